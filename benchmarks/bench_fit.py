"""Fitting force curves (issue 17): the time of one fit per tip and the error of the recovered
modulus; writes docs/fit_speed.md.

One curve of 2000 points per closed-form tip (half of it before contact), made by the tip's
forward model in hertzmdr.numeric (hertz, sphere, cone, contact.punch_force, powerlaw; the
three-sided pyramid by the cone of its force law) with E* = 2 MPa, contact point 1.3 um,
baseline 2 nN + 1e-4 N/m z and Gaussian noise of 0.1 % of the largest force, fitted by
``hertzmdr.numeric.fit.fit_curve``: the median time of one fit, the fastest round (the load of
the shared machine inflates the median more), the process's CPU time per fit
(time.process_time, median and fastest fit), the first call, and the recovered E* against the
truth in units of its reported standard error. The issue's goal is 5 ms per fit for a
closed-form tip.

Run: ``.venv/bin/python benchmarks/bench_fit.py [--quick] [--out DIR]`` (``make benchmark``
runs it; ``--quick``: 200 points, two rounds).
"""

from __future__ import annotations

import time

import _common
import numpy as np

from hertzmdr.numeric import _timing, cone, contact, hertz, powerlaw, sphere, worn
from hertzmdr.numeric.fit import (
    Cone,
    ExactSphere,
    FlatPunch,
    Paraboloid,
    PowerLaw,
    Pyramid,
    SampledTip,
    fit_curve,
)

E_STAR, Z0, F0, S0 = 2.0e6, 1.3e-6, 2.0e-9, 1.0e-4  # Pa, m, N, N/m
#: name: (tip, forward model F_tip(d) [N], deepest indentation [m]); as tests/test_fit.py
TIPS = {
    "paraboloid, R = 50 um": (Paraboloid(R=50e-6), lambda d: hertz.force(d, 50e-6, E_STAR),
                              4e-7),
    "exact sphere, R = 5 um, a/R = 0.59": (ExactSphere(R=5e-6),
                                           lambda d: sphere.force(d, 5e-6, E_STAR), 2e-6),
    "cone, theta = 0.09 rad": (Cone(theta=0.09), lambda d: cone.force(d, 0.09, E_STAR), 5e-7),
    "flat punch, a = 3 um": (FlatPunch(a=3e-6), lambda d: contact.punch_force(d, 3e-6, E_STAR),
                             2e-7),
    "power law, n = 3": (PowerLaw(c_n=1e9, n=3.0), lambda d: powerlaw.force(d, 1e9, 3.0, E_STAR),
                         3e-7),
}


def curve(force, depth, n, seed=0, noise=1e-3):
    """z [m], F [N] of a synthetic curve, half before contact, noise a fraction of max F."""
    z = np.linspace(Z0 - depth, Z0 + depth, n)
    F = force(np.maximum(z - Z0, 0.0)) + F0 + S0 * z
    sigma = noise * float(force(depth))
    return z, F + np.random.default_rng(seed).normal(0.0, sigma, n), sigma


def _sampled_sphere(R, n, r_max):
    """The spherical cap R - sqrt(R^2 - r^2) as n samples from 0 to r_max [m]."""
    r = np.linspace(0.0, r_max, n)
    return SampledTip.from_samples(r, R - np.sqrt(R * R - r * r))


#: a sampled tip for the speed row: the exact sphere of TIPS as 500 samples (the issue's case),
#: its curve made by the closed form (numeric/sphere.py)
SAMPLED = {"sampled exact sphere (500 samples), R = 5 um, a/R = 0.59":
           (_sampled_sphere(5e-6, 500, 4e-6), lambda d: sphere.force(d, 5e-6, E_STAR), 2e-6)}


def cpu_per_call(fn, calls):
    """(median, fastest) CPU time [s] of the process per call of fn() over ``calls`` calls
    (time.process_time: what the fit costs, whatever else the shared machine runs)."""
    ts = []
    for _ in range(calls):
        t0 = time.process_time()
        fn()
        ts.append(time.process_time() - t0)
    return float(np.median(ts)), min(ts)


