/* hertzmdr_laws.h -- the contact laws of hertzmdr for DEM codes: C99, double precision.
 *
 * GENERATED FILE -- DO NOT EDIT. Written by `python -m hertzmdr.derive` (make generate) from the
 * SymPy derivations of hertzmdr.derive (derive/c_codegen.py prints them with SymPy's C99
 * printer); `python -m hertzmdr.derive --check` fails when this file is stale.
 *
 * Every function is `static inline`, takes and returns doubles in SI units, and depends on
 * <math.h> alone (link with -lm where the platform needs it). Each one prints the same
 * relation as the NumPy function of the same name in hertzmdr.numeric._generated (its stable
 * form, where the derivation gives one), its constant factors folded into one literal and its
 * rational powers taken through sqrt and cbrt. tests/test_c_header.py compiles it as C99 and
 * as C++ with -Wall -Wextra -Werror -pedantic and compares every function with the NumPy and
 * the 30-digit mpmath routes over the domain stated in its comment: it agrees with NumPy, and
 * is at least as accurate, to 2e-15 beyond NumPy's own error. Arguments are not validated:
 * outside the stated domain a result may be inf or nan. Guide and timings: docs/c_laws.md;
 * every signature: docs/c_laws_reference.md.
 *
 * Functions:
 *   hertzmdr_bodies_effective_modulus
 *   hertzmdr_bodies_effective_radius
 *   hertzmdr_cattaneo_displacement
 *   hertzmdr_cattaneo_force
 *   hertzmdr_cattaneo_stick_radius
 *   hertzmdr_cattaneo_stick_radius_from_force
 *   hertzmdr_cone_contact_radius
 *   hertzmdr_cone_contact_radius_from_force
 *   hertzmdr_cone_depth_from_force
 *   hertzmdr_cone_force
 *   hertzmdr_cone_stiffness
 *   hertzmdr_ellipse_depth_from_force
 *   hertzmdr_ellipse_equivalent_radius
 *   hertzmdr_ellipse_force
 *   hertzmdr_ellipse_max_pressure
 *   hertzmdr_ellipse_radius_ratio
 *   hertzmdr_ellipse_semi_major
 *   hertzmdr_ellipse_semi_minor
 *   hertzmdr_ellipse_stiffness
 *   hertzmdr_hertz_contact_radius
 *   hertzmdr_hertz_contact_radius_from_force
 *   hertzmdr_hertz_depth_from_force
 *   hertzmdr_hertz_energy
 *   hertzmdr_hertz_force
 *   hertzmdr_hertz_max_pressure
 *   hertzmdr_hertz_stiffness
 *   hertzmdr_jkr_contact_radius_from_force
 *   hertzmdr_jkr_depth
 *   hertzmdr_jkr_force_from_radius
 *   hertzmdr_jkr_pull_off_depth_dc
 *   hertzmdr_jkr_pull_off_depth_fc
 *   hertzmdr_jkr_pull_off_force_dc
 *   hertzmdr_jkr_pull_off_force_fc
 *   hertzmdr_jkr_pull_off_radius_dc
 *   hertzmdr_jkr_pull_off_radius_fc
 *   hertzmdr_jkr_zero_load_radius
 *   hertzmdr_line_depth_from_force
 *   hertzmdr_line_force
 *   hertzmdr_line_force_per_length_from_half_width
 *   hertzmdr_line_half_width
 *   hertzmdr_line_half_width_from_force
 *   hertzmdr_line_max_pressure_from_force
 *   hertzmdr_line_stiffness
 *   hertzmdr_mindlin_energy
 *   hertzmdr_powerlaw_contact_radius
 *   hertzmdr_powerlaw_depth_from_force
 *   hertzmdr_powerlaw_force
 *   hertzmdr_powerlaw_force_from_radius
 *   hertzmdr_powerlaw_kappa
 *   hertzmdr_powerlaw_kappa_asymptotic
 *   hertzmdr_shear_modulus
 *   hertzmdr_tangential_modulus
 *   hertzmdr_tangential_stiffness
 */
#ifndef HERTZMDR_LAWS_H
#define HERTZMDR_LAWS_H

#include <math.h>

/* Carlson's symmetric elliptic integral of the second kind,
 *   R_D(x, y, z) = 3/2 int_0^inf dt / (sqrt(t + x) sqrt(t + y) (t + z)^(3/2)),
 * for x, y >= 0 (not both 0) and z > 0. The exact ellipse needs it: with m = 1 - t^2,
 *   2F1(1/2, 3/2; 2; m) = 4/(3 pi) R_D(0, t^2, 1)       ((K - E)/m),
 *   2F1(1/2, 1/2; 2; m) = 4/(3 pi) t^2 R_D(0, 1, t^2)   ((E - (1 - m) K)/m),
 * both free of cancellation for every 0 < t <= 1 (DLMF 19.25.1).
 * Method: Carlson's duplication (B. C. Carlson, Numer. Algorithms 10 (1995) 13-26;
 * DLMF 19.36.2). Each step adds 3 4^-k / (sqrt(z) (z + lambda)) to the sum and maps every
 * argument v to (v + lambda)/4, lambda = sqrt(x y) + sqrt(x z) + sqrt(y z), which
 * brings them together by a factor 4 per step. Once 4^-k Q < |A|, Q = (eps/4)^(-1/6)
 * times the initial spread, the fifth-order expansion in the elementary symmetric
 * functions E2..E5 of the scaled deviations truncates below the double rounding
 * (relative error of the result: a few ulp, measured in docs/c_laws.md). */
static inline double hertzmdr_carlson_rd(double x, double y, double z)
{
    const double q_factor = 576.0; /* (2^-53/4)^(-1/6) = 2^(55/6) = 575.9..., rounded up */
    double mean0 = (x + y + 3.0 * z) / 5.0, mean = mean0;
    double dx = mean0 - x, dy = mean0 - y, dz = mean0 - z;
    double q = q_factor * fmax(fabs(dx), fmax(fabs(dy), fabs(dz)));
    double sum = 0.0, scale = 1.0;
    int k;
    for (k = 0; k < 100 && scale * q >= fabs(mean); ++k) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * sy + sx * sz + sy * sz;
        sum += scale / (sz * (z + lam));
        scale *= 0.25;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        mean = 0.25 * (mean + lam);
    }
    {
        double X = dx * scale / mean, Y = dy * scale / mean, Z = -(X + Y) / 3.0;
        double xy = X * Y, z2 = Z * Z;
        double e2 = xy - 6.0 * z2, e3 = (3.0 * xy - 8.0 * z2) * Z;
        double e4 = 3.0 * (xy - z2) * z2, e5 = xy * z2 * Z;
        double series = 1.0 - 3.0 / 14.0 * e2 + e3 / 6.0 + 9.0 / 88.0 * e2 * e2
                        - 3.0 / 22.0 * e4 - 9.0 / 52.0 * e2 * e3 + 3.0 / 26.0 * e5;
        return scale * series / (mean * sqrt(mean)) + 3.0 * sum;
    }
}

