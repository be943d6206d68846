"""Models of a measured force-position curve, and their Jacobians, for fitting (issue 17).

A force curve records the force F on the tip against the position z_p of its base, increasing
into the sample. Before contact the force is a baseline F_0 + s_0 z_p (an offset and the drift
or the viscous drag of the cantilever); after the contact point z_0 the tip indents the sample
by d = z_p - z_0 (a rigid tip: the cantilever's deflection is assumed already subtracted) and
the tip's force law is added:

    F(z_p; E*, z_0, F_0, s_0) = F_tip(E*, d = max(0, z_p - z_0)) + F_0 + s_0 z_p.

Starting point: the force laws F_tip(d) derived in their own families -- Hertz's paraboloid
(5.23) in :mod:`hertzmdr.derive.hertz`, the cone (5.40) in :mod:`hertzmdr.derive.cone`, the power
law and the flat punch (Problem 7) in :mod:`hertzmdr.derive.powerlaw`, the exact sphere
(Sneddon's, (5.55) and (5.57) in lam = atanh(a/R)) in :mod:`hertzmdr.derive.sphere` -- are
taken as SymPy expressions, not retyped. SymPy differentiates the model: F is linear in E*, F_0
and s_0 (asserted here: dF/dF_0 = 1, dF/ds_0 = z_p), and dF/dz_0 = -dF_tip/dd at d > 0. At the
contact point the force laws go as d^((n+1)/n) (n = 2 for the paraboloid, 1 for the cone, any
n > 0 for a power law), so dF/dz_0 ~ d^(1/n) -> 0, continuous; the flat punch (n -> inf) has
F = 2 E* a d, whose dF/dz_0 jumps from -2 E* a to 0. max(0, z_p - z_0) differentiates to
-Heaviside(z_p - z_0); the Heaviside is printed with the value 0 at 0 (the left derivative,
no contact), so that dF/dz_0 = 0 wherever d <= 0 for every tip.

The exact sphere has no closed form F(d): its depth and force are both functions of
lam = atanh(a/R). Its model is written at the lam of the indentation (solved for by
:mod:`hertzmdr.numeric.sphere`'s bisection) and dF/dz_0 = -(dF/dlam)/(dd/dlam), which SymPy
simplifies to the stiffness -2 E* a = -2 E* R tanh(lam) (0 at lam = 0, no contact).
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import bodies, cone, hertz, powerlaw, sphere
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E, E_star, R, a, d, nu, symbol, unit_interval

TEST = "tests/test_fit.py"
JAC_TEST = f"{TEST}::test_jacobian_by_mpmath_derivative"
FORCE_TEST = f"{TEST}::test_model_by_forward_models"

z_p = symbol("z_p", real=True)
z_0 = symbol("z_0", real=True)
F_0 = symbol("F_0", real=True)
s_0 = symbol("s_0", real=True)


def _heaviside_left(expr: sp.Expr) -> sp.Expr:
    """Every Heaviside(x) written Heaviside(x, 0): the derivative at d = 0 is that of no contact."""
    return expr.replace(sp.Heaviside, lambda *args: sp.Heaviside(args[0], 0))


@cache
def tip_forces() -> dict[str, tuple[sp.Expr, tuple[sp.Symbol, ...], str]]:
    """F_tip(d) of each closed-form tip: (expression, its geometry arguments, where it is from)."""
    pun = powerlaw.punch()
    return {
        "hertz": (hertz.solution()["F"], (R,), "(5.23)"),
        "cone": (cone.solution()["F"], (cone.theta,), "(5.40)"),
        "punch": (pun["F"], (a,), "Problem 7(a)"),
        "powerlaw": (powerlaw.solution()["F"], (powerlaw.c_n, powerlaw.kappa_n, powerlaw.n),
                     "Problem 7(d)"),
    }


def _assert_linear_in_modulus(name, model, dE, dz0):
    """F = E* dF/dE* + F_0 + s_0 z_p and dF/dz_0 proportional to E*: what lets numeric/fit.py
    evaluate the tip's shape once per contact point (E* times it is the tip's force) and solve
    (E*, F_0, s_0) by linear least squares at a fixed z_0."""
    if sp.simplify(model - E_star * dE - F_0 - s_0 * z_p) != 0:
        raise AssertionError(f"the {name} model is not E* dF/dE* + F_0 + s_0 z_p")
    if sp.diff(dE, E_star) != 0 or sp.simplify(sp.diff(dz0, E_star, 2)) != 0:
        raise AssertionError(f"the {name} model's derivatives are not linear in E*")


@cache
def models() -> dict[str, dict[str, sp.Expr]]:
    """For each closed-form tip: the model F and its derivatives in E* and z_0."""
    out = {}
    for name, (force, _, _) in tip_forces().items():
        model = force.subs(d, sp.Max(0, z_p - z_0)) + F_0 + s_0 * z_p
        if sp.diff(model, F_0) != 1 or sp.diff(model, s_0) != z_p:
            raise AssertionError(f"the baseline of the {name} model is not F_0 + s_0 z_p")
        dE = sp.diff(model, E_star)
        dz0 = sp.factor_terms(_heaviside_left(sp.diff(model, z_0)))
        _assert_linear_in_modulus(name, model, dE, dz0)
        out[name] = {"F": model, "dE": dE, "dz0": dz0}
    return out


@cache
def sphere_model() -> dict[str, sp.Expr]:
    """The exact sphere's model at lam = atanh(a/R), and its derivatives in E* and z_0."""
    s = sphere.solution()
    lam = sphere.lam
    model = s["F_lam"] + F_0 + s_0 * z_p
    # d = z_p - z_0 = d(lam): dlam/dz_0 = -1/(dd/dlam)
    dz0 = sp.simplify(-sp.diff(s["F_lam"], lam) / sp.diff(s["d_lam"], lam))
    if sp.simplify(dz0 + 2 * E_star * s["a_lam"]) != 0:
        raise AssertionError(f"dF/dz_0 of the exact sphere is not -2 E* a: {dz0}")
    stable = sphere.force_lam_stable() + F_0 + s_0 * z_p
    dE = sp.diff(model, E_star)
    _assert_linear_in_modulus("exact sphere", model, dE, dz0)
    # Newton's step for lam in d = d(lam): dd/dlam, positive for lam > 0
    d_dlam = sp.simplify(sp.diff(s["d_lam"], lam))
    return {"F": model, "F_stable": stable, "dE": dE, "dz0": dz0, "d_dlam": d_dlam}


