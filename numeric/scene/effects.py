"""The registry of effects a scene can ask for.

Each row names an effect, its unit, what it is, and the nodes it needs; the contact kind of the
scene computes it (a method ``effect_<name>`` of its :class:`~.kinds.Contact`). Nodes are
evaluated once per run and only when an asked-for effect needs them: ``state`` (the contact at
the load), ``impact`` (the integrated equation of motion), ``stress`` (the stress solver).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Effect:
    name: str
    unit: str
    doc: str
    needs: tuple[str, ...] = ("state",)
    field: bool = False  # an object of arrays, drawn as a PNG by --out


EFFECTS: dict[str, Effect] = {e.name: e for e in [
    Effect("depth", "m", "indentation depth d (the approach of the two bodies)"),
    Effect("force", "N", "normal force F"),
    Effect("contact_radius", "m", "contact radius a of a circular contact (5.21), (5.55)"),
    Effect("semi_axes", "m", "semi-axes [a, b] of an elliptical contact (5.28), exact"),
    Effect("half_width", "m", "half-width a of the contact strip of a line contact (5.35)"),
    Effect("contact_area", "m^2", "contact area (BEM contacts: polygon punches, height maps)"),
    Effect("max_pressure", "Pa", "maximum contact pressure (5.22), (5.37)"),
    Effect("mean_pressure", "Pa", "mean pressure: force over contact area"),
    Effect("stiffness", "N/m", "differential normal stiffness dF/dd (Problem 5)"),
    Effect("elastic_energy", "J", "elastic energy stored in the contact (5.25)"),
    Effect("effective_modulus", "Pa", "effective modulus E* (5.26)", needs=()),
    Effect("effective_radius", "m", "effective radius R (5.27), or the Gaussian radius (5.30)",
           needs=()),
    Effect("principal_radii", "m", "principal radii [R1, R2] of the gap (Problem 2)", needs=()),
    Effect("force_law", "{K: N/m^n, n: 1, stiffness_K: N/m^n, stiffness_n: 1, "
           "K_per_length: N/m^(n+1), stiffness_K_per_length: N/m^(n+1)}",
           "the force law F = K d^n and stiffness law dF/dd = stiffness_K d^(n-1) where the "
           "force-depth relation is a power law (Hertz, elliptical, cone, flat punch, power "
           "law; a line contact also per unit length): the coefficients a DEM code takes",
           needs=()),
    Effect("pressure_profile", "{r: m, p: Pa}", "pressure p(r) across the contact",
           field=True),
    Effect("surface_displacement", "{r: m, u: m}",
           "surface displacement u_z(r), inside and outside the contact (Fig. 5.2)", field=True),
    Effect("force_depth_curve", "{depth: m, force: N}", "force against depth from 0 to the load",
           field=True),
    Effect("axis_stresses", "{z: m, sigma_zz: Pa, sigma_rr: Pa, tau_1: Pa}",
           "stresses on the axis under the contact (5.48), (5.49), and tau_1 (Fig. 5.8); "
           "a line contact: sigma_rr is sigma_xx, plus sigma_yy (plane strain)",
           needs=("stress",), field=True),
    Effect("max_shear", "{value: Pa, depth: m}", "the largest shear stress in the body and its "
           "depth (Fig. 5.8)", needs=("stress",)),
    Effect("von_mises_field", "{x: m, z: m, sigma_v: Pa}", "the von Mises stress (5.50) in the "
           "x-z plane (Fig. 5.9)", needs=("stress",), field=True),
    Effect("max_von_mises", "{value: Pa, x: m, z: m}", "the largest von Mises stress (5.50) in "
           "the body and where it is", needs=("stress",)),
    Effect("max_orthogonal_shear", "{value: Pa, x: m, z: m, y: m, value_xz: Pa, x_xz: m, "
           "z_xz: m}", "the largest orthogonal shear |tau_xz| (line contact) or |tau_rz| "
           "(circular contact) in the body and where it is (the shear of rolling-contact "
           "fatigue); an elliptical contact gives |tau_yz| in the plane x = 0 (value, y, z) "
           "and |tau_xz| in the plane y = 0 (value_xz, x_xz, z_xz)", needs=("stress",)),
    Effect("mdr_profile", "{x: m, g: m}", "the MDR's one-dimensional profile g(x) (5.52), "
           "Figs. 5.11 and 5.19", field=True),
    Effect("edge_displacement", "m", "surface displacement at the edge of a loaded disc "
           "(Problem 6; needs [load.pressure])"),
    Effect("contact_time", "s", "duration of an elastic impact (Problem 3); the equation of "
           "motion is integrated and compared with the closed form", needs=("impact",)),
    Effect("max_impact_depth", "m", "largest depth during an impact (Problem 3)",
           needs=("impact",)),
    Effect("max_impact_pressure", "Pa", "largest pressure during an impact (Problem 4)",
           needs=("impact",)),
    Effect("pull_off_force", "{force_control: N, depth_control: N}", "the force at which an "
           "adhesive contact lets go, under force and under depth control (needs "
           "[interface] work_of_adhesion)", needs=()),
    Effect("pull_off_depth", "{force_control: m, depth_control: m}", "the depth at pull-off, "
           "under force and under depth control (negative: pulled above the free surface)",
           needs=()),
    Effect("zero_load_contact_radius", "m", "contact radius of an adhesive contact at zero "
           "force", needs=()),
    Effect("adhesive_force_depth_curve", "{depth: m, force: N, contact_radius: m, "
           "loading: 1, jump_depth: m, jump_force: N, jump_contact_radius: m, hysteresis: J}",
           "approach-push-retract history of an adhesive contact with its jumps into and out "
           "of contact, and the work lost per cycle", field=True),

    Effect("sliding_force", "N", "tangential force of full sliding, mu F (needs [interface] "
           "friction)", needs=("tangential",)),
    Effect("tangential_stiffness", "N/m", "tangential contact stiffness 2 G* a before any slip",
           needs=("tangential",)),
    Effect("tangential_force", "N", "tangential force F_x at the tangential load (the "
           "amplitude of an oscillating one)", needs=("tangential",)),
    Effect("tangential_displacement", "m", "tangential displacement u_x at the tangential "
           "load (Cattaneo-Mindlin for a sphere)", needs=("tangential",)),
    Effect("stick_radius", "m", "radius c of the stick zone at the tangential load",
           needs=("tangential",)),
    Effect("traction_profile", "{r: m, q: Pa}", "tangential traction q(r) at the tangential "
           "load: mu (p(r; a) - p(r; c)) in the stick zone, mu p in the slip zone",
           needs=("tangential",), field=True),
    Effect("hysteresis_loop", "{u: m, F: N}", "tangential force against displacement: first "
           "loading, then the Masing branches of the cycles (needs [load] oscillating)",
           needs=("tangential",), field=True),
    Effect("dissipated_energy", "J", "energy dissipated per cycle of the oscillating "
           "tangential force (Mindlin-Deresiewicz for a sphere)", needs=("tangential",)),
]}


def listing() -> str:
    """The text `hertzmdr effects` prints."""
    width = max(map(len, EFFECTS))
    return "\n".join(f"{e.name:{width}}  [{e.unit}]  {e.doc}" for e in EFFECTS.values())
