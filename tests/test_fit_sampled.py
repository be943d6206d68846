"""Fitting with a measured (sampled) tip through the numerical MDR (issue 17).

Independent routes: the curves are made by closed forms that do not use the numerical MDR --
Sneddon's exact sphere (numeric/sphere.py, lam = atanh(a/R)), the cone (5.40) and the worn
paraboloid of Problem 8 (numeric/worn.py) -- and fitted with the tip given as samples of the same
profile, solved by the numerical MDR (numeric/mdr.py). Each tolerance is the fit's own
``model_error`` (the MDR's rel_error per point carried into the parameters) or comes from the
noise's statistics.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.stats import binom

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import fit, fit_batch, fit_io, mdr, sphere, worn
from hertzmdr.numeric.cli import main

from oracle import n_points

EXAMPLES = Path(__file__).parents[1] / "examples"
R_SPH = 10e-6  # m: the sampled sphere of most tests
E_TRUE = 2e6  # Pa: E* of the synthetic curves


def sampled_sphere(n: int = 201, r_max: float = 0.6 * R_SPH) -> fit.SampledTip:
    """The spherical cap f = R - sqrt(R^2 - r^2) sampled at n radii from 0 to r_max."""
    r = np.linspace(0.0, r_max, n)
    return fit.SampledTip.from_samples(r, R_SPH - np.sqrt(R_SPH**2 - r**2))


def sphere_curve(z, z0, E_star=E_TRUE, F0=1e-9, s0=2e-3):
    """The exact sphere's force (Sneddon, numeric/sphere.py) plus the baseline: no MDR."""
    d = np.maximum(z - z0, 0.0)
    return sphere.force(d, R_SPH, E_star) + F0 + s0 * z


@pytest.fixture(scope="module")
def tip():
    return sampled_sphere()


Z = np.linspace(-0.4e-6, 0.8e-6, 60)  # m: 60 points, 35 of them in contact at z_0 = 0.1 um
Z0 = 0.1e-6


# --- the tip's model against the closed forms -----------------------------------------------
def test_sampled_sphere_model_within_its_bound(tip):
    """Phi(d) = F/E* and its z_0 slope -2 a(d) by the MDR against Sneddon's closed forms;
    the bound per point is the MDR's rel_error (which must cover the true error)."""
    d = np.geomspace(1e-10, 0.7e-6, 25)
    g, h, eps = tip._exact(d, 0.0)
    ref = sphere.force(d, R_SPH, 1.0)
    a_ref = sphere.contact_radius(d, R_SPH)
    assert np.all(np.abs(g / ref - 1) <= eps), np.max(np.abs(g / ref - 1) / eps)
    # dF/dz_0 = -2 E* a (5.12): a carries the same bound as the force
    assert np.all(np.abs(-h / (2 * a_ref) - 1) <= eps)
    assert np.all(eps < 1e-6)  # 201 samples of a smooth cap: the MDR is far below 1e-6


def test_table_is_close_and_derivative_consistent(tip):
    """The table (the start's and Levenberg-Marquardt's model) interpolates Phi in sqrt(d) with
    the exact slopes: cubic Hermite, error O(h^4); 128 intervals give ~1e-8 relative away from
    the apex (its size sets the polish's work, not the result)."""
    d = np.linspace(0.05e-6, 0.9e-6, 37)
    phi, k = tip._tabled(d)
    ref = sphere.force(d, R_SPH, 1.0)
    assert np.max(np.abs(phi / ref - 1)) < 1e-5
    a_ref = sphere.contact_radius(d, R_SPH)
    assert np.max(np.abs(k / (2 * a_ref) - 1)) < 1e-3
    phi0, k0 = tip._tabled(np.array([-1e-7, 0.0]))
    assert np.all(phi0 == 0) and np.all(k0 == 0)


