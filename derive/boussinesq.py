"""Boussinesq: a normal point force on the elastic half-space, (5.1)-(5.6) and (5.41)-(5.46).

Starting point: the displacement field (5.1)-(5.3) of a force F acting at the origin in +z, into
the body, which fills z > 0 (Landau & Lifshitz, Theory of Elasticity, section 8). It is the given
solution and the only thing typed in besides the chapter's printed forms.

- The surface displacements (5.4)-(5.6) are its z -> 0 limit (the field is continuous at z = 0
  away from the origin, so the limit is the substitution z = 0).
- The stresses (5.41)-(5.46) follow from the small-strain tensor eps = (grad u + grad u^T)/2 and
  Hooke's law sigma = lambda tr(eps) I + 2 mu eps with lambda = E nu/((1 + nu)(1 - 2 nu)),
  mu = E/(2(1 + nu)); sigma > 0 is tension. SymPy writes x^2 + y^2 + z^2 = R^2 back into the
  numerators to get compact forms.
- ``tests/test_boussinesq.py`` checks symbolically that the stress field is in equilibrium
  (div sigma = 0), that the surface z = 0 is traction-free away from the origin, and that every
  plane z = c carries the force F (the integral of sigma_zz over it is -F).

The derivation finds the shear stresses tau_xz (5.46) and tau_yz (5.45) with the opposite sign
of the print: with the force pointing into the body, tau_xz = -3 F x z^2/(2 pi R^5).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E, F, nu, symbol

x = symbol("x", real=True)
y = symbol("y", real=True)
z = symbol("z", nonnegative=True)
_R = sp.Symbol("R_dist", positive=True)  # stands for sqrt(x^2 + y^2 + z^2) while simplifying

TEST = "tests/test_boussinesq.py"
COORDS = (x, y, z)
COMPONENTS = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "xy": (0, 1), "yz": (1, 2),
              "xz": (0, 2)}


def distance() -> sp.Expr:
    return sp.sqrt(x**2 + y**2 + z**2)


def displacement() -> list[sp.Expr]:
    """(5.1)-(5.3): the displacement of the point force F in +z at the origin (given)."""
    r = distance()
    c = (1 + nu) / (2 * sp.pi * E) * F
    return [c * (x * z / r**3 - (1 - 2 * nu) * x / (r * (r + z))),  # (5.1)
            c * (y * z / r**3 - (1 - 2 * nu) * y / (r * (r + z))),  # (5.2)
            c * (2 * (1 - nu) / r + z**2 / r**3)]  # (5.3)


def lame() -> tuple[sp.Expr, sp.Expr]:
    """Lame's lambda and mu from E and nu."""
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def _compact(expr: sp.Expr) -> sp.Expr:
    """Write sqrt(x^2 + y^2 + z^2) as R, reduce y^2 = R^2 - x^2 - z^2 in the numerator."""
    e = sp.together(expr.subs(distance(), _R))
    num, den = sp.fraction(e)
    for _ in range(2):  # y^4 -> (R^2 - x^2 - z^2)^2 needs the substitution twice
        num = sp.expand(sp.expand(num).subs(y**2, _R**2 - x**2 - z**2))
    return sp.factor(num) / sp.factor(den)


@cache
def stress_tensor() -> tuple[tuple[sp.Expr, ...], ...]:
    """sigma_ij of the point force from (5.1)-(5.3) by the strain tensor and Hooke's law."""
    u = displacement()
    lam, mu = lame()
    eps = [[(sp.diff(u[i], COORDS[j]) + sp.diff(u[j], COORDS[i])) / 2 for j in range(3)]
           for i in range(3)]
    trace = sum(eps[i][i] for i in range(3))
    sig = [[lam * trace * int(i == j) + 2 * mu * eps[i][j] for j in range(3)] for i in range(3)]
    return tuple(tuple(row) for row in sig)


@cache
def stresses() -> dict[str, sp.Expr]:
    """The six components, compact (R written back as sqrt(x^2 + y^2 + z^2))."""
    sig = stress_tensor()
    return {k: _compact(sig[i][j]).subs(_R, distance()) for k, (i, j) in COMPONENTS.items()}


