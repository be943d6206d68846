"""Tangential contact with Coulomb friction by the MDR: Cattaneo-Mindlin for axisymmetric profiles.

Starting point: the normal MDR of :mod:`hertzmdr.derive.mdr` ((5.51)-(5.59)) and the Cerruti
surface displacement of :mod:`hertzmdr.derive.cerruti`. Nothing else is typed in.

The tangential springs. Boussinesq's surface compliance is F/(pi E_i* rho) with E_i* = E/(1 - nu^2)
for each body, and the normal springs of (5.51) have the stiffness E* dx with
1/E* = 1/E_1* + 1/E_2*. The direction average of Cerruti's u_x is Q (2 - nu)/(4 pi G rho)
(:func:`hertzmdr.derive.cerruti.angular_mean_compliance`), i.e. Q/(pi G_i* rho) with
G_i* = 4 G/(2 - nu); the tangential springs have the stiffness G* dx with 1/G* = 1/G_1* + 1/G_2*.
(The remaining cos(2 phi) part of the Cerruti compliance, nu/(4 pi G) cos(2 phi)/rho, is what the
MDR leaves out; ``tests/test_tangential.py`` measures what that costs by putting the MDR
traction through the full Cerruti kernel.)

Coulomb per spring. A spring at x, pressed by the normal line load q_z(x) = E* (d - g(x)) (5.58),
carries the tangential line load q_x = G* w, w its elastic shear; it sticks while
|q_x| < mu q_z and slides with |q_x| = mu q_z otherwise. For a rigid tangential displacement u_x
applied monotonically from 0 at constant normal load every spring has w = u_x until it reaches
mu q_z: the springs with G* u_x < mu E* (d - g(x)) stick, the others slide. The stick radius c is
where the two are equal,

    g(c) = d - G* u_x/(mu E*),

and the tangential force is the spring sum
F_x = 2 [G* u_x c + mu E* integral_c^a (d - g(x)) dx], which SymPy rewrites (asserted below for
every profile) as F_x = mu (F_N(a) - F_N(c)): F_N(c) is the normal force of the same profile at
contact radius c. The traction follows from the line load by (5.59), exactly as the pressure
does from q_z: q(r) = mu (p(r; a) - p(r; c)) inside the stick zone, mu p(r; a) in the slip zone
(the Ciavarella-Jaeger superposition, found, not assumed). The tangential stiffness at u_x -> 0
(c = a, all springs stick) is dF_x/du_x = 2 G* a.

Unloading and Masing. Turned back from the turning point u* by D = u* - u, a spring keeps its
force minus G* D until it reaches -mu q_z. Where it stuck at u* (G* u* <= mu q_z) its force drops
by G* D (it never re-slips while D <= 2 u*: G* u* + mu q_z >= 2 G* u* >= G* D); where it slid
(force mu q_z) it drops by min(G* D, 2 mu q_z). Both are 2 min(G* D/2, mu q_z), twice the force
of the same spring loaded monotonically by D/2 (checked case by case in :func:`masing`):
summed, F_x(u) = F_x(u*) - 2 F_x,mono(D/2). Masing's rule is a consequence, not an assumption.

Energy per cycle. Under u_x oscillating between +-u*, a spring that slides is an
elastic-perfectly-plastic element: its loop is a parallelogram of height 2 mu q_z and width
2 (u* - mu q_z/G*), area 4 mu q_z (u* - mu q_z/G*). The energy per cycle is the sum,
W = 8 mu integral_c^a q_z (u* - mu q_z/G*) dx, c the stick radius at the amplitude: for the
paraboloid it is Mindlin-Deresiewicz's, for the power law its generalization; its leading
term at small amplitude is proportional to F_x*^3.
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from hertzmdr.derive import cerruti, mdr
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import E, E_star, F, R, a, nu, r, symbol, unit_interval

G1, G2 = symbol("G1"), symbol("G2")
nu1, nu2 = symbol("nu1", real=True), symbol("nu2", real=True)
G_star = symbol("G_star")
mu_f = symbol("mu_f")
u_x = symbol("u_x")
F_x = symbol("F_x")
F_amp = symbol("F_amp")
F_half = symbol("F_half")
c = symbol("c")
n = symbol("n")
c_n = symbol("c_n")
kappa_n = symbol("kappa_n")
theta = symbol("theta", positive=True)
r_c = symbol("r_c")
s_r = symbol("s_r")
c_a = symbol("c_a")
d_c = symbol("d_c")
s_x = symbol("s_x")
x = mdr.x
p_a, p_c = symbol("p_a"), symbol("p_c")
t = unit_interval("t")
t_c = unit_interval("t_c")

TEST = "tests/test_tangential.py"
#: the slip depth: a spring at x slides once g(x) > d - s, s = G* u_x/(mu E*)
SLIP_DEPTH = G_star * u_x / (mu_f * E_star)


# ---------------------------------------------------------------- the tangential springs (G*)
@cache
def single_body_modulus() -> sp.Expr:
    """G_i* = 4 G/(2 - nu): Q/(pi rho G_i*) is the direction average of Cerruti's u_x."""
    rho = cerruti.rho
    return sp.simplify(1 / (sp.pi * rho * cerruti.angular_mean_compliance()))


@cache
def effective_modulus() -> sp.Expr:
    """1/G* = 1/G_1* + 1/G_2*: the compliances of the two bodies' springs add, as for E*."""
    one = single_body_modulus()
    g1 = one.subs({cerruti.G: G1, nu: nu1}, simultaneous=True)
    g2 = one.subs({cerruti.G: G2, nu: nu2}, simultaneous=True)
    return sp.simplify(1 / (1 / g1 + 1 / g2))


@cache
def stiffness_ratio() -> sp.Expr:
    """G*/E* of one elastic body (E, nu) against a rigid one, G = E/(2 (1 + nu)).

    E_i* = E/(1 - nu^2) is read off Boussinesq's surface u_z = F/(pi E_i* rho) (5.6).
    """
    from hertzmdr.derive import boussinesq

    uz = boussinesq.relations()[5].derived  # boussinesq_surface_uz, (5.6)
    rho = cerruti.rho
    Ei = sp.simplify(F / (sp.pi * rho * uz.subs({boussinesq.x: rho, boussinesq.y: 0})))
    Gi = single_body_modulus().subs(cerruti.G, E / (2 * (1 + nu)))
    return sp.factor(sp.simplify(Gi / Ei))


# ---------------------------------------------------------------- springs of a profile g(x)
g_x = symbol("g_x")
q_z = symbol("q_z")


