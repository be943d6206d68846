"""Functions generated from the SymPy derivations in ``hertzmdr.derive``.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``);
``python -m hertzmdr.derive --check`` fails when this file is stale. Each function cites the chapter's
equation, the derivation it comes from and the test that verifies it by an independent route.
Arguments are floats or NumPy arrays in SI units; they are not validated here -- the
hand-written modules of ``hertzmdr.numeric`` validate and broadcast. Called with Python floats
only, a function evaluates the same expression with the math module (its scalar path).
"""

import math

import numpy

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

#: every relation: (name, equation, family, derived formula, erratum or "")
RELATIONS = (
    ('adhesion_cone_depth', '(5.55), adhesive', 'adhesion', 'pi*a*tan(theta)/2 - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)', ''),
    ('adhesion_cone_force_from_radius', '(5.57), adhesive', 'adhesion', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*sqrt(dgamma) + pi*E_star*a**2*tan(theta)/2', ''),
    ('adhesion_cone_g_slope', '(5.52) of r tan(theta)', 'adhesion', 'pi*tan(theta)/2', ''),
    ('adhesion_cone_pull_off_depth_dc', '(5.55), adhesive', 'adhesion', '-dgamma/(E_star*tan(theta))', ''),
    ('adhesion_cone_pull_off_depth_fc', '(5.55), adhesive', 'adhesion', '3*dgamma/(E_star*tan(theta))', ''),
    ('adhesion_cone_pull_off_force_dc', '(5.57), adhesive', 'adhesion', '-6*dgamma**2/(pi*E_star*tan(theta)**3)', ''),
    ('adhesion_cone_pull_off_force_fc', '(5.57), adhesive', 'adhesion', '-54*dgamma**2/(pi*E_star*tan(theta)**3)', ''),
    ('adhesion_cone_pull_off_radius_dc', '(5.57), adhesive', 'adhesion', '2*dgamma/(pi*E_star*tan(theta)**2)', ''),
    ('adhesion_cone_pull_off_radius_fc', '(5.57), adhesive', 'adhesion', '18*dgamma/(pi*E_star*tan(theta)**2)', ''),
    ('adhesion_cone_zero_load_radius', '(5.57), adhesive', 'adhesion', '32*dgamma/(pi*E_star*tan(theta)**2)', ''),
    ('adhesion_critical_elongation', '(5.55), energy balance', 'adhesion', 'sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)', ''),
    ('adhesion_depth', '(5.55), adhesive', 'adhesion', 'g_a - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)', ''),
    ('adhesion_depth_slope', '(5.55), adhesive', 'adhesion', 'g_slope - sqrt(2)*sqrt(pi)*sqrt(dgamma)/(2*sqrt(E_star)*sqrt(a))', ''),
    ('adhesion_displacement_outside_edge', '(5.60), adhesive', 'adhesion', '-2*sqrt(2)*sqrt(a)*sqrt(dgamma)*asin(a/r)/(sqrt(pi)*sqrt(E_star))', ''),
    ('adhesion_energy_release_rate', '(5.57), energy balance', 'adhesion', 'E_star*(d - g_a)**2/(2*pi*a)', ''),
    ('adhesion_force_slope', '(5.57), adhesive', 'adhesion', '-3*sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(dgamma) + 2*E_star*a*g_slope', ''),
    ('adhesion_paraboloid_g_slope', '(5.52) of r^2/(2R)', 'adhesion', '2*x/R', ''),
    ('adhesion_powerlaw_depth', '(5.55), adhesive', 'adhesion', 'a**n*c_n*kappa_n - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)', ''),
    ('adhesion_powerlaw_force_from_radius', '(5.57), adhesive', 'adhesion', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*sqrt(dgamma)*n/(n + 1) - 2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*sqrt(dgamma)/(n + 1) + 2*E_star*a*a**n*c_n*kappa_n*n/(n + 1)', ''),
    ('adhesion_powerlaw_g_slope', '(5.52), Problem 7(d)', 'adhesion', 'c_n*kappa_n*n*x**n/x', ''),
    ('adhesion_powerlaw_pull_off_depth_dc', '(5.55), adhesive', 'adhesion', '-sqrt(2)*sqrt(pi)*sqrt(dgamma)*(2*n - 1)*sqrt((pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))/(2*sqrt(E_star)*n)', ''),
    ('adhesion_powerlaw_pull_off_depth_fc', '(5.55), adhesive', 'adhesion', '-sqrt(2)*sqrt(pi)*sqrt(dgamma)*(2*n - 3)*sqrt((9*pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))/(2*sqrt(E_star)*n)', ''),
    ('adhesion_powerlaw_pull_off_force_dc', '(5.57), adhesive', 'adhesion', '-sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(dgamma)*(2*n + 1)*((pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))**(3/2)/(n + 1)', ''),
    ('adhesion_powerlaw_pull_off_force_fc', '(5.57), adhesive', 'adhesion', '-sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(dgamma)*(2*n - 1)*((9*pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1)))**(3/2)/(n + 1)', ''),
    ('adhesion_powerlaw_pull_off_radius_dc', '(5.57), adhesive', 'adhesion', '(pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))', ''),
    ('adhesion_powerlaw_pull_off_radius_fc', '(5.57), adhesive', 'adhesion', '(9*pi*dgamma/(2*E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))', ''),
    ('adhesion_powerlaw_zero_load_radius', '(5.57), adhesive', 'adhesion', '(2*pi*dgamma*(n**2 + 2*n + 1)/(E_star*c_n**2*kappa_n**2*n**2))**(1/(2*n - 1))', ''),
    ('adhesion_pressure_edge', '(5.59), adhesive', 'adhesion', '-sqrt(2)*sqrt(E_star)*sqrt(a)*sqrt(dgamma)/(sqrt(pi)*sqrt(a**2 - r**2))', ''),
    ('adhesion_punch_cycle_work', '(5.57), Kendall', 'adhesion', '2*pi*a**2*dgamma', ''),
    ('adhesion_punch_pull_off_force', '(5.57), Kendall', 'adhesion', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*sqrt(dgamma)', ''),
    ('adhesion_sphere_g_slope', "(5.52), Sneddon's sphere", 'adhesion', '(R*x + (R**2 - x**2)*atanh(x/R))/(R**2 - x**2)', ''),
    ('adhesion_tabor_parameter', 'Tabor (1977)', 'adhesion', 'R**(1/3)*dgamma**(2/3)/(E_star**(2/3)*z0)', ''),
    ('adhesion_worn_g_slope', '(5.52), Problem 8', 'adhesion', '(-b**2 + 2*x**2)/(R*sqrt(-b**2 + x**2))', ''),
    ('bodies_crossed_cylinders_curvature_1', '(5.32), (5.33), any angle', 'bodies', 'sqrt((cos(2*alpha)/R2 + 1/R1)**2 + sin(2*alpha)**2/R2**2)/2 + 1/(2*R2) + 1/(2*R1)', ''),
    ('bodies_crossed_cylinders_curvature_2', '(5.32), (5.33), any angle', 'bodies', '-sqrt((cos(2*alpha)/R2 + 1/R1)**2 + sin(2*alpha)**2/R2**2)/2 + 1/(2*R2) + 1/(2*R1)', ''),
    ('bodies_crossed_cylinders_gaussian_radius', '(5.33), any angle', 'bodies', 'sqrt(R1)*sqrt(R2)/Abs(sin(alpha))', ''),
    ('bodies_effective_modulus', '(5.26)', 'bodies', '-E1*E2/(E1*nu2**2 - E1 + E2*nu1**2 - E2)', ''),
    ('bodies_effective_modulus_rigid', '(5.8), (5.26) with E2 -> inf', 'bodies', '-E/(nu**2 - 1)', ''),
    ('bodies_effective_radius', '(5.27)', 'bodies', 'R1*R2/(R1 + R2)', ''),
    ('bodies_gaussian_approx_area', '(5.29), approximation', 'bodies', 'pi*sqrt(R1)*sqrt(R2)*d', ''),
    ('bodies_gaussian_approx_depth_from_force', '(5.24) with (5.30), approximation', 'bodies', '6**(2/3)*F**(2/3)/(4*E_star**(2/3)*R1**(1/6)*R2**(1/6))', ''),
    ('bodies_gaussian_approx_force', '(5.23) with (5.30), approximation', 'bodies', '4*E_star*R1**(1/4)*R2**(1/4)*d**(3/2)/3', ''),
    ('bodies_gaussian_approx_max_pressure', '(5.22) with (5.30), approximation', 'bodies', '2*E_star*sqrt(d)/(pi*R1**(1/4)*R2**(1/4))', ''),
    ('bodies_gaussian_approx_pressure', '(5.31), approximation', 'bodies', '2*E_star*sqrt(d)*sqrt(Max(0, 1 - y**2/(R2*d) - x**2/(R1*d)))/(pi*R1**(1/4)*R2**(1/4))', ''),
    ('bodies_gaussian_approx_semi_axis_1', '(5.28), approximation', 'bodies', 'sqrt(R1)*sqrt(d)', ''),
    ('bodies_gaussian_approx_semi_axis_2', '(5.28), approximation', 'bodies', 'sqrt(R2)*sqrt(d)', ''),
    ('bodies_gaussian_radius', '(5.30)', 'bodies', 'sqrt(R1)*sqrt(R2)', ''),
    ('bodies_principal_curvature_1', '(5.32), Problem 2, general', 'bodies', 'sqrt((-1/R2b + 1/R2a)**2*sin(2*omega)**2 + ((-1/R2b + 1/R2a)*cos(2*omega) - 1/R1b + 1/R1a)**2)/2 + 1/(2*R2b) + 1/(2*R2a) + 1/(2*R1b) + 1/(2*R1a)', ''),
    ('bodies_principal_curvature_2', '(5.32), Problem 2, general', 'bodies', '-sqrt((-1/R2b + 1/R2a)**2*sin(2*omega)**2 + ((-1/R2b + 1/R2a)*cos(2*omega) - 1/R1b + 1/R1a)**2)/2 + 1/(2*R2b) + 1/(2*R2a) + 1/(2*R1b) + 1/(2*R1a)', ''),
    ('bodies_problem2_force', 'Problem 2', 'bodies', '-2*2**(1/4)*E*sqrt(R)*d**(3/2)/(3*nu**2 - 3)', 'with R~ = sqrt(2) R the factor is 2^(5/4)/3, not 2^(7/4)/3 (the printed force is sqrt(2) times too large)'),
    ('bodies_problem2_gaussian_radius', 'Problem 2', 'bodies', 'sqrt(2)*R', 'with the principal radii halved, R~ = sqrt(2) R, not 2 sqrt(2) R (check: R/sin(alpha) is R at alpha = pi/2, the sphere of (5.33))'),
    ('bodies_problem2_principal_radius_1', 'Problem 2', 'bodies', '-sqrt(2)*R + 2*R', 'the chapter takes the eigenvalues of the coefficient matrix M of h = x^T M x, which are half the principal curvatures (the Hessian is 2M): R_1,2 = R/(1 +- 1/sqrt(2)), not 2R/(1 +- 1/sqrt(2))'),
    ('bodies_problem2_principal_radius_2', 'Problem 2', 'bodies', 'sqrt(2)*R + 2*R', 'eigenvalues of M instead of the Hessian 2M: the radius is R/(1 - 1/sqrt(2)), half the printed one'),
    ('boussinesq_sigma_xx', '(5.41)', 'boussinesq', '-F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(3/2) + 2*nu*z**3*(x**2 + y**2 + z**2) + 4*nu*z**2*(x**2 + y**2 + z**2)**(3/2) - 2*nu*(x**2 + y**2 + z**2)**(5/2) + 3*x**2*z**3 + 6*x**2*z**2*sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(3/2) - z**3*(x**2 + y**2 + z**2) - 2*z**2*(x**2 + y**2 + z**2)**(3/2) + (x**2 + y**2 + z**2)**(5/2))/(2*pi*(z + sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))', ''),
    ('boussinesq_sigma_xy', '(5.44)', 'boussinesq', '-F*x*y*(2*nu*z*(x**2 + y**2 + z**2) + 4*nu*(x**2 + y**2 + z**2)**(3/2) + 3*z**3 + 6*z**2*sqrt(x**2 + y**2 + z**2) + 2*z*(x**2 + y**2 + z**2) - 2*(x**2 + y**2 + z**2)**(3/2))/(2*pi*(z + sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))', ''),
    ('boussinesq_sigma_xz', '(5.46)', 'boussinesq', '-3*F*x*z**2/(2*pi*(x**2 + y**2 + z**2)**(5/2))', 'the sign: with the force F acting in +z (into the body, z > 0 in the body) the derivation gives tau_xz = -3 F x z^2/(2 pi R^5); the print has +3 F x z^2/(2 pi R^5), which together with the printed (5.43) violates the equilibrium d(tau_xz)/dx + d(tau_yz)/dy + d(sigma_zz)/dz = 0'),
    ('boussinesq_sigma_yy', '(5.42)', 'boussinesq', 'F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(3/2) - 2*nu*z*(x**2 + y**2 + z**2)**2 - 2*nu*(x**2 + y**2 + z**2)**(5/2) + 3*x**2*z**3 + 6*x**2*z**2*sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(3/2) + 3*z**5 + 6*z**4*sqrt(x**2 + y**2 + z**2) - 6*z**2*(x**2 + y**2 + z**2)**(3/2) - 2*z*(x**2 + y**2 + z**2)**2 + (x**2 + y**2 + z**2)**(5/2))/(2*pi*(z + sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))', ''),
    ('boussinesq_sigma_yz', '(5.45)', 'boussinesq', '-3*F*y*z**2/(2*pi*(x**2 + y**2 + z**2)**(5/2))', 'the sign: with the force F acting in +z (into the body, z > 0 in the body) the derivation gives tau_yz = -3 F y z^2/(2 pi R^5); the print has +3 F y z^2/(2 pi R^5), which together with the printed (5.43) violates the equilibrium d(tau_xz)/dx + d(tau_yz)/dy + d(sigma_zz)/dz = 0'),
    ('boussinesq_sigma_zz', '(5.43)', 'boussinesq', '-3*F*z**3/(2*pi*(x**2 + y**2 + z**2)**(5/2))', ''),
    ('boussinesq_surface_prefactor', '(5.7)', 'boussinesq', '1/(pi*E_star)', ''),
    ('boussinesq_surface_ux', '(5.4)', 'boussinesq', 'F*x*(nu + 1)*(2*nu - 1)/(2*pi*E*(x**2 + y**2))', ''),
    ('boussinesq_surface_uy', '(5.5)', 'boussinesq', 'F*y*(nu + 1)*(2*nu - 1)/(2*pi*E*(x**2 + y**2))', ''),
    ('boussinesq_surface_uz', '(5.6)', 'boussinesq', '-F*(nu - 1)*(nu + 1)/(pi*E*sqrt(x**2 + y**2))', ''),
    ('boussinesq_ux', '(5.1)', 'boussinesq', 'F*(nu + 1)*(x*z/(x**2 + y**2 + z**2)**(3/2) - x*(1 - 2*nu)/((z + sqrt(x**2 + y**2 + z**2))*sqrt(x**2 + y**2 + z**2)))/(2*pi*E)', ''),
    ('boussinesq_uy', '(5.2)', 'boussinesq', 'F*(nu + 1)*(y*z/(x**2 + y**2 + z**2)**(3/2) - y*(1 - 2*nu)/((z + sqrt(x**2 + y**2 + z**2))*sqrt(x**2 + y**2 + z**2)))/(2*pi*E)', ''),
    ('boussinesq_uz', '(5.3)', 'boussinesq', 'F*(nu + 1)*(z**2/(x**2 + y**2 + z**2)**(3/2) + (2 - 2*nu)/sqrt(x**2 + y**2 + z**2))/(2*pi*E)', ''),
    ('cattaneo_displacement', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', '3*(-F**(1/3)*mu_f**(1/3)*(F*mu_f - F_x)**(2/3) + F*mu_f)/(4*G_star*a)', ''),
    ('cattaneo_force', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', '4*(E_star**(3/2)*a**3*mu_f**(3/2) - E_star*a**2*mu_f*sqrt(E_star*a**2*mu_f - G_star*R*u_x) + G_star*R*u_x*sqrt(E_star*a**2*mu_f - G_star*R*u_x))/(3*sqrt(E_star)*R*sqrt(mu_f))', ''),
    ('cattaneo_stick_radius', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', 'sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(sqrt(E_star)*sqrt(mu_f))', ''),
    ('cattaneo_stick_radius_from_force', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', 'a*(F*mu_f - F_x)**(1/3)/(F**(1/3)*mu_f**(1/3))', ''),
    ('cattaneo_traction_slip', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', '2*E_star*mu_f*sqrt(a**2 - r**2)/(pi*R)', ''),
    ('cattaneo_traction_stick', 'Cattaneo-Mindlin (not in the chapter)', 'tangential', '2*E_star*mu_f*(sqrt(a**2 - r**2) - sqrt(c**2 - r**2))/(pi*R)', ''),
    ('cerruti_surface_ux', 'Cerruti (not in the chapter; Johnson (3.87))', 'cerruti', 'Q*(-nu*y**2 + x**2 + y**2)/(2*pi*G*(x**2 + y**2)**(3/2))', ''),
    ('cerruti_surface_uy', 'Cerruti (not in the chapter; Johnson (3.87))', 'cerruti', 'Q*nu*x*y/(2*pi*G*(x**2 + y**2)**(3/2))', ''),
    ('cerruti_surface_uz', 'Cerruti (not in the chapter; Johnson (3.87))', 'cerruti', '-Q*x*(2*nu - 1)/(4*pi*G*(x**2 + y**2))', ''),
    ('cerruti_ux', 'Cerruti (not in the chapter; Johnson (3.86))', 'cerruti', 'Q*(x**2/(x**2 + y**2 + z**2)**(3/2) + (1 - 2*nu)*(-x**2/((z + sqrt(x**2 + y**2 + z**2))**2*sqrt(x**2 + y**2 + z**2)) + 1/(z + sqrt(x**2 + y**2 + z**2))) + 1/sqrt(x**2 + y**2 + z**2))/(4*pi*G)', ''),
    ('cerruti_uy', 'Cerruti (not in the chapter; Johnson (3.86))', 'cerruti', 'Q*(-x*y*(1 - 2*nu)/((z + sqrt(x**2 + y**2 + z**2))**2*sqrt(x**2 + y**2 + z**2)) + x*y/(x**2 + y**2 + z**2)**(3/2))/(4*pi*G)', ''),
    ('cerruti_uz', 'Cerruti (not in the chapter; Johnson (3.86))', 'cerruti', 'Q*(x*z/(x**2 + y**2 + z**2)**(3/2) + x*(1 - 2*nu)/((z + sqrt(x**2 + y**2 + z**2))*sqrt(x**2 + y**2 + z**2)))/(4*pi*G)', ''),
    ('cone_contact_radius', '(5.38), Problem 7(c)', 'cone', '2*d/(pi*tan(theta))', ''),
    ('cone_contact_radius_from_force', '(5.38), (5.40)', 'cone', 'sqrt(2)*sqrt(F)/(sqrt(pi)*sqrt(E_star)*sqrt(tan(theta)))', ''),
    ('cone_depth', '(5.38)', 'cone', 'pi*a*tan(theta)/2', ''),
    ('cone_depth_from_force', '(5.40), inverted', 'cone', 'sqrt(2)*sqrt(pi)*sqrt(F)*sqrt(tan(theta))/(2*sqrt(E_star))', ''),
    ('cone_force', '(5.40)', 'cone', '2*E_star*d**2/(pi*tan(theta))', ''),
    ('cone_g', '(5.52) of f = r tan(theta)', 'tangential', 'pi*x*tan(theta)/2', ''),
    ('cone_mean_pressure', '(5.40)/(pi a^2)', 'cone', 'E_star*tan(theta)/2', ''),
    ('cone_pressure', '(5.39)', 'cone', 'E_star*tan(theta)*acosh(2*d/(pi*r*tan(theta)))/2', "the print has a spurious minus sign: the pressure is positive in compression, p = E* d/(pi a) arccosh(a/r) with E* = E/(1 - nu^2), as (5.9), (5.15) and the chapter's own Problem 7(c) have it"),
    ('cone_profile', '(5.52)', 'tangential', 'r*tan(theta)', ''),
    ('cone_stiffness', 'Problem 5', 'cone', '4*E_star*d/(pi*tan(theta))', ''),
    ('contact_mean_pressure', '(5.17)', 'contact', 'F/A', ''),
    ('coulomb_sliding_force', "Coulomb's law, from the springs (not in the chapter)", 'tangential', 'F*mu_f', ''),
    ('disc_mean_pressure', '(5.17)', 'contact', 'F/(pi*a**2)', ''),
    ('disc_pressure', '(5.9), (5.15), Problem 6', 'contact', 'p0*(1 - r**2/a**2)**n_p', ''),
    ('ellipse_area', '(5.29), exact', 'ellipse', '2*pi*R1*d*t_ba*(-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/((1 - t_ba**2)*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2)))', ''),
    ('ellipse_depth_from_force', '(5.23), exact, inverted', 'ellipse', '3**(2/3)*F**(2/3)*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(2*(1 - t_ba**2)) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(2*(1 - t_ba**2)))/(pi**(2/3)*E_star**(2/3)*R1**(1/3)*((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))**(1/3))', ''),
    ('ellipse_equivalent_radius', '(5.23), exact', 'ellipse', 'pi**2*R1*(-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(2*(1 - t_ba**2)*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))**3)', ''),
    ('ellipse_force', '(5.23), exact', 'ellipse', '2*sqrt(2)*pi*E_star*sqrt(R1)*d**(3/2)*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/(3*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))**(3/2))', ''),
    ('ellipse_max_pressure', '(5.31), exact', 'ellipse', 'sqrt(2)*E_star*sqrt(d)/(2*sqrt(R1)*t_ba*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))*sqrt((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2)))', ''),
    ('ellipse_mean_pressure', '(5.17), exact', 'ellipse', 'sqrt(2)*E_star*sqrt(d)/(3*sqrt(R1)*t_ba*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))*sqrt((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2)))', ''),
    ('ellipse_pressure', '(5.31)', 'ellipse', 'sqrt(2)*E_star*sqrt(d)*sqrt(Max(0, 1 - x**2*(1 - t_ba**2)*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/(2*R1*d*(-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))) - y**2*(1 - t_ba**2)*((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/(2*R1*d*t_ba**2*(-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2)))))/(2*sqrt(R1)*t_ba*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))*sqrt((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2)))', ''),
    ('ellipse_radius_ratio', '(5.31)-(5.32), exact', 'ellipse', '(-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(t_ba**2*(-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2)))', ''),
    ('ellipse_semi_major', '(5.28), exact', 'ellipse', 'sqrt(2)*sqrt(R1)*sqrt(d)*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/sqrt((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))', ''),
    ('ellipse_semi_minor', '(5.28), exact', 'ellipse', 'sqrt(2)*sqrt(R1)*sqrt(d)*t_ba*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/sqrt((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))', ''),
    ('ellipse_stiffness', '(5.13), exact', 'ellipse', 'sqrt(2)*pi*E_star*sqrt(R1)*sqrt(d)*sqrt((-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))/((-t_ba**2*elliptic_k(1 - t_ba**2) + elliptic_e(1 - t_ba**2))/(1 - t_ba**2) + (-elliptic_e(1 - t_ba**2) + elliptic_k(1 - t_ba**2))/(1 - t_ba**2))**(3/2)', ''),
    ('ellipse_stress_I_x', '(5.31)', 'ellipse_stress', '2*carlson_rd(b_e**2 + lam_e, lam_e, a**2 + lam_e)/3', ''),
    ('ellipse_stress_I_y', '(5.31)', 'ellipse_stress', '2*carlson_rd(a**2 + lam_e, lam_e, b_e**2 + lam_e)/3', ''),
    ('ellipse_stress_axis_shear_x', '(5.31), (5.50)', 'ellipse_stress', 'a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(2*sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(2*sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2))', ''),
    ('ellipse_stress_axis_shear_x_slope', '(5.31), (5.50)', 'ellipse_stress', 'a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) + a*b_e*nu*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - a*b_e*p0*z/(2*sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - a*b_e*p0*z*(2*nu - 1)/(2*(a**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - 3*a*b_e*p0*z/(2*(a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) + a*b_e*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(2*sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2)', ''),
    ('ellipse_stress_axis_shear_y', '(5.31), (5.50)', 'ellipse_stress', 'a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(2*sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(2*sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2))', ''),
    ('ellipse_stress_axis_shear_y_slope', '(5.31), (5.50)', 'ellipse_stress', 'a*b_e*nu*p0*z/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + a*b_e*nu*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*z*(2*nu - 1)/(2*(b_e**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - 3*a*b_e*p0*z/(2*sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - a*b_e*p0*z/(2*(a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) + a*b_e*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(2*sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2)', ''),
    ('ellipse_stress_axis_sigma_xx', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2)))', ''),
    ('ellipse_stress_axis_sigma_yy', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2)))', ''),
    ('ellipse_stress_axis_sigma_zz', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '-a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2))', ''),
    ('ellipse_stress_axis_von_mises', '(5.31), (5.50)', 'ellipse_stress', 'sqrt((-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))**2/2)', ''),
    ('ellipse_stress_axis_von_mises_slope', '(5.31), (5.50)', 'ellipse_stress', '((-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))*(-4*a*b_e*nu*p0*z/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 4*a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) - 4*a*b_e*nu*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + 2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) - 4*a*b_e*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2))/4 + (2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))*(4*a*b_e*nu*p0*z/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + 4*a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) + 4*a*b_e*nu*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)) + 4*a*b_e*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2))/4 + (2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))*(4*a*b_e*nu*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 4*a*b_e*nu*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 + 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(3/2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - 4*a*b_e*p0*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 4*a*b_e*p0*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2) + 2*a*b_e*p0*(2*nu - 1)*(-z/sqrt(b_e**2 + z**2) - z/sqrt(a**2 + z**2))/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))**2))/4)/sqrt((-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))**2/2) - 2*(-a*b_e*nu*p0*z*(-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))/2 + a*b_e*p0*z*(2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))/2 + (2*a*b_e*nu*p0*z - 2*a*b_e*p0*z)*(2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))/4)/(sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)*sqrt((-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))**2/2)) - 2*(a*b_e*nu*p0*z*(2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))/2 - a*b_e*p0*z*(-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))/2 + (-2*a*b_e*nu*p0*z + 2*a*b_e*p0*z)*(2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))/4)/((a**2 + z**2)**(3/2)*sqrt(b_e**2 + z**2)*sqrt((-2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) - 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) - a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*nu*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)) + 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0/(sqrt(a**2 + z**2)*sqrt(b_e**2 + z**2)))**2/2 + (2*a*b_e*nu*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 - 2*a*b_e*nu*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - 2*a*b_e*p0*z*carlson_rd(a**2 + z**2, z**2, b_e**2 + z**2)/3 + 2*a*b_e*p0*z*carlson_rd(b_e**2 + z**2, z**2, a**2 + z**2)/3 - a*b_e*p0*(2*nu - 1)/(sqrt(b_e**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(sqrt(a**2 + z**2)*(sqrt(a**2 + z**2) + sqrt(b_e**2 + z**2))))**2/2))', ''),
    ('ellipse_stress_cubic_lam', '(5.31)', 'ellipse_stress', 'lam_e*(lam_e - w1_e)*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e)*(b_e**2 + lam_e)', ''),
    ('ellipse_stress_cubic_lam_slope', '(5.31)', 'ellipse_stress', 'lam_e*(lam_e - w1_e) + lam_e*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e) - z**2*(b_e**2 + lam_e) + (lam_e - w1_e)*(d_e + lam_e - w1_e)', ''),
    ('ellipse_stress_cubic_q', '(5.31)', 'ellipse_stress', 'q_e*(d_e + q_e)*(q_e + w1_e) - z**2*(q_e + w1_a)*(q_e + w1_b)', ''),
    ('ellipse_stress_cubic_q_slope', '(5.31)', 'ellipse_stress', 'q_e*(d_e + q_e) + q_e*(q_e + w1_e) - z**2*(q_e + w1_a) - z**2*(q_e + w1_b) + (d_e + q_e)*(q_e + w1_e)', ''),
    ('ellipse_stress_d', '(5.31)', 'ellipse_stress', 'sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)', ''),
    ('ellipse_stress_e_sq', '(5.31)', 'ellipse_stress', 'q_e*(d_e + q_e)/((a**2 + lam_e)*(b_e**2 + lam_e))', ''),
    ('ellipse_stress_jxx_integrand', '(5.31)', 'ellipse_stress', '-2*(-d_e*v_q**2 - v_q**4 + v_q**2*x**2 + w1_b*x**2)/(sqrt(d_e + v_q**2)*(v_q**2 + w1_a)**2*(v_q**2 + w1_b))', ''),
    ('ellipse_stress_jxy_integrand', '(5.31)', 'ellipse_stress', '-2*x*y/(sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b))', ''),
    ('ellipse_stress_jyy_integrand', '(5.31)', 'ellipse_stress', '-2*(-d_e*v_q**2 - v_q**4 + v_q**2*y**2 + w1_a*y**2)/(sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b)**2)', ''),
    ('ellipse_stress_sigma_xx', '(5.31), (5.41)-(5.46)', 'ellipse_stress', 'I_x*a*b_e*e_c*sqrt(lam_e)*p0 + I_y*a*b_e*e_c*sqrt(lam_e)*nu*p0 + J_xx*a*b_e*p0*(2*nu - 1)/2 - a*b_e*e_c*p0*(lam_e*x**2 + 2*nu*(a**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/((a**2 + lam_e)**(5/2)*sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_sigma_yy', '(5.31), (5.41)-(5.46)', 'ellipse_stress', 'I_x*a*b_e*e_c*sqrt(lam_e)*nu*p0 + I_y*a*b_e*e_c*sqrt(lam_e)*p0 + J_yy*a*b_e*p0*(2*nu - 1)/2 - a*b_e*e_c*p0*(lam_e*y**2 + 2*nu*(b_e**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/(sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(5/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_sigma_zz', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '-a*b_e*e_c**3*p0/(sqrt(a**2 + lam_e)*sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_tau_xy', '(5.31), (5.41)-(5.46)', 'ellipse_stress', 'J_xy*a*b_e*p0*(2*nu - 1)/2 - a*b_e*e_c*lam_e*p0*x*y/((a**2 + lam_e)**(3/2)*(b_e**2 + lam_e)**(3/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_tau_xz', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '-a*b_e*e_c**2*sqrt(lam_e)*p0*x/((a**2 + lam_e)**(3/2)*sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_tau_yz', '(5.31), (5.41)-(5.46)', 'ellipse_stress', '-a*b_e*e_c**2*sqrt(lam_e)*p0*y/(sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(3/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))', ''),
    ('ellipse_stress_w1', '(5.31)', 'ellipse_stress', 'Piecewise((-a**2/2 - b_e**2/2 + x**2/2 + y**2/2 + sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)/2, a**2 + b_e**2 - x**2 - y**2 <= 0), ((-2*a**2*b_e**2 + 2*a**2*y**2 + 2*b_e**2*x**2)/(a**2 + b_e**2 - x**2 - y**2 + sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)), True))', ''),
    ('ellipse_stress_w1_a', '(5.31)', 'ellipse_stress', 'x**2/2 + y**2/2 + (a - b_e)*(a + b_e)/2 + sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)/2', ''),
    ('ellipse_stress_w1_b', '(5.31)', 'ellipse_stress', 'Piecewise((-a**2/2 + b_e**2/2 + x**2/2 + y**2/2 + sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)/2, -a**2 + b_e**2 + x**2 + y**2 >= 0), (2*y**2*(a - b_e)*(a + b_e)/(a**2 - b_e**2 - x**2 - y**2 + sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)), True))', ''),
    ('fit_adhesive_cone_depth', '(5.55), (5.57), adhesive cone, fit model', 'fit', 'pi*a*tan(theta)/2 - sqrt(2)*sqrt(pi)*sqrt(a)*rho_g/sqrt(E_star)', ''),
    ('fit_adhesive_cone_depth_da', '(5.55), (5.57), adhesive cone, fit model', 'fit', 'pi*tan(theta)/2 - sqrt(2)*sqrt(pi)*rho_g/(2*sqrt(E_star)*sqrt(a))', ''),
    ('fit_adhesive_cone_force', '(5.55), (5.57), adhesive cone, fit model', 'fit', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*rho_g + pi*E_star*a**2*tan(theta)/2 + F_0 + s_0*z_p', ''),
    ('fit_adhesive_cone_force_dE', '(5.55), (5.57), adhesive cone, fit model', 'fit', '(pi**2*E_star**(5/2)*a**(5/2)*tan(theta)**2 + 16*pi*E_star**(3/2)*a**(3/2)*rho_g**2 - 5*sqrt(2)*pi**(3/2)*E_star**2*a**2*rho_g*tan(theta))/(2*(pi*E_star**(5/2)*sqrt(a)*tan(theta) - sqrt(2)*sqrt(pi)*E_star**2*rho_g))', ''),
    ('fit_adhesive_cone_force_ddgamma', '(5.55), (5.57), adhesive cone, fit model', 'fit', '4*pi*E_star*a**(3/2)/(sqrt(2)*sqrt(pi)*sqrt(E_star)*rho_g - pi*E_star*sqrt(a)*tan(theta))', ''),
    ('fit_adhesive_cone_force_dz0', '(5.55), (5.57), adhesive cone, fit model', 'fit', '2*(-pi*E_star**(3/2)*a**(3/2)*tan(theta) + 3*sqrt(2)*sqrt(pi)*E_star*a*rho_g)/(pi*sqrt(E_star)*sqrt(a)*tan(theta) - sqrt(2)*sqrt(pi)*rho_g)', ''),
    ('fit_adhesive_powerlaw_depth', '(5.55), (5.57), adhesive power law, fit model', 'fit', 'a**n*c_n*kappa_n - sqrt(2)*sqrt(pi)*sqrt(a)*rho_g/sqrt(E_star)', ''),
    ('fit_adhesive_powerlaw_depth_da', '(5.55), (5.57), adhesive power law, fit model', 'fit', 'a**n*c_n*kappa_n*n/a - sqrt(2)*sqrt(pi)*rho_g/(2*sqrt(E_star)*sqrt(a))', ''),
    ('fit_adhesive_powerlaw_force', '(5.55), (5.57), adhesive power law, fit model', 'fit', 'F_0 + s_0*z_p + 2*(-sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*n*rho_g - sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*rho_g + E_star*a**(n + 1)*c_n*kappa_n*n)/(n + 1)', ''),
    ('fit_adhesive_powerlaw_force_dE', '(5.55), (5.57), adhesive power law, fit model', 'fit', '2*(2*E_star**(5/2)*a**(2*n + 3/2)*c_n**2*kappa_n**2*n**2 + 4*pi*E_star**(3/2)*a**(5/2)*n*rho_g**2 + 4*pi*E_star**(3/2)*a**(5/2)*rho_g**2 - 2*sqrt(2)*sqrt(pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n**2*rho_g - 3*sqrt(2)*sqrt(pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n*rho_g)/((n + 1)*(2*E_star**(5/2)*a**(n + 1/2)*c_n*kappa_n*n - sqrt(2)*sqrt(pi)*E_star**2*a*rho_g))', ''),
    ('fit_adhesive_powerlaw_force_ddgamma', '(5.55), (5.57), adhesive power law, fit model', 'fit', '4*pi*E_star*a**(5/2)/(sqrt(2)*sqrt(pi)*sqrt(E_star)*a*rho_g - 2*E_star*a**(n + 1/2)*c_n*kappa_n*n)', ''),
    ('fit_adhesive_powerlaw_force_dz0', '(5.55), (5.57), adhesive power law, fit model', 'fit', '2*(-2*E_star**(3/2)*a**(n + 3/2)*c_n*kappa_n*n + 3*sqrt(2)*sqrt(pi)*E_star*a**2*rho_g)/(2*sqrt(E_star)*a**(n + 1/2)*c_n*kappa_n*n - sqrt(2)*sqrt(pi)*a*rho_g)', ''),
    ('fit_adhesive_sampled_depth', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', 'g_a - sqrt(2)*sqrt(pi)*sqrt(a)*rho_g/sqrt(E_star)', ''),
    ('fit_adhesive_sampled_depth_da', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', 'g_slope - sqrt(2)*sqrt(pi)*rho_g/(2*sqrt(E_star)*sqrt(a))', ''),
    ('fit_adhesive_sampled_force', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*rho_g + 2*E_star*a*g_a - 2*E_star*g_integral + F_0 + s_0*z_p', ''),
    ('fit_adhesive_sampled_force_dE', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', '2*(2*E_star**(3/2)*a**(3/2)*g_a*g_slope - 2*E_star**(3/2)*sqrt(a)*g_integral*g_slope + 4*pi*sqrt(E_star)*a**(3/2)*rho_g**2 - 2*sqrt(2)*sqrt(pi)*E_star*a**2*g_slope*rho_g - sqrt(2)*sqrt(pi)*E_star*a*g_a*rho_g + sqrt(2)*sqrt(pi)*E_star*g_integral*rho_g)/(2*E_star**(3/2)*sqrt(a)*g_slope - sqrt(2)*sqrt(pi)*E_star*rho_g)', ''),
    ('fit_adhesive_sampled_force_ddgamma', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', '-4*pi*sqrt(E_star)*a**(3/2)/(2*sqrt(E_star)*sqrt(a)*g_slope - sqrt(2)*sqrt(pi)*rho_g)', ''),
    ('fit_adhesive_sampled_force_dz0', '(5.55), (5.57), adhesive MDR of any g, fit model', 'fit', '2*(-2*E_star**(3/2)*a**(3/2)*g_slope + 3*sqrt(2)*sqrt(pi)*E_star*a*rho_g)/(2*sqrt(E_star)*sqrt(a)*g_slope - sqrt(2)*sqrt(pi)*rho_g)', ''),
    ('fit_adhesive_sphere_depth', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', 'a*atanh(a/R) - sqrt(2)*sqrt(pi)*sqrt(a)*rho_g/sqrt(E_star)', ''),
    ('fit_adhesive_sphere_depth_da', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', 'atanh(a/R) + a/(R*(1 - a**2/R**2)) - sqrt(2)*sqrt(pi)*rho_g/(2*sqrt(E_star)*sqrt(a))', ''),
    ('fit_adhesive_sphere_force', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*rho_g + E_star*(R**2*atanh(a/R) - R*a + a**2*atanh(a/R)) + F_0 + s_0*z_p', ''),
    ('fit_adhesive_sphere_force_dE', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', '(2*E_star**(5/2)*R**4*sqrt(a)*atanh(a/R)**2 - 2*E_star**(5/2)*R**2*a**(5/2) + 4*E_star**(5/2)*R*a**(7/2)*atanh(a/R) - 2*E_star**(5/2)*a**(9/2)*atanh(a/R)**2 + 8*pi*E_star**(3/2)*R**2*a**(3/2)*rho_g**2 - 8*pi*E_star**(3/2)*a**(7/2)*rho_g**2 - sqrt(2)*sqrt(pi)*E_star**2*R**4*rho_g*atanh(a/R) + sqrt(2)*sqrt(pi)*E_star**2*R**3*a*rho_g - 4*sqrt(2)*sqrt(pi)*E_star**2*R**2*a**2*rho_g*atanh(a/R) - 5*sqrt(2)*sqrt(pi)*E_star**2*R*a**3*rho_g + 5*sqrt(2)*sqrt(pi)*E_star**2*a**4*rho_g*atanh(a/R))/(2*E_star**(5/2)*R**2*sqrt(a)*atanh(a/R) + 2*E_star**(5/2)*R*a**(3/2) - 2*E_star**(5/2)*a**(5/2)*atanh(a/R) - sqrt(2)*sqrt(pi)*E_star**2*R**2*rho_g + sqrt(2)*sqrt(pi)*E_star**2*a**2*rho_g)', ''),
    ('fit_adhesive_sphere_force_ddgamma', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', '4*pi*E_star*a**(3/2)*(-R**2 + a**2)/(-sqrt(2)*sqrt(pi)*sqrt(E_star)*R**2*rho_g + sqrt(2)*sqrt(pi)*sqrt(E_star)*a**2*rho_g + 2*E_star*R**2*sqrt(a)*atanh(a/R) + 2*E_star*R*a**(3/2) - 2*E_star*a**(5/2)*atanh(a/R))', ''),
    ('fit_adhesive_sphere_force_dz0', '(5.55), (5.57), adhesive exact sphere, fit model', 'fit', '2*(-2*E_star**(3/2)*R**2*a**(3/2)*atanh(a/R) - 2*E_star**(3/2)*R*a**(5/2) + 2*E_star**(3/2)*a**(7/2)*atanh(a/R) + 3*sqrt(2)*sqrt(pi)*E_star*R**2*a*rho_g - 3*sqrt(2)*sqrt(pi)*E_star*a**3*rho_g)/(2*sqrt(E_star)*R**2*sqrt(a)*atanh(a/R) + 2*sqrt(E_star)*R*a**(3/2) - 2*sqrt(E_star)*a**(5/2)*atanh(a/R) - sqrt(2)*sqrt(pi)*R**2*rho_g + sqrt(2)*sqrt(pi)*a**2*rho_g)', ''),
    ('fit_cone_force', '(5.40), fit model', 'fit', '2*E_star*Max(0, -z_0 + z_p)**2/(pi*tan(theta)) + F_0 + s_0*z_p', ''),
    ('fit_cone_force_dE', '(5.40), fit model', 'fit', '2*Max(0, -z_0 + z_p)**2/(pi*tan(theta))', ''),
    ('fit_cone_force_dz0', '(5.40), fit model', 'fit', '-4*E_star*Heaviside(-z_0 + z_p, 0)*Max(0, -z_0 + z_p)/(pi*tan(theta))', ''),
    ('fit_hertz_force', '(5.23), fit model', 'fit', '4*E_star*sqrt(R)*Max(0, -z_0 + z_p)**(3/2)/3 + F_0 + s_0*z_p', ''),
    ('fit_hertz_force_dE', '(5.23), fit model', 'fit', '4*sqrt(R)*Max(0, -z_0 + z_p)**(3/2)/3', ''),
    ('fit_hertz_force_dz0', '(5.23), fit model', 'fit', '-2*E_star*sqrt(R)*Heaviside(-z_0 + z_p, 0)*sqrt(Max(0, -z_0 + z_p))', ''),
    ('fit_jkr_depth', '(5.55), (5.57), JKR, fit model', 'fit', 'a**2/R - sqrt(2)*sqrt(pi)*sqrt(a)*rho_g/sqrt(E_star)', ''),
    ('fit_jkr_depth_da', '(5.55), (5.57), JKR, fit model', 'fit', '2*a/R - sqrt(2)*sqrt(pi)*rho_g/(2*sqrt(E_star)*sqrt(a))', ''),
    ('fit_jkr_force', '(5.55), (5.57), JKR, fit model', 'fit', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*rho_g + 4*E_star*a**3/(3*R) + F_0 + s_0*z_p', ''),
    ('fit_jkr_force_dE', '(5.55), (5.57), JKR, fit model', 'fit', '4*(4*E_star**(5/2)*a**(9/2) + 6*pi*E_star**(3/2)*R**2*a**(3/2)*rho_g**2 - 7*sqrt(2)*sqrt(pi)*E_star**2*R*a**3*rho_g)/(3*R*(4*E_star**(5/2)*a**(3/2) - sqrt(2)*sqrt(pi)*E_star**2*R*rho_g))', ''),
    ('fit_jkr_force_ddgamma', '(5.55), (5.57), JKR, fit model', 'fit', '4*pi*E_star*R*a**(3/2)/(sqrt(2)*sqrt(pi)*sqrt(E_star)*R*rho_g - 4*E_star*a**(3/2))', ''),
    ('fit_jkr_force_dz0', '(5.55), (5.57), JKR, fit model', 'fit', '2*(-4*E_star**(3/2)*a**(5/2) + 3*sqrt(2)*sqrt(pi)*E_star*R*a*rho_g)/(4*sqrt(E_star)*a**(3/2) - sqrt(2)*sqrt(pi)*R*rho_g)', ''),
    ('fit_powerlaw_force', 'Problem 7(d), fit model', 'fit', '2*E_star*n*(Max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*Max(0, -z_0 + z_p)/(n + 1) + F_0 + s_0*z_p', ''),
    ('fit_powerlaw_force_dE', 'Problem 7(d), fit model', 'fit', '2*n*(Max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*Max(0, -z_0 + z_p)/(n + 1)', ''),
    ('fit_powerlaw_force_dz0', 'Problem 7(d), fit model', 'fit', '-2*E_star*(Max(0, -z_0 + z_p)/(c_n*kappa_n))**(1/n)*Heaviside(-z_0 + z_p, 0)', ''),
    ('fit_punch_force', 'Problem 7(a), fit model', 'fit', '2*E_star*a*Max(0, -z_0 + z_p) + F_0 + s_0*z_p', ''),
    ('fit_punch_force_dE', 'Problem 7(a), fit model', 'fit', '2*a*Max(0, -z_0 + z_p)', ''),
    ('fit_punch_force_dz0', 'Problem 7(a), fit model', 'fit', '-2*E_star*a*Heaviside(-z_0 + z_p, 0)', ''),
    ('fit_pyramid_cone_angle', '(5.38), equal area', 'fit', 'atan(sqrt(pi)/(sqrt(n_sides)*tan(alpha_p)*sqrt(tan(pi/n_sides))))', ''),
    ('fit_pyramid_force_cone_angle', '(5.40), equal force', 'fit', 'atan(sqrt(pi)/(beta_p*sqrt(n_sides)*tan(alpha_p)*sqrt(tan(pi/n_sides))))', ''),
    ('fit_sample_modulus', '(5.26), inverted', 'fit', 'E2*E_star*(1 - nu1**2)/(E2 + E_star*nu2**2 - E_star)', ''),
    ('fit_sample_modulus_dE', '(5.26), inverted', 'fit', '-E2**2*nu1**2/(E2 + E_star*nu2**2 - E_star)**2 + E2**2/(E2 + E_star*nu2**2 - E_star)**2', ''),
    ('fit_sample_modulus_rigid', '(5.8), inverted', 'fit', 'E_star*(1 - nu**2)', ''),
    ('fit_sample_modulus_rigid_dE', '(5.8), inverted', 'fit', '1 - nu**2', ''),
    ('fit_sphere_depth', '(5.55)', 'fit', 'a*lam', ''),
    ('fit_sphere_depth_dlam', '(5.55)', 'fit', 'a + lam*(R - a)*(R + a)/R', ''),
    ('fit_sphere_force', '(5.57), fit model', 'fit', 'E_star*Piecewise((R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/(lam**2/15 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam, lam < 1/2), (-R*a + lam*(R**2 + a**2), True)) + F_0 + s_0*z_p', ''),
    ('fit_sphere_force_dE', '(5.57), fit model', 'fit', 'Piecewise((R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/(lam**2/15 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam, lam < 1/2), (-R*a + lam*(R**2 + a**2), True))', ''),
    ('fit_sphere_force_dz0', '(5.55), (5.57), fit model', 'fit', '-2*E_star*a', ''),
    ('fit_sphere_radius_dlam', '(5.55)', 'fit', '(R - a)*(R + a)/R', ''),
    ('flamant_sigma_xx', 'Flamant (2-D Boussinesq)', 'line_stress', '-2*F_L*x**2*z/(pi*(x**2 + z**2)**2)', ''),
    ('flamant_sigma_zz', 'Flamant (2-D Boussinesq)', 'line_stress', '-2*F_L*z**3/(pi*(x**2 + z**2)**2)', ''),
    ('flamant_tau_xz', 'Flamant (2-D Boussinesq)', 'line_stress', '-2*F_L*x*z**2/(pi*(x**2 + z**2)**2)', ''),
    ('flat_punch_tangential_traction', 'MDR tangential, flat punch (not in the chapter)', 'tangential', 'G_star*u_x/(pi*sqrt(a**2 - r**2))', ''),
    ('force_law_cone_exponent', '(5.40), F = K d^n', 'force_law', '2', ''),
    ('force_law_cone_prefactor', '(5.40), F = K d^n', 'force_law', '2*E_star/(pi*tan(theta))', ''),
    ('force_law_cone_stiffness_exponent', '(5.40), differentiated', 'force_law', '1', ''),
    ('force_law_cone_stiffness_prefactor', '(5.40), differentiated', 'force_law', '4*E_star/(pi*tan(theta))', ''),
    ('force_law_ellipse_exponent', '(5.23), exact ellipse, F = K d^n', 'force_law', '3/2', ''),
    ('force_law_ellipse_prefactor', '(5.23), exact ellipse, F = K d^n', 'force_law', '2*sqrt(2)*pi*E_star*sqrt(R1)*sqrt((elliptic_e(1 - t_ba**2) - elliptic_k(1 - t_ba**2))/(t_ba**2 - 1))/(3*elliptic_k(1 - t_ba**2)**(3/2))', ''),
    ('force_law_ellipse_stiffness_exponent', '(5.23), exact ellipse, differentiated', 'force_law', '1/2', ''),
    ('force_law_ellipse_stiffness_prefactor', '(5.23), exact ellipse, differentiated', 'force_law', 'sqrt(2)*pi*E_star*sqrt(R1)*sqrt((elliptic_e(1 - t_ba**2) - elliptic_k(1 - t_ba**2))/(t_ba**2 - 1))/elliptic_k(1 - t_ba**2)**(3/2)', ''),
    ('force_law_hertz_exponent', '(5.23), F = K d^n', 'force_law', '3/2', ''),
    ('force_law_hertz_prefactor', '(5.23), F = K d^n', 'force_law', '4*E_star*sqrt(R)/3', ''),
    ('force_law_hertz_stiffness_exponent', '(5.23), differentiated', 'force_law', '1/2', ''),
    ('force_law_hertz_stiffness_prefactor', '(5.23), differentiated', 'force_law', '2*E_star*sqrt(R)', ''),
    ('force_law_line_exponent', '(5.34), F = K d^n', 'force_law', '1', ''),
    ('force_law_line_prefactor', '(5.34), F = K d^n', 'force_law', 'pi*E_star/4', ''),
    ('force_law_line_stiffness_exponent', '(5.34), differentiated', 'force_law', '0', ''),
    ('force_law_line_stiffness_prefactor', '(5.34), differentiated', 'force_law', 'pi*E_star/4', ''),
    ('force_law_powerlaw_exponent', 'Problem 7(d), F = K d^n', 'force_law', '(n + 1)/n', ''),
    ('force_law_powerlaw_prefactor', 'Problem 7(d), F = K d^n', 'force_law', '2*E_star*n*(1/(c_n*kappa_n))**(1/n)/(n + 1)', ''),
    ('force_law_powerlaw_stiffness_exponent', 'Problem 7(d), differentiated', 'force_law', '1/n', ''),
    ('force_law_powerlaw_stiffness_prefactor', 'Problem 7(d), differentiated', 'force_law', '2*E_star*(1/(c_n*kappa_n))**(1/n)', ''),
    ('force_law_punch_exponent', 'Problem 7(a), F = K d^n', 'force_law', '1', ''),
    ('force_law_punch_prefactor', 'Problem 7(a), F = K d^n', 'force_law', '2*E_star*a', ''),
    ('force_law_punch_stiffness_exponent', 'Problem 7(a), differentiated', 'force_law', '0', ''),
    ('force_law_punch_stiffness_prefactor', 'Problem 7(a), differentiated', 'force_law', '2*E_star*a', ''),
    ('hertz_contact_radius', '(5.21)', 'hertz', 'sqrt(R)*sqrt(d)', ''),
    ('hertz_contact_radius_from_force', '(5.24)', 'hertz', '6**(1/3)*F**(1/3)*R**(1/3)/(2*E_star**(1/3))', ''),
    ('hertz_depth_from_force', '(5.23), inverted', 'hertz', '6**(2/3)*F**(2/3)/(4*E_star**(2/3)*R**(1/3))', ''),
    ('hertz_displacement_inside', '(5.18)', 'hertz', 'd - r**2/(2*R)', ''),
    ('hertz_displacement_outside', 'Fig. 5.2, Problem 7(b)', 'hertz', '(sqrt(R)*sqrt(d)*sqrt(-R*d + r**2) + 2*R*d*asin(sqrt(R)*sqrt(d)/r) - r**2*asin(sqrt(R)*sqrt(d)/r))/(pi*R)', ''),
    ('hertz_displacement_outside_elementary', 'Fig. 5.2, Problem 7(b), a < r < 2a', 'hertz', '2*d*(-sqrt(R)*sqrt(d)*(r**2*(3*R*d/(2*r**2) - 3/2)/(R*d*sqrt(-R*d/r**2 + 1)) + 3*r**3*asin(sqrt(R)*sqrt(d)/r)/(2*R**(3/2)*d**(3/2)))/(3*r) + asin(sqrt(R)*sqrt(d)/r))/pi', ''),
    ('hertz_displacement_outside_series', 'Fig. 5.2, Problem 7(b), r >= 2a', 'hertz', '2*sqrt(R)*d**(3/2)*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(4485482287*R*d/(35459249995776*r**2) + 34461632205/242304874971136)/r**2 + 1472719325/9156870275072)/r**2 + 756261275/4131758538752)/r**2 + 116680311/556198264832)/r**2 + 20036013/82678120448)/r**2 + 3231615/11442061312)/r**2 + 5014575/15082717184)/r**2 + 1300075/3284140032)/r**2 + 676039/1415577600)/r**2 + 88179/150732800)/r**2 + 46189/63307776)/r**2 + 12155/13074432)/r**2 + 6435/5292032)/r**2 + 143/87040)/r**2 + 77/33280)/r**2 + 63/18304)/r**2 + 35/6336)/r**2 + 5/504)/r**2 + 3/140)/r**2 + 1/15)/r**2 + 2/3)/(pi*r)', ''),
    ('hertz_energy', '(5.25)', 'hertz', '8*E_star*sqrt(R)*d**(5/2)/15', ''),
    ('hertz_force', '(5.23)', 'hertz', '4*E_star*sqrt(R)*d**(3/2)/3', ''),
    ('hertz_max_pressure', '(5.22)', 'hertz', '2*E_star*sqrt(d)/(pi*sqrt(R))', ''),
    ('hertz_max_pressure_from_force', '(5.24)', 'hertz', '6**(1/3)*E_star**(2/3)*F**(1/3)/(pi*R**(2/3))', ''),
    ('hertz_mean_pressure', '(5.17)', 'hertz', '4*E_star*sqrt(d)/(3*pi*sqrt(R))', ''),
    ('hertz_pressure', '(5.15)', 'hertz', '2*E_star*sqrt(d)*sqrt(Max(0, 1 - r**2/(R*d)))/(pi*sqrt(R))', ''),
    ('hertz_pressure_displacement', '(5.16)', 'pressures', 'pi*p0*(2*a**2 - r**2)/(4*E_star*a)', ''),
    ('hertz_pressure_displacement_outside', 'Fig. 5.2', 'pressures', 'p0*(2*a**2*asin(a/r) + a*sqrt(-a**2 + r**2) - r**2*asin(a/r))/(2*E_star*a)', ''),
    ('hertz_pressure_force', '(5.17)', 'pressures', '2*pi*a**2*p0/3', ''),
    ('hertz_stiffness', 'Problem 5', 'hertz', '2*E_star*sqrt(R)*sqrt(d)', ''),
    ('impact_contact_time', 'Problem 3', 'impact', '30**(2/5)*sqrt(pi)*m**(2/5)*gamma(2/5)/(5*E_star**(2/5)*R**(1/5)*v0**(1/5)*gamma(9/10))', ''),
    ('impact_contact_time_density', 'Problem 3, m = 4/3 pi R^3 rho', 'impact', '2*2**(1/5)*5**(2/5)*pi**(9/10)*R*rho**(2/5)*gamma(2/5)/(5*E_star**(2/5)*v0**(1/5)*gamma(9/10))', ''),
    ('impact_force_scale', '(5.23), nondimensionalized', 'impact', 'E_star**(2/5)*R**(1/5)*m**(3/5)*v0**(6/5)', ''),
    ('impact_length_scale', '(5.23), nondimensionalized', 'impact', 'm**(2/5)*v0**(4/5)/(E_star**(2/5)*R**(1/5))', ''),
    ('impact_max_contact_radius', 'Problem 4', 'impact', '30**(1/5)*R**(2/5)*m**(1/5)*v0**(2/5)/(2*E_star**(1/5))', ''),
    ('impact_max_contact_radius_density', 'Problem 4, m = 4/3 pi R^3 rho', 'impact', '2**(3/5)*5**(1/5)*pi**(1/5)*R*rho**(1/5)*v0**(2/5)/(2*E_star**(1/5))', ''),
    ('impact_max_depth', 'Problem 3', 'impact', '30**(2/5)*m**(2/5)*v0**(4/5)/(4*E_star**(2/5)*R**(1/5))', ''),
    ('impact_max_depth_density', 'Problem 3, m = 4/3 pi R^3 rho', 'impact', '2**(1/5)*5**(2/5)*pi**(2/5)*R*rho**(2/5)*v0**(4/5)/(2*E_star**(2/5))', ''),
    ('impact_max_force', 'Problem 4', 'impact', '30**(3/5)*E_star**(2/5)*R**(1/5)*m**(3/5)*v0**(6/5)/6', ''),
    ('impact_max_force_density', 'Problem 4, m = 4/3 pi R^3 rho', 'impact', '2**(4/5)*5**(3/5)*pi**(3/5)*E_star**(2/5)*R**2*rho**(3/5)*v0**(6/5)/3', ''),
    ('impact_max_pressure', 'Problem 4', 'impact', '30**(1/5)*E_star**(4/5)*m**(1/5)*v0**(2/5)/(pi*R**(3/5))', ''),
    ('impact_max_pressure_density', 'Problem 4', 'impact', '2**(3/5)*5**(1/5)*E_star**(4/5)*rho**(1/5)*v0**(2/5)/pi**(4/5)', ''),
    ('impact_sphere_mass', 'Problem 4, m = 4/3 pi R^3 rho', 'impact', '4*pi*R**3*rho/3', ''),
    ('impact_time_scale', '(5.23), nondimensionalized', 'impact', 'm**(2/5)/(E_star**(2/5)*R**(1/5)*v0**(1/5))', ''),
    ('jkr_contact_radius_from_force', '(5.57), JKR, inverted', 'adhesion', '(sqrt(3)*sqrt(R)*sqrt(2*F_load + 3*pi*R*dgamma) + 3*sqrt(pi)*R*sqrt(dgamma))**(2/3)/(2*E_star**(1/3))', ''),
    ('jkr_depth', '(5.55), JKR', 'adhesion', 'a**2/R - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)', ''),
    ('jkr_force_from_radius', '(5.57), JKR', 'adhesion', '-2*sqrt(2)*sqrt(pi)*sqrt(E_star)*a**(3/2)*sqrt(dgamma) + 4*E_star*a**3/(3*R)', ''),
    ('jkr_pressure', '(5.59), JKR', 'adhesion', '(-sqrt(2)*pi*sqrt(E_star)*R*sqrt(a)*sqrt(dgamma) + 2*sqrt(pi)*E_star*(a**2 - r**2))/(pi**(3/2)*R*sqrt(a**2 - r**2))', ''),
    ('jkr_pull_off_depth_dc', '(5.55), adhesive', 'adhesion', '-3*pi**(2/3)*R**(1/3)*dgamma**(2/3)/(4*E_star**(2/3))', ''),
    ('jkr_pull_off_depth_fc', '(5.55), adhesive', 'adhesion', '-3**(1/3)*pi**(2/3)*R**(1/3)*dgamma**(2/3)/(4*E_star**(2/3))', ''),
    ('jkr_pull_off_force_dc', '(5.57), adhesive', 'adhesion', '-5*pi*R*dgamma/6', ''),
    ('jkr_pull_off_force_fc', '(5.57), adhesive', 'adhesion', '-3*pi*R*dgamma/2', ''),
    ('jkr_pull_off_radius_dc', '(5.57), adhesive', 'adhesion', 'pi**(1/3)*R**(2/3)*dgamma**(1/3)/(2*E_star**(1/3))', ''),
    ('jkr_pull_off_radius_fc', '(5.57), adhesive', 'adhesion', '3**(2/3)*pi**(1/3)*R**(2/3)*dgamma**(1/3)/(2*E_star**(1/3))', ''),
    ('jkr_zero_load_radius', '(5.57), adhesive', 'adhesion', '6**(2/3)*pi**(1/3)*R**(2/3)*dgamma**(1/3)/(2*E_star**(1/3))', ''),
    ('line_depth_from_force', '(5.34), inverted', 'line', '4*F/(pi*E_star*L)', ''),
    ('line_force', '(5.34)', 'line', 'pi*E_star*L*d/4', ''),
    ('line_force_per_length_from_half_width', '(5.34), from the matching', 'line', 'pi*E_star*a**2/(4*R)', ''),
    ('line_half_width', '(5.35)', 'line', 'sqrt(R)*sqrt(d)', ''),
    ('line_half_width_from_force', '(5.34), (5.35)', 'line', '2*sqrt(F)*sqrt(R)/(sqrt(pi)*sqrt(E_star)*sqrt(L))', ''),
    ('line_max_pressure', '(5.37), second form', 'line', 'E_star*sqrt(d)/(2*sqrt(R))', ''),
    ('line_max_pressure_depth_width', '(5.37), first form', 'line', 'E_star*d/(2*a)', ''),
    ('line_max_pressure_from_force', '(5.37), third form', 'line', 'sqrt(E_star)*sqrt(F)/(sqrt(pi)*sqrt(L)*sqrt(R))', 'a factor pi is missing under the root: p0 = (E* F/(pi L R))^(1/2) (from p0 = E* a/(2R) and F/L = pi a p0/2; the print is sqrt(pi) = 1.77 times too large)'),
    ('line_max_pressure_from_half_width', '(5.37), from the matching', 'line', 'E_star*a/(2*R)', ''),
    ('line_pressure', '(5.36)', 'line', 'E_star*sqrt(d)*sqrt(Max(0, 1 - x**2/(R*d)))/(2*sqrt(R))', ''),
    ('line_stiffness', '(5.34), differentiated', 'line', 'pi*E_star*L/4', ''),
    ('line_stress_axis_max_shear', '(5.36), Flamant', 'line_stress', 'a*p0*z/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2)))', ''),
    ('line_stress_axis_max_shear_slope', '(5.36), Flamant', 'line_stress', '-a*p0*z**2/((a**2 + z**2)**(3/2)*(z + sqrt(a**2 + z**2))) + a*p0*z*(-z/sqrt(a**2 + z**2) - 1)/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) + a*p0/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2)))', ''),
    ('line_stress_axis_sigma_xx', '(5.36), Flamant', 'line_stress', 'p0*(2*a**2*z - a**2*sqrt(a**2 + z**2) + 2*z**3 - 2*z**2*sqrt(a**2 + z**2))/(a*(a**2 + z**2))', ''),
    ('line_stress_axis_sigma_zz', '(5.36), Flamant', 'line_stress', '-a*p0/sqrt(a**2 + z**2)', ''),
    ('line_stress_axis_von_mises', '(5.50), (5.36)', 'line_stress', 'sqrt(a**6*p0**2/((a**2 + z**2)*(z + sqrt(a**2 + z**2))**4) - a**4*p0**2/((a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) + a**3*nu*p0*(-a**3*p0/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) - a*p0/sqrt(a**2 + z**2))/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) + a**2*p0**2/(a**2 + z**2) + a*nu*p0*(-a**3*p0/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) - a*p0/sqrt(a**2 + z**2))/sqrt(a**2 + z**2) + nu**2*(-a**3*p0/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) - a*p0/sqrt(a**2 + z**2))**2)', ''),
    ('line_stress_axis_von_mises_slope', '(5.50), (5.36)', 'line_stress', '(-3*a**2*p0**2*z**3/((a**2 + z**2)**2*(z + sqrt(a**2 + z**2))**2) + 3*a**2*p0**2*z**2*(-2*z/sqrt(a**2 + z**2) - 2)/(2*(a**2 + z**2)*(z + sqrt(a**2 + z**2))**3) + 3*a**2*p0**2*z/((a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-a**3*p0/(2*sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) - a*p0/(2*sqrt(a**2 + z**2)))*(a**3*p0*z/((a**2 + z**2)**(3/2)*(z + sqrt(a**2 + z**2))**2) - a**3*p0*(-2*z/sqrt(a**2 + z**2) - 2)/(sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**3) + a*p0*z/(a**2 + z**2)**(3/2))/2)/sqrt(3*a**2*p0**2*z**2/((a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-a**3*p0/(2*sqrt(a**2 + z**2)*(z + sqrt(a**2 + z**2))**2) - a*p0/(2*sqrt(a**2 + z**2)))**2)', ''),
    ('line_stress_principal_max', 'plane stress state x-z', 'line_stress', 'sigma_xx/2 + sigma_zz/2 + sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)/2', ''),
    ('line_stress_principal_min', 'plane stress state x-z', 'line_stress', 'sigma_xx/2 + sigma_zz/2 - sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)/2', ''),
    ('line_stress_principal_shear', 'plane stress state x-z', 'line_stress', 'sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)/2', ''),
    ('line_stress_sigma_xx_core', '(5.36), Flamant', 'line_stress', '-p0*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (a - x)*(a + x))*(2*x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (a - x)*(a + x))*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/(z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)))/(a*(z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_sigma_xx_deep', '(5.36), Flamant', 'line_stress', '-2*a*p0*z**2*(2*a**2*z**2*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/((z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) + 2*x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))/((z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_sigma_xx_side', '(5.36), Flamant', 'line_stress', '-2*a*p0*z**2*(2*a**2*x*z**3/((x*z/sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z)*sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) - z**2 - (a - x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((x*z/sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z)*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) - z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_sigma_yy', 'plane strain', 'line_stress', 'nu*(sigma_xx + sigma_zz)', ''),
    ('line_stress_sigma_zz_core', '(5.36), Flamant', 'line_stress', '-p0*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (a - x)*(a + x))*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/(a*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_sigma_zz_deep', '(5.36), Flamant', 'line_stress', '-2*a*p0*z**2*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/((z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_sigma_zz_side', '(5.36), Flamant', 'line_stress', '-2*a*p0*x*z**3/(sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) - z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_1_core', '(5.36), Flamant', 'line_stress', 'p0*sqrt(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2)*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (a - x)*(a + x))/(a*(z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))*sqrt(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_1_deep', '(5.36), Flamant', 'line_stress', '2*a*p0*z**2*sqrt(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2)/((z + sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*sqrt(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_1_side', '(5.36), Flamant', 'line_stress', '2*a*p0*z**2*sqrt(z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/((x*z/sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z)*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*sqrt(x**2*z**2/(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) - z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_xz_core', '(5.36), Flamant', 'line_stress', '-p0*x*z*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + (a - x)*(a + x))/(a*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_xz_deep', '(5.36), Flamant', 'line_stress', '-2*a*p0*x*z**3/(sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_xz_side', '(5.36), Flamant', 'line_stress', '-2*a*p0*z**2*sqrt(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/((z**2 + (-a + x)*(a + x) + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) - z**2/2 - (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))', ''),
    ('line_stress_tau_xz_slope_x', '(5.36), Flamant', 'line_stress', '-a*p0*z*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(-3*x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)**3', ''),
    ('line_stress_tau_xz_slope_z', '(5.36), Flamant', 'line_stress', '(pi*a*p0*x*z**2*(-x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + 3*z**2/2 + 3*(a - x)*(a + x)/2 + 3*sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)/(sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)**3) - pi*p0*(-x*z**2/sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + x*sqrt(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2))/(a*(x**2*z**2/(z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2) + z**2/2 + (a - x)*(a + x)/2 + sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)/2)))/pi', ''),
    ('line_stress_von_mises', '(5.50), plane strain', 'line_stress', 'sqrt(nu**2*(sigma_xx + sigma_zz)**2 - nu*sigma_xx*(sigma_xx + sigma_zz) - nu*sigma_zz*(sigma_xx + sigma_zz) + sigma_xx**2 - sigma_xx*sigma_zz + sigma_zz**2 + 3*tau_xz**2)', ''),
    ('line_stress_von_mises_c_tau', '(5.50), plane strain', 'line_stress', 'sqrt(c_mean**2*(1 - 2*nu)**2 + 3*tau_1**2)', ''),
    ('masing_unloading_force', "Masing's rule, derived from the springs", 'tangential', 'F_amp - 2*F_half', ''),
    ('mdr_depth_of_line_load', '(5.58), inverted', 'tangential', 'g_x + q_z/E_star', ''),
    ('mdr_force', '(5.57)', 'numerical_mdr', '2*E_star*(a*d - g_integral)', ''),
    ('mdr_kink_G', '(5.57)', 'kink', '2*b*slope_jump*x*acosh(sqrt(2)*sqrt(b + x)/(2*sqrt(b))) - b*slope_jump*sqrt(-b + x)*sqrt(b + x)', ''),
    ('mdr_kink_g', '(5.52)', 'kink', '2*b*slope_jump*acosh(sqrt(2)*sqrt(b + x)/(2*sqrt(b)))', ''),
    ('mdr_kink_gprime', '(5.52)', 'kink', 'b*slope_jump/(sqrt(-b + x)*sqrt(b + x))', ''),
    ('mdr_kink_pressure', '(5.59)', 'kink', 'E_star*b*slope_jump*elliptic_f(atan2(sqrt(Max(0, (a - Max(b, r))*(a + Max(b, r)))), sqrt(Max(b, r) - Min(b, r))*sqrt(Max(b, r) + Min(b, r))), Min(b, r)**2/Max(b, r)**2)/(pi*Max(b, r))', ''),
    ('mdr_normal_line_load', '(5.58)', 'tangential', 'E_star*(d - g_x)', ''),
    ('mdr_stiffness', '(5.12), Problem 5', 'contact', '2*E_star*a', ''),
    ('mdr_tangential_line_load', 'MDR tangential springs (not in the chapter)', 'tangential', 'G_star*w_x', ''),
    ('mdr_tangential_spring_shear', 'MDR tangential springs (not in the chapter)', 'tangential', 'q_x/G_star', ''),
    ('mindlin_energy', 'Mindlin-Deresiewicz (not in the chapter)', 'tangential', '3*(-6*F**(4/3)*mu_f**(4/3)*(F*mu_f - F_amp)**(2/3) + F**(1/3)*F_amp*mu_f**(1/3)*(F*mu_f - F_amp)**(2/3) + 6*F**2*mu_f**2 - 5*F*F_amp*mu_f)/(5*G_star*a)', ''),
    ('mindlin_energy_small', 'Mindlin-Deresiewicz (not in the chapter)', 'tangential', 'F_amp**3/(9*F*G_star*a*mu_f)', ''),
    ('paraboloid_g', '(5.52) of f = r^2/(2R)', 'tangential', 'x**2/R', ''),
    ('paraboloid_profile', '(5.52)', 'tangential', 'r**2/(2*R)', ''),
    ('powerlaw_contact_radius', 'Problem 7(d)', 'powerlaw', '(d/(c_n*kappa_n))**(1/n)', ''),
    ('powerlaw_depth_from_force', 'Problem 7(d), inverted', 'powerlaw', '(F*(c_n*kappa_n)**(1/n)*(n + 1)/(2*E_star*n))**(n/(n + 1))', ''),
    ('powerlaw_displacement_far', 'Problem 7(d), (5.60), r >> a', 'powerlaw', '2*a*d*n*(a**2*(a**2*(a**2*(5*n + 5)/(r**2*(112*n + 784)) + (3*n + 3)/(40*n + 200))/r**2 + (n + 1)/(6*n + 18))/r**2 + 1)/(pi*r*(n + 1))', ''),
    ('powerlaw_displacement_outside', 'Problem 7(d), (5.60)', 'powerlaw', '2*d*(-a*hyper((1/2, n/2 + 1/2), (n/2 + 3/2,), a**2/r**2)/r + (n + 1)*asin(a/r))/(pi*(n + 1))', ''),
    ('powerlaw_displacement_outside_integrand', 'Problem 7(d), (5.60)', 'powerlaw', '(-2*d*(-r*sin(w_out - asin(a/r))/a)**n + 2*d)/pi', ''),
    ('powerlaw_force', 'Problem 7(d)', 'powerlaw', '2*E_star*d*n*(d/(c_n*kappa_n))**(1/n)/(n + 1)', 'the factor (kappa_n c_n)^(1/n) must be (kappa_n c_n)^(-1/n): with a = (d/(kappa_n c_n))^(1/n), (5.57) gives F = 2n/(n+1) E* a d; for n = 2 (kappa_2 c_2 = 1/R) only the corrected form reproduces (5.23)'),
    ('powerlaw_force_from_radius', 'Problem 7(d), (5.57)', 'powerlaw', '2*E_star*a*d*n/(n + 1)', ''),
    ('powerlaw_g', 'Problem 7(d)', 'powerlaw', 'c_n*kappa_n*x**n', ''),
    ('powerlaw_kappa', 'Problem 7(d)', 'powerlaw', 'sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2)', ''),
    ('powerlaw_kappa_asymptotic', 'Problem 7(d), large n', 'powerlaw', 'sqrt(2)*sqrt(pi)*sqrt(n)*exp(2*(4*(4*(4*(31/(4608*n**2.0) - 17/14336)/n**2.0 + 1/640)/n**2.0 - 1/192)/n**2.0 + 1/8)/n**1.0)/2', ''),
    ('powerlaw_mean_pressure', 'Fig. 5.17', 'powerlaw', '2*E_star*d*n/(pi*a*(n + 1))', ''),
    ('powerlaw_mean_pressure_from_depth', 'Fig. 5.17', 'powerlaw', '2*E_star*d*n*(c_n*kappa_n/d)**(1/n)/(pi*(n + 1))', ''),
    ('powerlaw_pressure', 'Problem 7(d), (5.59)', 'powerlaw', 'E_star*d*n*hyper((1, 1 - n/2), (3/2,), Max(0, (a - r)*(a + r))/a**2)*sqrt(Max(0, (a - r)*(a + r)))/(pi*a**2)', ''),
    ('powerlaw_pressure_centre', 'Problem 7(d), (5.59), r << a', 'powerlaw', 'E_star*d*n*(sqrt(pi)*(r/a)**(n - 1)*gamma(1/2 - n/2)/(2*gamma(1 - n/2)) + 1/(n - 1) + r**2*(1/(2*n - 6) + r**2*(3/(8*n - 40) + r**2*(5/(16*n - 112) + r**2*(35/(128*n - 1152) + r**2*(63/(256*n - 2816) + r**2*(231/(1024*n - 13312) + r**2*(429/(2048*n - 30720) + r**2*(6435/(32768*n - 557056) + 12155*r**2/(a**2*(65536*n - 1245184)))/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/(pi*a)', ''),
    ('powerlaw_pressure_integrand', 'Problem 7(d), (5.59)', 'powerlaw', 'E_star*d*n*sqrt(a**2 - r**2)*(r**2 + (1 - w_quad)**2*(a**2 - r**2))**(n/2 - 1)/(pi*a**n)', ''),
    ('powerlaw_pressure_n1', 'Problem 7(d), n = 1', 'powerlaw', 'E_star*d*log((a + sqrt(a**2 - r**2))/r)/(pi*a)', ''),
    ('powerlaw_pressure_n2', 'Problem 7(d), n = 2', 'powerlaw', '2*E_star*d*sqrt(a**2 - r**2)/(pi*a**2)', ''),
    ('powerlaw_pressure_n3', 'Problem 7(d), n = 3', 'powerlaw', '3*E_star*d*(a*sqrt(a**2 - r**2) - r**2*log(r) + r**2*log(a + sqrt(a**2 - r**2)))/(2*pi*a**3)', ''),
    ('powerlaw_pressure_n4', 'Problem 7(d), n = 4', 'powerlaw', '4*E_star*d*sqrt(a**2 - r**2)*(a**2 + 2*r**2)/(3*pi*a**4)', ''),
    ('powerlaw_pressure_normalized', 'Fig. 5.17', 'powerlaw', '(n + 1)*hyper((1, 1 - n/2), (3/2,), Max(0, (1 - r_tilde)*(r_tilde + 1)))*sqrt(Max(0, (1 - r_tilde)*(r_tilde + 1)))/2', ''),
    ('powerlaw_pressure_small_n', 'Problem 7(d), (5.59)', 'powerlaw', 'E_star*d*n*r**(n - 1)*hyper((1/2, n/2 + 1/2), (3/2,), Max(0, (a - r)*(a + r))/a**2)*sqrt(Max(0, (a - r)*(a + r)))/(pi*a*a**n)', ''),
    ('powerlaw_profile', 'Problem 7(d)', 'powerlaw', 'c_n*r**n', ''),
    ('powerlaw_punch_displacement_outside', 'Problem 7(a)', 'powerlaw', '2*d*asin(a/r)/pi', ''),
    ('powerlaw_punch_force', 'Problem 7(a)', 'powerlaw', '2*E_star*a*d', ''),
    ('powerlaw_punch_mean_pressure', 'Problem 7(a)', 'powerlaw', '2*E_star*d/(pi*a)', ''),
    ('powerlaw_punch_pressure', 'Problem 7(a)', 'powerlaw', 'E_star*d/(pi*sqrt(a**2 - r**2))', ''),
    ('punch_depth_from_force', '(5.11), inverted', 'contact', 'F/(2*E_star*a)', ''),
    ('punch_pressure_displacement', '(5.10)', 'pressures', 'pi*a*p0/E_star', ''),
    ('punch_pressure_displacement_outside', 'Fig. 5.2 (n = -1/2), Problem 7(a)', 'pressures', '2*a*p0*asin(a/r)/E_star', ''),
    ('punch_pressure_force', '(5.11)', 'pressures', '2*pi*a**2*p0', ''),
    ('punch_stiffness', '(5.12)', 'pressures', '2*E_star*a', ''),
    ('shear_modulus', "Lame's mu (not in the chapter)", 'tangential', 'E/(2*nu + 2)', ''),
    ('sphere_depth', "(5.55), Sneddon's sphere", 'sphere', 'a*atanh(a/R)', ''),
    ('sphere_force_from_radius', "(5.57), Sneddon's sphere", 'sphere', 'E_star*(R**2*atanh(a/R) - R*a + a**2*atanh(a/R))', ''),
    ('sphere_g', "(5.52), Sneddon's sphere", 'sphere', 'x*atanh(x/R)', ''),
    ('sphere_lam_contact_radius', "(5.55), Sneddon's sphere", 'sphere', 'R*tanh(lam)', ''),
    ('sphere_lam_depth', "(5.55), Sneddon's sphere", 'sphere', 'R*lam*tanh(lam)', ''),
    ('sphere_lam_force', "(5.57), Sneddon's sphere", 'sphere', 'E_star*R**2*(lam*tanh(lam)**2 + lam - tanh(lam))', ''),
    ('sphere_lam_pressure_pole', "(5.59), Sneddon's sphere", 'sphere', 'E_star*R*atanh(sqrt(R**2*tanh(lam)**2 - r**2)/sqrt(R**2 - r**2))/(pi*sqrt(R**2 - r**2))', ''),
    ('sphere_pressure_atanh_kernel', "(5.59), Sneddon's sphere", 'sphere', 'E_star*atanh(x/R)/(pi*x)', ''),
    ('sphere_profile', "(5.52), Sneddon's sphere", 'sphere', 'R - sqrt(R**2 - r**2)', ''),
    ('sphere_stiffness', "Problem 5, Sneddon's sphere", 'sphere', '2*E_star*a', ''),
    ('stress_axis_max_shear', 'Fig. 5.8', 'stress', 'p0*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*atan(a/z))/(4*a*(a**2 + z**2))', ''),
    ('stress_axis_max_shear_bracket', 'Fig. 5.8', 'stress', 'pi*a*(nu + 1)/(8*nu + 20)', ''),
    ('stress_axis_max_shear_slope', 'Fig. 5.8', 'stress', '-p0*z*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*atan(a/z))/(2*a*(a**2 + z**2)**2) + p0*(-4*a*z*(nu + 1) - 2*a*(a**2 + z**2)*(nu + 1)/(z*(a**2/z**2 + 1)) + 4*z**2*(nu + 1)*atan(a/z) + 2*(a**2 + z**2)*(nu + 1)*atan(a/z))/(4*a*(a**2 + z**2))', ''),
    ('stress_axis_sigma_xx', '(5.49)', 'stress', 'p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*atan(a/z))/(2*a*(a**2 + z**2))', ''),
    ('stress_axis_sigma_xx_deep', '(5.49)', 'stress', 'p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*atan(a/z))/(2*a*(a**2 + z**2))', ''),
    ('stress_axis_sigma_zz', '(5.48)', 'stress', '-a**2*p0/(a**2 + z**2)', ''),
    ('stress_hertz_max_orthogonal_shear', 'Fig. 5.9', 'stress', 'p0*sqrt(1 + sqrt(17))*(-7*sqrt(34) + 31*sqrt(2))/32', ''),
    ('stress_hertz_max_orthogonal_shear_r', 'Fig. 5.9', 'stress', 'a*sqrt(7/4 - sqrt(17)/4)', ''),
    ('stress_hertz_max_orthogonal_shear_z', 'Fig. 5.9', 'stress', 'a*sqrt(-4 + sqrt(17))', ''),
    ('stress_hertz_sigma_rr', 'Fig. 5.9', 'stress', 'p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*(-atan(xi) + pi/2) + 1 - 1/(3*(xi**2 + 1))) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))', ''),
    ('stress_hertz_sigma_rr_far', 'Fig. 5.9', 'stress', 'p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*atan(1/xi) + 1 - 1/(3*(xi**2 + 1))) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))', ''),
    ('stress_hertz_sigma_tt', 'Fig. 5.9', 'stress', 'p0*(-eta*(nu + 1)*(-xi*(-atan(xi) + pi/2) + 1 - 1/(3*(xi**2 + 1))) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))', ''),
    ('stress_hertz_sigma_tt_far', 'Fig. 5.9', 'stress', 'p0*(-eta*(nu + 1)*(-xi*atan(1/xi) + 1 - 1/(3*(xi**2 + 1))) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))', ''),
    ('stress_hertz_sigma_zz', 'Fig. 5.9', 'stress', '-eta**3*p0/(eta**2 + xi**2)', ''),
    ('stress_hertz_tau_rz', 'Fig. 5.9', 'stress', '-chi*eta**2*p0*xi/((eta**2 + xi**2)*sqrt(xi**2 + 1))', ''),
    ('stress_spheroidal_cos_beta_inside', 'Johnson (1985), (3.44)', 'stress', 'sqrt(-z**2/2 - (-a + r)*(a + r)/2 + sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2)/2)/a', ''),
    ('stress_spheroidal_u', 'Johnson (1985), (3.44)', 'stress', '-a**2/2 + r**2/2 + z**2/2 + sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)/2', ''),
    ('stress_spheroidal_u_inside', 'Johnson (1985), (3.44)', 'stress', '-a**2/2 + r**2/2 + z**2/2 + sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)/2', ''),
    ('stress_von_mises', '(5.50)', 'stress', 'sqrt(sigma_xx**2 - sigma_xx*sigma_yy - sigma_xx*sigma_zz + sigma_yy**2 - sigma_yy*sigma_zz + sigma_zz**2 + 3*tau_xy**2 + 3*tau_xz**2 + 3*tau_yz**2)', ''),
    ('strip_mean_pressure', '(5.34)-(5.37)', 'contact', 'F/(2*L*a)', ''),
    ('tangential_cone_displacement', 'MDR tangential, cone (not in the chapter)', 'tangential', '(-sqrt(F)*sqrt(mu_f)*sqrt(F*mu_f - F_x) + F*mu_f)/(G_star*a)', ''),
    ('tangential_cone_energy', 'MDR tangential, cone (not in the chapter)', 'tangential', '4*sqrt(F)*sqrt(mu_f)*(sqrt(F)*sqrt(mu_f) - sqrt(F*mu_f - F_amp))**3/(3*G_star*a)', ''),
    ('tangential_cone_force', 'MDR tangential, cone (not in the chapter)', 'tangential', '2*G_star*u_x*(pi*E_star*a*mu_f - G_star*u_x/tan(theta))/(pi*E_star*mu_f)', ''),
    ('tangential_cone_stick_radius', 'MDR tangential, cone (not in the chapter)', 'tangential', 'a - 2*G_star*u_x/(pi*E_star*mu_f*tan(theta))', ''),
    ('tangential_cone_traction_stick', 'MDR tangential, cone (not in the chapter)', 'tangential', 'mu_f*(E_star*log((a + sqrt(a**2 - r**2))/r)*tan(theta)/2 - E_star*log((c + sqrt(c**2 - r**2))/r)*tan(theta)/2)', ''),
    ('tangential_modulus', 'MDR tangential springs (not in the chapter)', 'tangential', '-4*G1*G2/(G1*(nu2 - 2) + G2*(nu1 - 2))', ''),
    ('tangential_powerlaw_displacement', 'MDR tangential, power law (not in the chapter)', 'tangential', 'F*mu_f*(1 - (1 - F_x/(F*mu_f))**(n/(n + 1)))*(n + 1)/(2*G_star*a*n)', ''),
    ('tangential_powerlaw_energy', 'MDR tangential, power law (not in the chapter)', 'tangential', '2*F**2*mu_f**2*(-2*c_a**n*n**2 - 3*c_a**n*n - c_a**n + 2*c_a**(n + 1)*n**2 + 3*c_a**(n + 1)*n + c_a**(n + 1) - c_a**(2*n + 1)*n - c_a**(2*n + 1) + n + 1)/(G_star*a*n*(2*n + 1))', ''),
    ('tangential_powerlaw_energy_density', 'MDR tangential, power law (not in the chapter)', 'tangential', '-(1 - d_c)**n*expm1(n*log1p(-d_c*(1 - s_x)))*expm1(n*log1p(d_c*s_x/(1 - d_c)))', ''),
    ('tangential_powerlaw_energy_scale', 'MDR tangential, power law (not in the chapter)', 'tangential', '2*F**2*mu_f**2*(n + 1)**2/(G_star*a*n**2)', ''),
    ('tangential_powerlaw_energy_small', 'MDR tangential, power law (not in the chapter)', 'tangential', 'F_amp**3/(3*F*G_star*a*mu_f*(n + 1))', ''),
    ('tangential_powerlaw_force', 'MDR tangential, power law (not in the chapter)', 'tangential', '2*E_star*a**(n + 1)*c_n*kappa_n*mu_f*n*(1 - (1 - G_star*u_x/(E_star*a**n*c_n*kappa_n*mu_f))**((n + 1)/n))/(n + 1)', ''),
    ('tangential_powerlaw_stick_deficit', 'MDR tangential, power law (not in the chapter)', 'tangential', '1 - (1 - F_amp/(F*mu_f))**(1/(n + 1))', ''),
    ('tangential_powerlaw_stick_radius', 'MDR tangential, power law (not in the chapter)', 'tangential', 'a*(1 - G_star*u_x/(E_star*a**n*c_n*kappa_n*mu_f))**(1/n)', ''),
    ('tangential_powerlaw_stick_radius_from_force', 'MDR tangential, power law (not in the chapter)', 'tangential', 'a*(1 - F_x/(F*mu_f))**(1/(n + 1))', ''),
    ('tangential_powerlaw_traction_stick_centre', 'MDR tangential, power law (not in the chapter), (5.59)', 'tangential', 'E_star*c**(n - 1)*c_n*kappa_n*mu_f*n*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(121683714103007*r_c**2*expm1((n - 55)*log1p((a - c)/c))/(1125899906842624*(n - 55)) + 61989816618513*expm1((n - 53)*log1p((a - c)/c))/(562949953421312*(n - 53))) + 15801325804719*expm1((n - 51)*log1p((a - c)/c))/(140737488355328*(n - 51))) + 8061900920775*expm1((n - 49)*log1p((a - c)/c))/(70368744177664*(n - 49))) + 514589420475*expm1((n - 47)*log1p((a - c)/c))/(4398046511104*(n - 47))) + 263012370465*expm1((n - 45)*log1p((a - c)/c))/(2199023255552*(n - 45))) + 67282234305*expm1((n - 43)*log1p((a - c)/c))/(549755813888*(n - 43))) + 34461632205*expm1((n - 41)*log1p((a - c)/c))/(274877906944*(n - 41))) + 4418157975*expm1((n - 39)*log1p((a - c)/c))/(34359738368*(n - 39))) + 2268783825*expm1((n - 37)*log1p((a - c)/c))/(17179869184*(n - 37))) + 583401555*expm1((n - 35)*log1p((a - c)/c))/(4294967296*(n - 35))) + 300540195*expm1((n - 33)*log1p((a - c)/c))/(2147483648*(n - 33))) + 9694845*expm1((n - 31)*log1p((a - c)/c))/(67108864*(n - 31))) + 5014575*expm1((n - 29)*log1p((a - c)/c))/(33554432*(n - 29))) + 1300075*expm1((n - 27)*log1p((a - c)/c))/(8388608*(n - 27))) + 676039*expm1((n - 25)*log1p((a - c)/c))/(4194304*(n - 25))) + 88179*expm1((n - 23)*log1p((a - c)/c))/(524288*(n - 23))) + 46189*expm1((n - 21)*log1p((a - c)/c))/(262144*(n - 21))) + 12155*expm1((n - 19)*log1p((a - c)/c))/(65536*(n - 19))) + 6435*expm1((n - 17)*log1p((a - c)/c))/(32768*(n - 17))) + 429*expm1((n - 15)*log1p((a - c)/c))/(2048*(n - 15))) + 231*expm1((n - 13)*log1p((a - c)/c))/(1024*(n - 13))) + 63*expm1((n - 11)*log1p((a - c)/c))/(256*(n - 11))) + 35*expm1((n - 9)*log1p((a - c)/c))/(128*(n - 9))) + 5*expm1((n - 7)*log1p((a - c)/c))/(16*(n - 7))) + 3*expm1((n - 5)*log1p((a - c)/c))/(8*(n - 5))) + expm1((n - 3)*log1p((a - c)/c))/(2*(n - 3))) + expm1((n - 1)*log1p((a - c)/c))/(n - 1))/pi', ''),
    ('tangential_powerlaw_traction_stick_integrand', 'MDR tangential, power law (not in the chapter), (5.59)', 'tangential', 'E_star*c_n*kappa_n*mu_f*n*(r**2 + s_r**2)**(n/2 - 1)/pi', ''),
    ('tangential_slide_onset', 'MDR tangential springs (not in the chapter)', 'tangential', 'E_star*d*mu_f/G_star', ''),
    ('tangential_stiffness', 'MDR tangential springs (not in the chapter)', 'tangential', '2*G_star*a', ''),
    ('tangential_stiffness_ratio', 'MDR tangential springs (not in the chapter)', 'tangential', '2*(nu - 1)/(nu - 2)', ''),
    ('tangential_traction_slip', 'MDR tangential (Ciavarella-Jaeger, found)', 'tangential', 'mu_f*p_a', ''),
    ('tangential_traction_stick', 'MDR tangential (Ciavarella-Jaeger, found)', 'tangential', 'mu_f*(p_a - p_c)', ''),
    ('uniform_pressure_displacement', 'Problem 6', 'pressures', '4*a*p0*elliptic_e(r**2/a**2)/(pi*E_star)', ''),
    ('uniform_pressure_displacement_centre', 'Problem 6', 'pressures', '2*a*p0/E_star', ''),
    ('uniform_pressure_displacement_edge', 'Problem 6', 'pressures', '4*a*p0/(pi*E_star)', ''),
    ('uniform_pressure_displacement_outside', 'Problem 6 (outside the disc)', 'pressures', '4*p0*r*((a**2/r**2 - 1)*elliptic_k(a**2/r**2) + elliptic_e(a**2/r**2))/(pi*E_star)', ''),
    ('uniform_pressure_force', 'Problem 6', 'pressures', 'pi*a**2*p0', ''),
    ('worn_contact_radius', 'Problem 8', 'worn', 'sqrt(b**2/2 + sqrt(4*R**2*d**2 + b**4)/2)', ''),
    ('worn_depth', 'Problem 8', 'worn', 'a*sqrt(a**2 - b**2)/R', ''),
    ('worn_displacement_inside', 'Problem 8, (5.60)', 'worn', 'd - Max(0, (-b + r)*(b + r))/(2*R)', ''),
    ('worn_displacement_outside', 'Problem 8, (5.60)', 'worn', '(2*a*sqrt(a**2 - b**2)*asin(a/r) - (b - r)*(b + r)*(sqrt((-a**2 + b**2)/(b**2 - r**2))*sqrt((-a**2 + r**2)/(-b**2 + r**2)) - asin(sqrt((-a**2 + b**2)/(b**2 - r**2)))))/(pi*R)', ''),
    ('worn_force', 'Problem 8', 'worn', 'E_star*sqrt(-2*b**2 + 2*sqrt(4*R**2*d**2 + b**4))*(2*b**2 + sqrt(4*R**2*d**2 + b**4))/(3*R)', ''),
    ('worn_force_from_radius', 'Problem 8', 'worn', '2*E_star*sqrt(a - b)*sqrt(a + b)*(2*a**2 + b**2)/(3*R)', ''),
    ('worn_g', 'Problem 8', 'worn', 'x*sqrt(Max(0, (-b + x)*(b + x)))/R', ''),
    ('worn_pressure', 'Problem 8, (5.59)', 'worn', 'E_star*(2*a*sqrt(Max(0, (a - Max(b, r))*(a + Max(b, r))))/sqrt((Max(b, r) - Min(b, r))*(Max(b, r) + Min(b, r)) + Max(0, (a - Max(b, r))*(a + Max(b, r)))) + (-b**2 + 2*Max(b, r)**2)*elliptic_f(atan2(sqrt(Max(0, (a - Max(b, r))*(a + Max(b, r)))), sqrt(Max(b, r) - Min(b, r))*sqrt(Max(b, r) + Min(b, r))), Min(b, r)**2/Max(b, r)**2)/Max(b, r) - 2*elliptic_e(atan2(sqrt(Max(0, (a - Max(b, r))*(a + Max(b, r)))), sqrt(Max(b, r) - Min(b, r))*sqrt(Max(b, r) + Min(b, r))), Min(b, r)**2/Max(b, r)**2)*Max(b, r))/(pi*R)', ''),
    ('worn_profile', 'Problem 8', 'worn', 'Max(0, (-b + r)*(b + r))/(2*R)', ''),
)


def adhesion_cone_depth(E_star, a, dgamma, theta):
    """Indentation depth d [m] of a cone in adhesive contact of radius a.

    Chapter: (5.55), adhesive. Derived from: (5.52), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(theta) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_depth(E_star, a, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*a*numpy.tan(theta) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*numpy.sqrt(dgamma)/numpy.sqrt(E_star)


def adhesion_cone_force_from_radius(E_star, a, dgamma, theta):
    """Normal force F [N] of a cone in adhesive contact of radius a.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(theta) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_force_from_radius(E_star, a, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*numpy.sqrt(dgamma) + (1/2)*numpy.pi*E_star*a**2*numpy.tan(theta)


def adhesion_cone_g_slope(theta):
    """Slope g'(x) [1] of the MDR profile of the cone (the same at every x > 0).

    Chapter: (5.52) of r tan(theta). Derived from: the derivative of (5.52) for f = r
    tan(theta).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_g_slope(theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*numpy.tan(theta)


def adhesion_cone_pull_off_depth_dc(E_star, dgamma, theta):
    """Depth d_c [m] at pull-off of a cone under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_depth_dc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -dgamma/(E_star*numpy.tan(theta))


def adhesion_cone_pull_off_depth_fc(E_star, dgamma, theta):
    """Depth d_c [m] at pull-off of a cone under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_depth_fc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 3*dgamma/(E_star*numpy.tan(theta))


def adhesion_cone_pull_off_force_dc(E_star, dgamma, theta):
    """Pull-off force F_c [N] (negative) of a cone under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_force_dc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -6*dgamma**2/(numpy.pi*E_star*numpy.tan(theta)**3)


def adhesion_cone_pull_off_force_fc(E_star, dgamma, theta):
    """Pull-off force F_c [N] (negative) of a cone under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_force_fc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -54*dgamma**2/(numpy.pi*E_star*numpy.tan(theta)**3)


def adhesion_cone_pull_off_radius_dc(E_star, dgamma, theta):
    """Contact radius a_c [m] at pull-off of a cone under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_radius_dc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*dgamma/(numpy.pi*E_star*numpy.tan(theta)**2)


def adhesion_cone_pull_off_radius_fc(E_star, dgamma, theta):
    """Contact radius a_c [m] at pull-off of a cone under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_pull_off_radius_fc(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 18*dgamma/(numpy.pi*E_star*numpy.tan(theta)**2)


def adhesion_cone_zero_load_radius(E_star, dgamma, theta):
    """Contact radius a_0 [m] of a cone at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(dgamma) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_cone_zero_load_radius(E_star, dgamma, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 32*dgamma/(numpy.pi*E_star*numpy.tan(theta)**2)


def adhesion_critical_elongation(E_star, a, dgamma):
    """Critical elongation Delta l [m] of the boundary spring, g(a) - d.

    Chapter: (5.55), energy balance. Derived from: G = Delta gamma solved for d.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_energy_release_rate_by_3d_route``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if type(E_star) is float and type(a) is float and type(dgamma) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_critical_elongation(E_star, a, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*numpy.sqrt(dgamma)/numpy.sqrt(E_star)


def adhesion_depth(E_star, a, dgamma, g_a):
    """Indentation depth d [m] of an adhesive contact of radius a, g(a) - Delta l.

    Chapter: (5.55), adhesive. Derived from: (5.55) with the stretched boundary spring.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(g_a) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_depth(E_star, a, dgamma, g_a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return g_a - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*numpy.sqrt(dgamma)/numpy.sqrt(E_star)


def adhesion_depth_slope(E_star, a, dgamma, g_slope):
    """Dd/da [1] along an adhesive contact; 0 at pull-off under depth control.

    Chapter: (5.55), adhesive. Derived from: the derivative of d = g(a) - Delta l(a).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(g_slope) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_depth_slope(E_star, a, dgamma, g_slope)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return g_slope - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(dgamma)/(numpy.sqrt(E_star)*numpy.sqrt(a))


def adhesion_displacement_outside_edge(E_star, a, dgamma, r):
    """Adhesive term of the surface displacement u_z(r) [m] outside the contact (r > a); add the non-adhesive displacement of radius a.

    Chapter: (5.60), adhesive. Derived from: (5.60) of the constant u_z = -Delta l on |x| <
    a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_displacement_outside_edge(E_star, a, dgamma, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(a)*numpy.sqrt(dgamma)*numpy.arcsin(a/r)/(numpy.sqrt(numpy.pi)*numpy.sqrt(E_star))


def adhesion_energy_release_rate(E_star, a, d, g_a):
    """Energy release rate G [J/m^2] at the edge of a contact of radius a at depth d.

    Chapter: (5.57), energy balance. Derived from: dU/da at fixed d over 2 pi a, U the work
    of (5.57) along the non-adhesive path plus a flat punch.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_energy_release_rate_by_3d_route``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    """
    if (type(E_star) is float and type(a) is float and type(d) is float and
            type(g_a) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_energy_release_rate(E_star, a, d, g_a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*(d - g_a)**2/(numpy.pi*a)


def adhesion_force_slope(E_star, a, dgamma, g_slope):
    """DF/da [N/m] along an adhesive contact; 0 at pull-off under force control.

    Chapter: (5.57), adhesive. Derived from: the derivative of (5.57) along d = g(a) - Delta
    l(a).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(g_slope) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_force_slope(E_star, a, dgamma, g_slope)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*numpy.sqrt(a)*numpy.sqrt(dgamma) + 2*E_star*a*g_slope


def adhesion_paraboloid_g_slope(R, x):
    """Slope g'(x) [1] of the MDR profile of the paraboloid, x >= 0.

    Chapter: (5.52) of r^2/(2R). Derived from: the derivative of (5.52) for f = r^2/(2R).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_paraboloid_g_slope(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*x/R


def adhesion_powerlaw_depth(E_star, a, dgamma, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law profile c_n r^n (n > 1/2) in adhesive contact of radius a.

    Chapter: (5.55), adhesive. Derived from: (5.52), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(c_n) is float and type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_depth(E_star, a, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a**n*c_n*kappa_n - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*numpy.sqrt(dgamma)/numpy.sqrt(E_star)


def adhesion_powerlaw_force_from_radius(E_star, a, dgamma, c_n, kappa_n, n):
    """Normal force F [N] of a power-law profile c_n r^n (n > 1/2) in adhesive contact of radius a.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(c_n) is float and type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_force_from_radius(E_star, a, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*numpy.sqrt(dgamma)*n/(n + 1) - 2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*numpy.sqrt(dgamma)/(n + 1) + 2*E_star*a*a**n*c_n*kappa_n*n/(n + 1)


def adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """Slope g'(x) [1] of the MDR profile of the power law f = c_n r^n, x > 0.

    Chapter: (5.52), Problem 7(d). Derived from: the derivative of (5.52) for f = c_n r^n, g
    = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Printed in a stable form: x^n/x is 0/0 at x = 0 and overflows before x^(n - 1) does.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : float or ndarray
        coordinate [m]
    """
    if (type(c_n) is float and type(kappa_n) is float and type(n) is float and
            type(x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return c_n*kappa_n*n*x**(n - 1)


def adhesion_powerlaw_pull_off_depth_dc(E_star, dgamma, c_n, kappa_n, n):
    """Depth d_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_depth_dc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(dgamma)*(2*n - 1)*numpy.sqrt(((1/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0)))/(numpy.sqrt(E_star)*n)


def adhesion_powerlaw_pull_off_depth_fc(E_star, dgamma, c_n, kappa_n, n):
    """Depth d_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_depth_fc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(dgamma)*(2*n - 3)*numpy.sqrt(((9/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0)))/(numpy.sqrt(E_star)*n)


def adhesion_powerlaw_pull_off_force_dc(E_star, dgamma, c_n, kappa_n, n):
    """Pull-off force F_c [N] (negative) of a power-law profile c_n r^n (n > 1/2) under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_force_dc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*numpy.sqrt(dgamma)*(2*n + 1)*(((1/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0)))**(3/2)/(n + 1)


def adhesion_powerlaw_pull_off_force_fc(E_star, dgamma, c_n, kappa_n, n):
    """Pull-off force F_c [N] (negative) of a power-law profile c_n r^n (n > 1/2) under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_force_fc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*numpy.sqrt(dgamma)*(2*n - 1)*(((9/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0)))**(3/2)/(n + 1)


def adhesion_powerlaw_pull_off_radius_dc(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_radius_dc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return ((1/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0))


def adhesion_powerlaw_pull_off_radius_fc(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_c [m] at pull-off of a power-law profile c_n r^n (n > 1/2) under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_pull_off_radius_fc(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return ((9/2)*numpy.pi*dgamma/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0))


def adhesion_powerlaw_zero_load_radius(E_star, dgamma, c_n, kappa_n, n):
    """Contact radius a_0 [m] of a power-law profile c_n r^n (n > 1/2) at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_pull_off_by_mpmath_minimization``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(dgamma) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_powerlaw_zero_load_radius(E_star, dgamma, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2*numpy.pi*dgamma*(n**2 + 2*n + 1)/(E_star*c_n**2*kappa_n**2*n**2))**((2*n - 1)**(-1.0))


def adhesion_pressure_edge(E_star, a, dgamma, r):
    """Adhesive term of the contact pressure p(r) [Pa] for r < a (negative: tension; add the non-adhesive pressure of radius a).

    Chapter: (5.59), adhesive. Derived from: (5.59) with the jump of q(x) at x = a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Printed in a stable form: a^2 - r^2 loses the digits of a - r next to the edge, where
    the term is largest; written (a - r)(a + r).

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_pressure_edge(E_star, a, dgamma, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*numpy.sqrt(E_star)*numpy.sqrt(a)*numpy.sqrt(dgamma)/(numpy.sqrt(numpy.pi)*numpy.sqrt(a - r)*numpy.sqrt(a + r))


def adhesion_punch_cycle_work(E_star, a, dgamma):
    """Work W [J] done on a flat punch of radius a over an approach-push-retract cycle: dissipated by the jump at pull-off (>= 0).

    Chapter: (5.57), Kendall. Derived from: the closed integral of (5.57) with g = 0 over
    the cycle.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_punch_cycle_work_is_kendalls``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if type(E_star) is float and type(a) is float and type(dgamma) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_punch_cycle_work(E_star, a, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*numpy.pi*a**2*dgamma


def adhesion_punch_pull_off_force(E_star, a, dgamma):
    """Pull-off force F_c [N] of a flat punch of radius a (Kendall), negative.

    Chapter: (5.57), Kendall. Derived from: (5.57) with g = 0 at d = -Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_kendall_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if type(E_star) is float and type(a) is float and type(dgamma) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_punch_pull_off_force(E_star, a, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*numpy.sqrt(dgamma)


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_sphere_g_slope(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R*x/((R - x)*(R + x)) + (1/2)*numpy.log1p(2*x/(R - x))


def adhesion_tabor_parameter(E_star, R, dgamma, z0):
    """Tabor parameter mu_T [1]: JKR holds for mu_T > 5, DMT for mu_T < 0.1.

    Chapter: Tabor (1977). Derived from: the ratio of the JKR neck height to the range z0 (a
    definition).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_tabor_parameter``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    z0 : float or ndarray
        range of the adhesive forces (equilibrium distance) of the Tabor parameter [m]
    """
    if (type(E_star) is float and type(R) is float and type(dgamma) is float and
            type(z0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_tabor_parameter(E_star, R, dgamma, z0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R**(1/3)*dgamma**(2/3)/(E_star**(2/3)*z0)


def adhesion_worn_g_slope(R, b, x):
    """Slope g'(x) [1] of the MDR profile of the worn paraboloid for x > b (0 for x < b; infinite at the kink x = b+).

    Chapter: (5.52), Problem 8. Derived from: the derivative of (5.52) for f = (r^2 -
    b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Printed in a stable form: x^2 - b^2 as (x - b)(x + b), exact next to the kink.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(b) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_adhesion_worn_g_slope(R, b, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-b**2 + 2*x**2)/(R*numpy.sqrt(-b + x)*numpy.sqrt(b + x))


def bodies_crossed_cylinders_curvature_1(R1, R2, alpha):
    """Larger principal curvature [1/m] of the gap of two cylinders crossed at alpha.

    Chapter: (5.32), (5.33), any angle. Derived from: the larger eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    alpha : float or ndarray
        angle between the axes of two crossed cylinders [rad]
    """
    if type(R1) is float and type(R2) is float and type(alpha) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_crossed_cylinders_curvature_1(R1, R2, alpha)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt((numpy.cos(2*alpha)/R2 + R1**(-1.0))**2 + numpy.sin(2*alpha)**2/R2**2) + (1/2)/R2 + (1/2)/R1


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
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    alpha : float or ndarray
        angle between the axes of two crossed cylinders [rad]
    """
    if type(R1) is float and type(R2) is float and type(alpha) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_crossed_cylinders_curvature_2(R1, R2, alpha)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*numpy.sin(alpha)**2/(R1*R2*(numpy.sqrt((numpy.cos(2*alpha)/R2 + R1**(-1.0))**2 + numpy.sin(2*alpha)**2/R2**2) + R2**(-1.0) + R1**(-1.0)))


def bodies_crossed_cylinders_gaussian_radius(R1, R2, alpha):
    """Gaussian radius R~ [m] of two cylinders crossed at alpha (sqrt(R1 R2) at alpha = pi/2).

    Chapter: (5.33), any angle. Derived from: 1/sqrt(kappa_1 kappa_2) of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    alpha : float or ndarray
        angle between the axes of two crossed cylinders [rad]
    """
    if type(R1) is float and type(R2) is float and type(alpha) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_crossed_cylinders_gaussian_radius(R1, R2, alpha)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R1)*numpy.sqrt(R2)/abs(numpy.sin(alpha))


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
    E1 : float or ndarray
        Young's modulus of body 1 [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    E2 : float or ndarray
        Young's modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(E1) is float and type(nu1) is float and type(E2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_effective_modulus(E1, nu1, E2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return ((1 - nu2)*(nu2 + 1)/E2 + (1 - nu1)*(nu1 + 1)/E1)**(-1.0)


def bodies_effective_modulus_rigid(E, nu):
    """Effective modulus E* [Pa] of an elastic body against a rigid one.

    Chapter: (5.8), (5.26) with E2 -> inf. Derived from: the limit E2 -> inf of (5.26).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Printed in a stable form: 1 - nu^2 = (1 - nu)(1 + nu) is exact in floating point for nu
    near -1, where 1 - nu^2 cancels.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(E) is float and type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_effective_modulus_rigid(E, nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E/((1 - nu)*(nu + 1))


def bodies_effective_radius(R1, R2):
    """Effective radius R [m] of two spheres (negative radius: concave).

    Chapter: (5.27). Derived from: the sum of the two gaps r^2/(2 R_i).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_radius_by_gap``.

    Printed in a stable form: the sum of the curvatures accepts R = inf (flat).

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    """
    if type(R1) is float and type(R2) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_effective_radius(R1, R2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (R2**(-1.0) + R1**(-1.0))**(-1.0)


def bodies_gaussian_approx_area(R1, R2, d):
    """Contact area A = pi a b [m^2] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.29), approximation. Derived from: (5.28) in pi a b.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R1) is float and type(R2) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_area(R1, R2, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.pi*numpy.sqrt(R1)*numpy.sqrt(R2)*d


def bodies_gaussian_approx_depth_from_force(E_star, F, R1, R2):
    """Indentation depth d [m] of the elliptic contact under the force F (Gaussian-radius approximation).

    Chapter: (5.24) with (5.30), approximation. Derived from: the force of (5.31) over
    (5.28) solved for d.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    """
    if (type(E_star) is float and type(F) is float and type(R1) is float and
            type(R2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_depth_from_force(E_star, F, R1, R2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*6**(2/3)*F**(2/3)/(E_star**(2/3)*R1**(1/6)*R2**(1/6))


def bodies_gaussian_approx_force(E_star, R1, R2, d):
    """Normal force F [N] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.23) with (5.30), approximation. Derived from: the ellipsoidal pressure
    (5.31) integrated over the ellipse (5.28).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if (type(E_star) is float and type(R1) is float and type(R2) is float and
            type(d) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_force(E_star, R1, R2, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*R1**(1/4)*R2**(1/4)*d**(3/2)


def bodies_gaussian_approx_max_pressure(E_star, R1, R2, d):
    """Maximum pressure p0 [Pa] of the elliptic contact (Gaussian-radius approximation).

    Chapter: (5.22) with (5.30), approximation. Derived from: (5.22) with R = R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if (type(E_star) is float and type(R1) is float and type(R2) is float and
            type(d) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_max_pressure(E_star, R1, R2, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(d)/(numpy.pi*R1**(1/4)*R2**(1/4))


def bodies_gaussian_approx_pressure(E_star, R1, R2, d, x, y):
    """Pressure p(x, y) [Pa] of the elliptic contact (Gaussian-radius approximation; x along R1, 0 outside the ellipse).

    Chapter: (5.31), approximation. Derived from: (5.31) with (5.28) and the p0 of (5.22) at
    R = R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    d : float or ndarray
        indentation depth [m]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    import functools

    if (type(E_star) is float and type(R1) is float and type(R2) is float and
            type(d) is float and type(x) is float and type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_pressure(E_star, R1, R2, d, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - y**2/(R2*d) - x**2/(R1*d)]))/(numpy.pi*R1**(1/4)*R2**(1/4))


def bodies_gaussian_approx_semi_axis_1(R1, d):
    """Semi-axis a [m] along the principal radius R1 of the elliptic contact in the chapter's rough estimate.

    Chapter: (5.28), approximation. Derived from: (5.21) with R = R1.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R1) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_semi_axis_1(R1, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R1)*numpy.sqrt(d)


def bodies_gaussian_approx_semi_axis_2(R2, d):
    """Semi-axis b [m] along the principal radius R2 of the elliptic contact in the chapter's rough estimate.

    Chapter: (5.28), approximation. Derived from: (5.21) with R = R2.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R2) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_approx_semi_axis_2(R2, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R2)*numpy.sqrt(d)


def bodies_gaussian_radius(R1, R2):
    """Gaussian radius R~ [m] of a gap with the principal radii R1, R2.

    Chapter: (5.30). Derived from: the sphere with the same Gaussian curvature kappa_1
    kappa_2.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_gaussian_approximation``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    """
    if type(R1) is float and type(R2) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_gaussian_radius(R1, R2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R1)*numpy.sqrt(R2)


def bodies_principal_curvature_1(R1a, R1b, R2a, R2b, omega):
    """Larger principal curvature kappa_1 [1/m] of the gap between two bodies.

    Chapter: (5.32), Problem 2, general. Derived from: the larger eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1a : float or ndarray
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : float or ndarray
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : float or ndarray
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : float or ndarray
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : float or ndarray
        angle between the first principal directions of the two bodies [rad]
    """
    if (type(R1a) is float and type(R1b) is float and type(R2a) is float and
            type(R2b) is float and type(omega) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_principal_curvature_1(R1a, R1b, R2a, R2b, omega)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt((-1/R2b + R2a**(-1.0))**2*numpy.sin(2*omega)**2 + ((-1/R2b + R2a**(-1.0))*numpy.cos(2*omega) - 1/R1b + R1a**(-1.0))**2) + (1/2)/R2b + (1/2)/R2a + (1/2)/R1b + (1/2)/R1a


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
    R1a : float or ndarray
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : float or ndarray
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : float or ndarray
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : float or ndarray
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : float or ndarray
        angle between the first principal directions of the two bodies [rad]
    """
    if (type(R1a) is float and type(R1b) is float and type(R2a) is float and
            type(R2b) is float and type(omega) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2*(1/(R1b*R2a) + 1/(R1a*R2b))*numpy.cos(omega)**2 + 2*(1/(R1b*R2b) + 1/(R1a*R2a))*numpy.sin(omega)**2 + 2/(R2a*R2b) + 2/(R1a*R1b))/(numpy.sqrt((-1/R2b + R2a**(-1.0))**2*numpy.sin(2*omega)**2 + ((-1/R2b + R2a**(-1.0))*numpy.cos(2*omega) - 1/R1b + R1a**(-1.0))**2) + R2b**(-1.0) + R2a**(-1.0) + R1b**(-1.0) + R1a**(-1.0))


def bodies_problem2_force(E, nu, R, d):
    """Normal force F [N] of two equal cylinders of one material crossed at pi/4 (Gaussian-radius approximation).

    Chapter: Problem 2. Derived from: (5.23) with (5.26) and R~.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): with R~ = sqrt(2) R the factor is
    2^(5/4)/3, not 2^(7/4)/3 (the printed force is sqrt(2) times too large)

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    nu : float or ndarray
        Poisson's ratio [1]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E) is float and type(nu) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_problem2_force(E, nu, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*2**(1/4)*E*numpy.sqrt(R)*d**(3/2)/(3*nu**2 - 3)


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_problem2_gaussian_radius(R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(2)*R


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_problem2_principal_radius_1(R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*R + 2*R


def bodies_problem2_principal_radius_2(R):
    """Larger principal radius [m] of two equal cylinders crossed at pi/4.

    Chapter: Problem 2. Derived from: 1/kappa_2 of the gap's Hessian.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_problem2``.

    Differs from the print (see docs/errata.md): eigenvalues of M instead of the Hessian 2M:
    the radius is R/(1 - 1/sqrt(2)), half the printed one

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_bodies_problem2_principal_radius_2(R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(2)*R + 2*R


def boussinesq_sigma_xx(F, nu, x, y, z):
    """Stress sigma_xx [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.41). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_xx(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(3/2) + 2*nu*z**3*(x**2 + y**2 + z**2) + 4*nu*z**2*(x**2 + y**2 + z**2)**(3/2) - 2*nu*(x**2 + y**2 + z**2)**(5/2) + 3*x**2*z**3 + 6*x**2*z**2*numpy.sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(3/2) - z**3*(x**2 + y**2 + z**2) - 2*z**2*(x**2 + y**2 + z**2)**(3/2) + (x**2 + y**2 + z**2)**(5/2))/(numpy.pi*(z + numpy.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))


def boussinesq_sigma_xy(F, nu, x, y, z):
    """Stress sigma_xy [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.44). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_xy(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*F*x*y*(2*nu*z*(x**2 + y**2 + z**2) + 4*nu*(x**2 + y**2 + z**2)**(3/2) + 3*z**3 + 6*z**2*numpy.sqrt(x**2 + y**2 + z**2) + 2*z*(x**2 + y**2 + z**2) - 2*(x**2 + y**2 + z**2)**(3/2))/(numpy.pi*(z + numpy.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))


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
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_xz(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/2*F*x*z**2/(numpy.pi*(x**2 + y**2 + z**2)**(5/2))


def boussinesq_sigma_yy(F, nu, x, y, z):
    """Stress sigma_yy [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.42). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_yy(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*(2*nu*x**2*z*(x**2 + y**2 + z**2) + 4*nu*x**2*(x**2 + y**2 + z**2)**(3/2) - 2*nu*z*(x**2 + y**2 + z**2)**2 - 2*nu*(x**2 + y**2 + z**2)**(5/2) + 3*x**2*z**3 + 6*x**2*z**2*numpy.sqrt(x**2 + y**2 + z**2) + 2*x**2*z*(x**2 + y**2 + z**2) - 2*x**2*(x**2 + y**2 + z**2)**(3/2) + 3*z**5 + 6*z**4*numpy.sqrt(x**2 + y**2 + z**2) - 6*z**2*(x**2 + y**2 + z**2)**(3/2) - 2*z*(x**2 + y**2 + z**2)**2 + (x**2 + y**2 + z**2)**(5/2))/(numpy.pi*(z + numpy.sqrt(x**2 + y**2 + z**2))**2*(x**2 + y**2 + z**2)**(5/2))


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
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_yz(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/2*F*y*z**2/(numpy.pi*(x**2 + y**2 + z**2)**(5/2))


def boussinesq_sigma_zz(F, nu, x, y, z):
    """Stress sigma_zz [Pa] at (x, y, z) of a point force F in +z at the origin (tension positive).

    Chapter: (5.43). Derived from: (5.1)-(5.3) by the small-strain tensor and Hooke's law.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(F) is float and type(nu) is float and type(x) is float and type(y) is float and
            type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_sigma_zz(F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/2*F*z**3/(numpy.pi*(x**2 + y**2 + z**2)**(5/2))


def boussinesq_surface_prefactor(E_star):
    """Prefactor 1/(pi E*) [1/Pa] of the surface Green's function: u_z = F/(pi E* rho).

    Chapter: (5.7). Derived from: (5.6) times rho/F with E/(1 - nu^2) = E*.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_prefactor_against_the_point_force``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    """
    if type(E_star) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_surface_prefactor(E_star)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 1/(numpy.pi*E_star)


def boussinesq_surface_ux(E, F, nu, x, y):
    """Surface displacement u_x [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.4). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_surface_ux(E, F, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*x*(nu + 1)*(2*nu - 1)/(numpy.pi*E*(x**2 + y**2))


def boussinesq_surface_uy(E, F, nu, x, y):
    """Surface displacement u_y [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.5). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_surface_uy(E, F, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*y*(nu + 1)*(2*nu - 1)/(numpy.pi*E*(x**2 + y**2))


def boussinesq_surface_uz(E, F, nu, x, y):
    """Surface displacement u_z [m] at (x, y, 0) of a point force F in +z at the origin.

    Chapter: (5.6). Derived from: (5.1)-(5.3) at z -> 0.

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_surface_displacement_is_the_limit``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_surface_uz(E, F, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -F*(nu - 1)*(nu + 1)/(numpy.pi*E*numpy.sqrt(x**2 + y**2))


def boussinesq_ux(E, F, nu, x, y, z):
    """Displacement u_x [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.1). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_ux(E, F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*(nu + 1)*(x*z/(x**2 + y**2 + z**2)**(3/2) - x*(1 - 2*nu)/((z + numpy.sqrt(x**2 + y**2 + z**2))*numpy.sqrt(x**2 + y**2 + z**2)))/(numpy.pi*E)


def boussinesq_uy(E, F, nu, x, y, z):
    """Displacement u_y [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.2). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_uy(E, F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*(nu + 1)*(y*z/(x**2 + y**2 + z**2)**(3/2) - y*(1 - 2*nu)/((z + numpy.sqrt(x**2 + y**2 + z**2))*numpy.sqrt(x**2 + y**2 + z**2)))/(numpy.pi*E)


def boussinesq_uz(E, F, nu, x, y, z):
    """Displacement u_z [m] at (x, y, z) of a point force F in +z at the origin.

    Chapter: (5.3). Derived from: the given solution (Landau & Lifshitz, section 8).

    Derivation: ``hertzmdr.derive.boussinesq``. Verified by
    ``tests/test_boussinesq.py::test_stress_from_displacement_in_equilibrium``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    F : float or ndarray
        normal force [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(E) is float and type(F) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_boussinesq_uz(E, F, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*(nu + 1)*(z**2/(x**2 + y**2 + z**2)**(3/2) + (2 - 2*nu)/numpy.sqrt(x**2 + y**2 + z**2))/(numpy.pi*E)


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
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_displacement(a, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/4*F*mu_f*numpy.expm1((2/3)*numpy.log1p(-F_x/(F*mu_f)))/(G_star*a)


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
    a : float or ndarray
        contact radius [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(R) is float and type(E_star) is float and
            type(G_star) is float and type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_force(a, R, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*G_star*u_x*(a**2 + (E_star*a**2*mu_f - G_star*R*u_x)/(E_star*mu_f) + a*numpy.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(numpy.sqrt(E_star)*numpy.sqrt(mu_f)))/(a + numpy.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(numpy.sqrt(E_star)*numpy.sqrt(mu_f)))


def cattaneo_stick_radius(a, R, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a paraboloid (f = r^2/(2R)) displaced by u_x at constant load.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: g(c) = d - G* u_x/(mu E*),
    g = x^2/R.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(R) is float and type(E_star) is float and
            type(G_star) is float and type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_stick_radius(a, R, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(E_star*a**2*mu_f - G_star*R*u_x)/(numpy.sqrt(E_star)*numpy.sqrt(mu_f))


def cattaneo_stick_radius_from_force(a, F, mu_f, F_x):
    """Stick radius c [m] of a paraboloid under the normal force F and tangential force F_x.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^3.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if type(a) is float and type(F) is float and type(mu_f) is float and type(F_x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_stick_radius_from_force(a, F, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*(F*mu_f - F_x)**(1/3)/(F**(1/3)*mu_f**(1/3))


def cattaneo_traction_slip(r, a, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the slip zone c < r < a of a paraboloid (mu p(r)).

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the sliding
    springs' line load mu E* (d - g).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(a) is float and type(R) is float and type(E_star) is float
            and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_traction_slip(r, a, R, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*mu_f*numpy.sqrt(a**2 - r**2)/(numpy.pi*R)


def cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a paraboloid.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the tangential
    line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Printed in a stable form: the difference of the two square roots cancels as c -> a.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    c : float or ndarray
        radius of the stick zone [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(a) is float and type(c) is float and type(R) is float and
            type(E_star) is float and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cattaneo_traction_stick(r, a, c, R, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*mu_f*(a - c)*(a + c)/(numpy.pi*R*(numpy.sqrt(a - r)*numpy.sqrt(a + r) + numpy.sqrt(c - r)*numpy.sqrt(c + r)))


def cerruti_surface_ux(G, Q, nu, x, y):
    """Surface displacement u_x [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_surface_ux(G, Q, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*Q*(-nu*y**2 + x**2 + y**2)/(numpy.pi*G*(x**2 + y**2)**(3/2))


def cerruti_surface_uy(G, Q, nu, x, y):
    """Surface displacement u_y [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_surface_uy(G, Q, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*Q*nu*x*y/(numpy.pi*G*(x**2 + y**2)**(3/2))


def cerruti_surface_uz(G, Q, nu, x, y):
    """Surface displacement u_z [m] at (x, y, 0) of a tangential point force Q in +x at the origin.

    Chapter: Cerruti (not in the chapter; Johnson (3.87)). Derived from: the Cerruti field
    at z -> 0.

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_surface_is_the_limit_and_reciprocal_to_boussinesq``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_surface_uz(G, Q, nu, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/4*Q*x*(2*nu - 1)/(numpy.pi*G*(x**2 + y**2))


def cerruti_ux(G, Q, nu, x, y, z):
    """Displacement u_x [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_ux(G, Q, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*Q*(x**2/(x**2 + y**2 + z**2)**(3/2) + (1 - 2*nu)*(-x**2/((z + numpy.sqrt(x**2 + y**2 + z**2))**2*numpy.sqrt(x**2 + y**2 + z**2)) + (z + numpy.sqrt(x**2 + y**2 + z**2))**(-1.0)) + 1/numpy.sqrt(x**2 + y**2 + z**2))/(numpy.pi*G)


def cerruti_uy(G, Q, nu, x, y, z):
    """Displacement u_y [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_uy(G, Q, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*Q*(-x*y*(1 - 2*nu)/((z + numpy.sqrt(x**2 + y**2 + z**2))**2*numpy.sqrt(x**2 + y**2 + z**2)) + x*y/(x**2 + y**2 + z**2)**(3/2))/(numpy.pi*G)


def cerruti_uz(G, Q, nu, x, y, z):
    """Displacement u_z [m] at (x, y, z) of a tangential point force Q in +x at the origin of the surface.

    Chapter: Cerruti (not in the chapter; Johnson (3.86)). Derived from: the given solution
    (Cerruti 1882; Johnson, Contact Mechanics, (3.86)).

    Derivation: ``hertzmdr.derive.cerruti``. Verified by
    ``tests/test_cerruti.py::test_field_in_equilibrium_and_surface_traction_free``.

    Parameters
    ----------
    G : float or ndarray
        shear modulus [Pa]
    Q : float or ndarray
        tangential point force in +x at the origin of the surface [N]
    nu : float or ndarray
        Poisson's ratio [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if (type(G) is float and type(Q) is float and type(nu) is float and type(x) is float and
            type(y) is float and type(z) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cerruti_uz(G, Q, nu, x, y, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*Q*(x*z/(x**2 + y**2 + z**2)**(3/2) + x*(1 - 2*nu)/((z + numpy.sqrt(x**2 + y**2 + z**2))*numpy.sqrt(x**2 + y**2 + z**2)))/(numpy.pi*G)


def cone_contact_radius(d, theta):
    """Contact radius a [m] of a rigid cone at depth d.

    Chapter: (5.38), Problem 7(c). Derived from: (5.38) solved for a.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    d : float or ndarray
        indentation depth [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(d) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_contact_radius(d, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*d/(numpy.pi*numpy.tan(theta))


def cone_contact_radius_from_force(E_star, F, theta):
    """Contact radius a [m] of a rigid cone under the force F.

    Chapter: (5.38), (5.40). Derived from: (5.38) at the depth of (5.40) inverted.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(F) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_contact_radius_from_force(E_star, F, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(2)*numpy.sqrt(F)/(numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*numpy.sqrt(numpy.tan(theta)))


def cone_depth(a, theta):
    """Indentation depth d [m] of a rigid cone at the contact radius a.

    Chapter: (5.38). Derived from: flat punches superposed to match the cone's surface.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(a) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_depth(a, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*a*numpy.tan(theta)


def cone_depth_from_force(E_star, F, theta):
    """Indentation depth d [m] of a rigid cone under the force F.

    Chapter: (5.40), inverted. Derived from: (5.40) solved for d.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(F) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_depth_from_force(E_star, F, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(F)*numpy.sqrt(numpy.tan(theta))/numpy.sqrt(E_star)


def cone_force(E_star, d, theta):
    """Normal force F [N] of a rigid cone at depth d.

    Chapter: (5.40). Derived from: the forces 2 a' E* dd of the superposed punches.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    d : float or ndarray
        indentation depth [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(d) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_force(E_star, d, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d**2/(numpy.pi*numpy.tan(theta))


def cone_g(theta, x):
    """MDR profile g(x) [m] of the cone f = r tan(theta), x >= 0 (g is even in x).

    Chapter: (5.52) of f = r tan(theta). Derived from: (5.52) of r tan(theta).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_g_against_the_mdr_transform``.

    Parameters
    ----------
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    x : float or ndarray
        coordinate [m]
    """
    if type(theta) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_g(theta, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*x*numpy.tan(theta)


def cone_mean_pressure(E_star, theta):
    """Mean pressure F/(pi a^2) [Pa] of a rigid cone (independent of the depth).

    Chapter: (5.40)/(pi a^2). Derived from: (5.40) divided by the contact area.

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_mean_pressure(E_star, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*numpy.tan(theta)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    d : float or ndarray
        indentation depth [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(d) is float and type(theta) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_cone_pressure(E_star, d, theta, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*numpy.tan(theta)*numpy.arcsinh((1/2)*numpy.sqrt(2)*numpy.sqrt(2*d/(numpy.pi*numpy.tan(theta)) - r)/numpy.sqrt(r))


def cone_profile(theta, r):
    """Height f(r) [m] of the cone above its tip (the profile whose g is cone_g).

    Chapter: (5.52). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(theta) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_profile(theta, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return r*numpy.tan(theta)


def cone_stiffness(E_star, d, theta):
    """Differential stiffness dF/dd [N/m] of a rigid cone at depth d.

    Chapter: Problem 5. Derived from: the derivative of (5.40).

    Derivation: ``hertzmdr.derive.cone``. Verified by
    ``tests/test_cone.py::test_cone_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    d : float or ndarray
        indentation depth [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(d) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_cone_stiffness(E_star, d, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*E_star*d/(numpy.pi*numpy.tan(theta))


def contact_mean_pressure(A, F):
    """Mean pressure F/A [Pa] over a contact of area A.

    Chapter: (5.17). Derived from: the definition of the mean pressure.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_area``.

    Parameters
    ----------
    A : float or ndarray
        contact area [m^2]
    F : float or ndarray
        normal force [N]
    """
    if type(A) is float and type(F) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_contact_mean_pressure(A, F)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F/A


def coulomb_sliding_force(mu_f, F):
    """Tangential force mu F [N] of full sliding under the normal force F (Coulomb's limit).

    Chapter: Coulomb's law, from the springs (not in the chapter). Derived from: the spring
    sum at c = 0 over the normal force (5.57).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_sliding_force_is_the_spring_sum_at_full_slip``.

    Parameters
    ----------
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F : float or ndarray
        normal force [N]
    """
    if type(mu_f) is float and type(F) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_coulomb_sliding_force(mu_f, F)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F*mu_f


def disc_mean_pressure(F, a):
    """Mean pressure F/(pi a^2) [Pa] over a circular contact of radius a.

    Chapter: (5.17). Derived from: the definition of the mean pressure over a disc.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_disc``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    a : float or ndarray
        contact radius [m]
    """
    if type(F) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_disc_mean_pressure(F, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F/(numpy.pi*a**2)


def disc_pressure(a, n_p, p0, r):
    """Prescribed pressure p0 (1 - r^2/a^2)^n_p [Pa] on a disc of radius a, r < a.

    Chapter: (5.9), (5.15), Problem 6. Derived from: the distributions of section 5.1.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_disc_pressure_force``.

    Printed in a stable form: 1 - r^2/a^2 cancels towards the edge r -> a (1e-13 at r =
    0.9995 a); (a - r)(a + r)/a^2 does not.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n_p : float or ndarray
        exponent of a prescribed pressure p0*(1 - r^2/a^2)^n_p on a disc (section 5.1) [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(a) is float and type(n_p) is float and type(p0) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_disc_pressure(a, n_p, p0, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.pi**2*R1*d*t_ba*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)/((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return 6**(2/3)*F**(2/3)*((1/8)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/8)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/(numpy.pi*E_star**(2/3)*R1**(1/3)*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)**(1/3))


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
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/8)*numpy.pi**3*R1*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)/((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))**3


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/3)*numpy.sqrt(2)*numpy.pi**(3/2)*E_star*numpy.sqrt(R1)*d**(3/2)*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))**(3/2)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*E_star*numpy.sqrt(d)/(numpy.sqrt(numpy.pi)*numpy.sqrt(R1)*t_ba*numpy.sqrt((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (2/3)*numpy.sqrt(2)*E_star*numpy.sqrt(d)/(numpy.sqrt(numpy.pi)*numpy.sqrt(R1)*t_ba*numpy.sqrt((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    import functools
    import scipy.special

    return numpy.sqrt(2)*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - 2*x**2*((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/(numpy.pi*R1*d*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)) - 2*y**2*((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/(numpy.pi*R1*d*t_ba**2*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))]))/(numpy.sqrt(numpy.pi)*numpy.sqrt(R1)*t_ba*numpy.sqrt((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2)))


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
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2)/(t_ba**2*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))


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
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(R1)*numpy.sqrt(d)*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/numpy.sqrt((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))


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
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(R1)*numpy.sqrt(d)*t_ba*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/numpy.sqrt((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.sqrt(2)*numpy.pi**(3/2)*E_star*numpy.sqrt(R1)*numpy.sqrt(d)*numpy.sqrt(scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))/((1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 1/2, 2, 1 - t_ba**2) + (1/4)*numpy.pi*scipy.special.hyp2f1(1/2, 3/2, 2, 1 - t_ba**2))**(3/2)


def ellipse_stress_I_x(a, b_e, lam_e):
    """I_x [m^-3] = int_lam^inf dw/((a^2 + w) Delta(w)) as Carlson's (2/3) R_D.

    Chapter: (5.31). Derived from: w = lam + t in Carlson's definition of R_D.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    import scipy.special

    return (2/3)*scipy.special.elliprd(b_e**2 + lam_e, lam_e, a**2 + lam_e)


def ellipse_stress_I_y(a, b_e, lam_e):
    """I_y [m^-3] = int_lam^inf dw/((b^2 + w) Delta(w)) as Carlson's (2/3) R_D.

    Chapter: (5.31). Derived from: w = lam + t in Carlson's definition of R_D.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    import scipy.special

    return (2/3)*scipy.special.elliprd(a**2 + lam_e, lam_e, b_e**2 + lam_e)


def ellipse_stress_axis_shear_x(a, b_e, nu, p0, z):
    """Principal shear (sigma_xx - sigma_zz)/2 [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return (1/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (1/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + (1/2)*a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + (1/2)*a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_shear_x_slope(a, b_e, nu, p0, z):
    """D/dz of the principal shear (sigma_xx - sigma_zz)/2 [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) + (1/3)*a*b_e*nu*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 1/2*a*b_e*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 1/2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - 3/2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) + (1/3)*a*b_e*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + (1/2)*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2)


def ellipse_stress_axis_shear_y(a, b_e, nu, p0, z):
    """Principal shear (sigma_yy - sigma_zz)/2 [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return (1/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (1/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (1/2)*a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + (1/2)*a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_shear_y_slope(a, b_e, nu, p0, z):
    """D/dz of the principal shear (sigma_yy - sigma_zz)/2 [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return a*b_e*nu*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + (1/3)*a*b_e*nu*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 1/2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - 3/2*a*b_e*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 1/2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) + (1/3)*a*b_e*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (1/2)*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2)


def ellipse_stress_axis_sigma_xx(a, b_e, nu, p0, z):
    """Normal stress sigma_xx [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return (2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2)))


def ellipse_stress_axis_sigma_yy(a, b_e, nu, p0, z):
    """Normal stress sigma_yy [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return (2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2)))


def ellipse_stress_axis_sigma_zz(a, b_e, p0, z):
    """Normal stress sigma_zz [Pa] on the axis x = y = 0 under the elliptical Hertz pressure (semi-axes a along x, b along y).

    Chapter: (5.31), (5.41)-(5.46). Derived from: Boussinesq (5.41)-(5.46) superposed over
    (5.31) in Love's form, on the axis.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(b_e) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_axis_sigma_zz(a, b_e, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))


def ellipse_stress_axis_von_mises(a, b_e, nu, p0, z):
    """Von Mises stress (5.50) [Pa] on the axis of an elliptical Hertz contact.

    Chapter: (5.31), (5.50). Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return numpy.sqrt((1/2)*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))))**2)


def ellipse_stress_axis_von_mises_slope(a, b_e, nu, p0, z):
    """D/dz of the von Mises stress (5.50) [Pa/m] on the axis of an elliptical Hertz contact; its root is the depth of the maximum.

    Chapter: (5.31), (5.50). Derived from: the chain rule with dI/dz from the lower limit
    lam = z^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_axis_maxima_at_30_digits``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return ((1/4)*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))*(-4*a*b_e*nu*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 4*a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) - 4/3*a*b_e*nu*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + 2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) - 4/3*a*b_e*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2)) + (1/4)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))*(4*a*b_e*nu*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) + 4*a*b_e*nu*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) + (4/3)*a*b_e*nu*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)) - 2*a*b_e*p0*z/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)) + (4/3)*a*b_e*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2)) + (1/4)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))))*((4/3)*a*b_e*nu*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 4/3*a*b_e*nu*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) + 2*a*b_e*p0*z*(2*nu - 1)/((b_e**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - 2*a*b_e*p0*z*(2*nu - 1)/((a**2 + z**2)**(3/2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - 4/3*a*b_e*p0*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (4/3)*a*b_e*p0*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2) + 2*a*b_e*p0*(2*nu - 1)*(-z/numpy.sqrt(b_e**2 + z**2) - z/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))**2)))/numpy.sqrt((1/2)*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))))**2) - 2*(-1/2*a*b_e*nu*p0*z*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))) + (1/2)*a*b_e*p0*z*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))) + (1/4)*(2*a*b_e*nu*p0*z - 2*a*b_e*p0*z)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2)))))/(numpy.sqrt(a**2 + z**2)*(b_e**2 + z**2)**(3/2)*numpy.sqrt((1/2)*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))))**2)) - 2*((1/2)*a*b_e*nu*p0*z*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))) - 1/2*a*b_e*p0*z*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2))) + (1/4)*(-2*a*b_e*nu*p0*z + 2*a*b_e*p0*z)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2)))))/((a**2 + z**2)**(3/2)*numpy.sqrt(b_e**2 + z**2)*numpy.sqrt((1/2)*(-2/3*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) - 2/3*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) - a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2*a*b_e*nu*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0/(numpy.sqrt(a**2 + z**2)*numpy.sqrt(b_e**2 + z**2)))**2 + (1/2)*((2/3)*a*b_e*nu*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) - 2/3*a*b_e*nu*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - 2/3*a*b_e*p0*z*scipy.special.elliprd(a**2 + z**2, z**2, b_e**2 + z**2) + (2/3)*a*b_e*p0*z*scipy.special.elliprd(b_e**2 + z**2, z**2, a**2 + z**2) - a*b_e*p0*(2*nu - 1)/(numpy.sqrt(b_e**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))) + a*b_e*p0*(2*nu - 1)/(numpy.sqrt(a**2 + z**2)*(numpy.sqrt(a**2 + z**2) + numpy.sqrt(b_e**2 + z**2))))**2))


def ellipse_stress_cubic_lam(a, b_e, z, w1_e, d_e, lam_e):
    """Lam P2(lam) - z^2 (a^2 + lam)(b^2 + lam) [m^6], zero at lam.

    Chapter: (5.31). Derived from: g(lam) = 0 times lam (a^2 + lam)(b^2 + lam).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    z : float or ndarray
        depth below the surface [m]
    w1_e : float or ndarray
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    if (type(a) is float and type(b_e) is float and type(z) is float and type(w1_e) is float
            and type(d_e) is float and type(lam_e) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_cubic_lam(a, b_e, z, w1_e, d_e, lam_e)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return lam_e*(lam_e - w1_e)*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e)*(b_e**2 + lam_e)


def ellipse_stress_cubic_lam_slope(a, b_e, z, w1_e, d_e, lam_e):
    """D/dlam of ellipse_stress_cubic_lam [m^4].

    Chapter: (5.31). Derived from: its derivative.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    z : float or ndarray
        depth below the surface [m]
    w1_e : float or ndarray
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    """
    if (type(a) is float and type(b_e) is float and type(z) is float and type(w1_e) is float
            and type(d_e) is float and type(lam_e) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_cubic_lam_slope(a, b_e, z, w1_e, d_e, lam_e)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return lam_e*(lam_e - w1_e) + lam_e*(d_e + lam_e - w1_e) - z**2*(a**2 + lam_e) - z**2*(b_e**2 + lam_e) + (lam_e - w1_e)*(d_e + lam_e - w1_e)


def ellipse_stress_cubic_q(z, w1_e, w1_a, w1_b, d_e, q_e):
    """The same cubic [m^6] in q = lam - w1 (accurate where lam is close to w1 >= 0).

    Chapter: (5.31). Derived from: lam = w1 + q.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    z : float or ndarray
        depth below the surface [m]
    w1_e : float or ndarray
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    w1_a : float or ndarray
        a^2 + w1 >= 0 [m^2]
    w1_b : float or ndarray
        b^2 + w1 >= 0 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    q_e : float or ndarray
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    """
    if (type(z) is float and type(w1_e) is float and type(w1_a) is float and
            type(w1_b) is float and type(d_e) is float and type(q_e) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_cubic_q(z, w1_e, w1_a, w1_b, d_e, q_e)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return q_e*(d_e + q_e)*(q_e + w1_e) - z**2*(q_e + w1_a)*(q_e + w1_b)


def ellipse_stress_cubic_q_slope(z, w1_e, w1_a, w1_b, d_e, q_e):
    """D/dq of ellipse_stress_cubic_q [m^4].

    Chapter: (5.31). Derived from: its derivative.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    z : float or ndarray
        depth below the surface [m]
    w1_e : float or ndarray
        largest root w1 of P2(w) = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w), the confocal ellipse through (x, y) [m^2]
    w1_a : float or ndarray
        a^2 + w1 >= 0 [m^2]
    w1_b : float or ndarray
        b^2 + w1 >= 0 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    q_e : float or ndarray
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    """
    if (type(z) is float and type(w1_e) is float and type(w1_a) is float and
            type(w1_b) is float and type(d_e) is float and type(q_e) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_cubic_q_slope(z, w1_e, w1_a, w1_b, d_e, q_e)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return q_e*(d_e + q_e) + q_e*(q_e + w1_e) - z**2*(q_e + w1_a) - z**2*(q_e + w1_b) + (d_e + q_e)*(q_e + w1_e)


def ellipse_stress_d(a, b_e, x, y):
    """W1 - w2 [m^2] >= 0, the difference of the roots of P2.

    Chapter: (5.31). Derived from: the discriminant of P2 as a sum of squares.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if type(a) is float and type(b_e) is float and type(x) is float and type(y) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_d(a, b_e, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)


def ellipse_stress_e_sq(a, b_e, lam_e, q_e, d_e):
    """E^2 = z^2/lam [1], finite on the surface.

    Chapter: (5.31). Derived from: g(lam) = 0.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    q_e : float or ndarray
        lam - w1 >= 0, w1 the largest root of the surface quadratic P2 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    """
    if (type(a) is float and type(b_e) is float and type(lam_e) is float and
            type(q_e) is float and type(d_e) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_e_sq(a, b_e, lam_e, q_e, d_e)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return q_e*(d_e + q_e)/((a**2 + lam_e)*(b_e**2 + lam_e))


def ellipse_stress_jxx_integrand(x, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_xx (H1_xx of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    x : float or ndarray
        coordinate [m]
    w1_a : float or ndarray
        a^2 + w1 >= 0 [m^2]
    w1_b : float or ndarray
        b^2 + w1 >= 0 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : float or ndarray
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    if (type(x) is float and type(w1_a) is float and type(w1_b) is float and
            type(d_e) is float and type(v_q) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_jxx_integrand(x, w1_a, w1_b, d_e, v_q)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*(-d_e*v_q**2 - v_q**4 + v_q**2*x**2 + w1_b*x**2)/(numpy.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)**2*(v_q**2 + w1_b))


def ellipse_stress_jxy_integrand(x, y, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_xy (H1_xy of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    w1_a : float or ndarray
        a^2 + w1 >= 0 [m^2]
    w1_b : float or ndarray
        b^2 + w1 >= 0 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : float or ndarray
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    if (type(x) is float and type(y) is float and type(w1_a) is float and type(w1_b) is float
            and type(d_e) is float and type(v_q) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_jxy_integrand(x, y, w1_a, w1_b, d_e, v_q)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*x*y/(numpy.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b))


def ellipse_stress_jyy_integrand(y, w1_a, w1_b, d_e, v_q):
    """Integrand [m^-3] in v of J_yy (H1_yy of the elliptical pressure), w = w1 + v^2, v >= (lam - w1)^(1/2).

    Chapter: (5.31). Derived from: d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w)
    Delta).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    y : float or ndarray
        coordinate [m]
    w1_a : float or ndarray
        a^2 + w1 >= 0 [m^2]
    w1_b : float or ndarray
        b^2 + w1 >= 0 [m^2]
    d_e : float or ndarray
        w1 - w2 >= 0, the difference of the roots of P2 [m^2]
    v_q : float or ndarray
        integration variable v >= (lam - w1)^(1/2) of the field integrals, w = w1 + v^2 [m]
    """
    if (type(y) is float and type(w1_a) is float and type(w1_b) is float and
            type(d_e) is float and type(v_q) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_jyy_integrand(y, w1_a, w1_b, d_e, v_q)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*(-d_e*v_q**2 - v_q**4 + v_q**2*y**2 + w1_a*y**2)/(numpy.sqrt(d_e + v_q**2)*(v_q**2 + w1_a)*(v_q**2 + w1_b)**2)


def ellipse_stress_sigma_xx(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_xx):
    """Stress sigma_xx [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    I_x : float or ndarray
        integral over w > lam of dw/((a^2 + w) Delta(w)), Delta = ((a^2 + w)(b^2 + w) w)^(1/2) [m^-3]
    I_y : float or ndarray
        integral over w > lam of dw/((b^2 + w) Delta(w)) [m^-3]
    J_xx : float or ndarray
        integral over v of the H_xx integrand (ellipse_stress_jxx_integrand) [m^-2]
    """
    if (type(a) is float and type(b_e) is float and type(nu) is float and type(p0) is float
            and type(x) is float and type(y) is float and type(lam_e) is float and
            type(e_c) is float and type(I_x) is float and type(I_y) is float and
            type(J_xx) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_sigma_xx(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_xx)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return I_x*a*b_e*e_c*numpy.sqrt(lam_e)*p0 + I_y*a*b_e*e_c*numpy.sqrt(lam_e)*nu*p0 + (1/2)*J_xx*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*x**2 + 2*nu*(a**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/((a**2 + lam_e)**(5/2)*numpy.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_sigma_yy(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_yy):
    """Stress sigma_yy [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    I_x : float or ndarray
        integral over w > lam of dw/((a^2 + w) Delta(w)), Delta = ((a^2 + w)(b^2 + w) w)^(1/2) [m^-3]
    I_y : float or ndarray
        integral over w > lam of dw/((b^2 + w) Delta(w)) [m^-3]
    J_yy : float or ndarray
        integral over v of the H_yy integrand (ellipse_stress_jyy_integrand) [m^-2]
    """
    if (type(a) is float and type(b_e) is float and type(nu) is float and type(p0) is float
            and type(x) is float and type(y) is float and type(lam_e) is float and
            type(e_c) is float and type(I_x) is float and type(I_y) is float and
            type(J_yy) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_sigma_yy(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_yy)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return I_x*a*b_e*e_c*numpy.sqrt(lam_e)*nu*p0 + I_y*a*b_e*e_c*numpy.sqrt(lam_e)*p0 + (1/2)*J_yy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*y**2 + 2*nu*(b_e**2 + lam_e)**2*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))/(numpy.sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(5/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_sigma_zz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress sigma_zz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    if (type(a) is float and type(b_e) is float and type(p0) is float and type(x) is float
            and type(y) is float and type(lam_e) is float and type(e_c) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_sigma_zz(a, b_e, p0, x, y, lam_e, e_c)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*b_e*e_c**3*p0/(numpy.sqrt(a**2 + lam_e)*numpy.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_xy(a, b_e, nu, p0, x, y, lam_e, e_c, J_xy):
    """Stress tau_xy [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    J_xy : float or ndarray
        integral over v of the H_xy integrand (ellipse_stress_jxy_integrand) [m^-2]
    """
    if (type(a) is float and type(b_e) is float and type(nu) is float and type(p0) is float
            and type(x) is float and type(y) is float and type(lam_e) is float and
            type(e_c) is float and type(J_xy) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_tau_xy(a, b_e, nu, p0, x, y, lam_e, e_c, J_xy)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*J_xy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*lam_e*p0*x*y/((a**2 + lam_e)**(3/2)*(b_e**2 + lam_e)**(3/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_xz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress tau_xz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    if (type(a) is float and type(b_e) is float and type(p0) is float and type(x) is float
            and type(y) is float and type(lam_e) is float and type(e_c) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_tau_xz(a, b_e, p0, x, y, lam_e, e_c)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*b_e*e_c**2*numpy.sqrt(lam_e)*p0*x/((a**2 + lam_e)**(3/2)*numpy.sqrt(b_e**2 + lam_e)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_tau_yz(a, b_e, p0, x, y, lam_e, e_c):
    """Stress tau_yz [Pa] at (x, y, z) under the elliptical Hertz pressure, from the ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J.

    Chapter: (5.31), (5.41)-(5.46). Derived from: psi1 of the ellipse (Johnson 1985, 3.6) in
    Love's form of Boussinesq, derivatives under the integral sign, z = e lam^(1/2).

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    lam_e : float or ndarray
        ellipsoidal coordinate lambda >= 0 of the field point: the largest root of x^2/(a^2 + lam) + y^2/(b^2 + lam) + z^2/lam = 1 [m^2]
    e_c : float or ndarray
        z/lam^(1/2) in [0, 1] (finite on the surface, where z and lam vanish) [1]
    """
    if (type(a) is float and type(b_e) is float and type(p0) is float and type(x) is float
            and type(y) is float and type(lam_e) is float and type(e_c) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_tau_yz(a, b_e, p0, x, y, lam_e, e_c)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*b_e*e_c**2*numpy.sqrt(lam_e)*p0*y/(numpy.sqrt(a**2 + lam_e)*(b_e**2 + lam_e)**(3/2)*(e_c**2 + lam_e*(x**2/(a**2 + lam_e)**2 + y**2/(b_e**2 + lam_e)**2)))


def ellipse_stress_w1(a, b_e, x, y):
    """Largest root w1 [m^2] of the surface quadratic P2 at (x, y) (< 0 inside the contact ellipse, > 0 outside).

    Chapter: (5.31). Derived from: P2 = w^2 + beta w + gamma.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if type(a) is float and type(b_e) is float and type(x) is float and type(y) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_w1(a, b_e, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.where(numpy.less_equal(a**2 + b_e**2 - x**2 - y**2, 0), -1/2*a**2 - 1/2*b_e**2 + (1/2)*x**2 + (1/2)*y**2 + (1/2)*numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2), (-2*a**2*b_e**2 + 2*a**2*y**2 + 2*b_e**2*x**2)/(a**2 + b_e**2 - x**2 - y**2 + numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)))


def ellipse_stress_w1_a(a, b_e, x, y):
    """A^2 + w1 [m^2] >= 0.

    Chapter: (5.31). Derived from: P2 shifted by a^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if type(a) is float and type(b_e) is float and type(x) is float and type(y) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_w1_a(a, b_e, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*x**2 + (1/2)*y**2 + (1/2)*(a - b_e)*(a + b_e) + (1/2)*numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)


def ellipse_stress_w1_b(a, b_e, x, y):
    """B^2 + w1 [m^2] >= 0.

    Chapter: (5.31). Derived from: P2 shifted by b^2.

    Derivation: ``hertzmdr.derive.ellipse_stress``. Verified by
    ``tests/test_ellipse_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    b_e : float or ndarray
        semi-axis b <= a of an elliptical contact, along y (a along x) [m]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    if type(a) is float and type(b_e) is float and type(x) is float and type(y) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_ellipse_stress_w1_b(a, b_e, x, y)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.where(numpy.greater_equal(-a**2 + b_e**2 + x**2 + y**2, 0), -1/2*a**2 + (1/2)*b_e**2 + (1/2)*x**2 + (1/2)*y**2 + (1/2)*numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2), 2*y**2*(a - b_e)*(a + b_e)/(a**2 - b_e**2 - x**2 - y**2 + numpy.sqrt(4*x**2*y**2 + (a**2 - b_e**2 - x**2 + y**2)**2)))


def fit_adhesive_cone_depth(E_star, theta, a, rho_g):
    """Indentation depth d [m] of a cone in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: adhesion_cone_depth at
    Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_depth(E_star, theta, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*a*numpy.tan(theta) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*rho_g/numpy.sqrt(E_star)


def fit_adhesive_cone_depth_da(E_star, theta, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a cone: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: adhesion_cone_depth
    differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_radius_by_mpmath``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_depth_da(E_star, theta, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi*numpy.tan(theta) - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g/(numpy.sqrt(E_star)*numpy.sqrt(a))


def fit_adhesive_cone_force(E_star, theta, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a cone in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from:
    adhesion_cone_force_from_radius at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float and type(z_p) is float and type(F_0) is float and
            type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_force(E_star, theta, a, rho_g, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*rho_g + (1/2)*numpy.pi*E_star*a**2*numpy.tan(theta) + F_0 + s_0*z_p


def fit_adhesive_cone_force_dE(E_star, theta, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a cone at a fixed position.

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_force_dE(E_star, theta, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*(numpy.pi**2*E_star**(5/2)*a**(5/2)*numpy.tan(theta)**2 + 16*numpy.pi*E_star**(3/2)*a**(3/2)*rho_g**2 - 5*numpy.sqrt(2)*numpy.pi**(3/2)*E_star**2*a**2*rho_g*numpy.tan(theta))/(numpy.pi*E_star**(5/2)*numpy.sqrt(a)*numpy.tan(theta) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*rho_g)


def fit_adhesive_cone_force_ddgamma(E_star, theta, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a cone at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_force_ddgamma(E_star, theta, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*numpy.pi*E_star*a**(3/2)/(numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*rho_g - numpy.pi*E_star*numpy.sqrt(a)*numpy.tan(theta))


def fit_adhesive_cone_force_dz0(E_star, theta, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a cone at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive cone, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_cone_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_cone.py::test_adhesive_cone_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(theta) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_cone_force_dz0(E_star, theta, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(-numpy.pi*E_star**(3/2)*a**(3/2)*numpy.tan(theta) + 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a*rho_g)/(numpy.pi*numpy.sqrt(E_star)*numpy.sqrt(a)*numpy.tan(theta) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g)


def fit_adhesive_powerlaw_depth(E_star, c_n, kappa_n, n, a, rho_g):
    """Indentation depth d [m] of a power-law tip in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_depth at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_depth(E_star, c_n, kappa_n, n, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a**n*c_n*kappa_n - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*rho_g/numpy.sqrt(E_star)


def fit_adhesive_powerlaw_depth_da(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a power-law tip: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_depth differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_powerlaw.py::test_adhesive_powerlaw_radius_by_mpmath``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_depth_da(E_star, c_n, kappa_n, n, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a**n*c_n*kappa_n*n/a - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g/(numpy.sqrt(E_star)*numpy.sqrt(a))


def fit_adhesive_powerlaw_force(E_star, c_n, kappa_n, n, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a power-law tip in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from:
    adhesion_powerlaw_force_from_radius at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float and
            type(z_p) is float and type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_force(E_star, c_n, kappa_n, n, a, rho_g, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F_0 + s_0*z_p + 2*(-numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*n*rho_g - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*rho_g + E_star*a**(n + 1)*c_n*kappa_n*n)/(n + 1)


def fit_adhesive_powerlaw_force_dE(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a power-law tip at a fixed position.

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_force_dE(E_star, c_n, kappa_n, n, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(2*E_star**(5/2)*a**(2*n + 3/2)*c_n**2*kappa_n**2*n**2 + 4*numpy.pi*E_star**(3/2)*a**(5/2)*n*rho_g**2 + 4*numpy.pi*E_star**(3/2)*a**(5/2)*rho_g**2 - 2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n**2*rho_g - 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*a**(n + 2)*c_n*kappa_n*n*rho_g)/((n + 1)*(2*E_star**(5/2)*a**(n + 1/2)*c_n*kappa_n*n - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*a*rho_g))


def fit_adhesive_powerlaw_force_ddgamma(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a power-law tip at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in Delta
    gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_force_ddgamma(E_star, c_n, kappa_n, n, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*numpy.pi*E_star*a**(5/2)/(numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a*rho_g - 2*E_star*a**(n + 1/2)*c_n*kappa_n*n)


def fit_adhesive_powerlaw_force_dz0(E_star, c_n, kappa_n, n, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a power-law tip at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive power law, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of adhesion_powerlaw_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_powerlaw.py::
    test_adhesive_powerlaw_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_powerlaw_force_dz0(E_star, c_n, kappa_n, n, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(-2*E_star**(3/2)*a**(n + 3/2)*c_n*kappa_n*n + 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a**2*rho_g)/(2*numpy.sqrt(E_star)*a**(n + 1/2)*c_n*kappa_n*n - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*a*rho_g)


def fit_adhesive_sampled_depth(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Indentation depth d [m] of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: g(a) - Delta l
    at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_depth(E_star, g_a, g_slope, g_integral, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return g_a - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*rho_g/numpy.sqrt(E_star)


def fit_adhesive_sampled_depth_da(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]): Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: g(a) - Delta l
    differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sampled.py::test_adhesive_sampled_radius_by_mpmath``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_depth_da(E_star, g_a, g_slope, g_integral, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return g_slope - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g/(numpy.sqrt(E_star)*numpy.sqrt(a))


def fit_adhesive_sampled_force(E_star, g_a, g_slope, g_integral, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: 2 E* (a d -
    G(a)) at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float and
            type(z_p) is float and type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_force(E_star, g_a, g_slope, g_integral, a, rho_g, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*rho_g + 2*E_star*a*g_a - 2*E_star*g_integral + F_0 + s_0*z_p


def fit_adhesive_sampled_force_dE(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position.

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_force_dE(E_star, g_a, g_slope, g_integral, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(2*E_star**(3/2)*a**(3/2)*g_a*g_slope - 2*E_star**(3/2)*numpy.sqrt(a)*g_integral*g_slope + 4*numpy.pi*numpy.sqrt(E_star)*a**(3/2)*rho_g**2 - 2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a**2*g_slope*rho_g - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a*g_a*rho_g + numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*g_integral*rho_g)/(2*E_star**(3/2)*numpy.sqrt(a)*g_slope - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*rho_g)


def fit_adhesive_sampled_force_ddgamma(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_force_ddgamma(E_star, g_a, g_slope, g_integral, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -4*numpy.pi*numpy.sqrt(E_star)*a**(3/2)/(2*numpy.sqrt(E_star)*numpy.sqrt(a)*g_slope - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g)


def fit_adhesive_sampled_force_dz0(E_star, g_a, g_slope, g_integral, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of any tip of MDR profile g (g_a = g(a), g_slope = g'(a), g_integral = G(a), the integral of g over [0, a]) at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive MDR of any g, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of 2 E* (a d - G(a)) in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sampled.py::t
    est_adhesive_sampled_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_a : float or ndarray
        MDR profile g(a) at the contact radius (5.55) [m]
    g_slope : float or ndarray
        slope g'(a) of the MDR profile at the contact radius [1]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(g_a) is float and type(g_slope) is float and
            type(g_integral) is float and type(a) is float and type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sampled_force_dz0(E_star, g_a, g_slope, g_integral, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(-2*E_star**(3/2)*a**(3/2)*g_slope + 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a*rho_g)/(2*numpy.sqrt(E_star)*numpy.sqrt(a)*g_slope - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g)


def fit_adhesive_sphere_depth(E_star, R, a, rho_g):
    """Indentation depth d [m] of an exact sphere (spherical cap) in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: sphere_depth
    less Delta l at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_depth(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.arctanh(a/R) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*rho_g/numpy.sqrt(E_star)


def fit_adhesive_sphere_depth_da(E_star, R, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of an exact sphere (spherical cap): Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: sphere_depth
    less Delta l differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_radius_by_mpmath``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_depth_da(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.arctanh(a/R) + a/(R*(1 - a**2/R**2)) - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g/(numpy.sqrt(E_star)*numpy.sqrt(a))


def fit_adhesive_sphere_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on an exact sphere (spherical cap) in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from:
    sphere_force_from_radius less 2 E* a Delta l at Delta gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_adhesive_sphere.py::test_adhesive_sphere_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float and type(z_p) is float and type(F_0) is float and
            type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_force(E_star, R, a, rho_g, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*rho_g + E_star*(R**2*numpy.arctanh(a/R) - R*a + a**2*numpy.arctanh(a/R)) + F_0 + s_0*z_p


def fit_adhesive_sphere_force_dE(E_star, R, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position.

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_force_dE(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2*E_star**(5/2)*R**4*numpy.sqrt(a)*numpy.arctanh(a/R)**2 - 2*E_star**(5/2)*R**2*a**(5/2) + 4*E_star**(5/2)*R*a**(7/2)*numpy.arctanh(a/R) - 2*E_star**(5/2)*a**(9/2)*numpy.arctanh(a/R)**2 + 8*numpy.pi*E_star**(3/2)*R**2*a**(3/2)*rho_g**2 - 8*numpy.pi*E_star**(3/2)*a**(7/2)*rho_g**2 - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R**4*rho_g*numpy.arctanh(a/R) + numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R**3*a*rho_g - 4*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R**2*a**2*rho_g*numpy.arctanh(a/R) - 5*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R*a**3*rho_g + 5*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*a**4*rho_g*numpy.arctanh(a/R))/(2*E_star**(5/2)*R**2*numpy.sqrt(a)*numpy.arctanh(a/R) + 2*E_star**(5/2)*R*a**(3/2) - 2*E_star**(5/2)*a**(5/2)*numpy.arctanh(a/R) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R**2*rho_g + numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*a**2*rho_g)


def fit_adhesive_sphere_force_ddgamma(E_star, R, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_force_ddgamma(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*numpy.pi*E_star*a**(3/2)*(-R**2 + a**2)/(-numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*R**2*rho_g + numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**2*rho_g + 2*E_star*R**2*numpy.sqrt(a)*numpy.arctanh(a/R) + 2*E_star*R*a**(3/2) - 2*E_star*a**(5/2)*numpy.arctanh(a/R))


def fit_adhesive_sphere_force_dz0(E_star, R, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of an exact sphere (spherical cap) at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), adhesive exact sphere, fit model. Derived from: implicit
    differentiation at d(a) = z_p - z_0 of sphere_force_from_radius less 2 E* a Delta l in
    z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by ``tests/test_fit_adhesive_sphere.py::te
    st_adhesive_sphere_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_adhesive_sphere_force_dz0(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(-2*E_star**(3/2)*R**2*a**(3/2)*numpy.arctanh(a/R) - 2*E_star**(3/2)*R*a**(5/2) + 2*E_star**(3/2)*a**(7/2)*numpy.arctanh(a/R) + 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*R**2*a*rho_g - 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*a**3*rho_g)/(2*numpy.sqrt(E_star)*R**2*numpy.sqrt(a)*numpy.arctanh(a/R) + 2*numpy.sqrt(E_star)*R*a**(3/2) - 2*numpy.sqrt(E_star)*a**(5/2)*numpy.arctanh(a/R) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*R**2*rho_g + numpy.sqrt(2)*numpy.sqrt(numpy.pi)*a**2*rho_g)


def fit_cone_force(E_star, theta, z_p, z_0, F_0, s_0):
    """Force F [N] on a rigid cone at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    import functools

    if (type(E_star) is float and type(theta) is float and type(z_p) is float and
            type(z_0) is float and type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_cone_force(E_star, theta, z_p, z_0, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*functools.reduce(numpy.maximum, [0, -z_0 + z_p])**2/(numpy.pi*numpy.tan(theta)) + F_0 + s_0*z_p


def fit_cone_force_dE(theta, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a rigid cone.

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if type(theta) is float and type(z_p) is float and type(z_0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_cone_force_dE(theta, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*functools.reduce(numpy.maximum, [0, -z_0 + z_p])**2/(numpy.pi*numpy.tan(theta))


def fit_cone_force_dz0(E_star, theta, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a rigid cone (0 for d <= 0).

    Chapter: (5.40), fit model. Derived from: (5.40) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if (type(E_star) is float and type(theta) is float and type(z_p) is float and
            type(z_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_cone_force_dz0(E_star, theta, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -4*E_star*(numpy.where(numpy.greater_equal(z_0 - z_p, 0), 0, 1))*functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(numpy.pi*numpy.tan(theta))


def fit_hertz_force(E_star, R, z_p, z_0, F_0, s_0):
    """Force F [N] on a paraboloidal (Hertz) tip at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    import functools

    if (type(E_star) is float and type(R) is float and type(z_p) is float and
            type(z_0) is float and type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_hertz_force(E_star, R, z_p, z_0, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*numpy.sqrt(R)*functools.reduce(numpy.maximum, [0, -z_0 + z_p])**(3/2) + F_0 + s_0*z_p


def fit_hertz_force_dE(R, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a paraboloidal (Hertz) tip.

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if type(R) is float and type(z_p) is float and type(z_0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_hertz_force_dE(R, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*numpy.sqrt(R)*functools.reduce(numpy.maximum, [0, -z_0 + z_p])**(3/2)


def fit_hertz_force_dz0(E_star, R, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a paraboloidal (Hertz) tip (0 for d <= 0).

    Chapter: (5.23), fit model. Derived from: (5.23) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if (type(E_star) is float and type(R) is float and type(z_p) is float and
            type(z_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_hertz_force_dz0(E_star, R, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*E_star*numpy.sqrt(R)*(numpy.where(numpy.greater_equal(z_0 - z_p, 0), 0, 1))*numpy.sqrt(functools.reduce(numpy.maximum, [0, -z_0 + z_p]))


def fit_jkr_depth(E_star, R, a, rho_g):
    """Indentation depth d [m] of a paraboloid in adhesive contact of radius a, Delta gamma = rho_g^2.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_depth at Delta gamma =
    rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_depth(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a**2/R - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*rho_g/numpy.sqrt(E_star)


def fit_jkr_depth_da(E_star, R, a, rho_g):
    """Derivative dd/da [1] of the adhesive depth of a paraboloid: Newton's slope for a at a depth (0 at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_depth differentiated in a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_radius_by_mpmath``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_depth_da(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a/R - 1/2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*rho_g/(numpy.sqrt(E_star)*numpy.sqrt(a))


def fit_jkr_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """Force F [N] on a paraboloid in adhesive contact of radius a at the position z_p, plus the baseline F_0 + s_0 z_p.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: jkr_force_from_radius at Delta
    gamma = rho_g^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_model_by_mpmath_parametric``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float and type(z_p) is float and type(F_0) is float and
            type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_force(E_star, R, a, rho_g, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*rho_g + (4/3)*E_star*a**3/R + F_0 + s_0*z_p


def fit_jkr_force_dE(E_star, R, a, rho_g):
    """Derivative dF/dE* [m^2] of the adhesive fit model of a paraboloid at a fixed position.

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_force_dE(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*(4*E_star**(5/2)*a**(9/2) + 6*numpy.pi*E_star**(3/2)*R**2*a**(3/2)*rho_g**2 - 7*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R*a**3*rho_g)/(R*(4*E_star**(5/2)*a**(3/2) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star**2*R*rho_g))


def fit_jkr_force_ddgamma(E_star, R, a, rho_g):
    """Derivative dF/dDelta gamma [m] of the adhesive fit model of a paraboloid at a fixed position (-2 pi a/g'(a) at Delta gamma = 0).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in Delta gamma.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_force_ddgamma(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*numpy.pi*E_star*R*a**(3/2)/(numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*R*rho_g - 4*E_star*a**(3/2))


def fit_jkr_force_dz0(E_star, R, a, rho_g):
    """Derivative dF/dz_0 [N/m] of the adhesive fit model of a paraboloid at a fixed position (-dF/dd: infinite at the depth-controlled pull-off).

    Chapter: (5.55), (5.57), JKR, fit model. Derived from: implicit differentiation at d(a)
    = z_p - z_0 of jkr_force_from_radius in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit_jkr.py::test_jkr_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    rho_g : float or ndarray
        square root of the work of adhesion, sqrt(Delta gamma) (the JKR fit model's relations are written in it: no sqrt of a sum) [(J/m^2)^(1/2)]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(rho_g) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_jkr_force_dz0(E_star, R, a, rho_g)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(-4*E_star**(3/2)*a**(5/2) + 3*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*E_star*R*a*rho_g)/(4*numpy.sqrt(E_star)*a**(3/2) - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*R*rho_g)


def fit_powerlaw_force(E_star, c_n, kappa_n, n, z_p, z_0, F_0, s_0):
    """Force F [N] on a power-law tip at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    import functools

    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(z_p) is float and type(z_0) is float and
            type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_powerlaw_force(E_star, c_n, kappa_n, n, z_p, z_0, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*n*(functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(c_n*kappa_n))**(n**(-1.0))*functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(n + 1) + F_0 + s_0*z_p


def fit_powerlaw_force_dE(c_n, kappa_n, n, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a power-law tip.

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if (type(c_n) is float and type(kappa_n) is float and type(n) is float and
            type(z_p) is float and type(z_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_powerlaw_force_dE(c_n, kappa_n, n, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*n*(functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(c_n*kappa_n))**(n**(-1.0))*functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(n + 1)


def fit_powerlaw_force_dz0(E_star, c_n, kappa_n, n, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a power-law tip (0 for d <= 0).

    Chapter: Problem 7(d), fit model. Derived from: Problem 7(d) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float and type(z_p) is float and type(z_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_powerlaw_force_dz0(E_star, c_n, kappa_n, n, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*E_star*(functools.reduce(numpy.maximum, [0, -z_0 + z_p])/(c_n*kappa_n))**(n**(-1.0))*(numpy.where(numpy.greater_equal(z_0 - z_p, 0), 0, 1))


def fit_punch_force(E_star, a, z_p, z_0, F_0, s_0):
    """Force F [N] on a flat punch at the position z_p: the tip's force at d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p.

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_model_by_forward_models``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    import functools

    if (type(E_star) is float and type(a) is float and type(z_p) is float and
            type(z_0) is float and type(F_0) is float and type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_punch_force(E_star, a, z_p, z_0, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a*functools.reduce(numpy.maximum, [0, -z_0 + z_p]) + F_0 + s_0*z_p


def fit_punch_force_dE(a, z_p, z_0):
    """Derivative dF/dE* [m^2] of the fit model of a flat punch.

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0),
    differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    import functools

    if type(a) is float and type(z_p) is float and type(z_0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_punch_force_dE(a, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*functools.reduce(numpy.maximum, [0, -z_0 + z_p])


def fit_punch_force_dz0(E_star, a, z_p, z_0):
    """Derivative dF/dz_0 [N/m] of the fit model of a flat punch (0 for d <= 0).

    Chapter: Problem 7(a), fit model. Derived from: Problem 7(a) at d = max(0, z_p - z_0),
    differentiated in z_0.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    z_0 : float or ndarray
        contact point: the position z_p where the tip first touches the sample [m]
    """
    if (type(E_star) is float and type(a) is float and type(z_p) is float and
            type(z_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_punch_force_dz0(E_star, a, z_p, z_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*E_star*a*(numpy.where(numpy.greater_equal(z_0 - z_p, 0), 0, 1))


def fit_pyramid_cone_angle(alpha_p, n_sides):
    """Angle theta [rad] between the surface and the plane of the cone with the cross-section area of a regular pyramid (n_sides faces, half-angle alpha_p) at every depth: the pyramid's equivalent cone.

    Chapter: (5.38), equal area. Derived from: pi (d cot(theta))^2 = n (d tan(alpha_p))^2
    tan(pi/n).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_pyramid_cone_by_polygon_area``.

    Parameters
    ----------
    alpha_p : float or ndarray
        half-angle of a regular pyramid: between its axis and the mid-line of a face [rad]
    n_sides : float or ndarray
        number of faces of a regular pyramid (4: most AFM tips; 3: Berkovich) [1]
    """
    if type(alpha_p) is float and type(n_sides) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_pyramid_cone_angle(alpha_p, n_sides)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.arctan(numpy.sqrt(numpy.pi)/(numpy.sqrt(n_sides)*numpy.tan(alpha_p)*numpy.sqrt(numpy.tan(numpy.pi/n_sides))))


def fit_pyramid_force_cone_angle(alpha_p, n_sides, beta_p):
    """Angle theta [rad] between the surface and the plane of the cone whose force (5.40) is beta_p times the equal-area cone's: a regular pyramid's force law, beta_p from the BEM.

    Chapter: (5.40), equal force. Derived from: (2/pi) E* d^2 / tan(theta) = beta_p (2/pi)
    E* d^2 / tan(theta_area).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_pyramid_force_by_bem``.

    Parameters
    ----------
    alpha_p : float or ndarray
        half-angle of a regular pyramid: between its axis and the mid-line of a face [rad]
    n_sides : float or ndarray
        number of faces of a regular pyramid (4: most AFM tips; 3: Berkovich) [1]
    beta_p : float or ndarray
        a regular pyramid's force over its equal-area cone's at the same depth (by the BEM, docs/pyramid.md) [1]
    """
    if type(alpha_p) is float and type(n_sides) is float and type(beta_p) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_pyramid_force_cone_angle(alpha_p, n_sides, beta_p)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.arctan(numpy.sqrt(numpy.pi)/(beta_p*numpy.sqrt(n_sides)*numpy.tan(alpha_p)*numpy.sqrt(numpy.tan(numpy.pi/n_sides))))


def fit_sample_modulus(E_star, nu1, E2, nu2):
    """Young's modulus E1 [Pa] of the sample (body 1) under an elastic tip (body 2, E2, nu2), from the fitted E*.

    Chapter: (5.26), inverted. Derived from: (5.26) solved for E1.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    E2 : float or ndarray
        Young's modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(E_star) is float and type(nu1) is float and type(E2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sample_modulus(E_star, nu1, E2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E2*E_star*(1 - nu1**2)/(E2 + E_star*nu2**2 - E_star)


def fit_sample_modulus_dE(E_star, nu1, E2, nu2):
    """Derivative dE1/dE* [1] of the sample's modulus under an elastic tip.

    Chapter: (5.26), inverted. Derived from: (5.26) solved for E1, differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    E2 : float or ndarray
        Young's modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(E_star) is float and type(nu1) is float and type(E2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sample_modulus_dE(E_star, nu1, E2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -E2**2*nu1**2/(E2 + E_star*nu2**2 - E_star)**2 + E2**2/(E2 + E_star*nu2**2 - E_star)**2


def fit_sample_modulus_rigid(E_star, nu):
    """Young's modulus E [Pa] of the sample under a rigid tip, from the fitted E*.

    Chapter: (5.8), inverted. Derived from: (5.8) solved for E.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(E_star) is float and type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sample_modulus_rigid(E_star, nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*(1 - nu**2)


def fit_sample_modulus_rigid_dE(nu):
    """Derivative dE/dE* [1] of the sample's modulus under a rigid tip.

    Chapter: (5.8), inverted. Derived from: (5.8) solved for E, differentiated in E*.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sample_modulus``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sample_modulus_rigid_dE(nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 1 - nu**2


def fit_sphere_depth(lam, a):
    """Indentation depth d [m] of the exact sphere at lam = atanh(a/R) and its contact radius a = R tanh(lam), both given: the function of Newton's iteration for lam at a given depth.

    Chapter: (5.55). Derived from: (5.55), d = a atanh(a/R), at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : float or ndarray
        contact radius [m]
    """
    if type(lam) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_depth(lam, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*lam


def fit_sphere_depth_dlam(R, lam, a):
    """Derivative dd/dlam [m] of the exact sphere's depth d = R lam tanh(lam) at lam and a = R tanh(lam), both given: the slope of Newton's iteration for lam at a given depth.

    Chapter: (5.55). Derived from: (5.55) at a = R tanh(lam), differentiated in lam;
    sech(lam)^2 as (R - a)(R + a)/R^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : float or ndarray
        contact radius [m]
    """
    if type(R) is float and type(lam) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_depth_dlam(R, lam, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : float or ndarray
        contact radius [m]
    z_p : float or ndarray
        position of the tip's base (piezo), increasing into the sample [m]
    F_0 : float or ndarray
        force baseline: the force at z_p = 0 before contact [N]
    s_0 : float or ndarray
        slope of the force baseline before contact (drift, drag) [N/m]
    """
    if (type(E_star) is float and type(R) is float and type(lam) is float and
            type(a) is float and type(z_p) is float and type(F_0) is float and
            type(s_0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_force(E_star, R, lam, a, z_p, F_0, s_0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*numpy.where(numpy.less(lam, 1/2), R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/((1/15)*lam**2 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam, -R*a + lam*(R**2 + a**2)) + F_0 + s_0*z_p


def fit_sphere_force_dE(R, lam, a):
    """Derivative dF/dE* [m^2] of the fit model of the exact sphere.

    Chapter: (5.57), fit model. Derived from: (5.57) differentiated in E* at lam =
    atanh(a/R) and the contact radius a = R tanh(lam), both given (the fit computes tanh
    once per point); below lam = 1/2 as fit_sphere_force.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_fit_force_by_mpmath``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    a : float or ndarray
        contact radius [m]
    """
    if type(R) is float and type(lam) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_force_dE(R, lam, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.where(numpy.less(lam, 1/2), R**2*lam**3/(lam**2 + lam**2/(lam**2/(lam**2/(lam**2/(lam**2/((1/15)*lam**2 + 13) + 11) + 9) + 7) + 5) + 3) + a**2*lam, -R*a + lam*(R**2 + a**2))


def fit_sphere_force_dz0(E_star, a):
    """Derivative dF/dz_0 [N/m] of the fit model of the exact sphere at the contact radius a = R tanh(lam) (0 at a = 0, no contact).

    Chapter: (5.55), (5.57), fit model. Derived from: -(dF/dlam)/(dd/dlam) of (5.57) and
    (5.55), simplified to -2 E* a.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_jacobian_by_mpmath_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_force_dz0(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*E_star*a


def fit_sphere_radius_dlam(R, a):
    """Derivative da/dlam [m] of the exact sphere's contact radius a = R tanh(lam) at a given: the contact radius at Newton's last step for lam, a + (da/dlam) step, to an ulp for a step below 1e-8 lam, without a tanh.

    Chapter: (5.55). Derived from: a = R tanh(lam) differentiated in lam, sech(lam)^2 as (R
    - a)(R + a)/R^2.

    Derivation: ``hertzmdr.derive.fit``. Verified by
    ``tests/test_fit.py::test_sphere_lam_by_newton``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_fit_sphere_radius_dlam(R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (R - a)*(R + a)/R


def flamant_sigma_xx(F_L, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : float or ndarray
        normal force per unit length of a line contact [N/m]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(F_L) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_flamant_sigma_xx(F_L, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*F_L*x**2*z/(numpy.pi*(x**2 + z**2)**2)


def flamant_sigma_zz(F_L, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : float or ndarray
        normal force per unit length of a line contact [N/m]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(F_L) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_flamant_sigma_zz(F_L, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*F_L*z**3/(numpy.pi*(x**2 + z**2)**2)


def flamant_tau_xz(F_L, x, z):
    """Shear stress tau_xz [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the half-plane z > 0 (plane strain, tension positive).

    Chapter: Flamant (2-D Boussinesq). Derived from: the Airy function phi = -(P/pi) x
    atan(x/z) of a line load.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_flamant_is_an_elastic_field``.

    Parameters
    ----------
    F_L : float or ndarray
        normal force per unit length of a line contact [N/m]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(F_L) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_flamant_tau_xz(F_L, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*F_L*x*z**2/(numpy.pi*(x**2 + z**2)**2)


def flat_punch_tangential_traction(r, a, G_star, u_x):
    """Tangential traction q(r) [Pa] of a stuck flat punch (all springs stick, u_x < mu d E*/G*).

    Chapter: MDR tangential, flat punch (not in the chapter). Derived from: (5.59) of q_x =
    G* u_x on |x| < a: the jump at a is a delta in q_x'.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(r) is float and type(a) is float and type(G_star) is float and
            type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_flat_punch_tangential_traction(r, a, G_star, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return G_star*u_x/(numpy.pi*numpy.sqrt(a**2 - r**2))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_cone_prefactor(E_star, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star/(numpy.pi*numpy.tan(theta))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    """
    if type(E_star) is float and type(theta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_cone_stiffness_prefactor(E_star, theta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*E_star/(numpy.pi*numpy.tan(theta))


def force_law_ellipse_exponent():
    """Exponent n [1] of the force law F = K d^n of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, F = K d^n. Derived from: the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_ellipse_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return 3/2


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (2/3)*numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/scipy.special.ellipk(1 - t_ba**2)**(3/2)


def force_law_ellipse_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio).

    Chapter: (5.23), exact ellipse, differentiated. Derived from: the logarithmic slope of
    dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return 1/2


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/scipy.special.ellipk(1 - t_ba**2)**(3/2)


def force_law_hertz_exponent():
    """Exponent n [1] of the force law F = K d^n of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), F = K d^n. Derived from: the logarithmic slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_hertz_law_by_pressure_quadrature``.

    A constant: no parameters.
    """
    return 3/2


def force_law_hertz_prefactor(E_star, R):
    """Prefactor K [N/m^n] of the force law F = K d^n of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), F = K d^n. Derived from: F/d^n with n the logarithmic slope d F'/F of
    the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_hertz_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_hertz_prefactor(E_star, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*numpy.sqrt(R)


def force_law_hertz_stiffness_exponent():
    """Exponent n - 1 [1] of the stiffness law of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    A constant: no parameters.
    """
    return 1/2


def force_law_hertz_stiffness_prefactor(E_star, R):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a Hertz contact (effective sphere of radius R).

    Chapter: (5.23), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the logarithmic
    slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_hertz_stiffness_prefactor(E_star, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(R)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    """
    if type(E_star) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_line_prefactor(E_star)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*E_star


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    """
    if type(E_star) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_line_stiffness_prefactor(E_star)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*E_star


def force_law_powerlaw_exponent(n):
    """Exponent n [1] of the force law F = K d^n of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), F = K d^n. Derived from: the logarithmic slope d F'/F of the
    force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_powerlaw_law_by_pressure_quadrature``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_powerlaw_exponent(n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (n + 1)/n


def force_law_powerlaw_prefactor(E_star, c_n, kappa_n, n):
    """Prefactor K [N/m^n] of the force law F = K d^n of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), F = K d^n. Derived from: F/d^n with n the logarithmic slope d
    F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_powerlaw_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_powerlaw_prefactor(E_star, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*n*(1/(c_n*kappa_n))**(n**(-1.0))/(n + 1)


def force_law_powerlaw_stiffness_exponent(n):
    """Exponent n - 1 [1] of the stiffness law of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), differentiated. Derived from: the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_powerlaw_stiffness_exponent(n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return n**(-1.0)


def force_law_powerlaw_stiffness_prefactor(E_star, c_n, kappa_n, n):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa).

    Chapter: Problem 7(d), differentiated. Derived from: (dF/dd)/d^(n_k) with n_k the
    logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(c_n) is float and type(kappa_n) is float and
            type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_powerlaw_stiffness_prefactor(E_star, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*(1/(c_n*kappa_n))**(n**(-1.0))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_punch_prefactor(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_force_law_punch_stiffness_prefactor(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a


def hertz_contact_radius(R, d):
    """Contact radius a [m] of a Hertz contact at depth d.

    Chapter: (5.21). Derived from: the matching condition (5.19).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_contact_radius(R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R)*numpy.sqrt(d)


def hertz_contact_radius_from_force(E_star, F, R):
    """Contact radius a [m] of a Hertz contact under the force F.

    Chapter: (5.24). Derived from: (5.21) at the depth of (5.23) inverted.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(F) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_contact_radius_from_force(E_star, F, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*6**(1/3)*F**(1/3)*R**(1/3)/E_star**(1/3)


def hertz_depth_from_force(E_star, F, R):
    """Indentation depth d [m] of a Hertz contact under the force F.

    Chapter: (5.23), inverted. Derived from: (5.23) solved for d.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(F) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_depth_from_force(E_star, F, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*6**(2/3)*F**(2/3)/(E_star**(2/3)*R**(1/3))


def hertz_displacement_inside(R, d, r):
    """Surface displacement u_z(r) [m] inside a Hertz contact (r <= a).

    Chapter: (5.18). Derived from: (5.16) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_displacement_inside(R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return d - 1/2*r**2/R


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return 2*d*(-1/3*numpy.sqrt(R)*numpy.sqrt(d)*scipy.special.hyp2f1(1/2, 3/2, 5/2, R*d/r**2)/r + numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r))/numpy.pi


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_displacement_outside_elementary(R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*d*(numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r) - 1/2*r**2*(-numpy.sqrt(R)*numpy.sqrt(d)*numpy.sqrt(-R*d/r**2 + 1)/r + numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r))/(R*d))/numpy.pi


def hertz_displacement_outside_series(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact, its Taylor series in z = a^2/r^2 to 22 terms: for r >= 2a (z <= 1/4) the truncation is below 1.3e-17 relative.

    Chapter: Fig. 5.2, Problem 7(b), r >= 2a. Derived from: the series of the stable far
    form (2F1(1/2, 3/2; 5/2; z) and asin).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_outside_forms_by_mpmath``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_displacement_outside_series(R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*numpy.sqrt(R)*d**(3/2)*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*((4485482287/35459249995776)*R*d/r**2 + 34461632205/242304874971136)/r**2 + 1472719325/9156870275072)/r**2 + 756261275/4131758538752)/r**2 + 116680311/556198264832)/r**2 + 20036013/82678120448)/r**2 + 3231615/11442061312)/r**2 + 5014575/15082717184)/r**2 + 1300075/3284140032)/r**2 + 676039/1415577600)/r**2 + 88179/150732800)/r**2 + 46189/63307776)/r**2 + 12155/13074432)/r**2 + 6435/5292032)/r**2 + 143/87040)/r**2 + 77/33280)/r**2 + 63/18304)/r**2 + 35/6336)/r**2 + 5/504)/r**2 + 3/140)/r**2 + 1/15)/r**2 + 2/3)/(numpy.pi*r)


def hertz_energy(E_star, R, d):
    """Elastic energy U [J] stored in a Hertz contact at depth d.

    Chapter: (5.25). Derived from: the integral of F = dU/dd from 0 to d.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_energy_by_work``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_energy(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (8/15)*E_star*numpy.sqrt(R)*d**(5/2)


def hertz_force(E_star, R, d):
    """Normal force F [N] of a Hertz contact at depth d.

    Chapter: (5.23). Derived from: (5.17) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_force(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*numpy.sqrt(R)*d**(3/2)


def hertz_max_pressure(E_star, R, d):
    """Maximum (central) pressure p0 [Pa] of a Hertz contact at depth d.

    Chapter: (5.22). Derived from: the matching condition (5.19).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_max_pressure(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(d)/(numpy.pi*numpy.sqrt(R))


def hertz_max_pressure_from_force(E_star, F, R):
    """Maximum pressure p0 [Pa] of a Hertz contact under the force F.

    Chapter: (5.24). Derived from: (5.22) at the depth of (5.23) inverted.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(F) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_max_pressure_from_force(E_star, F, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 6**(1/3)*E_star**(2/3)*F**(1/3)/(numpy.pi*R**(2/3))


def hertz_mean_pressure(E_star, R, d):
    """Mean pressure F/(pi a^2) [Pa] of a Hertz contact at depth d.

    Chapter: (5.17). Derived from: (5.23) divided by the contact area.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_mean_pressure(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*numpy.sqrt(d)/(numpy.pi*numpy.sqrt(R))


def hertz_pressure(E_star, R, d, r):
    """Contact pressure p(r) [Pa] of a Hertz contact at depth d (0 for r > a).

    Chapter: (5.15). Derived from: (5.15) with (5.21) and (5.22).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_matching_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools

    if type(E_star) is float and type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_pressure(E_star, R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - r**2/(R*d)]))/(numpy.pi*numpy.sqrt(R))


def hertz_pressure_displacement(E_star, a, p0, r):
    """Surface displacement u_z [m] inside a disc (r <= a) loaded by p0*(1 - r^2/a^2)^(1/2).

    Chapter: (5.16). Derived from: (5.7) over the pressure (5.15).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_hertz_displacement_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(p0) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_pressure_displacement(E_star, a, p0, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*p0*(2*a**2 - r**2)/(E_star*a)


def hertz_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) loaded by p0*(1 - r^2/a^2)^(1/2).

    Chapter: Fig. 5.2. Derived from: (5.7) over the pressure (5.15).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(p0) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_pressure_displacement_outside(E_star, a, p0, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*p0*(2*a**2*numpy.arcsin(a/r) + a*numpy.sqrt(-a**2 + r**2) - r**2*numpy.arcsin(a/r))/(E_star*a)


def hertz_pressure_force(a, p0):
    """Total force F [N] of the pressure p0*(1 - r^2/a^2)^(1/2).

    Chapter: (5.17). Derived from: the integral of (5.15) times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_pressure_force(a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2/3)*numpy.pi*a**2*p0


def hertz_stiffness(E_star, R, d):
    """Differential contact stiffness dF/dd [N/m] of a Hertz contact.

    Chapter: Problem 5. Derived from: the derivative of (5.23).

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_stiffness_by_punch``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_hertz_stiffness(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*numpy.sqrt(R)*numpy.sqrt(d)


def impact_contact_time(E_star, R, m, v0):
    """Contact time tau [s] of a sphere of mass m hitting a wall at v0 (the chapter's 2.94 x0/v0, with 2.94 = (4/5) sqrt(pi) Gamma(2/5)/Gamma(9/10)).

    Chapter: Problem 3. Derived from: twice the time integral of dx/v from 0 to x0, v from
    the energy balance.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    import scipy.special

    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_contact_time(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/5)*30**(2/5)*numpy.sqrt(numpy.pi)*m**(2/5)*scipy.special.gamma(2/5)/(E_star**(2/5)*R**(1/5)*v0**(1/5)*scipy.special.gamma(9/10))


def impact_contact_time_density(E_star, R, rho, v0):
    """Contact time tau [s] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 3, m = 4/3 pi R^3 rho. Derived from: twice the time integral of dx/v
    from 0 to x0.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : float or ndarray
        density [kg/m^3]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    import scipy.special

    if (type(E_star) is float and type(R) is float and type(rho) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_contact_time_density(E_star, R, rho, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2/5)*2**(1/5)*5**(2/5)*numpy.pi**(9/10)*R*rho**(2/5)*scipy.special.gamma(2/5)/(E_star**(2/5)*v0**(1/5)*scipy.special.gamma(9/10))


def impact_force_scale(E_star, R, m, v0):
    """Force scale F_s = m x_s/t_s^2 [N] of the impact: m x'' = -F(x) (5.23) reads X'' = -F(x_s X)/F_s = -(4/3) X^(3/2).

    Chapter: (5.23), nondimensionalized. Derived from: m x'' = (m x_s/t_s^2) X''.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_time_and_force_scales``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_force_scale(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star**(2/5)*R**(1/5)*m**(3/5)*v0**(6/5)


def impact_length_scale(E_star, R, m, v0):
    """Length scale x_s [m] of the impact: (m v0^2/(E* sqrt(R)))^(2/5), with which the equation of motion reads X'' = -(4/3) X^(3/2) in T = t v0/x_s.

    Chapter: (5.23), nondimensionalized. Derived from: m v0^2/x_s = E* sqrt(R) x_s^(3/2).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_length_scale``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_length_scale(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return m**(2/5)*v0**(4/5)/(E_star**(2/5)*R**(1/5))


def impact_max_contact_radius(E_star, R, m, v0):
    """Maximum contact radius [m] during the impact.

    Chapter: Problem 4. Derived from: (5.21) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_contact_radius(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*30**(1/5)*R**(2/5)*m**(1/5)*v0**(2/5)/E_star**(1/5)


def impact_max_contact_radius_density(E_star, R, rho, v0):
    """Maximum contact radius [m] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: (5.21) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : float or ndarray
        density [kg/m^3]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(rho) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_contact_radius_density(E_star, R, rho, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*2**(3/5)*5**(1/5)*numpy.pi**(1/5)*R*rho**(1/5)*v0**(2/5)/E_star**(1/5)


def impact_max_depth(E_star, R, m, v0):
    """Maximum indentation depth x0 [m] of a sphere of mass m hitting a wall at v0.

    Chapter: Problem 3. Derived from: energy conservation with (5.25).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_depth(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*30**(2/5)*m**(2/5)*v0**(4/5)/(E_star**(2/5)*R**(1/5))


def impact_max_depth_density(E_star, R, rho, v0):
    """Maximum indentation depth x0 [m] of a sphere of density rho hitting a wall.

    Chapter: Problem 3, m = 4/3 pi R^3 rho. Derived from: energy conservation with (5.25).

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : float or ndarray
        density [kg/m^3]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(rho) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_depth_density(E_star, R, rho, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*2**(1/5)*5**(2/5)*numpy.pi**(2/5)*R*rho**(2/5)*v0**(4/5)/E_star**(2/5)


def impact_max_force(E_star, R, m, v0):
    """Maximum contact force [N] during the impact.

    Chapter: Problem 4. Derived from: (5.23) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_force(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/6)*30**(3/5)*E_star**(2/5)*R**(1/5)*m**(3/5)*v0**(6/5)


def impact_max_force_density(E_star, R, rho, v0):
    """Maximum contact force [N] of a sphere of density rho hitting a wall at v0.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: (5.23) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : float or ndarray
        density [kg/m^3]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(rho) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_force_density(E_star, R, rho, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/3)*2**(4/5)*5**(3/5)*numpy.pi**(3/5)*E_star**(2/5)*R**2*rho**(3/5)*v0**(6/5)


def impact_max_pressure(E_star, R, m, v0):
    """Maximum contact pressure p0 [Pa] during the impact.

    Chapter: Problem 4. Derived from: (5.22) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_pressure(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 30**(1/5)*E_star**(4/5)*m**(1/5)*v0**(2/5)/(numpy.pi*R**(3/5))


def impact_max_pressure_density(E_star, rho, v0):
    """Maximum contact pressure p0 [Pa] of a sphere of density rho hitting a wall at v0 (independent of its radius).

    Chapter: Problem 4. Derived from: (5.22) at the maximum depth.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_impact_by_equation_of_motion``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    rho : float or ndarray
        density [kg/m^3]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if type(E_star) is float and type(rho) is float and type(v0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_impact_max_pressure_density(E_star, rho, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2**(3/5)*5**(1/5)*E_star**(4/5)*rho**(1/5)*v0**(2/5)/numpy.pi**(4/5)


def impact_sphere_mass(R, rho):
    """Mass m [kg] of a solid sphere of radius R and density rho.

    Chapter: Problem 4, m = 4/3 pi R^3 rho. Derived from: the volume of the sphere times its
    density.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_sphere_mass_by_quadrature``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    rho : float or ndarray
        density [kg/m^3]
    """
    if type(R) is float and type(rho) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_impact_sphere_mass(R, rho)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*numpy.pi*R**3*rho


def impact_time_scale(E_star, R, m, v0):
    """Time scale t_s = x_s/v0 [s] of the impact, with which the initial velocity is X'(0) = 1 in X = x/x_s, T = t/t_s.

    Chapter: (5.23), nondimensionalized. Derived from: x'(0) = v0 in the scaled variables.

    Derivation: ``hertzmdr.derive.impact``. Verified by
    ``tests/test_impact.py::test_time_and_force_scales``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    m : float or ndarray
        mass [kg]
    v0 : float or ndarray
        impact velocity [m/s]
    """
    if (type(E_star) is float and type(R) is float and type(m) is float and
            type(v0) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_impact_time_scale(E_star, R, m, v0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return m**(2/5)/(E_star**(2/5)*R**(1/5)*v0**(1/5))


def jkr_contact_radius_from_force(E_star, F_load, R, dgamma):
    """Contact radius a [m] of a paraboloid in JKR contact under the force F_load >= -3 pi R dgamma/2 (the stable branch).

    Chapter: (5.57), JKR, inverted. Derived from: (5.57) as a quadratic in a^(3/2), larger
    root.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F_load : float or ndarray
        normal force, negative when adhesion pulls (adhesive contact) [N]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if (type(E_star) is float and type(F_load) is float and type(R) is float and
            type(dgamma) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_contact_radius_from_force(E_star, F_load, R, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*(numpy.sqrt(3)*numpy.sqrt(R)*numpy.sqrt(2*F_load + 3*numpy.pi*R*dgamma) + 3*numpy.sqrt(numpy.pi)*R*numpy.sqrt(dgamma))**(2/3)/E_star**(1/3)


def jkr_depth(E_star, R, a, dgamma):
    """Indentation depth d [m] of a paraboloid in JKR contact of radius a.

    Chapter: (5.55), JKR. Derived from: (5.52) of r^2/(2R), (5.55) with Delta l.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(dgamma) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_depth(E_star, R, a, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a**2/R - numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(a)*numpy.sqrt(dgamma)/numpy.sqrt(E_star)


def jkr_force_from_radius(E_star, R, a, dgamma):
    """Normal force F [N] of a paraboloid in JKR contact of radius a.

    Chapter: (5.57), JKR. Derived from: (5.57) at the adhesive depth.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(dgamma) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_force_from_radius(E_star, R, a, dgamma)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*a**(3/2)*numpy.sqrt(dgamma) + (4/3)*E_star*a**3/R


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(dgamma) is float and type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pressure(E_star, R, a, dgamma, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*numpy.sqrt(E_star)*numpy.sqrt(a)*numpy.sqrt(dgamma)/(numpy.sqrt(numpy.pi)*numpy.sqrt(a - r)*numpy.sqrt(a + r)) + 2*E_star*numpy.sqrt(a - r)*numpy.sqrt(a + r)/(numpy.pi*R)


def jkr_pull_off_depth_dc(E_star, dgamma, R):
    """Depth d_c [m] at pull-off of a paraboloid (JKR) under depth control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_depth_dc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/4*numpy.pi**(2/3)*R**(1/3)*dgamma**(2/3)/E_star**(2/3)


def jkr_pull_off_depth_fc(E_star, dgamma, R):
    """Depth d_c [m] at pull-off of a paraboloid (JKR) under force control (negative: the surface is pulled up).

    Chapter: (5.55), adhesive. Derived from: (5.55) with Delta l at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_depth_fc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/4*3**(1/3)*numpy.pi**(2/3)*R**(1/3)*dgamma**(2/3)/E_star**(2/3)


def jkr_pull_off_force_dc(E_star, dgamma, R):
    """Pull-off force F_c [N] (negative) of a paraboloid (JKR) under depth control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_force_dc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -5/6*numpy.pi*R*dgamma


def jkr_pull_off_force_fc(E_star, dgamma, R):
    """Pull-off force F_c [N] (negative) of a paraboloid (JKR) under force control.

    Chapter: (5.57), adhesive. Derived from: (5.57) at the pull-off radius.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_force_fc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -3/2*numpy.pi*R*dgamma


def jkr_pull_off_radius_dc(E_star, dgamma, R):
    """Contact radius a_c [m] at pull-off of a paraboloid (JKR) under depth control.

    Chapter: (5.57), adhesive. Derived from: dd/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_radius_dc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.pi**(1/3)*R**(2/3)*dgamma**(1/3)/E_star**(1/3)


def jkr_pull_off_radius_fc(E_star, dgamma, R):
    """Contact radius a_c [m] at pull-off of a paraboloid (JKR) under force control.

    Chapter: (5.57), adhesive. Derived from: dF/da = 0.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_pull_off_radius_fc(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*3**(2/3)*numpy.pi**(1/3)*R**(2/3)*dgamma**(1/3)/E_star**(1/3)


def jkr_zero_load_radius(E_star, dgamma, R):
    """Contact radius a_0 [m] of a paraboloid (JKR) at zero load.

    Chapter: (5.57), adhesive. Derived from: F(a) = 0 of (5.57).

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_literature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(dgamma) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_jkr_zero_load_radius(E_star, dgamma, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*6**(2/3)*numpy.pi**(1/3)*R**(2/3)*dgamma**(1/3)/E_star**(1/3)


def line_depth_from_force(E_star, F, L):
    """Depth d [m] (in the sense of (5.35)) of a line contact under the force F.

    Chapter: (5.34), inverted. Derived from: (5.34) solved for d.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    L : float or ndarray
        length of a line contact [m]
    """
    if type(E_star) is float and type(F) is float and type(L) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_depth_from_force(E_star, F, L)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*F/(numpy.pi*E_star*L)


def line_force(E_star, L, d):
    """Normal force F [N] of a line contact of length L at the depth d of (5.35).

    Chapter: (5.34). Derived from: F/L of the matched pressure with a = sqrt(R d).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    L : float or ndarray
        length of a line contact [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(L) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_force(E_star, L, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*E_star*L*d


def line_force_per_length_from_half_width(E_star, R, a):
    """Normal force per unit length F/L [N/m] of a line contact of half-width a.

    Chapter: (5.34), from the matching. Derived from: the integral of (5.36) over the strip.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_force_per_length_from_half_width(E_star, R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*E_star*a**2/R


def line_half_width(R, d):
    """Half-width a [m] of a line contact at the (conventional) depth d.

    Chapter: (5.35). Derived from: the chapter's definition of the depth of a line contact.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_half_width(R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(R)*numpy.sqrt(d)


def line_half_width_from_force(E_star, F, L, R):
    """Half-width a [m] of a line contact of length L under the force F.

    Chapter: (5.34), (5.35). Derived from: F = L F/L(a) solved for a.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    L : float or ndarray
        length of a line contact [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(F) is float and type(L) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_half_width_from_force(E_star, F, L, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*numpy.sqrt(F)*numpy.sqrt(R)/(numpy.sqrt(numpy.pi)*numpy.sqrt(E_star)*numpy.sqrt(L))


def line_max_pressure(E_star, R, d):
    """Maximum pressure p0 [Pa] of a line contact at the depth d of (5.35).

    Chapter: (5.37), second form. Derived from: the matching, with a = sqrt(R d) (5.35).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_max_pressure(E_star, R, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*numpy.sqrt(d)/numpy.sqrt(R)


def line_max_pressure_depth_width(E_star, a, d):
    """Maximum pressure p0 [Pa] of a line contact from its depth and half-width.

    Chapter: (5.37), first form. Derived from: the matching, with R = a^2/d (5.35).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_max_pressure_depth_width(E_star, a, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*d/a


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    L : float or ndarray
        length of a line contact [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    """
    if type(E_star) is float and type(F) is float and type(L) is float and type(R) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_max_pressure_from_force(E_star, F, L, R)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(E_star)*numpy.sqrt(F)/(numpy.sqrt(numpy.pi)*numpy.sqrt(L)*numpy.sqrt(R))


def line_max_pressure_from_half_width(E_star, R, a):
    """Maximum pressure p0 [Pa] of a line contact of half-width a.

    Chapter: (5.37), from the matching. Derived from: the gradient of the 2-D surface
    displacement matched to -x/R.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_max_pressure_from_half_width(E_star, R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*a/R


def line_pressure(E_star, R, d, x):
    """Pressure p(x) [Pa] of a line contact at the depth d of (5.35) (0 outside).

    Chapter: (5.36). Derived from: (5.36) with the matched p0.

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_by_displacement_gradient``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    x : float or ndarray
        coordinate [m]
    """
    import functools

    if type(E_star) is float and type(R) is float and type(d) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_pressure(E_star, R, d, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - x**2/(R*d)]))/numpy.sqrt(R)


def line_stiffness(E_star, L):
    """Differential stiffness dF/dd [N/m] of a line contact of length L (with d defined by (5.35)).

    Chapter: (5.34), differentiated. Derived from: the derivative of (5.34).

    Derivation: ``hertzmdr.derive.line``. Verified by
    ``tests/test_line.py::test_line_stiffness_by_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    L : float or ndarray
        length of a line contact [m]
    """
    if type(E_star) is float and type(L) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stiffness(E_star, L)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*numpy.pi*E_star*L


def line_stress_axis_max_shear(a, p0, z):
    """Principal shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis of a line contact.

    Chapter: (5.36), Flamant. Derived from: the axis stresses.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_max_shear(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*p0*z/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2)))


def line_stress_axis_max_shear_slope(a, p0, z):
    """D(tau_1)/dz [Pa/m] on the axis of a line contact; its root is the depth of the largest tau_1.

    Chapter: (5.36), Flamant. Derived from: the derivative of tau_1.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_max_shear_slope(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*p0*z**2/((a**2 + z**2)**(3/2)*(z + numpy.sqrt(a**2 + z**2))) + a*p0*z*(-z/numpy.sqrt(a**2 + z**2) - 1)/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + a*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2)))


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
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_sigma_xx(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2)


def line_stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis of a line contact of half-width a.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over the line pressure (5.36)
    along the axis x = 0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_sigma_zz(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*p0/numpy.sqrt(a**2 + z**2)


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
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_von_mises(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(3*a**2*p0**2*z**2/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-1/2*a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - 1/2*a*p0/numpy.sqrt(a**2 + z**2))**2)


def line_stress_axis_von_mises_slope(a, nu, p0, z):
    """D(sigma_vM)/dz [Pa/m] on the axis of a line contact; its root is the depth of the largest von Mises stress.

    Chapter: (5.50), (5.36). Derived from: the derivative.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_axis_von_mises_slope(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-3*a**2*p0**2*z**3/((a**2 + z**2)**2*(z + numpy.sqrt(a**2 + z**2))**2) + (3/2)*a**2*p0**2*z**2*(-2*z/numpy.sqrt(a**2 + z**2) - 2)/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**3) + 3*a**2*p0**2*z/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + (1/2)*(1 - 2*nu)**2*(-1/2*a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - 1/2*a*p0/numpy.sqrt(a**2 + z**2))*(a**3*p0*z/((a**2 + z**2)**(3/2)*(z + numpy.sqrt(a**2 + z**2))**2) - a**3*p0*(-2*z/numpy.sqrt(a**2 + z**2) - 2)/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**3) + a*p0*z/(a**2 + z**2)**(3/2)))/numpy.sqrt(3*a**2*p0**2*z**2/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + (1 - 2*nu)**2*(-1/2*a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - 1/2*a*p0/numpy.sqrt(a**2 + z**2))**2)


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
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*sigma_xx + (1/2)*sigma_zz + numpy.sqrt(tau_xz**2 + (1/4)*(sigma_xx - sigma_zz)**2)


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
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*sigma_xx + (1/2)*sigma_zz - numpy.sqrt(tau_xz**2 + (1/4)*(sigma_xx - sigma_zz)**2)


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
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(tau_xz**2 + (1/4)*(sigma_xx - sigma_zz)**2)


def line_stress_sigma_xx_core(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_xx_core(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -p0*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*(2*x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))))/(a*(z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_xx_deep(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_xx_deep(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*z**2*(2*a**2*z**2*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) + 2*x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))/((z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_xx_side(a, p0, x, z):
    """Normal stress sigma_xx [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_xx_side(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*z**2*(2*a**2*x*z**3/((x*z/numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))) - z**2 - (a - x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((x*z/numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - 1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_yy(nu, sigma_xx, sigma_zz):
    """Out-of-plane stress sigma_yy [Pa] in plane strain.

    Chapter: plane strain. Derived from: eps_yy = (sigma_yy - nu (sigma_xx + sigma_zz))/E =
    0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    """
    if type(nu) is float and type(sigma_xx) is float and type(sigma_zz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_yy(nu, sigma_xx, sigma_zz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return nu*(sigma_xx + sigma_zz)


def line_stress_sigma_zz_core(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_zz_core(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -p0*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(a*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_zz_deep(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_zz_deep(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*z**2*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_sigma_zz_side(a, p0, x, z):
    """Normal stress sigma_zz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_sigma_zz_side(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*x*z**3/(numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - 1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_core(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_1_core(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*numpy.sqrt(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z**2)*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))/(a*(z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*numpy.sqrt(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_deep(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_1_deep(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*p0*z**2*numpy.sqrt(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z**2)/((z + numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*numpy.sqrt(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_1_side(a, p0, x, z):
    """Principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms; tau_1^2 factored.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_1_side(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*p0*z**2*numpy.sqrt((1/2)*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((x*z/numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + z)*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*numpy.sqrt(x**2*z**2/(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - 1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_core(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 <= a^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_xz_core(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -p0*x*z*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (a - x)*(a + x))/(a*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_deep(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 + z^2 > a^2 and x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_xz_deep(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*x*z**3/(numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_side(a, p0, x, z):
    """Shear stress tau_xz [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 and x^2 > a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over (5.36) by the Cauchy
    integral of the pressure (McEwen's m, n), in positive terms.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_field_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_xz_side(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*a*p0*z**2*numpy.sqrt(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/((z**2 + (-a + x)*(a + x) + numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/(-1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) - 1/2*z**2 - 1/2*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))


def line_stress_tau_xz_slope_x(a, p0, x, z):
    """D(tau_xz)/dx [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: -(z/pi) Im F'' of the Cauchy integral F of the
    pressure.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_orthogonal_shear_maximum``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_xz_slope_x(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a*p0*z*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(-3*x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))**3


def line_stress_tau_xz_slope_z(a, p0, x, z):
    """D(tau_xz)/dz [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2.

    Chapter: (5.36), Flamant. Derived from: -(Im F' + z Re F'')/pi of the Cauchy integral F
    of the pressure.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_orthogonal_shear_maximum``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    x : float or ndarray
        coordinate [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(x) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_tau_xz_slope_z(a, p0, x, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (numpy.pi*a*p0*x*z**2*(-x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (3/2)*z**2 + (3/2)*(a - x)*(a + x) + (3/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))/(numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))**3) - numpy.pi*p0*(-x*z**2/numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + x*numpy.sqrt((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)))/(a*(x**2*z**2/((1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2)) + (1/2)*z**2 + (1/2)*(a - x)*(a + x) + (1/2)*numpy.sqrt(4*x**2*z**2 + (z**2 + (a - x)*(a + x))**2))))/numpy.pi


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
    nu : float or ndarray
        Poisson's ratio [1]
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if (type(nu) is float and type(sigma_xx) is float and type(sigma_zz) is float and
            type(tau_xz) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(3*tau_xz**2 + (1 - 2*nu)**2*((1/2)*sigma_xx + (1/2)*sigma_zz)**2 + (3/4)*(sigma_xx - sigma_zz)**2)


def line_stress_von_mises_c_tau(nu, c_mean, tau_1):
    """Von Mises stress [Pa] of a plane-strain state from its mean in-plane stress c = (sigma_xx + sigma_zz)/2 and tau_1.

    Chapter: (5.50), plane strain. Derived from: line_stress_von_mises with sigma_xx,
    sigma_zz = c +- tau_1, tau_xz = 0 (the same Mohr circle).

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_tau_1_by_superposition``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    c_mean : float or ndarray
        mean in-plane normal stress (sigma_xx + sigma_zz)/2 (plane strain) [Pa]
    tau_1 : float or ndarray
        principal shear stress in the x-z plane, the radius of Mohr's circle [Pa]
    """
    if type(nu) is float and type(c_mean) is float and type(tau_1) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_line_stress_von_mises_c_tau(nu, c_mean, tau_1)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(c_mean**2*(1 - 2*nu)**2 + 3*tau_1**2)


def masing_unloading_force(F_amp, F_half):
    """Tangential force F_x [N] on the branch from a turning point: F_x* - 2 F_x,mono(D/2).

    Chapter: Masing's rule, derived from the springs. Derived from: per spring, unloaded by
    D from u*: f* - f = 2 min(G* D/2, mu q_z) (case check).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_history_solver_follows_masing``.

    Parameters
    ----------
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    F_half : float or ndarray
        tangential force of the monotonic loading at half the displacement travelled since the turning point [N]
    """
    if type(F_amp) is float and type(F_half) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_masing_unloading_force(F_amp, F_half)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F_amp - 2*F_half


def mdr_depth_of_line_load(E_star, g_x, q_z):
    """Depth d [m] at which the MDR spring with gap g(x) carries the line load q_z.

    Chapter: (5.58), inverted. Derived from: q_z = E* (d - g(x)) solved for d.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_normal_line_load_against_the_normal_force``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    g_x : float or ndarray
        MDR profile g(x) at the spring's coordinate x (5.52) [m]
    q_z : float or ndarray
        normal line load of the MDR springs, force per unit length (5.58) [N/m]
    """
    if type(E_star) is float and type(g_x) is float and type(q_z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_depth_of_line_load(E_star, g_x, q_z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return g_x + q_z/E_star


def mdr_force(E_star, a, d, g_integral):
    """Normal force F [N] of the MDR at the contact radius a and depth d = g(a), from the integral of g over [0, a].

    Chapter: (5.57). Derived from: (5.57) with (5.55) for any g(x).

    Derivation: ``hertzmdr.derive.numerical_mdr``. Verified by
    ``tests/test_mdr.py::test_mdr_force_by_the_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    g_integral : float or ndarray
        integral of the MDR profile g(x) over [0, a] (5.57) [m^2]
    """
    if (type(E_star) is float and type(a) is float and type(d) is float and
            type(g_integral) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_force(E_star, a, d, g_integral)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : float or ndarray
        coordinate [m]
    """
    if type(b) is float and type(slope_jump) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_kink_G(b, slope_jump, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return b*slope_jump*(2*x*numpy.arcsinh((1/2)*numpy.sqrt(2)*numpy.sqrt(-b + x)/numpy.sqrt(b)) - numpy.sqrt(-b + x)*numpy.sqrt(b + x))


def mdr_kink_g(b, slope_jump, x):
    """Integral from b to x > b [m] of the branch-point term of g' at a kink r = b.

    Chapter: (5.52). Derived from: integral of mdr_kink_gprime.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_g_by_quadrature``.

    Printed in a stable form: acosh of an argument 1 + (x - b)/(4b) loses digits as x -> b
    (relative eps b/(x - b)); it is written 2 asinh(sqrt((x - b)/(2b))).

    Parameters
    ----------
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : float or ndarray
        coordinate [m]
    """
    if type(b) is float and type(slope_jump) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_kink_g(b, slope_jump, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*b*slope_jump*numpy.arcsinh((1/2)*numpy.sqrt(2)*numpy.sqrt(-b + x)/numpy.sqrt(b))


def mdr_kink_gprime(b, slope_jump, x):
    """Branch-point term b s/sqrt(x^2 - b^2) [1] of g'(x), x > b, at a kink r = b where f' jumps by s.

    Chapter: (5.52). Derived from: lim sqrt(x^2 - b^2) g'(x), x -> b, of (5.52) for f = s (r
    - b).

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_gprime_is_the_singular_part_of_52``.

    Parameters
    ----------
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : float or ndarray
        coordinate [m]
    """
    if type(b) is float and type(slope_jump) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_kink_gprime(b, slope_jump, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return b*slope_jump/(numpy.sqrt(-b + x)*numpy.sqrt(b + x))


def mdr_kink_pressure(E_star, a, b, r, slope_jump):
    """Pressure p(r) [Pa] of the branch-point term b s/sqrt(x^2 - b^2) of g' at a kink r = b < a where f' jumps by s (log-infinite at r = b, 0 for r >= a).

    Chapter: (5.59). Derived from: (5.59) of the singular part of g' for f = s (r - b), r >
    b.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_pressure_by_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    """
    import functools
    import scipy.special

    return E_star*b*slope_jump*scipy.special.ellipkinc(numpy.arctan2(numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - functools.reduce(numpy.maximum, [b, r]))*(a + functools.reduce(numpy.maximum, [b, r]))])), numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) - functools.reduce(numpy.minimum, [b, r]))*numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) + functools.reduce(numpy.minimum, [b, r]))), functools.reduce(numpy.minimum, [b, r])**2/functools.reduce(numpy.maximum, [b, r])**2)/(numpy.pi*functools.reduce(numpy.maximum, [b, r]))


def mdr_normal_line_load(E_star, d, g_x):
    """Normal line load q_z [N/m] of the MDR spring at x with gap g(x) at depth d (in contact for d > g(x); pass g(x) capped at d for the springs out of contact).

    Chapter: (5.58). Derived from: the spring stiffness E* per unit length (5.51) times its
    compression d - g(x) (5.55).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_normal_line_load_against_the_normal_force``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    d : float or ndarray
        indentation depth [m]
    g_x : float or ndarray
        MDR profile g(x) at the spring's coordinate x (5.52) [m]
    """
    if type(E_star) is float and type(d) is float and type(g_x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_normal_line_load(E_star, d, g_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*(d - g_x)


def mdr_stiffness(E_star, a):
    """Differential normal stiffness dF/dd = 2 a E* [N/m] of an axisymmetric contact of radius a.

    Chapter: (5.12), Problem 5. Derived from: dF/dd of (5.57) with d = g(a) (5.55).

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_stiffness_by_differentiation``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_stiffness(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a


def mdr_tangential_line_load(G_star, w_x):
    """Tangential line load q_x [N/m] of the MDR spring sheared elastically by w.

    Chapter: MDR tangential springs (not in the chapter). Derived from: the tangential
    spring stiffness G* per unit length times its shear w.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_line_load_against_the_stiffness``.

    Parameters
    ----------
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    w_x : float or ndarray
        elastic shear displacement of an MDR tangential spring [m]
    """
    if type(G_star) is float and type(w_x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_tangential_line_load(G_star, w_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return G_star*w_x


def mdr_tangential_spring_shear(G_star, q_x):
    """Elastic shear w [m] of the MDR spring that carries the tangential line load q_x (the slip that a spring's excess over Coulomb's limit gives up).

    Chapter: MDR tangential springs (not in the chapter). Derived from: q_x = G* w solved
    for w.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_line_load_against_the_stiffness``.

    Parameters
    ----------
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    q_x : float or ndarray
        tangential line load of the MDR springs, force per unit length [N/m]
    """
    if type(G_star) is float and type(q_x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_mdr_tangential_spring_shear(G_star, q_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_mindlin_energy(a, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/5*(3*F**2*mu_f**2*numpy.exp((2/3)*numpy.log1p(-F_amp/(F*mu_f))) + 9*F**2*mu_f**2*numpy.exp((1/3)*numpy.log1p(-F_amp/(F*mu_f))) + 3*F**2*mu_f**2)*numpy.expm1((1/3)*numpy.log1p(-F_amp/(F*mu_f)))**3/(G_star*a)


def mindlin_energy_small(a, F, G_star, mu_f, F_amp):
    """Leading term [J] of the energy per cycle of a paraboloid at small amplitude F_amp.

    Chapter: Mindlin-Deresiewicz (not in the chapter). Derived from: series of
    mindlin_energy in F_amp.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cubic_small_amplitude_law``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_mindlin_energy_small(a, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/9)*F_amp**3/(F*G_star*a*mu_f)


def paraboloid_g(R, x):
    """MDR profile g(x) [m] of the paraboloid f = r^2/(2R) (the springs' gap; d = g(a)).

    Chapter: (5.52) of f = r^2/(2R). Derived from: (5.52) of r^2/(2R).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_g_against_the_mdr_transform``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_paraboloid_g(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return x**2/R


def paraboloid_profile(R, r):
    """Height f(r) [m] of the paraboloid above its tip (the profile whose g is paraboloid_g).

    Chapter: (5.52). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_paraboloid_profile(R, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*r**2/R


def powerlaw_contact_radius(c_n, d, kappa_n, n):
    """Contact radius a [m] of a power-law indenter at depth d.

    Chapter: Problem 7(d). Derived from: (5.55) with g of (5.52).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : float or ndarray
        indentation depth [m]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(c_n) is float and type(d) is float and type(kappa_n) is float and
            type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_contact_radius(c_n, d, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (d/(c_n*kappa_n))**(n**(-1.0))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(F) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (c_n*kappa_n)**((n + 1)**(-1.0))*((1/2)*F*(n + 1)/(E_star*n))**(n/(n + 1))


def powerlaw_displacement_far(a, d, n, r):
    """Surface displacement u_z(r) [m] of a power-law indenter far outside the contact (a/r < 1e-3: the series to (a/r)^7).

    Chapter: Problem 7(d), (5.60), r >> a. Derived from: (5.60) with 1/sqrt(r^2 - x^2)
    expanded in (x/r)^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_surface_displacement_far_outside``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(a) is float and type(d) is float and type(n) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_displacement_far(a, d, n, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*d*n*(a**2*(a**2*(a**2*(5*n + 5)/(r**2*(112*n + 784)) + (3*n + 3)/(40*n + 200))/r**2 + (n + 1)/(6*n + 18))/r**2 + 1)/(numpy.pi*r*(n + 1))


def powerlaw_displacement_outside(a, d, n, r):
    """Surface displacement u_z(r) [m] outside the contact (r > a) of a power-law indenter.

    Chapter: Problem 7(d), (5.60). Derived from: (5.60) for r > a.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return 2*d*(-a*scipy.special.hyp2f1(1/2, (1/2)*n + 1/2, (1/2)*n + 3/2, a**2/r**2)/r + (n + 1)*numpy.arcsin(a/r))/(numpy.pi*(n + 1))


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
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    w_out : float or ndarray
        integration variable in (0, asin(a/r)) of (5.60) outside the contact: x = r sin(asin(a/r) - w) [rad]
    """
    if (type(a) is float and type(d) is float and type(n) is float and type(r) is float and
            type(w_out) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_displacement_outside_integrand(a, d, n, r, w_out)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*d*numpy.expm1(n*numpy.log1p(-2*numpy.sin((1/2)*w_out)**2 - numpy.sqrt(-a + r)*numpy.sqrt(a + r)*numpy.sin(w_out)/a))/numpy.pi


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : float or ndarray
        indentation depth [m]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(c_n) is float and type(d) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_force(E_star, c_n, d, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d*n*(d/(c_n*kappa_n))**(n**(-1.0))/(n + 1)


def powerlaw_force_from_radius(E_star, a, d, n):
    """Normal force F [N] of a power-law indenter with contact radius a at depth d.

    Chapter: Problem 7(d), (5.57). Derived from: (5.57) with d = g(a) (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_force_from_radius(E_star, a, d, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a*d*n/(n + 1)


def powerlaw_g(c_n, kappa_n, n, x):
    """MDR profile g(x) [m] of the power-law profile f = c_n r^n, x >= 0.

    Chapter: Problem 7(d). Derived from: (5.52) for f = c_n r^n.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_g_by_quadrature``.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : float or ndarray
        coordinate [m]
    """
    if (type(c_n) is float and type(kappa_n) is float and type(n) is float and
            type(x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_g(c_n, kappa_n, n, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return c_n*kappa_n*x**n


def powerlaw_kappa(n):
    """MDR factor kappa_n [1] of the power-law profile, g = kappa_n c_n |x|^n (overflows for n > 340: use powerlaw_kappa_asymptotic there).

    Chapter: Problem 7(d). Derived from: (5.52) for f = c_n r^n.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_kappa_by_quadrature``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    import scipy.special

    if type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_kappa(n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(numpy.pi)*scipy.special.gamma((1/2)*n + 1)/scipy.special.gamma((1/2)*n + 1/2)


def powerlaw_kappa_asymptotic(n):
    """Kappa_n [1] from the Stirling series to O(n^-10); relative error < 1e-16 for n >= 40.

    Chapter: Problem 7(d), large n. Derived from: the Stirling series of ln Gamma(n/2 + 1) -
    ln Gamma(n/2 + 1/2).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_kappa_by_quadrature``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_kappa_asymptotic(n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(n)*numpy.exp(2*n**(-1.0)*(4*n**(-2.0)*(4*n**(-2.0)*(4*n**(-2.0)*((31/4608)*n**(-2.0) - 17/14336) + 1/640) - 1/192) + 1/8))


def powerlaw_mean_pressure(E_star, a, d, n):
    """Mean pressure F/(pi a^2) [Pa] of a power-law indenter.

    Chapter: Fig. 5.17. Derived from: (5.57) over the contact area.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(n) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_mean_pressure(E_star, a, d, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d*n/(numpy.pi*a*(n + 1))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : float or ndarray
        indentation depth [m]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(c_n) is float and type(d) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d*n*(c_n*kappa_n/d)**(n**(-1.0))/(numpy.pi*(n + 1))


def powerlaw_pressure(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; accurate for n >= 1.5 (use powerlaw_pressure_small_n below).

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x = r/sqrt(1 - z t), then
    Euler's transformation.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools
    import scipy.special

    return E_star*d*n*scipy.special.hyp2f1(1, 1 - 1/2*n, 3/2, functools.reduce(numpy.maximum, [0, (a - r)*(a + r)])/a**2)*numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - r)*(a + r)]))/(numpy.pi*a**2)


def powerlaw_pressure_centre(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter near the centre, 0 < n < 3 (n != 1), r < a/10: the series to (r/a)^18 plus its (r/a)^(n-1) term.

    Chapter: Problem 7(d), (5.59), r << a. Derived from: the 2F1 of (5.59) by the connection
    formula z -> 1 - z (DLMF 15.8.4).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_pressure_near_the_centre_by_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    if (type(E_star) is float and type(a) is float and type(d) is float and type(n) is float
            and type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_centre(E_star, a, d, n, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*d*n*((1/2)*numpy.sqrt(numpy.pi)*(r/a)**(n - 1)*scipy.special.gamma(1/2 - 1/2*n)/scipy.special.gamma(1 - 1/2*n) + (n - 1)**(-1.0) + r**2*((2*n - 6)**(-1.0) + r**2*(3/(8*n - 40) + r**2*(5/(16*n - 112) + r**2*(35/(128*n - 1152) + r**2*(63/(256*n - 2816) + r**2*(231/(1024*n - 13312) + r**2*(429/(2048*n - 30720) + r**2*(6435/(32768*n - 557056) + 12155*r**2/(a**2*(65536*n - 1245184)))/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/a**2)/(numpy.pi*a)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    w_quad : float or ndarray
        integration variable in (0, 1) of (5.59): x^2 = r^2 + (a^2 - r^2)(1 - w)^2 [1]
    """
    if (type(E_star) is float and type(a) is float and type(d) is float and type(n) is float
            and type(r) is float and type(w_quad) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*d*n*numpy.sqrt(a - r)*numpy.sqrt(a + r)*numpy.exp(((1/2)*n - 1)*numpy.log1p(-w_quad*(2 - w_quad)*(a - r)*(a + r)/a**2))/(numpy.pi*a**2)


def powerlaw_pressure_n1(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 1 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 1. Derived from: (5.59) for f = c_1 r^1.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_n1(E_star, a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*d*numpy.log((a + numpy.sqrt(a**2 - r**2))/r)/(numpy.pi*a)


def powerlaw_pressure_n2(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 2 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 2. Derived from: (5.59) for f = c_2 r^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_n2(E_star, a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d*numpy.sqrt(a**2 - r**2)/(numpy.pi*a**2)


def powerlaw_pressure_n3(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 3 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 3. Derived from: (5.59) for f = c_3 r^3.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_n3(E_star, a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (3/2)*E_star*d*(a*numpy.sqrt(a**2 - r**2) - r**2*numpy.log(r) + r**2*numpy.log(a + numpy.sqrt(a**2 - r**2)))/(numpy.pi*a**3)


def powerlaw_pressure_n4(E_star, a, d, r):
    """Contact pressure p(r) [Pa] of the power-law indenter n = 4 for 0 < r < a, in elementary functions.

    Chapter: Problem 7(d), n = 4. Derived from: (5.59) for f = c_4 r^4.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_pressure_n4(E_star, a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*E_star*d*numpy.sqrt(a**2 - r**2)*(a**2 + 2*r**2)/(numpy.pi*a**4)


def powerlaw_pressure_normalized(n, r_tilde):
    """Normalized pressure p/p_mean [1] at r_tilde = r/a < 1 of a power-law indenter (n >= 1.5).

    Chapter: Fig. 5.17. Derived from: (5.59) divided by (5.57)/(pi a^2).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_normalized_pressure_by_quadrature``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r_tilde : float or ndarray
        normalized radius r/a [1]
    """
    import functools
    import scipy.special

    return (1/2)*(n + 1)*scipy.special.hyp2f1(1, 1 - 1/2*n, 3/2, functools.reduce(numpy.maximum, [0, (1 - r_tilde)*(r_tilde + 1)]))*numpy.sqrt(functools.reduce(numpy.maximum, [0, (1 - r_tilde)*(r_tilde + 1)]))


def powerlaw_pressure_small_n(E_star, a, d, n, r):
    """Contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; the form accurate for n < 1.5 (singular like r^(n-1) at the centre for n < 1).

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x = r/sqrt(1 - z t).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_against_3d_elasticity``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools
    import scipy.special

    return E_star*a**(-n)*d*n*r**(n - 1)*scipy.special.hyp2f1(1/2, (1/2)*n + 1/2, 3/2, functools.reduce(numpy.maximum, [0, (a - r)*(a + r)])/a**2)*numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - r)*(a + r)]))/(numpy.pi*a)


def powerlaw_profile(c_n, n, r):
    """Height f(r) = c_n r^n [m] of a power-law profile above its tip (the profile whose g is powerlaw_g).

    Chapter: Problem 7(d). Derived from: the profile put through (5.52).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_tangential.py::test_profiles_against_their_g_by_5_53``.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(c_n) is float and type(n) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_profile(c_n, n, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return c_n*r**n


def powerlaw_punch_displacement_outside(a, d, r):
    """Surface displacement u_z(r) [m] outside a flat punch (r > a).

    Chapter: Problem 7(a). Derived from: the n -> infinity limit of (5.60) for the power
    law.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_punch_displacement_outside(a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*d*numpy.arcsin(a/r)/numpy.pi


def powerlaw_punch_force(E_star, a, d):
    """Normal force F [N] of a flat rigid punch of radius a at depth d.

    Chapter: Problem 7(a). Derived from: the n -> infinity limit of (5.57) for the power
    law.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_punch_force(E_star, a, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a*d


def powerlaw_punch_mean_pressure(E_star, a, d):
    """Mean pressure F/(pi a^2) [Pa] of a flat rigid punch of radius a at depth d.

    Chapter: Problem 7(a). Derived from: the punch's force over the contact area.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_punch_mean_pressure(E_star, a, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d/(numpy.pi*a)


def powerlaw_punch_pressure(E_star, a, d, r):
    """Contact pressure p(r) [Pa] under a flat rigid punch of radius a at depth d, r < a.

    Chapter: Problem 7(a). Derived from: (5.59) with q' = -E* d delta(x - a).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_punch``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(E_star) is float and type(a) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_powerlaw_punch_pressure(E_star, a, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*d/(numpy.pi*numpy.sqrt(a**2 - r**2))


def punch_depth_from_force(E_star, F, a):
    """Indentation depth d [m] of a flat rigid punch of radius a under the force F.

    Chapter: (5.11), inverted. Derived from: (5.11) F = 2 E* a d solved for d.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_punch_round_trip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(F) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_punch_depth_from_force(E_star, F, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F/(E_star*a)


def punch_pressure_displacement(E_star, a, p0):
    """Surface displacement u_z [m] inside a disc loaded by p0*(1 - r^2/a^2)^(-1/2).

    Chapter: (5.10). Derived from: (5.7) over the pressure (5.9).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_punch_displacement_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(E_star) is float and type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_punch_pressure_displacement(E_star, a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.pi*a*p0/E_star


def punch_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) loaded by p0*(1 - r^2/a^2)^(-1/2).

    Chapter: Fig. 5.2 (n = -1/2), Problem 7(a). Derived from: (5.7) over the pressure (5.9).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(p0) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_punch_pressure_displacement_outside(E_star, a, p0, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*p0*numpy.arcsin(a/r)/E_star


def punch_pressure_force(a, p0):
    """Total force F [N] of the pressure p0*(1 - r^2/a^2)^(-1/2).

    Chapter: (5.11). Derived from: the integral of (5.9) times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_punch_pressure_force(a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*numpy.pi*a**2*p0


def punch_stiffness(E_star, a):
    """Stiffness k = F/u_z [N/m] of a flat rigid circular punch of radius a.

    Chapter: (5.12). Derived from: (5.11) divided by (5.10).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_punch_stiffness_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_punch_stiffness(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a


def shear_modulus(E, nu):
    """Shear modulus G [Pa] of an isotropic body.

    Chapter: Lame's mu (not in the chapter). Derived from: Hooke's law in Lame's form.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(E) is float and type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_shear_modulus(E, nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_depth(R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*a*numpy.log1p(2*a/(R - a))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    import scipy.special

    return numpy.where(numpy.less(a, (1/2)*R), E_star*R**2*((1/2)*a**2*numpy.log1p(2*a/(R - a))/R**2 + (1/3)*a**3*scipy.special.hyp2f1(1, 3/2, 5/2, a**2/R**2)/R**3), E_star*(-R*a + (1/2)*(R**2 + a**2)*numpy.log1p(2*a/(R - a))))


def sphere_g(R, x):
    """MDR profile g(x) [m] of the spherical cap, 0 <= x < R.

    Chapter: (5.52), Sneddon's sphere. Derived from: (5.52) with r = sqrt(x^2 - v^2).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Printed in a stable form: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R
    - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_g(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*x*numpy.log1p(2*x/(R - x))


def sphere_lam_contact_radius(R, lam):
    """Contact radius a = R tanh(lam) [m] of a rigid spherical cap.

    Chapter: (5.55), Sneddon's sphere. Derived from: the definition lam = atanh(a/R).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    if type(R) is float and type(lam) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_lam_contact_radius(R, lam)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R*numpy.tanh(lam)


def sphere_lam_depth(R, lam):
    """Indentation depth d [m] of a rigid spherical cap at lam = atanh(a/R).

    Chapter: (5.55), Sneddon's sphere. Derived from: (5.55) at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    if type(R) is float and type(lam) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_lam_depth(R, lam)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R*lam*numpy.tanh(lam)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    import scipy.special

    return numpy.where(numpy.less(lam, 1/2), E_star*R**2*(lam*numpy.tanh(lam)**2 + (1/3)*numpy.tanh(lam)**3*scipy.special.hyp2f1(1, 3/2, 5/2, numpy.tanh(lam)**2)), E_star*R**2*(lam*(numpy.tanh(lam)**2 + 1) - numpy.tanh(lam)))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(R) is float and type(lam) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_lam_pressure_pole(E_star, R, lam, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*R*numpy.log1p(2*numpy.sqrt(R*numpy.tanh(lam) - r)*numpy.sqrt(R*numpy.tanh(lam) + r)*(numpy.sqrt(R - r)*numpy.sqrt(R + r) + numpy.sqrt(R*numpy.tanh(lam) - r)*numpy.sqrt(R*numpy.tanh(lam) + r))*numpy.cosh(lam)**2/R**2)/(numpy.pi*numpy.sqrt(R - r)*numpy.sqrt(R + r))


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(E_star) is float and type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_pressure_atanh_kernel(E_star, R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*numpy.log1p(2*x/(R - x))/(numpy.pi*x)


def sphere_profile(R, r):
    """Height f(r) [m] of a spherical cap of radius R above its apex, 0 <= r <= R.

    Chapter: (5.52), Sneddon's sphere. Derived from: the sphere x^2 + (R - z)^2 = R^2.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Printed in a stable form: R - sqrt(R^2 - r^2) cancels for r << R; it is written r^2/(R +
    sqrt((R - r)(R + r))).

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_profile(R, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return r**2/(R + numpy.sqrt(R - r)*numpy.sqrt(R + r))


def sphere_stiffness(E_star, a):
    """Differential stiffness dF/dd [N/m] of a rigid spherical cap at contact radius a.

    Chapter: Problem 5, Sneddon's sphere. Derived from: (dF/da)/(dd/da) of (5.57) and
    (5.55).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_stiffness``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_sphere_stiffness(E_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a


def stress_axis_max_shear(a, nu, p0, z):
    """Maximum shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis under the Hertz pressure.

    Chapter: Fig. 5.8. Derived from: (5.48), (5.49).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_axis_max_shear(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/4)*p0*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2))


def stress_axis_max_shear_bracket(a, nu):
    """Depth z_lo [m] on the axis where d(tau_1)/dz > 0 for -1 < nu <= 1/2: the lower end of the bracket [z_lo, 2a] of the maximum shear stress.

    Chapter: Fig. 5.8. Derived from: lower bounds of the terms of d(tau_1)/dz
    (stress_axis_max_shear_slope).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear_bracket``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(a) is float and type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_axis_max_shear_bracket(a, nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.pi*a*(nu + 1)/(8*nu + 20)


def stress_axis_max_shear_slope(a, nu, p0, z):
    """D(tau_1)/dz [Pa/m] on the axis under the Hertz pressure; its root is the depth of the maximum shear stress.

    Chapter: Fig. 5.8. Derived from: the derivative of tau_1.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_maximum_shear``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_axis_max_shear_slope(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*p0*z*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2)**2) + (1/4)*p0*(-4*a*z*(nu + 1) - 2*a*(a**2 + z**2)*(nu + 1)/(z*(a**2/z**2 + 1)) + 4*z**2*(nu + 1)*numpy.arctan(a/z) + 2*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2))


def stress_axis_sigma_xx(a, nu, p0, z):
    """Radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure, the form of (5.49) (for z < a).

    Chapter: (5.49). Derived from: (5.41) superposed over (5.15) along the axis.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_axis_sigma_xx(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2))


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
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    import scipy.special

    return p0*(-a**4*((2/15)*nu + 2/15)*scipy.special.hyp2f1(2, 5/2, 7/2, -a**2/z**2)/z**4 + a**2*(1 - 2*nu)/(z**2*(6*a**2/z**2 + 6)))


def stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis under the Hertz pressure.

    Chapter: (5.48). Derived from: (5.43) superposed over (5.15) along the axis, (5.47).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Printed in a stable form: one division, no cancellation.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_axis_sigma_zz(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_max_orthogonal_shear(p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt(2)*p0*(5 - numpy.sqrt(17))**(3/2)/numpy.sqrt(-5 + 3*numpy.sqrt(17))


def stress_hertz_max_orthogonal_shear_r(a):
    """Distance r [m] from the axis of the largest |tau_rz| under the Hertz pressure.

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    """
    if type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_max_orthogonal_shear_r(a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.sqrt(7/4 - 1/4*numpy.sqrt(17))


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
    a : float or ndarray
        contact radius [m]
    """
    if type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_max_orthogonal_shear_z(a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a/numpy.sqrt(4 + numpy.sqrt(17))


def stress_hertz_sigma_rr(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta) (for xi < 1).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : float or ndarray
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    if (type(nu) is float and type(p0) is float and type(xi) is float and type(eta) is float
            and type(chi) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_sigma_rr(nu, p0, xi, eta, chi)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*(-numpy.arctan(xi) + (1/2)*numpy.pi) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


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
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : float or ndarray
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    import scipy.special

    return p0*(-chi**2*eta*xi**(-2.0)/((xi**(-2.0) + 1)*(eta**2*xi**(-2.0) + 1)) - 2/15*eta*xi**(-4.0)*(nu + 1)*scipy.special.hyp2f1(1, 3/2, 7/2, -xi**(-2.0))/(xi**(-2.0) + 1) + xi**(-2.0)*(1 - 2*nu)/((3*eta + 3)*(xi**(-2.0) + 1)))


def stress_hertz_sigma_tt(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta) (for xi < 1).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    if type(nu) is float and type(p0) is float and type(xi) is float and type(eta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_sigma_tt(nu, p0, xi, eta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(-eta*(nu + 1)*(-xi*(-numpy.arctan(xi) + (1/2)*numpy.pi) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


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
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    import scipy.special

    return p0*(-2/15*eta*xi**(-4.0)*(nu + 1)*scipy.special.hyp2f1(1, 3/2, 7/2, -xi**(-2.0))/(xi**(-2.0) + 1) + xi**(-2.0)*(1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**(-2.0) + 1)))


def stress_hertz_sigma_zz(p0, xi, eta):
    """Normal stress sigma_zz [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    if type(p0) is float and type(xi) is float and type(eta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_sigma_zz(p0, xi, eta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -eta**3*p0/(eta**2 + xi**2)


def stress_hertz_tau_rz(p0, xi, eta, chi):
    """Shear stress tau_rz [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) of the contact disc, eta = cos(beta), chi = sin(beta).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : float or ndarray
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    if (type(p0) is float and type(xi) is float and type(eta) is float and
            type(chi) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_stress_hertz_tau_rz(p0, xi, eta, chi)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -chi*eta**2*p0*xi/((eta**2 + xi**2)*numpy.sqrt(xi**2 + 1))


def stress_spheroidal_cos_beta_inside(a, r, z):
    """Cos(beta) = z/u^(1/2) [1] for r^2 + z^2 < a^2 (finite at z = 0).

    Chapter: Johnson (1985), (3.44). Derived from: z/u^(1/2) with u = 2 a^2 z^2/(D - q)
    (stress_spheroidal_u_inside): z cancels.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(r) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_spheroidal_cos_beta_inside(a, r, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(-1/2*z**2 - 1/2*(-a + r)*(a + r) + (1/2)*numpy.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2))/a


def stress_spheroidal_u(a, r, z):
    """Johnson's u [m^2], the root of r^2/(a^2 + u) + z^2/u = 1 (for r^2 + z^2 >= a^2).

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Printed in a stable form: the expanded discriminant cancels near the contact edge; q =
    (r - a)(r + a) + z^2 keeps it exact.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(r) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_spheroidal_u(a, r, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*z**2 + (1/2)*(-a + r)*(a + r) + (1/2)*numpy.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2)


def stress_spheroidal_u_inside(a, r, z):
    """Johnson's u [m^2] for r^2 + z^2 < a^2.

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Printed in a stable form: (q + D)/2 cancels for q = r^2 + z^2 - a^2 < 0; written as 2
    a^2 z^2/(D - q).

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(r) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_stress_spheroidal_u_inside(a, r, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a**2*z**2/(-z**2 - (-a + r)*(a + r) + numpy.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2))


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
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_yy : float or ndarray
        normal stress component sigma_yy [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xy : float or ndarray
        shear stress component tau_xy [Pa]
    tau_yz : float or ndarray
        shear stress component tau_yz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if (type(sigma_xx) is float and type(sigma_yy) is float and type(sigma_zz) is float and
            type(tau_xy) is float and type(tau_yz) is float and type(tau_xz) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt(2)*numpy.sqrt(6*tau_xy**2 + 6*tau_xz**2 + 6*tau_yz**2 + (sigma_xx - sigma_yy)**2 + (sigma_xx - sigma_zz)**2 + (-sigma_yy + sigma_zz)**2)


def strip_mean_pressure(F, L, a):
    """Mean pressure F/(2 a L) [Pa] over a contact strip of half-width a and length L.

    Chapter: (5.34)-(5.37). Derived from: the definition of the mean pressure over a strip.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_mean_pressure_strip``.

    Parameters
    ----------
    F : float or ndarray
        normal force [N]
    L : float or ndarray
        length of a line contact [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(F) is float and type(L) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_strip_mean_pressure(F, L, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F/(L*a)


def tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a cone under normal force F and tangential F_x.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^2, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: 1 - sqrt(1 - F_x/(mu F)) cancels as F_x -> 0.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_cone_displacement(a, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return F_x/(G_star*a*(numpy.sqrt(1 - F_x/(F*mu_f)) + 1))


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
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_cone_energy(a, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*F_amp**3/(F*G_star*a*mu_f*(numpy.sqrt(1 - F_amp/(F*mu_f)) + 1)**3)


def tangential_cone_force(a, theta, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a cone displaced by u_x (monotonic, constant load).

    Chapter: MDR tangential, cone (not in the chapter). Derived from: sum of the stuck and
    sliding springs.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(theta) is float and type(E_star) is float and
            type(G_star) is float and type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_cone_force(a, theta, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*G_star*u_x*(numpy.pi*E_star*a*mu_f - G_star*u_x/numpy.tan(theta))/(numpy.pi*E_star*mu_f)


def tangential_cone_stick_radius(a, theta, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a cone (angle theta to the plane) displaced by u_x.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: g(c) = d - G* u_x/(mu
    E*), g = (pi/2) tan(theta) x.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(theta) is float and type(E_star) is float and
            type(G_star) is float and type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_cone_stick_radius(a, theta, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a - 2*G_star*u_x/(numpy.pi*E_star*mu_f*numpy.tan(theta))


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
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    c : float or ndarray
        radius of the stick zone [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(a) is float and type(c) is float and type(theta) is float
            and type(E_star) is float and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*mu_f*numpy.tan(theta)*numpy.log1p((a - c)*((a + c)/(numpy.sqrt(a - r)*numpy.sqrt(a + r) + numpy.sqrt(c - r)*numpy.sqrt(c + r)) + 1)/(c + numpy.sqrt(c - r)*numpy.sqrt(c + r)))


def tangential_modulus(G1, nu1, G2, nu2):
    """Tangential effective modulus G* [Pa] of two elastic bodies.

    Chapter: MDR tangential springs (not in the chapter). Derived from: direction average of
    the Cerruti surface compliance of each body, compliances added.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Printed in a stable form: a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf.

    Parameters
    ----------
    G1 : float or ndarray
        shear modulus of body 1 [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    G2 : float or ndarray
        shear modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(G1) is float and type(nu1) is float and type(G2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_modulus(G1, nu1, G2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return ((1/4)*(2 - nu2)/G2 + (1/4)*(2 - nu1)/G1)**(-1.0)


def tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a power-law profile under normal force F and tangential force F_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: c from F_x, then
    g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Printed in a stable form: 1 - (1 - F_x/(mu F))^(n/(n+1)) cancels as F_x -> 0.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(G_star) is float
            and type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*F*mu_f*(n + 1)*numpy.expm1(n*numpy.log1p(-F_x/(F*mu_f))/(n + 1))/(G_star*a*n)


def tangential_powerlaw_energy(a, n, F, G_star, mu_f, c_a):
    """Energy W [J] dissipated per cycle by a power-law profile under normal force F whose stick zone at the amplitude has the radius c = c_a a (cancels for c_a -> 1: numeric/tangential.py integrates the density there).

    Chapter: MDR tangential, power law (not in the chapter). Derived from: sum of the
    sliding springs' parallelogram loops.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    c_a : float or ndarray
        stick ratio c/a (stick radius over contact radius) [1]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(G_star) is float
            and type(mu_f) is float and type(c_a) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_energy(a, n, F, G_star, mu_f, c_a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
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
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    d_c : float or ndarray
        stick deficit 1 - c/a (c the stick radius, a the contact radius) [1]
    s_x : float or ndarray
        position (x - c)/(a - c) in the slip zone c < x < a, in (0, 1) [1]
    """
    if type(n) is float and type(d_c) is float and type(s_x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_energy_density(n, d_c, s_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -(1 - d_c)**n*numpy.expm1(n*numpy.log1p(-d_c*(1 - s_x)))*numpy.expm1(n*numpy.log1p(d_c*s_x/(1 - d_c)))


def tangential_powerlaw_energy_scale(a, n, F, G_star, mu_f):
    """Energy per cycle [J] of a power-law profile per unit of d_c times the integral of tangential_powerlaw_energy_density over 0 < s_x < 1.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: the sliding
    springs' loops with x = a (1 - d_c (1 - s_x)), q_z ~ a^n - x^n.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(G_star) is float
            and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_energy_scale(a, n, F, G_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*F**2*mu_f**2*(n + 1)**2/(G_star*a*n**2)


def tangential_powerlaw_energy_small(a, n, F, G_star, mu_f, F_amp):
    """Leading term [J] of the energy per cycle of a power-law profile at small amplitude.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: series in F_amp
    of the energy per cycle.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cubic_small_amplitude_law``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(G_star) is float
            and type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_energy_small(a, n, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/3)*F_amp**3/(F*G_star*a*mu_f*(n + 1))


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
    a : float or ndarray
        contact radius [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(c_n) is float and type(n) is float and
            type(kappa_n) is float and type(E_star) is float and type(G_star) is float and
            type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -2*E_star*a**(n + 1)*c_n*kappa_n*mu_f*n*numpy.expm1((n + 1)*numpy.log1p(-G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)/(n + 1)


def tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """1 - c/a [1] of a power-law profile under normal force F and tangential force F_amp.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Printed in a stable form: 1 - (1 - F_amp/(mu F))^(1/(n+1)) cancels at small amplitude.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(n) is float and type(F) is float and type(mu_f) is float and
            type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.expm1(numpy.log1p(-F_amp/(F*mu_f))/(n + 1))


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
    a : float or ndarray
        contact radius [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(c_n) is float and type(n) is float and
            type(kappa_n) is float and type(E_star) is float and type(G_star) is float and
            type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.exp(numpy.log1p(-G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)


def tangential_powerlaw_stick_radius_from_force(a, n, F, mu_f, F_x):
    """Stick radius c [m] of a power-law profile under normal force F and tangential F_x.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(mu_f) is float
            and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_stick_radius_from_force(a, n, F, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*(1 - F_x/(F*mu_f))**((n + 1)**(-1.0))


def tangential_powerlaw_traction_stick_centre(r_c, a, c, c_n, n, kappa_n, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone of a power-law profile near the axis, r = r_c c <= c/2, 0 < n < 3, n != 1 (the cone): finite on the axis, where each of the two pressures of mu (p(r; a) - p(r; c)) is infinite for n <= 1; the series to r_c^54, the rest below (4/3) 4^-28 of it.

    Chapter: MDR tangential, power law (not in the chapter), (5.59). Derived from: (5.59) of
    the stuck springs' line load: (E*/pi) integral_c^a g'(x)/sqrt(x^2 - r^2) dx, its kernel
    expanded in (r/x)^2 and integrated termwise.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_powerlaw_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r_c : float or ndarray
        ratio r/c of the radial coordinate to the stick radius [1]
    a : float or ndarray
        contact radius [m]
    c : float or ndarray
        radius of the stick zone [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r_c) is float and type(a) is float and type(c) is float and type(c_n) is float
            and type(n) is float and type(kappa_n) is float and type(E_star) is float and
            type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_traction_stick_centre(r_c, a, c, c_n, n, kappa_n, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*c**(n - 1)*c_n*kappa_n*mu_f*n*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*(r_c**2*((121683714103007/1125899906842624)*r_c**2*numpy.expm1((n - 55)*numpy.log1p((a - c)/c))/(n - 55) + (61989816618513/562949953421312)*numpy.expm1((n - 53)*numpy.log1p((a - c)/c))/(n - 53)) + (15801325804719/140737488355328)*numpy.expm1((n - 51)*numpy.log1p((a - c)/c))/(n - 51)) + (8061900920775/70368744177664)*numpy.expm1((n - 49)*numpy.log1p((a - c)/c))/(n - 49)) + (514589420475/4398046511104)*numpy.expm1((n - 47)*numpy.log1p((a - c)/c))/(n - 47)) + (263012370465/2199023255552)*numpy.expm1((n - 45)*numpy.log1p((a - c)/c))/(n - 45)) + (67282234305/549755813888)*numpy.expm1((n - 43)*numpy.log1p((a - c)/c))/(n - 43)) + (34461632205/274877906944)*numpy.expm1((n - 41)*numpy.log1p((a - c)/c))/(n - 41)) + (4418157975/34359738368)*numpy.expm1((n - 39)*numpy.log1p((a - c)/c))/(n - 39)) + (2268783825/17179869184)*numpy.expm1((n - 37)*numpy.log1p((a - c)/c))/(n - 37)) + (583401555/4294967296)*numpy.expm1((n - 35)*numpy.log1p((a - c)/c))/(n - 35)) + (300540195/2147483648)*numpy.expm1((n - 33)*numpy.log1p((a - c)/c))/(n - 33)) + (9694845/67108864)*numpy.expm1((n - 31)*numpy.log1p((a - c)/c))/(n - 31)) + (5014575/33554432)*numpy.expm1((n - 29)*numpy.log1p((a - c)/c))/(n - 29)) + (1300075/8388608)*numpy.expm1((n - 27)*numpy.log1p((a - c)/c))/(n - 27)) + (676039/4194304)*numpy.expm1((n - 25)*numpy.log1p((a - c)/c))/(n - 25)) + (88179/524288)*numpy.expm1((n - 23)*numpy.log1p((a - c)/c))/(n - 23)) + (46189/262144)*numpy.expm1((n - 21)*numpy.log1p((a - c)/c))/(n - 21)) + (12155/65536)*numpy.expm1((n - 19)*numpy.log1p((a - c)/c))/(n - 19)) + (6435/32768)*numpy.expm1((n - 17)*numpy.log1p((a - c)/c))/(n - 17)) + (429/2048)*numpy.expm1((n - 15)*numpy.log1p((a - c)/c))/(n - 15)) + (231/1024)*numpy.expm1((n - 13)*numpy.log1p((a - c)/c))/(n - 13)) + (63/256)*numpy.expm1((n - 11)*numpy.log1p((a - c)/c))/(n - 11)) + (35/128)*numpy.expm1((n - 9)*numpy.log1p((a - c)/c))/(n - 9)) + (5/16)*numpy.expm1((n - 7)*numpy.log1p((a - c)/c))/(n - 7)) + (3/8)*numpy.expm1((n - 5)*numpy.log1p((a - c)/c))/(n - 5)) + (1/2)*numpy.expm1((n - 3)*numpy.log1p((a - c)/c))/(n - 3)) + numpy.expm1((n - 1)*numpy.log1p((a - c)/c))/(n - 1))/numpy.pi


def tangential_powerlaw_traction_stick_integrand(r, s_r, c_n, n, kappa_n, E_star, mu_f):
    """Integrand [Pa/m] of the stick-zone traction of a power-law profile in s = sqrt(x^2 - r^2): q(r) = its integral from sqrt(c^2 - r^2) to sqrt(a^2 - r^2), smooth there for every r < c.

    Chapter: MDR tangential, power law (not in the chapter), (5.59). Derived from: (5.59) of
    the stuck springs' line load over c < x < a with x^2 = r^2 + s^2.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_powerlaw_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    s_r : float or ndarray
        sqrt(x^2 - r^2), the integration variable of (5.59) beyond x = r [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(s_r) is float and type(c_n) is float and type(n) is float
            and type(kappa_n) is float and type(E_star) is float and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_powerlaw_traction_stick_integrand(r, s_r, c_n, n, kappa_n, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*c_n*kappa_n*mu_f*n*(r**2 + s_r**2)**((1/2)*n - 1)/numpy.pi


def tangential_slide_onset(E_star, G_star, mu_f, d):
    """Tangential displacement u_x [m] at which the last spring (the centre, g(0) = 0) starts to slide, depth d (d = g(a), or the flat punch's depth).

    Chapter: MDR tangential springs (not in the chapter). Derived from: G* u_x = mu q_z(0) =
    mu E* d, where the stick radius closes (asserted per profile).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_slide_onset_against_the_normal_force``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    d : float or ndarray
        indentation depth [m]
    """
    if (type(E_star) is float and type(G_star) is float and type(mu_f) is float and
            type(d) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_slide_onset(E_star, G_star, mu_f, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*d*mu_f/G_star


def tangential_stiffness(G_star, a):
    """Tangential contact stiffness k_x = dF_x/du_x [N/m] before any slip (c = a).

    Chapter: MDR tangential springs (not in the chapter). Derived from: sum of the 2a/dx
    stuck springs of stiffness G* dx.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_initial_stiffness_is_2_G_star_a_for_every_profile``.

    Parameters
    ----------
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    a : float or ndarray
        contact radius [m]
    """
    if type(G_star) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_stiffness(G_star, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*G_star*a


def tangential_stiffness_ratio(nu):
    """G*/E* [1] = tangential over normal contact stiffness of one elastic body on a rigid one.

    Chapter: MDR tangential springs (not in the chapter). Derived from: Cerruti and
    Boussinesq compliances of the same body, G = E/(2 (1 + nu)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_stiffness_ratio(nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*(nu - 1)/(nu - 2)


def tangential_traction_slip(mu_f, p_a):
    """Tangential traction q [Pa] in the slip zone: mu p(r; a) of the pressure p_a [Pa].

    Chapter: MDR tangential (Ciavarella-Jaeger, found). Derived from: (5.59) of the sliding
    springs' line load mu q_z.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_against_the_line_load_quadrature``.

    Parameters
    ----------
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    p_a : float or ndarray
        contact pressure p(r; a) of a profile at contact radius a [Pa]
    """
    if type(mu_f) is float and type(p_a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_traction_slip(mu_f, p_a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return mu_f*p_a


def tangential_traction_stick(mu_f, p_a, p_c):
    """Tangential traction q [Pa] in the stick zone r < c: mu (p(r; a) - p(r; c)) of the pressures p_a, p_c [Pa] of the profile at contact radii a and c.

    Chapter: MDR tangential (Ciavarella-Jaeger, found). Derived from: (5.59) of the stuck
    springs' line load mu (q_z(x; a) - q_z(x; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_against_the_line_load_quadrature``.

    Parameters
    ----------
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    p_a : float or ndarray
        contact pressure p(r; a) of a profile at contact radius a [Pa]
    p_c : float or ndarray
        contact pressure p(r; c) of the same profile at contact radius c (the stick radius) [Pa]
    """
    if type(mu_f) is float and type(p_a) is float and type(p_c) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_tangential_traction_stick(mu_f, p_a, p_c)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return mu_f*(p_a - p_c)


def uniform_pressure_displacement(E_star, a, p0, r):
    """Surface displacement u_z [m] inside a disc (r <= a) under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0); the phi-integral is 4 a
    E(r^2/a^2).

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return 4*a*p0*scipy.special.ellipe(r**2/a**2)/(numpy.pi*E_star)


def uniform_pressure_displacement_centre(E_star, a, p0):
    """Displacement u_z(0) [m] at the centre of a disc under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0) at r = 0.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(E_star) is float and type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_uniform_pressure_displacement_centre(E_star, a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*a*p0/E_star


def uniform_pressure_displacement_edge(E_star, a, p0):
    """Displacement u_z(a) [m] at the edge of a disc under a uniform pressure p0.

    Chapter: Problem 6. Derived from: (5.7) with p = p0 (n = 0) at r = a.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(E_star) is float and type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_uniform_pressure_displacement_edge(E_star, a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 4*a*p0/(numpy.pi*E_star)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return a**2*p0*scipy.special.hyp2f1(1/2, 1/2, 2, a**2/r**2)/(E_star*r)


def uniform_pressure_force(a, p0):
    """Total force F [N] of a uniform pressure p0 on a disc of radius a.

    Chapter: Problem 6. Derived from: the integral of p0 times 2 pi r over the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_force_by_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(a) is float and type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_uniform_pressure_force(a, p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.pi*a**2*p0


def worn_contact_radius(R, b, d):
    """Contact radius a [m] of the worn paraboloid at depth d > 0.

    Chapter: Problem 8. Derived from: (5.55) solved for a^2.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(R) is float and type(b) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_contact_radius(R, b, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt((1/2)*b**2 + (1/2)*numpy.sqrt(4*R**2*d**2 + b**4))


def worn_depth(R, a, b):
    """Indentation depth d [m] of the worn paraboloid at contact radius a > b.

    Chapter: Problem 8. Derived from: (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    """
    if type(R) is float and type(a) is float and type(b) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_depth(R, a, b)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.sqrt(a**2 - b**2)/R


def worn_displacement_inside(R, b, d, r):
    """Surface displacement u_z(r) [m] inside the contact (r <= a) of the worn paraboloid.

    Chapter: Problem 8, (5.60). Derived from: (5.60) of u = d - g(x) (5.54) for r <= a,
    which (5.53) makes d - f(r).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools

    if type(R) is float and type(b) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_displacement_inside(R, b, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return d - 1/2*functools.reduce(numpy.maximum, [0, (-b + r)*(b + r)])/R


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
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return (2*a*numpy.sqrt(a**2 - b**2)*numpy.arcsin(a/r) - 1/3*numpy.sqrt((a**2 - b**2)/(-b**2 + r**2))*(2*a**2 - 2*b**2)*scipy.special.hyp2f1(1/2, 3/2, 5/2, (a**2 - b**2)/(-b**2 + r**2)))/(numpy.pi*R)


def worn_force(E_star, R, b, d):
    """Normal force F [N] of the worn paraboloid at depth d.

    Chapter: Problem 8. Derived from: (5.57) at the contact radius of (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Printed in a stable form: sqrt(-1 + sqrt(1 + s^2)), s = 2 R d/b^2, cancels for s << 1;
    it is written s/sqrt(sqrt(1 + s^2) + 1).

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(b) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_force(E_star, R, b, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2/3)*numpy.sqrt(2)*E_star*b*d*(numpy.sqrt(4*R**2*d**2/b**4 + 1) + 2)/numpy.sqrt(numpy.sqrt(4*R**2*d**2/b**4 + 1) + 1)


def worn_force_from_radius(E_star, R, a, b):
    """Normal force F [N] of the worn paraboloid at contact radius a > b.

    Chapter: Problem 8. Derived from: (5.57) with d = g(a).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    """
    if type(E_star) is float and type(R) is float and type(a) is float and type(b) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_force_from_radius(E_star, R, a, b)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2/3)*E_star*numpy.sqrt(a - b)*numpy.sqrt(a + b)*(2*a**2 + b**2)/R


def worn_g(R, b, x):
    """MDR profile g(x) [m] of the worn paraboloid (0 for x < b).

    Chapter: Problem 8. Derived from: (5.52) for f = (r^2 - b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_g_by_quadrature``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : float or ndarray
        coordinate [m]
    """
    import functools

    if type(R) is float and type(b) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_g(R, b, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return x*numpy.sqrt(functools.reduce(numpy.maximum, [0, (-b + x)*(b + x)]))/R


def worn_pressure(E_star, R, a, b, r):
    """Contact pressure p(r) [Pa] of the worn paraboloid (log-infinite at r = b, 0 for r >= a).

    Chapter: Problem 8, (5.59). Derived from: (5.59) of g, in incomplete elliptic integrals
    (mdr.elliptic_abel_integral).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools
    import scipy.special

    return E_star*(2*a*numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - functools.reduce(numpy.maximum, [b, r]))*(a + functools.reduce(numpy.maximum, [b, r]))]))/numpy.sqrt((functools.reduce(numpy.maximum, [b, r]) - functools.reduce(numpy.minimum, [b, r]))*(functools.reduce(numpy.maximum, [b, r]) + functools.reduce(numpy.minimum, [b, r])) + functools.reduce(numpy.maximum, [0, (a - functools.reduce(numpy.maximum, [b, r]))*(a + functools.reduce(numpy.maximum, [b, r]))])) + (-b**2 + 2*functools.reduce(numpy.maximum, [b, r])**2)*scipy.special.ellipkinc(numpy.arctan2(numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - functools.reduce(numpy.maximum, [b, r]))*(a + functools.reduce(numpy.maximum, [b, r]))])), numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) - functools.reduce(numpy.minimum, [b, r]))*numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) + functools.reduce(numpy.minimum, [b, r]))), functools.reduce(numpy.minimum, [b, r])**2/functools.reduce(numpy.maximum, [b, r])**2)/functools.reduce(numpy.maximum, [b, r]) - 2*scipy.special.ellipeinc(numpy.arctan2(numpy.sqrt(functools.reduce(numpy.maximum, [0, (a - functools.reduce(numpy.maximum, [b, r]))*(a + functools.reduce(numpy.maximum, [b, r]))])), numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) - functools.reduce(numpy.minimum, [b, r]))*numpy.sqrt(functools.reduce(numpy.maximum, [b, r]) + functools.reduce(numpy.minimum, [b, r]))), functools.reduce(numpy.minimum, [b, r])**2/functools.reduce(numpy.maximum, [b, r])**2)*functools.reduce(numpy.maximum, [b, r]))/(numpy.pi*R)


def worn_profile(R, b, r):
    """Height f(r) [m] of the worn paraboloid's surface above its tip (0 for r < b).

    Chapter: Problem 8. Derived from: the paraboloid r^2/(2R) worn flat to the radius b.

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn_numeric.py::test_inside_displacement_is_d_minus_f``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import functools

    if type(R) is float and type(b) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_worn_profile(R, b, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*functools.reduce(numpy.maximum, [0, (-b + r)*(b + r)])/R


def textbook_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """Slope g'(x) [1] of the MDR profile of the power law f = c_n r^n, x > 0, in the derived (textbook) form; use adhesion_powerlaw_g_slope: x^n/x is 0/0 at x = 0 and overflows before x^(n - 1) does.

    Chapter: (5.52), Problem 7(d). Derived from: the derivative of (5.52) for f = c_n r^n, g
    = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    x : float or ndarray
        coordinate [m]
    """
    if (type(c_n) is float and type(kappa_n) is float and type(n) is float and
            type(x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return c_n*kappa_n*n*x**n/x


def textbook_adhesion_pressure_edge(E_star, a, dgamma, r):
    """Adhesive term of the contact pressure p(r) [Pa] for r < a (negative: tension; add the non-adhesive pressure of radius a), in the derived (textbook) form; use adhesion_pressure_edge: a^2 - r^2 loses the digits of a - r next to the edge, where the term is largest; written (a - r)(a + r).

    Chapter: (5.59), adhesive. Derived from: (5.59) with the jump of q(x) at x = a.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(a) is float and type(dgamma) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_adhesion_pressure_edge(E_star, a, dgamma, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -numpy.sqrt(2)*numpy.sqrt(E_star)*numpy.sqrt(a)*numpy.sqrt(dgamma)/(numpy.sqrt(numpy.pi)*numpy.sqrt(a**2 - r**2))


def textbook_adhesion_sphere_g_slope(R, x):
    """Slope g'(x) [1] of the MDR profile of the exact sphere, 0 <= x < R, in the derived (textbook) form; use adhesion_sphere_g_slope: atanh(x/R) as log1p(2x/(R - x))/2 and R^2 - x^2 as (R - x)(R + x), exact as x -> R where the slope is largest.

    Chapter: (5.52), Sneddon's sphere. Derived from: the derivative of (5.52) for the
    spherical cap.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_adhesion_sphere_g_slope(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (R*x + (R**2 - x**2)*numpy.arctanh(x/R))/(R**2 - x**2)


def textbook_adhesion_worn_g_slope(R, b, x):
    """Slope g'(x) [1] of the MDR profile of the worn paraboloid for x > b (0 for x < b; infinite at the kink x = b+), in the derived (textbook) form; use adhesion_worn_g_slope: x^2 - b^2 as (x - b)(x + b), exact next to the kink.

    Chapter: (5.52), Problem 8. Derived from: the derivative of (5.52) for f = (r^2 -
    b^2)/(2R), r > b.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_g_slopes_by_differences``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(b) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_adhesion_worn_g_slope(R, b, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-b**2 + 2*x**2)/(R*numpy.sqrt(-b**2 + x**2))


def textbook_bodies_crossed_cylinders_curvature_2(R1, R2, alpha):
    """Smaller principal curvature [1/m] of the gap of two cylinders crossed at alpha, in the derived (textbook) form; use bodies_crossed_cylinders_curvature_2: written with the curvatures 1/R so that R = inf (flat) works; the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det a sum of products, positive for convex bodies: no cancellation.

    Chapter: (5.32), (5.33), any angle. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    alpha : float or ndarray
        angle between the axes of two crossed cylinders [rad]
    """
    if type(R1) is float and type(R2) is float and type(alpha) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_bodies_crossed_cylinders_curvature_2(R1, R2, alpha)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*numpy.sqrt((numpy.cos(2*alpha)/R2 + R1**(-1.0))**2 + numpy.sin(2*alpha)**2/R2**2) + (1/2)/R2 + (1/2)/R1


def textbook_bodies_effective_modulus(E1, nu1, E2, nu2):
    """Effective modulus E* [Pa] of two elastic bodies, in the derived (textbook) form; use bodies_effective_modulus: 1/E* as the sum of the compliances, which accepts E2 = inf (rigid), with 1 - nu^2 = (1 - nu)(1 + nu) exact in floating point for nu near -1.

    Chapter: (5.26). Derived from: the sum of the two surface displacements (5.6), (5.7)
    under one pressure.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Parameters
    ----------
    E1 : float or ndarray
        Young's modulus of body 1 [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    E2 : float or ndarray
        Young's modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(E1) is float and type(nu1) is float and type(E2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_bodies_effective_modulus(E1, nu1, E2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -E1*E2/(E1*nu2**2 - E1 + E2*nu1**2 - E2)


def textbook_bodies_effective_modulus_rigid(E, nu):
    """Effective modulus E* [Pa] of an elastic body against a rigid one, in the derived (textbook) form; use bodies_effective_modulus_rigid: 1 - nu^2 = (1 - nu)(1 + nu) is exact in floating point for nu near -1, where 1 - nu^2 cancels.

    Chapter: (5.8), (5.26) with E2 -> inf. Derived from: the limit E2 -> inf of (5.26).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_modulus_by_two_displacements``.

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa]
    nu : float or ndarray
        Poisson's ratio [1]
    """
    if type(E) is float and type(nu) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_bodies_effective_modulus_rigid(E, nu)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -E/(nu**2 - 1)


def textbook_bodies_effective_radius(R1, R2):
    """Effective radius R [m] of two spheres (negative radius: concave), in the derived (textbook) form; use bodies_effective_radius: the sum of the curvatures accepts R = inf (flat).

    Chapter: (5.27). Derived from: the sum of the two gaps r^2/(2 R_i).

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_effective_radius_by_gap``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    R2 : float or ndarray
        radius of curvature of body 2, or second principal radius [m]
    """
    if type(R1) is float and type(R2) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_bodies_effective_radius(R1, R2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R1*R2/(R1 + R2)


def textbook_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega):
    """Smaller principal curvature kappa_2 [1/m] of the gap between two bodies, in the derived (textbook) form; use bodies_principal_curvature_2: written with the curvatures 1/R so that R = inf (flat) works; the discriminant as a sum of two squares and the smaller root as 2 det/(tr + s) with det a sum of products, positive for convex bodies: no cancellation.

    Chapter: (5.32), Problem 2, general. Derived from: the smaller eigenvalue of the Hessian
    of the gap.

    Derivation: ``hertzmdr.derive.bodies``. Verified by
    ``tests/test_bodies.py::test_principal_curvatures_by_hessian``.

    Parameters
    ----------
    R1a : float or ndarray
        first principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R1b : float or ndarray
        second principal radius of curvature of body 1 (negative: concave; inf: flat) [m]
    R2a : float or ndarray
        first principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    R2b : float or ndarray
        second principal radius of curvature of body 2 (negative: concave; inf: flat) [m]
    omega : float or ndarray
        angle between the first principal directions of the two bodies [rad]
    """
    if (type(R1a) is float and type(R1b) is float and type(R2a) is float and
            type(R2b) is float and type(omega) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*numpy.sqrt((-1/R2b + R2a**(-1.0))**2*numpy.sin(2*omega)**2 + ((-1/R2b + R2a**(-1.0))*numpy.cos(2*omega) - 1/R1b + R1a**(-1.0))**2) + (1/2)/R2b + (1/2)/R2a + (1/2)/R1b + (1/2)/R1a


def textbook_cattaneo_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a paraboloid under normal force F and tangential force F_x, in the derived (textbook) form; use cattaneo_displacement: 1 - (1 - F_x/(mu F))^(2/3) cancels as F_x -> 0: -expm1(2/3 log1p(-F_x/(mu F))).

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: F_x = mu (F_N(a) - F_N(c))
    solved for c, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_cattaneo_displacement(a, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (3/4)*(-F**(1/3)*mu_f**(1/3)*(F*mu_f - F_x)**(2/3) + F*mu_f)/(G_star*a)


def textbook_cattaneo_force(a, R, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a paraboloid displaced by u_x (monotonic, constant load), in the derived (textbook) form; use cattaneo_force: mu (F_N(a) - F_N(c)) cancels as u_x -> 0; a^3 - c^3 = (a^2 - c^2)(a^2 + a c + c^2)/(a + c) with a^2 - c^2 = R G* u_x/(mu E*) exactly.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: sum of the stuck and
    sliding springs.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cattaneo_mindlin_literature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(R) is float and type(E_star) is float and
            type(G_star) is float and type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_cattaneo_force(a, R, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*(E_star**(3/2)*a**3*mu_f**(3/2) - E_star*a**2*mu_f*numpy.sqrt(E_star*a**2*mu_f - G_star*R*u_x) + G_star*R*u_x*numpy.sqrt(E_star*a**2*mu_f - G_star*R*u_x))/(numpy.sqrt(E_star)*R*numpy.sqrt(mu_f))


def textbook_cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a paraboloid, in the derived (textbook) form; use cattaneo_traction_stick: the difference of the two square roots cancels as c -> a.

    Chapter: Cattaneo-Mindlin (not in the chapter). Derived from: (5.59) of the tangential
    line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_traction_through_cerruti_is_rigid_in_the_stick_zone``.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    c : float or ndarray
        radius of the stick zone [m]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(a) is float and type(c) is float and type(R) is float and
            type(E_star) is float and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_cattaneo_traction_stick(r, a, c, R, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*mu_f*(numpy.sqrt(a**2 - r**2) - numpy.sqrt(c**2 - r**2))/(numpy.pi*R)


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
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    d : float or ndarray
        indentation depth [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(d) is float and type(theta) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_cone_pressure(E_star, d, theta, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*E_star*numpy.tan(theta)*numpy.arccosh(2*d/(numpy.pi*r*numpy.tan(theta)))


def textbook_disc_pressure(a, n_p, p0, r):
    """Prescribed pressure p0 (1 - r^2/a^2)^n_p [Pa] on a disc of radius a, r < a, in the derived (textbook) form; use disc_pressure: 1 - r^2/a^2 cancels towards the edge r -> a (1e-13 at r = 0.9995 a); (a - r)(a + r)/a^2 does not.

    Chapter: (5.9), (5.15), Problem 6. Derived from: the distributions of section 5.1.

    Derivation: ``hertzmdr.derive.contact``. Verified by
    ``tests/test_contact.py::test_disc_pressure_force``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n_p : float or ndarray
        exponent of a prescribed pressure p0*(1 - r^2/a^2)^n_p on a disc (section 5.1) [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(a) is float and type(n_p) is float and type(p0) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_disc_pressure(a, n_p, p0, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(1 - r**2/a**2)**n_p


def textbook_ellipse_area(R1, d, t_ba):
    """Contact area pi a b [m^2] of an elliptical contact, in the derived (textbook) form; use ellipse_area: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.29), exact. Derived from: pi a b with a, b matched.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return 2*numpy.pi*R1*d*t_ba*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/((1 - t_ba**2)*((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_depth_from_force(E_star, F, R1, t_ba):
    """Indentation depth d [m] of an elliptical contact under the force F, in the derived (textbook) form; use ellipse_depth_from_force: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact, inverted. Derived from: the exact force solved for d.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_controlled_roundtrip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return 3**(2/3)*F**(2/3)*((1/2)*(-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (1/2)*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(numpy.pi**(2/3)*E_star**(2/3)*R1**(1/3)*((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(1/3))


def textbook_ellipse_equivalent_radius(R1, t_ba):
    """Radius R_e [m] of the sphere whose Hertz force (5.23) equals the elliptical contact's at every depth (compare with the Gaussian radius (5.30)), in the derived (textbook) form; use ellipse_equivalent_radius: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact. Derived from: the exact force equated to (5.23).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.pi**2*R1*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/((1 - t_ba**2)*((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))**3)


def textbook_ellipse_force(E_star, R1, d, t_ba):
    """Normal force F [N] of an elliptical Hertz contact at depth d, in the derived (textbook) form; use ellipse_force: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.23), exact. Derived from: (5.31) integrated over the ellipse, with a and p0
    from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (2/3)*numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*d**(3/2)*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(3/2)


def textbook_ellipse_max_pressure(E_star, R1, d, t_ba):
    """Maximum pressure p0 [Pa] of an elliptical contact at depth d, in the derived (textbook) form; use ellipse_max_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/2)*numpy.sqrt(2)*E_star*numpy.sqrt(d)/(numpy.sqrt(R1)*t_ba*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))*numpy.sqrt((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_mean_pressure(E_star, R1, d, t_ba):
    """Mean pressure F/(pi a b) [Pa] of an elliptical contact, in the derived (textbook) form; use ellipse_mean_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.17), exact. Derived from: the force divided by the area pi a b.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_force_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (1/3)*numpy.sqrt(2)*E_star*numpy.sqrt(d)/(numpy.sqrt(R1)*t_ba*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))*numpy.sqrt((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_pressure(E_star, R1, d, t_ba, x, y):
    """Contact pressure p(x, y) [Pa] of an elliptical contact (0 outside), in the derived (textbook) form; use ellipse_pressure: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31). Derived from: (5.31) with a, b, p0 from the matching.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_pressure_field``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    x : float or ndarray
        coordinate [m]
    y : float or ndarray
        coordinate [m]
    """
    import functools
    import scipy.special

    return (1/2)*numpy.sqrt(2)*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - 1/2*x**2*(1 - t_ba**2)*((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(R1*d*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))) - 1/2*y**2*(1 - t_ba**2)*((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/(R1*d*t_ba**2*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2)))]))/(numpy.sqrt(R1)*t_ba*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))*numpy.sqrt((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2)))


def textbook_ellipse_radius_ratio(t_ba):
    """Ratio R1/R2 >= 1 of the principal radii that gives the axis ratio t = b/a, in the derived (textbook) form; use ellipse_radius_ratio: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.31)-(5.32), exact. Derived from: (5.7) over (5.31) matched to the gap
    (5.32): the y^2 and x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(t_ba**2*(-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2)))


def textbook_ellipse_semi_major(R1, d, t_ba):
    """Semi-axis a [m] (along x, the direction of R1 >= R2) of an elliptical contact, in the derived (textbook) form; use ellipse_semi_major: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32): the x^0 and
    x^2 coefficients.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*numpy.sqrt(R1)*numpy.sqrt(d)*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/numpy.sqrt((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))


def textbook_ellipse_semi_minor(R1, d, t_ba):
    """Semi-axis b = t a [m] (along y, the direction of R2) of an elliptical contact, in the derived (textbook) form; use ellipse_semi_minor: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.28), exact. Derived from: (5.7) over (5.31) matched to (5.32).

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_displacement_by_boussinesq``.

    Parameters
    ----------
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*numpy.sqrt(R1)*numpy.sqrt(d)*t_ba*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/numpy.sqrt((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))


def textbook_ellipse_stiffness(E_star, R1, d, t_ba):
    """Differential stiffness dF/dd [N/m] of an elliptical contact, in the derived (textbook) form; use ellipse_stiffness: K(m) and E(m) are written through D = (K - E)/m and B = (E - (1 - m) K)/m as (pi/4) 2F1: the K, E form cancels as t -> 1 (the circle), where R1/R2 is 0/0.

    Chapter: (5.13), exact. Derived from: the derivative of the force at fixed R1, R2.

    Derivation: ``hertzmdr.derive.ellipse``. Verified by
    ``tests/test_ellipse.py::test_stiffness_by_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    d : float or ndarray
        indentation depth [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*numpy.sqrt(d)*numpy.sqrt((-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))/((-t_ba**2*scipy.special.ellipk(1 - t_ba**2) + scipy.special.ellipe(1 - t_ba**2))/(1 - t_ba**2) + (-scipy.special.ellipe(1 - t_ba**2) + scipy.special.ellipk(1 - t_ba**2))/(1 - t_ba**2))**(3/2)


def textbook_force_law_ellipse_prefactor(E_star, R1, t_ba):
    """Prefactor K [N/m^n] of the force law F = K d^n of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio), in the derived (textbook) form; use force_law_ellipse_prefactor: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force: the K, E form cancels as t -> 1 (the circle).

    Chapter: (5.23), exact ellipse, F = K d^n. Derived from: F/d^n with n the logarithmic
    slope d F'/F of the force.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_ellipse_law_by_pressure_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return (2/3)*numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*numpy.sqrt((scipy.special.ellipe(1 - t_ba**2) - scipy.special.ellipk(1 - t_ba**2))/(t_ba**2 - 1))/scipy.special.ellipk(1 - t_ba**2)**(3/2)


def textbook_force_law_ellipse_stiffness_prefactor(E_star, R1, t_ba):
    """Prefactor K_k [N/m^n] of the stiffness law dF/dd = K_k d^(n - 1) of an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a from ellipse_radius_ratio), in the derived (textbook) form; use force_law_ellipse_stiffness_prefactor: K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force: the K, E form cancels as t -> 1 (the circle).

    Chapter: (5.23), exact ellipse, differentiated. Derived from: (dF/dd)/d^(n_k) with n_k
    the logarithmic slope of dF/dd.

    Derivation: ``hertzmdr.derive.force_law``. Verified by
    ``tests/test_force_law.py::test_stiffness_law_is_the_derivative``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R1 : float or ndarray
        radius of curvature of body 1, or first principal radius [m]
    t_ba : float or ndarray
        axis ratio b/a in (0, 1] of an elliptical contact (a along R1 >= R2) [1]
    """
    import scipy.special

    return numpy.sqrt(2)*numpy.pi*E_star*numpy.sqrt(R1)*numpy.sqrt((scipy.special.ellipe(1 - t_ba**2) - scipy.special.ellipk(1 - t_ba**2))/(t_ba**2 - 1))/scipy.special.ellipk(1 - t_ba**2)**(3/2)


def textbook_hertz_displacement_outside(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact (r > a), in the derived (textbook) form; use hertz_displacement_outside: the textbook form cancels terms of size r/a to leave one of size a/r; asin t - t sqrt(1 - t^2) is written as (2 t^3/3) 2F1(1/2, 3/2; 5/2; t^2) with t = a/r.

    Chapter: Fig. 5.2, Problem 7(b). Derived from: (5.7) over the Hertz pressure, outside
    the disc.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_pressures.py::test_outside_displacement_by_kernel``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_hertz_displacement_outside(R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (numpy.sqrt(R)*numpy.sqrt(d)*numpy.sqrt(-R*d + r**2) + 2*R*d*numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r) - r**2*numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r))/(numpy.pi*R)


def textbook_hertz_displacement_outside_elementary(R, d, r):
    """Surface displacement u_z(r) [m] outside a Hertz contact with the 2F1 in elementary functions; it cancels ~0.65 eps a^2/r^2 relative: for a < r < 2a, in the derived (textbook) form; use hertz_displacement_outside_elementary: asin t - (asin t - t sqrt(1 - z))/(2 z), t = a/r, z = R d/r^2: the 2F1 in elementary functions as one cancellation of ~0.65 eps/z.

    Chapter: Fig. 5.2, Problem 7(b), a < r < 2a. Derived from: the stable far form with
    2F1(1/2, 3/2; 5/2; t^2) hyperexpanded.

    Derivation: ``hertzmdr.derive.hertz``. Verified by
    ``tests/test_hertz.py::test_outside_forms_by_mpmath``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    d : float or ndarray
        indentation depth [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(d) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_hertz_displacement_outside_elementary(R, d, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*d*(-1/3*numpy.sqrt(R)*numpy.sqrt(d)*(r**2*((3/2)*R*d/r**2 - 3/2)/(R*d*numpy.sqrt(-R*d/r**2 + 1)) + (3/2)*r**3*numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r)/(R**(3/2)*d**(3/2)))/r + numpy.arcsin(numpy.sqrt(R)*numpy.sqrt(d)/r))/numpy.pi


def textbook_jkr_pressure(E_star, R, a, dgamma, r):
    """Contact pressure p(r) [Pa] of a paraboloid in JKR contact, r < a, in the derived (textbook) form; use jkr_pressure: Hertz's part and the edge term apart, each with (a - r)(a + r) for a^2 - r^2, which loses the digits of a - r next to the edge.

    Chapter: (5.59), JKR. Derived from: (5.59): Hertz's pressure of radius a plus the edge
    term.

    Derivation: ``hertzmdr.derive.adhesion``. Verified by
    ``tests/test_adhesion.py::test_jkr_pressure_by_boussinesq``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    dgamma : float or ndarray
        work of adhesion Delta gamma (energy per unit area to separate) [J/m^2]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(R) is float and type(a) is float and
            type(dgamma) is float and type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_jkr_pressure(E_star, R, a, dgamma, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-numpy.sqrt(2)*numpy.pi*numpy.sqrt(E_star)*R*numpy.sqrt(a)*numpy.sqrt(dgamma) + 2*numpy.sqrt(numpy.pi)*E_star*(a**2 - r**2))/(numpy.pi**(3/2)*R*numpy.sqrt(a**2 - r**2))


def textbook_line_stress_axis_sigma_xx(a, p0, z):
    """Normal stress sigma_xx [Pa] on the axis of a line contact of half-width a, in the derived (textbook) form; use line_stress_axis_sigma_xx: the derived form subtracts terms of size z/a to leave one of size (a/z)^3; -p0 a^3/(s (s + z)^2), s = (a^2 + z^2)^(1/2), has none.

    Chapter: (5.36), Flamant. Derived from: Flamant superposed over the line pressure (5.36)
    along the axis x = 0.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_axis_sigma_xx(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(2*a**2*z - a**2*numpy.sqrt(a**2 + z**2) + 2*z**3 - 2*z**2*numpy.sqrt(a**2 + z**2))/(a*(a**2 + z**2))


def textbook_line_stress_axis_von_mises(a, nu, p0, z):
    """Von Mises stress [Pa] on the axis of a line contact (plane strain), in the derived (textbook) form; use line_stress_axis_von_mises: (5.50) expanded subtracts squares of size p0^2; with c = (sigma_xx + sigma_zz)/2 it is ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2).

    Chapter: (5.50), (5.36). Derived from: (5.50) with the axis stresses and sigma_yy = nu
    (sigma_xx + sigma_zz).

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_axis_maxima_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_axis_von_mises(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(a**6*p0**2/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**4) - a**4*p0**2/((a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + a**3*nu*p0*(-a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - a*p0/numpy.sqrt(a**2 + z**2))/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) + a**2*p0**2/(a**2 + z**2) + a*nu*p0*(-a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - a*p0/numpy.sqrt(a**2 + z**2))/numpy.sqrt(a**2 + z**2) + nu**2*(-a**3*p0/(numpy.sqrt(a**2 + z**2)*(z + numpy.sqrt(a**2 + z**2))**2) - a*p0/numpy.sqrt(a**2 + z**2))**2)


def textbook_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz):
    """Largest principal stress [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_max: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*sigma_xx + (1/2)*sigma_zz + (1/2)*numpy.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz):
    """Smallest principal stress [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_min: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: eigenvalues of the 2x2 stress tensor.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*sigma_xx + (1/2)*sigma_zz - 1/2*numpy.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz):
    """Principal shear stress tau_1 [Pa] in the x-z plane, in the derived (textbook) form; use line_stress_principal_shear: the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2) is a sum of squares.

    Chapter: plane stress state x-z. Derived from: half the difference of the principal
    stresses.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if type(sigma_xx) is float and type(sigma_zz) is float and type(tau_xz) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*numpy.sqrt(sigma_xx**2 - 2*sigma_xx*sigma_zz + sigma_zz**2 + 4*tau_xz**2)


def textbook_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz):
    """Von Mises stress [Pa] of a plane-strain state (sigma_yy = nu (sigma_xx + sigma_zz), tau_xy = tau_yz = 0), in the derived (textbook) form; use line_stress_von_mises: (5.50) expanded subtracts products of size p0^2 (it goes negative at the surface for nu = 1/2, where it is 0); ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2), c = (sigma_xx + sigma_zz)/2, has only squares.

    Chapter: (5.50), plane strain. Derived from: (5.50) with the plane-strain sigma_yy.

    Derivation: ``hertzmdr.derive.line_stress``. Verified by
    ``tests/test_line_stress.py::test_plane_strain_and_principal_stresses``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if (type(nu) is float and type(sigma_xx) is float and type(sigma_zz) is float and
            type(tau_xz) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(nu**2*(sigma_xx + sigma_zz)**2 - nu*sigma_xx*(sigma_xx + sigma_zz) - nu*sigma_zz*(sigma_xx + sigma_zz) + sigma_xx**2 - sigma_xx*sigma_zz + sigma_zz**2 + 3*tau_xz**2)


def textbook_mdr_kink_G(b, slope_jump, x):
    """Integral from b to x > b [m^2] of mdr_kink_g: the kink's part of the integral of g in the force (5.57), in the derived (textbook) form; use mdr_kink_G: acosh of an argument near 1 loses digits as x -> b (as in mdr_kink_g); the two terms still cancel to a relative (x - b)/b, which is rounding of the integral of g it is added to.

    Chapter: (5.57). Derived from: integral of mdr_kink_g by parts (x g - integral of y g').

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_G_by_quadrature``.

    Parameters
    ----------
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : float or ndarray
        coordinate [m]
    """
    if type(b) is float and type(slope_jump) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_mdr_kink_G(b, slope_jump, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*b*slope_jump*x*numpy.arccosh((1/2)*numpy.sqrt(2)*numpy.sqrt(b + x)/numpy.sqrt(b)) - b*slope_jump*numpy.sqrt(-b + x)*numpy.sqrt(b + x)


def textbook_mdr_kink_g(b, slope_jump, x):
    """Integral from b to x > b [m] of the branch-point term of g' at a kink r = b, in the derived (textbook) form; use mdr_kink_g: acosh of an argument 1 + (x - b)/(4b) loses digits as x -> b (relative eps b/(x - b)); it is written 2 asinh(sqrt((x - b)/(2b))).

    Chapter: (5.52). Derived from: integral of mdr_kink_gprime.

    Derivation: ``hertzmdr.derive.kink``. Verified by
    ``tests/test_kink.py::test_kink_g_by_quadrature``.

    Parameters
    ----------
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    slope_jump : float or ndarray
        jump f'(b+) - f'(b-) of the profile's slope at a kink r = b [1]
    x : float or ndarray
        coordinate [m]
    """
    if type(b) is float and type(slope_jump) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_mdr_kink_g(b, slope_jump, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*b*slope_jump*numpy.arccosh((1/2)*numpy.sqrt(2)*numpy.sqrt(b + x)/numpy.sqrt(b))


def textbook_mindlin_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle of a tangential force oscillating with amplitude F_amp at constant normal force F (paraboloid), in the derived (textbook) form; use mindlin_energy: the integrand vanishes to second order at the edge: (1 - c/a)^3 P(c/a) with 1 - c/a = -expm1(log1p(-F_amp/(mu F))/3) keeps the cubic law to rounding.

    Chapter: Mindlin-Deresiewicz (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops 4 mu q_z (u* - mu q_z/G*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_mindlin_deresiewicz_energy``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_mindlin_energy(a, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (3/5)*(-6*F**(4/3)*mu_f**(4/3)*(F*mu_f - F_amp)**(2/3) + F**(1/3)*F_amp*mu_f**(1/3)*(F*mu_f - F_amp)**(2/3) + 6*F**2*mu_f**2 - 5*F*F_amp*mu_f)/(G_star*a)


def textbook_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law indenter under the force F, in the derived (textbook) form; use powerlaw_depth_from_force: (kappa_n c_n)^(1/n) of the derived form overflows or underflows for small n although d is ordinary (c_n = 1e-3, n = 3 at F = 1 N: NaN); split into (F (n + 1)/(2 E* n))^(n/(n + 1)) (kappa_n c_n)^(1/(n + 1)), whose factors stay within the range of the inputs.

    Chapter: Problem 7(d), inverted. Derived from: the force of Problem 7(d) solved for d.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_roundtrip``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    F : float or ndarray
        normal force [N]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(F) is float and type(c_n) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return ((1/2)*F*(c_n*kappa_n)**(n**(-1.0))*(n + 1)/(E_star*n))**(n/(n + 1))


def textbook_powerlaw_displacement_outside_integrand(a, d, n, r, w_out):
    """Integrand [m] of (5.60) in w: u_z(r > a) = integral_0^asin(a/r) of it dw, positive and smooth (a layer of width ~1/(n cot(asin(a/r))) at w = 0 for large n), in the derived (textbook) form; use powerlaw_displacement_outside_integrand: (x/a)^n with x/a = 1 - O(1/n) amplifies its rounding n-fold and r^2 - a^2 overflows for r > 1e154; written -expm1(n log1p(-2 sin(w/2)^2 - sqrt(r - a) sqrt(r + a) sin(w)/a)).

    Chapter: Problem 7(d), (5.60). Derived from: (5.60) with x = r sin(asin(a/r) - w).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_displacement_outside_large_n``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    w_out : float or ndarray
        integration variable in (0, asin(a/r)) of (5.60) outside the contact: x = r sin(asin(a/r) - w) [rad]
    """
    if (type(a) is float and type(d) is float and type(n) is float and type(r) is float and
            type(w_out) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_powerlaw_displacement_outside_integrand(a, d, n, r, w_out)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-2*d*(-r*numpy.sin(w_out - numpy.arcsin(a/r))/a)**n + 2*d)/numpy.pi


def textbook_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n):
    """Mean pressure F/(pi a^2) [Pa] of a power-law indenter at depth d, in the derived (textbook) form; use powerlaw_mean_pressure_from_depth: the contact radius a = (d/(kappa_n c_n))^(1/n) underflows to 0 for small n where F/(pi a^2) is still a float (and overflows where it is not): one power of the ratio kappa_n c_n/d, times d.

    Chapter: Fig. 5.17. Derived from: (5.57) over the contact area, a from (5.55).

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    d : float or ndarray
        indentation depth [m]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    """
    if (type(E_star) is float and type(c_n) is float and type(d) is float and
            type(kappa_n) is float and type(n) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*d*n*(c_n*kappa_n/d)**(n**(-1.0))/(numpy.pi*(n + 1))


def textbook_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad):
    """Integrand [Pa] of (5.59) in w: p(r) = integral_0^1 of it dw, smooth in w (a boundary layer of width ~1/(n (1 - r^2/a^2)) at w = 0 for large n), in the derived (textbook) form; use powerlaw_pressure_integrand: (x/a)^(n-2) with x/a = 1 - O(1/n) amplifies its rounding n-fold and overflows/underflows in parts; written exp((n/2 - 1) log1p(-(1 - x^2/a^2))) with 1 - x^2/a^2 factored.

    Chapter: Problem 7(d), (5.59). Derived from: (5.59) with x^2 = r^2 + (a^2 - r^2)(1 -
    w)^2.

    Derivation: ``hertzmdr.derive.powerlaw``. Verified by
    ``tests/test_powerlaw.py::test_pressure_large_n_by_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    d : float or ndarray
        indentation depth [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    w_quad : float or ndarray
        integration variable in (0, 1) of (5.59): x^2 = r^2 + (a^2 - r^2)(1 - w)^2 [1]
    """
    if (type(E_star) is float and type(a) is float and type(d) is float and type(n) is float
            and type(r) is float and type(w_quad) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*a**(-n)*d*n*numpy.sqrt(a**2 - r**2)*(r**2 + (1 - w_quad)**2*(a**2 - r**2))**((1/2)*n - 1)/numpy.pi


def textbook_sphere_depth(R, a):
    """Indentation depth d [m] of a rigid spherical cap at the contact radius a < R, in the derived (textbook) form; use sphere_depth: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.55), Sneddon's sphere. Derived from: (5.55), d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_depth(R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.arctanh(a/R)


def textbook_sphere_force_from_radius(E_star, R, a):
    """Normal force F [N] of a rigid spherical cap at the contact radius a < R, in the derived (textbook) form; use sphere_force_from_radius: (a^2 + R^2) atanh(a/R) - a R cancels as (a/R)^2 for a << R; below a = R/2 it is written E* R^2 (b^2 atanh(b) + (b^3/3) 2F1(1, 3/2; 5/2; b^2)), b = a/R, above it with atanh in log1p.

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) with d = g(a).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    """
    if type(E_star) is float and type(R) is float and type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_force_from_radius(E_star, R, a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*(R**2*numpy.arctanh(a/R) - R*a + a**2*numpy.arctanh(a/R))


def textbook_sphere_g(R, x):
    """MDR profile g(x) [m] of the spherical cap, 0 <= x < R, in the derived (textbook) form; use sphere_g: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.52), Sneddon's sphere. Derived from: (5.52) with r = sqrt(x^2 - v^2).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_g(R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return x*numpy.arctanh(x/R)


def textbook_sphere_lam_force(E_star, R, lam):
    """Normal force F [N] of a rigid spherical cap at lam = atanh(a/R), in the derived (textbook) form; use sphere_lam_force: (1 + tanh(lam)^2) lam - tanh(lam) cancels as lam^2 for small lam; below lam = 1/2 it is written with (b^3/3) 2F1(1, 3/2; 5/2; b^2) for lam - b, b = tanh(lam).

    Chapter: (5.57), Sneddon's sphere. Derived from: (5.57) at a = R tanh(lam).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_depth_and_force_by_quadrature``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    """
    if type(E_star) is float and type(R) is float and type(lam) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_lam_force(E_star, R, lam)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*R**2*(lam*numpy.tanh(lam)**2 + lam - numpy.tanh(lam))


def textbook_sphere_lam_pressure_pole(E_star, R, lam, r):
    """The part of the contact pressure p(r) [Pa] of a rigid spherical cap from the pole R x/(R^2 - x^2) of g'(x), at lam = atanh(a/R), 0 <= r < a, in the derived (textbook) form; use sphere_lam_pressure_pole: atanh(k/c), k^2 = a^2 - r^2, c^2 = R^2 - r^2, loses 1 - k/c as a -> R; it is written log1p(2k(c + k) cosh(lam)^2/R^2)/2.

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) with x^2 = r^2 + w^2, w =
    sqrt(R^2 - r^2) tanh(u).

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    lam : float or ndarray
        atanh(a/R) of a rigid spherical cap (derive/sphere.py): a = R tanh(lam), d = R lam tanh(lam) [1]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if (type(E_star) is float and type(R) is float and type(lam) is float and
            type(r) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_lam_pressure_pole(E_star, R, lam, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*R*numpy.arctanh(numpy.sqrt(R**2*numpy.tanh(lam)**2 - r**2)/numpy.sqrt(R**2 - r**2))/(numpy.pi*numpy.sqrt(R**2 - r**2))


def textbook_sphere_pressure_atanh_kernel(E_star, R, x):
    """Integrand (E*/pi) atanh(x/R)/x [Pa/m] of the rest of (5.59) for the spherical cap, to be integrated over w in (0, sqrt(a^2 - r^2)) at x = sqrt(r^2 + w^2), in the derived (textbook) form; use sphere_pressure_atanh_kernel: atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 keeps them (R - x is exact there) and is exact as x -> 0.

    Chapter: (5.59), Sneddon's sphere. Derived from: (5.59) of the atanh term of g', with
    x^2 = r^2 + w^2 (dx/sqrt(x^2 - r^2) = dw/x); no elementary antiderivative.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_pressure_by_quadrature_of_59``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    x : float or ndarray
        coordinate [m]
    """
    if type(E_star) is float and type(R) is float and type(x) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_pressure_atanh_kernel(E_star, R, x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return E_star*numpy.arctanh(x/R)/(numpy.pi*x)


def textbook_sphere_profile(R, r):
    """Height f(r) [m] of a spherical cap of radius R above its apex, 0 <= r <= R, in the derived (textbook) form; use sphere_profile: R - sqrt(R^2 - r^2) cancels for r << R; it is written r^2/(R + sqrt((R - r)(R + r))).

    Chapter: (5.52), Sneddon's sphere. Derived from: the sphere x^2 + (R - z)^2 = R^2.

    Derivation: ``hertzmdr.derive.sphere``. Verified by
    ``tests/test_sphere.py::test_profile_and_g``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_sphere_profile(R, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return R - numpy.sqrt(R**2 - r**2)


def textbook_stress_axis_sigma_xx_deep(a, nu, p0, z):
    """Radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure (for z >= a), in the derived (textbook) form; use stress_axis_sigma_xx_deep: (5.49) subtracts terms of size 1 to leave one of size (a/z)^2 (of size (a/z)^4 at nu = 1/2); 1 - atan(t)/t - t^2/(3(1 + t^2)) is written as (2/15) t^4 2F1(2, 5/2; 7/2; -t^2), t = a/z, used for z >= a.

    Chapter: (5.49). Derived from: (5.41) superposed over (5.15) along the axis.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(nu) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_axis_sigma_xx_deep(a, nu, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*p0*(a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2))


def textbook_stress_axis_sigma_zz(a, p0, z):
    """Normal stress sigma_zz [Pa] on the axis under the Hertz pressure, in the derived (textbook) form; use stress_axis_sigma_zz: one division, no cancellation.

    Chapter: (5.48). Derived from: (5.43) superposed over (5.15) along the axis, (5.47).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_axis_stresses_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(p0) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_axis_sigma_zz(a, p0, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -a**2*p0/(a**2 + z**2)


def textbook_stress_hertz_max_orthogonal_shear(p0):
    """The largest orthogonal shear |tau_rz| [Pa] under the Hertz pressure (any nu), in the derived (textbook) form; use stress_hertz_max_orthogonal_shear: the solved form subtracts 7 34^(1/2) from 31 2^(1/2) (a factor 14 of cancellation); this one has 5 - 17^(1/2) = 0.88 at worst.

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    """
    if type(p0) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_hertz_max_orthogonal_shear(p0)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/32)*p0*numpy.sqrt(1 + numpy.sqrt(17))*(-7*numpy.sqrt(34) + 31*numpy.sqrt(2))


def textbook_stress_hertz_max_orthogonal_shear_z(a):
    """Depth z [m] of the largest |tau_rz| under the Hertz pressure, in the derived (textbook) form; use stress_hertz_max_orthogonal_shear_z: 17^(1/2) - 4 = 0.12 cancels a factor 33; it is 1/(17^(1/2) + 4).

    Chapter: Fig. 5.9. Derived from: the root of the gradient of tau_rz (Huber's field in
    spheroidal variables).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_orthogonal_shear_maximum_by_superposition``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    """
    if type(a) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_hertz_max_orthogonal_shear_z(a)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*numpy.sqrt(-4 + numpy.sqrt(17))


def textbook_stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at (xi, beta), for xi >= 1, in the derived (textbook) form; use stress_hertz_sigma_rr_far: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4 overflows for xi > 1e77).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    chi : float or ndarray
        sin(beta) of the oblate spheroidal angle beta [1]
    """
    if (type(nu) is float and type(p0) is float and type(xi) is float and type(eta) is float
            and type(chi) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*numpy.arctan(xi**(-1.0)) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


def textbook_stress_hertz_sigma_tt_far(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at (xi, beta), for xi >= 1, in the derived (textbook) form; use stress_hertz_sigma_tt_far: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of 1/xi (xi^4 overflows for xi > 1e77).

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Parameters
    ----------
    nu : float or ndarray
        Poisson's ratio [1]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    xi : float or ndarray
        oblate spheroidal coordinate of the contact disc: xi^2 = u/a^2 [1]
    eta : float or ndarray
        cos(beta) of the oblate spheroidal angle beta: r = a (1 + xi^2)^(1/2) sin(beta), z = a xi cos(beta) [1]
    """
    if type(nu) is float and type(p0) is float and type(xi) is float and type(eta) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_hertz_sigma_tt_far(nu, p0, xi, eta)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return p0*(-eta*(nu + 1)*(-xi*numpy.arctan(xi**(-1.0)) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


def textbook_stress_spheroidal_u(a, r, z):
    """Johnson's u [m^2], the root of r^2/(a^2 + u) + z^2/u = 1 (for r^2 + z^2 >= a^2), in the derived (textbook) form; use stress_spheroidal_u: the expanded discriminant cancels near the contact edge; q = (r - a)(r + a) + z^2 keeps it exact.

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(r) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_spheroidal_u(a, r, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*a**2 + (1/2)*r**2 + (1/2)*z**2 + (1/2)*numpy.sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)


def textbook_stress_spheroidal_u_inside(a, r, z):
    """Johnson's u [m^2] for r^2 + z^2 < a^2, in the derived (textbook) form; use stress_spheroidal_u_inside: (q + D)/2 cancels for q = r^2 + z^2 - a^2 < 0; written as 2 a^2 z^2/(D - q).

    Chapter: Johnson (1985), (3.44). Derived from: the oblate spheroid through (r, z).

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_spheroidal_coordinates``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    z : float or ndarray
        depth below the surface [m]
    """
    if type(a) is float and type(r) is float and type(z) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_spheroidal_u_inside(a, r, z)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -1/2*a**2 + (1/2)*r**2 + (1/2)*z**2 + (1/2)*numpy.sqrt(a**4 - 2*a**2*r**2 + 2*a**2*z**2 + r**4 + 2*r**2*z**2 + z**4)


def textbook_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """Von Mises equivalent stress [Pa] of the stress tensor, in the derived (textbook) form; use stress_von_mises: the expanded 3 J2 subtracts products of the stresses and rounds below 0 for a nearly hydrostatic state (sqrt: NaN at the centre of a Hertz contact with nu = 1/2); (5.50) is a sum of squares.

    Chapter: (5.50). Derived from: sqrt(3 J2), J2 the second invariant of the stress
    deviator.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_von_mises_invariant``.

    Parameters
    ----------
    sigma_xx : float or ndarray
        normal stress component sigma_xx [Pa]
    sigma_yy : float or ndarray
        normal stress component sigma_yy [Pa]
    sigma_zz : float or ndarray
        normal stress component sigma_zz [Pa]
    tau_xy : float or ndarray
        shear stress component tau_xy [Pa]
    tau_yz : float or ndarray
        shear stress component tau_yz [Pa]
    tau_xz : float or ndarray
        shear stress component tau_xz [Pa]
    """
    if (type(sigma_xx) is float and type(sigma_yy) is float and type(sigma_zz) is float and
            type(tau_xy) is float and type(tau_yz) is float and type(tau_xz) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return numpy.sqrt(sigma_xx**2 - sigma_xx*sigma_yy - sigma_xx*sigma_zz + sigma_yy**2 - sigma_yy*sigma_zz + sigma_zz**2 + 3*tau_xy**2 + 3*tau_xz**2 + 3*tau_yz**2)


def textbook_tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a cone under normal force F and tangential F_x, in the derived (textbook) form; use tangential_cone_displacement: 1 - sqrt(1 - F_x/(mu F)) cancels as F_x -> 0.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: F_x = mu (F_N(a) -
    F_N(c)), F_N ~ c^2, then g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_cone_displacement(a, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (-numpy.sqrt(F)*numpy.sqrt(mu_f)*numpy.sqrt(F*mu_f - F_x) + F*mu_f)/(G_star*a)


def textbook_tangential_cone_energy(a, F, G_star, mu_f, F_amp):
    """Energy W [J] dissipated per cycle by a cone under normal force F, amplitude F_amp, in the derived (textbook) form; use tangential_cone_energy: a - c = a x/(1 + sqrt(1 - x)), x = F_amp/(mu F), instead of a (1 - sqrt(1 - x)).

    Chapter: MDR tangential, cone (not in the chapter). Derived from: sum of the sliding
    springs' parallelogram loops.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(a) is float and type(F) is float and type(G_star) is float and
            type(mu_f) is float and type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_cone_energy(a, F, G_star, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (4/3)*numpy.sqrt(F)*numpy.sqrt(mu_f)*(numpy.sqrt(F)*numpy.sqrt(mu_f) - numpy.sqrt(F*mu_f - F_amp))**3/(G_star*a)


def textbook_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f):
    """Tangential traction q(r) [Pa] in the stick zone r < c of a cone, finite on the axis: mu E* tan(theta)/2 ln(a/c) at r = 0, in the derived (textbook) form; use tangential_cone_traction_stick: the two pressures are each log-infinite on the axis (inf - inf = NaN at r = 0); as one logarithm of (a + sqrt(a^2 - r^2))/(c + sqrt(c^2 - r^2)), written log1p of its excess over 1, it is finite at r = 0 and keeps its digits as c -> a.

    Chapter: MDR tangential, cone (not in the chapter). Derived from: (5.59) of the
    tangential line load: mu (p(r; a) - p(r; c)).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_cone_traction_on_and_near_the_axis``.

    Parameters
    ----------
    r : float or ndarray
        radial coordinate on the surface [m]
    a : float or ndarray
        contact radius [m]
    c : float or ndarray
        radius of the stick zone [m]
    theta : float or ndarray
        angle between the cone's surface and the plane [rad]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    """
    if (type(r) is float and type(a) is float and type(c) is float and type(theta) is float
            and type(E_star) is float and type(mu_f) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return mu_f*((1/2)*E_star*numpy.log((a + numpy.sqrt(a**2 - r**2))/r)*numpy.tan(theta) - 1/2*E_star*numpy.log((c + numpy.sqrt(c**2 - r**2))/r)*numpy.tan(theta))


def textbook_tangential_modulus(G1, nu1, G2, nu2):
    """Tangential effective modulus G* [Pa] of two elastic bodies, in the derived (textbook) form; use tangential_modulus: a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf.

    Chapter: MDR tangential springs (not in the chapter). Derived from: direction average of
    the Cerruti surface compliance of each body, compliances added.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_tangential_modulus_from_the_cerruti_compliance``.

    Parameters
    ----------
    G1 : float or ndarray
        shear modulus of body 1 [Pa]
    nu1 : float or ndarray
        Poisson's ratio of body 1 [1]
    G2 : float or ndarray
        shear modulus of body 2 [Pa]
    nu2 : float or ndarray
        Poisson's ratio of body 2 [1]
    """
    if (type(G1) is float and type(nu1) is float and type(G2) is float and
            type(nu2) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_modulus(G1, nu1, G2, nu2)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return -4*G1*G2/(G1*(nu2 - 2) + G2*(nu1 - 2))


def textbook_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """Tangential displacement u_x [m] of a power-law profile under normal force F and tangential force F_x, in the derived (textbook) form; use tangential_powerlaw_displacement: 1 - (1 - F_x/(mu F))^(n/(n+1)) cancels as F_x -> 0.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: c from F_x, then
    g(c) = d - G* u_x/(mu E*).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_x : float or ndarray
        tangential force [N]
    """
    if (type(a) is float and type(n) is float and type(F) is float and type(G_star) is float
            and type(mu_f) is float and type(F_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/2)*F*mu_f*(1 - (1 - F_x/(F*mu_f))**(n/(n + 1)))*(n + 1)/(G_star*a*n)


def textbook_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Tangential force F_x [N] of a power-law profile displaced by u_x, in the derived (textbook) form; use tangential_powerlaw_force: 1 - (c/a)^(n+1) cancels as u_x -> 0: -expm1((n+1)/n log1p(-q)).

    Chapter: MDR tangential, power law (not in the chapter). Derived from: mu (F_N(a) -
    F_N(c)), asserted equal to the spring sum.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(c_n) is float and type(n) is float and
            type(kappa_n) is float and type(E_star) is float and type(G_star) is float and
            type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 2*E_star*a**(n + 1)*c_n*kappa_n*mu_f*n*(1 - (1 - G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))**((n + 1)/n))/(n + 1)


def textbook_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """1 - c/a [1] of a power-law profile under normal force F and tangential force F_amp, in the derived (textbook) form; use tangential_powerlaw_stick_deficit: 1 - (1 - F_amp/(mu F))^(1/(n+1)) cancels at small amplitude.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: F_x = mu (F_N(a)
    - F_N(c)), F_N ~ c^(n+1).

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_loop_area_equals_the_energy``.

    Parameters
    ----------
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    F : float or ndarray
        normal force [N]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    F_amp : float or ndarray
        amplitude F_x* of an oscillating tangential force [N]
    """
    if (type(n) is float and type(F) is float and type(mu_f) is float and
            type(F_amp) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return 1 - (1 - F_amp/(F*mu_f))**((n + 1)**(-1.0))


def textbook_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """Stick radius c [m] of a power-law profile f = c_n r^n displaced by u_x, in the derived (textbook) form; use tangential_powerlaw_stick_radius: (1 - q)^(1/n) as exp(log1p(-q)/n): accurate for large n and tiny q.

    Chapter: MDR tangential, power law (not in the chapter). Derived from: g(c) = d - G*
    u_x/(mu E*), g = kappa_n c_n x^n.

    Derivation: ``hertzmdr.derive.tangential``. Verified by
    ``tests/test_tangential.py::test_closed_forms_against_the_spring_quadrature``.

    Parameters
    ----------
    a : float or ndarray
        contact radius [m]
    c_n : float or ndarray
        coefficient of the power-law profile f = c_n r^n [m^(1-n)]
    n : float or ndarray
        exponent of the power-law profile f = c_n r^n, n > 0 [1]
    kappa_n : float or ndarray
        MDR factor of the power-law profile, g = kappa_n c_n |x|^n (Problem 7(d)) [1]
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    G_star : float or ndarray
        tangential effective modulus G*: 1/G* = (2 - nu1)/(4 G1) + (2 - nu2)/(4 G2) [Pa]
    mu_f : float or ndarray
        coefficient of (Coulomb) friction mu [1]
    u_x : float or ndarray
        rigid tangential displacement of the indenter relative to the half-space [m]
    """
    if (type(a) is float and type(c_n) is float and type(n) is float and
            type(kappa_n) is float and type(E_star) is float and type(G_star) is float and
            type(mu_f) is float and type(u_x) is float):
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return a*(1 - G_star*a**(-n)*u_x/(E_star*c_n*kappa_n*mu_f))**(n**(-1.0))


def textbook_uniform_pressure_displacement_outside(E_star, a, p0, r):
    """Surface displacement u_z [m] outside a disc (r > a) under a uniform pressure p0, in the derived (textbook) form; use uniform_pressure_displacement_outside: E(m) - (1 - m) K(m) cancels like m = a^2/r^2 for r >> a; it equals (pi m/4) 2F1(1/2, 1/2; 2; m).

    Chapter: Problem 6 (outside the disc). Derived from: (5.7) with p = p0 (n = 0) outside
    the disc.

    Derivation: ``hertzmdr.derive.pressures``. Verified by
    ``tests/test_pressures.py::test_uniform_by_kernel``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    a : float or ndarray
        contact radius [m]
    p0 : float or ndarray
        pressure scale of p0*(1 - r^2/a^2)^n; the maximum pressure for n >= 0 [Pa]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    import scipy.special

    return 4*p0*r*((a**2/r**2 - 1)*scipy.special.ellipk(a**2/r**2) + scipy.special.ellipe(a**2/r**2))/(numpy.pi*E_star)


def textbook_worn_displacement_outside(R, a, b, r):
    """Surface displacement u_z(r) [m] outside the contact (r > a) of the worn paraboloid, in the derived (textbook) form; use worn_displacement_outside: S sqrt(1 - S^2) - asin S, S^2 = (a^2 - b^2)/(r^2 - b^2), cancels for r >> a; it is written -(2 S^3/3) 2F1(1/2, 3/2; 5/2; S^2).

    Chapter: Problem 8, (5.60). Derived from: (5.60) with x^2 = b^2 + (r^2 - b^2)
    sin^2(phi).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_against_3d_elasticity``.

    Parameters
    ----------
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    a : float or ndarray
        contact radius [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    r : float or ndarray
        radial coordinate on the surface [m]
    """
    if type(R) is float and type(a) is float and type(b) is float and type(r) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_worn_displacement_outside(R, a, b, r)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (2*a*numpy.sqrt(a**2 - b**2)*numpy.arcsin(a/r) - (b - r)*(b + r)*(numpy.sqrt((-a**2 + b**2)/(b**2 - r**2))*numpy.sqrt((-a**2 + r**2)/(-b**2 + r**2)) - numpy.arcsin(numpy.sqrt((-a**2 + b**2)/(b**2 - r**2)))))/(numpy.pi*R)


def textbook_worn_force(E_star, R, b, d):
    """Normal force F [N] of the worn paraboloid at depth d, in the derived (textbook) form; use worn_force: sqrt(-1 + sqrt(1 + s^2)), s = 2 R d/b^2, cancels for s << 1; it is written s/sqrt(sqrt(1 + s^2) + 1).

    Chapter: Problem 8. Derived from: (5.57) at the contact radius of (5.55).

    Derivation: ``hertzmdr.derive.worn``. Verified by
    ``tests/test_worn.py::test_force_by_pressure``.

    Parameters
    ----------
    E_star : float or ndarray
        effective modulus E* (5.8), (5.26) [Pa]
    R : float or ndarray
        radius of curvature (effective radius (5.27) for two bodies) [m]
    b : float or ndarray
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8); the radius of a kink of the profile (derive/kink.py) [m]
    d : float or ndarray
        indentation depth [m]
    """
    if type(E_star) is float and type(R) is float and type(b) is float and type(d) is float:
        try:  # the scalar path: Python floats, the math module
            return _math_textbook_worn_force(E_star, R, b, d)
        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings
            pass
    return (1/3)*E_star*numpy.sqrt(-2*b**2 + 2*numpy.sqrt(4*R**2*d**2 + b**4))*(2*b**2 + numpy.sqrt(4*R**2*d**2 + b**4))/R


def fit_sphere_force_unit(R, a, lam):
    """(``fit_sphere_force_dE``) at once, their common subexpressions computed once
    (SymPy's cse): each as the relation's own function gives it, to rounding. Arguments
    as there.
    """
    _c0 = (a*a)
    _c1 = (R*R)
    _c2 = (lam*lam)
    return numpy.where(numpy.less(lam, 1/2), _c0*lam + _c1*(lam*lam*lam)/(_c2 + _c2/(_c2/(_c2/(_c2/(_c2/((1/15)*_c2 + 13) + 11) + 9) + 7) + 5) + 3), -R*a + lam*(_c0 + _c1))


def hertz_displacement_far(R, d, r):
    """(``hertz_displacement_outside_series``) at once, their common subexpressions
    computed once (SymPy's cse): each as the relation's own function gives it, to
    rounding. Arguments as there.
    """
    _c0 = R*d/(r*r)
    return 2*numpy.sqrt(R)*d**(3/2)*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*(_c0*((4485482287/35459249995776)*_c0 + 34461632205/242304874971136) + 1472719325/9156870275072) + 756261275/4131758538752) + 116680311/556198264832) + 20036013/82678120448) + 3231615/11442061312) + 5014575/15082717184) + 1300075/3284140032) + 676039/1415577600) + 88179/150732800) + 46189/63307776) + 12155/13074432) + 6435/5292032) + 143/87040) + 77/33280) + 63/18304) + 35/6336) + 5/504) + 3/140) + 1/15) + 2/3)/(numpy.pi*r)


def hertz_displacement_near(R, d, r):
    """(``hertz_displacement_outside_elementary``) at once, their common subexpressions
    computed once (SymPy's cse): each as the relation's own function gives it, to
    rounding. Arguments as there.
    """
    _c0 = numpy.sqrt(R)*numpy.sqrt(d)/r
    _c1 = numpy.arcsin(_c0)
    _c2 = (r*r)
    return 2*d*(_c1 - 1/2*_c2*(-_c0*numpy.sqrt(-R*d/_c2 + 1) + _c1)/(R*d))/numpy.pi


def stress_hertz_field(chi, eta, nu, p0, xi):
    """(``stress_hertz_sigma_rr``, ``stress_hertz_sigma_tt``, ``stress_hertz_sigma_zz``,
    ``stress_hertz_tau_rz``) at once, their common subexpressions computed once (SymPy's
    cse): each as the relation's own function gives it, to rounding. Arguments as there.
    """
    _c0 = 1 - 2*nu
    _c1 = 1/(3*eta + 3)
    _c2 = (xi*xi)
    _c3 = _c2 + 1
    _c4 = 1/_c3
    _c5 = (eta*eta)
    _c6 = 1/(_c2 + _c5)
    _c7 = eta*(nu + 1)*(-1/3*_c4 - xi*(-numpy.arctan(xi) + (1/2)*numpy.pi) + 1)
    _c8 = _c6*p0
    return p0*(_c0*_c1*_c4 - _c2*_c4*_c6*(chi*chi)*eta - _c7), p0*(_c0*_c1*_c4*(_c5 + eta - 1) - _c7), -_c8*(eta*eta*eta), -_c5*_c8*chi*xi/numpy.sqrt(_c3)


def stress_hertz_field_far(chi, eta, nu, p0, xi):
    """(``stress_hertz_sigma_rr_far``, ``stress_hertz_sigma_tt_far``) at once, their common
    subexpressions computed once (SymPy's cse): each as the relation's own function
    gives it, to rounding. Arguments as there.
    """
    import scipy.special

    _c0 = xi**(-2.0)
    _c1 = 1 - 2*nu
    _c2 = 1/(_c0 + 1)
    _c3 = 1/(3*eta + 3)
    _c4 = (eta*eta)
    _c5 = (2/15)*_c2*eta*xi**(-4.0)*(nu + 1)*scipy.special.hyp2f1(1, 3/2, 7/2, -_c0)
    return p0*(_c0*_c1*_c2*_c3 - _c0*_c2*(chi*chi)*eta/(_c0*_c4 + 1) - _c5), p0*(_c0*_c1*_c2*_c3*(_c4 + eta - 1) - _c5)


def stress_spheroidal(a, r, z):
    """(``stress_spheroidal_u``, ``stress_spheroidal_u_inside``,
    ``stress_spheroidal_cos_beta_inside``) at once, their common subexpressions computed
    once (SymPy's cse): each as the relation's own function gives it, to rounding.
    Arguments as there.
    """
    _c0 = (z*z)
    _c1 = _c0*(a*a)
    _c2 = (-a + r)*(a + r)
    _c3 = _c0 + _c2
    _c4 = numpy.sqrt(4*_c1 + (_c3*_c3))
    _c5 = (1/2)*_c0 + (1/2)*_c2
    return (1/2)*_c4 + _c5, 2*_c1/(-_c3 + _c4), numpy.sqrt((1/2)*_c4 - _c5)/a


def _math_adhesion_cone_depth(E_star, a, dgamma, theta):
    """``adhesion_cone_depth`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*a*math.tan(theta) - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*math.sqrt(dgamma)/math.sqrt(E_star)


def _math_adhesion_cone_force_from_radius(E_star, a, dgamma, theta):
    """``adhesion_cone_force_from_radius`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*math.sqrt(dgamma) + (1/2)*math.pi*E_star*(a*a)*math.tan(theta)


def _math_adhesion_cone_g_slope(theta):
    """``adhesion_cone_g_slope`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*math.tan(theta)


def _math_adhesion_cone_pull_off_depth_dc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_depth_dc`` for Python floats (the math module); raises where it does."""
    return -dgamma/(E_star*math.tan(theta))


def _math_adhesion_cone_pull_off_depth_fc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_depth_fc`` for Python floats (the math module); raises where it does."""
    return 3*dgamma/(E_star*math.tan(theta))


def _math_adhesion_cone_pull_off_force_dc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_force_dc`` for Python floats (the math module); raises where it does."""
    return -6*(dgamma*dgamma)/(math.pi*E_star*math.tan(theta)**3)


def _math_adhesion_cone_pull_off_force_fc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_force_fc`` for Python floats (the math module); raises where it does."""
    return -54*(dgamma*dgamma)/(math.pi*E_star*math.tan(theta)**3)


def _math_adhesion_cone_pull_off_radius_dc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_radius_dc`` for Python floats (the math module); raises where it does."""
    return 2*dgamma/(math.pi*E_star*(math.tan(theta)*math.tan(theta)))


def _math_adhesion_cone_pull_off_radius_fc(E_star, dgamma, theta):
    """``adhesion_cone_pull_off_radius_fc`` for Python floats (the math module); raises where it does."""
    return 18*dgamma/(math.pi*E_star*(math.tan(theta)*math.tan(theta)))


def _math_adhesion_cone_zero_load_radius(E_star, dgamma, theta):
    """``adhesion_cone_zero_load_radius`` for Python floats (the math module); raises where it does."""
    return 32*dgamma/(math.pi*E_star*(math.tan(theta)*math.tan(theta)))


def _math_adhesion_critical_elongation(E_star, a, dgamma):
    """``adhesion_critical_elongation`` for Python floats (the math module); raises where it does."""
    return math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*math.sqrt(dgamma)/math.sqrt(E_star)


def _math_adhesion_depth(E_star, a, dgamma, g_a):
    """``adhesion_depth`` for Python floats (the math module); raises where it does."""
    return g_a - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*math.sqrt(dgamma)/math.sqrt(E_star)


def _math_adhesion_depth_slope(E_star, a, dgamma, g_slope):
    """``adhesion_depth_slope`` for Python floats (the math module); raises where it does."""
    return g_slope - 1/2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(dgamma)/(math.sqrt(E_star)*math.sqrt(a))


def _math_adhesion_displacement_outside_edge(E_star, a, dgamma, r):
    """``adhesion_displacement_outside_edge`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(a)*math.sqrt(dgamma)*math.asin(a/r)/(math.sqrt(math.pi)*math.sqrt(E_star))


def _math_adhesion_energy_release_rate(E_star, a, d, g_a):
    """``adhesion_energy_release_rate`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*((d - g_a)*(d - g_a))/(math.pi*a)


def _math_adhesion_force_slope(E_star, a, dgamma, g_slope):
    """``adhesion_force_slope`` for Python floats (the math module); raises where it does."""
    return -3*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.sqrt(a)*math.sqrt(dgamma) + 2*E_star*a*g_slope


def _math_adhesion_paraboloid_g_slope(R, x):
    """``adhesion_paraboloid_g_slope`` for Python floats (the math module); raises where it does."""
    return 2*x/R


def _math_adhesion_powerlaw_depth(E_star, a, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_depth`` for Python floats (the math module); raises where it does."""
    return math.pow(a, n)*c_n*kappa_n - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*math.sqrt(dgamma)/math.sqrt(E_star)


def _math_adhesion_powerlaw_force_from_radius(E_star, a, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_force_from_radius`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*math.sqrt(dgamma)*n/(n + 1) - 2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*math.sqrt(dgamma)/(n + 1) + 2*E_star*a*math.pow(a, n)*c_n*kappa_n*n/(n + 1)


def _math_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """``adhesion_powerlaw_g_slope`` for Python floats (the math module); raises where it does."""
    return c_n*kappa_n*n*math.pow(x, n - 1)


def _math_textbook_adhesion_powerlaw_g_slope(c_n, kappa_n, n, x):
    """``textbook_adhesion_powerlaw_g_slope`` for Python floats (the math module); raises where it does."""
    return c_n*kappa_n*n*math.pow(x, n)/x


def _math_adhesion_powerlaw_pull_off_depth_dc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_depth_dc`` for Python floats (the math module); raises where it does."""
    return -1/2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(dgamma)*(2*n - 1)*math.sqrt(math.pow((1/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1)))/(math.sqrt(E_star)*n)


def _math_adhesion_powerlaw_pull_off_depth_fc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_depth_fc`` for Python floats (the math module); raises where it does."""
    return -1/2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(dgamma)*(2*n - 3)*math.sqrt(math.pow((9/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1)))/(math.sqrt(E_star)*n)


def _math_adhesion_powerlaw_pull_off_force_dc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_force_dc`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.sqrt(dgamma)*(2*n + 1)*math.pow(math.pow((1/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1)), 3/2)/(n + 1)


def _math_adhesion_powerlaw_pull_off_force_fc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_force_fc`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.sqrt(dgamma)*(2*n - 1)*math.pow(math.pow((9/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1)), 3/2)/(n + 1)


def _math_adhesion_powerlaw_pull_off_radius_dc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_radius_dc`` for Python floats (the math module); raises where it does."""
    return math.pow((1/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1))


def _math_adhesion_powerlaw_pull_off_radius_fc(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_pull_off_radius_fc`` for Python floats (the math module); raises where it does."""
    return math.pow((9/2)*math.pi*dgamma/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1))


def _math_adhesion_powerlaw_zero_load_radius(E_star, dgamma, c_n, kappa_n, n):
    """``adhesion_powerlaw_zero_load_radius`` for Python floats (the math module); raises where it does."""
    return math.pow(2*math.pi*dgamma*((n*n) + 2*n + 1)/(E_star*(c_n*c_n)*(kappa_n*kappa_n)*(n*n)), 1/(2*n - 1))


def _math_adhesion_pressure_edge(E_star, a, dgamma, r):
    """``adhesion_pressure_edge`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*math.sqrt(E_star)*math.sqrt(a)*math.sqrt(dgamma)/(math.sqrt(math.pi)*math.sqrt(a - r)*math.sqrt(a + r))


def _math_textbook_adhesion_pressure_edge(E_star, a, dgamma, r):
    """``textbook_adhesion_pressure_edge`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*math.sqrt(E_star)*math.sqrt(a)*math.sqrt(dgamma)/(math.sqrt(math.pi)*math.sqrt((a*a) - (r*r)))


def _math_adhesion_punch_cycle_work(E_star, a, dgamma):
    """``adhesion_punch_cycle_work`` for Python floats (the math module); raises where it does."""
    return 2*math.pi*(a*a)*dgamma


def _math_adhesion_punch_pull_off_force(E_star, a, dgamma):
    """``adhesion_punch_pull_off_force`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*math.sqrt(dgamma)


def _math_adhesion_sphere_g_slope(R, x):
    """``adhesion_sphere_g_slope`` for Python floats (the math module); raises where it does."""
    return R*x/((R - x)*(R + x)) + (1/2)*math.log1p(2*x/(R - x))


def _math_textbook_adhesion_sphere_g_slope(R, x):
    """``textbook_adhesion_sphere_g_slope`` for Python floats (the math module); raises where it does."""
    return (R*x + ((R*R) - (x*x))*math.atanh(x/R))/((R*R) - (x*x))


def _math_adhesion_tabor_parameter(E_star, R, dgamma, z0):
    """``adhesion_tabor_parameter`` for Python floats (the math module); raises where it does."""
    return math.pow(R, 1/3)*math.pow(dgamma, 2/3)/(math.pow(E_star, 2/3)*z0)


def _math_adhesion_worn_g_slope(R, b, x):
    """``adhesion_worn_g_slope`` for Python floats (the math module); raises where it does."""
    return (-(b*b) + 2*(x*x))/(R*math.sqrt(-b + x)*math.sqrt(b + x))


def _math_textbook_adhesion_worn_g_slope(R, b, x):
    """``textbook_adhesion_worn_g_slope`` for Python floats (the math module); raises where it does."""
    return (-(b*b) + 2*(x*x))/(R*math.sqrt(-(b*b) + (x*x)))


def _math_bodies_crossed_cylinders_curvature_1(R1, R2, alpha):
    """``bodies_crossed_cylinders_curvature_1`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(((math.cos(2*alpha)/R2 + 1/R1)*(math.cos(2*alpha)/R2 + 1/R1)) + (math.sin(2*alpha)*math.sin(2*alpha))/(R2*R2)) + (1/2)/R2 + (1/2)/R1


def _math_bodies_crossed_cylinders_curvature_2(R1, R2, alpha):
    """``bodies_crossed_cylinders_curvature_2`` for Python floats (the math module); raises where it does."""
    return 2*(math.sin(alpha)*math.sin(alpha))/(R1*R2*(math.sqrt(((math.cos(2*alpha)/R2 + 1/R1)*(math.cos(2*alpha)/R2 + 1/R1)) + (math.sin(2*alpha)*math.sin(2*alpha))/(R2*R2)) + 1/R2 + 1/R1))


def _math_textbook_bodies_crossed_cylinders_curvature_2(R1, R2, alpha):
    """``textbook_bodies_crossed_cylinders_curvature_2`` for Python floats (the math module); raises where it does."""
    return -1/2*math.sqrt(((math.cos(2*alpha)/R2 + 1/R1)*(math.cos(2*alpha)/R2 + 1/R1)) + (math.sin(2*alpha)*math.sin(2*alpha))/(R2*R2)) + (1/2)/R2 + (1/2)/R1


def _math_bodies_crossed_cylinders_gaussian_radius(R1, R2, alpha):
    """``bodies_crossed_cylinders_gaussian_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R1)*math.sqrt(R2)/abs(math.sin(alpha))


def _math_bodies_effective_modulus(E1, nu1, E2, nu2):
    """``bodies_effective_modulus`` for Python floats (the math module); raises where it does."""
    return 1/((1 - nu2)*(nu2 + 1)/E2 + (1 - nu1)*(nu1 + 1)/E1)


def _math_textbook_bodies_effective_modulus(E1, nu1, E2, nu2):
    """``textbook_bodies_effective_modulus`` for Python floats (the math module); raises where it does."""
    return -E1*E2/(E1*(nu2*nu2) - E1 + E2*(nu1*nu1) - E2)


def _math_bodies_effective_modulus_rigid(E, nu):
    """``bodies_effective_modulus_rigid`` for Python floats (the math module); raises where it does."""
    return E/((1 - nu)*(nu + 1))


def _math_textbook_bodies_effective_modulus_rigid(E, nu):
    """``textbook_bodies_effective_modulus_rigid`` for Python floats (the math module); raises where it does."""
    return -E/((nu*nu) - 1)


def _math_bodies_effective_radius(R1, R2):
    """``bodies_effective_radius`` for Python floats (the math module); raises where it does."""
    return 1/(1/R2 + 1/R1)


def _math_textbook_bodies_effective_radius(R1, R2):
    """``textbook_bodies_effective_radius`` for Python floats (the math module); raises where it does."""
    return R1*R2/(R1 + R2)


def _math_bodies_gaussian_approx_area(R1, R2, d):
    """``bodies_gaussian_approx_area`` for Python floats (the math module); raises where it does."""
    return math.pi*math.sqrt(R1)*math.sqrt(R2)*d


def _math_bodies_gaussian_approx_depth_from_force(E_star, F, R1, R2):
    """``bodies_gaussian_approx_depth_from_force`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pow(6, 2/3)*math.pow(F, 2/3)/(math.pow(E_star, 2/3)*math.pow(R1, 1/6)*math.pow(R2, 1/6))


def _math_bodies_gaussian_approx_force(E_star, R1, R2, d):
    """``bodies_gaussian_approx_force`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*math.pow(R1, 1/4)*math.pow(R2, 1/4)*math.pow(d, 3/2)


def _math_bodies_gaussian_approx_max_pressure(E_star, R1, R2, d):
    """``bodies_gaussian_approx_max_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(d)/(math.pi*math.pow(R1, 1/4)*math.pow(R2, 1/4))


def _math_bodies_gaussian_approx_pressure(E_star, R1, R2, d, x, y):
    """``bodies_gaussian_approx_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(d)*math.sqrt(max(0, 1 - (y*y)/(R2*d) - (x*x)/(R1*d)))/(math.pi*math.pow(R1, 1/4)*math.pow(R2, 1/4))


def _math_bodies_gaussian_approx_semi_axis_1(R1, d):
    """``bodies_gaussian_approx_semi_axis_1`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R1)*math.sqrt(d)


def _math_bodies_gaussian_approx_semi_axis_2(R2, d):
    """``bodies_gaussian_approx_semi_axis_2`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R2)*math.sqrt(d)


def _math_bodies_gaussian_radius(R1, R2):
    """``bodies_gaussian_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R1)*math.sqrt(R2)


def _math_bodies_principal_curvature_1(R1a, R1b, R2a, R2b, omega):
    """``bodies_principal_curvature_1`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(((-1/R2b + 1/R2a)*(-1/R2b + 1/R2a))*(math.sin(2*omega)*math.sin(2*omega)) + (((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a)*((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a))) + (1/2)/R2b + (1/2)/R2a + (1/2)/R1b + (1/2)/R1a


def _math_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega):
    """``bodies_principal_curvature_2`` for Python floats (the math module); raises where it does."""
    return (2*(1/(R1b*R2a) + 1/(R1a*R2b))*(math.cos(omega)*math.cos(omega)) + 2*(1/(R1b*R2b) + 1/(R1a*R2a))*(math.sin(omega)*math.sin(omega)) + 2/(R2a*R2b) + 2/(R1a*R1b))/(math.sqrt(((-1/R2b + 1/R2a)*(-1/R2b + 1/R2a))*(math.sin(2*omega)*math.sin(2*omega)) + (((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a)*((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a))) + 1/R2b + 1/R2a + 1/R1b + 1/R1a)


def _math_textbook_bodies_principal_curvature_2(R1a, R1b, R2a, R2b, omega):
    """``textbook_bodies_principal_curvature_2`` for Python floats (the math module); raises where it does."""
    return -1/2*math.sqrt(((-1/R2b + 1/R2a)*(-1/R2b + 1/R2a))*(math.sin(2*omega)*math.sin(2*omega)) + (((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a)*((-1/R2b + 1/R2a)*math.cos(2*omega) - 1/R1b + 1/R1a))) + (1/2)/R2b + (1/2)/R2a + (1/2)/R1b + (1/2)/R1a


def _math_bodies_problem2_force(E, nu, R, d):
    """``bodies_problem2_force`` for Python floats (the math module); raises where it does."""
    return -2*math.pow(2, 1/4)*E*math.sqrt(R)*math.pow(d, 3/2)/(3*(nu*nu) - 3)


def _math_bodies_problem2_gaussian_radius(R):
    """``bodies_problem2_gaussian_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt(2)*R


def _math_bodies_problem2_principal_radius_1(R):
    """``bodies_problem2_principal_radius_1`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*R + 2*R


def _math_bodies_problem2_principal_radius_2(R):
    """``bodies_problem2_principal_radius_2`` for Python floats (the math module); raises where it does."""
    return math.sqrt(2)*R + 2*R


def _math_boussinesq_sigma_xx(F, nu, x, y, z):
    """``boussinesq_sigma_xx`` for Python floats (the math module); raises where it does."""
    return -1/2*F*(2*nu*(x*x)*z*((x*x) + (y*y) + (z*z)) + 4*nu*(x*x)*math.pow((x*x) + (y*y) + (z*z), 3/2) + 2*nu*z**3*((x*x) + (y*y) + (z*z)) + 4*nu*(z*z)*math.pow((x*x) + (y*y) + (z*z), 3/2) - 2*nu*math.pow((x*x) + (y*y) + (z*z), 5/2) + 3*(x*x)*z**3 + 6*(x*x)*(z*z)*math.sqrt((x*x) + (y*y) + (z*z)) + 2*(x*x)*z*((x*x) + (y*y) + (z*z)) - 2*(x*x)*math.pow((x*x) + (y*y) + (z*z), 3/2) - z**3*((x*x) + (y*y) + (z*z)) - 2*(z*z)*math.pow((x*x) + (y*y) + (z*z), 3/2) + math.pow((x*x) + (y*y) + (z*z), 5/2))/(math.pi*((z + math.sqrt((x*x) + (y*y) + (z*z)))*(z + math.sqrt((x*x) + (y*y) + (z*z))))*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_sigma_xy(F, nu, x, y, z):
    """``boussinesq_sigma_xy`` for Python floats (the math module); raises where it does."""
    return -1/2*F*x*y*(2*nu*z*((x*x) + (y*y) + (z*z)) + 4*nu*math.pow((x*x) + (y*y) + (z*z), 3/2) + 3*z**3 + 6*(z*z)*math.sqrt((x*x) + (y*y) + (z*z)) + 2*z*((x*x) + (y*y) + (z*z)) - 2*math.pow((x*x) + (y*y) + (z*z), 3/2))/(math.pi*((z + math.sqrt((x*x) + (y*y) + (z*z)))*(z + math.sqrt((x*x) + (y*y) + (z*z))))*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_sigma_xz(F, nu, x, y, z):
    """``boussinesq_sigma_xz`` for Python floats (the math module); raises where it does."""
    return -3/2*F*x*(z*z)/(math.pi*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_sigma_yy(F, nu, x, y, z):
    """``boussinesq_sigma_yy`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*(2*nu*(x*x)*z*((x*x) + (y*y) + (z*z)) + 4*nu*(x*x)*math.pow((x*x) + (y*y) + (z*z), 3/2) - 2*nu*z*(((x*x) + (y*y) + (z*z))*((x*x) + (y*y) + (z*z))) - 2*nu*math.pow((x*x) + (y*y) + (z*z), 5/2) + 3*(x*x)*z**3 + 6*(x*x)*(z*z)*math.sqrt((x*x) + (y*y) + (z*z)) + 2*(x*x)*z*((x*x) + (y*y) + (z*z)) - 2*(x*x)*math.pow((x*x) + (y*y) + (z*z), 3/2) + 3*z**5 + 6*z**4*math.sqrt((x*x) + (y*y) + (z*z)) - 6*(z*z)*math.pow((x*x) + (y*y) + (z*z), 3/2) - 2*z*(((x*x) + (y*y) + (z*z))*((x*x) + (y*y) + (z*z))) + math.pow((x*x) + (y*y) + (z*z), 5/2))/(math.pi*((z + math.sqrt((x*x) + (y*y) + (z*z)))*(z + math.sqrt((x*x) + (y*y) + (z*z))))*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_sigma_yz(F, nu, x, y, z):
    """``boussinesq_sigma_yz`` for Python floats (the math module); raises where it does."""
    return -3/2*F*y*(z*z)/(math.pi*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_sigma_zz(F, nu, x, y, z):
    """``boussinesq_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -3/2*F*z**3/(math.pi*math.pow((x*x) + (y*y) + (z*z), 5/2))


def _math_boussinesq_surface_prefactor(E_star):
    """``boussinesq_surface_prefactor`` for Python floats (the math module); raises where it does."""
    return 1/(math.pi*E_star)


def _math_boussinesq_surface_ux(E, F, nu, x, y):
    """``boussinesq_surface_ux`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*x*(nu + 1)*(2*nu - 1)/(math.pi*E*((x*x) + (y*y)))


def _math_boussinesq_surface_uy(E, F, nu, x, y):
    """``boussinesq_surface_uy`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*y*(nu + 1)*(2*nu - 1)/(math.pi*E*((x*x) + (y*y)))


def _math_boussinesq_surface_uz(E, F, nu, x, y):
    """``boussinesq_surface_uz`` for Python floats (the math module); raises where it does."""
    return -F*(nu - 1)*(nu + 1)/(math.pi*E*math.sqrt((x*x) + (y*y)))


def _math_boussinesq_ux(E, F, nu, x, y, z):
    """``boussinesq_ux`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*(nu + 1)*(x*z/math.pow((x*x) + (y*y) + (z*z), 3/2) - x*(1 - 2*nu)/((z + math.sqrt((x*x) + (y*y) + (z*z)))*math.sqrt((x*x) + (y*y) + (z*z))))/(math.pi*E)


def _math_boussinesq_uy(E, F, nu, x, y, z):
    """``boussinesq_uy`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*(nu + 1)*(y*z/math.pow((x*x) + (y*y) + (z*z), 3/2) - y*(1 - 2*nu)/((z + math.sqrt((x*x) + (y*y) + (z*z)))*math.sqrt((x*x) + (y*y) + (z*z))))/(math.pi*E)


def _math_boussinesq_uz(E, F, nu, x, y, z):
    """``boussinesq_uz`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*(nu + 1)*((z*z)/math.pow((x*x) + (y*y) + (z*z), 3/2) + (2 - 2*nu)/math.sqrt((x*x) + (y*y) + (z*z)))/(math.pi*E)


def _math_cattaneo_displacement(a, F, G_star, mu_f, F_x):
    """``cattaneo_displacement`` for Python floats (the math module); raises where it does."""
    return -3/4*F*mu_f*math.expm1((2/3)*math.log1p(-F_x/(F*mu_f)))/(G_star*a)


def _math_textbook_cattaneo_displacement(a, F, G_star, mu_f, F_x):
    """``textbook_cattaneo_displacement`` for Python floats (the math module); raises where it does."""
    return (3/4)*(-math.pow(F, 1/3)*math.pow(mu_f, 1/3)*math.pow(F*mu_f - F_x, 2/3) + F*mu_f)/(G_star*a)


def _math_cattaneo_force(a, R, E_star, G_star, mu_f, u_x):
    """``cattaneo_force`` for Python floats (the math module); raises where it does."""
    return (4/3)*G_star*u_x*((a*a) + (E_star*(a*a)*mu_f - G_star*R*u_x)/(E_star*mu_f) + a*math.sqrt(E_star*(a*a)*mu_f - G_star*R*u_x)/(math.sqrt(E_star)*math.sqrt(mu_f)))/(a + math.sqrt(E_star*(a*a)*mu_f - G_star*R*u_x)/(math.sqrt(E_star)*math.sqrt(mu_f)))


def _math_textbook_cattaneo_force(a, R, E_star, G_star, mu_f, u_x):
    """``textbook_cattaneo_force`` for Python floats (the math module); raises where it does."""
    return (4/3)*(math.pow(E_star, 3/2)*a**3*math.pow(mu_f, 3/2) - E_star*(a*a)*mu_f*math.sqrt(E_star*(a*a)*mu_f - G_star*R*u_x) + G_star*R*u_x*math.sqrt(E_star*(a*a)*mu_f - G_star*R*u_x))/(math.sqrt(E_star)*R*math.sqrt(mu_f))


def _math_cattaneo_stick_radius(a, R, E_star, G_star, mu_f, u_x):
    """``cattaneo_stick_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt(E_star*(a*a)*mu_f - G_star*R*u_x)/(math.sqrt(E_star)*math.sqrt(mu_f))


def _math_cattaneo_stick_radius_from_force(a, F, mu_f, F_x):
    """``cattaneo_stick_radius_from_force`` for Python floats (the math module); raises where it does."""
    return a*math.pow(F*mu_f - F_x, 1/3)/(math.pow(F, 1/3)*math.pow(mu_f, 1/3))


def _math_cattaneo_traction_slip(r, a, R, E_star, mu_f):
    """``cattaneo_traction_slip`` for Python floats (the math module); raises where it does."""
    return 2*E_star*mu_f*math.sqrt((a*a) - (r*r))/(math.pi*R)


def _math_cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """``cattaneo_traction_stick`` for Python floats (the math module); raises where it does."""
    return 2*E_star*mu_f*(a - c)*(a + c)/(math.pi*R*(math.sqrt(a - r)*math.sqrt(a + r) + math.sqrt(c - r)*math.sqrt(c + r)))


def _math_textbook_cattaneo_traction_stick(r, a, c, R, E_star, mu_f):
    """``textbook_cattaneo_traction_stick`` for Python floats (the math module); raises where it does."""
    return 2*E_star*mu_f*(math.sqrt((a*a) - (r*r)) - math.sqrt((c*c) - (r*r)))/(math.pi*R)


def _math_cerruti_surface_ux(G, Q, nu, x, y):
    """``cerruti_surface_ux`` for Python floats (the math module); raises where it does."""
    return (1/2)*Q*(-nu*(y*y) + (x*x) + (y*y))/(math.pi*G*math.pow((x*x) + (y*y), 3/2))


def _math_cerruti_surface_uy(G, Q, nu, x, y):
    """``cerruti_surface_uy`` for Python floats (the math module); raises where it does."""
    return (1/2)*Q*nu*x*y/(math.pi*G*math.pow((x*x) + (y*y), 3/2))


def _math_cerruti_surface_uz(G, Q, nu, x, y):
    """``cerruti_surface_uz`` for Python floats (the math module); raises where it does."""
    return -1/4*Q*x*(2*nu - 1)/(math.pi*G*((x*x) + (y*y)))


def _math_cerruti_ux(G, Q, nu, x, y, z):
    """``cerruti_ux`` for Python floats (the math module); raises where it does."""
    return (1/4)*Q*((x*x)/math.pow((x*x) + (y*y) + (z*z), 3/2) + (1 - 2*nu)*(-(x*x)/(((z + math.sqrt((x*x) + (y*y) + (z*z)))*(z + math.sqrt((x*x) + (y*y) + (z*z))))*math.sqrt((x*x) + (y*y) + (z*z))) + 1/(z + math.sqrt((x*x) + (y*y) + (z*z)))) + 1/math.sqrt((x*x) + (y*y) + (z*z)))/(math.pi*G)


def _math_cerruti_uy(G, Q, nu, x, y, z):
    """``cerruti_uy`` for Python floats (the math module); raises where it does."""
    return (1/4)*Q*(-x*y*(1 - 2*nu)/(((z + math.sqrt((x*x) + (y*y) + (z*z)))*(z + math.sqrt((x*x) + (y*y) + (z*z))))*math.sqrt((x*x) + (y*y) + (z*z))) + x*y/math.pow((x*x) + (y*y) + (z*z), 3/2))/(math.pi*G)


def _math_cerruti_uz(G, Q, nu, x, y, z):
    """``cerruti_uz`` for Python floats (the math module); raises where it does."""
    return (1/4)*Q*(x*z/math.pow((x*x) + (y*y) + (z*z), 3/2) + x*(1 - 2*nu)/((z + math.sqrt((x*x) + (y*y) + (z*z)))*math.sqrt((x*x) + (y*y) + (z*z))))/(math.pi*G)


def _math_cone_contact_radius(d, theta):
    """``cone_contact_radius`` for Python floats (the math module); raises where it does."""
    return 2*d/(math.pi*math.tan(theta))


def _math_cone_contact_radius_from_force(E_star, F, theta):
    """``cone_contact_radius_from_force`` for Python floats (the math module); raises where it does."""
    return math.sqrt(2)*math.sqrt(F)/(math.sqrt(math.pi)*math.sqrt(E_star)*math.sqrt(math.tan(theta)))


def _math_cone_depth(a, theta):
    """``cone_depth`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*a*math.tan(theta)


def _math_cone_depth_from_force(E_star, F, theta):
    """``cone_depth_from_force`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(F)*math.sqrt(math.tan(theta))/math.sqrt(E_star)


def _math_cone_force(E_star, d, theta):
    """``cone_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*(d*d)/(math.pi*math.tan(theta))


def _math_cone_g(theta, x):
    """``cone_g`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*x*math.tan(theta)


def _math_cone_mean_pressure(E_star, theta):
    """``cone_mean_pressure`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*math.tan(theta)


def _math_cone_pressure(E_star, d, theta, r):
    """``cone_pressure`` for Python floats (the math module); raises where it does."""
    return E_star*math.tan(theta)*math.asinh((1/2)*math.sqrt(2)*math.sqrt(2*d/(math.pi*math.tan(theta)) - r)/math.sqrt(r))


def _math_textbook_cone_pressure(E_star, d, theta, r):
    """``textbook_cone_pressure`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*math.tan(theta)*math.acosh(2*d/(math.pi*r*math.tan(theta)))


def _math_cone_profile(theta, r):
    """``cone_profile`` for Python floats (the math module); raises where it does."""
    return r*math.tan(theta)


def _math_cone_stiffness(E_star, d, theta):
    """``cone_stiffness`` for Python floats (the math module); raises where it does."""
    return 4*E_star*d/(math.pi*math.tan(theta))


def _math_contact_mean_pressure(A, F):
    """``contact_mean_pressure`` for Python floats (the math module); raises where it does."""
    return F/A


def _math_coulomb_sliding_force(mu_f, F):
    """``coulomb_sliding_force`` for Python floats (the math module); raises where it does."""
    return F*mu_f


def _math_disc_mean_pressure(F, a):
    """``disc_mean_pressure`` for Python floats (the math module); raises where it does."""
    return F/(math.pi*(a*a))


def _math_disc_pressure(a, n_p, p0, r):
    """``disc_pressure`` for Python floats (the math module); raises where it does."""
    return p0*math.pow((a - r)*(a + r)/(a*a), n_p)


def _math_textbook_disc_pressure(a, n_p, p0, r):
    """``textbook_disc_pressure`` for Python floats (the math module); raises where it does."""
    return p0*math.pow(1 - (r*r)/(a*a), n_p)


def _math_ellipse_stress_axis_sigma_zz(a, b_e, p0, z):
    """``ellipse_stress_axis_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -a*b_e*p0/(math.sqrt((a*a) + (z*z))*math.sqrt((b_e*b_e) + (z*z)))


def _math_ellipse_stress_cubic_lam(a, b_e, z, w1_e, d_e, lam_e):
    """``ellipse_stress_cubic_lam`` for Python floats (the math module); raises where it does."""
    return lam_e*(lam_e - w1_e)*(d_e + lam_e - w1_e) - (z*z)*((a*a) + lam_e)*((b_e*b_e) + lam_e)


def _math_ellipse_stress_cubic_lam_slope(a, b_e, z, w1_e, d_e, lam_e):
    """``ellipse_stress_cubic_lam_slope`` for Python floats (the math module); raises where it does."""
    return lam_e*(lam_e - w1_e) + lam_e*(d_e + lam_e - w1_e) - (z*z)*((a*a) + lam_e) - (z*z)*((b_e*b_e) + lam_e) + (lam_e - w1_e)*(d_e + lam_e - w1_e)


def _math_ellipse_stress_cubic_q(z, w1_e, w1_a, w1_b, d_e, q_e):
    """``ellipse_stress_cubic_q`` for Python floats (the math module); raises where it does."""
    return q_e*(d_e + q_e)*(q_e + w1_e) - (z*z)*(q_e + w1_a)*(q_e + w1_b)


def _math_ellipse_stress_cubic_q_slope(z, w1_e, w1_a, w1_b, d_e, q_e):
    """``ellipse_stress_cubic_q_slope`` for Python floats (the math module); raises where it does."""
    return q_e*(d_e + q_e) + q_e*(q_e + w1_e) - (z*z)*(q_e + w1_a) - (z*z)*(q_e + w1_b) + (d_e + q_e)*(q_e + w1_e)


def _math_ellipse_stress_d(a, b_e, x, y):
    """``ellipse_stress_d`` for Python floats (the math module); raises where it does."""
    return math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y))))


def _math_ellipse_stress_e_sq(a, b_e, lam_e, q_e, d_e):
    """``ellipse_stress_e_sq`` for Python floats (the math module); raises where it does."""
    return q_e*(d_e + q_e)/(((a*a) + lam_e)*((b_e*b_e) + lam_e))


def _math_ellipse_stress_jxx_integrand(x, w1_a, w1_b, d_e, v_q):
    """``ellipse_stress_jxx_integrand`` for Python floats (the math module); raises where it does."""
    return -2*(-d_e*(v_q*v_q) - v_q**4 + (v_q*v_q)*(x*x) + w1_b*(x*x))/(math.sqrt(d_e + (v_q*v_q))*(((v_q*v_q) + w1_a)*((v_q*v_q) + w1_a))*((v_q*v_q) + w1_b))


def _math_ellipse_stress_jxy_integrand(x, y, w1_a, w1_b, d_e, v_q):
    """``ellipse_stress_jxy_integrand`` for Python floats (the math module); raises where it does."""
    return -2*x*y/(math.sqrt(d_e + (v_q*v_q))*((v_q*v_q) + w1_a)*((v_q*v_q) + w1_b))


def _math_ellipse_stress_jyy_integrand(y, w1_a, w1_b, d_e, v_q):
    """``ellipse_stress_jyy_integrand`` for Python floats (the math module); raises where it does."""
    return -2*(-d_e*(v_q*v_q) - v_q**4 + (v_q*v_q)*(y*y) + w1_a*(y*y))/(math.sqrt(d_e + (v_q*v_q))*((v_q*v_q) + w1_a)*(((v_q*v_q) + w1_b)*((v_q*v_q) + w1_b)))


def _math_ellipse_stress_sigma_xx(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_xx):
    """``ellipse_stress_sigma_xx`` for Python floats (the math module); raises where it does."""
    return I_x*a*b_e*e_c*math.sqrt(lam_e)*p0 + I_y*a*b_e*e_c*math.sqrt(lam_e)*nu*p0 + (1/2)*J_xx*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*(x*x) + 2*nu*(((a*a) + lam_e)*((a*a) + lam_e))*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))/(math.pow((a*a) + lam_e, 5/2)*math.sqrt((b_e*b_e) + lam_e)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_sigma_yy(a, b_e, nu, p0, x, y, lam_e, e_c, I_x, I_y, J_yy):
    """``ellipse_stress_sigma_yy`` for Python floats (the math module); raises where it does."""
    return I_x*a*b_e*e_c*math.sqrt(lam_e)*nu*p0 + I_y*a*b_e*e_c*math.sqrt(lam_e)*p0 + (1/2)*J_yy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*p0*(lam_e*(y*y) + 2*nu*(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e))*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))/(math.sqrt((a*a) + lam_e)*math.pow((b_e*b_e) + lam_e, 5/2)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_sigma_zz(a, b_e, p0, x, y, lam_e, e_c):
    """``ellipse_stress_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -a*b_e*e_c**3*p0/(math.sqrt((a*a) + lam_e)*math.sqrt((b_e*b_e) + lam_e)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_tau_xy(a, b_e, nu, p0, x, y, lam_e, e_c, J_xy):
    """``ellipse_stress_tau_xy`` for Python floats (the math module); raises where it does."""
    return (1/2)*J_xy*a*b_e*p0*(2*nu - 1) - a*b_e*e_c*lam_e*p0*x*y/(math.pow((a*a) + lam_e, 3/2)*math.pow((b_e*b_e) + lam_e, 3/2)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_tau_xz(a, b_e, p0, x, y, lam_e, e_c):
    """``ellipse_stress_tau_xz`` for Python floats (the math module); raises where it does."""
    return -a*b_e*(e_c*e_c)*math.sqrt(lam_e)*p0*x/(math.pow((a*a) + lam_e, 3/2)*math.sqrt((b_e*b_e) + lam_e)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_tau_yz(a, b_e, p0, x, y, lam_e, e_c):
    """``ellipse_stress_tau_yz`` for Python floats (the math module); raises where it does."""
    return -a*b_e*(e_c*e_c)*math.sqrt(lam_e)*p0*y/(math.sqrt((a*a) + lam_e)*math.pow((b_e*b_e) + lam_e, 3/2)*((e_c*e_c) + lam_e*((x*x)/(((a*a) + lam_e)*((a*a) + lam_e)) + (y*y)/(((b_e*b_e) + lam_e)*((b_e*b_e) + lam_e)))))


def _math_ellipse_stress_w1(a, b_e, x, y):
    """``ellipse_stress_w1`` for Python floats (the math module); raises where it does."""
    return ((-1/2*(a*a) - 1/2*(b_e*b_e) + (1/2)*(x*x) + (1/2)*(y*y) + (1/2)*math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y))))) if ((a*a) + (b_e*b_e) - (x*x) - (y*y) <= 0) else ((-2*(a*a)*(b_e*b_e) + 2*(a*a)*(y*y) + 2*(b_e*b_e)*(x*x))/((a*a) + (b_e*b_e) - (x*x) - (y*y) + math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y)))))))


def _math_ellipse_stress_w1_a(a, b_e, x, y):
    """``ellipse_stress_w1_a`` for Python floats (the math module); raises where it does."""
    return (1/2)*(x*x) + (1/2)*(y*y) + (1/2)*(a - b_e)*(a + b_e) + (1/2)*math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y))))


def _math_ellipse_stress_w1_b(a, b_e, x, y):
    """``ellipse_stress_w1_b`` for Python floats (the math module); raises where it does."""
    return ((-1/2*(a*a) + (1/2)*(b_e*b_e) + (1/2)*(x*x) + (1/2)*(y*y) + (1/2)*math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y))))) if (-(a*a) + (b_e*b_e) + (x*x) + (y*y) >= 0) else (2*(y*y)*(a - b_e)*(a + b_e)/((a*a) - (b_e*b_e) - (x*x) - (y*y) + math.sqrt(4*(x*x)*(y*y) + (((a*a) - (b_e*b_e) - (x*x) + (y*y))*((a*a) - (b_e*b_e) - (x*x) + (y*y)))))))


def _math_fit_adhesive_cone_depth(E_star, theta, a, rho_g):
    """``fit_adhesive_cone_depth`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*a*math.tan(theta) - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*rho_g/math.sqrt(E_star)


def _math_fit_adhesive_cone_depth_da(E_star, theta, a, rho_g):
    """``fit_adhesive_cone_depth_da`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pi*math.tan(theta) - 1/2*math.sqrt(2)*math.sqrt(math.pi)*rho_g/(math.sqrt(E_star)*math.sqrt(a))


def _math_fit_adhesive_cone_force(E_star, theta, a, rho_g, z_p, F_0, s_0):
    """``fit_adhesive_cone_force`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*rho_g + (1/2)*math.pi*E_star*(a*a)*math.tan(theta) + F_0 + s_0*z_p


def _math_fit_adhesive_cone_force_dE(E_star, theta, a, rho_g):
    """``fit_adhesive_cone_force_dE`` for Python floats (the math module); raises where it does."""
    return (1/2)*((math.pi*math.pi)*math.pow(E_star, 5/2)*math.pow(a, 5/2)*(math.tan(theta)*math.tan(theta)) + 16*math.pi*math.pow(E_star, 3/2)*math.pow(a, 3/2)*(rho_g*rho_g) - 5*math.sqrt(2)*math.pow(math.pi, 3/2)*(E_star*E_star)*(a*a)*rho_g*math.tan(theta))/(math.pi*math.pow(E_star, 5/2)*math.sqrt(a)*math.tan(theta) - math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*rho_g)


def _math_fit_adhesive_cone_force_ddgamma(E_star, theta, a, rho_g):
    """``fit_adhesive_cone_force_ddgamma`` for Python floats (the math module); raises where it does."""
    return 4*math.pi*E_star*math.pow(a, 3/2)/(math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*rho_g - math.pi*E_star*math.sqrt(a)*math.tan(theta))


def _math_fit_adhesive_cone_force_dz0(E_star, theta, a, rho_g):
    """``fit_adhesive_cone_force_dz0`` for Python floats (the math module); raises where it does."""
    return 2*(-math.pi*math.pow(E_star, 3/2)*math.pow(a, 3/2)*math.tan(theta) + 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*a*rho_g)/(math.pi*math.sqrt(E_star)*math.sqrt(a)*math.tan(theta) - math.sqrt(2)*math.sqrt(math.pi)*rho_g)


def _math_fit_adhesive_powerlaw_depth(E_star, c_n, kappa_n, n, a, rho_g):
    """``fit_adhesive_powerlaw_depth`` for Python floats (the math module); raises where it does."""
    return math.pow(a, n)*c_n*kappa_n - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*rho_g/math.sqrt(E_star)


def _math_fit_adhesive_powerlaw_depth_da(E_star, c_n, kappa_n, n, a, rho_g):
    """``fit_adhesive_powerlaw_depth_da`` for Python floats (the math module); raises where it does."""
    return math.pow(a, n)*c_n*kappa_n*n/a - 1/2*math.sqrt(2)*math.sqrt(math.pi)*rho_g/(math.sqrt(E_star)*math.sqrt(a))


def _math_fit_adhesive_powerlaw_force(E_star, c_n, kappa_n, n, a, rho_g, z_p, F_0, s_0):
    """``fit_adhesive_powerlaw_force`` for Python floats (the math module); raises where it does."""
    return F_0 + s_0*z_p + 2*(-math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*n*rho_g - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*rho_g + E_star*math.pow(a, n + 1)*c_n*kappa_n*n)/(n + 1)


def _math_fit_adhesive_powerlaw_force_dE(E_star, c_n, kappa_n, n, a, rho_g):
    """``fit_adhesive_powerlaw_force_dE`` for Python floats (the math module); raises where it does."""
    return 2*(2*math.pow(E_star, 5/2)*math.pow(a, 2*n + 3/2)*(c_n*c_n)*(kappa_n*kappa_n)*(n*n) + 4*math.pi*math.pow(E_star, 3/2)*math.pow(a, 5/2)*n*(rho_g*rho_g) + 4*math.pi*math.pow(E_star, 3/2)*math.pow(a, 5/2)*(rho_g*rho_g) - 2*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*math.pow(a, n + 2)*c_n*kappa_n*(n*n)*rho_g - 3*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*math.pow(a, n + 2)*c_n*kappa_n*n*rho_g)/((n + 1)*(2*math.pow(E_star, 5/2)*math.pow(a, n + 1/2)*c_n*kappa_n*n - math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*a*rho_g))


def _math_fit_adhesive_powerlaw_force_ddgamma(E_star, c_n, kappa_n, n, a, rho_g):
    """``fit_adhesive_powerlaw_force_ddgamma`` for Python floats (the math module); raises where it does."""
    return 4*math.pi*E_star*math.pow(a, 5/2)/(math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*a*rho_g - 2*E_star*math.pow(a, n + 1/2)*c_n*kappa_n*n)


def _math_fit_adhesive_powerlaw_force_dz0(E_star, c_n, kappa_n, n, a, rho_g):
    """``fit_adhesive_powerlaw_force_dz0`` for Python floats (the math module); raises where it does."""
    return 2*(-2*math.pow(E_star, 3/2)*math.pow(a, n + 3/2)*c_n*kappa_n*n + 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*(a*a)*rho_g)/(2*math.sqrt(E_star)*math.pow(a, n + 1/2)*c_n*kappa_n*n - math.sqrt(2)*math.sqrt(math.pi)*a*rho_g)


def _math_fit_adhesive_sampled_depth(E_star, g_a, g_slope, g_integral, a, rho_g):
    """``fit_adhesive_sampled_depth`` for Python floats (the math module); raises where it does."""
    return g_a - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*rho_g/math.sqrt(E_star)


def _math_fit_adhesive_sampled_depth_da(E_star, g_a, g_slope, g_integral, a, rho_g):
    """``fit_adhesive_sampled_depth_da`` for Python floats (the math module); raises where it does."""
    return g_slope - 1/2*math.sqrt(2)*math.sqrt(math.pi)*rho_g/(math.sqrt(E_star)*math.sqrt(a))


def _math_fit_adhesive_sampled_force(E_star, g_a, g_slope, g_integral, a, rho_g, z_p, F_0, s_0):
    """``fit_adhesive_sampled_force`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*rho_g + 2*E_star*a*g_a - 2*E_star*g_integral + F_0 + s_0*z_p


def _math_fit_adhesive_sampled_force_dE(E_star, g_a, g_slope, g_integral, a, rho_g):
    """``fit_adhesive_sampled_force_dE`` for Python floats (the math module); raises where it does."""
    return 2*(2*math.pow(E_star, 3/2)*math.pow(a, 3/2)*g_a*g_slope - 2*math.pow(E_star, 3/2)*math.sqrt(a)*g_integral*g_slope + 4*math.pi*math.sqrt(E_star)*math.pow(a, 3/2)*(rho_g*rho_g) - 2*math.sqrt(2)*math.sqrt(math.pi)*E_star*(a*a)*g_slope*rho_g - math.sqrt(2)*math.sqrt(math.pi)*E_star*a*g_a*rho_g + math.sqrt(2)*math.sqrt(math.pi)*E_star*g_integral*rho_g)/(2*math.pow(E_star, 3/2)*math.sqrt(a)*g_slope - math.sqrt(2)*math.sqrt(math.pi)*E_star*rho_g)


def _math_fit_adhesive_sampled_force_ddgamma(E_star, g_a, g_slope, g_integral, a, rho_g):
    """``fit_adhesive_sampled_force_ddgamma`` for Python floats (the math module); raises where it does."""
    return -4*math.pi*math.sqrt(E_star)*math.pow(a, 3/2)/(2*math.sqrt(E_star)*math.sqrt(a)*g_slope - math.sqrt(2)*math.sqrt(math.pi)*rho_g)


def _math_fit_adhesive_sampled_force_dz0(E_star, g_a, g_slope, g_integral, a, rho_g):
    """``fit_adhesive_sampled_force_dz0`` for Python floats (the math module); raises where it does."""
    return 2*(-2*math.pow(E_star, 3/2)*math.pow(a, 3/2)*g_slope + 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*a*rho_g)/(2*math.sqrt(E_star)*math.sqrt(a)*g_slope - math.sqrt(2)*math.sqrt(math.pi)*rho_g)


def _math_fit_adhesive_sphere_depth(E_star, R, a, rho_g):
    """``fit_adhesive_sphere_depth`` for Python floats (the math module); raises where it does."""
    return a*math.atanh(a/R) - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*rho_g/math.sqrt(E_star)


def _math_fit_adhesive_sphere_depth_da(E_star, R, a, rho_g):
    """``fit_adhesive_sphere_depth_da`` for Python floats (the math module); raises where it does."""
    return math.atanh(a/R) + a/(R*(1 - (a*a)/(R*R))) - 1/2*math.sqrt(2)*math.sqrt(math.pi)*rho_g/(math.sqrt(E_star)*math.sqrt(a))


def _math_fit_adhesive_sphere_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """``fit_adhesive_sphere_force`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*rho_g + E_star*((R*R)*math.atanh(a/R) - R*a + (a*a)*math.atanh(a/R)) + F_0 + s_0*z_p


def _math_fit_adhesive_sphere_force_dE(E_star, R, a, rho_g):
    """``fit_adhesive_sphere_force_dE`` for Python floats (the math module); raises where it does."""
    return (2*math.pow(E_star, 5/2)*R**4*math.sqrt(a)*(math.atanh(a/R)*math.atanh(a/R)) - 2*math.pow(E_star, 5/2)*(R*R)*math.pow(a, 5/2) + 4*math.pow(E_star, 5/2)*R*math.pow(a, 7/2)*math.atanh(a/R) - 2*math.pow(E_star, 5/2)*math.pow(a, 9/2)*(math.atanh(a/R)*math.atanh(a/R)) + 8*math.pi*math.pow(E_star, 3/2)*(R*R)*math.pow(a, 3/2)*(rho_g*rho_g) - 8*math.pi*math.pow(E_star, 3/2)*math.pow(a, 7/2)*(rho_g*rho_g) - math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*R**4*rho_g*math.atanh(a/R) + math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*R**3*a*rho_g - 4*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*(R*R)*(a*a)*rho_g*math.atanh(a/R) - 5*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*R*a**3*rho_g + 5*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*a**4*rho_g*math.atanh(a/R))/(2*math.pow(E_star, 5/2)*(R*R)*math.sqrt(a)*math.atanh(a/R) + 2*math.pow(E_star, 5/2)*R*math.pow(a, 3/2) - 2*math.pow(E_star, 5/2)*math.pow(a, 5/2)*math.atanh(a/R) - math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*(R*R)*rho_g + math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*(a*a)*rho_g)


def _math_fit_adhesive_sphere_force_ddgamma(E_star, R, a, rho_g):
    """``fit_adhesive_sphere_force_ddgamma`` for Python floats (the math module); raises where it does."""
    return 4*math.pi*E_star*math.pow(a, 3/2)*(-(R*R) + (a*a))/(-math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*(R*R)*rho_g + math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*(a*a)*rho_g + 2*E_star*(R*R)*math.sqrt(a)*math.atanh(a/R) + 2*E_star*R*math.pow(a, 3/2) - 2*E_star*math.pow(a, 5/2)*math.atanh(a/R))


def _math_fit_adhesive_sphere_force_dz0(E_star, R, a, rho_g):
    """``fit_adhesive_sphere_force_dz0`` for Python floats (the math module); raises where it does."""
    return 2*(-2*math.pow(E_star, 3/2)*(R*R)*math.pow(a, 3/2)*math.atanh(a/R) - 2*math.pow(E_star, 3/2)*R*math.pow(a, 5/2) + 2*math.pow(E_star, 3/2)*math.pow(a, 7/2)*math.atanh(a/R) + 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*(R*R)*a*rho_g - 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*a**3*rho_g)/(2*math.sqrt(E_star)*(R*R)*math.sqrt(a)*math.atanh(a/R) + 2*math.sqrt(E_star)*R*math.pow(a, 3/2) - 2*math.sqrt(E_star)*math.pow(a, 5/2)*math.atanh(a/R) - math.sqrt(2)*math.sqrt(math.pi)*(R*R)*rho_g + math.sqrt(2)*math.sqrt(math.pi)*(a*a)*rho_g)


def _math_fit_cone_force(E_star, theta, z_p, z_0, F_0, s_0):
    """``fit_cone_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*(max(0, -z_0 + z_p)*max(0, -z_0 + z_p))/(math.pi*math.tan(theta)) + F_0 + s_0*z_p


def _math_fit_cone_force_dE(theta, z_p, z_0):
    """``fit_cone_force_dE`` for Python floats (the math module); raises where it does."""
    return 2*(max(0, -z_0 + z_p)*max(0, -z_0 + z_p))/(math.pi*math.tan(theta))


def _math_fit_cone_force_dz0(E_star, theta, z_p, z_0):
    """``fit_cone_force_dz0`` for Python floats (the math module); raises where it does."""
    return -4*E_star*(((0) if (z_0 - z_p >= 0) else (1)))*max(0, -z_0 + z_p)/(math.pi*math.tan(theta))


def _math_fit_hertz_force(E_star, R, z_p, z_0, F_0, s_0):
    """``fit_hertz_force`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*math.sqrt(R)*math.pow(max(0, -z_0 + z_p), 3/2) + F_0 + s_0*z_p


def _math_fit_hertz_force_dE(R, z_p, z_0):
    """``fit_hertz_force_dE`` for Python floats (the math module); raises where it does."""
    return (4/3)*math.sqrt(R)*math.pow(max(0, -z_0 + z_p), 3/2)


def _math_fit_hertz_force_dz0(E_star, R, z_p, z_0):
    """``fit_hertz_force_dz0`` for Python floats (the math module); raises where it does."""
    return -2*E_star*math.sqrt(R)*(((0) if (z_0 - z_p >= 0) else (1)))*math.sqrt(max(0, -z_0 + z_p))


def _math_fit_jkr_depth(E_star, R, a, rho_g):
    """``fit_jkr_depth`` for Python floats (the math module); raises where it does."""
    return (a*a)/R - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*rho_g/math.sqrt(E_star)


def _math_fit_jkr_depth_da(E_star, R, a, rho_g):
    """``fit_jkr_depth_da`` for Python floats (the math module); raises where it does."""
    return 2*a/R - 1/2*math.sqrt(2)*math.sqrt(math.pi)*rho_g/(math.sqrt(E_star)*math.sqrt(a))


def _math_fit_jkr_force(E_star, R, a, rho_g, z_p, F_0, s_0):
    """``fit_jkr_force`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*rho_g + (4/3)*E_star*a**3/R + F_0 + s_0*z_p


def _math_fit_jkr_force_dE(E_star, R, a, rho_g):
    """``fit_jkr_force_dE`` for Python floats (the math module); raises where it does."""
    return (4/3)*(4*math.pow(E_star, 5/2)*math.pow(a, 9/2) + 6*math.pi*math.pow(E_star, 3/2)*(R*R)*math.pow(a, 3/2)*(rho_g*rho_g) - 7*math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*R*a**3*rho_g)/(R*(4*math.pow(E_star, 5/2)*math.pow(a, 3/2) - math.sqrt(2)*math.sqrt(math.pi)*(E_star*E_star)*R*rho_g))


def _math_fit_jkr_force_ddgamma(E_star, R, a, rho_g):
    """``fit_jkr_force_ddgamma`` for Python floats (the math module); raises where it does."""
    return 4*math.pi*E_star*R*math.pow(a, 3/2)/(math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*R*rho_g - 4*E_star*math.pow(a, 3/2))


def _math_fit_jkr_force_dz0(E_star, R, a, rho_g):
    """``fit_jkr_force_dz0`` for Python floats (the math module); raises where it does."""
    return 2*(-4*math.pow(E_star, 3/2)*math.pow(a, 5/2) + 3*math.sqrt(2)*math.sqrt(math.pi)*E_star*R*a*rho_g)/(4*math.sqrt(E_star)*math.pow(a, 3/2) - math.sqrt(2)*math.sqrt(math.pi)*R*rho_g)


def _math_fit_powerlaw_force(E_star, c_n, kappa_n, n, z_p, z_0, F_0, s_0):
    """``fit_powerlaw_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*n*math.pow(max(0, -z_0 + z_p)/(c_n*kappa_n), 1/n)*max(0, -z_0 + z_p)/(n + 1) + F_0 + s_0*z_p


def _math_fit_powerlaw_force_dE(c_n, kappa_n, n, z_p, z_0):
    """``fit_powerlaw_force_dE`` for Python floats (the math module); raises where it does."""
    return 2*n*math.pow(max(0, -z_0 + z_p)/(c_n*kappa_n), 1/n)*max(0, -z_0 + z_p)/(n + 1)


def _math_fit_powerlaw_force_dz0(E_star, c_n, kappa_n, n, z_p, z_0):
    """``fit_powerlaw_force_dz0`` for Python floats (the math module); raises where it does."""
    return -2*E_star*math.pow(max(0, -z_0 + z_p)/(c_n*kappa_n), 1/n)*(((0) if (z_0 - z_p >= 0) else (1)))


def _math_fit_punch_force(E_star, a, z_p, z_0, F_0, s_0):
    """``fit_punch_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a*max(0, -z_0 + z_p) + F_0 + s_0*z_p


def _math_fit_punch_force_dE(a, z_p, z_0):
    """``fit_punch_force_dE`` for Python floats (the math module); raises where it does."""
    return 2*a*max(0, -z_0 + z_p)


def _math_fit_punch_force_dz0(E_star, a, z_p, z_0):
    """``fit_punch_force_dz0`` for Python floats (the math module); raises where it does."""
    return -2*E_star*a*(((0) if (z_0 - z_p >= 0) else (1)))


def _math_fit_pyramid_cone_angle(alpha_p, n_sides):
    """``fit_pyramid_cone_angle`` for Python floats (the math module); raises where it does."""
    return math.atan(math.sqrt(math.pi)/(math.sqrt(n_sides)*math.tan(alpha_p)*math.sqrt(math.tan(math.pi/n_sides))))


def _math_fit_pyramid_force_cone_angle(alpha_p, n_sides, beta_p):
    """``fit_pyramid_force_cone_angle`` for Python floats (the math module); raises where it does."""
    return math.atan(math.sqrt(math.pi)/(beta_p*math.sqrt(n_sides)*math.tan(alpha_p)*math.sqrt(math.tan(math.pi/n_sides))))


def _math_fit_sample_modulus(E_star, nu1, E2, nu2):
    """``fit_sample_modulus`` for Python floats (the math module); raises where it does."""
    return E2*E_star*(1 - (nu1*nu1))/(E2 + E_star*(nu2*nu2) - E_star)


def _math_fit_sample_modulus_dE(E_star, nu1, E2, nu2):
    """``fit_sample_modulus_dE`` for Python floats (the math module); raises where it does."""
    return -(E2*E2)*(nu1*nu1)/((E2 + E_star*(nu2*nu2) - E_star)*(E2 + E_star*(nu2*nu2) - E_star)) + (E2*E2)/((E2 + E_star*(nu2*nu2) - E_star)*(E2 + E_star*(nu2*nu2) - E_star))


def _math_fit_sample_modulus_rigid(E_star, nu):
    """``fit_sample_modulus_rigid`` for Python floats (the math module); raises where it does."""
    return E_star*(1 - (nu*nu))


def _math_fit_sample_modulus_rigid_dE(nu):
    """``fit_sample_modulus_rigid_dE`` for Python floats (the math module); raises where it does."""
    return 1 - (nu*nu)


def _math_fit_sphere_depth(lam, a):
    """``fit_sphere_depth`` for Python floats (the math module); raises where it does."""
    return a*lam


def _math_fit_sphere_depth_dlam(R, lam, a):
    """``fit_sphere_depth_dlam`` for Python floats (the math module); raises where it does."""
    return a + lam*(R - a)*(R + a)/R


def _math_fit_sphere_force(E_star, R, lam, a, z_p, F_0, s_0):
    """``fit_sphere_force`` for Python floats (the math module); raises where it does."""
    return E_star*(((R*R)*lam**3/((lam*lam) + (lam*lam)/((lam*lam)/((lam*lam)/((lam*lam)/((lam*lam)/((1/15)*(lam*lam) + 13) + 11) + 9) + 7) + 5) + 3) + (a*a)*lam) if (lam < 1/2) else (-R*a + lam*((R*R) + (a*a)))) + F_0 + s_0*z_p


def _math_fit_sphere_force_dE(R, lam, a):
    """``fit_sphere_force_dE`` for Python floats (the math module); raises where it does."""
    return (((R*R)*lam**3/((lam*lam) + (lam*lam)/((lam*lam)/((lam*lam)/((lam*lam)/((lam*lam)/((1/15)*(lam*lam) + 13) + 11) + 9) + 7) + 5) + 3) + (a*a)*lam) if (lam < 1/2) else (-R*a + lam*((R*R) + (a*a))))


def _math_fit_sphere_force_dz0(E_star, a):
    """``fit_sphere_force_dz0`` for Python floats (the math module); raises where it does."""
    return -2*E_star*a


def _math_fit_sphere_radius_dlam(R, a):
    """``fit_sphere_radius_dlam`` for Python floats (the math module); raises where it does."""
    return (R - a)*(R + a)/R


def _math_flamant_sigma_xx(F_L, x, z):
    """``flamant_sigma_xx`` for Python floats (the math module); raises where it does."""
    return -2*F_L*(x*x)*z/(math.pi*(((x*x) + (z*z))*((x*x) + (z*z))))


def _math_flamant_sigma_zz(F_L, x, z):
    """``flamant_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -2*F_L*z**3/(math.pi*(((x*x) + (z*z))*((x*x) + (z*z))))


def _math_flamant_tau_xz(F_L, x, z):
    """``flamant_tau_xz`` for Python floats (the math module); raises where it does."""
    return -2*F_L*x*(z*z)/(math.pi*(((x*x) + (z*z))*((x*x) + (z*z))))


def _math_flat_punch_tangential_traction(r, a, G_star, u_x):
    """``flat_punch_tangential_traction`` for Python floats (the math module); raises where it does."""
    return G_star*u_x/(math.pi*math.sqrt((a*a) - (r*r)))


def _math_force_law_cone_exponent():
    """``force_law_cone_exponent`` for Python floats (the math module); raises where it does."""
    return 2


def _math_force_law_cone_prefactor(E_star, theta):
    """``force_law_cone_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star/(math.pi*math.tan(theta))


def _math_force_law_cone_stiffness_exponent():
    """``force_law_cone_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 1


def _math_force_law_cone_stiffness_prefactor(E_star, theta):
    """``force_law_cone_stiffness_prefactor`` for Python floats (the math module); raises where it does."""
    return 4*E_star/(math.pi*math.tan(theta))


def _math_force_law_ellipse_exponent():
    """``force_law_ellipse_exponent`` for Python floats (the math module); raises where it does."""
    return 3/2


def _math_force_law_ellipse_stiffness_exponent():
    """``force_law_ellipse_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 1/2


def _math_force_law_hertz_exponent():
    """``force_law_hertz_exponent`` for Python floats (the math module); raises where it does."""
    return 3/2


def _math_force_law_hertz_prefactor(E_star, R):
    """``force_law_hertz_prefactor`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*math.sqrt(R)


def _math_force_law_hertz_stiffness_exponent():
    """``force_law_hertz_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 1/2


def _math_force_law_hertz_stiffness_prefactor(E_star, R):
    """``force_law_hertz_stiffness_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(R)


def _math_force_law_line_exponent():
    """``force_law_line_exponent`` for Python floats (the math module); raises where it does."""
    return 1


def _math_force_law_line_prefactor(E_star):
    """``force_law_line_prefactor`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*E_star


def _math_force_law_line_stiffness_exponent():
    """``force_law_line_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 0


def _math_force_law_line_stiffness_prefactor(E_star):
    """``force_law_line_stiffness_prefactor`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*E_star


def _math_force_law_powerlaw_exponent(n):
    """``force_law_powerlaw_exponent`` for Python floats (the math module); raises where it does."""
    return (n + 1)/n


def _math_force_law_powerlaw_prefactor(E_star, c_n, kappa_n, n):
    """``force_law_powerlaw_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star*n*math.pow(1/(c_n*kappa_n), 1/n)/(n + 1)


def _math_force_law_powerlaw_stiffness_exponent(n):
    """``force_law_powerlaw_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 1/n


def _math_force_law_powerlaw_stiffness_prefactor(E_star, c_n, kappa_n, n):
    """``force_law_powerlaw_stiffness_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.pow(1/(c_n*kappa_n), 1/n)


def _math_force_law_punch_exponent():
    """``force_law_punch_exponent`` for Python floats (the math module); raises where it does."""
    return 1


def _math_force_law_punch_prefactor(E_star, a):
    """``force_law_punch_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a


def _math_force_law_punch_stiffness_exponent():
    """``force_law_punch_stiffness_exponent`` for Python floats (the math module); raises where it does."""
    return 0


def _math_force_law_punch_stiffness_prefactor(E_star, a):
    """``force_law_punch_stiffness_prefactor`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a


def _math_hertz_contact_radius(R, d):
    """``hertz_contact_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R)*math.sqrt(d)


def _math_hertz_contact_radius_from_force(E_star, F, R):
    """``hertz_contact_radius_from_force`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(6, 1/3)*math.pow(F, 1/3)*math.pow(R, 1/3)/math.pow(E_star, 1/3)


def _math_hertz_depth_from_force(E_star, F, R):
    """``hertz_depth_from_force`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pow(6, 2/3)*math.pow(F, 2/3)/(math.pow(E_star, 2/3)*math.pow(R, 1/3))


def _math_hertz_displacement_inside(R, d, r):
    """``hertz_displacement_inside`` for Python floats (the math module); raises where it does."""
    return d - 1/2*(r*r)/R


def _math_textbook_hertz_displacement_outside(R, d, r):
    """``textbook_hertz_displacement_outside`` for Python floats (the math module); raises where it does."""
    return (math.sqrt(R)*math.sqrt(d)*math.sqrt(-R*d + (r*r)) + 2*R*d*math.asin(math.sqrt(R)*math.sqrt(d)/r) - (r*r)*math.asin(math.sqrt(R)*math.sqrt(d)/r))/(math.pi*R)


def _math_hertz_displacement_outside_elementary(R, d, r):
    """``hertz_displacement_outside_elementary`` for Python floats (the math module); raises where it does."""
    return 2*d*(math.asin(math.sqrt(R)*math.sqrt(d)/r) - 1/2*(r*r)*(-math.sqrt(R)*math.sqrt(d)*math.sqrt(-R*d/(r*r) + 1)/r + math.asin(math.sqrt(R)*math.sqrt(d)/r))/(R*d))/math.pi


def _math_textbook_hertz_displacement_outside_elementary(R, d, r):
    """``textbook_hertz_displacement_outside_elementary`` for Python floats (the math module); raises where it does."""
    return 2*d*(-1/3*math.sqrt(R)*math.sqrt(d)*((r*r)*((3/2)*R*d/(r*r) - 3/2)/(R*d*math.sqrt(-R*d/(r*r) + 1)) + (3/2)*r**3*math.asin(math.sqrt(R)*math.sqrt(d)/r)/(math.pow(R, 3/2)*math.pow(d, 3/2)))/r + math.asin(math.sqrt(R)*math.sqrt(d)/r))/math.pi


def _math_hertz_displacement_outside_series(R, d, r):
    """``hertz_displacement_outside_series`` for Python floats (the math module); raises where it does."""
    return 2*math.sqrt(R)*math.pow(d, 3/2)*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*(R*d*((4485482287/35459249995776)*R*d/(r*r) + 34461632205/242304874971136)/(r*r) + 1472719325/9156870275072)/(r*r) + 756261275/4131758538752)/(r*r) + 116680311/556198264832)/(r*r) + 20036013/82678120448)/(r*r) + 3231615/11442061312)/(r*r) + 5014575/15082717184)/(r*r) + 1300075/3284140032)/(r*r) + 676039/1415577600)/(r*r) + 88179/150732800)/(r*r) + 46189/63307776)/(r*r) + 12155/13074432)/(r*r) + 6435/5292032)/(r*r) + 143/87040)/(r*r) + 77/33280)/(r*r) + 63/18304)/(r*r) + 35/6336)/(r*r) + 5/504)/(r*r) + 3/140)/(r*r) + 1/15)/(r*r) + 2/3)/(math.pi*r)


def _math_hertz_energy(E_star, R, d):
    """``hertz_energy`` for Python floats (the math module); raises where it does."""
    return (8/15)*E_star*math.sqrt(R)*math.pow(d, 5/2)


def _math_hertz_force(E_star, R, d):
    """``hertz_force`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*math.sqrt(R)*math.pow(d, 3/2)


def _math_hertz_max_pressure(E_star, R, d):
    """``hertz_max_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(d)/(math.pi*math.sqrt(R))


def _math_hertz_max_pressure_from_force(E_star, F, R):
    """``hertz_max_pressure_from_force`` for Python floats (the math module); raises where it does."""
    return math.pow(6, 1/3)*math.pow(E_star, 2/3)*math.pow(F, 1/3)/(math.pi*math.pow(R, 2/3))


def _math_hertz_mean_pressure(E_star, R, d):
    """``hertz_mean_pressure`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*math.sqrt(d)/(math.pi*math.sqrt(R))


def _math_hertz_pressure(E_star, R, d, r):
    """``hertz_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(d)*math.sqrt(max(0, 1 - (r*r)/(R*d)))/(math.pi*math.sqrt(R))


def _math_hertz_pressure_displacement(E_star, a, p0, r):
    """``hertz_pressure_displacement`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*p0*(2*(a*a) - (r*r))/(E_star*a)


def _math_hertz_pressure_displacement_outside(E_star, a, p0, r):
    """``hertz_pressure_displacement_outside`` for Python floats (the math module); raises where it does."""
    return (1/2)*p0*(2*(a*a)*math.asin(a/r) + a*math.sqrt(-(a*a) + (r*r)) - (r*r)*math.asin(a/r))/(E_star*a)


def _math_hertz_pressure_force(a, p0):
    """``hertz_pressure_force`` for Python floats (the math module); raises where it does."""
    return (2/3)*math.pi*(a*a)*p0


def _math_hertz_stiffness(E_star, R, d):
    """``hertz_stiffness`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.sqrt(R)*math.sqrt(d)


def _math_impact_contact_time(E_star, R, m, v0):
    """``impact_contact_time`` for Python floats (the math module); raises where it does."""
    return (1/5)*math.pow(30, 2/5)*math.sqrt(math.pi)*math.pow(m, 2/5)*math.gamma(2/5)/(math.pow(E_star, 2/5)*math.pow(R, 1/5)*math.pow(v0, 1/5)*math.gamma(9/10))


def _math_impact_contact_time_density(E_star, R, rho, v0):
    """``impact_contact_time_density`` for Python floats (the math module); raises where it does."""
    return (2/5)*math.pow(2, 1/5)*math.pow(5, 2/5)*math.pow(math.pi, 9/10)*R*math.pow(rho, 2/5)*math.gamma(2/5)/(math.pow(E_star, 2/5)*math.pow(v0, 1/5)*math.gamma(9/10))


def _math_impact_force_scale(E_star, R, m, v0):
    """``impact_force_scale`` for Python floats (the math module); raises where it does."""
    return math.pow(E_star, 2/5)*math.pow(R, 1/5)*math.pow(m, 3/5)*math.pow(v0, 6/5)


def _math_impact_length_scale(E_star, R, m, v0):
    """``impact_length_scale`` for Python floats (the math module); raises where it does."""
    return math.pow(m, 2/5)*math.pow(v0, 4/5)/(math.pow(E_star, 2/5)*math.pow(R, 1/5))


def _math_impact_max_contact_radius(E_star, R, m, v0):
    """``impact_max_contact_radius`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(30, 1/5)*math.pow(R, 2/5)*math.pow(m, 1/5)*math.pow(v0, 2/5)/math.pow(E_star, 1/5)


def _math_impact_max_contact_radius_density(E_star, R, rho, v0):
    """``impact_max_contact_radius_density`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(2, 3/5)*math.pow(5, 1/5)*math.pow(math.pi, 1/5)*R*math.pow(rho, 1/5)*math.pow(v0, 2/5)/math.pow(E_star, 1/5)


def _math_impact_max_depth(E_star, R, m, v0):
    """``impact_max_depth`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pow(30, 2/5)*math.pow(m, 2/5)*math.pow(v0, 4/5)/(math.pow(E_star, 2/5)*math.pow(R, 1/5))


def _math_impact_max_depth_density(E_star, R, rho, v0):
    """``impact_max_depth_density`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(2, 1/5)*math.pow(5, 2/5)*math.pow(math.pi, 2/5)*R*math.pow(rho, 2/5)*math.pow(v0, 4/5)/math.pow(E_star, 2/5)


def _math_impact_max_force(E_star, R, m, v0):
    """``impact_max_force`` for Python floats (the math module); raises where it does."""
    return (1/6)*math.pow(30, 3/5)*math.pow(E_star, 2/5)*math.pow(R, 1/5)*math.pow(m, 3/5)*math.pow(v0, 6/5)


def _math_impact_max_force_density(E_star, R, rho, v0):
    """``impact_max_force_density`` for Python floats (the math module); raises where it does."""
    return (1/3)*math.pow(2, 4/5)*math.pow(5, 3/5)*math.pow(math.pi, 3/5)*math.pow(E_star, 2/5)*(R*R)*math.pow(rho, 3/5)*math.pow(v0, 6/5)


def _math_impact_max_pressure(E_star, R, m, v0):
    """``impact_max_pressure`` for Python floats (the math module); raises where it does."""
    return math.pow(30, 1/5)*math.pow(E_star, 4/5)*math.pow(m, 1/5)*math.pow(v0, 2/5)/(math.pi*math.pow(R, 3/5))


def _math_impact_max_pressure_density(E_star, rho, v0):
    """``impact_max_pressure_density`` for Python floats (the math module); raises where it does."""
    return math.pow(2, 3/5)*math.pow(5, 1/5)*math.pow(E_star, 4/5)*math.pow(rho, 1/5)*math.pow(v0, 2/5)/math.pow(math.pi, 4/5)


def _math_impact_sphere_mass(R, rho):
    """``impact_sphere_mass`` for Python floats (the math module); raises where it does."""
    return (4/3)*math.pi*R**3*rho


def _math_impact_time_scale(E_star, R, m, v0):
    """``impact_time_scale`` for Python floats (the math module); raises where it does."""
    return math.pow(m, 2/5)/(math.pow(E_star, 2/5)*math.pow(R, 1/5)*math.pow(v0, 1/5))


def _math_jkr_contact_radius_from_force(E_star, F_load, R, dgamma):
    """``jkr_contact_radius_from_force`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(math.sqrt(3)*math.sqrt(R)*math.sqrt(2*F_load + 3*math.pi*R*dgamma) + 3*math.sqrt(math.pi)*R*math.sqrt(dgamma), 2/3)/math.pow(E_star, 1/3)


def _math_jkr_depth(E_star, R, a, dgamma):
    """``jkr_depth`` for Python floats (the math module); raises where it does."""
    return (a*a)/R - math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(a)*math.sqrt(dgamma)/math.sqrt(E_star)


def _math_jkr_force_from_radius(E_star, R, a, dgamma):
    """``jkr_force_from_radius`` for Python floats (the math module); raises where it does."""
    return -2*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(E_star)*math.pow(a, 3/2)*math.sqrt(dgamma) + (4/3)*E_star*a**3/R


def _math_jkr_pressure(E_star, R, a, dgamma, r):
    """``jkr_pressure`` for Python floats (the math module); raises where it does."""
    return -math.sqrt(2)*math.sqrt(E_star)*math.sqrt(a)*math.sqrt(dgamma)/(math.sqrt(math.pi)*math.sqrt(a - r)*math.sqrt(a + r)) + 2*E_star*math.sqrt(a - r)*math.sqrt(a + r)/(math.pi*R)


def _math_textbook_jkr_pressure(E_star, R, a, dgamma, r):
    """``textbook_jkr_pressure`` for Python floats (the math module); raises where it does."""
    return (-math.sqrt(2)*math.pi*math.sqrt(E_star)*R*math.sqrt(a)*math.sqrt(dgamma) + 2*math.sqrt(math.pi)*E_star*((a*a) - (r*r)))/(math.pow(math.pi, 3/2)*R*math.sqrt((a*a) - (r*r)))


def _math_jkr_pull_off_depth_dc(E_star, dgamma, R):
    """``jkr_pull_off_depth_dc`` for Python floats (the math module); raises where it does."""
    return -3/4*math.pow(math.pi, 2/3)*math.pow(R, 1/3)*math.pow(dgamma, 2/3)/math.pow(E_star, 2/3)


def _math_jkr_pull_off_depth_fc(E_star, dgamma, R):
    """``jkr_pull_off_depth_fc`` for Python floats (the math module); raises where it does."""
    return -1/4*math.pow(3, 1/3)*math.pow(math.pi, 2/3)*math.pow(R, 1/3)*math.pow(dgamma, 2/3)/math.pow(E_star, 2/3)


def _math_jkr_pull_off_force_dc(E_star, dgamma, R):
    """``jkr_pull_off_force_dc`` for Python floats (the math module); raises where it does."""
    return -5/6*math.pi*R*dgamma


def _math_jkr_pull_off_force_fc(E_star, dgamma, R):
    """``jkr_pull_off_force_fc`` for Python floats (the math module); raises where it does."""
    return -3/2*math.pi*R*dgamma


def _math_jkr_pull_off_radius_dc(E_star, dgamma, R):
    """``jkr_pull_off_radius_dc`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(math.pi, 1/3)*math.pow(R, 2/3)*math.pow(dgamma, 1/3)/math.pow(E_star, 1/3)


def _math_jkr_pull_off_radius_fc(E_star, dgamma, R):
    """``jkr_pull_off_radius_fc`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(3, 2/3)*math.pow(math.pi, 1/3)*math.pow(R, 2/3)*math.pow(dgamma, 1/3)/math.pow(E_star, 1/3)


def _math_jkr_zero_load_radius(E_star, dgamma, R):
    """``jkr_zero_load_radius`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.pow(6, 2/3)*math.pow(math.pi, 1/3)*math.pow(R, 2/3)*math.pow(dgamma, 1/3)/math.pow(E_star, 1/3)


def _math_line_depth_from_force(E_star, F, L):
    """``line_depth_from_force`` for Python floats (the math module); raises where it does."""
    return 4*F/(math.pi*E_star*L)


def _math_line_force(E_star, L, d):
    """``line_force`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*E_star*L*d


def _math_line_force_per_length_from_half_width(E_star, R, a):
    """``line_force_per_length_from_half_width`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*E_star*(a*a)/R


def _math_line_half_width(R, d):
    """``line_half_width`` for Python floats (the math module); raises where it does."""
    return math.sqrt(R)*math.sqrt(d)


def _math_line_half_width_from_force(E_star, F, L, R):
    """``line_half_width_from_force`` for Python floats (the math module); raises where it does."""
    return 2*math.sqrt(F)*math.sqrt(R)/(math.sqrt(math.pi)*math.sqrt(E_star)*math.sqrt(L))


def _math_line_max_pressure(E_star, R, d):
    """``line_max_pressure`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*math.sqrt(d)/math.sqrt(R)


def _math_line_max_pressure_depth_width(E_star, a, d):
    """``line_max_pressure_depth_width`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*d/a


def _math_line_max_pressure_from_force(E_star, F, L, R):
    """``line_max_pressure_from_force`` for Python floats (the math module); raises where it does."""
    return math.sqrt(E_star)*math.sqrt(F)/(math.sqrt(math.pi)*math.sqrt(L)*math.sqrt(R))


def _math_line_max_pressure_from_half_width(E_star, R, a):
    """``line_max_pressure_from_half_width`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*a/R


def _math_line_pressure(E_star, R, d, x):
    """``line_pressure`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*math.sqrt(d)*math.sqrt(max(0, 1 - (x*x)/(R*d)))/math.sqrt(R)


def _math_line_stiffness(E_star, L):
    """``line_stiffness`` for Python floats (the math module); raises where it does."""
    return (1/4)*math.pi*E_star*L


def _math_line_stress_axis_max_shear(a, p0, z):
    """``line_stress_axis_max_shear`` for Python floats (the math module); raises where it does."""
    return a*p0*z/(math.sqrt((a*a) + (z*z))*(z + math.sqrt((a*a) + (z*z))))


def _math_line_stress_axis_max_shear_slope(a, p0, z):
    """``line_stress_axis_max_shear_slope`` for Python floats (the math module); raises where it does."""
    return -a*p0*(z*z)/(math.pow((a*a) + (z*z), 3/2)*(z + math.sqrt((a*a) + (z*z)))) + a*p0*z*(-z/math.sqrt((a*a) + (z*z)) - 1)/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + a*p0/(math.sqrt((a*a) + (z*z))*(z + math.sqrt((a*a) + (z*z))))


def _math_line_stress_axis_sigma_xx(a, p0, z):
    """``line_stress_axis_sigma_xx`` for Python floats (the math module); raises where it does."""
    return -a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z)))))


def _math_textbook_line_stress_axis_sigma_xx(a, p0, z):
    """``textbook_line_stress_axis_sigma_xx`` for Python floats (the math module); raises where it does."""
    return p0*(2*(a*a)*z - (a*a)*math.sqrt((a*a) + (z*z)) + 2*z**3 - 2*(z*z)*math.sqrt((a*a) + (z*z)))/(a*((a*a) + (z*z)))


def _math_line_stress_axis_sigma_zz(a, p0, z):
    """``line_stress_axis_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -a*p0/math.sqrt((a*a) + (z*z))


def _math_line_stress_axis_von_mises(a, nu, p0, z):
    """``line_stress_axis_von_mises`` for Python floats (the math module); raises where it does."""
    return math.sqrt(3*(a*a)*(p0*p0)*(z*z)/(((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + ((1 - 2*nu)*(1 - 2*nu))*((-1/2*a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - 1/2*a*p0/math.sqrt((a*a) + (z*z)))*(-1/2*a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - 1/2*a*p0/math.sqrt((a*a) + (z*z)))))


def _math_textbook_line_stress_axis_von_mises(a, nu, p0, z):
    """``textbook_line_stress_axis_von_mises`` for Python floats (the math module); raises where it does."""
    return math.sqrt(a**6*(p0*p0)/(((a*a) + (z*z))*(z + math.sqrt((a*a) + (z*z)))**4) - a**4*(p0*p0)/(((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + a**3*nu*p0*(-a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - a*p0/math.sqrt((a*a) + (z*z)))/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + (a*a)*(p0*p0)/((a*a) + (z*z)) + a*nu*p0*(-a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - a*p0/math.sqrt((a*a) + (z*z)))/math.sqrt((a*a) + (z*z)) + (nu*nu)*((-a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - a*p0/math.sqrt((a*a) + (z*z)))*(-a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - a*p0/math.sqrt((a*a) + (z*z)))))


def _math_line_stress_axis_von_mises_slope(a, nu, p0, z):
    """``line_stress_axis_von_mises_slope`` for Python floats (the math module); raises where it does."""
    return (-3*(a*a)*(p0*p0)*z**3/((((a*a) + (z*z))*((a*a) + (z*z)))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + (3/2)*(a*a)*(p0*p0)*(z*z)*(-2*z/math.sqrt((a*a) + (z*z)) - 2)/(((a*a) + (z*z))*(z + math.sqrt((a*a) + (z*z)))**3) + 3*(a*a)*(p0*p0)*z/(((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + (1/2)*((1 - 2*nu)*(1 - 2*nu))*(-1/2*a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - 1/2*a*p0/math.sqrt((a*a) + (z*z)))*(a**3*p0*z/(math.pow((a*a) + (z*z), 3/2)*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - a**3*p0*(-2*z/math.sqrt((a*a) + (z*z)) - 2)/(math.sqrt((a*a) + (z*z))*(z + math.sqrt((a*a) + (z*z)))**3) + a*p0*z/math.pow((a*a) + (z*z), 3/2)))/math.sqrt(3*(a*a)*(p0*p0)*(z*z)/(((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) + ((1 - 2*nu)*(1 - 2*nu))*((-1/2*a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - 1/2*a*p0/math.sqrt((a*a) + (z*z)))*(-1/2*a**3*p0/(math.sqrt((a*a) + (z*z))*((z + math.sqrt((a*a) + (z*z)))*(z + math.sqrt((a*a) + (z*z))))) - 1/2*a*p0/math.sqrt((a*a) + (z*z)))))


def _math_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz):
    """``line_stress_principal_max`` for Python floats (the math module); raises where it does."""
    return (1/2)*sigma_xx + (1/2)*sigma_zz + math.sqrt((tau_xz*tau_xz) + (1/4)*((sigma_xx - sigma_zz)*(sigma_xx - sigma_zz)))


def _math_textbook_line_stress_principal_max(sigma_xx, sigma_zz, tau_xz):
    """``textbook_line_stress_principal_max`` for Python floats (the math module); raises where it does."""
    return (1/2)*sigma_xx + (1/2)*sigma_zz + (1/2)*math.sqrt((sigma_xx*sigma_xx) - 2*sigma_xx*sigma_zz + (sigma_zz*sigma_zz) + 4*(tau_xz*tau_xz))


def _math_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz):
    """``line_stress_principal_min`` for Python floats (the math module); raises where it does."""
    return (1/2)*sigma_xx + (1/2)*sigma_zz - math.sqrt((tau_xz*tau_xz) + (1/4)*((sigma_xx - sigma_zz)*(sigma_xx - sigma_zz)))


def _math_textbook_line_stress_principal_min(sigma_xx, sigma_zz, tau_xz):
    """``textbook_line_stress_principal_min`` for Python floats (the math module); raises where it does."""
    return (1/2)*sigma_xx + (1/2)*sigma_zz - 1/2*math.sqrt((sigma_xx*sigma_xx) - 2*sigma_xx*sigma_zz + (sigma_zz*sigma_zz) + 4*(tau_xz*tau_xz))


def _math_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz):
    """``line_stress_principal_shear`` for Python floats (the math module); raises where it does."""
    return math.sqrt((tau_xz*tau_xz) + (1/4)*((sigma_xx - sigma_zz)*(sigma_xx - sigma_zz)))


def _math_textbook_line_stress_principal_shear(sigma_xx, sigma_zz, tau_xz):
    """``textbook_line_stress_principal_shear`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt((sigma_xx*sigma_xx) - 2*sigma_xx*sigma_zz + (sigma_zz*sigma_zz) + 4*(tau_xz*tau_xz))


def _math_line_stress_sigma_xx_core(a, p0, x, z):
    """``line_stress_sigma_xx_core`` for Python floats (the math module); raises where it does."""
    return -p0*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (a - x)*(a + x))*(2*(x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + ((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (a - x)*(a + x))*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/(z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))))/(a*(z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_sigma_xx_deep(a, p0, x, z):
    """``line_stress_sigma_xx_deep`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*(z*z)*(2*(a*a)*(z*z)*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/((z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))) + 2*(x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))/((z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_sigma_xx_side(a, p0, x, z):
    """``line_stress_sigma_xx_side`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*(z*z)*(2*(a*a)*x*z**3/((x*z/math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + z)*math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))) - (z*z) - (a - x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/((x*z/math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + z)*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) - 1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_sigma_yy(nu, sigma_xx, sigma_zz):
    """``line_stress_sigma_yy`` for Python floats (the math module); raises where it does."""
    return nu*(sigma_xx + sigma_zz)


def _math_line_stress_sigma_zz_core(a, p0, x, z):
    """``line_stress_sigma_zz_core`` for Python floats (the math module); raises where it does."""
    return -p0*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (a - x)*(a + x))*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/(a*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_sigma_zz_deep(a, p0, x, z):
    """``line_stress_sigma_zz_deep`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*(z*z)*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/(((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_sigma_zz_side(a, p0, x, z):
    """``line_stress_sigma_zz_side`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*x*z**3/(math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) - 1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_1_core(a, p0, x, z):
    """``line_stress_tau_1_core`` for Python floats (the math module); raises where it does."""
    return p0*math.sqrt((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (z*z))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (a - x)*(a + x))/(a*(z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))*math.sqrt((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_1_deep(a, p0, x, z):
    """``line_stress_tau_1_deep`` for Python floats (the math module); raises where it does."""
    return 2*a*p0*(z*z)*math.sqrt((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (z*z))/((z + math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*math.sqrt((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_1_side(a, p0, x, z):
    """``line_stress_tau_1_side`` for Python floats (the math module); raises where it does."""
    return 2*a*p0*(z*z)*math.sqrt((1/2)*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/((x*z/math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + z)*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*math.sqrt((x*x)*(z*z)/(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) - 1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_xz_core(a, p0, x, z):
    """``line_stress_tau_xz_core`` for Python floats (the math module); raises where it does."""
    return -p0*x*z*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (a - x)*(a + x))/(a*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_xz_deep(a, p0, x, z):
    """``line_stress_tau_xz_deep`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*x*z**3/(math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_xz_side(a, p0, x, z):
    """``line_stress_tau_xz_side`` for Python floats (the math module); raises where it does."""
    return -2*a*p0*(z*z)*math.sqrt(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/(((z*z) + (-a + x)*(a + x) + math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/(-1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) - 1/2*(z*z) - 1/2*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))


def _math_line_stress_tau_xz_slope_x(a, p0, x, z):
    """``line_stress_tau_xz_slope_x`` for Python floats (the math module); raises where it does."""
    return -a*p0*z*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*(-3*(x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))**3


def _math_line_stress_tau_xz_slope_z(a, p0, x, z):
    """``line_stress_tau_xz_slope_z`` for Python floats (the math module); raises where it does."""
    return (math.pi*a*p0*x*(z*z)*(-(x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (3/2)*(z*z) + (3/2)*(a - x)*(a + x) + (3/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))/(math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))**3) - math.pi*p0*(-x*(z*z)/math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + x*math.sqrt((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))))/(a*((x*x)*(z*z)/((1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x))))) + (1/2)*(z*z) + (1/2)*(a - x)*(a + x) + (1/2)*math.sqrt(4*(x*x)*(z*z) + (((z*z) + (a - x)*(a + x))*((z*z) + (a - x)*(a + x)))))))/math.pi


def _math_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz):
    """``line_stress_von_mises`` for Python floats (the math module); raises where it does."""
    return math.sqrt(3*(tau_xz*tau_xz) + ((1 - 2*nu)*(1 - 2*nu))*(((1/2)*sigma_xx + (1/2)*sigma_zz)*((1/2)*sigma_xx + (1/2)*sigma_zz)) + (3/4)*((sigma_xx - sigma_zz)*(sigma_xx - sigma_zz)))


def _math_textbook_line_stress_von_mises(nu, sigma_xx, sigma_zz, tau_xz):
    """``textbook_line_stress_von_mises`` for Python floats (the math module); raises where it does."""
    return math.sqrt((nu*nu)*((sigma_xx + sigma_zz)*(sigma_xx + sigma_zz)) - nu*sigma_xx*(sigma_xx + sigma_zz) - nu*sigma_zz*(sigma_xx + sigma_zz) + (sigma_xx*sigma_xx) - sigma_xx*sigma_zz + (sigma_zz*sigma_zz) + 3*(tau_xz*tau_xz))


def _math_line_stress_von_mises_c_tau(nu, c_mean, tau_1):
    """``line_stress_von_mises_c_tau`` for Python floats (the math module); raises where it does."""
    return math.sqrt((c_mean*c_mean)*((1 - 2*nu)*(1 - 2*nu)) + 3*(tau_1*tau_1))


def _math_masing_unloading_force(F_amp, F_half):
    """``masing_unloading_force`` for Python floats (the math module); raises where it does."""
    return F_amp - 2*F_half


def _math_mdr_depth_of_line_load(E_star, g_x, q_z):
    """``mdr_depth_of_line_load`` for Python floats (the math module); raises where it does."""
    return g_x + q_z/E_star


def _math_mdr_force(E_star, a, d, g_integral):
    """``mdr_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*(a*d - g_integral)


def _math_mdr_kink_G(b, slope_jump, x):
    """``mdr_kink_G`` for Python floats (the math module); raises where it does."""
    return b*slope_jump*(2*x*math.asinh((1/2)*math.sqrt(2)*math.sqrt(-b + x)/math.sqrt(b)) - math.sqrt(-b + x)*math.sqrt(b + x))


def _math_textbook_mdr_kink_G(b, slope_jump, x):
    """``textbook_mdr_kink_G`` for Python floats (the math module); raises where it does."""
    return 2*b*slope_jump*x*math.acosh((1/2)*math.sqrt(2)*math.sqrt(b + x)/math.sqrt(b)) - b*slope_jump*math.sqrt(-b + x)*math.sqrt(b + x)


def _math_mdr_kink_g(b, slope_jump, x):
    """``mdr_kink_g`` for Python floats (the math module); raises where it does."""
    return 2*b*slope_jump*math.asinh((1/2)*math.sqrt(2)*math.sqrt(-b + x)/math.sqrt(b))


def _math_textbook_mdr_kink_g(b, slope_jump, x):
    """``textbook_mdr_kink_g`` for Python floats (the math module); raises where it does."""
    return 2*b*slope_jump*math.acosh((1/2)*math.sqrt(2)*math.sqrt(b + x)/math.sqrt(b))


def _math_mdr_kink_gprime(b, slope_jump, x):
    """``mdr_kink_gprime`` for Python floats (the math module); raises where it does."""
    return b*slope_jump/(math.sqrt(-b + x)*math.sqrt(b + x))


def _math_mdr_normal_line_load(E_star, d, g_x):
    """``mdr_normal_line_load`` for Python floats (the math module); raises where it does."""
    return E_star*(d - g_x)


def _math_mdr_stiffness(E_star, a):
    """``mdr_stiffness`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a


def _math_mdr_tangential_line_load(G_star, w_x):
    """``mdr_tangential_line_load`` for Python floats (the math module); raises where it does."""
    return G_star*w_x


def _math_mdr_tangential_spring_shear(G_star, q_x):
    """``mdr_tangential_spring_shear`` for Python floats (the math module); raises where it does."""
    return q_x/G_star


def _math_mindlin_energy(a, F, G_star, mu_f, F_amp):
    """``mindlin_energy`` for Python floats (the math module); raises where it does."""
    return -1/5*(3*(F*F)*(mu_f*mu_f)*math.exp((2/3)*math.log1p(-F_amp/(F*mu_f))) + 9*(F*F)*(mu_f*mu_f)*math.exp((1/3)*math.log1p(-F_amp/(F*mu_f))) + 3*(F*F)*(mu_f*mu_f))*math.expm1((1/3)*math.log1p(-F_amp/(F*mu_f)))**3/(G_star*a)


def _math_textbook_mindlin_energy(a, F, G_star, mu_f, F_amp):
    """``textbook_mindlin_energy`` for Python floats (the math module); raises where it does."""
    return (3/5)*(-6*math.pow(F, 4/3)*math.pow(mu_f, 4/3)*math.pow(F*mu_f - F_amp, 2/3) + math.pow(F, 1/3)*F_amp*math.pow(mu_f, 1/3)*math.pow(F*mu_f - F_amp, 2/3) + 6*(F*F)*(mu_f*mu_f) - 5*F*F_amp*mu_f)/(G_star*a)


def _math_mindlin_energy_small(a, F, G_star, mu_f, F_amp):
    """``mindlin_energy_small`` for Python floats (the math module); raises where it does."""
    return (1/9)*F_amp**3/(F*G_star*a*mu_f)


def _math_paraboloid_g(R, x):
    """``paraboloid_g`` for Python floats (the math module); raises where it does."""
    return (x*x)/R


def _math_paraboloid_profile(R, r):
    """``paraboloid_profile`` for Python floats (the math module); raises where it does."""
    return (1/2)*(r*r)/R


def _math_powerlaw_contact_radius(c_n, d, kappa_n, n):
    """``powerlaw_contact_radius`` for Python floats (the math module); raises where it does."""
    return math.pow(d/(c_n*kappa_n), 1/n)


def _math_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """``powerlaw_depth_from_force`` for Python floats (the math module); raises where it does."""
    return math.pow(c_n*kappa_n, 1/(n + 1))*math.pow((1/2)*F*(n + 1)/(E_star*n), n/(n + 1))


def _math_textbook_powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """``textbook_powerlaw_depth_from_force`` for Python floats (the math module); raises where it does."""
    return math.pow((1/2)*F*math.pow(c_n*kappa_n, 1/n)*(n + 1)/(E_star*n), n/(n + 1))


def _math_powerlaw_displacement_far(a, d, n, r):
    """``powerlaw_displacement_far`` for Python floats (the math module); raises where it does."""
    return 2*a*d*n*((a*a)*((a*a)*((a*a)*(5*n + 5)/((r*r)*(112*n + 784)) + (3*n + 3)/(40*n + 200))/(r*r) + (n + 1)/(6*n + 18))/(r*r) + 1)/(math.pi*r*(n + 1))


def _math_powerlaw_displacement_outside_integrand(a, d, n, r, w_out):
    """``powerlaw_displacement_outside_integrand`` for Python floats (the math module); raises where it does."""
    return -2*d*math.expm1(n*math.log1p(-2*(math.sin((1/2)*w_out)*math.sin((1/2)*w_out)) - math.sqrt(-a + r)*math.sqrt(a + r)*math.sin(w_out)/a))/math.pi


def _math_textbook_powerlaw_displacement_outside_integrand(a, d, n, r, w_out):
    """``textbook_powerlaw_displacement_outside_integrand`` for Python floats (the math module); raises where it does."""
    return (-2*d*math.pow(-r*math.sin(w_out - math.asin(a/r))/a, n) + 2*d)/math.pi


def _math_powerlaw_force(E_star, c_n, d, kappa_n, n):
    """``powerlaw_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d*n*math.pow(d/(c_n*kappa_n), 1/n)/(n + 1)


def _math_powerlaw_force_from_radius(E_star, a, d, n):
    """``powerlaw_force_from_radius`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a*d*n/(n + 1)


def _math_powerlaw_g(c_n, kappa_n, n, x):
    """``powerlaw_g`` for Python floats (the math module); raises where it does."""
    return c_n*kappa_n*math.pow(x, n)


def _math_powerlaw_kappa(n):
    """``powerlaw_kappa`` for Python floats (the math module); raises where it does."""
    return math.sqrt(math.pi)*math.gamma((1/2)*n + 1)/math.gamma((1/2)*n + 1/2)


def _math_powerlaw_kappa_asymptotic(n):
    """``powerlaw_kappa_asymptotic`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(2)*math.sqrt(math.pi)*math.sqrt(n)*math.exp(2*math.pow(n, -1.0)*(4*math.pow(n, -2.0)*(4*math.pow(n, -2.0)*(4*math.pow(n, -2.0)*((31/4608)*math.pow(n, -2.0) - 17/14336) + 1/640) - 1/192) + 1/8))


def _math_powerlaw_mean_pressure(E_star, a, d, n):
    """``powerlaw_mean_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d*n/(math.pi*a*(n + 1))


def _math_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n):
    """``powerlaw_mean_pressure_from_depth`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d*n*math.pow(c_n*kappa_n/d, 1/n)/(math.pi*(n + 1))


def _math_textbook_powerlaw_mean_pressure_from_depth(E_star, c_n, d, kappa_n, n):
    """``textbook_powerlaw_mean_pressure_from_depth`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d*n*math.pow(c_n*kappa_n/d, 1/n)/(math.pi*(n + 1))


def _math_powerlaw_pressure_centre(E_star, a, d, n, r):
    """``powerlaw_pressure_centre`` for Python floats (the math module); raises where it does."""
    return E_star*d*n*((1/2)*math.sqrt(math.pi)*math.pow(r/a, n - 1)*math.gamma(1/2 - 1/2*n)/math.gamma(1 - 1/2*n) + 1/(n - 1) + (r*r)*(1/(2*n - 6) + (r*r)*(3/(8*n - 40) + (r*r)*(5/(16*n - 112) + (r*r)*(35/(128*n - 1152) + (r*r)*(63/(256*n - 2816) + (r*r)*(231/(1024*n - 13312) + (r*r)*(429/(2048*n - 30720) + (r*r)*(6435/(32768*n - 557056) + 12155*(r*r)/((a*a)*(65536*n - 1245184)))/(a*a))/(a*a))/(a*a))/(a*a))/(a*a))/(a*a))/(a*a))/(a*a))/(math.pi*a)


def _math_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad):
    """``powerlaw_pressure_integrand`` for Python floats (the math module); raises where it does."""
    return E_star*d*n*math.sqrt(a - r)*math.sqrt(a + r)*math.exp(((1/2)*n - 1)*math.log1p(-w_quad*(2 - w_quad)*(a - r)*(a + r)/(a*a)))/(math.pi*(a*a))


def _math_textbook_powerlaw_pressure_integrand(E_star, a, d, n, r, w_quad):
    """``textbook_powerlaw_pressure_integrand`` for Python floats (the math module); raises where it does."""
    return E_star*math.pow(a, -n)*d*n*math.sqrt((a*a) - (r*r))*math.pow((r*r) + ((1 - w_quad)*(1 - w_quad))*((a*a) - (r*r)), (1/2)*n - 1)/math.pi


def _math_powerlaw_pressure_n1(E_star, a, d, r):
    """``powerlaw_pressure_n1`` for Python floats (the math module); raises where it does."""
    return E_star*d*math.log((a + math.sqrt((a*a) - (r*r)))/r)/(math.pi*a)


def _math_powerlaw_pressure_n2(E_star, a, d, r):
    """``powerlaw_pressure_n2`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d*math.sqrt((a*a) - (r*r))/(math.pi*(a*a))


def _math_powerlaw_pressure_n3(E_star, a, d, r):
    """``powerlaw_pressure_n3`` for Python floats (the math module); raises where it does."""
    return (3/2)*E_star*d*(a*math.sqrt((a*a) - (r*r)) - (r*r)*math.log(r) + (r*r)*math.log(a + math.sqrt((a*a) - (r*r))))/(math.pi*a**3)


def _math_powerlaw_pressure_n4(E_star, a, d, r):
    """``powerlaw_pressure_n4`` for Python floats (the math module); raises where it does."""
    return (4/3)*E_star*d*math.sqrt((a*a) - (r*r))*((a*a) + 2*(r*r))/(math.pi*a**4)


def _math_powerlaw_profile(c_n, n, r):
    """``powerlaw_profile`` for Python floats (the math module); raises where it does."""
    return c_n*math.pow(r, n)


def _math_powerlaw_punch_displacement_outside(a, d, r):
    """``powerlaw_punch_displacement_outside`` for Python floats (the math module); raises where it does."""
    return 2*d*math.asin(a/r)/math.pi


def _math_powerlaw_punch_force(E_star, a, d):
    """``powerlaw_punch_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a*d


def _math_powerlaw_punch_mean_pressure(E_star, a, d):
    """``powerlaw_punch_mean_pressure`` for Python floats (the math module); raises where it does."""
    return 2*E_star*d/(math.pi*a)


def _math_powerlaw_punch_pressure(E_star, a, d, r):
    """``powerlaw_punch_pressure`` for Python floats (the math module); raises where it does."""
    return E_star*d/(math.pi*math.sqrt((a*a) - (r*r)))


def _math_punch_depth_from_force(E_star, F, a):
    """``punch_depth_from_force`` for Python floats (the math module); raises where it does."""
    return (1/2)*F/(E_star*a)


def _math_punch_pressure_displacement(E_star, a, p0):
    """``punch_pressure_displacement`` for Python floats (the math module); raises where it does."""
    return math.pi*a*p0/E_star


def _math_punch_pressure_displacement_outside(E_star, a, p0, r):
    """``punch_pressure_displacement_outside`` for Python floats (the math module); raises where it does."""
    return 2*a*p0*math.asin(a/r)/E_star


def _math_punch_pressure_force(a, p0):
    """``punch_pressure_force`` for Python floats (the math module); raises where it does."""
    return 2*math.pi*(a*a)*p0


def _math_punch_stiffness(E_star, a):
    """``punch_stiffness`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a


def _math_shear_modulus(E, nu):
    """``shear_modulus`` for Python floats (the math module); raises where it does."""
    return E/(2*nu + 2)


def _math_sphere_depth(R, a):
    """``sphere_depth`` for Python floats (the math module); raises where it does."""
    return (1/2)*a*math.log1p(2*a/(R - a))


def _math_textbook_sphere_depth(R, a):
    """``textbook_sphere_depth`` for Python floats (the math module); raises where it does."""
    return a*math.atanh(a/R)


def _math_textbook_sphere_force_from_radius(E_star, R, a):
    """``textbook_sphere_force_from_radius`` for Python floats (the math module); raises where it does."""
    return E_star*((R*R)*math.atanh(a/R) - R*a + (a*a)*math.atanh(a/R))


def _math_sphere_g(R, x):
    """``sphere_g`` for Python floats (the math module); raises where it does."""
    return (1/2)*x*math.log1p(2*x/(R - x))


def _math_textbook_sphere_g(R, x):
    """``textbook_sphere_g`` for Python floats (the math module); raises where it does."""
    return x*math.atanh(x/R)


def _math_sphere_lam_contact_radius(R, lam):
    """``sphere_lam_contact_radius`` for Python floats (the math module); raises where it does."""
    return R*math.tanh(lam)


def _math_sphere_lam_depth(R, lam):
    """``sphere_lam_depth`` for Python floats (the math module); raises where it does."""
    return R*lam*math.tanh(lam)


def _math_textbook_sphere_lam_force(E_star, R, lam):
    """``textbook_sphere_lam_force`` for Python floats (the math module); raises where it does."""
    return E_star*(R*R)*(lam*(math.tanh(lam)*math.tanh(lam)) + lam - math.tanh(lam))


def _math_sphere_lam_pressure_pole(E_star, R, lam, r):
    """``sphere_lam_pressure_pole`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*R*math.log1p(2*math.sqrt(R*math.tanh(lam) - r)*math.sqrt(R*math.tanh(lam) + r)*(math.sqrt(R - r)*math.sqrt(R + r) + math.sqrt(R*math.tanh(lam) - r)*math.sqrt(R*math.tanh(lam) + r))*(math.cosh(lam)*math.cosh(lam))/(R*R))/(math.pi*math.sqrt(R - r)*math.sqrt(R + r))


def _math_textbook_sphere_lam_pressure_pole(E_star, R, lam, r):
    """``textbook_sphere_lam_pressure_pole`` for Python floats (the math module); raises where it does."""
    return E_star*R*math.atanh(math.sqrt((R*R)*(math.tanh(lam)*math.tanh(lam)) - (r*r))/math.sqrt((R*R) - (r*r)))/(math.pi*math.sqrt((R*R) - (r*r)))


def _math_sphere_pressure_atanh_kernel(E_star, R, x):
    """``sphere_pressure_atanh_kernel`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*math.log1p(2*x/(R - x))/(math.pi*x)


def _math_textbook_sphere_pressure_atanh_kernel(E_star, R, x):
    """``textbook_sphere_pressure_atanh_kernel`` for Python floats (the math module); raises where it does."""
    return E_star*math.atanh(x/R)/(math.pi*x)


def _math_sphere_profile(R, r):
    """``sphere_profile`` for Python floats (the math module); raises where it does."""
    return (r*r)/(R + math.sqrt(R - r)*math.sqrt(R + r))


def _math_textbook_sphere_profile(R, r):
    """``textbook_sphere_profile`` for Python floats (the math module); raises where it does."""
    return R - math.sqrt((R*R) - (r*r))


def _math_sphere_stiffness(E_star, a):
    """``sphere_stiffness`` for Python floats (the math module); raises where it does."""
    return 2*E_star*a


def _math_stress_axis_max_shear(a, nu, p0, z):
    """``stress_axis_max_shear`` for Python floats (the math module); raises where it does."""
    return (1/4)*p0*(3*a**3 - 2*a*((a*a) + (z*z))*(nu + 1) + 2*z*((a*a) + (z*z))*(nu + 1)*math.atan(a/z))/(a*((a*a) + (z*z)))


def _math_stress_axis_max_shear_bracket(a, nu):
    """``stress_axis_max_shear_bracket`` for Python floats (the math module); raises where it does."""
    return math.pi*a*(nu + 1)/(8*nu + 20)


def _math_stress_axis_max_shear_slope(a, nu, p0, z):
    """``stress_axis_max_shear_slope`` for Python floats (the math module); raises where it does."""
    return -1/2*p0*z*(3*a**3 - 2*a*((a*a) + (z*z))*(nu + 1) + 2*z*((a*a) + (z*z))*(nu + 1)*math.atan(a/z))/(a*(((a*a) + (z*z))*((a*a) + (z*z)))) + (1/4)*p0*(-4*a*z*(nu + 1) - 2*a*((a*a) + (z*z))*(nu + 1)/(z*((a*a)/(z*z) + 1)) + 4*(z*z)*(nu + 1)*math.atan(a/z) + 2*((a*a) + (z*z))*(nu + 1)*math.atan(a/z))/(a*((a*a) + (z*z)))


def _math_stress_axis_sigma_xx(a, nu, p0, z):
    """``stress_axis_sigma_xx`` for Python floats (the math module); raises where it does."""
    return (1/2)*p0*(a**3 - 2*a*((a*a) + (z*z))*(nu + 1) + 2*z*((a*a) + (z*z))*(nu + 1)*math.atan(a/z))/(a*((a*a) + (z*z)))


def _math_textbook_stress_axis_sigma_xx_deep(a, nu, p0, z):
    """``textbook_stress_axis_sigma_xx_deep`` for Python floats (the math module); raises where it does."""
    return (1/2)*p0*(a**3 - 2*a*((a*a) + (z*z))*(nu + 1) + 2*z*((a*a) + (z*z))*(nu + 1)*math.atan(a/z))/(a*((a*a) + (z*z)))


def _math_stress_axis_sigma_zz(a, p0, z):
    """``stress_axis_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -(a*a)*p0/((a*a) + (z*z))


def _math_textbook_stress_axis_sigma_zz(a, p0, z):
    """``textbook_stress_axis_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -(a*a)*p0/((a*a) + (z*z))


def _math_stress_hertz_max_orthogonal_shear(p0):
    """``stress_hertz_max_orthogonal_shear`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(2)*p0*math.pow(5 - math.sqrt(17), 3/2)/math.sqrt(-5 + 3*math.sqrt(17))


def _math_textbook_stress_hertz_max_orthogonal_shear(p0):
    """``textbook_stress_hertz_max_orthogonal_shear`` for Python floats (the math module); raises where it does."""
    return (1/32)*p0*math.sqrt(1 + math.sqrt(17))*(-7*math.sqrt(34) + 31*math.sqrt(2))


def _math_stress_hertz_max_orthogonal_shear_r(a):
    """``stress_hertz_max_orthogonal_shear_r`` for Python floats (the math module); raises where it does."""
    return a*math.sqrt(7/4 - 1/4*math.sqrt(17))


def _math_stress_hertz_max_orthogonal_shear_z(a):
    """``stress_hertz_max_orthogonal_shear_z`` for Python floats (the math module); raises where it does."""
    return a/math.sqrt(4 + math.sqrt(17))


def _math_textbook_stress_hertz_max_orthogonal_shear_z(a):
    """``textbook_stress_hertz_max_orthogonal_shear_z`` for Python floats (the math module); raises where it does."""
    return a*math.sqrt(-4 + math.sqrt(17))


def _math_stress_hertz_sigma_rr(nu, p0, xi, eta, chi):
    """``stress_hertz_sigma_rr`` for Python floats (the math module); raises where it does."""
    return p0*(-(chi*chi)*eta*(xi*xi)/(((eta*eta) + (xi*xi))*((xi*xi) + 1)) - eta*(nu + 1)*(-xi*(-math.atan(xi) + (1/2)*math.pi) + 1 - (1/3)/((xi*xi) + 1)) + (1 - 2*nu)/((3*eta + 3)*((xi*xi) + 1)))


def _math_textbook_stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi):
    """``textbook_stress_hertz_sigma_rr_far`` for Python floats (the math module); raises where it does."""
    return p0*(-(chi*chi)*eta*(xi*xi)/(((eta*eta) + (xi*xi))*((xi*xi) + 1)) - eta*(nu + 1)*(-xi*math.atan(1/xi) + 1 - (1/3)/((xi*xi) + 1)) + (1 - 2*nu)/((3*eta + 3)*((xi*xi) + 1)))


def _math_stress_hertz_sigma_tt(nu, p0, xi, eta):
    """``stress_hertz_sigma_tt`` for Python floats (the math module); raises where it does."""
    return p0*(-eta*(nu + 1)*(-xi*(-math.atan(xi) + (1/2)*math.pi) + 1 - (1/3)/((xi*xi) + 1)) + (1 - 2*nu)*((eta*eta) + eta - 1)/((3*eta + 3)*((xi*xi) + 1)))


def _math_textbook_stress_hertz_sigma_tt_far(nu, p0, xi, eta):
    """``textbook_stress_hertz_sigma_tt_far`` for Python floats (the math module); raises where it does."""
    return p0*(-eta*(nu + 1)*(-xi*math.atan(1/xi) + 1 - (1/3)/((xi*xi) + 1)) + (1 - 2*nu)*((eta*eta) + eta - 1)/((3*eta + 3)*((xi*xi) + 1)))


def _math_stress_hertz_sigma_zz(p0, xi, eta):
    """``stress_hertz_sigma_zz`` for Python floats (the math module); raises where it does."""
    return -eta**3*p0/((eta*eta) + (xi*xi))


def _math_stress_hertz_tau_rz(p0, xi, eta, chi):
    """``stress_hertz_tau_rz`` for Python floats (the math module); raises where it does."""
    return -chi*(eta*eta)*p0*xi/(((eta*eta) + (xi*xi))*math.sqrt((xi*xi) + 1))


def _math_stress_spheroidal_cos_beta_inside(a, r, z):
    """``stress_spheroidal_cos_beta_inside`` for Python floats (the math module); raises where it does."""
    return math.sqrt(-1/2*(z*z) - 1/2*(-a + r)*(a + r) + (1/2)*math.sqrt(4*(a*a)*(z*z) + (((z*z) + (-a + r)*(a + r))*((z*z) + (-a + r)*(a + r)))))/a


def _math_stress_spheroidal_u(a, r, z):
    """``stress_spheroidal_u`` for Python floats (the math module); raises where it does."""
    return (1/2)*(z*z) + (1/2)*(-a + r)*(a + r) + (1/2)*math.sqrt(4*(a*a)*(z*z) + (((z*z) + (-a + r)*(a + r))*((z*z) + (-a + r)*(a + r))))


def _math_textbook_stress_spheroidal_u(a, r, z):
    """``textbook_stress_spheroidal_u`` for Python floats (the math module); raises where it does."""
    return -1/2*(a*a) + (1/2)*(r*r) + (1/2)*(z*z) + (1/2)*math.sqrt(a**4 - 2*(a*a)*(r*r) + 2*(a*a)*(z*z) + r**4 + 2*(r*r)*(z*z) + z**4)


def _math_stress_spheroidal_u_inside(a, r, z):
    """``stress_spheroidal_u_inside`` for Python floats (the math module); raises where it does."""
    return 2*(a*a)*(z*z)/(-(z*z) - (-a + r)*(a + r) + math.sqrt(4*(a*a)*(z*z) + (((z*z) + (-a + r)*(a + r))*((z*z) + (-a + r)*(a + r)))))


def _math_textbook_stress_spheroidal_u_inside(a, r, z):
    """``textbook_stress_spheroidal_u_inside`` for Python floats (the math module); raises where it does."""
    return -1/2*(a*a) + (1/2)*(r*r) + (1/2)*(z*z) + (1/2)*math.sqrt(a**4 - 2*(a*a)*(r*r) + 2*(a*a)*(z*z) + r**4 + 2*(r*r)*(z*z) + z**4)


def _math_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """``stress_von_mises`` for Python floats (the math module); raises where it does."""
    return (1/2)*math.sqrt(2)*math.sqrt(6*(tau_xy*tau_xy) + 6*(tau_xz*tau_xz) + 6*(tau_yz*tau_yz) + ((sigma_xx - sigma_yy)*(sigma_xx - sigma_yy)) + ((sigma_xx - sigma_zz)*(sigma_xx - sigma_zz)) + ((-sigma_yy + sigma_zz)*(-sigma_yy + sigma_zz)))


def _math_textbook_stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """``textbook_stress_von_mises`` for Python floats (the math module); raises where it does."""
    return math.sqrt((sigma_xx*sigma_xx) - sigma_xx*sigma_yy - sigma_xx*sigma_zz + (sigma_yy*sigma_yy) - sigma_yy*sigma_zz + (sigma_zz*sigma_zz) + 3*(tau_xy*tau_xy) + 3*(tau_xz*tau_xz) + 3*(tau_yz*tau_yz))


def _math_strip_mean_pressure(F, L, a):
    """``strip_mean_pressure`` for Python floats (the math module); raises where it does."""
    return (1/2)*F/(L*a)


def _math_tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """``tangential_cone_displacement`` for Python floats (the math module); raises where it does."""
    return F_x/(G_star*a*(math.sqrt(1 - F_x/(F*mu_f)) + 1))


def _math_textbook_tangential_cone_displacement(a, F, G_star, mu_f, F_x):
    """``textbook_tangential_cone_displacement`` for Python floats (the math module); raises where it does."""
    return (-math.sqrt(F)*math.sqrt(mu_f)*math.sqrt(F*mu_f - F_x) + F*mu_f)/(G_star*a)


def _math_tangential_cone_energy(a, F, G_star, mu_f, F_amp):
    """``tangential_cone_energy`` for Python floats (the math module); raises where it does."""
    return (4/3)*F_amp**3/(F*G_star*a*mu_f*(math.sqrt(1 - F_amp/(F*mu_f)) + 1)**3)


def _math_textbook_tangential_cone_energy(a, F, G_star, mu_f, F_amp):
    """``textbook_tangential_cone_energy`` for Python floats (the math module); raises where it does."""
    return (4/3)*math.sqrt(F)*math.sqrt(mu_f)*(math.sqrt(F)*math.sqrt(mu_f) - math.sqrt(F*mu_f - F_amp))**3/(G_star*a)


def _math_tangential_cone_force(a, theta, E_star, G_star, mu_f, u_x):
    """``tangential_cone_force`` for Python floats (the math module); raises where it does."""
    return 2*G_star*u_x*(math.pi*E_star*a*mu_f - G_star*u_x/math.tan(theta))/(math.pi*E_star*mu_f)


def _math_tangential_cone_stick_radius(a, theta, E_star, G_star, mu_f, u_x):
    """``tangential_cone_stick_radius`` for Python floats (the math module); raises where it does."""
    return a - 2*G_star*u_x/(math.pi*E_star*mu_f*math.tan(theta))


def _math_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f):
    """``tangential_cone_traction_stick`` for Python floats (the math module); raises where it does."""
    return (1/2)*E_star*mu_f*math.tan(theta)*math.log1p((a - c)*((a + c)/(math.sqrt(a - r)*math.sqrt(a + r) + math.sqrt(c - r)*math.sqrt(c + r)) + 1)/(c + math.sqrt(c - r)*math.sqrt(c + r)))


def _math_textbook_tangential_cone_traction_stick(r, a, c, theta, E_star, mu_f):
    """``textbook_tangential_cone_traction_stick`` for Python floats (the math module); raises where it does."""
    return mu_f*((1/2)*E_star*math.log((a + math.sqrt((a*a) - (r*r)))/r)*math.tan(theta) - 1/2*E_star*math.log((c + math.sqrt((c*c) - (r*r)))/r)*math.tan(theta))


def _math_tangential_modulus(G1, nu1, G2, nu2):
    """``tangential_modulus`` for Python floats (the math module); raises where it does."""
    return 1/((1/4)*(2 - nu2)/G2 + (1/4)*(2 - nu1)/G1)


def _math_textbook_tangential_modulus(G1, nu1, G2, nu2):
    """``textbook_tangential_modulus`` for Python floats (the math module); raises where it does."""
    return -4*G1*G2/(G1*(nu2 - 2) + G2*(nu1 - 2))


def _math_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """``tangential_powerlaw_displacement`` for Python floats (the math module); raises where it does."""
    return -1/2*F*mu_f*(n + 1)*math.expm1(n*math.log1p(-F_x/(F*mu_f))/(n + 1))/(G_star*a*n)


def _math_textbook_tangential_powerlaw_displacement(a, n, F, G_star, mu_f, F_x):
    """``textbook_tangential_powerlaw_displacement`` for Python floats (the math module); raises where it does."""
    return (1/2)*F*mu_f*(1 - math.pow(1 - F_x/(F*mu_f), n/(n + 1)))*(n + 1)/(G_star*a*n)


def _math_tangential_powerlaw_energy(a, n, F, G_star, mu_f, c_a):
    """``tangential_powerlaw_energy`` for Python floats (the math module); raises where it does."""
    return 2*(F*F)*(mu_f*mu_f)*(-2*math.pow(c_a, n)*(n*n) - 3*math.pow(c_a, n)*n - math.pow(c_a, n) + 2*math.pow(c_a, n + 1)*(n*n) + 3*math.pow(c_a, n + 1)*n + math.pow(c_a, n + 1) - math.pow(c_a, 2*n + 1)*n - math.pow(c_a, 2*n + 1) + n + 1)/(G_star*a*n*(2*n + 1))


def _math_tangential_powerlaw_energy_density(n, d_c, s_x):
    """``tangential_powerlaw_energy_density`` for Python floats (the math module); raises where it does."""
    return -math.pow(1 - d_c, n)*math.expm1(n*math.log1p(-d_c*(1 - s_x)))*math.expm1(n*math.log1p(d_c*s_x/(1 - d_c)))


def _math_tangential_powerlaw_energy_scale(a, n, F, G_star, mu_f):
    """``tangential_powerlaw_energy_scale`` for Python floats (the math module); raises where it does."""
    return 2*(F*F)*(mu_f*mu_f)*((n + 1)*(n + 1))/(G_star*a*(n*n))


def _math_tangential_powerlaw_energy_small(a, n, F, G_star, mu_f, F_amp):
    """``tangential_powerlaw_energy_small`` for Python floats (the math module); raises where it does."""
    return (1/3)*F_amp**3/(F*G_star*a*mu_f*(n + 1))


def _math_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """``tangential_powerlaw_force`` for Python floats (the math module); raises where it does."""
    return -2*E_star*math.pow(a, n + 1)*c_n*kappa_n*mu_f*n*math.expm1((n + 1)*math.log1p(-G_star*math.pow(a, -n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)/(n + 1)


def _math_textbook_tangential_powerlaw_force(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """``textbook_tangential_powerlaw_force`` for Python floats (the math module); raises where it does."""
    return 2*E_star*math.pow(a, n + 1)*c_n*kappa_n*mu_f*n*(1 - math.pow(1 - G_star*math.pow(a, -n)*u_x/(E_star*c_n*kappa_n*mu_f), (n + 1)/n))/(n + 1)


def _math_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """``tangential_powerlaw_stick_deficit`` for Python floats (the math module); raises where it does."""
    return -math.expm1(math.log1p(-F_amp/(F*mu_f))/(n + 1))


def _math_textbook_tangential_powerlaw_stick_deficit(n, F, mu_f, F_amp):
    """``textbook_tangential_powerlaw_stick_deficit`` for Python floats (the math module); raises where it does."""
    return 1 - math.pow(1 - F_amp/(F*mu_f), 1/(n + 1))


def _math_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """``tangential_powerlaw_stick_radius`` for Python floats (the math module); raises where it does."""
    return a*math.exp(math.log1p(-G_star*math.pow(a, -n)*u_x/(E_star*c_n*kappa_n*mu_f))/n)


def _math_textbook_tangential_powerlaw_stick_radius(a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x):
    """``textbook_tangential_powerlaw_stick_radius`` for Python floats (the math module); raises where it does."""
    return a*math.pow(1 - G_star*math.pow(a, -n)*u_x/(E_star*c_n*kappa_n*mu_f), 1/n)


def _math_tangential_powerlaw_stick_radius_from_force(a, n, F, mu_f, F_x):
    """``tangential_powerlaw_stick_radius_from_force`` for Python floats (the math module); raises where it does."""
    return a*math.pow(1 - F_x/(F*mu_f), 1/(n + 1))


def _math_tangential_powerlaw_traction_stick_centre(r_c, a, c, c_n, n, kappa_n, E_star, mu_f):
    """``tangential_powerlaw_traction_stick_centre`` for Python floats (the math module); raises where it does."""
    return E_star*math.pow(c, n - 1)*c_n*kappa_n*mu_f*n*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((r_c*r_c)*((121683714103007/1125899906842624)*(r_c*r_c)*math.expm1((n - 55)*math.log1p((a - c)/c))/(n - 55) + (61989816618513/562949953421312)*math.expm1((n - 53)*math.log1p((a - c)/c))/(n - 53)) + (15801325804719/140737488355328)*math.expm1((n - 51)*math.log1p((a - c)/c))/(n - 51)) + (8061900920775/70368744177664)*math.expm1((n - 49)*math.log1p((a - c)/c))/(n - 49)) + (514589420475/4398046511104)*math.expm1((n - 47)*math.log1p((a - c)/c))/(n - 47)) + (263012370465/2199023255552)*math.expm1((n - 45)*math.log1p((a - c)/c))/(n - 45)) + (67282234305/549755813888)*math.expm1((n - 43)*math.log1p((a - c)/c))/(n - 43)) + (34461632205/274877906944)*math.expm1((n - 41)*math.log1p((a - c)/c))/(n - 41)) + (4418157975/34359738368)*math.expm1((n - 39)*math.log1p((a - c)/c))/(n - 39)) + (2268783825/17179869184)*math.expm1((n - 37)*math.log1p((a - c)/c))/(n - 37)) + (583401555/4294967296)*math.expm1((n - 35)*math.log1p((a - c)/c))/(n - 35)) + (300540195/2147483648)*math.expm1((n - 33)*math.log1p((a - c)/c))/(n - 33)) + (9694845/67108864)*math.expm1((n - 31)*math.log1p((a - c)/c))/(n - 31)) + (5014575/33554432)*math.expm1((n - 29)*math.log1p((a - c)/c))/(n - 29)) + (1300075/8388608)*math.expm1((n - 27)*math.log1p((a - c)/c))/(n - 27)) + (676039/4194304)*math.expm1((n - 25)*math.log1p((a - c)/c))/(n - 25)) + (88179/524288)*math.expm1((n - 23)*math.log1p((a - c)/c))/(n - 23)) + (46189/262144)*math.expm1((n - 21)*math.log1p((a - c)/c))/(n - 21)) + (12155/65536)*math.expm1((n - 19)*math.log1p((a - c)/c))/(n - 19)) + (6435/32768)*math.expm1((n - 17)*math.log1p((a - c)/c))/(n - 17)) + (429/2048)*math.expm1((n - 15)*math.log1p((a - c)/c))/(n - 15)) + (231/1024)*math.expm1((n - 13)*math.log1p((a - c)/c))/(n - 13)) + (63/256)*math.expm1((n - 11)*math.log1p((a - c)/c))/(n - 11)) + (35/128)*math.expm1((n - 9)*math.log1p((a - c)/c))/(n - 9)) + (5/16)*math.expm1((n - 7)*math.log1p((a - c)/c))/(n - 7)) + (3/8)*math.expm1((n - 5)*math.log1p((a - c)/c))/(n - 5)) + (1/2)*math.expm1((n - 3)*math.log1p((a - c)/c))/(n - 3)) + math.expm1((n - 1)*math.log1p((a - c)/c))/(n - 1))/math.pi


def _math_tangential_powerlaw_traction_stick_integrand(r, s_r, c_n, n, kappa_n, E_star, mu_f):
    """``tangential_powerlaw_traction_stick_integrand`` for Python floats (the math module); raises where it does."""
    return E_star*c_n*kappa_n*mu_f*n*math.pow((r*r) + (s_r*s_r), (1/2)*n - 1)/math.pi


def _math_tangential_slide_onset(E_star, G_star, mu_f, d):
    """``tangential_slide_onset`` for Python floats (the math module); raises where it does."""
    return E_star*d*mu_f/G_star


def _math_tangential_stiffness(G_star, a):
    """``tangential_stiffness`` for Python floats (the math module); raises where it does."""
    return 2*G_star*a


def _math_tangential_stiffness_ratio(nu):
    """``tangential_stiffness_ratio`` for Python floats (the math module); raises where it does."""
    return 2*(nu - 1)/(nu - 2)


def _math_tangential_traction_slip(mu_f, p_a):
    """``tangential_traction_slip`` for Python floats (the math module); raises where it does."""
    return mu_f*p_a


def _math_tangential_traction_stick(mu_f, p_a, p_c):
    """``tangential_traction_stick`` for Python floats (the math module); raises where it does."""
    return mu_f*(p_a - p_c)


def _math_uniform_pressure_displacement_centre(E_star, a, p0):
    """``uniform_pressure_displacement_centre`` for Python floats (the math module); raises where it does."""
    return 2*a*p0/E_star


def _math_uniform_pressure_displacement_edge(E_star, a, p0):
    """``uniform_pressure_displacement_edge`` for Python floats (the math module); raises where it does."""
    return 4*a*p0/(math.pi*E_star)


def _math_uniform_pressure_force(a, p0):
    """``uniform_pressure_force`` for Python floats (the math module); raises where it does."""
    return math.pi*(a*a)*p0


def _math_worn_contact_radius(R, b, d):
    """``worn_contact_radius`` for Python floats (the math module); raises where it does."""
    return math.sqrt((1/2)*(b*b) + (1/2)*math.sqrt(4*(R*R)*(d*d) + b**4))


def _math_worn_depth(R, a, b):
    """``worn_depth`` for Python floats (the math module); raises where it does."""
    return a*math.sqrt((a*a) - (b*b))/R


def _math_worn_displacement_inside(R, b, d, r):
    """``worn_displacement_inside`` for Python floats (the math module); raises where it does."""
    return d - 1/2*max(0, (-b + r)*(b + r))/R


def _math_textbook_worn_displacement_outside(R, a, b, r):
    """``textbook_worn_displacement_outside`` for Python floats (the math module); raises where it does."""
    return (2*a*math.sqrt((a*a) - (b*b))*math.asin(a/r) - (b - r)*(b + r)*(math.sqrt((-(a*a) + (b*b))/((b*b) - (r*r)))*math.sqrt((-(a*a) + (r*r))/(-(b*b) + (r*r))) - math.asin(math.sqrt((-(a*a) + (b*b))/((b*b) - (r*r))))))/(math.pi*R)


def _math_worn_force(E_star, R, b, d):
    """``worn_force`` for Python floats (the math module); raises where it does."""
    return (2/3)*math.sqrt(2)*E_star*b*d*(math.sqrt(4*(R*R)*(d*d)/b**4 + 1) + 2)/math.sqrt(math.sqrt(4*(R*R)*(d*d)/b**4 + 1) + 1)


def _math_textbook_worn_force(E_star, R, b, d):
    """``textbook_worn_force`` for Python floats (the math module); raises where it does."""
    return (1/3)*E_star*math.sqrt(-2*(b*b) + 2*math.sqrt(4*(R*R)*(d*d) + b**4))*(2*(b*b) + math.sqrt(4*(R*R)*(d*d) + b**4))/R


def _math_worn_force_from_radius(E_star, R, a, b):
    """``worn_force_from_radius`` for Python floats (the math module); raises where it does."""
    return (2/3)*E_star*math.sqrt(a - b)*math.sqrt(a + b)*(2*(a*a) + (b*b))/R


def _math_worn_g(R, b, x):
    """``worn_g`` for Python floats (the math module); raises where it does."""
    return x*math.sqrt(max(0, (-b + x)*(b + x)))/R


def _math_worn_profile(R, b, r):
    """``worn_profile`` for Python floats (the math module); raises where it does."""
    return (1/2)*max(0, (-b + r)*(b + r))/R
