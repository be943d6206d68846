"""Fit a measured force curve F(z_p) for the sample's modulus, contact point and baseline.

The model (generated from :mod:`hertzmdr.derive.fit`) is

    F(z_p; E*, z_0, F_0, s_0) = F_tip(E*, d = max(0, z_p - z_0)) + F_0 + s_0 z_p,

with z_p the position of the tip's base (increasing into the sample, the cantilever's
deflection already subtracted), z_0 the contact point, F_0 + s_0 z_p the baseline before
contact, and F_tip the force law of a closed-form tip: the paraboloid (Hertz, (5.23)), the exact
spherical cap (Sneddon's sphere by the MDR, (5.55) and (5.57)), the cone (5.40), the flat punch
and the power law (Problem 7). Its derivatives in E* and z_0 are derived by SymPy (dF/dz_0 = 0
where d <= 0); F is linear in F_0 and s_0.

Method: the model is linear in (E*, F_0, s_0) at a fixed z_0, so a scan of trial contact points
over the curve, each solved by linear least squares, gives a start that needs no guess from the
user; :func:`scipy.optimize.leastsq` (Levenberg-Marquardt, MINPACK) then refines all four
parameters with the generated Jacobian. The standard errors are the square roots of the diagonal
of (J^T J)^-1 s^2 at the solution, s^2 = sum(r^2)/(N - 4) the residual variance (of the weighted
residuals when ``sigma`` is given): the linearised covariance, which is what the coverage test
of tests/test_fit.py checks against the nominal 68 % per standard error.

A regular pyramid is fitted as the cone of its force law (:class:`Pyramid`: the BEM's factor
over the equal-area cone). A measured tip (:class:`SampledTip`) goes through the numerical MDR:
the scan and Levenberg-Marquardt use a table of its force law, then Gauss-Newton steps on the
exact MDR at every point finish the fit (:func:`_polish`) and carry the MDR's error bound into
the parameters (``model_error``). Adhesive retract curves: :mod:`hertzmdr.numeric.fit_adhesive`.
Batches and force maps: :mod:`hertzmdr.numeric.fit_batch`.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from functools import cache

import numpy as np
from scipy.optimize import leastsq

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, between, poisson, positive
from hertzmdr.numeric.powerlaw import kappa
from hertzmdr.numeric.scene.assumptions import check as check_assumptions

__all__ = ["Paraboloid", "ExactSphere", "Cone", "Pyramid", "FlatPunch", "PowerLaw", "SampledTip",
           "FitResult", "NoContactError", "fit_curve", "PARAMETERS"]

#: names of the fitted parameters, in the order of :attr:`FitResult.values`
PARAMETERS = ("E_star", "z_0", "F_0", "s_0")
#: their SI units
UNITS = ("Pa", "m", "N", "N/m")
#: fewest points the fit accepts: four parameters and at least two degrees of freedom
MIN_POINTS = 6
#: fewest points in contact (d > 0) for the tip's two parameters (E*, z_0) to be determined
MIN_CONTACT_POINTS = 3
#: trial contact points of the start scan, spread evenly over the curve
N_SCAN = 32
#: points of the curve the start scans use at most (evenly spread, the deepest ones kept)
SCAN_POINTS = 128
#: trial contact points of the second scan, between the best first one's neighbours
N_REFINE = 16
#: a contact is detected when the tip's force at the deepest point exceeds this many standard
#: deviations of the residuals (5 sigma: a false contact in pure noise is then a 3e-7 event)
CONTACT_SIGNIFICANCE = 5.0
#: ... and when E* exceeds this many of its standard errors: a modulus within 3 of them of 0 is
#: not measured (a straight line without noise fits any E* ~ 0 to its rounding)
MODULUS_SIGNIFICANCE = 3.0
#: most Newton steps for the exact sphere's lam (a bisection step each at worst; 5-7 suffice)
LAM_MAX_STEPS = 80
#: Levenberg-Marquardt stops when a step would lower sum(r^2) by less than this fraction of it:
#: the step left is then below sqrt(FTOL N) standard errors of the parameters (a step of k
#: standard errors lowers sum(r^2) by k^2 s^2, and sum(r^2) = (N - 4) s^2), 4.5e-4 of them for
#: N = 2000 points; a noise-free curve, whose sum(r^2) falls to rounding, still converges to
#: the last digits (xtol)
FTOL = 1e-10
#: sigma(z_0) above this fraction of the deepest indentation: the contact point is poorly
#: determined (the modulus then inherits its uncertainty through their correlation)
Z0_POOR = 0.1
#: a step between neighbouring residuals above this many standard deviations of such steps is
#: a jump (8: a false alarm in Gaussian noise is a 1e-15 event per point)
JUMP_SIGNIFICANCE = 8.0


class NoContactError(ValueError):
    """The curve shows no contact with the sample: nothing to fit."""


@dataclass(frozen=True)
class _Tip(ABC):
    """What every tip provides: its force model, the model's derivatives, its limit ratios."""

    @abstractmethod
    def force(self, E_star, z, z0, F0, s0):
        """Model force F [N] at the positions z [m] (E* [Pa], z0 [m], F0 [N], s0 [N/m])."""

    @abstractmethod
    def derivatives(self, E_star, z, z0):
        """(dF/dE* [m^2], dF/dz_0 [N/m]) at the positions z [m]."""

    @abstractmethod
    def basis(self, z, z0):
        """dF/dE* [m^2] at the positions z [m] for the contact points z0 [m] (broadcast): the
        tip's force per unit E*, since F = E* dF/dE* + F_0 + s_0 z_p (asserted in
        derive/fit.py)."""

    def _unit(self, z, z0, state=None):
        """(dF/dE*, dF/dz_0 at E* = 1) at one contact point; dF/dz_0 is proportional to E*
        (asserted in derive/fit.py), so the fit evaluates the tip once per contact point.
        ``state``: a dict one fit owns across its evaluations (the exact sphere's warm start)."""
        return self.derivatives(1.0, z, z0)

    #: whether :meth:`_unit` is a table (a sampled tip): the fit then ends on the tip's
    #: ``_exact`` (the model and the bound of its relative error per point; only a tabulated
    #: tip has one, :meth:`SampledTip._exact`)
    tabulated = False

    @abstractmethod
    def ratios(self, d_max: float) -> dict[str, float]:
        """The chapter's limit ratios at the deepest indentation d_max [m] (assumptions.py)."""

    @abstractmethod
    def describe(self) -> str:
        """The tip in words, with its geometry in SI units."""


_EPS = float(np.finfo(float).eps)


#: Newton's iteration for lam stops after a step below this fraction of lam: the convergence is
#: quadratic, the next correction at most ~(1e-8)^2/2 of lam (the error after a step is
#: (f''/(2 f')) e^2 with f = lam tanh(lam) - d/R: e^2/(2 lam) at small lam, less beyond), far
#: below an ulp; a bisection step must still shrink to 2 ulp
LAM_NEWTON_STOP = 1e-8
#: plain Newton steps from a close start before the safeguarded iteration takes over: from the
#: table's ~2.5e-4 two suffice, from a warm start 1-3 (the relative error squares each step)
LAM_FAST_STEPS = 4
#: the start table of lam(d/R): nodes in ln(d/R) over [LAM_TABLE_SPAN], linear interpolation of
#: ln(lam) in ln(d/R) (a smooth function, slope 1/2 to 1): error ~1e-4 relative, after which
#: two Newton steps end at the last digit
LAM_TABLE_SPAN = (-30.0, 12.0)
LAM_TABLE_NODES = 512