@cache
def normal_line_load() -> dict[str, sp.Expr]:
    """q_z = E* (d - g(x)) (5.58): the normal spring at x, of stiffness E* dx (5.51), is
    pressed by d - g(x) once the depth d reaches its gap g(x) (5.55); and the depth that gives
    a spring the line load q_z, d = g + q_z/E*.

    Asserted: the springs' line load summed over -a < x < a at d = g(a) is the normal force
    (5.57) of :func:`hertzmdr.derive.mdr.force`, for the paraboloid and the cone.
    """
    dd = mdr.d
    qz = E_star * (dd - g_x)  # spring stiffness E* per unit length times its compression
    (depth,) = sp.solve(sp.Eq(q_z, qz), dd)
    xi = sp.Symbol("xi", positive=True)
    for g in (x**2 / R, sp.pi / 2 * sp.tan(theta) * x):  # (5.52) of r^2/(2R) and r tan(theta)
        summed = 2 * sp.integrate(qz.subs({g_x: g.subs(x, xi), dd: g.subs(x, a)}), (xi, 0, a))
        assert sp.simplify(summed - mdr.force(g)) == 0, (g, summed)
    return {"q_z": qz, "d": depth}


q_x = symbol("q_x")
w_x = symbol("w_x")


@cache
def tangential_line_load() -> dict[str, sp.Expr]:
    """q_x = G* w: the tangential spring at x, of stiffness G* dx (the direction average of
    the Cerruti compliance, :func:`effective_modulus`), sheared elastically by w; and the
    shear w = q_x/G* that carries the line load q_x (what a sliding spring gives up).

    Asserted: every spring stuck at w = u_x, summed over -a < x < a, is the tangential force
    of :func:`spring_force` at c = a (no slip).
    """
    qx = G_star * w_x
    (shear,) = sp.solve(sp.Eq(q_x, qx), w_x)
    xi = sp.Symbol("xi", positive=True)
    summed = 2 * sp.integrate(qx.subs(w_x, u_x), (xi, 0, a))
    assert sp.expand(summed - spring_force(sp.S.Zero, a)) == 0, summed  # any g: c = a
    return {"q_x": qx, "w": shear}


def spring_force(g: sp.Expr, c_expr: sp.Expr) -> sp.Expr:
    """F_x = 2 [G* u_x c + mu E* integral_c^a (d - g(x)) dx] with d = g(a) (5.55)."""
    xi = sp.Symbol("xi", positive=True)
    slip = mu_f * E_star * sp.integrate(g.subs(x, a) - g.subs(x, xi), (xi, c, a))
    return 2 * (G_star * u_x * c + slip).subs(c, c_expr)


def normal_force_at(g: sp.Expr, radius: sp.Expr) -> sp.Expr:
    """F_N at contact radius ``radius`` (5.57) with d = g(radius) (5.55)."""
    return mdr.force(g).subs(a, radius)


def check_superposition(g: sp.Expr, c_expr: sp.Expr) -> sp.Expr:
    """Assert F_x(springs) = mu (F_N(a) - F_N(c)) and return the latter (Ciavarella-Jaeger)."""
    springs = spring_force(g, c_expr)
    cj = mu_f * (normal_force_at(g, a) - normal_force_at(g, c))
    at_c = {u_x: mu_f * E_star * (g.subs(x, a) - g.subs(x, c)) / G_star}  # g(c) = d - s
    assert sp.simplify((springs.subs(c_expr, c) if c_expr != c else springs).subs(at_c)
                       - cj) == 0, (g, springs, cj)
    return cj


def energy_integral(g: sp.Expr) -> sp.Expr:
    """W = 8 mu integral_c^a q_z (u* - mu q_z/G*) dx with G* u* = mu q_z(c): in (a, c)."""
    xi = sp.Symbol("xi", positive=True)
    qz = E_star * (g.subs(x, a) - g.subs(x, xi))  # (5.58)
    qc = E_star * (g.subs(x, a) - g.subs(x, c))
    return sp.factor(sp.simplify(8 * mu_f**2 / G_star
                                 * sp.integrate(qz * (qc - qz), (xi, c, a))))


def traction_stick(g: sp.Expr) -> sp.Expr:
    """q(r) for r < c: (5.59) of the tangential line load, mu (p(r; a) - p(r; c))."""
    p = mdr.pressure(g)
    return mu_f * (p - p.subs(a, c))


def masing() -> bool:
    """Per spring: force at u* minus force after unloading by D equals 2 f_mono(D/2).

    Checked on both sides of the stick edge at u*, for 0 <= D <= 2 u*, with k, w >= 0 writing
    the inequalities into the symbols: f_mono(v) = min(G v, mu q), the unloaded force
    max(f* - G D, -mu q). Returns True (raises AssertionError otherwise).
    """
    Gs, ustar, k, w, D = sp.symbols("G_s u_s k w D", positive=True)
    # stick at u*: mu q = G u* + k; D = 2 u* - w
    muq = Gs * ustar + k
    Dv = 2 * ustar - w
    f_star = Gs * ustar
    after = f_star - Gs * Dv  # >= -mu q since f* - G D + mu q = G w + k >= 0
    assert sp.simplify(after + muq - (Gs * w + k)) == 0
    half = Gs * Dv / 2  # <= mu q since mu q - G D/2 = k + G w/2 >= 0
    assert sp.simplify(muq - half - (k + Gs * w / 2)) == 0
    assert sp.simplify(f_star - after - 2 * half) == 0
    # slid at u*: f* = mu q, G u* = mu q + k. (i) G D <= 2 mu q: mu q = G D/2 + w
    muq = Gs * D / 2 + w
    assert sp.simplify((muq - Gs * D) + muq - 2 * w) == 0  # no reverse slip: >= -mu q
    assert sp.simplify(muq - (muq - Gs * D) - 2 * (Gs * D / 2)) == 0
    # (ii) G D > 2 mu q: reverse slip, force -mu q; f_mono(D/2) = mu q
    muq = sp.Symbol("q_s", positive=True)
    assert sp.simplify(muq - (-muq) - 2 * muq) == 0
    return True


@cache
def superposition() -> dict[str, sp.Expr]:
    """The tangential tractions in the normal pressures (Ciavarella-Jaeger, found per spring).

    A stuck spring (|x| < c) carries G* u_x = mu E* (d - g(c)), by the stick radius's
    g(c) = d - G* u_x/(mu E*): that is mu (q_z(x; d) - q_z(x; g(c))), the difference of the
    normal line loads (5.58) at the depths d and g(c) (the second 0 for |x| > c). A sliding
    spring carries mu q_z(x; d). (5.59) is linear in the line load, so the traction is
    mu (p(r; a) - p(r; c)) in the stick zone and mu p(r; a) in the slip zone, p(r; c) the
    pressure of the same profile at contact radius c.
    """
    gx, gc, dd = sp.symbols("g_x g_c d_s", positive=True)
    (u_c,) = sp.solve(sp.Eq(gc, dd - SLIP_DEPTH), u_x)
    stuck = G_star * u_c
    assert sp.simplify(stuck - mu_f * (E_star * (dd - gx) - E_star * (gc - gx))) == 0, stuck
    return {"stick": mu_f * (p_a - p_c), "slip": mu_f * p_a}


