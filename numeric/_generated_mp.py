"""The relations of ``hertzmdr.derive`` printed for mpmath: any precision, no SymPy needed.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``) from the same
expressions as ``_generated.py``; ``python -m hertzmdr.derive --check`` fails when this file is stale. Call with
mpmath numbers inside ``mpmath.workdps(...)``: every constant is an exact mpmath rational, so the
result carries the working precision. The accuracy report (``hertzmdr accuracy``) takes its
50-digit truths from here; ``tests/`` check these expressions against independent quadratures.
"""

import mpmath

__all__ = [
    'adhesion_cone_depth',
    'adhesion_cone_force_from_radius',
    'adhesion_cone_g_slope',
    'adhesion_cone_pull_off_depth_dc',
    'adhesion_cone_pull_off_depth_fc',
    'adhesion_cone_pull_off_force_dc',
    'adhesion_cone_pull_off_force_fc',
    'adhesion_cone_pull_off_radius_dc',
    'adhesion_cone_pull_off_radius_fc',
    'adhesion_cone_zero_load_radius',
    'adhesion_critical_elongation',
    'adhesion_depth',
    'adhesion_depth_slope',
    'adhesion_displacement_outside_edge',
    'adhesion_energy_release_rate',
    'adhesion_force_slope',
    'adhesion_paraboloid_g_slope',
    'adhesion_powerlaw_depth',
    'adhesion_powerlaw_force_from_radius',
    'adhesion_powerlaw_g_slope',
    'adhesion_powerlaw_pull_off_depth_dc',
    'adhesion_powerlaw_pull_off_depth_fc',
    'adhesion_powerlaw_pull_off_force_dc',
    'adhesion_powerlaw_pull_off_force_fc',
    'adhesion_powerlaw_pull_off_radius_dc',
    'adhesion_powerlaw_pull_off_radius_fc',
    'adhesion_powerlaw_zero_load_radius',
    'adhesion_pressure_edge',
    'adhesion_punch_cycle_work',
    'adhesion_punch_pull_off_force',
    'adhesion_sphere_g_slope',
    'adhesion_tabor_parameter',
    'adhesion_worn_g_slope',
    'bodies_crossed_cylinders_curvature_1',
    'bodies_crossed_cylinders_curvature_2',
    'bodies_crossed_cylinders_gaussian_radius',
    'bodies_effective_modulus',
    'bodies_effective_modulus_rigid',
    'bodies_effective_radius',
    'bodies_gaussian_approx_area',
    'bodies_gaussian_approx_depth_from_force',
    'bodies_gaussian_approx_force',
    'bodies_gaussian_approx_max_pressure',
    'bodies_gaussian_approx_pressure',
    'bodies_gaussian_approx_semi_axis_1',
    'bodies_gaussian_approx_semi_axis_2',
    'bodies_gaussian_radius',
    'bodies_principal_curvature_1',
    'bodies_principal_curvature_2',
    'bodies_problem2_force',
    'bodies_problem2_gaussian_radius',
    'bodies_problem2_principal_radius_1',
    'bodies_problem2_principal_radius_2',
    'boussinesq_sigma_xx',
    'boussinesq_sigma_xy',
    'boussinesq_sigma_xz',
    'boussinesq_sigma_yy',
    'boussinesq_sigma_yz',
    'boussinesq_sigma_zz',
    'boussinesq_surface_prefactor',
    'boussinesq_surface_ux',
    'boussinesq_surface_uy',
    'boussinesq_surface_uz',
    'boussinesq_ux',
    'boussinesq_uy',
    'boussinesq_uz',
    'cattaneo_displacement',
    'cattaneo_force',
    'cattaneo_stick_radius',
    'cattaneo_stick_radius_from_force',
    'cattaneo_traction_slip',
    'cattaneo_traction_stick',
    'cerruti_surface_ux',
    'cerruti_surface_uy',
    'cerruti_surface_uz',
    'cerruti_ux',
    'cerruti_uy',
    'cerruti_uz',
    'cone_contact_radius',
    'cone_contact_radius_from_force',
    'cone_depth',
    'cone_depth_from_force',
    'cone_force',
    'cone_g',
    'cone_mean_pressure',
    'cone_pressure',
    'cone_profile',
    'cone_stiffness',
    'contact_mean_pressure',
    'coulomb_sliding_force',
    'disc_mean_pressure',
    'disc_pressure',
    'ellipse_area',
    'ellipse_depth_from_force',
    'ellipse_equivalent_radius',
    'ellipse_force',
    'ellipse_max_pressure',
    'ellipse_mean_pressure',
    'ellipse_pressure',
    'ellipse_radius_ratio',
    'ellipse_semi_major',
    'ellipse_semi_minor',
    'ellipse_stiffness',
    'ellipse_stress_I_x',
    'ellipse_stress_I_y',
    'ellipse_stress_axis_shear_x',
    'ellipse_stress_axis_shear_x_slope',
    'ellipse_stress_axis_shear_y',
    'ellipse_stress_axis_shear_y_slope',
    'ellipse_stress_axis_sigma_xx',
    'ellipse_stress_axis_sigma_yy',
    'ellipse_stress_axis_sigma_zz',
    'ellipse_stress_axis_von_mises',
    'ellipse_stress_axis_von_mises_slope',
    'ellipse_stress_cubic_lam',
    'ellipse_stress_cubic_lam_slope',
    'ellipse_stress_cubic_q',
    'ellipse_stress_cubic_q_slope',
    'ellipse_stress_d',
    'ellipse_stress_e_sq',
    'ellipse_stress_jxx_integrand',
    'ellipse_stress_jxy_integrand',
    'ellipse_stress_jyy_integrand',
    'ellipse_stress_sigma_xx',
    'ellipse_stress_sigma_yy',
    'ellipse_stress_sigma_zz',
    'ellipse_stress_tau_xy',
    'ellipse_stress_tau_xz',
    'ellipse_stress_tau_yz',
    'ellipse_stress_w1',
    'ellipse_stress_w1_a',
    'ellipse_stress_w1_b',
    'fit_adhesive_cone_depth',
    'fit_adhesive_cone_depth_da',
    'fit_adhesive_cone_force',
    'fit_adhesive_cone_force_dE',
    'fit_adhesive_cone_force_ddgamma',
    'fit_adhesive_cone_force_dz0',
    'fit_adhesive_powerlaw_depth',
    'fit_adhesive_powerlaw_depth_da',
    'fit_adhesive_powerlaw_force',
    'fit_adhesive_powerlaw_force_dE',
    'fit_adhesive_powerlaw_force_ddgamma',
    'fit_adhesive_powerlaw_force_dz0',
    'fit_adhesive_sampled_depth',
    'fit_adhesive_sampled_depth_da',
    'fit_adhesive_sampled_force',
    'fit_adhesive_sampled_force_dE',
    'fit_adhesive_sampled_force_ddgamma',
    'fit_adhesive_sampled_force_dz0',
    'fit_adhesive_sphere_depth',
    'fit_adhesive_sphere_depth_da',
    'fit_adhesive_sphere_force',
    'fit_adhesive_sphere_force_dE',
    'fit_adhesive_sphere_force_ddgamma',
    'fit_adhesive_sphere_force_dz0',
    'fit_cone_force',
    'fit_cone_force_dE',
    'fit_cone_force_dz0',
    'fit_hertz_force',
    'fit_hertz_force_dE',
    'fit_hertz_force_dz0',
    'fit_jkr_depth',
    'fit_jkr_depth_da',
    'fit_jkr_force',
    'fit_jkr_force_dE',
    'fit_jkr_force_ddgamma',
    'fit_jkr_force_dz0',
    'fit_powerlaw_force',
    'fit_powerlaw_force_dE',
    'fit_powerlaw_force_dz0',
    'fit_punch_force',
    'fit_punch_force_dE',
    'fit_punch_force_dz0',
    'fit_pyramid_cone_angle',
    'fit_pyramid_force_cone_angle',
    'fit_sample_modulus',
    'fit_sample_modulus_dE',
    'fit_sample_modulus_rigid',
    'fit_sample_modulus_rigid_dE',
    'fit_sphere_depth',
    'fit_sphere_depth_dlam',
    'fit_sphere_force',
    'fit_sphere_force_dE',
    'fit_sphere_force_dz0',
    'fit_sphere_radius_dlam',
    'flamant_sigma_xx',
    'flamant_sigma_zz',
    'flamant_tau_xz',
    'flat_punch_tangential_traction',
    'force_law_cone_exponent',
    'force_law_cone_prefactor',
    'force_law_cone_stiffness_exponent',
    'force_law_cone_stiffness_prefactor',
    'force_law_ellipse_exponent',
    'force_law_ellipse_prefactor',
    'force_law_ellipse_stiffness_exponent',
    'force_law_ellipse_stiffness_prefactor',
    'force_law_hertz_exponent',
    'force_law_hertz_prefactor',
    'force_law_hertz_stiffness_exponent',
    'force_law_hertz_stiffness_prefactor',
    'force_law_line_exponent',
    'force_law_line_prefactor',
    'force_law_line_stiffness_exponent',
    'force_law_line_stiffness_prefactor',
    'force_law_powerlaw_exponent',
    'force_law_powerlaw_prefactor',
    'force_law_powerlaw_stiffness_exponent',
    'force_law_powerlaw_stiffness_prefactor',
    'force_law_punch_exponent',
    'force_law_punch_prefactor',
    'force_law_punch_stiffness_exponent',
    'force_law_punch_stiffness_prefactor',
    'hertz_contact_radius',
    'hertz_contact_radius_from_force',
    'hertz_depth_from_force',
    'hertz_displacement_inside',
    'hertz_displacement_outside',
    'hertz_displacement_outside_elementary',
    'hertz_displacement_outside_series',
    'hertz_energy',
    'hertz_force',
    'hertz_max_pressure',
    'hertz_max_pressure_from_force',
    'hertz_mean_pressure',
    'hertz_pressure',
    'hertz_pressure_displacement',
    'hertz_pressure_displacement_outside',
    'hertz_pressure_force',
    'hertz_stiffness',
    'impact_contact_time',
    'impact_contact_time_density',
    'impact_force_scale',
    'impact_length_scale',
    'impact_max_contact_radius',
    'impact_max_contact_radius_density',
    'impact_max_depth',
    'impact_max_depth_density',
    'impact_max_force',
    'impact_max_force_density',
    'impact_max_pressure',
    'impact_max_pressure_density',
    'impact_sphere_mass',
    'impact_time_scale',
    'jkr_contact_radius_from_force',
    'jkr_depth',
    'jkr_force_from_radius',
    'jkr_pressure',
    'jkr_pull_off_depth_dc',
    'jkr_pull_off_depth_fc',
    'jkr_pull_off_force_dc',
    'jkr_pull_off_force_fc',
    'jkr_pull_off_radius_dc',
    'jkr_pull_off_radius_fc',
    'jkr_zero_load_radius',
    'line_depth_from_force',
    'line_force',
    'line_force_per_length_from_half_width',
    'line_half_width',
    'line_half_width_from_force',
    'line_max_pressure',
    'line_max_pressure_depth_width',
    'line_max_pressure_from_force',
    'line_max_pressure_from_half_width',
    'line_pressure',
    'line_stiffness',
    'line_stress_axis_max_shear',
    'line_stress_axis_max_shear_slope',
    'line_stress_axis_sigma_xx',
    'line_stress_axis_sigma_zz',
    'line_stress_axis_von_mises',
    'line_stress_axis_von_mises_slope',
    'line_stress_principal_max',
    'line_stress_principal_min',
    'line_stress_principal_shear',
    'line_stress_sigma_xx_core',
    'line_stress_sigma_xx_deep',
    'line_stress_sigma_xx_side',
    'line_stress_sigma_yy',
    'line_stress_sigma_zz_core',
    'line_stress_sigma_zz_deep',
    'line_stress_sigma_zz_side',
    'line_stress_tau_1_core',
    'line_stress_tau_1_deep',
    'line_stress_tau_1_side',
    'line_stress_tau_xz_core',
    'line_stress_tau_xz_deep',
    'line_stress_tau_xz_side',
    'line_stress_tau_xz_slope_x',
    'line_stress_tau_xz_slope_z',
    'line_stress_von_mises',
    'line_stress_von_mises_c_tau',
    'masing_unloading_force',
    'mdr_depth_of_line_load',
    'mdr_force',
    'mdr_kink_G',
    'mdr_kink_g',
    'mdr_kink_gprime',
    'mdr_kink_pressure',
    'mdr_normal_line_load',
    'mdr_stiffness',
    'mdr_tangential_line_load',
    'mdr_tangential_spring_shear',
    'mindlin_energy',
    'mindlin_energy_small',
    'paraboloid_g',
    'paraboloid_profile',
    'powerlaw_contact_radius',
    'powerlaw_depth_from_force',
    'powerlaw_displacement_far',
    'powerlaw_displacement_outside',
    'powerlaw_displacement_outside_integrand',
    'powerlaw_force',
    'powerlaw_force_from_radius',
    'powerlaw_g',
    'powerlaw_kappa',
    'powerlaw_kappa_asymptotic',
    'powerlaw_mean_pressure',
    'powerlaw_mean_pressure_from_depth',
    'powerlaw_pressure',
    'powerlaw_pressure_centre',
    'powerlaw_pressure_integrand',
    'powerlaw_pressure_n1',
    'powerlaw_pressure_n2',
    'powerlaw_pressure_n3',
    'powerlaw_pressure_n4',
    'powerlaw_pressure_normalized',
    'powerlaw_pressure_small_n',
    'powerlaw_profile',
    'powerlaw_punch_displacement_outside',
    'powerlaw_punch_force',
    'powerlaw_punch_mean_pressure',
    'powerlaw_punch_pressure',
    'punch_depth_from_force',
    'punch_pressure_displacement',
    'punch_pressure_displacement_outside',
    'punch_pressure_force',
    'punch_stiffness',
    'shear_modulus',
    'sphere_depth',
    'sphere_force_from_radius',
    'sphere_g',
    'sphere_lam_contact_radius',
    'sphere_lam_depth',
    'sphere_lam_force',
    'sphere_lam_pressure_pole',
    'sphere_pressure_atanh_kernel',
    'sphere_profile',
    'sphere_stiffness',
    'stress_axis_max_shear',
    'stress_axis_max_shear_bracket',
    'stress_axis_max_shear_slope',
    'stress_axis_sigma_xx',
    'stress_axis_sigma_xx_deep',
    'stress_axis_sigma_zz',
    'stress_hertz_max_orthogonal_shear',
    'stress_hertz_max_orthogonal_shear_r',
    'stress_hertz_max_orthogonal_shear_z',
    'stress_hertz_sigma_rr',
    'stress_hertz_sigma_rr_far',
    'stress_hertz_sigma_tt',
    'stress_hertz_sigma_tt_far',
    'stress_hertz_sigma_zz',
    'stress_hertz_tau_rz',
    'stress_spheroidal_cos_beta_inside',
    'stress_spheroidal_u',
    'stress_spheroidal_u_inside',
    'stress_von_mises',
    'strip_mean_pressure',
    'tangential_cone_displacement',
    'tangential_cone_energy',
    'tangential_cone_force',
    'tangential_cone_stick_radius',
    'tangential_cone_traction_stick',
    'tangential_modulus',
    'tangential_powerlaw_displacement',
    'tangential_powerlaw_energy',
    'tangential_powerlaw_energy_density',
    'tangential_powerlaw_energy_scale',
    'tangential_powerlaw_energy_small',
    'tangential_powerlaw_force',
    'tangential_powerlaw_stick_deficit',
    'tangential_powerlaw_stick_radius',
    'tangential_powerlaw_stick_radius_from_force',
    'tangential_powerlaw_traction_stick_centre',
    'tangential_powerlaw_traction_stick_integrand',
    'tangential_slide_onset',
    'tangential_stiffness',
    'tangential_stiffness_ratio',
    'tangential_traction_slip',
    'tangential_traction_stick',
    'uniform_pressure_displacement',
    'uniform_pressure_displacement_centre',
    'uniform_pressure_displacement_edge',
    'uniform_pressure_displacement_outside',
    'uniform_pressure_force',
    'worn_contact_radius',
    'worn_depth',
    'worn_displacement_inside',
    'worn_displacement_outside',
    'worn_force',
    'worn_force_from_radius',
    'worn_g',
    'worn_pressure',
    'worn_profile',
]


def adhesion_cone_depth(E_star, a, dgamma, theta):
    """Indentation depth d [m] of a cone in adhesive contact of radius a.

    Chapter: (5.55), adhesive. Derived from: (5.52), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*a*mpmath.tan(theta) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/mpmath.sqrt(E_star)


def adhesion_cone_force_from_radius(E_star, a, dgamma, theta):
    """Normal force F [N] of a cone in adhesive contact of radius a.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(dgamma) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*E_star*a**2*mpmath.tan(theta)


def adhesion_cone_g_slope(theta):
    """Slope g'(x) [1] of the MDR profile of the cone (the same at every x > 0).

    Chapter: (5.52) of r tan(theta). Derived from: the derivative of (5.52) for f = r
    tan(theta).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*mpmath.tan(theta)


def adhesion_cone_pull_off_depth_dc(E_star, dgamma, theta):
    """Depth d_c [m] at pull-off of a cone under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return -dgamma/(E_star*mpmath.tan(theta))


def adhesion_cone_pull_off_depth_fc(E_star, dgamma, theta):
    """Depth d_c [m] at pull-off of a cone under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 3*dgamma/(E_star*mpmath.tan(theta))


def adhesion_cone_pull_off_force_dc(E_star, dgamma, theta):
    """Pull-off force F_c [N] (negative) of a cone under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return -6*dgamma**2/(mpmath.pi*E_star*mpmath.tan(theta)**3)


def adhesion_cone_pull_off_force_fc(E_star, dgamma, theta):
    """Pull-off force F_c [N] (negative) of a cone under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return -54*dgamma**2/(mpmath.pi*E_star*mpmath.tan(theta)**3)


def adhesion_cone_pull_off_radius_dc(E_star, dgamma, theta):
    """Contact radius a_c [m] at pull-off of a cone under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 2*dgamma/(mpmath.pi*E_star*mpmath.tan(theta)**2)


def adhesion_cone_pull_off_radius_fc(E_star, dgamma, theta):
    """Contact radius a_c [m] at pull-off of a cone under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 18*dgamma/(mpmath.pi*E_star*mpmath.tan(theta)**2)


def adhesion_cone_zero_load_radius(E_star, dgamma, theta):
    """Contact radius a_0 [m] of a cone at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 32*dgamma/(mpmath.pi*E_star*mpmath.tan(theta)**2)


def adhesion_critical_elongation(E_star, a, dgamma):
    """Critical elongation Delta l [m] of the boundary spring, g(a) - d.

    Chapter: (5.55), energy balance. Derived from: G = Delta gamma solved for d.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_energy_release_rate_by_3d_route``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/mpmath.sqrt(E_star)


def adhesion_depth(E_star, a, dgamma, g_a):
    """Indentation depth d [m] of an adhesive contact of radius a, g(a) - Delta l.

    Chapter: (5.55), adhesive. Derived from: (5.55) with the stretched boundary spring.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    """
    return g_a - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/mpmath.sqrt(E_star)


def adhesion_depth_slope(E_star, a, dgamma, g_slope):
    """Dd/da [1] along an adhesive contact; 0 at pull-off under depth control.

    Chapter: (5.55), adhesive. Derived from: the derivative of d = g(a) - Delta l(a).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    """
    return g_slope - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(dgamma)/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def adhesion_displacement_outside_edge(E_star, a, dgamma, r):
    """Adhesive term of the surface displacement u_z(r) [m] outside the contact (r > a); add the non-adhesive displacement of radius a.

    Chapter: (5.60), adhesive. Derived from: (5.60) of the constant u_z = -Delta l on |x| <
    a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)*mpmath.asin(a/r)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star))


def adhesion_energy_release_rate(E_star, a, d, g_a):
    """Energy release rate G [J/m^2] at the edge of a contact of radius a at depth d.

    Chapter: (5.57), energy balance. Derived from: dU/da at fixed d over 2 pi a, U the work
    of (5.57) along the non-adhesive path plus a flat punch.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_energy_release_rate_by_3d_route``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*(d - g_a)**2/(mpmath.pi*a)


def adhesion_force_slope(E_star, a, dgamma, g_slope):
    """DF/da [N/m] along an adhesive contact; 0 at pull-off under force control.

    Chapter: (5.57), adhesive. Derived from: the derivative of (5.57) along d = g(a) - Delta
    l(a).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    """
    return -3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*mpmath.sqrt(a)*mpmath.sqrt(dgamma) + 2*E_star*a*g_slope


def adhesion_paraboloid_g_slope(R, x):
    """Slope g'(x) [1] of the MDR profile of the paraboloid, x >= 0.

    Chapter: (5.52) of r^2/(2R). Derived from: the derivative of (5.52) for f = r^2/(2R).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return 2*x/R


