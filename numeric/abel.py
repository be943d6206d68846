"""Abel transforms of sampled contact data: the pressure back-transform (5.59) and (5.61).

On PyAbel's input convention -- a uniform grid x_i = i*dx, i = 0..N-1, the right half of a
symmetric profile, any leading axes are rows -- this module offers::

    from hertzmdr.numeric import abel
    p = abel.pressure_from_line_load(q, dx)     # (5.59): q [N/m] -> p [Pa], inverse Abel
    q = abel.line_load_from_pressure(p, dx)     # (5.61): p [Pa] -> q [N/m], forward Abel

Method (product integration in s = x^2)
---------------------------------------
With s = x^2 and t = r^2 both transforms become Riemann-Liouville integrals with the kernel
(s - t)^(-1/2) (Q(s) = q(sqrt s), P(t) = p(sqrt t), A = a^2):

.. math::

    P(t) = -\\frac{1}{\\pi}\\int_t^A \\frac{Q'(s)}{\\sqrt{s - t}}\\,ds \\quad (5.59),
    \\qquad
    Q(s) = \\int_s^A \\frac{P(t)}{\\sqrt{t - s}}\\,dt \\quad (5.61).

- The samples are interpolated by a piecewise polynomial of degree ``degree`` in s on the
  nodes s_i = (i dx)^2: each piece [s_i, s_(i+1)] takes the Lagrange polynomial of the
  ``degree + 1`` nodes centred on it (shifted, never straddling the end of the support).
  Even profiles are smooth functions of s = x^2, so no mirror points are needed at the axis
  and p(0) needs no special case; Hertz (q linear in s) and every even power law of degree
  <= 2*degree are reproduced to rounding.
- (5.59): the moments of the derivative of the interpolant against (s - t)^(-1/2) are
  integrated EXACTLY: with s = t + w^2 the kernel disappears, ds/sqrt(s - t) = 2 dw, and the
  integrand is a polynomial in w of degree 2*degree - 2. On the piece [s_a, s_b], with
  w = w_a + (w_b - w_a) x, the local variable is v = x (x + beta (1 - x)), beta =
  2 w_a/(w_a + w_b), so each moment is 2 (w_b - w_a) times a polynomial in beta with
  positive coefficients, exact and free of cancellation (w_b - w_a = (s_b - s_a)/(w_a +
  w_b)); the coefficients are folded into the derivative's once per piece, and an operator
  entry costs one square root and about 40 flops. The 1/sqrt singularity is therefore
  integrated analytically -- no point is dropped or shifted.
- (5.61) with a contact edge: p ~ sqrt(a^2 - r^2) at the edge, so the interpolated function is
  the smooth R(t) = P(t)/sqrt(A - t) (R_i = p_i/sqrt(a^2 - r_i^2) at the samples; the last
  piece [r_K^2, a^2] extrapolates the last stencil), and the weight sqrt(A - t)/sqrt(t - s) is
  integrated against it. Pieces at least 10 widths from the edge: t = s + w^2 as above, the
  factor sqrt(A - t) is analytic there and Gauss-Legendre with degree + 6 points in w gives
  every moment to 1e-15. The last 10 pieces: t = s + (A - s) sin^2(theta) turns the weight
  into 2 (A - s) cos^2(theta) d(theta), both end singularities vanish, and Gauss-Legendre on
  panels of at most 0.1 rad gives 1e-15 (both checked against mpmath moments). Without an
  edge (the samples do not vanish at the end of the grid) P itself is interpolated, the
  w-substitution integrates it exactly, and the transform is truncated at the end of the
  grid, as in PyAbel.
- A square-root kink of q at x = b (``kink=b`` in (5.59)), the MDR image of a kink of the
  profile such as the edge of a worn flat (Problem 8): left of b the pieces end at b; beyond
  it U = (Q - Q(b^2))/sqrt(s - b^2) is interpolated (Q(b^2) from the left interpolant, or the
  sample at b), so Q' = T(s)/sqrt(s - b^2) with T a polynomial, and the moments of
  1/sqrt((s - b^2)(s - t)) come from s = c + h cosh(u), c = (b^2 + t)/2, h = |b^2 - t|/2,
  whose weight is du: Gauss-Legendre on u-panels of at most 0.25. p is log-singular at b.
  ``kink=0`` is the same for a conical tip, q = q(0) + |x| U(x^2).
- The end of the support: ``edge=None`` takes the last non-zero sample x_K; when the samples
  after it are zero, the edge a in (x_K, x_(K+1)] is the root of the cubic through the last
  four samples of q (which vanishes like a - x at a contact edge) or of p^2 (p vanishes like
  sqrt(a - r)), extrapolated from x_K; if it has no root there, a = x_(K+1). Data that vanish
  otherwise (faster, or with a jump) need ``edge=a`` (then samples at x >= a must be zero, up
  to 1e-12 of the largest). An edge within 1e-9 dx after a sample is snapped to that sample
  (a/dx off a grid point by rounding). For (5.59) the node a carries q(a) = 0.
- Operators, applied to the last axis and cached (least recently used, up to 512 MB): (5.59)
  without an edge is one N x N matrix per (N, degree); with an edge it is that matrix
  restricted to the samples 0..K plus a correction of the last ~degree/2 + 1 pieces, whose
  stencils see the edge -- O(N degree^2) to build, so a new contact radius on the same grid
  costs no O(N^2) rebuild. (5.61) with an edge depends on a through every weight: one
  (K+1) x (K+1) matrix per (N, a, degree). A repeated transform of the same support is one
  matrix product, O(N^2), as with PyAbel's cached operators. For a known contact radius,
  ``pressure_matrix``/``line_load_matrix`` return the whole operator as an N x N matrix, to
  be applied by a product with no per-call validation or edge search (about 2 us at N = 51).

Accuracy: for data that are smooth functions of x^2 inside the support the error is
O(dx^degree) for (5.59) (one derivative of the interpolant; measured 5.4 for degree 5) and
O(dx^(degree + 1)) for (5.61); data polynomial in s (Hertz, n = 4) are reproduced to
rounding. A profile |x|^n that is not even-smooth limits the order to n - 1 for (5.59) and
n for (5.61) at the axis; the worn paraboloid's sqrt(x^2 - b^2) to 1.5 for r < b. The
measured orders and the comparison with PyAbel are in ``docs/abel.md``
(``benchmarks/bench_abel.py``).

Layout
------
This module is the public face (validation, rows, the four functions); the engine is the
private package ``numeric/_abel``: ``interpolation`` (the piecewise Lagrange interpolant in
s), ``moments`` (the kernels' moments), ``operators`` (the matrices, built, cached, applied),
``edge`` (the support's end found from the samples).

Two (5.59) engines
------------------
:mod:`hertzmdr.numeric.mdr` evaluates (5.59) too, by its own quadrature; the two are kept apart
on purpose. Here the input is samples of the line load on a uniform grid and the result must be
a linear operator on them (a matrix, cached and reused for every row and every call): the
derivative of the interpolant is integrated exactly against the kernel, which loses about
log10(N) digits to the differentiation of samples. The numerical MDR has g'(x) itself, not
samples of q: its smooth remainder tabulated in x or sqrt(x - b) (graded towards the axis and
the kinks) and the kinks' branch-point terms in closed form (the generated
``mdr_kink_pressure``), with a contact radius anywhere, not on a grid, and evaluates p at any
radius with an error bound from a second, coarser representation. Put through this operator, it
would have to be resampled on a uniform grid ending at a and differentiated again, losing both
the closed-form kink terms and the graded resolution. What they share is the Gauss-Legendre
rule (``numeric/_quadrature.py``) and the substitution that removes the kernel's singularity
(s = t + w^2 here, x = r + w^2 there).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric._abel.edge import _edge_index, _edge_over_dx
from hertzmdr.numeric._abel.operators import (
    _CACHE,  # noqa: F401 (cleared by tests, benchmarks)
    _apply,
    _build_kink,
    _cached,
    _operator,
)
from hertzmdr.numeric._validate import as_float, nonnegative, positive

__all__ = ["pressure_from_line_load", "line_load_from_pressure", "pressure_matrix",
           "line_load_matrix"]


def _check_degree(degree) -> None:
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)) or not (
            1 <= degree <= 9):
        raise ValueError(f"degree = {degree!r} is out of range; valid: an integer 1 <= degree "
                         "<= 9")


def _transform(direction, name, values, dx, edge, degree, kink=None):
    try:
        y = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        y = as_float(name, values)  # raises, naming the value
    if y.ndim == 0 or y.shape[-1] < 2:
        raise ValueError(f"{name} has shape {y.shape}; valid: at least 2 samples along the "
                         "last axis (x_i = i*dx, i = 0..N-1)")
    if not np.isfinite(y).all():
        as_float(name, y)  # NaN: its message
        i = tuple(int(k) for k in np.argwhere(~np.isfinite(y))[0])
        raise ValueError(f"{name}{list(i)} = {float(y[i])!r} is out of range; valid: finite "
                         "numbers")
    h = dx if isinstance(dx, float) and 0 < dx < np.inf else float(positive("dx", dx))
    _check_degree(degree)
    N = y.shape[-1]
    x_edge = None
    if edge is not None:
        a = float(positive("edge", edge))
        x_edge = _edge_over_dx(a, h, N)
        first_out = int(np.ceil(x_edge))
        tail = y[..., first_out:]
        beyond = np.abs(tail) > 1e-12 * np.max(np.abs(y))  # rounding-level values count as 0
        if beyond.any():
            where = tuple(int(k) for k in np.argwhere(beyond)[0])
            where = where[:-1] + (where[-1] + first_out,)
            raise ValueError(f"{name}{list(where)} = {float(y[where])!r} at x = "
                             f"{where[-1] * h!r} "
                             f"is beyond edge = {a!r}; valid: 0 at and beyond the edge")
        # the rounding-level tail needs no zeroing: with an edge, _edge_index reads no sample
        # and _apply only the samples 0..K, K = ceil(x_edge) - 1 < first_out; out is 0 beyond
    beta = None
    if kink is not None:
        b = float(nonnegative("kink", kink))
        if not b < (N - 1) * h:
            raise ValueError(f"kink = {b!r} is out of range; valid: 0 <= kink < (N-1)*dx = "
                             f"{(N - 1) * h!r}")
        beta = (b / h) ** 2
    rows = y.reshape(-1, N)
    groups: dict = {}
    for r, row in enumerate(rows):
        K, A = _edge_index(row if direction == "inverse" else row * row, x_edge)
        groups.setdefault((K, A), []).append(r)
    scale = 1 / h if direction == "inverse" else h
    out = np.zeros_like(rows)
    for (K, A), members in groups.items():
        if K < 0:
            continue  # an all-zero row transforms to zero
        sel = slice(None) if len(members) == len(rows) else members
        out[sel, :K + 1] = _apply(direction, K, A, int(degree), N, rows[sel, :K + 1],
                                  beta) * scale
    return out.reshape(y.shape)


def pressure_from_line_load(q, dx, *, edge=None, degree=5, kink=None):
    """Contact pressure p(r) [Pa] from samples of the MDR line load q(x) [N/m], (5.59).

    The inverse Abel transform p(r) = -(1/pi) int_r^a q'(x)/sqrt(x^2 - r^2) dx on PyAbel's
    convention: q[..., i] = q(i*dx), i = 0..N-1, the right half of the symmetric line load;
    leading axes are independent rows. Returns p on the same grid, 0 at and beyond the edge.

    Parameters
    ----------
    q : array_like, shape (..., N)
        Line load samples [N/m] (q = E* (d - g(x)) inside the contact, (5.58)), finite.
    dx : float
        Grid spacing [m], dx > 0.
    edge : float, optional
        Contact radius a [m], 0 < a <= (N-1)*dx; samples at x >= a must be 0. By default the
        edge is found from the samples: between the last non-zero sample and the next one, at
        the root of the cubic through the last four non-zero samples (q vanishes like a - x);
        if no sample is zero at the end of the grid, the integral is truncated there.
    degree : int, optional
        Degree of the piecewise interpolant of q in s = x^2, 1..9 (default 5). The error is
        O(dx^degree) for a line load that is a smooth function of x^2.
    kink : float, optional
        Radius b [m], 0 <= b < (N-1)*dx, where q has a square-root kink: smooth for x < b,
        q(b) + sqrt(x - b) * (smooth) beyond -- the MDR image (5.52) of a kink of the profile
        f, e.g. the edge of the flat of a worn paraboloid (Problem 8). The part beyond b is
        interpolated as (q - q(b))/sqrt(x^2 - b^2) and integrated against the kernel exactly
        (see the module docstring); without it, stencils straddling b limit the error to
        O(dx^1.5) for r < b. ``kink=0`` is a conical tip, q = q(0) + |x| * (smooth in x^2)
        (the cone's q ~ d - c|x| is then reproduced to rounding). p is log-singular at r = b:
        a sample there is returned as +inf (or -inf for a line load rising beyond b).

    Returns
    -------
    ndarray, shape (..., N)
        p(r_i) [Pa] at r_i = i*dx.

    Notes
    -----
    With s = x^2, t = r^2 (5.59) reads

    .. math:: p(\\sqrt t) = -\\frac{1}{\\pi}\\int_t^{a^2}\\frac{dq/ds}{\\sqrt{s - t}}\\,ds,

    integrated exactly for the piecewise polynomial (substitution s = t + w^2, Gauss-Legendre
    exact in w); see the module docstring. The operator is cached per (N, edge, degree).
    """
    return _transform("inverse", "q", q, dx, edge, degree, kink)  # (5.59)


def line_load_from_pressure(p, dx, *, edge=None, degree=5):
    """MDR line load q(x) [N/m] from samples of the pressure p(r) [Pa], (5.61).

    The forward Abel transform q(x) = 2 int_x^a r p(r)/sqrt(r^2 - x^2) dr on PyAbel's
    convention: p[..., i] = p(i*dx), i = 0..N-1; leading axes are independent rows. Returns q
    on the same grid, 0 at and beyond the edge.

    Parameters
    ----------
    p : array_like, shape (..., N)
        Pressure samples [Pa], finite.
    dx : float
        Grid spacing [m], dx > 0.
    edge : float, optional
        Contact radius a [m], 0 < a <= (N-1)*dx; samples at r >= a must be 0. By default found
        from the samples as the root of the cubic through the last four non-zero values of
        p^2 (p vanishes like sqrt(a - r) at a contact edge), extrapolated to the next sample;
        if no sample is zero at the end of the grid, p is interpolated itself and the integral
        truncated there.
    degree : int, optional
        Degree of the piecewise interpolant in s = r^2, 1..9 (default 5). With an edge the
        interpolated function is p/sqrt(a^2 - r^2), smooth for a contact pressure; the error
        is O(dx^(degree + 1)) when it is a smooth function of r^2.

    Returns
    -------
    ndarray, shape (..., N)
        q(x_i) [N/m] at x_i = i*dx.

    Notes
    -----
    With s = x^2, t = r^2 (5.61) reads

    .. math:: q(\\sqrt s) = \\int_s^{a^2}\\frac{p(\\sqrt t)}{\\sqrt{t - s}}\\,dt
        = \\int_s^{a^2} R(t)\\,\\frac{\\sqrt{a^2 - t}}{\\sqrt{t - s}}\\,dt,

    with R = p/sqrt(a^2 - t) interpolated and the weight integrated by t = s + (a^2 - s)
    sin^2(theta); see the module docstring. The operator is cached per (N, edge, degree).
    """
    return _transform("forward", "p", p, dx, edge, degree)  # (5.61)


def _matrix(direction: str, N, dx, edge, degree, kink=None) -> np.ndarray:
    if isinstance(N, bool) or not isinstance(N, (int, np.integer)) or N < 2:
        raise ValueError(f"N = {N!r} is out of range; valid: an integer N >= 2")
    h = float(positive("dx", dx))
    _check_degree(degree)
    a = float(positive("edge", edge))
    x_edge = _edge_over_dx(a, h, N)
    K, A = _edge_index(np.zeros(N), x_edge)
    beta = None
    if kink is not None:
        b = float(nonnegative("kink", kink))
        if not b < a:
            raise ValueError(f"kink = {b!r} is out of range; valid: 0 <= kink < edge = {a!r}")
        beta = (b / h) ** 2
        _, j_kink, _ = _cached(("inverse-kink", K, A, beta, int(degree)),
                               lambda: _build_kink(K, A, beta, int(degree)))
        if j_kink >= 0:
            raise ValueError(f"kink = {b!r} is a grid point, where p is infinite: the matrix "
                             "cannot hold it; use pressure_from_line_load, or a grid without "
                             "a sample at the kink")
    scale = 1 / h if direction == "inverse" else h
    M = np.zeros((N, N))
    # the transform is linear in the samples 0..K: its cached operator (for (5.59) with an
    # edge, the edge-free one plus this edge's correction), as _apply applies it
    M[:K + 1, :K + 1] = _operator(direction, K, A, int(degree), N, beta) * scale
    return M


def pressure_matrix(N: int, dx: float, *, edge: float, degree: int = 5,
                    kink: float | None = None) -> np.ndarray:
    """The operator of :func:`pressure_from_line_load` (5.59) for a known contact radius.

    ``pressure_matrix(N, dx, edge=a) @ q`` equals ``pressure_from_line_load(q, dx, edge=a)``
    for every line load q [N/m] on the grid x_i = i*dx that vanishes at and beyond a: one
    matrix product, with no validation or edge search per call, for repeated transforms at a
    fixed contact radius (time stepping, DEM, fitting). Returns p [Pa] per unit q [N/m].

    Parameters
    ----------
    N : int
        Samples, N >= 2.
    dx : float
        Grid spacing [m], dx > 0.
    edge : float
        Contact radius a [m], 0 < a <= (N-1)*dx.
    degree : int, optional
        As in :func:`pressure_from_line_load`.
    kink : float, optional
        As in :func:`pressure_from_line_load`, 0 <= kink < edge, not on a grid point (where p
        is infinite).

    Returns
    -------
    ndarray, shape (N, N)
        [1/m]; rows and columns at and beyond the edge are 0.
    """
    return _matrix("inverse", N, dx, edge, degree, kink)  # (5.59)


def line_load_matrix(N: int, dx: float, *, edge: float, degree: int = 5) -> np.ndarray:
    """The operator of :func:`line_load_from_pressure` (5.61) for a known contact radius.

    ``line_load_matrix(N, dx, edge=a) @ p`` equals ``line_load_from_pressure(p, dx, edge=a)``
    for every pressure p [Pa] on the grid r_i = i*dx that vanishes at and beyond a. Returns
    q [N/m] per unit p [Pa].

    Parameters
    ----------
    N : int
        Samples, N >= 2.
    dx : float
        Grid spacing [m], dx > 0.
    edge : float
        Contact radius a [m], 0 < a <= (N-1)*dx.
    degree : int, optional
        As in :func:`line_load_from_pressure`.

    Returns
    -------
    ndarray, shape (N, N)
        [m]; rows and columns at and beyond the edge are 0.
    """
    return _matrix("forward", N, dx, edge, degree)  # (5.61)
