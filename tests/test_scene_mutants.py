"""Tests that kill the surviving mutants of numeric/scene/ (docs/mutation_scene.md): each checks
a line of the scene layer that computes something -- a value, its location, a grid, a unit
conversion, a validation range, a rel_error -- by a route other than that line, through the
public scene API unless the line is reachable no other way."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.kinds import stresses

# every pytest.approx here has abs=0: its default absolute tolerance (1e-12) would accept any
# error of the small values compared (rel_errors of 1e-13, lengths of 1e-6 m)
STEEL = {"E": 210e9, "nu": 0.3}


def run(bodies, load, effects, **extra):
    return scene.load({"effects": list(effects), "body": bodies, "load": load, **extra}).run()


# -- the stress maxima of a superposed field (kinds/stresses.py) -------------------------------

SAMPLED_R = list(np.linspace(0.0, 1e-3, 30))
TIPS = {
    "power_law": {"shape": "power_law", "coefficient": 1e6, "exponent": 3},
    # a paraboloid R = 10 mm sampled on 30 points: the numerical MDR
    "sampled": {"shape": "profile", "r": SAMPLED_R, "f": [r * r / 0.02 for r in SAMPLED_R]},
}

@pytest.mark.parametrize("body, r_s", [
    ({"shape": "cone", "angle": "80 deg"}, 0.0),                      # the tip
    ({"shape": "flat_punch", "radius": 1e-3}, 1e-3),                  # the punch's edge r = a
    ({"shape": "flattened_parabola", "radius": 0.05, "flat_radius": 1e-4}, 1e-4),  # r = b
])
def test_unbounded_maxima_sit_at_the_singular_radius(body, r_s):
    """Under a pressure unbounded at the surface radius r_s the largest stresses are +inf at
    (x, z) = (r_s, 0) (the surface stress grows like (1 - 2 nu) p there): the location is the
    singular radius of the shape's closed form, the depth 0."""
    eff = run([{**body, "rigid": True}, {"shape": "flat", **STEEL}], {"depth": 1e-6},
              ["max_shear", "max_von_mises"])["effects"]
    assert eff["max_shear"]["value"] == {"value": math.inf, "depth": 0.0}
    assert eff["max_von_mises"]["value"] == {"value": math.inf, "x": r_s, "z": 0.0}


def test_superposed_maxima_agree_with_their_field(monkeypatch):
    """The maxima of a superposed field (a power law, whose pressure is bounded) against the
    von Mises field of the same run and the pointwise bounds sqrt(3) tau <= sigma_v <= 2 tau
    (tau = (sigma_1 - sigma_3)/2; pure shear and uniaxial stress are the two ends). On a
    4-point grid instead of GRID_SUPERPOSED's 13 (12 superposed points, not 156: a test of the
    bookkeeping, not of the superposition, which tests/test_stress.py checks)."""
    monkeypatch.setattr(stresses, "GRID_SUPERPOSED", 4)
    eff = run([{**TIPS["power_law"], "rigid": True}, {"shape": "flat", **STEEL}], {"depth": 1e-6},
              ["max_shear", "max_von_mises", "von_mises_field"])["effects"]
    field = eff["von_mises_field"]["value"]
    x, z, sv = np.array(field["x"]), np.array(field["z"]), np.array(field["sigma_v"])
    assert sv.shape == (3, 7)  # z: 3 points 0 < z <= 2a; x: -2a..2a mirrored from 4 points
    vm, tau = eff["max_von_mises"]["value"], eff["max_shear"]["value"]
    # the largest von Mises stress is refined from the field's largest value (Nelder-Mead,
    # stress.superposed_maximum): at least that value, less its bound, and near where it is
    bound = eff["max_von_mises"]["rel_error"]
    k = np.unravel_index(np.argmax(sv), sv.shape)
    assert vm["value"] >= sv[k] * (1 - bound)
    assert abs(vm["z"] - z[k[0]]) <= z[1] - z[0] and abs(vm["x"] - abs(x[k[1]])) <= x[1] - x[0]
    # sigma_v <= 2 tau at every point: max sigma_v <= 2 max tau <= (2/sqrt 3) max sigma_v,
    # each maximum within its bound
    tol = bound + eff["max_shear"]["rel_error"]
    assert vm["value"] / 2 <= tau["value"] * (1 + tol)
    assert tau["value"] <= vm["value"] / math.sqrt(3) * (1 + tol)
    for name in ("max_shear", "max_von_mises"):
        assert "refined by Nelder-Mead" in eff[name]["method"]


# -- the grids of the field effects (kinds/base.py, kinds/axisym.py) ---------------------------

#: one scene per way an axisymmetric kind builds its fields: Hertz, a shape's closed form, the
#: flat punch (g = 0 inside, infinite outside), the numerical MDR of a sampled paraboloid
AXISYMMETRIC = {
    "hertz": {"shape": "sphere", "radius": 0.01},
    "cone": {"shape": "cone", "angle": 0.35},
    "punch": {"shape": "flat_punch", "radius": 1e-4},
    "sampled": TIPS["sampled"],
    "exact_sphere": {"shape": "exact_sphere", "radius": 0.01},
}
FIELDS = ["contact_radius", "pressure_profile", "surface_displacement", "mdr_profile",
          "force_depth_curve"]


