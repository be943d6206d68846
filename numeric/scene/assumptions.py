"""The assumptions of the chapter that a scene can stretch, and the one table of their limits.

The chapter's contacts are those of the half-space approximation (section 5.1): "the gradient
of the surfaces in the area of contact and within relative proximity is much smaller than
one", linear elasticity (small strains), frictionless normal contact, and for the line contact
the plane strain of a long strip. A scene can leave that range (a 1e308 N load on a 5 mm
sphere gives a/R = 37): its result then carries a warning naming the assumption, the measured
ratio and the limit. JKR adhesion (numeric/adhesion.py) assumes in addition a Tabor parameter
large enough: its limit is a lower one (``direction="below"``).

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

from hertzmdr.numeric.adhesion import TABOR_JKR


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
        The largest ratio without a warning (``direction`` "above"), or the smallest
        ("below").
    reason : str
        Why that limit (docs/scenes.md).
    kinds : str
        Which contacts measure it.
    direction : str
        "above": a ratio above the limit warns (a geometric ratio that must stay small);
        "below": a ratio below it warns (the Tabor parameter, which must stay large).
    """

    ratio: str
    assumption: str
    limit: float
    reason: str
    kinds: str
    direction: str = "above"

    def __post_init__(self):
        if self.direction not in ("above", "below"):
            raise ValueError(f"direction = {self.direction!r} is not 'above' or 'below'")

    def stretched(self, value: float) -> bool:
        """Whether ``value`` is past the limit (on the side of :attr:`direction`)."""
        return value > self.limit if self.direction == "above" else value < self.limit

    def message(self, value: float) -> str:
        past = "exceeds" if self.direction == "above" else "is below"
        return f"{self.ratio} = {value:.3g} {past} the limit {self.limit:g}: {self.assumption}"

    def limit_text(self) -> str:
        """The limit as the table prints it: a lower limit says so."""
        return f"{self.limit:g}" + (" (warns below)" if self.direction == "below" else "")


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
    Assumption(
        "mu_T", "JKR takes the adhesive contact compliant against the range of the adhesive "
        "forces (mu_T < 0.1: DMT; in between: Maugis-Dugdale); the adhesive results are "
        "those of JKR", TABOR_JKR,
        "the Tabor parameter mu_T = (R Delta gamma^2/(E*^2 z0^3))^(1/3) compares the elastic "
        "neck at the edge of the contact with the range z0 of the adhesive forces; by "
        "Maugis's (1992) Dugdale model the JKR pull-off force is within a few per cent for "
        "mu_T > 5 (it falls from -3/2 to -2 pi R Delta gamma, the DMT value, as mu_T goes "
        "to 0)",
        "adhesive contacts with a radius of curvature (sphere, exact sphere, worn parabola, "
        "power law n = 2) whose interface gives a `range`", "below"),
    Assumption(
        "1/sides", "the MDR takes the profile axisymmetric (a cone is a pyramid of infinitely "
        "many faces); a pyramid is solved as the cone of the same cross-section area at every "
        "depth (F = K E* d^2, K stated with the model), an approximation of its force", 0.0,
        "no pyramid is axisymmetric: the equal-area cone has its contact area at every depth "
        "but not its exact force; the flat punch of square section is 1.021 times stiffer "
        "than the circular one of the same area, of triangular section 1.061 "
        "(docs/non_axisymmetric.md), and other equivalent-cone conventions differ by a few "
        "per cent (docs/fitting.md)",
        "pyramid"),
]}


def check(ratios: dict[str, float]) -> list[dict]:
    """The warnings of the measured ``ratios`` (key of :data:`ASSUMPTIONS` -> value): one
    record per ratio past its limit (above it, or below a lower limit), with the assumption,
    the ratio, its value, the limit and the message the table prints."""
    out = []
    for key, value in ratios.items():
        a = ASSUMPTIONS[key]
        if a.stretched(value):
            out.append({"assumption": a.assumption, "ratio": a.ratio, "value": float(value),
                        "limit": a.limit, "message": a.message(value)})
    return out


def markdown() -> str:
    """The table of docs/scenes.md."""
    rows = ["| ratio | assumption | limit | why this limit | measured by |",
            "| --- | --- | --- | --- | --- |"]
    rows += [f"| `{a.ratio}` | {a.assumption} | {a.limit_text()} | {a.reason} | {a.kinds} |"
             for a in ASSUMPTIONS.values()]
    return "\n".join(rows)
