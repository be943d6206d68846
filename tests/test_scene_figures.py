"""The figures and the table as issue 13 asks, checked on matplotlib's objects and the table's
text: the von Mises colour bar's ticks at round values, a line contact's pressure against x,
Fig. 5.2 only where it is that figure, the contact's extent marked on every profile plot, and
a near-zero coordinate of a maximum printed as 0."""

import math

import matplotlib
import numpy as np
import pytest

from hertzmdr.numeric import plots
from hertzmdr.numeric.scene import figures, load
from hertzmdr.numeric.scene.figures import Context
from hertzmdr.numeric.scene.report import NEAR_ZERO, format_value

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


@pytest.fixture
def kept(monkeypatch):
    """Figures stay open (the drawing functions close them); closed after the test."""
    before = set(plt.get_fignums())
    real_close = plt.close
    monkeypatch.setattr(plt, "close", lambda *a, **k: None)
    yield
    for num in set(plt.get_fignums()) - before:
        real_close(num)


def _new_figure(before):
    (num,) = set(plt.get_fignums()) - before
    return plt.figure(num)


def _is_round(ticks) -> bool:
    """Evenly spaced by 1, 2, 2.5 or 5 times a power of ten, each a multiple of the step."""
    step = ticks[1] - ticks[0]
    mant = step / 10 ** math.floor(math.log10(step))
    return (any(abs(mant - m) < 1e-9 for m in (1, 2, 2.5, 5))
            and all(abs(t / step - round(t / step)) < 1e-9 for t in ticks))


def test_von_mises_colour_bar_ticks_are_round(tmp_path, kept):
    x = np.linspace(-1, 1, 21)
    X, Z = np.meshgrid(x, np.linspace(0, 1, 11))
    vm = 812.3 * np.exp(-(X**2 + (Z - 0.5) ** 2))  # top 812.3: its levels are top/40 apart
    before = set(plt.get_fignums())
    plots.draw_von_mises(tmp_path / "vm.png", X, Z, vm, xlabel="x", ylabel="z", clabel="MPa",
                         title="t")
    fig = _new_figure(before)
    cbar = fig.axes[1]
    ticks = [t for t in cbar.get_yticks() if 0 <= t <= vm.max()]
    assert len(ticks) >= 3 and _is_round(ticks), ticks


def _profile(kind, extent, fig52=False):
    r = np.linspace(0, 1.5 * extent, 31)
    return {"r": r, "p": np.maximum(0, 1 - (r / extent) ** 2) * 1e9,
            "u": 1e-6 / (1 + r / extent), "x": r, "g": r**2, "q": r}, Context(
        kind, extent, figures.EXTENT_LABELS.get(kind, "a (contact radius)"), fig52)


@pytest.mark.parametrize("kind,label", [("line", "x (across the strip) [µm]"),
                                        ("hertz", "r [µm]"), ("elliptic", "x (along a) [µm]")])
def test_pressure_axis_and_extent(tmp_path, kept, kind, label):
    """The line contact's pressure is drawn against x, across the strip; the extent is a
    dashed line at a (in the axis' units: 150 um here)."""
    value, ctx = _profile(kind, 150e-6)
    before = set(plt.get_fignums())
    figures.pressure_profile(value, "t", tmp_path / "p.png", ctx)
    ax = _new_figure(before).axes[0]
    assert ax.get_xlabel() == label
    (mark,) = [ln for ln in ax.get_lines() if ln.get_gid() == "contact-extent"]
    assert mark.get_xdata()[0] == pytest.approx(150.0)


@pytest.mark.parametrize("draw", ["surface_displacement", "mdr_profile", "traction_profile"])
def test_every_profile_plot_marks_the_extent(tmp_path, kept, draw):
    value, ctx = _profile("cone", 2e-3)
    before = set(plt.get_fignums())
    getattr(figures, draw)(value, "t", tmp_path / "f.png", ctx)
    ax = _new_figure(before).axes[0]
    (mark,) = [ln for ln in ax.get_lines() if ln.get_gid() == "contact-extent"]
    assert mark.get_xdata()[0] == pytest.approx(2.0)  # in mm