alpha_p = symbol("alpha_p", positive=True)
n_sides = symbol("n_sides", positive=True)
beta_p = symbol("beta_p", positive=True)


@cache
def pyramid_cone() -> sp.Expr:
    """theta [rad] of the cone with the cross-section area of a regular pyramid at every depth.

    A regular pyramid of n faces and half-angle alpha_p (axis to a face's mid-line) cut at the
    depth d below its apex is a regular n-gon of apothem d tan(alpha_p), area
    n (d tan(alpha_p))^2 tan(pi/n); the cone f = r tan(theta) (5.38) has the disc of radius
    d/tan(theta), area pi (d/tan(theta))^2. Equal areas at every depth give cot(theta). The
    pyramid is not axisymmetric: the cone's force (5.40) at this theta is an approximation of the
    pyramid's, not the chapter's result (docs/fitting.md).
    """
    cot = sp.Symbol("cot_theta", positive=True)
    depth = symbol("d")
    area_ngon = n_sides * (depth * sp.tan(alpha_p)) ** 2 * sp.tan(sp.pi / n_sides)
    roots = sp.solve(sp.Eq(sp.pi * (depth * cot) ** 2, area_ngon), cot)
    # two roots +-: SymPy cannot tell tan(alpha_p) > 0 (alpha_p < pi/2); keep the positive one
    root = max(roots, key=lambda e: e.subs({alpha_p: sp.Rational(1, 2), n_sides: 4}))
    if len(roots) != 2 or sp.simplify(roots[0] + roots[1]) != 0:
        raise AssertionError(f"the pyramid's equal-area cone: unexpected roots {roots}")
    return sp.atan(1 / root)


