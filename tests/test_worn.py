"""The worn (flattened) paraboloid of Problem 8 by independent routes.

The MDR pressure is an incomplete elliptic integral (derive/worn.py). It is checked against
(5.59) evaluated by mpmath quadrature of the derived g'(x); its mpmath form is then put through
the Boussinesq integral (5.7) (tests/kernels.py, tanh-sinh, split at the circle rho = b where p
is log-singular), which must give back d - f(r) inside and the derived u(r) outside. The force
is the pressure integrated over the disc.
"""

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from hertzmdr.derive import worn as dw
from hertzmdr.derive.mdr import x
from hertzmdr.derive.symbols import R
from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import _generated_mp as gen_mp

from kernels import uz_rings
from oracle import WORST, assert_close, n_points


def _record(what, err, tol):
    """Keep the error for the end-of-run summary (conftest), then check it."""
    WORST[what] = max(WORST.get(what, 0.0), float(err))
    assert err < tol, f"{what}: {err} >= {tol}"

TOL_FLOAT = 1e-14  # a handful of correctly rounded float64 operations


def gprime(xx, b, Rv, x_minus_b=None):
    """g'(x) = (2x^2 - b^2)/(R sqrt((x - b)(x + b))) for x > b: the derivative of the derived g,
    factored so that x -> b keeps full precision (checked against SymPy's diff below)."""
    xmb = xx - b if x_minus_b is None else x_minus_b
    return (2 * xx**2 - b**2) / (Rv * mp.sqrt(xmb * (xx + b)))


def test_gprime_is_the_derivative():
    expr = sp.diff(dw.solution()["g"], x)
    typed = (2 * x**2 - dw.b**2) / (R * sp.sqrt((x - dw.b) * (x + dw.b)))
    assert sp.simplify(expr - typed) == 0


def pressure_ref(rho, a, b, Rv, E):
    """(5.59): p = (E*/pi) integral_max(rho, b)^a g'(x)/sqrt(x^2 - rho^2) dx by quadrature.

    x = lo + u^2 (lo = max(rho, b)) removes the 1/sqrt endpoint singularity (at x = b from g',
    at x = rho from the Abel kernel): dx/sqrt(x - lo) = 2 du.
    """
    if rho < b:
        def integrand(u):
            xx = b + u * u
            kern = mp.sqrt((xx - rho) * (xx + rho))
            return 2 * (2 * xx**2 - b**2) / (Rv * mp.sqrt(xx + b) * kern)
        top = mp.sqrt(a - b)
    else:
        def integrand(u):
            xx = rho + u * u
            return 2 * gprime(xx, b, Rv, (rho - b) + u * u) / mp.sqrt(xx + rho)
        top = mp.sqrt(a - rho)
    return E / mp.pi * mp.quad(integrand, [0, top])


def _pressure_tol(rho, a, b):
    """Float64 error model of worn_pressure: a few ulp, times the conditioning of F(phi|m) as
    m = (S/L)^2 -> 1 near the kink (an absolute rounding of m is relative 1/(1 - m) in 1 - m,
    and F ~ log(1/(1 - m))/2), and of sqrt(a^2 - r^2) at the rim."""
    L, S = max(rho, b), min(rho, b)
    one_minus_m = (L - S) * (L + S) / L**2
    return 8 * 2.2e-16 * (1 + 1 / one_minus_m + a / max(a - rho, 1e-300))


# radii on the flat, at the kink from both sides, beyond it and at the rim (a = 0.8, b = 0.5)
RHOS = (0.0, 0.1, 0.3, 0.499, 0.5 - 1e-7, 0.5 + 1e-7, 0.501, 0.6, 0.79, 0.8 - 1e-9)


