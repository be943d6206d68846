"""The quantities of the accuracy report and every way of computing each (see accuracy.py),
each way with the bound of its error model (accuracy.Way.bound).

The models used throughout:

- a closed form evaluated once, in float64 or in mpmath at ``dps`` digits: a few tens of
  operations, each rounded once (relative error at most the unit roundoff u), whose errors add:
  ``ROUNDINGS`` u (:func:`closed_form`); mpmath's quadrature and special functions aim at the
  working precision and get the same;
- a form that cancels (a textbook form): u times the ratio of the cancelling terms to the result,
  the condition of the subtraction, times a small constant; such a way *predicts* its error;
- a truncated series: its first omitted term;
- a quadrature or integrator with a tolerance: the tolerance (a multiple for the global error of
  an integrator), plus the roundings of the float64 sum;
- a rule without an estimate of its own: twice its difference from the same rule with half the
  points (:func:`halving`): where the rule converges geometrically the coarser rule's error is
  far above the finer one's, so the difference is about the coarser error;
- hertzmdr's methods that report an error (``rel_error``, ``*_error``): that report -- so the
  report also shows whether hertzmdr's stated errors bound the true ones.
"""

from __future__ import annotations

from hertzmdr.numeric.accuracy import Quantity, Way


def _steel_pair() -> float:
    """E* (5.26) of two steel bodies, E = 210 GPa and nu = 0.3."""
    from hertzmdr.numeric import bodies

    return float(bodies.effective_modulus(210e9, 0.3, 210e9, 0.3))


E_STEEL = _steel_pair()

#: the roundings of one closed-form evaluation (see the module docstring)
ROUNDINGS = 64


def unit_roundoff(dps: int) -> float:
    """The unit roundoff 2^-prec of mpmath at ``dps`` digits (mpmath's prec for dps: 53 bits,
    float64's, at 15 digits; 103 at 30)."""
    import mpmath as mp

    with mp.workdps(dps):
        return 2.0 ** -mp.mp.prec


def closed_form(dps: int = 15) -> float:
    """The bound of a closed form evaluated once at ``dps`` digits (15: float64)."""
    return ROUNDINGS * unit_roundoff(dps)


FLOAT64 = closed_form(15)  # 7.1e-15


def halving(fine, coarse, floor: float = FLOAT64):
    """The bound of a rule from the same rule with half the points: 2 |fine - coarse| / |fine|
    plus ``floor`` (the roundings of the sum), a function (computed when the report asks)."""
    def bound() -> float:
        f, c = float(fine()), float(coarse())
        return 2 * abs(f - c) / abs(f) + floor
    return bound


def _mp_digits(fn, args, dps):
    """Evaluate an mpmath function at ``dps`` digits."""
    import mpmath as mp

    def run():
        with mp.workdps(dps):
            return +fn(*[mp.mpf(a) for a in args])
    return run


