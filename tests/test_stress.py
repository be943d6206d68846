"""Stresses under the Hertz pressure and by superposition: (5.47)-(5.50), Figs. 5.8 and 5.9.

Independent routes: mpmath quadrature of the derived point-force field (5.41)-(5.46) over the
pressure (5.47); Johnson's printed form of Huber's field evaluated at 50 digits (where the
float64 forms would cancel); finite-difference equilibrium; the surface tractions; the
point-force far field.
"""

import re
from functools import cache

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from hertzmdr.derive import boussinesq as b
from hertzmdr.derive import stress as ds
from hertzmdr.derive.symbols import F, a, nu, p0, r, z
from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import stress

from named import assert_inputs_named
from oracle import WORST, Arg, assert_close, assert_mpmath_equal, memo, n_points


@cache
def _kernel(comp):
    """Derived point-force stress of a unit force, as an mpmath function of (nu, x, y, z)."""
    return sp.lambdify((nu, b.x, b.y, b.z), b.stresses()[comp].subs(F, 1), "mpmath")


# @memo: a mutation run's memo of a reference (tests/oracle.py); these references use derive/
# and mpmath only, nothing of numeric/
@memo
def _axis_reference(comp, nu_, zz):
    """(5.47) on the axis for the unit Hertz pressure: the phi-mean of K_xx is (K_xx + K_yy)/2
    at phi = 0; rho = sin(theta) makes the pressure's rim smooth (Gauss-Legendre)."""
    def f(th):
        rho = mp.sin(th)
        if comp == "zz":
            k = _kernel("zz")(nu_, rho, 0, zz)
        else:
            k = (_kernel("xx")(nu_, rho, 0, zz) + _kernel("yy")(nu_, rho, 0, zz)) / 2
        return k * mp.cos(th) * 2 * mp.pi * rho * mp.cos(th)
    return mp.quad(f, _splits(zz), method="gauss-legendre")


#: ds.axis_maxima (the 30-digit root of the derivation's slope), memoized in a mutation run
_axis_maxima = memo(ds.axis_maxima)


@memo
def _axis_slope_30(nu_, zz):
    """d(tau_1)/dz of the derivation at z/a = zz (nu a decimal string), at 30 digits."""
    slope = sp.lambdify(z, ds.max_shear_axis().diff(z).subs({a: 1, p0: 1,
                                                              nu: sp.Rational(nu_)}), "mpmath")
    with mp.workdps(30):
        return slope(zz)


def _splits(zz):
    """Break points in theta (rho = sin theta): the kernel's scale z is resolved near 0."""
    pts = [mp.mpf(0)]
    t = zz / 8
    while t < 1:
        pts.append(mp.asin(t))
        t *= 4
    return pts + [mp.pi / 2]


def test_axis_stresses_by_superposition():
    """(5.48), (5.49) against quadrature of (5.43), (5.41) over (5.15), z from 1e-4 a to 1e4 a
    (both branches of (5.49)) and nu up to 1/2."""
    dom = {"z": Arg(1e-4, 1e4), "nu": Arg(0.0, 0.5, log=False)}

    def szz(z, nu):
        return stress.axis_stresses(z, 1.0, 1.0, nu)[0]

    def sxx(z, nu):
        return stress.axis_stresses(z, 1.0, 1.0, nu)[1]

    # (5.48): one division; (5.49) and its deep form: a few roundings, no cancellation left
    # (the hypergeometric form removes it for z >= a); 30-digit Gauss-Legendre reference
    assert_mpmath_equal(szz, lambda z, nu: _axis_reference("zz", nu, z), dom, rtol=1e-14,
                        n=n_points(40, 8), dps=30, name="stress_axis_sigma_zz")
    assert_mpmath_equal(sxx, lambda z, nu: _axis_reference("xx", nu, z), dom, rtol=1e-13,
                        n=n_points(40, 8), dps=30, name="stress_axis_sigma_xx")
    # nu = 1/2 deep below: the O((a/z)^2) terms cancel exactly; the form keeps full accuracy
    for zz in (10.0, 1e3):
        with mp.workdps(30):
            ref = _axis_reference("xx", mp.mpf("0.5"), mp.mpf(zz))
        assert_close(stress.axis_stresses(zz, 1.0, 1.0, 0.5)[1], ref, 1e-13, f"nu=1/2 z={zz}")
    # the surface value -(1 + 2 nu) p0/2
    assert abs(stress.axis_stresses(0.0, 1.0, 1.0, 0.3)[1] + 0.8) < 1e-15


def test_axis_maximum_shear():
    """tau_1 maximum on the axis: float64 root against the 30-digit root of the derivation;
    the chapter's z ~ 0.49 a for nu = 0.33 and the classical 0.31 p0 at 0.48 a for nu = 0.3."""
    for nu_, z_round, tau_round in (("0.3", 0.48, 0.31), ("0.33", 0.49, 0.30)):
        z30, t30 = _axis_maxima(nu_)
        zf, tf = stress.axis_max_shear(float(nu_))
        # a simple root found by Brent to 4 ulp of the slope: ~1e-15 relative in z
        assert_close(zf, z30, 1e-14, f"z/a at nu={nu_}")
        assert_close(tf, t30, 1e-15, f"tau1/p0 at nu={nu_}")
        assert round(float(z30), 2) == z_round and round(float(t30), 2) == tau_round
        # the slope at the 30-digit root is zero (the derivation's, evaluated at 30 digits)
        assert abs(_axis_slope_30(nu_, z30)) < mp.mpf(10) ** -27
        assert abs(gen.stress_axis_max_shear_slope(1.0, float(nu_), 1.0, zf)) < 1e-15


@pytest.mark.parametrize("criterion", ["von_mises", "tresca"])
def test_maximum_in_the_body(criterion):
    """The maximum over the body lies on the axis at the tau_1 depth; von Mises = Tresca =
    2 tau_1 there (sigma_xx = sigma_yy on the axis)."""
    for nu_ in ("0.3", "0.33"):
        z30, t30 = _axis_maxima(nu_)
        val, rb, zb = stress.hertz_maximum(float(nu_), criterion)
        # the peak is flat: Nelder-Mead stops at 1e-10 in value, ~1e-7 a in position
        assert_close(val, 2 * t30, 1e-13, f"{criterion} max at nu={nu_}")
        assert rb < 1e-6 and abs(zb - float(z30)) < 1e-6


@cache
def _johnson():
    return {k: sp.lambdify((nu, r, z), e.subs({a: 1, p0: 1}), "mpmath")
            for k, e in ds.johnson_field().items()}


@memo
def _johnson_at(comp, nu_, rr, zz):
    """Johnson's printed component at (r, z) (a = p0 = 1), at the caller's precision."""
    return _johnson()[comp](nu_, rr, zz)


def _field_reference_superposition(nu_, rr, zz):
    """(sigma_rr, sigma_tt, sigma_zz, tau_rz) at (r, 0, z) by 2-D quadrature of the derived
    point-force field over the unit Hertz pressure; rho = sin(theta), phi in [0, pi] doubled."""
    out = []
    for comp in ("xx", "yy", "zz", "xz"):
        k = _kernel(comp)

        def f(th, ph, k=k):
            rho = mp.sin(th)
            return k(nu_, rr - rho * mp.cos(ph), -rho * mp.sin(ph), zz) * mp.cos(th) ** 2 * rho
        out.append(2 * mp.quad(f, [0, mp.pi / 2], [0, mp.pi], method="gauss-legendre"))
    return out


def _tensor_error(got, ref):
    scale = max(abs(v) for v in ref)
    return max(float(abs(mp.mpf(float(gv)) - rv) / scale) for gv, rv in zip(got, ref,
                                                                           strict=True))


