"""Fit many force curves (a force map, a folder of curves) in parallel, one result per curve.

:func:`fit_curves` fits each curve with :func:`hertzmdr.numeric.fit.fit_curve` (with
``adhesion=True``, :func:`hertzmdr.numeric.fit_adhesive.fit_curve`: a retract curve's work of
adhesion as a fifth parameter) and the same tip, over worker processes; a curve that cannot be
fitted (no contact, too few points, any error) is one :class:`CurveFit` with its message, never
an exception of the batch. :func:`write_table` writes the per-curve results as CSV; the figures
(the modulus map) are in :mod:`hertzmdr.numeric.fit_io`.
"""

from __future__ import annotations

import math
import multiprocessing
import os
import time
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from hertzmdr.numeric import fit
from hertzmdr.numeric._validate import positive

__all__ = ["Curve", "CurveFit", "fit_curves", "write_table", "TABLE_COLUMNS"]

#: curves per task sent to a worker process at least (fewer tasks: less pickling overhead)
MIN_CHUNK = 4
#: tasks per worker (more: a smoother progress bar and a better balance of slow curves)
TASKS_PER_WORKER = 16
#: below this many curves the batch runs in this process (starting workers costs more)
MIN_PARALLEL = 32


@dataclass(frozen=True)
class Curve:
    """One force curve of a batch: its name, its position on the sample [m] (None when the
    batch has no positions), positions z [m] and forces F [N]."""

    name: str
    x: float | None
    y: float | None
    z: np.ndarray
    F: np.ndarray


@dataclass(frozen=True)
class CurveFit:
    """The fit of one curve of a batch, without its arrays (cheap to send between processes).

    ``values``/``errors`` are (E* [Pa], z_0 [m], F_0 [N], s_0 [N/m]) and their standard errors
    (NaN when the fit failed); ``error`` is the message of a failed fit, else None;
    ``dgamma``/``dgamma_error``: the work of adhesion [J/m^2] and its standard error of an
    adhesive fit (None without adhesion; NaN when it failed).
    """

    name: str
    x: float | None
    y: float | None
    values: tuple[float, ...]
    errors: tuple[float, ...]
    corr_E_z0: float
    E: float | None
    E_error: float | None
    reduced_chi2: float
    n_points: int
    n_contact: int
    max_depth: float
    warnings: tuple[str, ...]
    error: str | None
    dgamma: float | None = None
    dgamma_error: float | None = None

    @property
    def ok(self) -> bool:
        return self.error is None


def _failed(curve: Curve, message: str, adhesion: bool = False) -> CurveFit:
    nan4 = (math.nan,) * 4
    dg = math.nan if adhesion else None
    return CurveFit(curve.name, curve.x, curve.y, nan4, nan4, math.nan, None, None, math.nan,
                    int(np.size(curve.z)), 0, math.nan, (), message, dg, dg)


def _one_line(exc: BaseException) -> str:
    """An exception as a failed curve's message: a ValueError's text (the validators' own
    messages), else its type and text; its first line only."""
    msg = str(exc) if isinstance(exc, ValueError) else f"{type(exc).__name__}: {exc}"
    return msg.splitlines()[0] if msg else type(exc).__name__


#: the adhesive fit's parameters (E*, z_0, Delta gamma, F_0, s_0) that CurveFit.values holds
_ADHESIVE_BASE = [0, 1, 3, 4]


def _fit_one(curve: Curve, tip, options: dict) -> CurveFit:
    options = dict(options)
    adhesion = options.pop("adhesion", False)
    try:
        if adhesion:
            from hertzmdr.numeric import fit_adhesive

            r = fit_adhesive.fit_curve(curve.z, curve.F, tip, **options)
        else:
            r = fit.fit_curve(curve.z, curve.F, tip, **options)
    except Exception as exc:  # noqa: BLE001 -- one curve's failure is its row, not the batch's
        return _failed(curve, _one_line(exc), adhesion)
    keep = _ADHESIVE_BASE if adhesion else slice(None)
    dg, dg_err = (float(r.values[2]), float(r.errors[2])) if adhesion else (None, None)
    return CurveFit(curve.name, curve.x, curve.y, tuple(map(float, r.values[keep])),
                    tuple(map(float, r.errors[keep])), float(r.correlation[0, 1]), r.E,
                    r.E_error, r.reduced_chi2, int(r.F.size), r.n_contact, r.max_depth,
                    r.warnings, None, dg, dg_err)


