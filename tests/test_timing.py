"""numeric/_timing.py, the one timing mechanism of the benchmarks and ``hertzmdr accuracy``.

What is called how often, what is kept apart, and the arithmetic of planning the rounds,
checked on a fake clock: each timed call advances it by a known number of seconds, so every
figure a Timing holds is known exactly (binary fractions: no rounding). Never the speed of the
machine.
"""

from __future__ import annotations

import math
import os

import pytest

from hertzmdr.numeric import _timing


class Clock:
    """A fake ``time.perf_counter``/``time.process_time``: a timed call advances it by the
    next of ``costs`` (the last one repeats)."""

    def __init__(self, costs):
        self.now = 64.0  # not 0: a time is a difference of two readings
        self.costs = list(costs)
        self.calls = 0

    def __call__(self):
        return self.now

    def work(self, *_):
        self.now += self.costs[min(self.calls, len(self.costs) - 1)]
        self.calls += 1


@pytest.fixture
def clock(monkeypatch):
    def make(*costs):
        c = Clock(costs)
        monkeypatch.setattr(_timing.time, "perf_counter", c)
        monkeypatch.setattr(_timing.time, "process_time", c)
        return c
    return make


def test_measure_keeps_the_first_call_apart():
    calls = []
    t = _timing.measure(lambda: calls.append(1), _timing.Budget(repeats=3, min_time=0.0))
    assert len(calls) == 1 + 3 and len(t.rounds) == 3 and t.number == 1  # first, then rounds
    made = []
    t = _timing.measure(lambda obj: obj.append(2), _timing.Budget(repeats=4, min_time=0.0),
                        setup=lambda: made.append([]) or made[-1])
    assert len(made) == 1 + 4 and all(m == [2] for m in made)  # a fresh object each call
    assert t.spread[0] <= t.median <= t.spread[1]
    assert t.quantile(0) == t.spread[0] and t.quantile(1) == t.spread[1]


def test_budget_stops_slow_calls_early_and_checks_its_fields():
    import time

    t = _timing.measure(lambda: time.sleep(0.05),
                        _timing.Budget(repeats=10, min_time=0.0, max_time=0.12))
    assert 1 <= len(t.rounds) <= 3  # 0.05 s a round: no new round once 0.12 s are spent
    for bad in (dict(repeats=0, min_time=0.0), dict(repeats=1, min_time=-1.0),
                dict(repeats=1, min_time=1.0, max_time=0.5)):
        with pytest.raises(ValueError, match="Budget"):
            _timing.Budget(**bad)


def test_budget_refusals_name_the_field_and_the_range():
    with pytest.raises(ValueError, match=r"^Budget.repeats = 0: at least 1$"):
        _timing.Budget(repeats=0, min_time=0.0)
    with pytest.raises(ValueError, match=r"^Budget.min_time = nan s: must be >= 0$"):
        _timing.Budget(repeats=1, min_time=math.nan)
    with pytest.raises(ValueError, match=r"^Budget.max_time = 0.5 s: must exceed min_time "
                                         r"= 0.5 s$"):
        _timing.Budget(repeats=1, min_time=0.5, max_time=0.5)
    assert _timing.Budget(repeats=1, min_time=0.0).max_time == math.inf  # no cap by default
    _timing.Budget(repeats=1, min_time=0.0, max_time=2.0**-20)  # the smallest budgets hold
    assert (_timing.FULL.repeats, _timing.FULL.min_time, _timing.FULL.max_time) == (5, 0.1, 1.0)
    assert (_timing.QUICK.repeats, _timing.QUICK.min_time) == (2, 0.0)


def test_rounds_planned_from_a_warm_call(clock):
    # first call 1 s (a cold cache), warm calls 1/64 s: rounds of ceil(0.5 / 4 / (1/64)) = 8
    # calls reach min_time = 0.5 s in 4 rounds
    c = clock(1.0, 2.0**-6)
    t = _timing.measure(c.work, _timing.Budget(repeats=4, min_time=0.5))
    assert t.first == 1.0 and t.number == 8 and t.rounds == (2.0**-6,) * 4
    assert c.calls == 1 + 1 + 4 * 8  # first, the warm call that plans, the rounds
    # the number of calls rounds up: 0.5 / 4 / (3/64) = 2.67 -> 3
    c = clock(1.0, 3 * 2.0**-6)
    assert _timing.measure(c.work, _timing.Budget(repeats=4, min_time=0.5)).number == 3
    # a warm call slower than a round's share: one call a round, never none
    c = clock(1.0, 4.0)
    assert _timing.measure(c.work, _timing.Budget(repeats=2, min_time=0.5)).number == 1
    # a clock that does not advance: the warm call is taken as 1e-7 s, not a division by 0
    c = clock(0.0)
    assert _timing.measure(c.work, _timing.Budget(repeats=2, min_time=1e-3)).number == \
        math.ceil(1e-3 / 2 / 1e-7)


