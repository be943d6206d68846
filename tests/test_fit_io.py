"""numeric/fit_io.py: the curve files of ``hertzmdr fit``, read or refused in one line, and the
fit of a depth range.

Every refusal is checked in full (the file, the line, the value and what is valid: promise 1);
the units are checked by the SI value of a known number; a depth range's fit is checked to be
the fit of exactly the points in the range of its own contact point, closed at both ends.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hertzmdr.numeric import fit, fit_io, mdr
from hertzmdr.numeric.fit_io import CurveError


def write(tmp_path, text, name="c.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def refused(match_path, call, *args, **kwargs) -> str:
    with pytest.raises(CurveError) as info:
        call(*args, **kwargs)
    msg = str(info.value)
    assert msg.startswith(f"{match_path}") and "\n" not in msg, msg
    return msg


# -- read_curve: one curve, two columns with units ------------------------------------------
def test_read_curve_scales_each_column_by_its_unit(tmp_path):
    # a byte-order mark, comments (one indented), an empty line before the header; a comment
    # between the points
    path = write(tmp_path, "\ufeff# comment\n\n   #z [m], F [N]\nz [um], F [nN]\n"
                 "1.5, 2\n  # 7, 8\n-0.25, 4e3\n")
    z, F = fit_io.read_curve(path)
    # 1 um = 1e-6 m, 1 nN = 1e-9 N: each value times its column's unit, nothing else
    assert z.tolist() == [1.5 * 1e-6, -0.25 * 1e-6] and F.tolist() == [2 * 1e-9, 4e3 * 1e-9]
    z, F = fit_io.read_curve(write(tmp_path, "height [nm], Force [pN]\n3, 5\n"))
    assert z.tolist() == [3 * 1e-9] and F.tolist() == [5 * 1e-12]


def test_read_curve_refusals_name_the_file_the_line_and_what_is_valid(tmp_path):
    # the header is on line 3 (after a comment and an empty line): every message counts lines
    # of the file, comments included
    def curve(header, *rows):
        return write(tmp_path, "# a comment\n\n" + header + "\n" + "".join(r + "\n" for r in rows))

    p = curve("z [um], F [nN], x [m]", "1, 2, 3")
    assert refused(p, fit_io.read_curve, p) == (
        f"{p}:3: the header must name two columns, position and force, with units, e.g. "
        "`z [um], F [nN]`; got 3")
    p = curve("z um, F [nN]", "1, 2")
    assert refused(p, fit_io.read_curve, p) == (
        f"{p}:3: column 'z um' must be a name and a unit in brackets, e.g. `z [um]`")
    p = curve("z [um], F nN", "1, 2")
    assert refused(p, fit_io.read_curve, p) == (
        f"{p}:3: column 'F nN' must be a name and a unit in brackets, e.g. `F [nN]`")
    p = curve("z [nN], F [nN]", "1, 2")
    assert refused(p, fit_io.read_curve, p) == (
        f"{p}:3: column 'z [nN]': '1 nN' has the unit nanonewton, which is not a length "
        "(convertible to m)")
    p = curve("z [um], F [um]", "1, 2")
    assert refused(p, fit_io.read_curve, p).startswith(
        f"{p}:3: column 'F [um]': '1 um' has the unit micrometer, which is not a force")
    p = curve("z [um], F [nN]", "1, 2", "3, 4, 5")
    assert refused(p, fit_io.read_curve, p) == f"{p}:5: 3 values; each line has 2"
    p = curve("z [um], F [nN]", "1, 2", "3, x")
    assert refused(p, fit_io.read_curve, p) == f"{p}:5: '3, x' is not two numbers"
    # the first value that is not finite, by its line: the third point's position (an inf
    # later too)
    p = curve("z [um], F [nN]", "1, 2", "3, 4", "inf, 5", "6, nan")
    assert refused(p, fit_io.read_curve, p) == f"{p}:6: a value is not finite"
    p = curve("z [um], F [nN]", "1, 2", "3, 4", "5, -inf")
    assert refused(p, fit_io.read_curve, p) == f"{p}:6: a value is not finite"
    # finite as written, beyond float in SI units: refused too, never an inf returned
    p = curve("z [km], F [nN]", "1, 2", "1e306, 4")
    assert refused(p, fit_io.read_curve, p) == f"{p}:5: a value is not finite"
    p = write(tmp_path, "# only\n# comments\n", "empty.csv")
    assert refused(p, fit_io.read_curve, p) == f"{p}: no header line (e.g. `z [um], F [nN]`)"
    p = tmp_path / "missing.csv"
    assert refused(p, fit_io.read_curve, p) == f"{p}: no such file"
    p = tmp_path / "latin1.csv"
    p.write_bytes(b"z [\xb5m], F [nN]\n1, 2\n")
    assert refused(p, fit_io.read_curve, p).startswith(f"{p}: cannot read the file (")


# -- read_columns: a scene's [fit] columns and units ----------------------------------------
def test_read_columns_picks_and_scales(tmp_path):
    p = write(tmp_path, "F[nN],curve,z[um]\n2,a,1.5\n4e3,b,-0.25\n")
    z, F = fit_io.read_columns(p, ("z", "F"))
    assert z.tolist() == [1.5 * 1e-6, -0.25 * 1e-6] and F.tolist() == [2 * 1e-9, 4e3 * 1e-9]
    bare = write(tmp_path, "t, height, force\n0, 3, 5\n1, 7, 9\n", "bare.csv")
    z, F = fit_io.read_columns(bare, ("height", "force"), (1e-9, 1e-12))
    assert z.tolist() == [3 * 1e-9, 7 * 1e-9] and F.tolist() == [5 * 1e-12, 9 * 1e-12]
    two = write(tmp_path, "h, f\n3, 5\n", "two.csv")
    z, F = fit_io.read_columns(two, None, (1e-9, 1e-12))  # units alone: the file has two
    assert z.tolist() == [3 * 1e-9] and F.tolist() == [5 * 1e-12]
    # neither: read_curve's rules
    plain = write(tmp_path, "z [nm], F [pN]\n1, 2\n", "plain.csv")
    assert [a.tolist() for a in fit_io.read_columns(plain)] == [[1 * 1e-9], [2 * 1e-12]]


def test_read_columns_refusals_in_one_line(tmp_path):
    p = write(tmp_path, "# c\nz [nm], z [nm], F [nN]\n1, 2, 3\n")
    assert refused(p, fit_io.read_columns, p, ("z", "F")) == (
        f"{p}:2: the position column 'z' of [fit] columns is twice in the header (its names: "
        "'z', 'z', 'F')")
    p = write(tmp_path, "z [nm], F [nN]\n1, 2\n")
    assert refused(p, fit_io.read_columns, p, ("z", "Force")) == (
        f"{p}:1: the force column 'Force' of [fit] columns is not in the header (its names: "
        "'z', 'F')")
    assert refused(p, fit_io.read_columns, p, ("z", "F"), (1e-9, 1e-9)) == (
        f"{p}:1: column 'z [nm]' gives its unit, and so does [fit] units: give it once")
    p3 = write(tmp_path, "z, F, t\n1, 2, 3\n", "three.csv")
    assert refused(p3, fit_io.read_columns, p3, None, (1e-9, 1e-9)) == (
        f"{p3}:1: the header names 3 columns; without [fit] columns the file has two, "
        "position and force")
    # a column of the header given without a unit and none in [fit]: read_curve's message
    bare = write(tmp_path, "t, z, F\n0, 1, 2\n", "bare.csv")
    assert refused(bare, fit_io.read_columns, bare, ("z", "F")) == (
        f"{bare}:1: column 'z' must be a name and a unit in brackets, e.g. `z [um]`")
    assert refused(bare, fit_io.read_columns, bare, ("t", "F")) == (
        f"{bare}:1: column 't' must be a name and a unit in brackets, e.g. `z [um]`")
    # found by its name (all before the bracket), but no name and unit in brackets
    extra = write(tmp_path, "t, z [nm], F [nN] each\n0, 1, 2\n", "extra.csv")
    assert refused(extra, fit_io.read_columns, extra, ("z", "F")) == (
        f"{extra}:1: column 'F [nN] each' must be a name and a unit in brackets, e.g. `F [nN]`")
    unit = write(tmp_path, "t, z [nm], F [nm]\n0, 1, 2\n", "unit.csv")
    assert refused(unit, fit_io.read_columns, unit, ("z", "F")) == (
        f"{unit}:1: column 'F [nm]': '1 nm' has the unit nanometer, which is not a force "
        "(convertible to N)")
    # a name is all before the first bracket: a cell with two brackets is no name and unit
    two = write(tmp_path, "z [x] [um], F [nN]\n1, 2\n", "brackets.csv")
    assert refused(two, fit_io.read_columns, two, ("z", "F")) == (
        f"{two}:1: column 'z [x] [um]' must be a name and a unit in brackets, e.g. `z [um]`")
    rows = write(tmp_path, "t, z, F\n0, 1, 2\n0, 1\n", "rows.csv")
    assert refused(rows, fit_io.read_columns, rows, ("z", "F"), (1e-9, 1e-9)) == (
        f"{rows}:3: 2 values; each line has 3")
    words = write(tmp_path, "t, z, F\n0, 1, 2\nx, 1, y\n", "words.csv")
    assert refused(words, fit_io.read_columns, words, ("z", "F"), (1e-9, 1e-9)) == (
        f"{words}:3: 'x, 1, y': the position and force are not numbers")
    inf = write(tmp_path, "t, z, F\n0, 1, 2\n0, 3, 4\n0, 5, inf\n0, nan, 1\n", "inf.csv")
    assert refused(inf, fit_io.read_columns, inf, ("z", "F"), (1e-9, 1e-9)) == (
        f"{inf}:4: a value is not finite")
    # a unit so large that a finite value overflows: still one line, not inf
    big = write(tmp_path, "z, F\n1e300, 2\n", "big.csv")
    assert refused(big, fit_io.read_columns, big, None, (1e10, 1.0)) == (
        f"{big}:2: a value is not finite")


def test_profile_tip_uses_the_scenes_spline_degree():
    """The sampled tip of a scene's profile body has the spline degree the scene's numerical
    MDR uses (3 below 20 samples, 5 from 20): its g(x) is that of mdr.Profile with that k."""
    for n, k in ((10, 3), (25, 5)):
        r = np.linspace(0.0, 1e-6, n)
        f = 1e-7 * (r / 1e-6) ** 4  # a quartic: the degree-3 and degree-5 splines differ
        tip = fit_io.TIP_SHAPES["profile"]({"r": r.tolist(), "f": f.tolist()})
        x = np.array([0.37e-6, 0.81e-6])
        want = mdr.Profile.from_samples(r.tolist(), f.tolist(), k=k).g(x)
        other = mdr.Profile.from_samples(r.tolist(), f.tolist(), k=8 - k).g(x)
        assert np.array_equal(tip.profile.g(x), want) and not np.array_equal(want, other)


# -- fit_in_range ------------------------------------------------------------------------------
R_TIP, E_STAR = 1e-6, 1e6  # m, Pa


def hertz_curve(z, z_true, stiff_from=math.inf):
    """Hertz's force 4/3 E* sqrt(R) d^1.5 of a paraboloid (5.57) beyond z_true; from
    ``stiff_from`` deeper on, a much stiffer sample (a substrate) adds k (d - stiff_from)^2."""
    d = np.maximum(z - z_true, 0.0)
    F = 4 / 3 * E_STAR * math.sqrt(R_TIP) * d**1.5
    return F + 1e6 * np.maximum(d - stiff_from, 0.0) ** 2  # k = 1e6 N/m^2


def test_depth_range_closed_at_both_ends_and_exactly_min_points():
    """With the contact point held (fixed_z0, a binary fraction) the range's points are those
    with lo <= z - z_0 <= hi: both ends in, on a grid that has points exactly there."""
    z = np.arange(-64, 192) * 2.0**-30  # m, about 1 nm apart; z - 0 is exact
    F = hertz_curve(z, 0.0)
    tip = fit.Paraboloid(R=R_TIP)
    lo, hi = 16 * 2.0**-30, 40 * 2.0**-30
    r = fit_io.fit_in_range(z, F, tip, (lo, hi), fixed_z0=0.0)
    assert r.z_0 == 0.0 and r.F.size == 25  # 16, 17, ..., 40
    assert r.z.min() == lo and r.z.max() == hi
    # exactly MIN_POINTS points: fitted, not refused
    hi = (16 + fit.MIN_POINTS - 1) * 2.0**-30
    r = fit_io.fit_in_range(z, F, tip, (lo, hi), fixed_z0=0.0)
    assert r.F.size == fit.MIN_POINTS
    # one fewer: refused in one line naming the range, the contact point and the count
    hi = (16 + fit.MIN_POINTS - 2) * 2.0**-30
    with pytest.raises(CurveError) as info:
        fit_io.fit_in_range(z, F, tip, (lo, hi), fixed_z0=0.0)
    assert str(info.value) == (
        f"[fit] depth_range [{lo:g}, {hi:g}] m of the contact point 0 m holds "
        f"{fit.MIN_POINTS - 1} points; at least {fit.MIN_POINTS} are needed")


def moving_curve():
    """A curve whose deep part (a stiff substrate from 150 nm) pulls the whole curve's contact
    point away from the shallow part's (to 31 nm): the range's points change after the first
    fit."""
    z = np.linspace(-200e-9, 400e-9, 301)
    return z, hertz_curve(z, 0.0, stiff_from=150e-9)


def test_depth_range_refits_until_its_points_settle():
    z, F = moving_curve()
    tip = fit.Paraboloid(R=R_TIP)
    lo, hi = -100e-9, 120e-9
    whole = fit.fit_curve(z, F, tip)
    first = (z - whole.z_0 >= lo) & (z - whole.z_0 <= hi)
    r = fit_io.fit_in_range(z, F, tip, (lo, hi))
    keep = (z - r.z_0 >= lo) & (z - r.z_0 <= hi)
    assert not np.array_equal(first, keep)  # the case moves: the first set is not the last
    # a fixed point: exactly the points in the range of its own contact point
    assert np.array_equal(r.z, z[keep]) and np.array_equal(r.F, F[keep])
    # and the shallow part is Hertz's: E* and the contact point of the truth (the fit is of
    # exact data, so to the solver's tolerance, far below 1e-6)
    assert abs(r.values[0] / E_STAR - 1) < 1e-6 and abs(r.z_0) < 1e-6 * hi


def test_depth_range_that_never_settles_is_one_line(monkeypatch):
    z, F = moving_curve()
    monkeypatch.setattr(fit_io, "RANGE_PASSES", 1)
    lo, hi = -100e-9, 120e-9
    with pytest.raises(CurveError) as info:
        fit_io.fit_in_range(z, F, fit.Paraboloid(R=R_TIP), (lo, hi))
    assert str(info.value) == (
        "[fit] depth_range [-1e-07, 1.2e-07] m: the points in it still change after 1 fits "
        "(the contact point moves with them); widen it")


# -- a batch's maps and summary ---------------------------------------------------------------
def result(x, y, ok=True, E=None, E_error=None, values=(0.0, 0.0), errors=(0.0, 0.0),
           dgamma=None, warnings=()):
    from types import SimpleNamespace

    return SimpleNamespace(x=x, y=y, ok=ok, E=E, E_error=E_error, values=values, errors=errors,
                           dgamma=dgamma, warnings=warnings)


def test_map_grids_put_each_fit_at_its_position():
    # a 3 x 2 map given out of order, one curve failed, one position never measured
    rs = [result(2e-6, 1e-6, E=5e3, E_error=50.0, values=(4e3, 7e-9)),
          result(0.0, 0.0, E=1e3, E_error=10.0, values=(9e2, 1e-9)),
          result(1e-6, 0.0, ok=False, E=None),
          result(0.0, 1e-6, E=3e3, E_error=30.0, values=(2e3, 3e-9)),
          result(2e-6, 0.0, E=2e3, E_error=20.0, values=(1e3, 2e-9))]
    xs, ys, grids = fit_io.map_grids(rs)
    assert xs.tolist() == [0.0, 1e-6, 2e-6] and ys.tolist() == [0.0, 1e-6]
    nan = math.nan
    want = np.array([[[1e3, nan, 2e3], [3e3, nan, 5e3]],      # E [Pa]: row y, column x
                     [[10.0, nan, 20.0], [30.0, nan, 50.0]],   # its standard error [Pa]
                     [[1e-9, nan, 2e-9], [3e-9, nan, 7e-9]]])  # z_0 [m]
    np.testing.assert_array_equal(grids, want)
    # without a Poisson's ratio (E is None): E* and its error, values[0] and errors[0]
    rs = [result(0.0, 0.0, values=(9e2, 1e-9), errors=(8.0, 1e-11)),
          result(1e-6, 0.0, values=(4e2, 2e-9), errors=(3.0, 1e-11))]
    xs, ys, grids = fit_io.map_grids(rs)
    np.testing.assert_array_equal(grids[:, 0, :], [[9e2, 4e2], [8.0, 3.0], [1e-9, 2e-9]])
    assert fit_io._modulus(rs)[0] == "E*" and fit_io._modulus(
        [result(0, 0, ok=False), result(0, 1, E=1.0, E_error=0.1)])[0] == "E"


def test_batch_summary_counts_and_spans():
    rs = [result(None, None, E=1e3, E_error=10.0), result(None, None, ok=False),
          result(None, None, E=4e3, E_error=40.0, warnings=("w",)),
          result(None, None, E=2e3, E_error=31.4)]
    assert fit_io.batch_summary(rs, scene_E=2.5e3) == (
        "4 curves: 3 fitted (1 with warnings), 1 failed\n"
        "E: median 2 kPa, from 1 kPa to 4 kPa; median standard error 31 Pa\n"
        "the scene's sample E = 2.5 kPa (not used)")
    rs = [result(None, None, values=(1e3, 0.0), errors=(10.5, 0.0), dgamma=0.01),
          result(None, None, values=(3e3, 0.0), errors=(20.0, 0.0), dgamma=0.03)]
    for r, e in zip(rs, (0.001, 0.003), strict=True):
        r.dgamma_error = e
    assert fit_io.batch_summary(rs) == (
        "2 curves: 2 fitted (0 with warnings), 0 failed\n"
        "E*: median 2 kPa, from 1 kPa to 3 kPa; median standard error 15 Pa\n"
        "work of adhesion: median 0.02 J/m^2, from 0.01 to 0.03 J/m^2; median standard "
        "error 0.002 J/m^2")
    assert fit_io.batch_summary([result(None, None, ok=False)]) == (
        "1 curves: 0 fitted (0 with warnings), 1 failed")
    one = result(None, None, values=(1e3, 0.0), errors=(10.0, 0.0), dgamma=0.01)
    one.dgamma_error = 0.001
    assert fit_io.batch_summary([result(None, None, ok=False), one]).endswith(
        "work of adhesion: median 0.01 J/m^2, from 0.01 to 0.01 J/m^2; median standard error "
        "0.001 J/m^2")


def test_read_columns_arguments_are_checked(tmp_path):
    p = write(tmp_path, "z, F\n1, 2\n")
    for columns in (("z", "F", "t"), ("z",), ("z", 1), "zF", 5):
        with pytest.raises(ValueError, match=r"^columns = .*: the header names of the "
                                             r"position and the force column, two strings$"):
            fit_io.read_columns(p, columns)
    for units in ((1e-9,), (1e-9, 0.0), (1e-9, math.inf), (math.nan, 1.0), (True, 1.0),
                  ("nm", "nN"), 1e-9):
        with pytest.raises(ValueError, match=r"^units = .*: the size in SI units of one unit "
                                             r"of the position \[m\] and of the force \[N\], "
                                             r"two positive finite numbers$"):
            fit_io.read_columns(p, None, units)
    z, F = fit_io.read_columns(p, ["z", "F"], [np.float64(1e-9), np.int64(1)])
    assert z.tolist() == [1 * 1e-9] and F.tolist() == [2.0]


# -- force maps --------------------------------------------------------------------------------
def test_read_batch_folder_and_maps(tmp_path):
    folder = tmp_path / "curves"
    folder.mkdir()
    (folder / "a_bad.csv").write_text("z [um]\n1\n")
    (folder / "b.csv").write_text("z [nm], F [nN]\n1, 2\n3, 4\n")
    (folder / "c.csv").write_text("z [nm], F [pN]\n5, 6\n")
    (folder / "notes.txt").write_text("not a curve")
    curves, failed = fit_io.read_batch(folder)
    # every file after a failed one is read too; names are the stems, in name order
    assert [c.name for c in curves] == ["b", "c"]
    assert curves[0].z.tolist() == [1 * 1e-9, 3 * 1e-9] and curves[1].F.tolist() == [6 * 1e-12]
    assert failed == [("a_bad", f"{folder / 'a_bad.csv'}:1: the header must name two columns, "
                                "position and force, with units, e.g. `z [um], F [nN]`; got 1")]
    empty = tmp_path / "empty"
    empty.mkdir()
    assert refused(empty, fit_io.read_batch, empty) == (
        f"{empty}: a folder of curves, but no *.csv file in it")
    # a map of named curves, its lines in any order
    m = write(tmp_path, "curve, z [nm], F [nN]\nb, 1, 2\na, 3, 4\nb, 5, 6\n", "named.csv")
    curves, failed = fit_io.read_batch(m)
    assert failed == [] and [(c.name, c.z.tolist(), c.F.tolist(), c.x) for c in curves] == [
        ("b", [1 * 1e-9, 5 * 1e-9], [2 * 1e-9, 6 * 1e-9], None),
        ("a", [3 * 1e-9], [4 * 1e-9], None)]
    # a map by position
    m = write(tmp_path, "x [um], y [um], z [nm], F [nN]\n1, 2, 3, 4\n0, 2, 5, 6\n1, 2, 7, 8\n",
              "xy.csv")
    curves, _ = fit_io.read_batch(m)
    assert [(c.x, c.y, c.z.tolist()) for c in curves] == [
        (1 * 1e-6, 2 * 1e-6, [3 * 1e-9, 7 * 1e-9]), (0.0, 2 * 1e-6, [5 * 1e-9])]
    assert curves[0].name == "x = 1 µm, y = 2 µm"


def test_is_batch_by_the_header_or_a_folder(tmp_path):
    assert fit_io.is_batch(tmp_path)  # a folder
    for header, batch in (("z [nm], F [nN]", False), ("curve, z [nm], F [nN]", True),
                          ("x [um], y [um], z [nm], F [nN]", True), ("a, b, c, d, e", False)):
        assert fit_io.is_batch(write(tmp_path, header + "\n", "h.csv")) is batch, header
    # a file that cannot be read is no batch: the single-curve reader names its problem
    assert fit_io.is_batch(tmp_path / "missing.csv") is False
    assert fit_io.is_batch(write(tmp_path, "# only a comment\n", "c.csv")) is False


@pytest.mark.parametrize("text,line", [
    ("curve [nm], z [nm], F [nN]\na, 1, 2\n",
     "1: the first of three columns is the curve's name, without a unit (e.g. `curve, z [nm], "
     "F [nN]`); got 'curve [nm]'"),
    ("curve, z nm, F [nN]\na, 1, 2\n",
     "1: column 'z nm' must be a name and a unit in brackets, e.g. `z [um]`"),
    ("curve, z [nm], F nN\na, 1, 2\n",
     "1: column 'F nN' must be a name and a unit in brackets, e.g. `F [nN]`"),
    ("curve, z [nm], F [nN]\na, 1, x\n", "2: 'a, 1, x' is not two numbers after the curve name"),
    ("x um, y [um], z [nm], F [nN]\n", "1: column 'x um' must be a name and a unit in brackets, "
     "e.g. `x [um]`"),
    ("x [um], y um, z [nm], F [nN]\n", "1: column 'y um' must be a name and a unit in brackets, "
     "e.g. `y [um]`"),
    ("x [um], y [um], z nm, F [nN]\n", "1: column 'z nm' must be a name and a unit in "
     "brackets, e.g. `z [nm]`"),
    ("x [um], y [um], z [nm], F nN\n", "1: column 'F nN' must be a name and a unit in "
     "brackets, e.g. `F [nN]`"),
    ("x [um], y [um], z [nm], F [nm]\n", "1: column 'F [nm]': '1 nm' has the unit nanometer, "
     "which is not a force (convertible to N)"),
    ("x [um], y [um], z [nm], F [nN]\n1, 2, 3, 4, 5\n", "2: 5 values; each line has 4"),
    ("x [um], y [um], z [nm], F [nN]\n1, 2, 3, x\n", "2: '1, 2, 3, x' is not four numbers"),
    ("a, b, c, d, e\n", "1: a force map names three columns (`curve, z [nm], F [nN]`) or four "
     "(`x [um], y [um], z [nm], F [nN]`); got 5"),
])
def test_read_batch_refusals(tmp_path, text, line):
    m = write(tmp_path, text, "map.csv")
    assert refused(m, fit_io.read_batch, m) == f"{m}:{line}"


def test_report_in_full():
    from types import SimpleNamespace

    corr = np.array([[1.0, -0.25, 0.5], [-0.25, 1.0, 0.75], [0.5, 0.75, 1.0]])
    r = SimpleNamespace(tip=SimpleNamespace(describe=lambda: "a tip"), table=lambda: "TABLE",
                        correlation=corr, E=1234.5, E_error=56.78, warnings=("w1", "w2"))
    assert fit_io.report(r, scene_E=2e3) == (
        "tip: a tip\nTABLE\ncorrelation(E*, z_0) = -0.250\n"
        "the scene's sample E = 2 kPa; fitted E = 1.2345 kPa ± 57 Pa\n"
        "warning: w1\nwarning: w2")
    assert fit_io.report(r) == ("tip: a tip\nTABLE\ncorrelation(E*, z_0) = -0.250\n"
                                "warning: w1\nwarning: w2")
    r.E = None  # no Poisson's ratio: no E to compare
    assert "sample E" not in fit_io.report(r, scene_E=2e3)


# -- the tip of a scene -------------------------------------------------------------------------
def scene_file(tmp_path, tip, sample='shape = "flat"\nE = "20 kPa"\nnu = 0.5'):
    path = tmp_path / "s.toml"
    path.write_text('effects = ["force"]\n[load]\ndepth = "1 um"\n'
                    f'[[body]]\nname = "tip"\n{tip}\n[[body]]\nname = "gel"\n{sample}\n')
    return path


def test_tip_from_scene_returns_the_tip_and_both_materials(tmp_path):
    p = scene_file(tmp_path, 'shape = "sphere"\nradius = "2 um"\nE = "170 GPa"\nnu = 0.28')
    tip, nu, E, tip_E, tip_nu = fit_io.tip_from_scene(p)
    assert repr(tip) == repr(fit.Paraboloid(R=2e-6))
    assert (nu, E, tip_E, tip_nu) == (0.5, 20e3, 170e9, 0.28)
    p = scene_file(tmp_path, 'shape = "cone"\nangle = "70 deg"\nrigid = true')
    tip, nu, E, tip_E, tip_nu = fit_io.tip_from_scene(p)
    assert repr(tip) == repr(fit.Cone(theta=math.radians(70)))
    assert (tip_E, tip_nu) == (None, None)


@pytest.mark.parametrize("tip,sample,words", [
    ('shape = "flat"\nE = "1 GPa"\nnu = 0.3', 'shape = "flat"\nE = "20 kPa"\nnu = 0.5',
     "body: a fit needs one flat body (the sample) and one tip; this scene has 2 flat bodies"),
    ('shape = "sphere"\nradius = "2 um"\nE = "1 GPa"\nnu = 0.3', 'shape = "flat"\nrigid = true',
     "body (gel): the sample is rigid; give its E and nu (E is shown for comparison, nu "
     "converts E* to E)"),
    ('shape = "cylinder"\nradius = "2 um"\nlength = "1 mm"\nrigid = true', None,
     "body (tip).shape: 'cylinder' has no fit model yet; tips: sphere, exact_sphere, cone, "
     "pyramid, flat_punch, power_law, profile"),
])
def test_tip_from_scene_refusals(tmp_path, tip, sample, words):
    p = scene_file(tmp_path, tip, *([sample] if sample else []))
    assert refused(p, fit_io.tip_from_scene, p) == f"{p}: {words}"


def test_tip_from_scene_names_the_tip_a_model_refuses(tmp_path, monkeypatch):
    def refuse(p):
        raise ValueError("R = 2e-06 m: a test refusal")

    monkeypatch.setitem(fit_io.TIP_SHAPES, "sphere", refuse)
    p = scene_file(tmp_path, 'shape = "sphere"\nradius = "2 um"\nrigid = true')
    assert refused(p, fit_io.tip_from_scene, p) == f"{p}: body (tip): R = 2e-06 m: a test refusal"
