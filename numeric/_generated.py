"""Functions generated from the SymPy derivations in ``hertzmdr.derive``.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``);
``python -m hertzmdr.derive --check`` fails when this file is stale. Each function cites the chapter's
equation, the derivation it comes from and the test that verifies it by an independent route.
Arguments are floats or NumPy arrays in SI units; they are not validated here -- the
hand-written modules of ``hertzmdr.numeric`` validate and broadcast.
"""

import numpy

__all__ = [
    'boussinesq_sigma_xx',
    'boussinesq_sigma_xy',
    'boussinesq_sigma_xz',
    'boussinesq_sigma_yy',
    'boussinesq_sigma_yz',
    'boussinesq_sigma_zz',
    'boussinesq_surface_ux',
    'boussinesq_surface_uy',
    'boussinesq_surface_uz',
    'boussinesq_ux',
    'boussinesq_uy',
    'boussinesq_uz',
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
    'punch_pressure_displacement',
    'punch_pressure_displacement_outside',
    'punch_pressure_force',
    'punch_stiffness',
    'stress_axis_max_shear',
    'stress_axis_max_shear_slope',
    'stress_axis_sigma_xx',
    'stress_axis_sigma_xx_deep',
    'stress_axis_sigma_zz',
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
    'uniform_pressure_displacement_centre',
    'uniform_pressure_displacement_edge',
]


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
    return -3/2*F*z**3/(numpy.pi*(x**2 + y**2 + z**2)**(5/2))


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
    return (1/2)*F*(nu + 1)*(z**2/(x**2 + y**2 + z**2)**(3/2) + (2 - 2*nu)/numpy.sqrt(x**2 + y**2 + z**2))/(numpy.pi*E)


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
    return (1/4)*p0*(3*a**3 - 2*a*(a**2 + z**2)*(nu + 1) + 2*z*(a**2 + z**2)*(nu + 1)*numpy.arctan(a/z))/(a*(a**2 + z**2))


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
    return -a**2*p0/(a**2 + z**2)


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
    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - eta*(nu + 1)*(-xi*(-numpy.arctan(xi) + (1/2)*numpy.pi) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


def stress_hertz_sigma_rr_far(nu, p0, xi, eta, chi):
    """Radial stress sigma_rr [Pa] under the Hertz pressure at (xi, beta), for xi >= 1.

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Printed in a stable form: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written
    as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2.

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

    return p0*(-chi**2*eta*xi**2/((eta**2 + xi**2)*(xi**2 + 1)) - 2/15*eta*(nu + 1)*scipy.special.hyp2f1(1, 3/2, 7/2, -1/xi**2)/(xi**2*(xi**2 + 1)) + (1 - 2*nu)/((3*eta + 3)*(xi**2 + 1)))


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
    return p0*(-eta*(nu + 1)*(-xi*(-numpy.arctan(xi) + (1/2)*numpy.pi) + 1 - (1/3)/(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


def stress_hertz_sigma_tt_far(nu, p0, xi, eta):
    """Hoop stress sigma_theta [Pa] under the Hertz pressure at (xi, beta), for xi >= 1.

    Chapter: Fig. 5.9. Derived from: Huber (1904) as given by Johnson (1985), eqs. (3.44),
    in spheroidal variables.

    Derivation: ``hertzmdr.derive.stress``. Verified by
    ``tests/test_stress.py::test_hertz_field_by_superposition``.

    Printed in a stable form: 1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written
    as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2.

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

    return p0*(-2/15*eta*(nu + 1)*scipy.special.hyp2f1(1, 3/2, 7/2, -1/xi**2)/(xi**2*(xi**2 + 1)) + (1 - 2*nu)*(eta**2 + eta - 1)/((3*eta + 3)*(xi**2 + 1)))


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
    return 2*a**2*z**2/(-z**2 - (-a + r)*(a + r) + numpy.sqrt(4*a**2*z**2 + (z**2 + (-a + r)*(a + r))**2))


def stress_von_mises(sigma_xx, sigma_yy, sigma_zz, tau_xy, tau_yz, tau_xz):
    """Von Mises equivalent stress [Pa] of the stress tensor.

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
    return numpy.sqrt(sigma_xx**2 - sigma_xx*sigma_yy - sigma_xx*sigma_zz + sigma_yy**2 - sigma_yy*sigma_zz + sigma_zz**2 + 3*tau_xy**2 + 3*tau_xz**2 + 3*tau_yz**2)


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
