"""The materials of a scene's two bodies and the properties of their interface, as the two
objects every contact kind receives.

:class:`Materials` holds both bodies' E and nu (or that a body is rigid), the effective modulus
E* (5.26) derived from them by :func:`hertzmdr.numeric.bodies.effective_modulus`, and which body
the stress effects report (the first elastic one). A kind that needs more material data (G* for
tangential contact, say) reads it from here: no kind constructor changes.

:class:`Interface` holds the properties of the interface between the bodies. It has none yet:
the contact is frictionless and non-adhesive, and the ``[interface]`` table of a scene accepts no
keys. Adhesion (the work of adhesion) and friction (the coefficient of friction) plug in here as
fields with their keys in :data:`Interface.KEYS`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar


@dataclass(frozen=True)
class Material:
    """One body's material: Young's modulus E [Pa] and Poisson's ratio nu, or rigid (both None)."""

    body: str
    E: float | None
    nu: float | None

    @property
    def rigid(self) -> bool:
        return self.E is None


@dataclass(frozen=True)
class Materials:
    """Both bodies' materials and what follows from them.

    Attributes
    ----------
    bodies : tuple of two :class:`Material`
        In the order of the scene's ``[[body]]`` tables.
    E_star : float
        Effective modulus E* [Pa] (5.26): both materials, or the elastic one when the other body
        is rigid.
    """

    bodies: tuple[Material, Material]
    E_star: float

    @classmethod
    def of(cls, first: Material, second: Material) -> Materials:
        """The materials of two bodies, at least one elastic; E* from (5.26)."""
        from hertzmdr.numeric import bodies

        elastic = [m for m in (first, second) if not m.rigid]
        if not elastic:
            raise ValueError("both bodies are rigid: at least one must have E and nu")
        args = [v for m in elastic for v in (m.E, m.nu)]
        return cls((first, second), float(bodies.effective_modulus(*args)))

    @property
    def stressed(self) -> Material:
        """The body whose stresses the stress effects report: the first elastic one."""
        return next(m for m in self.bodies if not m.rigid)


@dataclass(frozen=True)
class Interface:
    """Properties of the interface between the two bodies: none yet (frictionless, no adhesion).

    A scene's optional ``[interface]`` table fills it; :data:`KEYS` (key -> dimension) lists
    the keys it accepts, none today, so any key there is an error naming the allowed ones.
    """

    KEYS: ClassVar[dict[str, str]] = {}
