"""Stresses under an elliptical Hertz contact, and their maxima.

The pressure is p0 (1 - x^2/a^2 - y^2/b^2)^(1/2) (5.31) on the ellipse with semi-axes a >= b
(a along x, b along y); z > 0 into the body; stresses in Pa, tension positive. The formulas
are generated from :mod:`hertzmdr.derive.ellipse_stress` (Boussinesq superposed in Love's
form over the pressure): on the axis they are closed forms in Carlson's R_D; off the axis
sigma_zz, tau_xz, tau_yz are algebraic in the ellipsoidal coordinate lam, and sigma_xx,
sigma_yy, tau_xy need three 1-D integrals J_xx, J_yy, J_xy (of the logarithmic potential
H1), which this module computes by double-exponential quadrature with an error estimate.

This module validates, solves the cubic for lam (Newton's method from above, monotone: the
cubic has only real roots, all <= lam), integrates, and finds the maxima by root finding on
generated derivatives (the axis) or by local search (the orthogonal shear).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, between, nonnegative, poisson, positive, result

__all__ = ["EllipseStresses", "stresses", "von_mises", "principal_shear", "axis_stresses",
           "max_shear", "max_von_mises", "max_orthogonal_shear", "DEFAULT_RTOL",
           "MAX_DISTANCE"]

#: default relative accuracy (to p0) of the quadrature of the field integrals
DEFAULT_RTOL = 1e-10

#: the double-exponential rule: u = s exp((pi/2) sinh t), t in [T_LO, T_HI]; below T_LO the
#: integrand (finite at u = 0) contributes < s exp(-43) of it, above T_HI the u^-3 tail
#: (s/u)^2/2 < 1e-16 of the integral
_T_LO, _T_HI = -4.2, 3.6
_H0 = 0.5  # the coarsest step; each level halves it
_MAX_LEVEL = 6  # h = 1/128: far below the rounding level for every point tested
#: the roundings of the components (lam, e, the R_D's, the sums), relative to p0: the
#: worst measured against the polar-coordinate superposition of tests/ellipse_reference.py
#: is 7e-16 p0 (b/a = 1 ... 0.001, near the surface, the edge and far below); 16 eps
#: bounds it with a margin
_ROUNDING = 16 * np.finfo(float).eps


class EllipseStresses(NamedTuple):
    """The six stress components [Pa] at the field points and the estimated error [Pa]."""

    sigma_xx: np.ndarray
    sigma_yy: np.ndarray
    sigma_zz: np.ndarray
    tau_xy: np.ndarray
    tau_xz: np.ndarray
    tau_yz: np.ndarray
    error: np.ndarray


def _semi_axes(a, b):
    a = positive("a", a)
    b = positive("b", b)
    bad = b > a
    if np.any(bad):
        i = np.unravel_index(np.argmax(np.broadcast_to(bad, np.broadcast(a, b).shape)),
                             np.broadcast(a, b).shape)
        aa, bb = np.broadcast_arrays(a, b)
        raise ValueError(f"b = {float(bb[i]):g} m > a = {float(aa[i]):g} m: the semi-axis b "
                         "(along y) must not exceed a (along x); swap x and y")
    return a, b


def _roots(a, b, x, y):
    """w1, a^2 + w1, b^2 + w1, w1 - w2 of the surface quadratic (the branches of the printed
    Piecewise are both evaluated: the one not taken may divide by zero)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return (gen.ellipse_stress_w1(a, b, x, y), gen.ellipse_stress_w1_a(a, b, x, y),
                gen.ellipse_stress_w1_b(a, b, x, y), gen.ellipse_stress_d(a, b, x, y))


def _newton_down(f, fp, start):
    """The largest root of a cubic with only real roots, by Newton's method from above it
    (monotone decreasing iterates); stops when a step no longer decreases the iterate."""
    t = start.copy()
    active = np.ones(t.shape, bool)
    for _ in range(200):
        if not active.any():
            break
        ta = t[active]
        val, slope = f(ta, active), fp(ta, active)
        with np.errstate(divide="ignore", invalid="ignore"):
            new = ta - val / slope
        ok = (val > 0) & (slope > 0) & (new < ta)
        new = np.where(ok, np.maximum(new, 0.0), ta)
        t[active] = new
        idx = np.flatnonzero(active)
        active[idx[~ok | (ta - new <= 4e-16 * ta)]] = False
    return t


