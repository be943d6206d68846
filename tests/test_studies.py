"""Parameter studies (issue 13, docs/scenes.md "Studies"): a sweep on any numeric key, one or
two of them; every point agrees with its own single run; only the requested effects are
computed; results.csv holds the JSON's numbers; a bad sweep is one line, exit 2, nothing
written."""

from __future__ import annotations

import contextlib
import copy
import csv
import io
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric.cli import main
from hertzmdr.numeric.scene.kinds.elliptic import EllipticContact
from hertzmdr.numeric.scene.kinds.hertz import HertzContact

EXAMPLES = Path(__file__).parents[1] / "examples"
BALL = {"name": "ball", "shape": "sphere", "radius": "5 mm", "E": "210 GPa", "nu": 0.3}
PLATE = {"name": "plate", "shape": "flat", "E": "70 GPa", "nu": 0.33}
HERTZ = ["depth", "force", "contact_radius", "max_pressure", "mean_pressure", "stiffness",
         "elastic_energy", "effective_modulus", "effective_radius", "principal_radii"]


def hertz_study(effects=("force", "contact_radius", "max_pressure"), **sweeps) -> dict:
    """A ball on a plate under 10 N, with sweeps {key: sweep} on the ball, the plate or the
    load."""
    ball, plate, load = dict(BALL), dict(PLATE), {"force": "10 N"}
    for key, sweep in sweeps.items():
        where, name = key.split("_", 1)
        {"ball": ball, "plate": plate, "load": load}[where][name] = sweep
    return {"title": "study", "effects": list(effects), "body": [ball, plate], "load": load}


def run_cli(*args) -> tuple[int, str, str]:
    so, se = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(so), contextlib.redirect_stderr(se):
        rc = main(["run", *map(str, args)])
    return rc, so.getvalue(), se.getvalue()


def write(tmp_path, doc: dict) -> Path:
    from test_fuzz_scenes import toml_text

    path = tmp_path / "scene.toml"
    path.write_text(toml_text(doc), encoding="utf-8")
    return path


def single(doc: dict, values: dict) -> dict:
    """The scene ``doc`` with each swept key set to one value (SI): a single run."""
    one = copy.deepcopy(doc)
    for path, v in values.items():
        node = one
        for p in path[:-1]:
            node = node[p]
        node[path[-1]] = v
    return scene.load(one).run()


def per_point(study_doc: dict, name: str, k: int):
    v = study_doc["effects"][name]["value"]
    return {key: x[k] for key, x in v.items()} if isinstance(v, dict) else v[k]


def as_single(v):
    """A single run's value as a study keeps it per point (arrays of one load as numbers)."""
    if isinstance(v, dict):
        return {k: as_single(x) for k, x in v.items()}
    if isinstance(v, list) and all(isinstance(x, list) and len(x) == 1 for x in v):
        return [x[0] for x in v]
    if isinstance(v, list) and len(v) == 1:
        return v[0]
    return v


# -- agreement with single runs ------------------------------------------------------------------
def test_array_study_equals_single_runs_point_by_point():
    """A radius x force map of a Hertz contact, evaluated as arrays: at every point each
    closed form equals the single run at that point's radius and force, exactly (the same
    generated functions on the same floats, elementwise)."""
    doc = hertz_study(HERTZ + ["max_shear", "max_orthogonal_shear"],
                      ball_radius={"from": "1 mm", "to": "10 mm", "points": 4,
                                   "spacing": "log"},
                      load_force={"from": "1 N", "to": "100 N", "points": 3})
    record, _, out = scene.load(doc).run_full()
    assert record.route == "arrays"
    pts = out["study"]["points"]
    for k in range(12):
        R, F = pts["body[0] (ball).radius"][k], pts["load.force"][k]
        ref = single(doc, {("body", 0, "radius"): R, ("load", "force"): F})
        for name in doc["effects"]:
            assert per_point(out, name, k) == as_single(ref["effects"][name]["value"]), \
                (name, k)


