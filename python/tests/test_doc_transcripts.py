"""Every printed number and key in the README and docs comes from the program.

**Transcripts.** A fenced block (```text, ```console, ```sh or bare) of
README.md or docs/*.md with a line `$ COMMAND` naming `t2spline` is a
transcript: each `$` line is a command, the lines up to the next `$` line its
shown output. The block's commands run in order, through bash (pipes,
redirections, `echo $?` and comments work as shown), in one fresh folder
holding `examples/` and `fixtures/` of this checkout and the input files the
pages only name (`bad.json`, `job.json`, `lines/*.json`, … : written by
`INPUTS` below, as the Rust tests that print the same messages write them),
with `t2spline` on the PATH the CLI under test. Outputs written with `-o`
land in that folder. The shown output is compared with the real output
(standard output and error, interleaved as printed), token by token:

- Both texts are cut into tokens: numbers (unsigned, `1.5e-3`), words,
  single punctuation characters; whitespace separates tokens and is
  otherwise ignored. A shown number matches a real one when it is the same
  text, the same float, or (if it has a decimal point) the real one rounded
  to the shown digits; every other token must be equal.
- `…` or `...` in the shown output is an elision: a line of its own, or
  part of a line (`[…]`, `{…}`, `"text …"`). Between two elisions the shown
  tokens form a *fragment*, which must occur contiguously in the real
  output; the fragments must occur in the shown order, without overlap.
  So every number, key, header and quoted token shown is printed, in
  that order, and nothing can be left out silently.
- When the real output is JSON, line breaks are not tokens (the docs may
  lay several keys out on one line). Otherwise a line break is a token, so
  a shown line without elisions is a whole real line, and consecutive
  shown lines are consecutive real lines.
- The output is shown complete unless it begins or ends with an elision:
  a first fragment is anchored at the start of the real output, a last one
  at its end. A command shown without output prints nothing.
- `VOLATILE` transcripts (timings) match any number where a number is
  shown; everything else is checked as above.

**Excerpts.** `EXCERPTS` are ```json blocks that show a command's output or
a file the program wrote without a `$` prompt; they are compared by the
same rules (a piece from the middle of a file as if `…` stood around it).

**Prose.** `CLAIMS` lists numbers the pages quote outside transcripts: the
phrase (with format fields, the rounding shown) that must occur in the page,
whitespace collapsed, once filled with the values computed from the
program's output of the commands its function runs (from the repository
root). Numbers that are timings or sizes of files (docs/performance.md, the
README's speed table, docs/figures.md's report sizes) are not claims here.
"""

from __future__ import annotations

import functools
import json
import math
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Dict, List, Sequence, Tuple

import pytest

from conftest import ROOT

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"

# Transcripts whose numbers are timings: any number matches a shown one.
VOLATILE = {"docs/library.md:118": "bench prints timings, which vary from run to run"}


# ---------------------------------------------------------------------------
# Finding the transcripts
# ---------------------------------------------------------------------------


@dataclass
class Command:
    line: int  # 1-based line of the `$` line in its page
    text: str  # the command, without `$ `
    shown: List[str]  # the shown output lines


@dataclass
class Transcript:
    page: str  # relative to the repository root
    line: int  # the first `$` line
    commands: List[Command]

    @property
    def id(self) -> str:
        return f"{self.page}:{self.line}"


def find_transcripts() -> List[Transcript]:
    found: List[Transcript] = []
    for page in PAGES:
        lines = page.read_text(encoding="utf-8").splitlines()
        i = 0
        while i < len(lines):
            fence = re.match(r"^\s*```(\w*)\s*$", lines[i])
            if not fence:
                i += 1
                continue
            end = i + 1
            while end < len(lines) and not re.match(r"^\s*```\s*$", lines[end]):
                end += 1
            body = lines[i + 1 : end]
            prompts = [k for k, l in enumerate(body) if l.lstrip().startswith("$ ")]
            if fence.group(1) in ("text", "console", "sh", "") and any(
                re.search(r"\bt2spline\b", body[k]) for k in prompts
            ):
                assert prompts[0] == 0, f"{page.name}:{i + 2}: output before the first `$` line"
                commands = []
                for n, k in enumerate(prompts):
                    stop = prompts[n + 1] if n + 1 < len(prompts) else len(body)
                    commands.append(Command(i + 2 + k, body[k].lstrip()[2:], body[k + 1 : stop]))
                found.append(Transcript(str(page.relative_to(ROOT)), commands[0].line, commands))
            i = end + 1
    return found


TRANSCRIPTS = find_transcripts()


def test_the_transcripts_are_found() -> None:
    # A finder that found nothing would let every page say anything.
    pages = {t.page for t in TRANSCRIPTS}
    assert {"README.md", "docs/set.md", "docs/fitting.md", "docs/jobs.md"} <= pages
    assert sum(len(t.commands) for t in TRANSCRIPTS) >= 40
    assert set(VOLATILE) <= {t.id for t in TRANSCRIPTS}
    assert len(VOLATILE) <= 2


# ---------------------------------------------------------------------------
# The input files the pages name but do not ship
# ---------------------------------------------------------------------------

