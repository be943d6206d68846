"""The scene reader's loads and ``[fit]`` table (numeric/scene/schema.py), in-process: every
accepted form with its values in SI (each checked against a number worked by hand from the
unit: "2 um" is 2e-6 m), the defaults, and every refusal with its one-line message (the key,
the value given and what is valid). Only the reader runs here, no effect: milliseconds a test.

Conversions go through one multiplication by a power of ten (units.FAST) or through pint;
both are compared with rel = 1e-15 (a few ulps: the factor 1e-9 is not exact in binary)."""

from __future__ import annotations

import copy

import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.schema import FitSpec, History, SceneError, Tangential

BODIES = [{"shape": "sphere", "radius": "1 mm", "rigid": True},
          {"shape": "flat", "E": "1 GPa", "nu": 0.3}]
ULPS = 1e-15  # a unit's factor applied once: a few ulps (see the module's docstring)
HISTORY_MISSING = ('missing: a history is {file = "h.csv", normal = "depth" or "force", '
                   'tangential = "displacement" or "force"} (units = [..., ...] optional)')


def doc(load=None, **top):
    return {"effects": ["force"], "body": copy.deepcopy(BODIES),
            "load": {"depth": 1e-9} if load is None else load, **top}


def spec_of(load=None, **top):
    return scene.load(doc(load, **top)).spec


def refused(load=None, **top) -> SceneError:
    with pytest.raises(SceneError) as info:
        spec_of(load, **top)
    err = info.value
    assert "\n" not in str(err)  # a message is one line
    assert str(err) == f"<scene>: {err.key}: {err.message}"
    return err


def approx(v):
    return pytest.approx(v, rel=ULPS, abs=0)


# -- [load]: its keys and history's exclusivity ----------------------------------------------

def test_unknown_load_key_names_it_and_the_allowed_keys():
    err = refused({"depth": 1e-9, "histroy": 1})
    assert err.key == "load.histroy"
    assert err.message == ("unknown key; did you mean 'history'? (allowed: cycle, depth, force, "
                           "history, impact, oscillating, pressure, tangential)")


@pytest.mark.parametrize("others, named", [
    ({"depth": 1e-9}, "depth"),
    ({"tangential": {"force": 1.0}, "depth": 1e-9}, "depth and tangential"),
])
def test_history_goes_alone(others, named):
    err = refused({"history": {"file": "h.csv", "normal": "depth", "tangential": "force"},
                   **others})
    assert err.key == "load"
    assert err.message == ("a history gives both the normal and the tangential load: give "
                           f"history alone, not with {named}")


@pytest.mark.parametrize("load, key, message", [
    ({}, "load", "give exactly one of depth, force, cycle, [load.impact] or [load.pressure]"),
    ({"depth": 1e-9, "force": 1.0}, "load",
     "give exactly one of depth, force, cycle, [load.impact] or [load.pressure], not depth and "
     "force"),
    ({"force": 1.0, "cycle": {"to": 1e-9}}, "load",
     "give exactly one of depth, force, cycle, [load.impact] or [load.pressure], not force and "
     "cycle"),
    ({"cycle": 1}, "load.cycle", "must be a table, got int"),
    ({"pressure": 1}, "load.pressure", "must be a table, got int"),
    ({"impact": "x"}, "load.impact", "must be a table, got str"),
])
def test_normal_load_refusals(load, key, message):
    err = refused(load)
    assert (err.key, err.message) == (key, message)


# -- a tangential load -----------------------------------------------------------------------

@pytest.mark.parametrize("normal", [{"depth": "2 nm"}, {"force": "3 mN"}])
@pytest.mark.parametrize("given, kind, si, dim", [
    ({"force": "2 mN"}, "force", 2e-3, "force"),
    ({"displacement": "3 nm"}, "displacement", 3e-9, "length"),
])
def test_tangential_accepted(normal, given, kind, si, dim):
    spec = spec_of({**normal, "tangential": given})
    t = spec.load.tangential
    assert isinstance(t, Tangential)
    assert (t.kind, t.cycles, t.history) == (kind, 0, None)
    assert t.value == approx(si)
    assert spec.read_as[f"load.tangential.{kind}"] == ("quantity", dim)
    (k, v), = normal.items()
    assert spec.load.kind == k and not spec.load.sweep
    assert spec.load.values == approx([2e-9 if k == "depth" else 3e-3])


