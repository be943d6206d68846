"""Tests that kill the surviving mutants of numeric/scene/kinds/adhesive.py (and of
kinds/pressure.py and kinds/line.py) of the scene_kinds mutation run
(benchmarks/mutation_runs/scene_kinds.json; notes in benchmarks/mutation_notes_scene_adhesive.toml).

Each test checks what a line of the adhesive kind computes -- which adhesive shape a contact
becomes, its parameters, the model block and the ratios it reports, the grids of its fields,
the effects no earlier test called (mean pressure, stiffness, force-depth curve, MDR profile,
effective radius), the error model of a sampled profile (coarse vs fine samples), which
effects it refuses and why -- by another route: JKR's and Kendall's closed forms and the
exact sphere's limit JKR at mpmath's 30 digits, a cone against the power law n = 1 of the
same slope, the adhesive stiffness as the derivative of JKR's parametric F(d), and the error
model recomputed from its docstring on the coarse representation. Small scenes only: the
whole file takes a few seconds."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import adhesion as ad
from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds import adhesive as kadh
from hertzmdr.numeric.scene.kinds import base
from hertzmdr.numeric.scene.model import build
from hertzmdr.numeric.scene.schema import SceneError

from oracle import assert_close

# every pytest.approx here has abs=0: its default absolute tolerance (1e-12) would accept any
# error of the small values compared (forces of nN, lengths of nm)

#: a rigid tip on PDMS (E* = E/(1 - nu^2) = 2 MPa/0.75), Delta gamma = 0.05 J/m^2: JKR holds
PDMS = {"shape": "flat", "E": 2e6, "nu": 0.5}
E_STAR = 2e6 / 0.75
DG = 0.05
R = 20e-9
SPHERE = {"shape": "sphere", "radius": R}


def spec(tip, load, effects=("force",), interface=None, flat=PDMS, **extra):
    """A scene of the rigid ``tip`` on ``flat`` (PDMS) with Delta gamma = DG by default."""
    return scene.load({"effects": list(effects), "body": [{**tip, "rigid": True}, flat],
                       "interface": {"work_of_adhesion": DG} if interface is None else interface,
                       "load": load, **extra})


def effects(tip, load, names, interface=None, **extra):
    return spec(tip, load, names, interface, **extra).run()["effects"]


def kind_and_state(sp):
    contact = build(sp.spec)
    return contact, contact.state(sp.spec.load)


def jkr(a_ref=None):
    """JKR's closed forms at 30 digits (mpmath numbers): d(a), F(a) and the pull-offs."""
    Em, Rm, gm = mp.mpf(E_STAR), mp.mpf(R), mp.mpf(DG)
    return {
        "d": lambda a: a**2 / Rm - mp.sqrt(2 * mp.pi * a * gm / Em),
        "F": lambda a: 4 * Em * a**3 / (3 * Rm) - mp.sqrt(8 * mp.pi * a**3 * gm * Em),
        # a(F) on the stable branch (a beyond the force-control pull-off radius)
        "a_of_F": lambda F: mp.cbrt(3 * Rm / (4 * Em) * (F + 3 * mp.pi * Rm * gm + mp.sqrt(
            6 * mp.pi * Rm * gm * F + (3 * mp.pi * Rm * gm) ** 2))),
        "F_fc": -3 * mp.pi * Rm * gm / 2, "F_dc": -5 * mp.pi * Rm * gm / 6,
        "a0": mp.cbrt(9 * mp.pi * Rm**2 * gm / (2 * Em)),  # F = 0
    }


# -- which adhesive shape a contact becomes (_shape) and the model block -----------------------

def _kendall(a):
    return -math.sqrt(8 * math.pi * a**3 * E_STAR * DG)


