"""A rigid cone, f(r) = r tan(theta): (5.38)-(5.40) by the MDR."""

from __future__ import annotations

import math

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class Cone(Shape):
    name = "cone"
    doc = "z = r·tan θ"
    keys = (Key("angle", "angle", doc="θ between the cone's surface and the plane, as in (5.38)"),)
    kinds = ("mdr",)

    def check(self, p, fail, base_dir):
        if not 0 < p["angle"] < math.pi / 2:
            fail("angle", "the angle between the cone's surface and the plane (5.38) must be in "
                 f"(0, 90 deg), got {math.degrees(p['angle']):.6g} deg")

    def mdr(self, p):
        from hertzmdr.numeric import cone, force_law, powerlaw
        from hertzmdr.numeric.scene.kinds.axisym import ClosedForm

        th = p["angle"]
        c = math.tan(th)  # f = r tan(theta) is the power law n = 1, c = tan(theta)
        return ClosedForm(
            kind="cone", label="rigid cone (5.38)-(5.40)", method="(5.38)-(5.40)",
            params={"angle": th},
            contact_radius=lambda d: cone.contact_radius(d, th),
            force=lambda d, E: cone.force(d, th, E),
            depth_from_force=lambda F, E: cone.depth_from_force(F, th, E),
            pressure=lambda r, d, E: cone.pressure(r, d, th, E),
            surface_displacement=lambda r, d: powerlaw.surface_displacement(r, d, c, 1.0),
            g_profile=lambda x: powerlaw.g_profile(x, c, 1.0),
            no_max_pressure="the cone's pressure is log-singular at the tip (5.39)",
            singular_at=lambda a: 0.0, slope=c,
            force_law=lambda E: force_law.cone(th, E), force_law_method="(5.40)")
