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

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import bodies, ellipse, hertz, impact

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


def _crossed_radius(omega, which):
    """Principal radii of two cylinders (R = 0.1 m) crossed at omega, by mpmath eigenvalues."""
    def ref():
        R = mp.mpf("0.1")
        c, s = mp.cos(mp.mpf(omega)), mp.sin(mp.mpf(omega))
        H = mp.matrix([[1 / R + c * c / R, c * s / R], [c * s / R, s * s / R]])
        ev = sorted((abs(x) for x in mp.eig(H)[0]), reverse=True)
        return 1 / ev[which]
    return ref


def _ellipse_force(q, d=1e-6, E=1e11, R1=1.0):
    """F of the exact elliptical contact with R1/R2 = q by Johnson's elliptic integrals."""
    from test_ellipse import ref_force, ref_t

    def ref():
        return ref_force(mp.mpf(E), mp.mpf(R1), mp.mpf(d), ref_t(q))
    return (lambda: ellipse.solve(R1, R1 / q, E, depth=d).force), ref


def _impact(v0, key):
    from test_impact import reference

    E, R, m = 2e11, 0.01, 0.03
    fn = {"tau": impact.contact_time, "x0": impact.max_depth}[key]
    return (lambda: fn(v0, R, E, m=m)), (lambda: reference(mp.mpf(E), mp.mpf(R), mp.mpf(m),
                                                           mp.mpf(v0))[key])


def _worn_force(s, b=1e-3, R=0.1, E=1e9):
    """F(d) of the worn parabola at 2 R d/b^2 = s: a from d = (a/R) sqrt(a^2 - b^2) by findroot
    at 50 digits, then F(a) = (2 E*/(3R)) (2a^2 + b^2) sqrt(a^2 - b^2) (Problem 8)."""
    d = s * b**2 / (2 * R)

    def ref():
        with mp.workdps(60):
            bb, RR, dd = mp.mpf(b), mp.mpf(R), mp.mpf(d)
            # a^2 = (b^2 + sqrt(b^4 + 4 R^2 d^2))/2 solves the depth relation exactly; findroot
            # polishes it on the defining equation
            a2 = (bb**2 + mp.sqrt(bb**4 + 4 * RR**2 * dd**2)) / 2
            a = mp.findroot(lambda x: x / RR * mp.sqrt(x**2 - bb**2) - dd, mp.sqrt(a2))
            return 2 * E / (3 * RR) * (2 * a**2 + bb**2) * mp.sqrt((a - bb) * (a + bb))
    return (lambda: gen.worn_force(E, R, b, d)), ref


CASES += [
    Case("principal radii of cylinders crossed at 1e-8 rad",
         "the small curvature ~ omega^2/(2R) is 1e-16 of the trace: (trace - sqrt(disc))/2 "
         "would cancel completely",
         lambda: bodies.principal_radii(0.1, np.inf, 0.1, np.inf, 1e-8)[1],
         _crossed_radius(1e-8, 1), WELL),
    Case("principal radii of cylinders crossed at 1e-12 rad", "as above, omega^2 = 1e-24",
         lambda: bodies.principal_radii(0.1, np.inf, 0.1, np.inf, 1e-12)[1],
         _crossed_radius(1e-12, 1), WELL),
    Case("elliptical contact with R1/R2 = 1 + 1e-9", "nearly circular: the K, E forms of the "
         "elliptical solution are 0/0 at the circle", *_ellipse_force(1 + 1e-9), WELL),
    Case("elliptical contact with R1/R2 = 1e4", "very elongated: b/a ~ 2e-3, the eccentricity "
         "equation is solved where K(m) has its log singularity",
         *_ellipse_force(1e4), 1e4 * np.log(1e4) * 10 * EPS,
         "the axis-ratio equation's condition number ~ q log q (q = R1/R2), times 10 eps"),
    Case("impact at 1e-6 m/s", "very low velocity: x0 ~ 1e-12 m", *_impact(1e-6, "tau"), WELL),
    Case("impact at 1e3 m/s", "very high velocity (elastically): x0 ~ 1e-3 m",
         *_impact(1e3, "x0"), WELL),
    *[Case(f"worn parabola F(d) at 2Rd/b^2 = {s:g}",
           "the printed F(d) subtracts sqrt(1 + s^2) - 1 and cancels all digits for small s; "
           "the printed stable form does not", *_worn_force(s), WELL)
      for s in (1e-12, 1e-6, 1.0, 1e6, 1e12)],
    Case("worn parabola with b -> 0 (b = 1e-9 R)", "tends to Hertz; the flat is 1e-9 of R",
         *_worn_force(1e3, b=1e-10), WELL),
]


