"""Line contact (5.34)-(5.37) by the numerical 2-D displacement gradient of the pressure.

The 2-D kernel is checked first: the x-derivative of the point-load displacement (5.6),
integrated along the line by quadrature, is -2/(pi E* x). The gradient of the displacement
under p0 sqrt(1 - s^2/a^2) is then -(2/(pi E*)) PV int p(s)/(x - s) ds, evaluated by mpmath
with the singularity subtracted: PV int f(s)/(x - s) ds = int (f(s) - f(x))/(x - s) ds +
f(x) ln((a + x)/(a - x)), tanh-sinh split at s = x. For the unit strip this gives the constant
K1 = PV(x)/x (no closed form used); matching -x/R gives p0 = pi E* a/(2 K1 R), the force per
length is the pressure integrated by quadrature. The depth is the chapter's convention
a = sqrt(R d) (5.35).
"""

from functools import cache

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import line

from named import assert_inputs_named
from oracle import Arg, assert_close, assert_mpmath_equal, n_points

E_DOM = Arg(1e3, 1e12)
R_DOM = Arg(1e-9, 1e3)
STRAIN = Arg(1e-12, 1e-1)  # d/R
L_DOM = Arg(1e-6, 1e2)
F_DOM = Arg(1e-6, 1e8)
# products, quotients and square roots, each correctly rounded: a few ulps.
TOL = 1e-14


def pv_gradient_integral(f, x, a):
    """PV int_-a^a f(s)/(x - s) ds for |x| < a, by subtracting the singularity."""
    fx = f(x)
    smooth = mp.quad(lambda s: (f(s) - fx) / (x - s), [-a, x, a])
    return smooth + fx * mp.log((a + x) / (a - x))


@cache
def K1():
    """PV int_-1^1 sqrt(1 - s^2)/(x - s) ds / x on the unit strip, at x = 0.3 and 0.8: the
    ratio must not depend on x (else no p0 would match -x/R); 40 digits."""
    with mp.workdps(40):
        f = lambda s: mp.sqrt(1 - s**2)  # noqa: E731
        xs = [mp.mpf("0.3"), mp.mpf("0.8")]
        k = [pv_gradient_integral(f, x, 1) / x for x in xs]
        assert abs(k[0] / k[1] - 1) < mp.mpf(10) ** -35
        return +k[0]


def reference(E_star, R, a):
    """(p0, F/L) of the line contact of half-width a; call inside mp.workdps. Kept by its
    arguments and the working precision (a pure function of them): test_line_sweep checks two
    functions at the same points and three inverses by the same root finding on F/L."""
    key = (E_star, R, a, mp.mp.prec)
    if key not in _REFERENCES:
        p0 = mp.pi * E_star * a / (2 * K1() * R)
        F_L = mp.quad(lambda s: p0 * mp.sqrt(1 - (s / a) ** 2), [-a, a])
        _REFERENCES[key] = p0, F_L
    return _REFERENCES[key]


_REFERENCES: dict = {}


def test_line_by_displacement_gradient():
    E, R, d, L = 2.1e11, 0.05, 1e-6, 0.02
    with mp.workdps(30):
        # the 2-D kernel from (5.6) along the line: d/dx int dy/(pi E* sqrt(x^2 + y^2))
        xk = mp.mpf("0.37")
        k = mp.quad(lambda y: -xk / (mp.pi * E * (xk**2 + y**2) ** 1.5), [-mp.inf, 0, mp.inf])
        assert abs(k / (-2 / (mp.pi * E * xk)) - 1) < 1e-25
        a = mp.sqrt(mp.mpf(R) * d)  # (5.35)
        p0, F_L = reference(mp.mpf(E), mp.mpf(R), a)
        # the matched pressure reproduces du/dx = -x/R across the strip
        for s in ("0.1", "0.5", "0.95"):
            x = mp.mpf(s) * a
            grad = -2 / (mp.pi * E) * pv_gradient_integral(
                lambda t: p0 * mp.sqrt(1 - (t / a) ** 2), x, a)
            assert abs(grad / (-x / R) - 1) < 1e-25, s
            assert_close(gen.line_pressure(E, R, d, float(x)), p0 * mp.sqrt(1 - (x / a) ** 2),
                         TOL, "(5.36)")
        assert_close(gen.line_half_width(R, d), a, TOL, "(5.35)")
        assert_close(gen.line_max_pressure_from_half_width(E, R, float(a)), p0, TOL, "p0(a)")
        assert_close(gen.line_force_per_length_from_half_width(E, R, float(a)), F_L, TOL, "F/L")
        assert_close(gen.line_force(E, L, d), L * F_L, TOL, "(5.34)")
        assert_close(gen.line_max_pressure(E, R, d), p0, TOL, "(5.37) second form")
        assert_close(gen.line_max_pressure_depth_width(E, float(a), d), p0, TOL,
                     "(5.37) first form")
        F = float(L * F_L)
        assert_close(gen.line_max_pressure_from_force(E, F, L, R), p0, TOL, "(5.37) third form")
        assert_close(gen.line_half_width_from_force(E, F, L, R), a, TOL, "a(F)")
        assert_close(gen.line_depth_from_force(E, F, L), d, TOL, "d(F)")
        # the chapter's third form of (5.37) lacks a pi: sqrt(pi) times too large
        printed = mp.sqrt(E * F / (L * R))
        assert abs(printed / p0 - mp.sqrt(mp.pi)) < 1e-13
    assert gen.line_pressure(E, R, d, 2 * float(a)) == 0.0


