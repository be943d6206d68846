"""result.json echoes the scene as understood (numeric/scene/echo.py), and reading it back
reproduces the run: every example scene, every value, exactly (the echo's SI numbers are the
floats the reader made of the original strings, and JSON keeps a float's 17 digits)."""

import json
import shutil
from pathlib import Path

import pytest

from hertzmdr.numeric import __version__, cli
from hertzmdr.numeric.scene import SceneError, load

EXAMPLES = sorted((Path(__file__).parents[1] / "examples").glob("*.toml"))


def _values(doc):
    """Every effect's value, method, error and the model: all but the timings."""
    return {"model": doc["model"], "warnings": doc["warnings"],
            "effects": {k: {kk: vv for kk, vv in v.items() if kk != "seconds"}
                        for k, v in doc["effects"].items()}}


def _resolved(spec):
    """The bodies with file names resolved (the echo writes the resolved path)."""
    out = []
    for b in spec.bodies:
        params = {k: (str(((spec.base_dir or Path.cwd()) / v).resolve()) if k == "file" else v)
                  for k, v in b.params.items()}
        out.append((b.name, b.shape, params, b.E, b.nu))
    return out


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_result_json_reproduces_every_example(path):
    """The scene read back from the run's JSON text is the same scene, and running it gives
    every value of every effect exactly (all examples run in about 3 s, twice)."""
    first = load(path)
    doc = json.loads(json.dumps(first.run()))  # what result.json holds
    again = load(doc)
    for f in ("title", "effects", "load", "rtol", "elliptic", "interface"):
        assert getattr(again.spec, f) == getattr(first.spec, f), f
    assert _resolved(again.spec) == _resolved(first.spec)
    assert _values(json.loads(json.dumps(again.run()))) == _values(doc)


def test_hertzmdr_run_result_json(tmp_path, capsys):
    """The command: --out writes result.json; `hertzmdr run result.json --json` prints the
    same values."""
    scene = Path(__file__).parents[1] / "examples" / "problem1_rail_wheel.toml"
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "out")]) == 0
    first = json.loads((tmp_path / "out" / "result.json").read_text())
    capsys.readouterr()
    assert cli.main(["run", str(tmp_path / "out" / "result.json"), "--json"]) == 0
    again = json.loads(capsys.readouterr().out)
    assert _values(again) == _values(first)
    assert again["scene"] == first["scene"]


def _leaves(x, path=()):
    if isinstance(x, dict) and set(x) == {"value", "unit"}:
        yield path, x
    elif isinstance(x, dict):
        for k, v in x.items():
            yield from _leaves(v, (*path, k))
    elif isinstance(x, list):
        for j, v in enumerate(x):
            yield from _leaves(v, (*path, j))
    else:
        yield path, x


def test_echo_names_every_input_with_its_si_unit():
    """Problem 1's inputs in SI with their units, the version, and no bare number left."""
    doc = load(Path(__file__).parents[1] / "examples" / "problem1_rail_wheel.toml").run()
    sc = doc["scene"]
    assert doc["hertzmdr_version"] == __version__
    wheel, rail = sc["body"]
    assert wheel["radius"] == {"value": 0.5, "unit": "m"}
    assert wheel["E"] == {"value": 210e9, "unit": "Pa"}
    assert wheel["nu"] == {"value": 0.3, "unit": "1"}
    assert rail["axis"]["unit"] == "rad" and rail["axis"]["value"] == pytest.approx(1.5707963)
    assert sc["load"]["force"] == {"value": 1e5, "unit": "N"}
    for path, leaf in _leaves(sc):
        assert not isinstance(leaf, (int, float)) or isinstance(leaf, bool), path


