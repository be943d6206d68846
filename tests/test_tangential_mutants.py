"""Tangential contact: the cases the mutation run of numeric/tangential.py found untested
(issue 11): every refusal as one anchored line, inputs taken as floats, mu = 0 and mu = 1,
the flat punch's closed forms, the Masing loop point by point, the history solver's grid
(trapezoid weights, contact and stick edges, scale invariance) and its force control against
a bisection of the springs' sum."""

import re

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import hertz
from hertzmdr.numeric import tangential as tg

E_STEEL, NU = 210e9, 0.3
G_STEEL = E_STEEL / (2 * (1 + NU))
E_STAR = E_STEEL / (2 * (1 - NU**2))  # two steel bodies (5.26)
G_STAR = 2 * G_STEEL / (2 - NU)  # 1/G* = 2 (2 - nu)/(4 G), Mindlin's two equal bodies
R, F_N, MU = 0.01, 100.0, 0.6
A = float(hertz.contact_radius_from_force(F_N, R, E_STAR))
EPS = np.finfo(float).eps


def _sphere(mu=MU, prof=None):
    return tg.Contact(prof or tg.Paraboloid(R), A, E_STAR, G_STAR, mu)


def _refused(call, message):
    """``call`` raises one ValueError whose message is exactly ``message``."""
    with pytest.raises(ValueError) as err:
        call()
    assert str(err.value) == message, str(err.value)
    assert "\n" not in str(err.value)


def _hist(**kw):
    args = dict(E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=2 * A, depth=[A * A / R],
                u_x=[0.0], n_grid=100)
    args.update(kw)
    return tg.history(kw.pop("g", tg.Paraboloid(R)), **{k: v for k, v in args.items()
                                                          if k != "g"})


