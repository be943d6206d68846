"""(5.10)-(5.17), Fig. 5.2 and Problem 6 against the Boussinesq kernel (5.7), by 2-D quadrature.

The kernel quadrature (tests/kernels.py) at 35 digits is accurate to about 1e-33 (tanh-sinh
on smooth integrands split at the rim; checked against 50 digits when it was written), so the
derived expressions, evaluated at 35 digits, must agree to 1e-30; the float64 functions to a
few ulps (a handful of correctly rounded operations: 1e-14).
"""

from functools import cache

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen

from kernels import force_axisymmetric, uz_axisymmetric
from oracle import FULL, Arg, assert_close, assert_mpmath_equal, n_points

DPS = 35
TOL_DERIVED = 1e-30  # kernel quadrature error ~1e-33 at 35 digits
TOL_FLOAT = 1e-14  # a handful of correctly rounded float64 operations


def punch(p0, a):
    return lambda gap: p0 * a / mp.sqrt(gap)  # (5.9): p0 (1 - rho^2/a^2)^(-1/2)


def hertzian(p0, a):
    return lambda gap: p0 * mp.sqrt(gap) / a  # (5.15): p0 (1 - rho^2/a^2)^(1/2)


# r/a = 0.99 is the closest the default run goes: at 0.999 the outer integrand varies on a
# scale of 0.05 near phi = pi/2 and the check costs a minute; 0.25 (8 s) repeats what the
# centre and 0.7 show, that u does not depend on r (HERTZMDR_SWEEP=full runs both)
@pytest.mark.parametrize("r_over_a", ["0", "0.7", "0.99"]
                         + (["0.25", "0.999"] if FULL else []))
def test_punch_displacement_by_kernel(r_over_a):
    E, a, p0 = 2.1e11, 3e-3, 4.5e8
    with mp.workdps(DPS):
        u = uz_axisymmetric(punch(mp.mpf(p0), mp.mpf(a)), mp.mpf(r_over_a) * a, a, E)
        # uniform inside (5.10): the value does not depend on r
        assert_close(gen.punch_pressure_displacement(E, a, p0), u, TOL_FLOAT, "(5.10)")


@pytest.mark.parametrize("r_over_a", ["0", "0.5", "0.95", "1"])
def test_hertz_displacement_by_kernel(r_over_a):
    E, a, p0 = 7.0e10, 2e-4, 1.3e9
    with mp.workdps(DPS):
        r = mp.mpf(r_over_a) * a
        u = uz_axisymmetric(hertzian(mp.mpf(p0), mp.mpf(a)), r, a, E)
        assert_close(gen.hertz_pressure_displacement(E, a, p0, float(r)), u, TOL_FLOAT, "(5.16)")


@pytest.mark.parametrize("r_over_a", ["1.0001", "1.5", "10", "1e4"])
def test_outside_displacement_by_kernel(r_over_a):
    E, a, p0 = 1.0e9, 1e-3, 2e6
    with mp.workdps(DPS):
        r = mp.mpf(r_over_a) * a
        u_h = uz_axisymmetric(hertzian(mp.mpf(p0), mp.mpf(a)), r, a, E)
        u_p = uz_axisymmetric(punch(mp.mpf(p0), mp.mpf(a)), r, a, E)
        # the punch form 2 a p0 asin(a/r)/E* has no cancellation: full float64 accuracy
        assert_close(gen.punch_pressure_displacement_outside(E, a, p0, float(r)), u_p,
                     TOL_FLOAT, "punch outside")
        # the n = 1/2 textbook form cancels terms of relative size (r/a)^2: allow that many ulps
        tol = TOL_FLOAT * max(1.0, float(r / a) ** 2)
        assert_close(gen.hertz_pressure_displacement_outside(E, a, p0, float(r)), u_h, tol,
                     "Hertz outside, textbook form")
        # the stable form of hertzmdr.derive.hertz (in terms of d and R) keeps full accuracy
        R = a**2 / 1e-6  # any R, with d = a^2/R; p0 = 2 E* sqrt(d/R)/pi fixes the scale below
        d = a**2 / R
        scale = (2 * E * mp.sqrt(mp.mpf(d) / R) / mp.pi) / p0
        assert_close(gen.hertz_displacement_outside(R, d, float(r)), u_h * scale, TOL_FLOAT,
                     "Hertz outside, stable form")


