"""Every malformed scene gets one clear message naming the file and the key, and exit code 2."""

import re
import subprocess
import sys

import pytest

from hertzmdr.numeric.cli import main

GOOD = """\
title = "ok"
effects = ["force"]

[[body]]
name = "ball"
shape = "sphere"
radius = "10 mm"
E = "210 GPa"
nu = 0.3

[[body]]
name = "plate"
shape = "flat"
rigid = true

[load]
depth = "1 um"
"""

CASES = [
    # (what, text replacement (old, new) or full text, expected fragments of the message)
    ("unknown shape", ('shape = "sphere"', 'shape = "sphre"'),
     ["body[0] (ball).shape", "unknown shape 'sphre'", "did you mean 'sphere'"]),
    ("unknown effect", ('effects = ["force"]', 'effects = ["forse"]'),
     ["effects", "unknown effect 'forse'", "did you mean 'force'"]),
    ("missing radius", ('radius = "10 mm"\n', ""), ["body[0] (ball).radius", "missing"]),
    ("extra key", ('nu = 0.3\n', 'nu = 0.3\ncolour = "red"\n'),
     ["body[0] (ball).colour", "unknown key"]),
    ("wrong unit", ('radius = "10 mm"', 'radius = "10 kg"'),
     ["body[0] (ball).radius", "not a length"]),
    ("nu out of range", ("nu = 0.3", "nu = 0.7"), ["body[0] (ball).nu", "-1 < nu <= 0.5"]),
    ("E negative", ('E = "210 GPa"', 'E = "-210 GPa"'), ["body[0] (ball).E", "must be > 0"]),
    ("zero radius", ('radius = "10 mm"', "radius = 0"), ["body[0] (ball).radius", "not be 0"]),
    ("unworn worn tip", ('shape = "sphere"', 'shape = "flattened_parabola"\nflat_radius = 0'),
     ["body[0] (ball).flat_radius", "must be > 0", "shape = \"sphere\""]),
    ("two loads", ('depth = "1 um"', 'depth = "1 um"\nforce = "1 N"'),
     ["load", "exactly one of depth, force"]),
    ("no load", ('[load]\ndepth = "1 um"\n', ""), ["load", "missing"]),
    ("toml syntax", ('nu = 0.3', 'nu = = 0.3'), ["TOML syntax error", "line 9"]),
    ("three bodies", ("[load]", '[[body]]\nshape = "flat"\nrigid = true\n\n[load]'),
     ["body", "exactly two [[body]] tables"]),
    ("both rigid", ('E = "210 GPa"\nnu = 0.3', "rigid = true"), ["body", "both bodies are rigid"]),
    ("cone angle", ('shape = "sphere"\nradius = "10 mm"', 'shape = "cone"\nangle = "95 deg"'),
     ["body[0] (ball).angle", "(0, 90 deg)"]),
    ("samples not increasing", ('shape = "sphere"\nradius = "10 mm"',
                                'shape = "profile"\nr = [0, 2e-6, 1e-6]\nf = [0, 1e-9, 2e-9]'),
     ["body[0] (ball).r", "increase strictly"]),
    ("samples with NaN", ('shape = "sphere"\nradius = "10 mm"',
                          'shape = "profile"\nr = [0, 1e-6, 2e-6]\nf = [0, nan, 2e-9]'),
     ["body[0] (ball).f[1]", "must be finite, got nan"]),
    ("missing sample file", ('shape = "sphere"\nradius = "10 mm"',
                             'shape = "profile"\nfile = "no_such_tip.csv"'),
     ["body[0] (ball).file", "not found"]),
    ("pressure on a sphere", ('depth = "1 um"',
                              'pressure = { distribution = "uniform", p0 = 1e6, radius = 1e-3 }'),
     ["load.pressure", "two flat bodies"]),
    ("unknown distribution", ('depth = "1 um"',
                              'pressure = { distribution = "unifrom", p0 = 1e6, radius = 1e-3 }'),
     ["load.pressure.distribution", "did you mean 'uniform'"]),
    ("polygon with two corners", ('shape = "sphere"\nradius = "10 mm"',
                                  'shape = "polygon_punch"\nvertices = [[0, 0], [1e-3, 0]]'),
     ["body[0] (ball).vertices", "at least three"]),
    ("missing height map", ('shape = "sphere"\nradius = "10 mm"',
                            'shape = "height_map"\nfile = "nope.csv"\nspacing = "1 um"'),
     ["body[0] (ball).file", "not found"]),
    # a pyramid: a preset, or sides and half_angle (numeric/scene/shapes/pyramid.py)
    ("pyramid: unknown preset", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\npreset = "berkovic"'),
     ['body[0] (ball).preset', "unknown preset 'berkovic'", "did you mean 'berkovich'",
      '(one of: berkovich, vickers, cube_corner)']),
    ("pyramid: preset and sides", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\npreset = "vickers"\nsides = 4'),
     ['body[0] (ball).sides', 'give preset or sides and half_angle, not both',
      "the preset 'vickers' sets them"]),
    ("pyramid: preset and half-angle", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\npreset = "vickers"\nhalf_angle = "60 deg"'),
     ['body[0] (ball).half_angle', 'not both']),
    ("pyramid: no half-angle", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\nsides = 4'),
     ['body[0] (ball).half_angle', 'missing: a pyramid needs sides and half_angle, or a preset '
      '(one of: berkovich, vickers, cube_corner)']),
    ("pyramid: no sides", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\nhalf_angle = "60 deg"'),
     ['body[0] (ball).sides', 'missing']),
    ("pyramid: five sides", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\nsides = 5\nhalf_angle = "60 deg"'),
     ['body[0] (ball).sides', 'must be one of 3, 4, 6, 8', 'got 5']),
    ("pyramid: half-angle 90 deg", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\nsides = 4\nhalf_angle = "90 deg"'),
     ['body[0] (ball).half_angle', 'must be in (0, 90 deg), got 90 deg']),
    ("pyramid: half-angle 0", ('shape = "sphere"\nradius = "10 mm"',
      'shape = "pyramid"\nsides = 3\nhalf_angle = 0'),
     ['body[0] (ball).half_angle', 'got 0 deg']),
    ("bad rtol", ("[load]", "[accuracy]\nrtol = 2.0\n\n[load]"), ["accuracy.rtol"]),
    ("sweep points", ('depth = "1 um"', 'depth = { from = 0, to = "1 um", points = 1 }'),
     ["load.depth.points"]),
]


