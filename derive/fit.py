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

from hertzmdr.derive import adhesion, bodies, cone, hertz, mdr, powerlaw, sphere
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E, E_star, R, a, d, nu, symbol, unit_interval

TEST = "tests/test_fit.py"
JAC_TEST = f"{TEST}::test_jacobian_by_mpmath_derivative"

#: the exact sphere's dF/dE* printed once more with its common subexpressions computed once
#: (codegen.render_fused: lam^2 once, squares and the cube as products, not NumPy's pow): the
#: fit evaluates it at every point of every contact point it tries (numeric/fit.py), where the
#: plain print costs ~5 times as much
FUSED = {"fit_sphere_force_unit": ("fit_sphere_force_dE",)}
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
    dE = sp.diff(model, E_star)
    _assert_linear_in_modulus("exact sphere", model, dE, dz0)
    # the form the fit evaluates (derive/sphere.py's force_lam_fit: in lam and a = R tanh(lam),
    # a continued fraction for the cancelling part below lam = 1/2, no 2F1); its branch above is
    # (5.57) itself at a = R tanh(lam)
    on_lam = {a: s["a_lam"]}
    fast = sphere.force_lam_fit()
    (pw,) = fast.atoms(sp.Piecewise)
    if sp.simplify(fast.subs(pw, pw.args[1][0]).subs(on_lam) - s["F_lam"]) != 0:
        raise AssertionError(f"the fit's sphere force above lam = 1/2 is not (5.57): {fast}")
    fit_force = fast + F_0 + s_0 * z_p
    # dF/dz_0 = -2 E* a (asserted above) at the given a: no tanh of its own
    dz0_a = -2 * E_star * a
    # Newton's step for lam in d = d(lam) = a lam (5.55): dd/dlam, positive for lam > 0, in
    # lam and a: R (lam sech(lam)^2 + tanh(lam)) with sech^2 = 1 - tanh^2 = (R - a)(R + a)/R^2
    # (no cosh to overflow beyond lam = 355: there a = R, and dd/dlam = a)
    d_dlam = sp.simplify(sp.diff(s["d_lam"], lam))
    depth_a = a * lam
    d_dlam_a = lam * (R - a) * (R + a) / R + a
    # da/dlam = R sech(lam)^2 in a: the contact radius at Newton's last step, a + (da/dlam) step
    a_dlam = sp.diff(s["a_lam"], lam)
    a_dlam_a = (R - a) * (R + a) / R
    for form, ref in ((depth_a, s["d_lam"]), (d_dlam_a, d_dlam), (dz0_a, dz0),
                      (a_dlam_a, a_dlam)):
        if sp.simplify((form.subs(on_lam) - ref).rewrite(sp.exp)) != 0:
            raise AssertionError(f"the exact sphere's {form} at a = R tanh(lam) is not {ref}")
    return {"F": model, "F_fit": fit_force, "dE": dE, "dE_fit": sp.diff(fit_force, E_star),
            "dz0": dz0_a, "d": depth_a, "d_dlam": d_dlam_a, "a_dlam": a_dlam_a}


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
    t_lam = unit_interval("t_lam")
    lam_a_dom = {lam: sp.atanh(t_lam), a: R * t_lam}  # lam in (0, inf): a/R = t_lam
    given_a = (" at lam = atanh(a/R) and the contact radius a = R tanh(lam), both given (the fit "
               "computes tanh once per point)")
    rels += [
        Relation("fit_sphere_force", "(5.57), fit model", sm["F_fit"],
                 (E_star, R, lam, a, z_p, F_0, s_0),
                 "force F [N] on a rigid spherical cap (exact sphere) at the position z_p, "
                 "with lam = atanh(a/R) at the depth d = max(0, z_p - z_0), plus the baseline "
                 "F_0 + s_0 z_p", "(5.57)" + given_a + "; below lam = 1/2 its cancelling "
                 "lam - tanh(lam) by Lambert's continued fraction of tanh, 7 levels (truncation "
                 "< 1e-18 relative; no 2F1, cheap at every point of a fit)",
                 f"{TEST}::test_sphere_fit_force_by_mpmath", domain=lam_a_dom),
        Relation("fit_sphere_force_dE", "(5.57), fit model", sm["dE_fit"], (R, lam, a),
                 "derivative dF/dE* [m^2] of the fit model of the exact sphere",
                 "(5.57) differentiated in E*" + given_a + "; below lam = 1/2 as "
                 "fit_sphere_force", f"{TEST}::test_sphere_fit_force_by_mpmath",
                 domain=lam_a_dom),
        Relation("fit_sphere_force_dz0", "(5.55), (5.57), fit model", sm["dz0"],
                 (E_star, a),
                 "derivative dF/dz_0 [N/m] of the fit model of the exact sphere at the contact "
                 "radius a = R tanh(lam) (0 at a = 0, no contact)",
                 "-(dF/dlam)/(dd/dlam) of (5.57) and (5.55), simplified to -2 E* a", JAC_TEST),
        Relation("fit_sphere_depth", "(5.55)", sm["d"], (lam, a),
                 "indentation depth d [m] of the exact sphere at lam = atanh(a/R) and its "
                 "contact radius a = R tanh(lam), both given: the function of Newton's "
                 "iteration for lam at a given depth",
                 "(5.55), d = a atanh(a/R), at a = R tanh(lam)",
                 f"{TEST}::test_sphere_lam_by_newton", domain=lam_a_dom),
        Relation("fit_sphere_depth_dlam", "(5.55)", sm["d_dlam"], (R, lam, a),
                 "derivative dd/dlam [m] of the exact sphere's depth d = R lam tanh(lam) at "
                 "lam and a = R tanh(lam), both given: the slope of Newton's iteration for lam "
                 "at a given depth",
                 "(5.55) at a = R tanh(lam), differentiated in lam; sech(lam)^2 as "
                 "(R - a)(R + a)/R^2", f"{TEST}::test_sphere_lam_by_newton",
                 domain=lam_a_dom),
        Relation("fit_sphere_radius_dlam", "(5.55)", sm["a_dlam"], (R, a),
                 "derivative da/dlam [m] of the exact sphere's contact radius a = R tanh(lam) "
                 "at a given: the contact radius at Newton's last step for lam, a + (da/dlam) "
                 "step, to an ulp for a step below 1e-8 lam, without a tanh",
                 "a = R tanh(lam) differentiated in lam, sech(lam)^2 as (R - a)(R + a)/R^2",
                 f"{TEST}::test_sphere_lam_by_newton", domain={a: R * t_lam}),
    ]
    return rels + jkr_relations()


