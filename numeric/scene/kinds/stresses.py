"""Stress effects for axisymmetric contacts (section 5.5, Figs. 5.8 and 5.9) and for line
contacts (plane strain, the Flamant superposition of numeric/line_stress.py).

The stresses are those in the first elastic body of the scene (its Poisson's ratio, from the
kind's :class:`~..materials.Materials`). Under the
Hertz pressure they come from the closed forms of numeric/stress.py; under any other
axisymmetric pressure (cone, flat punch, power law, worn parabola, sampled tips) from the
superposition of the point-force field, with its error estimate, on coarser grids (a point
costs about 0.1 s).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import Value

AXIS_POINTS_CLOSED, AXIS_POINTS_SUPERPOSED = 201, 31
GRID_CLOSED, GRID_SUPERPOSED = 101, 13


def symmetric_grid(half: float, n: int) -> np.ndarray:
    """n (odd) points over [-half, half] [m], mirror images of each other exactly, the centre
    exactly 0 (np.linspace's centre can be 1e-20 off: the field's column x = 0 then is not on
    the axis, and its symmetry is not exact)."""
    right = np.linspace(0.0, half, (n + 1) // 2)
    return np.concatenate([-right[:0:-1], right])
#: the tolerances to which tests/test_stress.py verifies the closed-form field and its maxima
FIELD_RTOL, MAXIMUM_RTOL = 1e-12, 1e-10
#: the superposition's estimate is the difference of two tanh-sinh levels, not a bound: against
#: 30 digits the finer level's error reached 1.4 times it under the flat punch (whose
#: 1/sqrt rim pressure both levels cut at the last float64 below a) and 1.35 times it at the
#: rounding level under the power law n = 3 (4e-16 against 3e-16); twice the estimate plus
#: float64's rounding of sums of ~1e4 kernel terms is what the scene reports (issue 12,
#: tests/test_scene_routes.py checks the bound itself)
ESTIMATE_SAFETY, ROUNDING = 2.0, 1e-14


def _bound(estimate: float) -> float:
    return ESTIMATE_SAFETY * estimate + ROUNDING


def _tau_1(szz, srr):
    """tau_1 = (sigma_1 - sigma_3)/2 on the axis (Fig. 5.8), where the principal stresses are
    sigma_zz and sigma_rr (twice): numeric/stress.py's max_shear of that diagonal tensor."""
    from hertzmdr.numeric import stress

    szz, srr = np.broadcast_arrays(np.asarray(szz, float), np.asarray(srr, float))
    sigma = np.zeros(szz.shape + (3, 3))
    sigma[..., 0, 0] = sigma[..., 1, 1] = srr
    sigma[..., 2, 2] = szz
    return np.asarray(stress.max_shear(sigma), float)


class HertzStresses:
    """Closed forms: the Hertz pressure of contact radius a and maximum pressure p0."""

    ranges = {"axis_stresses": FIELD_RTOL, "von_mises_field": FIELD_RTOL,
              "max_shear": MAXIMUM_RTOL, "max_von_mises": MAXIMUM_RTOL,
              "max_orthogonal_shear": CLOSED_FORM_RTOL}

    def __init__(self, a, p0, nu):
        self.a, self.p0, self.nu = a, p0, nu
        self.method = "closed form (Huber/Hamilton field, (5.48), (5.49))"

    def axis(self):
        from hertzmdr.numeric import stress

        z = np.linspace(0.0, 3.0 * self.a, AXIS_POINTS_CLOSED)
        szz, srr = stress.axis_stresses(z, self.a, self.p0, self.nu)
        return Value({"z": z, "sigma_zz": szz, "sigma_rr": srr, "tau_1": _tau_1(szz, srr)},
                     self.method, FIELD_RTOL)

    def max_shear(self):
        from hertzmdr.numeric import stress

        value, r, z = stress.hertz_maximum(self.nu, "max_shear")
        return Value({"value": value * self.p0, "depth": z * self.a},
                     "maximum of (sigma_1 - sigma_3)/2 in the body (grid, then Nelder-Mead)",
                     MAXIMUM_RTOL)

    def field(self):
        from hertzmdr.numeric import stress

        x = symmetric_grid(2.0 * self.a, GRID_CLOSED)
        z = np.linspace(0.0, 2.0 * self.a, GRID_CLOSED)
        X, Z = np.meshgrid(x, z)
        sv = stress.von_mises(stress.hertz_stress(X, 0.0 * X, Z, self.a, self.p0, self.nu))
        return Value({"x": x, "z": z, "sigma_v": sv}, self.method + ", (5.50)", FIELD_RTOL)

    def max_von_mises(self):
        from hertzmdr.numeric import stress

        value, r, z = stress.hertz_maximum(self.nu, "von_mises")
        return Value({"value": value * self.p0, "x": r * self.a, "z": z * self.a},
                     "maximum of (5.50) in the body (grid, then Nelder-Mead)", MAXIMUM_RTOL)

    def max_orthogonal_shear(self):
        from hertzmdr.numeric import stress

        value, r, z = stress.hertz_max_orthogonal_shear()
        return Value({"value": value * self.p0, "x": r * self.a, "z": z * self.a},
                     "closed form: the root of the gradient of Huber's tau_rz, derived "
                     "(any nu)", CLOSED_FORM_RTOL)


