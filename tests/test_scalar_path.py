"""The fast paths of issue 18: Python floats through the generated functions' math branch and
the public functions' scalar path, and the one-reduction checks of large arrays. Each must give
what the array path gives: the same values (to the last bits in which libm and NumPy's SIMD
loops differ) and the same errors, word for word."""

import inspect
import math
import random
import zlib

import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import bodies, cone, contact, hertz, impact, line, powerlaw, tangential
from hertzmdr.numeric._validate import (
    _scalar_path,
    between,
    nonnegative,
    poisson,
    positive,
)

MODULES = (hertz, cone, line, powerlaw, bodies, contact, impact, tangential)


def _public(module):
    return [(f"{module.__name__.rsplit('.', 1)[-1]}.{name}", f)
            for name, f in inspect.getmembers(module, inspect.isfunction)
            if f.__module__ == module.__name__ and not name.startswith("_")]


def _with_branch():
    """The generated functions with a math branch (the printer gave one to every expression
    the math module can evaluate)."""
    return [name for name in gen.__all__
            if "the scalar path" in inspect.getsource(getattr(gen, name))]


def test_most_generated_functions_have_a_math_branch():
    # only hypergeometric and elliptic functions (SciPy) have no math-module form, and the
    # constants (a force law's exponent: no argument, nothing to branch on)
    names = _with_branch()
    assert len(names) > 0.7 * len(gen.__all__), (len(names), len(gen.__all__))
    for name in set(gen.__all__) - set(names):
        f = getattr(gen, name)
        assert ("scipy.special" in inspect.getsource(f)
                or not inspect.signature(f).parameters), name


@pytest.mark.parametrize("name", _with_branch())
def test_math_branch_agrees_with_the_numpy_form(name):
    """At 3 points inside the usual domain (those of test_generated's printer check): the math
    branch returns a Python float within 1e-13 of the NumPy form on 0-d arrays. They are the
    same expression; libm and NumPy's AVX-512 loops each round pow, asin, exp, ... within an
    ulp but not always to the same bit, and a stable form's conditioning stays below ~1e2."""
    f = getattr(gen, name)
    params = list(inspect.signature(f).parameters)
    rng = random.Random(zlib.crc32(name.encode()))
    for _ in range(3):
        args = [rng.uniform(0.05, 0.45) if p.startswith("nu")
                else rng.uniform(0.05, 0.95) if p in ("eta", "chi", "t") or p.startswith("t_")
                else rng.uniform(0.05, 1.5) if p == "theta"
                else rng.uniform(0.5, 3.0) for p in params]
        with np.errstate(all="ignore"):
            ref = np.asarray(f(*[np.asarray(a) for a in args]), dtype=float)
        if ref.ndim or not np.isfinite(ref):  # outside the relation's domain at this point
            continue
        got = f(*args)
        if type(got) is not float:  # the math module raised: the NumPy form ran instead
            assert float(got) == float(ref) or (math.isnan(got) and math.isnan(ref))
            continue
        assert abs(got - float(ref)) <= 1e-13 * abs(float(ref)) + 1e-300, (name, args)


#: the public closed forms that take the scalar path (its detection must not silently stop)
FAST = {
    "hertz": {"contact_radius", "max_pressure", "mean_pressure", "force", "energy",
              "stiffness", "depth_from_force", "contact_radius_from_force",
              "max_pressure_from_force"},
    "cone": {"contact_radius", "depth", "force", "mean_pressure", "stiffness",
             "depth_from_force", "contact_radius_from_force"},
    "line": {"half_width", "force", "depth_from_force", "half_width_from_force",
             "max_pressure", "max_pressure_from_force", "stiffness"},
    "bodies": {"gaussian_radius", "crossed_cylinders_gaussian_radius", "gaussian_approx_area",
               "gaussian_approx_force", "gaussian_approx_max_pressure",
               "gaussian_approx_depth_from_force"},
    "powerlaw": {"force_from_radius"},
    "contact": {"stiffness", "punch_force", "punch_depth_from_force"},
    "impact": {"sphere_mass"},
    "tangential": {"shear_modulus", "stiffness", "stiffness_ratio"},
}


def test_the_closed_forms_have_a_scalar_path():
    for module in MODULES:
        short = module.__name__.rsplit(".", 1)[-1]
        found = {name.split(".")[1] for name, f in _public(module)
                 if hasattr(f, "__wrapped__") and _scalar_path(f.__wrapped__) is not None}
        assert FAST.get(short, set()) <= found, (short, FAST[short] - found)


def _fast_functions():
    return [(name, f) for module in MODULES for name, f in _public(module)
            if name.split(".")[1] in FAST.get(name.split(".")[0], set())]


def _valid_args(f, rng):
    args = []
    for p in inspect.signature(f).parameters:
        if p in ("theta", "alpha"):
            args.append(rng.uniform(0.1, 1.4))
        elif p == "n":
            args.append(rng.uniform(0.5, 4.0))
        else:
            args.append(rng.uniform(1e-3, 2.0) * 10.0 ** rng.randint(-6, 6))
    return args


