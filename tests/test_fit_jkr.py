"""The adhesive (JKR) fit of retract curves (hertzmdr.numeric.fit_adhesive, derive/fit.py).

Independent routes: the JKR curve as the literature prints it (Johnson, Kendall & Roberts 1971;
Maugis 2000), d = a^2/R - sqrt(2 pi a Delta gamma/E*), F = 4 E* a^3/(3R) -
sqrt(8 pi Delta gamma E* a^3), evaluated by mpmath at 30 digits (the package derives it from
the MDR's energy balance instead); a(d) by mpmath.findroot on the branch a > a_dc; the Jacobian
by mpmath.diff of that curve (numerical differentiation at 30 digits, not SymPy's implicit
differentiation); synthetic curves made by mpmath (parametric in a) and by the forward
numeric/adhesion.py (its own root finder on a uniform grid of positions).
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import adhesion, hertz
from hertzmdr.numeric import fit as hfit
from hertzmdr.numeric.cli import main
from hertzmdr.numeric.fit_adhesive import contact_radius, fit_curve
from tests.oracle import n_points

DPS = 30
R_TIP = 1e-6  # m: an AFM colloidal probe
E_TRUE = 2.0e6  # Pa: PDMS-like
DG_TRUE = 0.05  # J/m^2
Z0_TRUE = 1.3e-6  # m
F0_TRUE = 2.0e-9  # N
S0_TRUE = 1.0e-4  # N/m
TRUTH = np.array([E_TRUE, Z0_TRUE, DG_TRUE, F0_TRUE, S0_TRUE])
TIP = hfit.Paraboloid(R=R_TIP)
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
EXAMPLE_CURVE = EXAMPLES / "fit_jkr_retract.csv"
EXAMPLE_SCENE = EXAMPLES / "fit_jkr_retract.toml"


def lit_depth(a, E, R, dg):
    """JKR's depth as printed in the literature (mpmath)."""
    return a**2 / R - mp.sqrt(2 * mp.pi * a * dg / E)


def lit_force(a, E, R, dg):
    """JKR's force as printed in the literature (mpmath)."""
    return 4 * E * a**3 / (3 * R) - mp.sqrt(8 * mp.pi * dg * E * a**3)


def lit_a_dc(E, R, dg):
    """The depth-controlled pull-off radius: dd/da = 0 of lit_depth, by mpmath.findroot."""
    return mp.findroot(lambda a: mp.diff(lambda x: lit_depth(x, E, R, dg), a),
                       (R * (dg / (E * R)) ** (mp.mpf(1) / 3)))


def mp_radius(d, E, R, dg, a_dc):
    """a(d) on the branch a > a_dc: bisection-safe findroot in [a_dc, big]."""
    hi = mp.mpf(a_dc)
    while lit_depth(hi, E, R, dg) < d:
        hi *= 2
    return mp.findroot(lambda a: lit_depth(a, E, R, dg) - d, (a_dc, hi), solver="anderson")


def test_jkr_model_by_mpmath_parametric():
    """fit_jkr_depth and fit_jkr_force against the literature's JKR at 30 digits."""
    rng = np.random.default_rng(0)
    worst = 0.0
    for _ in range(200):
        E = 10 ** rng.uniform(4, 11)
        R = 10 ** rng.uniform(-8, -2)
        dg = 10 ** rng.uniform(-4, 0)
        a = R * 10 ** rng.uniform(-4, 0)
        z, F0, s0 = rng.uniform(-1e-6, 1e-6), rng.uniform(-1e-9, 1e-9), rng.uniform(-1, 1)
        with mp.workdps(DPS):
            d_ref = lit_depth(mp.mpf(a), E, R, dg)
            F_ref = lit_force(mp.mpf(a), E, R, dg) + F0 + s0 * mp.mpf(z)
            # each term's size: the rounding of a difference is relative to its largest term
            d_scale = a**2 / R + float(mp.sqrt(2 * mp.pi * a * dg / E))
            F_scale = 4 * E * a**3 / (3 * R) + float(mp.sqrt(8 * mp.pi * dg * E * a**3)) \
                + abs(F0) + abs(s0 * z)
            d_num = gen.fit_jkr_depth(E, R, a, math.sqrt(dg))
            F_num = gen.fit_jkr_force(E, R, a, math.sqrt(dg), z, F0, s0)
            worst = max(worst, float(abs(d_num - d_ref)) / d_scale,
                        float(abs(F_num - F_ref)) / F_scale)
    # a few roundings of terms of the size of the largest (the sqrt(dg) of the argument adds
    # one ulp): 1e-15 of the scale
    assert worst < 1e-15, worst


