"""What accuracy costs in time: every way hertzmdr can compute a quantity, its error and time.

``hertzmdr accuracy`` (``make accuracy``) measures, for a fixed set of quantities with 50-digit
truths, each way of computing them (the generated closed form in float64, stable against
textbook forms, SciPy quadrature of the defining integral at several tolerances, mpmath at 15
to 100 digits, the numerical methods at several resolutions), and writes ``docs/accuracy.md``
with a table per quantity and a log-log plot of error against time. Times are taken by
``hertzmdr.numeric._timing`` (the benchmarks' helper); ``--quick`` (the tests) times each way in
two rounds of one call: numbers that show the report is whole, not timings.

The truths come from ``_generated_mp`` (the derived expressions printed for mpmath) at 60
digits, or from 60-digit quadrature where there is no closed form; ``tests/`` verify those
expressions against independent quadratures to >= 30 digits.

Every way states the error it should have: its *bound*, from the method's error model (the
roundings of a closed form, the cancellation a textbook form suffers, a series' first omitted
term, a quadrature's tolerance) or the error estimate the method itself reports (hertzmdr's
``rel_error``). The report prints it beside the measured error and marks a row whose error
exceeds it; ``tests/test_accuracy.py`` checks every way's error against its bound. A way that
demonstrates a failure (a textbook form's lost digits, an overflow) *predicts* its error: that
error must then also be at least a hundredth of the bound, so the demonstration shows what it
claims.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from hertzmdr.numeric import _timing

TRUTH_DPS = 60
FLOOR = 1e-50  # errors below this are shown as "< 1e-50" and drawn at this value
#: a predicting way's error must be at least its bound divided by this
PREDICTS_WITHIN = 100.0


@dataclass(frozen=True)
class Way:
    """One way of computing a quantity.

    ``bound``: the relative error this way should have at most (a number from its error
    model, or a function returning the error estimate the method reports; ``inf`` for a way
    expected to fail). ``predicts``: the bound is also the size of the error (a demonstrated
    failure), which must then be at least ``bound / PREDICTS_WITHIN``."""

    method: str  # "closed form", "SciPy quad", "mpmath quad", ...
    setting: str  # "float64", "epsrel=1e-8", "30 digits", ...
    run: Callable[[], object]
    bound: float | Callable[[], float]
    predicts: bool = False


@dataclass(frozen=True)
class Quantity:
    name: str
    description: str
    truth: Callable[[], object]  # called inside mpmath.workdps(TRUTH_DPS)
    ways: Callable[[], list[Way]]
    #: the truth's own relative error, added to every way's bound (60 digits of a closed form
    #: by default; a truth given as data or by a coarser quadrature says its own)
    truth_error: float = 1e-55


@dataclass
class Row:
    method: str
    setting: str
    rel_error: float
    seconds: float  # median time per evaluation
    spread: tuple[float, float]  # min and max of the repeats, per evaluation
    bound: float = float("inf")  # the way's bound, the truth's error included
    predicts: bool = False

    @property
    def within(self) -> bool:
        """Whether the measured error is within the bound (and, for a way that predicts its
        error, at least the bound over PREDICTS_WITHIN)."""
        e, b = self.rel_error, self.bound
        if e != e:
            return False
        if self.predicts:
            return b / PREDICTS_WITHIN <= e <= b
        return e <= b


@dataclass
class Measured:
    quantity: Quantity
    rows: list[Row] = field(default_factory=list)


def bound_of(way: Way, q: Quantity) -> float:
    """The way's bound with the truth's own error added (a bound that is a function, the
    method's reported error, is called here)."""
    b = way.bound() if callable(way.bound) else way.bound
    b = float(b)
    if not b >= 0:  # nan or negative: a bound that bounds nothing
        raise ValueError(f"{q.name}, {way.method} ({way.setting}): bound = {b!r}; valid: >= 0")
    return b + q.truth_error


def measure(q: Quantity, progress=None, budget: _timing.Budget | None = _timing.FULL
            ) -> Measured:
    """Each way's relative error against the truth, its bound and (unless ``budget`` is
    None: the errors only, times 0) its time per evaluation."""
    import mpmath as mp

    with mp.workdps(TRUTH_DPS):
        truth = q.truth()
    out = Measured(q)
    for way in q.ways():
        value = way.run()
        with mp.workdps(TRUTH_DPS):
            v = mp.mpf(value)
            err = float(abs((v - truth) / truth)) if mp.isfinite(v) else float("inf")
        if budget is None:
            seconds, spread = 0.0, (0.0, 0.0)
        else:
            t = _timing.measure(way.run, budget)
            seconds, spread = t.median, t.spread
        out.rows.append(Row(way.method, way.setting, err, seconds, spread, bound_of(way, q),
                            way.predicts))
        if progress:
            progress()
    return out


def _fmt_err(e: float) -> str:
    if e != e or e == float("inf"):
        return "fails (inf or nan)"
    return f"< {FLOOR:.0e}" if e < FLOOR else f"{e:.1e}"


def _fmt_bound(r: Row) -> str:
    """The bound as an error is shown, "predicted" for a way that predicts its error, and the
    mark of a row outside it."""
    text = "fails" if r.bound == float("inf") else _fmt_err(r.bound)
    if r.predicts:
        text += " (predicted)"
    return text if r.within else f"{text}, **outside its bound**"


def _fmt_time(s: float) -> str:
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if s >= scale:
            return f"{s / scale:.3g} {unit}"
    return f"{s * 1e9:.3g} ns"


def digits(e: float) -> float:
    import math

    if not math.isfinite(e) or e >= 1:
        return 0.0
    return 50.0 if e < FLOOR else -math.log10(max(e, 1e-300))


def markdown(results: list[Measured], figure: str | None,
             budget: _timing.Budget = _timing.FULL) -> str:
    lines = ["# What accuracy costs in time\n",
             "<!-- Written by `hertzmdr accuracy` (make accuracy); regenerate, do not edit. -->\n",
             f"{_timing.conditions()}\n",
             "For each quantity: every way hertzmdr can compute it, the relative error against "
             "a 50-digit truth, and the median time per evaluation with the spread (min-max of "
             f"up to {budget.repeats} rounds of at least {budget.min_time:g} s together; the "
             "first call apart, not shown). *Digits* is -log10 of the error. Read it as: how many "
             "digits can I have, and what does each digit cost.\n",
             "*Bound* is the error each way should have at most: from its error model (the "
             "roundings of a closed form, the cancellation of a textbook form, a series' first "
             "omitted term, a quadrature's tolerance) or the error estimate the method reports, "
             "plus the truth's own error. *predicted*: a demonstrated failure, whose error "
             "must also be at least a hundredth of the bound. A row whose error is outside is "
             "marked **outside its bound**.\n"]
    if figure:
        lines.append(f"![error against time]({figure})\n")
    rows = [r for m in results for r in m.rows]
    outside = [r for r in rows if not r.within]
    lines.append(f"{len(rows) - len(outside)} of {len(rows)} ways within their bounds"
                 + (": **" + "; ".join(f"{r.method} ({r.setting})" for r in outside) + "** not"
                    if outside else "") + ".\n")
    lines.append("## Headline\n")
    lines.append("| quantity | fastest way to 1e-12 | its time | most digits | at what cost |")
    lines.append("| --- | --- | --- | --- | --- |")
    for m in results:
        good = [r for r in m.rows if r.rel_error <= 1e-12]
        fast = min(good, key=lambda r: r.seconds) if good else None
        best = min(m.rows, key=lambda r: (r.rel_error, r.seconds))
        lines.append(f"| {m.quantity.name} | "
                     + (f"{fast.method} ({fast.setting}) | {_fmt_time(fast.seconds)}" if fast
                        else "none | -")
                     + f" | {digits(best.rel_error):.0f} ({best.method}, {best.setting}) | "
                     f"{_fmt_time(best.seconds)} |")
    for m in results:
        lines.append(f"\n## {m.quantity.name}\n\n{m.quantity.description}\n")
        lines.append("| method | setting | rel. error | bound | digits | time per evaluation "
                     "| spread |")
        lines.append("| --- | --- | --- | --- | --- | --- | --- |")
        for r in sorted(m.rows, key=lambda r: r.seconds):
            lines.append(f"| {r.method} | {r.setting} | {_fmt_err(r.rel_error)} | "
                         f"{_fmt_bound(r)} | "
                         f"{digits(r.rel_error):.1f} | {_fmt_time(r.seconds)} | "
                         f"{_fmt_time(r.spread[0])} - {_fmt_time(r.spread[1])} |")
    return "\n".join(lines) + "\n"


# The figure below is drawing only (what it draws, the rows, is measured and tested above):
# mutation runs leave it out, as they do numeric/plots.py and fit_io.py's figures.
# pragma: no mutate start
def plot(results: list[Measured], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = len(results)
    cols = min(3, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.0 * cols, 3.8 * rows), dpi=110,
                             squeeze=False)
    for ax, m in zip(axes.flat, results, strict=False):
        methods = sorted({r.method for r in m.rows})
        for meth in methods:
            pts = [(r.seconds, max(r.rel_error, FLOOR)) for r in m.rows
                   if r.method == meth and r.rel_error < float("inf")]
            if pts:
                ax.loglog(*zip(*pts, strict=True), "o", label=meth, ms=5)
        front, best = [], float("inf")
        for r in sorted(m.rows, key=lambda r: r.seconds):
            if r.rel_error < best:
                best = r.rel_error
                front.append((r.seconds, max(r.rel_error, FLOOR)))
        ax.loglog(*zip(*front, strict=True), "k-", lw=0.8, alpha=0.6, drawstyle="steps-post",
                  label="Pareto front")
        ax.set_title(m.quantity.name, fontsize=9)
        ax.set_xlabel("seconds per evaluation")
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=6)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