class SuperposedStresses:
    """Any axisymmetric pressure p(r) on r < a by superposition of (5.41)-(5.46); its error is
    its own estimate (tanh-sinh) made a bound (:func:`_bound`), whatever rtol asks (``met_rtol``
    says whether it met it),
    plus ``pressure_error``, the relative error of p itself (0 for a closed form's p, exact to
    rounding; a numerical MDR's bound relative to its largest p)."""

    ranges: dict[str, float] = {}

    def __init__(self, pressure, a, nu, pressure_error=0.0):
        self.p, self.a, self.nu = pressure, a, nu
        self.pressure_error = pressure_error
        #: (why, r_s [m]) when the pressure is unbounded at the surface radius r_s: the largest
        #: stresses are then +inf there (set by the kind; None for a bounded pressure)
        self.unbounded: tuple[str, float] | None = None
        self.method = "superposition of the point-force field (5.47), tanh-sinh"

    def _stress(self, x, z):
        from hertzmdr.numeric import stress

        return stress.superposed_stress(x, 0.0 * x, z, self.p, self.a, self.nu)

    def axis(self):
        z = np.linspace(0.0, 3.0 * self.a, AXIS_POINTS_SUPERPOSED)[1:]  # z > 0 for this route
        s, e = self._stress(0.0 * z, z)
        szz, srr = s[..., 2, 2], s[..., 0, 0]
        scale = float(np.max(np.abs(szz)))
        err = _bound(float(np.max(e[..., 2, 2] + e[..., 0, 0])) / scale) + self.pressure_error
        return Value({"z": z, "sigma_zz": szz, "sigma_rr": srr, "tau_1": _tau_1(szz, srr)},
                     self.method, err)

    @cached_property
    def _plane(self):
        """numeric/stress.py's superposed plane field, once for the three effects using it."""
        from hertzmdr.numeric import stress

        return stress.superposed_plane(self.p, self.a, self.nu, n=GRID_SUPERPOSED)

    def _infinite(self, keys: dict) -> Value:
        why, _ = self.unbounded
        return Value({"value": math.inf, **keys}, f"unbounded: {why}, and the stress at the "
                     "surface grows like (1 - 2 nu) p", 0.0)

    def max_shear(self):
        if self.unbounded:
            return self._infinite({"depth": 0.0})
        value, _, z, err = self._maximum("max_shear")
        return Value({"value": value, "depth": z}, self._max_method, err)

    def field(self):
        f = self._plane
        xs = np.concatenate([-f.x[:0:-1], f.x])  # mirror: the field is symmetric in x
        full = np.concatenate([f.von_mises[:, :0:-1], f.von_mises], axis=1)
        return Value({"x": xs, "z": f.z, "sigma_v": full}, self.method + ", (5.50)",
                     _bound(f.rel_error) + self.pressure_error)

    def max_von_mises(self):
        if self.unbounded:
            return self._infinite({"x": self.unbounded[1], "z": 0.0})
        value, x, z, err = self._maximum("von_mises")
        return Value({"value": value, "x": x, "z": z}, self._max_method, err)

    @property
    def _max_method(self) -> str:
        return (f"largest on a {GRID_SUPERPOSED}x{GRID_SUPERPOSED - 1} grid, refined by "
                "Nelder-Mead (rel_error: the quadrature's estimate, the refinement's miss and "
                "the pressure's error), " + self.method)

    def _maximum(self, criterion):
        """(value, x, z, rel_error) of the largest stress, refined from the grid's
        (numeric/stress.py's superposed_maximum, whose bound includes how far the refined
        point may still miss it; the grid alone missed Hertz's by 1e-3 while reporting the
        quadrature's 1e-16, issue 12)."""
        from hertzmdr.numeric import stress

        value, x, z, err = stress.superposed_maximum(self.p, self.a, self.nu, criterion,
                                                     self._plane)
        return value, x, z, _bound(err) + self.pressure_error

    def max_orthogonal_shear(self):
        value, x, z, err = self._maximum("orthogonal_shear")
        return Value({"value": value, "x": x, "z": z}, "|tau_rz|: " + self._max_method, err)


