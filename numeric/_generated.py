"""Functions generated from the SymPy derivations in ``hertzmdr.derive``.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``);
``python -m hertzmdr.derive --check`` fails when this file is stale. Each function cites the chapter's
equation, the derivation it comes from and the test that verifies it by an independent route.
Arguments are floats or NumPy arrays in SI units; they are not validated here -- the
hand-written modules of ``hertzmdr.numeric`` validate and broadcast.
"""

import numpy

__all__ = [
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
    'powerlaw_contact_radius',
    'powerlaw_depth_from_force',
    'powerlaw_displacement_outside',
    'powerlaw_force',
    'powerlaw_force_from_radius',
    'powerlaw_g',
    'powerlaw_kappa',
    'powerlaw_kappa_asymptotic',
    'powerlaw_mean_pressure',
    'powerlaw_pressure',
    'powerlaw_pressure_n1',
    'powerlaw_pressure_n2',
    'powerlaw_pressure_n3',
    'powerlaw_pressure_n4',
    'powerlaw_pressure_normalized',
    'powerlaw_pressure_small_n',
    'powerlaw_punch_displacement_outside',
    'powerlaw_punch_force',
    'powerlaw_punch_pressure',
    'punch_pressure_displacement',
    'punch_pressure_displacement_outside',
    'punch_pressure_force',
    'punch_stiffness',
    'uniform_pressure_displacement_centre',
    'uniform_pressure_displacement_edge',
    'worn_contact_radius',
    'worn_depth',
    'worn_displacement_outside',
    'worn_force',
    'worn_force_from_radius',
    'worn_g',
]


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
    return (d/(c_n*kappa_n))**(n**(-1.0))


def powerlaw_depth_from_force(E_star, F, c_n, kappa_n, n):
    """Indentation depth d [m] of a power-law indenter under the force F.

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
    return ((1/2)*F*(c_n*kappa_n)**(n**(-1.0))*(n + 1)/(E_star*n))**(n/(n + 1))


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
    return (1/2)*numpy.sqrt(2)*numpy.sqrt(numpy.pi)*numpy.sqrt(n)*numpy.exp(2*(1/8 + 4*(-1/192 + 4*(1/640 + 4*(-17/14336 + (31/4608)/n**2)/n**2)/n**2)/n**2)/n)


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
    return 2*E_star*d*n/(numpy.pi*a*(n + 1))


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
    return 2*E_star*a*d


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
    return E_star*d/(numpy.pi*numpy.sqrt(a**2 - r**2))


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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
    d : float or ndarray
        indentation depth [m]
    """
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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
    """
    return a*numpy.sqrt(a**2 - b**2)/R


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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
    d : float or ndarray
        indentation depth [m]
    """
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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
    """
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
        radius of the flat (worn) tip of a flattened paraboloid (Problem 8) [m]
    x : float or ndarray
        coordinate [m]
    """
    import functools

    return x*numpy.sqrt(functools.reduce(numpy.maximum, [0, (-b + x)*(b + x)]))/R