def test_force_by_quadrature():
    a, p0 = 5e-3, 3e8
    with mp.workdps(50):
        f_p = force_axisymmetric(lambda r: p0 / mp.sqrt(1 - (r / a) ** 2), mp.mpf(a))
        f_h = force_axisymmetric(lambda r: p0 * mp.sqrt(1 - (r / a) ** 2), mp.mpf(a))
    assert_close(gen.punch_pressure_force(a, p0), f_p, TOL_FLOAT, "(5.11)")
    assert_close(gen.hertz_pressure_force(a, p0), f_h, TOL_FLOAT, "(5.17)")
    with mp.workdps(50):
        f_u = force_axisymmetric(lambda r: mp.mpf(p0), mp.mpf(a))
    assert_close(gen.uniform_pressure_force(a, p0), f_u, TOL_FLOAT, "uniform")


def test_punch_stiffness_by_kernel():
    # k = F / u_z with both from quadrature: F from the pressure, u_z from the kernel at r = 0
    E, a, p0 = 2e11, 1e-2, 1.0
    with mp.workdps(DPS):
        F = force_axisymmetric(lambda r: p0 / mp.sqrt(1 - (r / a) ** 2), mp.mpf(a))
        u = uz_axisymmetric(punch(mp.mpf(p0), mp.mpf(a)), 0, a, E)
        assert_close(gen.punch_stiffness(E, a), F / u, TOL_FLOAT, "(5.12)")


def test_uniform_by_kernel():
    E, a, p0 = 1e8, 0.02, 5e5
    with mp.workdps(DPS):
        uniform = lambda gap: mp.mpf(p0)  # noqa: E731
        centre = uz_axisymmetric(uniform, 0, a, E)
        edge = uz_axisymmetric(uniform, a, a, E)
        assert_close(gen.uniform_pressure_displacement_centre(E, a, p0), centre, TOL_FLOAT, "u(0)")
        assert_close(gen.uniform_pressure_displacement_edge(E, a, p0), edge, TOL_FLOAT, "u(a)")
        for s in ("0", "0.5", "0.99", "1"):
            r = mp.mpf(s) * a
            u = uz_axisymmetric(uniform, r, a, E)
            # scipy's ellipe is accurate to a few ulps (Cephes): the float64 tolerance holds
            assert_close(gen.uniform_pressure_displacement(E, a, p0, float(r)), u, TOL_FLOAT,
                         f"uniform u({s} a)")
        for s in ("1.0001", "2", "1e4"):  # the stable print keeps full accuracy far away
            r = mp.mpf(s) * a
            u = uz_axisymmetric(uniform, r, a, E)
            assert_close(gen.uniform_pressure_displacement_outside(E, a, p0, float(r)), u,
                         TOL_FLOAT, f"uniform u({s} a)")


def test_derived_expressions_to_30_digits():
    """The SymPy expressions themselves (not their float64 print) against the kernel."""
    import sympy as sp

    from hertzmdr.derive import pressures
    from hertzmdr.derive.symbols import E_star, a, p0, r

    vals = {E_star: sp.Integer(3), a: sp.Rational(7, 5), p0: sp.Rational(2, 3)}
    half = sp.Rational(1, 2)
    with mp.workdps(DPS):
        for n, pfun in ((half, hertzian), (-half, punch)):
            for rv, fn in ((sp.Rational(1, 2), pressures.displacement_inside),
                           (sp.Integer(3), pressures.displacement_outside)):
                a_ = mp.mpf(7) / 5
                ref = uz_axisymmetric(pfun(mp.mpf(2) / 3, a_), mp.mpf(rv), a_, 3)
                got = sp.N(fn(n).subs({**vals, r: rv}), DPS + 5)
                assert abs(mp.mpf(str(got)) / ref - 1) < TOL_DERIVED, (n, rv)


def test_arrays_broadcast():
    a = np.array([1e-3, 2e-3, 4e-3])
    np.testing.assert_allclose(gen.punch_stiffness(1e9, a), 2e9 * a, rtol=1e-15)


