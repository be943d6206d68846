"""The adhesive fit of a power-law tip's retract curve (hertzmdr.numeric.fit_adhesive,
derive/fit.py's adhesive_powerlaw_model).

Independent route: the energy method of test_fit_adhesive_sphere.py (Johnson's: the
non-adhesive state plus a flat punch, Griffith's balance at a fixed depth, by mpmath.diff and
findroot at 30 digits), with the power law's non-adhesive d_H(a) = kappa_n c_n a^n (kappa_n from
its Gamma functions) and F_H(a) = 2 E* integral_0^a (d_H(a) - kappa_n c_n x^n) dx (mpmath.quad
in test_energy_route_integral, then its closed value). Synthetic curves by the forward
numeric/adhesion.py (AdhesiveContact of its PowerLaw).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from test_fit_adhesive_sphere import (
    DG_TRUE,
    DPS,
    E_TRUE,
    TRUTH,
    Z0_TRUE,
    EnergyRoute,
    check_coverage,
    coverage,
    forward_curve,
    jacobian_check,
)
from test_fit_jkr import (
    check_radius_beyond_and_without_adhesion,
    cli_adhesive_fit,
    radius_tolerance,
)

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import adhesion
from hertzmdr.numeric import fit as hfit
from hertzmdr.numeric import fit_adhesive as fa

from oracle import n_points

C_N, N = 250.0, 1.5  # f = c_n r^n [m]: at r = 0.5 um, f = 88 nm
DEPTH = 150e-9  # m
TIP = hfit.PowerLaw(c_n=C_N, n=N)
SHAPE = adhesion.PowerLaw(c_n=C_N, n=N)


def kappa(n):
    n = mp.mpf(n)
    return mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)  # (5.52)


def route(c, n):
    c, n = mp.mpf(c), mp.mpf(n)
    k = kappa(n)
    return EnergyRoute(lambda a: k * c * a**n,
                       lambda a, E: 2 * E * k * c * a ** (n + 1) * n / (n + 1))


def test_energy_route_integral():
    """F_H's closed value is 2 E* integral_0^a (d_H(a) - g(x)) dx (mpmath.quad at 30 digits)."""
    with mp.workdps(DPS):
        a, E, c, n = mp.mpf("3e-7"), mp.mpf(E_TRUE), mp.mpf(C_N), mp.mpf(N)
        k = kappa(n)
        ref = 2 * E * mp.quad(lambda x: k * c * a**n - k * c * x**n, [0, a])
        assert abs(route(C_N, N).F_H(a, E) / ref - 1) < mp.mpf(10) ** -25


def _a_dc(E, dg):
    return float(gen.adhesion_powerlaw_pull_off_radius_dc(E, dg, C_N, TIP.kappa_n, N))


def test_adhesive_powerlaw_model_by_mpmath_parametric():
    """fit_adhesive_powerlaw_depth and fit_adhesive_powerlaw_force against the energy route at
    30 digits, over decades of E*, c_n, Delta gamma, a and n from 0.6 to 6."""
    rng = np.random.default_rng(0)
    worst = 0.0
    for _ in range(n_cases := 16):
        E = 10 ** rng.uniform(4, 11)
        n = rng.uniform(0.6, 6.0)
        a = 10 ** rng.uniform(-8, -5)
        c = 10 ** rng.uniform(-1, 1) * 0.3 * a ** (1 - n)  # f(a) ~ 0.3 a
        dg = 10 ** rng.uniform(-4, 0)
        z, F0, s0 = rng.uniform(-1e-6, 1e-6), rng.uniform(-1e-9, 1e-9), rng.uniform(-1, 1)
        k = float(kappa(n))
        rt = route(c, n)
        with mp.workdps(DPS):
            am = mp.mpf(a)
            d_ref = rt.depth(am, E, dg)
            F_ref = rt.force(am, E, dg) + F0 + s0 * mp.mpf(z)
            dl = float(mp.sqrt(2 * mp.pi * am * dg / E))
            d_scale = float(rt.d_H(am)) + dl
            F_scale = float(rt.F_H(am, E)) + 2 * E * a * dl + abs(F0) + abs(s0 * z)
        d_num = gen.fit_adhesive_powerlaw_depth(E, c, k, n, a, math.sqrt(dg))
        F_num = gen.fit_adhesive_powerlaw_force(E, c, k, n, a, math.sqrt(dg), z, F0, s0)
        worst = max(worst, float(abs(d_num - d_ref)) / d_scale,
                    float(abs(F_num - F_ref)) / F_scale)
    assert n_cases == 16
    # a few roundings of terms of the size of the largest; a^n rounds to ~n ulp of a's
    # (a^n = exp(n log a): the ulp of n log a, |n log a| < 100, is ~1e-14 relative); kappa_n
    # is rounded to a double: 3e-14
    assert worst < 3e-14, worst


