"""Relations every contact shares, whatever its profile: the mean pressure over a disc, a strip
or a measured area; the differential stiffness 2 a E* of an axisymmetric contact (5.12),
Problem 5; the flat punch's force (5.11) and its inverse.

Floats or NumPy arrays in SI units; bad input raises ValueError. The formulas are generated
from :mod:`hertzmdr.derive.contact` and :mod:`hertzmdr.derive.powerlaw` (the punch).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import nonnegative, positive, result, scalar_path

__all__ = ["mean_pressure", "mean_pressure_disc", "mean_pressure_strip", "stiffness",
           "punch_force", "punch_depth_from_force"]


def _unloaded(F, size, name: str, size_name: str):
    """(F, size, empty) broadcast, ``empty`` where the contact has zero size: allowed only
    where F = 0 too (an unloaded point of a sweep), refused under a force (a point load has no
    mean pressure). Where empty, ``size`` is replaced by 1 so that the formula never divides
    by 0; the caller sets 0 there."""
    F, size = np.broadcast_arrays(nonnegative("F", F), nonnegative(size_name, size))
    empty = size == 0
    loaded = empty & (F > 0)
    if loaded.any():
        raise ValueError(f"{size_name} = 0 under F = {float(F[loaded].flat[0])!r} N: a contact "
                         f"of zero {name} carries no force; valid: {size_name} > 0, or "
                         f"{size_name} = 0 with F = 0 (no load)")
    return F, np.where(empty, 1.0, size), empty


def mean_pressure(F, A):
    """Mean pressure F/A [Pa] over a contact of area A, (5.17).

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    A : float or array_like
        Contact area [m^2], > 0; or 0 where F = 0 (no load: no contact, no pressure; the
        result is 0 there).
    """
    F, A, empty = _unloaded(F, A, "area", "A")
    return result(np.where(empty, 0.0, gen.contact_mean_pressure(A, F)))


def mean_pressure_disc(F, a):
    """Mean pressure F/(pi a^2) [Pa] over a circular contact of radius a, (5.17).

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    a : float or array_like
        Contact radius [m], > 0; or 0 where F = 0 (no load: no contact, no pressure; the
        result is 0 there, although F/(pi a^2) of a cone tends to E* cot(theta)/2 as the load
        goes to 0, a constant of the self-similar contact).
    """
    F, a, empty = _unloaded(F, a, "radius", "a")
    return result(np.where(empty, 0.0, gen.disc_mean_pressure(F, a)))


def mean_pressure_strip(F, a, L):
    """Mean pressure F/(2 a L) [Pa] over a contact strip of half-width a and length L, (5.34).

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    a : float or array_like
        Half-width of the strip [m], > 0; or 0 where F = 0 (no load: the result is 0 there).
    L : float or array_like
        Length of the strip [m], > 0.
    """
    L = positive("L", L)
    F, a, empty = _unloaded(F, a, "half-width", "a")
    return result(np.where(empty, 0.0, gen.strip_mean_pressure(F, L, a)))


@scalar_path
def stiffness(a, E_star):
    """Differential normal stiffness dF/dd = 2 a E* [N/m] of an axisymmetric contact of radius a,
    (5.12), Problem 5 (dF/dd of (5.57) with d = g(a)).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], >= 0.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    """
    return result(gen.mdr_stiffness(positive("E_star", E_star), nonnegative("a", a)))


@scalar_path
def punch_force(d, a, E_star):
    """Normal force F = 2 E* a d [N] of a flat rigid punch of radius a at depth d, (5.11).

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], >= 0.
    a : float or array_like
        Punch radius [m], > 0.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    """
    return result(gen.powerlaw_punch_force(positive("E_star", E_star), positive("a", a),
                                           nonnegative("d", d)))


@scalar_path
def punch_depth_from_force(F, a, E_star):
    """Indentation depth d = F/(2 E* a) [m] of a flat rigid punch under the force F, (5.11).

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    a, E_star
        As in :func:`punch_force`.
    """
    return result(gen.punch_depth_from_force(positive("E_star", E_star), nonnegative("F", F),
                                             positive("a", a)))
