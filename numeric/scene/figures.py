"""PNG figures of the field effects (matplotlib, the optional ``plot`` extra).

One function per field effect, all with the signature ``draw(value, title, path)``; the table
:data:`FIGURES` maps effect names to them. matplotlib is imported only when a figure is drawn.
"""

from __future__ import annotations

from pathlib import Path


def _plt():
    try:
        import matplotlib
    except ImportError:
        raise RuntimeError("figures need matplotlib: pip install 'hertzmdr[plot]'") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _line(x, y, xlabel, ylabel, title, path, *, xscale=1.0, yscale=1.0):
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), dpi=120)
    ax.plot([v / xscale for v in x], [v / yscale for v in y], lw=1.8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def pressure_profile(value, title, path):
    """Pressure against radius (Figs. 5.7 b and 5.17)."""
    _line(value["r"], value["p"], "r [mm]", "p [MPa]", f"{title}\npressure distribution",
          path, xscale=1e-3, yscale=1e6)


def surface_displacement(value, title, path):
    """Surface displacement inside and outside the contact (Fig. 5.2)."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), dpi=120)
    r = [v * 1e3 for v in value["r"]]
    ax.plot(r, [-v * 1e6 for v in value["u"]], lw=1.8)
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("surface position -u_z [µm]")
    ax.set_title(f"{title}\nsurface displacement (Fig. 5.2)", fontsize=10)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def force_depth_curve(value, title, path):
    """Force against indentation depth."""
    _line(value["depth"], value["force"], "depth [µm]", "force [N]",
          f"{title}\nforce-depth curve", path, xscale=1e-6)


FIGURES = {
    "pressure_profile": pressure_profile,
    "surface_displacement": surface_displacement,
    "force_depth_curve": force_depth_curve,
}


def write_all(results: dict, title: str, folder: Path) -> list[Path]:
    """Draw every field effect of ``results`` that has a figure into ``folder``."""
    written = []
    for name, res in results.items():
        if name in FIGURES:
            path = folder / f"{name}.png"
            FIGURES[name](res.value, title, path)
            written.append(path)
    return written
