"""Rigid cone on an elastic half-space, (5.38)-(5.40).

theta is the angle between the cone's surface and the plane (profile f(r) = r tan(theta));
the half-space approximation needs theta small. The formulas are generated from
:mod:`hertzmdr.derive.cone` (flat punches superposed, Problem 5's argument); this module
validates and broadcasts. The pressure is log-singular at the tip: there is no finite maximum
pressure; :func:`mean_pressure` is the useful scale, and it does not depend on the depth.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import between, nonnegative, positive, representable, result

__all__ = ["contact_radius", "depth", "force", "pressure", "mean_pressure", "stiffness",
           "depth_from_force", "contact_radius_from_force"]


def _theta(theta):
    return between("theta", theta, 0.0, np.pi / 2)


@representable
def contact_radius(d, theta):
    """Contact radius a = 2 d/(pi tan(theta)) [m], (5.38).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], theta in [1e-300, 1.5] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    theta : float or array_like
        Angle between the cone's surface and the plane [rad], 0 < theta < pi/2.
    """
    return result(gen.cone_contact_radius(nonnegative("d", d), _theta(theta)))


@representable
def depth(a, theta):
    """Indentation depth d = (pi/2) a tan(theta) [m] at the contact radius a, (5.38).

    Guaranteed finite and accurate for a in [1e-12, 1e+06], theta in [1e-300, 1.5] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], a >= 0.
    theta : float or array_like
        Angle between the cone's surface and the plane [rad], 0 < theta < pi/2.
    """
    return result(gen.cone_depth(nonnegative("a", a), _theta(theta)))


@representable
def force(d, theta, E_star):
    """Normal force F = (2/pi) E* d^2/tan(theta) [N], (5.40).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], theta in [1e-300, 1.5], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    theta : float or array_like
        Angle between the cone's surface and the plane [rad], 0 < theta < pi/2.
    E_star : float or array_like
        Effective modulus (5.8)/(5.26) [Pa], E_star > 0.
    """
    return result(gen.cone_force(positive("E_star", E_star), nonnegative("d", d),
                               _theta(theta)))


def pressure(r, d, theta, E_star):
    """Contact pressure p(r) = (E*/2) tan(theta) arccosh(a/r) [Pa], (5.39) with its sign
    corrected (positive in compression; see docs/errata.md).

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in {0} U [1e-15, 1000], theta
    in [1e-300, 1.5], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py).
    Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    The pressure has a logarithmic singularity at the tip: at r = 0 exactly this returns
    ``inf`` (no warning); it is 0 for r >= a.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], r >= 0.
    d : float or array_like
        Indentation depth [m], d >= 0.
    theta, E_star
        As in :func:`force`.
    """
    r, d, theta, E_star = np.broadcast_arrays(nonnegative("r", r), nonnegative("d", d),
                                              _theta(theta), positive("E_star", E_star))
    a = gen.cone_contact_radius(d, theta)
    out = np.zeros(r.shape)
    tip = (r == 0) & (a > 0)
    out[tip] = np.inf
    inside = (r > 0) & (r < a)
    out[inside] = gen.cone_pressure(E_star[inside], d[inside], theta[inside], r[inside])  # (5.39)
    return result(out)


@representable
def mean_pressure(theta, E_star):
    """Mean pressure F/(pi a^2) = (E*/2) tan(theta) [Pa], the same at every depth.

    Guaranteed finite and accurate for theta in [1e-300, 1.5], E_star in [0.001, 1e+15] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    theta : float or array_like
        Angle between the cone's surface and the plane [rad], 0 < theta < pi/2.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.cone_mean_pressure(positive("E_star", E_star), _theta(theta)))


@representable
def stiffness(d, theta, E_star):
    """Differential stiffness dF/dd = 2 a E* [N/m] (Problem 5). Parameters as :func:`force`.

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], theta in [1e-300, 1.5], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.
    """
    return result(gen.cone_stiffness(positive("E_star", E_star), nonnegative("d", d),
                                   _theta(theta)))


@representable
def depth_from_force(F, theta, E_star):
    """Indentation depth d = (pi F tan(theta)/(2 E*))^(1/2) [m], (5.40) inverted.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], theta in [1e-300, 1.5], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    theta, E_star
        As in :func:`force`.
    """
    return result(gen.cone_depth_from_force(positive("E_star", E_star), nonnegative("F", F),
                                          _theta(theta)))


@representable
def contact_radius_from_force(F, theta, E_star):
    """Contact radius a = (2 F/(pi E* tan(theta)))^(1/2) [m], (5.38) with (5.40) inverted.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], theta in [1e-300, 1.5], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters as :func:`depth_from_force`.
    """
    return result(gen.cone_contact_radius_from_force(positive("E_star", E_star),
                                                   nonnegative("F", F), _theta(theta)))
