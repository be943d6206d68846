"""The exact sphere (Sneddon's sphere, derive/sphere.py) by independent routes.

References come from the cap's profile f(r) = R - sqrt(R^2 - r^2) itself, never from the
derived g: f'(r) = r/sqrt(R^2 - r^2) and f''(r) = R^2/(R^2 - r^2)^(3/2) (checked against mpmath's
numerical derivative of f below) go into the MDR integrals, evaluated by mpmath's tanh-sinh at
30 digits:

- (5.52) with r = x sin(theta): g(x) = x integral_0^(pi/2) f'(x sin(theta)) dtheta;
- (5.55) and (5.57) with the order of integration exchanged (no g at all):
  d(a) = a integral_0^a f'(r)/sqrt(a^2 - r^2) dr and
  F(a) = 2 E* integral_0^a f'(r) r^2/sqrt(a^2 - r^2) dr (Sneddon's form of (5.57));
- (5.59) with g'(x) = integral_0^(pi/2) [f'(x s) + x s f''(x s)] ds (s = sin(theta)) inside
  p = (E*/pi) integral_r^a g'(x)/sqrt(x^2 - r^2) dx;
- the pressure through the Boussinesq integral (5.7) (tests/kernels.py) must give back
  d - f(r) inside the contact and the numeric (5.60) outside it.

Endpoint singularities are taken out by substitution (r = a sin(phi); x^2 = r^2 + w^2) so that
tanh-sinh sees smooth integrands or integrable endpoint singularities only.
"""

from functools import cache

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import hertz, sphere

from kernels import uz_rings
from oracle import WORST, Arg, assert_close, assert_mpmath_equal, n_points

# a handful of correctly rounded float64 operations (log1p, hyp2f1 and tanh are within an ulp
# or two of exact): 1e-14 leaves an order of magnitude for their sum
TOL = 1e-14
DPS = 30


def _record(what, err, tol):
    """Keep the error for the end-of-run summary (conftest), then check it."""
    WORST[what] = max(WORST.get(what, 0.0), float(err))
    assert err < tol, f"{what}: {err} >= {tol}"


def f(r, R):
    return R - mp.sqrt(R**2 - r**2)


def fp(r, R):
    return r / mp.sqrt((R - r) * (R + r))


def fpp(r, R):
    return R**2 / mp.sqrt((R - r) * (R + r)) ** 3


def g_ref(x, R):
    """(5.52) with r = x sin(theta)."""
    return x * mp.quad(lambda th: fp(x * mp.sin(th), R), [0, mp.pi / 2])


def _kept(ref):
    """``ref`` with its values kept by its arguments and the working precision (a pure
    function of them): test_sweep_over_decades checks d(a), F(a) and F(d) at the same sampled
    points, and F(d)'s reference is d(a)'s and F(a)'s quadratures again."""
    done = {}

    def kept(*args):
        key = (*args, mp.mp.prec)
        if key not in done:
            done[key] = ref(*args)
        return done[key]

    kept.__doc__ = ref.__doc__
    return kept


@_kept
def depth_ref(a, R):
    """(5.55) with the order exchanged: d = a integral_0^a f'(r)/sqrt(a^2 - r^2), r = a sin(phi)."""
    return a * mp.quad(lambda ph: fp(a * mp.sin(ph), R), [0, mp.pi / 2])


@_kept
def force_ref(a, R, E):
    """(5.57) with the order exchanged: F = 2 E* integral_0^a f'(r) r^2/sqrt(a^2 - r^2) dr.

    The factor a^2 stays outside the quadrature: mpmath's quad stops on an absolute error
    estimate, so the integrand is kept of order f' (>= 1e-8 here)."""
    return 2 * E * a**2 * mp.quad(lambda ph: fp(a * mp.sin(ph), R) * mp.sin(ph) ** 2,
                                  [0, mp.pi / 2])


def gprime_ref(x, R):
    """g'(x) of (5.52) differentiated under the integral sign."""
    return mp.quad(lambda th: fp(x * mp.sin(th), R) + x * mp.sin(th) * fpp(x * mp.sin(th), R),
                   [0, mp.pi / 2])


@cache
def _derived_gprime():
    """SymPy's derivative of the derived g (derive/sphere.py), for mpmath."""
    import sympy as sp

    from hertzmdr.derive import sphere as ds
    from hertzmdr.derive.symbols import R as R_s

    return sp.lambdify((ds.x, R_s), sp.diff(ds.solution()["g"], ds.x), "mpmath")