@pytest.mark.parametrize("key", sorted(AXISYMMETRIC))
def test_axisymmetric_field_grids(key):
    """Every field effect of an axisymmetric contact on the grid its docstring gives, in units
    of the contact radius a that the scene reports: the pressure from 0 (from 1e-3 a for a
    shape's closed form, whose p may be singular at the axis, as under a cone) to 1.5 a, the
    displacement to 4 a, g(x) to 1.2 a (the punch's to just inside a, where its g becomes
    infinite), the force-depth curve from 0 (or its first step) to the load, Hertz's axis
    stresses from 0 to 3 a; FIELD_POINTS = 201 points each."""
    d = 2e-6
    fields = FIELDS + (["axis_stresses"] if key == "hertz" else [])  # closed forms only
    eff = run([{**AXISYMMETRIC[key], "rigid": True}, {"shape": "flat", **STEEL}], {"depth": d},
              fields)["effects"]
    a = eff["contact_radius"]["value"]
    rel = 1e-15  # linspace's rounding of a * factor

    def grid(values, start, end, n=201):
        v = np.asarray(values)
        assert v.shape == (n,)
        assert v[0] == pytest.approx(start, rel=rel, abs=0.0)
        assert v[-1] == pytest.approx(end, rel=rel, abs=0)
        assert np.allclose(np.diff(v[1:]), (end - v[1]) / (n - 2), rtol=1e-9)  # evenly spaced

    r = eff["pressure_profile"]["value"]["r"]
    grid(r, 1e-3 * a if key in ("cone", "punch") else 0.0, 1.5 * a)
    grid(eff["surface_displacement"]["value"]["r"], 0.0, 4.0 * a)
    g = eff["mdr_profile"]["value"]
    if key == "punch":
        grid(g["x"], 0.0, a * (1 - 1e-9))
        assert not np.any(g["g"])  # g = 0 for |x| < a (Problem 7(a))
    else:
        grid(g["x"], 0.0, 1.2 * a)
        # g(x) = d at x = a (5.55): the grid's point nearest a, by the slope of g there
        x, gx = np.asarray(g["x"]), np.asarray(g["g"])
        # 1e-3: linear interpolation between grid points
        assert np.interp(a, x, gx) == pytest.approx(d, rel=1e-3, abs=0)
    curve = eff["force_depth_curve"]["value"]
    first = 0.0 if key == "hertz" else d / 200  # the closed forms start at their first step
    grid(curve["depth"], first, d, n=201 if key == "hertz" else 200)
    if key == "hertz":
        grid(eff["axis_stresses"]["value"]["z"], 0.0, 3.0 * a)


def test_numerical_mdr_mean_pressure_bound():
    """The numerical MDR's mean pressure F/(pi a^2) adds the bounds of F and a^2: 3 times the
    state's rel_error (docs/scenes.md, the accuracy table)."""
    eff = run([{**AXISYMMETRIC["sampled"], "rigid": True}, {"shape": "flat", **STEEL}],
              {"depth": 2e-6}, ["contact_radius", "mean_pressure"])["effects"]
    assert eff["contact_radius"]["rel_error"] > 0
    assert eff["mean_pressure"]["rel_error"] == 3 * eff["contact_radius"]["rel_error"]


def test_numerical_mdr_max_pressure_bound():
    """The numerical MDR's largest pressure reports mdr.Solution.max_pressure's own bound
    relative to the value, plus the state's rel_error (p scales with the contact radius, whose
    error that bound leaves out): docs/scenes.md, the accuracy table. Checked against the
    numerical MDR called directly (numeric/mdr.py)."""
    from hertzmdr.numeric import mdr
    from hertzmdr.numeric.scene.accuracy import DEFAULT_RTOL

    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)  # (5.26) with a rigid tip
    tip = TIPS["sampled"]
    sol = mdr.Profile.from_samples(tip["r"], tip["f"], k=5).solve(
        E_star=E_star, rtol=DEFAULT_RTOL, depth=2e-6)
    v, e = sol.max_pressure(return_error=True)
    eff = run([{**tip, "rigid": True}, {"shape": "flat", **STEEL}], {"depth": 2e-6},
              ["max_pressure", "contact_radius"])["effects"]
    assert eff["max_pressure"]["value"] == pytest.approx(v, rel=1e-14, abs=0)  # the same solve
    assert eff["contact_radius"]["rel_error"] == sol.rel_error > 0
    # 1e-2: the bound of the largest pressure is an estimate, which moves by 1e-3 between two
    # solves of the same profile (the terms are 1.0e-13 and 0.4e-13 here)
    assert eff["max_pressure"]["rel_error"] == pytest.approx(e / v + sol.rel_error, rel=1e-2,
                                                             abs=0)


# -- what every kind reports beside its values (kinds/*.py, runner.py) ------------------------

