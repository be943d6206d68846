"""The Abel transforms of sampled contact data (numeric/abel.py), (5.59) and (5.61).

References, each by a route independent of the transform: the generated closed forms of the
MDR (Hertz (5.15), the power-law pressures of Problem 7, derived by SymPy from (5.52)/(5.59)),
the worn paraboloid's pressure by mpmath quadrature of (5.59) (tests/test_worn.py), and the
Gaussian Abel pair exp(-r^2) <-> sqrt(pi) exp(-x^2) for the transform without a contact edge.

Error model (module docstring of numeric/abel.py): the interpolant is a piecewise polynomial
of degree m in s = x^2, integrated exactly against the kernel. Data that are polynomials in s
of degree <= m inside the support (Hertz, n = 4; for (5.61) p/sqrt(a^2 - r^2)) are transformed
to rounding: the inverse loses ~log10(N) digits to the derivative (q_i/dx differences), the
forward none. Otherwise the error is set by the smoothness in s: |x|^n at the axis is s^(n/2),
which limits (5.59) to O(dx^(n-1)) and (5.61) to O(dx^n) near the axis; the worn profile's
sqrt(x^2 - b^2) at x = b limits (5.59) to O(dx^1.5) for r < b.
"""

import math
import os
import subprocess
import sys

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import abel
from hertzmdr.numeric._abel import edge as abel_edge
from hertzmdr.numeric._abel import moments, operators

from oracle import WORST, memo
from test_worn import pressure_ref

# the mpmath references, memoized in a mutation run (tests/oracle.py's memo; each a pure
# function of its arguments, mpmath and tests/ only, never numeric/)
worn_pressure_ref = memo(pressure_ref)  # (5.59) of the worn paraboloid by quadrature

E = 2.1e11  # Pa
A_CONTACT = 3e-4  # m
D = 2e-6  # m


@pytest.fixture(autouse=True)
def _operators_built_anew_under_mutation_testing():
    """Under mutmut (benchmarks/mutation.py) each mutant's tests run in a process forked from
    one that has run them all, with the operator and edge caches full: a mutant of a builder
    would never be called. There every test builds its operators anew."""
    if os.environ.get("MUTANT_UNDER_TEST"):
        operators._CACHE.clear()
        abel_edge._EDGE_CACHE.clear()


def _record(what, err, tol):
    WORST[what] = max(WORST.get(what, 0.0), float(err))
    assert err <= tol, f"{what}: {err:.3g} > {tol:.3g}"


def grid(N, span=1.2):
    """PyAbel's grid x_i = i dx on [0, span*a]; a = A_CONTACT is never a grid point."""
    x = np.linspace(0, span * A_CONTACT, N)
    return x, x[1]


def powerlaw_pair(n, x):
    """q = E* (d - g(x)) (5.58) with g = kappa c |x|^n, and the closed-form pressure."""
    kappa = float(gen.powerlaw_kappa(n))
    c = D / (kappa * A_CONTACT**n)  # so that g(a) = d (5.55)
    q = np.where(x < A_CONTACT, E * (D - gen.powerlaw_g(c, kappa, n, np.minimum(x, A_CONTACT))),
                 0.0)
    if n >= 1.5:
        p = gen.powerlaw_pressure(E, A_CONTACT, D, n, x)
    else:
        p = gen.powerlaw_pressure_small_n(E, A_CONTACT, D, n, x)
    return q, p


def rel_err(got, ref, mask):
    return float(np.max(np.abs(got[mask] / ref[mask] - 1)))


def inside(x, lo=0.0, hi=0.95):
    return (x >= lo * A_CONTACT) & (x <= hi * A_CONTACT)


@pytest.mark.parametrize("N", [51, 201, 801])
def test_hertz_to_rounding(N):
    """Hertz: q = E*(d - x^2/R) is linear in s, p/sqrt(a^2 - r^2) constant: both exact."""
    x, dx = grid(N)
    R = A_CONTACT**2 / D
    q = np.where(x < A_CONTACT, E * (D - x**2 / R), 0.0)
    p = gen.hertz_pressure(E, R, D, x)
    m = inside(x)
    # inverse: the rounding of q (1e-16 q_max) divided by the differences of ~N samples
    _record("abel inverse Hertz", rel_err(abel.pressure_from_line_load(q, dx), p, m), 2e-15 * N)
    # forward: a sum of positive terms, no amplification: a few ulp
    _record("abel forward Hertz", rel_err(abel.line_load_from_pressure(p, dx), q, m), 1e-14)


@pytest.mark.parametrize("degree", [2, 3, 5])
def test_powerlaw_n4_to_rounding(degree):
    """n = 4: q is quadratic in s (exact for degree >= 2); p/sqrt(a^2 - r^2) is linear in s."""
    x, dx = grid(301)
    q, p = powerlaw_pair(4, x)
    m = inside(x)
    _record("abel inverse n=4", rel_err(abel.pressure_from_line_load(q, dx, degree=degree), p, m),
            2e-15 * 301)  # rounding amplified by ~N, as for Hertz
    _record("abel forward n=4", rel_err(abel.line_load_from_pressure(p, dx, degree=degree), q, m),
            1e-14)


@pytest.mark.parametrize("k", [0, 1, 2, 3, 4])
def test_polynomials_in_s_to_rounding(k):
    """The Abel pair p = (a^2 - r^2)^(k + 1/2) <-> q = B(k + 3/2, 1/2) (a^2 - x^2)^(k + 1)
    (Euler's Beta integral): q is a polynomial of degree k + 1 in s, p/sqrt(a^2 - r^2) one of
    degree k, so the quintic reproduces both and every moment v^0..v^5 of the exact
    integration enters: rounding only (inverse: ~N ulp from the differences of q; forward:
    a few ulp, the moments are sums of positive terms). For k >= 1 these vanish faster than a
    contact's q ~ a - x, p ~ sqrt(a - r), which the edge finder assumes: the edge is given."""
    x, dx = grid(201)
    a2 = A_CONTACT**2
    beta = math.gamma(k + 1.5) * math.gamma(0.5) / math.gamma(k + 2)
    gap = np.clip(a2 - x**2, 0, None) / a2
    p = E * gap ** (k + 0.5)
    q = E * A_CONTACT * beta * gap ** (k + 1)
    m = inside(x)
    p_got = abel.pressure_from_line_load(q, dx, edge=A_CONTACT)
    q_got = abel.line_load_from_pressure(p, dx, edge=A_CONTACT)
    _record("abel inverse (a^2-x^2)^(k+1)", rel_err(p_got, p, m), 2e-15 * 201)
    _record("abel forward (a^2-r^2)^(k+1/2)", rel_err(q_got, q, m), 1e-14)


def _errors(n, Ns, degree, lo=0.0):
    inv, fwd = [], []
    for N in Ns:
        x, dx = grid(N)
        q, p = powerlaw_pair(n, x)
        m = inside(x, lo=lo) & (x > 0 if n < 1.5 else True)
        inv.append(rel_err(abel.pressure_from_line_load(q, dx, degree=degree), p, m))
        if n > 1:
            fwd.append(rel_err(abel.line_load_from_pressure(p, dx, degree=degree), q, m))
    return np.array(inv), np.array(fwd)


def _order(Ns, errs):
    return float(-np.polyfit(np.log(Ns), np.log(errs), 1)[0])


@pytest.mark.parametrize("n, level_inv, level_fwd", [(2.5, 1.9e-5, 9.1e-8),
                                                  (3.5, 4.4e-8, 2.9e-10)])
def test_powerlaw_noninteger_converges_at_its_order(n, level_inv, level_fwd):
    """q ~ s^(n/2) at the axis: the orders are n - 1 (inverse) and n (forward), set by the
    first pieces. Measured (degree 5, N = 101, 201, 401, 0 <= r <= 0.95 a): n = 2.5: 1.51,
    2.51; n = 3.5: 2.51, 3.53; away from the axis (r >= 0.1 a) ~5 (the degree). Asserted: the
    orders minus 0.2 (a three-point fit), the levels at N = 401 (measured, given as
    level_inv/level_fwd) with a factor 2 of margin (another BLAS may round differently)."""
    Ns = np.array([101, 201, 401])
    inv, fwd = _errors(n, Ns, 5)
    o_inv, o_fwd = _order(Ns, inv), _order(Ns, fwd)
    _record(f"abel order inverse n={n} (>= n - 1.2)", (n - 1.2) / o_inv, 1.0)
    _record(f"abel order forward n={n} (>= n - 0.2)", (n - 0.2) / o_fwd, 1.0)
    _record(f"abel inverse n={n} N=401", inv[-1], 2 * level_inv)
    _record(f"abel forward n={n} N=401", fwd[-1], 2 * level_fwd)


def test_cone_converges_away_from_the_axis():
    """n = 1 (cone): p = (E* d/(pi a)) acosh(a/r) is log-singular at r = 0 and q ~ sqrt(s) is
    not smooth in s there: the first samples do not converge (a fixed ~5 % at r = dx, the same
    shape at every dx), but from r = 0.1 a on the error falls at order >= 2 (measured ~5.5)."""
    Ns = np.array([101, 201, 401])
    inv, _ = _errors(1, Ns, 5, lo=0.1)
    _record("abel order inverse cone r >= 0.1a (>= 2)", 2.0 / _order(Ns, inv), 1.0)
    _record("abel inverse cone N=401 r >= 0.1a", inv[-1], 1e-6)  # measured 6e-8


