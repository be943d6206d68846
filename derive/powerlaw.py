"""Power-law indenters f = c_n r^n by the MDR (Problem 7), the flat punch as n -> infinity.

Starting point: the MDR steps of :mod:`hertzmdr.derive.mdr` applied to f = c_n r^n with a
symbolic n > 0. SymPy evaluates (5.52) to g = kappa_n c_n x^n with kappa_n in Gamma functions,
solves (5.55), integrates (5.57), and evaluates the outside displacement (5.60) as a 2F1.

The pressure (5.59), p = (E*/pi) kappa_n c_n n * integral_r^a x^(n-1)/sqrt(x^2 - r^2) dx, is
beyond SymPy's integrator for symbolic n, so the derivation substitutes
x = r/sqrt(1 - z t), z = 1 - r^2/a^2 (t from 0 at x = r to 1 at x = a), which removes the
endpoint singularity and leaves the Euler integral integral_0^1 t^(-1/2) (1 - z t)^(-(n+1)/2) dt
that SymPy does evaluate: p = (E*/pi) kappa_n c_n n r^(n-1) sqrt(z) 2F1(1/2, (n+1)/2; 3/2; z).
Euler's transformation 2F1(a, b; c; z) = (1 - z)^(c-a-b) 2F1(c-a, c-b; c; z) (DLMF 15.8.1)
then gives the form a^(n-1) sqrt(z) 2F1(1, 1 - n/2; 3/2; z), finite at the centre for n > 1.
For integer n = 1..4, :func:`hertzmdr.derive.mdr.pressure` gives elementary functions directly.

kappa_n for large n: the Gamma ratio overflows for n > 340 and its logarithm (gammaln
differences) loses eps*ln Gamma(n/2) in relative accuracy; the Stirling series of
ln Gamma(m + 1) - ln Gamma(m + 1/2) (m = n/2), derived by SymPy, is printed for large n.

The flat punch (Problem 7(a)): g = 0 inside, so q' = -E* d delta(x - a) and (5.59) gives the
pressure with a Dirac delta; its force is the n -> infinity limit of the power-law force.
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from hertzmdr.derive import mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, F, a, d, r, symbol, unit_interval

n = symbol("n")
c_n = symbol("c_n")
kappa_n = symbol("kappa_n")
r_tilde = symbol("r_tilde")
x = mdr.x
t = mdr.t
z = sp.Symbol("z", positive=True)
rp = sp.Symbol("r", positive=True)

TEST = "tests/test_powerlaw.py"
#: number of terms of the Stirling series printed for kappa_n (error ~ 2e-3 m^-11, m = n/2)
STIRLING_ORDER = 10


@cache
def _g() -> sp.Expr:
    return mdr.transform(c_n * rp**n, rp)  # (5.52)


@cache
def kappa() -> sp.Expr:
    """kappa_n from (5.52): g(x)/(c_n x^n) for f = c_n r^n."""
    return sp.simplify(_g() / (c_n * x**n))


@cache
def kappa_asymptotic() -> sp.Expr:
    """sqrt(pi m) exp(S(1/m)), m = n/2, S the Stirling series of ln(kappa_n/sqrt(pi m))."""
    m = sp.Symbol("m", positive=True)
    k = kappa().subs(n, 2 * m)
    # kappa = sqrt(pi) Gamma(m + 1)/Gamma(m + 1/2): take logs, expand at m = oo
    num, den = (k / sp.sqrt(sp.pi)).as_numer_denom()
    assert isinstance(num, sp.gamma) and isinstance(den, sp.gamma), k
    log_ratio = sp.loggamma(num.args[0]) - sp.loggamma(den.args[0]) - sp.log(m) / 2
    series = sp.series(log_ratio, m, sp.oo, STIRLING_ORDER).removeO()
    series = sp.expand(sp.expand_log(series, force=True))  # the log(2 pi) terms cancel
    assert not series.has(sp.log), series
    # Horner in 1/m = 2/n, printed as powers of n**(-1.0): 1/n**2 would overflow n**2 for
    # n > 1.3e154 (the terms it scales underflow harmlessly to 0 instead)
    return (sp.sqrt(sp.pi * m) * sp.exp(sp.horner(series.subs(m, 1 / z)).subs(
        z, 2 * sp.Pow(n, -1.0)))).subs(m, n / 2)


@cache
def solution() -> dict[str, sp.Expr]:
    """g, d(a), a(d), F(a), F(d) of the power law, with kappa_n as the symbol ``kappa_n``."""
    k = kappa()
    g = _g().subs(k, kappa_n)  # kappa_n c_n x^n
    assert sp.simplify(g - kappa_n * c_n * x**n) == 0
    depth = g.subs(x, a)  # (5.55)
    (a_d,) = sp.solve(sp.Eq(depth, d), a)
    F_a = sp.simplify(mdr.force(g))  # (5.57) as a function of a
    F_ad = sp.factor(sp.simplify(F_a.subs(c_n, d / (kappa_n * a**n))))  # F(a, d)
    F_d = sp.powsimp(sp.simplify(F_a.subs(a, a_d)), force=True)
    (d_F,) = sp.solve(sp.Eq(F, F_d), d)
    return {"g": g, "a": a_d, "F_a": F_a, "F_ad": F_ad, "F": F_d, "d_F": d_F,
            "pm": sp.simplify(F_ad / (sp.pi * a**2))}


def _euler_transformation(h: sp.hyper) -> sp.Expr:
    """2F1(a, b; c; z) = (1 - z)^(c - a - b) 2F1(c - a, c - b; c; z), DLMF 15.8.1."""
    (pa, pb), (pc,) = h.ap, h.bq
    zz = h.argument
    return (1 - zz) ** (pc - pa - pb) * sp.hyper([pc - pa, pc - pb], [pc], zz)


@cache
def pressure_hyper() -> tuple[sp.Expr, sp.Expr]:
    """p(r) inside for general n: (form with 2F1(1/2, (n+1)/2; 3/2; z), Euler-transformed form).

    Both in terms of (E*, a, d, n, r), with kappa_n c_n = d/a^n from (5.55).
    """
    g = solution()["g"]
    gp = sp.diff(g, x)
    # x = r (1 - z t)^(-1/2): x from r (t = 0) to a (t = 1) when z = 1 - r^2/a^2; with
    # w = 1 - z t > 0 as a symbol, x^2 - r^2 = r^2 z t / w and dx/dt = r z w^(-3/2) / 2
    w = sp.Symbol("w", positive=True)
    xt = rp / sp.sqrt(w)
    dxdt = sp.diff(rp / sp.sqrt(1 - z * t), t).subs(1 - z * t, w)
    assert sp.simplify((xt**2 - rp**2).subs(w, 1 - z * t) - rp**2 * z * t / (1 - z * t)) == 0
    integrand = gp.subs(x, xt) * dxdt / sp.sqrt(rp**2 * z * t / w)
    integrand = sp.powsimp(sp.expand_power_base(integrand, force=True), force=True,
                           combine="exp")
    integrand = integrand.subs(w, 1 - z * t)
    const, tpart = integrand.as_independent(t, as_Add=False)
    J = const * mdr._integrate(tpart, (t, 0, 1))  # the Euler integral of 2F1
    assert not J.has(sp.Integral), J
    # no simplify() from here on: it would hyperexpand the 2F1 into branch-cut forms
    at = {c_n: d / (kappa_n * a**n)}
    p_b = (E_star / sp.pi * J).subs(at)
    hypers = p_b.atoms(sp.hyper)
    assert len(hypers) == 1, p_b
    (h,) = hypers
    p_a = p_b.subs(h, _euler_transformation(h))
    # z = 1 - r^2/a^2, 1 - z = r^2/a^2
    p_a = sp.powsimp(sp.expand_power_base(p_a.subs(1 - z, rp**2 / a**2), force=True),
                     force=True)
    p_b = sp.powsimp(sp.expand_power_base(p_b, force=True), force=True, combine="exp")
    return p_b.subs(z, 1 - rp**2 / a**2).subs(rp, r), p_a.subs(z, 1 - rp**2 / a**2).subs(rp, r)


w_quad = symbol("w_quad")


@cache
def pressure_integrand() -> tuple[sp.Expr, sp.Expr]:
    """(5.59) as an integral over w in (0, 1) with a smooth integrand, for quadrature at any n.

    x^2 = r^2 + (a^2 - r^2)(1 - w)^2 takes x from a (w = 0) to r (w = 1) and removes the
    1/sqrt(x^2 - r^2) of the Abel kernel: dx/sqrt(x^2 - r^2) = -sqrt(a^2 - r^2) dw / x. The
    variable is w = 1 - v rather than v so that the layer at x = a, where the integrand lives
    for large n, is resolved in absolute terms (1 - v rounded would cost n ulp). Returns
    (derived, stable): the stable form writes (x/a)^(n - 2) as
    exp((n/2 - 1) log1p(-(a^2 - r^2) w (2 - w)/a^2)), which neither overflows nor loses
    digits for n up to 1e8 and more.
    """
    g = solution()["g"].subs(c_n, d / (kappa_n * a**n))  # (5.52), d = g(a) (5.55)
    u = sp.Symbol("u", positive=True)  # u = 1 - w in (0, 1)
    xw = sp.sqrt(rp**2 + (a**2 - rp**2) * u**2)
    jac = sp.diff(xw, u) / sp.sqrt(sp.factor(xw**2 - rp**2))  # dx/dw = -dx/du, w: 0 -> 1
    derived = sp.powsimp(sp.simplify(E_star / sp.pi * sp.diff(g, x).subs(x, xw) * jac),
                         force=True).subs(u, 1 - w_quad)
    ratio = (a - rp) * (a + rp) * w_quad * (2 - w_quad) / a**2  # 1 - (x/a)^2
    stable = (E_star * n * d / (sp.pi * a**2) * sp.sqrt((a - rp) * (a + rp))
              * sp.exp((n / 2 - 1) * log1p(-ratio)))
    return derived.subs(rp, r), stable.subs(rp, r)


def _hyper_arg_clipped(expr: sp.Expr) -> sp.Expr:
    """Write z = 1 - r^2/a^2 as Max(0, (a - r)(a + r))/a^2: exact near the rim, 0 outside."""
    zc = sp.Max(0, (a - r) * (a + r)) / a**2
    return expr.subs(1 - r**2 / a**2, zc).subs(-r**2 / a**2 + 1, zc)


def _normalized(p_a: sp.Expr, pm: sp.Expr) -> sp.Expr:
    """p/p_mean as a function of r_tilde = r/a, written with Max(0, (1 - r~)(1 + r~))."""
    ratio = sp.cancel(p_a.subs(r, a * r_tilde) / pm)
    zc = sp.Max(0, (1 - r_tilde) * (1 + r_tilde))
    return sp.factor_terms(ratio.subs(1 - r_tilde**2, zc))


@cache
def pressure_integer(k: int) -> sp.Expr:
    """p(r) inside for integer n = k from mdr.pressure, in terms of (E*, a, d, r)."""
    kk = sp.Integer(k)
    g = kappa().subs(n, kk) * c_n * x**kk
    p = mdr.pressure(g).subs(c_n, d / (kappa().subs(n, kk) * a**kk))
    return sp.simplify(p)


@cache
def displacement_outside() -> sp.Expr:
    """u(r > a) from (5.60), in terms of (a, d, n, r)."""
    u = mdr.displacement_outside(kappa_n * c_n * x**n)
    u = sp.simplify(u.subs(c_n, d / (kappa_n * a**n)))
    half = sp.Rational(1, 2)  # Gamma(z + 1) = z Gamma(z): the Gammas cancel (no overflow)
    u = u.subs(sp.gamma(n / 2 + 3 * half), (n / 2 + half) * sp.gamma(n / 2 + half))
    return sp.collect(sp.factor_terms(sp.expand(sp.cancel(u))), sp.asin(a / r))


#: terms of the centre series of (5.59) (r/a)^0 ... (r/a)^(2 CENTRE_TERMS - 2) printed; the
#: first term left out is below 1e-20 of the centre value for r < a/10
CENTRE_TERMS = 10
#: terms of the far-field series of (5.60) in (a/r)^2 printed (a/r < 1e-3: the first term
#: left out is below 1e-24 of the result)
FAR_TERMS = 4


@cache
def pressure_centre() -> sp.Expr:
    """p(r) inside near the centre, r << a, in terms of (E*, a, d, n, r), for 0 < n < 3.

    The 2F1 forms of :func:`pressure_hyper` take z = 1 - r^2/a^2, which rounds to 1 for
    r < 1e-8 a and loses the non-analytic part (r/a)^(n-1) of p - p(0) (for 1 < n < 3) or
    its own leading part (n < 1). The connection formula DLMF 15.8.4 (z -> 1 - z) splits the
    2F1(1/2, (n+1)/2; 3/2; z) of the derived form into a 2F1 whose b = c (hyperexpanded to
    (1 - w)^(-1/2), w = r^2/a^2: the singular term) and a 2F1 in w times w^((1-n)/2), a power
    series in w, of which CENTRE_TERMS terms are kept (times the sqrt(1 - w) of the form):
    p = E* n d/(pi a) (sum_k (1/2)_k/k! (r/a)^(2k)/(n - 1 - 2k)
    + sqrt(pi) Gamma((1 - n)/2)/(2 Gamma(1 - n/2)) (r/a)^(n-1)).
    """
    w = sp.Symbol("w", positive=True)  # (r/a)^2
    rho = sp.Symbol("rho", positive=True)  # r/a
    p_b, _ = pressure_hyper()
    (h,) = p_b.atoms(sp.hyper)
    (pa, pb), (pc,) = h.ap, h.bq
    assert sp.simplify(h.argument - (1 - r**2 / a**2)) == 0, h
    gam = sp.gamma
    singular = (gam(pc) * gam(pc - pa - pb) / (gam(pc - pa) * gam(pc - pb))
                * sp.hyperexpand(sp.hyper([pa, pb], [pa + pb - pc + 1], w)))
    # the regular part: w^(c - a - b) Gamma(c) Gamma(a + b - c)/(Gamma(a) Gamma(b)) times
    # 2F1(c - a, c - b; c - a - b + 1; w), of which CENTRE_TERMS terms are kept
    a2, b2, c2 = pc - pa, pc - pb, pc - pa - pb + 1
    u = pa + pb - pc
    assert (pb - u).is_Integer, (pb, u)  # Gamma(u)/Gamma(b) = 1/(u)_(b - u), a rational in n
    const = gam(pc) / gam(pa) / sp.expand_func(sp.rf(u, pb - u))
    terms = [sp.expand_func(sp.rf(a2, j) * sp.rf(b2, j) / (sp.rf(c2, j) * sp.factorial(j)))
             for j in range(CENTRE_TERMS)]
    scale = E_star * n * d / (sp.pi * a)
    base = sp.simplify((p_b / h / scale).subs(r, rho * a))  # rho^(n-1) sqrt(1 - rho^2)
    sing = sp.powsimp(sp.expand_power_base(sp.simplify((base * singular).subs(w, rho**2)),
                                           force=True), force=True)
    # base w^(c - a - b) in w is free of the power of w (sqrt(1 - w) for (5.59)): its series
    # times the 2F1's terms (a Cauchy product) is the regular part's series
    pref = sp.powsimp(sp.expand_power_base((base * w ** (pc - pa - pb)).subs(rho, sp.sqrt(w)),
                                           force=True), force=True)
    assert not pref.has(n), pref
    pref = sp.series(pref, w, 0, CENTRE_TERMS).removeO()
    coeffs = [sp.factor(const * sum(pref.coeff(w, i) * terms[j - i] for i in range(j + 1)))
              for j in range(CENTRE_TERMS)]
    for j, c in enumerate(coeffs):  # the termwise expansion of (1 - r^2/x^2)^(-1/2) in (5.59)
        assert sp.simplify(c - sp.rf(sp.Rational(1, 2), j) / sp.factorial(j)
                           / (n - 1 - 2 * j)) == 0, (j, c)
    assert not sing.has(w) and sp.simplify(sing / rho ** (n - 1)).free_symbols == {n}, sing
    wr = (r / a) ** 2
    poly = sp.horner(sum(c * w**j for j, c in enumerate(coeffs)), w).subs(w, wr)
    return scale * (poly + sing.subs(rho, r / a))


@cache
def displacement_far() -> sp.Expr:
    """u_z(r) of (5.60) for r >> a, in terms of (a, d, n, r): the series in (a/r)^2.

    (5.60) with g = d (x/a)^n, d = g(a) (5.55): u_z = (2/pi) integral_0^a (d - g(x))/
    sqrt(r^2 - x^2) dx; 1/sqrt(r^2 - x^2) = (1/r) sum_j (1/2)_j/j! (x/r)^(2j) converges
    uniformly on [0, a] for r > a, and each term integrates in closed form. FAR_TERMS terms:
    u_z = (2 d a/(pi r)) sum_j (1/2)_j/j! n/((2j + 1)(n + 2j + 1)) (a/r)^(2j). Unlike the 2F1
    form it never squares r/a into an underflow (its (a/r)^2 terms underflow harmlessly).
    """
    xx = sp.Symbol("xx", positive=True)
    q = sp.Symbol("q", positive=True)
    g = solution()["g"].subs(c_n, d / (kappa_n * a**n)).subs(x, xx)  # (5.52) with (5.55)
    kernel = sp.series(1 / sp.sqrt(1 - q), q, 0, FAR_TERMS).removeO()  # (1 - (x/r)^2)^(-1/2)
    terms = []
    for j in range(FAR_TERMS):
        cj = kernel.coeff(q, j)
        moment = sp.integrate((g.subs(xx, a) - g) * xx ** (2 * j), (xx, 0, a))
        terms.append(sp.simplify(2 / sp.pi * cj * moment / r ** (2 * j + 1)))
    w = sp.Symbol("w", positive=True)  # (a/r)^2
    lead = sp.factor(terms[0])
    rest = [sp.factor(sp.simplify(tj / lead).subs(a, sp.sqrt(w) * r)) for tj in terms]
    for j, c in enumerate(rest):  # a power of (a/r)^2 with a rational coefficient in n
        assert c.free_symbols <= {n, w}, c
        assert sp.simplify(c - sp.rf(sp.Rational(1, 2), j) / sp.factorial(j) * (n + 1)
                           / ((2 * j + 1) * (n + 2 * j + 1)) * w**j) == 0, (j, c)
    return lead * sp.horner(sum(rest), w).subs(w, (a / r) ** 2)


w_out = symbol("w_out")


@cache
def displacement_outside_integrand() -> tuple[sp.Expr, sp.Expr]:
    """(5.60) as an integral over w in (0, asin(a/r)) with a smooth integrand, for any n.

    x = r sin(asin(a/r) - w) takes x from a (w = 0) to 0 (w = asin(a/r)) and removes the
    1/sqrt(r^2 - x^2) of (5.60): dx/sqrt(r^2 - x^2) = -dw. With g = d (x/a)^n (5.55), u_z(r) =
    integral of (2 d/pi)(1 - (r sin(asin(a/r) - w)/a)^n) dw, no cancellation: the integrand is
    positive. Returns (derived, stable): the stable form writes the power as
    exp(n log1p(-2 sin(w/2)^2 - sqrt(r - a) sqrt(r + a) sin(w)/a)) (the base is
    cos(w) - cot(asin(a/r)) sin(w)), which keeps the digits of a base 1 - O(1/n) and never
    squares r, and 1 - exp(...) as -expm1(...).
    """
    xx = sp.Symbol("xx", positive=True)
    g = solution()["g"].subs(c_n, d / (kappa_n * a**n))  # (5.52), d = g(a) (5.55)
    integrand = 2 / sp.pi * (g.subs(x, a) - g.subs(x, xx))  # (5.60) times sqrt(r^2 - x^2)
    derived = sp.powsimp(integrand.subs(xx, r * sp.sin(sp.asin(a / r) - w_out)), force=True)
    base = -2 * sp.sin(w_out / 2) ** 2 - sp.sqrt(r - a) * sp.sqrt(r + a) * sp.sin(w_out) / a
    stable = -2 * d / sp.pi * expm1(n * log1p(base))
    return derived, stable


def punch() -> dict[str, sp.Expr]:
    """Flat punch (Problem 7(a)): pressure from (5.59) with q' = -E* d delta(x - a)."""
    xx = sp.Symbol("xx", positive=True)
    qp = -E_star * d * sp.DiracDelta(xx - a)
    p = -1 / sp.pi * sp.integrate(qp / sp.sqrt(xx**2 - rp**2), (xx, rp, sp.oo))
    p = sp.simplify(p.subs(sp.Heaviside(rp - a), 0))  # inside, r < a
    F_limit = sp.limit(solution()["F_ad"], n, sp.oo)
    xx_ = sp.Symbol("xx", positive=True)  # (5.60) with g = 0 inside: u_z = d for |x| < a
    u_out = 2 / sp.pi * sp.integrate(d / sp.sqrt(rp**2 - xx_**2), (xx_, 0, a))
    u_out = sp.simplify(u_out.subs(rp, a / unit_interval())).subs(unit_interval(), a / r)
    return {"p": p.subs(rp, r), "F": F_limit, "u_out": u_out}