#: one scene per kind (two for the elliptical contact's two models), each with every effect it
#: offers that costs no superposition
KIND_SCENES = {
    "hertz": ([{"shape": "sphere", "radius": 0.01, **STEEL}, {"shape": "flat", "rigid": True}],
              {"depth": 1e-6}, {}),
    "elliptic": ([{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL},
                  {"shape": "flat", "rigid": True}], {"force": 10.0}, {}),
    "gaussian": ([{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL},
                  {"shape": "flat", "rigid": True}], {"force": 10.0},
                 {"model": {"elliptic": "gaussian"}}),
    "line": ([{"shape": "cylinder", "radius": 0.01, "length": 0.02, **STEEL},
              {"shape": "flat", "rigid": True}], {"force": 100.0}, {}),
    "pressure": ([{"shape": "flat", **STEEL}, {"shape": "flat", "rigid": True}],
                 {"pressure": {"distribution": "hertzian", "p0": 1e8, "radius": 1e-3}}, {}),
    "cone": ([{**AXISYMMETRIC["cone"], "rigid": True}, {"shape": "flat", **STEEL}],
             {"depth": 1e-6}, {}),
    "sampled": ([{**TIPS["sampled"], "rigid": True}, {"shape": "flat", **STEEL}],
                {"depth": 1e-6}, {}),
    "punch": ([{"shape": "flat_punch", "radius": 1e-4, "rigid": True},
               {"shape": "flat", **STEEL}], {"force": 1.0}, {}),
    "exact_sphere": ([{"shape": "exact_sphere", "radius": 0.01, "rigid": True},
                      {"shape": "flat", **STEEL}], {"force": 1.0}, {}),
    "bem": ([{"shape": "polygon_punch", "vertices": [[0, 0], [1e-3, 0], [0, 1e-3]],
              "pixels": 32, "rigid": True},
             {"shape": "flat", **STEEL}], {"depth": 1e-6}, {"accuracy": {"rtol": 1e-6}}),
}
CHEAP = [name for name, e in scene.EFFECTS.items()
         if "impact" not in e.needs and name not in ("max_shear", "max_von_mises",
                                                     "max_orthogonal_shear",
                                                     "von_mises_field")]


def offered(bodies, load, extra):
    """The effects of CHEAP that the contact of a scene of these bodies and load has."""
    from hertzmdr.numeric.scene.model import build

    spec = scene.load({"effects": ["force"], "body": bodies, "load": load, **extra}).spec
    contact = build(spec)
    # the axis stresses of kinds other than Hertz are superposed: seconds
    # the tangential effects need [interface] friction, which these scenes do not give
    return [n for n in CHEAP if contact.has(n) and "tangential" not in scene.EFFECTS[n].needs
            and (n != "axis_stresses" or contact.kind == "hertz")]


@pytest.mark.parametrize("key", sorted(KIND_SCENES))
def test_every_effect_says_how_it_was_computed(key):
    """Each effect's method is a text (the JSON's "method"), and the model block reports the
    scene's rtol: what a reader of the output needs to trust a number."""
    bodies, load, extra = KIND_SCENES[key]
    names = offered(bodies, load, extra)
    assert len(names) >= 4, names
    doc = run(bodies, load, names, **extra)
    for name in names:
        method = doc["effects"][name]["method"]
        assert isinstance(method, str) and method.strip(), (name, method)
    assert doc["model"]["rtol"] == extra.get("accuracy", {}).get("rtol", 1e-10)
    assert isinstance(doc["model"]["description"], str) and doc["model"]["description"]


def test_elliptic_model_block_and_sweep():
    """The elliptical contact's model block names its principal radii, its Gaussian radius
    sqrt(R1 R2) (5.30) and the model; under a force sweep its semi-axes are one [a, b] per
    load, each that of the single load (the semi-axes of one force do not depend on the
    others)."""
    bodies, _, _ = KIND_SCENES["elliptic"]
    forces = [1.0, 50.5, 100.0]
    doc = run(bodies, {"force": {"from": 1.0, "to": 100.0, "points": 3}},
              ["semi_axes", "stiffness"])
    R1, R2 = doc["model"]["principal_radii"]
    assert doc["model"]["gaussian_radius"] == pytest.approx(math.sqrt(R1 * R2), rel=1e-15, abs=0)
    assert doc["model"]["elliptic_model"] == "exact"
    axes = doc["effects"]["semi_axes"]["value"]
    assert np.shape(axes) == (3, 2)
    for F, ab in zip(forces, axes, strict=True):
        one = run(bodies, {"force": F}, ["semi_axes"])["effects"]["semi_axes"]["value"]
        assert ab == pytest.approx(one, rel=1e-12, abs=0)  # 1e-12: the same solve, rounding apart
        # the semi-axes grow like F^(1/3) (Hertz): a check independent of the solver
        assert ab[0] / axes[0][0] == pytest.approx((F / forces[0]) ** (1 / 3), rel=1e-9, abs=0)


def test_line_stiffness_under_a_sweep():
    """The line contact's stiffness dF/dd = (pi/4) E* L of (5.34) does not depend on the load:
    a sweep gets that one value at each of its points."""
    bodies, _, _ = KIND_SCENES["line"]
    doc = run(bodies, {"force": {"from": 10.0, "to": 100.0, "points": 4}}, ["stiffness"])
    k = doc["effects"]["stiffness"]["value"]
    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)
    assert k == pytest.approx([math.pi / 4 * E_star * 0.02] * 4, rel=1e-14, abs=0)


# -- the builders' refusals (kinds/*.py build functions, Setup.fail) ----------------------------

SPHERE = {"shape": "sphere", "radius": 0.01, **STEEL}
RIGID_FLAT = {"shape": "flat", "rigid": True}


