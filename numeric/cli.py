"""The ``hertzmdr`` command: run scenes, list effects.

    hertzmdr run [SCENE] [--json | --csv] [--out DIR [--force]]
    hertzmdr effects
    hertzmdr fit CURVE.csv --scene TIP.toml [--out FIG.png [--force]] [--z0 GUESS] [--sigma NOISE]
    hertzmdr fit RETRACT.csv --scene TIP.toml --adhesion [...]  (JKR, cone, exact sphere, power law)
    hertzmdr fit --scene SCENE.toml [...]   (the curve and its settings from the scene's [fit])
    hertzmdr fit MAP --scene TIP.toml [--out DIR [--force]] [--workers N] [--z0 ..] [--sigma ..]

``hertzmdr run`` with no SCENE runs the built-in tour (the chapter's Problems 1-8 and figures).
A malformed scene prints one message naming the file, the key and the problem, and exits 2.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path

from hertzmdr.numeric import __version__


class UsageError(Exception):
    """A command-line value that cannot work: printed as one line, exit 2."""


class _Parser(argparse.ArgumentParser):
    """argparse, but a bad argument is one line (``hertzmdr: <what>; see hertzmdr CMD -h``),
    not the usage block and the message (issue 12: one line on stderr, exit 2)."""

    def error(self, message):
        sub = self.prog.removeprefix("hertzmdr").strip()
        raise UsageError(f"{sub + ': ' if sub else ''}{message} (see: {self.prog} -h)")


parser = _Parser(
    prog="hertzmdr",
    description="Normal contact of elastic bodies (Boussinesq, Hertz, MDR): derived, "
    "generated and verified. See docs/scenes.md for the scene schema.")
parser.add_argument("--version", action="version", version=f"hertzmdr {__version__}")
sub = parser.add_subparsers(dest="command", required=True)
p_run = sub.add_parser("run", help="run a scene file, or the built-in tour without one")
p_run.add_argument("scene", nargs="?", help="scene file (TOML), or a result.json to run its "
                   "echoed scene again; omit for the built-in tour")
p_run.add_argument("--json", action="store_true", help="print one JSON document to stdout")
p_run.add_argument("--csv", action="store_true", help="print the table of the scalar results "
                   "as CSV to stdout: a row per point of a study, `name [unit]` headers")
p_run.add_argument("--out", type=Path, help="write result.json, results.csv, a PNG per field "
                   "effect and, for a study, a PNG per scalar effect here")
p_run.add_argument("--force", action="store_true", help="allow --out into a non-empty folder")
sub.add_parser("effects", help="list the effects a scene can ask for, with their units")
p_fit = sub.add_parser("fit", help="fit a force curve, or a force map, for the sample's "
                       "modulus, the contact point and the baseline (docs/fitting.md)")
p_fit.add_argument("curve", type=Path, metavar="CURVE_OR_MAP", nargs="?",
                   help="omit it to fit the scene's [fit] curve (docs/fitting.md); a curve "
                   "(CSV: a header `z [um], F [nN]` with any length and force "
                   "units, then one position and force per line); or a force map (CSV with the "
                   "header `x [um], y [um], z [nm], F [nN]` or `curve, z [nm], F [nN]`), or a "
                   "folder of curve files")
p_fit.add_argument("--scene", type=Path, required=True,
                   help="scene (TOML) with the tip and the flat sample (its nu converts E* to E), "
                   "and optionally a [fit] table: the curve, its columns and units, the depth "
                   "range (a CURVE and --z0/--sigma given here replace the table's)")
p_fit.add_argument("--out", type=Path, help="a curve: write the figure of data, fit and "
                   "residuals (PNG); a map: write the table, the map and a fit's figure into "
                   "this folder")
p_fit.add_argument("--force", action="store_true",
                   help="allow --out to replace an existing file (write into a non-empty folder)")
p_fit.add_argument("--workers", type=int, help="a map: worker processes (default: the cores)")
p_fit.add_argument("--z0", help="a guess of the contact point, with a unit (e.g. \"1.2 um\")")
p_fit.add_argument("--sigma", help="the force noise's standard deviation, with a unit "
                   "(e.g. \"20 pN\"): weights the residuals; the reduced chi^2 is then ~1")
p_fit.add_argument("--fix-z0", metavar="Z0", help="hold the contact point fixed at Z0, with a "
                   "unit (e.g. \"1.3 um\"): only the other parameters are fitted")
p_fit.add_argument("--fix-baseline", nargs=2, metavar=("F0", "S0"),
                   help="hold the baseline F_0 + s_0 z fixed, with units (e.g. \"2 nN\" "
                   "\"0.1 mN/m\"): only E* (and z_0) are fitted")
p_fit.add_argument("--adhesion", action="store_true",
                   help="a curve: fit an adhesive retract curve with the JKR paraboloid or "
                   "the adhesive cone, exact sphere or power law (a scene's sphere, cone, "
                   "exact_sphere or power_law tip; the "
                   "work of adhesion as a fifth parameter; the scene's [interface] "
                   "work_of_adhesion is shown for comparison, never used)")
p_acc = sub.add_parser("accuracy", help="measure what accuracy costs in time; write a report")
p_acc.add_argument("--out", type=Path, default=Path("docs/accuracy.md"),
                   help="the Markdown report to write, its plot beside it as .png (default: "
                   "docs/accuracy.md under the current folder)")
p_acc.add_argument("--only", help="measure only the quantities whose name contains this text "
                   "(the names: `hertzmdr accuracy --only ?` lists them)")
p_acc.add_argument("--quick", action="store_true",
                   help="two rounds of one call per way: checks the report, not a measurement")


def tour_scenes() -> list[Path]:
    from importlib.resources import files

    folder = files("hertzmdr.numeric.tour")
    return sorted(Path(str(p)) for p in folder.iterdir() if p.name.endswith(".toml"))


def check_out(folder: Path, force: bool) -> None:
    """Refuse an --out folder before anything is computed: an existing file, a non-empty
    folder without --force, or a parent that is a file or cannot be written."""
    if folder.exists() and not folder.is_dir():
        raise UsageError(f"--out {folder}: is a file, not a folder; give a folder")
    if folder.exists() and any(folder.iterdir()) and not force:
        raise UsageError(f"--out {folder}: is not empty; pass --force to write into it")
    parent = next((p for p in (folder, *folder.parents) if p.exists()), Path("."))
    if not parent.is_dir():
        raise UsageError(f"--out {folder}: {parent} is a file, not a folder")
    _probe(parent, f"--out {folder}")


def _probe(parent: Path, what: str) -> None:
    """Create and remove a folder in ``parent``: os.access says yes to root even where the
    file system refuses (/proc, /sys, a read-only mount)."""
    if not os.access(parent, os.W_OK | os.X_OK):
        raise UsageError(f"{what}: {parent} is not writable")
    try:
        os.rmdir(tempfile.mkdtemp(prefix=".hertzmdr-probe-", dir=parent))
    except OSError as exc:
        raise UsageError(f"{what}: cannot write in {parent} ({exc.strerror})") from None


def _write_out(folder: Path, docs: list[tuple], force: bool) -> None:
    """Write atomically: everything goes to a temporary folder first, then is moved in.
    ``docs``: (subfolder, document, results, title, figures.Context) of each run."""
    from hertzmdr.numeric.scene.table import write

    check_out(folder, force)
    try:
        folder.parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=".hertzmdr-", dir=folder.parent))
    except OSError as exc:
        raise UsageError(f"--out {folder}: cannot write ({exc.strerror})") from None
    try:
        for sub_name, doc, results, title, ctx in docs:
            target = tmp / sub_name if sub_name else tmp
            target.mkdir(parents=True, exist_ok=True)
            (target / "result.json").write_text(json.dumps(doc, indent=2) + "\n")
            write(doc, results, title, target, ctx)
        folder.mkdir(exist_ok=True)
        for item in sorted(tmp.rglob("*")):
            dest = folder / item.relative_to(tmp)
            if item.is_dir():
                dest.mkdir(exist_ok=True)
            else:
                os.replace(item, dest)
    except OSError as exc:  # a full disk, a file system that refuses midway
        raise UsageError(f"--out {folder}: cannot write ({exc.strerror})") from None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _check_figures(runs) -> None:
    """--out draws a PNG per field effect: without matplotlib (the ``plot`` extra) say so in
    one line before anything is printed or written."""
    from hertzmdr.numeric.scene.figures import FIGURES
    from hertzmdr.numeric.scene.table import needs_matplotlib

    fields = sorted({name for *_, results, _ in runs for name in results if name in FIGURES})
    fields += ["the study's plots"] if any(needs_matplotlib(doc) for *_, doc in runs) else []
    if not fields:
        return
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        raise UsageError(f"--out draws the field effects ({', '.join(fields)}) as PNGs, which "
                         "needs matplotlib: pip install 'hertzmdr[plot]'") from None


def cmd_run(args) -> int:
    from hertzmdr.numeric import scene
    from hertzmdr.numeric.scene.report import table
    from hertzmdr.numeric.scene.table import axes_lines, csv_text, rows_table, study_table

    if args.json and args.csv:
        raise UsageError("run: give --json or --csv, not both (see: hertzmdr run -h)")
    if args.csv and not args.scene:
        raise UsageError("run: --csv prints the table of one scene: give a SCENE "
                         "(see: hertzmdr run -h)")
    paths = [Path(args.scene)] if args.scene else tour_scenes()
    if args.out:
        check_out(args.out, args.force)
    runs = []
    for path in paths:
        sc = scene.load(path)
        record, results, doc = sc.run_full(progress=_progress())
        runs.append((path, record, results, doc))
    if args.out:
        _check_figures(runs)
    if args.json:
        docs = [doc for *_, doc in runs]
        print(json.dumps(docs[0] if args.scene else docs, indent=2))
    elif args.csv:
        sys.stdout.write(csv_text(runs[0][-1]))
    else:
        for *_, results, doc in runs:
            if "route" in doc.get("study", {}):
                print(study_table(doc, doc["warnings"]))
            else:
                print(table(doc["title"], doc["model"], results, doc["warnings"]))
                if "study" in doc:  # a load sweep: its points, one row each
                    print("\n".join(axes_lines(doc["study"]) + rows_table(doc)))
            print()
    if args.out:
        from hertzmdr.numeric.scene.figures import context_of

        _write_out(args.out, [("" if args.scene else p.stem, doc, res, doc["title"],
                               context_of(record)) for p, record, res, doc in runs],
                   args.force)
        if not args.json:
            print(f"wrote {args.out}")
    return 0


def _progress():
    """A study run point by point reports its progress on stderr, when stderr is a terminal
    (a pipe or a log file gets nothing), once a study has taken a second."""
    if not sys.stderr.isatty():
        return None
    import time

    start, shown = time.perf_counter(), []

    def report(done: int, total: int) -> None:
        if time.perf_counter() - start > 1.0 or (shown and done == total):
            shown.append(done)
            end = "\n" if done == total else ""
            print(f"\rstudy: {done}/{total} points", end=end, file=sys.stderr, flush=True)

    return report


def main(argv: list[str] | None = None) -> int:
    try:
        args = parser.parse_args(argv)
        if args.command == "effects":
            from hertzmdr.numeric.scene.effects import listing

            print(listing())
            return 0
        if args.command == "accuracy":
            return cmd_accuracy(args)
        if args.command == "fit":
            return cmd_fit(args)
        from hertzmdr.numeric.scene.schema import SceneError

        try:
            rc = cmd_run(args)
        except SceneError as exc:
            raise UsageError(str(exc)) from None
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
        return rc
    except UsageError as exc:
        print(f"hertzmdr: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # `hertzmdr run ... --json | head`: the reader left; say nothing
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


def _fit_table(args):
    """The scene's [fit] table (schema.FitSpec; an empty one without), with args.curve set to
    the curve: the command line's CURVE, else the table's (a UsageError without either)."""
    from hertzmdr.numeric import fit_io
    from hertzmdr.numeric.scene.schema import FitSpec, SceneError

    try:
        table = fit_io.fit_table(args.scene) or FitSpec()
    except SceneError as exc:
        raise UsageError(str(exc)) from None
    if args.curve is None:
        if table.curve is None:
            raise UsageError(f"fit: give a CURVE_OR_MAP, or a [fit] table with curve = "
                             f"\"...\" in {args.scene} (see: hertzmdr fit -h)")
        args.curve = table.curve
    return table


def _fit_options(args, table, nu, tip_E, tip_nu) -> dict:
    """fit_curve's keywords: --z0 and --sigma, else the [fit] table's contact_point and sigma;
    no sample modulus with [fit] modulus = "E_star"."""
    from hertzmdr.numeric.scene.units import UnitError, to_si

    try:
        z0 = table.contact_point if args.z0 is None else to_si(args.z0, "length")
        sigma = table.sigma if args.sigma is None else to_si(args.sigma, "force")
    except UnitError as exc:
        raise UsageError(f"--z0/--sigma: {exc}") from None
    try:
        fixed_z0 = (table.fixed_contact_point if args.fix_z0 is None
                    else to_si(args.fix_z0, "length"))
        fixed_baseline = (table.fixed_baseline if args.fix_baseline is None else
                          (to_si(args.fix_baseline[0], "force"),
                           to_si(args.fix_baseline[1], "force_per_length")))
    except UnitError as exc:
        raise UsageError(f"--fix-z0/--fix-baseline: {exc}") from None
    if table.modulus == "E_star":
        nu = tip_E = tip_nu = None
    out = {"nu": nu, "tip_modulus": tip_E, "tip_nu": tip_nu, "z0": z0, "sigma": sigma}
    if fixed_z0 is not None or fixed_baseline is not None:
        if args.adhesion:
            raise UsageError("--fix-z0/--fix-baseline (or [fit] fixed_contact_point, "
                             "fixed_baseline): the adhesive fit fits all five parameters; "
                             "valid only without --adhesion")
        out.update(fixed_z0=fixed_z0, fixed_baseline=fixed_baseline)
    return out


def cmd_fit(args) -> int:
    from hertzmdr.numeric import fit, fit_io
    from hertzmdr.numeric.scene.schema import SceneError

    table = _fit_table(args)
    if table.columns is None and table.units is None and fit_io.is_batch(args.curve):
        return cmd_fit_batch(args, table)
    if args.adhesion and table.depth_range is not None:
        raise UsageError("--adhesion: the scene's [fit] depth_range is for the fits without "
                         "adhesion; the adhesive fit takes the whole retract curve")
    if args.workers is not None:
        raise UsageError(f"--workers: {args.curve} is one curve; --workers is for a force map "
                         "or a folder of curves")
    try:
        tip, nu, scene_E, tip_E, tip_nu = fit_io.tip_from_scene(args.scene)
        z, F = fit_io.read_columns(args.curve, table.columns, table.units)
        options = _fit_options(args, table, nu, tip_E, tip_nu)
        if args.out is not None:
            check_figure_out(args.out, args.force)
        if args.adhesion:
            from hertzmdr.numeric import fit_adhesive
            scene_dgamma = _scene_work_of_adhesion(args.scene)
            result = fit_adhesive.fit_curve(z, F, tip, **options)
        elif table.depth_range is None:
            result = fit.fit_curve(z, F, tip, **options)
        else:
            result = fit_io.fit_in_range(z, F, tip, table.depth_range, **options)
    except SceneError as exc:
        raise UsageError(str(exc)) from None
    except ValueError as exc:  # CurveError, NoContactError and the validators' messages
        raise UsageError(f"{args.curve}: {exc}" if not isinstance(exc, fit_io.CurveError)
                         else str(exc)) from None
    if args.out is not None:  # before the report: a failed write leaves nothing on stdout
        try:
            fit_io.figure(result, args.out)
        except ImportError:
            raise UsageError("--out needs matplotlib: pip install 'hertzmdr[plot]'") from None
        except OSError as exc:
            raise UsageError(f"--out {args.out}: cannot write ({exc})") from None
    print(fit_io.report(result, scene_E))
    if args.adhesion and scene_dgamma:
        print(f"the scene's work of adhesion = {scene_dgamma:.6g} J/m^2; fitted "
              f"{result.dgamma:.6g} ± {result.errors[2]:.3g} J/m^2")
    if args.out is not None:
        print(f"wrote {args.out}")
    return 0


def _scene_work_of_adhesion(path) -> float:
    """The scene's [interface] work_of_adhesion [J/m^2] (0 when it gives none)."""
    from hertzmdr.numeric import scene

    return float(scene.load(path).spec.interface.work_of_adhesion)


