"""The materials of a scene's two bodies and the properties of their interface, as the two
objects every contact kind receives.

:class:`Materials` holds both bodies' E and nu (or that a body is rigid), the effective modulus
E* (5.26) derived from them by :func:`hertzmdr.numeric.bodies.effective_modulus`, and which body
the stress effects report (the first elastic one). A kind that needs more material data (G* for
tangential contact, say) reads it from here: no kind constructor changes.

:class:`Interface` holds the properties of the interface between the bodies: the work of
adhesion Delta gamma (0: no adhesion), the range z0 of the adhesive forces (for the Tabor
parameter) and the coefficient of friction ``friction`` (mu, for the tangential effects; None:
not given); each field has its key in :data:`Interface.KEYS`.
"""

from __future__ import annotations

import math
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
    def G_star(self) -> float:
        """Tangential effective modulus G* [Pa]: 1/G* = sum over the elastic bodies of
        (2 - nu_i)/(4 G_i), G_i = E_i/(2 (1 + nu_i)) (derive/tangential.py)."""
        import math

        from hertzmdr.numeric import tangential

        el = [m for m in self.bodies if not m.rigid]
        G = [float(tangential.shear_modulus(m.E, m.nu)) for m in el]
        if len(el) == 1:
            return float(tangential.effective_modulus(G[0], el[0].nu, math.inf, 0.0))
        return float(tangential.effective_modulus(G[0], el[0].nu, G[1], el[1].nu))

    @property
    def stressed(self) -> Material:
        """The body whose stresses the stress effects report: the first elastic one."""
        return next(m for m in self.bodies if not m.rigid)


@dataclass(frozen=True)
class Interface:
    """Properties of the interface between the two bodies.

    A scene's optional ``[interface]`` table fills it; :data:`KEYS` (key -> dimension) lists
    the keys it accepts, any other key is an error naming the allowed ones.

    Attributes
    ----------
    work_of_adhesion : float
        Delta gamma [J/m^2], >= 0; 0 (the default) is the non-adhesive contact, exactly.
    range : float or None
        z0 [m] > 0, the range of the adhesive forces (equilibrium distance): with it, the
        Tabor parameter is computed and a scene where JKR does not hold gets a warning.
    friction : float or None
        Coefficient of (Coulomb) friction mu >= 0, ``[interface] friction``; None when not
        given (the tangential effects then say that they need it).
    """

    work_of_adhesion: float = 0.0
    range: float | None = None
    friction: float | None = None

    KEYS: ClassVar[dict[str, str]] = {"work_of_adhesion": "surface_energy", "range": "length",
                                      "friction": "number"}

    def __post_init__(self):
        if not (math.isfinite(self.work_of_adhesion) and self.work_of_adhesion >= 0):
            raise ValueError(f"work_of_adhesion = {self.work_of_adhesion!r} J/m^2; valid: >= 0")
        if self.range is not None and not (math.isfinite(self.range) and self.range > 0):
            raise ValueError(f"range = {self.range!r} m; valid: > 0")
        if self.friction is not None and not (math.isfinite(self.friction)
                                              and self.friction >= 0):
            raise ValueError(f"friction = {self.friction!r}; valid: >= 0")

    @property
    def adhesive(self) -> bool:
        return self.work_of_adhesion > 0