def _lam(a, b, x, y, z, w1, w1a, w1b, d):
    """lam and q = lam - w1, each without cancellation: solved for lam inside the surface
    ellipse's confocal family where w1 < 0, for q where w1 >= 0."""
    inside = w1 < 0
    rho2 = x * x + y * y + z * z  # lam <= rho^2: g(rho^2) <= 0
    lam = np.zeros(x.shape)
    q = np.zeros(x.shape)
    if inside.any():
        A, B, Z, W1, D = (v[inside] for v in (a, b, z, w1, d))
        root = _newton_down(
            lambda t, m: gen.ellipse_stress_cubic_lam(A[m], B[m], Z[m], W1[m], D[m], t),
            lambda t, m: gen.ellipse_stress_cubic_lam_slope(A[m], B[m], Z[m], W1[m], D[m], t),
            rho2[inside])
        lam[inside] = root
        q[inside] = root - W1
    out = ~inside
    if out.any():
        Z, W1, WA, WB, D = (v[out] for v in (z, w1, w1a, w1b, d))
        root = _newton_down(
            lambda t, m: gen.ellipse_stress_cubic_q(Z[m], W1[m], WA[m], WB[m], D[m], t),
            lambda t, m: gen.ellipse_stress_cubic_q_slope(Z[m], W1[m], WA[m], WB[m], D[m], t),
            np.maximum(rho2[out] - W1, 0.0) + 1e-300)
        q[out] = root
        lam[out] = W1 + root
    return lam, q


def _de_nodes(level):
    """Nodes t and weights of the level (the odd-indexed nodes only above level 0)."""
    h = _H0 / 2**level
    n_lo, n_hi = int(np.floor(-_T_LO / h)), int(np.ceil(_T_HI / h))
    k = np.arange(-n_lo, n_hi + 1)
    if level:
        k = k[k % 2 == 1]
    t = k * h
    return t, h


def _j_integrals(x, y, w1a, w1b, d, v0, scale, rtol):
    """J_xx, J_yy, J_xy by the double-exponential rule on v = v0 + u, and an error estimate
    (the change from the previous level, an over-estimate: the error falls like exp(-c/h))."""
    sums = np.zeros((3, *x.shape))
    prev = None
    err = np.full(x.shape, np.inf)
    for level in range(_MAX_LEVEL + 1):
        t, h = _de_nodes(level)
        s = np.sinh(t)
        u = scale[..., None] * np.exp(0.5 * np.pi * s)
        wgt = u * (0.5 * np.pi) * np.cosh(t)
        vv = v0[..., None] + u
        args = [v[..., None] for v in (x, y, w1a, w1b, d)]
        fx = gen.ellipse_stress_jxx_integrand(args[0], args[2], args[3], args[4], vv)
        fy = gen.ellipse_stress_jyy_integrand(args[1], args[2], args[3], args[4], vv)
        fxy = gen.ellipse_stress_jxy_integrand(args[0], args[1], args[2], args[3], args[4], vv)
        for i, f in enumerate((fx, fy, fxy)):
            sums[i] += np.sum(f * wgt, axis=-1)
        est = sums * h  # the trapezoid sum of all levels so far, step h
        if prev is not None:
            err = np.max(np.abs(est - prev), axis=0)
            ref = np.max(np.abs(est), axis=0) + 1.0 / scale**2
            if np.all(err <= rtol * ref):
                break
        prev = est
    return est[0], est[1], est[2], err


def _geometry(X, Y, Z, Bt):
    """Dimensionless (a = 1) coordinates of the field points: lam, q, e and the roots."""
    one = np.ones(X.shape)
    w1, w1a, w1b, d = _roots(one, Bt, X, Y)
    lam, q = _lam(one, Bt, X, Y, Z, w1, w1a, w1b, d)
    e2 = gen.ellipse_stress_e_sq(one, Bt, lam, q, d)
    return {"one": one, "Bt": Bt, "X": X, "Y": Y, "lam": lam, "q": q, "w1a": w1a, "w1b": w1b,
            "d": d, "e": np.sqrt(np.clip(e2, 0.0, 1.0))}