def adhesion_powerlaw_depth(E_star, a, dgamma, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law profile c_n r^n (n > 1/2) in adhesive contact of radius a.

    Chapter: (5.55), adhesive. Derived from: (5.52), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return a**n*c_n*kappa_n - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/mpmath.sqrt(E_star)


def adhesion_powerlaw_force_from_radius(E_star, a, dgamma, c_n, kappa_n, n):
    """Normal force F [N] of a power-law profile c_n r^n (n > 1/2) in adhesive contact of radius a.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(dgamma)*n/(n + 1) - 2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(dgamma)/(n + 1) + 2*E_star*a*a**n*c_n*kappa_n*n/(n + 1)


def adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """Slope g'(x) [1] of the MDR profile of the power law f = c_n r^n, x > 0.

    Chapter: (5.52), Problem 7(d). Derived from: the derivative of (5.52) for f = c_n r^n, g
    = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Printed in a stable form: x^n/x is 0/0 at x = 0 and overflows before x^(n - 1) does.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return c_n*kappa_n*n*x**(n - 1)


def adhesion_powerlaw_pull_off_depth_dc(E_star, dgamma, c_n, kappa_n, n):
    """Depth d_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(dgamma)*(2*n - 1)*mpmath.sqrt(((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))/(mpmath.sqrt(E_star)*n)


def adhesion_powerlaw_pull_off_depth_fc(E_star, dgamma, c_n, kappa_n, n):
    """Depth d_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(dgamma)*(2*n - 3)*mpmath.sqrt(((mpmath.mpf(9)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))/(mpmath.sqrt(E_star)*n)


def adhesion_powerlaw_pull_off_force_dc(E_star, dgamma, c_n, kappa_n, n):
    """Pull-off force F_c [N] (negative) of a power-law profile c_n r^n (n > 1/2) under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return -mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*mpmath.sqrt(dgamma)*(2*n + 1)*(((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))**(mpmath.mpf(3)/mpmath.mpf(2))/(n + 1)


def adhesion_powerlaw_pull_off_force_fc(E_star, dgamma, c_n, kappa_n, n):
    """Pull-off force F_c [N] (negative) of a power-law profile c_n r^n (n > 1/2) under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return -mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*mpmath.sqrt(dgamma)*(2*n - 1)*(((mpmath.mpf(9)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))**(mpmath.mpf(3)/mpmath.mpf(2))/(n + 1)


def adhesion_powerlaw_pull_off_radius_dc(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return ((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))


def adhesion_powerlaw_pull_off_radius_fc(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return ((mpmath.mpf(9)/mpmath.mpf(2))*mpmath.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))


def adhesion_powerlaw_zero_load_radius(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_0 [m] of a power-law profile c_n r^n (n > 1/2) at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return (2*mpmath.pi*dgamma*(n**2 + 2*n + 1)/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))


def adhesion_pressure_edge(E_star, a, dgamma, r):
    """Adhesive term of the contact pressure p(r) [Pa] for r < a (negative: tension; add the non-adhesive pressure of radius a).

    Chapter: (5.59), adhesive. Derived from: (5.59) with the jump of q(x) at x = a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Printed in a stable form: a^2 - r^2 loses the digits of a - r next to the edge, where
    the term is largest; written (a - r)(a + r).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return -mpmath.sqrt(2)*mpmath.sqrt(E_star)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a - r)*mpmath.sqrt(a + r))


def adhesion_punch_cycle_work(E_star, a, dgamma):
    """Work W [J] done on a flat punch of radius a over an approach-push-retract cycle: dissipated by the jump at pull-off (>= 0).

    Chapter: (5.57), Kendall. Derived from: the closed integral of (5.57) with g = 0 over
    the cycle.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_punch_cycle_work_is_kendalls``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return 2*mpmath.pi*a**2*dgamma


def adhesion_punch_pull_off_force(E_star, a, dgamma):
    """Pull-off force F_c [N] of a flat punch of radius a (Kendall), negative.

    Chapter: (5.57), Kendall. Derived from: (5.57) with g = 0 at d = -Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_kendall_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(dgamma)


def adhesion_sphere_g_slope(R, x):
    """Slope g'(x) [1] of the MDR profile of the exact sphere, 0 <= x < R.

    Chapter: (5.52), Sneddon's sphere. Derived from: the derivative of (5.52) for the
    spherical cap.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Printed in a stable form: atanh(x/R) as log1p(2x/(R - x))/2 and R^2 - x^2 as (R - x)(R +
    x), exact as x -> R where the slope is largest.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return R*x/((R - x)*(R + x)) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.log1p(2*x/(R - x))


def adhesion_tabor_parameter(E_star, R, dgamma, z0):
    """Tabor parameter mu_T [1]: JKR holds for mu_T > 5, DMT for mu_T < 0.1.

    Chapter: Tabor (1977). Derived from: the ratio of the JKR neck height to the range z0 (a
    definition).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_tabor_parameter``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    z0 : mpmath.mpf
        range of the adhesive forces (equilibrium distance) of the Tabor parameter [m]
    """
    return R**(mpmath.mpf(1)/mpmath.mpf(3))*dgamma**(mpmath.mpf(2)/mpmath.mpf(3))/(E_star**(mpmath.mpf(2)/mpmath.mpf(3))*z0)


def adhesion_worn_g_slope(R, b, x):
    """Slope g'(x) [1] of the MDR profile of the worn paraboloid for x > b (0 for x < b; infinite at the kink x = b+).

    Chapter: (5.52), Problem 8. Derived from: the derivative of (5.52) for f = (r^2 -
    b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Printed in a stable form: x^2 - b^2 as (x - b)(x + b), exact next to the kink.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (-b**2 + 2*x**2)/(R*mpmath.sqrt(-b + x)*mpmath.sqrt(b + x))


def bodies_crossed_cylinders_curvature_1(R1, R2, alpha):
    """Larger principal curvature [1/m] of the gap of two cylinders crossed at alpha.

    Chapter: (5.32), (5.33), any angle. Derived from: the larger eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    alpha : mpmath.mpf
        angle between the axes of two crossed cylinders [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt((mpmath.cos(2*alpha)/R2 + 1/R1)**2 + mpmath.sin(2*alpha)**2/R2**2) + (mpmath.mpf(1)/mpmath.mpf(2))/R2 + (mpmath.mpf(1)/mpmath.mpf(2))/R1


def bodies_crossed_cylinders_curvature_2(R1, R2, alpha):
    """Smaller principal curvature [1/m] of the gap of two cylinders crossed at alpha.

    Chapter: (5.32), (5.33), any angle. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Printed in a stable form: written with the curvatures 1/R so that R = inf (flat) works;
    the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det
    a sum of products, positive for convex bodies: no cancellation.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    alpha : mpmath.mpf
        angle between the axes of two crossed cylinders [rad]
    """
    return 2*mpmath.sin(alpha)**2/(R1*R2*(mpmath.sqrt((mpmath.cos(2*alpha)/R2 + 1/R1)**2 + mpmath.sin(2*alpha)**2/R2**2) + 1/R2 + 1/R1))


def bodies_crossed_cylinders_gaussian_radius(R1, R2, alpha):
    """Gaussian radius R~ [m] of two cylinders crossed at alpha (sqrt(R1 R2) at alpha = pi/2).

    Chapter: (5.33), any angle. Derived from: 1/sqrt(kappa_1 kappa_2) of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    alpha : mpmath.mpf
        angle between the axes of two crossed cylinders [rad]
    """
    return mpmath.sqrt(R1)*mpmath.sqrt(R2)/abs(mpmath.sin(alpha))


def bodies_effective_modulus(E1, nu1, E2, nu2):
    """Effective modulus E* [Pa] of two elastic bodies.

    Chapter: (5.26). Derived from: the sum of the two surface displacements (5.6), (5.7)
    under one pressure.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Printed in a stable form: 1/E* as the sum of the compliances, which accepts E2 = inf
    (rigid), with 1 - nu^2 = (1 - nu)(1 + nu) exact in floating point for nu near -1.

    Parameters
    ----------
    E1 : mpmath.mpf
        Young's modulus of body 1 [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    E2 : mpmath.mpf
        Young's modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return 1/((1 - nu2)*(nu2 + 1)/E2 + (1 - nu1)*(nu1 + 1)/E1)


def bodies_effective_modulus_rigid(E, nu):
    """Effective modulus E* [Pa] of an elastic body against a rigid one.

    Chapter: (5.8), (5.26) with E2 -> inf. Derived from: the limit E2 -> inf of (5.26).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Printed in a stable form: 1 - nu^2 = (1 - nu)(1 + nu) is exact in floating point for nu
    near -1, where 1 - nu^2 cancels.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return E/((1 - nu)*(nu + 1))


def bodies_effective_radius(R1, R2):
    """Effective radius R [m] of two spheres (negative radius: concave).

    Chapter: (5.27). Derived from: the sum of the two gaps r^2/(2 R_i).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_radius_by_gap``.

    Printed in a stable form: the sum of the curvatures accepts R = inf (flat).

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    """
    return 1/(1/R2 + 1/R1)


def bodies_gaussian_approx_area(R1, R2, d):
    """Contact area A = pi a b [m^2] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.29), approximation. Derived from: (5.28) in pi a b.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.pi*mpmath.sqrt(R1)*mpmath.sqrt(R2)*d


def bodies_gaussian_approx_depth_from_force(E_star, F, R1, R2):
    """Indentation depth d [m] of the elliptic contact under the force F (Gaussian-radius approximation).

    Chapter: (5.24) with (5.30), approximation. Derived from: the force of (5.31) over
    (5.28) solved for d.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*6**(mpmath.mpf(2)/mpmath.mpf(3))*F**(mpmath.mpf(2)/mpmath.mpf(3))/(E_star**(mpmath.mpf(2)/mpmath.mpf(3))*R1**(mpmath.mpf(1)/mpmath.mpf(6))*R2**(mpmath.mpf(1)/mpmath.mpf(6)))


def bodies_gaussian_approx_force(E_star, R1, R2, d):
    """Normal force F [N] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.23) with (5.30), approximation. Derived from: the ellipsoidal pressure
    (5.31) integrated over the ellipse (5.28).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*R1**(mpmath.mpf(1)/mpmath.mpf(4))*R2**(mpmath.mpf(1)/mpmath.mpf(4))*d**(mpmath.mpf(3)/mpmath.mpf(2))


def bodies_gaussian_approx_max_pressure(E_star, R1, R2, d):
    """Maximum pressure p0 [Pa] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.22) with (5.30), approximation. Derived from: (5.22) with R = R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return 2*E_star*mpmath.sqrt(d)/(mpmath.pi*R1**(mpmath.mpf(1)/mpmath.mpf(4))*R2**(mpmath.mpf(1)/mpmath.mpf(4)))


def bodies_gaussian_approx_pressure(E_star, R1, R2, d, x, y):
    """Pressure p(x, y) [Pa] of the elliptic contact (Gaussian-radius approximation; x along R1, 0 outside the ellipse).

    Chapter: (5.31), approximation. Derived from: (5.31) with (5.28) and the p0 of (5.22) at
    R = R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return 2*E_star*mpmath.sqrt(d)*mpmath.sqrt(max(0, 1 - y**2/(R2*d) - x**2/(R1*d)))/(mpmath.pi*R1**(mpmath.mpf(1)/mpmath.mpf(4))*R2**(mpmath.mpf(1)/mpmath.mpf(4)))


def bodies_gaussian_approx_semi_axis_1(R1, d):
    """Semi-axis a [m] along the principal radius R1 of the elliptic contact in the chapter's rough estimate.

    Chapter: (5.28), approximation. Derived from: (5.21) with R = R1.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.sqrt(R1)*mpmath.sqrt(d)


def bodies_gaussian_approx_semi_axis_2(R2, d):
    """Semi-axis b [m] along the principal radius R2 of the elliptic contact in the chapter's rough estimate.

    Chapter: (5.28), approximation. Derived from: (5.21) with R = R2.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.sqrt(R2)*mpmath.sqrt(d)


def bodies_gaussian_radius(R1, R2):
    """Gaussian radius R~ [m] of a gap with the principal radii R1, R2.

    Chapter: (5.30). Derived from: the sphere with the same Gaussian curvature kappa_1
    kappa_2.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    """
    return mpmath.sqrt(R1)*mpmath.sqrt(R2)


def bodies_principal_curvature_1(R1a, R1b, R2a, R2b, omega):
    """Larger principal curvature kappa_1 [1/m] of the gap between two bodies.

    Chapter: (5.32), Problem 2, general. Derived from: the larger eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1a : mpmath.mpf
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : mpmath.mpf
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : mpmath.mpf
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : mpmath.mpf
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : mpmath.mpf
        angle between the first principal directions of the two bodies [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt((-1/R2b + 1/R2a)**2*mpmath.sin(2*omega)**2 + ((-1/R2b + 1/R2a)*mpmath.cos(2*omega) - 1/R1b + 1/R1a)**2) + (mpmath.mpf(1)/mpmath.mpf(2))/R2b + (mpmath.mpf(1)/mpmath.mpf(2))/R2a + (mpmath.mpf(1)/mpmath.mpf(2))/R1b + (mpmath.mpf(1)/mpmath.mpf(2))/R1a


def bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega):
    """Smaller principal curvature kappa_2 [1/m] of the gap between two bodies.

    Chapter: (5.32), Problem 2, general. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Printed in a stable form: written with the curvatures 1/R so that R = inf (flat) works;
    the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det
    a sum of products, positive for convex bodies: no cancellation.

    Parameters
    ----------
    R1a : mpmath.mpf
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : mpmath.mpf
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : mpmath.mpf
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : mpmath.mpf
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : mpmath.mpf
        angle between the first principal directions of the two bodies [rad]
    """
    return (2*(1/(R1b*R2a) + 1/(R1a*R2b))*mpmath.cos(omega)**2 + 2*(1/(R1b*R2b) + 1/(R1a*R2a))*mpmath.sin(omega)**2 + 2/(R2a*R2b) + 2/(R1a*R1b))/(mpmath.sqrt((-1/R2b + 1/R2a)**2*mpmath.sin(2*omega)**2 + ((-1/R2b + 1/R2a)*mpmath.cos(2*omega) - 1/R1b + 1/R1a)**2) + 1/R2b + 1/R2a + 1/R1b + 1/R1a)


def bodies_problem2_force(E, nu, R, d):
    """Normal force F [N] of two equal cylinders of one material crossed at pi/4 (Gaussian-radius approximation).

    Chapter: Problem 2. Derived from: (5.23) with (5.26) and R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): with R~ = sqrt(2) R the factor is
    2^(5/4)/3, not 2^(7/4)/3 (the printed force is sqrt(2) times too large)

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    nu : mpmath.mpf
        Poisson's ratio [1]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return -2*2**(mpmath.mpf(1)/mpmath.mpf(4))*E*mpmath.sqrt(R)*d**(mpmath.mpf(3)/mpmath.mpf(2))/(3*nu**2 - 3)


def bodies_problem2_gaussian_radius(R):
    """Gaussian radius R~ [m] of two equal cylinders crossed at pi/4.

    Chapter: Problem 2. Derived from: 1/sqrt(det) of the gap's Hessian.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): with the principal radii halved, R~ =
    sqrt(2) R, not 2 sqrt(2) R (check: R/sin(alpha) is R at alpha = pi/2, the sphere of
    (5.33))

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return mpmath.sqrt(2)*R


def bodies_problem2_principal_radius_1(R):
    """Smaller principal radius [m] of two equal cylinders crossed at pi/4.

    Chapter: Problem 2. Derived from: 1/kappa_1 of the gap's Hessian.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): the chapter takes the eigenvalues of the
    coefficient matrix M of h = x^T M x, which are half the principal curvatures (the
    Hessian is 2M): R_1,2 = R/(1 +- 1/sqrt(2)), not 2R/(1 +- 1/sqrt(2))

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return -mpmath.sqrt(2)*R + 2*R


def bodies_problem2_principal_radius_2(R):
    """Larger principal radius [m] of two equal cylinders crossed at pi/4.

    Chapter: Problem 2. Derived from: 1/kappa_2 of the gap's Hessian.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): eigenvalues of M instead of the Hessian 2M:
    the radius is R/(1 - 1/sqrt(2)), half the printed one

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return mpmath.sqrt(2)*R + 2*R


def boussinesq_sigma_xx(F, nu, x, y, z):
    """Stress sigma_xx [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.41). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + 2*nu*z**3*(x**2 + y**2 + z**2) + 4*nu*z**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*nu*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)) + 3*x**2*z**3 + 6*x**2*z**2*mpmath.sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - z**3*(x**2 + y**2 + z**2) - 2*z**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + (x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))/(mpmath.pi*(z + mpmath.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_sigma_xy(F, nu, x, y, z):
    """Stress sigma_xy [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.44). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*F*x*y*(2*nu*z*(x**2 + y**2 + z**2) + 4*nu*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + 3*z**3 + 6*z**2*mpmath.sqrt(x**2 + y**2 + z**2) + 2*z*(x**2 + y**2 + z**2) - 2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)))/(mpmath.pi*(z + mpmath.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_sigma_xz(F, nu, x, y, z):
    """Stress sigma_xz [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.46). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Differs from the print (see docs/errata.md): the sign: with the force F acting in +z
    (into the body, z > 0 in the body) the derivation gives tau_xz = -3 F x z^2/(2 pi R^5);
    the print has +3 F x z^2/(2 pi R^5), which together with the printed (5.43) violates the
    equilibrium d(tau_xz)/dx + d(tau_yz)/dy + d(sigma_zz)/dz = 0

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(3)/mpmath.mpf(2)*F*x*z**2/(mpmath.pi*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_sigma_yy(F, nu, x, y, z):
    """Stress sigma_yy [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.42). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*nu*z*(x**2 + y**2 + z**2)**2 - 2*nu*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)) + 3*x**2*z**3 + 6*x**2*z**2*mpmath.sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + 3*z**5 + 6*z**4*mpmath.sqrt(x**2 + y**2 + z**2) - 6*z**2*(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*z*(x**2 + y**2 + z**2)**2 + (x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))/(mpmath.pi*(z + mpmath.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_sigma_yz(F, nu, x, y, z):
    """Stress sigma_yz [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.45). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Differs from the print (see docs/errata.md): the sign: with the force F acting in +z
    (into the body, z > 0 in the body) the derivation gives tau_yz = -3 F y z^2/(2 pi R^5);
    the print has +3 F y z^2/(2 pi R^5), which together with the printed (5.43) violates the
    equilibrium d(tau_xz)/dx + d(tau_yz)/dy + d(sigma_zz)/dz = 0

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(3)/mpmath.mpf(2)*F*y*z**2/(mpmath.pi*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_sigma_zz(F, nu, x, y, z):
    """Stress sigma_zz [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.43). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(3)/mpmath.mpf(2)*F*z**3/(mpmath.pi*(x**2 + y**2 + z**2)**(mpmath.mpf(5)/mpmath.mpf(2)))


def boussinesq_surface_prefactor(E_star):
    """Prefactor 1/(pi E*) [1/Pa] of the surface Green's function: u_z = F/(pi E* rho).

    Chapter: (5.7). Derived from: (5.6) times rho/F with E/(1 - nu^2) = E*.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_prefactor_against_the_point_force``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    """
    return 1/(mpmath.pi*E_star)


def boussinesq_surface_ux(E, F, nu, x, y):
    """Surface displacement u_x [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.4). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*x*(nu + 1)*(2*nu - 1)/(mpmath.pi*E*(x**2 + y**2))


def boussinesq_surface_uy(E, F, nu, x, y):
    """Surface displacement u_y [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.5). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*y*(nu + 1)*(2*nu - 1)/(mpmath.pi*E*(x**2 + y**2))


def boussinesq_surface_uz(E, F, nu, x, y):
    """Surface displacement u_z [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.6). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return -F*(nu - 1)*(nu + 1)/(mpmath.pi*E*mpmath.sqrt(x**2 + y**2))


def boussinesq_ux(E, F, nu, x, y, z):
    """Displacement u_x [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.1). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*(nu + 1)*(x*z/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - x*(1 - 2*nu)/((z + mpmath.sqrt(x**2 + y**2 + z**2))*mpmath.sqrt(x**2 + y**2 + z**2)))/(mpmath.pi*E)


def boussinesq_uy(E, F, nu, x, y, z):
    """Displacement u_y [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.2). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*(nu + 1)*(y*z/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) - y*(1 - 2*nu)/((z + mpmath.sqrt(x**2 + y**2 + z**2))*mpmath.sqrt(x**2 + y**2 + z**2)))/(mpmath.pi*E)


def boussinesq_uz(E, F, nu, x, y, z):
    """Displacement u_z [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.3). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    F : mpmath.mpf
        normal force [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*(nu + 1)*(z**2/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + (2 - 2*nu)/mpmath.sqrt(x**2 + y**2 + z**2))/(mpmath.pi*E)


def cattaneo_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a paraboloid under normal force F and tangential force F_x.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: F_x = mu (F_N(a) - F_N(c))
    solved for c, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Printed in a stable form: 1 - (1 - F_x/(mu F))^(2/3) cancels as F_x -> 0: -expm1(2/3
    log1p(-F_x/(mu F))).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return -mpmath.mpf(3)/mpmath.mpf(4)*F*mu_f*mpmath.expm1((mpmath.mpf(2)/mpmath.mpf(3))*mpmath.log1p(-F_x/(F*mu_f)))/(G_star*a)


def cattaneo_force(a, R, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a paraboloid displaced by u_x (monotonic, constant load).

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: sum of the stuck and
    sliding springs.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Printed in a stable form: mu (F_N(a) - F_N(c)) cancels as u_x -> 0; a^3 - c^3 = (a^2 -
    c^2)(a^2 + a c + c^2)/(a + c) with a^2 - c^2 = R G* u_x/(mu E*) exactly.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*G_star*u_x*(a**2 + (E_star*a**2*mu_f - G_star*R*u_x)/(E_star*mu_f) + a*mpmath.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(mpmath.sqrt(E_star)*mpmath.sqrt(mu_f)))/(a + mpmath.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(mpmath.sqrt(E_star)*mpmath.sqrt(mu_f)))


def cattaneo_stick_radius(a, R, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a paraboloid (f = r^2/(2R)) displaced by u_x at constant load.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: g(c) = d - G* u_x/(mu E*),
    g = x^2/R.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return mpmath.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(mpmath.sqrt(E_star)*mpmath.sqrt(mu_f))


def cattaneo_stick_radius_from_force(a, F, mu_f, F_x):
    """Stick radius c [m] of a paraboloid under the normal force F and tangential force F_x.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^3.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return a*(F*mu_f - F_x)**(mpmath.mpf(1)/mpmath.mpf(3))/(F**(mpmath.mpf(1)/mpmath.mpf(3))*mu_f**(mpmath.mpf(1)/mpmath.mpf(3)))


def cattaneo_traction_slip(r, a, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the slip zone c < r < a of a paraboloid (mu p(r)).

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the sliding
    springs' line load mu E* (d - g).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return 2*E_star*mu_f*mpmath.sqrt(a**2 - r**2)/(mpmath.pi*R)


def cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a paraboloid.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the tangential
    line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Printed in a stable form: the difference of the two square roots cancels as c -> a.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    c : mpmath.mpf
        radius of the stick zone [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return 2*E_star*mu_f*(a - c)*(a + c)/(mpmath.pi*R*(mpmath.sqrt(a - r)*mpmath.sqrt(a + r) + mpmath.sqrt(c - r)*mpmath.sqrt(c + r)))


def cerruti_surface_ux(G, Q, nu, x, y):
    """Surface displacement u_x [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*Q*(-nu*y**2 + x**2 + y**2)/(mpmath.pi*G*(x**2 + y**2)**(mpmath.mpf(3)/mpmath.mpf(2)))


def cerruti_surface_uy(G, Q, nu, x, y):
    """Surface displacement u_y [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*Q*nu*x*y/(mpmath.pi*G*(x**2 + y**2)**(mpmath.mpf(3)/mpmath.mpf(2)))


def cerruti_surface_uz(G, Q, nu, x, y):
    """Surface displacement u_z [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(4)*Q*x*(2*nu - 1)/(mpmath.pi*G*(x**2 + y**2))


def cerruti_ux(G, Q, nu, x, y, z):
    """Displacement u_x [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*Q*(x**2/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + (1 - 2*nu)*(-x**2/((z + mpmath.sqrt(x**2 + y**2 + z**2))**2*mpmath.sqrt(x**2 + y**2 + z**2)) + 1/(z + mpmath.sqrt(x**2 + y**2 + z**2))) + 1/mpmath.sqrt(x**2 + y**2 + z**2))/(mpmath.pi*G)


def cerruti_uy(G, Q, nu, x, y, z):
    """Displacement u_y [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*Q*(-x*y*(1 - 2*nu)/((z + mpmath.sqrt(x**2 + y**2 + z**2))**2*mpmath.sqrt(x**2 + y**2 + z**2)) + x*y/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)))/(mpmath.pi*G)


def cerruti_uz(G, Q, nu, x, y, z):
    """Displacement u_z [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : mpmath.mpf
        shear modulus [Pa]
    Q : mpmath.mpf
        tangential point force in +x at the origin of the surface [N]
    nu : mpmath.mpf
        Poisson's ratio [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*Q*(x*z/(x**2 + y**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2)) + x*(1 - 2*nu)/((z + mpmath.sqrt(x**2 + y**2 + z**2))*mpmath.sqrt(x**2 + y**2 + z**2)))/(mpmath.pi*G)


def cone_contact_radius(d, theta):
    """Contact radius a [m] of a rigid cone at depth d.

    Chapter: (5.38), Problem 7(c). Derived from: (5.38) solved for a.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    d : mpmath.mpf
        indentation depth [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 2*d/(mpmath.pi*mpmath.tan(theta))


def cone_contact_radius_from_force(E_star, F, theta):
    """Contact radius a [m] of a rigid cone under the force F.

    Chapter: (5.38), (5.40). Derived from: (5.38) at the depth of (5.40) inverted.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return mpmath.sqrt(2)*mpmath.sqrt(F)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*mpmath.sqrt(mpmath.tan(theta)))


def cone_depth(a, theta):
    """Indentation depth d [m] of a rigid cone at the contact radius a.

    Chapter: (5.38). Derived from: flat punches superposed to match the cone's surface.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*a*mpmath.tan(theta)


def cone_depth_from_force(E_star, F, theta):
    """Indentation depth d [m] of a rigid cone under the force F.

    Chapter: (5.40), inverted. Derived from: (5.40) solved for d.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(F)*mpmath.sqrt(mpmath.tan(theta))/mpmath.sqrt(E_star)


def cone_force(E_star, d, theta):
    """Normal force F [N] of a rigid cone at depth d.

    Chapter: (5.40). Derived from: the forces 2 a' E* dd of the superposed punches.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    d : mpmath.mpf
        indentation depth [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 2*E_star*d**2/(mpmath.pi*mpmath.tan(theta))


def cone_g(theta, x):
    """MDR profile g(x) [m] of the cone f = r tan(theta), x >= 0 (g is even in x).

    Chapter: (5.52) of f = r tan(theta). Derived from: (5.52) of r tan(theta).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_g_against_the_mdr_transform``.

    Parameters
    ----------
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    x : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*x*mpmath.tan(theta)


def cone_mean_pressure(E_star, theta):
    """Mean pressure F/(pi a^2) [Pa] of a rigid cone (independent of the depth).

    Chapter: (5.40)/(pi a^2). Derived from: (5.40) divided by the contact area.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.tan(theta)


def cone_pressure(E_star, d, theta, r):
    """Contact pressure p(r) [Pa] of a rigid cone at depth d, for 0 < r <= a (log-singular at r = 0).

    Chapter: (5.39). Derived from: the pressures (5.9) of the superposed punches.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Printed in a stable form: arccosh(a/r) = 2 asinh(sqrt((a - r)/(2 r))): a/r overflows for
    a flat cone (theta = 1e-300: a = 6e296 m) where the pressure is a float, and arccosh of
    1 + (a - r)/r loses the digits of a - r next to the rim.

    Differs from the print (see docs/errata.md): the print has a spurious minus sign: the
    pressure is positive in compression, p = E* d/(pi a) arccosh(a/r) with E* = E/(1 -
    nu^2), as (5.9), (5.15) and the chapter's own Problem 7(c) have it

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    d : mpmath.mpf
        indentation depth [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*mpmath.tan(theta)*mpmath.asinh((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(2*d/(mpmath.pi*mpmath.tan(theta)) - r)/mpmath.sqrt(r))


def cone_profile(theta, r):
    """Height f(r) [m] of the cone above its tip (the profile whose g is cone_g).

    Chapter: (5.52). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return r*mpmath.tan(theta)


def cone_stiffness(E_star, d, theta):
    """Differential stiffness dF/dd [N/m] of a rigid cone at depth d.

    Chapter: Problem 5. Derived from: the derivative of (5.40).

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    d : mpmath.mpf
        indentation depth [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 4*E_star*d/(mpmath.pi*mpmath.tan(theta))


def contact_mean_pressure(A, F):
    """Mean pressure F/A [Pa] over a contact of area A.

    Chapter: (5.17). Derived from: the definition of the mean pressure.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_area``.

    Parameters
    ----------
    A : mpmath.mpf
        contact area [m^2]
    F : mpmath.mpf
        normal force [N]
    """
    return F/A


def coulomb_sliding_force(mu_f, F):
    """Tangential force mu F [N] of full sliding under the normal force F (Coulomb's limit).

    Chapter: Coulomb's law, from the springs (not in the chapter). Derived from: the spring
    sum at c = 0 over the normal force (5.57).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_sliding_force_is_the_spring_sum_at_full_slip``.

    Parameters
    ----------
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F : mpmath.mpf
        normal force [N]
    """
    return F*mu_f


def disc_mean_pressure(F, a):
    """Mean pressure F/(pi a^2) [Pa] over a circular contact of radius a.

    Chapter: (5.17). Derived from: the definition of the mean pressure over a disc.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_disc``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    a : mpmath.mpf
        contact radius [m]
    """
    return F/(mpmath.pi*a**2)


def disc_pressure(a, n_p, p0, r):
    """Prescribed pressure p0 (1 - r^2/a^2)^n_p [Pa] on a disc of radius a, r < a.

    Chapter: (5.9), (5.15), Problem 6. Derived from: the distributions of section 5.1.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_disc_pressure_force``.

    Printed in a stable form: 1 - r^2/a^2 cancels towards the edge r -> a (1e-13 at r =
    0.9995 a); (a - r)(a + r)/a^2 does not.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n_p : mpmath.mpf
        exponent of a prescribed pressure p0*(1 - r^2/a^2)^n_p on a disc (section 5.1) [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return p0*((a - r)*(a + r)/a**2)**n_p


def ellipse_area(R1, d, t_ba):
    """Contact area pi a b [m^2] of an elliptical contact.

    Chapter: (5.29), exact. Derived from: pi a b with a, b matched.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi**2*R1*d*t_ba*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)/((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))


def ellipse_depth_from_force(E_star, F, R1, t_ba):
    """Indentation depth d [m] of an elliptical contact under the force F.

    Chapter: (5.23), exact, inverted. Derived from: the exact force solved for d.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_controlled_roundtrip``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return 6**(mpmath.mpf(2)/mpmath.mpf(3))*F**(mpmath.mpf(2)/mpmath.mpf(3))*((mpmath.mpf(1)/mpmath.mpf(8))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(8))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/(mpmath.pi*E_star**(mpmath.mpf(2)/mpmath.mpf(3))*R1**(mpmath.mpf(1)/mpmath.mpf(3))*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)**(mpmath.mpf(1)/mpmath.mpf(3)))


def ellipse_equivalent_radius(R1, t_ba):
    """Radius R_e [m] of the sphere whose Hertz force (5.23) equals the elliptical contact's at every depth (compare with the Gaussian radius (5.30)).

    Chapter: (5.23), exact. Derived from: the exact force equated to (5.23).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(8))*mpmath.pi**3*R1*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)/((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))**3


def ellipse_force(E_star, R1, d, t_ba):
    """Normal force F [N] of an elliptical Hertz contact at depth d.

    Chapter: (5.23), exact. Derived from: (5.31) integrated over the ellipse, with a and p0
    from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*mpmath.sqrt(2)*mpmath.pi**(mpmath.mpf(3)/mpmath.mpf(2))*E_star*mpmath.sqrt(R1)*d**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))**(mpmath.mpf(3)/mpmath.mpf(2))


def ellipse_max_pressure(E_star, R1, d, t_ba):
    """Maximum pressure p0 [Pa] of an elliptical contact at depth d.

    Chapter: (5.31), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*E_star*mpmath.sqrt(d)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(R1)*t_ba*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)))


def ellipse_mean_pressure(E_star, R1, d, t_ba):
    """Mean pressure F/(pi a b) [Pa] of an elliptical contact.

    Chapter: (5.17), exact. Derived from: the force divided by the area pi a b.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.sqrt(2)*E_star*mpmath.sqrt(d)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(R1)*t_ba*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)))


def ellipse_pressure(E_star, R1, d, t_ba, x, y):
    """Contact pressure p(x, y) [Pa] of an elliptical contact (0 outside).

    Chapter: (5.31). Derived from: (5.31) with a, b, p0 from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_pressure_field``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return mpmath.sqrt(2)*E_star*mpmath.sqrt(d)*mpmath.sqrt(max(0, 1 - 2*x**2*((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/(mpmath.pi*R1*d*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)) - 2*y**2*((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/(mpmath.pi*R1*d*t_ba**2*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))))/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(R1)*t_ba*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2)))


def ellipse_radius_ratio(t_ba):
    """Ratio R1/R2 >= 1 of the principal radii that gives the axis ratio t = b/a.

    Chapter: (5.31)-(5.32), exact. Derived from: (5.7) over (5.31) matched to the gap
    (5.32): the y^2 and x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2)/(t_ba**2*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))


def ellipse_semi_major(R1, d, t_ba):
    """Semi-axis a [m] (along x, the direction of R1 >= R2) of an elliptical contact.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32): the x^0 and
    x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(R1)*mpmath.sqrt(d)*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))


def ellipse_semi_minor(R1, d, t_ba):
    """Semi-axis b = t a [m] (along y, the direction of R2) of an elliptical contact.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(R1)*mpmath.sqrt(d)*t_ba*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))


def ellipse_stiffness(E_star, R1, d, t_ba):
    """Differential stiffness dF/dd [N/m] of an elliptical contact.

    Chapter: (5.13), exact. Derived from: the derivative of the force at fixed R1, R2.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_stiffness_by_derivative``.

    Printed in a stable form: K(m) and E(m) are written through D = (K - E)/m and B = (E -
    (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is
    0/0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.pi**(mpmath.mpf(3)/mpmath.mpf(2))*E_star*mpmath.sqrt(R1)*mpmath.sqrt(d)*mpmath.sqrt(mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))/((mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), 1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (2,), 1 - t_ba**2))**(mpmath.mpf(3)/mpmath.mpf(2))


def ellipse_stress_I_x(a, b_e, lam_e):
    """I_x [m^-3] = int_lam^inf dw/((a^2 + w) Delta(w)) as Carlson's (2/3) R_D.

    Chapter: (5.31). Derived from: w = lam + t in Carlson's definition of R_D.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.elliprd(b_e**2 + lam_e, lam_e, a**2 + lam_e)


def ellipse_stress_I_y(a, b_e, lam_e):
    """I_y [m^-3] = int_lam^inf dw/((b^2 + w) Delta(w)) as Carlson's (2/3) R_D.

    Chapter: (5.31). Derived from: w = lam + t in Carlson's definition of R_D.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.elliprd(a**2 + lam_e, lam_e, b_e**2 + lam_e)


def ellipse_stress_axis_shear_x(a, b_e, nu, p0, z):
    """Principal shear (sigma_xx - sigma_zz)/2 [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_shear_x_slope(a, b_e, nu, p0, z):
    """D/dz of the principal shear (sigma_xx - sigma_zz)/2 [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return a*b_e*nu*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*nu*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) - mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - mpmath.mpf(3)/mpmath.mpf(2)*a*b_e*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2)


def ellipse_stress_axis_shear_y(a, b_e, nu, p0, z):
    """Principal shear (sigma_yy - sigma_zz)/2 [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_shear_y_slope(a, b_e, nu, p0, z):
    """D/dz of the principal shear (sigma_yy - sigma_zz)/2 [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return a*b_e*nu*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*nu*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - mpmath.mpf(3)/mpmath.mpf(2)*a*b_e*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) - mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(1)/mpmath.mpf(3))*a*b_e*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2)


def ellipse_stress_axis_sigma_xx(a, b_e, nu, p0, z):
    """Normal stress sigma_xx [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2)))


def ellipse_stress_axis_sigma_yy(a, b_e, nu, p0, z):
    """Normal stress sigma_yy [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2)))


def ellipse_stress_axis_sigma_zz(a, b_e, p0, z):
    """Normal stress sigma_zz [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_von_mises(a, b_e, nu, p0, z):
    """Von Mises stress (5.50) [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))))**2)


def ellipse_stress_axis_von_mises_slope(a, b_e, nu, p0, z):
    """D/dz of the von Mises stress (5.50) [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return ((mpmath.mpf(1)/mpmath.mpf(4))*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))*(-4*a*b_e*nu*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) - 4*a*b_e*nu*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(4)/mpmath.mpf(3)*a*b_e*nu*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) + 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + 2*a*b_e*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(4)/mpmath.mpf(3)*a*b_e*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2)) + (mpmath.mpf(1)/mpmath.mpf(4))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))*(4*a*b_e*nu*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) + 4*a*b_e*nu*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(4)/mpmath.mpf(3))*a*b_e*nu*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))) - 2*a*b_e*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(4)/mpmath.mpf(3))*a*b_e*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2)) + (mpmath.mpf(1)/mpmath.mpf(4))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))))*((mpmath.mpf(4)/mpmath.mpf(3))*a*b_e*nu*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(4)/mpmath.mpf(3)*a*b_e*nu*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - mpmath.mpf(4)/mpmath.mpf(3)*a*b_e*p0*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(4)/mpmath.mpf(3))*a*b_e*p0*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2) + 2*a*b_e*p0*(2*nu - 1)*(-z/mpmath.sqrt(b_e**2 + z**2) - z/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))**2)))/mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))))**2) - 2*(-mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*nu*p0*z*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))) + (mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*p0*z*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))) + (mpmath.mpf(1)/mpmath.mpf(4))*(2*a*b_e*nu*p0*z - 2*a*b_e*p0*z)*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2)))))/(mpmath.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))))**2)) - 2*((mpmath.mpf(1)/mpmath.mpf(2))*a*b_e*nu*p0*z*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))) - mpmath.mpf(1)/mpmath.mpf(2)*a*b_e*p0*z*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2))) + (mpmath.mpf(1)/mpmath.mpf(4))*(-2*a*b_e*nu*p0*z + 2*a*b_e*p0*z)*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2)))))/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + z**2)*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*(-mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) - a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0/(mpmath.sqrt(a**2 + z**2)*mpmath.sqrt(b_e**2 + z**2)))**2 + (mpmath.mpf(1)/mpmath.mpf(2))*((mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*nu*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*nu*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - mpmath.mpf(2)/mpmath.mpf(3)*a*b_e*p0*z*mpmath.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (mpmath.mpf(2)/mpmath.mpf(3))*a*b_e*p0*z*mpmath.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(b_e**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(mpmath.sqrt(a**2 + z**2)*(mpmath.sqrt(a**2 + z**2) + mpmath.sqrt(b_e**2 + z**2))))**2))


