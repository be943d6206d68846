"""Adhesive (JKR-type) contact by the MDR, against independent routes.

- Literature: JKR (Johnson, Kendall & Roberts 1971; Maugis 2000, ch. 5) and Kendall's punch
  (1971) typed from the literature in mpmath at 30 digits, against the float64 functions
  (13 digits asked for).
- Pull-off of the cone, the power law, the exact sphere and the worn tip: the derived F(a)
  and d(a) printed for mpmath, minimized by mpmath (a root of the numerical derivative by
  the secant method, 30 digits): neither the closed-form pull-off nor the float root-finder
  enters.
- 3-D route: the derived adhesive pressure put through the Boussinesq integral (5.7)
  (tests/kernels.py) gives d - f(r) inside and the derived displacement outside (20 digits);
  the stress intensity factor of the pressure at the edge, through Irwin's G = K^2/(2 E*),
  gives the energy release rate, which equals Delta gamma at equilibrium.
- The hysteresis of a cycle against the mpmath quadrature of F dd along the derived curve.
"""

import math

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gmp
from hertzmdr.numeric import adhesion as ad
from hertzmdr.numeric import hertz, sphere

from kernels import uz_axisymmetric
from named import assert_inputs_named
from oracle import WORST, assert_close, memo

DPS = 30
TOL_LIT = 1e-13  # the 13 digits; closed forms are a handful of roundings (~1e-15)
TOL_3D = 1e-20  # the 20 digits; Gauss-Legendre kernel quadrature at 30 digits ~1e-25
# (E*, R, dgamma): the AFM tip on PDMS (R = 20 nm, E = 2 MPa, nu = 0.5), a steel ball on
# glass, a rubber sphere on glass
CASES = [(2e6 / 0.75, 20e-9, 0.05), (1.1e11, 1e-2, 0.1), (1.3e6, 5e-3, 0.07)]


def _record(what, err, tol):
    WORST[what] = max(WORST.get(what, 0.0), float(err))
    assert err < tol, f"{what}: {err} >= {tol}"


def _mp_min(fun, a0):
    """The stationary point of fun within 1e-3 of a0 at the working precision: Anderson's
    bracketing method on fun' (mpmath's numerical derivative), a minimization that knows no
    closed form (the bracket is checked to hold a sign change)."""
    lo, hi = a0 * (1 - mp.mpf(10) ** -3), a0 * (1 + mp.mpf(10) ** -3)

    def slope(a):
        return mp.diff(fun, a)

    assert slope(lo) < 0 < slope(hi)
    return mp.findroot(slope, (lo, hi), solver="anderson", verify=False)


def test_jkr_literature():
    for E, R, dg in CASES:
        c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
        with mp.workdps(DPS):
            Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
            K = 4 * Em / 3
            lit = {
                ("force", "force"): -3 * mp.pi * Rm * gm / 2,
                ("depth", "force"): -5 * mp.pi * Rm * gm / 6,
                ("force", "radius"): mp.cbrt(9 * mp.pi * gm * Rm**2 / (8 * Em)),
                ("depth", "radius"): mp.cbrt(mp.pi * gm * Rm**2 / (8 * Em)),
                ("depth", "depth"): -mp.mpf(3) / 4 * mp.cbrt(mp.pi**2 * gm**2 * Rm / Em**2),
            }
            # the force-control depth from JKR's delta(a) = a^2/R - sqrt(2 pi a dg/E*)
            a_fc = lit[("force", "radius")]
            lit[("force", "depth")] = a_fc**2 / Rm - mp.sqrt(2 * mp.pi * a_fc * gm / Em)
            for (control, what), ref in lit.items():
                po = c.pull_off(control)
                got = {"force": po.force, "radius": po.contact_radius, "depth": po.depth}[what]
                assert_close(got, ref, TOL_LIT, f"JKR {what} at pull-off, {control} control")
            a0 = mp.cbrt(9 * mp.pi * gm * Rm**2 / (2 * Em))  # a0^3 = 6 pi dg R^2 / K
            assert_close(c.zero_load_contact_radius(), a0, TOL_LIT, "JKR zero-load radius")
            for s in ("0.3", "1.5", "4"):  # not 1: F(a0) = 0
                a = mp.mpf(s) * a0
                F_lit = K * a**3 / Rm - mp.sqrt(8 * mp.pi * gm * Em * a**3)
                d_lit = a**2 / Rm - mp.sqrt(2 * mp.pi * a * gm / Em)
                assert_close(c.force(float(a)), F_lit, TOL_LIT, "JKR F(a)")
                assert_close(c.depth(float(a)), d_lit, TOL_LIT, "JKR d(a)")
                if a >= lit[("force", "radius")]:  # the stable branch under force control
                    F = float(F_lit)
                    Fm = mp.mpf(F)
                    a_lit = mp.cbrt(Rm / K * (Fm + 3 * mp.pi * Rm * gm + mp.sqrt(
                        6 * mp.pi * Rm * gm * Fm + (3 * mp.pi * Rm * gm) ** 2)))
                    # a(F) is ill-conditioned next to F_c (da/dF infinite there): 1 ulp of F
                    # at a = a_fc * 1.2 costs ~30 ulp of a
                    assert_close(c.contact_radius(force=F), a_lit, 1e-13, "JKR a(F)")
                if a >= lit[("depth", "radius")]:
                    assert_close(c.contact_radius(depth=float(d_lit)), a, 1e-13, "JKR a(d)")


def test_kendall_literature():
    for E, R, dg in CASES:
        c = ad.AdhesiveContact(ad.FlatPunch(R), E, dg)
        with mp.workdps(DPS):
            ref = -mp.sqrt(8 * mp.pi * mp.mpf(R) ** 3 * mp.mpf(E) * mp.mpf(dg))
            for control in ad.CONTROLS:
                po = c.pull_off(control)
                assert_close(po.force, ref, TOL_LIT, "Kendall pull-off force")
                # the depth: F = 2 E* a d (5.12) at the pull-off force
                assert_close(po.depth, ref / (2 * mp.mpf(E) * mp.mpf(R)), TOL_LIT,
                             "Kendall pull-off depth")


def _mp_curves(shape):
    """(d(a), F(a)) of a shape as mpmath functions: the derived relations printed for mpmath."""
    E, dg = mp.mpf(3e6), mp.mpf(0.04)
    if isinstance(shape, ad.Cone):
        th = mp.mpf(shape.theta)
        return (E, dg, lambda a: gmp.adhesion_cone_depth(E, a, dg, th),
                lambda a: gmp.adhesion_cone_force_from_radius(E, a, dg, th))
    if isinstance(shape, ad.PowerLaw):
        c, n = mp.mpf(shape.c_n), mp.mpf(shape.n)
        k = gmp.powerlaw_kappa(n)
        return (E, dg, lambda a: gmp.adhesion_powerlaw_depth(E, a, dg, c, k, n),
                lambda a: gmp.adhesion_powerlaw_force_from_radius(E, a, dg, c, k, n))
    if isinstance(shape, ad.Sphere):
        R = mp.mpf(shape.R)
        def dl(a):
            return (gmp.adhesion_critical_elongation(E, a, dg))
        return (E, dg, lambda a: gmp.sphere_depth(R, a) - dl(a),
                lambda a: gmp.sphere_force_from_radius(E, R, a) - 2 * E * a * dl(a))
    if isinstance(shape, ad.Worn):
        R, b = mp.mpf(shape.R), mp.mpf(shape.b)
        def dl(a):
            return (gmp.adhesion_critical_elongation(E, a, dg))
        return (E, dg, lambda a: gmp.worn_depth(R, a, b) - dl(a),
                lambda a: gmp.worn_force_from_radius(E, R, a, b) - 2 * E * a * dl(a))
    raise AssertionError(shape)


SHAPES = [ad.Cone(np.radians(20)), ad.Cone(1.2), ad.PowerLaw(2.5e7, 2.0),
          ad.PowerLaw(3e3, 1.5), ad.PowerLaw(1e14, 3.0), ad.PowerLaw(50.0, 0.8),
          ad.Sphere(20e-9), ad.Sphere(1e-6), ad.Worn(1e-6, 5e-9)]


@pytest.mark.parametrize("shape", SHAPES, ids=repr)
def test_pull_off_by_mpmath_minimization(shape):
    E, dg, d_fn, F_fn = _mp_curves(shape)
    c = ad.AdhesiveContact(shape, float(E), float(dg))
    with mp.workdps(DPS):
        for control, fn in (("force", F_fn), ("depth", d_fn)):
            po = c.pull_off(control)
            a_ref = _mp_min(fn, mp.mpf(po.contact_radius))
            # F and d are stationary at a_c: the float value is the function at a root good
            # to ~1e-15, so F_c to a few ulp; the root itself to ~sqrt(eps) in principle,
            # but the slope's root is simple: Brent's method and the closed forms give 1e-14
            assert_close(po.contact_radius, a_ref, 2e-14, f"{shape} a_c {control}")
            assert_close(po.force, F_fn(a_ref), 1e-14, f"{shape} F_c {control}")
            # d_c = g(a_c) - Delta l(a_c) cancels (to 0 for n = 3/2): relative to Delta l
            dl = gmp.adhesion_critical_elongation(E, a_ref, dg)
            err = abs((po.depth - d_fn(a_ref)) / dl)
            assert err < 1e-14, f"{shape} d_c {control}: {err}"
            assert po.rel_error < 1e-13
        if not isinstance(shape, (ad.Sphere, ad.Worn)):
            # the closed forms against the bracketed route of the same module
            for control in ad.CONTROLS:
                a_from = 100 * c.pull_off(control).contact_radius
                root = c.pull_off(control, a_from=a_from)
                assert root.method.startswith("bracketed")
                assert abs(root.force / c.pull_off(control).force - 1) < 1e-14


def test_worn_tip_has_its_own_pull_off():
    """A wide flat (b >> the JKR pull-off radius) lets go at the kink a = b: Kendall's punch."""
    E, dg, R, b = 3e6, 0.04, 1e-6, 300e-9
    c = ad.AdhesiveContact(ad.Worn(R, b), E, dg)
    po = c.pull_off("force")
    assert po.contact_radius == b
    with mp.workdps(DPS):
        ref = -mp.sqrt(8 * mp.pi * mp.mpf(b) ** 3 * mp.mpf(E) * mp.mpf(dg))
        assert_close(po.force, ref, TOL_LIT, "worn tip = Kendall punch at the kink")


def test_g_slopes_by_differences():
    with mp.workdps(DPS):
        # the references at the float inputs: g' is ill-conditioned next to R (and b)
        R, b = mp.mpf(2e-8), mp.mpf(5e-9)
        for t in ("1e-6", "0.3", "0.9", "0.999999"):
            x = mp.mpf(float(mp.mpf(t) * R))
            ref = mp.diff(lambda u: gmp.sphere_g(R, u), x)
            assert_close(gen.adhesion_sphere_g_slope(float(R), float(x)), ref, 4e-15,
                         f"sphere g'({t} R)")
        for t in ("1.000001", "1.5", "30"):
            x = mp.mpf(float(mp.mpf(t) * b))
            ref = mp.diff(lambda u: gmp.worn_g(R, b, u), x)
            assert_close(gen.adhesion_worn_g_slope(float(R), float(b), float(x)), ref, 4e-15,
                         f"worn g'({t} b)")
        # the paraboloid, the cone and the power law: g of the literature (x^2/R, (pi/2)
        # tan(theta) x, kappa_n c_n x^n with kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2))
        # differentiated by mpmath; a few roundings
        th = mp.mpf(0.4)
        for n, c_n in ((1.5, 40.0), (3.0, 1e6), (0.75, 2.0)):
            nn = mp.mpf(n)
            kap = mp.sqrt(mp.pi) * mp.gamma(nn / 2 + 1) / mp.gamma(nn / 2 + mp.mpf(1) / 2)
            kc = kap * mp.mpf(c_n)
            for x in (0.0, 1e-9, 3e-6, 2e-3) if n > 1 else (1e-9, 3e-6, 2e-3):
                # at x = 0: g' = 0 for n > 1 (x^n/x would be 0/0); infinite for n < 1
                ref = mp.diff(lambda u, k=kc, m=nn: k * u**m, mp.mpf(x)) if x else 0
                got = gen.adhesion_powerlaw_g_slope(c_n, float(kap), n, x)
                assert_close(got, ref, 4e-15, f"power law n = {n} g'({x})")
        for x in (0.0, 1e-9, 3e-6, 2e-3):
            xm = mp.mpf(x)
            got = gen.adhesion_paraboloid_g_slope(float(R), x)
            assert_close(got, mp.diff(lambda u: u * u / R, xm), 4e-15, f"paraboloid g'({x})")
        assert_close(gen.adhesion_cone_g_slope(0.4), mp.diff(lambda u: mp.pi / 2 * mp.tan(th) * u,
                                                             mp.mpf("1e-3")), 4e-15, "cone g'")


