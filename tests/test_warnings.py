"""Warnings in results (issue 12): a scene that stretches an assumption of the chapter (a
contact large against the radius of curvature, a steep cone, a short line contact, ...) still
runs, and its result names the assumption, the measured ratio and the limit, in the table, in
result.json and in the Python API's document. Every example scene warns of exactly what
docs/scenes.md says it does.

The ratios are checked against the run's own reported effects and the scene's inputs
(contact_radius / R, half_width / L, depth / contact_radius), so a ratio wired to the wrong
quantity fails."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.cli import main, tour_scenes
from hertzmdr.numeric.scene.assumptions import ASSUMPTIONS, markdown

ROOT = Path(__file__).resolve().parents[1]
#: the example scenes that warn, and of which ratios (docs/scenes.md, "Warnings")
EXPECTED = {"exact_sphere_deep": {"a/R", "d/R"},
            "problem5_differential_stiffness": {"tan(theta)"},
            "problem7c_cone": {"tan(theta)"},
            "afm_sphere_tip_pdms": {"a/R", "d/R"},
            "afm_cone_tip_pdms": {"tan(theta)"},
            "pyramid_berkovich_silica": {"tan(theta)", "1/sides"},
            "fit_pyramid_afm": {"tan(theta)", "1/sides"}}
#: the relative agreement of a warning's value with the same ratio from the reported effects:
#: both are quotients of the same float64 quantities, a few roundings apart
RATIO_RTOL = 1e-14


def _rigid(**keys) -> dict:
    return {"name": "indenter", "rigid": True, **keys}


def _flat(E="70 GPa") -> dict:
    return {"name": "half-space", "shape": "flat", "E": E, "nu": 0.3}


def _run(indenter, load, effects, other=None):
    doc = scene.load({"effects": effects, "body": [indenter, other or _flat()],
                      "load": load}).run()
    values = {k: v["value"] for k, v in doc["effects"].items()}
    return values, {w["ratio"]: w for w in doc["warnings"]}


def test_a_over_R_37_at_1e308_N():
    """The issue's scene: a 1e308 N load on a 5 mm sphere (a modulus of 5.4e307 Pa keeps the
    numbers finite) gives a/R = 37."""
    got, warned = _run(_rigid(shape="sphere", radius="5 mm"), {"force": 1e308},
                       ["contact_radius", "depth"], _flat("5.4e307 Pa"))
    assert set(warned) == {"a/R", "d/R"}
    assert warned["a/R"]["value"] == pytest.approx(got["contact_radius"] / 5e-3, rel=RATIO_RTOL)
    assert round(warned["a/R"]["value"]) == 37
    assert warned["d/R"]["value"] == pytest.approx(got["depth"] / 5e-3, rel=RATIO_RTOL)
    w = warned["a/R"]
    assert w["limit"] == ASSUMPTIONS["a/R"].limit == 0.1
    assert w["message"] == ("a/R = 37 exceeds the limit 0.1: the half-space approximation "
                            "takes the contact radius small against the radius of curvature")


def test_a_168_mm_on_a_5_mm_sphere():
    got, warned = _run(_rigid(shape="sphere", radius="5 mm"), {"depth": "5.6448 m"},
                       ["contact_radius"])
    assert got["contact_radius"] == pytest.approx(0.168, rel=1e-14)  # a = sqrt(R d) (5.21)
    assert warned["a/R"]["value"] == pytest.approx(33.6, rel=RATIO_RTOL)
    assert "d/R" in warned


def test_each_kind_measures_its_ratios():
    """One scene per kind past its limits; each warning's value is the same ratio of the
    reported effects."""
    E1 = _flat("1 GPa")
    got, w = _run(_rigid(shape="cylinder", radius="5 mm", length="1 mm", axis="0 deg"),
                  {"force": "1 kN"}, ["half_width", "depth"], E1)
    assert set(w) == {"a/R", "d/R", "a/L"}
    assert w["a/L"]["value"] == pytest.approx(got["half_width"] / 1e-3, rel=RATIO_RTOL)
    assert w["a/R"]["value"] == pytest.approx(got["half_width"] / 5e-3, rel=RATIO_RTOL)

    got, w = _run(_rigid(shape="ellipsoid", radii=["5 mm", "10 mm"]), {"force": "1 kN"},
                  ["semi_axes", "depth"], E1)
    a, b = got["semi_axes"]  # a along the smaller radius R1 = 5 mm, b along R2 = 10 mm
    assert w["a/R"]["value"] == pytest.approx(max(a / 5e-3, b / 10e-3), rel=RATIO_RTOL)
    assert w["d/R"]["value"] == pytest.approx(got["depth"] / 5e-3, rel=RATIO_RTOL)

    for indenter, load in ((_rigid(shape="power_law", coefficient=1e6, exponent=3),
                            {"depth": "50 um"}),
                           (_rigid(shape="flat_punch", radius="1 mm"), {"depth": "0.2 mm"}),
                           (_rigid(shape="profile", r=["0 um", "10 um", "20 um", "40 um"],
                                   f=["0 um", "1 um", "3 um", "9 um"]), {"depth": "2 um"})):
        got, w = _run(indenter, load, ["contact_radius", "depth"], E1)
        assert set(w) == {"d/a"}, indenter["shape"]
        assert w["d/a"]["value"] == pytest.approx(got["depth"] / got["contact_radius"],
                                                  rel=RATIO_RTOL)

    got, w = _run(_rigid(shape="flattened_parabola", radius="50 um", flat_radius="2 um"),
                  {"depth": "2 um"}, ["contact_radius"], E1)
    assert set(w) == {"a/R", "d/R"}
    assert w["a/R"]["value"] == pytest.approx(got["contact_radius"] / 50e-6, rel=RATIO_RTOL)

    got, w = _run(_rigid(shape="cone", angle="10 deg"), {"depth": "1 um"}, ["force"], E1)
    assert set(w) == {"tan(theta)"}
    assert w["tan(theta)"]["value"] == pytest.approx(0.17632698070846498, rel=1e-15)

    got, w = _run(_flat("1 MPa"), {"pressure": {"distribution": "uniform", "p0": "0.1 MPa",
                                               "radius": "1 mm"}}, ["depth"], _rigid(shape="flat"))
    assert w["d/a"]["value"] == pytest.approx(got["depth"] / 1e-3, rel=RATIO_RTOL)


def test_the_afm_examples_numbers():
    """The AFM sphere (R = 20 nm) pushed to d = 10 nm: d/R = 0.5 and a/R = 1.978, the JKR
    contact radius of a = 39.57 nm (a^2/R - sqrt(2 pi a dgamma/E*) = d, solved at 30 digits);
    the AFM cone's tan(20 deg) = 0.364."""
    import mpmath as mp

    from hertzmdr.numeric.scene.model import build

    sphere = next(p for p in tour_scenes() if p.stem == "afm_sphere_tip_pdms")
    w = {x["ratio"]: x for x in scene.load(sphere).run()["warnings"]}
    E = build(scene.load(sphere).spec).E_star
    with mp.workdps(30):
        R, dg, d, Em = mp.mpf(20e-9), mp.mpf(0.05), mp.mpf(10e-9), mp.mpf(E)
        a = mp.findroot(lambda a: a**2 / R - mp.sqrt(2 * mp.pi * a * dg / Em) - d, 40e-9)
        assert w["a/R"]["value"] == pytest.approx(float(a / R), rel=1e-13)  # Brent to 4 eps
    assert round(w["a/R"]["value"], 3) == 1.978
    assert w["d/R"]["value"] == pytest.approx(0.5, rel=1e-15)
    cone = next(p for p in tour_scenes() if p.stem == "afm_cone_tip_pdms")
    (w,) = scene.load(cone).run()["warnings"]
    assert w["value"] == pytest.approx(0.36397023426620234, rel=1e-15)  # tan(20 deg)


