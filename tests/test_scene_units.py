"""Unit strings in scenes: the fast table agrees with pint, and wrong dimensions are refused."""

import pint
import pytest

from hertzmdr.numeric.scene.units import DIMENSIONS, FAST, UnitError, to_si

UREG = pint.UnitRegistry()


@pytest.mark.parametrize("dim, unit", sorted(FAST), ids=lambda x: str(x))
def test_fast_table_agrees_with_pint(dim, unit):
    si = DIMENSIONS[dim][0]
    expected = UREG.Quantity(f"2.5 {unit}").to(si).magnitude
    # both are one or two correctly rounded multiplications of the same decimal factors
    assert to_si(f"2.5 {unit}", dim) == pytest.approx(expected, rel=4e-16)


@pytest.mark.parametrize("text, dim, si", [
    ("210 GPa", "pressure", 210e9), ("30 deg", "angle", 0.5235987755982988),
    ("5 um", "length", 5e-6), ("7.8 g/cm^3", "density", 7800.0), ("3 inch", "length", 0.0762),
    ("1 lbf", "force", 4.4482216152605), ("2 mm", "length", 2e-3), ("100 kN", "force", 1e5),
    (0.5, "length", 0.5), (1e-3, "length", 1e-3),
])
def test_parse(text, dim, si):
    assert to_si(text, dim) == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize("text, dim, message", [
    ("3 kg", "length", "not a length"), ("3 blah", "length", "cannot read"),
    ("210 GPa", "force", "not a force"), (True, "length", "expected a length"),
    ([1, 2], "length", "expected a length"), ("__import__('os')", "length", "cannot read"),
    # a string without a unit is not silently SI: "70" meant as GPa would be 1e9 times off
    ("70", "pressure", "has no unit"), (" 1e-3 ", "length", "has no unit"),
])
def test_refused(text, dim, message):
    with pytest.raises(UnitError, match=message):
        to_si(text, dim)
