"""Files of ``hertzmdr fit``: a force curve from CSV, its tip from a scene, a figure of the fit.

The curve file (CSV, UTF-8): lines starting with ``#`` are comments; the first other line is
the header naming the two columns with their units in brackets, the position first and the
force second, e.g. ``z [um], F [nN]``; every further line is one point. The units are any
length and force pint reads (``nm``, ``um``, ``m``; ``pN``, ``nN``, ``N``).

The tip file is a scene (docs/scenes.md) with its two bodies: the sample is the ``flat`` body
(its ``nu`` gives the sample's Young's modulus beside E*; its ``E``, which a scene requires, is
shown beside the fitted one for comparison, not used), the tip is the other body (``sphere``:
the paraboloid of Hertz, ``exact_sphere``, ``cone``, ``flat_punch`` or ``power_law``; rigid or
elastic). The scene's effects and load are not used.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import numpy as np

from hertzmdr.numeric import fit
from hertzmdr.numeric.scene.units import UnitError, engineering, prefixed, to_si

_HEADER = re.compile(r"^\s*([A-Za-z_][\w]*)\s*\[\s*([^\]]+?)\s*\]\s*$")
#: scene shapes that have a closed-form fit model, and how to make the tip from their keys
TIP_SHAPES = {
    "sphere": lambda p: fit.Paraboloid(R=p["radius"]),
    "exact_sphere": lambda p: fit.ExactSphere(R=p["radius"]),
    "cone": lambda p: fit.Cone(theta=p["angle"]),
    "flat_punch": lambda p: fit.FlatPunch(a=p["radius"]),
    "power_law": lambda p: fit.PowerLaw(c_n=p["coefficient"], n=p["exponent"]),
}


class CurveError(ValueError):
    """A curve or tip file that cannot be used; the message names the file and the line."""


def read_curve(path) -> tuple[np.ndarray, np.ndarray]:
    """Positions z [m] and forces F [N] of a curve file (format in the module docstring)."""
    path = Path(path)
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
    hline, header = rows[0]
    if len(header) != 2:
        raise CurveError(f"{path}:{hline}: the header must name two columns, position and "
                         f"force, with units, e.g. `z [um], F [nN]`; got {len(header)}")
    scales = []
    for col, dim in zip(header, ("length", "force"), strict=True):
        m = _HEADER.match(col)
        if not m:
            raise CurveError(f"{path}:{hline}: column {col.strip()!r} must be a name and a unit "
                             f"in brackets, e.g. `z [um]` or `F [nN]`")
        try:
            scales.append(to_si(f"1 {m.group(2)}", dim))
        except UnitError as exc:
            raise CurveError(f"{path}:{hline}: column {col.strip()!r}: {exc}") from None
    data = []
    for lineno, row in rows[1:]:
        if len(row) != 2:
            raise CurveError(f"{path}:{lineno}: {len(row)} values; each line has two (position, "
                             "force)")
        try:
            data.append([float(v) for v in row])
        except ValueError:
            raise CurveError(f"{path}:{lineno}: {','.join(row)!r} is not two numbers") from None
    arr = np.array(data, dtype=float).reshape(-1, 2)
    if not np.isfinite(arr).all():
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise CurveError(f"{path}:{rows[1 + bad][0]}: a value is not finite")
    return arr[:, 0] * scales[0], arr[:, 1] * scales[1]


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
                         f"model yet; closed-form tips: {', '.join(TIP_SHAPES)}")
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


def figure(result: fit.FitResult, path) -> Path:
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
    ax.set_title(result.tip.describe())
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
