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
import tomllib

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.scene import runner
from hertzmdr.numeric.scene.runner import to_json_value
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


# -- model.why (model.why_chosen) ---------------------------------------------------------------

def test_why_names_both_bodies_the_load_the_row_and_the_choice():
    """A ball on a plate: both shapes with their names, in the scene's order, the load, the
    row and the quadratic builder's choice (after ': ')."""
    why = scene.load(scene_of([PLATE, BALL], {"force": 1.0}, ["depth"])).run()["model"]["why"]
    assert why.startswith(f"flat (plate) and sphere (ball) under a force load -> {QUADRATIC}: "
                          "principal radii R1 = 0.01 m, R2 = 0.01 m equal")


def test_why_without_a_choice_ends_with_the_contact():
    """A cone's builder makes no choice (one closed form): the why ends with ' -> ' and the
    contact's description, not with an empty choice."""
    model = scene.load(scene_of([TIP, PLATE], {"depth": 1e-6}, ["force"])).run()["model"]
    assert model["why"] == (f"cone (tip) and flat (plate) under a depth load -> {MDR} -> "
                            f"{model['description']}")
    assert model["description"] == "rigid cone (5.38)-(5.40)"


# -- refusals ----------------------------------------------------------------------------------

def write(tmp_path, bodies, load, effects, **tables) -> str:
    """The scene as a TOML file (its path is the 'where' of every SceneError)."""
    def value(v):
        return f'"{v}"' if isinstance(v, str) else ("true" if v is True else repr(v))

    lines = [f"effects = [{', '.join(value(e) for e in effects)}]"]
    for name, table in tables.items():
        lines += [f"[{name}]", *(f"{k} = {value(v)}" for k, v in table.items())]
    for b in bodies:
        lines += ["[[body]]", *(f"{k} = {value(v)}" for k, v in b.items())]
    lines += ["[load]", *(f"{k} = {value(v)}" for k, v in load.items())]
    path = tmp_path / "s.toml"
    path.write_text("\n".join(lines) + "\n")
    tomllib.loads(path.read_text())  # valid TOML
    return str(path)


def test_a_pair_no_kind_takes_is_refused_naming_both_shapes_and_their_kinds(tmp_path):
    """A sphere and a cone: no KINDS row takes both and neither is flat. The message names the
    file, the key body, both shapes (sorted), the rule, and the kinds each shape takes part in
    (SHAPES' own lists: a sphere in 'quadratic' and 'impact', a cone in 'mdr'), in the
    scene's order."""
    path = write(tmp_path, [BALL, TIP], {"depth": 1e-6}, ["force"])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "body")
    assert str(exc) == (f"{path}: body: this combination of shapes (cone and sphere) is not "
                        "supported: two bodies make a contact when both take part in the same "
                        "kind, or one is flat (kinds: sphere: quadratic, impact; cone: mdr)")


def test_an_rtol_outside_the_methods_range_is_refused_with_the_range(tmp_path):
    """rtol = 1e-17 is below what a closed form delivers (CLOSED_FORM_RTOL's range
    [1e-14, 1]): the file, accuracy.rtol, the value and the range."""
    path = write(tmp_path, [TIP, PLATE], {"depth": 1e-6}, ["force"], accuracy={"rtol": 1e-17})
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "accuracy.rtol")
    assert str(exc) == (f"{path}: accuracy.rtol: 1e-17 is outside the range closed forms can "
                        "deliver: [1e-14, 1]")


def test_an_impact_effect_without_an_impact_says_how_to_give_one(tmp_path):
    path = write(tmp_path, [BALL, PLATE], {"depth": 1e-6}, ["force", "contact_time"])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "effects")
    assert str(exc) == (f"{path}: effects: effect 'contact_time' needs an impact: give "
                        "[load.impact] with velocity and mass or density")


def test_an_adhesive_effect_without_adhesion_says_how_to_give_it(tmp_path):
    """pull_off_force after an effect that applies (force: each effect is checked, not only
    the first), on a non-adhesive scene: the message says which key to give, its unit and
    its valid range (> 0), not the generic 'has no pull off force'."""
    path = write(tmp_path, [BALL, PLATE], {"depth": 1e-6}, ["force", "pull_off_force"])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "effects")
    assert str(exc) == (f"{path}: effects: effect 'pull_off_force' does not apply to this "
                        "scene: it needs adhesion: give [interface] work_of_adhesion = "
                        '"... J/m^2" (> 0)')


def test_an_effect_the_contact_lacks_is_refused_in_words():
    """edge_displacement (a flat punch's) on a Hertz contact, which has no why_not for it:
    the contact's description and the effect's name in words (underscores as spaces)."""
    exc = refusal(scene_of([BALL, PLATE], {"depth": 1e-6}, ["force", "edge_displacement"]))
    assert (exc.where, exc.key) == ("<scene>", "effects")
    assert str(exc) == ("<scene>: effects: effect 'edge_displacement' does not apply to this "
                        "scene: circular Hertz contact (effective sphere on an elastic "
                        "half-space) has no edge displacement")


# -- float64's range: np.errstate turns overflow, 0/0 and x/0 into a refusal -------------------

FAR = ("a load, size or modulus of the scene is far outside what the contact can represent")