TRIANGLE = [[0, 0], [1e-3, 0], [0, 1e-3]]


@pytest.mark.parametrize("bodies, load, key, message", [
    ([{"shape": "flat", **STEEL}, RIGID_FLAT], {"depth": 1e-6}, "body",
     "two flat bodies have no contact point: give one a curved shape, or use a flat_punch"),
    ([{"shape": "cylinder", "radius": 0.01, **STEEL}, RIGID_FLAT], {"force": 1.0}, "body",
     "parallel cylinders make a line contact, whose force depends on the contact length: "
     "give the cylinder(s) a length"),
    ([{"shape": "cylinder", "radius": 0.01, "length": 0.0, **STEEL}, RIGID_FLAT],
     {"depth": 1e-6}, "body", "the cylinder length must be > 0, got 0.0"),
    ([SPHERE, {"shape": "sphere", "radius": -0.005, "rigid": True}], {"depth": 1e-6}, "body",
     ...),  # numeric/bodies.py's message, then the scene's hint
    ([{"shape": "cone", "angle": 0.3, **STEEL}, {"shape": "cone", "angle": 0.4, "rigid": True}],
     {"depth": 1e-6}, "body", "two profiled bodies (cone and cone) are not supported: give "
     "one of them shape = \"flat\" (the MDR sums the two profiles; sample their sum as a "
     "profile)"),
    ([SPHERE, {"shape": "sphere", "radius": 0.02, "rigid": True}],
     {"impact": {"velocity": 1.0, "mass": 0.1}}, "load.impact",
     "an impact scene is a sphere striking a flat wall (Problems 3 and 4); this one has "
     "sphere and sphere"),
    ([{"shape": "sphere", "radius": -0.01, **STEEL}, RIGID_FLAT],
     {"impact": {"velocity": 1.0, "mass": 0.1}}, "body",
     "the striking sphere must be convex (radius > 0)"),
    ([{"shape": "polygon_punch", "vertices": TRIANGLE, **STEEL},
      {"shape": "polygon_punch", "vertices": TRIANGLE, "rigid": True}], {"depth": 1e-6},
     "body", "a polygon_punch or height_map presses on a flat body: give the other body "
     "shape = \"flat\""),
    ([{"shape": "profile", "r": [0, 1e-6, 2e-6], "f": [0, 1e-9, 4e-9], "rigid": True},
      {"shape": "flat", **STEEL}], {"depth": 1e-9}, "body (body 1)",
     "profile samples: r and f must be 1-D of equal length >= 4; got (3,), (3,)"),
])
def test_builder_refusals_name_the_key(bodies, load, key, message):
    """A combination the schema accepts but no contact can be built from is one SceneError
    naming the key and saying why."""
    with pytest.raises(scene.SceneError) as info:
        run(bodies, load, ["force"])
    assert info.value.key == key and info.value.where == "<scene>"
    if message is ...:
        assert info.value.message.startswith("principal_radii: R1a = 0.01, R1b = 0.01, "
                                             "R2a = -0.005, R2b = -0.005, omega = 0.0: ")
        assert info.value.message.endswith("; a concave radius must be larger than the "
                                           "convex one it holds")
    else:
        assert info.value.message == message


def test_height_map_that_cannot_be_read(tmp_path):
    """A height map file that numeric/bem.py cannot read is a SceneError on the body, with
    the reader's reason."""
    path = tmp_path / "h.txt"
    path.write_text("1 2 x\n3 4 5\n")
    with pytest.raises(scene.SceneError) as info:
        run([{"shape": "height_map", "file": str(path), "spacing": 1e-6, "rigid": True},
             {"shape": "flat", **STEEL}], {"depth": 1e-7}, ["force"])
    assert info.value.key == "body (body 1)"
    assert "'x'" in info.value.message


def test_line_contact_under_a_depth():
    """A line contact under a depth d (the chapter's convention a = sqrt(R d), (5.35)): the
    force (pi/4) E* L d of (5.34), typed here from the chapter, and the model block names R
    and L."""
    R, L, d = 0.01, 0.02, 1e-6
    doc = run([{"shape": "cylinder", "radius": R, "length": L, **STEEL}, RIGID_FLAT],
              {"depth": {"from": d, "to": 3 * d, "points": 3}}, ["depth", "force"])
    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)  # (5.26), the other body rigid
    assert doc["effects"]["depth"]["value"] == pytest.approx([d, 2 * d, 3 * d], rel=1e-15, abs=0)
    assert doc["effects"]["force"]["value"] == pytest.approx(
        [math.pi / 4 * E_star * L * x for x in (d, 2 * d, 3 * d)], rel=1e-14, abs=0)  # rounding
    assert doc["effects"]["force"]["rel_error"] <= 1e-14
    assert doc["model"]["effective_radius"] == R and doc["model"]["length"] == L


def test_bem_errors_are_the_change_from_half_resolution():
    """The BEM's rel_error of each effect is its relative change from half the resolution
    (first order in the pixel size for a punch): positive, and below 20 % on a 32-pixel
    triangle; the contact area's is at least the band of pixels its edge cuts (40 % of the
    area at this resolution), below 1."""
    bodies, load, extra = KIND_SCENES["bem"]
    eff = run(bodies, load, ["stiffness", "mean_pressure", "contact_area", "force"],
              **extra)["effects"]
    for name in ("stiffness", "mean_pressure", "force"):
        assert 0 < eff[name]["rel_error"] < 0.2, (name, eff[name]["rel_error"])
    assert 0.2 < eff["contact_area"]["rel_error"] < 1


