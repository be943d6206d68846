"""Two quadratic surfaces (flat, sphere, cylinder, ellipsoid): the gap is a quadratic form, and
its principal radii (Problem 2) pick the kind: equal -> circular Hertz (kinds/hertz.py);
different -> elliptical contact (kinds/elliptic.py, exact or the chapter's Gaussian radius
(5.28)-(5.30) with ``[model] elliptic = "gaussian"``); one zero curvature (parallel cylinders,
or a cylinder on a flat) -> line contact (kinds/line.py, (5.34)-(5.37)).
"""

from __future__ import annotations

import math

from hertzmdr.numeric.scene.kinds.base import Contact, Setup

#: relative difference of the principal radii below which a gap is treated as circular: the
#: elliptical solution tends continuously to the circular one, and at this difference the
#: two agree to about 1e-12 (documented in docs/scenes.md)
CIRCULAR_RTOL = 1e-12


def build(setup: Setup) -> Contact:
    from hertzmdr.numeric import bodies
    from hertzmdr.numeric.scene.shapes import SHAPES

    (a1, b1, t1), (a2, b2, t2) = (SHAPES[b.shape].principal(b.params)
                                  for b in setup.spec.bodies)
    if math.isinf(a1) and math.isinf(b1) and math.isinf(a2) and math.isinf(b2):
        setup.fail("body", "two flat bodies have no contact point: give one a curved shape, or "
                   "use a flat_punch")
    try:
        R1, R2 = (float(v) for v in bodies.principal_radii(a1, b1, a2, b2, t2 - t1))
    except ValueError as exc:
        setup.fail("body", f"{exc}; a concave radius must be larger than the convex one it "
                   "holds")
    m, i, r = setup.materials, setup.interface, setup.rtol
    if math.isinf(R2) or math.isinf(R1):
        return _line(setup, min(R1, R2))
    if abs(R1 - R2) <= CIRCULAR_RTOL * max(R1, R2):
        from hertzmdr.numeric.scene.kinds.hertz import HertzContact

        # equal radii (a sphere, crossed equal cylinders): R itself; else the Gaussian radius
        R = R1 if R1 == R2 else float(bodies.gaussian_radius(R1, R2))  # (5.30)
        out = HertzContact(m, i, r, R=R, principal_radii=[R1, R2])
        out.choice = (f"principal radii R1 = {R1:.6g} m, R2 = {R2:.6g} m equal (to a relative "
                      f"{CIRCULAR_RTOL:g}) -> circular Hertz with R = {R:.6g} m")
        if any(b.shape == "sphere" for b in setup.spec.bodies):
            out.choice += ("; a 'sphere' is Hertz's paraboloid (5.19), the exact spherical "
                           "cap (shape 'exact_sphere') was not requested")
        return out
    from hertzmdr.numeric.scene.kinds.elliptic import EllipticContact

    out = EllipticContact(m, i, r, R1, R2, model=setup.spec.elliptic)
    out.choice = (f"principal radii R1 = {R1:.6g} m, R2 = {R2:.6g} m differ (R1/R2 = "
                  f"{R1 / R2:.6g}) -> elliptical contact, "
                  + ("exact (elliptic integrals)" if setup.spec.elliptic == "exact"
                     else "the chapter's Gaussian radius ([model] elliptic = 'gaussian')"))
    return out


def _line(setup: Setup, R: float) -> Contact:
    """Parallel cylinders (or a cylinder on a flat): the line contact; needs a length."""
    from hertzmdr.numeric.scene.kinds.line import LineContact

    lengths = [b.params["length"] for b in setup.spec.bodies if b.shape == "cylinder"
               and "length" in b.params]
    if not lengths:
        setup.fail("body", "parallel cylinders make a line contact, whose force depends on the "
                   "contact length: give the cylinder(s) a length")
    L = min(lengths)
    if not L > 0:
        setup.fail("body", f"the cylinder length must be > 0, got {L}")
    out = LineContact(setup.materials, setup.interface, setup.rtol, R, L)
    out.choice = (f"one principal curvature is zero (parallel axes, or a cylinder on a flat) "
                  f"-> line contact with R = {R:.6g} m over the length L = {L:.6g} m (the "
                  "shorter cylinder's)")
    return out
