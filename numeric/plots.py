"""Figures of the chapter drawn from the generated formulas (matplotlib, the ``plot`` extra).

Each function writes one PNG and returns its path; matplotlib is imported inside the functions
with the non-interactive Agg backend, so importing this module needs neither.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hertzmdr.numeric import stress
from hertzmdr.numeric._validate import poisson

__all__ = ["axis_stresses_figure", "von_mises_figure"]


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def axis_stresses_figure(path, nu: float = 0.33, z_max: float = 3.0) -> Path:
    """Fig. 5.8: sigma_zz (5.48), sigma_xx = sigma_yy (5.49) and tau_1 on the axis, over p0,
    against z/a under the Hertz pressure, with the maximum of tau_1 marked.

    Parameters
    ----------
    path : str or Path
        PNG file to write.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5 (the chapter's figure: 0.33).
    z_max : float
        Depth range 0 <= z/a <= z_max.

    Returns
    -------
    Path
        The file written.

    Examples
    --------
    >>> hertzmdr.numeric.plots.axis_stresses_figure("fig5_8.png", nu=0.33)  # doctest: +SKIP
    """
    nu = float(poisson("nu", nu))
    s = np.linspace(0.0, z_max, 601)
    szz, sxx = stress.axis_stresses(s, 1.0, 1.0, nu)
    tau1 = 0.5 * np.abs(szz - sxx)
    zm, tm = stress.axis_max_shear(nu)
    return draw_axis_stresses(
        path, s, szz, sxx, tau1, xlabel="z / a", ylabel="stress / p0",
        title=f"Stresses on the axis under the Hertz pressure, nu = {nu:g} (Fig. 5.8)",
        mark=(zm, tm, f"max {tm:.4f} p0 at z = {zm:.4f} a"), ylim=(-1.05, 0.45))


def draw_axis_stresses(path, z, szz, sxx, tau1, *, xlabel, ylabel, title, mark=None,
                       ylim=None, syy=None) -> Path:
    """Draw sigma_zz, sigma_xx = sigma_yy and tau_1 against depth (the layout of Fig. 5.8),
    from arrays in any units; ``mark`` = (z, tau, text) annotates the maximum. With ``syy``
    (a line contact, plane strain) sigma_xx and sigma_yy differ: both are drawn, and tau_1 is
    the 3-D (sigma_1 - sigma_3)/2."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.2), dpi=120)
    if syy is None:
        ax.plot(z, szz, label=r"$\sigma_{zz}$ (5.48)")
        ax.plot(z, sxx, label=r"$\sigma_{xx}=\sigma_{yy}$ (5.49)")
        ax.plot(z, tau1, label=r"$\tau_1=|\sigma_{zz}-\sigma_{xx}|/2$")
    else:
        ax.plot(z, szz, label=r"$\sigma_{zz}$")
        ax.plot(z, sxx, label=r"$\sigma_{xx}$")
        ax.plot(z, syy, label=r"$\sigma_{yy}=\nu(\sigma_{xx}+\sigma_{zz})$")
        ax.plot(z, tau1, label=r"$(\sigma_1-\sigma_3)/2$")
    if mark is not None:
        zm, tm, text = mark
        ax.plot([zm], [tm], "ko", ms=4)
        ax.annotate(text, (zm, tm), xytext=(0.35, 0.9), textcoords="axes fraction",
                    arrowprops={"arrowstyle": "->"}, fontsize=8)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    out = Path(path)
    fig.savefig(out)
    plt.close(fig)
    return out


def von_mises_figure(path, nu: float = 0.33, x_max: float = 2.0, z_max: float = 2.0,
                     n: int = 241) -> Path:
    """Fig. 5.9: the von Mises stress (5.50) over p0 in the x-z plane under the Hertz pressure.

    Parameters
    ----------
    path : str or Path
        PNG file to write.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    x_max, z_max : float
        Plotted region -x_max <= x/a <= x_max, 0 <= z/a <= z_max (depth drawn downwards).
    n : int
        Grid points per axis.

    Returns
    -------
    Path
        The file written.

    Examples
    --------
    >>> hertzmdr.numeric.plots.von_mises_figure("fig5_9.png", nu=0.33)  # doctest: +SKIP
    """
    nu = float(poisson("nu", nu))
    x = np.linspace(-x_max, x_max, n)
    z = np.linspace(0.0, z_max, n)
    X, Z = np.meshgrid(x, z)
    vm = stress.von_mises(stress.hertz_stress(X, 0.0, Z, 1.0, 1.0, nu))
    val, _, zb = stress.hertz_maximum(nu)
    return draw_von_mises(
        path, X, Z, vm, xlabel="x / a", ylabel="z / a", clabel=r"$\sigma_V / p_0$ (5.50)",
        title=f"von Mises stress / p0 under the Hertz pressure, nu = {nu:g} (Fig. 5.9)",
        mark=(0.0, zb, f"max {val:.4f} p0 at z = {zb:.4f} a"))


def draw_von_mises(path, X, Z, vm, *, xlabel, ylabel, clabel, title, mark=None) -> Path:
    """Draw a von Mises map in the x-z plane, depth downwards (the layout of Fig. 5.9), from
    grids in any units; ``mark`` = (x, z, text) annotates the maximum."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.8), dpi=120)
    top = float(np.nanmax(vm))
    cs = ax.contourf(X, Z, vm, levels=np.linspace(0, top, 41), cmap="viridis")
    ax.contour(X, Z, vm, levels=np.linspace(0.1, 0.9, 5) * top, colors="w", linewidths=0.5)
    if mark is not None:
        xm, zm, text = mark
        ax.plot([xm], [zm], "r+", ms=10)
        ax.annotate(text, (xm, zm), xytext=(0.03, 0.08), textcoords="axes fraction",
                    color="w", arrowprops={"arrowstyle": "->", "color": "w"})
    ax.set_ylim(float(np.max(Z)), 0.0)
    ax.set_aspect("equal")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    # ticks at round values, 1, 2, 2.5 or 5 times a power of ten apart (the contour levels,
    # top/40 apart, are not)
    from matplotlib.ticker import MaxNLocator

    fig.colorbar(cs, ax=ax, label=clabel, ticks=MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]))
    fig.tight_layout()
    out = Path(path)
    fig.savefig(out)
    plt.close(fig)
    return out