@pytest.mark.sweep
def test_hertz_field_by_superposition():
    """The closed form against 2-D mpmath quadrature of (5.41)-(5.46) over (5.15): error of
    every component relative to the largest component at the point (the tensor's scale)."""
    pts = [(0.5, 0.5, 0.3), (1.5, 0.3, 0.25), (0.2, 1.2, 0.5), (2.0, 2.0, 0.33),
           (0.9, 0.1, 0.0), (3.0, 0.05, 0.45)][:n_points(6, 2)]
    worst = 0.0
    for rr, zz, nu_ in pts:
        got = stress.hertz_stress_cylindrical(rr, zz, 1.0, 1.0, nu_)
        with mp.workdps(20):
            ref = _field_reference_superposition(mp.mpf(nu_), mp.mpf(rr), mp.mpf(zz))
            err = _tensor_error(got, ref)
        # Gauss-Legendre at 20 digits resolves these smooth integrands to ~1e-18; the closed
        # form is a few roundings and one hyp2f1 (<= 1e-15): 1e-13 leaves a margin
        assert err < 1e-13, (rr, zz, nu_, err)
        worst = max(worst, err)
    WORST["hertz_stress (superposition)"] = max(WORST.get("hertz_stress (superposition)", 0),
                                                worst)


def test_hertz_field_against_johnson_at_50_digits():
    """Across the body, including the axis (r = 1e-9 a), the surface (z = 1e-9 a), far away
    (1e4 a) and nu = 1/2, against Johnson's printed form at 50 digits (which cancels in
    float64 where ours does not); tensor-scaled relative error."""
    rng = np.random.default_rng(3)
    m = n_points(400, 80)
    rr = np.exp(rng.uniform(np.log(1e-9), np.log(1e4), m))
    zz = np.exp(rng.uniform(np.log(1e-9), np.log(1e4), m))
    nus = rng.choice([0.0, 0.3, 0.33, 0.5, -0.5], m)
    got = np.array(stress.hertz_stress_cylindrical(rr, zz, 1.0, 1.0, nus))
    assert np.all(np.isfinite(got))
    worst = 0.0
    with mp.workdps(50):
        for k in range(m):
            args = (mp.mpf(float(nus[k])), mp.mpf(float(rr[k])), mp.mpf(float(zz[k])))
            ref = [_johnson_at(c, *args) for c in ("rr", "tt", "zz", "rz")]
            worst = max(worst, _tensor_error(got[:, k], ref))
    WORST["hertz_stress_cylindrical"] = max(WORST.get("hertz_stress_cylindrical", 0), worst)
    # a few roundings, one hyp2f1 (<= 1e-14 relative) per component
    assert worst < 1e-12, worst


def test_spheroidal_coordinates():
    """(xi, beta) map back to (r, z), and u solves r^2/(a^2 + u) + z^2/u = 1."""
    r_ = np.array([0.0, 0.5, 1.0, 1.0, 1.0 + 1e-12, 2.0, 1e-8, 0.7, 1e4, 0.3])
    z_ = np.array([0.5, 0.0, 0.0, 1e-12, 0.0, 3.0, 1e-8, 0.7, 1e-3, 1e-200])
    xi, eta, chi = stress.spheroidal(r_ * 2.0, z_ * 2.0, 2.0)
    assert np.allclose(eta**2 + chi**2, 1, rtol=1e-15)
    back_r = np.sqrt(1 + xi**2) * chi
    back_z = xi * eta
    assert np.allclose(back_r, r_, rtol=1e-14, atol=1e-15)
    assert np.allclose(back_z, z_, rtol=1e-14, atol=1e-15)
    u = xi**2
    ok = u > 0
    lhs = r_[ok] ** 2 / (1 + u[ok]) + z_[ok] ** 2 / u[ok]
    assert np.allclose(lhs, 1, rtol=1e-13)


def test_spheroidal_broadcasts_its_inputs():
    """spheroidal() broadcasts r, z and a together (each of them the one array in turn, and a
    column of radii against a row of points): the shape of the result, and each value the
    scalar call's (the same operations on the same numbers: equal to the last bit)."""
    v = np.array([0.2, 0.5, 1.5])
    col = np.array([[1.0], [2.0]])
    for r_, z_, a_, shape in ((v, 0.3, 1.0, (3,)), (0.3, v, 1.0, (3,)), (0.7, 0.3, v, (3,)),
                              (v, v[::-1], col, (2, 3))):
        out = stress.spheroidal(r_, z_, a_)
        r_b, z_b, a_b = np.broadcast_arrays(r_, z_, a_)
        for k in np.ndindex(*shape):
            one = stress.spheroidal(float(r_b[k]), float(z_b[k]), float(a_b[k]))
            for got, want in zip(out, one, strict=True):
                assert got.shape == shape and got[k] == want, (k, shape)


def test_hertz_stress_cylindrical_broadcasts_its_inputs():
    """hertz_stress_cylindrical() broadcasts r, z, a, p0 and nu together, each the one array
    in turn: the shape of each component, and each value the scalar call's (the same
    operations on the same numbers: equal to the last bit)."""
    base = {"r": 0.7e-3, "z": 0.4e-3, "a": 1e-3, "p0": 1e9, "nu": 0.3}
    values = {"r": [0.2e-3, 1e-3, 2.5e-3], "z": [0.0, 0.3e-3, 2e-3], "a": [0.5e-3, 1e-3, 3e-3],
              "p0": [0.0, 1e8, 2e9], "nu": [-0.5, 0.0, 0.5]}
    for name, v in values.items():
        out = stress.hertz_stress_cylindrical(**{**base, name: np.array(v)})
        for k, x in enumerate(v):
            one = stress.hertz_stress_cylindrical(**{**base, name: x})
            for got, want in zip(out, one, strict=True):
                assert got.shape == (3,) and got[k] == want, (name, k)
    # lengths in units of a (the field depends on r/a, z/a only): a power of 2 as a scales
    # exactly, so the same bits for a = 1/2, 1, 2, 4 m as for the same point at a = 1 m
    r1, z1 = np.array([0.3, 0.9, 1.7]), np.array([0.2, 0.5, 1e-3])
    ref = stress.hertz_stress_cylindrical(r1, z1, 1.0, 1e9, 0.3)
    for aa in (0.5, 2.0, 4.0):
        got = stress.hertz_stress_cylindrical(aa * r1, aa * z1, aa, 1e9, 0.3)
        for g, w in zip(got, ref, strict=True):
            assert np.array_equal(g, w), aa


def test_spheroidal_far_away_and_empty():
    """Beyond 2^200 a (~1.6e60 a; r^4 would overflow past ~1e77 a) spheroidal() works in units
    of a power of 2 near max(r, z): (xi, cos(beta), sin(beta)) at points from 1e61 a to
    MAX_DISTANCE a (on the axis, on the surface, both large, z tiny beside r) mixed with
    points near the contact in one call, against the positive root u of
    r^2/(a^2 + u) + z^2/u = 1 in mpmath at 30 digits (xi = sqrt(u)/a, cos(beta) = z/(a xi),
    sin(beta) = r/sqrt(a^2 + u)): a few roundings of the scaled forms, 1e-14 each; no
    overflow warning on the way (warnings are errors). An empty input gives empty results."""
    aa = 2.0
    r_ = np.array([1e61, 0.0, 3e80, 1e99, 5e99, 0.5, 2e60, 7.0, 1e100])
    z_ = np.array([0.0, 1e70, 2e80, 1e-3, 5e99, 0.3, 1e-5, 1e65, 0.0])
    xi, cos_b, sin_b = stress.spheroidal(r_ * aa, z_ * aa, aa)
    with mp.workdps(30):
        for i in range(r_.size):
            rm, zm = mp.mpf(r_[i]), mp.mpf(z_[i])
            q = rm**2 + zm**2 - 1
            u = (q + mp.sqrt(q**2 + 4 * zm**2)) / 2  # in units of a^2
            ref = (mp.sqrt(u), zm / mp.sqrt(u), rm / mp.sqrt(1 + u))
            for what, got, want in zip(("xi", "cos", "sin"), (xi[i], cos_b[i], sin_b[i]), ref,
                                       strict=True):
                if want == 0:
                    assert got == 0, (what, r_[i], z_[i], got)
                else:
                    assert_close(float(got), want, 1e-14, f"{what} at ({r_[i]}, {z_[i]}) a")
    empty = stress.spheroidal(np.array([]), np.array([]), aa)
    assert all(v.shape == (0,) for v in empty)


