"""Axisymmetric contacts: the MDR of section 5.6 and Problems 7-8.

:class:`Axisymmetric` writes every effect of an axisymmetric contact once, from six primitives
a subclass provides: the contact radius a(d), the force F(d), the depth d(F), the pressure
p(r, d), the surface displacement u(r, d) and the MDR profile g(x). The Hertz contact
(kinds/hertz.py) is one; :class:`ClosedFormContact` takes them from a shape's
:class:`ClosedForm` (cone (5.38)-(5.40), flat punch (5.9)-(5.12), power law Problem 7(d), worn
parabola Problem 8, ...), and :class:`NumericalMDR` from the numerical MDR of numeric/mdr.py.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Contact, Setup, State, Value
from hertzmdr.numeric.scene.kinds.friction import TangentialEffects
from hertzmdr.numeric.scene.kinds.stresses import StressEffects

#: the relative accuracy of numeric/pressures.py's max_pressure_of (located to 1e-12 a;
#: verified by tests/test_pressures.py)
MAX_SEARCH_RTOL = 1e-12


class Axisymmetric(TangentialEffects, StressEffects, Contact):
    """Base: the effects of an axisymmetric contact, from the primitives ``radius(d)``,
    ``force_of(d)``, ``depth_of(F)``, ``p(r, d)``, ``u(r, d)`` and ``g(x)`` of a subclass
    (a subclass that writes an effect itself leaves out the primitives only that effect would
    call: the numerical MDR writes its surface displacement from its solution, without u)."""

    instead = {"half_width": "contact_radius", "semi_axes": "contact_radius"}
    #: the method of the contact state (and of the force-depth curve)
    method = "closed form"
    #: effect -> the method text of its value
    methods = {"contact_radius": "(5.55) d = g(a)", "mean_pressure": "F/(pi a^2)",
               "stiffness": "2 a E* (Problem 5, (5.12))", "pressure_profile": "(5.59)",
               "surface_displacement": "d - f(r) inside, (5.60) outside",
               "mdr_profile": "(5.52)"}
    #: the first point of a pressure profile sits at 1e-3 a, off the axis (a cone's p is
    #: singular there)
    off_axis = True
    #: a radius where p is log-infinite (a kink of the profile), kept off the profile's grid
    kink: float | None = None
    curve_from_zero = False

    @property
    def curve_method(self):
        return self.methods.get("force_depth_curve", self.method)

    @property
    def pressure_method(self):
        return self.methods["pressure_profile"]

    def extent(self, d):
        return self.a_at(d)

    def ratios(self, nodes):
        """d/a at the largest load (a profile with no one radius or angle); none where no load
        makes a contact (a sweep from 0 to 0 cannot be given)."""
        st = nodes.get("state")
        if st is None:
            return {}
        d = self.last(st)
        a = self.a_at(d)
        return {"d/a": d / a} if a > 0 else {}

    def state(self, load) -> State:
        v = np.asarray(load.values, dtype=float)
        if load.kind == "depth":
            return State(v, np.asarray(self.force_of(v), float), self.rel, self.method)
        return State(np.asarray(self.depth_of(v), float), v, self.rel, self.method + ", inverted")

    def rtol_ranges(self, effects):
        return super().rtol_ranges(effects) + self.stress_ranges(effects, closed=False)

    def stress_solver(self, st):
        from hertzmdr.numeric.scene.kinds.stresses import SuperposedStresses

        d = self.last(st)
        a = self.a_at(d)
        return SuperposedStresses(lambda r, d=d: np.asarray(self.p(r, d), float), a,
                                  self.materials.stressed.nu)

    def a_at(self, d: float) -> float:
        """The contact radius [m] at one depth d [m], as a float (``radius`` may return an
        array of one)."""
        return float(np.atleast_1d(self.radius(d))[0])

    def _radius_at(self, st) -> np.ndarray:
        return np.asarray(self.radius(st.depth), float)

    def effect_contact_radius(self, st):
        return Value(self._radius_at(st), self.methods["contact_radius"], st.rel_error)

    def effect_mean_pressure(self, st):
        from hertzmdr.numeric import contact

        return Value(contact.mean_pressure_disc(st.force, self._radius_at(st)),
                     self.methods["mean_pressure"], st.rel_error)

    def effect_stiffness(self, st):
        from hertzmdr.numeric import contact

        return Value(contact.stiffness(self._radius_at(st), self.E_star),
                     self.methods["stiffness"], st.rel_error)

    def pressure_radii(self, a: float) -> np.ndarray:
        """The radii of a pressure profile: 0 to 1.5 a, kept off the axis and off a kink."""
        r = super().pressure_radii(a)
        if self.off_axis:
            r[0] = a * 1e-3
        if self.kink is not None:  # p is log-infinite there: such a point moves by 1e-3 step
            r[np.abs(r - self.kink) <= 1e-12 * a] += 1e-3 * (r[1] - r[0])
        return r

    def effect_surface_displacement(self, st):
        d = self.last(st)
        r = np.linspace(0.0, 4.0 * self.a_at(d), FIELD_POINTS)
        return Value({"r": r, "u": np.asarray(self.u(r, d), float)},
                     self.methods["surface_displacement"], st.rel_error)

    def effect_mdr_profile(self, st):
        a = self.a_at(self.last(st))
        x = np.linspace(0.0, 1.2 * a, FIELD_POINTS)
        return Value({"x": x, "g": np.asarray(self.g(x), float)}, self.methods["mdr_profile"],
                     st.rel_error)


@dataclass(frozen=True)
class ClosedForm:
    """The MDR closed form of one axisymmetric profile, as a shape provides it: validated
    functions of numeric/ with the profile's parameters bound (lengths in m, forces in N,
    pressures and E* in Pa).

    Attributes
    ----------
    kind, label, method : str
        The model's kind and description, and the equations of its state.
    params : dict
        The profile's parameters, reported in the JSON's ``model``.
    contact_radius, force, depth_from_force, pressure, surface_displacement, g_profile
        a(d), F(d, E*), d(F, E*), p(r, d, E*), u_z(r, d), g(x).
    no_max_pressure : str or None
        Why the pressure has no finite maximum, or None when it has one.
    singular_at : callable or None
        With ``no_max_pressure``: the radius r_s(a) [m] where the pressure is unbounded (0 at a
        tip, a at a punch's edge, b at a worn tip's kink), where the stresses are too.
    kink : float or None
        A radius where the pressure is log-infinite (kept off the profile's grid).
    radius, slope : float or None
        The profile's radius of curvature R [m] at its tip, or its one surface gradient (a
        cone's tan(theta)): the contact then reports a/R and d/R, or tan(theta), instead of d/a
        (:mod:`..assumptions`).
    off_axis : bool
        Whether a pressure profile starts at 1e-3 a (a pressure singular at the axis).
    methods : dict
        Method texts that differ from :attr:`Axisymmetric.methods`.
    contact : type
        The kind class (:class:`ClosedFormContact` or a subclass).
    force_law : callable or None
        E* -> :class:`hertzmdr.numeric.force_law.Law` where F(d) is a power law F = K d^n
        (numeric/force_law.py), with ``force_law_method`` its equation; None where it is
        not, and ``not_power_law`` says why (the ``force_law`` effect's error).
    """

    kind: str
    label: str
    method: str
    params: dict[str, float]
    contact_radius: Callable
    force: Callable
    depth_from_force: Callable
    pressure: Callable
    surface_displacement: Callable
    g_profile: Callable
    no_max_pressure: str | None = None
    singular_at: Callable | None = None
    kink: float | None = None
    radius: float | None = None
    slope: float | None = None
    off_axis: bool = True
    methods: dict[str, str] = field(default_factory=dict)
    contact: type | None = None
    force_law: Callable | None = None
    force_law_method: str = ""
    not_power_law: str = ""


class ClosedFormContact(Axisymmetric):
    """An axisymmetric profile on a flat, in the closed form of its shape's :class:`ClosedForm`."""

    def __init__(self, materials, interface, rtol, form: ClosedForm):
        super().__init__(materials, interface, rtol)
        self.form = form
        self.kind, self.label, self.method = form.kind, form.label, form.method
        self.methods = {**Axisymmetric.methods, **form.methods}
        self.kink, self.off_axis = form.kink, form.off_axis
        if form.no_max_pressure:
            self.why_not = {"max_pressure": form.no_max_pressure}

    def info(self):
        return {**super().info(), **self.form.params}

    def ratios(self, nodes):
        if self.form.slope is not None:
            return {"tan(theta)": self.form.slope}
        if self.form.radius is None:
            return super().ratios(nodes)
        st = nodes.get("state")
        if st is None:
            return {}
        d = self.last(st)
        return {"a/R": self.a_at(d) / self.form.radius, "d/R": d / self.form.radius}

    def has(self, effect):
        if effect == "force_law" and self.form.force_law is None:
            self.not_power_law = self.form.not_power_law or self.not_power_law
            return self.refuse_force_law()
        if effect == "max_pressure" and self.form.no_max_pressure:
            return False
        if effect in ("max_shear", "max_von_mises") and self._unbounded_at_half():
            return False
        if effect == "max_orthogonal_shear" and self._singular():
            self.why_not = {**self.why_not, "max_orthogonal_shear": (
                f"{self.form.no_max_pressure}; the largest |tau_rz| is at that point or "
                "unbounded toward it, which the stress grid cannot resolve (ask for "
                "'von_mises_field')")}
            return False
        return super().has(effect)

    def _singular(self) -> bool:
        """Whether the pressure is unbounded somewhere (cone, flat punch, worn parabola, power
        law n <= 1)."""
        return bool(self.form.no_max_pressure) and self.form.singular_at is not None

    def _unbounded_at_half(self) -> bool:
        """A singular pressure in an incompressible body (nu = 0.5): the surface stress is
        hydrostatic to leading order, so the maxima may be finite, and the grid cannot bound
        them: refused (:meth:`stress_solver` says +inf for nu < 0.5)."""
        if self._singular() and self.materials.stressed.nu >= 0.5:
            self.why_not = {**self.why_not, **dict.fromkeys(
                ("max_shear", "max_von_mises"),
                f"{self.form.no_max_pressure}; with nu = 0.5 the stress there is hydrostatic to "
                "leading order and the maximum is not computed (ask for 'axis_stresses' or "
                "'von_mises_field')")}
            return True
        return False

    def stress_solver(self, st):
        """Superposition over the closed-form pressure; where that pressure is unbounded (and
        nu < 0.5) the largest stresses are too: the surface stress there grows like
        (1 - 2 nu) p."""
        solver = super().stress_solver(st)
        if self.form.no_max_pressure and self.form.singular_at is not None:
            r_s = float(self.form.singular_at(self.a_at(self.last(st))))
            solver.unbounded = (self.form.no_max_pressure, r_s)
        return solver

    def tangential_profile(self, d):
        from hertzmdr.numeric import tangential as tg

        p = self.form.params
        if self.form.kind == "cone":
            return tg.Cone(p["angle"])
        if self.form.kind == "power_law":
            return tg.PowerLaw(p["coefficient"], p["exponent"])
        if self.form.kind == "flat_punch":
            return tg.FlatPunch(d)
        return None

    def radius(self, d):
        return self.form.contact_radius(d)

    def force_of(self, d):
        return self.form.force(d, self.E_star)

    def depth_of(self, F):
        return self.form.depth_from_force(F, self.E_star)

    def p(self, r, d):
        return self.form.pressure(r, d, self.E_star)

    def u(self, r, d):
        return self.form.surface_displacement(r, d)

    def g(self, x):
        return self.form.g_profile(x)

    def effect_force_law(self):
        """F = K d^n of the profile (numeric/force_law.py)."""
        return self.law_value(self.form.force_law(self.E_star), self.form.force_law_method,
                              self.rel)

    def effect_max_pressure(self, st):
        """The largest pressure over the contact, wherever it lies
        (numeric/pressures.py's ``max_pressure_of``: a grid, then a bounded search)."""
        from hertzmdr.numeric import pressures

        out = [pressures.max_pressure_of(lambda r, d=d: self.p(r, d), self.a_at(d))[0]
               for d in np.atleast_1d(st.depth)]
        return Value(np.array(out), "max of (5.59) over r (grid + bounded search)",
                     MAX_SEARCH_RTOL)

    def rtol_ranges(self, effects):
        out = super().rtol_ranges(effects)
        if "max_pressure" in effects:
            out.append(("the search for the largest pressure", (MAX_SEARCH_RTOL, 1.0)))
        return out


class PunchContact(ClosedFormContact):
    """The flat punch: its g is 0 inside the contact and infinite outside (Problem 7(a))."""

    def spring_profile(self):
        """The tangential springs of a history: g = 0 on a grid that ends at the radius."""
        return (lambda x: np.zeros_like(np.asarray(x, float)),
                float(self.form.params["radius"]))

    def effect_mdr_profile(self, st):
        a = float(self.form.params["radius"])
        x = np.linspace(0.0, a * (1 - 1e-9), FIELD_POINTS)
        return Value({"x": x, "g": np.zeros_like(x)}, "Problem 7(a): g = 0 for |x| < a, "
                     "infinite outside", st.rel_error)


def build_closed_form(setup: Setup) -> ClosedFormContact:
    """An axisymmetric profile with an MDR closed form (its shape's ``mdr``) on a flat."""
    from hertzmdr.numeric.scene.shapes import SHAPES

    body = _profiled(setup)
    form = SHAPES[body.shape].mdr(body.params)
    return (form.contact or ClosedFormContact)(setup.materials, setup.interface, setup.rtol,
                                               form)


def _profiled(setup: Setup):
    shaped = setup.shaped()
    if len(shaped) != 1:
        names = " and ".join(b.shape for b in shaped)
        setup.fail("body", f"two profiled bodies ({names}) are not supported: give one of them "
                   "shape = \"flat\" (the MDR sums the two profiles; sample their sum as a "
                   "profile)")
    return shaped[0]


@dataclass
class MDRState(State):
    """The contact state of the numerical MDR: one solution per load point."""

    solutions: list = field(default_factory=list)


class NumericalMDR(Axisymmetric):
    """Any axisymmetric gap by the numerical MDR (numeric/mdr.py), with its error estimate."""

    kind = "profile"
    off_axis = False
    not_power_law = ("a sampled profile's force-depth relation is computed point by point, "
                     "not a power law F = K d^n")
    state_method = "the numerical MDR"

    def __init__(self, materials, interface, rtol, profile, label):
        super().__init__(materials, interface, rtol)
        from hertzmdr.numeric import mdr

        self.state_range = mdr.RTOL_RANGE  # the rtol the numerical MDR can refine towards
        self.profile = profile
        self.label = label
        self.method = "numerical MDR"
        self._cache = {}

    def _solve(self, **kw):
        key = tuple(sorted(kw.items()))
        if key not in self._cache:
            self._cache[key] = self.profile.solve(E_star=self.E_star, rtol=self.rtol, **kw)
        return self._cache[key]

    def state(self, load) -> MDRState:
        sols = [self._solve(**{load.kind: float(v)}) for v in load.values]
        err = max(s.rel_error for s in sols)
        return MDRState(np.array([s.depth for s in sols]), np.array([s.force for s in sols]),
                        err, self._label(sols), sols)

    def ratios(self, nodes):
        """d/a of the solution at the largest load (no new solve)."""
        st = nodes.get("state")
        if st is None:
            return {}
        s = max(st.solutions, key=lambda sol: sol.depth)
        return {"d/a": s.depth / s.contact_radius} if s.contact_radius > 0 else {}

    def _label(self, sols) -> str:
        """The state's method: the numerical MDR's reason when a solve did not meet rtol (a
        sampled profile cannot be refined past its samples). It names no tolerance: the
        effect's ``met_rtol`` says whether its own error met it."""
        missed = [s.why_not_met for s in sols if not s.met]
        return "numerical MDR" + (f" (rtol not met: {missed[0]})" if missed else "")

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

    def g(self, x):
        return self.profile.g(x)  # the tangential springs' profile (kinds/friction.py)

    # -- every effect with the solver's own bound (numeric/mdr.py) ----------------------------
    # Field effects report max |error| / max |value| over their points; the pressure's bound is
    # that of p at the solution's own contact radius (the error of a is contact_radius's).
    @staticmethod
    def _field_error(value, err) -> float:
        fin = np.isfinite(value)  # p(0) = +inf under a conical tip
        scale = float(np.max(np.abs(value[fin]))) if fin.any() else 0.0
        return float(np.max(err[fin])) / scale if scale > 0 else 0.0

    def effect_contact_radius(self, st):
        return Value(np.array([s.contact_radius for s in st.solutions]), st.method,
                     st.rel_error)

    def effect_mean_pressure(self, st):
        """F/(pi a^2): the bounds of F and of a^2 add up, 3 rel_error."""
        v = super().effect_mean_pressure(st)
        return Value(v.value, v.method, 3.0 * st.rel_error)

    def effect_max_pressure(self, st):
        """mdr.Solution.max_pressure with its bound, plus the state's rel_error (p scales with
        the contact radius, whose error the pressure's bound leaves out)."""
        vals, errs = [], []
        for s in st.solutions:
            v, e = s.max_pressure(return_error=True)
            vals.append(v)  # +inf under a conical tip (p is log-infinite at r = 0)
            errs.append(e / v + s.rel_error if 0 < v < np.inf else s.rel_error)
        return Value(np.array(vals), st.method + ", the largest of (5.59) over r (grid + "
                     "bounded search)", max(errs))

    def effect_force_depth_curve(self, st):
        d = np.linspace(0.0, self.last(st), FIELD_POINTS)[1:]
        curve = self.profile.force_depth_curve(d, E_star=self.E_star, rtol=self.rtol)
        return Value({"depth": curve.depth, "force": curve.force}, st.method,
                     float(np.max(curve.rel_error)))

    def effect_pressure_profile(self, st):
        s = self._solve(depth=self.last(st))
        r = np.linspace(0.0, 1.5 * s.contact_radius, FIELD_POINTS)
        p, e = s.pressure(r, return_error=True)
        return Value({"r": r, "p": p}, st.method, self._field_error(p, e))

    def effect_surface_displacement(self, st):
        s = self._solve(depth=self.last(st))
        r = np.linspace(0.0, 4.0 * s.contact_radius, FIELD_POINTS)
        u, e = s.displacement(r, return_error=True)
        return Value({"r": r, "u": u}, st.method + ", (5.60)", self._field_error(u, e))

    def effect_mdr_profile(self, st):
        s = self._solve(depth=self.last(st))
        x = np.linspace(0.0, 1.2 * s.contact_radius, FIELD_POINTS)
        g, e = self.profile.g(x, return_error=True)
        return Value({"x": x, "g": g}, "numerical MDR, (5.52)", self._field_error(g, e))

    def stress_solver(self, st):
        """Superposition over the solution's pressure; its error adds the pressure's bound
        relative to its largest value (the stresses are linear in p) and 3 times the contact
        radius's (the pressure's bound is at the solution's own radius: an error delta in a
        scales p like F/a^2 and stretches the field by delta, as for the mean pressure)."""
        from hertzmdr.numeric.scene.kinds.stresses import SuperposedStresses

        s = self._solve(depth=self.last(st))
        r = np.linspace(0.0, s.contact_radius, FIELD_POINTS)[:-1]
        p, e = s.pressure(r, return_error=True)
        return SuperposedStresses(lambda rr: np.asarray(s.pressure(rr), float),
                                  s.contact_radius, self.materials.stressed.nu,
                                  pressure_error=self._field_error(p, e)
                                  + 3 * float(s.rel_error))


def build_numerical(setup: Setup) -> NumericalMDR:
    """A sampled profile (its shape's ``samples``) on a flat, by the numerical MDR."""
    from hertzmdr.numeric import mdr
    from hertzmdr.numeric.scene.shapes import SHAPES

    body = _profiled(setup)
    r, f, k = SHAPES[body.shape].samples(body.params)
    try:
        prof = mdr.Profile.from_samples(r, f, k=k,
                                        breakpoints=SHAPES[body.shape].breakpoints(body.params))
    except ValueError as exc:
        setup.fail(f"body ({body.name})", f"profile samples: {exc}")
    return NumericalMDR(setup.materials, setup.interface, setup.rtol, prof,
                        f"sampled profile ({len(r)} samples), numerical MDR")
