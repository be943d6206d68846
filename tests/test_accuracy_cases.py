"""The quantities of the accuracy report (numeric/_accuracy_cases.py): their truths and bounds.

Each case's truth (what every way of the report is measured against) recomputed by a route of
its own, written here at the parameters the case states (its description, or its comment where
the description names none), in mpmath at 50 digits: a closed form from the textbook
(Johnson's Contact Mechanics, Popov's MDR), a quadrature by another substitution, a minimum
found by calculus, Masing's rule for a hysteresis loop. Then the bounds of the error models
(the roundings of a closed form, a tolerance plus those roundings, an error relative to p0
turned relative to the stress), the ways that predict their error, and the texts a row shows.
"""

from __future__ import annotations

import inspect
import math
from functools import cache

import mpmath as mp
import pytest

from hertzmdr.numeric import _accuracy_cases, accuracy

DPS = 50

#: E = 210 GPa, nu = 0.3 for both bodies (the cases' steel pair): E* = E / (2 (1 - nu^2)),
#: taken as the float the cases use (tests/test_accuracy.py::test_the_steel_pair checks it
#: against that form to 1e-15)
E_STEEL = 210e9 / (2 * (1 - 0.3**2))


def f(x) -> mp.mpf:
    """A parameter as the case stores it: the float nearest the stated decimal, exactly."""
    return mp.mpf(float(x))


def hertz_force():
    """F = 4/3 E* R^(1/2) d^(3/2) (Johnson (4.23)), R = 0.5 m, d = 10 um."""
    E, R, d = f(E_STEEL), f(0.5), f(1e-5)
    return 4 * E * mp.sqrt(R) * d ** mp.mpf(1.5) / 3


def hertz_far_displacement():
    """u_z outside a Hertz contact (Johnson (3.42b) with p0 = 2 a E*/(pi R), a^2 = R d):
    ((2 a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)) / (pi R), at r = 1e4 a; R = 0.5 m,
    d = 10 um. The bracket cancels terms of size r^2 to leave one of size a^2 a/r: 12 of the
    50 digits go."""
    R, d = f(0.5), f(1e-5)
    a = mp.sqrt(R * d)
    r = f(1e4 * float(a))  # the case places r at 1e4 times its float a
    return ((2 * a**2 - r**2) * mp.asin(a / r) + a * mp.sqrt(r**2 - a**2)) / (mp.pi * R)


def kappa(n):
    """The MDR factor of f = c r^n: g(r) = kappa_n c r^n with
    kappa_n = n int_0^1 t^(n-1)/sqrt(1 - t^2) dt = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2)
    (the Beta integral; kappa_2 = 2: g = r^2/R for f = r^2/(2R))."""
    n = mp.mpf(n)
    return mp.sqrt(mp.pi) * mp.exp(mp.loggamma(n / 2 + 1) - mp.loggamma(n / 2 + mp.mpf(1) / 2))


def kappa_large_n():
    """kappa_n at n = 1000, by log-Gamma (no overflow at any n)."""
    return kappa(1000)


def worn_small_depth():
    """The parabola r^2/(2R) worn flat to the radius b: f = (r^2 - b^2)/(2R) for r > b, 0
    inside. Its MDR profile is g(r) = r sqrt(r^2 - b^2)/R for r > b, so the contact radius
    solves a^2 (a^2 - b^2) = R^2 d^2, and F = 2 E* int_0^a (d - g) dr = 2 E* (a d - (a^2 -
    b^2)^(3/2)/(3R)), with a^2 - b^2 = 2 R^2 d^2/(b^2 + sqrt(b^4 + 4 R^2 d^2)) (no
    cancellation); E* = 1 GPa, R = 0.1 m, b = 1 mm, 2 R d/b^2 = 1e-6."""
    E, R, b = f(1e9), f(0.1), f(1e-3)
    d = f(1e-6 * 1e-3**2 / (2 * 0.1))  # the float the case computes
    c2 = 2 * R**2 * d**2 / (b**2 + mp.sqrt(b**4 + 4 * R**2 * d**2))
    a = mp.sqrt(b**2 + c2)
    return 2 * E * (a * d - c2 ** mp.mpf(1.5) / (3 * R))


