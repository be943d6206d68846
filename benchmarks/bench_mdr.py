"""Benchmark of the numerical MDR (numeric/mdr.py); writes docs/mdr.md and docs/mdr_*.png.

Run: ``.venv/bin/python benchmarks/bench_mdr.py`` (needs the ``plot`` extra; the PyAbel
comparison is bench_abel.py's, summarized here). Timings are of this machine, wall clock.
"""

from __future__ import annotations

import time
from pathlib import Path

import bench_abel
import numpy as np

from hertzmdr.numeric import _generated as g
from hertzmdr.numeric import mdr
from hertzmdr.numeric import powerlaw as pl

DOCS = Path(__file__).resolve().parents[1] / "docs"
E = 1e9


def powerlaw_errors(n, N):
    r = np.linspace(0, 1, N + 1)
    prof = mdr.Profile.from_samples(r, r**n)
    d = float(pl.kappa(n)) * 0.5**n
    t0 = time.perf_counter()
    sol = prof.solve(depth=d, E_star=E)
    t1 = time.perf_counter()
    rr = np.linspace(0.02, 0.98, 50) * sol.contact_radius
    p = sol.pressure(rr)
    t2 = time.perf_counter()
    sol2 = prof.solve(depth=0.9 * d, E_star=E)  # a second depth: the tables are reused
    sol2.pressure(rr)
    t3 = time.perf_counter()
    eF = abs(sol.force / pl.force(d, 1.0, n, E) - 1)
    ea = abs(sol.contact_radius / pl.contact_radius(d, 1.0, n) - 1)
    ep = np.max(np.abs(p / pl.pressure(rr, d, 1.0, n, E) - 1))
    ro = np.array([0.5, 1.5, 3.0]) * sol.contact_radius
    eu = np.max(np.abs(sol.displacement(ro) / pl.surface_displacement(ro, d, 1.0, n) - 1))
    return dict(F=eF, a=ea, p=ep, u=eu, est=sol.rel_error, first=t1 - t0 + t2 - t1,
                again=t3 - t2)