# The file of crates/t2spline-io/tests/limits.rs: a problem of nearly every kind.
BAD_JOB = """{
  "order": 3,
  "alhpa": 0.5,
  "lower_height": 0.5,
  "samples": 1,
  "weights": [1, 0, 1, 1e200],
  "knots": [0, 0, 0, 0.7, 0.5, 1, 1],
  "points": [
    {"x": {"crisp": 1, "upper": [1e151, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5], "lower": [0.8, 1.2]}},
    {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2], "lower_height": 2},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5, "1.5"], "lower": [0.8, 1.2]}},
    {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 3, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]}},
    {"x": {"upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
     "y": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]}}
  ],
  "samples": 7
}"""

# A net whose order is not a pair, with a planar point, a ragged row and
# weights of the wrong shape (docs/jobs.md).
_P2 = '{"x": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}, "y": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}}'
_P3 = _P2[:-1] + ', "z": {"crisp": 0, "upper": [0, 0], "primary": [0, 0], "lower": [0, 0]}}'
BAD_NET = "\n".join([
    "{",
    '  "order": 3,',
    '  "lower_height": 0.5,',
    '  "weights": [[1, 1, 1], [1, 1], [1, 1, 1]],',
    '  "points": [',
    "    [",
    f"      {_P3},",
    f"      {_P3},",
    f"      {_P3}",
    "    ],",
    "    [",
    f"      {_P3},",
    f"      {_P2},",
    f"      {_P3}",
    "    ],",
    "    [",
    f"      {_P3},",
    f"      {_P3}",
    "    ]",
    "  ]",
    "}",
    "",
])

# The readings of crates/t2spline-cli/tests/fuzzify_net.rs.
BAD_NET_READINGS = (
    "row,col,x,y,z\n0,0,1,1,1\n0,0,1,1,2\n0,2,1,1,1\n1,0,1,x,1\n1,0,1,2,1\n"
    "2,1,1,1,1\n2,1,1,1,2\n2,2,1,1,1\n2,2,1,1,1\n"
)
BAD_READINGS = "station,x,y\nS01,1.0,1.0\nS01,1.0,abc\nS02,2.0,2.0\nS01,1.5,1.5\nS01,2.0,1.0\n"


def _small_net() -> str:
    def n(c: float) -> Dict[str, Any]:
        return {"crisp": c, "upper": [c - 0.5, c + 0.5], "primary": [c - 0.25, c + 0.25],
                "lower": [c - 0.1, c + 0.1]}

    rows = [[{"x": n(j), "y": n(i), "z": n(i * j)} for j in range(4)] for i in range(3)]
    head = ['{', '  "degree": [3, 3],', '  "lower_height": 0.5,', '  "alpha": 0.5,', '  "samples": 5,',
            '  "type_reduction": "paper",', '  "description": "three rows of four stations",',
            '  "points": [']
    body = ["    " + json.dumps(r) + ("," if i < 2 else "") for i, r in enumerate(rows)]
    return "\n".join([*head, *body, "  ]", "}", ""])


SMALL_NET = _small_net()


def _big_data() -> str:
    """crates/t2spline-cli/tests/fit.rs: data near 1e150 whose interpolant
    swings beyond it."""

    def n(c: float) -> Dict[str, Any]:
        return {"crisp": c, "upper": [c - 1e148, c + 1e148], "primary": [c - 5e147, c + 5e147],
                "lower": [c - 1e147, c + 1e147]}

    ys = [0.0, 9e149, -9e149, 9e149, 0.0]
    points = [{"x": n(i * 1e149), "y": n(y)} for i, y in enumerate(ys)]
    return json.dumps({"degree": 3, "lower_height": 0.5, "points": points})


def _degree_zero() -> str:
    job = json.loads(EXAMPLE.read_text())
    job["order"] = 1
    return json.dumps(job, indent=2)


def _write_inputs(work: Path, commands: str, cli: Path) -> None:
    (work / "bad.json").write_text(BAD_JOB)
    (work / "net.json").write_text(BAD_NET)
    (work / "bad.csv").write_text(BAD_READINGS)
    (work / "bad-net.csv").write_text(BAD_NET_READINGS)
    (work / "big.json").write_text(_big_data())
    (work / "deg0.json").write_text(_degree_zero())
    shutil.copy(EXAMPLE, work / "job.json")
    shutil.copy(EXAMPLE, work / "linked.json")
    os.link(work / "linked.json", work / "linked-too.json")
    # docs/output.md: a folder of jobs, one of them invalid (as batch.rs).
    (work / "lines").mkdir()
    shutil.copy(EXAMPLE, work / "lines" / "a.json")
    (work / "lines" / "b.json").write_text('{\n  "order": 2,\n  "alhpa": 0.5\n}\n')
    shutil.copy(ROOT / "fixtures" / "spiral-3d.json", work / "lines" / "c.json")
    if "fit data.json" in commands:
        # docs/jobs.md: a net of 3 rows, too few for degree 3, `points` on line 8.
        (work / "data.json").write_text(SMALL_NET)
    if "dem.asc" in commands:
        # docs/fitting.md: an ESRI grid of 4 × 5 cells, in blocks of 2 × 2.
        cells = "".join(" ".join(str(5 * r + c) for c in range(5)) + "\n" for r in range(4))
        (work / "dem.asc").write_text("ncols 5\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 1\n" + cells)
    if "out/beach-data.json" in commands:
        # The first command of the beach example (README, docs/fitting.md).
        (work / "out").mkdir()
        subprocess.run(
            [str(cli), "fuzzify", "examples/beach-readings.csv", "--tolerance", "0.02",
             "--alpha", "0.5", "-o", "out/beach-data.json"],
            cwd=work, check=True, capture_output=True,
        )
    if "seabed-data.json" in commands:
        # The first two steps of the walk of docs/terrain.md.
        pytest.importorskip("matplotlib")
        done = subprocess.run(
            [sys.executable, str(ROOT / "examples" / "salish-sea" / "topobathy_raster.py"),
             "topobathy.npy"], cwd=work, check=True, capture_output=True, text=True,
        )
        subprocess.run(
            [str(cli), "fuzzify", "topobathy.npy", "--block", "3", *done.stdout.split(),
             "-o", "seabed-data.json"], cwd=work, check=True, capture_output=True,
        )