def ellipse_stress_cubic_lam(a, b_e, z, w1_e, d_e, lam_e):
    """Lam P2(lam) - z^2 (a^2 + lam)(b^2 + lam) [m^6], zero at lam.

    Chapter: (5.31). Derived from: g(lam) = 0 times lam (a^2 + lam)(b^2 + lam).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    z : mpmath.mpf
        depth below the surface [m]
    w1_e : mpmath.mpf
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    return lam_e*(lam_e - w1_e)*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e)*(b_e**2 + lam_e)


def ellipse_stress_cubic_lam_slope(a, b_e, z, w1_e, d_e, lam_e):
    """D/dlam of ellipse_stress_cubic_lam [m^4].

    Chapter: (5.31). Derived from: its derivative.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    z : mpmath.mpf
        depth below the surface [m]
    w1_e : mpmath.mpf
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    return lam_e*(lam_e - w1_e) + lam_e*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e) - z**2*(b_e**2 + lam_e) + (lam_e - w1_e)*(d_e + lam_e - w1_e)


def ellipse_stress_cubic_q(z, w1_e, w1_a, w1_b, d_e, q_e):
    """The same cubic [m^6] in q = lam - w1 (accurate where lam is close to w1 >= 0).

    Chapter: (5.31). Derived from: lam = w1 + q.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    z : mpmath.mpf
        depth below the surface [m]
    w1_e : mpmath.mpf
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    w1_a : mpmath.mpf
        a^2 + w1 >= 0 [m^2]
    w1_b : mpmath.mpf
        b^2 + w1 >= 0 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    q_e : mpmath.mpf
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    """
    return q_e*(d_e + q_e)*(q_e + w1_e) - z**2*(q_e + w1_a)*(q_e + w1_b)


def ellipse_stress_cubic_q_slope(z, w1_e, w1_a, w1_b, d_e, q_e):
    """D/dq of ellipse_stress_cubic_q [m^4].

    Chapter: (5.31). Derived from: its derivative.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    z : mpmath.mpf
        depth below the surface [m]
    w1_e : mpmath.mpf
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    w1_a : mpmath.mpf
        a^2 + w1 >= 0 [m^2]
    w1_b : mpmath.mpf
        b^2 + w1 >= 0 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    q_e : mpmath.mpf
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    """
    return q_e*(d_e + q_e) + q_e*(q_e + w1_e) - z**2*(q_e + w1_a) - z**2*(q_e + w1_b) + (d_e + q_e)*(q_e + w1_e)


def ellipse_stress_d(a, b_e, x, y):
    """W1 - w2 [m^2] >= 0, the difference of the roots of P2.

    Chapter: (5.31). Derived from: the discriminant of P2 as a sum of squares.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)


def ellipse_stress_e_sq(a, b_e, lam_e, q_e, d_e):
    """E^2 = z^2/lam [1], finite on the surface.

    Chapter: (5.31). Derived from: g(lam) = 0.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    q_e : mpmath.mpf
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    """
    return q_e*(d_e + q_e)/((a**2 + lam_e)*(b_e**2 + lam_e))


def ellipse_stress_jxx_integrand(x, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_xx (H1_xx of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    x : mpmath.mpf
        coordinate [m]
    w1_a : mpmath.mpf
        a^2 + w1 >= 0 [m^2]
    w1_b : mpmath.mpf
        b^2 + w1 >= 0 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : mpmath.mpf
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    return -2*(-d_e*v_q**2 - v_q**4 + v_q**2*x**2 + w1_b*x**2)/(mpmath.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)**2*(v_q**2 + w1_b))


def ellipse_stress_jxy_integrand(x, y, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_xy (H1_xy of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    w1_a : mpmath.mpf
        a^2 + w1 >= 0 [m^2]
    w1_b : mpmath.mpf
        b^2 + w1 >= 0 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : mpmath.mpf
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    return -2*x*y/(mpmath.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b))


def ellipse_stress_jyy_integrand(y, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_yy (H1_yy of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    y : mpmath.mpf
        coordinate [m]
    w1_a : mpmath.mpf
        a^2 + w1 >= 0 [m^2]
    w1_b : mpmath.mpf
        b^2 + w1 >= 0 [m^2]
    d_e : mpmath.mpf
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : mpmath.mpf
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    return -2*(-d_e*v_q**2 - v_q**4 + v_q**2*y**2 + w1_a*y**2)/(mpmath.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b)**2)


def ellipse_stress_sigma_xx(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_xx):
    """Stress sigma_xx [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    I_x : mpmath.mpf
        integral over w > lam of dw/((a^2 + w) Delta(w)), Delta = ((a^2 + w)(b^2 + w) w)^(1/2) [m^-3]
    I_y : mpmath.mpf
        integral over w > lam of dw/((b^2 + w) Delta(w)) [m^-3]
    J_xx : mpmath.mpf
        integral over v of the H_xx integrand (ellipse_stress_jxx_integrand) [m^-2]
    """
    return I_x*a*b_e*e_c*mpmath.sqrt(lam_e)*p0 + I_y*a*b_e*e_c*mpmath.sqrt(lam_e)*nu*p0 + (mpmath.mpf(1)/mpmath.mpf(2))*J_xx*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*x**2 + 2*nu*(a**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/((a**2 + lam_e)**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_sigma_yy(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_yy):
    """Stress sigma_yy [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    I_x : mpmath.mpf
        integral over w > lam of dw/((a^2 + w) Delta(w)), Delta = ((a^2 + w)(b^2 + w) w)^(1/2) [m^-3]
    I_y : mpmath.mpf
        integral over w > lam of dw/((b^2 + w) Delta(w)) [m^-3]
    J_yy : mpmath.mpf
        integral over v of the H_yy integrand (ellipse_stress_jyy_integrand) [m^-2]
    """
    return I_x*a*b_e*e_c*mpmath.sqrt(lam_e)*nu*p0 + I_y*a*b_e*e_c*mpmath.sqrt(lam_e)*p0 + (mpmath.mpf(1)/mpmath.mpf(2))*J_yy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*y**2 + 2*nu*(b_e**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/(mpmath.sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(mpmath.mpf(5)/mpmath.mpf(2))*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_sigma_zz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress sigma_zz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    return -a*b_e*e_c**3*p0/(mpmath.sqrt(a**2 + lam_e)*mpmath.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_xy(a, b_e, nu, p0, x, y, lam_e, e_c, J_xy):
    """Stress tau_xy [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    J_xy : mpmath.mpf
        integral over v of the H_xy integrand (ellipse_stress_jxy_integrand) [m^-2]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*J_xy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*lam_e*p0*x*y/((a**2 + lam_e)**(mpmath.mpf(3)/mpmath.mpf(2))*(b_e**2 + lam_e)**(mpmath.mpf(3)/mpmath.mpf(2))*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_xz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress tau_xz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    return -a*b_e*e_c**2*mpmath.sqrt(lam_e)*p0*x/((a**2 + lam_e)**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_yz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress tau_yz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    lam_e : mpmath.mpf
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : mpmath.mpf
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    return -a*b_e*e_c**2*mpmath.sqrt(lam_e)*p0*y/(mpmath.sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(mpmath.mpf(3)/mpmath.mpf(2))*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_w1(a, b_e, x, y):
    """Largest root w1 [m^2] of the surface quadratic P2 at (x, y) (< 0 inside the contact ellipse, > 0 outside).

    Chapter: (5.31). Derived from: P2 = w^2 + beta w + gamma.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return ((-mpmath.mpf(1)/mpmath.mpf(2)*a**2 - mpmath.mpf(1)/mpmath.mpf(2)*b_e**2 + (mpmath.mpf(1)/mpmath.mpf(2))*x**2 + (mpmath.mpf(1)/mpmath.mpf(2))*y**2 + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)) if (a**2 + b_e**2 - x**2 - y**2 <= 0) else ((-2*a**2*b_e**2 + 2*a**2*y**2 + 2*b_e**2*x**2)/(a**2 + b_e**2 - x**2 - y**2 + mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2))))


def ellipse_stress_w1_a(a, b_e, x, y):
    """A^2 + w1 [m^2] >= 0.

    Chapter: (5.31). Derived from: P2 shifted by a^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*x**2 + (mpmath.mpf(1)/mpmath.mpf(2))*y**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - b_e)*(a + b_e) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)


def ellipse_stress_w1_b(a, b_e, x, y):
    """B^2 + w1 [m^2] >= 0.

    Chapter: (5.31). Derived from: P2 shifted by b^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    b_e : mpmath.mpf
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return ((-mpmath.mpf(1)/mpmath.mpf(2)*a**2 + (mpmath.mpf(1)/mpmath.mpf(2))*b_e**2 + (mpmath.mpf(1)/mpmath.mpf(2))*x**2 + (mpmath.mpf(1)/mpmath.mpf(2))*y**2 + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)) if (-a**2 + b_e**2 + x**2 + y**2 >= 0) else (2*y**2*(a - b_e)*(a + b_e)/(a**2 - b_e**2 - x**2 - y**2 + mpmath.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2))))


def fit_adhesive_cone_depth(E_star, theta, a, rho_g):
    """Indentation depth d [m] of a cone in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: adhesion_cone_depth at
    Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*a*mpmath.tan(theta) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*rho_g/mpmath.sqrt(E_star)


def fit_adhesive_cone_depth_da(E_star, theta, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a cone: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: adhesion_cone_depth
    differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_radius_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*mpmath.tan(theta) - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def fit_adhesive_cone_force(E_star, theta, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a cone in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from:
    adhesion_cone_force_from_radius at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi*E_star*a**2*mpmath.tan(theta) + F_0 + s_0*z_p


def fit_adhesive_cone_force_dE(E_star, theta, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a cone at a fixed position.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*(mpmath.pi**2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.tan(theta)**2 + 16*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g**2 - 5*mpmath.sqrt(2)*mpmath.pi**(mpmath.mpf(3)/mpmath.mpf(2))*E_star**2*a**2*rho_g*mpmath.tan(theta))/(mpmath.pi*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.sqrt(a)*mpmath.tan(theta) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*rho_g)


def fit_adhesive_cone_force_ddgamma(E_star, theta, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a cone at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 4*mpmath.pi*E_star*a**(mpmath.mpf(3)/mpmath.mpf(2))/(mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*rho_g - mpmath.pi*E_star*mpmath.sqrt(a)*mpmath.tan(theta))


def fit_adhesive_cone_force_dz0(E_star, theta, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a cone at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(-mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.tan(theta) + 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a*rho_g)/(mpmath.pi*mpmath.sqrt(E_star)*mpmath.sqrt(a)*mpmath.tan(theta) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g)


def fit_adhesive_powerlaw_depth(E_star, c_n, kappa_n, n, a, rho_g):
    """Indentation depth d [m] of a power-law tip in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_depth at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return a**n*c_n*kappa_n - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*rho_g/mpmath.sqrt(E_star)


def fit_adhesive_powerlaw_depth_da(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a power-law tip: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_depth differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_powerlaw.py::test_adhesive_powerlaw_radius_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return a**n*c_n*kappa_n*n/a - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def fit_adhesive_powerlaw_force(E_star, c_n, kappa_n, n, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a power-law tip in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_force_from_radius at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return F_0 + s_0*z_p + 2*(-mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*n*rho_g - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g + E_star*a**(n + 1)*c_n*kappa_n*n)/(n + 1)


def fit_adhesive_powerlaw_force_dE(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a power-law tip at a fixed position.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(2*n + mpmath.mpf(3)/mpmath.mpf(2))*c_n**2*kappa_n**2*n**2 + 4*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(5)/mpmath.mpf(2))*n*rho_g**2 + 4*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(5)/mpmath.mpf(2))*rho_g**2 - 2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n**2*rho_g - 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n*rho_g)/((n + 1)*(2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(n + mpmath.mpf(1)/mpmath.mpf(2))*c_n*kappa_n*n - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*a*rho_g))


def fit_adhesive_powerlaw_force_ddgamma(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a power-law tip at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in Delta
    gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 4*mpmath.pi*E_star*a**(mpmath.mpf(5)/mpmath.mpf(2))/(mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a*rho_g - 2*E_star*a**(n + mpmath.mpf(1)/mpmath.mpf(2))*c_n*kappa_n*n)


def fit_adhesive_powerlaw_force_dz0(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a power-law tip at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(-2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(n + mpmath.mpf(3)/mpmath.mpf(2))*c_n*kappa_n*n + 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a**2*rho_g)/(2*mpmath.sqrt(E_star)*a**(n + mpmath.mpf(1)/mpmath.mpf(2))*c_n*kappa_n*n - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*a*rho_g)


def fit_adhesive_sampled_depth(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Indentation depth d [m] of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: g(a) - Delta l
    at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return g_a - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*rho_g/mpmath.sqrt(E_star)


def fit_adhesive_sampled_depth_da(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]): Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: g(a) - Delta l
    differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sampled.py::test_adhesive_sampled_radius_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return g_slope - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def fit_adhesive_sampled_force(E_star, g_a, g_slope, g_integral, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: 2 E* (a d -
    G(a)) at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g + 2*E_star*a*g_a - 2*E_star*g_integral + F_0 + s_0*z_p


def fit_adhesive_sampled_force_dE(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(3)/mpmath.mpf(2))*g_a*g_slope - 2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(a)*g_integral*g_slope + 4*mpmath.pi*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g**2 - 2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a**2*g_slope*rho_g - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a*g_a*rho_g + mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*g_integral*rho_g)/(2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(a)*g_slope - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*rho_g)


def fit_adhesive_sampled_force_ddgamma(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return -4*mpmath.pi*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))/(2*mpmath.sqrt(E_star)*mpmath.sqrt(a)*g_slope - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g)


def fit_adhesive_sampled_force_dz0(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : mpmath.mpf
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : mpmath.mpf
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(-2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(3)/mpmath.mpf(2))*g_slope + 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a*rho_g)/(2*mpmath.sqrt(E_star)*mpmath.sqrt(a)*g_slope - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g)


def fit_adhesive_sphere_depth(E_star, R, a, rho_g):
    """Indentation depth d [m] of an exact sphere (spherical cap) in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: sphere_depth
    less Delta l at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return a*mpmath.atanh(a/R) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*rho_g/mpmath.sqrt(E_star)


def fit_adhesive_sphere_depth_da(E_star, R, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of an exact sphere (spherical cap): Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: sphere_depth
    less Delta l differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_radius_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return mpmath.atanh(a/R) + a/(R*(1 - a**2/R**2)) - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def fit_adhesive_sphere_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on an exact sphere (spherical cap) in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from:
    sphere_force_from_radius less 2 E* a Delta l at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g + E_star*(R**2*mpmath.atanh(a/R) - R*a + a**2*mpmath.atanh(a/R)) + F_0 + s_0*z_p


def fit_adhesive_sphere_force_dE(E_star, R, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return (2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*R**4*mpmath.sqrt(a)*mpmath.atanh(a/R)**2 - 2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*R**2*a**(mpmath.mpf(5)/mpmath.mpf(2)) + 4*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*R*a**(mpmath.mpf(7)/mpmath.mpf(2))*mpmath.atanh(a/R) - 2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(mpmath.mpf(9)/mpmath.mpf(2))*mpmath.atanh(a/R)**2 + 8*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*R**2*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g**2 - 8*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(7)/mpmath.mpf(2))*rho_g**2 - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R**4*rho_g*mpmath.atanh(a/R) + mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R**3*a*rho_g - 4*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R**2*a**2*rho_g*mpmath.atanh(a/R) - 5*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R*a**3*rho_g + 5*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*a**4*rho_g*mpmath.atanh(a/R))/(2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*R**2*mpmath.sqrt(a)*mpmath.atanh(a/R) + 2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*R*a**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.atanh(a/R) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R**2*rho_g + mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*a**2*rho_g)


def fit_adhesive_sphere_force_ddgamma(E_star, R, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 4*mpmath.pi*E_star*a**(mpmath.mpf(3)/mpmath.mpf(2))*(-R**2 + a**2)/(-mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*R**2*rho_g + mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**2*rho_g + 2*E_star*R**2*mpmath.sqrt(a)*mpmath.atanh(a/R) + 2*E_star*R*a**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*E_star*a**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.atanh(a/R))


def fit_adhesive_sphere_force_dz0(E_star, R, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(-2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*R**2*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.atanh(a/R) - 2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*R*a**(mpmath.mpf(5)/mpmath.mpf(2)) + 2*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(7)/mpmath.mpf(2))*mpmath.atanh(a/R) + 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*R**2*a*rho_g - 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*a**3*rho_g)/(2*mpmath.sqrt(E_star)*R**2*mpmath.sqrt(a)*mpmath.atanh(a/R) + 2*mpmath.sqrt(E_star)*R*a**(mpmath.mpf(3)/mpmath.mpf(2)) - 2*mpmath.sqrt(E_star)*a**(mpmath.mpf(5)/mpmath.mpf(2))*mpmath.atanh(a/R) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*R**2*rho_g + mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*a**2*rho_g)


def fit_cone_force(E_star, theta, z_p, z_0, F_0, s_0):
    """Force F [N] on a rigid cone at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return 2*E_star*max(0, -z_0 + z_p)**2/(mpmath.pi*mpmath.tan(theta)) + F_0 + s_0*z_p


def fit_cone_force_dE(theta, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a rigid cone.

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return 2*max(0, -z_0 + z_p)**2/(mpmath.pi*mpmath.tan(theta))


def fit_cone_force_dz0(E_star, theta, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a rigid cone (0 for d <= 0).

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return -4*E_star*(((0) if (z_0 - z_p >= 0) else (1)))*max(0, -z_0 + z_p)/(mpmath.pi*mpmath.tan(theta))


def fit_hertz_force(E_star, R, z_p, z_0, F_0, s_0):
    """Force F [N] on a paraboloidal (Hertz) tip at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*mpmath.sqrt(R)*max(0, -z_0 + z_p)**(mpmath.mpf(3)/mpmath.mpf(2)) + F_0 + s_0*z_p


def fit_hertz_force_dE(R, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a paraboloidal (Hertz) tip.

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*mpmath.sqrt(R)*max(0, -z_0 + z_p)**(mpmath.mpf(3)/mpmath.mpf(2))


def fit_hertz_force_dz0(E_star, R, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a paraboloidal (Hertz) tip (0 for d <= 0).

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return -2*E_star*mpmath.sqrt(R)*(((0) if (z_0 - z_p >= 0) else (1)))*mpmath.sqrt(max(0, -z_0 + z_p))


def fit_jkr_depth(E_star, R, a, rho_g):
    """Indentation depth d [m] of a paraboloid in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_depth at Delta gamma =
    rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return a**2/R - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*rho_g/mpmath.sqrt(E_star)


def fit_jkr_depth_da(E_star, R, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a paraboloid: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_depth differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_radius_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*a/R - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*rho_g/(mpmath.sqrt(E_star)*mpmath.sqrt(a))


def fit_jkr_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a paraboloid in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_force_from_radius at Delta
    gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g + (mpmath.mpf(4)/mpmath.mpf(3))*E_star*a**3/R + F_0 + s_0*z_p


def fit_jkr_force_dE(E_star, R, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a paraboloid at a fixed position.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*(4*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(mpmath.mpf(9)/mpmath.mpf(2)) + 6*mpmath.pi*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*R**2*a**(mpmath.mpf(3)/mpmath.mpf(2))*rho_g**2 - 7*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R*a**3*rho_g)/(R*(4*E_star**(mpmath.mpf(5)/mpmath.mpf(2))*a**(mpmath.mpf(3)/mpmath.mpf(2)) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star**2*R*rho_g))


def fit_jkr_force_ddgamma(E_star, R, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a paraboloid at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 4*mpmath.pi*E_star*R*a**(mpmath.mpf(3)/mpmath.mpf(2))/(mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*R*rho_g - 4*E_star*a**(mpmath.mpf(3)/mpmath.mpf(2)))


def fit_jkr_force_dz0(E_star, R, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a paraboloid at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    rho_g : mpmath.mpf
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    return 2*(-4*E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**(mpmath.mpf(5)/mpmath.mpf(2)) + 3*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*E_star*R*a*rho_g)/(4*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2)) - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*R*rho_g)


def fit_powerlaw_force(E_star, c_n, kappa_n, n, z_p, z_0, F_0, s_0):
    """Force F [N] on a power-law tip at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return 2*E_star*n*(max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*max(0, -z_0 + z_p)/(n + 1) + F_0 + s_0*z_p


def fit_powerlaw_force_dE(c_n, kappa_n, n, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a power-law tip.

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return 2*n*(max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*max(0, -z_0 + z_p)/(n + 1)


def fit_powerlaw_force_dz0(E_star, c_n, kappa_n, n, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a power-law tip (0 for d <= 0).

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return -2*E_star*(max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*(((0) if (z_0 - z_p >= 0) else (1)))


def fit_punch_force(E_star, a, z_p, z_0, F_0, s_0):
    """Force F [N] on a flat punch at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return 2*E_star*a*max(0, -z_0 + z_p) + F_0 + s_0*z_p


def fit_punch_force_dE(a, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a flat punch.

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return 2*a*max(0, -z_0 + z_p)


def fit_punch_force_dz0(E_star, a, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a flat punch (0 for d <= 0).

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : mpmath.mpf
        contact point: the position z_p where the tip first touches the sample [m]
    """
    return -2*E_star*a*(((0) if (z_0 - z_p >= 0) else (1)))


def fit_pyramid_cone_angle(alpha_p, n_sides):
    """Angle theta [rad] between the surface and the plane of the cone with the cross-section area of a regular pyramid (n_sides faces, half-angle alpha_p) at every depth: the pyramid's equivalent cone.

    Chapter: (5.38), equal area. Derived from: pi (d cot(theta))^2 = n (d tan(alpha_p))^2
    tan(pi/n).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_pyramid_cone_by_polygon_area``.

    Parameters
    ----------
    alpha_p : mpmath.mpf
        half-angle of a regular pyramid: between its axis and the mid-line of a face [rad]
    n_sides : mpmath.mpf
        number of faces of a regular pyramid (4: most AFM tips; 3: Berkovich) [1]
    """
    return mpmath.atan(mpmath.sqrt(mpmath.pi)/(mpmath.sqrt(n_sides)*mpmath.tan(alpha_p)*mpmath.sqrt(mpmath.tan(mpmath.pi/n_sides))))


def fit_pyramid_force_cone_angle(alpha_p, n_sides, beta_p):
    """Angle theta [rad] between the surface and the plane of the cone whose force (5.40) is beta_p times the equal-area cone's: a regular pyramid's force law, beta_p from the BEM.

    Chapter: (5.40), equal force. Derived from: (2/pi) E* d^2 / tan(theta) = beta_p (2/pi)
    E* d^2 / tan(theta_area).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_pyramid_force_by_bem``.

    Parameters
    ----------
    alpha_p : mpmath.mpf
        half-angle of a regular pyramid: between its axis and the mid-line of a face [rad]
    n_sides : mpmath.mpf
        number of faces of a regular pyramid (4: most AFM tips; 3: Berkovich) [1]
    beta_p : mpmath.mpf
        a regular pyramid's force over its equal-area cone's at the same depth (by the BEM, docs/pyramid.md) [1]
    """
    return mpmath.atan(mpmath.sqrt(mpmath.pi)/(beta_p*mpmath.sqrt(n_sides)*mpmath.tan(alpha_p)*mpmath.sqrt(mpmath.tan(mpmath.pi/n_sides))))


def fit_sample_modulus(E_star, nu1, E2, nu2):
    """Young's modulus E1 [Pa] of the sample (body 1) under an elastic tip (body 2, E2, nu2), from the fitted E*.

    Chapter: (5.26), inverted. Derived from: (5.26) solved for E1.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    E2 : mpmath.mpf
        Young's modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return E2*E_star*(1 - nu1**2)/(E2 + E_star*nu2**2 - E_star)


def fit_sample_modulus_dE(E_star, nu1, E2, nu2):
    """Derivative dE1/dE* [1] of the sample's modulus under an elastic tip.

    Chapter: (5.26), inverted. Derived from: (5.26) solved for E1, differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    E2 : mpmath.mpf
        Young's modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return -E2**2*nu1**2/(E2 + E_star*nu2**2 - E_star)**2 + E2**2/(E2 + E_star*nu2**2 - E_star)**2


def fit_sample_modulus_rigid(E_star, nu):
    """Young's modulus E [Pa] of the sample under a rigid tip, from the fitted E*.

    Chapter: (5.8), inverted. Derived from: (5.8) solved for E.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return E_star*(1 - nu**2)


def fit_sample_modulus_rigid_dE(nu):
    """Derivative dE/dE* [1] of the sample's modulus under a rigid tip.

    Chapter: (5.8), inverted. Derived from: (5.8) solved for E, differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return 1 - nu**2


def fit_sphere_depth(lam, a):
    """Indentation depth d [m] of the exact sphere at lam = atanh(a/R) and its contact radius a = R tanh(lam), both given: the function of Newton's iteration for lam at a given depth.

    Chapter: (5.55). Derived from: (5.55), d = a atanh(a/R), at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : mpmath.mpf
        contact radius [m]
    """
    return a*lam


def fit_sphere_depth_dlam(R, lam, a):
    """Derivative dd/dlam [m] of the exact sphere's depth d = R lam tanh(lam) at lam and a = R tanh(lam), both given: the slope of Newton's iteration for lam at a given depth.

    Chapter: (5.55). Derived from: (5.55) at a = R tanh(lam), differentiated in lam;
    sech(lam)^2 as (R - a)(R + a)/R^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : mpmath.mpf
        contact radius [m]
    """
    return a + lam*(R - a)*(R + a)/R


def fit_sphere_force(E_star, R, lam, a, z_p, F_0, s_0):
    """Force F [N] on a rigid spherical cap (exact sphere) at the position z_p, with lam = atanh(a/R) at the depth d = max(0, z_p - z_0), plus the baseline F_0 + s_0 z_p.

    Chapter: (5.57), fit model. Derived from: (5.57) at lam = atanh(a/R) and the contact
    radius a = R tanh(lam), both given (the fit computes tanh once per point); below lam =
    1/2 its cancelling lam - tanh(lam) by Lambert's continued fraction of tanh, 7 levels
    (truncation < 1e-18 relative; no 2F1, cheap at every point of a fit).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_fit_force_by_mpmath``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : mpmath.mpf
        contact radius [m]
    z_p : mpmath.mpf
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : mpmath.mpf
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : mpmath.mpf
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    return E_star*((R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/((mpmath.mpf(1)/mpmath.mpf(15))*lam**2 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam) if (lam < mpmath.mpf(1)/mpmath.mpf(2)) else (-R*a + lam*(R**2 + a**2))) + F_0 + s_0*z_p


def fit_sphere_force_dE(R, lam, a):
    """Derivative dF/dE* [m^2] of the fit model of the exact sphere.

    Chapter: (5.57), fit model. Derived from: (5.57) differentiated in E* at lam =
    atanh(a/R) and the contact radius a = R tanh(lam), both given (the fit computes tanh
    once per point); below lam = 1/2 as fit_sphere_force.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_fit_force_by_mpmath``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : mpmath.mpf
        contact radius [m]
    """
    return ((R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/((mpmath.mpf(1)/mpmath.mpf(15))*lam**2 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam) if (lam < mpmath.mpf(1)/mpmath.mpf(2)) else (-R*a + lam*(R**2 + a**2)))


def fit_sphere_force_dz0(E_star, a):
    """Derivative dF/dz_0 [N/m] of the fit model of the exact sphere at the contact radius a = R tanh(lam) (0 at a = 0, no contact).

    Chapter: (5.55), (5.57), fit model. Derived from: -(dF/dlam)/(dd/dlam) of (5.57) and
    (5.55), simplified to -2 E* a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return -2*E_star*a


def fit_sphere_radius_dlam(R, a):
    """Derivative da/dlam [m] of the exact sphere's contact radius a = R tanh(lam) at a given: the contact radius at Newton's last step for lam, a + (da/dlam) step, to an ulp for a step below 1e-8 lam, without a tanh.

    Chapter: (5.55). Derived from: a = R tanh(lam) differentiated in lam, sech(lam)^2 as (R
    - a)(R + a)/R^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return (R - a)*(R + a)/R


def flamant_sigma_xx(F_L, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : mpmath.mpf
        normal force per unit length of a line contact [N/m]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*F_L*x**2*z/(mpmath.pi*(x**2 + z**2)**2)


def flamant_sigma_zz(F_L, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : mpmath.mpf
        normal force per unit length of a line contact [N/m]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*F_L*z**3/(mpmath.pi*(x**2 + z**2)**2)


def flamant_tau_xz(F_L, x, z):
    """Shear stress tau_xz [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : mpmath.mpf
        normal force per unit length of a line contact [N/m]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*F_L*x*z**2/(mpmath.pi*(x**2 + z**2)**2)


def flat_punch_tangential_traction(r, a, G_star, u_x):
    """Tangential traction q(r) [Pa] of a stuck flat punch (all springs stick, u_x < mu d E*/G*).

    Chapter: MDR tangential, flat punch (not in the chapter). Derived from: (5.59) of q_x =
    G* u_x on |x| < a: the jump at a is a delta in q_x'.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return G_star*u_x/(mpmath.pi*mpmath.sqrt(a**2 - r**2))


def force_law_cone_exponent():
    """Exponent n [1] of the force law F = K d^n of a rigid cone of angle theta with the plane.

    Chapter: (5.40), F = K d^n. Derived from: the logarithmic slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_cone_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return 2


def force_law_cone_prefactor(E_star, theta):
    """Prefactor K [N/m^n] of the force law F = K d^n of a rigid cone of angle theta with the plane.

    Chapter: (5.40), F = K d^n. Derived from: F/d^n with n the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_cone_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 2*E_star/(mpmath.pi*mpmath.tan(theta))


def force_law_cone_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of a rigid cone of angle theta with the plane.

    Chapter: (5.40), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return 1


def force_law_cone_stiffness_prefactor(E_star, theta):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a rigid cone of angle theta with the plane.

    Chapter: (5.40), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the logarithmic
    slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    """
    return 4*E_star/(mpmath.pi*mpmath.tan(theta))


def force_law_ellipse_exponent():
    """Exponent n [1] of the force law F = K d^n of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, F = K d^n. Derived from: the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_ellipse_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return mpmath.mpf(3)/mpmath.mpf(2)


def force_law_ellipse_prefactor(E_star, R1, t_ba):
    """Prefactor K [N/m^n] of the force law F = K d^n of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, F = K d^n. Derived from: F/d^n with n the logarithmic
    slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_ellipse_law_by_pressure_quadrature``.

    Printed in a stable form: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force:
    the K, E form cancels as t -> 1 (the circle).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/mpmath.ellipk(1 - t_ba**2)**(mpmath.mpf(3)/mpmath.mpf(2))


def force_law_ellipse_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, differentiated. Derived from: the logarithmic slope of
    dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return mpmath.mpf(1)/mpmath.mpf(2)


def force_law_ellipse_stiffness_prefactor(E_star, R1, t_ba):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, differentiated. Derived from: (dF/dd)/d^(n_k) with n_k
    the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Printed in a stable form: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force:
    the K, E form cancels as t -> 1 (the circle).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/mpmath.ellipk(1 - t_ba**2)**(mpmath.mpf(3)/mpmath.mpf(2))


def force_law_hertz_exponent():
    """Exponent n [1] of the force law F = K d^n of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), F = K d^n. Derived from: the logarithmic slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_hertz_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return mpmath.mpf(3)/mpmath.mpf(2)


def force_law_hertz_prefactor(E_star, R):
    """Prefactor K [N/m^n] of the force law F = K d^n of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), F = K d^n. Derived from: F/d^n with n the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_hertz_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*mpmath.sqrt(R)


def force_law_hertz_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return mpmath.mpf(1)/mpmath.mpf(2)


def force_law_hertz_stiffness_prefactor(E_star, R):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the logarithmic
    slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return 2*E_star*mpmath.sqrt(R)


def force_law_line_exponent():
    """Exponent n [1] of the force law F per unit length = K d^n of a line contact, per unit length (F/L), with d the conventional depth of (5.35), a = sqrt(R d).

    Chapter: (5.34), F = K d^n. Derived from: the logarithmic slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_line_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return 1


def force_law_line_prefactor(E_star):
    """Prefactor K [N/m per m] of the force law F per unit length = K d^n of a line contact, per unit length (F/L), with d the conventional depth of (5.35), a = sqrt(R d).

    Chapter: (5.34), F = K d^n. Derived from: F/d^n with n the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_line_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*E_star


def force_law_line_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of a line contact, per unit length (F/L), with d the conventional depth of (5.35), a = sqrt(R d).

    Chapter: (5.34), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return 0


def force_law_line_stiffness_prefactor(E_star):
    """Prefactor K_k [N/m per m] of the stiffness law dF/L/dd = K_k d^(n - 1) of a line contact, per unit length (F/L), with d the conventional depth of (5.35), a = sqrt(R d).

    Chapter: (5.34), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the logarithmic
    slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*E_star


def force_law_powerlaw_exponent(n):
    """Exponent n [1] of the force law F = K d^n of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), F = K d^n. Derived from: the logarithmic slope d F'/F of the
    force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_powerlaw_law_by_pressure_quadrature``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return (n + 1)/n


def force_law_powerlaw_prefactor(E_star, c_n, kappa_n, n):
    """Prefactor K [N/m^n] of the force law F = K d^n of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), F = K d^n. Derived from: F/d^n with n the logarithmic slope d
    F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_powerlaw_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*n*(1/(c_n*kappa_n))**(1/n)/(n + 1)


def force_law_powerlaw_stiffness_exponent(n):
    """Exponent n - 1 [1] of the stiffness law of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 1/n


def force_law_powerlaw_stiffness_prefactor(E_star, c_n, kappa_n, n):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the
    logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*(1/(c_n*kappa_n))**(1/n)


def force_law_punch_exponent():
    """Exponent n [1] of the force law F = K d^n of a flat rigid punch of radius a.

    Chapter: Problem 7(a), F = K d^n. Derived from: the logarithmic slope d F'/F of the
    force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_punch_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return 1


def force_law_punch_prefactor(E_star, a):
    """Prefactor K [N/m^n] of the force law F = K d^n of a flat rigid punch of radius a.

    Chapter: Problem 7(a), F = K d^n. Derived from: F/d^n with n the logarithmic slope d
    F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_punch_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*E_star*a


def force_law_punch_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of a flat rigid punch of radius a.

    Chapter: Problem 7(a), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return 0


def force_law_punch_stiffness_prefactor(E_star, a):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a flat rigid punch of radius a.

    Chapter: Problem 7(a), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the
    logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*E_star*a


def hertz_contact_radius(R, d):
    """Contact radius a [m] of a Hertz contact at depth d.

    Chapter: (5.21). Derived from: the matching condition (5.19).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.sqrt(R)*mpmath.sqrt(d)


def hertz_contact_radius_from_force(E_star, F, R):
    """Contact radius a [m] of a Hertz contact under the force F.

    Chapter: (5.24). Derived from: (5.21) at the depth of (5.23) inverted.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*6**(mpmath.mpf(1)/mpmath.mpf(3))*F**(mpmath.mpf(1)/mpmath.mpf(3))*R**(mpmath.mpf(1)/mpmath.mpf(3))/E_star**(mpmath.mpf(1)/mpmath.mpf(3))


def hertz_depth_from_force(E_star, F, R):
    """Indentation depth d [m] of a Hertz contact under the force F.

    Chapter: (5.23), inverted. Derived from: (5.23) solved for d.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*6**(mpmath.mpf(2)/mpmath.mpf(3))*F**(mpmath.mpf(2)/mpmath.mpf(3))/(E_star**(mpmath.mpf(2)/mpmath.mpf(3))*R**(mpmath.mpf(1)/mpmath.mpf(3)))


def hertz_displacement_inside(R, d, r):
    """Surface displacement u_z(r) [m] inside a Hertz contact (r <= a).

    Chapter: (5.18). Derived from: (5.16) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return d - mpmath.mpf(1)/mpmath.mpf(2)*r**2/R


def hertz_displacement_outside(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact (r > a).

    Chapter: Fig. 5.2, Problem 7(b). Derived from: (5.7) over the Hertz pressure, outside
    the disc.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Printed in a stable form: the textbook form cancels terms of size r/a to leave one of
    size a/r; asin t - t sqrt(1 - t^2) is written as (2 t^3/3) 2F1(1/2, 3/2; 5/2; t^2) with
    t = a/r.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*d*(-mpmath.mpf(1)/mpmath.mpf(3)*mpmath.sqrt(R)*mpmath.sqrt(d)*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(5)/mpmath.mpf(2),), R*d/r**2)/r + mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r))/mpmath.pi


def hertz_displacement_outside_elementary(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact with the 2F1 in elementary functions; it cancels ~0.65 eps a^2/r^2 relative: for a < r < 2a.

    Chapter: Fig. 5.2, Problem 7(b), a < r < 2a. Derived from: the stable far form with
    2F1(1/2, 3/2; 5/2; t^2) hyperexpanded.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_outside_forms_by_mpmath``.

    Printed in a stable form: asin t - (asin t - t sqrt(1 - z))/(2 z), t = a/r, z = R d/r^2:
    the 2F1 in elementary functions as one cancellation of ~0.65 eps/z.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*d*(mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r) - mpmath.mpf(1)/mpmath.mpf(2)*r**2*(-mpmath.sqrt(R)*mpmath.sqrt(d)*mpmath.sqrt(-R*d/r**2 + 1)/r + mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r))/(R*d))/mpmath.pi


def hertz_displacement_outside_series(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact, its Taylor series in z = a^2/r^2 to 22 terms: for r >= 2a (z <= 1/4) the truncation is below 1.3e-17 relative.

    Chapter: Fig. 5.2, Problem 7(b), r >= 2a. Derived from: the series of the stable far
    form (2F1(1/2, 3/2; 5/2; z) and asin).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_outside_forms_by_mpmath``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*mpmath.sqrt(R)*d**(mpmath.mpf(3)/mpmath.mpf(2))*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*((mpmath.mpf(4485482287)/mpmath.mpf(35459249995776))*R*d/r**2 + mpmath.mpf(34461632205)/mpmath.mpf(242304874971136))/r**2 + mpmath.mpf(1472719325)/mpmath.mpf(9156870275072))/r**2 + mpmath.mpf(756261275)/mpmath.mpf(4131758538752))/r**2 + mpmath.mpf(116680311)/mpmath.mpf(556198264832))/r**2 + mpmath.mpf(20036013)/mpmath.mpf(82678120448))/r**2 + mpmath.mpf(3231615)/mpmath.mpf(11442061312))/r**2 + mpmath.mpf(5014575)/mpmath.mpf(15082717184))/r**2 + mpmath.mpf(1300075)/mpmath.mpf(3284140032))/r**2 + mpmath.mpf(676039)/mpmath.mpf(1415577600))/r**2 + mpmath.mpf(88179)/mpmath.mpf(150732800))/r**2 + mpmath.mpf(46189)/mpmath.mpf(63307776))/r**2 + mpmath.mpf(12155)/mpmath.mpf(13074432))/r**2 + mpmath.mpf(6435)/mpmath.mpf(5292032))/r**2 + mpmath.mpf(143)/mpmath.mpf(87040))/r**2 + mpmath.mpf(77)/mpmath.mpf(33280))/r**2 + mpmath.mpf(63)/mpmath.mpf(18304))/r**2 + mpmath.mpf(35)/mpmath.mpf(6336))/r**2 + mpmath.mpf(5)/mpmath.mpf(504))/r**2 + mpmath.mpf(3)/mpmath.mpf(140))/r**2 + mpmath.mpf(1)/mpmath.mpf(15))/r**2 + mpmath.mpf(2)/mpmath.mpf(3))/(mpmath.pi*r)


