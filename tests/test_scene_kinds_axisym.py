"""Tests that kill surviving mutants of numeric/scene/kinds/ axisym.py, elliptic.py,
stresses.py, grid.py, hertz.py and quadratic.py (benchmarks/mutation_notes_scene_axisym.toml):
the assumption ratios each kind measures, the grids and keys of the stress effects of the
closed forms (Hertz, line, ellipse), the kink and axis of a pressure profile, which branch a
kind takes (exact or Gaussian ellipse, closed-form or spring tangential contact), the error
a numerical MDR hands its stresses, each checked by a route other than the line itself: a
closed form, a scaling law, a symmetry, the other model of the same contact. Every
superposition is kept off (or shrunk to a few points): the file runs in a few seconds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.schema import SceneError

# every pytest.approx here has abs=0: its default absolute tolerance (1e-12) would accept any
# error of the small values compared (lengths of 1e-6 m, ratios of 1e-4)
STEEL = {"E": 210e9, "nu": 0.3}
RIGID_FLAT = {"shape": "flat", "rigid": True}
SWEEP = {"depth": {"from": 1e-6, "to": 2e-6, "points": 2}}  # the largest load 2 um


def run_full(bodies, load, effects, **extra):
    """(run record, results, JSON document) of a scene: the record holds the contact and the
    nodes it evaluated (state, stress, impact)."""
    return scene.load({"effects": list(effects), "body": bodies, "load": load,
                       **extra}).run_full()


def tip(body, load, effects, **extra):
    """A rigid axisymmetric tip on a steel flat."""
    return run_full([{**body, "rigid": True}, {"shape": "flat", **STEEL}], load, effects,
                    **extra)


# -- the ratios that measure the chapter's assumptions (Contact.ratios of each kind) ----------

def test_power_law_and_punch_report_d_over_a():
    """A profile with no one radius or angle (power law, flat punch) reports d/a at the
    largest load, from the contact radius the scene itself reports; no state, no ratio; a
    state at d = 0 (a = 0) has no d/a (it would divide by zero)."""
    from hertzmdr.numeric.scene.kinds.base import State

    for body in ({"shape": "power_law", "coefficient": 1e6, "exponent": 3},
                 {"shape": "flat_punch", "radius": 1e-3}):
        rec, res, _ = tip(body, SWEEP, ["contact_radius"])
        a = float(np.max(res["contact_radius"].value))
        # 1e-15: one division of two floats
        assert rec.contact.ratios(rec._nodes) == {"d/a": pytest.approx(2e-6 / a, rel=1e-15,
                                                                        abs=0)}
        assert rec.contact.ratios({}) == {}
    zero = State(np.array([0.0]), np.array([0.0]), 1e-14, "test")
    pl, _, _ = tip({"shape": "power_law", "coefficient": 1e6, "exponent": 3}, {"depth": 1e-6},
                   ["depth"])
    assert pl.contact.ratios({"state": zero}) == {}


@pytest.mark.parametrize("body", [{"shape": "exact_sphere", "radius": 0.01},
                                  {"shape": "flattened_parabola", "radius": 0.05,
                                   "flat_radius": 1e-4}])
def test_profiles_with_a_radius_report_a_over_r(body):
    """A closed-form profile with a radius of curvature R (exact sphere, worn parabola) reports
    a/R and d/R at the largest load, from the scene's own contact radius and depth."""
    rec, res, _ = tip(body, {"depth": 2e-6}, ["contact_radius"])
    R = body["radius"]
    a = float(np.max(res["contact_radius"].value))
    # 1e-15: one division of two floats
    assert rec.contact.ratios(rec._nodes) == {"a/R": pytest.approx(a / R, rel=1e-15, abs=0),
                                              "d/R": pytest.approx(2e-6 / R, rel=1e-15, abs=0)}
    assert rec.contact.ratios({}) == {}


def test_numerical_mdr_reports_d_over_a():
    """A sampled profile reports d/a of its solution at the largest load; a solution of zero
    contact radius gives none (no division by zero)."""
    from types import SimpleNamespace

    r = list(np.linspace(0.0, 1e-3, 30))
    body = {"shape": "profile", "r": r, "f": [x * x / 0.02 for x in r]}
    rec, res, _ = tip(body, SWEEP,
                      ["contact_radius"])
    a = float(np.max(res["contact_radius"].value))
    assert rec.contact.ratios(rec._nodes) == {"d/a": pytest.approx(2e-6 / a, rel=1e-15, abs=0)}
    assert rec.contact.ratios({}) == {}
    none = SimpleNamespace(solutions=[SimpleNamespace(depth=0.0, contact_radius=0.0)])
    assert rec.contact.ratios({"state": none}) == {}


def test_elliptic_ratios_take_the_larger_semi_axis_ratio():
    """The elliptical contact's a/R is the larger of a/R1 and b/R2 (each semi-axis over the
    radius along it) and d/R is over the smaller radius: from the scene's semi-axes and depth,
    and for a state whose ratios swap which of the two is the larger."""
    from types import SimpleNamespace

    rec, res, _ = run_full([{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL}, RIGID_FLAT],
                           {"force": 10.0}, ["semi_axes", "depth"])
    c = rec.contact
    R1, R2 = c.R1, c.R2
    assert sorted([R1, R2]) == [0.01, 0.04]
    a, b = res["semi_axes"].value
    d = float(np.max(res["depth"].value))
    assert c.ratios(rec._nodes) == {"a/R": pytest.approx(max(a / R1, b / R2), rel=1e-15, abs=0),
                                    "d/R": pytest.approx(d / 0.01, rel=1e-15, abs=0)}
    assert c.ratios({}) == {}
    for sa, sb in ((1e-4, 1e-6), (1e-6, 1e-4)):  # a/R1 the larger, then b/R2
        st = SimpleNamespace(contact=SimpleNamespace(a=np.array([sa]), b=np.array([sb])),
                             depth=np.array([1e-6]))
        assert c.ratios({"state": st})["a/R"] == max(sa / R1, sb / R2)


