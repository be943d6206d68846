"""Rigid cone (5.38)-(5.40) against the Boussinesq kernel (5.7) and pressure quadrature.

The candidate pressure p = (E*/2) tan(theta) arccosh(a/rho) is put through the kernel
(tests/kernels.py, tanh-sinh because of the log singularity at rho = 0): it must displace the
surface as the cone, u_z = d - r tan(theta), inside the contact. The kernel at the centre of
the unit problem (a = 1, E* = 1, p = arccosh(1/rho)) gives U0 = u_z(0); by linearity and
scaling the depth of the cone at contact radius a is d = (tan(theta)/2) a U0, so
a = 2 d/(tan(theta) U0) with U0 from quadrature alone (at the centre the kernel is 1-D).
The force is the pressure integrated over the disc by 1-D quadrature (tanh-sinh copes with
the log at r = 0).
"""

from functools import cache

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import cone

from kernels import uz_axisymmetric
from named import assert_inputs_named
from oracle import FULL, Arg, assert_close, assert_mpmath_equal, n_points

E_DOM = Arg(1e3, 1e12)
D_DOM = Arg(1e-9, 1e3)
THETA = Arg(1e-4, 1.4)
# tan within 1 ulp and a handful of correctly rounded operations: a few ulps.
TOL = 1e-14


def unit_pressure(gap):
    """arccosh(1/rho) on the unit disc, as a function of gap = 1 - rho^2, without cancellation."""
    rho2 = 1 - gap
    if rho2 <= 0:  # the centre itself: a node of weight ~0 in tanh-sinh
        return mp.mpf(0)
    return mp.log((1 + mp.sqrt(gap)) / mp.sqrt(rho2))


@cache
def U0():
    """u_z(0) of the unit problem: the kernel (5.7) in polar coordinates about the centre,
    u_z(0) = (1/(pi E*)) int p(rho) 2 pi rho / rho d rho, by tanh-sinh at 40 digits."""
    with mp.workdps(40):
        return 2 * mp.quad(lambda rho: mp.acosh(1 / rho), [0, 1])


#: reference()'s results by (E*, d, theta, working precision): the sweep's checks of a, F and
#: dF/dd sample the same points (same domains, same seed), and its two inverse checks run the
#: same root finding, so each quadrature is done once (its value is a function of these alone)
_REFERENCES: dict = {}


def reference(E_star, d, theta):
    """(a, F) of the cone at depth d: a from the kernel constant, F by quadrature."""
    key = (E_star, d, theta, mp.mp.prec)
    if key not in _REFERENCES:
        tan = mp.tan(theta)
        a = 2 * d / (tan * U0())
        F = mp.quad(lambda r: E_star * tan / 2 * mp.acosh(a / r) * 2 * mp.pi * r, [0, a])
        _REFERENCES[key] = a, F
    return _REFERENCES[key]


def test_cone_by_kernel():
    """The pressure makes the cone's displacement; the generated functions match it."""
    E, d, theta = 1e9, 2e-6, 0.1
    ratios = ["0.5"] + (["0.2", "0.8", "0.97"] if FULL else [])
    with mp.workdps(20):
        a, F = reference(mp.mpf(E), mp.mpf(d), mp.mpf(theta))
        tan = mp.tan(mp.mpf(theta))
        for s in ratios:
            r = mp.mpf(s) * a
            u = uz_axisymmetric(lambda gap: E * tan / 2 * unit_pressure(gap / a**2), r, a, E,
                                method="tanh-sinh")
            # 20 digits (the 2-D tanh-sinh kernel costs ~10 s per point): 1e-17 is below the
            # float64 tolerances this test goes on to check, with 3 digits of margin
            assert abs(u / (d - r * tan) - 1) < 1e-17, s
            assert_close(gen.cone_pressure(E, d, theta, float(r)),
                         E * tan / 2 * mp.acosh(a / r), TOL, "(5.39)")
        assert_close(gen.cone_contact_radius(d, theta), a, TOL, "(5.38)")
        assert_close(gen.cone_depth(float(a), theta), d, TOL, "(5.38)")
        assert_close(gen.cone_force(E, d, theta), F, TOL, "(5.40)")
        assert_close(gen.cone_mean_pressure(E, theta), F / (mp.pi * a**2), TOL, "F/(pi a^2)")
        k = mp.diff(lambda x: reference(mp.mpf(E), x, mp.mpf(theta))[1], mp.mpf(d))
        assert_close(gen.cone_stiffness(E, d, theta), k, TOL, "dF/dd")
        assert_close(gen.cone_stiffness(E, d, theta), 2 * a * E, TOL, "Problem 5: 2 a E*")
    assert cone.pressure(0.0, d, theta, E) == np.inf
    assert cone.pressure(float(a) * 1.001, d, theta, E) == 0.0


