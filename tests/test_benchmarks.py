"""Every benchmark and report generator runs, and writes finite numbers.

A generator that nothing runs is already broken (scipy's ``_precompute`` lesson, STYLE.md).
Each step of ``benchmarks/run_all.py`` (what ``make benchmark`` runs) runs here in its
``--quick`` mode, in the same order, into a temporary folder (never docs/). The tests check that
it exits 0, writes every file the step declares, and that every number in the Markdown tables it
writes is finite. The peers of the ``bench`` extra need not be installed: a script whose peer is
missing skips its rows with a note (checked here by hiding the peer). Timings are never asserted.
"""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks"
sys.path.insert(0, str(BENCH))
import run_all  # noqa: E402  (benchmarks/ is a folder of scripts, not a package)

# `make test` runs this file on one worker (GROUPED, tests/conftest.py): one module fixture

NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
NONFINITE = re.compile(r"\b(?:nan|inf|infinity)\b", re.IGNORECASE)
#: a cell that reports a failure as a result: the accuracy report's float64 Gamma ratio of
#: kappa_n overflows at n = 1000, which is what that row shows
REPORTED_FAILURE = "fails (inf or nan)"


def table_cells(markdown: str) -> list[list[str]]:
    """The data rows of every Markdown table (header and separator rows left out)."""
    rows, header_next = [], True
    for line in markdown.splitlines():
        if not line.startswith("|"):
            header_next = True
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header_next:
            header_next = False
            continue
        if all(set(c) <= set("-: ") for c in cells):
            continue
        rows.append(cells)
    return rows


def assert_finite_tables(path: Path):
    rows = table_cells(path.read_text())
    assert rows, f"{path.name}: no table"
    numbers = 0
    for cells in rows:
        for cell in cells:
            if cell == REPORTED_FAILURE:
                continue
            assert not NONFINITE.search(cell), f"{path.name}: non-finite cell {cell!r} in {cells}"
            for tok in NUMBER.findall(cell.replace(",", "")):
                assert math.isfinite(float(tok)), f"{path.name}: {tok} in {cells}"
                numbers += 1
    assert numbers, f"{path.name}: its tables hold no number"


def test_table_checker_catches_nan(tmp_path):
    """The checker itself can fail: a nan, an inf or a table without numbers is caught."""
    for bad in ("| a | b |\n|---|---|\n| x | nan |\n", "| a |\n|---|\n| -inf |\n",
                "| a |\n|---|\n| text |\n", "no table\n"):
        f = tmp_path / "bad.md"
        f.write_text(bad)
        with pytest.raises(AssertionError):
            assert_finite_tables(f)
    f.write_text("| a | b |\n|---|---|\n| 1.5e-3 | 2 x 1 |\n")
    assert_finite_tables(f)


@pytest.fixture(scope="module")
def quick_run(tmp_path_factory):
    """Every step in make benchmark's order, --quick, into one temporary folder (later steps
    read earlier steps' results from it). A failed step does not stop the others here: each
    test reports its own."""
    out = tmp_path_factory.mktemp("bench")
    run = run_all._common.Run(True, out, out, run_all._common._timing.QUICK)
    return out, {step.name: run_all.run_step(step, run, out) for step in run_all.STEPS}


@pytest.mark.parametrize("step", run_all.STEPS, ids=[s.name for s in run_all.STEPS])
def test_quick_run_writes_finite_tables(quick_run, step):
    out, procs = quick_run
    proc = procs[step.name]
    assert proc.returncode == 0, (f"{step.name} failed:\n{proc.stdout[-2000:]}\n"
                                  f"{proc.stderr[-4000:]}")
    for name in step.docs + step.results:
        assert (out / name).is_file() and (out / name).stat().st_size > 0, f"{name} not written"
        if name.endswith(".md"):
            assert_finite_tables(out / name)
        if name.endswith(".json"):
            json.loads((out / name).read_text())


@pytest.mark.parametrize("script, doc", [("bench_abel.py", "abel.md"),
                                         ("bench_mdr.py", "mdr.md")])
def test_docs_only_rewrites_the_same_report(quick_run, script, doc):
    """--docs-only (the cheap refresh, e.g. after a change of derive/) writes exactly what the
    measuring run wrote, from its saved JSON."""
    out, procs = quick_run
    assert procs[script].returncode == 0
    before = (out / doc).read_text()
    (out / doc).unlink()
    subprocess.run([sys.executable, str(BENCH / script), "--docs-only", "--out", str(out)],
                   cwd=BENCH, env=run_all.environment(), check=True, capture_output=True)
    assert (out / doc).read_text() == before


def _without(module: str, script: str, out: Path) -> subprocess.CompletedProcess:
    """Run a script with ``module`` made unimportable, as where the bench extra is missing."""
    code = (f"import runpy, sys; sys.modules[{module!r}] = None; "
            f"sys.path.insert(0, {str(BENCH)!r}); "
            f"sys.argv = [{script!r}, '--quick', '--out', {str(out)!r}]; "
            f"runpy.run_path({str(BENCH / script)!r}, run_name='__main__')")
    return subprocess.run([sys.executable, "-c", code], cwd=BENCH, env=run_all.environment(),
                          capture_output=True, text=True)


def _installed(module: str) -> bool:
    import importlib.util

    return importlib.util.find_spec(module) is not None


def test_missing_peers_are_skipped_with_a_note(quick_run, tmp_path):
    """No PyAbel: abel.md has hertzmdr's rows and says PyAbel's are left out. No Tamaas:
    bem.json records it and non_axisymmetric.md says its row is skipped. Where neither peer
    is installed (CI: the bench extra is not a test dependency), the quick run above ran
    without them, and its output is what is checked; else the scripts run again here with the
    peer hidden."""
    if not _installed("abel") and not _installed("tamaas"):
        out, procs = quick_run
        outs = [procs[s] for s in ("bench_abel.py", "bench_bem.py", "beta.py",
                                   "make_nonaxi_doc.py")]
        shutil.copytree(out, tmp_path, dirs_exist_ok=True)
    else:
        outs = [_without("abel", "bench_abel.py", tmp_path),
                _without("tamaas", "bench_bem.py", tmp_path)]
        outs.append(_without("tamaas", "beta.py", tmp_path))  # make_nonaxi_doc reads its JSON
        outs.append(_without("tamaas", "make_nonaxi_doc.py", tmp_path))
    for proc in outs:
        assert proc.returncode == 0, proc.stderr[-4000:]
    assert "PyAbel not installed" in outs[0].stdout
    assert "tamaas not installed" in outs[1].stdout
    abel_md = (tmp_path / "abel.md").read_text()
    assert "PyAbel was not installed for this run" in abel_md
    assert "basex" not in "".join("".join(r) for r in table_cells(abel_md))
    assert_finite_tables(tmp_path / "abel.md")
    assert "error" in json.loads((tmp_path / "bem.json").read_text())["tamaas"]
    assert "its row is skipped" in (tmp_path / "non_axisymmetric.md").read_text()
    assert_finite_tables(tmp_path / "non_axisymmetric.md")
