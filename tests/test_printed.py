"""Every derived relation against the chapter's printed form, and every stable rewrite against
the form it replaces: symbolically, and numerically at 50 digits at random points (so that a
weak ``simplify`` cannot hide a real difference, nor a lucky one invent an agreement)."""

import random

import mpmath as mp
import pytest
import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from hertzmdr.derive import all_relations

RELATIONS = all_relations()


def _in_domain(rel, expr):
    return expr.subs(rel.domain) if rel.domain else expr


def _points(rel, x, y, n=5, seed=1):
    """Random points of the domain: nu in (0, 0.5), the unit-interval symbols t, t_* of
    ``Relation.domain`` in (0, 1), every other symbol in (0.5, 3)."""
    rng = random.Random(seed)
    syms = sorted(x.free_symbols | y.free_symbols, key=lambda s: s.name)
    for _ in range(n):
        pt = {}
        for s in syms:
            if s.name.startswith("nu"):
                pt[s] = sp.Rational(rng.randint(1, 49), 100)
            elif s.name == "t" or s.name.startswith("t_"):
                pt[s] = sp.Rational(rng.randint(1, 99), 100)
            else:
                pt[s] = sp.Rational(rng.randint(50, 300), 100)
        yield pt


def _numeric_diffs(rel, x, y):
    x, y = _in_domain(rel, _exact(x)), _in_domain(rel, _exact(y))
    out = []
    with mp.workdps(50):
        for pt in _points(rel, x, y):
            vx, vy = sp.N(x.subs(pt), 50), sp.N(y.subs(pt), 50)
            out.append(abs(vx - vy) / max(abs(vx), abs(vy), sp.Float(1e-300)))
    return out


def _exact(e):
    """Integer-valued float exponents (xi**(-1.0), printed so to keep powers from overflowing)
    as the exact integers they are."""
    return e.xreplace({f: sp.Integer(int(f)) for f in e.atoms(sp.Float) if float(f).is_integer()})


def _algebraic_zero(e):
    """e == 0 for an algebraic e: every square root is split into square roots of the factors
    of its radicand (principal branches, positive on the domain), each of those becomes a
    symbol q with q^2 = radicand, and the numerator is reduced modulo those relations."""
    def split(z):
        coeff, factors = sp.factor_list(z.base)
        factors = [list(f) for f in factors]
        if coeff < 0:  # move the sign into a factor of odd power: -(t - 1) = 1 - t
            odd = next((f for f in factors if f[1] % 2), None)
            if odd is None:
                return z
            coeff, odd[0] = -coeff, -odd[0]
        return sp.sqrt(coeff) * sp.Mul(*(sp.sqrt(b) ** k for b, k in factors))

    e = sp.together(e.replace(lambda z: z.is_Pow and abs(z.exp) == sp.S.Half,
                              lambda z: split(z) if z.exp > 0 else 1 / split(1 / z)))
    num = sp.expand(sp.numer(e))
    roots = sorted(num.atoms(sp.Pow), key=str)
    roots = [z for z in roots if z.exp == sp.S.Half]
    qs = sp.symbols(f"q0:{len(roots)}")
    num = sp.expand(num.subs(dict(zip(roots, qs, strict=True))))
    rules = {q**2: z.base for q, z in zip(qs, roots, strict=True)}
    for _ in range(8):
        reduced = sp.expand(num.replace(
            lambda m: m.is_Pow and m.base in qs and m.exp >= 2,
            lambda m: rules[m.base**2] * m.base ** (m.exp - 2)))
        if reduced == num:
            break
        num = reduced
    return sp.simplify(num) == 0


def _equal_in_atanh(rel, x, y):
    """log1p(z) is 2 atanh(z/(2 + z)): rewritten so, the stable forms of atanh built from
    log1p meet the derived atanh; Piecewise forms are compared branch by branch, and two atanh
    whose arguments are equal as algebraic functions (:func:`_algebraic_zero`) are merged."""
    def prep(e):
        e = _in_domain(rel, e).replace(log1p, lambda z: 2 * sp.atanh(sp.simplify(z / (2 + z))))
        return sp.hyperexpand(e).replace(sp.atanh, lambda z: sp.atanh(sp.simplify(z)))

    diff = sp.piecewise_fold(prep(x) - prep(y))
    for e in ([b for b, _ in diff.args] if isinstance(diff, sp.Piecewise) else [diff]):
        e = sp.simplify(e)
        args = sorted((f.args[0] for f in e.atoms(sp.atanh)), key=str)
        for i, A in enumerate(args):
            for B in args[i + 1:]:
                if _algebraic_zero(A - B):
                    e = sp.simplify(e.subs(sp.atanh(A), sp.atanh(B)))
        if e != 0:
            return False
    return True


def _equal_in_logs(rel, x, y):
    """Sums of logarithms (log1p(z) as log(1 + z)) with commensurate coefficients: equal when
    the product of their arguments raised to the coefficients' ratios is 1 as an algebraic
    function (:func:`_algebraic_zero`); the arguments are positive on the domain (the 50-digit
    check catches a branch)."""
    e = _in_domain(rel, x - y).replace(log1p, lambda z: sp.log(1 + z))
    terms = sp.Add.make_args(sp.expand(e))
    parts = []
    for term in terms:
        logs = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.log)]
        if len(logs) != 1:
            return False
        parts.append((sp.simplify(term / logs[0]), logs[0].args[0]))
    k0 = parts[0][0]
    prod = sp.S.One
    for k, arg in parts:
        m = sp.simplify(k / k0)
        if not m.is_Rational:
            return False
        prod *= arg**m
    return _algebraic_zero(sp.together(prod) - 1)