def test_adhesive_powerlaw_radius_by_mpmath():
    """Newton on the generated d(a) against mpmath.findroot on the energy route, from next to
    the jump-off to deep contact; the generated pull-off radius against the route's; NaN past
    the jump-off; a(d) without adhesion from d = kappa_n c_n a^n."""
    fam = fa._family(TIP)
    rho = math.sqrt(DG_TRUE)
    a_c, d_c = fa._jump_off_radius(E_TRUE, fam, rho)
    rt = route(C_N, N)
    with mp.workdps(DPS):
        a_dc = rt.a_dc(E_TRUE, DG_TRUE, a_c / 2, a_c * 2)
        assert a_c == pytest.approx(float(a_dc), rel=1e-13)
    ds = d_c + np.r_[np.geomspace(1e-8, 1e-2, 4) * abs(d_c), 0.5 * abs(d_c),
                     np.geomspace(abs(d_c), 100 * abs(d_c), 3)]
    a = fa._contact_radius(ds, fam, E_TRUE, rho)
    with mp.workdps(DPS):
        for di, ai in zip(ds, a, strict=True):
            ref = rt.radius(mp.mpf(di), E_TRUE, DG_TRUE, a_dc)
            # and a^n's rounding (n ulp)
            tol = radius_tolerance(lambda x: rt.depth(x, E_TRUE, DG_TRUE), rt.d_H, ref, a_dc,
                                   di, d_c, E_TRUE, DG_TRUE, rounding=8e-16)
            assert abs(ai - float(ref)) <= tol, (di, ai, float(ref), tol)
    check_radius_beyond_and_without_adhesion(
        fam, d_c, rho, E_TRUE, lambda di: (mp.mpf(di) / (kappa(N) * C_N)) ** (1 / mp.mpf(N)))


def test_adhesive_powerlaw_jacobian_by_mpmath_derivative():
    """dF/dE*, dF/dz_0, dF/dDelta gamma (SymPy's implicit differentiation, generated) against
    mpmath.diff of the energy route's curve at fixed positions, at 30 digits; and
    dF/dDelta gamma -> -2 pi a/g'(a) as Delta gamma -> 0."""
    rt = route(C_N, N)
    worst = jacobian_check(TIP, rt, (1.3, 4.0),
                           lambda E, dg: rt.a_dc(E, dg, _a_dc(E_TRUE, DG_TRUE) / 2,
                                                 _a_dc(E_TRUE, DG_TRUE) * 2))
    # as the sphere's and the cone's (1/(dd/da) ~ 10 at 1.3 a_dc on a of ~1e-15)
    assert worst < 1e-11, worst
    fam = fa._family(TIP)
    a0 = 3e-7
    with mp.workdps(DPS):
        ref = float(-2 * mp.pi * a0 / mp.diff(rt.d_H, mp.mpf(a0)))
    assert fam.ddgamma(E_TRUE, a0, 0.0) == pytest.approx(ref, rel=1e-14)


def test_noise_free_recovery():
    """A noise-free curve by the forward model: every parameter to <= 1e-10 relative."""
    z, F = forward_curve(shape=SHAPE, depth=DEPTH)
    res = fa.fit_curve(z, F, TIP)
    span = float(np.ptp(F))
    assert res.values[0] == pytest.approx(E_TRUE, rel=1e-10)
    assert abs(res.values[1] - Z0_TRUE) <= 1e-10 * DEPTH
    assert res.values[2] == pytest.approx(DG_TRUE, rel=1e-10)
    assert abs(res.values[3] + res.values[4] * Z0_TRUE - TRUTH[3] - TRUTH[4] * Z0_TRUE) \
        <= 1e-10 * span
    assert res.jump_off is not None and res.z_split is not None
    assert "power law f = c_n r^n, adhesive" in res.tip.describe()


@pytest.mark.sweep
def test_coverage_of_standard_errors():
    """The truth within one reported standard error in ~68.3 % of 1000 noisy curves (25 in
    CI: ~10 s)."""
    m = n_points(1000, 25)
    check_coverage(coverage(TIP, SHAPE, m, depth=DEPTH), m)


def test_power_law_without_pull_off_is_one_clear_error():
    with pytest.raises(ValueError, match=r"n = 0.5 has no adhesive pull-off.*valid for the "
                       r"adhesive fit: n > 1/2"):
        fa.fit_curve(np.linspace(0, 1, 10), np.linspace(0, 1, 10), hfit.PowerLaw(c_n=1, n=0.5))


def test_cli_fits_a_power_law_with_adhesion(tmp_path, capsys):
    """``hertzmdr fit --adhesion`` with a power_law scene: exit 0, the work of adhesion within
    4 standard errors of the truth."""
    z, F0 = forward_curve(shape=SHAPE, depth=DEPTH)
    sigma = 5e-3 * float(np.ptp(F0))
    z, F = forward_curve(noise=sigma, seed=5, shape=SHAPE, depth=DEPTH)
    cli_adhesive_fit(tmp_path, capsys, z, F, sigma,
                     f'shape = "power_law"\ncoefficient = {C_N}\nexponent = {N}',
                     "power law f = c_n r^n, adhesive")
