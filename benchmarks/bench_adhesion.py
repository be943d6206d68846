"""Adhesion by the MDR: the time and the error of a pull-off, a cycle and a sampled profile;
writes docs/adhesion_speed.md.

Each row is one call of ``hertzmdr.numeric.adhesion`` (on a fresh AdhesiveContact, so that
no cached pull-off is reused), timed by ``hertzmdr.numeric._timing.measure`` (the median of
its rounds), beside the issue's target and the relative error of its result against a
reference: the literature's JKR values and mpmath minimizations of the derived F(a) at 30
digits (closed forms, bracketed roots), the closed-form JKR pull-off (the sampled profile and
the cycle's end points).

Run: ``.venv/bin/python benchmarks/bench_adhesion.py [--quick] [--out DIR]`` (``make
benchmark`` runs it; ``--quick``: 200 samples and 100 points instead of 1000, few repeats).
"""

from __future__ import annotations

import _common
import mpmath as mp
import numpy as np

from hertzmdr.numeric import _generated_mp as gmp
from hertzmdr.numeric import _timing, mdr
from hertzmdr.numeric import adhesion as ad

E, DG, R = 2e6 / 0.75, 0.05, 20e-9  # the AFM tip on PDMS of the tour [Pa, J/m^2, m]


def _mp_min(fun, a0):
    """The stationary point of fun near a0 (mpmath, 30 digits), and fun there."""
    with mp.workdps(30):
        a = mp.findroot(lambda x: mp.diff(fun, x), (mp.mpf(a0) * 0.999, mp.mpf(a0) * 1.001),
                        solver="anderson", verify=False)
        return fun(a)


def rows(quick: bool):
    """(what, target [s], callable, its value, reference value)."""
    n_samples, n_points = (200, 100) if quick else (1000, 1000)
    jkr = -1.5 * np.pi * R * DG
    th = np.radians(20)
    cone_ref = _mp_min(lambda a: gmp.adhesion_cone_force_from_radius(
        mp.mpf(E), a, mp.mpf(DG), mp.mpf(th)), ad.AdhesiveContact(
        ad.Cone(th), E, DG).pull_off("force").contact_radius)

    def sphere_F(a):  # at the caller's precision (mp.diff raises it for its differences)
        return (gmp.sphere_force_from_radius(mp.mpf(E), mp.mpf(R), a)
                - 2 * mp.mpf(E) * a * gmp.adhesion_critical_elongation(mp.mpf(E), a,
                                                                       mp.mpf(DG)))

    sphere_ref = _mp_min(sphere_F, ad.AdhesiveContact(ad.Sphere(R), E, DG).pull_off(
        "force").contact_radius)
    r = np.linspace(0.0, 10 * R, n_samples + 1)
    prof = mdr.Profile.from_samples(r, r**2 / (2 * R))
    prof.g(np.array([R]))  # the spline and its tables, built once (as a fit reuses them)

    def pull(shape):
        return lambda: ad.AdhesiveContact(shape, E, DG).pull_off("force").force

    def cycle():
        c = ad.AdhesiveContact(ad.Paraboloid(R), E, DG).cycle(10e-9, "depth", n_points)
        return c.jumps[-1].before[1]

    return [
        ("JKR pull-off force (closed form)", 100e-6, pull(ad.Paraboloid(R)), jkr),
        ("cone pull-off force (closed form)", 100e-6, pull(ad.Cone(th)), float(cone_ref)),
        ("power law n = 2 pull-off force (closed form)", 100e-6,
         pull(ad.PowerLaw(1 / (2 * R), 2.0)), jkr),
        ("exact sphere pull-off force (bracketed root)", 5e-3, pull(ad.Sphere(R)),
         float(sphere_ref)),
        (f"JKR approach-retract cycle, {n_points} points (depth control)", 5e-3, cycle,
         -5 * np.pi * R * DG / 6),
        (f"sampled paraboloid, {n_samples} samples: pull-off force (numerical MDR)", 50e-3,
         pull(ad.Sampled(prof)), jkr),
        (f"sampled paraboloid, {n_samples} samples: {n_points}-point cycle (numerical MDR)",
         50e-3, lambda: ad.AdhesiveContact(ad.Sampled(prof), E, DG).cycle(
             10e-9, "depth", n_points).jumps[-1].before[1], -5 * np.pi * R * DG / 6),
    ]


def main(argv=None):
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    lines = ["# Adhesion by the MDR: speed and accuracy\n\n",
             "<!-- Written by `benchmarks/bench_adhesion.py`; regenerate, do not edit. -->\n\n",
             _timing.conditions() + "\n\n",
             " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
             "| call | median time | target (issue 15) | met | relative error |\n"
             "|---|---|---|---|---|\n"]
    for what, target, fn, ref in rows(args.quick):
        t = _timing.measure(fn, run.budget)
        err = abs(float(fn()) / ref - 1)
        lines.append(f"| {what} | {_common.seconds(t.median)} | {_common.seconds(target)} | "
                     f"{'yes' if t.median <= target else 'no'} | {err:.1e} |\n")
    lines.append("\nThe sampled profile's pull-off solves twice (fine and coarse samples, for "
                 "the error estimate), each a scan of dF/da by the quadrature of (5.52) and "
                 "Brent's method on scalar quadratures. Its cycle finds the instabilities and "
                 "the jumps the same way (Brent's method on scalar quadratures: most of its "
                 "time), then takes d and F at its points along each branch from Chebyshev "
                 "interpolation of g, g' and G on 32-128 radii (accepted at 1e-12, else the "
                 "quadrature). The machine is shared: under the load of other jobs (a load "
                 "average of 20 on 2 cores) the same two took 49-101 ms and 50-110 ms; the "
                 "table is the run that regenerated this page.\n")
    out = run.docs / "adhesion_speed.md"
    out.write_text("".join(lines))
    print("".join(lines))


if __name__ == "__main__":
    main()