def pressure_ref(r, a, R, E, gprime=gprime_ref):
    """(5.59) with x^2 = r^2 + w^2 (dx/sqrt(x^2 - r^2) = dw/x), w in (0, sqrt(a^2 - r^2))."""
    k = mp.sqrt((a - r) * (a + r))
    return E / mp.pi * mp.quad(lambda w: gprime(mp.sqrt(r * r + w * w), R)
                               / mp.sqrt(r * r + w * w), [0, k])


# a/R over the decades the brief asks for: 1e-8 to 1 - 1e-10
BETAS = ["1e-8", "1e-4", "0.01", "0.1", "0.3", "0.5", "0.7", "0.9", "0.99", "0.999999",
         "0.9999999999"]


def test_derivatives_of_f():
    """The typed f' and f'' are the derivatives of f (mpmath's numerical differentiation)."""
    with mp.workdps(DPS):
        R = mp.mpf(2)
        for r in (mp.mpf("0.3"), mp.mpf("1.9")):
            assert abs(mp.diff(lambda v: f(v, R), r) / fp(r, R) - 1) < mp.mpf(10) ** -25
            assert abs(mp.diff(lambda v: f(v, R), r, 2) / fpp(r, R) - 1) < mp.mpf(10) ** -25


def test_profile_and_g():
    """f(r) and g(x) of the float64 code against f itself and (5.52) by quadrature."""
    R = 1.5
    for s in BETAS:
        with mp.workdps(DPS):
            x = mp.mpf(s) * R
            xf = float(x)
            ref_f = f(mp.mpf(xf), R)
            ref_g = g_ref(mp.mpf(xf), R)
            _record("g by (5.52)", abs(gen_mp.sphere_g(mp.mpf(R), mp.mpf(xf)) / ref_g - 1),
                    mp.mpf(10) ** -25)
        assert_close(sphere.profile(xf, R), ref_f, TOL, f"f at x/R = {s}")
        assert_close(sphere.g_profile(xf, R), ref_g, TOL, f"g at x/R = {s}")
    assert sphere.profile(R, R) == R  # the equator of the cap
    assert sphere.g_profile(0.0, R) == 0.0


def test_depth_and_force_by_quadrature():
    """d(a), F(a) and their lam forms against (5.55), (5.57) from f, over a/R = 1e-8..1-1e-10."""
    R, E = 0.7, 2e9
    for s in BETAS:
        with mp.workdps(DPS):
            a = mp.mpf(float(mp.mpf(s) * R))  # the float64 input, exactly
            d, F = depth_ref(a, R), force_ref(a, R, E)
            lam = mp.atanh(a / R)
        af = float(a)
        assert_close(sphere.depth(af, R), d, TOL, f"d(a) at a/R = {s}")
        assert_close(sphere.force_from_radius(af, R, E), F, TOL, f"F(a) at a/R = {s}")
        # d and F at lam: the float lam is the exact lam of a/R within 1 ulp, which moves d and F
        # by at most 3 ulps (d ln F/d ln lam <= 3)
        lf = float(lam)
        assert_close(float(gen.sphere_lam_depth(R, lf)), d, TOL, f"d(lam) at a/R = {s}")
        assert_close(float(gen.sphere_lam_force(E, R, lf)), F, TOL, f"F(lam) at a/R = {s}")
        assert_close(float(gen.sphere_lam_contact_radius(R, lf)), a, TOL, f"a(lam) at {s}")


def test_contact_radius_and_force_at_depth():
    """a(d) and F(d) at the reference depth of a float64 a (round trip through the solver)."""
    R, E = 0.7, 2e9
    for s in BETAS:
        with mp.workdps(DPS):
            a = mp.mpf(float(mp.mpf(s) * R))
            d = depth_ref(a, R)
            df = float(d)
            # the reference at the float64 depth: a' = a + (df - d)/g'(a), F' = F + 2 a E* (df - d)
            gp = gprime_ref(a, R)
            a_ref = a + (df - d) / gp
            F_ref = force_ref(a, R, E) + 2 * a * E * (df - d)
        # a(d) is ill-conditioned as a -> R (d a/a = (d/(a g')) d d/d), well-conditioned in F
        cond_a = float(d / (a * gp))
        assert_close(sphere.contact_radius(df, R), a_ref, TOL * max(cond_a, 1), f"a(d) at {s}")
        assert_close(sphere.force(df, R, E), F_ref, TOL, f"F(d) at a/R = {s}")
        assert_close(sphere.stiffness(df, R, E), 2 * a_ref * E, TOL * max(cond_a, 1),
                     f"k(d) at {s}")
        assert_close(sphere.depth_from_force(float(F_ref), R, E), df, TOL, f"d(F) at {s}")


