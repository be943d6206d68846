"""(5.26)-(5.33) and Problems 1-2 by independent routes.

- E*: the surface displacement of each body from the point-load field (5.3) evaluated by
  mpmath near z = 0, the two displacements added under one pressure (Boussinesq kernel).
- R: the gap of two exact spheres z = R - sqrt(R^2 - r^2) at r << R.
- principal curvatures: the Hessian of the gap by numerical differentiation, diagonalised by
  mpmath's symmetric eigensolver at 50 digits.
- the Gaussian approximation: its force by 2-D quadrature of the pressure (5.31).
"""

import re

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import bodies, hertz

from kernels import uz_axisymmetric
from named import assert_inputs_named
from oracle import Arg, assert_close, assert_mpmath_equal, n_points

E_DOM = Arg(1e3, 1e12)
NU_DOM = Arg(-0.999, 0.5, log=False)
R_DOM = Arg(1e-9, 1e3)
ANGLE = Arg(0.01, np.pi - 0.01, log=False)
# A handful of correctly rounded float64 operations (and sin/cos/sqrt within 1 ulp); the
# stable forms have no cancellation for convex bodies: a few ulps, 1e-14 leaves 45 of them.
TOL = 1e-14


def kernel_coefficient(E, nu):
    """lim r u_z / F of the point-load field (5.3) at the surface, by mpmath at z = 1e-30 r."""
    r, z = mp.mpf(1), mp.mpf(10) ** -30
    rr = mp.sqrt(r**2 + z**2)
    uz = (1 + nu) / (2 * mp.pi * E) * (2 * (1 - nu) / rr + z**2 / rr**3)  # (5.3), F = 1
    return uz * r  # error O(z^2) = 1e-60


@pytest.mark.sweep
def test_effective_modulus_by_two_displacements():
    """(5.26): under one (Hertzian) pressure, u1 + u2 equals the displacement of one body E*."""
    E1, nu1, E2, nu2 = 2.1e11, 0.3, 7.0e10, 0.25
    a, p0 = mp.mpf("1e-3"), mp.mpf("1e9")
    with mp.workdps(35):
        press = lambda gap: p0 * mp.sqrt(gap) / a  # noqa: E731
        total = 0
        for E, nu in ((E1, nu1), (E2, nu2)):
            E_i = 1 / (mp.pi * kernel_coefficient(mp.mpf(E), mp.mpf(nu)))
            total += uz_axisymmetric(press, a / 3, a, E_i)
        Es = gen.bodies_effective_modulus(E1, nu1, E2, nu2)
        one = uz_axisymmetric(press, a / 3, a, mp.mpf(float(Es)))
        # the kernel is linear in 1/E*: the float64 E* reproduces u1 + u2 to its own accuracy
        assert_close(float(one), total, TOL, "u1 + u2 = u(E*)")

    def ref(E1, nu1, E2, nu2):
        return 1 / (mp.pi * (kernel_coefficient(E1, nu1) + kernel_coefficient(E2, nu2)))

    doms = {"E1": E_DOM, "nu1": NU_DOM, "E2": E_DOM, "nu2": NU_DOM}
    assert_mpmath_equal(gen.bodies_effective_modulus, ref, doms, rtol=TOL,
                        n=n_points(300, 40), name="bodies_effective_modulus")

    def ref_rigid(E, nu):
        return 1 / (mp.pi * kernel_coefficient(E, nu))

    assert_mpmath_equal(gen.bodies_effective_modulus_rigid, ref_rigid,
                        {"E": E_DOM, "nu": NU_DOM}, rtol=TOL, n=n_points(300, 40),
                        name="bodies_effective_modulus_rigid")


def sphere_gap_radius(R1, R2):
    """R of the gap of two exact spheres (negative R: concave) at r = 1e-25 |R|: 50 digits."""
    r = min(abs(R1), abs(R2)) * mp.mpf(10) ** -25

    def z(R):  # height R - sqrt(R^2 - r^2) of a sphere above its tangent plane, without
        # cancellation; signed (negative for concave)
        return mp.sign(R) * r**2 / (abs(R) + mp.sqrt(R**2 - r**2))

    return r**2 / (2 * (z(R1) + z(R2)))  # error O(r^2/R^2) = 1e-50