# ---------------------------------------------------------------------------------------------
# The adhesive (JKR) fit: a retract curve of a paraboloid, parametric in the contact radius a
# ---------------------------------------------------------------------------------------------
JKR_TEST = "tests/test_fit_jkr.py"
CONE_TEST = "tests/test_fit_adhesive_cone.py"
rho_g = symbol("rho_g")


def _adhesive_model(family: dict[str, sp.Expr], name: str) -> dict[str, sp.Expr]:
    """An adhesive fit model in (E*, z_0, Delta gamma, F_0, s_0) at the contact radius a, and its
    Jacobian, written in rho_g = sqrt(Delta gamma), from an adhesive family's d(a) and F(a)
    (:func:`hertzmdr.derive.adhesion.family`: (5.55), (5.57) with the critical elongation
    Delta l = sqrt(2 pi a Delta gamma/E*)).

    Implicit differentiation: the measured position fixes d(a(p), p) = z_p - z_0 for every
    parameter p, so da/dp = -(dd/dp + [p = z_0])/(dd/da) and dF/dp = dF/dp|_a + dF/da da/dp.
    SymPy does it on an undefined a(E*, z_0, Delta gamma). dd/da = 0 at the depth-controlled
    pull-off a_dc: dF/dE* and dF/dz_0 are singular there (F(d) has a vertical tangent at the
    jump-off). dF/dDelta gamma is finite as Delta gamma -> 0: -2 pi a/g'(a), g' = dd/da without
    adhesion (asserted; -pi R for the paraboloid), since the sqrt(Delta gamma) terms of
    dF/da da/dDelta gamma and dF/dDelta gamma|_a cancel once the common factor sqrt(Delta gamma)
    is cancelled, which the form in rho_g does.
    """
    dg = adhesion.dgamma
    A = sp.Function("A")(E_star, z_0, dg)
    eq = family["d"].subs(a, A) - (z_p - z_0)  # the measured position fixes the depth
    to_rho = {dg: rho_g**2}
    out = {"d": sp.simplify(family["d"].subs(to_rho)),
           "F": sp.simplify(family["F"].subs(to_rho)) + F_0 + s_0 * z_p,
           "d_da": sp.simplify(sp.diff(family["d"], a).subs(to_rho))}
    for key, p in (("dE", E_star), ("dz0", z_0), ("ddgamma", dg)):
        dA = sp.Derivative(A, p)
        (slope,) = sp.solve(sp.diff(eq, p), dA)
        dF = sp.diff(family["F"].subs(a, A), p).subs(dA, slope).subs(A, a)
        out[key] = sp.simplify(sp.factor(sp.simplify(dF.subs(to_rho))))
    limit = -2 * sp.pi * a / out["d_da"].subs(rho_g, 0)
    if sp.simplify(out["ddgamma"].subs(rho_g, 0) - limit) != 0:
        raise AssertionError(f"dF/dDelta gamma of the {name} at Delta gamma = 0 is not "
                             f"-2 pi a/g'(a) = {limit}: {out['ddgamma']}")
    # F = E* f(a; kappa) and d = d(a; kappa) with kappa = rho_g/sqrt(E*): at a fixed kappa the
    # model is linear in E* (what lets the start scan solve E*, F_0, s_0 by linear least squares)
    kap = sp.Symbol("kappa", positive=True)
    force = out["F"] - F_0 - s_0 * z_p
    scaled = {rho_g: kap * sp.sqrt(E_star)}
    if sp.simplify(force.subs(scaled) - E_star * force.subs(scaled).subs(E_star, 1)) != 0 \
            or sp.simplify(out["d"].subs(scaled) - out["d"].subs(scaled).subs(E_star, 1)) != 0:
        raise AssertionError(f"the adhesive {name} model is not E* f(a; rho_g/sqrt(E*))")
    return out


