"""Numerical MDR, resolution: the pairs (coarse, fine) of representations a solve compares,
and how each kind of profile refines them when the error bound misses rtol.

A sampled profile cannot be refined past its samples: the fine representation takes all of
them, the coarse one every other; what can be refined is the quadrature (``QUADRATURE_LEVELS``).
A callable is sampled on grids of m and 2m intervals a segment, m = n, 2n, 4n, ... up to n_max.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric._mdr.spline import Rep, build

# Gauss-Legendre points a panel of the (coarse, fine) quadratures, in the order a sampled
# profile refines them when the error bound misses rtol (its splines cannot be refined)
QUADRATURE_LEVELS = ((6, 8), (10, 12), (14, 16))


class Samples:
    """The representations of a sampled profile: all samples (fine) and every other one
    (coarse), at increasing quadrature resolution (the splines cannot be refined)."""

    only_quadrature = True  # a level that does not lower the bound ends the refinement

    def __init__(self, r: np.ndarray, f: np.ndarray, breakpoints: np.ndarray, k: int,
                 smoothing: float | str | None):
        # the coarse representation: every other sample, keeping 0, the breakpoints and r_max
        keep = np.zeros(len(r), bool)
        keep[::2] = True
        keep[-1] = True
        keep |= np.isin(r, breakpoints)
        coarse = build(r[keep], f[keep], breakpoints, k, smoothing, 6)
        fine = build(r, f, breakpoints, k, smoothing, 8)
        coarse.table_nodes = fine.table_nodes // 2  # the coarse one: coarser tables too
        self._base = (coarse, fine)
        self._levels: dict[int, tuple[Rep, Rep]] = {}

    def pair(self, level: int) -> tuple[Rep, Rep] | None:
        """(coarse, fine) at the quadrature ``level``; None past the last."""
        if level >= len(QUADRATURE_LEVELS):
            return None
        if level not in self._levels:
            mc, mf = QUADRATURE_LEVELS[level]
            c, f = self._base
            self._levels[level] = (c if c.m_theta == mc else c.with_quadrature(mc),
                                   f if f.m_theta == mf else f.with_quadrature(mf))
        return self._levels[level]

    def why_not(self, err: float, level: int) -> str:
        """Why the bound ``err`` of ``level`` could not be lowered further."""
        n = len(self._base[1].knots)
        return (f"a sampled profile cannot be refined past its {n} samples; its estimate is "
                f"{err:.1e} with {QUADRATURE_LEVELS[level][1]} Gauss points a panel")


class Grid:
    """The representations of a callable profile on grids of m and 2m intervals a segment,
    m = n, 2n, 4n, ... while 2m <= n_max (built on first use, kept)."""

    only_quadrature = False

    def __init__(self, f, r_max: float, breakpoints: np.ndarray, n: int, k: int, n_max: int):
        self._f, self._bp, self._n, self._k, self._n_max = f, breakpoints, n, k, n_max
        self._edges = np.concatenate([[0.0], breakpoints, [r_max]])
        self._reps: dict[int, Rep] = {}
        self._coarse: dict[int, Rep] = {}  # the same grids as the coarse of a pair

    def rep(self, m: int) -> Rep:
        """The representation on the grid of m intervals a segment."""
        if m not in self._reps:
            parts = [np.linspace(lo, hi, m + 1)[:-1]
                     for lo, hi in zip(self._edges[:-1], self._edges[1:], strict=True)]
            rr = np.concatenate(parts + [self._edges[-1:]])
            ff = np.asarray(self._f(rr), float)
            if ff.shape != rr.shape or not np.all(np.isfinite(ff)):
                raise ValueError("f returned a non-finite value (or the wrong shape) on "
                                 "[0, r_max]; valid: finite values, one per radius")
            self._reps[m] = build(rr, ff - ff[0], self._bp, self._k, None, 8)
        return self._reps[m]

    def pair(self, level: int) -> tuple[Rep, Rep] | None:
        """(coarse, fine) on the grids of m and 2m intervals, m = n 2^level; None past
        n_max."""
        m = self._n * 2**level
        if level > 0 and 2 * m > self._n_max:
            return None
        if m not in self._coarse:  # the coarse one of a pair: coarser tables too
            fine = self.rep(m)
            self._coarse[m] = fine.with_quadrature(fine.m_theta, fine.table_nodes // 2)
        return self._coarse[m], self.rep(2 * m)

    def why_not(self, err: float, level: int) -> str:
        """Why the bound ``err`` of ``level`` could not be lowered further."""
        m = 2 * self._n * 2**level
        return (f"the callable's grid reached {m} intervals a segment (n_max = {self._n_max}); "
                f"its estimate is {err:.1e}")