def test_rounds_stop_at_max_time(clock):
    # warm calls of 1/4 s, one a round (min_time 0): after rounds 1, 2, 3 the time spent is
    # 1/4, 1/2, 3/4 s; with max_time = 3/4 s no round begins after the third
    c = clock(0.25)
    t = _timing.measure(c.work, _timing.Budget(repeats=10, min_time=0.0, max_time=0.75))
    assert t.rounds == (0.25,) * 3 and t.number == 1
    # the time spent counts every call of a round: warm 1/16 s plans 4 calls a round
    # (ceil(1 / 4 / (1/16))); the rounds' calls then take 1/4 s, 1 s a round, so with
    # max_time 1.5 s no round begins after the second
    c = clock(1.0, 0.0625, 0.25)
    t = _timing.measure(c.work, _timing.Budget(repeats=4, min_time=1.0, max_time=1.5))
    assert t.number == 4 and t.rounds == (0.25, 0.25)


def test_measure_with_setup_times_only_the_call(clock):
    c = clock(0.25)
    made = []

    def setup():
        made.append(c.now)
        c.now += 100.0  # setup's own time is never counted
        return made[-1]

    t = _timing.measure(c.work, _timing.Budget(repeats=2, min_time=1.0), setup=setup)
    # rounds go on until both 2 rounds and 1 s of calls: 4 rounds of 1/4 s
    assert t.first == 0.25 and t.rounds == (0.25,) * 4 and t.number == 1
    assert len(made) == 1 + 4
    # max_time stops them (at least one round): 1 s calls, max_time 2 s -> no round begins
    # once 2 s are spent
    c = clock(1.0)
    t = _timing.measure(c.work, _timing.Budget(repeats=5, min_time=0.0, max_time=2.0),
                        setup=lambda: None)
    assert t.rounds == (1.0, 1.0)
    # a call slower than max_time still gets its one round
    c = clock(8.0)
    t = _timing.measure(c.work, _timing.Budget(repeats=5, min_time=0.0, max_time=1.5),
                        setup=lambda: None)
    assert t.rounds == (8.0,)


def test_timing_statistics():
    t = _timing.Timing(first=9.0, rounds=(4.0, 1.0, 3.0, 2.0), number=1)
    assert t.best == 1.0 and t.median == 2.5 and t.spread == (1.0, 4.0)
    # linear interpolation between order statistics: position q * (n - 1) in (1, 2, 3, 4)
    assert t.quantile(0.0) == 1.0 and t.quantile(1.0) == 4.0
    assert t.quantile(0.5) == 2.5 and t.quantile(0.25) == 1.75 and t.quantile(2 / 3) == 3.0
    assert t.quantile(0.875) == 3.625  # between the last two: position 2.625
    one = _timing.Timing(first=1.0, rounds=(5.0,), number=3)
    assert one.quantile(0.5) == 5.0 and one.quantile(1.0) == 5.0  # one round: no neighbour
    for q in (-0.25, 1.5, math.nan):
        with pytest.raises(ValueError, match=r"quantile q = .*: must lie in \[0, 1\]"):
            t.quantile(q)


def test_compare_interleaves_and_ratios():
    order = []
    t = _timing.compare({"a": lambda: order.append("a"), "b": lambda: order.append("b")},
                        _timing.Budget(repeats=3, min_time=0.0))
    assert order == ["a", "b"] + ["a", "b"] * 3  # first calls, then the rounds alternate
    assert _timing.ratio(t["a"], t["b"]) == t["a"].median / t["b"].median


def test_compare_plans_each_and_stops_at_max_time(clock):
    c = clock(0.25)
    spent = {"a": [], "b": []}

    def fn(name, cost):
        def call():
            spent[name].append(cost)
            c.now += cost
        return call

    # a: 1/4 s a call, b: 1/16 s; min_time 1 s over 2 rounds -> a 2 calls, b 8 calls a round
    t = _timing.compare({"a": fn("a", 0.25), "b": fn("b", 0.0625)},
                        _timing.Budget(repeats=2, min_time=1.0))
    assert (t["a"].number, t["b"].number) == (2, 8)
    assert t["a"].rounds == (0.25, 0.25) and t["b"].rounds == (0.0625, 0.0625)
    assert t["a"].first == 0.25 and len(spent["a"]) == 2 + 2 * 2
    assert _timing.ratio(t["a"], t["b"]) == 4.0 and _timing.ratio(t["b"], t["a"]) == 0.25
    # max_time: no new round once the slower has spent it (a: 1 s a round, max 2 s -> 2)
    spent = {"a": [], "b": []}
    t = _timing.compare({"a": fn("a", 1.0), "b": fn("b", 0.0625)},
                        _timing.Budget(repeats=5, min_time=0.0, max_time=2.0))
    assert len(t["a"].rounds) == len(t["b"].rounds) == 2


