"""Checks of numeric/scene/shapes/ that its mutation run (docs/mutation_scene.md) found missing:
each refusal of a bad key value ends in exit 2 and one line naming the key, the value and what is
valid; each geometry a shape hands to its contact kind (a radius, a slope, a force-law inverse,
the dispatch key of the adhesive and tangential forms) is checked against a closed form at 30
digits, or against numeric/'s own public API where the point is the scene layer's plumbing."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from hertzmdr.numeric import adhesion as ad
from hertzmdr.numeric import scene
from hertzmdr.numeric.cli import main

E, NU = 1e9, 0.3
E_STAR = E / (1 - NU**2)  # a rigid tip on an elastic flat: E* = E / (1 - nu^2)
FLAT = {"shape": "flat", "E": E, "nu": NU}

SCENE = """\
effects = ["force"]

[[body]]
name = "tip"
{body}
rigid = true

[[body]]
name = "plate"
shape = "flat"
E = "1 GPa"
nu = 0.3

[load]
depth = "1 nm"
"""

PROFILE = 'shape = "profile"\n'
# each refusal: (what, the tip's keys, the words of the one line; the first names the key)
REFUSALS = [
    ("ellipsoid radius 0", 'shape = "ellipsoid"\nradii = [0, 0.01]',
     ["body[0] (tip).radii: radii must not be 0"]),
    ("cone angle 0", 'shape = "cone"\nangle = 0',
     ["body[0] (tip).angle:", "(0, 90 deg), got 0 deg"]),
    ("cone angle 90 deg", 'shape = "cone"\nangle = "90 deg"',
     ["body[0] (tip).angle:", "(0, 90 deg), got 90 deg"]),
    ("profile file and r", PROFILE + 'file = "tip.csv"\nr = [0, 1e-6]',
     ["body[0] (tip): give samples r and f, or file, not both"]),
    ("profile file and f", PROFILE + 'file = "tip.csv"\nf = [0, 1e-9]',
     ["body[0] (tip): give samples r and f, or file, not both"]),
    ("profile r alone", PROFILE + "r = [0, 1e-6]",
     ["body[0] (tip): a profile needs samples r = [...] and f = [...], or file"]),
    ("profile f alone", PROFILE + "f = [0, 1e-9]",
     ["body[0] (tip): a profile needs samples r = [...] and f = [...], or file"]),
    ("profile unequal lengths", PROFILE + "r = [0, 1e-6, 2e-6]\nf = [0, 1e-9]",
     ["body[0] (tip): r has 3 samples and f has 2"]),
    ("profile file with nan", PROFILE + 'file = "nan.csv"',
     ["body[0] (tip).r/f[1]: samples must be finite numbers, not NaN or inf"]),
    ("profile repeated r", PROFILE + "r = [0, 1e-6, 1e-6]\nf = [0, 1e-9, 2e-9]",
     ["body[0] (tip).r: samples must start at r = 0 and increase strictly"]),
    # the first drop, at index 1, with the values on both sides of it
    ("profile drops at 1", PROFILE + "r = [0, 1e-6, 2e-6]\nf = [1e-9, 0, 2e-9]",
     ["body[0] (tip).f[1]: the profile decreases there (f = 0.0 m after 1e-09 m, at r = "
      "1e-06 m)", "f non-decreasing in r"]),
    # a -0.0 before the drop is printed as 0.0 (the line's + 0.0)
    ("profile drops after -0", PROFILE + "r = [0, 1e-6, 2e-6]\nf = [0.0, -0.0, -1e-9]",
     ["body[0] (tip).f[2]: the profile decreases there (f = -1e-09 m after 0.0 m, at r = "
      "2e-06 m)"]),
    ("breakpoint off the samples", PROFILE + "r = [0, 1e-6, 2e-6, 3e-6, 4e-6]\n"
     "f = [0, 1e-9, 2e-9, 3e-9, 4e-9]\nbreakpoints = [1.5e-6]",
     ["body[0] (tip).breakpoints[0]: 1.5e-06 m is not one of the samples inside the profile"]),
]


@pytest.mark.parametrize("what, body, words", REFUSALS, ids=[c[0] for c in REFUSALS])
def test_bad_shape_value_is_one_line(tmp_path, capsys, what, body, words):
    (tmp_path / "nan.csv").write_text("r, f\n0, 0\n1e-6, nan\n2e-6, 2e-9\n")
    path = tmp_path / "scene.toml"
    path.write_text(SCENE.format(body=body))
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    for w in words:
        assert w in err, f"{what}: {w!r} not in {err!r}"


def run(tip, load, effects, **extra):
    return scene.load({"effects": list(effects), "body": [{**tip, "rigid": True}, FLAT],
                       "load": load, **extra}).run()


@pytest.mark.parametrize("tip", [
    {"shape": "ellipsoid", "radii": [1.0, 2.0]},       # a radius of 1 m is not 0
    {"shape": "profile", "r": [0, 1e-6, 2e-6, 3e-6], "f": [0, 0, 1e-9, 4e-9]},  # a flat apex
])
def test_valid_shape_values_are_accepted(tip):
    scene.load({"effects": ["force"], "body": [{**tip, "rigid": True}, FLAT],
                "load": {"depth": 1e-10}})


def kappa(n):
    """kappa_n of Problem 7(d): g(x) = kappa_n c |x|^n for f = c r^n (MDR)."""
    return mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)


def test_power_law_under_force():
    """A power law under a force load: the depth inverts F = 2 E* n/(n+1) kappa_n c a^(n+1),
    d = kappa_n c a^n (Problem 7 d), here solved for a in closed form at 30 digits; the model
    reports kappa_n. The scene's figures are closed forms: 1e-13 (a few ulps through the
    generated functions)."""
    c, n, F = 1e3, 1.5, 1e-3
    doc = run({"shape": "power_law", "coefficient": c, "exponent": n}, {"force": F}, ["depth"])
    with mp.workdps(30):
        nm, cm, k = mp.mpf(n), mp.mpf(c), kappa(mp.mpf(n))
        a = (mp.mpf(F) * (nm + 1) / (2 * mp.mpf(E_STAR) * nm * k * cm)) ** (1 / (nm + 1))
        d = k * cm * a**nm
        assert doc["effects"]["depth"]["value"] == pytest.approx(float(d), rel=1e-13, abs=0)
        assert doc["model"]["kappa_n"] == pytest.approx(float(k), rel=1e-14, abs=0)
    assert (doc["model"]["coefficient"], doc["model"]["exponent"]) == (c, n)


def test_power_law_max_pressure_is_at_the_centre():
    """For 1 < n <= 2 the MDR pressure p(r) = (E*/pi) int_0^sqrt(a^2-r^2) g'(x)/x ds
    (x = sqrt(r^2 + s^2)) falls with r (g'(x)/x = n kappa c x^(n-2) falls with x), so its
    maximum is p(0) = E* n kappa_n c a^(n-1) / (pi (n-1)); the scene searches it numerically
    (its rel_error, at most 1e-8, plus 1e-13 for the closed form)."""
    c, n, d = 1e3, 1.5, 1e-6
    eff = run({"shape": "power_law", "coefficient": c, "exponent": n}, {"depth": d},
              ["max_pressure"])["effects"]["max_pressure"]
    with mp.workdps(30):
        nm, cm, k = mp.mpf(n), mp.mpf(c), kappa(mp.mpf(n))
        a = (mp.mpf(d) / (k * cm)) ** (1 / nm)
        p0 = mp.mpf(E_STAR) * nm * k * cm * a ** (nm - 1) / (mp.pi * (nm - 1))
    val = eff["value"]
    val = val["value"] if isinstance(val, dict) else val
    assert abs(val / float(p0) - 1) <= max(eff["rel_error"], 1e-13) + 1e-13


@pytest.mark.parametrize("n", [1.0, 0.8])
def test_power_law_singular_at_the_centre(tmp_path, capsys, monkeypatch, n):
    """f = c r^n with n <= 1: the pressure is unbounded at r = 0 (g'(x)/x = n kappa c x^(n-2)
    is not integrable at 0): max_pressure is refused with the reason, and the largest stresses
    are +inf at the tip (x, z) = (0, 0). (A 4-point superposition grid: a finite maximum would
    be searched on it, quickly, where the singular tip is not known.)"""
    from hertzmdr.numeric.scene.kinds import stresses

    monkeypatch.setattr(stresses, "GRID_SUPERPOSED", 4)
    path = tmp_path / "s.toml"
    path.write_text(SCENE.replace('["force"]', '["max_pressure"]').format(
        body=f'shape = "power_law"\ncoefficient = 1.0\nexponent = {n}'))
    assert main(["run", str(path)]) == 2
    assert "singular at the centre" in capsys.readouterr().err
    tip = {"shape": "power_law", "coefficient": 1.0, "exponent": n}
    eff = run(tip, {"depth": 1e-6}, ["max_shear", "max_von_mises"])["effects"]
    assert eff["max_von_mises"]["value"] == {"value": math.inf, "x": 0.0, "z": 0.0}


def test_cylinder_across_an_ellipsoid_is_a_sphere():
    """A cylinder R_c = 20 mm (axis 0: curved across it, along y) on an ellipsoid R1 = 10 mm
    along x, R2 = 20 mm along y: the gap's curvatures are 1/10 + 0 along x and 1/20 + 1/20
    along y, equal, so the contact is Hertz's of R = 10 mm: F = (4/3) E* sqrt(R) d^(3/2),
    to 1e-8 (the elliptical kind's own tolerance at a ratio of curvatures 1)."""
    d = 1e-7
    doc = scene.load({"effects": ["force"], "body": [
        {"shape": "cylinder", "radius": 0.02, "rigid": True},
        {"shape": "ellipsoid", "radii": [0.01, 0.02], "E": E, "nu": NU}],
        "load": {"depth": d}}).run()
    with mp.workdps(30):
        ref = 4 * mp.mpf(E_STAR) * mp.sqrt(mp.mpf("0.01")) * mp.mpf(d) ** 1.5 / 3
    assert doc["effects"]["force"]["value"] == pytest.approx(float(ref), rel=1e-8, abs=0)


def sneddon_a(d, R):
    """Sneddon's spherical cap: d = (a/2) ln((R + a)/(R - a)), solved for a at 30 digits."""
    with mp.workdps(30):
        d, R = mp.mpf(d), mp.mpf(R)
        return mp.findroot(lambda a: a / 2 * mp.log((R + a) / (R - a)) - d, (R / 100, R * 0.99),
                           solver="illinois")


def warning(doc, ratio):
    return {w["ratio"]: w["value"] for w in doc["warnings"]}.get(ratio)


def test_ratios_name_the_shape_geometry():
    """The assumption a deep or steep tip stretches is measured on its own geometry: a cone's
    tan(theta), an exact sphere's a/R (a from Sneddon's cap), a worn parabola's a/R (a from
    d = a sqrt(a^2 - b^2)/R, the MDR of f = (r^2 - b^2)/(2R) beyond the flat r = b)."""
    doc = run({"shape": "cone", "angle": "80 deg"}, {"depth": 1e-6}, ["force"])
    assert warning(doc, "tan(theta)") == pytest.approx(math.tan(math.radians(80)), rel=1e-15)
    R, d = 1e-3, 1e-4  # a/R = 0.3
    doc = run({"shape": "exact_sphere", "radius": R}, {"depth": d}, ["force"])
    assert warning(doc, "a/R") == pytest.approx(float(sneddon_a(d, R) / R), rel=1e-12, abs=0)
    R, b, d = 1e-3, 1e-4, 1e-4
    doc = run({"shape": "flattened_parabola", "radius": R, "flat_radius": b}, {"depth": d},
              ["force"])
    with mp.workdps(30):
        a = mp.findroot(lambda a: a * mp.sqrt(a**2 - mp.mpf(b) ** 2) / R - d, (b, 10 * R),
                        solver="illinois")
    assert warning(doc, "a/R") == pytest.approx(float(a / R), rel=1e-12, abs=0)


@pytest.mark.parametrize("tip, words", [
    ({"shape": "exact_sphere", "radius": 0.01}, "Sneddon's spherical cap has F = K d^(3/2)"),
    ({"shape": "flattened_parabola", "radius": 0.01, "flat_radius": 1e-4},
     "the flat tip carries a punch's F = 2 E* b d"),
])
def test_no_force_law_says_why(tip, words):
    with pytest.raises(scene.SceneError) as exc:
        run(tip, {"depth": 1e-7}, ["force_law"])
    assert words in str(exc.value)


def test_worn_pressure_profile_steps_off_the_kink():
    """The worn parabola's pressure is log-infinite at r = b: with b on the profile's grid
    (r = 0 ... 1.5 a, FIELD_POINTS points) every reported pressure is still finite, and the
    profile starts on the axis, where the pressure is finite."""
    from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS

    R, a = 1e-2, 1e-4
    b = 1.5 * a * 20 / (FIELD_POINTS - 1)  # the 21st grid point
    d = a * math.sqrt(a * a - b * b) / R   # the MDR's d(a) of the worn tip (see above)
    prof = run({"shape": "flattened_parabola", "radius": R, "flat_radius": b}, {"depth": d},
               ["pressure_profile"])["effects"]["pressure_profile"]["value"]
    assert any(abs(r - b) < 1e-3 * a for r in prof["r"])
    assert prof["r"][0] == 0.0
    assert all(math.isfinite(p) for p in prof["p"])


@pytest.mark.parametrize("tip, shape", [
    ({"shape": "cone", "angle": "70 deg"}, lambda: ad.Cone(math.radians(70))),
    ({"shape": "power_law", "coefficient": 1e3, "exponent": 1.5}, lambda: ad.PowerLaw(1e3, 1.5)),
    ({"shape": "flattened_parabola", "radius": 1e-6, "flat_radius": 1e-7},
     lambda: ad.Worn(1e-6, 1e-7)),
])
def test_adhesive_form_of_each_closed_form(tip, shape):
    """The adhesive contact is made of the shape's own profile and parameters: its pull-off
    force is numeric/adhesion.py's for that profile (the scene's plumbing against the
    module's public API), to 1e-12."""
    dg = 0.05
    eff = run(tip, {"force": 1e-9}, ["pull_off_force"],
              interface={"work_of_adhesion": dg})["effects"]["pull_off_force"]["value"]
    ref = ad.AdhesiveContact(shape(), E_STAR, dg).pull_off("force").force
    assert eff["force_control"] == pytest.approx(ref, rel=1e-12, abs=0)


def test_power_law_n2_pull_off_is_jkr():
    """f = r^2/(2R) as a power law is the JKR sphere: F_c = -3 pi R dgamma / 2."""
    R, dg = 1e-6, 0.05
    eff = run({"shape": "power_law", "coefficient": 1 / (2 * R), "exponent": 2}, {"force": 1e-9},
              ["pull_off_force"], interface={"work_of_adhesion": dg})["effects"]
    with mp.workdps(30):
        ref = -3 * mp.pi * mp.mpf(R) * mp.mpf(dg) / 2
    assert eff["pull_off_force"]["value"]["force_control"] == pytest.approx(float(ref),
                                                                           rel=1e-12, abs=0)


def test_defaults_of_punches():
    """A polygonal punch is meshed with 128 pixels along its longer side by default; a flat
    punch's contact radius is its radius at every depth of a sweep."""
    doc = run({"shape": "polygon_punch", "vertices": [[0, 0], [1e-3, 0], [0, 1e-3]]},
              {"depth": 1e-7}, ["force"])
    assert doc["model"]["grid"] == [128, 128]
    eff = run({"shape": "flat_punch", "radius": 1e-3},
              {"depth": {"from": 0, "to": 1e-6, "points": 3}}, ["contact_radius"])["effects"]
    assert eff["contact_radius"]["value"] == [1e-3] * 3


def test_sampled_profile_spline_degree():
    """A profile's spline is quintic from 20 samples (cubic below): 20 samples of f = c r^4,
    which a quintic reproduces, give the force of Problem 7(d) with n = 4 to 1e-12 (the
    quadrature's and the estimate's 3e-13; a cubic's interpolation error is far larger)."""
    c, n, d = 1e15, 4, 1e-9
    r = [i * 1e-5 / 19 for i in range(20)]
    force = run({"shape": "profile", "r": r, "f": [c * x**n for x in r]}, {"depth": d},
                ["force"])["effects"]["force"]["value"]
    with mp.workdps(30):
        k = kappa(mp.mpf(n))
        a = (mp.mpf(d) / (k * c)) ** (mp.mpf(1) / n)
        ref = 2 * mp.mpf(E_STAR) * k * c * a ** (n + 1) * n / (n + 1)
    assert force == pytest.approx(float(ref), rel=1e-12, abs=0)


def test_sampled_profile_kink_as_breakpoint():
    """A worn tip sampled with its kink r = b as a breakpoint (given 1e-13 off the sample, as a
    value in another unit would round): the spline restarts there, each piece a polynomial of
    degree <= 2 it reproduces, and the force meets its estimate (3e-6 here; 5e-2 with the spline
    continued through the kink) against the MDR of f = (r^2 - b^2)/(2R), F = 2 E* (d a -
    int_b^a x sqrt(x^2 - b^2)/R dx), at 30 digits."""
    R, d = 1e-3, 2e-9
    r = [i * 4e-6 / 12 for i in range(13)]
    b = r[3]
    f = [0.0 if x <= b else (x * x - b * b) / (2 * R) for x in r]
    eff = run({"shape": "profile", "r": r, "f": f, "breakpoints": [b * (1 + 1e-13)]},
              {"depth": d}, ["force"])["effects"]["force"]
    with mp.workdps(30):
        bm, Rm, dm = mp.mpf(b), mp.mpf(R), mp.mpf(d)
        a = mp.findroot(lambda a: a * mp.sqrt(a * a - bm * bm) / Rm - dm, (bm, 10 * Rm),
                        solver="illinois")
        ref = 2 * mp.mpf(E_STAR) * (dm * a - mp.quad(lambda x: x * mp.sqrt(x * x - bm * bm) / Rm,
                                                     [bm, a]))
    assert eff["rel_error"] < 1e-4
    assert abs(eff["value"] / float(ref) - 1) <= eff["rel_error"]
