"""numeric/accuracy.py, the report of what accuracy costs in time (``hertzmdr accuracy``).

On made-up quantities whose errors are known exactly: the relative error of each way against
its 60-digit truth (computed here by mpmath from the float the way returns), a way that fails
reported as failing, the bounds and the rows outside them, the formatting of errors, digits
and times at their boundaries, the headline's choice of the fastest way to 1e-12 and the most
digits, and the whole report written by ``main``. Timings are never checked, only that each
row has one. Then the report's own quantities: every way's measured error within the bound of
its error model (numeric/_accuracy_cases.py), each demonstrated failure as large as predicted.
"""

from __future__ import annotations

import json
import math

import mpmath as mp
import pytest

from hertzmdr.numeric import _accuracy_cases, _timing, accuracy
from hertzmdr.numeric.accuracy import Measured, Quantity, Row, Way


def third() -> Quantity:
    """1/3 by five ways: float64 (error 2^-54 / (1/3) = 1.85e-17, bound 1e-16), a 2e-7 slip
    (predicted: 3e-7), a sign slip (-1/3: error 2, outside its bound 1) and two failures (nan,
    inf: predicted)."""
    return Quantity("one third", "a made-up quantity", lambda: mp.mpf(1) / 3, lambda: [
        Way("float", "float64", lambda: 1 / 3, 1e-16),
        Way("slip", "2e-7", lambda: (1 + 2e-7) / 3, lambda: 3e-7, predicts=True),
        Way("sign", "negated", lambda: -1 / 3, 1.0),
        Way("broken", "nan", lambda: math.nan, math.inf, predicts=True),
        Way("broken", "inf", lambda: math.inf, math.inf, predicts=True),
    ])


def test_measure_reports_each_ways_relative_error():
    calls = []
    m = accuracy.measure(third(), lambda: calls.append(1), _timing.QUICK)
    assert len(calls) == 5 and [(r.method, r.setting) for r in m.rows] == [
        ("float", "float64"), ("slip", "2e-7"), ("sign", "negated"), ("broken", "nan"),
        ("broken", "inf")]
    with mp.workdps(60):  # the errors by mpmath from the floats the ways return
        truth = mp.mpf(1) / 3
        want = [float(abs((mp.mpf(v) - truth) / truth)) for v in (1 / 3, (1 + 2e-7) / 3)]
    assert [r.rel_error for r in m.rows[:2]] == want
    assert want[0] == pytest.approx(2.0**-54 * 3, rel=1e-12)  # the float's rounding of 1/3
    assert m.rows[2].rel_error == 2.0  # -1/3 against 1/3
    assert m.rows[3].rel_error == math.inf and m.rows[4].rel_error == math.inf
    for r in m.rows:  # each has its time: a median within its spread
        assert r.spread[0] <= r.seconds <= r.spread[1]
    # the bounds, the truth's error (1e-55 by default) added; the bound given as a function
    # is called; within: error <= bound, and a predicted error at least bound / 100
    assert [r.bound for r in m.rows] == [1e-16 + 1e-55, 3e-7 + 1e-55, 1.0 + 1e-55, math.inf,
                                         math.inf]
    assert [r.predicts for r in m.rows] == [False, True, False, True, True]
    assert [r.within for r in m.rows] == [True, True, False, True, True]
    # errors only, without timing
    m = accuracy.measure(third(), budget=None)
    assert [(r.seconds, r.spread) for r in m.rows] == [(0.0, (0.0, 0.0))] * 5
    assert m.rows[1].rel_error == want[1]


def test_a_row_is_within_its_bound_at_both_ends():
    def row(err, bound, predicts):
        return Row("m", "s", err, 0.0, (0.0, 0.0), bound, predicts)
    b = 1e-8
    assert row(b, b, False).within and row(0.0, b, False).within
    assert not row(b * (1 + 1e-15), b, False).within
    # a predicted error: between bound / PREDICTS_WITHIN and the bound, both ends included
    low = b / accuracy.PREDICTS_WITHIN
    assert row(low, b, True).within and row(b, b, True).within
    assert not row(low * (1 - 1e-15), b, True).within
    assert not row(b * (1 + 1e-15), b, True).within
    assert not row(math.nan, math.inf, False).within and not row(math.nan, math.inf, True).within
    assert row(math.inf, math.inf, True).within and not row(1.0, math.inf, True).within
    assert accuracy.PREDICTS_WITHIN == 100.0


