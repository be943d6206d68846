"""Stresses in the half-plane under a line contact (plane strain), and their maxima.

The pressure is the 2-D Hertz pressure p0 (1 - x^2/b^2)^(1/2) (5.36) on the strip |x| < b
(b the half-width, (5.35)); x along the surface across the strip, z > 0 into the body, y
along the cylinders' axes. Stresses in Pa, tension positive; sigma_yy = nu (sigma_xx +
sigma_zz) (plane strain). The formulas are generated from :mod:`hertzmdr.derive.line_stress`
(Flamant's line load superposed over the pressure, printed in cancellation-free forms); this
module validates, picks the region of the printed form, uses the symmetry in x and finds the
maxima by root finding on generated derivatives.
"""

from __future__ import annotations

from functools import cache, lru_cache

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, nonnegative, poisson, positive, result

__all__ = ["stresses", "principal_shear", "von_mises", "axis_stresses", "max_shear",
           "max_shear_3d", "max_von_mises", "max_orthogonal_shear"]

#: below this depth (in units of b) z^2 underflows in the printed forms; the stresses there
#: are the surface values to within O(z/b) * p0 < 1e-140 p0
_Z_SURFACE = 1e-140


#: the largest distance from the strip, in half-widths, the field is evaluated at: the forms
#: raise x/b and z/b to powers up to the fourth and overflow above about 1e60; the
#: far field is tested against the superposition to 1e6, the limit by tests/test_line_stress.py
MAX_DISTANCE = 1e50


def _inputs(x, z, b, p0, nu):
    x = as_float("x", x)
    x, z, b, p0, nu = np.broadcast_arrays(x, nonnegative("z", z), positive("b", b),
                                          nonnegative("p0", p0), poisson("nu", nu))
    far = np.maximum(np.abs(x), z) > MAX_DISTANCE * b
    if far.any():
        i = np.unravel_index(np.argmax(far), far.shape)
        raise ValueError(f"(x, z) = ({float(x[i]):g}, {float(z[i]):g}) m with b = "
                         f"{float(b[i]):g} m: the line-contact field is evaluated within "
                         f"{MAX_DISTANCE:g} half-widths of the strip")
    return x, z, b, p0, nu


def _in_plane(x, z, b, p0, tau_1=False, tau_xz=True):
    """sigma_xx, sigma_zz, tau_xz [Pa] (broadcast float arrays in), and with ``tau_1`` the
    principal shear in the x-z plane from its own cancellation-free form; without ``tau_xz``
    (not needed for the von Mises stress) it is returned as None."""
    X, Z = np.abs(x) / b, z / b  # dimensionless; the field is even in x, tau_xz odd
    Z = np.where(Z < _Z_SURFACE, 0.0, Z)
    comps = ("sigma_xx", "sigma_zz") + (("tau_xz",) if tau_xz else ()) \
        + (("tau_1",) if tau_1 else ())
    out = [np.zeros(X.shape) for _ in comps]
    free = (Z == 0) & (X >= 1)  # the surface outside the strip is traction-free
    core = (X * X + Z * Z <= 1) & ~free
    side = ((1 - X) * (1 + X) + Z * Z < 0) & ~free
    deep = ~(core | side | free)
    for mask, region in ((core, "core"), (deep, "deep"), (side, "side")):
        if not mask.any():
            continue
        xs, zs = X[mask], Z[mask]
        for k, comp in enumerate(comps):
            out[k][mask] = getattr(gen, f"line_stress_{comp}_{region}")(1.0, 1.0, xs, zs)
    sxx, szz, *rest = (v * p0 for v in out)
    txz = np.where(x < 0, -rest[0], rest[0]) if tau_xz else None
    # on the free surface outside the strip every stress is 0, tau_1 too (zeros above)
    return (sxx, szz, txz, *rest[1 if tau_xz else 0:])