@pytest.mark.parametrize("body, load, effect, what", [
    # a flat punch pressed 1e300 m: F = 2 a E* d overflows
    ({"name": "punch", "shape": "flat_punch", "radius": 1e-3, **STEEL}, {"depth": 1e300},
     "force", "overflow"),
    # a cone at 1e-300 m: a^2 and F underflow to 0, F/(pi a^2) is 0/0
    (TIP, {"depth": 1e-300}, "mean_pressure", "invalid value"),
    # a cone under 1e-320 N (a subnormal force): a^2 underflows to 0, F/(pi a^2) is F/0
    (TIP, {"force": 1e-320}, "mean_pressure", "divide by zero"),
])
def test_an_effect_leaving_float64_is_refused_not_nan(tmp_path, body, load, effect, what):
    """Each of numpy's three floating-point errors during an effect is a refusal naming the
    file, the effects key, the effect and numpy's own words, instead of a warning and an
    inf or NaN in the result."""
    path = write(tmp_path, [body, PLATE], load, [effect])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "effects")
    head = f"{path}: effects: {effect!r} at this load: the computation leaves float64's range ("
    assert str(exc).startswith(head) and str(exc).endswith(f"): {FAR}")
    assert what in str(exc)


@pytest.mark.parametrize("radius, what", [(1e160, "overflow"), (1e-300, "divide by zero")])
def test_a_model_leaving_float64_is_refused(tmp_path, radius, what):
    """A ball of radius 1e160 m or 1e-300 m: building the contact leaves float64 (an
    overflow, a division by zero); the refusal names the file and the bodies."""
    path = write(tmp_path, [{**BALL, "radius": radius}, PLATE], {"depth": 1e-6}, ["force"])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "body")
    assert str(exc).startswith(f"{path}: body: the computation leaves float64's range (")
    assert str(exc).endswith(f"): {FAR}") and what in str(exc)


def test_a_builder_making_nan_is_refused(monkeypatch):
    """0/0 while the contact is built (no scene input found that makes a builder's numpy
    arithmetic invalid without first overflowing or dividing by zero, so a builder that does
    stands in): a refusal, not a NaN contact."""
    def build(spec):
        return np.zeros(1) / np.zeros(1)

    monkeypatch.setattr(runner, "build", build)
    exc = refusal(scene_of([BALL, PLATE], {"depth": 1e-6}, ["force"]))
    assert (exc.where, exc.key) == ("<scene>", "body")
    assert str(exc) == ("<scene>: body: the computation leaves float64's range (invalid value "
                        f"encountered in divide): {FAR}")


# -- the run record and the JSON values ---------------------------------------------------------

def test_the_run_records_its_nodes_in_order_and_its_time():
    """The model first, then each node once (state, which both effects need) and each effect;
    model_seconds is the whole run's time: a float at least the effects' times together."""
    record, results, _ = scene.load(scene_of([BALL, PLATE], {"depth": 1e-6},
                                             ["force", "max_pressure"])).run_full()
    assert record.evaluated == ["model", "state", "force", "max_pressure"]
    assert type(record.model_seconds) is float
    assert record.model_seconds >= sum(r.seconds for r in results.values()) > 0


@pytest.mark.parametrize("value, want", [
    (np.int64(32), 32), (np.uint8(7), 7),                   # a count stays an integer
    (np.float64(2.5), 2.5), (np.float32(0.5), 0.5),         # numpy floats to Python floats
    (np.array([32]), 32), (np.array([2.5]), 2.5),           # a one-element vector: its value
    (np.array(3), 3), (np.array(0.25), 0.25),               # 0-d arrays
    (np.array([1, 2]), [1, 2]), (np.array([[0.5], [1.5]]), [[0.5], [1.5]]),
    ({"n": np.int32(4), "x": [np.float64(1.5), (np.uint16(2),)]}, {"n": 4, "x": [1.5, [2]]}),
])
def test_json_values_are_python_numbers_of_the_right_type(value, want):
    """The exact Python types: json prints 32, not 32.0, for an int, and a numpy float (a
    float subclass) is not what the document should hold."""
    got = to_json_value(value)

    def types(v):
        if isinstance(v, dict):
            return {k: types(x) for k, x in v.items()}
        if isinstance(v, list):
            return [types(x) for x in v]
        return type(v)

    assert got == want
    assert types(got) == types(want)


def test_json_values_that_are_no_numbers_pass_through():
    """A 0-d value that is neither an integer nor a float (a bool, a text) is itself."""
    flag = np.bool_(True)
    assert to_json_value(flag) is flag
    assert to_json_value("hertz") == "hertz"


def test_two_rigid_bodies_are_refused_naming_what_one_needs(tmp_path):
    """Materials.of: with no elastic body there is no E* (5.26); the message says what one
    body must have, word for word."""
    path = write(tmp_path, [{**PLATE, "name": "a"}, {**PLATE, "name": "b"}], {"depth": 1e-6},
                 ["force"])
    exc = refusal(path)
    assert (exc.where, exc.key) == (path, "body")
    assert str(exc) == f"{path}: body: both bodies are rigid: at least one must have E and nu"
    # the scene reader refuses it first; the Python API (Materials.of) in the same words
    from hertzmdr.numeric.scene.materials import Material, Materials

    with pytest.raises(ValueError) as info:
        Materials.of(Material("a", None, None), Material("b", None, None))
    assert str(info.value) == "both bodies are rigid: at least one must have E and nu"
