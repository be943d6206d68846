"""What every contact kind shares: the value of an effect, the contact state at the load, what
a builder receives, and the :class:`Contact` base class with the effects written once."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, NoReturn

import numpy as np

from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RANGE, CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.materials import Interface, Materials

if TYPE_CHECKING:
    from hertzmdr.numeric.scene.schema import SceneSpec

#: points of every field effect (profiles, curves): one constant for all kinds
FIELD_POINTS = 201


@dataclass
class Value:
    """One computed effect: its value (SI), how it was computed and its relative error."""

    value: object
    method: str
    rel_error: float


@dataclass
class State:
    """The contact at the scene's load: depth and force as arrays (one entry per load point),
    their relative error and how they were found. Kinds with more to carry subclass it."""

    depth: np.ndarray
    force: np.ndarray
    rel_error: float
    method: str


@dataclass(frozen=True)
class Setup:
    """What a kind's builder receives: the scene, both bodies' materials (E* among them)."""

    spec: SceneSpec
    materials: Materials

    @property
    def interface(self) -> Interface:
        return self.spec.interface

    @property
    def rtol(self) -> float:
        return self.spec.rtol

    def fail(self, key: str, message: str) -> NoReturn:
        from hertzmdr.numeric.scene.schema import SceneError

        raise SceneError(self.spec.source, key, message)

    def shaped(self) -> list:
        """The bodies that are not flat."""
        return [b for b in self.spec.bodies if b.shape != "flat"]


class Contact:
    """Base of the contact kinds.

    A kind defines ``state(load) -> State`` and one ``effect_<name>`` method per effect it can
    compute (an effect it lacks does not apply to it); the runner calls them with the nodes the
    effect needs (:mod:`..effects`). Every kind receives the :class:`Materials` and the
    :class:`Interface` of the scene and its ``rtol``.
    """

    kind = "?"
    label = "?"
    #: effect -> the effect that applies instead, for the error message
    instead: dict[str, str] = {}
    #: effect -> why it does not apply
    why_not: dict[str, str] = {}
    #: what computes the contact state, and the rtol it can deliver (accuracy.py)
    state_method = "closed forms"
    state_range: tuple[float, float] = CLOSED_FORM_RANGE
    rel = CLOSED_FORM_RTOL
    #: effect -> the primitive it is written from on this class: a kind without the primitive
    #: does not have the effect. ``force_of(d)``: the force [N] at depths d [m] (an array);
    #: ``p(r, d)``: the pressure [Pa] at distances r [m] from the centre of the contact along
    #: a line through it, at depth d [m]; ``extent(d)``: the contact's half-length [m] along
    #: that line
    PRIMITIVES = {"force_depth_curve": ("force_of",), "pressure_profile": ("p", "extent")}
    #: the method texts of the two effects written from them
    curve_method = "?"
    pressure_method = "?"
    #: whether the force-depth curve starts at d = 0 (else at its first step)
    curve_from_zero = True
    #: what the kind's builder decided, in words (quadratic: which principal radii made it)
    choice: str = ""
    #: why the model chose this kind (model.build), reported as the JSON's ``model.why``
    why: str = ""
    #: why the force-depth relation is no power law F = K d^n: the ``force_law`` effect's
    #: error on a kind without ``effect_force_law`` (it names ``force_depth_curve``)
    not_power_law = "its force-depth relation is not a power law F = K d^n"

    def __init__(self, materials: Materials, interface: Interface, rtol: float):
        self.materials = materials
        self.interface = interface
        self.rtol = rtol

    @property
    def E_star(self) -> float:
        """Effective modulus E* [Pa] (5.26)."""
        return self.materials.E_star

    def info(self) -> dict:
        out = {"kind": self.kind, "description": self.label, "effective_modulus": self.E_star,
               "rtol": self.rtol}
        if self.why:  # set by model.build: why this kind was chosen
            out["why"] = self.why
        return out

    def ratios(self, nodes: dict) -> dict[str, float]:
        """The ratios that measure how far the scene stretches the chapter's assumptions (keys
        of :data:`~..assumptions.ASSUMPTIONS`), at the largest load, from the nodes the run
        evaluated (``state``, ``impact``; a ratio of a node not evaluated is not measured).
        A kind measures what it already computes; this base measures nothing."""
        return {}

    def has(self, effect: str) -> bool:
        if effect == "force_law" and not callable(getattr(self, "effect_force_law", None)):
            return self.refuse_force_law()
        if not all(callable(getattr(self, prim, None)) for prim in self.PRIMITIVES.get(effect, ())):
            return False
        return callable(getattr(self, "effect_" + effect, None))

    def refuse_force_law(self) -> bool:
        """``force_law`` does not apply: say why (:attr:`not_power_law`) and offer the
        tabulated ``force_depth_curve`` where the kind has it; returns False."""
        self.why_not = {**self.why_not, "force_law": f"{self.label}: {self.not_power_law}"}
        if self.has("force_depth_curve"):
            self.instead = {**self.instead, "force_law": "force_depth_curve"}
        return False

    @staticmethod
    def law_value(law, equation: str, rel_error: float, per_length: float | None = None
                  ) -> Value:
        """The ``force_law`` effect of a :class:`hertzmdr.numeric.force_law.Law`: F = K d^n
        and dF/dd = stiffness_K d^stiffness_n; a line contact (``per_length`` its length L
        [m]) reports the law per unit length too, K = L K_per_length."""
        n = float(law.n)
        value = {"K": law.K, "n": law.n, "stiffness_K": law.stiffness_K,
                 "stiffness_n": law.stiffness_n}
        method = (f"F = K d^n, dF/dd = stiffness_K d^(n - 1), from {equation}: K and "
                  f"stiffness_K in N/m^{n:g}")
        if per_length is not None:
            value = {"K": law.K * per_length, "n": law.n,
                     "stiffness_K": law.stiffness_K * per_length,
                     "stiffness_n": law.stiffness_n, "K_per_length": law.K,
                     "stiffness_K_per_length": law.stiffness_K}
            method += (f"; per unit length F/L = K_per_length d^n (N/m^{n + 1:g}), d the "
                       "conventional depth of (5.35), a = sqrt(R d), not the approach of "
                       "the axes (which adds a logarithmic term)")
        return Value(value, method, rel_error)

    def rtol_ranges(self, effects) -> list[tuple[str, tuple[float, float]]]:
        """(method, the rtol range it can deliver) of each method the effects use."""
        return [(self.state_method, self.state_range)]

    def node_state(self, run) -> State:
        return self.state(run.spec.load)

    def effect_effective_modulus(self) -> Value:
        return Value(self.E_star, "(5.26)", CLOSED_FORM_RTOL)

    def effect_depth(self, st: State) -> Value:
        return Value(st.depth, st.method, st.rel_error)

    def effect_force(self, st: State) -> Value:
        return Value(st.force, st.method, st.rel_error)

    def effect_force_depth_curve(self, st: State) -> Value:
        """F(d) [N] on FIELD_POINTS depths from 0 (or its first step) to the largest load,
        from the kind's ``force_of``."""
        d = np.linspace(0.0, self.last(st), FIELD_POINTS)
        if not self.curve_from_zero:
            d = d[1:]
        return Value({"depth": d, "force": np.asarray(self.force_of(d), float)},
                     self.curve_method, st.rel_error)

    def pressure_radii(self, a: float) -> np.ndarray:
        """The points of a pressure profile [m]: 0 to 1.5 times the contact's half-length."""
        return np.linspace(0.0, 1.5 * a, FIELD_POINTS)

    def effect_pressure_profile(self, st: State) -> Value:
        """p along a line through the centre of the contact at the largest load, from the
        kind's ``p`` and ``extent``."""
        d = self.last(st)
        r = self.pressure_radii(self.extent(d))
        return Value({"r": r, "p": np.asarray(self.p(r, d), float)}, self.pressure_method,
                     st.rel_error)

    @staticmethod
    def last(st: State, key: str = "depth") -> float:
        """Field effects of a sweep are drawn at its largest load."""
        return float(np.max(getattr(st, key)))
