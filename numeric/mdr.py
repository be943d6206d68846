"""Numerical MDR (5.51)-(5.61) for any axisymmetric gap profile: a callable or samples.

Usage::

    from hertzmdr.numeric import mdr
    prof = mdr.Profile.from_samples(r_i, f_i)            # or Profile.from_callable(f, r_max)
    res = prof.solve(depth=1e-6, E_star=1e11)            # or force=..., rtol=...
    res.contact_radius, res.force, res.rel_error
    res.pressure(r), res.displacement(r), res.g(x)
    curve = prof.force_depth_curve(depths, E_star=1e11)  # F(d), a(d), rel_error per depth

Method (all lengths in m, pressures in Pa, forces in N):

- The profile f is represented by interpolating splines of degree ``k`` (5 by default: f' and
  f'' are then accurate to O(h^5), O(h^4) for a smooth profile sampled with spacing h), one per
  segment between user ``breakpoints`` (kinks such as the edge of a worn tip).
- (5.52) with r = x sin(theta): g(x) = x * integral_0^(pi/2) f'(x sin theta) dtheta, and
  g'(x) = integral_0^(pi/2) h(x sin theta) dtheta with h(u) = (u f'(u))' -- no endpoint
  singularity is left; Gauss-Legendre in theta, split at the images of the breakpoints.
- (5.55) g(a) = d by a safeguarded Newton iteration (g' is known); force control solves
  F(a) = F by bracketing and Brent's method on the monotone F(a) = 2 E* integral_0^a x g'(x) dx.
- (5.57) F = 2 E* (d a - integral_0^a g),
  integral_0^a g = a^2 integral_0^(pi/2) f'(a sin t) cos^2 t dt.
- (5.59) with x = r cosh(tau): p(r) = (E*/pi) integral_0^(acosh(a/r)) g'(r cosh tau) dtau,
  p(0) = (E*/pi) integral_0^a g'(x)/x dx.
- Every quadrature is composite Gauss-Legendre with panels broken at the images of the sample
  radii (the spline's pieces) and graded geometrically towards the ends, so that profiles like
  r^1.5 (f'' singular at 0) and kinks at breakpoints keep the order of the interpolation.
- (5.60) with x = r sin(theta): u(r) = (2/pi) integral_0^(asin(min(1, a/r))) (d - g(r sin theta)).
- Error estimate: every result is computed twice, with the full resolution and with every other
  sample (samples) or half the grid (callables) and half the quadrature points; ``rel_error`` is
  their relative difference, an upper estimate of the error of the coarse solution (so a
  conservative estimate for the returned, fine one). For callables the grid is doubled until
  ``rel_error <= rtol``; for samples the resolution is what was measured, and ``converged``
  says whether ``rtol`` was met.

Measured convergence orders are in ``docs/mdr.md`` (``benchmarks/bench_mdr.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric._validate import as_float, nonnegative, positive, result

__all__ = ["Profile", "Solution", "ForceDepthCurve"]

_GL_CACHE: dict[int, tuple[np.ndarray, np.ndarray]] = {}


def _gauss(m: int) -> tuple[np.ndarray, np.ndarray]:
    if m not in _GL_CACHE:
        _GL_CACHE[m] = np.polynomial.legendre.leggauss(m)
    return _GL_CACHE[m]


def _panels(lo, hi, breaks, m):
    """Composite Gauss-Legendre nodes/weights on [lo, hi] (arrays, shape (M,)), split at the
    sorted ``breaks`` (shape (M, B), values outside [lo, hi] clipped). Returns (M, P*m)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    edges = np.concatenate([lo[:, None], np.clip(breaks, lo[:, None], hi[:, None]),
                            hi[:, None]], axis=1)
    edges = np.sort(edges, axis=1)
    t, w = _gauss(m)
    left, right = edges[:, :-1], edges[:, 1:]
    half = (right - left) / 2
    nodes = (left + half)[:, :, None] + half[:, :, None] * t
    weights = half[:, :, None] * w
    return nodes.reshape(len(lo), -1), weights.reshape(len(lo), -1)


_GRADE = 0.5 ** np.arange(1, 31)  # geometric grading towards an endpoint: 2^-1 ... 2^-30


