"""The result table a user reads (numeric/scene/report.py), checked against text written out by
hand: every value with its unit and SI prefix, a force law's K in N/m^n with its n, the "near
zero" cut of a maximum's coordinates, arrays of one, three and more values, the "> rtol (!)"
flag and its closing line, the time in ms, and the columns' alignment. Then what else a user
reads of a run: a result.json read back (echo.py) and its refusals, the assumptions' table
(assumptions.py), and the study point a study's warning or refusal names (study.py)."""

import json

import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.assumptions import ASSUMPTIONS, Assumption, markdown
from hertzmdr.numeric.scene.echo import read_result, scene_of
from hertzmdr.numeric.scene.report import NEAR_ZERO, format_value, positions_scale, table, unit_of
from hertzmdr.numeric.scene.runner import Result
from hertzmdr.numeric.scene.schema import SceneError
from hertzmdr.numeric.scene.study import VECTOR_EFFECTS

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


# -- echo.py: reading a run's result.json back ---------------------------------------------

def _result_doc(tmp_path):
    """A result.json's document with one file it read (its SHA-256 from hashlib, by hand)."""
    import hashlib

    tip = tmp_path / "tip.csv"
    tip.write_bytes(b"0 0\n1e-4 5e-7\n")
    return tip, {"scene": {"title": "t", "body": [{"radius": {"value": 0.005, "unit": "m"}}]},
                 "files": [{"key": "body[0] (tip).file", "path": str(tip),
                            "sha256": hashlib.sha256(b"0 0\n1e-4 5e-7\n").hexdigest()}]}


def test_result_json_gives_its_scene_back(tmp_path):
    """The scene with each {value, unit} pair as its SI number; a document without "files"
    (a scene that read none) is read all the same."""
    _, doc = _result_doc(tmp_path)
    assert scene_of(doc, "r.json") == {"title": "t", "body": [{"radius": 0.005}]}
    del doc["files"]
    assert read_result(json.dumps(doc), "r.json") == {"title": "t", "body": [{"radius": 0.005}]}


def _refused(call, *args):
    with pytest.raises(SceneError) as info:
        call(*args)
    return info.value.where, info.value.key, info.value.message


def test_result_json_refusals(tmp_path):
    """Each refusal names the document, the key and what to do."""
    tip, doc = _result_doc(tmp_path)
    assert _refused(read_result, json.dumps([doc]), "tour.json") == (
        "tour.json", "scene", "a result.json of `hertzmdr run` has the scene it ran under "
        "\"scene\"; this document has none (the tour's --json prints a list: read one scene's "
        "result.json)")
    assert _refused(read_result, "{\"scene\": ", "bad.json")[:2] == ("bad.json", "")
    assert _refused(read_result, "{\"scene\": ", "bad.json")[2].startswith("JSON syntax error: ")
    tip.write_bytes(b"0 0\n1e-4 6e-7\n")
    assert _refused(scene_of, doc, "r.json") == (
        "r.json", "body[0] (tip).file", f"the file {tip} changed since the run (its SHA-256 "
        "differs): the run cannot be reproduced from it")
    tip.unlink()
    assert _refused(scene_of, doc, "r.json") == (
        "r.json", "body[0] (tip).file", f"the file {tip} that the run read is gone")


# -- assumptions.py -------------------------------------------------------------------------

def test_assumption_direction_is_checked():
    for direction in ("above", "below"):
        Assumption("a/R", "small", 0.1, "why", "Hertz", direction)
    with pytest.raises(ValueError) as info:
        Assumption("a/R", "small", 0.1, "why", "Hertz", "Above")
    assert str(info.value) == "direction = 'Above' is not 'above' or 'below'"


def test_assumptions_markdown_has_a_row_per_assumption():
    """The header, the separator, then one row per assumption, in ASSUMPTIONS' order."""
    lines = markdown().splitlines()
    assert lines[:2] == ["| ratio | assumption | limit | why this limit | measured by |",
                         "| --- | --- | --- | --- | --- |"]
    assert len(lines) == 2 + len(ASSUMPTIONS)
    for line, a in zip(lines[2:], ASSUMPTIONS.values(), strict=True):
        assert line.startswith(f"| `{a.ratio}` | {a.assumption} | ")


# -- study.py: the points a study's messages name -------------------------------------------

STEEL_BALL = {"name": "ball", "shape": "sphere", "E": "210 GPa", "nu": 0.3}
ALU_PLATE = {"name": "plate", "shape": "flat", "E": "70 GPa", "nu": 0.33}


