"""Run a scene: build the contact its bodies call for, then evaluate exactly the requested
effects and the nodes they need, each once, timing each."""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric.scene.assumptions import check as check_assumptions
from hertzmdr.numeric.scene.effects import EFFECTS
from hertzmdr.numeric.scene.kinds import Contact
from hertzmdr.numeric.scene.kinds.adhesive import ADHESIVE_EFFECTS
from hertzmdr.numeric.scene.model import build
from hertzmdr.numeric.scene.schema import SceneError, SceneSpec


@dataclass
class Result:
    """The outcome of one effect."""

    name: str
    value: object
    unit: str
    method: str
    rel_error: float
    met_rtol: bool  # rel_error <= the scene's rtol
    seconds: float


@dataclass
class Run:
    """One run of a scene: its contact, and the nodes evaluated (each once), in order."""

    spec: SceneSpec
    contact: Contact
    evaluated: list[str] = field(default_factory=list)  # nodes, in the order they ran
    model_seconds: float = 0.0
    #: the chapter's assumptions the scene stretches (assumptions.check), after the effects
    warnings: list[dict] = field(default_factory=list)
    _nodes: dict = field(default_factory=dict)

    def node(self, name: str):
        """The node ``name`` (``state``, ``impact``, ``stress``), evaluated on first use."""
        if name not in self._nodes:
            self._nodes[name] = getattr(self.contact, "node_" + name)(self)
            self.evaluated.append(name)
        return self._nodes[name]

    def effect(self, name: str) -> Result:
        eff = EFFECTS[name]
        t0 = time.perf_counter()
        try:
            with np.errstate(over="raise", invalid="raise", divide="raise"):
                args = [self.node(n) for n in eff.needs]
                v = getattr(self.contact, "effect_" + name)(*args)
        except SceneError:  # a node's own message names its key already
            raise
        except (ValueError, ArithmeticError) as exc:  # numeric/'s validators name the input
            raise SceneError(self.spec.source, "effects",  # and its valid range
                             f"{name!r} at this load: {reason(exc)}") from exc
        seconds = time.perf_counter() - t0
        self.evaluated.append(name)
        err = float(v.rel_error)
        return Result(name, v.value, eff.unit, v.method, err, err <= self.spec.rtol, seconds)


def reason(exc: Exception) -> str:
    """The message of a failed computation; float64's own (an overflow, 0/0 of inputs far
    outside the physics' range) says which values to look at."""
    if isinstance(exc, FloatingPointError):
        return (f"the computation leaves float64's range ({exc}): a load, size or modulus of "
                "the scene is far outside what the contact can represent")
    return str(exc)


def check_applicable(spec: SceneSpec, contact) -> None:
    for name in spec.effects:
        if "impact" in EFFECTS[name].needs and spec.load.kind != "impact":
            raise SceneError(spec.source, "effects", f"effect {name!r} needs an impact: give "
                             "[load.impact] with velocity and mass or density")
        if contact.has(name):
            continue
        why = contact.why_not.get(name, f"{contact.label} has no {name.replace('_', ' ')}")
        if name in ADHESIVE_EFFECTS and not spec.interface.adhesive:
            why = ("it needs adhesion: give [interface] work_of_adhesion = \"... J/m^2\" "
                   "(> 0)")
        alt = contact.instead.get(name)
        hint = f"; use {alt!r}" if alt else ""
        raise SceneError(spec.source, "effects",
                         f"effect {name!r} does not apply to this scene: {why}{hint}")


def run(spec: SceneSpec) -> tuple[Run, dict[str, Result]]:
    t0 = time.perf_counter()
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            contact = build(spec)
    except ArithmeticError as exc:  # (a ValueError is the builders' SceneError)
        raise SceneError(spec.source, "body", reason(exc)) from exc
    r = Run(spec, contact)
    r.evaluated.append("model")
    check_applicable(spec, contact)
    results = {name: r.effect(name) for name in spec.effects}
    r.warnings = check_assumptions(contact.ratios(r._nodes))
    r.model_seconds = time.perf_counter() - t0
    return r, results


def to_json_value(value):
    """Arrays to lists, NumPy scalars to Python numbers (a count stays an integer: a grid of
    32 x 32 pixels, not 32.0), recursively."""
    if isinstance(value, dict):
        return {k: to_json_value(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [to_json_value(v) for v in value]
    arr = np.asarray(value)
    if arr.ndim == 0:
        return (int(arr) if arr.dtype.kind in "iu" else float(arr) if arr.dtype.kind == "f"
                else value)
    if arr.size == 1 and arr.ndim == 1 and arr.dtype.kind in "fiu":
        return int(arr[0]) if arr.dtype.kind in "iu" else float(arr[0])
    return arr.tolist()


def document(run_: Run, results: dict[str, Result]) -> dict:
    """The JSON document of a run (see docs/scenes.md); its scene as understood, version and
    files from :func:`.echo.inputs`."""
    from hertzmdr.numeric.scene.echo import inputs

    model = {k: to_json_value(v) for k, v in run_.contact.info().items()}
    return {
        "title": run_.spec.title,
        "model": model,
        "effects": {name: {"value": to_json_value(res.value), "unit": res.unit,
                           "method": res.method, "rel_error": res.rel_error,
                           "met_rtol": res.met_rtol, "seconds": res.seconds}
                    for name, res in results.items()},
        "warnings": run_.warnings,
        **inputs(run_.spec),
    }
