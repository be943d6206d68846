"""Print the derived relations as a NumPy module and as Markdown.

The output is deterministic: relations are sorted by name, and everything printed is a pure
function of the relations and the pinned SymPy release (``constraints.txt``).
"""

from __future__ import annotations

import textwrap

import sympy as sp
from sympy.printing.numpy import SciPyPrinter
from sympy.printing.precedence import precedence
from sympy.printing.pycode import MpmathPrinter, PythonCodePrinter

from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import DESCRIPTIONS

COMMAND = "python -m hertzmdr.derive"

MODULE_HEADER = f'''\
"""Functions generated from the SymPy derivations in ``hertzmdr.derive``.

GENERATED FILE -- DO NOT EDIT. Written by ``{COMMAND}`` (``make generate``);
``{COMMAND} --check`` fails when this file is stale. Each function cites the chapter's
equation, the derivation it comes from and the test that verifies it by an independent route.
Arguments are floats or NumPy arrays in SI units; they are not validated here -- the
hand-written modules of ``hertzmdr.numeric`` validate and broadcast. Called with Python floats
only, a function evaluates the same expression with the math module (its scalar path).
"""

import math

import numpy

'''

MP_MODULE_HEADER = f'''\
"""The relations of ``hertzmdr.derive`` printed for mpmath: any precision, no SymPy needed.

GENERATED FILE -- DO NOT EDIT. Written by ``{COMMAND}`` (``make generate``) from the same
expressions as ``_generated.py``; ``{COMMAND} --check`` fails when this file is stale. Call with
mpmath numbers inside ``mpmath.workdps(...)``: every constant is an exact mpmath rational, so the
result carries the working precision. The accuracy report (``hertzmdr accuracy``) takes its
50-digit truths from here; ``tests/`` check these expressions against independent quadratures.
"""

import mpmath

'''


class _Printer(SciPyPrinter):
    """SciPy printer that refuses to print what it does not know, instead of a comment."""

    def _print_Pi(self, expr):  # numpy.pi, not scipy.constants.pi: no SciPy import for pi
        return "numpy.pi"

    def _print_Piecewise(self, expr):
        """A Piecewise whose last condition is True as nested numpy.where, first piece
        outermost (the first true condition wins, as in numpy.select): the same values as
        SymPy's numpy.select(conds, exprs, default=nan), without select's ~30 us of list
        handling a call (the exact sphere's fit calls its Piecewise ~10 times a fit)."""
        from sympy.logic.boolalg import ITE

        args = expr.args
        if args[-1].cond is not sp.true or any(a.cond.has(ITE) for a in args):
            return super()._print_Piecewise(expr)
        out = self._print(args[-1].expr)
        for arg in reversed(args[:-1]):
            out = (f"{self._module_format(self._module + '.where')}"
                   f"({self._print(arg.cond)}, {self._print(arg.expr)}, {out})")
        return out

    def _print_Exp1(self, expr):
        return "numpy.e"

    def _print_EulerGamma(self, expr):
        return "numpy.euler_gamma"

    def _print_hyper(self, expr):
        if len(expr.ap) != 2 or len(expr.bq) != 1:
            return self._print_not_supported(expr)
        args = ", ".join(self._print(e) for e in (*expr.ap, *expr.bq, expr.argument))
        return f"scipy.special.hyp2f1({args})"

    # SymPy's elliptic_k(m), elliptic_e(m), elliptic_f(phi, m), elliptic_e(phi, m) and SciPy's
    # ellipk(m), ellipe(m), ellipkinc(phi, m), ellipeinc(phi, m) share the parameter m = k^2.
    def _print_elliptic_k(self, expr):
        return f"scipy.special.ellipk({self._print(expr.args[0])})"

    def _print_elliptic_e(self, expr):
        args = ", ".join(self._print(e) for e in expr.args)
        return f"scipy.special.{'ellipe' if len(expr.args) == 1 else 'ellipeinc'}({args})"

    def _print_elliptic_f(self, expr):
        args = ", ".join(self._print(e) for e in expr.args)
        return f"scipy.special.ellipkinc({args})"

    def _print_carlson_rd(self, expr):  # Carlson's R_D(x, y, z), z the distinguished argument
        args = ", ".join(self._print(e) for e in expr.args)
        return f"scipy.special.elliprd({args})"

    def _print_not_supported(self, expr):
        raise ValueError(f"cannot print {expr!r} as NumPy/SciPy code")


