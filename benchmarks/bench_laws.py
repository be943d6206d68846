"""Closed-form contact laws called from Python: the cost of hertzmdr's validated API against
the bare expression and against nanite's Hertz model; writes docs/laws_speed.md.

The Hertz force (5.23) F = (4/3) E* R^(1/2) d^(3/2) on 10^6 depths (an array: validation,
broadcasting and the generated function) and on one Python float (a fitting loop's call),
beside the same expression written by hand in NumPy / on floats, and beside nanite's
``hertz_paraboloidal`` (the model its AFM fits evaluate; nu = 0 so that its E/(1 - nu^2) is E*).
Times are CPU times of this process (``time.process_time``, so that other processes' turns on
a shared machine do not count), the best of interleaved rounds, reported with their ratio to
the bare expression.

Run: ``.venv/bin/python benchmarks/bench_laws.py [--quick] [--out DIR]`` (``make benchmark``
runs it; ``--quick``: 10^3 depths).
"""

from __future__ import annotations

import math
import os

import _common
import numpy as np

from hertzmdr.numeric import _timing, bodies, cone, hertz, line, powerlaw

E, R = 1e9, 1e-5  # E* [Pa], tip radius [m]: an AFM-like contact


def cases(n: int):
    """(name, {way: callable}, {way: value to compare}) for each comparison."""
    d = np.linspace(1e-9, 1e-6, n)
    d0 = 3e-7
    nanite = _common.peer("nanite.model.model_hertz_paraboloidal", "nanite",
                          "the nanite column")
    arrays = {"hertzmdr `hertz.force`": lambda: hertz.force(d, R, E),
              "by hand in NumPy": lambda: 4.0 / 3.0 * E * np.sqrt(R) * d**1.5}
    if nanite is not None:  # its delta is the tip position: negative into the sample
        arrays["nanite `hertz_paraboloidal`"] = lambda: nanite.hertz_paraboloidal(
            -d, E, R, 0.0)
    scalars = {"hertzmdr `hertz.force`": lambda: hertz.force(d0, R, E),
               "by hand on floats": lambda: 4.0 / 3.0 * E * math.sqrt(R) * d0**1.5}
    return [(f"Hertz force (5.23) on {n:,} depths", arrays),
            ("Hertz force (5.23) on one Python float", scalars)]


def every_closed_form():
    """{name: call on Python floats} for the public closed forms with a scalar path (issue 18:
    <= 2 µs a call), at an AFM-like contact."""
    d, F, th, L = 3e-7, 1e-6, 1.2, 1e-3
    return {
        "hertz.contact_radius": lambda: hertz.contact_radius(d, R),
        "hertz.max_pressure": lambda: hertz.max_pressure(d, R, E),
        "hertz.force": lambda: hertz.force(d, R, E),
        "hertz.stiffness": lambda: hertz.stiffness(d, R, E),
        "hertz.energy": lambda: hertz.energy(d, R, E),
        "hertz.depth_from_force": lambda: hertz.depth_from_force(F, R, E),
        "hertz.max_pressure_from_force": lambda: hertz.max_pressure_from_force(F, R, E),
        "cone.force": lambda: cone.force(d, th, E),
        "cone.depth_from_force": lambda: cone.depth_from_force(F, th, E),
        "line.force": lambda: line.force(d, L, E),
        "line.half_width_from_force": lambda: line.half_width_from_force(F, L, R, E),
        "powerlaw.force_from_radius": lambda: powerlaw.force_from_radius(1e-6, d, 3.0, E),
        "bodies.gaussian_radius": lambda: bodies.gaussian_radius(R, 2 * R),
        "bodies.gaussian_approx_force": lambda: bodies.gaussian_approx_force(d, R, 2 * R, E),
    }


