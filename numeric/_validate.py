"""Input validation shared by the public API: arrays in, a clear ValueError out.

Every check names the parameter, the offending value (the first one, with its index for
arrays) and the valid range, so that no function returns NaN for bad input.

Speed (issue 18): an array is checked by one or two reductions over its bits or its extremes
(no boolean temporaries); only when that check fails are the exact element-wise passes run,
which find the offending element and word the error. :func:`representable` gives a function
whose body is ``return result(gen.NAME(<checked arguments>))`` a path for Python floats that
checks with comparisons and evaluates the generated function's math-module branch: ~1 µs a
call instead of ~15 µs, the same value to an ulp (libm and NumPy's SIMD loops differ in the
last bit), and the same errors, since anything unusual takes the array path.
"""

from __future__ import annotations

import math

import numpy as np

#: the bits of +inf: a float64 viewed as uint64 is finite and >= +0.0 exactly when its bits
#: are below these (a negative number or NaN has the sign bit or an all-ones exponent)
_INF_BITS = np.uint64(0x7FF0000000000000)

#: arrays this small are checked by the exact passes directly (a reduction's fixed cost)
_SMALL = 64


def _fail(name: str, arr: np.ndarray, bad: np.ndarray, valid: str) -> None:
    if arr.ndim == 0:
        raise ValueError(f"{name} = {arr.item()!r} is out of range; valid: {valid}")
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    where = idx[0] if len(idx) == 1 else idx
    raise ValueError(f"{name}[{where}] = {arr[idx].item()!r} is out of range; valid: {valid}")


def _array(name: str, value) -> np.ndarray:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} = {value!r} is not a number or an array of numbers") from exc


def _bits(arr: np.ndarray) -> np.ndarray | None:
    """``arr``'s bits as uint64 for the one-reduction checks, None if it is small."""
    return arr.view(np.uint64) if arr.size > _SMALL else None


def _extremes_within(arr: np.ndarray, lo: float, hi: float, lo_open: bool,
                     hi_open: bool) -> bool:
    """True if every element lies within the bounds, by min and max (NaN propagates into
    both and fails the comparison); False sends the caller to the exact passes."""
    if arr.size <= _SMALL:
        return False
    a, b = arr.min(), arr.max()
    return bool((a > lo if lo_open else a >= lo) and (b < hi if hi_open else b <= hi))


def as_float(name: str, value) -> np.ndarray:
    """``value`` as a float array; NaN is refused."""
    arr = _array(name, value)
    if arr.size > _SMALL and not math.isnan(arr.sum()):  # NaN propagates into the sum
        return arr
    nan = np.isnan(arr)
    if nan.any():
        _fail(name, arr, nan, "a number, not NaN")
    return arr


def positive(name: str, value, *, allow_inf: bool = False) -> np.ndarray:
    """``value > 0`` (and finite unless ``allow_inf``)."""
    arr = _array(name, value)
    bits = _bits(arr)
    # +0.0 has the bits 0; -0.0, negatives and NaN the sign bit or an all-ones exponent
    if bits is not None and bits.min() > 0:
        top = bits.max()
        if top < _INF_BITS or (allow_inf and top == _INF_BITS):
            return arr
    arr = as_float(name, arr)
    bad = ~(arr > 0) if allow_inf else ~((arr > 0) & np.isfinite(arr))
    if bad.any():
        _fail(name, arr, bad, f"{name} > 0" + ("" if allow_inf else " and finite"))
    return arr


def nonnegative(name: str, value) -> np.ndarray:
    """``0 <= value < inf``."""
    arr = _array(name, value)
    bits = _bits(arr)
    if bits is not None and bits.max() < _INF_BITS:  # one pass: sign, NaN, inf (-0.0: below)
        return arr
    arr = as_float(name, arr)
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
    arr = _array(name, value)
    if _extremes_within(arr, -1.0, 0.5, True, False):
        return arr
    arr = as_float(name, arr)
    bad = ~((arr > -1) & (arr <= 0.5))
    if bad.any():
        _fail(name, arr, bad, f"-1 < {name} <= 0.5")
    return arr