# pragma: no mutate end


def quantities() -> list[Quantity]:
    from hertzmdr.numeric import _accuracy_cases

    return _accuracy_cases.all_quantities()


def main(out: Path, only: str | None = None, quick: bool = False) -> list[Measured]:
    """Measure every quantity (or those whose name contains ``only``) and write the report
    ``out`` with its plot beside it; ``quick``: two rounds of one call per way."""
    from tqdm import tqdm

    budget = _timing.QUICK if quick else _timing.FULL
    qs = [q for q in quantities() if only is None or only in q.name]
    if not qs:
        raise ValueError(f"only = {only!r} matches no quantity; the names: "
                         + "; ".join(q.name for q in quantities()))
    with tqdm(total=sum(len(q.ways()) for q in qs), desc="ways measured", unit="way",
              file=sys.stderr) as bar:
        results = [measure(q, lambda: bar.update(1), budget) for q in qs]
    out.parent.mkdir(parents=True, exist_ok=True)
    fig = out.with_suffix(".png")
    plot(results, fig)
    out.write_text(markdown(results, fig.name, budget) + domain_search_section())
    return results


#: the counts of the last bulk run of the documented-domain search (tests/domain_search.py)
DOMAIN_SEARCH_RECORD = Path(__file__).resolve().parent.parent / "docs" / "domain_search.json"