@pytest.mark.parametrize("name, tip, closed", [
    ("punch", {"shape": "flat_punch", "radius": 1e-6}, True),
    ("power_law n = 2", {"shape": "power_law", "coefficient": 1 / (2 * R), "exponent": 2},
     True),
    ("flattened parabola", {"shape": "flattened_parabola", "radius": R, "flat_radius": 1e-6 * R},
     False),
    ("exact sphere", {"shape": "exact_sphere", "radius": 1e-3}, False),
])
def test_each_profile_becomes_its_adhesive_counterpart(name, tip, closed):
    """The pull-off of each closed-form profile against an independent closed form: the flat
    punch Kendall's -sqrt(8 pi a^3 E* Delta gamma) under either control; the power law
    c r^2 with c = 1/(2R) and a flattened parabola of flat radius 1e-6 R JKR's -3 pi R Delta
    gamma/2 (force control) and -5 pi R Delta gamma/6 (depth control); the exact sphere JKR to
    order (a/R)^2, a_c = (9 pi R^2 Delta gamma/(8 E*))^(1/3) the pull-off radius (measured
    0.4 (a/R)^2 at R = 1 mm, so a paraboloid, off by 0, or another shape fails). The method
    says whether the pull-off is a closed form or bracketed roots, and the model block names
    the adhesive kind, Delta gamma and the inner contact."""
    sp = spec(tip, {"depth": 1e-8}, ["pull_off_force", "force"])
    doc = sp.run()
    po = doc["effects"]["pull_off_force"]["value"]
    contact = build(sp.spec)
    if name == "punch":
        for control in ("force", "depth"):  # rounding of the closed forms: a few ulp
            assert po[f"{control}_control"] == pytest.approx(_kendall(1e-6), rel=1e-14, abs=0)
    elif name == "exact sphere":
        Rs = 1e-3
        a_c = (9 * math.pi * Rs**2 * DG / (8 * E_STAR)) ** (1 / 3)
        dev = po["force_control"] / (-1.5 * math.pi * Rs * DG) - 1
        assert 0.05 * (a_c / Rs) ** 2 < abs(dev) < (a_c / Rs) ** 2
    else:
        ref = jkr()
        with mp.workdps(30):  # the closed forms' and the root search's rounding: 1e-13
            assert_close(po["force_control"], ref["F_fc"], 1e-13, name)
            assert_close(po["depth_control"], ref["F_dc"], 1e-13, name)
    method = doc["effects"]["force"]["method"]
    assert method == ("adhesive MDR, closed form" if closed else
                      "adhesive MDR, closed form; pull-off by bracketed roots")
    assert (contact.shape.closed_pull_off("force", E_STAR, DG) is not None) == closed
    model = doc["model"]
    inner = build(spec(tip, {"depth": 1e-8}, interface={}).spec)  # the non-adhesive contact
    assert model["kind"] == f"adhesive {inner.kind}"
    assert model["description"] == (f"{inner.label}, adhesive (JKR-type MDR, work of adhesion "
                                    "0.05 J/m^2)")
    assert model["work_of_adhesion"] == DG
    assert model["rtol"] == sp.spec.rtol


def test_power_law_n1_is_the_cone_of_its_slope():
    """c r^n with n = 1 is the cone of tan(theta) = c: the same pull-offs and zero-load
    radius, one by the power law's closed forms (kappa_1), the other by the cone's. Exponents
    in (1/2, 3/2] have a pull-off; 1/2 and below are refused, naming the exponent."""
    th = 1.2
    names = ["pull_off_force", "pull_off_depth", "zero_load_contact_radius"]
    cone = effects({"shape": "cone", "angle": th}, {"depth": 1e-8}, names)
    law = effects({"shape": "power_law", "coefficient": math.tan(th), "exponent": 1},
                  {"depth": 1e-8}, names)
    for name in names:  # two closed forms of one quantity: rounding, 1e-13
        v1, v2 = cone[name]["value"], law[name]["value"]
        for key in (v1 if isinstance(v1, dict) else [None]):
            x1, x2 = (v1, v2) if key is None else (v1[key], v2[key])
            assert x2 == pytest.approx(x1, rel=1e-13, abs=0), (name, key)
    for n in (0.5, 0.3):
        with pytest.raises(SceneError) as exc:
            spec({"shape": "power_law", "coefficient": 1e3, "exponent": n}, {"depth": 1e-8}).run()
        assert str(exc.value) == (
            f"<scene>: interface.work_of_adhesion: a power law with exponent {n:g} <= 1/2 has "
            "no pull-off: the adhesive force falls without bound as the contact grows")


def test_cycle_without_adhesion_on_a_line_contact_names_the_cycle():
    """A contact with no adhesive form under a ``cycle`` load and Delta gamma = 0: the refusal
    names the key that asked for adhesion, load.cycle (not the interface's)."""
    steel = {"E": 210e9, "nu": 0.3}
    with pytest.raises(SceneError, match=r"^<scene>: load\.cycle: adhesion is derived"):
        scene.load({"effects": ["force"],
                    "body": [{"shape": "cylinder", "radius": 0.01, "length": 0.01, **steel},
                             {"shape": "flat", **steel}],
                    "load": {"cycle": {"to": 1e-6, "control": "depth"}}}).run()


