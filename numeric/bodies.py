"""Two elastic bodies with curved surfaces: effective modulus and radius, principal radii of a
quadratic gap, crossed cylinders, and the chapter's Gaussian-radius elliptic approximation,
(5.26)-(5.33) and Problem 2.

All functions take floats or NumPy arrays in SI units, broadcast them against each other and
raise ValueError for inputs outside their domain. The formulas are generated from
:mod:`hertzmdr.derive.bodies`; this module validates and dispatches. Feed ``E_star`` and ``R``
(or the Gaussian radius) into :mod:`hertzmdr.numeric.hertz`.

Radii of curvature are positive for a convex surface, negative for a concave one (its centre of
curvature lies outside the body), and ``inf`` for a flat one.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import (
    as_float,
    between,
    nonnegative,
    nonzero,
    poisson,
    positive,
    representable,
    result,
)

__all__ = [
    "effective_modulus", "effective_radius", "principal_radii", "crossed_cylinder_radii",
    "crossed_cylinders_gaussian_radius", "gaussian_radius", "gaussian_approx_semi_axes",
    "gaussian_approx_area", "gaussian_approx_max_pressure", "gaussian_approx_force",
    "gaussian_approx_depth_from_force", "gaussian_approx_pressure",
]


@representable
def effective_modulus(E1, nu1, E2=None, nu2=None):
    """Effective modulus E* [Pa] of two elastic bodies, (5.26); of one body on a rigid one, (5.8).

    Guaranteed finite and accurate for E1 in [0.001, 1e+15], nu1 in (-1, 0.5], E2 in [0.001, 1e+15],
    nu2 in (-1, 0.5] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    .. math:: 1/E^* = (1 - \\nu_1^2)/E_1 + (1 - \\nu_2^2)/E_2

    Parameters
    ----------
    E1 : float or array_like
        Young's modulus of body 1 [Pa], E1 > 0 and finite.
    nu1 : float or array_like
        Poisson's ratio of body 1, -1 < nu1 <= 0.5.
    E2 : float or array_like, optional
        Young's modulus of body 2 [Pa], E2 > 0; ``None`` or ``inf`` for a rigid body 2.
    nu2 : float or array_like, optional
        Poisson's ratio of body 2, -1 < nu2 <= 0.5; required unless body 2 is rigid.

    Returns
    -------
    E_star : float or ndarray
        Effective modulus [Pa].
    """
    E1, nu1 = positive("E1", E1), poisson("nu1", nu1)
    if E2 is None:
        return result(gen.bodies_effective_modulus_rigid(E1, nu1))  # (5.8)
    E2 = positive("E2", E2, allow_inf=True)
    if nu2 is None:
        if np.isfinite(E2).any():
            raise ValueError("nu2 = None: give Poisson's ratio of body 2 (-1 < nu2 <= 0.5) "
                             "unless body 2 is rigid (E2 = None or inf)")
        nu2 = 0.0  # does not matter: (1 - nu2^2)/inf = 0
    nu2 = poisson("nu2", nu2)
    return result(gen.bodies_effective_modulus(E1, nu1, E2, nu2))  # (5.26)


@representable
def effective_radius(R1, R2=np.inf):
    """Effective radius R [m] of two spheres (or any two axisymmetric quadratic surfaces), (5.27).

    Guaranteed finite and accurate for R1 in [1e-12, 1e+150], R2 in [1e-12, 1e+150] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    .. math:: 1/R = 1/R_1 + 1/R_2

    Parameters
    ----------
    R1, R2 : float or array_like
        Radii of curvature [m], nonzero; negative for a concave surface, ``inf`` for a plane.
        The sum of the curvatures 1/R1 + 1/R2 must be positive (else the surfaces do not
        touch in a point).

    Returns
    -------
    R : float or ndarray
        Effective radius [m], positive (``inf`` never: two planes are refused).
    """
    R1, R2 = nonzero("R1", R1), nonzero("R2", R2)
    total = 1 / R1 + 1 / R2
    if not (total > 0).all():
        bad = np.broadcast_to(~(total > 0), total.shape)
        idx = np.argwhere(bad)[0] if total.ndim else ()
        r1 = np.broadcast_to(R1, total.shape)[tuple(idx)]
        r2 = np.broadcast_to(R2, total.shape)[tuple(idx)]
        raise ValueError(f"R1 = {float(r1)!r}, R2 = {float(r2)!r}: the sum of the curvatures "
                         "1/R1 + 1/R2 must be > 0 (a concave surface must be flatter than the "
                         "convex one)")
    return result(gen.bodies_effective_radius(R1, R2))  # (5.27)


def _radii_from_curvatures(curvature_1, curvature_2, args, names):
    """(R_1, R_2) from the generated principal curvatures k1 >= k2 of ``args``.

    k2 is printed as 2 det/(trace + root) = det/k1: it is evaluated only where k1 > 0 (a gap
    with k1 <= 0 is refused below, before 0/0 can give a warning)."""
    shape = np.broadcast_shapes(*(np.shape(v) for v in args))
    # the generated forms broadcast by themselves: a flat's inf radii stay scalars
    k1 = np.broadcast_to(np.asarray(curvature_1(*args), dtype=float), shape).copy()
    ok = k1 > 0
    if ok.all():
        k2 = np.broadcast_to(np.asarray(curvature_2(*args), dtype=float), shape).copy()
    else:
        args = np.broadcast_arrays(*args)
        k2 = np.zeros(shape)
        k2[ok] = curvature_2(*(v[ok] for v in args))
    bad = ~(k2 >= 0) | ~(k1 > 0)
    if bad.any():
        args = np.broadcast_arrays(*args)
        i = tuple(int(j) for j in np.argwhere(bad)[0]) if bad.ndim else ()
        given = ", ".join(f"{n} = {float(v[i])!r}" for n, v in zip(names[1], args, strict=True))
        raise ValueError(f"{names[0]}: {given}: the gap is not convex (principal curvatures "
                         f"{float(k1[i])!r}, {float(k2[i])!r} [1/m]); both must be >= 0 "
                         "and the larger > 0 for the bodies to touch in a point or a line")
    R_1 = 1 / k1
    R_2 = np.full(k2.shape, np.inf)
    with np.errstate(over="ignore"):  # k2 below 1/DBL_MAX (cylinders crossed at ~1e-154 rad):
        np.divide(1.0, k2, out=R_2, where=k2 > 0)  # R_2 = inf, the line-contact limit, is right

    return result(R_1), result(R_2)


def principal_radii(R1a, R1b=np.inf, R2a=np.inf, R2b=np.inf, omega=0.0):
    """Principal radii (R_1, R_2) [m] of the gap between two bodies, R_1 <= R_2.

    Guaranteed finite and accurate for R1a in [1e-06, 1e+06], R1b in [1e-06, 1e+06], R2a in [1e-06,
    1e+06], R2b in [1e-06, 1e+06], omega in [-10, 10] (each radius of either sign, or inf;
    ValueError for a gap that is not convex) (SI units; searched by tests/domain_search.py). Beyond
    float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Body i has the principal radii R_ia, R_ib; the first principal directions of the two
    bodies enclose the angle omega. The gap is h = (x, y) H (x, y)^T / 2 with
    H = diag(1/R1a, 1/R1b) + Q(omega) diag(1/R2a, 1/R2b) Q(omega)^T, and its principal
    curvatures are the eigenvalues of H (as in Problem 2; (5.32) for omega = 0). A body of
    revolution has R_a = R_b, a cylinder R_b = inf, a plane both inf.

    Parameters
    ----------
    R1a, R1b, R2a, R2b : float or array_like
        Principal radii of curvature [m], nonzero; negative for concave, ``inf`` for flat.
    omega : float or array_like
        Angle between the first principal directions [rad], any real.

    Returns
    -------
    R_1, R_2 : float or ndarray
        Principal radii of the gap [m]; R_2 = inf for a line contact (parallel cylinders).

    Raises
    ------
    ValueError
        For a zero radius, NaN, or a gap that is not convex (a principal curvature < 0).
    """
    args = [nonzero(n, v) for n, v in (("R1a", R1a), ("R1b", R1b), ("R2a", R2a), ("R2b", R2b))]
    w = as_float("omega", omega)
    if not np.isfinite(w).all():
        raise ValueError(f"omega = {omega!r}: must be finite")
    return _radii_from_curvatures(gen.bodies_principal_curvature_1,
                                  gen.bodies_principal_curvature_2, (*args, w),
                                  ("principal_radii", ("R1a", "R1b", "R2a", "R2b", "omega")))


def crossed_cylinder_radii(R1, R2, alpha):
    """Principal radii (R_1, R_2) [m] of the gap of two cylinders crossed at the angle alpha.

    Guaranteed finite and accurate for R1 in [1e-12, 1e+150], R2 in [1e-12, 1e+150], alpha in [0,
    3.14159] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    (5.32) for alpha = pi/2 (R_1, R_2 = the two cylinder radii); Problem 2 for alpha = pi/4;
    parallel cylinders (alpha = 0 or pi) give R_2 = inf (line contact, (5.34)-(5.37)).

    Parameters
    ----------
    R1, R2 : float or array_like
        Cylinder radii [m], R > 0 (``inf``: a plane).
    alpha : float or array_like
        Angle between the axes [rad], 0 <= alpha <= pi.

    Returns
    -------
    R_1, R_2 : float or ndarray
        Principal radii of the gap [m], R_1 <= R_2.
    """
    R1, R2 = positive("R1", R1, allow_inf=True), positive("R2", R2, allow_inf=True)
    alpha = between("alpha", alpha, 0.0, np.pi, lo_open=False, hi_open=False)
    return _radii_from_curvatures(gen.bodies_crossed_cylinders_curvature_1,
                                  gen.bodies_crossed_cylinders_curvature_2, (R1, R2, alpha),
                                  ("crossed_cylinder_radii", ("R1", "R2", "alpha")))


@representable
def crossed_cylinders_gaussian_radius(R1, R2, alpha):
    """Gaussian radius sqrt(R_1 R_2) = sqrt(R1 R2)/sin(alpha) [m] of two crossed cylinders, (5.33).

    Guaranteed finite and accurate for R1 in [1e-12, 1e+150], R2 in [1e-12, 1e+150], alpha in
    [1e-300, 3.14159] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    R1, R2 : float or array_like
        Cylinder radii [m], R > 0 and finite.
    alpha : float or array_like
        Angle between the axes [rad], 0 < alpha < pi.
    """
    return result(gen.bodies_crossed_cylinders_gaussian_radius(
        positive("R1", R1), positive("R2", R2), between("alpha", alpha, 0.0, np.pi)))


@representable
def gaussian_radius(R1, R2):
    """Gaussian radius R~ = sqrt(R1 R2) [m] of a gap with the principal radii R1, R2, (5.30).

    Guaranteed finite and accurate for R1 in [1e-12, 1e+150], R2 in [1e-12, 1e+150] (SI units;
    searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming
    the inputs.

    Parameters
    ----------
    R1, R2 : float or array_like
        Principal radii of the gap [m], R > 0 and finite.
    """
    return result(gen.bodies_gaussian_radius(positive("R1", R1), positive("R2", R2)))


def gaussian_approx_semi_axes(d, R1, R2):
    """Semi-axes (a, b) = (sqrt(R1 d), sqrt(R2 d)) [m] of the elliptic contact, (5.28).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R1 in [1e-12, 1e+06], R2 in [1e-12,
    1e+06] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    The chapter's rough estimate (its footnote 4): the exact semi-axes follow from elliptic
    integrals and are closer together than these.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R1, R2 : float or array_like
        Principal radii of the gap [m], R > 0 and finite.
    """
    d, R1, R2 = nonnegative("d", d), positive("R1", R1), positive("R2", R2)
    return (result(gen.bodies_gaussian_approx_semi_axis_1(R1, d)),
            result(gen.bodies_gaussian_approx_semi_axis_2(R2, d)))


@representable
def gaussian_approx_area(d, R1, R2):
    """Contact area A = pi sqrt(R1 R2) d [m^2] of the elliptic contact, (5.29) (approximation).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R1 in [1e-12, 1e+06], R2 in [1e-12,
    1e+06] (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    Parameters as :func:`gaussian_approx_semi_axes`.
    """
    return result(gen.bodies_gaussian_approx_area(positive("R1", R1), positive("R2", R2),
                                                nonnegative("d", d)))


@representable
def gaussian_approx_max_pressure(d, R1, R2, E_star):
    """Maximum pressure p0 [Pa] of the elliptic contact: (5.22) with R = R~ (approximation).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R1 in [1e-12, 1e+06], R2 in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], d >= 0.
    R1, R2 : float or array_like
        Principal radii of the gap [m], R > 0 and finite.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.bodies_gaussian_approx_max_pressure(
        positive("E_star", E_star), positive("R1", R1), positive("R2", R2),
        nonnegative("d", d)))


