"""A power-law indenter f(r) = c r^n: Problem 7(d) by the MDR."""

from __future__ import annotations

from hertzmdr.numeric.scene.shapes.base import Key, Shape


class PowerLaw(Shape):
    name = "power_law"
    doc = "z = c·rⁿ"
    keys = (Key("coefficient", "number", doc="c (SI: m^(1-n))", rule="positive",
                unit="m^(1-n)"),
            Key("exponent", "number", doc="n > 0", rule="positive"))
    kinds = ("mdr",)

    def mdr(self, p):
        from hertzmdr.numeric import force_law, powerlaw
        from hertzmdr.numeric.scene.kinds.axisym import ClosedForm

        c, n = p["coefficient"], p["exponent"]
        return ClosedForm(
            kind="power_law", label=f"power-law profile f = c r^{n:g} (Problem 7 d)",
            method="Problem 7(d)",
            force_law=lambda E: force_law.power_law(c, n, E), force_law_method="Problem 7(d)",
            params={"coefficient": c, "exponent": n, "kappa_n": float(powerlaw.kappa(n))},
            contact_radius=lambda d: powerlaw.contact_radius(d, c, n),
            force=lambda d, E: powerlaw.force(d, c, n, E),
            depth_from_force=lambda F, E: powerlaw.depth_from_force(F, c, n, E),
            pressure=lambda r, d, E: powerlaw.pressure(r, d, c, n, E),
            surface_displacement=lambda r, d: powerlaw.surface_displacement(r, d, c, n),
            g_profile=lambda x: powerlaw.g_profile(x, c, n),
            no_max_pressure=(None if n > 1 else "the pressure of f = c r^n with n <= 1 is "
                             "singular at the centre"),
            singular_at=None if n > 1 else (lambda a: 0.0))
