"""A paraboloid worn flat at its tip: Problem 8 by the MDR (numeric/worn.py)."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class FlattenedParabola(Shape):
    name = "flattened_parabola"
    doc = ("worn parabola (Problem 8); its pressure is log-infinite at r = b, so "
           "`max_pressure` is refused")
    keys = (Key("radius", "length", doc="R", rule="positive"),
            Key("flat_radius", "length", doc="b", rule="positive",
                hint='an unworn tip, b = 0, is shape = "sphere"'))
    kinds = ("mdr",)

    def mdr(self, p):
        from hertzmdr.numeric import worn
        from hertzmdr.numeric.scene.kinds.axisym import ClosedForm

        R, b = p["radius"], p["flat_radius"]
        return ClosedForm(
            kind="flattened_parabola", label="flattened (worn) parabola, Problem 8",
            method="Problem 8", params={"radius": R, "flat_radius": b},
            contact_radius=lambda d: worn.contact_radius(d, R, b),
            force=lambda d, E: worn.force(d, R, b, E),
            depth_from_force=lambda F, E: worn.depth_from_force(F, R, b, E),
            pressure=lambda r, d, E: worn.pressure(r, d, R, b, E),
            surface_displacement=lambda r, d: worn.surface_displacement(r, d, R, b),
            g_profile=lambda x: worn.g_profile(x, R, b),
            no_max_pressure="the worn parabola's pressure is log-infinite at the edge of the "
            "flat r = b (where the slope of the profile jumps): it has no finite maximum; ask "
            "for 'pressure_profile' or the stresses",
            singular_at=lambda a: b, kink=b, off_axis=False, radius=R,
            not_power_law="the flat tip carries a punch's F = 2 E* b d until the parabola "
            "touches, then the force grows towards the Hertz d^(3/2): no one K and n",
            methods={"pressure_profile": "(5.59) in incomplete elliptic integrals (Problem 8)"})