def test_parallel_cylinders_take_the_shorter_length():
    """Two parallel cylinders make a line contact of the length given (one of them may omit
    it), or of the shorter of the two: 1/R = 1/R1 + 1/R2 (5.27)."""
    a = {"shape": "cylinder", "radius": 0.01, "length": 0.02, **STEEL}
    b = {"shape": "cylinder", "radius": 0.02, "rigid": True}
    model = run([a, b], {"depth": 1e-6}, ["force"])["model"]
    assert model["length"] == 0.02
    assert model["effective_radius"] == pytest.approx(1 / (1 / 0.01 + 1 / 0.02), rel=1e-15, abs=0)
    model = run([a, {**b, "length": 0.015}], {"depth": 1e-6}, ["force"])["model"]
    assert model["length"] == 0.015


def test_rtol_reaches_the_bem_and_the_numerical_mdr_curve():
    """[accuracy] rtol is the conjugate gradients' tolerance of the BEM (the force at rtol 1e-3
    differs from the one at 1e-14, by less than 1e-3) and the target of the numerical MDR's
    force-depth curve (at rtol 1e-4 its error bound is above the default's 1e-10)."""
    bodies, load, _ = KIND_SCENES["bem"]
    F = [run(bodies, load, ["force"], accuracy={"rtol": r})["effects"]["force"]["value"]
         for r in (1e-3, 1e-14)]
    assert 1e-9 < abs(F[0] / F[1] - 1) < 1e-3
    bodies, _, _ = KIND_SCENES["sampled"]
    eff = run(bodies, {"depth": 2e-6}, ["force_depth_curve"],
              accuracy={"rtol": 1e-4})["effects"]["force_depth_curve"]
    assert 1e-10 < eff["rel_error"] <= 1e-4
    tight = run(bodies, {"depth": 2e-6}, ["force_depth_curve"])["effects"]["force_depth_curve"]
    assert tight["rel_error"] < 1e-3 * eff["rel_error"]  # the default rtol, 1e-10, refines


@pytest.mark.parametrize("load, key", [({"depth": 1e-6}, "force"), ({"force": 200.0}, "depth")])
def test_bem_state_error_is_the_change_from_half_resolution(load, key):
    """The BEM state's rel_error is the relative change of the computed quantity (the force
    under a depth, the depth under a force) from the same solve on every other pixel with
    twice the pixel size (numeric/bem.py called directly on the shape's height map)."""
    from hertzmdr.numeric import bem
    from hertzmdr.numeric.scene.kinds.grid import GCI_FACTOR

    bodies, _, extra = KIND_SCENES["bem"]
    eff = run(bodies, load, [key], **extra)["effects"][key]
    height, dx = bem.polygon_punch(bodies[0]["vertices"], 32, margin=0.05)
    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)
    fine = bem.solve(height, dx, E_star, tol=1e-6, **load)
    coarse = bem.solve(height[::2, ::2], 2 * dx, E_star, tol=1e-6, **load)
    # both solves stop at the CG tolerance 1e-6: a solve may differ from the scene's by that
    assert eff["value"] == pytest.approx(getattr(fine, key), rel=1e-6, abs=0)
    model = run(bodies, load, [key], **extra)["model"]
    assert model["grid"] == list(height.shape) and model["pixel_size"] == dx
    # ... which moves a change of about 4 % by 1e-6 / 0.04
    # ... times Roache's safety factor of a two-grid convergence index (kinds/grid.py)
    change = abs(getattr(fine, key) / getattr(coarse, key) - 1)
    assert eff["rel_error"] == pytest.approx(GCI_FACTOR * change, rel=1e-3, abs=0)


# -- units.py: writing values with SI prefixes ------------------------------------------------

@pytest.mark.parametrize("x, unit, text", [
    (1.0134e9, "Pa", "1.0134 GPa"),
    (1.23456789e9, "Pa", "1.2346 GPa"),      # 5 significant digits by default
    (2.5e-6, "m", "2.5 µm"),
    (-2e-3, "m", "-2 mm"),                    # the prefix of |x|
    (999.99999999, "N", "1 kN"),              # rounds up to the next prefix, not "1000 N"
    (1e3 * 0.9999999, "N", "1 kN"),           # ... from 0.9999999 of it on
    (1e-18, "m", "1e-18 m"),                  # below femto: plain scientific notation
    (0.0, "Pa", "0 Pa"),
    (math.inf, "Pa", "inf Pa"),
    (math.nan, "Pa", "nan Pa"),
    (0.5, "rad", "0.5 rad"),                  # radians, numbers: no prefix
    (1234.5, "", "1234.5"),
    (1234.5, "1", "1234.5"),                # a pure number: no unit "1" (n = 1.5)
    (2.0e5, "N/m", "2e+05 N/m"),              # compound units: no prefix
    (3e-6, "m^2", "3e-06 m^2"),
])
def test_engineering(x, unit, text):
    """engineering() writes the tables' values: the largest engineering prefix (powers of
    1000) not above |x|, expected strings written out by hand."""
    from hertzmdr.numeric.scene.units import engineering

    assert engineering(x, unit) == text


