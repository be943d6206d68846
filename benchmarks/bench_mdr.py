"""Benchmark of the numerical MDR (numeric/mdr.py); writes docs/mdr.md and docs/mdr_convergence.png.

Run: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_mdr.py [--quick] [--out DIR]
[--docs-only]`` (``make benchmark`` runs it after bench_abel.py; needs the ``plot`` extra). The
measurements go to benchmarks/results/mdr.json; the PyAbel comparison is bench_abel.py's
(results/abel.json), summarized. ``--docs-only`` rewrites docs/mdr.md and its figure from the
two JSON files and the generated relations, measuring nothing (a second or two: after a change
of derive/, this refreshes the Derivations table). Timings are wall clock on this machine, by
``hertzmdr.numeric._timing``.
"""

from __future__ import annotations

import json
import os
import time

import _common
import bench_abel
import numpy as np
from _mdr_doc import derivations_section, verification_section

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _timing, mdr
from hertzmdr.numeric import powerlaw as pl

E = 1e9


def powerlaw_errors(n, N, budget):
    """Errors of r^n sampled at N + 1 points against the closed forms; the time of the first
    depth (a fresh profile: solve + pressure) and of a second depth (the tables reused)."""
    r = np.linspace(0, 1, N + 1)
    d = float(pl.kappa(n)) * 0.5**n
    rr = np.linspace(0.02, 0.98, 50) * 0.5  # the contact radius is 1/2

    def first_depth():
        sol = mdr.Profile.from_samples(r, r**n).solve(depth=d, E_star=E)
        return sol, sol.pressure(rr)

    def solved():
        prof = mdr.Profile.from_samples(r, r**n)
        prof.solve(depth=d, E_star=E).pressure(rr)
        return prof

    t_first = _timing.measure(first_depth, budget)
    t_again = _timing.measure(lambda prof: prof.solve(depth=0.9 * d, E_star=E).pressure(rr),
                              budget, setup=solved)
    sol, p = first_depth()
    rr = np.linspace(0.02, 0.98, 50) * sol.contact_radius
    p = sol.pressure(rr)
    eF = abs(sol.force / pl.force(d, 1.0, n, E) - 1)
    ea = abs(sol.contact_radius / pl.contact_radius(d, 1.0, n) - 1)
    ep = np.max(np.abs(p / pl.pressure(rr, d, 1.0, n, E) - 1))
    ro = np.array([0.5, 1.5, 3.0]) * sol.contact_radius
    eu = np.max(np.abs(sol.displacement(ro) / pl.surface_displacement(ro, d, 1.0, n) - 1))
    return dict(F=eF, a=ea, p=ep, u=eu, est=sol.rel_error, first=t_first.median,
                again=t_again.median)