def _fit_chunk(curves: Sequence[Curve], tip, options: dict) -> list[CurveFit]:
    return [_fit_one(c, tip, options) for c in curves]


def _submit(pool, *args) -> Future:
    """A chunk's task; a pool broken before it was sent (a worker that died) gives a future
    holding that error, failed like the tasks the pool had."""
    try:
        return pool.submit(_fit_chunk, *args)
    except BrokenProcessPool as exc:
        fut = Future()
        fut.set_exception(exc)
        return fut


def fit_curves(curves: Sequence[Curve], tip, *, nu=None, tip_modulus=None, tip_nu=None,
               z0=None, sigma=None, fixed_z0=None, fixed_baseline=None, adhesion=False,
               workers: int | None = None,
               progress: Callable[[int, int, int], None] | None = None) -> list[CurveFit]:
    """Fit every curve with the same tip and options, in parallel; one result per curve.

    Parameters
    ----------
    curves : sequence of Curve
        The curves (positions z [m], forces F [N]).
    tip, nu, tip_modulus, tip_nu, z0, sigma, fixed_z0, fixed_baseline
        As :func:`hertzmdr.numeric.fit.fit_curve` (sigma [N] one number for every curve; a
        fixed contact point [m] or baseline (F_0 [N], s_0 [N/m]) the same for every curve).
    adhesion : bool
        Fit each curve as an adhesive retract curve
        (:func:`hertzmdr.numeric.fit_adhesive.fit_curve`: the work of adhesion as a fifth
        parameter, in each result's ``dgamma``); not with a fixed contact point or baseline.
    workers : int, optional
        Worker processes, >= 1 (default: the machine's cores). Batches of fewer than 32
        curves, and ``workers = 1``, run in this process.
    progress : callable, optional
        Called as ``progress(done, total, failed)`` after each finished group of curves.

    Returns
    -------
    list of CurveFit
        In the order of ``curves``; a curve that could not be fitted has ``error`` set (its
        message, one line) and NaN values; so has each curve of a worker process that ended
        abruptly (killed, out of memory: ``BrokenProcessPool: ...``), never the batch.

    Raises
    ------
    ValueError
        For an option every curve shares (workers, nu, tip_modulus, tip_nu, sigma, fixed_z0,
        fixed_baseline, a tip without an adhesive model): one message for the batch, before
        any curve is fitted.
    """
    if workers is None:
        workers = os.cpu_count() or 1
    if isinstance(workers, np.integer):  # a count from numpy is a count
        workers = int(workers)
    if not (isinstance(workers, int) and not isinstance(workers, bool) and workers >= 1):
        raise ValueError(f"workers = {workers!r} is out of range; valid: an integer >= 1")
    options = {"nu": nu, "tip_modulus": tip_modulus, "tip_nu": tip_nu, "z0": z0, "sigma": sigma}
    if adhesion:
        from hertzmdr.numeric import fit_adhesive

        if fixed_z0 is not None or fixed_baseline is not None:
            raise ValueError("fixed_z0/fixed_baseline with adhesion = True: the adhesive fit "
                             "fits all five parameters; valid only without adhesion")
        fit_adhesive._check_tip(tip)  # one message for the batch, not one per curve
        options["adhesion"] = True
    else:
        fit._fixed_values(fixed_z0, fixed_baseline)  # checked once, as below
        options.update(fixed_z0=fixed_z0, fixed_baseline=fixed_baseline)
    # the options every curve shares, checked once: one message for the batch, not one per
    # curve (the moduli's were checked only after each curve's fit, every curve fitted first)
    fit._sample_modulus(0.0, 0.0, nu, tip_modulus, tip_nu)  # E* = 0: any tip is stiffer
    if sigma is not None:
        positive("sigma", sigma)
    total = len(curves)
    if total == 0:
        return []
    results: list[CurveFit | None] = [None] * total
    failed = 0
    if workers == 1 or total < MIN_PARALLEL:
        step = max(1, total // 100)
        for k, c in enumerate(curves):
            results[k] = _fit_one(c, tip, options)
            failed += not results[k].ok
            if progress is not None and ((k + 1) % step == 0 or k + 1 == total):
                progress(k + 1, total, failed)
        return results
    size = max(MIN_CHUNK, math.ceil(total / (workers * TASKS_PER_WORKER)))
    starts = range(0, total, size)
    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else None)
    done = 0
    with ProcessPoolExecutor(max_workers=workers, mp_context=ctx) as pool:
        futures = {_submit(pool, curves[s:s + size], tip, options): s for s in starts}
        for fut in as_completed(futures):
            s = futures[fut]
            try:
                chunk = fut.result()
            except Exception as exc:  # noqa: BLE001 -- a worker that died (killed, out of
                # memory; BrokenProcessPool) or a task that could not be sent: its curves fail
                chunk = [_failed(c, _one_line(exc), bool(options.get("adhesion")))
                         for c in curves[s:s + size]]
            results[s:s + len(chunk)] = chunk
            done += len(chunk)
            failed += sum(not r.ok for r in chunk)
            if progress is not None:
                progress(done, total, failed)
    return results