def test_stiffness():
    """dF/dd by mpmath differentiation of the quadrature references equals 2 a E*."""
    R, E = 1.0, 3.0
    with mp.workdps(DPS):
        for s in ("0.01", "0.5", "0.99"):
            a = mp.mpf(s)
            k = (mp.diff(lambda v: force_ref(v, R, E), a)
                 / mp.diff(lambda v: depth_ref(v, R), a))
            assert_close(float(gen.sphere_stiffness(E, float(a))), k, TOL, f"dF/dd at a/R = {s}")


def test_pressure_by_quadrature_of_59():
    """p(r) against (5.59) evaluated from f'' by nested quadrature (30 digits)."""
    R, E = 1.0, 1.0
    # (a/R, r/a): CI runs the first three (shallow, the rim, the centre of a deep contact);
    # a point is a nested 30-digit quadrature of 2-10 s, 100 s at a/R = 1 - 1e-10, whose
    # cheaper check, from the derived g' (itself checked against f), follows
    cases = [("0.001", "0.5"), ("0.5", "0.99999"), ("0.999", "0"), ("0.9999999999", "0.7"),
             ("0.001", "0"), ("0.001", "0.999"), ("0.5", "0"), ("0.5", "0.3"), ("0.5", "0.9"),
             ("0.999", "0.5"), ("0.999", "0.999"), ("0.9999999999", "0")]
    deep = [("0.9999999999", "0"), ("0.9999999999", "0.7"), ("0.9999999999", "0.9999")]
    runs = [(s, fr, gprime_ref) for s, fr in cases[:n_points(len(cases), 3)]]
    runs += [(s, fr, _derived_gprime()) for s, fr in deep]
    for s, fr, gprime in runs:
        with mp.workdps(DPS):
            a = mp.mpf(float(mp.mpf(s) * R))
            df = float(depth_ref(a, R))
            am = mp.mpf(float(sphere.contact_radius(df, R)))  # the a the code works with
            r = float(mp.mpf(fr) * am)
            ref = pressure_ref(mp.mpf(r), am, R, E, gprime)
        # the pressure at r < a depends on a through sqrt(a - r) at the rim: the rounding of
        # a (1 ulp) costs a/(2 (a - r)) ulps
        tol = TOL * (1 + float(am / (2 * (am - r))))
        assert_close(sphere.pressure(r, df, R, E), ref, tol, f"p at a/R={s}, r/a={fr}")
    assert sphere.pressure(1.0, 0.5, R, E) == 0.0  # r > a(0.5) = 0.55...


def test_force_is_integral_of_pressure():
    """integral p 2 pi r dr of the numeric pressure (Gauss-Legendre on the float64 p, in
    u = sqrt(a^2 - r^2), where p is smooth) equals F(d)."""
    R, E = 1.0, 1.0
    for d in (1e-6, 0.3, 3.0):
        a = sphere.contact_radius(d, R)
        u, wt = np.polynomial.legendre.leggauss(60)
        u = (u + 1) / 2 * a
        r = np.sqrt((a - u) * (a + u))
        F = np.sum(wt * a / 2 * sphere.pressure(r, d, R, E) * 2 * np.pi * u)  # r dr = -u du
        assert abs(F / sphere.force(d, R, E) - 1) < 1e-13, d