@pytest.mark.parametrize("top, scale, prefix", [
    (3e-3, 1e-3, "m"), (1e3, 1e3, "k"), (999.0, 1.0, ""), (5e13, 1e12, "T"),
    (1e-20, 1e-15, "f"),                      # below the smallest: the smallest
])
def test_prefixed(top, scale, prefix):
    """prefixed() picks a figure axis' unit: the largest prefix not above the largest value."""
    from hertzmdr.numeric.scene.units import prefixed

    assert prefixed(top) == (scale, prefix)


def test_effects_listing():
    """`hertzmdr effects`: one line per effect, its name padded to the longest name, its unit
    in brackets, its description."""
    from hertzmdr.numeric.scene.effects import EFFECTS, listing

    lines = listing().split("\n")
    width = max(len(n) for n in EFFECTS)
    assert len(lines) == len(EFFECTS)
    for line, e in zip(lines, EFFECTS.values(), strict=True):
        assert line == e.name.ljust(width) + f"  [{e.unit}]  {e.doc}"


# -- schema.py: messages -----------------------------------------------------------------------

def test_scene_error_without_a_key(tmp_path):
    """A SceneError about the whole file names the file only: "<file>: <message>"."""
    path = tmp_path / "none.toml"
    with pytest.raises(scene.SceneError) as info:
        scene.load(path)
    assert str(info.value) == f"{path}: no such file"


@pytest.mark.parametrize("shape, message", [
    ("cyl", "unknown shape 'cyl'; did you mean 'cylinder'?"),   # similarity 0.545 >= 0.5
    ("zzzz", "unknown shape 'zzzz'"),                           # nothing close: no hint
])
def test_unknown_shape_suggests_the_closest(shape, message):
    with pytest.raises(scene.SceneError) as info:
        run([{"shape": shape, "rigid": True}, {"shape": "flat", **STEEL}], {"depth": 1e-6},
            ["force"])
    assert info.value.message == message


@pytest.mark.parametrize("text, message", [
    ("5 N", "'5 N' has the unit newton, which is not a length (convertible to m)"),
    ("2*3", "'2*3' has the unit dimensionless, which is not a length (convertible to m)"),
    ("5 blorbs", "cannot read '5 blorbs' as a quantity (UndefinedUnitError: 'blorbs' is not "
                 "defined in the unit registry)"),
])
def test_units_read_by_pint_are_refused_by_name(text, message):
    """A quantity pint reads (or cannot) with the wrong dimension: the message names the
    text, its unit, the dimension wanted and its SI unit (or pint's reason)."""
    from hertzmdr.numeric.scene.units import UnitError, to_si

    with pytest.raises(UnitError) as info:
        to_si(text, "length")
    assert str(info.value) == message


def test_document_numbers_are_plain_floats():
    """The JSON document holds Python floats, never NumPy scalars (whose repr, np.float64(...),
    would leak into messages and printed output)."""
    doc = run(*KIND_SCENES["hertz"][:2], ["force", "max_pressure", "contact_radius"])
    for name in ("force", "max_pressure", "contact_radius"):
        assert type(doc["effects"][name]["value"]) is float, name


def test_document_entry_of_each_effect():
    """Each effect's entry in the JSON document (docs/scenes.md): its value, its unit from the
    registry, how it was computed, its rel_error, whether that met rtol and its time."""
    doc = run(*KIND_SCENES["hertz"][:2], ["force", "pressure_profile"])
    for name, entry in doc["effects"].items():
        assert set(entry) == {"value", "unit", "method", "rel_error", "met_rtol", "seconds"}
        assert entry["unit"] == scene.EFFECTS[name].unit
        assert entry["met_rtol"] is (entry["rel_error"] <= 1e-10)
        assert isinstance(entry["seconds"], float) and 0 <= entry["seconds"] < 60
    assert doc["title"] == "scene" and set(doc) == {"title", "model", "effects", "warnings",
                                                    "scene", "files", "hertzmdr_version"}
    assert doc["warnings"] == []  # a small Hertz contact stretches no assumption


def test_numeric_refusal_at_the_load_names_the_effect():
    """A ValueError from numeric/ while an effect is computed (here an ellipse beyond the
    radius ratio numeric/ellipse.py covers) is a SceneError on `effects` naming the effect."""
    with pytest.raises(scene.SceneError) as info:
        run([{"shape": "ellipsoid", "radii": [1e-3, 1e7], **STEEL}, RIGID_FLAT],
            {"depth": 1e-6}, ["force"])
    assert (info.value.where, info.value.key) == ("<scene>", "effects")
    assert info.value.message == ("'force' at this load: R1/R2 = 10000000000.0 (or its "
                                  "inverse) is out of range; valid: 1/1e+08 <= R1/R2 <= 1e+08")


# -- shapes ----------------------------------------------------------------------------------------

