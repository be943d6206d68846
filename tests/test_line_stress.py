"""Stresses under the line contact (plane strain): Flamant and its superposition over (5.36).

Independent routes: symbolic checks of the Flamant field (compatibility, equilibrium,
tractions, resultant); mpmath tanh-sinh quadrature of the *derived* Flamant kernel over the
pressure (split at the strip's edges and at the field point, as the "Singularities" section of
mpmath's quad advises) at 30 and 50 digits; Johnson's printed (McEwen) form at 50 digits;
finite-difference equilibrium and compatibility on grids; the surface tractions; numpy
eigenvalues for the principal stresses; the maxima by mp.findroot on the quadrature route.
"""

from functools import cache

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from hertzmdr.derive import line_stress as dl
from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import line_stress as ls

from oracle import FULL, WORST, memo

X, Z, P = dl.x, sp.Symbol("z_s", positive=True), dl.F_L


# -- Flamant, symbolically --------------------------------------------------------------------

def test_flamant_is_an_elastic_field():
    """The derived line-load field: biharmonic Airy function (plane-strain compatibility),
    equilibrium, traction-free surface away from the load, and every half-circle carries it."""
    zs = sp.Symbol("z_pos", positive=True)
    phi = dl.airy()
    lap = lambda f: sp.diff(f, X, 2) + sp.diff(f, zs, 2)  # noqa: E731
    assert sp.simplify(lap(lap(phi))) == 0
    s = {k: v.subs(dl.z, zs) for k, v in dl.flamant().items()}
    assert sp.simplify(sp.diff(s["xx"], X) + sp.diff(s["xz"], zs)) == 0
    assert sp.simplify(sp.diff(s["xz"], X) + sp.diff(s["zz"], zs)) == 0
    # compatibility of the stresses themselves: the trace is harmonic
    assert sp.simplify(lap(s["xx"] + s["zz"])) == 0
    xn = sp.Symbol("x_nz", nonzero=True, real=True)
    for comp in ("zz", "xz"):  # traction on z = 0, x != 0
        assert sp.limit(s[comp].subs(X, xn), zs, 0) == 0
    # resultant over the half-circle r = c: outward normal (sin t, cos t); the body inside it
    # carries the load P in +z, so the traction of the outside on it sums to -P
    c, t = sp.Symbol("c", positive=True), sp.Symbol("theta", real=True)
    on = {X: c * sp.sin(t), zs: c * sp.cos(t)}
    fz = sp.integrate(sp.simplify((s["xz"] * sp.sin(t) + s["zz"] * sp.cos(t)).subs(on)) * c,
                      (t, -sp.pi / 2, sp.pi / 2))
    fx = sp.integrate(sp.simplify((s["xx"] * sp.sin(t) + s["xz"] * sp.cos(t)).subs(on)) * c,
                      (t, -sp.pi / 2, sp.pi / 2))
    assert sp.simplify(fz + P) == 0 and sp.simplify(fx) == 0


def test_complex_representation_and_printed_forms():
    """The stable printed forms equal the forms SymPy took from the Cauchy integral, and those
    equal Johnson's printed (McEwen) forms, symbolically in (m, n, z)."""
    got, stable, john = dl.field_mn(), dl.field_stable_mn(), dl.johnson_mn()
    aux = {dl._g: dl._m**2 - dl._z**2, dl._h: dl._m - dl._z}
    for k in ("xx", "zz", "xz"):
        assert sp.simplify(got[k] - john[k]) == 0
        assert sp.simplify(stable[k].subs(aux) - got[k]) == 0


# -- the quadrature route ---------------------------------------------------------------------

@cache
def _kernel(comp, deriv=""):
    """Derived Flamant stress of a unit line load (optionally d/dx, d/dz), mpmath (x, z)."""
    k = dl.flamant()[comp].subs(P, 1)
    for d in deriv:
        k = sp.diff(k, {"x": X, "z": dl.z}[d])
    return sp.lambdify((X, dl.z), k, "mpmath")


