"""Scene speed: the rail-wheel scene as a whole process, and scene.run() in-process.

Goals (issue 5): `hertzmdr run examples/problem1_rail_wheel.toml --json` as a whole process in
<= 0.6 s, `scene.run()` of a closed-form scene in <= 1 ms. Studies (issue 13): a 1e5-point study
of the Hertz force, contact radius and max pressure in <= 50 ms in-process, a 100-point study of
max_shear of a circular contact in <= 1 s. Writes docs/scene_speed.md.
Run: ``.venv/bin/python benchmarks/bench_scene.py [--quick] [--out DIR]`` (``make benchmark``
runs it). Timings by ``hertzmdr.numeric._timing``: medians and 10 %/90 % quantiles of the
rounds; the first call (cold caches, lazy imports) apart.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import _common

from hertzmdr.numeric import _timing

SCENE = _common.ROOT / "examples" / "problem1_rail_wheel.toml"


def whole_process(budget: _timing.Budget) -> _timing.Timing:
    exe = Path(sys.executable).with_name("hertzmdr")
    return _timing.measure(lambda: subprocess.run(
        [str(exe), "run", str(SCENE), "--json"], check=True, stdout=subprocess.DEVNULL), budget)


def python_startup(budget: _timing.Budget) -> _timing.Timing:
    return _timing.measure(lambda: subprocess.run([sys.executable, "-c", "import numpy"],
                                                  check=True), budget)


def in_process(budget_run: _timing.Budget, budget_load: _timing.Budget):
    from hertzmdr.numeric import scene

    sc = scene.load(SCENE)
    return (_timing.measure(sc.run, budget_run),
            _timing.measure(lambda: scene.load(SCENE), budget_load))


def study(sweep: dict, effects: list[str], key: str = "radius") -> dict:
    """A ball (R = 5 mm) on a plate under 10 N, ``key`` of the ball swept."""
    ball = {"name": "ball", "shape": "sphere", "radius": "5 mm", "E": "210 GPa", "nu": 0.3}
    ball[key] = sweep
    return {"effects": effects, "body": [ball, {"shape": "flat", "E": "70 GPa", "nu": 0.33}],
            "load": {"force": "10 N"}}


def studies(quick: bool, budget: _timing.Budget) -> list[tuple[str, _timing.Timing, str]]:
    """(what, timing, route) of the study rows: the computation (``study.run``, the results as
    arrays) and the whole ``run()`` (the JSON document's lists too)."""
    from hertzmdr.numeric import scene
    from hertzmdr.numeric.scene import study as st

    n = 1000 if quick else 100_000
    closed = ["force", "contact_radius", "max_pressure"]
    cases = [
        (f"{n}-point study of the ball's radius (log, 1 to 10 mm): {', '.join(closed)}",
         study({"from": "1 mm", "to": "10 mm", "points": n, "spacing": "log"}, closed)),
        (f"{n}-point study of the ball's E (10 to 400 GPa): {', '.join(closed)}",
         study({"from": "10 GPa", "to": "400 GPa", "points": n}, closed, "E")),
        ("100-point study of the ball's radius: max_shear",
         study({"from": "1 mm", "to": "10 mm", "points": 100}, ["max_shear"])),
        ("100-point study of the ball's radius: pressure_profile (a field per point)",
         study({"from": "1 mm", "to": "10 mm", "points": 100}, ["pressure_profile"])),
    ]
    rows = []
    for what, doc in cases:
        sc = scene.load(doc)
        route = st.run(sc.spec).route
        rows.append((f"{what}: `study.run` [ms]", _timing.measure(lambda s=sc: st.run(s.spec),
                                                                   budget), route))
        rows.append(("the same, `scene.run()` with the JSON document [ms]",
                     _timing.measure(sc.run, budget), route))
    return rows


def fmt(t: _timing.Timing, unit: float, name: str) -> str:
    return (f"| {name} | {t.median / unit:.3g} | {t.quantile(0.1) / unit:.3g} - "
            f"{t.quantile(0.9) / unit:.3g} | {t.first / unit:.3g} | {len(t.rounds)} x "
            f"{t.number} |")


def main(argv=None) -> None:
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    if args.quick:
        # one timed process after the first (each `hertzmdr run` a ~1.5 s process of CPU:
        # the quick run only needs the path and finite numbers)
        proc_budget, run_budget, load_budget = (_timing.Budget(1, 0.0), _timing.QUICK,
                                                _timing.QUICK)
    else:
        proc_budget = _timing.Budget(15, 0.0)  # 15 processes, one each
        run_budget = _timing.Budget(200, 0.4)  # 200 rounds, 0.4 s of calls in all
        load_budget = _timing.Budget(100, 0.2)
    proc, start = whole_process(proc_budget), python_startup(proc_budget)
    runs, loads = in_process(run_budget, load_budget)
    study_rows = studies(args.quick, _timing.QUICK if args.quick else _timing.Budget(7, 0.5))
    text = "\n".join([
        "# Scene speed",
        "",
        "<!-- Written by benchmarks/bench_scene.py; regenerate, do not edit. -->",
        "",
        _timing.conditions(),
        "",
        "Goals (issue 5): the rail-wheel scene (`examples/problem1_rail_wheel.toml`) as a whole "
        "process `hertzmdr run ... --json` in <= 0.6 s; `scene.run()` of a closed-form scene "
        "in-process in <= 1 ms. Imports are lazy: SciPy, pint, matplotlib and SymPy are not "
        "loaded for this scene (tests/test_scenes.py checks the modules it loads). Median and "
        "10 % - 90 % of the rounds (each round: the time per call of its calls); 'first': the "
        "first call alone (lazy imports, cold caches).",
        "",
        "| what | median | 10 % - 90 % | first | rounds x calls |",
        "| --- | --- | --- | --- | --- |",
        fmt(proc, 1e-3, "`hertzmdr run problem1 --json`, whole process [ms]"),
        fmt(start, 1e-3, "of which: `python -c 'import numpy'` alone [ms]"),
        fmt(runs, 1e-6, "`scene.run()`, in-process [µs]"),
        fmt(loads, 1e-6, "`scene.load(path)` (read, parse, validate) [µs]"),
        "",
        "## Studies",
        "",
        "Goals (issue 13): a 10⁵-point study of the Hertz force, contact radius and max "
        "pressure in <= 50 ms in-process; a 100-point study of `max_shear` of a circular "
        "contact in <= 1 s. `study.run` is the computation (every point's results as arrays); "
        "`scene.run()` adds the JSON document (Python lists of every number). The route: "
        "`arrays` evaluates the closed forms once over all points, `per point` runs the scene "
        "at each point (docs/scenes.md, \"Studies\").",
        "",
        "| what | route | median | 10 % - 90 % | first | rounds x calls |",
        "| --- | --- | --- | --- | --- | --- |",
        *(fmt(t, 1e-3, what).replace(" | ", f" | {route} | ", 1) for what, t, route in study_rows),
        "",
    ])
    out = run.docs / "scene_speed.md"
    out.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
