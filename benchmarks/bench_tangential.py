"""Tangential contact (numeric/tangential.py): speed, and the incremental Hertz-Mindlin rule of
DEM codes against the exact spring history; writes docs/tangential_speed.md.

Speed: a full hysteresis loop of 1000 points of the fretting sphere (closed forms, Masing's
branches), the energy per cycle (Mindlin-Deresiewicz, one call), and a DEM-style history of
10^4 steps (normal force and tangential displacement changing together) on a 1000-interval
MDR grid, with and without the grid-error estimate. Targets: 5 ms, 50 us, 1 s.

The DEM rule: F_t += k_t du with k_t = 2 G* a (written 8 G a in DEM codes with their G =
1/((2 - nu1)/G1 + (2 - nu2)/G2), i.e. G*/4), then |F_t| capped at mu F_n. It is run beside
the springs (the exact Mindlin-Deresiewicz memory) on the same histories: a monotonic loading
to 0.9 mu F, an oscillation of amplitude 0.5 mu F (two cycles), and a random DEM-like history
of 10^4 steps. Reported: the largest difference of F_t over mu F, and the energy dissipated.

Run: ``.venv/bin/python benchmarks/bench_tangential.py [--quick] [--out DIR]`` (``make
benchmark`` runs it; ``--quick``: 10^3 steps, few repeats).
"""

from __future__ import annotations

import time

import _common
import numpy as np

from hertzmdr.numeric import _timing, hertz
from hertzmdr.numeric import tangential as tg

E, NU, R, F_N, MU, F_AMP = 210e9, 0.3, 0.01, 100.0, 0.6, 30.0
E_STAR = E / (2 * (1 - NU**2))
G_STAR = float(tg.effective_modulus(float(tg.shear_modulus(E, NU)), NU,
                                    float(tg.shear_modulus(E, NU)), NU))
TARGETS = {"loop": 5e-3, "energy": 50e-6, "history": 1.0}


def sphere() -> tg.Contact:
    a = float(hertz.contact_radius_from_force(F_N, R, E_STAR))
    return tg.Contact(tg.Paraboloid(R), a, E_STAR, G_STAR, MU)


def dem_rule(normal_force, u_x):
    """The incremental rule: F_t += 2 G* a(F_n) du, |F_t| <= mu F_n; its friction work."""
    a = hertz.contact_radius_from_force(np.asarray(normal_force, float), R, E_STAR)
    F = np.zeros(len(u_x))
    Ft, u_prev, W = 0.0, 0.0, 0.0
    for k, (Fn, ak, u) in enumerate(zip(normal_force, a, u_x, strict=True)):
        cap = MU * Fn
        Ft = float(np.clip(Ft, -cap, cap))
        kt = 2 * G_STAR * ak
        trial = Ft + kt * (u - u_prev)
        Ft = float(np.clip(trial, -cap, cap))
        W += cap * abs(trial - Ft) / kt
        u_prev = u
        F[k] = Ft
    return F, W