def test_every_refusal_of_the_tangential_api_is_one_anchored_line():
    """Each check names its input, the value and what is valid, exactly (case included)."""
    _refused(lambda: tg.effective_modulus(-1.0, NU, G_STEEL, NU),
             "G1 = -1.0 is out of range; valid: G1 > 0")
    _refused(lambda: tg.effective_modulus(G_STEEL, NU, 0.0, NU),
             "G2 = 0.0 is out of range; valid: G2 > 0")
    _refused(lambda: tg.effective_modulus(np.inf, NU, np.inf, NU),
             "G1 = G2 = inf: two rigid bodies have no tangential compliance; valid: at least "
             "one finite shear modulus")
    _refused(lambda: tg.effective_modulus(G_STEEL, 0.7, G_STEEL, NU),
             "nu1 = 0.7 is out of range; valid: -1 < nu1 <= 0.5")
    _refused(lambda: tg.effective_modulus(G_STEEL, NU, G_STEEL, -1.0),
             "nu2 = -1.0 is out of range; valid: -1 < nu2 <= 0.5")
    _refused(lambda: tg.Paraboloid(-1.0), "R = -1.0 is out of range; valid: R > 0 and finite")
    _refused(lambda: tg.PowerLaw(0.0, 2.0),
             "c_n = 0.0 is out of range; valid: c_n > 0 and finite")
    _refused(lambda: tg.PowerLaw(1.0, -2.0), "n = -2.0 is out of range; valid: n > 0 and finite")
    _refused(lambda: tg.FlatPunch(-1e-7),
             "depth = -1e-07 is out of range; valid: depth > 0 and finite")
    _refused(lambda: tg.Contact("sphere", A, E_STAR, G_STAR, MU),
             "profile = 'sphere' is not one of ['cone', 'flat_punch', 'paraboloid', "
             "'power_law'] (tangential.Paraboloid(R=...), Cone(theta=...), PowerLaw(c_n=..., "
             "n=...), FlatPunch(depth=...)); for any other profile use history()")
    for i, name in enumerate(("a", "E_star", "G_star")):
        args = [A, E_STAR, G_STAR, MU]
        args[i] = -2.0
        _refused(lambda args=args: tg.Contact(tg.Paraboloid(R), *args),
                 f"{name} = -2.0 is out of range; valid: {name} > 0 and finite")
    _refused(lambda: _sphere(-0.1), "mu = -0.1 is out of range; valid: 0 <= mu < inf")
    ct = _sphere()
    lim = ct.sliding_force
    for meth in ("stick_radius", "force"):
        _refused(lambda meth=meth: getattr(ct, meth)(np.nan),
                 "u_x = nan is out of range; valid: a number, not NaN")
    _refused(lambda: ct.traction(-1.0, 1e-9), "r = -1.0 is out of range; valid: 0 <= r < inf")
    _refused(lambda: ct.traction(0.0, np.nan),
             "u_x = nan is out of range; valid: a number, not NaN")
    for meth, name in (("displacement", "F_x"), ("stick_radius_from_force", "F_x"),
                       ("energy", "F_amp"), ("energy_small", "F_amp"), ("loop", "F_amp")):
        _refused(lambda meth=meth: getattr(ct, meth)(np.nan),
                 f"{name} = nan is out of range; valid: a number, not NaN")
        _refused(lambda meth=meth: getattr(ct, meth)(2 * lim),
                 f"{name} = {2 * lim!r} exceeds the sliding force mu F_N = {lim!r} N "
                 f"(mu = {MU}, F_N = {ct.normal_force!r} N); valid: |{name}| <= mu F_N")
    for bad in (True, 5, 2, 6.0):
        _refused(lambda bad=bad: ct.loop(0.5 * lim, bad),
                 f"n_points = {bad!r} is out of range; valid: an even integer >= 4")

    def hist(**kw):
        return lambda: _hist(**kw)

    for name in ("E_star", "G_star", "x_max"):
        _refused(hist(**{name: 0.0}), f"{name} = 0.0 is out of range; valid: {name} > 0 and finite")
    _refused(hist(mu=-1.0), "mu = -1.0 is out of range; valid: 0 <= mu < inf")
    for bad in (True, 7, 6, 10.0):
        _refused(hist(n_grid=bad),
                 f"n_grid = {bad!r} is out of range; valid: an even integer >= 8")
    _refused(hist(normal_force=[1.0]), "give exactly one of depth= and normal_force=")
    _refused(hist(depth=None), "give exactly one of depth= and normal_force=")
    _refused(hist(F_x=[0.0]), "give exactly one of u_x= and F_x=")
    _refused(hist(depth=[[1e-7]]), "depth must be a 1-D sequence of states; got shape (1, 1)")
    _refused(hist(depth=None, normal_force=[[1.0]]),
             "normal_force must be a 1-D sequence of states; got shape (1, 1)")
    _refused(hist(depth=[0.0, 1e-7, -1e-7], u_x=[0, 0, 0]),
             "depth[2] = -1e-07 is out of range; valid: >= 0")
    _refused(hist(depth=None, normal_force=[0.0, -1.0], u_x=[0, 0]),
             "normal_force[1] = -1.0 is out of range; valid: >= 0")
    _refused(hist(depth=[0.0, np.inf], u_x=[0, 0]), "depth[1] = inf is out of range; valid: finite")
    _refused(hist(depth=[0.0, np.nan], u_x=[0, 0]),
             "depth[1] = nan is out of range; valid: a number, not NaN")
    _refused(hist(depth=[0.0, 1e-7], u_x=[0.0]), "u_x has 1 states, the normal history has 2")
    _refused(hist(depth=[0.0, 1e-7], u_x=None, F_x=[0, 0, 0]),
             "F_x has 3 states, the normal history has 2")
    _refused(hist(u_x=[np.inf]), "u_x[0] = inf is out of range; valid: finite")
    _refused(hist(u_x=None, F_x=[-np.inf]), "F_x[0] = -inf is out of range; valid: finite")
    _refused(hist(g=3.0), "g = 3.0 is neither a callable g(x) [m] nor a profile with a .g method")
    # the flat punch's g needs its radius: refused as such (was: a depth "beyond x_max")
    _refused(hist(g=tg.FlatPunch(1e-7)),
             "g = FlatPunch(depth=1e-07) holds no radius, and a flat punch's g(x) (0 inside its "
             "radius a, a wall beyond) needs it; valid: a callable g(x) [m] with its wall at "
             "x = a, or Contact(FlatPunch(...), a=...) for the closed forms")
    monotone = "g(x) must be finite and non-decreasing on [0, x_max]"
    _refused(hist(g=lambda x: 0.0 * x[:-1]), monotone)  # wrong shape, finite, non-decreasing
    _refused(hist(g=lambda x: np.where(x > A, np.nan, 0.0)), monotone)  # NaN alone
    _refused(hist(g=lambda x: -x), monotone)  # decreasing alone
    _refused(hist(depth=[1e-7, 4 * A * A / R + 1e-9], u_x=[0, 0]),
             f"depth[1] = {4 * A * A / R + 1e-9!r} m reaches beyond x_max = {2 * A!r} m; "
             "valid: a larger x_max")
    _refused(hist(depth=None, normal_force=[0.0, 1e9], u_x=[0, 0]),
             f"normal_force[1] = 1000000000.0 N needs a contact wider than the grid "
             f"(x_max = {2 * A!r} m); valid: a larger x_max")
    ok = _hist(depth=[0.0, 2e-7], u_x=[0.0, 1e-9])
    total = MU * float(ok.normal_force[-1])
    with pytest.raises(ValueError) as err:
        _hist(depth=[0.0, 2e-7], u_x=None, F_x=[0.0, 1.01 * total])
    m = re.fullmatch(r"F_x\[1\] = (\S+) N exceeds the sliding force mu F_N = (\S+) N of that "
                     r"step; valid: \|F_x\| <= mu F_N", str(err.value))
    assert m and float(m[1]) == 1.01 * total, str(err.value)
    assert float(m[2]) == pytest.approx(total, rel=1e-14)  # the springs' sum of mu q_z