@pytest.mark.sweep
def test_line_sweep():
    n = n_points(200, 30)
    doms = {"E_star": E_DOM, "R": R_DOM, "strain": STRAIN}

    def ref_d(which):
        def ref(E_star, R, strain):
            p0, F_L = reference(E_star, R, mp.sqrt(R * strain * R))
            return p0 if which == "p0" else F_L
        return ref

    assert_mpmath_equal(lambda E_star, R, strain: gen.line_max_pressure(E_star, R, strain * R),
                        ref_d("p0"), doms, rtol=TOL, n=n, dps=35, name="line_max_pressure")
    assert_mpmath_equal(lambda E_star, R, strain: gen.line_force(E_star, 1.0, strain * R),
                        ref_d("F_L"), doms, rtol=TOL, n=n, dps=35, name="line_force")

    def ref_F(which):
        def ref(E_star, F, L, R):
            # a whose force L F/L(a) is F: F/L is proportional to a^2 by the quadrature's own
            # scaling, checked by findroot on the quadrature
            a = mp.findroot(lambda x: L * reference(E_star, R, x)[1] - F,
                            mp.sqrt(F * R / (E_star * L)))
            return {"a": a, "p0": reference(E_star, R, a)[0], "d": a**2 / R}[which]
        return ref

    fdoms = {"E_star": E_DOM, "F": F_DOM, "L": L_DOM, "R": R_DOM}
    m = n_points(60, 10)
    assert_mpmath_equal(gen.line_max_pressure_from_force, ref_F("p0"), fdoms, rtol=TOL, n=m,
                        dps=35, name="line_max_pressure_from_force")
    assert_mpmath_equal(gen.line_half_width_from_force, ref_F("a"), fdoms, rtol=TOL, n=m,
                        dps=35, name="line_half_width_from_force")
    assert_mpmath_equal(lambda E_star, F, L, R: gen.line_depth_from_force(E_star, F, L),
                        ref_F("d"), fdoms, rtol=TOL, n=m, dps=35, name="line_depth_from_force")


def test_line_stiffness_by_derivative():
    """dF/dd of the quadrature force (d from (5.35), a = sqrt(R d)) by mpmath's numerical
    derivative at 35 digits; the float64 closed form is one product (1e-15)."""
    E, R, L = 2e11, 0.01, 0.02
    for d in (1e-9, 1e-6):
        with mp.workdps(35):
            k = mp.diff(lambda x: L * reference(mp.mpf(E), mp.mpf(R), mp.sqrt(R * x))[1],
                        mp.mpf(d))
        assert abs(gen.line_stiffness(E, L) / k - 1) < 1e-15


@given(st.floats(1e-9, 1e-1), st.floats(1e-6, 1e2), st.floats(1e3, 1e12),
       st.floats(1.0 + 1e-9, 10.0))
def test_force_increases_and_inverts(d, L, E, factor):
    F = line.force(d, L, E)
    assert line.force(d * factor, L, E) > F
    assert abs(line.depth_from_force(F, L, E) / d - 1) < 1e-14
    R = 0.01
    assert abs(line.half_width_from_force(F, L, R, E) / line.half_width(d, R) - 1) < 1e-14
    assert abs(line.max_pressure_from_force(F, L, R, E) / line.max_pressure(d, R, E) - 1) < 1e-14


def test_bad_input():
    with pytest.raises(ValueError, match=r"L = 0\.0 is out of range"):
        line.force(1e-6, 0.0, 1e9)
    with pytest.raises(ValueError, match="x"):
        line.pressure(float("nan"), 1e-6, 0.01, 1e9)


