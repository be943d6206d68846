"""Abel transforms of sampled contact data: hertzmdr.numeric.abel against PyAbel, in one run.

Run: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_abel.py [--quick] [--out DIR]
[--docs-only]`` (``make benchmark`` runs it; needs the ``plot`` extra, and PyAbel, the ``bench``
extra, for its side; one BLAS thread: on the shared 2-core machine threaded matrix-vector
products time the other jobs more than the methods). Writes docs/abel.md,
docs/abel_error_time.png and benchmarks/results/abel.json (``--docs-only``: the docs from that
JSON, nothing measured); ``bench_mdr.py`` shows :func:`summary` in docs/mdr.md. Timings are wall
clock on this machine, by ``hertzmdr.numeric._timing``; each method runs in a forked process of
its own, so its first call at each N finds every cache empty.

Set-up, the same for every method: contact radius a = 1, E* = 1, the grid x_i = i*dx,
dx = 1.2/(N - 1), N - 1 = 50 * 2^k (a is never a grid point), the right half of the profile as
one row. (5.59): the input is q(x_i) = E* (d - g(x_i)) (0 beyond a), the output p(r_i); (5.61):
the input is the closed-form p(r_i), the output q(x_i). The error is the maximum relative
error over the radii r = 0.024 k, k = 3..39 (0.072 <= r <= 0.936: grid points of every N,
away from the axis and the edge), against the closed form (the worn profile's pressure, an
incomplete elliptic integral, by mpmath quadrature of (5.59) at 30 digits).
"""

from __future__ import annotations

import contextlib
import io
import json
import warnings

import _common
import mpmath as mp
import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _timing
from hertzmdr.numeric import abel as habel

NS = (51, 101, 201, 401, 801, 1601, 3201)
NS_QUICK = (51, 101)
WARM_N = 11  # a grid size not in NS: the imports' and first-use costs are paid on it
FIRST_NS, FIRST_NS_QUICK = (1025, 4097), (101,)  # issue 18's grids of the first-call race
FIRST_REPEATS, FIRST_REPEATS_QUICK = 3, 1  # fresh processes per (method, N): the minimum
K_COMMON = np.arange(3, 40)  # common radii r = 0.024 k
WORN_R, WORN_B = 1.0, 0.3
KINK = "hertzmdr (degree=5, kink=b)"  # the worn profile's kink
KINK0 = "hertzmdr (degree=5, kink=0)"  # the cone's tip
MATRIX = "hertzmdr matrix (degree=5, edge=a)"  # pressure_matrix / line_load_matrix, a known
MATRIX_KINK = "hertzmdr matrix (degree=5, edge=a, kink=b)"  # where b is not a sample
A_EDGE = 1.0  # the contact radius of every profile


def _powerlaw(n):
    def q(x):
        return np.where(x < 1, 1 - np.minimum(x, 1) ** n, 0.0)  # d = 1, c = 1/kappa: g = x^n

    def p(r):
        if n >= 1.5:
            return gen.powerlaw_pressure(1.0, 1.0, 1.0, n, r)
        return gen.powerlaw_pressure_small_n(1.0, 1.0, 1.0, n, r)
    return q, p


def _worn():
    d = float(gen.worn_depth(WORN_R, 1.0, WORN_B))

    def q(x):
        return np.where(x < 1, d - gen.worn_g(WORN_R, WORN_B, np.minimum(x, 1)), 0.0)

    def p_ref(rho):
        """(5.59) by mpmath: (1/pi) int g'(x)/sqrt(x^2 - rho^2), x = lo + u^2 at both
        singular ends (g' ~ 1/sqrt(x - b), the kernel ~ 1/sqrt(x - rho))."""
        with mp.workdps(30):
            b, R, rho = mp.mpf(WORN_B), mp.mpf(WORN_R), mp.mpf(rho)
            lo = max(rho, b)

            def f(u):
                xx = lo + u * u
                gp = (2 * xx**2 - b**2) / (R * mp.sqrt(xx + b))  # g' sqrt(x - b)
                if rho < b:
                    return 2 * gp / mp.sqrt((xx - rho) * (xx + rho))
                return 2 * gp / mp.sqrt(xx - b) / mp.sqrt(xx + rho)
            return float(mp.quad(f, [0, mp.sqrt(1 - lo)]) / mp.pi)

    r = 0.024 * K_COMMON
    pr = np.array([p_ref(v) for v in r])

    def p(rr):
        # only ever evaluated on the common radii (the worn input p is not sampled: no (5.61))
        return np.interp(rr, r, pr)
    return q, p


