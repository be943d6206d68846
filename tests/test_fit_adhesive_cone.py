"""The adhesive fit of a cone's retract curve (hertzmdr.numeric.fit_adhesive, derive/fit.py's
adhesive_cone_model).

Independent route: the energy method (Johnson's, as for JKR), not the MDR's critical
elongation. A cone f = r tan(theta) in contact of radius a at the depth d stores the elastic
energy of its non-adhesive state plus that of a flat punch of radius a pressed by the
difference d - d_H(a):

    U(a, d) = U_H(a) + F_H(a) (d - d_H(a)) + E* a (d - d_H(a))^2,

with d_H(a) = (pi/2) a tan(theta) (5.38), F_H(d) = (2/pi) E* d^2/tan(theta) (5.40) and
U_H(a) = integral of F_H from 0 to d_H(a) (mpmath.quad); the force is dU/dd and equilibrium
is d/da [U - pi a^2 Delta gamma] = 0 at a fixed d (Griffith). mpmath evaluates these at 30
digits by quad, diff and findroot: d(a) from the equilibrium condition, F(a) = dU/dd there;
the Jacobian by mpmath.diff of the curve F(z) with a from findroot; the pull-off by
minimising F(a) and d(a). Synthetic curves are made by the forward numeric/adhesion.py (its
own root finder on a uniform grid of positions).
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
THETA = 0.3  # rad: a blunt AFM cone
E_TRUE = 2.0e6  # Pa
DG_TRUE = 0.05  # J/m^2
Z0_TRUE = 1.3e-6  # m
F0_TRUE = 2.0e-9  # N
S0_TRUE = 1.0e-4  # N/m
TRUTH = np.array([E_TRUE, Z0_TRUE, DG_TRUE, F0_TRUE, S0_TRUE])
TIP = hfit.Cone(theta=THETA)


# --- the energy route (mpmath) -----------------------------------------------------------
def d_H(a, th):
    return mp.pi / 2 * a * mp.tan(th)  # (5.38)


def F_H(d, E, th):
    return 2 / mp.pi * E * d**2 / mp.tan(th)  # (5.40)


def U_H(a, E, th):
    """The elastic energy of the non-adhesive cone at the contact radius a: the work of
    (5.40) up to d_H(a), integrated in closed form (a cubic; checked against mpmath.quad in
    test_energy_route_integral)."""
    return 2 / (3 * mp.pi) * E * d_H(a, th) ** 3 / mp.tan(th)


def energy(a, d, E, th):
    """U(a, d): the cone's non-adhesive state at a plus a flat punch of radius a."""
    dh = d_H(a, th)
    return U_H(a, E, th) + F_H(dh, E, th) * (d - dh) + E * a * (d - dh) ** 2


def en_depth(a, E, th, dg):
    """The depth at which a is in equilibrium: d/da [U - pi a^2 Delta gamma] = 0, the root
    below d_H(a) (adhesion pulls the surface up)."""
    def cond(d):
        return mp.diff(lambda x: energy(x, d, E, th), a) - 2 * mp.pi * a * dg
    dh = d_H(a, th)
    return mp.findroot(cond, (dh - 4 * mp.sqrt(2 * mp.pi * a * dg / E), dh), solver="anderson")


def en_force(a, E, th, dg):
    """F = dU/dd at the equilibrium depth."""
    d = en_depth(a, E, th, dg)
    return mp.diff(lambda x: energy(a, x, E, th), d)


def en_a_dc(E, th, dg):
    """The depth-controlled pull-off radius: dd/da = 0 of en_depth, bracketed (dd/da < 0 at
    small a, where the adhesive term sqrt(a) dominates, > 0 at large a)."""
    guess = dg / (E * mp.tan(th) ** 2)
    return mp.findroot(lambda a: mp.diff(lambda x: en_depth(x, E, th, dg), a),
                       (guess / 10, guess * 10), solver="anderson")