def histories(steps: int):
    ct = sphere()
    on = ct.slide_onset
    ustar = float(ct.displacement(F_AMP))
    s = np.linspace(0, 1, steps)
    mono = (np.full(steps, F_N), s * float(ct.displacement(0.9 * ct.sliding_force)))
    osc_u = ustar * np.concatenate([s[: steps // 5], np.cos(np.linspace(0, 4 * np.pi,
                                                                        steps - steps // 5))])
    osc = (np.full(steps, F_N), osc_u)
    rng = np.random.default_rng(1)
    Fn = F_N * (1 + 0.4 * np.sin(np.linspace(0, 6 * np.pi, steps))
                + 0.05 * np.cumsum(rng.standard_normal(steps)) / np.sqrt(steps))
    du = 0.15 * on * np.cumsum(rng.standard_normal(steps)) / np.sqrt(steps)
    dem = (Fn, np.sin(np.linspace(0, 10 * np.pi, steps)) * 0.6 * on + du)
    return {"monotonic to 0.9 mu F": mono, "oscillation, amplitude 0.5 mu F": osc,
            "random DEM-like history": dem}


def main(argv=None):
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    steps = 10**3 if args.quick else 10**4
    ct = sphere()
    Fn, u = histories(steps)["random DEM-like history"]
    x_max = 1.3 * float(hertz.contact_radius_from_force(Fn.max(), R, E_STAR))
    ways = {
        "loop": lambda: ct.loop(F_AMP, 1000),
        "energy": lambda: ct.energy(F_AMP),
        "history": lambda: tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU,
                                      x_max=x_max, normal_force=Fn, u_x=u, n_grid=1000,
                                      estimate_error=False),
        "history + error estimate": lambda: tg.history(
            tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=x_max,
            normal_force=Fn, u_x=u, n_grid=1000),
    }
    t = _timing.compare(ways, run.budget)
    cpu = {}
    for k, fn in ways.items():  # the process's CPU time of one call: what the load moves less
        c0 = time.process_time()
        reps = 0
        while reps < 3 or time.process_time() - c0 < (0.01 if args.quick else 0.2):
            fn()
            reps += 1
        cpu[k] = (time.process_time() - c0) / reps
    lines = ["# Tangential contact: speed, and the DEM rule against the exact history\n\n",
             "<!-- Written by `benchmarks/bench_tangential.py`; regenerate, do not edit. -->\n\n",
             _timing.conditions() + "\n\n",
             " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
             "Wall-clock medians move with the load of the shared machine; the CPU time of the "
             "process (mean of repeated calls) moves less.\n\n"
             "| what | median time | CPU time | target |\n|---|---|---|---|\n"]
    what = {"loop": "hysteresis loop, 1000 points (`Contact.loop`)",
            "energy": "energy per cycle (`Contact.energy`)",
            "history": f"history of {steps:,} steps on 1000 intervals (`history`)",
            "history + error estimate": "the same with the grid-error estimate"}
    for k in ways:
        target = TARGETS.get(k.split(" ")[0] if k != "history + error estimate" else "history")
        lines.append(f"| {what[k]} | {_common.seconds(t[k].median)} | {_common.seconds(cpu[k])} | "
                     f"{_common.seconds(target) if k in TARGETS else '-'} |\n")
    lines.append("\n## The incremental DEM rule against the springs\n\n"
                 + " ".join(__doc__.split("\n\n")[2].split()) + "\n\n"
                 "| history | steps | largest F_t difference / mu F | energy dissipated, "
                 "springs | energy dissipated, DEM rule | grid-error estimate of F_t / mu F "
                 "|\n|---|---|---|---|---|---|\n")
    for name, (N, ux) in histories(steps).items():
        h = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU,
                       x_max=1.3 * float(hertz.contact_radius_from_force(N.max(), R, E_STAR)),
                       normal_force=N, u_x=ux, n_grid=1000)
        Fd, Wd = dem_rule(N, ux)
        scale = MU * N.max()
        lines.append(f"| {name} | {len(N):,} | {np.max(np.abs(Fd - h.F_x)) / scale:.3g} | "
                     f"{h.dissipated[-1]:.4g} J | {Wd:.4g} J | {h.F_x_error / scale:.2g} |\n")
    lines.append("\nThe DEM rule keeps the initial stiffness 2 G* a up to mu F: it is too stiff "
                 "as soon as the edge of the contact slips (Cattaneo-Mindlin softens as "
                 "(1 - F/(mu F))^(1/3)), and it dissipates nothing below full sliding, where "
                 "the springs dissipate Mindlin-Deresiewicz's energy at every amplitude.\n")
    out = run.docs / "tangential_speed.md"
    out.write_text("".join(lines))
    print("".join(lines))


if __name__ == "__main__":
    main()