@cache
def coulomb_limit() -> sp.Expr:
    """mu F: the tangential force once every spring slides (c = 0), asserted to be mu F_N(a)
    for the paraboloid, the cone and the power law (the spring sum against (5.57))."""
    ratios = set()
    for prof in (paraboloid(), cone(), powerlaw()):
        g = prof["g"]
        full = spring_force(g, sp.S.Zero)
        ratios.add(sp.simplify(full / normal_force_at(g, a)))
    (ratio,) = ratios
    assert ratio == mu_f, ratio
    return ratio * F


# ---------------------------------------------------------------- the profiles
@cache
def paraboloid() -> dict[str, sp.Expr]:
    rp = sp.Symbol("r", positive=True)
    f = rp**2 / (2 * R)
    g = mdr.transform(f, rp)  # (5.52): x^2/R
    (c_u,) = [s for s in sp.solve(sp.Eq(g.subs(x, c), g.subs(x, a) - SLIP_DEPTH), c)
              if s.could_extract_minus_sign() is False]
    Fx = sp.simplify(spring_force(g, c_u))
    cj = check_superposition(g, c)
    F_a = normal_force_at(g, a)  # 4 E* a^3/(3 R)
    (c_F,) = [s for s in sp.solve(sp.Eq(cj, F_x), c) if s.is_real is not False
              and s.could_extract_minus_sign() is False]
    u_F = sp.simplify(SLIP_DEPTH.subs(u_x, 1) ** -1 * (g.subs(x, a) - g.subs(x, c_F)))
    W = energy_integral(g)
    return {"f": f.subs(rp, r), "g": g, "c_u": c_u, "F_x": Fx, "F_a": F_a, "c_F": c_F,
            "u_F": u_F, "W": W,
            "q_stick": sp.simplify(traction_stick(g)), "q_slip": mu_f * mdr.pressure(g)}


@cache
def cone() -> dict[str, sp.Expr]:
    rp = sp.Symbol("r", positive=True)
    f = rp * sp.tan(theta)
    g = mdr.transform(f, rp)  # (5.52): (pi/2) tan(theta) x
    (c_u,) = sp.solve(sp.Eq(g.subs(x, c), g.subs(x, a) - SLIP_DEPTH), c)
    Fx = sp.simplify(spring_force(g, c_u))
    cj = check_superposition(g, c)
    (c_F,) = [s for s in sp.solve(sp.Eq(cj, F_x), c) if s.could_extract_minus_sign() is False]
    u_F = sp.simplify((g.subs(x, a) - g.subs(x, c_F)) / SLIP_DEPTH.subs(u_x, 1))
    return {"f": f.subs(rp, r), "g": g, "c_u": c_u, "F_x": Fx, "F_a": normal_force_at(g, a),
            "c_F": c_F,
            "u_F": u_F, "W": energy_integral(g), "q_stick": traction_stick(g)}


@cache
def powerlaw() -> dict[str, sp.Expr]:
    g = kappa_n * c_n * x**n  # (5.52) of c_n r^n (derive/powerlaw.py)
    c_u = a * (1 - SLIP_DEPTH / (kappa_n * c_n * a**n)) ** (1 / n)  # g(c) = d - s
    w = sp.Symbol("w", positive=True)  # 1 - s/g(a) > 0 before sliding
    at_w = {u_x: (1 - w) * mu_f * E_star * kappa_n * c_n * a**n / G_star}
    assert sp.simplify((g.subs(x, c_u) - (g.subs(x, a) - SLIP_DEPTH)).subs(at_w)) == 0
    cj = check_superposition(g, c)
    F_a = sp.simplify(normal_force_at(g, a))  # 2 n E* kappa c_n a^(n+1)/(n + 1)
    # mu (F_N(a) - F_N(c)) with F_N proportional to c^(n+1): c from F_x
    ratio = sp.simplify(normal_force_at(g, c) / F_a)
    assert sp.simplify(ratio - (c / a) ** (n + 1)) == 0, ratio
    c_F = a * (1 - F_x / (mu_f * F_a)) ** (1 / (n + 1))
    assert sp.simplify(cj.subs(c, c_F) - F_x) == 0
    Fx = mu_f * F_a * (1 - (1 - SLIP_DEPTH / (kappa_n * c_n * a**n)) ** ((n + 1) / n))
    assert sp.simplify((Fx - cj.subs(c, c_u)).subs(at_w)) == 0
    u_F = sp.simplify((g.subs(x, a) - g.subs(x, c_F)) / SLIP_DEPTH.subs(u_x, 1))
    # the energy per cycle in the ratio c/a = c_a and F (E* kappa c_n from F_N(a) = F)
    W = energy_integral(g)
    Ekc = sp.solve(sp.Eq(F_a, F), kappa_n)[0] * E_star * c_n
    W = sp.simplify(W.subs(kappa_n, Ekc / (E_star * c_n)).subs(c, c_a * a))
    return {"g": g, "c_u": c_u, "F_x": Fx, "F_a": F_a, "c_F": c_F, "u_F": u_F, "W": W}


@cache
def slide_onset() -> sp.Expr:
    """u_x at which the last spring, the centre x = 0, starts to slide: G* u_x = mu E* d.

    q_z = E* (d - g(x)) is largest at the centre (g(0) = 0, g non-decreasing), so the slip
    depth G* u_x/(mu E*) reaches d there last. Asserted to be where the stick radius of the
    paraboloid, the cone and the power law closes (c = 0 at d = g(a)); the flat punch
    (g = 0 inside) slides all at once at the same u_x.
    """
    (u_on,) = sp.solve(sp.Eq(SLIP_DEPTH, mdr.d), u_x)
    for prof in (paraboloid(), cone()):
        at = {u_x: u_on.subs(mdr.d, prof["g"].subs(x, a))}
        assert sp.simplify(prof["c_u"].subs(at)) == 0, prof["c_u"]
    Pw = powerlaw()
    assert sp.simplify(Pw["c_u"].subs(u_x, u_on.subs(mdr.d, Pw["g"].subs(x, a)))) == 0
    return u_on


#: terms of the power law's stick-zone traction series about the axis, printed; for r <= c/2
#: the terms fall at least 4-fold each, so the part left out is below (4/3) 4^-K of the sum
STICK_CENTRE_TERMS = 28
#: the series is used for r <= STICK_CENTRE_RADIUS c
STICK_CENTRE_RADIUS = sp.Rational(1, 2)