def test_pressure_by_quadrature_of_59():
    """The closed form against (5.59) by quadrature: float64 within its error model, the mpmath
    form at 30 digits within 1e-25 (tanh-sinh on the smooth substituted integrand: ~1e-28)."""
    Rv, b, E, a = 1.0, 0.5, 3.0, 0.8
    for rho in RHOS:
        with mp.workdps(30):
            ref = pressure_ref(mp.mpf(rho), mp.mpf(a), mp.mpf(b), mp.mpf(Rv), mp.mpf(E))
            assert abs(gen_mp.worn_pressure(*(mp.mpf(v) for v in (E, Rv, a, b, rho))) / ref - 1) \
                < 1e-25, rho
        assert_close(gen.worn_pressure(E, Rv, a, b, rho), ref, _pressure_tol(rho, a, b),
                     f"p({rho})")
    assert gen.worn_pressure(E, Rv, a, b, b) == float("inf")  # log singularity at the kink
    assert list(gen.worn_pressure(E, Rv, a, b, [a, 2 * a])) == [0.0, 0.0]


def test_pressure_is_hertz_without_wear():
    """b -> 0: the worn pressure tends to Hertz's (2E*/(pi R)) sqrt(a^2 - r^2) (5.15)."""
    Rv, E, a = 1.0, 3.0, 0.8
    r = [0.0, 0.3, 0.7]
    hertz = [2 * E / (mp.pi * Rv) * mp.sqrt(a**2 - rr**2) for rr in r]
    b = 1e-9
    for rr, h in zip(r, hertz, strict=True):
        # the flat removes O(b) at the centre, -(E*/(pi R)) b acos(b/a) (relative pi b/(4a)),
        # and O(b^2/r^2) beyond the flat, where the modulus k = b/r of F and E is small
        tol = 1e-14 + (np.pi * b / (4 * a) * 1.01 if rr == 0 else (b / rr) ** 2)
        assert_close(gen.worn_pressure(E, Rv, a, b, rr), h, tol, f"b->0 at r={rr}")


def test_force_by_closed_form_pressure():
    """integral p 2 pi r dr of the closed form (30 digits, split at the log singularity at b)
    equals (5.57) of the derived F(a)."""
    Rv, b, E, a = 1.0, 0.5, 3.0, 0.8
    with mp.workdps(30):
        args = [mp.mpf(v) for v in (E, Rv, a, b)]
        F = mp.quad(lambda rr: gen_mp.worn_pressure(*args, rr) * 2 * mp.pi * rr, [0, b, a])
        F_a = gen_mp.worn_force_from_radius(*args)
        assert abs(F / F_a - 1) < 1e-25


def test_g_by_quadrature():
    Rv, b = 0.02, 1e-4
    for xv in (1.5e-4, 3e-4):
        with mp.workdps(30):
            xm = mp.mpf(xv)
            ref = xm * mp.quad(lambda rr, xm=xm: rr / Rv / mp.sqrt((xm - rr) * (xm + rr)),
                               [b, xm])
        assert_close(gen.worn_g(Rv, b, xv), ref, TOL_FLOAT, "g(x)")
    assert gen.worn_g(Rv, b, 0.5e-4) == 0.0


def test_force_by_pressure():
    """a(d), F(d) and F(a) against the pressure (5.59) by quadrature, integrated over the disc
    (a nested 25-digit quadrature, ~2 s of CPU a depth).

    s = 2 R d/b^2 from 4e-3 to 40. The default run takes the two ends: s = 4e-3, the contact
    just beyond the flat (a - b = 2e-6 b: the kink's log singularity next to the rim, F(a)
    conditioned by a^2/(a^2 - b^2) = 2.5e5), and s = 40, the parabola's regime (a = 4.5 b);
    the middle one, s = 0.4 (a = 1.02 b), lies between them on the same closed forms and is
    added by HERTZMDR_SWEEP=full."""
    Rv, b, E = 0.02, 1e-4, 2e9
    for d in (1e-9, 1e-5, 1e-7)[:n_points(3, 2)]:
        with mp.workdps(25):
            bm = mp.mpf(b)
            # contact radius from d = g(a) (5.55), solved at 25 digits
            am = mp.findroot(lambda aa, bm=bm, d=d: aa * mp.sqrt((aa - bm) * (aa + bm)) / Rv - d,
                             mp.mpf(gen.worn_contact_radius(Rv, b, d)))
            F = mp.quad(lambda rr, am=am, bm=bm: pressure_ref(rr, am, bm, Rv, E) * 2 * mp.pi * rr,
                        [0, bm, am])
        assert_close(gen.worn_contact_radius(Rv, b, d), am, 1e-14, "a(d)")
        assert_close(gen.worn_force(E, Rv, b, d), F, 1e-13, f"F(d) at d={d}")
        # F(a) near a = b amplifies the rounding of a by a^2/(a^2 - b^2): allow for it
        a = float(am)
        cond = float(am**2 / (am**2 - bm**2))
        assert_close(gen.worn_force_from_radius(E, Rv, a, b), F, 1e-14 * max(cond, 10), "F(a)")


