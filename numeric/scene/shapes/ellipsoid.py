"""An ellipsoid's tip: a quadratic surface of principal radii R1, R2."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class Ellipsoid(Shape):
    name = "ellipsoid"
    doc = "principal radii R1, R2"
    keys = (Key("radii", "length_pair", doc="[R1, R2]", rule="nonzero_each"),
            Key("axis", "angle", required=False, doc="direction of R1, default 0"))
    kinds = ("quadratic",)

    def principal(self, p):
        R1, R2 = p["radii"]
        return R1, R2, p.get("axis", 0.0)