def _jkr_mp(E, R, dg, a):
    """The derived adhesive pressure and displacement of a paraboloid, at 30 digits."""
    d = gmp.jkr_depth(E, R, a, dg)
    def p(rho):
        return (gmp.jkr_pressure(E, R, a, dg, rho))
    def u_out(r):
        return (gmp.hertz_displacement_outside(R, a**2 / R, r)
                 + gmp.adhesion_displacement_outside_edge(E, a, dg, r))
    return d, p, u_out


@memo  # a mutation run's memo (tests/oracle.py): the generated mpmath forms (derive/'s, not
# numeric/adhesion.py), tests/kernels.py's quadrature and mpmath only
def _jkr_uz_3d(E, R, dg, a, rr):
    """u_z(rr) of the derived JKR pressure of radius a put through the Boussinesq integral
    (5.7) (tests/kernels.py), at the working precision."""
    _, p, _ = _jkr_mp(E, R, dg, a)

    def p_gap(gap):
        return p(mp.sqrt(a**2 - gap))

    return uz_axisymmetric(p_gap, rr, a, E)


def test_jkr_pressure_by_boussinesq():
    with mp.workdps(DPS):
        E, R, dg = mp.mpf(3), mp.mpf(2), mp.mpf("0.05")
        a = mp.mpf("0.7")
        d, _, u_out = _jkr_mp(E, R, dg, a)
        for s in ("0", "0.6"):
            rr = mp.mpf(s) * a
            u = _jkr_uz_3d(E, R, dg, a, rr)
            _record("JKR 3-D inside", abs(u / (d - rr**2 / (2 * R)) - 1), TOL_3D)
        rr = 2 * a
        u = _jkr_uz_3d(E, R, dg, a, rr)
        _record("JKR 3-D outside", abs(u / u_out(rr) - 1), TOL_3D)
    # the float64 fields at the same points
    c = ad.AdhesiveContact(ad.Paraboloid(2.0), 3.0, 0.05)
    with mp.workdps(DPS):
        for rr in (0.0, 0.35, 0.7 * (1 - 1e-9)):
            # at the float a = 0.7, not the decimal one
            ref = gmp.jkr_pressure(E, R, mp.mpf(0.7), dg, mp.mpf(rr))
            assert_close(float(c.pressure(rr, 0.7)), ref, 1e-13, f"p({rr})")
        a7 = mp.mpf(0.7)
        u_ref = (gmp.hertz_displacement_outside(R, a7**2 / R, mp.mpf(1.4))
                 + gmp.adhesion_displacement_outside_edge(E, a7, dg, mp.mpf(1.4)))
        assert_close(float(c.surface_displacement(1.4, 0.7)), u_ref, 1e-14, "u(2a)")
        d7 = gmp.jkr_depth(E, R, a7, dg)
        assert_close(float(c.surface_displacement(0.35, 0.7)),
                     d7 - mp.mpf(0.35) ** 2 / (2 * R), 1e-14, "u inside")


def test_energy_release_rate_by_3d_route():
    """K_I = lim p(r) sqrt(2 pi (a - r)) of the 3-D pressure, G = K_I^2/(2 E*) (Irwin)."""
    # at 80 digits with a - r = 1e-30 a: rounding of r costs 1e-50/1e-30, the next term of
    # the edge expansion (a - r)/a = 1e-30; both far below the 20 digits asked for
    with mp.workdps(80):
        E, R, dg = mp.mpf(3), mp.mpf(2), mp.mpf("0.05")
        for a in (mp.mpf("0.3"), mp.mpf("0.7"), mp.mpf(2)):
            # at equilibrium: the JKR pressure of the derivation
            eps = mp.mpf(10) ** -30 * a
            K = -gmp.jkr_pressure(E, R, a, dg, a - eps) * mp.sqrt(2 * mp.pi * eps)
            _record("G = dgamma at the edge", abs(K**2 / (2 * E) / dg - 1), 1e-20)
            assert_close(float(gen.adhesion_critical_elongation(float(E), float(a), float(dg))),
                         mp.sqrt(2 * mp.pi * a * dg / E), 1e-15, "Delta l")
            # off equilibrium, at any depth d < g(a): Hertz's pressure of radius a plus the
            # flat punch of (5.9) pushed by d - g(a), whose K is the edge coefficient
            g_a = a**2 / R
            for d in (g_a / 2, -g_a):
                K = -(d - g_a) * E / (mp.pi * mp.sqrt(2 * a)) * mp.sqrt(2 * mp.pi)
                G_ref = K**2 / (2 * E)
                assert_close(gen.adhesion_energy_release_rate(float(E), float(a), float(d),
                                                              float(g_a)),
                             G_ref, 1e-14, "G(a, d)")


def test_tabor_parameter():
    with mp.workdps(DPS):
        E, R, dg, z0 = 2e6 / 0.75, 20e-9, 0.05, 0.3e-9
        ref = mp.cbrt(mp.mpf(R) * mp.mpf(dg) ** 2 / (mp.mpf(E) ** 2 * mp.mpf(z0) ** 3))
        assert_close(ad.tabor_parameter(R, E, dg, z0), ref, 1e-15, "Tabor")
        assert ad.tabor_parameter(R, E, dg, z0) > ad.TABOR_JKR  # soft PDMS: JKR
        assert ad.tabor_parameter(R, 1e11, 0.05, z0) < ad.TABOR_JKR  # stiff: not JKR


@pytest.mark.parametrize("control", ad.CONTROLS)
def test_jkr_cycle(control):
    E, R, dg = 2e6 / 0.75, 20e-9, 0.05
    c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
    to = 10e-9 if control == "depth" else 5e-9
    cyc = c.cycle(to, control, 1000)
    assert len(cyc.depth) == len(cyc.force) == len(cyc.contact_radius) == 1000
    kinds = [j.kind for j in cyc.jumps]
    assert kinds == ["jump into contact", "pull-off"]
    po = c.pull_off(control)
    assert abs(cyc.jumps[-1].before[1] / po.force - 1) < 1e-14  # a root, not the closed form
    top = cyc.depth.max() if control == "depth" else cyc.force.max()
    assert abs(top / to - 1) < 1e-14
    with mp.workdps(DPS):
        Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
        # jump into contact: d = 0 (depth) with a^3 = 2 pi dg R^2/E*, or F = 0 (force)
        a_in = (mp.cbrt(2 * mp.pi * gm * Rm**2 / Em) if control == "depth"
                else mp.cbrt(9 * mp.pi * gm * Rm**2 / (2 * Em)))
        assert_close(cyc.jumps[0].after[2], a_in, 1e-14, "radius after the jump in")

        def F(a):
            return 4 * Em * a**3 / (3 * Rm) - mp.sqrt(8 * mp.pi * gm * Em * a**3)

        def dd(a):
            return 2 * a / Rm - mp.sqrt(2 * mp.pi * gm / Em) / (2 * mp.sqrt(a))

        # the closed integral of F dd: the loop between the jump in and the pull-off
        W = -mp.quad(lambda a: F(a) * dd(a), [mp.mpf(po.contact_radius), a_in])
        assert_close(cyc.hysteresis, W, 1e-13, f"hysteresis ({control})")
        assert cyc.hysteresis_error < 1e-12 * float(W)
    # the path: loading first, increasing a on contact; F and d consistent with the curve
    inside = cyc.contact_radius > 0
    assert np.allclose(cyc.force[inside], c.force(cyc.contact_radius[inside]), rtol=0,
                       atol=1e-15 * abs(po.force))
    assert cyc.loading[0] and not cyc.loading[-1]


def test_worn_cycle():
    """A worn tip: F(a) has a corner (a local minimum) at the kink besides the JKR-like
    minimum; the cycle stays on the derived curve and ends with a pull-off."""
    c = ad.AdhesiveContact(ad.Worn(1e-6, 60e-9), 3e6, 0.04)
    cyc = c.cycle(50e-9, "force", 400)
    assert cyc.jumps[-1].kind == "pull-off"
    assert cyc.hysteresis > 0
    inside = cyc.contact_radius > 0
    assert np.allclose(cyc.force[inside], c.force(cyc.contact_radius[inside]), rtol=1e-13,
                       atol=1e-22)


def test_punch_cycle_hysteresis():
    E, a, dg = 3e6, 1e-6, 0.04
    cyc = ad.AdhesiveContact(ad.FlatPunch(a), E, dg).cycle(1e-7, "depth", 100)
    # the loop: F = 2 E* a d from d = -Delta l to 0, retraced only on the way out:
    # E* a Delta l^2 = 2 pi a^2 dgamma
    with mp.workdps(DPS):
        assert_close(cyc.hysteresis, 2 * mp.pi * mp.mpf(a) ** 2 * mp.mpf(dg), 1e-14,
                     "punch hysteresis")


@pytest.mark.parametrize("shape", [ad.Paraboloid(1e-6), ad.Cone(0.3), ad.PowerLaw(1e3, 1.5),
                                   ad.Sphere(1e-6), ad.Worn(1e-6, 1e-8)], ids=repr)
def test_zero_adhesion_is_the_non_adhesive_contact(shape):
    """Delta gamma -> 0: the curves tend to the non-adhesive ones like sqrt(dgamma), the
    pull-off to 0 like dgamma (paraboloid) or faster; dgamma = 0 is no adhesion at all."""
    E = 3e6
    a = np.geomspace(2e-8, 1e-7, 5)  # beyond the worn tip's flat b = 1e-8
    F0 = shape.force0(a, E)
    d0 = shape.g(a)
    prev, prev_Fc = None, None
    for dg in (1e-6, 1e-10, 1e-14, 0.0):
        c = ad.AdhesiveContact(shape, E, dg)
        errF = np.max(np.abs(c.force(a) - F0) / F0)
        errd = np.max(np.abs(c.depth(a) - d0) / d0)
        if dg == 0:
            assert errF < 1e-15 and errd < 1e-15
            assert c.pull_off("force").force == 0.0
            cyc = c.cycle(1e-8, "depth", 50)
            assert cyc.jumps == [] and abs(cyc.hysteresis) < 1e-12 * 1e-8 * F0.max()
        else:
            if prev is not None:  # sqrt(dgamma) convergence: 1e-4 less per 1e-4 in dgamma
                assert errF < prev * 2e-2
            prev = errF
            Fc = abs(c.pull_off("force").force)
            if prev_Fc is not None:  # like dgamma (paraboloid, sphere), dgamma^2 (cone), or
                # sqrt(dgamma) (the worn tip lets go at its kink: Kendall's punch)
                assert Fc < prev_Fc * 1e-2 * 1.001
            prev_Fc = Fc


def test_large_adhesion_and_tiny_radius():
    with mp.workdps(DPS):
        for dg in (1e3, 1e8):  # far beyond any real interface: the scaling must hold
            c = ad.AdhesiveContact(ad.Paraboloid(1e-6), 1e9, dg)
            assert_close(c.pull_off("force").force, -3 * mp.pi * mp.mpf(1e-6) * mp.mpf(dg) / 2,
                         TOL_LIT, "large dgamma")
        c = ad.AdhesiveContact(ad.Paraboloid(1e-6), 1e9, 0.05)
        for a in (1e-20, 1e-14):  # the adhesive term dominates: F ~ -sqrt(8 pi dg E* a^3)
            am = mp.mpf(a)
            ref = (4 * mp.mpf(1e9) * am**3 / (3 * mp.mpf(1e-6))
                   - mp.sqrt(8 * mp.pi * mp.mpf(0.05) * mp.mpf(1e9) * am**3))
            assert_close(c.force(a), ref, 1e-14, f"F at a = {a}")


def test_sphere_tends_to_jkr_for_small_contacts():
    """The exact cap is a paraboloid to O(a^2/R^2): its pull-off tends to -3 pi R dg/2."""
    E, dg = 1e9, 1e-3
    for R in (1e-3, 1e-1):
        po = ad.AdhesiveContact(ad.Sphere(R), E, dg).pull_off("force")
        jkr = -1.5 * np.pi * R * dg
        assert abs(po.force / jkr - 1) < 10 * (po.contact_radius / R) ** 2


