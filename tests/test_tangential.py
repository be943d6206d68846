"""Tangential contact by the MDR (numeric/tangential.py, derive/tangential.py) by independent
routes: the Cattaneo-Mindlin and Mindlin-Deresiewicz forms of the literature at 30+ digits, the
springs' sums by mpmath quadrature, the 3-D route through Cerruti's kernel (tests/kernels.py),
the loop area, the cubic law, and the history solver's convergence against the closed forms.

The literature forms (Johnson, Contact Mechanics, section 7.2 and (7.59)) are written with the
tangential compliance of the pair, 3 mu F/(16 a) (sum (2 - nu_i)/G_i) = 3 mu F/(4 a G*), i.e.
(2 - nu)/G -> 4/G* for one elastic body on a rigid one.
"""

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import hertz
from hertzmdr.numeric import tangential as tg

from kernels import ux_cerruti_axisymmetric
from oracle import FULL, assert_close

E_STEEL, NU_STEEL = 210e9, 0.3
E_STAR = E_STEEL / (2 * (1 - NU_STEEL**2))  # two steel bodies (5.26)
G_STEEL = E_STEEL / (2 * (1 + NU_STEEL))
G_STAR = 1 / (2 * (2 - NU_STEEL) / (4 * G_STEEL))
R, F_N, MU = 0.01, 100.0, 0.6


def _sphere():
    a = float(hertz.contact_radius_from_force(F_N, R, E_STAR))
    return tg.Contact(tg.Paraboloid(R), a, E_STAR, G_STAR, MU)


def test_tangential_modulus_from_the_cerruti_compliance():
    """G* of two bodies against the Popov-Hess/Johnson compliance sum (typed here, 30 digits),
    for nu1 != nu2 and a rigid partner; G = E/(2(1 + nu)); G*/E* of one body = 2(1-nu)/(2-nu)
    from the two compliances; the generated direction average is checked in test_cerruti."""
    for G1, nu1, G2, nu2 in ((80e9, 0.3, 26e9, 0.45), (1e6, 0.49, 3e9, -0.2), (5e9, 0.1, np.inf,
                                                                                   0.3)):
        got = float(tg.effective_modulus(G1, nu1, G2, nu2))
        with mp.workdps(30):
            comp = (2 - mp.mpf(nu1)) / (4 * mp.mpf(G1))
            if np.isfinite(G2):
                comp += (2 - mp.mpf(nu2)) / (4 * mp.mpf(G2))
            assert_close(got, 1 / comp, 4e-16, "G*")  # a few roundings
    with mp.workdps(30):
        for E, nu in ((210e9, 0.3), (3e6, 0.49), (1e9, -0.5)):
            assert_close(float(tg.shear_modulus(E, nu)), mp.mpf(E) / (2 * (1 + mp.mpf(nu))),
                         3e-16, "G")
            # one elastic body: E* = E/(1 - nu^2), G* = 4 G/(2 - nu)
            ref = (4 * mp.mpf(E) / (2 * (1 + mp.mpf(nu))) / (2 - mp.mpf(nu))) / (
                mp.mpf(E) / (1 - mp.mpf(nu) ** 2))
            assert_close(float(tg.stiffness_ratio(nu)), ref, 5e-16, "G*/E*")
    with pytest.raises(ValueError, match="G1 = G2 = inf"):
        tg.effective_modulus(np.inf, 0.3, np.inf, 0.3)
    with pytest.raises(ValueError, match="nu2"):
        tg.effective_modulus(1e9, 0.3, 1e9, 0.7)


def test_cattaneo_mindlin_literature():
    """Sphere: c = a (1 - F_x/(mu F))^(1/3), delta = 3 mu F/(4 a G*) (1 - (1 - F_x/(mu F))^(2/3))
    and its inverse, at 40 digits, from F_x = 1e-12 mu F (stable forms) to mu F; >= 13 digits."""
    ct = _sphere()
    a, F = ct.a, ct.normal_force
    xs = np.array([1e-12, 1e-8, 1e-4, 0.01, 0.3, 0.5, 0.9, 0.999, 1 - 1e-9, 1.0])
    Fx = xs * MU * F
    u = ct.displacement(Fx)
    c = ct.stick_radius_from_force(Fx)
    with mp.workdps(40):
        for i, F_x in enumerate(Fx):
            X = mp.mpf(F_x) / (MU * mp.mpf(F))
            aa, ff = mp.mpf(a), mp.mpf(F)
            delta = 3 * MU * ff / (4 * aa * G_STAR) * (1 - (1 - X) ** (mp.mpf(2) / 3))
            # 1e-13 plus the conditioning near sliding: mu F is rounded (eps), and c ~ (1 -
            # x)^(1/3), delta ~ 1 - (1 - x)^(2/3) amplify it by 1/(3 (1 - x)) and 1/(1 - x)^(1/3)
            # (at x = 1 the rounding of mu F enters as eps^(2/3) ~ 4e-11)
            cond = 4 * 2.2e-16 / (1 - xs[i]) if xs[i] < 1 else 1e-10
            assert_close(u[i], delta, 1e-13 + cond, f"delta at x = {xs[i]}")
            if xs[i] < 1:
                assert_close(c[i], aa * (1 - X) ** (mp.mpf(1) / 3), 1e-13 + cond, "c(F_x)")
    # F_x(u) and c(u) from the displacement, against the inverse of delta(F_x) (40 digits)
    us = np.array([1e-14, 1e-9, 1e-3, 0.2, 0.7, 0.99999]) * ct.slide_onset
    got_F, got_c = ct.force(us), ct.stick_radius(us)
    with mp.workdps(40):
        ds = 3 * MU * mp.mpf(F) / (4 * mp.mpf(a) * G_STAR)  # delta at sliding onset
        for i, uu in enumerate(us):
            X = 1 - (1 - mp.mpf(uu) / ds) ** mp.mpf(1.5)
            assert_close(got_F[i], MU * mp.mpf(F) * X, 1e-13, "F_x(u)")
            # c ~ sqrt(1 - u/delta_s): its condition number 1/(2 (1 - u/delta_s))
            assert_close(got_c[i], mp.mpf(a) * mp.sqrt(1 - mp.mpf(uu) / ds),
                         1e-13 + 4 * 2.2e-16 / (1 - uu / ct.slide_onset), "c(u)")
    assert ct.slide_onset == pytest.approx(float(3 * MU * F / (4 * a * G_STAR)), rel=1e-14)
    assert ct.force(2 * ct.slide_onset) == ct.sliding_force  # beyond the onset: mu F
    assert ct.force(-0.5 * ct.slide_onset) == -ct.force(0.5 * ct.slide_onset)
    assert ct.stick_radius(3 * ct.slide_onset) == 0.0


def _md_literature(F_amp, F, a, mu, G_star):
    """Mindlin-Deresiewicz (Johnson (7.59)), (2 - nu)/G -> 4/G*."""
    X = min(mp.mpf(F_amp) / (mu * mp.mpf(F)), 1)  # 1: at sliding (mu F rounded in float)
    return (9 * mu**2 * mp.mpf(F) ** 2 / (10 * mp.mpf(a)) * 4 / G_star
            * (1 - (1 - X) ** (mp.mpf(5) / 3) - 5 * X / 6 * (1 + (1 - X) ** (mp.mpf(2) / 3))))


def test_mindlin_deresiewicz_energy():
    """Energy per cycle of the sphere against Mindlin-Deresiewicz at 60 digits (the bracket
    cancels like x^3: 36 digits are lost at x = 1e-12), from x = 1e-12 to 1; >= 13 digits."""
    ct = _sphere()
    xs = np.array([1e-12, 1e-7, 1e-3, 0.05, 0.3, 0.5, 0.8, 0.99, 1.0])
    W = ct.energy(xs * ct.sliding_force)
    with mp.workdps(60):
        for i, x in enumerate(xs):
            ref = _md_literature(x * ct.sliding_force, ct.normal_force, ct.a, MU, G_STAR)
            assert_close(W[i], ref, 1e-13, f"W at x = {x}")
            # 1e-13: the stable form (1 - c/a)^3 P(c/a) loses nothing to cancellation