def pyramid_force_cone() -> sp.Expr:
    """theta [rad] of the cone whose force (5.40) is the pyramid's at every depth.

    The pyramid's force is beta_p times its equal-area cone's (:func:`pyramid_cone`), beta_p
    measured by the BEM for each number of faces (benchmarks/pyramid_factor.py,
    docs/pyramid.md); (5.40) is E* d^2 times a function of theta alone, so the cone with
    F(theta) = beta_p F(theta_area) carries the pyramid's force law exactly (to beta_p's
    error); its pressure and contact radius stand in for the pyramid's non-circular ones.
    """
    theta = cone.theta
    F = cone.solution()["F"]
    th = sp.Symbol("th", positive=True)
    target = beta_p * F.subs(theta, pyramid_cone())
    roots = sp.solve(sp.Eq(F.subs(theta, th), target), sp.tan(th))
    if len(roots) != 1:
        raise AssertionError(f"the pyramid's equal-force cone: unexpected roots {roots}")
    return sp.atan(sp.simplify(roots[0]))


@cache
def sample_modulus() -> dict[str, sp.Expr]:
    """The sample's Young's modulus E1 from the fitted E* (5.26), under a rigid or elastic tip."""
    E1, nu1, E2 = bodies.E1, bodies.nu1, bodies.E2
    eff = bodies.effective_modulus()
    (rigid,) = sp.solve(sp.Eq(E_star, eff["E_star_rigid"]), E)
    (elastic,) = sp.solve(sp.Eq(E_star, eff["E_star"]), E1)
    elastic = sp.simplify(elastic)
    if sp.simplify(sp.limit(elastic, E2, sp.oo) - rigid.subs({E: E1, nu: nu1})) != 0:
        raise AssertionError(f"the elastic-tip modulus {elastic} has not the rigid limit {rigid}")
    return {"rigid": rigid, "elastic": elastic,
            "rigid_dE": sp.diff(rigid, E_star), "elastic_dE": sp.simplify(sp.diff(elastic, E_star))}


