"""numeric/worn.py, the worn (flattened) paraboloid of Problem 8, by independent routes: the
depth under a force against mpmath's findroot on the 30-digit generated F(a), the inside
displacement against d - f(r) from the geometry, the pressure against the 30-digit form at a
contact radius found by findroot, and the two displacement forms meeting at the edge."""

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import worn

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
