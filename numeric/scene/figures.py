"""PNG figures of the field effects (matplotlib, the optional ``plot`` extra).

One function per field effect, all with the signature ``draw(value, title, path, ctx)``
(``ctx`` a :class:`Context`: what the figure needs to know of the contact beyond the value);
the table :data:`FIGURES` maps effect names to them. matplotlib is imported only when a figure
is drawn.

Every profile plot (pressure, surface displacement, MDR profile, traction) marks the contact's
extent along its axis: the contact radius a, a line contact's half-width, an elliptical
contact's semi-axis along x, a prescribed pressure's loaded radius.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Context:
    """What a figure needs beyond its value.

    Attributes
    ----------
    kind : str
        The model's kind (``"hertz"``, ``"line"``, ``"elliptic"``, ``"pressure"``, ...).
    extent : float or None
        The contact's extent [m] along the plotted line at the drawn (largest) load, or None
        when the run has no contact state (or the kind no extent: the BEM).
    extent_label : str
        Its name on the plot.
    fig52 : bool
        Whether the surface displacement is the one of Fig. 5.2 (the Hertzian pressure (5.15)).
    """

    kind: str = ""
    extent: float | None = None
    extent_label: str = "a"
    fig52: bool = False


#: the name of the contact's extent on a profile plot, by kind (default: the contact radius)
EXTENT_LABELS = {"line": "a (half-width)", "elliptic": "a (semi-axis along x)",
                 "pressure": "a (loaded radius)"}


def context_of(run) -> Context:
    """The :class:`Context` of a run (runner.Run): its kind and its extent at the largest load
    (from the kind's ``extent(d)``, when the run evaluated the contact state)."""
    contact = getattr(run, "contact", None)
    if contact is None:  # a study (study.StudyRun): one contact per point, nothing to mark
        return Context()
    kind = contact.kind
    st = run._nodes.get("state")
    extent = None
    if st is not None and callable(getattr(contact, "extent", None)):
        extent = float(contact.extent(contact.last(st)))
    fig52 = kind == "hertz" or (kind == "pressure" and contact.distribution == "hertzian")
    return Context(kind, extent, EXTENT_LABELS.get(kind, "a (contact radius)"), fig52)


def _plt():
    try:
        import matplotlib
    except ImportError:
        raise RuntimeError("figures need matplotlib: pip install 'hertzmdr[plot]'") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _scale(values) -> tuple[float, str]:
    """(scale, prefix) of the SI prefix that suits the largest finite magnitude of values."""
    import numpy as np

    from hertzmdr.numeric.scene.units import prefixed

    v = np.asarray(values, dtype=float)
    finite = np.abs(v[np.isfinite(v)])
    return prefixed(float(finite.max()) if finite.size else 1.0)


def _scaled(values, name: str, unit: str):
    """Values divided by the SI prefix that suits their largest magnitude, and the axis label."""
    import numpy as np

    scale, prefix = _scale(values)
    return np.asarray(values, dtype=float) / scale, f"{name} [{prefix}{unit}]"


def mark_extent(ax, ctx: Context, scale: float) -> None:
    """A dashed vertical line at the contact's extent (x axis in units of ``scale`` [m]),
    labelled; nothing when the extent is unknown. Its gid is ``contact-extent``."""
    if ctx.extent is None or not ctx.extent > 0:
        return
    x = ctx.extent / scale
    ax.axvline(x, ls="--", lw=1.0, color="0.35", gid="contact-extent")
    ax.annotate(ctx.extent_label, (x, 1.0), xycoords=("data", "axes fraction"),
                xytext=(3, -12), textcoords="offset points", fontsize=8, color="0.25")


def _line(x, y, xname, xunit, yname, yunit, title, path, ctx: Context | None = None):
    """y against x; with ``ctx`` the contact's extent marked on the x axis."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), dpi=120)
    xscale, xprefix = _scale(x)
    xs, xlabel = _scaled(x, xname, xunit)
    ys, ylabel = _scaled(y, yname, yunit)
    ax.plot(xs, ys, lw=1.8)
    if ctx is not None:
        mark_extent(ax, ctx, xscale)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def pressure_profile(value, title, path, ctx: Context = Context()):
    """Pressure against radius (Figs. 5.7 b and 5.17); a line contact's against x, the
    distance across the strip; an elliptical contact's along x (the semi-axis a)."""
    xname = {"line": "x (across the strip)", "elliptic": "x (along a)"}.get(ctx.kind, "r")
    _line(value["r"], value["p"], xname, "m", "p", "Pa", f"{title}\npressure distribution",
          path, ctx)


def surface_displacement(value, title, path, ctx: Context = Context()):
    """Surface displacement inside and outside the contact; captioned Fig. 5.2 only where it
    is that figure's (the Hertzian pressure (5.15))."""
    import numpy as np

    caption = "surface displacement" + (" (Fig. 5.2)" if ctx.fig52 else "")
    _line(value["r"], -np.asarray(value["u"]), "r", "m", "surface position -u_z", "m",
          f"{title}\n{caption}", path, ctx)


def force_depth_curve(value, title, path, ctx: Context = Context()):
    """Force against indentation depth."""
    _line(value["depth"], value["force"], "depth", "m", "force", "N",
          f"{title}\nforce-depth curve", path)


def mdr_profile(value, title, path, ctx: Context = Context()):
    """The MDR's equivalent profile g(x) (Figs. 5.11, 5.19)."""
    _line(value["x"], value["g"], "x", "m", "g(x)", "m", f"{title}\nMDR profile g(x) (5.52)",
          path, ctx)


def _axis_stresses_ellipse(value, title, path):
    """The three normal stresses and tau_1 on the axis of an elliptical contact."""
    import numpy as np

    from hertzmdr.numeric import plots

    z, zlabel = _scaled(value["z"], "z", "m")
    keys = ("sigma_xx", "sigma_yy", "sigma_zz", "tau_1")
    top = max(float(np.max(np.abs(value[k]))) for k in keys)
    scale, slabel = _scaled([top], "stress", "Pa")
    f = float(scale[0]) / top
    plt = plots._pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.2), dpi=120)
    for k, label in zip(keys, (r"$\sigma_{xx}$ (along a)", r"$\sigma_{yy}$ (along b)",
                               r"$\sigma_{zz}$", r"$\tau_1$"), strict=True):
        ax.plot(z, np.asarray(value[k]) * f, label=label)
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(zlabel)
    ax.set_ylabel(slabel)
    ax.set_title(f"{title}\nstresses on the axis of the elliptical contact", fontsize=9)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def axis_stresses(value, title, path, ctx: Context = Context()):
    """Stresses on the axis (the layout of Fig. 5.8), in the scene's units."""
    import numpy as np

    from hertzmdr.numeric import plots

    if "sigma_xx" in value and "sigma_rr" not in value:  # an elliptical contact
        return _axis_stresses_ellipse(value, title, path)
    z, zlabel = _scaled(value["z"], "z", "m")
    top = max(float(np.max(np.abs(value[k]))) for k in ("sigma_zz", "sigma_rr", "tau_1"))
    scale, slabel = _scaled([top], "stress", "Pa")
    f = float(scale[0]) / top
    line = "sigma_yy" in value  # a line contact (plane strain): sigma_rr is sigma_xx
    plots.draw_axis_stresses(path, z, np.asarray(value["sigma_zz"]) * f,
                             np.asarray(value["sigma_rr"]) * f, np.asarray(value["tau_1"]) * f,
                             xlabel=zlabel, ylabel=slabel,
                             title=f"{title}\nstresses on the axis "
                             + ("(plane strain)" if line else "(Fig. 5.8)"),
                             syy=np.asarray(value["sigma_yy"]) * f if line else None)