@cache
def powerlaw_traction_stick_centre() -> sp.Expr:
    """mu (p(r; a) - p(r; c)) of g = kappa_n c_n x^n for r <= c/2, finite on the axis for n <= 1.

    For r < c, (5.59) with q' = -E* g' (:func:`hertzmdr.derive.mdr.pressure`) integrates over
    r < x < a and r < x < c: the difference is (E*/pi) integral_c^a g'(x)/sqrt(x^2 - r^2) dx,
    whose integrand has no singularity (x >= c > r). Each pressure is infinite on the axis for
    n <= 1 (its singular (r/a)^(n-1) term, see :func:`hertzmdr.derive.powerlaw.pressure_centre`,
    has the same coefficient d/a^n = kappa_n c_n at a and at c, so it cancels); the difference
    is finite: at r = 0, mu E* n kappa_n c_n (a^(n-1) - c^(n-1))/(pi (n - 1)), for the cone
    (n = 1) mu E* tan(theta)/2 ln(a/c).

    Expanded with (1 - r^2/x^2)^(-1/2) = sum_k (1/2)_k/k! (r/x)^(2k) (uniformly convergent on
    x >= c > r), termwise: integral_c^a x^(m-1) dx = c^m expm1(m ln(a/c))/m, m = n - 1 - 2k.
    For n < 3 every term is positive (no cancellation, none as c -> a either: expm1), and
    decreasing by at least (r/c)^2 each: the first STICK_CENTRE_TERMS are kept.
    """
    m = sp.Symbol("m", nonzero=True)
    xi = sp.Symbol("xi", positive=True)
    # the difference of the two (5.59) integrals for r < c is their integral over (c, a)
    gp = sp.diff(kappa_n * c_n * x**n, x).subs(x, xi)
    assert sp.expand(gp * xi - n * kappa_n * c_n * xi**n) == 0, gp
    # the binomial series of the kernel (1 - s)^(-1/2), s = r^2/x^2: (-1)^k binomial(-1/2, k)
    coef = [sp.rf(sp.Rational(1, 2), j) / sp.factorial(j) for j in range(STICK_CENTRE_TERMS)]
    assert all((-1) ** j * sp.binomial(sp.Rational(-1, 2), j) == coef[j]
               for j in range(STICK_CENTRE_TERMS))
    # termwise: integral_c^a x^(m-1) dx = c^m expm1(m log(a/c))/m (m != 0), log(a/c) as
    # log1p((a - c)/c), which keeps its digits as c -> a (equal at 50 digits at random points;
    # simplify takes half a second for it)
    term = sp.integrate(xi ** (m - 1), (xi, c, a), conds="none")
    assert sp.expand(term * m - (a**m - c**m)) == 0, term
    L = log1p((a - c) / c)
    plain = c**m * (sp.exp(m * sp.log(1 + (a - c) / c)) - 1) / m
    for pt in ({a: 3, c: sp.Rational(1, 7), m: sp.Rational(-9, 4)},
               {a: sp.Rational(5, 4), c: sp.Rational(6, 5), m: sp.Rational(1, 3)}):
        diff = sp.N((term - plain).subs(pt), 50)
        assert abs(diff) < sp.Float(10) ** -45 * abs(sp.N(term.subs(pt), 50)), (pt, diff)
    # r^(2k) c^(n - 1 - 2k) = c^(n-1) r_c^(2k), r_c = r/c <= 1/2; Horner in r_c^2
    z = r_c**2
    total = sp.S.Zero
    for j in reversed(range(STICK_CENTRE_TERMS)):
        mj = n - 1 - 2 * j
        total = coef[j] * expm1(mj * L) / mj + (z * total if j < STICK_CENTRE_TERMS - 1
                                                else 0)
    return mu_f * E_star / sp.pi * n * kappa_n * c_n * c ** (n - 1) * total


@cache
def powerlaw_traction_stick_integrand() -> sp.Expr:
    """The integrand of mu (p(r; a) - p(r; c)) = integral over s of it, s = sqrt(x^2 - r^2)
    from sqrt(c^2 - r^2) to sqrt(a^2 - r^2) (x from c to a in (5.59)): with x^2 = r^2 + s^2,
    dx/sqrt(x^2 - r^2) = ds/x, so mu (E*/pi) g'(x)/x = mu (E*/pi) n kappa_n c_n
    (r^2 + s^2)^((n - 2)/2), smooth on the whole interval even at r = c (no endpoint
    singularity), and its length sqrt(a^2 - r^2) - sqrt(c^2 - r^2) is computed without
    cancellation as c -> a: the stick zone's traction near the edge of a nearly stuck
    contact, where the two pressures cancel."""
    xi = sp.Symbol("xi", positive=True)
    gp = sp.diff(kappa_n * c_n * x**n, x).subs(x, xi)
    xs = sp.sqrt(r**2 + s_r**2)
    dx_ds = sp.diff(xs, s_r)
    out = mu_f * E_star / sp.pi * n * kappa_n * c_n * (r**2 + s_r**2) ** ((n - 2) / 2)
    changed = (mu_f * E_star / sp.pi * gp / sp.sqrt(xi**2 - r**2)).subs(xi, xs) * dx_ds
    assert sp.simplify(sp.powsimp(changed / out, force=True)) == 1, changed
    return out


def flat_punch_traction() -> sp.Expr:
    """(5.59) of the stuck flat punch's line load q_x = G* u_x on |x| < a, 0 outside.

    q_x' = -G* u_x delta(x - a): the Dirac delta at the edge gives the whole integral.
    """
    xx = sp.Symbol("xx", positive=True)
    rp = sp.Symbol("r", positive=True)
    qx_prime = -G_star * u_x * sp.DiracDelta(xx - a)
    tau = -1 / sp.pi * sp.integrate(qx_prime / sp.sqrt(xx**2 - rp**2), (xx, rp, sp.oo))
    tau = sp.simplify(tau.subs(sp.Heaviside(rp - a), 0))  # inside the contact, r < a
    assert not tau.has(sp.Heaviside, sp.Piecewise), tau
    return tau.subs(rp, r)


def small_amplitude(W_of_F: sp.Expr) -> sp.Expr:
    """Leading term of W(F_amp) as F_amp -> 0 (asserted to be the cube)."""
    eps = sp.Symbol("epsilon", positive=True)
    ser = sp.series(W_of_F.subs(F_amp, eps * F_amp), eps, 0, 4).removeO()
    lead = sp.simplify(ser.coeff(eps, 3) * eps**3).subs(eps, 1)
    assert sp.simplify(ser.coeff(eps, 0)) == 0 and sp.simplify(ser.coeff(eps, 1)) == 0
    assert sp.simplify(ser.coeff(eps, 2)) == 0
    return sp.factor(lead)


