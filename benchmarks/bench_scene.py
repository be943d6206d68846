"""Scene speed: the rail-wheel scene as a whole process, and scene.run() in-process.

Goals (issue 5): `hertzmdr run examples/problem1_rail_wheel.toml --json` as a whole process in
<= 0.6 s, `scene.run()` of a closed-form scene in <= 1 ms. Writes docs/scene_speed.md.
Run: .venv/bin/python benchmarks/bench_scene.py
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "problem1_rail_wheel.toml"


def whole_process(n: int = 15) -> list[float]:
    exe = Path(sys.executable).with_name("hertzmdr")
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        subprocess.run([str(exe), "run", str(SCENE), "--json"], check=True,
                       stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return times


def python_startup(n: int = 15) -> list[float]:
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", "import numpy"], check=True)
        times.append(time.perf_counter() - t0)
    return times


def in_process(n: int = 2000) -> tuple[list[float], list[float]]:
    from hertzmdr.numeric import scene

    sc = scene.load(SCENE)
    sc.run()  # warm: first-call imports
    runs, loads = [], []
    for _ in range(n):
        t0 = time.perf_counter()
        sc.run()
        runs.append(time.perf_counter() - t0)
    for _ in range(200):
        t0 = time.perf_counter()
        scene.load(SCENE)
        loads.append(time.perf_counter() - t0)
    return runs, loads


def fmt(ts: list[float], unit: float, name: str) -> str:
    q = statistics.quantiles(ts, n=10)
    return (f"| {name} | {statistics.median(ts) / unit:.3g} | {q[0] / unit:.3g} - "
            f"{q[-1] / unit:.3g} | {len(ts)} |")


def main() -> None:
    from hertzmdr.numeric.accuracy import machine

    proc, start = whole_process(), python_startup()
    runs, loads = in_process()
    text = "\n".join([
        "# Scene speed",
        "",
        "<!-- Written by benchmarks/bench_scene.py; regenerate, do not edit. -->",
        "",
        f"Measured on: {machine()}.",
        "",
        "Goals (issue 5): the rail-wheel scene (`examples/problem1_rail_wheel.toml`) as a whole "
        "process `hertzmdr run ... --json` in <= 0.6 s; `scene.run()` of a closed-form scene "
        "in-process in <= 1 ms. Imports are lazy: SciPy, pint, matplotlib and SymPy are not "
        "loaded for this scene (tests/test_scenes.py checks the modules it loads).",
        "",
        "| what | median | 10 % - 90 % | runs |",
        "| --- | --- | --- | --- |",
        fmt(proc, 1e-3, "`hertzmdr run problem1 --json`, whole process [ms]"),
        fmt(start, 1e-3, "of which: `python -c 'import numpy'` alone [ms]"),
        fmt(runs, 1e-6, "`scene.run()`, in-process [µs]"),
        fmt(loads, 1e-6, "`scene.load(path)` (read, parse, validate) [µs]"),
        "",
    ])
    out = ROOT / "docs" / "scene_speed.md"
    out.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
