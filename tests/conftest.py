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