def profiles():
    out = {f"n = {n}" + (" (Hertz)" if n == 2 else " (cone)" if n == 1 else ""): _powerlaw(n)
           for n in (2, 4, 2.5, 1)}
    out["worn (b = 0.3 a)"] = _worn()
    return out


def pyabel_methods(direction):
    import abel

    def basex(y, dx):
        return abel.basex.basex_transform(y, dr=dx, verbose=False, direction=direction)

    def three_point(y, dx):
        return abel.dasch.three_point_transform(y, dr=dx, direction=direction)

    def daun(y, dx):
        return abel.daun.daun_transform(y, dr=dx, verbose=False, direction=direction)

    def daun3(y, dx):
        return abel.daun.daun_transform(y, dr=dx, degree=3, verbose=False, direction=direction)

    def hansenlaw(y, dx):
        return abel.hansenlaw.hansenlaw_transform(y, dr=dx, direction=direction)

    def direct(y, dx):
        with contextlib.redirect_stdout(io.StringIO()):  # its "no C backend" notice
            return abel.direct.direct_transform(y, dr=dx, direction=direction)

    meths = {"basex": basex, "three_point": three_point, "daun": daun,
             "daun (degree=3)": daun3, "hansenlaw": hansenlaw, "direct": direct}
    if direction == "forward":
        del meths["three_point"]  # PyAbel's Dasch methods are inverse only
    return meths


def hertzmdr_methods(direction):
    f = habel.pressure_from_line_load if direction == "inverse" else habel.line_load_from_pressure
    meths = {f"hertzmdr (degree={k})": (lambda y, dx, k=k: f(y, dx, degree=k)) for k in (3, 5)}
    if direction == "inverse":  # told where the kink is (PyAbel cannot use it)
        meths[KINK] = lambda y, dx: f(y, dx, degree=5, kink=WORN_B)
        meths[KINK0] = lambda y, dx: f(y, dx, degree=5, kink=0.0)
    # the operator as a matrix for the known contact radius: one product a call, no
    # validation or edge search (built on the first call of each N, as PyAbel's operators)
    build = habel.pressure_matrix if direction == "inverse" else habel.line_load_matrix
    mats: dict = {}

    def matrix(y, dx):
        N = y.shape[-1]
        if N not in mats:
            mats[N] = build(N, dx, edge=A_EDGE).T.copy()
        return y @ mats[N]

    meths[MATRIX] = matrix
    if direction == "inverse":
        kmats: dict = {}

        def matrix_kink(y, dx):  # only on grids where b is not a sample (p(b) = inf there)
            N = y.shape[-1]
            if N not in kmats:
                kmats[N] = build(N, dx, edge=A_EDGE, kink=WORN_B).T.copy()
            return y @ kmats[N]

        meths[MATRIX_KINK] = matrix_kink
    return meths


def _method_rows(direction, name, call, profs, Ns, budget, verbose):
    """One method on every N and profile (run in a forked process: its caches start empty).
    'first' is the method's first call at N (the operator build, with the first profile),
    'again' the median of the repeated calls on each profile (its own edge cached too)."""
    rows = []
    for N in Ns:
        x = np.linspace(0, 1.2, N)
        dx = x[1]
        step = (N - 1) // 50
        common = K_COMMON * step
        first = None
        for pname, (q, p) in profs.items():
            if direction == "forward" and pname.startswith(("worn", "n = 1 ")):
                continue  # no sampled p: the worn p has no closed form, the cone's p(0) is
                # infinite
            if (name in (KINK, MATRIX_KINK) and not pname.startswith("worn")) or (
                    name == KINK0 and not pname.startswith("n = 1 ")):
                continue
            if name == MATRIX_KINK and abs(WORN_B / dx - round(WORN_B / dx)) < 1e-6:
                continue  # b is a sample: the matrix cannot hold p(b) = inf
            if direction == "inverse":
                y, ref = q(x), p(x[common])
            else:
                y, ref = p(x), q(x[common])
            y = y[None, :]
            t = _timing.measure(lambda y=y, dx=dx: call(y, dx), budget)
            if first is None:  # the operator build, once per (method, N)
                first = t.first
            out = np.ravel(call(y, dx))
            err = float(np.max(np.abs(out[common] / ref - 1)))
            rows.append(dict(direction=direction, profile=pname, method=name, N=N, error=err,
                             first=first, again=t.median))
            if verbose:
                print(f"{direction:8s} {pname:18s} {name:22s} {N:5d} "
                      f"{err:9.2e} {1e3 * first:9.2f} {1e3 * t.median:9.3f} ms", flush=True)
    return rows


