"""The result table a user reads (numeric/scene/report.py), checked against text written out by
hand: every value with its unit and SI prefix, a force law's K in N/m^n with its n, the "near
zero" cut of a maximum's coordinates, arrays of one, three and more values, the "> rtol (!)"
flag and its closing line, the time in ms, and the columns' alignment."""

import pytest

from hertzmdr.numeric.scene.report import NEAR_ZERO, format_value, positions_scale, table, unit_of
from hertzmdr.numeric.scene.runner import Result

MAX_VM = "{value: Pa, x: m, z: m}"
ORTHO = "{value: Pa, x: m, z: m, y: m, value_xz: Pa, x_xz: m, z_xz: m}"
FORCE_LAW = ("{K: N/m^n, n: 1, stiffness_K: N/m^n, stiffness_n: 1, K_per_length: N/m^(n+1), "
             "stiffness_K_per_length: N/m^(n+1)}")


# -- unit_of: one key of a compound unit ----------------------------------------------------

def test_unit_of_reads_one_key():
    assert unit_of("Pa", "value") == "Pa"   # a plain unit is every key's unit
    assert unit_of(MAX_VM, "value") == "Pa"
    assert unit_of(MAX_VM, "z") == "m"      # the last key, before the closing brace
    assert unit_of(FORCE_LAW, "K_per_length") == "N/m^(n+1)"
    assert unit_of(MAX_VM, "depth") == ""   # a key the unit does not name has none


# -- positions_scale: the contact's size a located maximum sees ----------------------------

def test_positions_scale_is_the_largest_coordinate():
    """The largest |coordinate| among the keys in m: a negative x of 5e-4 m beats z = 1e-4 m;
    the value (Pa, 8e8), a second value in Pa (9e8), a coordinate field (an array) and a NaN
    coordinate are not coordinates of the maximum."""
    rec = {"value": 8e8, "x": -5e-4, "z": 1e-4, "y": float("nan"), "value_xz": 9e8,
           "x_xz": [1.0, 2.0], "z_xz": 2e-4}
    assert positions_scale(rec, ORTHO) == 5e-4


def test_positions_scale_skips_the_value_even_in_m():
    """The value is what was located, not where: a value in m (3 m, far above the
    coordinates) does not set the scale."""
    assert positions_scale({"value": 3.0, "x": 2e-6, "z": 7e-6}, "{value: m, x: m, z: m}") == 7e-6


@pytest.mark.parametrize("rec, unit", [
    # a record that locates nothing: two pull-off depths, no "value" key
    ({"force_control": 1e-5, "depth_control": 2e-5}, "{force_control: m, depth_control: m}"),
    # a located value with no coordinate in m
    ({"value": 4e8}, "{value: Pa}"),
])
def test_positions_scale_zero_without_coordinates(rec, unit):
    scale = positions_scale(rec, unit)
    assert scale == 0.0 and isinstance(scale, float)


# -- format_value: records ------------------------------------------------------------------

def test_a_maximum_with_its_position():
    """Each key with its own unit and prefix, in the record's order, comma-separated."""
    text = format_value({"value": 1.2345e9, "x": 2.5e-5, "z": 1.3119e-4}, MAX_VM)
    assert text == "value = 1.2345 GPa, x = 25 µm, z = 131.19 µm"


def test_near_zero_cut_of_a_coordinate():
    """z = 1e-4 m: a coordinate below NEAR_ZERO * 1e-4 = 1e-10 m prints as 0; one at the cut
    or above it (3e-8 m, 3e-4 of the size) prints as it is; the value itself (Pa) is never
    compared with a length, however small."""
    z = 1e-4
    cut = NEAR_ZERO * z
    assert format_value({"value": 8e8, "x": -0.5 * cut, "z": z}, MAX_VM) == \
        "value = 800 MPa, x = 0 m, z = 100 µm"
    assert format_value({"value": 8e8, "x": cut, "z": z}, MAX_VM) == \
        "value = 800 MPa, x = 100 pm, z = 100 µm"
    assert format_value({"value": 8e8, "x": 3e-8, "z": z}, MAX_VM) == \
        "value = 800 MPa, x = 30 nm, z = 100 µm"
    # a tiny stress beside the coordinates stays what it is
    assert format_value({"value": 5e-12, "x": 2e-5, "z": z}, MAX_VM) == \
        "value = 5 pPa, x = 20 µm, z = 100 µm"


def test_near_zero_cut_spares_the_value_in_m():
    """Only the coordinates are cut: a value in m far below the coordinates (2 pm beside
    z = 100 um) is printed as it is."""
    text = format_value({"value": 2e-12, "x": 0.0, "z": 1e-4}, "{value: m, x: m, z: m}")
    assert text == "value = 2 pm, x = 0 m, z = 100 µm"


def test_coordinates_of_a_record_without_value_are_not_cut():
    """Two pull-off depths locate nothing: 1 pm beside 10 um is printed as 1 pm."""
    text = format_value({"force_control": 1e-12, "depth_control": 1e-5},
                        "{force_control: m, depth_control: m}")
    assert text == "force_control = 1 pm, depth_control = 10 µm"


@pytest.mark.parametrize("n, k_unit, per_length_unit", [
    (1.5, "N/m^1.5", "N/m^2.5"),   # Hertz sphere: F = K d^1.5, per length m^(n+1) = m^2.5
    (1.0, "N/m^1", "N/m^2"),       # flat punch / line contact: n = 1, per length N/m^2
    (2.0, "N/m^2", "N/m^3"),       # cone: n = 2
])
def test_force_law_units_carry_n(n, k_unit, per_length_unit):
    """K in N/m^n and K per length in N/m^(n+1), with the record's own n; n (unit 1) as a
    pure number."""
    rec = {"K": 2.5e9, "n": n, "K_per_length": 4e13}
    assert format_value(rec, FORCE_LAW) == \
        f"K = 2.5e+09 {k_unit}, n = {n:g}, K_per_length = 4e+13 {per_length_unit}"