# --- noise-free recovery ---------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["sphere", "cone"])
def test_noise_free_recovery_within_the_mdr_bound(kind):
    """A noise-free curve of a closed form recovered by the sampled tip: each parameter within
    the fit's model_error (the MDR's per-point bound carried through the fit) plus the
    rounding of a fit of double-precision data (1e-12 relative of E*; the closed-form tips
    reach 1e-10 in tests/test_fit.py)."""
    if kind == "sphere":
        tp, F = sampled_sphere(), sphere_curve(Z, Z0)
    else:
        theta = np.radians(20.0)
        r = np.linspace(0.0, 4e-6, 201)
        tp = fit.SampledTip.from_samples(r, r * np.tan(theta))
        F = gen.fit_cone_force(E_TRUE, theta, Z, Z0, 1e-9, 2e-3)
    res = fit.fit_curve(Z, F, tp)
    assert res.model_error is not None
    truth = np.array([E_TRUE, Z0, 1e-9, 2e-3])
    floor = np.array([1e-12 * E_TRUE, 1e-12 * np.ptp(Z), 1e-12 * np.ptp(F), 1e-12 * np.ptp(F)
                      / np.ptp(Z)])
    assert np.all(np.abs(res.values - truth) <= res.model_error + floor), \
        (res.values - truth, res.model_error)
    # and the bound is not vacuous: below 1e-6 relative for E*
    assert res.model_error[0] < 1e-6 * E_TRUE
    # the table says it, each figure in its place, and (no sigma given) the residuals' std
    table = res.table().splitlines()
    assert table[5] == (f"the tip's MDR error moves E* by at most {res.model_error[0]:.3g} Pa "
                        f"and z_0 by {res.model_error[1]:.3g} m")
    assert table[6].startswith(f"residuals' std = {np.sqrt(res.reduced_chi2):.4g} N, ")


def test_worn_tip_without_breakpoint_has_a_larger_honest_bound():
    """Problem 8's worn paraboloid sampled with no breakpoint: the spline rings across the
    kink at r = b and the MDR's error is ~1e-5 at 100 nm; model_error says so and covers the
    true error of E* (the curve is the closed form of numeric/worn.py)."""
    R, b = 5e-6, 1e-6
    r = np.linspace(0.0, 3e-6, 301)
    tp = fit.SampledTip.from_samples(r, worn.profile(r, R, b))
    z = np.linspace(-0.1e-6, 0.15e-6, 60)
    F = worn.force(np.maximum(z, 0.0), R, b, E_TRUE)
    res = fit.fit_curve(z, F, tp)
    assert abs(res.values[0] - E_TRUE) <= res.model_error[0]
    assert res.model_error[0] > 1e-7 * E_TRUE  # the kink shows in the bound
    # with its breakpoint the MDR is exact to rounding: the bound drops by orders
    tp_b = fit.SampledTip.from_samples(r, worn.profile(r, R, b), breakpoints=[b])
    res_b = fit.fit_curve(z, F, tp_b)
    assert abs(res_b.values[0] - E_TRUE) <= res_b.model_error[0] + 1e-12 * E_TRUE
    assert res_b.model_error[0] < 1e-2 * res.model_error[0]


# --- noise: coverage --------------------------------------------------------------------------
def _coverage(tip, seeds):
    sigma = 2e-9  # N: ~0.3 % of the deepest force
    hits = 0
    for seed in seeds:
        rng = np.random.default_rng(seed)
        F = sphere_curve(Z, Z0) + rng.normal(0.0, sigma, Z.size)
        res = fit.fit_curve(Z, F, tip, sigma=sigma)
        hits += abs(res.values[0] - E_TRUE) <= res.errors[0]
    return hits


def _check_coverage(hits, n):
    # the count of 1-sigma hits is binomial(n, 0.6827); reject below its 0.1 % quantile or
    # above its 99.9 % one (a false failure of a right error in 1 of 500 runs)
    lo, hi = binom.ppf(0.001, n, 0.6827), binom.ppf(0.999, n, 0.6827)
    assert lo <= hits <= hi, (hits, n, lo, hi)


@pytest.mark.sweep
def test_coverage(tip):
    """The truth of E* within one reported standard error in ~68.3 % of noisy curves (the
    MDR's error, < 1e-9 here, is far below the noise's 1e-3)."""
    n = n_points(400, 40)
    _check_coverage(_coverage(tip, range(n)), n)


