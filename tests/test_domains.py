"""hypothesis searches each public function's documented domain for NaN, inf and broken
monotonicity. One row per function: its arguments' domains (log-uniform over decades, as in
the docstrings) and the argument it is monotone in, with the direction. pytest's
filterwarnings=error turns any floating-point warning into a failure too."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hertzmdr.numeric import bodies, cone, ellipse, hertz, impact, line, powerlaw, stress

EPS = np.finfo(float).eps


def logs(lo: float, hi: float):
    """Floats spread evenly over the decades from lo to hi."""
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: 10.0**e)


E = logs(1e3, 1e12)  # moduli [Pa]
L = logs(1e-9, 1e3)  # lengths [m]
D = logs(1e-12, 1e-1)  # depths [m]
F = logs(1e-12, 1e9)  # forces [N]
NU = st.floats(-0.99, 0.5)
ANGLE = st.floats(0.01, 1.5)  # cone angle [rad], (0, pi/2)


# (name, function, {argument: strategy}, monotone argument or None, +1 increasing, -1 decreasing)
ROWS = [
    ("hertz.contact_radius", hertz.contact_radius, {"d": D, "R": L}, "d", +1),
    ("hertz.max_pressure", hertz.max_pressure, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("hertz.mean_pressure", hertz.mean_pressure, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("hertz.force", hertz.force, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("hertz.energy", hertz.energy, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("hertz.stiffness", hertz.stiffness, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("hertz.depth_from_force", hertz.depth_from_force, {"F": F, "R": L, "E_star": E}, "F", +1),
    ("hertz.contact_radius_from_force", hertz.contact_radius_from_force,
     {"F": F, "R": L, "E_star": E}, "F", +1),
    ("hertz.max_pressure_from_force", hertz.max_pressure_from_force,
     {"F": F, "R": L, "E_star": E}, "F", +1),
    ("hertz.surface_displacement", hertz.surface_displacement,
     {"r": logs(1e-12, 1e6), "d": D, "R": L}, "r", -1),
    ("bodies.effective_modulus", bodies.effective_modulus,
     {"E1": E, "nu1": NU, "E2": E, "nu2": NU}, "E1", +1),
    ("bodies.effective_radius", bodies.effective_radius, {"R1": L, "R2": L}, "R1", +1),
    ("cone.contact_radius", cone.contact_radius, {"d": D, "theta": ANGLE}, "d", +1),
    ("cone.force", cone.force, {"d": D, "theta": ANGLE, "E_star": E}, "d", +1),
    ("cone.depth_from_force", cone.depth_from_force, {"F": F, "theta": ANGLE, "E_star": E},
     "F", +1),
    ("line.force", line.force, {"d": D, "L": L, "E_star": E}, "d", +1),
    ("line.half_width", line.half_width, {"d": D, "R": L}, "d", +1),
    ("line.max_pressure", line.max_pressure, {"d": D, "R": L, "E_star": E}, "d", +1),
    ("impact.max_depth", lambda v0, R, E_star, m: impact.max_depth(v0, R, E_star, m=m),
     {"v0": logs(1e-6, 1e3), "R": L, "E_star": E, "m": logs(1e-12, 1e6)}, "v0", +1),
    ("impact.contact_time", lambda v0, R, E_star, m: impact.contact_time(v0, R, E_star, m=m),
     {"v0": logs(1e-6, 1e3), "R": L, "E_star": E, "m": logs(1e-12, 1e6)}, "v0", -1),
    ("impact.max_pressure", lambda v0, R, E_star, rho: impact.max_pressure(v0, R, E_star,
                                                                           rho=rho),
     {"v0": logs(1e-6, 1e3), "R": L, "E_star": E, "rho": logs(1e2, 2e4)}, "v0", +1),
    ("powerlaw.kappa", powerlaw.kappa, {"n": logs(0.1, 1e6)}, "n", +1),
    ("powerlaw.contact_radius", powerlaw.contact_radius,
     {"d": D, "c_n": logs(1e-3, 1e3), "n": logs(0.2, 50.0)}, "d", +1),
    ("powerlaw.force", powerlaw.force,
     {"d": D, "c_n": logs(1e-3, 1e3), "n": logs(0.2, 50.0), "E_star": E}, "d", +1),
    ("ellipse.solve(...).force", lambda R1, q, E_star, depth: ellipse.solve(
        R1, R1 / q, E_star, depth=depth).force,
     {"R1": L, "q": logs(1.0, 1e4), "E_star": E, "depth": D}, "depth", +1),
    ("stress.axis_stresses (sigma_zz)", lambda z, a, p0, nu: stress.axis_stresses(z, a, p0,
                                                                                  nu)[0],
     {"z": logs(1e-12, 1e6), "a": L, "p0": E, "nu": NU}, "z", +1),
]


@pytest.mark.parametrize("row", ROWS, ids=[r[0] for r in ROWS])
@settings(max_examples=40, deadline=None)
@given(data=st.data())
def test_finite_and_monotone(row, data):
    name, fn, doms, mono, sign = row
    args = {k: data.draw(s, label=k) for k, s in doms.items()}
    value = float(np.asarray(fn(**args)))
    assert math.isfinite(value), f"{name}{args} = {value}"
    if mono is None:
        return
    step = data.draw(st.floats(1e-6, 1.0), label="relative step")
    moved = {**args, mono: args[mono] * (1 + step)}
    other = float(np.asarray(fn(**moved)))
    assert math.isfinite(other)
    # allow a few roundings of noise where the two values are nearly equal
    assert sign * (other - value) >= -8 * EPS * max(abs(value), abs(other)), \
        f"{name} not {'increasing' if sign > 0 else 'decreasing'} in {mono}: {args} -> {value}, " \
        f"{moved} -> {other}"


# -- the documented-domain search (issue 19): every public function of the closed-form modules,
# each parameter over its documented range, the neighbours of every branch boundary, mpmath
# references that also say where the true value is no float64, round trips; see
# tests/domain_search.py. CI runs a few points per function, the sweep the bulk.

import domain_search  # noqa: E402

from oracle import n_points  # noqa: E402

SEARCH_ROWS = domain_search.rows()


@pytest.mark.parametrize("row", SEARCH_ROWS, ids=[r.name for r in SEARCH_ROWS])
def test_documented_domain(row):
    failures, _ = domain_search.run([row], 3)  # the corners, the edges, 3 random points
    assert not failures, "\n".join(failures)


@pytest.mark.sweep
@pytest.mark.parametrize("row", SEARCH_ROWS, ids=[r.name for r in SEARCH_ROWS])
def test_documented_domain_sweep(row):
    # the corners are test_documented_domain's (the same box each time): here only random
    # points, another seed (for the costly rows, corners and their edges were ~90 % of the work)
    failures, _ = domain_search.run([row], n_points(full=400, ci=8), seed=1, corners=False)
    assert not failures, "\n".join(failures)


def test_search_uses_the_documented_reach():
    from hertzmdr.numeric import stress

    assert domain_search.MAX_DISTANCE == stress.MAX_DISTANCE


@pytest.mark.parametrize("row", SEARCH_ROWS, ids=[r.name for r in SEARCH_ROWS])
def test_docstring_states_the_searched_domain(row):
    """Each public function's docstring states the domain the search tests, word for word."""
    import inspect

    doc = " ".join(inspect.getdoc(row.target).split())
    assert " ".join(domain_search.guarantee(row).split()) in doc, row.target.__qualname__


def test_accuracy_report_has_the_search_counts(tmp_path):
    import json

    from hertzmdr.numeric import accuracy

    record = tmp_path / "search.json"
    record.write_text(json.dumps({"functions": 62, "parameters": 198, "cases": 1000,
                                  "failures": 0, "seconds": 12.5, "points_per_row": 400,
                                  "command": "python tests/domain_search.py"}))
    text = accuracy.domain_search_section(record)
    assert "| 62 | 198 | 1000 | 0 | 12.5 |" in text
    assert accuracy.domain_search_section(tmp_path / "missing.json") == ""