def stresses(x, z, b, p0, nu):
    """Stresses [Pa] at (x, z) under the line-contact pressure p0 (1 - x^2/b^2)^(1/2) (5.36).

    Flamant's line load superposed over the pressure (derived in
    :mod:`hertzmdr.derive.line_stress`), in forms that keep full relative accuracy near the
    surface, at the contact edge and far away (tested to z/b = 1e6); beyond
    :data:`MAX_DISTANCE` half-widths from the strip a ValueError.

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+60], z in {0} U [1e-300,
    1e+60], b in [1e-12, 1e+06], p0 in [0.001, 1e+15], nu in (-1, 0.5], max(|x|, z) <= 1e50
    b (a ValueError beyond) (SI units; searched by tests/domain_search.py).

    Parameters
    ----------
    x : float or array_like
        Coordinate across the strip [m], from its centre line.
    z : float or array_like
        Depth [m], z >= 0.
    b : float or array_like
        Half-width of the contact strip [m], b > 0.
    p0 : float or array_like
        Maximum pressure [Pa], p0 >= 0.
    nu : float or array_like
        Poisson's ratio, -1 < nu <= 0.5.

    Returns
    -------
    sigma_xx, sigma_zz, tau_xz, sigma_yy : ndarray
        [Pa], tension positive; sigma_yy = nu (sigma_xx + sigma_zz) (plane strain).
    """
    x, z, b, p0, nu = _inputs(x, z, b, p0, nu)
    sxx, szz, txz = _in_plane(x, z, b, p0)
    syy = gen.line_stress_sigma_yy(nu, sxx, szz)  # plane strain
    return result(sxx), result(szz), result(txz), result(syy)


def principal_shear(x, z, b, p0, nu):
    """Principal shear stresses [Pa] at (x, z) under the line-contact pressure.

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+60], z in {0} U [1e-300,
    1e+60], b in [1e-12, 1e+06], p0 in [0.001, 1e+15], nu in (-1, 0.5], max(|x|, z) <= 1e50
    b (a ValueError beyond) (SI units; searched by tests/domain_search.py).

    Parameters
    ----------
    x, z, b, p0, nu
        As in :func:`stresses`.

    Returns
    -------
    tau_1 : ndarray
        (sigma_1 - sigma_3)/2 [Pa] of the principal stresses in the x-z plane.
    tau_max : ndarray
        The 3-D maximum shear (Tresca/2) [Pa], sigma_yy included.
    """
    x, z, b, p0, nu = _inputs(x, z, b, p0, nu)
    sxx, szz, txz, tau1 = _in_plane(x, z, b, p0, tau_1=True)
    syy = gen.line_stress_sigma_yy(nu, sxx, szz)
    hi = gen.line_stress_principal_max(sxx, szz, txz)
    lo = gen.line_stress_principal_min(sxx, szz, txz)
    # (max(hi, syy) - min(lo, syy))/2, with the in-plane part from tau_1's own form (hi - lo
    # loses digits where tau_1 << p0: just below the centre)
    tmax = np.maximum(tau1, 0.5 * np.maximum(hi - syy, syy - lo))
    return result(tau1), result(tmax)


def von_mises(x, z, b, p0, nu):
    """von Mises stress (5.50) [Pa] at (x, z) under the line-contact pressure (plane strain).

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+60], z in {0} U [1e-300,
    1e+60], b in [1e-12, 1e+06], p0 in [0.001, 1e+15], nu in (-1, 0.5], max(|x|, z) <= 1e50
    b (a ValueError beyond) (SI units; searched by tests/domain_search.py).

    Parameters
    ----------
    x, z, b, p0, nu
        As in :func:`stresses`.
    """
    x, z, b, p0, nu = _inputs(x, z, b, p0, nu)
    sxx, szz, _, tau1 = _in_plane(x, z, b, p0, tau_1=True, tau_xz=False)
    # (5.50) with sigma_yy = nu (sigma_xx + sigma_zz), as ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2),
    # c the mean in-plane stress, tau_1 from its own cancellation-free form
    return result(gen.line_stress_von_mises_c_tau(nu, (sxx + szz) / 2, tau1))


