"""Benchmark of numeric/bem.py: the 256 x 256 Hertz solve, Tamaas side by side, and the error
against exact solutions as a function of the grid.

Problem: rigid sphere R = 1 m on a half-space E* = 1 Pa, grid of n x n pixels on [-1, 1]^2 m,
the Hertz force of the depth d = 0.25 m (a = 0.5 m), force-controlled, relative residual 1e-8.
Tamaas (if importable): the same grid and surface, its non-periodic "dcfft" operator and its
Polonsky-Keer-Rey solver at tolerance 1e-8; its depth is taken as the mean of u + h over its
contact, u computed by our operator from its pressure (its model does not return the
non-periodic displacement).

The large problem (issue 18: 1024 x 1024 to 1e-8 in <= 20 s): the same solve on a 1024^2 grid,
each side once in a process of its own (wall and CPU time, peak memory).

Run: ``python benchmarks/bench_bem.py [--quick] [--out DIR]`` (``make benchmark`` runs it);
writes benchmarks/results/bem.json, which ``make_nonaxi_doc.py`` turns into
docs/non_axisymmetric.md. Timings: medians of ``--repeat`` solves of each side, their rounds
interleaved (``hertzmdr.numeric._timing.compare``), and Tamaas's time over ours, on this machine
(2 shared cores); tests never assert on them.
"""

from __future__ import annotations

import json
import platform

import _common
import numpy as np

from hertzmdr.numeric import _timing, bem, hertz

E, R, D = 1.0, 1.0, 0.25


def sphere(n):
    x, y, dx, _ = bem.grid(n, 2.0)
    return (x**2 + y**2) / (2 * R), dx


def hertz_errors(p, depth, dx):
    F = p.sum() * dx * dx
    a = hertz.contact_radius(D, R)
    return {"force": F / hertz.force(D, R, E) - 1, "depth": depth / D - 1,
            "area": (p > 0).sum() * dx * dx / (np.pi * a * a) - 1,
            "max_pressure": p.max() / hertz.max_pressure(D, R, E) - 1}


def solvers(n):
    """The two force-controlled solves of the same problem, as callables (Tamaas's: None when
    it is not installed)."""
    h, dx = sphere(n)
    F = hertz.force(D, R, E)

    def ours():
        return bem.solve(h, dx, E, force=F, tol=1e-8, stiffness=False)

    tm = _common.peer("tamaas", "tamaas", "the Tamaas row")
    if tm is None:
        return ours, None
    tm.set_log_level(tm.LogLevel.warning)  # no per-iteration printout

    def theirs():
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [2.0, 2.0], [n, n])
        model.E, model.nu = E, 0.0  # E* = E/(1 - nu^2) = E
        tm.ModelFactory.registerNonPeriodic(model, "dcfft")
        solver = tm.PolonskyKeerRey(model, -np.ascontiguousarray(h), 1e-8)
        solver.setIntegralOperator("dcfft")
        solver.solve(F / 4.0)  # mean pressure over the 2 x 2 m domain
        return np.array(model.traction, copy=True)

    return ours, theirs


def side_by_side(n, budget):
    """Both solvers on the n x n Hertz problem: times (interleaved), errors, their ratio."""
    ours, theirs = solvers(n)
    h, dx = sphere(n)
    fns = {"hertzmdr": ours} if theirs is None else {"hertzmdr": ours, "tamaas": theirs}
    t = _timing.compare(fns, budget)
    res = ours()
    mine = {"seconds": t["hertzmdr"].median, "first_seconds": t["hertzmdr"].first,
            "iterations": res.iterations, "residual": res.residual,
            **hertz_errors(res.pressure, res.depth, dx)}
    if theirs is None:
        return mine, {"error": "tamaas not installed"}
    p = theirs()
    u = bem.HalfSpace((n, n), dx, dx, E)(p)
    S = p > 0
    depth = float(np.mean(u[S] + h[S]))
    other = {"seconds": t["tamaas"].median, "first_seconds": t["tamaas"].first,
             "version": _common.version("tamaas"),
             "time_over_hertzmdr": _timing.ratio(t["tamaas"], t["hertzmdr"]),
             "max_pressure_difference_to_ours": float(np.max(np.abs(p - res.pressure))
                                                      / res.pressure.max()),
             **hertz_errors(p, depth, dx)}
    return mine, other


