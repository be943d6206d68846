"""One timing mechanism for the benchmarks (``benchmarks/``) and ``hertzmdr accuracy``.

Every script times by :func:`measure` (one callable) or :func:`compare` (several, their rounds
interleaved so that the load of a shared machine falls on all of them alike), and records the
conditions with :func:`conditions`. A :class:`Timing` keeps the first call apart from the
repeated ones (a first call builds caches and imports modules); the repeated calls are grouped
in rounds of ``number`` calls, ``number`` chosen so that all rounds together take at least
``Budget.min_time``. Where peers are compared, the scripts report :func:`ratio` of medians, which
the noise of the machine moves much less than the times themselves.

:func:`in_fork` runs a function in a forked child process: the child has every module the
parent imported, and whatever it caches dies with it, so a first call measured there is a
first call whatever the parent had computed before (no private cache has to be cleared).
"""

from __future__ import annotations

import math
import os
import platform
import statistics
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass

#: the environment variables that set the threads of the BLAS and OpenMP libraries
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


@dataclass(frozen=True)
class Budget:
    """How much measuring: ``repeats`` rounds taking at least ``min_time`` seconds in all; no
    new round once the rounds have taken ``max_time`` seconds (a slow call gets fewer rounds,
    at least one)."""

    repeats: int
    min_time: float
    max_time: float = math.inf

    def __post_init__(self):
        if self.repeats < 1:
            raise ValueError(f"Budget.repeats = {self.repeats}: at least 1")
        if not self.min_time >= 0:
            raise ValueError(f"Budget.min_time = {self.min_time} s: must be >= 0")
        if not self.max_time > self.min_time:
            raise ValueError(f"Budget.max_time = {self.max_time} s: must exceed min_time = "
                             f"{self.min_time} s")


#: the reports' setting: the median of 5 rounds of at least 0.1 s together (fewer rounds for
#: calls slower than 0.2 s: no new round after 1 s)
FULL = Budget(repeats=5, min_time=0.1, max_time=1.0)
#: the ``--quick`` runs of the tests: two rounds of one call each (numbers, not timings)
QUICK = Budget(repeats=2, min_time=0.0)


@dataclass(frozen=True)
class Timing:
    """Seconds of one measured callable.

    ``first`` is the first call, timed alone; ``rounds`` holds the time per call of each
    round of ``number`` repeated calls.
    """

    first: float
    rounds: tuple[float, ...]
    number: int

    @property
    def best(self) -> float:
        return min(self.rounds)

    @property
    def median(self) -> float:
        return statistics.median(self.rounds)

    @property
    def spread(self) -> tuple[float, float]:
        return min(self.rounds), max(self.rounds)

    def quantile(self, q: float) -> float:
        """The q-quantile (0 <= q <= 1) of the rounds, linearly interpolated."""
        if not 0 <= q <= 1:
            raise ValueError(f"quantile q = {q}: must lie in [0, 1]")
        s = sorted(self.rounds)
        pos = q * (len(s) - 1)
        lo = math.floor(pos)
        hi = min(lo + 1, len(s) - 1)
        return s[lo] + (pos - lo) * (s[hi] - s[lo])


def _clock(fn: Callable[[], object], number: int) -> float:
    t0 = time.perf_counter()
    for _ in range(number):
        fn()
    return (time.perf_counter() - t0) / number


def _plan(fn: Callable[[], object], budget: Budget) -> tuple[float, int]:
    """Time the first call, then choose the calls per round from a second, warm call."""
    first = _clock(fn, 1)
    if budget.min_time == 0:
        return first, 1
    warm = max(_clock(fn, 1), 1e-7)
    return first, max(1, math.ceil(budget.min_time / budget.repeats / warm))


def measure(fn: Callable[..., object], budget: Budget = FULL,
            setup: Callable[[], object] | None = None) -> Timing:
    """Time ``fn()``: its first call, then ``budget.repeats`` rounds of repeated calls.

    With ``setup``, every call is ``fn(setup())`` and only ``fn`` is timed: a first call on a
    fresh object each time (a new profile's first depth, say); each round is then one call,
    and there are as many rounds as ``budget`` asks for (at least ``repeats``, at least
    ``min_time`` seconds of calls).
    """
    if setup is None:
        first, number = _plan(fn, budget)
        rounds = []
        while len(rounds) < budget.repeats and number * sum(rounds) < budget.max_time:
            rounds.append(_clock(fn, number))
        return Timing(first, tuple(rounds), number)

    def once():
        arg = setup()
        t0 = time.perf_counter()
        fn(arg)
        return time.perf_counter() - t0

    first = once()
    rounds: list[float] = []
    while (len(rounds) < budget.repeats or sum(rounds) < budget.min_time) and (
            sum(rounds) < budget.max_time or not rounds):
        rounds.append(once())
    return Timing(first, tuple(rounds), 1)