def test_per_point_study_equals_single_runs():
    """The crossing-angle example (exact elliptical contacts, run point by point) and the
    Poisson's ratio example (a stress maximum searched per nu): each point is its own run."""
    for stem, path in (("study_crossing_angle", ("body", 1, "axis")),
                       ("study_poisson_ratio", ("body", 1, "nu"))):
        raw = tomllib.loads((EXAMPLES / f"{stem}.toml").read_text())
        record, _, out = scene.load(EXAMPLES / f"{stem}.toml").run_full()
        assert record.route == "per point"
        (key,) = out["study"]["points"]
        for k in (0, len(out["study"]["points"][key]) - 1):
            ref = single(raw, {path: out["study"]["points"][key][k]})
            for name in raw["effects"]:
                assert per_point(out, name, k) == as_single(ref["effects"][name]["value"])


def test_load_sweep_is_unchanged_and_names_its_load():
    """A load sweep alone keeps its run (the same document as before) and gains the study
    block with the swept load and its unit."""
    from hertzmdr.numeric.scene.runner import document, run

    sc = scene.load(EXAMPLES / "problem7d_power_law.toml")
    _, _, doc = sc.run_full()
    record, results = run(sc.spec)
    before = document(record, results)
    study = doc.pop("study")
    for name in before["effects"]:  # identical values (times differ)
        assert doc["effects"][name]["value"] == before["effects"][name]["value"]
    assert study["axes"][0]["key"] == "load.depth" and study["axes"][0]["unit"] == "m"
    assert study["points"]["load.depth"] == list(sc.spec.load.values)


# -- only what was asked -------------------------------------------------------------------------
@pytest.mark.parametrize("study", ["arrays", "per point"])
def test_a_study_computes_only_the_requested_effects(monkeypatch, study):
    """A spy on every effect method of the Hertz and elliptical kinds: a study calls the
    requested ones only (and no stress node unless a stress effect is asked for)."""
    calls = []
    for cls in (HertzContact, EllipticContact):
        for name in [n for n in dir(cls) if n.startswith(("effect_", "node_"))]:
            method = getattr(cls, name)

            def spy(self, *args, _m=method, _n=name):
                calls.append(_n)
                return _m(self, *args)

            monkeypatch.setattr(cls, name, spy)
    if study == "arrays":
        doc = hertz_study(["force", "max_pressure"],
                          ball_radius={"from": "1 mm", "to": "2 mm", "points": 5})
    else:
        doc = hertz_study(["semi_axes"], plate_radii=["20 mm", "-30 mm"])
        doc["body"][1]["shape"] = "ellipsoid"
        doc["body"][0]["radius"] = {"from": "1 mm", "to": "2 mm", "points": 5}
    record, _, _ = scene.load(doc).run_full()
    assert record.route == study
    effects = {c.removeprefix("effect_") for c in calls if c.startswith("effect_")}
    assert effects == set(doc["effects"])
    assert {c for c in calls if c.startswith("node_")} <= {"node_state"}


# -- output ----------------------------------------------------------------------------------
def test_csv_round_trip(tmp_path):
    """results.csv (read back with the csv module and with numpy) holds the JSON's numbers
    exactly, one row per point, the unit in each header; --csv prints the same table."""
    doc = hertz_study(["force", "semi_axes", "max_pressure"],
                      ball_radius={"from": "4 mm", "to": "6 mm", "points": 3},
                      load_force={"from": "0.5 kN", "to": "2 kN", "points": 2})
    doc["body"][1] |= {"shape": "ellipsoid", "radii": ["25 mm", "-6.3 mm"]}  # a grooved race
    path = write(tmp_path, doc)
    rc, _, err = run_cli(path, "--out", tmp_path / "out")
    assert rc == 0, err
    doc = json.loads((tmp_path / "out" / "result.json").read_text())
    with open(tmp_path / "out" / "results.csv", newline="") as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]
    assert head == ["body[0] (ball).radius [m]", "load.force [N]", "force [N]",
                    "semi_axes[0] [m]", "semi_axes[1] [m]", "max_pressure [Pa]"]
    assert len(body) == 6
    cols = {h: [float(r[j]) for r in body] for j, h in enumerate(head)}
    e = doc["effects"]
    assert cols["body[0] (ball).radius [m]"] == doc["study"]["points"]["body[0] (ball).radius"]
    assert cols["force [N]"] == e["force"]["value"]
    assert cols["semi_axes[1] [m]"] == [v[1] for v in e["semi_axes"]["value"]]
    table = np.genfromtxt(tmp_path / "out" / "results.csv", delimiter=",", skip_header=1)
    assert table.shape == (6, 6) and table[:, 5].tolist() == e["max_pressure"]["value"]
    rc, out, _ = run_cli(path, "--csv")
    assert rc == 0 and out == (tmp_path / "out" / "results.csv").read_text()
    pngs = {p.name for p in (tmp_path / "out").glob("*.png")}
    assert pngs == {"force.png", "semi_axes_0.png", "semi_axes_1.png", "max_pressure.png"}


