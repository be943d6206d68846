"""Stresses under the Hertz pressure: the axis (5.47)-(5.49), the maximum shear, the full field.

Starting points:

- On the axis, the point-force field (5.41)-(5.46) derived in :mod:`hertzmdr.derive.boussinesq`
  superposed over the Hertz pressure p0 (1 - rho^2/a^2)^(1/2) (5.15) as (5.47) prescribes. The
  mean of the kernel over the source angle phi is a function of R = (rho^2 + z^2)^(1/2) alone;
  with rho d(rho) = R dR and p = (p0/a)(c^2 - R^2)^(1/2), c^2 = a^2 + z^2, the substitution
  R = c/(1 + t^2)^(1/2) makes every radial integrand rational in t (t runs from a/z to 0), so
  SymPy integrates it exactly: (5.48) and (5.49) come out, nothing typed in.
- tau_1 = (sigma_rr - sigma_zz)/2 on the axis; its maximum is the root of d(tau_1)/dz
  (:func:`axis_maxima`, 30 digits with mpmath). On the axis the von Mises stress (5.50) is
  |sigma_rr - sigma_zz| = 2 tau_1 (sigma_xx = sigma_yy, no shear), so it peaks at the same depth.
- Off the axis, Huber's (1904) closed form, as given by Johnson, Contact Mechanics (1985),
  eqs. (3.44) (:func:`johnson_field`; typed in, the one literature input), rewritten in the
  oblate spheroidal coordinates of the contact disc, r = a (1 + xi^2)^(1/2) sin(beta),
  z = a xi cos(beta): xi^2 = u/a^2 where u is the positive root of r^2/(a^2 + u) + z^2/u = 1
  (Johnson's u, derived here by ``sp.solve``), and cos(beta) = z/u^(1/2). With eta = cos(beta)
  and chi = sin(beta) passed as arguments (beta itself would lose cos(beta) near the surface
  outside the contact), the a^2/r^2 (1 - eta^3) term of sigma_r, sigma_theta (0/0 on the axis)
  becomes (1 + eta + eta^2) w/(1 + eta), w = 1/(1 + xi^2), and the terms that cancel far away
  and on the axis are grouped into K = 1 - xi atan(1/xi) - w/3 = (2/15) w^2 2F1(1, 2; 7/2; w),
  printed for xi >= 1 as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2 (Pfaff). Every term then
  decays like the point-force field. ``tests/test_stress.py`` checks the form against mpmath
  superposition of the derived (5.41)-(5.46) over the pressure, against Johnson's form at
  50 digits, by equilibrium and the surface tractions on grids, and symbolically: on the axis
  (eta = 1, chi = 0) it is the derived (5.48), (5.49).
- The orthogonal shear |tau_rz| (the quantity of rolling-contact fatigue) is, in these
  variables, p0 xi eta^2 chi/((xi^2 + eta^2)(1 + xi^2)^(1/2)), free of nu. It vanishes on the
  axis (chi = 0), on the surface (xi = 0 under the contact, eta = 0 outside it) and far away,
  so its maximum is an interior critical point; (xi, beta) -> (r, z) is a diffeomorphism of
  the interior, so it is a critical point in (X, C) = (xi^2, eta^2) too. The logarithmic
  derivatives are rational in X, C: SymPy solves them (:func:`orthogonal_shear_maximum`),
  X = (17^(1/2) - 3)/4, C = (5 - 17^(1/2))/2, i.e. r^2 = (7 - 17^(1/2)) a^2/4,
  z^2 = (17^(1/2) - 4) a^2: |tau_rz| = 0.21389 p0 at r = 0.84807 a, z = 0.35087 a.
"""

from __future__ import annotations

from functools import cache

import mpmath as mp
import sympy as sp

from hertzmdr.derive import _cache
from hertzmdr.derive import boussinesq as b
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import F, a, nu, p0, r, symbol, unit_interval, z

TEST = "tests/test_stress.py"

