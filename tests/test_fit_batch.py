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


# --- the batch's plumbing: what each result carries, failures, workers, progress, table -------
# A stand-in fit (fit.fit_curve replaced) returns numbers unlike any default, so that the batch
# is seen to carry each one, and fails on demand; an in-process stand-in for the worker pool
# records how the batch used it. Real fits are checked above and in test_adhesive_batch.


def _stub_result(F, k):
    """A fit result whose every field is distinct and derived from the curve's index k."""
    from types import SimpleNamespace

    corr = np.eye(4) + 0.25 * (1 + k / 100) * (np.ones((4, 4)) - np.eye(4))
    corr[0, 2] = corr[2, 0] = -0.5
    return SimpleNamespace(values=np.array([1e6 + k, 2e-7 + k * 1e-9, 3e-9, -4e-3]),
                           errors=np.array([5e3, 6e-10, 7e-11, 8e-5]), correlation=corr,
                           E=1.5e6 + k, E_error=9e3, reduced_chi2=1.25, F=np.asarray(F),
                           n_contact=int(np.size(F)) - 3, max_depth=1e-7 * (k + 1),
                           warnings=("careful",) if k % 2 else ())


@pytest.fixture
def stub_fit(monkeypatch):
    """fit.fit_curve replaced: the curve whose first position is k >= 0 gets _stub_result; one
    whose first position is -j < 0 raises ``stub_fit.raises[-j]``. Every call's keyword
    arguments are kept in ``stub_fit.calls``."""
    from types import SimpleNamespace

    from hertzmdr.numeric import fit as fit_module

    state = SimpleNamespace(calls=[], raises={})

    def fake(z, F, tip, **kw):
        state.calls.append((tip, kw))
        k = int(round(float(z[0])))
        if k < 0:
            raise state.raises[k]
        return _stub_result(F, k)

    monkeypatch.setattr(fit_module, "fit_curve", fake)
    return state


def _stub_curves(n, bad=(), size=10):
    """n curves whose z starts at their index (the stand-in's k); the indices in ``bad`` start
    at -1 - (their place in bad) instead, so that the stand-in raises for them."""
    out = []
    for k in range(n):
        start = -1 - bad.index(k) if k in bad else k
        out.append(fit_batch.Curve(f"c{k}", 1e-6 * k, 2e-6 * k, start + np.arange(size) * 0.01,
                                   np.linspace(0, 1e-9, size)))
    return out


class _InlinePool:
    """ProcessPoolExecutor's stand-in: runs each task when it is submitted, in this process,
    and records its keyword arguments and the curves of each task."""

    made: list = []

    def __init__(self, **kw):
        import concurrent.futures

        self.kw, self.tasks, self._future = kw, [], concurrent.futures.Future
        _InlinePool.made.append(self)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def submit(self, fn, curves, *args):
        fut = self._future()
        self.tasks.append([c.name for c in curves])
        fut.set_result(fn(curves, *args))
        return fut


@pytest.fixture
def inline_pool(monkeypatch):
    _InlinePool.made = []
    monkeypatch.setattr(fit_batch, "ProcessPoolExecutor", _InlinePool)
    return _InlinePool.made


def test_failed_record_is_nan_with_its_message():
    """A failed curve's record: its name and position kept (the map shows the failed pixel),
    every number NaN or None (never a value that looks fitted), its points counted, none in
    contact, the message; the work of adhesion NaN in an adhesive batch, None otherwise."""
    c = fit_batch.Curve("p", 1.5e-6, 2.5e-6, np.arange(7.0), np.zeros(7))
    for adhesion, dg in ((False, None), (True, math.nan)):
        r = (fit_batch._failed(c, "no contact", adhesion) if adhesion
             else fit_batch._failed(c, "no contact"))
        assert (r.name, r.x, r.y, r.E, r.E_error, r.n_points, r.n_contact, r.warnings,
                r.error) == ("p", 1.5e-6, 2.5e-6, None, None, 7, 0, (), "no contact")
        assert not r.ok and len(r.values) == len(r.errors) == 4
        assert all(math.isnan(v) for v in (*r.values, *r.errors, r.corr_E_z0, r.reduced_chi2,
                                           r.max_depth))
        for got in (r.dgamma, r.dgamma_error):
            assert got is None if dg is None else math.isnan(got)