def von_mises_field(value, title, path, ctx: Context = Context()):
    """The von Mises stress in the x-z plane (the layout of Fig. 5.9), in the scene's units."""
    import numpy as np

    from hertzmdr.numeric import plots

    x, xlabel = _scaled(value["x"], "x", "m")
    factor = float(x[-1]) / float(value["x"][-1]) if value["x"][-1] else 1.0
    z = np.asarray(value["z"]) * factor
    sv, clabel = _scaled(value["sigma_v"], "von Mises stress", "Pa")
    X, Z = np.meshgrid(x, z)
    plots.draw_von_mises(path, X, Z, sv, xlabel=xlabel, ylabel=xlabel.replace("x [", "z ["),
                         clabel=clabel, title=f"{title}\nvon Mises stress (5.50), Fig. 5.9")


def adhesive_force_depth_curve(value, title, path, ctx: Context = Context()):
    """Approach (solid) and retract (dashed) of an adhesive contact, the jumps as dotted
    segments with markers."""
    import numpy as np

    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), dpi=120)
    d, dlabel = _scaled(value["depth"], "depth", "m")
    F, Flabel = _scaled(value["force"], "force", "N")

    def factor(raw, scaled):  # the factor _scaled applied, for the jumps' end points
        i = int(np.argmax(np.abs(raw)))
        return float(scaled[i] / raw[i]) if raw[i] else 1.0

    fd = factor(np.asarray(value["depth"], float), d)
    fF = factor(np.asarray(value["force"], float), F)
    load = np.asarray(value["loading"], bool)
    ax.plot(d[load], F[load], lw=1.8, label="approach and push")
    ax.plot(d[~load], F[~load], lw=1.8, ls="--", label="retract")
    jd, jF = np.asarray(value["jump_depth"], float), np.asarray(value["jump_force"], float)
    for k in range(len(jd)):
        ax.plot(jd[k] * fd, jF[k] * fF, ls=":", color="k", marker="o", ms=3,
                label="jumps" if k == 0 else None)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel(dlabel)
    ax.set_ylabel(Flabel)
    ax.set_title(f"{title}\nadhesive approach-retract", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def traction_profile(value, title, path, ctx: Context = Context()):
    """Tangential traction against radius: mu (p(a) - p(c)) in the stick zone."""
    _line(value["r"], value["q"], "r", "m", "q", "Pa", f"{title}\ntangential traction", path,
          ctx)


def hysteresis_loop(value, title, path, ctx: Context = Context()):
    """Tangential force against displacement: the first loading (dashed) and the loop of
    Masing's branches."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), dpi=120)
    u, xlabel = _scaled(value["u"], "u_x", "m")
    F, ylabel = _scaled(value["F"], "F_x", "N")
    k = next((i for i in range(1, len(u)) if u[i] < u[i - 1]), len(u))  # the first turn
    ax.plot(u[:k], F[:k], "--", lw=1.4, label="first loading")
    ax.plot(u[k - 1:], F[k - 1:], lw=1.8, label="Masing branches F* - 2 F((u* - u)/2)")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(f"{title}\nhysteresis loop (Mindlin-Deresiewicz)", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


FIGURES = {
    "adhesive_force_depth_curve": adhesive_force_depth_curve,

    "traction_profile": traction_profile,
    "hysteresis_loop": hysteresis_loop,
    "axis_stresses": axis_stresses,
    "von_mises_field": von_mises_field,
    "mdr_profile": mdr_profile,
    "pressure_profile": pressure_profile,
    "surface_displacement": surface_displacement,
    "force_depth_curve": force_depth_curve,
}


def plain(title: str) -> str:
    """A scene's title as plain text for matplotlib: ``$`` escaped (two of them would start
    mathtext, which raises on what it cannot parse) and control characters dropped."""
    return "".join(c for c in title if c.isprintable() or c == "\n").replace("$", r"\$")


def write_all(results: dict, title: str, folder: Path, ctx: Context = Context()) -> list[Path]:
    """Draw every field effect of ``results`` that has a figure into ``folder`` (``ctx``: the
    run's :func:`context_of`). A title's characters that the font lacks are drawn as boxes,
    silently; every figure opened here is closed, also when drawing fails."""
    import warnings

    if not any(name in FIGURES for name in results):
        return []  # nothing to draw: matplotlib (an extra) is not needed
    plt = _plt()
    before = set(plt.get_fignums())
    written = []
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="Glyph .* missing", category=UserWarning)
            for name, res in results.items():
                if name in FIGURES:
                    path = folder / f"{name}.png"
                    FIGURES[name](res.value, plain(title), path, ctx)
                    written.append(path)
    finally:
        for num in set(plt.get_fignums()) - before:
            plt.close(num)
    return written