@pytest.mark.sweep
def test_effective_radius_by_gap():
    assert_mpmath_equal(gen.bodies_effective_radius, sphere_gap_radius,
                        {"R1": R_DOM, "R2": R_DOM}, rtol=TOL, n=n_points(300, 40),
                        name="bodies_effective_radius")

    # concave R2 with |R2| >= 2 R1: the curvature difference has condition number <= 3
    def concave(R1, ratio):
        return gen.bodies_effective_radius(R1, -ratio * R1)

    assert_mpmath_equal(concave, lambda R1, ratio: sphere_gap_radius(R1, -ratio * R1),
                        {"R1": R_DOM, "ratio": Arg(2.0, 1e6)}, rtol=3 * TOL,
                        n=n_points(200, 30), name="bodies_effective_radius (concave)")
    assert bodies.effective_radius(0.1, np.inf) == 0.1
    with pytest.raises(ValueError, match="sum of the curvatures"):
        bodies.effective_radius(0.1, -0.05)


def hessian_curvatures(R1a, R1b, R2a, R2b, omega):
    """Eigenvalues (large, small) of the Hessian of the gap, by mp.diff and mp.eigsy."""
    c, s = mp.cos(omega), mp.sin(omega)

    def gap(x, y):
        xi, eta = c * x + s * y, -s * x + c * y  # body 2's principal axes, turned by omega
        return (x**2 / R1a + y**2 / R1b + xi**2 / R2a + eta**2 / R2b) / 2

    hxx = mp.diff(gap, (0, 0), (2, 0))
    hyy = mp.diff(gap, (0, 0), (0, 2))
    hxy = mp.diff(gap, (0, 0), (1, 1))
    ev = mp.eigsy(mp.matrix([[hxx, hxy], [hxy, hyy]]), eigvals_only=True)
    lo, hi = sorted([ev[0], ev[1]])
    return hi, lo


@pytest.mark.sweep
def test_principal_curvatures_by_hessian():
    doms = {"R1a": R_DOM, "R1b": R_DOM, "R2a": R_DOM, "R2b": R_DOM, "omega": ANGLE}
    for name, idx in (("bodies_principal_curvature_1", 0), ("bodies_principal_curvature_2", 1)):
        assert_mpmath_equal(getattr(gen, name),
                            lambda idx=idx, **kw: hessian_curvatures(**kw)[idx], doms,
                            rtol=TOL, n=n_points(300, 40), dps=40, name=name)
    inf = mp.inf
    cyl = {"R1": R_DOM, "R2": R_DOM, "alpha": ANGLE}
    for name, idx in (("bodies_crossed_cylinders_curvature_1", 0),
                      ("bodies_crossed_cylinders_curvature_2", 1)):
        assert_mpmath_equal(
            getattr(gen, name),
            lambda R1, R2, alpha, idx=idx: hessian_curvatures(R1, inf, R2, inf, alpha)[idx],
            cyl, rtol=TOL, n=n_points(300, 40), dps=40, name=name)

    def gauss(R1, R2, alpha):
        k1, k2 = hessian_curvatures(R1, inf, R2, inf, alpha)
        return 1 / mp.sqrt(k1 * k2)

    assert_mpmath_equal(gen.bodies_crossed_cylinders_gaussian_radius, gauss, cyl, rtol=TOL,
                        n=n_points(300, 40), dps=40,
                        name="bodies_crossed_cylinders_gaussian_radius")
    # (5.32)/(5.33): at alpha = pi/2 the principal radii are the two cylinder radii
    R_1, R_2 = bodies.crossed_cylinder_radii(0.3, 0.7, np.pi / 2)
    assert abs(R_1 / 0.3 - 1) < TOL and abs(R_2 / 0.7 - 1) < TOL


