"""Every effect of a sampled-profile scene (the numerical MDR kind) reports a ``rel_error`` that
bounds its actual error against a 30-digit reference of the analytic profile the samples come
from (issue 12: the scene's force-depth curve once reported 1e-14 against an actual 1e-7).

The references are those of tests/test_mdr_bounds.py, by independent quadratures of the
chapter's integrals (5.52), (5.55), (5.57), (5.59), (5.60) at 30 digits. Field effects report
max |error| / max |value| over their points, and are checked at a subsample of them in that
same measure; the pressure profile against (5.59) at the solution's own contact radius (its
bound leaves the error of a to ``contact_radius``, as ``mdr.Solution.pressure`` documents).
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import test_mdr_bounds as ref

from hertzmdr.numeric import scene

EFFECTS = ["force", "contact_radius", "mean_pressure", "stiffness", "max_pressure",
           "pressure_profile", "surface_displacement", "mdr_profile", "force_depth_curve"]
#: (case of test_mdr_bounds, depth [m]): a smooth sphere, and the issue-12 sphere-cone tip
#: whose f'' jumps at the tangent point
CASES = [(0, 40e-9), (4, 100e-9)]
STEP = 40  # every 40th point of a field effect's 201 (the edge region included: 120 of 201)


def _run(case, d):
    doc = {"effects": EFFECTS, "load": {"depth": d},
           "body": [{"shape": "profile", "r": list(case.r), "f": list(case.f), "rigid": True},
                    {"shape": "flat", "E": ref.E, "nu": 0.0}]}  # E* = E with nu = 0
    return scene.load(doc).run()["effects"]


def _field_error(got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    return float(np.max(np.abs(got - want)) / np.max(np.abs(got)))


def measured(index, d):
    """effect -> (reported rel_error, actual error)."""
    case = ref._cases()[index]
    out = _run(case, d)
    a_sol = out["contact_radius"]["value"]
    pp, us, gs = (out[k]["value"] for k in ("pressure_profile", "surface_displacement",
                                             "mdr_profile"))
    curve = out["force_depth_curve"]["value"]
    with mp.workdps(ref.DPS):
        a, F = ref.reference(case, d)
        p_axis = ref.p_ref(case, a, 0)
        # the largest pressure of these convex profiles is on the axis: check it is
        assert all(ref.p_ref(case, a, x * a) < p_axis for x in (0.2, 0.5))
        ir = [i for i in range(0, len(pp["r"]), STEP) if pp["r"][i] < a_sol]
        p_want = [ref.p_ref(case, a_sol, pp["r"][i]) for i in ir]
        iu = range(0, len(us["r"]), STEP)
        u_want = [ref.u_ref(case, a, d, us["r"][i]) for i in iu]
        ig = range(0, len(gs["x"]), STEP)
        g_want = [ref.g_ref(case, gs["x"][i]) for i in ig]
        ic = [0, len(curve["depth"]) // 2, len(curve["depth"]) - 1]
        F_curve = [ref.reference(case, curve["depth"][i])[1] for i in ic]
        actual = {
            "force": abs(out["force"]["value"] / F - 1),
            "contact_radius": abs(a_sol / a - 1),
            "mean_pressure": abs(out["mean_pressure"]["value"] / (F / (mp.pi * a * a)) - 1),
            "stiffness": abs(out["stiffness"]["value"] / (2 * a * ref.E) - 1),
            "max_pressure": abs(out["max_pressure"]["value"] / p_axis - 1),
            "pressure_profile": _field_error([pp["p"][i] for i in ir], p_want),
            "surface_displacement": _field_error([us["u"][i] for i in iu], u_want),
            "mdr_profile": _field_error([gs["g"][i] for i in ig], g_want),
            "force_depth_curve": max(abs(curve["force"][i] / Fr - 1)
                                     for i, Fr in zip(ic, F_curve, strict=True)),
        }
    return {k: (out[k]["rel_error"], float(v)) for k, v in actual.items()}


@pytest.mark.parametrize("index, d", CASES)
def test_every_effect_bound_holds(index, d):
    rows = measured(index, d)
    bad = {k: v for k, v in rows.items() if v[0] < v[1]}
    assert not bad, f"reported rel_error below the actual error (effect: (bound, error)): {bad}"
    # and the bounds are the solver's, not the closed forms' 1e-14: the issue-12 tip's force
    # error is ~1e-7 (test_mdr_bounds), so its bound cannot be below that
    if index == 4:
        assert rows["force_depth_curve"][0] > 1e-9 and rows["force"][0] > 1e-9


if __name__ == "__main__":
    for index, d in CASES:
        for k, (bd, err) in measured(index, d).items():
            print(f"{ref._cases()[index].name[:30]:30} {k:22} bound {bd:.1e} actual {err:.1e}")