def test_hertz_ratios_at_the_load_and_at_an_impact():
    """Hertz reports a/R and d/R at the largest load, and for an impact at its largest
    compression (the closed form of Problem 3): a = sqrt(R d) (5.21)."""
    R = 0.01
    rec, res, doc = run_full([{"shape": "sphere", "radius": R, **STEEL}, RIGID_FLAT],
                             {"depth": 2e-6}, ["contact_radius"])
    a = float(np.max(res["contact_radius"].value))
    assert rec.contact.ratios(rec._nodes) == {"a/R": pytest.approx(a / R, rel=1e-15, abs=0),
                                              "d/R": pytest.approx(2e-6 / R, rel=1e-15, abs=0)}
    assert rec.contact.ratios({}) == {}
    # the model block names the effective radius and the principal radii (R, R)
    assert doc["model"]["effective_radius"] == R
    assert doc["model"]["principal_radii"] == [R, R]
    rec, res, doc = run_full([{"shape": "sphere", "radius": R, **STEEL},
                              {"shape": "flat", **STEEL}],
                             {"impact": {"velocity": 1.0, "mass": 0.1}}, ["max_impact_depth"])
    assert "state" not in rec._nodes
    d = res["max_impact_depth"].value
    # 1e-15: a square root and a division
    assert rec.contact.ratios(rec._nodes) == {
        "a/R": pytest.approx(math.sqrt(R * d) / R, rel=1e-15, abs=0),
        "d/R": pytest.approx(d / R, rel=1e-15, abs=0)}
    assert doc["model"]["principal_radii"] == [R, R]  # an impact's striker: R itself


# -- the quadratic builder's choice (kinds/quadratic.py) and the Hertz kind (kinds/hertz.py) ---

def test_nearly_equal_radii_make_hertz_with_the_gaussian_radius():
    """Principal radii equal to a relative 1e-12 (CIRCULAR_RTOL) make a circular Hertz contact
    of the Gaussian radius sqrt(R1 R2) (5.30), which keeps the two principal radii it was made
    of; 1e-11 apart they make an elliptical contact (the threshold is relative to the larger
    radius, not absolute; radii exactly 1e-12 apart are still circular). The model block says
    why, in words that do not mention the exact sphere (no body is a 'sphere'). Exactly equal
    radii (a sphere) give R itself."""
    R1, R2 = 0.01, 0.01 * (1 + 1e-13)
    _, res, doc = run_full([{"shape": "ellipsoid", "radii": [R1, R2], **STEEL}, RIGID_FLAT],
                           {"force": 10.0}, ["principal_radii", "effective_radius"])
    assert doc["model"]["kind"] == "hertz"
    assert res["principal_radii"].value == [R1, R2]
    assert doc["model"]["principal_radii"] == [R1, R2]
    # 1e-15: a product and a square root; R1 itself is 5e-14 (relative) off
    assert res["effective_radius"].value == pytest.approx(math.sqrt(R1 * R2), rel=1e-15, abs=0)
    assert "equal (to a relative 1e-12) -> circular Hertz" in doc["model"]["why"]
    assert "exact_sphere" not in doc["model"]["why"]
    _, _, doc = run_full([{"shape": "ellipsoid", "radii": [R1, 0.01 * (1 + 1e-11)], **STEEL},
                          RIGID_FLAT], {"force": 10.0}, ["force"])
    assert doc["model"]["kind"] == "elliptic"
    # radii exactly at the threshold, |R1 - R2| = 1e-12 R2 in float64 (found by a search over
    # R2 = k ulp / 1e-12): still circular
    R1, R2 = 0.011267028976458095, 0.011267028976469362
    assert abs(R1 - R2) == 1e-12 * R2
    _, _, doc = run_full([{"shape": "ellipsoid", "radii": [R1, R2], **STEEL}, RIGID_FLAT],
                         {"force": 10.0}, ["force"])
    assert doc["model"]["kind"] == "hertz"
    # equal radii: R itself, not the Gaussian radius, whose float64 sqrt(R R) is 2e-18 m off
    _, res, _ = run_full([{"shape": "sphere", "radius": 0.01, **STEEL}, RIGID_FLAT],
                         {"force": 10.0}, ["effective_radius"])
    assert res["effective_radius"].value == 0.01


def test_the_model_says_which_quadratic_contact_and_why():
    """model.why names the builder's decision: a 'sphere' is Hertz's paraboloid (and the exact
    cap was not asked for); unequal radii make the exact or the Gaussian elliptical contact
    with their ratio R1/R2; a cylinder on a flat makes the line contact of its radius and
    length."""
    def why(bodies, **extra):
        return run_full(bodies, {"force": 10.0}, ["force"], **extra)[2]["model"]["why"]

    w = why([{"shape": "sphere", "radius": 0.01, **STEEL}, RIGID_FLAT])
    assert "R2 = 0.01 m equal (to a relative 1e-12) -> circular Hertz with R = 0.01 m" in w
    assert "the exact spherical cap (shape 'exact_sphere') was not requested" in w
    ell = [{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL}, RIGID_FLAT]
    w = why(ell)
    assert "differ (R1/R2 = 0.25) -> elliptical contact, exact (elliptic integrals)" in w
    assert "Gaussian" not in w
    w = why(ell, model={"elliptic": "gaussian"})
    assert w.endswith("-> elliptical contact, the chapter's Gaussian radius ([model] "
                      "elliptic = 'gaussian')")
    w = why([{"shape": "cylinder", "radius": 0.01, "length": 0.02, **STEEL}, RIGID_FLAT])
    assert "-> line contact with R = 0.01 m over the length L = 0.02 m" in w