def test_inputs_named():
    assert_inputs_named(ad.critical_elongation, {"a": 1e-8, "E_star": 1e6, "dgamma": 0.05})
    assert_inputs_named(ad.tabor_parameter, {"R": 1e-8, "E_star": 1e6, "dgamma": 0.05,
                                             "z0": 3e-10})
    assert_inputs_named(lambda E_star, dgamma: ad.AdhesiveContact(ad.Paraboloid(1e-8), E_star,
                                                                  dgamma),
                        {"E_star": 1e6, "dgamma": 0.05})
    with pytest.raises(ValueError, match="dgamma = -1.0"):
        ad.AdhesiveContact(ad.Paraboloid(1e-8), 1e6, -1.0)
    with pytest.raises(ValueError, match="n = 0.4"):
        ad.PowerLaw(1.0, 0.4)
    with pytest.raises(ValueError, match="control = 'speed'"):
        ad.AdhesiveContact(ad.Paraboloid(1e-8), 1e6, 0.05).pull_off("speed")
    c = ad.AdhesiveContact(ad.Paraboloid(1e-8), 1e6, 0.05)
    with pytest.raises(ValueError, match="below the pull-off force"):
        c.contact_radius(force=-1.0)
    with pytest.raises(ValueError, match="a = -1"):
        c.force(-1e-9)
    with pytest.raises(ValueError, match="a = 2e-08"):
        ad.AdhesiveContact(ad.Sphere(1e-8), 1e6, 0.05).force(2e-8)


def test_non_adhesive_helpers_agree():
    """The shapes' non-adhesive parts are the package's own closed forms (used at dgamma = 0)."""
    a, R, E = 3e-8, 1e-6, 2e6
    assert ad.Paraboloid(R).force0(a, E) == pytest.approx(float(hertz.force(a**2 / R, R, E)),
                                                          rel=1e-15)
    assert ad.Sphere(R).g(a) == pytest.approx(float(sphere.depth(a, R)), rel=1e-15)


def test_sampled_profiles_converge_to_the_closed_forms():
    """The numerical MDR with adhesion (mdr.Profile samples, every other sample for the
    error estimate) against the closed-form pull-off: the estimate bounds the true error,
    and the error falls with the sample spacing h like h^4 or faster for r^2.5 (the quintic
    spline's g' error is O(h^4); measured 22-28 per halving, docs/adhesion.md)."""
    from hertzmdr.numeric import mdr

    E, dg = 3e6, 0.04
    shape = ad.PowerLaw(1e9, 2.5)
    ref = ad.AdhesiveContact(shape, E, dg)
    errs = {c: [] for c in ad.CONTROLS}
    for N in (100, 200, 400):
        r = np.linspace(0.0, 3e-6, N + 1)
        c = ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, 1e9 * r**2.5)), E, dg)
        for control in ad.CONTROLS:
            po, pr = c.pull_off(control), ref.pull_off(control)
            err = max(abs(po.force / pr.force - 1), abs(po.contact_radius / pr.contact_radius
                                                        - 1))
            assert err <= po.rel_error, (N, control, err, po.rel_error)
            assert po.method.endswith("coarse vs fine samples)")
            errs[control].append(err)
    for control, e in errs.items():
        orders = np.log2(np.array(e[:-1]) / np.array(e[1:]))
        assert np.all(orders > 3.5), (control, e, orders)
    # the exact sphere sampled on 200 points: its pull-off to 1e-10
    R = 1e-6
    r = np.linspace(0.0, 0.9 * R, 201)
    c = ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, sphere.profile(r, R))), E, dg)
    ref = ad.AdhesiveContact(ad.Sphere(R), E, dg)
    for control in ad.CONTROLS:
        po = c.pull_off(control)
        assert abs(po.force / ref.pull_off(control).force - 1) <= po.rel_error < 1e-9


def test_near_the_vertical_tangent():
    """Under depth control the pull-off is where dd/da = 0: F(d) has a vertical tangent and
    a(d) a square-root branch point. Just above it, the stable root of d(a) = d is found to
    the sqrt(eps) that a minimum allows (rounding of d(a), ~1e-16 |d|, moves a root next to
    a minimum by sqrt(2e-16 |d| / d'')), and the stiffness dF/dd tends to -infinity."""
    E, R, dg = 2e6 / 0.75, 20e-9, 0.05
    c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
    po = c.pull_off("depth")
    with mp.workdps(DPS):
        Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
        a_dc = mp.mpf(po.contact_radius)
        for rel in (1e-2, 1e-6, 1e-10):
            d = po.depth * (1 - rel)  # d_dc < 0: slightly above it

            def depth(a, d=d):
                return a**2 / Rm - mp.sqrt(2 * mp.pi * a * gm / Em) - mp.mpf(d)

            a_ref = mp.findroot(depth, (a_dc * (1 + mp.mpf(10) ** -20), 2 * a_dc),
                                solver="anderson")
            assert_close(c.contact_radius(depth=d), a_ref, 2e-7, f"a(d) at {rel}")
            a = float(a_ref)
            k = (gen.adhesion_force_slope(E, a, dg, 2 * a / R)
                 / gen.adhesion_depth_slope(E, a, dg, 2 * a / R))
            assert k < 0 and abs(k) > 1e-3 * E * R / np.sqrt(rel)  # like -1/sqrt(d - d_dc)


@pytest.mark.parametrize("E, R, dg", CASES)
def test_state_stiffness_mean_pressure_at_a_depth(E, R, dg):
    """The scene layer's numbers at a depth, from numeric/'s API alone: the JKR state
    (a(d) by mpmath's root of the literature's d(a) = a^2/R - sqrt(2 pi a dgamma/E*), F(a)),
    its stiffness dF/dd by mpmath's numerical derivative of F(d) along that root, and
    F/(pi a^2); Kendall's punch: F = 2 E* a d at any depth above its pull-off, dF/dd = 2 E* a,
    the pressure E* d/(pi sqrt(a^2 - r^2)) and the surface displacement (2 d/pi) asin(a/r)."""
    c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
    d_c = c.pull_off("depth").depth
    d = np.array([0.5 * d_c, 0.0, -2 * d_c, 30 * abs(d_c)])  # d_c < 0 for the paraboloid
    a, dd, F = c.equilibrium(depth=d)
    k, pm = c.stiffness(depth=d), c.mean_pressure(depth=d)
    with mp.workdps(DPS):
        Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
        def a_of(dv):  # the stable root, started from the float one (the secant refines it)
            return mp.findroot(lambda x: x**2 / Rm - mp.sqrt(2 * mp.pi * x * gm / Em) - dv,
                               mp.mpf(float(c.contact_radius(depth=float(dv)))))
        def F_of(dv):
            x = a_of(dv)
            return 4 * Em * x**3 / (3 * Rm) - mp.sqrt(8 * mp.pi * gm * Em * x**3)
        for i, dv in enumerate(d):
            dv = mp.mpf(dv)
            x = a_of(dv)
            assert_close(a[i], x, TOL_LIT, "JKR a(d)")
            assert_close(F[i], F_of(dv), 1e-12, "JKR F(d)")  # F ~ 0 near zero load: cancels
            assert_close(k[i], mp.diff(F_of, dv), TOL_LIT, "JKR dF/dd")
            assert_close(pm[i], F_of(dv) / (mp.pi * x**2), 1e-12, "JKR F/(pi a^2)")
    b = 1e-6
    p = ad.AdhesiveContact(ad.FlatPunch(b), E, dg)
    d_c = p.pull_off("depth").depth
    d = np.array([0.999 * d_c, 0.0, 1e-7])
    a, dd, F = p.equilibrium(depth=d)
    assert list(a) == [b] * 3 and list(dd) == list(d)
    a2, d2, F2 = p.equilibrium(force=F[[0, 2]])
    r = np.array([0.0, 0.3 * b, 0.9 * b, 2 * b])
    with mp.workdps(DPS):
        Em, bm = mp.mpf(E), mp.mpf(b)
        for i, dv in enumerate(d):
            assert_close(F[i], 2 * Em * bm * mp.mpf(dv), TOL_LIT, "Kendall F(d)")
        for kv in p.stiffness(depth=d):
            assert_close(kv, 2 * Em * bm, TOL_LIT, "punch dF/dd")
        for i in (0, 1):
            assert_close(d2[i], mp.mpf(F2[i]) / (2 * Em * bm), TOL_LIT, "Kendall d(F)")
        dv = mp.mpf(d[0])
        pr = p.pressure_at_depth(r, d[0])
        u = p.surface_displacement_at_depth(r, d[0])
        for i, rv in enumerate(r[:3]):
            assert_close(pr[i], Em * dv / (mp.pi * mp.sqrt(bm**2 - mp.mpf(rv) ** 2)), TOL_LIT,
                         "punch p(r) at a depth")
            assert u[i] == d[0]
        assert pr[3] == 0
        assert_close(u[3], 2 * dv / mp.pi * mp.asin(bm / mp.mpf(r[3])), TOL_LIT,
                     "punch u(r) outside")
    with pytest.raises(ValueError, match="below the pull-off depth"):
        p.equilibrium(depth=1.001 * d_c)


def test_sampled_cycle_shares_the_profile_integrals_along_each_branch():
    """A sampled r^2.5 tip's cycle takes d and F along each branch from Chebyshev
    interpolation of g, g' and G (adhesion.AdhesiveContact._branch): every point against the
    quadrature at its own radius to 1e-11 of the curve's largest value (the interpolation is
    accepted at 1e-12 of each function's); its hysteresis against the closed-form power law's
    within the sampled profile's own resolution (1e-7: 1000 samples, order > 4, docs/
    adhesion.md)."""
    from hertzmdr.numeric import mdr

    E, dg, R = 2e6 / 0.75, 0.05, 20e-9
    c_n = 0.5 * R**-1.5
    r = np.linspace(0.0, 10 * R, 1001)
    sam = ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, c_n * r**2.5)), E, dg)
    cyc = sam.cycle(10e-9, "depth", 400)
    m = cyc.contact_radius > 0
    d_ref, F_ref = sam.depth(cyc.contact_radius[m]), sam.force(cyc.contact_radius[m])
    assert np.max(np.abs(cyc.depth[m] - d_ref)) <= 1e-11 * np.max(np.abs(d_ref))
    assert np.max(np.abs(cyc.force[m] - F_ref)) <= 1e-11 * np.max(np.abs(F_ref))
    closed = ad.AdhesiveContact(ad.PowerLaw(c_n, 2.5), E, dg).cycle(10e-9, "depth", 400)
    assert abs(cyc.hysteresis / closed.hysteresis - 1) < 1e-7
    # promise 2: the estimate bounds the difference from the closed form (measured 2.1e-12;
    # the quadrature's 40-vs-80-node part alone is 7e-15, the coarse samples' cycle 2e-11)
    assert (abs(cyc.hysteresis / closed.hysteresis - 1)
            <= (cyc.hysteresis_error + closed.hysteresis_error) / cyc.hysteresis < 1e-9)


@pytest.mark.parametrize("name", ["cone", "paraboloid"])
def test_sampled_cone_and_paraboloid_pull_off(name):
    """The numerical MDR with adhesion of a sampled cone (conical tip: g' jumps at the apex)
    and a sampled paraboloid (200 samples on [0, 10 a_c], which a quintic spline reproduces)
    against their closed-form pull-offs under both controls: within the estimate, and to
    1e-12 (the spline is exact; the quadrature and the roots are not)."""
    from hertzmdr.numeric import mdr

    E, dg, th = 3e6, 0.04, np.radians(20)
    shape, f = ((ad.Cone(th), lambda r: r * np.tan(th)) if name == "cone" else
                (ad.Paraboloid(1e-6), lambda r: r**2 / 2e-6))
    ref = ad.AdhesiveContact(shape, E, dg)
    r = np.linspace(0.0, 10 * ref.pull_off("force").contact_radius, 201)
    c = ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, f(r))), E, dg)
    for control in ad.CONTROLS:
        po, pr = c.pull_off(control), ref.pull_off(control)
        err = abs(po.force / pr.force - 1)
        assert err <= po.rel_error and err < 1e-12, (control, err, po.rel_error)


# the 3-D fields of the shapes other than the paraboloid, each by its own route: the profile
# typed here, the force as the integral of the pressure, the far field of a point force
_FIELD_SHAPES = {
    "cone": (ad.Cone(0.3), lambda r: r * math.tan(0.3)),
    "power law": (ad.PowerLaw(1.0, 1.5), lambda r: r**1.5),
    "sphere": (ad.Sphere(1e-3), lambda r: 1e-3 - math.sqrt((1e-3 - r) * (1e-3 + r))),
    "worn": (ad.Worn(1e-3, 2e-5), lambda r: max(r * r - 4e-10, 0.0) / 2e-3),
}


