"""Tangential contact with Coulomb friction by the MDR: closed forms and a history solver.

Floats or NumPy arrays in SI units; bad input raises ValueError naming it. The formulas are
generated from :mod:`hertzmdr.derive.tangential` (the derivation, with Masing's rule and the
energy per cycle found from the springs) and :mod:`hertzmdr.derive.cerruti`; this module
validates, broadcasts, dispatches and integrates where there is no closed form.

Closed forms, one class per profile with one signature (:data:`PROFILES`)::

    from hertzmdr.numeric import tangential as tg
    G_star = tg.effective_modulus(G1, nu1, G2, nu2)
    c = tg.Contact(tg.Paraboloid(R=0.01), a=a, E_star=E_star, G_star=G_star, mu=0.6)
    c.stick_radius(u_x), c.force(u_x), c.displacement(F_x), c.traction(r, u_x)
    c.energy(F_amp)                     # per cycle of F_x oscillating in [-F_amp, F_amp]
    u, F = c.loop(F_amp, 1000)          # the hysteresis loop (Masing branches)

A displacement beyond the onset of sliding gives F_x = +-mu F_N (the springs all slide); a force
|F_x| > mu F_N is refused. mu = 0 is allowed: no tangential force, nothing dissipated.

The history solver (:func:`history`) runs the springs of the MDR through any sequence of
(normal depth or force, tangential displacement or force) states, on a grid, with memory: each
spring keeps its elastic shear between steps, new springs enter without shear, springs that
lose contact release it. It works for any MDR profile g(x) (a callable, or an
:class:`hertzmdr.numeric.mdr.Profile` for sampled profiles) and estimates its grid error by a
second run on half the grid.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import cone as _cone
from hertzmdr.numeric import powerlaw as _powerlaw
from hertzmdr.numeric._validate import as_float, nonnegative, poisson, positive, result, scalar_path

__all__ = ["effective_modulus", "shear_modulus", "stiffness_ratio", "stiffness", "sliding_force",
           "Paraboloid", "Cone", "PowerLaw", "FlatPunch", "PROFILES", "Contact",
           "history", "History", "GAUSS_NODES", "ENERGY_QUADRATURE_BELOW"]

#: Gauss-Legendre nodes of the power law's energy density where the closed form cancels
GAUSS_NODES = 24


#: within this many ulp under the onset of sliding a stick-zone form that rounds to NaN
#: (its radicand 1 - u/onset below 0) takes the full-slip value, its limit at the onset
ONSET_ULPS = 64


#: the power law's energy per cycle is integrated (not taken from its closed form, which
#: cancels like (1 - c/a)^3) where 1 - c/a is below this
ENERGY_QUADRATURE_BELOW = 0.25
#: the power law's stick-zone traction is the series about the axis for r <= this times c
#: (derive/tangential.py STICK_CENTRE_RADIUS: its terms fall at least 4-fold each there)
STICK_CENTRE_RADIUS = 0.5
#: and for c >= this times a (elsewhere beyond c/2) (5.59) over c < x < a by Gauss-Legendre:
#: there the difference of the two pressures loses 1 - c/a of its digits
STICK_QUADRATURE_ABOVE = 2 / 3


@scalar_path
def shear_modulus(E, nu):
    """Shear modulus G = E/(2 (1 + nu)) [Pa] (Lame's mu).

    Parameters
    ----------
    E : float or array_like
        Young's modulus [Pa], > 0.
    nu : float or array_like
        Poisson's ratio, -1 < nu <= 0.5.
    """
    return result(gen.shear_modulus(positive("E", E), poisson("nu", nu)))


def effective_modulus(G1, nu1, G2, nu2):
    """Tangential effective modulus G* [Pa], 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2).

    The tangential springs of the MDR have the stiffness G* dx, as the normal ones have E* dx
    (5.51); G_i* = 4 G_i/(2 - nu_i) is the direction average of the Cerruti compliance.
    ``G2 = inf`` is a rigid second body.

    Parameters
    ----------
    G1, G2 : float or array_like
        Shear moduli [Pa], > 0 (G2 may be inf).
    nu1, nu2 : float or array_like
        Poisson's ratios, -1 < nu <= 0.5.
    """
    G1 = positive("G1", G1, allow_inf=True)
    G2 = positive("G2", G2, allow_inf=True)
    if np.any(np.isinf(G1) & np.isinf(G2)):
        raise ValueError("G1 = G2 = inf: two rigid bodies have no tangential compliance; "
                         "valid: at least one finite shear modulus")
    return result(gen.tangential_modulus(G1, poisson("nu1", nu1), G2, poisson("nu2", nu2)))


@scalar_path
def stiffness_ratio(nu):
    """G*/E* = 2 (1 - nu)/(2 - nu) [1]: tangential over normal stiffness of one elastic body
    (Poisson's ratio nu) on a rigid one."""
    return result(gen.tangential_stiffness_ratio(poisson("nu", nu)))


@scalar_path
def stiffness(a, G_star):
    """Tangential contact stiffness k_x = 2 G* a [N/m] before any slip.

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], >= 0.
    G_star : float or array_like
        Tangential effective modulus [Pa], > 0.
    """
    return result(gen.tangential_stiffness(positive("G_star", G_star), nonnegative("a", a)))


@scalar_path
def sliding_force(mu, F_N):
    """Coulomb's limit mu F_N [N]: the tangential force once every spring slides.

    Parameters
    ----------
    mu : float or array_like
        Coefficient of friction, >= 0.
    F_N : float or array_like
        Normal force [N], >= 0.
    """
    return result(gen.coulomb_sliding_force(nonnegative("mu", mu), nonnegative("F_N", F_N)))


# ------------------------------------------------------------------------------ profiles
@dataclass(frozen=True)
class Paraboloid:
    """f = r^2/(2 R): Cattaneo-Mindlin, Mindlin-Deresiewicz. R [m] > 0."""

    R: float

    def __post_init__(self):
        object.__setattr__(self, "R", float(positive("R", self.R)))

    def g(self, x):
        """MDR profile g(x) = x^2/R [m] (5.52)."""
        return gen.paraboloid_g(self.R, np.asarray(x, float))  # (5.52)

    def normal_force(self, a, E_star):
        return gen.powerlaw_force_from_radius(E_star, a, self.g(a), 2.0)  # (5.57), (5.23)

    def slide_onset(self, a, E_star, G_star, mu):
        return gen.tangential_slide_onset(E_star, G_star, mu, self.g(a))  # d = g(a) (5.55)

    def stick_radius(self, u, a, E_star, G_star, mu):
        return gen.cattaneo_stick_radius(a, self.R, E_star, G_star, mu, u)

    def force(self, u, a, E_star, G_star, mu):
        return gen.cattaneo_force(a, self.R, E_star, G_star, mu, u)

    def displacement(self, F_x, F, a, E_star, G_star, mu):
        return gen.cattaneo_displacement(a, F, G_star, mu, F_x)

    def stick_radius_from_force(self, F_x, F, a, mu):
        return gen.cattaneo_stick_radius_from_force(a, F, mu, F_x)

    def traction(self, r, c, a, E_star, G_star, mu, u):
        stick = gen.cattaneo_traction_stick(r, a, c, self.R, E_star, mu)
        slip = gen.cattaneo_traction_slip(r, a, self.R, E_star, mu)
        return stick, slip

    def energy(self, F_amp, F, a, G_star, mu):
        return gen.mindlin_energy(a, F, G_star, mu, F_amp)

    def energy_small(self, F_amp, F, a, G_star, mu):
        return gen.mindlin_energy_small(a, F, G_star, mu, F_amp)


@dataclass(frozen=True)
class Cone:
    """f = r tan(theta), theta [rad] in (0, pi/2) the angle between surface and plane."""

    theta: float

    def __post_init__(self):
        object.__setattr__(self, "theta", float(_cone._theta(self.theta)))

    def g(self, x):
        """MDR profile g(x) = (pi/2) tan(theta) |x| [m] (5.52)."""
        return gen.cone_g(self.theta, np.abs(np.asarray(x, float)))  # (5.52)

    def normal_force(self, a, E_star):
        return _cone.force(_cone.depth(a, self.theta), self.theta, E_star)

    def slide_onset(self, a, E_star, G_star, mu):
        return gen.tangential_slide_onset(E_star, G_star, mu, self.g(a))  # d = g(a) (5.55)

    def stick_radius(self, u, a, E_star, G_star, mu):
        return gen.tangential_cone_stick_radius(a, self.theta, E_star, G_star, mu, u)

    def force(self, u, a, E_star, G_star, mu):
        return gen.tangential_cone_force(a, self.theta, E_star, G_star, mu, u)

    def displacement(self, F_x, F, a, E_star, G_star, mu):
        return gen.tangential_cone_displacement(a, F, G_star, mu, F_x)

    def stick_radius_from_force(self, F_x, F, a, mu):
        return gen.tangential_powerlaw_stick_radius_from_force(a, 1.0, F, mu, F_x)

    def traction(self, r, c, a, E_star, G_star, mu, u):
        p_a = _cone.pressure(r, _cone.depth(a, self.theta), self.theta, E_star)
        slip = gen.tangential_traction_slip(mu, p_a)  # Coulomb: the sliding springs
        # mu (p(r; a) - p(r; c)) as one log1p: finite on the axis, ln(a/c) there; c = 0 (all
        # slide) gives inf, and the caller takes the slip value there (r < c is empty)
        with np.errstate(divide="ignore", invalid="ignore"):
            stick = gen.tangential_cone_traction_stick(r, a, c, self.theta, E_star, mu)
        return stick, slip

    def energy(self, F_amp, F, a, G_star, mu):
        return gen.tangential_cone_energy(a, F, G_star, mu, F_amp)

    def energy_small(self, F_amp, F, a, G_star, mu):
        return gen.tangential_powerlaw_energy_small(a, 1.0, F, G_star, mu, F_amp)


@dataclass(frozen=True)
class PowerLaw:
    """f = c_n r^n: c_n [m^(1-n)] > 0, n > 0 (n = 2, c_n = 1/(2R) is the paraboloid)."""

    c_n: float
    n: float

    def __post_init__(self):
        object.__setattr__(self, "c_n", float(positive("c_n", self.c_n)))
        object.__setattr__(self, "n", float(positive("n", self.n)))

    @property
    def kappa(self) -> float:
        return float(_powerlaw.kappa(self.n))

    def g(self, x):
        """MDR profile g(x) = kappa_n c_n |x|^n [m] (5.52)."""
        return _powerlaw.g_profile(x, self.c_n, self.n)

    def normal_force(self, a, E_star):
        return _powerlaw.force_from_radius(a, self.g(a), self.n, E_star)

    def slide_onset(self, a, E_star, G_star, mu):
        return gen.tangential_slide_onset(E_star, G_star, mu, self.g(a))  # d = g(a) (5.55)

    def stick_radius(self, u, a, E_star, G_star, mu):
        return gen.tangential_powerlaw_stick_radius(a, self.c_n, self.n, self.kappa, E_star,
                                                    G_star, mu, u)

    def force(self, u, a, E_star, G_star, mu):
        return gen.tangential_powerlaw_force(a, self.c_n, self.n, self.kappa, E_star, G_star,
                                             mu, u)

    def displacement(self, F_x, F, a, E_star, G_star, mu):
        return gen.tangential_powerlaw_displacement(a, self.n, F, G_star, mu, F_x)

    def stick_radius_from_force(self, F_x, F, a, mu):
        return gen.tangential_powerlaw_stick_radius_from_force(a, self.n, F, mu, F_x)

    def traction(self, r, c, a, E_star, G_star, mu, u):
        if self.n == 1:  # the cone f = r tan(theta), tan(theta) = c_1: its own log1p form
            return Cone(float(np.arctan(self.c_n))).traction(r, c, a, E_star, G_star, mu, u)
        p_a = _powerlaw.pressure(r, self.g(a), self.c_n, self.n, E_star)
        p_c = _powerlaw.pressure(np.minimum(r, c), self.g(c), self.c_n, self.n, E_star)
        with np.errstate(invalid="ignore"):  # inf - inf on the axis for n <= 1: replaced below
            stick = gen.tangential_traction_stick(mu, p_a, p_c)  # the stick superposition
        r, c = np.broadcast_arrays(r, c)
        stick = np.array(stick, dtype=float, copy=True)
        near = (c > 0) & (r <= STICK_CENTRE_RADIUS * c) & (self.n < 3)
        # near the axis the difference of the two pressures (each infinite on the axis for
        # n <= 1) as the series of (5.59) over c < x < a: finite, without cancellation
        stick[near] = gen.tangential_powerlaw_traction_stick_centre(
            r[near] / c[near], a, c[near], self.c_n, self.n, self.kappa, E_star, mu)
        # a nearly stuck contact (c close to a): the two pressures cancel to 1 - c/a; (5.59)
        # over c < x < a by Gauss-Legendre in s = sqrt(x^2 - r^2), smooth for every r < c
        edge = ~near & (c > 0) & (r < c) & (c >= STICK_QUADRATURE_ABOVE * a)
        stick[edge] = self._stick_by_quadrature(r[edge], c[edge], a, E_star, mu)
        return stick, gen.tangential_traction_slip(mu, p_a)  # Coulomb: the sliding springs

    def _stick_by_quadrature(self, r, c, a, E_star, mu):
        """(5.59) of the stuck springs' line load over c < x < a at r < c, by GAUSS_NODES
        Gauss-Legendre nodes in s = sqrt(x^2 - r^2) (its integrand is smooth there, its
        nearest singularities s = +-i r at least 1.8 half-lengths away for c >= 2a/3)."""
        s_c = np.sqrt((c - r) * (c + r))
        s_a = np.sqrt((a - r) * (a + r))
        half = (a - c) * (a + c) / (s_a + s_c) / 2  # (s_a - s_c)/2 without cancellation
        z, w = np.polynomial.legendre.leggauss(GAUSS_NODES)
        s = (s_c + half)[..., None] + half[..., None] * z
        f = gen.tangential_powerlaw_traction_stick_integrand(
            r[..., None], s, self.c_n, self.n, self.kappa, E_star, mu)
        return half * np.sum(w * f, axis=-1)

    def energy(self, F_amp, F, a, G_star, mu):
        n = self.n
        with np.errstate(divide="ignore"):
            d_c = gen.tangential_powerlaw_stick_deficit(n, F, mu, F_amp)  # 1 - c/a
        closed = gen.tangential_powerlaw_energy(a, n, F, G_star, mu, 1 - d_c)
        # in a thin slip zone the closed form cancels like (1 - c/a)^3: integrate the density
        # over the slip zone (smooth and positive there) by Gauss-Legendre instead
        z, w = np.polynomial.legendre.leggauss(GAUSS_NODES)
        dc = np.asarray(d_c, float)[..., None]
        dens = gen.tangential_powerlaw_energy_density(n, dc, (z + 1) / 2)
        J = np.asarray(d_c) * np.sum(dens * w, axis=-1) / 2
        quad = gen.tangential_powerlaw_energy_scale(a, n, F, G_star, mu) * J
        return np.where(np.asarray(d_c) < ENERGY_QUADRATURE_BELOW, quad, closed)

    def energy_small(self, F_amp, F, a, G_star, mu):
        return gen.tangential_powerlaw_energy_small(a, self.n, F, G_star, mu, F_amp)


@dataclass(frozen=True)
class FlatPunch:
    """Flat cylindrical punch of radius a (g = 0 inside): all springs carry the same normal
    load, so all stick until F_x = mu F_N and then all slide; no partial slip, no dissipation
    below sliding. ``depth`` [m] > 0 is the indentation."""

    depth: float

    def __post_init__(self):
        object.__setattr__(self, "depth", float(positive("depth", self.depth)))

    def normal_force(self, a, E_star):
        return gen.powerlaw_punch_force(E_star, a, self.depth)  # (5.11)

    def slide_onset(self, a, E_star, G_star, mu):
        return gen.tangential_slide_onset(E_star, G_star, mu, self.depth)

    def stick_radius(self, u, a, E_star, G_star, mu):
        return np.broadcast_arrays(np.asarray(a, float), np.asarray(u, float))[0].copy()

    def force(self, u, a, E_star, G_star, mu):
        return gen.tangential_stiffness(G_star, a) * u

    def displacement(self, F_x, F, a, E_star, G_star, mu):
        return F_x / gen.tangential_stiffness(G_star, a)

    def stick_radius_from_force(self, F_x, F, a, mu):
        return np.broadcast_arrays(np.asarray(a, float), np.asarray(F_x, float))[0].copy()

    def traction(self, r, c, a, E_star, G_star, mu, u):
        stick = gen.flat_punch_tangential_traction(r, a, G_star, u)
        return stick, stick

    def energy(self, F_amp, F, a, G_star, mu):
        return np.zeros_like(np.asarray(F_amp, float))

    def energy_small(self, F_amp, F, a, G_star, mu):
        return np.zeros_like(np.asarray(F_amp, float))


PROFILES = {"paraboloid": Paraboloid, "cone": Cone, "power_law": PowerLaw,
            "flat_punch": FlatPunch}


def _profile(profile):
    if not isinstance(profile, tuple(PROFILES.values())):
        raise ValueError(f"profile = {profile!r} is not one of {sorted(PROFILES)} "
                         "(tangential.Paraboloid(R=...), Cone(theta=...), PowerLaw(c_n=..., "
                         "n=...), FlatPunch(depth=...)); for any other profile use history()")
    return profile


@dataclass(frozen=True)
class Contact:
    """A closed-form profile in contact at radius ``a`` [m] under constant normal load.

    Parameters
    ----------
    profile : Paraboloid, Cone, PowerLaw or FlatPunch
        The gap profile.
    a : float
        Contact radius [m], > 0 (the normal load is that of this radius, (5.55), (5.57)).
    E_star : float
        Effective modulus [Pa], > 0 (5.26).
    G_star : float
        Tangential effective modulus [Pa], > 0 (:func:`effective_modulus`).
    mu : float
        Coefficient of friction, >= 0.
    """

    profile: Paraboloid | Cone | PowerLaw | FlatPunch
    a: float
    E_star: float
    G_star: float
    mu: float
    normal_force: float = field(init=False)

    def __post_init__(self):
        _profile(self.profile)
        for name in ("a", "E_star", "G_star"):
            object.__setattr__(self, name, float(positive(name, getattr(self, name))))
        object.__setattr__(self, "mu", float(nonnegative("mu", self.mu)))
        object.__setattr__(self, "normal_force",
                           float(self.profile.normal_force(self.a, self.E_star)))

    # -- scalars ---------------------------------------------------------------------------
    @property
    def sliding_force(self) -> float:
        """mu F_N [N]: the tangential force of full sliding (Coulomb)."""
        return float(gen.coulomb_sliding_force(self.mu, self.normal_force))

    @property
    def slide_onset(self) -> float:
        """Tangential displacement [m] at which the last spring starts to slide."""
        return float(self.profile.slide_onset(self.a, self.E_star, self.G_star, self.mu))

    @property
    def stiffness(self) -> float:
        """Initial tangential stiffness 2 G* a [N/m]."""
        return float(stiffness(self.a, self.G_star))

    def _args(self):
        return self.a, self.E_star, self.G_star, self.mu

    def _force_in_range(self, name, value):
        value = as_float(name, value)
        lim = self.sliding_force
        bad = np.abs(value) > lim * (1 + 4 * np.finfo(float).eps)
        if np.any(bad):
            v = float(np.asarray(value)[bad].flat[0])
            raise ValueError(f"{name} = {v!r} exceeds the sliding force mu F_N = {lim!r} N "
                             f"(mu = {self.mu}, F_N = {self.normal_force!r} N); valid: "
                             f"|{name}| <= mu F_N")
        return np.clip(value, -lim, lim)

    # -- monotonic loading -----------------------------------------------------------------
    def _clip_at_onset(self, form, au, full):
        """``form(min(au, onset))`` for the displacements ``au`` >= 0 [m] below the onset of
        sliding, ``full`` (the full-slip value) at and beyond it.

        The stick-zone forms hold for au < onset; they reach the full-slip value through a
        radicand or logarithm of 1 - au/onset, which the rounding of the onset and of the form
        can push below 0 within a few ulp under the onset (NaN). There, and only there
        (au >= (1 - ONSET_ULPS eps) onset), the value is the limit au -> onset: ``full``.
        """
        on = self.slide_onset
        with np.errstate(invalid="ignore", divide="ignore"):
            v = np.asarray(form(np.minimum(au, on), *self._args()), float)
        rounded = (au >= on * (1 - ONSET_ULPS * np.finfo(float).eps)) & ~np.isfinite(v)
        return np.where((au >= on) | rounded, full, v)

    def stick_radius(self, u_x):
        """Stick radius c [m] at the tangential displacement u_x [m] (monotonic from 0);
        0 once everything slides (at and beyond the onset of sliding, exactly)."""
        u = np.abs(as_float("u_x", u_x))
        if self.mu == 0:
            return result(np.zeros_like(u))
        c = self._clip_at_onset(self.profile.stick_radius, u, 0.0)
        return result(np.maximum(c, 0.0))

    def force(self, u_x):
        """Tangential force F_x [N] at the displacement u_x [m] (monotonic from 0, odd in u_x);
        mu F_N at and beyond the onset of sliding, exactly."""
        u = as_float("u_x", u_x)
        if self.mu == 0:
            return result(np.zeros_like(u))
        lim = self.sliding_force
        Fx = self._clip_at_onset(self.profile.force, np.abs(u), lim)
        return result(np.sign(u) * np.minimum(Fx, lim))

    def displacement(self, F_x):
        """Tangential displacement u_x [m] under the tangential force F_x [N], |F_x| <= mu F_N
        (odd in F_x); at |F_x| = mu F_N the onset of sliding."""
        Fx = self._force_in_range("F_x", F_x)
        if self.mu == 0:
            return result(np.zeros_like(Fx))
        with np.errstate(divide="ignore"):
            u = self.profile.displacement(np.abs(Fx), self.normal_force, *self._args())
        return result(np.sign(Fx) * u)

    def stick_radius_from_force(self, F_x):
        """Stick radius c [m] under the tangential force F_x [N], |F_x| <= mu F_N."""
        Fx = np.abs(self._force_in_range("F_x", F_x))
        if self.mu == 0:
            return result(np.zeros_like(Fx))
        return result(self.profile.stick_radius_from_force(Fx, self.normal_force, self.a,
                                                           self.mu))

    def traction(self, r, u_x):
        """Tangential traction q(r) [Pa] (in the direction of u_x) at radii r [m] after the
        monotonic displacement u_x [m]: mu (p(r; a) - p(r; c)) in the stick zone, mu p(r; a)
        in the slip zone (derived, not assumed: derive/tangential.py), 0 outside.

        In the stick zone it is finite on the axis for every profile (for the cone and the
        power law with n < 3 near the axis, r <= c/2, by the series of (5.59) over c < x < a:
        tangential_powerlaw_traction_stick_centre). Once every spring slides (c = 0) the
        traction is mu p(r; a), and on the axis that is +inf for the cone and the power law
        with n <= 1: their pressure is infinite there (a logarithmic or r^(n-1) singularity),
        reported as inf, not NaN."""
        r = nonnegative("r", r)
        u = as_float("u_x", u_x)
        r, u = np.broadcast_arrays(r, u)
        inside = r < self.a
        rr = np.where(inside, r, 0.5 * self.a)
        if self.mu == 0 and not isinstance(self.profile, FlatPunch):
            return result(np.zeros_like(rr))
        c = self.stick_radius(u) if not isinstance(self.profile, FlatPunch) else self.a
        c = np.broadcast_to(c, rr.shape)
        au = np.minimum(np.abs(u), self.slide_onset)
        # the stick-zone form is used for r < c only; c >= r keeps its square roots real
        stick, slip = self.profile.traction(rr, np.maximum(c, rr), *self._args(), au)
        q = np.where(rr < c, stick, slip)
        return result(np.where(inside, np.sign(u) * q, 0.0))

    # -- oscillation -----------------------------------------------------------------------
    def energy(self, F_amp):
        """Energy W [J] dissipated per cycle of F_x oscillating between -F_amp and F_amp [N],
        0 <= F_amp <= mu F_N (Mindlin-Deresiewicz for the paraboloid)."""
        Fa = np.abs(self._force_in_range("F_amp", F_amp))
        if self.mu == 0:
            return result(np.zeros_like(Fa))
        with np.errstate(divide="ignore"):
            W = self.profile.energy(Fa, self.normal_force, self.a, self.G_star, self.mu)
        return result(W)

    def energy_small(self, F_amp):
        """Leading, cubic term [J] of :meth:`energy` at small amplitude F_amp [N]."""
        Fa = np.abs(self._force_in_range("F_amp", F_amp))
        if self.mu == 0:
            return result(np.zeros_like(Fa))
        return result(self.profile.energy_small(Fa, self.normal_force, self.a, self.G_star,
                                                self.mu))

    def loop(self, F_amp, n_points: int = 1000):
        """The hysteresis loop of F_x oscillating with amplitude F_amp [N]: ``(u, F)``.

        ``n_points`` (even, >= 4) points: the unloading branch from (u*, F_amp) to
        (-u*, -F_amp), then the reloading branch back, both by Masing's rule
        F = F_amp - 2 F_mono((u* - u)/2) (derived from the springs, masing_unloading_force).
        """
        Fa = float(np.abs(self._force_in_range("F_amp", F_amp)))
        if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) or (
                n_points < 4 or n_points % 2):
            raise ValueError(f"n_points = {n_points!r} is out of range; valid: an even "
                             "integer >= 4")
        ustar = float(self.displacement(Fa))
        half = n_points // 2
        s = np.linspace(0.0, 1.0, half)
        u_down = ustar - 2 * ustar * s
        F_down = gen.masing_unloading_force(Fa, self.force((ustar - u_down) / 2))
        u = np.concatenate([u_down, -u_down])
        F = np.concatenate([F_down, -F_down])
        return u, F


