"""Elliptical Hertz contact: the exact solution for a quadratic gap (5.28)-(5.33).

Starting point: the ellipsoidal pressure (5.31), p = p0 (1 - x^2/a^2 - y^2/b^2)^(1/2) with
b = t a (0 < t <= 1), put through the Boussinesq integral (5.7) in polar coordinates (s, phi)
centred on a field point (x, y) inside the ellipse. Along a ray the source point is
(x + s cos phi, y + s sin phi), and 1 - X^2/a^2 - Y^2/b^2 = alpha - 2 beta s - gamma s^2 is a
quadratic in s. Pairing the rays phi and phi + pi gives the whole chord between its two roots,
an elementary integral (the same one as for the circle, :func:`pressures.chord_integral`):

    u_z = p0/(2 E*) * integral_0^pi (beta^2 + alpha gamma) / gamma^(3/2) dphi,

which is a quadratic polynomial in (x, y) (the xy term is odd under phi -> pi - phi). With
gamma = (1 - m cos^2 phi)/b^2 and m = 1 - t^2 = e^2 (the squared eccentricity, SciPy's and SymPy's
*parameter*), every phi-integral is a combination of I0(m) = integral_0^pi (1 - m cos^2)^(-1/2)
dphi = 2 K(m) (the definition of K) and of its m-derivative: SymPy differentiates under the
integral sign, which gives the classical u_z = (p0/E*)(L - M x^2 - N y^2) with complete elliptic
integrals K(m), E(m). Matching u_z to d - x^2/(2 R1) - y^2/(2 R2) (the gap (5.32)) gives a and p0
from (R1, d, t), and the eccentricity equation R1/R2 = N/M, a function of t alone, which
:mod:`hertzmdr.numeric.ellipse` solves for t numerically.

K, E and their combinations D = (K - E)/m and B = (E - (1 - m) K)/m cancel as m -> 0 (the
circle), where the eccentricity equation is 0/0. The printed forms use K = D + B,
E = B + (1 - m) D with D = (pi/4) 2F1(1/2, 3/2; 2; m), B = (pi/4) 2F1(1/2, 1/2; 2; m), free of
cancellation (tests/test_printed.py proves them equal to the derived forms).

The chapter's Gaussian-radius approximation (5.28)-(5.31) is derived in one place,
:mod:`hertzmdr.derive.bodies` (relations ``bodies_gaussian_*``), with the other two-body
relations (5.26)-(5.33); :mod:`hertzmdr.numeric.ellipse` measures it against this solution.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import hertz, pressures
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, R, a, d, p0, symbol

TEST = "tests/test_ellipse.py"

R1, R2 = symbol("R1"), symbol("R2")
t = symbol("t_ba")  # b/a
x, y = symbol("x", real=True), symbol("y", real=True)
m = sp.Symbol("m", positive=True)  # parameter m = e^2 = 1 - t^2
s, phi, C = sp.symbols("s phi C", real=True)  # ray length, ray angle, cos(phi)^2


def _d_hyp() -> sp.Expr:
    """D(m) = (K - E)/m as (pi/4) 2F1(1/2, 3/2; 2; m): no cancellation as m -> 0."""
    return sp.pi / 4 * sp.hyper([sp.Rational(1, 2), sp.Rational(3, 2)], [2], m)


def _b_hyp() -> sp.Expr:
    """B(m) = (E - (1 - m) K)/m as (pi/4) 2F1(1/2, 1/2; 2; m)."""
    return sp.pi / 4 * sp.hyper([sp.Rational(1, 2), sp.Rational(1, 2)], [2], m)


def _even_trig_is_zero(expr: sp.Expr) -> bool:
    """True if the polynomial ``expr`` in cos(phi), sin(phi) vanishes: sin^2 -> 1 - cos^2,
    then expand (exact, and far cheaper than a general trigsimp)."""
    red = sp.expand(expr).subs(sp.sin(phi) ** 2, 1 - sp.cos(phi) ** 2)
    return sp.expand(red) == 0


@cache
def displacement_inside() -> sp.Expr:
    """u_z(x, y) inside the ellipse under (5.31), with b = t a, in E*, a, p0, t, x, y."""
    b = t * a
    g = sp.expand(1 - (x + s * sp.cos(phi)) ** 2 / a**2 - (y + s * sp.sin(phi)) ** 2 / b**2)
    alpha = g.coeff(s, 0)
    beta = -g.coeff(s, 1) / 2
    gamma = -g.coeff(s, 2)
    assert sp.expand(g - (alpha - 2 * beta * s - gamma * s**2)) == 0  # polynomial in s
    # completing the square: g = gamma (h^2 - tau^2), tau = s + beta/gamma
    h2 = (beta**2 + alpha * gamma) / gamma**2
    assert sp.cancel(g - gamma * (h2 - (s + beta / gamma) ** 2)) == 0
    # the ray pair phi, phi + pi covers the whole chord: sqrt(gamma) * int (h^2 - tau^2)^(1/2),
    # with gamma > 0 and numer = gamma^2 h^2 > 0 (G, Nm below) on every ray through the inside
    chord = pressures.chord_integral(sp.Rational(1, 2))
    G, Nm = sp.symbols("G N_m", positive=True)
    pair = sp.sqrt(G) * chord.subs(pressures.gamma, sp.sqrt(Nm / G**2))
    # pair = pi/2 * numer / gamma^(3/2); gamma^(-3/2) = b^3 (1 - m C)^(-3/2)
    assert sp.simplify(pair - sp.pi / 2 * Nm / G ** sp.Rational(3, 2)) == 0
    # gamma = (1 - m cos^2 phi)/b^2 with m = 1 - t^2
    gam_m = (1 - m * sp.cos(phi) ** 2) / b**2
    assert _even_trig_is_zero(gamma - gam_m.subs(m, 1 - t**2))
    numer = sp.expand(beta**2 + alpha * gamma)
    # the phi-integrals, by differentiation of I0 = 2 K(m) (the definition of K) under the
    # integral sign: J1 = int C (1 - m C)^(-3/2) = 2 dI0/dm, J0 = int (1 - m C)^(-3/2) = I0 + m J1
    I0 = 2 * sp.elliptic_k(m)
    J1 = 2 * sp.diff(I0, m)
    J0 = I0 + m * J1
    poly = sp.Poly(numer, x, y)
    u = sp.Integer(0)
    for (i, j), coeff in zip(poly.monoms(), poly.coeffs(), strict=True):
        c = sp.expand(sp.expand_trig(coeff))
        # the odd part in cos(phi) sin(phi) (the xy term) vanishes over phi in (0, pi):
        # phi -> pi - phi flips it and keeps gamma
        odd = c.subs(sp.cos(phi), -sp.cos(phi))
        if sp.expand(c + odd) == 0 and c != 0:
            continue
        assert sp.expand(c - odd) == 0, f"coefficient of x^{i} y^{j} not even in cos(phi)"
        cC = sp.expand(c.subs(sp.sin(phi), sp.sqrt(1 - C)).subs(sp.cos(phi), sp.sqrt(C)))
        cC = sp.Poly(cC, C)
        assert cC.degree() <= 1
        q0, q1 = cC.coeff_monomial(1), cC.coeff_monomial(C)
        integral = q0 * J0 + q1 * J1  # int_0^pi (q0 + q1 C) (1 - m C)^(-3/2) dphi
        u += x**i * y**j * p0 * b**3 * integral / (2 * E_star)  # (5.7): 1/(pi E*) * pi/2
    return u.subs(m, 1 - t**2)


_Ds, _Bs = sp.symbols("D B", positive=True)


def _to_d_b(expr: sp.Expr) -> sp.Expr:
    """K(m), E(m) (m = 1 - t^2) written through D = (K - E)/m and B = (E - (1 - m) K)/m.

    K = D + B and E = B + (1 - m) D is an invertible linear change of variables: in D, B the
    expressions are rational (times powers of d, R1, E*), where cancel and factor are exact
    and fast.
    """
    mm = 1 - t**2
    out = expr.subs({sp.elliptic_k(mm): _Ds + _Bs, sp.elliptic_e(mm): _Bs + (1 - mm) * _Ds})
    assert not out.has(sp.elliptic_k) and not out.has(sp.elliptic_e)
    return out


def _tidy_d_b(expr: sp.Expr) -> sp.Expr:
    """A rational expression in D, B (times powers) in a canonical factored form."""
    return sp.powsimp(sp.factor(sp.cancel(expr)), force=True)


@cache
def solution() -> dict[str, sp.Expr]:
    """a, p0, R1/R2, F, ... of the elliptical contact as functions of (E*, R1, d, t), each
    written with D(t), B(t) of :func:`_to_d_b` (the symbols ``_Ds``, ``_Bs``)."""
    u = sp.expand(_to_d_b(displacement_inside()))
    match = sp.Poly(sp.expand(u - (d - x**2 / (2 * R1) - y**2 / (2 * R2))), x, y)
    L_eq = match.coeff_monomial(1)
    M_eq = match.coeff_monomial(x**2)
    N_eq = match.coeff_monomial(y**2)
    # every coefficient is linear in its unknown: p0 from x^0, a^2 from x^2, R2 from y^2
    (p0_a,) = sp.solve(L_eq, p0)
    a2 = sp.Symbol("a2", positive=True)
    (a2_d,) = sp.solve(sp.cancel(M_eq.subs(p0, p0_a).subs(a, sp.sqrt(a2))), a2)
    a_d = sp.sqrt(_tidy_d_b(a2_d))
    p0_d = _tidy_d_b(p0_a.subs(a, a_d))
    (inv_r2,) = sp.solve(N_eq.subs({a: a_d, p0: p0_d}).subs(R2, 1 / R2), R2)
    ratio = _tidy_d_b(R1 * inv_r2)
    force = _tidy_d_b(sp.Rational(2, 3) * sp.pi * a_d * t * a_d * p0_d)  # int of (5.31)
    # F = c d^(3/2) with c free of d (the force is homogeneous of degree 3/2 in d)
    c = _tidy_d_b(force / d ** sp.Rational(3, 2))
    assert not c.has(d)
    d_F = (F / c) ** sp.Rational(2, 3)
    # R_e with F = (4/3) E* R_e^(1/2) d^(3/2), the Hertz force (5.23) of a sphere of radius R_e
    c_hertz = sp.powsimp(hertz.solution()["F"] / d ** sp.Rational(3, 2), force=True)
    assert sp.cancel(c_hertz.subs(R, 1) * sp.sqrt(R) - c_hertz) == 0  # c_hertz ~ R^(1/2)
    r_e = (c / c_hertz.subs(R, 1)) ** 2
    return {
        "a": a_d, "b": t * a_d, "p0": p0_d, "ratio": ratio, "F": force,
        "pm": _tidy_d_b(force / (sp.pi * a_d * t * a_d)),
        "k": _tidy_d_b(sp.diff(force, d)), "area": sp.pi * t * a_d**2,
        "d_F": _tidy_d_b(d_F), "R_e": _tidy_d_b(r_e),
    }


def _tidy(expr: sp.Expr) -> sp.Expr:
    """The derived ``expr`` (in D, B) in its K, E form."""
    mm = 1 - t**2
    K, E = sp.elliptic_k(mm), sp.elliptic_e(mm)
    return expr.subs({_Ds: (K - E) / mm, _Bs: (E - (1 - mm) * K) / mm})


def _stable(expr: sp.Expr) -> sp.Expr:
    """``expr`` (in D, B) with D and B as (pi/4) 2F1: no cancellation as m -> 0."""
    mm = 1 - t**2
    return expr.subs({_Ds: _d_hyp().subs(m, mm), _Bs: _b_hyp().subs(m, mm)})


def relations() -> list[Relation]:
    sol = solution()
    why = ("K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as "
           "(pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0")
    dom = "tests/test_ellipse.py"

    def rel(name, eq, key, args, summary, origin, test, **kw):
        return Relation(name, eq, _tidy(sol[key]), args, summary, origin, f"{dom}::{test}",
                        stable=_stable(sol[key]), stable_why=why, **kw)

    pressure = _tidy(sol["p0"]) * sp.sqrt(
        sp.Max(0, 1 - x**2 / _tidy(sol["a"]) ** 2 - y**2 / _tidy(sol["b"]) ** 2))
    pressure_stable = _stable(sol["p0"]) * sp.sqrt(
        sp.Max(0, 1 - x**2 / _stable(sol["a"]) ** 2 - y**2 / _stable(sol["b"]) ** 2))
    return [
        rel("ellipse_radius_ratio", "(5.31)-(5.32), exact", "ratio", (t,),
            "ratio R1/R2 >= 1 of the principal radii that gives the axis ratio t = b/a",
            "(5.7) over (5.31) matched to the gap (5.32): the y^2 and x^2 coefficients",
            "test_displacement_by_boussinesq"),
        rel("ellipse_semi_major", "(5.28), exact", "a", (R1, d, t),
            "semi-axis a [m] (along x, the direction of R1 >= R2) of an elliptical contact",
            "(5.7) over (5.31) matched to (5.32): the x^0 and x^2 coefficients",
            "test_displacement_by_boussinesq"),
        rel("ellipse_semi_minor", "(5.28), exact", "b", (R1, d, t),
            "semi-axis b = t a [m] (along y, the direction of R2) of an elliptical contact",
            "(5.7) over (5.31) matched to (5.32)", "test_displacement_by_boussinesq"),
        rel("ellipse_max_pressure", "(5.31), exact", "p0", (E_star, R1, d, t),
            "maximum pressure p0 [Pa] of an elliptical contact at depth d",
            "(5.7) over (5.31) matched to (5.32)", "test_displacement_by_boussinesq"),
        rel("ellipse_force", "(5.23), exact", "F", (E_star, R1, d, t),
            "normal force F [N] of an elliptical Hertz contact at depth d",
            "(5.31) integrated over the ellipse, with a and p0 from the matching",
            "test_force_by_pressure_quadrature"),
        rel("ellipse_mean_pressure", "(5.17), exact", "pm", (E_star, R1, d, t),
            "mean pressure F/(pi a b) [Pa] of an elliptical contact",
            "the force divided by the area pi a b", "test_force_by_pressure_quadrature"),
        rel("ellipse_stiffness", "(5.13), exact", "k", (E_star, R1, d, t),
            "differential stiffness dF/dd [N/m] of an elliptical contact",
            "the derivative of the force at fixed R1, R2", "test_stiffness_by_derivative"),
        rel("ellipse_area", "(5.29), exact", "area", (R1, d, t),
            "contact area pi a b [m^2] of an elliptical contact", "pi a b with a, b matched",
            "test_displacement_by_boussinesq"),
        rel("ellipse_depth_from_force", "(5.23), exact, inverted", "d_F", (E_star, F, R1, t),
            "indentation depth d [m] of an elliptical contact under the force F",
            "the exact force solved for d", "test_force_controlled_roundtrip"),
        rel("ellipse_equivalent_radius", "(5.23), exact", "R_e", (R1, t),
            "radius R_e [m] of the sphere whose Hertz force (5.23) equals the elliptical "
            "contact's at every depth (compare with the Gaussian radius (5.30))",
            "the exact force equated to (5.23)", "test_force_by_pressure_quadrature"),
        Relation("ellipse_pressure", "(5.31)", pressure, (E_star, R1, d, t, x, y),
                 "contact pressure p(x, y) [Pa] of an elliptical contact (0 outside)",
                 "(5.31) with a, b, p0 from the matching", f"{dom}::test_pressure_field",
                 stable=pressure_stable, stable_why=why),
    ]
