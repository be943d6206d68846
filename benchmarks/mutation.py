"""Mutation testing of numeric/ with mutmut, one module at a time; writes docs/mutation.md.

Run: ``make mutation`` (every module of MODULES with its own test files), or for other modules

    .venv/bin/python benchmarks/mutation.py --module scene --tests tests/test_scenes.py \
        --out docs/mutation_scene.md

``--module`` takes paths relative to numeric/ (a file, or a folder for all the files in it, or
several joined by commas, mutated in one run with one set of tests); each ``--module`` is run
with the ``--tests`` given after it (or MODULES' test files).

mutmut 3 copies the sources to ``mutants/`` and runs the tests there, choosing a mutant by the
module's import name. numeric/ installs as ``hertzmdr.numeric`` (package-dir), so every module
runs in a scratch folder ``build/mutation/<module>/`` that lays the sources out under that name
(``hertzmdr/numeric`` -> numeric/, a link) beside ``tests``, ``examples`` and ``docs`` (links,
copied into ``mutants/``: the scene tests read the example scenes and docs/scenes.md), with the
repository's pyproject.toml whose ``[tool.mutmut]`` (the shared settings) gets this module's
``only_mutate`` and test files. mutmut runs the tests that reach a function with ``-x`` for
each of its mutants, one worker, under ``nice -n 19``.

Each surviving mutant is printed with its line; a note for it comes from
benchmarks/mutation_notes.toml (why it cannot be killed), matched by module, original line and
mutated line. A survivor without a note is listed as *unexplained*: that is the list to work
on (add a test by an independent route, or a note).
"""

from __future__ import annotations

import argparse
import ast
import datetime
import json
import os
import re
import shutil
import subprocess
import sys
import time
import tomllib
from dataclasses import asdict, dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NUMERIC = ROOT / "numeric"
NOTES = ROOT / "benchmarks" / "mutation_notes.toml"
#: the notes on numeric/scene/ (a file of their own: the scene layer's runs are separate)
SCENE_NOTES = ROOT / "benchmarks" / "mutation_notes_scene.toml"
#: folders besides tests/ that the tests read (the example scenes, docs/scenes.md)
EXTRA = ("examples", "docs")
PACKAGE = "hertzmdr/numeric"  # the import path of numeric/ (see [tool.setuptools.package-dir])

# the stable closed-form modules, most physics first, each with the test files written for it
MODULES: dict[str, list[str]] = {
    "hertz.py": ["tests/test_hertz.py"],
    "cone.py": ["tests/test_cone.py"],
    "powerlaw.py": ["tests/test_powerlaw.py"],
    "line.py": ["tests/test_line.py"],
    "bodies.py": ["tests/test_bodies.py"],
    "ellipse.py": ["tests/test_ellipse.py"],
    "stress.py": ["tests/test_stress.py"],
    "impact.py": ["tests/test_impact.py"],
    "motion.py": ["tests/test_impact.py"],
    "bem.py": ["tests/test_bem.py"],
    "_validate.py": ["tests/test_validate.py"],
    "_quadrature.py": ["tests/test_quadrature.py"],
}

STATUS = {1: "killed", 3: "killed", 0: "survived", 5: "no tests", 33: "no tests",
          34: "skipped", 36: "timeout", 24: "timeout", -24: "timeout", 152: "timeout",
          255: "timeout", None: "not checked"}
COLUMNS = ["killed", "survived", "no tests", "timeout"]


@dataclass
class Survivor:
    name: str
    status: str
    line: int
    original: str
    mutant: str
    note: str | None = None


@dataclass
class Run:
    module: str
    tests: list[str]
    command: str
    seconds: float
    date: str = ""
    counts: dict[str, int] = field(default_factory=dict)
    survivors: list[Survivor] = field(default_factory=list)


def mutmut_config(module: str, tests: list[str]) -> dict:
    """The repository's [tool.mutmut] settings with this module's scope."""
    shared = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"].get("mutmut", {})
    targets = [f"{PACKAGE}/{m}".rstrip("/") for m in module.split(",")]
    only = [t if t.endswith(".py") else t + "/*" for t in targets]
    return {**shared, "source_paths": [PACKAGE], "only_mutate": only, "also_copy": list(EXTRA),
            "pytest_add_cli_args_test_selection": list(tests)}


def workdir(module: str) -> str:
    """The scratch folder's name of a --module (``scene/kinds`` -> ``scene_kinds``)."""
    return module.replace("/", "_").replace(",", "+").replace(".py", "")


