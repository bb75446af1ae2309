"""The command `t2spline`, installed with the package as a console script:
the command-line tool itself (the Rust crate `t2spline-cli`), built into
the package's extension; `t2spline --help` lists its commands. Its figures
are SVG (the package carries no PNG renderer)."""

import sys

from t2spline._t2spline import _cli_main


def main() -> None:
    """Runs `t2spline` on the command line's arguments and exits with its
    code."""
    raise SystemExit(_cli_main(["t2spline", *sys.argv[1:]]))