@pytest.mark.parametrize("name", list(_FIELD_SHAPES))
def test_pressure_and_displacement_of_each_shape_by_their_own_routes(name):
    """E* = 1 GPa, dgamma = 0.05 J/m^2, a = 50 um (compressed well past the pull-off):
    F(a) = 2 pi int_0^a p r dr by tanh-sinh in phi, r = a sin(phi) (the edge's
    1/sqrt(a^2 - r^2) and the cone's log at the axis are endpoint singularities; the worn tip's
    kink at r = b a break point, panels graded toward the axis; where a node rounds onto the
    kink's log singularity, the float below it); inside, u = d - f(r) with f typed here
    (5.54); outside, continuity at the edge (the edge term goes as sqrt(r - a): 1e-6 at
    1e-12 a) and the far field of the point force F/(pi E* r) at r = 1e4 a ((5.60): O((a/r)^2)
    = 1e-8 from it).
    The force is checked without adhesion (the shape's own pressure0 and force0): the edge
    term -E* Delta l/(pi sqrt(a^2 - r^2)) at a float r cannot be integrated to the last
    1.5e-8 of phi below pi/2, where a sin(phi) rounds to a (it costs 8e-9 of that term; the
    JKR tests check it). Tolerances: the quadrature of a float64 integrand, 1e-11 of the
    force's scale (the cone: 2e-16); u inside a few roundings of d and f, 1e-13 of d."""
    shape, f = _FIELD_SHAPES[name]
    E, dg, a = 1e9, 0.05, 5e-5
    c0 = ad.AdhesiveContact(shape, E, 0.0)
    F0, d0 = float(c0.force(a)), float(c0.depth(a))
    below = np.nextafter(a, 0.0)

    def integrand(phi):
        r = min(a * float(mp.sin(phi)), below)
        p = float(c0.pressure(r, a))
        if math.isinf(p):  # r rounded onto the worn tip's kink r = b
            r = float(np.nextafter(r, 0.0))
            p = float(c0.pressure(r, a))
        return p * r * a * float(mp.cos(phi))

    with mp.workdps(20):
        # panels graded toward the axis (the cone's log), the worn tip's kink a break point
        cuts = sorted({mp.mpf(0), mp.mpf("1e-6"), mp.mpf("1e-3"), mp.mpf("0.1"), mp.pi / 2}
                      | ({mp.asin(2e-5 / a)} if name == "worn" else set()))
        F_ref = 2 * mp.pi * mp.quad(integrand, cuts, maxdegree=10)
    assert abs(F0 - float(F_ref)) <= 1e-11 * F0, (name, F0, F_ref)
    c = ad.AdhesiveContact(shape, E, dg)
    F, d = float(c.force(a)), float(c.depth(a))
    assert d < d0 and F < F0, name  # adhesion pulls
    r_in = np.array([0.0, 0.3 * a, 0.9 * a, a])
    u_in = c.surface_displacement(r_in, a)
    for r, u in zip(r_in, u_in, strict=True):
        assert abs(u - (d - f(r))) <= 1e-13 * abs(d), (name, r, u, d - f(r))
    u_edge = float(c.surface_displacement(a * (1 + 1e-12), a))
    assert abs(u_edge - (d - f(a))) <= 1e-5 * abs(d), (name, u_edge, d - f(a))
    r_far = 1e4 * a
    u_far = float(c.surface_displacement(r_far, a))
    assert abs(u_far / (F / (math.pi * E * r_far)) - 1) <= 1e-7, (name, u_far)