def test_tabor_parameter_only_with_a_range_and_a_radius():
    """mu_T = (R Delta gamma^2/(E*^2 z0^3))^(1/3) (Tabor 1977) in the model block and the
    ratios when the interface gives a range z0 and the tip a radius of curvature; without a
    range, or for a cone (no radius), neither the range nor mu_T is reported; with
    Delta gamma = 0 (a cycle) mu_T is not a ratio (it would be 0, far below JKR's 5)."""
    z0 = 0.3e-9
    sp = spec(SPHERE, {"depth": 1e-8}, interface={"work_of_adhesion": DG, "range": z0})
    model = sp.run()["model"]
    with mp.workdps(30):
        ref = mp.cbrt(mp.mpf(R) * mp.mpf(DG) ** 2 / (mp.mpf(E_STAR) ** 2 * mp.mpf(z0) ** 3))
        assert_close(model["tabor_parameter"], ref, 1e-14, "Tabor parameter")
    assert model["range"] == z0
    contact, st = kind_and_state(sp)
    assert contact.ratios({"state": st})["mu_T"] == model["tabor_parameter"]
    for tip, interface in ((SPHERE, {"work_of_adhesion": DG}),
                           ({"shape": "cone", "angle": 1.2}, {"work_of_adhesion": DG,
                                                              "range": z0})):
        sp = spec(tip, {"depth": 1e-8}, interface=interface)
        model = sp.run()["model"]
        assert "range" not in model and "tabor_parameter" not in model
        contact, st = kind_and_state(sp)
        assert "mu_T" not in contact.ratios({"state": st})
    sp = spec(SPHERE, {"cycle": {"to": 1e-8, "control": "depth", "points": 50}},
              interface={"work_of_adhesion": 0, "range": z0})
    contact, st = kind_and_state(sp)
    assert isinstance(contact, kadh.AdhesiveKind)
    assert "mu_T" not in contact.ratios({"state": st})


def test_ratios_at_the_largest_load():
    """The ratios on the adhesive state: a/R and d/R of the sphere (R the paraboloid's) and of
    the exact sphere (R its radius), from the contact_radius effect and the load; tan(theta)
    of a cone; d/a of a power law (no one radius); nothing without a state."""
    d = 1e-8
    for tip, Rt in ((SPHERE, R), ({"shape": "exact_sphere", "radius": 1e-6}, 1e-6)):
        sp = spec(tip, {"depth": d}, ["contact_radius"])
        a = sp.run()["effects"]["contact_radius"]["value"]
        contact, st = kind_and_state(sp)
        # the state's depth is d(a) of its contact radius: d within the state's error
        assert st.depth[0] == pytest.approx(d, rel=CLOSED_FORM_RTOL, abs=0)
        assert contact.ratios({"state": st}) == {"a/R": a / Rt, "d/R": st.depth[0] / Rt}
        assert contact.ratios({}) == {}
    contact, st = kind_and_state(spec({"shape": "cone", "angle": 1.2}, {"depth": d}))
    assert contact.ratios({"state": st}) == {"tan(theta)": math.tan(1.2)}
    sp = spec({"shape": "power_law", "coefficient": 1e3, "exponent": 1.2}, {"depth": d},
              ["contact_radius"])
    a = sp.run()["effects"]["contact_radius"]["value"]
    contact, st = kind_and_state(sp)
    assert contact.ratios({"state": st}) == {"d/a": st.depth[0] / a}


# -- the effects no test of the run called ---------------------------------------------------

def test_jkr_mean_pressure_stiffness_and_curve():
    """JKR at d = 10 nm: the mean pressure F/(pi a^2) from the force and contact_radius
    effects; the stiffness (dF/da)/(dd/da) of JKR's parametric F(a), d(a) by mpmath's
    derivatives at 30 digits; the force-depth curve on 201 depths from 0 to d, each point on
    JKR's curve (a from F by JKR's stable root, then d(a)); force and depth the state's, with
    its error (CLOSED_FORM_RTOL) and the kind's method."""
    d = 1e-8
    eff = effects(SPHERE, {"depth": d}, ["force", "depth", "contact_radius", "mean_pressure",
                                         "stiffness", "force_depth_curve"])
    F, a = eff["force"]["value"], eff["contact_radius"]["value"]
    # d(a) of the state's contact radius: d within the state's error
    assert eff["depth"]["value"] == pytest.approx(d, rel=CLOSED_FORM_RTOL, abs=0)
    method = "adhesive MDR, closed form"
    for name in ("force", "depth", "contact_radius", "mean_pressure", "stiffness",
                 "force_depth_curve"):
        assert eff[name]["rel_error"] == CLOSED_FORM_RTOL, name
    for name in ("force", "depth", "force_depth_curve"):
        assert eff[name]["method"] == method, name
    assert eff["mean_pressure"]["value"] == pytest.approx(F / (math.pi * a**2), rel=1e-15,
                                                          abs=0)
    assert eff["mean_pressure"]["method"] == "F/(pi a^2) (5.17)"
    assert eff["contact_radius"]["method"].startswith("d = g(a) - Delta l(a) (5.55)")
    ref = jkr()
    with mp.workdps(30):
        am = mp.mpf(a)
        assert_close(F, ref["F"](am), 1e-13, "JKR F(a)")
        k = mp.diff(ref["F"], am) / mp.diff(ref["d"], am)
        # a carries the state's 1e-14; k(a) is smooth: 1e-12
        assert_close(eff["stiffness"]["value"], k, 1e-12, "JKR stiffness")
        assert "2 a E*" not in eff["stiffness"]["method"]
        curve = eff["force_depth_curve"]["value"]
        dd, ff = curve["depth"], curve["force"]
        assert len(dd) == base.FIELD_POINTS and dd[0] == 0.0
        assert dd[-1] == eff["depth"]["value"]
        assert ff[-1] == pytest.approx(F, rel=1e-15, abs=0)
        for di, fi in zip(dd[::20], ff[::20], strict=True):
            # d(a(F)) against d: the cube root's conditioning, 1e-13 of the largest depth
            assert abs(ref["d"](ref["a_of_F"](mp.mpf(fi))) - di) <= 1e-13 * d, (di, fi)


