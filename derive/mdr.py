"""The Method of Dimensionality Reduction (5.51)-(5.61) for a symbolic profile f(r).

Every step is the chapter's integral, handed to SymPy as it stands; nothing else is typed in.
The endpoint singularities are taken out by substitution before SymPy sees them:

- (5.52) with r = x t:             g(x) = x * integral_0^1 f'(x t) / sqrt(1 - t^2) dt
- (5.53) with x = r t:             f(r) = (2/pi) * integral_0^1 g(r t) / sqrt(1 - t^2) dt
- (5.57):                          F = 2 E* (d a - integral_0^a g(x) dx)
- (5.59) with q' = -E* g' inside:  p(r) = (E*/pi) * integral_r^a g'(x) / sqrt(x^2 - r^2) dx
- (5.60) outside (r > a):          u(r) = (2/pi) * integral_0^a (d - g(x)) / sqrt(r^2 - x^2) dx
- (5.61):                          q(x) = 2 * integral_x^a r p(r) / sqrt(r^2 - x^2) dr

A user's profile goes through :func:`solve`, which returns an :class:`MDRSolution` holding the
closed forms SymPy found and, for each step it could not do, the unevaluated integral and why:

>>> import sympy as sp
>>> from hertzmdr.derive import mdr
>>> r = sp.Symbol("r", positive=True)
>>> sol = mdr.solve(r**2 / 2, r)           # a sphere of radius 1
>>> sol.g, sol.depth, sol.force
(x**2, a**2, 4*E_star*a**3/3)

The module has no ``relations()``: the generated functions of the MDR live in the families
that use it (:mod:`~hertzmdr.derive.powerlaw`, :mod:`~hertzmdr.derive.worn`).
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from dataclasses import dataclass, field

import sympy as sp

from hertzmdr.derive.symbols import E_star, a, d, symbol
from hertzmdr.derive.symbols import r as r_out

_rp = sp.Symbol("r", positive=True)  # r > 0 while integrating; results are in r_out

x = symbol("x")
t = sp.Symbol("t", positive=True)

__all__ = ["MDRSolution", "solve", "transform", "inverse_transform", "force",
           "pressure", "displacement_outside", "line_load_from_pressure", "x", "t",
           "abel_kernel", "line_load_after_pressure", "profile_after_transform",
           "elliptic_abel_integral", "branch_point_integral"]


class StepTimeout(Exception):
    pass


@contextmanager
def _time_limit(seconds: float | None):
    """Interrupt a SymPy step after ``seconds`` of this process's CPU time (ITIMER_PROF, only in
    the main thread, where signals work). CPU time, not wall time: on a loaded machine a
    wall-clock limit cut SymPy off before it had even returned its unevaluated Integral, so what
    a derivation could do depended on the other processes."""
    if not seconds or threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum, frame):
        raise StepTimeout(f"no closed form within {seconds} s of CPU time")

    old = signal.signal(signal.SIGPROF, handler)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)


def _clean(expr: sp.Expr) -> sp.Expr:
    """Drop SymPy's polar bookkeeping (exp_polar(2 i pi) z is z on the principal branch)."""
    expr = sp.unpolarify(expr.replace(sp.exp_polar, lambda arg: sp.S.One))
    if isinstance(expr, sp.Piecewise):  # the first branch holds under our positivity
        expr = expr.args[0][0]
    return expr


def _integrate(integrand, *limits, seconds=None) -> sp.Expr:
    with _time_limit(seconds):
        res = sp.integrate(integrand, *limits, conds="none")
    return _clean(res)


def transform(f: sp.Expr, r: sp.Symbol, *, seconds=None) -> sp.Expr:
    """g(x) of (5.52) for x > 0, with r = x t taking out the endpoint singularity."""
    fp = sp.diff(f, r).subs(r, x * t)
    return sp.simplify(x * _integrate(fp / sp.sqrt(1 - t**2), (t, 0, 1), seconds=seconds))


def inverse_transform(g: sp.Expr, xs: sp.Symbol = x, *, seconds=None) -> sp.Expr:
    """f(r) of (5.53), with x = r t, as an expression in :data:`r_out`."""
    integrand = g.subs(xs, _rp * t) / sp.sqrt(1 - t**2)
    res = sp.simplify(2 / sp.pi * _integrate(integrand, (t, 0, 1), seconds=seconds))
    return res.subs(_rp, r_out)