@pytest.mark.parametrize("control", ["depth", "force"])
def test_punch_cycle_path(control):
    """The flat punch's cycle point by point: out of contact F = 0 and a = 0; in contact F is
    Boussinesq's 2 E* a d with the punch's radius (typed here); the retract goes down to
    Kendall's pull-off F_c = -(8 pi E* dgamma a^3)^(1/2) at d_c = F_c/(2 E* a), then jumps to
    F = 0 there; the top is ``to`` (a depth, or a force over 2 E* a); the default start lies a
    fifth of the depth range below d_c. Each value is a few roundings: 1e-14."""
    E, a, dg, pts = 3e6, 1e-6, 0.04, 101
    k = 2 * E * a
    F_c = -math.sqrt(8 * math.pi * E * dg * a**3)
    d_c, d_top = F_c / k, 1e-7
    to = d_top if control == "depth" else k * d_top
    c = ad.AdhesiveContact(ad.FlatPunch(a), E, dg)
    # the pull-off depth itself is a valid start (its own float: d_c here may differ by an ulp)
    own_d_c = c.cycle(to, control, pts).jumps[0].before[0]
    for start in (None, -3e-7, own_d_c):
        cyc = c.cycle(to, control, pts, start=start)
        d, F, aa = cyc.depth, cyc.force, cyc.contact_radius
        assert len(d) == len(F) == len(aa) == len(cyc.loading) == pts
        s = d_c - 0.2 * (d_top - d_c) if start is None else start
        assert d[0] == pytest.approx(s, rel=1e-14, abs=0) and d[-1] == d[0], start
        assert d.max() == pytest.approx(d_top, rel=1e-14), start
        touching = aa > 0
        assert np.all(aa[touching] == a) and np.all(F[~touching] == 0.0), start
        np.testing.assert_allclose(F[touching], k * d[touching], rtol=1e-14, atol=0)
        assert np.all(d[~touching] <= 0) and touching.sum() >= pts // 2 - 2, start
        assert F.min() == pytest.approx(F_c, rel=1e-14), start
        # the approach and push first, then the retract
        assert cyc.loading[:pts // 2 - 1].all() and not cyc.loading[pts // 2 + 1:].any()
        [jump] = cyc.jumps
        assert jump.kind == "pull-off" and jump.after[1:] == (0.0, 0.0), start
        assert jump.before == pytest.approx((d_c, F_c, a), rel=1e-14), start
    with pytest.raises(ValueError, match=r"^start = .* m is in contact; valid: start <= "):
        c.cycle(to, control, pts, start=d_c / 2)
    with pytest.raises(ValueError, match=r"^start = nan"):
        c.cycle(to, control, pts, start=float("nan"))


def test_punch_cycle_work_is_kendalls():
    """The work over a flat punch's approach-push-retract cycle (adhesion_punch_cycle_work,
    and Cycle.work of AdhesiveContact.cycle) against Kendall's pull-off typed here at 30
    digits: the retract branch F = k d, k = 2 E* a, ends at F_c = -sqrt(8 pi a^3 E* Delta
    gamma) and jumps to 0, so W = F_c^2/(2 k): a few ulp."""
    for E, R, dg in CASES:
        with mp.workdps(DPS):
            Fc2 = 8 * mp.pi * mp.mpf(R) ** 3 * E * dg
            ref = Fc2 / (2 * 2 * E * mp.mpf(R))
        assert_close(gen.adhesion_punch_cycle_work(E, R, dg), ref, 8e-16, f"E {E} a {R}")
        cyc = ad.AdhesiveContact(ad.FlatPunch(R), E, dg).cycle(to=1e-9, control="depth")
        assert_close(cyc.hysteresis, ref, 8e-16, f"cycle E {E} a {R}")
        # its error bound: a few roundings of a closed form, above the error and ~1e-15
        err = abs(float((mp.mpf(cyc.hysteresis) - ref) / ref)) * cyc.hysteresis
        assert err <= cyc.hysteresis_error <= 1e-14 * cyc.hysteresis
        assert cyc.control == "depth"
    cyc = ad.AdhesiveContact(ad.FlatPunch(1e-6), 3e6, 0.0).cycle(to=1e-9, control="force")
    assert cyc.jumps == [] and cyc.hysteresis == 0 and cyc.control == "force"


def test_zero_load_radius_of_each_shape():
    """The zero-load radius (AdhesiveContact.zero_load_contact_radius) of the cone and the
    power law (closed forms) and of the exact sphere and the worn tip (Brent's root of F(a)
    above the pull-off radius) against the root of the derived F(a) printed for mpmath,
    bracketed from the pull-off radius (Anderson's method, 30 digits): the closed forms
    a few roundings, the float root a simple one of a smooth F, 1e-14 both; with dgamma = 0
    there is no contact at zero load, closed form or not."""
    for shape in (ad.Cone(np.radians(20)), ad.Cone(1.2), ad.PowerLaw(2.5e7, 2.0),
                  ad.PowerLaw(3e3, 1.5), ad.PowerLaw(50.0, 0.8), ad.Sphere(20e-9),
                  ad.Sphere(1e-6), ad.Worn(1e-6, 5e-9)):
        E, dg, _, F_fn = _mp_curves(shape)
        c = ad.AdhesiveContact(shape, float(E), float(dg))
        with mp.workdps(DPS):
            lo = mp.mpf(c.pull_off("force").contact_radius)  # F < 0 there
            lim = mp.mpf(shape.a_limit) if np.isfinite(shape.a_limit) else mp.inf
            hi = min(1.5 * lo, (lo + lim) / 2)  # the cap: a < R
            while F_fn(hi) < 0:
                hi = min(2 * hi, (hi + lim) / 2)
            a0 = mp.findroot(F_fn, (lo, hi), solver="anderson")
            assert_close(c.zero_load_contact_radius(), a0, 1e-14, f"{shape} a_0")
    for shape in (ad.Cone(0.3), ad.Sphere(1e-6)):
        assert ad.AdhesiveContact(shape, 3e6, 0.0).zero_load_contact_radius() == 0.0
    # without a closed form at dgamma = 1 J/m^2: a root of F (checked against mpmath above),
    # on the stable branch
    c = ad.AdhesiveContact(ad.Sphere(1e-6), 3e6, 1.0)
    a0, po = c.zero_load_contact_radius(), c.pull_off("force")
    assert a0 > po.contact_radius and abs(float(c.force(a0))) <= 1e-12 * abs(po.force)
    # where a closed form is derived it is the answer, not a root near it
    for shape in (ad.Cone(0.3), ad.PowerLaw(3e3, 1.5), ad.Paraboloid(1e-6)):
        assert ad.AdhesiveContact(shape, 3e6, 0.04).zero_load_contact_radius() == \
            shape.closed_zero_load(3e6, 0.04)


def test_worn_tip_inputs_named_and_taken_as_floats():
    """The worn tip's R and b: a bad one named with its value, and both kept as floats."""
    with pytest.raises(ValueError, match=r"^R = -1e-06"):
        ad.Worn(-1e-6, 1e-8)
    with pytest.raises(ValueError, match=r"^b = -1e-08"):
        ad.Worn(1e-6, -1e-8)
    w = ad.Worn(np.float32(1e-6), np.float32(1e-8))
    assert type(w.R) is float and w.R == float(np.float32(1e-6))
    assert type(w.b) is float and w.b == float(np.float32(1e-8)) and w.kinks == (w.b,)


def test_state_helpers_of_the_paraboloid():
    """critical_elongation, force_at_depth and the non-adhesive pressure of the paraboloid
    against the literature typed here at 30 digits: Delta l = sqrt(2 pi a dgamma/E*), the
    JKR force at the stable root of d = a^2/R - Delta l(a) (secant method from the float
    root), Hertz's p = 2 E*/(pi R) sqrt(a^2 - r^2) (Johnson (4.20) with p0 = 2 a E*/(pi R));
    a few roundings each (1e-14; the force at a depth 1e-12, it cancels near zero load)."""
    E, R, dg = 2e6 / 0.75, 20e-9, 0.05
    c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
    a = np.array([1e-9, 7e-9, 3e-8])
    d = np.array([0.0, 2e-9, 1e-8])
    dl, F, p = c.critical_elongation(a), c.force_at_depth(d), c.shape.pressure0(
        np.array([0.0, 0.5 * a[1], 0.99 * a[1]]), a[1], E)
    with mp.workdps(DPS):
        Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
        for i, x in enumerate(a):
            assert_close(dl[i], mp.sqrt(2 * mp.pi * mp.mpf(x) * gm / Em), 1e-14, "Delta l")
        for i, dv in enumerate(d):
            dm = mp.mpf(dv)
            x = mp.findroot(lambda s, dm=dm: s**2 / Rm - mp.sqrt(2 * mp.pi * s * gm / Em) - dm,
                            mp.mpf(float(c.contact_radius(depth=float(dv)))))
            F_ref = 4 * Em * x**3 / (3 * Rm) - mp.sqrt(8 * mp.pi * gm * Em * x**3)
            assert_close(F[i], F_ref, 1e-12, f"F at d = {dv}")
        a1 = mp.mpf(a[1])
        for i, t in enumerate((0.0, 0.5, 0.99)):
            rr = mp.mpf(float(t * a[1]))
            assert_close(p[i], 2 * Em / (mp.pi * Rm) * mp.sqrt(a1**2 - rr**2), 1e-14,
                         f"p0 at r = {t} a")


def test_radius_of_curvature_of_each_shape():
    """The tip's radius of curvature the Tabor parameter takes: R of the paraboloid, the cap
    and the worn tip, 1/(2 c_2) of the power law with n = 2 (c_2 r^2 = r^2/(2R)), none for
    other exponents, the cone or the punch; and the contact's text names its parts."""
    assert ad.Paraboloid(2e-6).radius_of_curvature == 2e-6
    assert ad.Sphere(3e-6).radius_of_curvature == 3e-6
    assert ad.Worn(4e-6, 1e-8).radius_of_curvature == 4e-6
    assert ad.PowerLaw(2.5e5, 2.0).radius_of_curvature == 1 / 5e5
    assert ad.PowerLaw(2.5e5, 2.5).radius_of_curvature is None
    assert ad.Cone(0.3).radius_of_curvature is None
    assert ad.FlatPunch(1e-6).radius_of_curvature is None
    assert repr(ad.AdhesiveContact(ad.Paraboloid(1e-6), 2e6, 0.05)) == \
        "AdhesiveContact(Paraboloid(R=1e-06), E_star=2000000.0, dgamma=0.05)"


def test_sampled_paraboloid_and_cone_fields():
    """The non-adhesive fields of a sampled paraboloid (201 samples of h0 + r^2/(2R) on
    [0, 3a], which the quintic spline reproduces; h0 = 1 nm, which no field may see) against
    Hertz's typed here: the height f(r) - f(0) = r^2/(2R), the pressure
    2 E*/(pi R) sqrt(a^2 - r^2) and the displacement outside
    ((2 a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2))/(pi R) (Johnson (3.42b) with d = a^2/R);
    of a sampled cone (r tan(theta)) the pressure E* tan(theta)/2 acosh(a/r) (the cone of
    Love 1939 and Sneddon 1948), +inf at the apex. Inputs of any shape give results of that shape.
    Tolerances: the spline exact to rounding (1e-13 of the largest height); the Abel integral
    of g' and the quadrature of g on the 201 samples 1e-12 (measured 2.6e-14 and 1.5e-14),
    on the coarse representation (every other sample: the companion of the error estimate)
    1e-9 (measured 3.6e-10 and 9.2e-11), and it differs from the fine one (else the estimate
    would be 0); the text names the source and only the coarse one says so."""
    from hertzmdr.numeric import mdr

    E, R, a, h0, th = 3e6, 1e-6, 1e-7, 1e-9, np.radians(20)
    r = np.linspace(0.0, 3 * a, 201)
    rin = np.array([[0.0], [0.4 * a], [0.9 * a]])
    rout = np.array([[1.0001 * a, 1.5 * a, 2.5 * a]])
    got = {}
    for coarse in (False, True):
        tol = 1e-9 if coarse else 1e-12
        s = ad.Sampled(mdr.Profile.from_samples(r, h0 + r**2 / (2 * R)), coarse=coarse)
        x = np.array([[0.0, 0.37 * a], [a, 2.9 * a]])
        h = s.height(x)
        assert h.shape == (2, 2)
        assert np.all(np.abs(h - x**2 / (2 * R)) <= 1e-13 * (3 * a) ** 2 / (2 * R)), h
        p = got[coarse] = s.pressure0(rin, a, E)
        u = s.displacement0_outside(rout, a)
        assert p.shape == (3, 1) and u.shape == (1, 3)
        cone = ad.Sampled(mdr.Profile.from_samples(r, r * np.tan(th)), coarse=coarse)
        pc = cone.pressure0(np.array([0.0, 0.2 * a, 0.7 * a]), a, E)
        assert pc[0] == np.inf
        with mp.workdps(DPS):
            am, Rm, Em = mp.mpf(a), mp.mpf(R), mp.mpf(E)
            for i, rv in enumerate(rin.ravel()):
                ref = 2 * Em / (mp.pi * Rm) * mp.sqrt(am**2 - mp.mpf(rv) ** 2)
                assert_close(p[i, 0], ref, tol, f"sampled p0 at {rv / a} a ({coarse})")
            for i, rv in enumerate(rout.ravel()):
                rm = mp.mpf(rv)
                ref = ((2 * am**2 - rm**2) * mp.asin(am / rm) + am * mp.sqrt(rm**2 - am**2)) \
                    / (mp.pi * Rm)
                assert_close(u[0, i], ref, tol, f"sampled u at {rv / a} a ({coarse})")
            for t, v in zip((0.2, 0.7), pc[1:], strict=True):
                ref = Em * mp.tan(mp.mpf(th)) / 2 * mp.acosh(1 / mp.mpf(t))
                assert_close(v, ref, tol, f"sampled cone p0 at {t} a ({coarse})")
        assert cone.pressure0(np.array([0.0]), a, E)[0] == np.inf  # the apex alone too
        text = repr(s)
        assert " at 0x" not in text and text == (
            f"Sampled({s.profile.source!r}, r_max={3 * a!r}"
            + (", coarse=True)" if coarse else ")"))
    assert np.all(np.abs(got[True] / got[False] - 1) > 1e-13)


def test_worn_tip_within_its_flat_has_no_depth():
    """A worn tip whose contact radius is within its flat (a <= b) has g(a) = 0 (5.52): no
    depth, so no non-adhesive pressure and no displacement outside, as float zeros of r's
    shape (r given as integers too); just past the flat both are positive."""
    w = ad.Worn(1e-6, 2e-8)
    for a in (1e-8, 2e-8):
        for r in ([0, 0], [0.0, 0.5e-8]):
            p = w.pressure0(r, a, 3e6)
            assert p.dtype == np.float64 and p.shape == (2,) and np.all(p == 0), (a, r)
        for r in ([1, 2], [3e-8, 1e-7]):
            u = w.displacement0_outside(r, a)
            assert u.dtype == np.float64 and u.shape == (2,) and np.all(u == 0), (a, r)
    a = 2.2e-8
    assert np.all(w.pressure0([0.0, 1e-8], a, 3e6) > 0)
    assert np.all(w.displacement0_outside([3e-8, 1e-7], a) > 0)


# --- triadh: survivors of adhesion.py's mutation run of 2026-11-27 17:22 UTC -------------


def test_shape_inputs_named_and_taken_as_floats():
    """Cone's theta, PowerLaw's c_n and n, FlatPunch's radius: a bad one named with its value
    and the valid range (theta < pi/2, not 2 pi), and each kept as a Python float under its
    own name."""
    for make, msg in ((lambda: ad.Cone(2.0), r"^theta = 2\.0 .*0 < theta < 1\.5707963267948966$"),
                      (lambda: ad.Cone(-1.0), r"^theta = -1\.0 "),
                      (lambda: ad.PowerLaw(-1.0, 2.0), r"^c_n = -1\.0 .*c_n > 0"),
                      (lambda: ad.PowerLaw(1.0, 0.3), r"^n = 0\.3 .*0\.5 < n"),
                      (lambda: ad.FlatPunch(-1e-6), r"^radius = -1e-06 .*radius > 0")):
        with pytest.raises(ValueError, match=msg):
            make()
    f32 = np.float32
    c = ad.Cone(f32(0.3))
    assert type(c.theta) is float and c.theta == float(f32(0.3))
    p = ad.PowerLaw(f32(2.5), f32(1.5))
    assert type(p.c_n) is float and p.c_n == float(f32(2.5))
    assert type(p.n) is float and p.n == 1.5
    k = ad.FlatPunch(f32(1e-6))
    assert type(k.radius) is float and k.radius == float(f32(1e-6))


def test_cone_g_slope_has_the_shape_of_a():
    """The cone's g'(a) = (pi/2) tan(theta) (from (5.38)) is the same at every a, returned with
    a's shape, in float64 (typed here at 30 digits: a few roundings, 1e-15)."""
    th = 0.3
    with mp.workdps(DPS):
        ref = mp.pi / 2 * mp.tan(mp.mpf(th))
    for a in (np.array([[1e-9, 2e-9, 5e-8]]), np.array([[1, 2, 3]], np.float32)):
        s = ad.Cone(th).g_slope(a)  # float64 for a in float32 too (not rounded to 1e-7)
        assert s.shape == (1, 3) and s.dtype == np.float64
        for v in s.ravel():
            assert_close(v, ref, 1e-15, "cone g'")


def test_flat_punch_height_is_float64_zeros_of_r_shape():
    """The punch's face f(r) = 0 [m]: float64 zeros of r's shape, for r in integers, bools or
    float32 too (a float32 r is not kept as float32)."""
    k = ad.FlatPunch(1e-6)
    for r in ([1, 2], [True, False], np.array([1e-7, 2e-7], np.float32)):
        h = k.height(r)
        assert h.dtype == np.float64 and h.shape == (2,) and np.all(h == 0), r


def test_worn_tip_g_and_slope_within_its_flat_and_at_a_large_flat():
    """Within the flat (a <= b, a = b included) the worn tip has g = g' = F0 = 0: the slope's
    infinite value belongs to a = b+ only. A flat wider than sqrt(2) m (b = 2 m, R = 10 m)
    gives no warning (the placeholder radius of the entries a <= b stays above b); above the
    flat g, g' and F0 against (5.52) worked by hand, g = a sqrt(a^2 - b^2)/R (f' = r/R beyond b),
    at 30 digits: g' by mpmath's numerical derivative, F0 = 2 E* int_0^a (g(a) - g(x)) dx
    (5.57) by mpmath's quadrature (a few roundings of the float forms: 1e-13)."""
    for R, b in ((1e-6, 2e-8), (10.0, 2.0)):
        w = ad.Worn(R, b)
        a = np.array([0.5 * b, b, 1.5 * b])
        g, s, F = w.g(a), w.g_slope(a), w.force0(a, 3e6)
        assert np.all(g[:2] == 0) and np.all(s[:2] == 0) and np.all(F[:2] == 0), (R, b)
        with mp.workdps(DPS):
            Rm, bm, am, Em = mp.mpf(R), mp.mpf(b), mp.mpf(float(a[2])), mp.mpf(3e6)

            def gm(x, Rm=Rm, bm=bm):
                return x * mp.sqrt(x**2 - bm**2) / Rm if x > bm else mp.mpf(0)

            assert_close(g[2], gm(am), 1e-13, "worn g")
            assert_close(s[2], mp.diff(gm, am), 1e-13, "worn g'")
            assert_close(F[2], 2 * Em * (am * gm(am) - mp.quad(gm, [bm, am])), 1e-13, "worn F0")


def test_flat_punch_curve_against_kendall_and_its_radius_checked():
    """The punch's equilibrium: it lets go at d = -Delta l(a) = -sqrt(2 pi a dgamma/E*) with
    F = -sqrt(8 pi a^3 E* dgamma) (Kendall 1971), typed here at 30 digits (a few roundings:
    1e-14), for a in [0, radius], both ends included; a outside, NaN or not a number is named.
    The sphere's a is in [0, R): a = 0 gives d = F = 0, a = R is refused."""
    E, dg, rad = 3e6, 0.05, 1e-6
    c = ad.AdhesiveContact(ad.FlatPunch(rad), E, dg)
    a = np.array([0.25e-6, 0.5e-6, 1e-6])
    d, F = c.depth(a), c.force(a)
    with mp.workdps(DPS):
        Em, gm = mp.mpf(E), mp.mpf(dg)
        for i, x in enumerate(a):
            am = mp.mpf(float(x))
            assert_close(d[i], -mp.sqrt(2 * mp.pi * am * gm / Em), 1e-14, "punch d")
            assert_close(F[i], -mp.sqrt(8 * mp.pi * am**3 * Em * gm), 1e-14, "punch F")
    assert c.depth(0.0) == 0 and c.force(0.0) == 0
    assert c.depth(rad) == d[2] and c.force(rad) == F[2]
    for bad, msg in ((-1e-9, r"^a = -1e-09 is out of range; valid: 0 <= a <= 1e-06$"),
                     (2e-6, r"^a = 2e-06 is out of range; valid: 0 <= a <= 1e-06$"),
                     (float("nan"), r"^a = nan .*not NaN"), ("x", r"^a = 'x' is not a number")):
        for fn in (c.depth, c.force):
            with pytest.raises(ValueError, match=msg):
                fn(bad)
    s = ad.AdhesiveContact(ad.Sphere(1e-6), E, dg)
    assert s.depth(0.0) == 0 and s.force(0.0) == 0
    with pytest.raises(ValueError, match=r"^a = 1e-06 is out of range; valid: 0 <= a < 1e-06$"):
        s.depth(1e-6)


def test_pull_off_without_adhesion_and_the_punch_from_a_given_radius():
    """Delta gamma = 0: no pull-off, every figure exactly 0 and the method says so. A closed
    form (paraboloid; the punch, from any a_from too) reports 8 eps and "closed form"; the
    punch's figures are Kendall's typed at 30 digits (1e-14), its radius exactly."""
    eps = np.finfo(float).eps
    p = ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.0).pull_off()
    assert (p.force, p.depth, p.contact_radius, p.rel_error, p.method) == (
        0.0, 0.0, 0.0, 0.0, "no adhesion")
    q = ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.05).pull_off()
    assert q.rel_error == 8 * eps and q.method == "closed form"
    E, dg, rad = 3e6, 0.05, 1e-6
    for a_from in (None, 0.5e-6):
        k = ad.AdhesiveContact(ad.FlatPunch(rad), E, dg).pull_off(a_from=a_from)
        assert k.rel_error == 8 * eps and k.method == "closed form" and k.contact_radius == rad
        with mp.workdps(DPS):
            Em, gm, am = mp.mpf(E), mp.mpf(dg), mp.mpf(rad)
            assert_close(k.force, -mp.sqrt(8 * mp.pi * am**3 * Em * gm), 1e-14, "punch F_c")
            assert_close(k.depth, -mp.sqrt(2 * mp.pi * am * gm / Em), 1e-14, "punch d_c")



