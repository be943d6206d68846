"""Rigid indenters of any shape on a grid, solved by the half-space BEM (numeric/bem.py):
polygonal flat punches ((5.13)-(5.14)) and measured height maps.

The error bound of each result is Roache's grid convergence index of two grids: the relative
difference from the same solve on a grid of half the resolution (every other pixel) times
:data:`GCI_FACTOR`. The BEM's error is set by the pixel size, first order in it for areas and
punch stiffnesses (second order for smooth indenters' forces, docs/non_axisymmetric.md), so the
fine grid's error is about the difference / (2^1 - 1); the staircase of the contact's edge makes
the convergence irregular (the triangular punch of examples/: the difference 2.2e-3 against an
actual error of 3.3e-3 in its force), and Roache's safety factor 3 for a two-grid estimate covers
that (issue 12: a reported error must bound the actual one; tests/test_error_bounds.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric.scene.accuracy import BEM_RANGE
from hertzmdr.numeric.scene.kinds.base import Contact, Setup, State, Value

#: Roache's safety factor for a grid convergence index from two grids (P. J. Roache, J. Fluids
#: Eng. 116 (1994) 405), over 2^p - 1 = 1 for the first order p = 1 of the BEM's areas and
#: punch stiffnesses
GCI_FACTOR = 3.0


def relative_difference(got, ref) -> float:
    """The largest |got/ref - 1| over the load points, 0 where both are 0 (a point with no
    load: the two resolutions agree exactly), inf where only ref is 0."""
    got, ref = np.broadcast_arrays(np.asarray(got, float), np.asarray(ref, float))
    same = got == ref
    with np.errstate(divide="ignore"):
        diff = np.where(same, 0.0, np.abs(got - ref) / np.where(same, 1.0, np.abs(ref)))
    return float(np.max(diff))


@dataclass
class GridState(State):
    """The BEM's state: the solutions at the scene's grid and at half its resolution."""

    fine: list = field(default_factory=list)
    coarse: list = field(default_factory=list)


class GridContact(Contact):
    kind = "bem"
    instead = {"contact_radius": "contact_area", "half_width": "contact_area",
               "semi_axes": "contact_area"}
    why_not = {"contact_radius": "the contact is not a circle: its area is",
               "max_pressure": "a flat punch's pressure is singular at its edge; on a grid its "
                               "largest value only measures the pixel size",
               "force_depth_curve": "every depth is a BEM solve (two with the error estimate): "
                                    "ask for 'force' under a depth sweep instead",
               "pressure_profile": "the BEM's pressure is a map of pixels, not a profile "
                                   "along a line"}

    not_power_law = ("the BEM solves each depth on a grid and gives no coefficients of a "
                     "force law (ask for 'force' under a depth sweep)")
    state_method = "the BEM's conjugate gradients (numeric/bem.py)"
    state_range = BEM_RANGE

    def __init__(self, materials, interface, rtol, height, dx, label, punch):
        super().__init__(materials, interface, rtol)
        self.height, self.dx, self.label, self.punch = height, dx, label, punch

    def info(self):
        return {**super().info(), "grid": list(self.height.shape), "pixel_size": self.dx}

    def has(self, effect):
        if effect == "max_pressure" and self.punch:
            return False
        return super().has(effect)

    def _solve(self, height, dx, load_kind, value):
        from hertzmdr.numeric import bem

        return bem.solve(height, dx, self.E_star, tol=self.rtol, **{load_kind: value})

    def state(self, load) -> GridState:
        fine, coarse = [], []
        for v in load.values:
            fine.append(self._solve(self.height, self.dx, load.kind, v))
            coarse.append(self._solve(self.height[::2, ::2], 2 * self.dx, load.kind, v))
        depth = np.array([s.depth for s in fine])
        force = np.array([s.force for s in fine])
        ref = np.array([(c.force if load.kind == "depth" else c.depth) for c in coarse])
        got = force if load.kind == "depth" else depth
        err = GCI_FACTOR * relative_difference(got, ref)
        return GridState(depth, force, err, f"BEM on {self.height.shape[0]}x"
                         f"{self.height.shape[1]} pixels (rel_error: {GCI_FACTOR:g} times the "
                         "change from half resolution)",
                         fine, coarse)

    def _both(self, st, fn, method):
        vals = np.array([fn(s) for s in st.fine])
        ref = np.array([fn(s) for s in st.coarse])
        return Value(vals, method, GCI_FACTOR * relative_difference(vals, ref))

    def effect_contact_area(self, st):
        """The pixel count's area; its error is the larger of the change from half resolution
        and the band of pixels the edge can cut (:func:`bem.boundary_area`): the two pixel
        counts can scale alike and agree exactly while both miss the edge by a pixel."""
        from hertzmdr.numeric import bem

        v = self._both(st, lambda s: s.area, "BEM contact area (pixel count; rel_error: the "
                       f"edge's pixel band, or {GCI_FACTOR:g} times the change from half "
                       "resolution if larger)")
        band = max(bem.boundary_area(s.contact, s.dx, s.dy) / s.area if s.area > 0 else 0.0
                   for s in st.fine)
        return Value(v.value, v.method, max(v.rel_error, band))

    def effect_stiffness(self, st):
        return self._both(st, lambda s: s.stiffness, "BEM: flat punch of the contact area, "
                          "(5.13)")

    def effect_mean_pressure(self, st):
        from hertzmdr.numeric import contact

        return self._both(st, lambda s: float(contact.mean_pressure(s.force, s.area)),
                          "F / contact area")

    def effect_max_pressure(self, st):
        return self._both(st, lambda s: float(np.max(s.pressure)), "largest pixel pressure")


def build(setup: Setup) -> GridContact:
    """A polygonal punch or a height map (its shape's ``height``) on a flat: the BEM."""
    from hertzmdr.numeric.scene.shapes import SHAPES

    shaped = setup.shaped()
    if len(shaped) != 1:
        setup.fail("body", "a polygon_punch or height_map presses on a flat body: give the "
                   "other body shape = \"flat\"")
    body = shaped[0]
    try:
        height, dx, label, punch = SHAPES[body.shape].height(body.params)
    except ValueError as exc:
        setup.fail(f"body ({body.name})", str(exc))
    return GridContact(setup.materials, setup.interface, setup.rtol, height, dx, label, punch)