def printed_stresses() -> dict[str, sp.Expr]:
    """(5.41)-(5.46) as the chapter prints them."""
    r = distance()
    k = F / (2 * sp.pi)
    common = (r**2 - r * z - z**2) / (r**3 * (r + z))
    return {
        "xx": k * (-3 * x**2 * z / r**5
                   + (1 - 2 * nu) * (x**2 * (2 * r + z) / (r**3 * (r + z) ** 2) - common)),
        "yy": k * (-3 * y**2 * z / r**5
                   + (1 - 2 * nu) * (y**2 * (2 * r + z) / (r**3 * (r + z) ** 2) - common)),
        "zz": -3 * F / (2 * sp.pi) * z**3 / r**5,
        "xy": k * (-3 * x * y * z / r**5 + (1 - 2 * nu) * x * y * (2 * r + z)
                   / (r**3 * (r + z) ** 2)),
        "yz": 3 * F / (2 * sp.pi) * y * z**2 / r**5,
        "xz": 3 * F / (2 * sp.pi) * x * z**2 / r**5,
    }


def relations() -> list[Relation]:
    u = displacement()
    surface = [sp.factor(sp.simplify(c.subs(z, 0))) for c in u]  # (5.4)-(5.6): z -> 0
    rs = sp.sqrt(x**2 + y**2)
    k = (1 + nu) * (1 - 2 * nu) / (2 * sp.pi * E)
    printed_surface = [-k * x / rs**2 * F, -k * y / rs**2 * F,
                       (1 - nu**2) / (sp.pi * E) / rs * F]
    rels = []
    for i, (comp, eq) in enumerate(zip("xyz", ("(5.1)", "(5.2)", "(5.3)"), strict=True)):
        rels.append(Relation(
            f"boussinesq_u{comp}", eq, u[i], (E, F, nu, x, y, z),
            f"displacement u_{comp} [m] at (x, y, z) of a point force F in +z at the origin",
            "the given solution (Landau & Lifshitz, section 8)",
            f"{TEST}::test_stress_from_displacement_in_equilibrium"))
    for i, (comp, eq) in enumerate(zip("xyz", ("(5.4)", "(5.5)", "(5.6)"), strict=True)):
        rels.append(Relation(
            f"boussinesq_surface_u{comp}", eq, surface[i], (E, F, nu, x, y),
            f"surface displacement u_{comp} [m] at (x, y, 0) of a point force F in +z at "
            "the origin", "(5.1)-(5.3) at z -> 0",
            f"{TEST}::test_surface_displacement_is_the_limit", printed=printed_surface[i]))
    # the surface Green's function of one elastic body under a rigid one: u_z rho/F at z = 0
    # (5.6) with E = E* (1 - nu^2), E* = E/(1 - nu^2) of that body (5.8)
    E_star = symbol("E_star")
    prefactor = sp.simplify((surface[2] * rs / F).subs(E, E_star * (1 - nu**2)))
    assert not prefactor.has(x, y, nu), prefactor
    rels.append(Relation(
        "boussinesq_surface_prefactor", "(5.7)", prefactor, (E_star,),
        "prefactor 1/(pi E*) [1/Pa] of the surface Green's function: u_z = F/(pi E* rho)",
        "(5.6) times rho/F with E/(1 - nu^2) = E*",
        f"{TEST}::test_surface_prefactor_against_the_point_force"))
    printed = printed_stresses()
    numbers = {"xx": "(5.41)", "yy": "(5.42)", "zz": "(5.43)", "xy": "(5.44)", "yz": "(5.45)",
               "xz": "(5.46)"}
    sign = ("the sign: with the force F acting in +z (into the body, z > 0 in the body) the "
            "derivation gives tau_{c}z = -3 F {c} z^2/(2 pi R^5); the print has +3 F {c} z^2/"
            "(2 pi R^5), which together with the printed (5.43) violates the equilibrium "
            "d(tau_xz)/dx + d(tau_yz)/dy + d(sigma_zz)/dz = 0")
    for comp, expr in stresses().items():
        erratum = sign.format(c=comp[0]) if comp in ("xz", "yz") else None
        rels.append(Relation(
            f"boussinesq_sigma_{comp}", numbers[comp], expr, (F, nu, x, y, z),
            f"stress sigma_{comp} [Pa] at (x, y, z) of a point force F in +z at the origin "
            "(tension positive)",
            "(5.1)-(5.3) by the small-strain tensor and Hooke's law",
            f"{TEST}::test_stress_from_displacement_in_equilibrium",
            printed=printed[comp], erratum=erratum))
    return rels