# ---------------------------------------------------------------------------
# Tokens and fragments
# ---------------------------------------------------------------------------

NL = ("nl", "\n")
ELISION = ("elision", "…")
TOKEN = re.compile(
    r"(?P<num>\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)|(?P<word>[^\W\d]\w*)|(?P<elision>…|\.\.\.)|(?P<punct>\S)"
)
Token = Tuple[str, str]


def tokens(line: str) -> List[Token]:
    out: List[Token] = []
    for m in TOKEN.finditer(line):
        kind = m.lastgroup or "punct"
        out.append(ELISION if kind == "elision" else (kind, m.group()))
    return out


def real_tokens(text: str, as_json: bool) -> List[Token]:
    if as_json:
        return tokens(text)
    out: List[Token] = [NL]
    for line in text.splitlines():
        out += tokens(line) + [NL]
    return out


def shown_fragments(shown: Sequence[str], as_json: bool) -> Tuple[List[List[Token]], bool, bool]:
    """The fragments of the shown output, and whether the first is anchored
    at the start and the last at the end of the real output."""
    stream: List[Token] = [] if as_json else [NL]
    for line in shown:
        line_tokens = tokens(line)
        if as_json:
            stream += line_tokens
        elif line_tokens == [ELISION]:
            # Whole lines left out: the lines around are whole lines.
            stream += [ELISION, NL]
        else:
            # A line that begins or ends with an elision joins the real line
            # it abridges at that side: no line break there.
            if line_tokens[:1] == [ELISION] and stream[-1:] == [NL]:
                stream.pop()
            stream += line_tokens
            if line_tokens[-1:] != [ELISION]:
                stream.append(NL)
    fragments: List[List[Token]] = [[]]
    for tok in stream:
        if tok == ELISION:
            fragments.append([])
        else:
            fragments[-1].append(tok)
    # A fragment of line breaks only says nothing (the end of a last `…` line).
    real = [f for f in fragments if any(t != NL for t in f)]
    start = bool(real) and real[0] is fragments[0]
    end = bool(real) and real[-1] is fragments[-1]
    return real, start, end


def same_token(shown: Token, real: Token, volatile: bool) -> bool:
    if shown[0] != real[0]:
        return False
    if shown[1] == real[1]:
        return True
    if shown[0] != "num":
        return False
    if volatile:
        return True
    s, r = float(shown[1]), float(real[1])
    if s == r:
        return True
    mantissa, _, exponent = shown[1].lower().partition("e")
    if "." not in mantissa:
        return False
    digits = len(mantissa.split(".")[1])
    step = 10.0 ** (int(exponent or 0) - digits)
    return abs(s - r) <= 0.5 * step * (1 + 1e-9)


def find(fragment: List[Token], real: List[Token], start: int, volatile: bool) -> int:
    """The first position at or after `start` where `fragment` occurs, or -1."""
    for p in range(start, len(real) - len(fragment) + 1):
        if all(same_token(f, real[p + k], volatile) for k, f in enumerate(fragment)):
            return p
    return -1


def show(toks: Sequence[Token]) -> str:
    return " ".join("⏎" if t == NL else t[1] for t in toks)


def check_output(where: str, shown: List[str], real: str, volatile: bool) -> None:
    if not shown:
        assert real == "", f"{where}: shown without output, but prints:\n{real}"
        return
    try:
        json.loads(real)
        as_json = True
    except ValueError:
        as_json = False
    have = real_tokens(real, as_json)
    fragments, anchored_start, anchored_end = shown_fragments(shown, as_json)
    if not fragments:  # only elisions shown
        return
    pos = 0
    for k, fragment in enumerate(fragments):
        last = k == len(fragments) - 1
        if k == 0 and anchored_start:
            at = 0 if find(fragment, have[: len(fragment)], 0, volatile) == 0 else -1
        elif last and anchored_end:
            # The last part ends the output (the first occurrence might not).
            at = len(have) - len(fragment)
            at = at if at >= pos and find(fragment, have, at, volatile) == at else -1
        else:
            at = find(fragment, have, pos, volatile)
        anchor = " at its start" if k == 0 and anchored_start else " at its end" if last and anchored_end else ""
        assert at >= 0, (
            f"{where}: the shown output's part\n  {show(fragment)}\n"
            f"is not in the real output{anchor}"
            f" after\n  {show(have[max(0, pos - 12):pos])}\nwhich goes on\n  {show(have[pos:pos + 60])}"
        )
        pos = at + len(fragment)
        # Two shown lines share the line break between them.
        if fragment[-1] == NL:
            pos -= 1
    if anchored_end:
        assert pos >= len(have) - 1 if not as_json else pos == len(have), (
            f"{where}: the real output goes on after the shown output, which does not end "
            f"in `…`:\n  {show(have[pos:pos + 60])}"
        )