@memo  # a mutation run's memo (tests/oracle.py): derive/ and mpmath only
def superposed(comp, x, z, deriv=""):
    """int_-1^1 sqrt(1 - s^2) K(x - s, z) ds (b = 1, p0 = 1): tanh-sinh, split at the strip's
    edges (the pressure's square-root ends) and around the field point (the kernel's peak of
    width z at s = x)."""
    x, z = mp.mpf(x), mp.mpf(z)
    k = _kernel(comp, deriv)
    pts = {mp.mpf(-1), mp.mpf(1)}
    for w in (0, 1, -1, 10, -10, 100, -100):
        s = x + w * z
        if -1 < s < 1:
            pts.add(s)
    return mp.quad(lambda s: mp.sqrt((1 - s) * (1 + s)) * k(x - s, z), sorted(pts),
                   method="tanh-sinh")


# points inside, below, near the surface, near the edge, outside and far away (b = 1)
POINTS = [(0.0, 0.5), (0.3, 0.2), (-0.7, 0.9), (0.5, 1e-8), (0.99, 1e-3), (1.0, 1e-6),
          (1 - 1e-6, 1e-7), (1 + 1e-6, 1e-7), (-1.5, 1e-5), (1.2, 0.3), (3.0, 0.5),
          (0.8, 0.6), (0.866, 0.5), (5.0, 20.0), (0.0, 1e3), (2.0, 1e6), (40.0, 1e-3),
          # outside the circle x^2 + z^2 = b^2 with q = b^2 - x^2 + z^2 >= 0 far from the
          # strip: the inside form of g, (b - x)(b + x) + n^2, cancels there (3e-13 here)
          (40.0, 40.0)]


@pytest.mark.parametrize(("x", "z"), POINTS)
def test_field_by_superposition(x, z):
    """stresses() against the 30-digit superposition of the derived Flamant kernel. The
    printed forms are products and quotients of positive terms built from square roots of
    sums (no cancellation): a few tens of roundings, 2e-14 relative per component."""
    got = ls.stresses(x, z, 1.0, 1.0, 0.3)
    with mp.workdps(30):
        for comp, val in zip(("xx", "zz", "xz"), got[:3], strict=False):
            ref = superposed(comp, x, z)
            err = float(abs((mp.mpf(float(val)) - ref) / ref)) if ref else abs(float(val))
            WORST["line_stress.stresses"] = max(WORST.get("line_stress.stresses", 0), err)
            assert err < 2e-14, (comp, x, z, float(val), ref)


@pytest.mark.parametrize(("x", "z"), [(0.0, 1e-6), (0.3, 1e-8), (0.5, 1e-8), (0.99, 1e-3),
                                      (1 - 1e-6, 1e-7), (1 + 1e-6, 1e-7), (1.2, 0.3),
                                      (0.866, 0.5), (5.0, 20.0), (2.0, 1e6)])
def test_tau_1_by_superposition(x, z):
    """tau_1 (its own form, (p0/b) h ((n^2 + z^2)/D)^(1/2)) and the von Mises stress at
    nu = 1/2 (3^(1/2) tau_1 there) against the 30-digit superposition, including just below
    the loaded surface, where tau_1 ~ z/b is a small difference of sigma_xx and sigma_zz
    (~ -p0): products and quotients of positive terms, 2e-14 as the components."""
    tau1, _ = ls.principal_shear(x, z, 1.0, 1.0, 0.3)
    vm = ls.von_mises(x, z, 1.0, 1.0, 0.5)
    with mp.workdps(30):
        sx, sz, t = (superposed(c, x, z) for c in ("xx", "zz", "xz"))
        ref = mp.sqrt((sx - sz) ** 2 / 4 + t * t)
        for got, want, what in ((tau1, ref, "tau_1"), (vm, mp.sqrt(3) * ref, "von Mises")):
            err = float(abs((mp.mpf(float(got)) - want) / want))
            assert err < 2e-14, (what, x, z, float(got), want)


def _closed_form_mp(comp, x, z):
    """The generated mpmath form, the region chosen as numeric/line_stress.py does."""
    ax, q = abs(x), (1 - abs(x)) * (1 + abs(x)) + z * z
    region = "core" if ax * ax + z * z <= 1 else ("side" if q < 0 else "deep")
    name = f"line_stress_{'tau' if comp == 'xz' else 'sigma'}_{comp}_{region}"
    v = getattr(gen_mp, name)(mp.mpf(1), mp.mpf(1), ax, z)
    return -v if (comp == "xz" and x < 0) else v


