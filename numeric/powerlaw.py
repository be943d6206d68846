"""Power-law indenters f = c_n r^n by the MDR (Problem 7), with the flat punch as n -> inf.

Floats or NumPy arrays in SI units; bad input raises ValueError. The formulas are generated
from :mod:`hertzmdr.derive.powerlaw`; this module validates, broadcasts and picks the form that
is accurate for the given n:

- kappa_n: the Gamma ratio for n < 40, the Stirling series above (no overflow up to n = 1e150).
- pressure: elementary forms for n = 1, 2, 3, 4; near the centre (r < a/10) for n < 3 the
  series about the centre; else the Euler-transformed 2F1 form for n >= 1.5, the 2F1 form
  for n < 1.5; the quadrature of (5.59) for n > 40.
- surface displacement outside: the 2F1 form of (5.60), its quadrature next to the edge and
  for n > 40, the far-field series for r > 1000 a.

``c_n`` has the unit m^(1-n) (f = c_n r^n in metres for r in metres).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import (
    as_float,
    nonnegative,
    positive,
    pow2_scale,
    representable,
    result,
)

__all__ = ["kappa", "g_profile", "contact_radius", "force", "force_from_radius",
           "depth_from_force", "mean_pressure", "pressure", "pressure_normalized",
           "surface_displacement", "N_ASYMPTOTIC", "N_PRESSURE_QUADRATURE"]

#: above this n, :func:`pressure` integrates (5.59) (powerlaw_pressure_integrand) instead of
#: evaluating the 2F1: SciPy's hyp2f1(1, 1 - n/2; 3/2; z) loses digits as n grows (5e-13 at
#: n = 300) and returns NaN near the centre for n >= 343 that is not an even integer
N_PRESSURE_QUADRATURE = 40.0
#: :func:`surface_displacement` integrates (5.60) instead of evaluating its 2F1 form where
#: n > N_PRESSURE_QUADRATURE or r < a (1 + EDGE_QUADRATURE)
EDGE_QUADRATURE = 1e-4
#: :func:`pressure` takes the series about the centre (powerlaw_pressure_centre) for n < 3
#: and r < CENTRE_SERIES a (its first term left out is below 1e-20 of the centre value there)
CENTRE_SERIES = 0.1
#: :func:`surface_displacement` takes the far-field series (powerlaw_displacement_far) for
#: r > a/FAR_SERIES, where its first term left out is below 1e-24 of u_z
FAR_SERIES = 1e-3
#: kappa_n switches from the Gamma ratio to the Stirling series at this n (both < 1e-15 there)
N_ASYMPTOTIC = 40.0


@representable
def kappa(n):
    """MDR factor kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2) [1], Problem 7(d).

    Guaranteed finite and accurate for n in [0.001, 1e+300] (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    g(x) = kappa_n c_n |x|^n is the MDR profile (5.52) of f = c_n r^n. kappa_n ~ sqrt(pi n/2)
    for large n; kappa_1 = pi/2, kappa_2 = 2.

    Parameters
    ----------
    n : float or array_like
        Exponent, n > 0 (finite).
    """
    n = positive("n", n)
    with np.errstate(over="ignore", invalid="ignore"):
        small = gen.powerlaw_kappa(np.minimum(n, N_ASYMPTOTIC))
    large = gen.powerlaw_kappa_asymptotic(np.maximum(n, N_ASYMPTOTIC))
    return result(np.where(n < N_ASYMPTOTIC, small, large))


@representable
def g_profile(x, c_n, n):
    """MDR profile g(x) = kappa_n c_n |x|^n [m] (5.52), Problem 7(d).

    Guaranteed finite and accurate for x in {0} U [1e-12, 1000], d in [1e-15, 1000], a in [1e-09,
    1000], n in [0.001, 1e+08], with c_n = d/(kappa_n a^n) for a contact radius a in that range (for
    n > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    x : float or array_like
        1-D coordinate [m].
    c_n : float or array_like
        Profile coefficient [m^(1-n)], > 0.
    n : float or array_like
        Exponent, > 0.
    """
    x = np.abs(as_float("x", x))  # g is even in x
    x, c_n, n = np.broadcast_arrays(nonnegative("x", x), positive("c_n", c_n), positive("n", n))
    # g(x; c_n) = g(c_n^(1/n) x; 1): for n >= 1 the scaled x, not x^n, is formed (x^n
    # underflowed at x = 6e-4, n = 123 where c_n = 5e236 brings g back to 4e-160); for n < 1
    # c_n^(1/n) could overflow instead, and x^n is harmless
    big = n >= 1
    xs = np.where(big, c_n ** (1.0 / np.where(big, n, 1.0)) * x, x)
    return result(gen.powerlaw_g(np.where(big, 1.0, c_n), kappa(n), n, xs))  # (5.52)


@representable
def contact_radius(d, c_n, n):
    """Contact radius a = (d/(kappa_n c_n))^(1/n) [m], (5.55).

    Guaranteed finite and accurate for d in [1e-15, 1000], a in [1e-09, 1000], n in [0.001, 1e+08],
    with c_n = d/(kappa_n a^n) for a contact radius a in that range (for n > 24 within exp(+-500/n)
    of 1 m, so that kappa_n c_n is a float) (SI units; searched by tests/domain_search.py). Beyond
    float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d : float or array_like
        Indentation depth [m], >= 0.
    c_n, n
        As in :func:`g_profile`.
    """
    c_n, n = positive("c_n", c_n), positive("n", n)
    # d/kappa_n first: the product kappa_n c_n of the printed form overflows for c_n ~ 1e306
    return result(gen.powerlaw_contact_radius(c_n, nonnegative("d", d) / kappa(n), 1.0,
                                              n))  # (5.55)


@representable
def force(d, c_n, n, E_star):
    """Normal force F = 2n/(n+1) E* a d [N], (5.57) (the print of Problem 7(d) has an erratum).

    Guaranteed finite and accurate for d in [1e-15, 1000], a in [1e-09, 1000], n in [0.001, 1e+08],
    E_star in [0.001, 1e+15], with c_n = d/(kappa_n a^n) for a contact radius a in that range (for n
    > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    d, c_n, n
        As in :func:`contact_radius`.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    """
    c_n, n = positive("c_n", c_n), positive("n", n)
    return result(gen.powerlaw_force(positive("E_star", E_star), c_n, nonnegative("d", d),
                                   kappa(n), n))


@representable
def force_from_radius(a, d, n, E_star):
    """F = 2n/(n+1) E* a d [N] for a contact of radius a at depth d, (5.57).

    Guaranteed finite and accurate for a in [1e-12, 1e+06], d in {0} U [1e-15, 1000], n in [0.001,
    1e+08], E_star in [0.001, 1e+15] (SI units; searched by tests/domain_search.py). Beyond float64
    (|result| > 1.8e308): OverflowError naming the inputs.

    Parameters
    ----------
    a : float or array_like
        Contact radius [m], >= 0.
    d : float or array_like
        Depth [m], >= 0.
    n, E_star
        As above.
    """
    return result(gen.powerlaw_force_from_radius(positive("E_star", E_star),
                                               nonnegative("a", a), nonnegative("d", d),
                                               positive("n", n)))


@representable
def depth_from_force(F, c_n, n, E_star):
    """Indentation depth d [m] under the normal force F, Problem 7(d) inverted.

    Guaranteed finite and accurate for F in {0} U [1e-300, 1e+30], d in [1e-15, 1000], a in [1e-09,
    1000], n in [0.001, 1e+08], E_star in [0.001, 1e+15], with c_n = d/(kappa_n a^n) for a contact
    radius a in that range (for n > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float)
    (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    Parameters
    ----------
    F : float or array_like
        Normal force [N], >= 0.
    c_n, n, E_star
        As above.
    """
    c_n, n = positive("c_n", c_n), positive("n", n)
    return result(gen.powerlaw_depth_from_force(positive("E_star", E_star), nonnegative("F", F),
                                              c_n, kappa(n), n))


@representable
def mean_pressure(d, c_n, n, E_star):
    """Mean pressure F/(pi a^2) [Pa] (Fig. 5.17). Parameters as :func:`force`.

    Guaranteed finite and accurate for d in [1e-15, 1000], a in [1e-09, 1000], n in [0.001, 1e+08],
    E_star in [0.001, 1e+15], with c_n = d/(kappa_n a^n) for a contact radius a in that range (for n
    > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.
    """
    c_n, n = positive("c_n", c_n), positive("n", n)
    return result(gen.powerlaw_mean_pressure_from_depth(positive("E_star", E_star), c_n,
                                                      positive("d", d), kappa(n), n))


def _pressure_at(r, a, d, n, E_star):
    """Pressure for broadcast arrays with r < a, n finite; picks the accurate form."""
    out = np.empty(r.shape)
    forms = {1.0: gen.powerlaw_pressure_n1, 2.0: gen.powerlaw_pressure_n2,
             3.0: gen.powerlaw_pressure_n3, 4.0: gen.powerlaw_pressure_n4}
    done = n > N_PRESSURE_QUADRATURE  # no 2F1 there: the quadrature of (5.59)
    if done.any():
        out[done] = _pressure_quadrature(r[done], a[done], d[done], n[done], E_star[done])
    for k, fn in forms.items():
        sel = n == k
        if k in (1.0, 3.0):
            sel &= r > 0  # log(a/r): the cone's centre is singular; n = 3 uses the 2F1 at 0
        out[sel] = fn(E_star[sel], a[sel], d[sel], r[sel])
        done |= sel
    # near the centre for n < 3 the 2F1 forms, whose z = 1 - r^2/a^2 rounds to 1, lose the
    # (r/a)^(n-1) part (6e-5 at n = 1.5, r = 1e-8 a; inf for n < 1.5): the series about the
    # centre, whose (r/a)^2/(2 (n - 3)) and (r/a)^(n-1) terms cancel as n -> 3 (kept where
    # (r/a)^2 < (3 - n)/10: at most 1e-14 there, measured against (5.59) by quadrature)
    rho = r / a
    centre = ~done & (n < 3) & (n != 1) & (rho < CENTRE_SERIES) & (rho * rho < (3 - n) / 10)
    with np.errstate(divide="ignore"):  # (r/a)^(n-1) at r = 0 for n < 1: the singularity
        out[centre] = gen.powerlaw_pressure_centre(E_star[centre], a[centre], d[centre],
                                                   n[centre], r[centre])
    done |= centre
    # n >= 1.5, and the centre for 1 < n < 1.5, where the small-n form is 0 * inf but this
    # one's 2F1 converges at z = 1 (c - a - b = (n - 1)/2 > 0)
    big = ~done & ((n >= 1.5) | ((r == 0) & (n > 1)))
    out[big] = gen.powerlaw_pressure(E_star[big], a[big], d[big], n[big], r[big])
    small = ~done & ~big
    with np.errstate(divide="ignore"):  # r^(n-1) at r = 0 for n < 1: the true singularity
        out[small] = gen.powerlaw_pressure_small_n(E_star[small], a[small], d[small],
                                                 n[small], r[small])
    return out


def _pressure_quadrature(r, a, d, n, E_star, m=16):
    """(5.59) as integral_0^1 powerlaw_pressure_integrand dw, for broadcast 1-D arrays, r < a.

    The integrand is smooth in w but, for large n, concentrated in a layer of width
    ~1/L, L = n (1 - r^2/a^2), at w = 0: composite m-point Gauss-Legendre on panels with edges
    w = 2^j/L (j = -6, -5, ...), so that each panel sees at most a factor e^(2^j) of decay
    (measured against 30-digit quadrature: < 1e-14 for n = 40 ... 1e8, tests/test_powerlaw.py).
    """
    from hertzmdr.numeric._quadrature import panels

    lam = n * (a - r) * (a + r) / a**2
    j = 2.0 ** np.arange(-6, 64)
    w, wts = panels(np.zeros(len(r)), np.ones(len(r)), j[None, :] / lam[:, None], m)
    w[wts == 0] = 0.5  # the empty panels of clipped edges: any w in (0, 1), weight 0

    def col(v):
        return v[:, None]

    f = gen.powerlaw_pressure_integrand(col(E_star), col(a), col(d), col(n), col(r), w)
    return np.sum(wts * f, axis=1)


def _displacement_quadrature(r, a, d, n, m=16):
    """(5.60) as integral_0^asin(a/r) powerlaw_displacement_outside_integrand dw, for broadcast
    1-D arrays, r > a.

    The integrand rises from 0 at w = 0 to ~2d/pi in a layer of width ~1/L,
    L = n cot(asin(a/r)) + sqrt(n) (the base cos(w) - cot(asin(a/r)) sin(w) of the power n
    falls linearly, or quadratically where r -> a): composite m-point Gauss-Legendre on panels
    with edges w = 2^j/L (j = -6, -5, ...), as for the pressure, and w = W (1 - 2^-k), W =
    asin(a/r) (k = 1 ... 40), where the integrand is 1 - O((W - w)^n), singular for small n.
    """
    from hertzmdr.numeric._quadrature import panels

    # W = asin(a/r) as atan2 of the same sqrt(r - a) sqrt(r + a) that the integrand's base
    # uses: asin of the rounded a/r next to 1 would put W past the zero of the base
    top = np.arctan2(a, np.sqrt(r - a) * np.sqrt(r + a))
    cot = np.sqrt(r - a) * np.sqrt(r + a) / a
    lam = n * cot + np.sqrt(n)
    j = 2.0 ** np.arange(-6, 64)
    k = 1 - 2.0 ** -np.arange(1, 41)  # nearer W, 1 + base = sin(W - w)/sin(W) < 1e-12 rounds
    breaks = np.concatenate([j[None, :] / lam[:, None], top[:, None] * k[None, :]], axis=1)
    w, wts = panels(np.zeros(len(r)), top, breaks, m)
    w[wts == 0] = 0.0  # the empty panels of clipped edges (nodes at asin(a/r)): weight 0

    def col(v):
        return v[:, None]

    f = gen.powerlaw_displacement_outside_integrand(col(a), col(d), col(n), col(r), w)
    return np.sum(wts * f, axis=1)


def pressure(r, d, c_n, n, E_star):
    """Contact pressure p(r) [Pa] of a power-law indenter, 0 outside the contact, (5.59).

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in [1e-15, 1000], a in [1e-09,
    1000], n in [1.5, 1e+08], E_star in [0.001, 1e+15], with c_n = d/(kappa_n a^n) for a contact
    radius a in that range (for n > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float)
    (SI units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308):
    OverflowError naming the inputs.

    n = inf is the flat punch of radius a = ``c_n`` (pass the punch radius as c_n then):
    p = E* d/(pi sqrt(a^2 - r^2)). At the centre p is +inf for n <= 1 (the cone's logarithmic
    and the r^(n-1) singularities); at the rim of the punch p is +inf.

    Parameters
    ----------
    r : float or array_like
        Distance from the centre [m], >= 0.
    d : float or array_like
        Depth [m], >= 0 (at d = 0, no load: p = 0 everywhere, the punch's too).
    c_n : float or array_like
        Profile coefficient [m^(1-n)], > 0 (the punch radius [m] for n = inf).
    n : float or array_like
        Exponent, n > 0, or inf. Up to N_PRESSURE_QUADRATURE (40) the closed forms (2F1,
        elementary for n = 1 ... 4, and for n < 3 at r < a/10 the series about the centre,
        powerlaw_pressure_centre); above it (5.59) by Gauss-Legendre quadrature of a smooth
        integrand (``powerlaw_pressure_integrand``), to ~1e-15 at any n.
    E_star : float or array_like
        Effective modulus [Pa], > 0.
    """
    r, d, c_n, n, E_star = np.broadcast_arrays(
        nonnegative("r", r), nonnegative("d", d), positive("c_n", c_n),
        positive("n", n, allow_inf=True), positive("E_star", E_star))
    out = np.zeros(r.shape)
    punch = np.isinf(n)
    a = np.where(punch, c_n, 0.0)
    fin = ~punch
    a[fin] = contact_radius(d[fin], c_n[fin], n[fin])
    inside = r < a
    sel = inside & punch
    with np.errstate(divide="ignore"):
        out[sel] = gen.powerlaw_punch_pressure(E_star[sel], a[sel], d[sel], r[sel])
    sel = inside & fin
    out[sel] = _pressure_at(r[sel], a[sel], d[sel], n[sel], E_star[sel])
    return result(out)


def pressure_normalized(r_tilde, n):
    """p/p_mean [1] at r_tilde = r/a (Fig. 5.17), 0 for r_tilde >= 1.

    Guaranteed finite and accurate for r_tilde in {0} U [1e-12, 1e+300], n in [1.5, 1e+08] (SI
    units; searched by tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError
    naming the inputs.

    Parameters
    ----------
    r_tilde : float or array_like
        Normalized radius r/a, >= 0.
    n : float or array_like
        Exponent, > 0, may be inf (flat punch: 1/(2 sqrt(1 - r_tilde^2))).
    """
    rt, n = np.broadcast_arrays(nonnegative("r_tilde", r_tilde), positive("n", n, allow_inf=True))
    # p/p_mean for a = 1, d = 1, E* = 1: p_mean = F/(pi a^2) from (5.57) (the punch's for
    # n = inf)
    nn = np.where(np.isinf(n), 1.0, n)
    p_mean = np.where(np.isinf(n), gen.powerlaw_punch_mean_pressure(1.0, 1.0, 1.0),
                      gen.powerlaw_mean_pressure(1.0, 1.0, 1.0, nn))
    c = np.where(np.isinf(n), 1.0, 1.0 / kappa(nn))  # a = 1 at d = 1
    p = pressure(rt, 1.0, c, n, 1.0)
    return result(p / p_mean)


@representable
def surface_displacement(r, d, c_n, n):
    """Surface displacement u_z(r) [m]: d - c_n r^n inside, (5.60) outside the contact.

    Guaranteed finite and accurate for r in {0} U [1e-300, 1e+300], d in [1e-15, 1000], a in [1e-09,
    1000], n in [0.001, 1e+08], with c_n = d/(kappa_n a^n) for a contact radius a in that range (for
    n > 24 within exp(+-500/n) of 1 m, so that kappa_n c_n is a float) (SI units; searched by
    tests/domain_search.py). Beyond float64 (|result| > 1.8e308): OverflowError naming the inputs.

    n = inf is the flat punch of radius ``c_n`` (inside: u_z = d).

    Parameters
    ----------
    r : float or array_like
        Distance from the centre [m], >= 0.
    d, c_n, n
        As in :func:`pressure`.
    """
    r, d, c_n, n = np.broadcast_arrays(nonnegative("r", r), positive("d", d),
                                       positive("c_n", c_n), positive("n", n, allow_inf=True))
    punch = np.isinf(n)
    a = np.where(punch, c_n, 0.0)
    fin = ~punch
    a[fin] = contact_radius(d[fin], c_n[fin], n[fin])
    out = np.empty(r.shape)
    inside = r <= a  # the rounded a that the outside forms take: a/r <= 1 there
    sel = inside & fin
    out[sel] = d[sel] - c_n[sel] * r[sel] ** n[sel]
    out[inside & punch] = d[inside & punch]
    # the 2F1 form subtracts two terms with a sqrt(r - a) singularity: next to the edge it
    # loses eps/sqrt(1 - a/r) (1e-7 at r = a(1 + 1e-15)), and for n > 40 SciPy's 2F1 fails
    quad = (n > N_PRESSURE_QUADRATURE) | (r < a * (1 + EDGE_QUADRATURE))
    far = ~inside & fin & ~quad & (a < r * FAR_SERIES)
    # (a/r)^2 of the 2F1 form underflows beyond r ~ 1e154 a (5e-4 off at 1e160 m for a = 1 m):
    # the far-field series, whose r^2 may overflow to inf harmlessly (its terms then are 0)
    with np.errstate(over="ignore"):
        out[far] = gen.powerlaw_displacement_far(a[far], d[far], n[far], r[far])
    sel = ~inside & fin & ~quad & ~far
    s = pow2_scale(r[sel])  # homogeneous of degree 1 in (a, d, r): in units of s ~ r (a power
    out[sel] = s * gen.powerlaw_displacement_outside(  # of 2, exact), (a/r)^2 cannot overflow
        a[sel] / s, d[sel] / s, n[sel], r[sel] / s)
    sel = ~inside & fin & quad  # (5.60) by quadrature of a positive, smooth integrand
    if sel.any():
        out[sel] = _displacement_quadrature(r[sel], a[sel], d[sel], n[sel])
    sel = ~inside & punch
    out[sel] = gen.powerlaw_punch_displacement_outside(a[sel], d[sel], r[sel])
    return result(out)