def scratch(module: str, tests: list[str], base: Path) -> Path:
    """A fresh scratch folder laying out numeric/ as hertzmdr/numeric for mutmut."""
    work = base / workdir(module)
    shutil.rmtree(work, ignore_errors=True)
    (work / "hertzmdr").mkdir(parents=True)
    (work / PACKAGE).symlink_to(NUMERIC, target_is_directory=True)
    for folder in ("tests", *EXTRA):
        (work / folder).symlink_to(ROOT / folder, target_is_directory=True)
    text = (ROOT / "pyproject.toml").read_text()
    text = re.sub(r"(?ms)^\[tool\.mutmut\]\n.*?(?=^\[|\Z)", "", text)  # replaced below
    cfg = mutmut_config(module, tests)
    text += "\n[tool.mutmut]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in cfg.items())
    (work / "pyproject.toml").write_text(text)
    return work


def function_lines(path: Path) -> dict[str, int]:
    """First line (decorators included) of each function, by mutmut's mangled name."""
    out = {}
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef):
                    first = min([item.lineno] + [d.lineno for d in item.decorator_list])
                    out[f"x\u01c1{node.name}\u01c1{item.name}"] = first
    for item in tree.body:
        if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef):
            out[f"x_{item.name}"] = min([item.lineno] + [d.lineno for d in item.decorator_list])
    return out


def load_notes(kind: str = "equivalent") -> list[dict]:
    """The notes of benchmarks/mutation_notes.toml and mutation_notes_scene.toml: "equivalent"
    (survivors that cannot be killed, with the reason), "since" (survivors of a module's last
    run killed by a test added after it), "text" (a line whose text-only mutants are
    presentation), "killed" (survivors of earlier runs and the tests added) or "finding"
    (defects seen while writing those tests)."""
    return [n for path in (NOTES, SCENE_NOTES) if path.exists()
            for n in tomllib.loads(path.read_text()).get(kind, [])]


def text_only(s: Survivor) -> bool:
    """Whether a mutant changes only the text inside string literals: wrapped in XX, or its
    case changed (mutmut's string mutations other than None)."""
    return (squash(s.mutant) != squash(s.original)
            and squash(s.mutant).replace("XX", "").lower() == squash(s.original).lower())


def squash(s: str) -> str:
    return " ".join(s.split())


def find_note(module: str, s: Survivor, notes: list[dict]) -> str | None:
    """The reason a survivor cannot be killed, or the test added since its run that kills it
    ("since" notes, for a module not run again since the test was added)."""
    # a test added since the run, checked to kill the mutant, first: it is a fact about this
    # mutant, where a reason may be written for a whole line
    for n in [{**k, "reason": f"killed since this run by {k['test']} (added after it)"}
              for k in load_notes("since")] + notes:
        if (n["module"] == module and squash(n["original"]) in squash(s.original)
                and squash(n["mutant"]) in squash(s.mutant)):
            return n["reason"]
    # "text" notes: every mutant of the line that only changes the text of a string (a method
    # text, a label): presentation, with the reason
    for n in load_notes("text"):
        if n["module"] == module and squash(n["original"]) in squash(s.original) and text_only(s):
            return n["reason"]
    return None


def survivors_of(work: Path, module: str, notes: list[dict]) -> tuple[dict, list[Survivor]]:
    """Counts by status and the survivors, read from mutmut's files in ``work``."""
    from mutmut.configuration import reset_config
    from mutmut.mutation.diff_apply import get_diff_for_mutant

    counts = {c: 0 for c in COLUMNS}
    counts["mutants"] = 0
    found: list[Survivor] = []
    here = os.getcwd()
    os.chdir(work)
    reset_config()
    try:
        for meta in sorted(Path("mutants").rglob("*.py.meta")):
            source = Path(str(meta.relative_to("mutants"))[: -len(".meta")])
            starts = function_lines(NUMERIC / source.relative_to(PACKAGE))
            codes = json.loads(meta.read_text())["exit_code_by_key"]
            for name, code in codes.items():
                status = STATUS.get(code, "suspicious")
                counts["mutants"] += 1
                counts[status] = counts.get(status, 0) + 1
                if status not in ("survived", "no tests", "suspicious", "timeout"):
                    continue
                diff = get_diff_for_mutant(name, path=source).splitlines()
                hunk = next(x for x in diff if x.startswith("@@"))
                offset = int(hunk.split()[1].split(",")[0].lstrip("-"))
                body = [x for x in diff[diff.index(hunk) + 1:] if not x.startswith("@@")]
                minus = [i for i, x in enumerate(body) if x.startswith("-")]
                lineno = starts[name.rpartition(".")[2].partition("__mutmut_")[0]]
                first = minus[0] if minus else 0
                skipped = sum(1 for x in body[:first] if x.startswith("+"))
                s = Survivor(name, status, lineno + offset - 1 + first - skipped,
                             " / ".join(x[1:].strip() for x in body if x.startswith("-")),
                             " / ".join(x[1:].strip() for x in body if x.startswith("+")))
                s.note = find_note(module, s, notes)
                found.append(s)
    finally:
        os.chdir(here)
    return counts, sorted(found, key=lambda s: (source_file(s.name), s.line))