def domain_search_section(record: Path | None = None) -> str:
    """The docs/accuracy.md section on the documented-domain search, from its record
    (default: :data:`DOMAIN_SEARCH_RECORD`)."""
    import json

    record = DOMAIN_SEARCH_RECORD if record is None else record
    if not record.exists():
        return ""
    c = json.loads(record.read_text())
    return ("\n## Documented domains searched\n\n"
            "Every public function of hertz, powerlaw, cone, line, bodies, ellipse, stress and "
            "line_stress, "
            "each parameter over the range its docstring guarantees (n from 1e-3 to 1e8, nu "
            "from nextafter(-1, 0) to 0.5, ratios to 1e8, positions to 1e300 m, forces down "
            "to 1e-300 N), the neighbours of every edge it branches on, round trips, and "
            "the documented OverflowError/ValueError where the true value (40-digit mpmath) "
            "is no float64, with every warning an error. Written by "
            f"`{c['command']}` ({c['points_per_row']} random points per function besides "
            "the corners and edges; CI runs a few).\n\n"
            "| functions | parameters | cases | failures | seconds |\n"
            "| --- | --- | --- | --- | --- |\n"
            f"| {c['functions']} | {c['parameters']} | {c['cases']} | {c['failures']} | "
            f"{c['seconds']} |\n")