def single_curves(n, budget):
    rows = []
    calls = max(budget.repeats, 3) * 6  # CPU-timed fits per tip (30 in the reports)
    for name, (tip, force, depth) in {**TIPS, **SAMPLED}.items():
        z, F, sigma = curve(force, depth, n)

        def once(z=z, F=F, tip=tip, sigma=sigma):
            return fit_curve(z, F, tip, sigma=sigma)

        t = _timing.measure(once, budget)
        cpu, cpu_best = cpu_per_call(once, calls)
        res = once()
        rows.append(f"| {name} | {n} | {_common.seconds(t.median)} | "
                    f"{_common.seconds(t.best)} | {_common.seconds(cpu)} | "
                    f"{_common.seconds(cpu_best)} | {_common.seconds(t.first)} | "
                    f"{(res.E_star / E_STAR - 1):+.2e} | "
                    f"{(res.E_star - E_STAR) / res.errors[0]:+.2f} | {res.reduced_chi2:.3f} |\n")
    return ("## One curve per tip\n\n"
            "The sampled tip's first call includes its table (128 depths by the numerical MDR) "
            "and the MDR's own tables of the profile; later fits with the same tip reuse them "
            "(a force map's curves). The issue's goal for it: 50 ms per fit.\n\n"
            "The CPU columns: the process's CPU time per fit (`time.process_time`, median and "
            f"fastest of {calls} fits), what a fit costs whatever else a shared machine runs; the "
            "wall-clock columns are `_timing.measure`'s rounds.\n\n"
            "| tip | points | time per fit (median) | fastest round | CPU per fit (median) | "
            "CPU, fastest fit | first call | E* rel. error | (E* - truth)/sigma | "
            "reduced chi^2 |\n"
            "|---|---|---|---|---|---|---|---|---|---|\n" + "".join(rows) + "\n")


#: nanite's metadata for a synthetic curve (it needs some; none of it enters a fit)
NANITE_METADATA = {"spring constant": 0.1, "sensitivity": 1e-7, "imaging mode": "force-distance",
                   "enum": 0, "path": "synthetic"}
NU = 0.5  # the sample's Poisson's ratio: both report E = E* (1 - nu^2)
#: the comparison's models: name, hertzmdr's tip, forward model F_tip(d), deepest indentation,
#: a sharp three-sided pyramid: nanite's hertz_pyr3s bounds alpha to 30 deg (its lmfit
#: parameter's max), so a Berkovich tip (65.27 deg) is out of its reach
PYR3 = Pyramid(alpha=np.radians(25.0), sides=3)
#: the pyramid's row of the speed table: fitted as its equal-force cone
TIPS["pyramid, 3 faces, alpha = 25 deg"] = (PYR3, lambda d: cone.force(d, PYR3.cone.theta,
                                                                       E_STAR), 5e-7)
#: nanite's model key and its geometry parameters (its cone's alpha is the half-opening angle,
#: 90 deg - theta; its sphere is Sneddon's truncated series for the cap)
PEERS = [
    ("paraboloid, R = 50 um", Paraboloid(R=50e-6), lambda d: hertz.force(d, 50e-6, E_STAR), 4e-7,
     "hertz_para", {"R": 50e-6}),
    ("cone, theta = 0.09 rad", Cone(theta=0.09), lambda d: cone.force(d, 0.09, E_STAR), 5e-7,
     "hertz_cone", {"alpha": 90 - np.degrees(0.09)}),
    ("sphere, R = 5 um, shallow (a/R = 0.2)", ExactSphere(R=5e-6),
     lambda d: sphere.force(d, 5e-6, E_STAR), 2e-7, "sneddon_spher_approx", {"R": 5e-6}),
    ("sphere, R = 5 um, deep (a/R = 0.59)", ExactSphere(R=5e-6),
     lambda d: sphere.force(d, 5e-6, E_STAR), 2e-6, "sneddon_spher_approx", {"R": 5e-6}),
    ("sphere deep, nanite's paraboloid", ExactSphere(R=5e-6),
     lambda d: sphere.force(d, 5e-6, E_STAR), 2e-6, "hertz_para", {"R": 5e-6}),
    # the curves by the pyramid's force law (the BEM's, docs/pyramid.md); nanite's alpha is
    # hertzmdr's (axis to a face's mid-line: its 0.8887 tan(alpha) is the BEM's 0.8824 + 0.7 %)
    ("pyramid, 3 faces, alpha = 25 deg", PYR3,
     lambda d: cone.force(d, PYR3.cone.theta, E_STAR), 5e-7, "hertz_pyr3s", {"alpha": 25.0}),
]


