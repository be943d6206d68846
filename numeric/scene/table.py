"""The table of a scene's scalar results: one row per point of its study (one row without a
study), one column per swept key and per scalar effect, the unit in each header
(``force [N]``). The same table is results.csv (``--out``), ``--csv`` on stdout, the text table
of a study, and the data of its figures (a curve per column against the swept key; a contour
map over two). Everything is read from the JSON document, so the CSV's numbers are the JSON's
(both print a float's shortest round-trip form).
"""

from __future__ import annotations

import csv
import io
import math
import re
from pathlib import Path

from hertzmdr.numeric.scene.effects import EFFECTS
from hertzmdr.numeric.scene.report import unit_of

#: the rows a study's text table shows: the first and the last ones, "..." between
SHOWN_ROWS = 12


def _numbers(v, n: int) -> bool:
    return isinstance(v, list) and len(v) == n and all(
        isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)


def columns(doc: dict) -> list[tuple[str, str, list[float]]]:
    """(header, kind, values) of each column: kind "axis" for a swept key, "effect" for an
    effect's number. An effect enters as one column (a number per point), one per entry of a
    table of numbers (``max_shear.value [Pa]``), or one per element of a list of numbers
    (``semi_axes[0] [m]``); fields, and what a load sweep computes at its largest load only,
    are not columns."""
    study = doc.get("study")
    n = math.prod(study["shape"]) if study else 1
    cols = []
    if study:
        cols += [(f"{a['key']} [{a['unit']}]", "axis", study["points"][a["key"]])
                 for a in study["axes"]]
    for name, e in doc["effects"].items():
        if name in EFFECTS and EFFECTS[name].field:
            continue
        v, unit = e["value"], e["unit"]
        if not study and isinstance(v, (int, float)) and not isinstance(v, bool):
            v = [v]
        if not study and isinstance(v, list) and _numbers(v, len(v)) and len(v) > 1:
            v = [[x] for x in v]  # one point, a list of numbers: one column per element
        if not study and isinstance(v, dict):
            v = {k: [x] for k, x in v.items()}
        if _numbers(v, n):
            cols.append((f"{name} [{unit}]", "effect", v))
        elif isinstance(v, list) and len(v) == n and all(isinstance(r, list) for r in v) \
                and len({len(r) for r in v}) == 1 and all(_numbers(r, len(r)) for r in v):
            cols += [(f"{name}[{j}] [{unit}]", "effect", [r[j] for r in v])
                     for j in range(len(v[0]))]
        elif isinstance(v, list) and v and all(_numbers(r, n) for r in v):  # [[a...], [b...]]
            cols += [(f"{name}[{j}] [{unit}]", "effect", r) for j, r in enumerate(v)]
        elif isinstance(v, dict):
            cols += [(f"{name}.{k} [{unit_of(unit, k)}]", "effect", x) for k, x in v.items()
                     if _numbers(x, n)]
    return cols


def csv_text(doc: dict) -> str:
    """results.csv: a header of ``name [unit]``, then one row per point of the study."""
    cols = columns(doc)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([h for h, _, _ in cols])
    for row in zip(*(v for _, _, v in cols), strict=True):
        w.writerow([repr(float(x)) for x in row])
    return buf.getvalue()


def _split(header: str) -> tuple[str, str]:
    name, _, unit = header.rpartition(" [")
    return name, unit[:-1]


def study_table(doc: dict, warnings=()) -> str:
    """The text table of a study: its model, its axes, the rows of its points (the first
    and last of them when there are many) and each effect's method and error."""
    title, model, study = doc["title"], doc["model"], doc["study"]
    lines = [title, "=" * len(title)]
    desc = model.get("description", model.get("kind", ""))
    desc = desc if isinstance(desc, str) else " / ".join(dict.fromkeys(desc))
    lines.append(f"model: {desc}; rtol = {model['rtol']:g}")
    lines += axes_lines(study)
    n = math.prod(study["shape"])
    lines.append(f"{n} points, evaluated {study['route']} in {study['seconds'] * 1e3:.1f} ms")
    lines += rows_table(doc)
    for name, e in doc["effects"].items():
        flag = "" if e["met_rtol"] else " > rtol (!)"
        field = " (a field per point: result.json)" if EFFECTS[name].field else ""
        lines.append(f"{name}: {e['method']}; rel. error <= {e['rel_error']:.1e}{flag}{field}")
    lines += [f"warning: {w['message']}" for w in warnings]
    return "\n".join(lines)


def axes_lines(study: dict) -> list[str]:
    """One line per swept key: from, to, points, spacing."""
    from hertzmdr.numeric.scene.study import show

    return [f"study: {a['key']} from {show(a['values'][0], a['unit'])} to "
            f"{show(a['values'][-1], a['unit'])}, {len(a['values'])} points ({a['spacing']})"
            for a in study["axes"]]