def between(name: str, value, lo: float, hi: float, *, lo_open=True, hi_open=True) -> np.ndarray:
    """``lo < value < hi``, each bound open or closed."""
    arr = _array(name, value)
    if _extremes_within(arr, lo, hi, lo_open, hi_open):
        return arr
    arr = as_float(name, arr)
    ok = (arr > lo if lo_open else arr >= lo) & (arr < hi if hi_open else arr <= hi)
    if not ok.all():
        lo_op, hi_op = ("<" if lo_open else "<="), ("<" if hi_open else "<=")
        _fail(name, arr, ~ok, f"{lo} {lo_op} {name} {hi_op} {hi}")
    return arr


def result(value):
    """Return a NumPy scalar for 0-d results, the array otherwise."""
    if type(value) is float:
        return np.float64(value)
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
    fast = _scalar_path(func)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        if fast is not None and not kwargs and len(args) == fast.arity:
            value = fast(*args)
            if value is not None:
                return value
        try:
            with np.errstate(over="raise"):
                value = func(*args, **kwargs)
            trapped = None
        except FloatingPointError as exc:
            trapped = exc
            with np.errstate(over="ignore"):
                value = func(*args, **kwargs)
        arr = np.asarray(value, dtype=float)
        # one pass: a finite sum has finite terms (an overflowing sum: the exact check)
        if not (arr.size > _SMALL and math.isfinite(arr.sum())) and not np.isfinite(arr).all():
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


def scalar_path(func):
    """Decorate a public closed form whose body is ``return result(gen.NAME(<checked
    arguments>))`` (and that is not :func:`representable`): calls on Python floats whose
    result is finite take the scalar path below; every other call runs ``func`` as before.
    A function with another body is returned unchanged."""
    import functools

    fast = _scalar_path(func)
    if fast is None:  # another body: the function as it is (tests/test_scalar_path.py lists
        return func   # the ones that must have the path)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        if not kwargs and len(args) == fast.arity:
            value = fast(*args)
            if value is not None:
                return value
        return func(*args, **kwargs)

    return wrapper


# -- the scalar path of representable() --------------------------------------------------------

def _scalar_check(validator, extra: list, keywords: dict) -> str | None:
    """The condition, on a Python float ``{v}``, that holds exactly where ``validator(name, v,
    *extra, **keywords)`` accepts v (False sends the call to the array path, which words the
    error); None for a check this path does not know."""
    if validator is as_float and not extra and not keywords:
        return "{v} == {v}"
    if validator is positive and not extra and set(keywords) <= {"allow_inf"}:
        return "0.0 < {v}" if keywords.get("allow_inf", False) else "0.0 < {v} < inf"
    if validator is nonnegative and not extra and not keywords:
        return "0.0 <= {v} < inf"
    if validator is poisson and not extra and not keywords:
        return "-1.0 < {v} <= 0.5"
    if validator is between and len(extra) == 2 and set(keywords) <= {"lo_open", "hi_open"}:
        lo, hi = float(extra[0]), float(extra[1])
        if not (math.isfinite(lo) and math.isfinite(hi)):
            return None
        lo_op = "<" if keywords.get("lo_open", True) else "<="
        hi_op = "<" if keywords.get("hi_open", True) else "<="
        return f"{lo!r} {lo_op} {{v}} {hi_op} {hi!r}"
    return None


