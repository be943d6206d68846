"""Human-readable output of a scene run: a table in engineering notation; an effect whose
rel. error is above the scene's rtol is flagged."""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric.scene.units import engineering

#: a coordinate of a located maximum below this fraction of the contact's size prints as 0
#: (the maxima are located to about sqrt(rtol) = 1e-5 of it: a smaller offset from the axis
#: or the surface is the search's noise, e.g. x = 3.2 pm beside z = 131 um)
NEAR_ZERO = 1e-6


def positions_scale(value: dict, unit: str) -> float:
    """The contact's size as a record that locates a maximum (``{value, x, z, ...}``) sees
    it: the largest of its coordinates (keys in m); 0 for any other record."""
    if "value" not in value:
        return 0.0
    coords = [abs(float(v)) for k, v in value.items()
              if k != "value" and unit_of(unit, k) == "m" and np.size(v) == 1
              and np.isfinite(float(v))]
    return max(coords, default=0.0)


def format_value(value, unit: str) -> str:
    """One effect's value as the table prints it: engineering notation; a coordinate of a
    located maximum within :data:`NEAR_ZERO` of the record's largest coordinate as 0."""
    if isinstance(value, dict):
        sizes = {k: np.size(v) for k, v in value.items()}
        n = max(sizes.values()) if sizes else 0
        scale = positions_scale(value, unit)

        exponent = (float(np.reshape(value["n"], -1)[0]) if np.size(value.get("n", [])) == 1
                    else None)

        def show(k, v):
            u = unit_of(unit, k)
            if exponent is not None:  # a force law's K: N/m^n with its n
                u = u.replace("^(n+1)", f"^{exponent + 1:g}").replace("^n", f"^{exponent:g}")
            x = float(np.reshape(v, -1)[0])
            if k != "value" and u == "m" and abs(x) < NEAR_ZERO * scale:
                x = 0.0
            return f"{k} = {engineering(x, u)}"

        scalars = [show(k, v) for k, v in value.items() if np.size(v) == 1]
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
