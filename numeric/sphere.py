"""Rigid spherical cap (Sneddon's sphere) on an elastic half-space, exact for deep indentation.

The indenter's profile is the sphere itself, f(r) = R - sqrt(R^2 - r^2), not Hertz's
paraboloid r^2/(2R): the contact radius a stays below R at every depth d (a -> R as d -> inf)
and the relations hold for a/R up to 1. The closed forms are generated from
:mod:`hertzmdr.derive.sphere` (the MDR, (5.52)-(5.60)); this module validates, broadcasts,
solves d = g(a) and F(d) = F for the depth parameter lam = atanh(a/R) (no closed form), and
integrates what has no elementary antiderivative: the atanh part of the pressure (5.59) and
the displacement outside the contact (5.60).

Domains: R > 0, E_star > 0; a contact radius 0 <= a < R; a depth d >= 0 (any depth; for
d > 19 R the contact radius rounds to R in float64, and :func:`pressure` and
:func:`surface_displacement` need d <= 16 R, i.e. a/R <= 1 - 2.5e-14, where the contact edge
is still 200 ulps away from R). A force F >= 0.

Relative to Hertz at the same depth (a/R small), the sphere's contact radius is smaller by
(a/R)^2/6 and its force by (a/R)^2/10 (tests/test_sphere.py::test_hertz_limit, docs/sphere.md).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._quadrature import panels
from hertzmdr.numeric._validate import as_float, nonnegative, positive, result

__all__ = ["profile", "g_profile", "depth", "contact_radius", "force", "force_from_radius",
           "depth_from_force", "pressure", "surface_displacement", "stiffness"]

#: deepest indentation d/R for the pressure and the displacement (see the module docstring)
DEEP_LIMIT = 16.0
_M = 14  # Gauss-Legendre nodes per panel: 1e-16 for a log singularity 2 half-lengths away
_LEVELS = 56  # geometric panels toward a singularity: widths down to 2^-56 of the distance


def _radius(R):
    return positive("R", R)


def _below(name, value, R, *, closed=False):
    """0 <= value < R (or <= R when ``closed``), broadcast with R; returns both arrays."""
    v, R = np.broadcast_arrays(as_float(name, value), _radius(R))
    bad = ~((v >= 0) & ((v <= R) if closed else (v < R)))
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0]) if v.ndim else ()
        where = "" if not idx else f"[{idx[0] if len(idx) == 1 else idx}]"
        op = "<=" if closed else "<"
        raise ValueError(f"{name}{where} = {v[idx].item()!r} is out of range; valid: "
                         f"0 <= {name} {op} R (R{where} = {R[idx].item()!r})")
    return v, R


def _increasing_root(fun, target, lo, hi):
    """lam with fun(lam) = target for an increasing fun, from lo <= lam (fun(lo) <= target):
    hi doubled until fun(hi) >= target, then bisection down to one ulp (vectorized)."""
    lo, hi = np.array(lo, float), np.array(hi, float)
    for _ in range(64):
        short = fun(hi) < target
        if not short.any():
            break
        lo = np.where(short, hi, lo)
        hi = np.where(short, 2 * hi, hi)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        active = (mid > lo) & (mid < hi)
        if not active.any():
            break
        below = fun(mid) < target
        lo = np.where(active & below, mid, lo)
        hi = np.where(active & ~below, mid, hi)
    # the end whose value is closer to the target
    return np.where(np.abs(fun(lo) - target) <= np.abs(fun(hi) - target), lo, hi)


def _lam_from_depth(d, R):
    """lam = atanh(a/R) with R lam tanh(lam) = d (5.55); 0 for d = 0.

    With delta = d/R, lam^2 >= lam tanh(lam) and lam >= lam tanh(lam) bound the root below by
    max(sqrt(delta), delta); tanh(lam) >= lam/(1 + lam) bounds it above by the root of
    lam^2/(1 + lam) = delta. The bracket is within a factor 2, so bisection takes ~53 steps.
    """
    delta = d / R
    lo = np.maximum(np.sqrt(delta), delta)
    hi = (delta + np.sqrt(delta * (delta + 4))) / 2
    lam = _increasing_root(lambda v: gen.sphere_lam_depth(R, v), d, lo, np.maximum(hi, lo))
    return np.where(d > 0, lam, 0.0)


def _lam_from_force(F, R, E_star):
    """lam with sphere_lam_force = F (5.57). phi = F/(E* R^2) = (1 + b^2) lam - b, b = tanh(lam),
    is at most 2 lam and at most 4 lam^3/3, so lam >= max(phi/2, (3 phi/4)^(1/3))."""
    phi = F / (E_star * R**2)
    lo = np.maximum(phi / 2, np.cbrt(0.75 * phi))
    lam = _increasing_root(lambda v: gen.sphere_lam_force(E_star, R, v), F, lo, 2 * lo)
    return np.where(F > 0, lam, 0.0)


def profile(r, R):
    """Height f(r) = R - sqrt(R^2 - r^2) [m] of the spherical cap above its apex.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], 0 <= r <= R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    """
    r, R = _below("r", r, R, closed=True)
    return result(gen.sphere_profile(R, r))


def g_profile(x, R):
    """MDR profile g(x) = x atanh(x/R) = (x/2) ln((R + x)/(R - x)) [m], (5.52).

    Parameters
    ----------
    x : float or array_like
        MDR coordinate [m], 0 <= x < R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    """
    x, R = _below("x", x, R)
    return result(gen.sphere_g(R, x))


def depth(a, R):
    """Indentation depth d = g(a) = a atanh(a/R) [m] at the contact radius a, (5.55).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], 0 <= a < R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    """
    a, R = _below("a", a, R)
    return result(gen.sphere_depth(R, a))


def contact_radius(d, R):
    """Contact radius a [m] at the depth d: the root of a atanh(a/R) = d, (5.55).

    Bisection on lam = atanh(a/R) to one ulp (a ~ sqrt(R d) for d << R;
    R - a ~ 2 R exp(-2 d/R) for d >> R, below the float64 spacing of R for d > 19 R, where
    this returns R).

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    """
    d, R = np.broadcast_arrays(nonnegative("d", d), _radius(R))
    return result(gen.sphere_lam_contact_radius(R, _lam_from_depth(d, R)))


def force_from_radius(a, R, E_star):
    """Normal force F = E* ((a^2 + R^2) atanh(a/R) - a R) [N] at the contact radius a, (5.57).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], 0 <= a < R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    E_star : float or array_like
        Effective modulus (5.8)/(5.26) [Pa], E_star > 0.
    """
    a, R = _below("a", a, R)
    return result(gen.sphere_force_from_radius(positive("E_star", E_star), R, a))


def force(d, R, E_star):
    """Normal force F [N] at the depth d, (5.57) at the contact radius of (5.55).

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    d, R, E_star = np.broadcast_arrays(nonnegative("d", d), _radius(R),
                                       positive("E_star", E_star))
    return result(gen.sphere_lam_force(E_star, R, _lam_from_depth(d, R)))