def test_a_point_beyond_max_distance_is_named_among_many():
    """max(r, z) <= MAX_DISTANCE a: the one point beyond it among 100 (more than 64 points:
    the whole-array check first), in a row and in a 10 x 10 array, at a = 1 mm, is named by
    its own r, z and a and the valid range, by spheroidal() and hertz_stress_cylindrical();
    points exactly at MAX_DISTANCE a are accepted, alone and among 100."""
    aa = 1e-3
    r_ = np.full(100, 0.5e-3)
    # 1e101 a, beyond MAX_DISTANCE a = 1e97 m (and below MAX_DISTANCE / a = 1e103 m)
    r_[37] = 1e98
    z_ = np.linspace(0.0, 1e-3, 100)
    msg = "^" + re.escape(f"r = 1e+98, z = {float(z_[37])!r}, a = 0.001: max(r, z) is out of "
                          "range; valid: max(r, z) <= 1e+100 a")
    for func, more in ((stress.spheroidal, ()), (stress.hertz_stress_cylindrical, (1e9, 0.3))):
        for shape in ((100,), (10, 10)):
            with pytest.raises(ValueError, match=msg):
                func(r_.reshape(shape), z_.reshape(shape), aa, *more)
        edge = stress.MAX_DISTANCE * aa
        for rr, zz in ((edge, 0.0), (0.0, edge), (np.full(100, edge), z_)):
            assert all(np.all(np.isfinite(v)) for v in func(rr, zz, aa, *more))


def test_hertz_stress_cylindrical_p0_and_nu_arrays_across_blocks_and_forms():
    """p0 and nu as arrays along one axis against a column of radii (a 2 x 3 result), and as
    arrays over 40,000 points (three blocks of 16,384) near the contact and far from it (xi
    from 0 to ~60: the form with atan and, where xi >= 1, the hypergeometric one, in every
    block): each value the one the function gives for that point alone or in a block of
    1,000 (the same operations on the same numbers: equal to the last bit)."""
    col = np.array([[0.4e-3], [2.5e-3]])
    p0s, nus = np.array([1e8, 2e9, 5e9]), np.array([-0.5, 0.3, 0.5])
    out = stress.hertz_stress_cylindrical(col, 0.8e-3, 1e-3, p0s, nus)
    for i, j in np.ndindex(2, 3):
        one = stress.hertz_stress_cylindrical(col[i, 0], 0.8e-3, 1e-3, p0s[j], nus[j])
        for got, want in zip(out, one, strict=True):
            assert got.shape == (2, 3) and got[i, j] == want, (i, j)
    rng = np.random.default_rng(7)
    n = 40_000
    r_ = 1e-3 * np.exp(rng.uniform(np.log(1e-3), np.log(60.0), n))
    z_ = 1e-3 * np.exp(rng.uniform(np.log(1e-3), np.log(60.0), n))
    p0_ = rng.uniform(1e8, 3e9, n)
    nu_ = rng.choice([-0.5, 0.0, 0.3, 0.5], n)
    xi = stress.spheroidal(r_, z_, 1e-3)[0]
    for k in range(0, n, 16384):  # both forms in every block
        assert np.any(xi[k:k + 16384] < 1) and np.any(xi[k:k + 16384] >= 1), k
    out = stress.hertz_stress_cylindrical(r_, z_, 1e-3, p0_, nu_)
    for k in range(0, n, 1000):
        part = stress.hertz_stress_cylindrical(r_[k:k + 1000], z_[k:k + 1000], 1e-3,
                                               p0_[k:k + 1000], nu_[k:k + 1000])
        for got, want in zip(out, part, strict=True):
            assert np.array_equal(got[k:k + 1000], want), k


def test_field_on_the_axis_is_the_derived_axis_field():
    """The literature form at eta = 1, chi = 0, xi = z/a is the derived (5.48), (5.49), exactly."""
    s = sp.Symbol("s", positive=True)
    axis = {ds.eta: 1, ds.chi: 0, ds.xi: s}
    derived = ds.axis_stresses()
    for far in (False, True):
        f = ds.hertz_field(far)
        for comp, ref in (("rr", derived["xx"]), ("tt", derived["xx"]), ("zz", derived["zz"])):
            diff = f[comp].subs(axis) - ref.subs(z, a * s).subs(a, 1).subs(p0, 1) * p0
            diff = diff.subs(sp.atan(1 / s), sp.pi / 2 - sp.atan(s))  # s > 0
            assert sp.simplify(diff) == 0, (far, comp)
        assert f["rz"].subs(axis) == 0


def test_von_mises_invariant():
    """(5.50) equals sqrt(((s1 - s2)^2 + (s2 - s3)^2 + (s3 - s1)^2)/2) of the principal
    stresses, and is invariant under rotation."""
    rng = np.random.default_rng(0)
    m = rng.normal(size=(50, 3, 3))
    sig = m + np.swapaxes(m, -1, -2)
    ev = np.linalg.eigvalsh(sig)
    ref = np.sqrt(((ev[:, 0] - ev[:, 1]) ** 2 + (ev[:, 1] - ev[:, 2]) ** 2
                   + (ev[:, 2] - ev[:, 0]) ** 2) / 2)
    assert np.allclose(stress.von_mises(sig), ref, rtol=1e-13)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    rot = q @ sig @ q.T
    assert np.allclose(stress.von_mises(rot), stress.von_mises(sig), rtol=1e-13)
    assert np.allclose(stress.tresca(sig), ev[:, 2] - ev[:, 0], rtol=1e-13)


def test_equilibrium_and_surface_traction():
    """div sigma = 0 by 4th-order central differences on a grid; sigma_zz = -p, no shear on z = 0.

    FD error model: truncation h^4 |d^5 sigma|/30 with |d^5 sigma| <= ~1e3 p0/a^5 away from
    the edge (distance >= 0.1 a) and rounding ~ 1.5 eps |sigma|/h: at h = 1e-3 a about 1e-10 +
    3e-13; tolerance 1e-8 p0/a."""
    h = 1e-3
    nu_ = 0.3
    xs = np.linspace(-2.0, 2.0, 9)
    X, Y, Z = np.meshgrid(xs, np.array([-0.7, 0.0, 0.4]), np.array([0.15, 0.5, 1.3]))
    keep = np.abs(np.hypot(X, Y) - 1) > 0.1
    X, Y, Z = X[keep], Y[keep], Z[keep]

    def d(axis):
        def at(k):
            p = [X, Y, Z]
            p[axis] = p[axis] + k * h
            return stress.hertz_stress(p[0], p[1], p[2], 1.0, 1.0, nu_)
        return (-at(2) + 8 * at(1) - 8 * at(-1) + at(-2)) / (12 * h)

    dx, dy, dz = d(0), d(1), d(2)
    div = dx[..., :, 0] + dy[..., :, 1] + dz[..., :, 2]
    assert np.max(np.abs(div)) < 1e-8, np.max(np.abs(div))
    # the surface: the traction is the pressure (5.15)
    rs = np.linspace(0, 3, 301)
    xs_, ys_ = rs / np.sqrt(2), rs / np.sqrt(2)
    sig = stress.hertz_stress(xs_, ys_, 0.0, 1.0, 1.0, nu_)
    rr = np.hypot(xs_, ys_)  # the radius actually evaluated (the edge is a sqrt singularity)
    p = np.sqrt(np.maximum((1 - rr) * (1 + rr), 0))
    assert np.max(np.abs(sig[..., 2, 2] + p)) < 1e-15
    assert np.max(np.abs(sig[..., 0, 2])) < 1e-15 and np.max(np.abs(sig[..., 1, 2])) < 1e-15