def test_jkr_radius_by_mpmath():
    """contact_radius (Newton on the generated d(a)) against mpmath.findroot at 30 digits, from
    next to the jump-off to deep contact; NaN past the jump-off."""
    E, R, dg = E_TRUE, R_TIP, DG_TRUE
    with mp.workdps(DPS):
        a_dc = lit_a_dc(E, R, dg)
        d_dc = float(lit_depth(a_dc, E, R, dg))
        ds = d_dc + np.r_[np.geomspace(1e-12, 1e-6, 40) * abs(d_dc), 0.5 * abs(d_dc),
                          np.geomspace(abs(d_dc), 100 * abs(d_dc), 20)]
        a = contact_radius(ds, R, E, math.sqrt(dg))
        for di, ai in zip(ds, a, strict=True):
            ref = mp_radius(mp.mpf(di), E, R, dg, a_dc)
            slope = float(mp.diff(lambda x: lit_depth(x, E, R, dg), ref))
            scale = float(ref**2 / R + mp.sqrt(2 * mp.pi * ref * dg / E))
            # the solver stops when d(a) - d_dc is at its rounding, 4 ulp of each of d(a),
            # d_dc, d (2x that here): a is then known to it over the slope d'(a), or, at the
            # fold (slope -> 0), to sqrt(2 * it / d''), whichever is smaller
            err = 8 * 2.2e-16 * (scale + 2 * abs(d_dc) + abs(di))
            tol = min(err / max(abs(slope), 1e-300), math.sqrt(2 * err / (2 / R)))
            tol += 4e-16 * float(ref)
            assert abs(ai - float(ref)) <= tol, (di, ai, float(ref), tol)
    past = contact_radius(np.array([d_dc * (1 + 1e-9), 2 * d_dc]), R, E, math.sqrt(dg))
    assert np.isnan(past).all()
    # without adhesion: Hertz's a = sqrt(R d) (5.22) and no contact at d <= 0
    d = np.array([-1e-9, 0.0, 1e-9, 1e-7])
    a0 = contact_radius(d, R, E, 0.0)
    assert np.isnan(a0[:2]).all()
    # both sides rounded (R d, its sqrt; the solver's d(a)): a few ulp
    np.testing.assert_allclose(a0[2:], np.sqrt(R * d[2:]), rtol=1e-15)


def mp_model(E, z0, dg, z, R=R_TIP):
    """The tip's force at position z (mpmath, parametric curve, branch a > a_dc)."""
    a_dc = lit_a_dc(E, R, dg)
    return lit_force(mp_radius(z - z0, E, R, dg, a_dc), E, R, dg)


def test_jkr_jacobian_by_mpmath_derivative():
    """dF/dE*, dF/dz_0, dF/dDelta gamma (SymPy's implicit differentiation, generated) against
    mpmath.diff of the literature's curve with a from findroot, at 30 digits."""
    worst = 0.0
    with mp.workdps(DPS):
        a_dc = float(lit_a_dc(E_TRUE, R_TIP, DG_TRUE))
        E, z0, dg = mp.mpf(E_TRUE), mp.mpf(Z0_TRUE), mp.mpf(DG_TRUE)
        for t in (1.05, 1.3, 2.0, 4.0, 10.0):
            a = a_dc * t
            z = float(Z0_TRUE + lit_depth(mp.mpf(a), E_TRUE, R_TIP, DG_TRUE))
            refs = (mp.diff(lambda x, z=z: mp_model(x, z0, dg, z), E),
                    mp.diff(lambda x, z=z: mp_model(E, x, dg, z), z0),
                    mp.diff(lambda x, z=z: mp_model(E, z0, x, z), dg))
            a_num = float(contact_radius(np.array([z - Z0_TRUE]), R_TIP, E_TRUE,
                                         math.sqrt(DG_TRUE))[0])
            rho = math.sqrt(DG_TRUE)
            nums = (gen.fit_jkr_force_dE(E_TRUE, R_TIP, a_num, rho),
                    gen.fit_jkr_force_dz0(E_TRUE, R_TIP, a_num, rho),
                    gen.fit_jkr_force_ddgamma(E_TRUE, R_TIP, a_num, rho))
            for num, ref in zip(nums, refs, strict=True):
                worst = max(worst, float(abs(num - ref) / abs(ref)))
    # the derivatives carry 1/(dd/da): at a = 1.05 a_dc the condition is ~20, so the ~1e-15
    # of a and of the terms grows to ~1e-13; 1e-11 leaves room without hiding a wrong term
    assert worst < 1e-11, worst
    # Delta gamma -> 0: dF/dDelta gamma = -pi R (the sqrt(Delta gamma) terms cancel)
    with mp.workdps(DPS):
        z = Z0_TRUE + 5e-8
        ref = mp.diff(lambda x: lit_force(mp_radius(z - Z0_TRUE, E_TRUE, R_TIP, x,
                                                    lit_a_dc(E_TRUE, R_TIP, x)),
                                          E_TRUE, R_TIP, x), mp.mpf("1e-20"))
    a0 = math.sqrt(R_TIP * 5e-8)
    assert gen.fit_jkr_force_ddgamma(E_TRUE, R_TIP, a0, 0.0) == pytest.approx(-math.pi * R_TIP,
                                                                             rel=1e-15)
    # at Delta gamma = 1e-20 the sqrt(Delta gamma) correction is ~1e-8 relative
    assert float(ref) == pytest.approx(-math.pi * R_TIP, rel=1e-6)


