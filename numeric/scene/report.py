"""Human-readable output of a scene run: a table in engineering notation."""

from __future__ import annotations

import math

import numpy as np

_PREFIXES = [(1e12, "T"), (1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"),
             (1e-6, "µ"), (1e-9, "n"), (1e-12, "p"), (1e-15, "f")]


def engineering(x: float, unit: str, digits: int = 5) -> str:
    """``x`` with an SI prefix: engineering(1.0134e9, "Pa") == "1.0134 GPa"."""
    if not math.isfinite(x):
        return f"{x} {unit}"
    if x == 0 or unit in ("", "1", "rad"):
        return f"{x:.{digits}g} {unit}".strip()
    if "/" in unit or "^" in unit:  # compound units keep plain scientific notation
        return f"{x:.{digits}g} {unit}"
    for scale, prefix in _PREFIXES:
        if abs(x) >= scale * 0.9999999:
            return f"{x / scale:.{digits}g} {prefix}{unit}"
    return f"{x:.{digits}g} {unit}"


def format_value(value, unit: str) -> str:
    if isinstance(value, dict):
        sizes = {k: np.size(v) for k, v in value.items()}
        n = max(sizes.values()) if sizes else 0
        scalars = [f"{k} = {engineering(float(v), unit_of(unit, k))}"
                   for k, v in value.items() if np.size(v) == 1]
        if scalars:
            return ", ".join(scalars)
        return f"field of {n} points ({', '.join(value)}); PNG with --out"
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0 or arr.size == 1:
        return engineering(float(arr.reshape(-1)[0]), unit)
    if arr.size <= 3:
        return "[" + ", ".join(engineering(float(v), unit) for v in arr) + "]"
    return (f"{arr.size} values, {engineering(float(arr[0]), unit)} .. "
            f"{engineering(float(arr[-1]), unit)}")


def unit_of(unit: str, key: str) -> str:
    """The unit of one key of a compound unit such as '{value: Pa, depth: m}'."""
    if not unit.startswith("{"):
        return unit
    for part in unit.strip("{}").split(","):
        k, _, u = part.partition(":")
        if k.strip() == key:
            return u.strip()
    return ""


def table(title: str, model: dict, results) -> str:
    lines = [title, "=" * len(title)]
    desc = model.get("description", model.get("kind", ""))
    lines.append(f"model: {desc}; E* = {engineering(model['effective_modulus'], 'Pa')}")
    rows = [("effect", "value", "method", "rel. error", "time")]
    for res in results.values():
        rows.append((res.name, format_value(res.value, res.unit), res.method,
                     f"{res.rel_error:.1e}", f"{res.seconds * 1e3:.2f} ms"))
    widths = [max(len(r[i]) for r in rows) for i in range(5)]
    for k, row in enumerate(rows):
        lines.append("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
        if k == 0:
            lines.append("  ".join("-" * w for w in widths))
    return "\n".join(lines)