def test_point_load_limit():
    """Far away the field is that of the point force F = (2/3) pi a^2 p0 (5.17) at the origin:
    the relative difference is O((a/R)^2)."""
    Fh = 2 / 3 * np.pi
    for R in (1e2, 1e4):
        for ang in (0.2, 0.8, 1.3):
            x, zz = R * np.sin(ang), R * np.cos(ang)
            sig = stress.hertz_stress(x, 0.0, zz, 1.0, 1.0, 0.3)
            pt = [gen.boussinesq_sigma_xx(Fh, 0.3, x, 0.0, zz), gen.boussinesq_sigma_zz(Fh, 0.3, x,
                                                                                   0.0, zz),
                  gen.boussinesq_sigma_xz(Fh, 0.3, x, 0.0, zz)]
            got = [sig[0, 0], sig[2, 2], sig[0, 2]]
            scale = max(abs(v) for v in pt)
            assert max(abs(gv - pv) for gv, pv in zip(got, pt, strict=True)) / scale < 3 / R**2


@settings(max_examples=200, deadline=None)
@given(st.floats(-1e6, 1e6), st.floats(-1e6, 1e6), st.floats(0.0, 1e6),
       st.floats(-0.99, 0.5))
def test_no_nan_anywhere(x, y, zz, nu_):
    sig = stress.hertz_stress(x, y, zz, 1.0, 1.0, nu_)
    assert np.all(np.isfinite(sig))
    assert np.isfinite(stress.von_mises(sig)) and np.isfinite(stress.tresca(sig))


def test_edge_of_contact():
    """At r = a, z = 0: sigma_rr = (1 - 2 nu) p0/3 = -sigma_theta, sigma_zz = tau_rz = 0, and the
    field is continuous there."""
    for nu_ in (0.0, 0.3, 0.5):
        srr, stt, szz, trz = stress.hertz_stress_cylindrical(1.0, 0.0, 1.0, 1.0, nu_)
        assert abs(srr - (1 - 2 * nu_) / 3) < 1e-15 and abs(stt + (1 - 2 * nu_) / 3) < 1e-15
        assert abs(szz) <= 1e-99 and abs(trz) <= 1e-99  # the limit 0, to within 1e-100
        near = stress.hertz_stress_cylindrical(1.0 + 1e-9, 1e-9, 1.0, 1.0, nu_)
        assert abs(near[0] - srr) < 1e-4  # continuous (sqrt-like approach to the edge)


def _superposition_axis_reference(p, zz):
    """sigma_zz on the axis (5.47) for a pressure p(theta) on the unit disc, rho = sin(theta)
    (the pressure is given as a function of theta, so that the rim keeps full precision)."""
    return mp.quad(lambda th: -3 * zz**3 / (2 * mp.pi) * p(th) * 2 * mp.pi
                   * mp.sin(th) * mp.cos(th) / (mp.sin(th) ** 2 + zz**2) ** 2.5,
                   _splits(zz), method="tanh-sinh")


@memo
def _punch_axis_reference(zz):
    """:func:`_superposition_axis_reference` under the flat punch's 1/(1 - rho^2)^(1/2)."""
    return _superposition_axis_reference(lambda th: 1 / mp.cos(th), zz)


def test_superposition_route():
    """Under the Hertz pressure the superposition route reproduces the closed form, and its error
    estimate bounds the actual error; under the flat-punch pressure (singular at the rim) it
    reproduces mpmath quadrature of (5.47) on the axis."""
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    pts = np.array([[0.3, 0.0, 0.2], [0.0, 0.9, 0.05], [1.4, 0.3, 0.4], [0.5, 0.5, 2.0],
                    [0.99, 0.0, 0.01]])
    sig, err = stress.superposed_stress(pts[:, 0], pts[:, 1], pts[:, 2], hp, 1.0, 0.3)
    ref = stress.hertz_stress(pts[:, 0], pts[:, 1], pts[:, 2], 1.0, 1.0, 0.3)
    actual = np.abs(sig - ref)
    # the estimate is the change from the coarse rule plus the roundings of the sums;
    # geometric convergence makes the finer result far better, so it bounds the error as it is
    assert np.all(actual <= err), (actual.max(), err.max())
    assert actual.max() < 1e-12
    punch = lambda rho: 1 / np.sqrt(1 - rho * rho)  # noqa: E731
    for zz in (0.05, 0.5, 3.0):
        s, e = stress.superposed_stress(0.0, 0.0, zz, punch, 1.0, 0.3)
        with mp.workdps(25):
            ref = _punch_axis_reference(mp.mpf(zz))
        # the estimate bounds the error (the rim's rounding term included: numeric/stress.py)
        assert abs(s[2, 2] - float(ref)) <= e[2, 2], (zz, abs(s[2, 2] - float(ref)), e[2, 2])
        assert_close(s[2, 2], ref, max(1e-12, float(e[2, 2] / abs(ref))), f"punch z={zz}")


def test_superposition_estimate_bounds_the_error_of_coarse_rules_under_the_punch():
    """The error estimate of coarse rules (8 angles; tanh-sinh levels 1 and 2, and the rules
    with half their steps) under the flat punch, whose rim singularity makes the rounding
    term (sources moved by a few ulps) as large as the rules' difference at some depths: on
    the axis from 0.5 a to 2.8 a, sigma_zz against mpmath quadrature of (5.47) at 25 digits
    (its error far below 1e-15 p0): the estimate is the sum of both terms and bounds the
    actual error at every depth (promise 2; measured: the rules' difference alone, or the
    two terms' difference, falls short at some of these depths)."""
    punch = lambda rho: 1 / np.sqrt(1 - rho * rho)  # noqa: E731
    for level in (1, 2):
        for zz in (0.5, 0.8, 0.91, 0.98, 1.22, 1.42, 1.92, 2.07, 2.78):
            s, e = stress.superposed_stress(0.0, 0.0, zz, punch, 1.0, 0.3, n_psi=8,
                                            level=level)
            with mp.workdps(25):
                ref = _punch_axis_reference(mp.mpf(zz))
            actual = abs(s[2, 2] - float(ref))
            assert actual <= e[2, 2], (level, zz, actual, e[2, 2])


