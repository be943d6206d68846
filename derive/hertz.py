"""Hertz: a rigid sphere (or an effective sphere, (5.26)-(5.27)) on an elastic half-space.

Starting point: the displacement (5.16) under the pressure p0*(1 - r^2/a^2)^(1/2), derived in
:mod:`hertzmdr.derive.pressures` from the Boussinesq kernel, must equal the sphere's
displacement d - r^2/(2R) (5.18) at every r of the contact: the matching condition (5.19).
Comparing the coefficients of r^0 and r^2 gives (5.20), hence (5.21) and (5.22); the force
(5.23) is the pressure integral (5.17); (5.24) inverts (5.23); the energy (5.25) integrates
F = dU/dd; the stiffness is dF/dd (Problem 5).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import pressures
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, R, a, d, p0, r, unit_interval

TEST = "tests/test_hertz.py"


@cache
def solution() -> dict[str, sp.Expr]:
    """a, p0, F, ... of the Hertz contact as functions of (E*, R, d), derived from (5.19)."""
    u = pressures.displacement_inside(sp.Rational(1, 2))
    match = sp.Poly(sp.expand(u - (d - r**2 / (2 * R))), r)  # (5.19): zero for every r
    eqs = [sp.Eq(c, 0) for c in match.coeffs()]
    (sol,) = sp.solve(eqs, [a, p0], dict=True)
    a_d, p0_d = sol[a], sol[p0]
    force = pressures.force(sp.Rational(1, 2)).subs({a: a_d, p0: p0_d})
    U_sym = sp.Symbol("U")
    energy = sp.integrate(force.subs(d, U_sym), (U_sym, 0, d))  # F = dU/dd, U(0) = 0
    (d_F,) = sp.solve(sp.Eq(F, force), d)
    return {
        "a": sp.simplify(a_d),
        "p0": sp.simplify(p0_d),
        "F": sp.simplify(force),
        "U": sp.simplify(energy),
        "k": sp.simplify(sp.diff(force, d)),
        "pm": sp.simplify(force / (sp.pi * a_d**2)),
        "d_F": sp.simplify(d_F),
        "a_F": sp.simplify(a_d.subs(d, d_F)),
        "p0_F": sp.simplify(p0_d.subs(d, d_F)),
        # (5.20): the two conditions written with p0 and a
        "a_from_p0": sp.solve(sp.Eq(match.coeff_monomial(r**2), 0), a)[0],
        "d_from_p0": sp.solve(sp.Eq(match.coeff_monomial(1), 0), d)[0],
    }


def displacement_outside_stable() -> sp.Expr:
    """u_z(r > a) without the cancellation of its textbook form for r >> a.

    With t = a/r the textbook form (d/pi)[(2 - 1/t^2) asin t + sqrt(1 - t^2)/t] subtracts terms
    of size r/a to leave a result of size a/r. Writing asin t - t sqrt(1 - t^2) as
    2 * integral_0^t s^2/sqrt(1 - s^2) ds = (2 t^3/3) 2F1(1/2, 3/2; 5/2; t^2) removes it.
    """
    t = a / r
    s = solution()
    h = sp.hyper([sp.Rational(1, 2), sp.Rational(3, 2)], [sp.Rational(5, 2)], t**2)
    return (2 * d / sp.pi * (sp.asin(t) - t / 3 * h)).subs(a, s["a"])


#: the far form's Taylor series in z = a^2/r^2 (issue 18): its number of terms and the largest
#: z where it is used; the elementary form (displacement_outside_elementary) takes z above it.
#: The choice, from the two error models (tests/test_hertz.py::test_outside_forms_by_mpmath
#: measures both): the elementary form cancels ~0.65 eps/z (measured over 3000 random z), 2.6
#: eps at z = 1/4; the series' truncation is below 0.06 eps there (series_tail_bound) and its
#: 22 positive terms round to ~1 eps. A switch at 1/2 would need 39 terms for 1.3 eps, at 1/8
#: 13 terms for 5.2 eps: 1/4 keeps the form's error at the level of the rounding of a/r
SERIES_TERMS = 22
SERIES_SWITCH = sp.Rational(1, 4)

_zs = sp.Symbol("z_s", positive=True)  # a^2/r^2, only inside this module
_ts = sp.Symbol("t_s", positive=True)  # a/r


@cache
def displacement_series_coefficients(n: int = SERIES_TERMS) -> tuple[sp.Rational, ...]:
    """g_0 .. g_{n-1} of asin t - (t/3) 2F1(1/2, 3/2; 5/2; t^2) = t sum g_k t^(2k), the bracket
    of the stable far form: asin's from SymPy's series, the 2F1's from its definition
    (1/2)_k (3/2)_k/((5/2)_k k!). They equal
    (1/2)_k/k! 2/((2k + 1)(2k + 3)) (asin's coefficient (1/2)_k/(k! (2k + 1)) minus the 2F1's
    (1/2)_k/(k! (2k + 3))): positive, and each ratio g_(k+1)/g_k = (2k + 1)^2/(2 (k + 1)
    (2k + 5)) < 1, which bounds the tail (:func:`series_tail_bound`)."""
    half = sp.Rational(1, 2)
    asin = sp.Poly(sp.series(sp.asin(_ts), _ts, 0, 2 * n + 1).removeO(), _ts)
    k = sp.Symbol("k", integer=True, nonnegative=True)
    # the 2F1's own series: its k-th coefficient in t^2 (hyper's definition, SymPy's rf)
    term = sp.rf(half, k) * sp.rf(3 * half, k) / (sp.rf(5 * half, k) * sp.factorial(k))
    coeffs = tuple(sp.Rational(asin.coeff_monomial(_ts ** (2 * j + 1)))
                   - term.subs(k, j) / 3 for j in range(n))
    for j, c in enumerate(coeffs):  # the closed form the tail bound rests on
        assert c == sp.rf(half, j) / sp.factorial(j) * 2 / ((2 * j + 1) * (2 * j + 3)), j
    return coeffs


def series_tail_bound(z_max=SERIES_SWITCH, n: int = SERIES_TERMS) -> sp.Rational:
    """A bound on the series' truncation error relative to its value, for 0 < z <= z_max:
    the omitted terms sum to at most g_n z^n/(1 - z) (the coefficients decrease), and the
    value is at least g_0 = 2/3."""
    g = displacement_series_coefficients(n + 1)
    return g[n] * z_max**n / (1 - z_max) / g[0]


def displacement_outside_series() -> sp.Expr:
    """u_z(r > a) as its Taylor series in z = a^2/r^2 = R d/r^2 to SERIES_TERMS terms, in
    Horner's form: (2 d/pi) t sum g_k z^k, t = a/r. For z <= SERIES_SWITCH its relative
    truncation error is below series_tail_bound() (4.6e-18)."""
    g = displacement_series_coefficients()
    poly = g[-1]
    for c in reversed(g[:-1]):
        poly = c + _zs * poly
    s = solution()
    t = s["a"] / r
    return (2 * d / sp.pi * t * poly).subs(_zs, R * d / r**2)


def displacement_outside_elementary() -> tuple[sp.Expr, sp.Expr]:
    """(derived, printed) u_z(r > a) with the 2F1 of the stable far form in elementary
    functions: hyperexpand gives 2F1(1/2, 3/2; 5/2; t^2) = 3 (asin t - t sqrt(1 - t^2))/(2 t^3),
    so the bracket is asin t - (asin t - t sqrt(1 - t^2))/(2 t^2), printed with z = R d/r^2
    for t^2 (R d < r^2 there, so 1 - z >= 0 in floats too). It cancels: ~0.65 eps/z relative
    (the terms are ~t/(2z), the result ~2t/3), so it is used for z > SERIES_SWITCH only."""
    s = solution()
    h = sp.hyperexpand(sp.hyper([sp.Rational(1, 2), sp.Rational(3, 2)], [sp.Rational(5, 2)],
                                _ts**2))
    derived = (2 * d / sp.pi * (sp.asin(_ts) - _ts / 3 * h)).subs(_ts, s["a"] / r)
    t, z = s["a"] / r, R * d / r**2
    arcsin = sp.asin(t)
    printed = 2 * d / sp.pi * (arcsin - (arcsin - t * sp.sqrt(1 - z)) / (2 * z))
    return derived, printed


#: the two forms of the outside displacement each printed as one function with its common
#: subexpressions computed once (codegen.render_fused): numeric/hertz.py evaluates them on
#: blocks of radii (issue 18)
FUSED = {
    "hertz_displacement_far": ("hertz_displacement_outside_series",),
    "hertz_displacement_near": ("hertz_displacement_outside_elementary",),
}


def relations() -> list[Relation]:
    s = solution()
    at_depth = {a: s["a"], p0: s["p0"]}
    u_in = sp.simplify(pressures.displacement_inside(sp.Rational(1, 2)).subs(at_depth))
    u_out = sp.simplify(pressures.displacement_outside(sp.Rational(1, 2)).subs(at_depth))
    pressure = s["p0"] * sp.sqrt(sp.Max(0, 1 - r**2 / s["a"] ** 2))  # (5.15), 0 outside
    third = sp.Rational(1, 3)
    _elementary = displacement_outside_elementary()
    return [
        Relation("hertz_contact_radius", "(5.21)", s["a"], (R, d),
                 "contact radius a [m] of a Hertz contact at depth d",
                 "the matching condition (5.19)", f"{TEST}::test_matching_by_kernel",
                 printed=sp.sqrt(R * d)),
        Relation("hertz_max_pressure", "(5.22)", s["p0"], (E_star, R, d),
                 "maximum (central) pressure p0 [Pa] of a Hertz contact at depth d",
                 "the matching condition (5.19)", f"{TEST}::test_matching_by_kernel",
                 printed=2 / sp.pi * E_star * sp.sqrt(d / R)),
        Relation("hertz_force", "(5.23)", s["F"], (E_star, R, d),
                 "normal force F [N] of a Hertz contact at depth d",
                 "(5.17) with (5.21) and (5.22)", f"{TEST}::test_force_by_pressure_quadrature",
                 printed=sp.Rational(4, 3) * E_star * sp.sqrt(R) * d ** sp.Rational(3, 2)),
        Relation("hertz_depth_from_force", "(5.23), inverted", s["d_F"], (E_star, F, R),
                 "indentation depth d [m] of a Hertz contact under the force F",
                 "(5.23) solved for d", f"{TEST}::test_force_controlled_roundtrip"),
        Relation("hertz_contact_radius_from_force", "(5.24)", s["a_F"], (E_star, F, R),
                 "contact radius a [m] of a Hertz contact under the force F",
                 "(5.21) at the depth of (5.23) inverted",
                 f"{TEST}::test_force_controlled_roundtrip",
                 printed=(3 * F * R / (4 * E_star)) ** third),
        Relation("hertz_max_pressure_from_force", "(5.24)", s["p0_F"], (E_star, F, R),
                 "maximum pressure p0 [Pa] of a Hertz contact under the force F",
                 "(5.22) at the depth of (5.23) inverted",
                 f"{TEST}::test_force_controlled_roundtrip",
                 printed=(6 * F * E_star**2 / (sp.pi**3 * R**2)) ** third),
        Relation("hertz_energy", "(5.25)", s["U"], (E_star, R, d),
                 "elastic energy U [J] stored in a Hertz contact at depth d",
                 "the integral of F = dU/dd from 0 to d", f"{TEST}::test_energy_by_work",
                 printed=sp.Rational(8, 15) * E_star * sp.sqrt(R) * d ** sp.Rational(5, 2)),
        Relation("hertz_stiffness", "Problem 5", s["k"], (E_star, R, d),
                 "differential contact stiffness dF/dd [N/m] of a Hertz contact",
                 "the derivative of (5.23)", f"{TEST}::test_stiffness_by_punch",
                 printed=2 * E_star * sp.sqrt(R * d)),
        Relation("hertz_pressure", "(5.15)", pressure, (E_star, R, d, r),
                 "contact pressure p(r) [Pa] of a Hertz contact at depth d (0 for r > a)",
                 "(5.15) with (5.21) and (5.22)", f"{TEST}::test_matching_by_kernel"),
        Relation("hertz_displacement_inside", "(5.18)", u_in, (R, d, r),
                 "surface displacement u_z(r) [m] inside a Hertz contact (r <= a)",
                 "(5.16) with (5.21) and (5.22)", f"{TEST}::test_matching_by_kernel",
                 printed=d - r**2 / (2 * R)),
        Relation("hertz_displacement_outside", "Fig. 5.2, Problem 7(b)", u_out, (R, d, r),
                 "surface displacement u_z(r) [m] outside a Hertz contact (r > a)",
                 "(5.7) over the Hertz pressure, outside the disc",
                 "tests/test_pressures.py::test_outside_displacement_by_kernel",
                 printed=d / sp.pi * ((2 - r**2 / s["a"] ** 2) * sp.asin(s["a"] / r)
                                      + sp.sqrt(r**2 / s["a"] ** 2 - 1)),
                 stable=displacement_outside_stable(),
                 stable_why="the textbook form cancels terms of size r/a to leave one of "
                 "size a/r; asin t - t sqrt(1 - t^2) is written as (2 t^3/3) 2F1(1/2, 3/2; "
                 "5/2; t^2) with t = a/r",
                 domain={r: s["a"] / unit_interval()}),
        Relation("hertz_displacement_outside_series", "Fig. 5.2, Problem 7(b), r >= 2a",
                 displacement_outside_series(), (R, d, r),
                 f"surface displacement u_z(r) [m] outside a Hertz contact, its Taylor series in "
                 f"z = a^2/r^2 to {SERIES_TERMS} terms: for r >= 2a (z <= "
                 f"{SERIES_SWITCH}) the truncation is below "
                 f"{float(series_tail_bound()):.1e} relative",
                 "the series of the stable far form (2F1(1/2, 3/2; 5/2; z) and asin)",
                 f"{TEST}::test_outside_forms_by_mpmath",
                 domain={r: s["a"] / unit_interval()}),
        Relation("hertz_displacement_outside_elementary", "Fig. 5.2, Problem 7(b), a < r < 2a",
                 _elementary[0], (R, d, r),
                 "surface displacement u_z(r) [m] outside a Hertz contact with the 2F1 in "
                 "elementary functions; it cancels ~0.65 eps a^2/r^2 relative: for a < r < 2a",
                 "the stable far form with 2F1(1/2, 3/2; 5/2; t^2) hyperexpanded",
                 f"{TEST}::test_outside_forms_by_mpmath",
                 stable=_elementary[1],
                 stable_why="asin t - (asin t - t sqrt(1 - z))/(2 z), t = a/r, z = R d/r^2: "
                 "the 2F1 in elementary functions as one cancellation of ~0.65 eps/z",
                 domain={r: s["a"] / unit_interval()}),
        Relation("hertz_mean_pressure", "(5.17)", s["pm"], (E_star, R, d),
                 "mean pressure F/(pi a^2) [Pa] of a Hertz contact at depth d",
                 "(5.23) divided by the contact area", f"{TEST}::test_force_by_pressure_quadrature",
                 printed=sp.Rational(2, 3) * s["p0"]),
    ]
