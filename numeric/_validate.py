"""Input validation shared by the public API: arrays in, a clear ValueError out.

Every check names the parameter, the offending value (the first one, with its index for
arrays) and the valid range, so that no function returns NaN for bad input.
"""

from __future__ import annotations

import numpy as np


def _fail(name: str, arr: np.ndarray, bad: np.ndarray, valid: str) -> None:
    if arr.ndim == 0:
        raise ValueError(f"{name} = {arr.item()!r} is out of range; valid: {valid}")
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    where = idx[0] if len(idx) == 1 else idx
    raise ValueError(f"{name}[{where}] = {arr[idx].item()!r} is out of range; valid: {valid}")


def as_float(name: str, value) -> np.ndarray:
    """``value`` as a float array; NaN is refused."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} = {value!r} is not a number or an array of numbers") from exc
    nan = np.isnan(arr)
    if nan.any():
        _fail(name, arr, nan, "a number, not NaN")
    return arr


def positive(name: str, value, *, allow_inf: bool = False) -> np.ndarray:
    """``value > 0`` (and finite unless ``allow_inf``)."""
    arr = as_float(name, value)
    bad = ~(arr > 0) if allow_inf else ~((arr > 0) & np.isfinite(arr))
    if bad.any():
        _fail(name, arr, bad, f"{name} > 0" + ("" if allow_inf else " and finite"))
    return arr


def nonnegative(name: str, value) -> np.ndarray:
    """``0 <= value < inf``."""
    arr = as_float(name, value)
    bad = ~((arr >= 0) & np.isfinite(arr))
    if bad.any():
        _fail(name, arr, bad, f"0 <= {name} < inf")
    return arr


def nonzero(name: str, value, *, allow_inf: bool = True) -> np.ndarray:
    """``value != 0``: a radius of curvature that may be negative (concave) or infinite (flat)."""
    arr = as_float(name, value)
    bad = arr == 0
    if not allow_inf:
        bad |= ~np.isfinite(arr)
    if bad.any():
        flat = ", inf: flat)" if allow_inf else ")"
        _fail(name, arr, bad, f"{name} != 0 (negative: concave{flat}")
    return arr


def poisson(name: str, value) -> np.ndarray:
    """Poisson's ratio, ``-1 < value <= 0.5``."""
    arr = as_float(name, value)
    bad = ~((arr > -1) & (arr <= 0.5))
    if bad.any():
        _fail(name, arr, bad, f"-1 < {name} <= 0.5")
    return arr


def between(name: str, value, lo: float, hi: float, *, lo_open=True, hi_open=True) -> np.ndarray:
    """``lo < value < hi``, each bound open or closed."""
    arr = as_float(name, value)
    ok = (arr > lo if lo_open else arr >= lo) & (arr < hi if hi_open else arr <= hi)
    if not ok.all():
        lo_op, hi_op = ("<" if lo_open else "<="), ("<" if hi_open else "<=")
        _fail(name, arr, ~ok, f"{lo} {lo_op} {name} {hi_op} {hi}")
    return arr


def result(value):
    """Return a NumPy scalar for 0-d results, the array otherwise."""
    arr = np.asarray(value)
    return arr[()] if arr.ndim == 0 else arr


def pow2_scale(x) -> np.ndarray:
    """An even power of 2 within a factor 4 of |x| (1 for x = 0): dividing by it is exact,
    and so is the square root of the quotient, so a homogeneous formula can be evaluated in
    units of it, unchanged to the last bit, without overflow in its squares."""
    _, e = np.frexp(np.asarray(x, dtype=float))
    return np.ldexp(1.0, 2 * ((e - 1) // 2))


def _first_bad(value: np.ndarray, bound: dict) -> tuple[str, str]:
    """The index (as text) of the first non-finite element of ``value`` and its inputs."""
    bad = ~np.isfinite(value)
    idx = tuple(int(i) for i in np.argwhere(bad)[0]) if value.ndim else ()
    parts = []
    for name, v in bound.items():
        arr = np.asarray(v) if not callable(v) else None
        if arr is None or arr.dtype.kind not in "fiu":
            continue
        try:
            item = np.broadcast_to(arr, value.shape)[idx]
        except ValueError:
            item = arr
        parts.append(f"{name} = {float(item) if np.ndim(item) == 0 else item!r}")
    where = "" if not idx else f"[{idx[0] if len(idx) == 1 else idx}]"
    return where, ", ".join(parts)


def representable(func):
    """Decorate a public function whose true result may exceed the float64 range.

    The function runs with floating-point overflow trapped. A result that is +-inf or NaN
    although every input was finite (the true value exceeds 1.8e308) raises OverflowError
    naming the function, the element and its inputs, never a silent inf. An overflow in an
    intermediate that leaves the result finite is reported as the RuntimeWarning NumPy would
    have given (a defect of the printed form, which the domain search turns into a failure).
    """
    import functools
    import inspect
    import warnings

    sig = inspect.signature(func)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        try:
            with np.errstate(over="raise"):
                value = func(*args, **kwargs)
            trapped = None
        except FloatingPointError as exc:
            trapped = exc
            with np.errstate(over="ignore"):
                value = func(*args, **kwargs)
        arr = np.asarray(value, dtype=float)
        if not np.isfinite(arr).all():
            bound = sig.bind(*args, **kwargs)
            bound.apply_defaults()
            where, inputs = _first_bad(arr, bound.arguments)
            raise OverflowError(f"{func.__module__.rsplit('.', 1)[-1]}.{func.__name__}{where}: "
                                f"the result at {inputs} exceeds the float64 range "
                                "(|value| > 1.8e308)")
        if trapped is not None:
            warnings.warn(f"{func.__name__}: {trapped} in an intermediate (result finite)",
                          RuntimeWarning, stacklevel=2)
        return value

    return wrapper
