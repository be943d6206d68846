"""Fit an adhesive retract curve F(z_p) for E*, the contact point and the work of adhesion: the
paraboloid (JKR), the cone, the exact sphere, the power law or a sampled (measured) tip.

The model (generated from :func:`hertzmdr.derive.fit.jkr_model`, itself from the MDR's adhesive
paraboloid in :mod:`hertzmdr.derive.adhesion`) is parametric in the contact radius a:

    d(a) = z_p - z_0 = jkr_depth(E*, R, a, Delta gamma),
    F(z_p) = jkr_force_from_radius(E*, R, a, Delta gamma) + F_0 + s_0 z_p,

with z_p the position of the tip's base (increasing into the sample, the cantilever's
deflection subtracted) and F_0 + s_0 z_p the baseline of the free cantilever. Five parameters:
E* [Pa], z_0 [m] (the depth d = 0: where the non-adhesive Hertz contact would start),
Delta gamma >= 0 [J/m^2], F_0 [N], s_0 [N/m]. The generated relations are written in
rho_g = sqrt(Delta gamma); dF/dDelta gamma is finite at Delta gamma = 0 (-pi R), so the fit
runs in Delta gamma itself, bounded below by 0.

Which branch, and where it jumps off. A displacement-controlled retract (a stiff cantilever:
the position, hence d, is prescribed) follows the equilibrium branch that is stable under depth
control, dd/da > 0, i.e. a > a_dc = (pi Delta gamma R^2/(8 E*))^(1/3)
(``jkr_pull_off_radius_dc``): past the force minimum -3 pi R Delta gamma/2 (force-controlled
pull-off, a_fc) it keeps its contact while the force rises again, and it jumps off at
a_dc, d_dc = ``jkr_pull_off_depth_dc`` < 0, F_dc = -5 pi R Delta gamma/6, to the free
cantilever's baseline. A softer cantilever jumps earlier (between a_fc and a_dc); either way the
points still in contact lie on this branch. For every position a is solved from d on the
branch a >= a_dc by Newton's method (d(a) is convex and increasing there, so Newton's iteration
from above converges monotonically; linearly only next to a_dc, where dd/da = 0).

The curve is split at its jump-off, found in the data (the largest downward step of F towards
positive z, significant against the noise and against the neighbouring steps): the points
before it (z below the step: the free cantilever) are fitted with the baseline only, the points
after it with the JKR model. A point of the contact part whose depth at the fitted parameters
lies below d_dc (past the jump-off, where no equilibrium exists) is excluded with a warning and
the fit repeated. Without a jump in the data (no visible adhesion, or the retract recorded
only in contact) a point is in contact where d >= d_dc and on the baseline elsewhere.

The cone (theta [rad] between its surface and the plane) is the same fit on the cone's
adhesive relations (:func:`hertzmdr.derive.fit.adhesive_cone_model`, from the MDR's adhesive
cone: d(a) = (pi/2) a tan(theta) - Delta l, ``fit_adhesive_cone_*``): its branch stable under
depth control is again a > a_dc (``adhesion_cone_pull_off_radius_dc``), and every step below
runs on a :class:`_Family` of the tip's generated relations. The exact sphere
(``fit_adhesive_sphere_*``, from the cap's g(x) = x atanh(x/R) through the adhesive MDR;
:func:`hertzmdr.derive.fit.adhesive_sphere_model`) and the power law c_n r^n, n > 1/2
(``fit_adhesive_powerlaw_*``, from :func:`hertzmdr.derive.adhesion.power`) are the same fit
again; the sphere's a_dc has no closed form and is the root of its generated dd/da
(:func:`_sphere_pull_off_radius`), and its contact radius stays below R. A sampled tip
(:class:`hertzmdr.numeric.fit.SampledTip`) runs on the relations of any MDR profile
(``fit_adhesive_sampled_*``, :func:`hertzmdr.derive.fit.adhesive_general_model`: g(a), g'(a)
and G(a) as arguments), evaluated with its numerical MDR's g, g' and G
(:func:`_sampled_family`); its contact radius stays below the samples' r_max.

Method: at a fixed kappa = rho_g/sqrt(E*) the model is E* times a shape of (z - z_0) (asserted
in derive/fit.py), so a scan over (z_0, kappa) solves (E*, F_0, s_0) by linear least squares
(:func:`hertzmdr.numeric.fit._linear_scan`) and gives a start without a guess; then
Levenberg-Marquardt (MINPACK; :func:`scipy.optimize.least_squares`'s 'trf' with the bound
Delta gamma >= 0 when it ends below 0, and the fit at Delta gamma = 0 itself when it ends next
to it) of all five parameters with the generated Jacobian (implicit differentiation, derived
by SymPy). The standard errors are those of :mod:`~.fit`: the linearised covariance times the
residual variance.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq, least_squares

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import fit as _fit
from hertzmdr.numeric._validate import as_float

__all__ = ["AdhesiveFitResult", "JKRTip", "fit_curve", "contact_radius", "PARAMETERS", "UNITS"]

#: names of the reported parameters, in the order of :attr:`AdhesiveFitResult.values`
PARAMETERS = ("E_star", "z_0", "dgamma", "F_0", "s_0")
#: their SI units
UNITS = ("Pa", "m", "J/m^2", "N", "N/m")
#: fewest points: five parameters and two degrees of freedom
MIN_POINTS = 7
#: most Newton steps for a (4-6 suffice; a bisection step each at worst)
A_MAX_STEPS = 80
#: trial contact points and trial kappa of the start scan, then of its refinement
N_SCAN_Z0, N_SCAN_KAPPA, N_REFINE = 32, 12, 8
#: refinements of the start scan, each between the best trial's neighbours of the last grid
REFINE_ROUNDS = 1
#: local minima of the coarse (z_0, kappa) grid refined, the lowest first (the cone's steep
#: jump-off makes the valley of the truth narrow in (z_0, kappa): its nearest grid point can
#: lie above another basin's minimum, and refining the lowest point only left starts that
#: Levenberg-Marquardt could not recover from on noise-free curves of 100-300 points)
START_CANDIDATES = 3
#: points of the curve the start scans use at most (evenly spread, the deepest ones kept)
SCAN_POINTS = 128
#: the trial kappa give jump-off depths |d_dc| between these fractions of the curve's span
KAPPA_SPAN = (1e-4, 1.0)
#: a downward step of F is the jump-off when it exceeds this many robust standard deviations of
#: the neighbouring differences ...
JUMP_SIGNIFICANCE = 8.0
#: ... and this many times the largest of the 2 steps on either side of it (the smooth curve's
#: own steps, steepest next to the vertical tangent at d_dc, stay below)
JUMP_NEIGHBOURS = 4.0
#: a fitted Delta gamma below this fraction of its scale (its pull-off force = the force range)
#: is compared with the fit on the bound Delta gamma = 0
NEAR_BOUND = 1e-3
#: refits after excluding points past the jump-off
MAX_EXCLUDE_ROUNDS = 4
#: the held fits' tolerances and most evaluations (each stage): a chi^2 compared within
#: fit.Z0_PROFILE needs no more (the best fit's 1e-15 and 2000 cost up to 2 s a held fit where
#: the unbounded Levenberg-Marquardt wanders below Delta gamma = 0 before 'trf' takes over)
PROFILE_TOL, PROFILE_NFEV = 1e-8, 200
#: where the data hold no jump-off, the contact point z_0 is held at z[0] minus these
#: multiples of the positions' span (0: the first position; negative: inside the data) to see
#: whether the curve bounds it (:func:`_z0_unbounded`; fit.Z0_PROFILE the criterion). On JKR
#: curves all in contact (200 points, noise 1 % of the pull-off force) the linearised errors
#: had put the truth 5 to 470 standard errors away; with this profile the truth was within 1.0
#: of E*'s error on 8 draws of each of two cuts (d from d_dc/2 and from -d_dc/2)
Z0_PROFILE_SPANS = (-0.5, -0.375, -0.25, -0.125, 0.0, 0.25, 0.5, 1.0, 2.0)

_EPS = float(np.finfo(float).eps)


@dataclass(frozen=True)
class _Family:
    """One adhesive tip's generated relations (derive/fit.py), all at the tip's geometry
    ``shape`` (a tuple: (R [m],) of the paraboloid and the exact sphere, (theta [rad],) of the
    cone, (c_n, kappa_n, n) of the power law): the depth d(E*, a, rho), its slope dd/da, the
    force F(E*, a, rho) and its three derivatives at a fixed position, the depth-controlled
    pull-off radius a_dc(E*, Delta gamma) and force F_dc(E*, Delta gamma), and the contact
    radius without adhesion a(d) (a start for Newton's iteration)."""

    name: str
    shape: tuple
    depth: object
    depth_da: object
    force: object
    dE: object
    dz0: object
    ddgamma: object
    a_dc: object
    F_dc: object
    a_plain: object
    #: a length of the geometry [m]: the floor of a's bracket (R; 1 m for the cone, scale-free)
    length: float
    #: the largest contact radius [m] (R of the exact sphere, r_max of a sampled tip; inf for
    #: the others)
    a_max: float = np.inf
    #: a cheaper family for the start's scan (a sampled tip's interpolated tables), or None
    scan: object = None

    def ratios(self, a_max: float) -> dict[str, float]:
        """The chapter's limit ratios at the largest contact radius a_max [m]."""
        if self.name in ("paraboloid", "exact sphere"):
            return {"a/R": a_max / self.shape[0]}
        if self.name == "sampled tip":  # its range is checked against r_max (fit_curve)
            return {}
        if self.name == "power law":  # d/a of the non-adhesive state at a_max
            return {"d/a": float(self.depth(1.0, a_max, 0.0)) / a_max}
        return {"tan(theta)": float(np.tan(self.shape[0]))}


def _generated_family(name, shape, fit, pull_off, a_plain, length, a_max=np.inf) -> _Family:
    """The _Family of the generated fit_<fit>_* relations at the geometry ``shape`` (a tuple of
    the relations' geometry arguments); ``pull_off``: the prefix of the generated
    <pull_off>_pull_off_{radius,force}_dc, or a pair of functions (E*, Delta gamma) -> a_dc
    and -> F_dc; ``a_plain``(d) is the contact radius without adhesion."""
    def at_shape(fn, baseline=False):
        if baseline:  # the force without its baseline F_0 + s_0 z_p
            return lambda E, a, rho: fn(E, *shape, a, rho, 0.0, 0.0, 0.0)
        return lambda E, a, rho: fn(E, *shape, a, rho)

    rel = {k: getattr(gen, f"fit_{fit}_{k}")
           for k in ("depth", "depth_da", "force", "force_dE", "force_dz0", "force_ddgamma")}
    if isinstance(pull_off, str):
        radius_dc = getattr(gen, f"{pull_off}_pull_off_radius_dc")
        force_dc = getattr(gen, f"{pull_off}_pull_off_force_dc")
        a_dc = lambda E, dg: radius_dc(E, dg, *shape)  # noqa: E731
        F_dc = lambda E, dg: force_dc(E, dg, *shape)  # noqa: E731
    else:
        a_dc, F_dc = pull_off
    return _Family(name, shape, at_shape(rel["depth"]), at_shape(rel["depth_da"]),
                   at_shape(rel["force"], baseline=True), at_shape(rel["force_dE"]),
                   at_shape(rel["force_dz0"]), at_shape(rel["force_ddgamma"]),
                   a_dc, F_dc, a_plain, length, a_max)


def _sphere_pull_off_radius(E_star, dgamma, R):
    """a_dc [m] of the adhesive exact sphere of radius R [m]: the root of dd/da = 0
    (``fit_adhesive_sphere_depth_da``; no closed form), vectorized over Delta gamma [J/m^2].

    dd/da = g'(a) - Delta l/(2 a) increases with a (g' increases, Delta l/a ~ a^(-1/2)
    falls), from -inf at a -> 0 to +inf at a -> R: one root. The cap's g'(a) >= 2a/R, the
    paraboloid's, so the root lies below the JKR a_dc (``jkr_pull_off_radius_dc``), and below
    R; bisection in log a from [1e-12, 1] of that bound (1e-16 of a in 64 steps). 0 for
    Delta gamma <= 0 (no adhesion: no pull-off).
    """
    dg = np.asarray(dgamma, float)
    if dg.ndim == 0:
        return _sphere_pull_off_radius_one(float(E_star), float(dg), float(R))
    rho = np.sqrt(np.maximum(dg, 0.0))
    hi = np.minimum(gen.jkr_pull_off_radius_dc(E_star, np.maximum(dg, 0.0), R),
                    R * (1 - 2 * _EPS))
    lo = hi * 1e-12
    for _ in range(64):
        mid = np.sqrt(lo * hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            neg = gen.fit_adhesive_sphere_depth_da(E_star, R, mid, rho) < 0
        lo, hi = np.where(neg, mid, lo), np.where(neg, hi, mid)
    out = np.where(dg > 0, np.sqrt(lo * hi), 0.0)
    return out if out.ndim else float(out)


@lru_cache(maxsize=256)
def _sphere_pull_off_radius_one(E_star, dgamma, R):
    """:func:`_sphere_pull_off_radius` at one Delta gamma: Brent's method on the same bracket
    (to 4 ulp of a), remembered (a fit asks for the same (E*, Delta gamma) many times)."""
    if not dgamma > 0:
        return 0.0
    rho = np.sqrt(dgamma)
    hi = min(float(gen.jkr_pull_off_radius_dc(E_star, dgamma, R)), R * (1 - 2 * _EPS))

    def slope(a):
        return float(gen.fit_adhesive_sphere_depth_da(E_star, R, a, rho))

    if not slope(hi) > 0:  # the root is the bound itself (to rounding)
        return hi
    return float(brentq(slope, hi * 1e-12, hi, xtol=1e-300, rtol=4 * _EPS))


#: contact radii of a sampled tip's tables: geometric from this fraction of r_max to r_max
SAMPLED_A_FLOOR = 1e-6
#: ... this many (the pull-off's bracket, a(d) without adhesion, the start scan's tables)
SAMPLED_GRID = 600


def _sampled_family(tip) -> _Family:
    """The adhesive family of a :class:`hertzmdr.numeric.fit.SampledTip`: the generated
    ``fit_adhesive_sampled_*`` (derive/fit.py's :func:`adhesive_general_model`, any g) at the
    tip's g(a) (5.52), g'(a) and G(a) = integral_0^a g of its numerical MDR
    (:class:`hertzmdr.numeric.adhesion.Sampled`: one quadrature of the profile's spline for all
    three; g' is the quadrature's own derivative, not a finite difference), at every contact
    radius a <= r_max asked for.

    The pull-off radius a_dc is the first root of dd/da = g'(a) - Delta l/(2a) from a -> 0 (where
    Delta l/(2a) ~ a^(-1/2) wins): bracketed on a geometric grid of SAMPLED_GRID radii from
    SAMPLED_A_FLOOR r_max to r_max, then Brent's method at one Delta gamma (linear
    interpolation between the grid's radii for arrays of Delta gamma: the start's scales only);
    r_max when dd/da < 0 up to r_max (no pull-off within the samples). The start's scan runs on
    ``scan``: the same relations on cubic Hermite interpolants of g (slopes g') and G (slopes g)
    on that grid, g' their derivative (an approximation for the start only; Levenberg-Marquardt
    and the reported Jacobian use the quadrature at every point).
    """
    from scipy.interpolate import CubicHermiteSpline

    from hertzmdr.numeric import adhesion

    shape = adhesion.Sampled(tip.profile)
    r_max = float(tip.profile.r_max)
    grid = np.geomspace(SAMPLED_A_FLOOR * r_max, r_max, SAMPLED_GRID)
    g_grid, gp_grid, G_grid = (np.asarray(v, float) for v in shape._tables(grid))
    g_spl = CubicHermiteSpline(np.r_[0.0, grid], np.r_[0.0, g_grid], np.r_[gp_grid[0], gp_grid])
    G_spl = CubicHermiteSpline(np.r_[0.0, grid], np.r_[0.0, G_grid], np.r_[0.0, g_grid])
    gp_spl = g_spl.derivative()
    rel = {k: getattr(gen, f"fit_adhesive_sampled_{k}")
           for k in ("depth", "depth_da", "force", "force_dE", "force_dz0", "force_ddgamma")}

    def exact(a):
        a = np.minimum(a, r_max)
        if a.size == 0:  # no point in contact (the quadrature takes no empty array)
            return a, a, a
        return shape._tables(a)

    def interpolated(a):
        a = np.clip(a, 0.0, r_max)
        return g_spl(a), gp_spl(a), G_spl(a)

    def bind(tables, fn, baseline=False):
        if baseline:  # the force without its baseline F_0 + s_0 z_p
            return lambda E, a, rho: fn(E, *tables(a), a, rho, 0.0, 0.0, 0.0)
        return lambda E, a, rho: fn(E, *tables(a), a, rho)

    @lru_cache(maxsize=256)
    def a_dc_one(E, dg):
        if not dg > 0:
            return 0.0
        rho = np.sqrt(dg)
        slope = rel["depth_da"](E, g_grid, gp_grid, G_grid, grid, rho)
        k = int(np.argmax(slope > 0)) if (slope > 0).any() else grid.size
        if k == grid.size:
            return r_max
        lo = grid[k - 1] if k else grid[0] * SAMPLED_A_FLOOR

        def f(a):
            return float(rel["depth_da"](E, *exact(np.array([a])), a, rho)[0])

        if not (f(lo) < 0 < f(grid[k])):  # the grid's sign at the quadrature's rounding
            return float(grid[k])
        return float(brentq(f, lo, grid[k], xtol=1e-300, rtol=4 * _EPS))

    def a_dc(E, dg):
        dg_arr = np.asarray(dg, float)
        if dg_arr.ndim == 0:
            return a_dc_one(float(E), float(dg_arr))
        rho = np.sqrt(np.maximum(dg_arr, 0.0))[:, None]
        slope = rel["depth_da"](E, g_grid, gp_grid, G_grid, grid, rho)
        pos = slope > 0
        k = np.where(pos.any(axis=1), np.argmax(pos, axis=1), grid.size - 1)
        k = np.maximum(k, 1)
        rows = np.arange(dg_arr.size)
        s0, s1 = slope[rows, k - 1], slope[rows, k]
        t = np.clip(np.where(s1 > s0, -s0 / (s1 - s0), 1.0), 0.0, 1.0)
        out = grid[k - 1] + t * (grid[k] - grid[k - 1])
        return np.where(dg_arr > 0, out, 0.0)

    def F_dc(E, dg):
        a_c = a_dc(E, dg)
        rho = np.sqrt(np.maximum(dg, 0.0))
        return rel["force"](E, *interpolated(a_c), a_c, rho, 0.0, 0.0, 0.0)

    def a_plain(d):  # g is increasing: a(d) without adhesion, by the grid
        return np.interp(d, np.r_[0.0, g_grid], np.r_[0.0, grid])

    def family(tables, scan=None):
        return _Family("sampled tip", (), bind(tables, rel["depth"]),
                       bind(tables, rel["depth_da"]), bind(tables, rel["force"], True),
                       bind(tables, rel["force_dE"]), bind(tables, rel["force_dz0"]),
                       bind(tables, rel["force_ddgamma"]), a_dc, F_dc, a_plain, r_max,
                       a_max=r_max, scan=scan)

    return family(exact, scan=family(interpolated))


def _family(tip) -> _Family:
    """The adhesive relations of a Paraboloid (JKR), a Cone, an ExactSphere or a PowerLaw tip
    of numeric/fit.py."""
    if isinstance(tip, _fit.Paraboloid):
        R = tip.R
        return _generated_family("paraboloid", (R,), "jkr", "jkr",
                                 lambda d: gen.hertz_contact_radius(R, d), R)
    if isinstance(tip, _fit.ExactSphere):
        R = tip.R

        def a_dc(E, dg):
            return _sphere_pull_off_radius(E, dg, R)

        def F_dc(E, dg):
            a_c = a_dc(E, dg)
            return gen.fit_adhesive_sphere_force(E, R, a_c, np.sqrt(np.maximum(dg, 0.0)),
                                                 0.0, 0.0, 0.0)

        def a_plain(d):
            return gen.sphere_lam_contact_radius(R, _fit.lam_from_depth(d, R))

        return _generated_family("exact sphere", (R,), "adhesive_sphere", (a_dc, F_dc),
                                 a_plain, R, a_max=R)
    if isinstance(tip, _fit.SampledTip):
        return _sampled_family(tip)
    if isinstance(tip, _fit.PowerLaw):
        geo = (tip.c_n, tip.kappa_n, tip.n)
        return _generated_family(
            "power law", geo, "adhesive_powerlaw", "adhesion_powerlaw",
            lambda d: gen.powerlaw_contact_radius(geo[0], d, geo[1], geo[2]), 1.0)
    th = tip.theta
    return _generated_family("cone", (th,), "adhesive_cone", "adhesion_cone",
                             lambda d: gen.cone_contact_radius(d, th), 1.0)


def _jump_off_radius(E_star, fam, rho):
    """(a_dc [m], d_dc [m]): the depth-controlled pull-off; (0, 0) for rho <= 0 (no adhesion)."""
    if not rho > 0:
        return 0.0, 0.0
    a_c = float(fam.a_dc(E_star, rho * rho))
    return a_c, float(fam.depth(E_star, a_c, rho))


def _dgamma_scale(fam, E_star, force):
    """Delta gamma [J/m^2] whose depth-controlled pull-off force is ``force`` [N] at E* [Pa]:
    interpolated in log-log on a grid of the generated F_dc (a power of Delta gamma)."""
    grid = np.logspace(-15, 8, 120)
    Fc = np.abs(fam.F_dc(E_star, grid))
    return float(np.exp(np.interp(np.log(force), np.log(Fc), np.log(grid))))


def contact_radius(d, R, E_star, rho):
    """Contact radius a [m] of the JKR paraboloid of radius R [m] on the branch stable under
    depth control (dd/da > 0) at the depths d [m] (vectorized); NaN where there is no such
    state (d < d_dc, past the jump-off; d <= 0 without adhesion). E* [Pa] > 0;
    rho = sqrt(Delta gamma) [(J/m^2)^(1/2)] >= 0. (:func:`_contact_radius` for any family.)"""
    return _contact_radius(d, _family(_fit.Paraboloid(R=R)), E_star, rho)


def _contact_radius(d, fam, E_star, rho):
    """Contact radius a [m] of the family ``fam`` on the branch stable under depth control
    (dd/da > 0) at the depths d [m]; NaN where there is no such state.

    Newton's method on phi(a) = sqrt(d(a) - d_dc) - sqrt(d - d_dc), d(a) = ``fit_jkr_depth``
    (``fit_adhesive_cone_depth``), phi' = dd/da/(2 sqrt(d(a) - d_dc)): at the fold a_dc,
    d(a) - d_dc grows as (a - a_dc)^2, so Newton on d(a) itself slows to one bit per step
    there, while phi is about linear in a from the fold (sqrt(d''/2) (a - a_dc)) to deep
    contact (a/sqrt(R) for the paraboloid; sqrt(a) for the cone, still 4-8 steps). The steps
    stay inside the bracket [a_dc, a_hi] (d(a_hi) >= d, found by doubling), a step out of it is
    a bisection step, so the iteration cannot diverge. Near the fold a is determined only to
    ~sqrt(eps) of a by the data (d is flat in a there), whatever the method.
    """
    d = np.asarray(d, float)
    a_c, d_c = _jump_off_radius(E_star, fam, rho)
    out = np.full(d.shape, np.nan)
    on = d >= d_c if rho > 0 else d > 0
    dd = d[on]
    hi = np.maximum(fam.a_plain(np.maximum(dd, 0.0)), a_c)
    hi = np.where(hi > 0, hi, np.maximum(a_c, fam.length * _EPS))
    for _ in range(200):  # double until above the root: d(hi) >= d
        low = fam.depth(E_star, hi, rho) < dd
        if not low.any():
            break
        hi = np.where(low, np.minimum(2 * hi, 0.5 * (hi + fam.a_max)), hi)  # a < a_max
        if fam.scan is not None and (hi[low] >= fam.a_max * (1 - 1e-9)).all():
            break  # a sampled tip: depths beyond its samples (fit_curve refuses them)
    lo = np.full(dd.shape, a_c)
    target = np.sqrt(dd - d_c)
    a = hi.copy()
    idx = np.arange(dd.size)  # the points still iterating
    for _ in range(A_MAX_STEPS):
        ai, lo_i, hi_i, t_i, d_i = a[idx], lo[idx], hi[idx], target[idx], dd[idx]
        depth = fam.depth(E_star, ai, rho)
        D = np.maximum(depth - d_c, 0.0)
        f = np.sqrt(D) - t_i
        # f at the rounding of d(a) - d_dc (4 ulp of each term): a is as good as the data
        # make it (at the fold only to ~sqrt(eps)); such a point stops here
        err = 4 * _EPS * (np.abs(depth) + abs(d_c) + np.abs(d_i))
        going = np.abs(f) > err / (np.sqrt(D) + np.sqrt(err))
        lo_i = np.where(f < 0, ai, lo_i)
        hi_i = np.where(f > 0, ai, hi_i)
        with np.errstate(divide="ignore", invalid="ignore"):
            new = ai - f * 2 * np.sqrt(D) / fam.depth_da(E_star, ai, rho)
        new = np.where(np.isfinite(new) & (new >= lo_i) & (new <= hi_i), new,
                       0.5 * (lo_i + hi_i))
        new = np.where(going, new, ai)
        going &= np.abs(new - ai) > 2 * _EPS * new
        a[idx], lo[idx], hi[idx] = new, lo_i, hi_i
        idx = idx[going]
        if idx.size == 0:
            break
    out[on] = a
    return out


@dataclass(frozen=True)
class _Layout:
    """Which points the JKR model covers: the data's jump-off split and the excluded points."""

    z_split: float  # points with z >= z_split may be in contact (-inf: no jump in the data)
    keep: np.ndarray  # bool per point: used in the fit


def _find_jump_off(z, F):
    """(z of the first point after the jump-off, the step [N]) or None: the largest downward step
    F[k+1] - F[k] < 0 (z sorted ascending) that exceeds JUMP_SIGNIFICANCE robust standard
    deviations of the differences, JUMP_NEIGHBOURS times its neighbouring steps, and 1e-6 of
    the force's range (noise-free curves)."""
    dF = np.diff(F)
    if dF.size < 5:
        return None
    k = int(np.argmin(dF))
    step = float(dF[k])
    if not step < 0:
        return None
    ddF = np.diff(dF)  # the noise of differences, robustly: the smooth part's trend removed
    scale = 1.4826 * float(np.median(np.abs(ddF - np.median(ddF)))) / np.sqrt(2)
    near = np.r_[dF[max(k - 2, 0):k], dF[k + 1:k + 3]]
    if abs(step) <= max(JUMP_SIGNIFICANCE * scale, 1e-6 * float(np.ptp(F)),
                        JUMP_NEIGHBOURS * float(np.abs(near).max(initial=0.0))):
        return None
    return float(z[k + 1]), step


def _tip_state(d, side, split, fam, E_star, rho):
    """(a [m]: NaN off contact, past: bool, the tip's force [N] without baseline) at the depths
    d [m] (any shape). ``side``: the points after the data's jump-off (all when ``split`` is
    False). Past the jump-off (side, d < d_dc, with a split) the force is clamped at F(a_dc),
    the value the iterations use before such points are excluded."""
    if not E_star > 0:  # a trial step of the optimizer to E* <= 0: no contact (no state)
        return np.full(np.shape(d), np.nan), np.zeros(np.shape(d), bool), np.zeros(np.shape(d))
    a = np.where(side, _contact_radius(d, fam, E_star, rho), np.nan)
    a_c, d_c = _jump_off_radius(E_star, fam, rho)
    past = side & (d < d_c) if split else np.zeros(np.shape(d), bool)
    force = np.zeros(np.shape(d))
    on = np.isfinite(a)
    force[on] = fam.force(E_star, a[on], rho)
    if past.any():
        force[past] = float(fam.force(E_star, a_c, rho))
    return a, past, force


class _Model:
    """The JKR model of a layout at one (E*, z_0, rho): a, the tip's force, the derivatives."""

    def __init__(self, fam, z, layout):
        self.fam, self.z, self.layout = fam, z, layout
        self.split = bool(np.isfinite(layout.z_split))
        self.side = z >= layout.z_split
        self._key, self._val = None, None

    def state(self, E_star, z0, dgamma):
        """(a per point, the points past the jump-off, the tip's force per point)."""
        key = (E_star, z0, dgamma)
        if key != self._key:
            self._key = key
            rho = np.sqrt(max(dgamma, 0.0))
            self._val = _tip_state(self.z - z0, self.side, self.split, self.fam, E_star, rho)
        return self._val

    def tip_force(self, E_star, z0, dgamma):
        """The tip's force [N] per point (no baseline)."""
        return self.state(E_star, z0, dgamma)[2]

    def jacobian(self, E_star, z0, dgamma):
        """(dF/dE*, dF/dz_0, dF/dDelta gamma) per point (0 off contact, past the jump-off)."""
        a = self.state(E_star, z0, dgamma)[0]
        rho = np.sqrt(max(dgamma, 0.0))
        J = np.zeros((self.z.size, 3))
        on = np.isfinite(a) & (a > 0)
        if on.any():
            ao = a[on]
            with np.errstate(divide="ignore", invalid="ignore"):  # dd/da = 0 exactly at a_dc
                J[on, 0] = self.fam.dE(E_star, ao, rho)
                J[on, 1] = self.fam.dz0(E_star, ao, rho)
                J[on, 2] = self.fam.ddgamma(E_star, ao, rho)
        return np.where(np.isfinite(J), J, 0.0)


class _ScanTip:
    """Adapter for :func:`hertzmdr.numeric.fit._linear_scan`: the model's shape F/E* at one
    kappa = rho/sqrt(E*) (E* = 1) for all trial contact points at once."""

    def __init__(self, fam, layout, kappa):
        self.fam, self.layout, self.kappa = fam, layout, kappa

    def basis(self, z, z0):
        d = z - z0
        side = np.broadcast_to(z >= self.layout.z_split, d.shape)
        split = bool(np.isfinite(self.layout.z_split))
        return _tip_state(d, side, split, self.fam, 1.0, self.kappa)[2]


def _kappas(fam, span):
    """Trial kappa [m^(1/2)]: 0 and N_SCAN_KAPPA values whose jump-off depths |d_dc| spread
    log-evenly over KAPPA_SPAN of the curve's span (d_dc from the generated relations)."""
    grid = np.logspace(-12, 4, 400)
    depth = -fam.depth(1.0, fam.a_dc(1.0, grid**2), grid)
    lo, hi = KAPPA_SPAN[0] * span, KAPPA_SPAN[1] * span
    target = np.geomspace(lo, hi, N_SCAN_KAPPA)
    return np.r_[0.0, np.interp(np.log(target), np.log(depth), grid)]


def _start(fam, z, F, w, layout, z0_guess):
    """The best (E*, z_0, Delta gamma, F_0, s_0) of a scan over trial (z_0, kappa), each solved for
    (E*, F_0, s_0) by linear least squares; then a finer scan around the best."""
    zs, Fs, ws = z[layout.keep], F[layout.keep], w[layout.keep]
    if zs.size > SCAN_POINTS:
        keep = np.unique(np.r_[np.linspace(0, zs.size - 1, SCAN_POINTS).round().astype(int),
                               np.arange(zs.size - _fit.MIN_CONTACT_POINTS - 1, zs.size)])
        zs, Fs, ws = zs[keep], Fs[keep], ws[keep]
    span = float(np.ptp(z))
    lo, hi = z[0] - 0.1 * span, z[-_fit.MIN_CONTACT_POINTS - 1] + 0.5 * span
    z0s = np.linspace(lo, hi, N_SCAN_Z0)
    if z0_guess is not None:
        z0s = np.append(z0s, z0_guess)
    kappas = _kappas(fam, span)

    def scan(z0s, kappas, best):
        """The best (params, rss, kappa) of the grid and of ``best``; and the grid's rss."""
        table = np.full((kappas.size, z0s.size), np.inf)
        for j, kap in enumerate(kappas):
            params, rss = _fit._linear_scan(_ScanTip(fam, layout, kap), zs, Fs, ws, z0s)
            rss = np.where((params[:, 0] > 0) & np.isfinite(rss), rss, np.inf)
            table[j] = rss
            k = int(np.argmin(rss))
            if np.isfinite(rss[k]) and (best is None or rss[k] < best[1]):
                best = (params[k], rss[k], kap)
        return best, table

    best, table = scan(z0s, kappas, None)
    if best is None:
        return None
    # refine around each of the START_CANDIDATES lowest local minima of the coarse grid, each
    # REFINE_ROUNDS times between the best trial's neighbours; the best of all is the start
    padded = np.pad(table, 1, constant_values=np.inf)
    local = np.isfinite(table)
    for dj in (-1, 0, 1):
        for dk in (-1, 0, 1):
            if dj or dk:
                local &= table <= padded[1 + dj:1 + dj + table.shape[0],
                                         1 + dk:1 + dk + table.shape[1]]
    cand = np.argwhere(local)
    cand = cand[np.argsort(table[local])][:START_CANDIDATES]
    overall = best
    for j, k in cand:
        best = (None, table[j, k], kappas[j])
        zc, kc = z0s[k], kappas
        dz = (hi - lo) / (N_SCAN_Z0 - 1)
        for _ in range(REFINE_ROUNDS):  # each round: a grid between the best one's neighbours
            i = int(np.argmin(np.abs(kc - best[2])))
            k_lo, k_hi = kc[max(i - 1, 0)], kc[min(i + 1, kc.size - 1)]
            kc = np.linspace(k_lo, k_hi, N_REFINE)
            best, _ = scan(np.linspace(zc - dz, zc + dz, N_REFINE), kc, best)
            if best[0] is None:
                break
            zc = best[0][1]
            dz = 2 * dz / (N_REFINE - 1)
        if best[0] is not None and best[1] < overall[1]:
            overall = best
    best = overall
    E, z0, F0, s0 = best[0]
    return np.array([E, z0, best[2] ** 2 * E, F0, s0])  # Delta gamma = kappa^2 E*


@dataclass(frozen=True)
class JKRTip:
    """The tip of an adhesive fit: the paraboloid of radius R [m] in JKR contact, the cone of
    angle theta [rad], the exact sphere of radius R [m] or the power law c_n r^n in adhesive
    contact (``paraboloid`` is then the Cone, the ExactSphere or the PowerLaw)."""

    paraboloid: _fit.Paraboloid | _fit.Cone | _fit.ExactSphere | _fit.PowerLaw

    @property
    def R(self) -> float:
        """Radius of curvature [m] (the paraboloid's, the exact sphere's)."""
        return self.paraboloid.R

    def describe(self) -> str:
        tip = self.paraboloid
        if isinstance(tip, _fit.Cone):
            return f"cone, adhesive (MDR), theta = {tip.theta:.6g} rad"
        if isinstance(tip, _fit.ExactSphere):
            return f"exact sphere (spherical cap), adhesive (MDR), R = {tip.R:.6g} m"
        if isinstance(tip, _fit.SampledTip):
            return (f"sampled tip, adhesive (numerical MDR), {tip.profile.source!r}, "
                    f"r_max = {tip.profile.r_max:.6g} m")
        if isinstance(tip, _fit.PowerLaw):
            return (f"power law f = c_n r^n, adhesive (MDR), c_n = {tip.c_n:.6g} m^(1-n), "
                    f"n = {tip.n:.6g}")
        return f"paraboloid, adhesive (JKR), R = {self.R:.6g} m"


@dataclass(frozen=True)
class AdhesiveFitResult(_fit._Fitted):
    """The fitted parameters of an adhesive (JKR) retract curve and the fit's diagnostics.

    Attributes as :class:`hertzmdr.numeric.fit.FitResult` (``values`` and ``errors`` in the
    order of :data:`PARAMETERS`: E* [Pa], z_0 [m], Delta gamma [J/m^2], F_0 [N], s_0 [N/m];
    ``correlation`` 5 x 5), and:

    used
        Bool per point (sorted by z): in the fit (False: excluded, past the jump-off).
    jump_off
        (d_dc [m], F_dc [N], a_dc [m]) of the fitted parameters: where a displacement-controlled
        retract leaves the sample (None without adhesion, Delta gamma <= 0).
    z_split
        Position [m] of the first point after the jump-off found in the data (None: no jump).
    """

    tip: JKRTip
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
    used: np.ndarray
    jump_off: tuple[float, float, float] | None
    z_split: float | None

    @property
    def dgamma(self) -> float:
        """Fitted work of adhesion Delta gamma [J/m^2]."""
        return float(self.values[2])

    def table(self) -> str:
        """The parameters with their standard errors, one per line, in SI units."""
        rows = self._parameter_rows(PARAMETERS, UNITS)
        fit = (f"reduced chi^2 = {self.reduced_chi2:.4g}" if self.weighted else
               f"residuals' std = {np.sqrt(self.reduced_chi2):.4g} N")
        rows.append(f"{fit}, {int(self.used.sum())} points used, {self.n_contact} in contact, "
                    f"deepest indentation {self.max_depth:.4g} m")
        if self.jump_off is not None:
            d_c, F_c, a_c = self.jump_off
            rows.append(f"jump-off (depth control): d = {d_c:.4g} m (z = {self.z_0 + d_c:.6g} m),"
                        f" F = {F_c:.4g} N, a = {a_c:.4g} m")
        return "\n".join(rows)


#: the tips with an adhesive fit model
ADHESIVE_TIPS = (_fit.Paraboloid, _fit.Cone, _fit.ExactSphere, _fit.PowerLaw, _fit.SampledTip)


def _check_tip(tip):
    if not isinstance(tip, ADHESIVE_TIPS):
        raise ValueError(f"tip = {tip!r} has no adhesive fit model; valid: a Paraboloid "
                         "(hertzmdr.numeric.fit.Paraboloid, the scene's `sphere` body), a Cone "
                         "(`cone`), an ExactSphere (`exact_sphere`), a PowerLaw (`power_law`) "
                         "with n > 1/2 or a SampledTip (`profile`): the adhesive fit is "
                         "written for these only (docs/fitting.md)")
    if isinstance(tip, _fit.PowerLaw) and not tip.n > 0.5:
        raise ValueError(f"the power law's n = {tip.n!r} has no adhesive pull-off (the adhesive "
                         "force falls without bound as the contact grows); valid for the "
                         "adhesive fit: n > 1/2")


def fit_curve(z, F, tip: _fit.Paraboloid | _fit.Cone | _fit.ExactSphere | _fit.PowerLaw
              | _fit.SampledTip, *,
              nu=None, tip_modulus=None, tip_nu=None, z0=None,
              sigma=None) -> AdhesiveFitResult:
    """Fit an adhesive retract curve F(z) with the JKR paraboloid, or the adhesive cone, exact
    sphere or power law (the MDR), a contact point, the work of adhesion and a linear baseline.

    Parameters
    ----------
    z, F : array_like
        Positions of the tip's base [m] (increasing into the sample, any order) and the force on
        the tip [N] (positive in compression, negative while adhesion pulls), as
        :func:`hertzmdr.numeric.fit.fit_curve`.
    tip : hertzmdr.numeric.fit.Paraboloid, Cone, ExactSphere, PowerLaw or SampledTip
        The tip (radius of curvature R [m], the cone's angle theta [rad], the cap's radius R
        [m], the power law's c_n [m^(1-n)] and n > 1/2, or a measured profile: its contact
        radius must stay below the samples' r_max [m], else one ValueError).
    nu, tip_modulus, tip_nu, z0, sigma
        As :func:`hertzmdr.numeric.fit.fit_curve` (z0 [m]: a guess of the contact point d = 0,
        added to the start scan; sigma [N]: the noise's standard deviation).

    Returns
    -------
    AdhesiveFitResult
        Values and standard errors (the linearised covariance times the residual variance).
        A curve without a jump-off that does not bound its contact point (a fit with z_0 held
        elsewhere is as good, :func:`_z0_unbounded`) reports z_0, Delta gamma, F_0 and s_0 with
        error inf and E*'s error at least its change among those fits, with a warning.

    Raises
    ------
    hertzmdr.numeric.fit.NoContactError
        When the curve shows no contact, or E* is below 3 of its standard errors.
    ValueError
        For invalid input, naming it, its value and the valid range.
    """
    _check_tip(tip)
    fam = _family(tip)
    z, F, w = _fit._curve(z, F, sigma)
    if z.size < MIN_POINTS:
        raise ValueError(f"the curve has {z.size} points; at least {MIN_POINTS} are needed "
                         "(five parameters and two degrees of freedom)")
    if z0 is not None:
        z0 = float(as_float("z0", z0))
    jump = _find_jump_off(z, F)
    z_split = -np.inf if jump is None else jump[0]
    layout = _Layout(z_split, np.ones(z.size, bool))
    p0 = _start(fam.scan or fam, z, F, w, layout, z0)
    if p0 is None:
        _fit._no_contact("no contact point makes the force rise with a positive modulus")

    excluded = 0
    for _ in range(MAX_EXCLUDE_ROUNDS):
        sol, model = _lm(fam, z, F, w, layout, p0)
        if sol.x[2] < NEAR_BOUND * max(abs(p0[2]), _dgamma_scale(fam, abs(p0[0]),
                                                                  float(np.ptp(F)))):
            sol0, model0 = _lm(fam, z, F, w, layout, p0, no_adhesion=True)
            if sol0.cost <= sol.cost:
                sol, model = sol0, model0
        p = sol.x
        past = model.state(p[0], p[1], p[2])[1] & layout.keep
        if not past.any():
            break
        excluded += int(past.sum())
        layout = _Layout(z_split, layout.keep & ~past)
        p0 = p
    keep = layout.keep
    if isinstance(tip, _fit.SampledTip):  # the contact would need a > r_max
        d_max = float(z[-1] - p[1])
        if not d_max < float(fam.depth(max(p[0], _EPS), fam.a_max, np.sqrt(max(p[2], 0.0)))):
            raise tip._too_deep(d_max)
    res = sol.fun
    dof = int(keep.sum()) - len(PARAMETERS)
    if dof < 2:
        _fit._no_contact(f"only {int(keep.sum())} points are left in the fit")
    chi2 = float(res @ res) / dof
    E_s, z_0, dgamma, F_0, s_0 = (float(v) for v in p)
    rho = np.sqrt(max(dgamma, 0.0))
    a = model.state(E_s, z_0, dgamma)[0]
    contact = np.isfinite(a) & keep
    n_contact = int(contact.sum())
    if not E_s > 0 or n_contact < _fit.MIN_CONTACT_POINTS:
        _fit._no_contact(f"the best fit has E* = {E_s:.3g} Pa and {n_contact} point(s) in "
                         "contact")
    tip_force = model.tip_force(E_s, z_0, dgamma)
    noise = np.sqrt(chi2) * float(np.median(w))
    if float(np.abs(tip_force[contact]).max()) < _fit.CONTACT_SIGNIFICANCE * noise:
        _fit._no_contact(f"the tip's largest force, {float(np.abs(tip_force).max()):.3g} N, is "
                         f"below {_fit.CONTACT_SIGNIFICANCE:g} standard deviations of the "
                         f"residuals ({noise:.3g} N)")
    J = _jac(model, z, w, keep, p)
    cov, full = _fit._covariance(J)
    # an undetermined parameter's variance stays inf (not inf * 0 = NaN at zero residuals)
    cov = np.where(np.isinf(cov), np.inf, cov * chi2)
    err = np.sqrt(np.diag(cov))
    unbounded = jump is None and _z0_unbounded(fam, z, F, w, layout, p, float(res @ res), chi2)
    if unbounded:
        # z_0, Delta gamma and the baseline: errors inf (as undetermined parameters: variance
        # inf, covariances NaN); E* at least its change over the profile
        for k in (1, 2, 3, 4):
            cov[k, :] = cov[:, k] = np.nan
            cov[k, k] = np.inf
        err = np.sqrt(np.diag(cov))
        err[0] = max(err[0], unbounded[1])
    if not E_s >= _fit.MODULUS_SIGNIFICANCE * err[0]:
        _fit._no_contact(f"the fitted E* = {E_s:.3g} Pa is below "
                         f"{_fit.MODULUS_SIGNIFICANCE:g} of its standard errors "
                         f"({err[0]:.3g} Pa)" + (
                             ", the contact point not being bounded by a curve without its "
                             "jump-off" if unbounded else ""))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(err, err)
    values = np.array([E_s, z_0, dgamma, F_0, s_0])
    d = z - z_0
    d_max = float(d[-1])
    warn = []
    if excluded:
        warn.append(f"{excluded} point(s) of the contact part lie past the jump-off (depth "
                    "below the depth-controlled pull-off d_dc, where no equilibrium exists) "
                    "and were excluded from the fit")
    if unbounded:
        warn.append(f"contact point not bounded by the curve: with z_0 held elsewhere about "
                    f"the first position {z[0]:.6g} m (no jump-off in the data) the fit is as "
                    f"good (chi^2 within {_fit.Z0_PROFILE:g} of its least), so z_0, Delta gamma "
                    "and the baseline are not determined (their errors: inf) and E*'s error is "
                    "at least its change between those fits; a retract curve through its "
                    "jump-off determines them")
    elif jump is None and rho > 0:
        warn.append("no jump-off found in the data: the points with d < d_dc were taken as "
                    "the free cantilever's baseline (is this a retract curve?)")
    if unbounded:  # Delta gamma's error is inf: the warning above says so
        pass
    elif not dgamma > err[2]:
        warn.append(f"no adhesion measured: Delta gamma = {dgamma:.3g} ± {err[2]:.3g} J/m^2 "
                    "is within one standard error of 0 (its bound); the Hertz fit, without "
                    "--adhesion, gives the same modulus")
    elif dgamma < 2 * err[2]:
        warn.append(f"the work of adhesion is poorly determined: Delta gamma = {dgamma:.3g} "
                    f"± {err[2]:.3g} J/m^2")
    warn += [w_["message"] for w_ in _fit.check_assumptions(
        fam.ratios(float(np.nanmax(a[contact]))))]
    if not full:
        warn.append("the Jacobian is singular: the parameters are not all determined by the "
                    "curve (their errors are not meaningful)")
    jump_off = None
    if rho > 0:
        a_c, d_c = _jump_off_radius(E_s, fam, rho)
        jump_off = (d_c, float(fam.force(E_s, a_c, rho)), a_c)
        if jump is not None:  # the data's jump against the model's: a soft cantilever jumps
            first = float(d[z >= z_split][0])  # earlier, never later
            if first < d_c - 1e-9 * abs(d_c):
                warn.append(f"the data leave contact at d = {first:.4g} m, below the "
                            f"depth-controlled jump-off d_dc = {d_c:.4g} m")
    E, E_err = _fit._sample_modulus(E_s, float(err[0]), nu, tip_modulus, tip_nu)
    fitted = model.tip_force(E_s, z_0, dgamma) + F_0 + s_0 * z
    return AdhesiveFitResult(
        tip=JKRTip(tip), values=values, errors=err, correlation=corr, E=E, E_error=E_err, z=z,
        F=F, fitted=fitted, residuals=F - fitted, reduced_chi2=chi2, weighted=sigma is not None,
        n_contact=n_contact, max_depth=d_max, warnings=tuple(warn), used=keep,
        jump_off=jump_off, z_split=None if jump is None else float(z_split))


def _z0_unbounded(fam, z, F, w, layout, p, rss, chi2):
    """Where the data hold no jump-off: whether a fit with the contact point held elsewhere
    (z[0] minus Z0_PROFILE_SPANS of the span) is as good as the best one, p with its weighted
    residual sum rss (within fit.Z0_PROFILE reduced chi^2, chi2). Then the curve, without its
    free part, does not bound z_0, and Delta gamma and the baseline trade with it (the
    linearised errors put the truth up to 470 of them away): ``(True, the largest
    |E*(held) - E*|)``; else None. Each held fit starts from the better of p and the best
    kappa of a linear scan at that z_0 (from p alone, Levenberg-Marquardt stays at the
    Delta gamma of p, up to 300 in chi^2 above the held z_0's least)."""
    span = float(np.ptp(z))
    kappas = _kappas(fam, span)
    keep = layout.keep
    changes = []
    for k in Z0_PROFILE_SPANS:
        z0 = np.array([float(z[0]) - k * span])
        starts, best = [p], np.inf
        for kap in kappas:
            params, scan_rss = _fit._linear_scan(_ScanTip(fam, layout, kap), z[keep], F[keep],
                                                 w[keep], z0)
            if params[0, 0] > 0 and scan_rss[0] < best:
                E, _, F0, s0 = params[0]
                best, starts[1:] = scan_rss[0], [np.array([E, z0[0], kap**2 * E, F0, s0])]
        sol = min((_lm(fam, z, F, w, layout, q, z0=z0[0], tol=PROFILE_TOL,
                       nfev=PROFILE_NFEV)[0] for q in starts),
                  key=lambda sol: sol.cost)
        if 2 * sol.cost - rss <= _fit.Z0_PROFILE * chi2 and sol.x[0] > 0:
            changes.append(abs(float(sol.x[0]) - float(p[0])))
    return (True, max(changes)) if changes else None


def _jac(model, z, w, keep, p):
    Jt = model.jacobian(p[0], p[1], p[2])
    J = np.column_stack([Jt, np.ones_like(z), z]) / w[:, None]
    return J[keep]


def _lm(fam, z, F, w, layout, p0, *, no_adhesion=False, z0=None, tol=1e-15, nfev=2000):
    """Least squares on the kept points, Delta gamma >= 0, with the generated Jacobian
    (Levenberg-Marquardt; 'trf' with the bound when it ends below 0); or, with
    ``no_adhesion``, Levenberg-Marquardt at Delta gamma = 0 fixed (the Hertz model: 'trf'
    approaches a bound only geometrically, so a curve without adhesion is refitted on the bound
    itself). With ``z0`` [m], the contact point is held there (the profile of
    :func:`_z0_unbounded`); ``tol``: the solver's xtol, ftol and gtol, ``nfev`` its most
    evaluations (each stage)."""
    model = _Model(fam, z, layout)
    keep = layout.keep
    cols = [0, 1, 3, 4] if no_adhesion else [0, 1, 2, 3, 4]
    if z0 is not None:
        p0 = np.array(p0, float)
        p0[1] = z0
        cols.remove(1)

    def full(q):
        p = np.zeros(5)
        if z0 is not None:
            p[1] = z0
        p[cols] = q
        return p

    def residuals(q):
        p = full(q)
        return ((model.tip_force(p[0], p[1], p[2]) + p[3] + p[4] * z - F) / w)[keep]

    def jacobian(q):
        return _jac(model, z, w, keep, full(q))[:, cols]

    Fs = max(float(np.ptp(F)), float(np.abs(F).max()))
    span = float(np.ptp(z))
    # Delta gamma's scale: the value whose pull-off force is the force range
    scale = np.array([abs(p0[0]), span, max(abs(p0[2]), _dgamma_scale(fam, abs(p0[0]), Fs)),
                      Fs, Fs / span])
    opts = {"xtol": tol, "ftol": tol, "gtol": tol, "max_nfev": nfev}
    if no_adhesion:
        sol = least_squares(residuals, p0[cols], jac=jacobian, method="lm",
                            x_scale=scale[cols], **opts)
    else:
        lower = np.array([-np.inf, -np.inf, 0.0, -np.inf, -np.inf])
        p0 = np.maximum(p0, lower)
        # MINPACK's Levenberg-Marquardt first (unbounded; the fastest, and it converges
        # further along ill-conditioned directions such as F_0 against s_0 than 'trf' stops);
        # only when it ends below Delta gamma = 0, 'trf' with the bound
        sol = least_squares(residuals, p0[cols], jac=jacobian, method="lm",
                            x_scale=scale[cols], **opts)
        if not full(sol.x)[2] >= 0:
            sol = least_squares(residuals, p0[cols], jac=jacobian, method="trf",
                                x_scale=scale[cols], bounds=(lower[cols], np.inf), **opts)
    sol.x = full(sol.x)
    return sol, model