@pytest.mark.sweep
def test_cone_sweep():
    doms = {"E_star": E_DOM, "d": D_DOM, "theta": THETA}
    n = n_points(200, 30)
    assert_mpmath_equal(lambda E_star, d, theta: gen.cone_contact_radius(d, theta),
                        lambda E_star, d, theta: reference(E_star, d, theta)[0], doms,
                        rtol=TOL, n=n, dps=35, name="cone_contact_radius")
    assert_mpmath_equal(gen.cone_force, lambda **kw: reference(**kw)[1], doms, rtol=TOL, n=n,
                        dps=35, name="cone_force")
    assert_mpmath_equal(gen.cone_stiffness,
                        lambda E_star, d, theta: 2 * reference(E_star, d, theta)[0] * E_star,
                        doms, rtol=TOL, n=n, dps=35, name="cone_stiffness")
    assert_mpmath_equal(lambda a, theta: gen.cone_depth(a, theta),
                        lambda a, theta: mp.tan(theta) * a * U0() / 2,
                        {"a": D_DOM, "theta": THETA}, rtol=TOL, n=n, dps=35, name="cone_depth")

    # the pressure inside, r/a in [1e-6, 0.9]: arccosh(a/r) amplifies the rounding of a by at
    # most 5 there (its condition number x/(sqrt(x^2 - 1) arccosh x) at x = 1/0.9)
    # (r is frac times the float64 a: its rounding, 1 ulp, is amplified by at most 5 too)
    def p_ref(E_star, d, theta, frac):
        return E_star * mp.tan(theta) / 2 * mp.acosh(1 / frac)

    def p_float(E_star, d, theta, frac):
        return gen.cone_pressure(E_star, d, theta, frac * gen.cone_contact_radius(d, theta))

    assert_mpmath_equal(p_float, p_ref, {**doms, "frac": Arg(1e-6, 0.9)}, rtol=TOL, n=n,
                        dps=35, name="cone_pressure")

    # force-controlled: the depth whose reference force is F (findroot on the quadrature)
    def inverse(which):
        def ref(E_star, F, theta):
            dd = mp.findroot(lambda x: reference(E_star, x, theta)[1] - F,
                             mp.sqrt(F * mp.tan(theta) / E_star))
            return dd if which == "d" else reference(E_star, dd, theta)[0]
        return ref

    fdoms = {"E_star": E_DOM, "F": Arg(1e-12, 1e6), "theta": THETA}
    assert_mpmath_equal(gen.cone_depth_from_force, inverse("d"), fdoms, rtol=TOL,
                        n=n_points(60, 10), dps=35, name="cone_depth_from_force")
    assert_mpmath_equal(gen.cone_contact_radius_from_force, inverse("a"), fdoms, rtol=TOL,
                        n=n_points(60, 10), dps=35, name="cone_contact_radius_from_force")


def test_pressure_near_the_edge():
    """At r = a (1 - eps) the rounding of a (1 ulp) is amplified by ~1/(2 eps): say so."""
    E, d, theta = 1e9, 2e-6, 0.1
    with mp.workdps(35):
        a = reference(mp.mpf(E), mp.mpf(d), mp.mpf(theta))[0]
        for eps in (1e-4, 1e-8):
            r = float(a * (1 - mp.mpf(eps)))
            ref = E * mp.tan(mp.mpf(theta)) / 2 * mp.acosh(a / r)
            assert_close(cone.pressure(r, d, theta, E), ref, 4e-16 / eps, f"1 - r/a = {eps}")