def _kappa(n):
    from hertzmdr.numeric import powerlaw

    from test_powerlaw import kappa_reference

    return (lambda: powerlaw.kappa(n)), (lambda: kappa_reference(mp.mpf(n)))


def _normalized_pressure(n, rt):
    """p/p_mean (Fig. 5.17) at r/a = rt: (n + 1)/2 integral_rt^1 xi^(n-1)/sqrt(xi^2 - rt^2)."""
    from hertzmdr.numeric import powerlaw

    def ref():
        n_, rt_ = mp.mpf(n), mp.mpf(rt)
        # xi = rt cosh(t) removes the 1/sqrt at xi = rt
        f = lambda t: (rt_ * mp.cosh(t)) ** (n_ - 1)  # noqa: E731
        return (n_ + 1) / 2 * mp.quad(f, [0, mp.acosh(1 / rt_)])
    return (lambda: powerlaw.pressure_normalized(rt, n)), ref


def _axis_stress(comp, nu, z_over_a):
    from hertzmdr.numeric import stress

    from test_stress import _axis_reference

    idx = 0 if comp == "zz" else 1
    return (lambda: stress.axis_stresses(z_over_a, 1.0, 1.0, nu)[idx]), \
        (lambda: _axis_reference(comp, mp.mpf(nu), mp.mpf(z_over_a)))


def _cone_tip(r_over_a):
    """The cone's pressure near the tip: (5.59) with g' = (pi/2) tan(theta) is
    (E* tan(theta)/2) acosh(a/r), the quadrature of 1/sqrt(x^2 - r^2) over [r, a] done exactly."""
    from hertzmdr.numeric import cone

    theta, E, d = 0.3, 1e9, 1e-6
    a = float(cone.contact_radius(d, theta))
    r = r_over_a * a

    def ref():
        am = 2 * mp.mpf(d) / (mp.pi * mp.tan(mp.mpf(theta)))  # (5.38) from the MDR, g(a) = d
        return mp.mpf(E) * mp.tan(mp.mpf(theta)) / 2 * mp.acosh(am / mp.mpf(r))
    return (lambda: cone.pressure(r, d, theta, E)), ref


def _powerlaw_pressure(n, rt):
    """p(r) of f = c r^n at r = rt a against (5.59) by 30-digit tanh-sinh (test_powerlaw)."""
    from hertzmdr.numeric import powerlaw

    from test_powerlaw import _abel_reference

    E, aa, dd = 2.0, 1.0, 0.3  # a = 1: a^n neither overflows nor underflows at n = 1e8
    c = dd / (float(powerlaw.kappa(n)) * aa**n)
    a = float(powerlaw.contact_radius(dd, c, n))  # the same float a in the reference
    return (lambda: powerlaw.pressure(rt * a, dd, c, n, E)), \
        (lambda: _abel_reference(E, a, dd, n, rt * a))


def _worn_pressure(r_of, a=0.8, b=0.5):
    """worn_pressure (incomplete elliptic integrals) against (5.59) by quadrature (test_worn)."""
    from test_worn import pressure_ref

    r = r_of(a, b)
    return (lambda: gen.worn_pressure(3.0, 1.0, a, b, r)), \
        (lambda: pressure_ref(mp.mpf(r), mp.mpf(a), mp.mpf(b), mp.mpf(1), mp.mpf(3)))


