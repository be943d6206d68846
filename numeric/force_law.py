"""Force laws F = K d^n and stiffness laws dF/dd = K_k d^(n - 1) of the contacts whose
force-depth relation is a power law: what a discrete-element code consumes (docs/dem.md).

Every function takes floats or NumPy arrays in SI units, validates them and returns a
:class:`Law` of the generated prefactors and exponents (derive/force_law.py: the logarithmic
slope d F'/F of each family's force and F/d^n, so nothing here retypes a formula).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import between, nonnegative, positive, result

__all__ = ["Law", "cone", "ellipse", "flat_punch", "hertz", "line", "power_law"]


@dataclass(frozen=True)
class Law:
    """F = K d^n and dF/dd = K_k d^(n_k), n_k = n - 1, K_k = n K.

    Attributes
    ----------
    K : float or ndarray
        Prefactor [N/m^n] (a line contact: per unit length, [N/m^(n+1)]).
    n : float or ndarray
        Exponent [1].
    stiffness_K : float or ndarray
        Prefactor of the stiffness [N/m^n] (a line contact: per unit length).
    stiffness_n : float or ndarray
        Exponent of the stiffness, n - 1 [1].
    """

    K: object
    n: object
    stiffness_K: object
    stiffness_n: object

    def force(self, d):
        """F = K d^n [N] at depths d [m], 0 <= d < inf (a line contact: F/L [N/m])."""
        return self.K * nonnegative("d", d) ** self.n

    def stiffness(self, d):
        """dF/dd = K_k d^(n_k) [N/m] at depths d [m], 0 <= d < inf (a line contact: per
        unit length)."""
        return self.stiffness_K * nonnegative("d", d) ** self.stiffness_n


def _law(K, n, Kk, nk) -> Law:
    return Law(result(K), result(np.asarray(n, float) * 1.0), result(Kk),
               result(np.asarray(nk, float) * 1.0))


def hertz(R, E_star) -> Law:
    """Hertz (5.23): K = (4/3) E* R^(1/2), n = 3/2; K_k = 2 E* R^(1/2), n_k = 1/2.

    Parameters
    ----------
    R : float or array_like
        Effective radius [m], R > 0 (5.27).
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0 (5.26).
    """
    R, E = positive("R", R), positive("E_star", E_star)
    return _law(gen.force_law_hertz_prefactor(E, R), gen.force_law_hertz_exponent(),
                gen.force_law_hertz_stiffness_prefactor(E, R),
                gen.force_law_hertz_stiffness_exponent())


def cone(theta, E_star) -> Law:
    """Rigid cone (5.40): K = (2/pi) E* cot(theta), n = 2.

    Parameters
    ----------
    theta : float or array_like
        Angle between the cone's surface and the plane [rad], 0 < theta < pi/2 (5.38).
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    th, E = between("theta", theta, 0.0, np.pi / 2), positive("E_star", E_star)
    return _law(gen.force_law_cone_prefactor(E, th), gen.force_law_cone_exponent(),
                gen.force_law_cone_stiffness_prefactor(E, th),
                gen.force_law_cone_stiffness_exponent())


def flat_punch(a, E_star) -> Law:
    """Flat rigid punch (Problem 7(a)): K = 2 E* a, n = 1 (a constant stiffness, n_k = 0).

    Parameters
    ----------
    a : float or array_like
        Punch radius [m], a > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    a, E = positive("a", a), positive("E_star", E_star)
    return _law(gen.force_law_punch_prefactor(E, a), gen.force_law_punch_exponent(),
                gen.force_law_punch_stiffness_prefactor(E, a),
                gen.force_law_punch_stiffness_exponent())


def power_law(c_n, n, E_star) -> Law:
    """Power-law profile f = c_n r^n (Problem 7(d)): n_F = (n + 1)/n,
    K = 2n/(n + 1) E* (kappa_n c_n)^(-1/n).

    Parameters
    ----------
    c_n : float or array_like
        Coefficient of the profile [m^(1-n)], c_n > 0.
    n : float or array_like
        Exponent of the profile [1], n > 0.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    from hertzmdr.numeric import powerlaw

    c, nn, E = positive("c_n", c_n), positive("n", n), positive("E_star", E_star)
    k = powerlaw.kappa(nn)
    return _law(gen.force_law_powerlaw_prefactor(E, c, k, nn),
                gen.force_law_powerlaw_exponent(nn),
                gen.force_law_powerlaw_stiffness_prefactor(E, c, k, nn),
                gen.force_law_powerlaw_stiffness_exponent(nn))


def line(E_star) -> Law:
    """Line contact per unit length (5.34): F/L = (pi/4) E* d, n = 1, with d the chapter's
    conventional depth of (5.35), a = sqrt(R d); the approach of two cylinders' axes adds a
    logarithmic term in their size, which this law does not contain.

    Parameters
    ----------
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    E = positive("E_star", E_star)
    return _law(gen.force_law_line_prefactor(E), gen.force_law_line_exponent(),
                gen.force_law_line_stiffness_prefactor(E),
                gen.force_law_line_stiffness_exponent())


def ellipse(R1, R2, E_star) -> Law:
    """Exact elliptical contact: F = K d^(3/2) with K of the elliptic-integral solution
    (derive/ellipse.py), the axis ratio from :func:`hertzmdr.numeric.ellipse.axis_ratio`.

    Parameters
    ----------
    R1, R2 : float or array_like
        Principal radii of the gap [m], > 0, 1e-8 <= R1/R2 <= 1e8.
    E_star : float or array_like
        Effective modulus [Pa], E_star > 0.
    """
    from hertzmdr.numeric import ellipse as ell

    t = np.asarray(ell.axis_ratio(R1, R2))
    Rmaj = np.maximum(positive("R1", R1), positive("R2", R2))
    E = positive("E_star", E_star)
    return _law(gen.force_law_ellipse_prefactor(E, Rmaj, t), gen.force_law_ellipse_exponent(),
                gen.force_law_ellipse_stiffness_prefactor(E, Rmaj, t),
                gen.force_law_ellipse_stiffness_exponent())
