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


#: radii evaluated at once by :func:`surface_displacement`: a block's intermediates (the far
#: form's ~45 temporaries of 128 kB) stay in the cache (issue 18)
_BLOCK = 16384
#: where r, d and R need no scaling: nothing in the forms can over- or underflow
_LO, _HI = 2.0**-250, 2.0**250


@representable
def surface_displacement(r, d, R):
    """Surface displacement u_z(r) [m] inside (5.18) and outside (Fig. 5.2) the contact.

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in [1e-15, 1000], R in [1e-12,
    1e+06] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    Inside, u_z = d - r^2/(2R); outside, the displacement of the Hertz pressure, in two forms
    of its stable far form (2 d/pi)(asin t - (t/3) 2F1(1/2, 3/2; 5/2; t^2)), t = a/r, each
    where it keeps full accuracy: for r >= 2a its Taylor series in a^2/r^2 (22 terms,
    truncation < 1.3e-17 relative), which decays like the point-load field F/(pi E* r) (5.6);
    for a < r < 2a the 2F1 in elementary functions (its cancellation ~0.65 eps a^2/r^2 stays
    below 2.6 eps there). See ``hertzmdr.derive.hertz.SERIES_SWITCH``.

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
    out = np.empty(r.shape)
    # d and R scalars within [2^-250, 2^250]: blocks of such radii need no scaling either
    plain = all(np.ndim(v) == 0 and _LO < v < _HI for v in (d, R))
    for start in range(0, r.size, _BLOCK):
        b = slice(start, start + _BLOCK)
        _displacement_block(r[b], _take(d, b), _take(R, b), out[b], plain)
    return result(out.reshape(shape))


def _displacement_block(r, d, R, out, plain):
    """u_z at the radii r of one block into out; ``plain``: d and R are scalars that need no
    scaling. A block of such radii wholly inside, or wholly at r >= 2a, is one call."""
    a = gen.hertz_contact_radius(R, d)  # (5.21)
    if plain:
        lo, hi = r.min(), r.max()
        if _LO < lo and hi < _HI:
            if hi <= a:
                out[...] = gen.hertz_displacement_inside(R, d, r)  # (5.18)
                return
            if lo >= 2 * a:  # z = a^2/r^2 <= 1/4: the series
                out[...] = gen.hertz_displacement_far(R, d, r)  # Fig. 5.2
                return
    # in or out on the same rounded a = sqrt(R) sqrt(d) as the outside forms' t = a/r, so
    # that t <= 1 there (r*r <= R*d disagreed with it at r = nextafter(a, 0): NaN); outside
    # only where R d < r^2 too (1 - R d/r^2 >= 0 under the elementary form's root).
    # Where r, d and R all lie in [2^-250, 2^250] nothing can over- or underflow. Where only
    # r is larger, the forms run as they are: r^2 may overflow (r > 2^512), but then
    # z = R d/r^2 < 2^-500 is 0 to rounding in the series, which is what inf gives, while its
    # prefactor sqrt(R) d^(3/2)/r stays in range. Elsewhere u, homogeneous of degree 1 in
    # (r, d, R), is evaluated in units of s ~ r, an even power of 2 (exact, square roots too)
    o = np.flatnonzero(r > a)
    ro, do, Ro = r[o], _take(d, o), _take(R, o)
    ok = ro > _LO  # no scaling needed
    if not plain:
        ok &= (do > _LO) & (do < _HI) & (Ro > _LO) & (Ro < _HI)
    huge = bool((ok & (ro >= _HI)).any())
    s = np.ones(ro.shape)
    k = np.flatnonzero(~ok)
    s[k] = pow2_scale(ro[k])  # s > a/4 there: (R/s)(d/s) <= 16
    if k.size:
        rs, ds, Rs = ro / s, do / s, Ro / s
    else:
        rs, ds, Rs = ro, do, Ro
    with np.errstate(over="ignore" if huge else "raise"):
        far = Rs * ds < rs * rs
        inside = np.ones(r.shape, dtype=bool)
        inside[o[far]] = False
        i = np.flatnonzero(inside)
        out[i] = gen.hertz_displacement_inside(_take(R, i), _take(d, i), r[i])  # (5.18)
        series = far & (rs >= 2 * gen.hertz_contact_radius(Rs, ds))  # z <= 1/4
        for f, form in ((np.flatnonzero(series), gen.hertz_displacement_far),
                        (np.flatnonzero(far & ~series), gen.hertz_displacement_near)):
            if f.size:  # Fig. 5.2
                out[o[f]] = _times(s, f, form(_take(Rs, f), _take(ds, f), rs[f]))


def _take(v, idx):
    """v at the flat indices (or slice) idx, or v itself when it is a scalar."""
    return v if np.ndim(v) == 0 else v[idx]


def _times(s, f, u):
    """s[f] * u, skipping the product where every s is 1 (it is exact either way)."""
    return u if s.size == 0 or (s[f] == 1.0).all() else s[f] * u