def test_energy_route_integral():
    """U_H's closed form is the integral of (5.40) (mpmath.quad at 30 digits)."""
    with mp.workdps(DPS):
        a, E, th = mp.mpf("3e-7"), mp.mpf(E_TRUE), mp.mpf(THETA)
        ref = mp.quad(lambda x: F_H(x, E, th), [0, d_H(a, th)])
        assert abs(U_H(a, E, th) / ref - 1) < mp.mpf(10) ** -25


def en_radius(d, E, th, dg, a_dc):
    """a on the branch a > a_dc at the depth d."""
    hi = mp.mpf(a_dc) * 2
    while en_depth(hi, E, th, dg) < d:
        hi *= 2
    return mp.findroot(lambda a: en_depth(a, E, th, dg) - d, (a_dc * (1 + mp.mpf(10)**-12), hi),
                       solver="anderson")


# --- the generated relations -------------------------------------------------------------
def test_adhesive_cone_model_by_mpmath_parametric():
    """fit_adhesive_cone_depth and fit_adhesive_cone_force against the energy route at 30
    digits, over decades of E*, theta, Delta gamma, a."""
    rng = np.random.default_rng(0)
    worst = 0.0
    for _ in range(n_cases := 25):
        E = 10 ** rng.uniform(4, 11)
        th = rng.uniform(0.05, 1.4)
        dg = 10 ** rng.uniform(-4, 0)
        a = 10 ** rng.uniform(-9, -4)
        z, F0, s0 = rng.uniform(-1e-6, 1e-6), rng.uniform(-1e-9, 1e-9), rng.uniform(-1, 1)
        with mp.workdps(DPS):
            d_ref = en_depth(mp.mpf(a), E, mp.mpf(th), dg)
            F_ref = en_force(mp.mpf(a), E, mp.mpf(th), dg) + F0 + s0 * mp.mpf(z)
            # rounding is relative to the largest term of each difference
            dl = float(mp.sqrt(2 * mp.pi * a * dg / E))
            d_scale = float(d_H(a, th)) + dl
            F_scale = float(mp.pi / 2 * E * mp.tan(th) * a**2) + 2 * E * a * dl \
                + abs(F0) + abs(s0 * z)
        d_num = gen.fit_adhesive_cone_depth(E, th, a, math.sqrt(dg))
        F_num = gen.fit_adhesive_cone_force(E, th, a, math.sqrt(dg), z, F0, s0)
        worst = max(worst, float(abs(d_num - d_ref)) / d_scale,
                    float(abs(F_num - F_ref)) / F_scale)
    assert n_cases == 25
    # a few roundings of terms of the size of the largest, and tan(theta) (1 ulp each)
    assert worst < 2e-15, worst


def test_adhesive_cone_pull_off_by_the_energy_route():
    """The generated depth-controlled pull-off (adhesion_cone_pull_off_radius_dc, the depth
    there) against the minimum of the energy route's d(a), at 30 digits."""
    with mp.workdps(DPS):
        a_dc = en_a_dc(E_TRUE, mp.mpf(THETA), DG_TRUE)
        d_dc = en_depth(a_dc, E_TRUE, mp.mpf(THETA), DG_TRUE)
    a_num, d_num = fa._jump_off_radius(E_TRUE, fa._family(TIP), math.sqrt(DG_TRUE))
    # the generated closed forms round to a few ulp; mpmath's root is good to ~1e-25
    assert a_num == pytest.approx(float(a_dc), rel=1e-14)
    assert d_num == pytest.approx(float(d_dc), rel=1e-14)