def run(Ns=NS, budget=_timing.FULL, verbose=True):
    """All (profile, direction, method, N): error, first-call and repeated-call time [s].
    Each method runs in a forked process of its own (``_timing.in_fork``), after one warm-up
    call of every method on WARM_N samples here (the imports)."""
    rows = []
    profs = profiles()
    abel = _common.peer("abel", "PyAbel", "the PyAbel rows")
    for direction in ("inverse", "forward"):
        meths = hertzmdr_methods(direction)
        if abel is not None:
            meths.update(pyabel_methods(direction))
        x = np.linspace(0, 1.2, WARM_N)
        y = np.maximum(1 - (x / 1.01) ** 2, 0)[None, :]
        for call in meths.values():
            call(y, x[1])
        for name, call in meths.items():
            rows += _timing.in_fork(_method_rows, direction, name, call, profs, Ns, budget,
                                    verbose)
    return rows


def first_call_methods():
    """(5.59), the first call at N: hertzmdr's functions (the operator built and applied) and
    PyAbel's inverse methods with an operator or none, its Dasch operators generated
    (``basis_dir=None``: not loaded from an earlier run's file on disk). basex (minutes to
    generate at these N) and direct (no operator: its first call is every call) are left
    out."""
    meths = {f"hertzmdr (degree={k})": (lambda y, dx, k=k: habel.pressure_from_line_load(
        y, dx, degree=k)) for k in (3, 5)}
    import abel

    def dasch(transform):
        return lambda y, dx: transform(y, dr=dx, direction="inverse", basis_dir=None)

    for name in ("three_point", "two_point", "onion_peeling"):
        meths[name] = dasch(getattr(abel.dasch, f"{name}_transform"))
    meths["daun"] = lambda y, dx: abel.daun.daun_transform(y, dr=dx, verbose=False,
                                                           direction="inverse")
    meths["hansenlaw"] = lambda y, dx: abel.hansenlaw.hansenlaw_transform(
        y, dr=dx, direction="inverse")
    return meths


def _first_call(call, N):
    """One first call at N in this (fresh) process: wall and CPU seconds, and the error on
    the common radii (the Hertz profile)."""
    import time

    x = np.linspace(0, 1.2, N)
    q, p = profiles()["n = 2 (Hertz)"]
    common = K_COMMON * ((N - 1) // 50) if (N - 1) % 50 == 0 else np.rint(
        0.024 * K_COMMON / x[1]).astype(int)
    y = q(x)[None, :]
    t0, c0 = time.perf_counter(), time.process_time()
    out = np.ravel(call(y, x[1]))
    c1, t1 = time.process_time(), time.perf_counter()
    return t1 - t0, c1 - c0, float(np.max(np.abs(out[common] / p(x[common]) - 1)))


def first_calls(Ns=FIRST_NS, repeats=FIRST_REPEATS, verbose=True):
    """Every method of :func:`first_call_methods` at each N: the minimum over ``repeats``
    fresh processes (forked after a warm-up call of every method on WARM_N samples: the
    imports paid) of the wall-clock and CPU time of the first call; [] without PyAbel."""
    if _common.peer("abel", "PyAbel", "the first-call race") is None:
        return []
    meths = first_call_methods()
    x = np.linspace(0, 1.2, WARM_N)
    y = np.maximum(1 - (x / 1.01) ** 2, 0)[None, :]
    for call in meths.values():
        call(y, x[1])
    rows = []
    for N in Ns:
        for name, call in meths.items():
            runs = [_timing.in_fork(_first_call, call, N) for _ in range(repeats)]
            rows.append(dict(method=name, N=N, wall=min(r[0] for r in runs),
                             cpu=min(r[1] for r in runs), error=runs[0][2], repeats=repeats))
            if verbose:
                r = rows[-1]
                print(f"first call {name:22s} {N:5d} wall {r['wall']:8.3f} s cpu "
                      f"{r['cpu']:8.3f} s error {r['error']:.1e}", flush=True)
    return rows


