"""A sphere, in the half-space approximation: the paraboloid z = r^2/(2R) of (5.19)."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class Sphere(Shape):
    name = "sphere"
    doc = "z = r²/(2R), the paraboloid of the Hertz theory (5.19)"
    keys = (Key("radius", "length", doc="R (negative: concave)", rule="nonzero"),)
    kinds = ("quadratic", "impact")

    def principal(self, p):
        return p["radius"], p["radius"], 0.0