def _graded(lo, hi, toward_lo=True):
    """Break points grading [lo, hi] geometrically towards lo (or hi): shape (M, 30)."""
    lo, hi = np.asarray(lo, float)[:, None], np.asarray(hi, float)[:, None]
    return lo + (hi - lo) * _GRADE if toward_lo else hi - (hi - lo) * _GRADE


@dataclass
class _Rep:
    """A piecewise spline representation of f at one resolution, and its MDR tables."""

    segments: list  # scipy BSplines, one per segment
    edges: np.ndarray  # segment edges, edges[0] = 0, edges[-1] = r_max
    m_theta: int  # Gauss points per panel
    knots: np.ndarray  # the sample radii: the spline's pieces
    k: int = 5
    _table: tuple | None = field(default=None, repr=False)

    def deriv(self, u: np.ndarray, nu: int) -> np.ndarray:
        u = np.asarray(u, float)
        out = np.zeros(u.shape)
        idx = np.clip(np.searchsorted(self.edges, u, side="right") - 1, 0, len(self.segments) - 1)
        for i, spl in enumerate(self.segments):
            sel = idx == i
            if sel.any():
                out[sel] = spl(u[sel], nu=nu)
        return out

    def fprime(self, u):
        return self.deriv(u, 1)

    def h(self, u):  # (u f')' = f' + u f''
        return self.deriv(u, 1) + u * self.deriv(u, 2)

    def _panel_knots(self):
        """Knots used as panel breaks: all of them for k = 1 (f' jumps there), every few for
        the smoother splines (at most 64 panels), always the segment edges."""
        inner = self.knots[1:-1]
        step = 1 if self.k == 1 else max(1, len(inner) // 64)
        return np.union1d(inner[::step], self.edges[1:-1])

    def _theta_breaks(self, x):
        """Panel breaks in theta for r = x sin(theta): the images of the knots and a geometric
        grading towards theta = 0 (for f' ~ r^alpha at the centre)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(x[:, None] > 0, self._panel_knots()[None, :] / x[:, None], 2.0)
        th = np.arcsin(np.clip(s, 0, 1))
        return np.concatenate([th, _graded(np.zeros(len(x)), np.full(len(x), np.pi / 2))],
                              axis=1)

    def _theta_quad(self, x, fn, weight=None):
        x = np.atleast_1d(np.abs(np.asarray(x, float)))
        th, w = _panels(np.zeros(len(x)), np.full(len(x), np.pi / 2),
                        self._theta_breaks(x), self.m_theta)
        vals = fn((x[:, None] * np.sin(th)).ravel()).reshape(th.shape)
        if weight is not None:
            vals = vals * weight(th)
        return x, np.sum(w * vals, axis=1)

    def g_direct(self, x):
        """(5.52): g(x) = x * integral_0^(pi/2) f'(x sin theta) dtheta."""
        x, q = self._theta_quad(x, self.fprime)
        return x * q

    def _jumps(self):
        """Radii u_j where f' jumps (segment edges; every knot for k = 1) and u_j [f'](u_j)."""
        u = self.knots[1:-1] if self.k == 1 else self.edges[1:-1]
        if len(u) == 0:
            return u, u
        eps = 1e-12 * self.edges[-1]
        jump = self.fprime(u + eps) - self.fprime(u - eps)
        if self.k != 1:  # exact one-sided values of the segment splines
            jump = np.array([self.segments[i + 1](uu, nu=1) - self.segments[i](uu, nu=1)
                             for i, uu in enumerate(u)])
        return u, u * jump

    def gprime_direct(self, x):
        """g'(x) = integral_0^(pi/2) h(x sin theta) dtheta, h = (u f')', plus the delta terms
        of h where f' jumps: sum_j u_j [f'](u_j) / sqrt(x^2 - u_j^2) for u_j < x."""
        x, q = self._theta_quad(x, self.h)
        u, uj = self._jumps()
        if len(u):
            with np.errstate(divide="ignore", invalid="ignore"):
                dx = (x[:, None] - u[None, :]) * (x[:, None] + u[None, :])
                q = q + np.sum(np.where(dx > 0, uj[None, :] / np.sqrt(np.where(dx > 0, dx, 1)),
                                        0.0), axis=1)
        return q

    def G(self, a):
        """integral_0^a g dx = a^2 integral_0^(pi/2) f'(a sin t) cos^2 t dt."""
        a, q = self._theta_quad(a, self.fprime, lambda th: np.cos(th) ** 2)
        return a**2 * q

    # -- tables: g and g' on the knots (graded towards 0 and the breakpoints) ----------------
    def table(self):
        """Cubic Hermite interpolant of g (from g, g') and cubic splines of g' per segment."""
        if self._table is None:
            from scipy.interpolate import CubicHermiteSpline, make_interp_spline

            parts = []
            for lo, hi in zip(self.edges[:-1], self.edges[1:], strict=True):
                kn = self.knots[(self.knots > lo) & (self.knots < hi)]
                # grade towards the centre and towards kinks (not towards r_max): 10 levels
                # keep the spline of g' well conditioned (spacing ratios <= 2^10)
                grade = lo + (hi - lo) * _GRADE[:10]
                if hi < self.edges[-1]:
                    grade = np.concatenate([grade, hi - (hi - lo) * _GRADE[:10]])
                parts.append(np.unique(np.concatenate([[lo, hi], kn, grade])))
            X = np.unique(np.concatenate(parts))
            gX, gpX = self.g_direct(X), self.gprime_direct(X)
            hermite = CubicHermiteSpline(X, gX, gpX)
            gp_spl = []
            for part in parts:
                sel = np.isin(X, part)
                xs, ys = X[sel], gpX[sel]
                gp_spl.append(make_interp_spline(xs, ys, k=min(3, len(xs) - 1)))
            self._table = (hermite, gp_spl)
        return self._table

    def g(self, x):
        x = np.abs(np.asarray(x, float))
        return self.table()[0](x)

    def gprime(self, x):
        x = np.abs(np.asarray(x, float))
        out = np.zeros(x.shape)
        idx = np.clip(np.searchsorted(self.edges, x, side="right") - 1, 0, len(self.edges) - 2)
        for i, spl in enumerate(self.table()[1]):
            sel = idx == i
            if sel.any():
                out[sel] = spl(x[sel])
        return out


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
        Estimated relative error of ``force`` and ``contact_radius`` (the larger).
    converged : bool
        ``rel_error <= rtol``.
    """

    depth: float
    contact_radius: float
    force: float
    E_star: float
    rel_error: float
    converged: bool
    rtol: float
    _rep: _Rep = field(repr=False)
    _coarse: _Rep = field(repr=False)

    def g(self, x):
        """MDR profile g(x) [m] (5.52) at |x| [m]."""
        x = nonnegative("x", np.abs(as_float("x", x)))
        return result(self._rep.g(x.ravel()).reshape(x.shape))

    def _pressure(self, rep, r, m_tau):
        a, E = self.contact_radius, self.E_star
        out = np.zeros(r.shape)
        ins = (r < a) & (r > 0)
        if ins.any():
            ri = r[ins]
            tau_max = np.arccosh(a / ri)
            # breaks: images of the knots, x = r cosh(tau), and a grading towards tau_max
            # (x -> a, where g' may have a kink) and towards 0
            with np.errstate(invalid="ignore"):
                kt = np.arccosh(np.clip(rep._panel_knots()[None, :] / ri[:, None], 1, None))
            br = np.concatenate([kt, _graded(np.zeros(len(ri)), tau_max, toward_lo=False),
                                 _graded(np.zeros(len(ri)), tau_max)[:, :8]], axis=1)
            tau, w = _panels(np.zeros(len(ri)), tau_max, br, m_tau)
            gp = rep.gprime((ri[:, None] * np.cosh(tau)).ravel()).reshape(tau.shape)
            out[ins] = E / np.pi * np.sum(w * gp, axis=1)
        zero = r == 0
        if zero.any():
            # p(0) = (E*/pi) integral_0^a g'(x)/x dx; +inf when g'(0) = (pi/2) f'(0) > 0
            if rep.fprime(np.array([0.0]))[0] > 1e-300:
                out[zero] = np.inf
            else:
                br = np.concatenate([rep._panel_knots()[None, :], _graded([0.0], [a])], axis=1)
                xs, w = _panels(np.zeros(1), np.full(1, a), br, m_tau)
                out[zero] = E / np.pi * np.sum(w * rep.gprime(xs.ravel()) / xs.ravel())
        return out

    def pressure(self, r, *, return_error=False):
        """Contact pressure p(r) [Pa] (5.59) at r [m] (0 outside the contact).

        With ``return_error=True`` also returns the estimated absolute error per point.
        """
        r = nonnegative("r", r)
        flat = r.ravel()
        p = self._pressure(self._rep, flat, 6)
        if not return_error:
            return result(p.reshape(r.shape))
        pc = self._pressure(self._coarse, flat, 4)
        return result(p.reshape(r.shape)), result(np.abs(p - pc).reshape(r.shape))

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
    """F(d) [N], a(d) [m] and the estimated relative error of each, at the given depths [m]."""

    depth: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    rel_error: np.ndarray


class Profile:
    """An axisymmetric gap profile f(r) [m], f(0) = 0, non-decreasing, for the numerical MDR.

    Build it with :meth:`from_samples` or :meth:`from_callable`; then :meth:`solve` at a depth
    or force, or :meth:`force_depth_curve`.
    """

    def __init__(self, reps: list[_Rep], r_max: float, source: str):
        self._reps = reps  # increasing resolution; the last is the finest
        self.r_max = r_max
        self.source = source

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
            chooses the smoothing by generalized cross-validation.
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

        def coarse_of(seg_r):  # every other sample, keeping 0, the breakpoints and r_max
            keep = np.zeros(len(seg_r), bool)
            keep[::2] = True
            keep[-1] = True
            keep |= np.isin(seg_r, bp)
            return keep

        keep = coarse_of(r)
        reps = [_build_rep(r[keep], f[keep], bp, k, smoothing, 6),
                _build_rep(r, f, bp, k, smoothing, 8)]
        return cls(reps, float(r[-1]), f"{len(r)} samples")

    @classmethod
    def from_callable(cls, f: Callable[[np.ndarray], np.ndarray], r_max: float, *,
                      breakpoints: Sequence[float] = (), n: int = 64, k: int = 5,
                      rtol: float = 1e-10, n_max: int = 8192) -> Profile:
        """Profile from a vectorized callable f(r) [m] on [0, r_max] [m].

        The callable is sampled on a grid refined (n, 2n, 4n, ... up to ``n_max`` intervals
        per segment) until the force of a test indentation to r_max/2 changes by less than
        ``rtol``; ``breakpoints`` are radii of kinks.
        """
        r_max = float(positive("r_max", r_max))
        bp = np.asarray(sorted(breakpoints), float)
        if np.any((bp <= 0) | (bp >= r_max)):
            raise ValueError(f"breakpoints {list(bp)} must lie in (0, {r_max})")
        edges = np.concatenate([[0.0], bp, [r_max]])

        def grid(m):
            parts = [np.linspace(lo, hi, m + 1)[:-1] for lo, hi in zip(edges[:-1], edges[1:],
                                                                     strict=True)]
            return np.concatenate(parts + [[r_max]])

        def rep(m):
            rr = grid(m)
            ff = np.asarray(f(rr), float)
            if not np.all(np.isfinite(ff)):
                raise ValueError("f returned a non-finite value on [0, r_max]")
            return _build_rep(rr, ff - ff[0], bp, k, None, 8)

        m = n
        prev = rep(m)
        while True:
            cur = rep(2 * m)
            test = Profile([prev, cur], r_max, "callable")
            a = r_max / 2
            F1, F0 = (float(2 * (rp.g_direct(np.array([a]))[0] * a - rp.G(np.array([a]))[0]))
                      for rp in (cur, prev))
            if abs(F1 - F0) <= rtol * abs(F1) or 2 * m >= n_max:
                del test
                break
            m, prev = 2 * m, cur
        return cls([prev, cur], r_max, f"callable, {2 * m} intervals per segment")

    # -- evaluation ------------------------------------------------------------------------
    def g(self, x):
        """MDR profile g(x) [m] (5.52)."""
        x = np.abs(as_float("x", x))
        return result(self._reps[-1].g(x.ravel()).reshape(x.shape))

    def _radius(self, rep: _Rep, d: float) -> float:
        """Solve g(a) = d (5.55): bracket on a grid, then safeguarded Newton."""
        lo, hi = 0.0, self.r_max
        if rep.g(np.array([hi]))[0] < d:
            raise ValueError(f"depth {d} exceeds g(r_max) = {rep.g(np.array([hi]))[0]}: "
                             "the profile is too short for this depth")
        xs = np.linspace(0, hi, 33)[1:]
        gs = rep.g(xs)
        i = int(np.searchsorted(gs, d))
        lo, hi = (xs[i - 1] if i > 0 else 0.0), xs[min(i, len(xs) - 1)]
        a = (lo + hi) / 2
        for _ in range(100):  # on the interpolated g
            ga, gp = rep.g(np.array([a]))[0] - d, rep.gprime(np.array([a]))[0]
            if ga > 0:
                hi = a
            else:
                lo = a
            step = ga / gp if gp > 0 else np.inf
            a_new = a - step
            if not (lo < a_new < hi):
                a_new = (lo + hi) / 2
            if abs(a_new - a) <= 1e-15 * a:
                a = a_new
                break
            a = a_new
        for _ in range(3):  # polish on g and g' by quadrature (quadratic convergence)
            ga = rep.g_direct(np.array([a]))[0] - d
            gp = rep.gprime_direct(np.array([a]))[0]
            if not gp > 0:
                break
            a_new = a - ga / gp
            if abs(a_new - a) <= 1e-15 * a:
                return a_new
            a = a_new
        return a

    def _force(self, rep: _Rep, a: float, d: float, E_star: float) -> float:
        return float(2 * E_star * (d * a - rep.G(np.array([a]))[0]))  # (5.57)

    def _force_of_radius(self, rep, a, E_star):
        return self._force(rep, a, rep.g_direct(np.array([a]))[0], E_star)

    def solve(self, *, depth: float | None = None, force: float | None = None,
              E_star: float, rtol: float = 1e-8) -> Solution:
        """Solve the contact at a given ``depth`` [m] or normal ``force`` [N].

        Parameters
        ----------
        depth, force : float
            Exactly one of them, > 0.
        E_star : float
            Effective modulus [Pa] (5.26), > 0.
        rtol : float
            Tolerance on the estimated relative error of force and contact radius.
        """
        from scipy.optimize import brentq

        E_star = float(positive("E_star", E_star))
        if (depth is None) == (force is None):
            raise ValueError("give exactly one of depth= and force=")
        coarse, fine = self._reps
        out = []
        for rep in (fine, coarse):
            if depth is not None:
                d = float(positive("depth", depth))
                a = self._radius(rep, d)
            else:
                Ft = float(positive("force", force))
                Fmax = self._force_of_radius(rep, self.r_max, E_star)
                if Ft > Fmax:
                    raise ValueError(f"force = {Ft} exceeds F(r_max) = {Fmax}")
                a = brentq(lambda aa, rp=rep, ft=Ft: self._force_of_radius(rp, aa, E_star) - ft,
                           0.0, self.r_max, xtol=1e-16 * self.r_max, rtol=1e-15)
                d = float(rep.g_direct(np.array([a]))[0])
            out.append((d, a, self._force(rep, a, d, E_star)))
        (d, a, F), (dc, ac, Fc) = out
        err = max(abs(F - Fc) / F, abs(a - ac) / a, abs(d - dc) / d)
        return Solution(depth=d, contact_radius=a, force=F, E_star=E_star, rel_error=err,
                        converged=err <= rtol, rtol=rtol, _rep=fine, _coarse=coarse)

    def force_depth_curve(self, depths, *, E_star: float) -> ForceDepthCurve:
        """F(d) [N] and a(d) [m] at each depth [m] of ``depths`` (monotone in d)."""
        depths = positive("depths", depths).ravel()
        sols = [self.solve(depth=float(dd), E_star=E_star, rtol=np.inf) for dd in depths]
        return ForceDepthCurve(depths, np.array([s.force for s in sols]),
                               np.array([s.contact_radius for s in sols]),
                               np.array([s.rel_error for s in sols]))
