"""The worn (flattened) paraboloid of Problem 8 by independent routes.

The MDR pressure has no closed form (an incomplete elliptic integral); the reference evaluates
(5.59) by mpmath quadrature of the derived g'(x) and puts it through the Boussinesq integral
(5.7) (tests/kernels.py, tanh-sinh, split at the circle rho = b where p is log-singular). The
force is the pressure integrated over the disc.
"""

import mpmath as mp
import pytest
import sympy as sp

from hertzmdr.derive import worn as dw
from hertzmdr.derive.mdr import x
from hertzmdr.derive.symbols import R
from hertzmdr.numeric import _generated as g

from kernels import uz_axisymmetric
from oracle import FULL, WORST, assert_close


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


def test_g_by_quadrature():
    Rv, b = 0.02, 1e-4
    for xv in (1.5e-4, 3e-4):
        with mp.workdps(30):
            xm = mp.mpf(xv)
            ref = xm * mp.quad(lambda rr, xm=xm: rr / Rv / mp.sqrt((xm - rr) * (xm + rr)),
                               [b, xm])
        assert_close(g.worn_g(Rv, b, xv), ref, TOL_FLOAT, "g(x)")
    assert g.worn_g(Rv, b, 0.5e-4) == 0.0


def test_force_by_pressure():
    Rv, b, E = 0.02, 1e-4, 2e9
    for d in (1e-9, 1e-7, 1e-5):  # s = 2 R d/b^2 from 4e-3 to 40
        with mp.workdps(25):
            bm = mp.mpf(b)
            # contact radius from d = g(a) (5.55), solved at 25 digits
            am = mp.findroot(lambda aa, bm=bm, d=d: aa * mp.sqrt((aa - bm) * (aa + bm)) / Rv - d,
                             mp.mpf(g.worn_contact_radius(Rv, b, d)))
            F = mp.quad(lambda rr, am=am, bm=bm: pressure_ref(rr, am, bm, Rv, E) * 2 * mp.pi * rr,
                        [0, bm, am])
        assert_close(g.worn_contact_radius(Rv, b, d), am, 1e-14, "a(d)")
        assert_close(g.worn_force(E, Rv, b, d), F, 1e-13, f"F(d) at d={d}")
        # F(a) near a = b amplifies the rounding of a by a^2/(a^2 - b^2): allow for it
        a = float(am)
        cond = float(am**2 / (am**2 - bm**2))
        assert_close(g.worn_force_from_radius(E, Rv, a, b), F, 1e-14 * max(cond, 10), "F(a)")


def test_stable_force_at_small_depth():
    """At s = 2Rd/b^2 = 1e-9 the printed form has lost all digits; the stable one has none."""
    Rv, b, E = 0.02, 1e-4, 2e9
    d = 1e-9 * b**2 / (2 * Rv)
    with mp.workdps(40):
        s = 2 * mp.mpf(Rv) * d / mp.mpf(b) ** 2
        root = mp.sqrt(1 + s**2)
        ref = mp.sqrt(2) * E * mp.mpf(b) ** 3 / (3 * Rv) * (2 + root) * mp.sqrt(root - 1)
    assert_close(g.worn_force(E, Rv, b, d), ref, 1e-14, "stable F(d)")


@pytest.mark.sweep
def test_against_3d_elasticity():
    """The quadrature pressure through (5.7): d - f(r) inside, worn_displacement_outside out."""
    Rv, b, E, d = mp.mpf(1), mp.mpf(1) / 2, mp.mpf(3), mp.mpf(1) / 4
    if not FULL:
        pytest.skip("nested tanh-sinh takes minutes: run with HERTZMDR_SWEEP=full")
    dps, tol = 30, 1e-20  # nested tanh-sinh at 30 digits: ~1e-25
    with mp.workdps(dps):
        a = mp.sqrt((b**2 + mp.sqrt(b**4 + 4 * Rv**2 * d**2)) / 2)

        def p_gap(gap):
            return pressure_ref(mp.sqrt(a**2 - gap), a, b, Rv, E)

        rr = (b + a) / 2  # on the parabolic part
        u = uz_axisymmetric(p_gap, rr, a, E, method="tanh-sinh", rho_splits=(b,))
        _record("worn 3-D inside", abs(u / (d - (rr**2 - b**2) / (2 * Rv)) - 1), tol)
        rr = 2 * a
        u = uz_axisymmetric(p_gap, rr, a, E, method="tanh-sinh", rho_splits=(b,))
        from hertzmdr.derive.symbols import a as a_s
        from hertzmdr.derive.symbols import r as r_s
        u_mp = sp.lambdify((R, a_s, dw.b, r_s), dw.solution()["u_out"], "mpmath")(Rv, a, b, rr)
        _record("worn 3-D outside (derived)", abs(u / u_mp - 1), tol)
        assert_close(g.worn_displacement_outside(float(Rv), float(a), float(b), float(rr)), u,
                     1e-14, "outside")
        rr = b / 2  # on the flat tip
        u = uz_axisymmetric(p_gap, rr, a, E, method="tanh-sinh", rho_splits=(b,))
        _record("worn 3-D flat tip", abs(u / d - 1), tol)