def test_csv_columns_of_a_table_of_numbers():
    """An effect with several numbers (max_shear: value and depth) gives a column each, with
    its own unit, holding the JSON's numbers."""
    from hertzmdr.numeric.scene.table import csv_text

    doc = scene.load(hertz_study(["max_shear"], ball_radius={"from": "1 mm", "to": "2 mm",
                                                             "points": 3})).run()
    head, *rows = list(csv.reader(io.StringIO(csv_text(doc))))
    assert head == ["body[0] (ball).radius [m]", "max_shear.value [Pa]", "max_shear.depth [m]"]
    assert [float(r[2]) for r in rows] == doc["effects"]["max_shear"]["value"]["depth"]


def test_csv_of_a_single_scene_and_of_a_load_sweep(tmp_path):
    rc, out, _ = run_cli(EXAMPLES / "problem1_rail_wheel.toml", "--csv")
    head, row = list(csv.reader(io.StringIO(out)))
    ref = scene.load(EXAMPLES / "problem1_rail_wheel.toml").run()["effects"]
    assert rc == 0 and head == [f"{n} [{e['unit']}]" for n, e in ref.items()]
    assert [float(x) for x in row] == [e["value"] for e in ref.values()]
    rc, out, _ = run_cli(EXAMPLES / "study_afm_force_gel.toml", "--csv")
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0][0] == "load.force [N]" and len(rows) == 22
    rc, _, err = run_cli(EXAMPLES / "problem1_rail_wheel.toml", "--csv", "--json")
    assert rc == 2 and err.count("\n") == 1 and "--csv" in err


def test_log_spacing_and_the_map_shape():
    doc = hertz_study(ball_radius={"from": "1 mm", "to": "1 m", "points": 4, "spacing": "log"},
                      load_force={"from": "1 N", "to": "2 N", "points": 3})
    out = scene.load(doc).run()
    radius = out["study"]["axes"][0]["values"]
    # evenly in log: 1 mm, 1 cm, 10 cm, 1 m, the ends exact, the ratios 10 to rounding
    # (exp of a linspace of logs: a few ulps)
    assert radius[0] == 1e-3 and radius[-1] == 1.0
    assert np.allclose(np.diff(np.log10(radius)), 1.0, rtol=0, atol=1e-14)
    assert out["study"]["shape"] == [4, 3] and len(out["effects"]["force"]["value"]) == 12
    # rows in the order of the CSV: the first key the slower
    assert out["study"]["points"]["body[0] (ball).radius"][:4] == [1e-3] * 3 + [radius[1]]
    assert out["study"]["points"]["load.force"][:4] == [1.0, 1.5, 2.0, 1.0]


def test_fields_are_kept_per_point_and_refused_beyond_the_limit():
    from hertzmdr.numeric.scene.study import MAX_FIELD_POINTS

    doc = hertz_study(["pressure_profile", "force"],
                      plate_E={"from": "10 GPa", "to": "70 GPa", "points": 3})
    out = scene.load(doc).run()
    fields = out["effects"]["pressure_profile"]["value"]
    assert len(fields) == 3 and all(len(f["p"]) == len(f["r"]) > 100 for f in fields)
    assert fields[0]["p"][0] < fields[-1]["p"][0]  # a stiffer plate: a higher pressure
    doc["body"][1]["E"]["points"] = MAX_FIELD_POINTS + 1
    with pytest.raises(scene.SceneError, match=f"up to {MAX_FIELD_POINTS} points"):
        scene.load(doc)


def test_a_point_by_point_study_reports_progress():
    doc = hertz_study(["pressure_profile"], ball_radius={"from": "1 mm", "to": "2 mm",
                                                         "points": 4})
    seen = []
    scene.load(doc).run_full(progress=lambda done, total: seen.append((done, total)))
    assert seen == [(1, 4), (2, 4), (3, 4), (4, 4)]