def relations() -> list[Relation]:
    rels = []
    mod = sample_modulus()
    E2, nu1, nu2 = bodies.E2, bodies.nu1, bodies.nu2
    rels += [
        Relation("fit_sample_modulus_rigid", "(5.8), inverted", mod["rigid"], (E_star, nu),
                 "Young's modulus E [Pa] of the sample under a rigid tip, from the fitted E*",
                 "(5.8) solved for E", f"{TEST}::test_sample_modulus",
                 printed=E_star * (1 - nu**2)),
        Relation("fit_sample_modulus_rigid_dE", "(5.8), inverted", mod["rigid_dE"], (nu,),
                 "derivative dE/dE* [1] of the sample's modulus under a rigid tip",
                 "(5.8) solved for E, differentiated in E*", f"{TEST}::test_sample_modulus"),
        Relation("fit_sample_modulus", "(5.26), inverted", mod["elastic"], (E_star, nu1, E2, nu2),
                 "Young's modulus E1 [Pa] of the sample (body 1) under an elastic tip (body 2, "
                 "E2, nu2), from the fitted E*", "(5.26) solved for E1",
                 f"{TEST}::test_sample_modulus"),
        Relation("fit_sample_modulus_dE", "(5.26), inverted", mod["elastic_dE"],
                 (E_star, nu1, E2, nu2),
                 "derivative dE1/dE* [1] of the sample's modulus under an elastic tip",
                 "(5.26) solved for E1, differentiated in E*", f"{TEST}::test_sample_modulus"),
    ]
    rels.append(Relation(
        "fit_pyramid_cone_angle", "(5.38), equal area", pyramid_cone(), (alpha_p, n_sides),
        "angle theta [rad] between the surface and the plane of the cone with the cross-section "
        "area of a regular pyramid (n_sides faces, half-angle alpha_p) at every depth: the "
        "pyramid's equivalent cone", "pi (d cot(theta))^2 = n (d tan(alpha_p))^2 tan(pi/n)",
        f"{TEST}::test_pyramid_cone_by_polygon_area",
        # 0 < alpha_p < pi/2 and n_sides >= 3, as t_a, t_n in (0, 1)
        domain={alpha_p: sp.pi / 2 * unit_interval("t_a"), n_sides: 3 / unit_interval("t_n")}))
    rels.append(Relation(
        "fit_pyramid_force_cone_angle", "(5.40), equal force", pyramid_force_cone(),
        (alpha_p, n_sides, beta_p),
        "angle theta [rad] between the surface and the plane of the cone whose force (5.40) is "
        "beta_p times the equal-area cone's: a regular pyramid's force law, beta_p from the BEM",
        "(2/pi) E* d^2 / tan(theta) = beta_p (2/pi) E* d^2 / tan(theta_area)",
        f"{TEST}::test_pyramid_force_by_bem",
        domain={alpha_p: sp.pi / 2 * unit_interval("t_a"), n_sides: 3 / unit_interval("t_n"),
                beta_p: 1 / unit_interval("t_b")}))
    base = (z_p, z_0, F_0, s_0)
    for name, (_, geom, eq) in tip_forces().items():
        m = models()[name]
        what = {"hertz": "a paraboloidal (Hertz) tip", "cone": "a rigid cone",
                "punch": "a flat punch", "powerlaw": "a power-law tip"}[name]
        rels += [
            Relation(f"fit_{name}_force", f"{eq}, fit model", m["F"], (E_star, *geom, *base),
                     f"force F [N] on {what} at the position z_p: the tip's force at "
                     "d = max(0, z_p - z_0) plus the baseline F_0 + s_0 z_p",
                     f"{eq} at d = max(0, z_p - z_0)", FORCE_TEST),
            Relation(f"fit_{name}_force_dE", f"{eq}, fit model", m["dE"],
                     (*geom, z_p, z_0),
                     f"derivative dF/dE* [m^2] of the fit model of {what}",
                     f"{eq} at d = max(0, z_p - z_0), differentiated in E*", JAC_TEST),
            Relation(f"fit_{name}_force_dz0", f"{eq}, fit model", m["dz0"],
                     (E_star, *geom, z_p, z_0),
                     f"derivative dF/dz_0 [N/m] of the fit model of {what} (0 for d <= 0)",
                     f"{eq} at d = max(0, z_p - z_0), differentiated in z_0", JAC_TEST),
        ]
    sm = sphere_model()
    lam = sphere.lam
    lam_dom = {lam: sp.atanh(unit_interval("t_lam"))}  # lam in (0, inf): a/R = t_lam
    rels += [
        Relation("fit_sphere_force", "(5.57), fit model", sm["F"],
                 (E_star, R, lam, z_p, F_0, s_0),
                 "force F [N] on a rigid spherical cap (exact sphere) at the position z_p, "
                 "with lam = atanh(a/R) at the depth d = max(0, z_p - z_0), plus the baseline "
                 "F_0 + s_0 z_p", "(5.57) at lam = atanh(a/R)", FORCE_TEST,
                 stable=sm["F_stable"],
                 stable_why="the sphere's force (1 + tanh(lam)^2) lam - tanh(lam) cancels as "
                 "lam^2 for small lam; below lam = 1/2 it is written with a 2F1, as "
                 "sphere_lam_force", domain=lam_dom),
        Relation("fit_sphere_force_dE", "(5.57), fit model", sm["dE"], (R, lam),
                 "derivative dF/dE* [m^2] of the fit model of the exact sphere",
                 "(5.57) differentiated in E*", JAC_TEST,
                 stable=sp.diff(sm["F_stable"], E_star),
                 stable_why="as fit_sphere_force: the 2F1 form below lam = 1/2",
                 domain=lam_dom),
        Relation("fit_sphere_force_dz0", "(5.55), (5.57), fit model", sm["dz0"],
                 (E_star, R, lam),
                 "derivative dF/dz_0 [N/m] of the fit model of the exact sphere (0 at lam = 0)",
                 "-(dF/dlam)/(dd/dlam) of (5.57) and (5.55)", JAC_TEST),
        Relation("fit_sphere_depth_dlam", "(5.55)", sm["d_dlam"], (R, lam),
                 "derivative dd/dlam [m] of the exact sphere's depth d = R lam tanh(lam): the "
                 "slope of Newton's iteration for lam at a given depth",
                 "(5.55) at a = R tanh(lam), differentiated in lam",
                 f"{TEST}::test_sphere_lam_by_newton"),
    ]
    return rels