def test_superposition_estimate_includes_its_roundings_and_rotates_as_a_bound():
    """Promise 2 where the rules have converged and off the coordinate planes. On the Hertz
    axis at z = a/50 (32 angles, level 4: both rules give the same float64 sum) the estimate of
    sigma_zz must still bound its error against the closed form (5.48) at 30 digits: the
    roundings of the ~1e4-term sum (16 eps times the sum of the terms' sizes; before, the
    estimate was 6e-19 relative against an error of 2e-16). At azimuth 45 degrees
    sigma_xy = (sigma_rr - sigma_theta)/2 and sigma_xx = (sigma_rr + sigma_theta)/2: errors of
    either sign add in both, so their bounds are equal (before, sigma_xy got the difference of
    the bounds, 7 times smaller at this point)."""
    a, p0, z = 1e-3, 1e9, 2e-5  # SI, as the accuracy report has it
    hp = lambda r: p0 * np.sqrt(np.clip(1 - (r / a) ** 2, 0, None))  # noqa: E731
    s, e = stress.superposed_stress(0.0, 0.0, z, hp, a, 0.3, n_psi=32, level=4)
    with mp.workdps(30):
        ref = gen_mp.stress_axis_sigma_zz(mp.mpf(a), mp.mpf(p0), mp.mpf(z))
        actual = float(abs((mp.mpf(float(s[2, 2])) - ref) / ref))
    assert 0 < actual <= e[2, 2] / abs(s[2, 2]) < 1e-13
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    s, e = stress.superposed_stress(0.5, 0.5, 0.3, hp, 1.0, 0.3, n_psi=8, level=1)
    assert e[0, 1] == e[1, 0] == pytest.approx(e[0, 0], rel=1e-12, abs=0)
    assert e[0, 0] == pytest.approx(e[1, 1], rel=1e-12, abs=0)


def test_superposed_plane_and_its_maxima():
    """superposed_plane under the Hertz pressure (a = 1, p0 = 1) against the closed-form field
    at the same grid points; its maxima are the closed form's largest values on that grid."""
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    f = stress.superposed_plane(hp, 1.0, 0.3, n=5)
    X, Z = np.meshgrid(f.x, f.z)
    ref = stress.hertz_stress(X, 0.0 * X, Z, 1.0, 1.0, 0.3)
    vm, tau = np.asarray(stress.von_mises(ref)), np.asarray(stress.max_shear(ref))
    # the superposition agrees to 1e-12 (test_superposition_route); its estimate bounds that,
    # and von Mises and (sigma_1 - sigma_3)/2 are within 2 components' errors of each other
    for got, want in ((f.von_mises, vm), (f.max_shear, tau)):
        assert np.max(np.abs(got - want)) <= 2 * f.rel_error * np.max(np.abs(ref)) + 1e-14
    k = np.unravel_index(int(np.argmax(vm)), vm.shape)
    value, x, z = f.maximum("von_mises")
    assert (x, z) == (f.x[k[1]], f.z[k[0]]) and abs(value - vm[k]) < 1e-12
    k = np.unravel_index(int(np.argmax(tau)), tau.shape)
    value, x, z = f.maximum("max_shear")
    assert (x, z) == (f.x[k[1]], f.z[k[0]]) and abs(value - tau[k]) < 1e-12
    with pytest.raises(ValueError, match=r"^criterion = 'tresca'; valid: 'von_mises', "
                                         r"'max_shear', 'orthogonal_shear'$"):
        f.maximum("tresca")
    with pytest.raises(ValueError, match="n = 1"):
        stress.superposed_plane(hp, 1.0, 0.3, n=1)