@cache
def _lam_table() -> tuple[np.ndarray, np.ndarray]:
    """(ln(d/R), ln(lam)) at LAM_TABLE_NODES nodes: lam(d/R) does not depend on R, so one
    table (Newton's method from the bracket's lower bound, once per process) serves every
    exact sphere."""
    x = np.linspace(*LAM_TABLE_SPAN, LAM_TABLE_NODES)
    return x, np.log(lam_from_depth(np.exp(x), 1.0, _table=False))


def lam_from_depth(d, R, start=None, *, with_radius=False, with_slope=False, _table=True):
    """lam = atanh(a/R) of the exact sphere at the depth d [m]: the root of R lam tanh(lam) = d
    (5.55), 0 for d <= 0 (vectorized; R [m] > 0).

    Newton's method on d = a lam (``fit_sphere_depth``) with the derived slope dd/dlam
    (``fit_sphere_depth_dlam``), both at the step's a = R tanh(lam) (one tanh a step). From a
    close start (the table, ``start``) first plain Newton steps (:func:`_lam_newton`: no
    bracket to keep), kept when they stop; else, and with no close start, inside the bracket
    [max(sqrt(d/R), d/R), (d/R + sqrt((d/R)(d/R + 4)))/2] of numeric/sphere.py's bisection: a
    step that leaves the bracket is replaced by a bisection step, so the iteration cannot
    diverge, and it converges quadratically. Both stop after a Newton step below
    LAM_NEWTON_STOP of lam (the next one would be below an ulp); a bisection step stops below
    2 ulp.
    The first iterate: ``start`` (d's shape, optional; e.g. the roots at nearby depths, a fit's
    previous contact point; any values are safe: a bad start fails the fast path's stop and is
    clipped into the bracket), else (and where ``start`` is NaN) the interpolated table
    :func:`_lam_table` (~1e-4 relative): 1-2 steps a point. ``with_radius``: also return the
    contact radius a = R tanh(lam) [m] at the root (0 where d <= 0), as the last iterate's a
    plus ``fit_sphere_radius_dlam`` times the last step (no tanh of its own: the step is below
    1e-8 lam, so the second-order term, R sech(lam)^2 tanh(lam) step^2 <= 0.5e-16 a, is below
    an ulp). ``with_slope``: also return dd/dlam [m] at the last iterate but one (inf where
    d <= 0), for the next call's start at shifted depths, lam + shift/(dd/dlam). The result:
    lam, then a (``with_radius``), then dd/dlam (``with_slope``).
    """
    d = np.asarray(d, float)
    touch = d > 0
    every = bool(touch.all())  # a fit's tail: no copies
    dd = d if every else d[touch]  # only the points in contact
    delta = dd / R
    lo = np.maximum(np.sqrt(delta), delta)
    first = None if start is None else np.asarray(start, float)
    first = first if first is None or every else first[touch]
    missing = True if first is None else np.isnan(first)
    lam = lo
    if _table and np.any(missing):
        x, y = _lam_table()
        lam = np.exp(np.interp(np.log(delta), x, y))
    if first is not None:
        lam = np.where(missing, lam, first) if np.any(missing) else first
    fast = _lam_newton(dd, R, np.maximum(lam, lo)) if _table or first is not None else None
    if fast is not None:
        lam, slope, last = fast
    else:
        lam, slope, last = _lam_safeguarded(dd, R, lam, lo)
    outs = [lam]
    if with_radius:  # the last iterate's a, moved along the last step
        prev, a = last
        outs.append(a + gen.fit_sphere_radius_dlam(R, a) * (lam - prev))
    if with_slope:
        outs.append(slope)
    if not every:  # lam = a = 0 (no contact); dd/dlam inf there: a shift gives no start
        fills = [0.0] * (1 + with_radius) + [np.inf] * with_slope
        for k, (v, fill) in enumerate(zip(outs, fills, strict=True)):
            outs[k] = np.full(d.shape, fill)
            outs[k][touch] = v
    return outs[0] if len(outs) == 1 else tuple(outs)


def _lam_newton(dd, R, lam):
    """:func:`lam_from_depth`'s fast path: at most LAM_FAST_STEPS plain Newton steps from a
    close start (the table's, a warm start's), no bracket kept; (lam, dd/dlam at the last
    iterate but one, (that iterate, its a)) when the last step is below LAM_NEWTON_STOP of the
    new lam at every point,
    else None (then the safeguarded iteration runs from the same start). That stop is the
    safeguarded iteration's own: lam > 0 (a step of at most 1e-8 lam leaves a positive lam)
    within 1e-8 lam of a root of the increasing a lam - d on lam > 0, its only root there, and
    the quadratic convergence puts the new lam within ~1e-16 lam of it. A step that runs off
    (lam <= 0, where the slope can vanish: NaN) fails the stop and falls back."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(LAM_FAST_STEPS):
            a = gen.sphere_lam_contact_radius(R, lam)  # tanh once a step
            slope = gen.fit_sphere_depth_dlam(R, lam, a)
            new = lam - (gen.fit_sphere_depth(lam, a) - dd) / slope
            if (np.abs(new - lam) <= LAM_NEWTON_STOP * new).all():
                return new, slope, (lam, a)
            lam = new
    return None


def _lam_safeguarded(dd, R, lam, lo):
    """:func:`lam_from_depth`'s safeguarded iteration: Newton's steps inside the bracket [lo,
    hi], bisection where a step leaves it; (lam, dd/dlam at the last iterate but one, (that
    iterate, its a))."""
    hi = np.maximum((dd / R + np.sqrt(dd / R * (dd / R + 4))) / 2, lo)
    lam = np.clip(lam, lo, hi)
    slope = np.ones(dd.shape)
    last = None
    for _ in range(LAM_MAX_STEPS):
        a = gen.sphere_lam_contact_radius(R, lam)  # tanh once a step, shared by d and dd/dlam
        last = (lam, a)
        f = gen.fit_sphere_depth(lam, a) - dd
        lo = np.where(f < 0, lam, lo)
        hi = np.where(f > 0, lam, hi)
        slope = gen.fit_sphere_depth_dlam(R, lam, a)
        new = lam - f / slope
        newton = (new >= lo) & (new <= hi)
        step = np.abs(new - lam)
        if newton.all():  # the usual case: Newton's steps, the quadratic-convergence stop
            lam = new
            if (step <= LAM_NEWTON_STOP * new).all():
                break
            continue
        new = np.where(newton, new, 0.5 * (lo + hi))
        step = np.abs(new - lam)
        done = (step <= 2 * _EPS * new) | (newton & (step <= LAM_NEWTON_STOP * new))
        lam = new
        if done.all():
            break
    return lam, slope, last


@dataclass(frozen=True)
class Paraboloid(_Tip):
    """Paraboloidal tip f = r^2/(2R) (Hertz, (5.23)); R [m] its radius of curvature, > 0."""

    R: float

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))

    def force(self, E_star, z, z0, F0, s0):
        return gen.fit_hertz_force(E_star, self.R, z, z0, F0, s0)

    def derivatives(self, E_star, z, z0):
        return (gen.fit_hertz_force_dE(self.R, z, z0),
                gen.fit_hertz_force_dz0(E_star, self.R, z, z0))

    def basis(self, z, z0):
        return gen.fit_hertz_force_dE(self.R, z, z0)

    def ratios(self, d_max):
        return {"a/R": float(gen.hertz_contact_radius(self.R, d_max)) / self.R}

    def describe(self):
        return f"paraboloid (Hertz), R = {self.R:.6g} m"


@dataclass(frozen=True)
class ExactSphere(_Tip):
    """Spherical cap f = R - sqrt(R^2 - r^2) (Sneddon's sphere, (5.55), (5.57)); R [m] > 0."""

    R: float

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))

    def _lam(self, z, z0):
        """(lam, a = R tanh(lam)) at the positions z: a from Newton's last step, shared by the
        force, dF/dE* and dF/dz_0 = -2 E* a."""
        return lam_from_depth(np.maximum(np.asarray(z, float) - z0, 0.0), self.R,
                              with_radius=True)

    def force(self, E_star, z, z0, F0, s0):
        lam, a = self._lam(z, z0)
        return gen.fit_sphere_force(E_star, self.R, lam, a, z, F0, s0)

    def _dE(self, lam, a):
        """dF/dE* at (lam, a), evaluated at the points in contact only (0 elsewhere), by
        ``fit_sphere_force_unit``: ``fit_sphere_force_dE`` with its common subexpressions
        computed once (derive/fit.py's FUSED)."""
        touch = lam > 0
        if touch.all():  # a fit's tail
            return gen.fit_sphere_force_unit(self.R, a, lam)
        out = np.zeros(lam.shape)
        out[touch] = gen.fit_sphere_force_unit(self.R, a[touch], lam[touch])
        return out

    def derivatives(self, E_star, z, z0):
        lam, a = self._lam(z, z0)
        return self._dE(lam, a), gen.fit_sphere_force_dz0(E_star, a)

    def basis(self, z, z0):
        return self._dE(*self._lam(z, z0))

    def _unit(self, z, z0, state=None):
        """As :meth:`_Tip._unit`; ``state`` (a dict one fit owns) keeps the last lam of the
        points z (a sorted curve's tail), its slope dd/dlam and z_0, to start Newton's
        iteration at the next z_0 from: lam + (z_0,old - z_0)/(dd/dlam), first order in the
        shift of every depth (the points new to the tail start from the table)."""
        start = None
        if state is not None and "lam" in state:
            # the previous tail's lam, shifted to the new depths: align the tails at their end
            prev = state["lam"] + (state["z0"] - z0) / state["slope"]
            start = (prev[prev.size - z.size:] if prev.size >= z.size
                     else np.r_[np.full(z.size - prev.size, np.nan), prev])
        lam, a, slope = lam_from_depth(np.maximum(np.asarray(z, float) - z0, 0.0), self.R,
                                       start, with_radius=True, with_slope=True)
        if state is not None:
            state.update(lam=lam, slope=slope, z0=z0)
        return self._dE(lam, a), gen.fit_sphere_force_dz0(1.0, a)

    def ratios(self, d_max):
        lam = lam_from_depth(np.float64(d_max), self.R)
        return {"a/R": float(gen.sphere_lam_contact_radius(self.R, lam)) / self.R}

    def describe(self):
        return f"exact sphere (spherical cap), R = {self.R:.6g} m"