def test_punch_stiffness_and_mdr_profile():
    """Kendall's punch: the stiffness 2 a E* (the contact radius fixed), its g = 0 to just
    inside a (the non-adhesive punch's grid)."""
    a = 1e-6
    eff = effects({"shape": "flat_punch", "radius": a}, {"depth": 1e-8},
                  ["stiffness", "mdr_profile"])
    assert eff["stiffness"]["value"] == pytest.approx(2 * a * E_STAR, rel=1e-15, abs=0)
    assert eff["stiffness"]["method"] == "2 a E* (5.12)"
    g = eff["mdr_profile"]["value"]
    assert len(g["x"]) == base.FIELD_POINTS and g["x"][-1] == a * (1 - 1e-9)
    assert not any(g["g"])


@pytest.mark.parametrize("tip, Rt, d", [
    (SPHERE, R, 1e-8),
    ({"shape": "exact_sphere", "radius": 1e-6}, 1e-6, 1e-8),    # 1.2 a < R: ends at 1.2 a
    ({"shape": "exact_sphere", "radius": 1e-6}, 1e-6, 1.5e-6),  # a > R/1.2: just inside R
])
def test_mdr_profile_grid_and_values(tip, Rt, d):
    """g(x) of (5.52) on 201 points from 0 to 1.2 a (a the contact_radius effect), or to
    R (1 - 1e-9) where 1.2 a would pass the exact sphere's edge: the paraboloid's g = x^2/R,
    the spherical cap's g = (x/2) ln((R + x)/(R - x)) (mpmath, 30 digits)."""
    eff = effects(tip, {"depth": d}, ["contact_radius", "mdr_profile"])
    a = eff["contact_radius"]["value"]
    v = eff["mdr_profile"]
    x, g = np.array(v["value"]["x"]), np.array(v["value"]["g"])
    top = 1.2 * a if tip is SPHERE else min(1.2 * a, Rt * (1 - 1e-9))
    if tip is not SPHERE:  # the third case is the one that reaches R
        assert (1.2 * a > Rt) == (d == 1.5e-6)
    assert len(x) == base.FIELD_POINTS and x[0] == 0.0
    assert x[-1] == pytest.approx(top, rel=1e-15, abs=0)
    assert v["rel_error"] == CLOSED_FORM_RTOL and v["method"] == "(5.52)"
    with mp.workdps(30):
        Rm = mp.mpf(Rt)
        for xi, gi in zip(x[1::10], g[1::10], strict=True):
            xm = mp.mpf(xi)
            ref = xm**2 / Rm if tip is SPHERE else xm / 2 * mp.log((Rm + xm) / (Rm - xm))
            # the cap's log near x = R: R - x is exact (Sterbenz), ln's rounding 1e-13
            assert_close(gi, ref, 1e-13, f"g({xi / a:.3g} a)")


def test_effective_radius_of_the_tip():
    """The radius of curvature of the tip: R of a sphere, 1/(2 c) of the power law c r^2; a
    cone has none (not offered, and the effect says so by name)."""
    eff = effects(SPHERE, {"depth": 1e-8}, ["effective_radius"])["effective_radius"]
    assert (eff["value"], eff["rel_error"]) == (R, CLOSED_FORM_RTOL)
    assert eff["method"] == "the radius of curvature of the tip"
    eff = effects({"shape": "power_law", "coefficient": 1e6, "exponent": 2}, {"depth": 1e-8},
                  ["effective_radius"])["effective_radius"]
    assert eff["value"] == pytest.approx(0.5e-6, rel=1e-15, abs=0)
    contact, _ = kind_and_state(spec({"shape": "cone", "angle": 1.2}, {"depth": 1e-8}))
    assert contact.has("effective_radius") is False
    with pytest.raises(ValueError, match="adhesive .* has no radius of curvature"):
        contact.effect_effective_radius()


# -- the field grids -------------------------------------------------------------------------