def test_timed_and_cpu_best(clock):
    c = clock(0.5)

    def call():
        c.work()
        return "result"

    assert _timing.timed(call) == ("result", 0.5)
    c = clock(3.0, 1.0, 2.0)
    assert _timing.cpu_best(c.work) == 1.0 and c.calls == 3  # the least of 3 rounds
    c = clock(3.0, 1.0, 2.0, 0.5)
    assert _timing.cpu_best(c.work, rounds=4) == 0.5


def test_in_fork_discards_the_child_cache_and_reports_its_errors():
    cache = {}

    def fill(key):
        cache[key] = True
        return sorted(cache)

    assert _timing.in_fork(fill, "x") == ["x"] and cache == {}
    assert _timing.in_fork(lambda k, v=0: (k, v), "x", v=2) == ("x", 2)  # keywords too

    def fail():
        raise ValueError("from the child")

    with pytest.raises(RuntimeError, match="from the child"):
        _timing.in_fork(fail)

    with pytest.raises(RuntimeError, match=r"^in_fork: the child died \(exit code 3\)$"):
        _timing.in_fork(os._exit, 3)


def test_in_fork_without_fork_runs_here(monkeypatch):
    import multiprocessing

    monkeypatch.setattr(multiprocessing, "get_all_start_methods", lambda: ["spawn"])
    cache = {}
    assert _timing.in_fork(lambda k, v=0: cache.setdefault(k, v), "x", v=2) == 2
    assert cache == {"x": 2}  # ran in this process


def test_conditions_name_the_machine_and_the_threads(monkeypatch):
    for v in _timing.THREAD_VARIABLES:
        monkeypatch.delenv(v, raising=False)
    assert _timing.blas_threads() == ("no thread variable set (the libraries' default, up to "
                                      f"{os.cpu_count()} threads)")
    monkeypatch.setenv("OMP_NUM_THREADS", "1")
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")
    assert _timing.blas_threads() == "OPENBLAS_NUM_THREADS = 2, OMP_NUM_THREADS = 1"
    import mpmath
    import numpy
    import scipy

    line = _timing.conditions()
    assert line.startswith("Measured on: ") and line.endswith(
        "; OPENBLAS_NUM_THREADS = 2, OMP_NUM_THREADS = 1.")
    for part in (f"{os.cpu_count()} cores", f"NumPy {numpy.__version__}",
                 f"SciPy {scipy.__version__}", f"mpmath {mpmath.__version__}"):
        assert part in line
    with open("/proc/cpuinfo") as fh:  # the CPU's model name, where Linux gives it
        model = next((x.split(":", 1)[1].strip() for x in fh if x.startswith("model name")),
                     None)
    if model:
        assert line.startswith(f"Measured on: {model}, ")


def test_machine_reads_the_cpu_model_or_falls_back(monkeypatch):
    import io
    import platform

    def cpuinfo(text):
        def fake_open(path, *args, **kwargs):
            if path != "/proc/cpuinfo":
                raise AssertionError(path)
            if text is None:
                raise OSError("no /proc")
            return io.StringIO(text)
        monkeypatch.setattr(_timing, "open", fake_open, raising=False)

    # the model name is all after the first colon, colons in it kept
    cpuinfo("processor\t: 0\nmodel name\t: Fake CPU: rev 2 @ 1:2\nmodel name\t: second\n")
    assert _timing.machine().startswith(f"Fake CPU: rev 2 @ 1:2, {os.cpu_count()} cores; ")
    # no /proc/cpuinfo (or no model name in it): platform's processor, else its machine
    monkeypatch.setattr(platform, "processor", lambda: "")
    monkeypatch.setattr(platform, "machine", lambda: "fake-arch")
    for text in (None, "processor\t: 0\n"):
        cpuinfo(text)
        assert _timing.machine().startswith(f"fake-arch, {os.cpu_count()} cores; ")
    monkeypatch.setattr(platform, "processor", lambda: "fake-processor")
    cpuinfo(None)
    assert _timing.machine().startswith("fake-processor, ")