# ---------------------------------------------------------------------------
# The transcripts
# ---------------------------------------------------------------------------


def run_shell(work: Path, cli: Path, command: str, status: int) -> "subprocess.CompletedProcess[str]":
    bin_dir = work / ".bin"
    if not bin_dir.exists():
        bin_dir.mkdir()
        (bin_dir / "t2spline").symlink_to(Path(cli).resolve())
    env = dict(os.environ, PATH=f"{bin_dir}{os.pathsep}{os.environ['PATH']}", LC_ALL="C.UTF-8")
    env.pop("SOURCE_DATE_EPOCH", None)
    return subprocess.run(
        ["bash", "-c", f"(exit {status}); {command}"], cwd=work, env=env,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120,
    )


@pytest.mark.parametrize("transcript", TRANSCRIPTS, ids=[t.id for t in TRANSCRIPTS])
def test_a_transcript_shows_what_the_program_prints(
    transcript: Transcript, cli: Path, tmp_path: Path
) -> None:
    work = tmp_path / "work"
    work.mkdir()
    for folder in ("examples", "fixtures", "docs/fit-example"):
        (work / folder).parent.mkdir(parents=True, exist_ok=True)
        (work / folder).symlink_to(ROOT / folder, target_is_directory=True)
    _write_inputs(work, "\n".join(c.text for c in transcript.commands), cli)
    status = 0
    for command in transcript.commands:
        done = run_shell(work, cli, command.text, status)
        status = done.returncode
        assert "panicked" not in done.stdout, (command.text, done.stdout)
        check_output(
            f"{transcript.page}:{command.line}: `{command.text}`", command.shown, done.stdout,
            transcript.id in VOLATILE,
        )


# ---------------------------------------------------------------------------
# Numbers quoted in the prose
# ---------------------------------------------------------------------------


class Program:
    """`t2spline ARGS` run from the repository root, each command once."""

    def __init__(self, cli: Path) -> None:
        self.cli = str(cli)
        self.done: Dict[Tuple[Tuple[str, ...], str], subprocess.CompletedProcess[str]] = {}

    def run(self, *args: str, stdin: str = "") -> "subprocess.CompletedProcess[str]":
        if (args, stdin) not in self.done:
            self.done[args, stdin] = subprocess.run(
                [self.cli, *args], cwd=ROOT, input=stdin, capture_output=True, text=True,
                timeout=120,
            )
        return self.done[args, stdin]

    def out(self, *args: str, stdin: str = "") -> str:
        """The standard output of a command that must succeed."""
        done = self.run(*args, stdin=stdin)
        assert done.returncode == 0, (args, done.stderr)
        return str(done.stdout)

    def json(self, *args: str) -> Any:
        return json.loads(self.out(*args))

    def err(self, *args: str) -> str:
        """The standard error, whatever the exit code."""
        return str(self.run(*args).stderr)


@pytest.fixture(scope="module")
def program(cli: Path) -> Program:
    return Program(cli)


def spaced(value: float) -> str:
    """A whole number with thin groups of three, as the pages write them
    (`30 500`)."""
    return f"{round(value):,}".replace(",", " ")


def sci(value: float, digits: int) -> str:
    """`6.1e-6`: scientific notation without the exponent's padding."""
    mantissa, exponent = f"{value:.{digits}e}".split("e")
    return f"{mantissa}e{int(exponent)}"


EX = "examples/paper-alg-1-1.json"
TERRAIN = "examples/fuzzy-terrain.json"
SEABED = "examples/salish-sea-seabed.json"
FIT_DATA = "examples/fit-measurements.json"


def region_areas(p: Program, alpha: str) -> Dict[str, float]:
    features = p.json("region", EX, "--alpha", alpha)["features"]
    return {f["properties"]["membership"]: f["properties"]["area"] for f in features}


def vertices(feature: Dict[str, Any]) -> int:
    return sum(len(ring) for polygon in feature["geometry"]["coordinates"] for ring in polygon)


@functools.lru_cache(maxsize=None)
def band_area(p: Program) -> float:
    """The band between the upper layer curves: the union of the
    quadrilaterals between 2 001 samples (docs/set.md)."""
    from shapely.geometry import Polygon  # type: ignore[import-untyped]
    from shapely.ops import unary_union  # type: ignore[import-untyped]

    layers = p.json("run", EX, "--samples", "2001")["curves"]["layers"]
    a, b = layers["upper_left"], layers["upper_right"]
    quads = [Polygon([a[k], a[k + 1], b[k + 1], b[k]]).buffer(0) for k in range(len(a) - 1)]
    return float(unary_union(quads).area)


@functools.lru_cache(maxsize=None)
def layer_lengths(p: Program) -> List[float]:
    """The lengths of the seven layer curves, as polylines of 20 001
    samples (to 1e-6 of their length)."""
    curves = p.json("run", EX, "--samples", "20001")["curves"]
    out = []
    for points in [curves["crisp"], *curves["layers"].values()]:
        out.append(sum(math.dist(points[k], points[k + 1]) for k in range(len(points) - 1)))
    return out


def length_at(p: Program, alpha: float) -> Tuple[float, float]:
    measured = p.json("measure", EX, "--levels", "3")
    at = next(e for e in measured["length"]["upper"] if e["alpha"] == alpha)
    return at["min"], at["max"]


