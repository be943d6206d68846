"""The relations every contact shares (derive/contact.py, numeric/contact.py) and the prescribed
pressures on a disc (numeric/pressures.py), by independent routes: forces by mpmath quadrature
of a pressure, stiffness by differentiating a force that quadrature gives, the punch's depth by
a round trip through its integrated pressure."""

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import contact, pressures

from kernels import uz_axisymmetric
from named import assert_inputs_named

# a handful of correctly rounded float64 operations against a 30-digit reference
TOL_FLOAT = 1e-14

CASES = [(1e-6, 1e9), (3e-3, 2.5e8), (0.7, 1.3e11)]  # (a [m], p0 or E* [Pa])


@pytest.mark.parametrize("a, p0", CASES)
def test_mean_pressure_disc(a, p0):
    """The Hertz pressure p0 sqrt(1 - r^2/a^2) carries F = integral 2 pi r p dr (tanh-sinh at
    30 digits); its mean pressure is (2/3) p0, (5.17)."""
    with mp.workdps(30):
        F = mp.quad(lambda r: 2 * mp.pi * r * p0 * mp.sqrt(1 - (r / a) ** 2), [0, a])
        got = contact.mean_pressure_disc(float(F), a)
        assert abs(got / (mp.mpf(2) / 3 * p0) - 1) < TOL_FLOAT


@pytest.mark.parametrize("a, p0", CASES)
def test_mean_pressure_strip(a, p0):
    """The line contact's pressure p0 sqrt(1 - x^2/a^2) on a strip of length L carries
    F = L integral p dx; its mean pressure is (pi/4) p0."""
    L = 0.37
    with mp.workdps(30):
        F = L * mp.quad(lambda x: p0 * mp.sqrt(1 - (x / a) ** 2), [-a, 0, a])
        got = contact.mean_pressure_strip(float(F), a, L)
        assert abs(got / (mp.pi / 4 * p0) - 1) < TOL_FLOAT


def test_mean_pressure_area():
    """A pressure p0 (1 + x y/s^2) on a square of side s: F by 2-D quadrature, mean p0 (5/4)."""
    s, p0 = 2e-4, 3e7
    with mp.workdps(30):
        F = mp.quad(lambda x, y: p0 * (1 + x * y / s**2), [0, s], [0, s])
        got = contact.mean_pressure(float(F), s * s)
        assert abs(got / (p0 * mp.mpf(5) / 4) - 1) < TOL_FLOAT


@pytest.mark.parametrize("n", [1.0, 2.0, 3.5])
def test_stiffness_by_differentiation(n):
    """dF/dd of the power-law force F(d) = 2 E* integral_0^a (d - g(x)) dx (5.57), g = kappa c
    x^n, a from g(a) = d (5.55) by findroot, differentiated by mpmath: 2 a E* (5.12)."""
    E, c, d0 = 1.7e11, 2.0e3, 1e-7
    with mp.workdps(30):
        kappa = mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)

        def radius(d):
            return mp.findroot(lambda a: kappa * c * a**n - d, (d / (kappa * c)) ** (1 / n))

        def force(d):
            a = radius(d)
            return 2 * E * mp.quad(lambda x: d - kappa * c * x**n, [0, a])

        k = mp.diff(force, mp.mpf(d0))
        got = contact.stiffness(float(radius(mp.mpf(d0))), E)
        # mp.diff's finite differences at 30 digits are good to ~1e-20; the float64 radius
        # passed in is rounded to 1e-16
        assert abs(got / k - 1) < TOL_FLOAT


@pytest.mark.parametrize("a, E", CASES)
def test_punch_round_trip(a, E):
    """The punch pressure E* d/(pi sqrt(a^2 - r^2)) (5.9) integrated over the disc (tanh-sinh
    copes with the edge singularity) gives the force; the force gives back the depth."""
    d = 3e-8
    with mp.workdps(30):
        am = mp.mpf(a)  # (a - r)(a + r) in mpmath keeps the edge r -> a exact
        F = mp.quad(lambda r: 2 * r * E * d / mp.sqrt((am - r) * (am + r)), [0, am])
        assert abs(contact.punch_force(d, a, E) / F - 1) < TOL_FLOAT
        assert abs(contact.punch_depth_from_force(float(F), a, E) / d - 1) < TOL_FLOAT


