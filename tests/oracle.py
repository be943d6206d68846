"""The one mpmath-oracle helper every accuracy test uses.

A test states the argument domains (:class:`Arg`, spanning decades on a log scale), the
reference (a function of mpmath numbers, evaluated inside ``mp.workdps(dps)``), and the
relative tolerance with its reason; :func:`assert_mpmath_equal` samples the domains, compares,
reports the worst point, and records the worst error per function for the summary that
``tests/conftest.py`` prints at the end of the run.
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Callable
from dataclasses import dataclass

import mpmath as mp
import numpy as np

#: worst relative error seen per function name, printed by conftest at the end of the run
WORST: dict[str, float] = {}

FULL = os.environ.get("HERTZMDR_SWEEP", "") == "full"


def n_points(full: int, ci: int) -> int:
    """Points of a sweep: ``full`` with HERTZMDR_SWEEP=full, else ``ci`` (the default runs)."""
    return full if FULL else ci


@dataclass(frozen=True)
class Arg:
    """A domain [lo, hi] of one argument, sampled log-uniformly unless ``log=False``."""

    lo: float
    hi: float
    log: bool = True

    def sample(self, u: np.ndarray) -> np.ndarray:
        if self.log:
            return np.exp(np.log(self.lo) + u * (np.log(self.hi) - np.log(self.lo)))
        return self.lo + u * (self.hi - self.lo)


def sample(domains: dict[str, Arg], n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """The corners of the box (up to 16) plus a Latin-hypercube sample of ``n`` points."""
    rng = np.random.default_rng(seed)
    names = list(domains)
    k = len(names)
    u = (rng.permuted(np.tile(np.arange(n), (k, 1)), axis=1).T + rng.random((n, k))) / n
    corners = np.array(list(itertools.product((0.0, 1.0), repeat=k)))[:16] if k <= 4 else None
    if corners is not None:
        u = np.vstack([corners, u])
    return {name: domains[name].sample(u[:, i]) for i, name in enumerate(names)}


def rel_error(value: float, ref: mp.mpf) -> float:
    if ref == 0:
        return abs(float(value))
    return float(abs((mp.mpf(float(value)) - ref) / ref))


def assert_mpmath_equal(
    func: Callable[..., np.ndarray],
    reference: Callable[..., mp.mpf],
    domains: dict[str, Arg],
    *,
    rtol: float,
    n: int = 20,
    dps: int = 50,
    name: str | None = None,
    seed: int = 0,
) -> float:
    """Compare the float64 ``func`` with the mpmath ``reference`` over ``domains``.

    ``func`` is called once with arrays (keyword arguments named as in ``domains``);
    ``reference`` once per point with mpmath numbers made from the same float64 inputs, inside
    ``mp.workdps(dps)``. Returns the worst relative error; fails if it exceeds ``rtol``.
    """
    pts = sample(domains, n, seed)
    got = np.broadcast_to(np.asarray(func(**pts), dtype=float), next(iter(pts.values())).shape)
    worst, where = 0.0, None
    with mp.workdps(dps):
        for i in range(got.size):
            args = {k: mp.mpf(float(v[i])) for k, v in pts.items()}
            err = rel_error(got[i], reference(**args))
            if not np.isfinite(got[i]):
                err = np.inf
            if err > worst:
                worst, where = err, {k: float(v[i]) for k, v in pts.items()}
    key = name or getattr(func, "__name__", "?")
    WORST[key] = max(WORST.get(key, 0.0), worst)
    assert worst <= rtol, f"{key}: relative error {worst:.3g} > {rtol:.3g} at {where}"
    return worst


def assert_close(value, ref, rtol: float, what: str = "") -> float:
    """Relative comparison of one number with an mpmath reference; returns the error."""
    err = float(abs((mp.mpf(value) - ref) / ref)) if ref != 0 else float(abs(mp.mpf(value)))
    assert err <= rtol, f"{what}: relative error {err:.3g} > {rtol:.3g} ({value} vs {ref})"
    return err