def test_an_adhesive_contact_measures_its_ratios_with_the_depth_s_size():
    """Adhesive contacts pulled above the free surface (d < 0, a state the scene's positive
    loads do not reach but a contact can be in) measure |d|: a JKR sphere and a Kendall punch,
    each ratio the quotient of the model's own contact radius; the Tabor parameter warns below
    its lower limit only."""
    from hertzmdr.numeric import adhesion as ad
    from hertzmdr.numeric.scene.kinds.base import State
    from hertzmdr.numeric.scene.model import build

    pdms = {"name": "PDMS", "shape": "flat", "E": "2 MPa", "nu": 0.5}
    glue = {"work_of_adhesion": "0.05 J/m^2"}
    spec = {"effects": ["contact_radius"], "load": {"depth": "10 nm"},
            "body": [_rigid(shape="sphere", radius="20 nm"), pdms], "interface": glue}
    kind = build(scene.load(spec).spec)
    st = State(np.array([-12e-9, -10e-9]), np.array([0.0, 0.0]), 0.0, "test")
    w = kind.ratios({"state": st})
    a = ad.AdhesiveContact(ad.Paraboloid(20e-9), kind.E_star, 0.05).contact_radius(depth=-1e-8)
    assert w == {"a/R": pytest.approx(a / 20e-9, rel=RATIO_RTOL),
                 "d/R": pytest.approx(0.5, rel=RATIO_RTOL)}
    # JKR: d = a^2/R - sqrt(2 pi a dgamma/E*); both terms near 5e-8, d = -1e-8: 1e-14
    assert a**2 / 20e-9 - np.sqrt(2 * np.pi * a * 0.05 / kind.E_star) == pytest.approx(
        -1e-8, rel=1e-13)

    spec = {**spec, "body": [_rigid(shape="flat_punch", radius="1 um"), pdms]}
    kind = build(scene.load(spec).spec)
    w = kind.ratios({"state": State(np.array([-0.15e-6]), np.array([0.0]), 0.0, "test")})
    assert w == {"d/a": pytest.approx(0.15, rel=RATIO_RTOL)}
    doc = scene.load({**spec, "effects": ["contact_radius", "depth"],
                      "load": {"depth": "0.15 um"}}).run()  # the same, run
    got = {k: v["value"] for k, v in doc["effects"].items()}
    (w,) = doc["warnings"]
    assert w["ratio"] == "d/a"
    assert w["value"] == pytest.approx(got["depth"] / got["contact_radius"],
                                       rel=RATIO_RTOL)

    # a big sphere on the same sample, with a range: mu_T = 7.1, above 5, no warning; a
    # 100 times stiffer sample: mu_T = 7.1/100^(2/3) = 0.33, below, one warning
    spec = {"effects": ["pull_off_force"], "load": {"depth": "1 nm"},
            "body": [_rigid(shape="sphere", radius="1 mm"), pdms],
            "interface": {**glue, "range": "0.1 um"}}
    doc = scene.load(spec).run()
    assert doc["model"]["tabor_parameter"] > 5 and doc["warnings"] == []
    doc = scene.load({**spec, "body": [spec["body"][0], {**pdms, "E": "200 MPa"}]}).run()
    (w,) = doc["warnings"]
    assert w["ratio"] == "mu_T" and w["value"] == doc["model"]["tabor_parameter"] < 5
    assert w["message"].startswith(f"mu_T = {w['value']:.3g} is below the limit 5: ")


