"""The adhesive fit of a sampled (measured) tip's retract curve (hertzmdr.numeric.fit_adhesive
with a SampledTip; derive/fit.py's adhesive_general_model, the adhesive MDR of any g).

Independent routes: the energy method at 30 digits (test_fit_adhesive_sphere.py's EnergyRoute:
Griffith's equilibrium of the non-adhesive state plus a flat punch, not the MDR's critical
elongation) of the paraboloid (d_H = a^2/R, F_H = 4 E* a^3/(3R)) and of the cap (Sneddon's);
the cap's g, g' and G by mpmath (atanh, quad). Synthetic curves by the closed-form forward
models of numeric/adhesion.py (AdhesiveContact of its Paraboloid, Sphere).

Sampled tips: the paraboloid sampled by a quintic spline (the default k = 5) is reproduced
exactly (a polynomial of degree <= 5), so its g, g', G are the paraboloid's to the quadrature's
rounding and the fit must find the truth as the closed-form fits do; the cap is not a
polynomial, and the fit's error must stay within the profile's own error bound
(Profile.g(..., return_error=True)) carried into the parameters.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from test_fit_adhesive_sphere import (  # the same truth, tip radius and depth as the cap's
    DEPTH,
    DG_TRUE,
    DPS,
    E_TRUE,
    R_TIP,
    TRUTH,
    EnergyRoute,
    assert_recovered,
    cap_cases,
    jacobian_check,
    route,
    sneddon_depth,
    sphere_a_dc,
)
from test_fit_jkr import forward_curve as jkr_forward_curve

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import adhesion
from hertzmdr.numeric import fit as hfit
from hertzmdr.numeric import fit_adhesive as fa
from hertzmdr.numeric.cli import main

R_MAX = 0.9 * R_TIP  # m: the samples' extent


def sampled(profile, n, r_max=R_MAX):
    r = np.linspace(0.0, r_max, n)
    return hfit.SampledTip.from_samples(r, profile(r))


def paraboloid(r):
    return r**2 / (2 * R_TIP)


def cap(r):
    return R_TIP - np.sqrt(R_TIP**2 - r**2)


PARABOLOID_TIP = sampled(paraboloid, 41)


def jkr_route(R):
    Rm = mp.mpf(R)
    return EnergyRoute(lambda a: a**2 / Rm, lambda a, E: 4 * E * a**3 / (3 * Rm))


def forward_curve(shape, n=400, depth=DEPTH):
    """A noise-free retract curve of ``shape`` by the closed-form forward model (test_fit_jkr's,
    depth control): contact down to the jump-off, then the baseline."""
    return jkr_forward_curve(n, TRUTH, 0.0, 0, shape, depth)


# --- the generated relations -------------------------------------------------------------
def test_adhesive_sampled_model_by_mpmath_parametric():
    """fit_adhesive_sampled_depth and _force, given the cap's g(a) = a atanh(a/R), g' and
    G = integral_0^a g by mpmath, against the energy route of the cap at 30 digits, over
    decades of E*, R, Delta gamma and a/R from 1e-3 to 0.95."""
    rng = np.random.default_rng(1)
    worst = 0.0
    for E, R, dg, a, z, F0, s0 in cap_cases(rng, n_cases := 12):
        rt = route(R)
        with mp.workdps(DPS):
            am, Rm = mp.mpf(a), mp.mpf(R)
            g = am * mp.atanh(am / Rm)
            gp = mp.diff(lambda x, Rm=Rm: x * mp.atanh(x / Rm), am)
            G = mp.quad(lambda x, Rm=Rm: x * mp.atanh(x / Rm), [0, am])
            d_ref = rt.depth(am, E, dg)
            F_ref = rt.force(am, E, dg) + F0 + s0 * mp.mpf(z)
            dl = float(mp.sqrt(2 * mp.pi * am * dg / E))
            d_scale = float(g) + dl
            # F = 2 E* (a g - G) - 2 E* a Delta l: rounding relative to its largest terms
            F_scale = 2 * E * (a * float(g) + float(G) + a * dl) + abs(F0) + abs(s0 * z)
        args = (E, float(g), float(gp), float(G), a, math.sqrt(dg))
        d_num = gen.fit_adhesive_sampled_depth(*args)
        F_num = gen.fit_adhesive_sampled_force(*args, z, F0, s0)
        worst = max(worst, float(abs(d_num - d_ref)) / d_scale,
                    float(abs(F_num - F_ref)) / F_scale)
    assert n_cases == 12
    # g, g', G rounded to doubles (1 ulp each) and a few roundings of terms of the largest
    # size; a 1e-14 bound leaves room without hiding a wrong term (each is O(1) of the scale)
    assert worst < 1e-14, worst


def test_adhesive_sampled_radius_by_mpmath():
    """The sampled paraboloid's pull-off radius (first root of dd/da on the quadrature's g')
    and its contact radius on the branch a > a_dc against the JKR energy route at 30 digits;
    NaN past the jump-off."""
    fam = fa._family(PARABOLOID_TIP)
    rho = math.sqrt(DG_TRUE)
    a_c, d_c = fa._jump_off_radius(E_TRUE, fam, rho)
    rt = jkr_route(R_TIP)
    a_jkr = float(gen.jkr_pull_off_radius_dc(E_TRUE, DG_TRUE, R_TIP))
    with mp.workdps(DPS):
        a_ref = rt.a_dc(mp.mpf(E_TRUE), mp.mpf(DG_TRUE), a_jkr / 2, 2 * a_jkr)
        d_ref = rt.depth(a_ref, mp.mpf(E_TRUE), mp.mpf(DG_TRUE))
    # Brent's method to 4 ulp of a on g' of the quadrature (rounding ~1e-15 relative of g'):
    # at the root dd/da = 0 the error of a is that of g' over d2d/da2 a / g' ~ 1 (JKR), 1e-13
    # leaves room; d is flat in a there, to its rounding
    assert a_c == pytest.approx(float(a_ref), rel=1e-13)
    assert d_c == pytest.approx(float(d_ref), rel=1e-13)
    ds = d_c + np.r_[np.geomspace(1e-6, 1e-2, 3) * abs(d_c), 0.5 * abs(d_c),
                     np.geomspace(abs(d_c), 4 * abs(d_c), 3)]  # a < r_max = 0.9 R
    a = fa._contact_radius(ds, fam, E_TRUE, rho)
    with mp.workdps(DPS):
        curv = float(mp.diff(lambda x: rt.depth(x, E_TRUE, DG_TRUE), a_ref, 2))
        for di, ai in zip(ds, a, strict=True):
            ref = rt.radius(mp.mpf(di), E_TRUE, DG_TRUE, a_ref, mp.mpf(R_MAX))
            slope = float(mp.diff(lambda x: rt.depth(x, E_TRUE, DG_TRUE), ref))
            scale = float(ref**2 / R_TIP) + float(mp.sqrt(2 * mp.pi * ref * DG_TRUE / E_TRUE))
            # as the closed-form sphere's: the solver stops at the rounding of d(a) - d_dc
            # (4 ulp of each of its terms; 2x here, and the quadrature's g to 4 ulp more):
            # a to it over the slope, at the fold to sqrt(2 err/d'')
            err = 12 * 2.2e-16 * (scale + 2 * abs(d_c) + abs(di))
            tol = min(err / max(abs(slope), 1e-300), math.sqrt(2 * err / curv))
            tol += 4e-16 * float(ref)
            assert abs(ai - float(ref)) <= tol, (di, ai, float(ref), tol)
    assert np.isnan(fa._contact_radius(np.array([2 * d_c]), fam, E_TRUE, rho)).all()
    assert fam.a_dc(E_TRUE, 0.0) == 0.0


def test_adhesive_sampled_jacobian_by_mpmath_derivative():
    """dF/dE*, dF/dz_0, dF/dDelta gamma of the sampled paraboloid (the generated implicit
    Jacobian at the quadrature's g, g', G) against mpmath.diff of the JKR energy route's curve
    F(z) at fixed positions (a = 1.3 and 4 a_dc); and of the sampled cap (81 samples) against
    the cap's energy route, to the profile's error."""
    rt = jkr_route(R_TIP)

    def a_lo(E, dg):
        return rt.a_dc(E, dg, 0.5 * float(gen.jkr_pull_off_radius_dc(float(E), float(dg),
                                                                        R_TIP)),
                       2 * float(gen.jkr_pull_off_radius_dc(float(E), float(dg), R_TIP)))

    worst = jacobian_check(PARABOLOID_TIP, rt, (1.3, 4.0), a_lo, mp.mpf(R_MAX))
    # as the closed-form tips': 1/(dd/da) (condition ~10 at 1.3 a_dc) on a of ~1e-15, the
    # position rounded to a double, g' of the quadrature to ~1e-15: 1e-11 leaves room without
    # hiding a wrong term (each is O(1))
    assert worst < 1e-11, worst
    cap_tip = sampled(cap, 81)
    rt_cap = route(R_TIP)
    worst = jacobian_check(cap_tip, rt_cap, (1.3, 4.0),
                           lambda E, dg: sphere_a_dc(rt_cap, E, dg, R_TIP), mp.mpf(R_MAX))
    # the cap sampled at 81 points: g to ~2e-11 relative (its true error; the bound
    # Profile.g reports is 5e-8), amplified by 1/(dd/da) ~ 10 at 1.3 a_dc: below the bound
    rel_bound = float(np.max(cap_tip.profile.g(np.linspace(0.05, 0.9, 18) * R_TIP,
                                               return_error=True)[1]
                             / cap_tip.profile.g(np.linspace(0.05, 0.9, 18) * R_TIP)))
    assert worst < 10 * rel_bound, (worst, rel_bound)
    assert worst > 1e-13  # the profile's error shows: this is the sampled cap, not the exact
    fam = fa._family(PARABOLOID_TIP)
    a0 = 0.3 * R_TIP
    # dF/dDelta gamma -> -2 pi a/g'(a) = -pi R at Delta gamma = 0 (the paraboloid's g' = 2a/R)
    assert fam.ddgamma(E_TRUE, a0, 0.0) == pytest.approx(-math.pi * R_TIP, rel=1e-13)


# --- fits ------------------------------------------------------------------------------------
def test_noise_free_recovery_sampled_paraboloid():
    """A noise-free JKR curve (closed form) fitted with the sampled paraboloid (exact to
    rounding, see the module's docstring): every parameter to <= 1e-10 relative, as the
    closed-form tips' (z_0 to 1e-10 of the depth, the baseline to 1e-10 of the force range)."""
    z, F = forward_curve(adhesion.Paraboloid(R=R_TIP))
    res = fa.fit_curve(z, F, PARABOLOID_TIP)
    assert_recovered(res, F)
    assert "sampled tip, adhesive" in res.tip.describe()
    assert not res.warnings, res.warnings


def profile_error_bound(res, tip):
    """The parameters' error bound [their units] from the sampled profile's error bound
    eps_g(a) (Profile.g, return_error): at a fixed position the force changes by
    dF = 2 E* (a dg - dG) - (dF/dd) dg to first order (d fixed, a moves along dd/da), with
    |dG(a)| <= a max_{x<=a} eps_g and dF/dd = -dF/dz_0, so |dF_i| <= 4 E* a max eps_g
    + |dF/dz_0| eps_g; a noise-free least-squares fit moves its parameters by J^+ dF,
    bounded by |J^+| |dF|."""
    fam = fa._family(tip)
    E_s, z_0, dgamma = res.values[:3]
    model = fa._Model(fam, res.z, fa._Layout(res.z_split or -np.inf, res.used))
    a = model.state(E_s, z_0, dgamma)[0]
    on = np.isfinite(a) & res.used
    eps = np.zeros(res.z.size)
    eps[on] = tip.profile.g(a[on], return_error=True)[1]
    J = fa._jac(model, res.z, np.ones(res.z.size), np.ones(res.z.size, bool), res.values)
    dF = np.where(on, 4 * E_s * np.nan_to_num(a) * np.maximum.accumulate(eps)
                  + np.abs(J[:, 1]) * eps, 0.0)
    return np.abs(np.linalg.pinv(J[res.used])) @ dF[res.used]


@pytest.mark.parametrize("n_samples", [21, 41])
def test_recovery_within_the_profile_error(n_samples):
    """A noise-free curve of the exact sphere (closed-form forward model), fitted with the cap
    sampled at 21 or 41 points: each parameter within the profile's error bound carried into
    the parameters (profile_error_bound, first order); the error is that of the samples, not
    the solver's (above 1e-10 of E* at 21 samples, where the cap's spline is off by ~5e-6)."""
    tip = sampled(cap, n_samples)
    z, F = forward_curve(adhesion.Sphere(R=R_TIP))
    res = fa.fit_curve(z, F, tip)
    bound = profile_error_bound(res, tip)
    err = np.abs(res.values - TRUTH)
    assert np.all(err <= bound), (err, bound)
    if n_samples == 21:
        assert err[0] > 1e-10 * E_TRUE  # the test sees the samples' error
    # the bound is meaningful: E* to < 1 % of itself at 21 samples
    assert bound[0] < 1e-2 * E_TRUE, bound


def test_too_deep_for_the_samples_is_one_clear_error():
    """A curve deeper than the samples reach (r_max = 0.3 R: g(r_max) ~ 90 nm < 300 nm)."""
    tip = sampled(cap, 41, r_max=0.3 * R_TIP)
    z, F = forward_curve(adhesion.Sphere(R=R_TIP), n=60)
    with pytest.raises(ValueError, match=r"^the indentation d = .* is deeper than the sampled "
                                         r"tip reaches: .*valid: d < ") as info:
        fa.fit_curve(z, F, tip)
    assert "\n" not in str(info.value)


def test_cli_fits_a_profile_with_adhesion(tmp_path, capsys):
    """``hertzmdr fit --adhesion`` with a scene's ``profile`` tip (the sampled paraboloid):
    exit 0, the work of adhesion of a noise-free JKR curve to 1e-8."""
    z, F = forward_curve(adhesion.Paraboloid(R=R_TIP))
    curve = tmp_path / "retract.csv"
    rows = zip(z.tolist(), F.tolist(), strict=True)
    curve.write_text("z [m], F [N]\n" + "".join(f"{a!r}, {b!r}\n" for a, b in rows))
    r = np.linspace(0.0, R_MAX, 41)
    scene = tmp_path / "tip.toml"
    scene.write_text('effects = ["force"]\n[[body]]\nshape = "profile"\n'
                     f"r = {r.tolist()!r}\nf = {paraboloid(r).tolist()!r}\nrigid = true\n"
                     '[[body]]\nshape = "flat"\nE = "1.5 MPa"\nnu = 0.5\n'
                     '[load]\ndepth = "100 nm"\n')
    assert main(["fit", str(curve), "--scene", str(scene), "--adhesion"]) == 0
    out = capsys.readouterr().out
    assert "sampled tip, adhesive" in out
    line = next(ln for ln in out.splitlines() if ln.startswith("dgamma "))
    # printed to 6-7 digits; the fit itself is at 1e-10 (test_noise_free_recovery_...)
    assert float(line.split()[1]) == pytest.approx(DG_TRUE, rel=1e-5), line


def test_sneddon_depth_is_the_caps_g():
    """The cap's g(a) = a atanh(a/R) (5.52) is Sneddon's depth: the two routes above agree."""
    with mp.workdps(DPS):
        a, R = mp.mpf("3e-7"), mp.mpf(R_TIP)
        assert abs(sneddon_depth(a, R) - a * mp.atanh(a / R)) < mp.mpf(10) ** -28 * a
