"""Numerical MDR, the spline representation of the profile f at one resolution.

f is interpolated (or smoothed) by a spline of degree k per segment between the breakpoints
(kinks); ``Rep`` holds the splines and, filled on first use by the other modules, the caches
of the quadrature nodes, the kinks and the tables.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from hertzmdr.numeric._mdr.ppoly import Piecewise

if TYPE_CHECKING:  # scipy is imported when the first representation is built
    from scipy.interpolate import BSpline


@dataclass
class Rep:
    """A piecewise spline representation of f at one resolution, and its MDR caches.

    f' jumps by s_j at the kinks b_j (the segment edges; every knot for k = 1). Then
    g'(x) = q(x) + sum_j b_j s_j / sqrt(x^2 - b_j^2) and g(x) = G_s(x) + sum_j b_j s_j
    acosh(x / b_j) (terms for x > b_j), where q(x) = integral_0^(pi/2) h(x sin theta) dtheta,
    h = (u f')' away from the kinks, and G_s' = q. The kink terms are exact (``kinks``); q
    and G_s are tabulated (``tables``; they go like c0 + c1 sqrt(x - b_j) + ... past a kink:
    tables in sqrt(x - b_j)).
    """

    segments: list[BSpline]  # one per segment
    edges: np.ndarray  # segment edges, edges[0] = 0, edges[-1] = r_max
    m_theta: int  # Gauss points per panel
    knots: np.ndarray  # the sample radii: the spline's pieces
    k: int = 5
    table_nodes: int = 128  # table spacing at most (segment length)/table_nodes
    # filled on first use by tables.tables(), kinks.jumps() and quadrature.ugrid()
    tables: list | None = field(default=None, repr=False)  # list[tables.Seg]
    kinks: tuple[np.ndarray, np.ndarray] | None = field(default=None, repr=False)  # (b, s)
    # (piece edges, nodes u, weights * f'(u), weights * (u f')'(u))
    ugrid: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = field(
        default=None, repr=False)
    _pp: list[Piecewise] | None = field(default=None, repr=False)  # the segments' polynomials
    # a smoothed representation's |f_i - s(r_i)| at its knots [m] (None: interpolating)
    residual: np.ndarray | None = field(default=None, repr=False)

    def polys(self) -> list[Piecewise]:
        """The segments' splines as piecewise polynomials (``ppoly``; made on first use and
        shared with the copies of ``with_quadrature``, the splines being the same)."""
        if self._pp is None:
            self._pp = [Piecewise.from_bspline(spl) for spl in self.segments]
        return self._pp

    def seg_index(self, u):
        """The segment holding each radius u [m]."""
        if len(self.segments) == 1:
            return np.zeros(np.shape(u), int)
        # (np.minimum/np.maximum: np.clip on integers takes a slow path)
        return np.minimum(np.maximum(np.searchsorted(self.edges, u, side="right") - 1, 0),
                          len(self.segments) - 1)

    def derivs(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """f'(u) and f''(u), one segment lookup for both."""
        u = np.asarray(u, float)
        pps = self.polys()
        if len(pps) == 1:
            i, h = pps[0].locate(u)
            return pps[0].at(i, h, 1), pps[0].at(i, h, 2)
        f1, f2 = np.zeros(u.shape), np.zeros(u.shape)
        idx = self.seg_index(u)
        for j, pp in enumerate(pps):
            sel = idx == j
            if sel.any():
                i, h = pp.locate(u[sel])
                f1[sel], f2[sel] = pp.at(i, h, 1), pp.at(i, h, 2)
        return f1, f2

    def smoothing_error(self, x) -> np.ndarray:
        """An estimate of a smoothed representation's own error |s - f| [m] on [0, x], x [m]
        (array): the largest residual |f_i - s(r_i)| at the samples up to the first one at or
        beyond x. The residual is the smoothing's error plus the noise of f_i: it covers the
        error where the smoothing is biased (the error shows in it) and overstates it where
        it is not (the noise, of which the smoothing keeps a fraction). 0 when interpolating."""
        x = np.asarray(x, float)
        if self.residual is None:
            return np.zeros(x.shape)
        upto = np.maximum.accumulate(self.residual)
        return upto[np.minimum(np.searchsorted(self.knots, x), len(upto) - 1)]

    def fprime(self, u):
        """f'(u) [1]."""
        return self.derivs(u)[0]

    def with_quadrature(self, m_theta: int, table_nodes: int | None = None) -> Rep:
        """The same splines with ``m_theta`` Gauss points a panel (and ``table_nodes``)."""
        return replace(self, m_theta=m_theta, tables=None, ugrid=None,
                       table_nodes=self.table_nodes if table_nodes is None else table_nodes)

    def halved(self) -> Rep:
        """A coarser representation: every other knot (the segment edges kept), interpolated
        by a spline of the same degree through this one's values there, with half the table
        nodes. The third resolution of the pressure's bound (``Solution.pressure``), which
        measures the order at which the (coarse, fine) pair converges."""
        keep = np.zeros(len(self.knots), bool)
        keep[::2] = True
        keep[-1] = True
        keep |= np.isin(self.knots, self.edges)
        r = self.knots[keep]
        seg = self.seg_index(r)
        f = np.empty(len(r))
        for j in np.unique(seg):  # each segment's spline at its own knots, at once
            f[seg == j] = self.segments[j](r[seg == j])
        out = build(r, f, self.edges[1:-1], self.k, None, self.m_theta)
        out.table_nodes = max(8, self.table_nodes // 2)
        return out

    def panel_knots(self):
        """Knots used as panel breaks: all of them for k = 1 (f' jumps there), every few for
        the smoother splines (at most 64 panels), always the segment edges."""
        inner = self.knots[1:-1]
        step = 1 if self.k == 1 else max(1, len(inner) // 64)
        return np.union1d(inner[::step], self.edges[1:-1])


def build(r, f, breakpoints, k, smoothing, m_theta) -> Rep:
    """The spline representation of the samples (r_i, f_i) [m], one spline per segment
    between the ``breakpoints`` [m]: interpolating of degree k, or a cubic smoothing spline
    (``smoothing``: its parameter, or "gcv"; see ``smoothed``)."""
    from scipy.interpolate import make_interp_spline

    edges = np.concatenate([[0.0], breakpoints, [r[-1]]])
    segments = []
    residual = np.zeros(len(r)) if smoothing is not None else None
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        sel = (r >= lo - 1e-15 * hi) & (r <= hi * (1 + 1e-15))
        rs, fs = r[sel], f[sel]
        kk = min(k, len(rs) - 1)
        if kk < 1:
            raise ValueError(f"segment [{lo}, {hi}] has {len(rs)} sample(s); need >= 2")
        if smoothing is not None:
            spl = smoothed(rs, fs, None if smoothing == "gcv" else float(smoothing))
            residual[sel] = np.maximum(residual[sel], np.abs(fs - spl(rs)))
            segments.append(spl)
        else:
            segments.append(make_interp_spline(rs, fs, k=kk))
    return Rep(segments, edges, m_theta, np.asarray(r, float), k if smoothing is None else 3,
               residual=residual)


def smoothed(rs: np.ndarray, fs: np.ndarray, lam: float | None) -> BSpline:
    """The cubic smoothing spline of the samples (rs, fs) [m] (scipy's
    ``make_smoothing_spline``; ``lam`` its parameter, None: by generalized cross-validation).

    A segment from the axis is smoothed with its mirror image f(-r) = f(r) and kept on
    [0, rs[-1]]: the smoothing spline is natural (s'' = 0 at its ends), and at the axis that
    would bend a profile whose f''(0) is not 0 (for r^2/2 with noise of 5e-7 on 401 samples,
    s(0) was 8.5e-5 below f(0), s'(0) 0.013, and the force at a = 0.5 off Hertz by 5.1e-4;
    mirrored, 1e-7 and 1e-6). Its restriction is the clamped cubic spline on the same knots
    with s'(0) = 0 (f is even) and the mirrored spline's s'(rs[-1]): the same polynomials."""
    from scipy.interpolate import make_interp_spline, make_smoothing_spline

    if rs[0] != 0:
        return make_smoothing_spline(rs, fs, lam=lam)
    both = make_smoothing_spline(np.concatenate([-rs[:0:-1], rs]),
                                 np.concatenate([fs[:0:-1], fs]), lam=lam)
    return make_interp_spline(rs, both(rs), k=3,
                              bc_type=([(1, 0.0)], [(1, float(both(rs[-1], 1)))]))