# -- float64 sweeps over decades -------------------------------------------------------------
# By linearity and scaling, u_z(r) = p0 a U(r/a)/E* with U the displacement of the unit load
# on the unit disc: the kernel quadrature gives U once per ratio r/a (35 digits), and the sweep
# varies E*, a and p0 over decades. The force is a 1-D quadrature of the pressure (50 digits).
RATIOS = {"inside": (0.0, 0.3, 0.8), "outside": (1.5, 10.0)}
SWEEP = {"E_star": Arg(1e3, 1e12), "a": Arg(1e-9, 1e3), "p0": Arg(1e3, 1e12)}


@cache
def _unit_displacement(kind, ratio):
    load = {"punch": punch(mp.mpf(1), mp.mpf(1)), "hertz": hertzian(mp.mpf(1), mp.mpf(1)),
            "uniform": lambda gap: mp.mpf(1)}[kind]
    with mp.workdps(DPS):
        return uz_axisymmetric(load, mp.mpf(ratio), 1, 1)


@pytest.mark.sweep
@pytest.mark.parametrize("name, kind, where", [
    ("punch_pressure_displacement", "punch", "inside"),
    ("punch_pressure_displacement_outside", "punch", "outside"),
    ("hertz_pressure_displacement", "hertz", "inside"),
    ("hertz_pressure_displacement_outside", "hertz", "outside"),
    ("uniform_pressure_displacement", "uniform", "inside"),
    ("uniform_pressure_displacement_outside", "uniform", "outside"),
])
def test_displacement_sweep(name, kind, where):
    fn = getattr(gen, name)
    for ratio in RATIOS[where]:
        U = _unit_displacement(kind, ratio)

        def func(E_star, a, p0, ratio=ratio):
            if name == "punch_pressure_displacement":  # uniform inside: no r argument
                return fn(E_star, a, p0)
            return fn(E_star, a, p0, ratio * a)

        def ref(E_star, a, p0, U=U):
            return p0 * a * U / E_star

        # the Hertz textbook form outside loses (r/a)^2 ulps (see test_outside_displacement)
        tol = TOL_FLOAT * (ratio**2 if name == "hertz_pressure_displacement_outside" else 1)
        assert_mpmath_equal(func, ref, SWEEP, rtol=tol, n=n_points(60, 8), dps=DPS, name=name)


@pytest.mark.sweep
@pytest.mark.parametrize("name, n", [("punch_pressure_force", -0.5),
                                     ("hertz_pressure_force", 0.5), ("uniform_pressure_force", 0)])
def test_force_sweep(name, n):
    def ref(a, p0):
        return force_axisymmetric(lambda r: p0 * (1 - (r / a) ** 2) ** mp.mpf(n), a)

    assert_mpmath_equal(getattr(gen, name), ref, {"a": Arg(1e-9, 1e3), "p0": Arg(1e3, 1e12)},
                        rtol=TOL_FLOAT, n=n_points(100, 12), dps=50, name=name)


# -- the largest value of a pressure over a contact (pressures.max_pressure_of) ---------------
A_DISC = 2e-4  # m


def _hertz_like(r):
    return 3e8 * np.sqrt(1 - (r / A_DISC) ** 2)


def _edge_peaked(r):
    return 1e16 * r * r * np.sqrt(1 - (r / A_DISC) ** 2)


def _off_grid(r):  # a peak at 0.31234567 a, between the grid's radii
    return 5e7 * np.exp(-(((r - 0.31234567 * A_DISC) / (0.05 * A_DISC)) ** 2))


def _references():
    """(p, largest value, where): Hertz-like at r = 0; r^2 sqrt(1 - r^2/a^2), whose derivative
    2 r (1 - r^2/a^2)^(1/2) - r^3 / (a^2 (1 - r^2/a^2)^(1/2)) vanishes at r = a sqrt(2/3),
    where it is (2/3) a^2 / sqrt(3); a Gaussian peak off the grid."""
    with mp.workdps(30):
        a = mp.mpf(A_DISC)
        edge = (float(mp.mpf(1e16) * 2 * a * a / 3 / mp.sqrt(3)),
                float(a * mp.sqrt(mp.mpf(2) / 3)))
    return [(_hertz_like, 3e8, 0.0), (_edge_peaked, *edge), (_off_grid, 5e7, 0.31234567 * A_DISC)]