def _algebraic(g):
    """sigma_zz, tau_xz, tau_yz / p0 (no integral needed)."""
    args = (g["one"], g["Bt"], g["one"], g["X"], g["Y"], g["lam"], g["e"])
    return (gen.ellipse_stress_sigma_zz(*args), gen.ellipse_stress_tau_xz(*args),
            gen.ellipse_stress_tau_yz(*args))


#: :func:`stresses` accepts max(|x|, |y|, z) up to this many semi-axes a (the stresses there
#: are below 1e-40 p0; from about 1e26 a the ellipsoidal coordinate's products overflow, and
#: from 1e60 a the result was a silent NaN)
MAX_DISTANCE = 1e20


def _inputs(x, y, z, a, b, p0, nu):
    a, b = _semi_axes(a, b)
    arrays = np.broadcast_arrays(as_float("x", x), as_float("y", y), nonnegative("z", z), a, b,
                                 nonnegative("p0", p0), poisson("nu", nu))
    x, y, z, a, b, p0, nu = [np.array(v, dtype=float) for v in arrays]
    far = np.maximum(np.maximum(np.abs(x), np.abs(y)), z) > MAX_DISTANCE * a
    if far.any():
        i = np.unravel_index(np.argmax(far), far.shape) if far.ndim else ()
        raise ValueError(f"x = {float(x[i])!r}, y = {float(y[i])!r}, z = {float(z[i])!r}, "
                         f"a = {float(a[i])!r}: max(|x|, |y|, z) is out of range; valid: "
                         f"max(|x|, |y|, z) <= {MAX_DISTANCE:g} a (the stresses there are "
                         "below 1e-40 p0)")
    return [x, y, z, a, b, p0, nu]


def stresses(x, y, z, a, b, p0, nu, rtol=DEFAULT_RTOL):
    """Stresses [Pa] at (x, y, z) under the elliptical Hertz pressure (5.31).

    Boussinesq superposed over the pressure in Love's form (derived in
    :mod:`hertzmdr.derive.ellipse_stress`): sigma_zz, tau_xz, tau_yz algebraic in the
    ellipsoidal coordinate lam, sigma_xx, sigma_yy with Carlson's R_D, and sigma_xx, sigma_yy,
    tau_xy with the three integrals of the logarithmic potential, computed by the
    double-exponential rule to ``rtol`` (relative to p0).

    Parameters
    ----------
    x, y : float or array_like
        Coordinates on the surface [m] from the centre of the contact, x along a, y along b.
    z : float or array_like
        Depth [m], z >= 0; max(|x|, |y|, z) <= ``MAX_DISTANCE`` a (1e20 a, where the
        stresses are below 1e-40 p0; farther points are refused, naming them).
    a, b : float or array_like
        Semi-axes of the contact ellipse [m], a >= b > 0.
    p0 : float or array_like
        Maximum pressure [Pa], p0 >= 0.
    nu : float or array_like
        Poisson's ratio, -1 < nu <= 0.5.
    rtol : float
        Relative accuracy (to p0) asked of the quadrature, in [1e-14, 1e-2].

    Returns
    -------
    EllipseStresses
        sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_xz, tau_yz [Pa] (tension positive) and
        ``error`` [Pa], the estimated bound of the error of the components: the quadrature's
        estimate plus 16 eps p0 for the roundings.
    """
    rtol = float(between("rtol", rtol, 1e-14, 1e-2, lo_open=False, hi_open=False))
    x, y, z, a, b, p0, nu = _inputs(x, y, z, a, b, p0, nu)
    g = _geometry(x / a, y / a, z / a, b / a)
    one, Bt, X, Y, lam, e = g["one"], g["Bt"], g["X"], g["Y"], g["lam"], g["e"]
    Ix = gen.ellipse_stress_I_x(one, Bt, lam)
    Iy = gen.ellipse_stress_I_y(one, Bt, lam)
    Jxx, Jyy, Jxy, jerr = _j_integrals(X, Y, g["w1a"], g["w1b"], g["d"], np.sqrt(g["q"]),
                                       np.sqrt(Bt * Bt + lam), rtol)
    args = (one, Bt, nu, one, X, Y, lam, e)
    szz, txz, tyz = _algebraic(g)
    out = [gen.ellipse_stress_sigma_xx(*args, Ix, Iy, Jxx),
           gen.ellipse_stress_sigma_yy(*args, Ix, Iy, Jyy),
           szz, gen.ellipse_stress_tau_xy(*args, Jxy), txz, tyz]
    # the J's enter with the factor a b p0 (1 - 2 nu)/2 (dimensionless: Bt |1 - 2 nu|/2);
    # the roundings of the rest are below _ROUNDING p0
    err = (jerr * Bt * np.abs(1 - 2 * nu) / 2 + _ROUNDING) * p0
    return EllipseStresses(*(result(v * p0) for v in out), result(err))


