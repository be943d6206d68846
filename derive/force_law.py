"""Force laws F = K d^n: the prefactor and exponent of the force-depth relations that are
power laws, and the same for the stiffness k = dF/dd = K_k d^(n_k).

Starting point: the force-depth relations already derived in the families (Hertz (5.23),
the cone (5.40), the flat punch (Problem 7(a)), the power-law profile (Problem 7(d)), the line
contact (5.34) per unit length, the exact elliptical contact). Nothing is retyped: for each
force F(d) the exponent is the logarithmic slope n = d (dF/dd)/F, which must come out free of d
(else F is not a power law and the derivation fails), and the prefactor is K = F/d^n, again
free of d. The stiffness law applies the same two steps to dF/dd, so n_k = n - 1 and
K_k = n K follow from the derivation instead of being assumed (the tests check both).

This is what a discrete-element code consumes: a Hertz-type contact law F = K d^n with the
constants of the two bodies folded into K (docs/dem.md).

The line contact's d is the chapter's conventional depth of (5.35), a = sqrt(R d): the
approach of two cylinders' axes has a further term F/L (2/(pi E*)) (ln(...) ...) that depends
on the bodies' size, so F/L = (pi/4) E* d is linear in that d only. The relation says so.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import cone, ellipse, hertz, line, powerlaw
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E_star, R, a, d

TEST = "tests/test_force_law.py"


def power_law(force: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(K, n) with force == K d^n: n the logarithmic slope d F'/F, K = F/d^n; both must be
    free of d, else ``force`` is no power law of d and ValueError says so."""
    n_ = sp.simplify(sp.powsimp(sp.expand_power_base(d * sp.diff(force, d) / force, force=True),
                                force=True))
    if n_.has(d):
        raise ValueError(f"not a power law of d: d F'/F = {n_}")
    K = sp.simplify(sp.powsimp(sp.expand_power_base(force / d**n_, force=True), force=True))
    if K.has(d):
        raise ValueError(f"not a power law of d: F/d^n = {K}")
    return K, n_


@cache
def laws() -> dict[str, dict]:
    """name -> {F: the force-depth relation it comes from, args: the prefactor's arguments,
    equation, what, printed: the chapter's prefactor where it prints one, stable: a map of the
    printed expression to its stable form (or None)}."""
    pl = powerlaw.solution()
    ell = ellipse.solution()
    third = sp.Rational(4, 3)
    return {
        "hertz": dict(F=hertz.solution()["F"], args=(E_star, R), equation="(5.23)",
                      what="a Hertz contact (effective sphere of radius R)",
                      printed=third * E_star * sp.sqrt(R), stable=None),
        "cone": dict(F=cone.solution()["F"], args=(E_star, cone.theta), equation="(5.40)",
                     what="a rigid cone of angle theta with the plane",
                     printed=2 / sp.pi * E_star / sp.tan(cone.theta), stable=None),
        "punch": dict(F=powerlaw.punch()["F"], args=(E_star, a), equation="Problem 7(a)",
                      what="a flat rigid punch of radius a", printed=2 * E_star * a,
                      stable=None),
        "powerlaw": dict(F=pl["F"], args=(E_star, powerlaw.c_n, powerlaw.kappa_n, powerlaw.n),
                         equation="Problem 7(d)",
                         what="a power-law profile f = c_n r^n (kappa_n from powerlaw_kappa)",
                         printed=None, stable=None),
        "line": dict(F=line.solution()["F"] / line.L, args=(E_star,), equation="(5.34)",
                     what="a line contact, per unit length (F/L), with d the conventional "
                     "depth of (5.35), a = sqrt(R d)", printed=sp.pi / 4 * E_star, stable=None),
        "ellipse": dict(F=ellipse._tidy(ell["F"]), args=(E_star, ellipse.R1, ellipse.t),
                        equation="(5.23), exact ellipse",
                        what="an elliptical contact (R1 >= R2 the principal radii, t_ba = b/a "
                        "from ellipse_radius_ratio)", printed=None,
                        stable=ellipse._stable(ell["F"])),
    }


def relations() -> list[Relation]:
    rels = []
    for name, law in laws().items():
        K, n_ = power_law(law["F"])
        k = sp.diff(law["F"], d)
        Kk, nk = power_law(k)
        stable_K = stable_Kk = why = None
        if law["stable"] is not None:  # the elliptical contact: no cancellation as t -> 1
            stable_K, _ = power_law(law["stable"])
            stable_Kk, _ = power_law(sp.diff(law["stable"], d))
            why = ("K(m) and E(m) written through (pi/4) 2F1 as in ellipse_force: the K, E "
                   "form cancels as t -> 1 (the circle)")
        unit_n = "N/m per m" if name == "line" else "N/m^n"
        per = " per unit length" if name == "line" else ""
        eq = law["equation"]
        exps = [s for s in law["args"] if s in n_.free_symbols]
        rels += [
            Relation(f"force_law_{name}_prefactor", f"{eq}, F = K d^n", K, law["args"],
                     f"prefactor K [{unit_n}] of the force law F{per} = K d^n of {law['what']}",
                     "F/d^n with n the logarithmic slope d F'/F of the force",
                     f"{TEST}::test_{name}_law_by_pressure_quadrature",
                     printed=law["printed"], stable=stable_K, stable_why=why),
            Relation(f"force_law_{name}_exponent", f"{eq}, F = K d^n", n_, tuple(exps),
                     f"exponent n [1] of the force law F{per} = K d^n of {law['what']}",
                     "the logarithmic slope d F'/F of the force",
                     f"{TEST}::test_{name}_law_by_pressure_quadrature"),
            Relation(f"force_law_{name}_stiffness_prefactor", f"{eq}, differentiated", Kk,
                     law["args"], f"prefactor K_k [{unit_n}] of the stiffness law "
                     f"dF{'/L' if name == 'line' else ''}/dd = K_k d^(n - 1) of {law['what']}",
                     "(dF/dd)/d^(n_k) with n_k the logarithmic slope of dF/dd",
                     f"{TEST}::test_stiffness_law_is_the_derivative",
                     stable=stable_Kk, stable_why=why),
            Relation(f"force_law_{name}_stiffness_exponent", f"{eq}, differentiated", nk,
                     tuple(s for s in law["args"] if s in nk.free_symbols),
                     f"exponent n - 1 [1] of the stiffness law of {law['what']}",
                     "the logarithmic slope of dF/dd",
                     f"{TEST}::test_stiffness_law_is_the_derivative"),
        ]
    return rels