def force(g: sp.Expr, *, seconds=None) -> sp.Expr:
    """F_N of (5.57) with d = g(a) (5.55), as a function of the contact radius a."""
    xi = sp.Symbol("xi", positive=True)
    G = _integrate(g.subs(x, xi), (xi, 0, a), seconds=seconds)
    return sp.simplify(2 * E_star * (g.subs(x, a) * a - G))


def pressure(g: sp.Expr, *, seconds=None) -> sp.Expr:
    """p(r) of (5.59) inside the contact (r < a), with q'(x) = -E* g'(x) for x < a."""
    xx = sp.Symbol("xx", positive=True)
    integrand = sp.diff(g, x).subs(x, xx) / sp.sqrt(xx**2 - _rp**2)
    res = sp.simplify(E_star / sp.pi * _integrate(integrand, (xx, _rp, a), seconds=seconds))
    return res.subs(_rp, r_out)


def displacement_outside(g: sp.Expr, *, seconds=None) -> sp.Expr:
    """u_3D(r) of (5.60) for r > a, with d = g(a)."""
    xx = sp.Symbol("xx", positive=True)
    integrand = (g.subs(x, a) - g.subs(x, xx)) / sp.sqrt(_rp**2 - xx**2)
    res = 2 / sp.pi * _integrate(integrand, (xx, 0, a), seconds=seconds)
    return sp.simplify(res).subs(_rp, r_out)


def line_load_from_pressure(p: sp.Expr, *, seconds=None) -> sp.Expr:
    """q(x) of (5.61) for 0 < x < a from a pressure p(r) that vanishes for r > a."""
    integrand = 2 * _rp * p.subs(r_out, _rp) / sp.sqrt(_rp**2 - x**2)
    return sp.simplify(_integrate(integrand, (_rp, x, a), seconds=seconds))


def abel_kernel() -> sp.Expr:
    """K(x, s) = integral_x^s r dr / sqrt((r^2 - x^2)(s^2 - r^2)) for 0 <= x < s.

    The kernel left when two Abel integrals are composed and the order of integration is
    exchanged. With r^2 = x^2 + D v (D = s^2 - x^2), r dr = D dv/2, it is
    (1/2) integral_0^1 dv/sqrt(v (1 - v)): independent of x and s (SymPy: pi/2).
    """
    v, D = sp.symbols("v D", positive=True)
    K = _integrate(sp.simplify((D / 2) / sp.sqrt((D * v) * (D - D * v))), (v, 0, 1))
    if K.free_symbols:
        raise AssertionError(f"the Abel kernel depends on {K.free_symbols}: {K}")
    return K


def line_load_after_pressure(q: sp.Expr, xs: sp.Symbol = x) -> sp.Expr:
    """(5.61) after (5.59) for a line load q(x) on (0, a), symbolically.

    p(r) = -(1/pi) integral_r^a q'(s)/sqrt(s^2 - r^2) ds (5.59) put into (5.61),
    q~(x) = 2 integral_x^a r p(r)/sqrt(r^2 - x^2) dr, with the order exchanged over
    x < r < s < a: q~(x) = -(2/pi) integral_x^a q'(s) K(x, s) ds, K of :func:`abel_kernel`.
    The round trip is the identity when this equals q(x), i.e. when q(a) = 0.
    """
    s = sp.Symbol("s_", positive=True)
    return -2 / sp.pi * _integrate(sp.diff(q, xs).subs(xs, s) * abel_kernel(), (s, xs, a))


def profile_after_transform(f: sp.Expr, r: sp.Symbol) -> sp.Expr:
    """(5.53) after (5.52) for a profile f(r), symbolically.

    g(x) = x integral_0^x f'(u)/sqrt(x^2 - u^2) du (5.52) put into (5.53),
    f~(r) = (2/pi) integral_0^r g(x)/sqrt(r^2 - x^2) dx, with the order exchanged over
    0 < u < x < r: f~(r) = (2/pi) integral_0^r f'(u) K(u, r) du, K of :func:`abel_kernel`.
    The round trip is the identity when this equals f(r), i.e. when f(0) = 0.
    """
    u = sp.Symbol("u_", positive=True)
    return 2 / sp.pi * _integrate(sp.diff(f, r).subs(r, u) * abel_kernel(), (u, 0, r))