def test_an_impact_warns_at_its_largest_compression():
    got, w = _run({"name": "ball", "shape": "sphere", "radius": "10 mm", "E": "210 GPa",
                   "nu": 0.3}, {"impact": {"velocity": "3 km/s", "density": "7.8 g/cm^3"}},
                  ["max_impact_depth"], {"name": "wall", "shape": "flat", "E": "210 GPa",
                                         "nu": 0.3})
    assert w["d/R"]["value"] == pytest.approx(got["max_impact_depth"] / 1e-2, rel=RATIO_RTOL)
    assert "a/R" in w


def test_under_the_limits_nothing_warns():
    """Just under each limit: a/R = 0.099 (d = (a/R)^2 R (5.21)), a cone at tan = 0.0999."""
    _, w = _run(_rigid(shape="sphere", radius="1 m"), {"depth": 0.099**2}, ["force"])
    assert w == {}
    _, w = _run(_rigid(shape="cone", angle="5.7 deg"), {"depth": "1 um"}, ["force"])
    assert w == {}


def test_only_the_nodes_the_run_evaluated_are_measured():
    """A scene asking for E* alone computes no contact: nothing to measure, nothing run."""
    spec = {"effects": ["effective_modulus"], "load": {"force": 1e308},
            "body": [_rigid(shape="sphere", radius="5 mm"), _flat("5.4e307 Pa")]}
    record, _, doc = scene.load(spec).run_full()
    assert record.evaluated == ["model", "effective_modulus"] and doc["warnings"] == []


@pytest.mark.parametrize("path", tour_scenes(), ids=lambda p: p.stem)
def test_every_example_warns_of_what_the_docs_say(path):
    doc = scene.load(path).run()
    assert {w["ratio"] for w in doc["warnings"]} == EXPECTED.get(path.stem, set())


def test_the_table_the_json_and_result_json_carry_them(tmp_path, capsys):
    path = next(p for p in tour_scenes() if p.stem == "problem7c_cone")
    message = scene.load(path).run()["warnings"][0]["message"]
    assert main(["run", str(path)]) == 0
    assert f"warning: {message}" in capsys.readouterr().out.splitlines()
    assert main(["run", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["warnings"][0]["message"] == message
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    written = json.loads((tmp_path / "out" / "result.json").read_text())
    assert [w["ratio"] for w in written["warnings"]] == ["tan(theta)"]


def test_docs_quote_the_one_table():
    text = (ROOT / "docs" / "scenes.md").read_text()
    assert markdown() in text
    for name in EXPECTED:
        assert f"`{name}.toml` " in text, name


def test_a_result_beyond_float64_is_one_line(tmp_path, capsys):
    """The same scene asking for the pressure: p0 (5.22) at E* = 5.9e307 Pa passes 1.8e308,
    which numeric/ says (an OverflowError naming the inputs) in one line, exit 2."""
    path = tmp_path / "huge.toml"
    path.write_text('effects = ["contact_radius", "max_pressure"]\n'
                    '[[body]]\nshape = "sphere"\nradius = "5 mm"\nrigid = true\n'
                    '[[body]]\nshape = "flat"\nE = "5.4e307 Pa"\nnu = 0.3\n'
                    '[load]\nforce = 1e308\n')
    assert main(["run", str(path)]) == 2
    out = capsys.readouterr()
    assert out.out == "" and len(out.err.strip().splitlines()) == 1, out.err
    assert "'max_pressure' at this load: hertz.max_pressure" in out.err
    assert "exceeds the float64 range" in out.err