def test_concave_and_flat_principal_radii():
    """A ball (R 1) in a concave spherical seat (-3) and a cylinder groove: as the Hessian."""
    with mp.workdps(40):
        for args in ((1.0, 1.0, -3.0, -3.0, 0.3), (1.0, 2.0, -5.0, np.inf, 1.1),
                     (0.5, np.inf, np.inf, np.inf, 0.0)):
            hi, lo = hessian_curvatures(*(mp.mpf(v) for v in args))
            R_1, R_2 = bodies.principal_radii(*args)
            # concave: 1/R1 - 1/|R2| has a condition number <= 2 here
            assert_close(R_1, 1 / hi, 3 * TOL, f"R_1 at {args}")
            if lo == 0:
                assert R_2 == np.inf
            else:
                assert_close(R_2, 1 / lo, 3 * TOL, f"R_2 at {args}")
    with pytest.raises(ValueError, match="not convex"):
        bodies.principal_radii(1.0, 1.0, -0.5, -0.5)


def test_problem2():
    """Problem 2: equal cylinders at pi/4. The Hessian gives R_1,2 = R/(1 +- 1/sqrt 2),
    R~ = sqrt(2) R and F = 2^(5/4)/3 E/(1 - nu^2) sqrt(R) d^(3/2): half the chapter's radii."""
    R, E, nu, d = 0.02, 2.1e11, 0.3, 1e-6
    with mp.workdps(40):
        s = mp.sqrt(2)

        def gap(x, y):  # the chapter's z1 + z2, with z2 = (x - y)^2/(4R)
            return x**2 / (2 * R) + (x - y) ** 2 / (4 * R)

        H = mp.matrix([[mp.diff(gap, (0, 0), (2, 0)), mp.diff(gap, (0, 0), (1, 1))],
                       [mp.diff(gap, (0, 0), (1, 1)), mp.diff(gap, (0, 0), (0, 2))]])
        k = sorted(mp.eigsy(H, eigvals_only=True))
        assert_close(gen.bodies_problem2_principal_radius_1(R), 1 / k[1], TOL, "R_1")
        assert_close(gen.bodies_problem2_principal_radius_2(R), 1 / k[0], TOL, "R_2")
        assert_close(gen.bodies_problem2_gaussian_radius(R), 1 / mp.sqrt(k[0] * k[1]), TOL, "R~")
        assert_close(gen.bodies_problem2_gaussian_radius(R), s * R, TOL, "sqrt(2) R")
        # the chapter's values are twice (radii) and 2^(1/2) (force) the derived ones
        printed = 2 * R / (1 + 1 / s)
        assert abs(2 * gen.bodies_problem2_principal_radius_1(R) / printed - 1) < TOL
        Es = 1 / (mp.pi * 2 * kernel_coefficient(mp.mpf(E), mp.mpf(nu)))
        F = 4 * Es * mp.sqrt(1 / mp.sqrt(k[0] * k[1])) * mp.mpf(d) ** 1.5 / 3  # (5.23), R~
        assert_close(gen.bodies_problem2_force(E, nu, R, d), F, TOL, "F")
        # the same through the public API at alpha = pi/4
        Rg = bodies.crossed_cylinders_gaussian_radius(R, R, np.pi / 4)
        assert abs(Rg / float(s * R) - 1) < TOL


def test_problem1_rail_wheel():
    """Problem 1: E = 210 GPa, nu = 0.3, R = 0.5 m crossed at 90 deg, F = 1e5 N.

    The chapter rounds E* to 1.2e11 Pa (it is 1.154e11) and quotes p0 ~ 1.0 GPa, a ~ 6.8 mm:
    agreement to 2 % is all its two-digit rounding allows.
    """
    E_star = bodies.effective_modulus(210e9, 0.3, 210e9, 0.3)
    assert abs(E_star / 1.2e11 - 1) < 0.04
    R_1, R_2 = bodies.crossed_cylinder_radii(0.5, 0.5, np.pi / 2)
    R = bodies.gaussian_radius(R_1, R_2)
    assert abs(R / 0.5 - 1) < TOL  # equal crossed cylinders = a sphere of radius R
    p0 = hertz.max_pressure_from_force(1e5, R, E_star)
    a = hertz.contact_radius_from_force(1e5, R, E_star)
    assert abs(p0 / 1.0e9 - 1) < 0.02
    assert abs(a / 6.8e-3 - 1) < 0.02