# ------------------------------------------------------------------------- history solver
@dataclass
class History:
    """The springs' answer to a load history, one entry per step (SI units).

    Per step: ``depth`` [m], ``normal_force`` [N], ``contact_radius`` [m], ``u_x`` [m],
    ``F_x`` [N], ``stick_radius`` [m] (the edge of the central stick zone; 0 when the centre
    slides), ``sliding`` (every spring in contact slides), ``dissipated`` [J] (cumulative
    friction work). ``*_error``: estimates of the grid error of the same quantities over the
    whole history: the largest difference from a run on half the grid (the method is second
    order, so this is about 3 times the error of the coarse run's fine partner; its
    pointwise error oscillates as the stick and contact edges cross the nodes, hence one
    number for the history), or None when the run was made with ``estimate_error=False``.
    When both loads change at once, the steps add an error of first order in the step size
    (not included: refine the steps). ``normal_force_error`` and ``contact_radius_error``
    are the same estimates for the normal springs; ``traction_error`` [Pa] is the largest
    difference of the final :meth:`traction` of the two runs at the coarse run's nodes,
    divided by sqrt(2) - 1: next to a stick-slip edge the traction converges like sqrt(h),
    where the difference of the runs on h and 2 h is (sqrt(2) - 1) times the error on h.
    Final state on the grid ``x`` [m]: the normal and tangential line loads ``q_z``, ``q_x``
    [N/m] and ``stuck`` (bool).
    """

    depth: np.ndarray
    normal_force: np.ndarray
    contact_radius: np.ndarray
    u_x: np.ndarray
    F_x: np.ndarray
    stick_radius: np.ndarray
    sliding: np.ndarray
    dissipated: np.ndarray
    x: np.ndarray
    q_z: np.ndarray
    q_x: np.ndarray
    stuck: np.ndarray
    u_x_error: float | None = None
    F_x_error: float | None = None
    stick_radius_error: float | None = None
    dissipated_error: float | None = None
    normal_force_error: float | None = None
    contact_radius_error: float | None = None
    traction_error: float | None = None

    def traction(self):
        """Final tangential traction q(r) [Pa] at r = ``x``: (5.59) applied to ``q_x``
        (numeric/abel.py). The line load has a kink at each stick-slip edge, where the
        traction has a square-root cusp: on the few nodes next to an edge the error is
        O(sqrt(h)) (0.3-0.9 % of the largest traction on 500-4000 intervals for the sphere),
        elsewhere about 1e-4 of it."""
        return _traction(self.x, self.q_x, float(self.contact_radius[-1]))