def hertz_energy(E_star, R, d):
    """Elastic energy U [J] stored in a Hertz contact at depth d.

    Chapter: (5.25). Derived from: the integral of F = dU/dd from 0 to d.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_energy_by_work``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(8)/mpmath.mpf(15))*E_star*mpmath.sqrt(R)*d**(mpmath.mpf(5)/mpmath.mpf(2))


def hertz_force(E_star, R, d):
    """Normal force F [N] of a Hertz contact at depth d.

    Chapter: (5.23). Derived from: (5.17) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*mpmath.sqrt(R)*d**(mpmath.mpf(3)/mpmath.mpf(2))


def hertz_max_pressure(E_star, R, d):
    """Maximum (central) pressure p0 [Pa] of a Hertz contact at depth d.

    Chapter: (5.22). Derived from: the matching condition (5.19).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return 2*E_star*mpmath.sqrt(d)/(mpmath.pi*mpmath.sqrt(R))


def hertz_max_pressure_from_force(E_star, F, R):
    """Maximum pressure p0 [Pa] of a Hertz contact under the force F.

    Chapter: (5.24). Derived from: (5.22) at the depth of (5.23) inverted.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return 6**(mpmath.mpf(1)/mpmath.mpf(3))*E_star**(mpmath.mpf(2)/mpmath.mpf(3))*F**(mpmath.mpf(1)/mpmath.mpf(3))/(mpmath.pi*R**(mpmath.mpf(2)/mpmath.mpf(3)))


def hertz_mean_pressure(E_star, R, d):
    """Mean pressure F/(pi a^2) [Pa] of a Hertz contact at depth d.

    Chapter: (5.17). Derived from: (5.23) divided by the contact area.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*mpmath.sqrt(d)/(mpmath.pi*mpmath.sqrt(R))


def hertz_pressure(E_star, R, d, r):
    """Contact pressure p(r) [Pa] of a Hertz contact at depth d (0 for r > a).

    Chapter: (5.15). Derived from: (5.15) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*E_star*mpmath.sqrt(d)*mpmath.sqrt(max(0, 1 - r**2/(R*d)))/(mpmath.pi*mpmath.sqrt(R))


def hertz_pressure_displacement(E_star, a, p0, r):
    """Surface displacement u_z [m] inside a disc (r <= a) loaded by p0*(1 - r^2/a^2)^(1/2).

    Chapter: (5.16). Derived from: (5.7) over the pressure (5.15).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_hertz_displacement_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*p0*(2*a**2 - r**2)/(E_star*a)


def hertz_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) loaded by p0*(1 - r^2/a^2)^(1/2).

    Chapter: Fig. 5.2. Derived from: (5.7) over the pressure (5.15).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*p0*(2*a**2*mpmath.asin(a/r) + a*mpmath.sqrt(-a**2 + r**2) - r**2*mpmath.asin(a/r))/(E_star*a)


def hertz_pressure_force(a, p0):
    """Total force F [N] of the pressure p0*(1 - r^2/a^2)^(1/2).

    Chapter: (5.17). Derived from: the integral of (5.15) times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.pi*a**2*p0


def hertz_stiffness(E_star, R, d):
    """Differential contact stiffness dF/dd [N/m] of a Hertz contact.

    Chapter: Problem 5. Derived from: the derivative of (5.23).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_stiffness_by_punch``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return 2*E_star*mpmath.sqrt(R)*mpmath.sqrt(d)


def impact_contact_time(E_star, R, m, v0):
    """Contact time tau [s] of a sphere of mass m hitting a wall at v0 (the chapter's 2.94 x0/v0, with 2.94 = (4/5) sqrt(pi) Gamma(2/5)/Gamma(9/10)).

    Chapter: Problem 3. Derived from: twice the time integral of dx/v from 0 to x0, v from
    the energy balance.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(5))*30**(mpmath.mpf(2)/mpmath.mpf(5))*mpmath.sqrt(mpmath.pi)*m**(mpmath.mpf(2)/mpmath.mpf(5))*mpmath.gamma(mpmath.mpf(2)/mpmath.mpf(5))/(E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(1)/mpmath.mpf(5))*mpmath.gamma(mpmath.mpf(9)/mpmath.mpf(10)))


def impact_contact_time_density(E_star, R, rho, v0):
    """Contact time tau [s] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 3, m = 4/3 pi R^3 rho. Derived from: twice the time integral of dx/v
    from 0 to x0.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : mpmath.mpf
        density [kg/m^3]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(2)/mpmath.mpf(5))*2**(mpmath.mpf(1)/mpmath.mpf(5))*5**(mpmath.mpf(2)/mpmath.mpf(5))*mpmath.pi**(mpmath.mpf(9)/mpmath.mpf(10))*R*rho**(mpmath.mpf(2)/mpmath.mpf(5))*mpmath.gamma(mpmath.mpf(2)/mpmath.mpf(5))/(E_star**(mpmath.mpf(2)/mpmath.mpf(5))*v0**(mpmath.mpf(1)/mpmath.mpf(5))*mpmath.gamma(mpmath.mpf(9)/mpmath.mpf(10)))


def impact_force_scale(E_star, R, m, v0):
    """Force scale F_s = m x_s/t_s^2 [N] of the impact: m x'' = -F(x) (5.23) reads X'' = -F(x_s X)/F_s = -(4/3) X^(3/2).

    Chapter: (5.23), nondimensionalized. Derived from: m x'' = (m x_s/t_s^2) X''.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_time_and_force_scales``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5))*m**(mpmath.mpf(3)/mpmath.mpf(5))*v0**(mpmath.mpf(6)/mpmath.mpf(5))


def impact_length_scale(E_star, R, m, v0):
    """Length scale x_s [m] of the impact: (m v0^2/(E* sqrt(R)))^(2/5), with which the equation of motion reads X'' = -(4/3) X^(3/2) in T = t v0/x_s.

    Chapter: (5.23), nondimensionalized. Derived from: m v0^2/x_s = E* sqrt(R) x_s^(3/2).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_length_scale``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return m**(mpmath.mpf(2)/mpmath.mpf(5))*v0**(mpmath.mpf(4)/mpmath.mpf(5))/(E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5)))


def impact_max_contact_radius(E_star, R, m, v0):
    """Maximum contact radius [m] during the impact.

    Chapter: Problem 4. Derived from: (5.21) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*30**(mpmath.mpf(1)/mpmath.mpf(5))*R**(mpmath.mpf(2)/mpmath.mpf(5))*m**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(2)/mpmath.mpf(5))/E_star**(mpmath.mpf(1)/mpmath.mpf(5))


def impact_max_contact_radius_density(E_star, R, rho, v0):
    """Maximum contact radius [m] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: (5.21) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : mpmath.mpf
        density [kg/m^3]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*2**(mpmath.mpf(3)/mpmath.mpf(5))*5**(mpmath.mpf(1)/mpmath.mpf(5))*mpmath.pi**(mpmath.mpf(1)/mpmath.mpf(5))*R*rho**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(2)/mpmath.mpf(5))/E_star**(mpmath.mpf(1)/mpmath.mpf(5))


def impact_max_depth(E_star, R, m, v0):
    """Maximum indentation depth x0 [m] of a sphere of mass m hitting a wall at v0.

    Chapter: Problem 3. Derived from: energy conservation with (5.25).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*30**(mpmath.mpf(2)/mpmath.mpf(5))*m**(mpmath.mpf(2)/mpmath.mpf(5))*v0**(mpmath.mpf(4)/mpmath.mpf(5))/(E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5)))


def impact_max_depth_density(E_star, R, rho, v0):
    """Maximum indentation depth x0 [m] of a sphere of density rho hitting a wall.

    Chapter: Problem 3, m = 4/3 pi R^3 rho. Derived from: energy conservation with (5.25).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : mpmath.mpf
        density [kg/m^3]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*2**(mpmath.mpf(1)/mpmath.mpf(5))*5**(mpmath.mpf(2)/mpmath.mpf(5))*mpmath.pi**(mpmath.mpf(2)/mpmath.mpf(5))*R*rho**(mpmath.mpf(2)/mpmath.mpf(5))*v0**(mpmath.mpf(4)/mpmath.mpf(5))/E_star**(mpmath.mpf(2)/mpmath.mpf(5))


def impact_max_force(E_star, R, m, v0):
    """Maximum contact force [N] during the impact.

    Chapter: Problem 4. Derived from: (5.23) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(6))*30**(mpmath.mpf(3)/mpmath.mpf(5))*E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5))*m**(mpmath.mpf(3)/mpmath.mpf(5))*v0**(mpmath.mpf(6)/mpmath.mpf(5))


def impact_max_force_density(E_star, R, rho, v0):
    """Maximum contact force [N] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: (5.23) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : mpmath.mpf
        density [kg/m^3]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*2**(mpmath.mpf(4)/mpmath.mpf(5))*5**(mpmath.mpf(3)/mpmath.mpf(5))*mpmath.pi**(mpmath.mpf(3)/mpmath.mpf(5))*E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**2*rho**(mpmath.mpf(3)/mpmath.mpf(5))*v0**(mpmath.mpf(6)/mpmath.mpf(5))


def impact_max_pressure(E_star, R, m, v0):
    """Maximum contact pressure p0 [Pa] during the impact.

    Chapter: Problem 4. Derived from: (5.22) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return 30**(mpmath.mpf(1)/mpmath.mpf(5))*E_star**(mpmath.mpf(4)/mpmath.mpf(5))*m**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(2)/mpmath.mpf(5))/(mpmath.pi*R**(mpmath.mpf(3)/mpmath.mpf(5)))


def impact_max_pressure_density(E_star, rho, v0):
    """Maximum contact pressure p0 [Pa] of a sphere of density rho hitting a wall at v0 (independent of its radius).

    Chapter: Problem 4. Derived from: (5.22) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    rho : mpmath.mpf
        density [kg/m^3]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return 2**(mpmath.mpf(3)/mpmath.mpf(5))*5**(mpmath.mpf(1)/mpmath.mpf(5))*E_star**(mpmath.mpf(4)/mpmath.mpf(5))*rho**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(2)/mpmath.mpf(5))/mpmath.pi**(mpmath.mpf(4)/mpmath.mpf(5))


def impact_sphere_mass(R, rho):
    """Mass m [kg] of a solid sphere of radius R and density rho.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: the volume of the sphere times its
    density.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_sphere_mass_by_quadrature``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : mpmath.mpf
        density [kg/m^3]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*mpmath.pi*R**3*rho


def impact_time_scale(E_star, R, m, v0):
    """Time scale t_s = x_s/v0 [s] of the impact, with which the initial velocity is X'(0) = 1 in X = x/x_s, T = t/t_s.

    Chapter: (5.23), nondimensionalized. Derived from: x'(0) = v0 in the scaled variables.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_time_and_force_scales``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : mpmath.mpf
        mass [kg]
    v0 : mpmath.mpf
        impact velocity [m/s]
    """
    return m**(mpmath.mpf(2)/mpmath.mpf(5))/(E_star**(mpmath.mpf(2)/mpmath.mpf(5))*R**(mpmath.mpf(1)/mpmath.mpf(5))*v0**(mpmath.mpf(1)/mpmath.mpf(5)))


def jkr_contact_radius_from_force(E_star, F_load, R, dgamma):
    """Contact radius a [m] of a paraboloid in JKR contact under the force F_load >= -3 pi R dgamma/2 (the stable branch).

    Chapter: (5.57), JKR, inverted. Derived from: (5.57) as a quadratic in a^(3/2), larger
    root.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F_load : mpmath.mpf
        normal force, negative when adhesion pulls (adhesive contact) [N]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*(mpmath.sqrt(3)*mpmath.sqrt(R)*mpmath.sqrt(2*F_load + 3*mpmath.pi*R*dgamma) + 3*mpmath.sqrt(mpmath.pi)*R*mpmath.sqrt(dgamma))**(mpmath.mpf(2)/mpmath.mpf(3))/E_star**(mpmath.mpf(1)/mpmath.mpf(3))


def jkr_depth(E_star, R, a, dgamma):
    """Indentation depth d [m] of a paraboloid in JKR contact of radius a.

    Chapter: (5.55), JKR. Derived from: (5.52) of r^2/(2R), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return a**2/R - mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/mpmath.sqrt(E_star)


def jkr_force_from_radius(E_star, R, a, dgamma):
    """Normal force F [N] of a paraboloid in JKR contact of radius a.

    Chapter: (5.57), JKR. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    return -2*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*a**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(dgamma) + (mpmath.mpf(4)/mpmath.mpf(3))*E_star*a**3/R


def jkr_pressure(E_star, R, a, dgamma, r):
    """Contact pressure p(r) [Pa] of a paraboloid in JKR contact, r < a.

    Chapter: (5.59), JKR. Derived from: (5.59): Hertz's pressure of radius a plus the edge
    term.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Printed in a stable form: Hertz's part and the edge term apart, each with (a - r)(a + r)
    for a^2 - r^2, which loses the digits of a - r next to the edge.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return -mpmath.sqrt(2)*mpmath.sqrt(E_star)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a - r)*mpmath.sqrt(a + r)) + 2*E_star*mpmath.sqrt(a - r)*mpmath.sqrt(a + r)/(mpmath.pi*R)


def jkr_pull_off_depth_dc(E_star, dgamma, R):
    """Depth d_c [m] at pull-off of a paraboloid (JKR) under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return -mpmath.mpf(3)/mpmath.mpf(4)*mpmath.pi**(mpmath.mpf(2)/mpmath.mpf(3))*R**(mpmath.mpf(1)/mpmath.mpf(3))*dgamma**(mpmath.mpf(2)/mpmath.mpf(3))/E_star**(mpmath.mpf(2)/mpmath.mpf(3))


def jkr_pull_off_depth_fc(E_star, dgamma, R):
    """Depth d_c [m] at pull-off of a paraboloid (JKR) under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(4)*3**(mpmath.mpf(1)/mpmath.mpf(3))*mpmath.pi**(mpmath.mpf(2)/mpmath.mpf(3))*R**(mpmath.mpf(1)/mpmath.mpf(3))*dgamma**(mpmath.mpf(2)/mpmath.mpf(3))/E_star**(mpmath.mpf(2)/mpmath.mpf(3))


def jkr_pull_off_force_dc(E_star, dgamma, R):
    """Pull-off force F_c [N] (negative) of a paraboloid (JKR) under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return -mpmath.mpf(5)/mpmath.mpf(6)*mpmath.pi*R*dgamma


def jkr_pull_off_force_fc(E_star, dgamma, R):
    """Pull-off force F_c [N] (negative) of a paraboloid (JKR) under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return -mpmath.mpf(3)/mpmath.mpf(2)*mpmath.pi*R*dgamma


def jkr_pull_off_radius_dc(E_star, dgamma, R):
    """Contact radius a_c [m] at pull-off of a paraboloid (JKR) under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi**(mpmath.mpf(1)/mpmath.mpf(3))*R**(mpmath.mpf(2)/mpmath.mpf(3))*dgamma**(mpmath.mpf(1)/mpmath.mpf(3))/E_star**(mpmath.mpf(1)/mpmath.mpf(3))


def jkr_pull_off_radius_fc(E_star, dgamma, R):
    """Contact radius a_c [m] at pull-off of a paraboloid (JKR) under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*3**(mpmath.mpf(2)/mpmath.mpf(3))*mpmath.pi**(mpmath.mpf(1)/mpmath.mpf(3))*R**(mpmath.mpf(2)/mpmath.mpf(3))*dgamma**(mpmath.mpf(1)/mpmath.mpf(3))/E_star**(mpmath.mpf(1)/mpmath.mpf(3))


