"""Surface displacement under axisymmetric pressures p0*(1 - rho^2/a^2)^n, from (5.7).

Starting point: the Boussinesq surface displacement (5.7), u_z = 1/(pi E*) * iint p / s dA, in
polar coordinates (s, phi) centred on the field point at distance r from the centre of the
loaded disc. A source point then sits at rho^2 = r^2 + 2 r s cos(phi) + s^2, so that with
beta = r cos(phi), gamma^2 = a^2 - r^2 sin^2(phi) and t = s + beta,

    a^2 - rho^2 = gamma^2 - t^2,      dA / s = ds dphi,

and the 1/s singularity of the kernel is gone. Inside the disc (r < a) the ray runs from t = beta
to t = gamma; the part of the t-integral odd in beta drops out of the phi-integral because
phi -> pi - phi flips beta and keeps gamma, so only half the full chord from -gamma to gamma
remains. Outside (r > a) the rays that meet the disc (|phi - pi| < arcsin(a/r)) cross the full
chord from -gamma to gamma.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, a, p0, r, unit_interval

t, gamma, beta, phi, psi = sp.symbols("t gamma beta phi psi", real=True)
_gamma_pos = sp.Symbol("gamma_pos", positive=True)

TEST = "tests/test_pressures.py"


def chord_integral(n: sp.Rational) -> sp.Expr:
    """Integral of (gamma^2 - t^2)^n over the whole chord t in (-gamma, gamma)."""
    val = sp.integrate((_gamma_pos**2 - t**2) ** n, (t, -_gamma_pos, _gamma_pos))
    return sp.simplify(val).subs(_gamma_pos, gamma)


def complete_elliptic(integrand: sp.Expr, var: sp.Symbol, m: sp.Expr, scale=1) -> sp.Expr:
    """integral_0^(pi/2) of ``integrand`` d``var``, recognised as ``scale`` K(m) or E(m).

    By their definitions (``f(m).rewrite(Integral)``): the integrand must be ``scale`` times
    the definition's, term by term (a general ``integrate`` finds the same K, E in about a
    second each).
    """
    for f in (sp.elliptic_e, sp.elliptic_k):
        defn = f(m).rewrite(sp.Integral)
        ((dummy, lo, hi),) = defn.limits
        assert (lo, hi) == (0, sp.pi / 2)
        ours = scale * defn.function.subs(dummy, var)
        if sp.expand(ours - integrand) == 0:
            return scale * f(m)
    raise ValueError(f"{integrand} is not the integrand of K or E of {m}")


@cache
def _check_symmetry() -> None:
    """phi -> pi - phi maps beta to -beta and keeps gamma^2: the odd part integrates to 0."""
    b = r * sp.cos(phi)
    g2 = a**2 - r**2 * sp.sin(phi) ** 2
    assert sp.simplify(b.subs(phi, sp.pi - phi) + b) == 0
    assert sp.simplify(g2.subs(phi, sp.pi - phi) - g2) == 0
    # and gamma^2 - (s + beta)^2 is a^2 - rho^2 with rho^2 = r^2 + 2 r s cos(phi) + s^2
    s = sp.Symbol("s", positive=True)
    rho2 = r**2 + 2 * r * s * sp.cos(phi) + s**2
    assert sp.simplify(g2 - (s + b) ** 2 - (a**2 - rho2)) == 0


@cache
def displacement_inside(n: sp.Rational) -> sp.Expr:
    """u_z(r) for r < a under p0*(1 - rho^2/a^2)^n, as an expression in E*, a, p0, r."""
    _check_symmetry()
    half_chord = chord_integral(n) / 2  # even part in beta of the integral from beta to gamma
    g = sp.sqrt(a**2 - r**2 * sp.sin(phi) ** 2)
    inner = half_chord.subs(gamma, g)
    total = _full_turn(sp.expand(sp.simplify(inner)))
    return sp.simplify(p0 * a ** (-2 * n) * total / (sp.pi * E_star))


def _full_turn(f: sp.Expr) -> sp.Expr:
    """integral_0^(2 pi) of f d phi.

    n = 0 gives f = sqrt(a^2 - r^2 sin^2 phi) = a sqrt(1 - m sin^2 phi) (a > 0, m = r^2/a^2):
    pi-periodic and even about pi/2, so 4 times its quarter-period integral, a E(m) by the
    definition of E (integrate takes ~0.6 s CPU to find it). Everything else by integrate.
    """
    m_ = r**2 / a**2
    q = sp.sqrt(1 - m_ * sp.sin(phi) ** 2)
    if (f.is_Pow and f.exp == sp.Rational(1, 2) and sp.expand(f.base - a**2 * q.base) == 0
            and f.subs(phi, phi + sp.pi) == f and f.subs(phi, sp.pi - phi) == f):
        return 4 * complete_elliptic(a * q, phi, m_, scale=a)
    return sp.integrate(f, (phi, 0, 2 * sp.pi))


@cache
def displacement_outside(n: sp.Rational) -> sp.Expr:
    """u_z(r) for r > a under p0*(1 - rho^2/a^2)^n."""
    ro = sp.Symbol("r", positive=True)
    g = sp.sqrt(a**2 - ro**2 * sp.sin(psi) ** 2)
    inner = sp.expand(sp.simplify(chord_integral(n).subs(gamma, g)))
    # rays with |phi - pi| < arcsin(a/r); the integrand is even in psi = phi - pi
    total = 2 * sp.integrate(inner, (psi, 0, sp.asin(a / ro)))
    u = p0 * a ** (-2 * n) * total / (sp.pi * E_star)
    return sp.simplify(u).subs(ro, r)


@cache
def uniform_displacement_outside() -> tuple[sp.Expr, sp.Expr]:
    """u_z(r > a) under a uniform pressure p0: (derived form, stable form), in E*, a, p0, r.

    The chord integral of n = 0 is 2 gamma, so u_z = 4 p0/(pi E*) * integral_0^asin(a/r) of
    sqrt(a^2 - r^2 sin^2 psi) dpsi. The substitution sin psi = t sin beta (t = a/r) maps it to
    a t * integral_0^(pi/2) cos^2 beta / sqrt(1 - t^2 sin^2 beta) dbeta, and writing cos^2 beta
    as ((1 - m sin^2 beta) - (1 - m))/m (m = t^2) splits it into the complete integrals E and K.
    """
    t = unit_interval()
    beta = sp.Symbol("beta", positive=True)  # 0 < beta < pi/2: cos(beta) > 0
    ro = sp.Symbol("r", positive=True)
    psi_of_beta = sp.asin(t * sp.sin(beta))
    integrand = sp.sqrt(a**2 - ro**2 * sp.sin(psi_of_beta) ** 2) * sp.diff(psi_of_beta, beta)
    integrand = sp.simplify(integrand.subs(ro, a / t).subs(sp.sin(beta) ** 2,
                                                            1 - sp.cos(beta) ** 2))
    integrand = integrand.replace(sp.Abs, lambda x: x)  # |cos beta| = cos beta on (0, pi/2)
    m = t**2
    root = sp.sqrt(1 - m * sp.sin(beta) ** 2)
    split = a * t * (root - (1 - m) / root) / m
    assert sp.simplify(split - integrand) == 0
    integral = (a * t / m) * (complete_elliptic(root, beta, m)
                              - (1 - m) * complete_elliptic(1 / root, beta, m))
    u = sp.simplify(4 * p0 / (sp.pi * E_star) * integral).subs(t, a / r)
    # (E(m) - (1 - m) K(m))/m = (pi/4) 2F1(1/2, 1/2; 2; m): no cancellation for r >> a
    h = sp.hyper([sp.Rational(1, 2), sp.Rational(1, 2)], [2], a**2 / r**2)
    stable = p0 * a**2 / (E_star * r) * h
    return u, stable


def force(n: sp.Rational) -> sp.Expr:
    """Total force, the integral of p * 2 pi r over the disc (5.11), (5.17)."""
    xi = sp.Symbol("xi", positive=True)  # r = a*xi, so that SymPy sees 0 < xi < 1
    integrand = p0 * (1 - xi**2) ** n * 2 * sp.pi * a * xi * a
    return sp.simplify(sp.integrate(integrand, (xi, 0, 1)))


def relations() -> list[Relation]:
    half = sp.Rational(1, 2)
    u_punch = displacement_inside(-half)
    u_hertz = displacement_inside(half)
    F_punch = force(-half)
    F_hertz = force(half)
    # Problem 6: uniform pressure (n = 0): the centre and the edge of the disc.
    g0 = sp.sqrt(a**2 - r**2 * sp.sin(phi) ** 2)
    inner0 = chord_integral(sp.Integer(0)).subs(gamma, g0) / 2
    u_centre = sp.integrate(inner0.subs(r, 0), (phi, 0, 2 * sp.pi)) * p0 / (sp.pi * E_star)
    u_edge = sp.integrate(sp.Abs(a * sp.cos(phi)), (phi, 0, 2 * sp.pi)) * p0 / (sp.pi * E_star)
    u_uniform = displacement_inside(sp.Integer(0))
    u_uniform_out, u_uniform_out_stable = uniform_displacement_outside()
    rels = [
        Relation("uniform_pressure_displacement_outside", "Problem 6 (outside the disc)",
                 u_uniform_out, (E_star, a, p0, r),
                 "surface displacement u_z [m] outside a disc (r > a) under a uniform pressure p0",
                 "(5.7) with p = p0 (n = 0) outside the disc",
                 f"{TEST}::test_uniform_by_kernel",
                 stable=u_uniform_out_stable,
                 stable_why="E(m) - (1 - m) K(m) cancels like m = a^2/r^2 for r >> a; it equals "
                 "(pi m/4) 2F1(1/2, 1/2; 2; m)",
                 domain={r: a / unit_interval()}),
        Relation("uniform_pressure_force", "Problem 6", force(sp.Integer(0)), (a, p0),
                 "total force F [N] of a uniform pressure p0 on a disc of radius a",
                 "the integral of p0 times 2 pi r over the disc",
                 f"{TEST}::test_force_by_quadrature"),
        Relation("uniform_pressure_displacement", "Problem 6", u_uniform, (E_star, a, p0, r),
                 "surface displacement u_z [m] inside a disc (r <= a) under a uniform pressure p0",
                 "(5.7) with p = p0 (n = 0); the phi-integral is 4 a E(r^2/a^2)",
                 f"{TEST}::test_uniform_by_kernel", domain={r: a * unit_interval()}),
        Relation("punch_pressure_displacement", "(5.10)", u_punch, (E_star, a, p0),
                 "surface displacement u_z [m] inside a disc loaded by p0*(1 - r^2/a^2)^(-1/2)",
                 "(5.7) over the pressure (5.9)", f"{TEST}::test_punch_displacement_by_kernel",
                 printed=sp.pi * p0 * a / E_star),
        Relation("punch_pressure_displacement_outside", "Fig. 5.2 (n = -1/2), Problem 7(a)",
                 displacement_outside(-half), (E_star, a, p0, r),
                 "surface displacement u_z [m] outside a disc (r > a) loaded by "
                 "p0*(1 - r^2/a^2)^(-1/2)", "(5.7) over the pressure (5.9)",
                 f"{TEST}::test_outside_displacement_by_kernel",
                 domain={r: a / unit_interval()}),
        Relation("punch_pressure_force", "(5.11)", F_punch, (a, p0),
                 "total force F [N] of the pressure p0*(1 - r^2/a^2)^(-1/2)",
                 "the integral of (5.9) times 2 pi r over the disc",
                 f"{TEST}::test_force_by_quadrature", printed=2 * sp.pi * p0 * a**2),
        Relation("punch_stiffness", "(5.12)", sp.simplify(F_punch / u_punch), (E_star, a),
                 "stiffness k = F/u_z [N/m] of a flat rigid circular punch of radius a",
                 "(5.11) divided by (5.10)", f"{TEST}::test_punch_stiffness_by_kernel",
                 printed=2 * a * E_star),
        Relation("hertz_pressure_displacement", "(5.16)", u_hertz, (E_star, a, p0, r),
                 "surface displacement u_z [m] inside a disc (r <= a) loaded by "
                 "p0*(1 - r^2/a^2)^(1/2)", "(5.7) over the pressure (5.15)",
                 f"{TEST}::test_hertz_displacement_by_kernel",
                 printed=sp.pi * p0 / (4 * E_star * a) * (2 * a**2 - r**2)),
        Relation("hertz_pressure_displacement_outside", "Fig. 5.2", displacement_outside(half),
                 (E_star, a, p0, r),
                 "surface displacement u_z [m] outside a disc (r > a) loaded by "
                 "p0*(1 - r^2/a^2)^(1/2)", "(5.7) over the pressure (5.15)",
                 f"{TEST}::test_outside_displacement_by_kernel",
                 domain={r: a / unit_interval()}),
        Relation("hertz_pressure_force", "(5.17)", F_hertz, (a, p0),
                 "total force F [N] of the pressure p0*(1 - r^2/a^2)^(1/2)",
                 "the integral of (5.15) times 2 pi r over the disc",
                 f"{TEST}::test_force_by_quadrature",
                 printed=sp.Rational(2, 3) * p0 * sp.pi * a**2),
        Relation("uniform_pressure_displacement_centre", "Problem 6", sp.simplify(u_centre),
                 (E_star, a, p0), "displacement u_z(0) [m] at the centre of a disc under a "
                 "uniform pressure p0", "(5.7) with p = p0 (n = 0) at r = 0",
                 f"{TEST}::test_uniform_by_kernel", printed=2 * p0 * a / E_star),
        Relation("uniform_pressure_displacement_edge", "Problem 6", sp.simplify(u_edge),
                 (E_star, a, p0), "displacement u_z(a) [m] at the edge of a disc under a "
                 "uniform pressure p0", "(5.7) with p = p0 (n = 0) at r = a",
                 f"{TEST}::test_uniform_by_kernel", printed=4 * a * p0 / (sp.pi * E_star)),
    ]
    return rels