def hertz_force() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp

    E, R, d = E_STEEL, 0.5, 1e-5

    def truth():
        import mpmath as mp

        return gen_mp.hertz_force(mp.mpf(E), mp.mpf(R), mp.mpf(d))

    def ways():
        import math

        import mpmath as mp
        from scipy.integrate import quad

        a = float(gen.hertz_contact_radius(R, d))
        out = [Way("closed form", "float64", lambda: gen.hertz_force(E, R, d), FLOAT64)]
        for eps in (1e-3, 1e-6, 1e-9, 1e-12):
            # QUADPACK's requested relative error, plus the roundings of its sum
            out.append(Way("SciPy quad of the pressure (5.17)", f"epsrel={eps:g}",
                           lambda eps=eps: quad(lambda r: gen.hertz_pressure(E, R, d, r) * 2
                                                * math.pi * r, 0, a, epsrel=eps,
                                                epsabs=0)[0], eps + FLOAT64))
        for dps in (15, 30, 50, 100):
            def mp_quad(dps=dps):
                with mp.workdps(dps):
                    Em, Rm, dm = mp.mpf(E), mp.mpf(R), mp.mpf(d)
                    am = gen_mp.hertz_contact_radius(Rm, dm)
                    return +mp.quad(lambda r: gen_mp.hertz_pressure(Em, Rm, dm, r) * 2 * mp.pi * r,
                                    [0, am])
            out.append(Way("mpmath quad of the pressure (5.17)", f"{dps} digits", mp_quad,
                           closed_form(dps)))
        for dps in (15, 30, 50, 100):
            out.append(Way("closed form in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.hertz_force, (E, R, d), dps), closed_form(dps)))
        return out

    return Quantity("Hertz force F(d)",
                    "Normal force of a steel sphere pair, R = 0.5 m, d = 10 µm: the closed form "
                    "(5.23), and the defining integral of the pressure (5.15) over the contact.",
                    truth, ways)


def hertz_far_displacement() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp

    R, d = 0.5, 1e-5
    a = float(gen.hertz_contact_radius(R, d))  # (5.21)
    r = 1e4 * a

    def truth():
        import mpmath as mp

        return gen_mp.hertz_displacement_outside(mp.mpf(R), mp.mpf(d), mp.mpf(r))

    def ways():
        p0_over_E = float(gen.hertz_max_pressure(1.0, R, d))
        # the textbook form's terms are (r/a)^2 times its result: it loses that factor
        cancels = (r / a) ** 2
        out = [
            Way("stable closed form (hypergeometric)", "float64",
                lambda: gen.hertz_displacement_outside(R, d, r), FLOAT64),
            # the series is taken to float64's precision for r >= 2a (its truncation there is
            # below u), so the roundings alone
            Way("series in a^2/r^2 (the runtime's form for r >= 2a)", "float64",
                lambda: gen.hertz_displacement_outside_series(R, d, r), FLOAT64),
            Way("textbook closed form (Problem 7 b)", "float64",
                lambda: gen.hertz_pressure_displacement_outside(1.0, a, p0_over_E, r),
                4 * unit_roundoff(15) * cancels, predicts=True),
        ]
        for dps in (15, 30, 50):
            out.append(Way("stable closed form in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.hertz_displacement_outside, (R, d, r), dps),
                           closed_form(dps)))
            def textbook(dps=dps):
                import mpmath as mp

                with mp.workdps(dps):
                    Rm, dm = mp.mpf(R), mp.mpf(d)
                    am = gen_mp.hertz_contact_radius(Rm, dm)
                    pm = gen_mp.hertz_max_pressure(1, Rm, dm)
                    return +gen_mp.hertz_pressure_displacement_outside(1, am, pm, mp.mpf(r))
            out.append(Way("textbook closed form in mpmath", f"{dps} digits", textbook,
                           4 * unit_roundoff(dps) * cancels, predicts=True))
        return out

    return Quantity("Hertz surface displacement at r = 1e4 a",
                    "u_z far outside the contact, where the textbook form cancels terms of size "
                    "r/a to leave one of size a/r: the stable form printed by hertzmdr against "
                    "the textbook form, in float64 and in mpmath.", truth, ways)


def kappa_large_n() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp
    from hertzmdr.numeric import powerlaw

    n = 1e3

    def truth():
        import mpmath as mp

        return gen_mp.powerlaw_kappa(mp.mpf(n))

    def ways():
        import warnings

        def ratio():
            with warnings.catch_warnings(), __import__("numpy").errstate(all="ignore"):
                warnings.simplefilter("ignore")
                return gen.powerlaw_kappa(n)
        # Gamma(n/2 + ...) overflows float64 for n > ~340: the ratio is inf/inf (predicted);
        # the series is summed to float64's precision for n >= 40, so the roundings alone
        out = [Way("Gamma ratio (the derived form)", "float64", ratio, float("inf"),
                   predicts=True),
               Way("Stirling series (large-n expansion)", "float64",
                   lambda: gen.powerlaw_kappa_asymptotic(n), FLOAT64),
               Way("numeric.powerlaw.kappa (picks the series above n = 40)", "float64",
                   lambda: powerlaw.kappa(n), FLOAT64)]
        for dps in (15, 30, 50):
            out.append(Way("Gamma ratio in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.powerlaw_kappa, (n,), dps), closed_form(dps)))
        return out

    return Quantity("kappa_n at n = 1000",
                    "The MDR factor of f = c r^n (Problem 7 d). Its Gamma ratio overflows "
                    "float64 beyond n ~ 340 (the ratio becomes inf/inf); the Stirling series "
                    "printed beside it does not.", truth, ways)


def worn_small_depth() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp

    E, R, b = 1e9, 0.1, 1e-3
    d = 1e-6 * b**2 / (2 * R)  # 2 R d/b^2 = 1e-6

    def truth():
        import mpmath as mp

        return gen_mp.worn_force(*(mp.mpf(v) for v in (E, R, b, d)))

    def ways():
        # sqrt(1 + s^2) - 1 = s^2/2 computed from terms of size 1: relative error u / (s^2/2),
        # halved by the square root taken of it: u / s^2, s = 2 R d / b^2 (predicted)
        s2 = (2 * R * d / b**2) ** 2
        out = [Way("stable form (hertzmdr)", "float64", lambda: gen.worn_force(E, R, b, d),
                   FLOAT64),
               Way("the chapter's F(d) (Problem 8)", "float64",
                   lambda: gen.textbook_worn_force(E, R, b, d), 4 * unit_roundoff(15) / s2,
                   predicts=True)]
        for dps in (15, 30, 50):
            out.append(Way("the chapter's F(d) in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.textbook_worn_force, (E, R, b, d), dps),
                           4 * unit_roundoff(dps) / s2, predicts=True))
            out.append(Way("stable form in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.worn_force, (E, R, b, d), dps), closed_form(dps)))
        return out

    return Quantity("worn parabola F(d) at 2Rd/b^2 = 1e-6",
                    "The force of the flattened parabola of Problem 8 just after the flat has "
                    "touched: the chapter's F(d) subtracts 1 from sqrt(1 + s^2) and keeps "
                    "nothing of s^2 = 1e-12 in float64.", truth, ways)


def powerlaw_pressure_large_n() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp
    from hertzmdr.numeric import powerlaw

    E, a, d, n = 1e9, 1e-3, 1e-6, 1001.0
    r = 0.1 * a

    def truth():
        import mpmath as mp

        # (5.59) by tanh-sinh: E* n d/(pi a) integral_0^acosh(a/r) (r cosh(t)/a)^(n-1) dt,
        # split in the layer x = a (1 - k/n) where the integrand lives; scaled to at most 1
        # (mp.quad's tolerance is absolute)
        with mp.workdps(40):
            nn, A, rr = mp.mpf(n), mp.mpf(a), mp.mpf(r)
            pts = [0, *(mp.acosh(A * (1 - k / nn) / rr) for k in (100, 10, 1)),
                   mp.acosh(A / rr)]
            return E * nn * d / (mp.pi * A) * mp.quad(
                lambda t: (rr * mp.cosh(t) / A) ** (nn - 1), pts)

    def ways():
        import numpy as np

        args = [np.atleast_1d(v) for v in (r, a, d, n, E)]

        def gauss(m):
            return lambda: powerlaw._pressure_quadrature(*args[:4], args[4], m=m)[0]
        # SciPy's 2F1 returns NaN here (predicted: the way fails)
        out = [Way("2F1 closed form (SciPy hyp2f1)", "float64",
                   lambda: gen.powerlaw_pressure(E, a, d, n, r), float("inf"), predicts=True)]
        for m in (4, 8, 16):
            out.append(Way("Gauss-Legendre of the (5.59) integrand (hertzmdr: 16)",
                           f"{m} points a panel", gauss(m), halving(gauss(m), gauss(m // 2))))
        for dps in (15, 30):
            out.append(Way("2F1 closed form in mpmath", f"{dps} digits",
                           _mp_digits(gen_mp.powerlaw_pressure, (E, a, d, n, r), dps),
                           closed_form(dps)))
        return out

    return Quantity("power-law pressure, n = 1001, at r = a/10",
                    "The pressure of f = c r^n for large n (towards the flat punch, Fig. 5.17). "
                    "SciPy's 2F1(1, 1 - n/2; 3/2; z) returns NaN near the centre once n > ~340 "
                    "(unless n is even, when the series terminates); "
                    "hertzmdr integrates the derived (5.59) integrand instead.", truth, ways,
                    truth_error=1e-35)  # the truth's 40-digit quadrature


def numerical_mdr_force() -> Quantity:
    import numpy as np

    from hertzmdr.numeric import _generated_mp as gen_mp

    E, c, n, d = 1e9, 1e2, 2.5, 1e-6  # n = 2.5: no spline represents r^2.5 exactly

    def truth():
        import mpmath as mp

        return gen_mp.powerlaw_force(mp.mpf(E), mp.mpf(c), mp.mpf(d),
                                 gen_mp.powerlaw_kappa(mp.mpf(n)), mp.mpf(n))

    def ways():
        from hertzmdr.numeric import mdr, powerlaw

        a = float(powerlaw.contact_radius(d, c, n))
        out = [Way("closed form (Problem 7 d)", "float64", lambda: powerlaw.force(d, c, n, E),
                   FLOAT64)]
        for N in (16, 32, 64, 128, 256, 512):
            r = np.linspace(0, 2 * a, N + 1)
            prof = mdr.Profile.from_samples(r, c * r**n)
            # the loosest rtol the method accepts (mdr.RTOL_RANGE): the samples' own accuracy,
            # no refinement towards a target
            # the bound: the rel_error the method reports with its force
            out.append(Way("numerical MDR of samples", f"{N} samples",
                           lambda prof=prof: prof.solve(depth=d, E_star=E,
                                                        rtol=mdr.RTOL_RANGE[1]).force,
                           lambda prof=prof: prof.solve(depth=d, E_star=E,
                                                        rtol=mdr.RTOL_RANGE[1]).rel_error))
        return out

    return Quantity("power-law force by the numerical MDR",
                    "F(d) of f = c r^2.5 sampled at N + 1 points on [0, 2a] (an AFM tip given as "
                    "samples), by the numerical MDR of numeric/mdr.py, against the closed form.",
                    truth, ways)


def impact_time() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp
    from hertzmdr.numeric import impact, motion

    E, R, v0 = E_STEEL, 0.01, 1.0
    m = float(gen.impact_sphere_mass(R, 7800.0))  # the steel ball of Problem 3

    def truth():
        import mpmath as mp

        return gen_mp.impact_contact_time(mp.mpf(E), mp.mpf(R), mp.mpf(m), mp.mpf(v0))

    def ways():
        out = [Way("closed form (Problem 3)", "float64",
                   lambda: impact.contact_time(v0, R, E, m=m), FLOAT64)]
        for rtol in (1e-4, 1e-7, 1e-10, 1e-13):
            # rtol is the integrator's local tolerance; the global error of this half
            # oscillation (no stiffness, no growth of errors) is a small multiple of it: 10
            # rtol (measured: 0.03 to 0.5 rtol)
            out.append(Way("equation of motion (SciPy DOP853)", f"rtol={rtol:g}",
                           lambda rtol=rtol: motion.integrate(v0, R, E, m, rtol=rtol)
                           .contact_time, 10 * rtol + FLOAT64))
        for dps in (15, 30):
            def quad(dps=dps):
                import mpmath as mp

                with mp.workdps(dps):
                    Em, Rm, mm, vm = (mp.mpf(v) for v in (E, R, m, v0))
                    x0 = gen_mp.impact_max_depth(Em, Rm, mm, vm)
                    # tau = (2 x0/v0) * integral_0^1 dxi / sqrt(1 - xi^(5/2)) (Problem 3); with
                    # t = xi^(5/2) it is (2/5) integral_0^1 t^(-3/5) (1 - t)^(-1/2) dt, split at
                    # 1/2: t = u^5 on the left, 1 - t = v^2 on the right; both are then smooth
                    h = mp.mpf(1) / 2
                    left = mp.quad(lambda u: 2 * u / mp.sqrt(1 - u**5), [0, h ** (mp.mpf(1) / 5)])
                    right = mp.quad(lambda v: 4 * (1 - v * v) ** (-mp.mpf(3) / 5) / 5,
                                    [0, mp.sqrt(h)])
                    return 2 * x0 / vm * (left + right)
            out.append(Way("mpmath quad of the time integral", f"{dps} digits", quad,
                           closed_form(dps)))
        return out

    return Quantity("impact contact time (Problem 3)",
                    "A steel ball (R = 1 cm) hitting a steel wall at 1 m/s: the closed form with "
                    "the exact constant, the integrated equation of motion, and the defining "
                    "time integral by mpmath quadrature.", truth, ways)


def stress_superposition() -> Quantity:
    from hertzmdr.numeric import _generated_mp as gen_mp
    from hertzmdr.numeric import stress

    a, p0, nu, z = 1e-3, 1e9, 0.3, 0.02e-3  # near the surface, where the kernel is sharp

    def truth():
        import mpmath as mp

        return gen_mp.stress_axis_sigma_zz(mp.mpf(a), mp.mpf(p0), mp.mpf(z))

    def ways():
        import numpy as np

        hertz_p = lambda r: p0 * np.sqrt(np.clip(1 - (np.asarray(r) / a) ** 2, 0, None))  # noqa
        def superposed(n_psi, level):
            return lambda: stress.superposed_stress(0.0, 0.0, z, hertz_p, a, nu, n_psi=n_psi,
                                                    level=level)

        def reported(n_psi, level):  # the error the method reports, relative
            def bound():
                sigma, err = superposed(n_psi, level)()
                return float(err[2, 2] / abs(sigma[2, 2]))
            return bound

        out = [Way("closed form (5.48)", "float64",
                   lambda: stress.axis_stresses(z, a, p0, nu)[0], FLOAT64)]
        for n_psi, level in ((8, 2), (16, 3), (32, 4)):
            out.append(Way("superposition of (5.43) over the pressure", f"{n_psi} angles, "
                           f"tanh-sinh level {level}",
                           lambda n_psi=n_psi, level=level: superposed(n_psi, level)()[0][2, 2],
                           reported(n_psi, level)))
        return out

    return Quantity("Hertz sigma_zz on the axis at z = a/50",
                    "sigma_zz (5.48) below a Hertz contact: the closed form against the "
                    "superposition of the point-force field (5.47) at several resolutions (the "
                    "route every non-Hertz pressure takes).", truth, ways)


def adhesive_pull_off() -> Quantity:
    import numpy as np

    from hertzmdr.numeric import _generated_mp as gen_mp

    E, dg, c, n = 3e6, 0.04, 1e9, 2.5  # a soft sample; n = 2.5: no spline is exact

    def truth():
        import mpmath as mp

        return gen_mp.adhesion_powerlaw_pull_off_force_fc(
            mp.mpf(E), mp.mpf(dg), mp.mpf(c), gen_mp.powerlaw_kappa(mp.mpf(n)), mp.mpf(n))

    def ways():
        from hertzmdr.numeric import adhesion, mdr

        shape = adhesion.PowerLaw(c, n)
        a_c = adhesion.AdhesiveContact(shape, E, dg).pull_off("force").contact_radius
        def pull_off(shape_, **kw):
            return lambda: adhesion.AdhesiveContact(shape_, E, dg).pull_off("force", **kw)

        # every way's bound: the rel_error the method reports with its pull-off force
        closed, root = pull_off(shape), pull_off(shape, a_from=100 * a_c)
        out = [Way("closed form (derive/adhesion.py)", "float64", lambda: closed().force,
                   lambda: closed().rel_error),
               Way("bracketed root of the derived dF/da", "float64", lambda: root().force,
                   lambda: root().rel_error)]
        for N in (50, 100, 200, 400):
            r = np.linspace(0, 10 * a_c, N + 1)
            sampled = pull_off(adhesion.Sampled(mdr.Profile.from_samples(r, c * r**n)))
            out.append(Way("numerical MDR of samples, with adhesion", f"{N} samples",
                           lambda sampled=sampled: sampled().force,
                           lambda sampled=sampled: sampled().rel_error))
        return out

    return Quantity("adhesive pull-off force of f = c r^2.5 (force control)",
                    "The pull-off force of an adhesive contact (numeric/adhesion.py): the "
                    "derived closed form, the bracketed root of the derived dF/da, and the "
                    "numerical MDR of the profile sampled on [0, 10 a_c] (an AFM tip given as "
                    "samples).", truth, ways)


def line_stress_near_edge() -> Quantity:
    from hertzmdr.numeric import _generated as gen
    from hertzmdr.numeric import _generated_mp as gen_mp
    from hertzmdr.numeric import line_stress as ls

    b, p0, nu, x, z = 1e-4, 1e9, 0.3, 0.99e-4, 1e-6  # just below the surface by the edge

    def von_mises(sxx, szz, txz, sqrt):
        syy = nu * (sxx + szz)  # plane strain
        return sqrt(((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) / 2 + 3 * txz**2)

    def truth():
        import mpmath as mp

        # Flamant's load (generated) superposed over (5.36) by tanh-sinh, split at the edges
        # and around the field point (the kernel's peak of width z)
        bb, xx, zz, pp = (mp.mpf(v) for v in (b, x, z, p0))
        pts = sorted({-bb, bb, *(xx + w * zz for w in (0, 1, -1, 10, -10)
                                if -bb < xx + w * zz < bb)})
        comps = [mp.quad(lambda s, f=f: pp * mp.sqrt((1 - s / bb) * (1 + s / bb))
                         * f(1, xx - s, zz), pts)
                 for f in (gen_mp.flamant_sigma_xx, gen_mp.flamant_sigma_zz,
                           gen_mp.flamant_tau_xz)]
        return von_mises(*comps, mp.sqrt)

    def ways():
        import numpy as np

        def gauss(n):
            # s = b sin(theta) removes the pressure's square-root edges; n Gauss-Legendre
            # points in theta on each side of the field point
            t, w = np.polynomial.legendre.leggauss(n)
            th0 = np.arcsin(x / b)
            nodes, weights = [], []
            for lo, hi in ((-np.pi / 2, th0), (th0, np.pi / 2)):
                nodes.append(lo + (hi - lo) * (t + 1) / 2)
                weights.append(w * (hi - lo) / 2)
            th, wt = np.concatenate(nodes), np.concatenate(weights)
            s = b * np.sin(th)
            f = p0 * b * np.cos(th) ** 2 * wt  # p(s) ds
            return lambda: von_mises(*(np.sum(f * k(1.0, x - s, z)) for k in (
                gen.flamant_sigma_xx, gen.flamant_sigma_zz, gen.flamant_tau_xz)), np.sqrt)

        # the rule's bound: from half the points, with a floor for the roundings of its sum of
        # 2n terms of both signs, which cancel to about a twentieth of their sizes at this
        # point (measured: 7e-15 at 1024 points, where the rule has converged)
        out = [Way("closed form (derive/line_stress.py)", "float64",
                   lambda: ls.von_mises(x, z, b, p0, nu), FLOAT64)]
        out += [Way("Gauss-Legendre of Flamant's load", f"{n} points a side", gauss(n),
                    halving(gauss(n), gauss(n // 2), floor=1e-13))
                for n in (16, 64, 256, 1024)]
        return out

    return Quantity("line-contact von Mises stress by the contact edge",
                    "(5.50) with the plane-strain sigma_yy at x = 0.99 b, z = 0.01 b under a "
                    "line contact: the closed form of the field against float64 quadrature of "
                    "Flamant's line load over the pressure (the route without a closed form), "
                    "whose kernel peak of width z next to the square-root edge needs many "
                    "points.", truth, ways)


def ellipse_field_slender() -> Quantity:
    from hertzmdr.numeric import ellipse_stress as el

    t = 0.01
    x, y, z = 0.3, 0.4 * t, 0.3 * t  # a = p0 = 1, b = 0.01: under an almost-line contact

    def truth():
        import mpmath as mp

        # sigma_xx/p0 by the superposition of the derived point-force field over the
        # pressure in polar coordinates about the field point, at 22 digits (the 14- and
        # 20-point rules agree to 20 digits): data with its recipe,
        # tests/ellipse_reference.py's superposed_polar_mp (minutes), recomputed by
        # tests/test_ellipse_stress.py::test_slender_point_at_20_digits under the sweep
        return mp.mpf("-0.37873169247983486760")

    def ways():
        def field(r):
            return lambda: el.stresses(x, y, z, 1.0, t, 1.0, 0.3, rtol=r).sigma_xx

        # the method's rtol is relative to p0 (= 1 here): relative to the stress, rtol/|sigma|
        return [Way("Love's form, double-exponential rule for the field integrals",
                    f"rtol={r:g}", field(r),
                    lambda r=r: r / abs(float(field(r)())) + FLOAT64)
                for r in (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14)]

    return Quantity("elliptical-contact sigma_xx off the axis, b/a = 0.01",
                    "The field of an almost-line elliptical contact at (0.3 a, 0.4 b, 0.3 b) "
                    "(numeric/ellipse_stress.py): the accuracy-time trade-off of its "
                    "quadrature of the field integrals, against the 22-digit superposition "
                    "of the point-force field.", truth, ways,
                    # data: the two rules agree to 1e-20 (absolute, p0 = 1) and the 20th
                    # decimal is rounded (5e-21): 1.5e-20 over |sigma_xx| = 0.379 is 4e-20
                    truth_error=5e-20)


def mindlin_energy_small_amplitude() -> Quantity:
    from hertzmdr.numeric import hertz, tangential

    G = float(tangential.shear_modulus(210e9, 0.3))
    G_star = float(tangential.effective_modulus(G, 0.3, G, 0.3))
    R, F, mu = 0.01, 100.0, 0.6  # the tour's fretting sphere
    a = float(hertz.contact_radius_from_force(F, R, E_STEEL))
    Fa = 1e-2 * mu * F  # a small amplitude: the textbook bracket cancels like x^3

    def truth():
        import mpmath as mp

        X = mp.mpf(Fa) / (mp.mpf(mu) * F)
        return (9 * mp.mpf(mu) ** 2 * F**2 / (10 * mp.mpf(a)) * 4 / mp.mpf(G_star)
                * (1 - (1 - X) ** (mp.mpf(5) / 3) - 5 * X / 6 * (1 + (1 - X) ** (mp.mpf(2) / 3))))

    def ways():
        import numpy as np

        ct = tangential.Contact(tangential.Paraboloid(R), a, E_STEEL, G_star, mu)

        def textbook():
            X = Fa / (mu * F)
            return (9 * mu**2 * F**2 / (10 * a) * 4 / G_star
                    * (1 - (1 - X) ** (5 / 3) - 5 * X / 6 * (1 + (1 - X) ** (2 / 3))))

        # the printed bracket subtracts terms of size 1 to leave one of size ~X^3: its error is
        # u times the sum of their sizes over the bracket (the stable form's bracket), times
        # the roundings of the powers and the sums, 16 (predicted)
        X = Fa / (mu * F)
        terms = [1.0, (1 - X) ** (5 / 3), 5 * X / 6, 5 * X / 6 * (1 - X) ** (2 / 3)]
        bracket = float(ct.energy(Fa)) / (9 * mu**2 * F**2 / (10 * a) * 4 / G_star)
        out = [Way("closed form, stable (derive/tangential.py)", "float64",
                   lambda: float(ct.energy(Fa)), FLOAT64),
               Way("Johnson (7.59) as printed", "float64", textbook,
                   16 * unit_roundoff(15) * sum(terms) / abs(bracket), predicts=True),
               # the series of the energy in X: its second term is 2X/3 of the first (derived,
               # tests/test_tangential.py), so the cubic term alone is off by that (predicted)
               Way("cubic term F*^3/(9 G* a mu F)", "float64",
                   lambda: float(ct.energy_small(Fa)), X, predicts=True)]
        path = np.concatenate([np.linspace(0, Fa, 11), np.linspace(Fa, -Fa, 21)[1:],
                               np.linspace(-Fa, Fa, 21)[1:]])
        def run(n, estimate):
            return tangential.history(tangential.Paraboloid(R), E_star=E_STEEL,
                                      G_star=G_star, mu=mu, x_max=1.2 * a,
                                      normal_force=np.full(path.size, F), F_x=path,
                                      n_grid=n, estimate_error=estimate)

        def reported(n):
            # the solver's estimate of the grid error of the cumulative work, at both ends
            # of the cycle, relative to the cycle's work
            def bound():
                h = run(n, True)
                return 2 * h.dissipated_error / abs(float(h.dissipated[-1] - h.dissipated[10]))
            return bound

        # up to 4000 intervals: the solver's estimate (a second run, and the traction of both
        # by the Abel transform, quadratic in n) costs 2 s there and 34 s on 16000
        for n in (1000, 2000, 4000):
            def springs(n=n):
                h = run(n, False)
                return float(h.dissipated[-1] - h.dissipated[10])
            out.append(Way("the MDR's springs on a grid (history solver)",
                           f"{n} intervals", springs, reported(n)))
        return out

    return Quantity("Mindlin-Deresiewicz energy per cycle at F* = 0.01 mu F",
                    "The energy dissipated per cycle of a tangential force oscillating with a "
                    "small amplitude under a sphere (numeric/tangential.py): the stable closed "
                    "form, the textbook form (its bracket cancels like x^3), the leading cubic "
                    "term, and the history solver's springs on grids of three sizes.",
                    truth, ways)


def all_quantities() -> list[Quantity]:
    return [hertz_force(), hertz_far_displacement(), kappa_large_n(), worn_small_depth(),
            powerlaw_pressure_large_n(), numerical_mdr_force(), impact_time(),
            stress_superposition(), adhesive_pull_off(), line_stress_near_edge(),
            ellipse_field_slender(), mindlin_energy_small_amplitude()]
