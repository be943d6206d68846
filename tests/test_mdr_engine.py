"""The numerical MDR's engine pieces: the splines as piecewise polynomials
(numeric/_mdr/ppoly.py) against scipy's own B-spline evaluation."""

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline

from hertzmdr.numeric._mdr.ppoly import Piecewise

EPS = np.finfo(float).eps


def _spline(n=40, k=5, seed=0, shift=0.0):
    """A quintic through uneven samples of a non-polynomial function on [0, 1]."""
    rng = np.random.default_rng(seed)
    x = np.sort(np.concatenate([[0.0, 1.0], rng.random(n)]))
    return make_interp_spline(x, np.sin(3 * x) + x**1.5 + shift * x**2, k=k)


@pytest.mark.parametrize("k", [1, 3, 5])
def test_piecewise_is_the_bspline(k):
    """The same polynomials as scipy's de Boor evaluation on [0, 1] (its knots included):
    f, f' and f'' (what the engine evaluates). Error model: both carry the rounding of the
    B-spline's coefficients, for the m-th derivative amplified by the knot spacings' ratio
    to the m-th power (150 here: 41 random knots, the closest 1.6e-4 apart): 8 eps, 1e-13
    and 1e-11 of the largest value (measured 8e-16, 6e-14, 2.5e-12 over five seeds)."""
    spl = _spline(k=k)
    pp = Piecewise.from_bspline(spl)
    u = np.concatenate([np.linspace(0, 1, 2001), spl.t[k:-k]])
    for nu, tol in zip(range(min(k, 2) + 1), (8 * EPS, 1e-13, 1e-11), strict=False):
        want = spl(u, nu=nu)
        got = pp(u, nu)
        assert np.max(np.abs(got - want)) <= tol * np.max(np.abs(want)), nu