def von_mises(x, y, z, a, b, p0, nu, rtol=DEFAULT_RTOL):
    """von Mises stress (5.50) [Pa] at (x, y, z) and its estimated error [Pa].

    Parameters
    ----------
    x, y, z, a, b, p0, nu, rtol
        As in :func:`stresses`.

    Returns
    -------
    (ndarray, ndarray)
        sigma_vM [Pa] and the error bound [Pa] (that of the components times 2: sigma_vM is
        1-Lipschitz in each difference of normal stresses).
    """
    s = stresses(x, y, z, a, b, p0, nu, rtol)
    vm = gen.stress_von_mises(s.sigma_xx, s.sigma_yy, s.sigma_zz, s.tau_xy, s.tau_yz, s.tau_xz)
    return result(vm), result(2 * s.error)


def principal_shear(x, y, z, a, b, p0, nu, rtol=DEFAULT_RTOL):
    """The largest principal shear tau_1 = (sigma_1 - sigma_3)/2 [Pa] at (x, y, z).

    Parameters
    ----------
    x, y, z, a, b, p0, nu, rtol
        As in :func:`stresses`.

    Returns
    -------
    (ndarray, ndarray)
        tau_1 [Pa] and the error bound [Pa] of the components.
    """
    s = stresses(x, y, z, a, b, p0, nu, rtol)
    t = np.stack([np.stack([s.sigma_xx, s.tau_xy, s.tau_xz], -1),
                  np.stack([s.tau_xy, s.sigma_yy, s.tau_yz], -1),
                  np.stack([s.tau_xz, s.tau_yz, s.sigma_zz], -1)], -2)
    ev = np.linalg.eigvalsh(t)
    return result((ev[..., -1] - ev[..., 0]) / 2), result(s.error)


def axis_stresses(z, a, b, p0, nu):
    """sigma_xx, sigma_yy, sigma_zz [Pa] on the axis x = y = 0 of an elliptical contact.

    Closed forms in Carlson's R_D (incomplete elliptic integrals), derived in
    :mod:`hertzmdr.derive.ellipse_stress`; (5.48), (5.49) at b = a, the line contact's axis
    stresses as b/a -> 0.

    Parameters
    ----------
    z : float or array_like
        Depth [m], z >= 0.
    a, b, p0, nu
        As in :func:`stresses`.

    Returns
    -------
    (ndarray, ndarray, ndarray)
        sigma_xx, sigma_yy, sigma_zz [Pa], tension positive (no shear on the axis).
    """
    _, _, z, a, b, p0, nu = _inputs(0.0, 0.0, z, a, b, p0, nu)
    Z, Bt = z / a, b / a
    one = np.ones(Z.shape)
    sxx = gen.ellipse_stress_axis_sigma_xx(one, Bt, nu, one, Z)
    syy = gen.ellipse_stress_axis_sigma_yy(one, Bt, nu, one, Z)
    szz = gen.ellipse_stress_axis_sigma_zz(one, Bt, one, Z)
    return result(sxx * p0), result(syy * p0), result(szz * p0)


def _brent(f, lo, hi):
    from scipy.optimize import brentq

    return brentq(f, lo, hi, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=200)


def _axis_peak(name, t, nu):
    """(value/p0, z/b) of the largest interior maximum of an axis quantity, a = 1, b = t."""
    value = getattr(gen, f"ellipse_stress_axis_{name}")
    slope = getattr(gen, f"ellipse_stress_axis_{name}_slope")
    grid = t * np.geomspace(1e-3, 20.0, 80)
    s = slope(1.0, t, nu, 1.0, grid)
    best = (float(value(1.0, t, nu, 1.0, 0.0)), 0.0)
    for i in np.flatnonzero((s[:-1] > 0) & (s[1:] <= 0)):
        zr = _brent(lambda zz: float(slope(1.0, t, nu, 1.0, zz)), grid[i], grid[i + 1])
        v = float(value(1.0, t, nu, 1.0, zr))
        if v > best[0]:
            best = (v, zr / t)
    return best


