"""The top-level package (issue 12): ``hertzmdr.__version__``, its docstring, ``python -m
hertzmdr`` (the same command as the ``hertzmdr`` script), and a non-editable wheel that holds
and runs the same package."""

from __future__ import annotations

import importlib.metadata as md
import importlib.util
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from oracle import FULL

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = Path(sys.executable).with_name("hertzmdr")


def _run(*argv, cwd, env=None):
    return subprocess.run(list(argv), capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=300)


def test_version_is_the_installed_one():
    import hertzmdr
    import hertzmdr.numeric

    assert hertzmdr.__version__ == md.version("hertzmdr") == hertzmdr.numeric.__version__
    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", hertzmdr.__version__)


def test_docstring_says_what_is_where():
    """Every ``hertzmdr.x.y`` the docstring names is a module that exists."""
    import hertzmdr

    doc = hertzmdr.__doc__
    for words in ("hertzmdr.derive", "hertzmdr.numeric", "python -m hertzmdr", "SI units"):
        assert words in doc, words
    named = set(re.findall(r"``(hertzmdr(?:\.\w+)+)``", doc))
    assert {"hertzmdr.derive", "hertzmdr.numeric", "hertzmdr.numeric.scene"} <= named
    for name in named:
        assert importlib.util.find_spec(name) is not None, name
    for short in re.findall(r"``(\w+)``", doc):  # the numeric modules it lists by name
        if short not in ("run", "effects", "accuracy", "hertzmdr", "Relation"):
            assert importlib.util.find_spec(f"hertzmdr.numeric.{short}") is not None, short


@pytest.mark.parametrize("argv", [["--version"], ["effects"], ["run", "missing.toml"], []])
def test_python_m_is_the_script(tmp_path, argv):
    """``python -m hertzmdr ARGS`` prints and exits as ``hertzmdr ARGS`` does (good, bad and
    usage-error paths)."""
    mod = _run(sys.executable, "-m", "hertzmdr", *argv, cwd=tmp_path)
    script = _run(str(SCRIPT), *argv, cwd=tmp_path)
    assert (mod.returncode, mod.stdout, mod.stderr) == \
        (script.returncode, script.stdout, script.stderr)
    assert mod.returncode == (0 if argv in (["--version"], ["effects"]) else 2)
    assert "Traceback" not in mod.stderr
    if argv == ["--version"]:
        assert mod.stdout.strip() == f"hertzmdr {md.version('hertzmdr')}"


@pytest.mark.sweep
def test_wheel_install(tmp_path):
    """A non-editable install: ``pip wheel .`` holds hertzmdr/__init__.py, __main__.py,
    derive/, numeric/ and the tour (and no pkg/ folder); installed on its own (``--target``,
    its dependencies from this environment) it is the package imported, ``python -m hertzmdr``
    runs a tour scene from it and the script entry point is declared. With HERTZMDR_SWEEP=full
    also in a fresh virtual environment with its dependencies from the index (about a
    minute)."""
    pip = [sys.executable, "-m", "pip"]
    built = _run(*pip, "wheel", "--no-deps", "-q", "-w", str(tmp_path / "wheel"), str(ROOT),
                 cwd=tmp_path)
    assert built.returncode == 0, built.stderr
    (wheel,) = (tmp_path / "wheel").glob("hertzmdr-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    for name in ("hertzmdr/__init__.py", "hertzmdr/__main__.py", "hertzmdr/derive/hertz.py",
                 "hertzmdr/numeric/_generated.py", "hertzmdr/numeric/cli.py",
                 "hertzmdr/numeric/c/__init__.py", "hertzmdr/numeric/c/hertzmdr_laws.h",
                 "hertzmdr/numeric/tour/problem1_rail_wheel.toml",
                 "hertzmdr/numeric/tour/paraboloid_tip.csv"):
        assert name in names, name
    assert not [n for n in names if n.startswith("pkg/")]
    entry = zipfile.ZipFile(wheel).read(
        f"hertzmdr-{md.version('hertzmdr')}.dist-info/entry_points.txt").decode()
    assert "hertzmdr = hertzmdr.numeric.cli:main" in entry

    site = tmp_path / "site"
    done = _run(*pip, "install", "-q", "--no-deps", "--target", str(site), str(wheel),
                cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    env = {**os.environ, "PYTHONPATH": str(site)}  # ahead of the editable install's finder
    where = _run(sys.executable, "-c", "import hertzmdr, hertzmdr.numeric.scene as s; "
                 "print(hertzmdr.__file__); print(s.__file__)", cwd=tmp_path, env=env)
    assert where.returncode == 0, where.stderr
    assert all(line.startswith(str(site)) for line in where.stdout.splitlines()), where.stdout
    scene = site / "hertzmdr/numeric/tour/problem1_rail_wheel.toml"
    out = _run(sys.executable, "-m", "hertzmdr", "run", str(scene), "--json", cwd=tmp_path,
               env=env)
    assert out.returncode == 0, out.stderr
    assert '"max_pressure"' in out.stdout

    if not FULL:
        return
    venv = tmp_path / "venv"
    assert _run(sys.executable, "-m", "venv", str(venv), cwd=tmp_path).returncode == 0
    vpy = venv / "bin" / "python"
    got = _run(str(vpy), "-m", "pip", "install", "-q", "-c", str(ROOT / "constraints.txt"),
               str(wheel), cwd=tmp_path)
    assert got.returncode == 0, got.stderr
    ver = _run(str(venv / "bin" / "hertzmdr"), "--version", cwd=tmp_path)
    assert ver.stdout.strip() == f"hertzmdr {md.version('hertzmdr')}"
    tour = _run(str(vpy), "-m", "hertzmdr", "run", "--json", cwd=tmp_path)
    assert tour.returncode == 0, tour.stderr
