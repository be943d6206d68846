"""Cerruti's tangential point force (derive/cerruti.py): the given field checked by the laws it
must obey (equilibrium, free surface, the force it carries, Betti's reciprocity with Boussinesq),
and the generated surface displacements against the 3-D field at z -> 0 (mpmath)."""

import mpmath as mp
import sympy as sp

from hertzmdr.derive import cerruti as ce
from hertzmdr.derive.symbols import nu
from hertzmdr.numeric import _generated as gen

from oracle import Arg, assert_mpmath_equal, n_points

X, Y, Z = ce.x, ce.y, ce.z
COORDS = (X, Y, Z)


def _stress():
    u = ce.displacement()
    G = ce.G
    lam = 2 * G * nu / (1 - 2 * nu)
    eps = [[(sp.diff(u[i], COORDS[j]) + sp.diff(u[j], COORDS[i])) / 2 for j in range(3)]
           for i in range(3)]
    tr = eps[0][0] + eps[1][1] + eps[2][2]
    return [[lam * tr * int(i == j) + 2 * G * eps[i][j] for j in range(3)] for i in range(3)]


def test_field_in_equilibrium_and_surface_traction_free():
    """div sigma = 0 at random interior points and sigma_iz = 0 on z = 0 away from the origin,
    exactly (rational points, 40-digit evaluation: a residual is ~1e-40 or O(1)); every plane
    z = 1 carries the force: the integral of tau_xz over it is -Q (SymPy)."""
    vals = {ce.G: sp.Rational(13, 10), ce.Q: sp.Rational(17, 10), nu: sp.Rational(3, 10)}
    sig = [[e.subs(vals) for e in row] for row in _stress()]
    div = sp.lambdify(COORDS, [sum(sp.diff(sig[i][j], COORDS[j]) for j in range(3))
                               for i in range(3)], "mpmath")
    surf = sp.lambdify(COORDS, [sig[i][2] for i in range(3)], "mpmath")
    with mp.workdps(40):
        for x, y, z in ((3 / mp.mpf(7), -2 / mp.mpf(5), 5 / mp.mpf(11)),
                        (-9 / mp.mpf(4), 1 / mp.mpf(3), 7 / mp.mpf(2))):
            assert max(abs(v) for v in div(x, y, z)) < 1e-35  # O(1) if the field were wrong
            assert max(abs(v) for v in surf(x, y, 0)) < 1e-35
    # the plane z = 1 carries -Q in x: integral over rho, phi of tau_xz (x = rho cos phi)
    rho, phi = sp.symbols("rho phi", positive=True)
    txz = sp.simplify(sig[0][2].subs({X: rho * sp.cos(phi), Y: rho * sp.sin(phi), Z: 1}))
    total = sp.integrate(sp.integrate(txz * rho, (phi, 0, 2 * sp.pi)), (rho, 0, sp.oo))
    assert sp.simplify(total + vals[ce.Q]) == 0


def test_surface_is_the_limit_and_reciprocal_to_boussinesq():
    """The generated surface displacements against the 3-D field at z = 1e-30 (40 digits); and
    Betti: Q u_z(x, y) of the tangential force equals F u_x at the origin of a normal force at
    (x, y) (generated Boussinesq (5.4) with E = 2 G (1 + nu)): fixes the sign of u_z."""
    u3 = [sp.lambdify((ce.G, ce.Q, nu, X, Y, Z), c, "mpmath") for c in ce.displacement()]
    funcs = (gen.cerruti_surface_ux, gen.cerruti_surface_uy, gen.cerruti_surface_uz)
    dom = {"G": Arg(1e3, 1e12), "Q": Arg(1e-6, 1e6), "nu": Arg(-0.99, 0.5, log=False),
           "x": Arg(1e-9, 1e3), "y": Arg(1e-9, 1e3)}
    for k, fn in enumerate(funcs):
        assert_mpmath_equal(
            lambda G, Q, nu, x, y, fn=fn: fn(G, Q, nu, x, y),
            lambda G, Q, nu, x, y, k=k: u3[k](G, Q, nu, x, y, mp.mpf("1e-30")),
            dom, rtol=1e-13, n=n_points(200, 20), dps=40, name=fn.__name__)
        # 1e-13: a handful of roundings in the generated rational function (the field's own
        # correction at z = 1e-30 is ~1e-30 relative)
    for G, nu_, x, y in ((1.3, 0.3, 0.4, -0.7), (2e9, 0.45, -1e-3, 2e-3), (5.0, 0.0, 2.0, 0.1)):
        E = 2 * G * (1 + nu_)
        uz = gen.cerruti_surface_uz(G, 1.0, nu_, x, y)
        ux = gen.boussinesq_surface_ux(E, 1.0, nu_, -x, -y)  # origin seen from the load
        assert abs(uz - ux) <= 1e-15 * abs(ux) + 1e-300


def test_angular_mean_compliance():
    """The direction average of u_x is Q (2 - nu)/(4 pi G rho) (SymPy), and by mpmath
    quadrature of the generated surface u_x at 30 digits."""
    assert sp.simplify(ce.angular_mean_compliance()
                       - (2 - nu) / (4 * sp.pi * ce.G * ce.rho)) == 0
    G, nu_, rho = 3.0, 0.3, 0.25
    with mp.workdps(30):
        mean = mp.quad(lambda p: gen.cerruti_surface_ux(G, 1.0, nu_, float(rho * mp.cos(p)),
                                                        float(rho * mp.sin(p))),
                       [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]) / (2 * mp.pi)
        assert abs(mean / ((2 - mp.mpf(nu_)) / (4 * mp.pi * G * rho)) - 1) < 1e-14
        # 1e-14: the float64 integrand (the cos^2 average loses nothing; ~ten roundings)