@pytest.mark.parametrize("name, f", _fast_functions())
def test_scalar_and_array_paths_give_the_same_values(name, f):
    """Python floats (the scalar path) against the same values as 1-element arrays (the array
    path): a NumPy float64 within 1e-13 (the math branch against NumPy's loops, as above)."""
    rng = random.Random(zlib.crc32(name.encode()))
    for _ in range(5):
        args = _valid_args(f, rng)
        try:
            ref = f(*[np.array([a]) for a in args])
        except (ValueError, OverflowError):
            continue  # this draw lies outside the function's domain (e.g. a > R)
        got = f(*args)
        assert type(got) is np.float64, (name, type(got))
        assert abs(float(got) - float(ref[0])) <= 1e-13 * abs(float(ref[0])), (name, args)


@pytest.mark.parametrize("name, f", _fast_functions())
def test_scalar_and_array_paths_give_the_same_errors(name, f):
    """Each argument in turn set to a bad value: the scalar path raises what the 0-d array
    path raises, word for word (it hands every such call to the array path)."""
    rng = random.Random(zlib.crc32(name.encode()))
    base = _valid_args(f, rng)
    for k in range(len(base)):
        for bad in (-1.0, 0.0, math.nan, math.inf, -math.inf, 1e300, 4.0):
            args = list(base)
            args[k] = bad
            outcomes = []
            for call in (args, [np.asarray(a) for a in args]):
                try:
                    outcomes.append(("value", float(f(*call))))
                except (ValueError, OverflowError, RuntimeWarning) as exc:  # warnings: errors
                    outcomes.append((type(exc).__name__, str(exc)))
            assert outcomes[0] == outcomes[1], (name, k, bad)


def test_scalar_path_handles_ints_and_keywords_by_the_array_path():
    assert hertz.force(1, 2, 3) == hertz.force(1.0, 2.0, 3.0)
    assert hertz.force(d=1e-6, R=0.01, E_star=1e9) == hertz.force(1e-6, 0.01, 1e9)
    with pytest.raises(ValueError, match=r"^d = -1\.0 is out of range; valid: 0 <= d < inf$"):
        hertz.force(-1.0, 0.01, 1e9)
    with pytest.raises(OverflowError, match="exceeds the float64 range"):
        hertz.force(1e300, 1e300, 1e300)


# -- the one-reduction checks of large arrays (more than 64 elements) --------------------------

TINY = 5e-324


def _message(func, *args, **kwargs):
    try:
        func(*args, **kwargs)
    except ValueError as exc:
        return str(exc)
    return None


@pytest.mark.parametrize("bad, message", [
    (-TINY, "d[70] = -5e-324 is out of range; valid: 0 <= d < inf"),
    (math.inf, "d[70] = inf is out of range; valid: 0 <= d < inf"),
    (math.nan, "d[70] = nan is out of range; valid: a number, not NaN"),
    (-math.inf, "d[70] = -inf is out of range; valid: 0 <= d < inf"),
])
def test_large_array_checks_find_the_element(bad, message):
    arr = np.linspace(0.0, 1.0, 100)
    arr[70] = bad
    assert _message(nonnegative, "d", arr) == message


def test_large_array_checks_at_both_sides_of_their_bounds():
    arr = np.full(100, 0.5)
    arr[3] = -0.0  # -0.0 >= 0: accepted (its sign bit sends it to the exact pass)
    assert nonnegative("d", arr)[3] == 0.0
    arr[3] = TINY
    assert positive("R", arr)[3] == TINY
    arr[3] = 0.0
    assert _message(positive, "R", arr) == "R[3] = 0.0 is out of range; valid: R > 0 and finite"
    arr[3] = math.inf
    assert positive("R", arr, allow_inf=True)[3] == math.inf
    assert _message(positive, "R", arr) == "R[3] = inf is out of range; valid: R > 0 and finite"
    arr[3] = -math.inf
    assert _message(positive, "R", arr, allow_inf=True) == (
        "R[3] = -inf is out of range; valid: R > 0")
    arr[3] = 0.5
    assert poisson("nu", arr)[3] == 0.5
    arr[3] = float(np.nextafter(0.5, 1.0))
    assert _message(poisson, "nu", arr) == (
        "nu[3] = 0.5000000000000001 is out of range; valid: -1 < nu <= 0.5")
    arr[3] = math.nan
    assert _message(between, "t", arr, 0.0, 1.0) == (
        "t[3] = nan is out of range; valid: a number, not NaN")
    arr[3] = 1.0
    assert between("t", arr, 0.0, 1.0, hi_open=False)[3] == 1.0
    assert _message(between, "t", arr, 0.0, 1.0) == (
        "t[3] = 1.0 is out of range; valid: 0.0 < t < 1.0")


def test_large_result_check():
    """A finite result whose sum overflows is not an error; a non-finite element is, by name."""
    d = np.full(100, 1.0)
    F = hertz.force(d, 1e300, 1e8)  # each 1.3e158: their sum is finite
    assert np.all(np.isfinite(F))
    d[42] = 1e250
    with pytest.raises(OverflowError, match=r"hertz\.force\[42\]: the result at d = 1e\+250"):
        hertz.force(d, 1e300, 1e8)
    ok = np.full(100, 1e307)
    assert np.all(np.isfinite(hertz.contact_radius(ok, 1e300)))  # sum overflows; no error
