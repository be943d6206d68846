"""The adhesive fit of an exact sphere's retract curve (hertzmdr.numeric.fit_adhesive,
derive/fit.py's adhesive_sphere_model).

Independent route: the energy method (Johnson's, as for the cone in test_fit_adhesive_cone.py),
not the MDR's critical elongation. A tip in contact of radius a at the depth d stores the
elastic energy of its non-adhesive state plus that of a flat punch of radius a pressed by the
difference d - d_H(a):

    U(a, d) = U_H(a) + F_H(a) (d - d_H(a)) + E* a (d - d_H(a))^2,

with d_H(a), F_H(a) the non-adhesive depth and force at the contact radius a (for the cap
Sneddon's in logarithms: d_H = (a/2) ln((R + a)/(R - a)), F_H = E* ((a^2 + R^2)/2
ln((R + a)/(R - a)) - a R)) and dU_H/da = F_H(a) d_H'(a) (U_H is the work of the non-adhesive
loading). The force is dU/dd and equilibrium is d/da [U - pi a^2 Delta gamma] = 0 at a fixed d
(Griffith); mpmath evaluates these at 30 digits by diff and findroot: d(a) from the equilibrium
condition, F(a) = dU/dd there; the Jacobian by mpmath.diff of the curve F(z) with a from
findroot; the pull-off radius by findroot on the route's dd/da. Synthetic curves are made by the
forward numeric/adhesion.py (AdhesiveContact of its Sphere: its own root finder on a uniform
grid of positions).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from test_fit_jkr import (
    check_radius_beyond_and_without_adhesion,
    cli_adhesive_fit,
    radius_tolerance,
)
from test_fit_jkr import forward_curve as jkr_forward_curve

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import adhesion
from hertzmdr.numeric import fit as hfit
from hertzmdr.numeric import fit_adhesive as fa

from oracle import n_points

DPS = 30
R_TIP = 1e-6  # m: a colloidal probe, indented to a/R ~ 0.6
E_TRUE = 2.0e6  # Pa
DG_TRUE = 0.05  # J/m^2
Z0_TRUE = 1.3e-6  # m
F0_TRUE = 2.0e-9  # N
S0_TRUE = 1.0e-4  # N/m
DEPTH = 300e-9  # m: the deepest indentation of the synthetic curves
TRUTH = np.array([E_TRUE, Z0_TRUE, DG_TRUE, F0_TRUE, S0_TRUE])
TIP = hfit.ExactSphere(R=R_TIP)


class EnergyRoute:
    """The adhesive contact of a tip by the energy method at mpmath's precision, from its
    non-adhesive d_H(a) and F_H(a) (functions of a and E*)."""

    def __init__(self, d_H, F_H):
        self.d_H, self.F_H = d_H, F_H

    def _dU_da(self, a, d, E):
        """dU/da at a fixed d: dU_H/da = F_H d_H' plus mpmath.diff of the punch's terms."""
        def rest(x):
            return self.F_H(x, E) * (d - self.d_H(x)) + E * x * (d - self.d_H(x)) ** 2
        return self.F_H(a, E) * mp.diff(self.d_H, a) + mp.diff(rest, a)

    def depth(self, a, E, dg):
        """The depth at which a is in equilibrium, the root below d_H(a) (adhesion pulls the
        surface up): d/da [U - pi a^2 Delta gamma] = 0."""
        dh = self.d_H(a)
        width = 4 * mp.sqrt(2 * mp.pi * a * dg / E)
        return mp.findroot(lambda d: self._dU_da(a, d, E) - 2 * mp.pi * a * dg,
                           (dh - width, dh), solver="anderson")

    def force(self, a, E, dg):
        """F = dU/dd at the equilibrium depth (U_H does not depend on d)."""
        d = self.depth(a, E, dg)
        return mp.diff(lambda x: self.F_H(a, E) * (x - self.d_H(a))
                       + E * a * (x - self.d_H(a)) ** 2, d)

    def a_dc(self, E, dg, lo, hi):
        """The depth-controlled pull-off radius: dd/da = 0 of :meth:`depth`, bracketed by
        [lo, hi]."""
        return mp.findroot(lambda a: mp.diff(lambda x: self.depth(x, E, dg), a),
                           (mp.mpf(lo), mp.mpf(hi)), solver="anderson")

    def radius(self, d, E, dg, a_dc, a_max=mp.inf):
        """a on the branch a > a_dc at the depth d."""
        hi = min(mp.mpf(a_dc) * 2, (a_dc + a_max) / 2)
        while self.depth(hi, E, dg) < d:
            hi = min(hi * 2, (hi + a_max) / 2)
        return mp.findroot(lambda a: self.depth(a, E, dg) - d,
                           (a_dc * (1 + mp.mpf(10) ** -12), hi), solver="anderson")


def sneddon_depth(a, R):
    return a / 2 * mp.log((R + a) / (R - a))  # Sneddon (1965), the cap's depth


def sneddon_force(a, E, R):
    return E * ((a**2 + R**2) / 2 * mp.log((R + a) / (R - a)) - a * R)  # Sneddon's load


def route(R):
    return EnergyRoute(lambda a: sneddon_depth(a, mp.mpf(R)),
                       lambda a, E: sneddon_force(a, E, mp.mpf(R)))


def sphere_a_dc(rt, E, dg, R):
    """The energy route's pull-off radius of the cap: below JKR's (the cap's g' is above the
    paraboloid's), above a quarter of it (a/R <= 0.6 here)."""
    a_jkr = float(gen.jkr_pull_off_radius_dc(float(E), float(dg), R))
    return rt.a_dc(E, dg, a_jkr / 4, a_jkr)


def assert_recovered(res, F):
    """A noise-free fit of the forward curve (F [N]) of TRUTH: every parameter to <= 1e-10
    relative (z_0 to 1e-10 of DEPTH, the baseline's value at z_0 to 1e-10 of the force range),
    with the jump-off found."""
    span = float(np.ptp(F))
    assert res.values[0] == pytest.approx(E_TRUE, rel=1e-10)
    assert abs(res.values[1] - Z0_TRUE) <= 1e-10 * DEPTH
    assert res.values[2] == pytest.approx(DG_TRUE, rel=1e-10)
    assert abs(res.values[3] + res.values[4] * Z0_TRUE - F0_TRUE - S0_TRUE * Z0_TRUE) \
        <= 1e-10 * span
    assert res.jump_off is not None and res.z_split is not None


def cap_cases(rng, n):
    """n draws of (E* [Pa], R [m], Delta gamma [J/m^2], a [m], z_p [m], F_0 [N], s_0 [N/m])
    over decades of E*, R, Delta gamma and a/R from 1e-3 to 0.95, with a baseline."""
    for _ in range(n):
        E = 10 ** rng.uniform(4, 11)
        R = 10 ** rng.uniform(-8, -4)
        dg = 10 ** rng.uniform(-4, 0)
        a = R * 10 ** rng.uniform(-3, math.log10(0.95))
        yield (E, R, dg, a, rng.uniform(-1e-6, 1e-6), rng.uniform(-1e-9, 1e-9),
               rng.uniform(-1, 1))


# --- the generated relations -------------------------------------------------------------
def test_adhesive_sphere_model_by_mpmath_parametric():
    """fit_adhesive_sphere_depth and fit_adhesive_sphere_force against the energy route at 30
    digits, over decades of E*, R, Delta gamma and a/R from 1e-3 to 0.95."""
    rng = np.random.default_rng(0)
    worst = 0.0
    for E, R, dg, a, z, F0, s0 in cap_cases(rng, n_cases := 16):
        rt = route(R)
        with mp.workdps(DPS):
            am = mp.mpf(a)
            d_ref = rt.depth(am, E, dg)
            F_ref = rt.force(am, E, dg) + F0 + s0 * mp.mpf(z)
            # rounding is relative to the largest term of each difference
            dl = float(mp.sqrt(2 * mp.pi * am * dg / E))
            d_scale = float(sneddon_depth(am, mp.mpf(R))) + dl
            F_scale = float(E * (am**2 + R**2) * mp.atanh(am / R)) + 2 * E * a * dl \
                + abs(F0) + abs(s0 * z)
        d_num = gen.fit_adhesive_sphere_depth(E, R, a, math.sqrt(dg))
        F_num = gen.fit_adhesive_sphere_force(E, R, a, math.sqrt(dg), z, F0, s0)
        worst = max(worst, float(abs(d_num - d_ref)) / d_scale,
                    float(abs(F_num - F_ref)) / F_scale)
    assert n_cases == 16
    # a few roundings of terms of the size of the largest, and atanh (1 ulp each); atanh(a/R)
    # near a/R = 0.95 carries the rounding of a/R amplified by 1/(1 - (a/R)^2) ~ 10
    assert worst < 1e-14, worst


def test_adhesive_sphere_pull_off_by_the_energy_route():
    """The sphere's depth-controlled pull-off radius (no closed form: the root of the generated
    dd/da, fit_adhesive._sphere_pull_off_radius) against the minimum of the energy route's d(a),
    at 30 digits, from a shallow pull-off (a/R ~ 0.02, JKR's) to a deep one (a/R ~ 0.5)."""
    fam = fa._family(TIP)
    for dg in (1e-4, DG_TRUE, 1.0):
        with mp.workdps(DPS):
            a_dc = sphere_a_dc(route(R_TIP), E_TRUE, dg, R_TIP)
            d_dc = route(R_TIP).depth(a_dc, E_TRUE, dg)
        a_num, d_num = fa._jump_off_radius(E_TRUE, fam, math.sqrt(dg))
        # the bisection ends at 1e-16 of a; d is flat in a there (dd/da = 0): d to its rounding
        assert a_num == pytest.approx(float(a_dc), rel=1e-13), dg
        assert d_num == pytest.approx(float(d_dc), rel=1e-13), dg
    assert fam.a_dc(E_TRUE, 0.0) == 0.0


def test_adhesive_sphere_radius_by_mpmath():
    """Newton on the generated d(a) against mpmath.findroot on the energy route, from next to
    the jump-off to a/R = 0.999; NaN past the jump-off; Sneddon's a(d) without adhesion."""
    fam = fa._family(TIP)
    rho = math.sqrt(DG_TRUE)
    a_c, d_c = fa._jump_off_radius(E_TRUE, fam, rho)
    ds = d_c + np.r_[np.geomspace(1e-8, 1e-2, 4) * abs(d_c), 0.5 * abs(d_c),
                     np.geomspace(abs(d_c), 100 * abs(d_c), 3)]
    ds = np.r_[ds, 3 * R_TIP]  # a/R = 0.9993
    a = fa._contact_radius(ds, fam, E_TRUE, rho)
    rt = route(R_TIP)
    with mp.workdps(DPS):
        a_dc = sphere_a_dc(rt, E_TRUE, DG_TRUE, R_TIP)
        for di, ai in zip(ds, a, strict=True):
            ref = rt.radius(mp.mpf(di), E_TRUE, DG_TRUE, a_dc, mp.mpf(R_TIP))
            tol = radius_tolerance(lambda x: rt.depth(x, E_TRUE, DG_TRUE),
                                   lambda x: sneddon_depth(x, mp.mpf(R_TIP)), ref, a_dc, di,
                                   d_c, E_TRUE, DG_TRUE)
            assert abs(ai - float(ref)) <= tol, (di, ai, float(ref), tol)
    Rm = mp.mpf(R_TIP)
    check_radius_beyond_and_without_adhesion(
        fam, d_c, rho, E_TRUE,
        lambda di: mp.findroot(lambda x: sneddon_depth(x, Rm) - di,
                               (mp.sqrt(di * Rm) / 2, Rm * (1 - mp.mpf(10) ** -25)),
                               solver="anderson"))


def mp_model(rt, E, z0, dg, z, a_lo, a_max):
    """The tip's force at the position z by the energy route, on the branch a > a_lo."""
    return rt.force(rt.radius(z - z0, E, dg, a_lo, a_max), E, dg)


def jacobian_check(tip, rt, ts, a_lo_of, a_max=mp.inf, E_true=E_TRUE, dg_true=DG_TRUE):
    """The largest relative error of (dF/dE*, dF/dz_0, dF/dDelta gamma) of the tip's family
    against mpmath.diff of the energy route's curve at the positions where a = t a_dc."""
    fam = fa._family(tip)
    rho = math.sqrt(dg_true)
    a_c, _ = fa._jump_off_radius(E_true, fam, rho)
    worst = 0.0
    with mp.workdps(DPS):
        E, z0, dg = mp.mpf(E_true), mp.mpf(Z0_TRUE), mp.mpf(dg_true)
        lo = a_lo_of(E, dg)
        for t in ts:
            a = a_c * t
            z = float(Z0_TRUE + rt.depth(mp.mpf(a), E, dg))
            refs = (mp.diff(lambda x, z=z: mp_model(rt, x, z0, dg, z, lo, a_max), E),
                    mp.diff(lambda x, z=z: mp_model(rt, E, x, dg, z, lo, a_max), z0),
                    mp.diff(lambda x, z=z: mp_model(rt, E, z0, x, z, lo, a_max), dg))
            a_num = float(fa._contact_radius(np.array([z - Z0_TRUE]), fam, E_true, rho)[0])
            nums = (fam.dE(E_true, a_num, rho), fam.dz0(E_true, a_num, rho),
                    fam.ddgamma(E_true, a_num, rho))
            for num, ref in zip(nums, refs, strict=True):
                worst = max(worst, float(abs(num - ref) / abs(ref)))
    return worst


def test_adhesive_sphere_jacobian_by_mpmath_derivative():
    """dF/dE*, dF/dz_0, dF/dDelta gamma (SymPy's implicit differentiation, generated) against
    mpmath.diff of the energy route's curve at fixed positions, at 30 digits (a/R = 0.26 and
    0.8); and dF/dDelta gamma -> -2 pi a/g'(a) as Delta gamma -> 0."""
    rt = route(R_TIP)
    worst = jacobian_check(TIP, rt, (1.3, 4.0), lambda E, dg: sphere_a_dc(rt, E, dg, R_TIP),
                           mp.mpf(R_TIP))
    # as the cone's: 1/(dd/da) (condition ~10 at 1.3 a_dc) on a of ~1e-15, the position z
    # rounded to a double: 1e-11 leaves room without hiding a wrong term (one is O(1))
    assert worst < 1e-11, worst
    fam = fa._family(TIP)
    a0 = 0.3 * R_TIP
    with mp.workdps(DPS):
        gp = mp.diff(lambda x: sneddon_depth(x, mp.mpf(R_TIP)), mp.mpf(a0))
        ref = float(-2 * mp.pi * a0 / gp)
    assert fam.ddgamma(E_TRUE, a0, 0.0) == pytest.approx(ref, rel=1e-14)


# --- fits ------------------------------------------------------------------------------------
def forward_curve(n=400, truth=TRUTH, noise=0.0, seed=0, shape=None, depth=DEPTH):
    """test_fit_jkr's retract curve of ``shape`` (default: the exact sphere of radius R_TIP)
    to the indentation ``depth``."""
    return jkr_forward_curve(n, truth, noise, seed,
                             adhesion.Sphere(R=R_TIP) if shape is None else shape, depth)


def test_noise_free_recovery():
    """A noise-free curve by the forward model (a/R up to 0.62): every parameter to <= 1e-10
    relative (z_0 to 1e-10 of the deepest indentation, the baseline's to 1e-10 of the force
    range); the jump-off force the energy route's."""
    z, F = forward_curve()
    res = fa.fit_curve(z, F, TIP)
    assert_recovered(res, F)
    assert "exact sphere (spherical cap), adhesive" in res.tip.describe()
    assert not any("excluded" in w for w in res.warnings), res.warnings


def test_noise_recovery_within_errors():
    """With noise of 0.5 % of the force range: the truth within 4 reported standard errors
    (a 6e-5 event each for right errors), the reduced chi^2 near 1."""
    z, F0 = forward_curve()
    sigma = 5e-3 * float(np.ptp(F0))
    z, F = forward_curve(noise=sigma, seed=3)
    res = fa.fit_curve(z, F, TIP, sigma=sigma)
    assert np.all(np.abs(res.values - TRUTH) <= 4 * res.errors), (res.values, res.errors)
    # chi^2/(N - 5) has a standard deviation of sqrt(2/(N - 5)) = 0.07 at N = 400
    assert abs(res.reduced_chi2 - 1) < 0.3


def coverage(tip, shape, m, depth=DEPTH):
    """The fraction of m noisy curves (noise 1 % of the depth-controlled pull-off force, 200
    points, the same curve per seed, new noise each) whose truth lies within one reported
    standard error, per parameter."""
    z, F = forward_curve(n=200, shape=shape, depth=depth)
    c = adhesion.AdhesiveContact(shape, E_star=E_TRUE, dgamma=DG_TRUE)
    noise = 0.01 * abs(c.pull_off("depth").force)
    inside = np.zeros(5)
    for seed in range(m):
        Fn = F + np.random.default_rng(seed).normal(0.0, noise, z.size)
        res = fa.fit_curve(z, Fn, tip, sigma=noise)
        inside += np.abs(res.values - TRUTH) <= res.errors
    return inside / m


def check_coverage(frac, m):
    """Binomial(m, 0.683): standard deviation sqrt(0.683 0.317/m) (0.093 at m = 25, 0.015 at
    m = 1000); the tolerance of 3.5 of them makes a false failure a 5e-4 event per
    parameter."""
    tol = 3.5 * math.sqrt(0.6827 * 0.3173 / m)
    assert np.all(np.abs(frac - 0.6827) <= tol), (frac, tol)


@pytest.mark.sweep
def test_coverage_of_standard_errors():
    """The truth within one reported standard error in ~68.3 % of 1000 noisy curves (25 in
    CI: ~10 s)."""
    m = n_points(1000, 25)
    check_coverage(coverage(TIP, adhesion.Sphere(R=R_TIP), m), m)


def test_flat_punch_is_one_clear_error():
    with pytest.raises(ValueError, match="has no adhesive fit model; valid: a Paraboloid"):
        fa.fit_curve(np.linspace(0, 1, 10), np.linspace(0, 1, 10), hfit.FlatPunch(a=1e-6))


def test_cli_fits_an_exact_sphere_with_adhesion(tmp_path, capsys):
    """``hertzmdr fit --adhesion`` with an exact_sphere scene: exit 0, the work of adhesion
    within 4 standard errors of the truth."""
    z, F0 = forward_curve()
    sigma = 5e-3 * float(np.ptp(F0))
    z, F = forward_curve(noise=sigma, seed=5)
    cli_adhesive_fit(tmp_path, capsys, z, F, sigma,
                     f'shape = "exact_sphere"\nradius = "{R_TIP} m"',
                     "exact sphere (spherical cap), adhesive")
