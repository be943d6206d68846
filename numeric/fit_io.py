"""Files of ``hertzmdr fit``: a force curve from CSV, its tip from a scene, a figure of the fit.

The curve file (CSV, UTF-8): lines starting with ``#`` are comments; the first other line is
the header naming the two columns with their units in brackets, the position first and the
force second, e.g. ``z [um], F [nN]``; every further line is one point. The units are any
length and force pint reads (``nm``, ``um``, ``m``; ``pN``, ``nN``, ``N``).

The tip file is a scene (docs/scenes.md) with its two bodies: the sample is the ``flat`` body
(its ``nu`` gives the sample's Young's modulus beside E*; its ``E``, which a scene requires, is
shown beside the fitted one for comparison, not used), the tip is the other body (``sphere``:
the paraboloid of Hertz, ``exact_sphere``, ``cone``, ``pyramid`` (the cone of its force law),
``flat_punch``, ``power_law``, or a measured ``profile``, fitted through the numerical MDR; rigid
or elastic). The scene's effects and load are not used. Its optional ``[fit]`` table
(:class:`..scene.schema.FitSpec`, docs/fitting.md) names the curve, its columns and units
(:func:`read_columns`), the modulus reported and a depth range (:func:`fit_in_range`).
"""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import numpy as np

from hertzmdr.numeric import fit, fit_batch
from hertzmdr.numeric.scene.units import UnitError, engineering, prefixed, to_si

_HEADER = re.compile(r"^\s*([A-Za-z_][\w]*)\s*\[\s*([^\]]+?)\s*\]\s*$")
#: scene shapes that have a closed-form fit model, and how to make the tip from their keys
TIP_SHAPES = {
    "sphere": lambda p: fit.Paraboloid(R=p["radius"]),
    "exact_sphere": lambda p: fit.ExactSphere(R=p["radius"]),
    "cone": lambda p: fit.Cone(theta=p["angle"]),
    "pyramid": lambda p: _pyramid_tip(p),
    "flat_punch": lambda p: fit.FlatPunch(a=p["radius"]),
    "power_law": lambda p: fit.PowerLaw(c_n=p["coefficient"], n=p["exponent"]),
    "profile": lambda p: _sampled_tip(p),
}


def _sampled_tip(p):
    """A measured tip of a scene's ``profile`` body (samples r, f [m], inline or from a file;
    the spline degree the scene's numerical MDR uses; its ``breakpoints``, the kinks)."""
    from hertzmdr.numeric.scene.shapes import SHAPES

    r, f, k = SHAPES["profile"].samples(p)
    return fit.SampledTip.from_samples(r, f, k=k, breakpoints=SHAPES["profile"].breakpoints(p))


def _pyramid_tip(p) -> fit.Pyramid:
    """The fit's pyramid (its equal-area cone) of a scene's pyramid body: its keys or preset."""
    from hertzmdr.numeric.scene.shapes.pyramid import Pyramid

    sides, alpha = Pyramid.geometry(p)
    return fit.Pyramid(alpha=alpha, sides=sides)


class CurveError(ValueError):
    """A curve or tip file that cannot be used; the message names the file and the line."""