def test_adhesive_cone_radius_by_mpmath():
    """Newton on the generated d(a) against mpmath.findroot on the energy route, from next to
    the jump-off to deep contact; NaN past the jump-off; a = 2 d/(pi tan(theta)) without
    adhesion (5.38)."""
    fam = fa._family(TIP)
    rho = math.sqrt(DG_TRUE)
    a_c, d_c = fa._jump_off_radius(E_TRUE, fam, rho)
    ds = d_c + np.r_[np.geomspace(1e-8, 1e-2, 4) * abs(d_c), 0.5 * abs(d_c),
                     np.geomspace(abs(d_c), 100 * abs(d_c), 3)]
    a = fa._contact_radius(ds, fam, E_TRUE, rho)
    with mp.workdps(DPS):
        a_dc = en_a_dc(E_TRUE, mp.mpf(THETA), DG_TRUE)
        for di, ai in zip(ds, a, strict=True):
            ref = en_radius(mp.mpf(di), E_TRUE, mp.mpf(THETA), DG_TRUE, a_dc)
            tol = radius_tolerance(lambda x: en_depth(x, E_TRUE, mp.mpf(THETA), DG_TRUE),
                                   lambda x: d_H(x, THETA), ref, a_dc, di, d_c, E_TRUE,
                                   DG_TRUE)
            assert abs(ai - float(ref)) <= tol, (di, ai, float(ref), tol)
    check_radius_beyond_and_without_adhesion(  # (5.38)
        fam, d_c, rho, E_TRUE, lambda di: 2 * di / (np.pi * np.tan(THETA)), rel=1e-15)


def mp_model(E, z0, dg, z, a_lo):
    """The tip's force at the position z by the energy route, on the branch a > a_lo (the
    pull-off radius at the truth: the roots differentiated lie far above it)."""
    return en_force(en_radius(z - z0, E, mp.mpf(THETA), dg, a_lo), E, mp.mpf(THETA), dg)


def test_adhesive_cone_jacobian_by_mpmath_derivative():
    """dF/dE*, dF/dz_0, dF/dDelta gamma (SymPy's implicit differentiation, generated) against
    mpmath.diff of the energy route's curve at fixed positions, at 30 digits; and
    dF/dDelta gamma -> -4 a/tan(theta) as Delta gamma -> 0."""
    fam = fa._family(TIP)
    rho = math.sqrt(DG_TRUE)
    a_c, _ = fa._jump_off_radius(E_TRUE, fam, rho)
    worst = 0.0
    with mp.workdps(DPS):
        E, z0, dg = mp.mpf(E_TRUE), mp.mpf(Z0_TRUE), mp.mpf(DG_TRUE)
        lo = en_a_dc(E, mp.mpf(THETA), dg)
        for t in (1.3, 4.0):
            a = a_c * t
            z = float(Z0_TRUE + en_depth(mp.mpf(a), E, mp.mpf(THETA), dg))
            refs = (mp.diff(lambda x, z=z: mp_model(x, z0, dg, z, lo), E),
                    mp.diff(lambda x, z=z: mp_model(E, x, dg, z, lo), z0),
                    mp.diff(lambda x, z=z: mp_model(E, z0, x, z, lo), dg))
            a_num = float(fa._contact_radius(np.array([z - Z0_TRUE]), fam, E_TRUE, rho)[0])
            nums = (fam.dE(E_TRUE, a_num, rho), fam.dz0(E_TRUE, a_num, rho),
                    fam.ddgamma(E_TRUE, a_num, rho))
            for num, ref in zip(nums, refs, strict=True):
                worst = max(worst, float(abs(num - ref) / abs(ref)))
    # the derivatives carry 1/(dd/da) (condition ~10 at 1.3 a_dc) on a of ~1e-15, and the
    # position z is rounded to a double (the slope dF/dz times its ulp): 1e-11 leaves room
    # without hiding a wrong term (a wrong factor is O(1))
    assert worst < 1e-11, worst
    a0 = 2 * 5e-8 / (np.pi * np.tan(THETA))
    assert fam.ddgamma(E_TRUE, a0, 0.0) == pytest.approx(-4 * a0 / np.tan(THETA), rel=1e-14)