@pytest.mark.parametrize("n", [2.5, 3.5])
def test_round_trip(n):
    """(5.61) o (5.59) = id on the samples inside the contact: the two errors add up."""
    x, dx = grid(401)
    q, _ = powerlaw_pair(n, x)
    back = abel.line_load_from_pressure(abel.pressure_from_line_load(q, dx), dx)
    m = inside(x)
    # the inverse's O(dx^(n-1)) error at the axis (2e-5 in p for n = 2.5 here) is confined to
    # the first pieces, which the forward transform weights by ~dx: measured 1.9e-8 (n = 2.5),
    # 1.0e-10 (n = 3.5); asserted with a factor 2
    _record(f"abel round trip n={n}", rel_err(back, q, m), {2.5: 4e-8, 3.5: 2e-10}[n])


def test_worn_paraboloid_against_quadrature():
    """Problem 8, R = 1, b = 0.3 a: q = E*(d - g(x)) with g from worn_g; the reference is (5.59)
    by mpmath. q is constant for x < b and ~ sqrt(x - b) beyond: a stencil straddling x = b
    errs by O(dx^0.5) over a piece of width O(dx), so p errs by O(dx^1.5) for r < b (measured
    1.5, N = 401 ... 1601, largest just inside b: 2.4e-4 at r = 0.288 for N = 1601). For r > b
    those pieces are not in the integral: measured 1e-14 at r = 0.6, 0.9."""
    a, b, Rv = 1.0, 0.3, 1.0
    d = float(gen.worn_depth(Rv, a, b))
    radii = np.array([0.0, 0.15, 0.288, 0.6, 0.9])  # grid points of every N below
    with mp.workdps(30):
        ref = np.array([float(worn_pressure_ref(mp.mpf(r), mp.mpf(a), mp.mpf(b), mp.mpf(Rv),
                                                mp.mpf(1))) for r in radii])
    errs = []
    Ns = [401, 801, 1601]
    for N in Ns:
        x = np.linspace(0, 1.2, N)
        q = np.where(x < a, d - gen.worn_g(Rv, b, np.minimum(x, a)), 0.0)
        p = abel.pressure_from_line_load(q, x[1])
        idx = np.rint(radii / x[1]).astype(int)
        assert np.allclose(x[idx], radii, rtol=0, atol=1e-12)
        errs.append(np.abs(p[idx] / ref - 1))
    errs = np.array(errs)
    inner = errs[:, :3].max(axis=1)
    _record("abel order inverse worn r < b (>= 1.3)", 1.3 / _order(np.array(Ns), inner), 1.0)
    _record("abel inverse worn r < b, N=1601", inner[-1], 5e-4)  # measured 2.4e-4
    # r > b: the rounding of the inverse (~N ulp, as for Hertz) and the quadrature reference
    _record("abel inverse worn r > b, N=1601", errs[-1, 3:].max(), 1e-12)


def test_worn_paraboloid_with_the_kink_given():
    """kink=b: beyond b the interpolated function is (q - q(b))/sqrt(x^2 - b^2), which for the
    worn paraboloid is -E* x/R, smooth; the kernel 1/sqrt((s - b^2)(s - r^2)) is integrated
    by s = c + h cosh(u). Measured (degree 5) at r = 0, 0.15, 0.288, 0.312, 0.6, 0.9:
    1.5e-10, 3.3e-12, 3.4e-13 for N = 201, 401, 801 (order ~5.5, then rounding); asserted
    with a factor 2. p(b) is log-singular: +inf at the sample r = b."""
    a, b, Rv = 1.0, 0.3, 1.0
    d = float(gen.worn_depth(Rv, a, b))
    radii = np.array([0.0, 0.15, 0.288, 0.312, 0.6, 0.9])  # grid points of every N below
    with mp.workdps(30):
        ref = np.array([float(worn_pressure_ref(mp.mpf(r), mp.mpf(a), mp.mpf(b), mp.mpf(Rv),
                                                mp.mpf(1))) for r in radii])
    for N, tol in ((201, 3e-10), (401, 7e-12), (801, 7e-13)):
        x = np.linspace(0, 1.2, N)
        q = np.where(x < a, d - gen.worn_g(Rv, b, np.minimum(x, a)), 0.0)
        p = abel.pressure_from_line_load(q, x[1], kink=b)
        idx = np.rint(radii / x[1]).astype(int)
        _record(f"abel inverse worn kink=b N={N}", float(np.max(np.abs(p[idx] / ref - 1))), tol)
        assert p[int(np.rint(b / x[1]))] == np.inf
    # b between two samples (N = 203): no infinite sample, the same accuracy
    x = np.linspace(0, 1.2, 203)
    q = np.where(x < a, d - gen.worn_g(Rv, b, np.minimum(x, a)), 0.0)
    p = abel.pressure_from_line_load(q, x[1], kink=b)
    assert np.all(np.isfinite(p))
    j = int(np.searchsorted(x, b))  # the samples either side of b
    with mp.workdps(30):
        near = [float(worn_pressure_ref(mp.mpf(float(x[i])), mp.mpf(a), mp.mpf(b), mp.mpf(Rv),
                                        mp.mpf(1))) for i in (j - 1, j)]
    # measured 1.3e-13 and 3.7e-10 (the larger next to b, beyond it: 0.5 dx from the kink)
    _record("abel inverse worn kink between samples", float(np.max(np.abs(p[[j - 1, j]] / near
                                                                     - 1))), 1e-9)


def test_cone_with_kink_at_the_axis():
    """kink=0: q = q(0) + |x| U(x^2); for the cone U is constant, so with the edge given the
    transform is exact to rounding and p(0) = +inf (the cone's
    pressure is log-singular at the axis). With the edge found, the cubic extrapolation of
    q = d - c sqrt(s) to its root is the error: measured 2.5e-6, 1.2e-9, 4e-12 for N = 51,
    201, 801 (order ~5, as that of the root); asserted with a factor 2."""
    for N, tol_found in ((51, 5e-6), (201, 2.4e-9), (801, 8e-12)):
        x, dx = grid(N)
        q, p = powerlaw_pair(1, x)
        m = inside(x) & (x > 0)
        given = abel.pressure_from_line_load(q, dx, kink=0.0, edge=A_CONTACT)
        assert given[0] == np.inf
        # U_1 = (q_1 - q(0))/dx is a difference of nearly equal samples: near the axis the
        # rounding grows like N^2 (measured 1.7e-14, 9.7e-14, 2.9e-12 at r = dx), elsewhere
        # ~N ulp as for Hertz
        _record("abel inverse cone kink=0 edge given", rel_err(given, p, m), 1e-17 * N**2 + 1e-13)
        found = abel.pressure_from_line_load(q, dx, kink=0.0)
        _record(f"abel inverse cone kink=0 N={N}", rel_err(found, p, m), tol_found)


def test_without_edge_the_gaussian_pair():
    """No zero at the end of the grid: the transform is truncated there (PyAbel's convention).
    exp(-r^2) <-> sqrt(pi) exp(-x^2) on [0, 7]: the truncation is below 1e-21, what is left is
    the interpolation error. Measured (degree 5, N = 141, 281, 561, x <= 3, where the values
    are > 1e-4): inverse 9.1e-6, 2.2e-7, 5.0e-9 (order 5.4: the quintic's derivative, O(dx^5),
    half an order gained by the integration), forward 2.5e-6, 4.0e-8, 6.4e-10 (order 6.0)."""
    Ns = np.array([141, 281, 561])
    inv, fwd = [], []
    for N in Ns:
        x = np.linspace(0, 7, N)
        p, q = np.exp(-(x**2)), np.sqrt(np.pi) * np.exp(-(x**2))
        m = x <= 3
        inv.append(rel_err(abel.pressure_from_line_load(q, x[1]), p, m))
        fwd.append(rel_err(abel.line_load_from_pressure(p, x[1]), q, m))
    _record("abel order inverse gaussian (>= 5)", 5.0 / _order(Ns, inv), 1.0)
    _record("abel order forward gaussian (>= 5.5)", 5.5 / _order(Ns, fwd), 1.0)
    _record("abel inverse gaussian N=561", inv[-1], 1e-8)  # measured 5.0e-9: factor 2
    _record("abel forward gaussian N=561", fwd[-1], 1.3e-9)  # measured 6.4e-10: factor 2


