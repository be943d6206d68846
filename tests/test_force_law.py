"""Force laws F = K d^n (derive/force_law.py, numeric/force_law.py, the ``force_law`` effect)
by an independent route: the force at two depths d1, d2 from a 30-digit quadrature of the
pressure (or, for the power law, of the MDR's (5.57) with g from a quadrature of the profile
(5.52)), then n = ln(F2/F1)/ln(d2/d1) and K = F1/d1^n. No closed form of the force enters.

Tolerance: every K and n is a product, quotient or root of a few float64 values (plus, for
the ellipse, a complete elliptic integral through 2F1 and the 64-bisection axis ratio, and
for the power law kappa_n's Gamma ratio): a few ulps, bounded by 1e-13; the 30-digit fits
are exact to ~1e-25.
"""

import math

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import force_law
from hertzmdr.numeric.scene import SceneError, load

from kernels import force_axisymmetric, hertz_reference
from named import assert_inputs_named
from oracle import assert_close

TOL = 1e-13
DEPTHS = ("1e-7", "3.7e-6")  # two depths [m] far enough apart for a well-conditioned fit


def fit(force) -> tuple:
    """(K, n) of F = K d^n through the forces at the two DEPTHS (inside mp.workdps)."""
    d1, d2 = (mp.mpf(x) for x in DEPTHS)
    F1, F2 = force(d1), force(d2)
    n = mp.log(F2 / F1) / mp.log(d2 / d1)
    return F1 / d1**n, n


def check(law, K, n, what):
    assert_close(float(law.K), K, TOL, f"{what}: K")
    assert_close(float(law.n), n, TOL, f"{what}: n")
    # the stiffness law: dF/dd of the fitted law, K_k = n K, n_k = n - 1
    assert_close(float(law.stiffness_K), n * K, TOL, f"{what}: stiffness K")
    assert abs(float(law.stiffness_n) - float(n - 1)) <= TOL, what


def test_hertz_law_by_pressure_quadrature():
    """The Hertz pressure matched through the Boussinesq kernel (tests/kernels.py)."""
    E, R = 2.1e11, 0.012
    with mp.workdps(30):
        K, n = fit(lambda d: hertz_reference(mp.mpf(E), mp.mpf(R), d)[2])
    check(force_law.hertz(R, E), K, n, "hertz")


@pytest.mark.parametrize("theta", [0.35, 1.3])
def test_cone_law_by_pressure_quadrature(theta):
    """(5.39) as printed, p = (E* d/(pi a)) arccosh(a/r), a = 2 d/(pi tan theta) (5.38),
    integrated over the disc (tanh-sinh takes the log singularity at r = 0); a shallow cone and
    a sharp one (theta = 1.3 rad, near the pi/2 limit)."""
    E = 3e9
    with mp.workdps(30):
        def F(d):
            a = 2 * d / (mp.pi * mp.tan(theta))
            return force_axisymmetric(lambda r: E * d / (mp.pi * a) * mp.acosh(a / r), a)

        K, n = fit(F)
    check(force_law.cone(theta, E), K, n, "cone")


def test_punch_law_by_pressure_quadrature():
    """Boussinesq's punch pressure E* d/(pi sqrt(a^2 - r^2)) (5.9) over the disc."""
    E, a = 7e10, 2.5e-3
    with mp.workdps(30):
        am = mp.mpf(a)
        K, n = fit(lambda d: force_axisymmetric(
            lambda r: E * d / (mp.pi * mp.sqrt((am - r) * (am + r))), am))
    check(force_law.flat_punch(a, E), K, n, "punch")


@pytest.mark.parametrize("n_profile", [0.7, 1.5, 3.0])
def test_powerlaw_law_by_pressure_quadrature(n_profile):
    """f = c r^n: g(x) = x int_0^x f'(r)/sqrt(x^2 - r^2) dr (5.52) by quadrature, the
    contact radius from d = g(a) (5.55), F = 2 E* int_0^a (d - g(x)) dx (5.57): the MDR
    evaluated numerically, not its closed form (kappa_n included)."""
    E, c = 1e9, 4.0
    with mp.workdps(30):
        nn = mp.mpf(n_profile)
        # g(x) = x int_0^x c n r^(n-1)/sqrt(x^2 - r^2) dr = G x^n, G by r = x sin(s)
        G = mp.quad(lambda s: c * nn * mp.sin(s) ** (nn - 1), [0, mp.pi / 2])

        def F(d):
            a = (d / G) ** (1 / nn)
            return 2 * E * mp.quad(lambda x: d - G * x**nn, [0, a])

        K, n = fit(F)
    check(force_law.power_law(c, n_profile, E), K, n, f"power law n = {n_profile}")