@pytest.mark.parametrize("load, key, message", [
    ({"depth": 1e-9, "tangential": {"force": 1.0}, "oscillating": {"amplitude": 1.0}},
     "load", "give tangential or oscillating, not both"),
    ({"depth": 1e-9, "tangential": 2.0}, "load.tangential", "must be a table, got float"),
    ({"depth": 1e-9, "tangential": {"force": 1.0, "angle": 1.0}}, "load.tangential.angle",
     "unknown key (allowed: displacement, force)"),
    ({"depth": 1e-9, "tangential": {}}, "load.tangential",
     "give exactly one of force or displacement"),
    ({"depth": 1e-9, "tangential": {"force": 1.0, "displacement": 1e-9}}, "load.tangential",
     "give exactly one of force or displacement"),
    ({"depth": 1e-9, "tangential": {"force": -1.0}}, "load.tangential.force",
     "must be > 0, got -1.0"),
    ({"depth": 1e-9, "tangential": {"force": "2 nm"}}, "load.tangential.force",
     "'2 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"depth": 1e-9, "tangential": {"displacement": "2 mN"}}, "load.tangential.displacement",
     "'2 mN' has the unit millinewton, which is not a length (convertible to m)"),
    ({"impact": {"velocity": 1.0, "mass": 1.0}, "tangential": {"force": 1.0}}, "load",
     "a tangential load needs a constant normal load: one depth or force, not a sweep, an "
     "impact or a prescribed pressure"),
    ({"depth": {"from": 0.0, "to": 1e-9, "points": 3}, "oscillating": {"amplitude": 1.0}},
     "load", "a tangential load needs a constant normal load: one depth or force, not a sweep, "
     "an impact or a prescribed pressure"),
    ({"depth": 1e-9, "oscillating": [1]}, "load.oscillating", "must be a table, got list"),
    ({"depth": 1e-9, "oscillating": {"amplitude": 1.0, "cycle": 2}}, "load.oscillating.cycle",
     "unknown key; did you mean 'cycles'? (allowed: amplitude, cycles)"),
    ({"depth": 1e-9, "oscillating": {"cycles": 2}}, "load.oscillating.amplitude",
     "missing: the amplitude of the tangential force"),
    ({"depth": 1e-9, "oscillating": {"amplitude": 0.0}}, "load.oscillating.amplitude",
     "must be > 0, got 0.0"),
    ({"depth": 1e-9, "oscillating": {"amplitude": "1 nm"}}, "load.oscillating.amplitude",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
])
def test_tangential_refusals(load, key, message):
    err = refused(load)
    assert (err.key, err.message) == (key, message)


@pytest.mark.parametrize("cycles", [0, 1001, True, 2.0, "3"])
def test_oscillating_cycles_refused(cycles):
    err = refused({"depth": 1e-9, "oscillating": {"amplitude": 1.0, "cycles": cycles}})
    assert err.key == "load.oscillating.cycles"
    assert err.message == f"must be an integer in [1, 1000], got {cycles!r}"


@pytest.mark.parametrize("given, cycles", [({}, 1), ({"cycles": 1}, 1), ({"cycles": 7}, 7),
                                           ({"cycles": 1000}, 1000)])
def test_oscillating_accepted(given, cycles):
    spec = spec_of({"force": "1 N", "oscillating": {"amplitude": "5 mN", **given}})
    t = spec.load.tangential
    assert (t.kind, t.cycles, t.history) == ("oscillating", cycles, None)
    assert t.value == approx(5e-3)
    assert spec.read_as["load.oscillating.amplitude"] == ("quantity", "force")
    assert spec.load.kind == "force" and spec.load.values == [1.0]


# -- a cycle ---------------------------------------------------------------------------------

@pytest.mark.parametrize("cy, control, to, points", [
    ({"to": "2 um"}, "depth", 2e-6, 1000),
    ({"to": "2 um", "control": "depth", "points": 20}, "depth", 2e-6, 20),
    ({"to": "3 mN", "control": "force", "points": 100_000}, "force", 3e-3, 100_000),
])
def test_cycle_accepted(cy, control, to, points):
    spec = spec_of({"cycle": cy})
    ld = spec.load
    assert (ld.kind, ld.control, ld.points, ld.sweep, ld.tangential) == (
        "cycle", control, points, False, None)
    assert ld.values == approx([to])
    assert spec.read_as["load.cycle.to"] == ("quantity",
                                             "length" if control == "depth" else "force")


@pytest.mark.parametrize("cy, key, message", [
    ({"to": 1e-9, "point": 30}, "load.cycle.point",
     "unknown key; did you mean 'points'? (allowed: control, points, to)"),
    ({"points": 30}, "load.cycle.to", "missing: the largest depth (or force) of the cycle"),
    ({"to": 1e-9, "control": "time"}, "load.cycle.control",
     "must be \"depth\" or \"force\", got 'time'"),
    ({"to": -1e-9}, "load.cycle.to", "must be > 0, got -1e-09"),
    ({"to": "1 mN"}, "load.cycle.to",
     "'1 mN' has the unit millinewton, which is not a length (convertible to m)"),
    ({"to": "1 nm", "control": "force"}, "load.cycle.to",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
])
def test_cycle_refusals(cy, key, message):
    err = refused({"cycle": cy})
    assert (err.key, err.message) == (key, message)


@pytest.mark.parametrize("points", [19, 100_001, True, 50.0, "50"])
def test_cycle_points_refused(points):
    err = refused({"cycle": {"to": 1e-9, "points": points}})
    assert err.key == "load.cycle.points"
    assert err.message == f"must be an integer in [20, 100000], got {points!r}"


# -- a prescribed pressure and an impact -----------------------------------------------------

def test_pressure_accepted():
    spec = spec_of({"pressure": {"distribution": "hertzian", "p0": "1 GPa", "radius": "2 um"}})
    ld = spec.load
    assert (ld.kind, ld.distribution, ld.values, ld.sweep) == ("pressure", "hertzian", [], False)
    assert ld.p0 == approx(1e9) and ld.radius == approx(2e-6)
    assert spec.read_as["load.pressure.p0"] == ("quantity", "pressure")
    assert spec.read_as["load.pressure.radius"] == ("quantity", "length")


PRESSURE_CHOICES = ("(one of: uniform (n = 0, Problem 6), hertzian (n = 0.5, (5.16), Fig. 5.2), "
                    "punch (n = -0.5, (5.10)))")
PR = {"distribution": "uniform", "p0": 1e6, "radius": 1e-6}


@pytest.mark.parametrize("pr, key, message", [
    ({**PR, "p": 1}, "load.pressure.p",
     "unknown key; did you mean 'p0'? (allowed: distribution, p0, radius)"),
    ({"p0": 1e6, "radius": 1e-6}, "load.pressure.distribution", "missing"),
    ({"distribution": "uniform", "radius": 1e-6}, "load.pressure.p0", "missing"),
    ({"distribution": "uniform", "p0": 1e6}, "load.pressure.radius", "missing"),
    ({**PR, "distribution": "hertzain"}, "load.pressure.distribution",
     "unknown distribution 'hertzain'; did you mean 'hertzian'? " + PRESSURE_CHOICES),
    ({**PR, "distribution": 2}, "load.pressure.distribution",
     "unknown distribution 2 " + PRESSURE_CHOICES),
    ({**PR, "p0": -1.0}, "load.pressure.p0", "must be > 0, got -1.0"),
    ({**PR, "p0": "1 mm"}, "load.pressure.p0",
     "'1 mm' has the unit millimeter, which is not a pressure or modulus (convertible to Pa)"),
    ({**PR, "radius": 0}, "load.pressure.radius", "must be > 0, got 0"),
    ({**PR, "radius": "1 GPa"}, "load.pressure.radius",
     "'1 GPa' has the unit gigapascal, which is not a length (convertible to m)"),
])
def test_pressure_refusals(pr, key, message):
    err = refused({"pressure": pr})
    assert (err.key, err.message) == (key, message)


@pytest.mark.parametrize("imp, mass, density", [
    ({"velocity": "2 m/s", "mass": "3 g"}, 3e-3, None),
    ({"velocity": "2 m/s", "density": "7800 kg/m^3"}, None, 7800.0),
])
def test_impact_accepted(imp, mass, density):
    spec = spec_of({"impact": imp})
    ld = spec.load
    assert (ld.kind, ld.values, ld.sweep) == ("impact", [], False)
    assert ld.velocity == approx(2.0)
    assert ld.mass == (None if mass is None else approx(mass))
    assert ld.density == (None if density is None else approx(density))
    assert spec.read_as["load.impact.velocity"] == ("quantity", "velocity")
    if mass is not None:
        assert spec.read_as["load.impact.mass"] == ("quantity", "mass")
    else:
        assert spec.read_as["load.impact.density"] == ("quantity", "density")


@pytest.mark.parametrize("imp, key, message", [
    ({"velocity": 1.0, "mass": 1.0, "speed": 1}, "load.impact.speed",
     "unknown key (allowed: density, mass, velocity)"),
    ({"mass": 1.0}, "load.impact.velocity", "missing"),
    ({"velocity": 1.0}, "load.impact", "give exactly one of mass or density"),
    ({"velocity": 1.0, "mass": 1.0, "density": 1.0}, "load.impact",
     "give exactly one of mass or density"),
    ({"velocity": -1.0, "mass": 1.0}, "load.impact.velocity", "must be > 0, got -1.0"),
    ({"velocity": "1 m", "mass": 1.0}, "load.impact.velocity",
     "'1 m' has the unit meter, which is not a velocity (convertible to m/s)"),
    ({"velocity": 1.0, "mass": 0.0}, "load.impact.mass", "must be > 0, got 0.0"),
    ({"velocity": 1.0, "mass": "1 m"}, "load.impact.mass",
     "'1 m' has the unit meter, which is not a mass (convertible to kg)"),
    ({"velocity": 1.0, "density": -2.0}, "load.impact.density", "must be > 0, got -2.0"),
    ({"velocity": 1.0, "density": "1 kg"}, "load.impact.density",
     "'1 kg' has the unit kilogram, which is not a density (convertible to kg/m^3)"),
])
def test_impact_refusals(imp, key, message):
    err = refused({"impact": imp})
    assert (err.key, err.message) == (key, message)


# -- a history file --------------------------------------------------------------------------

H_CSV = "# a history\nnormal [nm], tangential [nm]\n0, 0\n5, 1\n10 -2.5\n"


def history_spec(tmp_path, monkeypatch, text=H_CSV, **h):
    (tmp_path / "h.csv").write_text(text)
    monkeypatch.chdir(tmp_path)  # a dict scene has no folder: names are relative to cwd
    return spec_of({"history": {"file": "h.csv", "normal": "depth",
                                "tangential": "displacement", **h}})


def history_refused(tmp_path, monkeypatch, text=H_CSV, **h) -> SceneError:
    with pytest.raises(SceneError) as info:
        history_spec(tmp_path, monkeypatch, text, **h)
    assert "\n" not in str(info.value)
    return info.value


def test_history_in_nm(tmp_path, monkeypatch):
    """Rows 3-5 of the file (a comment line, a header line before them), both columns in nm:
    normal (0, 5, 10) nm, tangential (0, 1, -2.5) nm; the Tangential's value is the largest
    |tangential|, 2.5 nm."""
    spec = history_spec(tmp_path, monkeypatch, units=["nm", " nm "])
    ld = spec.load
    assert (ld.kind, ld.sweep) == ("depth", True)
    assert ld.values == approx([0.0, 5e-9, 1e-8])
    t = ld.tangential
    assert (t.kind, t.cycles) == ("history", 0)
    assert t.value == approx(2.5e-9)
    h = t.history
    assert isinstance(h, History)
    assert (h.file, h.control, h.lines) == ("h.csv", "displacement", (3, 4, 5))
    assert h.values == approx((0.0, 1e-9, -2.5e-9))
    assert spec.read_as["load.history.file"] == ("path", "")
    assert not any(k.startswith("load.history.units") for k in spec.read_as)


def test_history_forces_in_si_and_in_units(tmp_path, monkeypatch):
    """Without units the columns are SI; ["mN", "uN"] scales them by 1e-3 and 1e-6."""
    si = history_spec(tmp_path, monkeypatch, normal="force", tangential="force")
    assert si.load.kind == "force"
    assert si.load.values == [0.0, 5.0, 10.0]
    assert si.load.tangential.history.values == (0.0, 1.0, -2.5)
    assert si.load.tangential.history.control == "force"
    assert si.load.tangential.value == 2.5
    scaled = history_spec(tmp_path, monkeypatch, normal="force", tangential="force",
                          units=["mN", "uN"])
    assert scaled.load.values == approx([0.0, 5e-3, 1e-2])
    assert scaled.load.tangential.history.values == approx((0.0, 1e-6, -2.5e-6))


def scene_in_a_folder(tmp_path, monkeypatch, data: str, tables: str):
    """A scene file scenes/s.toml with a data file scenes/<data name> beside it (data: the
    name, a colon, its text), read with the current folder elsewhere (tmp_path)."""
    folder = tmp_path / "scenes"
    folder.mkdir()
    name, text = data.split(":", 1)
    (folder / name).write_text(text)
    (folder / "s.toml").write_text(
        'effects = ["force"]\n[[body]]\nshape = "sphere"\nradius = 1e-3\nrigid = true\n'
        '[[body]]\nshape = "flat"\nE = 1e9\nnu = 0.3\n' + tables)
    monkeypatch.chdir(tmp_path)
    return folder, scene.load(folder / "s.toml").spec


def test_history_file_beside_a_scene_file(tmp_path, monkeypatch):
    """A scene file's history is named relative to the scene's folder, not to cwd."""
    _, spec = scene_in_a_folder(
        tmp_path, monkeypatch, "h.csv:1, 2\n3, 4\n",
        '[load.history]\nfile = "h.csv"\nnormal = "depth"\ntangential = "force"\n')
    ld = spec.load
    assert ld.values == [1.0, 3.0] and ld.tangential.history.values == (2.0, 4.0)


@pytest.mark.parametrize("h, key, message", [
    ({"unit": ["nm", "nm"]}, "load.history.unit",
     "unknown key; did you mean 'units'? (allowed: file, normal, tangential, units)"),
    ({"normal": "pressure"}, "load.history.normal",
     "must be \"depth\" or \"force\", got 'pressure'"),
    ({"tangential": "depth"}, "load.history.tangential",
     "must be \"displacement\" or \"force\", got 'depth'"),
    ({"units": "nm"}, "load.history.units", "must be a list of two unit strings [normal, "
     "tangential], e.g. [\"nm\", \"nm\"] or [\"N\", \"mN\"]; got 'nm'"),
    ({"units": ["nm"]}, "load.history.units", "must be a list of two unit strings [normal, "
     "tangential], e.g. [\"nm\", \"nm\"] or [\"N\", \"mN\"]; got ['nm']"),
    ({"units": ["nm", " "]}, "load.history.units", "must be a list of two unit strings "
     "[normal, tangential], e.g. [\"nm\", \"nm\"] or [\"N\", \"mN\"]; got ['nm', ' ']"),
    ({"units": ["nm", 1]}, "load.history.units", "must be a list of two unit strings "
     "[normal, tangential], e.g. [\"nm\", \"nm\"] or [\"N\", \"mN\"]; got ['nm', 1]"),
    ({"units": ["N", "nm"]}, "load.history.units[0]",
     "'1 N' has the unit newton, which is not a length (convertible to m)"),
    ({"units": ["nm", "N"]}, "load.history.units[1]",
     "'1 N' has the unit newton, which is not a length (convertible to m)"),
    ({"normal": "force", "units": ["nm", "nm"]}, "load.history.units[0]",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"tangential": "force", "units": ["nm", "nm"]}, "load.history.units[1]",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"file": 3}, "load.history.file", "must be a file name (a string), got 3"),
    ({"file": "  "}, "load.history.file", "must be a file name (a string), got '  '"),
])
def test_history_refusals(tmp_path, monkeypatch, h, key, message):
    err = history_refused(tmp_path, monkeypatch, **h)
    assert (err.key, err.message) == (key, message)


