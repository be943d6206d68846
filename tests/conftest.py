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



#: the test files whose tests share a costly module fixture, each run on one worker by `make
#: test` (--dist loadgroup): the benchmarks' quick run (~70 s of CPU), the regenerated files,
#: the numerical MDR's 30-digit references (~20 s); split over two workers, each built its own
GROUPED = {"test_benchmarks.py": "benchmarks", "test_generated.py": "generated",
           "test_mdr_bounds.py": "mdr_bounds"}


@pytest.hookimpl(tryfirst=True)  # before xdist's own hook reads the marks
def pytest_collection_modifyitems(items):
    for item in items:
        group = GROUPED.get(item.path.name)
        if group:
            item.add_marker(pytest.mark.xdist_group(group))


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_node_collection_finished(node, ids):
    """xdist groups the tests marked ``xdist_group`` by writing ``@group`` into each test's id
    on the worker; under pytest 9.2 that write no longer takes (pytest-xdist issue 1386), and
    every worker then builds the fixture again, silently. constraints.txt keeps pytest below
    9.2; this check (on the controller, as each worker reports its collection) stops the run in
    one line if the grouping is lost again."""
    if node.config.getoption("dist") != "loadgroup":
        return
    lost = [i for i in ids if i.split("::")[0].rsplit("/", 1)[-1] in GROUPED and "@" not in i]
    if lost:
        pytest.exit(f"--dist loadgroup did not group {len(lost)} tests marked xdist_group "
                    f"(e.g. {lost[0]}): pytest {pytest.__version__} and this pytest-xdist do "
                    "not work together (pytest-xdist issue 1386); install pytest < 9.2 "
                    "(constraints.txt)", returncode=3)
