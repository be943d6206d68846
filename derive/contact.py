"""Relations every contact shares, whatever its profile: the mean pressure (force over the
contact area), the differential stiffness of an MDR contact and the flat punch's depth under a
force.

- The mean pressure is the force over the area of the contact: a disc of radius a ((5.17) for
  the Hertz pressure, Fig. 5.17 for the power laws), a strip of half-width a and length L (the
  line contact (5.34)-(5.37)), or any measured area A (the BEM's pixels in contact).
- The stiffness: (5.57) F(d) = 2 E* (d a - integral_0^a g(x) dx) with g(a) = d (5.55). Its
  derivative in d is 2 E* (a + d da/dd - g(a) da/dd) = 2 E* a: the terms in da/dd cancel, so
  the differential stiffness of every axisymmetric contact is that of the flat punch of its
  contact radius (5.12), Problem 5. The derivation below differentiates F(d(a)), a(d) for a
  generic g and lets SymPy do the cancellation.
- The flat punch's depth under a force: (5.11) F = 2 E* a d solved for d.
- The prescribed pressures p0 (1 - r^2/a^2)^n_p on a disc of section 5.1: n_p = 0 uniform
  (Problem 6), 1/2 Hertzian (5.15), -1/2 the punch's (5.9).
"""

from __future__ import annotations

import sympy as sp

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, a, d, p0, r, symbol, unit_interval

TEST = "tests/test_contact.py"
A = symbol("A")
L = symbol("L")
n_p = symbol("n_p", real=True)


def stiffness() -> sp.Expr:
    """dF/dd of (5.57) F = 2 E* (d a - integral_0^a g) at the contact radius a(d), g(a) = d."""
    g = sp.Function("g")
    aa = sp.Function("a")(d)  # the contact radius as a function of the depth
    xi = sp.Symbol("xi", positive=True)
    force = 2 * E_star * (d * aa - sp.Integral(g(xi), (xi, 0, aa)))  # (5.57)
    da_dd = sp.Symbol("da_dd")
    k = sp.diff(force, d).doit().subs(sp.Derivative(aa, d), da_dd)
    k = sp.expand(k.subs(g(aa), d).subs(aa, a))  # (5.55): g(a) = d
    if da_dd in k.free_symbols:
        raise AssertionError(f"the terms in da/dd did not cancel: {k}")
    return k


def punch_depth() -> sp.Expr:
    """(5.11) F = 2 E* a d solved for d."""
    (sol,) = sp.solve(sp.Eq(F, 2 * E_star * a * d), d)
    return sol


def relations() -> list[Relation]:
    return [
        Relation("contact_mean_pressure", "(5.17)", F / A, (A, F),
                 "mean pressure F/A [Pa] over a contact of area A",
                 "the definition of the mean pressure", f"{TEST}::test_mean_pressure_area"),
        Relation("disc_mean_pressure", "(5.17)", F / (sp.pi * a**2), (F, a),
                 "mean pressure F/(pi a^2) [Pa] over a circular contact of radius a",
                 "the definition of the mean pressure over a disc",
                 f"{TEST}::test_mean_pressure_disc"),
        Relation("strip_mean_pressure", "(5.34)-(5.37)", F / (2 * a * L), (F, L, a),
                 "mean pressure F/(2 a L) [Pa] over a contact strip of half-width a and length "
                 "L", "the definition of the mean pressure over a strip",
                 f"{TEST}::test_mean_pressure_strip"),
        Relation("mdr_stiffness", "(5.12), Problem 5", stiffness(), (E_star, a),
                 "differential normal stiffness dF/dd = 2 a E* [N/m] of an axisymmetric contact "
                 "of radius a", "dF/dd of (5.57) with d = g(a) (5.55)",
                 f"{TEST}::test_stiffness_by_differentiation", printed=2 * E_star * a),
        Relation("punch_depth_from_force", "(5.11), inverted", punch_depth(), (E_star, F, a),
                 "indentation depth d [m] of a flat rigid punch of radius a under the force F",
                 "(5.11) F = 2 E* a d solved for d", f"{TEST}::test_punch_round_trip"),
        Relation("disc_pressure", "(5.9), (5.15), Problem 6", p0 * (1 - r**2 / a**2) ** n_p,
                 (a, n_p, p0, r), "prescribed pressure p0 (1 - r^2/a^2)^n_p [Pa] on a disc of "
                 "radius a, r < a", "the distributions of section 5.1",
                 f"{TEST}::test_disc_pressure_force",
                 stable=p0 * ((a - r) * (a + r) / a**2) ** n_p,
                 stable_why="1 - r^2/a^2 cancels towards the edge r -> a (1e-13 at r = "
                 "0.9995 a); (a - r)(a + r)/a^2 does not",
                 domain={r: a * unit_interval()}),
    ]
