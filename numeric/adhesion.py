"""Adhesive (JKR-type) contact of axisymmetric profiles by the MDR: curves, pull-off, cycles.

Floats or NumPy arrays in SI units (lengths in m, forces in N, the work of adhesion Delta gamma
in J/m^2); bad input raises ValueError naming it. The formulas are generated from
:mod:`hertzmdr.derive.adhesion`; this module validates, broadcasts, finds roots and walks
loading-unloading histories. An adhesive contact of radius a has

- the critical elongation of the boundary spring Delta l(a) = sqrt(2 pi a Delta gamma/E*),
  derived from the energy release rate of the 3-D contact;
- the depth d(a) = g(a) - Delta l(a) ((5.55) with the stretched edge spring) and the force
  F(a) = F_0(a) - 2 E* a Delta l(a) ((5.57): F_0 is the non-adhesive force at radius a);
- the pressure p_0(r; a) - E* Delta l/(pi sqrt(a^2 - r^2)) ((5.59): the edge term is singular
  like 1/sqrt(a - r)) and outside the displacement u_0(r; a) - (2/pi) Delta l asin(a/r) (5.60).

Usage::

    from hertzmdr.numeric import adhesion
    c = adhesion.AdhesiveContact(adhesion.Paraboloid(R=20e-9), E_star=2.67e6, dgamma=0.05)
    c.pull_off("force")          # PullOff(force=-4.71e-9, depth=..., contact_radius=..., ...)
    c.force(a), c.depth(a)       # along the equilibrium curve, a in m
    a, d, F = c.equilibrium(depth=d)  # the stable state at a depth (or force=), any shape
    c.stiffness(depth=d), c.mean_pressure(depth=d), c.pressure_at_depth(r, d)
    cyc = c.cycle(to=10e-9, control="depth", points=1000)  # approach-retract history
    cyc.depth, cyc.force, cyc.contact_radius, cyc.jumps, cyc.hysteresis

Shapes: :class:`Paraboloid` (JKR), :class:`Cone`, :class:`PowerLaw` (c_n r^n, Hess),
:class:`FlatPunch` (Kendall), :class:`Sphere` (the exact spherical cap) and :class:`Worn`
(the worn paraboloid of Problem 8, with a kink). The first four have closed-form pull-off
(derived); the sphere and the worn tip are solved by bracketed roots of dF/da (or dd/da),
with an error estimate.

Stability (derived in :mod:`hertzmdr.derive.adhesion`): under force control an equilibrium is
stable where dF/da > 0, under depth control where dd/da > 0. Unloading follows the stable
branch to a minimum of the controlled quantity, then jumps, at the same force (depth), to the
next stable state with a smaller contact, or separates. The pull-off is the lowest such
minimum (the global minimum of F(a), resp. d(a), below the loaded state).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cache

import numpy as np
from scipy.optimize import brentq

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import cone as _cone
from hertzmdr.numeric import hertz as _hertz
from hertzmdr.numeric import powerlaw as _powerlaw
from hertzmdr.numeric import sphere as _sphere
from hertzmdr.numeric import worn as _worn
from hertzmdr.numeric._validate import as_float, between, nonnegative, positive

__all__ = ["Shape", "Paraboloid", "Sphere", "Cone", "PowerLaw", "FlatPunch", "Worn", "Sampled",
           "AdhesiveContact", "PullOff", "Cycle", "Jump", "CONTROLS", "critical_elongation",
           "tabor_parameter", "TABOR_JKR"]

#: the controls of a loading history: the prescribed quantity is the depth or the force
CONTROLS = ("depth", "force")
#: JKR holds for a Tabor parameter above this (Maugis 1992: within a few per cent of JKR's
#: pull-off force for mu_T > 5); below it the scene layer warns
TABOR_JKR = 5.0
_EPS = np.finfo(float).eps
#: points of the log-spaced scan for the extrema of F(a) or d(a) of a profile without closed
#: form; each sign change of the slope is then refined by Brent's method to the last bit
_SCAN = 400
#: Gauss-Legendre nodes per branch of the hysteresis integral (and twice that for its error)
_GL_NODES = 40


@cache
def _gauss_legendre(m):
    """Gauss-Legendre nodes and weights on [0, 1] (computed once per order)."""
    u, w = np.polynomial.legendre.leggauss(m)
    return (u + 1) / 2, w / 2


def critical_elongation(a, E_star, dgamma):
    """Critical elongation Delta l = sqrt(2 pi a Delta gamma/E*) [m] of the boundary spring.

    Derived from the energy release rate of the 3-D contact, G = E* (g(a) - d)^2/(2 pi a),
    set equal to Delta gamma (derive/adhesion.py).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], >= 0.
    E_star : float or array_like
        Effective modulus (5.26) [Pa], > 0.
    dgamma : float or array_like
        Work of adhesion [J/m^2], >= 0.
    """
    return gen.adhesion_critical_elongation(positive("E_star", E_star), nonnegative("a", a),
                                            nonnegative("dgamma", dgamma))


def tabor_parameter(R, E_star, dgamma, z0):
    """Tabor parameter mu_T = (R Delta gamma^2/(E*^2 z0^3))^(1/3) [1] (Tabor 1977).

    JKR (this module) holds for mu_T > :data:`TABOR_JKR`; DMT for mu_T < 0.1 (small, stiff
    contacts); in between a Maugis-Dugdale model is needed.

    Parameters
    ----------
    R : float or array_like
        Radius of curvature of the tip [m], > 0.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    dgamma : float or array_like
        Work of adhesion [J/m^2], >= 0.
    z0 : float or array_like
        Range of the adhesive forces (equilibrium distance) [m], > 0.
    """
    return gen.adhesion_tabor_parameter(positive("E_star", E_star), positive("R", R),
                                        nonnegative("dgamma", dgamma), positive("z0", z0))


# --------------------------------------------------------------------------------- shapes
@dataclass(frozen=True)
class Shape:
    """An axisymmetric profile as the adhesive MDR needs it (subclasses below).

    ``g(a)`` and ``g_slope(a)`` are the MDR profile (5.52) and its slope at the contact
    radius, ``force0(a, E_star)`` the non-adhesive force at radius a ((5.57) with d = g(a)),
    ``a_limit`` the largest possible contact radius [m], ``kinks`` the radii where g' jumps.
    """

    a_limit = np.inf
    kinks: tuple = field(default=(), init=False, repr=False)
    #: the radius of curvature of the tip [m] (for the Tabor parameter), None if it has none
    radius_of_curvature = None

    def g(self, a):
        raise NotImplementedError

    def g_slope(self, a):
        raise NotImplementedError

    def force0(self, a, E_star):
        raise NotImplementedError

    def height(self, r):
        raise NotImplementedError

    def pressure0(self, r, a, E_star):
        raise NotImplementedError

    def displacement0_outside(self, r, a):
        raise NotImplementedError

    def scale(self, E_star, dgamma) -> float:
        """A length near the pull-off radius, where the scan for extrema is centred [m]."""
        raise NotImplementedError

    def companion(self):
        """The same profile at a coarser resolution, for an error estimate (None: exact)."""
        return None

    # closed forms, where derived: (radius, force, depth) at pull-off, the zero-load radius
    def closed_pull_off(self, control, E_star, dgamma):
        return None

    def closed_zero_load(self, E_star, dgamma):
        return None

    def depth(self, a, E_star, dgamma):
        return gen.adhesion_depth(E_star, a, dgamma, self.g(a))  # (5.55), adhesive

    def force(self, a, E_star, dgamma):
        # (5.57) at d = g(a) - Delta l: the non-adhesive force less a flat punch's (5.11) of
        # depth Delta l (F is linear in d at fixed a)
        return self.force0(a, E_star) - gen.powerlaw_punch_force(
            E_star, a, gen.adhesion_critical_elongation(E_star, a, dgamma))


@dataclass(frozen=True)
class Paraboloid(Shape):
    """The paraboloid f = r^2/(2R) of Hertz's theory: the JKR contact. R [m] > 0."""

    R: float

    @property
    def radius_of_curvature(self):
        return self.R

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))

    def g(self, a):
        return gen.paraboloid_g(self.R, a)  # (5.52): g = x^2/R

    def g_slope(self, a):
        return gen.adhesion_paraboloid_g_slope(self.R, a)

    def force0(self, a, E_star):
        return _hertz.force(self.g(a), self.R, E_star)  # d = g(a) (5.55)

    def height(self, r):
        return gen.paraboloid_profile(self.R, r)

    def pressure0(self, r, a, E_star):
        return _hertz.pressure(r, self.g(a), self.R, E_star)

    def displacement0_outside(self, r, a):
        return _hertz.surface_displacement(r, self.g(a), self.R)

    def scale(self, E_star, dgamma):
        return float(gen.jkr_pull_off_radius_fc(E_star, dgamma, self.R))

    def depth(self, a, E_star, dgamma):
        return gen.jkr_depth(E_star, self.R, a, dgamma)

    def force(self, a, E_star, dgamma):
        return gen.jkr_force_from_radius(E_star, self.R, a, dgamma)

    def closed_pull_off(self, control, E_star, dgamma):
        k = "fc" if control == "force" else "dc"
        return tuple(float(getattr(gen, f"jkr_pull_off_{q}_{k}")(E_star, dgamma, self.R))
                     for q in ("radius", "force", "depth"))

    def closed_zero_load(self, E_star, dgamma):
        return float(gen.jkr_zero_load_radius(E_star, dgamma, self.R))