def test_rows_are_independent_and_edge_given_agrees():
    """Leading axes are rows (PyAbel's convention), each with its own support; a given edge
    equals the found one to the accuracy of the edge finder (the cubic through the last four
    samples of a function linear in s: exact to rounding)."""
    x, dx = grid(201)
    q1, p1 = powerlaw_pair(2, x)
    q2, p2 = powerlaw_pair(4, x / 0.8)  # a smaller contact, radius 0.8 a: q(x/c) <-> p(r/c)/c
    p2 = p2 / 0.8
    Q = np.stack([[q1, q2], [q2, np.zeros_like(q1)]])
    P = abel.pressure_from_line_load(Q, dx)
    assert P.shape == Q.shape
    # the same operator on each row; a matrix-matrix product may round differently from a
    # matrix-vector one: a few ulp of the largest term
    np.testing.assert_allclose(P[0, 0], abel.pressure_from_line_load(q1, dx), rtol=1e-13)
    np.testing.assert_allclose(P[0, 1], abel.pressure_from_line_load(q2, dx), rtol=1e-13)
    np.testing.assert_array_equal(P[1, 1], 0.0)
    given_edge = abel.pressure_from_line_load(q1, dx, edge=A_CONTACT)
    m = inside(x)
    _record("abel edge given vs found", rel_err(given_edge, P[0, 0], m), 1e-12)
    back = abel.line_load_from_pressure(np.stack([p1, p2]), dx)
    assert rel_err(back[1], q2, inside(x / 0.8)) < 1e-13  # n = 4 is exact: a few ulp


@settings(max_examples=25, deadline=None)
@given(ratio=st.floats(2.5, 300.0), N_extra=st.integers(1, 40))
def test_hertz_any_edge_position(ratio, N_extra):
    """Wherever the edge falls between two samples (a/dx from 2.5 to 300), Hertz is exact:
    the edge finder and the last piece [x_K, a] hold for every position."""
    dx = 1.0 / ratio
    N = int(np.ceil(ratio)) + N_extra
    x = np.arange(N) * dx
    q = np.where(x < 1, 1 - x**2, 0.0)
    p = 2 / np.pi * np.sqrt(np.clip(1 - x**2, 0, None))
    m = x <= 0.9
    assert rel_err(abel.pressure_from_line_load(q, dx), p, m) < 2e-15 * N + 1e-13
    assert rel_err(abel.line_load_from_pressure(p, dx), q, m) < 1e-13
    assert np.all(abel.pressure_from_line_load(q, dx)[x >= 1] == 0)


@pytest.mark.parametrize("frac", [0.0, 1e-14, 1e-12, 1e-9, 2e-9, 1e-6, 0.5, 1 - 1e-12])
def test_edge_next_to_a_sample(frac):
    """a = (80 + frac) dx, given or found: an edge within 1e-9 dx after a sample is snapped to
    it (the last piece would amplify the rounding of the nearly-zero sample by dx/(a - x_K));
    the worst case is the crossover, measured 2.5e-11 (inverse) and 1.5e-11 (forward)."""
    x = np.arange(120.0)
    a = 80 + frac
    q = np.where(x < a, a * a - x**2, 0.0)
    p = 2 / np.pi * np.sqrt(np.clip(a * a - x**2, 0, None))
    m = x <= 0.9 * a
    for edge in (None, a):
        _record("abel edge next to a sample, inverse",
                rel_err(abel.pressure_from_line_load(q, 1.0, edge=edge), p, m), 5e-11)
        _record("abel edge next to a sample, forward",
                rel_err(abel.line_load_from_pressure(p, 1.0, edge=edge), q, m), 5e-11)


@pytest.mark.parametrize("kwargs, match", [
    (dict(values=[[1.0, np.nan, 0.0]], dx=1.0), "NaN"),
    (dict(values=[1.0, np.inf, 0.0], dx=1.0), "finite"),
    (dict(values=[1.0, 0.5, 0.0], dx=0.0), "dx"),
    (dict(values=[1.0, 0.5, 0.0], dx=-1.0), "dx"),
    (dict(values=[1.0], dx=1.0), "at least 2 samples"),
    (dict(values=3.0, dx=1.0), "at least 2 samples"),
    (dict(values=[1.0, 0.5, 0.0], dx=1.0, degree=0), "degree"),
    (dict(values=[1.0, 0.5, 0.0], dx=1.0, degree=2.0), "degree"),
    (dict(values=[1.0, 0.5, 0.0], dx=1.0, edge=3.0), "edge"),
    (dict(values=[1.0, 0.5, 0.2], dx=1.0, edge=1.5), "beyond edge"),
    (dict(values=[1.0, 0.5, 0.0], dx=1.0, edge=-1.0), "edge"),
    (dict(values=["a", "b"], dx=1.0), "not a number"),
])
def test_bad_input_raises(kwargs, match):
    kwargs = dict(kwargs)
    values = kwargs.pop("values")
    for f in (abel.pressure_from_line_load, abel.line_load_from_pressure):
        with pytest.raises(ValueError, match=match):
            f(values, **kwargs)


@pytest.mark.parametrize("kink", [-1e-300, -1.0, 2.0, np.nan, np.inf])
def test_bad_kink_raises(kink):
    with pytest.raises(ValueError, match="kink"):
        abel.pressure_from_line_load([1.0, 0.5, 0.0], 1.0, kink=kink)


def test_kink_outside_the_support_is_ignored():
    """A row whose edge lies before the kink has no kink: the plain transform."""
    x, dx = grid(101)
    q, _ = powerlaw_pair(2, x)
    np.testing.assert_array_equal(abel.pressure_from_line_load(q, dx, kink=1.1 * A_CONTACT),
                                  abel.pressure_from_line_load(q, dx))


def test_operators_are_cached():
    """A repeated transform of the same support is one matrix product with a cached operator;
    for (5.59) a new edge on the same grid only adds the correction of its last pieces."""
    x, dx = grid(101)
    q, p = powerlaw_pair(2, x)
    abel._CACHE.clear()
    abel.pressure_from_line_load(q, dx)
    first = dict(abel._CACHE)  # the edge-free operator of N samples and this edge's correction
    assert len(first) == 2
    abel.pressure_from_line_load(2 * q, dx)  # the same support: nothing new
    assert all(abel._CACHE[k] is v for k, v in first.items()) and len(abel._CACHE) == 2
    q2, _ = powerlaw_pair(2, x / 0.9)  # another edge: one more correction, the same base
    abel.pressure_from_line_load(q2, dx)
    assert len(abel._CACHE) == 3 and all(abel._CACHE[k] is v for k, v in first.items())
    big = [v for v in abel._CACHE.values() if isinstance(v, np.ndarray)]
    assert len(big) == 1 and big[0].shape == (101, 101)
    abel.line_load_from_pressure(p, dx)
    abel.line_load_from_pressure(3 * p, dx)
    assert len(abel._CACHE) == 4


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _moment_ref(sl, sh, tt, k):
    """mu_k = int_sl^sh v^k (s - tt)^(-1/2) ds, v = (s - sl)/(sh - sl), by tanh-sinh
    quadrature in u = s - sl (no cancellation near s_lo)."""
    return mp.quad(lambda u: (u / (sh - sl)) ** k / mp.sqrt(u + (sl - tt)), [0, sh - sl])


@pytest.mark.parametrize("kmax", [0, 2, 4, 8])
def test_inverse_moments_in_closed_form(kmax):
    """The (5.59) operator's moments mu_k = int v^k (s - t)^(-1/2) ds over a piece
    [s_lo, s_hi] (v = (s - s_lo)/(s_hi - s_lo)), taken as a polynomial in one parameter with
    positive coefficients (numeric/_abel/moments.py), against mpmath's tanh-sinh quadrature
    of the integral in s - s_lo at 30 digits (the endpoint singularity at s = t handled by
    the quadrature, not by the substitution s = t + w^2 the code uses). Pieces of the grid
    s = i^2 (units dx = 1): adjacent to the output point t = j^2, next to it, far from it
    (j = 0 and j = 3000), and a last piece ending at a non-integer edge. Tolerance 16 eps: a sum of
    <= 9 positive terms, each a few roundings (sqrt, the division by w_a + w_b, the powers)."""
    from hertzmdr.numeric._abel.moments import _BETA_TABLES, _half_powers

    t = np.array([[0.0, 4.0, 9.0, 3000.0**2]])
    i = np.array([0, 2, 3, 4, 7, 40, 3000, 3001, 5000], float)
    lo, hi = (i**2)[:, None], ((i + 1) ** 2)[:, None]
    hi[-1, 0] = 5000.0**2 + 1234.56789  # an edge inside the piece after the last sample
    # the pieces one at a time (the function takes consecutive pieces: [i^2, (i+1)^2], ...)
    mu = np.concatenate([_BETA_TABLES[kmax] @ _half_powers(t, lo[a:a + 1], hi[a:a + 1], kmax)
                         for a in range(len(i))])
    # and consecutive pieces at once: the same numbers
    run = np.arange(3000, 3010, dtype=float)
    together = _BETA_TABLES[kmax] @ _half_powers(t, (run**2)[:, None], ((run + 1)**2)[:, None],
                                                 kmax)
    np.testing.assert_array_equal(together[0], mu[6])
    worst = 0.0
    with mp.workdps(30):
        for a in range(len(i)):
            for b in range(t.shape[1]):
                sl, sh, tt = mp.mpf(lo[a, 0]), mp.mpf(hi[a, 0]), mp.mpf(t[0, b])
                if sl < tt:
                    assert np.all(mu[a, :, b] == 0.0)  # a piece left of the output point
                    continue
                for k in range(kmax + 1):
                    ref = _moment_ref(sl, sh, tt, k)
                    worst = max(worst, abs(float(mu[a, k, b] / ref) - 1))
    _record(f"abel exact moments kmax={kmax}", worst, 16 * np.finfo(float).eps)


