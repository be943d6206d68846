"""The tangential effects of a scene (Cattaneo-Mindlin by the MDR, numeric/tangential.py),
written once for every axisymmetric kind.

A kind with a closed-form tangential solution returns its profile from
``tangential_profile(d)`` (a sphere: a paraboloid of radius R; a cone, a power law, a flat
punch); any other axisymmetric kind with an MDR profile ``g(x)`` (a sampled profile, an exact
sphere, a worn tip) is run through the MDR's tangential springs on a grid
(``numeric.tangential.history``, with its grid-error estimate). The effects need
``[interface] friction`` and, except ``sliding_force`` and ``tangential_stiffness``, a
tangential part of the load: ``[load] tangential = {force = ...}`` or ``{displacement = ...}``
(monotonic from 0 at the constant normal load), ``oscillating = {amplitude = ..., cycles = N}``
(a tangential force between -amplitude and +amplitude), or ``history = {file = ...}``: an
explicit (normal, tangential) history, always run through the springs. See
docs/tangential.md and docs/scenes.md.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Value

#: relative error of the tangential closed forms (tests/test_tangential.py: 1e-13 against
#: 40-digit references, a few roundings more than the normal closed forms)
TANGENTIAL_RTOL = 1e-13
METHOD = "MDR tangential springs (Cattaneo-Mindlin, derive/tangential.py)"
#: the method of the spring runs, and their grid (intervals on [0, x_max]; the error estimate
#: runs on half of it)
SPRINGS = "MDR tangential springs on a grid (numeric.tangential.history; error: half grid)"
SPRING_GRID = 1000
#: the grid reaches this far beyond the largest contact radius
GRID_MARGIN = 1.25


@dataclass
class Springs:
    """A run of the tangential springs (numeric.tangential.History) and how to read it.

    ``history``: an explicit history (effects are arrays, one entry per state) or a constant
    normal load (effects at the tangential load, state ``at``); ``cycle``: the states of one
    full cycle of an oscillating load (after the first loading to the amplitude)."""

    run: object
    history: bool
    at: int = -1
    cycle: slice | None = None


@dataclass
class TangentialState:
    """The tangential contact at the scene's load: the closed-form contact (None when the
    springs are run), the tangential load (None when the scene gives only friction), its u_x
    [m] and F_x [N], the cycles of an oscillating load, and the springs' run (or None).
    ``sliding`` and ``stiffness`` are mu F [N] and 2 G* a [N/m] at the normal load, and
    ``rel`` their relative error; ``source`` the scene's file, named by the effects' refusals."""

    contact: object
    kind: str | None
    u_x: float | None
    F_x: float | None
    cycles: int
    springs: Springs | None = None
    sliding: float = 0.0
    stiffness: float = 0.0
    rel: float = CLOSED_FORM_RTOL
    source: str = "<scene>"


def _rel(err, value) -> float:
    """An absolute error over the largest |value| (a field's or a history's norm-wise
    relative error); 0 when both vanish."""
    scale = float(np.max(np.abs(np.asarray(value, float)))) if np.size(value) else 0.0
    if err == 0:
        return 0.0
    return float(err) / scale if scale > 0 else float("inf")


class TangentialEffects:
    """Mixin of the tangential effects; ``tangential_profile(d)`` is the kind's hook."""

    def tangential_profile(self, d: float):
        """The profile of numeric/tangential.py at depth d [m], or None (no closed form)."""
        return None

    def spring_profile(self):
        """The MDR profile g(x) [m] the springs run on, and the grid's fixed extent [m] (None:
        from the largest contact radius); None when the kind has no profile."""
        g = getattr(self, "g", None)
        return (g, None) if callable(g) else None

    def node_tangential(self, run) -> TangentialState:
        from hertzmdr.numeric import tangential as tg
        from hertzmdr.numeric.scene.schema import SceneError

        spec = run.spec
        mu = self.interface.friction
        if mu is None:
            raise SceneError(spec.source, "interface.friction", "the tangential effects need "
                             "the coefficient of friction: [interface] friction = 0.6, say")
        tl = spec.load.tangential
        if tl is not None and tl.kind == "history":
            return self._history_state(spec, mu)
        st = run.node("state")
        d = self.last(st)
        prof = self.tangential_profile(d)
        if prof is None:
            return self._spring_state(spec, st, mu)
        ct = tg.Contact(prof, float(self.a_at(d)), self.E_star, self.materials.G_star, mu)
        base = dict(sliding=ct.sliding_force, stiffness=ct.stiffness, source=spec.source)
        if tl is None:
            return TangentialState(ct, None, None, None, 0, **base)
        try:
            if tl.kind == "displacement":
                return TangentialState(ct, tl.kind, tl.value, float(ct.force(tl.value)), 0,
                                       **base)
            u = float(ct.displacement(tl.value))
        except ValueError as exc:
            key = "load.oscillating.amplitude" if tl.kind == "oscillating" else \
                "load.tangential.force"
            raise SceneError(spec.source, key, str(exc)) from None
        return TangentialState(ct, tl.kind, u, tl.value, tl.cycles, **base)

    def _profile_or_fail(self, spec):
        from hertzmdr.numeric.scene.schema import SceneError

        sp = self.spring_profile()
        if sp is None:
            raise SceneError(spec.source, "effects", "the tangential effects are derived for "
                             f"axisymmetric contacts with an MDR profile; this scene is "
                             f"{self.label}")
        return sp

    def _grid(self, spec, a_max):
        """g and x_max of the springs' grid for contact radii up to a_max [m]."""
        from hertzmdr.numeric.scene.schema import SceneError

        g, fixed = self._profile_or_fail(spec)
        # a flat punch's grid is fixed too, but a load that never presses is refused alike
        if not a_max > 0:
            raise SceneError(spec.source, "load", "the load never presses the bodies together "
                             "(contact radius 0 in every state): no tangential contact")
        if fixed is not None:
            return g, fixed
        x_max = GRID_MARGIN * a_max
        r_max = getattr(getattr(self, "profile", None), "r_max", None)  # a sampled profile
        return g, (min(x_max, r_max) if r_max is not None else x_max)

    def _springs(self, spec, key, lines=None, **kw):
        """numeric.tangential.history with the kind's profile; a ValueError becomes a
        SceneError on ``key`` (a step named by its line of the history file)."""
        from hertzmdr.numeric import tangential as tg
        from hertzmdr.numeric.scene.schema import SceneError

        n = SPRING_GRID // 2 if kw.pop("half", False) else SPRING_GRID
        try:
            return tg.history(E_star=self.E_star, G_star=self.materials.G_star,
                              mu=self.interface.friction, n_grid=n, wall=self._wall(), **kw)
        except ValueError as exc:
            msg = str(exc)
            if lines is not None:
                h = spec.load.tangential.history
                msg = re.sub(r"(\w+)\[(\d+)\]", lambda m: f"{m.group(1)} of {h.file} line "
                             f"{lines[int(m.group(2))]}", msg)
            raise SceneError(spec.source, key, msg) from None

    def _wall(self) -> bool:
        """Whether the springs' grid ends at a wall (a profile with a fixed extent: the flat
        punch, whose g is infinite beyond its radius)."""
        sp = self.spring_profile()
        return sp is not None and sp[1] is not None

    def _history_state(self, spec, mu) -> TangentialState:
        """An explicit history: every state through the springs, normal load included."""
        from hertzmdr.numeric import tangential as tg

        ld = spec.load
        h = ld.tangential.history
        normal = np.asarray(ld.values, float)
        top = float(normal.max())
        d_max = top if ld.kind == "depth" else float(np.atleast_1d(self.depth_of(top))[0])
        g, x_max = self._grid(spec, self.a_at(d_max) if d_max > 0 else 0.0)
        tang = np.asarray(h.values, float)
        kw = {"depth" if ld.kind == "depth" else "normal_force": normal,
              "u_x" if h.control == "displacement" else "F_x": tang}
        H = self._springs(spec, "load.history", h.lines, g=g, x_max=x_max, **kw)
        return TangentialState(None, "history", None, None, 0, Springs(H, True),
                               sliding=float(tg.sliding_force(mu, H.normal_force[-1])),
                               stiffness=float(tg.stiffness(float(H.contact_radius[-1]),
                                                            self.materials.G_star)))

    def _spring_state(self, spec, st, mu) -> TangentialState:
        """A constant normal load (the scene's depth or force) and a monotonic or oscillating
        tangential load, through the springs at the state's depth."""
        from hertzmdr.numeric import tangential as tg

        d = self.last(st)
        a = self.a_at(d)
        F_N = float(np.max(st.force))
        mu_F = float(tg.sliding_force(mu, F_N))  # Coulomb's limit
        base = dict(sliding=mu_F, stiffness=float(tg.stiffness(a, self.materials.G_star)),
                    rel=float(st.rel_error), source=spec.source)
        tl = spec.load.tangential
        if tl is None:
            self._profile_or_fail(spec)
            return TangentialState(None, None, None, None, 0, **base)
        g, x_max = self._grid(spec, a)
        if tl.kind == "oscillating":
            n1, n2 = FIELD_POINTS // 4, FIELD_POINTS // 2
            path = np.concatenate([np.linspace(0.0, tl.value, n1),
                                   np.linspace(tl.value, -tl.value, n2)[1:],
                                   np.linspace(-tl.value, tl.value, n2)[1:]])
            key, at, cyc = "load.oscillating.amplitude", n1 - 1, slice(n1 - 1, None)
        else:
            path = np.array([0.0, tl.value])
            key, at, cyc = f"load.tangential.{tl.kind}", 1, None
        if tl.kind != "displacement" and tl.value > mu_F * (1 + 1e-12):
            from hertzmdr.numeric.scene.schema import SceneError

            raise SceneError(spec.source, key, f"{tl.value!r} N exceeds the sliding force mu F "
                             f"= {mu_F!r} N (mu = {mu}); valid: <= mu F")
        if tl.kind != "displacement":
            # the grids' mu F (fine and half) may lie a little below the state's: an amplitude
            # within that grid error of mu F is clipped to the smaller (full sliding)
            lim = float(tg.sliding_force(mu, min(
                float(self._springs(spec, key, g=g, x_max=x_max, depth=[d], u_x=[0.0],
                                    estimate_error=False, half=half).normal_force[0])
                for half in (False, True))))
            path = np.clip(path, -lim, lim)
        kw = {"u_x" if tl.kind == "displacement" else "F_x": path}
        H = self._springs(spec, key, g=g, x_max=x_max, depth=np.full(path.size, d), **kw)
        sp = Springs(H, False, at, cyc)
        return TangentialState(None, tl.kind, float(H.u_x[at]), float(H.F_x[at]), tl.cycles,
                               sp, **base)

    def _need_load(self, ts: TangentialState, effect: str, oscillating: bool = False):
        from hertzmdr.numeric.scene.schema import SceneError

        if ts.kind is None or (oscillating and ts.kind not in ("oscillating", "history")):
            what = ("[load] oscillating = {amplitude = ..., cycles = N} or a history"
                    if oscillating else "[load] tangential = {force = ...} or "
                    "{displacement = ...}, oscillating or history")
            raise SceneError(ts.source, "effects", f"effect {effect!r} needs {what}")

    @staticmethod
    def _series(ts: TangentialState, name: str, label: str) -> Value:
        """A quantity of the springs' run: every state of a history, or the state at the
        tangential load; its error the grid estimate (norm-wise over a history)."""
        H = ts.springs.run
        v, err = getattr(H, name), getattr(H, name + "_error")
        if ts.springs.history:
            return Value(v, f"{SPRINGS}, {label} of every state", _rel(err, v))
        x = float(v[ts.springs.at])
        return Value(x, SPRINGS, _rel(err, x) + ts.rel)

    def effect_sliding_force(self, ts: TangentialState) -> Value:
        sp = ts.springs
        if sp is not None and sp.history:
            from hertzmdr.numeric import tangential as tg

            H = sp.run
            mu_F = tg.sliding_force(self.interface.friction, H.normal_force)
            return Value(mu_F, f"Coulomb: mu F of every state ({SPRINGS})",
                         _rel(H.normal_force_error, H.normal_force))
        return Value(ts.sliding, "Coulomb: mu F", ts.rel)

    def effect_tangential_stiffness(self, ts: TangentialState) -> Value:
        from hertzmdr.numeric import tangential as tg

        sp = ts.springs
        if sp is not None and sp.history:
            H = sp.run
            return Value(tg.stiffness(H.contact_radius, self.materials.G_star),
                         f"2 G* a (all springs stick) of every state, a from {SPRINGS}",
                         _rel(H.contact_radius_error, H.contact_radius))
        return Value(ts.stiffness, "2 G* a (all springs stick)", ts.rel)

    def effect_tangential_force(self, ts: TangentialState) -> Value:
        self._need_load(ts, "tangential_force")
        if ts.springs is not None:
            return self._series(ts, "F_x", "F_x")
        return Value(ts.F_x, METHOD, TANGENTIAL_RTOL)

    def effect_tangential_displacement(self, ts: TangentialState) -> Value:
        self._need_load(ts, "tangential_displacement")
        if ts.springs is not None:
            return self._series(ts, "u_x", "u_x")
        return Value(ts.u_x, METHOD, TANGENTIAL_RTOL)

    def effect_stick_radius(self, ts: TangentialState) -> Value:
        self._need_load(ts, "stick_radius")
        if ts.springs is not None:
            return self._series(ts, "stick_radius", "the stick radius")
        return Value(float(ts.contact.stick_radius_from_force(ts.F_x)), METHOD,
                     TANGENTIAL_RTOL)

    def effect_traction_profile(self, ts: TangentialState) -> Value:
        self._need_load(ts, "traction_profile")
        if ts.springs is not None:  # the final state (of a history) or at the load
            sp = ts.springs
            H = sp.run
            if not sp.history and sp.at != H.F_x.size - 1:  # an oscillation: to its amplitude
                H = self._springs_to(ts, sp.at)
            a = float(H.contact_radius[-1])
            keep = H.x <= a
            q = H.traction()
            return Value({"r": H.x[keep], "q": q[keep]}, f"{SPRINGS}, (5.59) of the springs' "
                         "line load" + (" in the final state" if sp.history else ""),
                         _rel(H.traction_error, q) + (0.0 if sp.history else ts.rel))
        a = ts.contact.a
        r = np.linspace(0.0, a, FIELD_POINTS)[:-1]  # the edge value of a punch is infinite
        if getattr(self, "off_axis", False):  # as the pressure profile: a cone's p (and so q
            r[0] = a * 1e-3  # under full slip) is log-infinite on the axis
        return Value({"r": r, "q": np.asarray(ts.contact.traction(r, ts.u_x), float)},
                     METHOD + ", (5.59)", TANGENTIAL_RTOL)

    def _springs_to(self, ts, k):
        """The springs' run of a constant-load oscillation up to its state k (the first
        arrival at the amplitude), for the traction there."""
        from hertzmdr.numeric import tangential as tg

        H = ts.springs.run
        return tg.history(self.spring_profile()[0], E_star=self.E_star,
                          G_star=self.materials.G_star, mu=self.interface.friction,
                          x_max=float(H.x[-1]), n_grid=SPRING_GRID, depth=H.depth[:k + 1],
                          F_x=H.F_x[:k + 1], wall=self._wall())

    def effect_dissipated_energy(self, ts: TangentialState) -> Value:
        self._need_load(ts, "dissipated_energy", oscillating=True)
        sp = ts.springs
        if sp is not None:
            H = sp.run
            if sp.history:
                W = float(H.dissipated[-1])
                return Value(W, f"{SPRINGS}: the friction work over the whole history",
                             _rel(H.dissipated_error, W))
            W = float(H.dissipated[-1] - H.dissipated[sp.at])
            return Value(W, f"{SPRINGS}: the friction work of one cycle",
                         _rel(2 * H.dissipated_error, W) + ts.rel)
        return Value(float(ts.contact.energy(ts.F_x)), "springs' loops (Mindlin-Deresiewicz "
                     "for a sphere)", TANGENTIAL_RTOL)

    def effect_hysteresis_loop(self, ts: TangentialState) -> Value:
        """First loading 0 -> (u*, F*), then ``cycles`` Masing loops (a history: F_x against
        u_x over all its states)."""
        self._need_load(ts, "hysteresis_loop", oscillating=True)
        sp = ts.springs
        if sp is not None:
            H = sp.run
            err = max(_rel(H.u_x_error, H.u_x), _rel(H.F_x_error, H.F_x))
            if sp.history:
                return Value({"u": H.u_x, "F": H.F_x}, f"{SPRINGS}, every state", err)
            first = slice(0, sp.at + 1)
            loop = slice(sp.at + 1, None)
            u = np.concatenate([H.u_x[first]] + [H.u_x[loop]] * ts.cycles)
            F = np.concatenate([H.F_x[first]] + [H.F_x[loop]] * ts.cycles)
            return Value({"u": u, "F": F}, f"{SPRINGS}: first loading, then one cycle of the "
                         "springs (repeated: a cycle returns every spring to its state)",
                         err + ts.rel)
        ct = ts.contact
        u0 = np.linspace(0.0, ts.u_x, FIELD_POINTS // 4)
        F0 = np.asarray(ct.force(u0), float)
        u_loop, F_loop = ct.loop(ts.F_x, 2 * (FIELD_POINTS // 2))
        u = np.concatenate([u0] + [u_loop] * ts.cycles)
        F = np.concatenate([F0] + [F_loop] * ts.cycles)
        return Value({"u": u, "F": F}, "first loading, then Masing's branches "
                     "F* - 2 F((u* - u)/2) (derived from the springs)", TANGENTIAL_RTOL)
