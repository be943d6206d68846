"""Impact of an elastic sphere on a wall (Hertz 1882): Problems 3 and 4.

Starting point: energy conservation m/2 (dx/dt)^2 + U(x) = m v0^2/2 with the Hertz energy U of
(5.25), taken from :mod:`hertzmdr.derive.hertz` at d = x. The maximum depth x0 is where the
velocity vanishes, U(x0) = m v0^2/2. The contact time is twice the time from x = 0 to x0,
tau = 2 int_0^x0 dx/v(x) = (2 x0/v0) int_0^1 dxi/sqrt(1 - xi^(5/2)); SymPy evaluates the
integral (a Beta function: the chapter's 2.94 is twice it, rounded). The maximum pressure and
force are (5.22) and (5.23) at x0; for a sphere of density rho, m = 4/3 pi R^3 rho.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import hertz
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, R, d, symbol

TEST = "tests/test_impact.py"

m, v0, rho = symbol("m"), symbol("v0"), symbol("rho")


@cache
def time_integral() -> sp.Expr:
    """int_0^1 dxi / sqrt(1 - xi^(5/2)), by SymPy, as Gamma functions."""
    xi = sp.Symbol("xi", positive=True)
    val = sp.integrate(1 / sp.sqrt(1 - xi ** sp.Rational(5, 2)), (xi, 0, 1))
    val = sp.gammasimp(sp.hyperexpand(val))
    assert not val.has(sp.Integral, sp.hyper)
    return val


@cache
def solution() -> dict[str, sp.Expr]:
    s = hertz.solution()
    x, x0 = sp.symbols("x x_0", positive=True)
    U = s["U"].subs(d, x)  # (5.25) at d = x
    speed = sp.sqrt(v0**2 - 2 * U / m)  # from the energy balance
    (xmax,) = [r for r in sp.solve(sp.Eq(U, m * v0**2 / 2), x) if r.is_positive]
    # tau = 2 int_0^x0 dx / speed(x); with x = x0 xi the integrand is 1/(v0 sqrt(1 - xi^(5/2)))
    xi = sp.Symbol("xi", positive=True)
    scaled = sp.simplify((x0 / speed.subs(x, x0 * xi)).subs(x0, xmax))
    assert sp.simplify(scaled - xmax / (v0 * sp.sqrt(1 - xi ** sp.Rational(5, 2)))) == 0
    tau = 2 * xmax / v0 * time_integral()
    at_max = {d: xmax}
    mass = {m: sp.Rational(4, 3) * sp.pi * R**3 * rho}
    out = {"x0": sp.simplify(xmax), "tau": sp.simplify(tau),
           "p0": sp.simplify(s["p0"].subs(at_max)), "F": sp.simplify(s["F"].subs(at_max)),
           "a": sp.simplify(s["a"].subs(at_max))}
    out.update({k + "_rho": sp.simplify(v.subs(mass)) for k, v in list(out.items())})
    out["m_rho"] = mass[m]
    # the integrator's length scale: x = x_s X, t = (x_s/v0) T turn m x'' = -F(x) (5.23) into
    # X'' = -(4/3) X^(3/2) when m v0^2/x_s = E* sqrt(R) x_s^(3/2)
    xs = sp.Symbol("x_s", positive=True)
    balance = sp.Eq(m * v0**2 / xs, E_star * sp.sqrt(R) * xs ** sp.Rational(3, 2))
    (out["xs"],) = [r for r in sp.solve(balance, xs) if r.is_positive]
    # the time scale: x'(0) = v0 becomes X'(0) = 1 when t_s = x_s/v0; the force scale turns
    # m x'' = m (x_s/t_s^2) X'': with both, m x'' = -F(x) reads X'' = -F(x_s X)/F_s
    ts, fs = sp.symbols("t_s F_s", positive=True)
    (out["ts"],) = sp.solve(sp.Eq(v0 * ts / xs, 1), ts)
    out["ts"] = out["ts"].subs(xs, out["xs"])
    out["fs"] = sp.simplify((m * xs / ts**2).subs(ts, out["ts"]).subs(xs, out["xs"]))
    F_hertz = s["F"].subs(d, xs * x)  # (5.23) at x = x_s X
    assert sp.simplify(F_hertz.subs(xs, out["xs"]) / out["fs"]
                       - sp.Rational(4, 3) * x ** sp.Rational(3, 2)) == 0, F_hertz
    assert sp.simplify(out["fs"] - m * v0**2 / out["xs"]) == 0, out["fs"]
    return out


def relations() -> list[Relation]:
    s = solution()
    fifth = sp.Rational(1, 5)
    x0_printed = (sp.Rational(15, 16) * m * v0**2 / (E_star * sp.sqrt(R))) ** sp.Rational(2, 5)
    rels = [
        Relation("impact_max_depth", "Problem 3", s["x0"], (E_star, R, m, v0),
                 "maximum indentation depth x0 [m] of a sphere of mass m hitting a wall at v0",
                 "energy conservation with (5.25)", f"{TEST}::test_impact_by_equation_of_motion",
                 printed=x0_printed),
        Relation("impact_contact_time", "Problem 3", s["tau"], (E_star, R, m, v0),
                 "contact time tau [s] of a sphere of mass m hitting a wall at v0 (the "
                 "chapter's 2.94 x0/v0, with 2.94 = (4/5) sqrt(pi) Gamma(2/5)/Gamma(9/10))",
                 "twice the time integral of dx/v from 0 to x0, v from the energy balance",
                 f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_max_pressure", "Problem 4", s["p0"], (E_star, R, m, v0),
                 "maximum contact pressure p0 [Pa] during the impact",
                 "(5.22) at the maximum depth", f"{TEST}::test_impact_by_equation_of_motion",
                 printed=2 / sp.pi * (sp.Rational(15, 16) * E_star**4 * m * v0**2 / R**3)
                 ** fifth),
        Relation("impact_max_force", "Problem 4", s["F"], (E_star, R, m, v0),
                 "maximum contact force [N] during the impact", "(5.23) at the maximum depth",
                 f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_max_contact_radius", "Problem 4", s["a"], (E_star, R, m, v0),
                 "maximum contact radius [m] during the impact", "(5.21) at the maximum depth",
                 f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_max_depth_density", "Problem 3, m = 4/3 pi R^3 rho", s["x0_rho"],
                 (E_star, R, rho, v0),
                 "maximum indentation depth x0 [m] of a sphere of density rho hitting a wall",
                 "energy conservation with (5.25)", f"{TEST}::test_impact_by_equation_of_motion",
                 printed=x0_printed.subs(m, sp.Rational(4, 3) * sp.pi * R**3 * rho)),
        Relation("impact_contact_time_density", "Problem 3, m = 4/3 pi R^3 rho", s["tau_rho"],
                 (E_star, R, rho, v0),
                 "contact time tau [s] of a sphere of density rho hitting a wall at v0",
                 "twice the time integral of dx/v from 0 to x0",
                 f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_max_pressure_density", "Problem 4", s["p0_rho"], (E_star, rho, v0),
                 "maximum contact pressure p0 [Pa] of a sphere of density rho hitting a wall "
                 "at v0 (independent of its radius)", "(5.22) at the maximum depth",
                 f"{TEST}::test_impact_by_equation_of_motion",
                 printed=2 / sp.pi * (sp.Rational(5, 4) * sp.pi * E_star**4 * rho * v0**2)
                 ** fifth),
        Relation("impact_max_force_density", "Problem 4, m = 4/3 pi R^3 rho", s["F_rho"],
                 (E_star, R, rho, v0),
                 "maximum contact force [N] of a sphere of density rho hitting a wall at v0",
                 "(5.23) at the maximum depth", f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_max_contact_radius_density", "Problem 4, m = 4/3 pi R^3 rho",
                 s["a_rho"], (E_star, R, rho, v0),
                 "maximum contact radius [m] of a sphere of density rho hitting a wall at v0",
                 "(5.21) at the maximum depth", f"{TEST}::test_impact_by_equation_of_motion"),
        Relation("impact_length_scale", "(5.23), nondimensionalized", s["xs"],
                 (E_star, R, m, v0),
                 "length scale x_s [m] of the impact: (m v0^2/(E* sqrt(R)))^(2/5), with which "
                 "the equation of motion reads X'' = -(4/3) X^(3/2) in T = t v0/x_s",
                 "m v0^2/x_s = E* sqrt(R) x_s^(3/2)", f"{TEST}::test_length_scale"),
        Relation("impact_time_scale", "(5.23), nondimensionalized", s["ts"],
                 (E_star, R, m, v0),
                 "time scale t_s = x_s/v0 [s] of the impact, with which the initial velocity "
                 "is X'(0) = 1 in X = x/x_s, T = t/t_s",
                 "x'(0) = v0 in the scaled variables", f"{TEST}::test_time_and_force_scales"),
        Relation("impact_force_scale", "(5.23), nondimensionalized", s["fs"],
                 (E_star, R, m, v0),
                 "force scale F_s = m x_s/t_s^2 [N] of the impact: m x'' = -F(x) (5.23) reads "
                 "X'' = -F(x_s X)/F_s = -(4/3) X^(3/2)",
                 "m x'' = (m x_s/t_s^2) X''", f"{TEST}::test_time_and_force_scales"),
        Relation("impact_sphere_mass", "Problem 4, m = 4/3 pi R^3 rho", s["m_rho"], (R, rho),
                 "mass m [kg] of a solid sphere of radius R and density rho",
                 "the volume of the sphere times its density",
                 f"{TEST}::test_sphere_mass_by_quadrature"),
    ]
    return rels