xi = symbol("xi", nonnegative=True)
sxx, syy, szz, sxy, syz, sxz = (symbol(n, real=True) for n in (
    "sigma_xx", "sigma_yy", "sigma_zz", "tau_xy", "tau_yz", "tau_xz"))
eta = symbol("eta", nonnegative=True)  # cos(beta), passed as such: accurate near beta = pi/2
chi = symbol("chi", nonnegative=True)  # sin(beta)
_z = sp.Symbol("z_pos", positive=True)  # z > 0 while integrating along the axis
_R = sp.Symbol("R_pos", positive=True)
_t = sp.Symbol("t_int", positive=True)
_phi = sp.Symbol("phi", real=True)
_rho = sp.Symbol("rho", positive=True)


def _mean_kernel(comp: str) -> sp.Expr:
    """Mean over phi of the point-force stress at (0, 0, z) of a unit force at
    (rho cos phi, rho sin phi, 0), as a function of R = (rho^2 + z^2)^(1/2)."""
    k = b.stresses()[comp].subs(F, 1)
    k = k.subs({b.x: -_rho * sp.cos(_phi), b.y: -_rho * sp.sin(_phi), b.z: _z})
    k = k.subs(sp.sqrt(_rho**2 * sp.sin(_phi) ** 2 + _rho**2 * sp.cos(_phi) ** 2 + _z**2), _R)
    mean = sp.integrate(sp.expand(k), (_phi, 0, 2 * sp.pi)) / (2 * sp.pi)
    return sp.factor(mean.subs(_rho, sp.sqrt(_R**2 - _z**2)))


@cache
def axis_stresses() -> dict[str, sp.Expr]:
    """sigma_zz and sigma_xx = sigma_yy on the axis under the Hertz pressure, by (5.47).

    Derived once (~1.5 s of CPU) and kept in the disk cache of derived relations
    (:mod:`hertzmdr.derive._cache`, keyed by the derive sources; HERTZMDR_DERIVE_CACHE=0
    derives afresh): the test workers, bench_stress.py and the domain search each needed it."""
    return _cache.cached(_axis_stresses_derived, "stress-axis")[0]


def _axis_stresses_derived() -> dict[str, sp.Expr]:
    c = sp.sqrt(a**2 + _z**2)
    R_t = c / sp.sqrt(1 + _t**2)  # R = z at t = a/z, R = c at t = 0
    out = {}
    for comp in ("zz", "xx"):
        # sigma = int_0^a p(rho) mean 2 pi rho d rho, rho d rho = R dR, p = (p0/a) sqrt(c^2 - R^2)
        integrand = 2 * sp.pi * _mean_kernel(comp) * _R * p0 / a * sp.sqrt(c**2 - _R**2)
        integrand = integrand.subs(_R, R_t) * sp.diff(R_t, _t)
        integrand = sp.factor(sp.powsimp(sp.simplify(integrand), force=True))
        val = sp.integrate(integrand, (_t, a / _z, 0))
        out[comp] = sp.simplify(val).subs(_z, z)
    return out


def axis_sigma_rr_stable() -> sp.Expr:
    """sigma_xx on the axis for z >= a, free of the cancellation of (5.49).

    With t = a/z, 1 - atan(t)/t - t^2/(3 (1 + t^2)) = (2/15) t^4 2F1(2, 5/2; 7/2; -t^2) (the
    series term by term), so that (5.49) is p0 [(1 - 2 nu) t^2/(6 (1 + t^2)) - (1 + nu) (2/15)
    t^4 2F1(2, 5/2; 7/2; -t^2)]: the O(t^2) parts of its two terms, which cancel to
    (1 - 2 nu)/6 (entirely at nu = 1/2), are combined exactly.
    """
    t = a / z
    h = sp.hyper([2, sp.Rational(5, 2)], [sp.Rational(7, 2)], -(t**2))
    return p0 * ((1 - 2 * nu) * t**2 / (6 * (1 + t**2))
                 - (1 + nu) * sp.Rational(2, 15) * t**4 * h)