def first_call_section(firsts):
    """docs/abel.md's section on issue 18's first-call goal, from :func:`first_calls`."""
    if not firsts:
        return ("## First call at N = 1025 and 4097\n\nPyAbel was not installed for this run: "
                "no first-call race.\n\n")
    Ns = list(dict.fromkeys(r["N"] for r in firsts))
    meths = list(dict.fromkeys(r["method"] for r in firsts))
    cell = {(r["method"], r["N"]): r for r in firsts}
    out = ["## First call at N = " + " and ".join(map(str, Ns)) + "\n\n"
           "Issue 18's goal: the first call of (5.59) at N = 1025 and 4097 no slower than "
           "PyAbel's fastest method's first call at the same N, at the present accuracy. The "
           "Hertz profile of the set-up above; each (method, N) in "
           f"{firsts[0]['repeats']} fresh processes forked after a warm-up call on {WARM_N} "
           "samples (imports paid, every cache empty), the minimum of each time; wall clock "
           "and the process's CPU time (the machine was shared: the CPU time is the method's "
           "cost without the other jobs' share). PyAbel's Dasch operators (three_point, "
           "two_point, onion_peeling) are generated, not loaded from the file an earlier "
           "run may have left in ~/.cache/PyAbel (`basis_dir=None`); its basex (minutes to "
           "generate at these N) and direct (no operator) are not in this race.\n\n"
           "| method | " + " | ".join(f"N = {N}: wall [s] | CPU [s] | error" for N in Ns)
           + " |\n|---|" + "---|---|---|" * len(Ns) + "\n"]
    for m in meths:
        cells = []
        for N in Ns:
            r = cell.get((m, N))
            cells.append(f"{r['wall']:.3f} | {r['cpu']:.3f} | {r['error']:.1e}" if r
                         else " | | ")
        out.append(f"| {m} | " + " | ".join(cells) + " |\n")
    ours = "hertzmdr (degree=5)"
    text = []
    for N in Ns:
        mine = cell.get((ours, N))
        if mine is None:
            continue
        peers = [r for r in firsts if r["N"] == N and not r["method"].startswith("hertzmdr")]
        ratios = ", ".join(f"{r['method']} {r['cpu'] / mine['cpu']:.2g}x" for r in peers)
        slower = [r for r in peers if r["cpu"] < mine["cpu"]]
        text.append(f"N = {N}: hertzmdr (degree 5) {mine['cpu']:.3f} s CPU "
                    f"({mine['wall']:.3f} s wall) at error {mine['error']:.0e}; each peer's "
                    f"CPU time over it: {ratios}" + (
                        "; faster on the first call: " + ", ".join(
                            f"{r['method']} (error {r['error']:.0e})" for r in slower)
                        if slower else "") + ".")
    out.append("\n" + " ".join(text) + " Against three_point, the method issue 18 names as "
               "PyAbel's fastest, the goal is met where its ratio is >= 1. Where other PyAbel "
               "methods are faster on the first call, it is at the errors listed: hansenlaw "
               "has no operator (an O(N) recursion, the same cost again on every call), the "
               "operators of daun (degree 0) and two_point are a few closed-form terms an "
               "entry. "
               "hertzmdr's first call is the O(N^2) operator of the exact "
               "moments (one square root and about 40 flops an entry, plus writing N^2 "
               "doubles, 134 MB at N = 4097), cached for every later call; its accuracy is "
               "unchanged (tests/test_abel.py).\n\n")
    return "".join(out)


def verdict(rows, direction, profile, with_kink=False, with_matrix=False):
    """Is every PyAbel (time, error) point beaten by a hertzmdr point no slower than it?"""
    sel = [r for r in rows if r["direction"] == direction and r["profile"] == profile]
    ours = [(r["again"], r["error"]) for r in sel if r["method"].startswith("hertzmdr")
            and (with_kink or "kink" not in r["method"])
            and (with_matrix or "matrix" not in r["method"])]
    theirs = [r for r in sel if not r["method"].startswith("hertzmdr")]
    beaten, faster, worse = 0, [], []
    fastest_ours = min(t for t, _ in ours)
    for r in theirs:
        cand = [e for t, e in ours if t <= r["again"]]
        if not cand:
            faster.append(r)
        elif min(cand) < r["error"]:
            beaten += 1
        else:
            worse.append(r)
    return dict(beaten=beaten, total=len(theirs), faster=faster, worse=worse,
                fastest_ours=fastest_ours)


