"""An edit in `t2spline serve`, end to end in a real browser: from the moment
the page's alpha slider moves to the moment the page has redrawn the answer
(the job sent, run and regions computed by the server, the SVG rebuilt, and
the next two animation frames painted).

Headless Chromium is driven through ChromeDriver (Debian's `chromium` and
`chromium-driver`) by the W3C WebDriver protocol over loopback; the page's
own hook `window.t2splineServe.idle()` says when it shows the latest job.
Each round moves the slider to a new alpha (0.05, 0.10, ...) and times it
inside the page with `performance.now()`. Two jobs: the shipped example and
a 200-point cubic curve written here; the medians (and the range) of the
rounds are printed.

    python python/bench/bench_editor.py [--bin target/release/t2spline] [--rounds 40]
"""

from __future__ import annotations

import argparse
import json
import math
import shutil
import socket
import statistics
import subprocess
import tempfile
import time
import urllib.request
from pathlib import Path
from typing import Any, Dict, List

ROOT = Path(__file__).resolve().parents[2]

EDIT = """
const [alpha, done] = [arguments[0], arguments[arguments.length - 1]];
const s = window.t2splineServe, slider = document.getElementById("alpha");
const t0 = performance.now();
slider.value = String(alpha);
slider.dispatchEvent(new Event("input", { bubbles: true }));
slider.dispatchEvent(new Event("change", { bubbles: true }));
const wait = () => {
  if (s.idle() && JSON.parse(s.jobText()).alpha === alpha) {
    requestAnimationFrame(() => requestAnimationFrame(() => done(performance.now() - t0)));
  } else {
    requestAnimationFrame(wait);
  }
};
wait();
"""

READY = """
const done = arguments[arguments.length - 1];
const wait = () => (window.t2splineServe && window.t2splineServe.idle() ? done(true) : setTimeout(wait, 20));
wait();
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def post(url: str, body: Dict[str, Any]) -> Any:
    req = urllib.request.Request(
        url, data=json.dumps(body).encode(), headers={"Content-Type": "application/json"}
    )
    with urllib.request.urlopen(req, timeout=120) as r:
        return json.loads(r.read())["value"]


def curve_of_200(path: Path) -> None:
    """A cubic curve of 200 fuzzy control points along a wave."""

    def number(c: float, s: float) -> Dict[str, Any]:
        return {
            "crisp": c,
            "upper": [c - 3 * s, c + 3 * s],
            "primary": [c - 2 * s, c + 2 * s],
            "lower": [c - s, c + s],
        }

    points = [
        {"x": number(i * 0.1, 0.02), "y": number(math.sin(i * 0.15), 0.03)} for i in range(200)
    ]
    job = {"order": 4, "alpha": 0.5, "lower_height": 0.6, "points": points}
    path.write_text(json.dumps(job))


def time_edits(binary: Path, job: Path, rounds: int, chromium: str, driver: str) -> List[float]:
    port = free_port()
    chromedriver = subprocess.Popen(
        [driver, f"--port={port}"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    server = subprocess.Popen(
        [str(binary), "serve", str(job)], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True
    )
    try:
        assert server.stdout is not None
        url = server.stdout.readline().strip()
        base = f"http://127.0.0.1:{port}"
        for _ in range(300):
            try:
                with urllib.request.urlopen(f"{base}/status", timeout=2) as r:
                    if json.loads(r.read())["value"]["ready"]:
                        break
            except OSError:
                pass
            time.sleep(0.1)
        with tempfile.TemporaryDirectory() as profile:
            args = [
                "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                "--disable-background-networking", "--window-size=1300,1000",
                f"--user-data-dir={profile}",
            ]
            session = post(f"{base}/session", {"capabilities": {"alwaysMatch": {
                "browserName": "chrome",
                "goog:chromeOptions": {"binary": chromium, "args": args},
                "timeouts": {"script": 60000},
            }}})["sessionId"]
            post(f"{base}/session/{session}/url", {"url": url})
            script = f"{base}/session/{session}/execute/async"
            post(script, {"script": READY, "args": []})
            times = []
            for k in range(rounds + 3):
                alpha = round(0.05 * (1 + k % 19), 2)
                ms = float(post(script, {"script": EDIT, "args": [alpha]}))
                if k >= 3:  # three warm-up edits
                    times.append(ms)
            urllib.request.urlopen(
                urllib.request.Request(f"{base}/session/{session}", method="DELETE"), timeout=30
            )
            return times
    finally:
        server.terminate()
        chromedriver.terminate()
        server.wait()
        chromedriver.wait()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", type=Path, default=ROOT / "target" / "release" / "t2spline")
    parser.add_argument("--rounds", type=int, default=40)
    args = parser.parse_args()
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if chromium is None or driver is None:
        raise SystemExit("needs Debian's chromium and chromium-driver")
    with tempfile.TemporaryDirectory() as tmp:
        wave = Path(tmp) / "wave-200.json"
        curve_of_200(wave)
        for name, job in [("shipped example", ROOT / "examples" / "paper-alg-1-1.json"),
                          ("200-point cubic", wave)]:
            t = time_edits(args.bin, job, args.rounds, chromium, driver)
            print(
                f"{name}: an edit recomputed and redrawn in {statistics.median(t):.1f} ms "
                f"(median of {len(t)}; {min(t):.1f}–{max(t):.1f})"
            )


if __name__ == "__main__":
    main()