def test_pressure_and_displacement_grids():
    """The adhesive pressure on 201 points from 0 (from 1e-3 a for a cone, whose p is
    log-infinite on the axis) to 1.5 a; the surface displacement from 0 to 4 a; both with the
    state's error."""
    for tip, start in ((SPHERE, 0.0), ({"shape": "cone", "angle": 1.2}, 1e-3)):
        eff = effects(tip, {"depth": 1e-8}, ["contact_radius", "pressure_profile",
                                              "surface_displacement"])
        a = eff["contact_radius"]["value"]
        r = np.array(eff["pressure_profile"]["value"]["r"])
        assert len(r) == base.FIELD_POINTS
        assert r[0] == start * a and r[-1] == pytest.approx(1.5 * a, rel=1e-15, abs=0)
        assert np.all(np.isfinite(eff["pressure_profile"]["value"]["p"]))
        u = eff["surface_displacement"]
        ru = np.array(u["value"]["r"])
        assert len(ru) == base.FIELD_POINTS and ru[0] == 0.0
        assert ru[-1] == pytest.approx(4 * a, rel=1e-15, abs=0)
        assert u["rel_error"] == CLOSED_FORM_RTOL


def test_pressure_grid_leaves_out_the_edge(monkeypatch):
    """On a 4-point grid (0, a/2, a, 3a/2) the point at the edge, where the adhesive pressure
    is -inf, is left out: three points, all finite."""
    monkeypatch.setattr(base, "FIELD_POINTS", 4)
    eff = effects(SPHERE, {"depth": 1e-8}, ["contact_radius", "pressure_profile"])
    a = eff["contact_radius"]["value"]
    r = np.array(eff["pressure_profile"]["value"]["r"])
    assert r == pytest.approx([0.0, 0.5 * a, 1.5 * a], rel=1e-15, abs=0)
    assert np.all(np.isfinite(eff["pressure_profile"]["value"]["p"]))


# -- a sampled profile: the numerical MDR's errors (coarse vs fine samples) ------------------

def _sampled():
    r = np.linspace(0.0, 200e-9, 41)
    return {"shape": "profile", "r": r.tolist(), "f": (r**2 / (2 * R)).tolist()}


def test_sampled_profile_errors_are_coarse_vs_fine():
    """A sampled paraboloid (41 samples): every reported error is the coarse-vs-fine
    difference its docstring defines, recomputed here on the shape's coarse companion -- the
    state's (a, d, F) plus the closed-form floor, the fields' (largest difference over the
    largest |value|, plus twice the state's), the zero-load radius's -- and it bounds the
    actual error against JKR. The pressure leaves out the points within 1e-3 a of the edge."""
    d = 1e-8
    names = ["force", "contact_radius", "zero_load_contact_radius", "pressure_profile",
             "surface_displacement"]
    sp = spec(_sampled(), {"depth": d}, names)
    eff = sp.run()["effects"]
    contact, st = kind_and_state(sp)
    other = ad.AdhesiveContact(contact.shape.companion(), E_STAR, DG)
    # the state: a, d, F of the fine and the coarse samples at the same depth
    a = eff["contact_radius"]["value"]
    F = eff["force"]["value"]
    a2 = float(other.contact_radius(depth=d))
    d2, F2 = float(other.depth(a2)), float(other.force(a2))
    diff = max(abs(a2 - a) / a, abs(d2 - d) / d, abs(F2 - F) / abs(F))
    assert st.rel_error == eff["force"]["rel_error"] == pytest.approx(
        diff + CLOSED_FORM_RTOL, rel=1e-12, abs=0)
    assert eff["force"]["rel_error"] - diff == pytest.approx(CLOSED_FORM_RTOL, rel=1e-3, abs=0)
    ref = jkr()
    with mp.workdps(30):
        assert float(abs(a / ref["a_of_F"](mp.mpf(F)) - 1)) <= st.rel_error
        a0 = eff["zero_load_contact_radius"]
        diff0 = abs(other.zero_load_contact_radius() / a0["value"] - 1)
        assert a0["rel_error"] == pytest.approx(diff0 + CLOSED_FORM_RTOL, rel=1e-12, abs=0)
        assert float(abs(a0["value"] / ref["a0"] - 1)) <= a0["rel_error"]
    assert a0["method"] == "F(a) = 0 on the stable branch"
    # the fields
    p = eff["pressure_profile"]["value"]
    r, pv = np.array(p["r"]), np.array(p["p"])
    grid = np.linspace(0.0, 1.5 * a, base.FIELD_POINTS)
    assert r == pytest.approx(grid[np.abs(grid - a) > 1e-3 * a], rel=1e-15, abs=0)
    u = eff["surface_displacement"]["value"]
    ru, uv = np.array(u["r"]), np.array(u["u"])
    assert ru[-1] == pytest.approx(4 * a, rel=1e-15, abs=0) and len(ru) == base.FIELD_POINTS
    for name, rr, vv, field in (("pressure_profile", r, pv, "pressure_at_depth"),
                                ("surface_displacement", ru, uv,
                                 "surface_displacement_at_depth")):
        with np.errstate(invalid="ignore"):
            v2 = np.asarray(getattr(other, field)(rr, d), float)
        fin = np.isfinite(v2)
        twin = np.max(np.abs(v2 - vv)[fin]) / np.max(np.abs(vv))
        assert twin > st.rel_error  # the field's own difference is the larger
        assert eff[name]["rel_error"] == pytest.approx(twin + 2 * st.rel_error, rel=1e-12,
                                                       abs=0), name
        assert "(error: coarse vs fine samples)" in eff[name]["method"]