def axis_sigma_zz_stable() -> sp.Expr:
    return -p0 * a**2 / (a**2 + z**2)


def max_shear_axis() -> sp.Expr:
    s = axis_stresses()
    return sp.simplify((s["xx"] - s["zz"]) / 2)


@cache
def axis_maxima(nu_value: str, dps: int = 30) -> tuple[mp.mpf, mp.mpf]:
    """(z/a, tau_1/p0) at the maximum of tau_1 on the axis, the root of d(tau_1)/dz, to ``dps``
    digits. ``nu_value`` is a decimal string (exact: "0.3" means 3/10)."""
    s = sp.Symbol("s", positive=True)
    tau = (max_shear_axis() / p0).subs(z, a * s).subs(a, 1)
    tau = sp.simplify(tau.subs(nu, sp.Rational(nu_value)))
    slope = sp.lambdify(s, sp.diff(tau, s), "mpmath")
    value = sp.lambdify(s, tau, "mpmath")
    with mp.workdps(dps + 10):
        root = mp.findroot(slope, mp.mpf("0.5"))
        out = (+root, value(root))
    with mp.workdps(dps):
        return +out[0], +out[1]


def max_shear_bracket() -> sp.Expr:
    """A depth z_lo (0 < z_lo < the maximum) where d(tau_1)/dz > 0, for every -1 < nu <= 1/2.

    With s = z/a, 4 d(tau_1/p0)/ds = 2 (1 + nu)(atan(1/s) - s/(1 + s^2)) - 6 s/(1 + s^2)^2
    (the derivative of :func:`max_shear_axis`). atan(1/s) >= pi/2 - s, s/(1 + s^2) <= s and
    s/(1 + s^2)^2 <= s make it >= 2 (1 + nu)(pi/2 - 2 s) - 6 s, positive for
    s < pi (1 + nu)/(4 (1 + nu) + 6); half of that bound is z_lo. It tends to 0 with 1 + nu,
    as the maximum does (it reaches the surface at nu = -1: tau_1 = 3 p0/(4 (1 + s^2))). The
    upper end of the bracket is z = 2a for every nu: the slope grows with nu (its nu-term
    is positive) and at nu = 1/2 it is 3 (atan(1/2) - 2/5) - 12/25 < 0 at s = 2.
    """
    return sp.pi * (1 + nu) * a / (8 * (1 + nu) + 12)


@cache
def spheroidal_u() -> sp.Expr:
    """Johnson's u: the positive root of r^2/(a^2 + u) + z^2/u = 1 (a quadratic in u)."""
    u = sp.Symbol("u", positive=True)
    roots = sp.solve(sp.Eq(r**2 / (a**2 + u) + z**2 / u, 1), u)
    probe = {a: 1, r: sp.Rational(1, 2), z: sp.Rational(1, 3)}
    (pos,) = [e for e in roots if e.subs(probe) > 0]
    return pos


def von_mises() -> tuple[sp.Expr, sp.Expr]:
    """sqrt(3 J2) from the deviator of the stress tensor, and the printed (5.50)."""
    sig = sp.Matrix([[sxx, sxy, sxz], [sxy, syy, syz], [sxz, syz, szz]])
    dev = sig - sig.trace() / 3 * sp.eye(3)
    j2 = sum(dev[i, j] ** 2 for i in range(3) for j in range(3)) / 2
    derived = sp.sqrt(sp.factor(sp.expand(3 * j2)))
    printed = sp.sqrt((sxx - syy) ** 2 + (sxx - szz) ** 2 + (szz - syy) ** 2
                      + 6 * (sxy**2 + sxz**2 + syz**2)) / sp.sqrt(2)
    return derived, printed


