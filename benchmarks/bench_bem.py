"""Benchmark of numeric/bem.py: the 256 x 256 Hertz solve, Tamaas side by side, and the error
against exact solutions as a function of the grid.

Problem: rigid sphere R = 1 m on a half-space E* = 1 Pa, grid of n x n pixels on [-1, 1]^2 m,
the Hertz force of the depth d = 0.25 m (a = 0.5 m), force-controlled, relative residual 1e-8.
Tamaas (if importable): the same grid and surface, its non-periodic "dcfft" operator and its
Polonsky-Keer-Rey solver at tolerance 1e-8; its depth is taken as the mean of u + h over its
contact, u computed by our operator from its pressure (its model does not return the
non-periodic displacement).

Run: ``python benchmarks/bench_bem.py``; writes benchmarks/results/bem.json. Timings are the
best of ``--repeat`` runs on this machine (2 shared cores); tests never assert on them.
"""

from __future__ import annotations

import argparse
import json
import platform
import time
from pathlib import Path

import numpy as np

from hertzmdr.numeric import bem, hertz

OUT = Path(__file__).parent / "results" / "bem.json"
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


def best_of(fn, repeat):
    best, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def ours(n, repeat):
    h, dx = sphere(n)
    F = hertz.force(D, R, E)
    t, res = best_of(lambda: bem.solve(h, dx, E, force=F, tol=1e-8, stiffness=False), repeat)
    return {"seconds": t, "iterations": res.iterations, "residual": res.residual,
            **hertz_errors(res.pressure, res.depth, dx)}, res


def tamaas(n, repeat):
    try:
        import tamaas as tm
    except ImportError as exc:
        return {"error": f"tamaas not importable: {exc}"}, None
    tm.set_log_level(tm.LogLevel.warning)  # no per-iteration printout
    h, dx = sphere(n)
    F = hertz.force(D, R, E)

    def run():
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [2.0, 2.0], [n, n])
        model.E, model.nu = E, 0.0  # E* = E/(1 - nu^2) = E
        tm.ModelFactory.registerNonPeriodic(model, "dcfft")
        solver = tm.PolonskyKeerRey(model, -np.ascontiguousarray(h), 1e-8)
        solver.setIntegralOperator("dcfft")
        solver.solve(F / 4.0)  # mean pressure over the 2 x 2 m domain
        return np.array(model.traction, copy=True)

    t, p = best_of(run, repeat)
    u = bem.HalfSpace((n, n), dx, dx, E)(p)
    S = p > 0
    depth = float(np.mean(u[S] + h[S]))
    return {"seconds": t, "version": tm.__version__, **hertz_errors(p, depth, dx)}, p


def convergence(ns):
    rows = []
    for n in ns:
        h, dx = sphere(n)
        t0 = time.perf_counter()
        res = bem.solve(h, dx, E, depth=D)
        t_s = time.perf_counter() - t0
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
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--nmax", type=int, default=512, help="largest grid of the convergence study")
    args = ap.parse_args(argv)
    mine, res = ours(args.n, args.repeat)
    print("hertzmdr.bem:", mine)
    theirs, p_tm = tamaas(args.n, args.repeat)
    print("tamaas:", theirs)
    if p_tm is not None:
        theirs["max_pressure_difference_to_ours"] = float(
            np.max(np.abs(p_tm - res.pressure)) / res.pressure.max())
    ns = [n for n in (32, 64, 128, 256, 512, 1024) if n <= args.nmax]
    rows = convergence(ns)
    OUT.parent.mkdir(exist_ok=True)
    OUT.write_text(json.dumps({
        "machine": f"{platform.machine()}, {platform.python_implementation()} "
                   f"{platform.python_version()}, numpy {np.__version__}",
        "grid": args.n, "hertzmdr": mine, "tamaas": theirs, "convergence": rows,
    }, indent=1) + "\n")


if __name__ == "__main__":
    main()
