"""Line contact of two parallel cylinders, (5.34)-(5.37): the 2-D Hertz problem.

Starting point: the surface displacement of a line load, from (5.6)/(5.7) integrated along
the line. The displacement itself diverges logarithmically with the length of the line (the
reason why the depth of a line contact is not well defined, as the chapter says), but its
gradient converges: du/dx = -(2/(pi E*)) PV int p(s)/(x - s) ds (a Hilbert transform).
Matching the gap: inside the strip |x| < a the displacement is d - x^2/(2R), so
du/dx = -x/R. The pressure p0 sqrt(1 - x^2/a^2) (5.36) does it: with s = a sigma and
sqrt(1 - sigma^2)/(xi - sigma) = (1 - xi^2)/((xi - sigma) sqrt(1 - sigma^2))
+ (xi + sigma)/sqrt(1 - sigma^2), the principal value is (1 - xi^2) G0 + pi xi, where the
Glauert integral G0 = PV int_0^pi dphi/(cos(phi') - cos(phi)) (s = cos phi') vanishes. SymPy
shows G0 = 0 with t = tan(phi'/2), an explicit antiderivative and the symmetric limit around
the pole (for a simple pole the principal value does not depend on which smooth variable the
excision is symmetric in). This gives p0 = E* a/(2R); the force per length is the integral
of the pressure, F/L = pi a p0/2.

The chapter defines the depth by a = sqrt(R d) (5.35), a convention (the true approach of two
cylinders depends logarithmically on their size): then F = (pi/4) E* L d (5.34) and the three
forms of p0 (5.37). The third form is printed without a factor pi: p0 = (E* F/(pi L R))^(1/2).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, R, a, d, p0, symbol

TEST = "tests/test_line.py"

L = symbol("L")
x = symbol("x", real=True)


@cache
def glauert_zero() -> sp.Expr:
    """G0 = PV int_0^pi dphi'/(cos(phi') - cos(phi)), 0 < phi < pi, by t = tan(phi'/2)."""
    t, tau, eps = sp.symbols("t tau epsilon", positive=True)  # tau = tan(phi/2)
    c = (1 - tau**2) / (1 + tau**2)  # cos(phi)
    cos_p = (1 - t**2) / (1 + t**2)  # cos(phi')
    integrand = sp.simplify(1 / (cos_p - c) * 2 / (1 + t**2))  # dphi' = 2 dt/(1 + t^2)
    A = sp.integrate(integrand, t)
    assert sp.simplify(sp.diff(A, t) - integrand) == 0
    pv = sp.limit(A.subs(t, tau - eps) - A.subs(t, 0) + sp.limit(A, t, sp.oo)
                  - A.subs(t, tau + eps), eps, 0)
    return sp.simplify(pv)


@cache
def hilbert_of_ellipse() -> tuple[sp.Expr, sp.Symbol]:
    """PV int_-1^1 sqrt(1 - sigma^2)/(xi - sigma) d sigma for |xi| < 1."""
    xi, sig = sp.Symbol("xi", real=True), sp.Symbol("sigma", real=True)
    w = sp.sqrt(1 - sig**2)
    singular = (1 - xi**2) / ((xi - sig) * w)
    regular = (xi + sig) / w
    assert sp.simplify(w / (xi - sig) - singular - regular) == 0
    # int_-1^1 d sigma/((xi - sigma) sqrt(1 - sigma^2)) = -G0 (sigma = cos phi')
    sp_ = sp.Symbol("sigma_p", positive=True)
    reg = sp.integrate(regular.subs(sig, sp_), (sp_, 0, 1)) + sp.integrate(
        regular.subs(sig, -sp_), (sp_, 0, 1))
    return sp.simplify((1 - xi**2) * (-glauert_zero()) + reg), xi


@cache
def solution() -> dict[str, sp.Expr]:
    # the line-load kernel: x-derivative of (5.7) integrated along the line y
    y, xs = sp.Symbol("y", real=True), sp.Symbol("x_s", positive=True)
    kernel = sp.integrate(sp.diff(1 / (sp.pi * E_star * sp.sqrt(xs**2 + y**2)), xs),
                          (y, -sp.oo, sp.oo))  # du/dx of a unit line load at distance x > 0
    assert sp.simplify(kernel + 2 / (sp.pi * E_star * xs)) == 0
    H, xi = hilbert_of_ellipse()
    # du/dx = -(2/(pi E*)) PV int p(s)/(x - s) ds, p = p0 sqrt(1 - s^2/a^2), s = a sigma
    dudx = -2 / (sp.pi * E_star) * p0 * H.subs(xi, x / a)
    (p0_a,) = sp.solve(sp.Eq(sp.simplify(dudx), -x / R), p0)  # must hold for every |x| < a
    assert not p0_a.has(x)
    sigma = sp.Symbol("sigma", positive=True)
    F_L = sp.simplify(2 * sp.integrate(p0_a * sp.sqrt(1 - sigma**2) * a, (sigma, 0, 1)))
    a_d = sp.sqrt(R * d)  # (5.35): the chapter's definition of the depth
    force = sp.simplify(L * F_L.subs(a, a_d))
    (a_F,) = [s for s in sp.solve(sp.Eq(F, L * F_L), a) if s.is_positive]
    (d_F,) = sp.solve(sp.Eq(F, force), d)
    return {"p0_a": p0_a, "F_L": F_L, "a": a_d, "F": force, "a_F": a_F, "d_F": d_F,
            "p0_ad": sp.simplify(p0_a.subs(R, a**2 / d)),
            "p0_d": sp.simplify(p0_a.subs(a, a_d)),
            "p0_F": sp.simplify(p0_a.subs(a, a_F))}


def relations() -> list[Relation]:
    s = solution()
    half = sp.Rational(1, 2)
    pressure = s["p0_d"] * sp.sqrt(sp.Max(0, 1 - x**2 / s["a"] ** 2))  # (5.36)
    return [
        Relation("line_max_pressure_from_half_width", "(5.37), from the matching", s["p0_a"],
                 (E_star, R, a),
                 "maximum pressure p0 [Pa] of a line contact of half-width a",
                 "the gradient of the 2-D surface displacement matched to -x/R",
                 f"{TEST}::test_line_by_displacement_gradient"),
        Relation("line_force_per_length_from_half_width", "(5.34), from the matching",
                 s["F_L"], (E_star, R, a),
                 "normal force per unit length F/L [N/m] of a line contact of half-width a",
                 "the integral of (5.36) over the strip",
                 f"{TEST}::test_line_by_displacement_gradient"),
        Relation("line_half_width", "(5.35)", s["a"], (R, d),
                 "half-width a [m] of a line contact at the (conventional) depth d",
                 "the chapter's definition of the depth of a line contact",
                 f"{TEST}::test_line_by_displacement_gradient", printed=sp.sqrt(R * d)),
        Relation("line_force", "(5.34)", s["F"], (E_star, L, d),
                 "normal force F [N] of a line contact of length L at the depth d of (5.35)",
                 "F/L of the matched pressure with a = sqrt(R d)",
                 f"{TEST}::test_line_by_displacement_gradient",
                 printed=sp.pi / 4 * E_star * L * d),
        Relation("line_stiffness", "(5.34), differentiated", sp.diff(s["F"], d), (E_star, L),
                 "differential stiffness dF/dd [N/m] of a line contact of length L (with d "
                 "defined by (5.35))", "the derivative of (5.34)",
                 f"{TEST}::test_line_stiffness_by_derivative"),
        Relation("line_depth_from_force", "(5.34), inverted", s["d_F"], (E_star, F, L),
                 "depth d [m] (in the sense of (5.35)) of a line contact under the force F",
                 "(5.34) solved for d", f"{TEST}::test_line_by_displacement_gradient"),
        Relation("line_half_width_from_force", "(5.34), (5.35)", s["a_F"], (E_star, F, L, R),
                 "half-width a [m] of a line contact of length L under the force F",
                 "F = L F/L(a) solved for a", f"{TEST}::test_line_by_displacement_gradient"),
        Relation("line_max_pressure_depth_width", "(5.37), first form", s["p0_ad"],
                 (E_star, a, d), "maximum pressure p0 [Pa] of a line contact from its depth "
                 "and half-width", "the matching, with R = a^2/d (5.35)",
                 f"{TEST}::test_line_by_displacement_gradient",
                 printed=E_star * d / (2 * a)),
        Relation("line_max_pressure", "(5.37), second form", s["p0_d"], (E_star, R, d),
                 "maximum pressure p0 [Pa] of a line contact at the depth d of (5.35)",
                 "the matching, with a = sqrt(R d) (5.35)",
                 f"{TEST}::test_line_by_displacement_gradient",
                 printed=E_star / 2 * (d / R) ** half),
        Relation("line_max_pressure_from_force", "(5.37), third form", s["p0_F"],
                 (E_star, F, L, R),
                 "maximum pressure p0 [Pa] of a line contact of length L under the force F",
                 "the matching, with a from F = L F/L(a)",
                 f"{TEST}::test_line_by_displacement_gradient",
                 printed=(E_star * F / (L * R)) ** half,
                 erratum="a factor pi is missing under the root: p0 = (E* F/(pi L R))^(1/2) "
                 "(from p0 = E* a/(2R) and F/L = pi a p0/2; the print is sqrt(pi) = 1.77 "
                 "times too large)"),
        Relation("line_pressure", "(5.36)", pressure, (E_star, R, d, x),
                 "pressure p(x) [Pa] of a line contact at the depth d of (5.35) (0 outside)",
                 "(5.36) with the matched p0", f"{TEST}::test_line_by_displacement_gradient"),
    ]