# -- bad studies ---------------------------------------------------------------------------------
SWEEP = {"from": "1 mm", "to": "2 mm", "points": 3}
BAD = [
    ("ball_radius", {**SWEEP, "points": 1}, "body[0] (ball).radius.points"),
    ("ball_radius", {**SWEEP, "spacing": "cubic"}, "body[0] (ball).radius.spacing"),
    ("ball_radius", {**SWEEP, "step": 1}, "body[0] (ball).radius.step"),
    ("ball_radius", {"from": "1 mm", "points": 3}, "body[0] (ball).radius.to"),
    ("ball_radius", {**SWEEP, "from": "3 mm"}, "body[0] (ball).radius"),
    ("ball_radius", {**SWEEP, "to": "2 N"}, "body[0] (ball).radius.to"),
    ("ball_radius", {**SWEEP, "from": "-1 mm"}, "body[0] (ball).radius"),  # crosses 0
    ("ball_nu", {"from": 0.3, "to": 0.6, "points": 3}, "body[0] (ball).nu"),
    ("ball_nu", {"from": "0.1", "to": 0.4, "points": 3}, "body[0] (ball).nu.from"),
    ("ball_E", {"from": 0, "to": "1 GPa", "points": 3, "spacing": "log"},
     "body[0] (ball).E.spacing"),
    ("load_force", {"from": "1 N", "to": "2 N", "points": 2, "spacing": "log"}, None),
]


@pytest.mark.parametrize("key, sweep, named", BAD, ids=lambda v: str(v)[:30])
def test_bad_sweeps_are_one_line_exit_2_nothing_written(tmp_path, key, sweep, named):
    doc = hertz_study(**{key: sweep})
    if named is None:  # a third sweep, on top of two good ones
        doc["body"][0]["radius"], doc["body"][1]["E"] = dict(SWEEP), {
            "from": "1 GPa", "to": "2 GPa", "points": 2}
        named = "load.force"
    path = write(tmp_path, doc)
    rc, out, err = run_cli(path, "--out", tmp_path / "out")
    assert rc == 2 and out == "" and err.count("\n") == 1, err
    assert err.startswith(f"hertzmdr: {path}: {named}: "), err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("stem", ["study_afm_force_gel", "study_crossing_angle"])
def test_a_study_example_writes_its_csv_and_plots(tmp_path, stem):
    """Two users of issue 13 (a load sweep, and a study of another key): one `hertzmdr run
    ... --out DIR` gives result.json, results.csv (its first column the swept key, a row per
    point) and a PNG per effect column (the other examples: test_every_study_example_csv)."""
    out = tmp_path / "out"
    rc, _, err = run_cli(EXAMPLES / f"{stem}.toml", "--out", out)
    assert rc == 0, err
    doc = json.loads((out / "result.json").read_text())
    lines = (out / "results.csv").read_text().splitlines()
    assert lines[0].startswith(doc["study"]["axes"][0]["key"] + " ["), lines[0]
    assert len(lines) - 1 == math.prod(doc["study"]["shape"])
    n_effect_cols = len(lines[0].split(",")) - len(doc["study"]["axes"])
    assert len(list(out.glob("*.png"))) == n_effect_cols


def test_every_study_example_csv():
    """Every study example: --csv has a column per swept key and a row per point."""
    for path in sorted(EXAMPLES.glob("study_*.toml")):
        rc, out, err = run_cli(path, "--csv")
        assert rc == 0, err
        rows = list(csv.reader(io.StringIO(out)))
        doc = scene.load(path).spec.study
        assert [h for h in rows[0][:len(doc.axes)]] == [a.column for a in doc.axes]
        assert len(rows) - 1 == doc.size


def test_out_draws_a_studys_fields_at_each_point(tmp_path):
    """--out draws a field of a study at each of its points, named by the row of results.csv,
    and the text table lists the points."""
    doc = hertz_study(["pressure_profile", "force"],
                      plate_E={"from": "10 GPa", "to": "70 GPa", "points": 3})
    path = write(tmp_path, doc)
    rc, out, err = run_cli(path, "--out", tmp_path / "out")
    assert rc == 0, err
    names = {p.name for p in (tmp_path / "out").glob("*.png")}
    assert names == {"pressure_profile_0.png", "pressure_profile_1.png",
                     "pressure_profile_2.png", "force.png"}
    assert "study: body[1] (plate).E from 10 GPa to 70 GPa, 3 points (linear)" in out
    assert "pressure_profile: " in out and "(a field per point: result.json)" in out
