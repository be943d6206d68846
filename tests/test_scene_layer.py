"""The scene layer's structure and its accuracy contract: the registries agree with each other,
the materials and interface objects, rtol outside a method's range is one clear error, and an
effect's label never claims a tolerance its error did not meet."""

import dataclasses
import math

import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.cli import main
from hertzmdr.numeric.scene import accuracy
from hertzmdr.numeric.scene.kinds import KINDS
from hertzmdr.numeric.scene.materials import Interface, Material, Materials
from hertzmdr.numeric.scene.shapes import SHAPES
from hertzmdr.numeric.scene.shapes.base import VALUE_KINDS

SPHERE = {"effects": ["force"], "load": {"depth": "1 um"},
          "body": [{"shape": "sphere", "radius": "5 mm", "E": "200 GPa", "nu": 0.3},
                   {"shape": "flat", "rigid": True}]}
IMPACT = {"effects": ["contact_time"],
          "load": {"impact": {"velocity": 1.0, "density": "7.8 g/cm^3"}},
          "body": [{"shape": "sphere", "radius": "10 mm", "E": "210 GPa", "nu": 0.3},
                   {"shape": "flat", "rigid": True}]}


def test_registries_agree():
    """Every kind a shape lists is a row of KINDS and some shape makes every row; every key
    is read by a known reader; each shape provides the geometry its kinds build from."""
    rows = {k.name for k in KINDS}
    listed = {k for s in SHAPES.values() for k in s.kinds}
    assert listed <= rows and rows - listed <= {"impact"} | listed
    geometry = {"quadratic": "principal", "mdr": "mdr", "numerical_mdr": "samples",
                "bem": "height"}
    for s in SHAPES.values():
        assert all(k.kind in VALUE_KINDS for k in s.keys), s.name
        for k in s.kinds:
            if k in geometry:
                assert callable(getattr(s, geometry[k], None)), (s.name, k)
    for row in KINDS:
        mod = __import__(f"hertzmdr.numeric.scene.kinds.{row.module}", fromlist=[row.builder])
        assert callable(getattr(mod, row.builder)), row


def test_materials_and_interface():
    """E* (5.26) from both bodies or the elastic one; the stressed body is the first elastic
    one; both objects are frozen; G* of the tangential springs; the interface holds the work
    of adhesion (0: none) and the friction."""
    steel, glass = Material("a", 210e9, 0.3), Material("b", 70e9, 0.22)
    m = Materials.of(steel, glass)
    ref = 1 / ((1 - 0.3**2) / 210e9 + (1 - 0.22**2) / 70e9)
    assert abs(m.E_star / ref - 1) < 1e-15
    rigid = Materials.of(Material("tip", None, None), glass)
    assert abs(rigid.E_star / (70e9 / (1 - 0.22**2)) - 1) < 1e-15
    assert rigid.stressed.body == "b"
    with pytest.raises(dataclasses.FrozenInstanceError):
        m.E_star = 1.0
    adhesion = {"work_of_adhesion": "surface_energy", "range": "length"}
    assert {f.name for f in dataclasses.fields(Interface)} >= set(adhesion)
    assert Interface.KEYS.items() >= adhesion.items() and not Interface().adhesive
    assert Interface().friction is None and Interface.KEYS["friction"] == "number"
    G1, G2 = 210e9 / 2.6, 70e9 / 2.44  # G* (derive/tangential.py) from both bodies
    assert abs(m.G_star * ((2 - 0.3) / (4 * G1) + (2 - 0.22) / (4 * G2)) - 1) < 1e-15
    with pytest.raises(ValueError, match="rigid"):
        Materials.of(Material("x", None, None), Material("y", None, None))


def test_interface_table_accepts_no_keys_yet():
    scene.load({**SPHERE, "interface": {}}).run()
    assert scene.load({**SPHERE, "interface": {"friction": 0.3}}).spec.interface.friction == 0.3
    with pytest.raises(scene.SceneError, match=r"interface\.stickiness: unknown key"):
        scene.load({**SPHERE, "interface": {"stickiness": 0.3}})


SPHERE_TOML = """effects = ["force"]
[accuracy]
rtol = RTOL
[[body]]
shape = "sphere"
radius = "5 mm"
E = "200 GPa"
nu = 0.3
[[body]]
shape = "flat"
rigid = true
[load]
depth = "1 um"
"""
IMPACT_TOML = SPHERE_TOML.replace('["force"]', '["contact_time"]').replace(
    '[load]\ndepth = "1 um"', '[load.impact]\nvelocity = 1.0\nmass = 0.1')


@pytest.mark.parametrize("text, rtol, range_", [
    (IMPACT_TOML, 0.01, accuracy.MOTION_RANGE), (IMPACT_TOML, 1e-14, accuracy.MOTION_RANGE),
    (SPHERE_TOML, 1e-15, accuracy.CLOSED_FORM_RANGE)])
def test_rtol_outside_a_methods_range_is_one_clear_error(tmp_path, capsys, text, rtol, range_):
    """The CLI prints one line naming accuracy.rtol, the value and the range; exit 2."""
    path = tmp_path / "scene.toml"
    path.write_text(text.replace("RTOL", repr(rtol)))
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "accuracy.rtol" in err and f"{rtol:g}" in err
    assert f"[{range_[0]:g}, {range_[1]:g}]" in err


def test_rtol_reaches_the_impact_and_default_is_documented():
    doc = scene.load(IMPACT).run()
    assert doc["model"]["rtol"] == accuracy.DEFAULT_RTOL
    assert f"rtol {accuracy.DEFAULT_RTOL:g}" in doc["effects"]["contact_time"]["method"]
    assert doc["effects"]["contact_time"]["met_rtol"] is True