def readings_per_station() -> Dict[str, int]:
    rows = (ROOT / "examples" / "beach-readings.csv").read_text().splitlines()[1:]
    count: Dict[str, int] = {}
    for row in rows:
        count[row.split(",")[0]] = count.get(row.split(",")[0], 0) + 1
    return count


def last_point_box(p: Program) -> List[float]:
    """The upper cut at level 0 of the example's last control point:
    x from, x to, y from, y to."""
    layers = p.json("run", EX, "--samples", "3")["control_points"]["layers"]
    left, right = layers["upper_left"][-1], layers["upper_right"][-1]
    return [left[0], right[0], left[1], right[1]]


def upper_box_side(p: Program) -> float:
    layers = p.json("run", EX, "--samples", "3")["control_points"]["layers"]
    sides = [max(q[k] for q in layers["upper_right"]) - min(q[k] for q in layers["upper_left"])
             for k in range(2)]
    return round(float(max(sides)), 12)


def worked_value(p: Program) -> List[Any]:
    """The x number of the example's first control point through the four
    stages, at alpha 0.8."""
    c = p.json("run", EX, "--samples", "3")["control_points"]
    layers, cut = c["layers"], c["alpha_cut"]
    return [
        c["defuzzified"][0][0], c["defuzzified"][0][1],
        c["crisp"][0][0], layers["upper_left"][0][0], layers["upper_right"][0][0],
        layers["primary_left"][0][0], layers["primary_right"][0][0],
        cut["upper_left"][0][0], cut["upper_right"][0][0],
        cut["primary_left"][0][0], cut["primary_right"][0][0],
        c["type_reduced_left"][0][0], c["crisp"][0][0], c["type_reduced_right"][0][0],
        3 * c["defuzzified"][0][0],
    ]


def error_max(p: Program, *args: str) -> float:
    return float(p.json("run", *args)["error"]["max"])


def section(p: Program, *args: str) -> List[Dict[str, Any]]:
    levels: List[Dict[str, Any]] = p.json("section", *args)["levels"]
    return levels


def terrain_grades(p: Program, z: str) -> List[str]:
    """`membership` of the terrain at (250, 200, z): upper, primary, lower."""
    lines = p.out("membership", TERRAIN, "-", stdin=f"x,y,z\n250,200,{z}\n").splitlines()
    assert lines[0] == "x,y,z,upper,primary,lower", lines
    return lines[1].split(",")[3:]


def envelope_bands(p: Program) -> int:
    """The bands of the seabed's GeoTIFF at 3 levels: one per level,
    function and bound, as the table's rows of one cell."""
    rows = p.out("envelope", SEABED, "--grid", "1,1", "--levels", "3").splitlines()
    header = rows[0].split(",")
    assert header == ["x", "y", "alpha", "membership", "lower", "upper"], header
    return 2 * len({tuple(r.split(",")[2:4]) for r in rows[1:]})


def grade(p: Program, row: str, column: str) -> float:
    lines = p.out("membership", EX, "examples/query-points.csv").splitlines()
    header = lines[0].split(",")
    for line in lines[1:]:
        if line.startswith(row + ","):
            return float(line.split(",")[header.index(column)])
    raise AssertionError(row)


def contour_areas(p: Program, *args: str) -> Dict[Tuple[float, str], Dict[str, Any]]:
    """The band features of `contour` on the seabed, by level and function."""
    features = p.json("contour", SEABED, "--z", "0", *args)["features"]
    return {
        (f["properties"]["alpha"], f["properties"]["membership"]): f["properties"]
        for f in features if not f["properties"].get("crisp")
    }


def fit_report(p: Program, *args: str) -> Dict[str, List[str]]:
    """The deviation lines of `fit`'s report, by layer: the words after it."""
    rows: Dict[str, List[str]] = {}
    for line in p.err("fit", *args).splitlines():
        words = line.split()
        if len(words) >= 4 and words[0] == "t2spline" and words[1] == "fit:":
            rows.setdefault(words[2], words[3:])
    return rows


def beach_miss(p: Program) -> List[Any]:
    """docs/fitting.md: the largest miss of the valid fit and the spreads
    of the data around it (upper.left of y, in cm)."""
    row = fit_report(p, FIT_DATA, "-o", "-")["upper_left"]
    miss, where = float(row[0]), row[1]
    found = re.fullmatch(r"points\[(\d+)\]\.y", where)
    assert found, row
    station = int(found.group(1))
    points = json.loads((ROOT / FIT_DATA).read_text())["points"]

    def spread(i: int) -> float:
        y = points[i]["y"]
        return float(y["crisp"] - y["upper"][0])

    return [miss, station, 100 * spread(station), 100 * spread(station - 1), station - 1,
            100 * (spread(station) + float(row[3]))]


def area_row(p: Program, alpha: str) -> List[Any]:
    return [alpha, *region_areas(p, alpha).values()]


def reduction_row(p: Program, args: Tuple[str, ...]) -> List[float]:
    result = p.json("run", EX, "--samples", "2", *args)
    error = result["error"]
    return [error["max"], error["max_at"], error["rms"], *result["control_points"]["defuzzified"][0]]