def test_stable_force_at_small_depth():
    """At s = 2Rd/b^2 = 1e-9 the printed form has lost all digits; the stable one has none."""
    Rv, b, E = 0.02, 1e-4, 2e9
    d = 1e-9 * b**2 / (2 * Rv)
    with mp.workdps(40):
        s = 2 * mp.mpf(Rv) * d / mp.mpf(b) ** 2
        root = mp.sqrt(1 + s**2)
        ref = mp.sqrt(2) * E * mp.mpf(b) ** 3 / (3 * Rv) * (2 + root) * mp.sqrt(root - 1)
    assert_close(gen.worn_force(E, Rv, b, d), ref, 1e-14, "stable F(d)")


# field points of the 3-D check: (name, r/a or r/b), on the flat, at the kink, on the parabola,
# at the rim, outside; CI runs the first two (inside: d - f(r); outside: the derived form)
POINTS_3D = (("flat tip", "b", 0.5), ("outside", "a", 2.0), ("parabola", "a", 0.9),
             ("centre", "b", 0.0), ("kink", "b", 1.0), ("rim", "a", 1.0), ("far", "a", 10.0))


@pytest.mark.sweep
def test_against_3d_elasticity():
    """The closed-form pressure through (5.7) (2-D quadrature, tests/kernels.py::uz_rings) gives
    back d - f(r) inside the contact and the derived worn_displacement_outside beyond it.

    Tanh-sinh at 30 digits on integrands whose singularities (log at rho = b and rho = r,
    square root at the rim) sit at interval ends: ~1e-30 measured; asserted 1e-25 (>= 25 digits).
    """
    Rv, b, E, d = mp.mpf(1), mp.mpf(1) / 2, mp.mpf(3), mp.mpf(1) / 4
    with mp.workdps(30):
        a = mp.sqrt((b**2 + mp.sqrt(b**4 + 4 * Rv**2 * d**2)) / 2)  # (5.55) solved at 30 digits
        assert abs(gen_mp.worn_depth(Rv, a, b) / d - 1) < 1e-28

        def p(rho):
            return gen_mp.worn_pressure(E, Rv, a, b, rho)

        for name, unit, t in POINTS_3D[:n_points(len(POINTS_3D), 2)]:
            rr = t * (a if unit == "a" else b)
            u = uz_rings(p, rr, a, E, splits=(b,))
            if rr > a:
                from hertzmdr.derive.symbols import a as a_s
                from hertzmdr.derive.symbols import r as r_s
                ref = sp.lambdify((R, a_s, dw.b, r_s), dw.solution()["u_out"], "mpmath")(
                    Rv, a, b, rr)  # the derived (not the stable, printed) form
                assert_close(gen.worn_displacement_outside(*(float(v) for v in (Rv, a, b, rr))),
                             u, 1e-14, "float64 outside")
            else:
                ref = d - (max(rr, b) ** 2 - b**2) / (2 * Rv)  # d - f(r)
            _record(f"worn 3-D {name}", abs(u / ref - 1), 1e-25)