def _equal(rel, x, y):
    x, y = _exact(x), _exact(y)
    if sp.simplify(sp.hyperexpand(_in_domain(rel, x - y))) == 0:
        return True
    if (x.has(log1p) or y.has(log1p)) and (x.has(sp.atanh) or y.has(sp.atanh)):
        return _equal_in_atanh(rel, x, y)
    diff = _in_domain(rel, x - y)
    if diff.has(sp.acosh, sp.asinh) and sp.simplify(diff.rewrite(sp.log)) == 0:
        return True  # inverse hyperbolic identities: simplify proves them in logarithms
    fx, fy = ([e for e in v.atoms(sp.Function) if isinstance(e, (sp.asinh, sp.acosh))]
              for v in (x, y))
    if len(fx) == 1 and len(fy) == 1:
        # x = c F, y = c' G with F, G >= 0 inverse hyperbolic: x = y iff G = m F, m = c/c', iff
        # cosh(m F) = cosh(G) (cosh is one-to-one on [0, inf)); expand_trig writes cosh(m F)
        # as a polynomial in sinh(F) or cosh(F), which cancels against asinh or acosh
        m = sp.simplify((x / fx[0]) / (y / fy[0]))
        if m.is_Rational and m > 0:
            lhs = sp.expand_trig(sp.cosh(m * fx[0]))
            return sp.simplify(_in_domain(rel, lhs - sp.cosh(fy[0]))) == 0
    ratio = sp.powsimp(sp.expand_power_base(_in_domain(rel, x / y), force=True), force=True)
    if sp.simplify(ratio) == 1:
        return True  # products of powers regrouped (positive factors; the 50-digit check below
        # catches a sign or a branch)
    const = sp.simplify(ratio)
    if not const.free_symbols and const.is_algebraic:
        # nested radicals (the Hertz maximum of |tau_rz|) that simplify leaves apart: a
        # constant ratio is 1 exactly when the minimal polynomial of ratio - 1 is X
        return sp.minimal_polynomial(const - 1, sp.Symbol("X")) == sp.Symbol("X")
    if x.has(expm1) or y.has(expm1):
        # 1 - exp(k log1p(q)) against 1 - B^k: write exp(k log(1 + q)) as (1 + q)^k with the
        # base simplified (B > 0 on the domain; the 50-digit check below catches a sign)
        def powers(e):
            e = _in_domain(rel, e).replace(expm1, lambda z: sp.exp(z) - 1)
            e = e.replace(log1p, lambda z: sp.log(1 + z))

            def is_power(q):
                return (isinstance(q, sp.exp) and isinstance(q.args[0], sp.Mul)
                        and any(isinstance(f, sp.log) for f in q.args[0].args))

            def as_power(q):
                (lg,) = [f for f in q.args[0].args if isinstance(f, sp.log)]
                base = sp.simplify(sp.expand_trig(lg.args[0]))
                return sp.Pow(base, q.args[0] / lg)
            return e.replace(is_power, as_power)

        return sp.simplify(sp.expand_trig(powers(x) - powers(y))) == 0
    if x.has(log1p) and y.has(sp.log) and not x.has(sp.exp, expm1) and (
            _equal_in_logs(rel, x, y)):
        return True
    if x.has(log1p) or y.has(log1p):
        # exp(k log1p(-q)) against (1 - q)^k: simplify does not know 1 - q > 0. Both sides
        # are positive on the domain (the 50-digit check below catches a sign), so compare
        # their logarithms, expanded over the factored arguments
        def logs(e):
            e = _in_domain(rel, e).replace(log1p, lambda z: sp.log(1 + z))
            return sp.log(e).replace(sp.log, lambda z: sp.log(sp.factor(z)))

        diff = sp.expand_log(logs(x) - logs(y), force=True)
        diff = diff.replace(sp.log, lambda z: sp.log(sp.factor(z)))
        return sp.simplify(sp.expand_log(sp.expand(diff), force=True)) == 0
    return False


@pytest.mark.parametrize("rel", [r for r in RELATIONS if r.printed is not None],
                         ids=lambda r: r.name)
def test_derived_against_print(rel):
    diffs = _numeric_diffs(rel, rel.derived, rel.printed)
    if rel.erratum:
        # the print is wrong: the two must differ by far more than rounding at 50 digits
        assert max(diffs) > 1e-10, f"{rel.name}: marked as erratum but agrees with the print"
    else:
        assert _equal(rel, rel.derived, rel.printed), f"{rel.name}: derived != printed"
        assert max(diffs) < 1e-45, f"{rel.name}: numeric mismatch {max(diffs)}"


@pytest.mark.parametrize("rel", [r for r in RELATIONS if r.stable is not None],
                         ids=lambda r: r.name)
def test_stable_form_equals_derived(rel):
    assert _equal(rel, rel.stable, rel.derived), f"{rel.name}: stable form != derived"
    assert max(_numeric_diffs(rel, rel.stable, rel.derived)) < 1e-45