@pytest.mark.parametrize("bound", [math.nan, -1e-9, lambda: math.nan])
def test_a_bound_that_bounds_nothing_is_refused(bound):
    q = Quantity("q", "d", lambda: mp.mpf(1), lambda: [Way("m", "s", lambda: 1.0, bound)])
    with pytest.raises(ValueError, match=r"^q, m \(s\): bound = (nan|-1e-09); valid: >= 0$"):
        accuracy.measure(q, budget=None)


def test_errors_digits_and_times_formatted_at_their_boundaries():
    f = accuracy._fmt_err
    assert f(math.nan) == f(math.inf) == "fails (inf or nan)"
    assert f(1e-60) == "< 1e-50" and f(accuracy.FLOOR) == "1.0e-50" and f(1.26e-7) == "1.3e-07"
    assert f(2.0) == "2.0e+00"
    d = accuracy.digits
    assert d(math.nan) == d(math.inf) == d(1.0) == d(2.0) == 0.0
    assert d(1e-60) == 50.0 and d(accuracy.FLOOR) == 50.0  # -log10(1e-50) at the floor
    assert d(0.5) == -math.log10(0.5) and d(1e-3) == 3.0 and 0 < d(0.999) < 1e-3
    t = accuracy._fmt_time
    assert [t(s) for s in (2.5, 1.0, 0.999, 1e-3, 2.5e-4, 1e-6, 3.5e-7, 1e-9, 5e-10, 0.0)] == [
        "2.5 s", "1 s", "999 ms", "1 ms", "250 µs", "1 µs", "350 ns", "1 ns", "0.5 ns", "0 ns"]


def results() -> list[Measured]:
    q = third()
    a = Measured(q, [Row("slow exact", "60 digits", 1e-60, 2e-3, (1e-3, 3e-3), 1e-55),
                     Row("fast exact", "float64", 1e-13, 2e-6, (1e-6, 3e-6), 1e-14),
                     Row("faster rough", "float64", 1e-9, 1e-6, (1e-6, 1e-6), 2e-9, True),
                     Row("broken", "nan", math.inf, 1e-7, (1e-7, 1e-7), math.inf, True)])
    b = Measured(Quantity("rough", "nothing reaches 1e-12", q.truth, q.ways),
                 [Row("rough", "float64", 2e-5, 1e-6, (1e-6, 2e-6), 1e-4),
                  Row("rougher", "float64", 3e-2, 1e-6, (1e-6, 1e-6), 1.0)])
    return [a, b]


def test_markdown_headline_and_tables():
    text = accuracy.markdown(results(), "acc.png", _timing.QUICK)
    lines = text.splitlines()
    assert "![error against time](acc.png)" in lines
    assert "up to 2 rounds of at least 0 s together" in text
    head = lines.index("| quantity | fastest way to 1e-12 | its time | most digits | "
                       "at what cost |")
    # the fastest way with an error at most 1e-12 (not the faster rough one), the most digits
    # (the least error; a tie would go to the faster)
    assert lines[head + 2] == ("| one third | fast exact (float64) | 2 µs | 50 (slow exact, "
                               "60 digits) | 2 ms |")
    assert lines[head + 3] == "| rough | none | - | 5 (rough, float64) | 1 µs |"
    table = lines.index("## one third") + 1  # then the description and the table
    rows = lines[table + 5:table + 9]  # by time, fastest first (after the header and rule)
    assert rows == [
        "| broken | nan | fails (inf or nan) | fails (predicted) | 0.0 | 100 ns | "
        "100 ns - 100 ns |",
        "| faster rough | float64 | 1.0e-09 | 2.0e-09 (predicted) | 9.0 | 1 µs | 1 µs - 1 µs |",
        "| fast exact | float64 | 1.0e-13 | 1.0e-14, **outside its bound** | 13.0 | 2 µs | "
        "1 µs - 3 µs |",
        "| slow exact | 60 digits | < 1e-50 | < 1e-50 | 50.0 | 2 ms | 1 ms - 3 ms |"]
    # the count of rows within their bounds, and those outside, named
    assert "5 of 6 ways within their bounds: **fast exact (float64)** not.\n" in text
    a, b = results()
    good = [Measured(a.quantity, a.rows[:1]), Measured(b.quantity, b.rows)]
    assert "3 of 3 ways within their bounds.\n" in accuracy.markdown(good, None,
                                                                      _timing.QUICK)
    assert "![error" not in accuracy.markdown(results(), None, _timing.QUICK)


