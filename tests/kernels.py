"""Independent routes: the Boussinesq kernel (5.7) and pressure integrals by mpmath quadrature.

u_z(r) = 1/(pi E*) * iint p dA / s is evaluated in polar coordinates (s, phi) centred on the
field point, where dA/s = ds dphi removes the kernel's 1/s singularity. The pressure is passed
as a function of a^2 - rho^2 (rho the source point's distance from the centre), computed in the
factored form (gamma - t)(gamma + t) so that the rim of the loaded disc, where (5.9) is
singular, keeps full precision. Quadrature is tanh-sinh, split at the rim, as the "Singularities"
section of mpmath's quad documentation advises.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import mpmath as mp

from oracle import memo


def uz_axisymmetric(p_gap: Callable[[mp.mpf], mp.mpf], r, a, E_star,
                    method: str = "gauss-legendre", rho_splits=(),
                    weight: Callable[[mp.mpf], mp.mpf] | None = None) -> mp.mpf:
    """u_z(r) under an axisymmetric pressure p supported on rho < a, by (5.7).

    ``p_gap(g)`` returns the pressure at a source point with a^2 - rho^2 = g (g > 0).
    Along each ray, t = s + r cos(phi) = gamma cos(theta) makes a^2 - rho^2 = gamma^2 sin^2(theta)
    exact and turns the rim singularity of (5.9) into a smooth integrand.
    For pressures smooth in a^2 - rho^2 (such as (5.9), (5.15), uniform) both integrands are then
    analytic and Gauss-Legendre converges fastest (35 digits in 0.01-2.5 s, 5-100 times faster
    than tanh-sinh); pass ``method="tanh-sinh"`` for pressures with interior singularities
    (the cone's log singularity at rho = 0). Call inside ``mp.workdps``; returns an mpf.
    Along each ray the point closest to the centre (theta = pi/2; not for Gauss-Legendre, whose
    integrands are smooth there) is a split point, and so are the crossings of the circles
    rho = c for c in ``rho_splits`` (where p is singular, e.g. the edge b of a worn tip), so that
    tanh-sinh sees those singularities at interval ends.
    ``weight(phi)`` (r < a only; even in phi) multiplies the ray at angle phi from the field
    point's radial direction: a kernel w(phi)/s instead of 1/s, such as Cerruti's.
    """
    r, a, E_star = mp.mpf(r), mp.mpf(a), mp.mpf(E_star)

    def chord(gamma, theta_max, rho_min):
        """Integral of p along the part of a chord of half-length gamma, t = gamma cos(theta);
        rho_min is the ray's closest approach to the centre (rho^2 = rho_min^2 + t^2)."""
        g2 = gamma * gamma
        pts = {mp.mpf(0), theta_max}
        if theta_max > mp.pi / 2 and method != "gauss-legendre":
            pts.add(mp.pi / 2)  # closest approach to the centre
        for c in rho_splits:  # rho = c where gamma^2 cos^2(theta) = c^2 - rho_min^2
            c2 = mp.mpf(c) ** 2 - rho_min**2
            if 0 < c2 < g2:
                for sgn in (1, -1):
                    th = mp.acos(sgn * mp.sqrt(c2 / g2))
                    if 0 < th < theta_max:
                        pts.add(th)
        return mp.quad(lambda th: p_gap(g2 * mp.sin(th) ** 2) * gamma * mp.sin(th),
                       sorted(pts), method=method)

    if r < a:
        def along_ray(phi):
            sin_phi = abs(mp.sin(phi))
            gamma = mp.sqrt((a - r * sin_phi) * (a + r * sin_phi))
            # the ray starts at the field point: t from beta = r cos(phi) to gamma
            ray = chord(gamma, mp.acos(max(-1, min(1, r * mp.cos(phi) / gamma))),
                        r * sin_phi)
            return ray if weight is None else ray * weight(phi)

        total = 2 * mp.quad(along_ray, [0, mp.pi / 2, mp.pi], method=method)  # even in phi
    else:
        if weight is not None:
            raise ValueError("weight is implemented for field points inside the disc, r < a")
        # rays at angle psi from the direction of the centre meet the disc for sin(psi) < a/r;
        # sin(psi) = (a/r) sin(beta) makes gamma = a cos(beta) exact and removes the square-root
        # behaviour of gamma at the grazing ray; dpsi = (a/r) cos(beta)/cos(psi) dbeta
        t = a / r

        def along_beta(beta):
            s = t * mp.sin(beta)
            cos_psi = mp.sqrt((1 - s) * (1 + s))
            return chord(a * mp.cos(beta), mp.pi, a * mp.sin(beta)) * t * mp.cos(beta) / cos_psi

        total = 2 * mp.quad(along_beta, [0, mp.pi / 2], method=method)
    return total / (mp.pi * E_star)


def uz_rings(p: Callable[[mp.mpf], mp.mpf], r, a, E_star, splits=()) -> mp.mpf:
    """u_z(r) under an axisymmetric pressure p(rho) supported on rho < a, by (5.7) in polar
    coordinates (rho, phi) centred on the axis: u_z = 1/(pi E*) integral_0^a p(rho) rho
    integral_0^(2 pi) dphi / s drho, s^2 = (r - rho)^2 + 4 r rho sin^2(phi/2).

    Both integrals by tanh-sinh; the pressure is evaluated once per ring, which makes this the
    route for pressures that are costly to evaluate (elliptic integrals). The ring integral has
    a log singularity at rho = r (split there), ``splits`` are radii where p is singular (split
    there too, e.g. the edge b of a worn tip). Call inside ``mp.workdps``; returns an mpf.
    """
    r, a = mp.mpf(r), mp.mpf(a)

    def ring(rho):  # even in phi: twice the integral over (0, pi)
        def inv_s(phi):
            return 1 / mp.sqrt((r - rho) ** 2 + 4 * r * rho * mp.sin(phi / 2) ** 2)

        return 2 * rho * mp.quad(inv_s, [0, mp.pi])

    pts = {mp.mpf(0), a, *(mp.mpf(c) for c in splits if 0 < c < a)}
    if 0 < r < a:
        pts.add(r)
    return mp.quad(lambda rho: p(rho) * ring(rho), sorted(pts)) / (mp.pi * E_star)


def force_axisymmetric(p: Callable[[mp.mpf], mp.mpf], a) -> mp.mpf:
    """F = integral of p(r) 2 pi r dr over [0, a] (5.11), (5.17), (5.57)."""
    return mp.quad(lambda rr: p(rr) * 2 * mp.pi * rr, [0, a])


@cache
def _hertz_unit_constants():
    """U0 = u_z(0) and U1 = u_z(0) - u_z(1) of the unit pressure (1 - rho^2)^(1/2), 50 digits."""
    with mp.workdps(50):
        u0 = uz_axisymmetric(lambda gap: mp.sqrt(gap), 0, 1, 1)
        u1 = uz_axisymmetric(lambda gap: mp.sqrt(gap), 1, 1, 1)
        return +u0, u0 - u1


def hertz_reference(E_star, R, d):
    """(a, p0, F) of a Hertz contact at depth d from the Boussinesq kernel alone.

    By linearity and scaling, the pressure p0 (1 - rho^2/a^2)^(1/2) gives u_z(r) = p0 a U(r/a)/E*.
    Matching the sphere d - r^2/(2R) needs d = p0 a U0/E* and a^2/(2R) = p0 a U1/E*, whence
    a^2 = 2 R d U1/U0 and p0 = d E*/(a U0); the force is the pressure integrated by quadrature.
    No derived formula enters. Call inside ``mp.workdps`` (at most 50 digits).

    A pure function of its arguments and the working precision: its results are kept by them
    (the sweeps check several functions at the same sampled points, and their inverses run the
    same root finding on F, so each quadrature is done once).
    """
    key = (E_star, R, d, mp.mp.prec)
    if key not in _HERTZ_REFERENCES:
        U0, U1 = _hertz_unit_constants()
        a = mp.sqrt(2 * R * d * U1 / U0)
        p0 = d * E_star / (a * U0)
        F = force_axisymmetric(lambda r: p0 * mp.sqrt(1 - (r / a) ** 2), a)
        _HERTZ_REFERENCES[key] = a, p0, F
    return _HERTZ_REFERENCES[key]


_HERTZ_REFERENCES: dict = {}



@cache
def _ring_tau_rz():
    """tau_rz at (r, 0, z) of a ring load of unit line density on the circle of radius rho, and
    its derivatives in r and z, as one mpmath function of (r, z, rho).

    The point-force shear (5.46) is tau_xz = -3 x z^2/(2 pi R^5) (Johnson, Contact Mechanics,
    (3.21); tests/test_stress.py checks that the derived one is this); with
    x = r - rho cos(phi), R^2 = A - B cos(phi), A = r^2 + rho^2 + z^2, B = 2 r rho, its
    integral over phi uses I(A, B) = integral_0^(2 pi) (A - B cos(phi))^(-1/2) dphi
    = 4 K(2B/(A + B))/(A + B)^(1/2): integral (A - B cos)^(-5/2) = (4/3) I_AA and
    integral cos (A - B cos)^(-5/2) = -(4/3) I_AB.
    """
    import sympy as sp

    r, z, rho, A, B = sp.symbols("r_f z_f rho_s A_s B_s", positive=True)
    inv = 4 * sp.elliptic_k(2 * B / (A + B)) / sp.sqrt(A + B)
    ring = -3 / (2 * sp.pi) * z**2 * sp.Rational(4, 3) * (r * inv.diff(A, 2)
                                                          + rho * inv.diff(A, B))
    ring = ring.subs({A: r**2 + rho**2 + z**2, B: 2 * r * rho})
    return sp.lambdify((r, z, rho), [ring, ring.diff(r), ring.diff(z)], "mpmath", cse=True)


def tau_rz_rings(p: Callable[[mp.mpf], mp.mpf], r, z, a, degree: int = 5) -> list:
    """[tau_rz, d(tau_rz)/dr, d(tau_rz)/dz] at (r, z), z > 0, under an axisymmetric pressure
    p(rho) on rho < a, by superposing the rings of :func:`_ring_tau_rz` (the point-force field,
    nothing of a closed-form stress field). rho = a sin(theta) makes a square-root rim (Hertz,
    any smooth MDR profile) smooth; Gauss-Legendre of mpmath's ``degree`` (3 2^(degree - 1)
    nodes) on theta-intervals split where rho = r - z, r, r + z/2 resolves the rings' peak
    near rho = r. Call inside ``mp.workdps``; returns mpfs.
    """
    from mpmath.calculus.quadrature import GaussLegendre

    f = _ring_tau_rz()
    r, z, a = mp.mpf(r), mp.mpf(z), mp.mpf(a)
    nodes = GaussLegendre(mp.mp).calc_nodes(degree, mp.mp.prec)
    pts = [mp.mpf(0), *(mp.asin(v / a) for v in (r - z, r, r + z / 2) if 0 < v < a),
           mp.pi / 2]
    out = [mp.mpf(0)] * 3
    for lo, hi in zip(pts[:-1], pts[1:], strict=True):
        h = (hi - lo) / 2
        for t, w in nodes:
            th = lo + h * (t + 1)
            rho = a * mp.sin(th)
            wt = w * h * p(rho) * rho * a * mp.cos(th)  # p(rho) rho d(rho)
            for i, v in enumerate(f(r, z, rho)):
                out[i] += wt * v
    return out


@memo  # a mutation run's memo (tests/oracle.py): the point-force field and mpmath only
def hertz_tau_rz(r, z, degree: int = 5) -> list:
    """:func:`tau_rz_rings` under the unit Hertz pressure (1 - rho^2)^(1/2) on the unit disc
    (its factored form keeps the rim exact)."""
    return tau_rz_rings(lambda rho: mp.sqrt((1 - rho) * (1 + rho)), r, z, 1, degree)

def ux_cerruti_axisymmetric(tau_gap: Callable[[mp.mpf], mp.mpf], r, a, G, nu, along: str = "x",
                            rho_splits=(), method: str = "tanh-sinh") -> mp.mpf:
    """u_x at (r, 0) (``along="x"``) or (0, r) (``"y"``), r < a, of an axisymmetric traction
    tau(rho) in +x on rho < a, by Cerruti's surface kernel alone (Johnson (3.87a), typed in
    here independently of derive/):
    u_x = (1/(2 pi G)) iint tau [(1 - nu)/s + nu s_x^2/s^3] dA, i.e. the ray at angle phi
    weighted by (1 - nu) + nu cos^2 of its angle with the x axis. ``tau_gap`` as ``p_gap`` of
    :func:`uz_axisymmetric`. Call inside ``mp.workdps``.
    """
    nu = mp.mpf(nu)
    if along == "x":
        def weight(phi):
            return (1 - nu) + nu * mp.cos(phi) ** 2
    else:
        def weight(phi):
            return (1 - nu) + nu * mp.sin(phi) ** 2
    # uz_axisymmetric returns (1/(pi E*)) iint; the Cerruti prefactor is 1/(2 pi G)
    return uz_axisymmetric(tau_gap, r, a, 1, method=method, rho_splits=rho_splits,
                           weight=weight) / (2 * mp.mpf(G))