def jkr_zero_load_radius(E_star, dgamma, R):
    """Contact radius a_0 [m] of a paraboloid (JKR) at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*6**(mpmath.mpf(2)/mpmath.mpf(3))*mpmath.pi**(mpmath.mpf(1)/mpmath.mpf(3))*R**(mpmath.mpf(2)/mpmath.mpf(3))*dgamma**(mpmath.mpf(1)/mpmath.mpf(3))/E_star**(mpmath.mpf(1)/mpmath.mpf(3))


def line_depth_from_force(E_star, F, L):
    """Depth d [m] (in the sense of (5.35)) of a line contact under the force F.

    Chapter: (5.34), inverted. Derived from: (5.34) solved for d.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    L : mpmath.mpf
        length of a line contact [m]
    """
    return 4*F/(mpmath.pi*E_star*L)


def line_force(E_star, L, d):
    """Normal force F [N] of a line contact of length L at the depth d of (5.35).

    Chapter: (5.34). Derived from: F/L of the matched pressure with a = sqrt(R d).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    L : mpmath.mpf
        length of a line contact [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*E_star*L*d


def line_force_per_length_from_half_width(E_star, R, a):
    """Normal force per unit length F/L [N/m] of a line contact of half-width a.

    Chapter: (5.34), from the matching. Derived from: the integral of (5.36) over the strip.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*E_star*a**2/R


def line_half_width(R, d):
    """Half-width a [m] of a line contact at the (conventional) depth d.

    Chapter: (5.35). Derived from: the chapter's definition of the depth of a line contact.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.sqrt(R)*mpmath.sqrt(d)


def line_half_width_from_force(E_star, F, L, R):
    """Half-width a [m] of a line contact of length L under the force F.

    Chapter: (5.34), (5.35). Derived from: F = L F/L(a) solved for a.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    L : mpmath.mpf
        length of a line contact [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return 2*mpmath.sqrt(F)*mpmath.sqrt(R)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(E_star)*mpmath.sqrt(L))


def line_max_pressure(E_star, R, d):
    """Maximum pressure p0 [Pa] of a line contact at the depth d of (5.35).

    Chapter: (5.37), second form. Derived from: the matching, with a = sqrt(R d) (5.35).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.sqrt(d)/mpmath.sqrt(R)


def line_max_pressure_depth_width(E_star, a, d):
    """Maximum pressure p0 [Pa] of a line contact from its depth and half-width.

    Chapter: (5.37), first form. Derived from: the matching, with R = a^2/d (5.35).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*d/a


def line_max_pressure_from_force(E_star, F, L, R):
    """Maximum pressure p0 [Pa] of a line contact of length L under the force F.

    Chapter: (5.37), third form. Derived from: the matching, with a from F = L F/L(a).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Differs from the print (see docs/errata.md): a factor pi is missing under the root: p0 =
    (E* F/(pi L R))^(1/2) (from p0 = E* a/(2R) and F/L = pi a p0/2; the print is sqrt(pi) =
    1.77 times too large)

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    L : mpmath.mpf
        length of a line contact [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    return mpmath.sqrt(E_star)*mpmath.sqrt(F)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(L)*mpmath.sqrt(R))


def line_max_pressure_from_half_width(E_star, R, a):
    """Maximum pressure p0 [Pa] of a line contact of half-width a.

    Chapter: (5.37), from the matching. Derived from: the gradient of the 2-D surface
    displacement matched to -x/R.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*a/R


def line_pressure(E_star, R, d, x):
    """Pressure p(x) [Pa] of a line contact at the depth d of (5.35) (0 outside).

    Chapter: (5.36). Derived from: (5.36) with the matched p0.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.sqrt(d)*mpmath.sqrt(max(0, 1 - x**2/(R*d)))/mpmath.sqrt(R)


def line_stiffness(E_star, L):
    """Differential stiffness dF/dd [N/m] of a line contact of length L (with d defined by (5.35)).

    Chapter: (5.34), differentiated. Derived from: the derivative of (5.34).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_stiffness_by_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    L : mpmath.mpf
        length of a line contact [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*mpmath.pi*E_star*L


def line_stress_axis_max_shear(a, p0, z):
    """Principal shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis of a line contact.

    Chapter: (5.36), Flamant. Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return a*p0*z/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2)))


def line_stress_axis_max_shear_slope(a, p0, z):
    """D(tau_1)/dz [Pa/m] on the axis of a line contact; its root is the depth of the largest tau_1.

    Chapter: (5.36), Flamant. Derived from: the derivative of tau_1.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a*p0*z**2/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(z + mpmath.sqrt(a**2 + z**2))) + a*p0*z*(-z/mpmath.sqrt(a**2 + z**2) - 1)/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + a*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2)))


def line_stress_axis_sigma_xx(a, p0, z):
    """Normal stress sigma_xx [Pa] on the axis of a line contact of half-width a.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over the line pressure (5.36)
    along the axis x = 0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_stresses_by_superposition``.

    Printed in a stable form: the derived form subtracts terms of size z/a to leave one of
    size (a/z)^3; -p0 a^3/(s (s + z)^2), s = (a^2 + z^2)^(1/2), has none.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2)


def line_stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis of a line contact of half-width a.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over the line pressure (5.36)
    along the axis x = 0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a*p0/mpmath.sqrt(a**2 + z**2)


def line_stress_axis_von_mises(a, nu, p0, z):
    """Von Mises stress [Pa] on the axis of a line contact (plane strain).

    Chapter: (5.50), (5.36). Derived from: (5.50) with the axis stresses and sigma_yy = nu
    (sigma_xx + sigma_zz).

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Printed in a stable form: (5.50) expanded subtracts squares of size p0^2; with c =
    (sigma_xx + sigma_zz)/2 it is ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return mpmath.sqrt(3*a**2*p0**2*z**2/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-mpmath.mpf(1)/mpmath.mpf(2)*a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - mpmath.mpf(1)/mpmath.mpf(2)*a*p0/mpmath.sqrt(a**2 + z**2))**2)


def line_stress_axis_von_mises_slope(a, nu, p0, z):
    """D(sigma_vM)/dz [Pa/m] on the axis of a line contact; its root is the depth of the largest von Mises stress.

    Chapter: (5.50), (5.36). Derived from: the derivative.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (-3*a**2*p0**2*z**3/((a**2 + z**2)**2*(z + mpmath.sqrt(a**2 + z**2))**2) + (mpmath.mpf(3)/mpmath.mpf(2))*a**2*p0**2*z**2*(-2*z/mpmath.sqrt(a**2 + z**2) - 2)/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**3) + 3*a**2*p0**2*z/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + (mpmath.mpf(1)/mpmath.mpf(2))*(1 - 2*nu)**2*(-mpmath.mpf(1)/mpmath.mpf(2)*a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - mpmath.mpf(1)/mpmath.mpf(2)*a*p0/mpmath.sqrt(a**2 + z**2))*(a**3*p0*z/((a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))*(z + mpmath.sqrt(a**2 + z**2))**2) - a**3*p0*(-2*z/mpmath.sqrt(a**2 + z**2) - 2)/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**3) + a*p0*z/(a**2 + z**2)**(mpmath.mpf(3)/mpmath.mpf(2))))/mpmath.sqrt(3*a**2*p0**2*z**2/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-mpmath.mpf(1)/mpmath.mpf(2)*a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - mpmath.mpf(1)/mpmath.mpf(2)*a*p0/mpmath.sqrt(a**2 + z**2))**2)


def line_stress_principal_max(sigma_xx, sigma_zz, tau_xz):
    """Largest principal stress [Pa] in the x-z plane.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Printed in a stable form: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx
    sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded
    surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is
    a sum of squares.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*sigma_xx + (mpmath.mpf(1)/mpmath.mpf(2))*sigma_zz + mpmath.sqrt(tau_xz**2 + (mpmath.mpf(1)/mpmath.mpf(4))*(sigma_xx - sigma_zz)**2)


def line_stress_principal_min(sigma_xx, sigma_zz, tau_xz):
    """Smallest principal stress [Pa] in the x-z plane.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Printed in a stable form: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx
    sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded
    surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is
    a sum of squares.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*sigma_xx + (mpmath.mpf(1)/mpmath.mpf(2))*sigma_zz - mpmath.sqrt(tau_xz**2 + (mpmath.mpf(1)/mpmath.mpf(4))*(sigma_xx - sigma_zz)**2)


def line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz):
    """Principal shear stress tau_1 [Pa] in the x-z plane.

    Chapter: plane stress state x-z. Derived from: half the difference of the principal
    stresses.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Printed in a stable form: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx
    sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded
    surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is
    a sum of squares.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return mpmath.sqrt(tau_xz**2 + (mpmath.mpf(1)/mpmath.mpf(4))*(sigma_xx - sigma_zz)**2)


def line_stress_sigma_xx_core(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -p0*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*(2*x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))))/(a*(z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_xx_deep(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*z**2*(2*a**2*z**2*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) + 2*x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))/((z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_xx_side(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*z**2*(2*a**2*x*z**3/((x*z/mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) - z**2 - (a - x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((x*z/mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_yy(nu, sigma_xx, sigma_zz):
    """Out-of-plane stress sigma_yy [Pa] in plane strain.

    Chapter: plane strain. Derived from: eps_yy = (sigma_yy - nu (sigma_xx + sigma_zz))/E =
    0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    """
    return nu*(sigma_xx + sigma_zz)


def line_stress_sigma_zz_core(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -p0*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(a*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_zz_deep(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*z**2*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_zz_side(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*x*z**3/(mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_core(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return p0*mpmath.sqrt(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z**2)*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))/(a*(z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*mpmath.sqrt(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_deep(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return 2*a*p0*z**2*mpmath.sqrt(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z**2)/((z + mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*mpmath.sqrt(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_side(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return 2*a*p0*z**2*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((x*z/mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*mpmath.sqrt(x**2*z**2/(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_core(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -p0*x*z*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))/(a*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_deep(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*x*z**3/(mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_side(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -2*a*p0*z**2*mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z**2 + (-a + x)*(a + x) + mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_slope_x(a, p0, x, z):
    """D(tau_xz)/dx [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: -(z/pi) Im F'' of the Cauchy integral F of the
    pressure.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_orthogonal_shear_maximum``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a*p0*z*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(-3*x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))**3


def line_stress_tau_xz_slope_z(a, p0, x, z):
    """D(tau_xz)/dz [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: -(Im F' + z Re F'')/pi of the Cauchy integral F
    of the pressure.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_orthogonal_shear_maximum``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : mpmath.mpf
        coordinate [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.pi*a*p0*x*z**2*(-x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(3)/mpmath.mpf(2))*z**2 + (mpmath.mpf(3)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))**3) - mpmath.pi*p0*(-x*z**2/mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + x*mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))/(a*(x**2*z**2/((mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(a - x)*(a + x) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))))/mpmath.pi


def line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz):
    """Von Mises stress [Pa] of a plane-strain state (sigma_yy = nu (sigma_xx + sigma_zz), tau_xy = tau_yz = 0).

    Chapter: (5.50), plane strain. Derived from: (5.50) with the plane-strain sigma_yy.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Printed in a stable form: (5.50) expanded subtracts products of size p0^2 (it goes
    negative at the surface for nu = 1/2, where it is 0); ((1 - 2 nu)^2 c^2 + 3
    tau_1^2)^(1/2), c = (sigma_xx + sigma_zz)/2, has only squares.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return mpmath.sqrt(3*tau_xz**2 + (1 - 2*nu)**2*((mpmath.mpf(1)/mpmath.mpf(2))*sigma_xx + (mpmath.mpf(1)/mpmath.mpf(2))*sigma_zz)**2 + (mpmath.mpf(3)/mpmath.mpf(4))*(sigma_xx - sigma_zz)**2)


def line_stress_von_mises_c_tau(nu, c_mean, tau_1):
    """Von Mises stress [Pa] of a plane-strain state from its mean in-plane stress c = (sigma_xx + sigma_zz)/2 and tau_1.

    Chapter: (5.50), plane strain. Derived from: line_stress_von_mises with sigma_xx,
    sigma_zz = c +- tau_1, tau_xz = 0 (the same Mohr circle).

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    c_mean : mpmath.mpf
        mean in-plane normal stress (sigma_xx + sigma_zz)/2 (plane strain) [Pa]
    tau_1 : mpmath.mpf
        principal shear stress in the x-z plane, the radius of Mohr's circle [Pa]
    """
    return mpmath.sqrt(c_mean**2*(1 - 2*nu)**2 + 3*tau_1**2)


def masing_unloading_force(F_amp, F_half):
    """Tangential force F_x [N] on the branch from a turning point: F_x* - 2 F_x,mono(D/2).

    Chapter: Masing's rule, derived from the springs. Derived from: per spring, unloaded by
    D from u*: f* - f = 2 min(G* D/2, mu q_z) (case check).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_history_solver_follows_masing``.

    Parameters
    ----------
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    F_half : mpmath.mpf
        tangential force of the monotonic loading at half the displacement travelled since the turning point [N]
    """
    return F_amp - 2*F_half


def mdr_depth_of_line_load(E_star, g_x, q_z):
    """Depth d [m] at which the MDR spring with gap g(x) carries the line load q_z.

    Chapter: (5.58), inverted. Derived from: q_z = E* (d - g(x)) solved for d.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_normal_line_load_against_the_normal_force``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    g_x : mpmath.mpf
        MDR profile g(x) at the spring's coordinate x (5.52) [m]
    q_z : mpmath.mpf
        normal line load of the MDR springs, force per unit length (5.58) [N/m]
    """
    return g_x + q_z/E_star


def mdr_force(E_star, a, d, g_integral):
    """Normal force F [N] of the MDR at the contact radius a and depth d = g(a), from the integral of g over [0, a].

    Chapter: (5.57). Derived from: (5.57) with (5.55) for any g(x).

    Derivation: ``hertzmdr.derive.numerical_mdr``. Verified by
    ``tests/test_mdr.py::test_mdr_force_by_the_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    g_integral : mpmath.mpf
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    """
    return 2*E_star*(a*d - g_integral)


def mdr_kink_G(b, slope_jump, x):
    """Integral from b to x > b [m^2] of mdr_kink_g: the kink's part of the integral of g in the force (5.57).

    Chapter: (5.57). Derived from: integral of mdr_kink_g by parts (x g - integral of y g').

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_G_by_quadrature``.

    Printed in a stable form: acosh of an argument near 1 loses digits as x -> b (as in
    mdr_kink_g); the two terms still cancel to a relative (x - b)/b, which is rounding of
    the integral of g it is added to.

    Parameters
    ----------
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return b*slope_jump*(2*x*mpmath.asinh((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(-b + x)/mpmath.sqrt(b)) - mpmath.sqrt(-b + x)*mpmath.sqrt(b + x))


def mdr_kink_g(b, slope_jump, x):
    """Integral from b to x > b [m] of the branch-point term of g' at a kink r = b.

    Chapter: (5.52). Derived from: integral of mdr_kink_gprime.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_g_by_quadrature``.

    Printed in a stable form: acosh of an argument 1 + (x - b)/(4b) loses digits as x -> b
    (relative eps b/(x - b)); it is written 2 asinh(sqrt((x - b)/(2b))).

    Parameters
    ----------
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return 2*b*slope_jump*mpmath.asinh((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(-b + x)/mpmath.sqrt(b))


def mdr_kink_gprime(b, slope_jump, x):
    """Branch-point term b s/sqrt(x^2 - b^2) [1] of g'(x), x > b, at a kink r = b where f' jumps by s.

    Chapter: (5.52). Derived from: lim sqrt(x^2 - b^2) g'(x), x -> b, of (5.52) for f = s (r
    - b).

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_gprime_is_the_singular_part_of_52``.

    Parameters
    ----------
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return b*slope_jump/(mpmath.sqrt(-b + x)*mpmath.sqrt(b + x))


def mdr_kink_pressure(E_star, a, b, r, slope_jump):
    """Pressure p(r) [Pa] of the branch-point term b s/sqrt(x^2 - b^2) of g' at a kink r = b < a where f' jumps by s (log-infinite at r = b, 0 for r >= a).

    Chapter: (5.59). Derived from: (5.59) of the singular part of g' for f = s (r - b), r >
    b.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_pressure_by_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    """
    return E_star*b*slope_jump*mpmath.ellipf(mpmath.atan2(mpmath.sqrt(max(0, (a - max(b, r))*(a + max(b, r)))), mpmath.sqrt(max(b, r) - min(b, r))*mpmath.sqrt(max(b, r) + min(b, r))), min(b, r)**2/max(b, r)**2)/(mpmath.pi*max(b, r))


def mdr_normal_line_load(E_star, d, g_x):
    """Normal line load q_z [N/m] of the MDR spring at x with gap g(x) at depth d (in contact for d > g(x); pass g(x) capped at d for the springs out of contact).

    Chapter: (5.58). Derived from: the spring stiffness E* per unit length (5.51) times its
    compression d - g(x) (5.55).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_normal_line_load_against_the_normal_force``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    d : mpmath.mpf
        indentation depth [m]
    g_x : mpmath.mpf
        MDR profile g(x) at the spring's coordinate x (5.52) [m]
    """
    return E_star*(d - g_x)


def mdr_stiffness(E_star, a):
    """Differential normal stiffness dF/dd = 2 a E* [N/m] of an axisymmetric contact of radius a.

    Chapter: (5.12), Problem 5. Derived from: dF/dd of (5.57) with d = g(a) (5.55).

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_stiffness_by_differentiation``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*E_star*a


def mdr_tangential_line_load(G_star, w_x):
    """Tangential line load q_x [N/m] of the MDR spring sheared elastically by w.

    Chapter: MDR tangential springs (not in the chapter). Derived from: the tangential
    spring stiffness G* per unit length times its shear w.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_line_load_against_the_stiffness``.

    Parameters
    ----------
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    w_x : mpmath.mpf
        elastic shear displacement of an MDR tangential spring [m]
    """
    return G_star*w_x


def mdr_tangential_spring_shear(G_star, q_x):
    """Elastic shear w [m] of the MDR spring that carries the tangential line load q_x (the slip that a spring's excess over Coulomb's limit gives up).

    Chapter: MDR tangential springs (not in the chapter). Derived from: q_x = G* w solved
    for w.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_line_load_against_the_stiffness``.

    Parameters
    ----------
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    q_x : mpmath.mpf
        tangential line load of the MDR springs, force per unit length [N/m]
    """
    return q_x/G_star


def mindlin_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle of a tangential force oscillating with amplitude F_amp at constant normal force F (paraboloid).

    Chapter: Mindlin-Deresiewicz (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops 4 mu q_z (u* - mu q_z/G*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_mindlin_deresiewicz_energy``.

    Printed in a stable form: the integrand vanishes to second order at the edge: (1 -
    c/a)^3 P(c/a) with 1 - c/a = -expm1(log1p(-F_amp/(mu F))/3) keeps the cubic law to
    rounding.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return -mpmath.mpf(1)/mpmath.mpf(5)*(3*F**2*mu_f**2*mpmath.exp((mpmath.mpf(2)/mpmath.mpf(3))*mpmath.log1p(-F_amp/(F*mu_f))) + 9*F**2*mu_f**2*mpmath.exp((mpmath.mpf(1)/mpmath.mpf(3))*mpmath.log1p(-F_amp/(F*mu_f))) + 3*F**2*mu_f**2)*mpmath.expm1((mpmath.mpf(1)/mpmath.mpf(3))*mpmath.log1p(-F_amp/(F*mu_f)))**3/(G_star*a)


def mindlin_energy_small(a, F, G_star, mu_f, F_amp):
    """Leading term [J] of the energy per cycle of a paraboloid at small amplitude F_amp.

    Chapter: Mindlin-Deresiewicz (not in the chapter). Derived from: series of
    mindlin_energy in F_amp.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cubic_small_amplitude_law``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return (mpmath.mpf(1)/mpmath.mpf(9))*F_amp**3/(F*G_star*a*mu_f)


def paraboloid_g(R, x):
    """MDR profile g(x) [m] of the paraboloid f = r^2/(2R) (the springs' gap; d = g(a)).

    Chapter: (5.52) of f = r^2/(2R). Derived from: (5.52) of r^2/(2R).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_g_against_the_mdr_transform``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return x**2/R


def paraboloid_profile(R, r):
    """Height f(r) [m] of the paraboloid above its tip (the profile whose g is paraboloid_g).

    Chapter: (5.52). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*r**2/R


def powerlaw_contact_radius(c_n, d, kappa_n, n):
    """Contact radius a [m] of a power-law indenter at depth d.

    Chapter: Problem 7(d). Derived from: (5.55) with g of (5.52).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : mpmath.mpf
        indentation depth [m]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return (d/(c_n*kappa_n))**(1/n)


def powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law indenter under the force F.

    Chapter: Problem 7(d), inverted. Derived from: the force of Problem 7(d) solved for d.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_roundtrip``.

    Printed in a stable form: (kappa_n c_n)^(1/n) of the derived form overflows or
    underflows for small n although d is ordinary (c_n = 1e-3, n = 3 at F = 1 N: NaN); split
    into (F (n + 1)/(2 E* n))^(n/(n + 1)) (kappa_n c_n)^(1/(n + 1)), whose factors stay
    within the range of the inputs.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return (c_n*kappa_n)**(1/(n + 1))*((mpmath.mpf(1)/mpmath.mpf(2))*F*(n + 1)/(E_star*n))**(n/(n + 1))


def powerlaw_displacement_far(a, d, n, r):
    """Surface displacement u_z(r) [m] of a power-law indenter far outside the contact (a/r < 1e-3: the series to (a/r)^7).

    Chapter: Problem 7(d), (5.60), r >> a. Derived from: (5.60) with 1/sqrt(r^2 - x^2)
    expanded in (x/r)^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_surface_displacement_far_outside``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*a*d*n*(a**2*(a**2*(a**2*(5*n + 5)/(r**2*(112*n + 784)) + (3*n + 3)/(40*n + 200))/r**2 + (n + 1)/(6*n + 18))/r**2 + 1)/(mpmath.pi*r*(n + 1))


def powerlaw_displacement_outside(a, d, n, r):
    """Surface displacement u_z(r) [m] outside the contact (r > a) of a power-law indenter.

    Chapter: Problem 7(d), (5.60). Derived from: (5.60) for r > a.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*d*(-a*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), (mpmath.mpf(1)/mpmath.mpf(2))*n + mpmath.mpf(1)/mpmath.mpf(2)), ((mpmath.mpf(1)/mpmath.mpf(2))*n + mpmath.mpf(3)/mpmath.mpf(2),), a**2/r**2)/r + (n + 1)*mpmath.asin(a/r))/(mpmath.pi*(n + 1))


def powerlaw_displacement_outside_integrand(a, d, n, r, w_out):
    """Integrand [m] of (5.60) in w: u_z(r > a) = integral_0^asin(a/r) of it dw, positive and smooth (a layer of width ~1/(n cot(asin(a/r))) at w = 0 for large n).

    Chapter: Problem 7(d), (5.60). Derived from: (5.60) with x = r sin(asin(a/r) - w).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_displacement_outside_large_n``.

    Printed in a stable form: (x/a)^n with x/a = 1 - O(1/n) amplifies its rounding n-fold
    and r^2 - a^2 overflows for r > 1e154; written -expm1(n log1p(-2 sin(w/2)^2 - sqrt(r -
    a) sqrt(r + a) sin(w)/a)).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    w_out : mpmath.mpf
        integration variable in (0, asin(a/r)) of (5.60) outside the contact: x = r sin(asin(a/r) - w) [rad]
    """
    return -2*d*mpmath.expm1(n*mpmath.log1p(-2*mpmath.sin((mpmath.mpf(1)/mpmath.mpf(2))*w_out)**2 - mpmath.sqrt(-a + r)*mpmath.sqrt(a + r)*mpmath.sin(w_out)/a))/mpmath.pi


def powerlaw_force(E_star, c_n, d, kappa_n, n):
    """Normal force F [N] of a power-law indenter at depth d.

    Chapter: Problem 7(d). Derived from: (5.57) at the contact radius of (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Differs from the print (see docs/errata.md): the factor (kappa_n c_n)^(1/n) must be
    (kappa_n c_n)^(-1/n): with a = (d/(kappa_n c_n))^(1/n), (5.57) gives F = 2n/(n+1) E* a
    d; for n = 2 (kappa_2 c_2 = 1/R) only the corrected form reproduces (5.23)

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : mpmath.mpf
        indentation depth [m]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*d*n*(d/(c_n*kappa_n))**(1/n)/(n + 1)


def powerlaw_force_from_radius(E_star, a, d, n):
    """Normal force F [N] of a power-law indenter with contact radius a at depth d.

    Chapter: Problem 7(d), (5.57). Derived from: (5.57) with d = g(a) (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*a*d*n/(n + 1)


def powerlaw_g(c_n, kappa_n, n, x):
    """MDR profile g(x) [m] of the power-law profile f = c_n r^n, x >= 0.

    Chapter: Problem 7(d). Derived from: (5.52) for f = c_n r^n.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_g_by_quadrature``.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return c_n*kappa_n*x**n


def powerlaw_kappa(n):
    """MDR factor kappa_n [1] of the power-law profile, g = kappa_n c_n |x|^n (overflows for n > 340: use powerlaw_kappa_asymptotic there).

    Chapter: Problem 7(d). Derived from: (5.52) for f = c_n r^n.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_kappa_by_quadrature``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return mpmath.sqrt(mpmath.pi)*mpmath.gamma((mpmath.mpf(1)/mpmath.mpf(2))*n + 1)/mpmath.gamma((mpmath.mpf(1)/mpmath.mpf(2))*n + mpmath.mpf(1)/mpmath.mpf(2))


def powerlaw_kappa_asymptotic(n):
    """Kappa_n [1] from the Stirling series to O(n^-10); relative error < 1e-16 for n >= 40.

    Chapter: Problem 7(d), large n. Derived from: the Stirling series of ln Gamma(n/2 + 1) -
    ln Gamma(n/2 + 1/2).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_kappa_by_quadrature``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(mpmath.pi)*mpmath.sqrt(n)*mpmath.exp(2*n**(mpmath.mpf((1, 1, 0, 1)))*(4*n**(mpmath.mpf((1, 1, 1, 1)))*(4*n**(mpmath.mpf((1, 1, 1, 1)))*(4*n**(mpmath.mpf((1, 1, 1, 1)))*((mpmath.mpf(31)/mpmath.mpf(4608))*n**(mpmath.mpf((1, 1, 1, 1))) + mpmath.mpf(-17)/mpmath.mpf(14336)) + mpmath.mpf(1)/mpmath.mpf(640)) + mpmath.mpf(-1)/mpmath.mpf(192)) + mpmath.mpf(1)/mpmath.mpf(8)))


def powerlaw_mean_pressure(E_star, a, d, n):
    """Mean pressure F/(pi a^2) [Pa] of a power-law indenter.

    Chapter: Fig. 5.17. Derived from: (5.57) over the contact area.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*d*n/(mpmath.pi*a*(n + 1))


def powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n):
    """Mean pressure F/(pi a^2) [Pa] of a power-law indenter at depth d.

    Chapter: Fig. 5.17. Derived from: (5.57) over the contact area, a from (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Printed in a stable form: the contact radius a = (d/(kappa_n c_n))^(1/n) underflows to 0
    for small n where F/(pi a^2) is still a float (and overflows where it is not): one power
    of the ratio kappa_n c_n/d, times d.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : mpmath.mpf
        indentation depth [m]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*d*n*(c_n*kappa_n/d)**(1/n)/(mpmath.pi*(n + 1))


def powerlaw_pressure(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; accurate for n >= 1.5 (use powerlaw_pressure_small_n below).

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x = r/sqrt(1 - z t), then
    Euler's transformation.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*d*n*mpmath.hyper((1, 1 - mpmath.mpf(1)/mpmath.mpf(2)*n), (mpmath.mpf(3)/mpmath.mpf(2),), max(0, (a - r)*(a + r))/a**2)*mpmath.sqrt(max(0, (a - r)*(a + r)))/(mpmath.pi*a**2)


def powerlaw_pressure_centre(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter near the centre, 0 < n < 3 (n != 1), r < a/10: the series to (r/a)^18 plus its (r/a)^(n-1) term.

    Chapter: Problem 7(d), (5.59), r << a. Derived from: the 2F1 of (5.59) by the connection
    formula z -> 1 - z (DLMF 15.8.4).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_pressure_near_the_centre_by_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*d*n*((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(mpmath.pi)*(r/a)**(n - 1)*mpmath.gamma(mpmath.mpf(1)/mpmath.mpf(2) - mpmath.mpf(1)/mpmath.mpf(2)*n)/mpmath.gamma(1 - mpmath.mpf(1)/mpmath.mpf(2)*n) + 1/(n - 1) + r**2*(1/(2*n - 6) + r**2*(3/(8*n - 40) + r**2*(5/(16*n - 112) + r**2*(35/(128*n - 1152) + r**2*(63/(256*n - 2816) + r**2*(231/(1024*n - 13312) + r**2*(429/(2048*n - 30720) + r**2*(6435/(32768*n - 557056) + 12155*r**2/(a**2*(65536*n - 1245184)))/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/(mpmath.pi*a)


def powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad):
    """Integrand [Pa] of (5.59) in w: p(r) = integral_0^1 of it dw, smooth in w (a boundary layer of width ~1/(n (1 - r^2/a^2)) at w = 0 for large n).

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x^2 = r^2 + (a^2 - r^2)(1 -
    w)^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_pressure_large_n_by_quadrature``.

    Printed in a stable form: (x/a)^(n-2) with x/a = 1 - O(1/n) amplifies its rounding
    n-fold and overflows/underflows in parts; written exp((n/2 - 1) log1p(-(1 - x^2/a^2)))
    with 1 - x^2/a^2 factored.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    w_quad : mpmath.mpf
        integration variable in (0, 1) of (5.59): x^2 = r^2 + (a^2 - r^2)(1 - w)^2 [1]
    """
    return E_star*d*n*mpmath.sqrt(a - r)*mpmath.sqrt(a + r)*mpmath.exp(((mpmath.mpf(1)/mpmath.mpf(2))*n - 1)*mpmath.log1p(-w_quad*(2 - w_quad)*(a - r)*(a + r)/a**2))/(mpmath.pi*a**2)


def powerlaw_pressure_n1(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 1 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 1. Derived from: (5.59) for f = c_1 r^1.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*d*mpmath.log((a + mpmath.sqrt(a**2 - r**2))/r)/(mpmath.pi*a)


def powerlaw_pressure_n2(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 2 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 2. Derived from: (5.59) for f = c_2 r^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*E_star*d*mpmath.sqrt(a**2 - r**2)/(mpmath.pi*a**2)


def powerlaw_pressure_n3(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 3 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 3. Derived from: (5.59) for f = c_3 r^3.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(3)/mpmath.mpf(2))*E_star*d*(a*mpmath.sqrt(a**2 - r**2) - r**2*mpmath.log(r) + r**2*mpmath.log(a + mpmath.sqrt(a**2 - r**2)))/(mpmath.pi*a**3)


def powerlaw_pressure_n4(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 4 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 4. Derived from: (5.59) for f = c_4 r^4.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*E_star*d*mpmath.sqrt(a**2 - r**2)*(a**2 + 2*r**2)/(mpmath.pi*a**4)


def powerlaw_pressure_normalized(n, r_tilde):
    """Normalized pressure p/p_mean [1] at r_tilde = r/a < 1 of a power-law indenter (n >= 1.5).

    Chapter: Fig. 5.17. Derived from: (5.59) divided by (5.57)/(pi a^2).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_normalized_pressure_by_quadrature``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r_tilde : mpmath.mpf
        normalized radius r/a [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*(n + 1)*mpmath.hyper((1, 1 - mpmath.mpf(1)/mpmath.mpf(2)*n), (mpmath.mpf(3)/mpmath.mpf(2),), max(0, (1 - r_tilde)*(r_tilde + 1)))*mpmath.sqrt(max(0, (1 - r_tilde)*(r_tilde + 1)))


def powerlaw_pressure_small_n(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; the form accurate for n < 1.5 (singular like r^(n-1) at the centre for n < 1).

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x = r/sqrt(1 - z t).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*a**(-n)*d*n*r**(n - 1)*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), (mpmath.mpf(1)/mpmath.mpf(2))*n + mpmath.mpf(1)/mpmath.mpf(2)), (mpmath.mpf(3)/mpmath.mpf(2),), max(0, (a - r)*(a + r))/a**2)*mpmath.sqrt(max(0, (a - r)*(a + r)))/(mpmath.pi*a)