def main(argv=None):
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    n = 10**3 if args.quick else 10**6
    lines = ["# Closed-form laws from Python: hertzmdr, the bare expression, nanite\n\n",
             "<!-- Written by `benchmarks/bench_laws.py`; regenerate, do not edit. -->\n\n",
             _timing.conditions() + f" Load average at the start: {os.getloadavg()[0]:.1f} "
             f"({os.cpu_count()} cores).\n\n",
             " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
             "'time / bare': the way's best over the bare expression's (1: as fast). "
             "'largest difference': relative, against hertzmdr's values.\n\n"]
    comparisons = cases(n)
    floor = None
    for title, ways in comparisons:
        array = "depths" in title
        if array:  # what the checks cost by themselves: one pass over the depths' bits
            d = np.linspace(1e-9, 1e-6, n)  # (finite, >= 0), one sum over the result (finite)
            F = hertz.force(d, R, E)
            ways = {**ways, "check of d": lambda d=d: d.view(np.uint64).max(),
                    "check of F": lambda F=F: math.isfinite(F.sum())}
        t = _common.cpu_compare(ways, 1 if array else (200 if args.quick else 5000),
                                3 if args.quick else (41 if array else 30))
        if array:
            floor = {k: t.pop(k).best for k in ("check of d", "check of F")}
            ways = {k: v for k, v in ways.items() if not k.startswith("check of")}
            floor["bare"] = t["by hand in NumPy"].best
            floor["ours"] = t["hertzmdr `hertz.force`"].best
        bare = next(k for k in ways if k.startswith("by hand"))
        ours = np.asarray(next(iter(ways.values()))(), dtype=float)
        lines.append(f"## {title}\n\n| way | time | time / bare | first call | largest "
                     "difference |\n|---|---|---|---|---|\n")
        for name, fn in ways.items():
            diff = float(np.max(np.abs(np.asarray(fn(), dtype=float) / ours - 1)))
            lines.append(f"| {name} | {_common.seconds(t[name].best)} | "
                         f"{t[name].best / t[bare].best:.2f} | "
                         f"{_common.seconds(t[name].first)} | "
                         f"{diff:.1e} |\n")
        lines.append("\n")
    lines.append(
        "What the array path costs beyond the bare expression (issue 18 asks <= 1.1): the "
        "checks, one pass over the depths' bits (`numeric/_validate.py`: finite and >= 0 in "
        "one uint64 maximum) and one sum over the result (finite: the OverflowError of "
        "`representable`), both whole reads of an 8 MB array that no check can skip; NumPy's "
        "pow, which the expression needs, is the rest. ")
    if floor is not None:
        lines.append(
            f"Measured by themselves in the same rounds: {_common.seconds(floor['check of d'])}"
            f" and {_common.seconds(floor['check of F'])}, together "
            f"{(floor['check of d'] + floor['check of F']) / floor['bare']:.2f} of the bare "
            f"expression; hertzmdr's excess over it is "
            f"{floor['ours'] / floor['bare'] - 1:.2f}. ")
    lines.append(
        "Tried for issue 18 and reverted: the checks and the expression block by block "
        "(2^13-2^16 elements, in the cache) were slower (1.19 against 1.09 in one process), "
        "the blocks' temporaries and the copy into the result costing more than the two "
        "reads they saved. Before issue 18 the checks took six passes and two boolean "
        "temporaries (1.4-1.6).\n\n")
    ways = every_closed_form()
    d0 = 3e-7
    ways["by hand on floats (the force's expression)"] = (
        lambda: 4.0 / 3.0 * E * math.sqrt(R) * d0**1.5)
    t = _common.cpu_compare(ways, 200 if args.quick else 5000, 3 if args.quick else 30)
    bare = t["by hand on floats (the force's expression)"]
    lines.append("## Every closed form with a scalar path, on Python floats\n\n"
                 "The public functions whose body is a check of each argument and one "
                 "generated relation take the scalar path (`numeric/_validate.py`: the checks "
                 "as one line of comparisons, the relation's math-module form, a finite "
                 "result; anything else goes the array way, which words every error). "
                 "Goal (issue 18): <= 2 µs a call.\n\n"
                 "'time / bare': over the Hertz force's bare expression on floats in the same "
                 "interleaved rounds. CPU time a call, best of 30 rounds of 5,000 calls.\n\n"
                 "| function | time a call | time / bare | first call |\n|---|---|---|---|\n")
    for name in ways:
        label = name if name.startswith("by hand") else f"`{name}`"
        lines.append(f"| {label} | {_common.seconds(t[name].best)} | "
                     f"{t[name].best / bare.best:.1f} | "
                     f"{_common.seconds(t[name].first)} |\n")
    lines.append("\n")
    if not any("nanite" in k for _, ways in comparisons for k in ways):
        lines.append("nanite is not installed for this run: its column is skipped.\n")
    else:
        lines.append(f"nanite {_common.version('nanite')}.\n")
    out = run.docs / "laws_speed.md"
    out.write_text("".join(lines))
    print("".join(lines))


if __name__ == "__main__":
    main()
