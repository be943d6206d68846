"""Build the contact that a scene's two bodies and its load call for.

- The materials: both bodies' E and nu, E* (5.26) (:class:`~.materials.Materials`).
- The kind: the first row of :data:`~.kinds.KINDS` whose loads include the scene's load and
  whose name both bodies' shapes list (a flat partners any kind); its builder makes the contact
  from the shapes' geometry (principal radii, an MDR closed form, samples, a height map).
- Adhesion: with ``[interface] work_of_adhesion`` > 0 (or a ``[load] cycle``), the contact
  is made adhesive (:mod:`.kinds.adhesive`); 0 leaves it exactly as it is.
- The accuracy contract: ``[accuracy] rtol`` must lie in the range of every method the
  requested effects use (:mod:`.accuracy`), else a SceneError names the range.
"""

from __future__ import annotations

from hertzmdr.numeric.scene.accuracy import outside
from hertzmdr.numeric.scene.kinds import KINDS, Contact, Setup
from hertzmdr.numeric.scene.materials import Material, Materials
from hertzmdr.numeric.scene.schema import SceneError, SceneSpec
from hertzmdr.numeric.scene.shapes import SHAPES


def materials(spec: SceneSpec) -> Materials:
    return Materials.of(*(Material(b.name, b.E, b.nu) for b in spec.bodies))


def build(spec: SceneSpec) -> Contact:
    """The contact of the scene, its rtol checked against the methods it will use."""
    setup = Setup(spec, materials(spec))
    shapes = [SHAPES[b.shape] for b in spec.bodies]
    load = spec.load.kind if spec.load.kind != "cycle" else spec.load.control
    for row in KINDS:
        if load in row.loads and row.takes(shapes):
            contact = row.build(setup)
            why = why_chosen(spec, row, contact)
            if spec.interface.adhesive or spec.load.kind == "cycle":
                from hertzmdr.numeric.scene.kinds.adhesive import adhesive

                contact = adhesive(setup, contact)
                why += (f"; work of adhesion {spec.interface.work_of_adhesion:g} J/m^2 "
                        + ("> 0" if spec.interface.adhesive else "and a [load] cycle")
                        + f" -> made adhesive by the MDR: {contact.label}")
            contact.why = why
            check_rtol(spec, contact)
            return contact
    only = [row for row in KINDS if row.loads == (load,)]
    names = " and ".join(sorted(b.shape for b in spec.bodies))
    if only:  # a load that only one kind takes: say what that kind needs
        raise SceneError(spec.source, f"load.{load}", f"{only[0].needs}; this one has {names}")
    makes = "; ".join(f"{s.name}: {', '.join(s.kinds)}" for s in {s.name: s for s in shapes}
                      .values())
    raise SceneError(spec.source, "body", f"this combination of shapes ({names}) is not "
                     "supported: two bodies make a contact when both take part in the same "
                     f"kind, or one is flat (kinds: {makes})")


def why_chosen(spec: SceneSpec, row, contact: Contact) -> str:
    """The model's choice in words, for the JSON's ``model.why``: the two shapes and the
    load, the KINDS row that took them, and what its builder decided (``contact.choice``,
    e.g. the principal radii that made a quadratic gap circular, elliptical or a line)."""
    shapes = " and ".join(f"{b.shape} ({b.name})" for b in spec.bodies)
    out = f"{shapes} under a {spec.load.kind} load -> row '{row.name}' of KINDS ({row.needs})"
    return f"{out}: {contact.choice}" if contact.choice else f"{out} -> {contact.label}"


def check_rtol(spec: SceneSpec, contact: Contact) -> None:
    for method, rng in contact.rtol_ranges(spec.effects):
        if outside(spec.rtol, rng):
            raise SceneError(spec.source, "accuracy.rtol",
                             f"{spec.rtol:g} is outside the range {method} can deliver: "
                             f"[{rng[0]:g}, {rng[1]:g}]")