/* hertzmdr_bodies_effective_modulus: effective modulus E* [Pa] of two elastic bodies.
 * Equation: (5.26); derived from the sum of the two surface displacements (5.6), (5.7) under
 *   one pressure (hertzmdr.derive.bodies); NumPy:
 *   hertzmdr.numeric._generated.bodies_effective_modulus; verified by
 *   tests/test_bodies.py::test_effective_modulus_by_two_displacements.
 * Stable form: 1/E* as the sum of the compliances, which accepts E2 = inf (rigid), with 1 -
 *   nu^2 = (1 - nu)(1 + nu) exact in floating point for nu near -1.
 *   E1   [Pa] Young's modulus of body 1; [0.001, 1e+15]
 *   nu1  [1] Poisson's ratio of body 1; [-0.999999, 0.5] (linear)
 *   E2   [Pa] Young's modulus of body 2; [0.001, 1e+15]
 *   nu2  [1] Poisson's ratio of body 2; [-0.999999, 0.5] (linear)
 * Returns: [Pa] */
static inline double hertzmdr_bodies_effective_modulus(double E1, double nu1, double E2, double nu2)
{
    return 1.0/((1 - nu2)*(nu2 + 1)/E2 + (1 - nu1)*(nu1 + 1)/E1);
}

/* hertzmdr_bodies_effective_radius: effective radius R [m] of two spheres (negative radius:
 * concave).
 * Equation: (5.27); derived from the sum of the two gaps r^2/(2 R_i) (hertzmdr.derive.bodies);
 *   NumPy: hertzmdr.numeric._generated.bodies_effective_radius; verified by
 *   tests/test_bodies.py::test_effective_radius_by_gap.
 * Stable form: the sum of the curvatures accepts R = inf (flat).
 *   R1  [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   R2  [m] radius of curvature of body 2, or second principal radius; [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_bodies_effective_radius(double R1, double R2)
{
    return 1.0/(1.0/R2 + 1.0/R1);
}

/* hertzmdr_cattaneo_displacement: tangential displacement u_x [m] of a paraboloid under normal
 * force F and tangential force F_x.
 * Equation: Cattaneo-Mindlin (not in the chapter); derived from F_x = mu (F_N(a) - F_N(c))
 *   solved for c, then g(c) = d - G* u_x/(mu E*) (hertzmdr.derive.tangential); NumPy:
 *   hertzmdr.numeric._generated.cattaneo_displacement; verified by
 *   tests/test_tangential.py::test_cattaneo_mindlin_literature.
 * Stable form: 1 - (1 - F_x/(mu F))^(2/3) cancels as F_x -> 0: -expm1(2/3 log1p(-F_x/(mu F))).
 *   a       [m] contact radius; [1e-12, 1000000]
 *   F       [N] normal force; [1e-100, 1e+30]
 *   G_star  [Pa] tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2);
 *           [0.001, 1e+15]
 *   mu_f    [1] coefficient of (Coulomb) friction mu; [0.001, 10]
 *   F_x     [N] tangential force; = t*mu_f*F
 *   with t in [1e-12, 0.999999999]
 * Returns: [m] */
static inline double hertzmdr_cattaneo_displacement(double a, double F, double G_star, double mu_f, double F_x)
{
    return -3.0/4.0*F*mu_f*expm1((2.0/3.0)*log1p(-F_x/(F*mu_f)))/(G_star*a);
}

/* hertzmdr_cattaneo_force: tangential force F_x [N] of a paraboloid displaced by u_x
 * (monotonic, constant load).
 * Equation: Cattaneo-Mindlin (not in the chapter); derived from sum of the stuck and sliding
 *   springs (hertzmdr.derive.tangential); NumPy: hertzmdr.numeric._generated.cattaneo_force;
 *   verified by tests/test_tangential.py::test_cattaneo_mindlin_literature.
 * Stable form: mu (F_N(a) - F_N(c)) cancels as u_x -> 0; a^3 - c^3 = (a^2 - c^2)(a^2 + a c +
 *   c^2)/(a + c) with a^2 - c^2 = R G* u_x/(mu E*) exactly.
 *   a       [m] contact radius; [1e-12, 1000000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   G_star  [Pa] tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2);
 *           [0.001, 1e+15]
 *   mu_f    [1] coefficient of (Coulomb) friction mu; [0.001, 10]
 *   u_x     [m] rigid tangential displacement of the indenter relative to the half-space; =
 *           t*mu_f*E_star*a**2/(R*G_star)
 *   with t in [1e-12, 0.999999999]
 * Returns: [N] */
static inline double hertzmdr_cattaneo_force(double a, double R, double E_star, double G_star, double mu_f, double u_x)
{
    return (4.0/3.0)*G_star*u_x*(pow(a, 2) + (E_star*pow(a, 2)*mu_f - G_star*R*u_x)/(E_star*mu_f) + a*sqrt(E_star*pow(a, 2)*mu_f - G_star*R*u_x)/(sqrt(E_star)*sqrt(mu_f)))/(a + sqrt(E_star*pow(a, 2)*mu_f - G_star*R*u_x)/(sqrt(E_star)*sqrt(mu_f)));
}

