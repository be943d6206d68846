"""A kink of an axisymmetric profile in the MDR: the branch-point part of its pressure.

Starting point: a profile whose slope jumps by s = f'(b+) - f'(b-) at r = b, i.e. the part
f = s (r - b) for r > b added to a smooth profile. (5.52) gives its g(x) = s x acos(b/x)
(x > b), and g' has a square-root branch point at x = b of strength
B = lim_{x -> b} sqrt(x^2 - b^2) g'(x) = b s: g' = s acos(b/x) + b s / sqrt(x^2 - b^2). The
first part is continuous; the second, put through (5.59), is an incomplete elliptic integral of
the first kind (:func:`hertzmdr.derive.mdr.branch_point_integral`), log-infinite at r = b.

The numerical MDR (:mod:`hertzmdr.numeric.mdr`) adds this term analytically for every kink it
is told of (``breakpoints``), and integrates only the continuous remainder by quadrature.
For the worn paraboloid (Problem 8), s = b/R.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, a, r, symbol, unit_interval

b = symbol("b")
s = symbol("slope_jump", real=True)
x = mdr.x
TEST = "tests/test_kink.py"


@cache
def solution() -> dict[str, sp.Expr]:
    rr = sp.Symbol("rr", positive=True)
    # (5.52) of f = s (r - b), r > b: only (b, x) contributes
    g = sp.simplify(x * mdr._integrate(sp.diff(s * (rr - b), rr) / sp.sqrt(x**2 - rr**2),
                                       (rr, b, x)))
    gp = sp.diff(g, x)
    strength = sp.simplify(sp.limit(sp.sqrt(x**2 - b**2) * gp, x, b, "+"))
    integral = mdr.branch_point_integral(sp.S.Zero, strength, r, b, a)  # 0 for r >= a
    # the singular part of g' (x > b), factored at x -> b, and its integral from b
    gp_sing = strength / sp.sqrt((x - b) * (x + b))
    xx = sp.Symbol("xx", positive=True)
    g_sing = sp.simplify(mdr._integrate(gp_sing.subs(x, xx), (xx, b, x)))
    # its integral from b (the kink's part of integral_0^a g dx in (5.57)), by parts:
    # x g_sing(x) - integral_b^x y g_sing'(y) dy, the second in w = y^2 - b^2 (y dy = dw/2)
    w = sp.Symbol("w", positive=True)
    gp_w = (strength / sp.sqrt(x**2 - b**2)).subs(x, sp.sqrt(w + b**2))  # gp_sing at y
    G_sing = x * g_sing - mdr._integrate(gp_w / 2, (w, 0, (x - b) * (x + b)))
    assert sp.simplify(sp.diff(G_sing, x) - g_sing) == 0, G_sing
    assert sp.limit(G_sing, x, b, "+") == 0, G_sing
    return {"g": g, "strength": strength, "p": E_star / sp.pi * integral,
            "gp_sing": gp_sing, "g_sing": g_sing, "G_sing": G_sing}


def relations() -> list[Relation]:
    sol = solution()
    return [
        Relation("mdr_kink_pressure", "(5.59)", sol["p"], (E_star, a, b, r, s),
                 "pressure p(r) [Pa] of the branch-point term b s/sqrt(x^2 - b^2) of g' at a "
                 "kink r = b < a where f' jumps by s (log-infinite at r = b, 0 for r >= a)",
                 "(5.59) of the singular part of g' for f = s (r - b), r > b",
                 f"{TEST}::test_kink_pressure_by_quadrature",
                 domain={r: a * unit_interval(), b: a * unit_interval("t_b")}),
        Relation("mdr_kink_gprime", "(5.52)", sol["gp_sing"], (b, s, x),
                 "branch-point term b s/sqrt(x^2 - b^2) [1] of g'(x), x > b, at a kink r = b "
                 "where f' jumps by s",
                 "lim sqrt(x^2 - b^2) g'(x), x -> b, of (5.52) for f = s (r - b)",
                 f"{TEST}::test_kink_gprime_is_the_singular_part_of_52",
                 domain={x: b / unit_interval()}),
        Relation("mdr_kink_g", "(5.52)", sol["g_sing"], (b, s, x),
                 "integral from b to x > b [m] of the branch-point term of g' at a kink r = b",
                 "integral of mdr_kink_gprime", f"{TEST}::test_kink_g_by_quadrature",
                 stable=2 * b * s * sp.asinh(sp.sqrt((x - b) / (2 * b))),
                 stable_why="acosh of an argument 1 + (x - b)/(4b) loses digits as x -> b "
                 "(relative eps b/(x - b)); it is written 2 asinh(sqrt((x - b)/(2b)))",
                 domain={x: b / unit_interval()}),
        Relation("mdr_kink_G", "(5.57)", sol["G_sing"], (b, s, x),
                 "integral from b to x > b [m^2] of mdr_kink_g: the kink's part of the "
                 "integral of g in the force (5.57)",
                 "integral of mdr_kink_g by parts (x g - integral of y g')",
                 f"{TEST}::test_kink_G_by_quadrature",
                 stable=b * s * (2 * x * sp.asinh(sp.sqrt((x - b) / (2 * b)))
                                 - sp.sqrt((x - b) * (x + b))),
                 stable_why="acosh of an argument near 1 loses digits as x -> b (as in "
                 "mdr_kink_g); the two terms still cancel to a relative (x - b)/b, which is "
                 "rounding of the integral of g it is added to",
                 domain={x: b / unit_interval()}),
    ]
