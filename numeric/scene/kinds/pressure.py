"""A prescribed pressure p0 (1 - r^2/a^2)^n on a disc between two flat bodies: the direct
problem of section 5.1 ((5.9)-(5.17), Fig. 5.2, Problem 6), by numeric/pressures.py. The
displacements are those of (5.7) with E* of (5.26): the approach of the two surfaces."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import pressures
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Contact, Setup, State, Value


class PressureLoad(Contact):
    kind = "pressure"
    instead = {"contact_radius": "surface_displacement", "max_pressure": "pressure_profile"}
    not_power_law = "the load is a prescribed pressure: there is no force-depth relation"
    why_not = {"contact_radius": "the loaded disc is given, not found: there is no contact "
               "problem to solve",
               "force_depth_curve": "the load is a prescribed pressure: its force and depth "
               "are one point, not a curve"}

    def __init__(self, materials, interface, rtol, distribution, p0, a):
        super().__init__(materials, interface, rtol)
        self.distribution, self.p0, self.a = distribution, p0, a
        self.n, self.eq = pressures.DISTRIBUTIONS[distribution]
        self.label = f"prescribed {distribution} pressure on a disc (section 5.1, {self.eq})"

    def info(self):
        return {**super().info(), "distribution": self.distribution, "p0": self.p0,
                "radius": self.a}

    def _u(self, r):
        return np.asarray(pressures.surface_displacement(r, self.distribution, self.p0, self.a,
                                                         self.E_star), float)

    def ratios(self, nodes):
        """d/a: the displacement of the centre over the disc's radius."""
        st = nodes.get("state")
        return {} if st is None else {"d/a": self.last(st) / self.a}

    def state(self, load) -> State:
        d = np.atleast_1d(self._u(0.0))
        F = np.atleast_1d(pressures.force(self.distribution, self.p0, self.a))
        return State(d, F, CLOSED_FORM_RTOL, f"{self.eq} at r = 0")

    def effect_force(self, st):
        return Value(st.force, "the pressure integrated over the disc ((5.11), (5.17))",
                     CLOSED_FORM_RTOL)

    def effect_edge_displacement(self, st):
        return Value(float(self._u(self.a)), f"{self.eq} at r = a", CLOSED_FORM_RTOL)

    def effect_mean_pressure(self, st):
        from hertzmdr.numeric import contact

        return Value(float(contact.mean_pressure_disc(st.force[0], self.a)), "force / (pi a^2)",
                     CLOSED_FORM_RTOL)

    # -- the primitives of the pressure profile (base.Contact): the prescribed load itself,
    # p0 (1 - r^2/a^2)^n, zero outside the disc
    @property
    def pressure_method(self):
        return f"p0 (1 - r^2/a^2)^{self.n:g}"

    def p(self, r, d):
        return pressures.pressure(r, self.distribution, self.p0, self.a)

    def extent(self, d):
        return self.a

    def effect_surface_displacement(self, st):
        r = np.linspace(0.0, 4.0 * self.a, FIELD_POINTS)
        return Value({"r": r, "u": self._u(r)}, f"{self.eq}, inside and outside",
                     CLOSED_FORM_RTOL)


def build(setup: Setup) -> PressureLoad:
    """Two flat bodies under a prescribed pressure (the row "pressure" checks the shapes)."""
    ld = setup.spec.load
    return PressureLoad(setup.materials, setup.interface, setup.rtol, ld.distribution, ld.p0,
                        ld.radius)