@dataclass(frozen=True)
class Cone(_Tip):
    """Rigid cone f = r tan(theta) ((5.40)); theta [rad] between its surface and the plane."""

    theta: float

    def __post_init__(self):
        object.__setattr__(self, "theta", float(between("theta", self.theta, 0.0, np.pi / 2)))

    def force(self, E_star, z, z0, F0, s0):
        return gen.fit_cone_force(E_star, self.theta, z, z0, F0, s0)

    def derivatives(self, E_star, z, z0):
        return (gen.fit_cone_force_dE(self.theta, z, z0),
                gen.fit_cone_force_dz0(E_star, self.theta, z, z0))

    def basis(self, z, z0):
        return gen.fit_cone_force_dE(self.theta, z, z0)

    def ratios(self, d_max):
        return {"tan(theta)": float(np.tan(self.theta))}

    def describe(self):
        return f"cone, theta = {self.theta:.6g} rad"


#: a regular pyramid's force over its equal-area cone's, by the BEM, for each number of faces:
#: (beta_n, a bound of its error) from benchmarks/pyramid_factor.py (docs/pyramid.md: grids of
#: 128 to 1024 pixels a side, Richardson-extrapolated; the bound is the larger of the last
#: correction and the last step)
PYRAMID_BEM_FACTOR = {3: (1.0777689, 6e-7), 4: (1.0268222, 2.2e-5), 6: (1.0071782, 2.1e-6),
                      8: (1.0029514, 3.8e-6)}


@dataclass(frozen=True)
class Pyramid(_Tip):
    """Regular pyramid of ``sides`` faces and half-angle alpha [rad] (between its axis and the
    mid-line of a face), fitted as its **equal-force cone**: the pyramid's force is beta_n
    times that of its equal-area cone (theta_area = ``fit_pyramid_cone_angle(alpha, sides)``,
    the cone with the pyramid's cross-section area at every depth), beta_n measured by the BEM
    (``PYRAMID_BEM_FACTOR``, docs/pyramid.md: 1.0778 for three faces, 1.0268 for four), and
    the cone theta = ``fit_pyramid_force_cone_angle(alpha, sides, beta_n)`` has that force by
    (5.40). The force law is the pyramid's to beta_n's error (<= 2.2e-5); the cone's contact
    radius stands in for the pyramid's non-circular contact. sides in 3, 4, 6, 8 (the
    pyramids the BEM has measured), 0 < alpha < pi/2.
    """

    alpha: float
    sides: int = 4
    cone: Cone = field(init=False, repr=False)
    theta_area: float = field(init=False, repr=False)
    beta: float = field(init=False, repr=False)

    def __post_init__(self):
        alpha = float(between("alpha", self.alpha, 0.0, np.pi / 2))
        if not (isinstance(self.sides, int | np.integer)
                and int(self.sides) in PYRAMID_BEM_FACTOR):
            raise ValueError(f"sides = {self.sides!r} is out of range; valid: "
                             f"{', '.join(map(str, PYRAMID_BEM_FACTOR))} (the pyramids whose "
                             "force the BEM has measured, docs/pyramid.md)")
        n = int(self.sides)
        beta = PYRAMID_BEM_FACTOR[n][0]
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "sides", n)
        object.__setattr__(self, "beta", beta)
        object.__setattr__(self, "theta_area", float(gen.fit_pyramid_cone_angle(alpha, float(n))))
        theta = float(gen.fit_pyramid_force_cone_angle(alpha, float(n), beta))  # equal force
        object.__setattr__(self, "cone", Cone(theta=theta))

    def force(self, E_star, z, z0, F0, s0):
        return self.cone.force(E_star, z, z0, F0, s0)

    def derivatives(self, E_star, z, z0):
        return self.cone.derivatives(E_star, z, z0)

    def basis(self, z, z0):
        return self.cone.basis(z, z0)

    def ratios(self, d_max):
        """The cone's, and 1/sides: the warning that the pyramid is solved as a cone."""
        return {**self.cone.ratios(d_max), "1/sides": 1.0 / self.sides}

    def describe(self):
        from hertzmdr.numeric import force_law

        K = float(force_law.cone(self.cone.theta, 1.0).K)  # F = K E* d^2, (5.40) at theta
        return (f"{self.sides}-sided pyramid, alpha = {self.alpha:.6g} rad, as its equal-force "
                f"cone theta = {self.cone.theta:.6g} rad: F = {K:.6g} E* d^2 (the BEM's "
                f"{self.beta:.7g} times the equal-area cone's)")


@dataclass(frozen=True)
class FlatPunch(_Tip):
    """Flat cylindrical punch of radius a [m] > 0 (Problem 7(a))."""

    a: float

    def __post_init__(self):
        object.__setattr__(self, "a", float(positive("a", self.a)))

    def force(self, E_star, z, z0, F0, s0):
        return gen.fit_punch_force(E_star, self.a, z, z0, F0, s0)

    def derivatives(self, E_star, z, z0):
        return (gen.fit_punch_force_dE(self.a, z, z0),
                gen.fit_punch_force_dz0(E_star, self.a, z, z0))

    def basis(self, z, z0):
        return gen.fit_punch_force_dE(self.a, z, z0)

    def ratios(self, d_max):
        return {"d/a": d_max / self.a}

    def describe(self):
        return f"flat punch, a = {self.a:.6g} m"


