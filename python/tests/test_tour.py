"""docs/tour.ipynb runs from start to end in a fresh kernel (nbclient), and
its outputs hold the pictures: SVG drawn by the package (`_repr_html_`)."""

from __future__ import annotations

import re
from pathlib import Path

import nbformat
from nbclient import NotebookClient

ROOT = Path(__file__).resolve().parents[2]
TOUR = ROOT / "docs" / "tour.ipynb"


def test_the_tour_runs_and_shows_pictures() -> None:
    nb = nbformat.read(TOUR, as_version=4)
    # Any error in a cell raises here (CellExecutionError).
    NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(TOUR.parent)}}).execute()
    pictures = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for output in cell.get("outputs", []):
            assert output.get("output_type") != "error", output
            html = output.get("data", {}).get("text/html", "")
            if "<svg" in html:
                pictures.append((cell.source.splitlines()[-1], html))
    shown = [source for source, _ in pictures]
    # The curve, the number, the solution, the region, the section, the
    # measures, the beach curve and its solution and region, the seabed:
    # each cell ending in one of them shows its picture.
    for last in ["curve", "x", "solution", "region", "curve.section(3.0, levels=5)", "measures", "beach", "beach_solution", "seabed"]:
        assert last in shown, (last, shown)
    assert any("beach.region(" in source for source in shown), shown
    for _, html in pictures:
        assert re.search(r"<svg [^>]*viewBox=", html)
    # The solutions show the four stages.
    by_source = dict(pictures)
    assert by_source["solution"].count("<svg ") == 4
    assert by_source["beach_solution"].count("<svg ") == 4