def test_cubic_small_amplitude_law():
    """W -> F_amp^3/(3 (n+1) G* a mu F) (sphere: F_amp^3/(9 G* a mu F)) with relative
    correction O(F_amp/(mu F)): at x = 1e-10 the energy equals its cubic term to 1e-9, and
    W(x)/x^3 is flat to rounding over x = 1e-15 .. 1e-9 (no cancellation)."""
    for prof in (tg.Paraboloid(R), tg.Cone(0.2), tg.PowerLaw(3e5, 3.0), tg.PowerLaw(40.0, 1.5)):
        ct = tg.Contact(prof, 1e-4, E_STAR, G_STAR, MU)
        x = np.array([1e-15, 1e-13, 1e-11, 1e-9])
        W = ct.energy(x * ct.sliding_force)
        Ws = ct.energy_small(x * ct.sliding_force)
        assert np.all(np.abs(W / Ws - 1) < 2 * x + 1e-13), (prof, W / Ws - 1)
        # 2x: the next term of the series; 1e-13: rounding of the stable forms
    ct = _sphere()
    Fa = 1e-10 * ct.sliding_force
    with mp.workdps(30):
        ref = mp.mpf(Fa) ** 3 / (9 * G_STAR * mp.mpf(ct.a) * MU * mp.mpf(ct.normal_force))
        assert_close(ct.energy_small(Fa), ref, 1e-14, "cubic term")


def _spring_reference(g, a, E_star, G_star, mu, u):
    """F_x(u), c(u) by the springs: g(c) = g(a) - G* u/(mu E*) (findroot), the stuck springs
    G* u each on |x| < c, the sliding ones mu E* (g(a) - g(x)), integrated by mpmath."""
    a, u = mp.mpf(a), mp.mpf(u)
    s = G_star * u / (mu * E_star)
    c = mp.findroot(lambda cc: g(cc) - (g(a) - s), (0, a), solver="anderson")
    slip = mp.quad(lambda x: g(a) - g(x), [c, a])
    return 2 * (G_star * u * c + mu * E_star * slip), c


def test_closed_forms_against_the_spring_quadrature():
    """Cone and power laws (n = 1.5, 3, 6): F_x(u), c(u), and u(F_x) by the springs' sums in
    mpmath (30 digits); >= 13 digits."""
    from hertzmdr.numeric import powerlaw

    a = 2e-4
    cases = [(tg.Cone(0.15), lambda x: mp.pi / 2 * mp.tan(mp.mpf(0.15)) * x)]
    for c_n, n in ((50.0, 1.5), (2e7, 3.0), (1e20, 6.0)):
        k = float(powerlaw.kappa(n)) * c_n
        cases.append((tg.PowerLaw(c_n, n), lambda x, k=k, n=n: mp.mpf(k) * x ** mp.mpf(n)))
    for prof, g in cases:
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        us = np.array([1e-6, 0.1, 0.5, 0.9]) * ct.slide_onset
        F, c = ct.force(us), ct.stick_radius(us)
        with mp.workdps(30):
            for i, u in enumerate(us):
                Fr, cr = _spring_reference(g, a, E_STAR, G_STAR, MU, u)
                assert_close(F[i], Fr, 1e-13, f"{prof} F_x")
                # 1e-13: kappa_n (Gamma ratio) and the stable forms, a few roundings each
                assert_close(c[i], cr, 1e-13, f"{prof} c")
        back = ct.displacement(F)
        assert np.allclose(back, us, rtol=2e-13, atol=0)  # inverse: the same conditioning
        cF = ct.stick_radius_from_force(F)
        assert np.allclose(cF, c, rtol=2e-13, atol=0)


def test_initial_stiffness_is_2_G_star_a_for_every_profile():
    """dF_x/du_x at u_x -> 0 is 2 G* a for every profile (all springs stick)."""
    a = 1e-4
    for prof in (tg.Paraboloid(R), tg.Cone(0.3), tg.PowerLaw(1e5, 2.5), tg.FlatPunch(1e-7)):
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        u = 1e-12 * ct.slide_onset
        assert ct.force(u) / u == pytest.approx(2 * G_STAR * a, rel=1e-11)  # O(u/onset)
        assert ct.stiffness == pytest.approx(2 * G_STAR * a, rel=1e-15)


ONSET_PROFILES = (tg.Paraboloid(R), tg.Cone(0.3), tg.PowerLaw(1e5, 2.5), tg.PowerLaw(50.0, 1.5),
                  tg.PowerLaw(1e20, 6.0), tg.FlatPunch(1e-7))


def _normal_force_mp(prof, a):
    """F_N at contact radius a by the literature's forms at 30 digits: Hertz 4 E* a^3/(3R),
    the cone (pi/2) E* a^2 tan(theta), the power law 2n/(n+1) E* kappa_n c_n a^(n+1) with
    kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2), the punch 2 E* a d."""
    a, Es = mp.mpf(a), mp.mpf(E_STAR)
    if isinstance(prof, tg.Paraboloid):
        return 4 * Es * a**3 / (3 * mp.mpf(prof.R)), 2
    if isinstance(prof, tg.Cone):
        return mp.pi / 2 * Es * a**2 * mp.tan(mp.mpf(prof.theta)), 1
    if isinstance(prof, tg.PowerLaw):
        n = mp.mpf(prof.n)
        kap = mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)
        return 2 * n / (n + 1) * Es * kap * mp.mpf(prof.c_n) * a ** (n + 1), n
    return 2 * Es * a * mp.mpf(prof.depth), mp.inf


def test_slide_onset_against_the_normal_force():
    """The onset of sliding is u_x(F_x = mu F_N): mu F_N (n + 1)/(2 n a G*) for f ~ r^n, with
    F_N from the literature's normal force at 30 digits (3 mu F/(4 a G*) for the sphere,
    mu F/(2 a G*) for the punch, n -> inf); the closed form mu E* d/G* is a different route
    (the depth, not the force). >= 14 digits."""
    a = 1e-4
    for prof in ONSET_PROFILES:
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        with mp.workdps(30):
            FN, n = _normal_force_mp(prof, a)
            ref = MU * FN / (2 * mp.mpf(a) * G_STAR) * (1 if n == mp.inf else (n + 1) / n)
            # 1e-14: kappa_n (Gamma ratio, power law) and a few roundings of g(a) and mu E*/G*
            assert_close(ct.slide_onset, ref, 1e-14, f"{prof} onset")
            assert_close(ct.normal_force, FN, 1e-14, f"{prof} F_N")


def test_profiles_g_against_the_mdr_transform():
    """g(x) of the paraboloid and the cone against (5.52), g(x) = |x| int_0^|x| f'(r)/
    sqrt(x^2 - r^2) dr, by mpmath quadrature (tanh-sinh copes with the endpoint singularity)
    at 30 digits, for x of both signs over 8 decades; <= 4e-16 (two or three roundings)."""
    xs = np.array([-3e-3, -1e-6, 0.0, 1e-11, 2e-7, 5e-5, 1e-3])
    for prof, fprime in ((tg.Paraboloid(R), lambda r: r / mp.mpf(R)),
                         (tg.Cone(0.3), lambda r: mp.tan(mp.mpf(0.3))),
                         (tg.Cone(1.5), lambda r: mp.tan(mp.mpf(1.5)))):
        g = np.asarray(prof.g(xs))
        with mp.workdps(30):
            for x, got in zip(xs, g, strict=True):
                ax = abs(mp.mpf(x))
                if ax == 0:
                    assert got == 0
                    continue
                ref = ax * mp.quad(lambda r, fp=fprime, s=ax: fp(r) / mp.sqrt(s * s - r * r),
                                   [0, ax])
                assert_close(got, ref, 4e-16, f"{prof} g({x})")