def test_sampled_profile_refusals_and_rtol():
    """A sampled profile's adhesive stresses are refused (the superposition would take
    minutes), and an rtol below what the numerical MDR can deliver names it."""
    soft = {**PDMS, "nu": 0.45}  # not 0.5, whose refusal of the maxima comes first
    contact, _ = kind_and_state(spec(_sampled(), {"depth": 1e-8}, flat=soft))
    for effect in kadh.SAMPLED_NOT:
        assert contact.has(effect) is False
        assert contact.why_not[effect] == kadh.SAMPLED_NOT[effect]
    assert contact.has("pressure_profile")
    with pytest.raises(SceneError, match=r"accuracy\.rtol: 1e-15 is outside the range the "
                                         r"numerical MDR can deliver"):
        spec(_sampled(), {"depth": 1e-8}, accuracy={"rtol": 1e-15}).run()


# -- stresses and the effects an adhesive contact does not have --------------------------------

def test_stress_maxima_refused_for_an_incompressible_sample():
    """Under Delta gamma > 0 the pressure is unbounded at the edge: the stress solver says so
    (the edge radius a); with nu = 0.5 the maxima are refused with the reason, the fields
    offered. With Delta gamma = 0 (a cycle) the pressure is bounded: no such mark, and the
    maxima are offered. The impact effects never apply."""
    sp = spec(SPHERE, {"depth": 1e-8}, ["contact_radius"])
    a = sp.run()["effects"]["contact_radius"]["value"]
    contact, st = kind_and_state(sp)
    assert contact.stress_solver(st).unbounded == (kadh.UNBOUNDED, a)
    for effect in ("max_shear", "max_von_mises"):
        assert contact.has(effect) is False
        why = contact.why_not[effect]
        assert why.startswith(kadh.UNBOUNDED + "; with nu = 0.5 the stress there is hydrostatic")
        assert why.endswith("(ask for 'axis_stresses' or 'von_mises_field')")
    assert contact.has("axis_stresses") and contact.has("von_mises_field")
    assert contact.has("effective_radius")
    for effect in ("contact_time", "max_impact_depth", "max_impact_pressure"):
        assert contact.has(effect) is False
    sp = spec(SPHERE, {"cycle": {"to": 1e-8, "control": "depth", "points": 50}},
              interface={"work_of_adhesion": 0})
    contact, st = kind_and_state(sp)
    assert contact.stress_solver(st).unbounded is None
    assert contact.has("max_shear") and contact.has("max_von_mises")


def test_pull_offs_force_control_first():
    """Both pull-offs, force control first (the JSON's order), each JKR's."""
    eff = effects(SPHERE, {"depth": 1e-8}, ["pull_off_force", "pull_off_depth"])
    po = eff["pull_off_force"]["value"]
    assert list(po) == ["force_control", "depth_control"]
    assert list(eff["pull_off_depth"]["value"]) == ["force_control", "depth_control"]
    ref = jkr()
    with mp.workdps(30):
        assert_close(po["force_control"], ref["F_fc"], 1e-13, "JKR pull-off, force control")
        a0 = effects(SPHERE, {"depth": 1e-8}, ["zero_load_contact_radius"])[
            "zero_load_contact_radius"]
        assert_close(a0["value"], ref["a0"], 1e-13, "JKR zero-load radius")
        assert a0["rel_error"] == CLOSED_FORM_RTOL


# -- the approach-push-retract curve ----------------------------------------------------------