@dataclass(frozen=True)
class PowerLaw(_Tip):
    """Power-law tip f = c_n r^n (Problem 7(d)); c_n [m^(1-n)] > 0, n > 0."""

    c_n: float
    n: float
    kappa_n: float = field(init=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "c_n", float(positive("c_n", self.c_n)))
        object.__setattr__(self, "n", float(positive("n", self.n)))
        object.__setattr__(self, "kappa_n", float(kappa(self.n)))

    def force(self, E_star, z, z0, F0, s0):
        return gen.fit_powerlaw_force(E_star, self.c_n, self.kappa_n, self.n, z, z0, F0, s0)

    def derivatives(self, E_star, z, z0):
        return (gen.fit_powerlaw_force_dE(self.c_n, self.kappa_n, self.n, z, z0),
                gen.fit_powerlaw_force_dz0(E_star, self.c_n, self.kappa_n, self.n, z, z0))

    def basis(self, z, z0):
        return gen.fit_powerlaw_force_dE(self.c_n, self.kappa_n, self.n, z, z0)

    def ratios(self, d_max):
        a = float(gen.powerlaw_contact_radius(self.c_n, d_max / self.kappa_n, 1.0, self.n))
        return {"d/a": d_max / a}

    def describe(self):
        return f"power law f = c_n r^n, c_n = {self.c_n:.6g} m^(1-n), n = {self.n:.6g}"


#: intervals in sqrt(d) of a sampled tip's table (the start's scan and Levenberg-Marquardt's
#: model; the fit ends on the exact MDR at every point, so the table sets speed, not accuracy:
#: at 128 the table's error moves the parameters by ~1e-11 relative, and one Gauss-Newton
#: step on the exact MDR, confirmed by a second evaluation, finishes the fit; at 48 it took two)
TABLE_INTERVALS = 128
#: the table reaches this factor beyond the deepest indentation asked for (fewer rebuilds)
TABLE_MARGIN = 1.25
#: most Gauss-Newton steps on the exact MDR after Levenberg-Marquardt on a sampled tip's table
#: (one suffices in the usual case, see TABLE_INTERVALS)
POLISH_STEPS = 4
#: a Gauss-Newton step below this fraction of every parameter's scale (E*, the span of z, of F
#: and of F/z) ends the polish: the next one would be of its square
POLISH_TOL = 1e-12
#: ... or below this fraction of every parameter's standard error (a noisy curve)
POLISH_SIGMA = 1e-3
#: a singular value of the column-scaled Jacobian below this fraction of the largest is a
#: direction of the parameters the curve does not determine (_covariance)
SINGULAR_TOL = 1e-12
#: ... and a parameter with more than this part of its unit vector along such a direction is
#: undetermined (error inf); a determined one has rounding there only (~1e-16)
NULL_TOL = 1e-8


@dataclass(frozen=True, eq=False)
class SampledTip(_Tip):
    """A measured axisymmetric tip: any :class:`hertzmdr.numeric.mdr.Profile` (samples r_i, f_i
    or a callable), its force law F_tip = E* Phi(d) by the numerical MDR ((5.55), (5.57)).

    Phi(d) = F(d)/E* [m^2] and the stiffness dF/dd = 2 E* a(d) ((5.12), the MDR's own
    derivative ``ForceDepthCurve.stiffness``, not a finite difference) do not depend on E* or
    z_0: the tip keeps a table of (d, Phi, dPhi/dd) at depths uniform in sqrt(d) (Phi goes like
    d^(3/2) for a smooth apex, d^2 for a conical one), interpolated by cubic Hermite
    polynomials in sqrt(d) with the exact slopes, for the start's scan and for
    Levenberg-Marquardt. :func:`fit_curve` then finishes with Gauss-Newton steps on the exact
    MDR at every point (:meth:`_exact`), whose ``rel_error`` per point bounds the model's
    error; :attr:`FitResult.model_error` carries it into the parameters.

    Parameters
    ----------
    profile : hertzmdr.numeric.mdr.Profile
        The tip's gap profile f(r) [m] from its apex.
    rtol : float, optional
        Target of the MDR's relative error bound per point (``mdr.RTOL_RANGE``, default
        ``mdr.DEFAULT_RTOL``); a sampled profile reaches what its samples allow.
    """

    profile: object
    rtol: float | None = None

    tabulated = True  # a class attribute, not a field: fit_curve polishes on _exact

    def __post_init__(self):
        from hertzmdr.numeric import mdr

        if not isinstance(self.profile, mdr.Profile):
            raise ValueError(f"profile = {self.profile!r} is out of range; valid: a "
                             "hertzmdr.numeric.mdr.Profile (Profile.from_samples(r, f))")
        if self.rtol is not None:
            object.__setattr__(self, "rtol", mdr._check_rtol(self.rtol))
        g, err = self.profile.g(np.array([self.profile.r_max]), return_error=True)
        # the deepest depth both representations (fine and coarse) reach (5.55)
        object.__setattr__(self, "d_limit", float(g[0] - 2 * err[0]))
        if not self.d_limit > 0:
            raise ValueError(f"the sampled tip reaches no depth: g(r_max) = {float(g[0]):.3g} m "
                             f"(5.52) at r_max = {self.profile.r_max:.6g} m, within its error "
                             f"{float(err[0]):.3g} m of 0 (flat over its samples); valid: a "
                             "profile that rises above its apex within the samples")
        object.__setattr__(self, "_memo", {})

    @classmethod
    def from_samples(cls, r, f, *, breakpoints=(), k: int = 5, rtol=None) -> SampledTip:
        """The tip of samples r_i [m] (from 0, increasing) and f_i [m] (non-decreasing):
        :meth:`hertzmdr.numeric.mdr.Profile.from_samples` with its ``breakpoints`` and ``k``."""
        from hertzmdr.numeric import mdr

        return cls(mdr.Profile.from_samples(r, f, breakpoints=breakpoints, k=k), rtol)

    def __repr__(self):  # no object address: messages must be the same in every run
        return f"SampledTip({self.profile.source!r}, r_max={self.profile.r_max!r})"

    def _too_deep(self, d_max: float) -> ValueError:
        return ValueError(
            f"the indentation d = {d_max:.6g} m is deeper than the sampled tip reaches: "
            f"g(r_max) = {self.d_limit:.6g} m (5.55), its samples ending at r_max = "
            f"{self.profile.r_max:.6g} m; valid: d < {self.d_limit:.6g} m (sample the tip "
            "further out, or fit the curve to a shallower depth)")

    def _curve(self, d):
        """(Phi [m^2], dPhi/dd = 2 a [m], rel_error [1]) at the depths d > 0 [m] by the exact
        MDR ((5.55), (5.57); the stiffness (5.12), whose relative error is that of a)."""
        c = self.profile.force_depth_curve(d, E_star=1.0, rtol=self.rtol)
        return c.force, c.stiffness, c.rel_error

    def _table(self, d_max: float):
        """The cubic Hermite interpolant of Phi in s = sqrt(d) up to d_max [m] at least (with
        TABLE_MARGIN), and the top of the table [m], its Phi [m^2] and dPhi/dd [m]."""
        from scipy.interpolate import CubicHermiteSpline

        t = self._memo.get("table")
        if t is not None and t[1] >= min(d_max, self.d_limit):
            return t
        top = min(TABLE_MARGIN * d_max, self.d_limit)
        s = np.sqrt(top) * np.linspace(0.0, 1.0, TABLE_INTERVALS + 1)
        phi, k, _ = self._curve(s[1:] ** 2)
        phi, k = np.r_[0.0, phi], np.r_[0.0, k]
        t = (CubicHermiteSpline(s, phi, k * 2 * s), top, float(phi[-1]), float(k[-1]))
        self._memo["table"] = t
        return t

    def _tabled(self, d):
        """(Phi [m^2], dPhi/dd [m]) at the depths d [m] (any shape) from the table; 0 for
        d <= 0, continued linearly (as the cylinder of the last contact radius) past its top."""
        d = np.asarray(d, float)
        spl, top, phi_top, k_top = self._table(float(np.max(d, initial=0.0)))
        ds = np.sqrt(np.clip(d, 0.0, top))
        phi = spl(ds)
        with np.errstate(divide="ignore", invalid="ignore"):
            k = np.where(ds > 0, spl(ds, 1) / (2 * ds), 0.0)
        over = d > top
        phi = np.where(over, phi_top + k_top * (d - top), np.where(d > 0, phi, 0.0))
        k = np.where(over, k_top, np.where(d > 0, k, 0.0))
        return phi, k

    def _exact(self, z, z0):
        """(dF/dE* [m^2], dF/dz_0 at E* = 1 [m], rel_error [1]) at the positions z [m] by the
        exact MDR at every point in contact: dF/dE* = Phi(d), dF/dz_0 = -E* 2 a(d) (the
        stiffness (5.12) with a minus: d = z - z_0), and the bound of the relative error of
        both per point (0 where d <= 0)."""
        d = np.asarray(z, float) - z0
        touch = d > 0
        out = np.zeros((3, d.size))
        if touch.any():
            d_max = float(d[touch].max())
            if d_max > self.d_limit:
                raise self._too_deep(d_max)
            phi, k, err = self._curve(d[touch])
            out[0, touch], out[1, touch] = phi, -k
            out[2, touch] = err
        return out[0], out[1], out[2]

    def force(self, E_star, z, z0, F0, s0):
        g, _, _ = self._exact(np.ravel(z), z0)
        return E_star * g.reshape(np.shape(z)) + F0 + s0 * np.asarray(z, float)

    def derivatives(self, E_star, z, z0):
        g, h, _ = self._exact(np.ravel(z), z0)
        return g.reshape(np.shape(z)), E_star * h.reshape(np.shape(z))

    def basis(self, z, z0):
        return self._tabled(np.asarray(z, float) - z0)[0]

    def _unit(self, z, z0, state=None):  # Levenberg-Marquardt's model: the table
        phi, k = self._tabled(np.asarray(z, float) - z0)
        return phi, -k

    def ratios(self, d_max):
        if d_max > self.d_limit:
            raise self._too_deep(d_max)
        c = self.profile.force_depth_curve(np.array([d_max]), E_star=1.0, rtol=self.rtol)
        return {"d/a": d_max / float(c.contact_radius[0])}

    def describe(self):
        return (f"sampled tip ({self.profile.source}, r_max = {self.profile.r_max:.6g} m), "
                "numerical MDR")