def _johnson_mp(comp, x, z):
    """Johnson's printed form with McEwen's m, n straight from their definitions."""
    q = 1 - x * x + z * z
    root = mp.sqrt(q * q + 4 * x * x * z * z)
    m = mp.sqrt((root + q) / 2)
    n = mp.sign(x) * mp.sqrt((root - q) / 2)
    f = dl.johnson_mn()[comp].subs(dl.p0, 1).subs(dl.a, 1)
    return sp.lambdify((dl._m, dl._n, dl._z), f, "mpmath")(m, n, z)


@pytest.mark.parametrize(("x", "z"), [(0.0, 0.5), (0.3, 0.2), (-0.7, 0.9), (0.99, 1e-3),
                                      (1.0, 1e-6), (1.2, 0.3), (3.0, 0.5), (5.0, 20.0),
                                      (-2.0, 1e3)])
def test_closed_form_equals_superposition_at_50_digits(x, z):
    """The proof the brief asks for where SymPy does not do the Cauchy integral: the printed
    field (all three regions) equals the superposition, and Johnson's form, at 50 digits."""
    with mp.workdps(60):
        x, z = mp.mpf(x), mp.mpf(z)
        for comp in ("xx", "zz", "xz"):
            ref = superposed(comp, x, z)
            got = _closed_form_mp(comp, x, z)
            john = _johnson_mp(comp, x, z)
            assert abs(got - ref) <= mp.mpf(10) ** -50 * abs(ref), (comp, x, z)
            # Johnson's form cancels far away and near the surface: 60 digits leave >= 45
            assert abs(john - ref) <= mp.mpf(10) ** -45 * abs(ref), (comp, x, z)


def test_axis_stresses_by_superposition():
    """axis_stresses() from z = 1e-6 b to 1e6 b against the quadrature (the printed forms are
    cancellation-free: a handful of roundings, 4e-15), and against stresses() at x = 0."""
    zs = np.logspace(-6, 6, 25)
    sxx, szz, syy = ls.axis_stresses(zs, 1.0, 1.0, 0.3)
    with mp.workdps(30):
        for i, zz in enumerate(zs):
            for comp, val in (("xx", sxx[i]), ("zz", szz[i])):
                ref = superposed(comp, 0.0, zz)
                assert abs(float((val - ref) / ref)) < 4e-15, (comp, zz)
    full = ls.stresses(0.0, zs, 1.0, 1.0, 0.3)
    np.testing.assert_allclose(full[0], sxx, rtol=2e-14)  # two printed routes, 2e-14 as above
    np.testing.assert_allclose(full[1], szz, rtol=2e-14)
    np.testing.assert_allclose(syy, 0.3 * (sxx + szz), rtol=4e-16)  # one product, one sum


def test_surface_tractions():
    """sigma_zz(x, 0) = -p(x), tau_xz(x, 0) = 0, and sigma_xx(x, 0) = -p(x) (0 outside), the
    known surface state of the Hertz line contact; 4 roundings: 1e-15."""
    xs = np.concatenate([np.linspace(-0.999, 0.999, 41), [-1, 1, 1 - 1e-12, 1.5, -3.0]])
    sxx, szz, txz, _ = ls.stresses(xs, 0.0, 1.0, 1e9, 0.3)  # b = 1: x/b exact
    p = 1e9 * np.sqrt(np.maximum((1 - xs) * (1 + xs), 0.0))
    np.testing.assert_allclose(szz, -p, rtol=1e-15, atol=0)
    np.testing.assert_allclose(sxx, -p, rtol=1e-15, atol=0)
    assert np.all(txz == 0)


