"""Two elastic bodies with curved surfaces, (5.26)-(5.33) and Problem 2.

Starting points:

- (5.26): the point-load displacement (5.3) of each body, taken at its surface z = 0, gives the
  kernel (1 - nu_i^2)/(pi E_i r) of (5.6)/(5.7). Both bodies carry the same contact pressure,
  so their approach u1 + u2 is the kernel integral times the sum of the two coefficients: the
  contact is that of a rigid body on one half-space with 1/E* = sum of (1 - nu_i^2)/E_i.
- (5.27): the gap between two surfaces z_i = r^2/(2 R_i) facing each other is their sum,
  h = r^2/(2R) with 1/R = 1/R1 + 1/R2; a concave surface has R_i < 0.
- Any quadratic gap: body i has the principal curvatures 1/R_ia, 1/R_ib, the first principal
  directions of the two bodies enclose the angle omega. The gap is h = x^T H x / 2 with
  H = K1 + Q(omega) K2 Q(omega)^T, and its principal curvatures are the eigenvalues of H
  (as in Problem 2). Crossed cylinders are the case 1/R_1b = 1/R_2b = 0, omega = alpha.
- The elliptic contact by the Gaussian radius (5.28)-(5.31) is the chapter's APPROXIMATION:
  semi-axes sqrt(R_i d), the ellipsoidal pressure (5.31) with the p0 of (5.22) at R = R~, its
  force and the depth under a given force. This module is its only derivation:
  :mod:`hertzmdr.derive.ellipse` derives the exact contact, and
  ``hertzmdr.numeric.ellipse.solve(..., model="gaussian")`` calls the ``bodies_gaussian_*``
  functions.

Problem 2 of the chapter takes the eigenvalues of the coefficient matrix of h (h = x^T M x),
not of its Hessian H = 2M: its principal radii, Gaussian radius and force are wrong (errata).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import hertz
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E, E_star, F, R, d, nu, symbol

TEST = "tests/test_bodies.py"

E1, E2 = symbol("E1"), symbol("E2")
nu1, nu2 = symbol("nu1", real=True), symbol("nu2", real=True)
# radii may be negative (concave); inf (flat) is handled by printing curvatures 1/R
R1, R2 = symbol("R1", real=True, nonzero=True), symbol("R2", real=True, nonzero=True)
R1a, R1b, R2a, R2b = (symbol(n, real=True, nonzero=True) for n in ("R1a", "R1b", "R2a", "R2b"))
omega = symbol("omega", real=True)
RC1, RC2 = symbol("R1"), symbol("R2")  # convex cylinders, and principal radii of a convex gap
alpha = symbol("alpha", positive=True)
x, y = symbol("x", real=True), symbol("y", real=True)

# curvatures: the derivations work with them, radii enter as 1/R only at the end
k1a, k1b, k2a, k2b = sp.symbols("k1a k1b k2a k2b", real=True)
RADII = {k1a: 1 / R1a, k1b: 1 / R1b, k2a: 1 / R2a, k2b: 1 / R2b}


@cache
def effective_modulus() -> dict[str, sp.Expr]:
    """1/E* of two bodies from the sum of their surface displacements (5.26)."""
    xs, ys, zs, Fz = sp.symbols("x_s y_s z_s F_z", positive=True)
    coeffs = []
    for Ei, nui in ((E1, nu1), (E2, nu2)):
        rr = sp.sqrt(xs**2 + ys**2 + zs**2)
        uz = (1 + nui) / (2 * sp.pi * Ei) * (2 * (1 - nui) / rr + zs**2 / rr**3) * Fz  # (5.3)
        surface = sp.limit(uz, zs, 0)  # (5.6)
        rs = sp.sqrt(xs**2 + ys**2)
        coeffs.append(sp.simplify(surface * rs / Fz))  # u_z = coeff * F / r
    # same pressure on both surfaces: u1 + u2 = (c1 + c2) iint p/r dA = iint p/r dA / (pi E*)
    (Es,) = sp.solve(sp.Eq(coeffs[0] + coeffs[1], 1 / (sp.pi * E_star)), E_star)
    single = sp.limit(Es, E2, sp.oo)  # body 2 rigid
    return {"E_star": Es, "E_star_rigid": single.subs({E1: E, nu1: nu}),
            "kernel_1": coeffs[0]}


@cache
def effective_radius() -> sp.Expr:
    """R of (5.27): the gap of two facing surfaces r^2/(2 R_i) written as r^2/(2R)."""
    r = sp.Symbol("r", positive=True)
    Rs = sp.Symbol("R_s", real=True, nonzero=True)
    gap = r**2 / (2 * R1) + r**2 / (2 * R2)  # z1 + z2: both measured away from the contact
    (sol,) = sp.solve(sp.Eq(gap, r**2 / (2 * Rs)), Rs)
    return sol


@cache
def principal_curvatures() -> dict[str, sp.Expr]:
    """Principal curvatures of the gap between two bodies, as eigenvalues of its Hessian H.

    The identities are proved as polynomials in c = cos(omega), s = sin(omega), reduced
    modulo c^2 + s^2 - 1 (fast and exact, unlike a general trigsimp).
    """
    c, s = sp.symbols("c s", real=True)
    Q = sp.Matrix([[c, -s], [s, c]])
    H = sp.diag(k1a, k1b) + Q * sp.diag(k2a, k2b) * Q.T  # h = X^T H X / 2

    def is_zero(expr):
        return sp.rem(sp.expand(expr), c**2 + s**2 - 1, s) == 0

    T, D, kap = sp.symbols("T D kappa")
    char = sp.expand((H - kap * sp.eye(2)).det())
    assert is_zero(char - (kap**2 - H.trace() * kap + H.det()))
    hi, lo = sorted(sp.solve(kap**2 - T * kap + D, kap),
                    key=lambda e: -e.coeff(sp.sqrt(T**2 - 4 * D)))  # the + root first
    trace = k1a + k1b + k2a + k2b
    assert is_zero(H.trace() - trace)
    # the discriminant tr^2 - 4 det as a sum of two squares (no cancellation in floating
    # point), and det as a sum of products that are all positive for convex bodies
    cos2, sin2 = c**2 - s**2, 2 * s * c
    diff = (k1a - k1b) + (k2a - k2b) * cos2  # H11 - H22
    off = (k2a - k2b) * sin2  # 2 H12, up to its sign
    det = (k1a * k1b + k2a * k2b + (k1a * k2a + k1b * k2b) * s**2
           + (k1a * k2b + k1b * k2a) * c**2)
    assert is_zero(H.det() - det)
    assert is_zero(H.trace() ** 2 - 4 * H.det() - diff**2 - off**2)
    trig = {c: sp.cos(omega), s: sp.sin(omega)}
    double = {cos2: sp.cos(2 * omega), sin2: sp.sin(2 * omega)}
    root = sp.sqrt(diff.subs(cos2, double[cos2]) ** 2 + off.subs(sin2, double[sin2]) ** 2)
    at = {T: trace, sp.sqrt(T**2 - 4 * D): root}
    k_hi, k_lo = hi.subs(at), lo.subs(at)
    assert sp.expand(k_hi + k_lo - trace) == 0
    return {"k1": k_hi, "k2": k_lo, "k2_stable": 2 * det.subs(trig) / (trace + root),
            "det": det.subs(trig), "trace": trace}


def _crossed(expr: sp.Expr) -> sp.Expr:
    """Two cylinders: body i curved only across its axis; the axes enclose alpha."""
    return expr.subs({k1b: 0, k2b: 0, omega: alpha}).subs({k1a: 1 / RC1, k2a: 1 / RC2})


@cache
def crossed_cylinders() -> dict[str, sp.Expr]:
    pc = principal_curvatures()
    k1, k2, k2s, det = (_crossed(pc[k]) for k in ("k1", "k2", "k2_stable", "det"))
    gauss = 1 / sp.sqrt(det)  # R~ = sqrt(R_1 R_2) = 1/sqrt(kappa_1 kappa_2)
    gauss = sp.simplify(gauss)
    # (5.32)/(5.33): at alpha = pi/2 the gap is x^2/(2R1) + y^2/(2R2), R~ = sqrt(R1 R2)
    assert sp.simplify(gauss.subs(alpha, sp.pi / 2) - sp.sqrt(RC1 * RC2)) == 0
    return {"k1": k1, "k2": k2, "k2_stable": k2s, "gauss": gauss}


@cache
def problem2() -> dict[str, sp.Expr]:
    """Two equal cylinders of one material crossed at pi/4 (Problem 2)."""
    cc = crossed_cylinders()
    at = {RC1: R, RC2: R, alpha: sp.pi / 4}
    R_1 = sp.radsimp(sp.simplify(1 / cc["k1"].subs(at)))
    R_2 = sp.radsimp(sp.simplify(1 / cc["k2"].subs(at)))
    gauss = sp.simplify(cc["gauss"].subs(at))
    Es = effective_modulus()["E_star"].subs({E1: E, E2: E, nu1: nu, nu2: nu})
    force = hertz.solution()["F"].subs({E_star: Es}).subs(R, gauss)  # (5.23) with R~
    # the same gap in the chapter's coordinates: z1 = x^2/(2R), z2 = (x - y)^2/(4R)
    h = x**2 / (2 * R) + (x - y) ** 2 / (4 * R)
    hess = sp.hessian(h, (x, y))
    assert sp.simplify(hess.det() - 1 / gauss**2) == 0
    return {"R_1": R_1, "R_2": R_2, "gauss": gauss, "F": sp.simplify(force)}


@cache
def gaussian_approximation() -> dict[str, sp.Expr]:
    """The chapter's elliptic contact (5.28)-(5.31) with the Gaussian radius (5.30)."""
    Rg = sp.Symbol("R_g", positive=True)
    # R~ from equal Gaussian curvature: the gap x^2/(2R1) + y^2/(2R2) has kappa1 kappa2 =
    # 1/(R1 R2); a sphere of radius R~ has 1/R~^2
    hess = sp.hessian(x**2 / (2 * R1) + y**2 / (2 * R2), (x, y))
    (gauss,) = [s for s in sp.solve(sp.Eq(hess.det(), 1 / Rg**2), Rg) if s.is_positive is not False]
    Rp1, Rp2 = RC1, RC2
    gauss = gauss.subs({R1: Rp1, R2: Rp2})
    a_ = hertz.solution()["a"].subs(R, Rp1)  # (5.28): rough estimate, sqrt(R_i d)
    b_ = hertz.solution()["a"].subs(R, Rp2)
    p0_ = hertz.solution()["p0"].subs(R, gauss)  # (5.22) with R~
    rho, phi = sp.symbols("rho phi", positive=True)
    # (5.31) over the ellipse, x = a rho cos(phi), y = b rho sin(phi), Jacobian a b rho
    integrand = p0_ * sp.sqrt(1 - rho**2) * a_ * b_ * rho
    force = sp.integrate(sp.integrate(integrand, (rho, 0, 1)), (phi, 0, 2 * sp.pi))
    force = sp.simplify(force)
    (d_F,) = sp.solve(sp.Eq(F, force), d)  # force-controlled: the force solved for d
    xs, ys = symbol("x", real=True), symbol("y", real=True)
    pressure = p0_ * sp.sqrt(sp.Max(0, 1 - xs**2 / a_**2 - ys**2 / b_**2))
    return {"gauss": gauss, "a": a_, "b": b_, "area": sp.simplify(sp.pi * a_ * b_),
            "p0": sp.simplify(p0_), "F": force, "d_F": d_F, "p": pressure,
            "R1": Rp1, "R2": Rp2}


