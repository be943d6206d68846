"""Functions generated from the SymPy derivations in ``hertzmdr.derive``.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``);
``python -m hertzmdr.derive --check`` fails when this file is stale. Each function cites the chapter's
equation, the derivation it comes from and the test that verifies it by an independent route.
Arguments are floats or NumPy arrays in SI units; they are not validated here -- the
hand-written modules of ``hertzmdr.numeric`` validate and broadcast.
"""

import numpy

__all__ = [
    'bodies_crossed_cylinders_curvature_1',
    'bodies_crossed_cylinders_curvature_2',
    'bodies_crossed_cylinders_gaussian_radius',
    'bodies_effective_modulus',
    'bodies_effective_modulus_rigid',
    'bodies_effective_radius',
    'bodies_gaussian_approx_area',
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
    'cone_contact_radius',
    'cone_contact_radius_from_force',
    'cone_depth',
    'cone_depth_from_force',
    'cone_force',
    'cone_mean_pressure',
    'cone_pressure',
    'cone_stiffness',
    'hertz_contact_radius',
    'hertz_contact_radius_from_force',
    'hertz_depth_from_force',
    'hertz_displacement_inside',
    'hertz_displacement_outside',
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
    'impact_max_contact_radius',
    'impact_max_contact_radius_density',
    'impact_max_depth',
    'impact_max_depth_density',
    'impact_max_force',
    'impact_max_force_density',
    'impact_max_pressure',
    'impact_max_pressure_density',
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
    'punch_pressure_displacement',
    'punch_pressure_displacement_outside',
    'punch_pressure_force',
    'punch_stiffness',
    'uniform_pressure_displacement_centre',
    'uniform_pressure_displacement_edge',
]


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
    return numpy.pi*numpy.sqrt(R1)*numpy.sqrt(R2)*d


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
    return numpy.sqrt(2)*R + 2*R


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
    return 2*E_star*d**2/(numpy.pi*numpy.tan(theta))


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
    return (1/2)*E_star*numpy.tan(theta)


def cone_pressure(E_star, d, theta, r):
    """Contact pressure p(r) [Pa] of a rigid cone at depth d, for 0 < r <= a (log-singular at r = 0).

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
    return (1/2)*E_star*numpy.tan(theta)*numpy.arccosh(2*d/(numpy.pi*r*numpy.tan(theta)))


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
    return 4*E_star*d/(numpy.pi*numpy.tan(theta))


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

    return (2/5)*2**(1/5)*5**(2/5)*numpy.pi**(9/10)*R*rho**(2/5)*scipy.special.gamma(2/5)/(E_star**(2/5)*v0**(1/5)*scipy.special.gamma(9/10))


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
    return 2**(3/5)*5**(1/5)*E_star**(4/5)*rho**(1/5)*v0**(2/5)/numpy.pi**(4/5)


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

    return (1/2)*E_star*numpy.sqrt(d)*numpy.sqrt(functools.reduce(numpy.maximum, [0, 1 - x**2/(R*d)]))/numpy.sqrt(R)


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
    return 2*E_star*a


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
    return 4*a*p0/(numpy.pi*E_star)
