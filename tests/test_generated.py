"""The generated module is fresh, deterministic, and importing the runtime never loads SymPy."""

import difflib
import os
import random
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from hertzmdr.derive.__main__ import ROOT

from oracle import FULL

# `make test` runs this file on one worker (GROUPED, tests/conftest.py): one module fixture

#: the files ``python -m hertzmdr.derive`` writes, relative to the source tree
GENERATED = ["numeric/_generated.py", "numeric/_generated_mp.py", "docs/derivations.md",
             "docs/errata.md", "numeric/c/hertzmdr_laws.h", "docs/c_laws_reference.md"]


def test_generated_files_are_fresh(regenerated, monkeypatch, capsys):
    """`python -m hertzmdr.derive --check`: its entry point in this process, on the texts that
    ``targets()`` printed in the fresh process of ``regenerated`` (the printers are run once in
    this file, not once here and again there: ~8 s of CPU each). It exits 0 on the committed
    files, and 1 with the diff and the advice when one file is stale. The committed files were
    printed by an earlier run, so passing also shows the output is byte-identical on a re-run
    (and, the fixture's hash seed being drawn per run, under another hash seed each run)."""
    from hertzmdr.derive import __main__ as cli

    out, _ = regenerated
    texts = {ROOT / name: (out / name).read_text() for name in GENERATED}
    monkeypatch.setattr(cli, "targets", lambda: dict(texts))
    rc = cli.main(["--check"])
    res = capsys.readouterr()
    assert rc == 0, res.out[-3000:] + res.err
    # the same check fails on one stale file, names it and shows the changed line
    name = "docs/errata.md"
    monkeypatch.setattr(cli, "targets", lambda: {**texts, ROOT / name: texts[ROOT / name]
                                                 + "a line the committed file lacks\n"})
    rc = cli.main(["--check"])
    res = capsys.readouterr()
    assert rc == 1
    assert f"{name} (regenerated)" in res.out and "+a line the committed file lacks" in res.out
    assert "1 generated file(s) stale" in res.err


def stale(committed: Path, regenerated: Path) -> dict[str, str]:
    """{file: unified diff} for every generated file whose text under ``committed`` differs
    from the one under ``regenerated`` (both laid out like the source tree)."""
    out = {}
    for name in GENERATED:
        old = (committed / name).read_text() if (committed / name).exists() else ""
        new = (regenerated / name).read_text()
        if old != new:
            out[name] = "".join(difflib.unified_diff(
                old.splitlines(keepends=True), new.splitlines(keepends=True),
                f"{name} (committed)", f"{name} (regenerated)", n=1))
    return out


@pytest.fixture(scope="module")
def regenerated(tmp_path_factory):
    """Every generated file printed by a fresh interpreter into a temporary directory, with a
    hash seed other than this process's (set and dict orders that leak into the output would
    differ), through the same ``targets()`` that ``python -m hertzmdr.derive`` writes. The seed
    is drawn per run (as this process's own is, unless PYTHONHASHSEED is set), so that the runs
    together try many; it is named in every failure. Returns (folder, seed)."""
    out = tmp_path_factory.mktemp("regenerated")
    code = ("import sys; from pathlib import Path; "
            "from hertzmdr.derive.__main__ import ROOT, targets; out = Path(sys.argv[1])\n"
            "for path, text in targets().items():\n"
            "    dest = out / path.relative_to(ROOT)\n"
            "    dest.parent.mkdir(parents=True, exist_ok=True)\n"
            "    dest.write_text(text)\n")
    seed = str(random.SystemRandom().randrange(1, 2**32))
    if seed == os.environ.get("PYTHONHASHSEED"):
        seed = str(int(seed) % (2**32 - 1) + 1)
    # With HERTZMDR_SWEEP=full the cache of derived relations is off: this process derives
    # every relation afresh under another hash seed (the derivation's own determinism, ~2 min
    # of CPU). Otherwise it reads the cache (keyed by the derive sources), so that the printers
    # run under another seed; in a fresh clone (no cache yet) it derives them and writes the
    # cache, which this process's tests then read: that a derivation prints the committed
    # files is checked there, once
    cache = "0" if FULL else "1"
    subprocess.run([sys.executable, "-c", code, str(out)], check=True,
                   env={**os.environ, "PYTHONHASHSEED": seed, "HERTZMDR_DERIVE_CACHE": cache})
    assert sorted(str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()) \
        == sorted(GENERATED), "the generator writes exactly the files listed here"
    return out, seed


