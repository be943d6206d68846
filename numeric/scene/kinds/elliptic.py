"""Elliptical Hertz contact of a quadratic gap with unequal principal radii: exact (complete
elliptic integrals, numeric/ellipse.py) or the chapter's Gaussian-radius estimate (5.28)-(5.30).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric import bodies, ellipse
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import Contact, State, Value
from hertzmdr.numeric.scene.kinds.stresses import StressEffects

#: the tolerance to which tests/test_ellipse.py verifies the exact solution against mpmath
EXACT_RTOL = 1e-12

#: tests/test_ellipse_stress.py verifies the axis closed forms to 1e-14 p0 against
#: superposition; the field's quadrature is asked FIELD_RTOL (its estimate is reported); the
#: axis maxima are Brent roots to 4 ulp (verified to 1e-12 against 40-digit roots), the
#: orthogonal shear a Nelder-Mead maximum (1e-11 in position, ~1e-15 in value); the field's
#: quadrature is asked the scene's rtol, at best FIELD_RTOL, and reports its estimate
AXIS_RTOL, FIELD_RTOL, MAXIMUM_RTOL = 1e-12, 1e-12, 1e-10
AXIS_POINTS, GRID_POINTS = 201, 101


class EllipseStresses:
    """Stresses under the elliptical Hertz pressure (numeric/ellipse_stress.py): semi-axes
    a >= b (a along x, the direction of R1), maximum pressure p0; lengths in m, stresses in
    Pa."""

    ranges = {"axis_stresses": AXIS_RTOL, "von_mises_field": FIELD_RTOL,
              "max_shear": MAXIMUM_RTOL, "max_von_mises": MAXIMUM_RTOL,
              "max_orthogonal_shear": MAXIMUM_RTOL}

    def __init__(self, a, b, p0, nu, rtol=FIELD_RTOL):
        self.a, self.b, self.p0, self.nu = a, b, p0, nu
        self.rtol = max(rtol, FIELD_RTOL)
        self.method = ("Boussinesq superposed in Love's form (derive/ellipse_stress.py): "
                       "Carlson R_D on the axis")

    def axis(self):
        from hertzmdr.numeric import ellipse_stress as el
        from hertzmdr.numeric import stress

        z = np.linspace(0.0, 3.0 * self.b, AXIS_POINTS)
        sxx, syy, szz = el.axis_stresses(z, self.a, self.b, self.p0, self.nu)
        sigma = np.zeros(z.shape + (3, 3))  # on the axis the stress tensor is diagonal
        sigma[..., 0, 0], sigma[..., 1, 1], sigma[..., 2, 2] = sxx, syy, szz
        return Value({"z": z, "sigma_xx": sxx, "sigma_yy": syy, "sigma_zz": szz,
                      "tau_1": stress.max_shear(sigma)}, self.method, AXIS_RTOL)

    def max_shear(self):
        from hertzmdr.numeric import ellipse_stress as el

        v, zb, plane = el.max_shear(self.b / self.a, self.nu)
        return Value({"value": v * self.p0, "depth": zb * self.b},
                     f"largest (sigma_{plane}{plane} - sigma_zz)/2 on the axis, Brent on the "
                     "derived slope (R_D)", MAXIMUM_RTOL)

    def field(self):
        """The von Mises stress in the x-z plane (y = 0) and the y-z plane (x = 0)."""
        from hertzmdr.numeric import ellipse_stress as el

        z = np.linspace(0.0, 2.0 * self.b, GRID_POINTS)
        x = np.linspace(-2.0 * self.a, 2.0 * self.a, GRID_POINTS)
        y = np.linspace(-2.0 * self.b, 2.0 * self.b, GRID_POINTS)
        X, Z = np.meshgrid(x, z)
        vx, ex = el.von_mises(X, 0.0 * X, Z, self.a, self.b, self.p0, self.nu,
                              rtol=self.rtol)
        Y, Z = np.meshgrid(y, z)
        vy, ey = el.von_mises(0.0 * Y, Y, Z, self.a, self.b, self.p0, self.nu,
                              rtol=self.rtol)
        err = max(float(np.max(ex)), float(np.max(ey))) / max(float(np.max(vx)), 1e-300)
        return Value({"x": x, "z": z, "sigma_v": vx, "y": y, "sigma_v_yz": vy},
                     self.method + "; off the axis the ellipsoidal coordinate and "
                     "double-exponential quadrature, (5.50)", err)

    def max_von_mises(self):
        from hertzmdr.numeric import ellipse_stress as el

        v, zb = el.max_von_mises(self.b / self.a, self.nu)
        return Value({"value": v * self.p0, "x": 0.0, "z": zb * self.b},
                     "largest (5.50) on the axis, Brent on the derived slope (R_D)",
                     MAXIMUM_RTOL)

    def max_orthogonal_shear(self):
        from hertzmdr.numeric import ellipse_stress as el

        out = el.max_orthogonal_shear(self.b / self.a)
        v, yb, zb = out["yz"]
        vx, xb, zxb = out["xz"]
        return Value({"value": v * self.p0, "x": 0.0, "y": yb * self.b, "z": zb * self.b,
                      "value_xz": vx * self.p0, "x_xz": xb * self.b, "z_xz": zxb * self.b},
                     "largest |tau_yz| (plane x = 0) and |tau_xz| (plane y = 0), algebraic "
                     "in the ellipsoidal coordinate, Nelder-Mead", MAXIMUM_RTOL)


def _deviation(got, exact) -> float:
    """A bound on the relative deviation of ``got`` from the true exact solution, of which
    ``exact`` is the float64 value, itself within EXACT_RTOL: |got/exact - 1| + |got/exact|
    EXACT_RTOL (the deviation alone fell 1e-12 short of the 30-digit one)."""
    q = np.asarray(got, float) / np.asarray(exact, float)
    return float(np.max(np.abs(q - 1) + np.abs(q) * EXACT_RTOL))


@dataclass
class EllipticState(State):
    """The state of an elliptical contact: its solution, and the exact one when the model is the
    Gaussian estimate (whose error is its deviation from it)."""

    contact: ellipse.EllipticContact | None = None
    exact: ellipse.EllipticContact | None = None


class EllipticContact(StressEffects, Contact):
    kind = "elliptic"
    instead = {"contact_radius": "semi_axes", "half_width": "semi_axes"}
    why_not = {"contact_radius": "the contact is an ellipse, not a circle"}

    state_method = "the elliptic integrals of the exact solution"
    state_range = (EXACT_RTOL, 1.0)

    def __init__(self, materials, interface, rtol, R1, R2, model="exact"):
        super().__init__(materials, interface, rtol)
        self.R1, self.R2, self.model = R1, R2, model
        self.label = ("elliptical Hertz contact (exact, complete elliptic integrals)"
                      if model == "exact" else
                      "elliptical Hertz contact (the chapter's Gaussian radius (5.28)-(5.30))")

    def info(self):
        return {**super().info(), "principal_radii": [self.R1, self.R2],
                "gaussian_radius": float(bodies.gaussian_radius(self.R1, self.R2)),
                "elliptic_model": self.model}

    def ratios(self, nodes):
        """The larger of a/R1 and b/R2 (each semi-axis over the radius along it), and d over the
        smaller principal radius, at the largest load."""
        st = nodes.get("state")
        if st is None:
            return {}
        c = st.contact
        a, b = float(np.max(c.a)), float(np.max(c.b))
        return {"a/R": max(a / self.R1, b / self.R2),
                "d/R": float(np.max(st.depth)) / min(self.R1, self.R2)}

    def rtol_ranges(self, effects):
        out = super().rtol_ranges(effects)
        return out + [(f"{e} (elliptical stresses)", (EllipseStresses.ranges[e], 1.0))
                      for e in effects if e in EllipseStresses.ranges]

    def stress_solver(self, st):
        c = st.contact if st.exact is None else st.exact  # the exact ellipse's stresses
        a, b = float(np.atleast_1d(c.a)[-1]), float(np.atleast_1d(c.b)[-1])
        p0 = float(np.atleast_1d(c.max_pressure)[-1])
        return EllipseStresses(max(a, b), min(a, b), p0, self.materials.stressed.nu,
                               self.rtol)

    def effect_max_orthogonal_shear(self, solver):
        return solver.max_orthogonal_shear()

    def _solve(self, **load):
        return ellipse.solve(self.R1, self.R2, self.E_star, model=self.model, **load)

    def state(self, load) -> EllipticState:
        v = np.asarray(load.values, dtype=float)
        c = self._solve(**{load.kind: v})
        if self.model == "exact":
            return EllipticState(np.atleast_1d(c.depth), np.atleast_1d(c.force), EXACT_RTOL,
                                 "elliptic integrals", c)
        # the Gaussian estimate: its error is its deviation from the exact solution
        exact = ellipse.solve(self.R1, self.R2, self.E_star, model="exact", **{load.kind: v})
        return EllipticState(np.atleast_1d(c.depth), np.atleast_1d(c.force), EXACT_RTOL,
                             "Gaussian radius (5.28)-(5.30)", c, exact)

    def _value(self, st, attr, method):
        got = getattr(st.contact, attr)
        if st.exact is None:
            return Value(got, method, EXACT_RTOL)
        ref = getattr(st.exact, attr)
        return Value(got, f"{method}, Gaussian estimate; rel_error = deviation from exact",
                     _deviation(got, ref))

    def effect_depth(self, st):
        return self._value(st, "depth", st.method)

    def effect_force(self, st):
        return self._value(st, "force", st.method)

    def effect_force_law(self):
        """F = K d^(3/2) with K of the exact solution (numeric/force_law.py); under the
        Gaussian model the Hertz law of the Gaussian radius (5.30), whose rel_error is its
        deviation from the exact K."""
        from hertzmdr.numeric import force_law

        exact = force_law.ellipse(self.R1, self.R2, self.E_star)
        if self.model == "exact":
            return self.law_value(exact, "the exact elliptical contact (elliptic "
                                  "integrals)", EXACT_RTOL)
        law = force_law.hertz(float(bodies.gaussian_radius(self.R1, self.R2)), self.E_star)
        v = self.law_value(law, "(5.23) with the Gaussian radius (5.30)",
                           _deviation(law.K, exact.K))
        return Value(v.value, v.method + "; rel_error = deviation of K from exact",
                     v.rel_error)

    def effect_principal_radii(self):
        return Value([self.R1, self.R2], "eigenvalues of the gap's Hessian (Problem 2)",
                     CLOSED_FORM_RTOL)

    def effect_effective_radius(self):
        return Value(float(bodies.gaussian_radius(self.R1, self.R2)),
                     "Gaussian radius sqrt(R1 R2) (5.30)", CLOSED_FORM_RTOL)

    def effect_semi_axes(self, st):
        c = st.contact
        a, b = np.atleast_1d(c.a), np.atleast_1d(c.b)
        value = [float(a[0]), float(b[0])] if a.size == 1 else np.stack([a, b], axis=1)
        out = self._value(st, "a", "(5.28)" if self.model != "exact" else "elliptic integrals")
        if st.exact is not None:  # the larger deviation of the two semi-axes
            e = st.exact
            dev = max(_deviation(getattr(c, k), getattr(e, k)) for k in ("a", "b"))
            return Value(value, out.method, dev)
        return Value(value, out.method, out.rel_error)

    def effect_max_pressure(self, st):
        return self._value(st, "max_pressure", "(5.31)")

    def effect_mean_pressure(self, st):
        return self._value(st, "mean_pressure", "F/(pi a b)")

    def effect_stiffness(self, st):
        return self._value(st, "stiffness", "dF/dd")

    # -- the primitives of the force-depth curve and the pressure profile (base.Contact) -----
    pressure_method = "(5.31) along the R1 direction"

    @property
    def curve_method(self):
        return self.label

    def force_of(self, d):
        return self._solve(depth=d).force

    def p(self, x, d):
        """Along the x axis (the direction of R1)."""
        return self._solve(depth=d).pressure(x, 0.0)

    def extent(self, d):
        return float(self._solve(depth=d).a)