# --- clear messages ----------------------------------------------------------------------------
def test_no_contact_is_a_clear_message(tip):
    rng = np.random.default_rng(3)
    F = 1e-9 + 1e-3 * Z + rng.normal(0.0, 1e-10, Z.size)
    with pytest.raises(fit.NoContactError, match="no contact in the curve"):
        fit.fit_curve(Z, F, tip, sigma=1e-10)


def test_jump_is_a_warning(tip):
    F = sphere_curve(Z, Z0)
    F[Z > 0.5e-6] += 2e-8  # a step of 20 nN in the contact part
    F += np.random.default_rng(5).normal(0.0, 1e-10, Z.size)
    res = fit.fit_curve(Z, F, tip, sigma=1e-10)
    assert any("a jump of the force" in w for w in res.warnings), res.warnings


def test_indentation_beyond_the_samples_is_a_clear_message():
    """The curve indents deeper than the tip's samples reach: one ValueError naming the
    depth, g(r_max) and r_max (no traceback from the MDR's root finding)."""
    tp = sampled_sphere(n=41, r_max=1.5e-6)  # g(r_max) ~ 0.23 um
    with pytest.raises(ValueError, match=r"deeper than the sampled tip reaches: g\(r_max\)"):
        fit.fit_curve(Z, sphere_curve(Z, Z0), tp)


def test_not_a_profile_is_a_clear_message():
    with pytest.raises(ValueError, match="valid: a hertzmdr.numeric.mdr.Profile"):
        fit.SampledTip(profile=[0.0, 1.0])
    with pytest.raises(ValueError, match="the sampled tip reaches no depth"):
        fit.SampledTip.from_samples(np.linspace(0, 1e-6, 11), np.zeros(11))
    with pytest.raises(ValueError, match="rtol"):
        fit.SampledTip(mdr.Profile.from_samples([0, 1, 2, 3], [0, 1, 4, 9]), rtol=1.0)


def test_deep_indentation_warns(tip):
    res = fit.fit_curve(Z, sphere_curve(Z, Z0), tip)
    assert any(w.startswith("d/a = ") for w in res.warnings), res.warnings  # d/a = 0.3


# --- the example: scene, curve, command ------------------------------------------------------
EX_SCENE = EXAMPLES / "fit_worn_tip.toml"
EX_TIP = EXAMPLES / "fit_worn_tip_profile.csv"
EX_CURVE = EXAMPLES / "fit_worn_tip_curve.csv"
EX_R, EX_B = 5e-6, 1e-6  # m: the worn paraboloid (Problem 8)
EX_E_STAR = 4e6 / 3  # Pa: E = 1 MPa, nu = 0.5, a rigid tip (5.8)


def example_tip() -> str:
    """The text of examples/fit_worn_tip_profile.csv: worn.profile at 301 radii, in nm."""
    r = np.linspace(0.0, 3e-6, 301)
    f = worn.profile(r, EX_R, EX_B)
    lines = ["# a worn tip: Problem 8's paraboloid R = 5 um worn flat to r = b = 1 um, sampled",
             "# every 10 nm (made by tests/test_fit_sampled.py::example_tip)", "r, f"]
    lines += [f"{ri * 1e9:.4f}, {fi * 1e9:.9f}" for ri, fi in zip(r, f, strict=True)]
    return "\n".join(lines) + "\n"


def example_curve() -> str:
    """The text of examples/fit_worn_tip_curve.csv: worn.force (closed form) + noise."""
    z = np.linspace(350e-9, 550e-9, 300)
    d = np.maximum(z - 450e-9, 0.0)
    F = worn.force(d, EX_R, EX_B, EX_E_STAR) + 0.1e-9 + 5e-4 * z
    F = F + np.random.default_rng(17).normal(0.0, 0.5e-9, z.size)
    lines = ["# synthetic force curve: the worn tip of fit_worn_tip_profile.csv (Problem 8, R = 5 "
             "um,", "# b = 1 um) on E* = 1.3333 MPa (E = 1 MPa, nu = 0.5), contact point z_0 = "
             "450 nm,", "# baseline 0.1 nN + 5e-4 N/m * z, Gaussian noise of 0.5 nN (seed 17); "
             "made by", "# tests/test_fit_sampled.py::example_curve", "z [nm], F [nN]"]
    lines += [f"{zi * 1e9:.6f}, {Fi * 1e9:.6f}" for zi, Fi in zip(z, F, strict=True)]
    return "\n".join(lines) + "\n"


