"""Prescribed pressures p0 (1 - r^2/a^2)^n on a disc of radius a, the direct problem of section
5.1: uniform (n = 0, Problem 6), Hertzian (n = 1/2, (5.15)-(5.17)) and the punch's (n = -1/2,
(5.9)-(5.11)); the surface displacement (5.7) they cause inside and outside the disc (Fig. 5.2)
and the force they carry.

Floats or NumPy arrays in SI units; bad input raises ValueError. The formulas are generated
from :mod:`hertzmdr.derive.pressures` and :mod:`hertzmdr.derive.contact`; this module validates
and picks the inside or outside form. With two elastic bodies, E* (5.26) makes u the approach
of the two surfaces.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import nonnegative, positive, result

__all__ = ["DISTRIBUTIONS", "pressure", "force", "surface_displacement", "max_pressure_of"]

#: distribution -> (its exponent n, where the chapter gives it)
DISTRIBUTIONS = {"uniform": (0.0, "Problem 6"), "hertzian": (0.5, "(5.16), Fig. 5.2"),
                 "punch": (-0.5, "(5.10)")}


def _punch_inside(E_star, a, p0, r):
    return gen.punch_pressure_displacement(E_star, a, p0) + 0 * r  # (5.10): u = const


# distribution -> (inside u_z(E*, a, p0, r), outside u_z(E*, a, p0, r), force(a, p0))
_FORMS = {
    "uniform": (gen.uniform_pressure_displacement, gen.uniform_pressure_displacement_outside,
                gen.uniform_pressure_force),
    "hertzian": (gen.hertz_pressure_displacement, gen.hertz_pressure_displacement_outside,
                 gen.hertz_pressure_force),
    "punch": (_punch_inside, gen.punch_pressure_displacement_outside, gen.punch_pressure_force),
}


def _distribution(name: str) -> str:
    if name not in DISTRIBUTIONS:
        raise ValueError(f"distribution = {name!r} is not one of {', '.join(DISTRIBUTIONS)}")
    return name


def pressure(r, distribution, p0, a):
    """The prescribed pressure p0 (1 - r^2/a^2)^n [Pa] for r < a, 0 outside the disc.

    Parameters
    ----------
    r : float or array_like
        Distance from the centre [m], >= 0.
    distribution : str
        ``"uniform"``, ``"hertzian"`` or ``"punch"``.
    p0 : float or array_like
        Pressure scale [Pa], > 0 (the largest pressure for n >= 0).
    a : float or array_like
        Radius of the loaded disc [m], > 0.
    """
    n = DISTRIBUTIONS[_distribution(distribution)][0]
    r, p0, a = np.broadcast_arrays(nonnegative("r", r), positive("p0", p0), positive("a", a))
    out = np.zeros(r.shape)
    ins = r < a
    out[ins] = gen.disc_pressure(a[ins], n, p0[ins], r[ins])
    return result(out)


def force(distribution, p0, a):
    """Normal force F [N]: the pressure integrated over the disc ((5.11), (5.17), Problem 6).

    Parameters as :func:`pressure`.
    """
    total = _FORMS[_distribution(distribution)][2]
    return result(total(positive("a", a), positive("p0", p0)))


def surface_displacement(r, distribution, p0, a, E_star):
    """Surface displacement u_z(r) [m] inside (r <= a) and outside the disc, (5.7).

    Parameters
    ----------
    r, distribution, p0, a
        As in :func:`pressure`.
    E_star : float or array_like
        Effective modulus [Pa], > 0 (5.26).
    """
    inside, outside, _ = _FORMS[_distribution(distribution)]
    r, p0, a, E_star = np.broadcast_arrays(nonnegative("r", r), positive("p0", p0),
                                           positive("a", a), positive("E_star", E_star))
    out = np.empty(r.shape)
    ins = r <= a
    out[ins] = inside(E_star[ins], a[ins], p0[ins], r[ins])
    out[~ins] = outside(E_star[~ins], a[~ins], p0[~ins], r[~ins])
    return result(out)


def max_pressure_of(p, a, *, points=2001):
    """The largest value of a pressure p(r) [Pa] over a contact 0 <= r < a, wherever it lies
    (at the centre of a power law with n <= 2, towards the edge for n > 2, Fig. 5.17).

    The pressure is evaluated on ``points`` radii 0, a/(points - 1), ... (the edge r = a
    excluded) and the largest value is refined by a bounded scalar search (Brent) over the two
    cells beside it, to 1e-12 a + 1.5e-8 r in r (SciPy's bounded search adds sqrt(eps) r to
    its xatol); the result is the larger of the grid's and the search's.
    A pressure that is +inf on the grid (a conical tip's axis) gives +inf.

    Parameters
    ----------
    p : callable
        Vectorized pressure p(r) [Pa] of radii r [m] in [0, a).
    a : float
        Contact radius [m], >= 0. At a = 0 (an unloaded point of a sweep) the result is p(0).
    points : int
        Grid size, >= 3.

    Returns
    -------
    value : float
        The largest pressure [Pa].
    r_max : float
        Where it lies [m].
    """
    from scipy.optimize import minimize_scalar

    a = float(nonnegative("a", a))
    if not isinstance(points, (int, np.integer)) or points < 3:  # True, False < 3 too
        raise ValueError(f"points = {points!r} is out of range; valid: an integer >= 3")
    if a == 0.0:
        return float(np.asarray(p(np.zeros(1)), float)[0]), 0.0
    r = np.linspace(0.0, a, int(points))[:-1]
    values = np.asarray(p(r), float)
    k = int(np.argmax(values))
    best, where = float(values[k]), float(r[k])
    lo, hi = r[max(k - 1, 0)], r[min(k + 1, len(r) - 1)]
    if np.isfinite(best):  # hi > lo: r has at least 2 radii
        res = minimize_scalar(lambda x: -float(np.asarray(p(np.array([x])), float)[0]),
                              bounds=(lo, hi), method="bounded", options={"xatol": 1e-12 * a})
        if -res.fun > best:
            best, where = float(-res.fun), float(res.x)
    return best, where