@pytest.mark.parametrize("fig52", [False, True])
def test_fig_5_2_only_where_it_is_that_figure(tmp_path, kept, fig52):
    value, ctx = _profile("cone" if not fig52 else "hertz", 1e-3, fig52)
    before = set(plt.get_fignums())
    figures.surface_displacement(value, "t", tmp_path / "u.png", ctx)
    assert ("Fig. 5.2" in _new_figure(before).axes[0].get_title()) is fig52


def _run(body, effects):
    sc = load({"effects": effects, "body": [body, {"shape": "flat", "E": "100 GPa",
                                                     "nu": 0.3}], "load": {"force": "1 kN"}})
    record, results, doc = sc.run_full()
    return figures.context_of(record), doc


def test_context_of_a_run():
    """The extent is the run's own contact radius / half-width at the largest load; Fig. 5.2
    for Hertz, not for a cone."""
    ctx, doc = _run({"shape": "sphere", "radius": "10 mm", "rigid": True}, ["contact_radius"])
    assert ctx.extent == doc["effects"]["contact_radius"]["value"] and ctx.fig52
    ctx, doc = _run({"shape": "cylinder", "radius": "10 mm", "length": "10 mm", "rigid": True},
                    ["half_width"])
    # (5.35) at the depth against the half-width from the force: a rounding apart
    assert ctx.extent == pytest.approx(doc["effects"]["half_width"]["value"], rel=1e-15)
    assert ctx.kind == "line"
    ctx, _ = _run({"shape": "cone", "angle": "10 deg", "rigid": True}, ["force"])
    assert not ctx.fig52 and ctx.extent > 0
    ctx, _ = _run({"shape": "sphere", "radius": "10 mm", "rigid": True}, ["effective_modulus"])
    assert ctx.extent is None  # no contact state evaluated: nothing to mark


def test_near_zero_position_prints_as_zero():
    """x = 3.2 pm beside z = 131 um (the search's noise, 2.5e-8 of the contact's size) prints
    as 0; an offset above NEAR_ZERO of the size is printed as it is."""
    unit = "{value: Pa, x: m, z: m}"
    text = format_value({"value": 8.1e8, "x": 3.2441e-12, "z": 1.3119e-4}, unit)
    assert "x = 0 m" in text and "z = 131.19 µm" in text
    kept_x = 3 * NEAR_ZERO * 1.3119e-4
    assert "x = 0 m" not in format_value({"value": 8.1e8, "x": kept_x, "z": 1.3119e-4}, unit)
    # a record that locates nothing (two pull-off depths) is printed as it is
    pull = format_value({"force_control": 1e-12, "depth_control": 1e-5},
                        "{force_control: m, depth_control: m}")
    assert "1 pm" in pull


def test_force_law_in_the_table():
    """The table prints K with the unit of its n (N/m^1.5) and the exponents as numbers."""
    from hertzmdr.numeric.scene.effects import EFFECTS

    text = format_value({"K": 9.8692e8, "n": 1.5, "stiffness_K": 1.4804e9, "stiffness_n": 0.5},
                        EFFECTS["force_law"].unit)
    assert text == ("K = 9.8692e+08 N/m^1.5, n = 1.5, stiffness_K = 1.4804e+09 N/m^1.5, "
                    "stiffness_n = 0.5")


def test_a_field_is_printed_with_its_number_of_points():
    """The table's line of a field counts its points (a force law's exponent n, read from the
    same kind of record, once took the count's name and printed 'field of None points')."""
    text = format_value({"r": [0.0, 1e-6, 2e-6], "p": [3e6, 2e6, 0.0]}, "{r: m, p: Pa}")
    assert text == "field of 3 points (r, p); PNG with --out", text
