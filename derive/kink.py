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
    return {"g": g, "strength": strength, "p": E_star / sp.pi * integral}


def relations() -> list[Relation]:
    sol = solution()
    return [
        Relation("mdr_kink_pressure", "(5.59)", sol["p"], (E_star, a, b, r, s),
                 "pressure p(r) [Pa] of the branch-point term b s/sqrt(x^2 - b^2) of g' at a "
                 "kink r = b < a where f' jumps by s (log-infinite at r = b, 0 for r >= a)",
                 "(5.59) of the singular part of g' for f = s (r - b), r > b",
                 f"{TEST}::test_kink_pressure_by_quadrature",
                 domain={r: a * unit_interval(), b: a * unit_interval("t_b")}),
    ]
