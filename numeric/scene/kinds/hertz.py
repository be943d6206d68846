"""Circular Hertz contact: two spheres, a sphere on a flat, crossed cylinders of equal radii at
90 degrees, any quadratic gap with equal principal curvatures; (5.15)-(5.27)."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import hertz
from hertzmdr.numeric.scene.kinds import CLOSED_FORM_RTOL, Contact, State, Value

FIELD_POINTS = 201


class HertzContact(Contact):
    kind = "hertz"
    label = "circular Hertz contact (effective sphere on an elastic half-space)"
    instead = {"half_width": "contact_radius", "semi_axes": "contact_radius"}

    def __init__(self, E_star, rtol, R, principal_radii=None):
        super().__init__(E_star, rtol)
        self.R = R
        self.principal = principal_radii if principal_radii is not None else [R, R]

    def info(self):
        return {**super().info(), "effective_radius": self.R, "principal_radii": self.principal}

    def state(self, load) -> State:
        v = np.asarray(load.values, dtype=float)
        if load.kind == "depth":
            return State(v, hertz.force(v, self.R, self.E_star), CLOSED_FORM_RTOL, "(5.23)", {})
        if load.kind == "force":
            return State(hertz.depth_from_force(v, self.R, self.E_star), v, CLOSED_FORM_RTOL,
                         "(5.23) inverted", {})
        raise ValueError(load.kind)

    def effect_effective_radius(self):
        return Value(self.R, "(5.27)", CLOSED_FORM_RTOL)

    def effect_principal_radii(self):
        return Value(list(self.principal), "eigenvalues of the gap's quadratic form",
                     CLOSED_FORM_RTOL)

    def effect_contact_radius(self, st):
        return Value(hertz.contact_radius(st.depth, self.R), "(5.21)", CLOSED_FORM_RTOL)

    def effect_max_pressure(self, st):
        return Value(hertz.max_pressure(st.depth, self.R, self.E_star), "(5.22)", CLOSED_FORM_RTOL)

    def effect_mean_pressure(self, st):
        return Value(hertz.mean_pressure(st.depth, self.R, self.E_star), "(5.17)/(pi a^2)",
                     CLOSED_FORM_RTOL)

    def effect_stiffness(self, st):
        return Value(hertz.stiffness(st.depth, self.R, self.E_star), "2 a E* (Problem 5)",
                     CLOSED_FORM_RTOL)

    def effect_elastic_energy(self, st):
        return Value(hertz.energy(st.depth, self.R, self.E_star), "(5.25)", CLOSED_FORM_RTOL)

    def effect_pressure_profile(self, st):
        d = self.last(st)
        a = float(hertz.contact_radius(d, self.R))
        r = np.linspace(0.0, 1.5 * a, FIELD_POINTS)
        return Value({"r": r, "p": hertz.pressure(r, d, self.R, self.E_star)}, "(5.15)",
                     CLOSED_FORM_RTOL)

    def effect_surface_displacement(self, st):
        d = self.last(st)
        a = float(hertz.contact_radius(d, self.R))
        r = np.linspace(0.0, 4.0 * a, FIELD_POINTS)
        return Value({"r": r, "u": hertz.surface_displacement(r, d, self.R)},
                     "(5.18) inside, Fig. 5.2 outside", CLOSED_FORM_RTOL)

    def effect_force_depth_curve(self, st):
        d = np.linspace(0.0, self.last(st), FIELD_POINTS)
        return Value({"depth": d, "force": hertz.force(d, self.R, self.E_star)}, "(5.23)",
                     CLOSED_FORM_RTOL)
