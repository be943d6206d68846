"""The tangential effects of a scene (Cattaneo-Mindlin by the MDR, numeric/tangential.py),
written once for every axisymmetric kind with a closed-form tangential solution.

A kind takes part by returning its profile from ``tangential_profile(d)`` (a sphere: a
paraboloid of radius R; a cone, a power law, a flat punch); the effects then need
``[interface] friction`` and, except ``sliding_force`` and ``tangential_stiffness``, a
tangential part of the load: ``[load] tangential = {force = ...}`` or ``{displacement = ...}``
(monotonic from 0 at the constant normal load) or ``oscillating = {amplitude = ..., cycles = N}``
(a tangential force between -amplitude and +amplitude). See docs/tangential.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import FIELD_POINTS, Value

#: relative error of the tangential closed forms (tests/test_tangential.py: 1e-13 against
#: 40-digit references, a few roundings more than the normal closed forms)
TANGENTIAL_RTOL = 1e-13
METHOD = "MDR tangential springs (Cattaneo-Mindlin, derive/tangential.py)"


@dataclass
class TangentialState:
    """The tangential contact at the scene's load: the closed-form contact, the tangential
    load (None when the scene gives only friction), its u_x [m] and F_x [N]."""

    contact: object
    kind: str | None
    u_x: float | None
    F_x: float | None
    cycles: int


class TangentialEffects:
    """Mixin of the tangential effects; ``tangential_profile(d)`` is the kind's hook."""

    def tangential_profile(self, d: float):
        """The profile of numeric/tangential.py at depth d [m], or None (no closed form)."""
        return None

    def node_tangential(self, run) -> TangentialState:
        from hertzmdr.numeric import tangential as tg
        from hertzmdr.numeric.scene.schema import SceneError

        spec = run.spec
        mu = self.interface.friction
        if mu is None:
            raise SceneError(spec.source, "interface.friction", "the tangential effects need "
                             "the coefficient of friction: [interface] friction = 0.6, say")
        st = run.node("state")
        d = self.last(st)
        prof = self.tangential_profile(d)
        if prof is None:
            raise SceneError(spec.source, "effects", "tangential contact has closed forms for "
                             "a sphere, a cone, a power-law profile and a flat punch; this "
                             f"scene is {self.label} (numeric.tangential.history runs the "
                             "springs for any MDR profile g(x))")
        ct = tg.Contact(prof, float(self.a_at(d)), self.E_star, self.materials.G_star, mu)
        tl = spec.load.tangential
        if tl is None:
            return TangentialState(ct, None, None, None, 0)
        try:
            if tl.kind == "displacement":
                return TangentialState(ct, tl.kind, tl.value, float(ct.force(tl.value)), 0)
            u = float(ct.displacement(tl.value))
        except ValueError as exc:
            key = "load.oscillating.amplitude" if tl.kind == "oscillating" else \
                "load.tangential.force"
            raise SceneError(spec.source, key, str(exc)) from None
        return TangentialState(ct, tl.kind, u, tl.value, tl.cycles)

    def _need_load(self, ts: TangentialState, effect: str, oscillating: bool = False):
        from hertzmdr.numeric.scene.schema import SceneError

        if ts.kind is None or (oscillating and ts.kind != "oscillating"):
            what = ("[load] oscillating = {amplitude = ..., cycles = N}" if oscillating else
                    "[load] tangential = {force = ...} or {displacement = ...}, or oscillating")
            raise SceneError("<scene>", "effects", f"effect {effect!r} needs {what}")

    def effect_sliding_force(self, ts: TangentialState) -> Value:
        return Value(ts.contact.sliding_force, "Coulomb: mu F", CLOSED_FORM_RTOL)

    def effect_tangential_stiffness(self, ts: TangentialState) -> Value:
        return Value(ts.contact.stiffness, "2 G* a (all springs stick)", CLOSED_FORM_RTOL)

    def effect_tangential_force(self, ts: TangentialState) -> Value:
        self._need_load(ts, "tangential_force")
        return Value(ts.F_x, METHOD, TANGENTIAL_RTOL)

    def effect_tangential_displacement(self, ts: TangentialState) -> Value:
        self._need_load(ts, "tangential_displacement")
        return Value(ts.u_x, METHOD, TANGENTIAL_RTOL)

    def effect_stick_radius(self, ts: TangentialState) -> Value:
        self._need_load(ts, "stick_radius")
        return Value(float(ts.contact.stick_radius_from_force(ts.F_x)), METHOD,
                     TANGENTIAL_RTOL)

    def effect_traction_profile(self, ts: TangentialState) -> Value:
        self._need_load(ts, "traction_profile")
        a = ts.contact.a
        r = np.linspace(0.0, a, FIELD_POINTS)[:-1]  # the edge value of a punch is infinite
        if getattr(self, "off_axis", False):  # as the pressure profile: a cone's p (and so q
            r[0] = a * 1e-3  # under full slip) is log-infinite on the axis
        return Value({"r": r, "q": np.asarray(ts.contact.traction(r, ts.u_x), float)},
                     METHOD + ", (5.59)", TANGENTIAL_RTOL)

    def effect_dissipated_energy(self, ts: TangentialState) -> Value:
        self._need_load(ts, "dissipated_energy", oscillating=True)
        return Value(float(ts.contact.energy(ts.F_x)), "springs' loops (Mindlin-Deresiewicz "
                     "for a sphere)", TANGENTIAL_RTOL)

    def effect_hysteresis_loop(self, ts: TangentialState) -> Value:
        """First loading 0 -> (u*, F*), then ``cycles`` Masing loops."""
        self._need_load(ts, "hysteresis_loop", oscillating=True)
        ct = ts.contact
        u0 = np.linspace(0.0, ts.u_x, FIELD_POINTS // 4)
        F0 = np.asarray(ct.force(u0), float)
        u_loop, F_loop = ct.loop(ts.F_x, 2 * (FIELD_POINTS // 2))
        u = np.concatenate([u0] + [u_loop] * ts.cycles)
        F = np.concatenate([F0] + [F_loop] * ts.cycles)
        return Value({"u": u, "F": F}, "first loading, then Masing's branches "
                     "F* - 2 F((u* - u)/2) (derived from the springs)", TANGENTIAL_RTOL)