class _MpPrinter(MpmathPrinter):
    """mpmath printer with the elliptic integrals (parameter m, as in SymPy)."""

    def _print_elliptic_k(self, expr):
        return f"mpmath.ellipk({self._print(expr.args[0])})"

    def _print_elliptic_e(self, expr):  # mpmath.ellipe(m) or ellipe(phi, m)
        return f"mpmath.ellipe({', '.join(self._print(e) for e in expr.args)})"

    def _print_carlson_rd(self, expr):
        return f"mpmath.elliprd({', '.join(self._print(e) for e in expr.args)})"

    def _print_elliptic_f(self, expr):
        return f"mpmath.ellipf({', '.join(self._print(e) for e in expr.args)})"


class _MathPrinter(PythonCodePrinter):
    """The same expression for Python floats, with the math module: the scalar fast path.

    A non-integer power is ``math.pow``, which raises ValueError for a negative base where
    ``**`` would return a complex number; a square is a product, exactly NumPy's ``x**2``
    (its square loop); anything the math module lacks (hypergeometric and elliptic
    functions) is refused, and that relation gets no scalar path."""

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp == sp.S.Half or exp == -sp.S.Half:
            return super()._print_Pow(expr, rational)
        b = self.parenthesize(base, precedence(expr), strict=True)
        if exp == 2:
            return f"({b}*{b})"
        if exp.is_Integer or (exp.is_Float and exp == int(exp)):
            return super()._print_Pow(expr, rational)
        return f"math.pow({self._print(base)}, {self._print(exp)})"

    def _print_not_supported(self, expr):
        raise ValueError(f"cannot print {expr!r} with the math module")

    _print_hyper = _print_elliptic_k = _print_elliptic_e = _print_elliptic_f = \
        _print_carlson_rd = _print_not_supported


def print_expr(expr: sp.Expr, flavor: str = "numpy") -> str:
    cls = {"numpy": _Printer, "math": _MathPrinter}.get(flavor, _MpPrinter)
    printer = cls({"fully_qualified_modules": True, "inline": True,
                   "allow_unknown_functions": False})
    return printer.doprint(expr)


def _arg_lines(rel: Relation, flavor: str) -> str:
    kind = "float or ndarray" if flavor == "numpy" else "mpmath.mpf"
    lines = []
    for s in rel.args:
        unit, meaning = DESCRIPTIONS[s.name]
        lines.append(f"{s.name} : {kind}\n    {meaning} [{unit}]")
    return "\n".join(lines)


def render_function(rel: Relation, flavor: str = "numpy") -> str:
    code = print_expr(rel.expr, flavor)
    needed = [m for m in ("functools", "scipy.special") if f"{m}." in code]
    imports = "".join(f"    import {m}\n" for m in needed) + ("\n" if needed else "")
    notes = [f"Chapter: {rel.equation}. Derived from: {rel.origin}.",
             f"Derivation: ``hertzmdr.derive.{rel.family}``. Verified by ``{rel.verified_by}``."]
    if rel.stable_why:
        notes.append(f"Printed in a stable form: {rel.stable_why}.")
    if rel.erratum:
        notes.append(f"Differs from the print (see docs/errata.md): {rel.erratum}")
    notes_text = "\n\n".join(textwrap.fill(n, 88) for n in notes)
    summary = rel.summary[0].upper() + rel.summary[1:]
    params = (f"Parameters\n----------\n{_arg_lines(rel, flavor)}\n" if rel.args
              else "A constant: no parameters.\n")
    doc = f"{summary}.\n\n{notes_text}\n\n{params}"
    doc = textwrap.indent(doc, "    ").rstrip() + "\n    "
    doc = doc.replace("\\", "\\\\")
    argstr = ", ".join(s.name for s in rel.args)
    head = f'def {rel.name}({argstr}):\n    """{doc.lstrip()}"""\n{imports}'
    return head + (_scalar_path(rel) if flavor == "numpy" else "") + f"    return {code}\n"


def fused_groups() -> dict[str, tuple[str, ...]]:
    """Every family's ``FUSED``: {function name: names of the relations it returns at once}."""
    import importlib

    from hertzmdr.derive.relation import family_modules

    out: dict[str, tuple[str, ...]] = {}
    for fam in family_modules():
        for name, members in getattr(importlib.import_module(f"hertzmdr.derive.{fam}"),
                                     "FUSED", {}).items():
            if name in out:
                raise ValueError(f"fused function {name} defined twice")
            out[name] = tuple(members)
    return dict(sorted(out.items()))


class _FusedPrinter(_Printer):
    """For fused fields: a reciprocal as a quotient and a square or cube as products (NumPy's
    pow costs several times a product; each is within an ulp of it); the rest as _Printer."""

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp == -1:
            return f"1/{self.parenthesize(base, precedence(expr), strict=True)}"
        if exp in (2, 3):
            b = self.parenthesize(base, precedence(expr), strict=True)
            return "(" + "*".join([b] * int(exp)) + ")"
        return super()._print_Pow(expr, rational)