def _traction(x, q_x, a):
    """(5.59) of the tangential line load q_x [N/m] on the grid x [m] in a contact of radius a.

    The edge of q_x's support is left to abel (the root of the cubic through its last four
    non-zero samples: q_x = +-mu q_z vanishes like a - x): the solver's a is the root of
    the linear interpolant of g, O(h^2) off, which cost 9e-5 of mu p(0) at full slip on 100
    intervals, where the cubic is exact (mu E* (d - x^2/R) for the sphere)."""
    from hertzmdr.numeric import abel

    if a <= 0:
        return np.zeros_like(x)
    return abel.pressure_from_line_load(np.where(x < a, q_x, 0.0), float(x[1] - x[0]))


def _g_callable(g) -> Callable[[np.ndarray], np.ndarray]:
    if isinstance(g, FlatPunch):  # its g(x) is 0 inside its radius, which it does not hold
        raise ValueError(f"g = {g!r} holds no radius, and a flat punch's g(x) (0 inside its "
                         "radius a, a wall beyond) needs it; valid: a callable g(x) [m] with "
                         "its wall at x = a, or Contact(FlatPunch(...), a=...) for the closed "
                         "forms")
    if hasattr(g, "g") and callable(g.g):  # a closed-form profile or an mdr.Profile
        return g.g
    if callable(g):
        return g
    raise ValueError(f"g = {g!r} is neither a callable g(x) [m] nor a profile with a .g method")


