"""Stresses in the half-space under a contact pressure: Hertz in closed form, any axisymmetric
pressure by superposition of the point-force field; von Mises, Tresca and maximum shear.

Coordinates: x, y on the surface, z > 0 into the body, the contact centred at the origin.
Stresses in Pa, tension positive; tensors are returned as arrays of shape ``(..., 3, 3)``.
The formulas are generated from :mod:`hertzmdr.derive.stress` (Hertz field, axis stresses
(5.48), (5.49), von Mises (5.50)) and :mod:`hertzmdr.derive.boussinesq` (point force
(5.41)-(5.46)); this module validates, picks the stable branch, rotates and integrates.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import (
    as_float,
    nonnegative,
    poisson,
    positive,
    pow2_scale,
    result,
)

__all__ = [
    "spheroidal", "hertz_stress_cylindrical", "hertz_stress", "axis_stresses",
    "axis_max_shear", "von_mises", "tresca", "max_shear", "hertz_maximum",
    "hertz_max_orthogonal_shear",
    "superposed_stress", "superposed_plane", "PlaneField", "MAX_DISTANCE",
]


#: :func:`spheroidal`, :func:`hertz_stress_cylindrical`, :func:`hertz_stress` and
#: :func:`axis_stresses` accept max(r, z) up to this many contact radii (xi^3 stays below
#: 1e300; the stresses there are ~1e-200 p0)
MAX_DISTANCE = 1e100


def _within_reach(r, z, a):
    """ValueError naming the point if max(r, z) > MAX_DISTANCE a."""
    if np.size(r) > 64 and max(r.max(), z.max()) <= MAX_DISTANCE * a.min():
        return  # two reductions decide the common case (NaN cannot reach here: validated)
    far = np.maximum(r, z) > MAX_DISTANCE * a
    if far.any():
        i = np.unravel_index(np.argmax(far), far.shape) if far.ndim else ()
        raise ValueError(f"r = {float(r[i])!r}, z = {float(z[i])!r}, a = {float(a[i])!r}: "
                         f"max(r, z) is out of range; valid: max(r, z) <= {MAX_DISTANCE:g} a "
                         "(the stresses there are below 1e-200 p0)")


def _take(v, idx):
    """v at the flat indices idx, or v itself when it is a scalar (broadcast later)."""
    return v if np.ndim(v) == 0 else v.ravel()[idx]


#: beyond this many contact radii (2^200 ~ 1.6e60) the spheroidal forms are evaluated in units
#: of a power of 2 near max(r, z), so that the (r^2 + z^2)^2 inside them does not overflow
#: (it would beyond ~1e77); below, with s = 1, which gives the same bits
_SCALE_BEYOND = 2.0**200


#: points per block: the field is evaluated block by block, so that its ~50 intermediate
#: arrays stay in the processor's cache (2-3 times faster than whole 10^6-point arrays)
_BLOCK = 16384


def _blocks(n):
    return [slice(k, min(k + _BLOCK, n)) for k in range(0, n, _BLOCK)] or [slice(0, 0)]


def _spheroidal_flat(r, z):
    """(xi, cos(beta), sin(beta)) at flat arrays r/a, z/a (validated, within reach)."""
    # Speed (issue 18): both forms of u on every point at once (stress_spheroidal: their
    # common subexpressions once), each kept where it does not cancel: inside the sphere
    # r^2 + z^2 = a^2 (q <= 0) the cancellation-free forms, outside the other; far away
    # (max(r, z) > 2^200: r^4 would overflow) lengths in units of s, the power of 2 below
    # max(r, z), recomputed below (exact; s = 1 elsewhere gives the same bits)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        u_out, u_in, cos_in = gen.stress_spheroidal(1.0, r, z)
    q = (r - 1) * (r + 1) + z * z
    inside = q <= 0
    u = np.where(inside, u_in, u_out)
    xi = np.sqrt(u)
    with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 where the other form is kept
        cos_b = np.where(inside, cos_in, z / xi)  # u >= q > 0 outside the sphere
    sin_b = r / np.sqrt(1 + u)
    # the edge circle (to within z^2 underflow, z < 1e-154 a): the limit beta = pi/2, xi = 0,
    # which every generated form reaches continuously; 1e-100 keeps eta^3/(xi^2 + eta^2) from
    # being 0/0
    e = np.flatnonzero(q == 0)
    e = e[z[e] * z[e] == 0]
    xi[e] = 0.0
    cos_b[e] = 1e-100
    sin_b[e] = r[e]
    f = np.flatnonzero(np.maximum(r, z) > _SCALE_BEYOND) if max(
        r.max(initial=0.0), z.max(initial=0.0)) > _SCALE_BEYOND else ()
    if len(f):
        so = pow2_scale(np.maximum(r[f], z[f]))
        uo = gen.stress_spheroidal_u(1.0 / so, r[f] / so, z[f] / so)  # u = s^2 u'
        cos_b[f] = (z[f] / so) / np.sqrt(uo)
        xi[f] = so * np.sqrt(uo)
        sin_b[f] = (r[f] / so) / np.sqrt(1.0 / so**2 + uo)  # 1/s^2 underflows harmlessly
    return xi, cos_b, sin_b


def spheroidal(r, z, a):
    """Oblate spheroidal coordinates (xi, cos(beta), sin(beta)) of the contact disc at (r, z).

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+110], z in {0} U [1e-300, 1e+110], a
    in [1e-12, 1e+06], max(r, z) <= 1e100 a (a ValueError beyond) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta); xi^2 = u/a^2 with Johnson's u, the
    positive root of r^2/(a^2 + u) + z^2/u = 1. Inside the sphere r^2 + z^2 < a^2 the
    cancellation-free forms are used; at the contact edge (r = a, z = 0) the limit xi = 0,
    beta = pi/2 is returned. cos(beta) and sin(beta) are returned rather than beta, which
    would lose the relative accuracy of cos(beta) near the surface outside the contact.

    Guaranteed finite and accurate for max(r, z) <= MAX_DISTANCE a (1e100 a), a ValueError
    beyond; next to the edge circle xi keeps ~sqrt(eps) absolute (r/a is rounded).

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], r >= 0.
    z : float or array_like
        Depth [m], z >= 0.
    a : float or array_like
        Contact radius [m], a > 0.

    Returns
    -------
    xi : ndarray
        [1], xi >= 0.
    eta, chi : ndarray
        cos(beta), sin(beta) [1], 0 <= beta <= pi/2.
    """
    r, z, a = nonnegative("r", r), nonnegative("z", z), positive("a", a)
    shape = np.broadcast_shapes(r.shape, z.shape, a.shape)
    r, z = (np.broadcast_to(v, shape) for v in (r, z))
    _within_reach(r, z, np.broadcast_to(a, shape))
    if a.ndim or a != 1.0:  # dimensionless: u/a^2 below; no over- or underflow of a^4
        r, z = r / a, z / a
    r, z = r.ravel(), z.ravel()
    xi, cos_b, sin_b = np.empty(r.shape), np.empty(r.shape), np.empty(r.shape)
    for b in _blocks(r.size):
        xi[b], cos_b[b], sin_b[b] = _spheroidal_flat(r[b], z[b])
    xi, cos_b, sin_b = (v.reshape(shape) for v in (xi, cos_b, sin_b))
    return result(xi), result(cos_b), result(sin_b)


def hertz_stress_cylindrical(r, z, a, p0, nu):
    """Stresses (sigma_rr, sigma_theta, sigma_zz, tau_rz) [Pa] under the Hertz pressure.

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+110], z in {0} U [1e-300, 1e+110], a
    in [1e-12, 1e+06], p0 in [0.001, 1e+15], nu in (-1, 0.5], max(r, z) <= 1e100 a (a ValueError
    beyond) (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    Huber's closed form (Huber 1904; Johnson 1985, eqs. (3.44)) in spheroidal coordinates,
    printed without the cancellations of the textbook form on the axis, at depth and at the
    contact edge (see :mod:`hertzmdr.derive.stress`). Guaranteed finite and accurate for
    max(r, z) <= MAX_DISTANCE a (1e100 a), every -1 < nu <= 0.5 and any finite p0; beyond
    that distance a ValueError.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], r >= 0.
    z : float or array_like
        Depth [m], z >= 0.
    a : float or array_like
        Contact radius [m], a > 0.
    p0 : float or array_like
        Maximum pressure [Pa], p0 >= 0.
    nu : float or array_like
        Poisson's ratio, -1 < nu <= 0.5.

    Returns
    -------
    tuple of four ndarrays
        sigma_rr, sigma_theta, sigma_zz, tau_rz [Pa].
    """
    r, z, a = nonnegative("r", r), nonnegative("z", z), positive("a", a)
    p0, nu = nonnegative("p0", p0), poisson("nu", nu)
    shape = np.broadcast_shapes(r.shape, z.shape, a.shape, p0.shape, nu.shape)
    r, z = (np.broadcast_to(v, shape) for v in (r, z))
    _within_reach(r, z, np.broadcast_to(a, shape))
    if a.ndim or a != 1.0:  # dimensionless: u/a^2 below; no over- or underflow of a^4
        r, z = r / a, z / a
    r, z = r.ravel(), z.ravel()
    p0, nu = (v if v.ndim == 0 else np.broadcast_to(v, shape).ravel() for v in (p0, nu))
    srr, stt, szz, trz = (np.empty(r.size) for _ in range(4))
    for b in _blocks(r.size):
        xi, eta, chi = _spheroidal_flat(r[b], z[b])
        p0b, nub = (v if v.ndim == 0 else v[b] for v in (p0, nu))
        # Speed (issue 18): the form with atan on every point at once (xi >= 1 gives harmless
        # inf/0 there; stress_hertz_field: the four components, common subexpressions once),
        # then the hypergeometric form without its cancellation only at xi >= 1; p0 and nu
        # stay scalars when they are
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            srr[b], stt[b], szz[b], trz[b] = gen.stress_hertz_field(chi, eta, nub, p0b, xi)
        f = np.flatnonzero(xi >= 1.0)
        if f.size:
            fb = f + b.start
            srr[fb], stt[fb] = gen.stress_hertz_field_far(chi[f], eta[f], _take(nub, f),
                                                          _take(p0b, f), xi[f])
    srr, stt, szz, trz = (v.reshape(shape) for v in (srr, stt, szz, trz))
    return tuple(result(v) for v in (srr, stt, szz, trz))


def _rotate(x, y, srr, stt, szz, trz, rr=None):
    """Cartesian tensor (..., 3, 3) from cylindrical components at azimuth atan2(y, x).

    ``rr`` = hypot(x, y) when the caller has it. The components are written into a (3, 3, ...)
    buffer (each one contiguous) and returned as its (..., 3, 3) view: no strided writes,
    and a component read back (``sigma[..., 0, 0]``) is contiguous too."""
    x, y = np.broadcast_arrays(x, y)
    srr, stt, szz, trz = np.broadcast_arrays(srr, stt, szz, trz)
    if rr is None:
        rr = np.hypot(x, y)
    on = rr > 0
    c = np.ones(srr.shape)  # on the axis sigma_rr = sigma_theta: any angle
    s = np.zeros(srr.shape)
    np.divide(x, rr, out=c, where=on)
    np.divide(y, rr, out=s, where=on)
    out = np.empty((3, 3) + srr.shape)
    t = np.empty(srr.shape)
    for k, (p, q) in enumerate(((c, s), (s, c))):  # srr p p + stt q q
        np.multiply(srr, p, out=out[k, k, ...])
        out[k, k, ...] *= p
        np.multiply(stt, q, out=t)
        t *= q
        out[k, k, ...] += t
    out[2, 2, ...] = szz
    np.subtract(srr, stt, out=out[0, 1, ...])
    out[0, 1, ...] *= s
    out[0, 1, ...] *= c
    np.multiply(trz, c, out=out[0, 2, ...])
    np.multiply(trz, s, out=out[1, 2, ...])
    out[1, 0, ...], out[2, 0, ...], out[2, 1, ...] = out[0, 1, ...], out[0, 2, ...], out[1, 2, ...]
    return np.moveaxis(out, (0, 1), (-2, -1))


def _rotate_bound(x, y, err_rr, err_tt, err_zz, err_rz):
    """Bounds of the Cartesian components' errors from bounds of the cylindrical ones: as
    :func:`_rotate`, but sigma_xy = (sigma_rr - sigma_theta) s c gets the sum of their bounds
    (the errors may have either sign), not their difference."""
    e = np.abs(_rotate(x, y, err_rr, err_tt, err_zz, err_rz))
    x, y = np.broadcast_arrays(x, y)
    rr = np.hypot(x, y)
    sc = np.zeros(rr.shape)
    np.divide(np.abs(x * y), rr * rr, out=sc, where=rr > 0)
    e[..., 0, 1] = e[..., 1, 0] = (np.abs(err_rr) + np.abs(err_tt)) * sc
    return e


def hertz_stress(x, y, z, a, p0, nu):
    """Stress tensor [Pa] at (x, y, z) under the Hertz pressure p0 (1 - r^2/a^2)^(1/2) (5.15).

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+110], y in {0} U [1e-300, 1e+110], z
    in {0} U [1e-300, 1e+110], a in [1e-12, 1e+06], p0 in [0.001, 1e+15], nu in (-1, 0.5],
    max(sqrt(x^2 + y^2), z) <= 1e100 a (a ValueError beyond) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    x, y : float or array_like
        Surface coordinates [m] from the contact centre.
    z : float or array_like
        Depth [m], z >= 0.
    a, p0, nu
        Contact radius [m], maximum pressure [Pa], Poisson's ratio, as in
        :func:`hertz_stress_cylindrical`.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        sigma_ij [Pa], tension positive.
    """
    x, y = as_float("x", x), as_float("y", y)
    x, y, z = np.broadcast_arrays(x, y, z)  # a, p0, nu: broadcast where they are used
    rr = np.hypot(x, y)
    srr, stt, szz, trz = hertz_stress_cylindrical(rr, z, a, p0, nu)
    return _rotate(x, y, srr, stt, szz, trz, rr)


def axis_stresses(z, a, p0, nu):
    """sigma_zz (5.48) and sigma_xx = sigma_yy (5.49) [Pa] on the axis under the Hertz pressure.

    Guaranteed finite and accurate for z in {0} U [1e-300, 1e+110], a in [1e-12, 1e+06], p0 in
    [0.001, 1e+15], nu in (-1, 0.5], z <= 1e100 a (a ValueError beyond) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    (5.49) is used for z < a; for z >= a a form without its cancellation (exact at nu = 1/2).

    Parameters
    ----------
    z : float or array_like
        Depth [m], z >= 0.
    a, p0, nu
        As in :func:`hertz_stress_cylindrical`.
    """
    z, a, p0, nu = np.broadcast_arrays(nonnegative("z", z), positive("a", a),
                                       nonnegative("p0", p0), poisson("nu", nu))
    _within_reach(z, z, a)
    s_ = pow2_scale(np.maximum(a, z))  # homogeneous of degree 0 in (z, a): in units of a
    z, a = z / s_, a / s_  # power of 2 near max(a, z) (exact): z^4 of the deep form <= 16
    szz = gen.stress_axis_sigma_zz(a, p0, z)  # (5.48)
    sxx = np.empty(z.shape)
    shallow = z < a
    s, d = shallow & (z > 0), ~shallow
    sxx[s] = gen.stress_axis_sigma_xx(a[s], nu[s], p0[s], z[s])  # (5.49)
    sxx[d] = gen.stress_axis_sigma_xx_deep(a[d], nu[d], p0[d], z[d])
    top = z == 0  # (5.49) at z -> 0: -(1 + 2 nu) p0/2; the spheroidal form is exact there
    sxx[top] = gen.stress_hertz_sigma_rr(nu[top], p0[top], 0.0, 1.0, 0.0)
    return result(szz), result(sxx)


def axis_max_shear(nu):
    """Depth z/a and value tau_1/p0 of the maximum of tau_1 = (sigma_xx - sigma_zz)/2 on the
    axis under the Hertz pressure (Fig. 5.8); the von Mises stress there is 2 tau_1.

    Guaranteed finite and accurate for nu in (-1, 0.5] (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    The root of d(tau_1)/dz (generated from the derivation) by Brent's method on
    z_lo <= z <= 2 a, to full double precision (relative: the maximum approaches the surface
    like z = pi (1 + nu) a/6 as nu -> -1). z_lo (``stress_axis_max_shear_bracket``) is derived
    from lower bounds of the slope's terms, so that the bracket holds for every nu.

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 0.5: the whole range is guaranteed (finite, z/a to a few
        ulp).

    Returns
    -------
    (float, float)
        z/a and tau_1/p0 at the maximum.
    """
    from scipy.optimize import brentq

    nu = float(poisson("nu", nu))
    lo = float(gen.stress_axis_max_shear_bracket(1.0, nu))  # slope > 0 there, < 0 at 2a
    s = brentq(lambda t: gen.stress_axis_max_shear_slope(1.0, nu, 1.0, t), lo, 2.0,
               xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=200)
    return s, float(gen.stress_axis_max_shear(1.0, nu, 1.0, s))


def von_mises(sigma):
    """von Mises equivalent stress (5.50) [Pa] of stress tensors of shape (..., 3, 3).

    Guaranteed finite and accurate for s in [1e-100, 1e+100] (s: the size of the stress components)
    (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.
    """
    s = as_float("sigma", sigma)
    return result(gen.stress_von_mises(s[..., 0, 0], s[..., 1, 1], s[..., 2, 2], s[..., 0, 1],
                                     s[..., 1, 2], s[..., 0, 2]))


def tresca(sigma):
    """Tresca equivalent stress sigma_1 - sigma_3 [Pa] (largest minus smallest principal).

    Guaranteed finite and accurate for s in [1e-100, 1e+100] (s: the size of the stress components)
    (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.
    """
    ev = np.linalg.eigvalsh(as_float("sigma", sigma))
    return result(ev[..., -1] - ev[..., 0])


def max_shear(sigma):
    """Maximum shear stress (sigma_1 - sigma_3)/2 [Pa]; on the axis it is tau_1 of Fig. 5.8.

    Guaranteed finite and accurate for s in [1e-100, 1e+100] (s: the size of the stress components)
    (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.
    """
    return result(0.5 * np.asarray(tresca(sigma)))


def hertz_maximum(nu, criterion: str = "von_mises"):
    """Maximum of an equivalent stress in the body under the Hertz pressure, over p0.

    Guaranteed finite and accurate for nu in (-1, 0.5] (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    A 60 x 60 grid over 0 <= r <= 2a, 0 <= z <= 2a locates the peak; Nelder-Mead refines it
    (for the Hertz pressure the peak lies on the axis; it is searched for, not assumed).

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    criterion : {"von_mises", "tresca", "max_shear"}

    Returns
    -------
    (float, float, float)
        value/p0, r/a, z/a at the maximum.
    """
    from scipy.optimize import minimize

    funcs = {"von_mises": von_mises, "tresca": tresca, "max_shear": max_shear}
    if criterion not in funcs:
        raise ValueError(f"criterion = {criterion!r}; valid: {sorted(funcs)}")
    nu = float(poisson("nu", nu))
    f = funcs[criterion]

    def field(r, z):
        return np.asarray(f(hertz_stress(r, 0.0, z, 1.0, 1.0, nu)))

    rr, zz = np.meshgrid(np.linspace(0, 2, 61), np.linspace(0, 2, 61))
    vals = field(rr, zz)
    k = np.unravel_index(np.argmax(vals), vals.shape)
    start = np.array([rr[k], zz[k]])
    res = minimize(lambda p: -float(field(abs(p[0]), abs(p[1]))), start, method="Nelder-Mead",
                   options={"xatol": 1e-10, "fatol": 1e-15, "maxiter": 2000})
    r_best, z_best = abs(res.x[0]), abs(res.x[1])
    return float(field(r_best, z_best)), r_best, z_best


def hertz_max_orthogonal_shear():
    """The largest orthogonal shear |tau_rz| under the Hertz pressure and where it is.

    Exact (derived in :mod:`hertzmdr.derive.stress`, the one interior root of the gradient of
    Huber's tau_rz): |tau_rz| = 0.213891 p0 at r = ((7 - 17^(1/2))/4)^(1/2) a = 0.848071 a,
    z = (17^(1/2) - 4)^(1/2) a = 0.350864 a, for every nu (tau_rz does not depend on nu). It
    is the largest shear stress on planes normal to the surface, the one of rolling-contact
    fatigue under a rolling ball.

    Returns
    -------
    (float, float, float)
        |tau_rz|max/p0, r/a and z/a at the maximum (on the circle of that radius and depth).
    """
    return (float(gen.stress_hertz_max_orthogonal_shear(1.0)),
            float(gen.stress_hertz_max_orthogonal_shear_r(1.0)),
            float(gen.stress_hertz_max_orthogonal_shear_z(1.0)))


# -- superposition of the point-force field (5.41)-(5.46) over an axisymmetric pressure --------

def _tanh_sinh(level: int):
    """Tanh-sinh nodes on (0, 1) with 1 - x kept exact, and weights; step 2^-level."""
    h = 2.0 ** -level
    t = np.arange(-int(4.5 / h), int(4.5 / h) + 1) * h
    u = 0.5 * np.pi * np.sinh(t)
    lo = 1.0 / (1.0 + np.exp(2 * u))  # (1 - tanh u)/2 = distance from 1 in (0, 1) units
    x = 1.0 / (1.0 + np.exp(-2 * u))  # (1 + tanh u)/2
    w = h * 0.25 * np.pi * np.cosh(t) / np.cosh(u) ** 2
    keep = (w > 1e-300) & (lo > 0) & (x > 0)
    return x[keep], lo[keep], w[keep]


def _kernels(nu, dx, dy, z):
    """Point-force stresses of a unit force, field minus source = (dx, dy, z)."""
    return tuple(getattr(gen, f"boussinesq_sigma_{c}")(1.0, nu, dx, dy, z)
                 for c in ("xx", "yy", "zz", "xz"))


#: ulps by which the source radius is moved for the rounding term of the error estimate: a
#: node's radius rho carries a few ulps of rounding (s = z sinh(v), then hypot), which a pressure
#: singular at the rim (1/sqrt(a - rho): flat punch, adhesive edge) turns into an error of order
#: sqrt(eps) that the coarse-vs-fine difference does not see (both rules share it)
_RIM_ULPS = 4
#: the roundings of a superposed sum, in units of eps times the sum of its terms' sizes: each
#: term (kernel, pressure, node and weights: a few tens of operations) carries about 10 eps of
#: rounding and NumPy's pairwise summation adds log2 of the ~1e4 terms' count in eps/2; 16 eps
#: bounds both. Where both rules have converged their difference is below this, and an estimate
#: without it fell short of the actual error (2e-16 against 6e-19, relative, on the Hertz axis
#: at z = a/50: numeric/_accuracy_cases.py's stress_superposition)
_SUM_ROUNDINGS = 16


def _superpose_point(r, z, a, nu, pressure, n_psi, level):
    """(sigma_rr, sigma_theta, sigma_zz, tau_rz) at (r, 0, z), z > 0, by rays from the field
    point's projection: source = (r + s cos psi, s sin psi), dA = s ds dpsi; and the change of
    each when every source radius moves by _RIM_ULPS ulps (the rim's rounding term of the error),
    and the sum of each integrand's absolute values (its roundings' scale)."""
    x01, _, w01 = _tanh_sinh(level)
    if r < a:
        # psi in [0, pi] by the symmetry y -> -y; the integrand is smooth and periodic in psi,
        # so the trapezoidal rule converges geometrically
        psi = np.linspace(0.0, np.pi, n_psi + 1)
        wpsi = np.full(psi.shape, np.pi / n_psi)
        wpsi[[0, -1]] *= 0.5
        wpsi *= 2.0
        c, sn = np.cos(psi), np.sin(psi)
        smax = -r * c + np.sqrt((a - r * sn) * (a + r * sn))
        # s = z sinh(v), v in [0, V]: clusters nodes at the scale z of the kernel near s = 0;
        # tanh-sinh in v copes with the pressure's singularity at the disc's rim (s = smax)
        vmax = np.arcsinh(smax / z)[:, None]
        v = vmax * x01[None, :]
        s = z * np.sinh(v)
        ds = z * np.cosh(v) * vmax * w01[None, :]
    else:
        psim = np.arcsin(a / r)
        # psi = pi + psim sin(theta), Gauss-Legendre in theta: the chord vanishes like a square
        # root at the tangent rays, which the sine map makes smooth
        th, wth = np.polynomial.legendre.leggauss(n_psi)
        th, wth = th * np.pi / 2, wth * np.pi / 2
        psi = np.pi + psim * np.sin(th)
        wpsi = wth * psim * np.cos(th)
        c, sn = np.cos(psi), np.sin(psi)
        half = np.sqrt(np.maximum((a - r * np.abs(sn)) * (a + r * np.abs(sn)), 0.0))
        s1, s2 = -r * c - half, -r * c + half
        s = s1[:, None] + (s2 - s1)[:, None] * x01[None, :]
        ds = (s2 - s1)[:, None] * w01[None, :]
    cc, ss = c[:, None], sn[:, None]
    sx, sy = r + s * cc, s * ss
    rho = np.hypot(sx, sy)
    rho = np.minimum(rho, np.nextafter(a, 0.0))  # the pressure is evaluated inside the disc
    p = np.asarray(pressure(rho), dtype=float)
    moved = np.asarray(pressure(rho * (1 - _RIM_ULPS * np.finfo(float).eps)), dtype=float)
    k = _kernels(nu, -s * cc, -s * ss, z)
    wts = p * s * ds * wpsi[:, None]
    dw = (moved - p) * s * ds * wpsi[:, None]
    return (tuple(float(np.sum(kk * wts)) for kk in k)
            + tuple(float(np.sum(kk * dw)) for kk in k)
            + tuple(float(np.sum(np.abs(kk * wts))) for kk in k))


def superposed_stress(x, y, z, pressure, a, nu, *, n_psi: int = 64, level: int = 5):
    """Stress tensor [Pa] under an axisymmetric pressure p(r) on r < a, by superposing the
    point-force field (5.41)-(5.46) over the pressure (5.47), with an error estimate.

    Guaranteed finite and accurate for x in [0.001, 10], z in [0.001, 10], a in [0.1, 10], nu in
    (-1, 0.5] (x, z: the field point, for a uniform pressure on r < a) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Quadrature on rays from the field point's projection (so the kernel's scale z is resolved
    however close to the surface): in the distance s, tanh-sinh on s = z sinh(v), which copes
    with the end-point singularities of MDR pressures at the rim (flat punch (a^2 - r^2)^(-1/2),
    Hertz (a^2 - r^2)^(1/2)) and with the peak of the kernel near s = 0; in the ray angle, the
    trapezoidal rule inside the contact (periodic, smooth integrand: geometric convergence) and
    Gauss-Legendre on a sine map outside it. The error estimate is the difference between this
    result and one with half the step in both rules (the finer one is returned), plus the
    roundings of the sum (16 eps times the sum of its terms' sizes), plus the
    change of the finer one when every source radius moves by a few ulps: a pressure singular
    at the rim like 1/sqrt(a - r) turns the rounding of the nodes' radii into an error of order
    sqrt(eps) of the pressure's scale (5e-9 measured under the adhesive edge, five times the
    rules' difference), which both rules share; the moved radii bound it (tests/test_stress.py,
    tests/test_scene_adhesion.py, against mpmath).

    Parameters
    ----------
    x, y : float or array_like
        Surface coordinates [m].
    z : float or array_like
        Depth [m], z > 0 (on the surface, sigma_zz = -p and the tangential stresses need the
        principal value of the kernel, which this route does not compute).
    pressure : callable
        p(r) [Pa] for arrays 0 <= r < a; may be singular at r = a (integrably) and at r = 0.
    a : float
        Radius of the loaded disc [m], a > 0.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    n_psi, level : int
        Angle nodes and tanh-sinh level (step 2^-level) of the coarse rule.

    Returns
    -------
    sigma : ndarray, shape (..., 3, 3)
        Stress tensor [Pa].
    error : ndarray, shape (..., 3, 3)
        Estimated absolute error [Pa] of each component.
    """
    if not callable(pressure):
        raise ValueError(f"pressure = {pressure!r} is not callable; valid: a function p(r)")
    a = float(positive("a", a))
    nu = float(poisson("nu", nu))
    x, y, z = np.broadcast_arrays(as_float("x", x), as_float("y", y), positive("z", z))
    flat = [np.ravel(v) for v in (x, y, z)]
    out = np.empty((flat[0].size, 2, 12))
    for i, (xi_, yi_, zi_) in enumerate(zip(*flat, strict=True)):
        r = float(np.hypot(xi_, yi_))
        out[i, 0] = _superpose_point(r, zi_, a, nu, pressure, n_psi, level)
        out[i, 1] = _superpose_point(r, zi_, a, nu, pressure, 2 * n_psi, level + 1)
    fine = out[:, 1, :4].reshape(x.shape + (4,))
    err = (np.abs(out[:, 1, :4] - out[:, 0, :4]) + np.abs(out[:, 1, 4:8])
           + _SUM_ROUNDINGS * np.finfo(float).eps * out[:, 1, 8:]).reshape(x.shape + (4,))
    sig = _rotate(x, y, *np.moveaxis(fine, -1, 0))
    return sig, _rotate_bound(x, y, *np.moveaxis(err, -1, 0))


@dataclass(frozen=True)
class PlaneField:
    """The von Mises stress (5.50), the largest shear stress (sigma_1 - sigma_3)/2 and the
    orthogonal shear |tau_xz| (= |tau_rz| at y = 0) [Pa] on a grid of the x-z plane (y = 0),
    indexed [z][x], with a relative error estimate.

    Attributes
    ----------
    x, z : ndarray
        The grid's coordinates [m].
    von_mises, max_shear, orthogonal_shear : ndarray
        Shape (len(z), len(x)) [Pa].
    rel_error : float
        The largest estimated absolute error of any stress component over the largest
        |component| on the grid [1].
    """

    x: np.ndarray
    z: np.ndarray
    von_mises: np.ndarray
    max_shear: np.ndarray
    orthogonal_shear: np.ndarray
    rel_error: float

    def maximum(self, criterion: str) -> tuple[float, float, float]:
        """(value [Pa], x [m], z [m]) of the largest ``"von_mises"``, ``"max_shear"`` or
        ``"orthogonal_shear"`` on the grid (located to the grid's spacing)."""
        valid = ("von_mises", "max_shear", "orthogonal_shear")
        if criterion not in valid:
            raise ValueError(f"criterion = {criterion!r}; valid: {', '.join(map(repr, valid))}")
        field = getattr(self, criterion)
        k = np.unravel_index(int(np.argmax(field)), field.shape)
        return float(field[k]), float(self.x[k[1]]), float(self.z[k[0]])


def superposed_plane(pressure, a, nu, *, n: int = 13) -> PlaneField:
    """The von Mises and the largest shear stress under an axisymmetric pressure p(r) on r < a,
    by :func:`superposed_stress`, on n points 0 <= x <= 2a and the n - 1 points 0 < z <= 2a of
    an n-point grid (z = 0 excluded: see :func:`superposed_stress`).

    Parameters
    ----------
    pressure : callable
        p(r) [Pa], as :func:`superposed_stress` takes it.
    a : float
        Radius of the loaded disc [m], a > 0.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    n : int
        Grid points along x, >= 2.

    Returns
    -------
    PlaneField
    """
    if not isinstance(n, (int, np.integer)) or n < 2:  # True, False < 2 too
        raise ValueError(f"n = {n!r} is out of range; valid: an integer >= 2")
    a = float(positive("a", a))
    x = np.linspace(0.0, 2.0 * a, n)
    z = np.linspace(0.0, 2.0 * a, n)[1:]
    X, Z = np.meshgrid(x, z)
    sig, err = superposed_stress(X, 0.0 * X, Z, pressure, a, nu)
    rel = float(np.max(np.abs(err))) / float(np.max(np.abs(sig)))
    return PlaneField(x, z, np.asarray(von_mises(sig)), np.asarray(max_shear(sig)),
                      np.abs(sig[..., 0, 2]), rel)


def superposed_maximum(pressure, a, nu, criterion: str, plane: PlaneField, *,
                       xatol: float = 1e-5):
    """The largest ``"von_mises"``, ``"max_shear"`` or ``"orthogonal_shear"`` (|tau_xz| in the
    x-z plane, = |tau_rz|) stress [Pa] under an axisymmetric pressure
    p(r) on r < a, refined from the largest point of ``plane`` (:func:`superposed_plane`) by
    Nelder-Mead on the superposed field, with a bound on its relative error.

    The grid alone misses a maximum between its points by up to half a step squared times the
    field's curvature (a 13-point grid: 1e-2 of the value); the refinement stops when its
    simplex is smaller than ``xatol`` a. The bound is the sum of

    - the quadrature's estimate at the refined point (:func:`superposed_stress`, relative to the
      largest |component| there);
    - the miss of the refined point: 1/2 (|f_xx| + 2 |f_xz| + |f_zz|) (2 s)^2 over the value,
      s the final simplex's size, the curvature from the grid's second differences around its
      largest point (the field is even in x), times 4 because a grid of spacing a/6 averages a
      curvature that changes on the scale a;
    - where the maximum runs into the route's lowest depth z = 1e-3 a (a maximum on the
      surface, which this route does not reach): the change of the value over that last
      1e-3 a, a linear extrapolation to z = 0.

    Parameters
    ----------
    pressure : callable
        p(r) [Pa], as :func:`superposed_stress` takes it; bounded (an unbounded pressure has an
        infinite largest stress).
    a : float
        Radius of the loaded disc [m], a > 0.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    criterion : {"von_mises", "max_shear", "orthogonal_shear"}
    plane : PlaneField
        The field on the grid, from :func:`superposed_plane` with the same pressure, a and nu.
    xatol : float
        Size of the final simplex, in units of a.

    Returns
    -------
    (float, float, float, float)
        value [Pa], x [m], z [m] of the maximum, and the bound on the value's relative error.
    """
    from scipy.optimize import minimize

    funcs = {"von_mises": von_mises, "max_shear": max_shear,
             "orthogonal_shear": lambda sig: np.abs(sig[..., 0, 2])}
    if criterion not in funcs:
        raise ValueError(f"criterion = {criterion!r}; valid: 'von_mises', 'max_shear', "
                         "'orthogonal_shear'")
    a = float(positive("a", a))
    f = funcs[criterion]
    field = np.asarray(getattr(plane, criterion), float)
    i, j = np.unravel_index(int(np.argmax(field)), field.shape)
    top = float(field[i, j])
    hx, hz = float(plane.x[1] - plane.x[0]) / a, float(plane.z[1] - plane.z[0]) / a
    zlo = 1e-3

    def at(u, w, fine=False):
        x, z = abs(u) * a, max(abs(w), zlo) * a
        kw = {} if fine else {"n_psi": 32, "level": 4}
        sig, err = superposed_stress(x, 0.0, z, pressure, a, nu, **kw)
        return float(f(sig)), float(np.max(err)) / float(np.max(np.abs(sig)))

    u0, w0 = float(plane.x[j]) / a, float(plane.z[i]) / a
    simplex = [[u0, w0], [u0 + hx / 2, w0], [u0, w0 + hz / 2]]
    res = minimize(lambda p: -at(p[0], p[1])[0] / top, [u0, w0], method="Nelder-Mead",
                   options={"initial_simplex": simplex, "xatol": xatol, "fatol": 1e-13,
                            "maxiter": 400})
    best = res.final_simplex[0]
    s = max(xatol, float(np.max(np.abs(best[1:] - best[0]))))
    u, w = abs(float(best[0][0])), max(abs(float(best[0][1])), zlo)
    value, quad = at(u, w, fine=True)
    # the curvature [Pa / a^2] from the grid's second differences around its largest point;
    # columns mirror at x = 0 (the field is even in x), rows shift inwards at the grid's ends
    col = np.concatenate([field[:, :0:-1], field], axis=1)
    jj = j + field.shape[1] - 1
    ii = min(max(i, 1), field.shape[0] - 2)
    jj = min(jj, col.shape[1] - 2)
    fxx = abs(col[ii, jj + 1] - 2 * col[ii, jj] + col[ii, jj - 1]) / hx**2
    fzz = abs(col[ii + 1, jj] - 2 * col[ii, jj] + col[ii - 1, jj]) / hz**2
    fxz = abs(col[ii + 1, jj + 1] - col[ii + 1, jj - 1] - col[ii - 1, jj + 1]
              + col[ii - 1, jj - 1]) / (4 * hx * hz)
    miss = 4 * 0.5 * (fxx + 2 * fxz + fzz) * (2 * s) ** 2 / value
    if w <= 2 * zlo:  # the maximum at the route's lowest depth: extrapolate to the surface
        miss += abs(value - at(u, 2 * zlo, fine=True)[0]) / value
    return value, u * a, w * a, quad + miss
