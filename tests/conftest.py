import mpmath as mp
import pytest
from hypothesis import settings

from oracle import WORST

# benchmarks/mutation.py runs the tests with --hypothesis-profile=mutation: on a loaded machine
# a test's time says nothing (a missed deadline would count as killing the mutant), and every
# mutant should meet the same examples
settings.register_profile("mutation", deadline=None, derandomize=True)


@pytest.fixture(autouse=True)
def _reset_mpmath_precision():
    """Every test starts at mpmath's default precision (as mpmath's own conftest does)."""
    mp.mp.dps = 15
    yield
    mp.mp.dps = 15


def pytest_terminal_summary(terminalreporter):
    if not WORST:
        return
    tr = terminalreporter
    tr.section("worst relative error of each float64 function against its mpmath reference")
    for name in sorted(WORST):
        tr.write_line(f"{name:48s} {WORST[name]:.2e}")



#: the files whose tests share one costly module fixture (xdist_group marks), by group
GROUPED = {"tests/test_benchmarks.py": "benchmarks", "tests/test_generated.py": "generated"}


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_node_collection_finished(node, ids):
    """`make test` runs ``--dist loadgroup``: the tests of a file marked ``xdist_group`` share
    one costly module fixture (the benchmarks' quick run, ~80 s of CPU) and must run on one
    worker. xdist groups them by writing ``@group`` into each test's id on the worker; under
    pytest 9.2 that write no longer takes (pytest-xdist issue 1386), and every worker then
    builds the fixture again, silently. constraints.txt keeps pytest below 9.2; this check
    (on the controller, as each worker reports its collection) stops the run in one line if
    the grouping is lost again."""
    if node.config.getoption("dist") != "loadgroup":
        return
    lost = [i for i in ids if GROUPED.get(i.split("::")[0]) and "@" not in i]
    if lost:
        pytest.exit(f"--dist loadgroup did not group {len(lost)} tests marked xdist_group "
                    f"(e.g. {lost[0]}): pytest {pytest.__version__} and this pytest-xdist do "
                    "not work together (pytest-xdist issue 1386); install pytest < 9.2 "
                    "(constraints.txt)", returncode=3)
