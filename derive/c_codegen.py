"""Print the contact laws a DEM code needs as a dependency-free C99 header (issue 18).

DEM codes (LAMMPS, LIGGGHTS, Yade, MercuryDPM) evaluate the contact law inside their own C/C++
loops. :data:`LAWS` names the relations they need -- Hertz, cone, power law, line contact, JKR,
Cattaneo-Mindlin, the exact elliptical contact and the effective moduli -- and the domain over
which each is documented and tested; :func:`render_header` prints them from the same
:class:`~hertzmdr.derive.relation.Relation` records as ``numeric/_generated.py``, with SymPy's
C99 printer, in their stable form where a relation has one, as ``static inline`` double
functions named ``hertzmdr_<relation name>``. Three printing choices, each for accuracy or
speed and none changing the relation: the constant factors of a product become one correctly
rounded literal, x^(p/2) and x^(p/3) go through sqrt and cbrt instead of pow with a rounded
exponent, and the exact ellipse's two 2F1 become Carlson's R_D of t^2 (DLMF 19.25.1). The only
hand-written code of the header is R_D by Carlson's duplication, :data:`CARLSON_RD`.
``python -m hertzmdr.derive`` writes the header to ``numeric/c/hertzmdr_laws.h`` and its
reference to ``docs/c_laws_reference.md``; ``tests/test_c_header.py`` compiles it and compares
every function with the NumPy and the 30-digit mpmath routes over the domains below.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass, field

import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.precedence import precedence

from hertzmdr.derive.codegen import COMMAND
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import DESCRIPTIONS

PREFIX = "hertzmdr_"
#: where ``python -m hertzmdr.derive`` writes the header and its reference, relative to the
#: source tree
HEADER = "numeric/c/hertzmdr_laws.h"
REFERENCE = "docs/c_laws_reference.md"


@dataclass(frozen=True)
class Span:
    """The documented range [lo, hi] of one quantity, sampled log-uniformly unless ``log=False``."""

    lo: float
    hi: float
    log: bool = True

    def text(self) -> str:
        return f"[{self.lo:.10g}, {self.hi:.10g}]" + ("" if self.log else " (linear)")


@dataclass(frozen=True)
class CLaw:
    """One relation printed into the header, with the domain where it is documented and tested.

    Parameters
    ----------
    relation
        Name of the :class:`Relation`; the C function is ``hertzmdr_<relation>``.
    spans
        Range of each argument that is drawn independently, and of any auxiliary quantity (not
        an argument) that ``where`` uses, e.g. ``t`` in (0, 1) or the contact radius.
    where
        Arguments computed from the drawn quantities, as SymPy-readable expressions in their
        names (``u_x = t mu_f E_star a^2/(R G_star)``: below the onset of sliding).
    notes
        What the caller must know beyond the domain (a branch, a unit convention).
    hard
        Points of the catalogue of hard cases (tiny or huge scales, nu = 0.5, b/a -> 0, the
        onset of sliding), as values of the drawn quantities; tested beside the samples.
    unit
        The unit of the result, where the relation's summary does not end it in ``[unit]``.
    """

    relation: str
    spans: dict[str, Span]
    where: dict[str, str] = field(default_factory=dict)
    notes: str = ""
    hard: tuple[dict[str, float], ...] = ()
    unit: str = ""  # the result's unit where the relation's summary has no [unit]

    @property
    def c_name(self) -> str:
        return PREFIX + self.relation


# the documented ranges of hertzmdr.numeric (tests/domain_search.py searches the same ones)
DEPTH = Span(1e-15, 1e3)  # depths [m]
LEN = Span(1e-12, 1e6)  # radii, lengths [m]
MOD = Span(1e-3, 1e15)  # moduli [Pa]
FORCE = Span(1e-300, 1e30)  # forces [N]
ANGLE = Span(1e-300, 1.5)  # cone angle with the plane [rad]
NU = Span(-0.999999, 0.5, log=False)  # Poisson's ratio
# the adhesion and friction laws: no search of numeric/ covers them; these are the ranges tested
DGAMMA = Span(1e-6, 1e3)  # work of adhesion [J/m^2]
MU = Span(1e-3, 10.0)  # coefficient of friction
FRACTION = Span(1e-12, 1.0 - 1e-9)  # t: a fraction of the limit (sliding onset, mu F)
EXPONENT = Span(0.1, 20.0)  # power-law exponent n
T_BA = Span(3e-5, 1.0)  # axis ratio b/a of the ellipse: R1/R2 <= 1e8, as numeric.ellipse

KAPPA = "sqrt(pi)*gamma(n/2 + 1)/gamma(n/2 + 1/2)"  # powerlaw_kappa(n): kappa_n as it should be
DER = {"d": DEPTH, "R": LEN, "E_star": MOD}
FRE = {"F": FORCE, "R": LEN, "E_star": MOD}
SLIDE_U = {"u_x": "t*mu_f*E_star*a**2/(R*G_star)"}  # below full sliding, c > 0
TAN_U = {"a": LEN, "R": LEN, "E_star": MOD, "G_star": MOD, "mu_f": MU, "t": FRACTION}
# the tangential laws square the normal force (F^2 mu^2/(G* a)): F >= 1e-100 N keeps that normal
TAN_F = {"a": LEN, "F": Span(1e-100, 1e30), "G_star": MOD, "mu_f": MU, "t": FRACTION}
JKR = {"E_star": MOD, "dgamma": DGAMMA, "R": LEN}
TINY_HUGE = ({"d": 1e-12, "R": 1e-9, "E_star": 1e3}, {"d": 100.0, "R": 1e3, "E_star": 1e12})
ELLIPSE = {"E_star": MOD, "R1": LEN, "d": DEPTH, "t_ba": T_BA}
ELLIPSE_HARD = tuple({"E_star": 1e11, "R1": 1.0, "d": 1e-6, "t_ba": t}
                     for t in (1.0, 1.0 - 2.0**-40, 0.5, 1e-2, 3e-5))
POWER = {"E_star": MOD, "d": DEPTH, "a": Span(1e-9, 1e3), "n": EXPONENT}
POWER_WHERE = {"kappa_n": KAPPA, "c_n": f"d/(({KAPPA})*a**n)"}

LAWS: tuple[CLaw, ...] = (
    # Hertz, (5.21)-(5.25)
    CLaw("hertz_force", DER, hard=TINY_HUGE),
    CLaw("hertz_stiffness", DER, hard=TINY_HUGE),
    CLaw("hertz_contact_radius", {"d": DEPTH, "R": LEN}),
    CLaw("hertz_max_pressure", DER, hard=TINY_HUGE),
    CLaw("hertz_energy", DER, hard=TINY_HUGE),
    CLaw("hertz_depth_from_force", FRE, hard=({"F": 4e-23, "R": 1e-9, "E_star": 1e12},)),
    CLaw("hertz_contact_radius_from_force", FRE),
    # cone, (5.38)-(5.40)
    # E* d^2/tan(theta) leaves float64 below theta ~ 1e-285 at the largest E* and d
    CLaw("cone_force", {"E_star": MOD, "d": DEPTH, "theta": Span(1e-250, 1.5)}),
    CLaw("cone_stiffness", {"E_star": MOD, "d": DEPTH, "theta": Span(1e-250, 1.5)}),
    CLaw("cone_contact_radius", {"d": DEPTH, "theta": ANGLE}),
    CLaw("cone_depth_from_force", {"E_star": MOD, "F": FORCE, "theta": ANGLE}),
    CLaw("cone_contact_radius_from_force", {"E_star": MOD, "F": FORCE, "theta": ANGLE}),
    # power law f = c_n r^n, Problem 7(d)
    CLaw("powerlaw_kappa", {"n": EXPONENT},
         notes="Gamma ratio: overflows beyond n ~ 340; hertzmdr.numeric.powerlaw.kappa switches "
               "to hertzmdr_powerlaw_kappa_asymptotic above n = 40"),
    CLaw("powerlaw_kappa_asymptotic", {"n": Span(40.0, 1e8)}),
    CLaw("powerlaw_force", POWER, POWER_WHERE,
         notes="kappa_n = hertzmdr_powerlaw_kappa(n); the domain is drawn through the contact "
               "radius a, c_n = d/(kappa_n a^n)"),
    CLaw("powerlaw_contact_radius", {k: v for k, v in POWER.items() if k != "E_star"},
         POWER_WHERE),
    CLaw("powerlaw_force_from_radius", POWER, {}),
    CLaw("powerlaw_depth_from_force", POWER,
         {**POWER_WHERE, "F": "2*E_star*n*a*d/(n + 1)"}),
    # line contact per unit length, (5.34)-(5.37)
    CLaw("line_force", {"E_star": MOD, "L": LEN, "d": DEPTH},
         notes="(5.34) is independent of R: the line contact's depth is defined only up to a "
               "logarithm of the bodies' size, which the chapter's force-depth law leaves out"),
    CLaw("line_stiffness", {"E_star": MOD, "L": LEN}),
    CLaw("line_depth_from_force", {"E_star": MOD, "F": FORCE, "L": LEN}),
    CLaw("line_half_width", {"d": DEPTH, "R": LEN}),
    CLaw("line_half_width_from_force", {"E_star": MOD, "F": FORCE, "L": LEN, "R": LEN}),
    CLaw("line_force_per_length_from_half_width", {"E_star": MOD, "R": LEN, "a": LEN}),
    CLaw("line_max_pressure_from_force", {"E_star": MOD, "F": FORCE, "L": LEN, "R": LEN}),
    # JKR, (5.55)-(5.57) for the paraboloid
    CLaw("jkr_force_from_radius", {"E_star": MOD, "R": LEN, "a": LEN, "dgamma": DGAMMA},
         notes="along the JKR branch, parametrized by the contact radius a; the overlap at the "
               "same a is hertzmdr_jkr_depth"),
    CLaw("jkr_depth", {"E_star": MOD, "R": LEN, "a": LEN, "dgamma": DGAMMA}),
    CLaw("jkr_contact_radius_from_force", {**JKR, "t": Span(1e-9, 1e9)},
         {"F_load": "pi*R*dgamma*(t - 3/2)"},
         notes="force control: F_load >= the pull-off force -3/2 pi R dgamma"),
    CLaw("jkr_pull_off_force_fc", JKR),
    CLaw("jkr_pull_off_force_dc", JKR),
    CLaw("jkr_pull_off_depth_fc", JKR),
    CLaw("jkr_pull_off_depth_dc", JKR),
    CLaw("jkr_pull_off_radius_fc", JKR),
    CLaw("jkr_pull_off_radius_dc", JKR),
    CLaw("jkr_zero_load_radius", JKR),
    # Cattaneo-Mindlin, monotonic tangential loading at constant normal load
    CLaw("cattaneo_stick_radius", TAN_U, SLIDE_U),
    CLaw("cattaneo_force", TAN_U, SLIDE_U),
    CLaw("cattaneo_displacement", TAN_F, {"F_x": "t*mu_f*F"}),
    CLaw("cattaneo_stick_radius_from_force", {k: v for k, v in TAN_F.items() if k != "G_star"},
         {"F_x": "t*mu_f*F"}),
    CLaw("mindlin_energy", TAN_F, {"F_amp": "t*mu_f*F"}),
    CLaw("tangential_stiffness", {"G_star": MOD, "a": LEN}),
    # the effective moduli and radius of two bodies, (5.26)-(5.27)
    CLaw("bodies_effective_modulus", {"E1": MOD, "nu1": NU, "E2": MOD, "nu2": NU},
         hard=({"E1": 2e11, "nu1": 0.5, "E2": 1e6, "nu2": 0.5},)),
    CLaw("bodies_effective_radius", {"R1": LEN, "R2": LEN}),
    CLaw("shear_modulus", {"E": MOD, "nu": NU}, hard=({"E": 1e6, "nu": 0.5},)),
    CLaw("tangential_modulus", {"G1": MOD, "nu1": NU, "G2": MOD, "nu2": NU},
         hard=({"G1": 8e10, "nu1": 0.5, "G2": 1e6, "nu2": 0.5},)),
    # the exact elliptical contact (5.28)-(5.33) at a given axis ratio t = b/a
    CLaw("ellipse_radius_ratio", {"t_ba": T_BA}, unit="1",
         hard=tuple({"t_ba": h["t_ba"]} for h in ELLIPSE_HARD)),
    CLaw("ellipse_force", ELLIPSE, hard=ELLIPSE_HARD),
    CLaw("ellipse_stiffness", ELLIPSE, hard=ELLIPSE_HARD),
    CLaw("ellipse_max_pressure", ELLIPSE, hard=ELLIPSE_HARD),
    CLaw("ellipse_semi_major", {k: v for k, v in ELLIPSE.items() if k != "E_star"}),
    CLaw("ellipse_semi_minor", {k: v for k, v in ELLIPSE.items() if k != "E_star"}),
    CLaw("ellipse_depth_from_force", {"E_star": MOD, "F": FORCE, "R1": LEN, "t_ba": T_BA}),
    CLaw("ellipse_equivalent_radius", {"R1": LEN, "t_ba": T_BA}),
)

#: the hand-written part of the header: R_D by Carlson's duplication, double precision
CARLSON_RD = r"""
/* Carlson's symmetric elliptic integral of the second kind,
 *   R_D(x, y, z) = 3/2 int_0^inf dt / (sqrt(t + x) sqrt(t + y) (t + z)^(3/2)),
 * for x, y >= 0 (not both 0) and z > 0. The exact ellipse needs it: with m = 1 - t^2,
 *   2F1(1/2, 3/2; 2; m) = 4/(3 pi) R_D(0, t^2, 1)       ((K - E)/m),
 *   2F1(1/2, 1/2; 2; m) = 4/(3 pi) t^2 R_D(0, 1, t^2)   ((E - (1 - m) K)/m),
 * both free of cancellation for every 0 < t <= 1 (DLMF 19.25.1).
 * Method: Carlson's duplication (B. C. Carlson, Numer. Algorithms 10 (1995) 13-26;
 * DLMF 19.36.2). Each step adds 3 4^-k / (sqrt(z) (z + lambda)) to the sum and maps every
 * argument v to (v + lambda)/4, lambda = sqrt(x y) + sqrt(x z) + sqrt(y z), which
 * brings them together by a factor 4 per step. Once 4^-k Q < |A|, Q = (eps/4)^(-1/6)
 * times the initial spread, the fifth-order expansion in the elementary symmetric
 * functions E2..E5 of the scaled deviations truncates below the double rounding
 * (relative error of the result: a few ulp, measured in docs/c_laws.md). */