def axis_stresses(z, b, p0, nu):
    """sigma_xx, sigma_zz, sigma_yy [Pa] on the symmetry axis x = 0 of a line contact.

    sigma_zz = -p0 b/(b^2 + z^2)^(1/2), sigma_xx = -p0 b^3/(s (s + z)^2) with
    s = (b^2 + z^2)^(1/2) (the cancellation-free form of
    -p0 [(b^2 + 2 z^2)/(b s) - 2 z/b]), sigma_yy = nu (sigma_xx + sigma_zz); for
    z <= :data:`MAX_DISTANCE` b (a ValueError beyond).

    Guaranteed finite and accurate for z in {0} U [1e-300, 1e+60], b in [1e-12, 1e+06], p0
    in [0.001, 1e+15], nu in (-1, 0.5], z <= 1e50 b (a ValueError beyond) (SI units;
    searched by tests/domain_search.py).

    Parameters
    ----------
    z : float or array_like
        Depth [m], z >= 0.
    b, p0, nu
        As in :func:`stresses`.
    """
    _, z, b, p0, nu = _inputs(0.0, z, b, p0, nu)  # within MAX_DISTANCE half-widths
    sxx = gen.line_stress_axis_sigma_xx(b, p0, z)
    szz = gen.line_stress_axis_sigma_zz(b, p0, z)
    return result(sxx), result(szz), result(gen.line_stress_sigma_yy(nu, sxx, szz))


def _brent(f, lo, hi):
    from scipy.optimize import brentq

    return brentq(f, lo, hi, xtol=1e-16, rtol=4 * np.finfo(float).eps, maxiter=200)


def max_shear():
    """The largest principal shear tau_1 in the x-z plane under a line contact.

    It lies on the axis (tau_1 = p0 b z/(s (s + z)) there, s = (b^2 + z^2)^(1/2)); the root
    of its generated derivative by Brent's method. Exactly z/b = phi^(-1/2) = 0.78615...,
    tau_1/p0 = phi^(-5/2) = 0.30028... (phi the golden ratio); independent of nu.

    Returns
    -------
    (float, float)
        tau_1,max/p0 and its depth z/b (x = 0).
    """
    s = _brent(lambda t: gen.line_stress_axis_max_shear_slope(1.0, 1.0, t), 0.1, 3.0)
    return float(gen.line_stress_axis_max_shear(1.0, 1.0, s)), s


def max_shear_3d(nu):
    """The largest shear stress (sigma_1 - sigma_3)/2 of the 3-D stress tensor under a line
    contact (sigma_yy = nu (sigma_xx + sigma_zz), plane strain) and its depth.

    It lies on the axis, where the principal stresses are sigma_xx, sigma_yy, sigma_zz:
    the largest of the three half-differences' maxima. (sigma_xx - sigma_zz)/2 peaks at
    :func:`max_shear` (phi^(-5/2) p0 at z = phi^(-1/2) b); |sigma_yy - sigma_zz|/2 and
    |sigma_xx - sigma_yy|/2 are located on a grid of 400 depths 0 <= z <= 4 b and refined by
    bounded Brent (a flat maximum: the value to ~eps, the depth to ~1e-8 b). For
    nu >= 0.24227 it is the in-plane maximum (0.30028 p0 at 0.78615 b); for smaller nu the
    sigma_yy pair is larger (0.40850 p0 at 0.17337 b for nu = 0.1, p0/2 at the surface for
    nu = 0). ``tests/test_line_stress.py``
    checks on a grid that no point off the axis is higher.

    Guaranteed finite and accurate for nu in (-1, 0.5] (SI units; searched by
    tests/domain_search.py).

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.

    Returns
    -------
    (float, float)
        tau_max/p0 and its depth z/b (x = 0).
    """
    return _max_shear_3d(float(poisson("nu", nu)))