# nm and pN: lengths times 1e9, forces times 1e12, so E* [pN/nm^2] = 1e-6 E* [Pa] and
# Delta gamma [pN/nm] = 1e3 Delta gamma [J/m^2]
_NM, _PN = 1e9, 1e12


def _in_nm_pn(shape):
    if isinstance(shape, ad.Sphere):
        return ad.Sphere(shape.R * _NM)
    return ad.Worn(shape.R * _NM, shape.b * _NM)


@pytest.mark.parametrize("shape, minima", [(ad.Sphere(1e-6), 1), (ad.Worn(1e-6, 5e-9), 2)],
                         ids=repr)
def test_bracketed_pull_off_bounds_its_error_in_any_units(shape, minima):
    """Promise 2 for the bracketed pull-off (no closed form): its rel_error bounds the true
    error of F_c (the mpmath minimization of the derived F(a), d(a) at 30 digits, as in
    test_pull_off_by_mpmath_minimization), is at least its 8 eps floor, and is a relative
    figure: the same contact in nm and pN (E* 1e-6, Delta gamma 1e3, R 1e9 times the SI
    numbers) reports the force times 1e12 within it, with a bound below 1e-13 too (the
    spread of F over the final bracket of 4 eps is a few ulp of F, measured 9-15 eps). The
    method names the bracketed slope and the number of minima (the worn tip: the corner at
    the kink and the JKR-like one)."""
    E, dg, d_fn, F_fn = _mp_curves(shape)
    eps = np.finfo(float).eps
    c = ad.AdhesiveContact(shape, float(E), float(dg))
    c_nm = ad.AdhesiveContact(_in_nm_pn(shape), float(E) / 1e6, float(dg) * 1e3)
    with mp.workdps(DPS):
        for control, fn in (("force", F_fn), ("depth", d_fn)):
            po, po_nm = c.pull_off(control), c_nm.pull_off(control)
            F_ref = F_fn(_mp_min(fn, mp.mpf(po.contact_radius)))
            which = "dF/da" if control == "force" else "dd/da"
            assert po.method == f"bracketed root of {which} ({minima} minima)"
            for p, scale in ((po, 1.0), (po_nm, _PN)):
                err = abs(p.force / (scale * F_ref) - 1)
                assert err <= p.rel_error, (control, scale, err, p.rel_error)
                assert 8 * eps <= p.rel_error < 1e-13, (control, scale, p.rel_error)


def test_worn_tip_lets_go_at_its_kink_under_depth_control():
    """A worn tip whose flat (b = 120 nm) is near the JKR pull-off radius: under depth
    control d(a) has two minima, the corner at a = b (d = -Delta l(b), Kendall's punch,
    typed at 30 digits: a few roundings, 1e-14) and a smooth one at a ~ 166 nm that is
    higher in d but lower in F; the pull-off is the lowest d, at the kink, with F(b) =
    -sqrt(8 pi b^3 E* dgamma) bounded by its rel_error. From a_from between the two minima
    only the kink is seen; from a_from below b there is no minimum, named in one line."""
    E, dg, R, b = 3e6, 0.04, 1e-6, 1.2e-7
    c = ad.AdhesiveContact(ad.Worn(R, b), E, dg)
    po = c.pull_off("depth")
    assert po.contact_radius == b and po.method == "bracketed root of dd/da (2 minima)"
    with mp.workdps(DPS):
        Em, gm, bm = mp.mpf(E), mp.mpf(dg), mp.mpf(b)
        assert_close(po.depth, -mp.sqrt(2 * mp.pi * bm * gm / Em), 1e-14, "worn d_c at b")
        F_ref = -mp.sqrt(8 * mp.pi * bm**3 * Em * gm)
        assert abs(po.force / F_ref - 1) <= po.rel_error < 1e-7
        _, _, d_fn, _ = _mp_curves(ad.Worn(R, b))
        other = [a for a, k in c._extrema("depth", c._far(), closed=False) if k == "min"][1]
        assert d_fn(_mp_min(d_fn, mp.mpf(other))) > po.depth + 1e-9  # higher in d
        assert c.force(other) < po.force  # but lower in F
    part = c.pull_off("depth", a_from=1.4e-7)
    assert part.contact_radius == b and part.method == "bracketed root of dd/da (1 minima)"
    assert c.pull_off("depth") == po  # a pull-off from a given a_from is not kept as the default
    with pytest.raises(ValueError, match=r"^no pull-off under depth control below "
                                         r"a = 1e-07 m$"):
        c.pull_off("depth", a_from=1e-7)


@pytest.mark.parametrize("name", ["sphere", "cone"])
def test_sampled_pull_off_bounds_force_and_radius(name):
    """The numerical MDR's pull-off (a sampled exact sphere on 101 points, a sampled cone on
    61: g' jumps at its apex) against the closed-form shapes' pull-off (8 eps): its rel_error
    bounds the error of the force and of the contact radius (the radius moves at first
    order in the samples' error, the force, stationary there, much less), and the method
    names the bracketed slope, the minima and the coarse-vs-fine estimate."""
    from hertzmdr.numeric import mdr

    E, dg = 3e6, 0.04
    shape, f, r_max, n = ((ad.Sphere(1e-6), lambda r: sphere.profile(r, 1e-6), 0.9e-6, 100)
                          if name == "sphere" else
                          (ad.Cone(0.3), lambda r: r * math.tan(0.3), 2e-6, 60))
    r = np.linspace(0.0, r_max, n + 1)
    c = ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, f(r))), E, dg)
    ref = ad.AdhesiveContact(shape, E, dg)
    for control in ad.CONTROLS:
        po, pr = c.pull_off(control), ref.pull_off(control)
        which = "dF/da" if control == "force" else "dd/da"
        assert po.method == (f"bracketed root of {which} (1 minima), numerical MDR (error: "
                             "coarse vs fine samples)")
        err_F = abs(po.force / pr.force - 1)
        err_a = abs(po.contact_radius / pr.contact_radius - 1)
        assert max(err_F, err_a) <= po.rel_error < 1e-4, (control, err_F, err_a, po.rel_error)


def _terrace(E=3e6, dg=0.001):
    """A sampled paraboloid (R = 1 um) with a flat terrace on 200 nm < r < 400 nm: on the
    terrace g(a) falls (the MDR of a flat ring), so d(a) and F(a) have a minimum, a maximum
    near a = 200 nm above the touch and a second minimum beyond the terrace."""
    from hertzmdr.numeric import mdr

    R, r1, r2 = 1e-6, 2e-7, 4e-7
    r = np.linspace(0.0, 1e-6, 201)
    f = np.where(r < r1, r**2 / (2 * R),
                 np.where(r < r2, r1**2 / (2 * R), r1**2 / (2 * R) + (r - r2) ** 2 / (2 * R)))
    return ad.AdhesiveContact(ad.Sampled(mdr.Profile.from_samples(r, f)), E, dg)


@pytest.mark.parametrize("control", ad.CONTROLS)
def test_cycle_with_jumps_on_loading_and_unloading(control):
    """A terraced tip: loading jumps at the maximum of d(a) (F(a)) to the outer branch,
    unloading (depth control) jumps at the outer minimum back to the inner branch before it
    pulls off. Each jump starts at a local extremum of the controlled value (checked by its
    values at a(1 +- 1e-3)), keeps it (a jump at constant depth or force) and lands on a
    stable state of the curve (the value rising with a); the path is on the curve; the
    hysteresis against the trapezoid rule of the closed F dd along the branches (in d, on
    4000 and 8000 points each, extrapolated: the two differ by 1e-7 relative, the
    extrapolation by < 1e-8 from 32000 points) plus F times the depth of each jump at
    constant force: within its estimate (promise 2; measured 3e-7 and 1e-7; the estimate, 6e-3
    relative, is mostly the coarse-vs-fine difference of the sampled curve: every other one
    of 201 samples across the terrace's edges, where f'' jumps)."""
    c = _terrace()
    to = 1e-7 if control == "depth" else 2e-7
    cyc = c.cycle(to, control, 400)
    assert len(cyc.depth) == len(cyc.force) == len(cyc.contact_radius) == 400
    kinds = [j.kind for j in cyc.jumps]
    assert kinds == (["jump into contact", "jump", "jump", "pull-off"] if control == "depth"
                     else ["jump into contact", "jump", "pull-off"])
    k = 0 if control == "depth" else 1

    def val(a):
        return float(c.depth(a) if control == "depth" else c.force(a))

    assert cyc.jumps[0].before == (0.0, 0.0, 0.0) and abs(cyc.jumps[0].after[k]) < 1e-20
    for j, kind in zip(cyc.jumps[1:-1], ("max", "min"), strict=False):
        m = j.before[2]
        side = [val(m * (1 - 1e-3)), val(m * (1 + 1e-3))]
        assert (max(side) < val(m)) if kind == "max" else (min(side) > val(m)), (kind, m)
        assert j.before == (float(c.depth(m)), float(c.force(m)), m)
        n = j.after[2]
        assert (n > m) if kind == "max" else (n < m)
        assert abs(j.after[k] - j.before[k]) <= 1e-12 * abs(j.before[k])
        assert j.after == (float(c.depth(n)), float(c.force(n)), n)
        assert val(n * (1 - 1e-3)) < val(n) < val(n * (1 + 1e-3))  # stable
    po = cyc.jumps[-1]
    assert po.after == (po.before[0], 0.0, 0.0) and po.before[2] == pytest.approx(
        c.pull_off(control).contact_radius, rel=1e-12)
    inside = cyc.contact_radius > 0
    assert np.allclose(cyc.depth[inside], c.depth(cyc.contact_radius[inside]), rtol=1e-11,
                       atol=1e-11 * to)
    top = cyc.depth.max() if control == "depth" else cyc.force.max()
    assert abs(top / to - 1) < 1e-13
    # the closed integral of F dd: along each branch between the jumps, oriented
    js = cyc.jumps
    a_top = float(cyc.contact_radius.max())
    ends = [(js[0].after[2], js[1].before[2]), (js[1].after[2], a_top)]
    ends += ([(a_top, js[2].before[2]), (js[2].after[2], js[3].before[2])]
             if control == "depth" else [(a_top, js[2].before[2])])
    Ws = []
    for n in (4000, 8000):
        W = sum(j.before[1] * (j.after[0] - j.before[0]) for j in js)
        for lo, hi in ends:
            a = np.linspace(lo, hi, n + 1)
            d, F = c.depth(a), c.force(a)
            W += float(np.sum((F[1:] + F[:-1]) / 2 * np.diff(d)))
        Ws.append(W)
    W = (4 * Ws[1] - Ws[0]) / 3
    assert abs(cyc.hysteresis / W - 1) <= cyc.hysteresis_error / cyc.hysteresis < 1e-2, (
        cyc.hysteresis, W, cyc.hysteresis_error)


