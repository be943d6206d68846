"""Checks of numeric/scene/shapes/ that its second mutation run (benchmarks/mutation_runs/
scene_shapes.json) found missing: what a singular shape refuses before anything is computed,
the unit of a sample file, the rules of a profile's ``breakpoints`` (the tolerance that snaps a
value to a sample, the pieces of at least two intervals) with the refusals that name the key,
the value and what is valid, and the model block of a pyramid. Everything here is a load or a
contact built without running an effect: milliseconds."""

from __future__ import annotations

import math

import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.model import build

FLAT = {"shape": "flat", "E": 1e9, "nu": 0.3}


def spec_of(tip, nu=0.3, effects=("force",)):
    return scene.load({"effects": list(effects), "body": [{**tip, "rigid": True},
                                                          {**FLAT, "nu": nu}],
                       "load": {"depth": 1e-9}}).spec


# -- the singular shapes: refused before anything is computed ---------------------------------

@pytest.mark.parametrize("tip, reason", [
    ({"shape": "cone", "angle": "80 deg"}, "the cone's pressure is log-singular at the tip"),
    ({"shape": "flat_punch", "radius": 1e-3}, "the punch pressure (5.9) is singular at the edge"),
    ({"shape": "flattened_parabola", "radius": 0.05, "flat_radius": 1e-4},
     "the worn parabola's pressure is log-infinite at the edge of the flat r = b"),
])
def test_singular_shapes_refuse_their_maxima_up_front(tip, reason):
    """A pressure unbounded at a known radius (the cone's tip, the punch's edge, the worn
    parabola's r = b): max_pressure and max_orthogonal_shear are refused with that reason, and
    for nu = 0.5 max_shear and max_von_mises too -- by the contact's ``has``, which the runner
    asks before any effect is computed. (Without the shape's reason or its singular radius the
    maxima are searched on the singular pressure instead: tens of seconds, then a finite
    number, which test_scene_mutants.py::test_unbounded_maxima_sit_at_the_singular_radius
    refuses; here the same mutants fail in milliseconds.)"""
    contact = build(spec_of(tip))
    for name in ("max_pressure", "max_orthogonal_shear"):
        assert not contact.has(name)
        assert contact.why_not[name].startswith(reason)
    assert contact.has("max_shear") and contact.has("max_von_mises")  # +inf at r_s, nu < 0.5
    half = build(spec_of(tip, nu=0.5))
    for name in ("max_shear", "max_von_mises"):
        assert not half.has(name)
        assert half.why_not[name].startswith(reason) and "hydrostatic" in half.why_not[name]


# -- a profile's sample file and its unit ----------------------------------------------------

def test_sample_file_columns_take_the_unit(tmp_path):
    """unit = "nm" scales both columns of a sample file to m: the samples the body holds are
    the file's numbers times 1e-9, to the rounding of that product and of pint's conversion
    (2 ulps: 5e-16)."""
    r_nm = [0.0, 10.0, 20.0, 30.0, 40.0]
    f_nm = [0.0, 0.5, 2.0, 4.5, 8.0]
    (tmp_path / "tip.csv").write_text("r, f\n" + "".join(f"{r}, {f}\n"
                                                         for r, f in zip(r_nm, f_nm, strict=True)))
    path = tmp_path / "scene.toml"
    path.write_text('effects = ["force"]\n[[body]]\nshape = "profile"\nfile = "tip.csv"\n'
                    'unit = "nm"\nrigid = true\n[[body]]\nshape = "flat"\nE = 1e9\nnu = 0.3\n'
                    '[load]\ndepth = 1e-9\n')
    p = scene.load(path).spec.bodies[0].params
    assert "unit" not in p  # read and consumed
    assert p["r"] == pytest.approx([v / 1e9 for v in r_nm], rel=5e-16, abs=0)
    assert p["f"] == pytest.approx([v / 1e9 for v in f_nm], rel=5e-16, abs=0)


def test_unit_without_a_sample_file_is_refused():
    """``unit`` is the unit of a file's columns; with r and f inline it is refused by name
    (their values carry their own units)."""
    with pytest.raises(scene.SceneError) as info:
        spec_of({"shape": "profile", "r": [0.0, 1e-6, 2e-6, 3e-6],
                 "f": [0.0, 1e-9, 4e-9, 9e-9], "unit": "nm"})
    assert info.value.key == "body[0] (body 1).unit"
    assert info.value.message.startswith("is the unit of a sample file's columns; give r and f "
                                         "with their units")


# -- breakpoints -----------------------------------------------------------------------------

#: r_max chosen so that 1e-9 r_max is exactly 2^-47 m (7.1e-15 m): then 2 um + 2^-47 m is a
#: float whose distance from the sample 2 um is exactly the tolerance, 1e-9 r_max
T = 2.0**-47
R_MAX = T * 1e9
R = [0.0, 1e-6, 2e-6, 3e-6, 4e-6, 5e-6, 6e-6, R_MAX]


def profile(bps):
    return {"shape": "profile", "r": R, "f": [x * x / 1e-5 for x in R], "breakpoints": bps}


def breakpoints_of(bps):
    return spec_of(profile(bps)).bodies[0].params["breakpoints"]


def refusal(bps):
    with pytest.raises(scene.SceneError) as info:
        spec_of(profile(bps))
    return info.value.key, info.value.message


