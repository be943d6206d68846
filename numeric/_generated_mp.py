"""The relations of ``hertzmdr.derive`` printed for mpmath: any precision, no SymPy needed.

GENERATED FILE -- DO NOT EDIT. Written by ``python -m hertzmdr.derive`` (``make generate``) from the same
expressions as ``_generated.py``; ``python -m hertzmdr.derive --check`` fails when this file is stale. Call with
mpmath numbers inside ``mpmath.workdps(...)``: every constant is an exact mpmath rational, so the
result carries the working precision. The accuracy report (``hertzmdr accuracy``) takes its
50-digit truths from here; ``tests/`` check these expressions against independent quadratures.
"""

import mpmath

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
    'punch_pressure_displacement',
    'punch_pressure_displacement_outside',
    'punch_pressure_force',
    'punch_stiffness',
    'uniform_pressure_displacement',
    'uniform_pressure_displacement_centre',
    'uniform_pressure_displacement_edge',
    'uniform_pressure_displacement_outside',
    'uniform_pressure_force',
]


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