def test_gaussian_approximation():
    """(5.28)-(5.31): the force is the integral of (5.31) over the ellipse (2-D quadrature);
    the depth under that force inverts it."""
    E, R1, R2, d = 1e11, 0.01, 0.05, 1e-6
    with mp.workdps(30):
        a, b = mp.sqrt(mp.mpf(R1) * d), mp.sqrt(mp.mpf(R2) * d)
        Rg = mp.sqrt(mp.mpf(R1) * R2)
        p0 = 2 / mp.pi * E * mp.sqrt(d / Rg)  # (5.22) with R~ (verified in test_hertz)

        def p(x, y):
            return p0 * mp.sqrt(max(0, 1 - (x / a) ** 2 - (y / b) ** 2))

        F = mp.quad(lambda x: 2 * mp.quad(lambda y: p(x, y), [0, b * mp.sqrt(1 - (x / a) ** 2)]),
                    [-a, a])
        area = mp.quad(lambda x: 2 * b * mp.sqrt(1 - (x / a) ** 2), [-a, a])
        assert_close(bodies.gaussian_approx_force(d, R1, R2, E), F, 1e-13,
                     "(5.23) with R~ vs 2-D quadrature (30 digits, tanh-sinh at the rim)")
        assert_close(bodies.gaussian_approx_area(d, R1, R2), area, TOL, "(5.29)")
        assert_close(bodies.gaussian_approx_max_pressure(d, R1, R2, E), p0, TOL, "p0")
        x, y = a / 3, b / 2
        assert_close(bodies.gaussian_approx_pressure(float(x), float(y), d, R1, R2, E),
                     p(x, y), TOL, "(5.31)")
        sa, sb = bodies.gaussian_approx_semi_axes(d, R1, R2)
        assert_close(sa, a, TOL, "a")
        assert_close(sb, b, TOL, "b")
        assert_close(bodies.gaussian_radius(R1, R2), Rg, TOL, "(5.30)")
        # force-controlled: the depth at the quadrature force (rounded to float64: 2/3 ulp)
        assert_close(bodies.gaussian_approx_depth_from_force(float(F), R1, R2, E), d, TOL,
                     "(5.24) with R~")
    assert bodies.gaussian_approx_pressure(float(a), float(b), d, R1, R2, E) == 0.0


# ---------------------------------------------------------------- invariants (hypothesis)
radius = st.floats(1e-9, 1e3)
modulus = st.floats(1e3, 1e12)
ratio = st.floats(-0.99, 0.5)


@given(modulus, ratio)
def test_rigid_body_2_is_the_limit(E1, nu1):
    rigid = bodies.effective_modulus(E1, nu1)
    # 1/(1/x) is within 1 ulp of x
    assert abs(bodies.effective_modulus(E1, nu1, np.inf) / rigid - 1) < 3e-16
    assert abs(bodies.effective_modulus(E1, nu1, 1e30 * E1, 0.3) / rigid - 1) < 1e-14


@given(modulus, ratio, modulus, ratio)
def test_effective_modulus_symmetric_and_below_both(E1, nu1, E2, nu2):
    Es = bodies.effective_modulus(E1, nu1, E2, nu2)
    assert abs(Es / bodies.effective_modulus(E2, nu2, E1, nu1) - 1) < 1e-15
    assert Es <= min(bodies.effective_modulus(E1, nu1), bodies.effective_modulus(E2, nu2))


@given(radius, radius)
def test_flat_body_2_and_symmetry(R1, R2):
    assert abs(bodies.effective_radius(R1, np.inf) / R1 - 1) < 3e-16  # 1/(1/x): 1 ulp
    assert abs(bodies.effective_radius(R1, R2) / bodies.effective_radius(R2, R1) - 1) < 1e-15
    R_1, R_2 = bodies.principal_radii(R1, R1, R2, R2, 0.7)  # two spheres: (5.27) twice
    Rs = bodies.effective_radius(R1, R2)
    assert abs(R_1 / Rs - 1) < 1e-14 and abs(R_2 / Rs - 1) < 1e-14