def test_regenerated_in_a_fresh_process_matches_the_committed_files(regenerated):
    """Deterministic across processes and hash seeds, and fresh: a subprocess prints exactly
    the committed text."""
    out, seed = regenerated
    diffs = stale(ROOT, out)
    assert not diffs, (f"stale or non-deterministic output (PYTHONHASHSEED={seed}):\n"
                       + "\n".join(diffs.values())[:3000])


def test_the_staleness_check_fails_on_an_edited_file(regenerated, tmp_path):
    """The comparison above can fail: a copy of the committed files with one number of the
    generated module changed is reported stale, that file only, with the change in its diff."""
    regenerated, _ = regenerated
    for name in GENERATED:
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / name, tmp_path / name)
    assert not stale(tmp_path, regenerated)
    path = tmp_path / "numeric" / "_generated.py"
    text = path.read_text()
    i = next(k for k, ch in enumerate(text) if ch.isdigit() and text[k - 1] == " "
             and k > text.index("def "))
    edited = text[:i] + str((int(text[i]) + 1) % 10) + text[i + 1:]
    path.write_text(edited)
    diffs = stale(tmp_path, regenerated)
    assert list(diffs) == ["numeric/_generated.py"]
    assert edited.splitlines()[text[:i].count("\n")] in diffs["numeric/_generated.py"]


def test_numeric_does_not_import_sympy():
    code = ("import sys, hertzmdr.numeric, hertzmdr.numeric.hertz, hertzmdr.numeric._generated,"
            " hertzmdr.numeric._generated_mp, hertzmdr.numeric.scene, hertzmdr.numeric.cli;"
            "bad = [m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules];"
            "print(','.join(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"imported at import time: {out.stdout.strip()}"


def test_every_generated_function_cites_its_test():
    from hertzmdr.derive import all_relations

    for rel in all_relations():
        path, name = rel.verified_by.split("::")
        text = (Path(__file__).parents[1] / path).read_text()
        assert f"def {name}(" in text, f"{rel.name}: no test {rel.verified_by}"


def test_mpmath_print_agrees_with_numpy_print():
    """The two printers of one expression agree (printer consistency, not a physics check):
    at points inside each relation's domain the float64 value is within 1e-13 of the 50-digit
    one (a handful of roundings, or the stated conditioning of a stable form)."""
    import math
    import random
    import zlib

    import mpmath as mp

    from hertzmdr.derive import all_relations
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp

    for rel in all_relations():
        # a seed per relation: adding a relation moves no other relation's points
        rng = random.Random(zlib.crc32(rel.name.encode()))
        for _ in range(3):
            args = {}
            for s in rel.args:
                if s.name.startswith("nu"):
                    args[s.name] = rng.uniform(0.05, 0.45)
                elif s.name == "theta":  # the cone's angle with the plane, (5.38)
                    args[s.name] = rng.uniform(0.05, 1.5)
                elif s.name in ("eta", "chi"):  # cos and sin of the spheroidal angle
                    args[s.name] = rng.uniform(0.05, 0.95)
                else:
                    args[s.name] = rng.uniform(0.5, 3.0)
            if rel.domain:  # e.g. r = a/t: evaluate where the relation is stated
                continue_outer = False
                t_vals = {}  # one value per unit-interval symbol, shared by the items
                for sym, expr in rel.domain.items():
                    for t in sorted(expr.free_symbols, key=lambda s: s.name):
                        if (t.name == "t" or t.name.startswith("t_")) and t not in t_vals:
                            t_vals[t] = rng.uniform(0.05, 0.95)
                    val = expr.subs({**{k: args[k.name] for k in expr.free_symbols
                                        if k.name in args}, **t_vals})
                    if val.free_symbols:
                        continue_outer = True
                        break
                    args[sym.name] = float(val)
                if continue_outer:
                    continue
            f64 = float(getattr(gen, rel.name)(**args))
            with mp.workdps(50):
                ref = getattr(gen_mp, rel.name)(**{k: mp.mpf(v) for k, v in args.items()})
                assert math.isfinite(f64)
                assert abs(f64 - ref) <= 1e-13 * abs(ref) + 1e-300, (rel.name, args)
