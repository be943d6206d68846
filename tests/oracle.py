"""The one mpmath-oracle helper every accuracy test uses.

A test states the argument domains (:class:`Arg`, spanning decades on a log scale), the
reference (a function of mpmath numbers, evaluated inside ``mp.workdps(dps)``), and the
relative tolerance with its reason; :func:`assert_mpmath_equal` samples the domains, compares,
reports the worst point, and records the worst error per function for the summary that
``tests/conftest.py`` prints at the end of the run.
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import itertools
import json
import os
from collections.abc import Callable
from dataclasses import dataclass

import mpmath as mp
import numpy as np

#: worst relative error seen per function name, printed by conftest at the end of the run
WORST: dict[str, float] = {}

FULL = os.environ.get("HERTZMDR_SWEEP", "") == "full"

#: the file of the oracle memo (:func:`memo`): set only by benchmarks/mutation.py, for its
#: mutation runs; unset in every other run, where every reference is computed
MEMO_FILE = os.environ.get("HERTZMDR_ORACLE_MEMO", "")


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


# -- the oracle memo of mutation runs ------------------------------------------------------------
#
# mutmut 3 runs the tests of each mutant in a fresh process forked from one that has only
# collected them, so every mutant recomputed the 30-digit references, which do not depend on the
# mutated module. In a mutation run (HERTZMDR_ORACLE_MEMO names a file; benchmarks/mutation.py
# sets it) a reference decorated with @memo is looked up there by its function (name and source)
# and its exact arguments and working precision; the clean-test pass of the run computes and
# writes each one, the mutants read them. Only for references that are pure functions of their
# arguments and independent of numeric/ (a mutant cannot change them; if it changes their
# arguments, the lookup misses and the reference is computed). Without the variable @memo
# returns the function itself.

_MEMO: dict[str, object] = {}
_MEMO_SIZE = [-1]  # the file's size when last read


def _code(x):
    """A JSON-able exact form of an argument or value: mpf by its binary digits at full
    precision, float by its hex, ints and strings as they are, sequences and dicts
    element-wise; None
    for what has no such form (a callable: that call is not memoized)."""
    if isinstance(x, mp.mpf):
        sign, man, exp, bc = x._mpf_
        return ["mpf", sign, hex(man), exp, bc]
    if isinstance(x, mp.mpc):
        return ["mpc", _code(x.real), _code(x.imag)]
    if isinstance(x, bool | str) or x is None:
        return x
    if isinstance(x, int | np.integer):
        return ["int", int(x)]
    if isinstance(x, float | np.floating):
        return ["float", float(x).hex()]
    if isinstance(x, dict):
        items = _code(list(x.items()))
        return None if items is None else ["dict", items[1]]
    if isinstance(x, list | tuple):
        items = [_code(v) for v in x]
        return None if any(v is None and w is not None for v, w in zip(items, x, strict=True)) \
            else ["tuple" if isinstance(x, tuple) else "list", items]
    return None


def _decode(c):
    if not isinstance(c, list):
        return c
    tag = c[0]
    if tag == "mpf":
        # the stored binary digits as they are (not rounded to the caller's precision: a value
        # made inside a function's mp.workdps keeps its digits after it returns)
        return mp.make_mpf((c[1], mp.libmp.MPZ(int(c[2], 16)), c[3], c[4]))
    if tag == "mpc":
        return mp.mpc(_decode(c[1]), _decode(c[2]))
    if tag == "int":
        return c[1]
    if tag == "float":
        return float.fromhex(c[1])
    items = [_decode(v) for v in c[1]]
    if tag == "dict":
        return dict(items)
    return tuple(items) if tag == "tuple" else items


def _read_memo() -> None:
    try:
        size = os.path.getsize(MEMO_FILE)
    except OSError:
        return
    if size == _MEMO_SIZE[0]:
        return
    with open(MEMO_FILE) as fh:
        for line in fh:
            try:  # a line cut short (a mutant's run stopped mid-write) is skipped
                row = json.loads(line)
                _MEMO[row["key"]] = row["value"]
            except (ValueError, KeyError):
                continue
    _MEMO_SIZE[0] = size


def memo(func: Callable) -> Callable:
    """``func`` memoized on disk during a mutation run (see above), else ``func`` itself."""
    if not MEMO_FILE:
        return func
    try:  # its source text (a changed reference is a new one), else its bytecode
        text = inspect.getsource(func).encode()
    except (OSError, TypeError):
        text = func.__code__.co_code
    source = hashlib.sha256(text).hexdigest()[:16]
    name = f"{func.__module__}.{func.__qualname__}:{source}"

    @functools.wraps(func)
    def memoized(*args, **kwargs):
        code = _code([list(args), sorted(kwargs.items())])
        if code is None:
            return func(*args, **kwargs)
        key = json.dumps([name, mp.mp.prec, code])
        if key not in _MEMO:
            _read_memo()
        if key in _MEMO:
            return _decode(_MEMO[key])
        value = func(*args, **kwargs)
        stored = _code(value)
        if stored is not None:
            _MEMO[key] = stored
            with open(MEMO_FILE, "a") as fh:  # one line per value, appended
                fh.write(json.dumps({"key": key, "value": stored}) + "\n")
        return value

    return memoized
