"""Composite Gauss-Legendre rules shared by the numerical modules (NumPy only)."""

from __future__ import annotations

import numpy as np

_GL_CACHE: dict[int, tuple[np.ndarray, np.ndarray]] = {}


def gauss(m: int) -> tuple[np.ndarray, np.ndarray]:
    """m-point Gauss-Legendre nodes on [-1, 1] and their weights (cached)."""
    if m not in _GL_CACHE:
        _GL_CACHE[m] = np.polynomial.legendre.leggauss(m)
    return _GL_CACHE[m]


def panels(lo, hi, breaks, m):
    """Composite Gauss-Legendre nodes/weights on [lo, hi] (arrays, shape (M,)), split at the
    ``breaks`` (shape (M, B), any order, values outside [lo, hi] clipped; coinciding breaks
    give empty panels with zero weights). Returns (nodes, weights), each (M, (B + 1) m)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    edges = np.concatenate([lo[:, None], np.clip(breaks, lo[:, None], hi[:, None]),
                            hi[:, None]], axis=1)
    edges = np.sort(edges, axis=1)
    t, w = gauss(m)
    left, right = edges[:, :-1], edges[:, 1:]
    half = (right - left) / 2
    nodes = (left + half)[:, :, None] + half[:, :, None] * t
    weights = half[:, :, None] * w
    return nodes.reshape(len(lo), -1), weights.reshape(len(lo), -1)
