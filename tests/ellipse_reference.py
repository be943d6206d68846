"""A fast independent route to the stresses under the elliptical Hertz pressure.

The derived Boussinesq point-force stresses (5.41)-(5.46) (``derive/boussinesq.py``, not the
Love-form potentials of ``derive/ellipse_stress.py``) integrated over p0 (1 - x^2/a^2 -
y^2/b^2)^(1/2) in float64, in polar coordinates (rho, psi) about the foot (x, y) of the field
point. That is the coordinate system of the kernel: its peak of width z under the point is at
rho = 0 whatever the axis ratio, where a grid in the ellipse's own angles (``superposed`` in
``test_ellipse_stress.py``) meets it as a slanted band of width z/a (for b/a = 0.01 that band
was under-resolved there and the 20-digit reference was off by 6e-7 p0, issue 14).

Along a ray psi the pressure is (gamma (rho_max - rho)(rho + rho_2))^(1/2) exactly; rho runs
over Gauss-Legendre panels geometric in z (z/16 ... rho_max/2, so the kernel's scale is
resolved at any depth), then rho = rho_max - (rho_max/2) s^2 makes the square-root edge
smooth. psi runs over panels refined geometrically (ratio 4) towards 0 and pi, where
rho_max(psi) changes on the angular scale b/a. Every integrand is then analytic on its
panel and n-point Gauss-Legendre converges geometrically: the n = 12, 16 and 32 rules agree
to 2e-16 p0 at b/a = 1 ... 1e-8, near the surface, at the edge and on the axis
(``test_ellipse_stress.py::test_polar_route_converges``); with the roundings of a sum of
~10^5 terms below p0, the route is good to ~1e-15 p0.

Field points inside the contact's projection (x^2/a^2 + y^2/b^2 < 1) and below the surface
(z > 0), which is where the maxima are (``superposed_fast``); points beside the contact by the
same coordinates, the rays between its two tangents (``superposed_beside``). The route is
tested, not the package.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from hertzmdr.derive import boussinesq as bq
from hertzmdr.derive.symbols import F, nu

from oracle import memo

COMPONENTS = ("xx", "yy", "zz", "xy", "xz", "yz")


@cache
def _kernels():
    """The six derived point-force stresses of a unit force, numpy functions of (nu, x, y, z)
    (common subexpressions shared)."""
    exprs = [bq.stresses()[c].subs(F, 1) for c in COMPONENTS]
    return sp.lambdify((nu, bq.x, bq.y, bq.z), exprs, "numpy", cse=True)


@cache
def _gauss(n):
    return np.polynomial.legendre.leggauss(n)


def _panels(lo, hi, n):
    """Gauss-Legendre nodes and weights on the panels [lo_k, hi_k] (last axis: the panels;
    panels of zero width get zero weight)."""
    u, w = _gauss(n)
    mid, half = (lo + hi) / 2, (hi - lo) / 2
    nodes = mid[..., None] + half[..., None] * u
    weights = half[..., None] * w
    return nodes.reshape(*lo.shape[:-1], -1), weights.reshape(*lo.shape[:-1], -1)


def _psi_breaks(t):
    """[0, 2 pi] cut at pi/2, 3 pi/2 and refined towards 0 and pi at the angles atan(t 4^j),
    t 4^-4 ... 4: rho_max(psi) turns from ~b/sin(psi) to ~a at psi ~ t = b/a."""
    br = {0.0, np.pi / 2, np.pi, 1.5 * np.pi, 2 * np.pi}
    for base in (0.0, np.pi, 2 * np.pi):
        for j in range(-4, int(np.log(4 / t) / np.log(4)) + 1):
            d = np.arctan(t * 4.0**j)
            br |= {v for v in (base - d, base + d) if 0 < v < 2 * np.pi}
    return np.array(sorted(br))


@memo  # a mutation run's memo (tests/oracle.py): derive/'s kernel only
def superposed_fast(nu_, a, b, x, y, z, n=16):
    """The six stresses {comp: sigma/p0} at (x, y, z), a >= b, under the unit elliptical
    pressure (p0 = 1), by Gauss-Legendre of the derived point-force field in polar
    coordinates about (x, y); n nodes a panel. float64; see the module docstring."""
    a, b, x, y, z, nu_ = (float(v) for v in (a, b, x, y, z, nu_))
    alpha = (1 - x / a) * (1 + x / a) - (y / b) ** 2
    if not (alpha > 0 and z > 0):
        raise ValueError(f"({x}, {y}, {z}): the route takes points below the contact, z > 0")
    br = _psi_breaks(b / a)
    psi, wpsi = _panels(br[:-1][None], br[1:][None], n)
    psi, wpsi = psi[0][:, None], wpsi[0][:, None]
    c, s = np.cos(psi), np.sin(psi)
    beta = x * c / a**2 + y * s / b**2
    gam = (c / a) ** 2 + (s / b) ** 2
    root = np.sqrt(beta**2 + alpha * gam)
    rmax = alpha / (beta + root)  # the two roots of gamma rho^2 + 2 beta rho - alpha,
    r2 = (beta + root) / gam  # rho_max and -rho_2, without cancellation
    half = rmax / 2
    # the inner panels: [0, z/16], then doubling, clipped at rho_max/2
    steps = int(np.ceil(np.log2(max(float(np.max(half)) / z, 1.0)))) + 5
    cuts = np.minimum(z * 2.0 ** np.arange(-4, steps), half)
    cuts = np.concatenate([np.zeros_like(half), cuts, half], axis=1)
    rho, wr = _panels(cuts[:, :-1], cuts[:, 1:], n)
    q = np.sqrt(gam * (rmax - rho) * (rho + r2))
    # the edge panel: rho = rho_max - (rho_max/2) u^2, u in [0, 1] (two panels)
    u, wu = _panels(np.array([[0.0, 0.5]]), np.array([[0.5, 1.0]]), n)
    rho_e = rmax - half * u**2
    q_e = np.sqrt(gam * half * (rho_e + r2)) * u  # = (gamma (rho_max - rho)(rho + rho_2))^1/2
    w_e = wu * 2 * half * u  # d rho = 2 (rho_max/2) u du
    R = np.concatenate([rho, rho_e], axis=1)
    W = np.concatenate([wr * q, w_e * q_e], axis=1) * R * wpsi
    vals = _kernels()(nu_, -R * c, -R * s, z)
    return {comp: float(np.sum(v * W)) for comp, v in zip(COMPONENTS, vals, strict=True)}


@cache
def _kernels_mp():
    exprs = [bq.stresses()[c].subs(F, 1) for c in COMPONENTS]
    return sp.lambdify((nu, bq.x, bq.y, bq.z), exprs, "mpmath", cse=True)


def _gauss_mp(n):
    """n-point Gauss-Legendre nodes and weights at the working precision: numpy's nodes
    polished by Newton's method on P_n (P_n' from P_n and P_(n-1))."""
    import mpmath as mp

    nodes, weights = [], []
    for x0 in _gauss(n)[0]:
        x = mp.mpf(float(x0))
        for _ in range(8):
            p, q = mp.legendre(n, x), mp.legendre(n - 1, x)
            x -= p / (n * (x * p - q) / (x * x - 1))
        p, q = mp.legendre(n, x), mp.legendre(n - 1, x)
        dp = n * (x * p - q) / (x * x - 1)
        nodes.append(x)
        weights.append(2 / ((1 - x * x) * dp * dp))
    return nodes, weights


@memo  # a mutation run's memo (tests/oracle.py): derive/'s kernel only
def superposed_polar_mp(nu_, a, b, x, y, z, n=14):
    """superposed_fast in mpmath at the working precision (call inside mp.workdps): the same
    panels and substitutions, n-point Gauss-Legendre on each; all six components. Minutes a
    point: for HERTZMDR_SWEEP=full. At (0.3, 0.4 b, 0.3 b), b/a = 0.01 the n = 14 and n = 20
    rules agree to 20 digits (22-digit arithmetic)."""
    import mpmath as mp

    u, w = _gauss_mp(n)

    def panels(cuts):
        out = []
        for lo, hi in zip(cuts[:-1], cuts[1:], strict=True):
            mid, half = (lo + hi) / 2, (hi - lo) / 2
            out += [(mid + half * ui, half * wi) for ui, wi in zip(u, w, strict=True)]
        return out

    a, b, x, y, z, nu_ = (mp.mpf(v) for v in (a, b, x, y, z, nu_))
    alpha = (1 - x / a) * (1 + x / a) - (y / b) ** 2
    t = b / a
    br = {mp.mpf(0), mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi}
    for base in (0, mp.pi, 2 * mp.pi):
        for j in range(-4, int(mp.log(4 / t) / mp.log(4)) + 1):
            d = mp.atan(t * mp.mpf(4) ** j)
            br |= {v for v in (base - d, base + d) if 0 < v < 2 * mp.pi}
    ker = _kernels_mp()
    total = [mp.mpf(0)] * 6
    for psi, wp in panels(sorted(br)):
        c, s = mp.cos(psi), mp.sin(psi)
        beta = x * c / a**2 + y * s / b**2
        gam = (c / a) ** 2 + (s / b) ** 2
        root = mp.sqrt(beta**2 + alpha * gam)
        rmax, r2 = alpha / (beta + root), (beta + root) / gam
        half = rmax / 2
        cuts = [mp.mpf(0)] + [z * mp.mpf(2) ** j for j in range(-4, 200)
                              if z * mp.mpf(2) ** j < half] + [half]
        nodes = [(r, wr * mp.sqrt(gam * (rmax - r) * (r + r2))) for r, wr in panels(cuts)]
        for ue, we in panels([mp.mpf(0), mp.mpf(1) / 2, mp.mpf(1)]):
            r = rmax - half * ue * ue
            nodes.append((r, we * 2 * half * ue * mp.sqrt(gam * half * (r + r2)) * ue))
        for r, wr in nodes:
            f = wr * r * wp
            for i, v in enumerate(ker(nu_, -r * c, -r * s, z)):
                total[i] += v * f
    return dict(zip(COMPONENTS, total, strict=True))


@memo  # a mutation run's memo (tests/oracle.py): derive/'s kernel only
def superposed_beside(nu_, a, b, x, y, z, n=16, n_psi=64, refine=12):
    """The six stresses {comp: sigma/p0} at a point beside the contact (x^2/a^2 + y^2/b^2 >
    1, z > 0), the same polar superposition about its foot (x, y): the rays psi that meet
    the ellipse (a cone between its two tangents, found by bracketing the discriminant on a
    fine scan and Brent's method) enter it at rho_1 and leave at rho_2, and along a ray the
    pressure is (gamma (rho_2 - rho)(rho - rho_1))^(1/2) exactly; rho = m + h sin(phi)
    makes both square-root ends smooth (p d rho = gamma^(1/2) h^2 cos^2(phi) d phi), with
    panels geometric in z from rho_1 (the near edge, where the kernel of width z peaks).
    psi: n_psi uniform panels refined geometrically (ratio 2, ``refine`` levels) towards
    both tangents. float64; at b/a = 0.01, (0.2 a, 1.5 b, 0.8 b) the rules from (n, n_psi) =
    (12, 64) to (32, 256) agree to 3e-16 p0."""
    from scipy.optimize import brentq

    a, b, x, y, z, nu_ = (float(v) for v in (a, b, x, y, z, nu_))
    alpha = (1 - x / a) * (1 + x / a) - (y / b) ** 2
    if not (alpha < 0 and z > 0):
        raise ValueError(f"({x}, {y}, {z}): this route takes points beside the contact, z > 0")

    def parts(psi):
        c, s = np.cos(psi), np.sin(psi)
        beta = x * c / a**2 + y * s / b**2
        gam = (c / a) ** 2 + (s / b) ** 2
        return beta, gam, beta**2 + alpha * gam

    psi0 = np.arctan2(-y, -x)  # towards the centre: a ray that meets the ellipse
    scan = np.linspace(psi0 - np.pi, psi0 + np.pi, 200_001)
    beta, _, disc = parts(scan)
    hit = (disc > 0) & (beta < 0)
    i = j = scan.size // 2
    while hit[i - 1]:
        i -= 1
    while hit[j + 1]:
        j += 1
    lo = brentq(lambda p: parts(p)[2], scan[i - 1], scan[i], xtol=1e-16, rtol=1e-15)
    hi = brentq(lambda p: parts(p)[2], scan[j], scan[j + 1], xtol=1e-16, rtol=1e-15)
    width = (hi - lo) / n_psi
    cuts = set(np.linspace(lo, hi, n_psi + 1))
    for k in range(1, refine + 1):
        cuts |= {lo + width * 2.0**-k, hi - width * 2.0**-k}
    cuts = np.array(sorted(cuts))
    psi, wpsi = _panels(cuts[:-1][None], cuts[1:][None], n)
    total = np.zeros(6)
    for ps, wp in zip(psi[0], wpsi[0], strict=True):
        beta, gam, disc = parts(ps)
        if not (disc > 0 and beta < 0):
            continue
        root = np.sqrt(disc)
        r2 = (-beta + root) / gam
        r1 = -alpha / (-beta + root)  # r1 r2 = -alpha/gamma, without cancellation
        m, h = (r1 + r2) / 2, (r2 - r1) / 2
        near = [r1 + z * 2.0**j for j in range(-6, 60) if r1 + z * 2.0**j < m]
        phic = np.unique(np.concatenate([[-np.pi / 2], np.arcsin((np.array(near) - m) / h),
                                         np.linspace(0.0, np.pi / 2, 5)]))
        phi, wphi = _panels(phic[:-1][None], phic[1:][None], n)
        phi, wphi = phi[0], wphi[0]
        rho = m + h * np.sin(phi)
        w = wphi * np.sqrt(gam) * h**2 * np.cos(phi) ** 2 * rho * wp
        vals = _kernels()(nu_, -rho * np.cos(ps), -rho * np.sin(ps), z)
        total += np.array([np.sum(v * w) for v in vals])
    return dict(zip(COMPONENTS, (float(v) for v in total), strict=True))
