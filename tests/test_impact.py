"""Problems 3 and 4 (Hertz impact) by integrating the equation of motion and by quadrature.

Route 1, the equation of motion m x'' = -K x^(3/2) with the Hertz force (5.23), K = 4/3 E* R^(1/2),
x(0) = 0, x'(0) = v0. The scales T = (m/(K v0^(1/2)))^(2/5), X = v0 T (the ODE's own, no energy
argument) turn it into xi'' = -xi^(3/2), xi(0) = 0, xi'(0) = 1, solved once at 45 digits: a
Frobenius series xi = sum b_k s^(1 + 5k/2) starts it at s = 1/2 (x^(3/2) is not analytic at
x = 0), mpmath's Taylor integrator odefun carries it to the turning point xi' = 0, found by
findroot. The contact time is twice the time of the turning point (the motion is
time-reversible), the maximum depth is xi there.
Route 2, the time integral 2 int_0^x0 dx / v(x) by tanh-sinh quadrature, with x0 the root of
the energy balance found by findroot.
"""

import re
from functools import cache

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import hertz, impact, motion

from named import assert_inputs_named
from oracle import Arg, assert_close, assert_mpmath_equal, n_points

E_DOM = Arg(1e3, 1e12)
R_DOM = Arg(1e-9, 1e3)
V_DOM = Arg(1e-3, 1e3)
M_DOM = Arg(1e-24, 1e12)
RHO_DOM = Arg(1e2, 3e4)
# products of up to eight fractional powers, each within 1 ulp, and gamma (scipy, ~1e-16):
# about 10 ulps at worst; 1e-14 leaves margin for it.
TOL = 1e-14


def _series(n):
    """Coefficients b_k of xi = sum b_k s^(1 + 5k/2) solving xi'' = -xi^(3/2), xi'(0) = 1."""
    b, e, alpha = [mp.mpf(1)], [mp.mpf(1)], mp.mpf(3) / 2
    for j in range(n):
        if j:  # e_j: coefficient j of (sum b_k u^k)^(3/2), by the J.C.P. Miller recurrence
            e.append(sum(((alpha + 1) * k - j) * b[k] * e[j - k] for k in range(1, j + 1)) / j)
        k = j + 1
        b.append(-e[j] / ((1 + mp.mpf(5) * k / 2) * (mp.mpf(5) * k / 2)))
    return b


@cache
def turning_point():
    """(s_m, xi_m) of xi'' = -xi^(3/2): time and depth of the turning point, 45 digits."""
    with mp.workdps(45):
        b = _series(60)  # terms decay like 0.04^k at s = 1/2: 1e-80, far below 1e-45
        s0 = mp.mpf(1) / 2
        u = s0 ** (mp.mpf(5) / 2)
        xi = sum(bk * s0 * u**k for k, bk in enumerate(b))
        dxi = sum(bk * (1 + mp.mpf(5) * k / 2) * u**k for k, bk in enumerate(b))
        sol = mp.odefun(lambda s, y: [y[1], -y[0] ** (mp.mpf(3) / 2)], s0, [xi, dxi],
                        tol=mp.mpf(10) ** -45, degree=50)
        s_m = mp.findroot(lambda s: sol(s)[1], mp.mpf("1.6"))
        return +s_m, +sol(s_m)[0]


def by_equation_of_motion(E_star, R, m, v0):
    """(x0, tau) from the equation of motion; call inside mp.workdps."""
    s_m, xi_m = turning_point()
    K = 4 * E_star * mp.sqrt(R) / 3  # (5.23): F = K x^(3/2)
    T = (m / (K * mp.sqrt(v0))) ** (mp.mpf(2) / 5)
    return v0 * T * xi_m, 2 * T * s_m


def by_time_integral(E_star, R, m, v0):
    """(x0, tau) from the energy balance: x0 by findroot, tau by quadrature."""
    U = lambda x: 8 * E_star * mp.sqrt(R) * x ** (mp.mpf(5) / 2) / 15  # noqa: E731 (5.25)
    guess = (m * v0**2 / (2 * E_star * mp.sqrt(R))) ** (mp.mpf(2) / 5)
    x0 = mp.findroot(lambda x: U(x) - m * v0**2 / 2, guess)
    tau = 2 * mp.quad(lambda x: 1 / mp.sqrt(v0**2 - 2 * U(x) / m), [0, x0])
    return x0, tau


def reference(E_star, R, m, v0):
    """x0, tau, p0 (5.22), F (5.23), a (5.21) at the turning point of the equation of motion."""
    x0, tau = by_equation_of_motion(E_star, R, m, v0)
    return {"x0": x0, "tau": tau, "p0": 2 * E_star * mp.sqrt(x0 / R) / mp.pi,
            "F": 4 * E_star * mp.sqrt(R) * x0 ** (mp.mpf(3) / 2) / 3, "a": mp.sqrt(R * x0)}