def test_hertz_stresses_hold_the_scene_to_their_closed_forms_range():
    """The Hertz stresses' maxima are Nelder-Mead maxima verified to 1e-10 (MAXIMUM_RTOL): an
    rtol of 1e-12 with max_shear is refused, naming accuracy.rtol and the range; the cone's
    superposed stresses report their own estimate and restrict no rtol."""
    from hertzmdr.numeric.scene.kinds.stresses import MAXIMUM_RTOL

    sphere = [{"shape": "sphere", "radius": 0.01, **STEEL}, RIGID_FLAT]
    with pytest.raises(SceneError, match=r"accuracy.rtol: 1e-12 is outside the range "
                                         r"max_shear \(closed form\) can deliver: \[1e-10, 1\]"):
        run_full(sphere, {"depth": 1e-6}, ["max_shear"], accuracy={"rtol": 1e-12})
    assert MAXIMUM_RTOL == 1e-10
    # the cone at 1e-12 with its superposed stresses: no stress range is checked (the run
    # itself is not made: the check is the model's, before any effect)
    from hertzmdr.numeric.scene import model

    spec = scene.load({"effects": ["max_shear"], "body": [{"shape": "cone", "angle": "80 deg",
                                                           "rigid": True},
                                                          {"shape": "flat", **STEEL}],
                       "load": {"depth": 1e-6}, "accuracy": {"rtol": 1e-12}}).spec
    c = model.build(spec)
    assert [m for m, _ in c.rtol_ranges(["max_shear", "max_pressure"])] == [
        c.state_method, "the search for the largest pressure"]
    assert [m for m, _ in c.rtol_ranges(["max_shear"])] == [c.state_method]


def test_hertz_states_and_laws_name_their_equations():
    """Which closed form made each Hertz number: a force load inverts (5.23), a depth load
    evaluates it, the force law is (5.23)'s K and n (K d^1.5 = the scene's force at the
    depth), an impact's motion is integrated to the scene's rtol."""
    sphere = [{"shape": "sphere", "radius": 0.01, **STEEL}, RIGID_FLAT]
    _, res, _ = run_full(sphere, {"force": 10.0}, ["depth", "force_law", "force"])
    assert res["depth"].method == "(5.23) inverted"
    law = res["force_law"].value
    d = float(np.max(res["depth"].value))
    # 1e-14: (5.23) and its inverse, each a few roundings
    assert law["K"] * d ** law["n"] == pytest.approx(10.0, rel=1e-14, abs=0)
    assert "from (5.23):" in res["force_law"].method
    _, res, _ = run_full([{"shape": "sphere", "radius": 0.01, **STEEL},
                          {"shape": "flat", **STEEL}],
                         {"impact": {"velocity": 1.0, "mass": 0.1}}, ["contact_time", "depth"],
                         accuracy={"rtol": 1e-8})
    assert "(DOP853, rtol 1e-08)" in res["contact_time"].method
    assert res["depth"].method == "Problem 3 (largest compression)"


# -- the grids, keys and methods of the stress effects (kinds/stresses.py, kinds/elliptic.py) --

STRESS = ["axis_stresses", "max_shear", "von_mises_field", "max_von_mises",
          "max_orthogonal_shear"]


def _grid(v, start, end, n):
    """v is n points from start to end, evenly spaced (1e-15: linspace's rounding)."""
    v = np.asarray(v)
    assert v.shape == (n,)
    assert v[0] == pytest.approx(start, rel=1e-15, abs=0)
    assert v[-1] == pytest.approx(end, rel=1e-15, abs=0)
    assert np.allclose(np.diff(v), (end - start) / (n - 1), rtol=1e-9, atol=0)