def test_stick_zone_forms_at_the_onset():
    """At u = onset and one ulp either side (and a few ulp under it), every profile's stick
    radius and force are finite, c = 0 and F_x = mu F_N at and beyond the onset exactly, and
    just under it c and F_x are within their conditioning of the limit: c/a = (1 - u/onset)^(1/n)
    with 1 - u/onset ~ rounding (a few eps) gives c <= a (64 eps)^(1/n), and F_x =
    mu F_N (1 - (1 - u/onset)^((n+1)/n)) rounds to mu F_N to 1e-15. The traction stays finite."""
    eps = np.finfo(float).eps
    a = 1e-4
    for prof in ONSET_PROFILES:
        for mu in (MU, 1e-3, 1.7):
            ct = tg.Contact(prof, a, E_STAR, G_STAR, mu)
            on = ct.slide_onset
            below = [np.nextafter(on, 0), on * (1 - 2 * eps), on * (1 - 8 * eps)]
            us = np.array([on, np.nextafter(on, np.inf), 2 * on] + below)
            for sign in (1, -1):
                c, F = ct.stick_radius(sign * us), ct.force(sign * us)
                assert np.all(np.isfinite(c)) and np.all(np.isfinite(F)), (prof, mu, c, F)
                assert np.all(c[:3] == 0) and np.all(F[:3] == sign * ct.sliding_force), (prof, c)
                if isinstance(prof, tg.FlatPunch):
                    assert np.all(c[3:] == a)  # the punch sticks everywhere until it slides
                    tol = 16 * eps  # F_x = 2 G* a u is linear: 1 - u/onset (8 eps) and rounding
                else:
                    n = {tg.Paraboloid: 2.0, tg.Cone: 1.0}.get(type(prof), getattr(prof, "n", 0))
                    assert np.all((c[3:] >= 0) & (c[3:] <= a * (64 * eps) ** (1 / n))), (prof, c)
                    tol = 1e-15  # (1 - u/onset)^((n+1)/n) < 1e-20: rounding of the form only
                assert np.all(np.abs(F[3:] / (sign * ct.sliding_force) - 1) <= tol), (prof, F)
                # off the axis (the cone's stick-zone form is inf - inf on it: see
                # docs/tangential.md)
                q = ct.traction(np.linspace(0.01 * a, 0.99 * a, 7), sign * us[3])
                assert np.all(np.isfinite(q)), (prof, q)


def _loop_area(ct, F_amp):
    """Area of the Masing loop by mpmath quadrature of the float branches: -4 F* u* + 8 int_0^u*
    F_mono (the loop's two branches F* - 2F((u* -+ u)/2))."""
    ustar = float(ct.displacement(F_amp))
    with mp.workdps(20):
        I = mp.quad(lambda v: float(ct.force(float(v))), [0, ustar / 2, ustar])
        return -4 * F_amp * ustar + 8 * I


def _energy_by_springs(g, a, E_star, G_star, mu, F_amp):
    """W = 8 mu int_c^a q_z (u* - mu q_z/G*) dx: each sliding spring's friction force times
    its slip over a cycle (mpmath; u* from F_x(u*) = F_amp by findroot on the springs' sum)."""
    a = mp.mpf(a)
    onset = mu * E_star * g(a) / G_star  # the last spring slides
    ustar = mp.findroot(lambda u: _spring_reference(g, a, E_star, G_star, mu, u)[0] - F_amp,
                        (0, onset), solver="anderson")
    c = _spring_reference(g, a, E_star, G_star, mu, ustar)[1]

    def qz(x):
        return E_star * (g(a) - g(x))
    return 8 * mu * mp.quad(lambda x: qz(x) * (ustar - mu * qz(x) / G_star), [c, a])


def test_loop_area_equals_the_energy():
    """The energy per cycle equals (1) the area of the Masing loop (quadrature of the branches)
    and (2) the sliding springs' friction force times slip summed over the contact (mpmath),
    at amplitudes 0.05 .. 0.99 mu F, for the sphere, the cone and power laws."""
    from hertzmdr.numeric import powerlaw

    a = 1.5e-4
    cases = [(tg.Paraboloid(R), lambda x: x * x / R),
             (tg.Cone(0.1), lambda x: mp.pi / 2 * mp.tan(mp.mpf(0.1)) * x)]
    for c_n, n in ((300.0, 1.5), (2e9, 4.0)):
        k = float(powerlaw.kappa(n)) * c_n
        cases.append((tg.PowerLaw(c_n, n), lambda x, k=k, n=n: mp.mpf(k) * x ** mp.mpf(n)))
    for prof, g in cases:
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        for x in (0.05, 0.5, 0.7, 0.99):
            Fa = x * ct.sliding_force
            W = float(ct.energy(Fa))
            # 1e-9: the float branches lose ~1e-16 F* u* against a loop of area ~x^3 F* u*,
            # amplified by the -4 F* u* + 8 int cancellation (x = 0.05: ~1e-12)
            assert abs(_loop_area(ct, Fa) - W) <= 1e-9 * W, (prof, x)
            with mp.workdps(25):
                assert_close(W, _energy_by_springs(g, a, E_STAR, G_STAR, MU, Fa), 1e-12,
                             f"{prof} W springs x = {x}")
                # 1e-12: closed form vs quadrature; the power law's switch to its Gauss-
                # Legendre density (x <= 0.25 here) is exact to ~1e-15 for 24 nodes
    assert tg.Contact(tg.FlatPunch(1e-7), a, E_STAR, G_STAR, MU).energy(1.0) == 0.0


# along y (the direction the Cerruti kernel's cos(2 phi) part turns over) with
# HERTZMDR_SWEEP=full; x in every run (each 2-D quadrature costs ~9 s)
@pytest.mark.parametrize("along", ["x", "y"] if FULL else ["x"])
def test_traction_through_cerruti_is_rigid_in_the_stick_zone(along):
    """The MDR's traction (numeric Contact.traction, a sphere and a flat punch) put through
    Cerruti's surface kernel (mpmath, 17 digits) displaces the stick zone rigidly by u_x: at a
    point on the x or y axis inside the stick zone u_x(3-D) = u_x(MDR) to >= 15 digits.
    One elastic body (nu = 0.3) on a rigid one: G* = 4 G/(2 - nu). (The cos(2 phi) part of the
    Cerruti kernel, which the MDR's springs leave out, cancels between p(r; a) and p(r; c).)"""
    G, nu = 1.0e9, 0.3
    Gs = 4 * G / (2 - nu)
    Es = 2 * G * (1 + nu) / (1 - nu**2)
    a, Rs, mu = 1e-3, 0.05, 0.5
    ct = tg.Contact(tg.Paraboloid(Rs), a, Es, Gs, mu)
    u = 0.6 * ct.slide_onset
    c = float(ct.stick_radius(u))
    with mp.workdps(17):
        k = 2 * mu * mp.mpf(Es) / (mp.pi * Rs)  # Hertz: p(r; a) = (2 E*/(pi R)) sqrt(a^2 - r^2)

        def tau(gap):  # gap = a^2 - rho^2: mu (p(rho; a) - p(rho; c)), the MDR's traction
            cg = mp.mpf(c) ** 2 - mp.mpf(a) ** 2 + gap
            return k * (mp.sqrt(gap) - (mp.sqrt(cg) if cg > 0 else 0))

        for rho in (0.0, 0.3 * c, 0.99 * c, 1.01 * c, 0.7 * a):  # the numeric traction is it
            ref = tau(mp.mpf(a) ** 2 - mp.mpf(rho) ** 2)
            assert abs(float(ct.traction(rho, u)) / ref - 1) < 1e-13  # 0.99 c: sqrt(c^2-r^2)
        got = ux_cerruti_axisymmetric(tau, 0.5 * c, a, G, nu, along=along, rho_splits=(c,))
    assert abs(got / u - 1) < 1e-14  # 17-digit quadrature
    # flat punch: q = G* u/(pi sqrt(a^2 - r^2)), all stuck
    pt = tg.Contact(tg.FlatPunch(1e-6), a, Es, Gs, 0.5)
    u = 0.5 * pt.slide_onset
    with mp.workdps(17):
        got = ux_cerruti_axisymmetric(lambda gap: Gs * u / (mp.pi * mp.sqrt(gap)), 0.7 * a, a,
                                      G, nu, along=along)
    assert abs(got / u - 1) < 1e-14
    assert float(pt.traction(0.7 * a, u)) == pytest.approx(
        Gs * u / (np.pi * np.sqrt(a * a - (0.7 * a) ** 2)), rel=1e-15)


