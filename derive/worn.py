"""The flattened (worn) paraboloid of Problem 8 by the MDR.

Starting point: the profile f = 0 for r < b, f = (r^2 - b^2)/(2R) for b <= r (a paraboloid of
radius R worn flat to a tip of radius b), put through the MDR steps of
:mod:`hertzmdr.derive.mdr`: (5.52) gives g, (5.55) d(a), (5.57) F(a); the biquadratic
d = g(a) is solved for a^2, giving a(d) and F(d). The outside displacement (5.60) is the
integral of x sqrt(x^2 - b^2)/sqrt(r^2 - x^2) over (b, a), which the substitution
x^2 = b^2 + (r^2 - b^2) sin^2(phi) turns into the elementary integral of sin^2(phi).

The pressure (5.59) is an incomplete elliptic integral: the radicand of
integral (2x^2 - b^2) dx / sqrt((x^2 - b^2)(x^2 - r^2)) is a cubic in x^2 with three distinct
roots. SymPy's ``integrate`` has no closed form (:func:`hertzmdr.derive.mdr.solve` says so);
:func:`hertzmdr.derive.mdr.elliptic_abel_integral` finds it in Legendre's incomplete integrals
F(phi|m), E(phi|m), with the larger of r, b as L and the smaller as S. It is log-infinite at the
edge r = b of the flat (where f' jumps) and 0 outside the contact.

The chapter's F(d) contains sqrt(-1 + sqrt(1 + s^2)), s = 2 R d / b^2, which cancels
catastrophically for s << 1 (a shallow indentation of a strongly worn tip, where the contact
is nearly the flat punch); the code uses sqrt(sqrt(1 + s^2) - 1) = s/sqrt(sqrt(1 + s^2) + 1).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, R, a, d, r, symbol, unit_interval

b = symbol("b")
x = mdr.x
TEST = "tests/test_worn.py"


@cache
def solution() -> dict[str, sp.Expr]:
    rr = sp.Symbol("rr", positive=True)
    fp = sp.diff((rr**2 - b**2) / (2 * R), rr)  # f' for r > b; f' = 0 for r < b
    # (5.52) for x > b: only (b, x) contributes
    g = sp.simplify(x * mdr._integrate(fp / sp.sqrt(x**2 - rr**2), (rr, b, x)))
    depth = g.subs(x, a)  # (5.55)
    xi = sp.Symbol("xi", positive=True)
    F_a = sp.factor(sp.simplify(2 * E_star * (depth * a - sp.integrate(g.subs(x, xi),
                                                                        (xi, b, a)))))
    # (5.55) squared is quadratic in A = a^2: A (A - b^2) = (R d)^2
    A = sp.Symbol("A", positive=True)
    roots = sp.solve(sp.Eq((depth**2).subs(a, sp.sqrt(A)), d**2), A)
    (A_d,) = [s for s in roots if s.subs({b: 1, R: 1, d: 1}).is_positive]
    a_d = sp.sqrt(A_d)
    F_d = sp.simplify(F_a.subs(a, a_d))
    # (5.60) outside, r > a: (2/pi) [d asin(a/r) - (1/R) integral_b^a x sqrt(x^2-b^2)/sqrt(r^2-x^2)]
    phi, ph_a = sp.symbols("phi phi_a", positive=True)
    ro = sp.Symbol("r", positive=True)
    x_phi = sp.sqrt(b**2 + (ro**2 - b**2) * sp.sin(phi) ** 2)
    integrand = (x_phi * sp.sqrt(x_phi**2 - b**2) / sp.sqrt(ro**2 - x_phi**2)
                 * sp.diff(x_phi, phi))
    integrand = sp.simplify(sp.powsimp(integrand, force=True).subs(
        {sp.sqrt(sp.sin(phi) ** 2): sp.sin(phi), sp.sqrt(1 - sp.sin(phi) ** 2): sp.cos(phi)}))
    integrand = sp.trigsimp(sp.factor(integrand.replace(
        lambda e: e.is_Pow and e.exp == sp.Rational(1, 2),
        lambda e: sp.sqrt(sp.factor(e.base)))), )
    integrand = sp.powdenest(integrand, force=True).subs(sp.Abs(sp.cos(phi)), sp.cos(phi))
    I_phi = sp.integrate(integrand, (phi, 0, ph_a))
    sin_a = sp.sqrt((a**2 - b**2) / (ro**2 - b**2))  # x = a
    I_x = sp.expand_trig(I_phi).subs(sp.sin(ph_a), sin_a).subs(
        sp.cos(ph_a), sp.sqrt(1 - sin_a**2)).subs(ph_a, sp.asin(sin_a))
    u_out = 2 / sp.pi * (depth * sp.asin(a / ro) - I_x / R)
    return {"g": g, "d": depth, "F_a": F_a, "a": a_d, "F": F_d,
            "u_out": sp.simplify(u_out).subs(ro, r), "p": pressure(g)}


def pressure(g: sp.Expr) -> sp.Expr:
    """(5.59): p(r) = (E*/pi) integral_{max(r, b)}^a g'(x)/sqrt(x^2 - r^2) dx (g' = 0 below b).

    R sqrt(x^2 - b^2) g'(x) is a polynomial A x^2 + B (checked), so the integrand is
    (A x^2 + B)/(R sqrt((x^2 - b^2)(x^2 - r^2))): mdr.branch_point_integral, 0 for r >= a.
    """
    poly = sp.Poly(sp.expand(sp.simplify(R * sp.sqrt(x**2 - b**2) * sp.diff(g, x))), x)
    if poly.degree() != 2 or poly.coeff_monomial(x) != 0:
        raise AssertionError(f"R sqrt(x^2 - b^2) g' is not A x^2 + B: {poly}")
    A, B = poly.coeff_monomial(x**2), poly.coeff_monomial(1)
    return E_star / (sp.pi * R) * mdr.branch_point_integral(A, B, r, b, a)


def displacement_outside_stable() -> sp.Expr:
    """u(r > a) without the cancellation of S C - asin S (S = sin phi_a) for r >> a.

    S sqrt(1 - S^2) - asin S = -2 integral_0^S s^2/sqrt(1 - s^2) ds
    = -(2 S^3/3) 2F1(1/2, 3/2; 5/2; S^2), as in hertzmdr.derive.hertz.
    """
    S = sp.sqrt((a**2 - b**2) / (r**2 - b**2))
    h = sp.hyper([sp.Rational(1, 2), sp.Rational(3, 2)], [sp.Rational(5, 2)], S**2)
    return (2 * a * sp.sqrt(a**2 - b**2) * sp.asin(a / r)
            - 2 * (a**2 - b**2) * S / 3 * h) / (sp.pi * R)


def force_stable() -> sp.Expr:
    s2 = (2 * R * d / b**2) ** 2
    root = sp.sqrt(1 + s2)
    return (sp.sqrt(2) * E_star * b**3 / (3 * R) * (2 + root)
            * (2 * R * d / b**2) / sp.sqrt(root + 1))


def relations() -> list[Relation]:
    s = solution()
    s_ = 2 * R * d / b**2
    root = sp.sqrt(1 + s_**2)
    tb = unit_interval("t_b")
    wide = {b: a * tb}  # b < a
    f = sp.Max(0, (r - b) * (r + b)) / (2 * R)  # the profile: 0 on the flat r < b
    return [
        Relation("worn_profile", "Problem 8", f, (R, b, r),
                 "height f(r) [m] of the worn paraboloid's surface above its tip (0 for r < b)",
                 "the paraboloid r^2/(2R) worn flat to the radius b",
                 "tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f"),
        Relation("worn_displacement_inside", "Problem 8, (5.60)", d - f, (R, b, d, r),
                 "surface displacement u_z(r) [m] inside the contact (r <= a) of the worn "
                 "paraboloid",
                 "(5.60) of u = d - g(x) (5.54) for r <= a, which (5.53) makes d - f(r)",
                 "tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f"),
        Relation("worn_g", "Problem 8", s["g"].subs(sp.sqrt(x**2 - b**2),
                                                   sp.sqrt(sp.Max(0, (x - b) * (x + b)))),
                 (R, b, x), "MDR profile g(x) [m] of the worn paraboloid (0 for x < b)",
                 "(5.52) for f = (r^2 - b^2)/(2R), r > b", f"{TEST}::test_g_by_quadrature"),
        Relation("worn_depth", "Problem 8", s["d"], (R, a, b),
                 "indentation depth d [m] of the worn paraboloid at contact radius a > b",
                 "(5.55)", f"{TEST}::test_against_3d_elasticity",
                 printed=a / R * sp.sqrt(a**2 - b**2), domain=wide),
        Relation("worn_force_from_radius", "Problem 8", s["F_a"], (E_star, R, a, b),
                 "normal force F [N] of the worn paraboloid at contact radius a > b",
                 "(5.57) with d = g(a)", f"{TEST}::test_force_by_pressure",
                 printed=2 * E_star / (3 * R) * (2 * a**2 + b**2) * sp.sqrt(a**2 - b**2),
                 domain=wide),
        Relation("worn_contact_radius", "Problem 8", s["a"], (R, b, d),
                 "contact radius a [m] of the worn paraboloid at depth d > 0",
                 "(5.55) solved for a^2", f"{TEST}::test_against_3d_elasticity"),
        Relation("worn_force", "Problem 8", s["F"], (E_star, R, b, d),
                 "normal force F [N] of the worn paraboloid at depth d",
                 "(5.57) at the contact radius of (5.55)", f"{TEST}::test_force_by_pressure",
                 printed=sp.sqrt(2) * E_star * b**3 / (3 * R) * (2 + root)
                 * sp.sqrt(-1 + root),
                 stable=force_stable(),
                 stable_why="sqrt(-1 + sqrt(1 + s^2)), s = 2 R d/b^2, cancels for s << 1; "
                 "it is written s/sqrt(sqrt(1 + s^2) + 1)"),
        Relation("worn_pressure", "Problem 8, (5.59)", s["p"], (E_star, R, a, b, r),
                 "contact pressure p(r) [Pa] of the worn paraboloid (log-infinite at r = b, 0 "
                 "for r >= a)",
                 "(5.59) of g, in incomplete elliptic integrals (mdr.elliptic_abel_integral)",
                 f"{TEST}::test_pressure_by_quadrature_of_59", domain={r: a * unit_interval(),
                                                                      b: a * tb}),
        Relation("worn_displacement_outside", "Problem 8, (5.60)", s["u_out"], (R, a, b, r),
                 "surface displacement u_z(r) [m] outside the contact (r > a) of the worn "
                 "paraboloid", "(5.60) with x^2 = b^2 + (r^2 - b^2) sin^2(phi)",
                 f"{TEST}::test_against_3d_elasticity",
                 stable=displacement_outside_stable(),
                 stable_why="S sqrt(1 - S^2) - asin S, S^2 = (a^2 - b^2)/(r^2 - b^2), cancels "
                 "for r >> a; it is written -(2 S^3/3) 2F1(1/2, 3/2; 5/2; S^2)",
                 domain={r: a / unit_interval(), b: a * tb}),
    ]
