"""Fitting force curves (issue 17): the time of one fit per tip and the error of the recovered
modulus; writes docs/fit_speed.md.

One curve of 2000 points per closed-form tip (half of it before contact), made by the tip's
forward model in hertzmdr.numeric (hertz, sphere, cone, contact.punch_force, powerlaw) with
E* = 2 MPa, contact point 1.3 um, baseline 2 nN + 1e-4 N/m z and Gaussian noise of 0.1 % of the
largest force, fitted by ``hertzmdr.numeric.fit.fit_curve``: the median time of one fit, the
fastest round (the load of the shared machine inflates the median more), the first call, and
the recovered E* against the truth in units of its reported standard error. The issue's goal
is 5 ms per fit for a closed-form tip.

Run: ``.venv/bin/python benchmarks/bench_fit.py [--quick] [--out DIR]`` (``make benchmark``
runs it; ``--quick``: 200 points, two rounds).
"""

from __future__ import annotations

import _common
import numpy as np

from hertzmdr.numeric import _timing, cone, contact, hertz, powerlaw, sphere
from hertzmdr.numeric.fit import Cone, ExactSphere, FlatPunch, Paraboloid, PowerLaw, fit_curve

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


def single_curves(n, budget):
    rows = []
    for name, (tip, force, depth) in TIPS.items():
        z, F, sigma = curve(force, depth, n)
        t = _timing.measure(lambda z=z, F=F, tip=tip, sigma=sigma: fit_curve(z, F, tip,
                                                                               sigma=sigma),
                            budget)
        res = fit_curve(z, F, tip, sigma=sigma)
        rows.append(f"| {name} | {n} | {_common.seconds(t.median)} | "
                    f"{_common.seconds(t.best)} | {_common.seconds(t.first)} | "
                    f"{(res.E_star / E_STAR - 1):+.2e} | "
                    f"{(res.E_star - E_STAR) / res.errors[0]:+.2f} | {res.reduced_chi2:.3f} |\n")
    return ("## One curve per tip\n\n"
            "| tip | points | time per fit (median) | fastest round | first call | "
            "E* rel. error | (E* - truth)/sigma | reduced chi^2 |\n"
            "|---|---|---|---|---|---|---|---|\n" + "".join(rows) + "\n")


def main(argv=None):
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    n = 200 if args.quick else 2000
    text = ["# Fitting force curves: speed\n\n",
            "<!-- Written by `benchmarks/bench_fit.py`; regenerate, do not edit. -->\n\n",
            _timing.conditions() + "\n\n",
            " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
            single_curves(n, run.budget)]
    out = run.docs / "fit_speed.md"
    out.write_text("".join(text))
    print("".join(text))


if __name__ == "__main__":
    main()
