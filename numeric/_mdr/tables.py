"""Numerical MDR, tables: the smooth remainders of g and g' on each segment of the profile.

G_s = g - (the kink terms) and q = g' - (the kink terms) are computed by quadrature on table
nodes and interpolated by quintic splines: in x on the first segment (nodes spaced at most x/32
towards the centre, where q ~ x^(n-1) for f ~ r^n), in t = sqrt(x - b) on a segment that starts
at a kink b (where they go like c0 + c1 sqrt(x - b) + ...); with them the remainder of
integral_0^x g (what the force (5.57) needs), the kinks' primitives (``kinks.primitive``) off.
Computed on first use only as far as the radii asked for need (a contact radius, a pressure,
a g or a displacement), grown when a later call asks for more, kept on the representation.
"""

from __future__ import annotations

from bisect import bisect_left
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric._mdr import kinks, quadrature
from hertzmdr.numeric._mdr.ppoly import Piecewise
from hertzmdr.numeric._mdr.spline import Rep
from hertzmdr.numeric._quadrature import gauss

GRADE = 0.5 ** np.arange(1, 31)  # geometric grading towards an endpoint: 2^-1 ... 2^-30


def _merge(base, extra):
    """The sorted union of ``base`` and those ``extra`` points not closer to a point of base
    than a fifth of the local spacing (nearly coincident nodes make an interpolating spline
    amplify the quadrature noise of the tabulated values)."""
    base = np.unique(base)
    i = np.clip(np.searchsorted(base, extra), 1, len(base) - 1)
    left, right = base[i - 1], base[i]
    keep = np.minimum(extra - left, right - extra) > 0.2 * (right - left)
    return np.unique(np.concatenate([base, extra[keep]]))


def _thin(v, step, rel):
    """A subset of the sorted positive v: each kept point at least min(step, rel * v) from the
    previous kept one (all of them where the spacing of v is finer than that). Greedy from
    the first point; v - 0.999 min(step, rel v) increases with v, so the next kept point is
    found by bisection (``bisect`` on lists: a few hundred scalar searches, where NumPy's
    per-call cost would dominate)."""
    v = np.asarray(v, float)
    if not len(v):
        return v
    y = (v - 0.999 * np.minimum(step, rel * v)).tolist()
    vl = v.tolist()
    n = len(vl)
    keep = [0]
    i = 0
    while True:
        i = max(bisect_left(y, vl[i]), i + 1)
        if i >= n:
            break
        keep.append(i)
    return v[keep]


def _fill(v, step):
    """Sorted nodes v with every interval longer than ``step`` divided evenly."""
    parts = [v[:1]]
    for lo, hi in zip(v[:-1], v[1:], strict=True):
        n = max(1, int(np.ceil((hi - lo) / step)))
        parts.append(np.linspace(lo, hi, n + 1)[1:])
    return np.concatenate(parts)


#: Nodes past a radius that a table must have for its spline to be as accurate there as
#: in the interior (the interpolating quintic's end conditions act over a few intervals).
EXTRA = 6


@dataclass
class Seg:
    """Tables of the smooth remainders on one segment [lo, hi] of the profile: in x on the
    first segment, in t = sqrt(x - lo) on a segment that starts at a kink (where the
    remainders go like sqrt(x - lo)).

    The nodes are planned for the whole segment; the values are computed (by quadrature) for
    the first ``built`` of them only, as far as the radii asked for need (``cover``), and the
    spline interpolates those: a table grows with the contact radius instead of being made
    for the whole profile at once. (A grown spline differs from the smaller one by about the
    tables' interpolation error, 1e-12 relative for a smooth profile.)"""

    lo: float
    hi: float
    in_t: bool
    nodes: np.ndarray  # all the planned nodes, in the table variable
    xv: np.ndarray  # the same as radii [m]
    vals: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))  # G_s, q, I
    spl: Piecewise | None = None  # quintic through the built nodes, columns G_s, q, I
    G: Piecewise | None = None  # its column G_s alone
    q: Piecewise | None = None  # its column q alone

    @property
    def built(self) -> int:
        return len(self.vals)

    def x_nodes(self) -> np.ndarray:
        """The built nodes as radii x [m]."""
        return self.xv[:self.built]

    def var(self, x):
        """The table variable of x [m]: x, or sqrt(x - lo) past a kink."""
        return np.sqrt(np.maximum(x - self.lo, 0.0)) if self.in_t else x

    def cover(self, rep: Rep, x: float):
        """Compute the table as far as radius x [m] needs (EXTRA nodes past it)."""
        n_all = len(self.nodes)
        if self.built == n_all:
            return
        n = min(n_all, int(np.searchsorted(self.xv, x)) + 1 + EXTRA)
        if n <= self.built:
            return
        from scipy.interpolate import make_interp_spline

        xv = self.xv[self.built:n]
        gg, q, GG = quadrature.direct(rep, xv, with_G=True)
        # G_s = g - the kink terms; the remainder of integral_0^x g (the kinks' primitives
        # off) has G_s as its derivative: smooth in the table variable as well
        new = np.column_stack([gg - kinks.terms(rep, xv, 0), q, GG - kinks.primitive(rep, xv)])
        self.vals = np.concatenate([self.vals, new])
        # as piecewise polynomials (``ppoly``: evaluated faster than the BSpline)
        self.spl = Piecewise.from_bspline(
            make_interp_spline(self.nodes[:n], self.vals, k=min(5, n - 1)))
        # the columns G_s and q alone, on the same knots (for the callers that need one)
        self.G, self.q = self.spl.column(0), self.spl.column(1)