def nanite_fit(nanite, key, geom, z, F):
    """E [Pa] and its standard error by nanite: an Indentation of the curve (tip position
    = -z, nanite's sign), its own initial parameters (its contact-point guess), the tip's
    geometry and nu set, no contact-point weighting (the synthetic data have no artefact
    there), its default lmfit least squares. Its baseline is a constant (no slope)."""
    data = {"force": F, "tip position": -z, "segment": np.zeros(z.size, dtype=bool),
            "time": np.linspace(0.0, 1.0, z.size)}
    idnt = nanite.Indentation(data, NANITE_METADATA)
    p = idnt.get_initial_fit_parameters(model_key=key)
    for k, v in {**geom, "nu": NU}.items():
        p[k].value = v
    idnt.fit_model(model_key=key, params_initial=p, weight_cp=0)
    pf = idnt.fit_properties["params_fitted"]
    return float(pf["E"].value), float(pf["E"].stderr or np.nan)


def ours_fit(tip, z, F):
    r = fit_curve(z, F, tip, nu=NU)
    return r.E, r.E_error


def peer_curve(force, depth, n, seed):
    """As curve(), with a flat baseline (nanite's baseline has no slope) and 1 % noise."""
    z = np.linspace(Z0 - depth, Z0 + depth, n)
    F = force(np.maximum(z - Z0, 0.0)) + F0
    return z, F + np.random.default_rng(seed).normal(0.0, 1e-2 * float(force(depth)), n)


def _stats(vals, errs, truth):
    vals, errs = np.asarray(vals), np.asarray(errs)
    rel = vals / truth - 1
    within = float(np.mean(np.abs(vals - truth) <= errs))
    return (f"{np.mean(rel):+.2e} | {np.std(rel):.1e} | {np.median(errs / truth):.1e} | "
            f"{within:.2f}")


def side_by_side(nanite, n, seeds, budget):
    """The same synthetic curves fitted by both: E's error, scatter, standard error, time."""
    E_true = E_STAR * (1 - NU**2)  # (5.8)
    head = ("## Side by side with nanite\n\n"
            f"{seeds} curves per row ({n} points, half before contact, noise 1 % of the largest "
            "force, a flat baseline of 2 nN, E* = 2 MPa, nu = 0.5: E = 1.5 MPa) made by "
            "hertzmdr's forward models, fitted by hertzmdr (`fit_curve`, four parameters with "
            "the baseline's slope) and by nanite (its nearest model; three parameters). Per "
            "program: the mean relative error of E over the curves (the bias), their standard "
            "deviation (the scatter), the median reported standard error relative to E, the "
            "fraction of curves whose truth lies within one reported standard error (0.68 "
            "for right errors), and the median time per curve (nanite's includes building "
            "its Indentation object from the arrays).\n\n"
            "| curves | nanite model | program | E bias | E scatter | reported error | "
            "within 1 sigma | time per curve |\n|---|---|---|---|---|---|---|---|\n")
    rows = []
    for name, tip, force, depth, key, geom in PEERS:
        curves = [peer_curve(force, depth, n, seed) for seed in range(seeds)]
        ways = {"hertzmdr": lambda z, F, tip=tip: ours_fit(tip, z, F)}
        if nanite is not None:
            ways["nanite"] = lambda z, F, key=key, geom=geom: nanite_fit(nanite, key, geom, z, F)
        for prog, fn in ways.items():
            got = [fn(z, F) for z, F in curves]
            t = _timing.measure(lambda fn=fn, c=curves[0]: fn(*c), budget)
            rows.append(f"| {name} | `{key}` | {prog} | "
                        f"{_stats([g[0] for g in got], [g[1] for g in got], E_true)} | "
                        f"{_common.seconds(t.median)} |\n")
    note = ("" if nanite is not None else
            "\nnanite is not installed for this run: its rows are skipped.\n")
    return head + "".join(rows) + note + "\n"


#: measured tips that are none of nanite's shapes: Problem 8's worn paraboloid (R, b) at two
#: depths, its curves by the closed form of numeric/worn.py; hertzmdr fits it from 301 samples
#: (no breakpoint: a measured tip does not know its kink), nanite with its paraboloid of the
#: same R (the nearest of its models)
WORN = [("worn tip R = 5 um, b = 1 um, 100 nm deep", 5e-6, 1e-6, 1e-7),
        ("worn tip R = 5 um, b = 1 um, 400 nm deep", 5e-6, 1e-6, 4e-7),
        ("worn tip R = 5 um, b = 0.3 um, 100 nm deep", 5e-6, 0.3e-6, 1e-7)]


