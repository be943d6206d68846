"""A scene's ``profile`` body with ``breakpoints``: the radii of a measured tip's kinks.

The tip is Problem 8's worn paraboloid (flat for r < b, (r^2 - b^2)/(2R) beyond: a kink at
r = b), sampled; the references are its closed forms (numeric/worn.py), an independent route
(no spline, no quadrature). With its breakpoint the numerical MDR does not continue the spline
across the kink, and both the scene's force and a fitted modulus come closer to the closed form
than without it. A bad value is one line naming the key, the value and what is valid.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import fit, fit_io, scene, worn
from hertzmdr.numeric.cli import main

EXAMPLES = Path(__file__).parents[1] / "examples"
R, B = 5e-6, 1e-6  # m: the worn paraboloid of examples/fit_worn_tip_profile.csv
E_STAR = 4e6 / 3  # Pa: its scene's sample (E = 1 MPa, nu = 0.5, a rigid tip)


def worn_scene(depth, **extra):
    """A scene dict: the worn tip as 301 samples from 0 to 3 um on the example's sample."""
    r = np.linspace(0.0, 3e-6, 301)
    return {"effects": ["force"], "load": {"depth": depth},
            "body": [{"shape": "profile", "r": r.tolist(),
                      "f": worn.profile(r, R, B).tolist(), "rigid": True, **extra},
                     {"shape": "flat", "E": 1e6, "nu": 0.5}]}


@pytest.mark.parametrize("depth", [30e-9, 100e-9])
def test_scene_force_closer_with_the_breakpoint(depth):
    """The force at a depth whose contact lies beyond the kink (a > b): by the numerical MDR
    with and without breakpoints = [b], against worn.force. Without it the spline rings across
    the kink (error ~1e-5, tests/test_fit_sampled.py); with it the MDR's own error remains
    (~1e-10 and below), and each reported rel_error bounds the true error (promise 2)."""
    truth = float(worn.force(depth, R, B, E_STAR))
    errs = {}
    for bps in ([], ["1 um"]):
        doc = scene.load(worn_scene(depth, breakpoints=bps)).run()["effects"]["force"]
        errs[len(bps)] = abs(doc["value"] / truth - 1)
        # promise 2, plus rounding of the closed form's evaluation (1e-14)
        assert errs[len(bps)] <= doc["rel_error"] + 1e-14, (bps, errs, doc["rel_error"])
    # the kink costs orders of magnitude: a factor of 100 at least
    assert errs[1] < 1e-2 * errs[0], errs


def _example_scene(tmp_path, breakpoints: str | None) -> Path:
    """examples/fit_worn_tip.toml (the tip from its CSV file in nm), with a breakpoints line."""
    text = (EXAMPLES / "fit_worn_tip.toml").read_text().replace(
        'file = "fit_worn_tip_profile.csv"',
        f'file = "{EXAMPLES / "fit_worn_tip_profile.csv"}"')
    if breakpoints is not None:
        text = text.replace('unit = "nm"\n', f'unit = "nm"\nbreakpoints = {breakpoints}\n')
    path = tmp_path / f"tip{len(list(tmp_path.iterdir()))}.toml"
    path.write_text(text)
    return path


def test_fit_with_the_breakpoint_recovers_the_modulus_better(tmp_path):
    """A noise-free curve by the closed form (worn.force, 100 nm deep) fitted with the tip of
    the example scene, whose samples are in nm: with ``breakpoints = ["1 um"]`` (in another
    unit than the samples: snapped to the sample 1000 nm) E* and z_0 come out closer to the
    truth than without, and the truth lies within model_error in both (promise 2)."""
    z = np.linspace(-0.1e-6, 0.1e-6, 400)
    F = worn.force(np.maximum(z, 0.0), R, B, E_STAR)
    out = {}
    for bps in (None, '["1 um"]'):
        tip = fit_io.tip_from_scene(_example_scene(tmp_path, bps))[0]
        res = fit.fit_curve(z, F, tip)
        err = abs(res.E_star / E_STAR - 1)
        # the MDR's bound carried into E*, plus the solver's rounding (1e-12 relative)
        assert err * E_STAR <= res.model_error[0] + 1e-12 * E_STAR, (bps, err, res.model_error)
        out[bps] = (err, abs(res.z_0))
    (e_no, z_no), (e_bp, z_bp) = out[None], out['["1 um"]']
    assert e_no > 1e-7  # without it the kink shows (the spline's ringing, ~1e-5)
    assert e_bp < 1e-2 * e_no, out
    assert z_bp < z_no or z_bp < 1e-18, out  # 1e-18 m: z_0 = 0 to rounding


def test_cli_fit_with_breakpoints(tmp_path, capsys):
    """``hertzmdr fit`` takes the key: the example's curve with the breakpoint, exit code 0,
    the truth within 4 standard errors (a 6e-5 event for a right error)."""
    assert main(["fit", str(EXAMPLES / "fit_worn_tip_curve.csv"), "--scene",
                 str(_example_scene(tmp_path, '["1000 nm"]')), "--sigma", "0.5 nN"]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines()
                if ln.startswith("E_star "))
    value, err = float(line.split()[1]), float(line.split()[2])
    assert abs(value - E_STAR) < 4 * err, line


@pytest.mark.parametrize("bps, key, words", [
    (["1.005 um"], "breakpoints[0]", "is not one of the samples inside the profile"),
    ([0.0], "breakpoints[0]", "strictly between 0 and r_max"),
    (["3 um"], "breakpoints[0]", "strictly between 0 and r_max"),
    (["1 um", "1000 nm"], "breakpoints[1]", "given twice"),
    # a piece of one interval: the MDR's coarse-vs-fine bound cannot see its error there
    (["10 nm"], "breakpoints", "leave one sample interval"),
    (["1 um", "1.01 um"], "breakpoints", "leave one sample interval"),
    ("1 um", "breakpoints", "must be a list of lengths"),
    (["1 N"], "breakpoints[0]", "N"),
    ([float("nan")], "breakpoints[0]", "finite"),
])
def test_bad_breakpoints_are_one_line(tmp_path, capsys, bps, key, words):
    """Through the loader (SceneError) and the command line (exit code 2, one line on
    stderr): the key, its value and what is valid."""
    with pytest.raises(scene.SceneError, match=r"body\[0\] \(body 1\)\." + key.replace(
            "[", r"\[").replace("]", r"\]")) as info:
        scene.load(worn_scene(1e-8, breakpoints=bps))
    assert words in str(info.value), str(info.value)
    if isinstance(bps, list) and bps and isinstance(bps[0], str) and bps[0][0] == "1":
        text = _example_scene(tmp_path, "[" + ", ".join(f'"{b}"' for b in bps) + "]")
        assert main(["fit", str(EXAMPLES / "fit_worn_tip_curve.csv"), "--scene",
                     str(text)]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "breakpoints" in err, err


def test_breakpoints_echo_and_round_trip():
    """The key is echoed in SI with its unit, snapped to the sample it names, and the echoed
    scene runs to the same force."""
    doc = scene.load(worn_scene(1e-7, breakpoints=["1 um"])).run()
    body = doc["scene"]["body"][0]
    assert body["breakpoints"] == [{"value": 1e-6, "unit": "m"}]