static inline double hertzmdr_carlson_rd(double x, double y, double z)
{
    const double q_factor = 576.0; /* (2^-53/4)^(-1/6) = 2^(55/6) = 575.9..., rounded up */
    double mean0 = (x + y + 3.0 * z) / 5.0, mean = mean0;
    double dx = mean0 - x, dy = mean0 - y, dz = mean0 - z;
    double q = q_factor * fmax(fabs(dx), fmax(fabs(dy), fabs(dz)));
    double sum = 0.0, scale = 1.0;
    int k;
    for (k = 0; k < 100 && scale * q >= fabs(mean); ++k) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * sy + sx * sz + sy * sz;
        sum += scale / (sz * (z + lam));
        scale *= 0.25;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        mean = 0.25 * (mean + lam);
    }
    {
        double X = dx * scale / mean, Y = dy * scale / mean, Z = -(X + Y) / 3.0;
        double xy = X * Y, z2 = Z * Z;
        double e2 = xy - 6.0 * z2, e3 = (3.0 * xy - 8.0 * z2) * Z;
        double e4 = 3.0 * (xy - z2) * z2, e5 = xy * z2 * Z;
        double series = 1.0 - 3.0 / 14.0 * e2 + e3 / 6.0 + 9.0 / 88.0 * e2 * e2
                        - 3.0 / 22.0 * e4 - 9.0 / 52.0 * e2 * e3 + 3.0 / 26.0 * e5;
        return scale * series / (mean * sqrt(mean)) + 3.0 * sum;
    }
}
"""


class _CPrinter(C99CodePrinter):
    """C99 printer: numeric constants as double literals (M_PI and the like are POSIX, not
    C99), rational powers through sqrt and cbrt, and nothing it does not know."""

    def _print_Pow(self, expr):
        # x^(p/3) as cbrt(x)^p: pow(x, 2.0/3.0) takes the exponent rounded to 53 bits, which
        # costs |log x| 2^-54 relative (3e-14 at x = 1e-300); cbrt is exact to an ulp.
        # x^(p/2) as x^((p-1)/2) sqrt(x): a correctly rounded sqrt and a product, several
        # times faster than pow (d^(3/2) in every Hertz force). A negative p is a quotient.
        e = expr.exp
        if e.is_Rational and e.q in (2, 3) and abs(e.p) != 1:
            base = self._print(expr.base)
            root = f"sqrt({base})" if e.q == 2 else f"cbrt({base})"
            if e.q == 3:
                body = f"pow({root}, {abs(e.p)})"
            else:
                k = (abs(e.p) - 1) // 2
                paren = self.parenthesize(expr.base, precedence(expr))
                body = root if k == 0 else (f"{paren}*{root}" if k == 1
                                            else f"pow({base}, {k})*{root}")
            return f"(1.0/({body}))" if e.p < 0 else f"({body})"
        return super()._print_Pow(expr)

    def _print_not_supported(self, expr):
        raise ValueError(f"cannot print {expr!r} as C99")


_RD = sp.Function(PREFIX + "carlson_rd")


def _hyper_to_rd(ap, bq, z):
    """The exact ellipse's 2F1 through Carlson's R_D of the complement 1 - m = t^2, taken from
    the expression itself: m = 1 - t^2 rounded would cost what the NumPy route loses."""
    half, comp = sp.Rational(1, 2), sp.expand(1 - z)
    if tuple(ap) == (half, 3 * half) and tuple(bq) == (2,):  # (K - E)/m
        return 4 / (3 * sp.pi) * _RD(0, comp, 1)
    if tuple(ap) == (half, half) and tuple(bq) == (2,):  # (E - (1 - m) K)/m
        return 4 / (3 * sp.pi) * comp * _RD(0, 1, comp)
    raise ValueError(f"cannot print hyper({ap}, {bq}, {z}) as C99")


def fold_constants(expr: sp.Expr) -> sp.Expr:
    """``expr`` with the constant factors of every product (``sqrt(2) pi^(2/3)/4``) replaced
    by one literal, correctly rounded to double: one rounding instead of one per factor."""
    if expr.is_Atom:
        return expr
    args = [fold_constants(arg) for arg in expr.args]
    if expr.is_Mul:
        const = [arg for arg in args if not arg.free_symbols]
        rest = [arg for arg in args if arg.free_symbols]
        if len(const) > 1 or (const and not const[0].is_Rational):
            value = sp.Mul(*const)
            if value.is_Rational and abs(value.q) == 1:
                return sp.Mul(value, *rest)
            return sp.Mul(sp.Float(value.evalf(30), 17), *rest, evaluate=False)
    return expr.func(*args)


def print_c(expr: sp.Expr) -> tuple[list[str], str]:
    """``expr`` as C99: the declarations of its locals, and the double expression returned.

    Constant factors are folded (:func:`fold_constants`), pi and the like are 17-digit
    literals, rational powers go through sqrt and cbrt, and each distinct R_D call of the exact
    ellipse is evaluated once, into a local ``rd<k>`` (the rest of the expression is left as
    printed, so that it rounds as the NumPy route does)."""
    printer = _CPrinter({"math_macros": {}, "inline": True, "allow_unknown_functions": False,
                         "user_functions": {_RD.__name__: _RD.__name__}})
    expr = fold_constants(expr.replace(sp.hyper, _hyper_to_rd))
    calls = sorted(expr.atoms(_RD), key=sp.default_sort_key)
    names = [sp.Symbol(f"rd{k}") for k in range(len(calls))]
    decls = [f"const double {n} = {printer.doprint(c)};" for n, c in zip(names, calls,
                                                                           strict=True)]
    return decls, printer.doprint(expr.subs(dict(zip(calls, names, strict=True))))


def _unit(law: CLaw, rel: Relation) -> str:
    """The unit of the result: the summary's ``[unit]``, else the law's own."""
    head, sep, tail = rel.summary.rpartition("[")
    unit = tail.split("]")[0] if sep else law.unit
    if not unit:
        raise ValueError(f"{law.relation}: the summary gives no [unit]; set CLaw.unit")
    return unit


def _wrap(text: str, first: str, rest: str) -> list[str]:
    return textwrap.wrap(text, 96, initial_indent=first, subsequent_indent=rest,
                         break_on_hyphens=False) or [first.rstrip()]


def render_law(law: CLaw, rel: Relation) -> str:
    """One ``static inline`` function with its comment: what, units, origin, domain."""
    lines = _wrap(f"{law.c_name}: {rel.summary}.", "/* ", " * ")
    lines += _wrap(f"Equation: {rel.equation}; derived from {rel.origin} "
                   f"(hertzmdr.derive.{rel.family}); NumPy: hertzmdr.numeric._generated."
                   f"{rel.name}; verified by {rel.verified_by}.", " * ", " *   ")
    if rel.stable_why:
        lines += _wrap(f"Stable form: {rel.stable_why}.", " * ", " *   ")
    width = max(len(s.name) for s in rel.args)
    for s in rel.args:
        unit, meaning = DESCRIPTIONS[s.name]
        if s.name in law.spans:
            dom = law.spans[s.name].text()
        elif s.name in law.where:
            dom = f"= {law.where[s.name]}"
        else:
            raise ValueError(f"{law.relation}: argument {s.name} has no documented domain")
        lines += _wrap(f"{s.name:<{width}}  [{unit}] {meaning}; {dom}", " *   ",
                       " *   " + " " * (width + 2))
    aux = [k for k in law.spans if k not in {s.name for s in rel.args}]
    if aux:
        text = ", ".join(f"{k} in {law.spans[k].text()}" for k in aux)
        lines += _wrap(f"with {text}", " *   ", " *     ")
    lines.append(f" * Returns: [{_unit(law, rel)}]")
    if law.notes:
        lines += _wrap(f"Note: {law.notes}.", " * ", " *   ")
    args = ", ".join(f"double {s.name}" for s in rel.args)
    # an argument the law does not depend on (JKR's pull-off force and E*) keeps the NumPy
    # function's signature; the cast tells the compiler it is unused on purpose
    unused = "".join(f"    (void){s.name}; /* the law does not depend on it */\n"
                     for s in rel.args if s not in rel.expr.free_symbols)
    decls, body = print_c(rel.expr)
    local = "".join(f"    {d}\n" for d in decls)
    return ("\n".join(lines) + " */\n"
            f"static inline double {law.c_name}({args})\n{{\n{unused}{local}"
            f"    return {body};\n}}\n")


def render_header(relations) -> str:
    """The header ``numeric/c/hertzmdr_laws.h``: every law of :data:`LAWS`, sorted by name."""
    by_name = {rel.name: rel for rel in relations}
    missing = [law.relation for law in LAWS if law.relation not in by_name]
    if missing:
        raise ValueError(f"LAWS names relations that do not exist: {missing}")
    laws = sorted(LAWS, key=lambda law: law.relation)
    guard = "HERTZMDR_LAWS_H"
    names = "\n".join(f" *   {law.c_name}" for law in laws)
    head = f"""\