class LineStresses:
    """Line contact: the 2-D Hertz pressure of half-width b and maximum pressure p0 (5.36),
    plane strain (sigma_yy = nu (sigma_xx + sigma_zz)); closed forms of
    numeric/line_stress.py, maxima by root finding on their generated derivatives."""

    #: the tolerances to which tests/test_line_stress.py verifies the field (2e-14 per
    #: component against 30-digit superposition; von Mises and tau_max a few roundings more)
    #: and the maxima (values to 1e-14)
    ranges = {"axis_stresses": 1e-13, "von_mises_field": 1e-13, "max_shear": MAXIMUM_RTOL,
              "max_von_mises": MAXIMUM_RTOL, "max_orthogonal_shear": MAXIMUM_RTOL}

    def __init__(self, b, p0, nu):
        self.b, self.p0, self.nu = b, p0, nu
        self.method = "closed form (Flamant superposed over (5.36), plane strain)"

    def axis(self):
        from hertzmdr.numeric import line_stress as ls

        z = np.linspace(0.0, 3.0 * self.b, AXIS_POINTS_CLOSED)
        sxx, szz, syy = ls.axis_stresses(z, self.b, self.p0, self.nu)
        tau = ls.principal_shear(0.0, z, self.b, self.p0, self.nu)[1]
        return Value({"z": z, "sigma_zz": szz, "sigma_rr": sxx, "sigma_yy": syy,
                      "tau_1": np.asarray(tau, float)},
                     self.method + "; sigma_rr is sigma_xx (across the strip), tau_1 the 3-D "
                     "(sigma_1 - sigma_3)/2", self.ranges["axis_stresses"])

    def max_shear(self):
        from hertzmdr.numeric import line_stress as ls

        value, z = ls.max_shear_3d(self.nu)
        return Value({"value": value * self.p0, "depth": z * self.b},
                     "maximum of (sigma_1 - sigma_3)/2 on the axis (root of the generated "
                     "slope; bounded Brent for the sigma_yy pairs)", MAXIMUM_RTOL)

    def field(self):
        from hertzmdr.numeric import line_stress as ls

        x = symmetric_grid(2.0 * self.b, GRID_CLOSED)
        z = np.linspace(0.0, 2.0 * self.b, GRID_CLOSED)
        X, Z = np.meshgrid(x, z)
        sv = np.asarray(ls.von_mises(X, Z, self.b, self.p0, self.nu), float)
        return Value({"x": x, "z": z, "sigma_v": sv}, self.method + ", (5.50)",
                     self.ranges["von_mises_field"])

    def max_von_mises(self):
        from hertzmdr.numeric import line_stress as ls

        value, x, z = ls.max_von_mises(self.nu)
        return Value({"value": value * self.p0, "x": x * self.b, "z": z * self.b},
                     "maximum of (5.50) on the axis (the surface centre or the root of the "
                     "generated slope)", MAXIMUM_RTOL)

    def max_orthogonal_shear(self):
        from hertzmdr.numeric import line_stress as ls

        value, x, z = ls.max_orthogonal_shear()
        return Value({"value": value * self.p0, "x": x * self.b, "z": z * self.b},
                     "root of the generated gradient of tau_xz (exactly p0/4 at "
                     "(3^(1/2)/2 b, b/2); mirrored at -x)", MAXIMUM_RTOL)


class StressEffects:
    """Mixin for contact kinds: the five stress effects, through the ``stress`` node. A kind
    defines ``stress_solver(state)`` (:class:`HertzStresses` or :class:`SuperposedStresses`)."""

    STRESS_EFFECTS = ("axis_stresses", "max_shear", "von_mises_field", "max_von_mises",
                      "max_orthogonal_shear")

    def node_stress(self, run):
        return self.stress_solver(run.node("state"))

    def stress_ranges(self, effects, closed: bool,
                      table: dict[str, float] | None = None) -> list[tuple[str,
                                                                     tuple[float, float]]]:
        """The rtol each requested stress effect can deliver (closed forms only; superposition
        reports its estimate); ``table`` (effect -> rtol) overrides the Hertz one."""
        if table is None:
            table = HertzStresses.ranges if closed else SuperposedStresses.ranges
        return [(f"{e} (closed form)", (table[e], 1.0)) for e in effects if e in table]

    def effect_axis_stresses(self, solver):
        return solver.axis()

    def effect_max_shear(self, solver):
        return solver.max_shear()

    def effect_von_mises_field(self, solver):
        return solver.field()

    def effect_max_von_mises(self, solver):
        return solver.max_von_mises()

    def effect_max_orthogonal_shear(self, solver):
        return solver.max_orthogonal_shear()


__all__ = ["HertzStresses", "LineStresses", "StressEffects", "SuperposedStresses"]