def _cycle(ct, F_amp, steps):
    ustar = float(ct.displacement(F_amp))
    up = np.linspace(0, ustar, steps + 1)  # state 0: the normal load alone
    down = np.linspace(ustar, -ustar, 2 * steps + 1)[1:]
    back = np.linspace(-ustar, ustar, 2 * steps + 1)[1:]
    return np.concatenate([up, down, back]), ustar


def test_history_solver_follows_masing():
    """Displacement control 0 -> u* -> -u* -> u* on the sphere: F_x on every branch against the
    closed forms (Masing), the energy of the cycle against Mindlin-Deresiewicz, the stick
    radius at the turning point; errors within the solver's own estimate (x 3) and second
    order in the grid spacing. Force control gives back the displacements."""
    ct = _sphere()
    Fa = 30.0
    u, ustar = _cycle(ct, Fa, 100)
    k1, k2 = 100, 300  # the turning point u*, the bottom -u*
    errs = []
    for n_grid in (250, 1000, 4000):
        h = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU,
                       x_max=1.2 * ct.a, normal_force=np.full(u.size, F_N), u_x=u,
                       n_grid=n_grid)
        ref = np.where(np.arange(u.size) <= k1, ct.force(u),
                       np.where(np.arange(u.size) <= k2, Fa - 2 * ct.force((ustar - u) / 2),
                                -Fa + 2 * ct.force((ustar + u) / 2)))
        e_F = np.max(np.abs(h.F_x - ref)) / Fa
        W = h.dissipated[-1] - h.dissipated[k1]
        e_W = abs(W / float(ct.energy(Fa)) - 1)
        e_c = abs(h.stick_radius[k1] / float(ct.stick_radius_from_force(Fa)) - 1)
        errs.append((e_F, e_W, e_c))
        assert np.max(np.abs(h.F_x - ref)) <= h.F_x_error  # the estimate bounds the error
        assert abs(h.dissipated[-1] - h.dissipated[k1] - float(ct.energy(Fa))) <= (
            2 * h.dissipated_error)  # the cycle's energy is a difference of two dissipateds
        assert abs(h.normal_force[-1] / F_N - 1) < 1e-12  # force control of the normal load
    errs = np.array(errs)
    orders = np.log(errs[:-1] / errs[1:]) / np.log(4)
    assert np.all(orders > 1.8), orders  # second order (trapezoid across the edges)
    assert np.all(errs[-1] < [3e-7, 2e-6, 5e-8]), errs[-1]
    # force control: the same cycle in F_x gives u_x back
    Fs = np.concatenate([np.linspace(0, Fa, 101), np.linspace(Fa, -Fa, 201)[1:],
                         np.linspace(-Fa, Fa, 201)[1:]])
    hf = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.2 * ct.a,
                    normal_force=np.full(Fs.size, F_N), F_x=Fs, n_grid=2000)
    assert abs(hf.u_x[100] / ustar - 1) < 2e-6
    assert abs(hf.u_x[300] / ustar + 1) < 2e-6
    assert np.array_equal(hf.F_x, Fs)


def test_history_hard_cases():
    """Proportional loading T = lambda N (lambda < mu, Mindlin-Deresiewicz): no slip,
    u = lambda d E*/G*, c = a, for any steps (springs enter with their share of the step);
    decreasing normal load under a held tangential force: the force stays, u_x grows,
    energy is dissipated, and a force beyond mu F_N is refused naming the step; mu = 0
    slides at once."""
    lam = 0.3
    for N in (np.linspace(0, F_N, 101)[1:], np.geomspace(F_N * 1e-6, F_N, 60)):
        h = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=4e-4,
                       normal_force=N, F_x=lam * N, n_grid=2000)
        d = hertz.depth_from_force(N, R, E_STAR)
        err = np.abs(h.u_x / (lam * d * E_STAR / G_STAR) - 1)
        assert np.max(err[N > 0.1 * F_N]) < 1e-6  # grid: 2e-7 m against a > 0.9e-4 m
        assert abs(h.u_x[-1] - lam * d[-1] * E_STAR / G_STAR) <= h.u_x_error
        assert h.dissipated[-1] == 0.0  # no spring slides: entering springs take their share
        assert np.all(h.stick_radius == h.contact_radius)
    # hold T = 0.3 mu F0, let N fall to 0.35 F0
    Nd = np.concatenate([np.linspace(F_N / 10, F_N, 50), np.full(50, F_N),
                         np.linspace(F_N, 0.35 * F_N, 200)])
    T = np.concatenate([np.zeros(50), np.linspace(0, 0.3 * MU * F_N, 50), np.full(200,
                                                                             0.3 * MU * F_N)])
    h = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=4e-4,
                   normal_force=Nd, F_x=T, n_grid=1000)
    assert np.all(h.F_x[100:] == 0.3 * MU * F_N)
    assert np.all(np.diff(h.u_x[100:]) >= 0) and h.u_x[-1] > 1.5 * h.u_x[99]
    assert np.all(np.diff(h.dissipated) >= 0) and h.dissipated[-1] > 0
    assert np.all(h.stick_radius <= h.contact_radius + 1e-15)
    Nd[-1] = 0.2 * F_N
    with pytest.raises(ValueError, match=r"F_x\[299\] = .* exceeds the sliding force"):
        tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=4e-4,
                   normal_force=Nd, F_x=T, n_grid=200, estimate_error=False)
    h0 = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=0.0, x_max=4e-4,
                    normal_force=[F_N, F_N], u_x=[1e-9, 2e-9], n_grid=100)
    assert np.all(h0.F_x == 0) and np.all(h0.sliding)


def test_contact_hard_cases_and_errors():
    """F_x -> mu F, mu -> 0, mu = 0, and the messages."""
    ct = _sphere()
    on = ct.slide_onset
    assert ct.displacement(ct.sliding_force) == pytest.approx(on, rel=1e-14)
    assert ct.displacement(ct.sliding_force * (1 - 1e-12)) < on
    assert ct.energy(ct.sliding_force) == pytest.approx(
        float(18 * MU**2 * F_N**2 / (5 * ct.a * G_STAR) * (1 - 5 / 6)), rel=1e-14)
    tiny = tg.Contact(tg.Paraboloid(R), ct.a, E_STAR, G_STAR, 1e-12)
    assert tiny.force(1.0) == pytest.approx(1e-12 * ct.normal_force, rel=1e-15)
    assert tiny.energy(0.5 * tiny.sliding_force) == pytest.approx(
        float(ct.energy(0.5 * ct.sliding_force)) * (1e-12 / MU) ** 2, rel=1e-13)
    zero = tg.Contact(tg.Paraboloid(R), ct.a, E_STAR, G_STAR, 0.0)
    assert zero.force(1e-6) == 0 and zero.energy(0.0) == 0 and zero.stick_radius(1e-9) == 0
    with pytest.raises(ValueError, match=r"F_x = 70.0 exceeds the sliding force mu F_N"):
        ct.displacement(70.0)
    with pytest.raises(ValueError, match="mu"):
        tg.Contact(tg.Paraboloid(R), ct.a, E_STAR, G_STAR, -0.1)
    with pytest.raises(ValueError, match="n_points"):
        ct.loop(10.0, 5)
    with pytest.raises(ValueError, match="exactly one of u_x= and F_x="):
        tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1e-3,
                   depth=[1e-6], n_grid=100)
    with pytest.raises(ValueError, match=r"depth\[1\] = .* beyond x_max"):
        tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1e-4,
                   depth=[1e-7, 1e-5], u_x=[0, 1e-9], n_grid=100)


EXAMPLES = __import__("pathlib").Path(__file__).parents[1] / "examples"