@dataclass(frozen=True)
class Cone(Shape):
    """A cone f = r tan(theta), theta [rad] in (0, pi/2) the angle of its face to the plane."""

    theta: float

    def __post_init__(self):
        object.__setattr__(self, "theta", float(between("theta", self.theta, 0, np.pi / 2)))

    def g(self, a):
        return _cone.depth(a, self.theta)  # (5.38): g(a) = (pi/2) a tan(theta)

    def g_slope(self, a):
        return gen.adhesion_cone_g_slope(self.theta) + np.zeros_like(np.asarray(a, float))

    def force0(self, a, E_star):
        return _cone.force(_cone.depth(a, self.theta), self.theta, E_star)

    def height(self, r):
        return gen.cone_profile(self.theta, r)

    def pressure0(self, r, a, E_star):
        return _cone.pressure(r, _cone.depth(a, self.theta), self.theta, E_star)

    def displacement0_outside(self, r, a):
        c_1 = np.tan(self.theta)
        return _powerlaw.surface_displacement(r, _cone.depth(a, self.theta), c_1, 1.0)

    def scale(self, E_star, dgamma):
        return float(gen.adhesion_cone_pull_off_radius_fc(E_star, dgamma, self.theta))

    def depth(self, a, E_star, dgamma):
        return gen.adhesion_cone_depth(E_star, a, dgamma, self.theta)

    def force(self, a, E_star, dgamma):
        return gen.adhesion_cone_force_from_radius(E_star, a, dgamma, self.theta)

    def closed_pull_off(self, control, E_star, dgamma):
        k = "fc" if control == "force" else "dc"
        return tuple(float(getattr(gen, f"adhesion_cone_pull_off_{q}_{k}")(
            E_star, dgamma, self.theta)) for q in ("radius", "force", "depth"))

    def closed_zero_load(self, E_star, dgamma):
        return float(gen.adhesion_cone_zero_load_radius(E_star, dgamma, self.theta))


@dataclass(frozen=True)
class PowerLaw(Shape):
    """A power-law profile f = c_n r^n (Problem 7(d)); n > 1/2 for a pull-off to exist.

    c_n [m^(1-n)] > 0, n [1] > 1/2 (for n <= 1/2 the adhesive force falls without bound as the
    contact grows: there is no pull-off, and the contact never separates).
    """

    c_n: float
    n: float
    kappa: float = field(init=False, repr=False)  # kappa_n of Problem 7(d), computed once

    def __post_init__(self):
        object.__setattr__(self, "c_n", float(positive("c_n", self.c_n)))
        object.__setattr__(self, "n", float(between("n", self.n, 0.5, np.inf)))
        object.__setattr__(self, "kappa", float(_powerlaw.kappa(self.n)))

    @property
    def radius_of_curvature(self):
        """n = 2: c_2 r^2 is the paraboloid r^2/(2R) of (5.19), R = 1/(2 c_2); else None."""
        return 1 / (2 * self.c_n) if self.n == 2 else None

    def g(self, a):
        return _powerlaw.g_profile(a, self.c_n, self.n)

    def g_slope(self, a):
        return gen.adhesion_powerlaw_g_slope(self.c_n, self.kappa, self.n, a)

    def force0(self, a, E_star):
        return _powerlaw.force_from_radius(a, self.g(a), self.n, E_star)

    def height(self, r):
        return gen.powerlaw_profile(self.c_n, self.n, r)

    def pressure0(self, r, a, E_star):
        return _powerlaw.pressure(r, self.g(a), self.c_n, self.n, E_star)

    def displacement0_outside(self, r, a):
        return _powerlaw.surface_displacement(r, self.g(a), self.c_n, self.n)

    def _args(self):
        return (self.c_n, self.kappa, self.n)

    def scale(self, E_star, dgamma):
        return float(gen.adhesion_powerlaw_pull_off_radius_fc(E_star, dgamma, *self._args()))

    def depth(self, a, E_star, dgamma):
        return gen.adhesion_powerlaw_depth(E_star, a, dgamma, *self._args())

    def force(self, a, E_star, dgamma):
        return gen.adhesion_powerlaw_force_from_radius(E_star, a, dgamma, *self._args())

    def closed_pull_off(self, control, E_star, dgamma):
        k = "fc" if control == "force" else "dc"
        return tuple(float(getattr(gen, f"adhesion_powerlaw_pull_off_{q}_{k}")(
            E_star, dgamma, *self._args())) for q in ("radius", "force", "depth"))

    def closed_zero_load(self, E_star, dgamma):
        return float(gen.adhesion_powerlaw_zero_load_radius(E_star, dgamma, *self._args()))


