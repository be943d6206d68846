"""Abel transforms, the edge of the support: where the samples stop, and its snapping.

The contact radius a of one row is found from its last non-zero samples (a cubic through the
last four of q, or of p^2, extrapolated to its root), snapped to a sample within 1e-9 dx, and
checked against the grid.
"""

from __future__ import annotations

import numpy as np

_EDGE_CACHE: dict = {}


_EDGE_DEGREE = 3  # the edge extrapolation: cubic through the last 4 samples


def _edge_index(y: np.ndarray, x_edge: float | None) -> tuple[int, float | None]:
    """(K, A) of one row in units dx = 1: K the last sample inside the support, A = a^2.

    ``y`` is q (inverse) or p^2 (forward): a function vanishing linearly in s at the edge.
    """
    N = y.size
    if x_edge is not None:
        K = max(min(int(np.ceil(x_edge)) - 1, N - 1), 0)
        return _snap(K, x_edge**2)
    nz = np.flatnonzero(y)
    if nz.size == 0:
        return -1, None
    K = int(nz[-1])
    if K == N - 1:
        return K, None  # no edge on the grid: truncated transform
    deg = min(_EDGE_DEGREE, K)
    span = 2.0 * K + 1  # s_(K+1) - s_K; the local variable u = (s - s_K)/span
    if deg == 0:
        return K, K**2 + span
    coef = _edge_vandermonde_inv(K, deg) @ y[K - deg:K + 1]  # power coefficients in u
    u = _edge_root(coef)
    return _snap(K, K**2 + span * u)


def _snap(K: int, A: float) -> tuple[int, float]:
    """An edge within 1e-9 dx after the sample K is that sample (a/dx off a grid point by
    rounding): a last piece [s_K, A] that short would make the interpolant through the nearly
    coincident nodes s_K, A amplify the rounding of the (nearly zero) sample K by dx/(a - x_K).
    The sample K is then replaced by the edge's exact 0."""
    if K >= 1 and A - K**2 <= 1e-9 * (2 * K + 1):
        return K - 1, float(K**2)
    return K, A


def _edge_vandermonde_inv(K: int, deg: int) -> np.ndarray:
    key = (K, deg)
    V = _EDGE_CACHE.get(key)
    if V is None:
        nodes = (np.arange(K - deg, K + 1, dtype=float) ** 2 - K**2) / (2.0 * K + 1)
        V = np.linalg.inv(np.vander(nodes, deg + 1, increasing=True))
        if len(_EDGE_CACHE) > 4096:
            _EDGE_CACHE.clear()
        _EDGE_CACHE[key] = V
    return V


def _edge_root(coef: np.ndarray) -> float:
    """The smallest root in (0, 1] of the polynomial sum_k coef[k] u^k; 1 if there is none.

    Newton from the linear root (a few float operations; the data vanish nearly linearly),
    accepted when it converges inside (0, 1] with no sign change of the polynomial before it;
    otherwise the companion-matrix roots, polished by Newton.
    """
    c = [float(v) for v in coef]

    def val(u):
        acc, der = 0.0, 0.0
        for ck in reversed(c):
            der = der * u + acc
            acc = acc * u + ck
        return acc, der

    u = -c[0] / c[1] if c[1] != 0 else 0.5
    ok = False
    if 0 < u <= 1.5:
        for _ in range(8):
            f, d1 = val(u)
            if d1 == 0:
                break
            step = f / d1
            u -= step
            if abs(step) <= 1e-15 * max(abs(u), 1e-300):
                ok = True
                break
    if ok and 0 < u <= 1 + 1e-12:
        # no earlier root: the polynomial keeps the sign of c[0] on a few points of (0, u)
        mid = val(0.5 * u)[0]  # one probe: a root before u would show as a sign change
        if (mid > 0) == (c[0] > 0) and mid != 0:
            return min(u, 1.0)
    roots = np.polynomial.polynomial.polyroots(coef) if np.any(coef[1:]) else np.array([])
    real = roots.real[(np.abs(roots.imag) <= 1e-9) & (roots.real > 0)
                      & (roots.real <= 1 + 1e-12)]
    if not real.size:
        return 1.0  # no root before the next (zero) sample: the edge is that sample
    u = float(real.min())
    for _ in range(3):  # polish: the companion matrix loses digits when the top coefficients
        # are rounding noise (data linear in s, as for Hertz); a step is kept only where it
        # lowers |f| (at a double root f and f' are both rounding: (u - 1/2)^2 went to 0.625)
        f, d1 = val(u)
        if d1 == 0:
            break
        step = u - f / d1
        if not abs(val(step)[0]) < abs(f):
            break
        u = step
    return min(max(u, 0.0), 1.0)


def _edge_over_dx(a: float, h: float, N: int) -> float:
    """The edge a > 0 in units of dx = h, checked to lie on the grid of N samples."""
    if not a / h <= N - 1:
        raise ValueError(f"edge = {a!r} is out of range; valid: 0 < edge <= (N-1)*dx = "
                         f"{(N - 1) * h!r}")
    return a / h