def _series(name, value, n_steps=None):
    arr = np.atleast_1d(as_float(name, value))
    if arr.ndim != 1:
        raise ValueError(f"{name} must be a 1-D sequence of states; got shape {arr.shape}")
    if n_steps is not None and arr.size != n_steps:
        raise ValueError(f"{name} has {arr.size} states, the normal history has {n_steps}")
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}[{i}] = {float(arr[i])!r} is out of range; valid: finite")
    return arr


def _force_table(gv, w, E_star):
    """The normal force at d = g_k (nodes i <= k in contact) and the running sums that give it:
    E* sum_i w_i (d - g_i)_+ is piecewise linear in d, exact between nodes; with W = sum w_i
    and S = sum w_i g_i it is W times the line load (5.58) of the mean gap S/W."""
    W = np.cumsum(w)
    S = np.cumsum(w * gv)
    return W * gen.mdr_normal_line_load(E_star, gv, S / W), W, S


def _depth_of_force(F, table, E_star, step, x_max, wall=False):
    """d with E* sum_i w_i (d - g_i)_+ = F: the depth (5.58) at which the mean gap S/W of the
    springs in contact carries the mean line load F/W (beyond the last node, with a wall
    there, every spring is in contact)."""
    F_nodes, W, S = table
    k = int(np.searchsorted(F_nodes, F, side="right")) - 1
    if wall:
        k = min(k, F_nodes.size - 1)
    elif k >= F_nodes.size - 1:
        raise ValueError(f"normal_force[{step}] = {float(F)!r} N needs a contact wider than "
                         "the grid "
                         f"(x_max = {x_max!r} m); valid: a larger x_max")
    return gen.mdr_depth_of_line_load(E_star, S[k] / W[k], F / W[k])


