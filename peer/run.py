"""Runs the peer suite: t2spline against geomdl 5.4.0 and scipy on random
curves, and against geomdl 5.4.0 and splipy on random surfaces. Prints one line per topic (cases, comparisons, largest relative error
per peer), every failure, and a closing line `N passed, M failed` (cases).
Exits with 1 on any mismatch above the tolerance (1e-9 relative).

    peer/.venv/bin/python peer/run.py [--seed S] [--group curves|surfaces] [TOPIC ...]
"""

import argparse
import importlib
import random
import sys

from common import build_ours, TOLERANCE

GROUPS = {
    "curves": ["test_evaluation", "test_derivatives", "test_knot_insertion", "test_degree_elevation", "test_split"],
    "surfaces": [
        "test_surface_closed_forms",
        "test_surface_evaluation",
        "test_surface_derivatives",
        "test_surface_knot_insertion",
        "test_surface_degree_elevation",
    ],
}
TOPICS = GROUPS["curves"] + GROUPS["surfaces"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=20261126, help="seed of the random cases")
    parser.add_argument("--group", choices=sorted(GROUPS), help="run one group of topics")
    parser.add_argument("topics", nargs="*", help="topic modules to run (default: all)")
    args = parser.parse_args()
    args.topics = args.topics or (GROUPS[args.group] if args.group else TOPICS)
    binary = build_ours()
    passed = failed = 0
    print(f"peer suite: seed {args.seed}, tolerance {TOLERANCE:g} relative")
    for name in args.topics:
        topic = importlib.import_module(name).run(random.Random(f"{args.seed}/{name}"), binary)
        print(topic.summary())
        if getattr(topic, "note", None):
            print("  note: " + topic.note)
        for line in topic.failures[:20]:
            print("  FAIL " + line)
        failed += len(topic.failed_cases)
        passed += topic.cases - len(topic.failed_cases)
    print(f"peer: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