def cylinder(p: Program) -> List[float]:
    """The cylinder's defuzzified radius (its first control point lies on
    the x axis) over the crisp 2.5, the radius, and the two distances."""
    result = p.json("run", "examples/fuzzy-cylinder.json")
    radius = math.hypot(*result["control_points"]["defuzzified"][0][0][:2])
    assert abs(result["error"]["max"] - result["error"]["rms"]) < 1e-12
    return [radius / 2.5, radius, result["error"]["max"]]


Values = Callable[[Program], Sequence[Any]]


@dataclass
class Claim:
    page: str
    phrase: str  # a str.format template: its fields give the rounding shown
    values: Values  # from the program's output; the lambdas name the commands

    @property
    def id(self) -> str:
        return f"{self.page}: {self.phrase[:48]}"


AREA_ROW = "| {} | {:.4f} | {:.4f} | {:.4f} |"

CLAIMS: List[Claim] = [
    # README.md
    Claim("README.md",
          "The upper region at alpha 0 has an area of {:.2f} (primary {:.2f}, lower {:.2f}), "
          "nearly twice the {:.2f} of the band between the upper layer curves.",
          lambda p: [*region_areas(p, "0").values(), band_area(p)]),
    Claim("README.md",
          "on the shipped example they are {:.2f} to {:.2f}, while the curves whose control "
          "points lie in the upper cuts at alpha 0.5 measure from {:.4f} to {:.4f}.",
          lambda p: [min(layer_lengths(p)), max(layer_lengths(p)), *length_at(p, 0.5)]),
    Claim("README.md",
          "The solution's first control point, `[{}, {}]`, comes from the x number "
          "`({:g}; upper {:g}–{:g}, primary {:g}–{:g})` cut at 0.8 to `upper {:.2f}–{:.2f}, "
          "primary {:.2f}–{:.2f}`, reduced to `({:g}, {:g}, {:g})` and defuzzified to `{:.2f}/3`.",
          worked_value),
    Claim("README.md", "`error.max` is {:.4f} at alpha 0.6 = h and {:.4f} at 0.600001.",
          lambda p: [error_max(p, EX, "--alpha", "0.6"), error_max(p, EX, "--alpha", "0.600001")]),
    Claim("README.md", "same distance over (u, v); the largest, {:.4f} m, is at the corner",
          lambda p: [error_max(p, TERRAIN)]),
    Claim("docs/fitting.md", "13 stations from the dune crest to the waterline, each surveyed {} times "
          "with RTK-GNSS on a pole ({} rows)",
          lambda p: [*set(readings_per_station().values()), sum(readings_per_station().values())]),
    Claim("README.md", "13 stations, 20 readings each",
          lambda p: [len(json.loads((ROOT / FIT_DATA).read_text())["points"]),
                     *{n for n in readings_per_station().values()}]),
    # docs/method.md
    Claim("docs/method.md",
          "measure {:.2f} to {:.2f} (the crisp one the {}), while the curves with control points "
          "in the upper cuts at α = 0.5 measure from {:.4f} to {:.4f}.",
          lambda p: [min(layer_lengths(p)), max(layer_lengths(p)),
                     "shortest" if layer_lengths(p)[0] == min(layer_lengths(p)) else "?",
                     *length_at(p, 0.5)]),
    # docs/jobs.md
    Claim("docs/jobs.md",
          "is `[{}, {}]`: the x number `({:g}; upper {:g}–{:g}, primary {:g}–{:g})` is cut to "
          "`upper {:.2f}–{:.2f}, primary {:.2f}–{:.2f}` (alpha 0.8 is above its height 0.6, so "
          "the lower cut is absent), reduced to `({:g}, {:g}, {:g})` and defuzzified to `{:.2f}/3`.",
          worked_value),
    Claim("docs/jobs.md",
          "With `--derivatives 2 --samples 3` the crisp curve's first derivatives at t = 0, ½, 1 "
          "are `{}`",
          lambda p: [p.json("run", EX, "--derivatives", "2", "--samples", "3")
                     ["curves"]["derivatives"]["crisp"][0]]),
    Claim("docs/jobs.md", "The arc lengths are `crisp` {} and `defuzzified` {}.",
          lambda p: list(p.json("run", EX, "--derivatives", "2", "--samples", "3")
                         ["curves"]["arc_length"].values())),
    Claim("docs/jobs.md",
          "For the shipped example `error.max` is {:.4f} at alpha = 0.6 = h and {:.4f} at "
          "alpha = 0.600001.",
          lambda p: [error_max(p, EX, "--alpha", "0.6"), error_max(p, EX, "--alpha", "0.600001")]),
    Claim("docs/jobs.md", "`export` write `{}` on standard error",
          lambda p: [p.err("run", EX, "--alpha", "0.6000000000000001", "--samples", "2").strip()]),
    Claim("docs/jobs.md", "writes (abridged; the whole file is {} lines):",
          lambda p: [len(p.out("run", EX, "--samples", "3").splitlines())]),
    # docs/set.md
    Claim("docs/set.md",
          "the upper region at alpha 0 has an area of {:.2f}, while the band between the upper "
          "layer curves (their quadrilaterals between 2 001 samples, joined) covers {:.2f} of it",
          lambda p: [region_areas(p, "0")["upper"], band_area(p)]),
    *[
        Claim("docs/set.md", AREA_ROW if alpha in ("0", "0.5") else "| {} | {:.4f} | {:.4f} | — |",
              functools.partial(area_row, alpha=alpha))
        for alpha in ("0", "0.5", "0.8")
    ],
    Claim("docs/set.md", "| 1 | {:.5f} | {:.5f} | — |",
          lambda p: list(region_areas(p, "1").values())),
    Claim("docs/set.md",
          "whose upper cut at alpha 0 is the box `[{:g}, {:g}] × [{:g}, {:g}]`: the curve can end "
          "anywhere in that rectangle, not only on the segment from `({:g}, {:g})` to `({:g}, {:g})`.",
          lambda p: last_point_box(p) + last_point_box(p)[::2] + last_point_box(p)[1::2]),
    Claim("docs/set.md", "(the largest side of the box of the upper cuts at level 0, {:g} on the example",
          lambda p: [upper_box_side(p)]),
    Claim("docs/set.md",
          "`(250, 200, 111.745625)`, on the crisp surface, has grades {:g}, {:g} and {:g}; "
          "`(250, 200, 111.26)`, just inside the upper interval of the section below, {:.3f}.",
          lambda p: [*map(float, terrain_grades(p, "111.745625")),
                     float(terrain_grades(p, "111.26")[0])]),
    Claim("docs/set.md", "(its height at x = 3.5 is {:.3f})",
          lambda p: [section(p, EX, "--x", "3.5", "--alpha", "1")[0]["upper"][0][0]]),
    Claim("docs/set.md", "its upper grade is {} (the x number",
          lambda p: ["1/3" if abs(grade(p, "6.6", "upper") - 1 / 3) < 1e-7 else grade(p, "6.6", "upper")]),
    Claim("docs/set.md", "Its primary grade, {}, is the slack's share",
          lambda p: [sci(grade(p, "6.6", "primary"), 1)]),
    Claim("docs/set.md", "(6.1e-6 on the example)".replace("6.1e-6", "{}"),
          lambda p: [sci(p.json("region", EX, "--alpha", "0")["features"][0]["properties"]["tolerance"], 1)]),
    Claim("docs/set.md",
          "with `--tolerance 0.01` the example's upper region at alpha 0 has {} vertices and an "
          "area of {:.4f} instead of {} vertices and {:.4f}.",
          lambda p: [
              vertices(p.json("region", EX, "--alpha", "0", "--tolerance", "0.01")["features"][0]),
              p.json("region", EX, "--alpha", "0", "--tolerance", "0.01")["features"][0]["properties"]["area"],
              spaced(vertices(p.json("region", EX, "--alpha", "0")["features"][0])),
              region_areas(p, "0")["upper"],
          ]),
    Claim("docs/set.md",
          "This is the fuzzy value of y at x = 3.5: between {:.2f} and {:.2f} at all (upper, "
          "alpha 0), the crisp {:.3f} at alpha 1.",
          lambda p: [*section(p, EX, "--x", "3.5", "--levels", "3")[0]["upper"][0],
                     section(p, EX, "--x", "3.5", "--levels", "3")[2]["upper"][0][0]]),
    Claim("docs/set.md",
          "The crisp surface is at {:.4f} m there; the ground can be anywhere from {:.2f} to "
          "{:.2f} m at all",
          lambda p: [section(p, TERRAIN, "--at", "250,200", "--levels", "3")[2]["upper"][0][0],
                     *section(p, TERRAIN, "--at", "250,200", "--levels", "3")[0]["upper"][0]]),
    Claim("docs/set.md", "is `{}` at every level, at its edge `--at 2.5,0`",
          lambda p: [
              {json.dumps(level[m]) for level in section(p, "examples/fuzzy-cylinder.json",
                                                         "--at", "2.5,0")
               for m in ("upper", "primary", "lower") if level[m] is not None}.pop()
              .removeprefix("[").removesuffix("]")
          ]),
    # docs/terrain.md
    Claim("docs/terrain.md",
          "the bands at alpha 0.5 cover about {} km² (upper), {} km² (primary) and {} km² "
          "(lower) of the plan",
          lambda p: [spaced(round(contour_areas(p)[(0.5, m)]["area"] / 1e6, -2))
                     for m in ("upper", "primary", "lower")]),
    Claim("docs/terrain.md", "at alpha 0 the upper band is {} km²",
          lambda p: [spaced(round(contour_areas(p, "--levels", "3")[(0.0, "upper")]["area"] / 1e6, -3))]),
    Claim("docs/terrain.md", "and bound, {} here (levels 0, 0.5 and 1;",
          lambda p: [envelope_bands(p)]),
    Claim("docs/terrain.md", "here 239 × 178 cells of about {:.1f} km), grown to hold the truth",
          lambda p: [contour_areas(p)[(0.5, "upper")]["tolerance"] / math.sqrt(2) / 1e3]),
    Claim("docs/terrain.md",
          "`tolerance` (a cell's diagonal, {:.1f} km here) is how far a polygon's point can lie "
          "from the true band; `height_tolerance` how far a kept cell's corners may miss Z0 "
          "(here {:.0f} m)",
          lambda p: [contour_areas(p)[(0.5, "upper")]["tolerance"] / 1e3,
                     contour_areas(p)[(0.5, "upper")]["height_tolerance"]]),
    # docs/reductions.md: the worked comparison
    *[
        Claim("docs/reductions.md", row + " | {:.6f} | {:.4f} | {:.6f} | ({:.6f}, {:.6f}) |",
              functools.partial(reduction_row, args=args))
        for row, args in [
            ("| `paper`, alpha = 0.8 (the job's)", ("--type-reduction", "paper")),
            ("| `paper`, alpha = 0.6 = h", ("--type-reduction", "paper", "--alpha", "0.6")),
            ("| `paper`, alpha = 0", ("--type-reduction", "paper", "--alpha", "0")),
            ("| `centroid`", ("--type-reduction", "centroid")),
            ("| `nie-tan`", ("--type-reduction", "nie-tan")),
            ("| `alpha-planes`", ("--type-reduction", "alpha-planes")),
        ]
    ],
    # docs/surfaces.md: the two examples
    Claim("docs/surfaces.md",
          "its corner control point: `error.max` {:.4f} m at `{}` and `error.rms` {:.4f} m at α = 0.5.",
          lambda p: [p.json("run", TERRAIN)["error"][k] for k in ("max", "max_at", "rms")]),
    Claim("docs/surfaces.md",
          "`κ = 1 + (ρ − λ)/3 = {:.6f}` (λ, ρ the type-reduced left and right factors), i.e. "
          "{:.5f} m: `error.max` and `error.rms` are both {:.7f} m",
          lambda p: cylinder(p)),
    # docs/fitting.md
    Claim("docs/fitting.md", "For the example it happens at {} places",
          lambda p: re.findall(r"at (\d+) place\(s\)",
                               p.err("fit", FIT_DATA, "--fuzzy-fit", "independent", "-q"))[:1]),
    Claim("docs/fitting.md",
          "The largest miss, {:.2f} m, is the `upper.left` height at station {}: its spread of "
          "{:.0f} cm follows one of {:.0f} cm at station {}, and a spline with non-negative "
          "coefficients cannot drop that fast, so the fitted spread there is {:.0f} cm.",
          beach_miss),
]


