"""Hard cases stay numerically stable: a catalogue.

Each case says why it is hard, computes a value with the public float64 API, and compares it
with an mpmath reference (>= 30 digits, by an independent route) within a stated bound: 1e-12
where the problem is well conditioned, otherwise its condition number times machine epsilon
(stated with the case). pytest runs with filterwarnings=error, so a case also fails on any
warning (overflow, invalid value), and on NaN.
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import hertz

from kernels import hertz_reference, uz_axisymmetric

EPS = np.finfo(float).eps
WELL = 1e-12  # the bound for well-conditioned cases


@dataclass(frozen=True)
class Case:
    name: str
    why: str
    compute: object  # () -> float64 value
    reference: object  # () -> mpf, called inside mp.workdps(DPS)
    bound: float
    bound_why: str = "well conditioned"


DPS = 35


def _hertz(E, R, d, index):
    return lambda: hertz_reference(mp.mpf(E), mp.mpf(R), mp.mpf(d))[index]


def _far_displacement(R, d, r):
    """u_z(r) of the Hertz pressure by the Boussinesq kernel."""
    def ref():
        a, p0, _ = hertz_reference(mp.mpf(1), mp.mpf(R), mp.mpf(d))
        return uz_axisymmetric(lambda gap: p0 * mp.sqrt(gap) / a, mp.mpf(r), a, 1)
    return ref


def _edge_pressure(delta):
    R, d, E = 1.0, 1e-6, 1e11

    def ref():
        a, p0, _ = hertz_reference(mp.mpf(E), mp.mpf(R), mp.mpf(d))
        r = mp.mpf(float(mp.sqrt(R * d) * (1 - mp.mpf(delta))))  # the same float r as compute
        return p0 * mp.sqrt(1 - (r / a) ** 2)

    a = np.sqrt(R * d)
    r = float(mp.sqrt(R * d) * (1 - mp.mpf(delta)))
    # p ~ sqrt(1 - r^2/a^2): the condition number in r is (r^2/a^2)/(1 - r^2/a^2) ~ 1/(2 delta),
    # and a = sqrt(R d) itself carries one rounding, amplified the same way
    kappa = 1 / (2 * delta)
    return Case(f"Hertz pressure at r = a(1 - {delta:g})",
                "sqrt(1 - r^2/a^2) of a number near 1: the difference keeps only the digits of r "
                "that differ from a",
                lambda: hertz.pressure(r, d, R, E), ref, 4 * kappa * EPS,
                f"condition number 1/(2 delta) = {kappa:.1e} times a few eps (r and a rounded)") \
        if a > 0 else None


def _tiny_force():
    """The reference force at d = 1e-20 m, R = 1e-9 m, E* = 1e12 Pa, rounded to float64."""
    with mp.workdps(DPS):
        return float(hertz_reference(mp.mpf(1e12), mp.mpf(1e-9), mp.mpf(1e-20))[2])


CASES = [
    Case("Hertz force, depth 1e-12 m on R = 1e-9 m, E* = 1e3 Pa",
         "tiny scales: d^(3/2) R^(1/2) E* ~ 3e-29 N, far below the sizes of everyday floats",
         lambda: hertz.force(1e-12, 1e-9, 1e3), _hertz(1e3, 1e-9, 1e-12, 2), WELL),
    Case("Hertz force, d = 100 m on R = 1e3 m, E* = 1e12 Pa",
         "huge scales: F ~ 4e16 N",
         lambda: hertz.force(100.0, 1e3, 1e12), _hertz(1e12, 1e3, 100.0, 2), WELL),
    Case("Hertz depth from force 4e-23 N, R = 1e-9 m, E* = 1e12 Pa",
         "tiny force with a stiff material: the inverse takes F^(2/3) of a number near the "
         "bottom of the normal range of products",
         lambda: hertz.depth_from_force(_tiny_force(), 1e-9, 1e12),
         lambda: mp.mpf(1e-20), WELL),
    Case("Hertz max pressure, E* = 1e12 Pa, R = 1e-9 m, d = 1e-12 m",
         "sqrt(d/R) of a ratio of tiny numbers",
         lambda: hertz.max_pressure(1e-12, 1e-9, 1e12), _hertz(1e12, 1e-9, 1e-12, 1), WELL),
    Case("Hertz surface displacement at r = 1e6 a",
         "the textbook outside form (2 - r^2/a^2) asin(a/r) + sqrt(r^2/a^2 - 1) cancels terms of "
         "size 1e6 to leave one of size 1e-6: 12 digits lost; the printed stable form loses none",
         lambda: hertz.surface_displacement(1e6 * np.sqrt(0.5 * 1e-6), 1e-6, 0.5),
         _far_displacement(0.5, 1e-6, 1e6 * np.sqrt(0.5 * 1e-6)), WELL),
    Case("Hertz surface displacement at r = a(1 + 1e-12)",
         "just outside the edge: asin(a/r) at an argument rounding to 1",
         lambda: hertz.surface_displacement(np.sqrt(2e-7) * (1 + 1e-12), 2e-7, 1.0),
         _far_displacement(1.0, 2e-7, np.sqrt(2e-7) * (1 + 1e-12)), WELL),
    _edge_pressure(1e-6),
    _edge_pressure(1e-10),
]


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_hard_case(case):
    got = case.compute()
    assert np.isfinite(got), f"{case.name}: {got}"
    with mp.workdps(DPS):
        ref = case.reference()
        err = float(abs((mp.mpf(float(got)) - ref) / ref))
    assert err <= case.bound, (f"{case.name}: relative error {err:.2e} > {case.bound:.2e} "
                               f"({case.bound_why}); hard because {case.why}")
