"""The record every derivation returns, and the discovery of the family modules."""

from __future__ import annotations

import importlib
import os
import pkgutil
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from functools import cache

import sympy as sp

from hertzmdr.derive import _cache


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


def _family_relations(fam: str) -> tuple[list[Relation], float]:
    """The family's relations and the CPU seconds they took in this process."""
    start = time.process_time()
    module = importlib.import_module(f"hertzmdr.derive.{fam}")
    return list(module.relations()), time.process_time() - start


def _jobs() -> int:
    value = os.environ.get("HERTZMDR_DERIVE_JOBS", "")
    if not value:
        return os.cpu_count() or 1
    if not value.isdigit() or int(value) < 1:
        raise ValueError(f"HERTZMDR_DERIVE_JOBS={value!r}: give a whole number of processes, "
                         "at least 1")
    return int(value)


def _derive_all() -> tuple[Relation, ...]:
    families = family_modules()
    jobs = _jobs()
    if jobs > 1 and len(families) > 1:
        # the families that took longest last time start first (else the larger sources):
        # with one process per core, a long family started last would run alone at the end
        seen = _cache.read_timings()
        order = sorted(families, key=lambda fam: -seen.get(fam, _source_size(fam) / 1e4))
        with ProcessPoolExecutor(max_workers=min(jobs, len(families))) as pool:
            futures = {fam: pool.submit(_family_relations, fam) for fam in order}
            derived = {fam: futures[fam].result() for fam in families}
    else:
        derived = {fam: _family_relations(fam) for fam in families}
    _cache.write_timings({fam: round(sec, 2) for fam, (_, sec) in derived.items()})
    out: dict[str, Relation] = {}
    for fam in families:
        for rel in derived[fam][0]:
            rel = Relation(**{**rel.__dict__, "family": fam})
            rel.check()
            if rel.name in out:
                first = out[rel.name].family
                raise ValueError(f"relation name {rel.name} defined twice ({first}, {fam})")
            out[rel.name] = rel
    return tuple(out[k] for k in sorted(out))


def _source_size(fam: str) -> int:
    module = importlib.import_module(f"hertzmdr.derive.{fam}")
    return os.path.getsize(module.__file__)


#: where the last :func:`all_relations` of this process came from: "cache" or "derived..."
SOURCE: list[str] = []


@cache
def all_relations() -> tuple[Relation, ...]:
    """Every relation of every family, sorted by name; names must be unique.

    The families are derived in parallel processes (one per core; HERTZMDR_DERIVE_JOBS=1 for a
    single process), and the result is cached for the life of the process and on disk, keyed by
    the derive package's sources and SymPy's version (:mod:`hertzmdr.derive._cache`;
    HERTZMDR_DERIVE_CACHE=0 derives afresh).
    """
    relations, how = _cache.cached(_derive_all)
    SOURCE[:] = [how]
    return relations