NAMES = {"x0": "max_depth", "tau": "contact_time", "p0": "max_pressure", "F": "max_force",
         "a": "max_contact_radius"}


@pytest.mark.sweep
def test_impact_by_equation_of_motion():
    doms = {"E_star": E_DOM, "R": R_DOM, "m": M_DOM, "v0": V_DOM}
    for key, name in NAMES.items():
        assert_mpmath_equal(getattr(gen, f"impact_{name}"),
                            lambda key=key, **kw: reference(**kw)[key], doms, rtol=TOL,
                            n=n_points(200, 30), dps=40, name=f"impact_{name}")

    def ref_rho(key):
        return lambda E_star, R, rho, v0: reference(E_star, R, 4 * mp.pi * R**3 * rho / 3,
                                                    v0)[key]

    doms = {"E_star": E_DOM, "R": R_DOM, "rho": RHO_DOM, "v0": V_DOM}
    for key, name in NAMES.items():
        if key == "p0":
            continue
        assert_mpmath_equal(getattr(gen, f"impact_{name}_density"), ref_rho(key), doms,
                            rtol=TOL, n=n_points(200, 30), dps=40,
                            name=f"impact_{name}_density")
    # p0 of a sphere of density rho does not depend on R: any R gives the same reference
    assert_mpmath_equal(
        gen.impact_max_pressure_density,
        lambda E_star, rho, v0: ref_rho("p0")(E_star, mp.mpf("0.37"), rho, v0),
        {"E_star": E_DOM, "rho": RHO_DOM, "v0": V_DOM}, rtol=TOL, n=n_points(200, 30),
        dps=40, name="impact_max_pressure_density")


def test_impact_time_integral_agrees():
    """Route 2 at a few points: 60-digit quadrature (1 - (x/x0)^(5/2) cancels near x0, which
    costs digits), compared to 30 digits with route 1 and with the float64 functions."""
    for E, R, m, v0 in ((1e11, 0.01, 0.0327, 1.0), (3e6, 1e-6, 1e-15, 20.0),
                        (2e9, 100.0, 3e7, 0.05)):
        with mp.workdps(60):
            x0, tau = by_time_integral(*(mp.mpf(v) for v in (E, R, m, v0)))
            x0_ode, tau_ode = by_equation_of_motion(*(mp.mpf(v) for v in (E, R, m, v0)))
            assert abs(tau / tau_ode - 1) < mp.mpf(10) ** -30
            assert abs(x0 / x0_ode - 1) < mp.mpf(10) ** -30
            assert_close(gen.impact_contact_time(E, R, m, v0), tau, TOL, "tau")
            assert_close(gen.impact_max_depth(E, R, m, v0), x0, TOL, "x0")


def test_problem3_constant_294():
    """Problem 3: tau = 2.94 x0/v0; the constant is 2 int_0^1 dxi/sqrt(1 - xi^(5/2))."""
    E, R, m, v0 = 1e11, 0.01, 0.0327, 1.0
    ratio = gen.impact_contact_time(E, R, m, v0) * v0 / gen.impact_max_depth(E, R, m, v0)
    with mp.workdps(50):
        C = 2 * mp.quad(lambda t: 1 / mp.sqrt(1 - t ** (mp.mpf(5) / 2)), [0, 1])
    assert_close(ratio, C, 1e-14, "2 int dxi/sqrt(1 - xi^(5/2))")  # a ratio of two ~1e-15
    assert round(float(ratio), 2) == 2.94


def test_problem4_steel_ball():
    """Problem 4: steel on steel, E* ~ 1e11 Pa as the chapter takes it, rho = 7.8e3 kg/m^3,
    v0 = 1 m/s: p0 ~ 3.2e9 Pa (the chapter's two digits: agreement within 2 %)."""
    p0 = impact.max_pressure(1.0, 0.01, 1e11, rho=7.8e3)
    assert abs(p0 / 3.2e9 - 1) < 0.02
    # the same through the mass of a 1 cm sphere and through (5.22) at the maximum depth
    m = 4 / 3 * np.pi * 0.01**3 * 7.8e3
    assert abs(impact.max_pressure(1.0, 0.01, 1e11, m=m) / p0 - 1) < 1e-14
    x0 = impact.max_depth(1.0, 0.01, 1e11, m=m)
    assert abs(hertz.max_pressure(x0, 0.01, 1e11) / p0 - 1) < 1e-14


@given(st.floats(1e-2, 1e2), st.floats(1e-4, 1e1), st.floats(1e6, 1e12), st.floats(1e2, 2e4),
       st.floats(1.0 + 1e-6, 10.0))