def test_every_refusal_of_the_contact_api_is_one_line_naming_its_input():
    """Each refusal of AdhesiveContact's state and cycle API, matched in full: the input's
    name, its value (a float, never np.float64(...); the first bad element of an array) and
    what is valid."""
    import re

    c = ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.04)
    d_c, F_c = c.pull_off("depth").depth, c.pull_off("force").force
    sep = min(0.0, c.cycle(1e-7, "depth", 20).jumps[-1].after[0])
    cases = [
        (lambda: c.contact_radius(), "give exactly one of depth= and force="),
        (lambda: c.contact_radius(depth=1e-8, force=1e-9), "give exactly one of depth= and "
                                                            "force="),
        (lambda: c.contact_radius(depth=-1.0),
         f"depth = -1.0 is below the pull-off depth {d_c!r}: no contact"),
        (lambda: c.contact_radius(force=np.array([1e-9, -1.0, -2.0])),
         f"force = -1.0 is below the pull-off force {F_c!r}: no contact"),
        (lambda: c.contact_radius(depth="x"), "depth = 'x' is not a number or an array of "
                                              "numbers"),
        (lambda: c.equilibrium(depth="q"), "depth = 'q' is not a number or an array of numbers"),
        (lambda: c.equilibrium(force="q"), "force = 'q' is not a number or an array of numbers"),
        (lambda: c.cycle(1e-7, points=19), "points = 19 is out of range; valid: an integer >= 20"),
        (lambda: c.cycle(1e-7, points=20.5), "points = 20.5 is out of range; valid: an integer "
                                             ">= 20"),
        (lambda: c.cycle(-1.0), "to = -1.0 is out of range; valid: to > 0 and finite"),
        (lambda: c.cycle(1e-7, start=0.0),
         f"start = 0.0 m is in contact; valid: start <= {sep!r} m (below the touch and the "
         "pull-off depth)"),
        (lambda: c.pressure_at_depth(0.0, "x"), "d = 'x' is not a number or an array of numbers"),
        (lambda: c.surface_displacement_at_depth(0.0, "y"), "d = 'y' is not a number or an array "
                                                            "of numbers"),
        (lambda: c.pressure(-1.0, 1e-7), "r = -1.0 is out of range; valid: 0 <= r < inf"),
        (lambda: c.surface_displacement(-1.0, 1e-7), "r = -1.0 is out of range; valid: 0 <= r "
                                                     "< inf"),
        (lambda: ad.AdhesiveContact(3, 1, 1), "shape = 3 is not an adhesion.Shape (Paraboloid, "
                                              "Cone, PowerLaw, FlatPunch, Sphere, Worn)"),
        (lambda: ad.Sampled(3), "profile = 3 is not a hertzmdr.numeric.mdr.Profile"),
        (lambda: ad.AdhesiveContact(ad.Sphere(1e-6), 3e6, 0.04).contact_radius(depth=1.0),
         "depth = 1 m is not reached below the largest contact radius the profile describes, "
         "a = 1e-06 m"),
        (lambda: ad.AdhesiveContact(ad.Sphere(1e-6), 3e6, 0.04).contact_radius(force=1.0),
         "force = 1 N is not reached below the largest contact radius the profile describes, "
         "a = 1e-06 m"),
        # adhesion so strong that d(a) < 0 on the whole cap: the touch finds no stable state
        (lambda: ad.AdhesiveContact(ad.Sphere(1e-8), 1e6, 10.0).cycle(1e-9, "depth", 20),
         "no stable state at depth = 0.0 below a = 9.99999999e-09 m"),
    ]
    for fn, msg in cases:
        with pytest.raises(ValueError, match="^" + re.escape(msg) + "$"):
            fn()
    # 20 points: the smallest cycle; by default 1000 under depth control; an array of
    # forces keeps its shape
    assert len(c.cycle(1e-7, points=20).depth) == 20
    assert len(c.cycle(1e-7, points=101).depth) == 101  # an odd number of contact points
    default = c.cycle(1e-7)
    assert len(default.depth) == 1000 and default.control == "depth"
    # the default start: below 0 and the separation depth by a fifth of the depth range
    low = min(0.0, default.jumps[-1].after[0])
    assert default.depth[0] == default.depth[-1] == pytest.approx(
        low - 0.2 * (default.depth.max() - low), rel=1e-15)
    assert c.cycle(1e-7, "depth", 20, start=sep).depth[0] == sep  # the limit itself is valid
    # the default start of a cycle with four jumps: from the last one, the pull-off
    t = _terrace().cycle(1e-7, "depth", 100)
    low = min(0.0, t.jumps[-1].after[0])
    assert len(t.jumps) == 4 and t.depth[0] == pytest.approx(low - 0.2 * (1e-7 - low),
                                                             rel=1e-14)
    # no adhesion: no jumps, the retract from the touch d = 0 down to the start, no work
    z = ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.0).cycle(1e-8, "depth", 40)
    assert z.jumps == [] and z.depth.max() == pytest.approx(1e-8, rel=1e-14)
    assert z.depth[0] == z.depth[-1] == pytest.approx(-0.2e-8, rel=1e-14)
    assert abs(z.hysteresis) <= z.hysteresis_error < 1e-12 * 1e-8 * np.max(z.force)
    # a cone under force control lets go at d > 0 (dF/da = 0 at a g' = 3/2 Delta l, so d =
    # g - Delta l = Delta l/2 for g ~ a): the start is below the touch, d = 0
    cone = ad.AdhesiveContact(ad.Cone(0.3), 3e6, 0.04)
    cyc = cone.cycle(1e-7, "force", 40)
    assert cyc.jumps[-1].after[0] > 0
    assert cyc.depth[0] == pytest.approx(-0.2 * cyc.depth.max(), rel=1e-15)
    with pytest.raises(ValueError, match=r"^start = 5e-08 m is in contact; valid: start <= "
                                         r"0\.0 m \(below the touch and the pull-off depth\)$"):
        cone.cycle(1e-7, "force", 40, start=5e-8)
    assert c.contact_radius(force=np.array([[0.0, 1e-9]])).shape == (1, 2)
    sph = ad.AdhesiveContact(ad.Sphere(1e-6), 3e6, 0.04)
    assert sph.contact_radius(depth=np.array([[1e-8, 2e-8]])).shape == (1, 2)
    # the pull-off value itself is in contact, at the pull-off radius
    assert c.contact_radius(force=F_c) == pytest.approx(c.pull_off("force").contact_radius,
                                                        rel=1e-7)


def test_pressure_at_and_beyond_the_edge():
    """At r = a the adhesive pressure is -inf (the edge term ~ 1/sqrt(a - r)), beyond it 0;
    without adhesion it is 0 at the edge (not NaN: Hertz's pressure vanishes there); a flat
    punch's edge is infinite with the sign of its depth. Inside, the cone's adhesive
    pressure integrates to the force F(a) (r = a sin t takes the 1/sqrt edge away; 200
    Gauss-Legendre nodes; the cone's p ~ ln r at the apex leaves r ln r there: measured
    3e-10, 1e-8 asked)."""
    a = 1e-7
    for shape in (ad.Paraboloid(1e-6), ad.Cone(0.3), ad.Sphere(1e-6)):
        for dg, edge in ((0.04, -np.inf), (0.0, 0.0)):
            p = ad.AdhesiveContact(shape, 3e6, dg).pressure(np.array([a, 1.5 * a]), a)
            assert p[0] == edge and p[1] == 0.0, (shape, dg, p)
    k = ad.AdhesiveContact(ad.FlatPunch(a), 3e6, 0.04)
    for d, edge in ((1e-9, np.inf), (-1e-9, -np.inf)):
        p = k.pressure_at_depth(np.array([0.0, a, 2 * a]), d)
        assert p[1] == edge and p[2] == 0.0 and np.sign(p[0]) == np.sign(d)
    c = ad.AdhesiveContact(ad.Cone(0.3), 3e6, 0.04)
    t, w = np.polynomial.legendre.leggauss(200)
    t, w = np.pi / 4 * (t + 1), np.pi / 4 * w
    r = a * np.sin(t)
    F = np.sum(w * c.pressure(r, a) * 2 * np.pi * r * a * np.cos(t))
    assert abs(F / c.force(a) - 1) < 1e-8


def test_sampled_worn_tip_with_its_kink_against_the_worn_shape():
    """A worn tip (R = 1 um, flat b = 120 nm) given as samples with its kink as a breakpoint:
    piecewise quadratic, so the quintic spline is exact on both sides and the numerical MDR
    (kink terms of g' included) reproduces the derived Worn shape (its forms checked at 30
    digits in test_pull_off_by_mpmath_minimization): g and g' to 1e-13, the pull-off under
    both controls within its rel_error (under depth control exactly at the kink, a = b),
    the cycles' jumps and hysteresis to 1e-12 (roots and Gauss-Legendre: measured 5e-14),
    and the surface displacement inside, d - f(r) on the spline."""
    from hertzmdr.numeric import mdr

    E, dg, R, b = 3e6, 0.04, 1e-6, 1.2e-7
    r = np.concatenate([np.linspace(0, b, 25), np.linspace(b, 1e-6, 177)[1:]])
    s = ad.Sampled(mdr.Profile.from_samples(r, np.maximum(r**2 - b**2, 0) / (2 * R),
                                            breakpoints=[b]))
    assert s.kinks == (b,)
    c, ref = ad.AdhesiveContact(s, E, dg), ad.AdhesiveContact(ad.Worn(R, b), E, dg)
    a = np.array([1.5 * b, 3 * b])
    assert abs(float(s.g(0.5 * b))) < 1e-13 * float(ref.shape.g(3 * b))
    assert np.allclose(s.g(a), ref.shape.g(a), rtol=1e-13, atol=0)
    assert np.allclose(s.g_slope(a), ref.shape.g_slope(a), rtol=1e-13, atol=0)
    for control, jumps in (("force", ["jump into contact", "pull-off"]),
                           ("depth", ["jump into contact", "jump", "pull-off"])):
        po, pr = c.pull_off(control), ref.pull_off(control)
        assert max(abs(po.force / pr.force - 1),
                   abs(po.contact_radius / pr.contact_radius - 1)) <= po.rel_error < 1e-8
        if control == "depth":
            assert po.contact_radius == b
        cy, cr = c.cycle(5e-8, control, 200), ref.cycle(5e-8, control, 200)
        assert [j.kind for j in cy.jumps] == [j.kind for j in cr.jumps] == jumps
        for j, k in zip(cy.jumps[1:], cr.jumps[1:], strict=True):
            assert np.allclose(j.before + j.after, k.before + k.after, rtol=1e-12, atol=1e-22)
        assert abs(cy.hysteresis / cr.hysteresis - 1) < 1e-12
        assert cy.hysteresis_error < 1e-9 * cy.hysteresis
    d = 2e-8
    x = np.array([0.5 * b, 2 * b])
    u, u_ref = c.surface_displacement_at_depth(x, d), ref.surface_displacement_at_depth(x, d)
    assert np.allclose(u, u_ref, rtol=1e-11, atol=0)


@pytest.mark.parametrize("control", ad.CONTROLS)
def test_cycle_that_stops_at_or_below_the_maximum(control):
    """The terraced tip loaded to the value of its maximum (taken from the loading jump of a
    deeper cycle) or to half of it: no jump on loading; the top of the path is that value
    (at the maximum itself, 1e-13) on the inner branch (a at most the maximum's), then
    unloading down that branch to the pull-off. Out of contact F = 0 and a = 0; the path
    is flagged loading up to its top and unloading after it."""
    c = _terrace()
    deep = c.cycle(1e-7 if control == "depth" else 2e-7, control, 200)
    k = 0 if control == "depth" else 1
    m = deep.jumps[1].before
    for to in (m[k], 0.5 * m[k]):
        cyc = c.cycle(to, control, 200)
        assert [j.kind for j in cyc.jumps] == ["jump into contact", "pull-off"]
        top = cyc.depth.max() if control == "depth" else cyc.force.max()
        assert abs(top / to - 1) < 1e-13
        assert cyc.contact_radius.max() <= m[2] * (1 + 1e-12)
        # out of contact: no force, no radius; the flag: loading up to the top, then not
        assert cyc.control == control and np.all(cyc.contact_radius >= 0)
        free = cyc.contact_radius == 0
        assert np.all(cyc.force[free] == 0) and free[0] and free[-1]
        i_top = int(np.argmax(cyc.depth if control == "depth" else cyc.force))
        assert cyc.loading.dtype == bool and np.all(cyc.loading[:i_top + 1])
        assert not np.any(cyc.loading[i_top + 1:])


@pytest.mark.parametrize("control, to", [("depth", 2e-3), ("force", 1.0)])
def test_cycle_beyond_the_far_end_of_the_scan(control, to):
    """A worn tip pushed past the scan's far end (100 pull-off scales, 36 um here): the
    minima are scanned again up to the top, and unloading lets go at the same pull-off as
    pull_off (its state to 1e-14: the same bracketed root)."""
    c = ad.AdhesiveContact(ad.Worn(1e-6, 5e-9), 3e6, 0.04)
    cyc = c.cycle(to, control, 100)
    assert cyc.contact_radius.max() > c._far()
    assert [j.kind for j in cyc.jumps] == ["jump into contact", "pull-off"]
    po = c.pull_off(control)
    assert np.allclose(cyc.jumps[-1].before, (po.depth, po.force, po.contact_radius),
                       rtol=1e-14, atol=0)