@given(radius)
def test_equal_cylinders_at_right_angles_are_a_sphere(R):
    R_1, R_2 = bodies.crossed_cylinder_radii(R, R, np.pi / 2)
    assert abs(R_1 / R - 1) < 1e-14 and abs(R_2 / R - 1) < 1e-14
    assert abs(bodies.crossed_cylinders_gaussian_radius(R, R, np.pi / 2) / R - 1) < 1e-15


@given(radius, radius, st.floats(0.0, np.pi))
def test_crossed_cylinders_as_two_bodies(R1, R2, alpha):
    a = bodies.crossed_cylinder_radii(R1, R2, alpha)
    b = bodies.principal_radii(R1, np.inf, R2, np.inf, alpha)
    for u, v in zip(a, b, strict=True):
        assert u == v or abs(u / v - 1) < 1e-14


def test_arrays_and_bad_input():
    Es = bodies.effective_modulus([1e9, 2e9], 0.3, [np.inf, 1e9], [0.0, 0.5])
    assert Es.shape == (2,)
    with pytest.raises(ValueError, match=r"nu1 = 0\.6 is out of range"):
        bodies.effective_modulus(1e9, 0.6)
    with pytest.raises(ValueError, match="nu2 = None"):
        bodies.effective_modulus(1e9, 0.3, 2e9)
    with pytest.raises(ValueError, match=r"R1 = 0\.0 is out of range"):
        bodies.effective_radius(0.0, 1.0)
    with pytest.raises(ValueError, match="alpha"):
        bodies.crossed_cylinders_gaussian_radius(1.0, 1.0, 0.0)


@pytest.mark.sweep
def test_gaussian_approximation_sweep():
    """(5.28)-(5.31) over the decades: the force by radial quadrature of (5.31) over the
    ellipse (x = a rho cos phi, y = b rho sin phi), p0 of (5.22) at R~ = sqrt(R1 R2)."""
    doms = {"E_star": E_DOM, "R1": R_DOM, "ratio": Arg(1.0, 10.0), "strain": Arg(1e-12, 1e-1)}

    def parts(E_star, R1, ratio, strain):
        R2 = R1 * ratio
        d = strain * R1
        a, b = mp.sqrt(R1 * d), mp.sqrt(R2 * d)
        p0 = 2 / mp.pi * E_star * mp.sqrt(d / mp.sqrt(R1 * R2))
        F = 2 * mp.pi * a * b * mp.quad(lambda rho: p0 * mp.sqrt(1 - rho**2) * rho, [0, 1])
        return {"F": F, "p0": p0, "A": mp.pi * a * b, "R~": mp.sqrt(R1 * R2)}

    cases = {
        "bodies_gaussian_approx_force": (
            lambda E_star, R1, ratio, strain: gen.bodies_gaussian_approx_force(
                E_star, R1, R1 * ratio, strain * R1), "F"),
        "bodies_gaussian_approx_max_pressure": (
            lambda E_star, R1, ratio, strain: gen.bodies_gaussian_approx_max_pressure(
                E_star, R1, R1 * ratio, strain * R1), "p0"),
        "bodies_gaussian_approx_area": (
            lambda E_star, R1, ratio, strain: gen.bodies_gaussian_approx_area(
                R1, R1 * ratio, strain * R1), "A"),
        "bodies_gaussian_radius": (
            lambda E_star, R1, ratio, strain: gen.bodies_gaussian_radius(R1, R1 * ratio), "R~"),
    }
    # the products R1*ratio and strain*R1 are rounded in float64 before the call and exact in
    # the reference: one more ulp each, inside TOL
    for name, (func, key) in cases.items():
        assert_mpmath_equal(func, lambda key=key, **kw: parts(**kw)[key], doms, rtol=TOL,
                            n=n_points(200, 20), dps=30, name=name)


