"""The demo (``make demo``): its CLI runs, Problem 1 gives the chapter's numbers, and the
new numeric modules load neither SymPy nor SciPy at import time."""

import subprocess
import sys

from hertzmdr.numeric import demo


def test_demo_cli_runs():
    proc = subprocess.run([sys.executable, "-m", "hertzmdr.numeric.demo", "--family", "hertz"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "hertz_force(E_star, R, d)" in proc.stdout


def test_problem1_numbers(capsys):
    """E* ~ 1.2e11 Pa (1.154e11 exactly), p0 ~ 1.0 GPa, a ~ 6.8 mm: the chapter's two digits."""
    res = demo.problem1()
    capsys.readouterr()
    assert abs(res["E_star"] / 1.2e11 - 1) < 0.04  # the chapter rounds 1.154e11 to 1.2e11
    assert abs(res["R"] / 0.5 - 1) < 1e-15
    assert abs(res["p0"] / 1.0e9 - 1) < 0.02
    assert abs(res["a"] / 6.8e-3 - 1) < 0.02


def test_numeric_modules_do_not_import_sympy():
    code = ("import sys, hertzmdr.numeric.bodies, hertzmdr.numeric.line, hertzmdr.numeric.cone,"
            " hertzmdr.numeric.impact, hertzmdr.numeric.demo;"
            "bad = [m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules];"
            "print(','.join(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"imported at import time: {out.stdout.strip()}"