def _edge_sigma_rr(nu):
    """At the contact edge on the surface sigma_rr = (1 - 2 nu) p0/3 (Johnson 1985, 3.41)."""
    from hertzmdr.numeric import stress

    return (lambda: stress.hertz_stress_cylindrical(1.0, 0.0, 1.0, 1.0, nu)[0]), \
        (lambda: (1 - 2 * mp.mpf(nu)) / 3)


CASES += [
    Case("kappa_n at n = 0.1", "n -> 0+: Gamma(n/2 + 1/2) and Gamma(n/2 + 1) of small "
         "arguments", *_kappa(0.1), WELL),
    Case("kappa_n at n = 1e6", "the Gamma ratio overflows float64 beyond n ~ 340; the Stirling "
         "series must take over", *_kappa(1e6), WELL),
    Case("p/p_mean of the power law n = 1e3 at r = a/2", "n -> inf tends to the flat punch "
         "(Fig. 5.17): xi^(n-1) underflows over most of the range", *_normalized_pressure(1e3, 0.5),
         1e3 * 10 * EPS, "the integrand's condition number ~ n, times 10 eps"),
    Case("cone pressure at r = 1e-12 a", "the log singularity of (5.39) at the tip",
         *_cone_tip(1e-12), WELL),
    Case("cone pressure at r = a (1 - 1e-10)", "acosh(a/r) of an argument next to 1",
         *_cone_tip(1 - 1e-10), 4 * EPS / (2 * 1e-10),
         "acosh(1 + e) has the relative condition number 1/(2 e) = 5e9 in its argument, and "
         "a/r carries a few roundings (a from d and theta, the quotient): 4 eps/(2 e)"),
    Case("sigma_xx on the axis at z = 1e4 a", "z -> inf: 1 - (z/a) atan(a/z) cancels all digits "
         "in (5.49); the printed deep form does not", *_axis_stress("xx", 0.3, 1e4), WELL),
    Case("sigma_xx on the axis at z = 1e-6 a", "z -> 0", *_axis_stress("xx", 0.3, 1e-6), WELL),
    Case("sigma_xx on the axis at z = 100 a with nu = 0.5", "nu = 1/2: the leading far-field "
         "term of (5.49) vanishes and the rest cancels", *_axis_stress("xx", 0.5, 100.0), WELL),
    Case("sigma_zz on the axis at z = 1e4 a", "z -> inf: (5.48) decays as (a/z)^2",
         *_axis_stress("zz", 0.3, 1e4), WELL),
    Case("sigma_rr at the contact edge, nu = 0.3", "the surface at r = a, where the pressure's "
         "slope is infinite", *_edge_sigma_rr(0.3), WELL),
    Case("power-law pressure, n = 345 at r = 1e-3 a", "SciPy's 2F1(1, 1 - n/2; 3/2; z) returns "
         "NaN here; (5.59) is integrated instead", *_powerlaw_pressure(345.0, 1e-3), WELL),
    Case("power-law pressure, n = 1e8 at r = a/2", "x^(n-1) lives in a layer of width a/n at "
         "x = a and its base 1 - O(1/n) would amplify rounding n-fold",
         *_powerlaw_pressure(1e8, 0.5), WELL),
    Case("power-law pressure, n = 1.001 at the centre", "the small-n form is 0 * inf at r = 0 "
         "for 1 < n < 1.5; p(0) ~ 1/(n - 1) is large", *_powerlaw_pressure(1.001, 0.0), WELL),
    Case("worn parabola pressure at r = b (1 - 1e-10)", "next to the log singularity at the "
         "kink: the modulus m = (r/b)^2 of F(phi|m) is 1 - 2e-10",
         *_worn_pressure(lambda a, b: b * (1 - 1e-10)), 4 * EPS / 2e-10,
         "F(phi|m) ~ log(1/(1 - m))/2 as m -> 1: a rounding of m is relative 1/(1 - m) in "
         "1 - m, so 4 eps/(1 - m)"),
    Case("worn parabola pressure at r = a (1 - 1e-12)", "the rim, p ~ sqrt(a - r): (a - r)(a + r)"
         " is factored", *_worn_pressure(lambda a, b: a * (1 - 1e-12)), WELL),
    Case("worn parabola pressure, b = a (1 - 1e-9), at r = b/2", "a nearly flat punch: the "
         "contact barely reaches past the flat, sin(phi) ~ 4e-5",
         *_worn_pressure(lambda a, b: b / 2, b=0.8 * (1 - 1e-9)), WELL),
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


# -- issue 19: the edges of the documented domains ------------------------------------------

def _powerlaw_depth(F, c, n, E):
    """d with F(d) = F: F(d) = 2n/(n + 1) E* a d, a = (d/(kappa_n c))^(1/n) (5.55), (5.57),
    kappa_n by quadrature (test_powerlaw.kappa_reference), d by findroot on log d."""
    from test_powerlaw import kappa_reference

    def ref():
        n_, c_, E_, F_ = (mp.mpf(v) for v in (n, c, E, F))
        k = kappa_reference(n_)

        def force(logd):
            dd = mp.exp(logd)
            return mp.log(2 * n_ / (n_ + 1) * E_ * (dd / (k * c_)) ** (1 / n_) * dd) - mp.log(F_)
        # F is a power of d: d^((n + 1)/n) (kappa c)^(-1/n) 2n E/(n + 1); start from log d = 0
        return mp.exp(mp.findroot(force, mp.mpf(0)))
    return ref


def _powerlaw_outside(n, r_over_a):
    """u_z(r > a) of the power law against (5.60) by quadrature in x (test_powerlaw)."""
    from hertzmdr.numeric import powerlaw

    from test_powerlaw import displacement_outside_reference

    d = 1.0
    c = 1.0 / float(powerlaw.kappa(n))  # a = 1 m
    a = float(powerlaw.contact_radius(d, c, n))
    r = r_over_a * a
    return (lambda: powerlaw.surface_displacement(r, d, c, n)), \
        (lambda: displacement_outside_reference(r, d, a, n))


def _max_shear_depth(nu_):
    """The depth of the tau_1 maximum: the root of the derivation's slope, 30 digits, by
    findroot on a bracket (0.05 a ... 2 a fails for nu < -0.8985)."""
    import sympy as sp

    from hertzmdr.derive import stress as ds
    from hertzmdr.numeric import stress

    def ref():
        s = sp.Symbol("s", positive=True)
        tau = (ds.max_shear_axis() / ds.p0).subs(ds.z, ds.a * s).subs(ds.a, 1)
        slope = sp.lambdify(s, sp.diff(tau.subs(ds.nu, sp.Float(nu_, 40)), s), "mpmath")
        # the maximum lies near pi (1 + nu)/6 as nu -> -1 and at ~0.55 a for nu = 1/2
        return mp.findroot(slope, (mp.pi * (1 + mp.mpf(nu_)) / 20, mp.mpf(2)),
                           solver="anderson")
    return (lambda: stress.axis_max_shear(nu_)[0]), ref


def _hertz_edge_displacement():
    """r = nextafter(a, 0) for a (d, R) of issue 19, where r*r <= R*d said 'outside'."""
    d, R = 1.3923563196198173e-07, 3.770060549304781e-07
    r = 2.2911280259238836e-07
    return (lambda: hertz.surface_displacement(r, d, R)), _far_displacement(R, d, r)


def _cone_flat(r, d, theta, E):
    from hertzmdr.numeric import cone

    def ref():
        # (5.39), p = (E*/2) tan(theta) acosh(a/r), a = 2d/(pi tan(theta)) (5.38), in mpmath
        # (no overflow of a/r = 6e308 there)
        t = mp.tan(mp.mpf(theta))
        return mp.mpf(E) * t / 2 * mp.acosh(2 * mp.mpf(d) / (mp.pi * t * mp.mpf(r)))
    return (lambda: cone.pressure(r, d, theta, E)), ref


def _kappa_huge(n):
    from hertzmdr.numeric import powerlaw

    def ref():
        with mp.workdps(400):  # ln Gamma(n/2) ~ 3e302: the difference needs 300 more digits
            nn = mp.mpf(n)
            return mp.sqrt(mp.pi) * mp.exp(mp.loggamma(nn / 2 + 1) - mp.loggamma(nn / 2 + 0.5))
    return (lambda: powerlaw.kappa(n)), ref


def _far_axis_sigma_rr(z_over_a):
    from hertzmdr.numeric import stress

    def ref():
        # (5.49) as the chapter prints it, at 400 digits: its terms of size 1 cancel to leave
        # one of size (a/z)^2 = 1e-156, so ~320 digits are lost and ~80 remain
        with mp.workdps(400):
            z, nu = mp.mpf(z_over_a), mp.mpf(3) / 10
            return -((1 + nu) * (1 - z * mp.atan(1 / z)) - 1 / (2 * (1 + z**2)))
    return (lambda: stress.hertz_stress_cylindrical(0.0, z_over_a, 1.0, 1.0, 0.3)[0]), ref


CASES += [
    Case("power-law u_z, n = 1000 at r = 1.001 a", "SciPy's 2F1(1/2, (n + 1)/2; (n + 3)/2; z) "
         "of (5.60) returns NaN for n >= 342 next to the edge; the integral of a positive "
         "integrand is taken instead", *_powerlaw_outside(1000.0, 1.001), WELL),
    Case("power-law u_z, n = 343.5 at r = 1.001 a", "as above; the 2F1 gave -inf here",
         *_powerlaw_outside(343.5, 1.001), WELL),
    Case("power-law u_z, n = 1e-3 at r = a (1 + 1e-12)", "next to the edge the 2F1 form "
         "subtracts two sqrt(r - a) terms (and for small n loses 1/n more)",
         *_powerlaw_outside(1e-3, 1 + 1e-12), WELL),
    Case("Hertz u_z at r = nextafter(a, 0)", "r*r <= R*d and the rounded a = sqrt(R) sqrt(d) "
         "disagreed: arcsin(1 + 2e-16) = NaN", *_hertz_edge_displacement(), WELL),
    Case("power-law depth from F = 1 N, c_n = 3, n = 1e-3", "(kappa c)^(1/n) = 3^1000 of the "
         "textbook inverse overflows although d = 2.96 m (inf before)",
         lambda: powerlaw_depth_from_force(1.0, 3.0, 1e-3, 1e9),
         _powerlaw_depth(1.0, 3.0, 1e-3, 1e9),
         # d = (F ...)^(n/(n + 1)) (kappa c)^(1/(n + 1)): exponents below 1 shrink the
         # roundings; kappa_n (Gamma ratio) and the powers: a few eps
         WELL),
    Case("power-law depth from F = 3.3e-284 N, n = 0.0209", "F (kappa c)^(1/n) underflowed: "
         "0 was returned for d = 8.9e-8 m",
         lambda: powerlaw_depth_from_force(3.348556860994228e-284, 0.06977002573100553,
                                           0.020913738184586448, 11216280.892656678),
         _powerlaw_depth(3.348556860994228e-284, 0.06977002573100553, 0.020913738184586448,
                         11216280.892656678),
         # d = (F ...)^(n/(n + 1)): a relative rounding of the base is multiplied by
         # n/(n + 1) < 1, but the base's two powers each carry |log| ~ 650 times eps
         1e3 * EPS, "the powers of 1e-284: |log F| eps = 650 eps"),
    Case("depth of the maximum shear at nu = -0.9", "the maximum lies at 0.049 a, outside the "
         "fixed bracket 0.05 a ... 2 a", *_max_shear_depth(-0.9), WELL),
    Case("depth of the maximum shear at nu = nextafter(-1, 0)", "the maximum at 6e-17 a: the "
         "bracket and the tolerance of the root must be relative",
         *_max_shear_depth(float(np.nextafter(-1.0, 0.0))), WELL),
    Case("kappa_n at n = 1e300", "the Stirling series' 1/n^2 overflowed n^2 (value right, with "
         "a warning)", *_kappa_huge(1e300), WELL),
    Case("cone pressure with theta = 1e-300", "a/r = 6e308 overflowed in arccosh(a/r); "
         "2 asinh(sqrt(a - r)/sqrt(2 r)) does not", *_cone_flat(1e-12, 1e-3, 1e-300, 1.0),
         WELL),
    Case("sigma_rr on the axis at z = 1e78 a", "the far-field form's xi^4 overflowed (NaN): it "
         "is printed in powers of 1/xi", *_far_axis_sigma_rr(1e78), WELL),
]


def powerlaw_depth_from_force(F, c, n, E):
    from hertzmdr.numeric import powerlaw

    return powerlaw.depth_from_force(F, c, n, E)


@pytest.mark.parametrize("call", [
    lambda: __import__("hertzmdr.numeric.cone", fromlist=["x"]).force(1.0, 1e-300, 2.1e11),
    lambda: __import__("hertzmdr.numeric.powerlaw", fromlist=["x"]).contact_radius(
        1e-3, 1e-6, 1e-3),
    lambda: __import__("hertzmdr.numeric.powerlaw", fromlist=["x"]).g_profile(1000.0, 1.0, 343.5),
    lambda: __import__("hertzmdr.numeric.powerlaw", fromlist=["x"]).mean_pressure(
        1e-20, 1e-6, 1e-3, 1.0),
    lambda: bodies.crossed_cylinders_gaussian_radius(1e300, 1.0, 1e-300),
], ids=["cone.force", "powerlaw.contact_radius", "powerlaw.g_profile", "powerlaw.mean_pressure",
        "bodies.crossed_cylinders_gaussian_radius"])
def test_not_representable_is_an_error(call):
    """Issue 19, row 11: where the true value exceeds 1.8e308 (checked: log10 of each is > 308,
    e.g. cone.force = (2/pi) E* d^2/tan(theta) = 1.3e311 N), an OverflowError that names the
    inputs, never a silent inf."""
    with pytest.raises(OverflowError, match="exceeds the float64 range") as info:
        call()
    assert " = " in str(info.value)  # the inputs are named


# -- issue 14: the line-contact field (plane strain) --------------------------------------------

def _line(quantity, x, z, nu=0.3):
    """A line-contact stress (b = p0 = 1) by the public float64 API, against the 35-digit
    superposition of the derived Flamant load over the pressure (tests/test_line_stress.py's
    ``superposed``, split at the strip's edges and around the field point)."""
    from test_line_stress import superposed

    from hertzmdr.numeric import line_stress as ls

    def compute():
        if quantity == "von_mises":
            return ls.von_mises(x, z, 1.0, 1.0, nu)
        return ls.stresses(x, z, 1.0, 1.0, nu)[("xx", "zz", "xz").index(quantity)]

    def ref():
        if quantity != "von_mises":
            return superposed(quantity, x, z)
        sx, sz, t = (superposed(c, x, z) for c in ("xx", "zz", "xz"))
        sy = mp.mpf(nu) * (sx + sz)
        return mp.sqrt(((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) / 2 + 3 * t * t)
    return compute, ref


CASES += [
    Case("line von Mises just below the surface inside the edge (x = b(1 - 1e-6), z = 1e-7 b)",
         "the pressure's square-root edge: m^2 - z^2 and (a - x)(a + x) + n^2 are differences "
         "of nearly equal numbers in the textbook forms", *_line("von_mises", 1 - 1e-6, 1e-7),
         WELL),
    Case("line sigma_xx just below the surface outside the edge (x = b(1 + 1e-6), z = 1e-7 b)",
         "outside the strip the surface is traction-free: sigma_xx ~ z is what is left of "
         "terms of size p0 (the g = 2 a^2 z^2/(D + e) form keeps it)",
         *_line("xx", 1 + 1e-6, 1e-7), WELL),
    Case("line tau_xz near the surface far outside (x = 2 b, z = 1e-8 b)",
         "tau_xz ~ z/b vanishes on the free surface: a small difference in the textbook form",
         *_line("xz", 2.0, 1e-8), WELL),
    Case("line sigma_xx on the axis far below (z = 1e6 b)",
         "far field: the textbook 2z/b - (b^2 + 2 z^2)/(b s) cancels to O(b^3/z^3), 18 digits "
         "lost; -p0 b^3/(s (s + z)^2) has no cancellation", *_line("xx", 0.0, 1e6), WELL),
    Case("line von Mises at nu = 1/2 just below the centre (z = 1e-6 b)",
         "incompressible: the hydrostatic part (1 - 2 nu) c vanishes exactly and sigma_v = "
         "3^(1/2) tau_1 ~ z/b is all that is left of stresses of size p0",
         *_line("von_mises", 0.0, 1e-6, 0.5), WELL),
    Case("line von Mises at nu = 1/2 far away (x = z = 1e3 b)",
         "far field and incompressible: every stress ~ b/r, sigma_v a difference of them",
         *_line("von_mises", 1e3, 1e3, 0.5), WELL),
]


# -- issue 14: the elliptical-contact field ----------------------------------------------------

COMPS = ("xx", "yy", "zz", "xy", "xz", "yz")


def _ellipse_mp(t, x, y, z, nu):
    """The six stresses (a = p0 = 1, b = t) by the derived relations at DPS digits: their
    mpmath print, lam polished by mp.findroot on the cubic from the float64 lam, the J
    integrals by mp.quad (tanh-sinh, split at the integrand's scale)."""
    from hertzmdr.numeric import _generated_mp as gm
    from hertzmdr.numeric import ellipse_stress as el

    one, B, X, Y, Z, nu_ = (mp.mpf(v) for v in (1, t, x, y, z, nu))
    w1, w1a, w1b, d = (getattr(gm, f"ellipse_stress_{n}")(one, B, X, Y)
                       for n in ("w1", "w1_a", "w1_b", "d"))
    g = el._geometry(np.array([x]), np.array([y]), np.array([z]), np.array([t]))
    if w1 < 0:
        lam = mp.findroot(lambda v: gm.ellipse_stress_cubic_lam(one, B, Z, w1, d, v),
                          mp.mpf(float(g["lam"][0])))
        q = lam - w1
    else:
        q = mp.findroot(lambda v: gm.ellipse_stress_cubic_q(Z, w1, w1a, w1b, d, v),
                        mp.mpf(float(g["q"][0])))
        lam = w1 + q
    e = mp.sqrt(gm.ellipse_stress_e_sq(one, B, lam, q, d))
    Ix, Iy = gm.ellipse_stress_I_x(one, B, lam), gm.ellipse_stress_I_y(one, B, lam)
    v0 = mp.sqrt(q)
    pts = [v0, v0 + mp.sqrt(B * B + lam), v0 + 1, mp.inf]
    J = {k: mp.quad(f, pts) for k, f in (
        ("xx", lambda v: gm.ellipse_stress_jxx_integrand(X, w1a, w1b, d, v)),
        ("yy", lambda v: gm.ellipse_stress_jyy_integrand(Y, w1a, w1b, d, v)),
        ("xy", lambda v: gm.ellipse_stress_jxy_integrand(X, Y, w1a, w1b, d, v)))}
    args = (one, B, nu_, one, X, Y, lam, e)
    alg = (one, B, one, X, Y, lam, e)
    return {"xx": gm.ellipse_stress_sigma_xx(*args, Ix, Iy, J["xx"]),
            "yy": gm.ellipse_stress_sigma_yy(*args, Ix, Iy, J["yy"]),
            "zz": gm.ellipse_stress_sigma_zz(*alg), "xy": gm.ellipse_stress_tau_xy(*args, J["xy"]),
            "xz": gm.ellipse_stress_tau_xz(*alg), "yz": gm.ellipse_stress_tau_yz(*alg)}


def _ellipse(comp, t, x, y, z, nu=0.3):
    """One stress component of the elliptical Hertz pressure (a = p0 = 1, b = t) by the public
    float64 API (the double-exponential rule asked 1e-13), against the same derived relations
    at 35 digits (_ellipse_mp). These cases test float64 stability: the relations themselves
    are verified against the superposition of the point-force field at the same points
    (tests/test_ellipse_stress.py::test_hard_points_by_polar_superposition)."""
    from hertzmdr.numeric import ellipse_stress as el

    def compute():
        s = el.stresses(x, y, z, 1.0, t, 1.0, nu, rtol=1e-13)
        return dict(zip(COMPS, s[:6], strict=True))[comp]

    return compute, lambda: _ellipse_mp(t, x, y, z, nu)[comp]


def _ellipse_axis(comp, t, z, nu=0.3):
    """An axis stress by the R_D closed forms (ellipse_stress.axis_stresses) against the
    off-axis route of the derived relations at 35 digits on the axis (_ellipse_mp: lam, e and
    the J integrals, a different set of relations)."""
    from hertzmdr.numeric import ellipse_stress as el

    def compute():
        return el.axis_stresses(z, 1.0, t, 1.0, nu)[("xx", "yy", "zz").index(comp)]

    return compute, lambda: _ellipse_mp(t, 0.0, 0.0, z, nu)[comp]


ELLIPSE_CASES = [
    Case("ellipse b/a = 1e-3, sigma_xx at (0.3 a, 0.4 b, 0.3 b)",
         "almost a line: the J integrals grow like a/b and sigma_xx is what is left of them "
         "(b/a = 0.01 at this point was issue 14's open disagreement)",
         *_ellipse("xx", 1e-3, 0.3, 0.4e-3, 0.3e-3), WELL),
    Case("ellipse b/a = 0.1, sigma_xx just below the surface by the edge (0.99 a, 0, 1e-6 b)",
         "lam ~ z^2 is a small root of the cubic next to the surface ellipse's confocal family",
         *_ellipse("xx", 0.1, 0.99, 0.0, 1e-7), WELL),
    Case("ellipse b/a = 0.5, tau_xz just below the surface outside the edge (1.01 a, 0, 1e-6 a)",
         "outside the contact the surface is traction-free: tau_xz ~ z is a small remainder",
         *_ellipse("xz", 0.5, 1.01, 0.0, 1e-6), WELL),
    Case("ellipse b/a = 0.3, sigma_yy far away (3 a, 0.5 a, 50 a)",
         "far field: every stress ~ p0 (a/r)^2, a difference of terms of size p0",
         *_ellipse("yy", 0.3, 3.0, 0.5, 50.0), WELL),
    Case("ellipse b/a = 0.5, nu = 1/2, sigma_zz near the centre (1e-3 a, 1e-3 b, 1e-6 b)",
         "incompressible, at the loaded surface: lam ~ z^2 and e -> 1",
         *_ellipse("zz", 0.5, 1e-3, 0.5e-3, 0.5e-6, 0.5), WELL),
    Case("ellipse b/a = 1e-8 on the axis, sigma_xx at z = 0.786 b (R_D forms)",
         "almost a line: R_D with arguments b^2 + z^2, z^2 and a^2 + z^2 16 decades apart",
         *_ellipse_axis("xx", 1e-8, 0.786e-8), WELL),
    Case("ellipse b/a = 1 - 1e-9 on the axis, sigma_yy at z = 0.5 a (R_D forms)",
         "nearly circular: the x and y forms are the circle's up to O(1 - b/a)",
         *_ellipse_axis("yy", 1 - 1e-9, 0.5), WELL),
    Case("ellipse b/a = 0.3 on the axis far below, sigma_xx at z = 1e3 a (R_D forms)",
         "far field: sigma_xx ~ p0 (a/z)^2 is a difference of terms of size p0",
         *_ellipse_axis("xx", 0.3, 1e3), WELL),
]
CASES += ELLIPSE_CASES