def mp_curve(n_contact=300, n_free=60, truth=TRUTH):
    """A retract curve made by mpmath at 30 digits: contact points parametric in a (from
    1.001 a_dc to 6 a_dc), then the free cantilever's baseline below the jump-off."""
    E, z0, dg, F0, s0 = (mp.mpf(float(v)) for v in truth)
    with mp.workdps(DPS):
        a_dc = lit_a_dc(E, R_TIP, dg)
        d_dc = lit_depth(a_dc, E, R_TIP, dg)
        zs, Fs = [], []
        for t in np.linspace(1.001, 6.0, n_contact):
            a = a_dc * mp.mpf(float(t))
            zi = z0 + lit_depth(a, E, R_TIP, dg)
            zs.append(zi)
            Fs.append(lit_force(a, E, R_TIP, dg) + F0 + s0 * zi)
        for zi in np.linspace(float(z0 + 3 * d_dc), float(z0 + 1.05 * d_dc), n_free):
            zs.append(mp.mpf(zi))
            Fs.append(F0 + s0 * zs[-1])
        return np.array([float(v) for v in zs]), np.array([float(v) for v in Fs])


def forward_curve(n=400, truth=TRUTH, noise=0.0, seed=0, shape=None, depth=150e-9):
    """A retract curve on a uniform grid of positions by the forward numeric/adhesion.py
    (AdhesiveContact.equilibrium under depth control) of ``shape`` (default: the paraboloid of
    radius R_TIP), to the indentation ``depth`` [m]: contact down to the jump-off, then the
    baseline. The other adhesive tips' tests make their curves with it."""
    E, z0, dg, F0, s0 = truth
    shape = adhesion.Paraboloid(R=R_TIP) if shape is None else shape
    c = adhesion.AdhesiveContact(shape, E_star=E, dgamma=dg)
    d_dc = c.pull_off("depth").depth
    z = np.linspace(z0 + 2.5 * d_dc, z0 + depth, n)
    d = z - z0
    F = F0 + s0 * z
    on = d >= d_dc
    F[on] += c.equilibrium(depth=d[on])[2]
    if noise:
        F = F + np.random.default_rng(seed).normal(0.0, noise, n)
    return z, F


def radius_tolerance(depth, d_H, ref, a_dc, d, d_c, E, dgamma, rounding=4e-16):
    """How far an adhesive fit's contact radius at the depth d [m] may lie from the 30-digit
    ``ref`` (mpf) of the route's ``depth(a)`` (mpf function; the pull-off radius ``a_dc``, the
    depth there ``d_c``; the non-adhesive depth ``d_H(a)``): the solver stops when d(a) - d_c
    is at its rounding (4 ulp of each of d(a), d_c, d; 2x here), so a is known to it over the
    slope dd/da, or at the fold to sqrt(2 err/d''), whichever is smaller; plus ``rounding``
    (relative) of the tip's own roundings in a."""
    slope = float(mp.diff(depth, ref))
    curv = float(mp.diff(depth, a_dc, 2))
    scale = float(d_H(ref)) + float(mp.sqrt(2 * mp.pi * ref * dgamma / E))
    err = 8 * 2.2e-16 * (scale + 2 * abs(d_c) + abs(d))
    return min(err / max(abs(slope), 1e-300), math.sqrt(2 * err / curv)) + rounding * float(ref)


