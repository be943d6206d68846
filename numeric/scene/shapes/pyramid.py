"""A rigid regular pyramid (an AFM tip, a Berkovich or Vickers indenter), solved as the **cone
of its force law**: the pyramid's force is beta_n times that of its equal-area cone (the cone
with the pyramid's cross-section area at every depth), beta_n measured by the BEM
(``fit.PYRAMID_BEM_FACTOR``, docs/pyramid.md: 1.0778 for three faces, 1.0268 for four); the cone
f = r tan(theta) with that force, theta from ``fit_pyramid_force_cone_angle`` (derive/fit.py,
through :class:`hertzmdr.numeric.fit.Pyramid`), then every effect of the cone (5.38)-(5.40).

The force law F = K E* d^2 is the pyramid's to beta_n's error (<= 2.2e-5; K is reported in the
model). A pyramid is not axisymmetric and the MDR holds for axisymmetric profiles only: the
cone's pressure, contact radius and stresses stand in for the pyramid's non-circular contact,
and every result carries the ``1/sides`` warning of numeric/scene/assumptions.py saying so.
"""

from __future__ import annotations

import dataclasses
import math

from hertzmdr.numeric.scene.kinds.axisym import ClosedFormContact
from hertzmdr.numeric.scene.shapes.base import Key, Shape
from hertzmdr.numeric.scene.shapes.cone import Cone

#: the standard indenters: (faces, half-angle between the axis and a face's centre-line [deg]):
#: ISO 14577-2's modified Berkovich (projected area 24.5 d^2), Vickers (136 deg between
#: opposite faces) and the cube corner (three faces of a cube: 35.26 deg)
PRESETS = {"berkovich": (3, 65.27), "vickers": (4, 68.0), "cube_corner": (3, 35.2644)}


class PyramidContact(ClosedFormContact):
    """The cone of a pyramid's force law: the cone's contact, plus the ratio 1/sides that says
    the pyramid's contact is solved as an axisymmetric approximation (assumptions.py)."""

    def ratios(self, nodes):
        return {**super().ratios(nodes), "1/sides": 1.0 / self.form.params["sides"]}


class Pyramid(Shape):
    name = "pyramid"
    doc = ("a regular pyramid of `sides` faces, solved as the cone of its force law (the BEM's "
           "factor over the equal-area cone; its contact is an approximation: the warning "
           "`1/sides` says so)")
    keys = (Key("sides", "integer", required=False,
                doc="the number of faces, 3, 4, 6 or 8 (with `half_angle`)"),
            Key("half_angle", "angle", required=False,
                doc="the angle between the axis and the centre-line of a face (with `sides`)"),
            Key("preset", "name", required=False,
                doc="instead of both: " + ", ".join(
                    f"`\"{k}\"` ({n} faces, {a:g} deg)" for k, (n, a) in PRESETS.items())))
    kinds = ("mdr",)

    def check(self, p, fail, base_dir):
        if "preset" in p:
            if p["preset"] not in PRESETS:
                from hertzmdr.numeric.scene.schema import suggest

                fail("preset", f"unknown preset {p['preset']!r}{suggest(p['preset'], PRESETS)}"
                     f" (one of: {', '.join(PRESETS)})")
            both = [k for k in ("sides", "half_angle") if k in p]
            if both:
                fail(both[0], f"give preset or sides and half_angle, not both (the preset "
                     f"{p['preset']!r} sets them)")
            return
        for k in ("sides", "half_angle"):
            if k not in p:
                fail(k, "missing: a pyramid needs sides and half_angle, or a preset (one of: "
                     f"{', '.join(PRESETS)})")
        from hertzmdr.numeric.fit import PYRAMID_BEM_FACTOR

        if p["sides"] not in PYRAMID_BEM_FACTOR:
            fail("sides", f"must be one of {', '.join(map(str, PYRAMID_BEM_FACTOR))} (the "
                 f"pyramids whose force the BEM has measured, docs/pyramid.md), got "
                 f"{p['sides']!r}")
        if not 0 < p["half_angle"] < math.pi / 2:
            fail("half_angle", "the angle between the axis and a face's centre-line must be in "
                 f"(0, 90 deg), got {math.degrees(p['half_angle']):.6g} deg")

    @staticmethod
    def geometry(p) -> tuple[int, float]:
        """(faces, half-angle [rad]) of the keys or the preset."""
        if "preset" in p:
            n, deg = PRESETS[p["preset"]]
            return n, math.radians(deg)
        return int(p["sides"]), float(p["half_angle"])

    def mdr(self, p):
        from hertzmdr.numeric import fit, force_law

        n, alpha = self.geometry(p)
        tip = fit.Pyramid(alpha=alpha, sides=n)
        theta = tip.cone.theta  # equal force (derive/fit.py, the BEM's beta_n)
        K = float(force_law.cone(theta, 1.0).K)  # F = K E* d^2 (5.40) at theta
        name = f"{p['preset']} " if "preset" in p else ""
        form = Cone().mdr({"angle": theta})
        return dataclasses.replace(
            form, contact=PyramidContact,
            label=(f"{name}{n}-sided pyramid (half-angle {math.degrees(alpha):.6g} deg) as the "
                   f"cone of its force law, theta = {math.degrees(theta):.6g} deg, by the MDR "
                   f"(5.38)-(5.40): F = {K:.6g} E* d^2 (the BEM's {tip.beta:.7g} times the "
                   "equal-area cone's); its contact is the cone's, an approximation (the "
                   "pyramid is not axisymmetric)"),
            method="(5.38)-(5.40) at the cone of the pyramid's force law (the BEM's beta_n)",
            params={"angle": theta, "sides": n, "half_angle": alpha, "force_factor": K,
                    "bem_factor": tip.beta})