def worn_errors(N, breakpoint, k):
    Rv, b, d = 1.0, 0.3, 0.1
    if breakpoint:
        r = np.unique(np.concatenate([np.linspace(0, b, N // 3 + 1), np.linspace(b, 1, N + 1)]))
    else:
        r = np.linspace(0, 1, N + 1)
    f = np.where(r < b, 0, (r**2 - b**2) / (2 * Rv))
    sol = mdr.Profile.from_samples(r, f, breakpoints=[b] if breakpoint else (), k=k).solve(
        depth=d, E_star=E)
    return dict(F=abs(sol.force / g.worn_force(E, Rv, b, d) - 1),
                a=abs(sol.contact_radius / g.worn_contact_radius(Rv, b, d) - 1),
                est=sol.rel_error)


def noisy_errors(N, sigma, seed=0):
    rng = np.random.default_rng(seed)
    r = np.linspace(0, 1, N + 1)
    f = r**2 / 2 + sigma * rng.standard_normal(r.size)
    f[0] = 0
    sol = mdr.Profile.from_samples(r, f, smoothing="gcv").solve(depth=0.25, E_star=E)
    return dict(F=abs(sol.force / g.hertz_force(E, 1.0, 0.25) - 1), est=sol.rel_error)


def order(Ns, errs):
    Ns, errs = np.asarray(Ns, float), np.asarray(errs, float)
    ok = errs > 1e-14
    if ok.sum() < 2:
        return float("nan")
    return float(-np.polyfit(np.log(Ns[ok]), np.log(errs[ok]), 1)[0])


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    Ns = [25, 50, 100, 200, 400, 800]
    out = ["# Numerical MDR: accuracy, convergence, speed\n\n",
           "<!-- Written by `benchmarks/bench_mdr.py`; timings are wall clock on the shared "
           "2-core development machine. -->\n\n",
           "The derivations are in [derivations.md](derivations.md) (families `powerlaw`, "
           "`worn`) and the errata in [errata.md](errata.md). `hertzmdr.derive.mdr.solve(f, r)` "
           "runs the MDR on a user's SymPy profile and reports the steps without closed "
           "form.\n\n## Convergence against the closed forms\n\n",
           "Samples r_i = i/N on [0, 1], quintic splines (k = 5), contact radius 1/2. "
           "Errors are relative; 'order' is the least-squares slope of log(error) vs log(N). "
           "Power laws n = 1, 2, 3, 4 are reproduced to rounding by the quintic spline "
           "(polynomials of degree <= 5), so non-integer n probe the order.\n\n"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for n in (1.5, 2.5, 3.5):
        res = [powerlaw_errors(n, N) for N in Ns]
        out.append(f"### power law n = {n}\n\n| N | F | a | p (50 radii) | u (in/out) | "
                   "estimate | first depth [ms] | next depth [ms] |\n"
                   "|---|---|---|---|---|---|---|---|\n")
        for N, e in zip(Ns, res, strict=True):
            out.append(f"| {N} | {e['F']:.1e} | {e['a']:.1e} | {e['p']:.1e} | {e['u']:.1e} | "
                       f"{e['est']:.1e} | {1e3 * e['first']:.0f} | {1e3 * e['again']:.1f} |\n")
        orders = {k: order(Ns, [e[k] for e in res]) for k in ("F", "a", "p", "u")}
        out.append("\norders: " + ", ".join(f"{k}: {v:.1f}" for k, v in orders.items()) + "\n\n")
        axes[0].loglog(Ns, [e["F"] for e in res], "o-", label=f"F, n={n}")
        axes[0].loglog(Ns, [e["p"] for e in res], "s--", label=f"p, n={n}")
    axes[0].set_xlabel("samples N")
    axes[0].set_ylabel("relative error")
    axes[0].legend(fontsize=7)
    out.append("### worn paraboloid (Problem 8, R = 1, b = 0.3, d = 0.1): a kinked profile\n\n"
               "| N | with breakpoint b (k=5) F | without (k=3) F | without (k=3) a | "
               "without (k=1) F |\n|---|---|---|---|---|\n")
    wres = []
    for N in Ns[1:]:
        e1, e3, e1k = worn_errors(N, True, 5), worn_errors(N, False, 3), worn_errors(N, False, 1)
        wres.append((N, e1, e3, e1k))
        out.append(f"| {N} | {e1['F']:.1e} | {e3['F']:.1e} | {e3['a']:.1e} | {e1k['F']:.1e} |\n")
    o3 = order(Ns[1:], [w[2]["F"] for w in wres])
    o1 = order(Ns[1:], [w[3]["F"] for w in wres])
    out.append(f"\norders without breakpoint: k=3 F {o3:.1f}, "
               f"k=1 F {o1:.1f}; with the breakpoint the "
               "piecewise polynomial is reproduced to rounding.\n\n")
    axes[1].loglog(Ns[1:], [w[2]["F"] for w in wres], "o-", label="worn, no breakpoint, k=3")
    axes[1].loglog(Ns[1:], [w[3]["F"] for w in wres], "s-", label="worn, no breakpoint, k=1")
    out.append("### noisy samples (sphere R = 1, d = 0.25, GCV smoothing spline)\n\n"
               "| N | noise | F error | estimate |\n|---|---|---|---|\n")
    for sigma in (1e-8, 1e-6, 1e-4):
        res = [noisy_errors(N, sigma) for N in (100, 400, 1600)]
        for N, e in zip((100, 400, 1600), res, strict=True):
            out.append(f"| {N} | {sigma:g} | {e['F']:.1e} | {e['est']:.1e} |\n")
        axes[1].loglog((100, 400, 1600), [e["F"] for e in res], "^--", label=f"noise {sigma:g}")
    axes[1].set_xlabel("samples N")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(DOCS / "mdr_convergence.png", dpi=110)
    out.append("\n![convergence](mdr_convergence.png)\n\n")
    out.append("## Abel transforms (5.59), (5.61) from samples: PyAbel on the same grids\n\n")
    out.append(bench_abel.mdr_section())
    (DOCS / "mdr.md").write_text("".join(out))
    print("".join(out))


if __name__ == "__main__":
    main()