def check_radius_beyond_and_without_adhesion(fam, d_c, rho, E, radius, rel=1e-14):
    """An adhesive family's contact radius (fit_adhesive._contact_radius): NaN past the
    jump-off depth ``d_c`` [m] (no equilibrium there), NaN out of contact without adhesion,
    and ``radius(d)`` (the non-adhesive a(d) at 30 digits, mpf or float) within ``rel`` at
    d = 1 nm and 100 nm without adhesion."""
    from hertzmdr.numeric import fit_adhesive as fa

    assert np.isnan(fa._contact_radius(np.array([d_c * (1 + 1e-9), 2 * d_c]), fam, E,
                                       rho)).all()
    d = np.array([-1e-9, 0.0, 1e-9, 1e-7])
    a0 = fa._contact_radius(d, fam, E, 0.0)
    assert np.isnan(a0[:2]).all()
    with mp.workdps(30):
        for di, ai in zip(d[2:], a0[2:], strict=True):
            assert ai == pytest.approx(float(radius(di)), rel=rel), di


def cli_adhesive_fit(tmp_path, capsys, z, F, sigma, body, label, dg_true=DG_TRUE):
    """``hertzmdr fit --adhesion`` of the curve (z [m], F [N]) with a scene whose tip is the
    TOML ``body`` (rigid, on a flat sample of E = 1.5 MPa): exit 0, ``label`` in the report,
    the work of adhesion within 4 standard errors of ``dg_true`` (a 6e-5 event for right
    errors)."""
    curve = tmp_path / "retract.csv"
    rows = zip(z.tolist(), F.tolist(), strict=True)
    curve.write_text("z [m], F [N]\n" + "".join(f"{a!r}, {b!r}\n" for a, b in rows))
    scene = tmp_path / "tip.toml"
    scene.write_text(f'effects = ["force"]\n[[body]]\n{body}\nrigid = true\n[[body]]\n'
                     'shape = "flat"\nE = "1.5 MPa"\nnu = 0.5\n[load]\ndepth = "100 nm"\n')
    assert main(["fit", str(curve), "--scene", str(scene), "--adhesion", "--sigma",
                 f"{sigma} N"]) == 0
    out = capsys.readouterr().out
    assert label in out
    line = next(ln for ln in out.splitlines() if ln.startswith("dgamma "))
    value, err = float(line.split()[1]), float(line.split()[2])
    assert abs(value - dg_true) < 4 * err, line


@pytest.mark.parametrize("make", [mp_curve, forward_curve], ids=["mpmath", "forward"])
def test_noise_free_recovery(make):
    """Every parameter back to 1e-10 relative from a noise-free curve by another route."""
    z, F = make()
    rng = np.random.default_rng(4)
    order = rng.permutation(z.size)  # any order of the points
    fit = fit_curve(z[order], F[order], TIP)
    rel = np.abs(fit.values - TRUTH) / np.abs(TRUTH)
    # measured ~1e-13 (the data's rounding over the fit's conditioning); 1e-10 is the issue's
    assert np.all(rel < 1e-10), rel
    assert fit.z_split is not None and fit.used.all()
    d_c, F_c, _ = fit.jump_off
    assert F_c == pytest.approx(float(gen.jkr_pull_off_force_dc(E_TRUE, DG_TRUE, R_TIP)),
                                rel=1e-9)
    assert not any("excluded" in w for w in fit.warnings), fit.warnings


def test_points_past_the_jump_off_are_excluded():
    """Points that stay at the jump-off force below d_dc (no equilibrium there) are excluded
    with a warning, and the rest of the curve still gives the truth."""
    z, F = forward_curve()
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=R_TIP), E_star=E_TRUE, dgamma=DG_TRUE)
    po = c.pull_off("depth")
    beyond = np.flatnonzero(z - Z0_TRUE < po.depth)[-3:]  # the last 3 free points before it
    F[beyond] = po.force + F0_TRUE + S0_TRUE * z[beyond]
    fit = fit_curve(z, F, TIP)
    assert any(w.startswith("3 point(s) of the contact part lie past the jump-off")
               for w in fit.warnings), fit.warnings
    assert (~fit.used).sum() == 3
    assert np.all(np.abs(fit.values - TRUTH) / TRUTH < 1e-10)


