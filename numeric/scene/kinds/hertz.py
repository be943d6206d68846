"""Circular Hertz contact: two spheres, a sphere on a flat, crossed cylinders of equal radii at
90 degrees, any quadratic gap with equal principal curvatures; (5.15)-(5.27)."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import hertz
from hertzmdr.numeric.scene.kinds import CLOSED_FORM_RTOL, Contact, State, Value
from hertzmdr.numeric.scene.kinds.stresses import HertzStresses, StressEffects

FIELD_POINTS = 201


class HertzContact(StressEffects, Contact):
    kind = "hertz"
    label = "circular Hertz contact (effective sphere on an elastic half-space)"
    instead = {"half_width": "contact_radius", "semi_axes": "contact_radius"}

    def __init__(self, E_star, rtol, R, principal_radii=None, striker_radius=None):
        super().__init__(E_star, rtol)
        self.R = R
        self.principal = principal_radii if principal_radii is not None else [R, R]
        self.striker_radius = striker_radius  # the sphere of an impact scene, else None

    def info(self):
        return {**super().info(), "effective_radius": self.R, "principal_radii": self.principal}

    @staticmethod
    def _mass(load):
        return {"m": load.mass} if load.mass is not None else {"rho": load.density}

    def state(self, load) -> State:
        if load.kind == "impact":  # the contact at its largest compression
            from hertzmdr.numeric import impact

            d = np.atleast_1d(impact.max_depth(load.velocity, self.R, self.E_star,
                                               **self._mass(load)))
            return State(d, hertz.force(d, self.R, self.E_star), CLOSED_FORM_RTOL,
                         "Problem 3 (largest compression)", {})
        v = np.asarray(load.values, dtype=float)
        if load.kind == "depth":
            return State(v, hertz.force(v, self.R, self.E_star), CLOSED_FORM_RTOL, "(5.23)", {})
        if load.kind == "force":
            return State(hertz.depth_from_force(v, self.R, self.E_star), v, CLOSED_FORM_RTOL,
                         "(5.23) inverted", {})
        raise ValueError(load.kind)

    def stress_solver(self, st):
        d = self.last(st)
        return HertzStresses(float(hertz.contact_radius(d, self.R)),
                             float(hertz.max_pressure(d, self.R, self.E_star)), self.nu_body[1])

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

    def node_impact(self, run):
        """Closed forms of Problems 3 and 4, and the equation of motion integrated to check
        them (numeric/motion.py) at the scene's rtol (default 1e-10)."""
        from hertzmdr.numeric import _generated as gen
        from hertzmdr.numeric import impact, motion

        load = run.spec.load
        if load.kind != "impact":
            return None
        kw = self._mass(load)
        m = load.mass if load.mass is not None else \
            float(gen.impact_sphere_mass(self.striker_radius, load.density))
        rtol = self.rtol or 1e-10
        mo = motion.integrate(load.velocity, self.R, self.E_star, m, rtol=rtol)
        closed = {"time": float(impact.contact_time(load.velocity, self.R, self.E_star, **kw)),
                  "depth": float(impact.max_depth(load.velocity, self.R, self.E_star, **kw)),
                  "pressure": float(impact.max_pressure(load.velocity, self.R, self.E_star,
                                                        **kw))}
        return {"closed": closed, "motion": mo}

    def _impact_value(self, imp, key, numeric):
        if imp is None:
            raise ValueError("impact effects need [load.impact]")
        dev = abs(numeric / imp["closed"][key] - 1)
        return Value(imp["closed"][key],
                     f"closed form (Problems 3-4); the equation of motion (DOP853, rtol "
                     f"{imp['motion'].rtol:g}) agrees to {dev:.1e}", max(CLOSED_FORM_RTOL, dev))

    def effect_contact_time(self, imp):
        return self._impact_value(imp, "time", imp["motion"].contact_time if imp else 0)

    def effect_max_impact_depth(self, imp):
        return self._impact_value(imp, "depth", imp["motion"].max_depth if imp else 0)

    def effect_max_impact_pressure(self, imp):
        if imp is None:
            return self._impact_value(imp, "pressure", 0)
        p = float(hertz.max_pressure(imp["motion"].max_depth, self.R, self.E_star))  # (5.22)
        return self._impact_value(imp, "pressure", p)
