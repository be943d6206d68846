"""Contact kinds: one module per kind, each a :class:`~.base.Contact` subclass with one method per
effect it can compute, and :data:`KINDS`, the registry that says which bodies and loads make
which kind and how it is built.

A row of :data:`KINDS` applies to a scene when its load is among the row's ``loads`` and each
body's shape lists the row's name in its ``kinds`` (a flat partners any kind). The model takes
the first row that applies and calls its builder with a :class:`~.base.Setup`. A builder may
still refuse (two flat bodies have no contact point) with a SceneError that says why. Adding a
kind is adding a module and a row here (and the row's name to the shapes that make it).

The modules are imported only when a row builds its kind: a Hertz scene never imports the
numerical MDR, the BEM or the stress code.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass

from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Contact, Setup, State, Value

DEPTH_OR_FORCE = ("depth", "force")


@dataclass(frozen=True)
class Kind:
    """A row of the registry: which loads and shapes make the kind, and its builder.

    Attributes
    ----------
    name : str
        The row's name, listed in the ``kinds`` of the shapes that take part in it.
    loads : tuple of str
        The load kinds it accepts (``depth``, ``force``, ``impact``, ``pressure``).
    module, builder : str
        ``builder`` is a function of ``numeric/scene/kinds/<module>.py``: Setup -> Contact.
    needs : str
        The bodies it needs, in words: the error when a load only it accepts meets other shapes.
    """

    name: str
    loads: tuple[str, ...]
    module: str
    builder: str
    needs: str

    def build(self, setup: Setup) -> Contact:
        mod = importlib.import_module(f"hertzmdr.numeric.scene.kinds.{self.module}")
        return getattr(mod, self.builder)(setup)

    def takes(self, shapes) -> bool:
        """Whether two shapes make this kind: each lists it, or partners any kind (a flat),
        and at least one lists it."""
        return (all(self.name in s.kinds or s.partners_any for s in shapes)
                and any(self.name in s.kinds for s in shapes))


KINDS: tuple[Kind, ...] = (
    Kind("pressure", ("pressure",), "pressure", "build",
         "a prescribed pressure acts between two flat bodies (section 5.1); give both bodies "
         "shape = \"flat\""),
    Kind("impact", ("impact",), "hertz", "build_impact",
         "an impact scene is a sphere striking a flat wall (Problems 3 and 4)"),
    Kind("quadratic", DEPTH_OR_FORCE, "quadratic", "build",
         "two quadratic surfaces (flat, sphere, cylinder, ellipsoid)"),
    Kind("mdr", DEPTH_OR_FORCE, "axisym", "build_closed_form",
         "an axisymmetric profile with an MDR closed form on a flat body"),
    Kind("numerical_mdr", DEPTH_OR_FORCE, "axisym", "build_numerical",
         "a sampled axisymmetric profile on a flat body"),
    Kind("bem", DEPTH_OR_FORCE, "grid", "build",
         "a polygon_punch or height_map pressing on a flat body"),
)

__all__ = ["FIELD_POINTS", "KINDS", "Contact", "Kind", "Setup", "State", "Value"]