def test_soft_cantilever_jumps_earlier():
    """A soft cantilever leaves the sample at the force-controlled pull-off (d_fc > d_dc): the
    points in contact are on the same branch, the split comes from the data, and the fit holds
    (the truth within 4 standard errors: a 6e-5 event per parameter for right errors)."""
    noise = 1.3e-9
    z, F = forward_curve(noise=noise, seed=3)
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=R_TIP), E_star=E_TRUE, dgamma=DG_TRUE)
    off = z - Z0_TRUE < c.pull_off("force").depth
    F[off] = F0_TRUE + S0_TRUE * z[off] + np.random.default_rng(9).normal(0, noise, off.sum())
    fit = fit_curve(z, F, TIP, sigma=noise)
    assert np.all(np.abs(fit.values - TRUTH) < 4 * fit.errors), (fit.values - TRUTH) / fit.errors
    assert fit.used.all() and fit.z_split == pytest.approx(z[~off][0])
    assert not any("excluded" in w or "below the depth" in w for w in fit.warnings)


def test_without_adhesion_it_is_the_hertz_fit():
    """Delta gamma -> 0: a Hertz curve gives Delta gamma = 0 and the Hertz fit's parameters."""
    z = np.linspace(Z0_TRUE - 1e-7, Z0_TRUE + 1.5e-7, 300)
    F = hertz.force(np.maximum(z - Z0_TRUE, 0.0), R_TIP, E_TRUE) + F0_TRUE + S0_TRUE * z
    jkr = fit_curve(z, F, TIP)
    her = hfit.fit_curve(z, F, TIP)
    # 0, or a value whose pull-off force pi R Delta gamma is at the rounding of the forces
    assert jkr.dgamma * math.pi * R_TIP < 1e-15 * np.ptp(F), jkr.dgamma
    assert any(w.startswith("no adhesion measured") for w in jkr.warnings)
    np.testing.assert_allclose(jkr.values[[0, 1, 3, 4]], her.values, rtol=1e-10)
    # a tiny Delta gamma (a pull-off of 1e-6 of the force range): the same parameters
    truth = np.array([E_TRUE, Z0_TRUE, 1e-9, F0_TRUE, S0_TRUE])
    z, F = forward_curve(truth=truth)
    small = fit_curve(z, F, TIP)
    assert np.all(np.abs(small.values[[0, 1, 3, 4]] - truth[[0, 1, 3, 4]])
                  / truth[[0, 1, 3, 4]] < 1e-8), small.values


def test_curve_without_its_jump_off_claims_no_contact_point():
    """A retract curve cut before its jump-off (every point in contact, the first at
    d = d_dc/2) holds no free part: z_0, Delta gamma and the baseline trade with one another.
    The linearised errors put the truth 5 (E*) and 14 (z_0) of them away on such curves
    (Delta gamma and F_0 up to 470 on a curve cut at d = -d_dc/2). Now the fit with z_0 held
    elsewhere is found as good: those four get error inf with the warning, and E*'s error is
    at least its change over that profile, which covers the truth (within 3 of it: measured
    within 1 on 8 draws); or the fit refuses in one line. Noise 1 % of the pull-off force."""
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=R_TIP), E_star=E_TRUE, dgamma=DG_TRUE)
    d_dc = c.pull_off("depth").depth
    noise = 0.01 * 5 * math.pi * R_TIP * DG_TRUE / 6
    z = np.linspace(Z0_TRUE + d_dc / 2, Z0_TRUE + 150e-9, 200)
    clean = F0_TRUE + S0_TRUE * z + c.equilibrium(depth=z - Z0_TRUE)[2]
    fitted = 0
    for seed in (7, 0, 1, 5)[:n_points(4, 1)]:  # draws the fit does not refuse (8 tried)
        F = clean + np.random.default_rng(seed).normal(0.0, noise, z.size)
        fit = fit_curve(z, F, TIP, sigma=noise)
        assert np.all(np.isinf(fit.errors[1:])), fit.errors
        assert abs(fit.values[0] - E_TRUE) <= 3 * fit.errors[0], (fit.values[0], fit.errors[0])
        assert any(w.startswith("contact point not bounded by the curve") for w in fit.warnings)
        fitted += 1
    assert fitted


