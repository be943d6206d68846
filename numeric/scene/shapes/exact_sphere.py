"""A sphere of radius R, exactly: the spherical cap f(r) = R - sqrt(R^2 - r^2), not the
paraboloid of (5.19). Its MDR closed form (Sneddon's sphere, numeric/sphere.py) stays exact for
deep indentations, where a/R is no longer small and the Hertz theory departs from it."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class ExactSphere(Shape):
    name = "exact_sphere"
    doc = "z = R − √(R² − r²), the spherical cap itself (Sneddon); exact for deep indentations"
    keys = (Key("radius", "length", doc="R", rule="positive"),)
    kinds = ("mdr",)

    def mdr(self, p):
        from hertzmdr.numeric import sphere
        from hertzmdr.numeric.scene.kinds.axisym import ClosedForm

        R = p["radius"]
        return ClosedForm(
            kind="exact_sphere", label="exact sphere (spherical cap, Sneddon) by the MDR",
            method="MDR of the spherical cap (Sneddon)", params={"radius": R}, off_axis=False,
            radius=R,
            contact_radius=lambda d: sphere.contact_radius(d, R),
            force=lambda d, E: sphere.force(d, R, E),
            depth_from_force=lambda F, E: sphere.depth_from_force(F, R, E),
            pressure=lambda r, d, E: sphere.pressure(r, d, R, E),
            surface_displacement=lambda r, d: sphere.surface_displacement(r, d, R),
            g_profile=lambda x: sphere.g_profile(x, R),
            not_power_law="Sneddon's spherical cap has F = K d^(3/2) (Hertz) only as a/R -> "
            "0; a 'sphere' body gives that law")
