"""numeric/_quadrature.py: Gauss-Legendre rules checked by what they must integrate exactly.

An m-point Gauss-Legendre rule integrates every polynomial of degree <= 2m - 1 exactly and not
x^(2m); a composite rule split at the kinks of a piecewise polynomial integrates it exactly.
The exact integrals are written out by hand (powers), so no quadrature enters the reference.
Tolerances: sums of ~m positive terms of order 1, each rounded: 1e-14 (a few tens of ulps).
"""

from math import factorial

import numpy as np
import pytest

from hertzmdr.numeric._quadrature import _GL_CACHE, gauss, panels

TOL = 1e-14


@pytest.mark.parametrize("m", [1, 2, 5, 16])
def test_gauss_degree(m):
    _GL_CACHE.pop(m, None)  # other modules may have filled it: compute this rule here
    t, w = gauss(m)
    assert t.shape == w.shape == (m,)
    for k in range(2 * m):  # exact up to degree 2m - 1: int_-1^1 x^k = 2/(k+1) for even k
        exact = 2.0 / (k + 1) if k % 2 == 0 else 0.0
        assert abs(np.sum(w * t**k) - exact) < TOL, k
    # and not beyond: for x^(2m) the error is 2^(2m+1) (m!)^4 / ((2m+1) ((2m)!)^2)
    k = 2 * m
    err = 2.0 / (k + 1) - np.sum(w * t**k)
    expected = 2.0 ** (k + 1) * factorial(m) ** 4 / ((k + 1) * factorial(k) ** 2)
    assert abs(err / expected - 1) < 1e-4
    assert gauss(m)[0] is t  # cached


def test_panels_integrate_piecewise_polynomials_exactly():
    """f(x) = |x - b1| (x - b2)^2 + 3 on [lo, hi], breaks at b1, b2, b3 (given in any order,
    some outside [lo, hi], clipped) and with a repeated break: each panel sees a cubic, which
    m = 3 points integrate exactly (m = 3: unequal weights, unlike m = 2)."""
    lo = np.array([0.0, -1.0, 2.0])
    hi = np.array([3.0, 0.5, 5.0])
    b1 = np.array([1.0, -0.25, 4.0])
    b2 = np.array([2.5, 7.0, 4.0])  # 7 is outside [-1, 0.5]; 4.0 coincides with b1
    b3 = np.array([-3.0, -9.0, 1.0])  # below lo: clipped to it, an empty panel
    breaks = np.stack([b2, b1, b3], axis=1)  # b2 first: the order must not matter
    x, w = panels(lo, hi, breaks, 3)
    assert x.shape == w.shape == (3, 12)
    f = np.abs(x - b1[:, None]) * (x - b2[:, None]) ** 2 + 3

    def P(s, b1, b2):
        """An antiderivative of (s - b1) (s - b2)^2."""
        u = s - b2
        c = b2 - b1  # (s - b1) = u + c
        return u**4 / 4 + c * u**3 / 3

    def exact(lo, hi, b1, b2):
        k = min(max(b1, lo), hi)  # the kink, clipped to the interval
        # |s - b1| = -(s - b1) left of the kink, +(s - b1) right of it
        return -(P(k, b1, b2) - P(lo, b1, b2)) + (P(hi, b1, b2) - P(k, b1, b2)) + 3 * (hi - lo)

    for i in range(3):
        ref = exact(lo[i], hi[i], b1[i], b2[i])
        assert abs(np.sum(w[i] * f[i]) / ref - 1) < TOL, i
        assert np.all(w[i] >= 0) and np.all((x[i] >= lo[i]) & (x[i] <= hi[i]))
        assert abs(np.sum(w[i]) - (hi[i] - lo[i])) < TOL * (hi[i] - lo[i])
    # the empty panels: below lo (rows 0, 1, 2: b3 < lo) and between the coinciding breaks (row 2)
    assert [np.count_nonzero(wi == 0) for wi in w] == [3, 6, 6]