# --- fits ------------------------------------------------------------------------------------
def forward_curve(n=400, truth=TRUTH, noise=0.0, seed=0):
    """A retract curve by the forward numeric/adhesion.py (AdhesiveContact of a Cone under
    depth control): test_fit_jkr's set-up with the cone."""
    return jkr_forward_curve(n, truth, noise, seed, shape=adhesion.Cone(theta=THETA))


def test_noise_free_recovery():
    """A noise-free curve by the forward model: every parameter to <= 1e-10 relative (z_0 to
    1e-10 of the deepest indentation, the baseline's to 1e-10 of the force range)."""
    z, F = forward_curve()
    res = fa.fit_curve(z, F, TIP)
    span = float(np.ptp(F))
    assert res.values[0] == pytest.approx(E_TRUE, rel=1e-10)
    assert abs(res.values[1] - Z0_TRUE) <= 1e-10 * 150e-9
    assert res.values[2] == pytest.approx(DG_TRUE, rel=1e-10)
    assert abs(res.values[3] + res.values[4] * Z0_TRUE - F0_TRUE - S0_TRUE * Z0_TRUE) \
        <= 1e-10 * span
    assert res.jump_off is not None and res.z_split is not None
    assert "cone, adhesive" in res.tip.describe()


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


@pytest.mark.sweep
def test_coverage_of_standard_errors():
    """The truth within one reported standard error in ~68.3 % of noisy curves, per parameter.

    Binomial(m, 0.683): standard deviation sqrt(0.683 0.317/m) (0.060 at m = 60, 0.015 at
    m = 1000); the tolerance of 3.5 of them makes a false failure a 5e-4 event per parameter.
    Noise 1 % of the depth-controlled pull-off force, 200 points (the same curve per seed, by
    the forward numeric/adhesion.py, new noise each).
    """
    m = n_points(1000, 60)
    z, F = forward_curve(n=200)
    c = adhesion.AdhesiveContact(adhesion.Cone(theta=THETA), E_star=E_TRUE, dgamma=DG_TRUE)
    noise = 0.01 * abs(c.pull_off("depth").force)
    inside = np.zeros(5)
    for seed in range(m):
        Fn = F + np.random.default_rng(seed).normal(0.0, noise, z.size)
        res = fa.fit_curve(z, Fn, TIP, sigma=noise)
        inside += np.abs(res.values - TRUTH) <= res.errors
    frac = inside / m
    tol = 3.5 * math.sqrt(0.6827 * 0.3173 / m)
    assert np.all(np.abs(frac - 0.6827) <= tol), (frac, tol)


def test_non_adhesive_cone_curve_gives_zero_work():
    """The cone's approach curve (5.40) without adhesion: Delta gamma = 0 within its error,
    E* and z_0 as the fit without adhesion."""
    z = np.linspace(Z0_TRUE - 1e-7, Z0_TRUE + 1e-7, 300)
    F = gen.fit_cone_force(E_TRUE, THETA, z, Z0_TRUE, F0_TRUE, S0_TRUE)
    res = fa.fit_curve(z, F, TIP)
    assert abs(res.values[2]) <= max(res.errors[2], 1e-12)
    assert res.values[0] == pytest.approx(E_TRUE, rel=1e-9)


def test_other_tips_are_one_clear_error():
    with pytest.raises(ValueError, match="has no adhesive fit model; valid: a Paraboloid"):
        fa.fit_curve(np.linspace(0, 1, 10), np.linspace(0, 1, 10), hfit.FlatPunch(a=1e-6))


def test_cli_fits_a_cone_with_adhesion(tmp_path, capsys):
    """``hertzmdr fit --adhesion`` with a cone scene: exit 0, the work of adhesion within 4
    standard errors of the truth."""
    z, F0 = forward_curve()
    sigma = 5e-3 * float(np.ptp(F0))
    z, F = forward_curve(noise=sigma, seed=5)
    cli_adhesive_fit(tmp_path, capsys, z, F, sigma, f'shape = "cone"\nangle = {THETA}',
                     "cone, adhesive")