def test_fretting_scene_matches_mindlin_deresiewicz():
    """The tour's fretting scene (steel sphere R = 10 mm on a steel flat, 100 N, mu = 0.6,
    +-30 N): stick radius and energy per cycle against Mindlin-Deresiewicz from the scene's
    inputs alone at 40 digits (Hertz's a, Johnson's forms); <= 1e-13."""
    from hertzmdr.numeric import scene

    eff = scene.load(EXAMPLES / "fretting_sphere.toml").run()["effects"]
    with mp.workdps(40):
        E, nu, Rm, F, mu, Fa = (mp.mpf(210e9), mp.mpf("0.3"), mp.mpf("0.01"), mp.mpf(100),
                                mp.mpf("0.6"), mp.mpf(30))
        Es = E / (2 * (1 - nu**2))
        Gs = 1 / (2 * (2 - nu) / (4 * E / (2 * (1 + nu))))
        a = (3 * F * Rm / (4 * Es)) ** (mp.mpf(1) / 3)
        assert_close(eff["stick_radius"]["value"], a * (1 - Fa / (mu * F)) ** (mp.mpf(1) / 3),
                     1e-13, "stick radius")
        assert_close(eff["dissipated_energy"]["value"], _md_literature(Fa, F, a, mu, Gs),
                     1e-13, "energy per cycle")
        assert_close(eff["tangential_displacement"]["value"],
                     3 * mu * F / (4 * a * Gs) * (1 - (1 - Fa / (mu * F)) ** (mp.mpf(2) / 3)),
                     1e-13, "u_x")
        assert_close(eff["sliding_force"]["value"], mu * F, 1e-14, "mu F")
        assert_close(eff["tangential_stiffness"]["value"], 2 * Gs * a, 1e-14, "2 G* a")
    loop = eff["hysteresis_loop"]["value"]
    assert max(loop["F"]) == pytest.approx(30.0, rel=1e-14)
    assert min(loop["F"]) == pytest.approx(-30.0, rel=1e-14)


def test_scene_tangential_errors():
    """Missing friction, a tangential load with a sweep, an amplitude beyond mu F, a loop
    without an oscillating load, a profile without closed forms: each error names its key."""
    from hertzmdr.numeric import scene
    from hertzmdr.numeric.scene.schema import SceneError

    base = {"effects": ["stick_radius"], "load": {"force": "100 N",
                                                  "tangential": {"force": "10 N"}},
            "body": [{"shape": "sphere", "radius": "10 mm", "E": "210 GPa", "nu": 0.3},
                     {"shape": "flat", "E": "210 GPa", "nu": 0.3}]}
    with pytest.raises(SceneError, match="interface.friction: the tangential effects need"):
        scene.load(base).run()
    ok = {**base, "interface": {"friction": 0.6}}
    assert scene.load(ok).run()["effects"]["stick_radius"]["value"] > 0
    with pytest.raises(SceneError, match="interface.friction: must be a number >= 0"):
        scene.load({**base, "interface": {"friction": -1}})
    with pytest.raises(SceneError, match="a tangential load needs a constant normal load"):
        scene.load({**ok, "load": {"force": {"from": 1, "to": 2, "points": 3},
                                   "tangential": {"force": "1 N"}}})
    with pytest.raises(SceneError, match="load.oscillating.amplitude: .* exceeds the sliding"):
        scene.load({**ok, "load": {"force": "100 N", "oscillating": {"amplitude": "70 N"}},
                    "effects": ["dissipated_energy"]}).run()
    with pytest.raises(SceneError, match="needs \\[load\\] oscillating"):
        scene.load({**ok, "effects": ["dissipated_energy"]}).run()
    with pytest.raises(SceneError, match="load.tangential.speed: unknown key"):
        scene.load({**ok, "load": {"force": "1 N", "tangential": {"speed": 1}}})


def test_history_of_a_sampled_profile():
    """The history solver on a sampled paraboloid (mdr.Profile, quintic splines of 301
    samples) reproduces the closed-form cycle within its own error estimate."""
    from hertzmdr.numeric import mdr

    ct = _sphere()
    Fa = 30.0
    r = np.linspace(0, 3e-4, 301)
    prof = mdr.Profile.from_samples(r, r**2 / (2 * R))
    u, ustar = _cycle(ct, Fa, 50)
    h = tg.history(prof, E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.2 * ct.a,
                   normal_force=np.full(u.size, F_N), u_x=u, n_grid=1000)
    assert abs(h.F_x[50] - Fa) <= h.F_x_error
    assert abs(h.dissipated[-1] - h.dissipated[50] - float(ct.energy(Fa))) <= (
        2 * h.dissipated_error)


def test_history_traction():
    """The traction of the history's final state ((5.59) of the springs' line load, abel)
    against Cattaneo's: within 2e-4 of the peak away from the stick edge (4 nodes), within 2 %
    next to it (the square-root cusp there, documented in History.traction)."""
    ct = _sphere()
    ustar = float(ct.displacement(30.0))
    c = float(ct.stick_radius(ustar))
    u = np.linspace(0, ustar, 51)
    h = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.2 * ct.a,
                   normal_force=np.full(u.size, F_N), u_x=u, n_grid=1000,
                   estimate_error=False)
    q, ref = h.traction(), ct.traction(h.x, ustar)
    inside = h.x < 0.98 * ct.a
    band = np.abs(h.x - c) < 4 * (h.x[1] - h.x[0])
    err = np.abs(q - ref) / ref.max()
    assert np.max(err[inside & ~band]) < 2e-4 and np.max(err[inside]) < 2e-2
    assert np.all(q[h.x >= ct.a * 1.01] == 0)


# -- scenes: a history from a file, and the springs for profiles without closed forms ----------
_STEEL_BODIES = [{"shape": "sphere", "radius": "10 mm", "E": "210 GPa", "nu": 0.3},
                 {"shape": "flat", "E": "210 GPa", "nu": 0.3}]


def _history_scene(tmp_path, text, effects=("tangential_force",), **hist):
    (tmp_path / "h.csv").write_text(text, encoding="utf-8")
    table = {"file": "h.csv", "normal": "force", "tangential": "force", **hist}
    body = "\n".join(
        "[[body]]\n" + "\n".join(f"{k} = {v!r}".replace("'", '"') for k, v in b.items())
        for b in _STEEL_BODIES)
    (tmp_path / "s.toml").write_text(
        f"effects = {list(effects)!r}\n".replace("'", '"') + body
        + "\n[interface]\nfriction = 0.6\n[load]\nhistory = {"
        + ", ".join(f"{k} = {v!r}".replace("'", '"') for k, v in table.items()) + "}\n",
        encoding="utf-8")
    from hertzmdr.numeric import scene

    return scene.load(tmp_path / "s.toml")


def test_scene_history_from_a_file(tmp_path):
    """A history at constant normal force that loads to F_a, then cycles -F_a .. F_a: the
    springs' u_x at the turning points against Cattaneo-Mindlin's and the energy of the cycle
    (total minus the first loading's, which is the cycle's own half of the friction work
    beyond it) against Mindlin-Deresiewicz, within the reported grid errors; units from the
    table; the file's rows are the states."""
    ct = _sphere()
    Fa = 30.0
    Fs = np.concatenate([np.linspace(0, Fa, 41), np.linspace(Fa, -Fa, 81)[1:],
                         np.linspace(-Fa, Fa, 81)[1:]])
    rows = "normal_kN, shear_N  # a header, then the states\n" + "".join(
        f"{F_N / 1e3!r}, {float(F)!r}\n" for F in Fs)
    sc = _history_scene(tmp_path, rows, effects=["tangential_displacement", "dissipated_energy",
                                                 "sliding_force", "hysteresis_loop"],
                        units=["kN", "N"])
    assert sc.spec.load.values == pytest.approx([F_N] * Fs.size, rel=1e-15)
    eff = sc.run()["effects"]
    u = np.asarray(eff["tangential_displacement"]["value"])
    err = eff["tangential_displacement"]["rel_error"] * np.max(np.abs(u))
    ustar = float(ct.displacement(Fa))
    assert abs(u[40] - ustar) <= err and abs(u[120] + ustar) <= err
    assert abs(u[200] - ustar) <= err
    assert 0 < err < 1e-5 * ustar  # 1000 intervals, second order
    W = eff["dissipated_energy"]["value"]
    first = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU,
                       x_max=float(1.25 * ct.a), normal_force=np.full(41, F_N), F_x=Fs[:41],
                       n_grid=1000, estimate_error=False).dissipated[-1]
    W_md = float(ct.energy(Fa))
    assert abs(W - first - W_md) <= 2 * eff["dissipated_energy"]["rel_error"] * W + 1e-9 * W_md
    assert eff["sliding_force"]["value"] == pytest.approx([MU * F_N] * Fs.size, rel=1e-5)
    assert len(eff["hysteresis_loop"]["value"]["u"]) == Fs.size


