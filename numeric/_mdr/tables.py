"""Numerical MDR, tables: the smooth remainders of g and g' on each segment of the profile.

G_s = g - (the kink terms) and q = g' - (the kink terms) are computed by quadrature on table
nodes and interpolated by quintic splines: in x on the first segment (nodes spaced at most x/32
towards the centre, where q ~ x^(n-1) for f ~ r^n), in t = sqrt(x - b) on a segment that starts
at a kink b (where they go like c0 + c1 sqrt(x - b) + ...). Built on first use (a pressure, a
g or a displacement), kept on the representation.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from scipy.interpolate import BSpline

from hertzmdr.numeric._mdr import kinks, quadrature
from hertzmdr.numeric._mdr.spline import Rep

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
    previous kept one (all of them where the spacing of v is finer than that)."""
    keep, last = [], -np.inf
    for x in v:
        if x - last >= min(step, rel * x) * 0.999:
            keep.append(x)
            last = x
    return np.asarray(keep, float)


def _fill(v, step):
    """Sorted nodes v with every interval longer than ``step`` divided evenly."""
    parts = [v[:1]]
    for lo, hi in zip(v[:-1], v[1:], strict=True):
        n = max(1, int(np.ceil((hi - lo) / step)))
        parts.append(np.linspace(lo, hi, n + 1)[1:])
    return np.concatenate(parts)


@dataclass
class Seg:
    """Tables of the smooth remainders on one segment [lo, hi] of the profile: in x on the
    first segment, in t = sqrt(x - lo) on a segment that starts at a kink (where the
    remainders go like sqrt(x - lo))."""

    lo: float
    hi: float
    in_t: bool
    nodes: np.ndarray  # in the table variable
    G: BSpline  # quintic spline of G_s (the remainder of g)
    q: BSpline  # quintic spline of q (the remainder of g')
    I: BSpline  # quintic spline of the remainder of integral_0^x g (kinks.primitive off)

    def x_nodes(self) -> np.ndarray:
        """The table's nodes as radii x [m]."""
        return self.lo + self.nodes**2 if self.in_t else self.nodes

    def var(self, x):
        """The table variable of x [m]: x, or sqrt(x - lo) past a kink."""
        return np.sqrt(np.maximum(x - self.lo, 0.0)) if self.in_t else x


def tables(rep: Rep) -> list[Seg]:
    """The tables of every segment of ``rep`` (built on first use, kept on it)."""
    if rep.tables is None:
        from scipy.interpolate import make_interp_spline

        out = []
        for lo, hi in zip(rep.edges[:-1], rep.edges[1:], strict=True):
            kn = rep.knots[(rep.knots > lo) & (rep.knots < hi)]
            if lo == 0:
                # spacing at most (hi - lo)/table_nodes, and at most x/32 towards the
                # centre, where q ~ x^(n-1) for f ~ r^n; 10 levels below the first knot
                base = np.concatenate([[lo], _thin(kn, hi / rep.table_nodes, 1 / 32),
                                       [hi]])
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
            gg, q, GG = quadrature.direct(rep, xv, with_G=True)
            Gs = gg - kinks.terms(rep, xv, 0)
            # the remainder of integral_0^x g: its derivative is G_s, smooth in v as well
            Is = GG - kinks.primitive(rep, xv)
            kk = min(5, len(v) - 1)
            out.append(Seg(lo, hi, lo != 0, v, make_interp_spline(v, Gs, k=kk),
                           make_interp_spline(v, q, k=kk), make_interp_spline(v, Is, k=kk)))
        rep.tables = out
    return rep.tables


def _eval(rep: Rep, x, which):
    """The table ``which`` ("G" or "q") at |x| [m], segment by segment."""
    x = np.abs(np.asarray(x, float))
    out = np.zeros(x.shape)
    idx = rep.seg_index(x)
    for i, seg in enumerate(tables(rep)):
        sel = idx == i
        if sel.any():
            out[sel] = getattr(seg, which)(seg.var(x[sel]))
    return out


def g(rep: Rep, x) -> np.ndarray:
    """g(x) [m] (5.52) from the tables and the kink terms."""
    x = np.abs(np.asarray(x, float))
    return _eval(rep, x, "G") + kinks.terms(rep, x, 0)


def gprime(rep: Rep, x) -> np.ndarray:
    """g'(x) [1] from the table of q and the kink terms (+inf at a kink x = b_j)."""
    x = np.abs(np.asarray(x, float))
    return _eval(rep, x, "q") + kinks.terms(rep, x, 1)


def G(rep: Rep, x) -> np.ndarray:
    """integral_0^x g [m^2] (the integral of (5.57)) from the tables and the kinks'
    primitives."""
    x = np.abs(np.asarray(x, float))
    return _eval(rep, x, "I") + kinks.primitive(rep, x)
