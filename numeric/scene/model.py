"""Build the contact that a scene's two bodies call for.

- E* from both materials, or from the elastic one when the other is rigid (5.26).
- Two quadratic surfaces (flat, sphere, cylinder, ellipsoid): the gap is a quadratic form; its
  principal radii decide: equal -> circular Hertz; different -> elliptical contact (exact, or
  the chapter's Gaussian radius (5.28)-(5.30) with ``[model] elliptic = "gaussian"``); one zero
  curvature from parallel cylinders (or a cylinder on a flat) -> line contact (5.34)-(5.37).
- Axisymmetric profiles (cone, flat punch, power law, flattened parabola, samples) against a
  flat: the MDR closed form of that profile; any other axisymmetric pair: the numerical MDR of
  the summed gap f1(r) + f2(r).
"""

from __future__ import annotations

import math

from hertzmdr.numeric.scene.kinds.hertz import HertzContact
from hertzmdr.numeric.scene.schema import SceneError, SceneSpec

QUADRATIC = {"flat", "sphere", "cylinder", "ellipsoid"}
AXISYMMETRIC = {"flat", "sphere", "cone", "flat_punch", "power_law", "flattened_parabola",
                "profile"}
#: relative difference of the principal radii below which a gap is treated as circular: the
#: elliptical solution tends continuously to the circular one, and at this difference the
#: two agree to about 1e-12 (documented in docs/scenes.md)
CIRCULAR_RTOL = 1e-12


def effective_modulus(spec: SceneSpec) -> float:
    from hertzmdr.numeric import bodies

    b1, b2 = spec.bodies
    if b1.rigid:
        b1, b2 = b2, b1
    if b2.rigid:
        return float(bodies.effective_modulus(b1.E, b1.nu))
    return float(bodies.effective_modulus(b1.E, b1.nu, b2.E, b2.nu))


def _principal(body) -> tuple[float, float, float]:
    """(R1, R2, angle of R1's direction) of a quadratic surface; inf for flat directions."""
    p = body.params
    if body.shape == "flat":
        return math.inf, math.inf, 0.0
    if body.shape == "sphere":
        return p["radius"], p["radius"], 0.0
    if body.shape == "cylinder":  # curved across its axis, straight along it
        return p["radius"], math.inf, p.get("axis", 0.0) + math.pi / 2
    R1, R2 = p["radii"]
    return R1, R2, p.get("axis", 0.0)


def build(spec: SceneSpec):
    contact = _build(spec)
    elastic = next(b for b in spec.bodies if not b.rigid)
    contact.nu_body = (elastic.name, elastic.nu)  # whose stresses the stress effects report
    return contact


def _build(spec: SceneSpec):
    shapes = {b.shape for b in spec.bodies}
    E_star = effective_modulus(spec)
    if spec.load.kind == "impact":
        return _impact(spec, E_star)
    if spec.load.kind == "pressure":
        if shapes != {"flat"}:
            raise SceneError(spec.source, "load.pressure", "a prescribed pressure acts between "
                             "two flat bodies (section 5.1); give both bodies shape = \"flat\"")
        from hertzmdr.numeric.scene.kinds.pressure import PressureLoad

        ld = spec.load
        return PressureLoad(E_star, spec.rtol, ld.distribution, ld.p0, ld.radius)
    if shapes <= QUADRATIC:
        return _quadratic(spec, E_star)
    if shapes <= AXISYMMETRIC:
        return _axisymmetric(spec, E_star)
    if shapes & {"polygon_punch", "height_map"}:
        return _grid(spec, E_star)
    names = ", ".join(sorted(shapes))
    raise SceneError(spec.source, "body", f"this combination of shapes ({names}) "
                     "is not supported yet")


def _quadratic(spec: SceneSpec, E_star: float):
    from hertzmdr.numeric import bodies

    (a1, b1, t1), (a2, b2, t2) = (_principal(b) for b in spec.bodies)
    if math.isinf(a1) and math.isinf(b1) and math.isinf(a2) and math.isinf(b2):
        raise SceneError(spec.source, "body", "two flat bodies have no contact point: give one "
                         "a curved shape, or use a flat_punch")
    try:
        R1, R2 = (float(v) for v in bodies.principal_radii(a1, b1, a2, b2, t2 - t1))
    except ValueError as exc:
        raise SceneError(spec.source, "body", f"{exc}; a concave radius must be larger than "
                         "the convex one it holds") from None
    if math.isinf(R2) or math.isinf(R1):
        return _line(spec, E_star, min(R1, R2))
    if abs(R1 - R2) <= CIRCULAR_RTOL * max(R1, R2):
        return HertzContact(E_star, spec.rtol, R=math.sqrt(R1 * R2), principal_radii=[R1, R2])
    from hertzmdr.numeric.scene.kinds.elliptic import EllipticContact

    return EllipticContact(E_star, spec.rtol, R1, R2, model=spec.elliptic)