def test_imports_neither_sympy_nor_scipy():
    code = ("import sys, hertzmdr.numeric.abel;"
            "print(','.join(m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"imported at import time: {out.stdout.strip()}"


def _close(M, v, ref):
    """M @ v equals ref up to the rounding of the sums, whose order differs between a matrix
    and a transform (the functions add the edge correction separately): 64 ulp of
    sum_j |M_ij v_j|, the size of the terms (the differentiating (5.59) operator has terms
    ~1e3 times its result at N = 401)."""
    return np.all(np.abs(M @ v - ref) <= 64 * np.finfo(float).eps * (np.abs(M) @ np.abs(v)))


def _fresh_operators():
    """The transforms and the matrices share the operator cache: each side is computed from
    an empty one, so that a matrix is never the transform's cached operator (or the reverse)."""
    operators._CACHE.clear()
    abel_edge._EDGE_CACHE.clear()


@pytest.mark.parametrize("N", [51, 401])
def test_matrices_are_the_transforms(N):
    """pressure_matrix/line_load_matrix for a known edge apply the same operators as the
    functions (see _close), each built anew (_fresh_operators)."""
    x, dx = grid(N)
    for n in (2.0, 2.5, 4.0):
        q, p = powerlaw_pair(n, x)
        _fresh_operators()
        pq = abel.pressure_from_line_load(q, dx, edge=A_CONTACT)
        qp = abel.line_load_from_pressure(p, dx, edge=A_CONTACT)
        _fresh_operators()
        M, F = (abel.pressure_matrix(N, dx, edge=A_CONTACT),
                abel.line_load_matrix(N, dx, edge=A_CONTACT))
        assert _close(M, q, pq)
        assert _close(F, p, qp)
        assert not M[x >= A_CONTACT].any() and not M[:, x >= A_CONTACT].any()
    # with a kink between two samples: the worn paraboloid's operator
    a, b = 1.0, 0.3005
    xx = np.linspace(0, 1.2, N)
    q = np.where(xx < a, 0.1 - gen.worn_g(1.0, b, np.minimum(xx, a)), 0.0)
    _fresh_operators()
    pk = abel.pressure_from_line_load(q, xx[1], edge=a, kink=b)
    _fresh_operators()
    Mk = abel.pressure_matrix(N, xx[1], edge=a, kink=b)
    assert _close(Mk, q, pk)


def test_matrices_of_several_grids_and_edges_in_one_process():
    """Matrices of two grids and two edges built one after the other (the operator cache
    holds them all at once: each is its own entry) are each the transform of its own grid and
    edge, computed from an empty cache."""
    cases = [(51, A_CONTACT), (51, 0.9 * A_CONTACT), (81, A_CONTACT), (81, 0.8 * A_CONTACT)]
    refs = []
    for N, a_ in cases:
        x, dx = grid(N)
        q, p = powerlaw_pair(2.5, x * A_CONTACT / a_)  # the contact of radius a_
        _fresh_operators()
        refs.append((q, p, abel.pressure_from_line_load(q, dx, edge=a_),
                     abel.line_load_from_pressure(p, dx, edge=a_)))
    _fresh_operators()
    for (N, a_), (q, p, pq, qp) in zip(cases, refs, strict=True):
        dx = grid(N)[1]
        assert _close(abel.pressure_matrix(N, dx, edge=a_), q, pq), (N, a_)
        assert _close(abel.line_load_matrix(N, dx, edge=a_), p, qp), (N, a_)


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _kink_moment_ref(tau, beta, s_lo, s_hi, k):
    """mu_k = int_{s_lo}^{s_hi} v^k ds / sqrt((s - beta)(s - tau)), v = (s - s_lo)/(s_hi -
    s_lo), by tanh-sinh quadrature in t with s = max(beta, tau) + t^2 (ds/sqrt(s - max) =
    2 dt: no endpoint singularity left)."""
    top, bot = max(beta, tau), min(beta, tau)
    return mp.quad(lambda t: 2 * ((top + t * t - s_lo) / (s_hi - s_lo)) ** k
                   / mp.sqrt(t * t + (top - bot)), [mp.sqrt(s_lo - top), mp.sqrt(s_hi - top)])


def test_kink_moments_by_quadrature():
    """_moments_cosh (the kernel 1/sqrt((s - b^2)(s - r^2)) of a kink at s = b^2, in units
    dx = 1) against 30-digit quadrature, k <= 5, on pieces starting at the kink or at the
    output point, with the kink and the output point 0.01 ... 10 apart (u = acosh spans up to
    ~6 on the first piece: 24 panels of _COSH_PANEL) and a piece far away. Gauss-Legendre of 8
    points on panels <= 0.25 in u: (5 * 0.125)^16/16! ~ 1e-17 per panel; left is rounding: of
    the sums of <= 24 * 8 positive terms (16 eps), and of the centre c = (beta + tau)/2, whose
    ulp of s is relative eps s/h in s - c and in z = (s - c)/h (h = |beta - tau|/2): measured
    1.6e-13 for h = 0.005, s = 100 (the bound eps s_hi/|beta - tau| is 2.7e-12 there)."""
    from hertzmdr.numeric._abel.moments import _moments_cosh

    eps = np.finfo(float).eps
    # (tau, beta, s_lo, s_hi): tau < beta (an output point left of the kink), tau > beta
    for tau, beta, s_lo, s_hi in [(99.99, 100.0, 100.0, 121.0), (90.0, 100.0, 100.0, 121.0),
                                  (100.0, 99.99, 100.0, 121.0), (110.0, 100.0, 110.0, 121.0),
                                  (99.0, 100.0, 400.0, 441.0)]:
        mu = _moments_cosh(np.array([[tau]]), np.array([[s_lo]]), np.array([[s_hi]]),
                           np.array([[s_hi - s_lo]]), beta, 5, 8)[0, 0]
        with mp.workdps(30):
            err = max(abs(float(mu[k] / _kink_moment_ref(tau, beta, s_lo, s_hi, k)) - 1)
                      for k in range(6))
        _record("abel kink moments", err, 16 * eps + eps * s_hi / abs(beta - tau))


@pytest.mark.parametrize("kwargs, match", [
    (dict(N=1, dx=0.1, edge=0.05), "N = 1 is out of range"),
    (dict(N=11, dx=-0.1, edge=0.5), "dx"),
    (dict(N=11, dx=0.1, edge=2.0), "edge = 2.0 is out of range"),
    (dict(N=11, dx=0.1, edge=0.5, degree=0), "degree = 0 is out of range"),
    (dict(N=11, dx=0.1, edge=0.5, kink=0.6), "kink = 0.6 is out of range"),
    (dict(N=11, dx=0.1, edge=0.5, kink=0.2), "is a grid point"),
])
def test_matrix_bad_input_raises(kwargs, match):
    with pytest.raises(ValueError, match=match):
        abel.pressure_matrix(**kwargs)


def test_edge_on_the_last_sample_and_beyond_it():
    """The edge may be the last sample, x = (N - 1) dx (both the matrix and the transform take
    it); beyond it the error gives the grid's end (N - 1) dx."""
    assert abel.pressure_matrix(5, 0.25, edge=1.0).shape == (5, 5)
    p = abel.pressure_from_line_load(1 - np.linspace(0, 1, 5) ** 2, 0.25, edge=1.0)
    assert p[-1] == 0.0 and np.all(p[:-1] > 0)
    with pytest.raises(ValueError, match=r"^edge = 2.0 is out of range; valid: 0 < edge <= "
                                         r"\(N-1\)\*dx = 1.0$"):
        abel.pressure_matrix(5, 0.25, edge=2.0)


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _beta_ref(k, beta):
    """int_0^1 x^k (x + beta (1 - x))^k dx by quadrature at the working precision."""
    return mp.quad(lambda x: x**k * (x + beta * (1 - x)) ** k, [0, 1])


def test_beta_table_by_quadrature():
    """_beta_table's c[k, j] (the moments of the pieces in closed form, built at import) against
    int_0^1 x^k (x + beta (1 - x))^k dx by 30-digit quadrature at four beta, k <= 8 (the
    tables used): sums of k + 1 positive terms, each a ratio of exact factorials, so a few
    ulps (1e-15); and zero above the diagonal."""
    for k in range(9):
        c = moments._beta_table(k)
        assert c.shape == (k + 1, k + 1) and not np.triu(c, 1).any(), k
        for kk in range(k + 1):
            for beta in (0.0, 0.3, 1.0, 7.0):
                with mp.workdps(30):
                    ref = _beta_ref(kk, beta)
                got = sum(c[kk, j] * beta**j for j in range(kk + 1))
                _record("beta table", abs(got / ref - 1), 1e-15)


def _sloped_kink_q(x, b, u0):
    """A line load with a square-root kink at x = b that slopes on both sides (the worn
    paraboloid's is flat left of its kink): in s = x^2, beta = b^2, a = 1,
    q = beta - s + u0 sqrt(1 - beta) for s < beta (linear in s), u0 (sqrt(1 - beta) -
    sqrt(s - beta)) beyond (Q(beta) + sqrt(s - beta) U with U = -u0 constant), 0 for x >= 1."""
    s, beta = x**2, b**2
    # a sample on the kink carries Q(beta): its float x may lie an ulp beyond b, where
    # sqrt(s - beta) ~ 1e-8 would be an error of the data, not of the transform
    root = np.where(np.abs(x - b) <= 4 * np.finfo(float).eps * b, 0.0,
                    np.sqrt(np.clip(s - beta, 0, None)))
    q = u0 * (np.sqrt(1 - beta) - root) + np.clip(beta - s, 0, None)
    return np.where(x < 1, q, 0.0)


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _sloped_kink_p_ref(r, b, u0):
    """(5.59) of _sloped_kink_q, p = -(1/pi) int_r^1 q'(x) dx/sqrt(x^2 - r^2) with q' = -2x
    (x < b) and -u0 x/sqrt(x^2 - b^2) (x > b), in closed form (t = x^2: the first is
    2 sqrt(b^2 - r^2), the second u0 int dt/(2 sqrt((t - b^2)(t - r^2))) = u0 log(sqrt(t -
    b^2) + sqrt(t - r^2)) between its ends)."""
    r, b = mp.mpf(r), mp.mpf(b)
    beta, rr = b * b, r * r
    left = 2 * mp.sqrt(beta - rr) if r < b else 0
    return (left + u0 * mp.log((mp.sqrt(1 - beta) + mp.sqrt(1 - rr))
                               / mp.sqrt(abs(beta - rr)))) / mp.pi


def _sloped_kink_p_quad(r, b, u0):
    """(5.59) of _sloped_kink_q by tanh-sinh quadrature in t = x^2: the left part
    int_(r^2)^(b^2) dt/sqrt(t - r^2) with t = r^2 + w^2, the right part
    (u0/2) int dt/sqrt((t - b^2)(t - r^2)) from max(r, b)^2 to 1 with t = max^2 + w^2."""
    beta, rr = b * b, r * r
    left = mp.quad(lambda w: 2, [0, mp.sqrt(beta - rr)]) if r < b else 0
    lo, other = max(beta, rr), min(beta, rr)
    right = u0 / 2 * mp.quad(lambda w: 2 / mp.sqrt(w * w + lo - other), [0, mp.sqrt(1 - lo)])
    return (left + right) / mp.pi


def test_kink_with_a_sloped_left_part_is_exact():
    """A kink with q sloped on both sides (_sloped_kink_q: linear in s left of it, Q(beta) +
    sqrt(s - beta) U with U constant beyond, the edge given) is in the interpolants' span: the
    transform and the kinked matrix are exact to rounding, left of the kink, next to it and
    beyond, the kink between two samples or on one (p = +inf there), over more rows than one
    block of the build (_BLOCK = 48) on either side, and without an edge. The closed form is
    checked against 30-digit quadrature of (5.59) at two radii. Rounding: as for Hertz, the
    rounding of q divided by the differences of ~N samples, 2e-15 N (measured 2.0e-13 at
    N = 201, 6.6e-14 at N = 241, up to the last sample inside the edge; the sample next to
    the kink, within dx/2, is left out: there U_i = (q_i - Q(beta))/sqrt(s_i - beta) divides
    a difference of nearly equal samples)."""
    u0 = 0.3
    with mp.workdps(30):
        for r in (mp.mpf("0.2"), mp.mpf("0.7")):  # (5.59) by quadrature in t = x^2
            assert abs(_sloped_kink_p_quad(r, mp.mpf("0.5"), u0)
                       / _sloped_kink_p_ref(r, 0.5, u0) - 1) < 1e-25
    # dx = 0.006: b between samples; dx = 0.005: on one; b = 0.7, dx = 0.004: on a sample
    # where (b/dx)^2 = 30624.99999999999, not 175^2 (the build snaps it to the sample)
    # and b = 1.5 dx: two samples left of the kink, a linear left part
    # and K = 144 = 3 _BLOCK samples inside the edge (the build's last block of rows)
    grids = [(np.linspace(0, 1.2, N), b) for N, b in ((201, 0.5), (241, 0.5), (301, 0.7),
                                                      (201, 0.009))]
    for x, b in grids + [(np.arange(175) / 144.5, 0.5)]:
        N, dx = len(x), x[1]
        q = _sloped_kink_q(x, b, u0)
        on = abs(b / dx - round(b / dx)) < 1e-9
        m = (x < 1) & (np.abs(x - b) > 0.5 * dx)
        with mp.workdps(30):
            ref = np.array([float(_sloped_kink_p_ref(float(v), b, u0)) for v in x[m]])
        _fresh_operators()
        p = abel.pressure_from_line_load(q, dx, edge=1.0, kink=b)
        _record(f"abel inverse sloped kink N={N}", rel_err(p[m], ref, slice(None)), 2e-15 * N)
        if on:
            assert p[int(round(b / dx))] == np.inf
        else:
            _fresh_operators()
            M = abel.pressure_matrix(N, dx, edge=1.0, kink=b)
            _record(f"abel matrix sloped kink N={N}", rel_err((M @ q)[m], ref, slice(None)),
                    2e-15 * N)
    # without an edge: q + 1 on [0, 1] has no zero, the transform is truncated at the grid's
    # end x = 1, and p (which sees only q') is the same closed form
    x = np.linspace(0, 1, 201)
    q = _sloped_kink_q(x, 0.5, u0) + 1.0
    q[-1] = 1.0  # _sloped_kink_q is 0 from x = 1 on: its limit there, the constant
    m = (x < 0.98) & (np.abs(x - 0.5) > 0.5 * x[1])
    with mp.workdps(30):
        ref = np.array([float(_sloped_kink_p_ref(float(v), 0.5, u0)) for v in x[m]])
    _fresh_operators()
    p = abel.pressure_from_line_load(q, x[1], kink=0.5)
    assert p[100] == np.inf  # b = 100 dx: on a sample
    _record("abel inverse sloped kink, no edge", rel_err(p[m], ref, slice(None)), 2e-15 * 201)


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _edge_moment_ref(tau, A, s_lo, s_hi, k):
    """mu_k = int_{s_lo}^{s_hi} v^k sqrt(A - s)/sqrt(s - tau) ds, v = (s - s_lo)/(s_hi - s_lo),
    by tanh-sinh quadrature in w with s = tau + w^2 (ds/sqrt(s - tau) = 2 dw)."""
    return mp.quad(lambda w: 2 * ((tau + w * w - s_lo) / (s_hi - s_lo)) ** k
                   * mp.sqrt(max(A - tau - w * w, 0)), [mp.sqrt(s_lo - tau), mp.sqrt(s_hi - tau)])


def test_edge_moments_by_quadrature():
    """_moments_theta (the (5.61) weight sqrt(A - s)/sqrt(s - tau) next to a contact edge A, in
    units dx = 1) against 30-digit quadrature, k <= 5: the last piece [s_K, A] and the one
    before it, for the output point on them (theta spans up to pi/2: 16 panels of
    _THETA_PANEL) and a few samples before them. Gauss-Legendre of 11 points on panels <= 0.1
    rad of an entire function of theta: below 1e-16; left is the rounding of the sums of
    <= 16 * 11 positive terms and of the ends (sin and cos of theta from square roots): 64 eps."""
    from hertzmdr.numeric._abel.moments import _moments_theta

    A = 100.5**2
    worst = 0.0
    for tau, s_lo, s_hi in [(100.0**2, 100.0**2, A), (99.0**2, 100.0**2, A),
                            (99.0**2, 99.0**2, 100.0**2), (90.0**2, 99.0**2, 100.0**2),
                            (0.0, 100.0**2, A)]:
        mu = _moments_theta(np.array([[tau]]), np.array([[s_lo]]), np.array([[s_hi]]),
                            np.array([[s_hi - s_lo]]), A, 5, 11)[0, 0]
        with mp.workdps(30):
            for k in range(6):
                ref = _edge_moment_ref(mp.mpf(tau), mp.mpf(A), mp.mpf(s_lo), mp.mpf(s_hi), k)
                worst = max(worst, abs(float(mu[k] / ref) - 1))
    _record("abel edge moments", worst, 64 * np.finfo(float).eps)


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _first_root_ref(coef):
    """The smallest real root in (0, 1] of sum_k coef[k] u^k (mpmath's polyroots at the working
    precision, of the float coefficients as they are), or 1 if there is none."""
    top = max(k for k, c in enumerate(coef) if c != 0)  # polyroots needs a non-zero lead
    roots = mp.polyroots([mp.mpf(c) for c in reversed(coef[:top + 1])], maxsteps=200,
                         extraprec=200)
    real = [mp.re(z) for z in roots if abs(mp.im(z)) < mp.mpf(10) ** -20 and 0 < mp.re(z) <= 1]
    return min(real) if real else mp.mpf(1)


# (coefficients in u, whether Newton from the linear root is accepted): data vanishing nearly
# linearly (the fast path), a root of a cubic next to the grid's sample; then the cases for the
# companion matrix: the linear root past the next sample (or before the sample), a second root
# before Newton's (two), no root in (0, 1], the linear term 0, a root 1.8e-13 past the next
# sample and 2.3e-13 before it; then Newton's own limits: a root 1e-6 from the sample (its
# stop relative to u), a root 1e-13 past the next sample (returned as 1), the linear root at
# 1.5 (Newton's reach), a constant, complex roots of real part 0.5
_EDGE_ROOT_CASES = [
    ((0.3, -1.0, 0.05, -0.02), True), ((1e-3, -1.0, 0.2, 0.1), True),
    ((0.9, -1.0, 0.1, 0.0), True), ((2.0, -1.0, -1.0, 0.0), False),
    ((1.0, 1.0, -4.0), False), ((0.16, -2.0, 4.0), True), ((1e-3, -1.0, 10.0), True),
    ((1.0, 1.0, 1.0), False), ((1.0, -0.5), False), ((1.0, 0.0, -4.0), True),
    ((1.0, 0.2, -(1.2 - 4e-13)), None), ((1.0, 0.2, -(1.2 + 5e-13)), None),
    ((0.23, -0.28, -1.34, 1.45), False),  # Newton reaches the second root, 0.95: the probe
    ((-0.03125, 0.0625, 0.5, -1.0), False),  # Newton's root 0.5, the probe hits the root 0.25
    ((-1.23, 0.91, 2.71, -2.08), False),  # Newton goes past the next sample (1.29), root 0.69
    ((0.25, -1.0, 0.5, 4.0), False),  # p' = 0 at the linear root: no Newton step; no root
    ((1e-6, -1.0, 500.0), True), ((1 + 1e-13, -1.0), True), ((1.5, -1.0, -0.5), True),
    ((0.14, 0.0, -2.11, -1.74), True), ((1.0, 0.0, 0.0, 0.0), True), ((0.5, -1.0, 1.0), False),
    ((0.0, 1.0, -2.0), False),  # a root at 0 is not in (0, 1]
]


def test_edge_root_against_mpmath(monkeypatch):
    """_edge_root (the edge of a row between its last non-zero sample, u = 0, and the next one,
    u = 1) against mpmath's roots of the same float coefficients at 30 digits: the smallest
    root in (0, 1], or exactly 1 when there is none. Newton from the linear root is the path
    for data vanishing nearly linearly (the docstring's "a few float operations"): the
    companion matrix is called only where it must be (counted). Tolerance: a simple root of
    the float polynomial is determined to the rounding of its evaluation, eps sum|c_k u^k| /
    |p'(u)| (1 to 3.4 eps of u here; measured at most 0.49 of it); Newton's stop (a step <=
    1e-15 u) and the companion matrix's roots polished by Newton both reach it."""
    calls = []
    polyroots = np.polynomial.polynomial.polyroots

    def counted(c):
        calls.append(1)
        return polyroots(c)

    monkeypatch.setattr(np.polynomial.polynomial, "polyroots", counted)
    with mp.workdps(30):
        for coef, newton in _EDGE_ROOT_CASES:
            calls.clear()
            u = abel_edge._edge_root(np.array(coef))
            ref = float(_first_root_ref(coef))
            terms = sum(abs(c) * ref**k for k, c in enumerate(coef))
            slope = abs(sum(k * c * ref ** (k - 1) for k, c in enumerate(coef) if k))
            tol = np.finfo(float).eps * terms / slope if ref < 1 else 0.0  # no root: 1 exactly
            assert 0 < u <= 1 and abs(u - ref) <= tol, (coef, u, ref)
            if newton is not None:
                assert (not calls) == newton, (coef, calls)


@pytest.mark.parametrize("root", [0.5, 0.25, 0.75])
def test_edge_root_of_a_double_root(root):
    """A double root (u - u0)^2, its coefficients exact in binary (with 0.3 or 0.9 the float
    polynomial may have no real root): f and f' are both rounding there,
    and the companion matrix's root, polished by Newton steps that divided one by the other,
    went from 0.5 to 0.625 (found by the mutation triage of 2026-11-27); a step is now kept
    only where it lowers |f|. Tolerance: a double root is determined by the data to
    sqrt(eps) of it (the polynomial is below rounding within that distance), 1.5e-8."""
    u = abel_edge._edge_root(np.array([root * root, -2 * root, 1.0]))
    assert abs(u - root) <= 1.5e-8 * root, u


def test_edge_found_from_one_or_two_samples():
    """The smallest supports: one non-zero sample (the edge is the next sample, a = dx: q linear
    in s through q_0 and 0, p(0) = 2 q_0/(pi dx); forward, R = p_0 constant, q(0) = pi p_0/2 dx),
    two (the linear root of q in s: Hertz with a = 1.5 dx, exact), an edge given inside the
    first dx (a = 0.5 dx: p(0) = 2 q_0/(pi a)), and an edge 1e-10 dx past the sample 1 (snapped
    to it: the edge moves by 1e-10 dx, p(0) by 1e-10 of itself; unsnapped, the last piece
    [1, a^2] of width 2e-10 would amplify the rounding of q_1 ~ 2e-10 by 1/2e-10). Hertz is
    linear in s: exact but for a few roundings, 1e-14; the snapped case 1e-10 plus that."""
    dx = 0.5
    q0 = 3.0
    p = abel.pressure_from_line_load([q0, 0.0, 0.0, 0.0], dx)
    assert abs(p[0] / (2 * q0 / (np.pi * dx)) - 1) < 1e-14 and not p[1:].any()
    q = abel.line_load_from_pressure([q0, 0.0, 0.0, 0.0], dx)
    assert abs(q[0] / (np.pi * q0 / 2 * dx) - 1) < 1e-14 and not q[1:].any()
    x = np.arange(5.0)
    for a, edge in ((1.5, None), (1.5, 1.5), (0.5, 0.5), (1 + 1e-10, None), (1 + 1e-10, 1 + 1e-10)):
        q = np.where(x < a, a * a - x * x, 0.0)
        pa = 2 / np.pi * np.sqrt(np.clip(a * a - x * x, 0, None))
        tol = 1e-14 if a != 1 + 1e-10 else 1.1e-10
        got = abel.pressure_from_line_load(q, 1.0, edge=edge)
        assert rel_err(got, pa, x < a - 0.2) < tol, (a, edge)
        back = abel.line_load_from_pressure(pa, 1.0, edge=edge)
        assert rel_err(back, q, x < a - 0.2) < tol, (a, edge)


def test_edge_snapped_with_rounded_samples():
    """An edge a = (K + d) dx given within the snap's window after the sample K (A - K^2 <=
    1e-9 (2K + 1) in s = x^2) is moved to that sample, for K = 1 and 80 and d = 1e-9 (A - K^2
    = 2K d), with q = a^2 (1 - (x/a)^2): its samples carry a rounding of ~eps a^2, which the
    last piece [K^2, A] (width 2K d) would amplify by 1/(2K d) (measured 5e-9 at K = 80,
    d = 1.2e-9, just outside the window). Snapped, p moves with its edge by ~d/a (measured
    1.0e-9 at K = 1, 2.0e-10 at K = 80): tolerance 1.1 d."""
    for K in (1, 80):
        d = 1e-9
        a = K + d
        x = np.arange(K + 4.0)
        q = np.where(x < a, a * a * (1 - (x / a) ** 2), 0.0)
        pa = 2 / np.pi * np.sqrt(np.clip(a * a - x * x, 0, None))
        _record("abel edge snapped, rounded samples",
                rel_err(abel.pressure_from_line_load(q, 1.0, edge=a), pa, x < a - 0.2), 1.1 * d)

def test_scatter_of_the_pieces_is_the_sum_piece_by_piece():
    """_scatter_t (the pieces' contributions added to the transposed operator, WT[start_i + l,
    rows] += contrib[i, l]) against its definition, piece by piece in a loop: the stencil
    starts of the inverse operator's pieces (runs of equal starts at either end, clipped) for
    every degree 1..9 and a few sizes, one block of pieces from the middle (no run), a single
    piece, and starts with a gap (the general path). The same sums in another order: 8 ulp
    of the sum of |terms| (at most 2 deg + 2 terms meet in one entry)."""
    from hertzmdr.numeric._abel.interpolation import _stencils

    rng = np.random.default_rng(7)
    cases = []
    for deg in range(1, 10):
        for n_nodes in (deg + 1, deg + 2, 2 * deg + 3, 40):
            start = _stencils(n_nodes, n_nodes - 1, deg)  # n_nodes pieces (the edge a node)
            cases += [start, start[3:9] if len(start) > 9 else start[:1]]
    cases += [np.array([0, 0, 1, 3, 4]), np.array([2, 2, 2]), np.array([5])]
    for start in cases:
        P, L, n_rows = len(start), 3, 4
        contrib = rng.standard_normal((P, L, n_rows))
        got = np.zeros((int(start.max()) + L + 1, n_rows))
        operators._scatter_t(got, slice(0, n_rows), contrib, start)
        ref, size = np.zeros_like(got), np.zeros_like(got)
        for i, c in enumerate(start):
            ref[c:c + L] += contrib[i]
            size[c:c + L] += np.abs(contrib[i])
        assert np.all(np.abs(got - ref) <= 8 * np.finfo(float).eps * size), start


def test_edge_correction_is_the_operator_built_with_the_edge():
    """(5.59) with an edge is applied as the edge-free operator of N samples plus a correction
    of the last pieces (_edge_correction); built directly from the pieces with the edge
    (_build, every piece's moments against the kernel) it is the same matrix: N from 6 to 101,
    degree 1..9, edges 1.5 dx (K = 1, fewer samples than the stencil), mid-grid, next to a
    sample, on the last sample. The same terms summed in another order: 16 ulp of the row's
    largest entry (measured 0.7 ulp)."""
    worst = 0.0
    for N in (6, 12, 40, 101):
        for degree in (1, 2, 3, 5, 9):
            for x_edge in (1.5, 2.3, 4.7, N / 2 + 0.25, N - 1.5, N - 1.0):
                if x_edge > N - 1:
                    continue
                K, A = abel_edge._edge_index(np.zeros(N), x_edge)
                operators._CACHE.clear()
                M = operators._operator("inverse", K, A, degree, N)
                ref = operators._build("inverse", K, A, degree)
                row = np.max(np.abs(ref), axis=1, keepdims=True)
                worst = max(worst, float(np.max(np.abs(M - ref) / row)))
                y = np.random.default_rng(K).standard_normal(K + 1)
                got = operators._apply("inverse", K, A, degree, N, y[None, :])[0]
                assert np.all(np.abs(got - M @ y) <= 64 * np.finfo(float).eps
                              * (np.abs(M) @ np.abs(y)))  # as _close
    _record("abel edge correction vs direct build", worst / np.finfo(float).eps, 16)


def test_kink_on_a_sample_rising_flat_and_near_the_axis():
    """p at a kink on a sample is log-singular with the sign of -U(b) (U = (q - q(b))/sqrt(s -
    b^2) beyond it): q rising beyond the kink (U = +0.3) gives -inf; q flat beyond it (U = 0,
    no singular term) the mean of the two neighbouring samples, and there q = max(b^2 - x^2, 0)
    with the edge given beyond the kink is Hertz of radius b: p = (2/pi) sqrt(b^2 - r^2) left
    of the kink, 0 beyond it (linear in s: to rounding, 2e-15 N). And the kink 1.2 dx from the
    axis (its left piece [dx^2, b^2] narrower than one s-width, 0.44 dx^2) is exact like the
    others (_sloped_kink_q, 2e-15 N as there), on every sample."""
    N = 201
    x = np.linspace(0, 1, N)
    dx = x[1]
    b = x[100]
    p = abel.pressure_from_line_load(1 + 0.3 * np.sqrt(np.clip(x**2 - b**2, 0, None)), dx,
                                     kink=b)
    assert p[100] == -np.inf and np.isfinite(np.delete(p, 100)).all()
    q = np.clip(b * b - x**2, 0, None)
    p = abel.pressure_from_line_load(q, dx, edge=0.9, kink=b)
    assert p[100] == (p[99] + p[101]) / 2
    # q = 1 beyond the kink, dropping to 0 at the edge 0.9: p is not 0 right of the kink; U(b)
    # is a sum of terms that cancel, 0 or a rounding of either sign, so the kink's sample is
    # the mean of its neighbours or +-inf
    p1 = abel.pressure_from_line_load(np.where(x < 0.9, 1 + q, 0.0), dx, edge=0.9, kink=b)
    assert p1[100] in (np.inf, -np.inf, (p1[99] + p1[101]) / 2) and p1[101] != p1[102] != 0
    ref = 2 / np.pi * np.sqrt(np.clip(b * b - x**2, 0, None))
    m = np.abs(x - b) > 0.5 * dx
    assert np.all(np.abs(p[m] - ref[m]) <= 2e-15 * N * ref[0])
    u0 = 0.3
    x = np.linspace(0, 1.2, N)
    b = 1.2 * x[1]
    q = _sloped_kink_q(x, b, u0)
    m = x < 1  # every sample: the one left of the kink, 0.2 dx from it, too (its row takes
    # the short piece [dx^2, b^2] whole; measured 4.4e-14)
    with mp.workdps(30):
        ref = np.array([float(_sloped_kink_p_ref(float(v), b, u0)) for v in x[m]])
    _record("abel inverse sloped kink at 1.2 dx",
            rel_err(abel.pressure_from_line_load(q, x[1], edge=1.0, kink=b)[m], ref,
                    slice(None)), 2e-15 * N)
    _fresh_operators()
    M = abel.pressure_matrix(N, x[1], edge=1.0, kink=b)
    _record("abel matrix sloped kink at 1.2 dx", rel_err((M @ q)[m], ref, slice(None)),
            2e-15 * N)


def test_operator_cache_is_least_recently_used_within_its_bytes(monkeypatch):
    """_cached keeps at most _CACHE_BYTES of operators (set to 2000 bytes here): a new entry
    evicts the least recently used ones (a hit makes an entry the most recent), down to one
    entry, which stays even when it alone is larger than the bound."""
    monkeypatch.setattr(operators, "_CACHE_BYTES", 2000)
    operators._CACHE.clear()
    small = [np.full((10, 10), float(i)) for i in range(4)]  # 800 bytes each
    for i in range(2):
        assert operators._cached(("t", i), lambda i=i: small[i]) is small[i]
    assert list(operators._CACHE) == [("t", 0), ("t", 1)]
    operators._cached(("t", 0), lambda: small[3])  # a hit: 0 is now the most recent
    operators._cached(("t", 2), lambda: small[2])  # 2400 bytes: 1 goes
    assert list(operators._CACHE) == [("t", 0), ("t", 2)]
    big = (0, np.zeros((15, 15)))  # 1800 bytes, a tuple as _edge_correction's
    assert operators._cached(("t", 3), lambda: big) is big
    assert list(operators._CACHE) == [("t", 3)]  # 0 and 2 go
    huge = np.zeros((30, 30))  # 7200 bytes: alone over the bound, kept
    operators._cached(("t", 4), lambda: huge)
    assert list(operators._CACHE) == [("t", 4)]
    operators._CACHE.clear()


_R_COEF = (1.0, -0.7, 0.4, 0.9, -0.3, 0.2, -0.5, 0.1, 0.3, -0.2)  # R(s), degree 9


@memo  # a mutation run's memo (tests/oracle.py): mpmath only
def _forward_polynomial_ref(s, degree, edge):
    """(5.61) in s: q = int_s^T P(t)/sqrt(t - s) dt of P = sum_k<=degree _R_COEF[k] t^k times
    sqrt(1 - t) with an edge at t = 1 (t = s + (1 - s) sin^2(theta)), or truncated at T = 1
    without one (t = s + w^2), by quadrature of the smooth integrand at the working precision."""
    s = mp.mpf(s)

    def R(t):
        return sum(mp.mpf(c) * t**k for k, c in enumerate(_R_COEF[:degree + 1]))

    if edge:
        return 2 * (1 - s) * mp.quad(lambda th: R(s + (1 - s) * mp.sin(th) ** 2)
                                     * mp.cos(th) ** 2, [0, mp.pi / 2])
    return 2 * mp.quad(lambda w: R(s + w * w), [0, mp.sqrt(1 - s)])


def test_polynomials_of_every_degree_to_rounding():
    """The interpolants are exact on polynomials of their degree in s, and so are the
    transforms: (5.61) of p = P(s) of degree 5 and 9 without an edge (the transform truncated
    at the grid's end, Gauss-Legendre in w of degree + 1 points: exact), of p = sqrt(1 - s)
    P(s) with the edge at 1 (degree 9: the w-pieces far from the edge converge like (7 +
    sqrt 48)^-(2n - 2k) with n = degree + 6, the theta-pieces to 1e-15); and (5.59) with
    degree 1 (Hertz, linear in s), the edge found and given. References: 30-digit quadrature
    (_forward_polynomial_ref), the Hertz pair. Rounding: the sums of ~N terms of the size of
    q, 2e-15 N (measured 1.3e-15, 8.9e-16, 3.9e-15; degree 1: 3.8e-15)."""
    N = 41
    for degree, edge in ((5, False), (9, False), (9, True)):
        x = np.linspace(0, 1.2 if edge else 1.0, 61 if edge else N)
        s = x * x
        P = sum(c * s**k for k, c in enumerate(_R_COEF[:degree + 1]))
        if edge:
            P = np.where(x < 1, P * np.sqrt(np.clip(1 - s, 0, None)), 0.0)
        m = (x < (0.95 if edge else 0.99)) & (np.arange(len(x)) % 3 == 0)  # a third: time
        got = abel.line_load_from_pressure(P, x[1], edge=1.0 if edge else None, degree=degree)
        with mp.workdps(30):
            ref = np.array([float(_forward_polynomial_ref(float(v), degree, edge))
                            for v in s[m]])
        _record(f"abel forward polynomial degree {degree} edge {edge}",
                rel_err(got[m], ref, slice(None)), 2e-15 * len(x))
    x = np.linspace(0, 1.2, N)
    q = np.clip(1 - x**2, 0, None)
    p = 2 / np.pi * np.sqrt(np.clip(1 - x**2, 0, None))
    for edge in (None, 1.0):
        _record("abel inverse degree 1", rel_err(abel.pressure_from_line_load(
            q, x[1], edge=edge, degree=1), p, x < 0.95), 2e-15 * N)


def test_rows_after_an_all_zero_row_are_transformed():
    """Rows are grouped by their edge; an all-zero row (no edge: it transforms to zero) must not
    end the loop over the groups. Rows [0, q, 0, 2 q] of the Hertz line load (a = 30 dx)
    give [0, p, 0, 2 p] with p the single row's transform, to rounding (the batched product
    sums the same 64 terms in another order: measured 3e-15 of p's scale, asserted 1e-13).
    Found by the mutation run of abel.py (2026-11-27): `continue` -> `break` survived."""
    dx, a = 1.0, 30.0  # the edge 30 dx
    x = np.arange(64) * dx
    q = np.maximum(a * a - x * x, 0.0)
    p = abel.pressure_from_line_load(q, dx)
    rows = abel.pressure_from_line_load(np.array([0 * q, q, 0 * q, 2 * q]), dx)
    scale = np.max(np.abs(p))
    assert np.all(rows[[0, 2]] == 0) and p.any()
    assert np.max(np.abs(rows[1] - p)) <= 1e-13 * scale
    assert np.max(np.abs(rows[3] - 2 * p)) <= 2e-13 * scale


def test_every_refusal_of_the_abel_api_is_one_line_naming_its_input():
    """Each refusal of the four public functions, matched in full (promise 1: the input, its
    value and what is valid), and the ends of each range accepted: 2 samples (p(0) of a
    one-piece line load is 2 q_0/(pi dx), Hertz with a = dx), N = 2 for the matrices, degree 1
    and 9, a kink just inside the last interval. Found by the mutation run of abel.py
    (2026-11-27): the validation's mutants survived the tests of the numbers; the messages of
    a non-finite sample once printed np.float64(inf)."""
    q = np.maximum(25 - np.arange(8.0) ** 2, 0)
    refusals = [
        (lambda: abel.pressure_from_line_load(q, 1.0, degree=10),
         "degree = 10 is out of range; valid: an integer 1 <= degree <= 9"),
        (lambda: abel.pressure_from_line_load(q, 1.0, degree=0),
         "degree = 0 is out of range; valid: an integer 1 <= degree <= 9"),
        (lambda: abel.pressure_from_line_load([1.0], 1.0),
         "q has shape (1,); valid: at least 2 samples along the last axis (x_i = i*dx, "
         "i = 0..N-1)"),
        (lambda: abel.line_load_from_pressure([1.0], 1.0),
         "p has shape (1,); valid: at least 2 samples along the last axis (x_i = i*dx, "
         "i = 0..N-1)"),
        (lambda: abel.pressure_from_line_load(np.array([[1.0, 0, 0, 0], [1.0, 0, 0, np.inf]]),
                                              1.0),
         "q[1, 3] = inf is out of range; valid: finite numbers"),
        (lambda: abel.line_load_from_pressure(np.array([1.0, np.nan, 0]), 1.0),
         "p[1] = nan is out of range; valid: a number, not NaN"),
        (lambda: abel.pressure_from_line_load(q, np.inf),
         "dx = inf is out of range; valid: dx > 0 and finite"),
        (lambda: abel.line_load_from_pressure([1.0, 0], 0),
         "dx = 0.0 is out of range; valid: dx > 0 and finite"),
        (lambda: abel.pressure_from_line_load(q, 1.0, edge=np.nan),
         "edge = nan is out of range; valid: a number, not NaN"),
        (lambda: abel.pressure_from_line_load(
            np.array([[3.0, 2, 1, 0, 0, 0], [3.0, 2, 1, 0, 0, 1e-3]]), 0.5, edge=1.5),
         "q[1, 5] = 0.001 at x = 2.5 is beyond edge = 1.5; valid: 0 at and beyond the edge"),
        (lambda: abel.pressure_from_line_load(q, 1.0, kink=7.0),
         "kink = 7.0 is out of range; valid: 0 <= kink < (N-1)*dx = 7.0"),
        (lambda: abel.pressure_from_line_load(q, 0.5, kink=3.5),
         "kink = 3.5 is out of range; valid: 0 <= kink < (N-1)*dx = 3.5"),
        (lambda: abel.pressure_from_line_load(q, 1.0, kink=np.nan),
         "kink = nan is out of range; valid: a number, not NaN"),
        (lambda: abel.pressure_matrix(2.5, 1.0, edge=3.0),
         "N = 2.5 is out of range; valid: an integer N >= 2"),
        (lambda: abel.pressure_matrix(1, 1.0, edge=3.0),
         "N = 1 is out of range; valid: an integer N >= 2"),
        (lambda: abel.line_load_matrix(True, 1.0, edge=3.0),
         "N = True is out of range; valid: an integer N >= 2"),
        (lambda: abel.pressure_matrix(8, -1.0, edge=3.0),
         "dx = -1.0 is out of range; valid: dx > 0 and finite"),
        (lambda: abel.line_load_matrix(8, 1.0, edge=3.0, degree=10),
         "degree = 10 is out of range; valid: an integer 1 <= degree <= 9"),
        (lambda: abel.line_load_matrix(8, 1.0, edge=np.nan),
         "edge = nan is out of range; valid: a number, not NaN"),
        (lambda: abel.pressure_matrix(8, 1.0, edge=3.0, kink=3.0),
         "kink = 3.0 is out of range; valid: 0 <= kink < edge = 3.0"),
        (lambda: abel.pressure_matrix(8, 1.0, edge=3.5, kink=np.nan),
         "kink = nan is out of range; valid: a number, not NaN"),
    ] + [(lambda b=b: abel.pressure_matrix(8, 1.0, edge=3.5, kink=b),
          f"kink = {b!r} is a grid point, where p is infinite: the matrix cannot hold it; use "
          "pressure_from_line_load, or a grid without a sample at the kink")
         for b in (0.0, 2.0)]
    for call, message in refusals:
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == message
    p2 = abel.pressure_from_line_load([1.0, 0.0], 1.0)
    assert abs(p2[0] - 2 / np.pi) <= 4e-16 and p2[1] == 0
    assert abel.pressure_matrix(2, 1.0, edge=1.0).shape == (2, 2)
    for degree in (1, 9):
        assert np.isfinite(abel.pressure_from_line_load(q, 1.0, degree=degree)).all()
    assert abel.pressure_from_line_load(q, 1.0, kink=6.99).shape == q.shape


# --- trimdrabel: abel.py's survivors of the 17:33 run (rounding-level tails, units, the cache)


def test_units_rounding_tails_zero_rows_and_the_kink_check_of_the_matrix():
    """Hertz in SI units (E* = 1e11 Pa, R = 1 cm, a = 0.1 mm: q = E* (a^2 - x^2)/R (5.58), up
    to 1e5 N/m, on 61 samples, dx = a/40): the pressure is (2 E*/(pi R)) sqrt(a^2 - r^2)
    (5.15) to 1e-12 of p0 (measured 8e-15: the quintic pieces hold the parabola); a tail of
    rounding-level values beyond the edge (1e-14 of max |q|, below the 1e-12 the transform
    counts as 0) gives the same pressure bitwise, while a tail of 1e-6 of it is refused, in
    these units and in units 2^-40 (9e-13) as large; rows of zeros with an edge transform to
    zeros. A non-number is refused by name. pressure_matrix's refusal of a kink on a sample
    answers for that kink: off a sample, on one, off again (each answer cached under its own
    (K, A, beta, degree))."""
    E_, R, a_ = 1e11, 1e-2, 1e-4
    dx, N = a_ / 40, 61
    x = np.arange(N) * dx
    q = np.where(x < a_, E_ * (a_ * a_ - x * x) / R, 0.0)
    p = abel.pressure_from_line_load(q, dx, edge=a_)
    ref = np.where(x < a_, 2 * E_ / (np.pi * R) * np.sqrt(np.clip(a_ * a_ - x * x, 0, None)), 0)
    assert np.max(np.abs(p - ref)) < 1e-12 * ref[0]
    for unit in (1.0, 2.0**-40):  # a power of 2: the transform scales bitwise
        tail = q * unit
        tail[41:] = 1e-14 * np.max(tail) * np.cos(np.arange(N - 41))
        assert np.array_equal(abel.pressure_from_line_load(tail, dx, edge=a_), p * unit)
        tail[45] = 1e-6 * np.max(tail)
        with pytest.raises(ValueError, match=r"^q\[45\] = .* at x = .* is beyond edge = "):
            abel.pressure_from_line_load(tail, dx, edge=a_)
    assert not abel.pressure_from_line_load(np.zeros((2, N)), dx, edge=a_).any()
    assert not abel.line_load_from_pressure(np.zeros((2, N)), dx, edge=a_).any()
    for f, name in ((abel.pressure_from_line_load, "q"), (abel.line_load_from_pressure, "p")):
        with pytest.raises(ValueError, match=rf"^{name} = 'abc' is not a number or an array of "
                                             r"numbers$"):
            f("abc", dx)
    on = (r"^kink = 5e-05 is a grid point, where p is infinite: the matrix cannot hold it; "
          r"use pressure_from_line_load, or a grid without a sample at the kink$")
    for kink in (a_ / 2 + dx / 3, a_ / 2, a_ / 2 - dx / 3):
        if kink == a_ / 2:
            with pytest.raises(ValueError, match=on):
                abel.pressure_matrix(N, dx, edge=a_, kink=kink)
        else:
            M = abel.pressure_matrix(N, dx, edge=a_, kink=kink)
            assert np.allclose(M @ q, abel.pressure_from_line_load(q, dx, edge=a_, kink=kink),
                               rtol=1e-12, atol=1e-12 * ref[0])