def test_inputs_are_taken_as_floats():
    """Profiles and contacts store plain floats; integer radii are squared as floats (an int64
    x**2 would wrap beyond 9.2e18 silently)."""
    assert type(tg.Paraboloid(np.array(0.01)).R) is float
    assert type(tg.Cone(1).theta) is float
    pl = tg.PowerLaw(np.array(50.0), np.array(2))
    assert type(pl.c_n) is float and type(pl.n) is float
    assert type(tg.FlatPunch(np.array(1e-7)).depth) is float
    assert type(_sphere(np.array(0.6)).mu) is float
    assert tg.Paraboloid(1.0).g([4_000_000_000]) == 1.6e19  # exact in binary


def _cattaneo(u, mu, a=A):
    """Cattaneo-Mindlin in the MDR's terms (mpmath): F = mu F_N (1 - (1 - u/u*)^(3/2)),
    u* = mu (E*/G*) d with d = a^2/R (Popov and Hess, the onset of sliding)."""
    with mp.workdps(30):
        d = mp.mpf(a) ** 2 / R
        fn = 4 * mp.mpf(E_STAR) * mp.mpf(a) ** 3 / (3 * R)
        ustar = mu * mp.mpf(E_STAR) / mp.mpf(G_STAR) * d
        t = min(abs(mp.mpf(u)) / ustar, 1)
        return float(mp.sign(u) * mu * fn * (1 - (1 - t) ** mp.mpf(1.5))), float(ustar)


def test_mu_one_follows_cattaneo_and_mu_zero_is_zero_in_every_shape():
    """mu = 1 (not a special case) against Cattaneo; mu = 0: float zeros of the input's shape
    from every method, also on the cone's axis where the pressure is infinite (0, not NaN)."""
    one = _sphere(1.0)
    for frac in (0.1, 0.5, 0.9):
        ref, ustar = _cattaneo(frac * _cattaneo(0, 1.0)[1], 1.0)
        # 1e-13: the closed form in float against 30 digits, a few roundings of (1 - u/u*)
        assert float(one.force(frac * ustar)) == pytest.approx(ref, rel=1e-13)
        assert float(one.displacement(ref)) == pytest.approx(frac * ustar, rel=1e-12)
        assert float(one.stick_radius(frac * ustar)) == pytest.approx(
            A * (1 - frac) ** 0.5, rel=1e-13)
        assert float(one.stick_radius_from_force(ref)) == pytest.approx(
            A * (1 - frac) ** 0.5, rel=1e-12)
    assert float(one.energy(0.5 * one.sliding_force)) > 0
    assert float(one.energy_small(0.5 * one.sliding_force)) > 0
    for prof in (tg.Paraboloid(R), tg.Cone(0.1), tg.PowerLaw(300.0, 1.5)):
        zero = _sphere(0.0, prof)
        x3 = np.array([0.0, 1e-9, 1e-6])
        for out in (zero.force(x3), zero.stick_radius(x3), zero.displacement(x3 * 0),
                    zero.stick_radius_from_force(x3 * 0), zero.energy(x3 * 0),
                    zero.energy_small(x3 * 0), zero.traction(x3 * 0, 1e-9)):
            assert out.dtype == float and out.shape == (3,) and np.all(out == 0), (prof, out)


def test_flat_punch_closed_forms():
    """Flat punch: u = F_x (2 - nu)/(4 G a) for two equal bodies (Mindlin's punch compliance
    (2 - nu)/(8 G a) each), the stick radius is a (no partial slip), nothing dissipated, the
    traction 0 from the rim on (finite there, where the stick form is singular)."""
    ct = _sphere(prof=tg.FlatPunch(1e-7))
    F = np.array([0.0, 0.3, 0.9]) * ct.sliding_force
    # 1e-15: one division each way
    assert np.allclose(ct.displacement(F), F * (2 - NU) / (4 * G_STEEL * A), rtol=1e-14, atol=0)
    c = ct.stick_radius_from_force(F)
    assert c.shape == (3,) and c.dtype == float and np.all(c == A)
    assert float(ct.stick_radius_from_force(0.5 * ct.sliding_force)) == A
    for meth in (ct.energy, ct.energy_small):
        W = meth(F)
        assert W.shape == (3,) and W.dtype == float and np.all(W == 0)
    q = ct.traction(np.array([0.0, A, 2 * A]), 0.5 * ct.slide_onset)
    assert q[0] > 0 and q[1] == 0 and q[2] == 0