def verdict_line(rows, direction, prof, with_kink=False, with_matrix=False):
    v = verdict(rows, direction, prof, with_kink, with_matrix)
    what = "(5.59)" if direction == "inverse" else "(5.61)"
    line = f"- {what} {prof}" + (" with the kink given" if with_kink else "") + (
        (" and" if with_kink else "") + " with the matrix for a known contact radius"
        if with_matrix else "") + (
        f": {v['beaten']} of {v['total']} PyAbel points beaten")
    if v["faster"]:
        best = min(v["faster"], key=lambda r: r["error"])
        line += (f"; {len(v['faster'])} are faster than any hertzmdr call "
                 f"(< {1e3 * v['fastest_ours']:.3f} ms), the most accurate of them "
                 f"{best['method']} N={best['N']}, error {best['error']:.1e}")
    if v["worse"]:
        line += ("; NOT beaten: " + ", ".join(
            f"{r['method']} N={r['N']} ({1e3 * r['again']:.2f} ms, error {r['error']:.1e})"
            for r in v["worse"]))
    return line + "\n"


def order(Ns, errs):
    Ns, errs = np.asarray(Ns, float), np.asarray(errs, float)
    ok = errs > 1e-12  # the rounding floor (~1e-13 for (5.59) at large N) excluded
    if ok.sum() < 3:
        return float("nan")
    return float(-np.polyfit(np.log(Ns[ok]), np.log(errs[ok]), 1)[0])


def summary(rows, N=201):
    """The markdown table of one N (for docs/mdr.md): error, repeated-call time, and that time
    over the fastest PyAbel method's at the same N (a ratio from one run: the machine's load
    moves it less than the times)."""
    if not any(r["N"] == N for r in rows):
        N = max(r["N"] for r in rows)  # a --quick run has only small grids
    out = [f"Max relative error on 0.072 <= r <= 0.936 (a = 1), N = {N} samples on [0, 1.2]; "
           "time of a repeated call [ms] (operator cached; median over the profiles) and its "
           "ratio to the fastest PyAbel method's (< 1: faster). Full tables, first-call times, "
           "orders and the plot: [abel.md](abel.md).\n\n"]
    for direction in ("inverse", "forward"):
        sel = [r for r in rows if r["direction"] == direction and r["N"] == N]
        profs = list(dict.fromkeys(r["profile"] for r in sel))
        meths = list(dict.fromkeys(r["method"] for r in sel))
        what = "(5.59) inverse: q -> p" if direction == "inverse" else "(5.61) forward: p -> q"
        med = {m: float(np.median([x["again"] for x in sel if x["method"] == m]))
               for m in meths}
        theirs = [t for m, t in med.items() if not m.startswith("hertzmdr")]
        fastest = min(theirs) if theirs else None
        out.append(f"**{what}**\n\n| method | " + " | ".join(profs) + " | time [ms] | "
                   "/ fastest PyAbel |\n|---|" + "---|" * (len(profs) + 2) + "\n")
        for m in meths:
            cells = []
            for pr in profs:
                r = [x for x in sel if x["method"] == m and x["profile"] == pr]
                cells.append(f"{r[0]['error']:.1e}" if r else "")
            rel = f"{med[m] / fastest:.2f}" if fastest else "(PyAbel not run)"
            out.append(f"| {m} | " + " | ".join(cells) + f" | {1e3 * med[m]:.3f} | {rel} |\n")
        out.append("\n")
    return "".join(out)


def mdr_section(results_dir, N=201):
    """The comparison for docs/mdr.md: the summary table of the last run (abel.json in
    results_dir), or a line saying that there is none."""
    path = results_dir / "abel.json"
    if not path.exists():
        return f"No {path.name} in {results_dir}: run benchmarks/bench_abel.py first.\n"
    return summary(json.loads(path.read_text())["rows"], N)


REASONS = {
    "worn": "its line load has a square-root kink at x = b, which limits every method that "
            "interpolates across it to order ~1.5 -- PyAbel's and hertzmdr's without `kink=b` "
            "alike -- and then PyAbel's cheaper operators win at equal time. Told where the "
            "kink is (`kink=b`), hertzmdr reaches ~1e-13; the PyAbel points it still does not "
            "beat are on the 'with the kink given' line",
    "n = 1": "the cone's q ~ |x| is not smooth in s = x^2 at the axis, so hertzmdr's error falls "
             "at order 3-5 instead of being at rounding already on the coarsest grid; the "
             "PyAbel points listed are more accurate than every hertzmdr call that is no "
             "slower. With `kink=0` (a conical tip: q = q(0) + |x| U(x^2)) the cone's U is "
             "constant and only the edge finder's error is left ('with the kink given')",
}


