"""A pyramid in scenes and a scene's ``[fit]`` table (issue 17).

The pyramid is solved as the cone of its force law, beta_n times its equal-area cone's force
(beta_n by the BEM: tests/test_fit.py::test_pyramid_force_by_bem checks it against the BEM of the
pyramid itself): checked against the cone's closed form (Sneddon) at the equal-area angle
computed here, at 30 digits, from the area of the pyramid's cross-section (the shoelace formula
over the polygon's corners), not from the derived relations. Every effect a cone
scene gives, the pyramid's scene gives, with the same numbers. The ``[fit]`` table: ``hertzmdr
fit --scene`` without a curve fits and prints what ``hertzmdr fit CURVE --scene`` does; a
depth range is a fixed point of the fit; every bad key is one line naming it, exit 2.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import cone, fit, fit_io, scene
from hertzmdr.numeric.cli import main

EXAMPLES = Path(__file__).parents[1] / "examples"
FIT_SCENE = EXAMPLES / "fit_pyramid_afm.toml"
FIT_CURVE = EXAMPLES / "fit_pyramid_afm_curve.csv"
PYRAMID_SCENE = EXAMPLES / "pyramid_berkovich_silica.toml"
#: the example curve's truth: a rigid 4-sided pyramid, half-angle 35 deg, on E = 20 kPa,
#: nu = 0.5
EXAMPLE_E, EXAMPLE_NU, EXAMPLE_SIDES, EXAMPLE_ALPHA = 20e3, 0.5, 4, math.radians(35)
EXAMPLE_E_STAR = EXAMPLE_E / (1 - EXAMPLE_NU**2)


def cot_equal_area(sides: int, alpha) -> mp.mpf:
    """cot(theta) of the cone with the pyramid's cross-section area, at the working precision:
    the area of the regular polygon of apothem tan(alpha) (depth 1) by the shoelace formula
    over its corners (circumradius apothem/cos(pi/n)), then pi cot^2 = area."""
    rc = mp.tan(alpha) / mp.cos(mp.pi / sides)
    pts = [(rc * mp.cos(2 * mp.pi * k / sides), rc * mp.sin(2 * mp.pi * k / sides))
           for k in range(sides)]
    area = mp.fsum(x0 * y1 - x1 * y0
                   for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1], strict=True))
    return mp.sqrt(area / 2 / mp.pi)


def cot_force_law(sides: int, alpha) -> mp.mpf:
    """cot(theta) of the cone with the pyramid's force: beta_n (the BEM's, fit.PYRAMID_BEM_FACTOR)
    times the equal-area cone's (Sneddon's force (5.40) is proportional to cot(theta))."""
    return mp.mpf(fit.PYRAMID_BEM_FACTOR[sides][0]) * cot_equal_area(sides, alpha)


def _pyramid(**keys) -> dict:
    return {"name": "tip", "shape": "pyramid", "rigid": True, **keys}


def _run(body, effects, load=None, **extra) -> dict:
    return scene.load({"effects": effects, "body": [body, {"name": "sample", "shape": "flat",
                                                           "E": "70 GPa", "nu": 0.25}],
                       "load": load or {"depth": "100 nm"}, **extra}).run()


# -- the pyramid ------------------------------------------------------------------------------
@pytest.mark.parametrize("sides,deg", [(3, 65.27), (4, 68.0), (3, 35.2644), (4, 35.0), (6, 20.0),
                                       (8, 80.0)])
def test_pyramid_force_by_the_area_and_sneddon(sides, deg):
    """F = (2/pi) E* d^2 cot(theta) (Sneddon's cone) and a = 2 d cot(theta)/pi (5.38) at the
    force law's cot(theta): beta_n times the equal-area cone's from the polygon's shoelace area,
    at 30 digits. The scene's
    float64 chain (atan of the derived relation, tan inside the cone's laws) rounds a few
    times: 1e-13 relative bounds it, the closed forms' reported 1e-14 a value at a time."""
    d, E_star = 1e-7, 70e9 / (1 - 0.25**2)
    doc = _run(_pyramid(sides=sides, half_angle=f"{deg} deg"), ["force", "contact_radius"])
    with mp.workdps(30):
        cot = cot_force_law(sides, mp.radians(deg))
        F = 2 / mp.pi * E_star * mp.mpf(d) ** 2 * cot
        a = 2 * mp.mpf(d) * cot / mp.pi
    assert abs(doc["effects"]["force"]["value"] / float(F) - 1) < 1e-13
    assert abs(doc["effects"]["contact_radius"]["value"] / float(a) - 1) < 1e-13
    K = doc["model"]["force_factor"]  # F = K E* d^2, as the model states it
    assert abs(K / float(F / E_star / mp.mpf(d) ** 2) - 1) < 1e-13


@pytest.mark.parametrize("preset,sides,area", [("vickers", 4, 24.504), ("berkovich", 3, 24.494),
                                               ("cube_corner", 3, 2.598)])
def test_presets_have_the_indenters_areas(preset, sides, area):
    """The projected areas per d^2 the nanoindentation literature quotes (Vickers 24.504,
    modified Berkovich 24.494, cube corner 3 sqrt(3)/2 = 2.598; to their 4 digits) from the
    model's angle: pi cot^2(theta)/beta_n^2 (its cone has beta_n times the equal-area cone's
    cot(theta))."""
    doc = _run(_pyramid(preset=preset), ["force"])
    assert doc["model"]["sides"] == sides
    beta = fit.PYRAMID_BEM_FACTOR[sides][0]
    assert doc["model"]["bem_factor"] == beta
    got = math.pi / (math.tan(doc["model"]["angle"]) * beta) ** 2
    assert abs(got / area - 1) < 5e-4, got  # the quoted figures' 4 digits


def test_pyramid_warns_that_it_is_an_approximation():
    doc = _run(_pyramid(sides=4, half_angle="68 deg"), ["force"])
    w = {x["ratio"]: x for x in doc["warnings"]}
    assert w["1/sides"]["value"] == 0.25 and "approximation" in w["1/sides"]["message"]
    assert "cone of its force law" in doc["model"]["description"]
    assert f"F = {doc['model']['force_factor']:.6g} E* d^2" in doc["model"]["description"]


#: effects of a cone scene that cost little (the stresses take 20 s to a minute: the same
#: superposition over the same pressure)
CONE_EFFECTS = ["depth", "force", "contact_radius", "mean_pressure", "stiffness",
                "effective_modulus", "pressure_profile", "surface_displacement",
                "force_depth_curve", "mdr_profile", "force_law"]


@pytest.mark.parametrize("extra,effects", [
    ({}, CONE_EFFECTS),
    ({"interface": {"work_of_adhesion": "0.5 J/m^2"}},
     ["force", "pull_off_force", "pull_off_depth", "zero_load_contact_radius",
      "adhesive_force_depth_curve", "pressure_profile"]),
    ({"interface": {"friction": 0.4}},
     ["tangential_force", "stick_radius", "sliding_force", "tangential_stiffness",
      "traction_profile"]),
], ids=["normal", "adhesive", "tangential"])
def test_every_cone_effect_with_the_same_numbers(extra, effects):
    """The pyramid's scene gives every effect the cone scene at theta_eq gives, and the same
    numbers: its contact is that cone."""
    load = {"depth": "100 nm"}
    if "interface" in extra and "friction" in extra["interface"]:
        load["tangential"] = {"force": "0.1 mN"}
    pyr = _run(_pyramid(preset="berkovich"), effects, load, **extra)
    theta = pyr["model"]["angle"]
    con = _run({"name": "tip", "shape": "cone", "angle": theta, "rigid": True}, effects, load,
               **extra)
    for name in effects:
        assert pyr["effects"][name]["value"] == con["effects"][name]["value"], name
        assert pyr["effects"][name]["rel_error"] == con["effects"][name]["rel_error"], name


@pytest.mark.parametrize("keys,key,words", [
    ({"sides": 2, "half_angle": "60 deg"}, "sides", "one of 3, 4, 6, 8"),
    ({"sides": 5, "half_angle": "60 deg"}, "sides", "one of 3, 4, 6, 8"),
    ({"sides": 4.0, "half_angle": "60 deg"}, "sides", "must be an integer"),
    ({"sides": True, "half_angle": "60 deg"}, "sides", "must be an integer"),
    ({"sides": {"from": 3, "to": 5, "points": 3}, "half_angle": "60 deg"}, "sides",
     "not swept"),
    ({"sides": 4, "half_angle": "90 deg"}, "half_angle", "(0, 90 deg)"),
    ({"sides": 4, "half_angle": "1 mm"}, "half_angle", ""),
    ({"sides": 4}, "half_angle", "missing"),
    ({"preset": "vikers"}, "preset", "did you mean 'vickers'"),
    ({"preset": 3}, "preset", "must be a name"),
    ({"preset": "vickers", "sides": 4}, "sides", "not both"),
])
def test_pyramid_bad_keys_are_one_line(tmp_path, capsys, keys, key, words):
    body = _pyramid(**keys)
    with pytest.raises(scene.SceneError) as exc:
        _run(body, ["force"])
    assert exc.value.key == f"body[0] (tip).{key}" and words in exc.value.message
    path = tmp_path / "s.toml"
    path.write_text(toml({"effects": ["force"], "body": [body, {"shape": "flat", "E": 1e9,
                                                               "nu": 0.3}],
                          "load": {"depth": 1e-7}}))
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert err == f"hertzmdr: {str(exc.value).replace('<scene>', str(path))}\n"


def toml(doc: dict) -> str:
    from test_fuzz_scenes import toml_key, toml_value

    return "".join(f"{toml_key(k)} = {toml_value(v)}\n" for k, v in doc.items())


def test_pyramid_example_runs(capsys):
    assert main(["run", str(PYRAMID_SCENE)]) == 0
    out = capsys.readouterr().out
    assert "warning: 1/sides = 0.333" in out and "berkovich 3-sided pyramid" in out


# -- the [fit] table ---------------------------------------------------------------------------
def example_curve() -> str:
    """The text of examples/fit_pyramid_afm_curve.csv: its recipe. The force is the cone's
    (numeric/cone.py, (5.40)) at the force law's angle computed here from the polygon's area
    (not by the derived relation); three columns as an instrument exports them, the header
    without units (the scene's [fit] gives them)."""
    with mp.workdps(30):
        theta = float(mp.acot(cot_force_law(EXAMPLE_SIDES, mp.mpf(EXAMPLE_ALPHA))))
    z = np.linspace(0.0, 3e-6, 600)
    d = np.maximum(z - 1.5e-6, 0.0)
    F = cone.force(d, theta, EXAMPLE_E_STAR) + 0.5e-9 + 2e-4 * z
    F = F + np.random.default_rng(17).normal(0.0, 0.1e-9, z.size)
    lines = ["# synthetic AFM force curve: a rigid 4-sided pyramid (half-angle 35 deg) on E = 20",
             "# kPa, nu = 0.5 (E* = 26.667 kPa), by its force law; contact point 1.5 um,",
             "# baseline 0.5 nN + 2e-4 N/m * z, Gaussian noise of 0.1 nN (seed 17); made by",
             "# tests/test_fit_scene.py::example_curve. Columns: time [s], height [nm], force",
             "# [pN] (the units are in examples/fit_pyramid_afm.toml's [fit] table)",
             "time, height, force"]
    lines += [f"{k * 1e-3:.3f}, {zi * 1e9:.6f}, {Fi * 1e12:.4f}"
              for k, (zi, Fi) in enumerate(zip(z, F, strict=True))]
    return "\n".join(lines) + "\n"


def test_example_curve_is_its_recipe():
    assert FIT_CURVE.read_text() == example_curve()


def _fit_out(capsys, *argv) -> tuple[int, str, str]:
    rc = main(["fit", *map(str, argv)])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


def _scene_text(fit_table: str | None) -> str:
    """The example fit scene with its [fit] table replaced (None: none)."""
    text = FIT_SCENE.read_text()
    head = text.split("\n[fit]\n")[0]
    return head + ("\n[fit]\n" + fit_table if fit_table is not None else "")


def test_fit_table_fits_what_the_command_line_fits(tmp_path, capsys):
    """`hertzmdr fit --scene S` (the curve, its columns and units, the modulus from S's [fit])
    prints what `hertzmdr fit CURVE --scene S'` prints for the same points written as a plain
    two-column curve and S' without [fit]: the same fit, line for line."""
    z, F = fit_io.read_columns(FIT_CURVE, ("height", "force"), (1e-9, 1e-12))
    plain = tmp_path / "plain.csv"
    plain.write_text("z [m], F [N]\n" + "".join(f"{float(a)!r}, {float(b)!r}\n"
                                                 for a, b in zip(z, F, strict=True)))
    (tmp_path / FIT_CURVE.name).write_text(FIT_CURVE.read_text())
    with_table = tmp_path / "with.toml"
    with_table.write_text(_scene_text(
        f'curve = "{FIT_CURVE.name}"\ncolumns = ["height", "force"]\nunits = ["nm", "pN"]\n'))
    without = tmp_path / "without.toml"
    without.write_text(_scene_text(None))
    rc1, out1, _ = _fit_out(capsys, "--scene", with_table)
    rc2, out2, _ = _fit_out(capsys, plain, "--scene", without)
    assert rc1 == rc2 == 0
    assert out1 == out2
    # modulus = "E_star": no E line, the same E*
    with_table.write_text(_scene_text(f'curve = "{FIT_CURVE.name}"\ncolumns = ["height", '
                                      '"force"]\nunits = ["nm", "pN"]\nmodulus = "E_star"\n'))
    rc3, out3, _ = _fit_out(capsys, "--scene", with_table)
    assert rc3 == 0 and "\nE " not in out3
    assert out3.splitlines()[2] == out1.splitlines()[2]  # the E_star row


def test_the_example_recovers_its_modulus(tmp_path, capsys):
    """The example's fit over its depth range: the truth E = 20 kPa within 4 reported standard
    errors (a 6e-5 event for a right error; the curve's noise is fixed by its seed); its
    figure written."""
    rc, out, _ = _fit_out(capsys, "--scene", FIT_SCENE, "--out", tmp_path / "fit.png")
    assert rc == 0, out
    assert (tmp_path / "fit.png").read_bytes()[:4] == b"\x89PNG"
    row = next(ln for ln in out.splitlines() if ln.startswith("E "))
    E, err = float(row.split()[1]), float(row.split()[2])
    assert abs(E - EXAMPLE_E) < 4 * err and err < 0.01 * EXAMPLE_E, (E, err)
    assert "warning: 1/sides = 0.25" in out


def test_depth_range_is_a_fixed_point():
    """The range's fit is the fit of exactly the points in the range of its own contact point:
    fitting those points again gives the same parameters (to the solver's 1e-15 steps)."""
    z, F = fit_io.read_columns(FIT_CURVE, ("height", "force"), (1e-9, 1e-12))
    tip = fit.Pyramid(alpha=EXAMPLE_ALPHA, sides=EXAMPLE_SIDES)
    lo, hi = -1.5e-6, 1e-6
    r = fit_io.fit_in_range(z, F, tip, (lo, hi), nu=0.5)
    keep = (z - r.z_0 >= lo) & (z - r.z_0 <= hi)
    assert r.F.size == keep.sum() < z.size
    again = fit.fit_curve(z[keep], F[keep], tip, nu=0.5, z0=r.z_0)
    # the same data from a start of its own: Levenberg-Marquardt stops where its tolerances
    # stop it, within a tiny fraction of each standard error of where it stopped before
    assert np.all(np.abs(again.values - r.values) < 1e-5 * r.errors), (again.values, r.values)


def test_noise_free_pyramid_curve_by_the_shoelace_route(tmp_path, capsys):
    """A noise-free curve whose force is Sneddon's cone at the force law's angle (beta_n times
    the shoelace-area cot; mpmath, 30 digits), fitted through a [fit] table: E* back to 1e-10
    (the issue's noise-free bound; the curve's values are float64 roundings of the 30-digit
    force)."""
    E_star, z0, sides = 3e6, 2e-7, 3
    z = np.linspace(0.0, 4e-7, 300)
    with mp.workdps(30):
        cot = cot_force_law(sides, mp.radians(65.27))
        F = [float(2 / mp.pi * E_star * max(mp.mpf(float(x)) - mp.mpf(z0), 0) ** 2 * cot + 1e-9)
             for x in z]
    (tmp_path / "c.csv").write_text("z [m], F [N]\n" + "".join(
        f"{float(a)!r}, {float(b)!r}\n" for a, b in zip(z, F, strict=True)))
    (tmp_path / "s.toml").write_text(
        'effects = ["force"]\n[[body]]\nshape = "pyramid"\npreset = "berkovich"\nrigid = true\n'
        '[[body]]\nshape = "flat"\nE = "1 MPa"\nnu = 0.5\n[load]\ndepth = "100 nm"\n'
        '[fit]\ncurve = "c.csv"\nmodulus = "E_star"\n')
    rc, out, err = _fit_out(capsys, "--scene", tmp_path / "s.toml")
    assert rc == 0, err
    row = next(ln for ln in out.splitlines() if ln.startswith("E_star "))
    assert abs(float(row.split()[1]) / E_star - 1) < 1e-6  # the table prints 7 digits
    r = fit.fit_curve(z, F, fit_io.TIP_SHAPES["pyramid"]({"preset": "berkovich"}))
    assert abs(r.E_star / E_star - 1) < 1e-10 and abs(r.z_0 / z0 - 1) < 1e-10


def test_fixed_contact_point_and_baseline(tmp_path, capsys):
    """[fit] fixed_contact_point and fixed_baseline (and --fix-z0, --fix-baseline, which
    override them) hold those parameters: the table prints them "fixed", at the given values;
    the fit is fit_curve's with fixed_z0, fixed_baseline; with --adhesion, one line, exit 2."""
    z, F = fit_io.read_columns(FIT_CURVE, ("height", "force"), (1e-9, 1e-12))
    (tmp_path / FIT_CURVE.name).write_text(FIT_CURVE.read_text())
    base = f'curve = "{FIT_CURVE.name}"\ncolumns = ["height", "force"]\nunits = ["nm", "pN"]\n'
    free = fit.fit_curve(z, F, fit.Pyramid(alpha=EXAMPLE_ALPHA, sides=EXAMPLE_SIDES), nu=0.5)
    z0, F0, s0 = (float(v) for v in free.values[1:])
    path = tmp_path / "s.toml"
    path.write_text(_scene_text(base + f'fixed_contact_point = "{z0!r} m"\n'
                                f'fixed_baseline = ["{F0!r} N", "{s0!r} N/m"]\n'))
    rc, out, err = _fit_out(capsys, "--scene", path)
    assert rc == 0, err
    rows = {ln.split()[0]: ln.split() for ln in out.splitlines() if ln.split()
            and ln.split()[0] in ("E_star", "z_0", "F_0", "s_0")}
    assert rows["z_0"][2] == rows["F_0"][2] == rows["s_0"][2] == "fixed"
    assert rows["E_star"][2] != "fixed"
    ref = fit.fit_curve(z, F, fit.Pyramid(alpha=EXAMPLE_ALPHA, sides=EXAMPLE_SIDES), nu=0.5,
                        fixed_z0=z0, fixed_baseline=(F0, s0))
    assert float(rows["E_star"][1]) == pytest.approx(ref.E_star, rel=1e-6)  # 7 digits printed
    # at the free fit's own optimum, E* does not move, and its error is at most the free one's
    assert ref.E_star == pytest.approx(free.E_star, rel=1e-9)
    assert ref.errors[0] <= free.errors[0]
    # the command line overrides the table
    rc, out2, err = _fit_out(capsys, "--scene", path, "--fix-z0", f"{z0 + 1e-9!r} m")
    assert rc == 0, err
    row = next(ln for ln in out2.splitlines() if ln.startswith("z_0 "))
    assert float(row.split()[1]) == pytest.approx(z0 + 1e-9, rel=1e-6) and "fixed" in row
    rc, out3, err = _fit_out(capsys, tmp_path / FIT_CURVE.name, "--scene", FIT_SCENE,
                             "--fix-baseline", "1 nN", "1 nN")
    assert rc == 2 and err.count("\n") == 1 and "--fix-baseline" in err, err
    plain = tmp_path / "plain.csv"
    plain.write_text("z [m], F [N]\n" + "".join(f"{float(a)!r}, {float(b)!r}\n"
                                                 for a, b in zip(z, F, strict=True)))
    bare = tmp_path / "bare.toml"
    bare.write_text(_scene_text(None))
    rc, _, err = _fit_out(capsys, plain, "--scene", bare, "--fix-z0", "1 um", "--adhesion")
    assert rc == 2 and err.count("\n") == 1 and "valid only without --adhesion" in err, err


GOOD = 'curve = "c.csv"\n'


@pytest.mark.parametrize("table,key,words", [
    ('curve = "nope.csv"\n', "fit.curve", "no such file"),
    ('curve = 3\n', "fit.curve", "must be a file name"),
    (GOOD + 'colums = ["z", "F"]\n', "fit.colums", "did you mean 'columns'"),
    (GOOD + 'columns = ["z"]\n', "fit.columns", "two different columns"),
    (GOOD + 'columns = ["z", "z"]\n', "fit.columns", "two different columns"),
    (GOOD + 'units = ["nm", "nm"]\n', "fit.units[1]", "force"),
    (GOOD + 'units = "nm"\n', "fit.units", "two unit strings"),
    (GOOD + 'modulus = "G"\n', "fit.modulus", "\"E_star\""),
    (GOOD + 'depth_range = ["1 um", "-1 um"]\n', "fit.depth_range", "lowest < highest"),
    (GOOD + 'depth_range = ["-1 um", "1 N"]\n', "fit.depth_range[1]", ""),
    (GOOD + 'depth_range = "1 um"\n', "fit.depth_range", "list of two depths"),
    (GOOD + 'contact_point = "1 s"\n', "fit.contact_point", ""),
    (GOOD + 'sigma = "-1 nN"\n', "fit.sigma", "must be > 0"),
    (GOOD + 'fixed_contact_point = "1 N"\n', "fit.fixed_contact_point", "a length"),
    (GOOD + 'fixed_contact_point = "1 um"\ncontact_point = "1 um"\n',
     "fit.fixed_contact_point", "exclude each other"),
    (GOOD + 'fixed_baseline = "1 nN"\n', "fit.fixed_baseline", "[F_0, s_0]"),
    (GOOD + 'fixed_baseline = ["1 nN", "1 nN"]\n', "fit.fixed_baseline[1]",
     "a force per length"),
    (GOOD + 'fixed_baseline = ["1 m", "1 N/m"]\n', "fit.fixed_baseline[0]", "a force"),
    ("fit = 3\n", "fit", "must be a table"),
])
def test_bad_fit_keys_are_one_line(tmp_path, capsys, table, key, words):
    """Each bad key or value of [fit]: one line naming it, exit 2, from `fit` and from `run`
    (the table is part of the scene)."""
    (tmp_path / "c.csv").write_text("z [nm], F [nN]\n" + "".join(
        f"{k}, {max(k - 50, 0) ** 2 / 100}\n" for k in range(100)))
    text = _scene_text(None) + ("\n[fit]\n" + table if not table.startswith("fit =") else "")
    if table.startswith("fit ="):
        text = table + text
    path = tmp_path / "s.toml"
    path.write_text(text)
    for argv in (["fit", "--scene", str(path)], ["run", str(path)]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith(f"hertzmdr: {path}: {key}: ") and err.count("\n") == 1, err
        assert words in err, err


@pytest.mark.parametrize("table,argv,words", [
    (None, [], "give a CURVE_OR_MAP, or a [fit] table with curve"),
    ('columns = ["z", "Force"]\n', ["c.csv"], "the force column 'Force' of [fit] columns is not"),
    ('units = ["nm", "nN"]\n', ["c.csv"], "gives its unit, and so does [fit] units"),
    ('units = ["nm", "nN"]\n', ["bare.csv"], ""),
    ('depth_range = ["-1 nm", "1 nm"]\n', ["c.csv"], "holds"),
    ('depth_range = ["-1 um", "1 um"]\n', ["map.csv"], "fit.depth_range: applies to one curve"),
])
def test_fit_table_and_its_curve_errors(tmp_path, capsys, table, argv, words):
    """What only the curve can tell: one line, exit 2 (a bare header with [fit] units is
    read: exit 0)."""
    rows = "".join(f"{k}, {max(k - 50, 0) ** 2 / 100}\n" for k in range(100))
    (tmp_path / "c.csv").write_text("z [nm], F [nN]\n" + rows)
    (tmp_path / "bare.csv").write_text("z, F\n" + rows)
    (tmp_path / "map.csv").write_text("curve, z [nm], F [nN]\n" + "".join(
        f"a, {line}" for line in rows.splitlines(keepends=True)))
    path = tmp_path / "s.toml"
    path.write_text(_scene_text(table))
    rc, _, err = _fit_out(capsys, *[tmp_path / a for a in argv], "--scene", path)
    if not words:
        assert rc == 0, err
        return
    assert rc == 2 and err.count("\n") == 1 and words in err, err


def test_run_echoes_the_fit_table_and_runs_it_again(tmp_path, capsys):
    """`hertzmdr run` of a scene with [fit] computes its effects (the table changes none);
    result.json echoes the curve resolved with its SHA-256, and runs again to the same
    numbers; the echo read back fits the same."""
    out = tmp_path / "out"
    assert main(["run", str(FIT_SCENE), "--out", str(out)]) == 0
    doc = json.loads((out / "result.json").read_text())
    assert doc["scene"]["fit"]["curve"] == str(FIT_CURVE.resolve())
    assert [f["key"] for f in doc["files"]] == ["fit.curve"]
    again = scene.load(out / "result.json").run()
    assert again["effects"] == {**again["effects"], **{
        k: {**v, "seconds": again["effects"][k]["seconds"]} for k, v in doc["effects"].items()}}
    capsys.readouterr()
    rc1, out1, _ = _fit_out(capsys, "--scene", out / "result.json")
    rc2, out2, _ = _fit_out(capsys, "--scene", FIT_SCENE)
    assert rc1 == rc2 == 0 and out1 == out2
