"""Hertz contact of a sphere (or an effective sphere) and an elastic half-space, (5.15)-(5.25).

All functions take floats or NumPy arrays in SI units, broadcast them against each other and
raise ValueError for inputs outside their domain. The formulas themselves are generated from
the derivations in :mod:`hertzmdr.derive.hertz`; this module only validates and dispatches.
Two elastic bodies: pass ``E_star`` from :func:`hertzmdr.numeric.bodies.effective_modulus`
(5.26) and ``R`` from :func:`hertzmdr.numeric.bodies.effective_radius` (5.27).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import nonnegative, positive, pow2_scale, representable, result

__all__ = [
    "contact_radius", "max_pressure", "mean_pressure", "force", "energy", "stiffness",
    "depth_from_force", "contact_radius_from_force", "max_pressure_from_force",
    "pressure", "surface_displacement",
]


@representable
def contact_radius(d, R):
    """Contact radius a = sqrt(R d) [m], (5.21).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R : float or array_like
        Effective radius of curvature [m], R > 0.
    """
    return result(gen.hertz_contact_radius(positive("R", R), nonnegative("d", d)))


@representable
def max_pressure(d, R, E_star):
    """Maximum pressure p0 = (2/pi) E* sqrt(d/R) [Pa] at the centre, (5.22).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R : float or array_like
        Effective radius [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.hertz_max_pressure(positive("E_star", E_star), positive("R", R),
                                       nonnegative("d", d)))


@representable
def mean_pressure(d, R, E_star):
    """Mean pressure F/(pi a^2) = (2/3) p0 [Pa], (5.17). Parameters as :func:`max_pressure`.

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.
    """
    return result(gen.hertz_mean_pressure(positive("E_star", E_star), positive("R", R),
                                        nonnegative("d", d)))


@representable
def force(d, R, E_star):
    """Normal force F = (4/3) E* R^(1/2) d^(3/2) [N], (5.23). Parameters as :func:`max_pressure`.

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.
    """
    return result(gen.hertz_force(positive("E_star", E_star), positive("R", R),
                                nonnegative("d", d)))


@representable
def energy(d, R, E_star):
    """Elastic energy U = (8/15) E* R^(1/2) d^(5/2) [J], (5.25).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters as :func:`max_pressure`.
    """
    return result(gen.hertz_energy(positive("E_star", E_star), positive("R", R),
                                 nonnegative("d", d)))


@representable
def stiffness(d, R, E_star):
    """Differential stiffness dF/dd = 2 a E* [N/m] (Problem 5).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters as :func:`max_pressure`.
    """
    return result(gen.hertz_stiffness(positive("E_star", E_star), positive("R", R),
                                    nonnegative("d", d)))