def plain_statement(rows):
    """The verdict in words, from the numbers (REASONS holds the explanations)."""
    combos = list(dict.fromkeys((r["direction"], r["profile"]) for r in rows))
    met, not_met, floor, best_fast = [], [], [], []
    for direction, prof in combos:
        v = verdict(rows, direction, prof)
        what = ("(5.59) " if direction == "inverse" else "(5.61) ") + prof
        (not_met if v["worse"] else met).append((what, prof))
        floor.append(v["fastest_ours"])
        best_fast += v["faster"]
    text = ["**Plain statement.** The goal is met -- every PyAbel point with a hertzmdr point "
            "no slower than it is beaten -- for " + ", ".join(w for w, _ in met) + ". "]
    for what, prof in not_met:
        reason = next((r for k, r in REASONS.items() if prof.startswith(k)), "see the table")
        text.append(f"It is not met everywhere for {what}: {reason}. ")
    if best_fast:
        top = min(best_fast, key=lambda r: r["error"])
        coarse = [r["error"] for r in rows if r["method"].startswith("hertzmdr")
                  and "kink" not in r["method"] and r["N"] == min(r2["N"] for r2 in rows)]
        text.append(
            f"Below the functions' fastest call ({1e3 * min(floor):.3f}-{1e3 * max(floor):.3f} "
            "ms: validation, finding the edge, the cache lookup and the matrix product) only "
            "PyAbel's cached matrix products on the small grids have points, so there the "
            "functions cannot meet the goal (the matrices below can); their most accurate "
            "result in that range is "
            f"{top['error']:.1e} ({top['method']}, N={top['N']}), while hertzmdr's calls on "
            f"the coarsest grid give {min(coarse):.0e} to {max(coarse):.0e} depending on the "
            "profile. ")
    if any("matrix" in r["method"] for r in rows):
        met_m, not_m = [], []
        for direction, prof in combos:
            kinked = any("kink" in r["method"] and r["profile"] == prof for r in rows)
            v = verdict(rows, direction, prof, with_kink=kinked, with_matrix=True)
            what = ("(5.59) " if direction == "inverse" else "(5.61) ") + prof
            (not_m if (v["worse"] or v["faster"]) else met_m).append(what)
        t_m = [r["again"] for r in rows if r["method"] == MATRIX and r["N"] == min(
            r2["N"] for r2 in rows)]
        text.append(f"For a known contact radius, the operator as a matrix "
                    f"(`abel.pressure_matrix`, `abel.line_load_matrix`: one product a call, "
                    f"{1e3 * min(t_m):.4f}-{1e3 * max(t_m):.4f} ms at N = "
                    f"{min(r['N'] for r in rows)}) beats every PyAbel point, the fastest "
                    "included, for " + (", ".join(met_m) if met_m else "no profile")
                    + ("" if not not_m else "; not for " + ", ".join(not_m)
                       + " (see the lines 'with the matrix')") + ". ")
    nmax = max(r["N"] for r in rows)
    firsts = {}
    for r in rows:
        if r["N"] == nmax and r["direction"] == "inverse":
            firsts.setdefault(r["method"], r["first"])
    if firsts:
        ours = max(v for k, v in firsts.items() if k.startswith("hertzmdr"))
        others = ", ".join(f"{k} {1e3 * v:.0f} ms" for k, v in firsts.items()
                           if not k.startswith("hertzmdr"))
        text.append(f"First calls: building hertzmdr's (5.59) operator for N = {nmax} takes "
                    f"up to {ours:.2f} s (the O(N^2) exact moments), PyAbel's first calls "
                    f"take {others} (its basex and three_point may load an earlier run's "
                    "operator from disk; the race at N = 1025 and 4097 below generates "
                    "them).")
    return "".join(text) + "\n\n"