def run_module(module: str, tests: list[str], base: Path, notes: list[dict]) -> Run:
    work = scratch(module, tests, base)
    mutmut = str(Path(sys.executable).with_name("mutmut"))
    cmd = ["nice", "-n", "19", mutmut, "run", "--max-children", "1"]
    t = time.perf_counter()
    with open(work / "run.log", "w") as log:
        proc = subprocess.run(cmd, cwd=work, stdout=log, stderr=subprocess.STDOUT,
                              env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})
    seconds = time.perf_counter() - t
    if proc.returncode != 0:
        tail = (work / "run.log").read_text()[-2000:]
        raise SystemExit(f"mutmut failed on {module} (exit {proc.returncode}):\n{tail}")
    counts, survivors = survivors_of(work, module, notes)
    again = " ".join(["benchmarks/mutation.py", "--module", module, "--tests", *tests])
    date = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    run = Run(module, tests, again, seconds, date, counts, survivors)
    (work / "result.json").write_text(json.dumps(asdict(run), indent=1))
    return run


def load_run(module: str, tests: list[str], base: Path, notes: list[dict]) -> Run | None:
    """The result of an earlier run of ``module`` (``--report-only``), its notes read anew;
    None if there is none with these test files."""
    work = base / workdir(module)
    path = work / "result.json"
    if not path.exists():
        if not (work / "mutants").is_dir():
            return None
        # a run stopped before its end: what it checked, the rest counted as not checked
        cfg = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
        if cfg["pytest_add_cli_args_test_selection"] != list(tests):
            return None
        counts, survivors = survivors_of(work, module, notes)
        stopped = datetime.datetime.fromtimestamp((work / "run.log").stat().st_mtime,
                                                  datetime.UTC)
        again = " ".join(["benchmarks/mutation.py", "--module", module, "--tests", *tests])
        # the time it ran: from the scratch folder's pyproject.toml (written at its start) to
        # the last line of its log
        ran = (work / "run.log").stat().st_mtime - (work / "pyproject.toml").stat().st_mtime
        return Run(module, list(tests), again, ran,
                   stopped.strftime("%Y-%m-%d %H:%M UTC") + " (stopped before the end)",
                   counts, survivors)
    data = json.loads(path.read_text())
    if data["tests"] != list(tests):
        return None
    run = Run(**{**data, "survivors": [Survivor(**x) for x in data["survivors"]]})
    for s in run.survivors:
        s.note = find_note(module, s, notes)
    return run


def source_file(mutant: str) -> str:
    """The file of a mutant under numeric/ (``scene/kinds/axisym.py``), from its name
    (``hertzmdr.numeric.scene.kinds.axisym.xǁClassǁmethod__mutmut_3``): for a folder's run."""
    dotted = re.split(r"\.x[\u01c1_]", mutant)[0].removeprefix(PACKAGE.replace("/", ".") + ".")
    path = dotted.replace(".", "/")
    return path + ("/__init__.py" if (NUMERIC / path).is_dir() else ".py")


