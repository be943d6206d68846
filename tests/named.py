"""Every input of a public function is named in the error it raises (numeric/_validate.py).

:func:`assert_inputs_named` replaces one input at a time by NaN (refused by every validator)
and checks that the ValueError starts with that input's name, so a validator called with the
wrong name (or none) fails. Mutation testing (benchmarks/mutation.py) found these names
untested in every module but one: a message naming the wrong input misleads the user.
"""

from __future__ import annotations

import pytest


def assert_inputs_named(func, valid: dict, names: dict | None = None) -> None:
    """Call ``func(**valid)`` with each input in turn set to NaN; the error must name it.

    ``names`` maps an argument to the name its error uses, where the two differ.
    """
    func(**valid)  # the valid call itself must pass, or the check below proves nothing
    for arg in valid:
        name = (names or {}).get(arg, arg)
        with pytest.raises(ValueError) as info:
            func(**{**valid, arg: float("nan")})
        message = str(info.value)
        assert message.startswith((f"{name} = nan", f"{name}[")), \
            f"{func.__qualname__}({arg}=nan) raised {message!r}; expected it to name {name!r}"