def test_hard_cases_and_vectors():
    R, E = 2.0, 5.0
    a = np.array([0.0, 1e-8 * R, 0.5 * R, (1 - 1e-12) * R])
    d = sphere.depth(a, R)
    assert d[0] == 0.0 and np.all(np.diff(d) > 0)
    back = sphere.contact_radius(d, R)
    # a(d): 1 ulp of d moves a by (d/(a g')) ulps; at a/R = 1 - 1e-12 that is ~3e-11
    assert np.allclose(back, a, rtol=1e-10, atol=0)
    assert abs(back[1] / a[1] - 1) < 1e-15
    F = sphere.force(d, R, E)
    assert F[0] == 0.0 and np.all(np.diff(F) > 0)
    assert np.all(np.abs(sphere.depth_from_force(F, R, E)[1:] / d[1:] - 1) < 1e-14)
    assert sphere.depth_from_force(0.0, R, E) == 0.0
    assert sphere.contact_radius(0.0, R) == 0.0
    p = sphere.pressure(np.array([0.0, 1e-5, 10.0]), np.array([0.0, 1e-9, 30.0 / 2]), R, E)
    assert p[0] == 0.0 and p[1] > 0 and p[2] == 0.0
    u = sphere.surface_displacement(np.array([0.0, 1.0, 100.0]), 0.0, R)
    assert np.all(u == 0.0)
    # (5.60) meets d - f(r) at the rim: (5.53) of (5.54) at r = a; a vector mixing depths
    # a/R from 2e-5 to 1 - 9e-5 (nearer R the (r - a)^(3/2) term, ~f''(a) (r - a)^2 with
    # f'' ~ (R^2 - a^2)^(-3/2), outgrows the offset below)
    dd = np.array([1e-9, 0.1, 1.0, 5.0]) * R
    aa = sphere.contact_radius(dd, R)
    rr = aa * (1 + 1e-13)
    rim = sphere.surface_displacement(rr, dd, R)
    # the displacement of a smooth contact is C^1 at the rim (u' = -f'), so the cap continued
    # to r = a (1 + 1e-13) < R matches it to O(1e-26 u'')
    assert np.all(np.abs(rim / (dd - sphere.profile(rr, R)) - 1) < 1e-12)
    # very deep: a rounds to R in float64 for d > 19 R, F stays finite and increasing
    Fd = sphere.force(np.array([20.0, 40.0, 1e6]) * R, R, E)
    assert np.all(np.isfinite(Fd)) and np.all(np.diff(Fd) > 0)


def test_bad_input():
    R = 1.0
    with pytest.raises(ValueError, match=r"a = 1\.0 is out of range; valid: 0 <= a < R"):
        sphere.depth(1.0, R)
    with pytest.raises(ValueError, match=r"a\[1\] = 2\.0"):
        sphere.force_from_radius([0.5, 2.0], R, 1.0)
    with pytest.raises(ValueError, match=r"r = 1\.5 .*0 <= r <= R"):
        sphere.profile(1.5, R)
    with pytest.raises(ValueError, match="d = 17.0 .*16 R"):
        sphere.pressure(0.0, 17.0, R, 1.0)
    with pytest.raises(ValueError, match="R = 0.0"):
        sphere.force(1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="d = -1.0"):
        sphere.contact_radius(-1.0, R)


@given(st.floats(1e-12, 50.0), st.floats(1e-3, 1e3), st.floats(1.0 + 1e-9, 4.0))
def test_force_increases_and_inverts(d_over_R, R, factor):
    E = 1e9
    d = d_over_R * R
    F = sphere.force(d, R, E)
    assert sphere.force(d * factor, R, E) > F
    assert sphere.contact_radius(d, R) <= R
    assert abs(sphere.depth_from_force(F, R, E) / d - 1) < 1e-14
    # F -> d -> F: dF/F = (2 a E* d/F) dd/d <= 3 dd/d, and d(F) is within 1e-14
    assert abs(sphere.force(sphere.depth_from_force(F, R, E), R, E) / F - 1) < 3e-14
    if d_over_R < 18:  # a < R in float64: R - a ~ 2 R exp(-2 d/R) > R eps/2 for d < 18.7 R
        a = sphere.contact_radius(d, R)
        assert a < R
        # d(a(d)): 1 ulp of a moves d by d ln d/d ln a = 1 + a R/((R^2 - a^2) atanh(a/R)) ulps,
        # which grows like exp(2 d/R) as a -> R
        cond = 1 + a * R / ((R - a) * (R + a) * (d / a))
        assert abs(sphere.depth(a, R) / d - 1) < 4e-16 * cond + 1e-15