def test_main_writes_the_report_and_its_plot(tmp_path, monkeypatch):
    monkeypatch.setattr(accuracy, "quantities", lambda: [third()])
    record = tmp_path / "record.json"
    record.write_text(json.dumps({"command": "python tests/domain_search.py --bulk",
                                  "points_per_row": 7, "functions": 11, "parameters": 22,
                                  "cases": 33, "failures": 0, "seconds": 44}))
    monkeypatch.setattr(accuracy, "DOMAIN_SEARCH_RECORD", record)
    out = tmp_path / "sub" / "acc.md"
    res = accuracy.main(out, quick=True)
    assert [len(m.rows) for m in res] == [5]
    text = out.read_text()
    assert text.startswith("# What accuracy costs in time\n") and "(acc.png)" in text
    assert (tmp_path / "sub" / "acc.png").stat().st_size > 1000
    assert text.endswith("| 11 | 22 | 33 | 0 | 44 |\n")
    assert "`python tests/domain_search.py --bulk` (7 random points per function" in text
    with pytest.raises(ValueError, match=r"^only = 'no such' matches no quantity; the names: "
                                         r"one third$"):
        accuracy.main(out, only="no such", quick=True)
    assert accuracy.domain_search_section(tmp_path / "missing.json") == ""


#: the report's quantities, by the function of numeric/_accuracy_cases.py that makes each
#: (called inside the test: a mutation run sees the call)
CASES = ["hertz_force", "hertz_far_displacement", "kappa_large_n", "worn_small_depth",
         "powerlaw_pressure_large_n", "numerical_mdr_force", "impact_time",
         "stress_superposition", "adhesive_pull_off", "line_stress_near_edge",
         "ellipse_field_slender", "mindlin_energy_small_amplitude"]


def test_the_cases_are_the_reports_quantities():
    assert [q.name for q in _accuracy_cases.all_quantities()] == [
        getattr(_accuracy_cases, c)().name for c in CASES]


@pytest.mark.parametrize("case", CASES)
def test_every_way_within_the_bound_of_its_error_model(case):
    """Each way's relative error against the 60-digit truth (by mpmath: accuracy.measure) is
    within its bound: the roundings of a closed form (64 u at the way's precision), a textbook
    form's cancellation, a series' first omitted term, a quadrature's tolerance, a rule against
    itself with twice the points, or the error the method reports (hertzmdr's rel_error: promise
    2); a way that demonstrates a failure must fail by at least a hundredth of what it predicts.
    The bounds are 3.3 to 7e8 times the measured errors (a tolerance is an upper bound: SciPy's
    quad asked for 1e-6 reaches 1.5e-15), the predictions 1.5 to 52 times (measured when the
    bounds were written)."""
    q = getattr(_accuracy_cases, case)()
    m = accuracy.measure(q, budget=None)
    outside = [(r.method, r.setting, r.rel_error, r.bound) for r in m.rows if not r.within]
    assert not outside
    assert len(m.rows) >= 4


def test_the_steel_pair():
    """E_STEEL, the cases' modulus: (5.26) for two steel bodies, E = 210 GPa and nu = 0.3,
    is E / (2 (1 - nu^2)) (equal bodies)."""
    assert _accuracy_cases.E_STEEL == pytest.approx(210e9 / (2 * (1 - 0.3**2)), rel=1e-15,
                                                    abs=0)