@representable
def gaussian_approx_force(d, R1, R2, E_star):
    """Normal force F [N] of the elliptic contact: (5.23) with R = R~ (approximation).

    Guaranteed finite and accurate for d in {0} U [1e-15, 1000], R1 in [1e-12, 1e+06], R2 in [1e-12,
    1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    The chapter (footnote 5) quotes 2.5 % accuracy up to R1/R2 = 10. Parameters as
    :func:`gaussian_approx_max_pressure`.
    """
    return result(gen.bodies_gaussian_approx_force(
        positive("E_star", E_star), positive("R1", R1), positive("R2", R2),
        nonnegative("d", d)))


@representable
def gaussian_approx_depth_from_force(F, R1, R2, E_star):
    """Indentation depth d [m] of the elliptic contact under the force F [N]: (5.24) with
    R = R~ (approximation), the inverse of :func:`gaussian_approx_force`.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], R1 in [1e-12, 1e+06], R2 in
    [1e-12, 1e+06], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond
    float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], F >= 0.
    R1, R2 : float or array_like
        Principal radii of the gap [m], R > 0 and finite.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    return result(gen.bodies_gaussian_approx_depth_from_force(
        positive("E_star", E_star), nonnegative("F", F), positive("R1", R1),
        positive("R2", R2)))


@representable
def gaussian_approx_pressure(x, y, d, R1, R2, E_star):
    """Pressure p(x, y) = p0 sqrt(1 - x^2/a^2 - y^2/b^2) [Pa] of the elliptic contact, (5.31).

    Guaranteed finite and accurate for x in {0} U [1e-300, 1e+300], y in {0} U [1e-300, 1e+300], d
    in [1e-15, 1000], R1 in [1e-12, 1e+06], R2 in [1e-12, 1e+06], E_star in [0.001, 1e+15] (SI
    units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError
    naming the inputs.

    With the semi-axes (5.28) and the p0 of :func:`gaussian_approx_max_pressure`; 0 outside
    the ellipse. x runs along the principal direction of R1.

    Parameters
    ----------
    x, y : float or array_like
        Coordinates on the surface [m], finite.
    d : float or array_like
        Indentation depth [m], d > 0.
    R1, R2, E_star
        As in :func:`gaussian_approx_max_pressure`.
    """
    x, y = as_float("x", x), as_float("y", y)
    for name, v in (("x", x), ("y", y)):
        if not np.isfinite(v).all():
            raise ValueError(f"{name} must be finite")
    x, y, d, R1, R2, E_star = np.broadcast_arrays(x, y, positive("d", d), positive("R1", R1),
                                                  positive("R2", R2), positive("E_star", E_star))
    # the generated form decides in or out (its Max(0, 1 - x^2/a^2 - y^2/b^2)); it is called
    # only inside the box |x| < 2a, |y| < 2b (5.28), so that no coordinate far outside is
    # squared (y = 1e200 m would overflow); 0 elsewhere
    box = ((np.abs(x) < 2 * gen.bodies_gaussian_approx_semi_axis_1(R1, d))
           & (np.abs(y) < 2 * gen.bodies_gaussian_approx_semi_axis_2(R2, d)))
    p = gen.bodies_gaussian_approx_pressure(E_star, R1, R2, d, np.where(box, x, 0.0),
                                            np.where(box, y, 0.0))  # (5.31)
    return result(np.where(box, p, 0.0))