def relations() -> list[Relation]:
    s = solution()
    k = kappa()
    half = sp.Rational(1, 2)
    printed_kappa = sp.sqrt(sp.pi) / 2 * n * sp.gamma(n / 2) / sp.gamma(n / 2 + half)
    p_b, p_a = pressure_hyper()
    pq_derived, pq_stable = pressure_integrand()
    uq_derived, uq_stable = displacement_outside_integrand()
    outside = {r: a / unit_interval()}
    pun = punch()
    rels = [
        Relation("powerlaw_kappa", "Problem 7(d)", k, (n,),
                 "MDR factor kappa_n [1] of the power-law profile, g = kappa_n c_n |x|^n "
                 "(overflows for n > 340: use powerlaw_kappa_asymptotic there)",
                 "(5.52) for f = c_n r^n", f"{TEST}::test_kappa_by_quadrature",
                 printed=printed_kappa),
        Relation("powerlaw_kappa_asymptotic", "Problem 7(d), large n", kappa_asymptotic(),
                 (n,), f"kappa_n [1] from the Stirling series to O(n^-{STIRLING_ORDER}); "
                 "relative error < 1e-16 for n >= 40",
                 "the Stirling series of ln Gamma(n/2 + 1) - ln Gamma(n/2 + 1/2)",
                 f"{TEST}::test_kappa_by_quadrature"),
        Relation("powerlaw_g", "Problem 7(d)", s["g"], (c_n, kappa_n, n, x),
                 "MDR profile g(x) [m] of the power-law profile f = c_n r^n, x >= 0",
                 "(5.52) for f = c_n r^n", f"{TEST}::test_g_by_quadrature",
                 printed=kappa_n * c_n * x**n),
        Relation("powerlaw_profile", "Problem 7(d)", c_n * r**n, (c_n, n, r),
                 "height f(r) = c_n r^n [m] of a power-law profile above its tip (the profile "
                 "whose g is powerlaw_g)", "the profile put through (5.52)",
                 "tests/test_tangential.py::test_profiles_against_their_g_by_5_53"),
        Relation("powerlaw_contact_radius", "Problem 7(d)", s["a"], (c_n, d, kappa_n, n),
                 "contact radius a [m] of a power-law indenter at depth d",
                 "(5.55) with g of (5.52)", f"{TEST}::test_against_3d_elasticity",
                 printed=(d / (kappa_n * c_n)) ** (1 / n)),
        Relation("powerlaw_force", "Problem 7(d)", s["F"], (E_star, c_n, d, kappa_n, n),
                 "normal force F [N] of a power-law indenter at depth d",
                 "(5.57) at the contact radius of (5.55)", f"{TEST}::test_force_by_pressure",
                 printed=2 * n * E_star / (n + 1) * (kappa_n * c_n) ** (1 / n)
                 * d ** ((n + 1) / n),
                 erratum="the factor (kappa_n c_n)^(1/n) must be (kappa_n c_n)^(-1/n): with "
                 "a = (d/(kappa_n c_n))^(1/n), (5.57) gives F = 2n/(n+1) E* a d; for n = 2 "
                 "(kappa_2 c_2 = 1/R) only the corrected form reproduces (5.23)"),
        Relation("powerlaw_force_from_radius", "Problem 7(d), (5.57)", s["F_ad"],
                 (E_star, a, d, n),
                 "normal force F [N] of a power-law indenter with contact radius a at depth d",
                 "(5.57) with d = g(a) (5.55)", f"{TEST}::test_force_by_pressure"),
        Relation("powerlaw_depth_from_force", "Problem 7(d), inverted", s["d_F"],
                 (E_star, F, c_n, kappa_n, n),
                 "indentation depth d [m] of a power-law indenter under the force F",
                 "the force of Problem 7(d) solved for d", f"{TEST}::test_force_roundtrip",
                 stable=(F * (n + 1) / (2 * E_star * n)) ** (n / (n + 1))
                 * (kappa_n * c_n) ** (1 / (n + 1)),
                 stable_why="(kappa_n c_n)^(1/n) of the derived form overflows or underflows "
                 "for small n although d is ordinary (c_n = 1e-3, n = 3 at F = 1 N: NaN); "
                 "split into (F (n + 1)/(2 E* n))^(n/(n + 1)) (kappa_n c_n)^(1/(n + 1)), "
                 "whose factors stay within the range of the inputs"),
        Relation("powerlaw_mean_pressure_from_depth", "Fig. 5.17",
                 sp.powsimp(s["pm"].subs(a, s["a"]), force=True), (E_star, c_n, d, kappa_n, n),
                 "mean pressure F/(pi a^2) [Pa] of a power-law indenter at depth d",
                 "(5.57) over the contact area, a from (5.55)",
                 f"{TEST}::test_force_by_pressure",
                 stable=2 * E_star * n * d * (kappa_n * c_n / d) ** (1 / n) / (sp.pi * (n + 1)),
                 stable_why="the contact radius a = (d/(kappa_n c_n))^(1/n) underflows to 0 "
                 "for small n where F/(pi a^2) is still a float (and overflows where it is "
                 "not): one power of the ratio kappa_n c_n/d, times d"),
        Relation("powerlaw_mean_pressure", "Fig. 5.17", s["pm"], (E_star, a, d, n),
                 "mean pressure F/(pi a^2) [Pa] of a power-law indenter",
                 "(5.57) over the contact area", f"{TEST}::test_force_by_pressure"),
        Relation("powerlaw_pressure", "Problem 7(d), (5.59)", _hyper_arg_clipped(p_a),
                 (E_star, a, d, n, r),
                 "contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; accurate "
                 "for n >= 1.5 (use powerlaw_pressure_small_n below)",
                 "(5.59) with x = r/sqrt(1 - z t), then Euler's transformation",
                 f"{TEST}::test_against_3d_elasticity"),
        Relation("powerlaw_pressure_small_n", "Problem 7(d), (5.59)", _hyper_arg_clipped(p_b),
                 (E_star, a, d, n, r),
                 "contact pressure p(r) [Pa] of a power-law indenter, 0 for r > a; the form "
                 "accurate for n < 1.5 (singular like r^(n-1) at the centre for n < 1)",
                 "(5.59) with x = r/sqrt(1 - z t)", f"{TEST}::test_against_3d_elasticity"),
        Relation("powerlaw_pressure_centre", "Problem 7(d), (5.59), r << a",
                 pressure_centre(), (E_star, a, d, n, r),
                 "contact pressure p(r) [Pa] of a power-law indenter near the centre, "
                 f"0 < n < 3 (n != 1), r < a/10: the series to (r/a)^{2 * CENTRE_TERMS - 2} "
                 "plus its (r/a)^(n-1) term",
                 "the 2F1 of (5.59) by the connection formula z -> 1 - z (DLMF 15.8.4)",
                 f"{TEST}::test_pressure_near_the_centre_by_quadrature",
                 domain={r: a * unit_interval()}),
        Relation("powerlaw_displacement_far", "Problem 7(d), (5.60), r >> a",
                 displacement_far(), (a, d, n, r),
                 "surface displacement u_z(r) [m] of a power-law indenter far outside the "
                 f"contact (a/r < 1e-3: the series to (a/r)^{2 * FAR_TERMS - 1})",
                 "(5.60) with 1/sqrt(r^2 - x^2) expanded in (x/r)^2",
                 f"{TEST}::test_surface_displacement_far_outside",
                 domain={r: a / unit_interval()}),
        Relation("powerlaw_pressure_integrand", "Problem 7(d), (5.59)", pq_derived,
                 (E_star, a, d, n, r, w_quad),
                 "integrand [Pa] of (5.59) in w: p(r) = integral_0^1 of it dw, smooth in w (a "
                 "boundary layer of width ~1/(n (1 - r^2/a^2)) at w = 0 for large n)",
                 "(5.59) with x^2 = r^2 + (a^2 - r^2)(1 - w)^2",
                 f"{TEST}::test_pressure_large_n_by_quadrature",
                 stable=pq_stable,
                 stable_why="(x/a)^(n-2) with x/a = 1 - O(1/n) amplifies its rounding n-fold "
                 "and overflows/underflows in parts; written exp((n/2 - 1) log1p(-(1 - x^2/a^2)))"
                 " with 1 - x^2/a^2 factored",
                 domain={r: a * unit_interval(), w_quad: unit_interval("t_w")}),
        Relation("powerlaw_pressure_normalized", "Fig. 5.17",
                 _normalized(p_a, s["pm"]), (n, r_tilde),
                 "normalized pressure p/p_mean [1] at r_tilde = r/a < 1 of a power-law "
                 "indenter (n >= 1.5)", "(5.59) divided by (5.57)/(pi a^2)",
                 f"{TEST}::test_normalized_pressure_by_quadrature"),
        Relation("powerlaw_displacement_outside", "Problem 7(d), (5.60)", displacement_outside(),
                 (a, d, n, r),
                 "surface displacement u_z(r) [m] outside the contact (r > a) of a power-law "
                 "indenter", "(5.60) for r > a", f"{TEST}::test_against_3d_elasticity",
                 domain=outside),
        Relation("powerlaw_displacement_outside_integrand", "Problem 7(d), (5.60)",
                 uq_derived, (a, d, n, r, w_out),
                 "integrand [m] of (5.60) in w: u_z(r > a) = integral_0^asin(a/r) of it dw, "
                 "positive and smooth (a layer of width ~1/(n cot(asin(a/r))) at w = 0 for "
                 "large n)", "(5.60) with x = r sin(asin(a/r) - w)",
                 f"{TEST}::test_displacement_outside_large_n",
                 stable=uq_stable,
                 stable_why="(x/a)^n with x/a = 1 - O(1/n) amplifies its rounding n-fold and "
                 "r^2 - a^2 overflows for r > 1e154; written -expm1(n log1p(-2 sin(w/2)^2 - "
                 "sqrt(r - a) sqrt(r + a) sin(w)/a))",
                 domain={r: a / unit_interval(), w_out: sp.asin(unit_interval())
                         * unit_interval("t_w")}),
        Relation("powerlaw_punch_pressure", "Problem 7(a)", pun["p"], (E_star, a, d, r),
                 "contact pressure p(r) [Pa] under a flat rigid punch of radius a at depth d, "
                 "r < a", "(5.59) with q' = -E* d delta(x - a)", f"{TEST}::test_punch",
                 printed=E_star * d / (sp.pi * sp.sqrt(a**2 - r**2)),
                 domain={r: a * unit_interval()}),
        Relation("powerlaw_punch_force", "Problem 7(a)", pun["F"], (E_star, a, d),
                 "normal force F [N] of a flat rigid punch of radius a at depth d",
                 "the n -> infinity limit of (5.57) for the power law", f"{TEST}::test_punch",
                 printed=2 * E_star * a * d),
        Relation("powerlaw_punch_mean_pressure", "Problem 7(a)",
                 sp.simplify(pun["F"] / (sp.pi * a**2)), (E_star, a, d),
                 "mean pressure F/(pi a^2) [Pa] of a flat rigid punch of radius a at depth d",
                 "the punch's force over the contact area", f"{TEST}::test_punch"),
        Relation("powerlaw_punch_displacement_outside", "Problem 7(a)", pun["u_out"],
                 (a, d, r), "surface displacement u_z(r) [m] outside a flat punch (r > a)",
                 "the n -> infinity limit of (5.60) for the power law", f"{TEST}::test_punch",
                 printed=2 * d / sp.pi * sp.asin(a / r), domain=outside),
    ]
    for kk in (1, 2, 3, 4):
        rels.append(Relation(
            f"powerlaw_pressure_n{kk}", f"Problem 7(d), n = {kk}",
            pressure_integer(kk), (E_star, a, d, r),
            f"contact pressure p(r) [Pa] of the power-law indenter n = {kk} for 0 < r < a, "
            "in elementary functions", f"(5.59) for f = c_{kk} r^{kk}",
            f"{TEST}::test_against_3d_elasticity", domain={r: a * unit_interval()}))
    return rels