@cache
def jkr_model() -> dict[str, sp.Expr]:
    """The JKR fit model (the paraboloid) and its Jacobian (:func:`_adhesive_model`).

    Starting point: :func:`hertzmdr.derive.adhesion.jkr`'s d(a) and F(a) (the MDR's adhesive
    paraboloid, (5.55) and (5.57) with the critical elongation), not retyped. dF/dDelta gamma
    is -pi R at Delta gamma = 0 (asserted).
    """
    out = _adhesive_model(adhesion.jkr(), "paraboloid")
    if sp.simplify(out["ddgamma"].subs(rho_g, 0) + sp.pi * R) != 0:
        raise AssertionError(f"dF/dDelta gamma at Delta gamma = 0 is not -pi R: {out['ddgamma']}")
    return out


@cache
def adhesive_cone_model() -> dict[str, sp.Expr]:
    """The adhesive cone's fit model and its Jacobian (:func:`_adhesive_model`).

    Starting point: :func:`hertzmdr.derive.adhesion.cone`'s d(a) = (pi/2) a tan(theta) - Delta l
    and F(a) (the MDR's adhesive cone, (5.55) and (5.57) with the critical elongation), not
    retyped. dF/dDelta gamma is -4 a/tan(theta) at Delta gamma = 0 (asserted).
    """
    out = _adhesive_model(adhesion.cone(), "cone")
    if sp.simplify(out["ddgamma"].subs(rho_g, 0) + 4 * a / sp.tan(cone.theta)) != 0:
        raise AssertionError("dF/dDelta gamma of the cone at Delta gamma = 0 is not "
                             f"-4 a/tan(theta): {out['ddgamma']}")
    return out


