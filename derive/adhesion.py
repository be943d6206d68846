"""Adhesive (JKR-type) contact of axisymmetric profiles by the MDR, (5.51)-(5.61).

Starting point: the non-adhesive MDR of :mod:`hertzmdr.derive.mdr` and the energy balance of
the 3-D contact. Nothing of the adhesive theory is typed in; every step is derived here:

1. The state (a, d). In an adhesive contact the depth d and the contact radius a are
   independent: the springs inside are displaced by u_z(x) = d - g(x) (5.54), and (5.57) gives
   F(a, d) = 2 E* integral_0^a (d - g(x)) dx. At fixed a the contact is a rigid flat punch
   (dF/dd = 2 E* a), so the 3-D state (a, d) is the non-adhesive state of radius a (depth
   g(a), (5.55)) plus a flat punch of radius a pushed by d - g(a).
2. The elastic energy of that state: U(a, d) = U_0(a) + integral_g(a)^d F(a, delta) d delta,
   where U_0(a) = integral_0^a F(a', g(a')) g'(a') da' is the work of the non-adhesive loading.
3. The energy release rate G = (1/(2 pi a)) dU/da at fixed d (the elastic energy freed per
   unit of new contact area, with g left an undefined function); SymPy gives
   G = E* (g(a) - d)^2 / (2 pi a), for every profile.
4. Griffith's balance G = Delta gamma fixes the critical elongation of the boundary spring,
   Delta l(a) = g(a) - d = sqrt(2 pi a Delta gamma / E*) (the root with d < g(a): the edge
   springs are stretched), hence d(a) = g(a) - Delta l(a) and F(a) = F(a, d(a)).
5. Pressure (5.59): the line load q = E* (d - g) jumps from -E* Delta l to 0 at x = a, so
   q' carries E* Delta l delta(x - a), which adds the flat-punch term
   -E* Delta l / (pi sqrt(a^2 - r^2)): the 1/sqrt(a - r) edge singularity. The outside
   displacement (5.60) gains -(2/pi) Delta l asin(a/r).
6. Stability: dF/da and dd/da along d(a), derived from (5.57) for an undefined g. Under force
   control the contact is stable while dF/da > 0 and separates at dF/da = 0
   (a g'(a) = 3 Delta l/2); under depth control it is stable while dd/da > 0 and separates at
   dd/da = 0 (a g'(a) = Delta l/2).

Closed forms are then derived by putting the profiles' g (5.52) through steps 4-6: the flat
punch (Kendall), the paraboloid (JKR; g from (5.52) of r^2/(2R)), the cone (g from (5.52) of
r tan(theta)) and the power law c_n r^n (Hess, g = kappa_n c_n x^n): depth, force, pull-off
radius, force and depth under both controls (solved by SymPy from dF/da = 0 and dd/da = 0),
the zero-load radius. The power law has a pull-off only for n > 1/2.

The Tabor parameter mu_T = (R Delta gamma^2 / (E*^2 z0^3))^(1/3) is a definition (Tabor 1977),
not a derivation: JKR holds for mu_T >> 1 (in practice mu_T > 5), DMT for mu_T << 1.
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.codegen.cfunctions import log1p

from hertzmdr.derive import mdr, powerlaw, sphere, worn
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, R, a, d, r, symbol, unit_interval

x = mdr.x
dgamma = symbol("dgamma")
g_a = symbol("g_a")
g_slope = symbol("g_slope")
F_load = symbol("F_load", real=True)
z0 = symbol("z0")
theta = symbol("theta")
n, c_n, kappa_n = powerlaw.n, powerlaw.c_n, powerlaw.kappa_n

TEST = "tests/test_adhesion.py"


@cache
def energy_balance() -> dict[str, sp.Expr]:
    """Steps 1-4 for an undefined profile g: G(a, d) and the critical elongation Delta l(a)."""
    gf = sp.Function("g")
    ap, delta, xi = sp.symbols("a_p delta xi", positive=True)
    # (5.57) at an independent depth: F(a, d) = 2 E* integral_0^a (d - g(x)) dx
    F_ad = 2 * E_star * sp.Integral(d - gf(xi), (xi, 0, a)).doit()
    stiffness = sp.simplify(sp.diff(F_ad, d))
    assert sp.simplify(stiffness - 2 * E_star * a) == 0  # the flat punch (5.12)
    # the non-adhesive path d = g(a') (5.55) from a' = 0 to a: U_0 = int F(a', g(a')) g'(a')
    U0 = sp.Integral((F_ad.subs(d, gf(a)) * sp.diff(gf(a), a)).subs(a, ap), (ap, 0, a))
    # then at fixed a, the punch from g(a) to d
    U = U0 + sp.integrate(F_ad.subs(d, delta), (delta, gf(a), d))
    G = sp.simplify(sp.diff(U, a).doit() / (2 * sp.pi * a))  # energy release rate [J/m^2]
    g_sym = sp.Symbol("g_of_a", positive=True)
    G = sp.factor(sp.simplify(G.subs(gf(a), g_sym)))
    assert not G.has(sp.Integral, sp.Derivative), G
    roots = sp.solve(sp.Eq(G, dgamma), d)
    # the edge springs are stretched: d < g(a)
    (d_crit,) = [s for s in roots if (s - g_sym).subs({a: 1, dgamma: 1, E_star: 1}).is_negative]
    dl = sp.simplify(g_sym - d_crit)
    return {"G": G.subs(g_sym, g_a), "dl": dl, "g_sym": g_sym}


def critical_elongation() -> sp.Expr:
    """Delta l(a) = sqrt(2 pi a Delta gamma / E*), from G = Delta gamma."""
    return energy_balance()["dl"]


@cache
def slopes() -> dict[str, sp.Expr]:
    """dF/da and dd/da along d = g(a) - Delta l(a), for an undefined g (step 6)."""
    gf = sp.Function("g")
    xi = sp.Symbol("xi", positive=True)
    dl = critical_elongation()
    depth = gf(a) - dl
    F = 2 * E_star * (depth * a - sp.Integral(gf(xi), (xi, 0, a)))  # (5.57)
    sub = {sp.Derivative(gf(a), a): g_slope, gf(a): g_a}
    dF = sp.simplify(sp.diff(F, a).doit().subs(sub))
    dd = sp.simplify(sp.diff(depth, a).subs(sub))
    return {"dF": sp.expand(dF), "dd": sp.expand(dd)}


@cache
def edge_terms() -> dict[str, sp.Expr]:
    """The terms the jump of q at x = a adds to (5.59) and (5.60) (step 5)."""
    rp, xx = sp.Symbol("r", positive=True), sp.Symbol("xx", positive=True)
    dl = critical_elongation()
    # q(x) = E* (d - g(x)) for x < a and 0 beyond: q(a-) = -E* dl, so q' has + E* dl delta
    qp_jump = E_star * dl * sp.DiracDelta(xx - a)
    p = -1 / sp.pi * sp.integrate(qp_jump / sp.sqrt(xx**2 - rp**2), (xx, rp, sp.oo))
    p = sp.simplify(p.subs(sp.Heaviside(rp - a), 0))  # inside, r < a
    # (5.60) of the constant u_z = -dl on |x| < a, outside (r > a)
    u = 2 / sp.pi * sp.integrate(-dl / sp.sqrt(rp**2 - xx**2), (xx, 0, a))
    u = sp.simplify(u.subs(rp, a / unit_interval())).subs(unit_interval(), a / r)
    return {"p": p.subs(rp, r), "u_out": u}


def _stable_edge_pressure() -> sp.Expr:
    return -E_star * critical_elongation() / (sp.pi * sp.sqrt((a - r) * (a + r)))


@cache
def family(g: sp.Expr, coef: sp.Symbol) -> dict[str, sp.Expr]:
    """Steps 4-6 for a profile with the MDR profile g(x): d(a), F(a), pull-off, zero load.

    ``coef`` is the profile's shape coefficient (R, tan(theta), c_n): at a pull-off radius the
    condition dF/da = 0 (or dd/da = 0) is solved for it and put into F(a) and d(a), which then
    read -E* a Delta l (2n - 1)/(n + 1) and the like, evaluated at the pull-off radius.
    """
    dl = critical_elongation()
    depth = sp.simplify(g.subs(x, a) - dl)  # (5.55) with the stretched boundary spring
    F = sp.expand(sp.simplify(mdr.force(g) - 2 * E_star * a * dl))  # (5.57) at d(a)
    sl = slopes()
    gp = sp.diff(g, x).subs(x, a)
    dF = sl["dF"].subs({g_slope: gp, g_a: g.subs(x, a)})
    dd = sl["dd"].subs({g_slope: gp, g_a: g.subs(x, a)})
    assert sp.simplify(dF - sp.diff(F, a)) == 0, (dF, sp.diff(F, a))
    assert sp.simplify(dd - sp.diff(depth, a)) == 0

    def root(expr):
        sols = [s for s in sp.solve(sp.Eq(expr, 0), a) if s != 0]
        assert len(sols) == 1, (expr, sols)
        return sp.simplify(sols[0])

    out = {"d": depth, "F": F, "a_fc": root(dF), "a_dc": root(dd), "a_0": root(F)}
    for key, cond in (("fc", dF), ("dc", dd)):
        (c_at,) = sp.solve(sp.Eq(cond, 0), coef)  # the stationarity condition
        ac = out[f"a_{key}"]
        out[f"F_{key}"] = sp.factor(sp.simplify(F.subs(coef, c_at))).subs(a, ac)
        out[f"d_{key}"] = sp.factor(sp.simplify(depth.subs(coef, c_at))).subs(a, ac)
    return out


@cache
def jkr() -> dict[str, sp.Expr]:
    """The paraboloid f = r^2/(2R): g from (5.52), then :func:`family`; a(F) from F(a)."""
    rr = sp.Symbol("rr", positive=True)
    g = mdr.transform(rr**2 / (2 * R), rr)
    out = dict(family(g, R))
    # F(a) is a quadratic in s = a^(3/2); the stable branch is the larger root
    s = sp.Symbol("s", positive=True)
    Fs = sp.expand(out["F"].subs(a, s ** sp.Rational(2, 3)))
    roots = sp.solve(sp.Eq(Fs, F_load), s)
    big = [q for q in roots if (q - sum(roots) / 2).subs(
        {E_star: 1, R: 1, dgamma: 1, F_load: 1}).is_positive]
    (s_F,) = big
    out["a_F"] = sp.simplify(s_F ** sp.Rational(2, 3))
    out["p"] = sp.simplify(mdr.pressure(g) + edge_terms()["p"])  # (5.59)
    out["g"] = g
    return out


@cache
def cone() -> dict[str, sp.Expr]:
    rr = sp.Symbol("rr", positive=True)
    tan_t = sp.Symbol("tan_theta", positive=True)  # 0 < theta < pi/2
    g = mdr.transform(rr * tan_t, rr)
    return {k: v.subs(tan_t, sp.tan(theta)) for k, v in dict(family(g, tan_t), g=g).items()}


@cache
def power() -> dict[str, sp.Expr]:
    return dict(family(powerlaw.solution()["g"], c_n))


@cache
def slopes_of_profiles() -> dict[str, sp.Expr]:
    """g'(x) of the exact sphere, the worn paraboloid (x > b), the paraboloid, the cone and the
    power law (x > 0), from their (5.52)."""
    rr = sp.Symbol("rr", positive=True)
    return {"sphere": sp.simplify(sp.diff(sphere.solution()["g"], x)),
            "worn": sp.simplify(sp.diff(worn.solution()["g"], x)),
            "paraboloid": sp.diff(mdr.transform(rr**2 / (2 * R), rr), x),
            "cone": sp.diff(cone()["g"], x),
            "powerlaw": sp.diff(powerlaw.solution()["g"], x)}


@cache
def punch() -> dict[str, sp.Expr]:
    """Kendall's flat punch of radius a: g = 0 inside, so d = -Delta l at separation."""
    dl = critical_elongation()
    xi = sp.Symbol("xi", positive=True)
    F_depth = 2 * E_star * sp.integrate(d + 0 * xi, (xi, 0, a))  # (5.57) with g = 0
    # the work on the contact over an approach-push-retract cycle to a depth d_t > 0: F = 0
    # until d = 0, F_depth up to d_t and back down to d = -Delta l, then the jump to F = 0
    d_t, dd = sp.symbols("d_t dd", positive=True)
    Fd = F_depth.subs(d, dd)
    W = sp.simplify(sp.integrate(Fd, (dd, 0, d_t)) - sp.integrate(Fd, (dd, -dl, d_t)))
    assert not W.has(d_t), W
    return {"F_c": sp.simplify(F_depth.subs(d, -dl)), "d_c": -dl, "W": W}