def powerlaw_profile(c_n, n, r):
    """Height f(r) = c_n r^n [m] of a power-law profile above its tip (the profile whose g is powerlaw_g).

    Chapter: Problem 7(d). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return c_n*r**n


def powerlaw_punch_displacement_outside(a, d, r):
    """Surface displacement u_z(r) [m] outside a flat punch (r > a).

    Chapter: Problem 7(a). Derived from: the n -> infinity limit of (5.60) for the power
    law.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*d*mpmath.asin(a/r)/mpmath.pi


def powerlaw_punch_force(E_star, a, d):
    """Normal force F [N] of a flat rigid punch of radius a at depth d.

    Chapter: Problem 7(a). Derived from: the n -> infinity limit of (5.57) for the power
    law.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return 2*E_star*a*d


def powerlaw_punch_mean_pressure(E_star, a, d):
    """Mean pressure F/(pi a^2) [Pa] of a flat rigid punch of radius a at depth d.

    Chapter: Problem 7(a). Derived from: the punch's force over the contact area.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return 2*E_star*d/(mpmath.pi*a)


def powerlaw_punch_pressure(E_star, a, d, r):
    """Contact pressure p(r) [Pa] under a flat rigid punch of radius a at depth d, r < a.

    Chapter: Problem 7(a). Derived from: (5.59) with q' = -E* d delta(x - a).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*d/(mpmath.pi*mpmath.sqrt(a**2 - r**2))


def punch_depth_from_force(E_star, F, a):
    """Indentation depth d [m] of a flat rigid punch of radius a under the force F.

    Chapter: (5.11), inverted. Derived from: (5.11) F = 2 E* a d solved for d.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_punch_round_trip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    a : mpmath.mpf
        contact radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F/(E_star*a)


def punch_pressure_displacement(E_star, a, p0):
    """Surface displacement u_z [m] inside a disc loaded by p0*(1 - r^2/a^2)^(-1/2).

    Chapter: (5.10). Derived from: (5.7) over the pressure (5.9).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_punch_displacement_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return mpmath.pi*a*p0/E_star


def punch_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) loaded by p0*(1 - r^2/a^2)^(-1/2).

    Chapter: Fig. 5.2 (n = -1/2), Problem 7(a). Derived from: (5.7) over the pressure (5.9).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*a*p0*mpmath.asin(a/r)/E_star


def punch_pressure_force(a, p0):
    """Total force F [N] of the pressure p0*(1 - r^2/a^2)^(-1/2).

    Chapter: (5.11). Derived from: the integral of (5.9) times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return 2*mpmath.pi*a**2*p0


def punch_stiffness(E_star, a):
    """Stiffness k = F/u_z [N/m] of a flat rigid circular punch of radius a.

    Chapter: (5.12). Derived from: (5.11) divided by (5.10).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_punch_stiffness_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*E_star*a


def shear_modulus(E, nu):
    """Shear modulus G [Pa] of an isotropic body.

    Chapter: Lame's mu (not in the chapter). Derived from: Hooke's law in Lame's form.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return E/(2*nu + 2)


def sphere_depth(R, a):
    """Indentation depth d [m] of a rigid spherical cap at the contact radius a < R.

    Chapter: (5.55), Sneddon's sphere. Derived from: (5.55), d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Printed in a stable form: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R
    - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*a*mpmath.log1p(2*a/(R - a))


def sphere_force_from_radius(E_star, R, a):
    """Normal force F [N] of a rigid spherical cap at the contact radius a < R.

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) with d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Printed in a stable form: (a^2 + R^2) atanh(a/R) - a R cancels as (a/R)^2 for a << R;
    below a = R/2 it is written E* R^2 (b^2 atanh(b) + (b^3/3) 2F1(1, 3/2; 5/2; b^2)), b =
    a/R, above it with atanh in log1p.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return ((E_star*R**2*((mpmath.mpf(1)/mpmath.mpf(2))*a**2*mpmath.log1p(2*a/(R - a))/R**2 + (mpmath.mpf(1)/mpmath.mpf(3))*a**3*mpmath.hyper((1, mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(5)/mpmath.mpf(2),), a**2/R**2)/R**3)) if (a < (mpmath.mpf(1)/mpmath.mpf(2))*R) else (E_star*(-R*a + (mpmath.mpf(1)/mpmath.mpf(2))*(R**2 + a**2)*mpmath.log1p(2*a/(R - a)))))


def sphere_g(R, x):
    """MDR profile g(x) [m] of the spherical cap, 0 <= x < R.

    Chapter: (5.52), Sneddon's sphere. Derived from: (5.52) with r = sqrt(x^2 - v^2).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Printed in a stable form: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R
    - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*x*mpmath.log1p(2*x/(R - x))


def sphere_lam_contact_radius(R, lam):
    """Contact radius a = R tanh(lam) [m] of a rigid spherical cap.

    Chapter: (5.55), Sneddon's sphere. Derived from: the definition lam = atanh(a/R).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    return R*mpmath.tanh(lam)


def sphere_lam_depth(R, lam):
    """Indentation depth d [m] of a rigid spherical cap at lam = atanh(a/R).

    Chapter: (5.55), Sneddon's sphere. Derived from: (5.55) at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    return R*lam*mpmath.tanh(lam)


def sphere_lam_force(E_star, R, lam):
    """Normal force F [N] of a rigid spherical cap at lam = atanh(a/R).

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Printed in a stable form: (1 + tanh(lam)^2) lam - tanh(lam) cancels as lam^2 for small
    lam; below lam = 1/2 it is written with (b^3/3) 2F1(1, 3/2; 5/2; b^2) for lam - b, b =
    tanh(lam).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    return ((E_star*R**2*(lam*mpmath.tanh(lam)**2 + (mpmath.mpf(1)/mpmath.mpf(3))*mpmath.tanh(lam)**3*mpmath.hyper((1, mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(5)/mpmath.mpf(2),), mpmath.tanh(lam)**2))) if (lam < mpmath.mpf(1)/mpmath.mpf(2)) else (E_star*R**2*(lam*(mpmath.tanh(lam)**2 + 1) - mpmath.tanh(lam))))


def sphere_lam_pressure_pole(E_star, R, lam, r):
    """The part of the contact pressure p(r) [Pa] of a rigid spherical cap from the pole R x/(R^2 - x^2) of g'(x), at lam = atanh(a/R), 0 <= r < a.

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) with x^2 = r^2 + w^2, w =
    sqrt(R^2 - r^2) tanh(u).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Printed in a stable form: atanh(k/c), k^2 = a^2 - r^2, c^2 = R^2 - r^2, loses 1 - k/c as
    a -> R; it is written log1p(2k(c + k) cosh(lam)^2/R^2)/2.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*R*mpmath.log1p(2*mpmath.sqrt(R*mpmath.tanh(lam) - r)*mpmath.sqrt(R*mpmath.tanh(lam) + r)*(mpmath.sqrt(R - r)*mpmath.sqrt(R + r) + mpmath.sqrt(R*mpmath.tanh(lam) - r)*mpmath.sqrt(R*mpmath.tanh(lam) + r))*mpmath.cosh(lam)**2/R**2)/(mpmath.pi*mpmath.sqrt(R - r)*mpmath.sqrt(R + r))


def sphere_pressure_atanh_kernel(E_star, R, x):
    """Integrand (E*/pi) atanh(x/R)/x [Pa/m] of the rest of (5.59) for the spherical cap, to be integrated over w in (0, sqrt(a^2 - r^2)) at x = sqrt(r^2 + w^2).

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) of the atanh term of g', with
    x^2 = r^2 + w^2 (dx/sqrt(x^2 - r^2) = dw/x); no elementary antiderivative.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Printed in a stable form: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R
    - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.log1p(2*x/(R - x))/(mpmath.pi*x)


def sphere_profile(R, r):
    """Height f(r) [m] of a spherical cap of radius R above its apex, 0 <= r <= R.

    Chapter: (5.52), Sneddon's sphere. Derived from: the sphere x^2 + (R - z)^2 = R^2.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Printed in a stable form: R - sqrt(R^2 - r^2) cancels for r << R; it is written r^2/(R +
    sqrt((R - r)(R + r))).

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return r**2/(R + mpmath.sqrt(R - r)*mpmath.sqrt(R + r))


def sphere_stiffness(E_star, a):
    """Differential stiffness dF/dd [N/m] of a rigid spherical cap at contact radius a.

    Chapter: Problem 5, Sneddon's sphere. Derived from: (dF/da)/(dd/da) of (5.57) and
    (5.55).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_stiffness``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*E_star*a


def stress_axis_max_shear(a, nu, p0, z):
    """Maximum shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis under the Hertz pressure.

    Chapter: Fig. 5.8. Derived from: (5.48), (5.49).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(4))*p0*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*mpmath.atan(a/z))/(a*(a**2 + z**2))


def stress_axis_max_shear_bracket(a, nu):
    """Depth z_lo [m] on the axis where d(tau_1)/dz > 0 for -1 < nu <= 1/2: the lower end of the bracket [z_lo, 2a] of the maximum shear stress.

    Chapter: Fig. 5.8. Derived from: lower bounds of the terms of d(tau_1)/dz
    (stress_axis_max_shear_slope).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear_bracket``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return mpmath.pi*a*(nu + 1)/(8*nu + 20)


def stress_axis_max_shear_slope(a, nu, p0, z):
    """D(tau_1)/dz [Pa/m] on the axis under the Hertz pressure; its root is the depth of the maximum shear stress.

    Chapter: Fig. 5.8. Derived from: the derivative of tau_1.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*p0*z*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*mpmath.atan(a/z))/(a*(a**2 + z**2)**2) + (mpmath.mpf(1)/mpmath.mpf(4))*p0*(-4*a*z*(nu + 1) - 2*a*(a**2 + z**2)*(nu + 1)/(z*(a**2/z**2 + 1)) + 4*z**2*(nu + 1)*mpmath.atan(a/z) + 2*(a**2 + z**2)*(nu + 1)*mpmath.atan(a/z))/(a*(a**2 + z**2))


def stress_axis_sigma_xx(a, nu, p0, z):
    """Radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure, the form of (5.49) (for z < a).

    Chapter: (5.49). Derived from: (5.41) superposed over (5.15) along the axis.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*mpmath.atan(a/z))/(a*(a**2 + z**2))


def stress_axis_sigma_xx_deep(a, nu, p0, z):
    """Radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure (for z >= a).

    Chapter: (5.49). Derived from: (5.41) superposed over (5.15) along the axis.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Printed in a stable form: (5.49) subtracts terms of size 1 to leave one of size (a/z)^2
    (of size (a/z)^4 at nu = 1/2); 1 - atan(t)/t - t^2/(3(1 + t^2)) is written as (2/15) t^4
    2F1(2, 5/2; 7/2; -t^2), t = a/z, used for z >= a.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return p0*(-a**4*((mpmath.mpf(2)/mpmath.mpf(15))*nu + mpmath.mpf(2)/mpmath.mpf(15))*mpmath.hyper((2, mpmath.mpf(5)/mpmath.mpf(2)), (mpmath.mpf(7)/mpmath.mpf(2),), -a**2/z**2)/z**4 + a**2*(1 - 2*nu)/(z**2*(6*a**2/z**2 + 6)))


def stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis under the Hertz pressure.

    Chapter: (5.48). Derived from: (5.43) superposed over (5.15) along the axis, (5.47).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Printed in a stable form: one division, no cancellation.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a**2*p0/(a**2 + z**2)


def stress_hertz_max_orthogonal_shear(p0):
    """The largest orthogonal shear |tau_rz| [Pa] under the Hertz pressure (any nu).

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Printed in a stable form: the solved form subtracts 7 34^(1/2) from 31 2^(1/2) (a factor
    14 of cancellation); this one has 5 - 17^(1/2) = 0.88 at worst.

    Parameters
    ----------
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*p0*(5 - mpmath.sqrt(17))**(mpmath.mpf(3)/mpmath.mpf(2))/mpmath.sqrt(-5 + 3*mpmath.sqrt(17))


def stress_hertz_max_orthogonal_shear_r(a):
    """Distance r [m] from the axis of the largest |tau_rz| under the Hertz pressure.

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    """
    return a*mpmath.sqrt(mpmath.mpf(7)/mpmath.mpf(4) - mpmath.mpf(1)/mpmath.mpf(4)*mpmath.sqrt(17))


def stress_hertz_max_orthogonal_shear_z(a):
    """Depth z [m] of the largest |tau_rz| under the Hertz pressure.

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Printed in a stable form: 17^(1/2) - 4 = 0.12 cancels a factor 33; it is 1/(17^(1/2) +
    4).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    """
    return a/mpmath.sqrt(4 + mpmath.sqrt(17))


def stress_hertz_sigma_rr(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta) (for xi < 1).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : mpmath.mpf
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*(-mpmath.atan(xi) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi) + 1 - (mpmath.mpf(1)/mpmath.mpf(3))/(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


def stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at (xi, beta), for xi >= 1.

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Printed in a stable form: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written
    as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4
    overflows for xi > 1e77).

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : mpmath.mpf
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    return p0*(-chi**2*eta*xi**(mpmath.mpf((1, 1, 1, 1)))/((xi**(mpmath.mpf((1, 1, 1, 1))) + 1)*(eta**2*xi**(mpmath.mpf((1, 1, 1, 1))) + 1)) - mpmath.mpf(2)/mpmath.mpf(15)*eta*xi**(mpmath.mpf((1, 1, 2, 1)))*(nu + 1)*mpmath.hyper((1, mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(7)/mpmath.mpf(2),), -xi**(mpmath.mpf((1, 1, 1, 1))))/(xi**(mpmath.mpf((1, 1, 1, 1))) + 1) + xi**(mpmath.mpf((1, 1, 1, 1)))*(1 - 2*nu)/((3*eta + 3)*(xi**(mpmath.mpf((1, 1, 1, 1))) + 1)))


def stress_hertz_sigma_tt(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta) (for xi < 1).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    return p0*(-eta*(nu + 1)*(-xi*(-mpmath.atan(xi) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi) + 1 - (mpmath.mpf(1)/mpmath.mpf(3))/(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


def stress_hertz_sigma_tt_far(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at (xi, beta), for xi >= 1.

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Printed in a stable form: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written
    as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4
    overflows for xi > 1e77).

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    return p0*(-mpmath.mpf(2)/mpmath.mpf(15)*eta*xi**(mpmath.mpf((1, 1, 2, 1)))*(nu + 1)*mpmath.hyper((1, mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(7)/mpmath.mpf(2),), -xi**(mpmath.mpf((1, 1, 1, 1))))/(xi**(mpmath.mpf((1, 1, 1, 1))) + 1) + xi**(mpmath.mpf((1, 1, 1, 1)))*(1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**(mpmath.mpf((1, 1, 1, 1))) + 1)))


def stress_hertz_sigma_zz(p0, xi, eta):
    """Normal stress sigma_zz [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    return -eta**3*p0/(eta**2 + xi**2)


def stress_hertz_tau_rz(p0, xi, eta, chi):
    """Shear stress tau_rz [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : mpmath.mpf
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    return -chi*eta**2*p0*xi/((eta**2 + xi**2)*mpmath.sqrt(xi**2 + 1))


def stress_spheroidal_cos_beta_inside(a, r, z):
    """Cos(beta) = z/u^(1/2) [1] for r^2 + z^2 < a^2 (finite at z = 0).

    Chapter: Johnson (1985), (3.44). Derived from: z/u^(1/2) with u = 2 a^2 z^2/(D - q)
    (stress_spheroidal_u_inside): z cancels.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return mpmath.sqrt(-mpmath.mpf(1)/mpmath.mpf(2)*z**2 - mpmath.mpf(1)/mpmath.mpf(2)*(-a + r)*(a + r) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2))/a


def stress_spheroidal_u(a, r, z):
    """Johnson's u [m^2], the root of r^2/(a^2 + u) + z^2/u = 1 (for r^2 + z^2 >= a^2).

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Printed in a stable form: the expanded discriminant cancels near the contact edge; q =
    (r - a)(r + a) + z^2 keeps it exact.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*(-a + r)*(a + r) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2)


def stress_spheroidal_u_inside(a, r, z):
    """Johnson's u [m^2] for r^2 + z^2 < a^2.

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Printed in a stable form: (q + D)/2 cancels for q = r^2 + z^2 - a^2 < 0; written as 2
    a^2 z^2/(D - q).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return 2*a**2*z**2/(-z**2 - (-a + r)*(a + r) + mpmath.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2))


def stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """Von Mises equivalent stress [Pa] of the stress tensor.

    Chapter: (5.50). Derived from: sqrt(3 J2), J2 the second invariant of the stress
    deviator.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_von_mises_invariant``.

    Printed in a stable form: the expanded 3 J2 subtracts products of the stresses and
    rounds below 0 for a nearly hydrostatic state (sqrt: NaN at the centre of a Hertz
    contact with nu = 1/2); (5.50) is a sum of squares.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_yy : mpmath.mpf
        normal stress component sigma_yy [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xy : mpmath.mpf
        shear stress component tau_xy [Pa]
    tau_yz : mpmath.mpf
        shear stress component tau_yz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(6*tau_xy**2 + 6*tau_xz**2 + 6*tau_yz**2 + (sigma_xx - sigma_yy)**2 + (sigma_xx - sigma_zz)**2 + (-sigma_yy + sigma_zz)**2)


def strip_mean_pressure(F, L, a):
    """Mean pressure F/(2 a L) [Pa] over a contact strip of half-width a and length L.

    Chapter: (5.34)-(5.37). Derived from: the definition of the mean pressure over a strip.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_strip``.

    Parameters
    ----------
    F : mpmath.mpf
        normal force [N]
    L : mpmath.mpf
        length of a line contact [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F/(L*a)


def tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a cone under normal force F and tangential F_x.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^2, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: 1 - sqrt(1 - F_x/(mu F)) cancels as F_x -> 0.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return F_x/(G_star*a*(mpmath.sqrt(1 - F_x/(F*mu_f)) + 1))


def tangential_cone_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle by a cone under normal force F, amplitude F_amp.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Printed in a stable form: a - c = a x/(1 + sqrt(1 - x)), x = F_amp/(mu F), instead of a
    (1 - sqrt(1 - x)).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*F_amp**3/(F*G_star*a*mu_f*(mpmath.sqrt(1 - F_amp/(F*mu_f)) + 1)**3)


def tangential_cone_force(a, theta, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a cone displaced by u_x (monotonic, constant load).

    Chapter: MDR tangential, cone (not in the chapter). Derived from: sum of the stuck and
    sliding springs.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return 2*G_star*u_x*(mpmath.pi*E_star*a*mu_f - G_star*u_x/mpmath.tan(theta))/(mpmath.pi*E_star*mu_f)


def tangential_cone_stick_radius(a, theta, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a cone (angle theta to the plane) displaced by u_x.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: g(c) = d - G* u_x/(mu
    E*), g = (pi/2) tan(theta) x.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return a - 2*G_star*u_x/(mpmath.pi*E_star*mu_f*mpmath.tan(theta))


def tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a cone, finite on the axis: mu E* tan(theta)/2 ln(a/c) at r = 0.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: (5.59) of the
    tangential line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cone_traction_on_and_near_the_axis``.

    Printed in a stable form: the two pressures are each log-infinite on the axis (inf - inf
    = NaN at r = 0); as one logarithm of (a + sqrt(a^2 - r^2))/(c + sqrt(c^2 - r^2)),
    written log1p of its excess over 1, it is finite at r = 0 and keeps its digits as c ->
    a.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    c : mpmath.mpf
        radius of the stick zone [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mu_f*mpmath.tan(theta)*mpmath.log1p((a - c)*((a + c)/(mpmath.sqrt(a - r)*mpmath.sqrt(a + r) + mpmath.sqrt(c - r)*mpmath.sqrt(c + r)) + 1)/(c + mpmath.sqrt(c - r)*mpmath.sqrt(c + r)))


def tangential_modulus(G1, nu1, G2, nu2):
    """Tangential effective modulus G* [Pa] of two elastic bodies.

    Chapter: MDR tangential springs (not in the chapter). Derived from: direction average of
    the Cerruti surface compliance of each body, compliances added.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Printed in a stable form: a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf.

    Parameters
    ----------
    G1 : mpmath.mpf
        shear modulus of body 1 [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    G2 : mpmath.mpf
        shear modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return 1/((mpmath.mpf(1)/mpmath.mpf(4))*(2 - nu2)/G2 + (mpmath.mpf(1)/mpmath.mpf(4))*(2 - nu1)/G1)


def tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a power-law profile under normal force F and tangential force F_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: c from F_x, then
    g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: 1 - (1 - F_x/(mu F))^(n/(n+1)) cancels as F_x -> 0.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*F*mu_f*(n + 1)*mpmath.expm1(n*mpmath.log1p(-F_x/(F*mu_f))/(n + 1))/(G_star*a*n)


def tangential_powerlaw_energy(a, n, F, G_star, mu_f, c_a):
    """Energy W [J] dissipated per cycle by a power-law profile under normal force F whose stick zone at the amplitude has the radius c = c_a a (cancels for c_a -> 1: numeric/tangential.py integrates the density there).

    Chapter: MDR tangential, power law (not in the chapter). Derived from: sum of the
    sliding springs' parallelogram loops.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    c_a : mpmath.mpf
        stick ratio c/a (stick radius over contact radius) [1]
    """
    return 2*F**2*mu_f**2*(-2*c_a**n*n**2 - 3*c_a**n*n - c_a**n + 2*c_a**(n + 1)*n**2 + 3*c_a**(n + 1)*n + c_a**(n + 1) - c_a**(2*n + 1)*n - c_a**(2*n + 1) + n + 1)/(G_star*a*n*(2*n + 1))


def tangential_powerlaw_energy_density(n, d_c, s_x):
    """Dimensionless loop energy density (1 - x^n)(x^n - c^n) of a sliding spring at x/a = 1 - d_c (1 - s_x), c/a = 1 - d_c.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: q_z (u* - mu
    q_z/G*) with q_z ~ a^n - x^n; 1 - x^n and x^n - c^n as expm1 of log1p of the offsets,
    which keeps them exact in a thin slip zone.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    d_c : mpmath.mpf
        stick deficit 1 - c/a (c the stick radius, a the contact radius) [1]
    s_x : mpmath.mpf
        position (x - c)/(a - c) in the slip zone c < x < a, in (0, 1) [1]
    """
    return -(1 - d_c)**n*mpmath.expm1(n*mpmath.log1p(-d_c*(1 - s_x)))*mpmath.expm1(n*mpmath.log1p(d_c*s_x/(1 - d_c)))


def tangential_powerlaw_energy_scale(a, n, F, G_star, mu_f):
    """Energy per cycle [J] of a power-law profile per unit of d_c times the integral of tangential_powerlaw_energy_density over 0 < s_x < 1.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: the sliding
    springs' loops with x = a (1 - d_c (1 - s_x)), q_z ~ a^n - x^n.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return 2*F**2*mu_f**2*(n + 1)**2/(G_star*a*n**2)


def tangential_powerlaw_energy_small(a, n, F, G_star, mu_f, F_amp):
    """Leading term [J] of the energy per cycle of a power-law profile at small amplitude.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: series in F_amp
    of the energy per cycle.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cubic_small_amplitude_law``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*F_amp**3/(F*G_star*a*mu_f*(n + 1))


def tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a power-law profile displaced by u_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: mu (F_N(a) -
    F_N(c)), asserted equal to the spring sum.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: 1 - (c/a)^(n+1) cancels as u_x -> 0: -expm1((n+1)/n
    log1p(-q)).

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return -2*E_star*a**(n + 1)*c_n*kappa_n*mu_f*n*mpmath.expm1((n + 1)*mpmath.log1p(-G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)/(n + 1)


def tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """1 - c/a [1] of a power-law profile under normal force F and tangential force F_amp.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Printed in a stable form: 1 - (1 - F_amp/(mu F))^(1/(n+1)) cancels at small amplitude.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return -mpmath.expm1(mpmath.log1p(-F_amp/(F*mu_f))/(n + 1))


def tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a power-law profile f = c_n r^n displaced by u_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: g(c) = d - G*
    u_x/(mu E*), g = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: (1 - q)^(1/n) as exp(log1p(-q)/n): accurate for large n and
    tiny q.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return a*mpmath.exp(mpmath.log1p(-G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)


def tangential_powerlaw_stick_radius_from_force(a, n, F, mu_f, F_x):
    """Stick radius c [m] of a power-law profile under normal force F and tangential F_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return a*(1 - F_x/(F*mu_f))**(1/(n + 1))


def tangential_powerlaw_traction_stick_centre(r_c, a, c, c_n, n, kappa_n, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone of a power-law profile near the axis, r = r_c c <= c/2, 0 < n < 3, n != 1 (the cone): finite on the axis, where each of the two pressures of mu (p(r; a) - p(r; c)) is infinite for n <= 1; the series to r_c^54, the rest below (4/3) 4^-28 of it.

    Chapter: MDR tangential, power law (not in the chapter), (5.59). Derived from: (5.59) of
    the stuck springs' line load: (E*/pi) integral_c^a g'(x)/sqrt(x^2 - r^2) dx, its kernel
    expanded in (r/x)^2 and integrated termwise.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_powerlaw_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r_c : mpmath.mpf
        ratio r/c of the radial coordinate to the stick radius [1]
    a : mpmath.mpf
        contact radius [m]
    c : mpmath.mpf
        radius of the stick zone [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return E_star*c**(n - 1)*c_n*kappa_n*mu_f*n*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*((mpmath.mpf(121683714103007)/mpmath.mpf(1125899906842624))*r_c**2*mpmath.expm1((n - 55)*mpmath.log1p((a - c)/c))/(n - 55) + (mpmath.mpf(61989816618513)/mpmath.mpf(562949953421312))*mpmath.expm1((n - 53)*mpmath.log1p((a - c)/c))/(n - 53)) + (mpmath.mpf(15801325804719)/mpmath.mpf(140737488355328))*mpmath.expm1((n - 51)*mpmath.log1p((a - c)/c))/(n - 51)) + (mpmath.mpf(8061900920775)/mpmath.mpf(70368744177664))*mpmath.expm1((n - 49)*mpmath.log1p((a - c)/c))/(n - 49)) + (mpmath.mpf(514589420475)/mpmath.mpf(4398046511104))*mpmath.expm1((n - 47)*mpmath.log1p((a - c)/c))/(n - 47)) + (mpmath.mpf(263012370465)/mpmath.mpf(2199023255552))*mpmath.expm1((n - 45)*mpmath.log1p((a - c)/c))/(n - 45)) + (mpmath.mpf(67282234305)/mpmath.mpf(549755813888))*mpmath.expm1((n - 43)*mpmath.log1p((a - c)/c))/(n - 43)) + (mpmath.mpf(34461632205)/mpmath.mpf(274877906944))*mpmath.expm1((n - 41)*mpmath.log1p((a - c)/c))/(n - 41)) + (mpmath.mpf(4418157975)/mpmath.mpf(34359738368))*mpmath.expm1((n - 39)*mpmath.log1p((a - c)/c))/(n - 39)) + (mpmath.mpf(2268783825)/mpmath.mpf(17179869184))*mpmath.expm1((n - 37)*mpmath.log1p((a - c)/c))/(n - 37)) + (mpmath.mpf(583401555)/mpmath.mpf(4294967296))*mpmath.expm1((n - 35)*mpmath.log1p((a - c)/c))/(n - 35)) + (mpmath.mpf(300540195)/mpmath.mpf(2147483648))*mpmath.expm1((n - 33)*mpmath.log1p((a - c)/c))/(n - 33)) + (mpmath.mpf(9694845)/mpmath.mpf(67108864))*mpmath.expm1((n - 31)*mpmath.log1p((a - c)/c))/(n - 31)) + (mpmath.mpf(5014575)/mpmath.mpf(33554432))*mpmath.expm1((n - 29)*mpmath.log1p((a - c)/c))/(n - 29)) + (mpmath.mpf(1300075)/mpmath.mpf(8388608))*mpmath.expm1((n - 27)*mpmath.log1p((a - c)/c))/(n - 27)) + (mpmath.mpf(676039)/mpmath.mpf(4194304))*mpmath.expm1((n - 25)*mpmath.log1p((a - c)/c))/(n - 25)) + (mpmath.mpf(88179)/mpmath.mpf(524288))*mpmath.expm1((n - 23)*mpmath.log1p((a - c)/c))/(n - 23)) + (mpmath.mpf(46189)/mpmath.mpf(262144))*mpmath.expm1((n - 21)*mpmath.log1p((a - c)/c))/(n - 21)) + (mpmath.mpf(12155)/mpmath.mpf(65536))*mpmath.expm1((n - 19)*mpmath.log1p((a - c)/c))/(n - 19)) + (mpmath.mpf(6435)/mpmath.mpf(32768))*mpmath.expm1((n - 17)*mpmath.log1p((a - c)/c))/(n - 17)) + (mpmath.mpf(429)/mpmath.mpf(2048))*mpmath.expm1((n - 15)*mpmath.log1p((a - c)/c))/(n - 15)) + (mpmath.mpf(231)/mpmath.mpf(1024))*mpmath.expm1((n - 13)*mpmath.log1p((a - c)/c))/(n - 13)) + (mpmath.mpf(63)/mpmath.mpf(256))*mpmath.expm1((n - 11)*mpmath.log1p((a - c)/c))/(n - 11)) + (mpmath.mpf(35)/mpmath.mpf(128))*mpmath.expm1((n - 9)*mpmath.log1p((a - c)/c))/(n - 9)) + (mpmath.mpf(5)/mpmath.mpf(16))*mpmath.expm1((n - 7)*mpmath.log1p((a - c)/c))/(n - 7)) + (mpmath.mpf(3)/mpmath.mpf(8))*mpmath.expm1((n - 5)*mpmath.log1p((a - c)/c))/(n - 5)) + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.expm1((n - 3)*mpmath.log1p((a - c)/c))/(n - 3)) + mpmath.expm1((n - 1)*mpmath.log1p((a - c)/c))/(n - 1))/mpmath.pi


