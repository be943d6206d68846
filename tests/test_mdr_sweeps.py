"""Float64 sweeps over decades for the MDR closed forms (power law, worn parabola).

References by independent routes at 30 digits: kappa_n by the quadrature of (5.52)
(test_powerlaw.kappa_reference), the contact radius by solving g(a) = d (5.55) with findroot,
the force by the quadrature of (5.57), F = 2 E* integral_0^a (d - g(x)) dx; for the worn
parabola g(x) itself by the quadrature of (5.52). Lengths scale with R0 over 1e-9...1e3 m,
moduli over 1e3...1e12 Pa, strains d/R0 over 1e-12...1e-1.
"""

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import powerlaw

from oracle import Arg, assert_mpmath_equal, n_points
from test_powerlaw import kappa_reference

DOMS = {"E": Arg(1e3, 1e12), "R0": Arg(1e-9, 1e3), "strain": Arg(1e-12, 1e-1)}
# products and powers of a handful of correctly rounded operations, and kappa_n (1e-15 there)
TOL = 1e-13


def _pl_reference(n):
    """(a, F) of f = R0 (r/R0)^n at depth d, by quadrature; call inside mp.workdps.

    Its values are kept by the arguments and the working precision (kappa_n's quadrature by
    the precision alone): the sweep checks F, a and the inverse at the same sampled points
    (same domains and seed), which redid kappa_n and the force quadrature at each of them."""
    done = {}

    def ref(E, R0, strain):
        key = (E, R0, strain, mp.mp.prec)
        if key not in done:
            if mp.mp.prec not in done:
                done[mp.mp.prec] = kappa_reference(mp.mpf(n))
            k = done[mp.mp.prec]
            c = R0 ** (1 - n)
            d = strain * R0
            a = (d / (k * c)) ** (mp.mpf(1) / n)  # the root of g(a) = k c a^n = d (5.55)
            # (5.57) in t = x/a and normalised by d: mp.quad's error criterion is absolute
            F = 2 * E * a * d * mp.quad(lambda t: 1 - k * c * (a * t) ** n / d, [0, 1])
            done[key] = a, F
        return done[key]
    return ref


@pytest.mark.sweep
@pytest.mark.parametrize("n", [1.5, 2.5, 3.0, 7.0])
def test_power_law_sweep(n):
    ref = _pl_reference(mp.mpf(n))

    def force(E, R0, strain):
        return powerlaw.force(strain * R0, R0 ** (1 - n), n, E)

    def radius(E, R0, strain):
        return np.broadcast_to(powerlaw.contact_radius(strain * R0, R0 ** (1 - n), n),
                               np.shape(E))

    def depth(E, R0, strain):  # the inverse at the reference's own (rounded) force
        F = np.array([float(ref(mp.mpf(e), mp.mpf(r), mp.mpf(s))[1])
                      for e, r, s in zip(E, R0, strain, strict=True)])
        return powerlaw.depth_from_force(F, R0 ** (1 - n), n, E)

    kw = {"n": n_points(60, 8), "dps": 30}
    assert_mpmath_equal(force, lambda E, R0, strain: ref(E, R0, strain)[1], DOMS, rtol=TOL,
                        name="powerlaw_force", **kw)
    assert_mpmath_equal(radius, lambda E, R0, strain: ref(E, R0, strain)[0], DOMS, rtol=TOL,
                        name="powerlaw_contact_radius", **kw)
    with mp.workdps(30):  # the rounded reference forces inside depth() at 30 digits
        assert_mpmath_equal(depth, lambda E, R0, strain: strain * R0, DOMS, rtol=TOL,
                            name="powerlaw_depth_from_force", **kw)


@pytest.mark.sweep
def test_worn_force_sweep():
    """F(d) of the flattened parabola, flat radius b = R0/10 on the radius R = R0."""
    def ref(E, R0, strain):
        R, b, d = R0, R0 / 10, strain * R0

        def gq(x):  # (5.52) with f' = r/R for r > b, in r = x sin(theta) (no end-point root)
            if x <= b:
                return mp.mpf(0)
            return x * mp.quad(lambda th: x * mp.sin(th) / R, [mp.asin(b / x), mp.pi / 2])

        # g(a) = d (5.55) on the quadrature g, solved in the scaled form g(a)/d - 1 = 0
        # (findroot's tolerance is absolute), started at the algebraic root of
        # (a/R) sqrt(a^2 - b^2) = d, written without cancellation
        s2 = (2 * R * d / b**2) ** 2
        start = b * mp.sqrt(1 + s2 / (2 * (1 + mp.sqrt(1 + s2))))
        a = mp.findroot(lambda x: gq(x) / d - 1, start)
        # (5.57) F = 2 E (d a - integral_0^a g) with the order of integration of (5.52)
        # exchanged, integral_0^a g = integral_b^a f'(u) sqrt(a^2 - u^2) du (as
        # tests/test_mdr_bounds.py's G_ref): one quadrature of f' = u/R instead of a quadrature
        # of the quadrature g (the two agreed to 4e-49 at CI's nine points, at 60 digits, and
        # this one costs 0.5 s of CPU where that one cost 21 s)
        return 2 * E * (a * d - mp.quad(lambda u: u / R * mp.sqrt((a - u) * (a + u)), [b, a]))

    def func(E, R0, strain):
        return gen.worn_force(E, R0, R0 / 10, strain * R0)

    # 60 digits: for the smallest strains a - b ~ 5e-21 b, and asin(b/x) near 1 needs the
    # digits that the difference takes away
    assert_mpmath_equal(func, ref, DOMS, rtol=TOL, n=n_points(30, 1), dps=60, name="worn_force")