def _coverage(seeds, noise):
    inside = np.zeros(5, int)
    for seed in range(seeds):
        z, F = forward_curve(n=200, noise=noise, seed=seed)
        fit = fit_curve(z, F, TIP, sigma=noise)
        inside += np.abs(fit.values - TRUTH) <= fit.errors
    return inside / seeds


@pytest.mark.sweep
def test_coverage_of_standard_errors():
    """The truth within one reported standard error in ~68.3 % of noisy curves, per parameter.

    Binomial(m, 0.683): standard deviation sqrt(0.683 0.317/m) (0.060 at m = 60, 0.015 at
    m = 1000); the tolerance of 3.5 of them makes a false failure a 5e-4 event per parameter.
    Noise 1 % of the pull-off force (1.3 nN), 200 points.
    """
    m = n_points(1000, 60)
    noise = 0.01 * 5 * math.pi * R_TIP * DG_TRUE / 6
    frac = _coverage(m, noise)
    tol = 3.5 * math.sqrt(0.6827 * 0.3173 / m)
    assert np.all(np.abs(frac - 0.6827) <= tol), (frac, tol)


def test_no_contact_and_wrong_tip_are_one_clear_error():
    z = np.linspace(0, 1e-6, 200)
    F = F0_TRUE + S0_TRUE * z + np.random.default_rng(1).normal(0, 1e-11, z.size)
    with pytest.raises(hfit.NoContactError, match="no contact in the curve"):
        fit_curve(z, F, TIP)
    with pytest.raises(ValueError, match="has no adhesive fit model; valid: a Paraboloid"):
        fit_curve(z, F, hfit.FlatPunch(a=1e-6))  # the cone has one: test_fit_adhesive_cone
    with pytest.raises(ValueError, match="at least 7 are needed"):
        fit_curve(z[:6], F[:6], TIP)


def example_curve() -> str:
    """The text of examples/fit_jkr_retract.csv: its recipe (the forward adhesion + noise)."""
    truth = (2e6, 500e-9, 0.05, 0.1e-9, 2e-4)  # E* = 2 MPa (E = 1.5 MPa, nu = 0.5)
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=2e-6), E_star=truth[0], dgamma=truth[2])
    z = np.linspace(250e-9, 650e-9, 800)
    d = z - truth[1]
    F = truth[3] + truth[4] * z
    on = d >= c.pull_off("depth").depth
    F[on] += c.equilibrium(depth=d[on])[2]
    F = F + np.random.default_rng(17).normal(0.0, 2e-9, z.size)
    lines = ["# synthetic retract curve: a rigid paraboloid R = 2 um on E* = 2 MPa (E = 1.5 MPa,",
             "# nu = 0.5), work of adhesion 0.05 J/m^2, contact point z_0 = 500 nm (d = 0),",
             "# baseline 0.1 nN + 2e-4 N/m * z, Gaussian noise of 2 nN (seed 17); a stiff",
             "# cantilever: it jumps off at the depth-controlled pull-off, d = -173.3 nm,",
             "# F = -261.8 nN; made by tests/test_fit_jkr.py::example_curve",
             "z [nm], F [nN]"]
    lines += [f"{zi * 1e9:.6f}, {Fi * 1e9:.6f}" for zi, Fi in zip(z, F, strict=True)]
    return "\n".join(lines) + "\n"


def test_example_curve_is_its_recipe():
    assert EXAMPLE_CURVE.read_text() == example_curve()