def test_hertz_limit():
    """a/R -> 0: the sphere tends to Hertz (5.21)-(5.23), with the relative deviations
    a/a_H - 1 = -(a/R)^2/6 and F/F_H - 1 = -(a/R)^2/10 at the same depth (and
    F/((4/3) E* a^3/R) - 1 = +2 (a/R)^2/5 at the same contact radius). The next terms,
    -7 b^4/120 and -29 b^4/840 (b = a/R, SymPy's series), bound what is left: the test asserts
    the b^2 coefficient to within 0.1 b^2 (> 7/120) plus the float64 error over b^2."""
    R, E = 1.0, 1.0
    for b in (1e-4, 1e-3, 1e-2, 0.05):
        with mp.workdps(DPS):
            a = mp.mpf(b) * R
            d = depth_ref(a, R)  # the reference depth, from f
        df = float(d)
        slack = 0.1 * b**2 + 4e-16 / b**2
        da = (sphere.contact_radius(df, R) / hertz.contact_radius(df, R) - 1) / b**2
        dF = (sphere.force(df, R, E) / hertz.force(df, R, E) - 1) / b**2
        dF_a = (sphere.force_from_radius(b * R, R, E) / (4 / 3 * E * (b * R) ** 3 / R) - 1) / b**2
        assert abs(da + 1 / 6) < slack, (b, da)
        assert abs(dF + 1 / 10) < slack, (b, dF)
        assert abs(dF_a - 2 / 5) < 0.3 * b**2 + 4e-16 / b**2, (b, dF_a)  # next term 9 b^4/35


@cache
def _mp_pressure(a_s, R_s, E_s):
    """The pressure in mpmath (generated pole part + the atanh part by tanh-sinh), at the
    contact radius a (the depth's lam = atanh(a/R)); a function of rho, cached per ring."""
    a, Rm, Em = mp.mpf(a_s), mp.mpf(R_s), mp.mpf(E_s)
    lam = mp.atanh(a / Rm)

    @cache
    def p(rho):
        if rho >= a:
            return mp.mpf(0)
        k = mp.sqrt((a - rho) * (a + rho))
        rest = mp.quad(lambda w: gen_mp.sphere_pressure_atanh_kernel(
            Em, Rm, mp.sqrt(rho * rho + w * w)), [0, k])
        return gen_mp.sphere_lam_pressure_pole(Em, Rm, lam, rho) + rest

    return p


# field points (r/a) of the 3-D check: centre, inside, near the rim, outside; CI runs 3
POINTS_3D = (("inside", "0.5"), ("outside", "1.5"), ("centre", "0"), ("near rim", "0.95"),
             ("far", "10"))


@pytest.mark.sweep
@pytest.mark.parametrize("beta", ["0.5", "0.999"][:n_points(2, 1)])
def test_against_3d_elasticity(beta):
    """The pressure through the Boussinesq integral (5.7) (tests/kernels.py::uz_rings) gives
    back d - f(r) inside the contact and the numeric (5.60) outside it.

    Tanh-sinh at 25 digits: the pressure is smooth inside, ~sqrt(a - rho) at the rim and the
    ring integral log-singular at rho = r, all at interval ends: >= 20 digits asserted inside
    (the references d, f are exact); outside, the float64 (5.60) quadrature within 1e-14."""
    R, E = 1.0, 1.0
    with mp.workdps(25):
        a = mp.mpf(beta) * R
        d = a * mp.atanh(a / R)  # (5.55) from the derived g, checked by test_depth_and_force
        p = _mp_pressure(str(a), str(R), str(E))
        for name, fr in POINTS_3D[:n_points(len(POINTS_3D), 3)]:
            r = mp.mpf(fr) * a
            u = uz_rings(p, r, a, E)
            if r <= a:
                _record(f"sphere 3-D {name}", abs(u / (d - f(r, R)) - 1), 1e-20)
            else:
                num = sphere.surface_displacement(float(r), float(d), R)
                _record(f"sphere (5.60) {name}", abs(num / u - 1), 1e-14)


def test_doc_is_current(tmp_path):
    """benchmarks/sphere_bias.py runs, and docs/sphere.md is what it writes today."""
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    out = tmp_path / "sphere.md"
    subprocess.run([sys.executable, str(root / "benchmarks" / "sphere_bias.py"), "--out",
                    str(out), "--no-figure"], check=True, capture_output=True, cwd=root)
    fresh = out.read_text()
    committed = (root / "docs" / "sphere.md").read_text()
    assert committed.startswith(fresh), "docs/sphere.md is stale: run benchmarks/sphere_bias.py"


