"""numeric/worn.py, the worn (flattened) paraboloid of Problem 8, by independent routes: the
depth under a force against mpmath's findroot on the 30-digit generated F(a), the inside
displacement against d - f(r) from the geometry, the pressure against the 30-digit form at a
contact radius found by findroot, and the two displacement forms meeting at the edge."""

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import worn

from named import assert_inputs_named

# (R [m], b [m], E* [Pa]): a micro tip, a strongly worn one, a large one
GEOMETRIES = [(50e-6, 2e-6, 1.4e11), (1e-3, 4e-4, 7e10), (0.2, 1e-3, 2.1e11)]


def _radius_mp(d, R, b):
    """a(d) from (5.55), g(a) = (a/R) sqrt(a^2 - b^2) = d, by findroot at the working precision
    (an independent route to the closed-form root of the biquadratic)."""
    R, b, d = mp.mpf(R), mp.mpf(b), mp.mpf(d)
    return mp.findroot(lambda a: a * mp.sqrt((a - b) * (a + b)) / R - d,
                       mp.sqrt(b * b + R * d), tol=mp.mpf(10) ** (-mp.mp.dps + 3))


@pytest.mark.parametrize("R, b, E", GEOMETRIES)
@pytest.mark.parametrize("ratio", [1.05, 1.5, 4.0, 30.0])
def test_depth_from_force_round_trip(R, b, E, ratio):
    """F at the contact radius a = ratio b (the 30-digit generated F(a)), then
    worn.depth_from_force(F) against d = g(a) at 30 digits, and worn.force(d) back to F."""
    with mp.workdps(30):
        a = mp.mpf(ratio) * b
        F = gen_mp.worn_force_from_radius(mp.mpf(E), mp.mpf(R), a, mp.mpf(b))
        d_ref = gen_mp.worn_depth(mp.mpf(R), a, mp.mpf(b))
        # the root of F(a) by findroot instead of the closed form: F and d are one relation
        a_root = mp.findroot(lambda x: gen_mp.worn_force_from_radius(E, R, x, b) - F, a * 1.01)
        assert abs(a_root / a - 1) < 1e-16  # findroot's default tolerance at 30 digits
        d = worn.depth_from_force(float(F), R, b, E)
        # Brent to 4e-16 in a; d = g(a) has the condition number a^2 (2a^2 - b^2) /
        # ((a^2 - b^2)(...)) <= 1 + 1/(ratio^2 - 1): about 11 at ratio 1.05
        cond = 1 + 1 / (ratio**2 - 1)
        assert abs(d / d_ref - 1) < 4e-15 * cond, (d, d_ref)
        assert abs(worn.force(d, R, b, E) / F - 1) < 4e-15 * cond


@pytest.mark.parametrize("R, b, E", GEOMETRIES)
def test_inside_displacement_is_d_minus_f(R, b, E):
    """Inside the contact the surface follows the indenter: u = d - f(r), f = 0 on the flat and
    (r^2 - b^2)/(2R) beyond, evaluated in mpmath from the geometry; the inside and outside
    forms meet at the edge r = a (two relations derived apart)."""
    d = 0.5 * b * b / R * 3  # a depth that puts the edge well beyond the flat
    with mp.workdps(30):
        a = float(_radius_mp(d, R, b))
        r = np.concatenate([np.linspace(0.0, a, 41), [b * (1 - 1e-12), b, b * (1 + 1e-12)]])
        u = worn.surface_displacement(r, d, R, b)
        f = worn.profile(r, R, b)
        for ri, ui, fi in zip(r, u, f, strict=True):
            rm = mp.mpf(ri)
            f_ref = 0 if rm < b else (rm - b) * (rm + b) / (2 * R)
            # u = d - f subtracts two numbers of size d: an absolute error of a few ulp of d
            assert abs(ui - (d - f_ref)) <= 4e-16 * d, (ri, ui)
            # f = (r - b)(r + b)/(2R): three correctly rounded operations
            assert abs(fi - f_ref) <= 4 * 2.2e-16 * f_ref, (ri, fi)
        # the outside form (5.60) continues the inside one across r = a
        inside = worn.surface_displacement(a * (1 - 1e-9), d, R, b)
        outside = worn.surface_displacement(a * (1 + 1e-9), d, R, b)
        # u' is bounded (log-infinite only in u''), so 2e-9 a apart u changes by ~2e-9 d
        assert abs(inside - outside) < 1e-8 * d