@pytest.mark.parametrize("case", range(3))
def test_max_pressure_of(case):
    from hertzmdr.numeric import pressures

    p, ref, where = _references()[case]
    value, at = pressures.max_pressure_of(p, A_DISC)
    # the search locates r to 1e-12 a where p' = 0, so the value's error is quadratic in that:
    # what is left is the rounding of p (a few ulps), 1e-14 relative
    assert abs(value / ref - 1) < 1e-14
    # a flat maximum locates only to about sqrt(eps) of its curvature scale: 1e-7 a
    assert abs(at - where) < 1e-7 * A_DISC


def test_max_pressure_of_edge_cases():
    from hertzmdr.numeric import pressures

    # a conical tip's pressure is log-infinite on the axis: the largest value is +inf there
    def cone_like(r):
        with np.errstate(divide="ignore"):
            return -np.log(r / A_DISC)

    value, at = pressures.max_pressure_of(cone_like, A_DISC)
    assert value == np.inf and at == 0.0
    # an unloaded point of a sweep (a = 0): p(0)
    assert pressures.max_pressure_of(lambda r: 7.0 + 0 * r, 0.0) == (7.0, 0.0)
    with pytest.raises(ValueError, match="a"):
        pressures.max_pressure_of(_hertz_like, -1.0)
    with pytest.raises(ValueError, match="points"):
        pressures.max_pressure_of(_hertz_like, A_DISC, points=2)


def _kink(r0):
    """A pressure with a kink at r0: its maximum locates to ~eps, unlike a flat one."""
    return lambda r: 1e6 * (1 - np.abs(r - r0) / A_DISC)


def test_max_pressure_of_in_the_first_and_last_cells():
    """Maxima in the grid's first cell (0, h) and last one (a - 2h, a - h), h = a/2000: the
    search runs over the cells beside the best radius, at either end of the grid too. A kink
    locates to the search's tolerance in r: SciPy's bounded Brent stops within
    xatol/3 + sqrt(eps) |r| (xatol = 1e-12 a)."""
    from hertzmdr.numeric import pressures

    h = A_DISC / 2000
    for r0 in (0.3 * h, A_DISC - 1.3 * h):
        value, at = pressures.max_pressure_of(_kink(r0), A_DISC)
        tol = 2 * (1e-12 / 3 * A_DISC + 1.5e-8 * r0)  # twice the search's tolerance
        # the kink's value at r is 1e6 (1 - |r - r0|/a)
        assert abs(at - r0) < tol, (r0, at)
        assert abs(value / 1e6 - 1) < tol / A_DISC, (r0, value)


def test_max_pressure_of_a_narrow_peak_and_an_increasing_pressure():
    """A peak 1e-3 a wide between grid radii is found by the default 2001-point grid (a
    coarser grid would miss it); a pressure increasing to the edge gives its value at the
    last radius of the grid, a (1 - 1/(points - 1)); at a = 1 m as at a = 2 mm; the smallest
    grid, points = 3."""
    from hertzmdr.numeric import pressures

    for a in (A_DISC, 1.0):
        r0 = 0.4123 * a
        value, at = pressures.max_pressure_of(
            lambda r, a=a, r0=r0: 1 + np.exp(-(((r - r0) / (1e-3 * a)) ** 2)), a)
        # a flat maximum: the search stops within sqrt(eps) r0 = 6e-9 a of it (see above),
        # 6e-6 of the peak's width w = 1e-3 a: the value to (6e-6)^2 = 4e-11
        assert abs(value - 2) < 1e-10 and abs(at - r0) < 1e-8 * a, (a, value, at)
        value, at = pressures.max_pressure_of(lambda r, a=a: r / a, a, points=3)
        assert (value, at) == (0.5, 0.5 * a)
        value, at = pressures.max_pressure_of(lambda r, a=a: r / a, a)
        assert abs(value - (1 - 1 / 2000)) < 1e-15 and abs(at / a - (1 - 1 / 2000)) < 1e-15


def test_max_pressure_of_names_its_inputs():
    from hertzmdr.numeric import pressures

    with pytest.raises(ValueError, match=r"^a = nan"):
        pressures.max_pressure_of(_hertz_like, float("nan"))
    for bad in (True, 2.0, 2):
        with pytest.raises(ValueError, match=rf"^points = {bad!r} is out of range; valid: an "
                                             r"integer >= 3$"):
            pressures.max_pressure_of(_hertz_like, A_DISC, points=bad)
