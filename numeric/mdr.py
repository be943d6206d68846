"""Numerical MDR (5.51)-(5.61) for any axisymmetric gap profile: a callable or samples.

Usage::

    from hertzmdr.numeric import mdr
    prof = mdr.Profile.from_samples(r_i, f_i, breakpoints=[b])  # or Profile.from_callable(f, r_max)
    res = prof.solve(depth=1e-6, E_star=1e11)            # or force=..., rtol=...
    res.contact_radius, res.force, res.rel_error     # rel_error: a bound
    res.rtol, res.met, res.why_not_met               # the target and whether it was met
    res.pressure(r), res.displacement(r), res.g(x)
    p, err = res.pressure(r, return_error=True)
    curve = prof.force_depth_curve(depths, E_star=1e11)  # F(d), a(d), rel_error per depth

Method (all lengths in m, pressures in Pa, forces in N):

- The profile f is represented by interpolating splines of degree ``k`` (5 by default: f' and
  f'' are then accurate to O(h^5), O(h^4) for a smooth profile sampled with spacing h), one per
  segment between user ``breakpoints`` (kinks such as the edge of a worn tip).
- At a kink b_j, f' jumps by s_j. With h = (u f')' away from the kinks,
  g'(x) = q(x) + sum_j b_j s_j / sqrt(x^2 - b_j^2) and g(x) = G_s(x) + sum_j b_j s_j
  acosh(x / b_j) (terms for x > b_j), q(x) = integral_0^x h(u) du / sqrt(x^2 - u^2), G_s' = q.
  The kink terms are exact; q and G_s go like c0 + c1 sqrt(x - b_j) + ... past a kink and are
  tabulated in t = sqrt(x - b_j) there (in x on the first segment) by quintic splines,
  built on first use (a pressure, g or a displacement).
- (5.52) by quadrature: g(x) = x integral_0^x f'(u) du / sqrt(x^2 - u^2) and q(x): the
  spline's pieces at least two widths below x by Gauss-Legendre on fixed nodes in u (f', f''
  evaluated once for every x), the rest with u = x sin(theta), which removes the endpoint
  singularity, by Gauss-Legendre in theta broken at the pieces' ends.
- (5.55) g(a) = d by safeguarded Newton on g and g' by quadrature (no tables); force control
  solves F(a) = F by Brent's method on the monotone F(a) = 2 E* integral_0^a x g'(x) dx.
- (5.57) F = 2 E* (d a - integral_0^a g), integral_0^a g = integral_0^a f'(u) sqrt(a^2 - u^2) du.
- (5.59) p(r) = (E*/pi) integral_r^a g'(x) dx / sqrt(x^2 - r^2): the kink terms by the
  generated ``mdr_kink_pressure`` (incomplete elliptic integrals, log-infinite at r = b_j);
  the q part per segment with x = r + w^2 on the segment holding r (removes the Abel kernel's
  1/sqrt(x - r)) and x = b_j + t^2 on later segments, Gauss-Legendre graded towards w = 0 (or
  t = 0) down to the scale of the nearest singularity. p(0) is +inf for a conical tip (f'(0)
  > 0, resolved by both resolutions).
- (5.60) with x = r sin(theta): u(r) = (2/pi) integral_0^(asin(min(1, a/r))) (d - g(r sin theta)).
- (5.57) F = 2 E* (d a - integral_0^a g) by the generated ``mdr_force``.
- Error bound and the rtol contract: every result is computed twice, with the full
  resolution and with every other sample (samples) or half the grid (callables), coarser
  tables and fewer quadrature points. ``Solution.rel_error`` bounds the relative error of
  force, contact radius and depth by the larger of (1) their coarse-vs-fine relative
  differences, an upper estimate of the error of the coarse solution (so a conservative bound
  for the returned, fine one), and (2) the envelope of the differences of g and of its
  integral on radii within two coarse sample spacings of a, put through the linearized
  (5.55) and (5.57) (the differences at a alone can vanish by accident), plus a rounding
  floor (64 + 4 N) eps (the spline's derivative loses about log10(N) digits). The pressure's
  bound (``return_error=True``) adds the Abel integral of |q - q_coarse| and a rounding bound
  (a kink term's parameter (r/b)^2 near 1). ``rtol`` has one meaning: the target of
  ``rel_error``, in ``RTOL_RANGE`` (default ``DEFAULT_RTOL``). A callable's grid is doubled
  until the bound meets it; a sampled profile's quadrature is refined while that lowers the
  bound (its splines cannot be refined). ``Solution.met`` says whether it was met and
  ``why_not_met`` why not.

Measured convergence orders and timings are in ``docs/mdr.md`` (``benchmarks/bench_mdr.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._quadrature import gauss as _gauss
from hertzmdr.numeric._quadrature import panels as _panels
from hertzmdr.numeric._validate import as_float, nonnegative, positive, result

__all__ = ["Profile", "Solution", "ForceDepthCurve", "DEFAULT_RTOL", "RTOL_RANGE"]

#: The target of the relative error bound of a solve when none is given [1].
DEFAULT_RTOL = 1e-8
#: The targets a solve accepts, (lo, hi) [1]. lo is measured: the bound that the callable
#: refinement reaches at n_max = 8192 intervals a segment for a set of profiles (smooth r^2.5
#: and r^1.5, a kinked tip with its breakpoint, a sphere-cone tip with and without its tangent
#: point as a breakpoint, each at two depths) is 1.3e-13 ... 1.0e-11; the largest, rounded
#: up, is lo (tests/test_mdr.py::test_rtol_range_lower_end re-measures it). A sampled profile
#: reaches what its samples allow: its rounding floor alone is (64 + 4 N) eps, 4.5e-12 at
#: N = 5000. hi: the bound is a linearization of the difference of two resolutions
#: (da = dg/g'(a)); tests/test_mdr.py::test_bound_against_mpmath checks it on errors up to
#: about 1e-3, and a target above 1e-2 would rest on it where it is untested.
RTOL_RANGE = (1e-11, 1e-2)

_GRADE = 0.5 ** np.arange(1, 31)  # geometric grading towards an endpoint: 2^-1 ... 2^-30


def _graded(lo, hi, toward_lo=True, levels=30):
    """Break points grading [lo, hi] geometrically towards lo (or hi): shape (M, levels)."""
    lo, hi = np.asarray(lo, float)[:, None], np.asarray(hi, float)[:, None]
    g = _GRADE[:levels]
    return lo + (hi - lo) * g if toward_lo else hi - (hi - lo) * g


def _subsample(v, n):
    """At most about n of the sorted values v (every few), for panel breaks."""
    return v[:: max(1, len(v) // n)] if len(v) else v


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
class _Seg:
    """Tables of the smooth remainders on one segment [lo, hi] of the profile: in x on the
    first segment, in t = sqrt(x - lo) on a segment that starts at a kink (where the
    remainders go like sqrt(x - lo))."""

    lo: float
    hi: float
    in_t: bool
    nodes: np.ndarray  # in the table variable
    G: object  # quintic spline of G_s (the remainder of g)
    q: object  # quintic spline of q (the remainder of g')

    def var(self, x):
        return np.sqrt(np.maximum(x - self.lo, 0.0)) if self.in_t else x


@dataclass
class _Rep:
    """A piecewise spline representation of f at one resolution, and its MDR tables.

    f' jumps by s_j at the kinks b_j (the segment edges; every knot for k = 1). Then
    g'(x) = q(x) + sum_j b_j s_j / sqrt(x^2 - b_j^2) and g(x) = G_s(x) + sum_j b_j s_j
    acosh(x / b_j) (terms for x > b_j), where q(x) = integral_0^(pi/2) h(x sin theta) dtheta,
    h = (u f')' away from the kinks, and G_s' = q. The kink terms are exact; q and G_s are
    tabulated (they go like c0 + c1 sqrt(x - b_j) + ... past a kink: tables in sqrt(x - b_j)).
    """

    segments: list  # scipy BSplines, one per segment
    edges: np.ndarray  # segment edges, edges[0] = 0, edges[-1] = r_max
    m_theta: int  # Gauss points per panel
    knots: np.ndarray  # the sample radii: the spline's pieces
    k: int = 5
    _tables: list | None = field(default=None, repr=False)
    _kinks: tuple | None = field(default=None, repr=False)
    _u: tuple | None = field(default=None, repr=False)
    table_nodes: int = 128  # table spacing at most (segment length)/table_nodes

    def _seg_index(self, u):
        return np.clip(np.searchsorted(self.edges, u, side="right") - 1, 0,
                       len(self.segments) - 1)

    def derivs(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """f'(u) and f''(u), one segment lookup for both."""
        u = np.asarray(u, float)
        f1, f2 = np.zeros(u.shape), np.zeros(u.shape)
        if len(self.segments) == 1:
            spl = self.segments[0]
            return spl(u, nu=1), (spl(u, nu=2) if self.k > 1 else f2)
        idx = self._seg_index(u)
        for i, spl in enumerate(self.segments):
            sel = idx == i
            if sel.any():
                f1[sel] = spl(u[sel], nu=1)
                if self.k > 1:
                    f2[sel] = spl(u[sel], nu=2)
        return f1, f2

    def fprime(self, u):
        return self.derivs(u)[0]

    def with_quadrature(self, m_theta: int, table_nodes: int | None = None) -> _Rep:
        """The same splines with ``m_theta`` Gauss points a panel (and ``table_nodes``)."""
        return replace(self, m_theta=m_theta, _tables=None, _u=None,
                       table_nodes=self.table_nodes if table_nodes is None else table_nodes)

    def _panel_knots(self):
        """Knots used as panel breaks: all of them for k = 1 (f' jumps there), every few for
        the smoother splines (at most 64 panels), always the segment edges."""
        inner = self.knots[1:-1]
        step = 1 if self.k == 1 else max(1, len(inner) // 64)
        return np.union1d(inner[::step], self.edges[1:-1])

    def kinks(self):
        """The radii b_j where f' jumps (segment edges; every knot for k = 1) and the jumps
        s_j = f'(b_j+) - f'(b_j-)."""
        if self._kinks is None:
            b = self.edges[1:-1]
            s = np.array([self.segments[i + 1](bb, nu=1) - self.segments[i](bb, nu=1)
                          for i, bb in enumerate(b)], float)
            if self.k == 1:  # a linear spline: f' jumps at every knot
                inner = self.knots[1:-1]
                h = np.diff(self.knots)
                sk = self.fprime(inner + h[1:] / 2) - self.fprime(inner - h[:-1] / 2)
                sk[np.isin(inner, b)] = s
                b, s = inner, sk
            self._kinks = (b, s)
        return self._kinks

    def _kink_terms(self, x, nu):
        """sum_j b_j s_j acosh(x / b_j) (nu = 0) or b_j s_j / sqrt(x^2 - b_j^2) (nu = 1)."""
        b, s = self.kinks()
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

    def _ugrid(self):
        """Gauss nodes in u on every piece of the spline (between consecutive sample radii,
        where f is one polynomial), with f'(u) and h(u) = f' + u f'' there: computed once."""
        if self._u is None:
            br = np.unique(np.concatenate([self.knots, self.edges]))
            t, w = _gauss(self.m_theta - 2)
            half = np.diff(br) / 2
            u = (br[:-1] + half)[:, None] + half[:, None] * t
            f1, f2 = self.derivs(u.ravel())
            f1, f2 = f1.reshape(u.shape), f2.reshape(u.shape)
            wt = half[:, None] * w
            self._u = (br, u.ravel(), (wt * f1).ravel(), (wt * (f1 + u * f2)).ravel())
        return self._u

    def direct(self, x, with_G=False):
        """g(x) (5.52), the smooth part q(x) of g' and G(x) = integral_0^x g by quadrature
        (G only ``with_G``, else zeros):

            g = x integral_0^x f'(u) du / sqrt(x^2 - u^2),  q = integral_0^x h(u) du /
            sqrt(x^2 - u^2),  G = integral_0^x f'(u) sqrt(x^2 - u^2) du.

        The spline's pieces far from u = x (at least two widths away) by Gauss-Legendre in u
        on fixed nodes (f', h evaluated once for all x); the rest, [u_near, x], with
        u = x sin(theta), which removes the 1/sqrt(x - u), by Gauss-Legendre in theta with
        panels broken at the pieces' ends."""
        x = np.atleast_1d(np.abs(np.asarray(x, float)))
        br, u, wf1, wh = self._ugrid()
        lo, hi = br[:-1], br[1:]
        width = hi - lo
        # first piece that is not far from x: u_near is its left end
        notfar = (x[:, None] - hi[None, :] < 2 * width[None, :])
        first = np.argmax(notfar, axis=1)
        u_near = lo[first]
        g, q, G = np.zeros(len(x)), np.zeros(len(x)), np.zeros(len(x))
        # far pieces are a prefix: the first nfar nodes in u; rows by increasing nfar, in
        # chunks computed up to the chunk's largest nfar
        nfar = first * (len(u) // len(lo))
        order = np.argsort(nfar, kind="stable")
        for c in range(0, len(x), 64):
            rows = order[c:c + 64]
            ncol = int(nfar[rows[-1]])
            if ncol == 0:
                continue
            xc, uc = x[rows, None], u[None, :ncol]
            far = np.arange(ncol)[None, :] < nfar[rows, None]
            root = np.sqrt(np.maximum((xc - uc) * (xc + uc), 1e-300))
            inv = far / root
            g[rows] = x[rows] * (inv @ wf1[:ncol])
            q[rows] = inv @ wh[:ncol]
            if with_G:
                G[rows] = (root * far) @ wf1[:ncol]
        # near part: theta from asin(u_near/x) to pi/2, broken at the pieces' ends
        jx = np.clip(np.searchsorted(br, x, side="right") - 1, 0, len(lo) - 1)
        K = int(np.max(jx - first)) + 1 if len(x) else 1
        kidx = np.minimum(first[:, None] + 1 + np.arange(K)[None, :], len(br) - 1)
        kb = br[kidx]
        with np.errstate(divide="ignore", invalid="ignore"):
            s0 = np.where(x > 0, u_near / x, 0.0)
            sk = np.where(x[:, None] > 0, kb / x[:, None], 1.0)
        th0 = np.arcsin(np.clip(s0, 0, 1))
        thk = np.arcsin(np.clip(sk, 0, 1))
        th, w = _panels(th0, np.full(len(x), np.pi / 2), thk, self.m_theta)
        live = w > 0
        uu = x[:, None] * np.sin(th)
        f1, f2 = np.zeros(th.shape), np.zeros(th.shape)
        f1[live], f2[live] = self.derivs(uu[live])
        g += x * np.sum(w * f1, axis=1)
        q += np.sum(w * (f1 + uu * f2), axis=1)
        if with_G:
            G += x**2 * np.sum(w * f1 * np.cos(th) ** 2, axis=1)
        return g, q, G

    def g_direct(self, x):
        """(5.52): g(x) = x * integral_0^(pi/2) f'(x sin theta) dtheta."""
        return self.direct(x)[0]

    def gprime_direct(self, x):
        """g'(x) = q(x) + the kink terms sum_j b_j s_j / sqrt(x^2 - b_j^2), x > b_j."""
        x = np.atleast_1d(np.abs(np.asarray(x, float)))
        return self.direct(x)[1] + self._kink_terms(x, 1)

    def g_and_gprime_direct(self, x):
        x = np.atleast_1d(np.abs(np.asarray(x, float)))
        gg, q, _ = self.direct(x)
        return gg, q + self._kink_terms(x, 1)

    def G(self, a):
        """integral_0^a g dx = integral_0^a f'(u) sqrt(a^2 - u^2) du."""
        return self.direct(a, with_G=True)[2]

    # -- tables of the smooth remainders, built on first use --------------------------------
    def tables(self) -> list[_Seg]:
        if self._tables is None:
            from scipy.interpolate import make_interp_spline

            out = []
            for lo, hi in zip(self.edges[:-1], self.edges[1:], strict=True):
                kn = self.knots[(self.knots > lo) & (self.knots < hi)]
                if lo == 0:
                    # spacing at most (hi - lo)/table_nodes, and at most x/32 towards the
                    # centre, where q ~ x^(n-1) for f ~ r^n; 10 levels below the first knot
                    base = np.concatenate([[lo], _thin(kn, hi / self.table_nodes, 1 / 32),
                                           [hi]])
                    v = _merge(base, base[1] * _GRADE[:10])
                    xv = v
                else:
                    kn = kn[::-(-len(kn) // self.table_nodes)] if len(kn) else kn
                    # t = sqrt(x - lo): the knots' images, and the wide intervals near t = 0
                    # divided evenly (as many nodes as knots would give evenly)
                    T = np.sqrt(hi - lo)
                    v = _fill(np.concatenate([[0.0], np.sqrt(kn - lo), [T]]), T / (len(kn) + 1))
                    xv = lo + v * v
                    xv[-1] = hi
                gg, q, _ = self.direct(xv)
                Gs = gg - self._kink_terms(xv, 0)
                kk = min(5, len(v) - 1)
                out.append(_Seg(lo, hi, lo != 0, v, make_interp_spline(v, Gs, k=kk),
                                make_interp_spline(v, q, k=kk)))
            self._tables = out
        return self._tables

    def _eval(self, x, which):
        x = np.abs(np.asarray(x, float))
        out = np.zeros(x.shape)
        idx = self._seg_index(x)
        for i, seg in enumerate(self.tables()):
            sel = idx == i
            if sel.any():
                out[sel] = getattr(seg, which)(seg.var(x[sel]))
        return out

    def g(self, x):
        x = np.abs(np.asarray(x, float))
        return self._eval(x, "G") + self._kink_terms(x, 0)

    def gprime(self, x):
        x = np.abs(np.asarray(x, float))
        return self._eval(x, "q") + self._kink_terms(x, 1)

    def pressure(self, r, a, E_star, m, other=None):
        """(5.59): p(r) = (E*/pi) integral_r^a g'(x) / sqrt(x^2 - r^2) dx for 0 <= r < a: the
        kink terms exactly (incomplete elliptic integrals), the smooth part q by Gauss-Legendre
        per segment: x = r + w^2 on the segment holding r (removes the Abel kernel's
        1/sqrt(x - r)), x = b_j + t^2 on the later ones (the table's variable).

        With ``other`` (another representation of the same profile) also returns
        (E*/pi) integral_r^a |q - q_other| / sqrt(x^2 - r^2) dx on the same nodes: the
        difference of the two tables without the cancellations of the signed difference."""
        out = np.zeros(r.shape)
        dev = np.zeros(r.shape)
        otabs = other.tables() if other is not None else None
        b, s = self.kinks()
        for bj, sj in zip(b, s, strict=True):
            if bj < a and sj != 0:  # (a zero jump: k = 1 splines through collinear samples)
                out += gen.mdr_kink_pressure(E_star, a, bj, r, sj)  # (5.59)
        tabs = self.tables()
        idx = self._seg_index(r)
        smooth = np.zeros(r.shape)
        for i, seg in enumerate(tabs):
            if seg.lo >= a:
                break
            top = min(seg.hi, a)
            # the segment that holds r: x = r + w^2, dx / sqrt(x^2 - r^2) = 2 dw / sqrt(x + r)
            sel = np.flatnonzero(idx == i)
            if len(sel):
                rr = r[sel]
                W = np.sqrt(top - rr)
                xk = _subsample(seg.lo + seg.nodes**2 if seg.in_t else seg.nodes, 16)
                with np.errstate(invalid="ignore"):
                    wk = np.sqrt(np.clip(xk[None, :] - rr[:, None], 0, None))
                # grade towards w = 0 down to the scale of the nearest singularity: the
                # kernel's at w^2 = -2r, and past a kink q's sqrt(x - lo) at w^2 = lo - r
                sig = np.sqrt(2 * rr)
                if seg.in_t:
                    sig = np.minimum(sig, np.sqrt(rr - seg.lo))
                with np.errstate(divide="ignore"):
                    lev = np.clip(np.ceil(np.log2(W / np.maximum(sig, 1e-300 * W))) + 2, 3, 30)
                grade = _graded(np.zeros(len(rr)), W)
                grade[np.arange(30)[None, :] >= lev[:, None]] = 0.0
                wn, ww = _panels(np.zeros(len(rr)), W, np.concatenate([wk, grade], axis=1), m)
                live = ww > 0
                rl = np.broadcast_to(rr[:, None], wn.shape)[live]
                wl = wn[live]
                if seg.in_t:
                    qv = seg.q(np.sqrt((rl - seg.lo) + wl * wl))
                else:
                    qv = seg.q(rl + wl * wl)
                if i == 0 and (rr == 0).any():
                    # p(0) = (E*/pi) integral q(x)/x dx: a smooth tip has f'(0) = 0, so q(0) =
                    # pi f'(0)/2 = 0 (the spline's q(0) is its interpolation error, whose log
                    # divergence is not the profile's); a conical tip has p(0) = inf (Solution)
                    qv = qv - np.where(rl == 0, seg.q(np.zeros(1))[0], 0.0)
                vals = np.zeros(wn.shape)
                vals[live] = 2 * qv / np.sqrt(2 * rl + wl * wl)
                smooth[sel] += np.sum(ww * vals, axis=1)
                if otabs is not None:
                    o = otabs[i]
                    qo = o.q(np.sqrt((rl - seg.lo) + wl * wl) if seg.in_t else rl + wl * wl)
                    if i == 0 and (rr == 0).any():
                        qo = qo - np.where(rl == 0, o.q(np.zeros(1))[0], 0.0)
                    vals[live] = 2 * np.abs(qv - qo) / np.sqrt(2 * rl + wl * wl)
                    dev[sel] += np.sum(ww * vals, axis=1)
            # the later segments [lo, top] with r < lo: x = lo + t^2, dx = 2 t dt; the nodes
            # in t are the same for every r (graded towards t = 0 for r -> lo), q once
            sel = np.flatnonzero(idx < i)
            if len(sel) and seg.in_t:
                rr = r[sel]
                T = np.array([np.sqrt(top - seg.lo)])
                br = np.concatenate([_subsample(seg.nodes, 64)[None, :], _graded(np.zeros(1), T)],
                                    axis=1)
                tn, tw = _panels(np.zeros(1), T, br, m)
                tn, tw = tn[:, tw[0] > 0], tw[:, tw[0] > 0]
                qv = seg.q(tn[0])[None, :]
                xmr = (seg.lo - rr[:, None]) + tn * tn
                xx = seg.lo + tn * tn
                kern = tw * 2 * tn / np.sqrt(xmr * (xx + rr[:, None]))
                smooth[sel] += np.sum(kern * qv, axis=1)
                if otabs is not None:
                    dev[sel] += np.sum(kern * np.abs(qv - otabs[i].q(tn[0])[None, :]), axis=1)
        if other is not None:
            return out + E_star / np.pi * smooth, E_star / np.pi * dev
        return out + E_star / np.pi * smooth


def _build_rep(r, f, breakpoints, k, smoothing, m_theta) -> _Rep:
    from scipy.interpolate import make_interp_spline, make_smoothing_spline

    edges = np.concatenate([[0.0], breakpoints, [r[-1]]])
    segments = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        sel = (r >= lo - 1e-15 * hi) & (r <= hi * (1 + 1e-15))
        rs, fs = r[sel], f[sel]
        kk = min(k, len(rs) - 1)
        if kk < 1:
            raise ValueError(f"segment [{lo}, {hi}] has {len(rs)} sample(s); need >= 2")
        if smoothing is not None:
            lam = None if smoothing == "gcv" else float(smoothing)
            segments.append(make_smoothing_spline(rs, fs, lam=lam))
        else:
            segments.append(make_interp_spline(rs, fs, k=kk))
    return _Rep(segments, edges, m_theta, np.asarray(r, float), k if smoothing is None else 3)


_EPS = np.finfo(float).eps
# Gauss-Legendre points a panel of the (coarse, fine) quadratures, in the order a sampled
# profile refines them when the error estimate misses rtol (its splines cannot be refined)
_QUADRATURE_LEVELS = ((6, 8), (10, 12), (14, 16))


def _check_rtol(rtol) -> float:
    """rtol [1] within RTOL_RANGE (None: DEFAULT_RTOL)."""
    if rtol is None:
        return DEFAULT_RTOL
    lo, hi = RTOL_RANGE
    try:
        value = float(rtol)
    except (TypeError, ValueError):
        value = np.nan
    if not lo <= value <= hi:  # NaN included
        raise ValueError(f"rtol = {rtol!r} is out of range; valid: {lo:g} <= rtol <= {hi:g} "
                         "(what the numerical MDR can deliver: mdr.RTOL_RANGE)")
    return value


def _deviation(fine: _Rep, coarse: _Rep, a: float) -> tuple[float, float]:
    """The largest |g_fine - g_coarse| [m] and |G_fine - G_coarse| [m^2] (G = integral_0^x g)
    on 9 radii x within two coarse sample spacings of a (and below r_max).

    The signed differences at a alone can vanish by accident (the coarse error passing
    through 0 at that radius while both are in error); their envelope over the radii around
    a cannot. (Integrating |f'_fine - f'_coarse| instead would not do: the interpolating
    splines' f' errors cancel over every interval between samples, where both splines match
    f, by construction, and their absolute values overstate the error a thousandfold.)"""
    kn = coarse.knots
    i = int(np.clip(np.searchsorted(kn, a), 1, len(kn) - 1))
    h = kn[i] - kn[i - 1]
    x = np.clip(a + h * np.linspace(-2, 2, 9), a / 2, kn[-1])
    gf, _, Gf = fine.direct(x, with_G=True)
    gc, _, Gc = coarse.direct(x, with_G=True)
    return float(np.max(np.abs(gf - gc))), float(np.max(np.abs(Gf - Gc)))


@dataclass
class Solution:
    """The MDR solution at one depth. Lengths in m, force in N, pressure in Pa.

    Attributes
    ----------
    depth, contact_radius, force : float
        d, a (5.55) and F (5.57).
    E_star : float
        Effective modulus [Pa].
    rel_error : float
        A bound of the relative error of ``depth``, ``contact_radius`` and ``force`` (the
        largest of the three; see the module docstring for how it is made).
    rtol : float
        The target the solve refined towards [1], within ``RTOL_RANGE``.
    met : bool
        ``rel_error <= rtol``.
    why_not_met : str or None
        Why the target was not reached (None when ``met``): the resolution that could not be
        refined further and its estimate.
    """

    depth: float
    contact_radius: float
    force: float
    E_star: float
    rel_error: float
    rtol: float
    met: bool
    why_not_met: str | None
    _rep: _Rep = field(repr=False)
    _coarse: _Rep = field(repr=False)
    _a_coarse: float = field(repr=False)
    def g(self, x):
        """MDR profile g(x) [m] (5.52) at |x| [m]."""
        x = nonnegative("x", np.abs(as_float("x", x)))
        return result(self._rep.g(x.ravel()).reshape(x.shape))

    def _pressure(self, rep, r, m, a=None, other=None):
        a, E = (self.contact_radius if a is None else a), self.E_star
        out, dev = np.zeros(r.shape), np.zeros(r.shape)
        ins = r < a
        if ins.any():
            if other is None:
                out[ins] = rep.pressure(r[ins], a, E, m)
            else:
                out[ins], dev[ins] = rep.pressure(r[ins], a, E, m, other)
        if (r == 0).any() and self._conical_tip():
            out[r == 0] = np.inf  # p(0) = (E*/pi) integral_0^a g'(x)/x dx, g'(0) = pi f'(0)/2
        return out if other is None else (out, dev)

    def _conical_tip(self):
        """Whether f'(0) > 0 (then p is log-infinite at r = 0): the fine spline's slope at 0 is
        above rounding and the coarse one agrees with it to 10 % (a smooth tip's splines have
        f'(0) of the order of their interpolation error, which changes with the resolution)."""
        f0, fa = self._rep.fprime(np.array([0.0, self.contact_radius]))
        f0c = self._coarse.fprime(np.array([0.0]))[0]
        return f0 > 1e3 * np.finfo(float).eps * abs(fa) and abs(f0 - f0c) <= 0.1 * f0

    def pressure(self, r, *, return_error=False):
        """Contact pressure p(r) [Pa] (5.59) at r [m] (0 outside the contact).

        +inf at a kink r = b < a (a log singularity, (5.59) of b s / sqrt(x^2 - b^2)) and at
        r = 0 under a conical tip. With ``return_error=True`` also returns the estimated
        absolute error per point [Pa]: coarse-vs-fine difference, the Abel integral of the
        tables' difference and a rounding bound (module docstring); it bounds the error of
        the returned pressure, conservatively (tests/test_mdr.py checks it near kinks too).
        """
        r = nonnegative("r", r)
        flat = r.ravel()
        if not return_error:
            return result(self._pressure(self._rep, flat, 6).reshape(r.shape))
        # coarse: the half-resolution profile, its own contact radius, fewer Gauss points;
        # dev: the same integral of |q - q_coarse| (the signed difference may pass through 0
        # at some r while both are in error)
        p, dev = self._pressure(self._rep, flat, 6, other=self._coarse)
        pc = self._pressure(self._coarse, flat, 4, self._a_coarse)
        with np.errstate(invalid="ignore"):  # inf - inf at a conical tip's r = 0
            err = np.abs(p - pc) + dev + self._rounding(flat, p)
        err[np.isinf(p)] = np.inf
        return result(p.reshape(r.shape)), result(err.reshape(r.shape))

    def _rounding(self, r, p):
        """A bound of the rounding errors that the coarse-vs-fine difference cannot see:
        (64 + 4 N) eps |p| (N samples: differentiating the spline loses about log10(N)
        digits), amplified by a/(a - r) near the edge (the rounding of a enters p ~
        sqrt(a - r) there), and for each kink term the rounding of its parameter
        m = (S/L)^2 near 1: 4 eps E* |s| b / (pi L) * (1 + L^2/|L^2 - S^2|)."""
        eps = np.finfo(float).eps
        a = self.contact_radius
        out = np.zeros(r.shape)
        ins = r < a
        n = len(self._rep.knots)
        out[ins] = (64 + 4 * n) * eps * np.abs(p[ins]) * (1 + a / (a - r[ins]))
        b, s = self._rep.kinks()
        for bj, sj in zip(b, s, strict=True):
            L, S = np.maximum(r, bj), np.minimum(r, bj)
            sel = ins & (L < a) & (L > S)
            out[sel] += (4 * eps * self.E_star * abs(sj) * bj / (np.pi * L[sel])
                         * (1 + L[sel] ** 2 / ((L[sel] - S[sel]) * (L[sel] + S[sel]))))
        return out

    def displacement(self, r):
        """Surface displacement u_z(r) [m], inside and outside the contact (5.60)."""
        r = nonnegative("r", r)
        flat = r.ravel()
        a, d = self.contact_radius, self.depth
        th_max = np.arcsin(np.clip(np.divide(a, flat, out=np.full(flat.shape, 2.0),
                                             where=flat > 0), 0, 1))
        with np.errstate(divide="ignore", invalid="ignore"):
            kt = np.arcsin(np.clip(np.where(flat[:, None] > 0, self._rep._panel_knots()[None, :]
                                            / flat[:, None], 2.0), 0, 1))
        br = np.concatenate([kt, _graded(np.zeros(len(flat)), th_max)], axis=1)
        th, w = _panels(np.zeros(len(flat)), th_max, br, 6)
        gx = self._rep.g((flat[:, None] * np.sin(th)).ravel()).reshape(th.shape)
        u = 2 / np.pi * np.sum(w * (d - gx), axis=1)
        u[flat == 0] = d
        return result(u.reshape(r.shape))



@dataclass
class ForceDepthCurve:
    """F(d) [N], a(d) [m] at the given depths [m], each with its error bound and target.

    ``rel_error[i]`` bounds the relative error of ``force[i]`` and ``contact_radius[i]``;
    ``met[i]`` is ``rel_error[i] <= rtol`` and ``why_not_met[i]`` says why not (else None).
    """

    depth: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    rel_error: np.ndarray
    rtol: float
    met: np.ndarray
    why_not_met: list[str | None]


class _Samples:
    """The representations of a sampled profile: all samples (fine) and every other one
    (coarse), at increasing quadrature resolution (the splines cannot be refined)."""

    def __init__(self, coarse: _Rep, fine: _Rep):
        self._base = (coarse, fine)
        self._levels: dict[int, tuple[_Rep, _Rep]] = {}

    def pair(self, level: int) -> tuple[_Rep, _Rep] | None:
        if level >= len(_QUADRATURE_LEVELS):
            return None
        if level not in self._levels:
            mc, mf = _QUADRATURE_LEVELS[level]
            c, f = self._base
            self._levels[level] = (c if c.m_theta == mc else c.with_quadrature(mc),
                                   f if f.m_theta == mf else f.with_quadrature(mf))
        return self._levels[level]

    def why_not(self, err: float, level: int) -> str:
        n = len(self._base[1].knots)
        return (f"a sampled profile cannot be refined past its {n} samples; its estimate is "
                f"{err:.1e} with {_QUADRATURE_LEVELS[level][1]} Gauss points a panel")


class _Grid:
    """The representations of a callable profile on grids of m and 2m intervals a segment,
    m = n, 2n, 4n, ... while 2m <= n_max (built on first use, kept)."""

    def __init__(self, f, r_max: float, breakpoints: np.ndarray, n: int, k: int, n_max: int):
        self._f, self._bp, self._n, self._k, self._n_max = f, breakpoints, n, k, n_max
        self._edges = np.concatenate([[0.0], breakpoints, [r_max]])
        self._reps: dict[int, _Rep] = {}
        self._coarse: dict[int, _Rep] = {}  # the same grids as the coarse of a pair

    def rep(self, m: int) -> _Rep:
        if m not in self._reps:
            parts = [np.linspace(lo, hi, m + 1)[:-1]
                     for lo, hi in zip(self._edges[:-1], self._edges[1:], strict=True)]
            rr = np.concatenate(parts + [self._edges[-1:]])
            ff = np.asarray(self._f(rr), float)
            if ff.shape != rr.shape or not np.all(np.isfinite(ff)):
                raise ValueError("f returned a non-finite value (or the wrong shape) on "
                                 "[0, r_max]; valid: finite values, one per radius")
            self._reps[m] = _build_rep(rr, ff - ff[0], self._bp, self._k, None, 8)
        return self._reps[m]

    def pair(self, level: int) -> tuple[_Rep, _Rep] | None:
        m = self._n * 2**level
        if level > 0 and 2 * m > self._n_max:
            return None
        if m not in self._coarse:  # the coarse one of a pair: coarser tables too
            fine = self.rep(m)
            self._coarse[m] = fine.with_quadrature(fine.m_theta, fine.table_nodes // 2)
        return self._coarse[m], self.rep(2 * m)

    def why_not(self, err: float, level: int) -> str:
        m = 2 * self._n * 2**level
        return (f"the callable's grid reached {m} intervals a segment (n_max = {self._n_max}); "
                f"its estimate is {err:.1e}")


class Profile:
    """An axisymmetric gap profile f(r) [m], f(0) = 0, non-decreasing, for the numerical MDR.

    Build it with :meth:`from_samples` or :meth:`from_callable`; then :meth:`solve` at a depth
    or force, or :meth:`force_depth_curve`.
    """

    def __init__(self, source: _Samples | _Grid, r_max: float, description: str):
        self._source = source
        self.r_max = r_max
        self.source = description

    # -- construction -----------------------------------------------------------------------
    @classmethod
    def from_samples(cls, r: Sequence[float], f: Sequence[float], *,
                     breakpoints: Sequence[float] = (), k: int = 5,
                     smoothing: float | str | None = None) -> Profile:
        """Profile from samples (r_i [m], f_i [m]), e.g. a measured AFM or indenter tip.

        Parameters
        ----------
        r, f : array_like
            Strictly increasing radii from r_0 = 0 and the gap f(r_i); f(0) is subtracted.
        breakpoints : sequence of float
            Radii [m] where f has a kink (e.g. the edge of a worn tip); they must be among
            the samples. The spline is not continued across them.
        k : int
            Spline degree (5: quintic, for smooth profiles; 3 or 1 for rough ones).
        smoothing : None, float or "gcv"
            Fit a cubic smoothing spline instead of interpolating: for noisy samples. "gcv"
            chooses the smoothing by generalized cross-validation. The error bounds are then
            those of the MDR of the fitted spline, not of the noise.
        """
        r = nonnegative("r", r)
        f = as_float("f", f)
        if r.ndim != 1 or r.shape != f.shape or len(r) < 4:
            raise ValueError(f"r and f must be 1-D of equal length >= 4; got {r.shape}, "
                             f"{f.shape}")
        if r[0] != 0 or np.any(np.diff(r) <= 0):
            raise ValueError("r must start at 0 and increase strictly")
        bp = np.asarray(sorted(breakpoints), float)
        if np.any((bp <= 0) | (bp >= r[-1])) or not np.all(np.isin(bp, r)):
            raise ValueError(f"breakpoints {list(bp)} must be samples strictly inside "
                             f"(0, {r[-1]})")
        f = f - f[0]
        if not np.isin(k, (1, 3, 5)):
            raise ValueError(f"k = {k} is out of range; valid: 1, 3, 5")
        # the coarse representation: every other sample, keeping 0, the breakpoints and r_max
        keep = np.zeros(len(r), bool)
        keep[::2] = True
        keep[-1] = True
        keep |= np.isin(r, bp)
        coarse = _build_rep(r[keep], f[keep], bp, k, smoothing, 6)
        fine = _build_rep(r, f, bp, k, smoothing, 8)
        coarse.table_nodes = fine.table_nodes // 2  # the coarse one: coarser tables too
        return cls(_Samples(coarse, fine), float(r[-1]), f"{len(r)} samples")

    @classmethod
    def from_callable(cls, f: Callable[[np.ndarray], np.ndarray], r_max: float, *,
                      breakpoints: Sequence[float] = (), n: int = 64, k: int = 5,
                      n_max: int = 8192) -> Profile:
        """Profile from a vectorized callable f(r) [m] on [0, r_max] [m].

        Each :meth:`solve` samples the callable on grids of n, 2n, 4n, ... intervals per
        segment (up to ``n_max``; each grid is kept for later solves) until the error
        estimate meets its ``rtol``; ``breakpoints`` are radii [m] of kinks.
        """
        r_max = float(positive("r_max", r_max))
        bp = np.asarray(sorted(breakpoints), float)
        if np.any((bp <= 0) | (bp >= r_max)):
            raise ValueError(f"breakpoints {list(bp)} must lie in (0, {r_max})")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= n_max:
            raise ValueError(f"n = {n!r} is out of range; valid: an integer 4 <= n <= n_max = "
                             f"{n_max}")
        grid = _Grid(f, r_max, bp, int(n), k, int(n_max))
        grid.pair(0)  # sample now: a callable that fails should fail here
        return cls(grid, r_max, f"callable, {n} to {n_max} intervals a segment")

    # -- evaluation ------------------------------------------------------------------------
    def g(self, x):
        """MDR profile g(x) [m] (5.52) (of the finest representation a first solve uses)."""
        x = np.abs(as_float("x", x))
        return result(self._source.pair(0)[1].g(x.ravel()).reshape(x.shape))

    def _radius(self, rep: _Rep, d: float, guess: float | None = None) -> float:
        """Solve g(a) = d (5.55) by safeguarded Newton on g and g' by quadrature (no tables):
        bracket on 16 radii (one vectorized quadrature) unless a guess is given."""
        lo, hi = 0.0, self.r_max
        g_hi = rep.g_direct(np.array([hi]))[0]
        if g_hi < d:
            raise ValueError(f"depth {d} exceeds g(r_max) = {g_hi}: the profile is too short "
                             "for this depth")
        if guess is None:
            xs = np.linspace(0, hi, 17)[1:]
            gs = rep.g_direct(xs)
            i = int(np.searchsorted(gs, d))
            lo, hi = (xs[i - 1] if i > 0 else 0.0), xs[min(i, len(xs) - 1)]
            g_lo = gs[i - 1] if i > 0 else 0.0
            g_hi = gs[min(i, len(xs) - 1)]
            # secant start inside the bracket
            a = lo + (hi - lo) * (d - g_lo) / (g_hi - g_lo) if g_hi > g_lo else (lo + hi) / 2
        else:
            a = guess
        for _ in range(100):
            gg, gp = rep.g_and_gprime_direct(np.array([a]))
            ga, gp = gg[0] - d, gp[0]
            if ga == 0:
                return a
            if ga > 0:
                hi = a
            else:
                lo = a
            step = ga / gp if gp > 0 else np.inf
            if abs(step) <= 2e-16 * a:  # quadratic convergence: this step is the last
                return a - step
            a_new = a - step
            if not (lo <= a_new <= hi):
                a_new = (lo + hi) / 2
            if hi - lo <= 4e-16 * hi:
                return a_new
            a = a_new
        return a

    @staticmethod
    def _force(rep: _Rep, a: float, d: float, E_star: float) -> float:
        return float(gen.mdr_force(E_star, a, d, rep.G(np.array([a]))[0]))  # (5.57)

    def _force_of_radius(self, rep, a, E_star):
        return self._force(rep, a, rep.g_direct(np.array([a]))[0], E_star)

    def _solve_pair(self, coarse: _Rep, fine: _Rep, depth, force, E_star):
        """(d, a, F) on the fine representation and the bound of its relative error."""
        from scipy.optimize import brentq

        out = []
        for rep in (fine, coarse):
            if depth is not None:
                d = depth
                a = self._radius(rep, d, out[0][1] if out else None)
            else:
                Fmax = self._force_of_radius(rep, self.r_max, E_star)
                if force > Fmax:
                    raise ValueError(f"force = {force} exceeds F(r_max) = {Fmax}")
                a = brentq(lambda aa, rp=rep: self._force_of_radius(rp, aa, E_star) - force,
                           0.0, self.r_max, xtol=1e-16 * self.r_max, rtol=1e-15)
                d = float(rep.g_direct(np.array([a]))[0])
            out.append((d, a, self._force(rep, a, d, E_star)))
        (d, a, F), (dc, ac, Fc) = out
        # 1. coarse vs fine: the error of the coarse solution, conservative for the fine one
        diff = max(abs(F - Fc) / F, abs(a - ac) / a, abs(d - dc) / d)
        # 2. the same without an accidental cancellation at a: the envelope of the differences
        # of g and G around a (_deviation), put through the linearized (5.55) and (5.57): F
        # is stationary in a at a fixed d (dF/da = 2 E* (d - g(a)) = 0), so at a given depth
        # dF = -2 E* dG and da = dg/g'(a); at a given force F(a) = 2 E* (a g(a) - G(a)) with
        # dF/da = 2 E* a g'(a), and dd = g' da + dg
        Dg, DG = _deviation(fine, coarse, a)
        slope = a * float(fine.gprime_direct(np.array([a]))[0])  # a g'(a) [m]
        if depth is not None:
            dev = max(Dg / slope if slope > 0 else np.inf, 2 * E_star * DG / F)
        else:
            da = (a * Dg + DG) / (a * slope) if slope > 0 else np.inf
            dev = max(da, (slope * da + Dg) / d)
        # 3. rounding: f' of a spline through N samples loses about log10(N) digits
        floor = (64 + 4 * len(fine.knots)) * _EPS
        return d, a, F, ac, max(diff, dev) + floor

    def solve(self, *, depth: float | None = None, force: float | None = None,
              E_star: float, rtol: float | None = None) -> Solution:
        """Solve the contact at a given ``depth`` [m] or normal ``force`` [N].

        Parameters
        ----------
        depth, force : float
            Exactly one of them, > 0.
        E_star : float
            Effective modulus [Pa] (5.26), > 0.
        rtol : float, optional
            Target of the relative error bound of force, contact radius and depth [1], in
            ``RTOL_RANGE`` (default ``DEFAULT_RTOL``). A callable profile's grid is doubled,
            a sampled profile's quadrature refined, until the bound meets it; the solution
            says whether it did (``met``) and, if not, why (``why_not_met``).

        Returns
        -------
        Solution
        """
        rtol = _check_rtol(rtol)
        E_star = float(positive("E_star", E_star))
        if (depth is None) == (force is None):
            raise ValueError("give exactly one of depth= and force=")
        if depth is not None:
            depth = float(positive("depth", depth))
        else:
            force = float(positive("force", force))
        level, best = 0, None
        while True:
            pair = self._source.pair(level)
            if pair is None:
                break
            *res, err = self._solve_pair(*pair, depth, force, E_star)
            if best is not None and isinstance(self._source, _Samples) and err > best[-1] / 2:
                break  # the quadrature is not what limits a sampled profile: keep the last
            best = (pair, level, *res, err)
            if err <= rtol:
                break
            level += 1
        (coarse, fine), lvl, d, a, F, ac, err = best
        met = err <= rtol
        return Solution(depth=d, contact_radius=a, force=F, E_star=E_star, rel_error=err,
                        rtol=rtol, met=met, why_not_met=None if met else
                        self._source.why_not(err, lvl), _rep=fine, _coarse=coarse,
                        _a_coarse=ac)

    def force_depth_curve(self, depths, *, E_star: float,
                          rtol: float | None = None) -> ForceDepthCurve:
        """F(d) [N] and a(d) [m] at each depth [m] of ``depths`` (monotone in d), each solved
        as :meth:`solve` with the target ``rtol`` [1] (default ``DEFAULT_RTOL``)."""
        rtol = _check_rtol(rtol)
        depths = positive("depths", depths).ravel()
        sols = [self.solve(depth=float(dd), E_star=E_star, rtol=rtol) for dd in depths]
        return ForceDepthCurve(depths, np.array([s.force for s in sols]),
                               np.array([s.contact_radius for s in sols]),
                               np.array([s.rel_error for s in sols]), rtol,
                               np.array([s.met for s in sols]),
                               [s.why_not_met for s in sols])
