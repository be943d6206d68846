"""A rigid regular pyramid (an AFM tip, a Berkovich or Vickers indenter), solved as its
**equal-area cone**: the cone f = r tan(theta_eq) with the pyramid's cross-section area at every
depth, theta_eq from ``fit_pyramid_cone_angle`` (derive/fit.py, through
:class:`hertzmdr.numeric.fit.Pyramid`), then every effect of the cone (5.38)-(5.40).

A pyramid is not axisymmetric and the MDR holds for axisymmetric profiles only: the cone's
force F = K E* d^2 at theta_eq is an approximation of the pyramid's (a few per cent; the
factor K is reported in the model, and every result carries the ``1/sides`` warning of
numeric/scene/assumptions.py saying so).
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
#: the most faces a pyramid may have (more is a cone: use shape = "cone")
MAX_SIDES = 64


class PyramidContact(ClosedFormContact):
    """The equal-area cone of a pyramid: the cone's contact, plus the ratio 1/sides that says
    the pyramid is solved as an axisymmetric approximation (assumptions.py)."""

    def ratios(self, nodes):
        return {**super().ratios(nodes), "1/sides": 1.0 / self.form.params["sides"]}


class Pyramid(Shape):
    name = "pyramid"
    doc = ("a regular pyramid of `sides` faces, solved as its equal-area cone (an "
           "approximation: the warning `1/sides` says so)")
    keys = (Key("sides", "integer", required=False,
                doc=f"the number of faces, 3 to {MAX_SIDES} (with `half_angle`)"),
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
        if not 3 <= p["sides"] <= MAX_SIDES:
            fail("sides", f"must be an integer in [3, {MAX_SIDES}], got {p['sides']!r}")
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
        theta = fit.Pyramid(alpha=alpha, sides=n).cone.theta  # equal area (derive/fit.py)
        K = float(force_law.cone(theta, 1.0).K)  # F = K E* d^2 (5.40) at theta_eq
        name = f"{p['preset']} " if "preset" in p else ""
        form = Cone().mdr({"angle": theta})
        return dataclasses.replace(
            form, contact=PyramidContact,
            label=(f"{name}{n}-sided pyramid (half-angle {math.degrees(alpha):.6g} deg) as its "
                   f"equal-area cone theta_eq = {math.degrees(theta):.6g} deg by the MDR "
                   f"(5.38)-(5.40): F = {K:.6g} E* d^2, an approximation (the pyramid is not "
                   "axisymmetric)"),
            method="(5.38)-(5.40) at the equal-area cone's theta_eq",
            params={"angle": theta, "sides": n, "half_angle": alpha, "force_factor": K})