def _impact(spec: SceneSpec, E_star: float):
    """Problems 3-4: a sphere strikes a fixed flat wall."""
    shapes = sorted(b.shape for b in spec.bodies)
    if shapes != ["flat", "sphere"]:
        raise SceneError(spec.source, "load.impact", "an impact scene is a sphere striking a "
                         f"flat wall (Problems 3 and 4); this one has {' and '.join(shapes)}")
    sphere = next(b for b in spec.bodies if b.shape == "sphere")
    R = sphere.params["radius"]
    if R <= 0:
        raise SceneError(spec.source, "body", "the striking sphere must be convex (radius > 0)")
    return HertzContact(E_star, spec.rtol, R=R, striker_radius=R)


def _axisymmetric(spec: SceneSpec, E_star: float):
    """An axisymmetric profile on a flat: its MDR closed form, or the numerical MDR."""
    from hertzmdr.numeric.scene.kinds import axisym

    shaped = [b for b in spec.bodies if b.shape != "flat"]
    if len(shaped) != 1:
        names = " and ".join(b.shape for b in shaped)
        raise SceneError(spec.source, "body", f"two profiled bodies ({names}) are not "
                         "supported: give one of them shape = \"flat\" (the MDR sums the two "
                         "profiles; sample their sum as a profile)")
    b = shaped[0]
    p = b.params
    if b.shape == "cone":
        return axisym.Cone(E_star, spec.rtol, p["angle"])
    if b.shape == "flat_punch":
        return axisym.FlatPunch(E_star, spec.rtol, p["radius"])
    if b.shape == "power_law":
        return axisym.PowerLaw(E_star, spec.rtol, p["coefficient"], p["exponent"])
    if b.shape == "flattened_parabola":
        return axisym.Worn(E_star, spec.rtol, p["radius"], p["flat_radius"])
    from hertzmdr.numeric import mdr

    try:
        prof = mdr.Profile.from_samples(p["r"], p["f"], k=3 if len(p["r"]) < 20 else 5)
    except ValueError as exc:
        raise SceneError(spec.source, f"body ({b.name})", f"profile samples: {exc}") from None
    return axisym.NumericalMDR(E_star, spec.rtol, prof,
                               f"sampled profile ({len(p['r'])} samples), numerical MDR")


def _line(spec: SceneSpec, E_star: float, R: float):
    """Parallel cylinders (or a cylinder on a flat): the line contact; needs a length."""
    from hertzmdr.numeric.scene.kinds.line import LineContact

    lengths = [b.params["length"] for b in spec.bodies if b.shape == "cylinder"
               and "length" in b.params]
    if not lengths:
        raise SceneError(spec.source, "body", "parallel cylinders make a line contact, whose "
                         "force depends on the contact length: give the cylinder(s) a length")
    L = min(lengths)
    if not L > 0:
        raise SceneError(spec.source, "body", f"the cylinder length must be > 0, got {L}")
    return LineContact(E_star, spec.rtol, R, L)


def _grid(spec: SceneSpec, E_star: float):
    """A polygonal punch or a height map on a flat: the half-space BEM."""
    from hertzmdr.numeric.scene.kinds import grid

    others = [b for b in spec.bodies if b.shape not in ("polygon_punch", "height_map")]
    if len(others) != 1 or others[0].shape != "flat":
        raise SceneError(spec.source, "body", "a polygon_punch or height_map presses on a "
                         "flat body: give the other body shape = \"flat\"")
    b = next(b for b in spec.bodies if b.shape in ("polygon_punch", "height_map"))
    try:
        if b.shape == "polygon_punch":
            return grid.polygon_punch(E_star, spec.rtol, b.params["vertices"],
                                      b.params.get("pixels", 128))
        return grid.height_map(E_star, spec.rtol, b.params["file"], b.params["spacing"])
    except ValueError as exc:
        raise SceneError(spec.source, f"body ({b.name})", str(exc)) from None
