"""Circular Hertz contact: two spheres, a sphere on a flat, crossed cylinders of equal radii at
90 degrees, any quadratic gap with equal principal curvatures; (5.15)-(5.27). A Hertz contact is
an axisymmetric contact (the paraboloid f = r^2/(2R)): its field effects are those of
:class:`~.axisym.Axisymmetric`, from the primitives of numeric/hertz.py, and its stresses the
closed forms. An impact scene (Problems 3-4) is a Hertz contact at its largest compression.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import hertz
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL, MOTION_RANGE
from hertzmdr.numeric.scene.kinds.axisym import Axisymmetric
from hertzmdr.numeric.scene.kinds.base import Setup, State, Value

IMPACT_EFFECTS = ("contact_time", "max_impact_depth", "max_impact_pressure")


class HertzContact(Axisymmetric):
    kind = "hertz"
    label = "circular Hertz contact (effective sphere on an elastic half-space)"
    method = "(5.23)"
    methods = {**Axisymmetric.methods, "contact_radius": "(5.21)",
               "mean_pressure": "(5.17)/(pi a^2)", "stiffness": "2 a E* (Problem 5)",
               "pressure_profile": "(5.15)", "surface_displacement":
               "(5.18) inside, Fig. 5.2 outside", "mdr_profile": "(5.52): g = x^2/R (5.19)"}
    off_axis = False
    curve_from_zero = True

    def __init__(self, materials, interface, rtol, R, principal_radii=None,
                 striker_radius=None):
        super().__init__(materials, interface, rtol)
        self.R = R
        self.principal = principal_radii if principal_radii is not None else [R, R]
        self.striker_radius = striker_radius  # the sphere of an impact scene, else None

    def info(self):
        return {**super().info(), "effective_radius": self.R, "principal_radii": self.principal}

    def ratios(self, nodes):
        """a/R and d/R at the largest load, or at an impact's largest compression."""
        if "state" in nodes:
            d = self.last(nodes["state"])
        elif "impact" in nodes:
            d = nodes["impact"]["closed"]["depth"]
        else:
            return {}
        return {"a/R": self.a_at(d) / self.R, "d/R": d / self.R}

    def rtol_ranges(self, effects):
        out = [(self.state_method, self.state_range)]
        out += self.stress_ranges(effects, closed=True)
        if any(e in IMPACT_EFFECTS for e in effects):
            out.append(("the impact's equation of motion (numeric/motion.py)", MOTION_RANGE))
        return out

    # -- the primitives of an axisymmetric contact (numeric/hertz.py) -----------------------
    def tangential_profile(self, d):
        """The paraboloid of radius R (Cattaneo-Mindlin); None for an impact's striker."""
        from hertzmdr.numeric import tangential as tg

        return tg.Paraboloid(self.R)

    def radius(self, d):
        return hertz.contact_radius(d, self.R)

    def force_of(self, d):
        return hertz.force(d, self.R, self.E_star)

    def depth_of(self, F):
        return hertz.depth_from_force(F, self.R, self.E_star)

    def p(self, r, d):
        return hertz.pressure(r, d, self.R, self.E_star)

    def u(self, r, d):
        return hertz.surface_displacement(r, d, self.R)

    def effect_force_law(self):
        """F = (4/3) E* R^(1/2) d^(3/2) (5.23) as K and n (numeric/force_law.py)."""
        from hertzmdr.numeric import force_law

        return self.law_value(force_law.hertz(self.R, self.E_star), "(5.23)", self.rel)

    def g(self, x):
        from hertzmdr.numeric import powerlaw

        # the paraboloid f = r^2/(2R) (5.19) is the power law n = 2 with c = 1/(2R)
        return powerlaw.g_profile(x, 0.5 / self.R, 2.0)

    @staticmethod
    def _mass(load):
        return {"m": load.mass} if load.mass is not None else {"rho": load.density}

    def state(self, load) -> State:
        if load.kind == "impact":  # the contact at its largest compression
            from hertzmdr.numeric import impact

            d = np.atleast_1d(impact.max_depth(load.velocity, self.R, self.E_star,
                                               **self._mass(load)))
            return State(d, hertz.force(d, self.R, self.E_star), CLOSED_FORM_RTOL,
                         "Problem 3 (largest compression)")
        if load.kind == "depth":
            return super().state(load)
        return State(hertz.depth_from_force(np.asarray(load.values, float), self.R,
                                            self.E_star),
                     np.asarray(load.values, float), CLOSED_FORM_RTOL, "(5.23) inverted")

    def stress_solver(self, st):
        from hertzmdr.numeric.scene.kinds.stresses import HertzStresses

        d = self.last(st)
        return HertzStresses(float(hertz.contact_radius(d, self.R)),
                             float(hertz.max_pressure(d, self.R, self.E_star)),
                             self.materials.stressed.nu)

    def effect_effective_radius(self):
        return Value(self.R, "(5.27)", CLOSED_FORM_RTOL)

    def effect_principal_radii(self):
        return Value(list(self.principal), "eigenvalues of the gap's quadratic form",
                     CLOSED_FORM_RTOL)

    def effect_max_pressure(self, st):
        return Value(hertz.max_pressure(st.depth, self.R, self.E_star), "(5.22)", st.rel_error)

    def effect_mean_pressure(self, st):
        return Value(hertz.mean_pressure(st.depth, self.R, self.E_star),
                     self.methods["mean_pressure"], st.rel_error)

    def effect_stiffness(self, st):
        return Value(hertz.stiffness(st.depth, self.R, self.E_star), self.methods["stiffness"],
                     st.rel_error)

    def effect_elastic_energy(self, st):
        return Value(hertz.energy(st.depth, self.R, self.E_star), "(5.25)", st.rel_error)

    # -- impact (Problems 3-4) ---------------------------------------------------------------
    def node_impact(self, run):
        """Closed forms of Problems 3 and 4, and the equation of motion integrated to the
        scene's rtol to check them (numeric/motion.py)."""
        from hertzmdr.numeric import impact, motion

        load = run.spec.load
        kw = self._mass(load)
        m = load.mass if load.mass is not None else \
            float(impact.sphere_mass(self.striker_radius, load.density))
        mo = motion.integrate(load.velocity, self.R, self.E_star, m, rtol=self.rtol)
        closed = {"time": float(impact.contact_time(load.velocity, self.R, self.E_star, **kw)),
                  "depth": float(impact.max_depth(load.velocity, self.R, self.E_star, **kw)),
                  "pressure": float(impact.max_pressure(load.velocity, self.R, self.E_star,
                                                        **kw))}
        return {"closed": closed, "motion": mo}

    def _impact_value(self, imp, key, numeric):
        dev = abs(numeric / imp["closed"][key] - 1)
        return Value(imp["closed"][key],
                     f"closed form (Problems 3-4); the equation of motion (DOP853, rtol "
                     f"{imp['motion'].rtol:g}) agrees to {dev:.1e}", max(CLOSED_FORM_RTOL, dev))

    def effect_contact_time(self, imp):
        return self._impact_value(imp, "time", imp["motion"].contact_time)

    def effect_max_impact_depth(self, imp):
        return self._impact_value(imp, "depth", imp["motion"].max_depth)

    def effect_max_impact_pressure(self, imp):
        p = float(hertz.max_pressure(imp["motion"].max_depth, self.R, self.E_star))  # (5.22)
        return self._impact_value(imp, "pressure", p)


def build_impact(setup: Setup) -> HertzContact:
    """Problems 3-4: a sphere strikes a fixed flat wall."""
    shapes = sorted(b.shape for b in setup.spec.bodies)
    if shapes != ["flat", "sphere"]:
        setup.fail("load.impact", "an impact scene is a sphere striking a flat wall (Problems 3 "
                   f"and 4); this one has {' and '.join(shapes)}")
    R = next(b for b in setup.spec.bodies if b.shape == "sphere").params["radius"]
    if R <= 0:
        setup.fail("body", "the striking sphere must be convex (radius > 0)")
    return HertzContact(setup.materials, setup.interface, setup.rtol, R=R, striker_radius=R)