def test_the_claims_are_many() -> None:
    assert len(CLAIMS) >= 25
    assert {c.page for c in CLAIMS} >= {"README.md", "docs/set.md", "docs/terrain.md",
                                         "docs/fitting.md", "docs/jobs.md"}


@pytest.mark.parametrize("claim", CLAIMS, ids=[c.id for c in CLAIMS])
def test_a_number_quoted_in_the_prose_is_printed(claim: Claim, program: Program) -> None:
    filled = " ".join(claim.phrase.format(*claim.values(program)).split())
    text = " ".join((ROOT / claim.page).read_text(encoding="utf-8").split())
    assert filled in text, f"{claim.page} should say: {filled}"


# ---------------------------------------------------------------------------
# Outputs shown without a `$` prompt
# ---------------------------------------------------------------------------


@dataclass
class Excerpt:
    """The first ```json block after the text `after` of a page shows
    `source` (a command's output, or a file the program wrote), compared as
    a transcript; `part`: the block is a piece from the middle of it."""

    page: str
    after: str
    source: Callable[[Program], str]
    part: bool = False


EXCERPTS = [
    Excerpt("docs/jobs.md", "writes (abridged; the whole file is",
            lambda p: p.out("run", EX, "--samples", "3")),
    # The README's tour of the job file: the shipped jobs, abridged.
    Excerpt("README.md", "`examples/paper-alg-1-1.json` (abridged):",
            lambda p: (ROOT / EX).read_text(encoding="utf-8")),
    Excerpt("docs/jobs.md", "`examples/paper-alg-1-1.json` (abridged):",
            lambda p: (ROOT / EX).read_text(encoding="utf-8")),
    Excerpt("README.md", "abridged from `examples/fuzzy-cylinder.json`",
            lambda p: (ROOT / "examples" / "fuzzy-cylinder.json").read_text(encoding="utf-8")),
    # `out/beach-data.json` is the shipped data file, byte for byte (below).
    Excerpt("docs/fitting.md", "One of its stations",
            lambda p: (ROOT / FIT_DATA).read_text(encoding="utf-8"), part=True),
]