/* hertzmdr_laws.h -- the contact laws of hertzmdr for DEM codes: C99, double precision.
 *
 * GENERATED FILE -- DO NOT EDIT. Written by `{COMMAND}` (make generate) from the
 * SymPy derivations of hertzmdr.derive (derive/c_codegen.py prints them with SymPy's C99
 * printer); `{COMMAND} --check` fails when this file is stale.
 *
 * Every function is `static inline`, takes and returns doubles in SI units, and depends on
 * <math.h> alone (link with -lm where the platform needs it). Each one prints the same
 * relation as the NumPy function of the same name in hertzmdr.numeric._generated (its stable
 * form, where the derivation gives one), its constant factors folded into one literal and its
 * rational powers taken through sqrt and cbrt. tests/test_c_header.py compiles it as C99 and
 * as C++ with -Wall -Wextra -Werror -pedantic and compares every function with the NumPy and
 * the 30-digit mpmath routes over the domain stated in its comment: it agrees with NumPy, and
 * is at least as accurate, to 2e-15 beyond NumPy's own error. Arguments are not validated:
 * outside the stated domain a result may be inf or nan. Guide and timings: docs/c_laws.md;
 * every signature: docs/c_laws_reference.md.
 *
 * Functions:
{names}
 */
#ifndef {guard}
#define {guard}