def test_faster_impact_goes_deeper_and_shorter(v0, R, E, rho, factor):
    kw = dict(R=R, E_star=E, rho=rho)
    assert impact.max_depth(v0 * factor, **kw) > impact.max_depth(v0, **kw)
    assert impact.contact_time(v0 * factor, **kw) < impact.contact_time(v0, **kw)
    # mass and density forms agree
    m = 4 / 3 * np.pi * R**3 * rho
    assert abs(impact.contact_time(v0, R, E, m=m) / impact.contact_time(v0, **kw) - 1) < 1e-14
    # the maximum force is the Hertz force at the maximum depth
    x0 = impact.max_depth(v0, **kw)
    assert abs(impact.max_force(v0, **kw) / hertz.force(x0, R, E) - 1) < 1e-14
    assert abs(impact.max_contact_radius(v0, **kw) / hertz.contact_radius(x0, R) - 1) < 1e-14


def test_bad_input():
    with pytest.raises(ValueError, match="exactly one"):
        impact.max_depth(1.0, 0.01, 1e11)
    with pytest.raises(ValueError, match="exactly one"):
        impact.contact_time(1.0, 0.01, 1e11, m=1.0, rho=1.0)
    with pytest.raises(ValueError, match=r"v0 = -1\.0 is out of range"):
        impact.max_pressure(-1.0, 0.01, 1e11, rho=7.8e3)


def test_sphere_mass_by_quadrature():
    """m = integral of rho over the ball, as shells 4 pi r^2 dr, at 30 digits."""
    import mpmath as mp

    from hertzmdr.numeric import _generated as gen

    R, rho = 0.01, 7800.0
    with mp.workdps(30):
        ref = mp.quad(lambda r: rho * 4 * mp.pi * r**2, [0, R])
    # one power and three products in float64
    assert abs(gen.impact_sphere_mass(R, rho) / ref - 1) < 1e-15


# the public functions with one valid set of inputs each, by mass and by density (SI)
_BY = [dict(v0=1.0, R=0.01, E_star=1e11, m=0.03), dict(v0=1.0, R=0.01, E_star=1e11, rho=7800.0)]
PUBLIC = [(f, by) for f in (impact.max_depth, impact.contact_time, impact.max_pressure,
                            impact.max_force, impact.max_contact_radius) for by in _BY]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[f.__name__ for f, _ in PUBLIC])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def test_public_functions_against_the_equation_of_motion():
    """The validated wrappers (the sweeps above check the generated functions), by mass and
    by density, at inputs of distinct magnitudes so that an input in the wrong place changes
    the value, against the 45-digit solution of the equation of motion."""
    E, R, v0, rho = 2e11, 0.005, 3.0, 7800.0
    m = 4 * np.pi * R**3 * rho / 3
    with mp.workdps(30):
        ref = reference(mp.mpf(E), mp.mpf(R), mp.mpf(m), mp.mpf(v0))
    for key, name in NAMES.items():
        for by in (dict(m=m), dict(rho=rho)):
            # the density route adds the rounding of m = 4/3 pi R^3 rho: a few ulps more
            assert_close(getattr(impact, name)(v0, R, E, **by), ref[key], 4 * TOL, f"{name}{by}")
    with pytest.raises(ValueError, match="give exactly one"):
        impact.max_depth(v0, R, E, m=m, rho=rho)
    with pytest.raises(ValueError, match="give exactly one"):
        impact.max_depth(v0, R, E)


@pytest.mark.parametrize("rtol", [1e-13, 1e-10, 1e-6, 1e-3])
def test_motion_integrator_against_the_equation_of_motion(rtol):
    """numeric/motion.py (SciPy's DOP853 on the scaled equation) against the 45-digit Taylor
    solution: the depth, time and force of the turning point within 10 rtol (DOP853 with
    atol = 1e-3 rtol on order-1 variables: measured 0.1-0.5 rtol over the whole impact),
    at the two ends of the accepted rtol range too."""
    E, R, m, v0 = 3e10, 0.02, 0.5, 2.0
    with mp.workdps(30):
        ref = reference(mp.mpf(E), mp.mpf(R), mp.mpf(m), mp.mpf(v0))
    res = motion.integrate(v0, R, E, m, rtol=rtol)
    assert_close(res.max_depth, ref["x0"], 10 * rtol, "x0")
    assert_close(res.contact_time, ref["tau"], 10 * rtol, "tau")
    assert_close(res.max_force, ref["F"], 10 * rtol, "F")
    assert res.rtol == rtol and res.evaluations > 10


@pytest.mark.parametrize("rtol", [0.99e-13, 1.01e-3])
def test_motion_refuses_rtol_outside_its_range(rtol):
    with pytest.raises(ValueError, match="1e-13 <= rtol <= 1e-3"):
        motion.integrate(2.0, 0.02, 3e10, 0.5, rtol=rtol)


