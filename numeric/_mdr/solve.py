"""Numerical MDR, solving: the contact radius (5.55) and the force (5.57) at a depth or a
force on a pair of representations, and the bound of their relative error.

At given depths (``curve``, every depth at once): g(a) = d by safeguarded Newton on the
tables of g and g' and F from the table of integral g; under force control (``pair``)
g(a) = d by Newton on g and g' by quadrature and the monotone F(a) by Brent's method. The
bound is the larger of the coarse-vs-fine differences and the envelope of the differences of
g and of its integral around a put through the linearized (5.55) and (5.57), plus a smoothed
profile's own error (``smoothing``) and a rounding floor.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._mdr import quadrature, tables
from hertzmdr.numeric._mdr.spline import Rep

_EPS = np.finfo(float).eps


def radius(rep: Rep, r_max: float, d: float, guess: float | None = None) -> float:
    """Solve g(a) = d (5.55) by safeguarded Newton on g and g' by quadrature (no tables):
    bracket on 16 radii (one vectorized quadrature) unless a guess is given. d [m] -> a [m]."""
    lo, hi = 0.0, r_max
    g_hi = quadrature.g(rep, np.array([hi]))[0]
    if g_hi < d:
        raise _too_deep(d, g_hi, r_max)
    if guess is None:
        xs = np.linspace(0, hi, 17)[1:]
        gs = quadrature.g(rep, xs)
        i = int(np.searchsorted(gs, d))
        lo, hi = (xs[i - 1] if i > 0 else 0.0), xs[min(i, len(xs) - 1)]
        g_lo = gs[i - 1] if i > 0 else 0.0
        g_hi = gs[min(i, len(xs) - 1)]
        # secant start inside the bracket
        a = lo + (hi - lo) * (d - g_lo) / (g_hi - g_lo) if g_hi > g_lo else (lo + hi) / 2
    else:
        a = guess
    for _ in range(100):
        gg, gp = quadrature.g_and_gprime(rep, np.array([a]))
        ga, gp = gg[0] - d, gp[0]
        if ga == 0:
            return a
        if ga > 0:
            hi = a
        else:
            lo = a
        step = ga / gp if gp > 0 else np.inf
        if abs(step) <= 2e-16 * a:  # quadratic convergence: this step is the last
            return a - step
        a_new = a - step
        if not (lo <= a_new <= hi):
            a_new = (lo + hi) / 2
        if hi - lo <= 4e-16 * hi:
            return a_new
        a = a_new
    return a


def force(rep: Rep, a: float, d: float, E_star: float) -> float:
    """F [N] at the contact radius a [m] and depth d [m] (5.57)."""
    return float(gen.mdr_force(E_star, a, d, quadrature.G(rep, np.array([a]))[0]))  # (5.57)


def force_of_radius(rep: Rep, a: float, E_star: float) -> float:
    """F(a) [N] with d = g(a) (5.55), (5.57)."""
    return force(rep, a, quadrature.g(rep, np.array([a]))[0], E_star)


def envelope(fine: Rep, coarse: Rep, a: float) -> tuple[float, float]:
    """The largest |g_fine - g_coarse| [m] and |G_fine - G_coarse| [m^2] (G = integral_0^x g)
    on 9 radii x within two coarse sample spacings of a (and below r_max).

    The signed differences at a alone can vanish by accident (the coarse error passing
    through 0 at that radius while both are in error); their envelope over the radii around
    a cannot. (Integrating |f'_fine - f'_coarse| instead would not do: the interpolating
    splines' f' errors cancel over every interval between samples, where both splines match
    f, by construction, and their absolute values overstate the error a thousandfold.)"""
    kn = coarse.knots
    i = int(np.clip(np.searchsorted(kn, a), 1, len(kn) - 1))
    h = kn[i] - kn[i - 1]
    x = np.clip(a + h * np.linspace(-2, 2, 9), a / 2, kn[-1])
    gf, _, Gf = quadrature.direct(fine, x, with_G=True)
    gc, _, Gc = quadrature.direct(coarse, x, with_G=True)
    return float(np.max(np.abs(gf - gc))), float(np.max(np.abs(Gf - Gc)))


def pair(coarse: Rep, fine: Rep, r_max: float, depth: float | None, load: float | None,
         E_star: float) -> tuple[float, float, float, float, float, float]:
    """(d [m], a [m], F [N]) on the fine representation at the ``depth`` [m] or the force
    ``load`` [N],
    the coarse one's d [m] and a [m], and the bound of the relative error of d, a, F."""
    d, a, F = one(fine, r_max, depth, load, E_star)
    dc, ac, Fc = one(coarse, r_max, depth, load, E_star, a)
    # 1. coarse vs fine: the error of the coarse solution, conservative for the fine one
    diff = max(abs(F - Fc) / F, abs(a - ac) / a, abs(d - dc) / d)
    # 2. the same without an accidental cancellation at a: the envelope of the differences
    # of g and G around a (envelope), put through the linearized (5.55) and (5.57): F
    # is stationary in a at a fixed d (dF/da = 2 E* (d - g(a)) = 0), so at a given depth
    # dF = -2 E* dG and da = dg/g'(a); at a given force F(a) = 2 E* (a g(a) - G(a)) with
    # dF/da = 2 E* a g'(a), and dd = g' da + dg
    Dg, DG = envelope(fine, coarse, a)
    slope = a * float(quadrature.gprime(fine, np.array([a]))[0])  # a g'(a) [m]
    if depth is not None:
        dev = max(Dg / slope if slope > 0 else np.inf, 2 * E_star * DG / F)
    else:
        da = (a * Dg + DG) / (a * slope) if slope > 0 else np.inf
        dev = max(da, (slope * da + Dg) / d)
    # 3. rounding: f' of a spline through N samples loses about log10(N) digits
    floor = (64 + 4 * len(fine.knots)) * _EPS
    smooth = float(smoothing(fine, np.array([a]), np.array([d]), np.array([F]),
                             np.array([slope]), E_star)[0])
    return d, a, F, dc, ac, max(diff, dev) + smooth + floor