def test_each_field_carried_from_the_fit(stub_fit):
    """Each result holds its own curve's fit, field by field, with the batch's options passed
    to every fit; a failing fit is its curve's record with the first line of its message (a
    ValueError's text; any other exception named by its type)."""
    curves = _stub_curves(6, bad=(2, 3, 4))
    stub_fit.raises = {-1: ValueError("the first line\nthe second"), -2: ValueError(),
                       -3: ZeroDivisionError("float division by zero")}
    tip = Paraboloid(25e-6)
    res = fit_batch.fit_curves(curves, tip, nu=0.4, sigma=1e-9, fixed_z0=2e-7,
                               fixed_baseline=(1e-9, 0.0), workers=1)
    assert [r.name for r in res] == [c.name for c in curves]
    for got_tip, call in stub_fit.calls:
        assert got_tip is tip
        assert call == {"nu": 0.4, "tip_modulus": None, "tip_nu": None, "z0": None,
                        "sigma": 1e-9, "fixed_z0": 2e-7, "fixed_baseline": (1e-9, 0.0)}
    assert [r.error for r in res[2:5]] == ["the first line", "ValueError",
                                           "ZeroDivisionError: float division by zero"]
    for k in (0, 1, 5):
        r, s, c = res[k], _stub_result(curves[k].F, k), curves[k]
        assert (r.x, r.y, r.values, r.errors) == (c.x, c.y, tuple(s.values), tuple(s.errors))
        assert (r.corr_E_z0, r.E, r.E_error, r.reduced_chi2) == (s.correlation[0, 1], s.E,
                                                                 s.E_error, 1.25)
        assert (r.n_points, r.n_contact, r.max_depth, r.warnings) == (10, 7, s.max_depth,
                                                                      s.warnings)
        assert r.ok and r.error is None and r.dgamma is None and r.dgamma_error is None