def tangential_powerlaw_traction_stick_integrand(r, s_r, c_n, n, kappa_n, E_star, mu_f):
    """Integrand [Pa/m] of the stick-zone traction of a power-law profile in s = sqrt(x^2 - r^2): q(r) = its integral from sqrt(c^2 - r^2) to sqrt(a^2 - r^2), smooth there for every r < c.

    Chapter: MDR tangential, power law (not in the chapter), (5.59). Derived from: (5.59) of
    the stuck springs' line load over c < x < a with x^2 = r^2 + s^2.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_powerlaw_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    s_r : mpmath.mpf
        sqrt(x^2 - r^2), the integration variable of (5.59) beyond x = r [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return E_star*c_n*kappa_n*mu_f*n*(r**2 + s_r**2)**((mpmath.mpf(1)/mpmath.mpf(2))*n - 1)/mpmath.pi


def tangential_slide_onset(E_star, G_star, mu_f, d):
    """Tangential displacement u_x [m] at which the last spring (the centre, g(0) = 0) starts to slide, depth d (d = g(a), or the flat punch's depth).

    Chapter: MDR tangential springs (not in the chapter). Derived from: G* u_x = mu q_z(0) =
    mu E* d, where the stick radius closes (asserted per profile).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_slide_onset_against_the_normal_force``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    d : mpmath.mpf
        indentation depth [m]
    """
    return E_star*d*mu_f/G_star


def tangential_stiffness(G_star, a):
    """Tangential contact stiffness k_x = dF_x/du_x [N/m] before any slip (c = a).

    Chapter: MDR tangential springs (not in the chapter). Derived from: sum of the 2a/dx
    stuck springs of stiffness G* dx.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_initial_stiffness_is_2_G_star_a_for_every_profile``.

    Parameters
    ----------
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    a : mpmath.mpf
        contact radius [m]
    """
    return 2*G_star*a


def tangential_stiffness_ratio(nu):
    """G*/E* [1] = tangential over normal contact stiffness of one elastic body on a rigid one.

    Chapter: MDR tangential springs (not in the chapter). Derived from: Cerruti and
    Boussinesq compliances of the same body, G = E/(2 (1 + nu)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return 2*(nu - 1)/(nu - 2)


def tangential_traction_slip(mu_f, p_a):
    """Tangential traction q [Pa] in the slip zone: mu p(r; a) of the pressure p_a [Pa].

    Chapter: MDR tangential (Ciavarella-Jaeger, found). Derived from: (5.59) of the sliding
    springs' line load mu q_z.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_against_the_line_load_quadrature``.

    Parameters
    ----------
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    p_a : mpmath.mpf
        contact pressure p(r; a) of a profile at contact radius a [Pa]
    """
    return mu_f*p_a


def tangential_traction_stick(mu_f, p_a, p_c):
    """Tangential traction q [Pa] in the stick zone r < c: mu (p(r; a) - p(r; c)) of the pressures p_a, p_c [Pa] of the profile at contact radii a and c.

    Chapter: MDR tangential (Ciavarella-Jaeger, found). Derived from: (5.59) of the stuck
    springs' line load mu (q_z(x; a) - q_z(x; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_against_the_line_load_quadrature``.

    Parameters
    ----------
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    p_a : mpmath.mpf
        contact pressure p(r; a) of a profile at contact radius a [Pa]
    p_c : mpmath.mpf
        contact pressure p(r; c) of the same profile at contact radius c (the stick radius) [Pa]
    """
    return mu_f*(p_a - p_c)


def uniform_pressure_displacement(E_star, a, p0, r):
    """Surface displacement u_z [m] inside a disc (r <= a) under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0); the phi-integral is 4 a
    E(r^2/a^2).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 4*a*p0*mpmath.ellipe(r**2/a**2)/(mpmath.pi*E_star)


def uniform_pressure_displacement_centre(E_star, a, p0):
    """Displacement u_z(0) [m] at the centre of a disc under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0) at r = 0.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return 2*a*p0/E_star


def uniform_pressure_displacement_edge(E_star, a, p0):
    """Displacement u_z(a) [m] at the edge of a disc under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0) at r = a.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return 4*a*p0/(mpmath.pi*E_star)


def uniform_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) under a uniform pressure p0.

    Chapter: Problem 6 (outside the disc). Derived from: (5.7) with p = p0 (n = 0) outside
    the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Printed in a stable form: E(m) - (1 - m) K(m) cancels like m = a^2/r^2 for r >> a; it
    equals (pi m/4) 2F1(1/2, 1/2; 2; m).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return a**2*p0*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(1)/mpmath.mpf(2)), (2,), a**2/r**2)/(E_star*r)


def uniform_pressure_force(a, p0):
    """Total force F [N] of a uniform pressure p0 on a disc of radius a.

    Chapter: Problem 6. Derived from: the integral of p0 times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return mpmath.pi*a**2*p0


def worn_contact_radius(R, b, d):
    """Contact radius a [m] of the worn paraboloid at depth d > 0.

    Chapter: Problem 8. Derived from: (5.55) solved for a^2.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return mpmath.sqrt((mpmath.mpf(1)/mpmath.mpf(2))*b**2 + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(4*R**2*d**2 + b**4))


def worn_depth(R, a, b):
    """Indentation depth d [m] of the worn paraboloid at contact radius a > b.

    Chapter: Problem 8. Derived from: (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    """
    return a*mpmath.sqrt(a**2 - b**2)/R


def worn_displacement_inside(R, b, d, r):
    """Surface displacement u_z(r) [m] inside the contact (r <= a) of the worn paraboloid.

    Chapter: Problem 8, (5.60). Derived from: (5.60) of u = d - g(x) (5.54) for r <= a,
    which (5.53) makes d - f(r).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return d - mpmath.mpf(1)/mpmath.mpf(2)*max(0, (-b + r)*(b + r))/R


def worn_displacement_outside(R, a, b, r):
    """Surface displacement u_z(r) [m] outside the contact (r > a) of the worn paraboloid.

    Chapter: Problem 8, (5.60). Derived from: (5.60) with x^2 = b^2 + (r^2 - b^2)
    sin^2(phi).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Printed in a stable form: S sqrt(1 - S^2) - asin S, S^2 = (a^2 - b^2)/(r^2 - b^2),
    cancels for r >> a; it is written -(2 S^3/3) 2F1(1/2, 3/2; 5/2; S^2).

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (2*a*mpmath.sqrt(a**2 - b**2)*mpmath.asin(a/r) - mpmath.mpf(1)/mpmath.mpf(3)*mpmath.sqrt((a**2 - b**2)/(-b**2 + r**2))*(2*a**2 - 2*b**2)*mpmath.hyper((mpmath.mpf(1)/mpmath.mpf(2), mpmath.mpf(3)/mpmath.mpf(2)), (mpmath.mpf(5)/mpmath.mpf(2),), (a**2 - b**2)/(-b**2 + r**2)))/(mpmath.pi*R)


def worn_force(E_star, R, b, d):
    """Normal force F [N] of the worn paraboloid at depth d.

    Chapter: Problem 8. Derived from: (5.57) at the contact radius of (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Printed in a stable form: sqrt(-1 + sqrt(1 + s^2)), s = 2 R d/b^2, cancels for s << 1;
    it is written s/sqrt(sqrt(1 + s^2) + 1).

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.sqrt(2)*E_star*b*d*(mpmath.sqrt(4*R**2*d**2/b**4 + 1) + 2)/mpmath.sqrt(mpmath.sqrt(4*R**2*d**2/b**4 + 1) + 1)


def worn_force_from_radius(E_star, R, a, b):
    """Normal force F [N] of the worn paraboloid at contact radius a > b.

    Chapter: Problem 8. Derived from: (5.57) with d = g(a).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*E_star*mpmath.sqrt(a - b)*mpmath.sqrt(a + b)*(2*a**2 + b**2)/R


def worn_g(R, b, x):
    """MDR profile g(x) [m] of the worn paraboloid (0 for x < b).

    Chapter: Problem 8. Derived from: (5.52) for f = (r^2 - b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_g_by_quadrature``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return x*mpmath.sqrt(max(0, (-b + x)*(b + x)))/R


def worn_pressure(E_star, R, a, b, r):
    """Contact pressure p(r) [Pa] of the worn paraboloid (log-infinite at r = b, 0 for r >= a).

    Chapter: Problem 8, (5.59). Derived from: (5.59) of g, in incomplete elliptic integrals
    (mdr.elliptic_abel_integral).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*(2*a*mpmath.sqrt(max(0, (a - max(b, r))*(a + max(b, r))))/mpmath.sqrt((max(b, r) - min(b, r))*(max(b, r) + min(b, r)) + max(0, (a - max(b, r))*(a + max(b, r)))) + (-b**2 + 2*max(b, r)**2)*mpmath.ellipf(mpmath.atan2(mpmath.sqrt(max(0, (a - max(b, r))*(a + max(b, r)))), mpmath.sqrt(max(b, r) - min(b, r))*mpmath.sqrt(max(b, r) + min(b, r))), min(b, r)**2/max(b, r)**2)/max(b, r) - 2*mpmath.ellipe(mpmath.atan2(mpmath.sqrt(max(0, (a - max(b, r))*(a + max(b, r)))), mpmath.sqrt(max(b, r) - min(b, r))*mpmath.sqrt(max(b, r) + min(b, r))), min(b, r)**2/max(b, r)**2)*max(b, r))/(mpmath.pi*R)


def worn_profile(R, b, r):
    """Height f(r) [m] of the worn paraboloid's surface above its tip (0 for r < b).

    Chapter: Problem 8. Derived from: the paraboloid r^2/(2R) worn flat to the radius b.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*max(0, (-b + r)*(b + r))/R


def textbook_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """Slope g'(x) [1] of the MDR profile of the power law f = c_n r^n, x > 0, in the derived (textbook) form; use adhesion_powerlaw_g_slope: x^n/x is 0/0 at x = 0 and overflows before x^(n - 1) does.

    Chapter: (5.52), Problem 7(d). Derived from: the derivative of (5.52) for f = c_n r^n, g
    = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return c_n*kappa_n*n*x**n/x


def textbook_adhesion_pressure_edge(E_star, a, dgamma, r):
    """Adhesive term of the contact pressure p(r) [Pa] for r < a (negative: tension; add the non-adhesive pressure of radius a), in the derived (textbook) form; use adhesion_pressure_edge: a^2 - r^2 loses the digits of a - r next to the edge, where the term is largest; written (a - r)(a + r).

    Chapter: (5.59), adhesive. Derived from: (5.59) with the jump of q(x) at x = a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return -mpmath.sqrt(2)*mpmath.sqrt(E_star)*mpmath.sqrt(a)*mpmath.sqrt(dgamma)/(mpmath.sqrt(mpmath.pi)*mpmath.sqrt(a**2 - r**2))


def textbook_adhesion_sphere_g_slope(R, x):
    """Slope g'(x) [1] of the MDR profile of the exact sphere, 0 <= x < R, in the derived (textbook) form; use adhesion_sphere_g_slope: atanh(x/R) as log1p(2x/(R - x))/2 and R^2 - x^2 as (R - x)(R + x), exact as x -> R where the slope is largest.

    Chapter: (5.52), Sneddon's sphere. Derived from: the derivative of (5.52) for the
    spherical cap.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (R*x + (R**2 - x**2)*mpmath.atanh(x/R))/(R**2 - x**2)


def textbook_adhesion_worn_g_slope(R, b, x):
    """Slope g'(x) [1] of the MDR profile of the worn paraboloid for x > b (0 for x < b; infinite at the kink x = b+), in the derived (textbook) form; use adhesion_worn_g_slope: x^2 - b^2 as (x - b)(x + b), exact next to the kink.

    Chapter: (5.52), Problem 8. Derived from: the derivative of (5.52) for f = (r^2 -
    b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return (-b**2 + 2*x**2)/(R*mpmath.sqrt(-b**2 + x**2))


def textbook_bodies_crossed_cylinders_curvature_2(R1, R2, alpha):
    """Smaller principal curvature [1/m] of the gap of two cylinders crossed at alpha, in the derived (textbook) form; use bodies_crossed_cylinders_curvature_2: written with the curvatures 1/R so that R = inf (flat) works; the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det a sum of products, positive for convex bodies: no cancellation.

    Chapter: (5.32), (5.33), any angle. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    alpha : mpmath.mpf
        angle between the axes of two crossed cylinders [rad]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt((mpmath.cos(2*alpha)/R2 + 1/R1)**2 + mpmath.sin(2*alpha)**2/R2**2) + (mpmath.mpf(1)/mpmath.mpf(2))/R2 + (mpmath.mpf(1)/mpmath.mpf(2))/R1


def textbook_bodies_effective_modulus(E1, nu1, E2, nu2):
    """Effective modulus E* [Pa] of two elastic bodies, in the derived (textbook) form; use bodies_effective_modulus: 1/E* as the sum of the compliances, which accepts E2 = inf (rigid), with 1 - nu^2 = (1 - nu)(1 + nu) exact in floating point for nu near -1.

    Chapter: (5.26). Derived from: the sum of the two surface displacements (5.6), (5.7)
    under one pressure.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Parameters
    ----------
    E1 : mpmath.mpf
        Young's modulus of body 1 [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    E2 : mpmath.mpf
        Young's modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return -E1*E2/(E1*nu2**2 - E1 + E2*nu1**2 - E2)


def textbook_bodies_effective_modulus_rigid(E, nu):
    """Effective modulus E* [Pa] of an elastic body against a rigid one, in the derived (textbook) form; use bodies_effective_modulus_rigid: 1 - nu^2 = (1 - nu)(1 + nu) is exact in floating point for nu near -1, where 1 - nu^2 cancels.

    Chapter: (5.8), (5.26) with E2 -> inf. Derived from: the limit E2 -> inf of (5.26).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Parameters
    ----------
    E : mpmath.mpf
        Young's modulus [Pa]
    nu : mpmath.mpf
        Poisson's ratio [1]
    """
    return -E/(nu**2 - 1)


def textbook_bodies_effective_radius(R1, R2):
    """Effective radius R [m] of two spheres (negative radius: concave), in the derived (textbook) form; use bodies_effective_radius: the sum of the curvatures accepts R = inf (flat).

    Chapter: (5.27). Derived from: the sum of the two gaps r^2/(2 R_i).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_radius_by_gap``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    R2 : mpmath.mpf
        radius of curvature of body 2, or second principal radius [m]
    """
    return R1*R2/(R1 + R2)


def textbook_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega):
    """Smaller principal curvature kappa_2 [1/m] of the gap between two bodies, in the derived (textbook) form; use bodies_principal_curvature_2: written with the curvatures 1/R so that R = inf (flat) works; the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det a sum of products, positive for convex bodies: no cancellation.

    Chapter: (5.32), Problem 2, general. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1a : mpmath.mpf
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : mpmath.mpf
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : mpmath.mpf
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : mpmath.mpf
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : mpmath.mpf
        angle between the first principal directions of the two bodies [rad]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt((-1/R2b + 1/R2a)**2*mpmath.sin(2*omega)**2 + ((-1/R2b + 1/R2a)*mpmath.cos(2*omega) - 1/R1b + 1/R1a)**2) + (mpmath.mpf(1)/mpmath.mpf(2))/R2b + (mpmath.mpf(1)/mpmath.mpf(2))/R2a + (mpmath.mpf(1)/mpmath.mpf(2))/R1b + (mpmath.mpf(1)/mpmath.mpf(2))/R1a


def textbook_cattaneo_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a paraboloid under normal force F and tangential force F_x, in the derived (textbook) form; use cattaneo_displacement: 1 - (1 - F_x/(mu F))^(2/3) cancels as F_x -> 0: -expm1(2/3 log1p(-F_x/(mu F))).

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: F_x = mu (F_N(a) - F_N(c))
    solved for c, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return (mpmath.mpf(3)/mpmath.mpf(4))*(-F**(mpmath.mpf(1)/mpmath.mpf(3))*mu_f**(mpmath.mpf(1)/mpmath.mpf(3))*(F*mu_f - F_x)**(mpmath.mpf(2)/mpmath.mpf(3)) + F*mu_f)/(G_star*a)


def textbook_cattaneo_force(a, R, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a paraboloid displaced by u_x (monotonic, constant load), in the derived (textbook) form; use cattaneo_force: mu (F_N(a) - F_N(c)) cancels as u_x -> 0; a^3 - c^3 = (a^2 - c^2)(a^2 + a c + c^2)/(a + c) with a^2 - c^2 = R G* u_x/(mu E*) exactly.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: sum of the stuck and
    sliding springs.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*(E_star**(mpmath.mpf(3)/mpmath.mpf(2))*a**3*mu_f**(mpmath.mpf(3)/mpmath.mpf(2)) - E_star*a**2*mu_f*mpmath.sqrt(E_star*a**2*mu_f - G_star*R*u_x) + G_star*R*u_x*mpmath.sqrt(E_star*a**2*mu_f - G_star*R*u_x))/(mpmath.sqrt(E_star)*R*mpmath.sqrt(mu_f))


def textbook_cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a paraboloid, in the derived (textbook) form; use cattaneo_traction_stick: the difference of the two square roots cancels as c -> a.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the tangential
    line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    c : mpmath.mpf
        radius of the stick zone [m]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return 2*E_star*mu_f*(mpmath.sqrt(a**2 - r**2) - mpmath.sqrt(c**2 - r**2))/(mpmath.pi*R)


def textbook_cone_pressure(E_star, d, theta, r):
    """Contact pressure p(r) [Pa] of a rigid cone at depth d, for 0 < r <= a (log-singular at r = 0), in the derived (textbook) form; use cone_pressure: arccosh(a/r) = 2 asinh(sqrt((a - r)/(2 r))): a/r overflows for a flat cone (theta = 1e-300: a = 6e296 m) where the pressure is a float, and arccosh of 1 + (a - r)/r loses the digits of a - r next to the rim.

    Chapter: (5.39). Derived from: the pressures (5.9) of the superposed punches.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Differs from the print (see docs/errata.md): the print has a spurious minus sign: the
    pressure is positive in compression, p = E* d/(pi a) arccosh(a/r) with E* = E/(1 -
    nu^2), as (5.9), (5.15) and the chapter's own Problem 7(c) have it

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    d : mpmath.mpf
        indentation depth [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.tan(theta)*mpmath.acosh(2*d/(mpmath.pi*r*mpmath.tan(theta)))


def textbook_disc_pressure(a, n_p, p0, r):
    """Prescribed pressure p0 (1 - r^2/a^2)^n_p [Pa] on a disc of radius a, r < a, in the derived (textbook) form; use disc_pressure: 1 - r^2/a^2 cancels towards the edge r -> a (1e-13 at r = 0.9995 a); (a - r)(a + r)/a^2 does not.

    Chapter: (5.9), (5.15), Problem 6. Derived from: the distributions of section 5.1.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_disc_pressure_force``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n_p : mpmath.mpf
        exponent of a prescribed pressure p0*(1 - r^2/a^2)^n_p on a disc (section 5.1) [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return p0*(1 - r**2/a**2)**n_p


def textbook_ellipse_area(R1, d, t_ba):
    """Contact area pi a b [m^2] of an elliptical contact, in the derived (textbook) form; use ellipse_area: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.29), exact. Derived from: pi a b with a, b matched.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return 2*mpmath.pi*R1*d*t_ba*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/((1 - t_ba**2)*((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_depth_from_force(E_star, F, R1, t_ba):
    """Indentation depth d [m] of an elliptical contact under the force F, in the derived (textbook) form; use ellipse_depth_from_force: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact, inverted. Derived from: the exact force solved for d.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return 3**(mpmath.mpf(2)/mpmath.mpf(3))*F**(mpmath.mpf(2)/mpmath.mpf(3))*((mpmath.mpf(1)/mpmath.mpf(2))*(-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (mpmath.mpf(1)/mpmath.mpf(2))*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(mpmath.pi**(mpmath.mpf(2)/mpmath.mpf(3))*E_star**(mpmath.mpf(2)/mpmath.mpf(3))*R1**(mpmath.mpf(1)/mpmath.mpf(3))*((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(mpmath.mpf(1)/mpmath.mpf(3)))


def textbook_ellipse_equivalent_radius(R1, t_ba):
    """Radius R_e [m] of the sphere whose Hertz force (5.23) equals the elliptical contact's at every depth (compare with the Gaussian radius (5.30)), in the derived (textbook) form; use ellipse_equivalent_radius: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact. Derived from: the exact force equated to (5.23).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.pi**2*R1*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/((1 - t_ba**2)*((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))**3)


def textbook_ellipse_force(E_star, R1, d, t_ba):
    """Normal force F [N] of an elliptical Hertz contact at depth d, in the derived (textbook) form; use ellipse_force: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact. Derived from: (5.31) integrated over the ellipse, with a and p0
    from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*d**(mpmath.mpf(3)/mpmath.mpf(2))*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(mpmath.mpf(3)/mpmath.mpf(2))


def textbook_ellipse_max_pressure(E_star, R1, d, t_ba):
    """Maximum pressure p0 [Pa] of an elliptical contact at depth d, in the derived (textbook) form; use ellipse_max_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*E_star*mpmath.sqrt(d)/(mpmath.sqrt(R1)*t_ba*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))*mpmath.sqrt((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_mean_pressure(E_star, R1, d, t_ba):
    """Mean pressure F/(pi a b) [Pa] of an elliptical contact, in the derived (textbook) form; use ellipse_mean_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.17), exact. Derived from: the force divided by the area pi a b.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*mpmath.sqrt(2)*E_star*mpmath.sqrt(d)/(mpmath.sqrt(R1)*t_ba*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))*mpmath.sqrt((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_pressure(E_star, R1, d, t_ba, x, y):
    """Contact pressure p(x, y) [Pa] of an elliptical contact (0 outside), in the derived (textbook) form; use ellipse_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31). Derived from: (5.31) with a, b, p0 from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_pressure_field``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    x : mpmath.mpf
        coordinate [m]
    y : mpmath.mpf
        coordinate [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*E_star*mpmath.sqrt(d)*mpmath.sqrt(max(0, 1 - mpmath.mpf(1)/mpmath.mpf(2)*x**2*(1 - t_ba**2)*((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(R1*d*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))) - mpmath.mpf(1)/mpmath.mpf(2)*y**2*(1 - t_ba**2)*((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(R1*d*t_ba**2*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2)))))/(mpmath.sqrt(R1)*t_ba*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))*mpmath.sqrt((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_radius_ratio(t_ba):
    """Ratio R1/R2 >= 1 of the principal radii that gives the axis ratio t = b/a, in the derived (textbook) form; use ellipse_radius_ratio: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31)-(5.32), exact. Derived from: (5.7) over (5.31) matched to the gap
    (5.32): the y^2 and x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(t_ba**2*(-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2)))


def textbook_ellipse_semi_major(R1, d, t_ba):
    """Semi-axis a [m] (along x, the direction of R1 >= R2) of an elliptical contact, in the derived (textbook) form; use ellipse_semi_major: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32): the x^0 and
    x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*mpmath.sqrt(R1)*mpmath.sqrt(d)*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/mpmath.sqrt((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))


def textbook_ellipse_semi_minor(R1, d, t_ba):
    """Semi-axis b = t a [m] (along y, the direction of R2) of an elliptical contact, in the derived (textbook) form; use ellipse_semi_minor: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*mpmath.sqrt(R1)*mpmath.sqrt(d)*t_ba*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/mpmath.sqrt((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))


def textbook_ellipse_stiffness(E_star, R1, d, t_ba):
    """Differential stiffness dF/dd [N/m] of an elliptical contact, in the derived (textbook) form; use ellipse_stiffness: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.13), exact. Derived from: the derivative of the force at fixed R1, R2.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_stiffness_by_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    d : mpmath.mpf
        indentation depth [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*mpmath.sqrt(d)*mpmath.sqrt((-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))/((-t_ba**2*mpmath.ellipk(1 - t_ba**2) + mpmath.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-mpmath.ellipe(1 - t_ba**2) + mpmath.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(mpmath.mpf(3)/mpmath.mpf(2))


def textbook_force_law_ellipse_prefactor(E_star, R1, t_ba):
    """Prefactor K [N/m^n] of the force law F = K d^n of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio), in the derived (textbook) form; use force_law_ellipse_prefactor: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force: the K, E form cancels as t -> 1 (the circle).

    Chapter: (5.23), exact ellipse, F = K d^n. Derived from: F/d^n with n the logarithmic
    slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_ellipse_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return (mpmath.mpf(2)/mpmath.mpf(3))*mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*mpmath.sqrt((mpmath.ellipe(1 - t_ba**2) - mpmath.ellipk(1 - t_ba**2))/(t_ba**2 - 1))/mpmath.ellipk(1 - t_ba**2)**(mpmath.mpf(3)/mpmath.mpf(2))


def textbook_force_law_ellipse_stiffness_prefactor(E_star, R1, t_ba):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio), in the derived (textbook) form; use force_law_ellipse_stiffness_prefactor: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force: the K, E form cancels as t -> 1 (the circle).

    Chapter: (5.23), exact ellipse, differentiated. Derived from: (dF/dd)/d^(n_k) with n_k
    the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : mpmath.mpf
        radius of curvature of body 1, or first principal radius [m]
    t_ba : mpmath.mpf
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    return mpmath.sqrt(2)*mpmath.pi*E_star*mpmath.sqrt(R1)*mpmath.sqrt((mpmath.ellipe(1 - t_ba**2) - mpmath.ellipk(1 - t_ba**2))/(t_ba**2 - 1))/mpmath.ellipk(1 - t_ba**2)**(mpmath.mpf(3)/mpmath.mpf(2))


def textbook_hertz_displacement_outside(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact (r > a), in the derived (textbook) form; use hertz_displacement_outside: the textbook form cancels terms of size r/a to leave one of size a/r; asin t - t sqrt(1 - t^2) is written as (2 t^3/3) 2F1(1/2, 3/2; 5/2; t^2) with t = a/r.

    Chapter: Fig. 5.2, Problem 7(b). Derived from: (5.7) over the Hertz pressure, outside
    the disc.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (mpmath.sqrt(R)*mpmath.sqrt(d)*mpmath.sqrt(-R*d + r**2) + 2*R*d*mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r) - r**2*mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r))/(mpmath.pi*R)


def textbook_hertz_displacement_outside_elementary(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact with the 2F1 in elementary functions; it cancels ~0.65 eps a^2/r^2 relative: for a < r < 2a, in the derived (textbook) form; use hertz_displacement_outside_elementary: asin t - (asin t - t sqrt(1 - z))/(2 z), t = a/r, z = R d/r^2: the 2F1 in elementary functions as one cancellation of ~0.65 eps/z.

    Chapter: Fig. 5.2, Problem 7(b), a < r < 2a. Derived from: the stable far form with
    2F1(1/2, 3/2; 5/2; t^2) hyperexpanded.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_outside_forms_by_mpmath``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : mpmath.mpf
        indentation depth [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 2*d*(-mpmath.mpf(1)/mpmath.mpf(3)*mpmath.sqrt(R)*mpmath.sqrt(d)*(r**2*((mpmath.mpf(3)/mpmath.mpf(2))*R*d/r**2 + mpmath.mpf(-3)/mpmath.mpf(2))/(R*d*mpmath.sqrt(-R*d/r**2 + 1)) + (mpmath.mpf(3)/mpmath.mpf(2))*r**3*mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r)/(R**(mpmath.mpf(3)/mpmath.mpf(2))*d**(mpmath.mpf(3)/mpmath.mpf(2))))/r + mpmath.asin(mpmath.sqrt(R)*mpmath.sqrt(d)/r))/mpmath.pi


def textbook_jkr_pressure(E_star, R, a, dgamma, r):
    """Contact pressure p(r) [Pa] of a paraboloid in JKR contact, r < a, in the derived (textbook) form; use jkr_pressure: Hertz's part and the edge term apart, each with (a - r)(a + r) for a^2 - r^2, which loses the digits of a - r next to the edge.

    Chapter: (5.59), JKR. Derived from: (5.59): Hertz's pressure of radius a plus the edge
    term.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    dgamma : mpmath.mpf
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (-mpmath.sqrt(2)*mpmath.pi*mpmath.sqrt(E_star)*R*mpmath.sqrt(a)*mpmath.sqrt(dgamma) + 2*mpmath.sqrt(mpmath.pi)*E_star*(a**2 - r**2))/(mpmath.pi**(mpmath.mpf(3)/mpmath.mpf(2))*R*mpmath.sqrt(a**2 - r**2))


def textbook_line_stress_axis_sigma_xx(a, p0, z):
    """Normal stress sigma_xx [Pa] on the axis of a line contact of half-width a, in the derived (textbook) form; use line_stress_axis_sigma_xx: the derived form subtracts terms of size z/a to leave one of size (a/z)^3; -p0 a^3/(s (s + z)^2), s = (a^2 + z^2)^(1/2), has none.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over the line pressure (5.36)
    along the axis x = 0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return p0*(2*a**2*z - a**2*mpmath.sqrt(a**2 + z**2) + 2*z**3 - 2*z**2*mpmath.sqrt(a**2 + z**2))/(a*(a**2 + z**2))


def textbook_line_stress_axis_von_mises(a, nu, p0, z):
    """Von Mises stress [Pa] on the axis of a line contact (plane strain), in the derived (textbook) form; use line_stress_axis_von_mises: (5.50) expanded subtracts squares of size p0^2; with c = (sigma_xx + sigma_zz)/2 it is ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2).

    Chapter: (5.50), (5.36). Derived from: (5.50) with the axis stresses and sigma_yy = nu
    (sigma_xx + sigma_zz).

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return mpmath.sqrt(a**6*p0**2/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**4) - a**4*p0**2/((a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + a**3*nu*p0*(-a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - a*p0/mpmath.sqrt(a**2 + z**2))/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) + a**2*p0**2/(a**2 + z**2) + a*nu*p0*(-a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - a*p0/mpmath.sqrt(a**2 + z**2))/mpmath.sqrt(a**2 + z**2) + nu**2*(-a**3*p0/(mpmath.sqrt(a**2 + z**2)*(z + mpmath.sqrt(a**2 + z**2))**2) - a*p0/mpmath.sqrt(a**2 + z**2))**2)


def textbook_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz):
    """Largest principal stress [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_max: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*sigma_xx + (mpmath.mpf(1)/mpmath.mpf(2))*sigma_zz + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz):
    """Smallest principal stress [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_min: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*sigma_xx + (mpmath.mpf(1)/mpmath.mpf(2))*sigma_zz - mpmath.mpf(1)/mpmath.mpf(2)*mpmath.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz):
    """Principal shear stress tau_1 [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_shear: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: half the difference of the principal
    stresses.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz):
    """Von Mises stress [Pa] of a plane-strain state (sigma_yy = nu (sigma_xx + sigma_zz), tau_xy = tau_yz = 0), in the derived (textbook) form; use line_stress_von_mises: (5.50) expanded subtracts products of size p0^2 (it goes negative at the surface for nu = 1/2, where it is 0); ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2), c = (sigma_xx + sigma_zz)/2, has only squares.

    Chapter: (5.50), plane strain. Derived from: (5.50) with the plane-strain sigma_yy.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return mpmath.sqrt(nu**2*(sigma_xx + sigma_zz)**2 - nu*sigma_xx*(sigma_xx + sigma_zz) - nu*sigma_zz*(sigma_xx + sigma_zz) + sigma_xx**2 - sigma_xx*sigma_zz + sigma_zz**2 + 3*tau_xz**2)


def textbook_mdr_kink_G(b, slope_jump, x):
    """Integral from b to x > b [m^2] of mdr_kink_g: the kink's part of the integral of g in the force (5.57), in the derived (textbook) form; use mdr_kink_G: acosh of an argument near 1 loses digits as x -> b (as in mdr_kink_g); the two terms still cancel to a relative (x - b)/b, which is rounding of the integral of g it is added to.

    Chapter: (5.57). Derived from: integral of mdr_kink_g by parts (x g - integral of y g').

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_G_by_quadrature``.

    Parameters
    ----------
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return 2*b*slope_jump*x*mpmath.acosh((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(b + x)/mpmath.sqrt(b)) - b*slope_jump*mpmath.sqrt(-b + x)*mpmath.sqrt(b + x)


def textbook_mdr_kink_g(b, slope_jump, x):
    """Integral from b to x > b [m] of the branch-point term of g' at a kink r = b, in the derived (textbook) form; use mdr_kink_g: acosh of an argument 1 + (x - b)/(4b) loses digits as x -> b (relative eps b/(x - b)); it is written 2 asinh(sqrt((x - b)/(2b))).

    Chapter: (5.52). Derived from: integral of mdr_kink_gprime.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_g_by_quadrature``.

    Parameters
    ----------
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : mpmath.mpf
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : mpmath.mpf
        coordinate [m]
    """
    return 2*b*slope_jump*mpmath.acosh((mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(2)*mpmath.sqrt(b + x)/mpmath.sqrt(b))


def textbook_mindlin_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle of a tangential force oscillating with amplitude F_amp at constant normal force F (paraboloid), in the derived (textbook) form; use mindlin_energy: the integrand vanishes to second order at the edge: (1 - c/a)^3 P(c/a) with 1 - c/a = -expm1(log1p(-F_amp/(mu F))/3) keeps the cubic law to rounding.

    Chapter: Mindlin-Deresiewicz (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops 4 mu q_z (u* - mu q_z/G*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_mindlin_deresiewicz_energy``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return (mpmath.mpf(3)/mpmath.mpf(5))*(-6*F**(mpmath.mpf(4)/mpmath.mpf(3))*mu_f**(mpmath.mpf(4)/mpmath.mpf(3))*(F*mu_f - F_amp)**(mpmath.mpf(2)/mpmath.mpf(3)) + F**(mpmath.mpf(1)/mpmath.mpf(3))*F_amp*mu_f**(mpmath.mpf(1)/mpmath.mpf(3))*(F*mu_f - F_amp)**(mpmath.mpf(2)/mpmath.mpf(3)) + 6*F**2*mu_f**2 - 5*F*F_amp*mu_f)/(G_star*a)


def textbook_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law indenter under the force F, in the derived (textbook) form; use powerlaw_depth_from_force: (kappa_n c_n)^(1/n) of the derived form overflows or underflows for small n although d is ordinary (c_n = 1e-3, n = 3 at F = 1 N: NaN); split into (F (n + 1)/(2 E* n))^(n/(n + 1)) (kappa_n c_n)^(1/(n + 1)), whose factors stay within the range of the inputs.

    Chapter: Problem 7(d), inverted. Derived from: the force of Problem 7(d) solved for d.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_roundtrip``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    F : mpmath.mpf
        normal force [N]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return ((mpmath.mpf(1)/mpmath.mpf(2))*F*(c_n*kappa_n)**(1/n)*(n + 1)/(E_star*n))**(n/(n + 1))


def textbook_powerlaw_displacement_outside_integrand(a, d, n, r, w_out):
    """Integrand [m] of (5.60) in w: u_z(r > a) = integral_0^asin(a/r) of it dw, positive and smooth (a layer of width ~1/(n cot(asin(a/r))) at w = 0 for large n), in the derived (textbook) form; use powerlaw_displacement_outside_integrand: (x/a)^n with x/a = 1 - O(1/n) amplifies its rounding n-fold and r^2 - a^2 overflows for r > 1e154; written -expm1(n log1p(-2 sin(w/2)^2 - sqrt(r - a) sqrt(r + a) sin(w)/a)).

    Chapter: Problem 7(d), (5.60). Derived from: (5.60) with x = r sin(asin(a/r) - w).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_displacement_outside_large_n``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    w_out : mpmath.mpf
        integration variable in (0, asin(a/r)) of (5.60) outside the contact: x = r sin(asin(a/r) - w) [rad]
    """
    return (-2*d*(-r*mpmath.sin(w_out - mpmath.asin(a/r))/a)**n + 2*d)/mpmath.pi


def textbook_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n):
    """Mean pressure F/(pi a^2) [Pa] of a power-law indenter at depth d, in the derived (textbook) form; use powerlaw_mean_pressure_from_depth: the contact radius a = (d/(kappa_n c_n))^(1/n) underflows to 0 for small n where F/(pi a^2) is still a float (and overflows where it is not): one power of the ratio kappa_n c_n/d, times d.

    Chapter: Fig. 5.17. Derived from: (5.57) over the contact area, a from (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : mpmath.mpf
        indentation depth [m]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    return 2*E_star*d*n*(c_n*kappa_n/d)**(1/n)/(mpmath.pi*(n + 1))


def textbook_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad):
    """Integrand [Pa] of (5.59) in w: p(r) = integral_0^1 of it dw, smooth in w (a boundary layer of width ~1/(n (1 - r^2/a^2)) at w = 0 for large n), in the derived (textbook) form; use powerlaw_pressure_integrand: (x/a)^(n-2) with x/a = 1 - O(1/n) amplifies its rounding n-fold and overflows/underflows in parts; written exp((n/2 - 1) log1p(-(1 - x^2/a^2))) with 1 - x^2/a^2 factored.

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x^2 = r^2 + (a^2 - r^2)(1 -
    w)^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_pressure_large_n_by_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    d : mpmath.mpf
        indentation depth [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    w_quad : mpmath.mpf
        integration variable in (0, 1) of (5.59): x^2 = r^2 + (a^2 - r^2)(1 - w)^2 [1]
    """
    return E_star*a**(-n)*d*n*mpmath.sqrt(a**2 - r**2)*(r**2 + (1 - w_quad)**2*(a**2 - r**2))**((mpmath.mpf(1)/mpmath.mpf(2))*n - 1)/mpmath.pi


def textbook_sphere_depth(R, a):
    """Indentation depth d [m] of a rigid spherical cap at the contact radius a < R, in the derived (textbook) form; use sphere_depth: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.55), Sneddon's sphere. Derived from: (5.55), d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return a*mpmath.atanh(a/R)


def textbook_sphere_force_from_radius(E_star, R, a):
    """Normal force F [N] of a rigid spherical cap at the contact radius a < R, in the derived (textbook) form; use sphere_force_from_radius: (a^2 + R^2) atanh(a/R) - a R cancels as (a/R)^2 for a << R; below a = R/2 it is written E* R^2 (b^2 atanh(b) + (b^3/3) 2F1(1, 3/2; 5/2; b^2)), b = a/R, above it with atanh in log1p.

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) with d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    """
    return E_star*(R**2*mpmath.atanh(a/R) - R*a + a**2*mpmath.atanh(a/R))


def textbook_sphere_g(R, x):
    """MDR profile g(x) [m] of the spherical cap, 0 <= x < R, in the derived (textbook) form; use sphere_g: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.52), Sneddon's sphere. Derived from: (5.52) with r = sqrt(x^2 - v^2).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return x*mpmath.atanh(x/R)


def textbook_sphere_lam_force(E_star, R, lam):
    """Normal force F [N] of a rigid spherical cap at lam = atanh(a/R), in the derived (textbook) form; use sphere_lam_force: (1 + tanh(lam)^2) lam - tanh(lam) cancels as lam^2 for small lam; below lam = 1/2 it is written with (b^3/3) 2F1(1, 3/2; 5/2; b^2) for lam - b, b = tanh(lam).

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    return E_star*R**2*(lam*mpmath.tanh(lam)**2 + lam - mpmath.tanh(lam))


def textbook_sphere_lam_pressure_pole(E_star, R, lam, r):
    """The part of the contact pressure p(r) [Pa] of a rigid spherical cap from the pole R x/(R^2 - x^2) of g'(x), at lam = atanh(a/R), 0 <= r < a, in the derived (textbook) form; use sphere_lam_pressure_pole: atanh(k/c), k^2 = a^2 - r^2, c^2 = R^2 - r^2, loses 1 - k/c as a -> R; it is written log1p(2k(c + k) cosh(lam)^2/R^2)/2.

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) with x^2 = r^2 + w^2, w =
    sqrt(R^2 - r^2) tanh(u).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : mpmath.mpf
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return E_star*R*mpmath.atanh(mpmath.sqrt(R**2*mpmath.tanh(lam)**2 - r**2)/mpmath.sqrt(R**2 - r**2))/(mpmath.pi*mpmath.sqrt(R**2 - r**2))


def textbook_sphere_pressure_atanh_kernel(E_star, R, x):
    """Integrand (E*/pi) atanh(x/R)/x [Pa/m] of the rest of (5.59) for the spherical cap, to be integrated over w in (0, sqrt(a^2 - r^2)) at x = sqrt(r^2 + w^2), in the derived (textbook) form; use sphere_pressure_atanh_kernel: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) of the atanh term of g', with
    x^2 = r^2 + w^2 (dx/sqrt(x^2 - r^2) = dw/x); no elementary antiderivative.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : mpmath.mpf
        coordinate [m]
    """
    return E_star*mpmath.atanh(x/R)/(mpmath.pi*x)


def textbook_sphere_profile(R, r):
    """Height f(r) [m] of a spherical cap of radius R above its apex, 0 <= r <= R, in the derived (textbook) form; use sphere_profile: R - sqrt(R^2 - r^2) cancels for r << R; it is written r^2/(R + sqrt((R - r)(R + r))).

    Chapter: (5.52), Sneddon's sphere. Derived from: the sphere x^2 + (R - z)^2 = R^2.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return R - mpmath.sqrt(R**2 - r**2)


def textbook_stress_axis_sigma_xx_deep(a, nu, p0, z):
    """Radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure (for z >= a), in the derived (textbook) form; use stress_axis_sigma_xx_deep: (5.49) subtracts terms of size 1 to leave one of size (a/z)^2 (of size (a/z)^4 at nu = 1/2); 1 - atan(t)/t - t^2/(3(1 + t^2)) is written as (2/15) t^4 2F1(2, 5/2; 7/2; -t^2), t = a/z, used for z >= a.

    Chapter: (5.49). Derived from: (5.41) superposed over (5.15) along the axis.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*mpmath.atan(a/z))/(a*(a**2 + z**2))


def textbook_stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis under the Hertz pressure, in the derived (textbook) form; use stress_axis_sigma_zz: one division, no cancellation.

    Chapter: (5.48). Derived from: (5.43) superposed over (5.15) along the axis, (5.47).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -a**2*p0/(a**2 + z**2)


def textbook_stress_hertz_max_orthogonal_shear(p0):
    """The largest orthogonal shear |tau_rz| [Pa] under the Hertz pressure (any nu), in the derived (textbook) form; use stress_hertz_max_orthogonal_shear: the solved form subtracts 7 34^(1/2) from 31 2^(1/2) (a factor 14 of cancellation); this one has 5 - 17^(1/2) = 0.88 at worst.

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    return (mpmath.mpf(1)/mpmath.mpf(32))*p0*mpmath.sqrt(1 + mpmath.sqrt(17))*(-7*mpmath.sqrt(34) + 31*mpmath.sqrt(2))


def textbook_stress_hertz_max_orthogonal_shear_z(a):
    """Depth z [m] of the largest |tau_rz| under the Hertz pressure, in the derived (textbook) form; use stress_hertz_max_orthogonal_shear_z: 17^(1/2) - 4 = 0.12 cancels a factor 33; it is 1/(17^(1/2) + 4).

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    """
    return a*mpmath.sqrt(-4 + mpmath.sqrt(17))


def textbook_stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at (xi, beta), for xi >= 1, in the derived (textbook) form; use stress_hertz_sigma_rr_far: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4 overflows for xi > 1e77).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : mpmath.mpf
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*mpmath.atan(1/xi) + 1 - (mpmath.mpf(1)/mpmath.mpf(3))/(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


def textbook_stress_hertz_sigma_tt_far(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at (xi, beta), for xi >= 1, in the derived (textbook) form; use stress_hertz_sigma_tt_far: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4 overflows for xi > 1e77).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : mpmath.mpf
        Poisson's ratio [1]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : mpmath.mpf
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : mpmath.mpf
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    return p0*(-eta*(nu + 1)*(-xi*mpmath.atan(1/xi) + 1 - (mpmath.mpf(1)/mpmath.mpf(3))/(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


def textbook_stress_spheroidal_u(a, r, z):
    """Johnson's u [m^2], the root of r^2/(a^2 + u) + z^2/u = 1 (for r^2 + z^2 >= a^2), in the derived (textbook) form; use stress_spheroidal_u: the expanded discriminant cancels near the contact edge; q = (r - a)(r + a) + z^2 keeps it exact.

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*a**2 + (mpmath.mpf(1)/mpmath.mpf(2))*r**2 + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)


def textbook_stress_spheroidal_u_inside(a, r, z):
    """Johnson's u [m^2] for r^2 + z^2 < a^2, in the derived (textbook) form; use stress_spheroidal_u_inside: (q + D)/2 cancels for q = r^2 + z^2 - a^2 < 0; written as 2 a^2 z^2/(D - q).

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    z : mpmath.mpf
        depth below the surface [m]
    """
    return -mpmath.mpf(1)/mpmath.mpf(2)*a**2 + (mpmath.mpf(1)/mpmath.mpf(2))*r**2 + (mpmath.mpf(1)/mpmath.mpf(2))*z**2 + (mpmath.mpf(1)/mpmath.mpf(2))*mpmath.sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)


def textbook_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """Von Mises equivalent stress [Pa] of the stress tensor, in the derived (textbook) form; use stress_von_mises: the expanded 3 J2 subtracts products of the stresses and rounds below 0 for a nearly hydrostatic state (sqrt: NaN at the centre of a Hertz contact with nu = 1/2); (5.50) is a sum of squares.

    Chapter: (5.50). Derived from: sqrt(3 J2), J2 the second invariant of the stress
    deviator.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_von_mises_invariant``.

    Parameters
    ----------
    sigma_xx : mpmath.mpf
        normal stress component sigma_xx [Pa]
    sigma_yy : mpmath.mpf
        normal stress component sigma_yy [Pa]
    sigma_zz : mpmath.mpf
        normal stress component sigma_zz [Pa]
    tau_xy : mpmath.mpf
        shear stress component tau_xy [Pa]
    tau_yz : mpmath.mpf
        shear stress component tau_yz [Pa]
    tau_xz : mpmath.mpf
        shear stress component tau_xz [Pa]
    """
    return mpmath.sqrt(sigma_xx**2 - sigma_xx*sigma_yy - sigma_xx*sigma_zz + sigma_yy**2 - sigma_yy*sigma_zz + sigma_zz**2 + 3*tau_xy**2 + 3*tau_xz**2 + 3*tau_yz**2)


def textbook_tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a cone under normal force F and tangential F_x, in the derived (textbook) form; use tangential_cone_displacement: 1 - sqrt(1 - F_x/(mu F)) cancels as F_x -> 0.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^2, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return (-mpmath.sqrt(F)*mpmath.sqrt(mu_f)*mpmath.sqrt(F*mu_f - F_x) + F*mu_f)/(G_star*a)


def textbook_tangential_cone_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle by a cone under normal force F, amplitude F_amp, in the derived (textbook) form; use tangential_cone_energy: a - c = a x/(1 + sqrt(1 - x)), x = F_amp/(mu F), instead of a (1 - sqrt(1 - x)).

    Chapter: MDR tangential, cone (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return (mpmath.mpf(4)/mpmath.mpf(3))*mpmath.sqrt(F)*mpmath.sqrt(mu_f)*(mpmath.sqrt(F)*mpmath.sqrt(mu_f) - mpmath.sqrt(F*mu_f - F_amp))**3/(G_star*a)


def textbook_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a cone, finite on the axis: mu E* tan(theta)/2 ln(a/c) at r = 0, in the derived (textbook) form; use tangential_cone_traction_stick: the two pressures are each log-infinite on the axis (inf - inf = NaN at r = 0); as one logarithm of (a + sqrt(a^2 - r^2))/(c + sqrt(c^2 - r^2)), written log1p of its excess over 1, it is finite at r = 0 and keeps its digits as c -> a.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: (5.59) of the
    tangential line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cone_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r : mpmath.mpf
        radial coordinate on the surface [m]
    a : mpmath.mpf
        contact radius [m]
    c : mpmath.mpf
        radius of the stick zone [m]
    theta : mpmath.mpf
        angle between the cone's surface and the plane [rad]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    """
    return mu_f*((mpmath.mpf(1)/mpmath.mpf(2))*E_star*mpmath.log((a + mpmath.sqrt(a**2 - r**2))/r)*mpmath.tan(theta) - mpmath.mpf(1)/mpmath.mpf(2)*E_star*mpmath.log((c + mpmath.sqrt(c**2 - r**2))/r)*mpmath.tan(theta))


def textbook_tangential_modulus(G1, nu1, G2, nu2):
    """Tangential effective modulus G* [Pa] of two elastic bodies, in the derived (textbook) form; use tangential_modulus: a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf.

    Chapter: MDR tangential springs (not in the chapter). Derived from: direction average of
    the Cerruti surface compliance of each body, compliances added.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    G1 : mpmath.mpf
        shear modulus of body 1 [Pa]
    nu1 : mpmath.mpf
        Poisson's ratio of body 1 [1]
    G2 : mpmath.mpf
        shear modulus of body 2 [Pa]
    nu2 : mpmath.mpf
        Poisson's ratio of body 2 [1]
    """
    return -4*G1*G2/(G1*(nu2 - 2) + G2*(nu1 - 2))


def textbook_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a power-law profile under normal force F and tangential force F_x, in the derived (textbook) form; use tangential_powerlaw_displacement: 1 - (1 - F_x/(mu F))^(n/(n+1)) cancels as F_x -> 0.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: c from F_x, then
    g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_x : mpmath.mpf
        tangential force [N]
    """
    return (mpmath.mpf(1)/mpmath.mpf(2))*F*mu_f*(1 - (1 - F_x/(F*mu_f))**(n/(n + 1)))*(n + 1)/(G_star*a*n)


def textbook_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a power-law profile displaced by u_x, in the derived (textbook) form; use tangential_powerlaw_force: 1 - (c/a)^(n+1) cancels as u_x -> 0: -expm1((n+1)/n log1p(-q)).

    Chapter: MDR tangential, power law (not in the chapter). Derived from: mu (F_N(a) -
    F_N(c)), asserted equal to the spring sum.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return 2*E_star*a**(n + 1)*c_n*kappa_n*mu_f*n*(1 - (1 - G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))**((n + 1)/n))/(n + 1)


def textbook_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """1 - c/a [1] of a power-law profile under normal force F and tangential force F_amp, in the derived (textbook) form; use tangential_powerlaw_stick_deficit: 1 - (1 - F_amp/(mu F))^(1/(n+1)) cancels at small amplitude.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : mpmath.mpf
        normal force [N]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    F_amp : mpmath.mpf
        amplitude F_x* of an oscillating tangential force [N]
    """
    return 1 - (1 - F_amp/(F*mu_f))**(1/(n + 1))


def textbook_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a power-law profile f = c_n r^n displaced by u_x, in the derived (textbook) form; use tangential_powerlaw_stick_radius: (1 - q)^(1/n) as exp(log1p(-q)/n): accurate for large n and tiny q.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: g(c) = d - G*
    u_x/(mu E*), g = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : mpmath.mpf
        contact radius [m]
    c_n : mpmath.mpf
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : mpmath.mpf
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : mpmath.mpf
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : mpmath.mpf
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : mpmath.mpf
        coefficient of (Coulomb) friction mu [1]
    u_x : mpmath.mpf
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    return a*(1 - G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))**(1/n)


def textbook_uniform_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) under a uniform pressure p0, in the derived (textbook) form; use uniform_pressure_displacement_outside: E(m) - (1 - m) K(m) cancels like m = a^2/r^2 for r >> a; it equals (pi m/4) 2F1(1/2, 1/2; 2; m).

    Chapter: Problem 6 (outside the disc). Derived from: (5.7) with p = p0 (n = 0) outside
    the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    a : mpmath.mpf
        contact radius [m]
    p0 : mpmath.mpf
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return 4*p0*r*((a**2/r**2 - 1)*mpmath.ellipk(a**2/r**2) + mpmath.ellipe(a**2/r**2))/(mpmath.pi*E_star)


def textbook_worn_displacement_outside(R, a, b, r):
    """Surface displacement u_z(r) [m] outside the contact (r > a) of the worn paraboloid, in the derived (textbook) form; use worn_displacement_outside: S sqrt(1 - S^2) - asin S, S^2 = (a^2 - b^2)/(r^2 - b^2), cancels for r >> a; it is written -(2 S^3/3) 2F1(1/2, 3/2; 5/2; S^2).

    Chapter: Problem 8, (5.60). Derived from: (5.60) with x^2 = b^2 + (r^2 - b^2)
    sin^2(phi).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : mpmath.mpf
        contact radius [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : mpmath.mpf
        radial coordinate on the surface [m]
    """
    return (2*a*mpmath.sqrt(a**2 - b**2)*mpmath.asin(a/r) - (b - r)*(b + r)*(mpmath.sqrt((-a**2 + b**2)/(b**2 - r**2))*mpmath.sqrt((-a**2 + r**2)/(-b**2 + r**2)) - mpmath.asin(mpmath.sqrt((-a**2 + b**2)/(b**2 - r**2)))))/(mpmath.pi*R)


def textbook_worn_force(E_star, R, b, d):
    """Normal force F [N] of the worn paraboloid at depth d, in the derived (textbook) form; use worn_force: sqrt(-1 + sqrt(1 + s^2)), s = 2 R d/b^2, cancels for s << 1; it is written s/sqrt(sqrt(1 + s^2) + 1).

    Chapter: Problem 8. Derived from: (5.57) at the contact radius of (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : mpmath.mpf
        effective modulus E* (5.8), (5.26) [Pa]
    R : mpmath.mpf
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : mpmath.mpf
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : mpmath.mpf
        indentation depth [m]
    """
    return (mpmath.mpf(1)/mpmath.mpf(3))*E_star*mpmath.sqrt(-2*b**2 + 2*mpmath.sqrt(4*R**2*d**2 + b**4))*(2*b**2 + mpmath.sqrt(4*R**2*d**2 + b**4))/R
