"""``python -m hertzmdr.derive [--check]``: write, or check, the generated files."""

from __future__ import annotations

import argparse
import difflib
import os
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from hertzmdr.derive.c_codegen import HEADER, REFERENCE, render_header, render_reference
from hertzmdr.derive.codegen import render_derivations, render_errata, render_module
from hertzmdr.derive.relation import SOURCE, _jobs, all_relations

ROOT = Path(__file__).resolve().parents[1]

parser = argparse.ArgumentParser(
    prog="python -m hertzmdr.derive",
    description="Derive the chapter's relations with SymPy and print them into "
    "numeric/_generated.py (NumPy), numeric/_generated_mp.py (mpmath), docs/derivations.md, "
    "docs/errata.md, the C header numeric/c/hertzmdr_laws.h and docs/c_laws_reference.md.",
)
parser.add_argument("--check", action="store_true",
                    help="write nothing; exit 1 with a diff if a generated file is stale")
parser.add_argument("--no-cache", action="store_true",
                    help="derive every relation afresh, without reading the cache of derived "
                    "relations (the cache is keyed by the derive sources and SymPy's version; "
                    "same as HERTZMDR_DERIVE_CACHE=refresh)")


def targets() -> dict[Path, str]:
    """{path: text} of every generated file. The printers run in parallel processes, one per
    core (HERTZMDR_DERIVE_JOBS), the two modules first: they take longest."""
    relations = all_relations()
    jobs = [
        (ROOT / "numeric" / "_generated.py", render_module, ()),
        (ROOT / "numeric" / "_generated_mp.py", render_module, ("mpmath",)),
        (ROOT / "docs" / "errata.md", render_errata, ()),
        (ROOT / "docs" / "derivations.md", render_derivations, ()),
        (ROOT / HEADER, render_header, ()),  # the contact laws for DEM codes, C99
        (ROOT / REFERENCE, render_reference, ()),
    ]
    if _jobs() == 1:
        return {path: fn(relations, *extra) for path, fn, extra in jobs}
    with ProcessPoolExecutor(max_workers=_jobs()) as pool:
        futures = {path: pool.submit(fn, relations, *extra) for path, fn, extra in jobs}
        return {path: futures[path].result() for path, _, _ in jobs}


def main(argv: list[str] | None = None) -> int:
    args = parser.parse_args(argv)
    if not (ROOT / "numeric").is_dir() or not (ROOT / "docs").is_dir():
        print(f"{ROOT} is not a source checkout (no numeric/ and docs/ beside derive/)",
              file=sys.stderr)
        return 2
    if args.no_cache:
        os.environ["HERTZMDR_DERIVE_CACHE"] = "refresh"
    try:
        texts = targets()
    except ValueError as exc:  # a bad HERTZMDR_DERIVE_JOBS or HERTZMDR_DERIVE_CACHE
        if not str(exc).startswith("HERTZMDR_"):
            raise
        print(f"python -m hertzmdr.derive: {exc}", file=sys.stderr)
        return 2
    print(f"relations: {SOURCE[0] if SOURCE else 'derived'}", file=sys.stderr)
    stale = 0
    for path, text in texts.items():
        old = path.read_text() if path.exists() else ""
        if old == text:
            continue
        rel = path.relative_to(ROOT)
        if args.check:
            stale += 1
            sys.stdout.writelines(difflib.unified_diff(
                old.splitlines(keepends=True), text.splitlines(keepends=True),
                f"{rel} (committed)", f"{rel} (regenerated)", n=2))
        else:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
            print(f"wrote {rel}")
    if stale:
        print(f"\n{stale} generated file(s) stale: run `python -m hertzmdr.derive` "
              "(make generate) and commit the result.", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