def test_breakpoint_tolerance_is_1e_9_of_r_max():
    """A breakpoint is the sample it names to within 1e-9 of the largest sample r_max (a value
    in another unit than the samples' differs from them by rounding): exactly 1e-9 r_max away
    it is still that sample, snapped to it; twice as far it is refused. The tolerance is
    r_max's, not that of a smaller sample (here r[1] = 1e-6 m and r[-2] = 6e-6 m give 1e-15 m
    and 6e-15 m, below the 7.1e-15 m offset)."""
    assert 1e-9 * R_MAX == T and abs(R[2] - (R[2] + T)) == T  # exactly on the tolerance
    assert breakpoints_of([R[2] + T]) == [R[2]]
    assert breakpoints_of([R[2] - T]) == [R[2]]
    key, message = refusal([R[2] + 2 * T])
    assert key == "body[0] (body 1).breakpoints[0]"
    assert "is not one of the samples inside the profile" in message


def test_breakpoint_off_the_samples_names_them():
    """The refusal of a value that is no sample: the value, the valid range (0, r_max), the
    inner samples r[1] ... r[n-2] and the nearest sample, each by index and value; the value
    and the nearest sample in all their digits and how far apart (at 6 digits a value 1e-13 m
    off a sample read as that sample)."""
    key, message = refusal([2.4e-6])
    assert key == "body[0] (body 1).breakpoints[0]"
    assert message == ("2.4e-06 m is not one of the samples inside the profile; valid: a "
                       "sample radius strictly between 0 and r_max = 7.10543e-06 m (r[1] = "
                       "1e-06 m ... r[6] = 6e-06 m; nearest: r[2] = 2e-06 m, 4e-07 m away)")
    key, message = refusal([2e-6 + 1e-13])
    assert message.startswith("2.0000001e-06 m is not one of the samples")
    assert message.endswith("nearest: r[2] = 2e-06 m, 1e-13 m away)")


def test_breakpoint_given_twice_is_refused():
    """The same sample named twice (here once with the tolerance's offset): the second is
    refused, naming the sample and the rule."""
    key, message = refusal([2e-6, 3e-6, 2e-6 + T])
    assert key == "body[0] (body 1).breakpoints[2]"
    assert message == "2e-06 m is given twice (as r[2] = 2e-06 m); valid: each kink once"


@pytest.mark.parametrize("bps", [[R[2]], [R[-3]], [R[2], R[4]], [R[4], R[2]]])
def test_pieces_of_two_intervals_are_accepted(bps):
    """Every piece between 0, the breakpoints and r_max needs two sample intervals: r[2] (the
    first piece r[0..2]) and r[n-3] (the last r[n-3..n-1]) are the extreme valid breakpoints,
    and r[2], r[4] together leave a middle piece of two; they come back sorted."""
    assert breakpoints_of(bps) == sorted(bps)


@pytest.mark.parametrize("bps, between", [
    ([R[1]], "0 m and 1e-06 m"),                 # the first piece, r[0..1]
    ([R[-2]], "6e-06 m and 7.10543e-06 m"),      # the last, r[n-2..n-1]
    ([R[4], R[3]], "3e-06 m and 4e-06 m"),       # a middle one
])
def test_piece_of_one_interval_is_refused(bps, between):
    """A piece of one sample interval is refused (the numerical MDR's error bound compares a
    piece's samples with a coarser set of them): the key, the breakpoints, the piece's ends
    and the rule."""
    key, message = refusal(bps)
    assert key == "body[0] (body 1).breakpoints"
    listed = [float(f"{b:.6g}") for b in sorted(bps)]
    assert message == (f"{listed} m leave one sample interval between r = {between}; valid: "
                       "at least two intervals (three samples) in every piece between 0, the "
                       "breakpoints and r_max (the numerical MDR's error bound compares a "
                       "piece's samples with a coarser set of them)")


# -- the pyramid's model block ---------------------------------------------------------------

def test_pyramid_model_block_names_the_pyramid():
    """The model block of a pyramid reports its geometry as given (sides, the half-angle in
    rad), its label the preset's name when there is one, and each effect's method says it is
    the cone of the pyramid's force law (the cone's own method would hide the route)."""
    doc = scene.load({"effects": ["force"], "load": {"depth": 1e-7},
                      "body": [{"shape": "pyramid", "sides": 4, "half_angle": "60 deg",
                                "rigid": True}, FLAT]}).run()
    model = doc["model"]
    assert (model["sides"], model["half_angle"]) == (4, pytest.approx(math.pi / 3, rel=1e-15,
                                                                      abs=0))
    assert model["description"].startswith("4-sided pyramid (half-angle 60 deg)")
    # the method names the route, not the cone's own "(5.38)-(5.40)"
    assert doc["effects"]["force"]["method"] == ("(5.38)-(5.40) at the cone of the pyramid's "
                                                 "force law (the BEM's beta_n)")
    preset = scene.load({"effects": ["force"], "load": {"depth": 1e-7},
                         "body": [{"shape": "pyramid", "preset": "berkovich", "rigid": True},
                                  FLAT]}).run()["model"]
    assert preset["description"].startswith("berkovich 3-sided pyramid (half-angle 65.27 deg)")
    assert preset["half_angle"] == pytest.approx(math.radians(65.27), rel=1e-15, abs=0)
