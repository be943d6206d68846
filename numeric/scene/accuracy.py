"""The accuracy contract of a scene: one relative tolerance, ``[accuracy] rtol``, with one
default, and the range each method can deliver.

- Closed forms (every generated function in float64) reach :data:`CLOSED_FORM_RTOL`, the bound
  to which ``tests/`` verify each against its 50-digit independent reference; they cannot be
  asked for less than that.
- Numerical methods take rtol as their target: the impact's equation of motion is integrated to
  it (:data:`MOTION_RANGE`, what :func:`hertzmdr.numeric.motion.integrate` accepts), the BEM
  iterates its conjugate gradients to it (:data:`BEM_RANGE`), the numerical MDR refines its
  grid towards it (``mdr`` declares its range).
- A request outside the range of a method the scene uses is a :class:`~.schema.SceneError`
  naming ``accuracy.rtol``, the value and the range.
- Every effect reports its ``rel_error`` and ``met_rtol`` (rel_error <= rtol). Some errors are
  not set by the tolerance (the BEM's pixel size, a sampled profile's samples, the chapter's
  Gaussian estimate of an elliptical contact): those effects report ``met_rtol = false`` and
  the table flags them.
"""

from __future__ import annotations

#: the default ``[accuracy] rtol``: the tolerance of every numerical method of a scene
DEFAULT_RTOL = 1e-10
#: relative error bound of a generated closed form evaluated in float64
CLOSED_FORM_RTOL = 1e-14
#: rtol a closed form can deliver
CLOSED_FORM_RANGE = (CLOSED_FORM_RTOL, 1.0)
#: rtol the integrator of the impact's equation of motion accepts (numeric/motion.py, DOP853)
MOTION_RANGE = (1e-13, 1e-3)
#: tolerances of the BEM's conjugate gradients (numeric/bem.py): both BEM examples converge at
#: 1e-14 (in under 0.4 s); above 1e-3 the solver's own error would reach the discretization
#: error (1e-3 to 5e-2 on the examples) that the scene reports as rel_error
BEM_RANGE = (1e-14, 1e-3)


def outside(rtol: float, rng: tuple[float, float]) -> bool:
    """Whether ``rtol`` lies outside the closed range ``rng``."""
    return not rng[0] <= rtol <= rng[1]