def measured_tips(nanite, n, seeds, budget):
    """Curves of a worn tip: hertzmdr's sampled tip against nanite's nearest model."""
    E_true = E_STAR * (1 - NU**2)  # (5.8)
    head = ("## Measured tips: nanite's nearest model\n\n"
            f"{seeds} curves per row ({n} points, half before contact, noise 1 % of the largest "
            "force, a flat baseline of 2 nN, E = 1.5 MPa, nu = 0.5) made by the closed form of "
            "Problem 8's worn paraboloid (numeric/worn.py: flat for r < b, (r^2 - b^2)/(2R) "
            "beyond), a tip none of nanite's models has. hertzmdr fits it as a measured tip "
            "(`SampledTip`, 301 samples from 0 to 3 um, no breakpoint at b), nanite with its "
            "paraboloid `hertz_para` of the same R, the nearest of its shapes. Columns as "
            "above; `model error` is hertzmdr's bound of the shift of E by the MDR's error "
            "(median over the curves, relative to E; `FitResult.model_error`).\n\n"
            "| curves | program | E bias | E scatter | reported error | within 1 sigma | "
            "model error | time per curve |\n|---|---|---|---|---|---|---|---|\n")
    rows = []
    for name, R, b, depth in WORN:
        r = np.linspace(0.0, 3e-6, 301)
        tip = SampledTip.from_samples(r, worn.profile(r, R, b))
        curves = [peer_curve(lambda d, R=R, b=b: worn.force(d, R, b, E_STAR), depth, n, seed)
                  for seed in range(seeds)]

        def ours(z, F, tip=tip):
            res = fit_curve(z, F, tip, nu=NU)
            return res.E, res.E_error, res.model_error[0] * (1 - NU**2)

        ways = {"hertzmdr": ours}
        if nanite is not None:
            ways["nanite `hertz_para`"] = lambda z, F, R=R: (
                *nanite_fit(nanite, "hertz_para", {"R": R}, z, F), np.nan)
        for prog, fn in ways.items():
            got = [fn(z, F) for z, F in curves]
            t = _timing.measure(lambda fn=fn, c=curves[0]: fn(*c), budget)
            model = np.median([g[2] for g in got]) / E_true
            rows.append(f"| {name} | {prog} | "
                        f"{_stats([g[0] for g in got], [g[1] for g in got], E_true)} | "
                        f"{'-' if np.isnan(model) else f'{model:.1e}'} | "
                        f"{_common.seconds(t.median)} |\n")
    note = ("" if nanite is not None else
            "\nnanite is not installed for this run: its rows are skipped.\n")
    return head + "".join(rows) + note + "\n"


def _map_curves(side, n):
    """A side x side map of paraboloid curves: E* varying over the map, contact points on a
    tilted plane, noise 1 % of the largest force, a flat baseline."""
    rng = np.random.default_rng(64)
    z = np.linspace(0.0, 1e-6, n)
    out = []
    for k in range(side * side):
        i, j = divmod(k, side)
        E = E_STAR * (1 + 0.5 * np.sin(2 * np.pi * i / side) * np.cos(2 * np.pi * j / side))
        z0 = 5e-7 + 1e-7 * (i + j) / side
        F = hertz.force(np.maximum(z - z0, 0.0), 10e-6, E) + F0
        F = F + rng.normal(0.0, 1e-2 * float(hertz.force(1e-6 - z0, 10e-6, E)), n)
        out.append((i, j, z, F, E))
    return out


def _nanite_chunk(chunk):
    import nanite  # in the worker process (a module does not pickle)

    return [nanite_fit(nanite, "hertz_para", {"R": 10e-6}, z, F) for _, _, z, F, _ in chunk]