def test_line_law_by_pressure_quadrature():
    """(5.36) with (5.37) as printed, p = (E*/2) sqrt(d/R) sqrt(1 - x^2/a^2), a = sqrt(R d)
    (5.35), integrated across the strip: F/L, linear in that conventional d."""
    E, R = 2.1e11, 0.04
    with mp.workdps(30):
        def F_per_length(d):
            a = mp.sqrt(R * d)
            return mp.quad(lambda x: E / 2 * mp.sqrt(d / R) * mp.sqrt(1 - (x / a) ** 2),
                           [-a, a])

        K, n = fit(F_per_length)
    check(force_law.line(E), K, n, "line")


@pytest.mark.parametrize("t", [0.9, 0.3, 0.02])
def test_ellipse_law_by_pressure_quadrature(t):
    """The ellipse of Johnson's closed form (tests/test_ellipse.py's references, typed from
    the book): its pressure over the ellipse at two depths; R2 from the same matching."""
    from test_ellipse import ref_force, ref_state

    E, R1 = 2.1e11, 0.05
    with mp.workdps(30):
        tt = mp.mpf(t)
        R2 = ref_state(mp.mpf(E), mp.mpf(R1), mp.mpf(1e-6), tt)[3]
        K, n = fit(lambda d: ref_force(mp.mpf(E), mp.mpf(R1), d, tt))
    check(force_law.ellipse(R1, float(R2), E), K, n, f"ellipse t = {t}")


def test_stiffness_law_is_the_derivative():
    """dF/dd = K_k d^(n_k) against mpmath's derivative of K d^n at 30 digits, for every
    family, and the generated exponents against n - 1."""
    laws = {"hertz": force_law.hertz(0.01, 1e9), "cone": force_law.cone(0.2, 1e9),
            "punch": force_law.flat_punch(1e-3, 1e9), "line": force_law.line(1e9),
            "powerlaw": force_law.power_law(2.0, 2.5, 1e9),
            "ellipse": force_law.ellipse(0.01, 0.002, 1e9)}
    d = 2e-6
    for name, law in laws.items():
        with mp.workdps(30):
            K, n = mp.mpf(float(law.K)), mp.mpf(float(law.n))
            k = mp.diff(lambda x, K=K, n=n: K * x**n, mp.mpf(d))
        assert_close(float(law.stiffness(d)), k, TOL, name)
        # 1/n against (n + 1)/n - 1: two roundings
        assert abs(float(law.stiffness_n) - (float(law.n) - 1)) <= 4e-16, name
    assert gen.force_law_powerlaw_stiffness_exponent(2.5) == pytest.approx(0.4, rel=1e-15)


def test_law_force_and_stiffness_at_depths_by_pressure_quadrature():
    """Law.force and Law.stiffness at an array of depths (0, one between the fit's depths, one
    beyond them) against the 30-digit quadrature of the Hertz pressure (tests/kernels.py), and
    the punch's constant stiffness (n_k = 0, so 0^0 = 1 at d = 0) against F(d)/d of the
    quadrature of Boussinesq's punch pressure: K d^n is one power and one product (a few
    ulps, TOL)."""
    E, R, a = 2.1e11, 0.012, 2.5e-3
    ds = np.array([0.0, 5e-7, 2e-5])
    law = force_law.hertz(R, E)
    F, k = law.force(ds), law.stiffness(ds)
    assert F[0] == 0.0 and k[0] == 0.0
    with mp.workdps(30):
        for i, d in enumerate(ds[1:], 1):
            ref = hertz_reference(mp.mpf(E), mp.mpf(R), mp.mpf(d))[2]
            assert_close(F[i], ref, TOL, f"hertz force at d = {d}")
            # F ~ d^(3/2): dF/dd = (3/2) F/d (the power law's derivative, not its K_k)
            assert_close(k[i], ref * 3 / (2 * mp.mpf(d)), TOL, f"hertz stiffness at d = {d}")
        am, d = mp.mpf(a), mp.mpf("1e-6")
        punch = force_axisymmetric(lambda r: E * d / (mp.pi * mp.sqrt((am - r) * (am + r))), am)
        for kk in force_law.flat_punch(a, E).stiffness(np.array([0.0, 1e-6, 3.0])):
            assert_close(kk, punch / d, TOL, "punch stiffness")


def test_each_input_named_in_its_error():
    """Every input of every law, set to NaN, is named in the one-line error (tests/named.py)."""
    assert_inputs_named(force_law.hertz, {"R": 0.01, "E_star": 1e9})
    assert_inputs_named(force_law.cone, {"theta": 0.3, "E_star": 1e9})
    assert_inputs_named(force_law.flat_punch, {"a": 1e-3, "E_star": 1e9})
    assert_inputs_named(force_law.power_law, {"c_n": 2.0, "n": 2.5, "E_star": 1e9})
    assert_inputs_named(force_law.line, {"E_star": 1e9})
    assert_inputs_named(force_law.ellipse, {"R1": 0.01, "R2": 0.002, "E_star": 1e9})