def smoothing(fine: Rep, a: np.ndarray, d: np.ndarray, F: np.ndarray, slope: np.ndarray,
              E_star: float) -> np.ndarray:
    """The bound's share [1] of a smoothed profile's own error (0 when interpolating), which
    the coarse-vs-fine comparison cannot see (both are smoothed alike), from eps, the error
    estimate ``Rep.smoothing_error`` on [0, a], at contact radii a [m], depths d [m], forces
    F [N] and a g'(a) = ``slope`` [m]. f lying between s - eps and s + eps on [0, a], F(d)
    lies between F_s(d - eps) and F_s(d + eps) (the force grows with the indenter: the
    comparison principle), so |dF| <= 2 E* a eps (dF/dd = 2 E* a, (5.57)) and, at a given
    force, |dd| <= eps; a moves by dg/g'(a) (5.55), with |dg| <= 2 eps for an error growing
    like r^2 (the MDR takes c r^2 to 2 c x^2; c r to (pi/2) c x)."""
    eps = fine.smoothing_error(a)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.maximum(2 * E_star * a * eps / F, eps / d)
        out = np.maximum(out, np.where(slope > 0, 2 * eps / slope, np.inf))
    return np.where(eps > 0, out, 0.0)


def one(rep: Rep, r_max: float, depth: float | None, load: float | None, E_star: float,
        guess: float | None = None) -> tuple[float, float, float]:
    """(d [m], a [m], F [N]) on one representation at the ``depth`` [m] or the force
    ``load`` [N] (5.55), (5.57); ``guess``: a contact radius near a [m] (depth control)."""
    from scipy.optimize import brentq

    if depth is not None:
        d = depth
        a = radius(rep, r_max, d, guess)
    else:
        Fmax = force_of_radius(rep, r_max, E_star)
        if load > Fmax:
            raise ValueError(f"force = {load} exceeds F(r_max) = {Fmax}")
        a = brentq(lambda aa: force_of_radius(rep, aa, E_star) - load,
                   0.0, r_max, xtol=1e-16 * r_max, rtol=1e-15)
        d = float(quadrature.g(rep, np.array([a]))[0])
    return d, a, force(rep, a, d, E_star)


def _too_deep(d: float, g_hi: float, r_max: float) -> ValueError:
    return ValueError(f"depth {float(d):.6g} m exceeds g(r_max) = {float(g_hi):.6g} m, the "
                      f"largest depth the samples reach (they end at r_max = "
                      f"{float(r_max):.6g} m): the profile is too short for this depth; "
                      "sample it further out")