def test_example_files_are_their_recipes():
    assert EX_TIP.read_text() == example_tip()
    assert EX_CURVE.read_text() == example_curve()


def test_cli_fits_the_example(tmp_path, capsys):
    out = tmp_path / "fit.png"
    assert main(["fit", str(EX_CURVE), "--scene", str(EX_SCENE), "--out", str(out),
                 "--sigma", "0.5 nN"]) == 0
    text = capsys.readouterr().out
    assert "sampled tip (301 samples" in text
    line = next(ln for ln in text.splitlines() if ln.startswith("E_star "))
    value, err = float(line.split()[1]), float(line.split()[2])
    # the truth within 4 standard errors (a 6e-5 event for a right error)
    assert abs(value - EX_E_STAR) < 4 * err and err < 0.01 * EX_E_STAR, line
    assert "the tip's MDR error moves E* by at most" in text
    assert out.read_bytes()[:4] == b"\x89PNG"


def test_cli_too_short_profile_is_one_line(tmp_path, capsys):
    tipfile = tmp_path / "tip.csv"
    # the samples to r = 1.06 um: g(r_max) = 75 nm (numeric/worn.py), the curve goes to 100 nm
    tipfile.write_text("".join(line + "\n" for line in example_tip().splitlines()[:110]))
    scene = EX_SCENE.read_text().replace("fit_worn_tip_profile.csv", str(tipfile))
    (tmp_path / "s.toml").write_text(scene)
    assert main(["fit", str(EX_CURVE), "--scene", str(tmp_path / "s.toml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "deeper than the sampled tip reaches" in err, err


def test_batch_with_sampled_tip(tmp_path):
    """A small map (the example curve and a flat one): one result per curve, the flat one a
    message, in this process and over two worker processes (the tip pickles with its table)."""
    tip, *_ = fit_io.tip_from_scene(EX_SCENE)
    z, F = fit_io.read_curve(EX_CURVE)
    curves = [fit_batch.Curve("worn", None, None, z, F),
              fit_batch.Curve("flat", None, None, z, 1e-10 * np.cos(z / 1e-8))]
    for workers in (1,):
        res = fit_batch.fit_curves(curves, tip, nu=0.5, sigma=0.5e-9, workers=workers)
        assert res[0].ok and abs(res[0].values[0] - EX_E_STAR) < 4 * res[0].errors[0]
        assert not res[1].ok and "no contact" in res[1].error
    import pickle

    tip2 = pickle.loads(pickle.dumps(tip))
    assert tip2.d_limit == tip.d_limit and "table" in tip2._memo


def test_cli_batch_with_sampled_tip(tmp_path, capsys):
    """`hertzmdr fit FOLDER --scene TIP.toml --out DIR` with a measured tip: the table, the map
    and the median curve's figure; a flat curve is its row, not a crash."""
    folder = tmp_path / "curves"
    folder.mkdir()
    text = example_curve().splitlines()
    (folder / "a.csv").write_text(example_curve())
    (folder / "b.csv").write_text("\n".join(text[:5] + text[5::2]) + "\n")  # every other point
    (folder / "flat.csv").write_text("z [nm], F [nN]\n" + "".join(
        f"{z:.3f}, {0.1 * np.cos(z):.6f}\n" for z in np.linspace(350, 550, 50)))
    out = tmp_path / "out"
    assert main(["fit", str(folder), "--scene", str(EX_SCENE), "--out", str(out), "--sigma",
                 "0.5 nN"]) == 0
    text = capsys.readouterr().out
    assert "3 curves: 2 fitted" in text and "1 failed" in text, text
    rows = (out / "fits.csv").read_text().splitlines()
    assert len(rows) == 4 and sum(",failed," in r for r in rows) == 1
    assert (out / "modulus_map.png").exists() and (out / "fit_median.png").exists()


# --- the polish on the exact MDR: its minimum, its bound, fixed parameters ---------------------
def _exact_least_squares(tip, z, F, w, p, free):
    """The least squares of the exact MDR model (tip._exact's dF/dE* only) near p, by
    Gauss-Newton steps with a central-difference Jacobian solved by numpy's lstsq: another
    route to the polish's minimum (no table, no analytic dF/dz_0, no pseudo-inverse)."""
    p = np.array(p, float)

    def res(pp):
        g = tip._exact(z, pp[1])[0]
        return (pp[0] * g + pp[2] + pp[3] * z - F) / w

    h = 1e-6 * np.array([p[0], np.ptp(z), np.ptp(F), np.ptp(F) / np.ptp(z)])
    for _ in range(4):  # Gauss-Newton converges linearly at ~1e-2 a step on this residual
        cols = []
        for k in np.flatnonzero(free):
            e = np.zeros(4)
            e[k] = h[k]
            cols.append((res(p + e) - res(p - e)) / (2 * h[k]))
        step = np.linalg.lstsq(np.column_stack(cols), -res(p), rcond=None)[0]
        p = p.copy()
        p[free] += step
    return p


@pytest.mark.parametrize("fixed", [False, True])
def test_polish_reaches_the_exact_model_s_least_squares(tip, fixed):
    """A curve of the sampled sphere with a little noise (1e-12 N, 2e-7 of the deepest force):
    the fit's parameters are the exact MDR model's least squares (Gauss-Newton steps from them
    by central differences land within 1e-2 of a standard error: the polish stops at
    POLISH_SIGMA = 1e-3 of one, the differences' error is ~1e-12 relative; measured 7e-5 of
    one, the same with no polish step: this smooth tip's table is already that close); with
    z_0 fixed the polish keeps it exactly; the fitted curve is the exact model's at the
    returned parameters (not the table's)."""
    sigma = 1e-12
    F = sphere_curve(Z, Z0) + np.random.default_rng(21).normal(0.0, sigma, Z.size)
    kw = {"fixed_z0": Z0} if fixed else {}
    res = fit.fit_curve(Z, F, tip, sigma=sigma, **kw)
    free = np.array([True, not fixed, True, True])
    ref = _exact_least_squares(tip, res.z, res.F, np.full(Z.size, sigma), res.values, free)
    assert np.all(np.abs(res.values - ref)[free] <= 1e-2 * res.errors[free]), \
        ((res.values - ref) / np.where(free, res.errors, 1.0))
    if fixed:
        assert res.values[1] == Z0 and res.errors[1] == 0 and res.fixed == ("z_0",)
    # the fitted curve is the exact model's at the returned parameters (not the table's)
    g = tip._exact(res.z, res.values[1])[0]
    model = res.values[0] * g + res.values[2] + res.values[3] * res.z
    assert np.max(np.abs(res.fitted - model)) <= 1e-13 * np.ptp(F)


def test_model_error_bound_does_not_depend_on_the_weights(tip):
    """The MDR error's bound on the parameters (model_error) is the same whether sigma is
    given or not (constant weights leave the least squares and the propagated bound as they
    are), and it still covers the noise-free curve's true error with sigma given."""
    F = sphere_curve(Z, Z0)
    plain = fit.fit_curve(Z, F, tip)
    weighted = fit.fit_curve(Z, F, tip, sigma=1e-10)
    np.testing.assert_allclose(weighted.model_error, plain.model_error, rtol=1e-6)
    truth = np.array([E_TRUE, Z0, 1e-9, 2e-3])
    floor = 1e-12 * np.array([E_TRUE, np.ptp(Z), np.ptp(F), np.ptp(F) / np.ptp(Z)])
    assert np.all(np.abs(weighted.values - truth) <= weighted.model_error + floor)