def _solve_shift(f, cap, w, m, G_star, target, total, step):
    """Displacement increment D with sum_i w_i clip(f_i + G* m_i D, -cap_i, cap_i) = target."""
    live = (cap > 0) & (m > 0)
    k = gen.mdr_tangential_line_load(G_star, m[live])  # each spring's q_x per unit D
    lo = (-cap[live] - f[live]) / k
    hi = (cap[live] - f[live]) / k
    if target >= total:
        return float(hi.max()), True
    if target <= -total:
        return float(lo.min()), True
    b = np.concatenate([lo, hi])
    dslope = np.concatenate([w[live] * k, -w[live] * k])
    order = np.argsort(b, kind="stable")
    b, dslope = b[order], dslope[order]
    slope = np.cumsum(dslope)
    phi = -total + np.concatenate([[0.0], np.cumsum(slope[:-1] * np.diff(b))])
    m = int(np.searchsorted(phi, target, side="right")) - 1
    m = min(max(m, 0), b.size - 2)
    while slope[m] <= 0 and m < b.size - 2:  # a flat piece (coincident breakpoints)
        m += 1
    return float(b[m] + (target - phi[m]) / slope[m]), False


def _run(gfun, x_max, n, E_star, G_star, mu, depth, force, u_ctrl, F_ctrl, wall=False):
    x = np.linspace(0.0, x_max, n + 1)
    h = x_max / n
    gv = np.asarray(gfun(x), dtype=float)
    if gv.shape != x.shape or not np.all(np.isfinite(gv)) or np.any(np.diff(gv) < 0):
        raise ValueError("g(x) must be finite and non-decreasing on [0, x_max]")
    w = np.full(n + 1, 2 * h)  # the trapezoid rule on the symmetric line: 2 int_0^x_max
    w[0] = w[-1] = h
    steps = (depth if depth is not None else force).size
    out = {k: np.zeros(steps) for k in ("depth", "normal_force", "contact_radius", "u_x",
                                        "F_x", "stick_radius", "dissipated")}
    sliding = np.zeros(steps, bool)
    table = _force_table(gv, w, E_star) if force is not None else None
    f = np.zeros(n + 1)  # tangential line load of each spring [N/m]
    u_prev, W_acc, d_prev = 0.0, 0.0, 0.0
    ones = np.ones(n + 1)
    for k in range(steps):
        if depth is not None:
            d = depth[k]
            if d > gv[-1] and not wall:
                raise ValueError(f"depth[{k}] = {float(d)!r} m reaches beyond x_max = {x_max!r} m; "
                                 "valid: a larger x_max")
        else:
            d = (_depth_of_force(force[k], table, E_star, k, x_max, wall) if force[k] > 0
                 else 0.0)
        qz = gen.mdr_normal_line_load(E_star, d, np.minimum(gv, d))  # (5.58), 0 for g >= d
        cap = gen.coulomb_sliding_force(mu, qz)  # Coulomb's limit of each spring
        wcap = w * cap
        # springs that lost contact or normal load release their shear by sliding
        g_rel = np.minimum(np.maximum(f, -cap), cap)
        W_acc += float(wcap @ gen.mdr_tangential_spring_shear(G_star, np.abs(f - g_rel)))
        f = g_rel
        total = float(wcap.sum())
        # both loads change linearly within the step: a spring that comes into contact at
        # the fraction theta of the step (g_i = d_prev + theta (d - d_prev)) takes only the
        # tangential increment after it, (1 - theta) D
        if d > d_prev:
            m = np.clip((d - gv) / (d - d_prev), 0.0, 1.0)
        else:
            m = ones
        d_prev = d
        if u_ctrl is not None:
            D, full = u_ctrl[k] - u_prev, False
        else:
            if abs(F_ctrl[k]) > total * (1 + 1e-12) + 1e-300:
                raise ValueError(f"F_x[{k}] = {float(F_ctrl[k])!r} N exceeds the sliding force "
                                 f"mu F_N = {total!r} N of that step; valid: |F_x| <= mu F_N")
            D, full = _solve_shift(f, cap, w, m, G_star, F_ctrl[k], total, k) if total > 0 \
                else (0.0, True)
        trial = f + gen.mdr_tangential_line_load(G_star, m * D)
        f = np.minimum(np.maximum(trial, -cap), cap)  # Coulomb: |q_x| <= mu q_z
        # each sliding spring's slip (its excess shear) times its Coulomb line load
        W_acc += float(wcap @ gen.mdr_tangential_spring_shear(G_star, np.abs(trial - f)))
        u_prev = u_prev + D
        j = int(np.searchsorted(gv, d, side="left"))  # nodes i < j are in contact (g_i < d)
        slipping = np.abs(f[:j]) >= cap[:j]
        i = int(slipping.argmax()) if j else 0  # the first slipping node, if any
        any_slip = j > 0 and bool(slipping[i])
        out["depth"][k] = d
        out["normal_force"][k] = float(w @ qz)
        out["contact_radius"][k] = (x[j - 1] + h * (d - gv[j - 1]) / (gv[j] - gv[j - 1])
                                    if 0 < j <= n and gv[j] > gv[j - 1] else x[min(j, n)])
        out["u_x"][k] = u_prev
        out["F_x"][k] = F_ctrl[k] if F_ctrl is not None and not full else float(w @ f)
        out["dissipated"][k] = W_acc
        sliding[k] = j > 0 and bool(slipping.all())
        # central stick zone: up to the first slipping node; edge where cap(x) = |f| (linear)
        if j == 0 or (any_slip and i == 0):
            c = 0.0
        elif not any_slip:
            c = out["contact_radius"][k]
        else:
            # the edge where the stuck springs' |f| (linear through nodes i - 2, i - 1: it
            # varies along x after a normal load changed under a tangential one) meets cap
            # (linear between i - 1 and i)
            level = abs(f[i - 1])
            rise = level - abs(f[i - 2]) if i >= 2 else 0.0
            denom = cap[i - 1] - cap[i] + rise
            c = x[i - 1] + (h * (cap[i - 1] - level) / denom if denom > 0 else 0.0)
        out["stick_radius"][k] = c
    stuck = (qz > 0) & (np.abs(f) < cap)
    return out, sliding, x, qz, f, stuck