@dataclass(frozen=True)
class Sphere(Shape):
    """The exact spherical cap f = R - sqrt(R^2 - r^2) (Sneddon), R [m] > 0; a < R."""

    R: float

    @property
    def radius_of_curvature(self):
        return self.R

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))

    @property
    def a_limit(self):
        return self.R

    def g(self, a):
        return _sphere.depth(a, self.R)

    def g_slope(self, a):
        return gen.adhesion_sphere_g_slope(self.R, a)

    def force0(self, a, E_star):
        return _sphere.force_from_radius(a, self.R, E_star)

    def height(self, r):
        return _sphere.profile(r, self.R)

    def pressure0(self, r, a, E_star):
        return _sphere.pressure(r, _sphere.depth(a, self.R), self.R, E_star)

    def displacement0_outside(self, r, a):
        return _sphere.surface_displacement(r, _sphere.depth(a, self.R), self.R)

    def scale(self, E_star, dgamma):
        return min(float(gen.jkr_pull_off_radius_fc(E_star, dgamma, self.R)), 0.5 * self.R)


@dataclass(frozen=True)
class Worn(Shape):
    """The worn paraboloid of Problem 8: flat for r < b, (r^2 - b^2)/(2R) beyond; R, b [m] > 0.

    g' is infinite at the kink a = b+: F(a) and d(a) have a corner there, which can be the
    pull-off (the flat tip lets go as a whole).
    """

    R: float
    b: float

    @property
    def radius_of_curvature(self):
        return self.R

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))
        object.__setattr__(self, "b", float(positive("b", self.b)))
        object.__setattr__(self, "kinks", (self.b,))

    def g(self, a):
        return np.where(a > self.b, _worn.g_profile(np.maximum(a, self.b), self.R, self.b), 0.0)

    def g_slope(self, a):
        above = a > self.b
        with np.errstate(divide="ignore"):
            s = gen.adhesion_worn_g_slope(self.R, self.b, np.where(above, a, 2 * self.b))
        return np.where(above, s, 0.0)

    def force0(self, a, E_star):
        above = a > self.b
        f = _worn.force_from_radius(np.where(above, a, 2 * self.b), self.R, self.b, E_star)
        return np.where(above, f, 0.0)

    def height(self, r):
        return _worn.profile(r, self.R, self.b)

    def pressure0(self, r, a, E_star):
        if a <= self.b:
            return np.zeros_like(np.asarray(r, dtype=float))
        return _worn.pressure(r, self.g(a), self.R, self.b, E_star)

    def displacement0_outside(self, r, a):
        if a <= self.b:
            return np.zeros_like(np.asarray(r, dtype=float))
        return _worn.surface_displacement(r, self.g(a), self.R, self.b)

    def scale(self, E_star, dgamma):
        return max(float(gen.jkr_pull_off_radius_fc(E_star, dgamma, self.R)), self.b)


@dataclass(frozen=True)
class FlatPunch(Shape):
    """A rigid flat punch of radius ``radius`` [m] > 0 (Kendall): the contact radius is fixed.

    F = 2 E* a d while d >= -Delta l(a); it lets go at d = -Delta l(a) with the force
    -sqrt(8 pi a^3 E* Delta gamma) under either control.
    """

    radius: float

    def __post_init__(self):
        object.__setattr__(self, "radius", float(positive("radius", self.radius)))

    def closed_pull_off(self, control, E_star, dgamma):
        a = self.radius
        return (a, float(gen.adhesion_punch_pull_off_force(E_star, a, dgamma)),
                -float(gen.adhesion_critical_elongation(E_star, a, dgamma)))

    def height(self, r):
        return 0.0 * np.asarray(r, dtype=float)


@dataclass(frozen=True, eq=False)
class Sampled(Shape):
    """Any profile of :class:`hertzmdr.numeric.mdr.Profile` (samples or a callable), by the
    numerical MDR: g(a), g'(a) and the integral of g by its quadrature of the profile's spline.

    ``coarse=True`` is the same profile on its coarse representation (every other sample, or
    half the grid): :class:`AdhesiveContact` solves on both and reports their difference as
    the error estimate of a pull-off (as :mod:`hertzmdr.numeric.mdr` does for a solve). The
    pressure and the surface displacement are the numerical MDR's (Abel integral of g' and
    (5.60) by quadrature of g at d = g(a)) plus the adhesive edge terms, as for every shape.
    """

    profile: object
    coarse: bool = False

    def __post_init__(self):
        from hertzmdr.numeric import mdr

        if not isinstance(self.profile, mdr.Profile):
            raise ValueError(f"profile = {self.profile!r} is not a hertzmdr.numeric.mdr.Profile")
        object.__setattr__(self, "kinks", tuple(float(b) for b in self._rep().edges[1:-1]))
        object.__setattr__(self, "_memo", {})

    def __repr__(self):  # no object address: messages must be the same in every run
        return (f"Sampled({self.profile.source!r}, r_max={self.profile.r_max!r}"
                + (", coarse=True)" if self.coarse else ")"))

    def _rep(self):
        coarse, fine = self.profile._source.pair(0)
        return coarse if self.coarse else fine

    @property
    def a_limit(self):
        return self.profile.r_max

    def companion(self):
        return None if self.coarse else Sampled(self.profile, coarse=True)

    def _tables(self, a):
        """g(a) (5.52), g'(a) and G(a) = integral_0^a g [m^2], from one quadrature of the
        profile's spline for all three (``quadrature.direct``); the last few radii arrays
        asked for are kept, because the curve asks for g, g' and G at the same radii."""
        from hertzmdr.numeric._mdr import kinks, quadrature

        a = np.asarray(a, float)
        flat = np.abs(np.atleast_1d(a)).ravel()
        key = flat.tobytes()
        hit = self._memo.get(key)
        if hit is None:
            rep = self._rep()
            g, q, G = quadrature.direct(rep, flat, with_G=True)
            hit = (g, q + kinks.terms(rep, flat, 1), G)
            if len(self._memo) >= 8:
                self._memo.pop(next(iter(self._memo)))
            self._memo[key] = hit
        return tuple(np.reshape(v, a.shape) for v in hit)

    def g(self, a):
        return self._tables(a)[0]  # (5.52)

    def g_slope(self, a):
        return self._tables(a)[1]

    def force0(self, a, E_star):
        g, _, G = self._tables(a)
        return gen.mdr_force(E_star, np.asarray(a, float), g, G)  # (5.57) with d = g(a)

    def scale(self, E_star, dgamma):
        return self.profile.r_max / 100

    def height(self, r):
        """f(r) - f(0) [m]: the profile's spline (numeric/_mdr/spline.py)."""
        rep = self._rep()
        r = np.asarray(r, float)
        u = np.concatenate([np.ravel(r), [0.0]])
        idx = rep.seg_index(u)
        out = np.empty(u.shape)
        for i, spl in enumerate(rep.segments):
            sel = idx == i
            if sel.any():
                out[sel] = spl(u[sel])
        return np.reshape(out[:-1] - out[-1], r.shape)

    def pressure0(self, r, a, E_star):
        """The non-adhesive pressure [Pa] of contact radius a [m] at r < a (5.59) with d = g(a):
        the numerical MDR's Abel integral of g' (numeric/_mdr/operators.py); +inf at r = 0
        under a conical tip."""
        from hertzmdr.numeric._mdr import operators

        coarse, fine = self.profile._source.pair(0)
        rep = coarse if self.coarse else fine
        r = np.asarray(r, float)
        conical = bool((r == 0).any()) and operators.conical_tip(fine, coarse, float(a))
        flat = np.ravel(r)
        return np.reshape(operators.pressure(rep, flat, float(a), E_star, 6, conical), r.shape)

    def displacement0_outside(self, r, a):
        """The non-adhesive surface displacement [m] of contact radius a [m] at r >= a (5.60)
        with d = g(a), by the numerical MDR's quadrature of g."""
        from hertzmdr.numeric._mdr import operators

        r = np.asarray(r, float)
        flat = np.ravel(r)
        d = float(self.g(float(a)))
        return np.reshape(operators.displacement(self._rep(), flat, float(a), d), r.shape)


