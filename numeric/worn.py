"""The flattened (worn) paraboloid of Problem 8 by the MDR: a paraboloid of radius R worn flat
to a tip of radius b, f(r) = 0 for r < b and (r^2 - b^2)/(2R) beyond.

Floats or NumPy arrays in SI units; bad input raises ValueError. The formulas are generated
from :mod:`hertzmdr.derive.worn`; this module validates, broadcasts and inverts F(a), which has
no closed-form inverse in the depth: :func:`depth_from_force` solves F(a) = F for the contact
radius a > b by Brent's method (F(a) increases from 0 at a = b) and returns d = g(a) (5.55).
The pressure is log-infinite at the edge of the flat r = b, where the slope of the profile
jumps: it has no finite maximum.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, nonnegative, positive, result

__all__ = ["profile", "g_profile", "depth", "contact_radius", "force", "force_from_radius",
           "depth_from_force", "pressure", "surface_displacement"]


def _geometry(R, b):
    return positive("R", R), positive("b", b)


def profile(r, R, b):
    """Height f(r) [m] of the worn paraboloid above its tip: 0 for r < b, (r^2 - b^2)/(2R) beyond.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], >= 0.
    R : float or array_like
        Radius of the paraboloid before wear [m], > 0.
    b : float or array_like
        Radius of the flat (worn) tip [m], > 0.
    """
    R, b = _geometry(R, b)
    return result(gen.worn_profile(R, b, nonnegative("r", r)))


def g_profile(x, R, b):
    """MDR profile g(x) [m] (5.52): 0 for |x| < b. Parameters as :func:`profile` (x in m)."""
    x = nonnegative("x", np.abs(as_float("x", x)))  # g is even in x
    R, b = _geometry(R, b)
    return result(gen.worn_g(R, b, x))  # (5.52); the generated form is 0 for x <= b


def depth(a, R, b):
    """Indentation depth d = g(a) = (a/R) sqrt(a^2 - b^2) [m] at the contact radius a >= b, (5.55).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], a >= b.
    R, b
        As in :func:`profile`.
    """
    R, b = _geometry(R, b)
    a, R, b = np.broadcast_arrays(_radius("a", a, b), R, b)
    return result(gen.worn_depth(R, a, b))


def _radius(name, a, b):
    a = nonnegative(name, a)
    bad = a < b
    if np.any(bad):
        first = float(np.broadcast_to(a, bad.shape)[bad].flat[0])
        raise ValueError(f"{name} = {first!r} is out of range; valid: {name} >= b (the contact "
                         "covers at least the flat)")
    return a


def contact_radius(d, R, b):
    """Contact radius a(d) [m], (5.55) solved for a^2; a = b at d = 0.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], >= 0.
    R, b
        As in :func:`profile`.
    """
    R, b = _geometry(R, b)
    return result(gen.worn_contact_radius(R, b, nonnegative("d", d)))


def force(d, R, b, E_star):
    """Normal force F(d) [N], (5.57) at the contact radius of (5.55), in its stable form.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], >= 0.
    R, b
        As in :func:`profile`.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    """
    R, b = _geometry(R, b)
    return result(gen.worn_force(positive("E_star", E_star), R, b, nonnegative("d", d)))


def force_from_radius(a, R, b, E_star):
    """Normal force F(a) = (2 E*/(3R)) (2a^2 + b^2) sqrt(a^2 - b^2) [N], (5.57) with d = g(a).

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], a >= b.
    R, b, E_star
        As in :func:`force`.
    """
    R, b = _geometry(R, b)
    a, R, b = np.broadcast_arrays(_radius("a", a, b), R, b)
    return result(gen.worn_force_from_radius(positive("E_star", E_star), R, a, b))


def depth_from_force(F, R, b, E_star):
    """Indentation depth d [m] under the normal force F: F(a) = F solved for a, then d = g(a).

    F(a) increases from 0 at a = b; the root is bracketed in [b, 2^k b] and found by Brent's
    method to 4 eps (9e-16, the smallest rtol brentq accepts) relative in a.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    R, b, E_star
        As in :func:`force`.
    """
    from scipy.optimize import brentq

    F, R, b, E_star = np.broadcast_arrays(nonnegative("F", F), *_geometry(R, b),
                                          positive("E_star", E_star))
    out = np.empty(F.shape)
    for i in np.ndindex(F.shape):
        Ri, bi, Ei, Fi = float(R[i]), float(b[i]), float(E_star[i]), float(F[i])

        def excess(a, Ri=Ri, bi=bi, Ei=Ei, Fi=Fi):
            return float(gen.worn_force_from_radius(Ei, Ri, a, bi)) - Fi  # (5.57)

        hi = 2 * bi
        while excess(hi) < 0:
            hi *= 2
        a = brentq(excess, bi, hi, xtol=1e-15 * hi, rtol=4 * np.finfo(float).eps)
        out[i] = float(gen.worn_depth(Ri, a, bi))  # (5.55)
    return result(out)


def pressure(r, d, R, b, E_star):
    """Contact pressure p(r) [Pa], (5.59) in incomplete elliptic integrals; 0 for r >= a and
    +inf at r = b (the edge of the flat).

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], >= 0.
    d, R, b, E_star
        As in :func:`force`, d > 0.
    """
    R, b = _geometry(R, b)
    a = contact_radius(positive("d", d), R, b)
    return result(gen.worn_pressure(positive("E_star", E_star), R, a, b, nonnegative("r", r)))


def surface_displacement(r, d, R, b):
    """Surface displacement u_z(r) [m]: d - f(r) inside the contact, (5.60) outside.

    Parameters
    ----------
    r : float or array_like
        Distance from the axis [m], >= 0.
    d, R, b
        As in :func:`force`, d > 0.
    """
    r, d, R, b = np.broadcast_arrays(nonnegative("r", r), positive("d", d), *_geometry(R, b))
    a = np.asarray(gen.worn_contact_radius(R, b, d))
    out = np.empty(r.shape)
    ins = r <= a
    out[ins] = gen.worn_displacement_inside(R[ins], b[ins], d[ins], r[ins])  # (5.60), r <= a
    out[~ins] = gen.worn_displacement_outside(R[~ins], a[~ins], b[~ins], r[~ins])  # (5.60)
    return result(out)