@pytest.mark.parametrize("name, n", [("uniform", 0), ("hertzian", 0.5), ("punch", -0.5)])
def test_disc_pressure_force(name, n):
    """The prescribed pressure against p0 (1 - r^2/a^2)^n at 30 digits (0 outside the disc), and
    its integral over the disc (tanh-sinh) against the force derived in derive/pressures.py."""
    a, p0 = 2e-3, 4e6
    r = np.array([0.0, 1e-4, 0.9e-3, 1.7e-3, 1.999e-3, 2e-3, 3e-3])
    got = pressures.pressure(r, name, p0, a)
    with mp.workdps(30):
        am = mp.mpf(a)
        for ri, gi in zip(r, got, strict=True):
            ref = p0 * (1 - (mp.mpf(ri) / am) ** 2) ** n if ri < a else 0
            assert (gi == 0 if ref == 0 else abs(gi / ref - 1) < TOL_FLOAT), (ri, gi, ref)
        F = mp.quad(lambda rr: 2 * mp.pi * rr * p0 * ((am - rr) * (am + rr) / am**2) ** n,
                    [0, am])
    assert abs(pressures.force(name, p0, a) / F - 1) < TOL_FLOAT


def test_disc_pressure_refuses_bad_input():
    with pytest.raises(ValueError, match="distribution"):
        pressures.pressure(0.0, "triangular", 1e6, 1e-3)
    with pytest.raises(ValueError, match="a > 0"):
        pressures.force("uniform", 1e6, -1e-3)


def test_each_input_named_in_its_error():
    """Every input of the shared relations is named in its error (tests/named.py)."""
    assert_inputs_named(contact.mean_pressure, {"F": 1.0, "A": 1e-6})
    assert_inputs_named(contact.mean_pressure_disc, {"F": 1.0, "a": 1e-3})
    assert_inputs_named(contact.mean_pressure_strip, {"F": 1.0, "a": 1e-3, "L": 0.01})
    assert_inputs_named(contact.stiffness, {"a": 1e-3, "E_star": 1e11})
    assert_inputs_named(contact.punch_force, {"d": 1e-6, "a": 1e-3, "E_star": 1e11})
    assert_inputs_named(contact.punch_depth_from_force, {"F": 1.0, "a": 1e-3, "E_star": 1e11})


@pytest.mark.parametrize("name, n", [("uniform", 0), ("hertzian", 0.5), ("punch", -0.5)])
def test_disc_surface_displacement_by_the_kernel(name, n):
    """pressures.surface_displacement inside and outside the disc (r, a and E* arrays that
    differ along the row, p0 along the column, three points inside and two outside) against
    u_z of (5.7): the Boussinesq kernel integrated over p0 (1 - rho^2/a^2)^n by 2-D
    Gauss-Legendre at 20 digits (tests/kernels.py, ~1e-18 for these pressures)."""
    r = np.array([0.0, 0.6e-3, 2.4e-3, 3e-3, 2e-2])
    a = np.array([2e-3, 1e-3, 2.5e-3, 1.5e-3, 2e-3])
    E = np.array([7e10, 2e11, 1e9, 3e10, 7e10])
    p0 = np.array([[4e6], [9e6]])
    got = pressures.surface_displacement(r, name, p0, a, E)
    assert got.shape == (2, 5)
    with mp.workdps(20):
        for k in range(5):
            u = uz_axisymmetric(lambda gap, k=k: (gap / mp.mpf(a[k]) ** 2) ** n, r[k], a[k],
                                E[k])  # p0 = 1
            # inside: a few correctly rounded operations; outside, the n = 1/2 form cancels
            # terms of relative size (r/a)^2 (test_pressures.py::test_outside_displacement_...)
            tol = TOL_FLOAT * max(1.0, (r[k] / a[k]) ** 2)
            for j in range(2):
                assert abs(got[j, k] / (p0[j, 0] * u) - 1) < tol, (name, k, got[j, k])
    # r = a belongs to the inside form; the outside one meets it there (u_z is continuous)
    a, E = 2e-3, 7e10
    edge = pressures.surface_displacement(np.array([a, a * (1 + 1e-12)]), name, 4e6, a, E)
    # 1e-12 a outside the rim u_z has moved by ~1e-12 of itself where u_z' is finite (n >= 0);
    # the punch's u_z = d (2/pi) asin(a/r) falls as sqrt(r - a): by (2/pi) sqrt(2e-12) = 9e-7
    assert abs(edge[1] / edge[0] - 1) < (1e-6 if n < 0 else 1e-10)


def test_disc_pressures_name_their_inputs():
    """Every input of numeric/pressures.py is named in its error (tests/named.py), and an
    unknown distribution is named with the valid ones."""
    def u(r, p0, a, E_star):
        return pressures.surface_displacement(r, "hertzian", p0, a, E_star)

    assert_inputs_named(u, {"r": 1e-3, "p0": 1e6, "a": 2e-3, "E_star": 1e11})
    assert_inputs_named(lambda r, p0, a: pressures.pressure(r, "punch", p0, a),
                        {"r": 1e-3, "p0": 1e6, "a": 2e-3})
    assert_inputs_named(lambda p0, a: pressures.force("uniform", p0, a), {"p0": 1e6, "a": 2e-3})
    with pytest.raises(ValueError, match=r"^distribution = 'cone' is not one of uniform, "
                                         r"hertzian, punch$"):
        pressures.surface_displacement(0.0, "cone", 1e6, 2e-3, 1e11)