def _one_solve(solver):
    """One solve in this (forked) process: wall and CPU seconds, the pressures, and the peak
    resident memory of the process [bytes] (Linux reports ru_maxrss in KiB)."""
    import resource
    import time

    t0, c0 = time.perf_counter(), time.process_time()
    out = solver()
    c1, t1 = time.process_time(), time.perf_counter()
    p = out.pressure if hasattr(out, "pressure") else out
    extra = {"iterations": out.iterations, "residual": out.residual,
             "depth_solved": out.depth} if hasattr(out, "iterations") else {}
    return {"seconds": t1 - t0, "cpu_seconds": c1 - c0, "pressure": p,
            "max_rss_bytes": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024,
            **extra}


def big(n):
    """Issue 18's large problem: the Hertz solve of this benchmark on an n x n grid, each side
    once, in a process of its own (forked: its memory is its own), wall and CPU time."""
    ours, theirs = solvers(n)
    h, dx = sphere(n)
    mine = _timing.in_fork(_one_solve, ours)
    p = mine.pop("pressure")
    mine.update(hertz_errors(p, mine.pop("depth_solved"), dx))
    out = {"grid": n, "hertzmdr": mine}
    if theirs is None:
        out["tamaas"] = {"error": "tamaas not installed"}
        return out
    other = _timing.in_fork(_one_solve, theirs)
    pt = other.pop("pressure")
    u = bem.HalfSpace((n, n), dx, dx, E)(pt)
    S = pt > 0
    other.update(hertz_errors(pt, float(np.mean(u[S] + h[S])), dx))
    other["cpu_over_hertzmdr"] = other["cpu_seconds"] / mine["cpu_seconds"]
    other["max_pressure_difference_to_ours"] = float(np.max(np.abs(pt - p)) / p.max())
    out["tamaas"] = other
    return out


def convergence(ns):
    rows = []
    for n in ns:
        h, dx = sphere(n)
        res, t_s = _timing.timed(lambda h=h, dx=dx: bem.solve(h, dx, E, depth=D))
        a = hertz.contact_radius(D, R)
        x, y, dx, _ = bem.grid(n, 2.0)
        mask = x**2 + y**2 < 1.0
        k = bem.punch_stiffness(mask, dx, E)
        a_pix = np.sqrt(mask.sum() * dx * dx / np.pi)
        theta, a_c = 0.2, 0.7
        cone = bem.solve(np.hypot(x, y) * np.tan(theta), dx, E,
                         depth=np.pi * a_c * np.tan(theta) / 2)
        rows.append({
            "n": n, "seconds_sphere": t_s,
            "sphere_force": res.force / hertz.force(D, R, E) - 1,
            "sphere_area": res.area / (np.pi * a * a) - 1,
            "sphere_max_pressure": res.pressure.max() / hertz.max_pressure(D, R, E) - 1,
            "sphere_stiffness": res.stiffness / hertz.stiffness(D, R, E) - 1,
            "punch_k_vs_2aE": k / (2 * 1.0 * E) - 1,
            "punch_k_vs_2a_pixE": k / (2 * a_pix * E) - 1,
            "cone_force": cone.force / (np.pi / 2 * a_c**2 * E * np.tan(theta)) - 1,
            "cone_stiffness": cone.stiffness / (2 * a_c * E) - 1,
        })
        print({k_: (f"{v:.3g}" if isinstance(v, float) else v) for k_, v in rows[-1].items()})
    return rows


def main(argv=None):
    ap = _common.parser(__doc__)
    ap.add_argument("--n", type=int, help="grid of the side-by-side solve (default 256; "
                    "--quick: 64)")
    ap.add_argument("--repeat", type=int, default=3, help="solves of each side (default 3)")
    ap.add_argument("--nmax", type=int, help="largest grid of the convergence study (default "
                    "512; --quick: 64)")
    ap.add_argument("--big", type=int, help="grid of the one large solve of each side "
                    "(default 1024, issue 18's goal; --quick: 96; 0: none)")
    args = ap.parse_args(argv)
    run = _common.run_from(args)
    n = args.n or (64 if args.quick else 256)
    nmax = args.nmax or (64 if args.quick else 512)
    budget = _timing.Budget(repeats=1 if args.quick else args.repeat, min_time=0.0)
    mine, theirs = side_by_side(n, budget)
    print("hertzmdr.bem:", mine)
    print("tamaas:", theirs)
    rows = convergence([m for m in (32, 64, 128, 256, 512, 1024) if m <= nmax])
    n_big = (96 if args.quick else 1024) if args.big is None else args.big
    large = big(n_big) if n_big else None
    print("large:", large)
    out = run.results / "bem.json"
    out.write_text(json.dumps({
        "machine": f"{platform.machine()}, {platform.python_implementation()} "
                   f"{platform.python_version()}, numpy {np.__version__}",
        "conditions": _timing.conditions(), "repeat": budget.repeats,
        "grid": n, "hertzmdr": mine, "tamaas": theirs, "convergence": rows, "large": large,
    }, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