def test_force_law_n_as_a_one_element_array():
    """n may come as a one-element array (a JSON list): its value is read all the same."""
    rec = {"K": [2.5e9], "n": [1.5]}
    assert format_value(rec, FORCE_LAW) == "K = 2.5e+09 N/m^1.5, n = 1.5"


def test_a_field_prints_its_number_of_points():
    """A record of arrays prints its size and its keys, not values."""
    rec = {"u": [0.0, 1e-6, 2e-6, 3e-6], "F": [0.0, 1.0, 2.0, 3.0]}
    assert format_value(rec, "{u: m, F: N}") == "field of 4 points (u, F); PNG with --out"


def test_scalars_of_a_record_with_a_field():
    """A record with both scalars and arrays prints its scalars only (the curve of a
    hysteresis record is drawn, its jump values are numbers)."""
    rec = {"depth": [0.0, 1e-6, 2e-6], "jump_depth": -3e-7, "jump_force": -0.02}
    unit = "{depth: m, jump_depth: m, jump_force: N}"
    assert format_value(rec, unit) == "jump_depth = -300 nm, jump_force = -20 mN"


def test_empty_record():
    assert format_value({}, "{}") == "field of 0 points (); PNG with --out"


# -- format_value: numbers and arrays -------------------------------------------------------

@pytest.mark.parametrize("value, unit, text", [
    (1.234e-6, "m", "1.234 µm"),
    (1.0134e9, "Pa", "1.0134 GPa"),
    ([2.5e-3], "N", "2.5 mN"),             # one value in a list is one value
    ([[7e-9]], "m", "7 nm"),               # ... whatever its shape
    (2.0, "1", "2"),
    ([1e-6, 2e-6], "m", "[1 µm, 2 µm]"),
    ([1e-6, 2e-6, 3e-6], "m", "[1 µm, 2 µm, 3 µm]"),
    ([1e-6, 2e-6, 3e-6, 4e-6], "m", "4 values, 1 µm .. 4 µm"),
    ([5e3, 6e3, 7e3, 8e3, 9e3], "N", "5 values, 5 kN .. 9 kN"),
])
def test_numbers_and_arrays(value, unit, text):
    """Engineering notation with the unit; up to three values in brackets, more as the count,
    the first and the last."""
    assert format_value(value, unit) == text


# -- table ----------------------------------------------------------------------------------

def _results():
    return {
        "force": Result("force", 0.0125, "N", "(5.24)", 0.0, True, 1.234e-4),
        "max_shear": Result("max_shear", {"value": 3.1e8, "depth": 4.8e-5},
                            "{value: Pa, depth: m}", "golden section", 2.5e-7, False, 1.5),
        "contact_radius": Result("contact_radius", [1e-4, 2e-4, 3e-4, 4e-4], "m", "(5.23)",
                                 3e-3, False, 0.02),
    }


# written out by hand: columns two spaces apart, each as wide as its widest cell, no trailing
# blanks; times in ms (1.234e-4 s = 0.12 ms, 1.5 s = 1500.00 ms, 0.02 s = 20.00 ms)
EXPECTED = """\
demo run
========
model: sphere on flat; E* = 115.38 GPa; rtol = 1e-10
effect          value                           method          rel. error          time
--------------  ------------------------------  --------------  ------------------  ----------
force           12.5 mN                         (5.24)          0.0e+00             0.12 ms
max_shear       value = 310 MPa, depth = 48 µm  golden section  2.5e-07 > rtol (!)  1500.00 ms
contact_radius  4 values, 100 µm .. 400 µm      (5.23)          3.0e-03 > rtol (!)  20.00 ms
(!) rel. error above rtol = 1e-10: max_shear, contact_radius (the method cannot reach it \
here; the method column says why)
warning: the depth is 12 % of the radius
warning: second"""


def test_table_text():
    model = {"description": "sphere on flat", "kind": "sphere", "effective_modulus": 1.1538e11,
             "rtol": 1e-10}
    warnings = [{"message": "the depth is 12 % of the radius"}, {"message": "second"}]
    text = table("demo run", model, _results(), warnings)
    assert text == EXPECTED, text
    assert not any(line != line.rstrip() for line in text.splitlines())


def test_table_model_line_falls_back_to_the_kind():
    """Without a description the model line names the kind; with neither, nothing."""
    res = {"force": Result("force", 2.0, "N", "(5.24)", 1e-16, True, 0.0)}
    text = table("t", {"kind": "sphere", "effective_modulus": 1e9, "rtol": 1e-8}, res)
    assert text.splitlines()[2] == "model: sphere; E* = 1 GPa; rtol = 1e-08"
    text = table("t", {"effective_modulus": 1e9, "rtol": 1e-8}, res)
    assert text.splitlines()[2] == "model: ; E* = 1 GPa; rtol = 1e-08"


def test_table_without_misses_has_no_flag():
    """Every effect met rtol: no "> rtol (!)", no closing line, no warning line."""
    res = {"force": Result("force", 2.0, "N", "(5.24)", 1e-16, True, 0.0)}
    text = table("t", {"kind": "sphere", "effective_modulus": 1e9, "rtol": 1e-8}, res)
    assert text.splitlines()[-1] == "force   2 N    (5.24)  1.0e-16     0.00 ms"
    assert "(!)" not in text and "warning" not in text
