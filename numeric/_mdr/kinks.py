"""Numerical MDR, the kinks: where f' jumps, and the exact terms they put into g, g' and p.

At a kink b_j (a segment edge; every knot of a linear spline) f' jumps by s_j, and g' has the
branch point b_j s_j / sqrt(x^2 - b_j^2) (x > b_j). Its terms in g (5.52), g' and p (5.59) are
the generated ``mdr_kink_g``, ``mdr_kink_gprime`` and ``mdr_kink_pressure``
(derive/kink.py), with ``mdr_kink_G`` the integral of the term of g (5.57); the rest of g' is
smooth and left to the quadrature and the tables.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._mdr.spline import Rep

_EPS = np.finfo(float).eps


def jumps(rep: Rep) -> tuple[np.ndarray, np.ndarray]:
    """The radii b_j [m] where f' jumps (segment edges; every knot for k = 1) and the jumps
    s_j = f'(b_j+) - f'(b_j-) [1]."""
    if rep.kinks is None:
        b = rep.edges[1:-1]
        s = np.array([rep.segments[i + 1](bb, nu=1) - rep.segments[i](bb, nu=1)
                      for i, bb in enumerate(b)], float)
        if rep.k == 1:  # a linear spline: f' jumps at every knot
            inner = rep.knots[1:-1]
            h = np.diff(rep.knots)
            sk = rep.fprime(inner + h[1:] / 2) - rep.fprime(inner - h[:-1] / 2)
            sk[np.isin(inner, b)] = s
            b, s = inner, sk
        rep.kinks = (b, s)
    return rep.kinks


def terms(rep: Rep, x: np.ndarray, nu: int) -> np.ndarray:
    """sum_j of the kink terms of g (nu = 0) [m] or of g' (nu = 1) [1] at x [m]."""
    b, s = jumps(rep)
    out = np.zeros(x.shape)
    for bj, sj in zip(b, s, strict=True):
        sel = x > bj
        if sel.any():
            xs = x[sel]
            if nu == 0:
                out[sel] += gen.mdr_kink_g(bj, sj, xs)  # (5.52)
            else:
                out[sel] += gen.mdr_kink_gprime(bj, sj, xs)  # (5.52)
    return out


def primitive(rep: Rep, x: np.ndarray) -> np.ndarray:
    """sum_j of integral_(b_j)^x of the kink terms of g [m^2] at x [m] (x > b_j): the
    generated ``mdr_kink_G`` (its two terms go like (x - b)^(1/2) and cancel to (x - b)^(3/2):
    it loses digits relative to them as x -> b, not relative to the integral of g, which it
    is added to)."""
    b, s = jumps(rep)
    out = np.zeros(x.shape)
    for bj, sj in zip(b, s, strict=True):
        sel = x > bj
        if sel.any():
            out[sel] += gen.mdr_kink_G(bj, sj, x[sel])  # (5.57)
    return out


def pressure(rep: Rep, r: np.ndarray, a: float, E_star: float) -> np.ndarray:
    """sum_j of the kink terms of p(r) [Pa] (5.59), log-infinite at r = b_j."""
    out = np.zeros(r.shape)
    b, s = jumps(rep)
    for bj, sj in zip(b, s, strict=True):
        if bj < a and sj != 0:  # (a zero jump: k = 1 splines through collinear samples)
            out += gen.mdr_kink_pressure(E_star, a, bj, r, sj)  # (5.59)
    return out


def rounding(rep: Rep, r: np.ndarray, a: float, E_star: float) -> np.ndarray:
    """A bound of the rounding of the kink terms of p(r) [Pa] for r < a: the parameter
    m = (S/L)^2 near 1 (S, L = min, max of r and b_j) carries 4 eps of rounding, amplified
    by L^2/(L^2 - S^2): 4 eps E* |s| b / (pi L) * (1 + L^2/|L^2 - S^2|) per kink."""
    out = np.zeros(r.shape)
    b, s = jumps(rep)
    for bj, sj in zip(b, s, strict=True):
        L, S = np.maximum(r, bj), np.minimum(r, bj)
        sel = (r < a) & (L < a) & (L > S)
        out[sel] += (4 * _EPS * E_star * abs(sj) * bj / (np.pi * L[sel])
                     * (1 + L[sel] ** 2 / ((L[sel] - S[sel]) * (L[sel] + S[sel]))))
    return out
