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

    def run_full(self, progress=None):
        """(run record, results, document): the record lists the nodes evaluated; for a study
        (docs/scenes.md, "Studies") it is the :class:`~.study.StudyRun`, each result one entry
        per point, and ``progress(done, total)`` is called after each point of a study run
        point by point."""
        from hertzmdr.numeric.scene.runner import document, run

        study = self.spec.study
        if study is not None and not study.load_only:
            from hertzmdr.numeric.scene import study as st

            record = st.run(self.spec, progress)
            return record, record.results, st.document(self.spec, record)
        record, results = run(self.spec)
        doc = document(record, results)
        if study is not None:  # a load sweep: the swept load in the result too
            doc["study"] = study.block()
        return record, results, doc


def load(path_or_dict) -> Scene:
    """Read and validate a scene from a TOML file path or a dict; raises SceneError."""
    return Scene(read(path_or_dict, known_effects=EFFECTS))
