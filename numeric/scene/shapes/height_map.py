"""Any rigid indenter sampled on a regular grid, solved by the half-space BEM."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class HeightMap(Shape):
    name = "height_map"
    doc = "any rigid indenter on a regular grid; solved by the BEM"
    keys = (Key("file", "path", doc="`.npy`, `.csv` or whitespace text: heights in m, one grid "
                "row per line; `inf` or `nan` never touches"),
            Key("spacing", "length", doc="pixel size", rule="positive"))
    kinds = ("bem",)

    def check(self, p, fail, base_dir):
        super().check(p, fail, base_dir)
        path = base_dir / p["file"]
        if not path.is_file():
            fail("file", f"height map {str(path)!r} not found")
        p["file"] = str(path)

    def height(self, p):
        """(heights [m], pixel size [m], label, whether it is a punch) of the map."""
        from hertzmdr.numeric import bem

        height = bem.read_height_map(p["file"])
        return (height, p["spacing"], f"height map {height.shape[0]}x{height.shape[1]} (BEM)",
                False)
