"""The exact sphere (Sneddon's sphere) by the MDR: a rigid spherical cap f(r) = R - sqrt(R^2 - r^2).

Starting point: the cap's profile, put through the MDR steps of :mod:`hertzmdr.derive.mdr`.
Unlike the paraboloid r^2/(2R) of Hertz's theory, the relations hold for deep indentation: the
contact radius a tends to R as the depth d grows without bound.

- (5.52): with r = sqrt(x^2 - v^2), f'(r) dr/sqrt(x^2 - r^2) = dv/sqrt(R^2 - x^2 + v^2), which
  SymPy integrates to asinh(x/sqrt(R^2 - x^2)); this is atanh(x/R) for 0 < x < R (proved here),
  so g(x) = x atanh(x/R) = (x/2) ln((R + x)/(R - x)).
- (5.55): d = g(a) = a atanh(a/R).
- (5.57): F = 2 E* (d a - integral_0^a g) = E* ((a^2 + R^2) atanh(a/R) - a R).
- dF/dd = (dF/da)/(dd/da) = 2 a E* (Problem 5's stiffness, derived, not assumed).
- (5.59): g'(x) = atanh(x/R) + R x/(R^2 - x^2). The pole term, with x^2 = r^2 + w^2 and then
  w = c tanh(u), c = sqrt(R^2 - r^2), gives (E*/pi) (R/c) atanh(sqrt(a^2 - r^2)/c). The atanh
  term has no elementary closed form (SymPy returns it unevaluated; at the centre it is
  Legendre's chi function, integral_0^a atanh(x/R)/x dx = chi_2(a/R), a dilogarithm), so
  :mod:`hertzmdr.numeric.sphere` integrates it: after x^2 = r^2 + w^2 its integrand is
  (E*/pi) atanh(x/R)/x dw, analytic in w on [0, sqrt(a^2 - r^2)] (an even function of x), and
  log-singular only at x = R, just beyond the contact when a -> R.
- (5.60) outside: SymPy leaves it unevaluated. Integrated by parts it has a closed form (the
  atan/atanh of sqrt(R^2 - r^2) tan(asin(a/r))/R), but its terms cancel catastrophically both
  far from the contact (relative loss (r/a)^2) and for shallow contacts (loss (R/a)^2), so the
  numeric module evaluates (5.60) by quadrature of d - g(x), which has no cancellation.

A depth d >> R puts a so close to R that a float64 a no longer determines atanh(a/R): at
a/R = 1 - 1e-12 one rounding of a moves it by 5e-5. The depth-controlled relations are
therefore also written in lam = atanh(a/R) (a = R tanh(lam), d = R lam tanh(lam)), which
float64 carries for every depth; the numeric module solves d = g(a) for lam.

Stable forms printed: atanh(x/R) as log1p(2x/(R - x))/2 (R - x is exact near R, log1p exact
near 0); the force's (1 + b^2) atanh(b) - b (b = a/R), which cancels as b^2 for small b, as
b^2 atanh(b) + (b^3/3) 2F1(1, 3/2; 5/2; b^2) for b < 1/2; the cap's R - sqrt(R^2 - r^2) as
r^2/(R + sqrt((R - r)(R + r))).
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.codegen.cfunctions import log1p

from hertzmdr.derive import mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, R, a, r, symbol, unit_interval

x = mdr.x
lam = symbol("lam")
TEST = "tests/test_sphere.py"
HALF = sp.Rational(1, 2)


def profile() -> sp.Expr:
    """The spherical cap f(r) = R - sqrt(R^2 - r^2), 0 <= r <= R."""
    return R - sp.sqrt(R**2 - r**2)


def _atanh_stable(num: sp.Expr, den_minus: sp.Expr) -> sp.Expr:
    """atanh(num/den) printed as log1p(2 num/(den - num))/2, given den - num separately."""
    return log1p(2 * num / den_minus) / 2


@cache
def solution() -> dict[str, sp.Expr]:
    rr, v = sp.Symbol("r_c", positive=True), sp.Symbol("v", positive=True)
    fp = sp.diff(profile().subs(r, rr), rr)
    # (5.52) with r = sqrt(x^2 - v^2): dr/sqrt(x^2 - r^2) = -dv/r, v from x down to 0
    integrand = sp.simplify(fp.subs(rr, sp.sqrt(x**2 - v**2)) / sp.sqrt(x**2 - v**2))
    g_raw = x * mdr._integrate(integrand, (v, 0, x)).replace(sp.polar_lift, lambda z: z)
    g = x * sp.atanh(x / R)
    # g_raw/x and atanh(x/R) vanish at x = 0 and have the same derivative on 0 < x < R,
    # written with x = R s/sqrt(1 + s^2), s = x/sqrt(R^2 - x^2) in (0, inf)
    sv = sp.Symbol("s", positive=True)
    diff = (g_raw / x - sp.atanh(x / R)).subs(x, R * sv / sp.sqrt(1 + sv**2))
    if diff.subs(sv, 0) != 0 or sp.simplify(sp.diff(diff, sv)) != 0:
        raise AssertionError(f"(5.52) of the cap is not x atanh(x/R): {g_raw}")
    depth = g.subs(x, a)  # (5.55)
    F_a = mdr.force(g)  # (5.57)
    k = sp.simplify(sp.diff(F_a, a) / sp.diff(depth, a))  # dF/dd along the curve
    # (5.59): g' = atanh(x/R) + pole; the pole term in closed form
    gp = sp.diff(g, x)
    pole = sp.simplify(gp - sp.atanh(x / R))
    if sp.simplify(pole - R * x / (R**2 - x**2)) != 0:
        raise AssertionError(f"g' of the cap has an unexpected pole term: {pole}")
    w, u, c, kk = sp.symbols("w u c k", positive=True)
    # x^2 = r^2 + w^2: dx/sqrt(x^2 - r^2) = dw/x; then R^2 - r^2 = c^2 and w = c tanh(u)
    pole_w = sp.simplify((pole / x).subs(x, sp.sqrt(r**2 + w**2)).subs(r**2, R**2 - c**2))
    pole_u = sp.simplify((pole_w.subs(w, c * sp.tanh(u)) * sp.diff(c * sp.tanh(u), u))
                         .rewrite(sp.exp))
    p_pole = E_star / sp.pi * mdr._integrate(pole_u, (u, 0, sp.atanh(kk / c)))
    p_pole = p_pole.subs({c: sp.sqrt(R**2 - r**2), kk: sp.sqrt(a**2 - r**2)})
    atanh_kernel = E_star / sp.pi * sp.atanh(x / R) / x  # the rest of (5.59), per dw
    # in lam = atanh(a/R)
    on_lam = {a: R * sp.tanh(lam)}

    def in_lam(e):  # atanh(tanh(lam)) = lam for real lam
        return sp.simplify(e.subs(on_lam).subs(sp.atanh(sp.tanh(lam)), lam))

    return {"g": g, "d": depth, "F_a": F_a, "k": k, "p_pole": p_pole,
            "kernel": atanh_kernel,
            "a_lam": R * sp.tanh(lam),
            "d_lam": in_lam(depth),
            "F_lam": in_lam(F_a),
            "p_pole_lam": p_pole.subs(on_lam)}


def force_from_radius_stable() -> sp.Expr:
    b = a / R
    small = E_star * R**2 * (b**2 * sp.atanh(b) + b**3 / 3 * sp.hyper(
        [1, sp.Rational(3, 2)], [sp.Rational(5, 2)], b**2))
    large = E_star * ((a**2 + R**2) * _atanh_stable(a, R - a) - a * R)
    return sp.Piecewise((small.subs(sp.atanh(b), _atanh_stable(a, R - a)), a < R / 2),
                        (large, True))


def force_lam_stable() -> sp.Expr:
    b = sp.tanh(lam)
    small = E_star * R**2 * (b**2 * lam + b**3 / 3 * sp.hyper(
        [1, sp.Rational(3, 2)], [sp.Rational(5, 2)], b**2))
    large = E_star * R**2 * ((1 + b**2) * lam - b)
    return sp.Piecewise((small, lam < HALF), (large, True))


#: below this lam the fit's force is written with Lambert's continued fraction for lam - tanh(lam)
FIT_LAM_SPLIT = HALF
#: levels of that continued fraction: its truncation error is < 1e-18 of the force on
#: 0 < lam <= FIT_LAM_SPLIT (asserted by :func:`force_lam_fit`), far below a float64's rounding
FIT_CF_LEVELS = 7


def lam_minus_tanh_cf(levels: int = FIT_CF_LEVELS) -> sp.Expr:
    """lam - tanh(lam) by Lambert's continued fraction tanh(x) = x/(1 + q),
    q = x^2/(3 + x^2/(5 + x^2/(7 + ...))), truncated after ``levels`` denominators:
    lam - tanh(lam) = lam q/(1 + q). Every term is positive: no cancellation, unlike the
    difference lam - tanh(lam) ~ lam^3/3, which loses the digits of lam^2."""
    x2 = lam**2
    den = sp.Integer(2 * levels + 1)
    for k in range(levels, 1, -1):
        den = (2 * k - 1) + x2 / den
    return lam**3 / (den + x2)  # lam q/(1 + q) with q = x2/den: den is evaluated once


@cache
def force_lam_fit() -> sp.Expr:
    """The force E* R^2 ((1 + b^2) lam - b), b = tanh(lam), as the fit evaluates it: in lam and
    the contact radius a = R tanh(lam) (both arguments: the fit computes tanh once per point and
    shares it between Newton's iteration for lam, the force and dF/dz_0 = -2 E* a), below
    lam = FIT_LAM_SPLIT as E* (a^2 lam + R^2 (lam - b)) with the cancelling lam - b by
    :func:`lam_minus_tanh_cf` (no 2F1: the fit evaluates it at every point of every contact
    point it tries), above it as E* ((R^2 + a^2) lam - R a).

    Error model: the direct form's rounding is ~eps lam against a force ~(4/3) lam^3, a
    relative error ~1.5 eps/lam^2, <= 6 eps above lam = 1/2 (3.5 eps measured); the continued
    fraction's rounding is a few eps (positive terms only) and its truncation, checked here at
    40 digits on a grid of (0, FIT_LAM_SPLIT] (the relative truncation error grows with lam:
    a Pade approximant's error ~ lam^(4 levels + 3)), is below 1e-18. The rounding of the
    given a (an ulp) moves the force by (2 a^2 lam - [lam >= 1/2] R a)/(force/E*) ulp of a:
    at most 1.5 ulp below lam = 1/2 (a^2 lam against (4/3) R^2 lam^3) and 1.7 above it (at
    lam = 1/2, decreasing beyond).
    """
    b = sp.tanh(lam)
    exact = (1 + b**2) * lam - b
    small = b**2 * lam + lam_minus_tanh_cf()
    worst = max(abs(sp.N(((small - exact) / exact).subs(lam, FIT_LAM_SPLIT * sp.Rational(k, 16)),
                         40)) for k in range(1, 17))
    if not worst < 1e-18:
        raise AssertionError(f"the continued fraction's truncation error {worst} is not < 1e-18")
    small_a = a**2 * lam + R**2 * lam_minus_tanh_cf()
    exact_a = (R**2 + a**2) * lam - R * a
    on_lam = {a: R * b}
    for form, ref in ((small_a, small), (exact_a, exact)):
        if sp.simplify(form.subs(on_lam) - R**2 * ref) != 0:
            raise AssertionError(f"the fit's sphere force in (lam, a) is not R^2 ({ref}): {form}")
    return E_star * sp.Piecewise((small_a, lam < FIT_LAM_SPLIT), (exact_a, True))


def pressure_pole_lam_stable() -> sp.Expr:
    """(E*/pi)(R/c) atanh(k/c), c^2 = R^2 - r^2, k^2 = a^2 - r^2, a = R tanh(lam):
    atanh(k/c) = log1p(2k/(c - k))/2 with c - k = (R^2 - a^2)/(c + k) = R^2/(cosh(lam)^2 (c + k)),
    so no difference of nearly equal numbers is formed as a -> R or r -> a."""
    aa = R * sp.tanh(lam)
    c = sp.sqrt((R - r) * (R + r))
    k = sp.sqrt((aa - r) * (aa + r))
    return E_star / sp.pi * R / c * log1p(2 * k * (c + k) * sp.cosh(lam) ** 2 / R**2) / 2


def relations() -> list[Relation]:
    s = solution()
    t, ta = unit_interval(), unit_interval("t_a")
    inside = {a: R * ta}  # 0 < a < R
    t_lam = unit_interval("t_lam")
    lam_dom = {lam: sp.atanh(t_lam)}  # lam in (0, inf): a/R = t_lam
    why_atanh = ("atanh(x/R) loses the digits of 1 - x/R near x = R; log1p(2x/(R - x))/2 "
                 "keeps them (R - x is exact there) and is exact as x -> 0")
    return [
        Relation("sphere_profile", "(5.52), Sneddon's sphere", profile(), (R, r),
                 "height f(r) [m] of a spherical cap of radius R above its apex, 0 <= r <= R",
                 "the sphere x^2 + (R - z)^2 = R^2", f"{TEST}::test_profile_and_g",
                 stable=r**2 / (R + sp.sqrt((R - r) * (R + r))),
                 stable_why="R - sqrt(R^2 - r^2) cancels for r << R; it is written "
                 "r^2/(R + sqrt((R - r)(R + r)))", domain={r: R * t}),
        Relation("sphere_g", "(5.52), Sneddon's sphere", s["g"], (R, x),
                 "MDR profile g(x) [m] of the spherical cap, 0 <= x < R",
                 "(5.52) with r = sqrt(x^2 - v^2)", f"{TEST}::test_profile_and_g",
                 stable=x * _atanh_stable(x, R - x), stable_why=why_atanh,
                 domain={x: R * t}),
        Relation("sphere_depth", "(5.55), Sneddon's sphere", s["d"], (R, a),
                 "indentation depth d [m] of a rigid spherical cap at the contact radius a < R",
                 "(5.55), d = g(a)", f"{TEST}::test_depth_and_force_by_quadrature",
                 stable=a * _atanh_stable(a, R - a), stable_why=why_atanh, domain=inside),
        Relation("sphere_force_from_radius", "(5.57), Sneddon's sphere", s["F_a"],
                 (E_star, R, a),
                 "normal force F [N] of a rigid spherical cap at the contact radius a < R",
                 "(5.57) with d = g(a)", f"{TEST}::test_depth_and_force_by_quadrature",
                 stable=force_from_radius_stable(),
                 stable_why="(a^2 + R^2) atanh(a/R) - a R cancels as (a/R)^2 for a << R; "
                 "below a = R/2 it is written E* R^2 (b^2 atanh(b) + (b^3/3) "
                 "2F1(1, 3/2; 5/2; b^2)), b = a/R, above it with atanh in log1p",
                 domain=inside),
        Relation("sphere_stiffness", "Problem 5, Sneddon's sphere", s["k"], (E_star, a),
                 "differential stiffness dF/dd [N/m] of a rigid spherical cap at contact radius a",
                 "(dF/da)/(dd/da) of (5.57) and (5.55)", f"{TEST}::test_stiffness",
                 printed=2 * a * E_star),
        Relation("sphere_lam_contact_radius", "(5.55), Sneddon's sphere", s["a_lam"], (R, lam),
                 "contact radius a = R tanh(lam) [m] of a rigid spherical cap",
                 "the definition lam = atanh(a/R)", f"{TEST}::test_depth_and_force_by_quadrature"),
        Relation("sphere_lam_depth", "(5.55), Sneddon's sphere", s["d_lam"], (R, lam),
                 "indentation depth d [m] of a rigid spherical cap at lam = atanh(a/R)",
                 "(5.55) at a = R tanh(lam)", f"{TEST}::test_depth_and_force_by_quadrature"),
        Relation("sphere_lam_force", "(5.57), Sneddon's sphere", s["F_lam"], (E_star, R, lam),
                 "normal force F [N] of a rigid spherical cap at lam = atanh(a/R)",
                 "(5.57) at a = R tanh(lam)", f"{TEST}::test_depth_and_force_by_quadrature",
                 stable=force_lam_stable(),
                 stable_why="(1 + tanh(lam)^2) lam - tanh(lam) cancels as lam^2 for small lam; "
                 "below lam = 1/2 it is written with (b^3/3) 2F1(1, 3/2; 5/2; b^2) for "
                 "lam - b, b = tanh(lam)", domain=lam_dom),
        Relation("sphere_lam_pressure_pole", "(5.59), Sneddon's sphere", s["p_pole_lam"],
                 (E_star, R, lam, r),
                 "the part of the contact pressure p(r) [Pa] of a rigid spherical cap from the "
                 "pole R x/(R^2 - x^2) of g'(x), at lam = atanh(a/R), 0 <= r < a",
                 "(5.59) with x^2 = r^2 + w^2, w = sqrt(R^2 - r^2) tanh(u)",
                 f"{TEST}::test_pressure_by_quadrature_of_59",
                 stable=pressure_pole_lam_stable(),
                 stable_why="atanh(k/c), k^2 = a^2 - r^2, c^2 = R^2 - r^2, loses 1 - k/c as "
                 "a -> R; it is written log1p(2k(c + k) cosh(lam)^2/R^2)/2",
                 domain={lam: sp.atanh(t_lam), r: R * t_lam * t}),
        Relation("sphere_pressure_atanh_kernel", "(5.59), Sneddon's sphere", s["kernel"],
                 (E_star, R, x),
                 "integrand (E*/pi) atanh(x/R)/x [Pa/m] of the rest of (5.59) for the spherical "
                 "cap, to be integrated over w in (0, sqrt(a^2 - r^2)) at x = sqrt(r^2 + w^2)",
                 "(5.59) of the atanh term of g', with x^2 = r^2 + w^2 (dx/sqrt(x^2 - r^2) = "
                 "dw/x); no elementary antiderivative",
                 f"{TEST}::test_pressure_by_quadrature_of_59",
                 stable=E_star / sp.pi * _atanh_stable(x, R - x) / x, stable_why=why_atanh,
                 domain={x: R * t}),
    ]