def _adhesive_family(g: sp.Expr) -> dict[str, sp.Expr]:
    """d(a) and F(a) of the adhesive MDR for the MDR profile g(x) (5.52): steps 4-5 of
    :mod:`hertzmdr.derive.adhesion` -- the depth less the critical elongation,
    d(a) = g(a) - Delta l(a) (5.55), and (5.57) at that depth, F = F_0(a) - 2 E* a Delta l
    (F is linear in d at a fixed a, of slope 2 E* a: the flat punch). For the profiles whose
    pull-off :func:`hertzmdr.derive.adhesion.family` cannot solve in closed form (the exact
    sphere); checked against that family's d(a), F(a) on the paraboloid."""
    dl = adhesion.critical_elongation()
    return {"d": g.subs(mdr.x, a) - dl, "F": mdr.force(g) - 2 * E_star * a * dl}


@cache
def adhesive_sphere_model() -> dict[str, sp.Expr]:
    """The adhesive exact sphere's fit model and its Jacobian (:func:`_adhesive_model`).

    Starting point: the cap's MDR profile g(x) = x atanh(x/R) (5.52) of
    :func:`hertzmdr.derive.sphere.solution`, through :func:`_adhesive_family` (which gives
    derive/adhesion.py's JKR family back from the paraboloid's g: asserted). dF/dDelta gamma
    is -2 pi a/g'(a) at Delta gamma = 0, g'(a) = atanh(a/R) + a R/(R^2 - a^2) (asserted in
    :func:`_adhesive_model`); the depth-controlled pull-off dd/da = 0 has no closed form
    (atanh and a^(-1/2)): numeric/fit_adhesive.py solves it on ``fit_adhesive_sphere_depth_da``.
    """
    rr = sp.Symbol("rr", positive=True)
    par = _adhesive_family(mdr.transform(rr**2 / (2 * R), rr))
    jkr = adhesion.jkr()
    if sp.simplify(par["d"] - jkr["d"]) != 0 or sp.simplify(par["F"] - jkr["F"]) != 0:
        raise AssertionError("_adhesive_family of the paraboloid is not adhesion.jkr()")
    return _adhesive_model(_adhesive_family(sphere.solution()["g"]), "exact sphere")


@cache
def adhesive_powerlaw_model() -> dict[str, sp.Expr]:
    """The adhesive power law's fit model and its Jacobian (:func:`_adhesive_model`).

    Starting point: :func:`hertzmdr.derive.adhesion.power`'s d(a) = kappa_n c_n a^n - Delta l
    and F(a) (Hess's power law by the MDR), not retyped. dF/dDelta gamma is
    -2 pi a/(n kappa_n c_n a^(n - 1)) at Delta gamma = 0 (asserted in :func:`_adhesive_model`).
    """
    return _adhesive_model(adhesion.power(), "power law")


g_a = symbol("g_a")
g_slope = symbol("g_slope")
g_int = symbol("g_integral")