def test_scene_history_errors(tmp_path):
    """Every bad history ends in one line naming the key and, for a row, the file and line."""
    from hertzmdr.numeric import scene
    from hertzmdr.numeric.scene.schema import SceneError

    cases = [
        ("0, 0\n1, 2, 3\n", {}, r"load.history.file: h.csv line 2: expected two numbers"),
        ("n, t\nx, y\n1, 2\n", {}, r"line 2: expected two numbers"),
        ("0, 0\n", {}, r"h.csv has 1 state\(s\); a history needs at least two"),
        ("0, 0\n-5, 0\n", {}, r"h.csv line 2: the normal force -5.0 is below 0"),
        ("0, 0\n1e308, 0\n", {"units": ["kN", "N"]}, r"line 2: the values must be finite"),
        ("0, 0\n100, 0\n", {"units": ["nm", "N"]}, r"load.history.units\[0\]: "),
        ("0, 0\n100, 0\n", {"units": "N"}, r"load.history.units: must be a list of two"),
        ("0, 0\n100, 0\n", {"normal": "pressure"}, r"load.history.normal: must be \"depth\""),
        ("0, 0\n100, 0\n", {"tangential": "speed"}, r"load.history.tangential: must be"),
        ("0, 0\n100, 0\n", {"control": "x"}, r"load.history.control: unknown key"),
        ("0, 0\n100, 0\n100, 70\n", {}, r"load.history: F_x of h.csv line 3 = 70.0 N exceeds "
                                       r"the sliding force"),
    ]
    for text, hist, match in cases:
        with pytest.raises(SceneError, match=match) as info:
            _history_scene(tmp_path, text, **hist).run()
        assert "\n" not in str(info.value)
    with pytest.raises(SceneError, match="load.history.file: history file .* not found"):
        scene.load({"effects": ["force"], "body": _STEEL_BODIES,
                    "load": {"history": {"file": "nowhere.csv", "normal": "force",
                                         "tangential": "force"}}})
    with pytest.raises(SceneError, match="give history alone, not with force"):
        scene.load({"effects": ["force"], "body": _STEEL_BODIES,
                    "load": {"force": "1 N", "history": {"file": "h.csv"}}})
    with pytest.raises(SceneError, match="load.history.file: missing"):
        scene.load({"effects": ["force"], "body": _STEEL_BODIES,
                    "load": {"history": {"normal": "force", "tangential": "force"}}})


def test_sampled_and_exact_sphere_scenes_run_the_springs():
    """Profiles without a tangential closed form (a sampled paraboloid, an exact sphere at
    a/R = 0.01) run the springs on a grid: the fretting numbers of Mindlin-Deresiewicz within
    the reported errors, which are small; the method says so."""
    from hertzmdr.numeric import scene

    ct = _sphere()
    r = np.linspace(0, 1e-3, 401)
    sampled = {"shape": "profile", "r": list(r), "f": list(r**2 / (2 * R)), "E": "210 GPa",
               "nu": 0.3}
    exact = {"shape": "exact_sphere", "radius": "10 mm", "E": "210 GPa", "nu": 0.3}
    for tip, floor in ((sampled, 0.0), (exact, 1e-4)):  # the exact sphere is not Hertz: a/R
        doc = scene.load({"effects": ["stick_radius", "dissipated_energy", "tangential_force",
                                      "tangential_displacement", "traction_profile",
                                      "hysteresis_loop"],
                          "body": [tip, _STEEL_BODIES[1]], "interface": {"friction": MU},
                          "load": {"force": "100 N",
                                   "oscillating": {"amplitude": "30 N"}}}).run()
        eff = doc["effects"]
        c_ref = float(ct.stick_radius_from_force(30.0))
        for name, ref in (("stick_radius", c_ref), ("dissipated_energy", float(ct.energy(30.0))),
                          ("tangential_displacement", float(ct.displacement(30.0)))):
            got = eff[name]
            assert abs(got["value"] / ref - 1) <= got["rel_error"] + floor, (tip["shape"], name)
            assert got["rel_error"] < 1e-2 and "springs" in got["method"]
        assert eff["tangential_force"]["value"] == pytest.approx(30.0, rel=1e-12)
        q = eff["traction_profile"]["value"]
        ref = ct.traction(np.asarray(q["r"]), float(ct.displacement(30.0)))
        assert np.max(np.abs(q["q"] - ref)) <= (eff["traction_profile"]["rel_error"] + floor) \
            * np.max(np.abs(q["q"]))
        assert eff["hysteresis_loop"]["value"]["F"][-1] == pytest.approx(30.0, rel=1e-12)


def test_dissimilar_poisson_ratios():
    """nu1 != nu2 (steel on a polymer, G*/E* = 0.61 instead of one body's 2 (1 - nu)/(2 - nu)):
    Johnson's Cattaneo-Mindlin with the pair's compliance sum (2 - nu1)/G1 + (2 - nu2)/G2 at
    30 digits, from the closed forms (1e-13) and from the springs' history (within its
    estimate). The MDR leaves out the coupling of normal and tangential loads through Dundurs'
    second constant, as Johnson's forms do."""
    E1, nu1, E2, nu2 = 210e9, 0.3, 3e9, 0.45
    G1, G2 = E1 / (2 * (1 + nu1)), E2 / (2 * (1 + nu2))
    Es = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    Gs = float(tg.effective_modulus(G1, nu1, G2, nu2))
    a = float(hertz.contact_radius_from_force(F_N, R, Es))
    ct = tg.Contact(tg.Paraboloid(R), a, Es, Gs, MU)
    Fx = 0.7 * MU * F_N
    with mp.workdps(30):
        comp = (2 - mp.mpf(nu1)) / mp.mpf(G1) + (2 - mp.mpf(nu2)) / mp.mpf(G2)
        x = mp.mpf(Fx) / (MU * mp.mpf(F_N))
        delta = 3 * MU * mp.mpf(F_N) / (16 * mp.mpf(a)) * comp * (1 - (1 - x) ** (
            mp.mpf(2) / 3))
        assert_close(float(ct.displacement(Fx)), delta, 1e-13, "delta, nu1 != nu2")
        assert_close(float(ct.stick_radius_from_force(Fx)), a * (1 - x) ** (mp.mpf(1) / 3),
                     1e-13, "c, nu1 != nu2")
    h = tg.history(tg.Paraboloid(R), E_star=Es, G_star=Gs, mu=MU, x_max=1.2 * a,
                   normal_force=[F_N, F_N], F_x=[0.0, Fx], n_grid=1000)
    assert abs(h.u_x[-1] - float(delta)) <= h.u_x_error


def _g_mp(prof):
    """g(x) and g'(x) of a closed-form profile at 30 digits: (5.52) of c_n r^n is
    kappa_n c_n x^n, kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2) (the cone n = 1,
    c_n = tan(theta); the paraboloid n = 2, c_n = 1/(2R))."""
    if isinstance(prof, tg.Cone):
        n, cn = mp.mpf(1), mp.tan(mp.mpf(prof.theta))
    elif isinstance(prof, tg.Paraboloid):
        n, cn = mp.mpf(2), 1 / (2 * mp.mpf(prof.R))
    else:
        n, cn = mp.mpf(prof.n), mp.mpf(prof.c_n)
    kap = mp.sqrt(mp.pi) * mp.gamma(n / 2 + 1) / mp.gamma(n / 2 + mp.mpf(1) / 2)
    return (lambda x: kap * cn * x**n), (lambda x: n * kap * cn * x ** (n - 1))