def depth_from_force(F, R, E_star):
    """Indentation depth d [m] under the force F: (5.57) inverted by bisection on atanh(a/R).

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    R, E_star
        As in :func:`force`.
    """
    F, R, E_star = np.broadcast_arrays(nonnegative("F", F), _radius(R),
                                       positive("E_star", E_star))
    return result(gen.sphere_lam_depth(R, _lam_from_force(F, R, E_star)))


def stiffness(d, R, E_star):
    """Differential stiffness dF/dd = 2 a E* [N/m] at the depth d. Parameters as :func:`force`."""
    d, R, E_star = np.broadcast_arrays(nonnegative("d", d), _radius(R),
                                       positive("E_star", E_star))
    a = gen.sphere_lam_contact_radius(R, _lam_from_depth(d, R))
    return result(gen.sphere_stiffness(E_star, a))


def _deep(d, R):
    bad = d > DEEP_LIMIT * R
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0]) if d.ndim else ()
        raise ValueError(f"d = {d[idx].item()!r} is out of range; valid: 0 <= d <= "
                         f"{DEEP_LIMIT:g} R = {DEEP_LIMIT * R[idx].item()!r} (deeper, the "
                         "contact edge is within 200 ulps of R in float64)")


def _geometric_breaks(s, n):
    """Breaks s (1 - 2^-j), j = 1..n, shape (M, n): panels that shrink toward s."""
    return s[:, None] * (1 - 0.5 ** np.arange(1, n + 1))


def _levels(dist, scale):
    """How many geometric levels resolve a singularity ``dist`` beyond an interval of length
    ``scale``: enough for the last panel to be no wider than its distance to it."""
    ratio = np.where(dist > 0, scale / np.maximum(dist, 1e-300), np.inf)
    need = np.ceil(np.log2(np.clip(ratio, 1.0, 2.0**_LEVELS))) + 2
    return int(np.clip(need.max(initial=1), 1, _LEVELS))


