"""Line contact of two parallel cylinders, (5.34)-(5.37): the 2-D Hertz problem, and the stresses
under it (plane strain, :class:`~.stresses.LineStresses`). The depth of
a line contact is defined by the chapter's convention a = sqrt(R d) (5.35); force-controlled
scenes avoid it."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import line
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import Contact, State, Value
from hertzmdr.numeric.scene.kinds.stresses import StressEffects


class LineContact(StressEffects, Contact):
    kind = "line"
    label = "line contact of parallel cylinders (5.34)-(5.37)"
    instead = {"contact_radius": "half_width", "semi_axes": "half_width",
               "surface_displacement": "pressure_profile"}
    why_not = {"contact_radius": "a line contact is a strip, not a circle",
               "semi_axes": "a line contact is a strip of half-width a",
               "surface_displacement": "the displacement of a line load diverges "
                                       "logarithmically: it depends on the size of the bodies"}

    def __init__(self, materials, interface, rtol, R, L):
        super().__init__(materials, interface, rtol)
        self.R, self.L = R, L

    def info(self):
        return {**super().info(), "effective_radius": self.R, "length": self.L}

    def ratios(self, nodes):
        """a/R, d/R and a/L at the largest load (a the half-width (5.35))."""
        st = nodes.get("state")
        if st is None:
            return {}
        d = self.last(st)
        a = self.extent(d)
        return {"a/R": a / self.R, "d/R": d / self.R, "a/L": a / self.L}

    def rtol_ranges(self, effects):
        from hertzmdr.numeric.scene.kinds.stresses import LineStresses

        return super().rtol_ranges(effects) + self.stress_ranges(effects, True,
                                                                  LineStresses.ranges)

    def stress_solver(self, st):
        """The line-contact stresses at the largest load (plane strain, the first elastic
        body's nu)."""
        from hertzmdr.numeric.scene.kinds.stresses import LineStresses

        F = self.last(st, "force")
        return LineStresses(float(line.half_width_from_force(F, self.L, self.R, self.E_star)),
                            float(line.max_pressure_from_force(F, self.L, self.R,
                                                               self.E_star)),
                            self.materials.stressed.nu)

    def state(self, load) -> State:
        v = np.asarray(load.values, dtype=float)
        if load.kind == "depth":
            return State(v, line.force(v, self.L, self.E_star), CLOSED_FORM_RTOL,
                         "(5.34) with d defined by (5.35)")
        return State(line.depth_from_force(v, self.L, self.E_star), v, CLOSED_FORM_RTOL,
                     "(5.34) inverted")

    def effect_effective_radius(self):
        return Value(self.R, "(5.27), (5.35)", CLOSED_FORM_RTOL)

    def effect_half_width(self, st):
        return Value(line.half_width_from_force(st.force, self.L, self.R, self.E_star),
                     "2-D Hertz, (5.35)", CLOSED_FORM_RTOL)

    def effect_max_pressure(self, st):
        return Value(line.max_pressure_from_force(st.force, self.L, self.R, self.E_star),
                     "(5.37) p0 = (E* F/(pi L R))^(1/2) (the print lacks the pi)",
                     CLOSED_FORM_RTOL)

    def effect_mean_pressure(self, st):
        from hertzmdr.numeric import contact

        a = line.half_width_from_force(st.force, self.L, self.R, self.E_star)
        return Value(contact.mean_pressure_strip(st.force, a, self.L), "F/(2 a L)",
                     CLOSED_FORM_RTOL)

    def effect_force_law(self):
        """F/L = (pi/4) E* d (5.34) per unit length, and F = K d for the length L."""
        from hertzmdr.numeric import force_law

        return self.law_value(force_law.line(self.E_star), "(5.34)", CLOSED_FORM_RTOL,
                              per_length=self.L)

    def effect_stiffness(self, st):
        return Value(np.full(np.shape(st.force), float(line.stiffness(self.L, self.E_star))),
                     "dF/dd of (5.34), under the convention (5.35)", CLOSED_FORM_RTOL)

    # -- the primitives of the force-depth curve and the pressure profile (base.Contact) -----
    curve_method = "(5.34), linear in d"
    pressure_method = "(5.36) across the strip (r is the distance x from its centre line)"

    def force_of(self, d):
        return line.force(d, self.L, self.E_star)

    def p(self, x, d):
        return line.pressure(x, d, self.R, self.E_star)

    def extent(self, d):
        return float(line.half_width(d, self.R))