def test_equilibrium_and_compatibility_on_a_grid():
    """Central differences, step h = 1e-5 b: truncation h^2 |sigma_xxx|/6 <~ 2e-8 p0/b (third
    derivatives reach ~1e3 p0/b^3 at z = 0.05 b by the contact edge), rounding eps/h ~ 1e-11,
    so div sigma < 1e-7 p0/b (points 0.05 b or more below the surface). The Laplacian of the
    trace (compatibility) by the 5-point stencil, h = 1e-3 b, at z >= 0.3 b: truncation
    h^2 |d^4|/12 measured 2e-5 p0/b^2 (it grows 9-fold with h = 3e-3 b: truncation, not
    rounding, which is eps/h^2 ~ 1e-10), so < 1e-4; a field that is not compatible is off
    by O(1)."""
    xg, zg = np.meshgrid(np.linspace(-2.5, 2.5, 21), np.linspace(0.05, 2.5, 15))

    def field(x, z):
        return ls.stresses(x, z, 1.0, 1.0, 0.3)

    h = 1e-5
    dx = [(a - b) / (2 * h) for a, b in zip(field(xg + h, zg), field(xg - h, zg), strict=True)]
    dz = [(a - b) / (2 * h) for a, b in zip(field(xg, zg + h), field(xg, zg - h), strict=True)]
    assert np.max(np.abs(dx[0] + dz[2])) < 1e-7
    assert np.max(np.abs(dx[2] + dz[1])) < 1e-7
    h = 1e-3

    def trace(x, z):
        s = field(x, z)
        return s[0] + s[1]

    xg, zg = np.meshgrid(np.linspace(-2.5, 2.5, 21), np.linspace(0.3, 2.5, 12))
    lap = (trace(xg + h, zg) + trace(xg - h, zg) + trace(xg, zg + h) + trace(xg, zg - h)
           - 4 * trace(xg, zg)) / h**2
    assert np.max(np.abs(lap)) < 1e-4


