"""Line contact of two parallel cylinders (the 2-D Hertz problem), (5.34)-(5.37).

The depth d of a line contact is not well defined (the displacement of a 2-D load diverges
logarithmically with the size of the bodies); the chapter, and these functions, define it by
the half-width a = sqrt(R d) (5.35). The half-width, the pressure and the force per length
do not depend on that convention: prefer the force-controlled functions. R is the effective
radius (5.27) of the two cylinders, E* the effective modulus (5.26). Formulas generated from
:mod:`hertzmdr.derive.line`; this module validates and broadcasts.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import (
    as_float,
    nonnegative,
    positive,
    representable,
    result,
    scalar_path,
)

__all__ = ["half_width", "force", "depth_from_force", "half_width_from_force",
           "max_pressure", "max_pressure_from_force", "pressure", "stiffness"]


@representable
def half_width(d, R):
    """Half-width a = sqrt(R d) [m] of the contact strip, (5.35) (the definition of d).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    d : float or array_like
        Depth [m] in the sense of (5.35), d >= 0.
    R : float or array_like
        Effective radius (5.27) [m], R > 0.
    """
    return result(gen.line_half_width(positive("R", R), nonnegative("d", d)))


@representable
def force(d, L, E_star):
    """Normal force F = (pi/4) E* L d [N], (5.34), with d in the sense of (5.35).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], L in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Depth [m], d >= 0.
    L : float or array_like
        Length of the contact [m], L > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.line_force(positive("E_star", E_star), positive("L", L),
                               nonnegative("d", d)))


@representable
def depth_from_force(F, L, E_star):
    """Depth d = 4 F/(pi E* L) [m] (in the sense of (5.35)) under the force F, (5.34).

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], L in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    L, E_star
        As in :func:`force`.
    """
    return result(gen.line_depth_from_force(positive("E_star", E_star), nonnegative("F", F),
                                          positive("L", L)))


@representable
def half_width_from_force(F, L, R, E_star):
    """Half-width a = 2 (F R/(pi E* L))^(1/2) [m] of the strip under the force F.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], L in [1e-12, 1e+06], R in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    L : float or array_like
        Length of the contact [m], L > 0.
    R : float or array_like
        Effective radius [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.line_half_width_from_force(positive("E_star", E_star), nonnegative("F", F),
                                               positive("L", L), positive("R", R)))


@representable
def max_pressure(d, R, E_star):
    """Maximum pressure p0 = (E*/2) (d/R)^(1/2) [Pa], (5.37), d in the sense of (5.35).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R in [1e-12, 1e+06], E_star in
    [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Depth [m], d >= 0.
    R : float or array_like
        Effective radius [m], R > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.line_max_pressure(positive("E_star", E_star), positive("R", R),
                                      nonnegative("d", d)))


@representable
def max_pressure_from_force(F, L, R, E_star):
    """Maximum pressure p0 = (E* F/(pi L R))^(1/2) [Pa] under the force F, (5.37).

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], L in [1e-12, 1e+06], R in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    The chapter prints this without the pi (see docs/errata.md). Parameters as
    :func:`half_width_from_force`.
    """
    return result(gen.line_max_pressure_from_force(positive("E_star", E_star),
                                                 nonnegative("F", F), positive("L", L),
                                                 positive("R", R)))


@representable
def pressure(x, d, R, E_star):
    """Pressure p(x) = p0 (1 - x^2/a^2)^(1/2) [Pa] across the strip, 0 outside, (5.36).

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+300], d in [1e-15, 1000], R in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    x : float or array_like
        Distance from the middle of the strip [m], finite.
    d : float or array_like
        Depth [m] in the sense of (5.35), d > 0.
    R, E_star
        As in :func:`max_pressure`.
    """
    x = as_float("x", x)
    if not np.isfinite(x).all():
        raise ValueError(f"x = {x!r}: must be finite")
    x, d, R, E_star = np.broadcast_arrays(x, positive("d", d), positive("R", R),
                                          positive("E_star", E_star))
    # the generated form decides in or out (its Max(0, 1 - x^2/a^2)); it is called only for
    # |x| < 2a, so that x is never squared far outside (x = 1e155 m would overflow)
    inside = np.abs(x) < 2 * gen.line_half_width(R, d)  # (5.35)
    return result(np.where(inside, gen.line_pressure(E_star, R, d, np.where(inside, x, 0.0)),
                           0.0))  # (5.36)


@scalar_path
def stiffness(L, E_star):
    """Differential stiffness dF/dd = (pi/4) E* L [N/m] of a line contact, (5.34) differentiated
    (d in the sense of (5.35)); it does not depend on the load.

    Parameters
    ----------
    L : float or array_like
        Length of the contact [m], L > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.line_stiffness(positive("E_star", E_star), positive("L", L)))