@given(st.floats(1e-9, 1e3), st.floats(1e-4, 1.4), st.floats(1e3, 1e12),
       st.floats(1.0 + 1e-9, 10.0))
def test_force_increases_and_inverts(d, theta, E, factor):
    F = cone.force(d, theta, E)
    assert cone.force(d * factor, theta, E) > F
    assert abs(cone.depth_from_force(F, theta, E) / d - 1) < 1e-14
    a = cone.contact_radius(d, theta)
    assert abs(cone.contact_radius_from_force(F, theta, E) / a - 1) < 1e-14
    assert abs(cone.depth(a, theta) / d - 1) < 1e-14


def test_pressure_arrays_and_bad_input():
    d, theta, E = 1e-6, 0.2, 1e9
    a = cone.contact_radius(d, theta)
    p = cone.pressure(np.array([0.0, 0.5 * a, a, 2 * a]), d, theta, E)
    assert p[0] == np.inf and 0 < p[1] < np.inf and p[2] == 0.0 and p[3] == 0.0
    assert cone.pressure(0.0, 0.0, theta, E) == 0.0  # no contact: no singularity either
    with pytest.raises(ValueError, match="theta"):
        cone.force(d, np.pi / 2, E)
    with pytest.raises(ValueError, match=r"r = -1\.0"):
        cone.pressure(-1.0, d, theta, E)


@pytest.mark.sweep
def test_cone_mean_pressure_sweep():
    def ref(E_star, theta):
        a, F = reference(E_star, mp.mpf("1e-3"), theta)  # any depth: the same mean pressure
        return F / (mp.pi * a**2)

    assert_mpmath_equal(gen.cone_mean_pressure, ref, {"E_star": E_DOM, "theta": THETA},
                        rtol=TOL, n=n_points(100, 15), dps=35, name="cone_mean_pressure")


# the public functions with one valid set of inputs each (SI: m, rad, Pa, N)
PUBLIC = [
    (cone.contact_radius, dict(d=1e-6, theta=0.1)),
    (cone.depth, dict(a=1e-5, theta=0.1)),
    (cone.force, dict(d=1e-6, theta=0.1, E_star=1e11)),
    (cone.pressure, dict(r=1e-6, d=1e-6, theta=0.1, E_star=1e11)),
    (cone.mean_pressure, dict(theta=0.1, E_star=1e11)),
    (cone.stiffness, dict(d=1e-6, theta=0.1, E_star=1e11)),
    (cone.depth_from_force, dict(F=1.0, theta=0.1, E_star=1e11)),
    (cone.contact_radius_from_force, dict(F=1.0, theta=0.1, E_star=1e11)),
]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[f.__name__ for f, _ in PUBLIC])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def test_public_functions_against_the_kernel_reference():
    """The validated wrappers (the tests above check the generated functions), at inputs of
    distinct magnitudes so that an input passed in the wrong place changes the value: a and F
    from the kernel constant and the quadrature of the pressure, F/(pi a^2), 2 a E*."""
    E, d, theta = 3e9, 2e-6, 0.3
    with mp.workdps(30):
        a, F = reference(mp.mpf(E), mp.mpf(d), mp.mpf(theta))
        p_half = E * mp.tan(mp.mpf(theta)) / 2 * mp.acosh(2)  # (5.39) at r = a/2
    assert_close(cone.contact_radius(d, theta), a, TOL, "(5.38)")
    assert_close(cone.depth(float(a), theta), d, TOL, "(5.38) inverted")
    assert_close(cone.force(d, theta, E), F, TOL, "(5.40)")
    assert_close(cone.mean_pressure(theta, E), F / (mp.pi * a**2), TOL, "F/(pi a^2)")
    assert_close(cone.stiffness(d, theta, E), 2 * a * E, TOL, "Problem 5: 2 a E*")
    assert_close(cone.depth_from_force(float(F), theta, E), d, TOL, "(5.40) inverted")
    assert_close(cone.contact_radius_from_force(float(F), theta, E), a, TOL, "a(F)")
    assert_close(cone.pressure(float(a) / 2, d, theta, E), p_half, TOL, "(5.39)")