def powerlaw_pressure_large_n():
    """The pressure of f = c r^n, n = 1001, at r = a/10 (E* = 1 GPa, a = 1 mm, d = 1 um):
    p(r) = E*/pi int_r^a g'(x)/sqrt(x^2 - r^2) dx with g = d (x/a)^n; with x^2 = r^2 + s^2
    (not the case's x = r cosh t) it is E* n d/(pi a) int_0^S ((r^2 + s^2)/a^2)^((n-2)/2)
    ds / a, S = sqrt(a^2 - r^2): a smooth integrand, split where x = a (1 - k/n), the layer
    where it lives."""
    E, a, d, n = f(1e9), f(1e-3), f(1e-6), mp.mpf(1001)
    r = f(0.1 * 1e-3)
    S = mp.sqrt(a**2 - r**2)
    pts = [0, *(mp.sqrt((a * (1 - k / n)) ** 2 - r**2) for k in (100, 30, 10, 3, 1)), S]
    integral = mp.quad(lambda s: ((r**2 + s**2) / a**2) ** ((n - 2) / 2), pts)
    return E * n * d / (mp.pi * a) * integral / a


def numerical_mdr_force():
    """F of f = c r^2.5 (E* = 1 GPa, c = 100 m^-1.5, d = 1 um): the contact radius from
    kappa c a^n = d, F = 2 E* int_0^a (d - kappa c r^n) dr = 2 E* a d n/(n + 1)."""
    E, c, n, d = f(1e9), f(1e2), mp.mpf(2.5), f(1e-6)
    a = (d / (kappa(n) * c)) ** (1 / n)
    return 2 * E * a * d * n / (n + 1)


def impact_time():
    """The contact time of a steel ball, R = 1 cm, 7800 kg/m^3, on a steel wall at 1 m/s
    (Johnson (11.24)): x0 = (15 m v0^2/(16 E* R^(1/2)))^(2/5) from the energy balance, and
    tau = 2 x0/v0 int_0^1 dxi/sqrt(1 - xi^(5/2)) = (4/5) B(2/5, 1/2) x0/v0 (the Beta
    integral, where the case's way takes quadrature)."""
    E, R, v0 = f(E_STEEL), f(0.01), mp.mpf(1)
    m = 4 * mp.pi * R**3 * 7800 / 3
    x0 = (15 * m * v0**2 / (16 * E * mp.sqrt(R))) ** (mp.mpf(2) / 5)
    return 4 * mp.beta(mp.mpf(2) / 5, mp.mpf(1) / 2) * x0 / (5 * v0)


def stress_superposition():
    """sigma_zz on the axis below a Hertz contact, a = 1 mm, p0 = 1 GPa, z = a/50:
    -p0/(1 + z^2/a^2) (Johnson (3.45b))."""
    a, p0, z = f(1e-3), f(1e9), f(0.02e-3)
    return -p0 / (1 + (z / a) ** 2)


def adhesive_pull_off():
    """The pull-off force (force control) of f = c r^2.5, E* = 3 MPa, work of adhesion
    0.04 J/m^2, c = 1e9 m^-1.5: the MDR's adhesive force F(a) = 2 E* n/(n + 1) kappa c
    a^(n+1) - sqrt(8 pi dg E* a^3) is least where dF/da = 0, a^(n - 1/2) = 3 sqrt(8 pi dg
    E*)/(4 E* n kappa c), and the pull-off force is F there."""
    E, dg, c, n = f(3e6), f(0.04), f(1e9), mp.mpf(2.5)
    k = kappa(n)
    a = (3 * mp.sqrt(8 * mp.pi * dg * E) / (4 * E * n * k * c)) ** (1 / (n - mp.mpf(1) / 2))
    return 2 * E * n / (n + 1) * k * c * a ** (n + 1) - mp.sqrt(8 * mp.pi * dg * E * a**3)


