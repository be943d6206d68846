"""Tests that kill the surviving mutants of numeric/scene/kinds/friction.py (the tangential
effects of a scene) and numeric/scene/kinds/base.py (benchmarks/mutation_runs/scene_kinds.json;
the rest is explained in benchmarks/mutation_notes_scene_friction.toml).

Each checks, through the public scene API, a line that computes something: the closed-form
Cattaneo-Mindlin numbers of a sphere against Johnson's forms at 30 digits, the grids and
lengths of the profiles and loops against their documented construction, the springs' runs
(their load paths, grids and clipping at the sliding force) against Hertz, Mindlin and the
paths the docstrings give, the composition of each reported rel_error from the springs' own
grid estimates (tangential.history wrapped to keep its runs), and every refusal's file, key and
message. The springs run on SPRING_GRID = 100 intervals instead of 1000 (monkeypatched: the
bookkeeping is tested here, the solver's convergence in tests/test_tangential.py), so the file
takes about a second.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import scene
from hertzmdr.numeric import tangential as tg
from hertzmdr.numeric.scene.kinds import friction
from hertzmdr.numeric.scene.schema import SceneError

# every pytest.approx here has abs=0: its default absolute tolerance (1e-12) would accept any
# error of the small values compared (rel_errors of 1e-14, displacements of 1e-7 m)
STEEL = {"E": "210 GPa", "nu": 0.3}
FLAT = {"shape": "flat", **STEEL}
SPHERE = {"shape": "sphere", "radius": "10 mm", **STEEL}
R, F_N, MU = 0.01, 100.0, 0.6
#: a paraboloid R = 10 mm sampled on 41 points to 1 mm: the numerical MDR, run by the springs
_RS = np.linspace(0.0, 1e-3, 41)
SAMPLED = {"shape": "profile", "r": list(_RS), "f": list(_RS**2 / (2 * R)), **STEEL}
TANGENTIAL = ["sliding_force", "tangential_stiffness", "tangential_force",
              "tangential_displacement", "stick_radius", "traction_profile"]
OSCILLATING = TANGENTIAL + ["dissipated_energy", "hysteresis_loop"]
SPRING_GRID = 100  # the springs' grid in these tests (friction.SPRING_GRID is 1000)


def run(bodies, load, effects, mu=MU):
    return scene.load({"effects": list(effects), "body": bodies, "load": load,
                       "interface": {"friction": mu}}).run()["effects"]


@pytest.fixture
def springs(monkeypatch):
    """The springs on SPRING_GRID intervals, and every tangential.history run of the scene
    (its keyword arguments and its History) in the returned list, in order."""
    monkeypatch.setattr(friction, "SPRING_GRID", SPRING_GRID)
    runs = []
    history = tg.history

    def recording(*args, **kw):
        H = history(*args, **kw)
        runs.append((kw, H))
        return H

    monkeypatch.setattr(tg, "history", recording)
    return runs


def _main_run(runs):
    """The run the effects read: the first one with its error estimate (the runs before it,
    without, find the grids' sliding force)."""
    return next(H for kw, H in runs if kw.get("estimate_error", True))


# -- the references: Hertz and Cattaneo-Mindlin for two steel bodies, 30 digits ----------------

class Mindlin:
    """Johnson's Cattaneo-Mindlin forms of a sphere R on a flat under F [N] (mpmath, 30
    digits): E* (5.26), G* = 2 G/(2 - nu) for two equal bodies, a (5.29)."""

    def __init__(self, F=F_N, R=R, mu=MU):
        with mp.workdps(30):
            E, nu = mp.mpf(210e9), mp.mpf("0.3")
            self.E_star = E / (2 * (1 - nu**2))
            self.G_star = 2 * (E / (2 * (1 + nu))) / (2 - nu)
            self.F, self.mu = mp.mpf(F), mp.mpf(mu)
            self.a = (3 * self.F * mp.mpf(R) / (4 * self.E_star)) ** (mp.mpf(1) / 3)
            self.muF = self.mu * self.F
            self.u_slide = 3 * self.muF / (4 * self.a * self.G_star)  # u at full sliding

    def u(self, Fx):
        with mp.workdps(30):
            return self.u_slide * (1 - (1 - mp.mpf(Fx) / self.muF) ** (mp.mpf(2) / 3))

    def force(self, u):
        with mp.workdps(30):
            return self.muF * (1 - (1 - mp.mpf(u) / self.u_slide) ** (mp.mpf(3) / 2))

    def c(self, Fx):
        with mp.workdps(30):
            return self.a * (1 - mp.mpf(Fx) / self.muF) ** (mp.mpf(1) / 3)

    def q(self, r, Fx):
        """Cattaneo's traction: mu p0 sqrt(1 - r^2/a^2), less (c/a) mu p0 sqrt(1 - r^2/c^2)
        inside the stick radius c; 0 outside the contact."""
        with mp.workdps(30):
            r, c = mp.mpf(r), self.c(Fx)
            if r >= self.a:
                return mp.mpf(0)
            p0 = 3 * self.F / (2 * mp.pi * self.a**2)
            q = self.mu * p0 * mp.sqrt(1 - (r / self.a) ** 2)
            return q - (self.mu * p0 * c / self.a * mp.sqrt(1 - (r / c) ** 2) if r < c else 0)

    def energy(self, Fa):
        """Mindlin-Deresiewicz's energy per cycle (Johnson (7.59), (2 - nu)/G = 4/G*)."""
        with mp.workdps(30):
            X = mp.mpf(Fa) / self.muF
            return (9 * self.muF**2 / (10 * self.a) * 4 / self.G_star
                    * (1 - (1 - X) ** (mp.mpf(5) / 3)
                       - 5 * X / 6 * (1 + (1 - X) ** (mp.mpf(2) / 3))))


def close(value, ref, rtol):
    """|value/ref - 1| <= rtol with ref an mpmath number."""
    assert abs(float(mp.mpf(value) / ref - 1)) <= rtol, (value, ref, rtol)


# -- the closed forms of a sphere (node_tangential, the effects' closed-form branches) ----------

def test_sphere_friction_alone():
    """Friction without a tangential load: mu F and 2 G* a of Hertz's a at 30 digits (the
    closed forms, 1e-14: a few roundings of a and G*), the other effects refused."""
    eff = run([SPHERE, FLAT], {"force": "100 N"}, ["sliding_force", "tangential_stiffness"])
    m = Mindlin()
    close(eff["sliding_force"]["value"], m.muF, 1e-14)
    close(eff["tangential_stiffness"]["value"], 2 * m.G_star * m.a, 1e-14)
    assert eff["sliding_force"]["method"] == "Coulomb: mu F"
    assert eff["tangential_stiffness"]["method"] == "2 G* a (all springs stick)"


@pytest.mark.parametrize("load", [{"force": "30 N"}, {"displacement": "5e-7 m"}])
def test_sphere_under_a_tangential_load(load):
    """A tangential force, or a displacement, at 100 N: F_x, u_x, the stick radius and
    Cattaneo's traction against Johnson's forms at 30 digits (TANGENTIAL_RTOL = 1e-13, the
    closed forms' error), sliding force and stiffness as without it; the traction's grid is
    201 points on [0, a] less the edge (r[0] = 0: a sphere's q is finite on the axis)."""
    eff = run([SPHERE, FLAT], {"force": "100 N", "tangential": load}, TANGENTIAL)
    m = Mindlin()
    if "force" in load:
        Fx, u = 30.0, m.u(30)
    else:
        Fx, u = float(m.force(5e-7)), mp.mpf(5e-7)
    for name, ref in (("tangential_force", Fx), ("tangential_displacement", u),
                      ("stick_radius", m.c(Fx))):
        close(eff[name]["value"], ref, 1e-13)
        assert eff[name]["rel_error"] == friction.TANGENTIAL_RTOL
        assert eff[name]["method"] == friction.METHOD
    close(eff["sliding_force"]["value"], m.muF, 1e-14)
    close(eff["tangential_stiffness"]["value"], 2 * m.G_star * m.a, 1e-14)
    q = eff["traction_profile"]
    r = np.asarray(q["value"]["r"])
    assert r.shape == (200,) and r[0] == 0.0
    assert r == pytest.approx(np.linspace(0.0, float(m.a), 201)[:-1], rel=1e-14, abs=0)
    qq = np.asarray(q["value"]["q"])
    ref = np.array([float(m.q(x, Fx)) for x in r[::20]])
    # 1e-13 of the peak: q is a difference of two square roots near the stick edge
    assert np.max(np.abs(qq[::20] - ref)) <= 1e-12 * ref.max()
    assert q["method"] == friction.METHOD + ", (5.59)"
    assert q["rel_error"] == friction.TANGENTIAL_RTOL


@pytest.mark.parametrize("points", [201, 101])
def test_sphere_oscillating_closed_forms(monkeypatch, points):
    """+-30 N at 100 N, three cycles: the energy of a cycle against Mindlin-Deresiewicz, and
    the loop as documented: the first loading on n1 = FIELD_POINTS // 4 displacements from 0
    to u* (Mindlin's F(u)), then `cycles` copies of Masing's loop, 2 (FIELD_POINTS // 2)
    points from (u*, F*) down to (-u*, -F*) and back, F = F* - 2 F((u* - u)/2). With
    FIELD_POINTS = 201 and, monkeypatched, 101 (n1 = 50 is also linspace's default count)."""
    monkeypatch.setattr(friction, "FIELD_POINTS", points)
    eff = run([SPHERE, FLAT], {"force": "100 N", "oscillating": {"amplitude": "30 N",
                                                                  "cycles": 3}},
              ["dissipated_energy", "hysteresis_loop"])
    m = Mindlin()
    close(eff["dissipated_energy"]["value"], m.energy(30), 1e-13)
    assert eff["dissipated_energy"]["rel_error"] == friction.TANGENTIAL_RTOL
    assert eff["dissipated_energy"]["method"] == ("springs' loops (Mindlin-Deresiewicz for a "
                                                  "sphere)")
    loop = eff["hysteresis_loop"]
    u, F = np.asarray(loop["value"]["u"]), np.asarray(loop["value"]["F"])
    n1, half = points // 4, points // 2  # half: the points of each branch of the loop
    assert u.shape == F.shape == (n1 + 3 * 2 * half,)
    us = float(m.u(30))
    assert u[:n1] == pytest.approx(np.linspace(0.0, us, n1), rel=1e-13, abs=0)
    for k in (n1 // 5, n1 // 2, n1 - 1):
        close(F[k], m.force(u[k]), 1e-12)  # F(u) near sliding: 1 - u/u_s loses 1 digit
    assert u[n1] == pytest.approx(us, rel=1e-13, abs=0)
    assert F[n1] == pytest.approx(30.0, rel=1e-13, abs=0)
    assert u[n1 + half - 1] == pytest.approx(-us, rel=1e-13, abs=0)
    for k in (n1 + 10, n1 + half // 2, n1 + half - 1):  # unloading, by Masing's rule
        close(F[k], 30 - 2 * m.force((us - u[k]) / 2), 1e-12)
    for k in (n1 + half + 10, n1 + 2 * half - 10):  # reloading: the unloading one mirrored
        close(F[k], -(30 - 2 * m.force((us + u[k]) / 2)), 1e-12)
    one = slice(n1, n1 + 2 * half)
    assert np.array_equal(u[one], u[n1 + 2 * half:n1 + 4 * half])
    assert np.array_equal(F[one], F[n1 + 4 * half:])
    assert loop["rel_error"] == friction.TANGENTIAL_RTOL
    assert loop["method"].startswith("first loading, then Masing's branches")


def test_cone_traction_starts_off_the_axis():
    """A cone's traction (its pressure log-infinite on the axis): the profile's first point
    at 1e-3 a, the rest of the 201-point grid on [0, a) as for every kind, every q finite and
    positive (partial slip under a small displacement)."""
    eff = run([{"shape": "cone", "angle": 0.35, **STEEL}, FLAT],
              {"depth": "1 um", "tangential": {"displacement": "1 nm"}},
              ["traction_profile", "contact_radius"])
    a = eff["contact_radius"]["value"]
    r, q = np.asarray(eff["traction_profile"]["value"]["r"]), np.asarray(
        eff["traction_profile"]["value"]["q"])
    assert r.shape == (200,) and r[0] == pytest.approx(1e-3 * a, rel=1e-15, abs=0)
    assert r[1:] == pytest.approx(np.linspace(0.0, a, 201)[1:-1], rel=1e-14, abs=0)
    assert np.all(np.isfinite(q)) and np.all(q > 0)


def test_flat_punch_sticks_until_it_slides():
    """A flat punch (radius 0.1 mm) under 30 N tangential: all springs stick (stick radius =
    a), u = F_x/(2 G* a) with a the punch's radius (the punch's profile built at the scene's
    depth)."""
    eff = run([{"shape": "flat_punch", "radius": "0.1 mm", **STEEL}, FLAT],
              {"depth": "1 um", "tangential": {"force": "1 N"}},
              ["tangential_displacement", "stick_radius"])
    m = Mindlin()
    close(eff["tangential_displacement"]["value"], 1 / (2 * m.G_star * mp.mpf("1e-4")), 1e-13)
    close(eff["stick_radius"]["value"], mp.mpf("1e-4"), 1e-13)


# -- the springs at a constant normal load (_spring_state, _series, the springs' branches) -----

def test_sampled_friction_alone(springs):
    """Friction alone on a sampled profile (no closed form): mu F of the state's force and
    2 G* a of its contact radius, both with the state's rel_error (the numerical MDR's), and
    no run of the springs."""
    eff = run([SAMPLED, FLAT], {"force": "100 N"},
              ["sliding_force", "tangential_stiffness", "force", "contact_radius"])
    m = Mindlin()
    rel = eff["force"]["rel_error"]
    assert 0 < rel < 1e-12  # the numerical MDR's own, not CLOSED_FORM_RTOL
    assert eff["sliding_force"]["value"] == pytest.approx(MU * eff["force"]["value"], rel=1e-15,
                                                          abs=0)
    assert eff["tangential_stiffness"]["value"] == pytest.approx(
        2 * float(m.G_star) * eff["contact_radius"]["value"], rel=1e-15, abs=0)
    for name in ("sliding_force", "tangential_stiffness"):
        assert eff[name]["rel_error"] == rel
    assert eff["sliding_force"]["method"] == "Coulomb: mu F"
    assert springs == []


@pytest.mark.parametrize("load", [{"force": "30 N"}, {"displacement": "5e-7 m"}])
def test_sampled_tangential_load_runs_two_states(springs, load):
    """A monotonic tangential load on a sampled paraboloid: the springs run the two states
    (0, then the load) at the state's depth, on SPRING_GRID intervals of [0, 1.25 a]; the
    prescribed quantity comes back exactly with the state's rel_error (its grid error is 0),
    the other against Mindlin within its reported error (the springs' half-grid estimate plus
    the state's); the traction on the grid's nodes up to a, within its error of Cattaneo's."""
    eff = run([SAMPLED, FLAT], {"force": "100 N", "tangential": load},
              TANGENTIAL + ["force", "contact_radius"])
    m = Mindlin()
    st_rel, a = eff["force"]["rel_error"], eff["contact_radius"]["value"]
    H = _main_run(springs)
    kw = springs[-1][0]
    assert np.array_equal(kw["depth"], np.full(2, H.depth[0])) and kw["n_grid"] == SPRING_GRID
    assert kw["x_max"] == pytest.approx(1.25 * a, rel=1e-15, abs=0)
    given, other = (("tangential_force", "tangential_displacement") if "force" in load else
                    ("tangential_displacement", "tangential_force"))
    value = 30.0 if "force" in load else 5e-7
    assert eff[given]["value"] == value and eff[given]["rel_error"] == st_rel
    Fx = 30.0 if "force" in load else float(m.force(5e-7))
    ref = m.u(30) if "force" in load else Fx
    name = "u_x" if "force" in load else "F_x"
    got = eff[other]
    assert got["value"] == getattr(H, name)[1]
    assert got["rel_error"] == getattr(H, name + "_error") / abs(got["value"]) + st_rel
    close(got["value"], ref, got["rel_error"])
    c = eff["stick_radius"]
    assert c["rel_error"] == H.stick_radius_error / c["value"] + st_rel
    close(c["value"], m.c(Fx), c["rel_error"])
    for e in (given, other, "stick_radius"):
        assert eff[e]["method"] == friction.SPRINGS
    close(eff["sliding_force"]["value"], m.muF, 1e-12)  # the sampled profile's F = 100 N
    assert eff["tangential_stiffness"]["value"] == pytest.approx(
        2 * float(m.G_star) * a, rel=1e-15, abs=0)
    q = eff["traction_profile"]
    r, qq = np.asarray(q["value"]["r"]), np.asarray(q["value"]["q"])
    h = 1.25 * a / SPRING_GRID
    assert r[-1] <= a < r[-1] + h and np.allclose(np.diff(r), h, rtol=1e-9, atol=0)
    assert q["rel_error"] == H.traction_error / np.max(np.abs(qq)) + st_rel
    ref = np.array([float(m.q(x, Fx)) for x in r])
    assert np.max(np.abs(qq - ref)) <= q["rel_error"] * np.max(qq)
    assert q["method"] == friction.SPRINGS + ", (5.59) of the springs' line load"


@pytest.mark.parametrize("points", [201, 101])
def test_sampled_oscillation(springs, monkeypatch, points):
    """+-30 N at 100 N, two cycles, through the springs: the force path as documented (0 to
    F* on n1 = FIELD_POINTS // 4 states, then F* to -F* and back on n2 = FIELD_POINTS // 2
    each, the turning states shared; FIELD_POINTS 201 and, monkeypatched, 101: n1 = 50 is
    also linspace's default count); the effects at the first arrival at F* (state n1 - 1); the
    loop the first loading and the cycle repeated; the energy the friction work of the cycle
    against Mindlin-Deresiewicz; each rel_error the grid estimate of its run plus the
    state's; the traction from a run up to the first arrival on the same grid."""
    monkeypatch.setattr(friction, "FIELD_POINTS", points)
    n1, n2 = points // 4, points // 2
    eff = run([SAMPLED, FLAT], {"force": "100 N", "oscillating": {"amplitude": "30 N",
                                                                  "cycles": 2}},
              OSCILLATING + ["force"])
    m = Mindlin()
    st_rel = eff["force"]["rel_error"]
    H = _main_run(springs)
    path = np.concatenate([np.linspace(0, 30, n1), np.linspace(30, -30, n2)[1:],
                           np.linspace(-30, 30, n2)[1:]])
    assert np.array_equal(H.F_x, path)
    assert eff["tangential_force"]["value"] == 30.0
    assert eff["tangential_displacement"]["value"] == H.u_x[n1 - 1]
    assert eff["stick_radius"]["value"] == H.stick_radius[n1 - 1]
    close(eff["tangential_displacement"]["value"], m.u(30),
          eff["tangential_displacement"]["rel_error"])
    loop = eff["hysteresis_loop"]
    assert np.array_equal(loop["value"]["F"], np.concatenate([path[:n1], path[n1:], path[n1:]]))
    assert np.array_equal(loop["value"]["u"], np.concatenate([H.u_x[:n1], H.u_x[n1:],
                                                               H.u_x[n1:]]))
    assert loop["rel_error"] == max(H.u_x_error / np.max(np.abs(H.u_x)),
                                    H.F_x_error / 30.0) + st_rel
    assert loop["method"] == (friction.SPRINGS + ": first loading, then one cycle of the springs "
                              "(repeated: a cycle returns every spring to its state)")
    W = eff["dissipated_energy"]
    assert W["value"] == H.dissipated[-1] - H.dissipated[n1 - 1]
    assert W["rel_error"] == 2 * H.dissipated_error / W["value"] + st_rel
    close(W["value"], m.energy(30), W["rel_error"])
    # the traction at the first arrival: a run of the states 0..n1 - 1 on the main grid
    kw, H1st = springs[-1]
    assert kw["n_grid"] == SPRING_GRID and kw["x_max"] == H.x[-1]
    assert np.array_equal(kw["F_x"], path[:n1])
    q = eff["traction_profile"]
    assert np.array_equal(q["value"]["q"], H1st.traction()[H1st.x <= H1st.contact_radius[-1]])
    assert q["rel_error"] == H1st.traction_error / np.max(np.abs(q["value"]["q"])) + st_rel


def test_tangential_load_at_the_sliding_force(springs):
    """A tangential force of mu F: accepted (it is not above mu F (1 + 1e-12)) and clipped to
    mu times the smaller normal force of the two grids the springs run on (SPRING_GRID and
    its half, whose mu F lies a little below the state's), so neither run refuses it; the
    refusal's boundary mu F (1 + 1e-12) itself is accepted, 61 N is refused naming the key,
    the value and mu F."""
    eff = run([SAMPLED, FLAT], {"force": "100 N"}, ["sliding_force"])
    muF = eff["sliding_force"]["value"]
    springs.clear()
    for Fx in (muF, muF * (1 + 5e-13), muF * (1 + 1e-12)):
        springs.clear()
        got = run([SAMPLED, FLAT], {"force": "100 N", "tangential": {"force": Fx}},
                  ["tangential_force"])["tangential_force"]["value"]
        (kw1, H1), (kw2, H2) = springs[:2]  # the grids' mu F: fine, then half
        assert (kw1["n_grid"], kw2["n_grid"]) == (SPRING_GRID, SPRING_GRID // 2)
        lim = MU * min(H1.normal_force[0], H2.normal_force[0])
        assert H2.normal_force[0] < H1.normal_force[0] < muF / MU  # the half grid's is lower
        assert got == lim
    with pytest.raises(SceneError) as info:
        run([SAMPLED, FLAT], {"force": "100 N", "tangential": {"force": "61 N"}},
            ["tangential_force"])
    e = info.value
    assert (e.where, e.key) == ("<scene>", "load.tangential.force")
    assert e.message == (f"61.0 N exceeds the sliding force mu F = {muF!r} N (mu = 0.6); "
                         "valid: <= mu F")
    with pytest.raises(SceneError) as info:
        run([SAMPLED, FLAT], {"force": "100 N", "oscillating": {"amplitude": "61 N"}},
            ["tangential_force"])
    assert (info.value.where, info.value.key) == ("<scene>", "load.oscillating.amplitude")


def test_oscillation_at_the_sliding_force(springs):
    """An amplitude of mu F: the whole path (both signs) is clipped to the grids' smaller
    mu F, so the half grid's run of the error estimate takes it too."""
    eff = run([SAMPLED, FLAT], {"force": "100 N", "oscillating": {"amplitude": "60 N"}},
              ["tangential_force", "hysteresis_loop"])
    (_, H1), (_, H2) = springs[:2]
    lim = MU * min(H1.normal_force[0], H2.normal_force[0])
    F = np.asarray(eff["hysteresis_loop"]["value"]["F"])
    assert eff["tangential_force"]["value"] == lim and F.max() == lim and F.min() == -lim


def test_displacement_is_never_clipped(springs):
    """A tangential displacement is not a force: with mu = 1e-9 (mu F = 6e-8 N, below the
    1e-6 m asked) it is neither refused nor clipped to mu F; the springs slide."""
    eff = run([SAMPLED, FLAT], {"force": "100 N", "tangential": {"displacement": 1e-6}},
              ["tangential_displacement", "tangential_force", "sliding_force"], mu=1e-9)
    assert eff["tangential_displacement"]["value"] == 1e-6
    assert eff["tangential_force"]["value"] == pytest.approx(eff["sliding_force"]["value"],
                                                             rel=1e-2, abs=0)  # full sliding


def test_sampled_grid_ends_at_the_samples(springs):
    """A sampled profile that ends at 0.175 mm, inside 1.25 a = 0.197 mm (60 N): the springs'
    grid ends at the last sample (the profile is not known beyond)."""
    tip = {**SAMPLED, "r": list(_RS[:8]), "f": list(_RS[:8] ** 2 / (2 * R))}
    eff = run([tip, FLAT], {"force": "60 N", "tangential": {"force": "10 N"}},
              ["traction_profile", "contact_radius"])
    a = eff["contact_radius"]["value"]
    assert _RS[7] < 1.25 * a
    assert springs[-1][0]["x_max"] == _RS[7]
    r = np.asarray(eff["traction_profile"]["value"]["r"])
    assert np.allclose(np.diff(r), _RS[7] / SPRING_GRID, rtol=1e-9, atol=0)


# -- an explicit history (_history_state, the history branches of the effects) ------------------

def _history(tmp_path, monkeypatch, rows, effects, normal="force", tangential="force",
             bodies=(SPHERE, FLAT)):
    monkeypatch.chdir(tmp_path)  # a dict scene reads its history from the working directory
    (tmp_path / "h.csv").write_text("".join(f"{a!r}, {b!r}\n" for a, b in rows),
                                    encoding="utf-8")
    return scene.load({"effects": list(effects), "body": list(bodies),
                       "interface": {"friction": MU},
                       "load": {"history": {"file": "h.csv", "normal": normal,
                                            "tangential": tangential}}}).run()["effects"]


def test_force_history(springs, tmp_path, monkeypatch):
    """A force history that ends at another normal load (0, 100, 100, 100, 50 N; F_x 0, 0,
    30, -30, 10 N): every effect per state from the one run of the springs, each rel_error its
    grid estimate over the largest value (no state rel: the springs find the normal state
    too); mu F and 2 G* a against Hertz's per state within it; the traction of the final state
    (50 N) up to its contact radius."""
    rows = [(0.0, 0.0), (100.0, 0.0), (100.0, 30.0), (100.0, -30.0), (50.0, 10.0)]
    eff = _history(tmp_path, monkeypatch, rows, OSCILLATING)
    (kw, H), = springs
    assert np.array_equal(kw["normal_force"], [r[0] for r in rows])
    assert np.array_equal(kw["F_x"], [r[1] for r in rows]) and kw["n_grid"] == SPRING_GRID
    a_ref = [float(Mindlin(F).a) if F else 0.0 for F, _ in rows]
    assert kw["x_max"] == pytest.approx(1.25 * a_ref[1], rel=1e-14, abs=0)
    s = eff["sliding_force"]
    # the springs find each state's depth from its force: F back within a few roundings
    assert s["value"] == pytest.approx([MU * F for F, _ in rows], rel=1e-14, abs=0)
    assert s["rel_error"] == H.normal_force_error / np.max(H.normal_force)
    assert s["method"] == f"Coulomb: mu F of every state ({friction.SPRINGS})"
    k = eff["tangential_stiffness"]
    G = float(Mindlin().G_star)
    assert k["rel_error"] == H.contact_radius_error / np.max(H.contact_radius) > 0
    assert np.max(np.abs(np.asarray(k["value"]) - 2 * G * np.array(a_ref))) <= (
        k["rel_error"] * np.max(k["value"]))
    assert k["method"] == ("2 G* a (all springs stick) of every state, a from "
                           + friction.SPRINGS)
    for name, attr, label in (("tangential_force", "F_x", "F_x"),
                              ("tangential_displacement", "u_x", "u_x"),
                              ("stick_radius", "stick_radius", "the stick radius")):
        v = getattr(H, attr)
        assert np.array_equal(eff[name]["value"], v)
        assert eff[name]["rel_error"] == getattr(H, attr + "_error") / np.max(np.abs(v))
        assert eff[name]["method"] == f"{friction.SPRINGS}, {label} of every state"
    assert eff["tangential_force"]["rel_error"] == 0.0  # F_x is prescribed
    W = eff["dissipated_energy"]
    assert W["value"] == H.dissipated[-1] > 0
    assert W["rel_error"] == H.dissipated_error / W["value"]
    assert W["method"] == f"{friction.SPRINGS}: the friction work over the whole history"
    loop = eff["hysteresis_loop"]
    assert np.array_equal(loop["value"]["u"], H.u_x) and np.array_equal(loop["value"]["F"],
                                                                         H.F_x)
    assert loop["rel_error"] == H.u_x_error / np.max(np.abs(H.u_x))  # F_x's is 0
    assert loop["method"] == f"{friction.SPRINGS}, every state"
    q = eff["traction_profile"]
    r = np.asarray(q["value"]["r"])
    h = kw["x_max"] / SPRING_GRID
    assert r.ndim == 1 and r[-1] <= a_ref[-1] + 1e-3 * h < r[-1] + h  # a of 50 N, not 100
    assert q["rel_error"] == H.traction_error / np.max(np.abs(q["value"]["q"]))
    assert q["method"] == (f"{friction.SPRINGS}, (5.59) of the springs' line load in the "
                           "final state")


def test_depth_and_displacement_history(springs, tmp_path, monkeypatch):
    """A history of depths and displacements (0, 2, 2, 1 um; u_x 0, 0, 0.3, 0.1 um): the
    springs take depth and u_x (the displacements come back exactly, with rel_error 0), the
    grid ends at 1.25 a of the deepest state (Hertz's a = sqrt(R d)), the normal forces are
    Hertz's F(d) within their grid estimate, which is their rel_error; the loop's error is
    F_x's (u_x has none)."""
    rows = [(0.0, 0.0), (2e-6, 0.0), (2e-6, 3e-7), (1e-6, 1e-7)]
    eff = _history(tmp_path, monkeypatch, rows, OSCILLATING, normal="depth",
                   tangential="displacement")
    (kw, H), = springs
    assert np.array_equal(kw["depth"], [r[0] for r in rows])
    assert np.array_equal(kw["u_x"], [r[1] for r in rows])
    assert kw["x_max"] == pytest.approx(1.25 * math.sqrt(R * 2e-6), rel=1e-15, abs=0)
    u = eff["tangential_displacement"]
    assert np.array_equal(u["value"], [r[1] for r in rows]) and u["rel_error"] == 0.0
    m = Mindlin()
    F_ref = np.array([float(4 / 3 * m.E_star * mp.sqrt(R) * mp.mpf(d) ** 1.5) for d, _ in rows])
    s = eff["sliding_force"]
    assert s["rel_error"] == H.normal_force_error / np.max(H.normal_force) > 0
    assert np.max(np.abs(np.asarray(s["value"]) - MU * F_ref)) <= s["rel_error"] * MU * F_ref.max()
    loop = eff["hysteresis_loop"]
    assert loop["rel_error"] == H.F_x_error / np.max(np.abs(H.F_x)) > 0


def test_history_without_tangential_force(springs, tmp_path, monkeypatch):
    """F_x = 0 in every state: the force is 0 with rel_error 0 (not 0/0), no work is done."""
    eff = _history(tmp_path, monkeypatch, [(0.0, 0.0), (100.0, 0.0), (100.0, 0.0)],
                   ["tangential_force", "dissipated_energy"])
    assert eff["tangential_force"]["value"] == [0.0, 0.0, 0.0]
    assert eff["tangential_force"]["rel_error"] == 0.0
    assert eff["dissipated_energy"]["value"] == 0.0
    assert eff["dissipated_energy"]["rel_error"] == 0.0


def test_history_refusals(springs, tmp_path, monkeypatch):
    """A history that never presses the bodies together is refused on ``load`` before the
    springs run; one whose F_x exceeds mu F names the file's line; both name the scene."""
    with pytest.raises(SceneError) as info:
        _history(tmp_path, monkeypatch, [(0.0, 0.0), (0.0, 0.0)], ["tangential_force"])
    assert (info.value.where, info.value.key) == ("<scene>", "load")
    assert info.value.message == ("the load never presses the bodies together (contact radius "
                                  "0 in every state): no tangential contact")
    assert springs == []
    with pytest.raises(SceneError) as info:
        _history(tmp_path, monkeypatch, [(0.0, 0.0), (100.0, 0.0), (100.0, 70.0)],
                 ["tangential_force"])
    assert (info.value.where, info.value.key) == ("<scene>", "load.history")
    assert info.value.message.startswith("F_x of h.csv line 3 = 70.0 N exceeds")


# -- refusals of the closed forms and of effects without their load ---------------------------

def test_closed_form_refusals():
    """No friction, and a tangential force above mu F (the closed form's own refusal), each
    named by the scene, its key and what is valid."""
    with pytest.raises(SceneError) as info:
        scene.load({"effects": ["sliding_force"], "body": [SPHERE, FLAT],
                    "load": {"force": "100 N"}}).run()
    assert (info.value.where, info.value.key) == ("<scene>", "interface.friction")
    assert info.value.message == ("the tangential effects need the coefficient of friction: "
                                  "[interface] friction = 0.6, say")
    with pytest.raises(SceneError) as info:
        run([SPHERE, FLAT], {"force": "100 N", "tangential": {"force": "70 N"}},
            ["tangential_force"])
    assert (info.value.where, info.value.key) == ("<scene>", "load.tangential.force")
    assert "70" in info.value.message


@pytest.mark.parametrize("effect", ["tangential_force", "tangential_displacement",
                                    "stick_radius", "traction_profile"])
def test_effect_needs_a_tangential_load(effect):
    """Each effect of a tangential load, asked without one: one line naming the effect and
    the loads that give it."""
    with pytest.raises(SceneError) as info:
        run([SPHERE, FLAT], {"force": "100 N"}, [effect])
    assert (info.value.where, info.value.key) == ("<scene>", "effects")
    assert info.value.message == (f"effect {effect!r} needs [load] tangential = {{force = ...}}"
                                  " or {displacement = ...}, oscillating or history")


@pytest.mark.parametrize("effect", ["dissipated_energy", "hysteresis_loop"])
def test_effect_needs_an_oscillation(effect):
    """The energy of a cycle and the loop need an oscillating load (or a history): a
    monotonic tangential force is refused by name."""
    with pytest.raises(SceneError) as info:
        run([SPHERE, FLAT], {"force": "100 N", "tangential": {"force": "10 N"}}, [effect])
    assert (info.value.where, info.value.key) == ("<scene>", "effects")
    assert info.value.message == (f"effect {effect!r} needs [load] oscillating = {{amplitude = "
                                  "..., cycles = N} or a history")


# -- kinds/base.py: the model's why, the force law's refusal and a line's law per length ------

def test_model_says_why():
    """The JSON's model.why is the builder's reason (model.why_chosen): the shapes, the load,
    the KINDS row."""
    doc = scene.load({"effects": ["force"], "body": [SPHERE, FLAT],
                      "load": {"force": "1 N"}}).run()
    assert doc["model"]["why"].startswith("sphere (") and "-> row '" in doc["model"]["why"]


def test_force_law_refused_with_the_curve_instead():
    """A sampled profile has no power law: the refusal says why and names the tabulated
    force_depth_curve as the effect to use instead."""
    with pytest.raises(SceneError) as info:
        scene.load({"effects": ["force_law"], "body": [SAMPLED, FLAT],
                    "load": {"force": "1 N"}}).run()
    assert info.value.message.endswith("; use 'force_depth_curve'")


def test_line_force_law_per_length():
    """A line contact's law per unit length: K_per_length = K/L and stiffness_K_per_length =
    stiffness_K/L (L = 20 mm), in N/m^(n + 1) = N/m^2 for n = 1; the method keeps the law's
    own description first."""
    eff = scene.load({"effects": ["force_law"], "body": [
        {"shape": "cylinder", "radius": "10 mm", "length": "20 mm", "rigid": True}, FLAT],
        "load": {"depth": "1 um"}}).run()["effects"]["force_law"]
    v = eff["value"]
    assert v["n"] == 1.0
    assert v["stiffness_K_per_length"] == pytest.approx(v["stiffness_K"] / 0.02, rel=1e-15, abs=0)
    assert eff["method"].startswith("F = K d^n, dF/dd = stiffness_K d^(n - 1)")
    assert "F/L = K_per_length d^n (N/m^2)" in eff["method"]


def test_effect_refusal_names_the_scene_file(tmp_path):
    """An effect asked without its load, in a scene read from a file, names that file (as
    every other refusal does), for each way the tangential state of a constant normal load is
    found: a closed form, the springs (a history gives every effect its load). It named
    "<scene>" before."""
    sphere = 'shape = "sphere"\nradius = "10 mm"'
    sampled = (f'shape = "profile"\nr = {[float(x) for x in _RS[:9]]}\n'
               f'f = {[float(x) for x in _RS[:9] ** 2 / (2 * R)]}')
    cases = [(sphere, 'force = "100 N"\ntangential = {force = "10 N"}', "dissipated_energy"),
             (sampled, 'force = "10 N"', "tangential_force")]
    for tip, load, effect in cases:
        path = tmp_path / "s.toml"
        path.write_text(f'effects = ["{effect}"]\n[[body]]\n{tip}\nE = "210 GPa"\nnu = 0.3\n'
                        '[[body]]\nshape = "flat"\nE = "210 GPa"\nnu = 0.3\n'
                        f"[interface]\nfriction = 0.6\n[load]\n{load}\n", encoding="utf-8")
        with pytest.raises(SceneError, match=f"effect '{effect}' needs") as info:
            scene.load(path).run()
        assert (info.value.where, info.value.key) == (str(path), "effects"), effect


@pytest.mark.parametrize("normal, rows", [
    ("force", [(0.0, 0.0), (10.0, 0.0), (10.0, 2.0), (10.0, -2.0)]),
    ("depth", [(0.0, 0.0), (1e-6, 0.0), (1e-6, 2.0), (1e-6, -2.0)])])
def test_flat_punch_history(tmp_path, monkeypatch, normal, rows):
    """A flat punch (radius a = 0.1 mm, steel on steel) through a history: its grid ends at
    the punch's wall, where every spring is in contact at any depth (before: every history
    was refused, "needs a contact wider than the grid ... valid: a larger x_max", which the
    scene cannot set). With g = 0 every spring carries the same load: d = F/(2 E* a),
    F = 2 E* a d, and below mu F all stick with u = F_x/(2 G* a) (the punch's stiffnesses,
    closed forms at 30 digits), the stick radius a and nothing dissipated."""
    punch = {"shape": "flat_punch", "radius": "0.1 mm", **STEEL}
    eff = _history(tmp_path, monkeypatch, rows,
                   ["force", "depth", "tangential_displacement", "stick_radius",
                    "dissipated_energy"], normal=normal, bodies=(punch, FLAT))
    m, a = Mindlin(), mp.mpf("1e-4")
    for k, (n, fx) in enumerate(rows[1:], start=1):
        d = n / (2 * m.E_star * a) if normal == "force" else mp.mpf(n)
        F = 2 * m.E_star * a * d
        close(eff["depth"]["value"][k], d, 1e-13)
        close(eff["force"]["value"][k], F, 1e-13)
        # relative to the largest displacement, 2 N/(2 G* a): u = 0 comes out as 1e-21 m
        scale = 2 / (2 * m.G_star * a)
        u = eff["tangential_displacement"]["value"][k]
        assert abs(u - fx / (2 * m.G_star * a)) <= 1e-13 * scale, (k, u)
        close(eff["stick_radius"]["value"][k], a, 1e-13)
    assert eff["dissipated_energy"]["value"] == 0.0


def test_flat_punch_history_that_never_presses_is_refused(tmp_path, monkeypatch):
    """A history whose normal load stays 0 under a flat punch is refused as under every other
    shape (before: it ran, with stiffness 0 and no contact in any state)."""
    punch = {"shape": "flat_punch", "radius": "0.1 mm", **STEEL}
    with pytest.raises(SceneError, match=r"load: the load never presses the bodies "
                                               r"together \(contact radius 0 in every state\)"):
        _history(tmp_path, monkeypatch, [(0.0, 0.0), (0.0, 0.0)], ["tangential_stiffness"],
                 bodies=(punch, FLAT))