# the public functions with one valid set of inputs each (SI: m, Pa, N, rad)
PUBLIC = [
    (bodies.effective_modulus, dict(E1=2e11, nu1=0.3, E2=7e10, nu2=0.33)),
    (bodies.effective_modulus, dict(E1=2e11, nu1=0.3)),
    (bodies.effective_radius, dict(R1=0.01, R2=0.02)),
    (bodies.principal_radii, dict(R1a=0.01, R1b=0.02, R2a=0.03, R2b=0.05, omega=0.3)),
    (bodies.crossed_cylinder_radii, dict(R1=0.01, R2=0.02, alpha=0.7)),
    (bodies.crossed_cylinders_gaussian_radius, dict(R1=0.01, R2=0.02, alpha=0.7)),
    (bodies.gaussian_radius, dict(R1=0.01, R2=0.02)),
    (bodies.gaussian_approx_semi_axes, dict(d=1e-6, R1=0.01, R2=0.02)),
    (bodies.gaussian_approx_area, dict(d=1e-6, R1=0.01, R2=0.02)),
    (bodies.gaussian_approx_max_pressure, dict(d=1e-6, R1=0.01, R2=0.02, E_star=1e11)),
    (bodies.gaussian_approx_force, dict(d=1e-6, R1=0.01, R2=0.02, E_star=1e11)),
    (bodies.gaussian_approx_depth_from_force, dict(F=1.0, R1=0.01, R2=0.02, E_star=1e11)),
    (bodies.gaussian_approx_pressure, dict(x=1e-5, y=2e-5, d=1e-6, R1=0.01, R2=0.02,
                                           E_star=1e11)),
]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[f.__name__ for f, _ in PUBLIC])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def test_effective_radius_refuses_gaps_that_open():
    """1/R1 + 1/R2 <= 0 (a concave surface as curved as the convex one, or more) is refused,
    naming the first offending pair; just inside the bound the radius is 1/(1/R1 + 1/R2), here
    against mpmath (the bound itself and the values near it, not the formula, are the test)."""
    msg = r"the sum of the curvatures 1/R1 \+ 1/R2 must be > 0 \(a concave surface must be " \
          r"flatter than the convex one\)"
    for R1, R2 in ((1.0, -1.0), (2.0, -1.0), (2.0, -1.5), (1.0, -0.5)):
        with pytest.raises(ValueError, match=msg):
            bodies.effective_radius(R1, R2)
    # the first bad pair of an array, values shown (index 0 is fine, 1 and 2 are not)
    first = r"^R1 = (np\.float64\()?2\.0\)?, R2 = (np\.float64\()?-1\.0\)?: " + msg
    with pytest.raises(ValueError, match=first):
        bodies.effective_radius([1.0, 2.0, 1.0], [-2.0, -1.0, -1.0])
    with pytest.raises(ValueError, match=first):
        bodies.effective_radius(np.array([0.5, 2.0]), -1.0)  # R2 broadcast
    # a sum of exactly 0 is the first bad pair here (the bound itself is refused)
    with pytest.raises(ValueError, match=r"^R1 = (np\.float64\()?1\.0\)?, R2 = "
                                         r"(np\.float64\()?-1\.0\)?: " + msg):
        bodies.effective_radius([1.0, 1.0, 2.0], [-2.0, -1.0, -1.0])
    with mp.workdps(30):
        for R1, R2 in ((1.0, -1.5), (2.0, -4.0), (0.5, 1.0)):
            ref = 1 / (1 / mp.mpf(R1) + 1 / mp.mpf(R2))
            # two divisions and a sum without cancellation (curvatures 1 and -2/3 at worst:
            # a factor 3 on the rounding): 1e-15
            assert_close(bodies.effective_radius(R1, R2), ref, 1e-15, f"R({R1}, {R2})")