def test_cycle_of_a_depth_load():
    """A depth load's cycle: 1000 points to the load's depth; the jumps into contact (F from 0
    to JKR's -4 pi R Delta gamma/3 at d = 0) and out at the depth-control pull-off (the
    pull_off_force effect's, at its radius); its error the hysteresis's relative error or the
    state's, whichever is larger."""
    d = 1e-8
    sp = spec(SPHERE, {"depth": d}, ["adhesive_force_depth_curve", "pull_off_force"])
    eff = sp.run()["effects"]
    cur = eff["adhesive_force_depth_curve"]
    v = cur["value"]
    assert len(v["depth"]) == len(v["contact_radius"]) == len(v["loading"]) == 1000
    assert max(v["depth"]) == pytest.approx(d, rel=CLOSED_FORM_RTOL, abs=0)
    assert v["loading"][0] is True and v["loading"][-1] is False
    contact, st = kind_and_state(sp)
    po = contact.model.pull_off("depth")
    # the jump's state from the cycle's root search, the effect's from the closed form
    assert v["jump_force"][-1][0] == pytest.approx(
        eff["pull_off_force"]["value"]["depth_control"], rel=CLOSED_FORM_RTOL, abs=0)
    assert v["jump_contact_radius"][-1] == [po.contact_radius, 0.0]
    with mp.workdps(30):  # into contact: JKR's F at d = 0, a = (2 pi R^2 dg/E*)^(1/3)
        assert_close(v["jump_force"][0][1], -4 * mp.pi * R * DG / 3, 1e-13, "F at d = 0")
    cyc = contact.model.cycle(d, "depth", 1000)
    assert cur["rel_error"] == max(cyc.hysteresis_error / cyc.hysteresis, st.rel_error)
    assert cur["method"].startswith("depth-controlled cycle on the adhesive MDR curve")


def test_cycle_errors():
    """The curve's error is the hysteresis's relative error where that exceeds the state's:
    a sampled paraboloid of 21 samples, whose coarse-vs-fine difference of the hysteresis
    (2e-10) is a hundred times that of its state. Delta gamma = 0 under a cycle of 60
    points: a flat punch's loading and unloading are one line, the hysteresis exactly 0 and
    the curve's error the state's."""
    r = np.linspace(0.0, 200e-9, 21)
    tip = {"shape": "profile", "r": r.tolist(), "f": (r**2 / (2 * R)).tolist()}
    sp = spec(tip, {"depth": 1e-8}, ["adhesive_force_depth_curve"])
    cur = sp.run()["effects"]["adhesive_force_depth_curve"]
    contact, st = kind_and_state(sp)
    cyc = contact.model.cycle(1e-8, "depth", 1000)
    rel = cyc.hysteresis_error / cyc.hysteresis
    assert rel > 10 * st.rel_error
    # the same cycle recomputed on a new contact: its coarse-vs-fine hysteresis differs from
    # the run's in the 6th digit (measured 1e-6), a difference of two small differences
    assert cur["rel_error"] == pytest.approx(rel, rel=1e-4, abs=0)
    sp = spec({"shape": "flat_punch", "radius": 1e-6},
              {"cycle": {"to": 1e-8, "control": "depth", "points": 60}},
              ["adhesive_force_depth_curve"], interface={"work_of_adhesion": 0})
    cur = sp.run()["effects"]["adhesive_force_depth_curve"]
    assert len(cur["value"]["depth"]) == 60
    contact, st = kind_and_state(sp)
    assert cur["value"]["hysteresis"] == 0.0
    assert cur["rel_error"] == st.rel_error


@pytest.mark.parametrize("load", [{"depth": 1e-8}, {"force": 1e-9}, {"force": 1e-7}])
def test_sampled_state_error_each_of_a_d_f(load):
    """The state's error of a sampled paraboloid (41 samples) is the largest relative
    difference of a, d and F between the fine and the coarse samples (plus the closed-form
    floor), recomputed here: each of the three is the largest at one of these loads
    (measured: F under depth control, d at a small force, a at a large one)."""
    sp = spec(_sampled(), load)
    contact, st = kind_and_state(sp)
    other = ad.AdhesiveContact(contact.shape.companion(), E_STAR, DG)
    (control, v), = load.items()
    a, d, F = (float(x[0]) for x in contact.model.equilibrium(**{control: np.array([v])}))
    a2 = float(other.contact_radius(**{control: v}))
    d2, F2 = float(other.depth(a2)), float(other.force(a2))
    diffs = [abs(a2 - a) / a, abs(d2 - d) / abs(d), abs(F2 - F) / abs(F)]
    assert st.rel_error == pytest.approx(max(diffs) + CLOSED_FORM_RTOL, rel=1e-12, abs=0)
    assert max(diffs) > 10 * CLOSED_FORM_RTOL


def test_sampled_pressure_leaves_out_the_points_next_to_the_edge(monkeypatch):
    """On 1001 points (0 to 1.5 a in steps of 1.5e-3 a) one point lies 5e-4 a inside the
    edge, where the fine representation's -inf tension is finite in the coarse one (its own
    contact radius): it is left out, and only it."""
    monkeypatch.setattr(base, "FIELD_POINTS", 1001)
    eff = effects(_sampled(), {"depth": 1e-8}, ["contact_radius", "pressure_profile"])
    a = eff["contact_radius"]["value"]
    r = np.array(eff["pressure_profile"]["value"]["r"])
    grid = np.linspace(0.0, 1.5 * a, 1001)
    near = np.abs(grid - a) <= 1e-3 * a
    assert near.sum() == 1
    assert r == pytest.approx(grid[~near], rel=1e-15, abs=0)


# -- kinds/pressure.py and kinds/line.py -------------------------------------------------------