def _argument_plan(node, func, params: list[str]):
    """(index of the parameter or None, constant, check) for one argument of the generated
    call, or None when it is anything but a parameter, a constant or a checked parameter."""
    import ast

    env = func.__globals__
    if isinstance(node, ast.Name) and node.id in params:
        return params.index(node.id), None, None
    if isinstance(node, ast.Constant) and type(node.value) in (int, float):
        return None, float(node.value), None
    if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)):
        return None
    target = env.get(node.func.id)
    if target in (as_float, positive, nonnegative, poisson, between):
        if (len(node.args) < 2 or not isinstance(node.args[1], ast.Name)
                or node.args[1].id not in params):
            return None
        try:  # the bounds are constants (0.0, np.pi / 2): evaluated once, here
            extra = [eval(compile(ast.Expression(a), "<bound>", "eval"), env)  # noqa: S307
                     for a in node.args[2:]]
            keywords = {k.arg: eval(compile(ast.Expression(k.value), "<bound>", "eval"), env)  # noqa: S307
                        for k in node.keywords}
        except Exception:  # noqa: BLE001 -- not a constant: no scalar path
            return None
        check = _scalar_check(target, extra, keywords)
        return None if check is None else (params.index(node.args[1].id), None, check)
    # a module's one-line helper around a check (cone._theta): its body, with its parameter
    inner = _return_expression(target) if callable(target) else None
    if (inner is not None and len(node.args) == 1 and isinstance(node.args[0], ast.Name)
            and node.args[0].id in params and len(inner[1]) == 1):
        plan = _argument_plan(inner[0], target, inner[1])
        if plan is not None and plan[0] == 0:
            return params.index(node.args[0].id), None, plan[2]
    return None


def _return_expression(func):
    """(the expression of ``func``'s one return statement, its parameter names), or None."""
    import ast
    import inspect
    import textwrap

    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(func)))
    except (OSError, TypeError, SyntaxError):
        return None
    fn = tree.body[0]
    if not isinstance(fn, ast.FunctionDef):
        return None
    body = fn.body[1:] if (isinstance(fn.body[0], ast.Expr)
                           and isinstance(fn.body[0].value, ast.Constant)) else fn.body
    if len(body) != 1 or not isinstance(body[0], ast.Return) or body[0].value is None:
        return None
    a = fn.args
    if a.vararg or a.kwarg or a.kwonlyargs or a.posonlyargs:
        return None
    return body[0].value, [p.arg for p in a.args]


def _scalar_path(func):
    """For a function whose body is ``return result(gen.NAME(<arguments>))``, each argument a
    parameter, a constant or a parameter passed through one of the checks above: a callable
    that takes the call's positional arguments and returns the value when they are all Python
    floats, pass their checks and the generated function's math branch gives a finite float;
    None otherwise (the caller then runs the array path, which words every error). For any
    other body: None, and the function has no scalar path."""
    import ast

    found = _return_expression(func)
    if found is None:
        return None
    expr, params = found
    env = func.__globals__
    if not (isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name)
            and env.get(expr.func.id) is result and len(expr.args) == 1 and not expr.keywords):
        return None
    call = expr.args[0]
    if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
            and isinstance(call.func.value, ast.Name) and not call.keywords):
        return None
    module = env.get(call.func.value.id)
    # the relation's math-module form (``_math_<name>``, printed beside it by the generator)
    generated = getattr(module, f"_math_{call.func.attr}", None)
    if generated is None or getattr(module, "__name__", "").rsplit(".", 1)[-1] != "_generated":
        return None
    plan = [_argument_plan(a, func, params) for a in call.args]
    if any(p is None for p in plan):
        return None
    # the path as source, one line of comparisons (as dataclasses writes __init__): a loop
    # over checks costs more than the whole expression
    names = [f"a{k}" for k in range(len(params))]
    conds = [f"type({v}) is float" for v in names]
    conds += [check.format(v=names[i]) for i, _, check in plan if check is not None]
    call = ", ".join(repr(c) if i is None else names[i] for i, c, _ in plan)
    src = (f"def fast({', '.join(names)}):\n"
           f"    if {' and '.join(conds)}:\n"
           "        try:\n"
           f"            value = generated({call})\n"
           "        except (ArithmeticError, ValueError):  # overflow, ...: the array path\n"
           "            return None\n"
           "        if value - value == 0.0:  # finite\n"
           "            return float64(value)\n"
           "    return None\n")
    scope = {"generated": generated, "float64": np.float64, "inf": math.inf}
    exec(compile(src, f"<scalar path of {func.__qualname__}>", "exec"), scope)  # noqa: S102
    fast = scope["fast"]
    fast.arity = len(params)
    return fast
