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
(``hertzmdr/numeric``, a copy of numeric/) beside ``tests``, ``examples`` and ``docs`` (links,
copied into ``mutants/``: the scene tests read the example scenes and docs/scenes.md), with the
repository's pyproject.toml whose ``[tool.mutmut]`` (the shared settings) gets this module's
``only_mutate`` and test files. mutmut runs the tests that reach a function with ``-x`` for
each of its mutants, one worker, under ``nice -n 19``. mutmut 3 leaves decorated functions
alone; in the copy of the module under test, ``@representable`` is applied after the function
instead of above it (see :func:`undecorate`), so those functions are mutated too.

The oracle memo. mutmut 3 runs each mutant's tests in a process forked from one that has only
collected them (``forkserver_warmup = "collect"``), so before this memo every mutant recomputed
the tests' mpmath references (30-digit quadratures), which do not depend on the mutated module.
This script sets ``HERTZMDR_ORACLE_MEMO`` to ``build/mutation/<module>/oracle_memo.jsonl`` for
its mutmut run; the references decorated with tests/oracle.py's ``memo`` (pure functions of
their arguments, using derive/ and mpmath only, never numeric/) are then written there by the
run's first test passes and read by each mutant, keyed by the reference's name and source and
its exact arguments and working precision, values in their exact binary digits. Outside these
runs the variable is unset and every test computes every reference. A fresh run starts with an
empty memo (the scratch folder is made anew); ``--resume`` keeps it. Measured on
line_stress.py (the 177 mutants its first run checked without the memo, checked again with it,
same tests, same machine, durations from mutmut's ``.meta``): median 9.0 s -> 0.71 s a mutant,
3135 s -> 139 s in all (the rest is the tests of numeric/ themselves and the fork). The
reference tests of test_ellipse_stress.py (the 20-digit superposition, the polar routes, the
40-digit axis maxima: seven tests) take 32.9 s with the memo empty and 3.0 s with it filled.
mutmut's own settings stay as they are: ``forkserver_warmup = "collect"`` (its default) already
imports the tests, SymPy and the derivations once in the fork server; the time limit of a
mutant (``timeout_multiplier`` 15 times its tests' time in the stats pass, the pass that fills
the memo and so the slowest) only gets more generous with the memo; the test lists above leave
out the sweeps (2-D quadratures, minutes a mutant). What remains a mutant's time is the tests'
own calls of numeric/ (test_stress's superposed maximum, 10 s of numeric work, is the largest).

Each surviving mutant is printed with its line; a note for it comes from
benchmarks/mutation_notes.toml (why it cannot be killed), matched by module, original line and
mutated line. A survivor without a note is listed as *unexplained*: that is the list to work
on (add a test by an independent route, or a note).
"""

from __future__ import annotations

import argparse
import ast
import datetime
import functools
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
#: the notes on survivors; mutation_notes_*.toml beside it hold those of the scene layer
#: and of each fitting module (files of their own, written apart from the others)
NOTES = ROOT / "benchmarks" / "mutation_notes.toml"
# the last run of each module, one JSON file each (committed: --report-only assembles the page
# from them when build/mutation/ holds no newer run of the module)
RUNS = ROOT / "benchmarks" / "mutation_runs"
#: folders besides tests/ that the tests read (the example scenes, docs/scenes.md, the
#: benchmarks' scripts test_fit_batch.py imports)
EXTRA = ("examples", "docs", "benchmarks")
#: the oracle memo of a run (tests/oracle.py's memo), in its scratch folder
MEMO = "oracle_memo.jsonl"
PACKAGE = "hertzmdr/numeric"  # the import path of numeric/ (see [tool.setuptools.package-dir])

# test_stress.py but its 2-D quadrature sweep test_hertz_field_by_superposition (60 s for each
# mutant of the field; test_hertz_field_against_johnson_at_50_digits checks the same field)
_STRESS_TESTS = [f"tests/test_stress.py::test_{t}" for t in """
    axis_stresses_by_superposition axis_maximum_shear maximum_in_the_body
    hertz_field_against_johnson_at_50_digits spheroidal_coordinates
    field_on_the_axis_is_the_derived_axis_field von_mises_invariant
    equilibrium_and_surface_traction point_load_limit no_nan_anywhere edge_of_contact
    superposition_route superposed_plane_and_its_maxima
    stress_modules_import_no_sympy_scipy_matplotlib bad_input_is_named
    axis_maximum_shear_bracket each_input_named_in_its_error
    max_shear_of_known_principal_stresses hertz_maximum_refuses_an_unknown_criterion
    superposition_fills_both_rules_and_its_estimate_is_tight
    more_inputs_named_and_the_criteria_by_name plane_field_maximum_is_located_on_its_grid
    superposed_plane_on_its_smallest_grid superposed_plane_error_is_relative
    superposed_maximum_of_the_orthogonal_shear_within_its_bound
    orthogonal_shear_maximum_by_superposition orthogonal_shear_maximum_is_the_largest_in_the_body
    point_force_shear_is_the_ring_routes_kernel spheroidal_broadcasts_its_inputs
    spheroidal_far_away_and_empty hertz_stress_cylindrical_broadcasts_its_inputs
    superposed_maximum_bound_takes_the_curvature_of_the_plane
    superposed_maximum_bound_extrapolates_to_the_surface
    superposed_maximum_near_the_surface_within_its_bound
    a_point_beyond_max_distance_is_named_among_many
    hertz_stress_cylindrical_p0_and_nu_arrays_across_blocks_and_forms
    superposition_estimate_bounds_the_error_of_coarse_rules_under_the_punch
    superposed_plane_names_its_inputs""".split()]

# test_powerlaw.py but its slow references (the 3-D elasticity check, kappa by quadrature: 170 s
# for each mutant they reach) and five of the nine exponents of the outside displacement
_POWERLAW_TESTS = [f"tests/test_powerlaw.py::test_{t}" for t in """
    g_by_quadrature general_n_pressure_forms pressure_large_n_by_quadrature
    pressure_has_no_nan_at_any_n centre_pressure_for_n_between_1_and_2 force_by_pressure
    normalized_pressure_by_quadrature punch force_roundtrip force_increases_with_depth
    bad_input_is_named displacement_outside_large_n[2.5] displacement_outside_large_n[41.0]
    displacement_outside_large_n[343.5] displacement_outside_large_n[0.5]
    displacement_outside_large_n[0.001]
    each_input_named_in_its_error pressure_large_n_at_si_scale_in_one_call
    normalized_pressure_of_the_punch special_cases_are_hertz_cone_and_punch
    mean_pressure_needs_a_positive_depth g_profile_of_a_steep_power_law_at_a_small_x
    punch_pressure_is_zero_outside_its_radius g_profile_refuses_a_non_number_naming_x
    g_profile_refuses_an_infinite_x_naming_x
    pressure_near_the_centre_at_the_closed_form_exponents
    pressure_is_finite_near_the_centre_for_n_from_1_5
    surface_displacement_outside_at_several_radii_in_one_call
    pressure_near_the_centre_by_quadrature surface_displacement_far_outside""".split()]

# test_sphere.py but its sweeps (the 3-D elasticity check, decades), the symbolic check and
# the report's regeneration
_SPHERE_TESTS = [f"tests/test_sphere.py::test_{t}" for t in """
    profile_and_g depth_and_force_by_quadrature contact_radius_and_force_at_depth stiffness
    pressure_by_quadrature_of_59 force_is_integral_of_pressure hard_cases_and_vectors
    bad_input force_increases_and_inverts hertz_limit
    surface_displacement_outside_by_the_mdr_integral each_input_named_in_its_error
    an_input_out_of_range_in_a_2d_array_is_named_by_its_full_index
    the_deep_limit_itself_is_accepted_and_beyond_it_is_named""".split()]

# the tests of test_mdr.py that call numeric/mdr.py (the others check derive/mdr.py, and one
# of them, a SymPy solve given 10 s, fails when the machine is loaded)
_MDR_TESTS = [f"tests/test_mdr.py::test_{t}" for t in """
    numeric_powerlaw numeric_convergence_order numeric_worn_with_and_without_breakpoint
    numeric_from_callable_and_force_control numeric_noisy_samples numeric_roundtrips
    force_depth_curve_is_monotone force_depth_curve_vectorized_bounds_every_depth
    bad_input_is_named numeric_worn_pressure numeric_kinked_profile
    numeric_kinked_convergence_and_estimate mdr_force_by_the_pressure
    rtol_outside_the_range_is_refused rtol_is_the_target rtol_range_lower_end
    g_and_displacement_bounds_hold_and_are_tight callable_that_cannot_meet_rtol_says_why
    pressure_on_the_axis pressure_bound_on_the_axis_of_a_sampled_power_law
    pressure_bound_covers_power_laws_sampled_coarsely_and_finely
    numeric_worn_displacement""".split()]
# the public face, numeric/mdr.py: also the bounds of every sampled profile against 30-digit
# references and the unloaded solution
_MDR_PY_TESTS = _MDR_TESTS + ["tests/test_mdr_bounds.py", "tests/test_zero_load.py"]

# test_ellipse_stress.py but the bearing scene's two tests (the scene plumbing, 10 s each: the
# maxima they check are reached by test_maxima_lie_on_the_axis and
# test_orthogonal_shear_limits) and the 2-D polar route beside a slender contact (6 s; the
# field there is reached by test_field_by_polar_superposition and test_hard_points_...)
_ELLIPSE_STRESS_TESTS = [f"tests/test_ellipse_stress.py::test_{t}" for t in """
    love_form_is_boussinesq derivation_identities harmonic_h field_by_superposition
    field_by_polar_superposition hard_points_by_polar_superposition polar_route_converges
    circle_reproduces_huber axis_limits axis_maxima_at_30_digits maxima_lie_on_the_axis
    orthogonal_shear_limits bad_input_is_named
    von_mises_and_principal_shear_by_polar_superposition
    axis_stresses_in_si_units_by_polar_superposition
    semi_axes_refusal_names_the_element_that_is_too_long rtol_range_is_closed_and_named
    ratio_and_nu_of_the_maxima_are_named no_warning_beside_a_slender_contact
    maxima_at_the_surface_centre max_shear_in_the_long_axis_plane
    circle_just_beside_the_edge_near_the_surface
    orthogonal_shear_maximum_of_the_circle_is_the_exact_one error_is_that_of_each_point
    far_points_are_finite_up_to_max_distance_and_named_beyond""".split()]

# the modules of numeric/ but the generated ones, demo.py, plots.py and scene/ (its own page),
# most physics first, each with the (fast) test files written for it
MODULES: dict[str, list[str]] = {
    "hertz.py": ["tests/test_hertz.py"],
    "cone.py": ["tests/test_cone.py"],
    "powerlaw.py": _POWERLAW_TESTS,
    "line.py": ["tests/test_line.py"],
    "bodies.py": ["tests/test_bodies.py"],
    "ellipse.py": ["tests/test_ellipse.py"],
    "stress.py": _STRESS_TESTS,
    "worn.py": ["tests/test_worn_numeric.py"],
    "contact.py": ["tests/test_contact.py"],
    "pressures.py": ["tests/test_contact.py"] + [
        f"tests/test_pressures.py::test_max_pressure_of{t}" for t in (
            "", "_edge_cases", "_in_the_first_and_last_cells",
            "_a_narrow_peak_and_an_increasing_pressure", "_names_its_inputs")],
    "line_stress.py": ["tests/test_line_stress.py"],
    "sphere.py": _SPHERE_TESTS,
    "mdr.py": _MDR_PY_TESTS,
    "_mdr": _MDR_TESTS,
    "abel.py": ["tests/test_abel.py"],
    "_abel": ["tests/test_abel.py"],
    # `hertzmdr accuracy` and its cases: one run (one stats pass) for the two, whose tests are
    # the same two files
    "accuracy.py,_accuracy_cases.py": ["tests/test_accuracy.py", "tests/test_cli.py",
                                       "tests/test_domains.py"],
    # the command line: its commands are tested by the files of what they run
    "cli.py": ["tests/test_cli.py", "tests/test_cli_bad_args.py", "tests/test_fit_scene.py",
               "tests/test_fit_batch.py", "tests/test_scene_echo.py", "tests/test_warnings.py"],
    "impact.py": ["tests/test_impact.py"],
    "motion.py": ["tests/test_impact.py"],
    "bem.py": ["tests/test_bem.py"],
    "_validate.py": ["tests/test_validate.py"],
    "_quadrature.py": ["tests/test_quadrature.py"],
    "ellipse_stress.py": _ELLIPSE_STRESS_TESTS,
    "force_law.py": ["tests/test_force_law.py"],
    "adhesion.py": ["tests/test_adhesion.py"],
    "tangential.py": ["tests/test_tangential.py", "tests/test_tangential_mutants.py"],
    "fit.py": ["tests/test_fit.py", "tests/test_fit_sampled.py", "tests/test_fit_breakpoints.py"],
    "fit_adhesive.py": [f"tests/test_fit_adhesive_{t}.py" for t in (
        "sphere", "cone", "powerlaw", "sampled")] + ["tests/test_fit_jkr.py"],
    "fit_batch.py": ["tests/test_fit_batch.py"],
    "fit_io.py": ["tests/test_fit_io.py", "tests/test_fit_batch.py", "tests/test_fit_scene.py",
                  "tests/test_fit_breakpoints.py"],
    # the timing of the benchmarks and `hertzmdr accuracy`, on a fake clock (the benchmarks'
    # quick runs, which also use it, take about 70 s of CPU a mutant)
    "_timing.py": ["tests/test_timing.py"],
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
    file: str = ""  # the file under numeric/, for a module that is a folder


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
    # hypothesis's "mutation" profile (tests/conftest.py): no deadline (on a loaded machine a
    # test's time says nothing: DeadlineExceeded would count as a kill) and the same examples
    # for every mutant
    args = shared.get("pytest_add_cli_args", []) + ["--hypothesis-profile=mutation"]
    return {**shared, "source_paths": [PACKAGE], "only_mutate": only, "also_copy": list(EXTRA),
            "pytest_add_cli_args": args, "pytest_add_cli_args_test_selection": list(tests)}


def workdir(module: str) -> str:
    """The scratch folder's name of a --module (``scene/kinds`` -> ``scene_kinds``, several
    joined by ``+``)."""
    return module.replace("/", "_").replace(",", "+").replace(".py", "")


def scratch(module: str, tests: list[str], base: Path, resume: bool = False,
            refresh: bool = False) -> Path:
    """A fresh scratch folder laying out numeric/ as hertzmdr/numeric for mutmut; with
    ``resume``, the folder of a run of the same module and tests stopped before its end is
    kept (mutmut then checks only the mutants it has no result for, and those of functions
    changed since). With ``refresh``, the folder of a run, finished or not, is kept with its
    results and tests, and gets today's numeric/: mutmut compares each function's hash with
    the one it ran, and checks again only the mutants of functions changed since, and those
    that had no tests (with the run's tests, whose map of functions it makes again; a changed
    test selection would make it check every mutant again)."""
    work = base / workdir(module)
    if refresh:
        if not (work / "mutants").is_dir():
            raise SystemExit(f"--refresh: no run of numeric/{module} in {work} to refresh")
        cfg = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
        sel = "pytest_add_cli_args_test_selection"
        write_config(work, {**mutmut_config(module, tests), sel: cfg[sel]})
        shutil.rmtree(work / PACKAGE)
        copy_sources(work, module)
        # the tests' map of functions is made again (a function added since has no tests in
        # the old one), and the mutants it had no tests for are checked again with it
        (work / "mutants" / "mutmut-stats.json").unlink(missing_ok=True)
        for meta in (work / "mutants").rglob("*.py.meta"):
            data = json.loads(meta.read_text())
            codes = data["exit_code_by_key"]
            data["exit_code_by_key"] = {k: None if STATUS.get(c) == "no tests" else c
                                        for k, c in codes.items()}
            meta.write_text(json.dumps(data))
        for folder in ("tests", *EXTRA):  # this checkout's (the run may have been made in another)
            (work / folder).unlink(missing_ok=True)
            (work / folder).symlink_to(ROOT / folder, target_is_directory=True)
        (work / "result.json").unlink(missing_ok=True)
        print(f"  --refresh: numeric/{module} with today's source and the {len(cfg[sel])} "
              "tests its run began with", flush=True)
        return work
    if resume and (work / "mutants").is_dir() and not (work / "result.json").exists():
        cfg = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
        if cfg == mutmut_config(module, tests):
            return work
        # tests added to the module's list since the run began: it goes on with the tests it
        # began with (a changed test selection makes mutmut check every mutant again); the
        # survivors the added tests kill are its "since" notes
        # A changed time limit only reclassifies timeouts: the run goes on with the new one.
        sel = "pytest_add_cli_args_test_selection"
        limit = ("timeout_multiplier", "timeout_constant")
        now = mutmut_config(module, tests)
        if ({**cfg, sel: None, **dict.fromkeys(limit)} == {**now, sel: None,
                                                           **dict.fromkeys(limit)}
                and set(cfg[sel]) <= set(tests)):
            print(f"  --resume: numeric/{module} goes on with the {len(cfg[sel])} tests its "
                  "run began with", flush=True)
            if any(cfg.get(k) != now.get(k) for k in limit):
                write_config(work, {**now, sel: cfg[sel]})
            return work
    shutil.rmtree(work, ignore_errors=True)
    (work / "hertzmdr").mkdir(parents=True)
    copy_sources(work, module)
    for folder in ("tests", *EXTRA):
        (work / folder).symlink_to(ROOT / folder, target_is_directory=True)
    write_config(work, mutmut_config(module, tests))
    return work


def copy_sources(work: Path, module: str) -> None:
    """numeric/ copied to the scratch folder as hertzmdr/numeric, ``module`` undecorated."""
    shutil.copytree(NUMERIC, work / PACKAGE, ignore=shutil.ignore_patterns("__pycache__"))
    for part in module.split(","):
        target = work / PACKAGE / part
        for path in [target] if target.is_file() else sorted(target.rglob("*.py")):
            undecorate(path)


def write_config(work: Path, cfg: dict) -> None:
    """The scratch folder's pyproject.toml: the repository's, its [tool.mutmut] being ``cfg``.
    Its time of change is kept: load_run counts a run's time from the scratch folder's making."""
    path = work / "pyproject.toml"
    made = path.stat() if path.exists() else None
    text = (ROOT / "pyproject.toml").read_text()
    text = re.sub(r"(?ms)^\[tool\.mutmut\]\n.*?(?=^\[|\Z)", "", text)  # replaced below
    text += "\n[tool.mutmut]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in cfg.items())
    path.write_text(text)
    if made is not None:
        os.utime(path, ns=(made.st_atime_ns, made.st_mtime_ns))


def undecorate(path: Path) -> None:
    """Move ``@representable`` (numeric/_validate.py) from above each module-level function of
    ``path`` to a rebinding ``f = representable(f)`` at the end of the module: mutmut 3 does not
    mutate decorated functions, and this one only wraps the call. Its line becomes a comment,
    so every line keeps its number."""
    lines = path.read_text().splitlines(keepends=True)
    names = []
    for i, line in enumerate(lines[:-1]):
        found = re.match(r"def (\w+)\(", lines[i + 1])
        if line.rstrip() == "@representable" and found:
            names.append(found.group(1))
            lines[i] = "# @representable: applied at the end of the module (mutation run)\n"
    if names:
        lines.append("\n" + "".join(f"{n} = representable({n})\n" for n in names))
        path.write_text("".join(lines))


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


@functools.cache
def _notes_files() -> tuple[dict, ...]:
    """The parsed notes files, read once a run (find_note asks for them per survivor)."""
    return tuple(tomllib.loads(path.read_text())
                 for path in sorted(NOTES.parent.glob("mutation_notes*.toml")))


def load_notes(kind: str = "equivalent") -> list[dict]:
    """The notes of benchmarks/mutation_notes*.toml (one file for the scene layer, one for
    each fitting module, one for the rest): "equivalent"
    (survivors that cannot be killed, with the reason), "since" (survivors of a module's last
    run killed by a test added after it), "text" (a line whose text-only mutants are
    presentation), "killed" (survivors of earlier runs and the tests added) or "finding"
    (defects seen while writing those tests)."""
    return [n for data in _notes_files() for n in data.get(kind, [])]


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
        # a note's optional "line" (the run's) tells apart lines of the same text, and its
        # optional "file" (under numeric/) the files of a folder's run
        if n.get("line", s.line) != s.line or n.get("file", s.file) != s.file:
            continue
        # an "exact" note's mutant is the whole mutated line, not a part of it (a part that
        # every other mutant of the line contains too, such as its unchanged tail)
        if n.get("exact") and squash(n["mutant"]) != squash(s.mutant):
            continue
        if (n["module"] == module and squash(n["original"]) in squash(s.original)
                and squash(n["mutant"]) in squash(s.mutant)):
            return n["reason"]
    # "text" notes: every mutant of the line that only changes the text of a string (a method
    # text, a label): presentation, with the reason
    for n in load_notes("text"):
        if n.get("line", s.line) != s.line:
            continue
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
            starts = function_lines(source)  # the scratch's copy, as mutmut mutated it
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
                if not module.endswith(".py") or "," in module:
                    s.file = str(source.relative_to(PACKAGE))
                s.note = find_note(module, s, notes)
                found.append(s)
    finally:
        os.chdir(here)
    return counts, sorted(found, key=lambda s: (s.file, s.line))


def run_module(module: str, tests: list[str], base: Path, notes: list[dict],
               resume: bool = False, refresh: bool = False, workers: int = 1) -> Run:
    work = scratch(module, tests, base, resume, refresh)
    # the tests of the run (a resumed run keeps those it began with: see scratch)
    cfg = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
    tests = list(cfg["pytest_add_cli_args_test_selection"])
    resumed = (work / "run.log").exists()
    mutmut = str(Path(sys.executable).with_name("mutmut"))
    # one worker on a shared machine (a loaded machine trips mutmut's wall-time limit: false
    # timeouts); more on an idle one
    cmd = ["nice", "-n", "19", mutmut, "run", "--max-children", str(workers)]
    t = time.perf_counter()
    with open(work / "run.log", "a" if resumed else "w") as log:
        proc = subprocess.run(cmd, cwd=work, stdout=log, stderr=subprocess.STDOUT,
                              env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1",
                                   # the oracle memo (tests/oracle.py), this run's only
                                   "HERTZMDR_ORACLE_MEMO": str(work / MEMO)})
    seconds = time.perf_counter() - t
    if proc.returncode != 0:
        tail = (work / "run.log").read_text()[-2000:]
        raise SystemExit(f"mutmut failed on {module} (exit {proc.returncode}):\n{tail}")
    counts, survivors = survivors_of(work, module, notes)
    again = " ".join(["benchmarks/mutation.py", "--module", module, "--tests", *tests])
    date = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    if refresh:  # the time is that of the part run now
        date += " (refreshed)"
    elif resumed:
        date += " (resumed)"
    run = Run(module, tests, again, seconds, date, counts, survivors)
    (work / "result.json").write_text(json.dumps(asdict(run), indent=1))
    save_run(run)
    return run


def run_path(module: str) -> Path:
    return RUNS / (workdir(module) + ".json")


def save_run(run: Run) -> None:
    """Keep ``run`` in benchmarks/mutation_runs/ (its notes are read anew on loading)."""
    data = asdict(run)
    for s in data["survivors"]:
        del s["note"]
    RUNS.mkdir(exist_ok=True)
    run_path(run.module).write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")


def load_run(module: str, base: Path, notes: list[dict]) -> Run | None:
    """The result of the last run of ``module`` (``--report-only``), its notes read anew: the
    run in ``base`` (complete, or stopped before its end: what it checked, the rest counted as
    not checked; either is kept in benchmarks/mutation_runs/), else the one kept there; None if
    there is none. The page shows the tests that run used (MODULES may have more since: their
    kills are the "since" notes)."""
    work = base / workdir(module)
    path = work / "result.json"
    if not path.exists() and (work / "mutants").is_dir():
        cfg = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
        tests = cfg["pytest_add_cli_args_test_selection"]
        counts, survivors = survivors_of(work, module, notes)
        stopped = datetime.datetime.fromtimestamp((work / "run.log").stat().st_mtime,
                                                  datetime.UTC)
        again = " ".join(["benchmarks/mutation.py", "--module", module, "--tests", *tests])
        # the time it ran: from the scratch folder's pyproject.toml (written at its start) to
        # the last line of its log
        ran = (work / "run.log").stat().st_mtime - (work / "pyproject.toml").stat().st_mtime
        run = Run(module, list(tests), again, ran,
                  stopped.strftime("%Y-%m-%d %H:%M UTC") + " (stopped before the end)",
                  counts, survivors)
        save_run(run)
        return run
    if not path.exists():
        path = run_path(module)
    if not path.exists():
        return None
    data = json.loads(path.read_text())
    run = Run(**{**data, "survivors": [Survivor(**x) for x in data["survivors"]]})
    if path.parent == work:
        save_run(run)
    for s in run.survivors:
        s.note = find_note(module, s, notes)
    return run


def tests_cell(tests: list[str]) -> str:
    """The test files of a run for the table: a file, ``file::test``, or a file with the
    number of its tests chosen (the command below the table lists them)."""
    files: dict[str, list[str]] = {}
    for t in tests:
        name, _, test = t.partition("::")
        files.setdefault(Path(name).name, []).append(test)
    cells = []
    for name, chosen in files.items():
        if "" in chosen:
            cells.append(f"`{name}`")
        elif len(chosen) == 1:
            cells.append(f"`{name}::{chosen[0]}`")
        else:
            cells.append(f"`{name}` ({len(chosen)} tests)")
    return ", ".join(cells)


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
        "the scratch folder that `benchmarks/mutation.py` lays out (see its docstring). Where a "
        "file's slowest tests (2-D or 3-D quadrature references, minutes for each mutant they "
        "reach) are left out, the table gives the number of tests run and the command lists "
        "them. Functions under `@representable` are mutated too (mutmut 3 skips decorated "
        "functions: the scratch copy applies the decorator after the function); runs before "
        "2026-11-23 17:00 UTC did not mutate them. *not checked*: the run was stopped before "
        "mutmut reached those mutants (it checks the cheapest first); `--resume` continues it. "
        "Runs since 2026-11-27 10:00 UTC read the tests' mpmath references from a memo filled "
        "by the run's first test pass (`HERTZMDR_ORACLE_MEMO`, tests/oracle.py's `memo`; unset "
        "in every other run): on the 177 mutants of `line_stress.py` checked before and after "
        "it, the median time a mutant went from 9.0 s to 0.71 s (3135 s to 139 s in all). "
        "Runs since 2026-11-27 16:00 UTC stop a mutant at 6 times its tests' CPU time in the "
        "run's first pass (pyproject.toml's `timeout_multiplier` 3, was mutmut's 15: two "
        "looping mutants of `stress.py` had held a run 89 min each); its *timeout* count is "
        "of those. *(refreshed)*: the run was checked again on a later source with "
        "`--refresh`: mutmut compares each function's hash with the one it ran and checks "
        "again only the mutants of functions changed since and those that had no tests (the "
        "run's test files, their map of functions made again); the time is that of the "
        "refresh.",
        "*no tests*: no test of those files calls the function. Generated modules "
        "(`_generated*.py`) are not mutated: they are checked against the derivations by "
        "`tests/test_generated.py` and by the mpmath oracles. Nor are `demo.py` and `plots.py` "
        "(a demonstration and figures: nothing they compute is a result, and their tests check "
        "that they run), nor the drawing of `fit_io.py`'s two figures and of `accuracy.py`'s "
        "(`# pragma: no mutate` regions: what they draw is computed and tested apart, "
        "`map_grids` and the report's rows). The notes on the "
        "survivors are in `benchmarks/mutation_notes*.toml`. The scene layer, "
        "`numeric/scene/`, has its own page, [mutation_scene.md](mutation_scene.md).",
        "",
        "| module | test files | mutants | " + " | ".join(columns) + " | time | run on |",
        "|---|---|---:|" + "---:|" * len(columns) + "---:|---|",
    ]
    for r in runs:
        cells = [str(r.counts.get(c, 0)) for c in ["mutants", *columns]]
        tests = tests_cell(r.tests)
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
            where = f"`{s.file}` line {s.line}" if s.file else f"line {s.line}"
            lines.append(f"- {where} ({s.status}): `{s.original}` → `{s.mutant}`: {why}")
        lines.append("")
    if not any_left:
        lines += ["None: every mutant was killed.", ""]
    modules = {r.module for r in runs}
    found = [f for f in load_notes("finding") if f["module"] in modules]
    if found:
        lines += ["## Defects found on the way (each says whether and where it was fixed)", ""]
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
                    help="test files (or tests: file::name) for the --module before it")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "mutation.md")
    ap.add_argument("--work", type=Path, default=ROOT / "build" / "mutation")
    ap.add_argument("--resume", action="store_true",
                    help="continue a module's run stopped before its end (same tests)")
    ap.add_argument("--refresh", action="store_true",
                    help="run a module's last run again on today's source: only the mutants "
                    "of functions changed since are checked again (the run's tests)")
    ap.add_argument("--workers", type=int, default=1,
                    help="mutants checked at once (default 1; more only on an idle machine)")
    ap.add_argument("--report-only", action="store_true",
                    help="write the report from the last run of each module (in --work)")
    args = ap.parse_args(argv)
    if args.workers < 1:
        ap.error(f"--workers {args.workers}: at least 1")
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
            if not (ROOT / t.partition("::")[0]).is_file():  # a file, or a test in it
                ap.error(f"--tests {t}: no such file")
    notes = load_notes()
    t0 = time.perf_counter()
    runs = []
    missing = []
    for m, tests in jobs:
        if args.report_only:
            run = load_run(m, args.work.resolve(), notes)
            if run is None:
                missing.append(m)
            else:
                runs.append(run)
            continue
        print(f"mutating numeric/{m} with {' '.join(tests)} ...", flush=True)
        runs.append(run_module(m, tests, args.work.resolve(), notes, args.resume,
                                args.refresh, args.workers))
        r = runs[-1]
        print(f"  {r.counts} in {r.seconds:.0f} s", flush=True)
    total = sum(r.seconds for r in runs) if args.report_only else time.perf_counter() - t0
    shown = [a for a in argv if a not in ("--report-only", "--resume", "--refresh")]
    for opt in ("--work", "--workers"):  # a scratch folder, the machine: not the page's
        if opt in shown:
            i = shown.index(opt)
            del shown[i:i + 2]
    text = report(runs, shown, total, args.report_only)
    if missing:
        text += ("\n## Not run\n\nNo run of " + ", ".join(f"`{m}`" for m in missing)
                 + " yet.\n")
    args.out.write_text(text + "\n")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
