"""Axisymmetric profiles on a flat: the MDR of section 5.6 and Problems 7-8.

Closed forms where they exist (cone (5.38)-(5.40), flat punch (5.9)-(5.12), power law
Problem 7(d), worn parabola Problem 8) and the numerical MDR of numeric/mdr.py for sampled
profiles. The shared effects (stiffness 2 a E*, mean pressure, fields) live in the base class.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric.scene.kinds import CLOSED_FORM_RTOL, Contact, State, Value
from hertzmdr.numeric.scene.kinds.stresses import StressEffects, SuperposedStresses

FIELD_POINTS = 201


class Axisymmetric(StressEffects, Contact):
    """Base: subclasses define a(d), F(d), d(F), p(r, d), u(r, d), g(x) and their methods."""

    instead = {"half_width": "contact_radius", "semi_axes": "contact_radius"}
    method = "closed form"
    rel = CLOSED_FORM_RTOL

    # -- what each profile defines ---------------------------------------------------------
    def radius(self, d): ...
    def force_of(self, d): ...
    def depth_of(self, F): ...
    def p(self, r, d): ...
    def u(self, r, d): ...
    def g(self, x): ...

    def state(self, load) -> State:
        v = np.asarray(load.values, dtype=float)
        if load.kind == "depth":
            return State(v, np.asarray(self.force_of(v), float), self.rel, self.method, {})
        return State(np.asarray(self.depth_of(v), float), v, self.rel,
                     self.method + ", inverted", {})

    def effect_contact_radius(self, st):
        return Value(np.asarray(self.radius(st.depth), float), "(5.55) d = g(a)", self.rel)

    def stress_solver(self, st):
        d = self.last(st)
        a = float(np.atleast_1d(self.radius(d))[0])
        return SuperposedStresses(lambda r, d=d: np.asarray(self.p(r, d), float), a,
                                  self.nu_body[1])

    def effect_mean_pressure(self, st):
        a = np.asarray(self.radius(st.depth), float)
        return Value(st.force / (np.pi * a**2), "F/(pi a^2)", self.rel)

    def effect_stiffness(self, st):
        a = np.asarray(self.radius(st.depth), float)
        return Value(2 * a * self.E_star, "2 a E* (Problem 5, (5.12))", self.rel)

    def effect_pressure_profile(self, st):
        d = self.last(st)
        a = float(self.radius(d))
        r = np.linspace(0.0, 1.5 * a, FIELD_POINTS)
        r[0] = a * 1e-3  # the first point off the axis, where the cone's p is singular
        return Value({"r": r, "p": np.asarray(self.p(r, d), float)}, "(5.59)", self.rel)

    def effect_surface_displacement(self, st):
        d = self.last(st)
        a = float(self.radius(d))
        r = np.linspace(0.0, 4.0 * a, FIELD_POINTS)
        return Value({"r": r, "u": np.asarray(self.u(r, d), float)},
                     "d - f(r) inside, (5.60) outside", self.rel)

    def effect_force_depth_curve(self, st):
        d = np.linspace(0.0, self.last(st), FIELD_POINTS)[1:]
        return Value({"depth": d, "force": np.asarray(self.force_of(d), float)},
                     self.method, self.rel)

    def effect_mdr_profile(self, st):
        a = float(self.radius(self.last(st)))
        x = np.linspace(0.0, 1.2 * a, FIELD_POINTS)
        return Value({"x": x, "g": np.asarray(self.g(x), float)}, "(5.52)", self.rel)


class PowerLaw(Axisymmetric):
    kind = "power_law"
    why_not = {"max_pressure": "the pressure of f = c r^n with n <= 1 is singular at the centre"}

    def __init__(self, E_star, rtol, c, n):
        super().__init__(E_star, rtol)
        from hertzmdr.numeric import powerlaw

        self.pl, self.c, self.n = powerlaw, c, n
        self.label = f"power-law profile f = c r^{n:g} (Problem 7 d)"
        self.method = "Problem 7(d)"

    def info(self):
        return {**super().info(), "coefficient": self.c, "exponent": self.n,
                "kappa_n": float(self.pl.kappa(self.n))}

    def radius(self, d):
        return self.pl.contact_radius(d, self.c, self.n)

    def force_of(self, d):
        return self.pl.force(d, self.c, self.n, self.E_star)

    def depth_of(self, F):
        return self.pl.depth_from_force(F, self.c, self.n, self.E_star)

    def p(self, r, d):
        return self.pl.pressure(r, d, self.c, self.n, self.E_star)

    def u(self, r, d):
        return self.pl.surface_displacement(r, d, self.c, self.n)

    def g(self, x):
        return self.pl.g_profile(x, self.c, self.n)

    def has(self, effect):
        if effect == "max_pressure" and self.n <= 1:
            return False
        return super().has(effect)

    def effect_max_pressure(self, st):
        """The largest pressure: at the centre for n <= 2, towards the edge for n > 2 (Fig.
        5.17); located on a grid of 2001 points and refined by a bounded scalar search."""
        from scipy.optimize import minimize_scalar

        out = []
        for d in np.atleast_1d(st.depth):
            a = float(self.radius(d))
            r = np.linspace(0, a, 2001)[:-1]
            p = np.asarray(self.p(r, d), float)
            k = int(np.argmax(p))
            lo, hi = r[max(k - 1, 0)], r[min(k + 1, len(r) - 1)]
            best = p[k]
            if hi > lo:
                res = minimize_scalar(lambda x, d=d: -float(self.p(x, d)), bounds=(lo, hi),
                                      method="bounded", options={"xatol": 1e-12 * a})
                best = max(best, -res.fun)
            out.append(best)
        return Value(np.array(out), "max of (5.59) over r (grid + bounded search)", 1e-12)


class Cone(PowerLaw):
    """A cone is the power law n = 1 with c = tan(theta); its own relations (5.38)-(5.40)."""

    kind = "cone"
    why_not = {"max_pressure": "the cone's pressure is log-singular at the tip (5.39)"}

    def __init__(self, E_star, rtol, theta):
        super().__init__(E_star, rtol, float(np.tan(theta)), 1.0)
        from hertzmdr.numeric import cone

        self.cone, self.theta = cone, theta
        self.label = "rigid cone (5.38)-(5.40)"
        self.method = "(5.38)-(5.40)"

    def info(self):
        return {**Contact.info(self), "angle": self.theta}

    def radius(self, d):
        return self.cone.contact_radius(d, self.theta)

    def force_of(self, d):
        return self.cone.force(d, self.theta, self.E_star)

    def depth_of(self, F):
        return self.cone.depth_from_force(F, self.theta, self.E_star)

    def p(self, r, d):
        return self.cone.pressure(r, d, self.theta, self.E_star)


class FlatPunch(Axisymmetric):
    kind = "flat_punch"
    why_not = {"max_pressure": "the punch pressure (5.9) is singular at the edge"}

    def __init__(self, E_star, rtol, a):
        super().__init__(E_star, rtol)
        self.a = a
        self.label = "flat cylindrical punch (5.9)-(5.12), Problem 7(a)"
        self.method = "(5.11), (5.12)"

    def info(self):
        return {**super().info(), "radius": self.a}

    def radius(self, d):
        return np.full(np.shape(d), self.a)

    def force_of(self, d):
        return gen.powerlaw_punch_force(self.E_star, self.a, np.asarray(d, float))

    def depth_of(self, F):
        return np.asarray(F, float) / gen.punch_stiffness(self.E_star, self.a)  # (5.12)

    def p(self, r, d):
        r = np.asarray(r, float)
        out = np.zeros(r.shape)
        ins = r < self.a
        out[ins] = gen.powerlaw_punch_pressure(self.E_star, self.a, d, r[ins])
        return out

    def u(self, r, d):
        r = np.asarray(r, float)
        out = np.full(r.shape, float(d))
        out[r > self.a] = gen.powerlaw_punch_displacement_outside(self.a, d, r[r > self.a])
        return out

    def g(self, x):
        x = np.abs(np.asarray(x, float))
        return np.where(x < self.a, 0.0, np.inf)

    def effect_mdr_profile(self, st):
        x = np.linspace(0.0, self.a * (1 - 1e-9), FIELD_POINTS)
        return Value({"x": x, "g": np.zeros_like(x)}, "Problem 7(a): g = 0 for |x| < a, "
                     "infinite outside", self.rel)


class NumericalMDR(Axisymmetric):
    """Any axisymmetric gap by the numerical MDR (numeric/mdr.py), with its error estimate."""

    kind = "profile"

    def __init__(self, E_star, rtol, profile, label, breakpoints=()):
        super().__init__(E_star, rtol)
        self.profile = profile
        self.label = label
        self.tol = rtol or 1e-8
        self.method = f"numerical MDR (rtol {self.tol:g})"
        self._cache = {}

    def _solve(self, **kw):
        key = tuple(sorted(kw.items()))
        if key not in self._cache:
            self._cache[key] = self.profile.solve(E_star=self.E_star, rtol=self.tol, **kw)
        return self._cache[key]

    def state(self, load) -> State:
        sols = [self._solve(**{load.kind: float(v)}) for v in load.values]
        err = max(s.rel_error for s in sols)
        return State(np.array([s.depth for s in sols]), np.array([s.force for s in sols]),
                     err, self.method, {"sols": sols})

    def radius(self, d):
        d = np.atleast_1d(np.asarray(d, float))
        return np.array([self._solve(depth=float(v)).contact_radius for v in d])

    def force_of(self, d):
        d = np.atleast_1d(np.asarray(d, float))
        return np.array([self._solve(depth=float(v)).force for v in d])

    def depth_of(self, F):
        F = np.atleast_1d(np.asarray(F, float))
        return np.array([self._solve(force=float(v)).depth for v in F])

    def p(self, r, d):
        return self._solve(depth=float(d)).pressure(r)

    def u(self, r, d):
        return self._solve(depth=float(d)).displacement(r)

    def g(self, x):
        return self.profile.g(x)

    def effect_contact_radius(self, st):
        return Value(np.array([s.contact_radius for s in st.extra["sols"]]), self.method,
                     st.rel_error)

    def effect_max_pressure(self, st):
        vals, errs = [], []
        for s in st.extra["sols"]:
            r = np.linspace(0, s.contact_radius, 1001)[:-1]
            p, e = s.pressure(r, return_error=True)
            k = int(np.argmax(p))
            vals.append(p[k])  # +inf under a conical tip (p is log-infinite at r = 0)
            errs.append(e[k] / p[k] if 0 < p[k] < np.inf else 0.0)
        return Value(np.array(vals), self.method + ", max over 1000 radii", max(errs))

    def effect_pressure_profile(self, st):
        s = self._solve(depth=self.last(st))
        r = np.linspace(0.0, 1.5 * s.contact_radius, FIELD_POINTS)
        p, e = s.pressure(r, return_error=True)
        fin = np.isfinite(p)  # p(0) = +inf under a conical tip
        scale = float(np.max(p[fin])) if np.max(p[fin]) > 0 else 1.0
        return Value({"r": r, "p": p}, self.method, float(np.max(e[fin])) / scale)


class Worn(Axisymmetric):
    """Problem 8's flattened (worn) parabola: a(d), F(d), g(x), the pressure (incomplete elliptic
    integrals) and the outside displacement in closed form (derive/worn.py, F(d) in its stable
    form). The pressure is log-infinite at the edge of the flat r = b, where f' jumps: it has
    no maximum, and the stresses come from superposing it (tanh-sinh with an error estimate)."""

    kind = "flattened_parabola"
    why_not = {"max_pressure": "the worn parabola's pressure is log-infinite at the edge of "
               "the flat r = b (where the slope of the profile jumps): it has no finite maximum; "
               "ask for 'pressure_profile' or the stresses"}

    def has(self, effect):
        return effect != "max_pressure" and super().has(effect)

    def __init__(self, E_star, rtol, R, b):
        super().__init__(E_star, rtol)
        self.R, self.b = R, b
        self.label = "flattened (worn) parabola, Problem 8"
        self.method = "Problem 8"

    def info(self):
        return {**super().info(), "radius": self.R, "flat_radius": self.b}

    def radius(self, d):
        return gen.worn_contact_radius(self.R, self.b, np.asarray(d, float))

    def force_of(self, d):
        return gen.worn_force(self.E_star, self.R, self.b, np.asarray(d, float))

    def depth_of(self, F):
        """d(F): F(a) is increasing from 0 at a = b; solve it for a (brentq), then d = g(a)."""
        from scipy.optimize import brentq

        out = []
        for Fi in np.atleast_1d(np.asarray(F, float)):
            f = lambda a, Fi=Fi: float(gen.worn_force_from_radius(self.E_star, self.R, a,  # noqa
                                                                  self.b)) - Fi
            hi = 2 * max(self.b, 1e-300)
            while f(hi) < 0:
                hi *= 2
            a = brentq(f, self.b, hi, xtol=1e-15 * hi, rtol=4e-16)
            out.append(float(gen.worn_depth(self.R, a, self.b)))
        return np.array(out)

    def g(self, x):
        x = np.abs(np.asarray(x, float))
        out = np.zeros(x.shape)
        out[x > self.b] = gen.worn_g(self.R, self.b, x[x > self.b])
        return out

    def u(self, r, d):
        r = np.asarray(r, float)
        a = float(self.radius(d))
        out = np.empty(r.shape)
        ins = r <= a
        out[ins] = d - np.where(r[ins] < self.b, 0.0, (r[ins] ** 2 - self.b**2) / (2 * self.R))
        out[~ins] = gen.worn_displacement_outside(self.R, a, self.b, r[~ins])
        return out

    def p(self, r, d):
        a = float(self.radius(d))
        return gen.worn_pressure(self.E_star, self.R, a, self.b, np.asarray(r, float))  # (5.59)

    def effect_pressure_profile(self, st):
        d = self.last(st)
        a = float(self.radius(d))
        r = np.linspace(0.0, 1.5 * a, FIELD_POINTS)
        # p is log-infinite at r = b: a grid point that falls on it moves by 1e-3 of a step
        r[np.abs(r - self.b) <= 1e-12 * a] += 1e-3 * (r[1] - r[0])
        return Value({"r": r, "p": np.asarray(self.p(r, d), float)},
                     "(5.59) in incomplete elliptic integrals (Problem 8)", self.rel)