class _Fitted:
    """What the results of fit_curve and fit_adhesive.fit_curve share: E* and z_0 by name (the
    first two of ``values``) and the rows of the parameter table (``names``, ``units``: the
    fit's PARAMETERS and UNITS)."""

    @property
    def E_star(self) -> float:
        """Fitted effective modulus E* [Pa]."""
        return float(self.values[0])

    @property
    def z_0(self) -> float:
        """Fitted contact point [m] (where d = 0)."""
        return float(self.values[1])

    def _parameter_rows(self, names, units) -> list[str]:
        """The header, one line per parameter with its standard error, and E when fitted."""
        rows = [f"{'parameter':<10} {'value':>14} {'std. error':>12}  unit"]
        fixed = getattr(self, "fixed", ())
        for name, v, e, u in zip(names, self.values, self.errors, units, strict=True):
            err = f"{'fixed':>12}" if name in fixed else f"{e:>12.3g}"
            rows.append(f"{name:<10} {v:>14.7g} {err}  {u}")
        if self.E is not None:
            rows.append(f"{'E':<10} {self.E:>14.7g} {self.E_error:>12.3g}  Pa")
        return rows


@dataclass(frozen=True)
class FitResult(_Fitted):
    """The fitted parameters of a force curve, their uncertainties and the fit's diagnostics.

    Attributes
    ----------
    tip
        The tip the curve was fitted with.
    values, errors
        (E* [Pa], z_0 [m], F_0 [N], s_0 [N/m]) and their standard errors, in the order of
        :data:`PARAMETERS`; inf for a parameter the curve does not determine (a singular
        Jacobian, with its warning: e.g. a cone's contact point and baseline when every point
        is in contact, the tip's force then a parabola of z like the baseline's terms).
    correlation
        4 x 4 correlation matrix of the parameters (NaN for an undetermined one).
    E, E_error
        The sample's Young's modulus [Pa] and its standard error, when its Poisson's ratio was
        given (``None`` otherwise).
    z, F, fitted, residuals
        The data sorted by position [m], [N], the model at the data and F - model [N].
    reduced_chi2
        sum(weighted residuals^2)/(N - 4): about 1 when ``sigma`` was the noise's standard
        deviation; the residual variance [N^2] when no ``sigma`` was given.
    weighted
        Whether ``sigma`` was given.
    n_contact
        Number of points in contact (z > z_0).
    max_depth
        Deepest indentation max(z) - z_0 [m].
    warnings
        One sentence per problem found (limits of the chapter's assumptions exceeded, a poorly
        determined contact point, few points in contact).
    model_error
        A sampled tip only (None otherwise): bounds of the shift of each parameter, in the order
        of :data:`PARAMETERS`, that the numerical MDR's error can cause: sum_i |A_ki| eps_i
        |E* Phi_i| / w_i, A = (J^T J)^-1 J^T the linearised least-squares map of the weighted
        data, eps_i the MDR's ``rel_error`` bound of point i (docs/fitting.md, "Measured
        tips").
    fixed
        Names of the parameters held at given values (``fixed_z0``, ``fixed_baseline``): their
        errors are 0 and their correlations NaN; the covariance is that of the free ones.
    """

    tip: _Tip
    values: np.ndarray
    errors: np.ndarray
    correlation: np.ndarray
    E: float | None
    E_error: float | None
    z: np.ndarray
    F: np.ndarray
    fitted: np.ndarray
    residuals: np.ndarray
    reduced_chi2: float
    weighted: bool
    n_contact: int
    max_depth: float
    warnings: tuple[str, ...]
    model_error: np.ndarray | None = None
    fixed: tuple[str, ...] = ()

    def table(self) -> str:
        """The parameters with their standard errors, one per line, in SI units."""
        rows = self._parameter_rows(PARAMETERS, UNITS)
        if self.model_error is not None:
            rows.append(f"the tip's MDR error moves E* by at most {self.model_error[0]:.3g} Pa "
                        f"and z_0 by {self.model_error[1]:.3g} m")
        fit = (f"reduced chi^2 = {self.reduced_chi2:.4g}" if self.weighted else
               f"residuals' std = {np.sqrt(self.reduced_chi2):.4g} N")
        rows.append(f"{fit}, {self.F.size} points, {self.n_contact} in contact, deepest "
                    f"indentation {self.max_depth:.4g} m")
        return "\n".join(rows)


def _curve(z, F, sigma):
    z = as_float("z", z)
    F = as_float("F", F)
    if z.ndim != 1 or F.ndim != 1 or z.size != F.size:
        raise ValueError(f"z and F must be 1-D arrays of the same length; got shapes "
                         f"{z.shape} and {F.shape}")
    if z.size < MIN_POINTS:
        raise ValueError(f"the curve has {z.size} points; at least {MIN_POINTS} are needed "
                         "(four parameters and two degrees of freedom)")
    for name, arr in (("z", z), ("F", F)):
        bad = ~np.isfinite(arr)
        if bad.any():
            i = int(np.argmax(bad))
            raise ValueError(f"{name}[{i}] = {float(arr[i])!r} is out of range; valid: a "
                             "finite number")
    w = np.broadcast_to(positive("sigma", 1.0 if sigma is None else sigma), z.shape)
    order = np.argsort(z, kind="stable")
    z, F, w = z[order], F[order], w[order]
    if not np.ptp(z) > 0:
        raise ValueError(f"z spans no range (every z = {float(z[0])!r}): the curve has one "
                         "position")
    return z, F, w