@pytest.mark.sweep
def test_sweep_over_decades():
    """d(a), F(a), a(d), F(d), d(F) against the quadratures from f, R over 12 decades, a/R
    log-uniform in [1e-8, 0.5] and 1 - a/R log-uniform in [1e-10, 0.5]."""
    n = n_points(200, 25)
    E = 7e10
    doms_small = {"R": Arg(1e-9, 1e3), "b": Arg(1e-8, 0.5)}
    doms_deep = {"R": Arg(1e-9, 1e3), "q": Arg(1e-10, 0.5)}

    def a_of(R, b=None, q=None):
        return R * b if q is None else R - R * q

    for doms in (doms_small, doms_deep):
        def depth_num(R, **kw):
            return sphere.depth(a_of(R, **kw), R)

        def depth_mp(R, **kw):
            return depth_ref(mp.mpf(float(a_of(R, **kw))), R)

        def force_num(R, **kw):
            return sphere.force_from_radius(a_of(R, **kw), R, E)

        def force_mp(R, **kw):
            return force_ref(mp.mpf(float(a_of(R, **kw))), R, E)

        def force_d_num(R, **kw):
            return sphere.force(sphere.depth(a_of(R, **kw), R), R, E)

        def force_d_mp(R, **kw):
            # the reference at the float64 depth of the float64 a (see the round-trip test)
            a = mp.mpf(float(a_of(R, **kw)))
            d = depth_ref(a, R)
            df = mp.mpf(float(sphere.depth(float(a), float(R))))
            return force_ref(a, R, E) + 2 * a * E * (df - d)

        assert_mpmath_equal(depth_num, depth_mp, doms, rtol=TOL, n=n, dps=DPS,
                            name="sphere depth(a)")
        assert_mpmath_equal(force_num, force_mp, doms, rtol=TOL, n=n, dps=DPS,
                            name="sphere force_from_radius")
        assert_mpmath_equal(force_d_num, force_d_mp, doms, rtol=TOL, n=n, dps=DPS,
                            name="sphere force(d)")


def _u_outside_ref(r, d, R):
    """u_z(r) outside the contact by (5.60), (2/pi) integral_0^a (d - g(x))/sqrt(r^2 - x^2) dx,
    by tanh-sinh in x (not numeric/sphere.py's Gauss-Legendre in mu = atanh(x/R)), with
    g(x) = x atanh(x/R), the closed form of (5.52) that g_ref's quadrature checks
    (test_profile_and_g), and a = R tanh(lam) from d = g(a) = R lam tanh(lam) by findroot
    at the working precision (in lam, whose equation is tame up to a -> R). The
    interval is split at a - (r - a) 2^k, toward the near-singularity at x = r just beyond a
    (unsplit, tanh-sinh keeps only 14 digits at r = a (1 + 1e-6))."""
    r, d, R = mp.mpf(r), mp.mpf(d), mp.mpf(R)
    lam = mp.findroot(lambda v: v * mp.tanh(v) - d / R, max(mp.sqrt(d / R), d / R))
    a = R * mp.tanh(lam)
    pts = [mp.mpf(0)] + [a - (r - a) * 2**k for k in range(60, -1, -1) if a > (r - a) * 2**k]
    return 2 / mp.pi * mp.quad(lambda x: (d - x * mp.atanh(x / R)) / mp.sqrt((r - x) * (r + x)),
                               pts + [a])


def test_surface_displacement_outside_by_the_mdr_integral():
    """sphere.surface_displacement in one call over depths and radii: inside d - f(r) from the
    cap (30 digits); outside against (5.60) by tanh-sinh (20 digits), from just beyond the rim
    to r = R (where the numerical form's substitution point atanh(r/R) is infinite) and
    beyond R, and a contact 1e-5 short of R; d = 0 (no contact: u = 0 everywhere) in the same
    call."""
    R = 2e-3
    beta = np.array([0.01, 0.5, 0.9, 0.5, 0.5, 0.5, 0.0, 0.3, 0.99999])
    with mp.workdps(30):
        d = np.array([float(R * b * mp.atanh(b)) for b in beta])  # d = g(a) at a = beta R
    a = beta * R
    r = np.array([1.3 * a[0], a[1] * (1 + 1e-6), 3 * a[2], R, 3 * R, 0.2 * a[5], 0.7 * R,
                  0.6 * a[7], 2 * R])  # the last: mu up to atanh(0.99999) = 6.1, unit panels
    got = sphere.surface_displacement(r, d, R)
    with mp.workdps(20):
        for k in range(len(r)):
            if d[k] == 0:
                assert got[k] == 0.0
            elif r[k] < a[k]:
                with mp.workdps(30):
                    # d - f(r): the subtraction's rounding and f's few ulps, 2-4 ulps of d
                    assert abs(got[k] - (d[k] - f(mp.mpf(r[k]), R))) < 1e-15 * d[k], k
            else:
                ref = _u_outside_ref(r[k], d[k], R)
                # Gauss-Legendre panels to ~1e-15 (the module's error model); tanh-sinh at
                # 20 digits to ~1e-18
                assert abs(got[k] / ref - 1) < 1e-14, (k, got[k], ref)


