"""Rigid indenters of any shape on a grid, solved by the half-space BEM (numeric/bem.py):
polygonal flat punches ((5.13)-(5.14)) and measured height maps.

The error estimate of each result is its difference from the same solve on a grid of half the
resolution (every other pixel): the BEM's error is set by the pixel size (first order in it for
areas and punch stiffnesses, second order for smooth indenters' forces, docs/non_axisymmetric.md).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric.scene.kinds import Contact, State, Value


class GridContact(Contact):
    kind = "bem"
    instead = {"contact_radius": "contact_area", "half_width": "contact_area",
               "semi_axes": "contact_area"}
    why_not = {"contact_radius": "the contact is not a circle: its area is",
               "max_pressure": "a flat punch's pressure is singular at its edge; on a grid its "
                               "largest value only measures the pixel size"}

    def __init__(self, E_star, rtol, height, dx, label, punch):
        super().__init__(E_star, rtol)
        self.height, self.dx, self.label, self.punch = height, dx, label, punch
        self.tol = min(rtol or 1e-8, 1e-6)

    def info(self):
        return {**super().info(), "grid": list(self.height.shape), "pixel_size": self.dx}

    def has(self, effect):
        if effect == "max_pressure" and self.punch:
            return False
        return super().has(effect)

    def _solve(self, height, dx, load_kind, value):
        from hertzmdr.numeric import bem

        return bem.solve(height, dx, self.E_star, tol=self.tol, **{load_kind: value})

    def state(self, load) -> State:
        fine, coarse = [], []
        for v in load.values:
            fine.append(self._solve(self.height, self.dx, load.kind, v))
            coarse.append(self._solve(self.height[::2, ::2], 2 * self.dx, load.kind, v))
        depth = np.array([s.depth for s in fine])
        force = np.array([s.force for s in fine])
        ref = np.array([(c.force if load.kind == "depth" else c.depth) for c in coarse])
        got = force if load.kind == "depth" else depth
        err = float(np.max(np.abs(got / ref - 1)))
        return State(depth, force, err, f"BEM on {self.height.shape[0]}x{self.height.shape[1]} "
                     f"pixels (rel_error: against half resolution)",
                     {"fine": fine, "coarse": coarse})

    def _both(self, st, fn, method):
        vals = np.array([fn(s) for s in st.extra["fine"]])
        ref = np.array([fn(s) for s in st.extra["coarse"]])
        return Value(vals, method, float(np.max(np.abs(vals / ref - 1))))

    def effect_contact_area(self, st):
        return self._both(st, lambda s: s.area, "BEM contact area (pixel count)")

    def effect_stiffness(self, st):
        return self._both(st, lambda s: s.stiffness, "BEM: flat punch of the contact area, "
                          "(5.13)")

    def effect_mean_pressure(self, st):
        return self._both(st, lambda s: s.force / s.area, "F / contact area")

    def effect_max_pressure(self, st):
        return self._both(st, lambda s: float(np.max(s.pressure)), "largest pixel pressure")


def polygon_punch(E_star, rtol, vertices, pixels):
    from hertzmdr.numeric import bem

    height, dx = bem.polygon_punch(vertices, pixels, margin=0.05)
    return GridContact(E_star, rtol, height, dx,
                       f"polygonal flat punch, {len(vertices)} corners (BEM, (5.13))", True)


def height_map(E_star, rtol, path, spacing):
    from hertzmdr.numeric import bem

    height = bem.read_height_map(path)
    return GridContact(E_star, rtol, height, spacing,
                       f"height map {height.shape[0]}x{height.shape[1]} (BEM)", False)
