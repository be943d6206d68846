"""The generated module is fresh, deterministic, and importing the runtime never loads SymPy."""

import subprocess
import sys
from pathlib import Path

from hertzmdr.derive.__main__ import targets


def test_generated_files_are_fresh():
    # The same check as `python -m hertzmdr.derive --check`, run as a user would.
    proc = subprocess.run([sys.executable, "-m", "hertzmdr.derive", "--check"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr


def test_generation_is_deterministic():
    first, second = targets(), targets()
    assert first == second


def test_numeric_does_not_import_sympy():
    code = ("import sys, hertzmdr.numeric, hertzmdr.numeric.hertz, hertzmdr.numeric._generated;"
            "bad = [m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules];"
            "print(','.join(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"imported at import time: {out.stdout.strip()}"


def test_every_generated_function_cites_its_test():
    from hertzmdr.derive import all_relations

    for rel in all_relations():
        path, name = rel.verified_by.split("::")
        text = (Path(__file__).parents[1] / path).read_text()
        assert f"def {name}(" in text, f"{rel.name}: no test {rel.verified_by}"
