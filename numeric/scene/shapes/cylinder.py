"""A cylinder: curved across its axis, straight along it."""

from __future__ import annotations

import math

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class Cylinder(Shape):
    name = "cylinder"
    doc = "curved across its axis"
    keys = (Key("radius", "length", doc="R (negative: concave)", rule="nonzero"),
            Key("axis", "angle", required=False,
                doc="angle of the axis in the contact plane, default 0"),
            Key("length", "length", required=False,
                doc="the length of a line contact (parallel cylinders)"))
    kinds = ("quadratic",)

    def principal(self, p):
        return p["radius"], math.inf, p.get("axis", 0.0) + math.pi / 2