def test_traction_is_zero_outside_and_the_slip_value_on_the_axis_at_full_slip():
    """Outside the contact the traction is 0; once all slides, mu p(r) (Hertz at the centre)."""
    ct = _sphere()
    assert np.all(ct.traction(np.array([A, 1.5 * A]), 0.5 * ct.slide_onset) == 0)
    p0 = 3 * F_N / (2 * np.pi * A * A)  # Hertz's central pressure
    assert float(ct.traction(0.0, 2 * ct.slide_onset)) == pytest.approx(MU * p0, rel=1e-14)
    cone = _sphere(prof=tg.Cone(0.1))
    q = cone.traction(np.array([0.0, 0.5 * A]), 2 * cone.slide_onset)
    assert q[0] == np.inf and np.isfinite(q[1])


def test_force_a_rounding_beyond_the_sliding_force_gives_the_onset():
    """|F_x| within 4 ulp beyond mu F_N is taken as mu F_N: the onset, not NaN, both signs."""
    ct = _sphere()
    lim = ct.sliding_force
    for sign in (1, -1):
        F = sign * lim * (1 + 2 * EPS)
        # the closed form at mu F_N exactly against the onset: a few ulp of rounding
        assert float(ct.displacement(F)) == pytest.approx(sign * ct.slide_onset, rel=8 * EPS)
        assert float(ct.stick_radius_from_force(F)) == 0.0