@pytest.mark.parametrize("load_first", [False, True])
def test_array_study_names_its_worst_corner(load_first):
    """A ball's radius x force map (3 x 4, evaluated as arrays, assumptions checked at the 4
    corners): a/R is largest at R = 0.1 mm, F = 1 kN, where the closed form
    a = (3 F R / (4 E*))^(1/3) (5.23), written here, gives a/R = 1.0857; the message names that
    corner and counts the 2 corners of R = 0.1 mm. The axes come in the document's order: that
    corner is the second of the four (R first) or the third (the load first). The model keeps
    the scene's rtol."""
    body = {"body": [{**STEEL_BALL, "radius": {"from": "0.1 mm", "to": "10 mm", "points": 3}},
                     ALU_PLATE]}
    load = {"load": {"force": {"from": "1 N", "to": "1 kN", "points": 4}}}
    doc = {"title": "s", "effects": ["force", "contact_radius"],
           **({**load, **body} if load_first else {**body, **load}), "accuracy": {"rtol": 1e-8}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "arrays" and out["model"]["rtol"] == 1e-8
    E_star = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.33**2) / 70e9)
    R, F = 1e-4, 1e3
    (w,) = [w for w in out["warnings"] if w["ratio"] == "a/R"]
    # the same float operations in another order: a few ulp
    assert w["value"] == pytest.approx((3 * F * R / (4 * E_star)) ** (1 / 3) / R, rel=1e-14)
    at = ("load.force = 1 kN, body[0] (ball).radius = 100 µm" if load_first
          else "body[0] (ball).radius = 100 µm, load.force = 1 kN")
    assert w["message"].endswith("(at 2 of the 4 corners of the study, where it is checked; "
                                 f"the largest at {at})")


def test_study_error_names_the_point():
    """Crossed cylinders swept from 0 deg (parallel: a line contact, which needs a length):
    the refusal of the first point names both swept keys at that point."""
    doc = {"title": "x", "effects": ["force"],
           "body": [{"name": "c1", "shape": "cylinder", "radius": "20 mm", "axis": "0 deg",
                     "E": "210 GPa", "nu": 0.3},
                    {"name": "c2", "shape": "cylinder", "radius": "10 mm",
                     "axis": {"from": "0 deg", "to": "90 deg", "points": 2},
                     "E": "210 GPa", "nu": 0.3}],
           "load": {"depth": {"from": "1 um", "to": "2 um", "points": 2}}}
    with pytest.raises(SceneError) as info:
        scene.load(doc).run_full()
    assert (info.value.where, info.value.key) == ("<scene>", "body")
    assert info.value.message == (
        "parallel cylinders make a line contact, whose force depends on the contact length: "
        "give the cylinder(s) a length (at the study point body[1] (c2).axis = 0 deg, "
        "load.depth = 1 µm)")