def _read_rows(path: Path) -> tuple[int, list[str], list[tuple[int, list[str]]]]:
    """(header's line number, header cells, [(line number, cells)]) of a CSV file."""
    try:
        lines = path.read_text(encoding="utf-8-sig").splitlines()
    except FileNotFoundError:
        raise CurveError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise CurveError(f"{path}: cannot read the file ({exc})") from None
    rows = [(i + 1, r) for i, r in enumerate(csv.reader(lines))
            if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise CurveError(f"{path}: no header line (e.g. `z [um], F [nN]`)")
    return rows[0][0], rows[0][1], rows[1:]


def _unit_column(path, hline, col, dim, example):
    """The SI scale of a header cell `name [unit]` of the dimension dim."""
    m = _HEADER.match(col)
    if not m:
        raise CurveError(f"{path}:{hline}: column {col.strip()!r} must be a name and a unit "
                         f"in brackets, e.g. {example}")
    try:
        return to_si(f"1 {m.group(2)}", dim)
    except UnitError as exc:
        raise CurveError(f"{path}:{hline}: column {col.strip()!r}: {exc}") from None


def _numbers(path, rows, first, scales) -> np.ndarray:
    """The columns first, first + 1, ... of the rows as floats times their SI scales."""
    width = first + len(scales)
    data = []
    for lineno, row in rows:
        if len(row) != width:
            raise CurveError(f"{path}:{lineno}: {len(row)} values; each line has {width}")
        try:
            data.append([float(v) for v in row[first:]])
        except ValueError:
            raise CurveError(f"{path}:{lineno}: {','.join(row)!r} is not "
                             f"{'two' if len(scales) == 2 else 'four'} numbers"
                             f"{' after the curve name' if first else ''}") from None
    with np.errstate(over="ignore"):  # a value the unit takes beyond float: refused below
        arr = np.array(data, dtype=float).reshape(-1, len(scales)) * np.asarray(scales)
    if not np.isfinite(arr).all():
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise CurveError(f"{path}:{rows[bad][0]}: a value is not finite")
    return arr


def read_curve(path) -> tuple[np.ndarray, np.ndarray]:
    """Positions z [m] and forces F [N] of a curve file (format in the module docstring)."""
    path = Path(path)
    hline, header, rows = _read_rows(path)
    if len(header) != 2:
        raise CurveError(f"{path}:{hline}: the header must name two columns, position and "
                         f"force, with units, e.g. `z [um], F [nN]`; got {len(header)}")
    scales = [_unit_column(path, hline, col, dim, ex) for col, dim, ex in
              zip(header, ("length", "force"), ("`z [um]`", "`F [nN]`"), strict=True)]
    arr = _numbers(path, rows, 0, scales)
    return arr[:, 0], arr[:, 1]


def read_columns(path, columns=None, units=None) -> tuple[np.ndarray, np.ndarray]:
    """Positions z [m] and forces F [N] of a curve file as a scene's ``[fit]`` table reads it.

    ``columns`` (the header names of the position and the force column, e.g. ("z", "F")) picks
    two of any number of columns; without it the file has two. ``units`` (the SI size of one
    unit of each, [m] and [N]) is for a header without units, e.g. ``z, F``; a header that has
    them and ``units`` too is refused (the unit is given once). Neither: :func:`read_curve`.
    """
    if columns is not None and not (isinstance(columns, (list, tuple)) and len(columns) == 2
                                    and all(isinstance(c, str) for c in columns)):
        raise ValueError(f"columns = {columns!r}: the header names of the position and the "
                         "force column, two strings")
    if units is not None and not (isinstance(units, (list, tuple)) and len(units) == 2 and all(
            isinstance(u, (int, float, np.integer, np.floating)) and not isinstance(u, bool)
            and 0 < u < math.inf for u in units)):
        raise ValueError(f"units = {units!r}: the size in SI units of one unit of the position "
                         "[m] and of the force [N], two positive finite numbers")
    if columns is None and units is None:
        return read_curve(path)
    path = Path(path)
    hline, header, rows = _read_rows(path)
    names = [c.split("[", 1)[0].strip() for c in header]
    if columns is None:
        if len(header) != 2:
            raise CurveError(f"{path}:{hline}: the header names {len(header)} columns; without "
                             "[fit] columns the file has two, position and force")
        picks = [0, 1]
    else:
        picks = []
        for want, what in zip(columns, ("position", "force"), strict=True):
            if names.count(want) != 1:
                found = "twice" if names.count(want) else "not"
                raise CurveError(f"{path}:{hline}: the {what} column {want!r} of [fit] columns "
                                 f"is {found} in the header (its names: "
                                 f"{', '.join(map(repr, names))})")
            picks.append(names.index(want))
    scales = []
    for k, dim, ex, j in zip(picks, ("length", "force"), ("`z [um]`", "`F [nN]`"), (0, 1),
                             strict=True):
        given = _HEADER.match(header[k]) is not None
        if units is not None and given:
            raise CurveError(f"{path}:{hline}: column {header[k].strip()!r} gives its unit, and "
                             "so does [fit] units: give it once")
        scales.append(units[j] if units is not None else
                      _unit_column(path, hline, header[k], dim, ex))
    width = len(header)
    data = []
    for lineno, row in rows:
        if len(row) != width:
            raise CurveError(f"{path}:{lineno}: {len(row)} values; each line has {width}")
        try:
            data.append([float(row[k]) for k in picks])
        except ValueError:
            raise CurveError(f"{path}:{lineno}: {','.join(row)!r}: the position and force are "
                             "not numbers") from None
    with np.errstate(over="ignore"):  # a value the unit takes beyond float: refused below
        arr = np.array(data, dtype=float).reshape(-1, 2) * np.asarray(scales)
    if not np.isfinite(arr).all():
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise CurveError(f"{path}:{rows[bad][0]}: a value is not finite")
    return arr[:, 0], arr[:, 1]


#: most fits of a depth range before its points must have settled
RANGE_PASSES = 20


def fit_in_range(z, F, tip, depth_range, **options) -> fit.FitResult:
    """Fit the points whose z - z_0 lies in ``depth_range`` = (lowest, highest) [m], z_0 the
    fitted contact point: fit the whole curve, keep the points in the range of its z_0, fit
    them, and repeat until the points kept no longer change (at most :data:`RANGE_PASSES`
    fits; CurveError if they still change). ``options`` as :func:`fit.fit_curve`'s."""
    z, F = np.asarray(z, float), np.asarray(F, float)
    lo, hi = depth_range
    result = fit.fit_curve(z, F, tip, **options)
    keep = None
    for _ in range(RANGE_PASSES):
        d = z - result.z_0
        now = (d >= lo) & (d <= hi)
        if keep is not None and np.array_equal(now, keep):
            return result
        keep = now
        if keep.sum() < fit.MIN_POINTS:
            raise CurveError(f"[fit] depth_range [{lo:g}, {hi:g}] m of the contact point "
                             f"{result.z_0:.6g} m holds {int(keep.sum())} points; at least "
                             f"{fit.MIN_POINTS} are needed")
        result = fit.fit_curve(z[keep], F[keep], tip, **{**options, "z0": result.z_0})
    raise CurveError(f"[fit] depth_range [{lo:g}, {hi:g}] m: the points in it still change "
                     f"after {RANGE_PASSES} fits (the contact point moves with them); widen it")


def fit_table(path):
    """The ``[fit]`` table of the scene file ``path`` (:class:`..scene.schema.FitSpec`), or
    None; SceneError for a bad scene."""
    from hertzmdr.numeric import scene

    return scene.load(path).spec.fit


def is_batch(path) -> bool:
    """Whether ``hertzmdr fit`` reads path as many curves: a folder, or a CSV whose header has
    three columns (curve, z, F) or four (x, y, z, F). Unreadable files are not batches (the
    single-curve reader then names their problem)."""
    path = Path(path)
    if path.is_dir():
        return True
    try:
        return len(_read_rows(path)[1]) in (3, 4)
    except CurveError:
        return False


def read_batch(path) -> tuple[list[fit_batch.Curve], list[tuple[str, str]]]:
    """The curves of a force map or a folder of curves, and the files that could not be read.

    A folder: every ``*.csv`` in it (sorted by name) is one curve file, named by its stem; a
    file that cannot be read is returned as (name, message), not raised. A map file (CSV):
    comment lines start with ``#``; the header names either three columns ``curve, z [nm],
    F [nN]`` (a curve's name, without a unit) or four ``x [um], y [um], z [nm], F [nN]`` (the
    curve's position on the sample); every further line is one point; the points of a curve
    are the lines with the same name or position, in any order of curves.
    """
    path = Path(path)
    if path.is_dir():
        curves, failed = [], []
        files = sorted(path.glob("*.csv"))
        if not files:
            raise CurveError(f"{path}: a folder of curves, but no *.csv file in it")
        for f in files:
            try:
                z, F = read_curve(f)
            except CurveError as exc:
                failed.append((f.stem, str(exc)))
                continue
            curves.append(fit_batch.Curve(f.stem, None, None, z, F))
        return curves, failed
    hline, header, rows = _read_rows(path)
    if len(header) == 3:
        if _HEADER.match(header[0]):
            raise CurveError(f"{path}:{hline}: the first of three columns is the curve's name, "
                             f"without a unit (e.g. `curve, z [nm], F [nN]`); got "
                             f"{header[0].strip()!r}")
        scales = [_unit_column(path, hline, col, dim, ex) for col, dim, ex in
                  zip(header[1:], ("length", "force"), ("`z [um]`", "`F [nN]`"), strict=True)]
        arr = _numbers(path, rows, 1, scales)
        keys = [row[0].strip() for _, row in rows]
        pos = None
    elif len(header) == 4:
        scales = [_unit_column(path, hline, col, "length" if k < 3 else "force", ex)
                  for k, (col, ex) in enumerate(zip(header, ("`x [um]`", "`y [um]`", "`z [nm]`",
                                                             "`F [nN]`"), strict=True))]
        full = _numbers(path, rows, 0, scales)
        pos, arr = full[:, :2], full[:, 2:]
        keys = [tuple(p) for p in pos]
    else:
        raise CurveError(f"{path}:{hline}: a force map names three columns (`curve, z [nm], "
                         f"F [nN]`) or four (`x [um], y [um], z [nm], F [nN]`); got "
                         f"{len(header)}")
    if not rows:
        raise CurveError(f"{path}: no points after the header")
    groups: dict = {}
    for k, key in enumerate(keys):
        groups.setdefault(key, []).append(k)
    curves = []
    for key, idx in groups.items():
        if pos is None:
            name, x, y = key, None, None
        else:
            x, y = key
            name = f"x = {engineering(x, 'm')}, y = {engineering(y, 'm')}"
        curves.append(fit_batch.Curve(name, x, y, arr[idx, 0], arr[idx, 1]))
    return curves, []


def tip_from_scene(path):
    """(tip, sample's nu, sample's E in the scene [Pa], tip's E [Pa] or None, tip's nu or None)."""
    from hertzmdr.numeric import scene

    spec = scene.load(path).spec
    flats = [b for b in spec.bodies if b.shape == "flat"]
    if len(flats) != 1:
        raise CurveError(f"{path}: body: a fit needs one flat body (the sample) and one tip; "
                         f"this scene has {len(flats)} flat bodies")
    sample = flats[0]
    tip_body = next(b for b in spec.bodies if b is not sample)
    if sample.rigid:
        raise CurveError(f"{path}: body ({sample.name}): the sample is rigid; give its E and "
                         "nu (E is shown for comparison, nu converts E* to E)")
    if tip_body.shape not in TIP_SHAPES:
        raise CurveError(f"{path}: body ({tip_body.name}).shape: {tip_body.shape!r} has no fit "
                         f"model yet; tips: {', '.join(TIP_SHAPES)}")
    try:
        tip = TIP_SHAPES[tip_body.shape](tip_body.params)
    except ValueError as exc:
        raise CurveError(f"{path}: body ({tip_body.name}): {exc}") from None
    return tip, sample.nu, sample.E, tip_body.E, tip_body.nu


def report(result: fit.FitResult, scene_E: float | None = None) -> str:
    """The table of parameters with errors, the correlation of E* and z_0, the warnings."""
    lines = [f"tip: {result.tip.describe()}", result.table(),
             f"correlation(E*, z_0) = {result.correlation[0, 1]:+.3f}"]
    if scene_E is not None and result.E is not None:
        lines.append(f"the scene's sample E = {engineering(scene_E, 'Pa')}; fitted "
                     f"E = {engineering(result.E, 'Pa')} ± {engineering(result.E_error, 'Pa', 2)}")
    lines += [f"warning: {w}" for w in result.warnings]
    return "\n".join(lines)


def _modulus(results):
    """The modulus a batch reports: ("E", (E, its error) of a result) where the fits have a
    Poisson's ratio (the first fitted one tells), else ("E*", (E*, its error)) [Pa]."""
    ok = [r for r in results if r.ok]
    if ok and ok[0].E is not None:
        return "E", lambda r: (r.E, r.E_error)
    return "E*", lambda r: (r.values[0], r.errors[0])


def map_grids(results):
    """The maps of a force map's fits, on the grid of their positions: ``(xs, ys, grids)``,
    xs and ys the distinct x and y [m] of the curves (sorted), ``grids[k, i, j]`` the value at
    (xs[j], ys[i]) of k = 0: the modulus [Pa] (E, or E* where the fits have no Poisson's
    ratio), 1: its standard error [Pa], 2: the contact point z_0 [m] (the sample's
    topography); NaN where the curve failed or no curve was measured."""
    _, modulus = _modulus(results)
    xs = np.unique([r.x for r in results])
    ys = np.unique([r.y for r in results])
    grids = np.full((3, ys.size, xs.size), np.nan)
    for r in results:
        if r.ok:
            i, j = np.searchsorted(ys, r.y), np.searchsorted(xs, r.x)
            grids[:, i, j] = (*modulus(r), r.values[1])
    return xs, ys, grids


# The two figures below are drawing only (what they draw is a result above: the fit,
# map_grids, tested): mutation runs leave them out, as they do numeric/plots.py.
# pragma: no mutate start
def figure(result: fit.FitResult, path, title: str | None = None) -> Path:
    """Data, fit and residuals against the position, with the contact point marked (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    zs, zp = prefixed(float(np.abs(result.z).max()))
    fs, fp = prefixed(float(np.abs(result.F).max()))
    rs, rp = prefixed(float(np.abs(result.residuals).max()) or 1.0)
    fig, (ax, axr) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 5.6),
                                  gridspec_kw={"height_ratios": [3, 1]})
    ax.plot(result.z / zs, result.F / fs, ".", ms=3, color="0.5", label="data")
    ax.plot(result.z / zs, result.fitted / fs, "-", color="C3",
            label=f"fit: E* = {engineering(result.E_star, 'Pa', 4)}")
    for a in (ax, axr):
        a.axvline(result.z_0 / zs, color="C0", ls="--", lw=0.8)
    ax.set_ylabel(f"force [{fp}N]")
    ax.set_title(result.tip.describe() if title is None else
                 f"{title}; {result.tip.describe()}", fontsize=10 if title else None)
    ax.legend(loc="upper left")
    axr.plot(result.z / zs, result.residuals / rs, ".", ms=3, color="0.3")
    axr.axhline(0, color="C3", lw=0.8)
    axr.set_ylabel(f"residual [{rp}N]")
    axr.set_xlabel(f"position z [{zp}m] (dashed: contact point)")
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def map_figure(results, path, title: str) -> Path:
    """The modulus of every curve (PNG): with positions, maps of E (E* without a Poisson's
    ratio), its standard error and the contact point z_0 (the sample's topography), failed
    curves in grey; without positions, E with its error bar against the curve's index."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ok = [r for r in results if r.ok]
    label, modulus = _modulus(results)
    ms = prefixed(max((abs(modulus(r)[0]) for r in ok), default=1.0))
    if results and results[0].x is not None:
        xs, ys, grids = map_grids(results)
        ls = prefixed(float(max(np.abs(xs).max(), np.abs(ys).max())) or 1.0)
        zs = prefixed(float(np.nanmax(np.abs(grids[2]))) if ok else 1.0)
        fig, axes = plt.subplots(1, 3, figsize=(13.5, 4.2))
        es = prefixed(float(np.nanmax(grids[1])) if ok else 1.0)
        panels = [(grids[0] / ms[0], f"{label} [{ms[1]}Pa]", "viridis"),
                  (grids[1] / es[0], f"std. error of {label} [{es[1]}Pa]", "magma"),
                  (grids[2] / zs[0], f"contact point z_0 [{zs[1]}m]", "cividis")]
        ext = [xs[0] / ls[0], xs[-1] / ls[0], ys[0] / ls[0], ys[-1] / ls[0]]
        half = [np.diff(xs).min() / 2 if xs.size > 1 else 0.5 * ls[0],
                np.diff(ys).min() / 2 if ys.size > 1 else 0.5 * ls[0]]
        ext = [ext[0] - half[0] / ls[0], ext[1] + half[0] / ls[0],
               ext[2] - half[1] / ls[0], ext[3] + half[1] / ls[0]]
        for ax, (grid, name, cmap) in zip(axes, panels, strict=True):
            cm = plt.get_cmap(cmap).with_extremes(bad="0.75")
            im = ax.imshow(np.ma.masked_invalid(grid), origin="lower", extent=ext, cmap=cm,
                           interpolation="nearest")
            fig.colorbar(im, ax=ax, shrink=0.85, label=name)
            ax.set_xlabel(f"x [{ls[1]}m]")
            ax.set_ylabel(f"y [{ls[1]}m]")
            ax.set_title(name.split(" [")[0])
        failed = len(results) - len(ok)
        fig.suptitle(f"{title}: {len(ok)} of {len(results)} curves fitted"
                     + (f" ({failed} failed: grey)" if failed else ""))
    else:
        fig, ax = plt.subplots(figsize=(7.5, 4.2))
        idx = [k for k, r in enumerate(results) if r.ok]
        vals = np.array([modulus(r) for r in ok]).reshape(-1, 2) / ms[0]
        ax.errorbar(idx, vals[:, 0], yerr=vals[:, 1], fmt="o", ms=3, capsize=2)
        for k, r in enumerate(results):
            if not r.ok:
                ax.axvline(k, color="0.75", lw=3, zorder=0)
        ax.set_xlabel("curve (in the order of the table; grey: failed)")
        ax.set_ylabel(f"{label} [{ms[1]}Pa]")
        ax.set_title(f"{title}: {len(ok)} of {len(results)} curves fitted")
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# pragma: no mutate end


def batch_summary(results, scene_E: float | None = None) -> str:
    """A few lines: curves fitted, failed and with warnings; the modulus over the fitted ones."""
    ok = [r for r in results if r.ok]
    warned = sum(bool(r.warnings) for r in ok)
    lines = [f"{len(results)} curves: {len(ok)} fitted ({warned} with warnings), "
             f"{len(results) - len(ok)} failed"]
    if ok:
        name, modulus = _modulus(results)
        vals, errs = np.array([modulus(r) for r in ok]).T
        lines.append(f"{name}: median {engineering(float(np.median(vals)), 'Pa')}, from "
                     f"{engineering(float(vals.min()), 'Pa')} to "
                     f"{engineering(float(vals.max()), 'Pa')}; median standard error "
                     f"{engineering(float(np.median(errs)), 'Pa', 2)}")
        if ok[0].dgamma is not None:  # an adhesive batch
            dg = np.array([r.dgamma for r in ok])
            dg_err = np.array([r.dgamma_error for r in ok])
            lines.append(f"work of adhesion: median {float(np.median(dg)):.4g} J/m^2, from "
                         f"{float(dg.min()):.4g} to {float(dg.max()):.4g} J/m^2; median "
                         f"standard error {float(np.median(dg_err)):.2g} J/m^2")
    if scene_E is not None:
        lines.append(f"the scene's sample E = {engineering(scene_E, 'Pa')} (not used)")
    return "\n".join(lines)
