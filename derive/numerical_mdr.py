"""The MDR steps the numerical MDR (:mod:`hertzmdr.numeric.mdr`) takes for any profile.

The numerical MDR computes g(a) (5.52) and the integral of g by quadrature of the profile's
spline; the step that combines them is the chapter's (5.57), derived here by the same
:func:`hertzmdr.derive.mdr.force` that gives every closed-form force, applied to an undefined
g(x): its integral is left as the symbol ``g_integral`` and g(a) is d by (5.55).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, a, d, symbol

G_a = symbol("g_integral")
TEST = "tests/test_mdr.py"


@cache
def force() -> sp.Expr:
    """(5.57) for an undefined g: 2 E* (d a - g_integral)."""
    g = sp.Function("g")
    F = mdr.force(g(mdr.x))
    return sp.factor(F.replace(lambda e: isinstance(e, sp.Integral), lambda e: G_a)
                     .subs(g(a), d))


def relations() -> list[Relation]:
    return [
        Relation("mdr_force", "(5.57)", force(), (E_star, a, d, G_a),
                 "normal force F [N] of the MDR at the contact radius a and depth d = g(a), "
                 "from the integral of g over [0, a]",
                 "(5.57) with (5.55) for any g(x)",
                 f"{TEST}::test_mdr_force_by_the_pressure"),
    ]
