"""The command line's bad-argument paths (issue 12): each ends in one line on stderr naming the
flag and the value, exit 2, nothing written; the good paths still write."""

from __future__ import annotations

import subprocess
import sys

import pytest

from hertzmdr.numeric.cli import main, tour_scenes

SCENE = str(next(p for p in tour_scenes() if p.stem == "problem1_rail_wheel"))


def _one_line(capsys, *words):
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    for w in words:
        assert w in err, (w, err)


def test_out_is_an_existing_file(tmp_path, capsys):
    f = tmp_path / "taken.txt"
    f.write_text("keep me")
    assert main(["run", SCENE, "--out", str(f)]) == 2
    _one_line(capsys, "--out", "is a file")
    assert f.read_text() == "keep me"


def test_out_under_a_file(tmp_path, capsys):
    f = tmp_path / "taken.txt"
    f.write_text("keep me")
    assert main(["run", SCENE, "--out", str(f / "sub" / "dir")]) == 2
    _one_line(capsys, "--out", "is a file, not a folder")


def test_out_under_a_read_only_folder(tmp_path, capsys, monkeypatch):
    """(Root writes into read-only folders, so the permission is denied by monkeypatch.)"""
    from hertzmdr.numeric import cli

    monkeypatch.setattr(cli.os, "access", lambda path, mode: False)
    assert main(["run", SCENE, "--out", str(tmp_path / "res")]) == 2
    _one_line(capsys, "--out", "not writable")
    assert not (tmp_path / "res").exists()


def test_out_non_empty_without_force_computes_nothing(tmp_path, capsys):
    (tmp_path / "x").write_text("")
    assert main(["run", SCENE, "--out", str(tmp_path)]) == 2
    _one_line(capsys, "--out", "not empty", "--force")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x"]


def test_out_missing_parents_are_made(tmp_path):
    out = tmp_path / "a" / "b"
    assert main(["run", SCENE, "--out", str(out)]) == 0
    assert (out / "result.json").exists()


def test_accuracy_only_with_no_match_lists_the_names(tmp_path, capsys):
    out = tmp_path / "acc.md"
    assert main(["accuracy", "--only", "no such quantity", "--out", str(out)]) == 2
    _one_line(capsys, "--only", "no such quantity", "Hertz force F(d)")
    assert not out.exists() and not out.with_suffix(".png").exists()


def test_accuracy_out_is_a_folder(tmp_path, capsys):
    assert main(["accuracy", "--only", "kappa", "--out", str(tmp_path)]) == 2
    _one_line(capsys, "--out", "is a folder")


def test_accuracy_writes_where_out_says(tmp_path, monkeypatch):
    """Not into docs/ of whatever the current folder is."""
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "elsewhere" / "acc.md"
    assert main(["accuracy", "--only", "kappa", "--quick", "--out", str(out)]) == 0
    assert out.exists() and out.with_suffix(".png").exists()
    assert not (tmp_path / "docs").exists()


def test_json_into_a_closed_pipe():
    """`hertzmdr run --json | head -1`: the reader leaves before the output is written (the
    pipe is closed at once); no traceback, no error, also when the output fits the buffer."""
    cmd = [sys.executable, "-m", "hertzmdr.numeric.cli", "run", SCENE, "--json"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as proc:
        proc.stdout.close()  # as head does after its lines
        err = proc.stderr.read().decode()
        proc.wait(timeout=120)
    assert "Traceback" not in err and "BrokenPipe" not in err, err
    assert proc.returncode == 0


def test_out_with_a_field_effect_without_matplotlib(tmp_path, capsys, monkeypatch):
    """A base install (no `plot` extra) asked for figures: one line naming the extra."""
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib -> ImportError
    scene = str(next(p for p in tour_scenes() if p.stem == "problem7b_parabola"))
    assert main(["run", scene, "--out", str(tmp_path / "res")]) == 2
    _one_line(capsys, "--out", "hertzmdr[plot]")
    assert not (tmp_path / "res").exists()


def test_units_outside_the_fast_table_need_no_extra():
    """pint is a core dependency: "2 yard" is read, "5 N" for a radius is refused in words."""
    import importlib.metadata as md

    from hertzmdr.numeric.scene.units import UnitError, to_si

    assert any(r.startswith("pint") for r in md.requires("hertzmdr") if "extra" not in r)
    assert abs(to_si("2 yard", "length") / 1.8288 - 1) < 1e-15  # 1 yd = 0.9144 m exactly
    with pytest.raises(UnitError, match="not a length"):
        to_si("5 N", "length")


def test_version(capsys):
    """`hertzmdr --version` and `hertzmdr.numeric.__version__` say the installed version."""
    import importlib.metadata as md

    import hertzmdr.numeric

    with pytest.raises(SystemExit) as exit_:
        main(["--version"])
    assert exit_.value.code == 0
    assert capsys.readouterr().out.strip() == f"hertzmdr {md.version('hertzmdr')}"
    assert hertzmdr.numeric.__version__ == md.version("hertzmdr")