def test_crossed_ellipsoids_by_their_axes():
    """Two equal ellipsoids (R1, R2) = (10, 40) mm with their R1 directions 90 deg apart (given
    as 30 and 120 deg) have a circular gap: each direction has curvature 1/R1 + 1/R2, so
    R = 1/(1/10 + 1/40) mm = 8 mm in both (Problem 2); aligned (30 and 30 deg), the principal
    radii are R1/2 and R2/2."""
    def radii(axis_a, axis_b):
        bodies = [{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL},
                  {"shape": "ellipsoid", "radii": [0.01, 0.04], "axis": axis_b, "rigid": True}]
        if axis_a is not None:  # else the default, 0
            bodies[0]["axis"] = axis_a
        return sorted(run(bodies, {"depth": 1e-6}, ["principal_radii"])["model"]
                      ["principal_radii"])

    assert radii("30 deg", "120 deg") == pytest.approx([0.008, 0.008], rel=1e-12, abs=0)
    assert radii("30 deg", "30 deg") == pytest.approx([0.005, 0.02], rel=1e-12, abs=0)
    assert radii(None, "90 deg") == pytest.approx([0.008, 0.008], rel=1e-12, abs=0)  # 0 deg


SAMPLE_FILE = """r, f   # a header line
# a comment line

0, 0   # the apex # r = 0
1e-4, 5e-7   # f = r^2/(2R), R = 10 mm
2e-4 2e-6
3e-4,4.5e-6
4e-4, 8e-6
5e-4, 1.25e-5
"""


def test_sample_file_is_read_as_the_same_samples(tmp_path):
    """A profile read from a file (a header, comments, blank lines, commas or spaces) is the
    profile given by r and f inline: the same force at the same depth."""
    (tmp_path / "tip.csv").write_text(SAMPLE_FILE, encoding="utf-8")
    r = [0.0, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4]
    f = [0.0, 5e-7, 2e-6, 4.5e-6, 8e-6, 1.25e-5]
    inline = run([{"shape": "profile", "r": r, "f": f, "rigid": True},
                  {"shape": "flat", **STEEL}], {"depth": 1e-6}, ["force"])
    path = tmp_path / "scene.toml"
    path.write_text('effects = ["force"]\n[[body]]\nshape = "profile"\nfile = "tip.csv"\n'
                    'rigid = true\n[[body]]\nshape = "flat"\nE = 210e9\nnu = 0.3\n'
                    '[load]\ndepth = 1e-6\n')
    from_file = scene.load(path).run()
    assert from_file["effects"]["force"]["value"] == inline["effects"]["force"]["value"]


@pytest.mark.parametrize("content, message", [
    (b"r f\n0 0\n1e-4 x\n", "tip.csv line 3: expected two numbers r, f, got '1e-4 x'"),
    (b"0 0\n1e-4 5e-7 1\n", "tip.csv line 2: expected two numbers r, f, got '1e-4 5e-7 1'"),
    (b"r f\n0 0\n1e-4\n", "tip.csv line 3: expected two numbers r, f, got '1e-4'"),
    (b"r f\n0 0\n", "tip.csv has fewer than two samples"),
    # one header line only
    (b"r f\nr f\n0 0\n1e-4 5e-7\n", "tip.csv line 2: expected two numbers r, f, got 'r f'"),
    (b"0 0\n\xff\xfe 1\n", None),     # not UTF-8: cannot read it
    (None, None),                    # no such file
])
def test_sample_file_errors(tmp_path, content, message):
    """A sample file that cannot be read names the file key, the file, and the line."""
    path = tmp_path / "tip.csv"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(scene.SceneError) as info:
        run([{"shape": "profile", "file": str(path), "rigid": True},
             {"shape": "flat", **STEEL}], {"depth": 1e-9}, ["force"])
    assert info.value.key == "body[0] (body 1).file"
    if content is None:
        assert info.value.message == f"sample file {str(path)!r} not found"
    elif message is None:
        assert info.value.message.startswith(f"cannot read {str(path)!r} (")
        assert "codec can't decode" in info.value.message
    else:
        assert info.value.message == message


def test_exact_sphere_under_a_force():
    """The exact sphere under a force F: the depth it reports gives back F through the force
    at that depth (a depth-controlled scene), and near the Hertz depth (5.23) of the
    paraboloid, which the spherical cap approaches for a << R (here a/R = 0.01: they differ
    by O((a/R)^2))."""
    bodies, load, _ = KIND_SCENES["exact_sphere"]
    d = run(bodies, load, ["depth"])["effects"]["depth"]["value"]
    F = run(bodies, {"depth": d}, ["force"])["effects"]["force"]["value"]
    assert F == pytest.approx(1.0, rel=1e-12, abs=0)  # a root found to 1e-12 or better
    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)
    hertz = (9 * 1.0**2 / (16 * E_star**2 * 0.01)) ** (1 / 3)  # (5.23) solved for d
    assert d == pytest.approx(hertz, rel=1e-3, abs=0)


def test_two_samples_in_a_file_reach_the_numerical_mdr(tmp_path):
    """Two samples are enough for the file reader; the numerical MDR then asks for four."""
    path = tmp_path / "tip.csv"
    path.write_text("0 0\n1e-4 5e-7\n")
    with pytest.raises(scene.SceneError) as info:
        run([{"shape": "profile", "file": str(path), "rigid": True},
             {"shape": "flat", **STEEL}], {"depth": 1e-9}, ["force"])
    assert info.value.key == "body (body 1)"
    assert info.value.message == ("profile samples: r and f must be 1-D of equal length >= 4; "
                                  "got (2,), (2,)")


