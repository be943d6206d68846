"""Scenes: exactly the requested effects, only the code they need, the documented output."""

import json
import math
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.cli import main, tour_scenes
from hertzmdr.numeric.scene.effects import EFFECTS

EXAMPLES = Path(__file__).parents[1] / "examples"
RAIL = EXAMPLES / "problem1_rail_wheel.toml"


def test_json_document_has_exactly_the_requested_effects(capsys):
    assert main(["run", str(RAIL), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert set(doc) == {"title", "model", "effects", "warnings", "scene", "files",
                        "hertzmdr_version"}  # the last three: echo.inputs
    assert list(doc["effects"]) == ["max_pressure", "contact_radius", "effective_modulus",
                                    "depth"]
    for name, eff in doc["effects"].items():
        assert set(eff) == {"value", "unit", "method", "rel_error", "met_rtol", "seconds"}, name
        assert eff["unit"] == EFFECTS[name].unit
    assert doc["model"]["kind"] == "hertz"


def test_python_api_returns_the_same_document():
    doc = scene.load(RAIL).run()
    assert doc["effects"]["max_pressure"]["unit"] == "Pa"


def test_only_what_is_asked_is_run():
    """A scene asking only for force evaluates the model and the contact state, nothing else,
    and never imports the stress or impact code (checked in a fresh interpreter)."""
    spec = {"effects": ["force"], "load": {"depth": "1 um"},
            "body": [{"shape": "sphere", "radius": "5 mm", "E": "200 GPa", "nu": 0.3},
                     {"shape": "flat", "rigid": True}]}
    record, results, doc = scene.load(spec).run_full()
    assert record.evaluated == ["model", "state", "force"]
    code = ("import sys, json; from hertzmdr.numeric import scene;"
            f"scene.load({spec!r}).run();"
            "print(json.dumps(sorted(m for m in sys.modules if m.startswith('hertzmdr'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    loaded = json.loads(out.stdout)
    for forbidden in ("hertzmdr.numeric.stress", "hertzmdr.numeric.impact",
                      "hertzmdr.numeric.motion", "scipy.integrate",
                      "hertzmdr.numeric.mdr", "hertzmdr.numeric.plots", "sympy"):
        assert forbidden not in loaded, forbidden


def test_out_refuses_a_non_empty_folder(tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "keep.txt").write_text("mine")
    assert main(["run", str(RAIL), "--out", str(out)]) == 2
    assert "not empty" in capsys.readouterr().err
    assert (out / "keep.txt").read_text() == "mine"
    assert main(["run", str(RAIL), "--out", str(out), "--force"]) == 0
    assert (out / "keep.txt").read_text() == "mine"
    assert json.loads((out / "result.json").read_text())["title"].startswith("Rail-wheel")


def test_out_writes_nothing_when_the_run_fails(tmp_path, monkeypatch):
    """Atomic output: a failure while writing leaves no half-written file in DIR."""
    from hertzmdr.numeric.scene import figures

    def broken(*args, **kwargs):
        raise RuntimeError("disk full")

    spec_path = tmp_path / "s.toml"
    spec_path.write_text(RAIL.read_text().replace(
        'effects = ["max_pressure", "contact_radius", "effective_modulus", "depth"]',
        'effects = ["max_pressure", "pressure_profile"]'))
    monkeypatch.setitem(figures.FIGURES, "pressure_profile", broken)
    out = tmp_path / "out"
    with pytest.raises(RuntimeError):
        main(["run", str(spec_path), "--out", str(out)])
    assert not out.exists() or not any(out.iterdir())
    assert not list(tmp_path.glob(".hertzmdr-*"))


def test_field_effects_write_pngs(tmp_path):
    spec_path = tmp_path / "s.toml"
    spec_path.write_text(RAIL.read_text().replace(
        'effects = ["max_pressure", "contact_radius", "effective_modulus", "depth"]',
        'effects = ["pressure_profile", "surface_displacement", "force_depth_curve"]'))
    out = tmp_path / "out"
    assert main(["run", str(spec_path), "--out", str(out)]) == 0
    for name in ("pressure_profile", "surface_displacement", "force_depth_curve"):
        png = out / f"{name}.png"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name


def test_roller_scene_writes_its_stress_figures(tmp_path, monkeypatch):
    """The tour's roller scene draws its axis stresses with the plane-strain sigma_yy (four
    curves, the line contact's labels) and its von Mises map."""
    from hertzmdr.numeric import plots

    drawn = {}
    original = plots.draw_axis_stresses

    def spy(path, z, szz, sxx, tau1, **kw):
        drawn.update(kw)
        return original(path, z, szz, sxx, tau1, **kw)

    monkeypatch.setattr(plots, "draw_axis_stresses", spy)
    out = tmp_path / "out"
    assert main(["run", str(EXAMPLES / "roller_pair_stresses.toml"), "--out", str(out)]) == 0
    for name in ("axis_stresses", "von_mises_field"):
        assert (out / f"{name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
    assert drawn["syy"] is not None and "plane strain" in drawn["title"]


def test_every_effect_is_documented():
    text = (Path(__file__).parents[1] / "docs" / "scenes.md").read_text()
    for name, eff in EFFECTS.items():
        assert f"### `{name}` [{eff.unit}]" in text, name


def test_effects_command_lists_every_effect(capsys):
    assert main(["effects"]) == 0
    out = capsys.readouterr().out
    for name in EFFECTS:
        assert name in out


def test_tour_is_installed_with_the_package():
    names = {p.name for p in tour_scenes()}
    assert names == {p.name for p in EXAMPLES.glob("*.toml")}


# The chapter's numbers, each with the tolerance its own rounding allows.
CHAPTER = {
    # Problem 1 rounds E* = 1.154e11 Pa to 1.2e11 Pa (4 %) and prints two digits: p0 ~ E*^(2/3)
    # moves by 2.6 %, a ~ E*^(-1/3) by 1.3 % (6.875 mm exactly, 6.79 mm with the rounded E*)
    "problem1_rail_wheel.toml": {"max_pressure": (1.0e9, 0.05e9 + 0.026e9),
                                 "contact_radius": (6.8e-3, 0.05e-3 + 0.013 * 6.8e-3)},
    # Problem 2 with the Gaussian radius, as the chapter solves it, and its erratum applied
    # (docs/errata.md: R~ = sqrt(2) R, so F = 2^(5/4)/3 E/(1 - nu^2) R^(1/2) d^(3/2)); a few
    # float64 roundings apart
    "problem2_crossed_cylinders.toml": {
        "force": (2 ** 1.25 / 3 * 210e9 / (1 - 0.3**2) * 0.02**0.5 * 5e-6**1.5, 1e-13 * 289.3),
        "effective_radius": (2**0.5 * 0.02, 1e-15)},
    # Problem 4 prints p0 = 3.2e9 Pa (two digits) for E* = 1e11 Pa, rho = 7.8e3, v0 = 1 m/s
    # Problem 6: u(0) = 2 p0 a/E*, u(a) = 4 p0 a/(pi E*); E* = E/(1 - nu^2) with a rigid plate
    "problem6_uniform_pressure.toml": {
        "depth": (2 * 10e6 * 2e-3 / (70e9 / (1 - 0.33**2)), 1e-14 * 5.1e-7),
        "edge_displacement": (4 * 10e6 * 2e-3 / (3.141592653589793 * 70e9 / (1 - 0.33**2)),
                              1e-14 * 3.3e-7)},
    # Problems 5, 7 and 8: the chapter's formulas, evaluated here in float64 (a few roundings)
    "problem5_differential_stiffness.toml": {
        "stiffness": (2 * (2 * 200e-9 / (math.pi * math.tan(math.radians(19.7))))
                      * 72e9 / (1 - 0.17**2), 1e-13 * 1e4)},
    "problem7a_flat_punch.toml": {"force": (2 * 5e6 / (1 - 0.49**2) * 0.5e-3 * 10e-6, 1e-14)},
    "problem7b_parabola.toml": {
        "force": (4 / 3 * 210e9 / (1 - 0.09) * 0.01**0.5 * 1e-6**1.5, 1e-13 * 0.5),
        "contact_radius": ((0.01 * 1e-6) ** 0.5, 1e-13 * 1e-4)},
    "problem7c_cone.toml": {  # (5.40) inverted at F = 10 mN, and a from (5.38)
        "contact_radius": (2 / math.pi * (10e-3 * math.tan(math.radians(30)) * math.pi
                                          / (2 * 3e9 / (1 - 0.35**2))) ** 0.5
                           / math.tan(math.radians(30)), 1e-13 * 2e-6)},
    "problem8_worn_parabola.toml": {  # F(a) of Problem 8 at the contact radius found
        "force": (None, 1e-12)},
    # (5.37) with the pi the print lacks: p0 = (E* F/(pi L R))^(1/2), R from (5.27)
    "line_contact_roller.toml": {"max_pressure": (
        (210e9 / (2 * (1 - 0.09)) * 5e3 / (math.pi * 0.01 * (5e-3 * 25e-3 / 30e-3))) ** 0.5,
        1e-14 * 2.1e9)},
    "problem4_impact_pressure.toml": {"max_impact_pressure": (3.2e9, 0.05e9),
                                      "effective_modulus": (1e11, 1e-4)},
}


def test_problem3_contact_time_constant():
    """tau = 2.94 x0/v0 (the chapter prints three digits)."""
    doc = scene.load(EXAMPLES / "problem3_impact_time.toml").run()
    tau = doc["effects"]["contact_time"]["value"]
    x0 = doc["effects"]["max_impact_depth"]["value"]
    assert abs(tau * 1.0 / x0 - 2.94) < 0.005
    # and the integrated equation of motion confirmed the closed form (default rtol 1e-10)
    assert doc["effects"]["contact_time"]["rel_error"] < 1e-9


def test_impact_motion_integrated_only_when_asked():
    spec = {"effects": ["max_pressure"], "load": {"impact": {"velocity": 2.0, "mass": 0.1}},
            "body": [{"shape": "sphere", "radius": "5 mm", "E": "200 GPa", "nu": 0.3},
                     {"shape": "flat", "rigid": True}]}
    record, _, _ = scene.load(spec).run_full()
    assert "impact" not in record.evaluated
    spec["effects"] = ["max_pressure", "contact_time", "max_impact_pressure"]
    record, _, doc = scene.load(spec).run_full()
    assert record.evaluated.count("impact") == 1
    # the contact state at the largest compression and the impact agree on the pressure: both
    # are (5.22) at the x0 of Problem 3 (closed forms, 1e-14 each), reached by two paths (the
    # state node and the impact node)
    p_state = doc["effects"]["max_pressure"]["value"]
    p_impact = doc["effects"]["max_impact_pressure"]["value"]
    assert abs(p_state / p_impact - 1) <= 2e-14
    # and the integrated equation of motion reached the same largest pressure within the
    # disagreement the scene reports for it
    assert doc["effects"]["max_impact_pressure"]["rel_error"] < 1e-9
    assert "equation of motion" in doc["effects"]["contact_time"]["method"]


@pytest.mark.parametrize("name", sorted(CHAPTER))
def test_examples_give_the_chapters_numbers(name):
    doc = scene.load(EXAMPLES / name).run()
    for effect, (value, tol) in CHAPTER[name].items():
        got = doc["effects"][effect]["value"]
        if value is None:  # Problem 8: F(a) = (2 E*/(3R)) (2 a^2 + b^2) sqrt(a^2 - b^2)
            a, b, R, E = doc["effects"]["contact_radius"]["value"], 2e-6, 50e-6, 130e9 / (
                1 - 0.28**2)
            value = 2 * E / (3 * R) * (2 * a * a + b * b) * math.sqrt(a * a - b * b)
            tol *= value
        assert abs(got - value) <= tol, (name, effect, got, value)


def _documented_infinite(effect: str) -> bool:
    """Whether docs/scenes.md says this effect can be +inf (in its own section)."""
    text = (Path(__file__).parents[1] / "docs" / "scenes.md").read_text()
    head = f"### `{effect}` ["
    if head not in text:
        return False
    section = text.split(head, 1)[1].split("\n### ", 1)[0]
    return "+inf" in section


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_every_example_runs(path):
    """Through the installed command: `hertzmdr run SCENE --json` exits 0 and prints one JSON
    document with exactly the requested effects, every number finite (or +inf where
    docs/scenes.md documents it for that effect)."""
    exe = Path(sys.executable).with_name("hertzmdr")
    out = subprocess.run([str(exe), "run", str(path), "--json"], capture_output=True,
                         text=True, timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    infinite = []

    def constant(name):  # json calls this for NaN, Infinity and -Infinity
        infinite.append(name)
        return {"NaN": math.nan, "Infinity": math.inf, "-Infinity": -math.inf}[name]

    doc = json.loads(out.stdout, parse_constant=constant)
    asked = tomllib.loads(path.read_text())["effects"]
    assert list(doc["effects"]) == asked
    for name, eff in doc["effects"].items():
        values = np.asarray(eff["value"] if not isinstance(eff["value"], dict)
                            else np.concatenate([np.ravel(np.asarray(v, dtype=float))
                                                 for v in eff["value"].values()]), dtype=float)
        bad = values[~np.isfinite(values)]
        assert np.all(bad == np.inf) and (bad.size == 0 or _documented_infinite(name)), \
            f"{name}: {bad.size} non-finite values"
        assert math.isfinite(eff["rel_error"]) and eff["rel_error"] >= 0, name
    assert all(v == "Infinity" for v in infinite)


def test_stress_node_runs_once_and_only_when_asked():
    spec = {"effects": ["max_shear", "max_von_mises", "force"], "load": {"force": "100 N"},
            "body": [{"shape": "sphere", "radius": "10 mm", "rigid": True},
                     {"shape": "flat", "E": "210 GPa", "nu": 0.3}]}
    record, _, doc = scene.load(spec).run_full()
    assert record.evaluated.count("stress") == 1
    a = (3 * 100 * 0.01 / (4 * 210e9 / (1 - 0.09))) ** (1 / 3)  # (5.24)
    # Johnson's classical maximum for nu = 0.3: tau_1 = 0.31 p0 at z = 0.48 a (two digits)
    assert abs(doc["effects"]["max_shear"]["value"]["depth"] / a - 0.48) < 0.005
    spec["effects"] = ["force"]
    record, _, _ = scene.load(spec).run_full()
    assert "stress" not in record.evaluated


def test_fig5_8_maximum_shear_depth():
    """Fig. 5.8: for nu = 0.33 the maximum shear lies at z ~ 0.49 a (two digits printed)."""
    doc = scene.load(EXAMPLES / "fig5_8_fig5_9_stresses.toml").run()
    a = doc["effects"]["contact_radius"]["value"]
    assert abs(doc["effects"]["max_shear"]["value"]["depth"] / a - 0.49) < 0.005


def test_accuracy_rtol_changes_the_numerical_effects():
    """[accuracy] rtol reaches the numerical methods: the impact's integrated motion reports a
    larger disagreement with the closed form at rtol 1e-4 than at 1e-12 (both within their
    tolerance's reach: DOP853's global error is a small multiple of rtol)."""
    base = {"effects": ["contact_time"],
            "load": {"impact": {"velocity": 1.0, "density": "7.8 g/cm^3"}},
            "body": [{"shape": "sphere", "radius": "10 mm", "E": "210 GPa", "nu": 0.3},
                     {"shape": "flat", "rigid": True}]}
    loose = scene.load({**base, "accuracy": {"rtol": 1e-4}}).run()["effects"]["contact_time"]
    tight = scene.load({**base, "accuracy": {"rtol": 1e-12}}).run()["effects"]["contact_time"]
    assert 1e-8 < loose["rel_error"] < 1e-3
    assert tight["rel_error"] < 1e-10
    assert "rtol 0.0001" in loose["method"] and "rtol 1e-12" in tight["method"]
    assert loose["seconds"] > 0 and tight["seconds"] > 0


def test_height_map_meets_hertz():
    """The sampled paraboloid (R = 1 mm) solved by the BEM agrees with (5.23) within the
    error the scene reports (its difference from a half-resolution solve)."""
    doc = scene.load(EXAMPLES / "height_map_tip.toml").run()
    F = doc["effects"]["force"]
    hertz_F = 4 / 3 * 2e9 / (1 - 0.16) * 1e-3**0.5 * 1e-7**1.5  # (5.23)
    assert abs(F["value"] / hertz_F - 1) <= F["rel_error"]


def test_worn_tip_pressure_and_stresses(tmp_path):
    """A worn tip's scene gives the closed-form pressure (Problem 8) and the stresses under it:
    the pressure integrates to the scene's force, and sigma_zz under the centre tends to -p(0).
    """
    path = tmp_path / "worn.toml"
    path.write_text('effects = ["force", "pressure_profile", "axis_stresses"]\n'
                    '[[body]]\nshape = "flattened_parabola"\nradius = "50 um"\n'
                    'flat_radius = "2 um"\nrigid = true\n'
                    '[[body]]\nshape = "flat"\nE = "130 GPa"\nnu = 0.28\n'
                    '[load]\ndepth = "50 nm"\n')
    eff = scene.load(path).run()["effects"]
    prof = eff["pressure_profile"]["value"]
    r, p = np.asarray(prof["r"]), np.asarray(prof["p"])
    assert np.all(np.isfinite(p)) and p[-1] == 0.0
    # trapezoid over 201 points across a log singularity at b and a square root at a: the
    # rule's error is O(h log h) there, ~1 % for h = a/134
    F = np.trapezoid(2 * np.pi * r * p, r)
    assert abs(F / eff["force"]["value"] - 1) < 0.02
    ax = eff["axis_stresses"]
    szz = np.asarray(ax["value"]["sigma_zz"])
    # sigma_zz(z) = -p(0) + O(z) on the axis: the first depth is ~a/10; allow that and the
    # route's own error estimate
    assert abs(szz[0] / -p[0] - 1) < 0.05 + ax["rel_error"]


def test_numbers_quoted_in_the_scene_docs_come_from_a_run():
    """docs/scenes.md's Python example quotes Problem 1's max_pressure: it must be what a run
    gives, to the 5 digits it prints (it once said 1.0134e9 where the run gives 1.0101e9)."""
    import re
    from pathlib import Path

    from hertzmdr.numeric import scene

    text = (Path(__file__).resolve().parents[1] / "docs" / "scenes.md").read_text()
    quoted = re.search(r'\["max_pressure"\]\["value"\]\s*# ([0-9.e+-]+) \(Pa\)', text)
    assert quoted, "the example line moved: update this test"
    value = scene.load(next(p for p in tour_scenes() if p.stem == "problem1_rail_wheel")).run()
    got = value["effects"]["max_pressure"]["value"]
    assert abs(float(quoted.group(1)) / got - 1) < 5e-5  # 5 significant digits printed