def history(g, *, E_star, G_star, mu, x_max, depth=None, normal_force=None, u_x=None,
            F_x=None, n_grid: int = 1000, estimate_error: bool = True,
            wall: bool = False) -> History:
    """Run the MDR's normal and tangential springs through a load history.

    Each state k is reached from state k - 1 by first changing the normal load (springs that
    lose normal load slide back to mu q_z), then the tangential displacement: each spring adds
    G* du until it reaches +-mu q_z and slides. Springs that come into contact during the step
    enter without shear and take only the part of du after their entry (both loads change
    linearly within a step). Rate-independent.

    Parameters
    ----------
    g : callable or profile
        The MDR profile g(x) [m] (5.52): a vectorized callable, a closed-form profile
        (:class:`Paraboloid`, :class:`Cone`, :class:`PowerLaw`; not :class:`FlatPunch`, which
        holds no radius) or an :class:`hertzmdr.numeric.mdr.Profile` (sampled).
        Non-decreasing on [0, x_max].
    E_star, G_star : float
        Effective normal (5.26) and tangential moduli [Pa], > 0.
    mu : float
        Coefficient of friction, >= 0.
    x_max : float
        Extent of the grid [m] > 0: larger than every contact radius of the history, or, with
        ``wall``, the radius of a flat punch's wall.
    depth, normal_force : sequence of float
        Exactly one: the normal depth [m] or force [N] at each state (>= 0).
    u_x, F_x : sequence of float
        Exactly one: the tangential displacement [m] or force [N] at each state (from 0 at
        the start); |F_x| <= mu F_N at each state.
    n_grid : int
        Intervals of the grid on [0, x_max] (>= 8, even).
    estimate_error : bool
        Also run on n_grid/2 intervals and report the grid error of the history (the method is
        second order in the spacing: the trapezoid rule across the contact and stick edges).
    wall : bool
        g is infinite beyond x_max (a flat punch of radius x_max: g = 0 inside, Problem 7 a):
        a depth beyond g(x_max) keeps every spring on the grid in contact instead of needing
        a wider grid.

    Returns
    -------
    History
    """
    E_star = float(positive("E_star", E_star))
    G_star = float(positive("G_star", G_star))
    mu = float(nonnegative("mu", mu))
    x_max = float(positive("x_max", x_max))
    if isinstance(n_grid, bool) or not isinstance(n_grid, (int, np.integer)) or (
            n_grid < 8 or n_grid % 2):
        raise ValueError(f"n_grid = {n_grid!r} is out of range; valid: an even integer >= 8")
    if (depth is None) == (normal_force is None):
        raise ValueError("give exactly one of depth= and normal_force=")
    if (u_x is None) == (F_x is None):
        raise ValueError("give exactly one of u_x= and F_x=")
    dep = None if depth is None else _series("depth", depth)
    frc = None if normal_force is None else _series("normal_force", normal_force)
    for name, arr in (("depth", dep), ("normal_force", frc)):
        if arr is not None and np.any(arr < 0):
            i = int(np.argmax(arr < 0))
            raise ValueError(f"{name}[{i}] = {float(arr[i])!r} is out of range; valid: >= 0")
    steps = (dep if dep is not None else frc).size
    uc = None if u_x is None else _series("u_x", u_x, steps)
    Fc = None if F_x is None else _series("F_x", F_x, steps)
    gfun = _g_callable(g)
    wall = bool(wall)
    fine, sliding, x, qz, qx, stuck = _run(gfun, x_max, int(n_grid), E_star, G_star, mu, dep,
                                           frc, uc, Fc, wall)
    res = History(fine["depth"], fine["normal_force"], fine["contact_radius"], fine["u_x"],
                  fine["F_x"], fine["stick_radius"], sliding, fine["dissipated"], x, qz, qx,
                  stuck)
    if estimate_error:
        coarse, _, xc, _, qxc, _ = _run(gfun, x_max, int(n_grid) // 2, E_star, G_star, mu,
                                        dep, frc, uc, Fc, wall)
        (res.u_x_error, res.F_x_error, res.stick_radius_error, res.dissipated_error,
         res.normal_force_error, res.contact_radius_error) = (
            float(np.max(np.abs(fine[k] - coarse[k])))
            for k in ("u_x", "F_x", "stick_radius", "dissipated", "normal_force",
                      "contact_radius"))
        q_c = _traction(xc, qxc, float(coarse["contact_radius"][-1]))
        res.traction_error = float(np.max(np.abs(res.traction()[::2] - q_c))) / (np.sqrt(2) - 1)
    return res
