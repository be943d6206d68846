"""A prescribed pressure p0 (1 - r^2/a^2)^n on a disc between two flat bodies: the direct
problem of section 5.1 ((5.9)-(5.17), Fig. 5.2, Problem 6). The displacements are those of
(5.7) with E* of (5.26): the approach of the two surfaces."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric.scene.kinds import CLOSED_FORM_RTOL, Contact, State, Value

FIELD_POINTS = 201

# distribution -> (inside u_z(E, a, p0, r), outside u_z(E, a, p0, r), force(a, p0), equation)
_FORMS = {
    "uniform": (gen.uniform_pressure_displacement, gen.uniform_pressure_displacement_outside,
                gen.uniform_pressure_force, "Problem 6"),
    "hertzian": (gen.hertz_pressure_displacement, gen.hertz_pressure_displacement_outside,
                 gen.hertz_pressure_force, "(5.16), Fig. 5.2"),
    "punch": (lambda E, a, p0, r: gen.punch_pressure_displacement(E, a, p0) + 0 * r,
              gen.punch_pressure_displacement_outside, gen.punch_pressure_force, "(5.10)"),
}


class PressureLoad(Contact):
    kind = "pressure"
    instead = {"contact_radius": "surface_displacement", "max_pressure": "pressure_profile"}
    why_not = {"contact_radius": "the loaded disc is given, not found: there is no contact "
               "problem to solve"}

    def __init__(self, E_star, rtol, distribution, p0, a):
        super().__init__(E_star, rtol)
        self.distribution, self.p0, self.a = distribution, p0, a
        self.inside, self.outside, self.total, self.eq = _FORMS[distribution]
        self.label = f"prescribed {distribution} pressure on a disc (section 5.1, {self.eq})"

    def info(self):
        return {**super().info(), "distribution": self.distribution, "p0": self.p0,
                "radius": self.a}

    def _u(self, r):
        r = np.asarray(r, dtype=float)
        out = np.empty(r.shape)
        ins = r <= self.a
        out[ins] = self.inside(self.E_star, self.a, self.p0, r[ins])
        out[~ins] = self.outside(self.E_star, self.a, self.p0, r[~ins])
        return out

    def state(self, load) -> State:
        d = np.atleast_1d(self._u(0.0))
        F = np.atleast_1d(self.total(self.a, self.p0))
        return State(d, F, CLOSED_FORM_RTOL, f"{self.eq} at r = 0", {})

    def effect_force(self, st):
        return Value(st.force, "the pressure integrated over the disc ((5.11), (5.17))",
                     CLOSED_FORM_RTOL)

    def effect_edge_displacement(self, st):
        return Value(float(self._u(self.a)), f"{self.eq} at r = a", CLOSED_FORM_RTOL)

    def effect_mean_pressure(self, st):
        return Value(float(st.force[0]) / (np.pi * self.a**2), "force / (pi a^2)",
                     CLOSED_FORM_RTOL)

    def effect_pressure_profile(self, st):
        """The prescribed load itself, p0 (1 - r^2/a^2)^n, zero outside the disc."""
        r = np.linspace(0.0, 1.5 * self.a, FIELD_POINTS)
        n = {"uniform": 0.0, "hertzian": 0.5, "punch": -0.5}[self.distribution]
        s = 1.0 - (r / self.a) ** 2
        p = np.zeros_like(r)
        p[s > 0] = self.p0 * s[s > 0] ** n
        return Value({"r": r, "p": p}, f"p0 (1 - r^2/a^2)^{n:g}", CLOSED_FORM_RTOL)

    def effect_surface_displacement(self, st):
        r = np.linspace(0.0, 4.0 * self.a, FIELD_POINTS)
        return Value({"r": r, "u": self._u(r)}, f"{self.eq}, inside and outside",
                     CLOSED_FORM_RTOL)