def relations() -> list[Relation]:
    eb = energy_balance()
    dl = critical_elongation()
    sl = slopes()
    et = edge_terms()
    sps = slopes_of_profiles()
    b = worn.b
    j, c, pw, pu = jkr(), cone(), power(), punch()
    K = 4 * E_star / 3
    lit_jkr_F = K * a**3 / R - sp.sqrt(8 * sp.pi * dgamma * E_star * a**3)
    inside = {r: a * unit_interval()}
    outside = {r: a / unit_interval()}
    rels = [
        Relation("adhesion_energy_release_rate", "(5.57), energy balance", eb["G"],
                 (E_star, a, d, g_a),
                 "energy release rate G [J/m^2] at the edge of a contact of radius a at depth d",
                 "dU/da at fixed d over 2 pi a, U the work of (5.57) along the non-adhesive "
                 "path plus a flat punch", f"{TEST}::test_energy_release_rate_by_3d_route"),
        Relation("adhesion_critical_elongation", "(5.55), energy balance", dl,
                 (E_star, a, dgamma),
                 "critical elongation Delta l [m] of the boundary spring, g(a) - d",
                 "G = Delta gamma solved for d", f"{TEST}::test_energy_release_rate_by_3d_route"),
        Relation("adhesion_depth", "(5.55), adhesive", g_a - dl, (E_star, a, dgamma, g_a),
                 "indentation depth d [m] of an adhesive contact of radius a, g(a) - Delta l",
                 "(5.55) with the stretched boundary spring",
                 f"{TEST}::test_jkr_literature"),
        Relation("adhesion_force_slope", "(5.57), adhesive", sl["dF"],
                 (E_star, a, dgamma, g_slope),
                 "dF/da [N/m] along an adhesive contact; 0 at pull-off under force control",
                 "the derivative of (5.57) along d = g(a) - Delta l(a)",
                 f"{TEST}::test_pull_off_by_mpmath_minimization"),
        Relation("adhesion_depth_slope", "(5.55), adhesive", sl["dd"],
                 (E_star, a, dgamma, g_slope),
                 "dd/da [1] along an adhesive contact; 0 at pull-off under depth control",
                 "the derivative of d = g(a) - Delta l(a)",
                 f"{TEST}::test_pull_off_by_mpmath_minimization"),
        Relation("adhesion_pressure_edge", "(5.59), adhesive", et["p"],
                 (E_star, a, dgamma, r),
                 "adhesive term of the contact pressure p(r) [Pa] for r < a (negative: "
                 "tension; add the non-adhesive pressure of radius a)",
                 "(5.59) with the jump of q(x) at x = a",
                 f"{TEST}::test_jkr_pressure_by_boussinesq",
                 stable=_stable_edge_pressure(),
                 stable_why="a^2 - r^2 loses the digits of a - r next to the edge, where the "
                 "term is largest; written (a - r)(a + r)", domain=inside),
        Relation("adhesion_displacement_outside_edge", "(5.60), adhesive", et["u_out"],
                 (E_star, a, dgamma, r),
                 "adhesive term of the surface displacement u_z(r) [m] outside the contact "
                 "(r > a); add the non-adhesive displacement of radius a",
                 "(5.60) of the constant u_z = -Delta l on |x| < a",
                 f"{TEST}::test_jkr_pressure_by_boussinesq",
                 printed=-2 / sp.pi * dl * sp.asin(a / r), domain=outside),
        Relation("adhesion_punch_pull_off_force", "(5.57), Kendall", pu["F_c"],
                 (E_star, a, dgamma),
                 "pull-off force F_c [N] of a flat punch of radius a (Kendall), negative",
                 "(5.57) with g = 0 at d = -Delta l", f"{TEST}::test_kendall_literature",
                 printed=-sp.sqrt(8 * sp.pi * a**3 * E_star * dgamma)),
        Relation("adhesion_punch_cycle_work", "(5.57), Kendall", pu["W"], (E_star, a, dgamma),
                 "work W [J] done on a flat punch of radius a over an approach-push-retract "
                 "cycle: dissipated by the jump at pull-off (>= 0)",
                 "the closed integral of (5.57) with g = 0 over the cycle",
                 f"{TEST}::test_punch_cycle_work_is_kendalls"),
        Relation("jkr_depth", "(5.55), JKR", j["d"], (E_star, R, a, dgamma),
                 "indentation depth d [m] of a paraboloid in JKR contact of radius a",
                 "(5.52) of r^2/(2R), (5.55) with Delta l", f"{TEST}::test_jkr_literature",
                 printed=a**2 / R - sp.sqrt(2 * sp.pi * a * dgamma / E_star)),
        Relation("jkr_force_from_radius", "(5.57), JKR", j["F"], (E_star, R, a, dgamma),
                 "normal force F [N] of a paraboloid in JKR contact of radius a",
                 "(5.57) at the adhesive depth", f"{TEST}::test_jkr_literature",
                 printed=lit_jkr_F),
        Relation("jkr_contact_radius_from_force", "(5.57), JKR, inverted", j["a_F"],
                 (E_star, F_load, R, dgamma),
                 "contact radius a [m] of a paraboloid in JKR contact under the force F_load "
                 ">= -3 pi R dgamma/2 (the stable branch)",
                 "(5.57) as a quadratic in a^(3/2), larger root",
                 f"{TEST}::test_jkr_literature"),
        Relation("jkr_pressure", "(5.59), JKR", j["p"], (E_star, R, a, dgamma, r),
                 "contact pressure p(r) [Pa] of a paraboloid in JKR contact, r < a",
                 "(5.59): Hertz's pressure of radius a plus the edge term",
                 f"{TEST}::test_jkr_pressure_by_boussinesq", domain=inside,
                 stable=2 * E_star * sp.sqrt((a - r) * (a + r)) / (sp.pi * R)
                 + _stable_edge_pressure(),
                 stable_why="Hertz's part and the edge term apart, each with (a - r)(a + r) "
                 "for a^2 - r^2, which loses the digits of a - r next to the edge"),
        Relation("adhesion_sphere_g_slope", "(5.52), Sneddon's sphere", sps["sphere"],
                 (R, x), "slope g'(x) [1] of the MDR profile of the exact sphere, 0 <= x < R",
                 "the derivative of (5.52) for the spherical cap",
                 f"{TEST}::test_g_slopes_by_differences",
                 stable=log1p(2 * x / (R - x)) / 2 + R * x / ((R - x) * (R + x)),
                 stable_why="atanh(x/R) as log1p(2x/(R - x))/2 and R^2 - x^2 as "
                 "(R - x)(R + x), exact as x -> R where the slope is largest",
                 domain={x: R * unit_interval()}),
        Relation("adhesion_paraboloid_g_slope", "(5.52) of r^2/(2R)", sps["paraboloid"],
                 (R, x), "slope g'(x) [1] of the MDR profile of the paraboloid, x >= 0",
                 "the derivative of (5.52) for f = r^2/(2R)",
                 f"{TEST}::test_g_slopes_by_differences"),
        Relation("adhesion_cone_g_slope", "(5.52) of r tan(theta)", sps["cone"], (theta,),
                 "slope g'(x) [1] of the MDR profile of the cone (the same at every x > 0)",
                 "the derivative of (5.52) for f = r tan(theta)",
                 f"{TEST}::test_g_slopes_by_differences"),
        Relation("adhesion_powerlaw_g_slope", "(5.52), Problem 7(d)", sps["powerlaw"],
                 (c_n, kappa_n, n, x),
                 "slope g'(x) [1] of the MDR profile of the power law f = c_n r^n, x > 0",
                 "the derivative of (5.52) for f = c_n r^n, g = kappa_n c_n x^n",
                 f"{TEST}::test_g_slopes_by_differences",
                 stable=n * kappa_n * c_n * x ** (n - 1),
                 stable_why="x^n/x is 0/0 at x = 0 and overflows before x^(n - 1) does"),
        Relation("adhesion_worn_g_slope", "(5.52), Problem 8", sps["worn"], (R, b, x),
                 "slope g'(x) [1] of the MDR profile of the worn paraboloid for x > b (0 for "
                 "x < b; infinite at the kink x = b+)",
                 "the derivative of (5.52) for f = (r^2 - b^2)/(2R), r > b",
                 f"{TEST}::test_g_slopes_by_differences",
                 stable=(2 * x**2 - b**2) / (R * sp.sqrt((x - b) * (x + b))),
                 stable_why="x^2 - b^2 as (x - b)(x + b), exact next to the kink",
                 domain={x: b / unit_interval()}),
        Relation("adhesion_tabor_parameter", "Tabor (1977)",
                 (R * dgamma**2 / (E_star**2 * z0**3)) ** sp.Rational(1, 3),
                 (E_star, R, dgamma, z0),
                 "Tabor parameter mu_T [1]: JKR holds for mu_T > 5, DMT for mu_T < 0.1",
                 "the ratio of the JKR neck height to the range z0 (a definition)",
                 f"{TEST}::test_tabor_parameter"),
    ]
    lit = {"F_fc": -3 * sp.pi * R * dgamma / 2, "F_dc": -5 * sp.pi * R * dgamma / 6,
           "a_fc": (9 * sp.pi * dgamma * R**2 / (8 * E_star)) ** sp.Rational(1, 3),
           "a_dc": (sp.pi * dgamma * R**2 / (8 * E_star)) ** sp.Rational(1, 3),
           "a_0": (9 * sp.pi * dgamma * R**2 / (2 * E_star)) ** sp.Rational(1, 3)}
    what = {"fc": "under force control", "dc": "under depth control"}
    for prefix, sol, shape, label, test in (
            ("jkr", j, (R,), "a paraboloid (JKR)", "test_jkr_literature"),
            ("adhesion_cone", c, (theta,), "a cone", "test_pull_off_by_mpmath_minimization"),
            ("adhesion_powerlaw", pw, (c_n, kappa_n, n),
             "a power-law profile c_n r^n (n > 1/2)", "test_pull_off_by_mpmath_minimization")):
        args = (E_star, dgamma, *shape)
        is_jkr = prefix == "jkr"
        if not is_jkr:
            rels.append(Relation(f"{prefix}_depth", "(5.55), adhesive", sol["d"],
                                 (E_star, a, dgamma, *shape),
                                 f"indentation depth d [m] of {label} in adhesive contact of "
                                 "radius a", "(5.52), (5.55) with Delta l",
                                 f"{TEST}::{test}"))
            rels.append(Relation(f"{prefix}_force_from_radius", "(5.57), adhesive", sol["F"],
                                 (E_star, a, dgamma, *shape),
                                 f"normal force F [N] of {label} in adhesive contact of "
                                 "radius a", "(5.57) at the adhesive depth", f"{TEST}::{test}"))
        for key in ("fc", "dc"):
            rels.append(Relation(
                f"{prefix}_pull_off_radius_{key}", "(5.57), adhesive", sol[f"a_{key}"],
                args, f"contact radius a_c [m] at pull-off of {label} {what[key]}",
                "dF/da = 0" if key == "fc" else "dd/da = 0", f"{TEST}::{test}",
                printed=lit[f"a_{key}"] if is_jkr else None))
            rels.append(Relation(
                f"{prefix}_pull_off_force_{key}", "(5.57), adhesive", sol[f"F_{key}"],
                args, f"pull-off force F_c [N] (negative) of {label} {what[key]}",
                "(5.57) at the pull-off radius", f"{TEST}::{test}",
                printed=lit[f"F_{key}"] if is_jkr else None))
            rels.append(Relation(
                f"{prefix}_pull_off_depth_{key}", "(5.55), adhesive", sol[f"d_{key}"],
                args, f"depth d_c [m] at pull-off of {label} {what[key]} (negative: "
                "the surface is pulled up)", "(5.55) with Delta l at the pull-off radius",
                f"{TEST}::{test}"))
        rels.append(Relation(
            f"{prefix}_zero_load_radius", "(5.57), adhesive", sol["a_0"], args,
            f"contact radius a_0 [m] of {label} at zero load", "F(a) = 0 of (5.57)",
            f"{TEST}::{test}", printed=lit["a_0"] if is_jkr else None))
    return rels
