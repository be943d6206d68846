"""Scenes: describe two bodies, their load and the effects you want; get exactly those.

>>> from hertzmdr.numeric import scene
>>> doc = scene.load("examples/problem1_rail_wheel.toml").run()   # doctest: +SKIP
>>> doc["effects"]["max_pressure"]["value"]                        # doctest: +SKIP

The schema and every effect are documented in docs/scenes.md; ``hertzmdr run SCENE`` is the
command-line form.
"""

from __future__ import annotations

from hertzmdr.numeric.scene.effects import EFFECTS
from hertzmdr.numeric.scene.schema import SceneError, SceneSpec, read

__all__ = ["EFFECTS", "Scene", "SceneError", "load"]


class Scene:
    """A validated scene; :meth:`run` computes its effects."""

    def __init__(self, spec: SceneSpec):
        self.spec = spec

    def run(self) -> dict:
        """Compute the requested effects; returns the JSON document as a dict (SI units)."""
        return self.run_full()[2]

    def run_full(self):
        """(run record, results, document): the record lists the nodes evaluated."""
        from hertzmdr.numeric.scene.runner import document, run

        record, results = run(self.spec)
        return record, results, document(record, results)


def load(path_or_dict) -> Scene:
    """Read and validate a scene from a TOML file path or a dict; raises SceneError."""
    return Scene(read(path_or_dict, known_effects=EFFECTS))
