"""Every benchmark and report generator, in order: what ``make benchmark`` runs.

Run: ``.venv/bin/python benchmarks/run_all.py [--quick] [--out DIR]``. Each step is a script of
this folder (or ``hertzmdr accuracy``) run as its own process with ``OPENBLAS_NUM_THREADS=1``
(one BLAS thread on the shared 2-core machine: threaded products time the other jobs more
than the methods), given the same ``--quick``/``--out``; one progress line per step, and the
first failing step stops the run. The order matters where a step reads what an earlier one
wrote: bench_mdr.py shows bench_abel.py's results, make_nonaxi_doc.py turns beta.py's and
bench_bem.py's into docs/non_axisymmetric.md. tests/test_benchmarks.py runs every step with
``--quick --out tmp_path``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import _common

HERE = Path(__file__).resolve().parent


@dataclass(frozen=True)
class Step:
    """One generator: how to run it, and the files it writes (report files in the docs folder,
    measurements in the results folder).

    ``args`` is the command after ``python`` (default: the script ``name`` of this folder);
    ``out_file``: it takes ``--out`` as its report's path (its first doc) instead of a folder;
    ``quick``: it takes ``--quick`` (a generator that measures nothing need not).
    """

    name: str
    docs: tuple[str, ...]
    results: tuple[str, ...] = ()
    args: tuple[str, ...] = ()
    out_file: bool = False
    quick: bool = True

    def command(self, docs: Path, quick: bool, out: Path | None) -> list[str]:
        cmd = [sys.executable, *(self.args or (str(HERE / self.name),))]
        if self.out_file:
            cmd += ["--out", str(docs / self.docs[0])]
        elif out is not None:
            cmd += ["--out", str(out)]
        return cmd + (["--quick"] if quick and self.quick else [])


STEPS = (
    Step("bench_abel.py", ("abel.md", "abel_error_time.png"), ("abel.json",)),
    Step("bench_mdr.py", ("mdr.md", "mdr_convergence.png"), ("mdr.json",)),  # reads abel.json
    Step("beta.py", (), ("beta.json",)),
    Step("bench_bem.py", (), ("bem.json",)),
    Step("pyramid_factor.py", ("pyramid.md",), ("pyramid.json",)),  # fit.Pyramid's beta_n
    Step("make_nonaxi_doc.py", ("non_axisymmetric.md", "non_axisymmetric_errors.png")),
    Step("bench_stress.py", ("stress.md", "figures/fig5_8_axis_stresses.png",
                             "figures/fig5_9_von_mises.png")),
    # also writes the line-contact section of stress.md (bench_stress.py keeps it)
    Step("bench_line_stress.py", ("line_stress.md", "figures/line_stress_von_mises.png",
                                  "stress.md"), ("line_stress.json",)),
    Step("bench_ellipse_stress.py", ("ellipse_stress.md", "figures/ellipse_max_shear.png")),
    Step("bench_laws.py", ("laws_speed.md",)),
    Step("bench_c.py", ("c_laws.md",)),  # its table only; the rest of c_laws.md is by hand
    Step("bench_scene.py", ("scene_speed.md",)),
    Step("bench_adhesion.py", ("adhesion_speed.md",)),

    Step("bench_tangential.py", ("tangential_speed.md",)),
    Step("bench_fit.py", ("fit_speed.md",)),
    Step("sphere_bias.py", ("sphere.md", "sphere_bias.png"), out_file=True, quick=False),
    Step("hertzmdr accuracy", ("accuracy.md", "accuracy.png"),
         args=("-m", "hertzmdr.numeric.cli", "accuracy"), out_file=True),
)


def environment() -> dict[str, str]:
    return {**os.environ, "OPENBLAS_NUM_THREADS": "1", "MPLBACKEND": "Agg"}


def run_step(step: Step, run: _common.Run, out: Path | None) -> subprocess.CompletedProcess:
    """One step as its own process, its output captured."""
    return subprocess.run(step.command(run.docs, run.quick, out), cwd=HERE, env=environment(),
                          capture_output=True, text=True)


def main(argv=None) -> int:
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    t_all = time.perf_counter()
    for i, step in enumerate(STEPS, 1):
        print(f"[{i}/{len(STEPS)}] {step.name} ...", flush=True)
        t0 = time.perf_counter()
        proc = run_step(step, run, args.out)
        seconds = time.perf_counter() - t0
        written = [str(run.docs / f) for f in step.docs] + [str(run.results / f)
                                                             for f in step.results]
        if proc.returncode != 0:
            sys.stdout.write(proc.stdout[-4000:])
            sys.stderr.write(proc.stderr[-4000:])
            print(f"[{i}/{len(STEPS)}] {step.name} FAILED (exit {proc.returncode}) after "
                  f"{seconds:.0f} s", flush=True)
            return proc.returncode
        notes = [line for line in proc.stdout.splitlines() if "not installed" in line]
        print(f"[{i}/{len(STEPS)}] {step.name}: {seconds:.0f} s, wrote " + ", ".join(written)
              + "".join(f"\n    {n}" for n in notes), flush=True)
    print(f"all {len(STEPS)} steps in {time.perf_counter() - t_all:.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