def test_loop_point_by_point_against_masing_and_cattaneo():
    """Every point of the loop: u from u* to -u* and back, F = F_a - 2 F_mono((u* - u)/2)
    down and its mirror up, F_mono Cattaneo's (mpmath); 1000 points by default, 4 allowed."""
    ct = _sphere()
    Fa = 0.7 * ct.sliding_force
    ustar = float(ct.displacement(Fa))
    for n, (u, F) in ((1000, ct.loop(Fa)), (4, ct.loop(Fa, 4)), (10, ct.loop(Fa, np.int64(10)))):
        assert u.shape == F.shape == (n,)
        down = np.linspace(ustar, -ustar, n // 2)
        # 1e-15 of u*: u = u* - 2 u* s rounds once or twice
        assert np.allclose(u, np.concatenate([down, -down]), rtol=0, atol=4 * EPS * ustar)
        for k in range(n):
            sign = 1 if k < n // 2 else -1
            ref = sign * (Fa - 2 * _cattaneo((ustar - sign * u[k]) / 2, MU)[0])
            # 1e-12 of F_a: the closed forms' rounding near the turning points
            assert F[k] == pytest.approx(ref, abs=1e-12 * Fa), (n, k)


def _worn(x, b=0.3 * A):
    """A sphere worn flat to radius b: g = 0 for |x| <= b (a flat piece of g, allowed)."""
    x = np.abs(np.asarray(x, float))
    return np.where(x > b, (x - b) * (x + b) / R, 0.0)


@pytest.mark.parametrize("g", [tg.Paraboloid(R).g, _worn], ids=["sphere", "worn"])
def test_history_grid_trapezoid_and_contact_edge(g):
    """On a coarse grid (8 intervals, the fewest allowed), state by state: the normal force is
    the trapezoid rule of E* (d - g)+ on the symmetric line [-x_max, x_max] (np.trapezoid),
    the contact radius the root of the piecewise linear interpolant of g (np.interp), also for
    no contact, a contact inside the first interval, one in the last and one at x_max; with no
    contact nothing slides and the stick radius is 0."""
    X = 2 * A
    x = np.linspace(0, X, 9)
    gx = g(x)
    h = X / 8
    depths = [0.0, float(g(x[2] + 0.4 * h)) if g is _worn else float(g(0.4 * h)),
              float(g(x[3] + 0.3 * h)), 0.5 * (gx[-2] + gx[-1]), float(gx[-1])]
    res = tg.history(g, E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=X, depth=depths,
                     u_x=[0.0, 1e-12, 2e-12, 3e-12, 4e-12], n_grid=8, estimate_error=False)
    for k, d in enumerate(depths):
        q = E_STAR * np.maximum(d - gx, 0.0)
        # 1e-14: two summations of 9 terms in a different order
        assert res.normal_force[k] == pytest.approx(2 * np.trapezoid(q, x), rel=1e-14, abs=0)
        # the worn g is 0 on nodes 0 and 1: a contact (d > 0) reaches beyond node 1
        first = 1 if g is _worn else 0
        a = float(np.interp(d, gx[first:], x[first:])) if d > 0 else 0.0
        assert res.contact_radius[k] == pytest.approx(a, rel=1e-14, abs=0), k
    assert not res.sliding[0] and res.stick_radius[0] == 0.0
    assert res.sliding.dtype == bool and res.stuck.dtype == bool


def _full_slip_history(mu=MU, scale=1.0, n=200):
    """Depth-controlled sphere to u* and beyond, back to -u* and beyond; force-controlled copy
    to +-mu F_N exactly (from the first run's normal force)."""
    d = A * A / R
    X = 1.5 * A
    on = mu * E_STAR * d / G_STAR  # the MDR's onset of sliding mu (E*/G*) d
    kw = dict(E_star=scale * E_STAR, G_star=scale * G_STAR, mu=mu, x_max=X, n_grid=n)
    u = [0.0, 0.3 * on, 2 * on, -2 * on, -0.5 * on]
    res = tg.history(tg.Paraboloid(R), depth=[d] * 5, u_x=u, **kw)
    total = mu * float(res.normal_force[0])
    F = [0.0, 0.5 * total, total, -total, 0.2 * total]
    return res, tg.history(tg.Paraboloid(R), depth=[d] * 5, F_x=F, **kw), on, total


def test_history_full_slip_by_displacement_and_by_force():
    """Sliding: every spring slides, the stick radius is 0, F_x = +-mu F_N; driven by the
    force +-mu F_N exactly it slides too, at the displacements +-u* of the grid's springs
    (u* the MDR's onset within the grid's error, second order: (h/a)^2 ~ 6e-5 here)."""
    res, byF, on, total = _full_slip_history()
    for r in (res, byF):
        assert list(r.sliding) == [False, False, True, True, False]
        assert r.stick_radius[2] == 0.0 and r.stick_radius[3] == 0.0
        assert r.F_x[2] == pytest.approx(total, rel=1e-13)
        assert r.F_x[3] == pytest.approx(-total, rel=1e-13)
    assert byF.u_x[2] == pytest.approx(on, rel=2e-3)
    assert byF.u_x[3] == pytest.approx(-on, rel=2e-3)
    assert byF.u_x[2] - byF.u_x[3] == pytest.approx(2 * on, rel=2e-3)
    # the final state: q_z = E* (d - g)+ on the grid; stuck where |q_x| < mu q_z
    d = A * A / R
    assert np.allclose(res.q_z, E_STAR * np.maximum(d - res.x**2 / R, 0), rtol=1e-13, atol=0)
    assert np.array_equal(res.stuck, (res.q_z > 0) & (np.abs(res.q_x) < MU * res.q_z))
    assert res.stuck.any() and not res.stuck.all()


def test_history_is_invariant_under_the_scale_of_the_moduli():
    """Linear elasticity with Coulomb friction: multiplying E* and G* by s multiplies every
    force and energy by s and leaves every length alone (here s = 1e-9: a gel in nN);
    sub-unit line loads must not be treated as zero. Both drivers, with normal load changes."""
    s = 1e-9
    for drive in ("u", "F"):
        ref, gel = (_full_slip_history(scale=k) for k in (1.0, s))
        ref, gel = (ref[0], gel[0]) if drive == "u" else (ref[1], gel[1])
        for name in ("depth", "contact_radius", "u_x", "stick_radius"):
            # 1e-12: the same arithmetic, scaled; the force drive's root rounds differently
            assert np.allclose(getattr(gel, name), getattr(ref, name), rtol=1e-9,
                               atol=1e-12 * A), (drive, name)
        for name in ("normal_force", "F_x", "dissipated"):
            assert np.allclose(getattr(gel, name), s * getattr(ref, name), rtol=1e-9,
                               atol=1e-12 * s * F_N * A), (drive, name)
        assert np.array_equal(gel.sliding, ref.sliding) and np.array_equal(gel.stuck, ref.stuck)
    d = A * A / R
    steps = dict(depth=[0.5 * d, d, d, 1.4 * d, 1.4 * d, 0.7 * d],
                 u_x=np.array([0.0, 0.2, 0.5, 0.5, 0.9, -0.4]) * MU * E_STAR * d / G_STAR)
    ref, gel = (tg.history(_worn, E_star=k * E_STAR, G_star=k * G_STAR, mu=MU, x_max=2 * A,
                           n_grid=100, **steps) for k in (1.0, s))
    for name in ("contact_radius", "stick_radius", "u_x"):
        assert np.allclose(getattr(gel, name), getattr(ref, name), rtol=1e-9, atol=0), name
    for name in ("normal_force", "F_x", "dissipated"):
        assert np.allclose(getattr(gel, name), s * getattr(ref, name), rtol=1e-9, atol=0), name


def test_history_zero_normal_force_states():
    """F_N = 0: no contact, depth 0, no force, and under force control u_x stays (no spring)."""
    F = MU * F_N
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     normal_force=[0.0, F_N, 0.0], F_x=[0.0, 0.5 * F, 0.0], n_grid=100)
    assert res.depth[0] == res.depth[2] == 0.0
    assert res.normal_force[0] == res.normal_force[2] == 0.0
    assert res.u_x[2] == res.u_x[1] > 0 and res.contact_radius[2] == 0.0
    assert not res.sliding[2] and res.stick_radius[2] == 0.0
    assert res.x.size == 101


def test_history_default_grid_and_the_smallest_one():
    d = A * A / R
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     depth=[d], u_x=[0.0], estimate_error=False)
    assert res.x.size == 1001
    small = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                       depth=[d], u_x=[0.0], n_grid=8, estimate_error=False)
    assert small.x.size == 9