def _symmetric(x, half, n):
    """n points over [-half, half], exact mirror images, the centre exactly 0."""
    _grid(x, -half, half, n)
    assert np.array_equal(x, -x[::-1]) and x[n // 2] == 0.0


def test_hertz_stress_grids_and_methods():
    """The Hertz stresses on the grids their docstrings give, in units of the contact radius a
    the scene reports: the axis 0..3a (201 points), the von Mises field x in [-2a, 2a]
    (mirrored, centre 0) by z in [0, 2a] (101 x 101); the field's value on the axis column is
    the closed-form axis von Mises stress |sigma_zz - sigma_rr| (a diagonal tensor with two
    equal principal stresses). Every method names its equations."""
    rec, res, _ = run_full([{"shape": "sphere", "radius": 0.01, **STEEL}, RIGID_FLAT],
                           {"depth": 1e-6}, STRESS + ["contact_radius"])
    a = float(np.max(res["contact_radius"].value))
    ax = res["axis_stresses"].value
    _grid(ax["z"], 0.0, 3 * a, 201)
    f = res["von_mises_field"].value
    _symmetric(np.asarray(f["x"]), 2 * a, 101)
    _grid(f["z"], 0.0, 2 * a, 101)
    sv = np.asarray(f["sigma_v"])
    assert sv.shape == (101, 101)
    # the axis column against the axis stresses interpolated at the field's z (both closed
    # forms; 1e-12 p0: the field's and the axis' roundings)
    ref = np.abs(np.interp(f["z"], ax["z"], np.asarray(ax["sigma_zz"]) - ax["sigma_rr"]))
    on_grid = np.isin(np.round(np.asarray(f["z"]) / a * 200), np.arange(0, 401, 3))
    assert np.allclose(sv[on_grid, 50], ref[on_grid], rtol=1e-12, atol=1e-12 * sv.max())
    assert "(5.48), (5.49)" in res["axis_stresses"].method
    assert res["von_mises_field"].method.endswith(", (5.50)")
    assert "(grid, then Nelder-Mead)" in res["max_shear"].method
    assert "maximum of (5.50)" in res["max_von_mises"].method
    assert "Huber's tau_rz" in res["max_orthogonal_shear"].method


def test_line_stress_grids_and_methods():
    """The line contact's stresses on the grids of its half-width b: the axis 0..3b (201), the
    field x in [-2b, 2b] (mirrored) by z in [0, 2b] (101 x 101); the largest von Mises stress
    lies on the axis (x = 0). Every method names its route."""
    _, res, _ = run_full([{"shape": "cylinder", "radius": 0.01, "length": 0.02, **STEEL},
                          RIGID_FLAT], {"force": 100.0}, STRESS + ["half_width"])
    b = float(np.max(res["half_width"].value))
    _grid(res["axis_stresses"].value["z"], 0.0, 3 * b, 201)
    f = res["von_mises_field"].value
    _symmetric(np.asarray(f["x"]), 2 * b, 101)
    _grid(f["z"], 0.0, 2 * b, 101)
    assert np.asarray(f["sigma_v"]).shape == (101, 101)
    assert res["max_von_mises"].value["x"] == 0.0
    # the largest orthogonal shear: exactly p0/4 at (3^(1/2)/2 b, b/2) (the method says so)
    assert res["max_orthogonal_shear"].value["x"] == pytest.approx(math.sqrt(3) / 2 * b,
                                                                   rel=1e-10, abs=0)
    assert "sigma_rr is sigma_xx" in res["axis_stresses"].method
    assert res["von_mises_field"].method.endswith(", (5.50)")
    assert "bounded Brent" in res["max_shear"].method
    assert "the surface centre or the root" in res["max_von_mises"].method
    assert "exactly p0/4" in res["max_orthogonal_shear"].method


def test_symmetric_grid_points():
    """symmetric_grid(half, n): n points, mirror images, the centre 0, for the odd n the grids
    use (and n = 5 by hand)."""
    from hertzmdr.numeric.scene.kinds.stresses import symmetric_grid

    assert symmetric_grid(2.0, 5).tolist() == [-2.0, -1.0, 0.0, 1.0, 2.0]
    _symmetric(symmetric_grid(3e-4, 101), 3e-4, 101)


ELLIPSOID = [{"shape": "ellipsoid", "radii": [0.01, 0.04], **STEEL}, RIGID_FLAT]


def test_ellipse_axis_stresses():
    """The elliptical contact's axis stresses on z in [0, 3b] (b the smaller semi-axis the
    scene reports, 201 points), tau_1 = (sigma_1 - sigma_3)/2 of the diagonal tensor (the
    largest of the three differences, by hand), max_shear at least the largest tau_1 on the
    grid and within its spacing's reach (a smooth maximum: 1e-4 relative for a step of
    b/67), and every method naming its route."""
    _, res, _ = run_full(ELLIPSOID, {"force": 10.0}, ["axis_stresses", "max_shear",
                                                      "max_von_mises", "semi_axes"])
    a, b = sorted(res["semi_axes"].value, reverse=True)
    ax = res["axis_stresses"].value
    _grid(ax["z"], 0.0, 3 * b, 201)
    s = np.array([ax["sigma_xx"], ax["sigma_yy"], ax["sigma_zz"]])
    tau = np.max(np.abs(s[:, None, :] - s[None, :, :]), axis=(0, 1)) / 2
    assert np.array_equal(ax["tau_1"], tau)
    top = res["max_shear"].value["value"]
    assert tau.max() <= top * (1 + 1e-12) and top <= tau.max() * (1 + 1e-4)
    assert res["axis_stresses"].method.endswith("Carlson R_D on the axis")
    assert res["max_shear"].method.endswith("on the axis, Brent on the derived slope (R_D)")
    assert res["max_von_mises"].method.startswith("largest (5.50) on the axis")


def test_ellipse_field_is_the_nearly_circular_hertz_field(monkeypatch):
    """Radii 1e-6 apart make an elliptical contact whose von Mises field in both planes is
    Hertz's closed form of the Gaussian radius sqrt(a b) and the same p0 (x-z plane: x in
    [-2a, 2a]; y-z plane: y in [-2b, 2b]; z in [0, 2b]), to O(e^2) = O(1e-6) below the
    surface; on the surface the edge point y = b sits on the pressure's square-root edge,
    where the field moves like the square root of the semi-axes' difference (3e-4 p0
    measured). On 5 x 5 points instead of GRID_POINTS' 101."""
    from hertzmdr.numeric import stress
    from hertzmdr.numeric.scene.kinds import elliptic

    monkeypatch.setattr(elliptic, "GRID_POINTS", 5)
    rec, res, _ = run_full([{"shape": "ellipsoid", "radii": [0.01, 0.01 * (1 + 1e-6)], **STEEL},
                            RIGID_FLAT], {"force": 10.0},
                           ["von_mises_field", "semi_axes", "max_pressure"])
    assert rec.contact.kind == "elliptic"
    a, b = sorted(res["semi_axes"].value, reverse=True)
    p0 = float(np.max(res["max_pressure"].value))
    f = res["von_mises_field"].value
    _grid(f["x"], -2 * a, 2 * a, 5)
    _grid(f["y"], -2 * b, 2 * b, 5)
    _grid(f["z"], 0.0, 2 * b, 5)
    for key, plane in (("sigma_v", f["x"]), ("sigma_v_yz", f["y"])):
        P, Z = np.meshgrid(plane, f["z"])
        ref = stress.von_mises(stress.hertz_stress(P, 0 * P, Z, math.sqrt(a * b), p0, 0.3))
        dev = np.abs(np.asarray(f[key]) - ref) / p0
        assert np.max(dev[1:]) < 1e-5  # e^2 = 1 - b^2/a^2 = 1.3e-6, a few times it
        assert np.max(dev[0]) < 1e-3   # the surface row: 3e-4 p0 at the edge, see above
    assert res["von_mises_field"].method.endswith("double-exponential quadrature, (5.50)")


def test_ellipse_field_is_asked_the_scene_rtol(monkeypatch):
    """The field's quadrature is asked the scene's rtol (here 1e-6; at the default 1e-10 the
    estimate is 1.2e-14): both planes are numeric/ellipse_stress.py's von Mises at that rtol
    on the solver's semi-axes, which are the scene's, and the reported error is the larger
    plane's estimate over the largest stress."""
    from hertzmdr.numeric import ellipse_stress as el
    from hertzmdr.numeric.scene.kinds import elliptic

    monkeypatch.setattr(elliptic, "GRID_POINTS", 5)
    rec, res, _ = run_full(ELLIPSOID, {"force": 10.0}, ["von_mises_field", "semi_axes",
                                                        "max_pressure"],
                           accuracy={"rtol": 1e-6})
    s = rec._nodes["stress"]
    assert [s.a, s.b] == sorted(res["semi_axes"].value, reverse=True)
    assert s.p0 == float(np.max(res["max_pressure"].value))
    f = res["von_mises_field"].value
    X, Z = np.meshgrid(f["x"], f["z"])
    vx, ex = el.von_mises(X, 0 * X, Z, s.a, s.b, s.p0, 0.3, rtol=1e-6)
    Y, Z = np.meshgrid(f["y"], f["z"])
    vy, ey = el.von_mises(0 * Y, Y, Z, s.a, s.b, s.p0, 0.3, rtol=1e-6)
    assert np.array_equal(f["sigma_v"], vx) and np.array_equal(f["sigma_v_yz"], vy)
    assert res["von_mises_field"].rel_error == max(ex.max(), ey.max()) / vx.max() > 1e-9


def test_ellipse_field_error_is_relative(monkeypatch):
    """The field's rel_error is relative to its largest stress: a contact of the same radii
    and a modulus 2.1e11 times smaller (p0 = 0.09 Pa instead of 6.7e8 Pa) has the same
    dimensionless field and so the same rel_error (1e-12: the quadrature's estimate is the
    same sum in the scaled variables, rounded differently)."""
    from hertzmdr.numeric.scene.kinds import elliptic

    monkeypatch.setattr(elliptic, "GRID_POINTS", 5)
    errs = []
    for E, F in ((210e9, 10.0), (1.0, 1e-6)):
        _, res, _ = run_full([{"shape": "ellipsoid", "radii": [0.01, 0.04], "E": E, "nu": 0.3},
                              RIGID_FLAT], {"force": F}, ["von_mises_field"])
        errs.append(res["von_mises_field"].rel_error)
    assert 0 < errs[0] < 1e-12
    assert errs[1] == pytest.approx(errs[0], rel=1e-12, abs=0)


def test_ellipse_orthogonal_shear_where_it_is():
    """The largest |tau_yz| (plane x = 0) and |tau_xz| (plane y = 0): each reported value is
    |tau| of numeric/ellipse_stress.py's quadrature at the reported point (1e-9 p0: the
    quadrature at its default 1e-10), the point inside the half-space within the semi-axes
    (b/a = 0.4 here: 0.86 b and 0.45 b deep across, 0.86 a and 0.54 b deep along)."""
    from hertzmdr.numeric import ellipse_stress as el

    rec, res, _ = run_full(ELLIPSOID, {"force": 10.0}, ["max_orthogonal_shear"])
    s = rec._nodes["stress"]
    v = res["max_orthogonal_shear"].value
    assert v["x"] == 0.0
    yz = el.stresses(0.0, v["y"], v["z"], s.a, s.b, s.p0, 0.3)
    xz = el.stresses(v["x_xz"], 0.0, v["z_xz"], s.a, s.b, s.p0, 0.3)
    assert abs(float(yz.tau_yz)) == pytest.approx(v["value"], rel=0, abs=1e-9 * s.p0)
    assert abs(float(xz.tau_xz)) == pytest.approx(v["value_xz"], rel=0, abs=1e-9 * s.p0)
    # across the short axis between Hertz's 0.214 p0 and the line contact's p0/4; along the
    # long axis (the flatter pressure) less
    assert 0.214 * s.p0 < v["value"] < 0.25 * s.p0 and 0 < v["value_xz"] < v["value"]
    assert 0 < v["y"] < s.b and 0 < v["z"] < s.b and 0 < v["x_xz"] < s.a and 0 < v["z_xz"] < s.b
    assert "Nelder-Mead" in res["max_orthogonal_shear"].method


def test_gaussian_ellipse_stresses_are_the_exact_ones():
    """Under [model] elliptic = 'gaussian' the stresses are those of the exact ellipse (the
    estimate's own semi-axes would be a different field): the solver's a, b and p0 are the
    exact model's semi-axes and largest pressure. The two models take their own branches:
    the exact state names the elliptic integrals and no Gaussian estimate, the Gaussian one
    names it; the exact force law's K reproduces the scene's force at its depth."""
    rec, res, _ = run_full(ELLIPSOID, {"force": 10.0},
                           ["semi_axes", "max_pressure", "depth", "force_law"])
    assert res["depth"].method == "elliptic integrals"
    law = res["force_law"].value
    d = float(np.max(res["depth"].value))
    # 1e-12: the exact solution's K and its depth, each verified to EXACT_RTOL
    assert law["K"] * d ** 1.5 == pytest.approx(10.0, rel=1e-12, abs=0)
    assert "from the exact elliptical contact (elliptic integrals)" in res["force_law"].method
    g, gres, _ = run_full(ELLIPSOID, {"force": 10.0}, ["axis_stresses", "depth", "force_law"],
                          model={"elliptic": "gaussian"})
    s = g._nodes["stress"]
    assert [s.a, s.b] == sorted(res["semi_axes"].value, reverse=True)
    assert s.p0 == float(np.max(res["max_pressure"].value))
    assert gres["depth"].method.startswith("Gaussian radius (5.28)-(5.30), Gaussian estimate")
    assert "from (5.23) with the Gaussian radius (5.30)" in gres["force_law"].method


# -- the closed-form axisymmetric kinds (kinds/axisym.py) --------------------------------------

CONE = {"shape": "cone", "angle": "80 deg"}


@pytest.mark.parametrize("effect", ["max_shear", "max_von_mises"])
def test_each_maximum_is_refused_under_a_singular_pressure_at_half(effect):
    """A cone's pressure is singular at the tip; in an incompressible body (nu = 0.5) the
    surface stress there is hydrostatic to leading order and neither maximum is computed:
    each is refused on its own, with the reason."""
    with pytest.raises(SceneError, match=f"effect '{effect}' does not apply.*hydrostatic"):
        run_full([{**CONE, "rigid": True}, {"shape": "flat", "E": 70e9, "nu": 0.5}],
                 {"depth": 1e-6}, [effect])


def test_orthogonal_shear_is_refused_under_a_singular_pressure():
    """The largest |tau_rz| under a singular pressure sits at the singular point or grows
    toward it: refused with the pressure's reason and why the grid cannot resolve it."""
    with pytest.raises(SceneError, match="log-singular at the tip.*the stress grid cannot "
                                         "resolve"):
        tip(CONE, {"depth": 1e-6}, ["max_orthogonal_shear"])


def test_force_law_of_a_closed_form_profile():
    """The force law of a profile that is no power law is refused with the profile's own
    reason (the exact sphere: Hertz's law only as a/R -> 0), offering the tabulated curve; a
    cone's law names its equation (5.40) and reproduces the scene's force at its depth."""
    with pytest.raises(SceneError, match=r"Sneddon's spherical cap has F = K d\^\(3/2\) "
                                         r"\(Hertz\) only as a/R -> 0.*'force_depth_curve'"):
        tip({"shape": "exact_sphere", "radius": 0.01}, {"depth": 1e-6}, ["force_law"])
    _, res, _ = tip(CONE, {"depth": 1e-6}, ["force_law", "force"])
    law = res["force_law"].value
    # 1e-14: (5.40) and the force of (5.38)-(5.40), a few roundings each
    assert law["K"] * 1e-6 ** law["n"] == pytest.approx(float(np.max(res["force"].value)),
                                                        rel=1e-14, abs=0)
    assert "from (5.40):" in res["force_law"].method


def test_pressure_radii_step_off_the_kink():
    """A worn parabola's pressure is log-infinite at its kink r = b: a point of the pressure
    profile's grid that falls on b (to 1e-12 a) moves 1e-3 of the first step outward; every
    other point stays where linspace put it (the first on the axis: the worn parabola's p is
    finite there; with the first point off the axis, as a cone's, the first step is the one
    from 1e-3 a). Contact radii chosen to put b on the grid, and 1e-11 m off it (not moved:
    1e-11 m > 1e-12 a for a = 1.5e-3 m); a kink at 1e-12 a, the tolerance's edge, moves the
    point r = 0."""
    from hertzmdr.numeric.scene import model

    b = 1e-4
    spec = scene.load({"effects": ["pressure_profile"], "load": {"depth": 1e-6},
                       "body": [{"shape": "flattened_parabola", "radius": 0.05,
                                 "flat_radius": b, "rigid": True},
                                {"shape": "flat", **STEEL}]}).spec
    c = model.build(spec)
    assert c.kink == b and not c.off_axis
    a = b * 200 / (1.5 * 20)  # r[20] = 20 (1.5 a / 200) = b
    plain = np.linspace(0.0, 1.5 * a, 201)
    assert abs(plain[20] - b) <= 1e-12 * a
    r = c.pressure_radii(a)
    moved = plain.copy()
    moved[20] += 1e-3 * (plain[1] - plain[0])
    assert np.array_equal(r, moved)
    c.off_axis = True  # as a cone's profile: the first point at 1e-3 a, the step shorter
    moved[0] = 1e-3 * a
    moved[20] = plain[20] + 1e-3 * (plain[1] - moved[0])
    assert np.array_equal(c.pressure_radii(a), moved)
    c.off_axis = False
    a = 1.5e-3
    plain = np.linspace(0.0, 1.5 * a, 201)
    c.kink = plain[20] + 1e-11  # off the grid by 1e-11 m, more than 1e-12 a
    assert np.array_equal(c.pressure_radii(a), plain)
    c.kink = 1e-12 * a  # r[0] = 0 exactly 1e-12 a from it (in float64 too): moved
    moved = plain.copy()
    moved[0] = 1e-3 * plain[1]
    assert np.array_equal(c.pressure_radii(a), moved)


@pytest.mark.parametrize("body, n", [(CONE, 1.0),
                                     ({"shape": "power_law", "coefficient": 1e6,
                                       "exponent": 3}, 3.0)])
def test_cone_and_power_law_tangential_closed_forms(body, n):
    """A cone and a power law take the tangential closed forms (not the springs on a grid,
    whose error is 1e-6): the stick radius c of a tangential force F_x follows Jaeger's
    principle, the normal force of the contact of radius c is F - F_x/mu, and F ~ a^(n + 1)
    for f = c r^n: c = a (1 - F_x/(mu F))^(1/(n + 1)); to 1e-12 (the closed forms' 1e-13)."""
    F, Fx, mu = 10.0, 2.0, 0.6
    _, res, _ = tip(body, {"force": F, "tangential": {"force": f"{Fx} N"}},
                    ["stick_radius", "contact_radius"], interface={"friction": mu})
    a = float(np.max(res["contact_radius"].value))
    c = res["stick_radius"]
    assert c.rel_error == 1e-13
    assert c.value == pytest.approx(a * (1 - Fx / (mu * F)) ** (1 / (n + 1)), rel=1e-12, abs=0)


def test_flat_punch_tangential_closed_form():
    """A flat punch sticks wholly until it slides (Problem 7(a)'s g = 0 inside): the stick
    radius is the punch's radius and u_x = F_x/(2 G* a), G* = 4 G/(2 - nu) of the steel flat
    (the rigid punch adds nothing), G = E/(2 (1 + nu)); to 1e-13."""
    E, nu, a, Fx = STEEL["E"], STEEL["nu"], 1e-3, 2.0
    _, res, _ = tip({"shape": "flat_punch", "radius": a},
                    {"force": 10.0, "tangential": {"force": f"{Fx} N"}},
                    ["stick_radius", "tangential_displacement"], interface={"friction": 0.6})
    G_star = 4 * E / (2 * (1 + nu)) / (2 - nu)
    assert res["stick_radius"].value == a
    assert res["tangential_displacement"].value == pytest.approx(Fx / (2 * G_star * a),
                                                                 rel=1e-13, abs=0)
    # by the closed form: the springs on a grid give the same numbers for a punch since its
    # histories run (tangential.history's wall), so the method tells the routes apart
    for name in ("stick_radius", "tangential_displacement"):
        assert res[name].method == "MDR tangential springs (Cattaneo-Mindlin, derive/tangential.py)"


# -- the numerical MDR (kinds/axisym.py NumericalMDR, build_numerical) -------------------------

def _sampled(n, **extra):
    """A sampled profile f = r^2.5 / (2 sqrt(R)), R = 10 mm (no polynomial: the spline degree
    matters), on n samples to 1 mm."""
    r = list(np.linspace(0.0, 1e-3, n))
    return {"shape": "profile", "r": r, "f": [x ** 2.5 / (2 * 0.1) for x in r], **extra}


def test_sampled_profile_spline_degree_and_breakpoints():
    """A profile of fewer than 20 samples is splined cubically (k = 3, the shape's rule), and
    its breakpoints (kinks) are passed on: the scene's contact radius is that of
    numeric/mdr.py's Profile.from_samples with k = 3 and the breakpoint, and differs from the
    quintic's and from the spline across the kink (the test tells them apart)."""
    from hertzmdr.numeric import mdr
    from hertzmdr.numeric.scene.accuracy import DEFAULT_RTOL

    body = _sampled(11, breakpoints=[4e-4])
    _, res, _ = tip(body, {"depth": 1e-7}, ["contact_radius"])
    E_star = STEEL["E"] / (1 - STEEL["nu"] ** 2)  # (5.26) with a rigid tip

    def a(**kw):
        prof = mdr.Profile.from_samples(body["r"], body["f"], **kw)
        return prof.solve(E_star=E_star, rtol=DEFAULT_RTOL, depth=1e-7).contact_radius

    got = float(np.max(res["contact_radius"].value))
    assert got == pytest.approx(a(k=3, breakpoints=(4e-4,)), rel=1e-15, abs=0)
    assert got != pytest.approx(a(k=5, breakpoints=(4e-4,)), rel=1e-12, abs=0)
    assert got != pytest.approx(a(k=3), rel=1e-12, abs=0)


def test_numerical_mdr_stresses_carry_the_pressure_error():
    """The stresses under a sampled profile superpose the solution's own pressure over its
    own contact radius, and their error adds the pressure's bound relative to its largest
    value on r < a and 3 times the contact radius's (docstring of stress_solver): built
    here without superposing anything (the solver is made, not run)."""
    r = list(np.linspace(0.0, 1e-3, 30))
    body = {"shape": "profile", "r": r, "f": [x * x / 0.02 for x in r]}
    rec, res, _ = tip(body, {"depth": 2e-6}, ["contact_radius"])
    c, st = rec.contact, rec._nodes["state"]
    s = st.solutions[-1]
    solver = c.stress_solver(st)
    assert solver.a == s.contact_radius == float(np.max(res["contact_radius"].value))
    rr = np.linspace(0.0, s.contact_radius, 201)[:-1]
    p, e = s.pressure(rr, return_error=True)
    assert np.array_equal(solver.p(rr), p)
    assert s.rel_error > 0 and np.max(e) > 0
    assert solver.pressure_error == pytest.approx(np.max(e) / np.max(np.abs(p))
                                                  + 3 * s.rel_error, rel=1e-15, abs=0)


# -- the superposed stresses' bookkeeping (kinds/stresses.py SuperposedStresses) ---------------

def test_superposed_axis_under_a_paraboloid_is_hertz(monkeypatch):
    """The power law f = r^2/(2R) is Hertz's paraboloid: its superposed axis stresses at
    z = a, 2a, 3a (AXIS_POINTS_SUPERPOSED = 4 instead of 31: the grid 0..3a without its z = 0)
    are Hertz's closed forms (5.48)-(5.49) for the scene's a and p0, within the rel_error
    they report (of the largest |sigma_zz|), which is the quadrature's bound: 2 estimates +
    1e-14, with no pressure error for a closed-form pressure."""
    from hertzmdr.numeric import stress
    from hertzmdr.numeric.scene.kinds import stresses

    monkeypatch.setattr(stresses, "AXIS_POINTS_SUPERPOSED", 4)
    _, res, _ = tip({"shape": "power_law", "coefficient": 50.0, "exponent": 2},
                    {"depth": 1e-6}, ["axis_stresses", "contact_radius", "max_pressure"])
    a = float(np.max(res["contact_radius"].value))
    p0 = float(np.max(res["max_pressure"].value))
    ax = res["axis_stresses"]
    z = np.asarray(ax.value["z"])
    assert z == pytest.approx([a, 2 * a, 3 * a], rel=1e-15, abs=0)
    szz, srr = stress.axis_stresses(z, a, p0, 0.3)
    bound = ax.rel_error * np.max(np.abs(szz))
    assert 1e-14 <= ax.rel_error < 1e-13
    assert np.max(np.abs(ax.value["sigma_zz"] - szz)) <= bound
    assert np.max(np.abs(ax.value["sigma_rr"] - srr)) <= bound


class _Fake:
    """numeric/stress.py's superposition, replaced by fixed numbers: what SuperposedStresses
    does with them is the test."""

    def __init__(self, monkeypatch):
        from hertzmdr.numeric import stress

        self.calls = []
        monkeypatch.setattr(stress, "superposed_stress", self.stress)
        monkeypatch.setattr(stress, "superposed_plane", self.plane)
        monkeypatch.setattr(stress, "superposed_maximum", self.maximum)

    def stress(self, x, y, z, p, a, nu):
        self.calls.append(("stress", np.array(x), np.array(y), np.array(z)))
        s = np.zeros(np.shape(z) + (3, 3))
        s[..., 2, 2], s[..., 0, 0] = -4.0 * (1 + np.arange(np.size(z))), -1.0
        e = np.zeros_like(s)
        e[..., 2, 2], e[..., 0, 0], e[..., 0, 1], e[..., 1, 0] = 3e-6, 1e-6, 7e-6, 9e-6
        return s, e

    def plane(self, p, a, nu, *, n):
        from types import SimpleNamespace

        self.calls.append(("plane", n))
        x = np.linspace(0.0, 2 * a, n)
        return SimpleNamespace(x=x, z=np.linspace(0.0, 2 * a, n)[1:],
                               von_mises=np.arange((n - 1) * n, dtype=float).reshape(n - 1, n),
                               rel_error=5e-9)

    def maximum(self, p, a, nu, criterion, plane):
        self.calls.append(("maximum", criterion))
        return {"von_mises": 10.0, "max_shear": 5.0, "orthogonal_shear": 2.0}[criterion], \
            0.25 * a, 0.5 * a, 1e-7


def test_superposed_bookkeeping(monkeypatch):
    """From numeric/stress.py's numbers to the effects: the axis on z = 0..3a without z = 0
    (AXIS_POINTS_SUPERPOSED points), sigma_zz and sigma_rr the tensor's (2, 2) and (0, 0),
    tau_1 = |sigma_zz - sigma_rr|/2, the error 2 (e_zz + e_rr)/max|sigma_zz| + 1e-14 plus the
    pressure's; the field mirrored at x = 0 with 2 estimates + 1e-14 + the pressure's; each
    maximum asked by its criterion, with 2 estimates + 1e-14 + the pressure's. Without a
    pressure error (a closed form's p) that term is 0."""
    from hertzmdr.numeric.scene.kinds import stresses

    fake = _Fake(monkeypatch)
    a, pe = 2e-4, 1e-3
    s = stresses.SuperposedStresses(lambda r: 0 * r, a, 0.3, pressure_error=pe)
    ax = s.axis()
    n = stresses.AXIS_POINTS_SUPERPOSED
    _, x, y, z = fake.calls[0]
    assert np.array_equal(z, np.linspace(0.0, 3 * a, n)[1:]) and z.size == n - 1
    assert not np.any(x) and not np.any(y)
    szz = -4.0 * (1 + np.arange(n - 1))
    assert np.array_equal(ax.value["z"], z) and np.array_equal(ax.value["sigma_zz"], szz)
    assert ax.method == "superposition of the point-force field (5.47), tanh-sinh"
    assert np.array_equal(ax.value["sigma_rr"], np.full(n - 1, -1.0))
    assert np.allclose(ax.value["tau_1"], np.abs(szz + 1.0) / 2, rtol=1e-15, atol=0)
    assert ax.rel_error == pytest.approx(2 * 4e-6 / (4.0 * (n - 1)) + 1e-14 + pe, rel=1e-15,
                                         abs=0)
    assert stresses.SuperposedStresses(lambda r: 0 * r, a, 0.3).axis().rel_error == \
        pytest.approx(2 * 4e-6 / (4.0 * (n - 1)) + 1e-14, rel=1e-15, abs=0)
    f = s.field()
    m = stresses.GRID_SUPERPOSED
    assert ("plane", m) in fake.calls
    xs = np.asarray(f.value["x"])
    assert xs.size == 2 * m - 1 and np.array_equal(xs, -xs[::-1]) and xs[-1] == 2 * a
    vm = np.asarray(f.value["sigma_v"])
    assert vm.shape == (m - 1, 2 * m - 1) and np.array_equal(vm, vm[:, ::-1])
    assert f.rel_error == pytest.approx(2 * 5e-9 + 1e-14 + pe, rel=1e-15, abs=0)
    assert f.method.endswith("tanh-sinh, (5.50)")
    for name, crit, value in (("max_von_mises", "von_mises", 10.0),
                              ("max_orthogonal_shear", "orthogonal_shear", 2.0)):
        v = getattr(s, name)()
        assert fake.calls[-1] == ("maximum", crit)
        assert v.value == {"value": value, "x": 0.25 * a, "z": 0.5 * a}
        assert v.rel_error == pytest.approx(2e-7 + 1e-14 + pe, rel=1e-15, abs=0)
    v = s.max_shear()
    assert fake.calls[-1] == ("maximum", "max_shear")
    assert v.value == {"value": 5.0, "depth": 0.5 * a}
    assert s.max_orthogonal_shear().method.startswith("|tau_rz|: largest on a ")
    assert s.unbounded is None


# -- the BEM's error from half resolution (kinds/grid.py) --------------------------------------

def test_relative_difference_of_two_resolutions():
    """The largest |got/ref - 1|: points where both agree (a load of 0 at both resolutions)
    count 0, not 0/0, under the runner's floating-point checks; only ref = 0 is infinite."""
    from hertzmdr.numeric.scene.kinds.grid import relative_difference

    with np.errstate(over="raise", invalid="raise", divide="raise"):  # as runner.py runs it
        assert relative_difference([0.0, 3.0, 1.5], [0.0, 3.0, 1.0]) == 0.5
        assert relative_difference([0.0, 2.0], [0.0, 2.0]) == 0.0
        assert relative_difference([1.0, 2.0], [0.0, 2.0]) == math.inf


def test_bem_largest_pressure_method(tmp_path):
    """The BEM's largest pressure of a height map (a paraboloid on 16 x 16 pixels) is the
    largest pixel pressure, at both resolutions: at least the mean pressure."""
    x = (np.arange(16) - 7.5) * 1e-6
    h = (x[:, None] ** 2 + x[None, :] ** 2) / (2 * 1e-3)  # R = 1 mm
    np.savetxt(tmp_path / "heights.csv", h, delimiter=",")
    (tmp_path / "s.toml").write_text(
        'effects = ["max_pressure", "mean_pressure"]\n[[body]]\nshape = "height_map"\n'
        'file = "heights.csv"\nspacing = "1 um"\nrigid = true\n[[body]]\nshape = "flat"\n'
        'E = "1 GPa"\nnu = 0.3\n[load]\ndepth = "10 nm"\n')
    eff = scene.load(tmp_path / "s.toml").run()["effects"]
    assert eff["max_pressure"]["method"] == "largest pixel pressure"
    assert eff["max_pressure"]["value"] > eff["mean_pressure"]["value"] > 0