def render_fused(name: str, members: list[Relation]) -> str:
    """One NumPy function returning several relations at once, their common subexpressions
    (SymPy's ``cse``) computed once: for a field whose components share most of their work.
    Each value is the member relation's expression, to rounding (cse writes a quotient as a
    product with a reciprocal, and sums in another order; _FusedPrinter's products)."""
    args = sorted({s for rel in members for s in rel.args}, key=lambda s: s.name)
    repl, reduced = sp.cse([rel.expr for rel in members], symbols=sp.numbered_symbols("_c"))
    printer = _FusedPrinter({"fully_qualified_modules": True, "inline": True,
                             "allow_unknown_functions": False})
    body = [f"    {sym} = {printer.doprint(e)}\n" for sym, e in repl]
    ret = ", ".join(printer.doprint(e) for e in reduced)
    code = "".join(body) + ret
    needed = [m for m in ("functools", "scipy.special") if f"{m}." in code]
    imports = "".join(f"    import {m}\n" for m in needed) + ("\n" if needed else "")
    listing = ", ".join(f"``{rel.name}``" for rel in members)
    doc = textwrap.fill(f"({listing}) at once, their common subexpressions computed once "
                        "(SymPy's cse): each as the relation's own function gives it, to "
                        "rounding. Arguments as there.", 88, initial_indent="    ",
                        subsequent_indent="    ").lstrip()
    argstr = ", ".join(s.name for s in args)
    return (f'def {name}({argstr}):\n    """{doc}\n    """\n{imports}' + "".join(body)
            + f"    return {ret}\n")


def math_name(name: str) -> str:
    """The name of a relation's math-module function in the generated module."""
    return f"_math_{name}"


def render_math_function(rel: Relation) -> str:
    """The relation for Python floats, with the math module: ``_math_<name>``, ~50 times faster
    than NumPy on scalars. It raises where the math module does (overflow, division by zero, a
    domain error). "" when the math module cannot print the expression (SciPy's functions)."""
    try:
        code = print_expr(rel.expr, "math")
    except ValueError:
        return ""
    argstr = ", ".join(s.name for s in rel.args)
    return (f"def {math_name(rel.name)}({argstr}):\n"
            f'    """``{rel.name}`` for Python floats (the math module); raises where it does."""\n'
            f"    return {code}\n")


def _scalar_path(rel: Relation) -> str:
    """The branch of a generated function for Python floats: its math-module form; where that
    raises, the NumPy form runs as before (its inf/nan and warnings)."""
    if not rel.args or not render_math_function(rel):
        return ""
    floats = " and ".join(f"type({s.name})\0is\0float" for s in rel.args)  # \0: no break
    cond = textwrap.fill(f"if {floats}:", 92, initial_indent="    ",
                         subsequent_indent="            ").replace("\0", " ")
    if "\n" in cond:
        cond = cond.replace("    if ", "    if (", 1)[:-1] + "):"
    argstr = ", ".join(s.name for s in rel.args)
    return (f"{cond}\n        try:  # the scalar path: Python floats, the math module\n"
            f"            return {math_name(rel.name)}({argstr})\n"
            "        except (ArithmeticError, ValueError):  # NumPy's inf/nan and warnings\n"
            "            pass\n")


def textbook(rel: Relation) -> Relation:
    """The derived form of a relation printed in a stable form, as a relation of its own
    (``textbook_<name>``), so that the accuracy report can measure what the rewrite buys."""
    import dataclasses

    return dataclasses.replace(
        rel, name=f"textbook_{rel.name}", stable=None, stable_why=None,
        summary=f"{rel.summary}, in the derived (textbook) form; use {rel.name}: "
        f"{rel.stable_why}")


def render_module(relations, flavor: str = "numpy") -> str:
    """The generated module: ``flavor`` "numpy" (float64, arrays) or "mpmath" (any precision).

    Relations printed in a stable form also get their derived form as ``textbook_<name>``,
    outside ``__all__``: it exists to be measured, not used."""
    parts = [MODULE_HEADER if flavor == "numpy" else MP_MODULE_HEADER]
    names = [rel.name for rel in relations]
    parts.append("__all__ = [\n" + "".join(f"    {n!r},\n" for n in names) + "]\n")
    if flavor == "numpy":  # a listing that needs no SymPy (hertzmdr.numeric.demo prints it)
        rows = "".join(f"    ({rel.name!r}, {rel.equation!r}, {rel.family!r}, "
                       f"{sp.sstr(rel.derived)!r}, {rel.erratum or ''!r}),\n"
                       for rel in relations)
        parts.append("\n#: every relation: (name, equation, family, derived formula, erratum or "
                     "\"\")\nRELATIONS = (\n" + rows + ")\n")
    for rel in relations:
        parts.append("\n\n" + render_function(rel, flavor))
    for rel in relations:
        if rel.stable is not None:
            parts.append("\n\n" + render_function(textbook(rel), flavor))
    if flavor == "numpy":  # fused fields, then the math-module forms the scalar paths call
        by_name = {rel.name: rel for rel in relations}
        for name, members in fused_groups().items():
            parts.append("\n\n" + render_fused(name, [by_name[m] for m in members]))
        for rel in relations:
            parts.append("\n\n" + render_math_function(rel))
            if rel.stable is not None:
                parts.append("\n\n" + render_math_function(textbook(rel)))
    return "".join(p for p in parts if p != "\n\n")