def _ratio(b_over_a):
    return float(between("b_over_a", b_over_a, 0.0, 1.0, lo_open=True, hi_open=False))


def max_shear(b_over_a, nu):
    """The largest principal shear tau_1 under an elliptical contact and its depth.

    On the axis the principal stresses are sigma_xx, sigma_yy, sigma_zz; tau_1 is the larger
    of (sigma_xx - sigma_zz)/2 and (sigma_yy - sigma_zz)/2, each maximized at the root of its
    generated derivative (Brent's method, bracketed on a grid of depths). The circle: 0.31 p0
    at 0.48 a (nu = 0.3); the line contact (b/a -> 0): 0.300 p0 at 0.786 b.

    Parameters
    ----------
    b_over_a : float
        Axis ratio b/a in (0, 1].
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.

    Returns
    -------
    (float, float, str)
        tau_1,max/p0, its depth z/b on the axis, and the plane of the shear ("x" for
        (sigma_xx - sigma_zz)/2, "y" for (sigma_yy - sigma_zz)/2).
    """
    t, nu = _ratio(b_over_a), float(poisson("nu", nu))
    vx, zx = _axis_peak("shear_x", t, nu)
    vy, zy = _axis_peak("shear_y", t, nu)
    return (vy, zy, "y") if vy >= vx else (vx, zx, "x")


def max_von_mises(b_over_a, nu):
    """The largest von Mises stress on the axis of an elliptical contact and its depth.

    The root of the generated d(sigma_vM)/dz (Brent's method, bracketed on a grid of
    depths), or the surface centre if that is higher (small or negative nu);
    ``tests/test_ellipse_stress.py`` checks on a box around it, off the axis, that no point
    nearby is higher (b/a = 1, 0.5, 0.1; nu = 0.3, 0.5; for small nu the maximum may leave
    the axis, as it does for the circle).

    Parameters
    ----------
    b_over_a, nu
        As in :func:`max_shear`.

    Returns
    -------
    (float, float)
        sigma_vM,max/p0 and its depth z/b on the axis.
    """
    t, nu = _ratio(b_over_a), float(poisson("nu", nu))
    return _axis_peak("von_mises", t, nu)


def max_orthogonal_shear(b_over_a):
    """The largest orthogonal shear stresses |tau_yz| (in the plane x = 0) and |tau_xz| (in
    the plane y = 0) under an elliptical contact, and where they are.

    tau_yz and tau_xz are algebraic in lam (independent of nu); their maxima by Nelder-Mead
    from the best point of a grid. The line contact (b/a -> 0): |tau_yz| = p0/4 at
    y = (3^(1/2)/2) b, z = b/2.

    Parameters
    ----------
    b_over_a : float
        Axis ratio b/a in (0, 1].

    Returns
    -------
    dict
        ``{"yz": (tau/p0, y/b, z/b), "xz": (tau/p0, x/b, z/b)}``.
    """
    from scipy.optimize import minimize

    t = _ratio(b_over_a)
    out = {}
    for comp, half in {"yz": t, "xz": 1.0}.items():
        def neg(p, comp=comp):
            u, zz = float(p[0]) * t, abs(float(p[1])) * t
            xy = (0.0, u) if comp == "yz" else (u, 0.0)
            g = _geometry(np.array([xy[0]]), np.array([xy[1]]), np.array([zz]),
                          np.array([t]))
            return -abs(float(_algebraic(g)[1 if comp == "xz" else 2][0]))

        grid = [(u, zz) for u in np.linspace(0.2, 1.4, 7) * half / t
                for zz in (0.25, 0.5, 0.75)]
        start = min(grid, key=neg)
        sol = minimize(neg, start, method="Nelder-Mead",
                       options={"xatol": 1e-11, "fatol": 1e-15, "maxiter": 2000})
        out[comp] = (-float(sol.fun), abs(float(sol.x[0])), abs(float(sol.x[1])))
    return out