/* hertzmdr_cattaneo_stick_radius: stick radius c [m] of a paraboloid (f = r^2/(2R)) displaced
 * by u_x at constant load.
 * Equation: Cattaneo-Mindlin (not in the chapter); derived from g(c) = d - G* u_x/(mu E*), g =
 *   x^2/R (hertzmdr.derive.tangential); NumPy:
 *   hertzmdr.numeric._generated.cattaneo_stick_radius; verified by
 *   tests/test_tangential.py::test_cattaneo_mindlin_literature.
 *   a       [m] contact radius; [1e-12, 1000000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   G_star  [Pa] tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2);
 *           [0.001, 1e+15]
 *   mu_f    [1] coefficient of (Coulomb) friction mu; [0.001, 10]
 *   u_x     [m] rigid tangential displacement of the indenter relative to the half-space; =
 *           t*mu_f*E_star*a**2/(R*G_star)
 *   with t in [1e-12, 0.999999999]
 * Returns: [m] */
static inline double hertzmdr_cattaneo_stick_radius(double a, double R, double E_star, double G_star, double mu_f, double u_x)
{
    return sqrt(E_star*pow(a, 2)*mu_f - G_star*R*u_x)/(sqrt(E_star)*sqrt(mu_f));
}

/* hertzmdr_cattaneo_stick_radius_from_force: stick radius c [m] of a paraboloid under the
 * normal force F and tangential force F_x.
 * Equation: Cattaneo-Mindlin (not in the chapter); derived from F_x = mu (F_N(a) - F_N(c)), F_N
 *   ~ c^3 (hertzmdr.derive.tangential); NumPy:
 *   hertzmdr.numeric._generated.cattaneo_stick_radius_from_force; verified by
 *   tests/test_tangential.py::test_cattaneo_mindlin_literature.
 *   a     [m] contact radius; [1e-12, 1000000]
 *   F     [N] normal force; [1e-100, 1e+30]
 *   mu_f  [1] coefficient of (Coulomb) friction mu; [0.001, 10]
 *   F_x   [N] tangential force; = t*mu_f*F
 *   with t in [1e-12, 0.999999999]
 * Returns: [m] */
static inline double hertzmdr_cattaneo_stick_radius_from_force(double a, double F, double mu_f, double F_x)
{
    return a*cbrt(F*mu_f - F_x)/(cbrt(F)*cbrt(mu_f));
}

/* hertzmdr_cone_contact_radius: contact radius a [m] of a rigid cone at depth d.
 * Equation: (5.38), Problem 7(c); derived from (5.38) solved for a (hertzmdr.derive.cone);
 *   NumPy: hertzmdr.numeric._generated.cone_contact_radius; verified by
 *   tests/test_cone.py::test_cone_by_kernel.
 *   d      [m] indentation depth; [1e-15, 1000]
 *   theta  [rad] angle between the cone's surface and the plane; [1e-300, 1.5]
 * Returns: [m] */
static inline double hertzmdr_cone_contact_radius(double d, double theta)
{
    return 0.63661977236758134*d/tan(theta);
}

/* hertzmdr_cone_contact_radius_from_force: contact radius a [m] of a rigid cone under the force
 * F.
 * Equation: (5.38), (5.40); derived from (5.38) at the depth of (5.40) inverted
 *   (hertzmdr.derive.cone); NumPy: hertzmdr.numeric._generated.cone_contact_radius_from_force;
 *   verified by tests/test_cone.py::test_cone_by_kernel.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   theta   [rad] angle between the cone's surface and the plane; [1e-300, 1.5]
 * Returns: [m] */
static inline double hertzmdr_cone_contact_radius_from_force(double E_star, double F, double theta)
{
    return 0.79788456080286536*sqrt(F)/(sqrt(E_star)*sqrt(tan(theta)));
}

/* hertzmdr_cone_depth_from_force: indentation depth d [m] of a rigid cone under the force F.
 * Equation: (5.40), inverted; derived from (5.40) solved for d (hertzmdr.derive.cone); NumPy:
 *   hertzmdr.numeric._generated.cone_depth_from_force; verified by
 *   tests/test_cone.py::test_cone_by_kernel.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   theta   [rad] angle between the cone's surface and the plane; [1e-300, 1.5]
 * Returns: [m] */
static inline double hertzmdr_cone_depth_from_force(double E_star, double F, double theta)
{
    return 1.2533141373155003*sqrt(F)*sqrt(tan(theta))/sqrt(E_star);
}

/* hertzmdr_cone_force: normal force F [N] of a rigid cone at depth d.
 * Equation: (5.40); derived from the forces 2 a' E* dd of the superposed punches
 *   (hertzmdr.derive.cone); NumPy: hertzmdr.numeric._generated.cone_force; verified by
 *   tests/test_cone.py::test_cone_by_kernel.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   theta   [rad] angle between the cone's surface and the plane; [1e-250, 1.5]
 * Returns: [N] */
static inline double hertzmdr_cone_force(double E_star, double d, double theta)
{
    return 0.63661977236758134*E_star*pow(d, 2)/tan(theta);
}

/* hertzmdr_cone_stiffness: differential stiffness dF/dd [N/m] of a rigid cone at depth d.
 * Equation: Problem 5; derived from the derivative of (5.40) (hertzmdr.derive.cone); NumPy:
 *   hertzmdr.numeric._generated.cone_stiffness; verified by
 *   tests/test_cone.py::test_cone_by_kernel.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   theta   [rad] angle between the cone's surface and the plane; [1e-250, 1.5]
 * Returns: [N/m] */
static inline double hertzmdr_cone_stiffness(double E_star, double d, double theta)
{
    return 1.2732395447351627*E_star*d/tan(theta);
}

/* hertzmdr_ellipse_depth_from_force: indentation depth d [m] of an elliptical contact under the
 * force F.
 * Equation: (5.23), exact, inverted; derived from the exact force solved for d
 *   (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_depth_from_force;
 *   verified by tests/test_ellipse.py::test_force_controlled_roundtrip.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   R1      [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   t_ba    [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05,
 *           1]
 * Returns: [m] */
static inline double hertzmdr_ellipse_depth_from_force(double E_star, double F, double R1, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 1.3985822311062348*(pow(cbrt(F), 2))*((1.0/6.0)*rd0*pow(t_ba, 2) + (1.0/6.0)*rd1)/((pow(cbrt(E_star), 2))*cbrt(R1)*cbrt(rd1));
}

/* hertzmdr_ellipse_equivalent_radius: radius R_e [m] of the sphere whose Hertz force (5.23)
 * equals the elliptical contact's at every depth (compare with the Gaussian radius (5.30)).
 * Equation: (5.23), exact; derived from the exact force equated to (5.23)
 *   (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_equivalent_radius;
 *   verified by tests/test_ellipse.py::test_force_by_pressure_quadrature.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   R1    [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   t_ba  [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05, 1]
 * Returns: [m] */