# ---------------------------------------------------------------- relations
def relations() -> list[Relation]:
    rels = []
    cm = "Cattaneo-Mindlin (not in the chapter)"
    md = "Mindlin-Deresiewicz (not in the chapter)"
    rels.append(Relation(
        "tangential_modulus", "MDR tangential springs (not in the chapter)",
        effective_modulus(), (G1, nu1, G2, nu2),
        "tangential effective modulus G* [Pa] of two elastic bodies",
        "direction average of the Cerruti surface compliance of each body, compliances added",
        f"{TEST}::test_tangential_modulus_from_the_cerruti_compliance",
        stable=1 / ((2 - nu1) / (4 * G1) + (2 - nu2) / (4 * G2)),
        stable_why="a rigid body (G = inf) is G/(2 - nu) -> 0 instead of inf/inf"))
    from hertzmdr.derive import boussinesq

    rels.append(Relation(
        "shear_modulus", "Lame's mu (not in the chapter)", boussinesq.lame()[1], (E, nu),
        "shear modulus G [Pa] of an isotropic body", "Hooke's law in Lame's form",
        f"{TEST}::test_tangential_modulus_from_the_cerruti_compliance"))
    rels.append(Relation(
        "tangential_stiffness_ratio", "MDR tangential springs (not in the chapter)",
        stiffness_ratio(), (nu,),
        "G*/E* [1] = tangential over normal contact stiffness of one elastic body on a rigid one",
        "Cerruti and Boussinesq compliances of the same body, G = E/(2 (1 + nu))",
        f"{TEST}::test_tangential_modulus_from_the_cerruti_compliance"))
    rels.append(Relation(
        "tangential_stiffness", "MDR tangential springs (not in the chapter)",
        sp.simplify(sp.diff(spring_force(x**2 / R, a), u_x)), (G_star, a),
        "tangential contact stiffness k_x = dF_x/du_x [N/m] before any slip (c = a)",
        "sum of the 2a/dx stuck springs of stiffness G* dx",
        f"{TEST}::test_initial_stiffness_is_2_G_star_a_for_every_profile"))
    rels.append(Relation(
        "masing_unloading_force", "Masing's rule, derived from the springs",
        F_amp - 2 * F_half if masing() else sp.nan, (F_amp, F_half),
        "tangential force F_x [N] on the branch from a turning point: F_x* - 2 F_x,mono(D/2)",
        "per spring, unloaded by D from u*: f* - f = 2 min(G* D/2, mu q_z) (case check)",
        f"{TEST}::test_history_solver_follows_masing"))

    # paraboloid: Cattaneo-Mindlin, Mindlin-Deresiewicz
    P = paraboloid()
    dom_u = {u_x: t * mu_f * E_star * a**2 / (R * G_star)}  # 0 < u_x < sliding onset
    cu = P["c_u"]
    rels.append(Relation(
        "cattaneo_stick_radius", cm, cu, (a, R, E_star, G_star, mu_f, u_x),
        "stick radius c [m] of a paraboloid (f = r^2/(2R)) displaced by u_x at constant load",
        "g(c) = d - G* u_x/(mu E*), g = x^2/R", f"{TEST}::test_cattaneo_mindlin_literature",
        domain=dom_u))
    cc = sp.Symbol("cc", positive=True)
    stable_F = (sp.Rational(4, 3) * G_star * u_x * (a**2 + a * cc + cc**2) / (a + cc)).subs(cc, cu)
    rels.append(Relation(
        "cattaneo_force", cm, P["F_x"], (a, R, E_star, G_star, mu_f, u_x),
        "tangential force F_x [N] of a paraboloid displaced by u_x (monotonic, constant load)",
        "sum of the stuck and sliding springs", f"{TEST}::test_cattaneo_mindlin_literature",
        stable=stable_F, domain=dom_u,
        stable_why="mu (F_N(a) - F_N(c)) cancels as u_x -> 0; a^3 - c^3 = (a^2 - c^2)(a^2 + a c "
                   "+ c^2)/(a + c) with a^2 - c^2 = R G* u_x/(mu E*) exactly"))
    # u_x(F_x) with R/E* = 4 a^3/(3 F): in the normal force, as Mindlin writes it
    u_F = sp.simplify(P["u_F"].subs(R, 4 * E_star * a**3 / (3 * F)))
    rels.append(Relation(
        "cattaneo_displacement", cm, u_F, (a, F, G_star, mu_f, F_x),
        "tangential displacement u_x [m] of a paraboloid under normal force F and tangential "
        "force F_x", "F_x = mu (F_N(a) - F_N(c)) solved for c, then g(c) = d - G* u_x/(mu E*)",
        f"{TEST}::test_cattaneo_mindlin_literature", domain={F_x: t * mu_f * F},
        stable=-3 * mu_f * F / (4 * a * G_star)
        * expm1(sp.Rational(2, 3) * log1p(-F_x / (mu_f * F))),
        stable_why="1 - (1 - F_x/(mu F))^(2/3) cancels as F_x -> 0: "
                   "-expm1(2/3 log1p(-F_x/(mu F)))"))
    rels.append(Relation(
        "cattaneo_stick_radius_from_force", cm,
        sp.simplify(P["c_F"].subs(R, 4 * E_star * a**3 / (3 * F))), (a, F, mu_f, F_x),
        "stick radius c [m] of a paraboloid under the normal force F and tangential force F_x",
        "F_x = mu (F_N(a) - F_N(c)), F_N ~ c^3", f"{TEST}::test_cattaneo_mindlin_literature",
        domain={F_x: t * mu_f * F}))
    dom_r = {c: a * t_c, r: a * t_c * t}
    qs = P["q_stick"]
    rels.append(Relation(
        "cattaneo_traction_stick", cm, qs, (r, a, c, R, E_star, mu_f),
        "tangential traction q(r) [Pa] in the stick zone r < c of a paraboloid",
        "(5.59) of the tangential line load: mu (p(r; a) - p(r; c))",
        f"{TEST}::test_traction_through_cerruti_is_rigid_in_the_stick_zone", domain=dom_r,
        stable=2 * mu_f * E_star / (sp.pi * R) * (a - c) * (a + c)
        / (sp.sqrt((a - r) * (a + r)) + sp.sqrt((c - r) * (c + r))),
        stable_why="the difference of the two square roots cancels as c -> a"))
    rels.append(Relation(
        "cattaneo_traction_slip", cm, P["q_slip"], (r, a, R, E_star, mu_f),
        "tangential traction q(r) [Pa] in the slip zone c < r < a of a paraboloid (mu p(r))",
        "(5.59) of the sliding springs' line load mu E* (d - g)",
        f"{TEST}::test_traction_through_cerruti_is_rigid_in_the_stick_zone",
        domain={r: a * t}))
    # Mindlin-Deresiewicz: W(F_amp); c = a (1 - F_amp/(mu F))^(1/3), E*/R = 3 F/(4 a^3)
    W_c = P["W"].subs(R, 4 * E_star * a**3 / (3 * F))
    cF = a * (1 - F_amp / (mu_f * F)) ** sp.Rational(1, 3)
    W_F = sp.simplify(W_c.subs(c, cF))
    L = log1p(-F_amp / (mu_f * F)) / 3
    one_minus = -expm1(L)  # 1 - c/a
    tt = sp.Symbol("tt", positive=True)
    poly = sp.factor(sp.simplify(W_c.subs(c, a * tt)))
    # the integrand of W vanishes to second order at c = a: W ~ (1 - c/a)^3 P(c/a)
    q, rem = sp.div(sp.numer(sp.together(poly)), (1 - tt) ** 3, tt)
    assert rem == 0, rem
    W_stable = (q / sp.denom(sp.together(poly))).subs(tt, sp.exp(L)) * one_minus**3
    rels.append(Relation(
        "mindlin_energy", md, W_F, (a, F, G_star, mu_f, F_amp),
        "energy W [J] dissipated per cycle of a tangential force oscillating with amplitude "
        "F_amp at constant normal force F (paraboloid)",
        "sum of the sliding springs' parallelogram loops 4 mu q_z (u* - mu q_z/G*)",
        f"{TEST}::test_mindlin_deresiewicz_energy", domain={F_amp: t * mu_f * F},
        stable=W_stable,
        stable_why="the integrand vanishes to second order at the edge: (1 - c/a)^3 P(c/a) "
                   "with 1 - c/a = -expm1(log1p(-F_amp/(mu F))/3) keeps the cubic law to "
                   "rounding"))
    rels.append(Relation(
        "mindlin_energy_small", md, small_amplitude(W_F), (a, F, G_star, mu_f, F_amp),
        "leading term [J] of the energy per cycle of a paraboloid at small amplitude F_amp",
        "series of mindlin_energy in F_amp", f"{TEST}::test_cubic_small_amplitude_law"))

    # cone
    C = cone()
    dom_uc = {u_x: t * mu_f * E_star * a * sp.pi * sp.tan(theta) / (2 * G_star)}
    rels.append(Relation(
        "tangential_cone_stick_radius", "MDR tangential, cone (not in the chapter)", C["c_u"],
        (a, theta, E_star, G_star, mu_f, u_x),
        "stick radius c [m] of a cone (angle theta to the plane) displaced by u_x",
        "g(c) = d - G* u_x/(mu E*), g = (pi/2) tan(theta) x",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature", domain=dom_uc))
    rels.append(Relation(
        "tangential_cone_force", "MDR tangential, cone (not in the chapter)", C["F_x"],
        (a, theta, E_star, G_star, mu_f, u_x),
        "tangential force F_x [N] of a cone displaced by u_x (monotonic, constant load)",
        "sum of the stuck and sliding springs",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature", domain=dom_uc))
    u_Fc = sp.simplify(C["u_F"].subs(theta, sp.atan(2 * F / (sp.pi * E_star * a**2))))
    xF = F_x / (mu_f * F)
    rels.append(Relation(
        "tangential_cone_displacement", "MDR tangential, cone (not in the chapter)", u_Fc,
        (a, F, G_star, mu_f, F_x),
        "tangential displacement u_x [m] of a cone under normal force F and tangential F_x",
        "F_x = mu (F_N(a) - F_N(c)), F_N ~ c^2, then g(c) = d - G* u_x/(mu E*)",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature",
        domain={F_x: t * mu_f * F},
        stable=F_x / (a * G_star * (1 + sp.sqrt(1 - xF))),
        stable_why="1 - sqrt(1 - F_x/(mu F)) cancels as F_x -> 0"))
    Wc = C["W"].subs(theta, sp.atan(2 * F / (sp.pi * E_star * a**2)))
    Wc_F = sp.simplify(Wc.subs(c, a * sp.sqrt(1 - F_amp / (mu_f * F))))
    xA = F_amp / (mu_f * F)
    rels.append(Relation(
        "tangential_cone_energy", "MDR tangential, cone (not in the chapter)", Wc_F,
        (a, F, G_star, mu_f, F_amp),
        "energy W [J] dissipated per cycle by a cone under normal force F, amplitude F_amp",
        "sum of the sliding springs' parallelogram loops",
        f"{TEST}::test_loop_area_equals_the_energy", domain={F_amp: t * mu_f * F},
        stable=sp.Rational(4, 3) * mu_f**2 * F**2 * a**3 * (xA / (1 + sp.sqrt(1 - xA)))**3
        / (a**4 * G_star),
        stable_why="a - c = a x/(1 + sqrt(1 - x)), x = F_amp/(mu F), instead of "
                   "a (1 - sqrt(1 - x))"))

    # the tractions: Coulomb's limit and the stick superposition for every profile, and the
    # cone's stick-zone traction in a form that is finite on the axis
    S = superposition()
    rels.append(Relation(
        "coulomb_sliding_force", "Coulomb's law, from the springs (not in the chapter)",
        coulomb_limit(), (mu_f, F),
        "tangential force mu F [N] of full sliding under the normal force F (Coulomb's limit)",
        "the spring sum at c = 0 over the normal force (5.57)",
        f"{TEST}::test_sliding_force_is_the_spring_sum_at_full_slip"))
    rels.append(Relation(
        "tangential_traction_slip", "MDR tangential (Ciavarella-Jaeger, found)", S["slip"],
        (mu_f, p_a),
        "tangential traction q [Pa] in the slip zone: mu p(r; a) of the pressure p_a [Pa]",
        "(5.59) of the sliding springs' line load mu q_z",
        f"{TEST}::test_traction_against_the_line_load_quadrature"))
    rels.append(Relation(
        "tangential_traction_stick", "MDR tangential (Ciavarella-Jaeger, found)", S["stick"],
        (mu_f, p_a, p_c),
        "tangential traction q [Pa] in the stick zone r < c: mu (p(r; a) - p(r; c)) of the "
        "pressures p_a, p_c [Pa] of the profile at contact radii a and c",
        "(5.59) of the stuck springs' line load mu (q_z(x; a) - q_z(x; c))",
        f"{TEST}::test_traction_against_the_line_load_quadrature"))
    ra, rc = sp.sqrt((a - r) * (a + r)), sp.sqrt((c - r) * (c + r))
    rels.append(Relation(
        "tangential_cone_traction_stick", "MDR tangential, cone (not in the chapter)",
        C["q_stick"], (r, a, c, theta, E_star, mu_f),
        "tangential traction q(r) [Pa] in the stick zone r < c of a cone, finite on the axis: "
        "mu E* tan(theta)/2 ln(a/c) at r = 0",
        "(5.59) of the tangential line load: mu (p(r; a) - p(r; c))",
        f"{TEST}::test_cone_traction_on_and_near_the_axis", domain=dom_r,
        stable=mu_f * E_star * sp.tan(theta) / 2
        * log1p((a - c) * (1 + (a + c) / (ra + rc)) / (c + rc)),
        stable_why="the two pressures are each log-infinite on the axis (inf - inf = NaN at "
                   "r = 0); as one logarithm of (a + sqrt(a^2 - r^2))/(c + sqrt(c^2 - r^2)), "
                   "written log1p of its excess over 1, it is finite at r = 0 and keeps its "
                   "digits as c -> a"))

    # power law
    Pw = powerlaw()
    dom_up = {u_x: t * mu_f * E_star * kappa_n * c_n * a**n / G_star}
    q_over = SLIP_DEPTH / (kappa_n * c_n * a**n)
    rels.append(Relation(
        "tangential_powerlaw_stick_radius", "MDR tangential, power law (not in the chapter)",
        Pw["c_u"], (a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x),
        "stick radius c [m] of a power-law profile f = c_n r^n displaced by u_x",
        "g(c) = d - G* u_x/(mu E*), g = kappa_n c_n x^n",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature", domain=dom_up,
        stable=a * sp.exp(log1p(-q_over) / n),
        stable_why="(1 - q)^(1/n) as exp(log1p(-q)/n): accurate for large n and tiny q"))
    rels.append(Relation(
        "tangential_powerlaw_force", "MDR tangential, power law (not in the chapter)",
        Pw["F_x"], (a, c_n, n, kappa_n, E_star, G_star, mu_f, u_x),
        "tangential force F_x [N] of a power-law profile displaced by u_x",
        "mu (F_N(a) - F_N(c)), asserted equal to the spring sum",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature", domain=dom_up,
        stable=-mu_f * Pw["F_a"] * expm1((n + 1) / n * log1p(-q_over)),
        stable_why="1 - (c/a)^(n+1) cancels as u_x -> 0: -expm1((n+1)/n log1p(-q))"))
    rels.append(Relation(
        "tangential_powerlaw_traction_stick_centre",
        "MDR tangential, power law (not in the chapter), (5.59)",
        powerlaw_traction_stick_centre(), (r_c, a, c, c_n, n, kappa_n, E_star, mu_f),
        "tangential traction q(r) [Pa] in the stick zone of a power-law profile near the axis, "
        f"r = r_c c <= c/2, 0 < n < 3, n != 1 (the cone): finite on the axis, where each of "
        "the two pressures of mu (p(r; a) - p(r; c)) is infinite for n <= 1; the series to "
        f"r_c^{2 * STICK_CENTRE_TERMS - 2}, the rest below (4/3) 4^-{STICK_CENTRE_TERMS} of it",
        "(5.59) of the stuck springs' line load: (E*/pi) integral_c^a g'(x)/sqrt(x^2 - r^2) "
        "dx, its kernel expanded in (r/x)^2 and integrated termwise",
        f"{TEST}::test_powerlaw_traction_on_and_near_the_axis",
        domain={r_c: t / 2, c: a * t_c}))
    rels.append(Relation(
        "tangential_powerlaw_traction_stick_integrand",
        "MDR tangential, power law (not in the chapter), (5.59)",
        powerlaw_traction_stick_integrand(), (r, s_r, c_n, n, kappa_n, E_star, mu_f),
        "integrand [Pa/m] of the stick-zone traction of a power-law profile in "
        "s = sqrt(x^2 - r^2): q(r) = its integral from sqrt(c^2 - r^2) to sqrt(a^2 - r^2), "
        "smooth there for every r < c",
        "(5.59) of the stuck springs' line load over c < x < a with x^2 = r^2 + s^2",
        f"{TEST}::test_powerlaw_traction_on_and_near_the_axis"))
    xFp = F_x / (mu_f * F)
    rels.append(Relation(
        "tangential_powerlaw_stick_radius_from_force",
        "MDR tangential, power law (not in the chapter)",
        sp.simplify(Pw["c_F"].subs(kappa_n, sp.solve(sp.Eq(Pw["F_a"], F), kappa_n)[0])),
        (a, n, F, mu_f, F_x),
        "stick radius c [m] of a power-law profile under normal force F and tangential F_x",
        "F_x = mu (F_N(a) - F_N(c)), F_N ~ c^(n+1)",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature",
        domain={F_x: t * mu_f * F}))
    # u_x = (mu E*/G*) (g(a) - g(c)) with c/a = (1 - F_x/(mu F))^(1/(n+1))
    kap = sp.solve(sp.Eq(Pw["F_a"], F), kappa_n)[0]
    cF_a = (1 - F_x / (mu_f * F)) ** (1 / (n + 1))
    assert sp.simplify(Pw["c_F"].subs(kappa_n, kap) - a * cF_a) == 0
    u_Fp = sp.factor(sp.simplify(
        (mu_f * E_star / G_star * kappa_n * c_n * a**n).subs(kappa_n, kap))) * (
        1 - sp.powsimp(cF_a**n, force=True))
    rels.append(Relation(
        "tangential_powerlaw_displacement", "MDR tangential, power law (not in the chapter)",
        u_Fp, (a, n, F, G_star, mu_f, F_x),
        "tangential displacement u_x [m] of a power-law profile under normal force F and "
        "tangential force F_x", "c from F_x, then g(c) = d - G* u_x/(mu E*)",
        f"{TEST}::test_closed_forms_against_the_spring_quadrature",
        domain={F_x: t * mu_f * F},
        stable=-mu_f * F * (n + 1) / (2 * n * a * G_star)
        * expm1(n / (n + 1) * log1p(-xFp)),
        stable_why="1 - (1 - F_x/(mu F))^(n/(n+1)) cancels as F_x -> 0"))
    rels.append(Relation(
        "tangential_powerlaw_energy", "MDR tangential, power law (not in the chapter)",
        Pw["W"], (a, n, F, G_star, mu_f, c_a),
        "energy W [J] dissipated per cycle by a power-law profile under normal force F whose "
        "stick zone at the amplitude has the radius c = c_a a (cancels for c_a -> 1: "
        "numeric/tangential.py integrates the density there)",
        "sum of the sliding springs' parallelogram loops",
        f"{TEST}::test_loop_area_equals_the_energy", domain={c_a: t}))
    # the density of the energy per cycle over the slip zone, x = c + (a - c) s_x, in
    # d_c = 1 - c/a: each factor keeps full precision however thin the slip zone
    # (1 - x^n)(x^n - c^n) with x = 1 - d_c (1 - s_x), c = 1 - d_c, each factor as expm1 of
    # the logarithm of a ratio near 1 (asserted equal to the product at 50 digits)
    xs_, cs_ = 1 - d_c * (1 - s_x), 1 - d_c
    dens = (-expm1(n * log1p(-d_c * (1 - s_x))) * cs_**n
            * expm1(n * log1p(d_c * s_x / (1 - d_c))))
    plain = (1 - xs_**n) * (xs_**n - cs_**n)
    at = {n: sp.Rational(5, 2), d_c: sp.Rational(1, 1000), s_x: sp.Rational(3, 7)}
    assert abs(sp.N((dens - plain).subs(at), 50)) < 1e-45 * abs(sp.N(plain.subs(at), 50))
    J = sp.integrate(((1 - x**n) * (x**n - c_a**n)), (x, c_a, 1))
    scale = sp.factor(sp.simplify(Pw["W"] / J))
    assert not scale.has(c_a), scale
    rels.append(Relation(
        "tangential_powerlaw_energy_scale", "MDR tangential, power law (not in the chapter)",
        scale, (a, n, F, G_star, mu_f),
        "energy per cycle [J] of a power-law profile per unit of d_c times the integral of "
        "tangential_powerlaw_energy_density over 0 < s_x < 1",
        "the sliding springs' loops with x = a (1 - d_c (1 - s_x)), q_z ~ a^n - x^n",
        f"{TEST}::test_loop_area_equals_the_energy"))
    rels.append(Relation(
        "tangential_powerlaw_energy_density", "MDR tangential, power law (not in the chapter)",
        dens, (n, d_c, s_x),
        "dimensionless loop energy density (1 - x^n)(x^n - c^n) of a sliding spring at "
        "x/a = 1 - d_c (1 - s_x), c/a = 1 - d_c",
        "q_z (u* - mu q_z/G*) with q_z ~ a^n - x^n; 1 - x^n and x^n - c^n as expm1 of "
        "log1p of the offsets, which keeps them exact in a thin slip zone",
        f"{TEST}::test_loop_area_equals_the_energy", domain={d_c: t_c, s_x: t}))
    cF_pl = (1 - F_amp / (mu_f * F)) ** (1 / (n + 1))
    rels.append(Relation(
        "tangential_powerlaw_stick_deficit", "MDR tangential, power law (not in the chapter)",
        1 - cF_pl, (n, F, mu_f, F_amp),
        "1 - c/a [1] of a power-law profile under normal force F and tangential force F_amp",
        "F_x = mu (F_N(a) - F_N(c)), F_N ~ c^(n+1)",
        f"{TEST}::test_loop_area_equals_the_energy", domain={F_amp: t * mu_f * F},
        stable=-expm1(log1p(-F_amp / (mu_f * F)) / (n + 1)),
        stable_why="1 - (1 - F_amp/(mu F))^(1/(n+1)) cancels at small amplitude"))
    Wp_F = Pw["W"].subs(c_a, (1 - F_amp / (mu_f * F)) ** (1 / (n + 1)))
    rels.append(Relation(
        "tangential_powerlaw_energy_small", "MDR tangential, power law (not in the chapter)",
        small_amplitude(Wp_F), (a, n, F, G_star, mu_f, F_amp),
        "leading term [J] of the energy per cycle of a power-law profile at small amplitude",
        "series in F_amp of the energy per cycle", f"{TEST}::test_cubic_small_amplitude_law"))

    # the springs' normal line load and its inverse, for the history solver
    N = normal_line_load()
    rels.append(Relation(
        "mdr_normal_line_load", "(5.58)", N["q_z"], (E_star, mdr.d, g_x),
        "normal line load q_z [N/m] of the MDR spring at x with gap g(x) at depth d (in "
        "contact for d > g(x); pass g(x) capped at d for the springs out of contact)",
        "the spring stiffness E* per unit length (5.51) times its compression d - g(x) (5.55)",
        f"{TEST}::test_normal_line_load_against_the_normal_force"))
    rels.append(Relation(
        "mdr_depth_of_line_load", "(5.58), inverted", N["d"], (E_star, g_x, q_z),
        "depth d [m] at which the MDR spring with gap g(x) carries the line load q_z",
        "q_z = E* (d - g(x)) solved for d",
        f"{TEST}::test_normal_line_load_against_the_normal_force"))

    T = tangential_line_load()
    rels.append(Relation(
        "mdr_tangential_line_load", "MDR tangential springs (not in the chapter)", T["q_x"],
        (G_star, w_x),
        "tangential line load q_x [N/m] of the MDR spring sheared elastically by w",
        "the tangential spring stiffness G* per unit length times its shear w",
        f"{TEST}::test_tangential_line_load_against_the_stiffness"))
    rels.append(Relation(
        "mdr_tangential_spring_shear", "MDR tangential springs (not in the chapter)", T["w"],
        (G_star, q_x),
        "elastic shear w [m] of the MDR spring that carries the tangential line load q_x "
        "(the slip that a spring's excess over Coulomb's limit gives up)",
        "q_x = G* w solved for w",
        f"{TEST}::test_tangential_line_load_against_the_stiffness"))

    # the profiles' g(x) (5.52) and the onset of sliding, for numeric/tangential.py
    for name, prof, args, what in (("paraboloid_profile", P, (R, r), "paraboloid"),
                                   ("cone_profile", C, (theta, r), "cone")):
        rels.append(Relation(
            name, "(5.52)", prof["f"], args,
            f"height f(r) [m] of the {what} above its tip (the profile whose g is {what}_g)",
            "the profile put through (5.52)",
            f"{TEST}::test_profiles_against_their_g_by_5_53"))
    rels.append(Relation(
        "paraboloid_g", "(5.52) of f = r^2/(2R)", P["g"], (R, x),
        "MDR profile g(x) [m] of the paraboloid f = r^2/(2R) (the springs' gap; d = g(a))",
        "(5.52) of r^2/(2R)", f"{TEST}::test_profiles_g_against_the_mdr_transform"))
    rels.append(Relation(
        "cone_g", "(5.52) of f = r tan(theta)", C["g"], (theta, x),
        "MDR profile g(x) [m] of the cone f = r tan(theta), x >= 0 (g is even in x)",
        "(5.52) of r tan(theta)", f"{TEST}::test_profiles_g_against_the_mdr_transform"))
    rels.append(Relation(
        "tangential_slide_onset", "MDR tangential springs (not in the chapter)",
        slide_onset(), (E_star, G_star, mu_f, mdr.d),
        "tangential displacement u_x [m] at which the last spring (the centre, g(0) = 0) "
        "starts to slide, depth d (d = g(a), or the flat punch's depth)",
        "G* u_x = mu q_z(0) = mu E* d, where the stick radius closes (asserted per profile)",
        f"{TEST}::test_slide_onset_against_the_normal_force"))

    # flat punch: q_z = E* d on |x| < a, all springs stick until F_x = mu F_N
    rels.append(Relation(
        "flat_punch_tangential_traction", "MDR tangential, flat punch (not in the chapter)",
        flat_punch_traction(),
        (r, a, G_star, u_x),
        "tangential traction q(r) [Pa] of a stuck flat punch (all springs stick, u_x < mu d "
        "E*/G*)", "(5.59) of q_x = G* u_x on |x| < a: the jump at a is a delta in q_x'",
        f"{TEST}::test_traction_through_cerruti_is_rigid_in_the_stick_zone",
        domain={r: a * t}))
    return rels