# ------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class PullOff:
    """The pull-off (critical) state under one control.

    Attributes
    ----------
    force : float
        Pull-off force F_c [N] (negative: a tension).
    depth : float
        Depth d_c [m] at pull-off (negative: the surface is pulled above its free level).
    contact_radius : float
        Contact radius a_c [m] at pull-off.
    rel_error : float
        Estimated relative error of ``force`` [1].
    method : str
        "closed form" or "bracketed root of dF/da" / "... dd/da" (with the number of roots).
    """

    force: float
    depth: float
    contact_radius: float
    rel_error: float
    method: str


@dataclass(frozen=True)
class Jump:
    """An instability of a history: the state before and after, (d [m], F [N], a [m])."""

    kind: str  # "jump into contact", "jump" (to a smaller/larger contact), "pull-off"
    before: tuple[float, float, float]
    after: tuple[float, float, float]


@dataclass(frozen=True)
class Cycle:
    """An approach-push-retract history (see :meth:`AdhesiveContact.cycle`).

    Attributes
    ----------
    depth, force, contact_radius : ndarray
        The path in order [m, N, m], jumps included as consecutive points (a = 0: no contact).
    loading : ndarray of bool
        True on the approach and push, False on the retract.
    jumps : list of Jump
        The instabilities, in the order met.
    hysteresis : float
        The work done on the contact over the cycle, the closed integral of F dd [J] (>= 0:
        the energy dissipated by the jumps; 0 exactly without adhesion).
    hysteresis_error : float
        Its estimated absolute error [J] (two Gauss-Legendre orders per branch; for a
        sampled profile plus the difference from the same cycle on its coarse samples).
    control : str
        "depth" or "force".
    """

    depth: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    loading: np.ndarray
    jumps: list
    hysteresis: float
    hysteresis_error: float
    control: str


# ------------------------------------------------------------------------------- contact
def _control(control):
    if control not in CONTROLS:
        raise ValueError(f"control = {control!r} is not one of {CONTROLS}")
    return control


