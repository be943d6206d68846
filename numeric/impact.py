"""Elastic impact of a sphere on a wall (Hertz 1882): Problems 3 and 4 of the chapter.

The sphere (radius R, mass m or density rho) hits a wall at the speed v0; the contact is
Hertzian throughout (quasi-static, no losses), with the effective modulus E* of (5.26) and
the effective radius R (5.27) (for a sphere on a flat wall, its own radius). The formulas are
generated from :mod:`hertzmdr.derive.impact`: energy conservation with the energy (5.25).

Give exactly one of ``m`` (mass [kg]) and ``rho`` (density [kg/m^3], m = 4/3 pi R^3 rho).
All functions broadcast their arguments and raise ValueError for inputs outside their domain.
The differential stiffness of Problem 5 is :func:`hertzmdr.numeric.hertz.stiffness`.
"""

from __future__ import annotations

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import positive, result, scalar_path

__all__ = ["max_depth", "contact_time", "max_pressure", "max_force", "max_contact_radius",
           "sphere_mass"]


def _dispatch(by_mass, by_density, v0, R, E_star, m, rho):
    v0, R, E_star = positive("v0", v0), positive("R", R), positive("E_star", E_star)
    if (m is None) == (rho is None):
        raise ValueError(f"m = {m!r}, rho = {rho!r}: give exactly one of the mass m [kg] "
                         "and the density rho [kg/m^3]")
    if m is not None:
        return result(by_mass(E_star, R, positive("m", m), v0))
    return result(by_density(E_star, R, positive("rho", rho), v0))


def max_depth(v0, R, E_star, *, m=None, rho=None):
    """Maximum indentation depth x0 [m] (Problem 3).

    .. math:: x_0 = \\left(\\frac{15}{16} \\frac{m v_0^2}{E^* R^{1/2}}\\right)^{2/5}

    Parameters
    ----------
    v0 : float or array_like
        Impact speed [m/s], v0 > 0.
    R : float or array_like
        Radius of the sphere (effective radius (5.27)) [m], R > 0.
    E_star : float or array_like
        Effective modulus (5.26) [Pa], E_star > 0.
    m : float or array_like, optional
        Mass [kg], m > 0.
    rho : float or array_like, optional
        Density of the sphere [kg/m^3], rho > 0 (instead of m).
    """
    return _dispatch(gen.impact_max_depth, gen.impact_max_depth_density, v0, R, E_star, m, rho)


def contact_time(v0, R, E_star, *, m=None, rho=None):
    """Contact time tau [s] of the impact (Problem 3).

    .. math:: \\tau = \\frac{2 x_0}{v_0} \\int_0^1 \\frac{d\\xi}{\\sqrt{1 - \\xi^{5/2}}}
              = \\frac{4\\sqrt{\\pi}\\,\\Gamma(2/5)}{5\\,\\Gamma(9/10)} \\frac{x_0}{v_0}
              \\approx 2.94 \\frac{x_0}{v_0}

    Parameters as :func:`max_depth`.
    """
    return _dispatch(gen.impact_contact_time, gen.impact_contact_time_density, v0, R, E_star, m,
                     rho)


def max_pressure(v0, R, E_star, *, m=None, rho=None):
    """Maximum contact pressure p0 [Pa] during the impact (Problem 4): (5.22) at x0.

    For a sphere of density rho it does not depend on R:
    p0 = (2/pi) (5/4 pi E*^4 rho v0^2)^(1/5). Parameters as :func:`max_depth`.
    """
    v0_, E_ = positive("v0", v0), positive("E_star", E_star)
    if rho is not None and m is None:
        positive("R", R)
        return result(gen.impact_max_pressure_density(E_, positive("rho", rho), v0_))
    return _dispatch(gen.impact_max_pressure, None, v0, R, E_star, m, rho)


def max_force(v0, R, E_star, *, m=None, rho=None):
    """Maximum contact force [N] during the impact: (5.23) at x0. Parameters as
    :func:`max_depth`."""
    return _dispatch(gen.impact_max_force, gen.impact_max_force_density, v0, R, E_star, m, rho)


def max_contact_radius(v0, R, E_star, *, m=None, rho=None):
    """Maximum contact radius [m] during the impact: (5.21) at x0. Parameters as
    :func:`max_depth`."""
    return _dispatch(gen.impact_max_contact_radius, gen.impact_max_contact_radius_density, v0, R,
                     E_star, m, rho)


@scalar_path
def sphere_mass(R, rho):
    """Mass m = (4/3) pi R^3 rho [kg] of a solid sphere (Problem 4).

    Parameters
    ----------
    R : float or array_like
        Radius of the sphere [m], R > 0.
    rho : float or array_like
        Density [kg/m^3], rho > 0.
    """
    return result(gen.impact_sphere_mass(positive("R", R), positive("rho", rho)))