def test_each_input_named_in_its_error():
    """Every input of every public function is named in its error (tests/named.py)."""
    from named import assert_inputs_named

    R, E, d = 2e-3, 1e11, 1e-5
    assert_inputs_named(sphere.profile, {"r": 1e-4, "R": R})
    assert_inputs_named(sphere.g_profile, {"x": 1e-4, "R": R})
    assert_inputs_named(sphere.depth, {"a": 1e-4, "R": R})
    assert_inputs_named(sphere.contact_radius, {"d": d, "R": R})
    assert_inputs_named(sphere.force_from_radius, {"a": 1e-4, "R": R, "E_star": E})
    assert_inputs_named(sphere.force, {"d": d, "R": R, "E_star": E})
    assert_inputs_named(sphere.depth_from_force, {"F": 1.0, "R": R, "E_star": E})
    assert_inputs_named(sphere.stiffness, {"d": d, "R": R, "E_star": E})
    assert_inputs_named(sphere.pressure, {"r": 1e-4, "d": d, "R": R, "E_star": E})
    assert_inputs_named(sphere.surface_displacement, {"r": 1e-4, "d": d, "R": R})


def test_an_input_out_of_range_in_a_2d_array_is_named_by_its_full_index():
    """The first bad element of a 2-D input is named by its (row, column) index, with R at the
    same index, for the radii bounded by R (r <= R, x < R)."""
    with pytest.raises(ValueError, match=r"^r\[\(1, 1\)\] = 2\.0 is out of range; valid: "
                       r"0 <= r <= R \(R\[\(1, 1\)\] = 1\.0\)$"):
        sphere.profile(np.array([[0.1, 0.2], [0.3, 2.0]]), 1.0)
    with pytest.raises(ValueError, match=r"^x\[\(0, 1\)\] = 1\.0 is out of range; valid: "
                       r"0 <= x < R \(R\[\(0, 1\)\] = 1\.0\)$"):
        sphere.g_profile(np.array([[0.5, 1.0]]), 1.0)


def test_the_deep_limit_itself_is_accepted_and_beyond_it_is_named():
    """d = DEEP_LIMIT R = 16 R is in the documented range 0 <= d <= 16 R: the centre pressure
    there against (5.59) at r = 0 in closed form, p(0) = (E*/pi) (chi_2(a/R) + lam) with
    g'(x)/x = atanh(x/R)/x + R/(R^2 - x^2), chi_2 the Legendre chi function and lam = atanh(a/R)
    the root of R lam tanh(lam) = d (5.55), all at 30 digits. A deeper d in a vector is named
    with its value and the limit."""
    R, E = 1.0, 1.0
    d = sphere.DEEP_LIMIT * R
    got = float(sphere.pressure(0.0, d, R, E))
    with mp.workdps(30):
        lam = mp.findroot(lambda v: R * v * mp.tanh(v) - d, 16)
        t = mp.tanh(lam)
        ref = E / mp.pi * ((mp.polylog(2, t) - mp.polylog(2, -t)) / 2 + lam)
    # lam is found to one ulp by bisection (5.55) and the quadrature of the atanh term is good
    # to ~1e-15 (test_pressure_by_quadrature_of_59): 1e-13 leaves 100x
    assert abs(got / float(ref) - 1) < 1e-13, (got, ref)
    with pytest.raises(ValueError, match=r"^d = 40\.0 is out of range; valid: 0 <= d <= 16 R = "
                       r"32\.0 \(deeper, "):
        sphere.pressure(0.0, np.array([1.0, 40.0]), 2.0, E)