def pressure(r, d, R, E_star):
    """Contact pressure p(r) [Pa] of the spherical cap at the depth d, (5.59); 0 for r >= a.

    p = (E*/pi) integral_r^a g'(x)/sqrt(x^2 - r^2) dx with g' = atanh(x/R) + R x/(R^2 - x^2):
    the pole term in closed form (``sphere_lam_pressure_pole``), the atanh term by composite
    Gauss-Legendre quadrature over w = sqrt(x^2 - r^2) in (0, sqrt(a^2 - r^2)), where its
    integrand (``sphere_pressure_atanh_kernel``) is analytic; the panels shrink geometrically
    toward w = sqrt(R^2 - r^2) (x = R), where it is log-singular, so deep contacts keep full
    accuracy. The pressure is finite everywhere, with p ~ sqrt(a - r) at the edge.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], r >= 0.
    d : float or array_like
        Indentation depth [m], 0 <= d <= 16 R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    r, d, R, E_star = np.broadcast_arrays(nonnegative("r", r), nonnegative("d", d), _radius(R),
                                          positive("E_star", E_star))
    _deep(d, R)
    lam = _lam_from_depth(d, R)
    a = gen.sphere_lam_contact_radius(R, lam)
    out = np.zeros(r.shape)
    inside = r < a
    if inside.any():
        ri, Ri, Ei, li, ai = (v[inside] for v in (r, R, E_star, lam, a))
        k = np.sqrt((ai - ri) * (ai + ri))  # upper limit of w
        c = np.sqrt((Ri - ri) * (Ri + ri))  # w of the singularity x = R
        n = _levels(c - k, c)
        w, wt = panels(np.zeros_like(k), k, _geometric_breaks(c, n), _M)
        x = np.hypot(ri[:, None], w)
        rest = np.sum(wt * gen.sphere_pressure_atanh_kernel(Ei[:, None], Ri[:, None], x), axis=1)
        out[inside] = gen.sphere_lam_pressure_pole(Ei, Ri, li, ri) + rest  # (5.59)
    return result(out)


def surface_displacement(r, d, R):
    """Surface displacement u_z(r) [m]: d - f(r) inside the contact, (5.60) outside.

    Outside (r > a), u = (2/pi) integral_0^a (d - g(x))/sqrt(r^2 - x^2) dx (5.60) by composite
    Gauss-Legendre quadrature in mu = atanh(x/R) (x = R tanh(mu), dx = R sech(mu)^2 dmu), so that
    d - g(x) = R (lam tanh(lam) - mu tanh(mu)) carries no rounding of a even as a -> R; the
    panels have unit width in mu and shrink geometrically toward mu = atanh(r/R), where
    sqrt(r^2 - x^2) vanishes (r < R). The closed form of (5.60) cancels catastrophically (see
    :mod:`hertzmdr.derive.sphere`); this integrand is positive. Far away, u -> F/(pi E* r) (5.6).

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], r >= 0.
    d : float or array_like
        Indentation depth [m], 0 <= d <= 16 R.
    R : float or array_like
        Radius of the sphere [m], R > 0.
    """
    r, d, R = np.broadcast_arrays(nonnegative("r", r), nonnegative("d", d), _radius(R))
    _deep(d, R)
    lam = _lam_from_depth(d, R)
    a = gen.sphere_lam_contact_radius(R, lam)
    out = np.zeros(r.shape)  # u = 0 outside where there is no contact (d = 0)
    inside = r <= a
    out[inside] = d[inside] - gen.sphere_profile(R[inside], r[inside])  # (5.54) in 3-D
    outside = ~inside & (d > 0)
    if outside.any():
        ro, Ro, lo, do = (v[outside] for v in (r, R, lam, d))
        # mu of the zero of sqrt(r^2 - x^2) when r < R; none on the real axis otherwise
        below = ro < Ro
        mu_s = np.where(below, np.arctanh(np.where(below, ro / Ro, 0.0)), np.inf)
        finite = np.isfinite(mu_s)
        s = np.where(finite, mu_s, lo)
        n = _levels(np.where(finite, s - lo, np.inf), np.maximum(lo, 1e-300))
        unit = np.arange(1.0, np.ceil(lo.max()) + 1.0)
        breaks = np.concatenate([np.broadcast_to(unit, (len(lo), len(unit))),
                                 np.where(finite[:, None], _geometric_breaks(s, n), lo[:, None])],
                                axis=1)
        mu, wt = panels(np.zeros_like(lo), lo, breaks, _M)
        Rc = Ro[:, None]
        x = gen.sphere_lam_contact_radius(Rc, mu)
        gap = do[:, None] - gen.sphere_lam_depth(Rc, mu)  # d - g(x), (5.54)
        jac = Rc / np.cosh(mu) ** 2  # dx/dmu
        root = np.sqrt((ro[:, None] - x) * (ro[:, None] + x))
        out[outside] = 2 / np.pi * np.sum(wt * gap * jac / root, axis=1)  # (5.60)
    return result(out)
