"""Adhesive contacts: an axisymmetric contact with ``[interface] work_of_adhesion`` (JKR-type
MDR, numeric/adhesion.py).

:func:`adhesive` turns the contact the registry built for the bodies into an
:class:`AdhesiveKind`: the Hertz contact becomes the JKR paraboloid, the closed-form MDR
profiles their adhesive counterparts (cone, power law n > 1/2, flat punch, exact sphere, worn
parabola), a sampled profile its numerical-MDR counterpart (every field with the coarse-vs-fine
error of its samples). Other contacts (elliptical, line, BEM, prescribed pressures, impacts)
are refused with the reason. Delta gamma = 0 is never made adhesive (the model keeps
the non-adhesive contact, exactly), unless the load is a ``cycle``, whose history it walks.

The state at a depth (force) is the stable equilibrium under depth (force) control: the
branch dd/da > 0 (dF/da > 0), beyond the pull-off. The adhesive effects report both controls.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import adhesion as ad
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Contact, Setup, State, Value
from hertzmdr.numeric.scene.kinds.stresses import StressEffects

#: the effects only an adhesive contact has
ADHESIVE_EFFECTS = ("pull_off_force", "pull_off_depth", "zero_load_contact_radius",
                    "adhesive_force_depth_curve")
#: effects of the non-adhesive kinds that an adhesive contact does not compute, and why
#: the adhesive pressure is unbounded at the edge (a tension like 1/sqrt(a - r), (5.59))
UNBOUNDED = "the adhesive pressure is unbounded (a tension) at the edge of the contact"
WHY_NOT = {
    "max_pressure": f"{UNBOUNDED}: its extreme is not computed; ask for 'pressure_profile'",
    "elastic_energy": "the elastic energy of an adhesive contact is not computed (the "
                      "'adhesive_force_depth_curve' reports the work lost per cycle)",
}


#: effects of a sampled profile's adhesive contact that are not computed, and why
SAMPLED_NOT = dict.fromkeys(
    ("axis_stresses", "max_shear", "von_mises_field", "max_von_mises", "max_orthogonal_shear"),
    "the stresses under a sampled profile's adhesive pressure are not computed: the "
    "superposition would evaluate the numerical MDR's Abel integral of the pressure at every "
    "ring of every stress point (minutes a field); its pressure_profile and "
    "surface_displacement are")


def _shape(contact) -> ad.Shape:
    """The adhesion.Shape of a non-adhesive contact, or ValueError saying why there is none."""
    from hertzmdr.numeric.scene.kinds.axisym import ClosedFormContact, NumericalMDR
    from hertzmdr.numeric.scene.kinds.hertz import HertzContact

    if isinstance(contact, HertzContact) and contact.striker_radius is None:
        return ad.Paraboloid(contact.R)
    if isinstance(contact, NumericalMDR):
        return ad.Sampled(contact.profile)
    if isinstance(contact, ClosedFormContact):
        p, kind = contact.form.params, contact.form.kind
        if kind == "cone":
            return ad.Cone(p["angle"])
        if kind == "power_law":
            if not p["exponent"] > 0.5:
                raise ValueError(f"a power law with exponent {p['exponent']:g} <= 1/2 has no "
                                 "pull-off: the adhesive force falls without bound as the "
                                 "contact grows")
            return ad.PowerLaw(p["coefficient"], p["exponent"])
        if kind == "flat_punch":
            return ad.FlatPunch(p["radius"])
        if kind == "exact_sphere":
            return ad.Sphere(p["radius"])
        if kind == "flattened_parabola":
            return ad.Worn(p["radius"], p["flat_radius"])
    raise ValueError(f"adhesion is derived for axisymmetric profiles on a flat (sphere, cone, "
                     f"power law, flat punch, exact sphere, flattened parabola, a sampled "
                     f"profile); this scene is a {contact.label}")


def adhesive(setup: Setup, contact: Contact) -> AdhesiveKind:
    """The adhesive form of ``contact`` (see the module docstring); SceneError if none."""
    try:
        shape = _shape(contact)
    except ValueError as exc:
        key = "interface.work_of_adhesion" if setup.interface.adhesive else "load.cycle"
        setup.fail(key, str(exc))
    return AdhesiveKind(setup.materials, setup.interface, setup.rtol, contact, shape)


class AdhesiveKind(StressEffects, Contact):
    """An axisymmetric contact with adhesion (numeric/adhesion.py's AdhesiveContact).

    Its stresses are the superposition of the point-force field under the adhesive pressure
    (kinds/stresses.py); the pressure is unbounded at the edge, so are the largest stresses
    (+inf for nu < 0.5; refused for nu = 0.5, where the surface stress there is hydrostatic to
    leading order, as for the flat punch)."""

    why_not = WHY_NOT
    instead = {"half_width": "contact_radius", "semi_axes": "contact_radius"}
    not_power_law = ("with adhesion the force-depth relation has a pull-off and is not a "
                     "power law F = K d^n")
    rel = CLOSED_FORM_RTOL
    curve_from_zero = True

    def __init__(self, materials, interface, rtol, inner: Contact, shape: ad.Shape):
        super().__init__(materials, interface, rtol)
        self.inner, self.shape = inner, shape
        self.model = ad.AdhesiveContact(shape, self.E_star, interface.work_of_adhesion)
        self.kind = f"adhesive {inner.kind}"
        dg = interface.work_of_adhesion
        self.label = f"{inner.label}, adhesive (JKR-type MDR, work of adhesion {dg:g} J/m^2)"
        closed = shape.closed_pull_off("force", self.E_star, max(dg, 1e-300)) is not None
        if isinstance(shape, ad.Sampled):
            from hertzmdr.numeric import mdr

            self.method = "adhesive numerical MDR (error: coarse vs fine samples)"
            self.state_method = "the numerical MDR"
            self.state_range = mdr.RTOL_RANGE
        else:
            self.method = ("adhesive MDR, closed form" if closed else
                           "adhesive MDR, closed form; pull-off by bracketed roots")
        self.curve_method = self.method

    # -- the JSON's model and the assumptions it stretches ----------------------------------
    def _tabor(self):
        """mu_T of the tip's radius of curvature, or None (no range, or no one radius)."""
        z0, R = self.interface.range, self.shape.radius_of_curvature
        if z0 is None or R is None:
            return None
        return float(ad.tabor_parameter(R, self.E_star, self.interface.work_of_adhesion, z0))

    def info(self):
        out = {**self.inner.info(), "kind": self.kind, "description": self.label,
               "work_of_adhesion": self.interface.work_of_adhesion}
        mu = self._tabor()
        if mu is not None:
            out["range"] = self.interface.range
            out["tabor_parameter"] = mu
        return {**out, "why": self.why} if self.why else out  # model.build's, with adhesion

    def ratios(self, nodes):
        """The inner kind's geometric ratios, measured on the adhesive state at the largest
        load (|d|: the depth of an adhesive contact can be negative), and the Tabor parameter
        mu_T when the interface gives a range (Delta gamma > 0 and a radius of curvature)."""
        from hertzmdr.numeric.scene.kinds.axisym import ClosedFormContact
        from hertzmdr.numeric.scene.kinds.hertz import HertzContact

        out = {}
        mu = self._tabor()
        if mu is not None and self.interface.work_of_adhesion > 0:
            out["mu_T"] = mu
        inner = self.inner
        slope = inner.form.slope if isinstance(inner, ClosedFormContact) else None
        if slope is not None:
            return {"tan(theta)": slope, **out}
        st = nodes.get("state")
        if st is None:
            return out
        d = self.last(st)
        a = float(self.model.contact_radius(depth=d))
        R = (inner.R if isinstance(inner, HertzContact) else
             inner.form.radius if isinstance(inner, ClosedFormContact) else None)
        if R is not None:
            return {"a/R": a / R, "d/R": abs(d) / R, **out}
        return ({"d/a": abs(d) / a} if a > 0 else {}) | out

    # -- the state ----------------------------------------------------------------------
    def _control(self, load) -> str:
        return load.control if load.kind == "cycle" else load.kind

    def state(self, load) -> State:
        v = np.asarray(load.values, dtype=float)
        control = self._control(load)
        a, d, F = self.model.equilibrium(**{control: v})
        return State(d, F, self._state_error(control, v, a, d, F), self.method)

    def _state_error(self, control, v, a, d, F) -> float:
        """Closed forms: CLOSED_FORM_RTOL. The numerical MDR: the largest relative difference
        of a, d, F from the same state on the coarse samples, plus the closed-form floor."""
        twin = self.shape.companion()
        if twin is None:
            return self.rel
        other = ad.AdhesiveContact(twin, self.E_star, self.interface.work_of_adhesion)
        a2 = np.atleast_1d(np.asarray(other.contact_radius(**{control: v}), float))
        d2, F2 = np.asarray(other.depth(a2), float), np.asarray(other.force(a2), float)
        diffs = [np.abs(a2 - a) / a, np.abs(d2 - d) / np.abs(d), np.abs(F2 - F) / np.abs(F)]
        return float(max(np.max(x) for x in diffs)) + self.rel

    def _a_last(self, st) -> float:
        return self.extent(self.last(st))

    # -- the effects ----------------------------------------------------------------------
    def effect_contact_radius(self, st):
        a = self.model.contact_radius(depth=st.depth)
        return Value(np.atleast_1d(np.asarray(a, float)), "d = g(a) - Delta l(a) (5.55), "
                     "adhesive, the stable branch", st.rel_error)

    def effect_mean_pressure(self, st):
        return Value(self.model.mean_pressure(depth=st.depth), "F/(pi a^2) (5.17)",
                     st.rel_error)

    def effect_stiffness(self, st):
        punch = isinstance(self.shape, ad.FlatPunch)
        return Value(self.model.stiffness(depth=st.depth),
                     "2 a E* (5.12)" if punch else "(dF/da)/(dd/da), adhesive", st.rel_error)

    def force_of(self, d):
        """F(d) on the stable branch under depth control [N]."""
        return self.model.force_at_depth(np.atleast_1d(np.asarray(d, float)))

    def p(self, r, d):
        return self.model.pressure_at_depth(r, d)

    def extent(self, d):
        return float(self.model.contact_radius(depth=float(d)))

    pressure_method = "(5.59): the non-adhesive pressure of radius a plus -E* Delta l/(pi " \
                      "sqrt(a^2 - r^2))"

    def pressure_radii(self, a):
        r = super().pressure_radii(a)
        if getattr(self.inner, "off_axis", False):  # a cone's p is log-infinite at r = 0
            r[0] = 1e-3 * a
        return r[np.abs(r - a) > 1e-12 * a]  # p is -inf at the edge itself

    def _twin_error(self, field: str, r, d, value) -> float:
        """A sampled profile's field error: the largest difference of the fine and the coarse
        representation's field at the same radii and depth (each at its own contact radius),
        over the field's largest |value|, plus twice the state's (a and d move the field);
        0 for the closed forms (their error is the state's)."""
        twin = self.shape.companion()
        if twin is None:
            return 0.0
        other = ad.AdhesiveContact(twin, self.E_star, self.interface.work_of_adhesion)
        with np.errstate(invalid="ignore"):  # -inf - -inf where both meet their edges
            v2 = np.asarray(getattr(other, field)(r, d), float)
            diff = np.abs(v2 - value)
        fin = np.isfinite(value) & np.isfinite(v2)
        scale = float(np.max(np.abs(value[fin]))) if fin.any() else 0.0
        return float(np.max(diff[fin])) / scale if scale > 0 else 0.0

    def effect_pressure_profile(self, st):
        v = super().effect_pressure_profile(st)
        if not isinstance(self.shape, ad.Sampled):
            return v
        d = self.last(st)
        r, p = v.value["r"], v.value["p"]
        a = self.extent(d)
        # the edge's -inf of one representation is finite in the other: the points next to
        # it are left out, as is the axis of a conical tip (+inf)
        keep = (np.abs(r - a) > 1e-3 * a) & np.isfinite(p)
        r, p = r[keep], p[keep]
        err = self._twin_error("pressure_at_depth", r, d, p) + 2 * st.rel_error
        return Value({"r": r, "p": p}, "numerical MDR: " + self.pressure_method
                     + " (error: coarse vs fine samples)", err)

    def effect_surface_displacement(self, st):
        d = self.last(st)
        r = np.linspace(0.0, 4.0 * self.extent(d), FIELD_POINTS)
        u = np.asarray(self.model.surface_displacement_at_depth(r, d), float)
        err = st.rel_error
        method = "d - f(r) inside, (5.60) outside with the edge term -(2/pi) Delta l asin(a/r)"
        if isinstance(self.shape, ad.Sampled):
            err = self._twin_error("surface_displacement_at_depth", r, d, u) + 2 * st.rel_error
            method = "numerical MDR: " + method + " (error: coarse vs fine samples)"
        return Value({"r": r, "u": u}, method, err)

    def effect_mdr_profile(self, st):
        if isinstance(self.shape, ad.FlatPunch):
            return self.inner.effect_mdr_profile(st)
        a = self._a_last(st)
        top = 1.2 * a if np.isinf(self.shape.a_limit) else min(  # the exact sphere: x < R
            1.2 * a, self.shape.a_limit * (1 - 1e-9))
        x = np.linspace(0.0, top, FIELD_POINTS)
        return Value({"x": x, "g": np.asarray(self.shape.g(x), float)}, "(5.52)", st.rel_error)

    def effect_effective_radius(self):
        R = self.shape.radius_of_curvature
        if R is None:
            raise ValueError(f"{self.label} has no radius of curvature")
        return Value(R, "the radius of curvature of the tip", CLOSED_FORM_RTOL)

    def stress_solver(self, st):
        from hertzmdr.numeric.scene.kinds.stresses import SuperposedStresses

        d = self.last(st)
        a = self.extent(d)
        solver = SuperposedStresses(lambda r, d=d: np.asarray(self.p(r, d), float), a,
                                    self.materials.stressed.nu)
        if self.interface.work_of_adhesion > 0:
            solver.unbounded = (UNBOUNDED, a)
        return solver

    def has(self, effect):
        if effect in ("max_shear", "max_von_mises") and self.materials.stressed.nu >= 0.5 \
                and self.interface.work_of_adhesion > 0:
            self.why_not = {**self.why_not, effect: (
                f"{UNBOUNDED}; with nu = 0.5 the stress there is hydrostatic to leading order "
                "and the maximum is not computed (ask for 'axis_stresses' or "
                "'von_mises_field')")}
            return False
        if isinstance(self.shape, ad.Sampled) and effect in SAMPLED_NOT:
            self.why_not = {**self.why_not, effect: SAMPLED_NOT[effect]}
            return False
        if effect == "effective_radius":
            return self.shape.radius_of_curvature is not None
        if effect in ("contact_time", "max_impact_depth", "max_impact_pressure"):
            return False
        return super().has(effect)

    def _both(self, what):
        out, errs, methods = {}, [], set()
        for control in ad.CONTROLS[::-1]:  # force control first
            po = self.model.pull_off(control)
            out[f"{control}_control"] = getattr(po, what)
            errs.append(po.rel_error)
            methods.add(po.method)
        return Value(out, " / ".join(sorted(methods)), max(errs))

    def effect_pull_off_force(self):
        return self._both("force")

    def effect_pull_off_depth(self):
        return self._both("depth")

    def effect_zero_load_contact_radius(self):
        a0 = self.model.zero_load_contact_radius()
        err = self.rel
        twin = self.shape.companion()
        if twin is not None:  # the numerical MDR: coarse vs fine samples
            other = ad.AdhesiveContact(twin, self.E_star, self.interface.work_of_adhesion)
            err += abs(other.zero_load_contact_radius() / a0 - 1)
        return Value(a0, "F(a) = 0 on the stable branch", err)

    def effect_adhesive_force_depth_curve(self, st):
        """The approach-push-retract history: to the scene's cycle, or to its largest load
        under its own control."""
        load = self._load
        if load.kind == "cycle":
            control, to, n = load.control, load.values[0], load.points
        else:
            control, n = load.kind, 1000
            to = float(np.max(st.depth if control == "depth" else st.force))
        cyc = self.model.cycle(to, control, n)
        # each jump as [before, after] of depth, force and contact radius: rows in the order
        # met (into contact first, the pull-off last)
        jumps = np.array([[j.before, j.after] for j in cyc.jumps], float).reshape(-1, 2, 3)
        value = {"depth": cyc.depth, "force": cyc.force, "contact_radius": cyc.contact_radius,
                 "loading": cyc.loading, "jump_depth": jumps[:, :, 0],
                 "jump_force": jumps[:, :, 1], "jump_contact_radius": jumps[:, :, 2],
                 "hysteresis": cyc.hysteresis}
        err = cyc.hysteresis_error / cyc.hysteresis if cyc.hysteresis > 0 else 0.0
        return Value(value, f"{control}-controlled cycle on the adhesive MDR curve, jumps at "
                     "its instabilities; hysteresis: Gauss-Legendre of F dd",
                     max(err, st.rel_error))

    def node_state(self, run):
        self._load = run.spec.load
        return self.state(run.spec.load)

    def effect_force(self, st):
        return Value(st.force, self.method, st.rel_error)

    def effect_depth(self, st):
        return Value(st.depth, self.method, st.rel_error)
