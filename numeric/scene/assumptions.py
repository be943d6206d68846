"""The assumptions of the chapter that a scene can stretch, and the one table of their limits.

The chapter's contacts are those of the half-space approximation (section 5.1): "the gradient
of the surfaces in the area of contact and within relative proximity is much smaller than
one", linear elasticity (small strains), frictionless normal contact, and for the line contact
the plane strain of a long strip. A scene can leave that range (a 1e308 N load on a 5 mm
sphere gives a/R = 37): its result then carries a warning naming the assumption, the measured
ratio and the limit.

Each contact kind reports the ratios it measures (:meth:`~.kinds.base.Contact.ratios`) from
quantities it already computes, at the largest load of the scene; :func:`check` compares them
with :data:`ASSUMPTIONS`, the only place the limits live (docs/scenes.md quotes this table,
checked by tests/test_warnings.py).

Not warned, on purpose: nu = 0.5 with a rigid partner is where the chapter's frictionless
normal problem is exact even with friction (Dundurs' second constant vanishes: normal and
tangential problems decouple); the impact of Problems 3-4 is quasi-static, but the chapter
states no limit of speed for it; a BEM contact (polygon punch, height map) measures no ratio
(its slopes are those of the given heights, its contact no circle).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Assumption:
    """One assumption of the chapter and the limit of the ratio that measures it.

    Attributes
    ----------
    ratio : str
        The measured ratio, as the warning prints it (``a/R``); the key of :data:`ASSUMPTIONS`.
    assumption : str
        The assumption, in words.
    limit : float
        The largest ratio without a warning.
    reason : str
        Why that limit (docs/scenes.md).
    kinds : str
        Which contacts measure it.
    """

    ratio: str
    assumption: str
    limit: float
    reason: str
    kinds: str

    def message(self, value: float) -> str:
        return f"{self.ratio} = {value:.3g} exceeds the limit {self.limit:g}: {self.assumption}"


ASSUMPTIONS: dict[str, Assumption] = {a.ratio: a for a in [
    Assumption(
        "a/R", "the half-space approximation takes the contact radius small against the "
        "radius of curvature", 0.1,
        "a/R is the surface gradient at the edge of the contact, which section 5.1 takes "
        "much smaller than one; at a/R = 0.1 the paraboloid (5.19) of the Hertz theory "
        "gives a force 0.10 % and a contact radius 0.17 % above those of the exact "
        "spherical cap (numeric/sphere.py), growing like (a/R)^2 (2.8 % and 4.8 % at "
        "a/R = 0.5); the half-space's own small-gradient error grows alike",
        "Hertz (circular, impact at its largest compression), elliptical (the larger of "
        "a/R1, b/R2), line (half-width over R), exact sphere, worn parabola"),
    Assumption(
        "d/R", "linear elasticity takes the depth small against the radius of curvature "
        "(small strains)", 0.01,
        "d/R = (a/R)^2 for a Hertz contact (5.21): the same bound as a/R",
        "the same as a/R (elliptical: over the smaller principal radius)"),
    Assumption(
        "tan(theta)", "the half-space approximation takes a cone's surface gradient much "
        "smaller than one", 0.1,
        "section 5.1 takes the surface gradient much smaller than one; the corrections of "
        "finite slope to the cone's half-space solution (Sneddon) are first order in "
        "tan(theta): Hay, Bolshakov and Pharr (1999) give about 2 % at tan(theta) = 0.1 and "
        "8 % for a Berkovich-equivalent cone (theta = 19.7 deg) with nu = 0.25",
        "cone"),
    Assumption(
        "d/a", "linear elasticity takes the depth small against the contact radius (small "
        "strains)", 0.1,
        "the strain and the mean surface gradient under the contact are of order d/a; "
        "d/a = a/R for a Hertz contact and (pi/2) tan(theta) for a cone (5.38): the bound "
        "of a/R and about that of tan(theta), for profiles with no one radius or angle",
        "power law, flat punch, sampled profile (numerical MDR), prescribed pressure (the "
        "displacement of the centre over the disc's radius)"),
    Assumption(
        "a/L", "the line contact's plane strain takes the half-width small against the "
        "length", 0.1,
        "the ends of a finite strip disturb the pressure over about a half-width each: at "
        "a/L = 0.1 a fifth of the length",
        "line"),
]}


def check(ratios: dict[str, float]) -> list[dict]:
    """The warnings of the measured ``ratios`` (key of :data:`ASSUMPTIONS` -> value): one
    record per ratio above its limit, with the assumption, the ratio, its value, the limit and
    the message the table prints."""
    out = []
    for key, value in ratios.items():
        a = ASSUMPTIONS[key]
        if value > a.limit:
            out.append({"assumption": a.assumption, "ratio": a.ratio, "value": float(value),
                        "limit": a.limit, "message": a.message(value)})
    return out


def markdown() -> str:
    """The table of docs/scenes.md."""
    rows = ["| ratio | assumption | limit | why this limit | measured by |",
            "| --- | --- | --- | --- | --- |"]
    rows += [f"| `{a.ratio}` | {a.assumption} | {a.limit:g} | {a.reason} | {a.kinds} |"
             for a in ASSUMPTIONS.values()]
    return "\n".join(rows)