@cache
def adhesive_general_model() -> dict[str, sp.Expr]:
    """The adhesive fit model of any MDR profile, in its g(a), g'(a) and G(a) = integral_0^a g
    as symbols (``g_a``, ``g_slope``, ``g_integral``), and its Jacobian: what a sampled
    (measured) tip evaluates with its numerical MDR's g, g' and G.

    Starting point: the adhesive MDR's d(a) = g(a) - Delta l(a) (5.55) and (5.57) at that depth,
    F = 2 E* (a d - G(a)) (:func:`_adhesive_family` with an undefined g; G' = g). The implicit
    differentiation is :func:`_adhesive_model`'s (d(a(p), p) = z_p - z_0 for every parameter p:
    da/dp = -(dd/dp + [p = z_0])/(dd/da), dF/dp = dF/dp|_a + dF/da da/dp), on the partial
    derivatives in a of the undefined g and G, which are then written as the symbols. Asserted:
    the paraboloid's g = x^2/R (g' = 2a/R, G = a^3/(3R)) gives :func:`jkr_model` back, relation
    by relation; dF/dDelta gamma -> -2 pi a/g'(a) as Delta gamma -> 0; F = E* f(a; kappa).
    """
    dg = adhesion.dgamma
    gf, Gf = sp.Function("g_f"), sp.Function("G_f")
    dl = adhesion.critical_elongation()
    depth = gf(a) - dl
    force = 2 * E_star * (a * depth - Gf(a))  # (5.57) at d = g(a) - Delta l (5.55)

    def partial(expr, v):
        out = sp.diff(expr, v).subs(sp.Derivative(Gf(a), a), gf(a))
        return out.subs(sp.Derivative(gf(a), a), g_slope)

    def symbols_of(expr):
        return expr.subs({gf(a): g_a, Gf(a): g_int}).subs({dg: rho_g**2})

    dd_da, dF_da = partial(depth, a), partial(force, a)
    out = {"d": sp.simplify(symbols_of(depth)),
           "F": sp.simplify(symbols_of(force)) + F_0 + s_0 * z_p,
           "d_da": sp.simplify(symbols_of(dd_da))}
    for key, p in (("dE", E_star), ("dz0", z_0), ("ddgamma", dg)):
        da_dp = -(partial(depth, p) + (1 if p is z_0 else 0)) / dd_da
        dF = partial(force, p) + dF_da * da_dp
        out[key] = sp.simplify(sp.factor(sp.simplify(symbols_of(dF))))
    limit = -2 * sp.pi * a / g_slope
    if sp.simplify(out["ddgamma"].subs(rho_g, 0) - limit) != 0:
        raise AssertionError("dF/dDelta gamma of the general adhesive model at Delta gamma = 0 "
                             f"is not -2 pi a/g'(a): {out['ddgamma']}")
    kap = sp.Symbol("kappa", positive=True)
    scaled = {rho_g: kap * sp.sqrt(E_star)}
    tip_force = out["F"] - F_0 - s_0 * z_p
    if sp.simplify(tip_force.subs(scaled) - E_star * tip_force.subs(scaled).subs(E_star, 1)) \
            or sp.simplify(out["d"].subs(scaled) - out["d"].subs(scaled).subs(E_star, 1)):
        raise AssertionError("the general adhesive model is not E* f(a; rho_g/sqrt(E*))")
    # the paraboloid f = r^2/(2R): g = x^2/R (5.52), its slope and integral
    par = {g_a: a**2 / R, g_slope: 2 * a / R, g_int: a**3 / (3 * R)}
    jkr = jkr_model()
    for key, expr in out.items():
        if sp.simplify(expr.subs(par) - jkr[key]) != 0:
            raise AssertionError(f"the general adhesive model's {key} at g = x^2/R is not the "
                                 f"JKR model's: {expr}")
    return out


SPHERE_ADH_TEST = "tests/test_fit_adhesive_sphere.py"
POWER_ADH_TEST = "tests/test_fit_adhesive_powerlaw.py"
SAMPLED_ADH_TEST = "tests/test_fit_adhesive_sampled.py"


def jkr_relations() -> list[Relation]:
    return (_adhesive_relations("jkr", jkr_model(), (R,), "a paraboloid", "(5.55), (5.57), JKR",
                                "jkr_depth", "jkr_force_from_radius", JKR_TEST)
            + _adhesive_relations("adhesive_cone", adhesive_cone_model(), (cone.theta,),
                                  "a cone", "(5.55), (5.57), adhesive cone",
                                  "adhesion_cone_depth", "adhesion_cone_force_from_radius",
                                  CONE_TEST)
            + _adhesive_relations("adhesive_sphere", adhesive_sphere_model(), (R,),
                                  "an exact sphere (spherical cap)",
                                  "(5.55), (5.57), adhesive exact sphere",
                                  "sphere_depth less Delta l",
                                  "sphere_force_from_radius less 2 E* a Delta l",
                                  SPHERE_ADH_TEST,
                                  domain={a: R * unit_interval("t_a")})  # 0 < a < R
            + _adhesive_relations("adhesive_powerlaw", adhesive_powerlaw_model(),
                                  (powerlaw.c_n, powerlaw.kappa_n, powerlaw.n),
                                  "a power-law tip", "(5.55), (5.57), adhesive power law",
                                  "adhesion_powerlaw_depth",
                                  "adhesion_powerlaw_force_from_radius", POWER_ADH_TEST)
            + _adhesive_relations("adhesive_sampled", adhesive_general_model(),
                                  (g_a, g_slope, g_int),
                                  "any tip of MDR profile g (g_a = g(a), g_slope = g'(a), "
                                  "g_integral = G(a), the integral of g over [0, a])",
                                  "(5.55), (5.57), adhesive MDR of any g",
                                  "g(a) - Delta l", "2 E* (a d - G(a))", SAMPLED_ADH_TEST,
                                  domain=_SAMPLED_DOMAIN))


