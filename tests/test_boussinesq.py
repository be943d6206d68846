"""The point-force field (5.1)-(5.6), (5.41)-(5.46): symbolic checks of the derived stress field
and float64 checks of the generated functions against mpmath evaluations of the displacement
field's derivatives (an independent route: numerical differentiation of (5.1)-(5.3))."""

import mpmath as mp
import numpy as np
import sympy as sp

from hertzmdr.derive import boussinesq as b
from hertzmdr.derive.symbols import E, F, nu
from hertzmdr.numeric import _generated as gen

from oracle import Arg, assert_mpmath_equal, n_points

X, Y, Z = b.COORDS


def _vanishes(expr):
    """Exact zero test for a rational function of x, y, z and R = sqrt(x^2 + y^2 + z^2): the
    numerator is A(R^2) + R B(R^2); both polynomials must vanish with R^2 = x^2 + y^2 + z^2."""
    R = sp.Symbol("R", positive=True)
    num, _ = sp.fraction(sp.together(expr.subs(b.distance(), R)))
    poly = sp.Poly(sp.expand(num), R)
    even = sum(c * R**m for (m,), c in poly.terms() if m % 2 == 0)
    odd = sum(c * R**(m - 1) for (m,), c in poly.terms() if m % 2 == 1)
    s2 = X**2 + Y**2 + Z**2
    return all(sp.expand(sp.expand(part).subs(R, sp.sqrt(s2))) == 0 for part in (even, odd))


def _div(sig):
    return [_vanishes(sum(sp.diff(sig[i][j], b.COORDS[j]) for j in range(3))) for i in range(3)]


def test_stress_from_displacement_in_equilibrium():
    """div sigma = 0 for the derived field; traction-free surface away from the origin; every
    plane z = c carries the force F; the printed shear stresses (5.45), (5.46) break the
    equilibrium, the derived ones do not."""
    s = b.stresses()
    sig = [[s["xx"], s["xy"], s["xz"]], [s["xy"], s["yy"], s["yz"]],
           [s["xz"], s["yz"], s["zz"]]]
    assert _div(sig) == [True, True, True]
    assert _div(b.stress_tensor()) == [True, True, True]
    for comp in ("zz", "xz", "yz"):
        assert _vanishes(s[comp].subs(Z, 0))  # (x, y) != (0, 0): no traction
    rho, c = sp.symbols("rho c", positive=True)
    sz = s["zz"].subs({X: rho, Y: 0, Z: c})  # axisymmetric
    assert sp.simplify(sp.integrate(sz * 2 * sp.pi * rho, (rho, 0, sp.oo)) + F) == 0
    p = b.printed_stresses()
    printed = [[p["xx"], p["xy"], p["xz"]], [p["xy"], p["yy"], p["yz"]],
               [p["xz"], p["yz"], p["zz"]]]
    assert _div(printed)[2] is False


def test_surface_displacement_is_the_limit():
    """(5.4)-(5.6) against the 3-D field (5.1)-(5.3) at z = 1e-30 (mpmath, 40 digits)."""
    u = [sp.lambdify((E, F, nu, X, Y, Z), c, "mpmath") for c in b.displacement()]
    funcs = (gen.boussinesq_surface_ux, gen.boussinesq_surface_uy, gen.boussinesq_surface_uz)
    dom = {"E": Arg(1e3, 1e12), "F": Arg(1e-6, 1e6), "nu": Arg(-0.99, 0.5, log=False),
           "x": Arg(1e-9, 1e3), "y": Arg(1e-9, 1e3)}
    for k, fn in enumerate(funcs):
        # products and quotients of a few roundings; the mpmath value at z = 1e-30 m is the
        # limit to 1e-20 relative at the smallest |x|, |y| = 1e-9 m
        assert_mpmath_equal(fn, lambda E, F, nu, x, y, k=k: u[k](E, F, nu, x, y, mp.mpf("1e-30")),
                            dom, rtol=5e-15, n=n_points(100, 20), dps=40)