def _traction_mp(prof, a, mu, u, r):
    """(5.59) of the springs' tangential line load, at 30 digits: q_x = mu E* (d - g(x)) for
    the sliding springs |x| > c, constant for the stuck ones, so q_x' = -mu E* g'(x) on
    (c, a) and q(r) = (mu E*/pi) integral_max(r, c)^a g'(x)/sqrt(x^2 - r^2) dx, c from
    g(c) = g(a) - G* u/(mu E*) (u = None: all slide, c = 0). x = r + w^2 takes out the
    1/sqrt at x = r (r > c)."""
    g, gp = _g_mp(prof)
    a, r = mp.mpf(a), mp.mpf(r)
    c = mp.mpf(0)
    if u is not None:
        s = G_STAR * mp.mpf(u) / (mu * E_STAR)
        c = mp.findroot(lambda cc: g(cc) - (g(a) - s), (0, a), solver="anderson")
    if r < c:
        val = mp.quad(lambda x: gp(x) / mp.sqrt((x - r) * (x + r)), [c, a])
    else:
        val = mp.quad(lambda w: 2 * gp(r + w * w) / mp.sqrt(2 * r + w * w),
                      [0, mp.sqrt(a - r)])
    return mu * E_STAR / mp.pi * val, c


def test_sliding_force_is_the_spring_sum_at_full_slip():
    """Coulomb's limit (tg.sliding_force, Contact.sliding_force, the force beyond the onset)
    against the springs all sliding, 2 mu E* integral_0^a (g(a) - g(x)) dx by mpmath at 30
    digits: a few ulp (the normal force's own rounding, ~1e-15, and one product)."""
    a = 1.2e-4
    for prof in (tg.Paraboloid(R), tg.Cone(0.3), tg.PowerLaw(1e5, 2.5), tg.PowerLaw(50.0, 1.5)):
        g, _ = _g_mp(prof)
        for mu in (MU, 1e-3, 1.7):
            ct = tg.Contact(prof, a, E_STAR, G_STAR, mu)
            with mp.workdps(30):
                ref = 2 * mu * E_STAR * mp.quad(lambda x, g=g: g(mp.mpf(a)) - g(x), [0, a])
            assert_close(ct.sliding_force, ref, 2e-15, f"{prof} mu = {mu}")
            assert_close(tg.sliding_force(mu, ct.normal_force), ref, 2e-15, f"{prof}")
            assert ct.force(2 * ct.slide_onset) == ct.sliding_force
    assert tg.sliding_force(0.0, 5.0) == 0 and np.all(tg.sliding_force(0.5, [2.0, 4.0]) ==
                                                       [1.0, 2.0])
    with pytest.raises(ValueError, match="mu"):
        tg.sliding_force(-0.1, 1.0)


def test_traction_against_the_line_load_quadrature():
    """Contact.traction of the cone and power laws (stick superposition and Coulomb's slip
    traction) against (5.59) of the springs' line load by mpmath at 30 digits, in the stick
    and the slip zone, at three displacements. Error model: each pressure is good to a few
    ulp (1e-15 relative, numeric/powerlaw.py), and the stick form mu (p_a - p_c) loses the
    ratio p_a/(p_a - p_c) of it; near the rim a - r carries the rounding of a and r; the
    reference's c is found independently (findroot)."""
    a = 1.2e-4
    for prof in (tg.Cone(0.3), tg.PowerLaw(1e5, 2.5), tg.PowerLaw(50.0, 1.5),
                 tg.PowerLaw(30.0, 3.0)):
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        g, _ = _g_mp(prof)
        for frac in (0.05, 0.5, 0.95):
            u = frac * ct.slide_onset
            c = float(ct.stick_radius(u))
            for r in (0.2 * c, 0.7 * c, 0.99 * c, c + 0.3 * (a - c), c + 0.9 * (a - c)):
                with mp.workdps(30):
                    ref, _ = _traction_mp(prof, a, MU, u, r)
                    # the slip traction at r: the cancellation's scale in the stick zone
                    p_a, _ = _traction_mp(prof, a, MU, None, r)
                # near the rim the pressure's a (recomputed from d = g(a)) and r carry
                # rounding eps a into a - r: relative eps a/(a - r) for p ~ sqrt(a - r)
                tol = 8e-15 * float(abs(p_a / ref)) + 4e-15 + 8 * 2.0**-52 * a / (a - r)
                assert_close(ct.traction(r, u), ref, tol, f"{prof} u/onset = {frac}, r = {r}")


def test_cone_traction_on_and_near_the_axis():
    """The cone's stick-zone traction at r = 0, 1e-300 and 1e-8 c (it was NaN on the axis:
    the difference of two pressures each log-infinite there) against (5.59) of the line load
    by mpmath at 30 digits; on the axis the limit mu E* tan(theta)/2 ln(a/c). Also for c -> a
    (u = 1e-6 of the onset). Error model: the log1p form takes ~10 roundings, each eps
    relative, into an argument of condition <= 1: 32 eps."""
    a, eps = 1.2e-4, np.finfo(float).eps
    for theta in (0.3, 1e-3, 1.4):
        prof = tg.Cone(theta)
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        for frac in (1e-6, 0.3, 0.999):
            u = frac * ct.slide_onset
            c = float(ct.stick_radius(u))
            for r in (0.0, 1e-300, 1e-8 * c):
                q = ct.traction(r, u)
                assert np.isfinite(q), (theta, frac, r, q)
                with mp.workdps(30):
                    cm, am, rm = mp.mpf(c), mp.mpf(a), mp.mpf(r)
                    # the line load's (5.59) with the numeric c (the traction's input)
                    ref = (MU * E_STAR / mp.pi * mp.pi / 2 * mp.tan(mp.mpf(theta))
                           * mp.quad(lambda x, rm=rm: 1 / mp.sqrt((x - rm) * (x + rm)),
                                     [cm, am]))
                    if r == 0:
                        assert abs(ref / (MU * E_STAR * mp.tan(mp.mpf(theta)) / 2
                                          * mp.log(am / cm)) - 1) < mp.mpf(10) ** -25
                assert_close(q, ref, 32 * eps, f"theta {theta}, u/onset {frac}, r = {r}")
            # and the signed traction for u < 0
            assert ct.traction(0.0, -u) == -ct.traction(0.0, u)


def test_profiles_against_their_g_by_5_53():
    """paraboloid_profile, cone_profile and powerlaw_profile are the profiles whose g are
    paraboloid_g, cone_g and powerlaw_g: f(r) = (2/pi) integral_0^r g(x)/sqrt(r^2 - x^2) dx
    (5.53) of the generated g, by mpmath at 30 digits (x = r sin(phi) takes out the
    endpoint): a few ulp of the float64 profile."""
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import powerlaw

    cases = [(gen.paraboloid_profile, (R,), lambda x: gen.paraboloid_g(R, x)),
             (gen.cone_profile, (0.3,), lambda x: gen.cone_g(0.3, x))]
    for n, cn in ((2.5, 1e5), (1.5, 50.0), (6.0, 1e20)):
        kap = float(powerlaw.kappa(n))
        cases.append((gen.powerlaw_profile, (cn, n),
                      lambda x, cn=cn, n=n, kap=kap: gen.powerlaw_g(cn, kap, n, x)))
    for f, args, g in cases:
        for rr in (1e-6, 3e-5, 1.2e-4):
            with mp.workdps(30):
                ref = 2 / mp.pi * mp.quad(lambda ph, rr=rr, g=g: mp.mpf(float(
                    g(float(rr * mp.sin(ph))))), [0, mp.pi / 2])
            # the quadrature of the float64 g: its rounding (a few ulp) and kappa_n's
            assert_close(f(*args, rr), ref, 1e-14, f"{f.__name__}{args} r = {rr}")


