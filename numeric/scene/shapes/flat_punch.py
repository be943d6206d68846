"""A flat-ended cylindrical punch: (5.9)-(5.12), Problem 7(a), the power law as n -> inf."""

from __future__ import annotations

import math

import numpy as np

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class FlatPunch(Shape):
    name = "flat_punch"
    doc = "a flat-ended cylinder (Problem 7 a)"
    keys = (Key("radius", "length", doc="a", rule="positive"),)
    kinds = ("mdr",)

    def mdr(self, p):
        from hertzmdr.numeric import contact, force_law, powerlaw
        from hertzmdr.numeric.scene.kinds.axisym import ClosedForm, PunchContact

        a = p["radius"]
        return ClosedForm(
            kind="flat_punch", label="flat cylindrical punch (5.9)-(5.12), Problem 7(a)",
            method="(5.11), (5.12)", params={"radius": a}, contact=PunchContact,
            force_law=lambda E: force_law.flat_punch(a, E), force_law_method="Problem 7(a)",
            contact_radius=lambda d: np.full(np.shape(d), a),
            force=lambda d, E: contact.punch_force(d, a, E),
            depth_from_force=lambda F, E: contact.punch_depth_from_force(F, a, E),
            # the punch is the power law n = inf with c_n = a (numeric/powerlaw.py)
            pressure=lambda r, d, E: powerlaw.pressure(r, d, a, math.inf, E),
            surface_displacement=lambda r, d: powerlaw.surface_displacement(r, d, a, math.inf),
            g_profile=lambda x: np.where(np.abs(np.asarray(x, float)) < a, 0.0, np.inf),
            no_max_pressure="the punch pressure (5.9) is singular at the edge",
            singular_at=lambda a: a)