def timed(fn: Callable[[], object]) -> tuple[object, float]:
    """One call, timed: ``(fn(), seconds)``, for calls too expensive to repeat (a large grid's
    solve in a convergence study); its result is used, not thrown away."""
    t0 = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - t0


def cpu_best(fn: Callable[[], object], rounds: int = 3) -> float:
    """The least CPU time [s] of this process over ``rounds`` calls (``time.process_time``;
    single-threaded numpy): what a quiet machine's wall time would be, which a shared
    machine's wall time (:func:`measure`) overstates by the load."""
    best = math.inf
    for _ in range(rounds):
        t0 = time.process_time()
        fn()
        best = min(best, time.process_time() - t0)
    return best


def compare(fns: Mapping[str, Callable[[], object]], budget: Budget = FULL) -> dict[str, Timing]:
    """Time several callables with their rounds interleaved (round 1 of each, round 2 of each,
    ...), so that a change of the machine's load affects all of them alike."""
    plans = {name: _plan(fn, budget) for name, fn in fns.items()}
    rounds: dict[str, list[float]] = {name: [] for name in fns}
    for _ in range(budget.repeats):
        spent = [plans[n][1] * sum(rounds[n]) for n in fns]
        if rounds[next(iter(fns))] and max(spent) >= budget.max_time:
            break
        for name, fn in fns.items():
            rounds[name].append(_clock(fn, plans[name][1]))
    return {name: Timing(plans[name][0], tuple(rounds[name]), plans[name][1]) for name in fns}


def ratio(a: Timing, b: Timing) -> float:
    """a's median time over b's: > 1 when a is slower."""
    return a.median / b.median


def in_fork(fn: Callable[..., object], *args, **kwargs):
    """``fn(*args, **kwargs)`` in a forked child process (POSIX); its result is returned (it
    must pickle; ``fn`` itself need not), everything it cached is discarded with the child. An
    exception in the child is raised here as a RuntimeError with its traceback. Where fork
    does not exist, ``fn`` runs in this process."""
    import multiprocessing as mp
    import traceback

    if "fork" not in mp.get_all_start_methods():
        return fn(*args, **kwargs)
    ctx = mp.get_context("fork")
    receive, send = ctx.Pipe(duplex=False)

    def child():
        try:
            send.send((True, fn(*args, **kwargs)))
        except BaseException:  # noqa: BLE001 -- reported to the parent, which raises
            send.send((False, traceback.format_exc()))
        finally:
            send.close()

    proc = ctx.Process(target=child)
    proc.start()
    send.close()
    try:
        ok, value = receive.recv()
    except EOFError:
        proc.join()
        raise RuntimeError(f"in_fork: the child died (exit code {proc.exitcode})") from None
    proc.join()
    if not ok:
        raise RuntimeError(f"in_fork: the child raised\n{value}")
    return value


def blas_threads() -> str:
    """The thread settings of the BLAS/OpenMP libraries, as the environment gives them."""
    set_ = [f"{v} = {os.environ[v]}" for v in THREAD_VARIABLES if v in os.environ]
    return ", ".join(set_) if set_ else (
        f"no thread variable set (the libraries' default, up to {os.cpu_count()} threads)")


def machine() -> str:
    """CPU, cores, Python and the numerical libraries' versions, in one line."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    import mpmath
    import numpy
    import scipy

    return (f"{cpu}, {os.cpu_count()} cores; Python {platform.python_version()}, "
            f"NumPy {numpy.__version__}, SciPy {scipy.__version__}, mpmath {mpmath.__version__} "
            f"(backend {mpmath.libmp.BACKEND}); {platform.system()} {platform.release()}")


def conditions() -> str:
    """The line every report prints: the machine and the thread settings."""
    return f"Measured on: {machine()}; {blas_threads()}."
