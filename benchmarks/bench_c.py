"""The C header of the contact laws (numeric/c/hertzmdr_laws.h): nanoseconds per call, beside
NumPy's time per element, and the accuracy of both routes; writes its table into
docs/c_laws.md.

C: a loop over 1024 points of the law's documented domain, repeated to 10^6 calls, compiled
with ``cc -O2`` and timed in C (clock_gettime, the best of 5 rounds), the results summed so that
no call is optimized away. NumPy: the generated function of the same name on 10^6 elements
(the median of the rounds of hertzmdr.numeric._timing), divided by 10^6. Accuracy: the
relative error of each route against the 30-digit mpmath route of the same relation at 100
points of the domain (the header's test, tests/test_c_header.py, checks it at more).

Run: ``.venv/bin/python benchmarks/bench_c.py [--quick] [--out DIR]`` (``make benchmark`` runs
it; ``--quick``: 10^4 calls and elements, 10 accuracy points, one round).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import _common
import mpmath as mp
import numpy as np
import sympy as sp

from hertzmdr.derive.c_codegen import LAWS, CLaw
from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp
from hertzmdr.numeric import _timing
from hertzmdr.numeric.c import include_dir

DOC = "c_laws.md"
BEGIN, END = "<!-- bench_c.py: begin -->", "<!-- bench_c.py: end -->"
POINTS = 1024  # distinct inputs per law in the C loop: they stay in the cache


def arg_names(law: CLaw) -> list[str]:
    import inspect

    return list(inspect.signature(getattr(gen, law.relation)).parameters)


def draw(law: CLaw, n: int, seed: int) -> dict[str, np.ndarray]:
    """``n`` points of the law's documented domain (log-uniform or uniform per ``spans``), with
    the arguments of ``where`` computed from them; the same domain as the header's test."""
    rng = np.random.default_rng(seed)
    vals = {}
    for k, s in law.spans.items():
        u = rng.random(n)
        vals[k] = (np.exp(np.log(s.lo) + u * (np.log(s.hi) - np.log(s.lo))) if s.log
                   else s.lo + u * (s.hi - s.lo))
    for name, text in law.where.items():
        expr = sp.sympify(text)
        syms = sorted(expr.free_symbols, key=lambda s: s.name)
        fn = sp.lambdify(syms, expr, modules=["scipy", "numpy"])
        vals[name] = np.asarray(fn(*(vals[s.name] for s in syms)), dtype=float)
    return {k: vals[k] for k in arg_names(law)}


def timer_source(calls: int) -> str:
    """C source: per law, read POINTS rows of arguments, call the law ``calls`` times over
    them, print ``name ns_per_call checksum``; then print every result of the first rows."""
    blocks = []
    for law in LAWS:
        k = len(arg_names(law))
        args = ", ".join(f"in[{j}][i % {POINTS}]" for j in range(k))
        blocks.append(f"""\
    if (!read_rows(in, {k})) return 2;
    best = 1e300;
    for (round_ = 0; round_ < 5; ++round_) {{
        double t0 = now(), acc = 0.0;
        for (i = 0; i < {calls}; ++i) acc += {law.c_name}({args});
        t0 = now() - t0;
        if (t0 < best) best = t0;
        sink += acc;
    }}
    printf("time {law.relation} %.6g %.17g\\n", 1e9 * best / {calls}, sink);
    for (i = 0; i < {POINTS}; ++i)
        printf("value {law.relation} %.17g\\n", {law.c_name}({args}));
""")
    return f"""\
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>
#include "hertzmdr_laws.h"

static double in[8][{POINTS}];

static double now(void)
{{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}}

static int read_rows(double rows[8][{POINTS}], int k)
{{
    int i, j;
    for (i = 0; i < {POINTS}; ++i)
        for (j = 0; j < k; ++j)
            if (scanf("%lf", &rows[j][i]) != 1) return 0;
    return 1;
}}

int main(void)
{{
    long i;
    int round_;
    double best, sink = 0.0;
{''.join(blocks)}    return 0;
}}
"""