@pytest.mark.sweep
def test_line_half_width_forms_sweep():
    """p0(a), F/L(a), the first form of (5.37) and the pressure (5.36), over the decades."""
    doms = {"E_star": E_DOM, "R": R_DOM, "strain": STRAIN}
    n = n_points(200, 20)

    def at(E_star, R, strain):
        a = mp.sqrt(R * strain * R)
        return a, reference(E_star, R, a)

    # a = sqrt(R d) is rounded in float64 before the call (1 ulp), exact in the reference
    assert_mpmath_equal(
        lambda E_star, R, strain: gen.line_max_pressure_from_half_width(
            E_star, R, gen.line_half_width(R, strain * R)),
        lambda **kw: at(**kw)[1][0], doms, rtol=TOL, n=n, dps=35,
        name="line_max_pressure_from_half_width")
    assert_mpmath_equal(
        lambda E_star, R, strain: gen.line_force_per_length_from_half_width(
            E_star, R, gen.line_half_width(R, strain * R)),
        lambda **kw: at(**kw)[1][1], doms, rtol=TOL, n=n, dps=35,
        name="line_force_per_length_from_half_width")
    assert_mpmath_equal(
        lambda E_star, R, strain: gen.line_max_pressure_depth_width(
            E_star, gen.line_half_width(R, strain * R), strain * R),
        lambda **kw: at(**kw)[1][0], doms, rtol=TOL, n=n, dps=35,
        name="line_max_pressure_depth_width")
    assert_mpmath_equal(
        lambda E_star, R, strain: gen.line_half_width(R, strain * R),
        lambda **kw: at(**kw)[0], doms, rtol=TOL, n=n, dps=35, name="line_half_width")

    # the pressure at x = frac * a, frac in [0, 0.9]: sqrt(1 - frac^2) is well conditioned
    def p_float(E_star, R, strain, frac):
        d = strain * R
        return gen.line_pressure(E_star, R, d, frac * gen.line_half_width(R, d))

    def p_ref(E_star, R, strain, frac):
        return at(E_star, R, strain)[1][0] * mp.sqrt(1 - frac**2)

    assert_mpmath_equal(p_float, p_ref, {**doms, "frac": Arg(0.0, 0.9, log=False)}, rtol=TOL,
                        n=n, dps=35, name="line_pressure")


# the public functions with one valid set of inputs each (SI: m, Pa, N)
PUBLIC = [
    (line.half_width, dict(d=1e-6, R=0.01)),
    (line.force, dict(d=1e-6, L=0.02, E_star=1e11)),
    (line.depth_from_force, dict(F=10.0, L=0.02, E_star=1e11)),
    (line.half_width_from_force, dict(F=10.0, L=0.02, R=0.01, E_star=1e11)),
    (line.max_pressure, dict(d=1e-6, R=0.01, E_star=1e11)),
    (line.max_pressure_from_force, dict(F=10.0, L=0.02, R=0.01, E_star=1e11)),
    (line.pressure, dict(x=1e-5, d=1e-6, R=0.01, E_star=1e11)),
]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[f.__name__ for f, _ in PUBLIC])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def test_public_functions_against_the_gradient_reference():
    """The validated wrappers (the tests above check the generated functions), at inputs of
    distinct magnitudes so that an input in the wrong place changes the value, against p0 and
    F/L of the pressure that reproduces du/dx = -x/R (reference above), a = sqrt(R d) (5.35)."""
    E, R, d, L = 2.1e11, 0.05, 1e-6, 0.02
    with mp.workdps(30):
        a = mp.sqrt(mp.mpf(R) * d)
        p0, F_L = reference(mp.mpf(E), mp.mpf(R), a)
        F = F_L * L
        x = a / 3
        p_x = p0 * mp.sqrt(1 - (x / a) ** 2)
    assert_close(line.half_width(d, R), a, TOL, "(5.35)")
    assert_close(line.force(d, L, E), F, TOL, "(5.37)")
    assert_close(line.max_pressure(d, R, E), p0, TOL, "p0")
    assert_close(line.depth_from_force(float(F), L, E), d, TOL, "(5.37) inverted")
    assert_close(line.half_width_from_force(float(F), L, R, E), a, TOL, "a(F)")
    assert_close(line.max_pressure_from_force(float(F), L, R, E), p0, TOL, "p0(F)")
    assert_close(line.pressure(float(x), d, R, E), p_x, TOL, "(5.36)")
    assert line.pressure(float(a) * 1.001, d, R, E) == 0.0
    with pytest.raises(ValueError, match="x = .*must be finite"):
        line.pressure(np.inf, d, R, E)
