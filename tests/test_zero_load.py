"""Zero load is a valid point of a sweep (issue 12): ``depth = {from = 0, ...}`` and force
sweeps from 0 give zero force, an empty (or, for a flat punch, a just-touching) contact and
zero pressure, for every kind; and the numeric functions beneath them take the zero load.

The values at zero load are exact (no contact, no pressure), so they are compared exactly; the
second point of each sweep only has to be a loaded contact (its accuracy is tested elsewhere).
"""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from hertzmdr.numeric import bem, contact, mdr, powerlaw
from hertzmdr.numeric.scene.model import build
from hertzmdr.numeric.scene.schema import SceneError

FLAT = {"name": "half-space", "shape": "flat", "E": "70 GPa", "nu": 0.3}
#: shape -> (the indenter's table, what its unloaded contact is): 0 for a tip, else the
#: contact it already has when it just touches (a flat punch's radius, a worn tip's flat)
BODIES = {
    "sphere": ({"shape": "sphere", "radius": "5 mm"}, 0.0),
    "ellipsoid": ({"shape": "ellipsoid", "radii": ["5 mm", "10 mm"]}, 0.0),
    "cylinder": ({"shape": "cylinder", "radius": "5 mm", "length": "10 mm", "axis": "0 deg"},
                 0.0),
    "cone": ({"shape": "cone", "angle": "30 deg"}, 0.0),
    "flat_punch": ({"shape": "flat_punch", "radius": "1 mm"}, 1e-3),
    "power_law": ({"shape": "power_law", "coefficient": 1e6, "exponent": 3}, 0.0),
    "flattened_parabola": ({"shape": "flattened_parabola", "radius": "50 um",
                            "flat_radius": "2 um"}, 2e-6),
    "exact_sphere": ({"shape": "exact_sphere", "radius": "1 mm"}, 0.0),
    "profile": ({"shape": "profile", "r": ["0 um", "10 um", "20 um", "40 um"],
                 "f": ["0 um", "0.05 um", "0.2 um", "0.8 um"]}, 0.0),
    "polygon_punch": ({"shape": "polygon_punch", "pixels": 16,
                       "vertices": [["0 mm", "0 mm"], ["1 mm", "0 mm"], ["0 mm", "1 mm"]]},
                      None),  # the footprint's pixels
}
#: the load-dependent scalar effects; a kind is asked for those it has
SCALARS = ("depth", "force", "contact_radius", "semi_axes", "half_width", "contact_area",
           "max_pressure", "mean_pressure", "stiffness", "elastic_energy")
#: effects whose value at zero load is the just-touching contact's, not 0
SIZE = ("contact_radius", "semi_axes", "half_width", "contact_area")


def _scene(shape: str, load: str) -> dict:
    indenter = {**copy.deepcopy(BODIES[shape][0]), "name": shape, "rigid": True}
    to = "0.1 um" if load == "depth" else "1 mN"
    return {"effects": ["force"], "body": [indenter, dict(FLAT)],
            "load": {load: {"from": 0, "to": to, "points": 3}}}


@pytest.mark.parametrize("load", ["depth", "force"])
@pytest.mark.parametrize("shape", list(BODIES))
def test_sweep_from_zero(shape, load):
    from hertzmdr.numeric import scene

    doc = _scene(shape, load)
    c = build(scene.load(doc).spec)
    doc["effects"] = [e for e in SCALARS if c.has(e)]
    out = scene.load(doc).run()
    json.dumps(out, allow_nan=False)  # finite everywhere: no NaN at the empty contact
    eff = {k: v["value"] for k, v in out["effects"].items()}
    first = {k: np.asarray(v)[0] for k, v in eff.items()}
    assert first["force"] == 0.0
    assert first["depth"] == 0.0  # under F = 0 the BEM's depth is min(height), 0 for a punch
    for name in ("max_pressure", "mean_pressure", "elastic_energy"):
        if name in first:
            assert first[name] == 0.0, name
    touching = BODIES[shape][1]
    for name in SIZE:
        if name not in first:
            continue
        if touching is None:  # the punch's footprint: every pixel it covers
            assert first[name] == pytest.approx(np.isfinite(c.height).sum() * c.dx**2,
                                                rel=1e-12)
        else:
            assert np.all(first[name] == touching), name
    loaded = {k: np.asarray(v)[1] for k, v in eff.items()}
    if "stiffness" in first:  # 2 a E* of the just-touching contact (Problem 5): 0 for a tip
        if c.kind == "line":  # F of (5.34) is linear in d: one stiffness at every load
            assert first["stiffness"] == loaded["stiffness"] > 0
        elif touching == 0.0:
            assert first["stiffness"] == 0.0
        else:
            assert first["stiffness"] > 0.0
    assert loaded["force"] > 0 and loaded["depth"] > 0
    for name, errs in out["effects"].items():
        assert np.isfinite(errs["rel_error"]), name


