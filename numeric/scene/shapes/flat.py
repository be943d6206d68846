"""A plane: the partner of every other shape, and the two flat bodies of a prescribed pressure."""

from __future__ import annotations

import math

from hertzmdr.numeric.scene.shapes.base import Shape


class Flat(Shape):
    name = "flat"
    doc = "a plane"
    keys = ()
    kinds = ("pressure", "quadratic")
    partners_any = True

    def principal(self, p):
        """A plane has no curvature: both principal radii are infinite."""
        return math.inf, math.inf, 0.0