def _reference_stress(comp):
    """sigma_ij by mpmath differentiation of (5.1)-(5.3) and Hooke's law (no derived form)."""
    u = [sp.lambdify((E, F, nu, X, Y, Z), c, "mpmath") for c in b.displacement()]
    i, j = b.COMPONENTS[comp]

    def ref(F, nu, x, y, z):
        e = mp.mpf(1)  # the stress does not depend on E
        pt = [x, y, z]

        def du(m, n):  # d u_m / d x_n
            def f(t):
                q = list(pt)
                q[n] = t
                return u[m](e, F, nu, *q)
            return mp.diff(f, pt[n])

        lam = e * nu / ((1 + nu) * (1 - 2 * nu)) if nu != mp.mpf("0.5") else None
        mu = e / (2 * (1 + nu))
        eps = (du(i, j) + du(j, i)) / 2
        if i != j:
            return 2 * mu * eps
        tr = du(0, 0) + du(1, 1) + du(2, 2)
        return lam * tr + 2 * mu * eps

    return ref


def test_stress_against_differentiated_displacement():
    """The generated (5.41)-(5.46) against Hooke's law on mpmath derivatives of (5.1)-(5.3)."""
    dom = {"F": Arg(1e-3, 1e3), "nu": Arg(-0.9, 0.49, log=False), "x": Arg(1e-3, 1e2),
           "y": Arg(1e-3, 1e2), "z": Arg(1e-3, 1e2)}
    for comp in b.COMPONENTS:
        fn = getattr(gen, f"boussinesq_sigma_{comp}")
        # rational expressions with a few cancellations between terms of one sign pattern:
        # 1e-12 covers the worst sampled point where sigma_xx changes sign near the surface
        assert_mpmath_equal(fn, _reference_stress(comp), dom, rtol=1e-12,
                            n=n_points(60, 8), dps=30, name=f"boussinesq_sigma_{comp}")


def test_displacement_generated_equals_given():
    pts = np.array([[0.3, -0.2, 0.7], [1e-3, 2.0, 1e-4]])
    for k, comp in enumerate("xyz"):
        fn = getattr(gen, f"boussinesq_u{comp}")
        f = sp.lambdify((E, F, nu, X, Y, Z), b.displacement()[k], "mpmath")
        for x, y, z in pts:
            with mp.workdps(30):
                ref = f(mp.mpf(2e11), mp.mpf(10.0), mp.mpf(0.3), mp.mpf(x), mp.mpf(y), mp.mpf(z))
            assert abs(fn(2e11, 10.0, 0.3, x, y, z) / float(ref) - 1) < 1e-14


def test_surface_prefactor_against_the_point_force():
    """boussinesq_surface_prefactor is 1/(pi E*): u_z rho/F on the surface of one body
    (E, nu) under a point force, by the Landau-Lifshitz displacement typed here at 30 digits
    (u_z = F (1 + nu)/(2 pi E) (2 (1 - nu)/rho + z^2/rho^3), z -> 0), with E* = E/(1 - nu^2):
    a few ulp (two roundings)."""
    from hertzmdr.numeric import _generated as gen

    for Ev, nuv in ((210e9, 0.3), (1e3, 0.49), (5e12, -0.5), (1.0, 0.0)):
        with mp.workdps(30):
            Em, num, rho, Fm = mp.mpf(Ev), mp.mpf(nuv), mp.mpf("0.37"), mp.mpf(2)
            uz = Fm * (1 + num) / (2 * mp.pi * Em) * (2 * (1 - num) / rho)
            ref = uz * rho / Fm
            E_star = float(Em / (1 - num**2))
        got = gen.boussinesq_surface_prefactor(E_star)
        assert abs(mp.mpf(got) / ref - 1) < 4 * 2.0**-52, (Ev, nuv, got, ref)