def _latex(expr: sp.Expr) -> str:
    return sp.latex(expr, symbol_names={sp.Symbol("E_star", positive=True): "E^*"})


def render_derivations(relations) -> str:
    out = ["# Derived relations\n\n",
           f"<!-- GENERATED FILE -- DO NOT EDIT. Written by `{COMMAND}`; "
           "`--check` fails when stale. -->\n\n",
           "Every relation below is derived with SymPy in `derive/` from its starting point, "
           "printed into `numeric/_generated.py`, and verified by the test named beside it "
           "through an independent route (quadrature of the pressure, the Boussinesq kernel, "
           "the equation of motion). Units are SI.\n\n"]
    by_family: dict[str, list[Relation]] = {}
    for rel in relations:
        by_family.setdefault(rel.family, []).append(rel)
    for fam in sorted(by_family):
        out.append(f"## `hertzmdr.derive.{fam}`\n\n")
        for rel in by_family[fam]:
            out.append(f"### {rel.equation} `{rel.name}`\n\n{rel.summary}; from {rel.origin}.\n\n")
            out.append(f"$$ {_latex(rel.derived)} $$\n\n")
            if rel.stable is not None:
                out.append(f"Printed as the stable form ({rel.stable_why}):\n\n"
                           f"$$ {_latex(rel.stable)} $$\n\n")
            if rel.erratum:
                out.append(f"**Differs from the print** (see [errata](errata.md)): "
                           f"{rel.erratum}\n\n")
            out.append(f"Verified by `{rel.verified_by}`.\n\n")
    return "".join(out)


def render_errata(relations) -> str:
    out = ["# Errata: where the derivation disagrees with the chapter's print\n\n",
           f"<!-- GENERATED FILE -- DO NOT EDIT. Written by `{COMMAND}` from the relations "
           "whose derived form differs from the printed one; `--check` fails when stale. -->\n\n",
           "For each entry: the equation, what the derivation gives, what the chapter prints, "
           "the symbolic difference, and a numeric counterexample. The derivation wins; "
           "`tests/test_printed.py` re-checks every entry and every agreement.\n\n"]
    bad = [rel for rel in relations if rel.erratum]
    if not bad:
        out.append("No disagreement found.\n")
    for rel in sorted(bad, key=lambda r: (r.equation, r.name)):
        diff = sp.simplify(rel.derived - rel.printed)
        point = counterexample(rel)
        subs = ", ".join(f"{k} = {v}" for k, v in point.items())
        # evaluated inside the relation's domain (e.g. r = a t, 0 < t < 1, for the cone)
        dom = rel.domain or {}
        if dom:
            subs += " with " + ", ".join(f"{k} = {sp.sstr(v)}" for k, v in dom.items())
        dv = sp.N(rel.derived.subs(dom).subs(point), 15)
        pv = sp.N(rel.printed.subs(dom).subs(point), 15)
        out.append(f"## {rel.equation}: `{rel.name}`\n\n{rel.erratum}\n\n"
                   f"- derived: $ {_latex(rel.derived)} $\n"
                   f"- printed: $ {_latex(rel.printed)} $\n"
                   f"- derived - printed: $ {_latex(diff)} $\n"
                   f"- at {subs}: derived = {dv}, printed = {pv}\n\n")
    return "".join(out)


def counterexample(rel: Relation) -> dict[sp.Symbol, sp.Rational]:
    """A fixed, simple point of the domain where a printed form is evaluated (1/2, 2/3, ...)."""
    dom = rel.domain or {}
    symbols = sorted(rel.derived.subs(dom).free_symbols | rel.printed.subs(dom).free_symbols,
                     key=lambda s: s.name)
    return {s: sp.Rational(1, k + 2) if s.name.startswith("nu") else sp.Rational(k + 2, k + 3)
            for k, s in enumerate(symbols)}