@pytest.mark.parametrize("R, b, E", GEOMETRIES)
def test_pressure_and_radius(R, b, E):
    """p(r) against the 30-digit pressure at the contact radius findroot gives; 0 outside."""
    d = 2 * b * b / R
    with mp.workdps(30):
        a = _radius_mp(d, R, b)
        assert abs(worn.contact_radius(d, R, b) / a - 1) < 1e-15
        r = np.array([0.0, 0.3 * b, 0.99 * b, 1.01 * b, 0.5 * float(a + b), 0.999 * float(a)])
        got = worn.pressure(r, d, R, b, E)
        for ri, gi in zip(r, got, strict=True):
            ref = gen_mp.worn_pressure(mp.mpf(E), mp.mpf(R), a, mp.mpf(b), mp.mpf(ri))
            # the elliptic integrals near their log singularity r = b lose a few digits
            assert abs(gi / ref - 1) < 1e-12, (ri, gi, ref)
        assert worn.pressure(1.01 * float(a), d, R, b, E) == 0.0


def test_g_profile_and_depth():
    """g = 0 on the flat, the 30-digit g beyond it, even in x; d = g(a)."""
    R, b = 50e-6, 2e-6
    x = np.array([0.0, 0.5 * b, b, 1.5 * b, 10 * b])
    got = worn.g_profile(x, R, b)
    assert np.all(worn.g_profile(-x, R, b) == got)
    with mp.workdps(30):
        for xi, gi in zip(x, got, strict=True):
            ref = 0 if xi <= b else gen_mp.worn_g(mp.mpf(R), mp.mpf(b), mp.mpf(xi))
            assert (gi == 0 if ref == 0 else abs(gi / ref - 1) < 1e-15), (xi, gi)
        assert abs(worn.depth(3 * b, R, b) / gen_mp.worn_g(R, b, mp.mpf(3 * b)) - 1) < 1e-15


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="a >= b"):
        worn.depth(1e-6, 50e-6, 2e-6)
    with pytest.raises(ValueError, match="F"):
        worn.depth_from_force(-1.0, 50e-6, 2e-6, 1e11)
    with pytest.raises(ValueError, match="b"):
        worn.force(1e-8, 50e-6, 0.0, 1e11)


def _force_mdr_mp(a, R, b, E):
    """F(a) = 2 E* int_0^a (g(a) - g(x)) dx, (5.57), with g from the geometry by (5.52):
    g(x) = |x| int_0^x f'(r)/sqrt(x^2 - r^2) dr = (x/R) sqrt(x^2 - b^2) beyond the flat, 0 on it;
    tanh-sinh split at the kink x = b."""
    a, R, b, E = (mp.mpf(v) for v in (a, R, b, E))

    def g(x):
        return x * mp.sqrt((x - b) * (x + b)) / R if x > b else mp.mpf(0)

    return 2 * E * mp.quad(lambda x: g(a) - g(x), [0, b, a])


@pytest.mark.parametrize("R, b, E", GEOMETRIES)
def test_force_from_radius_by_the_mdr_integral(R, b, E):
    """worn.force_from_radius on an array of radii (and a broadcast R) against the MDR force
    integral (5.57) of g at 30 digits; F(b) = 0 exactly (the flat alone carries no force)."""
    ratios = np.array([1.0, 1.001, 1.3, 3.0, 50.0])
    got = worn.force_from_radius(ratios * b, np.full(2, R)[:, None], b, E)
    assert got.shape == (2, 5)
    assert np.all(got[:, 0] == 0.0)
    with mp.workdps(30):
        for k, ratio in enumerate(ratios[1:], start=1):
            ref = _force_mdr_mp(ratio * b, R, b, E)
            # closed form of a few correctly rounded factors and one square root of
            # (a - b)(a + b): a few ulp; the quadrature gives ~25 digits
            assert np.all(abs(got[:, k] / ref - 1) < 1e-15), (ratio, got[:, k], ref)