def elliptic_abel_integral(A: sp.Expr, B: sp.Expr, L: sp.Expr, S: sp.Expr, upper: sp.Expr,
                           X: sp.Expr | None = None, Q: sp.Expr | None = None) -> sp.Expr:
    """integral_L^upper (A x^2 + B) / sqrt((x^2 - L^2)(x^2 - S^2)) dx for upper > L > S > 0.

    ``X`` = upper^2 - L^2 and ``Q`` = L^2 - S^2 may be passed in a form that keeps precision
    (factored, clipped at 0); the amplitude is phi = atan2(sqrt(X), sqrt(Q)), which is exactly
    pi/2 when S = L (the log-infinite case) and keeps full relative precision as X -> 0.

    The integral of (5.59) (and of (5.52), (5.60)) whenever g' has one extra square-root branch
    point, such as the edge b of a worn tip or a kink of f: its radicand is a cubic in x^2, and
    SymPy's ``integrate`` has no closed form. The substitution
    sin^2(phi) = (x^2 - L^2)/(x^2 - S^2), i.e. x = L Delta/cos(phi) with
    Delta = sqrt(1 - m sin^2(phi)), m = S^2/L^2, turns dx/sqrt(...) into dphi/(L Delta) (checked
    here); the antiderivative is then sought as alpha x sin(phi) + beta E(phi|m) + gamma F(phi|m)
    with Legendre's incomplete integrals F(phi|m) = integral_0^phi dt/Delta and
    E(phi|m) = integral_0^phi Delta dt, and SymPy solves for alpha, beta, gamma by equating the
    derivative with the integrand. The lower limit x = L is phi = 0, where all three vanish.
    """
    Ls, Ss, As, Bs = sp.symbols("L S A B", positive=True)
    ph = sp.Symbol("phi", positive=True)
    s, c, D = sp.symbols("s c Delta", positive=True)
    m = Ss**2 / Ls**2
    Delta = sp.sqrt(1 - m * sp.sin(ph) ** 2)
    x_phi = Ls * Delta / sp.cos(ph)

    def reduce(e):  # a polynomial in (s, c, Delta) modulo c^2 = 1 - s^2, Delta^2 = 1 - m s^2
        e = sp.expand(e.subs({sp.sin(ph): s, sp.cos(ph): c}).subs(sp.sqrt(1 - m * s**2), D))
        e = sp.expand(sp.numer(sp.together(e)))
        for _ in range(3):
            e = sp.expand(e.subs({c**2: 1 - s**2, D**2: 1 - m * s**2}))
        return e

    # the Jacobian, squared to stay rational: (dx/dphi)^2 L^2 Delta^2 = (x^2 - L^2)(x^2 - S^2)
    jac = reduce(sp.together(sp.diff(x_phi, ph) ** 2 * Ls**2 * Delta**2
                             - (x_phi**2 - Ls**2) * (x_phi**2 - Ss**2)))
    if jac != 0:
        raise AssertionError(f"substitution of elliptic_abel_integral is wrong: {jac}")
    al, be, ga = sp.symbols("alpha beta gamma")
    ansatz = al * x_phi * sp.sin(ph) + be * sp.elliptic_e(ph, m) + ga * sp.elliptic_f(ph, m)
    residual = reduce(sp.together(sp.diff(ansatz, ph) - (As * x_phi**2 + Bs) / (Ls * Delta)))
    (coef,) = sp.solve(sp.Poly(residual, s, c, D).coeffs(), [al, be, ga], dict=True)
    X = upper**2 - L**2 if X is None else X
    Q = L**2 - S**2 if Q is None else Q
    sin_u = sp.sqrt(X) / sp.sqrt(X + Q)  # sin^2(phi) = (x^2 - L^2)/(x^2 - S^2) at x = upper
    phi_u = sp.atan2(sp.sqrt(X), sp.sqrt(Q))
    result = (coef[al] * upper * sin_u + coef[be] * sp.elliptic_e(phi_u, m)
              + coef[ga] * sp.elliptic_f(phi_u, m))
    return result.subs({As: A, Bs: B, Ls: L, Ss: S}, simultaneous=True)


def branch_point_integral(A: sp.Expr, B: sp.Expr, r: sp.Symbol, b: sp.Expr,
                          upper: sp.Expr) -> sp.Expr:
    """integral_{max(r, b)}^upper (A x^2 + B)/sqrt((x^2 - b^2)(x^2 - r^2)) dx, 0 for r >= upper.

    The (5.59) integral of a g' with a square-root branch point at b (a kink of f, the edge of
    a worn tip), for r on either side of b: :func:`elliptic_abel_integral` with L = max(r, b),
    S = min(r, b), the differences of squares factored (full precision as r -> upper and
    r -> b) and upper^2 - L^2 clipped at 0.
    """
    L, S = sp.Max(r, b), sp.Min(r, b)
    return elliptic_abel_integral(A, B, L, S, upper, X=sp.Max(0, (upper - L) * (upper + L)),
                                  Q=(L - S) * (L + S))


