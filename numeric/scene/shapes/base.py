"""What a shape module defines: its keys, their checks, its geometry and the kinds it makes.

A shape is a class with

- ``name``, ``doc`` (the surface, for docs/scenes.md) and ``keys``: :class:`Key` records giving
  each key's kind of value (read by :mod:`..schema`), whether it is required, and its range;
- ``kinds``: the names of the contact kinds (rows of :data:`..kinds.KINDS`) it takes part in,
  against a flat or a body that lists the same kind;
- ``check(params, fail, base_dir)`` for checks across keys (and files a key names);
- its geometry, one of: ``principal(params)`` -> (R1, R2, angle of R1) for a quadratic surface;
  ``closed_form(params)`` -> :class:`..kinds.axisym.ClosedForm` for an axisymmetric profile
  solved in closed form by the MDR; ``samples(params)`` for a sampled profile; ``height(params)``
  -> (heights, pixel size) for a height map solved by the BEM.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar, NoReturn

Fail = Callable[[str, str], NoReturn]

#: how a key's value is read (schema.py): a quantity with this dimension, or a structure
VALUE_KINDS = ("length", "angle", "number", "length_pair", "length_list", "lengths", "path",
               "points", "count", "length_unit", "integer", "name")


@dataclass(frozen=True)
class Key:
    """One key of a shape.

    Attributes
    ----------
    name : str
        The key in the ``[[body]]`` table.
    kind : str
        How its value is read, one of :data:`VALUE_KINDS` (lengths and angles take units).
    required : bool
        Whether the shape needs it.
    doc : str
        What it is, for docs/scenes.md.
    rule : str or None
        A range check on the SI value: ``"positive"`` (> 0), ``"nonzero"`` (a radius that may be
        negative, concave), ``"nonzero_each"`` (each of a list), or None.
    hint : str
        Added to the range error, e.g. what to use instead.
    unit : str
        The SI unit of a ``number`` key (result.json's echo): "m^(1-n)", "1".
    """

    name: str
    kind: str
    required: bool = True
    doc: str = ""
    rule: str | None = None
    hint: str = ""
    unit: str = "1"


class Shape:
    """Base of the shapes: the key checks every shape shares."""

    name: ClassVar[str]
    doc: ClassVar[str]
    keys: ClassVar[tuple[Key, ...]]
    kinds: ClassVar[tuple[str, ...]]
    #: a flat partners any kind: a shape that makes kind K does so against a flat
    partners_any: ClassVar[bool] = False

    def check(self, p: dict, fail: Fail, base_dir: Path) -> None:
        """Range checks of the keys' SI values (``p``), by each key's rule."""
        for key in self.keys:
            if key.name not in p or key.rule is None:
                continue
            v = p[key.name]
            hint = f" ({key.hint})" if key.hint else ""
            if key.rule == "positive" and not v > 0:
                fail(key.name, f"must be > 0, got {v}{hint}")
            if key.rule == "nonzero" and v == 0:
                fail(key.name, "must not be 0 (negative for a concave surface)")
            if key.rule == "nonzero_each" and any(x == 0 for x in v):
                fail(key.name, f"{key.name} must not be 0")
