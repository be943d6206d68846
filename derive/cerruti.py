"""Cerruti: a tangential point force on the elastic half-space, the tangential twin of Boussinesq.

Starting point: the displacement field of a force Q acting at the origin of the surface in +x,
the body filling z > 0 (Cerruti 1882; Johnson, Contact Mechanics, (3.86)), written with the
shear modulus G. It is the given solution, typed in once, as (5.1)-(5.3) are for Boussinesq;
the chapter does not print it.

- The surface displacements are its z -> 0 limit (the field is continuous at z = 0 away from
  the origin, so the limit is the substitution z = 0).
- ``tests/test_cerruti.py`` checks that the field is in equilibrium (div sigma = 0 with
  Hooke's law), that the surface z = 0 is traction-free away from the origin, that every plane
  z = h carries the force Q (the integral of tau_xz over it is -Q, with mpmath), and Betti's
  reciprocity with Boussinesq: u_z at (x, y) of the tangential force Q equals u_x at the origin
  of the normal force Q at (x, y), which fixes the sign of the (1 - 2 nu) term of u_z.
- :func:`angular_mean_compliance` averages the surface u_x over the direction: the
  axisymmetric part Q (2 - nu)/(4 pi G rho) of the compliance, which defines the tangential
  modulus G* of the MDR (derive/tangential.py) as E* is defined by the Boussinesq compliance
  F/(pi E* rho).
"""

from __future__ import annotations

import sympy as sp

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import nu, symbol

x = symbol("x", real=True)
y = symbol("y", real=True)
z = symbol("z", nonnegative=True)
G = symbol("G")
Q = symbol("Q")
rho = sp.Symbol("rho", positive=True)
phi = sp.Symbol("phi", real=True)

TEST = "tests/test_cerruti.py"


def distance() -> sp.Expr:
    return sp.sqrt(x**2 + y**2 + z**2)


def displacement() -> list[sp.Expr]:
    """The field of the tangential point force Q in +x at the origin (given, Johnson (3.86))."""
    r = distance()
    k = Q / (4 * sp.pi * G)
    return [k * (1 / r + x**2 / r**3 + (1 - 2 * nu) * (1 / (r + z) - x**2 / (r * (r + z) ** 2))),
            k * (x * y / r**3 - (1 - 2 * nu) * x * y / (r * (r + z) ** 2)),
            k * (x * z / r**3 + (1 - 2 * nu) * x / (r * (r + z)))]


def surface() -> list[sp.Expr]:
    """u_x, u_y, u_z at z = 0: the limit z -> 0 of :func:`displacement`."""
    return [sp.factor(sp.simplify(c.subs(z, 0))) for c in displacement()]


def angular_mean_compliance() -> sp.Expr:
    """(1/2 pi) integral_0^2pi u_x(rho cos phi, rho sin phi, 0) dphi per unit Q.

    SymPy finds (2 - nu)/(4 pi G rho)."""
    ux = surface()[0].subs({x: rho * sp.cos(phi), y: rho * sp.sin(phi)})
    mean = sp.integrate(sp.simplify(ux / Q), (phi, 0, 2 * sp.pi)) / (2 * sp.pi)
    return sp.factor(sp.simplify(mean))


def relations() -> list[Relation]:
    u = displacement()
    us = surface()
    rels = []
    for i, comp in enumerate("xyz"):
        rels.append(Relation(
            f"cerruti_u{comp}", "Cerruti (not in the chapter; Johnson (3.86))", u[i],
            (G, Q, nu, x, y, z),
            f"displacement u_{comp} [m] at (x, y, z) of a tangential point force Q in +x at "
            "the origin of the surface",
            "the given solution (Cerruti 1882; Johnson, Contact Mechanics, (3.86))",
            f"{TEST}::test_field_in_equilibrium_and_surface_traction_free"))
        rels.append(Relation(
            f"cerruti_surface_u{comp}", "Cerruti (not in the chapter; Johnson (3.87))", us[i],
            (G, Q, nu, x, y),
            f"surface displacement u_{comp} [m] at (x, y, 0) of a tangential point force Q in "
            "+x at the origin", "the Cerruti field at z -> 0",
            f"{TEST}::test_surface_is_the_limit_and_reciprocal_to_boussinesq"))
    return rels