def best_table(rows):
    """Per profile: hertzmdr's and PyAbel's most accurate result, and the time it took."""
    out = ["Most accurate result of each side over all N (repeated-call time):\n\n"
           "| transform | profile | hertzmdr | time [ms] | PyAbel | time [ms] |\n"
           "|---|---|---|---|---|---|\n"]
    for direction, prof in dict.fromkeys((r["direction"], r["profile"]) for r in rows):
        sel = [r for r in rows if r["direction"] == direction and r["profile"] == prof]
        ours = min((r for r in sel if r["method"].startswith("hertzmdr")
                    and "kink" not in r["method"]), key=lambda r: r["error"])
        theirs = min((r for r in sel if not r["method"].startswith("hertzmdr")),
                     key=lambda r: r["error"])
        what = "(5.59)" if direction == "inverse" else "(5.61)"
        how = ours["method"].removeprefix("hertzmdr ")
        if how.startswith("(") and how.endswith(")"):
            how = how[1:-1]
        out.append(f"| {what} | {prof} | {ours['error']:.1e} ({how}, "
                   f"N={ours['N']}) | {1e3 * ours['again']:.2f} | {theirs['error']:.1e} "
                   f"({theirs['method']}, N={theirs['N']}) | {1e3 * theirs['again']:.2f} |\n")
    return "".join(out) + "\n"


def write_docs(rows, conditions, docs_dir, firsts=()):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    combos = list(dict.fromkeys((r["direction"], r["profile"]) for r in rows))
    fig, axes = plt.subplots(2, 5, figsize=(20, 8))
    meths = list(dict.fromkeys(r["method"] for r in rows))
    colors = {m: plt.cm.tab10(i) for i, m in enumerate(meths)}
    for ax, (direction, prof) in zip(axes.ravel(), combos, strict=False):
        for m in meths:
            sel = [r for r in rows if r["direction"] == direction and r["profile"] == prof
                   and r["method"] == m]
            if not sel:
                continue
            style = "o-" if m.startswith("hertzmdr") else "s--"
            ax.loglog([1e3 * r["again"] for r in sel], [max(r["error"], 1e-17) for r in sel],
                      style, color=colors[m], label=m, ms=4)
        ax.set_title(f"{'(5.59) q->p' if direction == 'inverse' else '(5.61) p->q'}, {prof}",
                     fontsize=9)
        ax.set_xlabel("repeated call [ms]")
        ax.set_ylabel("max rel. error")
        ax.grid(True, which="major", alpha=0.3)
    handles = {}
    for ax in axes.ravel()[:len(combos)]:
        for hd, lb in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(lb, hd)
    for ax in axes.ravel()[len(combos):]:
        ax.axis("off")
    axes.ravel()[-1].legend(handles.values(), handles.keys(), loc="center", fontsize=9)
    fig.tight_layout()
    fig.savefig(docs_dir / "abel_error_time.png", dpi=90)
    plt.close(fig)

    out = ["# Abel transforms (5.59), (5.61) from samples: hertzmdr and PyAbel\n\n",
           "<!-- Written by `benchmarks/bench_abel.py`; timings are wall clock on the shared "
           "2-core development machine (other jobs were running: compare within a run). -->\n\n",
           __doc__.split("Set-up, the same for every method: ")[1].replace("\n", " ")
           .replace("  ", " ").strip().join(["Set-up, the same for every method: ", "\n\n"]),
           "Methods: `hertzmdr.numeric.abel` (product integration of a piecewise polynomial in "
           "s = x^2, exact against the kernel; degree 3 and 5; the edge found from the "
           "samples; `abel.pressure_matrix`/`abel.line_load_matrix` for the known contact "
           "radius a = 1 (the operator as one matrix, applied by a product); "
           "for the worn profile also with `kink=b`, the radius where its line load "
           "has a square-root kink, and for the cone with `kink=0`, its tip -- information "
           "PyAbel cannot use, so it is reported apart) and PyAbel's basex, three_point "
           "(inverse only), daun (degree 0, the default, and 3), hansenlaw, direct, all with "
           "their default parameters. 'first' is a method's first call at N in a process of "
           "its own (forked after the imports: every cache empty; the operator build), "
           "'again' the median of the repeated calls on the same samples "
           "(`hertzmdr.numeric._timing`). "
           "PyAbel caches its operators per N; hertzmdr caches (5.59) per N plus a cheap O(N) "
           "correction per contact radius, and (5.61) per (N, contact radius): a new profile "
           "with another radius pays the (5.61) first-call time again. The method and its "
           "error model: the docstring of `hertzmdr/numeric/abel.py`; the tests: "
           "`tests/test_abel.py`.\n\n"]
    out.append(f"{conditions} ")
    if not any(not r["method"].startswith("hertzmdr") for r in rows):
        out.append("PyAbel was not installed for this run: its rows, the verdict, the plain "
                   "statement and the table of best results are left out.\n\n")
    else:
        out.append(f"PyAbel {_common.version('PyAbel')}; its `direct` method runs the "
                   "pure-Python backend (the C extension is not built in this install), so "
                   "its times are pessimistic. Its `basex` keeps each N's basis on disk "
                   "(~/.cache/PyAbel) for later processes: its 'first' is the generation of "
                   "the basis (minutes at N = 3201) where no earlier run on this machine "
                   "saved it, else loading it.\n\n")
        out += _verdicts(rows, combos)
    out.append(first_call_section(firsts))
    out.append("\n![error vs time](abel_error_time.png)\n\n## Convergence orders\n\n"
               "Least-squares slope of log(error) against log(N), errors below 1e-12 (the "
               "rounding floor) left out; 'rounding': at the floor on every grid; '-': fewer "
               "than 3 points above it. Over this region, away from the axis, hertzmdr's "
               "n = 2.5 and cone errors fall at about the interpolation's order; with the "
               "axis included (tests/test_abel.py) |x|^n limits (5.59) to order n - 1 and "
               "(5.61) to order n.\n\n")
    meths_all = list(dict.fromkeys(r["method"] for r in rows))
    out.append("| direction | profile | " + " | ".join(meths_all) + " |\n|---|---|"
               + "---|" * len(meths_all) + "\n")
    for direction, prof in combos:
        cells = []
        for m in meths_all:
            sel = [r for r in rows if r["direction"] == direction and r["profile"] == prof
                   and r["method"] == m]
            if not sel:
                cells.append("")
                continue
            o = order([r["N"] for r in sel], [r["error"] for r in sel])
            cells.append("rounding" if max(r["error"] for r in sel) < 1e-12 else
                         "-" if np.isnan(o) else f"{o:.1f}")
        out.append(f"| {direction} | {prof} | " + " | ".join(cells) + " |\n")
    out.append("\n## All results\n\n")
    for direction, prof in combos:
        out.append(f"### {direction}, {prof}\n\n| method | N | max rel. error | first [ms] | "
                   "again [ms] |\n|---|---|---|---|---|\n")
        for r in rows:
            if r["direction"] == direction and r["profile"] == prof:
                out.append(f"| {r['method']} | {r['N']} | {r['error']:.2e} | "
                           f"{1e3 * r['first']:.2f} | {1e3 * r['again']:.3f} |\n")
        out.append("\n")
    (docs_dir / "abel.md").write_text("".join(out))


