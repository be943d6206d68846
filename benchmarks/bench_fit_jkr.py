"""The adhesive (JKR) fit (issue 17): CPU time of one 2000-point fit, beside the Hertz fit.

One retract curve of 2000 points (a rigid paraboloid R = 1 um on E* = 2 MPa, Delta gamma =
0.05 J/m^2, contact point 1.3 um, baseline 2 nN + 1e-4 N/m z, from 2.5 times the jump-off
depth below the contact point to 150 nm into the sample; a stiff cantilever, so the curve
jumps off at the depth-controlled pull-off), made by the forward numeric/adhesion.py, with
Gaussian noise of 0.1 % of the pull-off force; fitted by ``fit_adhesive.fit_curve``. Beside it,
in the same run, the Hertz fit (``fit.fit_curve``) of a Hertz curve of the same tip, sample and
points. CPU time of the process (``time.process_time``): the median over the rounds and the
fastest, and the recovered parameters in units of their standard errors.

Run: ``.venv/bin/python benchmarks/bench_fit_jkr.py [--rounds N]`` (prints a Markdown table).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from hertzmdr.numeric import adhesion, fit_adhesive, hertz
from hertzmdr.numeric import fit as hfit

R, E_STAR, DG, Z0, F0, S0 = 1e-6, 2.0e6, 0.05, 1.3e-6, 2.0e-9, 1.0e-4
N = 2000


def curves(seed=0):
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=R), E_star=E_STAR, dgamma=DG)
    po = c.pull_off("depth")
    z = np.linspace(Z0 + 2.5 * po.depth, Z0 + 150e-9, N)
    d = z - Z0
    noise = 1e-3 * abs(po.force)
    rng = np.random.default_rng(seed)
    F = F0 + S0 * z
    on = d >= po.depth
    F[on] += c.equilibrium(depth=d[on])[2]
    F_h = F0 + S0 * z + hertz.force(np.maximum(d, 0.0), R, E_STAR)
    return z, F + rng.normal(0, noise, N), F_h + rng.normal(0, noise, N), noise


def cpu(fun, rounds):
    fun()  # the first call (imports, caches) apart
    times = []
    for _ in range(rounds):
        t = time.process_time()
        out = fun()
        times.append(time.process_time() - t)
    return out, float(np.median(times)), float(min(times))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=20)
    args = ap.parse_args(argv)
    z, F, F_h, noise = curves()
    tip = hfit.Paraboloid(R=R)
    jkr, t_j, f_j = cpu(lambda: fit_adhesive.fit_curve(z, F, tip, sigma=noise), args.rounds)
    her, t_h, f_h = cpu(lambda: hfit.fit_curve(z, F_h, tip, sigma=noise), args.rounds)
    truth = np.array([E_STAR, Z0, DG, F0, S0])
    dev_j = (jkr.values - truth) / jkr.errors
    dev_h = (her.values - truth[[0, 1, 3, 4]]) / her.errors
    print(f"{N} points, noise {noise:.3g} N, {args.rounds} rounds, CPU time of the process\n")
    print("| fit | CPU median | CPU fastest | (value - truth)/sigma: E*, z_0, [dgamma,] F_0, "
          "s_0 |")
    print("|---|---|---|---|")
    print(f"| JKR (fit_adhesive) | {1e3 * t_j:.1f} ms | {1e3 * f_j:.1f} ms | "
          f"{', '.join(f'{v:+.2f}' for v in dev_j)} |")
    print(f"| Hertz (fit.fit_curve) | {1e3 * t_h:.1f} ms | {1e3 * f_h:.1f} ms | "
          f"{', '.join(f'{v:+.2f}' for v in dev_h)} |")


if __name__ == "__main__":
    main()