@representable
def depth_from_force(F, R, E_star):
    """Indentation depth d [m] under the normal force F, (5.23) inverted.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    R : float or array_like
        Effective radius [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.hertz_depth_from_force(positive("E_star", E_star), nonnegative("F", F),
                                           positive("R", R)))


@representable
def contact_radius_from_force(F, R, E_star):
    """Contact radius a = (3 F R / (4 E*))^(1/3) [m], (5.24).

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters as :func:`depth_from_force`.
    """
    return result(gen.hertz_contact_radius_from_force(positive("E_star", E_star),
                                                    nonnegative("F", F), positive("R", R)))


@representable
def max_pressure_from_force(F, R, E_star):
    """Maximum pressure p0 = (6 F E*^2 / (pi^3 R^2))^(1/3) [Pa], (5.24).

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters as :func:`depth_from_force`.
    """
    return result(gen.hertz_max_pressure_from_force(positive("E_star", E_star),
                                                  nonnegative("F", F), positive("R", R)))


@representable
def pressure(r, d, R, E_star):
    """Pressure p(r) = p0 sqrt(1 - r^2/a^2) [Pa] inside the contact and 0 outside, (5.15).

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in [1e-15, 1000], R in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    r : float or array_like
        Distance from the centre of the contact [m], r >= 0.
    d : float or array_like
        Indentation depth [m], d > 0.
    R, E_star
        As in :func:`max_pressure`.
    """
    r, d, R, E_star = np.broadcast_arrays(nonnegative("r", r), positive("d", d), positive("R", R),
                                          positive("E_star", E_star))
    # the generated form decides in or out (its Max(0, 1 - r^2/a^2)); it is called only for
    # r < 2a, so that r is never squared far outside (r = 1e155 m would overflow)
    inside = r < 2 * gen.hertz_contact_radius(R, d)  # (5.21)
    return result(np.where(inside, gen.hertz_pressure(E_star, R, d, np.where(inside, r, 0.0)),
                           0.0))  # (5.15)


@representable
def surface_displacement(r, d, R):
    """Surface displacement u_z(r) [m] inside (5.18) and outside (Fig. 5.2) the contact.

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in [1e-15, 1000], R in [1e-12,
    1e+06] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    Inside, u_z = d - r^2/(2R); outside, the displacement of the Hertz pressure, printed in a
    form that keeps full accuracy for r >> a, where it decays like the point-load field
    F/(pi E* r) (5.6).

    Parameters
    ----------
    r : float or array_like
        Distance from the centre [m], r >= 0.
    d : float or array_like
        Indentation depth [m], d > 0.
    R : float or array_like
        Effective radius [m], R > 0.
    """
    r, d, R = nonnegative("r", r), positive("d", d), positive("R", R)
    shape = np.broadcast_shapes(r.shape, d.shape, R.shape)
    r = np.broadcast_to(r, shape).ravel()
    d, R = (v if v.ndim == 0 else np.broadcast_to(v, shape).ravel() for v in (d, R))
    # in or out on the same rounded a = sqrt(R) sqrt(d) as the outside form's asin(a/r), so
    # that a/r <= 1 there (r*r <= R*d disagreed with it at r = nextafter(a, 0): NaN)
    # u is homogeneous of degree 1 in (r, d, R): lengths in units of s ~ r, an even power of
    # 2 (exact, square roots too), so that the outside form's R d/r^2 never squares a huge r;
    # outside only where both its asin(sqrt(R d)/r) and its 2F1(..., R d/r^2) see < 1.
    # Speed (issue 18): where r, d and R all lie in [2^-250, 2^250] nothing can over- or
    # underflow and s = 1 gives the same bits: only the other points are scaled; d and R stay
    # scalars when they are
    a = gen.hertz_contact_radius(R, d)  # (5.21)
    o = np.flatnonzero(r > a)
    ro, do, Ro = r[o], _take(d, o), _take(R, o)
    lo, hi = 2.0**-250, 2.0**250
    plain = (ro > lo) & (ro < hi)
    if np.ndim(do) or not lo < do < hi:
        plain &= (do > lo) & (do < hi)
    if np.ndim(Ro) or not lo < Ro < hi:
        plain &= (Ro > lo) & (Ro < hi)
    s = np.ones(ro.shape)
    k = np.flatnonzero(~plain)
    s[k] = pow2_scale(ro[k])  # s > a/4 there: (R/s)(d/s) <= 16
    if k.size:
        rs, ds, Rs = ro / s, do / s, Ro / s
    else:
        rs, ds, Rs = ro, do, Ro
    far = Rs * ds < rs * rs
    out = np.empty(r.shape)
    inside = np.ones(r.shape, dtype=bool)
    inside[o[far]] = False
    i = np.flatnonzero(inside)
    out[i] = gen.hertz_displacement_inside(_take(R, i), _take(d, i), r[i])  # (5.18)
    f = np.flatnonzero(far)
    out[o[f]] = _times(s, f, gen.hertz_displacement_outside(_take(Rs, f), _take(ds, f), rs[f]))
    return result(out.reshape(shape))


def _take(v, idx):
    """v at the flat indices idx, or v itself when it is a scalar."""
    return v if np.ndim(v) == 0 else v[idx]


def _times(s, f, u):
    """s[f] * u, skipping the product where every s is 1 (it is exact either way)."""
    return u if s.size == 0 or (s[f] == 1.0).all() else s[f] * u
