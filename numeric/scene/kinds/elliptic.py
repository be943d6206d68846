"""Elliptical Hertz contact of a quadratic gap with unequal principal radii: exact (complete
elliptic integrals, numeric/ellipse.py) or the chapter's Gaussian-radius estimate (5.28)-(5.30).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric import bodies, ellipse
from hertzmdr.numeric.scene.accuracy import CLOSED_FORM_RTOL
from hertzmdr.numeric.scene.kinds.base import Contact, State, Value

#: the tolerance to which tests/test_ellipse.py verifies the exact solution against mpmath
EXACT_RTOL = 1e-12


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


class EllipticContact(Contact):
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