def test_stress_modules_import_no_sympy_scipy_matplotlib():
    import subprocess
    import sys

    code = ("import sys, hertzmdr.numeric.stress, hertzmdr.numeric.plots;"
            "print(','.join(m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="nu = 0.6"):
        stress.hertz_stress(0.0, 0.0, 1.0, 1.0, 1.0, 0.6)
    with pytest.raises(ValueError, match="z = -1.0"):
        stress.hertz_stress(0.0, 0.0, -1.0, 1.0, 1.0, 0.3)
    with pytest.raises(ValueError, match=r"z = 0.0 is out of range; valid: z > 0"):
        stress.superposed_stress(0.0, 0.0, 0.0, lambda r: r, 1.0, 0.3)
    with pytest.raises(ValueError, match="pressure"):
        stress.superposed_stress(0.0, 0.0, 1.0, 3.0, 1.0, 0.3)


@memo
def _bracket_slopes_and_root(nu_, lo):
    """The derivation's slope of tau_1 at z = lo and 2a, and its root between them (anderson),
    at 30 digits, for nu_ (a float, taken exactly)."""
    s = sp.Symbol("s", positive=True)
    tau = (ds.max_shear_axis() / p0).subs(z, a * s).subs(a, 1).subs(nu, sp.Float(nu_, 40))
    slope = sp.lambdify(s, sp.diff(tau, s), "mpmath")
    with mp.workdps(30):
        return (slope(mp.mpf(lo)), slope(mp.mpf(2)),
                mp.findroot(slope, (mp.mpf(lo), mp.mpf(2)), solver="anderson"))


def test_axis_maximum_shear_bracket():
    """Over the whole -1 < nu <= 1/2: the slope of tau_1 (the derivation's, at 30 digits) is
    > 0 at the derived z_lo and < 0 at 2a, and the float64 maximum agrees with a 30-digit
    root found by bisection on that bracket, down to nu = nextafter(-1, 0) where the maximum
    lies at 6e-17 a (the fixed bracket 0.05 a ... 2 a missed it for nu < -0.8985)."""
    nus = [np.nextafter(-1.0, 0.0), -1 + 1e-10, -0.99, -0.9, -0.8985, -0.5, 0.0, 0.3, 0.5]
    for nu_ in nus:
        lo = float(gen.stress_axis_max_shear_bracket(1.0, nu_))
        at_lo, at_2, root = _bracket_slopes_and_root(float(nu_), lo)
        assert at_lo > 0 and at_2 < 0, nu_
        zf, _ = stress.axis_max_shear(nu_)
        # a simple root to 4 ulp of the slope by Brent, with a relative tolerance: ~1e-15
        assert_close(zf, root, 1e-14, f"z/a at nu = {nu_!r}")


# the public functions with one valid set of inputs each (SI: m, Pa; nu dimensionless)
PUBLIC = [
    (stress.spheroidal, dict(r=0.5, z=0.3, a=1.0)),
    (stress.hertz_stress_cylindrical, dict(r=0.5, z=0.3, a=1.0, p0=1e9, nu=0.3)),
    (stress.hertz_stress, dict(x=0.5, y=0.2, z=0.3, a=1.0, p0=1e9, nu=0.3)),
    (stress.axis_stresses, dict(z=0.3, a=1.0, p0=1e9, nu=0.3)),
    (stress.axis_max_shear, dict(nu=0.3)),
]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[f.__name__ for f, _ in PUBLIC])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def test_max_shear_of_known_principal_stresses():
    """max_shear is half the spread of the principal stresses: a tensor built from chosen
    principal values (1, -2, 3) Pa in a rotated frame has (3 - (-2))/2 = 2.5 Pa; tresca 5 Pa.
    Rotation and eigenvalues in float64: a few ulps of 5 (1e-14)."""
    c, s = np.cos(0.7), np.sin(0.7)
    Q = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ np.array(
        [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    sig = Q @ np.diag([1.0, -2.0, 3.0]) @ Q.T
    assert abs(stress.max_shear(sig) - 2.5) < 1e-14
    assert abs(stress.tresca(sig) - 5.0) < 1e-14
    both = stress.max_shear(np.stack([sig, 2 * sig]))
    assert np.allclose(both, [2.5, 5.0], rtol=1e-14, atol=0)


def test_hertz_maximum_refuses_an_unknown_criterion():
    with pytest.raises(ValueError, match=r"^criterion = 'rankine'; valid: \['max_shear', "
                                         r"'tresca', 'von_mises'\]$"):
        stress.hertz_maximum(0.3, "rankine")


def test_superposition_fills_both_rules_and_its_estimate_is_tight():
    """Three field points not used elsewhere, right after freeing an array of NaN of the size
    of the routine's work array (NumPy's allocator tends to hand that memory back, so a rule
    never written shows up as NaN instead of a stale result). Against the closed form; the
    error estimate (the change from the coarse rule) is not only an upper bound but small:
    both rules are converged here (measured 8e-16 p0), so below 1e-12 p0 as the test above."""
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    pts = np.array([[0.6, 0.2, 0.3], [0.1, 0.0, 0.5], [1.2, -0.4, 0.25]])
    junk = np.full((3, 2, 4), np.nan)
    del junk
    sig, err = stress.superposed_stress(pts[:, 0], pts[:, 1], pts[:, 2], hp, 1.0, 0.3)
    ref = stress.hertz_stress(pts[:, 0], pts[:, 1], pts[:, 2], 1.0, 1.0, 0.3)
    assert np.all(np.isfinite(sig)) and np.all(np.isfinite(err))
    assert np.abs(sig - ref).max() < 1e-12
    # both rules converged: the estimate is the roundings' term, and bounds the error (without
    # it, the rules' difference fell short at two of these components: 1.6 times)
    assert np.all(np.abs(sig - ref) <= err)
    assert err.max() < 1e-12


def test_more_inputs_named_and_the_criteria_by_name():
    """Inputs of the tensor criteria, hertz_maximum and superposed_stress named in their errors;
    hertz_maximum's default criterion is von Mises, and "max_shear" is half of Tresca (the
    maximum of sigma_1 - sigma_3 over the body, by the same search)."""
    sig = np.diag([1.0, -2.0, 3.0])
    assert_inputs_named(stress.von_mises, dict(sigma=sig))
    assert_inputs_named(stress.tresca, dict(sigma=sig))
    assert_inputs_named(lambda nu: stress.hertz_maximum(nu, "tresca"), dict(nu=0.3))
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    assert_inputs_named(lambda x, y, z, a, nu: stress.superposed_stress(x, y, z, hp, a, nu,
                                                                        n_psi=8, level=2),
                        dict(x=0.2, y=0.1, z=0.3, a=1.0, nu=0.3))
    assert stress.hertz_maximum(0.3) == stress.hertz_maximum(0.3, "von_mises")
    shear, r_s, z_s = stress.hertz_maximum(0.3, "max_shear")
    tres, r_t, z_t = stress.hertz_maximum(0.3, "tresca")
    # the same peak found twice by Nelder-Mead (flat there: 1e-13 in value, as above)
    assert abs(2 * shear / tres - 1) < 1e-13


def test_superposed_plane_names_its_inputs():
    """superposed_plane names a and nu in its errors (each NaN in turn), on its smallest grid."""
    hp = lambda rho: np.sqrt(np.maximum(1 - rho * rho, 0.0))  # noqa: E731
    assert_inputs_named(lambda a, nu: stress.superposed_plane(hp, a, nu, n=2),
                        dict(a=1.0, nu=0.3))


def test_orthogonal_shear_maximum_by_superposition():
    """The derived largest |tau_rz| and its place against Newton's method on the gradient of
    tau_rz superposed from the point-force field (tests/kernels.py's rings, no closed form),
    at 35 digits, from the float64 answer; compared to 30 digits with the derivation."""
    from kernels import hertz_tau_rz

    value, r0, z0 = stress.hertz_max_orthogonal_shear()
    with mp.workdps(20):  # the Hessian only steers Newton (its root is where the gradient
        h = mp.mpf(10) ** -6  # vanishes): central differences, ~1e-12 relative, suffice
        cols = []
        for dr, dz in ((h, 0), (0, h)):
            gp = hertz_tau_rz(r0 + dr, z0 + dz, degree=4)[1:]
            gm = hertz_tau_rz(r0 - dr, z0 - dz, degree=4)[1:]
            cols.append([(p - m) / (2 * h) for p, m in zip(gp, gm, strict=True)])
        hess = mp.matrix([[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]])
    with mp.workdps(35):
        pt = mp.matrix([r0, z0])
        for _ in range(3):  # 1e-16 -> ~1e-28 -> below 1e-35: the third step checks it
            tau, *grad = hertz_tau_rz(pt[0], pt[1])
            step = mp.lu_solve(hess, mp.matrix(grad))
            pt -= step
            if mp.norm(step) < mp.mpf(10) ** -32:
                break
        assert mp.norm(step) < mp.mpf(10) ** -32  # converged: the gradient is 0 to ~1e-32
        exact = {k: v.evalf(40) for k, v in ds.orthogonal_shear_maximum().items()}
        # Gauss-Legendre at 35 digits resolves the rings' smooth integrands to ~1e-33 (the
        # result is unchanged from degree 5 to 6 to 32 digits): 30 digits is the claim
        for got, key in ((pt[0], "r"), (pt[1], "z"), (-tau, "value")):
            assert abs(got - mp.mpf(str(exact[key]))) < mp.mpf(10) ** -30 * abs(got), key
    # float64: a few roundings of sqrt(17) and its powers
    for got, key in ((value, "value"), (r0, "r"), (z0, "z")):
        assert_close(got, mp.mpf(str(exact[key])), 4e-16, key)
    assert round(value, 4) == 0.2139 and round(r0, 3) == 0.848 and round(z0, 3) == 0.351


def test_point_force_shear_is_the_ring_routes_kernel():
    """tests/kernels.py's rings integrate tau_xz = -3 x z^2/(2 pi R^5) of a unit force: the
    derived (5.46) is that."""
    k = b.stresses()["xz"].subs(F, 1)
    R2 = b.x**2 + b.y**2 + b.z**2
    assert sp.simplify(k * R2 ** sp.Rational(5, 2) / (b.x * b.z**2) + 3 / (2 * sp.pi)) == 0


def test_orthogonal_shear_maximum_is_the_largest_in_the_body():
    """No point of a 200 x 200 grid over 0 <= r, z <= 3a has a larger |tau_rz| (the boundaries
    of the quadrant and infinity have tau_rz = 0; nu does not enter)."""
    value, r0, z0 = stress.hertz_max_orthogonal_shear()
    rr, zz = np.meshgrid(np.linspace(0, 3, 200), np.linspace(0, 3, 200))
    for nu_ in (-0.5, 0.3, 0.5):
        trz = stress.hertz_stress_cylindrical(rr, zz, 1.0, 1.0, nu_)[3]
        assert np.max(np.abs(trz)) <= value * (1 + 1e-15)
        # at the maximum the closed form's field gives the same value (to its rounding)
        at = stress.hertz_stress_cylindrical(r0, z0, 1.0, 1.0, nu_)[3]
        assert_close(-float(at), mp.mpf(value), 1e-14, f"tau_rz at the maximum, nu={nu_}")
    # the grid comes within its spacing (0.015 a) of the maximum: tau_rz is flat there
    assert np.max(np.abs(trz)) > value * (1 - 1e-3)

def test_plane_field_maximum_is_located_on_its_grid():
    """PlaneField.maximum on a field whose largest value lies off the grid's first row, column
    and diagonal: the value and its (x, z) (field indexed [z][x])."""
    x, z = np.array([0.0, 1.0, 2.0]), np.array([10.0, 20.0, 30.0, 40.0])
    vm = np.zeros((4, 3))
    vm[2, 1] = 5.0  # z = 30, x = 1
    tau = np.zeros((4, 3))
    tau[3, 0] = 7.0  # z = 40, x = 0
    trz = np.zeros((4, 3))
    trz[1, 2] = 3.0  # z = 20, x = 2
    f = stress.PlaneField(x, z, vm, tau, trz, 0.0)
    assert f.maximum("von_mises") == (5.0, 1.0, 30.0)
    assert f.maximum("max_shear") == (7.0, 0.0, 40.0)
    assert f.maximum("orthogonal_shear") == (3.0, 2.0, 20.0)


def test_superposed_plane_on_its_smallest_grid():
    """n = 2, the smallest grid: x = 0, 2a and z = 2a, the closed-form Hertz field there
    (a = 2 mm, p0 = 1 Pa); n = 1, 1.5 and True refused by name."""
    a = 2e-3
    f = stress.superposed_plane(lambda rho: np.sqrt(np.maximum(1 - (rho / a) ** 2, 0.0)), a,
                                0.3, n=2)
    assert f.x.tolist() == [0.0, 2 * a] and f.z.tolist() == [2 * a]
    ref = stress.hertz_stress(f.x, 0.0 * f.x, 2 * a + 0.0 * f.x, a, 1.0, 0.3)
    # superposition to ~1e-12 of the largest component (test_superposition_route)
    assert np.max(np.abs(f.von_mises[0] - stress.von_mises(ref))) < 1e-11
    for bad in (1, 1.5, True):
        with pytest.raises(ValueError, match=rf"^n = {bad!r} is out of range; valid: an "
                                             r"integer >= 2$"):
            stress.superposed_plane(lambda rho: rho, a, 0.3, n=bad)


def test_superposed_plane_error_is_relative():
    """rel_error is the error estimate over the largest stress: the same for the Hertz pressure
    at p0 = 1 Pa and at p0 = 1 GPa (the field is linear in p), and as small as the
    superposition's accuracy (1e-12 of the largest component, test_superposition_route)."""
    a = 2e-3

    def hp(rho, p0):
        return p0 * np.sqrt(np.maximum(1 - (rho / a) ** 2, 0.0))

    unit = stress.superposed_plane(lambda rho: hp(rho, 1.0), a, 0.3, n=2)
    giga = stress.superposed_plane(lambda rho: hp(rho, 1e9), a, 0.3, n=2)
    assert 0 < unit.rel_error < 1e-11
    # the same quadrature on a pressure 1e9 times larger; both estimates are at the rounding
    # level here (~2e-15), which differs between the two scalings by a few tenths of itself
    assert 0.5 < giga.rel_error / unit.rel_error < 2


def test_superposed_maximum_of_the_orthogonal_shear_within_its_bound():
    """superposed_maximum (the refined largest stress of the superposition route, with its
    bound) under the Hertz pressure (a = 2 mm, p0 = 1 GPa) on a 5-point grid: the orthogonal
    shear against the derived closed form (hertz_max_orthogonal_shear, exact: |tau_rz| =
    0.213891 p0 at r = 0.848 a, z = 0.351 a), and von Mises against 2 tau_1 on the axis
    (axis_max_shear, Fig. 5.8), and the maximum shear (sigma_1 - sigma_3)/2 against tau_1 there
    (sigma_rr = sigma_tt on the axis): the actual error within the bound it reports, the bound below
    1e-2 (the grid alone misses by about that), the place within 0.02 a (the field is flat at
    its maximum: an error e in the value allows ~sqrt(e) a in the place)."""
    aa, p00, nu_ = 2e-3, 1e9, 0.3
    p = lambda rr: p00 * np.sqrt(np.maximum((1 - np.asarray(rr) / aa)  # noqa: E731
                                            * (1 + np.asarray(rr) / aa), 0.0))
    plane = stress.superposed_plane(p, aa, nu_, n=5)
    tau, r0, z0 = stress.hertz_max_orthogonal_shear()
    zt, t1 = stress.axis_max_shear(nu_)
    for crit, ref, x_ref, z_ref in (("orthogonal_shear", tau, r0, z0),
                                    ("von_mises", 2 * t1, 0.0, zt), ("max_shear", t1, 0.0, zt)):
        v, x, z, bound = stress.superposed_maximum(p, aa, nu_, crit, plane)
        err = abs(v / (ref * p00) - 1)
        assert err <= bound < 1e-2, (crit, err, bound)
        assert abs(abs(x) / aa - x_ref) < 0.02 and abs(z / aa - z_ref) < 0.02, (crit, x, z)
    with pytest.raises(ValueError, match=r"^criterion = 'tresca'; valid: 'von_mises', "
                                         r"'max_shear', 'orthogonal_shear'$"):
        stress.superposed_maximum(p, aa, nu_, "tresca", plane)
    with pytest.raises(ValueError, match="^a"):
        stress.superposed_maximum(p, -aa, nu_, "von_mises", plane)


# superposed_maximum's bound, part by part. Its refinement climbs the superposed field itself;
# the plane only chooses where it starts and gives the curvature of the bound's miss term. A
# plane whose field is a polynomial has second differences known exactly, and a large xatol
# makes that term (~1e-2) stand out over the quadrature's estimate (~1e-15 for the smooth
# Hertz pressure) by 13 digits: the bound is then the error model's sum to ~1e-12 of itself.
_A, _P0 = 2e-3, 1e9


def _hertz_p(rr):
    return _P0 * np.sqrt(np.maximum((1 - np.asarray(rr) / _A) * (1 + np.asarray(rr) / _A), 0.0))


def _poly_plane(x0, z0, c, nx=7, nz=9):
    """A PlaneField (every criterion the same field) on nx x-points 0 ... 2a and the nz - 1
    z-points 0 < z <= 2a (hx = 2a/(nx - 1) != hz = 2a/(nz - 1), so hx and hz cannot be
    swapped unseen), its field p0 (1 - A dX^2 - B dZ^2 - C dX dZ - G dX^2 dZ + E dZ^3 - K dX^4)
    with dX = x/a - x0, dZ = z/a - z0, and its exact central second differences [Pa/a^2]
    (Taylor's series of a polynomial ends: those of dX^2, dZ^2, dZ^3 and the mixed one of
    dX dZ, dX^2 dZ are the derivatives; that of dX^4 is 12 dX^2 + 2 hx^2) as a function of
    the node (X, Z)."""
    A, B, C, G, E, K = c
    x = _A * np.linspace(0.0, 2.0, nx)
    z = _A * np.linspace(0.0, 2.0, nz)[1:]
    hx = 2.0 / (nx - 1)
    X, Z = np.meshgrid(x / _A - x0, z / _A - z0)
    f = _P0 * (1 - A * X**2 - B * Z**2 - C * X * Z - G * X**2 * Z + E * Z**3 - K * X**4)

    def curvature(xn, zn):
        dx, dz = xn - x0, zn - z0
        fxx = -2 * A - 2 * G * dz - K * (12 * dx**2 + 2 * hx**2)
        fzz = -2 * B + 6 * E * dz
        fxz = -C - 2 * G * dx
        return _P0 * (abs(fxx) + 2 * abs(fxz) + abs(fzz))

    return stress.PlaneField(x, z, f, f.copy(), f.copy(), 0.0), curvature


def _miss_model(curv, s, value):
    """The bound's miss term as its docstring states it: 4 (for the grid's averaging) times
    1/2 (|f_xx| + 2 |f_xz| + |f_zz|) (2 s)^2 over the value."""
    return 4 * 0.5 * curv * (2 * s) ** 2 / value


@pytest.mark.parametrize("case", ["axis", "off_axis", "corner"])
def test_superposed_maximum_bound_takes_the_curvature_of_the_plane(case):
    """The miss term of superposed_maximum's bound (von Mises, Hertz pressure, nu = 0.3) from a
    polynomial plane, against the model with the plane's exact second differences, at the
    node where the plane is largest: on the axis (columns mirrored at x = 0, the field even in
    x), off it (the mixed term), at the far corner (row and column shifted inwards). Each
    plane's peak is off its node, so the differences are not symmetric about it, and not where
    the field's maximum is (0, 0.481 a), so the refinement starts elsewhere: it still reaches
    2 tau_1 (derivation, 30 digits) to 1e-10 (Nelder-Mead's final simplex, ~1e-5 a, on a
    peak curving by ~1 per a^2), and with xatol = 0.05 the final simplex (~1e-6 a: fatol is
    what stops it) is well inside xatol, so s = xatol."""
    z30, t30 = _axis_maxima("0.3")
    xs, zs = _A * np.linspace(0.0, 2.0, 7), _A * np.linspace(0.0, 2.0, 9)[1:]
    if case == "axis":  # node (0, 0.75 a); even in x: C = 0
        x0, z0, c, node = 0.0, 0.78, (0.5, 0.7, 0.0, 0.3, 0.2, 0.4), (0, 2)
    elif case == "off_axis":  # node (2/3 a, 0.5 a)
        x0, z0, c, node = 0.7, 0.47, (0.5, 0.7, 0.3, 0.3, 0.2, 0.4), (2, 1)
    else:  # node (2 a, 2 a): curvature read at (5/3 a, 1.75 a)
        x0, z0, c, node = 2.1, 2.05, (0.5, 0.7, 0.3, 0.3, 0.2, 0.4), (6, 7)
    plane, curvature = _poly_plane(x0, z0, c)
    assert np.unravel_index(int(np.argmax(plane.von_mises)), plane.von_mises.shape) \
        == node[::-1]
    xa, za = (min(node[0], 5), min(max(node[1], 1), 6))  # where the bound reads the curvature
    xatol = 0.05
    v, x, z, bound = stress.superposed_maximum(_hertz_p, _A, 0.3, "von_mises", plane,
                                               xatol=xatol)
    ref = 2 * float(t30) * _P0
    # where Nelder-Mead stops (its simplex up to ~1e-5 a wide) is within ~1e-10 of the peak
    assert abs(v / ref - 1) < 1e-10 and abs(z / _A - float(z30)) < 1e-5 and abs(x) < 1e-5 * _A
    want = _miss_model(curvature(xs[xa] / _A, zs[za] / _A), xatol, v)
    # the quadrature's estimate (~1e-15) is the only other part, ~1e-13 of the miss term
    assert 1e-3 < want and abs(bound / want - 1) < 1e-10, (bound, want)


@cache
def _axis_tau_funcs(nu_):
    """tau_1/p0 of the derivation on the axis and its slope, functions of s = z/a for mpmath
    (nu a decimal string, exact)."""
    s_ = sp.Symbol("s", positive=True)
    tau = (ds.max_shear_axis() / p0).subs(z, a * s_).subs(a, 1).subs(nu, sp.Rational(nu_))
    return sp.lambdify(s_, tau, "mpmath"), sp.lambdify(s_, sp.diff(tau, s_), "mpmath")


@memo
def _axis_tau_30(nu_, zz, peak=False):
    """tau_1/p0 of the derivation on the axis (nu a decimal string) at z/a = zz, or with
    peak=True (z/a, tau_1/p0) at the root of its slope found from zz, at 30 digits."""
    value, slope = _axis_tau_funcs(nu_)
    with mp.workdps(30):
        if not peak:
            return +value(mp.mpf(zz))
        root = mp.findroot(slope, mp.mpf(zz))
        return +root, +value(root)


def _hertz_plane(nu_, n=5):
    """The PlaneField superposed_plane makes for the Hertz pressure, from the closed form
    (the same field to 1e-12, test_superposed_plane_and_its_maxima) in a fraction of its time."""
    x = np.linspace(0.0, 2.0 * _A, n)
    z = np.linspace(0.0, 2.0 * _A, n)[1:]
    X, Z = np.meshgrid(x, z)
    sig = stress.hertz_stress(X, 0.0 * X, Z, _A, _P0, nu_)
    return stress.PlaneField(x, z, np.asarray(stress.von_mises(sig)),
                             np.asarray(stress.max_shear(sig)), np.abs(sig[..., 0, 2]), 1e-15)


def test_superposed_maximum_bound_extrapolates_to_the_surface():
    """At nu = -0.9999 the largest shear (sigma_1 - sigma_3)/2 under the Hertz pressure lies
    at z = 5e-5 a, above the route's lowest depth 1e-3 a (tau_1 = 3 p0/(4 (1 + s^2)) at
    nu = -1, derive/stress.py): the refinement stops there and the bound adds the change of
    the value over the last 1e-3 a, |tau(1e-3 a) - tau(2e-3 a)| (derivation, 30 digits), to
    the miss term, here read from a polynomial plane largest on its top row (curvature one
    row inwards, at 0.5 a) with xatol = 0.05: the sum to 1e-9 of itself (the extrapolation
    term, 2.9e-6, is 3e-4 of it; the quadrature's estimate ~1e-15)."""
    plane, curvature = _poly_plane(0.0, 0.2, (0.5, 0.7, 0.0, 0.3, 0.2, 0.4))
    assert np.unravel_index(int(np.argmax(plane.max_shear)), plane.max_shear.shape) == (0, 0)
    xatol = 0.05
    v, x, z, bound = stress.superposed_maximum(_hertz_p, _A, -0.9999,
                                               "max_shear", plane, xatol=xatol)
    assert z == 1e-3 * _A and abs(x) < 1e-5 * _A
    t1, t2 = (float(_axis_tau_30("-0.9999", zz)) for zz in ("0.001", "0.002"))
    # Nelder-Mead stops with its vertices' values within fatol = 1e-13 of each other, its
    # simplex up to ~1e-5 a wide (measured 3e-6 ... 7e-6 a): a point that close to the axis,
    # where the field curves by ~1 per a^2, is within ~1e-10 of the value there
    assert abs(v / (t1 * _P0) - 1) < 1e-10
    extrapolation = (t1 - t2) / t1
    want = _miss_model(curvature(0.0, 0.5), xatol, v) + extrapolation
    assert 2e-6 < extrapolation and abs(bound / want - 1) < 1e-9, (bound, want, extrapolation)


@pytest.mark.parametrize("nu_, start", [("-0.9999", "5e-5"), ("-0.995", "2.6e-3")])
def test_superposed_maximum_near_the_surface_within_its_bound(nu_, start):
    """The largest shear under the Hertz pressure at nu = -0.9999 (at z = 5e-5 a, above the
    route's lowest depth 1e-3 a) and at nu = -0.995 (at z = 2.6e-3 a, just below twice it),
    from the plane superposed_plane makes (n = 5), against the derivation's maximum on the
    axis (30 digits): the actual error within the bound. At -0.9999 the linear extrapolation
    over the last 1e-3 a sets the bound (the field falls by ~(1 + s^2)^-1 from 5e-5 a to
    1e-3 a, 6.7e-7, and by 3 times that more over the next 1e-3 a): within 10 times the
    error. At -0.995 the maximum is reached, there is nothing to extrapolate: the bound is the
    curvature's and the quadrature's, 4e-9 (the extrapolation over (2e-3 a, 2.6e-3 a) would
    add ~5e-7)."""
    zr, tr = _axis_tau_30(nu_, start, peak=True)
    v, x, z, bound = stress.superposed_maximum(_hertz_p, _A, float(nu_), "max_shear",
                                               _hertz_plane(float(nu_)))
    err = abs(v / (float(tr) * _P0) - 1)
    assert err <= bound, (err, bound)
    if nu_ == "-0.9999":
        assert zr < 1e-4 and z == 1e-3 * _A and bound < 10 * err, (zr, z, err, bound)
    else:
        assert 2e-3 < zr < 3e-3 and abs(z / _A - float(zr)) < 1e-4 and bound < 1e-7, \
            (zr, z, err, bound)
