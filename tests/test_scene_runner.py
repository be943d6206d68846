"""Tests that kill the surviving mutants of numeric/scene/model.py, runner.py (and units.py) of
the scene's other modules' mutation run (benchmarks/mutation_runs/scene_units+...+scene_schema
.json; notes in benchmarks/mutation_notes_scene_runner.toml).

What they check, each by a route other than the line it guards:
- the refusals a scene can meet after its keys were read (a pair of shapes no kind takes, an
  rtol outside a method's range, an effect that needs an impact or adhesion or that the
  contact lacks, a computation that leaves float64's range): one line naming the scene's
  file, the key, the value and what is valid, compared whole;
- ``model.why``: both bodies (shape and name), the load, the KINDS row, and that adhesion (or a
  ``[load] cycle``) made the contact adhesive;
- adhesion and cycles giving the numbers of Hertz's and JKR's closed forms typed here;
- the run record (the nodes in order, ``model_seconds``) and ``to_json_value``'s types.
Small closed-form scenes only: the whole file takes about a second."""

from __future__ import annotations

import math

import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene.schema import SceneError

# every pytest.approx here has abs=0: its default absolute tolerance (1e-12) would accept any
# error of the small values compared (forces of mN, lengths of nm)

#: steel: E* = E/(1 - nu^2) on a rigid flat (5.26)
STEEL = {"E": 210e9, "nu": 0.3}
E_STAR = 210e9 / (1 - 0.3 ** 2)
BALL = {"name": "ball", "shape": "sphere", "radius": 0.01, **STEEL}
PLATE = {"name": "plate", "shape": "flat", "rigid": True}
TIP = {"name": "tip", "shape": "cone", "angle": "60 deg", **STEEL}
#: the KINDS rows' own words (numeric/scene/kinds/__init__.py), as model.why quotes them
QUADRATIC = "row 'quadratic' of KINDS (two quadratic surfaces (flat, sphere, cylinder, ellipsoid))"
MDR = "row 'mdr' of KINDS (an axisymmetric profile with an MDR closed form on a flat body)"
#: the closed forms report rel_error 1e-14 (CLOSED_FORM_RTOL); a few roundings of float64
CLOSED = 1e-13


def scene_of(bodies, load, effects, **extra) -> dict:
    return {"effects": list(effects), "body": list(bodies), "load": load, **extra}


def refusal(data) -> SceneError:
    with pytest.raises(SceneError) as info:
        scene.load(data).run()
    assert "\n" not in str(info.value)  # one line
    return info.value


# -- adhesion and cycles (model.build) ----------------------------------------------------------

def test_work_of_adhesion_makes_the_contact_adhesive_and_why_says_so():
    """A ball with Delta gamma = 0.05 J/m^2 under a depth load: the contact is the adhesive
    Hertz contact, its pull-off force under force control JKR's -3/2 pi R Delta gamma, and
    model.why (docs/scenes.md: "an [interface] work_of_adhesion adds that the contact was
    made adhesive") says so after the non-adhesive choice."""
    doc = scene.load(scene_of([BALL, PLATE], {"depth": 1e-6}, ["pull_off_force"],
                              interface={"work_of_adhesion": "0.05 J/m^2"})).run()
    model = doc["model"]
    assert model["kind"] == "adhesive hertz"
    jkr = -1.5 * math.pi * 0.01 * 0.05
    assert doc["effects"]["pull_off_force"]["value"]["force_control"] == pytest.approx(
        jkr, rel=CLOSED, abs=0)
    assert model["why"].startswith(f"sphere (ball) and flat (plate) under a depth load -> "
                                   f"{QUADRATIC}: principal radii R1 = 0.01 m, R2 = 0.01 m equal")
    assert model["why"].endswith("; work of adhesion 0.05 J/m^2 > 0 -> made adhesive by the "
                                 f"MDR: {model['description']}")


@pytest.mark.parametrize("control, to, effect", [("depth", 1e-8, "force"),
                                                 ("force", 0.01, "depth")])
def test_a_cycle_without_adhesion_runs_on_the_adhesive_model(control, to, effect):
    """A ``[load] cycle`` makes the contact adhesive even at Delta gamma = 0 (the cycle is an
    adhesive history), where it is Hertz's: at the cycle's end ``to`` the force
    F = 4/3 E* R^(1/2) d^(3/2) (5.21) at d = to, or the depth d = (3 F/(4 E* R^(1/2)))^(2/3).
    model.why names the cycle as the reason, not a work of adhesion "0 > 0"."""
    doc = scene.load(scene_of([BALL, PLATE], {"cycle": {"to": to, "control": control}},
                              [effect])).run()
    R = 0.01
    want = (4 / 3 * E_STAR * math.sqrt(R) * to ** 1.5 if control == "depth"
            else (3 * to / (4 * E_STAR * math.sqrt(R))) ** (2 / 3))
    assert doc["effects"][effect]["value"] == pytest.approx(want, rel=CLOSED, abs=0)
    model = doc["model"]
    assert model["kind"] == "adhesive hertz" and model["work_of_adhesion"] == 0.0
    assert model["why"].startswith(f"sphere (ball) and flat (plate) under a cycle load -> "
                                   f"{QUADRATIC}: ")
    assert model["why"].endswith("; work of adhesion 0 J/m^2 and a [load] cycle -> made "
                                 f"adhesive by the MDR: {model['description']}")
