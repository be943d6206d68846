"""What every benchmark script shares: its command line (``--quick``, ``--out DIR``), where it
writes, the timing budget, and how a peer library that is not installed is skipped.

Without ``--out`` a script writes its report (Markdown, figures) into ``docs/`` and its
measurements (JSON) into ``benchmarks/results/``, and reads the other scripts' measurements
from there. With ``--out DIR`` everything goes into DIR and is read from DIR: the tests run
every script with ``--quick --out tmp_path`` and never touch ``docs/``.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import dataclass
from importlib import import_module, metadata
from pathlib import Path
from types import ModuleType

from hertzmdr.numeric import _timing
from hertzmdr.numeric._timing import Budget

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
RESULTS = Path(__file__).resolve().parent / "results"


@dataclass(frozen=True)
class Run:
    """Where one run of a script writes and reads, and how much it measures."""

    quick: bool
    docs: Path  # the report: .md and figures
    results: Path  # the measurements: .json, this script's and the ones it reads
    budget: Budget


def parser(doc: str) -> argparse.ArgumentParser:
    """The command line every script accepts; a script adds its own options to it."""
    ap = argparse.ArgumentParser(description=doc.strip().splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="few points, few repeats: checks that the script runs and writes "
                         "finite numbers (the tests run this), not a measurement")
    ap.add_argument("--out", type=Path, metavar="DIR",
                    help="write the report and the measurements into DIR and read the other "
                         "scripts' measurements from there (default: docs/ and "
                         "benchmarks/results/)")
    return ap


def run_from(args: argparse.Namespace) -> Run:
    budget = _timing.QUICK if args.quick else _timing.FULL
    if args.out is None:
        return Run(args.quick, DOCS, RESULTS, budget)
    args.out.mkdir(parents=True, exist_ok=True)
    return Run(args.quick, args.out, args.out, budget)


def peer(module: str, dist: str, what: str) -> ModuleType | None:
    """Import a peer library, or say in one line that its rows are skipped and return None."""
    try:
        return import_module(module)
    except ImportError as exc:
        print(f"{dist} not installed ({exc}): {what} skipped "
              "(`pip install -e .[bench]` or `make benchmark` installs it)", flush=True)
        return None


def version(dist: str) -> str:
    """The installed version of a distribution (peers' own __version__ is not always one)."""
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "not installed"


def seconds(s: float) -> str:
    """A time [s] with its prefix, to 3 significant digits (``2.61 ms``), for the reports."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if s >= scale:
            return f"{s / scale:.3g} {unit}"
    return f"{s * 1e9:.3g} ns"


def cpu_compare(ways, number: int, rounds: int) -> dict[str, _timing.Timing]:
    """Each way's CPU time per call (``time.process_time``: this process's, so that the turns
    of other processes on a shared machine do not count), ``rounds`` interleaved rounds of
    ``number`` calls; ``first``: its first call."""
    first = {}
    for name, fn in ways.items():
        t0 = time.process_time()
        fn()
        first[name] = time.process_time() - t0
    per = {name: [] for name in ways}
    for _ in range(rounds):
        for name, fn in ways.items():
            t0 = time.process_time()
            for _ in range(number):
                fn()
            per[name].append((time.process_time() - t0) / number)
    return {name: _timing.Timing(first[name], tuple(per[name]), number) for name in ways}