@lru_cache(maxsize=256)
def _max_shear_3d(nu: float) -> tuple[float, float]:
    """:func:`max_shear_3d` for a validated nu, computed once per nu (~2 ms)."""
    from scipy.optimize import minimize_scalar

    best = max_shear()

    def pairs(t):
        sxx, szz, syy = axis_stresses(t, 1.0, 1.0, nu)
        return np.abs(syy - szz) / 2, np.abs(sxx - syy) / 2

    grid = np.linspace(0.0, 4.0, 401)
    for k, column in enumerate(pairs(grid)):
        i = int(np.argmax(column))
        t, v = float(grid[i]), float(column[i])
        if 0 < i < grid.size - 1:
            res = minimize_scalar(lambda s, k=k: -float(pairs(s)[k]),
                                  bounds=(grid[i - 1], grid[i + 1]), method="bounded",
                                  options={"xatol": 1e-12})
            if -res.fun > v:
                t, v = float(res.x), -float(res.fun)
        if v > best[0]:
            best = (v, t)
    return best


def max_von_mises(nu):
    """The largest von Mises stress under a line contact (plane strain) and where it is.

    It lies on the axis: at the surface centre (value |1 - 2 nu| p0, the maximum for small or
    negative nu) or at the interior root of the generated d(sigma_vM)/dz (Brent's method,
    bracketed on a grid of depths). ``tests/test_line_stress.py`` checks on a grid and by
    local search that no point off the axis is higher.

    Guaranteed finite and accurate for nu in (-1, 0.5] (SI units; searched by
    tests/domain_search.py).

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.

    Returns
    -------
    (float, float, float)
        sigma_vM,max/p0, x/b (= 0) and z/b at the maximum.
    """
    return _max_von_mises(float(poisson("nu", nu)))


@lru_cache(maxsize=256)
def _max_von_mises(nu: float) -> tuple[float, float, float]:
    """:func:`max_von_mises` for a validated nu, computed once per nu (~0.2 ms)."""
    best = (float(gen.line_stress_axis_von_mises(1.0, nu, 1.0, 0.0)), 0.0)
    grid = np.linspace(0.02, 4.0, 200)
    slope = gen.line_stress_axis_von_mises_slope(1.0, nu, 1.0, grid)
    for i in np.flatnonzero((slope[:-1] > 0) & (slope[1:] <= 0)):
        t = _brent(lambda s: gen.line_stress_axis_von_mises_slope(1.0, nu, 1.0, s),
                   grid[i], grid[i + 1])
        v = float(gen.line_stress_axis_von_mises(1.0, nu, 1.0, t))
        if v > best[0]:
            best = (v, t)
    return best[0], 0.0, best[1]


@cache
def max_orthogonal_shear():
    """The largest orthogonal shear |tau_xz| under a line contact and where it is.

    The root of the generated gradient (d(tau_xz)/dx, d(tau_xz)/dz) by MINPACK's hybrid
    method from (0.85 b, 0.5 b), found once (~10 ms) and kept. Exactly |tau_xz| = p0/4 at
    x = (3^(1/2)/2) b, z = b/2 (zeta = b e^(i pi/6), see :mod:`hertzmdr.derive.line_stress`);
    independent of nu.

    Returns
    -------
    (float, float, float)
        |tau_xz|max/p0 and its location x/b > 0 (it is mirrored at -x), z/b.
    """
    from scipy.optimize import root

    def grad(v):
        return [float(gen.line_stress_tau_xz_slope_x(1.0, 1.0, v[0], v[1])),
                float(gen.line_stress_tau_xz_slope_z(1.0, 1.0, v[0], v[1]))]

    sol = root(grad, [0.85, 0.5], method="hybr", options={"xtol": 1e-14})
    if not sol.success:  # pragma: no cover - the start is inside the basin of the root
        raise RuntimeError(f"max_orthogonal_shear: {sol.message}")
    xs, zs = (float(v) for v in sol.x)
    _, _, txz = _in_plane(np.array(xs), np.array(zs), 1.0, 1.0)
    return abs(float(txz)), xs, zs