def hertz_field(far: bool | str = False) -> dict[str, sp.Expr]:
    """Huber's stresses (Johnson 1985, (3.44)) in the spheroidal variables (xi, beta).

    eta = cos(beta), chi = sin(beta), w = 1/(1 + xi^2): Johnson's (a^2/r^2)(1 - eta^3) is
    (1 + eta + eta^2) w/(1 + eta), u(1 - nu)/(a^2 + u) = (1 - nu)(1 - w); regrouped, the terms
    of sigma_rr and sigma_theta that cancel on the axis and far away are combined into
    K = 1 - xi atan(1/xi) - w/3, which is (2/15) w^2 2F1(1, 2; 7/2; w). With ``far="hyper"``
    K is (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2 (Pfaff), free of the cancellation at
    xi >= 1; with ``far=True`` as written; else with atan(1/xi) = pi/2 - atan(xi), finite at
    xi = 0 (accurate for xi < 1).
    """
    if far == "scaled":
        # the "hyper" form in powers of v = 1/xi, printed as xi**(-1.0) powers: xi^4 of its
        # denominators would overflow for xi > 1e77 (z = 1e78 a), the powers of v underflow
        v = sp.Symbol("v", positive=True)
        wv = v**2 / (1 + v**2)  # w = 1/(1 + xi^2)
        k = (sp.Rational(2, 15) * wv * v**2
             * sp.hyper([1, sp.Rational(3, 2)], [sp.Rational(7, 2)], -(v**2)))
        out = {
            "rr": p0 * ((1 - 2 * nu) * wv / (3 * (1 + eta))
                        - eta * chi**2 * v**2 / ((1 + v**2) * (1 + eta**2 * v**2))
                        - (1 + nu) * eta * k),
            "tt": p0 * ((1 - 2 * nu) * wv * (eta**2 + eta - 1) / (3 * (1 + eta))
                        - (1 + nu) * eta * k),
        }
        return {key: e.subs(v, sp.Pow(xi, -1.0)) for key, e in out.items()}
    w = 1 / (1 + xi**2)
    if far == "hyper":
        k = (sp.Rational(2, 15) * w / xi**2
             * sp.hyper([1, sp.Rational(3, 2)], [sp.Rational(7, 2)], -1 / xi**2))
    elif far:
        k = 1 - xi * sp.atan(1 / xi) - w / 3
    else:
        k = 1 - xi * (sp.pi / 2 - sp.atan(xi)) - w / 3  # atan(1/xi), finite at xi = 0
    return {
        "rr": p0 * ((1 - 2 * nu) * w / (3 * (1 + eta))
                    - eta * xi**2 * chi**2 * w / (xi**2 + eta**2) - (1 + nu) * eta * k),
        "tt": p0 * ((1 - 2 * nu) * w * (eta**2 + eta - 1) / (3 * (1 + eta))
                    - (1 + nu) * eta * k),
        "zz": -p0 * eta**3 / (xi**2 + eta**2),
        "rz": -p0 * xi * eta**2 * chi / ((xi**2 + eta**2) * sp.sqrt(1 + xi**2)),
    }


@cache
def orthogonal_shear_maximum() -> dict[str, sp.Expr]:
    """The largest |tau_rz| under the Hertz pressure: value/p0, r/a and z/a at it, exactly.

    |tau_rz|/p0 of :func:`hertz_field` in X = xi^2 and C = eta^2 = cos^2(beta) (chi^2 = 1 - C)
    is X^(1/2) C (1 - C)^(1/2)/((X + C)(1 + X)^(1/2)); the numerators of d(log)/dX and
    d(log)/dC are polynomials, whose one root with X, C in (0, 1) SymPy finds. The point is
    r = a ((1 + X)(1 - C))^(1/2), z = a (X C)^(1/2) (the spheroidal map).
    """
    X, C = sp.symbols("X_sq C_sq", positive=True)
    tau = -hertz_field()["rz"] / p0
    tau = tau.subs(chi, sp.sqrt(1 - C)).subs({xi: sp.sqrt(X), eta: sp.sqrt(C)})
    log_tau = sp.expand_log(sp.log(tau), force=True)
    eqs = [sp.numer(sp.together(sp.diff(log_tau, v))) for v in (X, C)]
    (sol,) = [s_ for s_ in sp.solve(eqs, [X, C], dict=True)
              if all(0 < s_[v] < 1 for v in (X, C))]
    xs, cs = (sp.radsimp(sp.expand(sol[v])) for v in (X, C))
    return {"value": sp.radsimp(sp.simplify(tau.subs({X: xs, C: cs}))),
            "r": sp.sqrt(sp.expand((1 + xs) * (1 - cs))), "z": sp.sqrt(sp.expand(xs * cs)),
            "X": xs, "C": cs}