def cmd_fit_batch(args, table) -> int:
    """Fit a force map or a folder of curves: a summary on stdout, one line per failed curve on
    stderr, the table (fits.csv), the map (modulus_map.png) and the fit of the curve of median
    modulus (fit_median.png) in --out. Exit 0 when a curve was fitted, 1 when none was."""
    import numpy as np

    from hertzmdr.numeric import fit, fit_batch, fit_io
    from hertzmdr.numeric.scene.schema import SceneError

    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers {args.workers}: give a number of processes >= 1")
    if table.depth_range is not None:
        raise UsageError(f"{args.scene}: fit.depth_range: applies to one curve; {args.curve} "
                         "is a force map or a folder of curves, fitted whole")
    try:
        tip, nu, scene_E, tip_E, tip_nu = fit_io.tip_from_scene(args.scene)
        opts = _fit_options(args, table, nu, tip_E, tip_nu)
        nu, tip_E, tip_nu, z0, sigma = (opts[k] for k in ("nu", "tip_modulus", "tip_nu", "z0",
                                                          "sigma"))
        if args.out is not None:
            check_out(args.out, args.force)
        curves, unread = fit_io.read_batch(args.curve)
    except SceneError as exc:
        raise UsageError(str(exc)) from None
    except ValueError as exc:  # CurveError and the validators' messages
        raise UsageError(str(exc)) from None
    if args.out is not None:
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            raise UsageError("--out draws the map, which needs matplotlib: pip install "
                             "'hertzmdr[plot]'") from None
    bar = fit_batch.ProgressBar(sys.stderr) if sys.stderr.isatty() else None
    if args.adhesion:
        from hertzmdr.numeric import fit_adhesive

        try:  # a tip without an adhesive model: one line for the batch
            fit_adhesive._check_tip(tip)
        except ValueError as exc:
            raise UsageError(f"--adhesion: {exc}") from None
    try:  # the options every curve shares are checked once, for the batch
        results = fit_batch.fit_curves(curves, tip, nu=nu, tip_modulus=tip_E, tip_nu=tip_nu,
                                       z0=z0, sigma=sigma, fixed_z0=opts.get("fixed_z0"),
                                       fixed_baseline=opts.get("fixed_baseline"),
                                       adhesion=args.adhesion, workers=args.workers,
                                       progress=bar)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    results += [fit_batch._failed(fit_batch.Curve(name, None, None, np.zeros(0), np.zeros(0)),
                                  msg) for name, msg in unread]
    for r in results:
        if not r.ok:
            print(f"hertzmdr: {args.curve}: curve {r.name}: {r.error}", file=sys.stderr)
    print(f"tip: {tip.describe()}")
    print(fit_io.batch_summary(results, scene_E))
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        fit_batch.write_table(results, args.out / "fits.csv")
        fit_io.map_figure(results, args.out / "modulus_map.png", args.curve.name)
        ok = [(r, c) for r, c in zip(results, curves, strict=False) if r.ok]
        if ok:
            r, c = sorted(ok, key=lambda rc: rc[0].values[0])[len(ok) // 2]
            if args.adhesion:
                median = fit_adhesive.fit_curve(c.z, c.F, tip, nu=nu, tip_modulus=tip_E,
                                                tip_nu=tip_nu, z0=z0, sigma=sigma)
            else:
                median = fit.fit_curve(c.z, c.F, tip, nu=nu, tip_modulus=tip_E, tip_nu=tip_nu,
                                       z0=z0, sigma=sigma)
            fit_io.figure(median, args.out / "fit_median.png", f"curve {c.name} (median E*)")
        print(f"wrote {args.out}: fits.csv, modulus_map.png" + (", fit_median.png" if ok else ""))
    return 0 if any(r.ok for r in results) else 1


def check_figure_out(path: Path, force: bool) -> None:
    """Refuse a figure's --out before the fit: a folder, an existing file without --force, a
    name that is not .png, or a parent that is a file or cannot be written."""
    if path.is_dir():
        raise UsageError(f"--out {path}: is a folder; give the figure's file name")
    if path.suffix.lower() != ".png":
        raise UsageError(f"--out {path}: the figure is a PNG; give a name ending in .png")
    parent = next((p for p in path.parents if p.exists()), Path("."))
    if not parent.is_dir():
        raise UsageError(f"--out {path}: {parent} is a file, not a folder")
    if path.exists() and not force:
        raise UsageError(f"--out {path}: exists; pass --force to replace it")
    _probe(parent, f"--out {path}")


def cmd_accuracy(args) -> int:
    from hertzmdr.numeric import accuracy

    names = [q.name for q in accuracy.quantities()]
    if args.only is not None and not any(args.only in n for n in names):
        raise UsageError(f"--only {args.only!r} matches no quantity; the names: "
                         + "; ".join(names))
    check_out(args.out.parent if args.out.parent != Path("") else Path("."), force=True)
    if args.out.is_dir():
        raise UsageError(f"--out {args.out}: is a folder; give the report's file name")
    accuracy.main(args.out, args.only, args.quick)
    print(f"wrote {args.out} and {args.out.with_suffix('.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