def test_sampled_pull_off_without_a_coarse_minimum_says_so():
    """A worn tip sampled without its kink declared, from a_from = 200 nm: the samples'
    spline rounds the corner at b = 120 nm into a shallow minimum that every other sample
    misses, so the pull-off has no coarse-vs-fine estimate: one line saying so (it said
    "no pull-off below a = 2e-07 m", though the fine samples have one)."""
    from hertzmdr.numeric import mdr

    b, r = 1.2e-7, np.linspace(0, 1e-6, 401)
    c = ad.AdhesiveContact(
        ad.Sampled(mdr.Profile.from_samples(r, np.maximum(r**2 - b**2, 0) / 2e-6)), 3e6, 0.04)
    with pytest.raises(ValueError, match=r"^pull-off under force control below a = 2e-07 m: "
                       r"the samples have a minimum at a = 1\.2\d*e-07 m, the coarse samples "
                       r"\(every other one\) none, so it has no error estimate; give more "
                       r"samples, or declare the profile's kinks \(breakpoints=\)$"):
        c.pull_off("force", a_from=2e-7)


def test_sampled_cycle_hysteresis_error_bounds_its_error():
    """Promise 2 for a sampled profile's cycle: the hysteresis of the sampled worn tip (kink
    declared) under force control against the closed integral of F dd along the derived worn
    curve by mpmath at 30 digits (from the jump into contact to the pull-off: the jumps at
    F = 0 and at the pull-off do no work). Its error, 5e-14 relative, comes from the
    sampled curve (the pull-off radius moves W at first order), not from the quadrature
    (40 vs 80 nodes: 5e-15): the estimate adds the coarse-vs-fine difference of W (it did
    not, and reported 4.8e-15)."""
    from hertzmdr.numeric import mdr

    E, dg, R, b = 3e6, 0.04, 1e-6, 1.2e-7
    r = np.concatenate([np.linspace(0, b, 25), np.linspace(b, 1e-6, 177)[1:]])
    s = ad.Sampled(mdr.Profile.from_samples(r, np.maximum(r**2 - b**2, 0) / (2 * R),
                                            breakpoints=[b]))
    cyc = ad.AdhesiveContact(s, E, dg).cycle(5e-8, "force", 200)
    _, _, d_fn, F_fn = _mp_curves(ad.Worn(R, b))
    with mp.workdps(DPS):
        a_in = mp.findroot(F_fn, mp.mpf(cyc.jumps[0].after[2]))
        a_c = _mp_min(F_fn, mp.mpf(cyc.jumps[-1].before[2]))
        W = mp.quad(lambda a: F_fn(a) * mp.diff(d_fn, a), [a_in, a_c])
        err = abs(cyc.hysteresis / W - 1)
    assert err <= cyc.hysteresis_error / cyc.hysteresis < 1e-9, (err, cyc.hysteresis_error)


def test_flat_punch_equilibrium_at_a_depth_and_at_a_force():
    """The punch keeps its radius at every load above its pull-off: F = 2 E* a d (5.11) at a
    depth and d = F/(2 E* a) at a force, typed here (one rounding each: 1e-15), for a float
    (the radius a float too) and for an array (its shape kept)."""
    E, dg, rad = 3e6, 0.05, 1e-6
    k = ad.AdhesiveContact(ad.FlatPunch(rad), E, dg)
    assert type(k.contact_radius(depth=1e-8)) is float
    a, d, F = k.equilibrium(depth=1e-8)
    assert a == rad and d == 1e-8 and F == pytest.approx(2 * E * rad * 1e-8, rel=1e-15)
    a, d, F = k.equilibrium(force=np.array([1e-3, 2e-3]))
    assert np.all(a == rad) and a.shape == (2,)
    assert np.allclose(F, [1e-3, 2e-3], rtol=0, atol=0)
    assert np.allclose(d, np.array([1e-3, 2e-3]) / (2 * E * rad), rtol=1e-15, atol=0)


def test_equilibrium_and_mean_pressure_of_the_paraboloid_by_jkr():
    """The stable state at a depth and at a force returns the depth (force) asked for and
    the other on the curve at its radius: JKR's F(a) = 4 E* a^3/(3R) - sqrt(8 pi dgamma E*
    a^3) and d(a) = a^2/R - sqrt(2 pi a dgamma/E*), typed at 30 digits (a root to a few
    eps: 1e-13); the mean pressure at a force is F/(pi a^2) of that state. The punch's
    pressure at a radius is that at its pull-off depth: -inf at the edge."""
    E, R, dg = 3e6, 1e-6, 0.05
    c = ad.AdhesiveContact(ad.Paraboloid(R), E, dg)
    with mp.workdps(DPS):
        Em, Rm, gm = mp.mpf(E), mp.mpf(R), mp.mpf(dg)
        for kw in ({"depth": 2e-8}, {"force": 1e-7}):
            a, d, F = (float(x) for x in c.equilibrium(**kw))
            am = mp.mpf(a)
            assert_close(F, 4 * Em * am**3 / (3 * Rm) - mp.sqrt(8 * mp.pi * gm * Em * am**3),
                         1e-13, f"F at {kw}")
            assert_close(d, am**2 / Rm - mp.sqrt(2 * mp.pi * am * gm / Em), 1e-13, f"d at {kw}")
            assert (d if "depth" in kw else F) == pytest.approx(next(iter(kw.values())),
                                                                 rel=1e-13)
        a, _, F = c.equilibrium(force=1e-7)
        assert_close(float(c.mean_pressure(force=1e-7)),
                     mp.mpf(float(F)) / (mp.pi * mp.mpf(float(a))**2),
                     1e-15, "mean pressure at a force")
    k = ad.AdhesiveContact(ad.FlatPunch(1e-6), E, dg)
    p = k.pressure(np.array([0.0, 1e-6]), 1e-6)
    assert p[1] == -np.inf and p[0] < 0


@pytest.mark.parametrize("points", [20, 21, 37, 101])
def test_cycle_has_the_points_asked_for(points):
    """A cycle's path has exactly ``points`` points, jumps included, however many branches
    share them (the terraced tip: two loading and two unloading branches under depth
    control; the worn tip: two unloading branches) and without adhesion (the retract ends at
    the touch, a = 0, which is a point of the path). It had 22 for 20 asked (each branch's
    rounded share, at least 2, summed past the total) and 19 without adhesion (a = 0
    dropped)."""
    cases = [(_terrace(), 1e-7, "depth"), (_terrace(), 2e-7, "force"),
             (ad.AdhesiveContact(ad.Worn(1e-6, 1.2e-7), 3e6, 0.04), 5e-8, "depth"),
             (ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.0), 1e-8, "depth")]
    for c, to, control in cases:
        cyc = c.cycle(to, control, points)
        assert len(cyc.depth) == len(cyc.force) == len(cyc.contact_radius) == points, (c, control)
        assert len(cyc.loading) == points


def _largest_remainders(lengths, n):
    """Hamilton's apportionment in exact rationals (fractions.Fraction of the float lengths):
    2 points per branch, the rest shared in proportion to the lengths, the leftover points
    to the largest remainders, the earlier branch first on a tie; 2 each when n < 2 per
    branch; equal shares when every branch has zero length."""
    from fractions import Fraction

    extra = n - 2 * len(lengths)
    if extra <= 0:
        return [2] * len(lengths)
    fl = [Fraction(x) for x in lengths]
    total = sum(fl)
    share = [extra * (x / total if total else Fraction(1, len(fl))) for x in fl]
    k = [2 + math.floor(s) for s in share]
    rest = extra - sum(math.floor(s) for s in share)
    order = sorted(range(len(fl)), key=lambda i: (-(share[i] - math.floor(share[i])), i))
    for i in order[:rest]:
        k[i] += 1
    return k


def test_branch_points_shared_by_largest_remainders():
    """A cycle's radii along its branches (AdhesiveContact._branch_points): both ends of each
    branch and the rest shared in proportion to the branches' lengths (nanometre branches, a
    total below 1 m, one of them run downwards as on unloading), by the largest remainders
    with ties to the earlier branch (a stable sort: the path does not depend on numpy's sort
    algorithm), 2 each when there are fewer than 2 per branch, equal shares for branches of
    zero length. Against Hamilton's apportionment in exact rationals and hand-worked counts
    (13 points on lengths 1 and 3 nm: 2 + 2.25 and 2 + 6.75, the leftover to the 0.75)."""
    c = ad.AdhesiveContact(ad.Paraboloid(1e-6), 3e6, 0.04)
    two = [(2e-9, 3e-9), (6e-9, 3e-9)]
    ties = [(1e-9, 2e-9)] * 3 + [(1e-9, 3e-9)] * 2
    flat = [(1e-9, 1e-9), (2e-9, 2e-9)]
    cases = [(two, 13, [4, 9]), (two, 5, [2, 3]), (two, 4, [2, 2]), (two, 3, [2, 2]),
             (ties, 13, [3, 2, 2, 3, 3]), (flat, 7, [4, 3])]
    for branches, n, want in cases:
        got = c._branch_points(branches, n)
        lengths = [abs(b - a) for a, b in branches]
        assert [len(x) for x in got] == want == _largest_remainders(lengths, n), (branches, n)
        for (a, b), x in zip(branches, got, strict=True):
            assert x[0] == a and x[-1] == b  # both ends of every branch


@pytest.mark.parametrize("control", ad.CONTROLS)
def test_cone_cycle_hysteresis_error_bounds_its_error(control):
    """A derived cone's cycle (theta = 1.2 rad): its hysteresis against the mpmath quadrature
    (30 digits, tanh-sinh, which takes the sqrt(a) of the adhesive term at the ends) of the
    derived F d'(a) from the pull-off radius to the radius after the jump in, plus F times
    the depth of each jump at constant force (promise 2). Under force control the
    Gauss-Legendre rule's true error, 7e-14 relative (measured), is 40 times the 8 eps floor:
    only the quadrature's estimate (8.7e-12) bounds it."""
    shape = ad.Cone(1.2)
    E, dg, d_fn, F_fn = _mp_curves(shape)
    c = ad.AdhesiveContact(shape, float(E), float(dg))
    cyc = c.cycle(1e-7 if control == "force" else 5e-8, control, 100)
    assert [j.kind for j in cyc.jumps] == ["jump into contact", "pull-off"]
    with mp.workdps(DPS):
        a_po, a_in = mp.mpf(cyc.jumps[-1].before[2]), mp.mpf(cyc.jumps[0].after[2])
        W = -mp.quad(lambda a: F_fn(a) * mp.diff(d_fn, a), [a_po, a_in])
        W += sum(mp.mpf(j.before[1]) * (mp.mpf(j.after[0]) - j.before[0]) for j in cyc.jumps)
        err = abs(float((cyc.hysteresis - W) / W))
    assert err <= cyc.hysteresis_error / cyc.hysteresis < 1e-10, (err, cyc.hysteresis_error)


@pytest.mark.parametrize("shape", [ad.Paraboloid(20e-9), ad.Cone(np.radians(20))],
                         ids=["sphere", "cone"])
@pytest.mark.parametrize("control", ["depth", "force"])
def test_cycle_without_adhesion_dissipates_nothing(shape, control):
    """Without adhesion (dgamma = 0) the unloading retraces the loading curve and nothing
    jumps: the hysteresis is 0 with error 0, not the quadrature's roundings of the two
    branches (before: 3.9e-34 J with an estimate of 1.2e-32 J for the 20 nm sphere, whose
    ratio the scene reported as a relative error of 31; -5e-29 J for the cone). Each branch
    is the one force law, the force rising with the depth."""
    c = ad.AdhesiveContact(shape, 2e6 / 0.75, 0.0)  # PDMS: E = 2 MPa, nu = 0.5
    cyc = c.cycle(10e-9 if control == "depth" else 5e-10, control, 60)  # about 10 nm deep
    assert cyc.jumps == [] and cyc.hysteresis == 0.0 and cyc.hysteresis_error == 0.0
    inside = cyc.contact_radius > 0
    for part in (cyc.loading, ~cyc.loading):  # both branches on one curve F(d)
        sel = inside & part
        d, F = cyc.depth[sel], cyc.force[sel]
        order = np.argsort(d)
        assert np.all(np.diff(F[order]) >= 0)
