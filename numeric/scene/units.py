"""Quantities in scene files: a number in SI units, or a string with a unit parsed by pint.

pint takes about 0.7 s to import and build its registry, more than a whole closed-form scene
run, so the common unit strings are looked up in :data:`FAST` first; pint parses everything
else. ``tests/test_scene_units.py`` checks every entry of :data:`FAST` against pint.
"""

from __future__ import annotations

import math
import re
from functools import cache

# dimension name -> (SI unit string for pint, description)
DIMENSIONS = {
    "length": ("m", "a length"),
    "force": ("N", "a force"),
    "pressure": ("Pa", "a pressure or modulus"),
    "angle": ("rad", "an angle"),
    "mass": ("kg", "a mass"),
    "density": ("kg/m^3", "a density"),
    "velocity": ("m/s", "a velocity"),
    "surface_energy": ("J/m^2", "an energy per area (work of adhesion)"),
    "force_per_length": ("N/m", "a force per length (a force baseline's slope)"),
}

#: the SI prefixes, largest first: the one table for reading units (:data:`FAST`) and for
#: writing them (:func:`engineering` for the tables, :func:`prefixed` for the figures' axes)
PREFIXES: tuple[tuple[str, float], ...] = (
    ("T", 1e12), ("G", 1e9), ("M", 1e6), ("k", 1e3), ("", 1.0), ("c", 1e-2), ("m", 1e-3),
    ("µ", 1e-6), ("n", 1e-9), ("p", 1e-12), ("f", 1e-15))
#: other spellings of a prefix that scene files may use (ASCII u and the Greek mu for micro)
ALIASES = {"u": "µ", "μ": "µ"}
#: prefixes used when writing a value: engineering notation (powers of 1000) only
_WRITE = tuple((p, f) for p, f in PREFIXES if p != "c")

_PREFIX = {**dict(PREFIXES), **{k: dict(PREFIXES)[v] for k, v in ALIASES.items()}}

#: (dimension, unit) -> factor to SI, for the unit strings most scenes use
FAST: dict[tuple[str, str], float] = {}
for _p, _f in _PREFIX.items():
    FAST[("length", _p + "m")] = _f
    FAST[("force", _p + "N")] = _f
    FAST[("pressure", _p + "Pa")] = _f
    FAST[("mass", _p + "g")] = _f * 1e-3
    FAST[("surface_energy", _p + "J/m^2")] = _f
    FAST[("surface_energy", _p + "N/m")] = _f
FAST.update({
    ("angle", "rad"): 1.0, ("angle", "deg"): math.pi / 180, ("angle", "degree"): math.pi / 180,
    ("mass", "kg"): 1.0, ("velocity", "m/s"): 1.0, ("velocity", "km/h"): 1 / 3.6,
    ("density", "kg/m^3"): 1.0, ("density", "g/cm^3"): 1e3, ("density", "kg/m**3"): 1.0,
    ("density", "g/cm**3"): 1e3,
})
del _p, _f

_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\s].*?)?\s*$")


class UnitError(ValueError):
    """A quantity that cannot be read, or has the wrong dimension."""


@cache
def _registry():
    import pint

    return pint.UnitRegistry()


def to_si(value, dimension: str) -> float:
    """``value`` (a number in SI, or a string such as "210 GPa") as a float in SI units."""
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise UnitError(f"expected {DIMENSIONS[dimension][1]} (a number in "
                        f"{DIMENSIONS[dimension][0]} or a string with a unit), got {value!r}")
    if not isinstance(value, str):
        return float(value)
    m = _NUMBER_UNIT.match(value)
    if m and m.group(2) and (dimension, m.group(2)) in FAST:
        return float(m.group(1)) * FAST[(dimension, m.group(2))]
    if m and not m.group(2):  # "70": a bare number means SI only when it is not a string
        raise UnitError(f"{value!r} has no unit: a string carries one (e.g. \"{m.group(1)} "
                        f"{DIMENSIONS[dimension][0]}\"); a bare number ({m.group(1)}) is read "
                        f"in {DIMENSIONS[dimension][0]}")
    return _with_pint(value, dimension)


def _with_pint(text: str, dimension: str) -> float:
    ureg = _registry()
    try:
        q = ureg.Quantity(text)
    except Exception as exc:  # noqa: BLE001 -- pint's parser raises many kinds on bad text,
        # AssertionError among them; every one means the same thing to the user
        raise UnitError(f"cannot read {text!r} as a quantity ({type(exc).__name__}: {exc})") \
            from None
    target = ureg.Quantity(1, DIMENSIONS[dimension][0])
    if not hasattr(q, "dimensionality") or q.dimensionality != target.dimensionality:
        have = getattr(q, "units", "no unit")
        raise UnitError(f"{text!r} has the unit {have}, which is not {DIMENSIONS[dimension][1]} "
                        f"(convertible to {DIMENSIONS[dimension][0]})")
    return float(q.to(DIMENSIONS[dimension][0]).magnitude)


def engineering(x: float, unit: str, digits: int = 5) -> str:
    """``x`` with an SI prefix: engineering(1.0134e9, "Pa") == "1.0134 GPa"."""
    if not math.isfinite(x):
        return f"{x} {unit}"
    if unit == "1":  # a pure number
        return f"{x:.{digits}g}"
    if x == 0 or unit in ("", "rad"):
        return f"{x:.{digits}g} {unit}".strip()
    if "/" in unit or "^" in unit:  # compound units keep plain scientific notation
        return f"{x:.{digits}g} {unit}"
    for prefix, scale in _WRITE:
        if abs(x) >= scale * 0.9999999:
            return f"{x / scale:.{digits}g} {prefix}{unit}"
    return f"{x:.{digits}g} {unit}"


def prefixed(top: float) -> tuple[float, str]:
    """(scale, prefix) of the largest engineering prefix not above ``top`` (the smallest one
    for smaller values): an axis of values up to ``top`` is drawn in prefix-units."""
    for prefix, scale in _WRITE:
        if top >= scale:
            return scale, prefix
    return _WRITE[-1][1], _WRITE[-1][0]