class AdhesiveContact:
    """An adhesive contact of ``shape`` on an elastic half-space.

    Parameters
    ----------
    shape : Shape
        :class:`Paraboloid`, :class:`Cone`, :class:`PowerLaw`, :class:`FlatPunch`,
        :class:`Sphere` or :class:`Worn`.
    E_star : float
        Effective modulus (5.26) [Pa], > 0.
    dgamma : float
        Work of adhesion Delta gamma [J/m^2], >= 0 (0: the non-adhesive contact, exactly).
    """

    def __init__(self, shape: Shape, E_star: float, dgamma: float):
        if not isinstance(shape, Shape):
            raise ValueError(f"shape = {shape!r} is not an adhesion.Shape (Paraboloid, Cone, "
                             "PowerLaw, FlatPunch, Sphere, Worn)")
        self.shape = shape
        self.E_star = float(positive("E_star", E_star))
        self.dgamma = float(nonnegative("dgamma", dgamma))
        self._pull_offs: dict[str, PullOff] = {}  # by control, from the far default start

    def __repr__(self):
        return f"AdhesiveContact({self.shape!r}, E_star={self.E_star!r}, dgamma={self.dgamma!r})"

    @property
    def _punch(self):
        return isinstance(self.shape, FlatPunch)

    def _radius(self, a):
        a = as_float("a", a)
        lim = self.shape.a_limit
        if self._punch:
            return between("a", a, 0, self.shape.radius, lo_open=False, hi_open=False)
        if np.isfinite(lim):
            return between("a", a, 0, lim, lo_open=False)
        return nonnegative("a", a)

    # -------------------------------------------------------------- the equilibrium curve
    def critical_elongation(self, a):
        """Delta l(a) [m] of the boundary spring at contact radius a [m]."""
        return gen.adhesion_critical_elongation(self.E_star, self._radius(a), self.dgamma)

    def depth(self, a):
        """Depth d(a) = g(a) - Delta l(a) [m] of the equilibrium at contact radius a [m].

        For a flat punch, a is its radius and the result is the depth at which it lets go.
        """
        a = self._radius(a)
        if self._punch:
            return -gen.adhesion_critical_elongation(self.E_star, a, self.dgamma)
        return self.shape.depth(a, self.E_star, self.dgamma)  # (5.55), adhesive

    def force(self, a):
        """Force F(a) [N] of the equilibrium at contact radius a [m] (5.57), adhesive."""
        a = self._radius(a)
        if self._punch:
            return gen.adhesion_punch_pull_off_force(self.E_star, a, self.dgamma)
        return self.shape.force(a, self.E_star, self.dgamma)

    def _slope(self, control, a):
        """dd/da or dF/da along the curve: its sign is the stability under ``control``."""
        gs = self.shape.g_slope(a)
        if control == "force":
            return gen.adhesion_force_slope(self.E_star, a, self.dgamma, gs)
        return gen.adhesion_depth_slope(self.E_star, a, self.dgamma, gs)

    def _value(self, control, a):
        return self.depth(a) if control == "depth" else self.force(a)

    # ---------------------------------------------------------------- extrema and roots
    def _extrema(self, control, a_hi, *, closed=True):
        """Radii in (0, a_hi] where the slope under ``control`` changes sign, with the type
        ("min" where it goes from - to + with growing a, else "max"), each refined by Brent's
        method; kinks of the profile are candidates too (a corner of F or d)."""
        sh = self.shape
        known = sh.closed_pull_off(control, self.E_star, self.dgamma) if closed else None
        if known is not None and not self._punch:
            # A a^(n+1) - B a^(3/2) (and A a^n - B a^(1/2)), n > 1/2: one minimum, derived
            return [(known[0], "min")] if known[0] < a_hi else []
        lo = min(sh.scale(self.E_star, self.dgamma), a_hi) * 1e-6
        grid = np.geomspace(lo, a_hi, _SCAN)
        grid = np.unique(np.concatenate([grid, [k for k in sh.kinks if k < a_hi]]))
        s = np.sign(self._slope(control, grid))
        out = []
        kinks = set(sh.kinks)
        for i in np.flatnonzero(s[:-1] * s[1:] < 0):
            if grid[i] in kinks and np.sign(self._slope(control, grid[i] * (1 + 1e-12))) \
                    == s[i + 1]:
                continue  # the sign changes at the kink itself: below
            def f(a):
                return (float(self._slope(control, a)))
            root = brentq(f, grid[i], grid[i + 1], xtol=1e-300, rtol=4 * _EPS, maxiter=200)
            out.append((root, "min" if s[i] < 0 else "max"))
        for k in sh.kinks:  # a corner: the slope jumps from - below to + above
            if k < a_hi and self._slope(control, k * (1 - 1e-12)) < 0 < self._slope(
                    control, k * (1 + 1e-12)):
                out.append((k, "min"))
        return sorted(set(out))

    def _upper(self, control, target, a_from, a_cap=np.inf):
        """The a >= a_from where the value under ``control`` reaches ``target`` on the rising
        branch that starts at a_from and ends at a_cap (Brent's method on a doubling
        bracket)."""
        lim = min(self.shape.a_limit, a_cap)
        lo, hi = a_from, max(2 * a_from, self.shape.scale(self.E_star, self.dgamma))
        for _ in range(2000):
            if np.isfinite(lim):
                hi = min(hi, lim * (1 - 1e-15) if lim == self.shape.a_limit else lim)
            if self._value(control, hi) >= target:
                break
            lo, hi = hi, 2 * hi
        else:
            unit = "m" if control == "depth" else "N"
            where = (f"the largest contact radius the profile describes, a = {lim:.6g} m"
                     if np.isfinite(lim) else f"a contact radius of {hi:.6g} m")
            raise ValueError(f"{control} = {target:.6g} {unit} is not reached below {where}")
        if self._value(control, lo) >= target:
            return lo
        return brentq(lambda a: float(self._value(control, a)) - target, lo, hi,
                      xtol=1e-300, rtol=4 * _EPS, maxiter=300)

    # ------------------------------------------------------------------------- pull-off
    def pull_off(self, control: str = "force", *, a_from: float | None = None) -> PullOff:
        """Pull-off force, depth and contact radius under ``control`` ("force" or "depth").

        Closed forms where derived (paraboloid, cone, power law, flat punch); otherwise the
        global minimum of F(a) (force control) or d(a) (depth control) on (0, a_from]: the
        sign changes of dF/da (dd/da) on a log-spaced scan, each refined by Brent's method
        to a relative bracket of 4 eps, and the kinks of the profile. The error estimate is
        the spread of F over the final bracket (F is stationary there) plus 8 eps.

        ``a_from`` [m]: the contact radius unloading starts from (default: far beyond the
        pull-off, 100 times the profile's pull-off scale). Delta gamma = 0 gives F = d = a = 0.
        """
        control = _control(control)
        if a_from is None and control in self._pull_offs:
            return self._pull_offs[control]
        out = self._pull_off(control, a_from)
        if a_from is None:
            self._pull_offs[control] = out
        return out

    def _pull_off(self, control, a_from):
        if self.dgamma == 0:
            return PullOff(0.0, 0.0, 0.0, 0.0, "no adhesion")
        closed = self.shape.closed_pull_off(control, self.E_star, self.dgamma)
        if closed is not None and a_from is None:
            a_c, F_c, d_c = closed
            return PullOff(F_c, d_c, a_c, 8 * _EPS, "closed form")
        if self._punch:
            a_c, F_c, d_c = closed
            return PullOff(F_c, d_c, a_c, 8 * _EPS, "closed form")
        a_hi = a_from if a_from is not None else self._far()
        mins = [a for a, kind in self._extrema(control, a_hi, closed=False) if kind == "min"]
        if not mins:
            raise ValueError(f"no pull-off under {control} control below a = {a_hi!r} m")
        vals = [float(self._value(control, a)) for a in mins]
        a_c = mins[int(np.argmin(vals))]
        F_c, d_c = float(self.force(a_c)), float(self.depth(a_c))
        spread = max(abs(float(self.force(a_c * (1 + s * 4 * _EPS))) - F_c) for s in (-1, 1))
        which = "dF/da" if control == "force" else "dd/da"
        err = spread / abs(F_c) + 8 * _EPS
        method = f"bracketed root of {which} ({len(mins)} minima)"
        twin = self.shape.companion()
        if twin is not None:  # the numerical MDR: the coarse-vs-fine difference of the result
            try:
                other = AdhesiveContact(twin, self.E_star, self.dgamma)._pull_off(control, a_from)
            except ValueError:  # no estimate without the coarse solution: say so, not "none"
                raise ValueError(
                    f"pull-off under {control} control below a = {a_hi!r} m: the samples have a "
                    f"minimum at a = {a_c!r} m, the coarse samples (every other one) none, so "
                    "it has no error estimate; give more samples, or declare the profile's "
                    "kinks (breakpoints=)") from None
            err += max(abs(other.force - F_c) / abs(F_c),
                       abs(other.contact_radius - a_c) / a_c)
            method += ", numerical MDR (error: coarse vs fine samples)"
        return PullOff(F_c, d_c, a_c, err, method)

    def _far(self):
        lim = self.shape.a_limit
        far = 100 * self.shape.scale(self.E_star, self.dgamma)
        return min(far, lim * (1 - 1e-9)) if np.isfinite(lim) else far

    def zero_load_contact_radius(self) -> float:
        """Contact radius a_0 [m] at zero force on the stable branch (closed form or root)."""
        if self._punch:
            return self.shape.radius
        closed = self.shape.closed_zero_load(self.E_star, self.dgamma)
        if closed is not None:
            return closed
        if self.dgamma == 0:
            return 0.0
        a_c = self.pull_off("force").contact_radius
        return self._upper("force", 0.0, a_c)

    def contact_radius(self, *, depth=None, force=None):
        """Contact radius a [m] of the stable equilibrium at the given depth [m] or force [N].

        The stable branch under the matching control (dd/da > 0, dF/da > 0): the largest
        root, found by Brent's method above the pull-off radius. A depth (force) below the
        pull-off value has no contact: ValueError names it and the limit. A flat punch's
        contact radius is its radius at every depth (force) above its pull-off.
        """
        if (depth is None) == (force is None):
            raise ValueError("give exactly one of depth= and force=")
        control = "depth" if depth is not None else "force"
        value = as_float(control, depth if depth is not None else force)
        po = self.pull_off(control)
        low = po.depth if control == "depth" else po.force
        bad = value < low
        if bad.any():
            v = float(value[bad].flat[0]) if value.ndim else float(value)
            raise ValueError(f"{control} = {v!r} is below the pull-off {control} {low!r}: no "
                             "contact")
        if self._punch:  # the punch's contact radius is its own, at every load in contact
            return np.full(value.shape, self.shape.radius) if value.ndim else self.shape.radius
        if control == "force" and isinstance(self.shape, Paraboloid):
            return gen.jkr_contact_radius_from_force(self.E_star, value, self.shape.R,
                                                     self.dgamma)
        flat = [self._upper(control, float(v), max(po.contact_radius, 1e-300))
                for v in np.ravel(value)]
        return np.reshape(flat, value.shape) if value.ndim else flat[0]


    def equilibrium(self, *, depth=None, force=None):
        """(a [m], d [m], F [N]) of the stable equilibrium at the given depth [m] or force [N].

        Arrays of the input's shape: the contact radius of :meth:`contact_radius`, and the
        depth and force on the curve there; a flat punch (fixed radius) has F = 2 E* a d
        (5.11) at every depth above its pull-off depth.
        """
        a = self.contact_radius(depth=depth, force=force)
        a = np.asarray(a, float)
        if self._punch:
            if depth is not None:
                d = np.asarray(as_float("depth", depth), float) + 0 * a
                return a, d, np.asarray(gen.powerlaw_punch_force(self.E_star, a, d), float)
            F = np.asarray(as_float("force", force), float) + 0 * a
            return a, np.asarray(gen.punch_depth_from_force(self.E_star, F, a), float), F
        return a, np.asarray(self.depth(a), float), np.asarray(self.force(a), float)

    def force_at_depth(self, d):
        """Force F [N] of the stable equilibrium at depth d [m] (depth control)."""
        return self.equilibrium(depth=d)[2]

    def stiffness(self, *, depth=None, force=None):
        """Differential stiffness dF/dd [N/m] of the stable equilibrium at the given depth [m]
        or force [N]: (dF/da)/(dd/da) along the adhesive curve; 2 E* a for a flat punch
        (5.12), whose contact radius does not change."""
        a = np.asarray(self.contact_radius(depth=depth, force=force), float)
        if self._punch:
            return np.asarray(gen.mdr_stiffness(self.E_star, a), float)  # (5.12)
        gs = self.shape.g_slope(a)
        return np.asarray(gen.adhesion_force_slope(self.E_star, a, self.dgamma, gs)
                          / gen.adhesion_depth_slope(self.E_star, a, self.dgamma, gs), float)

    def mean_pressure(self, *, depth=None, force=None):
        """Mean pressure F/(pi a^2) [Pa] (5.17) of the stable equilibrium at the given depth
        [m] or force [N]: negative where the adhesive contact is in tension."""
        a, _, F = self.equilibrium(depth=depth, force=force)
        return np.asarray(gen.disc_mean_pressure(F, a), float)

    # ------------------------------------------------------------------------ 3-D fields
    def pressure(self, r, a):
        """Contact pressure p(r) [Pa] at contact radius a [m] (5.59); 0 for r > a.

        The non-adhesive pressure of radius a plus the edge term -E* Delta l/(pi
        sqrt(a^2 - r^2)), which is -inf at r = a. A flat punch's a is its radius, and the
        pressure that at its pull-off depth (:meth:`pressure_at_depth` at any depth).
        """
        a = float(self._radius(a))
        return self._pressure(r, a, float(self.depth(a)))

    def pressure_at_depth(self, r, d):
        """Contact pressure p(r) [Pa] of the stable equilibrium at depth d [m] (a float)."""
        a = float(self.contact_radius(depth=float(as_float("d", d))))
        return self._pressure(r, a, float(d))

    def _pressure(self, r, a, d):
        r = nonnegative("r", r)
        inside = r < a
        rr = np.where(inside, r, 0.0)
        if isinstance(self.shape, Paraboloid):
            p = gen.jkr_pressure(self.E_star, self.shape.R, a, self.dgamma, rr)
        elif self._punch:  # Problem 7(a): singular at the edge with the sign of d
            p = gen.powerlaw_punch_pressure(self.E_star, a, d, rr)
            return np.where(inside, p, np.where(r == a, np.sign(d) * np.inf, 0.0))
        else:
            p = (self.shape.pressure0(rr, a, self.E_star)
                 + gen.adhesion_pressure_edge(self.E_star, a, self.dgamma, rr))
        return np.where(inside, p, np.where(r == a, -np.inf if self.dgamma else 0.0, 0.0))

    def surface_displacement(self, r, a):
        """Surface displacement u_z(r) [m] at contact radius a [m]: d - f(r) inside (5.54),
        (5.60) outside (the non-adhesive field of radius a plus the edge term). A flat
        punch: at its pull-off depth (:meth:`surface_displacement_at_depth` at any depth)."""
        a = float(self._radius(a))
        return self._displacement(r, a, float(self.depth(a)))

    def surface_displacement_at_depth(self, r, d):
        """Surface displacement u_z(r) [m] of the stable equilibrium at depth d [m] (a
        float)."""
        a = float(self.contact_radius(depth=float(as_float("d", d))))
        d = float(d) if self._punch else float(self.depth(a))
        return self._displacement(r, a, d)

    def _displacement(self, r, a, d):
        r = nonnegative("r", r)
        inside = r <= a
        ro = np.where(inside, 2 * a, r)
        if self._punch:
            out = gen.powerlaw_punch_displacement_outside(a, d, ro)
        else:
            out = (self.shape.displacement0_outside(ro, a)
                   + gen.adhesion_displacement_outside_edge(self.E_star, a, self.dgamma, ro))
        return np.where(inside, d - self.shape.height(np.where(inside, r, 0.0)), out)

    # --------------------------------------------------------------------------- history
    def cycle(self, to: float, control: str = "depth", points: int = 1000,
              start: float | None = None) -> Cycle:
        """Approach, push to ``to`` (a depth [m] or a force [N]), retract to separation.

        Parameters
        ----------
        to : float
            The largest depth (control "depth") [m] or force (control "force") [N], > 0.
        control : str
            "depth" (displacement-controlled, a stiff instrument) or "force".
        points : int
            Number of points of the whole path (>= 20), jumps included.
        start : float, optional
            The depth [m] where the approach starts and the retract ends (default: below
            both 0 and the pull-off depth by a fifth of the depth range).

        Notes
        -----
        Out of contact the force is 0. Touching at d = 0 under depth control (F = 0 under
        force control), the contact jumps to the smallest stable state at that depth (force):
        the jump into contact. Loading follows the stable branch (dd/da > 0, resp.
        dF/da > 0), jumping at a maximum to the next stable state at the same depth (force);
        unloading follows it down to a minimum, then jumps to a smaller stable contact at the
        same depth (force) or separates: the pull-off. Under force control the separated
        probe is shown at F = 0 and the pull-off depth. The hysteresis is the closed integral
        of F dd: Gauss-Legendre in a along each branch (F d'(a), d' from the derived dd/da),
        plus F times the depth jump of each jump at constant force.
        """
        control = _control(control)
        to = float(positive("to", to))
        if int(points) != points or points < 20:
            raise ValueError(f"points = {points!r} is out of range; valid: an integer >= 20")
        if self._punch:
            return self._punch_cycle(to, control, int(points), start)
        far = self._far()
        ext = self._extrema(control, far) if self.dgamma > 0 else []
        mins = [a for a, k in ext if k == "min"]
        maxs = [a for a, k in ext if k == "max"]
        def val(a):
            return (float(self._value(control, a)))
        # loading: from the touch (depth or force 0) up the stable branches to `to`
        branches_load, jumps = [], []
        if self.dgamma == 0:
            a = 0.0
        else:
            a = self._stable_root(control, 0.0, 0.0, far, mins, maxs, smallest=True)
            jumps.append(Jump("jump into contact", (0.0, 0.0, 0.0), self._state(a)))
        cap = np.inf
        for m in sorted(x for x in maxs if x > a):
            if val(m) >= to:
                cap = m
                break
            branches_load.append((a, m))
            nxt = self._stable_root(control, val(m), m, far, mins, maxs, smallest=True)
            jumps.append(Jump("jump", self._state(m), self._state(nxt)))
            a = nxt
        if a == 0.0:  # no adhesion: the contact grows from a = 0 (doubling from 1e-300 m)
            a = 1e-300
        a_top = self._upper(control, to, a, cap)
        branches_load.append((a, a_top))
        if self.dgamma > 0 and a_top > far:
            mins = [x for x, k in self._extrema(control, a_top) if k == "min"]
        # unloading: down the stable branches from a_top
        branches_un, a = [], a_top
        while True:
            below = [x for x in mins if x < a]
            if not below:  # dgamma = 0: down to a = 0
                branches_un.append((a, 0.0))
                a_out = None
                break
            m = max(below)
            branches_un.append((a, m))
            nxt = self._stable_root(control, val(m), 0.0, m, mins, maxs, smallest=False)
            if nxt is None:
                a_out = m
                break
            jumps.append(Jump("jump", self._state(m), self._state(nxt)))
            a = nxt
        if a_out is not None:
            before = self._state(a_out)
            jumps.append(Jump("pull-off", before, (before[0], 0.0, 0.0)))
        d_sep = jumps[-1].after[0] if a_out is not None else 0.0
        d_top = float(self.depth(a_top))
        if start is None:
            low = min(0.0, d_sep)
            start = low - 0.2 * (d_top - low)
        start = float(as_float("start", start))
        if start > min(0.0, d_sep):
            raise ValueError(f"start = {start!r} m is in contact; valid: start <= "
                             f"{min(0.0, d_sep)!r} m (below the touch and the pull-off depth)")
        cyc = self._assemble(control, int(points), start, d_sep, branches_load, branches_un,
                             jumps)
        if self.dgamma == 0:
            # without adhesion the unloading retraces the loading curve and nothing jumps: the
            # cycle dissipates nothing, exactly. The quadrature of the two branches leaves their
            # roundings instead (3.9e-34 J with an estimate of 1.2e-32 J for a 20 nm sphere on
            # PDMS, -5e-29 J for a cone), whose ratio the scene reported as a relative error
            cyc = replace(cyc, hysteresis=0.0, hysteresis_error=0.0)
        twin = self.shape.companion()
        if twin is not None and self.dgamma > 0:
            # the numerical MDR: the curve itself (its pull-off radius above all, where
            # W moves at first order) carries the samples' error, which the quadrature's
            # estimate does not see: add the coarse-vs-fine difference, as pull_off does
            other = AdhesiveContact(twin, self.E_star, self.dgamma).cycle(to, control, 20)
            cyc = replace(cyc, hysteresis_error=cyc.hysteresis_error
                          + abs(other.hysteresis - cyc.hysteresis))
        return cyc

    def _state(self, a):
        return (float(self.depth(a)), float(self.force(a)), float(a))

    def _stable_root(self, control, target, a_lo, a_hi, mins, maxs, *, smallest):
        """A stable state (rising branch) with value ``target`` in (a_lo, a_hi): the smallest
        (loading) or the largest (unloading) one; None when there is none."""
        marks = sorted({a_lo, a_hi, *[x for x in mins + maxs if a_lo < x < a_hi]})
        if marks[0] == 0.0:
            marks[0] = min(self.shape.scale(self.E_star, self.dgamma), a_hi) * 1e-9
        def f(a):
            return (float(self._value(control, a)) - target)
        cands = []
        for lo, hi in zip(marks[:-1], marks[1:], strict=True):
            flo, fhi = f(lo), f(hi)
            if flo < 0 <= fhi:  # rising through the target
                cands.append(hi if fhi == 0 else brentq(f, lo, hi, xtol=1e-300,
                                                         rtol=4 * _EPS, maxiter=300))
        if not cands:
            if smallest:
                raise ValueError(f"no stable state at {control} = {target!r} below a = "
                                 f"{a_hi!r} m")
            return None
        return min(cands) if smallest else max(cands)

    def _branch_points(self, branches, n):
        """Radii along each branch, n in all: both ends of every branch, the rest shared in
        proportion to the branches' lengths (largest remainders), so that a path has the
        points asked for (n >= 2 per branch; more branches than n/2 get 2 each)."""
        lengths = np.array([abs(b - a) for a, b in branches], float)
        k = np.full(len(branches), 2)
        extra = n - 2 * len(branches)
        if extra > 0:
            total = lengths.sum()
            share = extra * (lengths / total if total > 0 else np.full(len(k), 1 / len(k)))
            k += np.floor(share).astype(int)
            rest = extra - int(np.floor(share).sum())
            k[np.argsort(np.floor(share) - share, kind="stable")[:rest]] += 1
        return [np.linspace(a, b, int(m)) for (a, b), m in zip(branches, k, strict=True)]

    def _branch(self, a, b):
        """(d, F, dd/da) as functions of arrays of radii in the branch [min(a, b), max(a, b)].

        The closed forms: the shape's. A sampled profile: its g, g' and G (one quadrature each
        for all radii asked at once) are shared along the branch by Chebyshev interpolation
        on ``n`` points (32, 64 or 128), accepted where it reproduces the quadrature at the
        midpoints between nodes to 1e-12 of each function's largest value (else the
        quadrature at every radius); a branch across a kink of the profile always takes the
        quadrature."""
        lo, hi = min(a, b), max(a, b)
        sh, E, dg = self.shape, self.E_star, self.dgamma

        def curve(x, g, gs, G):
            dl = gen.adhesion_critical_elongation(E, x, dg)
            return g - dl, gen.mdr_force(E, x, g, G) - 2 * E * x * dl, \
                gen.adhesion_depth_slope(E, x, dg, gs)  # (5.55), (5.57), adhesive

        direct = (lambda x: (self.depth(x), self.force(x),  # noqa: E731
                             gen.adhesion_depth_slope(E, x, dg, sh.g_slope(x))))
        if not isinstance(sh, Sampled) or not hi > lo or any(lo < k <= hi for k in sh.kinks):
            return direct
        from scipy.interpolate import BarycentricInterpolator

        for n in (32, 64, 128):
            t = np.cos(np.pi * np.arange(n + 1) / n)  # Chebyshev points of the second kind
            mid = np.cos(np.pi * (np.arange(n) + 0.5) / n)
            x = lo + (hi - lo) * (np.concatenate([t, mid]) + 1) / 2
            vals = sh._tables(x)
            fits = [BarycentricInterpolator(x[:n + 1], v[:n + 1]) for v in vals]
            if all(np.max(np.abs(f(x[n + 1:]) - v[n + 1:])) <= 1e-12 * np.max(np.abs(v))
                   for f, v in zip(fits, vals, strict=True)):
                return lambda xx, fits=fits: curve(np.asarray(xx, float),
                                                   *(f(xx) for f in fits))
        return direct

    def _work(self, branches, evals):
        """sum of the integrals of F d'(a) da along the branches, and an error estimate."""
        tot, err = 0.0, 0.0
        for (a, b), ev in zip(branches, evals, strict=True):
            if a == b:
                continue
            vals = []
            for m in (_GL_NODES, 2 * _GL_NODES):
                u, w = _gauss_legendre(m)
                s = 3 * u**2 - 2 * u**3  # smoothstep: kills 1/sqrt endpoint singularities
                x = a + (b - a) * s
                jac = (b - a) * 6 * u * (1 - u)
                _, F, dd = ev(x)
                vals.append(float(np.sum(w * jac * F * dd)))
            tot += vals[1]
            err += abs(vals[1] - vals[0])
        return tot, err

    def _assemble(self, control, points, start, d_sep, branches_load, branches_un, jumps):
        n_free = max(2, points // 10)
        n_contact = points - 2 * n_free
        load = self._branch_points(branches_load, n_contact // 2)
        unload = self._branch_points(branches_un, n_contact - n_contact // 2)
        d_parts, F_parts, a_parts, l_parts = [], [], [], []

        def add(d, F, a, loading):
            d_parts.append(np.asarray(d, float))
            F_parts.append(np.asarray(F, float))
            a_parts.append(np.asarray(a, float))
            l_parts.append(np.full(np.shape(d), loading))

        ev_load = [self._branch(a, b) for a, b in branches_load]
        ev_un = [self._branch(a, b) for a, b in branches_un]
        dz = np.linspace(start, 0.0, n_free)
        add(dz, 0 * dz, 0 * dz, True)
        for aa, ev in zip(load, ev_load, strict=True):
            d, F, _ = ev(aa)
            add(d, F, aa, True)
        for aa, ev in zip(unload, ev_un, strict=True):
            pos = aa[aa > 0]
            d, F, _ = ev(pos)
            z = np.zeros(aa.size - pos.size)  # a = 0 (no adhesion, down to the touch): d = F = 0
            add(np.concatenate([d, z]), np.concatenate([F, z]), np.concatenate([pos, z]), False)
        dr = np.linspace(d_sep, start, n_free)
        add(dr, 0 * dr, 0 * dr, False)
        w_load, e_load = self._work(branches_load, ev_load)
        w_un, e_un = self._work(branches_un, ev_un)
        # jumps at constant force do work F * (d_after - d_before); at constant depth none
        w_jumps = sum(j.before[1] * (j.after[0] - j.before[0]) for j in jumps)
        W = w_load + w_un + w_jumps
        return Cycle(np.concatenate(d_parts), np.concatenate(F_parts),
                     np.concatenate(a_parts), np.concatenate(l_parts), jumps, W,
                     e_load + e_un + 8 * _EPS * abs(W), control)

    def _punch_cycle(self, to, control, points, start):
        a = self.shape.radius
        k = float(gen.mdr_stiffness(self.E_star, a))  # (5.12)
        d_top = to if control == "depth" else to / k
        d_c = -float(gen.adhesion_critical_elongation(self.E_star, a, self.dgamma))
        F_c = k * d_c
        if start is None:
            start = d_c - 0.2 * (d_top - d_c)
        start = float(as_float("start", start))
        if start > d_c:
            raise ValueError(f"start = {start!r} m is in contact; valid: start <= {d_c!r} m")
        n = points // 4
        d = np.concatenate([np.linspace(start, 0, n), np.linspace(0, d_top, n),
                            np.linspace(d_top, d_c, n), np.linspace(d_c, start, points - 3 * n)])
        F = np.concatenate([np.zeros(n), k * d[n:2 * n], k * d[2 * n:3 * n],
                            np.zeros(points - 3 * n)])
        aa = np.zeros(points)
        aa[n:3 * n] = a
        loading = np.arange(points) < 2 * n
        jumps = [Jump("pull-off", (d_c, F_c, a), (d_c, 0.0, 0.0))] if self.dgamma else []
        W = float(gen.adhesion_punch_cycle_work(self.E_star, a, self.dgamma))  # closed F dd
        return Cycle(d, F, aa, loading, jumps, W, 8 * _EPS * W, control)