def report(runs: list[Run], argv: list[str], total: float, assembled: bool = False) -> str:
    import mutmut

    columns = COLUMNS + (["not checked"] if any(r.counts.get("not checked") for r in runs)
                         else [])
    lines = [
        "# Mutation testing of numeric/" + ("scene/" if runs and all(
            r.module.startswith("scene") for r in runs) else ""),
        "",
        f"Made by `{' '.join(['python', 'benchmarks/mutation.py', *argv])}`"
        + (" (or `make mutation`)" if all(r.module in MODULES for r in runs) else "")
        + f" with mutmut {mutmut.__version__}: {total / 60:.1f} min of "
        + ("complete " if any(not r.seconds for r in runs) else "")
        + "runs on a shared 2-core machine (each module's date below"
        + ("; this page was assembled by `--report-only` from the last run of each module, "
           "each made with the tests of that date)." if assembled else ")."),
        "Each module is mutated alone and tested with its own test files only (a mutant killed "
        "elsewhere in the suite counts as a survivor here). For each mutant, mutmut runs the tests "
        "of those files that reach the mutated function, with `-x`; the command below runs in "
        "the scratch folder that `benchmarks/mutation.py` lays out (see its docstring).",
        *(["*not checked*: the run was stopped before its end. mutmut checks first the mutants "
           "whose tests take least time, so those left are in the functions that most tests, "
           "or the slowest ones, reach.", ""]
          if any(r.counts.get("not checked") for r in runs) else []),
        "*no tests*: no test of those files calls the function. Generated modules "
        "(`_generated*.py`) are not mutated: they are checked against the derivations by "
        "`tests/test_generated.py` and by the mpmath oracles.",
        "",
        "| module | test files | mutants | " + " | ".join(columns) + " | time | run on |",
        "|---|---|---:|" + "---:|" * len(columns) + "---:|---|",
    ]
    for r in runs:
        cells = [str(r.counts.get(c, 0)) for c in ["mutants", *columns]]
        tests = ", ".join(f"`{Path(t).name}`" for t in r.tests)
        lines.append(f"| `{r.module}` | {tests} | " + " | ".join(cells)
                     + f" | {f'{r.seconds:.0f} s' if r.seconds else '-'} | {r.date} |")
    lines += ["", "Each module again alone (its report only, hence `--out`):", ""]
    lines += [f"- `.venv/bin/python {r.command} --out /tmp/mutation.md`" for r in runs]
    lines += ["", "Each runs `nice -n 19 mutmut run --max-children 1` in "
              "`build/mutation/<module>/`.", ""]
    lines += ["## Survivors", ""]
    any_left = False
    for r in runs:
        if not r.survivors:
            continue
        any_left = True
        lines += [f"### `{r.module}`", ""]
        for s in r.survivors:
            why = s.note if s.note else "**unexplained**"
            one_file = r.module.endswith(".py") and "," not in r.module
            where = "" if one_file else f"`{source_file(s.name)}` "
            lines.append(f"- {where}line {s.line} ({s.status}): `{s.original}` → `{s.mutant}`:"
                         f" {why}")
        lines.append("")
    if not any_left:
        lines += ["None: every mutant was killed.", ""]
    modules = {r.module for r in runs}
    found = [f for f in load_notes("finding") if f["module"] in modules]
    if found:
        lines += ["## Defects found on the way (not fixed here: their modules are being changed "
                  "on other branches)", ""]
        lines += [f"- `{f['module']}`: {f['text']}" for f in found]
        lines.append("")
    killed = [k for k in load_notes("killed") if k["module"] in modules]
    if killed:
        lines += ["## Survivors of earlier runs, killed by the tests added for them", "",
                  "| module | the mutants | killed by |", "|---|---|---|"]
        lines += [f"| `{k['module']}` | {k['mutants']} | {k['tests']} |" for k in killed]
        lines.append("")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--module", action="append", default=[],
                    help="path under numeric/ (file or folder), or several joined by commas "
                    "(mutated in one run); repeatable")
    ap.add_argument("--tests", action="append", nargs="+", default=[],
                    help="test files for the --module before it")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "mutation.md")
    ap.add_argument("--work", type=Path, default=ROOT / "build" / "mutation")
    ap.add_argument("--report-only", action="store_true",
                    help="write the report from the last run of each module (in --work)")
    args = ap.parse_args(argv)
    if args.tests and len(args.tests) != len(args.module):
        ap.error("give one --tests list after each --module")
    if args.module:
        jobs = [(m, args.tests[i] if args.tests else MODULES[m])
                for i, m in enumerate(args.module)]
    else:
        jobs = list(MODULES.items())
    for m, tests in jobs:
        for part in m.split(","):
            if not (NUMERIC / part).exists():
                ap.error(f"--module {m}: numeric/{part} does not exist")
        for t in tests:
            if not (ROOT / t).is_file():
                ap.error(f"--tests {t}: no such file")
    notes = load_notes()
    t0 = time.perf_counter()
    runs = []
    missing = []
    for m, tests in jobs:
        if args.report_only:
            run = load_run(m, tests, args.work.resolve(), notes)
            if run is None:
                missing.append(m)
            else:
                runs.append(run)
            continue
        print(f"mutating numeric/{m} with {' '.join(tests)} ...", flush=True)
        runs.append(run_module(m, tests, args.work.resolve(), notes))
        r = runs[-1]
        print(f"  {r.counts} in {r.seconds:.0f} s", flush=True)
    total = sum(r.seconds for r in runs) if args.report_only else time.perf_counter() - t0
    text = report(runs, [a for a in argv if a != "--report-only"], total, args.report_only)
    if missing:
        text += ("\n## Not run\n\nNo run of " + ", ".join(f"`{m}`" for m in missing)
                 + " with these test files yet.\n")
    args.out.write_text(text + "\n")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