def test_history_tiny_contact_inside_the_first_interval():
    """A contact narrower than one interval (one spring) sticks at small u (stick radius = the
    contact radius) and slides beyond its onset (sliding, stick radius 0)."""
    h = 1.5 * A / 100
    d = (0.4 * h) ** 2 / R
    on = MU * E_STAR * d / G_STAR
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     depth=[d, d, d], u_x=[0.0, 1e-3 * on, 3 * on], n_grid=100,
                     estimate_error=False)
    c1 = float(np.interp(d, res.x[:2] ** 2 / R, res.x[:2]))
    assert res.contact_radius[1] == pytest.approx(c1, rel=1e-14)
    assert res.stick_radius[1] == res.contact_radius[1] and not res.sliding[1]
    assert res.sliding[2] and res.stick_radius[2] == 0.0


def test_history_stick_edges_after_normal_load_changes():
    """Sphere: d, then u = u*/2, then 1.5 d at that u (new springs enter unsheared), then
    u = 0.8 u*, then back to 0.3 u*. By hand from the springs (u* = mu E* d/G*, g = x^2/R):
    the stick radii are a, a sqrt(1/2), a sqrt(1.5) (all stick), a sqrt(1.2) (the new springs
    slide where mu E* (1.5 d - g) < 0.3 mu E* d) and a sqrt(1.25) (the slid springs reverse
    elastically while cap - 0.5 mu E* d >= -cap). Second order in h: within (h/a)^2 a (the
    errors measured on 1000 intervals are 0.1-0.2 of it), and within stick_radius_error."""
    d = A * A / R
    on = MU * E_STAR * d / G_STAR
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     n_grid=1000, depth=[d, d, 1.5 * d, 1.5 * d, 1.5 * d],
                     u_x=np.array([0.0, 0.5, 0.5, 0.8, 0.3]) * on)
    exact = A * np.sqrt([1.0, 0.5, 1.5, 1.2, 1.25])
    err = np.abs(res.stick_radius - exact)
    assert np.max(err) <= (1.5e-3) ** 2 * A, err / A
    assert np.max(err) <= res.stick_radius_error


def test_history_final_traction_vanishes_outside_the_final_contact():
    """The contact shrinks at the end (1, 1.5, 0.8 d at u = u*/2): the final traction is 0
    beyond the final contact radius (not that of an earlier state)."""
    d = A * A / R
    on = MU * E_STAR * d / G_STAR
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     n_grid=200, depth=[d, 1.5 * d, 0.8 * d], u_x=[0.5 * on] * 3)
    q = res.traction()
    assert np.all(q[res.x >= res.contact_radius[-1]] == 0)
    assert np.max(np.abs(q)) > 0 and q.shape == res.x.shape


@pytest.mark.parametrize("n, frac", [(200, 0.5), (1000, 0.3)])
def test_history_traction_error_bounds_and_is_near_the_true_error(n, frac):
    """Cattaneo (constant depth, u = frac u*): the reported traction_error bounds the largest
    error against the closed form (measured 0.62-0.65 of it in these two cases) and is not
    grossly larger (below 5 % of the largest traction; measured 1.3-3.2 %)."""
    d = A * A / R
    on = MU * E_STAR * d / G_STAR
    ct = _sphere()
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     n_grid=n, depth=[d, d], u_x=[0.0, frac * on])
    exact = ct.traction(res.x, frac * on)
    assert np.max(np.abs(res.traction() - exact)) <= res.traction_error
    assert res.traction_error <= 0.05 * np.max(np.abs(exact))


def _spring_sum(D, f, cap, w, m):
    return float(np.sum(w * np.clip(f + G_STAR * m * D, -cap, cap)))