def test_effective_modulus_needs_nu2_unless_rigid():
    msg = ("nu2 = None: give Poisson's ratio of body 2 (-1 < nu2 <= 0.5) unless body 2 is "
           "rigid (E2 = None or inf)")
    with pytest.raises(ValueError, match=f"^{re.escape(msg)}$"):
        bodies.effective_modulus(1e9, 0.3, [np.inf, 1e9])  # one finite E2 is enough
    assert bodies.effective_modulus(1e9, 0.3, np.inf) == bodies.effective_modulus(1e9, 0.3)


def test_gap_radii_refuse_an_open_gap_and_take_planes_and_parallel_axes():
    """A concave second body more curved than the first along one direction: the gap opens
    (principal curvatures 1 - 1/0.5 < 0); planes (inf) and parallel or antiparallel axes
    (alpha = 0, pi: a line contact) are in the domain. Radii by (5.32) and by hand."""
    not_convex = (r"the gap is not convex \(principal curvatures .*0\.5.*, .*-1\.0.* \[1/m\]\); "
                  r"both must be >= 0 and the larger > 0 for the bodies to touch in a point or "
                  r"a line")
    # (the message may also list the inputs before the reason)
    with pytest.raises(ValueError, match="^principal_radii: (.*: )?" + not_convex):
        bodies.principal_radii(1.0, 1.0, -2.0, -0.5)
    with pytest.raises(ValueError, match="^omega = inf: must be finite$"):
        bodies.principal_radii(1.0, 1.0, 1.0, 1.0, omega=np.inf)
    # omega defaults to 0: aligned principal directions, 1/R_i = 1/R1x + 1/R2x (5.32)
    R_1, R_2 = bodies.principal_radii(0.01, 0.02, 0.03, 0.05)
    assert_close(R_1, 1 / (1 / mp.mpf("0.01") + 1 / mp.mpf("0.03")), 1e-15, "R_1")
    assert_close(R_2, 1 / (1 / mp.mpf("0.02") + 1 / mp.mpf("0.05")), 1e-15, "R_2")
    # a cylinder on a plane (either one given as inf): R_1 = the cylinder's, R_2 = inf
    assert bodies.crossed_cylinder_radii(np.inf, 0.02, 0.7) == (0.02, np.inf)
    assert bodies.crossed_cylinder_radii(0.02, np.inf, 0.7) == (0.02, np.inf)
    # parallel and antiparallel axes: R_1 = R1 R2/(R1 + R2), R_2 = inf or huge (sin(pi) != 0)
    for alpha in (0.0, np.pi):
        R_1, R_2 = bodies.crossed_cylinder_radii(0.01, 0.02, alpha)
        assert_close(R_1, mp.mpf("0.01") * mp.mpf("0.02") / mp.mpf("0.03"), 1e-15, "R_1")
        assert R_2 > 1e29


def test_cylinders_crossed_at_a_vanishing_angle():
    """k2 ~ alpha^2 below 1/DBL_MAX: R_2 = inf (the line-contact limit) without an overflow
    warning (pytest turns warnings into errors); R_1 = R/2 for equal cylinders."""
    R_1, R_2 = bodies.crossed_cylinder_radii(1.0, 1.0, 1e-155)
    assert R_2 == np.inf and abs(R_1 - 0.5) < 1e-15


def test_gaussian_pressure_refuses_infinite_coordinates():
    for name, args in (("x", (np.inf, 0.0)), ("y", (0.0, -np.inf))):
        with pytest.raises(ValueError, match=f"^{name} must be finite$"):
            bodies.gaussian_approx_pressure(*args, 1e-6, 0.01, 0.02, 1e11)


def test_messages_print_plain_numbers():
    """NumPy scalars in messages read as numbers, not as np.float64(...) (issue 12)."""
    from hertzmdr.numeric import ellipse

    for call in (lambda: bodies.effective_radius(np.float64(2.0), np.float64(-1.0)),
                 lambda: ellipse.solve(np.float64(1e10), 1.0, 1e9, depth=1e-3)):
        with pytest.raises(ValueError) as err:
            call()
        assert "np." not in str(err.value) and "float64" not in str(err.value), err.value
