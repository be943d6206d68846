"""The shapes a ``[[body]]`` can have: one module per shape, one registry.

Each module defines a :class:`~.base.Shape` subclass: its keys (with how they are read and their
ranges), its checks, its geometry and the contact kinds it takes part in. :data:`SHAPES` is the
registry the schema reads the keys from and the model builds the contact from. Adding a shape is
adding a module and a row here.
"""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape
from hertzmdr.numeric.scene.shapes.cone import Cone
from hertzmdr.numeric.scene.shapes.cylinder import Cylinder
from hertzmdr.numeric.scene.shapes.ellipsoid import Ellipsoid
from hertzmdr.numeric.scene.shapes.exact_sphere import ExactSphere
from hertzmdr.numeric.scene.shapes.flat import Flat
from hertzmdr.numeric.scene.shapes.flat_punch import FlatPunch
from hertzmdr.numeric.scene.shapes.flattened_parabola import FlattenedParabola
from hertzmdr.numeric.scene.shapes.height_map import HeightMap
from hertzmdr.numeric.scene.shapes.polygon_punch import PolygonPunch
from hertzmdr.numeric.scene.shapes.power_law import PowerLaw
from hertzmdr.numeric.scene.shapes.profile import Profile
from hertzmdr.numeric.scene.shapes.pyramid import Pyramid
from hertzmdr.numeric.scene.shapes.sphere import Sphere

#: shape name -> the shape; the order is that of the docs' table
SHAPES: dict[str, Shape] = {s.name: s for s in (
    Flat(), Sphere(), Cylinder(), Ellipsoid(), Cone(), FlatPunch(), PowerLaw(),
    FlattenedParabola(), ExactSphere(), Pyramid(), Profile(), PolygonPunch(), HeightMap(),
)}

__all__ = ["SHAPES", "Key", "Shape"]