def test_normal_line_load_against_the_normal_force():
    """mdr_normal_line_load (5.58) integrated over the contact -a < x < a at d = g(a) is the
    Hertz force 4/3 E* sqrt(R) d^(3/2) (typed here) for the paraboloid g = x^2/R and the flat
    punch's 2 E* a d for g = 0 (mpmath's tanh-sinh quadrature at 30 digits of the float
    function: its rounding, a few eps, is the error); and mdr_depth_of_line_load inverts it."""
    E, R = 7.3e10, 0.0125
    for a in (1e-7, 3e-4, 2e-2):
        d = a * a / R
        with mp.workdps(30):
            q = mp.quad(lambda x, d=d: gen.mdr_normal_line_load(E, d, float(x * x) / R), [0, a])
            hertz = mp.mpf(4) / 3 * E * mp.sqrt(R) * mp.mpf(d) ** 1.5
            # the integrand's rounding (3 operations, cancelling near the edge x -> a where
            # the line load -> 0, which weighs little): 8 eps
            assert abs(2 * q / hertz - 1) < 8 * 2.0**-52
        punch = 2 * a * gen.mdr_normal_line_load(E, d, 0.0)
        assert abs(punch / (2 * a * E * d) - 1) < 2 * 2.0**-52
    rng = np.random.default_rng(5)
    g = 10.0 ** rng.uniform(-12, 0, 50)
    d = g * (1 + 10.0 ** rng.uniform(-6, 2, 50))
    back = gen.mdr_depth_of_line_load(E, g, gen.mdr_normal_line_load(E, d, g))
    # the rounding of d - g, of the product and quotient by E* (each relative to d - g <= d)
    # and of the sum g + q_z/E*: <= 4 eps of d
    assert np.all(np.abs(back / d - 1) < 6 * 2.0**-52)


def test_powerlaw_traction_on_and_near_the_axis():
    """The power law's stick-zone traction at r = 0, 1e-300 and 1e-8 c, and out to the edge of
    its axis series (c/2), and (for c >= 2a/3, where the two pressures cancel to 1 - c/a)
    out to the stick edge (0.7 c, 0.99 c, c (1 - 1e-9): Gauss-Legendre in sqrt(x^2 - r^2)),
    against
    (5.59) of the line load, mu (E*/pi) n kappa_n c_n integral_c^a x^(n-1)/sqrt(x^2 - r^2) dx,
    by mpmath at 30 digits (kappa_n from its Gamma functions). For n <= 1 each pressure is
    infinite on the axis (it was NaN there); the limit on the axis is finite,
    mu E* n kappa_n c_n (a^(n-1) - c^(n-1))/(pi (n - 1)) (checked). n = 1 is the cone's form.
    Error model: the series' terms are positive and fall at least 4-fold (for r <= c/2); each
    takes ~6 roundings, the Horner sum and the prefactor ~8 more, each eps relative: 32 eps
    (the part of the series left out is below 1e-16 of it); the quadrature's sum of 24
    positive terms likewise (its truncation error is below 1e-25 there)."""
    a, eps = 1.2e-4, np.finfo(float).eps
    for n in (0.2, 0.6, 0.999, 1.0, 1.5, 2.5, 4.0):
        c_n = 1e-6 / a**n  # a depth of about 1 um at a
        prof = tg.PowerLaw(c_n, n)
        ct = tg.Contact(prof, a, E_STAR, G_STAR, MU)
        with mp.workdps(30):
            nm = mp.mpf(n)
            kap = mp.sqrt(mp.pi) * mp.gamma(nm / 2 + 1) / mp.gamma(nm / 2 + mp.mpf(1) / 2)
            pref = MU * E_STAR / mp.pi * nm * kap * mp.mpf(c_n)
        for frac in (1e-6, 0.3, 0.999):
            u = frac * ct.slide_onset
            c = float(ct.stick_radius(u))
            edge = (0.7 * c, 0.99 * c, c * (1 - 1e-9)) if c >= 2 * a / 3 else ()
            for r in (0.0, 1e-300, 1e-8 * c, 0.3 * c, 0.5 * c) + edge:
                q = ct.traction(r, u)
                assert np.isfinite(q), (n, frac, r, q)
                with mp.workdps(30):
                    cm, am, rm = mp.mpf(c), mp.mpf(a), mp.mpf(r)

                    def line(x, rm=rm, nm=nm):
                        return x ** (nm - 1) / mp.sqrt((x - rm) * (x + rm))

                    # c/a is as small as 1e-15 (n = 0.2 at 0.999 of the onset): the
                    # interval split at every decade
                    cuts = [cm * 10**k for k in range(int(mp.log10(am / cm)) + 1)] + [am]
                    ref = pref * mp.quad(line, cuts)
                    if r == 0:
                        axis = (pref * mp.log(am / cm) if n == 1 else
                                pref * (am ** (nm - 1) - cm ** (nm - 1)) / (nm - 1))
                        # the closed form cancels like 1 - c/a >= 1e-7 at 30 digits
                        assert abs(ref / axis - 1) < mp.mpf(10) ** -21
                assert_close(q, ref, 32 * eps, f"n {n}, u/onset {frac}, r = {r / c} c")
            assert ct.traction(0.0, -u) == -ct.traction(0.0, u)
        # all springs slide (c = 0): mu p(0; a), infinite on the axis for n <= 1, never NaN
        q0 = ct.traction(0.0, 2 * ct.slide_onset)
        assert (q0 == np.inf) if n <= 1 else np.isfinite(q0), (n, q0)


def test_tangential_line_load_against_the_stiffness():
    """mdr_tangential_line_load q_x = G* w of the springs all stuck at w = u_x, integrated
    over the contact -a < x < a by mpmath (30 digits) is the initial stiffness times u_x,
    2 G* a u_x (typed here; Mindlin's 8 G a/(2 - nu) for one body on a rigid one, the
    Cerruti average); and mdr_tangential_spring_shear inverts it. Rounding: one product (the
    quadrature of a constant is exact), one quotient: 2 eps."""
    for a, u in ((1e-7, 3e-12), (2.5e-4, 1e-8), (1e-2, 4e-6)):
        with mp.workdps(30):
            F = mp.quad(lambda x, u=u: gen.mdr_tangential_line_load(G_STAR, u), [-a, a])
            assert abs(F / (2 * mp.mpf(G_STAR) * a * u) - 1) < 2 * 2.0**-52
    rng = np.random.default_rng(11)
    w = 10.0 ** rng.uniform(-15, -3, 50)
    back = gen.mdr_tangential_spring_shear(G_STAR, gen.mdr_tangential_line_load(G_STAR, w))
    assert np.all(np.abs(back / w - 1) <= 2 * 2.0**-52)


def test_history_with_a_wall_at_the_grid_end():
    """A flat punch as g = 0 on [0, a] with its wall at x_max = a (wall=True): at any depth
    every spring is in contact, F = 2 E* a d and the tangential stiffness is 2 G* a (all
    springs carry the same load: no partial slip in the MDR of a punch), until all slide at
    mu F. Without the wall the same grid is too narrow for any load (its one clear line)."""
    E, G, mu, a = 1e11, 4e10, 0.5, 1e-4
    zero = lambda x: np.zeros_like(np.asarray(x, float))  # noqa: E731
    H = tg.history(zero, E_star=E, G_star=G, mu=mu, x_max=a, normal_force=[10.0, 10.0, 10.0],
                   F_x=[0.0, 2.0, 5.0], n_grid=16, wall=True)
    assert H.depth == pytest.approx(10.0 / (2 * E * a), rel=1e-14, abs=0)
    assert H.contact_radius.tolist() == [a] * 3 and H.stick_radius[1] == a
    assert H.u_x[1] == pytest.approx(2.0 / (2 * G * a), rel=1e-13, abs=0)
    assert H.sliding.tolist() == [False, False, True]  # 5 N = mu F: all slide
    d = tg.history(zero, E_star=E, G_star=G, mu=mu, x_max=a, depth=[1e-6], u_x=[0.0],
                   n_grid=16, wall=True)
    assert d.normal_force[0] == pytest.approx(2 * E * a * 1e-6, rel=1e-14, abs=0)
    with pytest.raises(ValueError, match=r"^normal_force\[0\] = 10\.0 N needs a contact wider "
                                         r"than the grid \(x_max = 0\.0001 m\); valid: a larger "
                                         r"x_max$"):
        tg.history(zero, E_star=E, G_star=G, mu=mu, x_max=a, normal_force=[10.0], F_x=[0.0],
                   n_grid=16)