@pytest.mark.parametrize("missing", ["file", "normal", "tangential"])
def test_history_missing_keys(tmp_path, monkeypatch, missing):
    h = {"file": "h.csv", "normal": "depth", "tangential": "force"}
    del h[missing]
    err = refused({"history": h})
    assert (err.key, err.message) == (f"load.history.{missing}", HISTORY_MISSING)


def test_history_not_a_table():
    err = refused({"history": "h.csv"})
    assert (err.key, err.message) == ("load.history", "must be a table, got str")


@pytest.mark.parametrize("text, message", [
    ("1, 2\n", "h.csv has 1 state(s); a history needs at least two"),
    ("normal, tangential\n", "h.csv has 0 state(s); a history needs at least two"),
    ("0, 0\n1, x\n", "h.csv line 2: expected two numbers (normal, tangential), got '1, x'"),
    ("0, 0\nnan, 1\n", "h.csv line 2: the values must be finite after the unit is applied"),
    ("0, 0\n1, inf\n", "h.csv line 2: the values must be finite after the unit is applied"),
    ("0, 0\n# state 2\n-1, 1\n",
     "h.csv line 3: the normal depth -1e-09 is below 0; valid: >= 0 (a state out of contact is "
     "0)"),
])
def test_history_file_refusals(tmp_path, monkeypatch, text, message):
    err = history_refused(tmp_path, monkeypatch, text, units=["nm", "nm"])
    assert (err.key, err.message) == ("load.history.file", message)