def johnson_field() -> dict[str, sp.Expr]:
    """Johnson's (3.44) as printed there, in (r, z, u) with u = u(r, z) (for the axis check)."""
    u = spheroidal_u()
    e = z / sp.sqrt(u)
    arc = sp.sqrt(u) / a * sp.atan(a / sp.sqrt(u))
    first = (1 - 2 * nu) / 3 * a**2 / r**2 * (1 - e**3)
    return {
        "rr": p0 * (first + e**3 * a**2 * u / (u**2 + a**2 * z**2)
                    + e * (u * (1 - nu) / (a**2 + u) + (1 + nu) * arc - 2)),
        "tt": p0 * (-first - e * (2 * nu + u * (1 - nu) / (a**2 + u) - (1 + nu) * arc)),
        "zz": -p0 * e**3 * a**2 * u / (u**2 + a**2 * z**2),
        "rz": -p0 * r * z**2 / (u**2 + a**2 * z**2) * a**2 * sp.sqrt(u) / (a**2 + u),
    }


#: relations printed together as one function as well (``codegen.render_fused``): the Hertz
#: field's components share most of their work (issue 18: the field on 10^6 points)
FUSED = {
    "stress_hertz_field": ("stress_hertz_sigma_rr", "stress_hertz_sigma_tt",
                           "stress_hertz_sigma_zz", "stress_hertz_tau_rz"),
    "stress_hertz_field_far": ("stress_hertz_sigma_rr_far", "stress_hertz_sigma_tt_far"),
    "stress_spheroidal": ("stress_spheroidal_u", "stress_spheroidal_u_inside",
                          "stress_spheroidal_cos_beta_inside"),
}


