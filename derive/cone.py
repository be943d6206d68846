"""Rigid cone on an elastic half-space, (5.38)-(5.40), by superposing flat punches.

Starting point: the flat punch of :mod:`hertzmdr.derive.pressures`, (5.9)-(5.12). The cone is
pressed in step by step (the argument of Problem 5): when the contact radius is a', a further
depth increment dd acts on the contact disc as a rigid flat punch of radius a'. By (5.10) that
punch carries the pressure (5.9) with p0 = E* dd/(pi a'), adds the force 2 a' E* dd (5.12), and
displaces the surface by dd inside r < a' and by the outside punch displacement (Fig. 5.2)
for r > a'. With dd = g(a') da', a surface point at r inside the final contact was lifted by
the increments with a' > r and by the outside field of those with a' < r; it must lie on the
cone, u_z(r) = d - r tan(theta). Since d = int_0^a g, this reads
int_0^r [1 - u_out(r; a')/dd] g(a') da' = r tan(theta) for every r, which fixes g (a power of a'
by dimensions: only a constant matches r^1) and with it d(a) (5.38). The force (5.40) and the
log-singular pressure (5.39) are the sums of the increments.

The chapter prints (5.39) with a minus sign: the pressure is positive in compression, as in
(5.9) and (5.15) (and Problem 7(c) of the chapter prints it without the sign): an erratum.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import pressures
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, a, d, p0, r, symbol, unit_interval

TEST = "tests/test_cone.py"

theta = symbol("theta", positive=True)


@cache
def solution() -> dict[str, sp.Expr]:
    half = sp.Rational(1, 2)
    ap, dd, rr = sp.symbols("a_p delta r_f", positive=True)  # a', increment, field point
    # the increment: a flat punch of radius a' pushed in by dd, (5.10) solved for p0
    (p0_inc,) = sp.solve(sp.Eq(pressures.displacement_inside(-half).subs(a, ap), dd), p0)
    dF = sp.simplify(pressures.force(-half).subs({a: ap, p0: p0_inc}))  # (5.11)
    assert sp.simplify(dF - 2 * ap * E_star * dd) == 0  # the stiffness (5.12)
    dp = p0_inc * (1 - rr**2 / ap**2) ** (-half)  # (5.9), for r < a'
    u_out = pressures.displacement_outside(-half).subs({a: ap, p0: p0_inc, r: rr})  # r > a'
    lag = sp.simplify(1 - u_out / dd)  # what an increment with a' < r lags behind dd
    # matching: int_0^r lag * g(a') da' = r tan(theta), with g = c a'^k
    c, k = sp.Symbol("c", positive=True), sp.Symbol("k", real=True)
    t = sp.Symbol("t", positive=True)  # a' = r t
    (k_val,) = sp.solve(sp.Eq(k + 1, 1), k)  # the power of r on the left is k + 1
    left = sp.integrate(sp.simplify(lag.subs(ap, rr * t)) * c * (rr * t) ** k_val * rr,
                        (t, 0, 1))
    (c_val,) = sp.solve(sp.Eq(sp.simplify(left), rr * sp.tan(theta)), c)
    g = c_val * ap**k_val  # dd/da'
    depth = sp.integrate(g, (ap, 0, a))  # (5.38)
    force_a = sp.integrate(dF.subs(dd, g), (ap, 0, a))
    # p(r) = int_r^a dp: with a' = r cosh(u) the integrand is smooth; a/r = 1 + B, B > 0
    u, B = sp.symbols("u B", positive=True)
    sub = rr * sp.cosh(u)
    integrand = sp.simplify((dp.subs(dd, g) * sp.diff(sub, u)).subs(ap, sub))
    pressure_a = sp.integrate(integrand, (u, 0, sp.acosh(1 + B)))
    pressure_a = pressure_a.subs(B, a / rr - 1).subs(rr, r)
    (a_d,) = sp.solve(sp.Eq(d, depth), a)
    force = sp.simplify(force_a.subs(a, a_d))
    # 0 < theta < pi/2: keep the root that is positive there
    (d_F,) = [s for s in sp.solve(sp.Eq(F, force), d)
              if s.subs({theta: sp.pi / 5, F: 1, E_star: 1}).is_positive]
    return {
        "depth": sp.simplify(depth), "a": sp.simplify(a_d), "F": force,
        "p_a": sp.simplify(pressure_a), "p": sp.simplify(pressure_a.subs(a, a_d)),
        "d_F": sp.simplify(d_F), "a_F": sp.simplify(a_d.subs(d, d_F)),
        "pm": sp.simplify(force_a / (sp.pi * a**2)), "k": sp.simplify(sp.diff(force, d)),
    }


def relations() -> list[Relation]:
    s = solution()
    a_d = s["a"]
    log_term = sp.log(a / r + sp.sqrt((a / r) ** 2 - 1))
    printed_p = (-E_star * d / (sp.pi * a) * log_term).subs(a, a_d)  # E/(1 - nu^2) = E* (5.8)
    return [
        Relation("cone_depth", "(5.38)", s["depth"], (a, theta),
                 "indentation depth d [m] of a rigid cone at the contact radius a",
                 "flat punches superposed to match the cone's surface",
                 f"{TEST}::test_cone_by_kernel",
                 printed=sp.pi / 2 * a * sp.tan(theta)),
        Relation("cone_contact_radius", "(5.38), Problem 7(c)", a_d, (d, theta),
                 "contact radius a [m] of a rigid cone at depth d",
                 "(5.38) solved for a", f"{TEST}::test_cone_by_kernel",
                 printed=2 / sp.pi * d / sp.tan(theta)),
        Relation("cone_force", "(5.40)", s["F"], (E_star, d, theta),
                 "normal force F [N] of a rigid cone at depth d",
                 "the forces 2 a' E* dd of the superposed punches",
                 f"{TEST}::test_cone_by_kernel",
                 printed=2 / sp.pi * E_star * d**2 / sp.tan(theta)),
        Relation("cone_pressure", "(5.39)", s["p"], (E_star, d, theta, r),
                 "contact pressure p(r) [Pa] of a rigid cone at depth d, for 0 < r <= a "
                 "(log-singular at r = 0)",
                 "the pressures (5.9) of the superposed punches",
                 f"{TEST}::test_cone_by_kernel", printed=printed_p,
                 erratum="the print has a spurious minus sign: the pressure is positive in "
                 "compression, p = E* d/(pi a) arccosh(a/r) with E* = E/(1 - nu^2), as (5.9), "
                 "(5.15) and the chapter's own Problem 7(c) have it",
                 stable=E_star * sp.tan(theta)
                 * sp.asinh(sp.sqrt(a_d - r) / sp.sqrt(2 * r)),
                 stable_why="arccosh(a/r) = 2 asinh(sqrt((a - r)/(2 r))): a/r overflows for a "
                 "flat cone (theta = 1e-300: a = 6e296 m) where the pressure is a float, and "
                 "arccosh of 1 + (a - r)/r loses the digits of a - r next to the rim",
                 domain={r: a_d * unit_interval()}),
        Relation("cone_depth_from_force", "(5.40), inverted", s["d_F"], (E_star, F, theta),
                 "indentation depth d [m] of a rigid cone under the force F",
                 "(5.40) solved for d", f"{TEST}::test_cone_by_kernel"),
        Relation("cone_contact_radius_from_force", "(5.38), (5.40)", s["a_F"],
                 (E_star, F, theta),
                 "contact radius a [m] of a rigid cone under the force F",
                 "(5.38) at the depth of (5.40) inverted", f"{TEST}::test_cone_by_kernel"),
        Relation("cone_mean_pressure", "(5.40)/(pi a^2)", s["pm"], (E_star, theta),
                 "mean pressure F/(pi a^2) [Pa] of a rigid cone (independent of the depth)",
                 "(5.40) divided by the contact area", f"{TEST}::test_cone_by_kernel"),
        Relation("cone_stiffness", "Problem 5", s["k"], (E_star, d, theta),
                 "differential stiffness dF/dd [N/m] of a rigid cone at depth d",
                 "the derivative of (5.40)", f"{TEST}::test_cone_by_kernel",
                 printed=2 * a_d * E_star),
    ]