def test_history_overflowing_unit_is_refused(tmp_path, monkeypatch):
    """1e300 km is 1e303 m, finite; 1e306 km overflows to inf once the unit is applied."""
    ok = history_spec(tmp_path, monkeypatch, "0, 0\n1e300, 1\n", units=["km", "km"])
    assert ok.load.values == approx([0.0, 1e303])
    err = history_refused(tmp_path, monkeypatch, "0, 0\n1, 1e306\n", units=["km", "km"])
    assert err.message == "h.csv line 2: the values must be finite after the unit is applied"


def test_history_file_not_found(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    err = refused({"history": {"file": "none.csv", "normal": "depth", "tangential": "force"}})
    assert err.key == "load.history.file"
    assert err.message == f"history file {str(tmp_path / 'none.csv')!r} not found"


def test_history_row_limit(tmp_path, monkeypatch):
    """At most 100000 states: 100000 rows are read, 100001 are refused with the count."""
    rows = "".join(f"{i}, 0\n" for i in range(100_000))
    ok = history_spec(tmp_path, monkeypatch, rows)
    assert len(ok.load.values) == 100_000 and ok.load.values[-1] == 99_999.0
    err = history_refused(tmp_path, monkeypatch, rows + "1, 0\n")
    assert (err.key, err.message) == ("load.history.file",
                                      "h.csv has 100001 states; at most 100000")


# -- [fit] -----------------------------------------------------------------------------------

def fit_spec(tmp_path, monkeypatch, **ft) -> FitSpec:
    monkeypatch.chdir(tmp_path)
    return spec_of(fit=ft).fit


def fit_refused(tmp_path, monkeypatch, **ft) -> SceneError:
    monkeypatch.chdir(tmp_path)
    return refused(fit=ft)


def test_no_fit_table_and_an_empty_one():
    assert spec_of().fit is None
    assert spec_of(fit={}).fit == FitSpec(None, None, None, "E", None, None, None, None, None)


def test_fit_every_key(tmp_path, monkeypatch):
    (tmp_path / "curve.csv").write_text("z, F\n0, 0\n")
    fit = fit_spec(tmp_path, monkeypatch, curve="curve.csv", columns=[" z ", "F"],
                   units=["um", " mN"], modulus="E_star", depth_range=["-1 um", "200 nm"],
                   contact_point="-5 nm", sigma="2 pN", fixed_baseline=["2 nN", "0.1 mN/m"])
    assert fit.curve == tmp_path / "curve.csv"
    assert fit.columns == ("z", "F")
    assert fit.units == approx((1e-6, 1e-3))
    assert fit.modulus == "E_star"
    assert fit.depth_range == approx((-1e-6, 2e-7))
    assert fit.contact_point == approx(-5e-9)
    assert fit.sigma == approx(2e-12)
    assert fit.fixed_contact_point is None
    assert fit.fixed_baseline == approx((2e-9, 1e-4))
    spec = spec_of(fit={"curve": "curve.csv", "units": ["nm", "nN"], "sigma": 1e-9})
    assert spec.read_as["fit.curve"] == ("path", "")
    assert spec.read_as["fit.sigma"] == ("quantity", "force")
    assert spec.fit.units == approx((1e-9, 1e-9))
    assert not any(k.startswith("fit.units") for k in spec.read_as)


def test_fit_curve_folder_and_fixed_contact_point(tmp_path, monkeypatch):
    """A folder of curves is accepted but not echoed as a file; fixed_contact_point alone."""
    (tmp_path / "curves").mkdir()
    monkeypatch.chdir(tmp_path)
    spec = spec_of(fit={"curve": "curves", "fixed_contact_point": "3 nm", "modulus": "E"})
    assert spec.fit.curve == tmp_path / "curves"
    assert "fit.curve" not in spec.read_as
    assert spec.fit.fixed_contact_point == approx(3e-9)
    assert spec.fit.contact_point is None and spec.fit.modulus == "E"
    assert spec.read_as["fit.fixed_contact_point"] == ("quantity", "length")


def test_fit_curve_beside_a_scene_file(tmp_path, monkeypatch):
    """[fit] curve is named relative to the scene's folder too."""
    folder, spec = scene_in_a_folder(tmp_path, monkeypatch, "c.csv:0, 0\n",
                                     '[load]\ndepth = 1e-9\n[fit]\ncurve = "c.csv"\n')
    assert spec.fit.curve == folder / "c.csv"


COLUMNS = "must be the header names of two different columns, position then force, e.g. " \
          "[\"z\", \"F\"]; got "
UNITS = "must be a list of two unit strings [position, force], e.g. [\"nm\", \"nN\"]; got "
RANGE = "must be a list of two depths [lowest, highest] of z - z_0, e.g. [\"-1 um\", " \
        "\"200 nm\"]; got "
BASELINE = "must be a list of the baseline's force at z = 0 and its slope [F_0, s_0], e.g. " \
           "[\"2 nN\", \"0.1 mN/m\"]; got "


@pytest.mark.parametrize("ft, key, message", [
    ({"curves": "c.csv"}, "fit.curves",
     "unknown key; did you mean 'curve'? (allowed: columns, contact_point, curve, depth_range, "
     "fixed_baseline, fixed_contact_point, modulus, sigma, units)"),
    ({"curve": 1}, "fit.curve", "must be a file name (a string), got 1"),
    ({"curve": " "}, "fit.curve", "must be a file name (a string), got ' '"),
    ({"curve": "a\tb"}, "fit.curve", "must be a file name (a string), got 'a\\tb'"),
    ({"curve": "none.csv"}, "fit.curve",
     "'none.csv': no such file or folder (a name relative to the scene's folder)"),
    ({"columns": "z"}, "fit.columns", COLUMNS + "'z'"),
    ({"columns": ["z"]}, "fit.columns", COLUMNS + "['z']"),
    ({"columns": ["z", "F", "t"]}, "fit.columns", COLUMNS + "['z', 'F', 't']"),
    ({"columns": ["z", 1]}, "fit.columns", COLUMNS + "['z', 1]"),
    ({"columns": ["z", " "]}, "fit.columns", COLUMNS + "['z', ' ']"),
    ({"columns": ["z", "F\n"]}, "fit.columns", COLUMNS + "['z', 'F\\n']"),
    ({"columns": ["z", " z"]}, "fit.columns", COLUMNS + "['z', ' z']"),
    ({"units": "nm"}, "fit.units", UNITS + "'nm'"),
    ({"units": ["nm", "nN", "s"]}, "fit.units", UNITS + "['nm', 'nN', 's']"),
    ({"units": ["nm", ""]}, "fit.units", UNITS + "['nm', '']"),
    ({"units": [1, "nN"]}, "fit.units", UNITS + "[1, 'nN']"),
    ({"units": ["nN", "nN"]}, "fit.units[0]",
     "'1 nN' has the unit nanonewton, which is not a length (convertible to m)"),
    ({"units": ["nm", "nm"]}, "fit.units[1]",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"modulus": "G"}, "fit.modulus",
     "must be \"E\" (the sample's Young's modulus, through its nu) or \"E_star\" (the "
     "effective modulus alone); got 'G'"),
    ({"depth_range": 1e-9}, "fit.depth_range", RANGE + "1e-09"),
    ({"depth_range": [0.0, 1e-9, 2e-9]}, "fit.depth_range", RANGE + "[0.0, 1e-09, 2e-09]"),
    ({"depth_range": [2e-9, 1e-9]}, "fit.depth_range",
     "needs lowest < highest and highest > 0 (some indentation), got 2e-09 m and 1e-09 m"),
    ({"depth_range": [1e-9, 1e-9]}, "fit.depth_range",
     "needs lowest < highest and highest > 0 (some indentation), got 1e-09 m and 1e-09 m"),
    ({"depth_range": ["-2 um", "0 m"]}, "fit.depth_range",
     "needs lowest < highest and highest > 0 (some indentation), got -2e-06 m and 0 m"),
    ({"depth_range": [0.0, "1 N"]}, "fit.depth_range[1]",
     "'1 N' has the unit newton, which is not a length (convertible to m)"),
    ({"contact_point": "1 N"}, "fit.contact_point",
     "'1 N' has the unit newton, which is not a length (convertible to m)"),
    ({"sigma": 0.0}, "fit.sigma", "must be > 0, got 0.0"),
    ({"sigma": "1 nm"}, "fit.sigma",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"contact_point": 0.0, "fixed_contact_point": 0.0}, "fit.fixed_contact_point",
     "and fit.contact_point (a guess) exclude each other: give one"),
    ({"fixed_contact_point": "1 N"}, "fit.fixed_contact_point",
     "'1 N' has the unit newton, which is not a length (convertible to m)"),
    ({"fixed_baseline": 0.0}, "fit.fixed_baseline", BASELINE + "0.0"),
    ({"fixed_baseline": [0.0]}, "fit.fixed_baseline", BASELINE + "[0.0]"),
    ({"fixed_baseline": ["1 nm", 0.0]}, "fit.fixed_baseline[0]",
     "'1 nm' has the unit nanometer, which is not a force (convertible to N)"),
    ({"fixed_baseline": [0.0, "1 N"]}, "fit.fixed_baseline[1]",
     "'1 N' has the unit newton, which is not a force per length (a force baseline's slope) "
     "(convertible to N/m)"),
])
def test_fit_refusals(tmp_path, monkeypatch, ft, key, message):
    err = fit_refused(tmp_path, monkeypatch, **ft)
    assert (err.key, err.message) == (key, message)


def test_fit_curve_name_too_long(tmp_path, monkeypatch):
    """A name the system cannot stat (too long) is refused by name, not with a traceback."""
    name = "x" * 5000
    err = fit_refused(tmp_path, monkeypatch, curve=name)
    assert err.key == "fit.curve"
    assert err.message.startswith(f"{name!r} cannot be a file name ([Errno ")
    assert "\n" not in err.message
