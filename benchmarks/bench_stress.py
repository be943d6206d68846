"""Benchmark of the stress fields; writes docs/stress.md (with the figures and the maxima),
keeping its line-contact section (bench_line_stress.py's) as it was.

Run: ``.venv/bin/python benchmarks/bench_stress.py [--quick] [--out DIR]`` (``make benchmark``
runs it; ``--quick``: a 40 x 40 grid, two superposition settings at 5 points). Timings by
``hertzmdr.numeric._timing`` on this machine; the accuracy figures are against the closed form
(itself verified to ~1e-15 by tests/test_stress.py).
"""

from __future__ import annotations

import _common
import mpmath as mp
import numpy as np

from hertzmdr.derive import stress as ds
from hertzmdr.numeric import _timing, plots, stress

GRID, GRID_QUICK = 200, 40
SETTINGS = ((8, 1), (16, 2), (32, 3), (64, 4), (64, 5))  # (n_psi, tanh-sinh level)
SETTINGS_QUICK = ((8, 1), (16, 2))


def closed_form_grid(m=GRID):
    x = np.linspace(-2, 2, m)
    z = np.linspace(0, 2, m)
    X, Z = np.meshgrid(x, z)
    return stress.von_mises(stress.hertz_stress(X, 0.0, Z, 1.0, 1.0, 0.3))


def superposition_table(settings=SETTINGS, npts=20):
    hp = lambda r: np.sqrt(np.maximum(1 - r * r, 0.0))  # noqa: E731
    rng = np.random.default_rng(1)
    pts = np.column_stack([rng.uniform(0, 2, npts), np.zeros(npts),
                           np.exp(rng.uniform(np.log(0.01), np.log(2), npts))])
    ref = stress.hertz_stress(pts[:, 0], pts[:, 1], pts[:, 2], 1.0, 1.0, 0.3)
    scale = np.max(np.abs(ref), axis=(-2, -1))
    rows = []
    for n_psi, level in settings:
        (sig, err), t = _timing.timed(lambda n_psi=n_psi, level=level: stress.superposed_stress(
            pts[:, 0], pts[:, 1], pts[:, 2], hp, 1.0, 0.3, n_psi=n_psi, level=level))
        dt = t / len(pts)
        actual = np.max(np.abs(sig - ref), axis=(-2, -1)) / scale
        est = np.max(err, axis=(-2, -1)) / scale
        rows.append((n_psi, level, dt, actual.max(), est.max()))
    return rows


