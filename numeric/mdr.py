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
  with the remainder of integral_0^x g (the kinks' primitives off); computed by quadrature
  on first use and only as far as the radii asked for need (a contact radius, a pressure,
  g, a displacement), grown when a later call needs more.
- (5.52) by quadrature: g(x) = x integral_0^x f'(u) du / sqrt(x^2 - u^2) and q(x): the
  spline's pieces at least two widths below x by Gauss-Legendre on fixed nodes in u (f', f''
  evaluated once for every x), the rest with u = x sin(theta), which removes the endpoint
  singularity, by Gauss-Legendre in theta broken at the pieces' ends.
- (5.55) g(a) = d at every depth at once by a safeguarded Newton on the tables of g and g'
  (started between the table nodes that bracket d); force control solves F(a) = F by
  Brent's method on the monotone F(a) = 2 E* integral_0^a x g'(x) dx by quadrature.
- (5.57) F = 2 E* (d a - integral_0^a g) by the generated ``mdr_force``, with
  integral_0^a g = integral_0^a f'(u) sqrt(a^2 - u^2) du from its table (by quadrature under
  force control).
- (5.59) p(r) = (E*/pi) integral_r^a g'(x) dx / sqrt(x^2 - r^2): the kink terms by the
  generated ``mdr_kink_pressure`` (incomplete elliptic integrals, log-infinite at r = b_j);
  the q part per segment with x = r + w^2 on the segment holding r (removes the Abel kernel's
  1/sqrt(x - r)) and x = b_j + t^2 on later segments, Gauss-Legendre graded towards w = 0 (or
  t = 0) down to the scale of the nearest singularity. p(0) is +inf for a conical tip (f'(0)
  > 0, resolved by both resolutions).
