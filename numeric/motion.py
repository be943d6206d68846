"""The equation of motion of an elastic impact, integrated numerically (Problem 3).

A sphere of mass m strikes a wall at v0; while in contact, m x'' = -F(x) with the Hertz force
F(x) of (5.23) at the depth x (generated from hertzmdr.derive.hertz). Integrating it gives the
maximum depth and the contact time without the energy-balance closed forms of
:mod:`hertzmdr.numeric.impact`, so the two check each other (the scenes report both).

Time and length are scaled by the dimensional analysis of the problem, x_s = (m v0^2 /
(E* R^(1/2)))^(2/5), t_s = x_s/v0 and F_s = m x_s/t_s^2 (no closed-form constant enters; all
three derived in hertzmdr.derive.impact), so the integrator sees numbers of order 1 whatever the
scales.
"""

from __future__ import annotations

from dataclasses import dataclass

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import positive


@dataclass(frozen=True)
class Motion:
    """Result of :func:`integrate`: maximum depth [m], contact time [s], maximum force [N],
    the integrator's tolerance and its number of right-hand-side evaluations."""

    max_depth: float
    contact_time: float
    max_force: float
    rtol: float
    evaluations: int


def integrate(v0, R, E_star, m, *, rtol: float = 1e-10) -> Motion:
    """Integrate m x'' = -F(x), x(0) = 0, x'(0) = v0, until the sphere leaves the wall.

    Parameters
    ----------
    v0 : float
        Impact velocity [m/s], > 0.
    R : float
        Effective radius [m] (the sphere's radius on a flat wall), > 0.
    E_star : float
        Effective modulus (5.26) [Pa], > 0.
    m : float
        Mass of the sphere [kg], > 0 (the wall does not move).
    rtol : float
        Relative tolerance of the integrator (SciPy's DOP853), in [1e-13, 1e-3].

    Returns
    -------
    Motion
    """
    from scipy.integrate import solve_ivp

    v0, R, E, m = (float(positive(n, v)) for n, v in
                   (("v0", v0), ("R", R), ("E_star", E_star), ("m", m)))
    if not 1e-13 <= rtol <= 1e-3:
        raise ValueError(f"rtol = {rtol!r} is out of range; valid: 1e-13 <= rtol <= 1e-3")
    # X = x/x_s, T = t/t_s, X'' = -F(x_s X)/F_s = -(4/3) X^(3/2), X'(0) = 1 (5.23)
    xs = float(gen.impact_length_scale(E, R, m, v0))
    ts = float(gen.impact_time_scale(E, R, m, v0))
    fs = float(gen.impact_force_scale(E, R, m, v0))

    def rhs(_, y):
        x = max(y[0], 0.0) * xs
        return [y[1], -float(gen.hertz_force(E, R, x)) / fs]  # (5.23)

    def turning(_, y):
        return y[1]

    def leaving(t, y):
        return y[0] if t > 0 else 1.0

    turning.terminal, leaving.terminal, leaving.direction = False, True, -1
    sol = solve_ivp(rhs, (0.0, 100.0), [0.0, 1.0], method="DOP853", rtol=rtol,
                    atol=rtol * 1e-3, events=(turning, leaving), dense_output=False)
    if sol.status != 1 or not len(sol.t_events[1]):
        raise RuntimeError(f"the impact did not end within the integration window: {sol.message}")
    x_max = float(sol.y_events[0][0][0]) * xs
    return Motion(x_max, float(sol.t_events[1][0]) * ts, float(gen.hertz_force(E, R, x_max)),
                  rtol, int(sol.nfev))