def run_c(calls: int) -> tuple[dict[str, float], dict[str, np.ndarray]] | None:
    """ns per call and the values at the first POINTS rows of every law, or None without cc."""
    cc = shutil.which("cc")
    if cc is None:
        print("no C compiler (cc) on PATH: the C column is not measured", flush=True)
        return None
    with tempfile.TemporaryDirectory() as tmp:
        src, exe = Path(tmp) / "bench.c", Path(tmp) / "bench"
        src.write_text(timer_source(calls))
        subprocess.run([cc, "-std=c99", "-O2", "-I", str(include_dir()), str(src), "-o",
                        str(exe), "-lm"], check=True)
        rows = []
        for law in LAWS:
            pts = draw(law, POINTS, seed=1)
            for i in range(POINTS):
                rows.append(" ".join(repr(float(v[i])) for v in pts.values()))
        out = subprocess.run([str(exe)], input="\n".join(rows) + "\n", capture_output=True,
                             text=True, check=True).stdout
    ns = {m[1]: float(m[2]) for m in re.finditer(r"^time (\w+) (\S+)", out, re.M)}
    values: dict[str, list[float]] = {}
    for m in re.finditer(r"^value (\w+) (\S+)", out, re.M):
        values.setdefault(m[1], []).append(float(m[2]))
    return ns, {k: np.array(v) for k, v in values.items()}


def rel_err(got: np.ndarray, ref: np.ndarray) -> float:
    with np.errstate(divide="ignore", invalid="ignore"):
        d = np.where(got == ref, 0.0, np.abs(got - ref) / np.abs(ref))
    return float(d.max())


def main(argv=None) -> int:
    args = _common.parser(__doc__).parse_args(argv)
    run = _common.run_from(args)
    load = os.getloadavg()[0]
    calls = 10**4 if args.quick else 10**6
    n_acc = 10 if args.quick else 100
    measured = run_c(calls)
    rows = []
    for law in LAWS:
        big = draw(law, calls, seed=2)
        fn = getattr(gen, law.relation)
        t = _timing.measure(lambda fn=fn, big=big: fn(**big), run.budget)
        pts = draw(law, POINTS, seed=1)
        k = slice(0, n_acc)
        f_mp = getattr(gen_mp, law.relation)
        with mp.workdps(30):
            truth = np.array([float(f_mp(*(mp.mpf(float(v[i])) for v in pts.values())))
                              for i in range(n_acc)])
        np_vals = np.asarray(fn(**pts), dtype=float) * np.ones(POINTS)
        row = {"law": law, "np_ns": 1e9 * t.median / calls, "np_err": rel_err(np_vals[k], truth)}
        if measured is not None:
            ns, values = measured
            row.update(c_ns=ns[law.relation], c_err=rel_err(values[law.relation][k], truth),
                       diff=rel_err(values[law.relation], np_vals))
        rows.append(row)
    table = [BEGIN + "\n\n",
             "Written by `benchmarks/bench_c.py` (`make benchmark`); regenerate, do not edit.\n\n",
             _timing.conditions() + f" C compiler: {compiler()}. Load average at the start "
             f"of the run: {load:.1f} (the machine is shared: the C times of the cheap laws are "
             "at the resolution of the loop, the others move with the load).\n\n",
             " ".join(__doc__.split("\n\n")[1].split()) + "\n\n",
             "| function | C, ns per call | NumPy, ns per element | C / NumPy | C error | "
             "NumPy error | largest C-NumPy difference |\n|---|---|---|---|---|---|---|\n"]
    for r in rows:
        if "c_ns" in r:
            c = (f"{r['c_ns']:.3g} | {r['np_ns']:.3g} | {r['c_ns'] / r['np_ns']:.2g} | "
                 f"{r['c_err']:.1e} | {r['np_err']:.1e} | {r['diff']:.1e}")
        else:
            c = f"no C compiler | {r['np_ns']:.3g} | - | - | {r['np_err']:.1e} | -"
        table.append(f"| `{r['law'].c_name}` | {c} |\n")
    table.append("\n" + END)
    template = (_common.DOCS / DOC).read_text()
    start, stop = template.index(BEGIN), template.index(END) + len(END)
    (run.docs / DOC).write_text(template[:start] + "".join(table) + template[stop:])
    print(f"wrote {run.docs / DOC}")
    return 0


def compiler() -> str:
    cc = shutil.which("cc")
    if cc is None:
        return "none"
    out = subprocess.run([cc, "--version"], capture_output=True, text=True).stdout
    return out.splitlines()[0].strip() + ", -O2" if out else cc


if __name__ == "__main__":
    sys.exit(main())
