"""Elliptical Hertz contact of a quadratic gap x^2/(2 R1) + y^2/(2 R2), (5.28)-(5.33).

Exact: the contact is the ellipse with semi-axes a (along x, the direction of R1) and b (along
y), the pressure is ellipsoidal (5.31), and the axis ratio follows from R1/R2 through the
eccentricity equation, derived in :mod:`hertzmdr.derive.ellipse` with the complete elliptic
integrals K(m), E(m) of the parameter m = e^2 = 1 - (b/a)^2 (SciPy's and SymPy's convention,
not the modulus e). That equation has no closed form: :func:`axis_ratio` solves it by bisection
in log(b/a), bracketed for every R1/R2 >= 1, stable in the circular limit R1/R2 -> 1 (where the
K, E form is 0/0: the generated code uses a hypergeometric form without cancellation) and up to
R1/R2 = 1e8. The generated code takes m = 1 - t^2 (t = b/a) in float64, which costs about
1e-16 (R1/R2) log(R1/R2) in relative accuracy: 1e-12 at R1/R2 = 1e4, 1e-8 at 1e8.

The chapter's Gaussian-radius approximation (5.28)-(5.31) stays available beside it
(``model="gaussian"`` of :func:`solve`; :func:`gaussian_radius` is
:func:`hertzmdr.numeric.bodies.gaussian_radius`): it is derived once, with the other two-body
relations, in :mod:`hertzmdr.derive.bodies` (``bodies_gaussian_*``).

Two elastic bodies: pass ``E_star`` (5.26) and the principal radii R1, R2 of the gap (the
relative curvatures of the two surfaces; crossed cylinders (5.32): their radii).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, nonnegative, positive, result
from hertzmdr.numeric.bodies import gaussian_radius  # (5.30): re-exported, owned by bodies

__all__ = ["EllipticContact", "solve", "axis_ratio", "eccentricity", "gaussian_radius",
           "MAX_RADIUS_RATIO"]

#: largest max(R1, R2)/min(R1, R2) accepted: beyond it (b/a < 3e-5) the float64 argument
#: m = 1 - (b/a)^2 of the elliptic integrals leaves less than 8 digits, and the contact is a line
#: contact for any practical purpose (Chapter 5 (E)).
MAX_RADIUS_RATIO = 1e8


def _ratio(R1, R2) -> np.ndarray:
    R1, R2 = positive("R1", R1), positive("R2", R2)
    q = np.maximum(R1, R2) / np.minimum(R1, R2)
    if np.any(q > MAX_RADIUS_RATIO):
        bad = np.broadcast_to(q, np.broadcast(R1, R2).shape)
        i = np.unravel_index(np.argmax(bad > MAX_RADIUS_RATIO), bad.shape)
        raise ValueError(f"R1/R2 = {float(bad[i])!r} (or its inverse) is out of range; valid: "
                         f"1/{MAX_RADIUS_RATIO:g} <= R1/R2 <= {MAX_RADIUS_RATIO:g}")
    return q


def axis_ratio(R1, R2):
    """Axis ratio b/a <= 1 (minor over major semi-axis) of the exact elliptical contact.

    Guaranteed finite and accurate for R1 in [1e-12, 1e+06], q in [1, 1e+08], q = max(R1,
    R2)/min(R1, R2) (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.

    Solves R_major/R_minor = ellipse_radius_ratio(t) for t = b/a: the ratio of the principal
    radii fixes the shape of the contact, independently of depth, force and modulus.

    Parameters
    ----------
    R1, R2 : float or array_like
        Principal radii of curvature of the gap [m], > 0, with 1e-8 <= R1/R2 <= 1e8.

    Returns
    -------
    float or ndarray
        b/a in (0, 1]; 1 for R1 = R2 (the circle).

    Notes
    -----
    f(u) = log rho(e^u) - log(R1/R2), rho = ``ellipse_radius_ratio``, decreases monotonically
    from +inf (u -> -inf) to -log(q) <= 0 at u = 0 (t = 1, rho = 1), q = R_major/R_minor.
    For small t, rho(t) ~ 1/(t^2 (log(4/t) - 1)), so rho > q at t = (q (2 + log q))^(-1/2):
    the root is bracketed in [-log(q (2 + log q))/2, 0] (tests/test_ellipse.py checks the
    bracket over 1 <= q <= 1e8) and bisection (64 halvings of an interval of width < 11)
    reaches it to the last bit of t.
    """
    q = np.asarray(_ratio(R1, R2), dtype=float)
    lo = -0.5 * np.log(q * (2 + np.log(q)))  # f(lo) > 0
    hi = np.zeros_like(q)  # f(hi) <= 0
    logq = np.log(q)
    f_lo = np.log(gen.ellipse_radius_ratio(np.exp(lo))) - logq
    if np.any(f_lo <= 0):  # never for 1 <= q <= 1e8; kept as a guard against a silent bracket
        raise RuntimeError("axis_ratio: the eccentricity equation is not bracketed")
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        f_mid = np.log(gen.ellipse_radius_ratio(np.exp(mid))) - logq
        pos = f_mid > 0
        lo = np.where(pos, mid, lo)
        hi = np.where(pos, hi, mid)
    return result(np.exp(0.5 * (lo + hi)))


def eccentricity(R1, R2):
    """Eccentricity e = sqrt(1 - (b/a)^2) of the exact contact ellipse; m = e^2 is SciPy's
    parameter of ellipk/ellipe. Parameters as :func:`axis_ratio`.

    Guaranteed finite and accurate for R1 in [1e-12, 1e+06], q in [1, 1e+08], q = max(R1,
    R2)/min(R1, R2) (SI units; searched by tests/domain_search.py). Beyond float64 (|result| >
    1.8e308): OverflowError naming the inputs.
    """
    t = np.asarray(axis_ratio(R1, R2))
    return result(np.sqrt((1 - t) * (1 + t)))


@dataclass(frozen=True)
class EllipticContact:
    """The state of an elliptical Hertz contact (arrays when :func:`solve` got arrays).

    Attributes
    ----------
    a, b : semi-axes [m] along x (direction of R1) and y (direction of R2).
    depth : indentation depth d [m].
    force : normal force F [N].
    max_pressure : central pressure p0 [Pa] of (5.31).
    mean_pressure : F/(pi a b) [Pa].
    stiffness : differential stiffness dF/dd [N/m].
    area : contact area pi a b [m^2].
    R1, R2, E_star : the inputs [m], [m], [Pa].
    model : ``"exact"`` or ``"gaussian"``.
    """

    a: np.ndarray
    b: np.ndarray
    depth: np.ndarray
    force: np.ndarray
    max_pressure: np.ndarray
    mean_pressure: np.ndarray
    stiffness: np.ndarray
    area: np.ndarray
    R1: np.ndarray
    R2: np.ndarray
    E_star: np.ndarray
    model: str

    def pressure(self, x, y):
        """Pressure p(x, y) = p0 sqrt(1 - x^2/a^2 - y^2/b^2) [Pa], 0 outside, (5.31).

        Guaranteed finite and accurate for R1 in [1e-12, 1e+06], q in [1, 1e+08], E_star in [0.001,
        1e+15], depth in [1e-15, 1000], x in {0} U [1e-300, 1e+300], y in {0} U [1e-300, 1e+300], q
        = max(R1, R2)/min(R1, R2), for the contact of solve(..., depth=depth) (SI units; searched by
        tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the
        inputs.

        Parameters
        ----------
        x, y : float or array_like
            Surface coordinates [m] from the centre, x along R1, y along R2; they broadcast
            against the contact's arrays.
        """
        x, y = as_float("x", x), as_float("y", y)
        x, y, a, b = np.broadcast_arrays(x, y, self.a, self.b)
        # the generated forms decide in or out (their Max(0, 1 - x^2/a^2 - y^2/b^2)); they are
        # called only inside the box |x| < 2a, |y| < 2b, so that no coordinate far outside is
        # squared (y = 1e200 m would overflow); 0 elsewhere
        box = (np.abs(x) < 2 * a) & (np.abs(y) < 2 * b)
        x, y = np.where(box, x, 0.0), np.where(box, y, 0.0)
        if self.model == "gaussian":  # (5.31) with (5.28), (5.22) and R~ (5.30)
            p = gen.bodies_gaussian_approx_pressure(self.E_star, self.R1, self.R2, self.depth,
                                                    x, y)
            return result(np.where(box, p, 0.0))
        major_x = np.asarray(self.R1 >= self.R2)  # the generated form has x along the major axis
        xm, ym = np.where(major_x, x, y), np.where(major_x, y, x)
        Rmaj = np.maximum(self.R1, self.R2)
        t = np.minimum(self.a, self.b) / np.maximum(self.a, self.b)
        p = gen.ellipse_pressure(self.E_star, Rmaj, self.depth, t, xm, ym)  # (5.31)
        return result(np.where(box, p, 0.0))


def solve(R1, R2, E_star, *, depth=None, force=None, model: str = "exact") -> EllipticContact:
    """Elliptical Hertz contact of the gap x^2/(2 R1) + y^2/(2 R2), depth- or force-controlled.

    Guaranteed finite and accurate for R1 in [1e-12, 1e+06], q in [1, 1e+08], E_star in [0.001,
    1e+15], depth in {0} U [1e-15, 1000], q = max(R1, R2)/min(R1, R2) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    R1, R2 : float or array_like
        Principal radii of curvature of the gap (5.32) [m], > 0, 1e-8 <= R1/R2 <= 1e8.
    E_star : float or array_like
        Effective modulus [Pa], > 0 (5.26).
    depth : float or array_like, optional
        Indentation depth d [m], >= 0. Give exactly one of ``depth`` and ``force``.
    force : float or array_like, optional
        Normal force F [N], >= 0.
    model : {"exact", "gaussian"}
        ``"exact"``: the elliptic-integral solution. ``"gaussian"``: the chapter's estimate,
        a = sqrt(R1 d), b = sqrt(R2 d) (5.28), A = pi R~ d (5.29), and the Hertz force, pressure
        and stiffness with R -> R~ = sqrt(R1 R2) (5.30), (5.23).

    Returns
    -------
    EllipticContact
    """
    if (depth is None) == (force is None):
        raise ValueError("give exactly one of depth= and force=")
    if model not in ("exact", "gaussian"):
        raise ValueError(f"model = {model!r} is out of range; valid: 'exact', 'gaussian'")
    _ratio(R1, R2)  # validates R1, R2 and their ratio
    R1, R2, E = positive("R1", R1), positive("R2", R2), positive("E_star", E_star)
    if model == "gaussian":  # the chapter's estimate, owned by derive/bodies.py
        Rt = gen.bodies_gaussian_radius(R1, R2)  # (5.30)
        d = (nonnegative("depth", depth) if force is None
             else gen.bodies_gaussian_approx_depth_from_force(
                 E, nonnegative("force", force), R1, R2))  # (5.24) with R~
        a = gen.bodies_gaussian_approx_semi_axis_1(R1, d)  # (5.28)
        b = gen.bodies_gaussian_approx_semi_axis_2(R2, d)
        F = gen.bodies_gaussian_approx_force(E, R1, R2, d)  # (5.23) with R~
        p0 = gen.bodies_gaussian_approx_max_pressure(E, R1, R2, d)  # (5.22) with R~
        pm, k = gen.hertz_mean_pressure(E, Rt, d), gen.hertz_stiffness(E, Rt, d)  # R -> R~
        area = gen.bodies_gaussian_approx_area(R1, R2, d)  # (5.29)
    else:
        t = np.asarray(axis_ratio(R1, R2))
        Rmaj = np.maximum(R1, R2)  # a_major lies along the larger radius
        d = (nonnegative("depth", depth) if force is None
             else gen.ellipse_depth_from_force(E, nonnegative("force", force), Rmaj, t))
        a_maj, b_min = gen.ellipse_semi_major(Rmaj, d, t), gen.ellipse_semi_minor(Rmaj, d, t)
        along_x = R1 >= R2
        a, b = np.where(along_x, a_maj, b_min), np.where(along_x, b_min, a_maj)
        F = gen.ellipse_force(E, Rmaj, d, t)
        p0 = gen.ellipse_max_pressure(E, Rmaj, d, t)
        pm = gen.ellipse_mean_pressure(E, Rmaj, d, t)
        k = gen.ellipse_stiffness(E, Rmaj, d, t)
        area = gen.ellipse_area(Rmaj, d, t)
    shape = np.broadcast(R1, R2, E, d).shape
    out = {name: np.broadcast_to(v, shape) * 1.0 for name, v in dict(
        a=a, b=b, depth=d, force=F, max_pressure=p0, mean_pressure=pm, stiffness=k,
        area=area, R1=R1, R2=R2, E_star=E).items()}
    return EllipticContact(**{k_: result(v) for k_, v in out.items()}, model=model)
