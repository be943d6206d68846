"""Fitting many curves: force maps, folders of curves (numeric/fit_batch.py, fit_io.read_batch).

The example force map (examples/fit_force_map.csv, made by benchmarks/make_force_map.py from
numeric.hertz with a stated modulus field) is fitted by the command, and every pixel's fitted E
is checked against the true field within its reported standard error; a pixel without contact
fails alone, with one line. Parallel and serial batches give the same numbers.
"""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from hertzmdr.numeric import fit_batch, fit_io, hertz
from hertzmdr.numeric.cli import main
from hertzmdr.numeric.fit import Paraboloid

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import make_force_map  # noqa: E402  (benchmarks/ is a folder of scripts)

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
MAP = EXAMPLES / "fit_force_map.csv"
MAP_SCENE = EXAMPLES / "fit_force_map.toml"


def test_example_map_is_its_recipe():
    assert MAP.read_text() == make_force_map.force_map_text()


def _rows(path):
    with path.open(encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_cli_fits_the_example_map(tmp_path, capsys):
    out = tmp_path / "fitmap"
    assert main(["fit", str(MAP), "--scene", str(MAP_SCENE), "--out", str(out),
                 "--sigma", "0.5 nN", "--workers", "2"]) == 0
    std = capsys.readouterr()
    # the hole fails alone, in one line naming it
    fails = std.err.strip().splitlines()
    assert len(fails) == 1 and "curve x = 9.5 µm, y = 500 nm: no contact" in fails[0], std.err
    assert "100 curves: 99 fitted (0 with warnings), 1 failed" in std.out
    rows = _rows(out / "fits.csv")
    assert len(rows) == 100 and rows[0].keys() == set(fit_batch.TABLE_COLUMNS)
    inside = 0
    for r in rows:
        x, y = float(r["x [m]"]), float(r["y [m]"])
        if r["status"] == "failed":
            assert (x, y) == pytest.approx((9.5e-6, 0.5e-6)) and r["E [Pa]"] == ""
            continue
        assert r["status"] == "ok", r
        E, err = float(r["E [Pa]"]), float(r["E_err [Pa]"])
        truth = float(make_force_map.true_modulus(x, y))
        # 5 sigma: a 6e-7 event per pixel for a right error; the error itself is 0.08-0.33 % of
        # E (the shallowest indentation, 75 nm at the far corner, the largest)
        assert abs(E - truth) < 5 * err and err < 5e-3 * truth, (r["curve"], E, truth, err)
        inside += abs(E - truth) <= err
        chi2 = float(r["reduced_chi2"])
        assert abs(chi2 - 1) < 0.5, chi2  # sigma is the recipe's noise: chi^2 ~ 1 +- 0.13
    # the truth within one standard error in 68 % of 99 pixels: binomial, sd 0.047; 3.5 sd
    assert abs(inside / 99 - 0.6827) < 3.5 * math.sqrt(0.6827 * 0.3173 / 99), inside
    for name in ("modulus_map.png", "fit_median.png"):
        assert (out / name).read_bytes()[:4] == b"\x89PNG" and (out / name).stat().st_size > 2e4


def _curve(E_star, z0=200e-9, seed=0, n=80):
    z = np.linspace(0, 300e-9, n)
    F = hertz.force(np.maximum(z - z0, 0), 25e-6, E_star) + np.random.default_rng(seed).normal(
        0, 0.5e-9, n)
    return z, F


def test_parallel_is_serial():
    """Worker processes give the same numbers as one process, in the curves' order."""
    curves = [fit_batch.Curve(f"c{k}", None, None, *_curve(1e6 * (1 + k / 10), seed=k))
              for k in range(fit_batch.MIN_PARALLEL + 3)]
    curves[5] = fit_batch.Curve("flat", None, None, curves[5].z, np.zeros(curves[5].z.size))
    seen = []
    par = fit_batch.fit_curves(curves, Paraboloid(25e-6), workers=2,
                               progress=lambda d, t, f: seen.append((d, t, f)))
    ser = fit_batch.fit_curves(curves, Paraboloid(25e-6), workers=1)
    assert [r.name for r in par] == [c.name for c in curves]
    for a, b in zip(par, ser, strict=True):  # equal, NaN for NaN (a failed fit's values)
        assert (a.name, a.error, a.warnings, a.n_contact) == (b.name, b.error, b.warnings,
                                                              b.n_contact)
        assert np.array_equal(a.values + a.errors, b.values + b.errors, equal_nan=True)
    assert not par[5].ok and par[5].error.startswith("no contact")
    assert seen[-1] == (len(curves), len(curves), 1)
    for k, r in enumerate(par):
        if k != 5:  # the truth within 5 standard errors
            assert abs(r.values[0] - 1e6 * (1 + k / 10)) < 5 * r.errors[0], (k, r.values)


def test_curve_names_and_folders(tmp_path, capsys):
    """The three-column map (curve, z, F) and a folder of curve files, one of them broken."""
    lines = ["# two curves by name", "curve, z [nm], F [nN]"]
    for name, E in (("soft", 1e6), ("stiff", 4e6)):
        z, F = _curve(E)
        lines += [f"{name}, {zi * 1e9:.4f}, {Fi * 1e9:.5f}" for zi, Fi in zip(z, F, strict=True)]
    (tmp_path / "named.csv").write_text("\n".join(lines) + "\n")
    curves, bad = fit_io.read_batch(tmp_path / "named.csv")
    assert [c.name for c in curves] == ["soft", "stiff"] and bad == []
    assert curves[0].x is None and curves[1].z.size == 80
    folder = tmp_path / "curves"
    folder.mkdir()
    for name, E in (("a", 1e6), ("b", 2e6)):
        z, F = _curve(E)
        (folder / f"{name}.csv").write_text("z [nm], F [nN]\n" + "".join(
            f"{zi * 1e9}, {Fi * 1e9}\n" for zi, Fi in zip(z, F, strict=True)))
    (folder / "c.csv").write_text("z [nm], F [nN]\n1, x\n")
    curves, bad = fit_io.read_batch(folder)
    assert [c.name for c in curves] == ["a", "b"]
    assert len(bad) == 1 and bad[0][0] == "c" and "is not two numbers" in bad[0][1]
    out = tmp_path / "out"
    assert main(["fit", str(folder), "--scene", str(MAP_SCENE), "--out", str(out)]) == 0
    std = capsys.readouterr()
    assert std.err.count("\n") == 1 and "curve c: " in std.err, std.err
    rows = _rows(out / "fits.csv")
    assert [r["status"] for r in rows] == ["ok", "ok", "failed"]
    assert float(rows[1]["E_star [Pa]"]) == pytest.approx(2e6, rel=0.01)  # noise 0.5 nN of ~200
    assert (out / "modulus_map.png").stat().st_size > 1e4


def test_every_curve_failing_exits_1(tmp_path, capsys):
    (tmp_path / "m.csv").write_text("curve, z [nm], F [nN]\n" + "".join(
        f"a, {k}, {1.0 - 0.01 * k}\n" for k in range(20)))
    assert main(["fit", str(tmp_path / "m.csv"), "--scene", str(MAP_SCENE)]) == 1
    std = capsys.readouterr()
    assert "1 curves: 0 fitted" in std.out and std.err.count("\n") == 1


@pytest.mark.parametrize("text, message", [
    ("x [um], y [um], z [nm], F [s]\n", "column 'F [s]'"),
    ("curve [um], z [nm], F [nN]\n", "the curve's name, without a unit"),
    ("x [um], y [um], z [nm], F [nN]\n", "no points after the header"),
    ("x [um], y [um], z [nm], F [nN]\n1, 2, 3\n", ":2: 3 values; each line has 4"),
    ("curve, z [nm], F [nN]\na, 1, b\n", ":2: 'a, 1, b' is not two numbers after the curve name"),
])
def test_bad_map_is_one_line_and_exit_2(tmp_path, capsys, text, message):
    (tmp_path / "m.csv").write_text(text)
    assert main(["fit", str(tmp_path / "m.csv"), "--scene", str(MAP_SCENE)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err, err


def test_progress_bar():
    """The bar redraws in place (carriage returns) and ends its line; the end is drawn even
    right after another redraw (the others are throttled to 10 a second)."""
    import io

    out = io.StringIO()
    bar = fit_batch.ProgressBar(out, width=10)
    bar(1, 4, 0)
    bar(4, 4, 1)
    text = out.getvalue()
    assert text.count("\r") == 2 and text.endswith("\n"), text
    assert "[##........] 1/4 curves, 0 failed" in text  # round(10 / 4) = 2 (to even)
    assert "[##########] 4/4 curves, 1 failed" in text