#: where the general adhesive model is stated: a profile g increasing from g(0) = 0 (so
#: G(a) < a g(a)) on the branch a > a_dc beyond the depth-controlled pull-off, where
#: dd/da = g'(a) - Delta l/(2a) > 0 (Delta l = sqrt(2 pi a Delta gamma/E*), (5.55)), i.e.
#: g'(a) = (Delta l/(2a))/t with t in (0, 1); at dd/da = 0, dF/dz_0 is infinite
_SAMPLED_DOMAIN = {
    g_slope: rho_g * sp.sqrt(2 * sp.pi * a / E_star) / (2 * a * unit_interval("t_s")),
    g_int: a * g_a * unit_interval("t_G")}


def _adhesive_relations(prefix, m, shape, label, src, depth_name, force_name, test,
                        domain=None):
    geo = (E_star, *shape, a, rho_g)
    how = "implicit differentiation at d(a) = z_p - z_0 of"
    return [
        Relation(f"fit_{prefix}_depth", f"{src}, fit model", m["d"], geo,
                 f"indentation depth d [m] of {label} in adhesive contact of radius a, "
                 "Delta gamma = rho_g^2", f"{depth_name} at Delta gamma = rho_g^2",
                 f"{test}::test_{prefix}_model_by_mpmath_parametric", domain=domain),
        Relation(f"fit_{prefix}_depth_da", f"{src}, fit model", m["d_da"], geo,
                 f"derivative dd/da [1] of the adhesive depth of {label}: Newton's slope for a "
                 "at a depth (0 at the depth-controlled pull-off)",
                 f"{depth_name} differentiated in a", f"{test}::test_{prefix}_radius_by_mpmath",
                 domain=domain),
        Relation(f"fit_{prefix}_force", f"{src}, fit model", m["F"], (*geo, z_p, F_0, s_0),
                 f"force F [N] on {label} in adhesive contact of radius a at the position "
                 f"z_p, plus the baseline F_0 + s_0 z_p", f"{force_name} at Delta gamma = "
                 "rho_g^2", f"{test}::test_{prefix}_model_by_mpmath_parametric", domain=domain),
        Relation(f"fit_{prefix}_force_dE", f"{src}, fit model", m["dE"], geo,
                 f"derivative dF/dE* [m^2] of the adhesive fit model of {label} at a fixed "
                 "position", f"{how} {force_name} in E*",
                 f"{test}::test_{prefix}_jacobian_by_mpmath_derivative", domain=domain),
        Relation(f"fit_{prefix}_force_dz0", f"{src}, fit model", m["dz0"], geo,
                 f"derivative dF/dz_0 [N/m] of the adhesive fit model of {label} at a fixed "
                 "position (-dF/dd: infinite at the depth-controlled pull-off)",
                 f"{how} {force_name} in z_0",
                 f"{test}::test_{prefix}_jacobian_by_mpmath_derivative", domain=domain),
        Relation(f"fit_{prefix}_force_ddgamma", f"{src}, fit model", m["ddgamma"], geo,
                 f"derivative dF/dDelta gamma [m] of the adhesive fit model of {label} at a "
                 "fixed position (-2 pi a/g'(a) at Delta gamma = 0)",
                 f"{how} {force_name} in Delta gamma",
                 f"{test}::test_{prefix}_jacobian_by_mpmath_derivative", domain=domain),
    ]
