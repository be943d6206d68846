"""A flat punch of any polygonal footprint, (5.13), solved by the half-space BEM."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class PolygonPunch(Shape):
    name = "polygon_punch"
    doc = "a flat punch of any polygonal footprint, (5.13); solved by the BEM"
    keys = (Key("vertices", "points", doc="[[x, y], ...] (at least 3 corners)"),
            Key("pixels", "count", required=False,
                doc="pixels along the longer side, default 128"))
    kinds = ("bem",)

    def height(self, p):
        """(heights [m], pixel size [m], label, whether it is a punch) of the footprint."""
        from hertzmdr.numeric import bem

        height, dx = bem.polygon_punch(p["vertices"], p.get("pixels", 128), margin=0.05)
        return (height, dx, f"polygonal flat punch, {len(p['vertices'])} corners (BEM, (5.13))",
                True)
