"""Symbols shared by the derivations, with the assumptions physics gives them and their SI units.

The generator takes each argument's unit and meaning from :data:`DESCRIPTIONS`, so every
symbol that is an argument of a relation must be listed there.
"""

from __future__ import annotations

import sympy as sp

# name: (unit, meaning); the name is also the argument name in the generated code.
DESCRIPTIONS: dict[str, tuple[str, str]] = {
    "E": ("Pa", "Young's modulus"),
    "E_star": ("Pa", "effective modulus E* (5.8), (5.26)"),
    "E1": ("Pa", "Young's modulus of body 1"),
    "E2": ("Pa", "Young's modulus of body 2"),
    "nu": ("1", "Poisson's ratio"),
    "nu1": ("1", "Poisson's ratio of body 1"),
    "nu2": ("1", "Poisson's ratio of body 2"),
    "F": ("N", "normal force"),
    "F_L": ("N/m", "normal force per unit length of a line contact"),
    "L": ("m", "length of a line contact"),
    "R": ("m", "radius of curvature (effective radius (5.27) for two bodies)"),
    "R1": ("m", "radius of curvature of body 1, or first principal radius"),
    "R2": ("m", "radius of curvature of body 2, or second principal radius"),
    "d": ("m", "indentation depth"),
    "a": ("m", "contact radius"),
    "A": ("m^2", "contact area"),
    "r": ("m", "radial coordinate on the surface"),
    "x": ("m", "coordinate"),
    "y": ("m", "coordinate"),
    "z": ("m", "depth below the surface"),
    "n_p": ("1", "exponent of a prescribed pressure p0*(1 - r^2/a^2)^n_p on a disc (section 5.1)"),
    "p0": ("Pa", "pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0"),
    "theta": ("rad", "angle between the cone's surface and the plane"),
    "m": ("kg", "mass"),
    "rho": ("kg/m^3", "density"),
    "v0": ("m/s", "impact velocity"),
    "alpha": ("rad", "angle between the axes of two crossed cylinders"),
    # family bodies (two elastic bodies, quadratic gaps, crossed cylinders), line, cone, impact
    "R1a": ("m", "first principal radius of curvature of body 1 (negative: concave; inf: flat)"),
    "R1b": ("m", "second principal radius of curvature of body 1 (negative: concave; inf: flat)"),
    "R2a": ("m", "first principal radius of curvature of body 2 (negative: concave; inf: flat)"),
    "R2b": ("m", "second principal radius of curvature of body 2 (negative: concave; inf: flat)"),
    "omega": ("rad", "angle between the first principal directions of the two bodies"),
    # ellipse (exact elliptical Hertz contact)
    "t_ba": ("1", "axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2)"),
    # family mdr, powerlaw, worn (Method of Dimensionality Reduction, Problems 7-8)
    "n": ("1", "exponent of the power-law profile f = c_n r^n, n > 0"),
    "c_n": ("m^(1-n)", "coefficient of the power-law profile f = c_n r^n"),
    "kappa_n": ("1", "MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d))"),
    "r_tilde": ("1", "normalized radius r/a"),
    "w_quad": ("1", "integration variable in (0, 1) of (5.59): x^2 = r^2 + (a^2 - r^2)(1 - w)^2"),
    "w_out": ("rad", "integration variable in (0, asin(a/r)) of (5.60) outside the contact: "
              "x = r sin(asin(a/r) - w)"),
    "b": ("m", "radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius "
          "of a kink of the profile (derive/kink.py)"),
    "slope_jump": ("1", "jump f'(b+) - f'(b-) of the profile's slope at a kink r = b"),
    "g_integral": ("m^2", "integral of the MDR profile g(x) over [0, a] (5.57)"),
    "lam": ("1", "atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), "
            "d = R lam tanh(lam)"),
    # adhesion family (derive/adhesion.py)
    "dgamma": ("J/m^2", "work of adhesion Delta gamma (energy per unit area to separate)"),
    "g_a": ("m", "MDR profile g(a) at the contact radius (5.55)"),
    "g_x": ("m", "MDR profile g(x) at the spring's coordinate x (5.52)"),
    "s_r": ("m", "sqrt(x^2 - r^2), the integration variable of (5.59) beyond x = r"),
    "r_c": ("1", "ratio r/c of the radial coordinate to the stick radius"),
    "q_x": ("N/m", "tangential line load of the MDR springs, force per unit length"),
    "w_x": ("m", "elastic shear displacement of an MDR tangential spring"),
    "q_z": ("N/m", "normal line load of the MDR springs, force per unit length (5.58)"),
    "g_slope": ("1", "slope g'(a) of the MDR profile at the contact radius"),
    "F_load": ("N", "normal force, negative when adhesion pulls (adhesive contact)"),
    "z0": ("m", "range of the adhesive forces (equilibrium distance) of the Tabor parameter"),
    # fit family (derive/fit.py): a measured force curve F(z_p)
    "z_p": ("m", "position of the tip's base (piezo), increasing into the sample"),
    "z_0": ("m", "contact point: the position z_p where the tip first touches the sample"),
    "F_0": ("N", "force baseline: the force at z_p = 0 before contact"),
    "s_0": ("N/m", "slope of the force baseline before contact (drift, drag)"),
    "rho_g": ("(J/m^2)^(1/2)", "square root of the work of adhesion, sqrt(Delta gamma) (the "
              "JKR fit model's relations are written in it: no sqrt of a sum)"),
    # stress family (derive/stress.py)
    "xi": ("1", "oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2"),
    "eta": ("1", "cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) "
            "sin(beta), z = a xi cos(beta)"),
    "chi": ("1", "sin(beta) of the oblate spheroidal angle beta"),
    # ellipse_stress family (derive/ellipse_stress.py): the field of an elliptical Hertz contact
    "b_e": ("m", "semi-axis b <= a of an elliptical contact, along y (a along x)"),
    "lam_e": ("m^2", "ellipsoidal coordinate lambda >= 0 of the field point: the largest root "
              "of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1"),
    "e_c": ("1", "z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish)"),
    "q_e": ("m^2", "lam - w1 >= 0, w1 the largest root of the surface quadratic P2"),
    "w1_e": ("m^2", "largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - "
             "y^2 (a^2 + w), the confocal ellipse through (x, y)"),
    "w1_a": ("m^2", "a^2 + w1 >= 0"),
    "w1_b": ("m^2", "b^2 + w1 >= 0"),
    "d_e": ("m^2", "w1 - w2 >= 0, the difference of the roots of P2"),
    "v_q": ("m", "integration variable v >= (lam - w1)^(1/2) of the field integrals, "
            "w = w1 + v^2"),
    "I_x": ("m^-3", "integral over w > lam of dw/((a^2 + w) Delta(w)), "
            "Delta = ((a^2 + w)(b^2 + w) w)^(1/2)"),
    "I_y": ("m^-3", "integral over w > lam of dw/((b^2 + w) Delta(w))"),
    "J_xx": ("m^-2", "integral over v of the H_xx integrand (ellipse_stress_jxx_integrand)"),
    "J_yy": ("m^-2", "integral over v of the H_yy integrand (ellipse_stress_jyy_integrand)"),
    "J_xy": ("m^-2", "integral over v of the H_xy integrand (ellipse_stress_jxy_integrand)"),
    "sigma_xx": ("Pa", "normal stress component sigma_xx"),
    "sigma_yy": ("Pa", "normal stress component sigma_yy"),
    "sigma_zz": ("Pa", "normal stress component sigma_zz"),
    "tau_xy": ("Pa", "shear stress component tau_xy"),
    "tau_yz": ("Pa", "shear stress component tau_yz"),
    "tau_xz": ("Pa", "shear stress component tau_xz"),
    "c_mean": ("Pa", "mean in-plane normal stress (sigma_xx + sigma_zz)/2 (plane strain)"),
    "tau_1": ("Pa", "principal shear stress in the x-z plane, the radius of Mohr's circle"),

    # tangential family (derive/tangential.py, derive/cerruti.py)
    "G": ("Pa", "shear modulus"),
    "G1": ("Pa", "shear modulus of body 1"),
    "G2": ("Pa", "shear modulus of body 2"),
    "G_star": ("Pa", "tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2)"),
    "mu_f": ("1", "coefficient of (Coulomb) friction mu"),
    "Q": ("N", "tangential point force in +x at the origin of the surface"),
    "u_x": ("m", "rigid tangential displacement of the indenter relative to the half-space"),
    "u_amp": ("m", "amplitude of an oscillating tangential displacement"),
    "F_x": ("N", "tangential force"),
    "F_amp": ("N", "amplitude F_x* of an oscillating tangential force"),
    "F_half": ("N", "tangential force of the monotonic loading at half the displacement "
               "travelled since the turning point"),
    "c": ("m", "radius of the stick zone"),
    "c_a": ("1", "stick ratio c/a (stick radius over contact radius)"),
    "d_c": ("1", "stick deficit 1 - c/a (c the stick radius, a the contact radius)"),
    "s_x": ("1", "position (x - c)/(a - c) in the slip zone c < x < a, in (0, 1)"),
    "p_a": ("Pa", "contact pressure p(r; a) of a profile at contact radius a"),
    "p_c": ("Pa", "contact pressure p(r; c) of the same profile at contact radius c (the stick "
            "radius)"),
    # fit (issue 17): a regular pyramid as its equivalent cone
    "alpha_p": ("rad", "half-angle of a regular pyramid: between its axis and the mid-line of "
                "a face"),
    "n_sides": ("1", "number of faces of a regular pyramid (4: most AFM tips; 3: Berkovich)"),
    "beta_p": ("1", "a regular pyramid's force over its equal-area cone's at the same depth "
               "(by the BEM, docs/pyramid.md)"),
}


def symbol(name: str, **assumptions) -> sp.Symbol:
    """A symbol with the given assumptions; default positive (lengths, moduli, forces)."""
    if name not in DESCRIPTIONS:
        raise KeyError(f"symbol {name!r}: add its unit and meaning to DESCRIPTIONS")
    if not assumptions:
        assumptions = {"positive": True}
    return sp.Symbol(name, **assumptions)


def unit_interval(name: str = "t") -> sp.Symbol:
    """A positive symbol that the proofs sample in (0, 1): see ``Relation.domain``."""
    if not (name == "t" or name.startswith("t_")):
        raise ValueError(f"unit-interval symbols are named t or t_*, not {name!r}")
    return sp.Symbol(name, positive=True)


E = symbol("E")
E_star = symbol("E_star")
nu = symbol("nu", real=True)
F = symbol("F")
R = symbol("R")
d = symbol("d")
a = symbol("a")
r = symbol("r", nonnegative=True)
z = symbol("z", nonnegative=True)
p0 = symbol("p0")