@pytest.mark.parametrize("name", list(NAMES.values()))
def test_give_exactly_one_of_mass_and_density(name):
    msg = ("m = {m}, rho = {rho}: give exactly one of the mass m [kg] and the density rho "
           "[kg/m^3]")
    func = getattr(impact, name)
    with pytest.raises(ValueError, match="^" + re.escape(msg.format(m=0.1, rho=7800.0)) + "$"):
        func(1.0, 0.01, 1e11, m=0.1, rho=7800.0)
    with pytest.raises(ValueError, match="^" + re.escape(msg.format(m=None, rho=None)) + "$"):
        func(1.0, 0.01, 1e11)


@pytest.mark.parametrize("E, R, m, v0", [(3e6, 1e-6, 1e-15, 20.0), (2e9, 100.0, 3e7, 0.05),
                                         (1e11, 1e-3, 1e-3, 1e3), (1e5, 10.0, 1e3, 1e-3),
                                         (1e5, 10.0, 1e3, 1e-6)])
def test_motion_integrator_at_any_scale(E, R, m, v0):
    """The scaled equation sees numbers of order 1 whatever the scales (the module's claim):
    the default rtol (1e-10) is met alike across 27 decades of mass and 9 of speed (measured
    4.5e-12, 1.1e-11, 6.8e-12 in depth, time and force at every one), asserted at 10 rtol."""
    with mp.workdps(30):
        ref = reference(mp.mpf(E), mp.mpf(R), mp.mpf(m), mp.mpf(v0))
    res = motion.integrate(v0, R, E, m)
    assert res.rtol == 1e-10
    assert_close(res.max_depth, ref["x0"], 1e-9, "x0")
    assert_close(res.contact_time, ref["tau"], 1e-9, "tau")
    assert_close(res.max_force, ref["F"], 1e-9, "F")


def test_motion_names_each_input_in_its_error():
    assert_inputs_named(motion.integrate, dict(v0=2.0, R=0.02, E_star=3e10, m=0.5))


def test_length_scale():
    """impact_length_scale x_s makes the equation of motion X'' = -(4/3) X^(3/2): checked as
    the scale at which the Hertz force (5.23), typed here, at x = x_s equals (4/3) m v0^2/x_s,
    at 30 digits; and the maximal depth in it is the literature's (15/16)^(2/5) x_s
    (Problem 3)."""
    for E, R, m, v0 in ((1e11, 0.01, 0.03, 1.0), (1e6, 1e-6, 1e-12, 1e-3), (5e9, 2.0, 70.0, 30.0)):
        xs = gen.impact_length_scale(E, R, m, v0)
        with mp.workdps(30):
            x = mp.mpf(xs)
            F = mp.mpf(4) / 3 * E * mp.sqrt(R) * x ** mp.mpf(1.5)
            # x_s's rounding (four powers of 1 ulp, three products: <= 7 eps) enters the
            # ratio, proportional to x_s^(5/2), 2.5-fold
            assert abs(F / (mp.mpf(4) / 3 * m * mp.mpf(v0) ** 2 / x) - 1) < 18 * 2.0**-52
            x0 = (mp.mpf(15) / 16 * m * mp.mpf(v0) ** 2 / (E * mp.sqrt(R))) ** mp.mpf(0.4)
            assert abs(x0 / ((mp.mpf(15) / 16) ** mp.mpf(0.4) * x) - 1) < 8 * 2.0**-52


def test_time_and_force_scales():
    """impact_time_scale t_s and impact_force_scale F_s turn m x'' = -F(x) (5.23), x'(0) = v0
    into X'' = -(4/3) X^(3/2), X'(0) = 1: checked at 30 digits as v0 t_s/x_s = 1, F_s t_s^2 =
    m x_s (Newton's law in the scaled variables) and the Hertz force, typed here, at x = x_s
    equal to (4/3) F_s."""
    for E, R, m, v0 in ((1e11, 0.01, 0.03, 1.0), (1e6, 1e-6, 1e-12, 1e-3), (5e9, 2.0, 70.0, 30.0),
                        (2e11, 1e-3, 1e-20, 1e3)):
        xs = mp.mpf(gen.impact_length_scale(E, R, m, v0))
        ts = gen.impact_time_scale(E, R, m, v0)
        fs = gen.impact_force_scale(E, R, m, v0)
        with mp.workdps(30):
            t, f = mp.mpf(ts), mp.mpf(fs)
            # each scale is a few products and powers of the inputs: <= 10 eps of rounding
            # each, and they enter the ratios to the first or second power
            assert abs(mp.mpf(v0) * t / xs - 1) < 16 * 2.0**-52
            assert abs(f * t**2 / (m * xs) - 1) < 32 * 2.0**-52
            F = mp.mpf(4) / 3 * E * mp.sqrt(R) * xs ** mp.mpf(1.5)
            assert abs(F / (mp.mpf(4) / 3 * f) - 1) < 32 * 2.0**-52