def test_exact_sphere_fields():
    """The exact sphere's surface displacement is d - f(r) inside the contact, with the
    spherical cap f = R - sqrt(R^2 - r^2) (the boundary condition, typed here), and its MDR
    profile reaches g(a) = d at the contact radius (5.55)."""
    R, d = 0.01, 2e-5
    eff = run([{"shape": "exact_sphere", "radius": R, "rigid": True},
               {"shape": "flat", **STEEL}], {"depth": d},
              ["contact_radius", "surface_displacement", "mdr_profile"])["effects"]
    a = eff["contact_radius"]["value"]
    u = eff["surface_displacement"]["value"]
    r, uz = np.asarray(u["r"]), np.asarray(u["u"])
    inside = r < a
    cap = R - np.sqrt(R * R - r[inside] ** 2)
    # 1e-9 of d: the rounding of R - sqrt(R^2 - r^2) (R^2 = 1e-4 against r^2 <= 1e-5)
    assert np.allclose(uz[inside], d - cap, rtol=0, atol=1e-9 * d)
    assert np.all(np.diff(uz[~inside]) < 0) and uz[-1] > 0  # decays outside, stays > 0
    g = eff["mdr_profile"]["value"]
    assert np.interp(a, g["x"], g["g"]) == pytest.approx(d, rel=1e-3, abs=0)  # interpolation


def test_height_map_keys(tmp_path):
    """A height map's file is relative to the scene file (whatever the working directory);
    its spacing must be > 0; a missing file is named."""
    import shutil

    folder = tmp_path / "scenes"
    folder.mkdir()
    shutil.copy(Path(__file__).parents[1] / "examples" / "paraboloid_tip.csv", folder / "h.csv")
    text = ('effects = ["force"]\n[[body]]\nshape = "height_map"\nfile = "{file}"\n'
            'spacing = "{spacing}"\nrigid = true\n[[body]]\nshape = "flat"\nE = 2e9\n'
            'nu = 0.4\n[load]\ndepth = 1e-7\n')
    path = folder / "scene.toml"
    path.write_text(text.format(file="h.csv", spacing="1 um"))
    assert scene.load(path).run()["effects"]["force"]["value"] > 0  # the cwd is not folder
    path.write_text(text.format(file="h.csv", spacing="0 um"))
    with pytest.raises(scene.SceneError) as info:
        scene.load(path)
    assert (info.value.key, info.value.message) == ("body[0] (body 1).spacing",
                                                    "must be > 0, got 0.0")
    path.write_text(text.format(file="missing.csv", spacing="1 um"))
    with pytest.raises(scene.SceneError) as info:
        scene.load(path)
    assert info.value.message == f"height map {str(folder / 'missing.csv')!r} not found"


def test_rtol_met_at_equality_and_impact_effects_need_an_impact():
    """An effect meets rtol when its rel_error is at most rtol: a closed form (1e-14) meets
    rtol = 1e-14. An impact effect in a scene without an impact is refused by name."""
    bodies, load, _ = KIND_SCENES["hertz"]
    eff = run(bodies, load, ["force"], accuracy={"rtol": 1e-14})["effects"]["force"]
    assert eff["rel_error"] == 1e-14 and eff["met_rtol"] is True
    with pytest.raises(scene.SceneError) as info:
        run(bodies, load, ["contact_time"])
    assert (info.value.key, info.value.message) == (
        "effects", "effect 'contact_time' needs an impact: give [load.impact] with velocity "
        "and mass or density")


def test_numerical_mdr_solves_each_load_to_the_scene_rtol():
    """The numerical MDR solves each load of a sweep (the forces of two depths differ, as
    F ~ d^(3/2) for the sampled paraboloid) to the scene's rtol (at rtol 1e-4 its bound is
    above the default's 1e-10)."""
    bodies, _, _ = KIND_SCENES["sampled"]
    eff = run(bodies, {"depth": {"from": 1e-6, "to": 2e-6, "points": 2}}, ["force"],
              accuracy={"rtol": 1e-4})["effects"]["force"]
    F1, F2 = eff["value"]
    assert F2 / F1 == pytest.approx(2**1.5, rel=1e-3, abs=0)  # 1e-3: the samples' paraboloid
    assert 1e-10 < eff["rel_error"] <= 1e-4
    tight = run(bodies, {"depth": 2e-6}, ["force"])["effects"]["force"]  # rtol 1e-10
    # the grid refined further for the default rtol: a bound far below the loose one
    assert tight["rel_error"] < 1e-3 * eff["rel_error"]


def test_closed_form_shapes_name_their_kind():
    """The model block of a closed-form shape: its kind and its parameters."""
    assert run(*KIND_SCENES["punch"][:2], ["force"])["model"]["kind"] == "flat_punch"
    model = run(*KIND_SCENES["exact_sphere"][:2], ["force"])["model"]
    assert (model["kind"], model["radius"]) == ("exact_sphere", 0.01)


def test_flat_punch_has_no_max_pressure():
    """The flat punch's pressure (5.9) is singular at its edge: max_pressure is refused with
    that reason."""
    with pytest.raises(scene.SceneError) as info:
        run(*KIND_SCENES["punch"][:2], ["max_pressure"])
    assert info.value.message == ("effect 'max_pressure' does not apply to this scene: the "
                                  "punch pressure (5.9) is singular at the edge")
