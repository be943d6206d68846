"""numeric/_validate.py: each check at both sides of its bounds, and its message.

The expected messages are written out here (the format the public API promises: the name, the
offending value with its index, the valid range), not built by the code under test.
"""

import re

import numpy as np
import pytest

from hertzmdr.numeric._validate import (
    as_float,
    between,
    nonnegative,
    nonzero,
    poisson,
    positive,
    result,
)

TINY = 5e-324  # the smallest positive float: a bound must hold to the last representable value


def raises(message, func, *args, **kwargs):
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        func(*args, **kwargs)


def test_as_float():
    out = as_float("x", [1, 2.5])
    assert out.dtype == np.float64 and out.tolist() == [1.0, 2.5]
    raises("x = 'abc' is not a number or an array of numbers", as_float, "x", "abc")
    raises("x = nan is out of range; valid: a number, not NaN", as_float, "x", float("nan"))
    raises("x[1] = nan is out of range; valid: a number, not NaN", as_float, "x",
           [0.0, np.nan, np.nan])
    raises("x[(1, 0)] = nan is out of range; valid: a number, not NaN", as_float, "x",
           [[0.0, 1.0], [np.nan, 2.0]])
    assert as_float("x", np.inf) == np.inf  # only NaN is refused here


def test_positive():
    assert positive("R", TINY) == TINY and positive("R", 1e308) == 1e308
    raises("R = 0.0 is out of range; valid: R > 0 and finite", positive, "R", 0.0)
    raises("R = -1.0 is out of range; valid: R > 0 and finite", positive, "R", -1.0)
    raises("R = inf is out of range; valid: R > 0 and finite", positive, "R", np.inf)
    assert positive("R", np.inf, allow_inf=True) == np.inf
    raises("R = 0.0 is out of range; valid: R > 0", positive, "R", 0.0, allow_inf=True)
    raises("R = -inf is out of range; valid: R > 0", positive, "R", -np.inf, allow_inf=True)
    raises("R[2] = 0.0 is out of range; valid: R > 0 and finite", positive, "R", [1.0, 2.0, 0.0])


def test_nonnegative():
    assert nonnegative("d", 0.0) == 0.0 and nonnegative("d", TINY) == TINY
    raises("d = -5e-324 is out of range; valid: 0 <= d < inf", nonnegative, "d", -TINY)
    raises("d = inf is out of range; valid: 0 <= d < inf", nonnegative, "d", np.inf)
    raises("d[0] = -1.0 is out of range; valid: 0 <= d < inf", nonnegative, "d", [-1.0, 1.0])


def test_nonzero():
    assert nonzero("R1", -TINY) == -TINY and nonzero("R1", np.inf) == np.inf
    assert nonzero("R1", -np.inf) == -np.inf
    raises("R1 = 0.0 is out of range; valid: R1 != 0 (negative: concave, inf: flat)",
           nonzero, "R1", 0.0)
    assert nonzero("R1", -2.0, allow_inf=False) == -2.0
    raises("R1 = inf is out of range; valid: R1 != 0 (negative: concave)", nonzero, "R1",
           np.inf, allow_inf=False)
    raises("R1 = 0.0 is out of range; valid: R1 != 0 (negative: concave)", nonzero, "R1", 0.0,
           allow_inf=False)


def test_poisson():
    below = float(np.nextafter(-1.0, 0.0))
    assert poisson("nu", 0.5) == 0.5 and poisson("nu", below) == below
    raises("nu = -1.0 is out of range; valid: -1 < nu <= 0.5", poisson, "nu", -1.0)
    above = float(np.nextafter(0.5, 1.0))
    raises(f"nu = {above!r} is out of range; valid: -1 < nu <= 0.5", poisson, "nu", above)


@pytest.mark.parametrize("lo_open, hi_open, text", [
    (True, True, "0.0 < t < 2.0"), (False, True, "0.0 <= t < 2.0"),
    (True, False, "0.0 < t <= 2.0"), (False, False, "0.0 <= t <= 2.0")])
def test_between(lo_open, hi_open, text):
    for value, bound_open in ((0.0, lo_open), (2.0, hi_open)):
        if bound_open:
            raises(f"t = {value!r} is out of range; valid: {text}", between, "t", value, 0.0,
                   2.0, lo_open=lo_open, hi_open=hi_open)
        else:
            assert between("t", value, 0.0, 2.0, lo_open=lo_open, hi_open=hi_open) == value
    for value in (TINY, float(np.nextafter(2.0, 0.0))):
        assert between("t", value, 0.0, 2.0, lo_open=lo_open, hi_open=hi_open) == value
    for value in (-TINY, float(np.nextafter(2.0, 3.0))):
        raises(f"t = {value!r} is out of range; valid: {text}", between, "t", value, 0.0, 2.0,
               lo_open=lo_open, hi_open=hi_open)


def test_result():
    scalar = result(np.asarray(2.5))
    assert type(scalar) is np.float64 and scalar == 2.5
    arr = np.array([1.0, 2.0])
    assert result(arr) is arr
    one = result(np.array([3.0]))
    assert isinstance(one, np.ndarray) and one.shape == (1,)


def test_array_messages_and_defaults():
    """The first offending element of an array is named with its index for every check; a
    positive value below 1 passes with allow_inf too; between's bounds are open by default."""
    assert positive("R", TINY, allow_inf=True) == TINY
    raises("R1[1] = 0.0 is out of range; valid: R1 != 0 (negative: concave, inf: flat)",
           nonzero, "R1", [1.0, 0.0, 0.0])
    raises("nu[1] = -1.0 is out of range; valid: -1 < nu <= 0.5", poisson, "nu", [0.3, -1.0])
    raises("t[1] = 0.0 is out of range; valid: 0.0 < t < 2.0", between, "t", [1.0, 0.0, 3.0],
           0.0, 2.0)
    raises("t = 2.0 is out of range; valid: 0.0 < t < 2.0", between, "t", 2.0, 0.0, 2.0)


@pytest.mark.parametrize("check", [positive, nonnegative, nonzero, poisson,
                                   lambda name, v: between(name, v, 0.0, 1.0)])
def test_every_check_names_nan_and_non_numbers(check):
    raises("q = nan is out of range; valid: a number, not NaN", check, "q", float("nan"))
    raises("q = 'abc' is not a number or an array of numbers", check, "q", "abc")