def _linear_scan(tip, z, F, w, trials):
    """(E*, F_0, s_0) by linear least squares at each trial contact point, and sum(r^2).

    All trials at once: the tip's shape g = dF/dE* as a (trials x points) array and the 3 x 3
    normal equations of the columns (g, 1, u), u = (z - mean z)/ptp(z), each column scaled to
    unit norm (which keeps them well conditioned), solved together; the residuals are then
    computed directly (not from the normal equations, which would lose the small sums of
    squares of a good fit to cancellation). Trials with no point in contact give NaN.
    """
    zc, span = float(z.mean()), float(np.ptp(z))
    Fw = F / w
    c1, c2 = 1 / w, (z - zc) / span / w
    n1, n2 = np.linalg.norm(c1), np.linalg.norm(c2)
    c1, c2 = c1 / n1, c2 / n2
    G = tip.basis(z[None, :], trials[:, None]) / w
    gn = np.linalg.norm(G, axis=1)
    ok = gn > 0
    G /= np.where(ok, gn, 1.0)[:, None]
    g1, g2, c12 = G @ c1, G @ c2, float(c1 @ c2)
    M = np.empty((trials.size, 3, 3))
    M[:, 0] = np.column_stack([np.ones_like(g1), g1, g2])
    M[:, 1] = np.column_stack([g1, np.ones_like(g1), np.full_like(g1, c12)])
    M[:, 2] = np.column_stack([g2, np.full_like(g1, c12), np.ones_like(g1)])
    b = np.column_stack([G @ Fw, np.full_like(g1, c1 @ Fw), np.full_like(g1, c2 @ Fw)])
    M[~ok] = np.eye(3)  # no contact: a dummy system, discarded below
    coef = np.linalg.solve(M, b[..., None])[..., 0]
    res = Fw - coef[:, :1] * G - np.outer(coef[:, 1], c1) - np.outer(coef[:, 2], c2)
    rss = np.einsum("kn,kn->k", res, res)
    E = np.where(ok, coef[:, 0] / np.where(ok, gn, 1.0), np.nan)
    s0 = coef[:, 2] / n2 / span
    F0 = coef[:, 1] / n1 - s0 * zc
    return np.column_stack([E, trials, F0, s0]), np.where(ok, rss, np.nan)


def _start(tip, z, F, w, z0_guess):
    """The best start over trial contact points (and the user's guess): E* > 0, least sum(r^2).

    A scan of N_SCAN points over the curve, then N_REFINE more between the best one's
    neighbours: the start is within 1/(N_SCAN N_REFINE) of the curve's span from the best
    contact point of the linearised problem, and Levenberg-Marquardt finishes in a few steps.
    """
    # trial points leave at least MIN_CONTACT_POINTS points in contact
    lo, hi = z[0] - 0.1 * np.ptp(z), z[-MIN_CONTACT_POINTS - 1]
    trials = np.linspace(lo, hi, N_SCAN)
    if z0_guess is not None:
        trials = np.append(trials, z0_guess)
    if z.size > SCAN_POINTS:  # the start needs the curve's shape, not all of its points
        keep = np.unique(np.r_[np.linspace(0, z.size - 1, SCAN_POINTS).round().astype(int),
                               np.arange(z.size - MIN_CONTACT_POINTS - 1, z.size)])
        z, F, w = z[keep], F[keep], w[keep]
    best = None
    for _ in range(2):
        params, rss = _linear_scan(tip, z, F, w, trials)
        rss = np.where(params[:, 0] > 0, rss, np.inf)
        k = int(np.argmin(rss))
        if np.isfinite(rss[k]) and (best is None or rss[k] < best[1]):
            best = (params[k], rss[k])
        if best is None:
            return None
        step = (hi - lo) / (N_SCAN - 1)
        trials = np.linspace(best[0][1] - step, min(best[0][1] + step, hi), N_REFINE)
    return best[0]


def _no_contact(why: str):
    raise NoContactError(f"no contact in the curve: {why}; check that z increases into the "
                         "sample and F is the force on the tip (positive in compression)")


def _jump(z, r, F):
    """A sentence when the residuals r [N] step between two neighbouring points, else None.

    A jump (a snap-in, the breakthrough of a membrane, a glitch of the instrument) is a change
    of the force between two points that the smooth model cannot follow: a difference of
    neighbouring residuals above JUMP_SIGNIFICANCE times the standard deviation of such
    differences, estimated robustly (1.4826 times their median absolute deviation, which the
    jump itself does not move), and above 1e-6 of the force's range (noise-free curves have
    residuals of rounding size only).
    """
    dr = np.diff(r)
    if dr.size < 3:
        return None
    scale = 1.4826 * float(np.median(np.abs(dr - np.median(dr))))
    k = int(np.argmax(np.abs(dr)))
    size = float(dr[k])
    if abs(size) <= max(JUMP_SIGNIFICANCE * scale, 1e-6 * float(np.ptp(F))):
        return None
    return (f"a jump of the force by {size:.3g} N between z = {z[k]:.6g} m and {z[k + 1]:.6g} "
            f"m ({abs(size) / scale:.3g} times the noise of neighbouring differences): a "
            "snap-in, a breakthrough or a glitch the smooth model cannot follow; the fit is "
            "biased by it (fit the curve on one side of it)")


def _polish(tip, z, F, w, p, free):
    """Gauss-Newton steps from p on the exact model of a tabulated tip (:meth:`SampledTip._exact`):
    (parameters, weighted residuals, bounds of the parameters' shifts by the model's error,
    the model's (dF/dE*, dF/dz_0 at E* = 1) at the returned z_0); ``free`` is the bool mask
    of the fitted parameters (the fixed ones are not moved).

    Each step is -pinv(J) r at the current parameters. The loop ends when the step the last
    evaluation proposes is below POLISH_TOL of every parameter's scale or below POLISH_SIGMA
    of its standard error (the parameters are then that close to the exact model's least
    squares; the step is not taken, so the returned residuals and model are those of the
    returned parameters), or when it stopped shrinking (rounding). The table's error moves p
    by ~1e-11 relative for a smooth tip: two evaluations of the MDR at every point. Gauss-Newton
    converges linearly on noisy curves (a nonzero residual), by ~1e-2 a step: the POLISH_SIGMA
    test then ends it after a step or two. The bound of the model error's effect is
    propagated linearly: |dp_k| <= sum_i |A_ki| |dF_i|/w_i, A = pinv(J), |dF_i| <= rel_error_i
    E* Phi_i the MDR's bound at point i.
    """
    big, last = np.ptp(F) or 1.0, np.inf
    scale = np.array([abs(p[0]), np.ptp(z), big, big / np.ptp(z)])[free]
    for it in range(POLISH_STEPS + 1):
        g, h, eps = tip._exact(z, p[1])
        r = (p[0] * g + p[2] + p[3] * z - F) / w
        J = (np.column_stack([g, p[0] * h, np.ones_like(z), z]) / w[:, None])[:, free]
        norms = np.linalg.norm(J, axis=0)
        norms = np.where(norms > 0, norms, 1.0)
        A = np.linalg.pinv(J / norms) / norms[:, None]
        step = -A @ r
        sigma = np.sqrt(np.einsum("kn,kn->k", A, A) * (r @ r) / max(z.size - free.sum(), 1))
        size = float(np.max(np.abs(step) / scale))
        if (it == POLISH_STEPS or size <= POLISH_TOL or size > last / 4
                or np.all(np.abs(step) <= POLISH_SIGMA * sigma)):
            break  # converged, or at the floor of rounding (the step stopped shrinking)
        p, last = p.copy(), size
        p[free] += step
    bound = np.zeros(len(p))  # a fixed parameter is not moved by the model's error
    bound[free] = np.abs(A) @ (eps * np.abs(p[0] * g) / w)
    return p, r, bound, (g, h)