def contactmechanics_table(m, budget):
    """hertzmdr and ContactMechanics's Hertz reference solutions on the same m^3 points (x, y
    log-spaced in +-[1e-8, 2] a: near the axis too; z log-spaced in [1e-3, 2] a) and m^3
    surface radii (log-spaced in [1e-3, 1e5] a): times (rounds interleaved), their ratio, and
    the largest difference. None when ContactMechanics is not installed."""
    cm = _common.peer("ContactMechanics.ReferenceSolutions.Hertz", "contactmechanics",
                      "the ContactMechanics comparison")
    if cm is None:
        return None
    from hertzmdr.numeric import hertz

    nu = 0.3
    half = np.geomspace(1e-8, 2, m // 2)
    xs = np.concatenate([-half[::-1], half])
    X, Y, Z = np.meshgrid(xs, xs, np.geomspace(1e-3, 2, m), indexing="ij")
    x, y, z = X.ravel(), Y.ravel(), Z.ravel()
    r = np.hypot(x, y)
    rs = np.geomspace(1e-3, 1e5, m**3)
    # units: a = 1, p0 = 1 (ContactMechanics's); its u_z is in p0 a/E*, negative into the
    # body: with R = 1, d = a^2/R = 1, p0 = 2 E* a/(pi R) (5.22), hertzmdr's u_z = -(2/pi) u
    cases = {
        "Hertz stress field, Cartesian": (
            lambda: stress.hertz_stress(x, y, z, 1.0, 1.0, nu),
            lambda: cm.stress_Cartesian(x, y, z, poisson=nu),
            lambda s, c: np.max(np.abs(np.stack(
                [s[:, 0, 0], s[:, 1, 1], s[:, 2, 2], s[:, 1, 2], s[:, 0, 2], s[:, 0, 1]])
                - np.stack(c))), "p0"),
        "same, cylindrical components": (
            lambda: stress.hertz_stress_cylindrical(r, z, 1.0, 1.0, nu),
            lambda: cm.stress(r, z, poisson=nu),
            lambda s, c: np.max(np.abs(np.stack(s) - np.stack((c[1], c[0], c[2], c[3])))),
            "p0"),
        "Hertz surface displacement": (
            lambda: hertz.surface_displacement(rs, 1.0, 1.0),
            lambda: cm.surface_displacements(rs),
            lambda s, c: np.max(np.abs(-2 / np.pi * c / s - 1)), "relative"),
    }
    rows = []
    for name, (ours, theirs, diff, unit) in cases.items():
        t = _timing.compare({"hertzmdr": ours, "ContactMechanics": theirs}, budget)
        rows.append((name, t["hertzmdr"].median, t["ContactMechanics"].median,
                     _timing.ratio(t["hertzmdr"], t["ContactMechanics"]),
                     float(diff(ours(), theirs())), unit))
    return rows


def main(argv=None):
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    m = GRID_QUICK if args.quick else GRID
    t_grid = _timing.measure(lambda: closed_form_grid(m), run.budget)
    vm = closed_form_grid(m)
    if not np.all(np.isfinite(vm)):
        raise RuntimeError("the closed-form von Mises field is not finite on the grid")
    rows = (superposition_table(SETTINGS_QUICK, 5) if args.quick else superposition_table())
    cm_m = 10 if args.quick else 100
    cm_rows = contactmechanics_table(
        cm_m, run.budget if args.quick else _timing.Budget(repeats=3, min_time=0.0))
    figures = run.docs / "figures"
    figures.mkdir(exist_ok=True)
    fig8 = plots.axis_stresses_figure(figures / "fig5_8_axis_stresses.png", nu=0.33)
    fig9 = plots.von_mises_figure(figures / "fig5_9_von_mises.png", nu=0.33)
    maxima = []
    for nu in ("0.3", "0.33"):
        z30, t30 = ds.axis_maxima(nu)
        vm_val, vr, vz = stress.hertz_maximum(float(nu), "von_mises")
        maxima.append((nu, mp.nstr(z30, 30), mp.nstr(t30, 30), mp.nstr(2 * t30, 30), vm_val,
                       vr, vz))
    lines = [
        "# Stresses under the Hertz contact\n\n",
        "<!-- Written by `benchmarks/bench_stress.py`; rerun it to refresh. -->\n\n",
        f"{_timing.conditions()}\n\n",
        "## Maxima on the axis (derived; 30 digits)\n\n",
        "The maximum shear stress tau_1 = (sigma_xx - sigma_zz)/2 on the axis peaks at the root "
        "of d(tau_1)/dz of the derived (5.48), (5.49) (`hertzmdr.derive.stress.axis_maxima`). "
        "The von Mises stress (5.50) on the axis is 2 tau_1; the search over the whole body "
        "(`hertzmdr.numeric.stress.hertz_maximum`) finds its maximum on the axis at the same "
        "depth; so does Tresca (= 2 tau_1 there).\n\n",
        "| nu | depth z/a | tau_1/p0 | von Mises/p0 | body search: von Mises/p0 at (r/a, z/a) |\n",
        "|---|---|---|---|---|\n",
    ]
    for nu, z30, t30, v30, vm_val, vr, vz in maxima:
        lines.append(f"| {nu} | {z30} | {t30} | {v30} | {vm_val:.15f} at ({vr:.1e}, "
                     f"{vz:.8f}) |\n")
    lines += [
        "\nThe chapter: z ~ 0.49 a for nu = 0.33 (Fig. 5.8); the classical tau_1 ~ 0.31 p0 at "
        "z ~ 0.48 a for nu = 0.3.\n\n",
        "## Figures\n\n",
        f"![Fig. 5.8](figures/{fig8.name})\n\n",
        "`hertzmdr.numeric.plots.axis_stresses_figure(path, nu=0.33)`\n\n",
        f"![Fig. 5.9](figures/{fig9.name})\n\n",
        "`hertzmdr.numeric.plots.von_mises_figure(path, nu=0.33)`\n\n",
        "## Speed: closed form\n\n",
        f"von Mises field on a {m} x {m} x-z grid (closed form, `hertz_stress` + `von_mises`): "
        f"**{t_grid.median * 1e3:.1f} ms** (median of {len(t_grid.rounds)} rounds; first call "
        f"{t_grid.first * 1e3:.1f} ms; goal <= 1 s).\n\n",
        "## Side by side with ContactMechanics\n\n",
    ]
    if cm_rows is None:
        lines.append("contactmechanics is not installed for this run: its comparison is "
                     "skipped.\n\n")
    else:
        lines += [
            f"The Hertz reference solutions of ContactMechanics "
            f"{_common.version('contactmechanics')} (`ContactMechanics.ReferenceSolutions."
            f"Hertz`: `stress_Cartesian`, `stress`, `surface_displacements`) and hertzmdr's "
            f"(`stress.hertz_stress`, `stress.hertz_stress_cylindrical`, "
            f"`hertz.surface_displacement`) on the same {cm_m ** 3:,} points: x, y "
            f"log-spaced in +-[1e-8, 2] a ({cm_m} each: the axis is approached to 1e-8 a), z "
            f"log-spaced in [1e-3, 2] a ({cm_m}), nu = 0.3; the displacement at "
            f"{cm_m ** 3:,} radii log-spaced in [1e-3, 1e5] a. Medians of "
            f"the interleaved rounds; the ratio from the same run. 'largest difference': "
            "over all points and components; hertzmdr's fields are checked against 30-digit "
            "references to ~1e-15 p0 (tests/test_stress.py, tests/test_hertz.py), so the "
            "difference is ContactMechanics's error to that accuracy.\n\n",
            "| what | hertzmdr [s] | ContactMechanics [s] | hertzmdr / ContactMechanics | "
            "largest difference |\n|---|---|---|---|---|\n"]
        for name, t_ours, t_cm, rel, diff, unit in cm_rows:
            lines.append(f"| {name} | {t_ours:.3g} | {t_cm:.3g} | {rel:.2f} | {diff:.1e} "
                         f"({unit}) |\n")
        lines.append("\n")
    lines += [
        "## Superposition route: error vs time\n\n",
        "`superposed_stress` under the Hertz pressure at 20 random points (0 <= r <= 2a, "
        "0.01a <= z <= 2a, nu = 0.3), against the closed form; errors relative to the largest "
        "component of the tensor at each point, the worst over the points. Each call evaluates "
        "the coarse rule and the one with half the step; the estimate is their difference, "
        "plus the change of the finer one when every source radius moves by 4 ulps (the "
        "rounding of the nodes at the rim, which a pressure singular there turns into an error "
        "of order sqrt(eps) that both rules share).\n\n",
        "| n_psi | tanh-sinh level | time per point | actual error | estimate |\n",
        "|---|---|---|---|---|\n",
    ]
    for n_psi, level, dt, act, est in rows:
        lines.append(f"| {n_psi} | {level} | {dt * 1e3:.1f} ms | {act:.1e} | {est:.1e} |\n")
    lines += [
        "\nOther pressures (error estimates only, default resolution n_psi = 64, level 5, at "
        "(r, z) = (0.5, 0.1), (0.99, 0.01), (2, 0.5) a): \n\n",
        "| pressure | worst estimate, relative to the tensor |\n|---|---|\n",
    ]
    for name, p in (("flat punch (1 - r^2)^(-1/2)", lambda r: 1 / np.sqrt(1 - r * r)),
                    ("cone arccosh(a/r) (log-singular at r = 0)",
                     lambda r: np.arccosh(1 / np.maximum(r, 1e-300)))):
        sig, err = stress.superposed_stress([0.5, 0.99, 2.0], 0.0, [0.1, 0.01, 0.5], p, 1.0,
                                            0.3)
        rel = np.max(err, axis=(-2, -1)) / np.max(np.abs(sig), axis=(-2, -1))
        lines.append(f"| {name} | {rel.max():.1e} |\n")
    lines.append(
        "\nThe rim singularities of MDR pressures sit at the ends of every ray, where tanh-sinh "
        "is at home; a singularity inside the disc (the cone's logarithm at r = 0) lies inside "
        "the rays through the centre and converges more slowly, as the estimate shows. The route "
        "takes z > 0: on the surface sigma_zz = -p(r) and the tangential stresses need the "
        "principal value of the kernel.\n")
    out = run.docs / "stress.md"
    # the line-contact section is bench_line_stress.py's: carried over from the old file
    from bench_line_stress import BEGIN, END
    old = out.read_text() if out.exists() else ""
    if BEGIN in old and END in old:
        lines.append("\n" + BEGIN + old.split(BEGIN, 1)[1].split(END, 1)[0] + END + "\n")
    out.write_text("".join(lines))
    print("".join(lines))


if __name__ == "__main__":
    main()