def test_law_refuses_a_negative_or_nan_depth_naming_d():
    """A depth below 0 (no contact: K d^n would be NaN for n = 3/2) or NaN is refused, one line
    naming d and its range, at its index in an array."""
    law = force_law.hertz(0.01, 1e9)
    for call in (law.force, law.stiffness):
        with pytest.raises(ValueError, match=r"^d = -1e-09 is out of range; valid: 0 <= d"):
            call(-1e-9)
        with pytest.raises(ValueError, match=r"^d\[1\] = nan"):
            call([1e-6, float("nan")])


def test_vectorized_and_validated():
    """Arrays broadcast; a bad input names itself and its range."""
    law = force_law.hertz(np.array([1e-3, 1e-2]), 1e9)
    assert np.shape(law.K) == (2,)
    assert law.K[1] / law.K[0] == pytest.approx(math.sqrt(10), rel=1e-15)
    with pytest.raises(ValueError, match="R"):
        force_law.hertz(-1.0, 1e9)
    with pytest.raises(ValueError, match="theta"):
        force_law.cone(2.0, 1e9)


# -- the scene effect ------------------------------------------------------------------------

def _scene(body, load_=None, effects=("force_law",), **extra):
    return {"effects": list(effects), "body": [body, {"shape": "flat", "E": "1 GPa", "nu": 0.3}],
            "load": load_ or {"depth": "1 um"}, **extra}


def test_scene_force_law_reproduces_the_force():
    """The effect's K d^n equals the scene's own force at its depth, for each power-law kind
    (the two routes share only E*)."""
    rigid = {"rigid": True}
    cases = {
        "sphere": {"shape": "sphere", "radius": "5 mm", **rigid},
        "cone": {"shape": "cone", "angle": "20 deg", **rigid},
        "flat_punch": {"shape": "flat_punch", "radius": "1 mm", **rigid},
        "power_law": {"shape": "power_law", "coefficient": 3.0, "exponent": 1.5, **rigid},
        "ellipsoid": {"shape": "ellipsoid", "radii": ["5 mm", "20 mm"], **rigid},
    }
    for name, body in cases.items():
        doc = load(_scene(body, effects=("force_law", "force", "stiffness", "depth"))).run()
        v, eff = doc["effects"]["force_law"]["value"], doc["effects"]
        d = eff["depth"]["value"]
        assert v["K"] * d ** v["n"] == pytest.approx(eff["force"]["value"], rel=1e-12), name
        assert v["stiffness_K"] * d ** v["stiffness_n"] == pytest.approx(
            eff["stiffness"]["value"], rel=1e-12), name
        assert "N/m^" in doc["effects"]["force_law"]["method"], name


def test_scene_line_law_per_length():
    """A line contact reports F = K d for its length and K_per_length = K/L."""
    body = {"shape": "cylinder", "radius": "10 mm", "length": "20 mm", "rigid": True}
    doc = load(_scene(body, effects=("force_law", "force"))).run()
    v = doc["effects"]["force_law"]["value"]
    assert v["n"] == 1.0 and v["K"] == pytest.approx(v["K_per_length"] * 0.02, rel=1e-15)
    assert v["K"] * 1e-6 == pytest.approx(doc["effects"]["force"]["value"], rel=1e-14)
    assert "(5.35)" in doc["effects"]["force_law"]["method"]


@pytest.mark.parametrize("body,why", [
    ({"shape": "flattened_parabola", "radius": "1 mm", "flat_radius": "0.1 mm"}, "flat tip"),
    ({"shape": "exact_sphere", "radius": "1 mm"}, "a/R -> 0"),
    ({"shape": "profile", "r": [0, 1e-4, 2e-4, 3e-4], "f": [0, 1e-6, 4e-6, 9e-6]},
     "sampled profile"),
])
def test_scene_force_law_refused_where_no_power_law(body, why):
    """One line: why not, and the tabulated curve instead."""
    with pytest.raises(SceneError, match="force_depth_curve") as exc:
        load(_scene({**body, "rigid": True})).run()
    assert why in str(exc.value) and "\n" not in str(exc.value)


def test_scene_adhesive_force_law_refused():
    body = {"shape": "sphere", "radius": "1 mm", "rigid": True}
    with pytest.raises(SceneError, match="pull-off.*force_depth_curve"):
        load(_scene(body, interface={"work_of_adhesion": "0.05 J/m^2"})).run()