def radii(rep: Rep, r_max: float, d: np.ndarray, guess: np.ndarray | None = None
          ) -> np.ndarray:
    """Solve g(a) = d (5.55) for every depth of the array d > 0 [m] at once: safeguarded
    Newton on g and g' from the tables (``tables``), started by the secant between the table
    nodes that bracket d, each radius to the same tolerance as :func:`radius`. The tables are
    computed as far as the depths need: from a quarter of r_max (or the largest ``guess``
    [m], e.g. the other representation's radii), grown to past the radius where a local
    power law g ~ x^n through the last two nodes reaches the largest depth. d [m] -> a [m]."""
    dmax = float(d.max())
    xs, gs = tables.covered(rep)
    cap = None
    if not len(xs):  # nothing computed yet: as far as the guess, or a quarter of r_max
        cap = r_max / 4 if guess is None else float(np.max(guess))
    while True:
        if cap is not None:
            tables.tables(rep, cap)
            xs, gs = tables.covered(rep)
        gs = np.maximum.accumulate(gs)
        if gs[-1] >= dmax:
            break
        if xs[-1] >= r_max:
            raise _too_deep(dmax, gs[-1], r_max)
        n = 1.0
        if len(xs) > 1 and gs[-2] > 0 and xs[-2] > 0:
            n = max(1.0, np.log(gs[-1] / gs[-2]) / np.log(xs[-1] / xs[-2]))
        est = xs[-1] * (dmax / gs[-1]) ** (1 / n) if gs[-1] > 0 else 2 * xs[-1]
        # (the table goes EXTRA nodes past cap: the margin)
        cap = min(r_max, max(est, 1.1 * xs[-1]))
    i = np.clip(np.searchsorted(gs, d), 1, len(xs) - 1)
    lo, hi, g_lo, g_hi = xs[i - 1], xs[i], gs[i - 1], gs[i]
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(g_hi > g_lo, lo + (hi - lo) * (d - g_lo) / (g_hi - g_lo), (lo + hi) / 2)
    lo, hi = lo.copy(), hi.copy()
    act = np.arange(len(d))
    for _ in range(100):
        aa = a[act]
        ga, gp = tables.g_and_gprime(rep, aa)
        ga = ga - d[act]
        up = ga > 0
        hi[act] = np.where(up, aa, hi[act])
        lo[act] = np.where(up, lo[act], aa)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(gp > 0, ga / gp, np.inf)
        new = aa - step
        out = ~((lo[act] <= new) & (new <= hi[act]))
        new[out] = (lo[act][out] + hi[act][out]) / 2
        # quadratic convergence: a step of 1e-15 a leaves ~1e-30 a, below rounding (the
        # tables' g, unlike the quadrature's, rounds differently at neighbouring radii, so
        # steps of 2e-16 a are not always reached); or the bracket has closed
        done = ((ga == 0) | (np.abs(step) <= 1e-15 * aa)
                | (hi[act] - lo[act] <= 4e-16 * hi[act]))
        a[act] = np.where(ga == 0, aa, new)
        act = act[~done]
        if not len(act):
            break
    return a


def curve(coarse: Rep, fine: Rep, r_max: float, depths: np.ndarray, E_star: float):
    """:func:`pair` at every depth of the array ``depths`` > 0 [m] at once, from the tables
    of g, g' and integral g of both representations (no quadrature once they exist): the
    fine a [m] and F [N], the coarse a [m], and the bound of the relative error of a and F
    per depth, made as :func:`pair` makes it (coarse-vs-fine differences; the envelope of the
    differences of g and its integral on 9 radii within two coarse sample spacings of a, put
    through the linearized (5.55), (5.57); a smoothed profile's own error, ``smoothing``;
    the rounding floor). The tables' interpolation
    error is part of both representations' values; the coarse tables have half the nodes
    (an error 2^6 times larger for the quintic splines), so the comparison covers it."""
    a = radii(fine, r_max, depths)
    ac = radii(coarse, r_max, depths, 1.02 * a)
    F = gen.mdr_force(E_star, a, depths, tables.G(fine, a))  # (5.57)
    Fc = gen.mdr_force(E_star, ac, depths, tables.G(coarse, ac))  # (5.57)
    diff = np.maximum(np.abs(F - Fc) / F, np.abs(a - ac) / a)
    kn = coarse.knots
    i = np.clip(np.searchsorted(kn, a), 1, len(kn) - 1)
    h = kn[i] - kn[i - 1]
    x = np.clip(a[:, None] + h[:, None] * np.linspace(-2, 2, 9), (a / 2)[:, None], kn[-1])
    xf = x.ravel()
    Dg = np.max(np.abs(tables.g(fine, xf) - tables.g(coarse, xf)).reshape(x.shape), axis=1)
    DG = np.max(np.abs(tables.G(fine, xf) - tables.G(coarse, xf)).reshape(x.shape), axis=1)
    slope = a * tables.gprime(fine, a)  # a g'(a) [m]
    with np.errstate(divide="ignore"):
        dev = np.maximum(np.where(slope > 0, Dg / slope, np.inf), 2 * E_star * DG / F)
    floor = (64 + 4 * len(fine.knots)) * _EPS
    smooth = smoothing(fine, a, depths, F, slope, E_star)
    return a, F, ac, np.maximum(diff, dev) + smooth + floor