def _covariance(J):
    """(J^T J)^-1 by the SVD of the column-scaled J, and whether J is of full rank.

    The SVD of the small triangular factor R of J = QR (its singular values are J's): the
    same (J^T J)^-1 = V S^-2 V^T as the SVD of J, at a fraction of its cost for a tall J.
    A singular J (singular values below SINGULAR_TOL of the largest: directions along which
    the model does not change) leaves the parameters with a part along those directions
    undetermined by the curve: their variance is inf and their covariances NaN (the
    pseudo-inverse's finite figure would drop that direction and report an error far below
    the true one); the others keep theirs (the pseudo-inverse's variance of a parameter
    orthogonal to the null space is that of an estimable function, exact).
    """
    norms = np.linalg.norm(J, axis=0)
    norms = np.where(norms > 0, norms, 1.0)
    r = np.linalg.qr(J / norms, mode="r")
    _, s, vt = np.linalg.svd(r)
    keep = s > s[0] * SINGULAR_TOL
    s_inv = np.where(keep, 1 / s, 0.0)
    cov = (vt.T * s_inv**2) @ vt / np.outer(norms, norms)
    loose = np.any(np.abs(vt[~keep]) > NULL_TOL, axis=0)
    cov[loose, :] = np.nan
    cov[:, loose] = np.nan
    cov[loose, loose] = np.inf
    return cov, bool(keep.all())


def _sample_modulus(E_star, err, nu, tip_modulus, tip_nu):
    if nu is None:
        if tip_modulus is not None:
            raise ValueError("tip_modulus is given without nu: the sample's Poisson's ratio is "
                             "needed to compute its Young's modulus")
        return None, None
    nu = float(poisson("nu", nu))
    if tip_modulus is None:  # rigid tip
        return (float(gen.fit_sample_modulus_rigid(E_star, nu)),
                float(abs(gen.fit_sample_modulus_rigid_dE(nu)) * err))
    E2 = float(positive("tip_modulus", tip_modulus))
    nu2 = float(poisson("tip_nu", 0.0 if tip_nu is None else tip_nu))
    if not E_star < E2 / (1 - nu2**2):
        raise ValueError(f"the fitted E* = {E_star:.6g} Pa is not below the tip's own "
                         f"E2/(1 - nu2^2) = {E2 / (1 - nu2**2):.6g} Pa: no sample modulus "
                         "gives it (5.26); is the tip softer than the sample?")
    return (float(gen.fit_sample_modulus(E_star, nu, E2, nu2)),
            float(abs(gen.fit_sample_modulus_dE(E_star, nu, E2, nu2)) * err))


def _fixed_values(fixed_z0, fixed_baseline):
    """(bool mask of the free parameters of PARAMETERS, the fixed values: NaN where free)."""
    vals = np.full(len(PARAMETERS), np.nan)
    if fixed_z0 is not None:
        v = float(np.ravel(as_float("fixed_z0", fixed_z0))[0])
        if np.size(fixed_z0) != 1 or not np.isfinite(v):
            raise ValueError(f"fixed_z0 = {fixed_z0!r} is out of range; valid: one finite "
                             "position [m]")
        vals[1] = v
    if fixed_baseline is not None:
        fb = np.ravel(as_float("fixed_baseline", fixed_baseline))
        if fb.size != 2 or not np.isfinite(fb).all():
            raise ValueError(f"fixed_baseline = {fixed_baseline!r} is out of range; valid: two "
                             "finite numbers (F_0 [N], s_0 [N/m])")
        vals[2:] = fb
    return np.isnan(vals), vals


#: how much worse (in reduced chi^2) the fit with z_0 at the first position may be for the
#: curve not to bound z_0: 9, three standard deviations (a cone on a curve without a baseline,
#: noise 1e-4 to 1e-2 of the force, 8 draws each: 0.03 to 1.1)
Z0_PROFILE = 9.0


def _z0_unbounded(g0, z, F, w, p, free, rss, chi2):
    """Whether the fit with z_0 held at the first position z[0] (the tip's unit force g0
    there) is as good as the best one, p with its weighted residual sum rss: its rss within
    Z0_PROFILE reduced chi^2 (chi2) of the best, z[0] within 3 standard deviations of z_0 on
    its profile. Then ``(True, |E*(z_0 = z[0]) - E*|)``, else None. With z_0 fixed the model
    is linear in the free E*, F_0, s_0: one weighted least-squares solve."""
    cols = [k for k in (0, 2, 3) if free[k]]
    basis = np.stack([g0, np.ones_like(z), z])  # dF/dE*, dF/dF_0, dF/ds_0
    rhs = F - sum(p[k] * basis[(0, 2, 3).index(k)] for k in (0, 2, 3) if not free[k])
    A = (basis[[(0, 2, 3).index(k) for k in cols]] / w).T
    q, *_ = np.linalg.lstsq(A, rhs / w, rcond=None)
    r = A @ q - rhs / w
    if not float(r @ r) - rss <= Z0_PROFILE * chi2:
        return None
    E0 = q[cols.index(0)] if free[0] else p[0]
    return True, abs(float(E0) - float(p[0]))