def test_solve_shift_against_bisection_of_the_spring_sum():
    """_solve_shift: the shift D with sum w clip(f + G* m D, -cap, cap) = target, against a
    bisection of that sum (each spring's elastic range contains D = 0, as in the solver,
    where |f| <= cap), for random springs and targets across (-total, total), near both ends
    (1e-12 .. 1e-3 of total, and a few ulp: the first and last pieces), and at +-total."""
    rng = np.random.default_rng(11)
    for trial in range(6):
        N = (3, 8, 40, 40, 200, 2)[trial]
        cap = rng.uniform(0.1, 2.0, N) * 1e5 * (rng.uniform(size=N) > 0.2)
        f = cap * rng.uniform(-1, 1, N) * (trial % 2)  # fresh (f = 0) or sheared springs
        if trial == 3:
            f = cap * np.sign(rng.uniform(-1, 1, N))  # every spring at its limit
        w = rng.uniform(0.5, 1.0, N) * 1e-6
        m = np.where(cap > 0, rng.choice([1.0, 0.25, rng.uniform()], N), 0.0)
        total = float(np.sum(w * cap))
        lo = float(np.min(np.where(cap > 0, (-cap - f) / (G_STAR * np.maximum(m, 1e-300)), 0)))
        hi = float(np.max(np.where(cap > 0, (cap - f) / (G_STAR * np.maximum(m, 1e-300)), 0)))
        deltas = [1e-12, 1e-9, 1e-6, 1e-3] + [k * EPS for k in (1, 2, 4, 8)]
        targets = list(np.linspace(-0.95, 0.95, 21) * total)
        targets += [s * total * (1 - dl) for dl in deltas for s in (1, -1)]
        for t in targets:
            D, full = tg._solve_shift(f, cap, w, m, G_STAR, t, total, 0)
            tol = 1e-9 * (hi - lo)  # D = hi at t = total (1 - eps) up to its rounding
            assert not full and lo - tol <= D <= hi + tol, (trial, t / total, D)
            a, b = lo, hi  # the sum increases with D: bisection to the last bit
            for _ in range(200):
                mid = 0.5 * (a + b)
                if _spring_sum(mid, f, cap, w, m) < t:
                    a = mid
                else:
                    b = mid
            # 1e-9 of the range: the piecewise linear root against bisection; near the ends
            # the one sliding spring's slope makes D sensitive to t's last bits
            assert abs(D - 0.5 * (a + b)) <= tol, (trial, t / total)
        for s in (1, -1):
            D, full = tg._solve_shift(f, cap, w, m, G_STAR, s * total, total, 0)
            assert full and D == (hi if s > 0 else lo)


def test_powerlaw_nearly_stuck_traction_is_the_same_in_one_call():
    """The Gauss-Legendre stick traction (c >= 2a/3, c/2 < r < c) of several radii in one
    call equals each radius alone (vectorized: one sum per radius)."""
    ct = _sphere(prof=tg.PowerLaw(2e9, 4.0))
    u = 0.05 * ct.slide_onset
    c = float(ct.stick_radius(u))
    assert c >= 2 * A / 3
    r = np.array([0.55, 0.7, 0.9, 0.99]) * c
    one = np.array([float(ct.traction(ri, u)) for ri in r])
    # the same sums in the same order: equal to the last bit
    assert np.array_equal(ct.traction(r, u), one)


def test_history_normal_force_up_to_the_grid_capacity():
    """Force control: a force between the springs' sums at d = g(x_{n-1}) and d = g(x_max)
    (the last interval) is carried, with the contact edge in the last interval; beyond
    g(x_max)'s sum it is refused."""
    X = 2 * A
    x = np.linspace(0, X, 9)
    kw = dict(E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=X, n_grid=8, estimate_error=False)
    caps = tg.history(tg.Paraboloid(R), depth=[x[-2] ** 2 / R, X * X / R], u_x=[0, 0], **kw)
    F = 0.5 * (caps.normal_force[0] + caps.normal_force[1])
    res = tg.history(tg.Paraboloid(R), normal_force=[F], u_x=[0.0], **kw)
    assert res.normal_force[0] == pytest.approx(F, rel=1e-14)
    assert x[-2] < res.contact_radius[0] < X
    with pytest.raises(ValueError, match=r"^normal_force\[0\] = .* needs a contact wider"):
        tg.history(tg.Paraboloid(R), normal_force=[caps.normal_force[1] * 1.001], u_x=[0.0],
                   **kw)


@pytest.mark.parametrize("scale", [1.0, 1e-9], ids=["steel", "gel"])
def test_history_small_stick_zone_is_the_root_of_the_interpolated_limit(scale):
    """Constant depth, fresh loading: every stuck spring carries G* u, so the stick edge is
    where the linear interpolant of the nodes' limits mu q_z meets G* u (np.interp), also
    when it lies in the first or second interval; in steel and in gel units (1e-9 Pa scale,
    sub-unit line loads)."""
    d = A * A / R
    n, X = 100, 1.5 * A
    h = X / n
    x = np.linspace(0, X, n + 1)
    cap = scale * MU * E_STAR * np.maximum(d - x * x / R, 0)
    on = MU * E_STAR * d / G_STAR
    for c in (0.5 * h, 1.5 * h, 2.5 * h, 7.3 * h):
        u = on * (1 - (c / A) ** 2)  # Cattaneo: c = a sqrt(1 - u/u*)
        res = tg.history(tg.Paraboloid(R), E_star=scale * E_STAR, G_star=scale * G_STAR, mu=MU,
                         x_max=X, depth=[d, d], u_x=[0.0, u], n_grid=n, estimate_error=False)
        inside = cap > 0
        level = scale * G_STAR * u
        ref = float(np.interp(level, cap[inside][::-1], x[inside][::-1]))
        # 1e-12: the same interpolation, rounded differently
        assert res.stick_radius[1] == pytest.approx(ref, rel=1e-12), c / h


