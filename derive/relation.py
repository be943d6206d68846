"""The record every derivation returns, and the discovery of the family modules."""

from __future__ import annotations

import importlib
import os
import pkgutil
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from functools import cache

import sympy as sp


@dataclass(frozen=True)
class Relation:
    """One derived relation, ready to be printed as a NumPy function.

    Parameters
    ----------
    name
        Name of the generated function in ``numeric/_generated.py``.
    equation
        Where the chapter states it: ``"(5.23)"``, ``"Problem 3"``, ``"(5.24), inverted"``.
    derived
        The expression as the derivation produced it.
    args
        Its arguments, in call order. Every symbol of ``derived`` must be among them.
    summary
        One line: what the function returns, with its SI unit, e.g. ``"normal force F [N]"``.
    origin
        One line: the starting point of the derivation, e.g. ``"integral of (5.15) over the disc"``.
    verified_by
        The test (``path::name``) that checks it by an independent route.
    printed
        The chapter's form as printed, when it prints one; compared with ``derived`` by the tests.
    erratum
        Set when ``derived`` and ``printed`` differ: what is wrong in the print.
    stable
        The form to print into code when ``derived`` loses accuracy in floating point; a test
        proves ``stable == derived`` symbolically and at 50 digits.
    stable_why
        Why ``stable`` is preferred.
    domain
        A substitution that writes the relation's domain into SymPy's assumptions for the
        proofs (printed == derived, stable == derived), e.g. ``{r: a/t}`` outside the contact.
        New symbols in it must be named ``t`` or ``t_<something>`` and range over (0, 1).
    """

    name: str
    equation: str
    derived: sp.Expr
    args: tuple[sp.Symbol, ...]
    summary: str
    origin: str
    verified_by: str
    printed: sp.Expr | None = None
    erratum: str | None = None
    stable: sp.Expr | None = None
    stable_why: str | None = None
    domain: dict | None = None
    family: str = field(default="", compare=False)

    @property
    def expr(self) -> sp.Expr:
        """The expression printed into the generated module."""
        return self.derived if self.stable is None else self.stable

    def check(self) -> None:
        """Raise ValueError if the record is inconsistent."""
        if not self.name.isidentifier():
            raise ValueError(f"relation name {self.name!r} is not a Python identifier")
        missing = self.expr.free_symbols - set(self.args)
        if missing:
            names = sorted(map(str, missing))
            raise ValueError(f"relation {self.name}: symbols {names} not in args")
        if (self.printed is None) and self.erratum:
            raise ValueError(f"relation {self.name}: an erratum needs the printed form")
        if (self.stable is None) != (self.stable_why is None):
            raise ValueError(f"relation {self.name}: give stable and stable_why together")
        if "::" not in self.verified_by:
            raise ValueError(f"relation {self.name}: verified_by must name a test as path::name")


def family_modules() -> list[str]:
    """Names of the modules of ``hertzmdr.derive`` that define ``relations()``, sorted."""
    import hertzmdr.derive as pkg

    names = []
    for info in sorted(pkgutil.iter_modules(pkg.__path__), key=lambda m: m.name):
        if info.name.startswith("_") or info.name in ("relation", "codegen", "symbols"):
            continue
        module = importlib.import_module(f"hertzmdr.derive.{info.name}")
        if hasattr(module, "relations"):
            names.append(info.name)
    return names


def _family_relations(fam: str) -> list[Relation]:
    module = importlib.import_module(f"hertzmdr.derive.{fam}")
    return list(module.relations())


@cache
def all_relations() -> tuple[Relation, ...]:
    """Every relation of every family, sorted by name; names must be unique.

    The families are derived in parallel processes (one per core; HERTZMDR_DERIVE_JOBS=1 for a
    single process), and the result is cached for the life of the process.
    """
    families = family_modules()
    jobs = int(os.environ.get("HERTZMDR_DERIVE_JOBS", os.cpu_count() or 1))
    if jobs > 1 and len(families) > 1:
        with ProcessPoolExecutor(max_workers=min(jobs, len(families))) as pool:
            derived = list(pool.map(_family_relations, families))
    else:
        derived = [_family_relations(fam) for fam in families]
    out: dict[str, Relation] = {}
    for fam, rels in zip(families, derived, strict=True):
        for rel in rels:
            rel = Relation(**{**rel.__dict__, "family": fam})
            rel.check()
            if rel.name in out:
                first = out[rel.name].family
                raise ValueError(f"relation name {rel.name} defined twice ({first}, {fam})")
            out[rel.name] = rel
    return tuple(out[k] for k in sorted(out))