class ProgressBar:
    """A one-line progress bar on a text stream: ``fitting [#####.....] 512/1024 curves, 3
    failed, 4.1 s``; redrawn at most 10 times a second, ended with a newline at the end."""

    def __init__(self, stream, width: int = 30):
        self.stream, self.width = stream, width
        self.t0 = time.perf_counter()
        self.last = -math.inf  # never drawn: the first call draws, whatever the clock's origin

    def __call__(self, done: int, total: int, failed: int) -> None:
        now = time.perf_counter()
        if done < total and now - self.last < 0.1:
            return
        self.last = now
        n = round(self.width * done / total)
        self.stream.write(f"\rfitting [{'#' * n}{'.' * (self.width - n)}] {done}/{total} "
                          f"curves, {failed} failed, {now - self.t0:.1f} s")
        if done == total:
            self.stream.write("\n")
        self.stream.flush()


#: the columns of the per-curve table, with their units
TABLE_COLUMNS = ("curve", "x [m]", "y [m]", "E_star [Pa]", "E_star_err [Pa]", "z_0 [m]",
                 "z_0_err [m]", "F_0 [N]", "F_0_err [N]", "s_0 [N/m]", "s_0_err [N/m]", "E [Pa]",
                 "E_err [Pa]", "corr_E_z0", "reduced_chi2", "points", "in_contact",
                 "max_depth [m]", "status", "message")


#: the columns an adhesive batch adds after s_0_err [N/m]
ADHESIVE_COLUMNS = ("dgamma [J/m^2]", "dgamma_err [J/m^2]")


def write_table(results: Sequence[CurveFit], path) -> Path:
    """The per-curve results as CSV (UTF-8, SI units in the header; empty cells where a value
    does not exist: no position, no Poisson's ratio, a failed fit). ``status`` is ``ok``,
    ``warning`` (the warnings in ``message``, joined by `` | ``) or ``failed``. An adhesive
    batch (any result with ``dgamma``) has the ADHESIVE_COLUMNS after ``s_0_err``."""
    import csv

    def num(v):
        return "" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.10g}"

    path = Path(path)
    adhesive = any(r.dgamma is not None for r in results)
    k = TABLE_COLUMNS.index("s_0_err [N/m]") + 1
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(TABLE_COLUMNS[:k] + ADHESIVE_COLUMNS + TABLE_COLUMNS[k:] if adhesive
                   else TABLE_COLUMNS)
        for r in results:
            pairs = [x for v, e in zip(r.values, r.errors, strict=True) for x in (num(v), num(e))]
            if adhesive:
                pairs += [num(r.dgamma), num(r.dgamma_error)]
            status = "failed" if not r.ok else ("warning" if r.warnings else "ok")
            message = r.error if not r.ok else " | ".join(r.warnings)
            w.writerow([r.name, num(r.x), num(r.y), *pairs, num(r.E), num(r.E_error),
                        num(r.corr_E_z0), num(r.reduced_chi2), r.n_points, r.n_contact,
                        num(r.max_depth), status, message])
    return path
