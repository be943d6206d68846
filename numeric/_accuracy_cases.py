"""The quantities of the accuracy report and every way of computing each (see accuracy.py)."""

from __future__ import annotations

from hertzmdr.numeric.accuracy import Quantity, Way

# a steel pair (E = 210 GPa, nu = 0.3 both): E* = E / (2 (1 - nu^2))
E_STEEL = 210e9 / (2 * (1 - 0.3**2))


def _mp_digits(fn, args, dps):
    """Evaluate an mpmath function at ``dps`` digits."""
    import mpmath as mp

    def run():
        with mp.workdps(dps):
            return +fn(*[mp.mpf(a) for a in args])
    return run


def hertz_force() -> Quantity:
    from hertzmdr.numeric import _generated as g
    from hertzmdr.numeric import _generated_mp as gm

    E, R, d = E_STEEL, 0.5, 1e-5

    def truth():
        import mpmath as mp

        return gm.hertz_force(mp.mpf(E), mp.mpf(R), mp.mpf(d))

    def ways():
        import math

        import mpmath as mp
        from scipy.integrate import quad

        a = float(g.hertz_contact_radius(R, d))
        out = [Way("closed form", "float64", lambda: g.hertz_force(E, R, d))]
        for eps in (1e-3, 1e-6, 1e-9, 1e-12):
            out.append(Way("SciPy quad of the pressure (5.17)", f"epsrel={eps:g}",
                           lambda eps=eps: quad(lambda r: g.hertz_pressure(E, R, d, r) * 2
                                                * math.pi * r, 0, a, epsrel=eps,
                                                epsabs=0)[0]))
        for dps in (15, 30, 50, 100):
            def mp_quad(dps=dps):
                with mp.workdps(dps):
                    Em, Rm, dm = mp.mpf(E), mp.mpf(R), mp.mpf(d)
                    am = gm.hertz_contact_radius(Rm, dm)
                    return +mp.quad(lambda r: gm.hertz_pressure(Em, Rm, dm, r) * 2 * mp.pi * r,
                                    [0, am])
            out.append(Way("mpmath quad of the pressure (5.17)", f"{dps} digits", mp_quad))
        for dps in (15, 30, 50, 100):
            out.append(Way("closed form in mpmath", f"{dps} digits",
                           _mp_digits(gm.hertz_force, (E, R, d), dps)))
        return out

    return Quantity("Hertz force F(d)",
                    "Normal force of a steel sphere pair, R = 0.5 m, d = 10 µm: the closed form "
                    "(5.23), and the defining integral of the pressure (5.15) over the contact.",
                    truth, ways)


def hertz_far_displacement() -> Quantity:
    from hertzmdr.numeric import _generated as g
    from hertzmdr.numeric import _generated_mp as gm

    R, d = 0.5, 1e-5
    a = (R * d) ** 0.5
    r = 1e4 * a

    def truth():
        import mpmath as mp

        return gm.hertz_displacement_outside(mp.mpf(R), mp.mpf(d), mp.mpf(r))

    def ways():
        p0_over_E = float(g.hertz_max_pressure(1.0, R, d))
        out = [
            Way("stable closed form (hypergeometric)", "float64",
                lambda: g.hertz_displacement_outside(R, d, r)),
            Way("textbook closed form (Problem 7 b)", "float64",
                lambda: g.hertz_pressure_displacement_outside(1.0, a, p0_over_E, r)),
        ]
        for dps in (15, 30, 50):
            out.append(Way("stable closed form in mpmath", f"{dps} digits",
                           _mp_digits(gm.hertz_displacement_outside, (R, d, r), dps)))
            def textbook(dps=dps):
                import mpmath as mp

                with mp.workdps(dps):
                    Rm, dm = mp.mpf(R), mp.mpf(d)
                    am, pm = gm.hertz_contact_radius(Rm, dm), gm.hertz_max_pressure(1, Rm, dm)
                    return +gm.hertz_pressure_displacement_outside(1, am, pm, mp.mpf(r))
            out.append(Way("textbook closed form in mpmath", f"{dps} digits", textbook))
        return out

    return Quantity("Hertz surface displacement at r = 1e4 a",
                    "u_z far outside the contact, where the textbook form cancels terms of size "
                    "r/a to leave one of size a/r: the stable form printed by hertzmdr against "
                    "the textbook form, in float64 and in mpmath.", truth, ways)


def all_quantities() -> list[Quantity]:
    return [hertz_force(), hertz_far_displacement()]