def line_stress_near_edge():
    """The von Mises stress under a line contact of half-width b = 0.1 mm, p0 = 1 GPa, nu =
    0.3 (plane strain: sigma_yy = nu (sigma_xx + sigma_zz)) at x = 0.99 b, z = 0.01 b, by
    McEwen's closed form of the field (Johnson (4.49)): with m^2, n^2 = (sqrt(k^2 + 4 x^2
    z^2) +- k)/2, k = b^2 - x^2 + z^2, sigma_xx = -p0/b (m (1 + (z^2 + n^2)/(m^2 + n^2)) -
    2z), sigma_zz = -p0/b m (1 - (z^2 + n^2)/(m^2 + n^2)), tau_xz = p0/b n (m^2 - z^2)/(m^2 +
    n^2) (its sign does not enter von Mises)."""
    b, p0, nu, x, z = f(1e-4), f(1e9), f(0.3), f(0.99e-4), f(1e-6)
    k = b**2 - x**2 + z**2
    root = mp.sqrt(k**2 + 4 * x**2 * z**2)
    m, n = mp.sqrt((root + k) / 2), mp.sqrt((root - k) / 2)
    q = (z**2 + n**2) / (m**2 + n**2)
    sxx = -p0 / b * (m * (1 + q) - 2 * z)
    szz = -p0 / b * m * (1 - q)
    txz = p0 / b * n * (m**2 - z**2) / (m**2 + n**2)
    syy = nu * (sxx + szz)
    return mp.sqrt(((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) / 2 + 3 * txz**2)


def mindlin_energy_small_amplitude():
    """The energy per cycle of a tangential force oscillating between +-F* = +-0.01 mu F under
    a steel sphere (R = 1 cm, F = 100 N, mu = 0.6), by Masing's rule: the loop of a
    loading curve u = phi(F_x) has the area W = 4 F* phi(F*) - 8 int_0^F* phi. phi from the
    MDR's springs (normal E* dx, tangential G* dx, 1/G* = 2 (2 - nu)/(4 G), G = E/(2 (1 +
    nu))): the springs within c stick, the others slip at mu E*/G* (d - x^2/R), so F_x/(mu
    F) = 1 - (c/a)^3 and phi = mu E*/G* d (1 - (1 - F_x/(mu F))^(2/3)), d = a^2/R."""
    E, nu = f(210e9), f(0.3)
    G = E / (2 * (1 + nu))
    G_star = 4 * G / (2 * (2 - nu))
    Es = f(E_STEEL)
    R, F, mu = f(0.01), f(100.0), f(0.6)
    a = (3 * F * R / (4 * Es)) ** (mp.mpf(1) / 3)
    d = a**2 / R
    Fa = f(1e-2 * 0.6 * 100.0)

    def phi(Fx):
        return mu * Es / G_star * d * (1 - (1 - Fx / (mu * F)) ** (mp.mpf(2) / 3))
    return 4 * Fa * phi(Fa) - 8 * mp.quad(phi, [0, Fa])


#: each case's truth by the route above, and the relative tolerance of the comparison: the
#: float inputs agree exactly, so what is left is E_STEEL's float against the cases' one
#: (test_the_steel_pair: 1e-15, entering as its power in the quantity: at most 1), the
#: truth's own error (accuracy.Quantity.truth_error: 1e-35 for the 40-digit quadrature of
#: the power law) and 50 digits, less the 12 the far displacement's bracket cancels
ROUTES = {
    "hertz_force": (hertz_force, 2e-15),
    "hertz_far_displacement": (hertz_far_displacement, 1e-30),
    "kappa_large_n": (kappa_large_n, 1e-40),
    "worn_small_depth": (worn_small_depth, 1e-40),
    "powerlaw_pressure_large_n": (powerlaw_pressure_large_n, 1e-34),
    "numerical_mdr_force": (numerical_mdr_force, 1e-40),
    "impact_time": (impact_time, 2e-15),
    "stress_superposition": (stress_superposition, 1e-40),
    "adhesive_pull_off": (adhesive_pull_off, 1e-40),
    "line_stress_near_edge": (line_stress_near_edge, 1e-40),
    "mindlin_energy_small_amplitude": (mindlin_energy_small_amplitude, 2e-15),
}


@pytest.mark.parametrize("case", sorted(ROUTES))
def test_each_truth_by_a_route_of_its_own(case):
    """The truth every way is measured against (at the report's 60 digits) equals the value
    of the route written here, at 50 digits, to the tolerance of ROUTES."""
    route, tol = ROUTES[case]
    q = getattr(_accuracy_cases, case)()
    with mp.workdps(accuracy.TRUTH_DPS):
        truth = q.truth()
    with mp.workdps(DPS):
        want = route()
        err = abs((mp.mpf(truth) - want) / want)
    assert err <= tol, (case, mp.nstr(truth, 25), mp.nstr(want, 25), float(err))


def test_the_powerlaw_truths_stated_error_covers_it():
    """The power law's truth is a 40-digit quadrature, not a 60-digit closed form: the error
    it states (added to every way's bound) covers its measured error against the route above
    (whose own error, at 50 digits on a smooth integrand, is below 1e-45), and the default of
    a closed form (1e-55) would not."""
    q = _accuracy_cases.powerlaw_pressure_large_n()
    with mp.workdps(accuracy.TRUTH_DPS):
        truth = q.truth()
    with mp.workdps(DPS):
        err = float(abs((truth - powerlaw_pressure_large_n()) / truth))
    assert 1e-50 < err <= q.truth_error <= 1e-30


#: float64's unit roundoff and mpmath's at 30 digits (103 bits: mpmath's precision for 30
#: digits, round(31 log2(10)))
U15, U30 = 2.0**-53, 2.0**-103
#: mpmath's bits at the digits the cases use (round((dps + 1) log2(10)))
BITS = {15: 53, 30: 103, 50: 169}


def test_a_closed_forms_bound_counts_its_roundings():
    """64 roundings of the unit roundoff: 7.1e-15 in float64 (the default, dps = 15), 6.3e-30
    at 30 digits."""
    assert _accuracy_cases.FLOAT64 == 64 * U15 == _accuracy_cases.closed_form()
    assert _accuracy_cases.closed_form(15) == 64 * U15
    assert _accuracy_cases.closed_form(30) == 64 * U30
    assert _accuracy_cases.unit_roundoff(15) == U15 and _accuracy_cases.unit_roundoff(50) == (
        2.0 ** -BITS[50])


def ways(case):
    return {(w.method, w.setting): w for w in getattr(_accuracy_cases, case)().ways()}


def test_a_tolerances_bound_adds_the_roundings_of_its_sum():
    """SciPy's quad asked for epsrel: that tolerance plus the roundings of a float64 sum;
    DOP853 asked for rtol: ten times it (the global error of the half oscillation, measured
    0.03 to 0.5 rtol) plus the same roundings."""
    quads = {k: w for k, w in ways("hertz_force").items() if k[1].startswith("epsrel=")}
    assert sorted(k[1] for k in quads) == [f"epsrel={e}" for e in ("0.001", "1e-06", "1e-09",
                                                                 "1e-12")]
    for (_, setting), w in quads.items():
        eps = float(setting.removeprefix("epsrel="))
        assert w.bound == pytest.approx(eps + 64 * U15, rel=1e-14, abs=0), setting
    odes = {k: w for k, w in ways("impact_time").items() if k[1].startswith("rtol=")}
    assert len(odes) == 4
    for (_, setting), w in odes.items():
        rtol = float(setting.removeprefix("rtol="))
        assert w.bound == pytest.approx(10 * rtol + 64 * U15, rel=1e-14, abs=0), setting


def test_a_cancelling_forms_bound_is_its_condition():
    """The textbook forms predict their error: 4 u times the ratio of the cancelling terms to
    the result, at the way's precision u = 2^-bits. Far outside the Hertz contact the terms
    are (r/a)^2 = 1e8 times the result (r = 1e4 a, the name says); the worn parabola's sqrt(1
    + s^2) - 1 keeps s^2/2 of terms of size 1, halved by the square root: 1/s^2 = 1e12
    (2 R d/b^2 = 1e-6, the name says)."""
    far = {k: w for k, w in ways("hertz_far_displacement").items() if w.predicts}
    assert sorted(k[1] for k in far) == ["15 digits", "30 digits", "50 digits", "float64"]
    worn = {k: w for k, w in ways("worn_small_depth").items() if w.predicts}
    assert sorted(k[1] for k in worn) == ["15 digits", "30 digits", "50 digits", "float64"]
    for table, ratio in ((far, 1e8), (worn, 1e12)):
        for (_, setting), w in table.items():
            bits = 53 if setting == "float64" else BITS[int(setting.split()[0])]
            assert w.bound == pytest.approx(4 * 2.0**-bits * ratio, rel=1e-9, abs=0), setting


#: the ways that demonstrate a failure, by case: the forms each description names as
#: cancelling or overflowing, and the leading term of a series (off by its next term); the
#: line contact's ways (9 s to build its 1024-point rules) have none
PREDICTED = {
    "hertz_force": set(),
    "hertz_far_displacement": {"textbook closed form (Problem 7 b)",
                               "textbook closed form in mpmath"},
    "kappa_large_n": {"Gamma ratio (the derived form)"},
    "worn_small_depth": {"the chapter's F(d) (Problem 8)", "the chapter's F(d) in mpmath"},
    "powerlaw_pressure_large_n": {"2F1 closed form (SciPy hyp2f1)"},
    "numerical_mdr_force": set(),
    "impact_time": set(),
    "stress_superposition": set(),
    "adhesive_pull_off": set(),
    "ellipse_field_slender": set(),
    "mindlin_energy_small_amplitude": {"Johnson (7.59) as printed",
                                       "cubic term F*^3/(9 G* a mu F)"},
}


@pytest.mark.parametrize("case", sorted(PREDICTED))
def test_the_demonstrated_failures_are_predicted_and_the_rows_named(case):
    """A way that demonstrates a failure says so (the report then checks that its error is at
    least a hundredth of its bound, and prints "(predicted)"); the two that overflow or return
    NaN in float64 predict an infinite error. Every way names its method and setting, and no
    two rows of a case share both."""
    q = getattr(_accuracy_cases, case)()
    ws = q.ways()
    assert {w.method for w in ws if w.predicts} == PREDICTED[case]
    for w in ws:
        assert isinstance(w.method, str) and w.method and isinstance(w.setting, str) and w.setting
        if w.predicts and "float64" == w.setting and case in ("kappa_large_n",
                                                               "powerlaw_pressure_large_n"):
            assert w.bound == math.inf
    assert len({(w.method, w.setting) for w in ws}) == len(ws)


@cache
def measured(case) -> accuracy.Measured:
    return accuracy.measure(getattr(_accuracy_cases, case)(), budget=None)


#: the sweeps of a numerical method over its resolution, by case and method
SWEEPS = {
    "hertz_force": "SciPy quad of the pressure (5.17)",
    "powerlaw_pressure_large_n": "Gauss-Legendre of the (5.59) integrand (hertzmdr: 16)",
    "numerical_mdr_force": "numerical MDR of samples",
    "stress_superposition": "superposition of (5.43) over the pressure",
    "adhesive_pull_off": "numerical MDR of samples, with adhesion",
    "ellipse_field_slender": "Love's form, double-exponential rule for the field integrals",
}


@pytest.mark.parametrize("case", sorted(SWEEPS))
def test_each_sweep_shows_what_its_resolution_buys(case):
    """A method's rows from its coarsest to its finest setting (the report's order): the
    error does not grow (beyond the roundings near 1e-15), and the coarsest is at least a
    hundred times the finest: each row is computed at the resolution it names (measured:
    3.2e-7 to 8.5e-16 (SciPy's quad, epsrel 1e-3 to 1e-12), 1.1e-6 to 1.7e-16 (power law),
    9e-8 to 1.6e-14 (MDR), 1e-9 to 2e-16 (superposition), 3.7e-6 to 1e-10 (adhesion), 5.2e-6
    to 2e-16 (ellipse))."""
    rows = [r for r in measured(case).rows if r.method == SWEEPS[case]]
    assert len(rows) >= 3
    errs = [r.rel_error for r in rows]
    assert errs[0] >= 100 * errs[-1], errs
    for coarse, fine in zip(errs, errs[1:], strict=False):
        assert fine <= max(coarse, 1e-15), errs


def test_the_ellipse_bound_turns_its_rtol_relative_to_the_stress():
    """The field's rtol is relative to p0 (= 1): relative to sigma_xx = -0.37873 p0 the bound
    is rtol/0.37873, plus float64's roundings and the data truth's 5e-20 (each way's value
    is within its bound of the truth: 2.6 % at rtol = 1e-2)."""
    m = measured("ellipse_field_slender")
    for r in m.rows:
        rtol = float(r.setting.removeprefix("rtol="))
        want = rtol / 0.37873169247983486760 + 64 * U15 + 5e-20
        assert r.bound == pytest.approx(want, rel=0.03 if rtol > 1e-3 else 1e-3, abs=0), (
            r.setting)
    # 20 digits agreed by two rules (1e-20 absolute) plus the rounding of the 20th decimal
    # (5e-21): relative to 0.37873, at least 4e-20; the truth says so, far below every bound
    assert 4e-20 <= m.quantity.truth_error <= 1e-19


def test_a_reported_bound_is_relative_to_the_value():
    """The superposition reports its error in Pa: the bound divides it by |sigma_zz| (1e9
    Pa here), so it stays below 1; the adhesive pull-off's bracketed root reports the spread
    of F over its bracket besides the 8 eps of the closed form (a root, not the closed
    form again)."""
    for r in measured("stress_superposition").rows:
        assert r.bound < 1e-3, (r.setting, r.bound)
    rows = {r.method: r for r in measured("adhesive_pull_off").rows}
    closed = rows["closed form (derive/adhesion.py)"]
    root = rows["bracketed root of the derived dF/da"]
    eps8 = 8 * 2.0**-52
    assert closed.bound == pytest.approx(eps8 + 1e-55, rel=1e-12, abs=0)
    assert root.bound > 1.01 * closed.bound


#: what each case's name or description states of its parameters (the routes above use them)
STATED = {
    "hertz_force": ["R = 0.5 m, d = 10 µm", "steel"],
    "hertz_far_displacement": ["r = 1e4 a"],
    "kappa_large_n": ["n = 1000"],
    "worn_small_depth": ["2Rd/b^2 = 1e-6", "s^2 = 1e-12"],
    "powerlaw_pressure_large_n": ["n = 1001, at r = a/10"],
    "numerical_mdr_force": ["f = c r^2.5", "N + 1 points on [0, 2a]"],
    "impact_time": ["steel ball (R = 1 cm)", "steel wall at 1 m/s"],
    "stress_superposition": ["z = a/50"],
    "adhesive_pull_off": ["f = c r^2.5", "(force control)", "sampled on [0, 10 a_c]"],
    "line_stress_near_edge": ["x = 0.99 b, z = 0.01 b"],
    "ellipse_field_slender": ["b/a = 0.01", "(0.3 a, 0.4 b, 0.3 b)"],
    "mindlin_energy_small_amplitude": ["F* = 0.01 mu F"],
}


@pytest.mark.parametrize("case", sorted(STATED))
def test_each_case_states_its_parameters(case):
    """The report shows each quantity's name and description: they state the parameters
    the truth is computed at (checked by the routes above)."""
    q = getattr(_accuracy_cases, case)()
    assert isinstance(q.description, str) and len(q.description) > 80
    text = f"{q.name}\n{q.description}"
    for s in STATED[case]:
        assert s in text, s



#: the cases with mpmath sweeps (a method's rows at "N digits")
DIGITS = ["hertz_force", "hertz_far_displacement", "kappa_large_n", "worn_small_depth",
          "powerlaw_pressure_large_n", "impact_time"]


@pytest.mark.parametrize("case", DIGITS)
def test_each_mpmath_sweep_starts_at_float64s_precision(case):
    """An mpmath sweep starts at 15 digits, float64's 53 bits (so its row beside the float64
    one tells a formula's error from float64's); the report's docstring says mpmath runs at
    15 to 100 digits: the sweeps end within that, the Hertz force's at 100."""
    sweeps = {}
    for w in getattr(_accuracy_cases, case)().ways():
        if w.setting.endswith(" digits"):
            sweeps.setdefault(w.method, []).append(int(w.setting.split()[0]))
    assert sweeps
    for method, dps in sweeps.items():
        assert min(dps) == 15 and max(dps) <= 100, (method, dps)
        assert max(dps) == 100 or case != "hertz_force", (method, dps)
    with mp.workdps(15):
        assert mp.mp.prec == 53


def test_the_samples_are_those_the_description_states():
    """The numerical MDR's profiles: f = c r^2.5 "sampled at N + 1 points on [0, 2a]" (a =
    (d/(kappa c))^(1/n): c = 100, d = 1 um) and, with adhesion, on [0, 10 a_c] (a_c of the
    pull-off, from dF/da = 0 (tests above): E* = 3 MPa, 0.04 J/m^2, c = 1e9); the row's
    setting says N samples: its profile has N + 1 (the description's N intervals)."""
    with mp.workdps(30):
        a = float((mp.mpf(1e-6) / (kappa(2.5) * 100)) ** (1 / mp.mpf(2.5)))
        E, dg, c, n = mp.mpf(3e6), mp.mpf(0.04), mp.mpf(1e9), mp.mpf(2.5)
        a_c = float((3 * mp.sqrt(8 * mp.pi * dg * E) / (4 * E * n * kappa(n) * c))
                    ** (1 / (n - mp.mpf(1) / 2)))
    seen = 0
    for w in _accuracy_cases.numerical_mdr_force().ways():
        if w.method == "numerical MDR of samples":
            prof = w.run.__defaults__[0]
            N = int(w.setting.removesuffix(" samples"))
            assert prof.source == f"{N + 1} samples"
            assert prof.r_max == pytest.approx(2 * a, rel=1e-12, abs=0)
            seen += 1
    assert seen == 6
    seen = 0
    for w in _accuracy_cases.adhesive_pull_off().ways():
        if w.method == "numerical MDR of samples, with adhesion":
            sampled = w.run.__defaults__[0]
            shape = inspect.getclosurevars(sampled).nonlocals["shape_"]
            N = int(w.setting.removesuffix(" samples"))
            assert shape.profile.source == f"{N + 1} samples"
            # a_c as the case computes it (float64, closed form): within 1e-14 of the truth
            assert shape.profile.r_max == pytest.approx(10 * a_c, rel=1e-13, abs=0)
            seen += 1
    assert seen == 4


# -- accuracy.py: what the report prints of the rows --------------------------------------------


def made_up(name: str, n: int) -> accuracy.Quantity:
    """n/3 by two float64 ways (errors of a rounding, 1e-16 at most) and one 1e-3 slip."""
    return accuracy.Quantity(name, "made up", lambda: mp.mpf(n) / 3, lambda: [
        accuracy.Way("float", "float64", lambda: n / 3, 1e-15),
        accuracy.Way("float", "again", lambda: n / 3, 1e-15),
        accuracy.Way("slip", "1e-3", lambda: n * (1 + 1e-3) / 3, 2e-3)])


def test_the_report_names_every_row_outside_and_keeps_its_tables():
    """Two rows outside their bounds are both named, "; " between them; the headline's and
    each quantity's table have their header and rule (markdown draws no table without); a
    way whose error is 1e-12 exactly reaches 1e-12."""
    from hertzmdr.numeric import _timing

    q = made_up("q", 1)
    rows = [accuracy.Row("a", "s1", 1e-12, 1e-6, (1e-6, 1e-6), 1e-13),
            accuracy.Row("b", "s2", 1e-3, 1e-7, (1e-7, 1e-7), 1e-4),
            accuracy.Row("c", "s3", 1e-20, 1e-3, (1e-3, 1e-3), 1e-19)]
    text = accuracy.markdown([accuracy.Measured(q, rows)], None, _timing.QUICK)
    lines = text.splitlines()
    assert "1 of 3 ways within their bounds: **a (s1); b (s2)** not." in lines
    head = lines.index("| quantity | fastest way to 1e-12 | its time | most digits | "
                       "at what cost |")
    assert lines[head + 1] == "| --- | --- | --- | --- | --- |"
    assert lines[head + 2].startswith("| q | a (s1) | 1 µs |")  # 1e-12 reaches 1e-12
    table = lines.index("## q")
    assert lines[table + 4:table + 6] == [
        "| method | setting | rel. error | bound | digits | time per evaluation | spread |",
        "| --- | --- | --- | --- | --- | --- | --- |"]


def test_main_measures_with_its_budget_and_shows_its_progress(tmp_path, monkeypatch, capsys):
    """Without --quick the report is timed with the full budget (here made small), with it
    the quick one, and says which; the progress bar on stderr counts the ways, one each; the
    report's folder is made with its parents, and a second report may go to the same one."""
    from hertzmdr.numeric import _timing

    monkeypatch.setattr(accuracy, "quantities", lambda: [made_up("one third", 1)])
    full = _timing.Budget(repeats=3, min_time=0.0)
    monkeypatch.setattr(_timing, "FULL", full)
    budgets = []  # the budget each way is timed with
    measure = _timing.measure
    monkeypatch.setattr(_timing, "measure", lambda fn, b: budgets.append(b) or measure(fn, b))
    out = tmp_path / "a" / "b" / "acc.md"
    accuracy.main(out)
    assert "up to 3 rounds of at least 0 s together" in out.read_text()
    assert budgets == [full] * 3
    err = capsys.readouterr().err
    assert "ways measured" in err and "3/3" in err and "/6" not in err
    assert "way/s" in err or "s/way" in err
    budgets.clear()
    accuracy.main(out, quick=True)
    assert "up to 2 rounds of at least 0 s together" in out.read_text()
    assert budgets == [_timing.QUICK] * 3


def test_an_unmatched_only_names_every_quantity(tmp_path, monkeypatch):
    """The refusal of --only lists the names it could match, "; " between them."""
    monkeypatch.setattr(accuracy, "quantities", lambda: [made_up("one third", 1),
                                                         made_up("two thirds", 2)])
    with pytest.raises(ValueError) as e:
        accuracy.main(tmp_path / "acc.md", only="half", quick=True)
    assert str(e.value) == ("only = 'half' matches no quantity; the names: one third; "
                            "two thirds")


def test_the_domain_search_section_is_a_table(tmp_path):
    """The section on the documented-domain search ends in a table of its record's counts:
    header, rule, one row (markdown draws no table without the rule)."""
    import json

    record = tmp_path / "record.json"
    record.write_text(json.dumps({"command": "c", "points_per_row": 1, "functions": 2,
                                  "parameters": 3, "cases": 4, "failures": 5, "seconds": 6}))
    text = accuracy.domain_search_section(record)
    assert text.startswith("\n## Documented domains searched\n\n")
    assert text.endswith("\n\n| functions | parameters | cases | failures | seconds |\n"
                         "| --- | --- | --- | --- | --- |\n| 2 | 3 | 4 | 5 | 6 |\n")