def worn_errors(N, breakpoint, k):
    Rv, b, d = 1.0, 0.3, 0.1
    if breakpoint:
        r = np.unique(np.concatenate([np.linspace(0, b, N // 3 + 1), np.linspace(b, 1, N + 1)]))
    else:
        r = np.linspace(0, 1, N + 1)
    f = np.where(r < b, 0, (r**2 - b**2) / (2 * Rv))
    sol = mdr.Profile.from_samples(r, f, breakpoints=[b] if breakpoint else (), k=k).solve(
        depth=d, E_star=E)
    a = sol.contact_radius
    rr = np.concatenate([np.linspace(0.02, 0.98, 25) * b, b * (1 + np.array([-1e-6, 1e-6])),
                         b + np.linspace(0.02, 0.98, 25) * (a - b)])
    p, e = sol.pressure(rr, return_error=True)
    p_ref = gen.worn_pressure(E, Rv, a, b, rr)  # Problem 8 in closed form (derive/worn.py)
    ep = np.abs(p / p_ref - 1)
    return dict(F=abs(sol.force / gen.worn_force(E, Rv, b, d) - 1),
                a=abs(a / gen.worn_contact_radius(Rv, b, d) - 1),
                est=sol.rel_error, p=float(np.max(ep)), p_est=float(np.max(e / p)),
                honest=bool(np.all(e / p >= ep)))


def noisy_errors(N, sigma, seed=0):
    rng = np.random.default_rng(seed)
    r = np.linspace(0, 1, N + 1)
    f = r**2 / 2 + sigma * rng.standard_normal(r.size)
    f[0] = 0
    sol = mdr.Profile.from_samples(r, f, smoothing="gcv").solve(depth=0.25, E_star=E)
    return dict(F=abs(sol.force / gen.hertz_force(E, 1.0, 0.25) - 1), est=sol.rel_error)


def kinked_reference(radii, n=2.5, b=0.4, c2=1.0, a_target=0.7, dps=20):
    """f = r^n (r <= b), b^n + c2 (r - b) beyond: a power-law tip on a cone, f' jumping by
    s = c2 - n b^(n-1) at b. The reference: (5.59) by mpmath quadrature of g' = q + b s /
    sqrt(x^2 - b^2), q(x) = n^2 x^(n-1) B(min(1, b^2/x^2); n/2, 1/2)/2 + c2 (pi/2 - asin(b/x))
    [x > b] (from (5.52)), with x = r + w^2 or b + t^2 at the 1/sqrt singularities; the depth
    is d = g(a_target) by quadrature."""
    import mpmath as mp

    with mp.workdps(dps):
        n, b, c2 = mp.mpf(n), mp.mpf(b), mp.mpf(c2)
        s = c2 - n * b ** (n - 1)

        def q(x):
            out = n**2 * x ** (n - 1) * mp.betainc(n / 2, 0.5, 0, min(1, (b / x) ** 2)) / 2
            return out + (c2 * (mp.pi / 2 - mp.asin(b / x)) if x > b else 0)

        a = mp.mpf(a_target)
        d = mp.quad(q, [0, b]) + mp.quad(lambda t: 2 * (t * q(b + t * t) + b * s / mp.sqrt(
            2 * b + t * t)), [0, mp.sqrt(a - b)])
        out = []
        for r in radii:
            r = mp.mpf(r)
            if r < b:
                tot = mp.quad(lambda w, r=r: 2 * q(r + w * w) / mp.sqrt(2 * r + w * w),
                              [0, mp.sqrt(b - r)])
                tot += mp.quad(lambda t, r=r: 2 * (t * q(b + t * t) + b * s / mp.sqrt(
                    2 * b + t * t)) / mp.sqrt(((b - r) + t * t) * (b + t * t + r)),
                    [0, mp.sqrt(a - b)])
            else:
                tot = mp.quad(lambda w, r=r: 2 * (q(r + w * w) + b * s / mp.sqrt(
                    ((r - b) + w * w) * (r + w * w + b))) / mp.sqrt(2 * r + w * w),
                    [0, mp.sqrt(a - r)])
            out.append(float(E / mp.pi * tot))
    return float(d), np.array(out)


KINK_RADII = {"r < b (0.5 b)": 0.2, "near b (b - 1e-4 b)": 0.4 * (1 - 1e-4),
              "near b (b + 1e-4 b)": 0.4 * (1 + 1e-4), "beyond ((a + b)/2)": 0.55}


def kinked_errors(N, d, p_ref, n=2.5, b=0.4, c2=1.0):
    r = np.unique(np.concatenate([np.linspace(0, b, round(N * b) + 1),
                                  np.linspace(b, 1, round(N * (1 - b)) + 1)]))
    f = np.where(r <= b, r**n, b**n + c2 * (r - b))
    sol = mdr.Profile.from_samples(r, f, breakpoints=[b]).solve(depth=d, E_star=E)
    p, e = sol.pressure(np.array(list(KINK_RADII.values())), return_error=True)
    return np.abs(p / p_ref - 1), e / p


SMOOTH = ((0.5, 2.0), (2.0, 6.0))  # f = r^2/2 + 2 r^6: analytic, not a quintic


def smooth_speed(N, budget, cpu_rounds=15):
    """First depth (no tables yet) and a later depth of a sampled smooth profile: wall-clock
    minimum over fresh profiles (the cost without the other jobs' share); errors against the
    closed form (the MDR is linear in f: sums of the power-law relations at the common contact
    radius). ``cpu_rounds``: calls of each CPU-time minimum (15; --quick: 2)."""
    a0 = 0.5
    dn = [float(pl.kappa(n)) * c * a0**n for c, n in SMOOTH]
    d = sum(dn)
    F_ref = sum(pl.force(di, c, n, E) for di, (c, n) in zip(dn, SMOOTH, strict=True))
    r = np.linspace(0, 1, N + 1)
    f = sum(c * r**n for c, n in SMOOTH)
    rr = np.linspace(0, 1.5, 201) * a0  # the scenes' pressure profile: 201 radii to 1.5 a
    ins = rr < a0
    p_ref = np.zeros(rr.shape)
    for di, (c, n) in zip(dn, SMOOTH, strict=True):
        p_ref[ins] += pl.pressure(rr[ins], di, c, n, E)

    def solve():
        return mdr.Profile.from_samples(r, f).solve(depth=d, E_star=E)

    def later(err):
        def setup():
            prof = mdr.Profile.from_samples(r, f)
            prof.solve(depth=d, E_star=E).pressure(rr, return_error=err)
            return prof
        return setup, lambda prof: prof.solve(depth=0.9 * d, E_star=E).pressure(
            rr, return_error=err)

    t = {"solve": _timing.measure(solve, budget),
         "p": _timing.measure(lambda sol: sol.pressure(rr), budget, setup=solve),
         "p_err": _timing.measure(lambda sol: sol.pressure(rr, return_error=True), budget,
                                  setup=solve)}
    for key, err in (("next", False), ("next_err", True)):
        setup, fn = later(err)
        t[key] = _timing.measure(fn, budget, setup=setup)
    ms = {k: 1e3 * v.best for k, v in t.items()}
    # CPU time of this process (the machine is shared: its wall clock carries the other jobs'
    # share): a first depth on a fresh profile, a later depth on a solved one, both with the
    # pressure's bound, and a force-depth curve of 2000 depths on a solved profile
    setup, fn = later(True)
    ds = d * np.linspace(0.01, 1.0, CURVE_DEPTHS)
    k = cpu_rounds
    cpu = {"first": _cpu_min(lambda _: solve().pressure(rr, return_error=True), lambda: None,
                             k),
           "first_solve": _cpu_min(lambda _: solve(), lambda: None, k),
           "next": _cpu_min(fn, setup, k),
           "next_solve": _cpu_min(lambda prof: prof.solve(depth=0.9 * d, E_star=E), setup, k),
           "p_err": _cpu_min(lambda sol: sol.pressure(rr, return_error=True),
                             lambda: setup().solve(depth=0.9 * d, E_star=E), k),
           "curve": _cpu_min(lambda prof: prof.force_depth_curve(ds, E_star=E), setup, k)}
    sol = solve()
    p = sol.pressure(rr)
    p_e, e = sol.pressure(rr, return_error=True)
    return dict(solve=ms["solve"], p=ms["p"], next=ms["next"], solve_e=ms["solve"],
                p_err=ms["p_err"], next_err=ms["next_err"],
                F=abs(sol.force / F_ref - 1), a=abs(sol.contact_radius / a0 - 1),
                p_max=float(np.max(np.abs(p[ins] / p_ref[ins] - 1))),
                est=sol.rel_error, p_est=float(np.max(e[ins] / p_e[ins])),
                curve_depths=CURVE_DEPTHS, **{f"cpu_{k}": 1e3 * v for k, v in cpu.items()})


CURVE_DEPTHS = 2000


def _cpu_min(fn, setup, rounds=15):
    """The least CPU time [s] of ``fn(setup())`` over ``rounds`` calls, only fn timed
    (``time.process_time``: this process alone, single-threaded NumPy)."""
    best = np.inf
    for _ in range(rounds):
        arg = setup()
        t0 = time.process_time()
        fn(arg)
        best = min(best, time.process_time() - t0)
    return best


def order(Ns, errs):
    Ns, errs = np.asarray(Ns, float), np.asarray(errs, float)
    ok = errs > 1e-14
    if ok.sum() < 2:
        return float("nan")
    return float(-np.polyfit(np.log(Ns[ok]), np.log(errs[ok]), 1)[0])


NS, NS_QUICK = [25, 50, 100, 200, 400, 800], [25, 50, 100]
NK, NK_QUICK = [50, 100, 200, 400, 800], [50, 100]
# --quick: one noisy N (the GCV smoothing's path; the table's trend is the full run's)
NOISY, NOISY_QUICK = (100, 400, 1600), (100,)
SPEED, SPEED_QUICK = (200, 1000), (200,)


def measure_all(quick, budget):
    """Every measurement of docs/mdr.md, as plain data (saved as results/mdr.json)."""
    Ns = NS_QUICK if quick else NS
    res = {"Ns": Ns, "powerlaw": {}, "worn": [], "kinked": {}, "noisy": {}, "speed": {}}
    for n in (1.5, 2.5, 3.5):
        res["powerlaw"][str(n)] = [powerlaw_errors(n, N, budget) for N in Ns]
    for N in Ns[1:]:
        res["worn"].append(dict(N=N, breakpoint=worn_errors(N, True, 5),
                                k3=worn_errors(N, False, 3), k1=worn_errors(N, False, 1)))
    Nk = NK_QUICK if quick else NK
    d_k, p_k = kinked_reference(list(KINK_RADII.values()))
    kres = [kinked_errors(N, d_k, p_k) for N in Nk]
    res["kinked"] = dict(Ns=Nk, err=[k[0].tolist() for k in kres],
                         est=[k[1].tolist() for k in kres])
    Nn = NOISY_QUICK if quick else NOISY
    for sigma in (1e-8, 1e-6, 1e-4):
        res["noisy"][repr(sigma)] = [dict(N=N, **noisy_errors(N, sigma)) for N in Nn]
    speed_budget = budget if quick else _timing.Budget(repeats=9, min_time=0.2, max_time=2.0)
    for N in SPEED_QUICK if quick else SPEED:
        # --quick: CPU minima of 2 calls, not 15 (numbers, not timings)
        res["speed"][str(N)] = smooth_speed(N, speed_budget, 2 if quick else 15)
    res["conditions"] = _timing.conditions()
    res["load"] = list(os.getloadavg())  # the 1, 5, 15 min load averages at the end
    return res


def write_docs(res, abel_section, docs_dir):
    """docs/mdr.md and mdr_convergence.png from the measurements (measure_all)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    Ns = res["Ns"]
    out = ["# Numerical MDR: accuracy, convergence, speed\n\n",
           "<!-- Written by `benchmarks/bench_mdr.py` (`--docs-only` rewrites it from "
           "benchmarks/results/mdr.json and abel.json); timings are wall clock on the shared "
           "2-core development machine. -->\n\n",
           derivations_section(), verification_section(),
           "Errata of the chapter's MDR formulas are in [errata.md](errata.md).\n\n"
           "## Convergence against the closed forms\n\n",
           f"{res['conditions']}\n\n",
           "Samples r_i = i/N on [0, 1], quintic splines (k = 5), contact radius 1/2. "
           "Errors are relative; 'order' is the least-squares slope of log(error) vs log(N). "
           "Power laws n = 1, 2, 3, 4 are reproduced to rounding by the quintic spline "
           "(polynomials of degree <= 5), so non-integer n probe the order. Times: medians "
           "over fresh profiles (first depth: from_samples, solve and the pressure at 50 "
           "radii) and over second depths of solved profiles (their tables reused).\n\n"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for n, rows in res["powerlaw"].items():
        out.append(f"### power law n = {n}\n\n| N | F | a | p (50 radii) | u (in/out) | "
                   "estimate | first depth [ms] | next depth [ms] |\n"
                   "|---|---|---|---|---|---|---|---|\n")
        for N, e in zip(Ns, rows, strict=True):
            out.append(f"| {N} | {e['F']:.1e} | {e['a']:.1e} | {e['p']:.1e} | {e['u']:.1e} | "
                       f"{e['est']:.1e} | {1e3 * e['first']:.1f} | {1e3 * e['again']:.1f} |\n")
        orders = {k: order(Ns, [e[k] for e in rows]) for k in ("F", "a", "p", "u")}
        out.append("\norders: " + ", ".join(f"{k}: {_num(v, '.1f')}" for k, v in orders.items())
                   + "\n\n")
        axes[0].loglog(Ns, [e["F"] for e in rows], "o-", label=f"F, n={n}")
        axes[0].loglog(Ns, [e["p"] for e in rows], "s--", label=f"p, n={n}")
    axes[0].set_xlabel("samples N")
    axes[0].set_ylabel("relative error")
    axes[0].legend(fontsize=7)
    out.append("### worn paraboloid (Problem 8, R = 1, b = 0.3, d = 0.1): a kinked profile\n\n"
               "With the kink as a breakpoint the splines are exact (piecewise quadratic); the "
               "pressure (p: max relative error over 25 radii on the flat, b(1 -+ 1e-6) and 25 "
               "beyond, against `worn_pressure` in closed form) is left with the tables and the "
               "rounding of the log singularity at b. 'honest': the estimate bounds the error "
               "at every radius.\n\n"
               "| N | with breakpoint b (k=5) F | p | p estimate | honest | without (k=3) F | "
               "without (k=3) a | without (k=1) F |\n|---|---|---|---|---|---|---|---|\n")
    for w in res["worn"]:
        e1, e3, e1k = w["breakpoint"], w["k3"], w["k1"]
        out.append(f"| {w['N']} | {e1['F']:.1e} | {e1['p']:.1e} | {e1['p_est']:.1e} | "
                   f"{'yes' if e1['honest'] else 'NO'} | {e3['F']:.1e} | {e3['a']:.1e} | "
                   f"{e1k['F']:.1e} |\n")
    Nw = [w["N"] for w in res["worn"]]
    o3 = order(Nw, [w["k3"]["F"] for w in res["worn"]])
    o1 = order(Nw, [w["k1"]["F"] for w in res["worn"]])
    out.append(f"\norders without breakpoint: k=3 F {_num(o3, '.1f')}, "
               f"k=1 F {_num(o1, '.1f')}; with the breakpoint the "
               "piecewise polynomial is reproduced to rounding.\n\n")
    Nk, kerr, kest = res["kinked"]["Ns"], res["kinked"]["err"], res["kinked"]["est"]
    out.append("### a power-law tip on a cone: f = r^2.5 (r <= 0.4), 0.4^2.5 + (r - 0.4) beyond\n\n"
               "f' jumps by s = 1 - 2.5 * 0.4^1.5 = 0.368 at b = 0.4 (a breakpoint); d = g(0.7). "
               "Not a polynomial: the splines' own error shows. Reference: (5.59) by mpmath "
               "quadrature (20 digits) of g' from (5.52) with the incomplete Beta function "
               "(tests/test_mdr.py checks the same construction at 30 digits). Relative error "
               "of p / its estimate:\n\n| N | " + " | ".join(KINK_RADII) + " |\n|---|"
               + "---|" * len(KINK_RADII) + "\n")
    for N, err, est in zip(Nk, kerr, kest, strict=True):
        out.append(f"| {N} | " + " | ".join(f"{x:.1e} / {y:.1e}" for x, y in zip(
            err, est, strict=True)) + " |\n")
    kord = [order(Nk[:4], [k[i] for k in kerr[:4]]) for i in range(len(KINK_RADII))]
    honest = all(np.all(np.array(es) >= np.array(er)) for er, es in zip(kerr, kest,
                                                                         strict=True))
    out.append(f"\norders of the pressure (N = {Nk[0]} to {Nk[:4][-1]}; at 800 the errors reach "
               "the tables' resolution and rounding, about 1e-12): " + ", ".join(
                   f"{name}: {_num(o, '.1f')}" for name, o in zip(KINK_RADII, kord, strict=True))
               + f". The estimate bounds the error at every radius and N: "
               f"{'yes' if honest else 'NO'}.\n\n")
    axes[1].loglog(Nw, [w["k3"]["F"] for w in res["worn"]], "o-", label="worn, no breakpoint, k=3")
    axes[1].loglog(Nw, [w["k1"]["F"] for w in res["worn"]], "s-", label="worn, no breakpoint, k=1")
    out.append("### noisy samples (sphere R = 1, d = 0.25, GCV smoothing spline)\n\n"
               "| N | noise | F error | estimate | bounds it |\n|---|---|---|---|---|\n")
    for sigma, rows in res["noisy"].items():
        for e in rows:
            out.append(f"| {e['N']} | {float(sigma):g} | {e['F']:.1e} | {e['est']:.1e} | "
                       f"{'yes' if e['est'] >= e['F'] else 'NO'} |\n")
        axes[1].loglog([e["N"] for e in rows], [e["F"] for e in rows], "^--",
                       label=f"noise {float(sigma):g}")
    axes[1].set_xlabel("samples N")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(docs_dir / "mdr_convergence.png", dpi=110)
    plt.close(fig)
    out.append("\n![convergence](mdr_convergence.png)\n\n")
    out.append("## Speed: first depth and later depths\n\n"
               "A sampled smooth profile f = r^2/2 + 2 r^6 on [0, 1], contact radius 1/2 "
               "(E* = 1 GPa); errors against the closed form (sums of the power-law relations). "
               "'solve': Profile.from_samples + solve (force, contact radius and their estimate: "
               "Newton on the tables of g and g', which the solve computes, for both "
               "representations, as far as the contact radius needs); 'p': the pressure on the "
               "scenes' 201 radii (0 to 1.5 a); 'p + est.': the same with its error estimate. "
               "Milliseconds, wall clock, the minimum over at least 9 fresh profiles "
               "(`hertzmdr.numeric._timing`; the minimum, not the median: on the shared 2-core "
               "machine the other jobs' share of the CPU is not the method's cost); 'CPU': the "
               "same first and next depth with the estimate, CPU time of the process, the "
               "least of 15." + _load(res) + "\n\n"
               "| N | solve | first p | first depth: solve + p | + est. | CPU | next depth: "
               "solve + p | + est. | CPU | F error | a error | p error (max) | F estimate | "
               "p estimate (max) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    goal = []
    for N, s in res["speed"].items():
        goal.append((N, max(s["solve_e"] + s["p_err"], s["next_err"]), max(s["F"], s["p_max"])))
        out.append(f"| {N} | {s['solve']:.1f} | {s['p']:.1f} | {s['solve'] + s['p']:.1f} | "
                   f"{s['solve_e'] + s['p_err']:.1f} | {s.get('cpu_first', np.nan):.1f} | "
                   f"{s['next']:.1f} | {s['next_err']:.1f} | {s.get('cpu_next', np.nan):.1f} "
                   f"| {s['F']:.1e} | {s['a']:.1e} | {s['p_max']:.1e} | {s['est']:.1e} | "
                   f"{s['p_est']:.1e} |\n")
    out.append("\nIssue 3's goal, force and pressure profile to a relative error <= 1e-8 in <= 20 "
               "ms per depth, the first one included: " + "; ".join(
                   f"N = {N}: {'met' if t <= 20 and e <= 1e-8 else 'NOT met'} ({t:.1f} ms with "
                   f"the error estimate, error {e:.1e})" for N, t, e in goal) + ".\n\n")
    out.append(_issue18(res["speed"]))
    out.append("## Abel transforms (5.59), (5.61) from samples: PyAbel on the same grids\n\n")
    out.append(abel_section)
    (docs_dir / "mdr.md").write_text("".join(out))


def _load(res):
    """The machine's load during the run, where recorded: it inflates wall clock (and, less,
    CPU time: shared caches) on the 2-core machine."""
    if "load" not in res:
        return ""
    one, five, _ = res["load"]
    return (f" Load average at the end of the run: {one:.1f} (1 min), {five:.1f} (5 min) on "
            f"{os.cpu_count()} cores; above the core count every figure here is inflated, "
            "wall clock most.")


def _issue18(speed):
    """Issue 18's goal for the sampled profile, from the speed table: the verdict, what bounds
    the time and why."""
    s = speed.get("1000")
    if s is None:
        return ("Issue 18's goal (N = 1000: first depth <= 5 ms, later depths <= 1 ms): no "
                "N = 1000 in this run (--quick).\n\n")
    if "cpu_first" not in s:
        return ("Issue 18's goal (N = 1000: first depth <= 5 ms, later depths <= 1 ms): "
                "results/mdr.json predates the CPU-time measurement; run the benchmark.\n\n")
    first, later = s["cpu_first"], s["cpu_next"]
    ok_first, ok_later = first <= 5, later <= 1
    verdict = ("met" if ok_first and ok_later else "first depth " + (
        "met" if ok_first else "NOT met") + ", later depths " + ("met" if ok_later else
                                                                 "NOT met"))
    out = (
        "### Issue 18's goal\n\n"
        "N = 1000 samples at rtol = 1e-8: the first depth (from_samples, solve and the pressure "
        "profile on 201 radii with its error bound) in <= 5 ms, each later depth in <= 1 ms. "
        "Measured as CPU time of the benchmark's process (`time.process_time`, the least of 15 "
        "calls; the shared machine's wall clock carries the other jobs' share): first depth "
        f"{first:.1f} ms (from_samples and solve alone {s['cpu_first_solve']:.1f} ms), later "
        f"depths {later:.1f} ms (the solve {s['cpu_next_solve']:.2f} ms, the pressure with its "
        f"bound {s['cpu_p_err']:.1f} ms): {verdict}. "
        f"`Profile.force_depth_curve` of {s['curve_depths']} depths on a solved profile: "
        f"{s['cpu_curve']:.1f} ms ({1e3 * s['cpu_curve'] / s['curve_depths']:.1f} us a "
        "depth).\n\n"
        "How: every depth is solved on the tables of g and g' (quintic splines of the "
        "quadrature's values) by one vectorized safeguarded Newton over all depths, the force "
        "from (5.57) with integral g at the table node below a (the quadrature's value) plus "
        "an exact Gauss integral of the spline to a, and the bound made as before (coarse vs "
        "fine, the envelope of the differences around a); the tables are computed only as "
        "far as the contact radius needs and grown with it; the profile's and the tables' "
        "splines are evaluated as piecewise polynomials (Taylor coefficients per knot "
        "interval, Horner's rule: about a fifth of a B-spline evaluation's cost, "
        "`numeric/_mdr/ppoly.py`), the table nodes planned without NumPy's per-call cost, "
        "and the far pieces' kernel matrix summed in blocks that stay in cache.\n\n")
    if not (ok_first and ok_later):
        out += (
            "What bounds it: (1) the first depth computes the tables of both representations "
            "(fine and coarse: the bound needs both) by quadrature of (5.52) at ~130 (fine) "
            "and ~100 (coarse) nodes up to the contact radius: each node sums the Abel kernel "
            "over every spline piece below it (6 and 4 Gauss points a piece), a dense "
            "O(nodes x N) sum, the largest part, besides the two profile splines themselves "
            "(from_samples solves two banded systems) and the tables' quintic splines, refitted "
            "as a table grows towards the contact radius. (2) A later depth is the solve on the "
            "tables (the Newton's iterations on two representations and the bound's envelope: "
            "NumPy calls on arrays of a few elements, their per-call cost) and, the larger "
            "part, the pressure with its bound: three Abel quadratures of (5.59) at 201 radii "
            "(fine, coarse, and the integral of |q - q_coarse|), ~110 Gauss points a radius. "
            "Closed forms were tried and measured, and left: (5.59) of the tables' own "
            "piecewise polynomials by parts against the kernel's repeated antiderivatives "
            "(exact, to 1e-13 of a 30-digit quadrature; one acosh and one square root per "
            "radius and knot below a) took 3.1 ms CPU where the quadrature on the piecewise "
            "polynomials took 2.2 ms (one interleaved run on the loaded machine): NumPy's inverse "
            "hyperbolic and trigonometric functions cost about ten times a square root, so one "
            "of them per knot costs as much as the Gauss points it replaces; the same holds "
            "for the far pieces of (5.52) (an arcsine per node and knot against six square "
            "roots and "
            "multiply-adds). Why it stays: the bound (`rel_error`, tests/test_mdr_bounds.py) "
            "needs the second representation, and the accuracy figures (tests/test_mdr.py, "
            "this page) rest on the present nodes and Gauss points.\n\n")
    return out


def _num(x, fmt):
    """A number, or '-' where it is undefined (an order from fewer than two errors)."""
    return "-" if not np.isfinite(x) else format(x, fmt)


def main(argv=None):
    ap = _common.parser(__doc__)
    ap.add_argument("--docs-only", action="store_true",
                    help="rewrite mdr.md and its figure from the saved mdr.json and abel.json, "
                         "measuring nothing")
    args = ap.parse_args(argv)
    run = _common.run_from(args)
    path = run.results / "mdr.json"
    if args.docs_only:
        res = json.loads(path.read_text())
    else:
        res = measure_all(args.quick, run.budget)
        path.write_text(json.dumps(res, indent=1) + "\n")
    write_docs(res, bench_abel.mdr_section(run.results), run.docs)
    print(f"wrote {run.docs / 'mdr.md'}, {run.docs / 'mdr_convergence.png'} and {path}")


if __name__ == "__main__":
    main()