def relations() -> list[Relation]:
    em = effective_modulus()
    Es = em["E_star"]
    Es_stable = 1 / sum(((1 - n) * (1 + n) / e for e, n in ((E1, nu1), (E2, nu2))),
                        sp.Integer(0))
    Es_rigid = em["E_star_rigid"]
    R_eff = effective_radius()
    pc = principal_curvatures()
    k1 = pc["k1"].subs(RADII)
    k2 = pc["k2"].subs(RADII)
    k2s = pc["k2_stable"].subs(RADII)
    cc = crossed_cylinders()
    p2 = problem2()
    ga = gaussian_approximation()
    Rp1, Rp2 = ga["R1"], ga["R2"]
    sqrt2 = sp.sqrt(2)
    curv_why = ("written with the curvatures 1/R so that R = inf (flat) works; the "
                "discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) "
                "with det a sum of products, positive for convex bodies: no cancellation")
    return [
        Relation("bodies_effective_modulus", "(5.26)", Es, (E1, nu1, E2, nu2),
                 "effective modulus E* [Pa] of two elastic bodies",
                 "the sum of the two surface displacements (5.6), (5.7) under one pressure",
                 f"{TEST}::test_effective_modulus_by_two_displacements",
                 printed=1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2),
                 stable=Es_stable,
                 stable_why="1/E* as the sum of the compliances, which accepts E2 = inf "
                 "(rigid), with 1 - nu^2 = (1 - nu)(1 + nu) exact in floating point for "
                 "nu near -1"),
        Relation("bodies_effective_modulus_rigid", "(5.8), (5.26) with E2 -> inf", Es_rigid,
                 (E, nu), "effective modulus E* [Pa] of an elastic body against a rigid one",
                 "the limit E2 -> inf of (5.26)",
                 f"{TEST}::test_effective_modulus_by_two_displacements",
                 printed=E / (1 - nu**2), stable=E / ((1 - nu) * (1 + nu)),
                 stable_why="1 - nu^2 = (1 - nu)(1 + nu) is exact in floating point for nu "
                 "near -1, where 1 - nu^2 cancels"),
        Relation("bodies_effective_radius", "(5.27)", R_eff, (R1, R2),
                 "effective radius R [m] of two spheres (negative radius: concave)",
                 "the sum of the two gaps r^2/(2 R_i)", f"{TEST}::test_effective_radius_by_gap",
                 printed=1 / (1 / R1 + 1 / R2), stable=1 / (1 / R1 + 1 / R2),
                 stable_why="the sum of the curvatures accepts R = inf (flat)"),
        Relation("bodies_principal_curvature_1", "(5.32), Problem 2, general", k1,
                 (R1a, R1b, R2a, R2b, omega),
                 "larger principal curvature kappa_1 [1/m] of the gap between two bodies",
                 "the larger eigenvalue of the Hessian of the gap",
                 f"{TEST}::test_principal_curvatures_by_hessian"),
        Relation("bodies_principal_curvature_2", "(5.32), Problem 2, general", k2,
                 (R1a, R1b, R2a, R2b, omega),
                 "smaller principal curvature kappa_2 [1/m] of the gap between two bodies",
                 "the smaller eigenvalue of the Hessian of the gap",
                 f"{TEST}::test_principal_curvatures_by_hessian",
                 stable=k2s, stable_why=curv_why),
        Relation("bodies_crossed_cylinders_curvature_1", "(5.32), (5.33), any angle",
                 cc["k1"], (RC1, RC2, alpha),
                 "larger principal curvature [1/m] of the gap of two cylinders crossed at alpha",
                 "the larger eigenvalue of the Hessian of the gap",
                 f"{TEST}::test_principal_curvatures_by_hessian"),
        Relation("bodies_crossed_cylinders_curvature_2", "(5.32), (5.33), any angle",
                 cc["k2"], (RC1, RC2, alpha),
                 "smaller principal curvature [1/m] of the gap of two cylinders crossed at "
                 "alpha", "the smaller eigenvalue of the Hessian of the gap",
                 f"{TEST}::test_principal_curvatures_by_hessian",
                 stable=cc["k2_stable"], stable_why=curv_why),
        Relation("bodies_crossed_cylinders_gaussian_radius", "(5.33), any angle", cc["gauss"],
                 (RC1, RC2, alpha),
                 "Gaussian radius R~ [m] of two cylinders crossed at alpha "
                 "(sqrt(R1 R2) at alpha = pi/2)", "1/sqrt(kappa_1 kappa_2) of the gap",
                 f"{TEST}::test_principal_curvatures_by_hessian"),
        Relation("bodies_problem2_principal_radius_1", "Problem 2", p2["R_1"], (R,),
                 "smaller principal radius [m] of two equal cylinders crossed at pi/4",
                 "1/kappa_1 of the gap's Hessian", f"{TEST}::test_problem2",
                 printed=2 * R / (1 + 1 / sqrt2),
                 erratum="the chapter takes the eigenvalues of the coefficient matrix M of "
                 "h = x^T M x, which are half the principal curvatures (the Hessian is 2M): "
                 "R_1,2 = R/(1 +- 1/sqrt(2)), not 2R/(1 +- 1/sqrt(2))"),
        Relation("bodies_problem2_principal_radius_2", "Problem 2", p2["R_2"], (R,),
                 "larger principal radius [m] of two equal cylinders crossed at pi/4",
                 "1/kappa_2 of the gap's Hessian", f"{TEST}::test_problem2",
                 printed=2 * R / (1 - 1 / sqrt2),
                 erratum="eigenvalues of M instead of the Hessian 2M: the radius is "
                 "R/(1 - 1/sqrt(2)), half the printed one"),
        Relation("bodies_problem2_gaussian_radius", "Problem 2", p2["gauss"], (R,),
                 "Gaussian radius R~ [m] of two equal cylinders crossed at pi/4",
                 "1/sqrt(det) of the gap's Hessian", f"{TEST}::test_problem2",
                 printed=2 * sqrt2 * R,
                 erratum="with the principal radii halved, R~ = sqrt(2) R, not 2 sqrt(2) R "
                 "(check: R/sin(alpha) is R at alpha = pi/2, the sphere of (5.33))"),
        Relation("bodies_problem2_force", "Problem 2", p2["F"], (E, nu, R, d),
                 "normal force F [N] of two equal cylinders of one material crossed at pi/4 "
                 "(Gaussian-radius approximation)", "(5.23) with (5.26) and R~",
                 f"{TEST}::test_problem2",
                 printed=2 ** sp.Rational(7, 4) / 3 * E / (1 - nu**2) * sp.sqrt(R)
                 * d ** sp.Rational(3, 2),
                 erratum="with R~ = sqrt(2) R the factor is 2^(5/4)/3, not 2^(7/4)/3 (the "
                 "printed force is sqrt(2) times too large)"),
        Relation("bodies_gaussian_radius", "(5.30)", ga["gauss"], (Rp1, Rp2),
                 "Gaussian radius R~ [m] of a gap with the principal radii R1, R2",
                 "the sphere with the same Gaussian curvature kappa_1 kappa_2",
                 f"{TEST}::test_gaussian_approximation",
                 printed=sp.sqrt(Rp1 * Rp2)),
        Relation("bodies_gaussian_approx_semi_axis_1", "(5.28), approximation", ga["a"],
                 (Rp1, d), "semi-axis a [m] along the principal radius R1 of the elliptic "
                 "contact in the chapter's rough estimate", "(5.21) with R = R1",
                 f"{TEST}::test_gaussian_approximation", printed=sp.sqrt(Rp1 * d)),
        Relation("bodies_gaussian_approx_semi_axis_2", "(5.28), approximation", ga["b"],
                 (Rp2, d), "semi-axis b [m] along the principal radius R2 of the elliptic "
                 "contact in the chapter's rough estimate", "(5.21) with R = R2",
                 f"{TEST}::test_gaussian_approximation", printed=sp.sqrt(Rp2 * d)),
        Relation("bodies_gaussian_approx_area", "(5.29), approximation", ga["area"],
                 (Rp1, Rp2, d), "contact area A = pi a b [m^2] of the elliptic contact "
                 "(Gaussian-radius approximation)", "(5.28) in pi a b",
                 f"{TEST}::test_gaussian_approximation",
                 printed=sp.pi * sp.sqrt(Rp1 * Rp2) * d),
        Relation("bodies_gaussian_approx_max_pressure", "(5.22) with (5.30), approximation",
                 ga["p0"], (E_star, Rp1, Rp2, d),
                 "maximum pressure p0 [Pa] of the elliptic contact (Gaussian-radius "
                 "approximation)", "(5.22) with R = R~",
                 f"{TEST}::test_gaussian_approximation"),
        Relation("bodies_gaussian_approx_force", "(5.23) with (5.30), approximation",
                 ga["F"], (E_star, Rp1, Rp2, d),
                 "normal force F [N] of the elliptic contact (Gaussian-radius approximation)",
                 "the ellipsoidal pressure (5.31) integrated over the ellipse (5.28)",
                 f"{TEST}::test_gaussian_approximation",
                 printed=sp.Rational(4, 3) * E_star * sp.sqrt(sp.sqrt(Rp1 * Rp2))
                 * d ** sp.Rational(3, 2)),
        Relation("bodies_gaussian_approx_depth_from_force", "(5.24) with (5.30), approximation",
                 ga["d_F"], (E_star, F, Rp1, Rp2),
                 "indentation depth d [m] of the elliptic contact under the force F "
                 "(Gaussian-radius approximation)", "the force of (5.31) over (5.28) solved "
                 "for d", f"{TEST}::test_gaussian_approximation"),
        Relation("bodies_gaussian_approx_pressure", "(5.31), approximation", ga["p"],
                 (E_star, Rp1, Rp2, d, x, y),
                 "pressure p(x, y) [Pa] of the elliptic contact (Gaussian-radius "
                 "approximation; x along R1, 0 outside the ellipse)",
                 "(5.31) with (5.28) and the p0 of (5.22) at R = R~",
                 f"{TEST}::test_gaussian_approximation"),
    ]