def test_nearly_flat_sphere_study_runs_as_arrays():
    """A sphere of R = 100 m to 1 km (4 points) on a plate: the gap's principal radii from the
    eigenvalues of its curvature differ by rounding (1.1e-13 m at R = 700 m, 1.6e-16 of it),
    far inside the circular tolerance 1e-12 of R: the study runs as arrays, R at each point the
    sphere's own radius to that rounding (a few ulp)."""
    doc = {"title": "s", "effects": ["effective_radius"],
           "body": [{**STEEL_BALL, "radius": {"from": "100 m", "to": "1 km", "points": 4}},
                    ALU_PLATE],
           "load": {"force": "1 N"}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "arrays"
    assert out["effects"]["effective_radius"]["value"] == \
        pytest.approx([100.0, 400.0, 700.0, 1000.0], rel=1e-15)


# -- study.py: a bad sweep is refused in one line naming the key -----------------------------

def _sweep_refusal(radius):
    doc = {"title": "s", "effects": ["force"], "body": [{**STEEL_BALL, "radius": radius},
                                                        ALU_PLATE], "load": {"force": "1 N"}}
    with pytest.raises(SceneError) as info:
        scene.load(doc)
    return info.value.key, info.value.message


@pytest.mark.parametrize("radius, key, message", [
    ({"from": "1 mm", "to": "2 mm"}, "body[0] (ball).radius.points",
     "missing: a sweep is {from, to, points} (and optionally spacing = \"linear\" or \"log\")"),
    ({"from": "1 mm", "to": "2 mm", "points": 1}, "body[0] (ball).radius.points",
     "must be an integer in [2, 100000], got 1"),
    ({"from": "1 mm", "to": "2 mm", "points": 100_001}, "body[0] (ball).radius.points",
     "must be an integer in [2, 100000], got 100001"),
    ({"from": "1 mm", "to": "2 mm", "points": True}, "body[0] (ball).radius.points",
     "must be an integer in [2, 100000], got True"),
    ({"from": "1 mm", "to": "2 mm", "points": 3.0}, "body[0] (ball).radius.points",
     "must be an integer in [2, 100000], got 3.0"),
    ({"from": "1 mm", "to": "2 mm", "points": 3, "spacing": "cubic"},
     "body[0] (ball).radius.spacing", "must be \"linear\" or \"log\", got 'cubic'"),
    ({"from": "2 mm", "to": "2 mm", "points": 3}, "body[0] (ball).radius",
     "a sweep needs from < to, got 0.002 and 0.002"),
])
def test_bad_sweep(radius, key, message):
    assert _sweep_refusal(radius) == (key, message)


def test_bad_sweep_of_a_number_and_of_log_spacing():
    doc = {"title": "s", "effects": ["force"],
           "body": [{**STEEL_BALL, "radius": "1 mm", "nu": {"from": "0.1", "to": 0.4,
                                                            "points": 2}}, dict(ALU_PLATE)],
           "load": {"force": "1 N"}}
    with pytest.raises(SceneError) as info:
        scene.load(doc)
    assert (info.value.key, info.value.message) == ("body[0] (ball).nu.from",
                                                    "must be a finite number, got '0.1'")
    doc["body"][0]["nu"] = 0.3
    doc["body"][1]["E"] = {"from": "0 GPa", "to": "70 GPa", "points": 3, "spacing": "log"}
    with pytest.raises(SceneError) as info:
        scene.load(doc)
    assert (info.value.key, info.value.message) == ("body[1] (plate).E.spacing",
                                                    "log spacing needs 0 < from, got 0")


@pytest.mark.parametrize("points", [2, 100_000])
def test_sweep_points_at_the_limits(points):
    """2 and 100000 points are both accepted (the closed range the refusal names)."""
    doc = {"title": "s", "effects": ["force"],
           "body": [{**STEEL_BALL, "radius": {"from": "1 mm", "to": "2 mm", "points": points}},
                    ALU_PLATE], "load": {"force": "1 N"}}
    spec = scene.load(doc).spec
    (axis,) = spec.study.axes
    assert len(axis.values) == points and axis.values[0] == 1e-3 and axis.values[-1] == 2e-3


def test_per_point_study_of_a_cone():
    """A rigid cone's slope angle swept 2, 6, 10 deg (run point by point: a cone is no array
    contact): each point's force is Sneddon's 2 E* d^2 / (pi tan(theta)) (5.38), written here;
    the model keeps what changes per point as a list; the slope warning counts the 2 points
    past tan(theta) = 0.1 and names the steepest; every point's effects were evaluated."""
    import math

    doc = {"title": "c", "effects": ["force", "contact_radius"],
           "body": [{"name": "tip", "shape": "cone", "rigid": True,
                     "angle": {"from": "2 deg", "to": "10 deg", "points": 3}},
                    dict(ALU_PLATE)],
           "load": {"depth": "1 um"}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "per point" and record.evaluated.count("force") == 3
    E_star, d = 70e9 / (1 - 0.33**2), 1e-6
    angles = [math.radians(t) for t in (2.0, 6.0, 10.0)]
    # closed forms of the same floats in another order: a few ulp
    assert out["effects"]["force"]["value"] == pytest.approx(
        [2 * E_star * d**2 / (math.pi * math.tan(t)) for t in angles], rel=1e-14)
    assert isinstance(out["effects"]["force"]["seconds"], float)
    # one method text for the three points, each met rtol
    assert out["effects"]["force"]["method"] == "(5.38)-(5.40)"
    assert out["effects"]["force"]["met_rtol"] is True and record.results["force"].name == "force"
    assert out["model"]["kind"] == "cone"
    assert out["model"]["angle"] == pytest.approx(angles, rel=1e-15)
    assert 0 < out["study"]["seconds"] < 60  # a wall-clock time of this run, not a clock
    (w,) = out["warnings"]
    assert w["ratio"] == "tan(theta)" and w["value"] == pytest.approx(math.tan(angles[2]),
                                                                      rel=1e-15)
    assert w["message"].endswith("(at 2 of 3 points; the largest at body[0] (tip).angle = "
                                 "10 deg)")


@pytest.mark.parametrize("sweep, effects", [
    ("E", sorted(VECTOR_EFFECTS)),   # every effect the arrays have, stress maxima included
    ("nu", ["force"]),               # nu swept, no stress maximum asked for
])
def test_material_sweeps_run_as_arrays(sweep, effects):
    """A ball's E (100 to 300 GPa) or nu (0.2 to 0.4) swept on a rigid plate at a depth of
    1 um: one array evaluation, each point's force Hertz's (4/3) E* sqrt(R) d^1.5 (5.22),
    written here, with E* = E / (1 - nu^2)."""
    import math

    ball = {**STEEL_BALL, "radius": "5 mm"}
    ball[sweep] = ({"from": "100 GPa", "to": "300 GPa", "points": 3} if sweep == "E"
                   else {"from": 0.2, "to": 0.4, "points": 3})
    doc = {"title": "s", "effects": effects,
           "body": [ball, {"name": "plate", "shape": "flat", "rigid": True}],
           "load": {"depth": "1 um"}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "arrays"
    E = [100e9, 200e9, 300e9] if sweep == "E" else [210e9] * 3
    nu = [0.3] * 3 if sweep == "E" else [0.2, 0.3, 0.4]
    R, d = 5e-3, 1e-6
    # the same closed form, its floats in another order: a few ulp
    assert out["effects"]["force"]["value"] == pytest.approx(
        [4 / 3 * e / (1 - n**2) * math.sqrt(R) * d**1.5 for e, n in zip(E, nu, strict=True)],
        rel=1e-14)


def test_friction_sweep():
    """The coefficient of friction swept 0.2, 0.4, 0.6 under 10 N (point by point: the
    tangential effects are no array effect): the sliding force mu F (Amontons) at each point."""
    doc = {"title": "f", "effects": ["sliding_force"],
           "body": [{**STEEL_BALL, "radius": "5 mm"}, dict(ALU_PLATE)],
           "interface": {"friction": {"from": 0.2, "to": 0.6, "points": 3}},
           "load": {"force": "10 N"}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "per point"
    # 0.2 + 0.4 i / 2 in floats against 0.2, 0.4, 0.6 times 10: a rounding apart
    assert out["effects"]["sliding_force"]["value"] == pytest.approx([2.0, 4.0, 6.0], rel=1e-15)


def test_adhesive_study_keeps_its_adhesion():
    """A sphere of R = 1 and 2 mm with a work of adhesion of 50 mJ/m^2 at a depth of 1 um:
    an adhesive contact, run point by point, never the arrays of plain Hertz: each point's
    force lies below Hertz's (4/3) E* sqrt(R) d^1.5 (5.22): the adhesive pull, 6e-5 of the force
    between these stiff bodies, far above rounding (1e-15)."""
    import math

    doc = {"title": "a", "effects": ["force"],
           "body": [{**STEEL_BALL, "radius": {"from": "1 mm", "to": "2 mm", "points": 2}},
                    dict(ALU_PLATE)],
           "interface": {"work_of_adhesion": "0.05 J/m^2"},
           "load": {"depth": "1 um"}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "per point"
    E_star = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.33**2) / 70e9)
    hertz = [4 / 3 * E_star * math.sqrt(R) * 1e-6**1.5 for R in (1e-3, 2e-3)]
    assert all(f < (1 - 3e-5) * h for f, h in zip(out["effects"]["force"]["value"], hertz,
                                            strict=True))


def test_per_point_study_with_a_load_sweep():
    """A rigid cone's slope angle (2, 10 deg) times the depth (1, 2 um), point by point: each
    point runs its own single depth, Sneddon's 2 E* d^2 / (pi tan(theta)) (5.38), written
    here."""
    import math

    doc = {"title": "c", "effects": ["force"],
           "body": [{"name": "tip", "shape": "cone", "rigid": True,
                     "angle": {"from": "2 deg", "to": "10 deg", "points": 2}},
                    dict(ALU_PLATE)],
           "load": {"depth": {"from": "1 um", "to": "2 um", "points": 2}}}
    record, _, out = scene.load(doc).run_full()
    assert record.route == "per point"
    E_star = 70e9 / (1 - 0.33**2)
    want = [2 * E_star * d**2 / (math.pi * math.tan(math.radians(t)))
            for t in (2.0, 10.0) for d in (1e-6, 2e-6)]
    # closed forms of the same floats in another order: a few ulp
    assert out["effects"]["force"]["value"] == pytest.approx(want, rel=1e-14)
