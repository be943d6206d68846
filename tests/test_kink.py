"""The branch-point pressure of a kink (derive/kink.py) by independent routes.

Reference: (5.59) of the singular part b s/sqrt(x^2 - b^2) of g', by mpmath quadrature at 30
digits with the substitution x = max(r, b) + u^2, which removes the 1/sqrt at the lower end; the
strength b s of the branch point is checked against g' of (5.52) evaluated by quadrature.
"""

import mpmath as mp

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp

from oracle import assert_close

E, A, B = 2e9, 1e-3, 4e-4  # Pa, m, m


def p_ref(rho, a, b, s, E_star):
    """(E*/pi) integral_{max(rho, b)}^a b s / sqrt((x^2 - b^2)(x^2 - rho^2)) dx."""
    lo, other = (b, rho) if rho < b else (rho, b)

    def integrand(u):  # x = lo + u^2, dx/sqrt(x - lo) = 2 du
        xx = lo + u * u
        return 2 * b * s / (mp.sqrt(xx + lo) * mp.sqrt((xx - other) * (xx + other)))

    return E_star / mp.pi * mp.quad(integrand, [0, mp.sqrt(a - lo)])


def test_kink_strength_from_52():
    """sqrt(x^2 - b^2) g'(x) -> b s as x -> b, with g' of f = s (r - b) from (5.52) by
    quadrature: g(x) = x integral_b^x s/sqrt(x^2 - r^2) dr, differentiated numerically."""
    s = mp.mpf("0.3")
    with mp.workdps(40):
        b = mp.mpf(B)

        def g_of(xx):  # r = x sin(theta): g = x s (pi/2 - asin(b/x)), here by quadrature
            return xx * mp.quad(lambda th: s, [mp.asin(b / xx), mp.pi / 2])

        for eps in (mp.mpf("1e-12"), mp.mpf("1e-16")):
            xx = b * (1 + eps)
            strength = mp.sqrt(xx**2 - b**2) * mp.diff(g_of, xx)
            # the continuous part s acos(b/x) sqrt(x^2 - b^2) = O(eps) relative
            assert abs(strength / (b * s) - 1) < 10 * eps


def test_kink_gprime_is_the_singular_part_of_52():
    """g' of (5.52) for f = s (r - b), by quadrature and numerical differentiation at 40
    digits, minus mdr_kink_gprime is the continuous rest s acos(b/x) -> 0 as x -> b: at
    x = b (1 + e) it is s sqrt(2 e) while g' itself is s/sqrt(2 e)."""
    s = 0.3
    with mp.workdps(40):
        b = mp.mpf(B)

        def g_of(xx):  # (5.52) with r = x sin(theta): x integral s dtheta over r > b
            return xx * mp.quad(lambda th: s, [mp.asin(b / xx), mp.pi / 2])

        for e in ("1e-12", "1e-6", "0.5"):
            x_f = float(b * (1 + mp.mpf(e)))  # the same float x on both sides
            rest = mp.diff(g_of, mp.mpf(x_f)) - mp.mpf(gen.mdr_kink_gprime(B, s, x_f))
            # bound: the continuous part s acos(b/x) <= s sqrt(2e) (1 + e), plus the float64
            # rounding of the generated term (s/sqrt(2e) times 1e-15)
            e_ = float(e)
            assert abs(rest) <= s * (2 * e_) ** 0.5 * (1 + e_) + 1e-15 * s / (2 * e_) ** 0.5


def test_kink_g_by_quadrature():
    """mdr_kink_g against integral_b^x b s/sqrt(t^2 - b^2) dt by 30-digit quadrature (t = b +
    u^2 removes the 1/sqrt): a few ulp of the float64 evaluation."""
    s = -0.7
    for ratio in (1 + 1e-10, 1.001, 2.0, 1e3):
        xx = B * ratio
        with mp.workdps(30):
            bm = mp.mpf(B)
            ref = mp.quad(lambda u, bm=bm: 2 * bm * s / mp.sqrt(2 * bm + u * u),
                          [0, mp.sqrt(mp.mpf(xx) - bm)])
        assert_close(gen.mdr_kink_g(B, s, xx), ref, 1e-14, f"x/b = {ratio}")


def test_kink_pressure_by_quadrature():
    """float64 within a few ulp times the conditioning of F(phi|m) as m -> 1 (as in
    tests/test_worn.py); the mpmath form within 1e-25 of the 30-digit quadrature."""
    s = 0.25
    for t in (0.0, 0.2, 0.399, 0.4 - 1e-8, 0.4 + 1e-8, 0.5, 0.9, 0.999):
        rho = t * A  # radii in (0, a); the kink is at t = B/A = 0.4
        with mp.workdps(30):
            args = [mp.mpf(v) for v in (E, A, B, rho, s)]
            ref = p_ref(args[3], args[1], args[2], args[4], args[0])
            assert abs(gen_mp.mdr_kink_pressure(*args) / ref - 1) < 1e-25, t
        L, S = max(rho, B), min(rho, B)
        tol = 8 * 2.2e-16 * (1 + L**2 / ((L - S) * (L + S)) + A / (A - rho))
        assert_close(gen.mdr_kink_pressure(E, A, B, rho, s), ref, tol, f"p({rho})")
    assert gen.mdr_kink_pressure(E, A, B, B, s) == float("inf")
    assert gen.mdr_kink_pressure(E, A, B, 2 * A, s) == 0.0


def test_worn_pressure_contains_the_kink_term():
    """The worn paraboloid's f' jumps by b/R at b: its pressure minus the kink term is finite at
    r = b and continuous there (the log singularities cancel)."""
    R = 0.05
    near = [B * (1 - 1e-9), B * (1 + 1e-9)]
    rest = [gen.worn_pressure(E, R, A, B, rr) - gen.mdr_kink_pressure(E, A, B, rr, B / R)
            for rr in near]
    assert abs(rest[0] - rest[1]) < 1e-6 * abs(rest[0])


def test_kink_G_by_quadrature():
    """mdr_kink_G against integral_b^x of b s acosh(t/b) (the kink's term of g) by 30-digit
    quadrature (t = b + u^2 puts the sqrt onset at u = 0 into a smooth integrand), from x at
    the kink to far out. Error model: the two terms of the closed form (each ~ b s
    sqrt(2 b (x - b))) cancel to ~ (x - b)^(3/2): relative 16 eps (1 + b/(x - b))."""
    s = -0.7
    eps = 2.0**-52
    for ratio in (1 + 1e-10, 1 + 1e-6, 1.001, 1.3, 2.0, 1e3, 1e6):
        xx = B * ratio
        with mp.workdps(30):
            bm, xm = mp.mpf(B), mp.mpf(xx)
            ref = mp.quad(lambda u, bm=bm: 2 * u * bm * s * mp.acosh(1 + u * u / bm),
                          [0, mp.sqrt(xm - bm)])
            tol = 16 * eps * (1 + float(bm / (xm - bm)))
        assert_close(gen.mdr_kink_G(B, s, xx), ref, tol, f"x/b = {ratio}")
    assert gen.mdr_kink_G(B, s, B) == 0  # at the kink itself