def force_map(nanite, side, n, workers):
    """The issue's 64 x 64 map: both programs over the same worker processes."""
    from concurrent.futures import ProcessPoolExecutor

    from hertzmdr.numeric import fit_batch

    data = _map_curves(side, n)
    curves = [fit_batch.Curve(f"{i},{j}", i, j, z, F) for i, j, z, F, _ in data]
    truth = np.array([E * (1 - NU**2) for *_, E in data])
    rows = []
    t0 = time.perf_counter()
    res = fit_batch.fit_curves(curves, Paraboloid(R=10e-6), nu=NU, workers=workers)
    t_ours = time.perf_counter() - t0
    ok = [r for r in res if r.ok]
    err = np.array([r.E for r in res if r.ok]) / truth[[r.ok for r in res]] - 1
    rows.append(f"| hertzmdr `fit_batch.fit_curves` | {workers} | {t_ours:.1f} s | "
                f"{len(ok)}/{len(res)} | {np.max(np.abs(err)):.1e} |\n")
    if nanite is not None:
        size = max(1, len(data) // (workers * 16))
        t0 = time.perf_counter()
        with ProcessPoolExecutor(max_workers=workers) as pool:
            parts = list(pool.map(_nanite_chunk,
                                  [data[s:s + size] for s in range(0, len(data), size)]))
        t_nan = time.perf_counter() - t0
        got = np.array([g[0] for part in parts for g in part])
        good = np.isfinite(got)
        rows.append(f"| nanite `hertz_para` | {workers} | {t_nan:.1f} s | "
                    f"{int(good.sum())}/{len(got)} | "
                    f"{np.max(np.abs(got[good] / truth[good] - 1)):.1e} |\n")
    return (f"## A {side} x {side} force map\n\n{side * side} curves of {n} points (a "
            "paraboloid R = 10 um; E* from 1 to 3 MPa over the map, contact points on a tilted "
            "plane, noise 1 % of each curve's largest force), fitted by both programs over the "
            f"same {workers} worker processes (wall time, including the processes' start). The "
            "issue's goal: 64 x 64 curves of 1000 points in 30 s on this 2-core machine, "
            "faster than nanite.\n\n| program | processes | wall time | fitted | largest E "
            "error |\n|---|---|---|---|---|\n" + "".join(rows) + "\n")


#: the pair whose CPU-time ratio --sphere-ratio measures (docs/fitting.md, "Speed")
RATIO_PAIR = ("paraboloid, R = 50 um", "exact sphere, R = 5 um, a/R = 0.59")


def sphere_ratio(rounds, n=2000):
    """The exact sphere's CPU time per fit over the paraboloid's, on a shared machine: one
    n-point curve each (as single_curves), fitted alternately ``rounds`` times in this process
    (time.process_time per fit), so that both see the same load; the ratio of the medians is
    what transfers to a quiet machine. Writes nothing."""
    fits = []
    for name in RATIO_PAIR:
        tip, force, depth = TIPS[name]
        z, F, sigma = curve(force, depth, n)
        fits.append(lambda z=z, F=F, tip=tip, sigma=sigma: fit_curve(z, F, tip, sigma=sigma))
    for fit in fits:  # the first calls (the sphere's start table) outside the timing
        fit()
    times = [[] for _ in fits]
    for _ in range(rounds):
        for fit, ts in zip(fits, times, strict=True):
            t0 = time.process_time()
            fit()
            ts.append(time.process_time() - t0)
    med = [float(np.median(ts)) for ts in times]
    rows = [f"{name}: CPU per fit, median {_common.seconds(m)} (fastest "
            f"{_common.seconds(min(ts))})" for name, m, ts in zip(RATIO_PAIR, med, times,
                                                                  strict=True)]
    return "\n".join(rows + [f"ratio of the medians: {med[1] / med[0]:.2f} ({rounds} rounds, "
                             f"{n} points)"])


def main(argv=None):
    ap = _common.parser(__doc__)
    ap.add_argument("--sphere-ratio", type=int, metavar="ROUNDS",
                    help="only print the exact sphere's CPU time per fit over the "
                         "paraboloid's, interleaved for ROUNDS rounds (a shared machine's "
                         "measure; writes nothing)")
    args = ap.parse_args(argv)
    if args.sphere_ratio:
        print(sphere_ratio(args.sphere_ratio, 200 if args.quick else 2000))
        return
    run = _common.run_from(args)
    n = 200 if args.quick else 2000
    nanite = _common.peer("nanite", "nanite", "the nanite rows")
    text = ["# Fitting force curves: speed, and nanite side by side\n\n",
            "<!-- Written by `benchmarks/bench_fit.py`; regenerate, do not edit. -->\n\n",
            _timing.conditions() + "\n\n",
            " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
            single_curves(n, run.budget),
            side_by_side(nanite, 200 if args.quick else 1000, 3 if args.quick else 50,
                         run.budget),
            measured_tips(nanite, 200 if args.quick else 1000, 3 if args.quick else 20,
                          run.budget),
            force_map(nanite, 4 if args.quick else 64, 200 if args.quick else 1000, 2)]
    if nanite is not None:
        text.append(f"nanite {_common.version('nanite')}, lmfit {_common.version('lmfit')}.\n")
    out = run.docs / "fit_speed.md"
    out.write_text("".join(text))
    print("".join(text))


if __name__ == "__main__":
    main()