def _verdicts(rows, combos):
    out = ["## Verdict: smaller error at equal time than PyAbel's best method?\n\n"
           "A PyAbel point (method, N) counts as beaten when some hertzmdr point (degree, "
           "N') is no slower (repeated call) and has a smaller error.\n\n"]
    for direction, prof in combos:
        out.append(verdict_line(rows, direction, prof))
        kinked = any("kink" in r["method"] and r["profile"] == prof for r in rows)
        if kinked:
            out.append(verdict_line(rows, direction, prof, with_kink=True))
        if any("matrix" in r["method"] for r in rows):
            out.append(verdict_line(rows, direction, prof, with_kink=kinked, with_matrix=True))
    out.append("\n" + plain_statement(rows) + best_table(rows))
    return out


def main(argv=None):
    ap = _common.parser(__doc__)
    ap.add_argument("--docs-only", action="store_true",
                    help="rewrite abel.md from the saved abel.json, measuring nothing")
    args = ap.parse_args(argv)
    run_ = _common.run_from(args)
    path = run_.results / "abel.json"
    if args.docs_only:
        saved = json.loads(path.read_text())
        rows, conditions = saved["rows"], saved["conditions"]
        firsts = saved.get("first_calls", [])
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # PyAbel's notices (direct without its C backend)
            rows = run(NS_QUICK if args.quick else NS, run_.budget)
            firsts = first_calls(FIRST_NS_QUICK if args.quick else FIRST_NS,
                                 FIRST_REPEATS_QUICK if args.quick else FIRST_REPEATS)
        conditions = _timing.conditions()
        path.write_text(json.dumps(dict(conditions=conditions, rows=rows, first_calls=firsts),
                                   indent=0))
    write_docs(rows, conditions, run_.docs, firsts)
    return rows


if __name__ == "__main__":
    main()