def rows_table(doc: dict) -> list[str]:
    """The lines of the table of :func:`columns`, the first and the last rows of a long one
    (the rows are those of results.csv)."""
    n = math.prod(doc["study"]["shape"])
    lines = []
    cols = columns(doc)
    heads = [h.replace(" [rad]", " [deg]") for h, _, _ in cols]
    rows = [heads]
    shown = range(n) if n <= SHOWN_ROWS else [*range(SHOWN_ROWS // 2),
                                              *range(n - SHOWN_ROWS // 2 + 1, n)]
    for i, k in enumerate(shown):
        if n > SHOWN_ROWS and i == SHOWN_ROWS // 2:
            rows.append(["..."] * len(cols))
        rows.append([_cell(v[k], _split(h)[1]) for h, _, v in cols])
    widths = [max(len(r[j]) for r in rows) for j in range(len(cols))]
    for k, row in enumerate(rows):
        lines.append("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
        if k == 0:
            lines.append("  ".join("-" * w for w in widths))
    return lines


def _cell(x: float, unit: str) -> str:
    from hertzmdr.numeric.scene.study import show

    return show(float(x), unit or "1")


def _file_name(header: str) -> str:
    return re.sub(r"[^A-Za-z0-9_]+", "_", _split(header)[0]).strip("_") + ".png"


def figures(doc: dict, folder: Path) -> list[Path]:
    """A PNG per effect column against the swept key (two swept keys: a contour map over
    them); an angle's axis in degrees, a log sweep on a log axis. None without a study."""
    import warnings

    import numpy as np

    from hertzmdr.numeric.scene.figures import _plt, _scaled, plain

    study = doc.get("study")
    cols = columns(doc)
    axes = [c for c in cols if c[1] == "axis"]
    if not study or not any(c[1] == "effect" for c in cols):
        return []
    plt = _plt()
    shape = tuple(study["shape"])
    written = []

    def axis_data(k):
        head, _, v = axes[k]
        name, unit = _split(head)
        v = np.asarray(v, float)
        if unit == "rad":
            return v * 180.0 / math.pi, f"{name} [deg]"
        if unit == "1":
            return v, name
        return _scaled(v, name, unit)

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Glyph .* missing", category=UserWarning)
        for head, kind, values in cols:
            if kind != "effect":
                continue
            name, unit = _split(head)
            y = np.asarray(values, float)
            fig, ax = plt.subplots(figsize=(6.0, 4.2), dpi=120)
            try:
                ys, ylabel = (y, name) if unit in ("1", "") else _scaled(y, name, unit)
                x, xlabel = axis_data(0)
                if len(axes) == 1:
                    ax.plot(x, ys, lw=1.8, marker="o" if len(x) <= 30 else None, ms=3)
                    ax.set_ylabel(ylabel)
                    if study["axes"][0]["spacing"] == "log":
                        ax.set_xscale("log")
                    ax.grid(True, alpha=0.3)
                else:
                    x2, ylabel2 = axis_data(1)
                    X, Y = x.reshape(shape), x2.reshape(shape)
                    Z = ys.reshape(shape)
                    if np.ptp(Z[np.isfinite(Z)]) > 0:
                        cs = ax.contourf(X, Y, Z, levels=14, cmap="viridis")
                        ax.contour(X, Y, Z, levels=cs.levels, colors="k", linewidths=0.3)
                    else:
                        cs = ax.pcolormesh(X, Y, Z, cmap="viridis", shading="auto")
                    fig.colorbar(cs, ax=ax, label=ylabel)
                    if Z.size <= 2500:  # the points computed
                        ax.plot(X.ravel(), Y.ravel(), "k.", ms=2)
                    ax.set_ylabel(ylabel2)
                    for j, setter in ((0, ax.set_xscale), (1, ax.set_yscale)):
                        if study["axes"][j]["spacing"] == "log":
                            setter("log")
                ax.set_xlabel(xlabel)
                ax.set_title(f"{plain(doc['title'])}\n{name}", fontsize=10)
                fig.tight_layout()
                path = folder / _file_name(head)
                fig.savefig(path)
                written.append(path)
            finally:
                plt.close(fig)
    return written


#: a study's fields are drawn at every point up to this many points, else at its first and last
DRAWN_FIELD_POINTS = 10


def write(doc: dict, results: dict, title: str, folder: Path, ctx=None) -> list[Path]:
    """What ``--out`` writes besides result.json: results.csv (when the scene has a number
    to tabulate), a PNG per field effect (a study's: ``<effect>_<row>.png``, the row of
    results.csv, at each point up to :data:`DRAWN_FIELD_POINTS` points, else at the first and
    the last), and a study's PNG per effect column. ``ctx``: the run's
    :class:`~.figures.Context` (the contact's extent marked on its profile plots)."""
    from hertzmdr.numeric.scene.figures import FIGURES, Context, plain, write_all

    written = []
    if len(columns(doc)) > 0:
        path = folder / "results.csv"
        path.write_text(csv_text(doc))
        written.append(path)
    study = doc.get("study")
    if study is None or "route" not in study:  # one scene, or a load sweep: its own fields
        written += write_all(results, title, folder, ctx or Context())
    else:
        n = math.prod(study["shape"])
        rows = range(n) if n <= DRAWN_FIELD_POINTS else (0, n - 1)
        for name, res in results.items():
            if name not in FIGURES:
                continue
            for k in rows:
                at = ", ".join(f"{key} = {_cell(v[k], unit)}"
                               for key, unit, v in _axes(study))
                path = folder / f"{name}_{k:0{len(str(n - 1))}d}.png"
                FIGURES[name](res.value[k], plain(f"{title} ({at})"), path)
                written.append(path)
    return written + figures(doc, folder)


def _axes(study: dict):
    return [(a["key"], a["unit"], study["points"][a["key"]]) for a in study["axes"]]


def needs_matplotlib(doc: dict) -> bool:
    """Whether --out draws a study's figures (its effect columns)."""
    return bool(doc.get("study")) and any(k == "effect" for _, k, _ in columns(doc))