def _scene(tmp_path, case):
    text = GOOD
    old, new = case
    assert old in text, old
    text = text.replace(old, new, 1)
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("what, case, fragments", CASES, ids=[c[0] for c in CASES])
def test_bad_scene(tmp_path, capsys, what, case, fragments):
    path = _scene(tmp_path, case)
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"hertzmdr: {path}"), err
    for frag in fragments:
        assert frag in err, f"{what}: {frag!r} not in {err!r}"
    assert "Traceback" not in err


def test_effect_that_does_not_apply(tmp_path, capsys):
    """The issue's example: a contact_radius for a line contact says why and what applies."""
    path = tmp_path / "line.toml"
    path.write_text('effects = ["contact_radius"]\n[[body]]\nshape = "cylinder"\n'
                    'radius = 0.01\nlength = 0.01\nE = 2e11\nnu = 0.3\n[[body]]\n'
                    'shape = "flat"\nrigid = true\n[load]\nforce = 100\n')
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert "'contact_radius' does not apply" in err and "use 'half_width'" in err


def test_worn_pressure_matches_the_numerical_mdr():
    """The worn tip's pressure (closed form, Problem 8) agrees with the numerical MDR of the
    same profile sampled with the kink r = b as a breakpoint (an independent route: splines,
    quadrature, the kink's branch-point term), and the axis stresses under it with a ring sum
    of Boussinesq's point force within their error estimate."""
    import numpy as np

    from hertzmdr.numeric import mdr, scene

    R, b, E, nu, d = 0.01, 1e-4, 1e9, 0.4, 1e-6
    doc = scene.load({"effects": ["pressure_profile", "axis_stresses"],
                      "body": [{"shape": "flattened_parabola", "radius": R, "flat_radius": b,
                                "rigid": True}, {"shape": "flat", "E": E, "nu": nu}],
                      "load": {"depth": d}}).run()["effects"]
    prof = doc["pressure_profile"]["value"]
    r, p = np.asarray(prof["r"]), np.asarray(prof["p"])
    E_star = E / (1 - nu**2)
    rs = np.unique(np.concatenate([np.linspace(0, b, 41), np.linspace(b, 4 * b, 121)]))
    sol = mdr.Profile.from_samples(rs, np.where(rs < b, 0, (rs**2 - b**2) / (2 * R)),
                                   breakpoints=[b]).solve(depth=d, E_star=E_star)
    pm, em = sol.pressure(r, return_error=True)
    assert np.all(np.isfinite(p)) and p[0] > 0 and p[-1] == 0
    # the numerical MDR's own estimate bounds its error (tests/test_mdr.py); x2 for safety
    assert np.all(np.abs(p - pm) <= 2 * em + 1e-12 * np.max(p))
    ax = doc["axis_stresses"]["value"]
    szz = np.asarray(ax["sigma_zz"])
    assert np.all(np.isfinite(szz)) and np.all(szz < 0)
    # on the axis sigma_zz = -integral_0^a p(rho) 3 z^3 rho / (rho^2 + z^2)^(5/2) d rho
    # (Boussinesq's point force summed over rings); QUADPACK split at the log singularity b
    from scipy.integrate import quad

    from hertzmdr.numeric import _generated as gen

    a = float(gen.worn_contact_radius(R, b, d))
    err = doc["axis_stresses"]["rel_error"]
    for zi, si in list(zip(ax["z"], szz, strict=True))[::10]:
        ref = -quad(lambda rho, z=zi: float(gen.worn_pressure(E_star, R, a, b, rho)) * 3 * z**3
                    * rho / (rho**2 + z**2) ** 2.5, 0, a, points=[b], limit=200)[0]
        assert abs(si / ref - 1) <= max(err, 1e-6), (zi, si, ref, err)