def test_plane_strain_and_principal_stresses():
    """principal_shear and von_mises against numpy's eigenvalues of the 3x3 tensor (another
    route, LAPACK): 1e-14 of p0 (a few roundings of quantities of size p0)."""
    rng = np.random.default_rng(3)
    x, z = rng.uniform(-3, 3, 60), rng.uniform(0, 3, 60)
    for nu in (0.3, 0.5, -0.9):
        sxx, szz, txz, syy = ls.stresses(x, z, 1.0, 1.0, nu)
        tens = np.zeros((60, 3, 3))
        tens[:, 0, 0], tens[:, 1, 1], tens[:, 2, 2] = sxx, syy, szz
        tens[:, 0, 2] = tens[:, 2, 0] = txz
        ev = np.linalg.eigvalsh(tens)
        inplane = np.linalg.eigvalsh(tens[:, [0, 2]][:, :, [0, 2]])
        tau1, tmax = ls.principal_shear(x, z, 1.0, 1.0, nu)
        np.testing.assert_allclose(tau1, (inplane[:, 1] - inplane[:, 0]) / 2, atol=1e-14)
        np.testing.assert_allclose(tmax, (ev[:, 2] - ev[:, 0]) / 2, atol=1e-14)
        dev = tens - np.trace(tens, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
        vm = np.sqrt(1.5 * np.sum(dev * dev, axis=(1, 2)))
        np.testing.assert_allclose(ls.von_mises(x, z, 1.0, 1.0, nu), vm, atol=1e-14)
        np.testing.assert_allclose(syy, nu * (sxx + szz), rtol=4e-16, atol=0)


# -- maxima -----------------------------------------------------------------------------------

@cache
@memo
def _tau1_root():
    """(z/b, tau_1/p0) at the root of d(tau_1)/dz on the axis: mp.findroot on the 30-digit
    superposition (computed once, shared by the tests below)."""
    with mp.workdps(30):
        def tau1_slope(zz):
            return (superposed("xx", 0, zz, "z") - superposed("zz", 0, zz, "z")) / 2

        depth = mp.findroot(tau1_slope, mp.mpf("0.78"))
        return depth, (superposed("xx", 0, depth) - superposed("zz", 0, depth)) / 2


@cache
@memo
def _orthogonal_root():
    """(x/b, z/b, |tau_xz|/p0) at the root of the gradient of tau_xz, x > 0: mp.findroot on the
    30-digit superposition (computed once, shared)."""
    with mp.workdps(30):
        def grad(xx, zz):
            return superposed("xz", xx, zz, "x"), superposed("xz", xx, zz, "z")

        xr, zr = mp.findroot(grad, (mp.mpf("0.86"), mp.mpf("0.5")))
        return xr, zr, -superposed("xz", xr, zr)


@cache
@memo
def _vm_root(nu_s, start):
    """(z/b, sigma_vM/p0) at the root of d(sigma_vM^2)/dz on the axis, sigma_yy =
    nu (sigma_xx + sigma_zz): mp.findroot on the 30-digit superposition, the kernel
    differentiated under the integral (computed once, shared with the roller scene's test)."""
    with mp.workdps(30):
        nu = mp.mpf(nu_s)

        def vm2_slope(t):
            sx, sz = superposed("xx", 0, t), superposed("zz", 0, t)
            dx, dz = superposed("xx", 0, t, "z"), superposed("zz", 0, t, "z")
            sy, dy = nu * (sx + sz), nu * (dx + dz)
            return (sx - sy) * (dx - dy) + (sy - sz) * (dy - dz) + (sz - sx) * (dz - dx)

        depth = mp.findroot(vm2_slope, mp.mpf(start))
        sx, sz = superposed("xx", 0, depth), superposed("zz", 0, depth)
        sy = nu * (sx + sz)
        return depth, mp.sqrt(((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) / 2)


def _check_vm_maximum(nu_s, start):
    """max_von_mises(nu) and the root of the generated mpmath slope against _vm_root."""
    depth, value = _vm_root(nu_s, start)
    with mp.workdps(30):
        nu, one = mp.mpf(nu_s), mp.mpf(1)
        # the generated mpmath slope's root (the docs' 30-digit table) is the same root
        d_gen = mp.findroot(
            lambda t: gen_mp.line_stress_axis_von_mises_slope(one, nu, one, t), mp.mpf(start))
        assert abs(d_gen - depth) < mp.mpf(10) ** -25 * depth
        assert abs(gen_mp.line_stress_axis_von_mises(one, nu, one, d_gen) - value) \
            < mp.mpf(10) ** -25 * value
    v, xm, d = ls.max_von_mises(float(nu_s))
    assert xm == 0.0
    # float64: the value at a maximum is flat (error ~ eps), the depth a simple root of a
    # slope computed to ~eps
    assert abs(v - value) < 1e-14 * value, (nu_s, v, value)
    assert abs(d - depth) < 1e-13 * depth, (nu_s, d, depth)


def test_axis_maxima_by_superposition():
    """tau_1 and von Mises maxima on the axis: mp.findroot of the derivative of the 30-digit
    superposition (kernel differentiated under the integral), against the exact golden-ratio
    values and max_shear()/max_von_mises(). float64: the value at a maximum is flat (error
    ~ eps), the depth is a simple root of a slope computed to ~eps: 1e-14 both. CI takes
    nu = 0.3 (the roots are shared with the roller scene's test); nu = 0.25 and 0.5 run in
    the sweep below."""
    with mp.workdps(30):
        depth, value = _tau1_root()
        gold = (1 + mp.sqrt(5)) / 2
        assert abs(depth - gold ** mp.mpf(-0.5)) < mp.mpf(10) ** -28
        assert abs(value - gold ** mp.mpf(-2.5)) < mp.mpf(10) ** -28
        v, d = ls.max_shear()
        assert abs(v - value) < 1e-14 * value and abs(d - depth) < 1e-14 * depth
    _check_vm_maximum("0.3", "0.7")


@pytest.mark.sweep
@pytest.mark.skipif(not FULL, reason="a root of the 30-digit superposition a nu, ~10 s "
                    "each: HERTZMDR_SWEEP=full runs it")
@pytest.mark.parametrize(("nu_s", "start"), [("0.25", "0.65"), ("0.5", "0.79")])
def test_axis_maxima_by_superposition_sweep(nu_s, start):
    """As test_axis_maxima_by_superposition, for two more Poisson's ratios."""
    _check_vm_maximum(nu_s, start)


def test_max_shear_3d_by_superposition():
    """The 3-D maximum shear: for nu = 0.1 the sigma_yy pair governs; mp.findroot of the
    slope of (sigma_yy - sigma_zz)/2 on the axis by the 30-digit superposition (kernel
    differentiated under the integral) against max_shear_3d (bounded Brent on a flat maximum:
    value ~eps, 1e-14; depth to xatol 1e-12 plus the flatness, sqrt(eps) ~ 1e-8 relative:
    1e-7). For nu = 0.3 it is the in-plane maximum, exactly."""
    with mp.workdps(30):
        nu = mp.mpf("0.1")

        def slope(zz):
            dx, dz = superposed("xx", 0, zz, "z"), superposed("zz", 0, zz, "z")
            return (nu * dx + (nu - 1) * dz) / 2

        depth = mp.findroot(slope, mp.mpf("0.17"))
        sx, sz = superposed("xx", 0, depth), superposed("zz", 0, depth)
        value = (nu * (sx + sz) - sz) / 2
    v, d = ls.max_shear_3d(0.1)
    assert abs(v - value) < 1e-14 * value and abs(d - depth) < 1e-7 * depth, (v, d)
    assert round(v, 4) == 0.4085 and round(d, 4) == 0.1734
    assert ls.max_shear_3d(0.3) == ls.max_shear()
    assert ls.max_shear_3d(0.0) == (0.5, 0.0)  # the surface centre: sigma_yy = 0


@pytest.mark.parametrize("nu", [-0.9, 0.0, 0.1, 0.2, 0.24, 0.25, 0.3, 0.5])
def test_max_shear_3d_is_the_global_one(nu):
    """No point of a 241 x 181 grid (|x| <= 3 b, z <= 3 b) has a larger 3-D maximum shear
    (1e-13: the field's rounding), and the field at the returned depth is the value."""
    v, d = ls.max_shear_3d(nu)
    x, z = np.meshgrid(np.linspace(-3, 3, 241), np.linspace(0, 3, 181))
    assert ls.principal_shear(x, z, 1.0, 1.0, nu)[1].max() <= v * (1 + 1e-13)
    assert abs(ls.principal_shear(0.0, d, 1.0, 1.0, nu)[1] - v) < 1e-14


def test_principal_stresses_at_the_loaded_surface():
    """sigma_xx = sigma_zz = -p, tau_xz = 0 on the loaded surface: the in-plane principal
    stresses are -p (Mohr's radius 0; the expanded discriminant went below 0: NaN)."""
    x = np.linspace(-0.999, 0.999, 101)
    tau1, tmax = ls.principal_shear(x, 0.0, 1.0, 1.0, 0.3)
    p = np.sqrt((1 - x) * (1 + x))
    assert np.all(np.isfinite(tau1)) and np.max(np.abs(tau1)) < 1e-15
    np.testing.assert_allclose(tmax, 0.2 * p, rtol=1e-14)  # (sigma_yy - sigma_zz)/2, nu = 0.3


@pytest.mark.parametrize("nu", [0.0, 0.1, 0.25, 0.3, 0.5, -0.5, -1 + 1e-9])
def test_von_mises_maximum_is_the_global_one(nu):
    """No point of a 241 x 181 grid (|x| <= 3 b, z <= 3 b) exceeds max_von_mises(nu); for
    small or negative nu the maximum is the surface centre, |1 - 2 nu| p0 (there
    sigma_xx = sigma_zz = -p0, sigma_yy = -2 nu p0). 1e-13: the field's rounding."""
    v, _, d = ls.max_von_mises(nu)
    x, z = np.meshgrid(np.linspace(-3, 3, 241), np.linspace(0, 3, 181))
    assert ls.von_mises(x, z, 1.0, 1.0, nu).max() <= v * (1 + 1e-13)
    if nu <= 0.1:
        assert d == 0.0 and abs(v - abs(1 - 2 * nu)) < 1e-15
    assert abs(ls.von_mises(0.0, d, 1.0, 1.0, nu) - v) < 1e-14


def test_orthogonal_shear_maximum():
    """|tau_xz| max: mp.findroot of the quadrature's gradient at 30 digits, against the exact
    p0/4 at (3^(1/2)/2 b, b/2) and max_orthogonal_shear() (hybr to xtol 1e-14: 1e-13 in the
    location; the value is flat there: 1e-15)."""
    with mp.workdps(30):
        xr, zr, value = _orthogonal_root()
        assert abs(xr - mp.sqrt(3) / 2) < mp.mpf(10) ** -28
        assert abs(zr - mp.mpf(1) / 2) < mp.mpf(10) ** -28
        assert abs(value - mp.mpf(1) / 4) < mp.mpf(10) ** -28
    v, xm, zm = ls.max_orthogonal_shear()
    assert abs(v - 0.25) < 1e-15 and abs(xm - np.sqrt(3) / 2) < 1e-13 and abs(zm - 0.5) < 1e-13
    x, z = np.meshgrid(np.linspace(-3, 3, 241), np.linspace(0, 3, 181))
    assert np.abs(ls.stresses(x, z, 1.0, 1.0, 0.3)[2]).max() <= 0.25 * (1 + 1e-14)


# -- hard cases, input ------------------------------------------------------------------------

def test_no_nan_and_symmetry_at_hard_points():
    """The edge x = +-b at z = 0 and at z = 1e-300, z/b = 1e6 and 1e-200, nu = 0.5 and -1+:
    finite everywhere, sigma even and tau_xz odd in x."""
    x = np.array([-1.0, 1.0, 1.0, 1.0 + 1e-15, 0.0, 2.0, 0.5, 1.0])
    z = np.array([0.0, 0.0, 1e-300, 1e-200, 1e6, 1e6, 1e-200, 1e-160])
    for nu in (0.5, -1 + 1e-12):
        out = ls.stresses(x, z, 1.0, 1.0, nu)
        assert all(np.all(np.isfinite(v)) for v in out)
        neg = ls.stresses(-x, z, 1.0, 1.0, nu)
        np.testing.assert_array_equal(out[0], neg[0])
        np.testing.assert_array_equal(out[2], -neg[2])
        assert np.all(np.isfinite(ls.von_mises(x, z, 1.0, 1.0, nu)))


def test_units_scale():
    """SI scaling: b = 2 mm, p0 = 1.5 GPa is the unit field times p0 at (x/b, z/b) (exact up to
    the roundings of x/b, z/b and the product: 1e-15)."""
    x, z = np.array([0.3e-3, 2.5e-3, -1e-3]), np.array([1e-3, 0.2e-3, 4e-3])
    got = ls.stresses(x, z, 2e-3, 1.5e9, 0.3)
    unit = ls.stresses(x / 2e-3, z / 2e-3, 1.0, 1.0, 0.3)
    for g, u in zip(got, unit, strict=True):
        np.testing.assert_allclose(g, 1.5e9 * u, rtol=1e-15)


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="nu = 0.6"):
        ls.stresses(0.0, 1.0, 1.0, 1.0, 0.6)
    with pytest.raises(ValueError, match="z = -1.0"):
        ls.von_mises(0.0, -1.0, 1.0, 1.0, 0.3)
    with pytest.raises(ValueError, match="b = 0.0"):
        ls.axis_stresses(1.0, 0.0, 1.0, 0.3)
    with pytest.raises(ValueError, match="nu = -1.0"):
        ls.max_von_mises(-1.0)


def test_far_field_limit():
    """Up to MAX_DISTANCE half-widths the field is finite and decays as the line load's
    (sigma ~ 1/rho: every component times rho stays below p0 b); beyond it, the documented
    ValueError instead of an overflow into NaN."""
    D = ls.MAX_DISTANCE
    for x, z in ((D, 1.0), (1.0, D), (D, D), (D, 1e-300)):
        out = ls.stresses(x, z, 1.0, 1.0, 0.3)
        assert all(np.isfinite(v) and abs(v) * max(x, z) <= 1.0 for v in out)
    for x, z in ((2 * D, 1.0), (1.0, 2 * D), (1e300, 1e300)):
        with pytest.raises(ValueError, match="half-widths"):
            ls.stresses(x, z, 1.0, 1.0, 0.3)
    assert all(np.isfinite(v) for v in ls.axis_stresses(D, 1.0, 1.0, 0.3))
    with pytest.raises(ValueError, match="half-widths"):
        ls.axis_stresses(1e300, 1.0, 1.0, 0.3)


# -- the roller scene (issue 14) ----------------------------------------------------------------

def test_roller_scene_by_superposition():
    """examples/roller_pair_stresses.toml (steel rollers of radii 10 mm and 20 mm, 30 mm long,
    5 kN): max shear, max von Mises and max orthogonal shear with their places, against an
    independent route at 30 digits: the half-width and p0 from the half-plane's Hilbert
    transform (tests/test_scene_routes.py's Line), the maxima by mp.findroot on the Flamant
    field superposed over the pressure (the kernel differentiated under the integral). The
    scene's values are products of closed forms (1e-14) with maxima found to ~eps in value:
    1e-13; places: roots to ~1e-15 b (hybr for tau_xz: 1e-13 b), times b: 1e-12."""
    from pathlib import Path

    from test_scene_routes import Line, e_star

    from hertzmdr.numeric import scene

    path = Path(__file__).parents[1] / "examples" / "roller_pair_stresses.toml"
    eff = scene.load(path).run()["effects"]
    nu = mp.mpf("0.3")
    with mp.workdps(30):
        R = mp.mpf("0.01") * mp.mpf("0.02") / mp.mpf("0.03")
        route = Line(e_star((210e9, 0.3), (210e9, 0.3)), R, mp.mpf("0.03"))
        d = route.depth_of(5e3, eff["half_width"]["value"] ** 2 / float(R))
        b, p0 = route.radius(d), route.p0(d)

        # the largest shear: the in-plane (sigma_xx - sigma_zz)/2 on the axis (for nu = 0.3
        # sigma_yy lies between sigma_xx and sigma_zz there: it is the 3-D maximum too)
        zt, tau = _tau1_root()
        sx, sz = superposed("xx", 0, zt), superposed("zz", 0, zt)
        assert sz < nu * (sx + sz) < sx

        # von Mises on the axis: the root of d(sigma_v^2)/dz, sigma_yy = nu (sx + sz)
        zv, vm = _vm_root("0.3", "0.7")
        assert vm > abs(1 - 2 * nu)  # above the surface centre's value

        # |tau_xz|: the root of its gradient
        xo, zo, txz = _orthogonal_root()

        def near(got, ref, rtol, what):
            assert abs(mp.mpf(got) - ref) <= rtol * abs(ref), (what, got, ref)

        ms, mv, mo = (eff[k]["value"] for k in ("max_shear", "max_von_mises",
                                                  "max_orthogonal_shear"))
        near(eff["half_width"]["value"], b, 1e-13, "half-width")
        near(eff["max_pressure"]["value"], p0, 1e-13, "p0")
        near(ms["value"], tau * p0, 1e-13, "max shear")
        near(ms["depth"], zt * b, 1e-12, "depth of max shear")
        near(mv["value"], vm * p0, 1e-13, "max von Mises")
        near(mv["z"], zv * b, 1e-12, "depth of max von Mises")
        assert mv["x"] == 0.0
        near(mo["value"], txz * p0, 1e-13, "max orthogonal shear")
        near(mo["x"], xo * b, 1e-12, "x of max orthogonal shear")
        near(mo["z"], zo * b, 1e-12, "depth of max orthogonal shear")
    # the figures quoted in docs/line_stress.md and the scene's comment
    assert round(ms["value"] / 1e6, 1) == 287.7 and round(ms["depth"] * 1e6, 1) == 87.0
    assert round(mv["value"] / 1e6, 1) == 534.2 and round(mv["z"] * 1e6, 1) == 78.0
    assert round(mo["value"] / 1e6, 1) == 239.6 and round(mo["z"] * 1e6, 1) == 55.4


def test_max_shear_3d_names_nu_in_its_error():
    """max_shear_3d's only input is named in its error (a NaN and nu = 0.6 > 0.5)."""
    from named import assert_inputs_named

    assert_inputs_named(ls.max_shear_3d, {"nu": 0.3})
    with pytest.raises(ValueError, match=r"^nu = 0\.6"):
        ls.max_shear_3d(0.6)


@pytest.mark.parametrize("func", [ls.stresses, ls.principal_shear, ls.von_mises])
def test_each_input_of_the_field_named_in_its_error(func):
    """Every input of the field functions is named in its error (NaN for each in turn), at an
    SI point (b = 1 mm, p0 = 1 GPa); axis_stresses likewise."""
    from named import assert_inputs_named

    assert_inputs_named(func, dict(x=0.3e-3, z=0.2e-3, b=1e-3, p0=1e9, nu=0.3))
    assert_inputs_named(ls.axis_stresses, dict(z=0.2e-3, b=1e-3, p0=1e9, nu=0.3))


def test_far_field_limit_in_half_widths_names_the_far_point():
    """MAX_DISTANCE counts half-widths: with b = 1 mm the field is evaluated at D b and refused
    at 2 D b (in metres, 1e47 and 2e47); in an array the error names the point that is too
    far, not the first one."""
    D, b = ls.MAX_DISTANCE, 1e-3
    assert all(np.isfinite(v) for v in ls.stresses(D * b, 1e-3, b, 1e9, 0.3))
    with pytest.raises(ValueError, match=r"^\(x, z\) = \(2e\+47, 0\.001\) m with b = 0\.001"):
        ls.stresses(np.array([0.5e-3, 2 * D * b]), 1e-3, b, 1e9, 0.3)
    with pytest.raises(ValueError, match=r"^\(x, z\) = \(0, 2e\+47\) m"):
        ls.axis_stresses(np.array([1e-3, 2 * D * b]), b, 1e9, 0.3)