def test_workers_and_tasks(stub_fit, inline_pool, monkeypatch):
    """Batches of fewer than MIN_PARALLEL curves, and workers = 1, run in this process; others
    go to a pool of exactly ``workers`` processes (default: the machine's cores; one when
    the count is unknown), started by fork where it exists, in tasks of at least MIN_CHUNK
    curves, about TASKS_PER_WORKER of them per worker; the results come back in order."""
    tip = Paraboloid(25e-6)
    for n, workers in ((fit_batch.MIN_PARALLEL - 1, 2), (fit_batch.MIN_PARALLEL + 8, 1)):
        res = fit_batch.fit_curves(_stub_curves(n), tip, workers=workers)
        assert len(res) == n and not inline_pool
    n = fit_batch.MIN_PARALLEL
    res = fit_batch.fit_curves(_stub_curves(n, bad=(3,)), tip, workers=2)
    (pool,) = inline_pool
    assert pool.kw["max_workers"] == 2
    import multiprocessing

    if "fork" in multiprocessing.get_all_start_methods():  # asked for, not Python's default
        # (which is forkserver on Linux from Python 3.14, spawn on macOS)
        assert pool.kw["mp_context"] is multiprocessing.get_context("fork")
    # 32 curves over 2 x 16 tasks would be 1 each: MIN_CHUNK = 4 a task instead
    assert [len(t) for t in pool.tasks] == [fit_batch.MIN_CHUNK] * (n // fit_batch.MIN_CHUNK)
    assert sum(pool.tasks, []) == [f"c{k}" for k in range(n)]
    assert [r.name for r in res] == [f"c{k}" for k in range(n)]
    assert [r.ok for r in res] == [k != 3 for k in range(n)]
    assert res[7].values[0] == 1e6 + 7
    assert all(got_tip is tip for got_tip, _ in stub_fit.calls)
    n = 1000  # 2 workers x 16 tasks of 32 curves (the last 8)
    fit_batch.fit_curves(_stub_curves(n, size=2), tip, workers=2)
    sizes = [len(t) for t in inline_pool[-1].tasks]
    assert len(sizes) == 2 * fit_batch.TASKS_PER_WORKER and sizes[:-1] == [32] * 31, sizes
    for cores, expected in ((3, 3), (None, None)):  # the default workers: the cores, else 1
        inline_pool.clear()
        monkeypatch.setattr(fit_batch.os, "cpu_count", lambda c=cores: c)
        fit_batch.fit_curves(_stub_curves(fit_batch.MIN_PARALLEL), tip)
        assert [p.kw["max_workers"] for p in inline_pool] == ([expected] if expected else [])


def test_serial_progress(stub_fit):
    """In this process, progress(done, total, failed) is called after every curve of a batch
    of up to 199 curves, after every (total // 100)-th of a larger one, and at the end; the
    failed count is of the curves done."""
    tip = Paraboloid(25e-6)
    seen = []
    stub_fit.raises = {-1: ValueError("x"), -2: ValueError("y")}
    fit_batch.fit_curves(_stub_curves(5, bad=(1, 3)), tip, workers=1,
                         progress=lambda *a: seen.append(a))
    assert seen == [(1, 5, 0), (2, 5, 1), (3, 5, 1), (4, 5, 2), (5, 5, 2)]
    seen.clear()
    n = 301  # total // 100 = 3: after every third curve, and the last
    fit_batch.fit_curves(_stub_curves(n, bad=(0,), size=2), tip, workers=1,
                         progress=lambda *a: seen.append(a))
    assert seen == [(k, n, 1) for k in range(3, n, 3)] + [(n, n, 1)]


def test_adhesive_batch():
    """adhesion=True: each curve by the adhesive fit (E*, z_0, F_0, s_0 in values, the work
    of adhesion in dgamma, each with its standard error), the same numbers as the fit of the
    curve alone, the truth within 4 standard errors; a curve without contact fails with NaN
    for its work of adhesion. A fixed contact point or baseline, or a tip without an adhesive
    model, is refused for the batch in one line."""
    from hertzmdr.numeric import fit_adhesive
    from tests.test_fit_jkr import R_TIP, TRUTH, forward_curve

    sigma = 2e-10
    curves = [fit_batch.Curve(f"c{s}", 1e-6 * s, None, *forward_curve(n=200, noise=sigma,
                                                                       seed=s))
              for s in (1, 2)]
    curves.append(fit_batch.Curve("flat", 5e-6, None, curves[0].z, np.zeros(200)))
    tip = Paraboloid(R=R_TIP)
    res = fit_batch.fit_curves(curves, tip, sigma=sigma, adhesion=True, workers=1)
    for r, c in zip(res[:2], curves, strict=False):
        alone = fit_adhesive.fit_curve(c.z, c.F, tip, sigma=sigma)
        assert r.ok and (r.name, r.x, r.y) == (c.name, c.x, c.y)
        assert r.values == tuple(alone.values[[0, 1, 3, 4]])
        assert r.errors == tuple(alone.errors[[0, 1, 3, 4]])
        assert (r.dgamma, r.dgamma_error) == (alone.values[2], alone.errors[2])
        assert (r.corr_E_z0, r.E, r.E_error, r.reduced_chi2) == (
            alone.correlation[0, 1], alone.E, alone.E_error, alone.reduced_chi2)
        assert (r.n_points, r.n_contact, r.max_depth, r.warnings) == (
            200, alone.n_contact, alone.max_depth, alone.warnings)
        for got, err, truth in zip((*r.values, r.dgamma), (*r.errors, r.dgamma_error),
                                   np.array(TRUTH)[[0, 1, 3, 4, 2]], strict=True):
            assert abs(got - truth) < 4 * err, (got, truth, err)
    flat = res[2]
    assert not flat.ok and "no contact" in flat.error, flat.error
    assert math.isnan(flat.dgamma) and math.isnan(flat.dgamma_error)
    for fixed in ({"fixed_z0": 1e-7}, {"fixed_baseline": (0.0, 0.0)}):
        with pytest.raises(ValueError, match=r"^fixed_z0/fixed_baseline with adhesion = True:"
                           r" the adhesive fit fits all five parameters; valid only without "
                           r"adhesion$"):
            fit_batch.fit_curves(curves, tip, adhesion=True, **fixed)
    from hertzmdr.numeric.fit import PowerLaw

    with pytest.raises(ValueError, match="n = 0.4 has no adhesive pull-off"):
        fit_batch.fit_curves(curves, PowerLaw(2e-6, 0.4), adhesion=True)


def test_workers_refused_in_one_line(stub_fit):
    """workers: an integer >= 1, numpy's too (np.int64(2) was refused as 'out of range' by a
    message that asked for an integer); True is not a count (it was taken as 1)."""
    res = fit_batch.fit_curves(_stub_curves(2), Paraboloid(25e-6), workers=np.int64(1))
    assert [r.ok for r in res] == [True, True]
    for bad, shown in ((0, "0"), (-1, "-1"), (2.5, "2.5"), ("2", "'2'"), (True, "True"),
                       (np.int64(0), "0")):
        with pytest.raises(ValueError) as exc:
            fit_batch.fit_curves([], Paraboloid(25e-6), workers=bad)
        assert str(exc.value) == f"workers = {shown} is out of range; valid: an integer >= 1"


def test_progress_bar_throttled(monkeypatch):
    """On a stand-in clock: the first call draws, later ones only 0.1 s or more after the last
    drawing (the end always), with the time since the bar was made; the width is 30."""
    import io
    from types import SimpleNamespace

    clock = [0.0625]  # the bar is made at 0.0625 s; 0.125 + 0.1 - 0.125 is 0.1 exactly
    monkeypatch.setattr(fit_batch, "time", SimpleNamespace(perf_counter=lambda: clock[0]))
    out = io.StringIO()
    bar = fit_batch.ProgressBar(out)
    drawn = []
    for t, done in ((0.125, 1), (0.1875, 2), (0.125 + 0.1, 3), (0.25, 4), (0.5, 5), (0.5, 10)):
        clock[0] = t
        before = out.getvalue()
        bar(done, 10, 0)
        drawn.append(out.getvalue() != before)
    assert drawn == [True, False, True, False, True, True]
    assert out.getvalue().endswith(f"\rfitting [{'#' * 30}] 10/10 curves, 0 failed, 0.4 s\n")
    assert f"\rfitting [{'#' * 3}{'.' * 27}] 1/10 curves, 0 failed, 0.1 s\r" in out.getvalue()
    # perf_counter's origin is undefined (only differences count): a bar made at -1.05 s draws
    # its first call at -1 s too (it did not: its "never drawn" was the time -1 s)
    clock[0] = -1.05
    out = io.StringIO()
    bar = fit_batch.ProgressBar(out)
    clock[0] = -1.0
    bar(1, 10, 0)
    assert out.getvalue() == f"\rfitting [{'#' * 3}{'.' * 27}] 1/10 curves, 0 failed, 0.1 s"


def test_table_cells(tmp_path):
    """Every cell of the table: values and errors in pairs, empty where a number does not
    exist, the status and message; an adhesive batch's work of adhesion after s_0_err."""
    ok = fit_batch.CurveFit("a", 1e-6, None, (1.0, 2.0, 3.0, 4.0), (0.1, 0.2, 0.3, 0.4), 0.5,
                            7.0, 0.7, 1.1, 20, 12, 3e-7, (), None)
    warned = fit_batch.CurveFit("b", None, 2e-6, (1.0, 2.0, 3.0, 4.0), (0.1, 0.2, 0.3, 0.4),
                                -0.5, None, None, 0.9, 21, 13, 4e-7, ("w1", "w2"), None)
    failed = fit_batch._failed(fit_batch.Curve("c", None, None, np.zeros(5), np.zeros(5)),
                               "no contact")
    rows = [["a", "1e-06", "", "1", "0.1", "2", "0.2", "3", "0.3", "4", "0.4", "7", "0.7",
             "0.5", "1.1", "20", "12", "3e-07", "ok", ""],
            ["b", "", "2e-06", "1", "0.1", "2", "0.2", "3", "0.3", "4", "0.4", "", "",
             "-0.5", "0.9", "21", "13", "4e-07", "warning", "w1 | w2"],
            ["c", "", "", *[""] * 12, "5", "0", "", "failed", "no contact"]]
    path = fit_batch.write_table([ok, warned, failed], tmp_path / "t.csv")
    with path.open(encoding="utf-8", newline="") as fh:
        got = list(csv.reader(fh))
    assert got == [list(fit_batch.TABLE_COLUMNS), *rows]
    from dataclasses import replace

    adh = [replace(ok, dgamma=0.05, dgamma_error=0.002), replace(failed, dgamma=math.nan,
                                                                  dgamma_error=math.nan)]
    path = fit_batch.write_table(adh, tmp_path / "u.csv")
    with path.open(encoding="utf-8", newline="") as fh:
        got = list(csv.reader(fh))
    k = 11  # after s_0_err [N/m]
    assert got[0] == [*fit_batch.TABLE_COLUMNS[:k], "dgamma [J/m^2]", "dgamma_err [J/m^2]",
                      *fit_batch.TABLE_COLUMNS[k:]]
    assert got[1] == [*rows[0][:k], "0.05", "0.002", *rows[0][k:]]
    assert got[2] == [*rows[2][:k], "", "", *rows[2][k:]]


@pytest.mark.skipif("fork" not in __import__("multiprocessing").get_all_start_methods(),
                    reason="the stand-in fit reaches the workers by fork")
def test_a_worker_that_dies_fails_its_curves(stub_fit, monkeypatch):
    """A worker process that ends abruptly (killed, out of memory) fails the curves it held,
    each with one line naming what happened, never the batch (it was a BrokenProcessPool
    traceback): one result per curve, in order, the others fitted or failed alike, and the
    progress reaches the end with every failure counted."""
    import os

    from hertzmdr.numeric import fit as fit_module

    stub = fit_module.fit_curve

    def dying(z, F, tip, **kw):
        if float(z[0]) == 5:
            os._exit(3)
        return stub(z, F, tip, **kw)

    monkeypatch.setattr(fit_module, "fit_curve", dying)
    n = fit_batch.MIN_PARALLEL + 8
    seen = []
    res = fit_batch.fit_curves(_stub_curves(n), Paraboloid(25e-6), workers=2,
                               progress=lambda *a: seen.append(a))
    assert [r.name for r in res] == [f"c{k}" for k in range(n)]
    lost = res[5]
    assert not lost.ok and lost.error.startswith("BrokenProcessPool: ") and math.isnan(
        lost.values[0]) and "\n" not in lost.error, lost.error
    for k, r in enumerate(res):
        assert (r.ok and r.values[0] == 1e6 + k) or r.error == lost.error, (k, r)
    assert seen[-1] == (n, n, sum(not r.ok for r in res))


def test_a_pool_broken_before_sending_fails_the_rest(stub_fit, monkeypatch):
    """A worker that dies while tasks are still being sent breaks the pool: the tasks not sent
    fail their curves with that one line (NaN work of adhesion in an adhesive batch)."""
    from concurrent.futures.process import BrokenProcessPool

    class Broken(_InlinePool):
        def submit(self, fn, curves, *args):
            if len(self.tasks) >= self.kw["max_workers"] - 2:  # workers 4: 2 sent
                raise BrokenProcessPool("a worker died")
            return super().submit(fn, curves, *args)

    monkeypatch.setattr(fit_batch, "ProcessPoolExecutor", Broken)
    n = fit_batch.MIN_PARALLEL
    res = fit_batch.fit_curves(_stub_curves(n), Paraboloid(25e-6), workers=4)
    sent = 2 * fit_batch.MIN_CHUNK
    assert [r.ok for r in res] == [True] * sent + [False] * (n - sent)
    assert {r.error for r in res[sent:]} == {"BrokenProcessPool: a worker died"}
    assert res[sent - 1].values[0] == 1e6 + sent - 1 and res[sent - 1].dgamma is None
    res = fit_batch.fit_curves(_stub_curves(n), Paraboloid(25e-6), adhesion=True, workers=2)
    assert all(not r.ok and math.isnan(r.dgamma) for r in res)


def test_table_is_utf8_with_crlf_on_any_platform(tmp_path, monkeypatch):
    """The table is UTF-8 with the csv module's \\r\\n line ends wherever it is written: here
    on a stand-in for Windows' defaults (the locale's encoding cp1252, \\n written as \\r\\n
    when open() is not told newline=''), a curve's name with a µ and a message with a sigma
    read back as written, and no \\r\\r\\n."""

    class WindowsPath(type(Path())):
        def open(self, mode="r", buffering=-1, encoding=None, errors=None, newline=None):
            if "b" not in mode:
                encoding = "cp1252" if encoding is None else encoding
                newline = "\r\n" if newline is None else newline
            return super().open(mode, buffering, encoding, errors, newline)

    monkeypatch.setattr(fit_batch, "Path", WindowsPath)
    c = fit_batch.Curve("x = 9.5 µm", None, None, np.zeros(2), np.zeros(2))
    path = fit_batch.write_table([fit_batch._failed(c, "no contact: σ = 0")], tmp_path / "t.csv")
    data = path.read_bytes()
    assert b"\r\r\n" not in data and data.count(b"\r\n") == 2, data
    row = data.decode("utf-8").splitlines()[1]
    assert row.startswith("x = 9.5 µm,") and row.endswith(",failed,no contact: σ = 0"), row


@pytest.mark.parametrize("options, message", [
    ({"nu": 0.7}, "nu = 0.7 is out of range; valid: -1 < nu <= 0.5"),
    ({"tip_modulus": 1e9}, "tip_modulus is given without nu"),
    ({"nu": 0.3, "tip_modulus": -1.0}, "tip_modulus = -1.0 is out of range"),
    ({"nu": 0.3, "tip_modulus": 1e9, "tip_nu": 0.6}, "tip_nu = 0.6 is out of range"),
    ({"sigma": 0.0}, "sigma = 0.0 is out of range"),
    ({"fixed_z0": math.nan}, "fixed_z0 = nan is out of range"),
    ({"fixed_baseline": (1.0,)}, "fixed_baseline = (1.0,) is out of range"),
])
def test_shared_options_refused_once(stub_fit, options, message):
    """The options every curve shares are checked before any fit: one ValueError for the
    batch (a bad nu was a failed record per curve, each curve fitted first)."""
    with pytest.raises(ValueError) as exc:
        fit_batch.fit_curves(_stub_curves(3), Paraboloid(25e-6), workers=1, **options)
    assert str(exc.value).startswith(message) and "\n" not in str(exc.value), exc.value
    assert not stub_fit.calls
    # a valid set passes, whatever the tip's modulus (any is above the E* = 0 it is checked at)
    res = fit_batch.fit_curves(_stub_curves(1), Paraboloid(25e-6), workers=1, nu=0.3,
                               tip_modulus=0.5, sigma=1e-9, fixed_z0=1e-7)
    assert res[0].ok


def test_cli_shared_option_is_one_line_and_exit_2(capsys):
    """hertzmdr fit MAP --sigma '0 nN': the batch's refusal is one line and exit 2 (as for one
    curve), not a traceback."""
    assert main(["fit", str(MAP), "--scene", str(MAP_SCENE), "--sigma", "0 nN"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "sigma = 0.0 is out of range" in err, err