#include <math.h>
"""
    body = [CARLSON_RD]
    for law in laws:
        body.append("\n" + render_law(law, by_name[law.relation]))
    return head + "".join(body) + f"\n#endif /* {guard} */\n"


def render_reference(relations) -> str:
    """``docs/c_laws_reference.md``: every function of the header with its signature, units,
    equation and documented domain, in the header's order."""
    by_name = {rel.name: rel for rel in relations}
    out = ["# C header reference: `hertzmdr_laws.h`\n\n",
           f"<!-- GENERATED FILE -- DO NOT EDIT. Written by `{COMMAND}` with the header; "
           "`--check` fails when stale. -->\n\n",
           "Every function of `numeric/c/hertzmdr_laws.h` (guide, examples and timings: "
           "[c_laws.md](c_laws.md)): `static inline`, doubles in SI units, the arguments in the "
           "order of the NumPy function of the same name in `hertzmdr.numeric._generated`. "
           "The domain is the one `tests/test_c_header.py` samples (log-uniform unless marked "
           "linear; an argument given by `=` is computed from the others, with `t` a fraction "
           "of its limit). Outside it a result may be inf or nan: the header validates "
           "nothing.\n\n"
           "Also in the header: `double hertzmdr_carlson_rd(double x, double y, double z)`, "
           "Carlson's R_D (x, y >= 0, not both 0, z > 0), which the exact ellipse uses.\n\n"]
    for law in sorted(LAWS, key=lambda law: law.relation):
        rel = by_name[law.relation]
        sig = ", ".join(f"double {s.name}" for s in rel.args)
        out.append(f"### `{law.c_name}`\n\n```c\ndouble {law.c_name}({sig});\n```\n\n"
                   f"{rel.summary[0].upper() + rel.summary[1:]}; {rel.equation}, "
                   f"`hertzmdr.derive.{rel.family}`.\n\n"
                   "| argument | unit | meaning | domain |\n|---|---|---|---|\n")
        for s in rel.args:
            unit, meaning = DESCRIPTIONS[s.name]
            dom = (law.spans[s.name].text() if s.name in law.spans
                   else f"= `{law.where[s.name]}`")
            out.append(f"| `{s.name}` | {unit} | {meaning} | {dom} |\n")
        aux = [k for k in law.spans if k not in {s.name for s in rel.args}]
        if aux:
            out.append("\nDrawn through " + ", ".join(
                f"`{k}` in {law.spans[k].text()}" for k in aux) + ".\n")
        if law.notes:
            out.append(f"\n{law.notes[0].upper() + law.notes[1:]}.\n")
        out.append("\n")
    return "".join(out)