def relations() -> list[Relation]:
    s = axis_stresses()
    printed_zz = -p0 / (1 + z**2 / a**2)  # (5.48)
    printed_xx = -p0 * ((1 + nu) * (1 - z / a * sp.atan(a / z))
                        - sp.Rational(1, 2) / (1 + z**2 / a**2))  # (5.49)
    tau = max_shear_axis()
    far = {z: a / unit_interval()}  # z > a, where the stable forms are used
    stable_xx = axis_sigma_rr_stable()
    why_xx = ("(5.49) subtracts terms of size 1 to leave one of size (a/z)^2 (of size (a/z)^4 at "
              "nu = 1/2); 1 - atan(t)/t - t^2/(3(1 + t^2)) is written as (2/15) t^4 "
              "2F1(2, 5/2; 7/2; -t^2), t = a/z, used for z >= a")
    u = spheroidal_u()
    inside = {r: a * unit_interval("t_r"),
              z: a * unit_interval("t_z") * sp.sqrt(1 - unit_interval("t_r") ** 2)}
    field = hertz_field()
    far_field = hertz_field(far="scaled")
    far_derived = hertz_field(far=True)
    q_st = (r - a) * (r + a) + z**2
    disc_st = sp.sqrt(q_st**2 + 4 * a**2 * z**2)
    outside = {r: a / unit_interval("t_r"), z: a * unit_interval("t_z")}
    lit = "Huber (1904) as given by Johnson (1985), eqs. (3.44), in spheroidal variables"
    fld = f"{TEST}::test_hertz_field_by_superposition"
    vm, vm_printed = von_mises()
    rels = [
        Relation("stress_von_mises", "(5.50)", vm, (sxx, syy, szz, sxy, syz, sxz),
                 "von Mises equivalent stress [Pa] of the stress tensor",
                 "sqrt(3 J2), J2 the second invariant of the stress deviator",
                 f"{TEST}::test_von_mises_invariant", printed=vm_printed,
                 stable=vm_printed, stable_why="the expanded 3 J2 subtracts products of the "
                 "stresses and rounds below 0 for a nearly hydrostatic state (sqrt: NaN at the "
                 "centre of a Hertz contact with nu = 1/2); (5.50) is a sum of squares"),
        Relation("stress_axis_sigma_zz", "(5.48)", s["zz"], (a, p0, z),
                 "normal stress sigma_zz [Pa] on the axis under the Hertz pressure",
                 "(5.43) superposed over (5.15) along the axis, (5.47)",
                 f"{TEST}::test_axis_stresses_by_superposition", printed=printed_zz,
                 stable=axis_sigma_zz_stable(), stable_why="one division, no cancellation"),
        Relation("stress_axis_sigma_xx", "(5.49)", s["xx"], (a, nu, p0, z),
                 "radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure, "
                 "the form of (5.49) (for z < a)",
                 "(5.41) superposed over (5.15) along the axis",
                 f"{TEST}::test_axis_stresses_by_superposition", printed=printed_xx,
                 domain={z: a * unit_interval()}),
        Relation("stress_axis_sigma_xx_deep", "(5.49)", s["xx"], (a, nu, p0, z),
                 "radial stress sigma_xx = sigma_yy [Pa] on the axis under the Hertz pressure "
                 "(for z >= a)", "(5.41) superposed over (5.15) along the axis",
                 f"{TEST}::test_axis_stresses_by_superposition", printed=printed_xx,
                 stable=stable_xx, stable_why=why_xx, domain=far),
        Relation("stress_axis_max_shear", "Fig. 5.8", tau, (a, nu, p0, z),
                 "maximum shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis under "
                 "the Hertz pressure", "(5.48), (5.49)",
                 f"{TEST}::test_axis_maximum_shear"),
        Relation("stress_axis_max_shear_slope", "Fig. 5.8", sp.diff(tau, z), (a, nu, p0, z),
                 "d(tau_1)/dz [Pa/m] on the axis under the Hertz pressure; its root is the "
                 "depth of the maximum shear stress", "the derivative of tau_1",
                 f"{TEST}::test_axis_maximum_shear"),
        Relation("stress_axis_max_shear_bracket", "Fig. 5.8", max_shear_bracket(), (a, nu),
                 "depth z_lo [m] on the axis where d(tau_1)/dz > 0 for -1 < nu <= 1/2: the "
                 "lower end of the bracket [z_lo, 2a] of the maximum shear stress",
                 "lower bounds of the terms of d(tau_1)/dz (stress_axis_max_shear_slope)",
                 f"{TEST}::test_axis_maximum_shear_bracket"),
        Relation("stress_spheroidal_u", "Johnson (1985), (3.44)", u, (a, r, z),
                 "Johnson's u [m^2], the root of r^2/(a^2 + u) + z^2/u = 1 (for "
                 "r^2 + z^2 >= a^2)", "the oblate spheroid through (r, z)",
                 f"{TEST}::test_spheroidal_coordinates",
                 stable=(q_st + disc_st) / 2, stable_why="the expanded discriminant cancels "
                 "near the contact edge; q = (r - a)(r + a) + z^2 keeps it exact",
                 domain=outside),
        Relation("stress_spheroidal_u_inside", "Johnson (1985), (3.44)", u, (a, r, z),
                 "Johnson's u [m^2] for r^2 + z^2 < a^2",
                 "the oblate spheroid through (r, z)", f"{TEST}::test_spheroidal_coordinates",
                 stable=2 * a**2 * z**2 / (disc_st - q_st),
                 stable_why="(q + D)/2 cancels for q = r^2 + z^2 - a^2 < 0; "
                 "written as 2 a^2 z^2/(D - q)", domain=inside),
        Relation("stress_spheroidal_cos_beta_inside", "Johnson (1985), (3.44)",
                 sp.sqrt((disc_st - q_st) / 2) / a, (a, r, z),
                 "cos(beta) = z/u^(1/2) [1] for r^2 + z^2 < a^2 (finite at z = 0)",
                 "z/u^(1/2) with u = 2 a^2 z^2/(D - q) (stress_spheroidal_u_inside): z cancels",
                 f"{TEST}::test_spheroidal_coordinates"),
    ]
    tmax = orthogonal_shear_maximum()
    ortho = f"{TEST}::test_orthogonal_shear_maximum_by_superposition"
    origin = "the root of the gradient of tau_rz (Huber's field in spheroidal variables)"
    rels += [
        Relation("stress_hertz_max_orthogonal_shear", "Fig. 5.9", p0 * tmax["value"], (p0,),
                 "the largest orthogonal shear |tau_rz| [Pa] under the Hertz pressure (any nu)",
                 origin, ortho, stable=p0 * sp.sqrt(2) * (5 - sp.sqrt(17)) ** sp.Rational(3, 2)
                 / (2 * sp.sqrt(3 * sp.sqrt(17) - 5)),
                 stable_why="the solved form subtracts 7 34^(1/2) from 31 2^(1/2) (a factor 14 "
                 "of cancellation); this one has 5 - 17^(1/2) = 0.88 at worst"),
        Relation("stress_hertz_max_orthogonal_shear_r", "Fig. 5.9", a * tmax["r"], (a,),
                 "distance r [m] from the axis of the largest |tau_rz| under the Hertz "
                 "pressure", origin, ortho),
        Relation("stress_hertz_max_orthogonal_shear_z", "Fig. 5.9", a * tmax["z"], (a,),
                 "depth z [m] of the largest |tau_rz| under the Hertz pressure", origin, ortho,
                 stable=a / sp.sqrt(4 + sp.sqrt(17)), stable_why="17^(1/2) - 4 = 0.12 cancels "
                 "a factor 33; it is 1/(17^(1/2) + 4)"),
    ]
    for comp, what in (("rr", "radial stress sigma_rr"), ("tt", "hoop stress sigma_theta"),
                       ("zz", "normal stress sigma_zz"), ("rz", "shear stress tau_rz")):
        name = {"rr": "sigma_rr", "tt": "sigma_tt", "zz": "sigma_zz", "rz": "tau_rz"}[comp]
        args = {"rr": (nu, p0, xi, eta, chi), "tt": (nu, p0, xi, eta), "zz": (p0, xi, eta),
                "rz": (p0, xi, eta, chi)}[comp]
        rels.append(Relation(
            f"stress_hertz_{name}", "Fig. 5.9", field[comp], args,
            f"{what} [Pa] under the Hertz pressure at the spheroidal coordinates (xi, beta) "
            "of the contact disc, eta = cos(beta), chi = sin(beta)"
            + (" (for xi < 1)" if comp in ("rr", "tt") else ""),
            lit, fld))
        if comp in ("rr", "tt"):
            rels.append(Relation(
                f"stress_hertz_{name}_far", "Fig. 5.9", far_derived[comp], args,
                f"{what} [Pa] under the Hertz pressure at (xi, beta), for xi >= 1",
                lit, fld, stable=far_field[comp], domain={xi: 1 / unit_interval()},
                stable_why="1 - xi atan(1/xi) - w/3 cancels to O(1/xi^4) far away; written "
                "as (2/15) w 2F1(1, 3/2; 7/2; -1/xi^2)/xi^2, and every term in powers of "
                "1/xi (xi^4 overflows for xi > 1e77)"))
    return rels