def block_after(page: str, after: str) -> List[str]:
    text = (ROOT / page).read_text(encoding="utf-8")
    assert after in text, f"{page}: `{after}` is gone"
    rest = text.split(after, 1)[1]
    return rest.split("```json\n", 1)[1].split("\n```", 1)[0].splitlines()


@pytest.mark.parametrize("excerpt", EXCERPTS, ids=[f"{e.page}: {e.after}" for e in EXCERPTS])
def test_an_excerpt_shows_what_the_program_writes(excerpt: Excerpt, program: Program) -> None:
    shown = block_after(excerpt.page, excerpt.after)
    if excerpt.part:
        shown = ["…", *shown, "…"]
    check_output(f"{excerpt.page}: after `{excerpt.after}`", shown, excerpt.source(program), False)


def test_the_beach_data_is_the_shipped_data_file(program: Program, tmp_path: Path) -> None:
    """docs/fitting.md: "`out/beach-data.json` is the shipped
    `examples/fit-measurements.json`, byte for byte"."""
    assert "`out/beach-data.json` is the shipped `examples/fit-measurements.json`, byte for byte" in " ".join(
        (ROOT / "docs" / "fitting.md").read_text(encoding="utf-8").split()
    )
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    subprocess.run(
        [program.cli, "fuzzify", "examples/beach-readings.csv", "--tolerance", "0.02",
         "--alpha", "0.5", "-o", "beach-data.json"], cwd=tmp_path, check=True, capture_output=True,
    )
    assert (tmp_path / "beach-data.json").read_bytes() == (ROOT / FIT_DATA).read_bytes()