static inline double hertzmdr_ellipse_equivalent_radius(double R1, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 1.6449340668482264*R1*rd1/pow((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1, 3);
}

/* hertzmdr_ellipse_force: normal force F [N] of an elliptical Hertz contact at depth d.
 * Equation: (5.23), exact; derived from (5.31) integrated over the ellipse, with a and p0 from
 *   the matching (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_force;
 *   verified by tests/test_ellipse.py::test_force_by_pressure_quadrature.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R1      [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   t_ba    [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05,
 *           1]
 * Returns: [N] */
static inline double hertzmdr_ellipse_force(double E_star, double R1, double d, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 1.7100664402158188*E_star*sqrt(R1)*(d*sqrt(d))*sqrt(rd1)/(((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1)*sqrt((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1));
}

/* hertzmdr_ellipse_max_pressure: maximum pressure p0 [Pa] of an elliptical contact at depth d.
 * Equation: (5.31), exact; derived from (5.7) over (5.31) matched to (5.32)
 *   (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_max_pressure;
 *   verified by tests/test_ellipse.py::test_displacement_by_boussinesq.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R1      [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   t_ba    [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05,
 *           1]
 * Returns: [Pa] */
static inline double hertzmdr_ellipse_max_pressure(double E_star, double R1, double d, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 1.224744871391589*E_star*sqrt(d)/(sqrt(R1)*sqrt(rd1)*t_ba*sqrt((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1));
}

/* hertzmdr_ellipse_radius_ratio: ratio R1/R2 >= 1 of the principal radii that gives the axis
 * ratio t = b/a.
 * Equation: (5.31)-(5.32), exact; derived from (5.7) over (5.31) matched to the gap (5.32): the
 *   y^2 and x^2 coefficients (hertzmdr.derive.ellipse); NumPy:
 *   hertzmdr.numeric._generated.ellipse_radius_ratio; verified by
 *   tests/test_ellipse.py::test_displacement_by_boussinesq.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   t_ba  [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05, 1]
 * Returns: [1] */
static inline double hertzmdr_ellipse_radius_ratio(double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return rd0/rd1;
}

/* hertzmdr_ellipse_semi_major: semi-axis a [m] (along x, the direction of R1 >= R2) of an
 * elliptical contact.
 * Equation: (5.28), exact; derived from (5.7) over (5.31) matched to (5.32): the x^0 and x^2
 *   coefficients (hertzmdr.derive.ellipse); NumPy:
 *   hertzmdr.numeric._generated.ellipse_semi_major; verified by
 *   tests/test_ellipse.py::test_displacement_by_boussinesq.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   R1    [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   d     [m] indentation depth; [1e-15, 1000]
 *   t_ba  [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05, 1]
 * Returns: [m] */
static inline double hertzmdr_ellipse_semi_major(double R1, double d, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 0.81649658092772603*sqrt(R1)*sqrt(d)*sqrt(rd1)/sqrt((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1);
}

/* hertzmdr_ellipse_semi_minor: semi-axis b = t a [m] (along y, the direction of R2) of an
 * elliptical contact.
 * Equation: (5.28), exact; derived from (5.7) over (5.31) matched to (5.32)
 *   (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_semi_minor; verified
 *   by tests/test_ellipse.py::test_displacement_by_boussinesq.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   R1    [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   d     [m] indentation depth; [1e-15, 1000]
 *   t_ba  [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05, 1]
 * Returns: [m] */
static inline double hertzmdr_ellipse_semi_minor(double R1, double d, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 0.81649658092772603*sqrt(R1)*sqrt(d)*sqrt(rd1)*t_ba/sqrt((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1);
}

/* hertzmdr_ellipse_stiffness: differential stiffness dF/dd [N/m] of an elliptical contact.
 * Equation: (5.13), exact; derived from the derivative of the force at fixed R1, R2
 *   (hertzmdr.derive.ellipse); NumPy: hertzmdr.numeric._generated.ellipse_stiffness; verified
 *   by tests/test_ellipse.py::test_stiffness_by_derivative.
 * Stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as
 *   (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R1      [m] radius of curvature of body 1, or first principal radius; [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   t_ba    [1] axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2); [3e-05,
 *           1]
 * Returns: [N/m] */
static inline double hertzmdr_ellipse_stiffness(double E_star, double R1, double d, double t_ba)
{
    const double rd0 = hertzmdr_carlson_rd(0, 1, pow(t_ba, 2));
    const double rd1 = hertzmdr_carlson_rd(0, pow(t_ba, 2), 1);
    return 2.5650996603237282*E_star*sqrt(R1)*sqrt(d)*sqrt(rd1)/(((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1)*sqrt((1.0/3.0)*rd0*pow(t_ba, 2) + (1.0/3.0)*rd1));
}

/* hertzmdr_hertz_contact_radius: contact radius a [m] of a Hertz contact at depth d.
 * Equation: (5.21); derived from the matching condition (5.19) (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_contact_radius; verified by
 *   tests/test_hertz.py::test_matching_by_kernel.
 *   R  [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d  [m] indentation depth; [1e-15, 1000]
 * Returns: [m] */
static inline double hertzmdr_hertz_contact_radius(double R, double d)
{
    return sqrt(R)*sqrt(d);
}

/* hertzmdr_hertz_contact_radius_from_force: contact radius a [m] of a Hertz contact under the
 * force F.
 * Equation: (5.24); derived from (5.21) at the depth of (5.23) inverted
 *   (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_contact_radius_from_force; verified by
 *   tests/test_hertz.py::test_force_controlled_roundtrip.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_hertz_contact_radius_from_force(double E_star, double F, double R)
{
    return 0.90856029641606983*cbrt(F)*cbrt(R)/cbrt(E_star);
}

/* hertzmdr_hertz_depth_from_force: indentation depth d [m] of a Hertz contact under the force
 * F.
 * Equation: (5.23), inverted; derived from (5.23) solved for d (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_depth_from_force; verified by
 *   tests/test_hertz.py::test_force_controlled_roundtrip.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_hertz_depth_from_force(double E_star, double F, double R)
{
    return 0.82548181222365667*(pow(cbrt(F), 2))/((pow(cbrt(E_star), 2))*cbrt(R));
}

/* hertzmdr_hertz_energy: elastic energy U [J] stored in a Hertz contact at depth d.
 * Equation: (5.25); derived from the integral of F = dU/dd from 0 to d (hertzmdr.derive.hertz);
 *   NumPy: hertzmdr.numeric._generated.hertz_energy; verified by
 *   tests/test_hertz.py::test_energy_by_work.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 * Returns: [J] */
static inline double hertzmdr_hertz_energy(double E_star, double R, double d)
{
    return (8.0/15.0)*E_star*sqrt(R)*(pow(d, 2)*sqrt(d));
}

/* hertzmdr_hertz_force: normal force F [N] of a Hertz contact at depth d.
 * Equation: (5.23); derived from (5.17) with (5.21) and (5.22) (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_force; verified by
 *   tests/test_hertz.py::test_force_by_pressure_quadrature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 * Returns: [N] */
static inline double hertzmdr_hertz_force(double E_star, double R, double d)
{
    return (4.0/3.0)*E_star*sqrt(R)*(d*sqrt(d));
}

/* hertzmdr_hertz_max_pressure: maximum (central) pressure p0 [Pa] of a Hertz contact at depth
 * d.
 * Equation: (5.22); derived from the matching condition (5.19) (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_max_pressure; verified by
 *   tests/test_hertz.py::test_matching_by_kernel.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 * Returns: [Pa] */
static inline double hertzmdr_hertz_max_pressure(double E_star, double R, double d)
{
    return 0.63661977236758134*E_star*sqrt(d)/sqrt(R);
}

/* hertzmdr_hertz_stiffness: differential contact stiffness dF/dd [N/m] of a Hertz contact.
 * Equation: Problem 5; derived from the derivative of (5.23) (hertzmdr.derive.hertz); NumPy:
 *   hertzmdr.numeric._generated.hertz_stiffness; verified by
 *   tests/test_hertz.py::test_stiffness_by_punch.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 * Returns: [N/m] */
static inline double hertzmdr_hertz_stiffness(double E_star, double R, double d)
{
    return 2*E_star*sqrt(R)*sqrt(d);
}

/* hertzmdr_jkr_contact_radius_from_force: contact radius a [m] of a paraboloid in JKR contact
 * under the force F_load >= -3 pi R dgamma/2 (the stable branch).
 * Equation: (5.57), JKR, inverted; derived from (5.57) as a quadratic in a^(3/2), larger root
 *   (hertzmdr.derive.adhesion); NumPy:
 *   hertzmdr.numeric._generated.jkr_contact_radius_from_force; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F_load  [N] normal force, negative when adhesion pulls (adhesive contact); = pi*R*dgamma*(t
 *           - 3/2)
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   with t in [1e-09, 1000000000]
 * Returns: [m]
 * Note: force control: F_load >= the pull-off force -3/2 pi R dgamma. */
static inline double hertzmdr_jkr_contact_radius_from_force(double E_star, double F_load, double R, double dgamma)
{
    return (1.0/2.0)*(pow(cbrt(1.7320508075688773*sqrt(R)*sqrt(2*F_load + 9.4247779607693797*R*dgamma) + 5.3173615527165481*R*sqrt(dgamma)), 2))/cbrt(E_star);
}

/* hertzmdr_jkr_depth: indentation depth d [m] of a paraboloid in JKR contact of radius a.
 * Equation: (5.55), JKR; derived from (5.52) of r^2/(2R), (5.55) with Delta l
 *   (hertzmdr.derive.adhesion); NumPy: hertzmdr.numeric._generated.jkr_depth; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   a       [m] contact radius; [1e-12, 1000000]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 * Returns: [m] */
static inline double hertzmdr_jkr_depth(double E_star, double R, double a, double dgamma)
{
    return pow(a, 2)/R - 2.5066282746310005*sqrt(a)*sqrt(dgamma)/sqrt(E_star);
}

/* hertzmdr_jkr_force_from_radius: normal force F [N] of a paraboloid in JKR contact of radius
 * a.
 * Equation: (5.57), JKR; derived from (5.57) at the adhesive depth (hertzmdr.derive.adhesion);
 *   NumPy: hertzmdr.numeric._generated.jkr_force_from_radius; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   a       [m] contact radius; [1e-12, 1000000]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 * Returns: [N]
 * Note: along the JKR branch, parametrized by the contact radius a; the overlap at the same a
 *   is hertzmdr_jkr_depth. */
static inline double hertzmdr_jkr_force_from_radius(double E_star, double R, double a, double dgamma)
{
    return -5.013256549262001*sqrt(E_star)*(a*sqrt(a))*sqrt(dgamma) + (4.0/3.0)*E_star*pow(a, 3)/R;
}

/* hertzmdr_jkr_pull_off_depth_dc: depth d_c [m] at pull-off of a paraboloid (JKR) under depth
 * control (negative: the surface is pulled up).
 * Equation: (5.55), adhesive; derived from (5.55) with Delta l at the pull-off radius
 *   (hertzmdr.derive.adhesion); NumPy: hertzmdr.numeric._generated.jkr_pull_off_depth_dc;
 *   verified by tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_jkr_pull_off_depth_dc(double E_star, double dgamma, double R)
{
    return -1.6087720478332692*cbrt(R)*(pow(cbrt(dgamma), 2))/(pow(cbrt(E_star), 2));
}

/* hertzmdr_jkr_pull_off_depth_fc: depth d_c [m] at pull-off of a paraboloid (JKR) under force
 * control (negative: the surface is pulled up).
 * Equation: (5.55), adhesive; derived from (5.55) with Delta l at the pull-off radius
 *   (hertzmdr.derive.adhesion); NumPy: hertzmdr.numeric._generated.jkr_pull_off_depth_fc;
 *   verified by tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_jkr_pull_off_depth_fc(double E_star, double dgamma, double R)
{
    return -0.77341693157003398*cbrt(R)*(pow(cbrt(dgamma), 2))/(pow(cbrt(E_star), 2));
}

/* hertzmdr_jkr_pull_off_force_dc: pull-off force F_c [N] (negative) of a paraboloid (JKR) under
 * depth control.
 * Equation: (5.57), adhesive; derived from (5.57) at the pull-off radius
 *   (hertzmdr.derive.adhesion); NumPy: hertzmdr.numeric._generated.jkr_pull_off_force_dc;
 *   verified by tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [N] */
static inline double hertzmdr_jkr_pull_off_force_dc(double E_star, double dgamma, double R)
{
    (void)E_star; /* the law does not depend on it */
    return -2.6179938779914944*R*dgamma;
}

/* hertzmdr_jkr_pull_off_force_fc: pull-off force F_c [N] (negative) of a paraboloid (JKR) under
 * force control.
 * Equation: (5.57), adhesive; derived from (5.57) at the pull-off radius
 *   (hertzmdr.derive.adhesion); NumPy: hertzmdr.numeric._generated.jkr_pull_off_force_fc;
 *   verified by tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [N] */
static inline double hertzmdr_jkr_pull_off_force_fc(double E_star, double dgamma, double R)
{
    (void)E_star; /* the law does not depend on it */
    return -4.7123889803846899*R*dgamma;
}

/* hertzmdr_jkr_pull_off_radius_dc: contact radius a_c [m] at pull-off of a paraboloid (JKR)
 * under depth control.
 * Equation: (5.57), adhesive; derived from dd/da = 0 (hertzmdr.derive.adhesion); NumPy:
 *   hertzmdr.numeric._generated.jkr_pull_off_radius_dc; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_jkr_pull_off_radius_dc(double E_star, double dgamma, double R)
{
    return 0.73229594378076163*(pow(cbrt(R), 2))*cbrt(dgamma)/cbrt(E_star);
}

/* hertzmdr_jkr_pull_off_radius_fc: contact radius a_c [m] at pull-off of a paraboloid (JKR)
 * under force control.
 * Equation: (5.57), adhesive; derived from dF/da = 0 (hertzmdr.derive.adhesion); NumPy:
 *   hertzmdr.numeric._generated.jkr_pull_off_radius_fc; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_jkr_pull_off_radius_fc(double E_star, double dgamma, double R)
{
    return 1.5232369463448889*(pow(cbrt(R), 2))*cbrt(dgamma)/cbrt(E_star);
}

/* hertzmdr_jkr_zero_load_radius: contact radius a_0 [m] of a paraboloid (JKR) at zero load.
 * Equation: (5.57), adhesive; derived from F(a) = 0 of (5.57) (hertzmdr.derive.adhesion);
 *   NumPy: hertzmdr.numeric._generated.jkr_zero_load_radius; verified by
 *   tests/test_adhesion.py::test_jkr_literature.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   dgamma  [J/m^2] work of adhesion Delta gamma (energy per unit area to separate); [1e-06,
 *           1000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_jkr_zero_load_radius(double E_star, double dgamma, double R)
{
    return 2.4179879310247045*(pow(cbrt(R), 2))*cbrt(dgamma)/cbrt(E_star);
}

/* hertzmdr_line_depth_from_force: depth d [m] (in the sense of (5.35)) of a line contact under
 * the force F.
 * Equation: (5.34), inverted; derived from (5.34) solved for d (hertzmdr.derive.line); NumPy:
 *   hertzmdr.numeric._generated.line_depth_from_force; verified by
 *   tests/test_line.py::test_line_by_displacement_gradient.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   L       [m] length of a line contact; [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_line_depth_from_force(double E_star, double F, double L)
{
    return 1.2732395447351627*F/(E_star*L);
}

/* hertzmdr_line_force: normal force F [N] of a line contact of length L at the depth d of
 * (5.35).
 * Equation: (5.34); derived from F/L of the matched pressure with a = sqrt(R d)
 *   (hertzmdr.derive.line); NumPy: hertzmdr.numeric._generated.line_force; verified by
 *   tests/test_line.py::test_line_by_displacement_gradient.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   L       [m] length of a line contact; [1e-12, 1000000]
 *   d       [m] indentation depth; [1e-15, 1000]
 * Returns: [N]
 * Note: (5.34) is independent of R: the line contact's depth is defined only up to a logarithm
 *   of the bodies' size, which the chapter's force-depth law leaves out. */
static inline double hertzmdr_line_force(double E_star, double L, double d)
{
    return 0.78539816339744831*E_star*L*d;
}

/* hertzmdr_line_force_per_length_from_half_width: normal force per unit length F/L [N/m] of a
 * line contact of half-width a.
 * Equation: (5.34), from the matching; derived from the integral of (5.36) over the strip
 *   (hertzmdr.derive.line); NumPy:
 *   hertzmdr.numeric._generated.line_force_per_length_from_half_width; verified by
 *   tests/test_line.py::test_line_by_displacement_gradient.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   a       [m] contact radius; [1e-12, 1000000]
 * Returns: [N/m] */
static inline double hertzmdr_line_force_per_length_from_half_width(double E_star, double R, double a)
{
    return 0.78539816339744831*E_star*pow(a, 2)/R;
}

/* hertzmdr_line_half_width: half-width a [m] of a line contact at the (conventional) depth d.
 * Equation: (5.35); derived from the chapter's definition of the depth of a line contact
 *   (hertzmdr.derive.line); NumPy: hertzmdr.numeric._generated.line_half_width; verified by
 *   tests/test_line.py::test_line_by_displacement_gradient.
 *   R  [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 *   d  [m] indentation depth; [1e-15, 1000]
 * Returns: [m] */
static inline double hertzmdr_line_half_width(double R, double d)
{
    return sqrt(R)*sqrt(d);
}

/* hertzmdr_line_half_width_from_force: half-width a [m] of a line contact of length L under the
 * force F.
 * Equation: (5.34), (5.35); derived from F = L F/L(a) solved for a (hertzmdr.derive.line);
 *   NumPy: hertzmdr.numeric._generated.line_half_width_from_force; verified by
 *   tests/test_line.py::test_line_by_displacement_gradient.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   L       [m] length of a line contact; [1e-12, 1000000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [m] */
static inline double hertzmdr_line_half_width_from_force(double E_star, double F, double L, double R)
{
    return 1.1283791670955126*sqrt(F)*sqrt(R)/(sqrt(E_star)*sqrt(L));
}

/* hertzmdr_line_max_pressure_from_force: maximum pressure p0 [Pa] of a line contact of length L
 * under the force F.
 * Equation: (5.37), third form; derived from the matching, with a from F = L F/L(a)
 *   (hertzmdr.derive.line); NumPy: hertzmdr.numeric._generated.line_max_pressure_from_force;
 *   verified by tests/test_line.py::test_line_by_displacement_gradient.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F       [N] normal force; [1e-300, 1e+30]
 *   L       [m] length of a line contact; [1e-12, 1000000]
 *   R       [m] radius of curvature (effective radius (5.27) for two bodies); [1e-12, 1000000]
 * Returns: [Pa] */
static inline double hertzmdr_line_max_pressure_from_force(double E_star, double F, double L, double R)
{
    return 0.56418958354775629*sqrt(E_star)*sqrt(F)/(sqrt(L)*sqrt(R));
}

/* hertzmdr_line_stiffness: differential stiffness dF/dd [N/m] of a line contact of length L
 * (with d defined by (5.35)).
 * Equation: (5.34), differentiated; derived from the derivative of (5.34)
 *   (hertzmdr.derive.line); NumPy: hertzmdr.numeric._generated.line_stiffness; verified by
 *   tests/test_line.py::test_line_stiffness_by_derivative.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   L       [m] length of a line contact; [1e-12, 1000000]
 * Returns: [N/m] */
static inline double hertzmdr_line_stiffness(double E_star, double L)
{
    return 0.78539816339744831*E_star*L;
}

/* hertzmdr_mindlin_energy: energy W [J] dissipated per cycle of a tangential force oscillating
 * with amplitude F_amp at constant normal force F (paraboloid).
 * Equation: Mindlin-Deresiewicz (not in the chapter); derived from sum of the sliding springs'
 *   parallelogram loops 4 mu q_z (u* - mu q_z/G*) (hertzmdr.derive.tangential); NumPy:
 *   hertzmdr.numeric._generated.mindlin_energy; verified by
 *   tests/test_tangential.py::test_mindlin_deresiewicz_energy.
 * Stable form: the integrand vanishes to second order at the edge: (1 - c/a)^3 P(c/a) with 1 -
 *   c/a = -expm1(log1p(-F_amp/(mu F))/3) keeps the cubic law to rounding.
 *   a       [m] contact radius; [1e-12, 1000000]
 *   F       [N] normal force; [1e-100, 1e+30]
 *   G_star  [Pa] tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2);
 *           [0.001, 1e+15]
 *   mu_f    [1] coefficient of (Coulomb) friction mu; [0.001, 10]
 *   F_amp   [N] amplitude F_x* of an oscillating tangential force; = t*mu_f*F
 *   with t in [1e-12, 0.999999999]
 * Returns: [J] */
static inline double hertzmdr_mindlin_energy(double a, double F, double G_star, double mu_f, double F_amp)
{
    return -1.0/5.0*(3*pow(F, 2)*pow(mu_f, 2)*exp((2.0/3.0)*log1p(-F_amp/(F*mu_f))) + 9*pow(F, 2)*pow(mu_f, 2)*exp((1.0/3.0)*log1p(-F_amp/(F*mu_f))) + 3*pow(F, 2)*pow(mu_f, 2))*pow(expm1((1.0/3.0)*log1p(-F_amp/(F*mu_f))), 3)/(G_star*a);
}

/* hertzmdr_powerlaw_contact_radius: contact radius a [m] of a power-law indenter at depth d.
 * Equation: Problem 7(d); derived from (5.55) with g of (5.52) (hertzmdr.derive.powerlaw);
 *   NumPy: hertzmdr.numeric._generated.powerlaw_contact_radius; verified by
 *   tests/test_powerlaw.py::test_against_3d_elasticity.
 *   c_n      [m^(1-n)] coefficient of the power-law profile f = c_n r^n; =
 *            d/((sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2))*a**n)
 *   d        [m] indentation depth; [1e-15, 1000]
 *   kappa_n  [1] MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)); =
 *            sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2)
 *   n        [1] exponent of the power-law profile f = c_n r^n, n > 0; [0.1, 20]
 *   with a in [1e-09, 1000]
 * Returns: [m] */
static inline double hertzmdr_powerlaw_contact_radius(double c_n, double d, double kappa_n, double n)
{
    return pow(d/(c_n*kappa_n), 1.0/n);
}

/* hertzmdr_powerlaw_depth_from_force: indentation depth d [m] of a power-law indenter under the
 * force F.
 * Equation: Problem 7(d), inverted; derived from the force of Problem 7(d) solved for d
 *   (hertzmdr.derive.powerlaw); NumPy: hertzmdr.numeric._generated.powerlaw_depth_from_force;
 *   verified by tests/test_powerlaw.py::test_force_roundtrip.
 * Stable form: (kappa_n c_n)^(1/n) of the derived form overflows or underflows for small n
 *   although d is ordinary (c_n = 1e-3, n = 3 at F = 1 N: NaN); split into (F (n + 1)/(2 E*
 *   n))^(n/(n + 1)) (kappa_n c_n)^(1/(n + 1)), whose factors stay within the range of the
 *   inputs.
 *   E_star   [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   F        [N] normal force; = 2*E_star*n*a*d/(n + 1)
 *   c_n      [m^(1-n)] coefficient of the power-law profile f = c_n r^n; =
 *            d/((sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2))*a**n)
 *   kappa_n  [1] MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)); =
 *            sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2)
 *   n        [1] exponent of the power-law profile f = c_n r^n, n > 0; [0.1, 20]
 *   with d in [1e-15, 1000], a in [1e-09, 1000]
 * Returns: [m] */
static inline double hertzmdr_powerlaw_depth_from_force(double E_star, double F, double c_n, double kappa_n, double n)
{
    return pow(c_n*kappa_n, 1.0/(n + 1))*pow((1.0/2.0)*F*(n + 1)/(E_star*n), n/(n + 1));
}

/* hertzmdr_powerlaw_force: normal force F [N] of a power-law indenter at depth d.
 * Equation: Problem 7(d); derived from (5.57) at the contact radius of (5.55)
 *   (hertzmdr.derive.powerlaw); NumPy: hertzmdr.numeric._generated.powerlaw_force; verified by
 *   tests/test_powerlaw.py::test_force_by_pressure.
 *   E_star   [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   c_n      [m^(1-n)] coefficient of the power-law profile f = c_n r^n; =
 *            d/((sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2))*a**n)
 *   d        [m] indentation depth; [1e-15, 1000]
 *   kappa_n  [1] MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)); =
 *            sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2)
 *   n        [1] exponent of the power-law profile f = c_n r^n, n > 0; [0.1, 20]
 *   with a in [1e-09, 1000]
 * Returns: [N]
 * Note: kappa_n = hertzmdr_powerlaw_kappa(n); the domain is drawn through the contact radius a,
 *   c_n = d/(kappa_n a^n). */
static inline double hertzmdr_powerlaw_force(double E_star, double c_n, double d, double kappa_n, double n)
{
    return 2*E_star*d*n*pow(d/(c_n*kappa_n), 1.0/n)/(n + 1);
}

/* hertzmdr_powerlaw_force_from_radius: normal force F [N] of a power-law indenter with contact
 * radius a at depth d.
 * Equation: Problem 7(d), (5.57); derived from (5.57) with d = g(a) (5.55)
 *   (hertzmdr.derive.powerlaw); NumPy: hertzmdr.numeric._generated.powerlaw_force_from_radius;
 *   verified by tests/test_powerlaw.py::test_force_by_pressure.
 *   E_star  [Pa] effective modulus E* (5.8), (5.26); [0.001, 1e+15]
 *   a       [m] contact radius; [1e-09, 1000]
 *   d       [m] indentation depth; [1e-15, 1000]
 *   n       [1] exponent of the power-law profile f = c_n r^n, n > 0; [0.1, 20]
 * Returns: [N] */
static inline double hertzmdr_powerlaw_force_from_radius(double E_star, double a, double d, double n)
{
    return 2*E_star*a*d*n/(n + 1);
}

/* hertzmdr_powerlaw_kappa: MDR factor kappa_n [1] of the power-law profile, g = kappa_n c_n
 * |x|^n (overflows for n > 340: use powerlaw_kappa_asymptotic there).
 * Equation: Problem 7(d); derived from (5.52) for f = c_n r^n (hertzmdr.derive.powerlaw);
 *   NumPy: hertzmdr.numeric._generated.powerlaw_kappa; verified by
 *   tests/test_powerlaw.py::test_kappa_by_quadrature.
 *   n  [1] exponent of the power-law profile f = c_n r^n, n > 0; [0.1, 20]
 * Returns: [1]
 * Note: Gamma ratio: overflows beyond n ~ 340; hertzmdr.numeric.powerlaw.kappa switches to
 *   hertzmdr_powerlaw_kappa_asymptotic above n = 40. */
static inline double hertzmdr_powerlaw_kappa(double n)
{
    return 1.772453850905516*tgamma((1.0/2.0)*n + 1)/tgamma((1.0/2.0)*n + 1.0/2.0);
}

/* hertzmdr_powerlaw_kappa_asymptotic: kappa_n [1] from the Stirling series to O(n^-10);
 * relative error < 1e-16 for n >= 40.
 * Equation: Problem 7(d), large n; derived from the Stirling series of ln Gamma(n/2 + 1) - ln
 *   Gamma(n/2 + 1/2) (hertzmdr.derive.powerlaw); NumPy:
 *   hertzmdr.numeric._generated.powerlaw_kappa_asymptotic; verified by
 *   tests/test_powerlaw.py::test_kappa_by_quadrature.
 *   n  [1] exponent of the power-law profile f = c_n r^n, n > 0; [40, 100000000]
 * Returns: [1] */
static inline double hertzmdr_powerlaw_kappa_asymptotic(double n)
{
    return 1.2533141373155003*sqrt(n)*exp(2*1.0/n*(4*pow(n, -2.0)*(4*pow(n, -2.0)*(4*pow(n, -2.0)*((31.0/4608.0)*pow(n, -2.0) - 17.0/14336.0) + 1.0/640.0) - 1.0/192.0) + 1.0/8.0));
}

/* hertzmdr_shear_modulus: shear modulus G [Pa] of an isotropic body.
 * Equation: Lame's mu (not in the chapter); derived from Hooke's law in Lame's form
 *   (hertzmdr.derive.tangential); NumPy: hertzmdr.numeric._generated.shear_modulus; verified by
 *   tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance.
 *   E   [Pa] Young's modulus; [0.001, 1e+15]
 *   nu  [1] Poisson's ratio; [-0.999999, 0.5] (linear)
 * Returns: [Pa] */
static inline double hertzmdr_shear_modulus(double E, double nu)
{
    return E/(2*nu + 2);
}

/* hertzmdr_tangential_modulus: tangential effective modulus G* [Pa] of two elastic bodies.
 * Equation: MDR tangential springs (not in the chapter); derived from direction average of the
 *   Cerruti surface compliance of each body, compliances added (hertzmdr.derive.tangential);
 *   NumPy: hertzmdr.numeric._generated.tangential_modulus; verified by
 *   tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance.
 * Stable form: a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf.
 *   G1   [Pa] shear modulus of body 1; [0.001, 1e+15]
 *   nu1  [1] Poisson's ratio of body 1; [-0.999999, 0.5] (linear)
 *   G2   [Pa] shear modulus of body 2; [0.001, 1e+15]
 *   nu2  [1] Poisson's ratio of body 2; [-0.999999, 0.5] (linear)
 * Returns: [Pa] */
static inline double hertzmdr_tangential_modulus(double G1, double nu1, double G2, double nu2)
{
    return 1.0/((1.0/4.0)*(2 - nu2)/G2 + (1.0/4.0)*(2 - nu1)/G1);
}

/* hertzmdr_tangential_stiffness: tangential contact stiffness k_x = dF_x/du_x [N/m] before any
 * slip (c = a).
 * Equation: MDR tangential springs (not in the chapter); derived from sum of the 2a/dx stuck
 *   springs of stiffness G* dx (hertzmdr.derive.tangential); NumPy:
 *   hertzmdr.numeric._generated.tangential_stiffness; verified by
 *   tests/test_tangential.py::test_initial_stiffness_is_2_G_star_a_for_every_profile.
 *   G_star  [Pa] tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2);
 *           [0.001, 1e+15]
 *   a       [m] contact radius; [1e-12, 1000000]
 * Returns: [N/m] */
static inline double hertzmdr_tangential_stiffness(double G_star, double a)
{
    return 2*G_star*a;
}

#endif /* HERTZMDR_LAWS_H */