def test_prescribed_pressure_model_ratio_and_displacement_grid():
    """A uniform pressure p0 on a disc of radius a (Problem 6): the model block names the
    distribution, p0 and a; the surface displacement on 201 points from 0 to 4 a, at the
    centre 2 p0 a/E* and at r = a (4/pi) p0 a/E* (Johnson (3.29)-(3.30), at 30 digits);
    the ratio d/a is the centre's displacement over a."""
    p0, a, E, nu = 10e6, 2e-3, 70e9, 0.33
    sp = scene.load({"effects": ["depth", "edge_displacement", "surface_displacement"],
                     "body": [{"shape": "flat", "E": E, "nu": nu},
                              {"shape": "flat", "rigid": True}],
                     "load": {"pressure": {"distribution": "uniform", "p0": p0, "radius": a}}})
    doc = sp.run()
    model = doc["model"]
    assert (model["distribution"], model["p0"], model["radius"]) == ("uniform", p0, a)
    u = doc["effects"]["surface_displacement"]["value"]
    r, uu = np.array(u["r"]), np.array(u["u"])
    assert len(r) == base.FIELD_POINTS and r[0] == 0.0
    assert r[-1] == pytest.approx(4 * a, rel=1e-15, abs=0)
    with mp.workdps(30):
        Es = mp.mpf(E) / (1 - mp.mpf(nu) ** 2)
        centre, edge = 2 * mp.mpf(p0) * mp.mpf(a) / Es, 4 * mp.mpf(p0) * mp.mpf(a) / (mp.pi * Es)
        # closed forms (elliptic integrals at the edge): rounding, 1e-14
        assert_close(uu[0], centre, 1e-14, "u(0)")
        assert_close(doc["effects"]["edge_displacement"]["value"], edge, 1e-14, "u(a)")
    contact = build(sp.spec)
    st = contact.state(sp.spec.load)
    assert contact.ratios({"state": st}) == {"d/a": doc["effects"]["depth"]["value"] / a}
    assert contact.ratios({}) == {}


def test_line_contact_ratios_rtol_ranges_and_law():
    """The roller on its ring (line_contact_roller.toml): a/R, d/R and a/L at the load from
    the half_width, effective_radius and depth effects and the shorter length L = 10 mm; the
    rtol its stress effects can deliver is the line contact's own table (LineStresses.ranges,
    which differs from Hertz's for the axis stresses and the orthogonal shear); the force law's
    method cites (5.34)."""
    from hertzmdr.numeric.scene.kinds import stresses

    path = Path(__file__).parents[1] / "examples" / "line_contact_roller.toml"
    data = tomllib.loads(path.read_text())
    data["effects"] = ["half_width", "effective_radius", "depth", "force_law"]
    sp = scene.load(data)
    eff = sp.run()["effects"]
    a, Re, d = (eff[k]["value"] for k in ("half_width", "effective_radius", "depth"))
    contact = build(sp.spec)
    st = contact.state(sp.spec.load)
    # a from the depth (5.35) there, from the force here: the closed forms' rounding, 1e-14
    assert contact.ratios({"state": st}) == pytest.approx(
        {"a/R": a / Re, "d/R": d / Re, "a/L": a / 0.01}, rel=CLOSED_FORM_RTOL, abs=0)
    assert contact.ratios({}) == {}
    line, hertz = stresses.LineStresses.ranges, stresses.HertzStresses.ranges
    names = ["axis_stresses", "max_orthogonal_shear"]
    assert [line[n] != hertz[n] for n in names] == [True, True]
    assert contact.rtol_ranges(names + ["force"]) == [
        (contact.state_method, contact.state_range),
        *((f"{n} (closed form)", (line[n], 1.0)) for n in names)]
    assert "from (5.34): K and stiffness_K" in eff["force_law"]["method"]


def test_model_block_reports_the_scenes_rtol():
    """The adhesive contact's model block states the rtol the scene asked for (base.Contact's
    info; the adhesive kind passes it on to its base)."""
    doc = spec(SPHERE, {"depth": 1e-8}, accuracy={"rtol": 1e-6}).run()
    assert doc["model"]["rtol"] == 1e-6 and doc["model"]["work_of_adhesion"] == DG


def test_depth_controlled_line_contact_names_its_depth():
    """A line contact under a prescribed depth: the force by (5.34) at the depth of (5.35)
    (a = sqrt(R d), not the approach of the axes), and the method says which depth it is."""
    steel = {"E": 210e9, "nu": 0.3}
    doc = scene.load({"effects": ["force"], "body": [
        {"shape": "cylinder", "radius": 0.01, "length": 0.02, **steel},
        {"shape": "flat", **steel}], "load": {"depth": 1e-6}}).run()
    assert doc["effects"]["force"]["method"] == "(5.34) with d defined by (5.35)"
