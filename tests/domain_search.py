"""The documented-domain search: every public function of the closed-form modules over the
whole domain its docstring guarantees, with the points next to every boundary it branches on.

Each :class:`Row` names a function, the documented range of each parameter, the points next
to its branch boundaries (``near``: nextafter of the contact edge, r = a (1 +- k eps)), an
mpmath reference of the relation at 40 digits (mpmath's exponent range is unbounded, so the
reference also says whether the true value is representable in float64), the argument it is
monotone in, and the inverse it must round-trip through. A case passes when, with every
warning an error,

- the true value is a float64 and the function returns it, finite, to ``rtol`` (a loose bound:
  this is a search for silent garbage, the accuracy tests are elsewhere) relative to
  max(|reference|, the row's scale);
- the true value exceeds 1.8e308 and the function raises OverflowError or ValueError whose
  message names an input;
- the inputs are outside a documented restriction (``refused``) and it raises ValueError;
- it moves in the stated direction when its monotone argument grows, and the inverse
  gives back the argument.

Run by ``tests/test_domains.py`` (few points per row in CI, the bulk behind the ``sweep``
marker with HERTZMDR_SWEEP=full), or as a script: ``python tests/domain_search.py --record
docs/domain_search.json`` runs the bulk and writes the counts that ``hertzmdr accuracy`` puts
into docs/accuracy.md.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass

import mpmath as mp
import numpy as np

from hertzmdr.numeric import _generated_mp as gm
from hertzmdr.numeric import bodies, cone, ellipse, hertz, line, line_stress, powerlaw, stress

EPS = np.finfo(float).eps
BIG = float(np.finfo(float).max)
TINY = float(np.finfo(float).tiny)
#: results below this are checked in absolute terms: a product of several factors may pass
#: through values 1e28 smaller than itself (documented: |result| >= 1e-280 is guaranteed)
SMALL = 1e-280
DPS = 40


@dataclass(frozen=True)
class P:
    """The documented range [lo, hi] of one parameter: log-uniform (``log``), uniform
    (``lin``), or ``nu`` (Poisson's ratio, -1 < nu <= 0.5, with its ends nextafter(-1, 0) and
    0.5 among the corners). ``zero``: 0 belongs to the range too."""

    lo: float
    hi: float
    kind: str = "log"
    zero: bool = False

    def draw(self, rng: np.random.Generator) -> float:
        if self.zero and rng.random() < 0.05:
            return 0.0
        if self.kind == "log":
            return float(np.exp(rng.uniform(np.log(self.lo), np.log(self.hi))))
        return float(rng.uniform(self.lo, self.hi))

    def ends(self) -> list[float]:
        return [self.lo, self.hi] + ([0.0] if self.zero else [])


LEN = P(1e-12, 1e6)  # lengths: radii, contact lengths [m]
DEPTH = P(1e-15, 1e3, zero=True)  # depths [m]
MOD = P(1e-3, 1e15)  # moduli [Pa]
FORCE = P(1e-300, 1e30, zero=True)  # forces [N], down to the bottom of the float range
POS = P(1e-300, 1e300, zero=True)  # surface coordinates [m]: anywhere, far outside too
NU = P(np.nextafter(-1.0, 0.0), 0.5, "lin")
N = P(1e-3, 1e8)  # power-law exponent
ANGLE = P(1e-300, 1.5)  # cone angle with the plane: guaranteed for 0 < theta <= 1.5
RATIO = P(1.0, 1e8)  # ratios of principal radii
MAX_DISTANCE = 1e100  # the stresses' documented reach, stress.MAX_DISTANCE (tested there)


@dataclass
class Row:
    name: str
    fn: Callable[..., object]
    params: dict[str, P]
    ref: Callable[..., mp.mpf] | None = None  # of mpf keyword arguments (after ``derive``)
    derive: Callable[[dict], dict] | None = None  # computed arguments (c_n from a, ...)
    near: Callable[[dict], list[dict]] | None = None  # points next to branch boundaries
    mono: tuple[str, int] | None = None
    # (argument, (args, value) -> argument, the documented range of the value as an input)
    inverse: tuple[str, Callable[..., object], P] | None = None
    refused: Callable[[dict], bool] | None = None  # documented ValueError
    scale: Callable[..., mp.mpf] | None = None  # absolute error allowed besides rtol, e.g.
    # p0 sqrt(eps) for a pressure next to the edge, where the rounding of a moves it that much
    pick: int | None = None  # component of a tuple result
    rtol: float = 1e-8
    cost: int = 1  # relative cost of one case (fewer cases for slow rows)
    target: Callable | None = None  # the public function whose docstring states the domain
    note: str = ""  # what the ranges stand for, when a parameter is drawn through another


def _range(name: str, p: P) -> str:
    if p.lo == np.nextafter(-1.0, 0.0):
        return f"{name} in (-1, {p.hi:g}]"
    return f"{name} in {'{0} U ' if p.zero else ''}[{p.lo:g}, {p.hi:g}]"


def guarantee(row: Row) -> str:
    """The sentence of the docstring that states the searched domain, as the search has it."""
    ranges = ", ".join(_range(k, v) for k, v in row.params.items())
    return (f"Guaranteed finite and accurate for {ranges}{row.note} (SI units; searched by "
            "tests/domain_search.py).")


def _mp(args: dict) -> dict:
    return {k: mp.mpf(v) if isinstance(v, float) else v for k, v in args.items()}


def _finite_tuple(value, pick):
    if isinstance(value, tuple):
        value = value[pick] if pick is not None else np.concatenate(
            [np.ravel(np.asarray(v, dtype=float)) for v in value])
    return np.asarray(value, dtype=float)


def check(row: Row, args: dict) -> str | None:
    """None if the case passes, else what went wrong."""
    where = f"{row.name}({', '.join(f'{k}={v!r}' for k, v in args.items())})"
    ref = None
    shown = "-"
    if row.ref is not None:
        with mp.workdps(DPS):
            ref = row.ref(**_mp(args))
            scale = abs(row.scale(**_mp(args))) if row.scale is not None else mp.mpf(0)
            shown = mp.nstr(ref, 8)
    refused = row.refused(args) if row.refused is not None else False
    except_ok = refused or refused is None  # None: a rounding decides, either outcome is right
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            value = _finite_tuple(row.fn(**args), row.pick)
    except (OverflowError, ValueError) as exc:
        named = any(k in str(exc) for k in args)
        if except_ok and isinstance(exc, ValueError):
            return None if named else f"{where}: the error names no input: {exc}"
        if ref is not None and abs(ref) > BIG:
            return None if named else f"{where}: the error names no input: {exc}"
        return f"{where}: {type(exc).__name__}: {exc} (reference {shown})"
    except Exception as exc:  # a RuntimeWarning turned error, a TypeError, ...
        return f"{where}: {type(exc).__name__}: {exc}"
    if refused:
        return f"{where}: returned {value} instead of the documented ValueError"
    if ref is not None and mp.isinf(ref) and np.isinf(value).all():
        return None  # a documented singular value (the cone's tip)
    if not np.isfinite(value).all():
        return f"{where}: returned {value} (reference {shown})"
    if ref is not None:
        v = float(np.ravel(value)[0])
        if abs(ref) > BIG:
            return f"{where}: returned {v!r}, but the true value {mp.nstr(ref, 8)} is no float64"
        with mp.workdps(DPS):
            err = abs(mp.mpf(v) - ref)
            bound = row.rtol * abs(ref) + scale + SMALL  # below SMALL: underflow is fine
            if err > bound:
                return (f"{where}: returned {v!r}, reference {mp.nstr(ref, 17)} (error "
                        f"{mp.nstr(err, 3)} > {row.rtol:g} |ref| + {mp.nstr(scale, 3)})")
    if row.mono is not None:
        name, sign = row.mono
        if args[name] > 0:
            moved = {**args, name: args[name] * (1 + 1e-3)}
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("error")
                    other = _finite_tuple(row.fn(**moved), row.pick)
            except (OverflowError, ValueError):
                other = None  # past the top of the range: nothing to compare
            if other is not None:
                a, b = float(np.ravel(value)[0]), float(np.ravel(other)[0])
                if sign * (b - a) < -8 * EPS * max(abs(a), abs(b)):
                    return f"{where}: not monotone in {name}: {a!r} -> {b!r} at {moved[name]!r}"
    if row.inverse is not None:
        name, inv, rng = row.inverse
        v = float(np.ravel(value)[0])
        if rng.lo <= v <= rng.hi:
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("error")
                    back = float(inv(args, v))
            except Exception as exc:  # noqa: BLE001 - a round trip may not fail in any way
                return f"{where}: the inverse failed at {v!r}: {type(exc).__name__}: {exc}"
            if not abs(back - args[name]) <= row.rtol * abs(args[name]):
                return f"{where}: round trip {name} = {args[name]!r} -> {v!r} -> {back!r}"
    return None


def cases(row: Row, n: int, seed: int = 0, corners: bool = True):
    """Corners of the box (up to 64; none with ``corners=False``), n log-uniform points, and
    the boundary neighbours of every point (``near``)."""
    rng = np.random.default_rng(seed)
    names = list(row.params)
    pts = []
    ends = [row.params[k].ends() for k in names]
    for i in range(min(64, math.prod(len(e) for e in ends)) if corners else 0):
        pt, j = {}, i
        for k, e in zip(names, ends, strict=True):
            pt[k] = e[j % len(e)]
            j //= len(e)
        pts.append(pt)
    pts += [{k: row.params[k].draw(rng) for k in names} for _ in range(n)]
    seen = set()  # corners that differ only in the argument `near` moves share its points

    def fresh(pt):
        key = tuple(sorted((k, repr(np.asarray(v).tolist())) for k, v in pt.items()))
        if key in seen:
            return False
        seen.add(key)
        return True

    for pt in pts:
        pt = dict(pt)
        if row.derive is not None:
            pt = row.derive(pt)
            if pt is None:
                continue
        if fresh(pt):
            yield pt
        if row.near is not None:
            yield from (q for q in row.near(pt) if fresh(q))


def run(rows: list[Row], n: int, seed: int = 0, keep: int = 3,
        corners: bool = True) -> tuple[list[str], dict]:
    """Run the search; the failures (the first ``keep`` per row) and the counts. With
    ``corners=False`` only the random points (and their neighbours) are searched."""
    failures: list[str] = []
    counts = {"functions": len(rows), "parameters": sum(len(r.params) for r in rows),
              "cases": 0}
    t0 = time.perf_counter()
    for row in rows:
        bad = 0
        for pt in cases(row, max(2, n // row.cost), seed, corners):
            counts["cases"] += 1
            msg = check(row, pt)
            if msg is not None:
                bad += 1
                if bad <= keep:
                    failures.append(msg)
        if bad > keep:
            failures.append(f"{row.name}: {bad - keep} more failing cases")
    counts["seconds"] = round(time.perf_counter() - t0, 1)
    return failures, counts


# -- the rows ---------------------------------------------------------------------------------

def _edge(key: str, radius: Callable[[dict], float]):
    """The points next to the edge r = a of every case: nextafter both ways, a (1 +- k eps),
    a (1 +- h) for h = 1e-9 ... 0.1 (just inside and just outside)."""
    def near(pt):
        a = radius(pt)
        if not (0 < a < 1e300):
            return []
        rs = [np.nextafter(a, 0.0), a, np.nextafter(a, np.inf)]
        rs += [a * (1 + k * EPS) for k in (-4, -2, 2, 4)]
        rs += [a * (1 + s * h) for h in (1e-9, 1e-6, 1e-3, 0.1) for s in (-1, 1)]
        return [{**pt, key: float(r)} for r in rs]
    return near


def _hertz_rows() -> list[Row]:
    def a_of(p):
        return float(hertz.contact_radius(p["d"], p["R"]))

    def F_ref(E_star, R, d):
        return gm.hertz_force(E_star=E_star, R=R, d=d)

    dRE = {"d": DEPTH, "R": LEN, "E_star": MOD}
    FRE = {"F": FORCE, "R": LEN, "E_star": MOD}
    rows = [
        Row("hertz.contact_radius", hertz.contact_radius, {"d": DEPTH, "R": LEN},
            lambda d, R: gm.hertz_contact_radius(R=R, d=d), mono=("d", +1)),
        Row("hertz.max_pressure", hertz.max_pressure, dRE,
            lambda d, R, E_star: gm.hertz_max_pressure(E_star=E_star, R=R, d=d), mono=("d", 1)),
        Row("hertz.mean_pressure", hertz.mean_pressure, dRE,
            lambda d, R, E_star: gm.hertz_mean_pressure(E_star=E_star, R=R, d=d),
            mono=("d", 1)),
        Row("hertz.force", hertz.force, dRE, F_ref, mono=("d", 1),
            inverse=("d", lambda p, v: hertz.depth_from_force(v, p["R"], p["E_star"]), FORCE)),
        Row("hertz.energy", hertz.energy, dRE,
            lambda d, R, E_star: gm.hertz_energy(E_star=E_star, R=R, d=d), mono=("d", 1)),
        Row("hertz.stiffness", hertz.stiffness, dRE,
            lambda d, R, E_star: gm.hertz_stiffness(E_star=E_star, R=R, d=d), mono=("d", 1)),
        Row("hertz.depth_from_force", hertz.depth_from_force, FRE,
            lambda F, R, E_star: gm.hertz_depth_from_force(E_star=E_star, F=F, R=R),
            mono=("F", 1), inverse=("F", lambda p, v: hertz.force(v, p["R"], p["E_star"]), DEPTH)),
        Row("hertz.contact_radius_from_force", hertz.contact_radius_from_force, FRE,
            lambda F, R, E_star: gm.hertz_contact_radius_from_force(E_star=E_star, F=F, R=R),
            mono=("F", 1)),
        Row("hertz.max_pressure_from_force", hertz.max_pressure_from_force, FRE,
            lambda F, R, E_star: gm.hertz_max_pressure_from_force(E_star=E_star, F=F, R=R),
            mono=("F", 1)),
        Row("hertz.pressure", hertz.pressure,
            {"r": POS, "d": P(1e-15, 1e3), "R": LEN, "E_star": MOD},
            lambda r, d, R, E_star: gm.hertz_max_pressure(E_star=E_star, R=R, d=d)
            * mp.sqrt(max(0, 1 - r**2 / (R * d))),
            near=_edge("r", a_of), mono=("r", -1),
            # p ~ p0 sqrt(2 (1 - r/a)): the rounding of a moves it by p0 sqrt(eps) at the edge
            scale=lambda r, d, R, E_star: gm.hertz_max_pressure(E_star=E_star, R=R, d=d) * 1e-7),
        Row("hertz.surface_displacement", hertz.surface_displacement,
            {"r": POS, "d": P(1e-15, 1e3), "R": LEN},
            lambda r, d, R: (d - r**2 / (2 * R)) if r**2 <= R * d
            else gm.hertz_displacement_outside(R=R, d=d, r=r),
            near=_edge("r", a_of), mono=("r", -1), scale=lambda r, d, R: d * 1e-7),
    ]
    return rows


def _powerlaw_rows() -> list[Row]:
    def kappa_mp(n):
        return mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)

    def with_c(p, keep_d=True):
        """c_n = d/(kappa_n a^n) for a drawn contact radius a (the physical parametrization:
        the depth and the contact radius in their ranges); None if c_n is no float."""
        # a^n must leave kappa_n c_n a float: for large n, a is drawn within exp(+-500/n) of
        # 1 m (the same log-uniform position in that band as in its own range)
        a, n = p.pop("a"), p["n"]
        band = min(1.0, 500.0 / n / math.log(1e9))  # |log a| <= log(1e9) in its range
        a = math.exp(math.log(a) * band)
        with mp.workdps(DPS):
            c = mp.mpf(p["d"]) / (kappa_mp(mp.mpf(n)) * mp.mpf(a) ** n)
        if not (TINY < c < BIG):
            return None
        if not keep_d:
            p.pop("d")
        return {**p, "c_n": float(c)}

    def without_d(p):
        return with_c(p, keep_d=False)

    def a_ref(d, c_n, n):
        return (d / (kappa_mp(n) * c_n)) ** (1 / n)

    def disp_ref(r, d, c_n, n):
        a = mp.mpf(float(powerlaw.contact_radius(float(d), float(c_n), float(n))))
        if r <= a:
            return d - c_n * r**n
        # (5.60) for g = d (x/a)^n, by quadrature (the rounded a that the function uses), with
        # x = r sin(phi_a - w), phi_a = asin(a/r): dx/sqrt(r^2 - x^2) = -dw takes out the
        # endpoint singularity; geometric breakpoints towards w = 0 resolve the layer where
        # (x/a)^n falls from 1 (width ~1/n away from the edge, ~1/sqrt(n) at r -> a)
        phi_a = mp.asin(a / r)
        f = lambda w: 1 - (r * mp.sin(phi_a - w) / a) ** n  # noqa: E731
        k = min(60, int(mp.log(n + 2, 2)) + 6)
        pts = [mp.mpf(0)] + [phi_a * mp.mpf(2) ** -j for j in range(k, 0, -1)] + [phi_a]
        # the quadrature at 30 digits, not DPS: 1e-30 against this row's rtol of 1e-6, and 30 %
        # less CPU (test_documented_domain's corners and edges: 17.8 -> 12.5 s)
        with mp.workdps(30):
            return 2 * d / mp.pi * mp.quad(f, pts)

    dcn = {"d": P(1e-15, 1e3), "a": P(1e-9, 1e3), "n": N}
    cn = (", with c_n = d/(kappa_n a^n) for a contact radius a in that range (for n > 24 "
          "within exp(+-500/n) of 1 m, so that kappa_n c_n is a float)")
    rows = [
        Row("powerlaw.kappa", powerlaw.kappa, {"n": P(1e-3, 1e300)},
            lambda n: kappa_mp(n) if n < 1e6 else mp.sqrt(mp.pi * n / 2) * mp.exp(1 / (4 * n)),
            mono=("n", 1)),
        Row("powerlaw.g_profile", powerlaw.g_profile, {"x": P(1e-12, 1e3, zero=True), **dcn},
            lambda x, c_n, n: kappa_mp(n) * c_n * x**n, note=cn, derive=without_d, mono=("x", 1)),
        Row("powerlaw.contact_radius", powerlaw.contact_radius, dcn, a_ref, note=cn, derive=with_c,
            mono=("d", 1)),
        Row("powerlaw.force", powerlaw.force, {**dcn, "E_star": MOD},
            lambda d, c_n, n, E_star: 2 * n / (n + 1) * E_star * a_ref(d, c_n, n) * d,
            note=cn, derive=with_c, mono=("d", 1),
            inverse=("d", lambda p, v: powerlaw.depth_from_force(v, p["c_n"], p["n"],
                                                                 p["E_star"]), FORCE)),
        Row("powerlaw.force_from_radius", powerlaw.force_from_radius,
            {"a": LEN, "d": DEPTH, "n": N, "E_star": MOD},
            lambda a, d, n, E_star: 2 * n / (n + 1) * E_star * a * d, mono=("d", 1)),
        Row("powerlaw.depth_from_force", powerlaw.depth_from_force,
            {"F": FORCE, "d": P(1e-15, 1e3), "a": P(1e-9, 1e3), "n": N, "E_star": MOD},
            lambda F, c_n, n, E_star: (F * (n + 1) / (2 * E_star * n)) ** (n / (n + 1))
            * (kappa_mp(n) * c_n) ** (1 / (n + 1)),
            note=cn, derive=without_d, mono=("F", 1),
            inverse=("F", lambda p, v: powerlaw.force(v, p["c_n"], p["n"], p["E_star"]),
                     DEPTH)),
        Row("powerlaw.mean_pressure", powerlaw.mean_pressure, {**dcn, "E_star": MOD},
            lambda d, c_n, n, E_star: 2 * n * E_star * d / (mp.pi * (n + 1) * a_ref(d, c_n, n)),
            note=cn, derive=with_c),
        Row("powerlaw.pressure", powerlaw.pressure,
            {"r": POS, "d": P(1e-15, 1e3), "a": P(1e-9, 1e3), "n": P(1.5, 1e8),
             "E_star": MOD}, None, note=cn, derive=with_c, cost=4,  # rises to the rim for large n
            near=_edge("r", lambda p: float(powerlaw.contact_radius(p["d"], p["c_n"],
                                                                    p["n"])))),
        Row("powerlaw.pressure_normalized", powerlaw.pressure_normalized,
            {"r_tilde": P(1e-12, 1e300, zero=True), "n": P(1.5, 1e8)}, None,
            cost=4, near=_edge("r_tilde", lambda p: 1.0)),
        Row("powerlaw.surface_displacement", powerlaw.surface_displacement,
            {"r": POS, "d": P(1e-15, 1e3), "a": P(1e-9, 1e3), "n": N}, disp_ref,
            note=cn, derive=with_c, mono=("r", -1), cost=8,
            near=_edge("r", lambda p: float(powerlaw.contact_radius(p["d"], p["c_n"],
                                                                    p["n"]))),
            # next to the edge the 2F1 form keeps ~sqrt(eps) of u(a) (measured 1e-8 at a(1 + eps))
            scale=lambda r, d, c_n, n: d * 1e-7, rtol=1e-6),
    ]
    return rows


def _cone_rows() -> list[Row]:
    dtE = {"d": DEPTH, "theta": ANGLE, "E_star": MOD}
    FtE = {"F": FORCE, "theta": ANGLE, "E_star": MOD}

    def a_of(p):
        return float(cone.contact_radius(p["d"], p["theta"]))

    return [
        Row("cone.contact_radius", cone.contact_radius, {"d": DEPTH, "theta": ANGLE},
            lambda d, theta: gm.cone_contact_radius(d=d, theta=theta), mono=("d", 1)),
        Row("cone.depth", cone.depth, {"a": LEN, "theta": ANGLE},
            lambda a, theta: gm.cone_depth(a=a, theta=theta), mono=("a", 1)),
        Row("cone.force", cone.force, dtE,
            lambda d, theta, E_star: gm.cone_force(E_star=E_star, d=d, theta=theta),
            mono=("d", 1),
            inverse=("d", lambda p, v: cone.depth_from_force(v, p["theta"], p["E_star"]),
                     FORCE)),
        Row("cone.pressure", cone.pressure, {"r": POS, **dtE},
            lambda r, d, theta, E_star: (E_star * mp.tan(theta) / 2 * mp.acosh(
                2 * d / (mp.pi * mp.tan(theta) * r))) if 0 < r < 2 * d / (
                mp.pi * mp.tan(theta)) else (mp.inf if r == 0 and d > 0 else mp.mpf(0)),
            near=_edge("r", a_of), mono=("r", -1),
            refused=lambda p: False,
            scale=lambda r, d, theta, E_star: E_star * mp.tan(theta) * 1e-7),
        Row("cone.mean_pressure", cone.mean_pressure, {"theta": ANGLE, "E_star": MOD},
            lambda theta, E_star: gm.cone_mean_pressure(E_star=E_star, theta=theta),
            mono=("E_star", 1)),
        Row("cone.stiffness", cone.stiffness, dtE,
            lambda d, theta, E_star: gm.cone_stiffness(E_star=E_star, d=d, theta=theta),
            mono=("d", 1)),
        Row("cone.depth_from_force", cone.depth_from_force, FtE,
            lambda F, theta, E_star: gm.cone_depth_from_force(E_star=E_star, F=F, theta=theta),
            mono=("F", 1)),
        Row("cone.contact_radius_from_force", cone.contact_radius_from_force, FtE,
            lambda F, theta, E_star: gm.cone_contact_radius_from_force(E_star=E_star, F=F,
                                                                       theta=theta),
            mono=("F", 1)),
    ]


def _line_rows() -> list[Row]:
    def a_of(p):
        return float(line.half_width(p["d"], p["R"]))

    FLRE = {"F": FORCE, "L": LEN, "R": LEN, "E_star": MOD}
    return [
        Row("line.half_width", line.half_width, {"d": DEPTH, "R": LEN},
            lambda d, R: gm.line_half_width(R=R, d=d), mono=("d", 1)),
        Row("line.force", line.force, {"d": DEPTH, "L": LEN, "E_star": MOD},
            lambda d, L, E_star: gm.line_force(E_star=E_star, L=L, d=d), mono=("d", 1),
            inverse=("d", lambda p, v: line.depth_from_force(v, p["L"], p["E_star"]), FORCE)),
        Row("line.depth_from_force", line.depth_from_force, {"F": FORCE, "L": LEN, "E_star": MOD},
            lambda F, L, E_star: gm.line_depth_from_force(E_star=E_star, F=F, L=L),
            mono=("F", 1)),
        Row("line.half_width_from_force", line.half_width_from_force, FLRE,
            lambda F, L, R, E_star: gm.line_half_width_from_force(E_star=E_star, F=F, L=L, R=R),
            mono=("F", 1)),
        Row("line.max_pressure", line.max_pressure, {"d": DEPTH, "R": LEN, "E_star": MOD},
            lambda d, R, E_star: gm.line_max_pressure(E_star=E_star, R=R, d=d), mono=("d", 1)),
        Row("line.max_pressure_from_force", line.max_pressure_from_force, FLRE,
            lambda F, L, R, E_star: gm.line_max_pressure_from_force(E_star=E_star, F=F, L=L,
                                                                    R=R), mono=("F", 1)),
        Row("line.pressure", line.pressure,
            {"x": POS, "d": P(1e-15, 1e3), "R": LEN, "E_star": MOD},
            lambda x, d, R, E_star: gm.line_max_pressure(E_star=E_star, R=R, d=d)
            * mp.sqrt(max(0, 1 - x**2 / (R * d))),
            near=_edge("x", a_of), mono=("x", -1),
            scale=lambda x, d, R, E_star: gm.line_max_pressure(E_star=E_star, R=R, d=d) * 1e-7),
    ]


def _bodies_rows() -> list[Row]:
    R = P(1e-12, 1e150)  # radii of curvature (guaranteed up to 1e150 m, and inf: flat)

    def eig(R1a, R1b, R2a, R2b, omega):
        c, s = mp.cos(omega), mp.sin(omega)
        k = [1 / v if mp.isfinite(v) else mp.mpf(0) for v in (R1a, R1b, R2a, R2b)]
        H = mp.matrix([[k[0] + k[2] * c * c + k[3] * s * s, (k[2] - k[3]) * c * s],
                       [(k[2] - k[3]) * c * s, k[1] + k[2] * s * s + k[3] * c * c]])
        return sorted(mp.eig(H)[0], key=lambda v: mp.re(v))

    def nonconvex(p):
        """True: refused; None: either (a principal curvature within 1e-12 of the curvature
        scale from 0, where a rounding of the inputs decides)."""
        with mp.workdps(DPS):
            lo, hi = eig(*(mp.mpf(p[k]) for k in ("R1a", "R1b", "R2a", "R2b", "omega")))
            size = sum(abs(1 / mp.mpf(p[k])) for k in ("R1a", "R1b", "R2a", "R2b"))
            if min(abs(mp.re(lo)), abs(mp.re(hi))) <= 1e-12 * size:
                return None
            return not (mp.re(lo) >= 0 and mp.re(hi) > 0)

    signed = P(1e-6, 1e6)

    def signs(p):
        rng = np.random.default_rng(abs(hash(tuple(p.values()))) % 2**32)
        out = {k: (v if rng.random() < 0.7 else -v) for k, v in p.items() if k != "omega"}
        out = {k: (np.inf if rng.random() < 0.15 else v) for k, v in out.items()}
        return {**out, "omega": p["omega"]}

    def gd(d, R1, R2, E_star):
        Rt = mp.sqrt(R1 * R2)
        return Rt, 2 / mp.pi * E_star * mp.sqrt(d / Rt)

    return [
        Row("bodies.effective_modulus", bodies.effective_modulus,
            {"E1": MOD, "nu1": NU, "E2": MOD, "nu2": NU},
            lambda E1, nu1, E2, nu2: 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2),
            mono=("E1", 1)),
        Row("bodies.effective_radius", bodies.effective_radius, {"R1": R, "R2": R},
            lambda R1, R2: 1 / (1 / R1 + 1 / R2), mono=("R1", 1)),
        Row("bodies.principal_radii", bodies.principal_radii,
            {"R1a": signed, "R1b": signed, "R2a": signed, "R2b": signed,
             "omega": P(-10.0, 10.0, "lin")}, derive=signs,
            note=" (each radius of either sign, or inf; ValueError for a gap that is not "
            "convex)", refused=nonconvex, pick=0,
            near=lambda p: [{**p, "R2a": -p["R1a"], "R2b": -p["R1b"]}, {**p, "omega": 0.0}]),
        Row("bodies.crossed_cylinder_radii", bodies.crossed_cylinder_radii,
            {"R1": R, "R2": R, "alpha": P(0.0, np.pi, "lin")},
            pick=0, refused=lambda p: np.isinf(p["R1"]) and np.isinf(p["R2"]),
            near=lambda p: [{**p, "R1": np.inf, "R2": np.inf}, {**p, "alpha": 0.0},
                            {**p, "alpha": np.pi}, {**p, "alpha": 1e-300}]),
        Row("bodies.crossed_cylinders_gaussian_radius", bodies.crossed_cylinders_gaussian_radius,
            {"R1": R, "R2": R, "alpha": P(1e-300, np.nextafter(np.pi, 0.0), "lin")},
            lambda R1, R2, alpha: mp.sqrt(R1 * R2) / mp.sin(alpha), mono=("R1", 1),
            near=lambda p: [{**p, "alpha": 1e-300}, {**p, "alpha": 1e-150}]),
        Row("bodies.gaussian_radius", bodies.gaussian_radius, {"R1": R, "R2": R},
            lambda R1, R2: mp.sqrt(R1 * R2), mono=("R1", 1)),
        Row("bodies.gaussian_approx_semi_axes", bodies.gaussian_approx_semi_axes,
            {"d": DEPTH, "R1": LEN, "R2": LEN}, lambda d, R1, R2: mp.sqrt(R1 * d), pick=0,
            mono=("d", 1)),
        Row("bodies.gaussian_approx_area", bodies.gaussian_approx_area,
            {"d": DEPTH, "R1": LEN, "R2": LEN},
            lambda d, R1, R2: mp.pi * mp.sqrt(R1 * R2) * d, mono=("d", 1)),
        Row("bodies.gaussian_approx_max_pressure", bodies.gaussian_approx_max_pressure,
            {"d": DEPTH, "R1": LEN, "R2": LEN, "E_star": MOD},
            lambda d, R1, R2, E_star: gd(d, R1, R2, E_star)[1], mono=("d", 1)),
        Row("bodies.gaussian_approx_force", bodies.gaussian_approx_force,
            {"d": DEPTH, "R1": LEN, "R2": LEN, "E_star": MOD},
            lambda d, R1, R2, E_star: 4 * E_star * mp.sqrt(gd(d, R1, R2, E_star)[0])
            * d ** mp.mpf(1.5) / 3, mono=("d", 1),
            inverse=("d", lambda p, v: bodies.gaussian_approx_depth_from_force(
                v, p["R1"], p["R2"], p["E_star"]), FORCE)),
        Row("bodies.gaussian_approx_depth_from_force", bodies.gaussian_approx_depth_from_force,
            {"F": FORCE, "R1": LEN, "R2": LEN, "E_star": MOD},
            lambda F, R1, R2, E_star: (3 * F / (4 * E_star * (R1 * R2) ** mp.mpf(0.25)))
            ** (mp.mpf(2) / 3), mono=("F", 1)),
        Row("bodies.gaussian_approx_pressure", bodies.gaussian_approx_pressure,
            {"x": POS, "y": POS, "d": P(1e-15, 1e3), "R1": LEN, "R2": LEN, "E_star": MOD},
            lambda x, y, d, R1, R2, E_star: gd(d, R1, R2, E_star)[1] * mp.sqrt(
                max(0, 1 - x**2 / (R1 * d) - y**2 / (R2 * d))),
            scale=lambda x, y, d, R1, R2, E_star: gd(d, R1, R2, E_star)[1] * 1e-7,
            near=lambda p: [{**p, "y": 0.0, "x": float(np.sqrt(p["R1"]) * np.sqrt(p["d"]))},
                            {**p, "x": 0.0, "y": 1e200}]),
    ]


def _ellipse_rows() -> list[Row]:
    def solve_force(R1, q, E_star, depth):
        return ellipse.solve(R1, R1 / q, E_star, depth=depth).force

    def pressure(R1, q, E_star, depth, x, y):
        c = ellipse.solve(R1, R1 / q, E_star, depth=depth)
        return c.pressure(x, y)

    def p_ref(R1, q, E_star, depth, x, y):
        c = ellipse.solve(float(R1), float(R1 / q), float(E_star), depth=float(depth))
        a, b, p0 = (mp.mpf(float(v)) for v in (c.a, c.b, c.max_pressure))
        return p0 * mp.sqrt(max(0, 1 - (x / a) ** 2 - (y / b) ** 2))

    return [
        Row("ellipse.axis_ratio", lambda R1, q: ellipse.axis_ratio(R1, R1 / q),
            {"R1": LEN, "q": RATIO}, mono=("q", -1), target=ellipse.axis_ratio,
            note=", q = max(R1, R2)/min(R1, R2)"),
        Row("ellipse.eccentricity", lambda R1, q: ellipse.eccentricity(R1, R1 / q),
            {"R1": LEN, "q": RATIO}, mono=("q", 1), target=ellipse.eccentricity,
            note=", q = max(R1, R2)/min(R1, R2)"),
        Row("ellipse.solve(...).force", solve_force,
            {"R1": LEN, "q": RATIO, "E_star": MOD, "depth": DEPTH}, mono=("depth", 1),
            target=ellipse.solve, note=", q = max(R1, R2)/min(R1, R2)"),
        Row("ellipse.solve(...).pressure", pressure,
            {"R1": LEN, "q": RATIO, "E_star": MOD, "depth": P(1e-15, 1e3), "x": POS,
             "y": POS}, p_ref, target=ellipse.EllipticContact.pressure,
            note=", q = max(R1, R2)/min(R1, R2), for the contact of solve(..., depth=depth)",
            scale=lambda R1, q, E_star, depth, x, y: mp.mpf(float(ellipse.solve(
                float(R1), float(R1 / q), float(E_star), depth=float(depth)).max_pressure))
            * 1e-7),
    ]


def _stress_rows() -> list[Row]:
    Z = P(1e-300, 1e110, zero=True)  # up to and past the documented max(r, z) <= 1e100 a

    def far(p):  # documented: max(r, z) <= MAX_DISTANCE a
        return max(math.hypot(p.get("r", 0.0), p.get("x", 0.0), p.get("y", 0.0)),
                   p["z"]) > MAX_DISTANCE * p["a"]

    def eta_ref(r, z, a):
        if z > 0:
            return z / a / xi_ref(r, z, a)
        return mp.sqrt(max(0, 1 - (r / a) ** 2))  # on the surface: cos(beta) = sqrt(1 - r^2/a^2)

    def xi_ref(r, z, a):
        r, z = r / a, z / a
        q = (r - 1) * (r + 1) + z * z
        D = mp.sqrt(q * q + 4 * z * z)
        u = (q + D) / 2 if q > 0 else (2 * z * z / (D - q) if z > 0 else mp.mpf(0))
        return mp.sqrt(u)

    def tau_max_ref(nu):
        import sympy as sp

        from hertzmdr.derive import stress as ds

        s = sp.Symbol("s", positive=True)
        tau = (ds.max_shear_axis() / ds.p0).subs(ds.z, ds.a * s).subs(ds.a, 1)
        tau = tau.subs(ds.nu, sp.Float(float(nu), 40))
        slope = sp.lambdify(s, sp.diff(tau, s), "mpmath")
        lo = mp.pi * (1 + nu) / 20  # the slope > 0 there (derive.stress.max_shear_bracket)
        return mp.findroot(slope, (lo, mp.mpf(2)), solver="anderson")

    return [
        Row("stress.spheroidal", stress.spheroidal, {"r": Z, "z": Z, "a": LEN}, xi_ref, pick=0,
            refused=far, note=", max(r, z) <= 1e100 a (a ValueError beyond)",
            near=_edge("r", lambda p: p["a"]), scale=lambda r, z, a: mp.mpf(1e-7)),
        Row("stress.hertz_stress_cylindrical (sigma_zz)",
            stress.hertz_stress_cylindrical,
            {"r": Z, "z": Z, "a": LEN, "p0": MOD, "nu": NU},
            lambda r, z, a, p0, nu: gm.stress_hertz_sigma_zz(
                p0=p0, xi=xi_ref(r, z, a), eta=eta_ref(r, z, a)) if z > 0
            else -p0 * mp.sqrt(max(0, 1 - (r / a) ** 2)),  # on the surface: -p (5.15)
            pick=2, near=_edge("r", lambda p: p["a"]), refused=far,
            note=", max(r, z) <= 1e100 a (a ValueError beyond)",
            scale=lambda r, z, a, p0, nu: p0 * 1e-7),
        Row("stress.hertz_stress", stress.hertz_stress,
            {"x": Z, "y": Z, "z": Z, "a": LEN, "p0": MOD, "nu": NU}, refused=far,
            note=", max(sqrt(x^2 + y^2), z) <= 1e100 a (a ValueError beyond)"),
        Row("stress.axis_stresses (sigma_zz)", stress.axis_stresses,
            {"z": Z, "a": LEN, "p0": MOD, "nu": NU},
            lambda z, a, p0, nu: -p0 / (1 + (z / a) ** 2), pick=0, mono=("z", 1), refused=far,
            note=", z <= 1e100 a (a ValueError beyond)"),
        Row("stress.axis_max_shear", stress.axis_max_shear, {"nu": NU}, tau_max_ref, pick=0,
            near=lambda p: [{"nu": v} for v in (-0.9, -0.8985, -0.99, -1 + 1e-10)]),
        Row("stress.von_mises", lambda s: stress.von_mises(s), {"s": P(1e-100, 1e100)},
            target=stress.von_mises, note=" (s: the size of the stress components)",
            derive=lambda p: {"s": np.diag([p["s"], -p["s"], 0.5 * p["s"]])}),
        Row("stress.tresca", lambda s: stress.tresca(s), {"s": P(1e-100, 1e100)},
            target=stress.tresca, note=" (s: the size of the stress components)",
            derive=lambda p: {"s": np.diag([p["s"], -p["s"], 0.5 * p["s"]])}),
        Row("stress.max_shear", lambda s: stress.max_shear(s), {"s": P(1e-100, 1e100)},
            target=stress.max_shear, note=" (s: the size of the stress components)",
            derive=lambda p: {"s": np.diag([p["s"], -p["s"], 0.5 * p["s"]])}),
        Row("stress.hertz_maximum", stress.hertz_maximum, {"nu": NU}, pick=0, cost=200),
        Row("stress.superposed_stress",
            lambda x, z, a, nu: stress.superposed_stress(x, 0.0, z, lambda r: 1.0 - 0 * r, a,
                                                         nu)[0],
            {"x": P(1e-3, 10.0), "z": P(1e-3, 10.0), "a": P(0.1, 10.0), "nu": NU}, cost=200,
            target=stress.superposed_stress, note=" (x, z: the field point, for a uniform "
            "pressure on r < a)"),
    ]


def _line_stress_rows() -> list[Row]:
    """Issue 14's line-contact stresses (plane strain) against McEwen's forms (Johnson,
    Contact Mechanics (4.49), in m and n; tests/test_line_stress.py proves them equal to the
    superposed Flamant field) at enough digits for their cancellation far away."""
    XZ = P(1e-300, 1e60, zero=True)  # up to and past the documented max(|x|, z) <= 1e50 b
    note = ", max(|x|, z) <= 1e50 b (a ValueError beyond)"

    def far(p):
        return max(abs(p.get("x", 0.0)), p["z"]) > line_stress.MAX_DISTANCE * p["b"]

    def mcewen(x, z, b, p0):
        """sigma_xx, sigma_zz, tau_xz: -(p0/b) [m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2 z],
        -(p0/b) m (1 - (z^2 + n^2)/(m^2 + n^2)), -(p0/b) n (m^2 - z^2)/(m^2 + n^2) (the
        package's sign: the load pushes +z into the body); m, n >= 0 for x, z >= 0. The far
        field cancels ~2 log10(r/b) digits: raised precision."""
        r = max(abs(x), z) / b
        with mp.workdps(DPS + 10 + int(2 * max(0, mp.log10(r) if r > 0 else 0))):
            x, z, b = mp.mpf(x), mp.mpf(z), mp.mpf(b)
            c = (b - x) * (b + x) + z * z
            root = mp.sqrt(c * c + 4 * x * x * z * z)
            m2 = (root + c) / 2
            n2 = (root - c) / 2 if c <= 0 else 2 * x * x * z * z / (root + c)
            m, n = mp.sqrt(m2), mp.sqrt(n2)
            k = (z * z + n2) / (m2 + n2) if m2 + n2 > 0 else mp.mpf(1)
            sxx = -(p0 / b) * (m * (1 + k) - 2 * z)
            szz = -(p0 / b) * m * (1 - k)
            txz = -(p0 / b) * n * (m2 - z * z) / (m2 + n2) if m2 + n2 > 0 else mp.mpf(0)
            return +sxx, +szz, +txz

    def vm(x, z, b, p0, nu):
        sxx, szz, txz = mcewen(x, z, b, p0)
        with mp.workdps(DPS + 10):
            syy = nu * (sxx + szz)
            return mp.sqrt(((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) / 2
                           + 3 * txz**2)

    def tau1(x, z, b, p0, nu):
        sxx, szz, txz = mcewen(x, z, b, p0)
        with mp.workdps(DPS + 10):
            return mp.sqrt(((sxx - szz) / 2) ** 2 + txz**2)

    field = {"x": XZ, "z": XZ, "b": LEN, "p0": MOD, "nu": NU}
    edge = _edge("x", lambda p: p["b"])
    # an absolute allowance of 1e-7 p0 ~ p0 sqrt(eps), as for the pressures: at the strip's
    # edge x = b (1 +- k eps) the field is ~p0 (k eps)^(1/2), and the rounding of x/b moves
    # it by as much
    tiny = lambda x, z, b, p0, nu: p0 * mp.mpf(1e-7)  # noqa: E731
    rows = [Row(f"line_stress.stresses ({name})", line_stress.stresses, field,
                lambda x, z, b, p0, nu, i=i: mcewen(x, z, b, p0)[i], pick=i, refused=far,
                note=note, near=edge, scale=tiny)
            for i, name in enumerate(("sigma_xx", "sigma_zz", "tau_xz"))]
    rows += [
        Row("line_stress.von_mises", line_stress.von_mises, field, vm, refused=far, note=note,
            near=edge, scale=tiny),
        Row("line_stress.principal_shear (tau_1)", line_stress.principal_shear, field, tau1,
            pick=0, refused=far, note=note, near=edge, scale=tiny),
        Row("line_stress.axis_stresses (sigma_zz)", line_stress.axis_stresses,
            {"z": XZ, "b": LEN, "p0": MOD, "nu": NU},
            lambda z, b, p0, nu: -p0 * b / mp.sqrt(b * b + z * z), pick=1, mono=("z", 1),
            refused=far, note=", z <= 1e50 b (a ValueError beyond)"),
        Row("line_stress.max_von_mises", line_stress.max_von_mises, {"nu": NU}, pick=0,
            near=lambda p: [{"nu": v} for v in (0.0, 0.1, 0.12, 0.25, -1 + 1e-10)], cost=20),
        Row("line_stress.max_shear_3d", line_stress.max_shear_3d, {"nu": NU}, pick=0,
            near=lambda p: [{"nu": v} for v in (0.0, 0.1, 0.2, 0.24, 0.25)], cost=20),
    ]
    return rows


def rows() -> list[Row]:
    out = (_hertz_rows() + _powerlaw_rows() + _cone_rows() + _line_rows() + _bodies_rows()
           + _ellipse_rows() + _stress_rows() + _line_stress_rows())
    modules = {"hertz": hertz, "powerlaw": powerlaw, "cone": cone, "line": line,
               "bodies": bodies, "stress": stress, "line_stress": line_stress}
    for row in out:
        if row.target is None:  # "module.function" or "module.function (component)"
            mod, fn = row.name.split(" ")[0].split(".")
            row.target = getattr(modules[mod], fn)
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=400, help="random points per row")
    parser.add_argument("--record", metavar="JSON", help="write the counts to this file")
    parser.add_argument("--only", help="rows whose name contains this")
    parser.add_argument("--keep", type=int, default=3, help="failures shown per row")
    args = parser.parse_args(argv)
    selected = [r for r in rows() if not args.only or args.only in r.name]
    failures, counts = run(selected, args.points, keep=args.keep)
    for f in failures:
        print(f)
    print(json.dumps(counts))
    if args.record:
        counts["failures"] = len(failures)
        counts["points_per_row"] = args.points
        counts["command"] = ("python tests/domain_search.py --points "
                             f"{args.points} --record {args.record}")
        with open(args.record, "w") as fh:
            json.dump(counts, fh, indent=1, sort_keys=True)
            fh.write("\n")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