- (5.60) with x = r sin(theta): u(r) = (2/pi) integral_0^(asin(min(1, a/r))) (d - g(r sin theta)).
- Error bound and the rtol contract: every result is computed twice, with the full
  resolution and with every other sample (samples) or half the grid (callables), coarser
  tables and fewer quadrature points. ``Solution.rel_error`` bounds the relative error of
  force, contact radius and depth by the larger of (1) their coarse-vs-fine relative
  differences, an upper estimate of the error of the coarse solution (so a conservative bound
  for the returned, fine one), and (2) the envelope of the differences of g and of its
  integral on radii within two coarse sample spacings of a, put through the linearized
  (5.55) and (5.57) (the differences at a alone can vanish by accident), plus, for a
  smoothed profile, its own error, which both resolutions share (eps, the largest residual
  of the smoothing inside the contact: |dF| <= 2 E* a eps by the comparison principle,
  ``solve.smoothing``), plus a rounding floor (64 + 4 N) eps (the spline's derivative loses
  about log10(N) digits). The pressure's
  bound (``return_error=True``) adds the Abel integral of |q - q_coarse| and a rounding bound
  (a kink term's parameter (r/b)^2 near 1); where a third resolution (half the coarse one)
  shows the pair converging at an order below 1 (the splines near a singular f'', as f ~
  r^1.5 at the axis: h^0.5), the difference is divided by (rho - 1), rho the ratio of the
  two differences (Richardson); where they neither shrink nor change sign (above ``STALLED``
  of the mean pressure), p has not converged and the bound is +inf. Within rel_error a of
  the edge it adds p(a - 2 rel_error a): the true p ~ sqrt(a_true - r) may be nonzero
  where every resolution's radius stops short of a_true and gives 0. ``rtol`` has one
  meaning: the target of ``rel_error``, in ``RTOL_RANGE`` (default ``DEFAULT_RTOL``). A
  callable's grid is doubled until the bound meets it; a sampled profile's quadrature is
  refined while that at least halves the bound (its splines cannot be refined). ``Solution.met``
  says whether it was met and ``why_not_met`` why not.

Layout: this module is the public face (``Profile``, ``Solution``, ``ForceDepthCurve``, the
rtol contract); the engine is the private package ``numeric/_mdr``: ``spline`` (the
representation of f), ``kinks`` (the exact branch-point terms), ``quadrature`` ((5.52) and the
integral of g), ``tables`` (the smooth remainders), ``operators`` ((5.59), (5.60)),
``resolution`` (coarse/fine pairs and their refinement), ``solve`` ((5.55), (5.57), the bound).
:mod:`hertzmdr.numeric.abel` evaluates (5.59) from samples of the line load by a second engine,
on purpose: its module docstring says why.

Measured convergence orders and timings are in ``docs/mdr.md`` (``benchmarks/bench_mdr.py``).
"""


from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._mdr import operators, solve, tables
from hertzmdr.numeric._mdr.resolution import Grid, Samples
from hertzmdr.numeric._mdr.spline import Rep
from hertzmdr.numeric._validate import as_float, between, nonnegative, positive, result

__all__ = ["Profile", "Solution", "ForceDepthCurve", "DEFAULT_RTOL", "RTOL_RANGE"]

#: The target of the relative error bound of a solve when none is given [1].
DEFAULT_RTOL = 1e-8
#: The targets a solve accepts, (lo, hi) [1]. lo is measured: the bound that the callable
#: refinement reaches at n_max = 8192 intervals a segment for a set of profiles (smooth r^2.5
#: and r^1.5, a kinked tip with its breakpoint, a sphere-cone tip with and without its tangent
#: point as a breakpoint, each at two depths) is 2.5e-13 ... 1.0e-11; the largest, rounded
#: up, is lo (tests/test_mdr.py::test_rtol_range_lower_end re-measures it). A sampled profile
#: reaches what its samples allow: its rounding floor alone is (64 + 4 N) eps, 4.5e-12 at
#: N = 5000. hi: the bound is a linearization of the difference of two resolutions
#: (da = dg/g'(a)); tests/test_mdr_bounds.py checks it against 30-digit references on
#: force and contact-radius errors up to 6e-4, and a target above 1e-2 would rest on it where
#: it is untested.
RTOL_RANGE = (1e-11, 1e-2)
#: A depth whose bound on the tables misses rtol by at most this factor is solved again by
#: quadrature (no tables) [1]: the tables' interpolation error reaches ~1e-10 relative on
#: the finest callable grids, 14 times RTOL_RANGE[0] (tests/test_mdr.py::
#: test_rtol_range_lower_end).
NEAR = 30.0
#: Coarse-vs-fine differences of the pressure below this fraction of the mean pressure are
#: taken as the quadratures' noise when they do not shrink with the resolution (measured
#: 1e-10 ... 1e-9 for smooth sampled profiles); above it, differences that neither shrink nor
#: change sign mean the pressure has not converged, and its bound is +inf [1].
STALLED = 1e-6


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


def _check_k(k) -> int:
    """The spline degree k: 1, 3 or 5 (an integer; a bool or a float is refused)."""
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k not in (1, 3, 5):
        raise ValueError(f"k = {k!r} is out of range; valid: 1, 3, 5")
    return int(k)


def _check_smoothing(smoothing) -> float | str | None:
    """None (interpolate), "gcv", or the smoothing spline's parameter lam >= 0 (finite; a
    bool is refused)."""
    if smoothing is None or (isinstance(smoothing, str) and smoothing == "gcv"):
        return smoothing
    if (not isinstance(smoothing, bool) and isinstance(smoothing, (int, float, np.integer,
                                                                   np.floating))
            and np.isfinite(smoothing) and smoothing >= 0):
        return float(smoothing)
    raise ValueError(f"smoothing = {smoothing!r} is out of range; valid: None, \"gcv\" or a "
                     "finite number >= 0 (the smoothing spline's lam)")


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
    _rep: Rep = field(repr=False)
    _coarse: Rep = field(repr=False)
    _d_coarse: float = field(repr=False)
    _a_coarse: float = field(repr=False)
    _r_max: float = field(default=0.0, repr=False)  # the profile's, for the third resolution
    _load: float | None = field(default=None, repr=False)  # the force, if solved at one
    _third: tuple | None = field(default=None, repr=False, compare=False)  # (Rep, a), a cache

    @property
    def unloaded(self) -> bool:
        """No load (depth 0, force 0): no contact, p = 0 and u_z = 0 everywhere, exactly."""
        return self.force == 0.0 and self.contact_radius == 0.0

    def g(self, x, *, return_error=False):
        """MDR profile g(x) [m] (5.52) at |x| [m]; with ``return_error=True`` also a bound of
        its absolute error [m] (``Profile.g``)."""
        return _g(self._rep, self._coarse, x, return_error)

    def _halved(self) -> tuple[Rep, float]:
        """The third resolution (half the coarse one, ``Rep.halved``) solved as this solution
        was (at its depth, or its force), and its contact radius [m]; where it cannot be
        solved (a depth beyond what the halved samples reach, at the profile's end), the
        coarse one's contact radius."""
        if self._third is None:
            rep = self._coarse.halved()
            try:
                _, a, _ = solve.one(rep, self._r_max, None if self._load is not None
                                    else self.depth, self._load, self.E_star, self._a_coarse)
            except ValueError:
                a = self._a_coarse
            self._third = (rep, a)
        return self._third

    def pressure(self, r, *, return_error=False):
        """Contact pressure p(r) [Pa] (5.59) at r [m] (0 outside the contact).

        +inf at a kink r = b < a (a log singularity, (5.59) of b s / sqrt(x^2 - b^2)) and at
        r = 0 under a conical tip. With ``return_error=True`` also returns a bound of the
        absolute error per point [Pa]: coarse-vs-fine difference, the Abel integral of the
        tables' difference (divided by rho - 1 where a third resolution shows an order below
        1, rho = 2^order), a rounding bound (module docstring) and, within rel_error a of
        the edge, p(a - 2 rel_error a) (the true p ~ sqrt(a_true - r) there may be nonzero
        where every resolution gives 0); tests/test_mdr.py and
        tests/test_mdr_bounds.py check it against 30-digit references, near kinks too.
        """
        r = nonnegative("r", r)
        if self.unloaded:
            zero = np.zeros(r.shape)
            return (zero, zero.copy()) if return_error else zero
        flat = r.ravel()
        a, E = self.contact_radius, self.E_star
        conical = bool((flat == 0).any()) and operators.conical_tip(self._rep, self._coarse, a)
        if not return_error:
            return result(operators.pressure(self._rep, flat, a, E, 6, conical).reshape(r.shape))
        # coarse: the half-resolution profile, its own contact radius, fewer Gauss points;
        # dev: the same integral of |q - q_coarse| (the signed difference may pass through 0
        # at some r while both are in error)
        p, dev = operators.pressure(self._rep, flat, a, E, 6, conical, other=self._coarse)
        with np.errstate(invalid="ignore"):  # inf - inf at a conical tip's r = 0
            # the same one level down (coarse vs half of it, ``_halved``): their ratio rho =
            # 2^order. The pair's difference bounds the fine error while the order is >= 1;
            # below (the splines near a singular f'', e.g. f ~ r^1.5 on the axis: h^0.5) the
            # error is difference / (rho - 1) (Richardson), up to 1 / (rho - 1) times it.
            # Where the differences do not shrink (rho <= 1) and keep their sign, the
            # pressure has not converged (f = 2 r^1.2 on 40 samples: p(0) 68 % off, the
            # differences 5 % each): no bound, +inf. Not where they are below STALLED of
            # the mean pressure: there they are the quadratures' last digits (1e-10 ...
            # 1e-9 of it for smooth profiles, measured), not a trend.
            third, a3 = self._halved()
            pc, dev_c = operators.pressure(self._coarse, flat, self._a_coarse, E, 4,
                                           conical, other=third)
            p3 = operators.pressure(third, flat, a3, E, 4, conical)
            est = np.abs(p - pc) + dev
            with np.errstate(divide="ignore"):
                rho = (np.abs(pc - p3) + dev_c) / est
                slow = (rho > 1) & (rho < 2)
                est = np.where(slow, est / np.where(slow, rho - 1, 1), est)
                stalled = ((rho <= 1) & ((p - pc) * (pc - p3) > 0)
                           & (est > STALLED * self.force / (np.pi * a * a)))
                est[stalled] = np.inf
            err = est + operators.rounding(self._rep, flat, p, a, E)
        # the edge: a is known to da = rel_error a, and where the three resolutions' radii
        # all lie on one side of the true one (f = 2 r^2.5 on 40 samples: all below it) they
        # all give p = 0 on [a, a_true) while the true p ~ C sqrt(a_true - r) is not: the bound
        # was 0 at r = a with a true error of 3.6e4 Pa (p(0.999 a) = 5.5e6 Pa). Within da of a
        # the error is at most C sqrt(2 da) = p(a - 2 da), added there
        da = self.rel_error * a
        near = np.abs(flat - a) <= da
        if near.any():
            err[near] += operators.pressure(self._rep, np.array([max(a - 2 * da, 0.0)]), a, E,
                                            6, conical)[0]
        err[np.isinf(p)] = np.inf
        return result(p.reshape(r.shape)), result(err.reshape(r.shape))

    def max_pressure(self, *, return_error=False):
        """The largest contact pressure [Pa] over 0 <= r < a, wherever it lies: on 1001 radii
        refined by a bounded search (:func:`hertzmdr.numeric.pressures.max_pressure_of`);
        +inf under a conical tip (p is log-infinite at r = 0).

        With ``return_error=True`` also a bound of its absolute error [Pa]: the pressure's bound
        (:meth:`pressure`) where the maximum lies (if p_true <= p + e everywhere, the largest
        values differ by at most e at one of the two maxima, which lie within the search's
        1e-12 a of each other where the bound is smooth); 0 for +inf, which the conical tip's
        test decides exactly.
        """
        from hertzmdr.numeric import pressures

        value, at = pressures.max_pressure_of(self.pressure, self.contact_radius, points=1001)
        if not return_error:
            return value
        if not np.isfinite(value):
            return value, 0.0
        _, err = self.pressure(np.array([at]), return_error=True)
        return value, float(err[0])

    def displacement(self, r, *, return_error=False):
        """Surface displacement u_z(r) [m] at r [m], inside and outside the contact (5.60).

        With ``return_error=True`` also a bound of the absolute error per point [m]: the
        envelope of the difference from the coarse representation (at its own depth and
        contact radius, fewer Gauss points) over half a coarse sample spacing, plus
        ``rel_error`` times the depth (the error of d and a) and a rounding bound."""
        r = nonnegative("r", r)
        if self.unloaded:
            zero = np.zeros(r.shape)
            return (zero, zero.copy()) if return_error else zero
        flat = r.ravel()
        u = operators.displacement(self._rep, flat, self.contact_radius, self.depth)
        if not return_error:
            return result(u.reshape(r.shape))

        def diff(rr):
            return (operators.displacement(self._rep, rr, self.contact_radius, self.depth)
                    - operators.displacement(self._coarse, rr, self._a_coarse, self._d_coarse,
                                             4))

        err = (operators.envelope(diff, flat, self._coarse.knots)
               + (self.rel_error + 64 * np.finfo(float).eps) * self.depth)
        return result(u.reshape(r.shape)), result(err.reshape(r.shape))


def _g(fine: Rep, coarse: Rep, x, return_error: bool):
    """g(|x|) [m] from the tables of ``fine``; with ``return_error`` also a bound [m]: the
    envelope of the difference from ``coarse`` over half a coarse sample spacing, four times
    a smoothed profile's own error on [0, x] (``Rep.smoothing_error``; ``solve.smoothing``
    says why four) and 64 eps |g| of rounding."""
    x = np.abs(between("x", x, -np.inf, np.inf))  # g is even: any finite x
    flat = x.ravel()
    g = tables.g(fine, flat)
    if not return_error:
        return result(g.reshape(x.shape))

    def diff(xx):
        return tables.g(fine, xx) - tables.g(coarse, xx)

    err = (operators.envelope(diff, flat, coarse.knots) + 4 * fine.smoothing_error(flat)
           + 64 * np.finfo(float).eps * np.abs(g))
    return result(g.reshape(x.shape)), result(err.reshape(x.shape))


@dataclass
class ForceDepthCurve:
    """F(d) [N], a(d) [m] at the given depths [m], each with its error bound and target.

    ``rel_error[i]`` bounds the relative error of ``force[i]``, ``contact_radius[i]`` and
    ``stiffness[i]`` (dF/dd = 2 E* a (5.12), the MDR's own derivative of F(d): relative
    error that of a); ``met[i]`` is ``rel_error[i] <= rtol`` and ``why_not_met[i]`` says why
    not (else None).
    """

    depth: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    rel_error: np.ndarray
    rtol: float
    met: np.ndarray
    why_not_met: list[str | None]
    stiffness: np.ndarray  # [N/m]


class Profile:
    """An axisymmetric gap profile f(r) [m], f(0) = 0, non-decreasing, for the numerical MDR.

    Build it with :meth:`from_samples` or :meth:`from_callable`; then :meth:`solve` at a depth
    or force, or :meth:`force_depth_curve`.
    """

    def __init__(self, source: Samples | Grid, r_max: float, description: str):
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
            raise ValueError(f"breakpoints {bp.tolist()} must be samples strictly inside "
                             f"(0, {r[-1]})")
        ends = np.concatenate([[0], np.searchsorted(r, bp), [len(r) - 1]])
        short = np.flatnonzero(np.diff(ends) < 2)
        if short.size:  # its coarse representation would be its fine one: no error bound
            j = short[0]
            raise ValueError(f"breakpoints {bp.tolist()} leave one sample interval between "
                             f"r = {r[ends[j]]:.6g} and {r[ends[j + 1]]:.6g}; valid: at least "
                             "two intervals (three samples) in every piece between 0, the "
                             "breakpoints and r[-1] (the error bound compares a piece's samples "
                             "with every other one of them)")
        k = _check_k(k)
        return cls(Samples(r, f - f[0], bp, k, _check_smoothing(smoothing)), float(r[-1]),
                   f"{len(r)} samples")

    @classmethod
    def from_callable(cls, f: Callable[[np.ndarray], np.ndarray], r_max: float, *,
                      breakpoints: Sequence[float] = (), n: int = 64, k: int = 5,
                      n_max: int = 8192) -> Profile:
        """Profile from a vectorized callable f(r) [m] on [0, r_max] [m].

        Each :meth:`solve` samples the callable on grids of n, 2n, 4n, ... intervals per
        segment (up to ``n_max``; each grid is kept for later solves) until the error
        estimate meets its ``rtol``; ``breakpoints`` are radii [m] of kinks; ``k`` is the
        spline degree (1, 3 or 5, as :meth:`from_samples`).
        """
        r_max = float(positive("r_max", r_max))
        bp = np.asarray(sorted(breakpoints), float)
        if np.any((bp <= 0) | (bp >= r_max)):
            raise ValueError(f"breakpoints {bp.tolist()} must lie in (0, {r_max})")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= n_max:
            raise ValueError(f"n = {n!r} is out of range; valid: an integer 4 <= n <= n_max = "
                             f"{n_max}")
        grid = Grid(f, r_max, bp, int(n), _check_k(k), int(n_max))
        grid.pair(0)  # sample now: a callable that fails should fail here
        return cls(grid, r_max, f"callable, {n} to {n_max} intervals a segment")

    # -- evaluation ------------------------------------------------------------------------
    def g(self, x, *, return_error=False):
        """MDR profile g(x) [m] (5.52) at |x| [m] (from the finest representation a first
        solve uses); with ``return_error=True`` also a bound of its absolute error [m]: the
        difference from the coarse representation, its envelope over half a coarse sample
        spacing (it may pass through 0 at some x), plus rounding."""
        coarse, fine = self._source.pair(0)
        return _g(fine, coarse, x, return_error)

    def solve(self, *, depth: float | None = None, force: float | None = None,
              E_star: float, rtol: float | None = None) -> Solution:
        """Solve the contact at a given ``depth`` [m] or normal ``force`` [N].

        Parameters
        ----------
        depth, force : float
            Exactly one of them, >= 0. At 0 (no load, the first point of a sweep) the solution
            is exact: d = F = a = 0, rel_error 0, p = u_z = 0 everywhere (a sampled tip's flat
            apex is not resolved as a contact either at small loads: its spline rises from
            r = 0).
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
            depth = float(nonnegative("depth", depth))
        else:
            force = float(nonnegative("force", force))
        if (depth if depth is not None else force) == 0.0:
            coarse, fine = self._source.pair(0)
            return Solution(depth=0.0, contact_radius=0.0, force=0.0, E_star=E_star,
                            rel_error=0.0, rtol=rtol, met=True, why_not_met=None, _rep=fine,
                            _coarse=coarse, _d_coarse=0.0, _a_coarse=0.0, _r_max=self.r_max)
        if depth is not None:
            at = self._at_depths(np.array([depth]), E_star, rtol)
            a, F, ac, err = (float(v[0]) for v in at[:4])
            lvl, d, dc = int(at[4][0]), depth, depth
            coarse, fine = self._source.pair(lvl)
        else:
            level, best = 0, None
            while True:
                pair = self._source.pair(level)
                if pair is None:
                    break
                *res, err = solve.pair(*pair, self.r_max, None, force, E_star)
                if best is not None and self._source.only_quadrature and err > best[-1] / 2:
                    break  # the quadrature is not what limits a sampled profile: keep the last
                best = (pair, level, *res, err)
                if err <= rtol:
                    break
                level += 1
            (coarse, fine), lvl, d, a, F, dc, ac, err = best
        met = err <= rtol
        return Solution(depth=d, contact_radius=a, force=F, E_star=E_star, rel_error=err,
                        rtol=rtol, met=met, why_not_met=None if met else
                        self._source.why_not(err, lvl), _rep=fine, _coarse=coarse,
                        _d_coarse=dc, _a_coarse=ac, _r_max=self.r_max, _load=force)

    def _at_depths(self, depths: np.ndarray, E_star: float, rtol: float):
        """a [m], F [N], the coarse a [m], the bound [1] and the refinement level at every
        depth [m] (0: exact zeros, level 0): each level is one (coarse, fine) pair, all its
        depths solved at once on the tables (``solve.curve``), those still short of rtol
        again by quadrature (``solve.pair``: slower, without the tables' interpolation error);
        every depth still short of rtol goes on to the next level (a sampled profile: only
        while the level at least halves its bound, else the last is kept)."""
        M = len(depths)
        a, F, ac, err = np.zeros(M), np.zeros(M), np.zeros(M), np.zeros(M)
        lvl = np.zeros(M, int)
        live = np.flatnonzero(depths > 0)
        level = 0
        while len(live):
            pair = self._source.pair(level)
            if pair is None:
                break
            aa, FF, cc, ee = solve.curve(*pair, self.r_max, depths[live], E_star)
            # where the tables' own interpolation error may keep the bound above rtol (fine
            # callable grids at rtol near RTOL_RANGE[0]: bounds ~1e-10 on the tables, ~1e-11
            # without), the quadrature route of a single solve, which has no tables; the
            # smaller bound is kept. Not where the bound misses rtol by more than NEAR: the
            # representations differ by more than the tables could explain, and the
            # quadrature's cost would be spent for nothing
            for k in np.flatnonzero((ee > rtol) & (ee <= NEAR * rtol)):
                _, a1, F1, _, c1, e1 = solve.pair(*pair, self.r_max, float(depths[live[k]]),
                                                  None, E_star)
                if e1 < ee[k]:
                    aa[k], FF[k], cc[k], ee[k] = a1, F1, c1, e1
            if level > 0 and self._source.only_quadrature:
                # the quadrature is not what limits a sampled profile: keep the last
                better = ee <= err[live] / 2
                live, aa, FF, cc, ee = (live[better], aa[better], FF[better], cc[better],
                                        ee[better])
            a[live], F[live], ac[live], err[live], lvl[live] = aa, FF, cc, ee, level
            live = live[ee > rtol]
            level += 1
        return a, F, ac, err, lvl

    def force_depth_curve(self, depths, *, E_star: float,
                          rtol: float | None = None) -> ForceDepthCurve:
        """F(d) [N], a(d) [m] and the stiffness dF/dd [N/m] at each depth [m] of ``depths``
        (>= 0, any order), to the target ``rtol`` [1] (default ``DEFAULT_RTOL``) as
        :meth:`solve`, all depths at once.

        Each refinement level is one (coarse, fine) pair of representations; every depth
        still short of rtol goes on to the next level (a sampled profile: only while the
        level at least halves its bound, as :meth:`solve`). On a pair, the contact radii
        solve (5.55) by a vectorized safeguarded Newton on the tables of g and g', the forces
        are (5.57) with the tables' integral of g, and the bound is made as :meth:`solve`
        makes it (``rel_error``); depth 0 is exact (no contact).
        """
        rtol = _check_rtol(rtol)
        E_star = float(positive("E_star", E_star))
        depths = nonnegative("depths", depths).ravel()
        a, F, _, err, lvl = self._at_depths(depths, E_star, rtol)
        met = err <= rtol
        why = [None if m else self._source.why_not(float(e), int(v))
               for m, e, v in zip(met, err, lvl, strict=True)]
        return ForceDepthCurve(depths, F, a, err, rtol, met, why,
                               gen.mdr_stiffness(E_star, a))  # (5.12)