def test_echo_units_of_every_kind_of_key():
    """Sweeps, the interface, the power law's coefficient (its unit from the shape's Key)."""
    doc = load({"effects": ["force"],
                "body": [{"shape": "power_law", "coefficient": 3.0, "exponent": 1.5,
                          "rigid": True}, {"shape": "flat", "E": "1 GPa", "nu": 0.5}],
                "load": {"depth": {"from": 0, "to": "2 um", "points": 3}},
                "interface": {"friction": 0.4}}).run()
    sc = doc["scene"]
    assert sc["body"][0]["coefficient"] == {"value": 3.0, "unit": "m^(1-n)"}
    assert sc["load"]["depth"] == {"from": {"value": 0, "unit": "m"},
                                   "to": {"value": 2e-6, "unit": "m"},
                                   "points": {"value": 3, "unit": "1"}}
    assert sc["interface"]["friction"] == {"value": 0.4, "unit": "1"}
    assert sc["title"] == "scene"


def test_model_says_why():
    """The model's choice in words: the principal radii and what they made."""
    crossed = load(Path(__file__).parents[1] / "examples" / "problem1_rail_wheel.toml").run()
    assert "equal" in crossed["model"]["why"] and "circular Hertz" in crossed["model"]["why"]
    sphere = load({"effects": ["force"], "body": [
        {"shape": "sphere", "radius": "1 mm", "rigid": True},
        {"shape": "flat", "E": "1 GPa", "nu": 0.3}], "load": {"depth": "1 um"}}).run()
    assert "exact_sphere" in sphere["model"]["why"]
    ellipse = load({"effects": ["force"], "body": [
        {"shape": "ellipsoid", "radii": ["1 mm", "4 mm"], "rigid": True},
        {"shape": "flat", "E": "1 GPa", "nu": 0.3}], "load": {"depth": "1 um"}}).run()
    assert "R1/R2 = 0.25" in ellipse["model"]["why"]


def test_a_file_changed_since_the_run_is_refused(tmp_path):
    """A sampled profile's file: echoed resolved, with its SHA-256; changed, it is refused."""
    (tmp_path / "tip.csv").write_text("0, 0\n1, 1\n2, 4\n3, 9\n")
    (tmp_path / "s.toml").write_text(
        'effects = ["force"]\n[[body]]\nshape = "profile"\nfile = "tip.csv"\nunit = "um"\n'
        'rigid = true\n[[body]]\nshape = "flat"\nE = "1 GPa"\nnu = 0.3\n[load]\ndepth = "1 um"\n')
    doc = load(tmp_path / "s.toml").run()
    body = doc["scene"]["body"][0]
    assert body["file"] == str((tmp_path / "tip.csv").resolve()) and body["unit"] == "um"
    assert doc["files"][0]["given"] == "tip.csv"
    moved = tmp_path / "elsewhere"
    moved.mkdir()
    (moved / "result.json").write_text(json.dumps(doc))
    again = load(moved / "result.json").run()  # from another folder: the path is absolute
    assert again["effects"]["force"]["value"] == doc["effects"]["force"]["value"]
    shutil.copy(tmp_path / "tip.csv", tmp_path / "old.csv")
    (tmp_path / "tip.csv").write_text("0, 0\n1, 1\n2, 4\n3, 9.5\n")
    with pytest.raises(SceneError, match="changed since the run"):
        load(moved / "result.json")


def test_a_json_without_a_scene_is_refused(tmp_path):
    (tmp_path / "r.json").write_text('{"title": "x"}')
    with pytest.raises(SceneError, match="has none"):
        load(tmp_path / "r.json")
    (tmp_path / "bad.json").write_text("{")
    with pytest.raises(SceneError, match="JSON syntax"):
        load(tmp_path / "bad.json")


def test_a_study_echoes_its_sweep():
    """A study's swept key is echoed as its sweep (not the corner its scene was read at), its
    ends in SI with the key's unit and its points a count; read back, the same study."""
    path = Path(__file__).parents[1] / "examples" / "study_bearing_load_radius.toml"
    doc = load(path).run()
    radius = doc["scene"]["body"][0]["radius"]
    assert radius["from"] == {"value": 0.004, "unit": "m"}
    assert radius["points"] == {"value": 5, "unit": "1"}
    again = load(json.loads(json.dumps(doc)))
    assert again.spec.study.shape == load(path).spec.study.shape