def test_cli_fits_the_example(tmp_path, capsys):
    out = tmp_path / "fit.png"
    assert main(["fit", str(EXAMPLE_CURVE), "--scene", str(EXAMPLE_SCENE), "--adhesion",
                 "--sigma", "2 nN", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert out.read_bytes()[:4] == b"\x89PNG"
    for name, truth in (("E_star", 2e6), ("dgamma", 0.05), ("z_0", 500e-9)):
        line = next(ln for ln in text.splitlines() if ln.startswith(name + " "))
        value, err = float(line.split()[1]), float(line.split()[2])
        # the truth within 4 standard errors (a 6e-5 event for right errors)
        assert abs(value - truth) < 4 * err, line
    chi2 = float(text.split("reduced chi^2 = ")[1].split(",")[0])
    assert abs(chi2 - 1) < 0.3, chi2  # 795 degrees of freedom: sd of chi^2 is 0.05
    assert "jump-off (depth control)" in text
    assert "the scene's work of adhesion = 0.05 J/m^2" in text


def test_cli_adhesion_errors(tmp_path, capsys):
    punch = tmp_path / "punch.toml"  # (the cone has an adhesive fit: test_fit_adhesive_cone)
    punch.write_text(EXAMPLE_SCENE.read_text().replace('shape = "sphere"\nradius = "2 um"',
                                                       'shape = "flat_punch"\nradius = "2 um"'))
    assert main(["fit", str(EXAMPLE_CURVE), "--scene", str(punch), "--adhesion"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "no adhesive fit model" in err[0], err
    flat = tmp_path / "flat.csv"
    flat.write_text("z [nm], F [nN]\n" + "".join(f"{i}, {0.001 * (-1) ** i}\n"
                                                 for i in range(50)))
    assert main(["fit", str(flat), "--scene", str(EXAMPLE_SCENE), "--adhesion"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "no contact in the curve" in err[0], err
    # a folder of curves with --adhesion and a tip without an adhesive model: one line for
    # the batch (not one per curve)
    folder = tmp_path / "curves"
    folder.mkdir()
    (folder / "a.csv").write_text(EXAMPLE_CURVE.read_text())
    assert main(["fit", str(folder), "--scene", str(punch), "--adhesion"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--adhesion" in err[0] and "no adhesive fit model" in err[0], err


def test_adhesive_batch(tmp_path, capsys):
    """A folder of three retract curves (noise of known size, other seeds) and one without
    contact, fitted with --adhesion: exit 0, the table has the work of adhesion with its
    error (each within 4 standard errors of the truth), the curve without contact is one
    failed row with its message, and the summary names the work of adhesion. Through the API,
    adhesion with a fixed contact point is one clear error."""
    import csv

    from hertzmdr.numeric import fit_batch

    folder = tmp_path / "map"
    folder.mkdir()
    sigma = 2e-10
    for seed in range(3):
        z, F = forward_curve(noise=sigma, seed=seed)
        rows = zip(z.tolist(), F.tolist(), strict=True)
        (folder / f"c{seed}.csv").write_text(
            "z [m], F [N]\n" + "".join(f"{a!r}, {b!r}\n" for a, b in rows))
    (folder / "flat.csv").write_text("z [nm], F [nN]\n" + "".join(
        f"{i}, {0.001 * (-1) ** i}\n" for i in range(50)))
    scene = tmp_path / "tip.toml"  # the example's scene with forward_curve's tip, R_TIP
    scene.write_text(EXAMPLE_SCENE.read_text().replace('radius = "2 um"',
                                                       f'radius = "{R_TIP} m"'))
    out = tmp_path / "out"
    assert main(["fit", str(folder), "--scene", str(scene), "--adhesion", "--sigma",
                 f"{sigma} N", "--out", str(out), "--workers", "1"]) == 0
    captured = capsys.readouterr()
    assert "work of adhesion: median" in captured.out
    assert "curve flat:" in captured.err and "no contact" in captured.err
    with (out / "fits.csv").open(encoding="utf-8") as fh:
        rows = {r["curve"]: r for r in csv.DictReader(fh)}
    assert list(rows["c0"])[11:13] == list(fit_batch.ADHESIVE_COLUMNS)  # after s_0_err
    for name in ("c0", "c1", "c2"):
        r = rows[name]
        assert r["status"] != "failed", r
        dg, err = float(r["dgamma [J/m^2]"]), float(r["dgamma_err [J/m^2]"])
        assert abs(dg - DG_TRUE) < 4 * err, r
        assert abs(float(r["E_star [Pa]"]) - E_TRUE) < 4 * float(r["E_star_err [Pa]"]), r
    assert rows["flat"]["status"] == "failed" and rows["flat"]["dgamma [J/m^2]"] == ""
    assert (out / "modulus_map.png").stat().st_size > 0
    assert (out / "fit_median.png").stat().st_size > 0
    with pytest.raises(ValueError, match="fixed_z0/fixed_baseline with adhesion"):
        fit_batch.fit_curves([], hfit.Paraboloid(R=R_TIP), fixed_z0=1e-7, adhesion=True)