def test_depth_from_force_at_the_nanoscale():
    """A 50 nm tip worn to 5 nm under a micronewton, far from the metre scale: the root
    a ~ 1e-8 m is found to ~eps relative (Brent's xtol is relative to the bracket, not in
    metres). Reference: the 30-digit F(a) (the MDR integral of g, (5.57)), d = g(a) at a = 1.5 b."""
    R, b, E = 50e-9, 5e-9, 1e11
    with mp.workdps(30):
        a = mp.mpf(1.5) * b
        F = _force_mdr_mp(a, R, b, E)
        d_ref = a * mp.sqrt((a - b) * (a + b)) / R  # (5.55)
        d = worn.depth_from_force(float(F), R, b, E)
        # Brent to 4 eps in a; d = g(a) amplifies it by 1 + 1/(1.5^2 - 1) = 1.8
        assert abs(d / d_ref - 1) < 4e-15 * 1.8, (d, d_ref)


def test_each_input_named_in_its_error():
    """Every input of every public function is named in its error (tests/named.py)."""
    R, b, E = 50e-6, 2e-6, 1e11
    d = 2 * b * b / R
    assert_inputs_named(worn.profile, {"r": 1e-6, "R": R, "b": b})
    assert_inputs_named(worn.g_profile, {"x": 3e-6, "R": R, "b": b})
    assert_inputs_named(worn.depth, {"a": 3e-6, "R": R, "b": b})
    assert_inputs_named(worn.contact_radius, {"d": d, "R": R, "b": b})
    assert_inputs_named(worn.force, {"d": d, "R": R, "b": b, "E_star": E})
    assert_inputs_named(worn.force_from_radius, {"a": 3e-6, "R": R, "b": b, "E_star": E})
    assert_inputs_named(worn.depth_from_force, {"F": 1e-3, "R": R, "b": b, "E_star": E})
    assert_inputs_named(worn.pressure, {"r": 1e-6, "d": d, "R": R, "b": b, "E_star": E})
    assert_inputs_named(worn.surface_displacement, {"r": 1e-6, "d": d, "R": R, "b": b})


def test_radius_below_the_flat_refused_with_its_value():
    """a < b is refused with the value as a plain number (one of an array, and a scalar a
    against an array of b); a = b, the contact of the flat alone, is accepted (d = 0)."""
    R, b = 50e-6, 2e-6
    msg = r"^a = 1e-06 is out of range; valid: a >= b \(the contact covers at least the flat\)$"
    with pytest.raises(ValueError, match=msg):
        worn.depth(np.array([3e-6, 1e-6]), R, b)
    with pytest.raises(ValueError, match=msg):
        worn.force_from_radius(1e-6, R, np.array([5e-7, 2e-6]), 1e11)
    assert worn.depth(b, R, b) == 0.0
    assert worn.force_from_radius(b, R, b, 1e11) == 0.0


def test_g_profile_refuses_a_non_number_naming_x():
    with pytest.raises(ValueError, match=r"^x = 'abc' is not a number"):
        worn.g_profile("abc", 50e-6, 2e-6)
    with pytest.raises(ValueError, match=r"^x = inf is out of range; valid: 0 <= x < inf$"):
        worn.g_profile(-np.inf, 50e-6, 2e-6)
    # g is even and 0 on the flat: integers are read as floats
    assert worn.g_profile(np.array([-3, 0, 1]), 1.0, 1.0).tolist() == \
        [float(3 * mp.sqrt(8)), 0.0, 0.0]