def _plan(rep: Rep) -> list[Seg]:
    """The segments' tables with their nodes planned and nothing computed."""
    out = []
    for lo, hi in zip(rep.edges[:-1], rep.edges[1:], strict=True):
        kn = rep.knots[(rep.knots > lo) & (rep.knots < hi)]
        if lo == 0:
            # spacing at most (hi - lo)/table_nodes, and at most x/32 towards the
            # centre, where q ~ x^(n-1) for f ~ r^n; 10 levels below the first knot
            base = np.concatenate([[lo], _thin(kn, hi / rep.table_nodes, 1 / 32), [hi]])
            v = _merge(base, base[1] * GRADE[:10])
            xv = v
        else:
            kn = kn[::-(-len(kn) // rep.table_nodes)] if len(kn) else kn
            # t = sqrt(x - lo): the knots' images, and the wide intervals near t = 0
            # divided evenly (as many nodes as knots would give evenly)
            T = np.sqrt(hi - lo)
            v = _fill(np.concatenate([[0.0], np.sqrt(kn - lo), [T]]), T / (len(kn) + 1))
            xv = lo + v * v
            xv[-1] = hi
        out.append(Seg(lo, hi, lo != 0, v, xv))
    return out


def tables(rep: Rep, upto: float | None = None) -> list[Seg]:
    """The tables of every segment of ``rep``, computed as far as the radius ``upto`` [m]
    (None: the whole profile); kept on ``rep`` and grown on later calls."""
    if rep.tables is None:
        rep.tables = _plan(rep)
    x = rep.edges[-1] if upto is None else upto
    for seg in rep.tables:
        if seg.lo > x:
            break
        seg.cover(rep, min(x, seg.hi))
    return rep.tables


def covered(rep: Rep) -> tuple[np.ndarray, np.ndarray]:
    """The radii [m] of the nodes computed so far (all segments, ascending) and g there [m]
    (the quadrature's values: the splines interpolate them)."""
    xs, gs = [], []
    for seg in rep.tables or []:
        if not seg.built:
            break
        xv = seg.x_nodes()
        xs.append(xv)
        gs.append(seg.vals[:, 0] + kinks.terms(rep, xv, 0))
    if not xs:
        return np.zeros(0), np.zeros(0)
    return np.concatenate(xs), np.concatenate(gs)


def _eval(rep: Rep, x, col=None):
    """The tables (columns G_s, q, I; or the column ``col``, 0 or 1) at |x| [m], segment by
    segment, computed as far as the largest x first."""
    x = np.abs(np.asarray(x, float))
    tabs = tables(rep, float(x.max()) if x.size else 0.0)

    def spline(seg):
        return seg.spl if col is None else (seg.G, seg.q)[col]

    if len(tabs) == 1:
        return spline(tabs[0])(x)
    out = np.zeros(x.shape + ((3,) if col is None else ()))
    idx = rep.seg_index(x)
    for i, seg in enumerate(tabs):
        sel = idx == i
        if sel.any():
            out[sel] = spline(seg)(seg.var(x[sel]))
    return out


def g(rep: Rep, x) -> np.ndarray:
    """g(x) [m] (5.52) from the tables and the kink terms."""
    x = np.abs(np.asarray(x, float))
    return _eval(rep, x, 0) + kinks.terms(rep, x, 0)


def gprime(rep: Rep, x) -> np.ndarray:
    """g'(x) [1] from the table of q and the kink terms (+inf at a kink x = b_j)."""
    x = np.abs(np.asarray(x, float))
    return _eval(rep, x, 1) + kinks.terms(rep, x, 1)


def g_and_gprime(rep: Rep, x) -> tuple[np.ndarray, np.ndarray]:
    """g(x) [m] and g'(x) [1] from one evaluation of the tables."""
    x = np.abs(np.asarray(x, float))
    t = _eval(rep, x)
    return t[..., 0] + kinks.terms(rep, x, 0), t[..., 1] + kinks.terms(rep, x, 1)


def G(rep: Rep, x) -> np.ndarray:
    """integral_0^x g [m^2] (the integral of (5.57)): its remainder at the table node x_j
    below x (the quadrature's value there, not interpolated: near a segment's start or the
    axis the integral is far smaller than the table's values elsewhere, and a spline of it
    would carry their absolute error), plus integral_(x_j)^x G_s by 4-point Gauss-Legendre
    (exact: one piece of the quintic spline, times dx/dt = 2t past a kink), plus the kinks'
    primitives."""
    x = np.abs(np.asarray(x, float))
    tabs = tables(rep, float(x.max()) if x.size else 0.0)
    out = np.zeros(x.shape)
    idx = rep.seg_index(x)
    t, w = gauss(4)
    for i, seg in enumerate(tabs):
        sel = idx == i
        if not sel.any():
            continue
        v = seg.var(x[sel])
        j = np.minimum(np.maximum(np.searchsorted(seg.nodes[:seg.built], v, side="right") - 1,
                                  0), seg.built - 1)
        half = (v - seg.nodes[j]) / 2
        vv = (seg.nodes[j] + half)[..., None] + half[..., None] * t
        Gs = seg.G(vv)
        if seg.in_t:
            Gs = Gs * 2 * vv
        out[sel] = seg.vals[j, 2] + half * np.sum(w * Gs, axis=-1)
    return out + kinks.primitive(rep, x)