def fit_curve(z, F, tip: _Tip, *, nu=None, tip_modulus=None, tip_nu=None, z0=None,
              sigma=None, fixed_z0=None, fixed_baseline=None) -> FitResult:
    """Fit the force curve F(z) with a tip's force law, a contact point and a linear baseline.

    Parameters
    ----------
    z : array_like
        Positions of the tip's base [m], increasing into the sample (any order; sorted here),
        the cantilever's deflection subtracted.
    F : array_like
        Force on the tip [N], positive in compression, one per position.
    tip : Paraboloid, ExactSphere, Cone, Pyramid, FlatPunch, PowerLaw or SampledTip
        The tip's shape.
    nu : float, optional
        Poisson's ratio of the sample, -1 < nu <= 0.5: when given, the sample's Young's modulus
        E is reported beside E* ((5.8) for a rigid tip, (5.26) for an elastic one).
    tip_modulus, tip_nu : float, optional
        Young's modulus [Pa] and Poisson's ratio of an elastic tip (default: a rigid tip;
        tip_nu defaults to 0 when only tip_modulus is given).
    z0 : float, optional
        A guess of the contact point [m], added to the scan of trial contact points.
    sigma : float or array_like, optional
        Standard deviation of the force noise [N] (a number, or one per point): the residuals
        are weighted by 1/sigma and the reduced chi^2 is then about 1 for a good fit.
    fixed_z0 : float, optional
        The contact point z_0 [m], held fixed: only the other parameters are fitted.
    fixed_baseline : (float, float), optional
        The baseline (F_0 [N], s_0 [N/m]), held fixed: only E* (and z_0) are fitted.
        With a parameter fixed, the covariance is that of the free parameters (the fixed ones
        have error 0), the reduced chi^2 is over N minus the free parameters.

    Returns
    -------
    FitResult

    Raises
    ------
    NoContactError
        When the curve shows no contact (no contact point gives a positive modulus, or the
        tip's force at the deepest point is below 5 standard deviations of the residuals).
    ValueError
        For invalid input, naming it, its value and the valid range.
    """
    if not isinstance(tip, _Tip):
        raise ValueError(f"tip = {tip!r} is not a tip; valid: Paraboloid, ExactSphere, Cone, "
                         "Pyramid, FlatPunch, PowerLaw or SampledTip of hertzmdr.numeric.fit")
    z, F, w = _curve(z, F, sigma)
    if z0 is not None:
        z0 = float(as_float("z0", z0))
    free, fixed_vals = _fixed_values(fixed_z0, fixed_baseline)
    # a fixed baseline: the start is the scan on the force less it; a fixed contact point:
    # the linear solve at that one point
    F_start = F if free[2] else F - fixed_vals[2] - fixed_vals[3] * z
    if free[1]:
        p0 = _start(tip, z, F_start, w, z0)
    else:
        params, rss = _linear_scan(tip, z, F_start, w, fixed_vals[1:2])
        p0 = params[0] if np.isfinite(rss[0]) and params[0, 0] > 0 else None
    if p0 is None:
        _no_contact("no contact point makes the force rise with a positive modulus")
    p0 = np.where(free, p0, fixed_vals)

    cache, state = {}, {}
    zeros = np.zeros(z.size)

    def unit(z0):  # the tip's shape and its z_0 slope, once per contact point
        if z0 not in cache:
            cache.clear()
            # z is sorted: the points in contact (z > z_0) are its tail, and the tip is
            # evaluated there only (0 before contact: d = max(0, z - z_0))
            k = int(np.searchsorted(z, z0, side="right"))
            g, h = zeros.copy(), zeros.copy()
            if k < z.size:
                g[k:], h[k:] = tip._unit(z[k:], z0, state)
            cache[z0] = (g, h)
        return cache[z0]

    def full(q):  # the four parameters from the free ones
        if free.all():
            return q
        p = fixed_vals.copy()
        p[free] = q
        return p

    def residuals(q):
        p = full(q)
        g, _ = unit(p[1])
        return (p[0] * g + p[2] + p[3] * z - F) / w  # F = E* dF/dE* + F_0 + s_0 z_p

    ones_w, z_w = 1 / w, z / w

    def jacobian_rows(q):  # the Jacobian's transpose (free x N), MINPACK's col_deriv layout
        p = full(q)
        g, h = unit(p[1])
        rows = np.stack([g / w, p[0] * h / w, ones_w, z_w])
        return rows if free.all() else rows[free]

    def jacobian(p):  # all four columns, at the four parameters
        g, h = unit(p[1])
        return np.stack([g / w, p[0] * h / w, ones_w, z_w]).T

    scale = np.array([abs(p0[0]), np.ptp(z), max(np.ptp(F), np.abs(F).max()),
                      max(np.ptp(F), np.abs(F).max()) / np.ptp(z)])
    with np.errstate(invalid="ignore"):  # numpy.select evaluates both branches of a Piecewise
        # MINPACK's lmder through scipy's leastsq: the same Levenberg-Marquardt as
        # least_squares(method="lm"), without its per-call wrappers (~1 ms of a 5 ms fit)
        q, _, info, _, _ = leastsq(residuals, p0[free], Dfun=jacobian_rows, col_deriv=True,
                                   full_output=True, xtol=1e-15, ftol=FTOL, gtol=1e-15,
                                   maxfev=2000, diag=1 / scale[free])
    p = full(np.atleast_1d(q))
    res = residuals(p[free])
    model_error = None
    if tip.tabulated:  # Levenberg-Marquardt ran on the tip's table: finish on the exact MDR
        p, res, model_error, exact = _polish(tip, z, F, w, p, free)
        cache.clear()
        cache[p[1]] = exact
    dof = z.size - int(free.sum())
    chi2 = float(res @ res) / dof
    d = z - p[1]
    n_contact = int((d > 0).sum())
    if not p[0] > 0 or n_contact < MIN_CONTACT_POINTS:
        _no_contact(f"the best fit has E* = {p[0]:.3g} Pa and {n_contact} point(s) in contact")
    d_max = float(d[-1])
    g_fit, _ = unit(p[1])
    tip_force = float(p[0] * g_fit[-1])
    # the residuals' spread, but not below the forces' own rounding: a noise-free curve can fit
    # to zero residuals (a straight line, with an E* ~ 1e-12 Pa whose force is below rounding)
    noise = max(np.sqrt(chi2) * float(w[-1]), np.finfo(float).eps * float(np.abs(F).max()))
    if tip_force < CONTACT_SIGNIFICANCE * noise:
        _no_contact(f"the tip's force at the deepest point, {tip_force:.3g} N, is below "
                    f"{CONTACT_SIGNIFICANCE:g} standard deviations of the residuals "
                    f"({noise:.3g} N)")
    cov = np.zeros((len(PARAMETERS), len(PARAMETERS)))  # the fixed parameters' rows: 0
    cov_free, full_rank = _covariance(jacobian(p)[:, free])
    # an undetermined parameter's variance stays inf (not inf * 0 = NaN on a curve fitted to
    # zero residuals)
    cov[np.ix_(free, free)] = np.where(np.isinf(cov_free), np.inf, cov_free * chi2)
    err = np.sqrt(np.diag(cov))
    unbounded = free[1] and p[1] >= z[0] and _z0_unbounded(unit(z[0])[0], z, F, w, p, free,
                                                           float(res @ res), chi2)
    if unbounded:
        # the curve does not bound z_0 from below: the local covariance, regular where z_0
        # sits among the first points, is then far too small (a cone on a curve without a
        # baseline: 45 of its sigma off). z_0 and the baseline, which trades with it, get
        # error inf; E* at least its change between the best fit and that with z_0 at z[0]
        for k in (1, 2, 3):
            if free[k]:  # as an undetermined parameter: variance inf, covariances NaN
                cov[k, :] = cov[:, k] = np.nan
                cov[k, k] = np.inf
        err = np.sqrt(np.diag(cov))
        err[0] = max(err[0], unbounded[1]) if free[0] else err[0]
    if not p[0] >= MODULUS_SIGNIFICANCE * err[0]:
        _no_contact(f"the fitted E* = {p[0]:.3g} Pa is below {MODULUS_SIGNIFICANCE:g} of its "
                    f"standard errors ({err[0]:.3g} Pa)")
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(err, err)
    warn = [w_["message"] for w_ in check_assumptions(tip.ratios(d_max))]
    if not full_rank:
        warn.append("the Jacobian is singular: the parameters are not all determined by the "
                    "curve (their errors are not meaningful)")
    if err[1] > Z0_POOR * d_max:
        warn.append(f"contact point poorly determined: sigma(z_0) = {err[1]:.3g} m is "
                    f"{100 * err[1] / d_max:.3g} % of the deepest indentation {d_max:.3g} m")
    if unbounded:
        warn.append(f"contact point not bounded by the curve: with z_0 at the first position "
                    f"{z[0]:.6g} m the fit is as good (chi^2 within {Z0_PROFILE:g} of its "
                    "least), so z_0 may lie anywhere before it and the baseline with it (their "
                    "errors: inf)")
    if p[1] < z[0]:
        warn.append(f"the contact point z_0 = {p[1]:.6g} m lies before the first position "
                    f"{z[0]:.6g} m: the baseline before contact is not measured")
    jump = _jump(z, -res * w, F)  # F - model
    if jump is not None:
        warn.append(jump)
    E, E_err = _sample_modulus(float(p[0]), float(err[0]), nu, tip_modulus, tip_nu)
    fitted = p[0] * g_fit + p[2] + p[3] * z  # = tip.force(p..) (asserted in derive/fit.py)
    return FitResult(tip=tip, values=p, errors=err, correlation=corr, E=E, E_error=E_err,
                     z=z, F=F, fitted=fitted, residuals=F - fitted, reduced_chi2=chi2,
                     weighted=sigma is not None,
                     n_contact=n_contact, max_depth=d_max, warnings=tuple(warn),
                     model_error=model_error,
                     fixed=tuple(n for n, f in zip(PARAMETERS, free, strict=True) if not f))