def test_misses_are_reported_and_flagged(capsys):
    """The BEM's error is its pixel size, not its tolerance: met_rtol is false and the table
    flags it; the chapter's Gaussian estimate likewise."""
    from pathlib import Path

    examples = Path(__file__).parents[1] / "examples"
    doc = scene.load(examples / "beta_triangle_punch.toml").run()
    for name, eff in doc["effects"].items():
        assert eff["met_rtol"] == (eff["rel_error"] <= doc["model"]["rtol"]), name
    assert not doc["effects"]["force"]["met_rtol"]
    assert main(["run", str(examples / "beta_triangle_punch.toml")]) == 0
    out = capsys.readouterr().out
    assert "> rtol (!)" in out and "rel. error above rtol" in out


@pytest.mark.parametrize("rtol", [1e-10, 1e-3])
def test_numerical_mdr_never_claims_an_unmet_rtol(rtol):
    """A sampled paraboloid by the numerical MDR: no method text names a tolerance as met,
    met_rtol follows each effect's own error, and the force agrees with Hertz (5.23) within
    the error the scene reports."""
    r = [i * 20e-6 / 59 for i in range(60)]
    R, E = 50e-6, 130e9 / (1 - 0.28**2)
    doc = scene.load({
        "effects": ["force", "pressure_profile", "mean_pressure"], "accuracy": {"rtol": rtol},
        "load": {"depth": "50 nm"},
        "body": [{"shape": "profile", "r": r, "f": [x * x / (2 * R) for x in r], "rigid": True},
                 {"shape": "flat", "E": "130 GPa", "nu": 0.28}]}).run()
    for name, eff in doc["effects"].items():
        assert "met" not in eff["method"] or "not met" in eff["method"], name
        assert eff["met_rtol"] == (eff["rel_error"] <= rtol), name
    F = doc["effects"]["force"]
    hertz = 4 / 3 * E * math.sqrt(R) * 50e-9**1.5  # (5.23)
    # the samples of the cubic spline carry the profile to ~1e-13 (an interpolating spline of
    # a parabola is exact up to rounding), so the estimate bounds the difference
    assert abs(F["value"] / hertz - 1) <= max(F["rel_error"], 1e-13)


def test_exact_sphere_is_one_shape_module():
    """The exact sphere (shapes/exact_sphere.py, nothing else) at a/R = 0.5 against Sneddon's
    closed form in the contact radius (1965), F = (E*/2) ((a^2 + R^2) ln((R + a)/(R - a))
    - 2 a R) at d = (a/2) ln((R + a)/(R - a)), at 30 digits; shallow, it tends to Hertz."""
    from pathlib import Path

    import mpmath as mp

    examples = Path(__file__).parents[1] / "examples"
    doc = scene.load(examples / "exact_sphere_deep.toml").run()
    assert doc["model"]["kind"] == "exact_sphere"
    R, E = mp.mpf("1e-3"), mp.mpf(10e6) / (1 - mp.mpf(0.5) ** 2)
    with mp.workdps(30):
        d = mp.mpf(0.274653e-3)  # the example's depth, as written
        a = mp.findroot(lambda x: x / 2 * mp.log((R + x) / (R - x)) - d, R / 2)
        F = E / 2 * ((a * a + R * R) * mp.log((R + a) / (R - a)) - 2 * a * R)
        # closed forms in float64 (1e-14, the contract of every closed form) against 30 digits
        assert abs(doc["effects"]["contact_radius"]["value"] / a - 1) < 1e-14
        assert abs(doc["effects"]["force"]["value"] / F - 1) < 1e-14
    shallow = scene.load({
        "effects": ["force", "contact_radius"], "load": {"depth": "1 nm"},
        "body": [{"shape": "exact_sphere", "radius": "1 mm", "rigid": True},
                 {"shape": "flat", "E": "10 MPa", "nu": 0.5}]}).run()["effects"]
    hertz = 4 / 3 * float(E) * 1e-3**0.5 * 1e-9**1.5  # (5.23)
    # the cap's force is below Hertz's by (a/R)^2/10 = 1e-7 at a/R = 1e-3 (docs/sphere.md)
    assert 0 < 1 - shallow["force"]["value"] / hertz < 2e-7


@pytest.mark.parametrize("body", [{"shape": "cone", "angle": "80 deg"},
                                  {"shape": "flat_punch", "radius": 1e-3},
                                  {"shape": "flattened_parabola", "radius": 0.05,
                                   "flat_radius": 1e-4}])
def test_maxima_under_a_singular_pressure(body):
    """+inf at the singular radius for nu < 0.5 (the surface stress grows like (1 - 2 nu) p);
    refused with the reason for nu = 0.5, where that term vanishes and no grid bounds the
    maximum."""
    def spec(nu):
        return {"effects": ["max_shear", "max_von_mises"], "load": {"depth": 1e-6},
                "body": [{**body, "rigid": True}, {"shape": "flat", "E": 70e9, "nu": nu}]}

    eff = scene.load(spec(0.3)).run()["effects"]
    for name in ("max_shear", "max_von_mises"):
        assert eff[name]["value"]["value"] == math.inf and eff[name]["rel_error"] == 0
        assert eff[name]["method"].startswith("unbounded")
    with pytest.raises(scene.SceneError, match="hydrostatic"):
        scene.load(spec(0.5)).run()