def test_worn_max_pressure_is_refused_with_the_reason(tmp_path, capsys):
    """The worn parabola's pressure is log-infinite at r = b: no maximum to report."""
    path = tmp_path / "worn.toml"
    path.write_text('effects = ["max_pressure"]\n[[body]]\nshape = "flattened_parabola"\n'
                    'radius = 0.01\nflat_radius = 1e-4\nrigid = true\n[[body]]\n'
                    'shape = "flat"\nE = 1e9\nnu = 0.4\n[load]\ndepth = 1e-6\n')
    assert main(["run", str(path)]) == 2
    assert "log-infinite at the edge of the flat" in capsys.readouterr().err


def test_missing_file(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.toml")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_cli_process_exit_code(tmp_path):
    """As a user runs it: a separate process, exit status 2, one line on stderr."""
    path = _scene(tmp_path, CASES[0][1])
    proc = subprocess.run([sys.executable, "-m", "hertzmdr.numeric.cli", "run", str(path)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr


def test_scene_never_executes_code(tmp_path, capsys):
    marker = tmp_path / "pwned"
    evil = f"__import__('os').system('touch {marker}')"
    text = GOOD.replace('radius = "10 mm"', f'radius = "{evil}"')
    path = tmp_path / "scene.toml"
    path.write_text(text)
    assert main(["run", str(path)]) == 2
    assert not marker.exists()
    assert "cannot read" in capsys.readouterr().err


def test_sampled_conical_tip_pressure_is_infinite_at_the_axis():
    """A sampled cone (f'(0) > 0): p(0) = +inf, max_pressure says +inf without a NaN error, the
    profile's error is over the finite values, and p agrees with the cone's (5.39)."""
    import numpy as np

    from hertzmdr.numeric import cone, scene

    tan_t, E, nu, d = 0.5, 1e9, 0.3, 1e-7
    r = np.linspace(0, 2e-6, 41)
    doc = scene.load({"effects": ["pressure_profile", "max_pressure"],
                      "body": [{"shape": "profile", "r": r.tolist(), "f": (tan_t * r).tolist(),
                                "rigid": True}, {"shape": "flat", "E": E, "nu": nu}],
                      "load": {"depth": d}}).run()["effects"]
    assert np.isinf(doc["max_pressure"]["value"])
    prof = doc["pressure_profile"]
    rr, p = np.asarray(prof["value"]["r"]), np.asarray(prof["value"]["p"])
    assert np.isinf(p[0]) and np.isfinite(prof["rel_error"]) and prof["rel_error"] < 1e-6
    ref = cone.pressure(rr[1:], d, np.arctan(tan_t), E / (1 - nu**2))
    # piecewise linear f: the quintic spline is exact; the tables' error (estimate above)
    np.testing.assert_allclose(p[1:], ref, rtol=1e-7, atol=1e-9 * np.max(p[1:]))


def test_byte_order_mark_is_accepted(tmp_path, capsys):
    """Editors on some systems start a UTF-8 file with a byte-order mark: it is no content."""
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + GOOD.encode())
    assert main(["run", str(path), "--json"]) == 0
    assert '"force"' in capsys.readouterr().out


def test_string_without_a_unit_names_the_key(tmp_path, capsys):
    path = tmp_path / "bare.toml"
    path.write_text(GOOD.replace('radius = "10 mm"', 'radius = "10"'))
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err
    assert "radius" in err and "has no unit" in err and len(err.strip().splitlines()) == 1


def _profile_scene(f, depth):
    r = [i * 1e-7 for i in range(11)]
    return {"effects": ["force"], "load": {"depth": depth},
            "body": [{"shape": "profile", "r": r, "f": f(r), "rigid": True},
                     {"shape": "flat", "E": 1e9, "nu": 0.3}]}


def test_sampled_profile_that_decreases_names_the_sample():
    from hertzmdr.numeric import scene

    bump = lambda r: [x * x / 2e-6 - (3e-8 if i == 3 else 0.0) for i, x in enumerate(r)]  # noqa
    with pytest.raises(scene.SceneError, match=r"f\[3\].*decreases"):
        scene.load(_profile_scene(bump, 1e-9))


def test_sampled_profile_too_short_says_where_the_samples_end():
    from hertzmdr.numeric import scene

    with pytest.raises(scene.SceneError, match=r"they end at r_max = 1e-06 m.*further out") \
            as info:
        scene.load(_profile_scene(lambda r: [x * x / 2e-6 for x in r], 1e-6)).run()
    # prose: the reached depth printed with 6 digits, not a float's 17 (g(r_max) = 0.25 um
    # carries the quadrature's last-digit noise)
    assert re.search(r"g\(r_max\) = \d(\.\d{1,5})?e-0\d m", str(info.value)), str(info.value)


def test_sample_file_unit(tmp_path):
    """unit = "nm" beside file reads the columns in nm: the same tip in m and in nm gives the
    same force (to rounding of the scale, 1e-15); unit without file, or not a length, is one
    clear error."""
    from hertzmdr.numeric import scene

    r = [i * 20e-9 for i in range(40)]
    (tmp_path / "m.csv").write_text("".join(f"{x!r}, {x * x / 2e-6!r}\n" for x in r))
    (tmp_path / "nm.csv").write_text("r_nm, f_nm\n" + "".join(
        f"{x * 1e9!r} {x * x / 2e-6 * 1e9!r}\n" for x in r))

    def force(body):
        spec = {"effects": ["force"], "load": {"depth": 20e-9},
                "body": [{"shape": "profile", "rigid": True, **body},
                         {"shape": "flat", "E": 1e9, "nu": 0.3}]}
        path = tmp_path / "s.toml"
        import json  # TOML's inline tables are JSON-like enough for these keys
        lines = [f"effects = {json.dumps(spec['effects'])}", "[load]", "depth = 20e-9"]
        for b in spec["body"]:
            lines += ["[[body]]"] + [f"{k} = {json.dumps(v)}" for k, v in b.items()]
        path.write_text("\n".join(lines) + "\n")
        return scene.load(path).run()["effects"]["force"]["value"]

    F_m, F_nm = force({"file": "m.csv"}), force({"file": "nm.csv", "unit": "nm"})
    assert abs(F_nm / F_m - 1) < 1e-12  # scaling by 1e-9 rounds each sample by 1 ulp
    with pytest.raises(scene.SceneError, match="unit: is the unit of a sample file"):
        force({"r": [0.0, 1e-7, 2e-7], "f": [0.0, 1e-8, 4e-8], "unit": "nm"})
    with pytest.raises(scene.SceneError, match="unit"):
        force({"file": "nm.csv", "unit": "N"})


HEIGHT_MAP_SCENE = """\
effects = ["force"]
[[body]]
shape = "height_map"
file = "heights.csv"
spacing = "1 um"
rigid = true
[[body]]
shape = "flat"
E = "1 GPa"
nu = 0.3
[load]
depth = "1 nm"
"""


@pytest.mark.parametrize("content", [b"0,1,2\n1,x,3\n2,3,4\n", b"\x00\xff\xfe"],
                         ids=["not a number", "not text"])
def test_unreadable_height_map_names_its_file(tmp_path, capsys, content):
    (tmp_path / "heights.csv").write_bytes(content)
    (tmp_path / "s.toml").write_text(HEIGHT_MAP_SCENE)
    assert main(["run", str(tmp_path / "s.toml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "heights.csv: cannot read the heights" in err, err


def test_grid_size_is_reported_as_integers(tmp_path):
    from hertzmdr.numeric import scene

    (tmp_path / "heights.csv").write_text(
        "\n".join(",".join(f"{(i - 3) ** 2 + (j - 3) ** 2:g}e-9" for j in range(8))
                  for i in range(8)) + "\n")
    (tmp_path / "s.toml").write_text(HEIGHT_MAP_SCENE)
    grid = scene.load(tmp_path / "s.toml").run()["model"]["grid"]
    assert grid == [8, 8] and all(type(n) is int for n in grid), grid
