"""Two columns of numbers from a text file: a sampled profile's r, f (shapes/profile.py) and a
load history's normal, tangential states (schema.py), read one way."""

from __future__ import annotations

from pathlib import Path


def read_pairs(path: Path, fail, what: str, names: str) -> list[tuple[int, tuple[float, float]]]:
    """The rows (line number, (first, second)) of a text file: two numbers a line, separated
    by a comma and/or spaces; ``#`` starts a comment; one header line may come before the
    first row; a UTF-8 byte-order mark is skipped. ``fail(message)`` is called on the first
    problem, naming the file (``what``: "sample", "history") and the line, and what a row
    holds (``names``: "r, f")."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        fail(f"{what} file {str(path)!r} not found")
    except (OSError, UnicodeDecodeError) as exc:
        fail(f"cannot read {str(path)!r} ({exc})")
    rows, header = [], False
    for n, line in enumerate(text.splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = line.replace(",", " ").split()
        try:
            if len(parts) != 2:
                raise ValueError
            vals = (float(parts[0]), float(parts[1]))
        except ValueError:
            if not rows and not header:  # one header line before the first row
                header = True
                continue
            fail(f"{path.name} line {n}: expected two numbers {names}, got {line[:60]!r}")
        rows.append((n, vals))
    return rows