@dataclass
class MDRSolution:
    """What SymPy could do for the profile f(r); ``missing`` names what it could not.

    Expressions are in x (1-D coordinate), a (contact radius), d (depth), r (radius, inside the
    contact for ``pressure``, outside for ``displacement_outside``) and E_star. A step that
    failed holds the unevaluated integral; ``missing[step]`` says why.
    """

    profile: sp.Expr
    g: sp.Expr | None = None
    depth: sp.Expr | None = None  # d(a) = g(a), (5.55)
    contact_radius: sp.Expr | None = None  # a(d), (5.55) solved for a
    force: sp.Expr | None = None  # F(a), (5.57)
    force_depth: sp.Expr | None = None  # F(d)
    pressure: sp.Expr | None = None  # p(r), r < a, (5.59)
    displacement_outside: sp.Expr | None = None  # u(r), r > a, (5.60)
    missing: dict[str, str] = field(default_factory=dict)

    def closed(self, step: str) -> bool:
        """True if ``step`` (a field name) was done in closed form."""
        return step not in self.missing and getattr(self, step) is not None


def _attempt(sol: MDRSolution, step: str, fn, *args, seconds=None):
    try:
        res = fn(*args, seconds=seconds)
    except StepTimeout as exc:
        sol.missing[step] = str(exc)
        return None
    except (NotImplementedError, ValueError, TypeError) as exc:  # SymPy's ways of giving up
        sol.missing[step] = f"SymPy failed: {type(exc).__name__}: {exc}"
        return None
    if res.has(sp.Integral):
        sol.missing[step] = "SymPy returned the integral unevaluated"
    setattr(sol, step, res)
    return res


def solve(f: sp.Expr, r: sp.Symbol, *, seconds: float | None = 20) -> MDRSolution:
    """Run the MDR on the profile ``f(r)`` (r > 0) as far as SymPy gets in closed form.

    Parameters
    ----------
    f
        The gap profile f(r) [m] (5.52), a SymPy expression, f(0) = 0, increasing.
    r
        Its radial symbol (declare it positive).
    seconds
        Limit of CPU time [s] for each SymPy integral (main thread only); None for no limit.

    Returns
    -------
    MDRSolution
        ``g``, ``depth``, ``contact_radius``, ``force``, ``force_depth``, ``pressure``,
        ``displacement_outside``; ``missing`` maps each step SymPy could not do to the reason.
    """
    f = f.subs(r, _rp)
    sol = MDRSolution(profile=f.subs(_rp, r_out))
    g = _attempt(sol, "g", lambda ff, seconds: transform(ff, _rp, seconds=seconds), f,
                 seconds=seconds)
    if g is None or "g" in sol.missing:
        for step in ("depth", "contact_radius", "force", "force_depth", "pressure",
                     "displacement_outside"):
            sol.missing.setdefault(step, "needs g(x) in closed form")
        return sol
    sol.depth = sp.simplify(g.subs(x, a))  # (5.55)
    try:
        with _time_limit(seconds):
            roots = [s for s in sp.solve(sp.Eq(sol.depth, d), a) if s.is_positive is not False]
    except (StepTimeout, NotImplementedError) as exc:
        roots = []
        sol.missing["contact_radius"] = f"SymPy could not solve g(a) = d: {exc}"
    if len(roots) == 1:
        sol.contact_radius = sp.simplify(roots[0])
    else:
        sol.missing.setdefault("contact_radius",
                               f"g(a) = d has {len(roots)} positive closed-form roots")
    F = _attempt(sol, "force", force, g, seconds=seconds)
    if F is not None and sol.contact_radius is not None and "force" not in sol.missing:
        sol.force_depth = sp.simplify(F.subs(a, sol.contact_radius))
    else:
        sol.missing.setdefault("force_depth", "needs F(a) and a(d) in closed form")
    _attempt(sol, "pressure", pressure, g, seconds=seconds)
    _attempt(sol, "displacement_outside", displacement_outside, g, seconds=seconds)
    return sol
