"""Human-readable output of a scene run: a table in engineering notation; an effect whose
rel. error is above the scene's rtol is flagged."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric.scene.units import engineering


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


def table(title: str, model: dict, results, warnings=()) -> str:
    """The table of a run: the model, one row per effect, then a line per flag and warning
    (``warnings``: the records of the document's ``warnings``)."""
    lines = [title, "=" * len(title)]
    desc = model.get("description", model.get("kind", ""))
    lines.append(f"model: {desc}; E* = {engineering(model['effective_modulus'], 'Pa')}; "
                 f"rtol = {model['rtol']:g}")
    rows = [("effect", "value", "method", "rel. error", "time")]
    missed = []
    for res in results.values():
        flag = "" if res.met_rtol else " > rtol (!)"
        if not res.met_rtol:
            missed.append(res.name)
        rows.append((res.name, format_value(res.value, res.unit), res.method,
                     f"{res.rel_error:.1e}{flag}", f"{res.seconds * 1e3:.2f} ms"))
    widths = [max(len(r[i]) for r in rows) for i in range(5)]
    for k, row in enumerate(rows):
        lines.append("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
        if k == 0:
            lines.append("  ".join("-" * w for w in widths))
    if missed:
        lines.append(f"(!) rel. error above rtol = {model['rtol']:g}: {', '.join(missed)} (the "
                     "method cannot reach it here; the method column says why)")
    lines += [f"warning: {w['message']}" for w in warnings]
    return "\n".join(lines)