def test_history_traction_error_of_a_shrinking_contact():
    """A contact that grows and then shrinks (1, 1.5, 0.8 d at u = u*/2): traction_error
    bounds the final traction's difference from a run on 8 times finer a grid and is within
    3 times it (measured 1.72 times on 500 intervals; the run on h/8 has about a third of
    the sqrt(h) error next to the edges, so the difference is the error within ~35 %)."""
    d = A * A / R
    on = MU * E_STAR * d / G_STAR
    kw = dict(E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A, depth=[d, 1.5 * d, 0.8 * d],
              u_x=[0.5 * on] * 3)
    res = tg.history(tg.Paraboloid(R), n_grid=500, **kw)
    fine = tg.history(tg.Paraboloid(R), n_grid=4000, estimate_error=False, **kw)
    diff = np.max(np.abs(res.traction() - fine.traction()[::8]))
    assert diff <= res.traction_error <= 3 * diff


@pytest.mark.parametrize("edge_in", [1.5, 5.3])
def test_history_stick_edge_through_springs_of_varying_shear_is_exact_for_the_cone(edge_in):
    """Cone (g = k x linear): slide fully at depth d (each spring at its limit mu E* (d - k x)),
    press to 1.5 d at that u (the limits grow, the shear stays), then pull back by delta. The
    stuck springs' |f| = G* delta - mu E* (d - k x) and the limits mu E* (1.5 d - k x) are both
    linear in x, so the solver's edge (|f| linear through the two stuck nodes before it, the
    limit linear between the nodes around it) is exact: by hand the springs slip from
    x_e = (2.5 d - G* delta/(mu E*))/(2 k) on (the pressed ring beyond the old contact slips
    too). x_e 1.5 or 5.3 intervals from the axis."""
    cone = tg.Cone(0.1)
    k = float(cone.g(1.0))
    d = k * A
    on = MU * E_STAR * d / G_STAR
    n, X = 100, 1.5 * 1.5 * A
    x_e = edge_in * X / n
    delta = MU * E_STAR * (2.5 * d - 2 * k * x_e) / G_STAR
    u1 = 2 * on
    res = tg.history(cone, E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=X, n_grid=n,
                     depth=[d, d, 1.5 * d, 1.5 * d], u_x=[0.0, u1, u1, u1 - delta],
                     estimate_error=False)
    assert res.sliding[1] and not res.sliding[3]
    # 1e-12: linear interpolation of linear data, a few roundings of differences of ~d
    assert res.stick_radius[3] == pytest.approx(x_e, rel=1e-12)


@pytest.mark.parametrize("u1", [0.2, 0.9])
def test_history_springs_landing_exactly_on_their_limits(u1):
    """A flat-ended profile (g = 0 to b = 0.8 a, slope 0.05 beyond) at depth d slid to u1 u*,
    pressed to 1.5 d, then pulled by G* D = mu E* d/2 exactly: the springs that had slid land
    on their new limits to rounding, so which of them count as stuck is rounding's choice. By
    hand the stick zone ends between x = b + (1 - u1) d/0.05 (the springs that stuck
    throughout) and the contact radius; the edge is taken at a node there (finite, not beyond
    the contact), whatever the rounding."""
    a, slope = 1e-4, 0.05
    b, d = 0.8 * a, 1e-6

    def g(x):
        x = np.abs(x)
        return np.where(x > b, slope * (x - b), 0.0)

    on = MU * E_STAR * d / G_STAR
    X = b + 4.5 * d / slope
    res = tg.history(g, E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=X, n_grid=100,
                     depth=[d, d, 1.5 * d, 1.5 * d], u_x=np.array([0, u1, u1, u1 + 0.5]) * on,
                     estimate_error=False)
    lo = b + (1 - u1) * d / slope  # stuck throughout: u1 mu E* d < mu E* (d - g) at step 2
    h = X / 100
    assert lo - h <= res.stick_radius[3] <= res.contact_radius[3], (lo / a, res.stick_radius / a)


@pytest.mark.parametrize("n", [100, 1000])
def test_history_traction_at_full_slip_is_mu_times_hertz(n):
    """Everything slides: q_x = mu q_z = mu E* (d - x^2/R), a parabola whose inverse (5.59)
    is mu times Hertz's pressure. abel finds its edge from the samples (the cubic through the
    last four is exact for it): to 1e-10 of mu p0 (measured 2e-13). Given the solver's
    contact radius (linear interpolation of g, O(h^2) off) as the edge it was 9e-5 on 100
    intervals, 3e-6 on 1000."""
    d = A * A / R
    on = MU * E_STAR * d / G_STAR
    res = tg.history(tg.Paraboloid(R), E_star=E_STAR, G_star=G_STAR, mu=MU, x_max=1.5 * A,
                     n_grid=n, depth=[d, d], u_x=[0.0, 2 * on], estimate_error=False)
    p0 = 3 * F_N / (2 * np.pi * A * A)
    exact = MU * p0 * np.sqrt(np.maximum(1 - (res.x / A) ** 2, 0))
    assert np.max(np.abs(res.traction() - exact)) <= 1e-10 * MU * p0
