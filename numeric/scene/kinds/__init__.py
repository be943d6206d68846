"""Contact kinds: one module per kind, each a :class:`Contact` subclass with one method per
effect it can compute. The runner asks a kind for an effect by name; an effect a kind does not
have does not apply to it. Adding a kind is adding a module and a row in :data:`KINDS`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: relative error bound of a generated closed form evaluated in float64: the tolerance to which
#: tests/ verify every generated function against its 50-digit independent reference
CLOSED_FORM_RTOL = 1e-14


@dataclass
class Value:
    """One computed effect: its value (SI), how it was computed and its relative error."""

    value: object
    method: str
    rel_error: float


@dataclass
class State:
    """The contact at the scene's load: depth and force as arrays (one entry per load point)."""

    depth: np.ndarray
    force: np.ndarray
    rel_error: float
    method: str
    extra: dict


class Contact:
    """Base of the contact kinds."""

    kind = "?"
    label = "?"
    #: effect -> the effect that applies instead, for the error message
    instead: dict[str, str] = {}
    #: effect -> why it does not apply
    why_not: dict[str, str] = {}

    def __init__(self, E_star: float, rtol: float | None):
        self.E_star = E_star
        self.rtol = rtol

    def info(self) -> dict:
        return {"kind": self.kind, "description": self.label, "effective_modulus": self.E_star}

    def has(self, effect: str) -> bool:
        return callable(getattr(self, "effect_" + effect, None))

    def state(self, load) -> State:
        """The contact at the load (depth- or force-controlled); every kind defines it."""
        raise NotImplementedError(f"{type(self).__name__} must define state()")

    def node_state(self, run) -> State:
        return self.state(run.spec.load)

    def node_impact(self, run):
        """The impact's closed forms and integrated motion; only kinds that can strike."""
        return None

    def effect_effective_modulus(self) -> Value:
        return Value(self.E_star, "(5.26)", CLOSED_FORM_RTOL)

    def effect_depth(self, st: State) -> Value:
        return Value(st.depth, st.method, st.rel_error)

    def effect_force(self, st: State) -> Value:
        return Value(st.force, st.method, st.rel_error)

    @staticmethod
    def last(st: State, key: str = "depth") -> float:
        """Field effects of a sweep are drawn at its largest load."""
        return float(np.max(getattr(st, key)))