def test_force_depth_curve_of_a_sweep_from_zero():
    """A field effect of a sweep from 0 is drawn at its largest load, from 0."""
    from hertzmdr.numeric import scene

    doc = _scene("profile", "depth")
    doc["effects"] = ["force_depth_curve", "pressure_profile"]
    out = scene.load(doc).run()["effects"]
    curve = out["force_depth_curve"]["value"]
    assert curve["depth"][-1] == pytest.approx(1e-7, rel=1e-15)
    assert max(out["pressure_profile"]["value"]["p"]) > 0


def test_a_single_load_of_zero_is_still_refused():
    """Only a sweep may start at 0: a scene loaded by nothing has nothing to compute."""
    from hertzmdr.numeric import scene

    doc = _scene("sphere", "depth")
    doc["load"] = {"depth": 0}
    with pytest.raises(SceneError, match=r"load\.depth: must be > 0"):
        scene.load(doc)


# -- the numeric functions beneath -----------------------------------------------------------

def test_mean_pressures_at_no_load():
    assert contact.mean_pressure(0.0, 0.0) == 0.0
    assert contact.mean_pressure_strip(0.0, 0.0, 1e-2) == 0.0
    got = contact.mean_pressure_disc([0.0, 2.0], [0.0, 1.0])
    assert got[0] == 0.0 and got[1] == pytest.approx(2 / np.pi, rel=1e-15)  # (5.17)
    for fn, args in ((contact.mean_pressure_disc, (1.0, 0.0)), (contact.mean_pressure, (1.0, 0.0)),
                     (contact.mean_pressure_strip, (1.0, 0.0, 1.0))):
        with pytest.raises(ValueError, match="carries no force"):
            fn(*args)
    with pytest.raises(ValueError, match=r"a = -1\.0 is out of range"):
        contact.mean_pressure_disc(0.0, -1.0)


@pytest.mark.parametrize("n", [1.0, 2.0, 3.0, 0.5, 50.0, np.inf])
def test_power_law_pressure_at_no_load(n):
    """p = 0 everywhere at d = 0, the cone's axis and the punch's inside too."""
    c = 1.0 if n in (1.0, np.inf) else 1e3
    assert np.all(powerlaw.pressure([0.0, 1e-9, 0.5, 2.0], 0.0, c, n, 1e9) == 0.0)


def test_numerical_mdr_at_no_load():
    """A conical sampled tip (p infinite on the axis under load) carries nothing at 0."""
    r = np.linspace(0, 1e-5, 21)
    prof = mdr.Profile.from_samples(r, 0.5 * r, k=1)
    for kw in ({"depth": 0.0}, {"force": 0.0}):
        s = prof.solve(E_star=1e9, **kw)
        assert (s.depth, s.force, s.contact_radius, s.rel_error, s.met) == (0, 0, 0, 0, True)
        p, e = s.pressure(np.array([0.0, 1e-6]), return_error=True)
        assert np.all(p == 0) and np.all(e == 0)
        assert np.all(s.displacement([0.0, 1e-6]) == 0)
        assert s.max_pressure(return_error=True) == (0.0, 0.0)
    curve = prof.force_depth_curve([0.0, 1e-6], E_star=1e9)
    assert curve.force[0] == 0.0 and curve.force[1] > 0
    with pytest.raises(ValueError, match=r"depth = -1e-09 is out of range"):
        prof.solve(depth=-1e-9, E_star=1e9)


def test_bem_at_no_load():
    """A punch just touching: its whole footprint, no pressure, the stiffness it has under
    load (a flat punch's is independent of the depth); a tip whose lowest point lies above the
    depth: no contact at all; under F = 0 the depth is where it touches."""
    h, dx = bem.polygon_punch([(0.0, 0.0), (1e-3, 0.0), (0.0, 1e-3)], 16)
    zero = bem.solve(h, dx, 1e9, depth=0.0)
    loaded = bem.solve(h, dx, 1e9, depth=1e-6)
    assert zero.force == 0 and np.all(zero.pressure == 0) and np.all(zero.displacement == 0)
    assert np.array_equal(zero.contact, np.isfinite(h))
    # the same pixel count times dx dy, summed in another order: a rounding apart
    assert zero.area == pytest.approx(loaded.area, rel=1e-15)
    assert zero.stiffness == pytest.approx(loaded.stiffness, rel=1e-8)  # both CG at tol 1e-8
    x, y, dx, _ = bem.grid(16, 1e-4)
    tip = 1e-9 + (x**2 + y**2) / 2e-3
    none = bem.solve(tip, dx, 1e9, depth=0.0)
    assert (none.force, none.area, none.stiffness, none.contact.any()) == (0, 0, 0, False)
    touch = bem.solve(tip, dx, 1e9, force=0.0)
    assert touch.depth == tip.min() and touch.contact.sum() == np.sum(tip == tip.min())
    assert touch.force == 0 and touch.stiffness > 0
