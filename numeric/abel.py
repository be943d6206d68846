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
  integrand is a polynomial in w of degree 2*degree - 2, which Gauss-Legendre with
  ``degree`` nodes integrates exactly (the piece boundaries in w are computed without
  cancellation, w_b - w_a = (s_b - s_a)/(w_a + w_b)). The 1/sqrt singularity is therefore
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
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np

from hertzmdr.numeric._quadrature import gauss
from hertzmdr.numeric._validate import as_float, nonnegative, positive

__all__ = ["pressure_from_line_load", "line_load_from_pressure", "pressure_matrix",
           "line_load_matrix"]

_THETA_PANEL = 0.1  # widest theta panel of the (5.61) edge quadrature [rad]
_CACHE: OrderedDict = OrderedDict()
_CACHE_BYTES = 512 * 2**20  # operators kept: N = 3201 takes 80 MB each
_BLOCK = 48  # rows of the operator built at once (bounds the memory of the build)


def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes mapped to [0, 1] and their weights (summing to 1)."""
    t, w = gauss(n)
    return (t + 1) / 2, w / 2


def _stencils(n_pieces: int, last_node: int, degree: int) -> np.ndarray:
    """First node of the stencil of each piece [i, i+1]: centred, never past ``last_node``."""
    start = np.arange(n_pieces) - (degree - 1) // 2
    return np.clip(start, 0, max(last_node - degree, 0))


def _lagrange_power(nodes: np.ndarray) -> np.ndarray:
    """Power-basis coefficients of the Lagrange polynomials of ``nodes`` (shape (P, m+1)).

    Returns C with shape (P, m+1, m+1): l_l(v) = sum_k C[:, k, l] v^k. Built as products of
    linear factors (no Vandermonde inverse), which stays accurate for the nodes 0, 1, 4, 9 ...
    of the first pieces.
    """
    P, m1 = nodes.shape
    C = np.zeros((P, m1, m1))
    for ll in range(m1):
        poly = np.zeros((P, m1))
        poly[:, 0] = 1.0
        for rr in range(m1):
            if rr == ll:
                continue
            den = nodes[:, ll] - nodes[:, rr]
            shifted = np.zeros_like(poly)
            shifted[:, 1:] = poly[:, :-1]
            poly = (shifted - nodes[:, rr, None] * poly) / den[:, None]
        C[:, :, ll] = poly
    return C


def _pieces(edges: np.ndarray, nodes: np.ndarray, degree: int):
    """Stencils, widths and Lagrange coefficients of the pieces [edges_i, edges_(i+1)].

    Returns (idx, width, C, deg): idx (P, deg+1) the node indices of each stencil (centred,
    clipped to the nodes), C (P, deg+1, deg+1) in the local variable v = (s - edges_i)/width_i.
    """
    n_pieces = len(edges) - 1
    deg = min(degree, len(nodes) - 1)
    start = _stencils(n_pieces, len(nodes) - 1, deg)
    idx = start[:, None] + np.arange(deg + 1)
    width = edges[1:] - edges[:-1]
    local = (nodes[idx] - edges[:-1, None]) / width[:, None]
    return idx, width, _lagrange_power(local), deg


def _moments_w(tau, s_lo, s_hi, width, kmax, n_gauss, A=None):
    """mu_k = int_{s_lo}^{s_hi} v^k (s - tau)^(-1/2) ds, v = (s - s_lo)/width, k = 0..kmax.

    Exact when 2*kmax <= 2*n_gauss - 1: the integrand is 2 v^k, a polynomial of degree 2k in
    w = sqrt(s - tau). With ``A``, the integrand has the factor sqrt(A - s), analytic on
    pieces at least 4 widths from A (see _build): Gauss-Legendre in w converges geometrically.
    Shapes: tau (B, 1), s_lo/s_hi/width (1, P) -> (B, P, kmax+1).
    """
    xg, wg = _gauss(n_gauss)
    wa = np.sqrt(np.maximum(s_lo - tau, 0.0))
    wb = np.sqrt(np.maximum(s_hi - tau, 0.0))
    span = (s_hi - s_lo) / np.where(wa + wb > 0, wa + wb, 1.0)  # wb - wa without cancellation
    w = wa[..., None] + span[..., None] * xg
    v = (w - wa[..., None]) * (w + wa[..., None]) / width[..., None]
    weight = np.broadcast_to(2 * span[..., None] * wg, v.shape)
    if A is not None:  # A - s = (A - s_lo) - v width, no cancellation (clipped at 0 for the
        # pieces left of tau, whose moments are discarded)
        weight = weight * np.sqrt(np.maximum((A - s_lo)[..., None] - v * width[..., None], 0))
    out = np.empty(v.shape[:-1] + (kmax + 1,))
    out[..., 0] = weight.sum(axis=-1)
    vk = weight
    for k in range(1, kmax + 1):
        vk = vk * v
        out[..., k] = vk.sum(axis=-1)
    return out


def _moments_theta(tau, s_lo, s_hi, width, A, kmax, n_gauss):
    """mu_k = int_{s_lo}^{s_hi} v^k sqrt(A - s)/sqrt(s - tau) ds (the (5.61) edge weight).

    With s = tau + (A - tau) sin^2(theta): mu_k = 2 (A - tau) int v^k cos^2(theta) d(theta),
    composite Gauss-Legendre on panels of at most _THETA_PANEL rad. Shapes as _moments_w.
    """
    L = A - tau  # (B, 1)
    sa = np.sqrt(np.clip((s_lo - tau) / L, 0, 1))
    ca = np.sqrt(np.clip((A - s_lo) / L, 0, 1))
    sb = np.sqrt(np.clip((s_hi - tau) / L, 0, 1))
    cb = np.sqrt(np.clip((A - s_hi) / L, 0, 1))
    # theta_b - theta_a from sin and cos of the difference: sin = (sb^2 - sa^2)/(sb ca + sa cb)
    den = sb * ca + sa * cb
    sin_d = np.where(den > 0, ((s_hi - s_lo) / L) / np.where(den > 0, den, 1), 0.0)
    cos_d = cb * ca + sb * sa
    dtheta = np.arctan2(sin_d, cos_d)
    theta_a = np.arctan2(sa, ca)
    xg, wg = _gauss(n_gauss)
    shape = np.broadcast_shapes(dtheta.shape, width.shape)
    out = np.zeros(shape + (kmax + 1,))
    n_panels = np.maximum(np.ceil(dtheta / _THETA_PANEL), 1).astype(int)
    for n_p in np.unique(n_panels):
        sel = n_panels == n_p
        ta = np.broadcast_to(theta_a, shape)[sel]
        dt = np.broadcast_to(dtheta, shape)[sel]
        Ls = np.broadcast_to(L, shape)[sel]
        ws = np.broadcast_to(width, shape)[sel]
        # all nodes of the n_p panels, as offsets phi from theta_a
        xs = ((np.arange(n_p)[:, None] + xg) / n_p).ravel()
        ww = np.tile(wg / n_p, n_p)
        phi = dt[:, None] * xs
        theta = ta[:, None] + phi
        v = Ls[:, None] * np.sin(phi) * np.sin(2 * ta[:, None] + phi) / ws[:, None]
        weight = 2 * Ls[:, None] * np.cos(theta) ** 2 * dt[:, None] * ww
        vk = np.ones_like(v)
        res = np.empty((sel.sum(), kmax + 1))
        for k in range(kmax + 1):
            res[:, k] = np.sum(vk * weight, axis=1)
            vk = vk * v
        out[sel] = res
    return out


_NEAR_EDGE = 10.0  # (5.61): pieces closer to the edge than this many widths use theta


def _config(direction, M, A, degree):
    """Pieces of the interpolant on the samples 0..M-1 (units dx = 1) and an edge A or None."""
    s = np.arange(M, dtype=float) ** 2
    edges = np.append(s, A) if A is not None else s
    if direction == "inverse":
        # the edge is a node too, carrying q(a) = 0 (its column is dropped by the caller)
        idx, width, C, deg = _pieces(edges, edges, degree)
        # the derivative Q'(s) = sum_k D[:, k, l] v^k y_l
        D = C[:, 1:, :] * np.arange(1, deg + 1)[None, :, None] / width[:, None, None]
    else:
        # R = P/sqrt(A - s) (or P without an edge) from the samples only; the last piece
        # [s_K, A] extrapolates the last stencil
        idx, width, D, deg = _pieces(edges, s, degree)
    return s, edges, idx, width, D, deg


def _assemble(direction, cfg, A, p0, p1, n_rows):
    """Contributions of the pieces p0..p1-1 to the rows 0..n_rows-1: (n_rows, len(edges))."""
    s, edges, idx, width, D, deg = cfg
    W = np.zeros((n_rows, len(edges)))
    if direction == "inverse":
        if deg == 0:
            return W  # a single node: Q' = 0
        kmax, n_gauss = deg - 1, deg
    else:
        # with an edge, sqrt(A - s) is analytic on the pieces done in w (>= _NEAR_EDGE widths
        # from A; its branch point then lies >= 3 piece widths away in w as well): the
        # polynomial v^k takes 2k of the 2n - 1 exact degrees, the rest converges like
        # (7 + sqrt 48)^-(2n - 2k): deg + 6 points give 1e-15 for every k (checked against
        # mpmath for k <= 5, 3 <= eps <= 1000); theta: 9 points on panels <= 0.1 rad, 1e-15
        kmax, n_gauss = deg, max(deg + 6, 9) if A is not None else deg + 1
    cols = len(edges)
    rows = min(n_rows, p1)  # the pieces left of an output point contribute nothing
    for j0 in range(0, rows, _BLOCK):
        j1 = min(j0 + _BLOCK, rows)
        tau = s[j0:j1, None]
        a0 = max(p0, j0)
        lo, hi, wd = edges[None, a0:p1], edges[None, a0 + 1:p1 + 1], width[None, a0:p1]
        if direction == "forward" and A is not None:
            # the last pieces (both end singularities close) by theta, the others by w
            near = int(np.searchsorted(-((A - hi[0]) / wd[0]), -_NEAR_EDGE))
            mu = np.concatenate([
                _moments_w(tau, lo[:, :near], hi[:, :near], wd[:, :near], kmax, n_gauss, A),
                _moments_theta(tau, lo[:, near:], hi[:, near:], wd[:, near:], A, kmax,
                               n_gauss)], axis=1)
        else:
            mu = _moments_w(tau, lo, hi, wd, kmax, n_gauss)
        mu[np.broadcast_to(lo < tau, mu.shape[:2])] = 0.0  # pieces left of the output point
        contrib = np.einsum("bik,ikl->bil", mu, D[a0:p1])  # piece i -> node idx[i, l]
        B = j1 - j0
        flat = (np.arange(B)[:, None, None] * cols + idx[None, a0:p1, :]).ravel()
        W[j0:j1] += np.bincount(flat, weights=contrib.ravel(), minlength=B * cols).reshape(
            B, cols)
    return W


def _build(direction: str, K: int, A: float | None, degree: int) -> np.ndarray:
    """The operator (K+1, K+1) on the samples 0..K, in units dx = 1 (see module docstring)."""
    cfg = _config(direction, K + 1, A, degree)
    n_pieces = len(cfg[1]) - 1
    W = _assemble(direction, cfg, A, 0, n_pieces, K + 1)[:, :K + 1]
    if direction == "inverse":
        return W * (-1 / np.pi)
    if A is not None:
        W /= np.sqrt(A - cfg[0])[None, :]  # R_i = P_i / sqrt(A - s_i)
    return W


def _edge_correction(K: int, A: float, degree: int, N: int):
    """(5.59) with an edge: the operator is the edge-free one of N samples (cached per N),
    restricted to the samples 0..K, plus this correction of the last pieces, O(N degree^2).

    Returns (c0, Corr): add y[c0:K+1] @ Corr.T. The pieces whose stencils are the same with
    and without the edge (all but the last ~degree/2 + 1) contribute the same to both.
    """
    edge_cfg = _config("inverse", K + 1, A, degree)
    full_cfg = _config("inverse", N, None, degree)
    idx_e, idx_f = edge_cfg[2], full_cfg[2]
    n_full = len(full_cfg[1]) - 1
    i_e = K
    for i in range(max(0, K - 2 * degree - 2), K + 1):
        same = (i < n_full and idx_e[i, 0] == idx_f[i, 0] and idx_e[i, -1] <= K
                and idx_f[i, -1] <= K and i < K)
        if not same:
            i_e = i
            break
    # the pieces of the edge-free operator that reach the columns 0..K from i_e on
    p1_full = n_full
    while p1_full > i_e and idx_f[p1_full - 1, 0] > K:
        p1_full -= 1
    T_edge = _assemble("inverse", edge_cfg, A, i_e, K + 1, K + 1)[:, :K + 1]
    T_full = (_assemble("inverse", full_cfg, None, i_e, p1_full, K + 1)[:, :K + 1]
              if p1_full > i_e else 0.0)
    c0 = int(min(idx_e[i_e, 0], idx_f[min(i_e, n_full - 1), 0]))
    corr = (T_edge - T_full)[:, c0:] * (-1 / np.pi)
    return c0, corr


_COSH_PANEL = 0.25  # widest u panel of the kink quadrature


def _moments_cosh(tau, s_lo, s_hi, width, beta, kmax, n_gauss):
    """mu_k = int_{s_lo}^{s_hi} v^k ds/sqrt((s - beta)(s - tau)), s_lo >= max(beta, tau).

    With c = (beta + tau)/2, h = |beta - tau|/2 and s = c + h cosh(u) the weight is du; the
    integrand v^k is an entire function of u, integrated by Gauss-Legendre on panels of at most
    _COSH_PANEL (error ~ (5 * 0.125)^16/16! for k = 5). Shapes as _moments_w; tau != beta.
    """
    hi_pt, lo_pt = np.maximum(beta, tau), np.minimum(beta, tau)
    valid = (s_lo >= hi_pt) & (hi_pt > lo_pt)  # the others are zero
    h = np.where(hi_pt > lo_pt, (hi_pt - lo_pt) / 2, 1.0)
    s_lo = np.where(valid, s_lo, hi_pt + width)
    s_hi = s_lo + width
    z_lo = (s_lo - (beta + tau) / 2) / h
    z_hi = (s_hi - (beta + tau) / 2) / h
    S_lo = np.sqrt((s_lo - hi_pt) * (s_lo - lo_pt)) / h  # sinh(u_lo)
    S_hi = np.sqrt((s_hi - hi_pt) * (s_hi - lo_pt)) / h
    # u_hi - u_lo from sinh of the difference, (z_hi^2 - z_lo^2)/(S_hi z_lo + z_hi S_lo)
    du = np.arcsinh((width / h) * (z_hi + z_lo) / (S_hi * z_lo + z_hi * S_lo))
    du = np.where(valid, du, 0.0)
    shape = du.shape
    out = np.zeros(shape + (kmax + 1,))
    xg, wg = _gauss(n_gauss)
    n_panels = np.maximum(np.ceil(du / _COSH_PANEL), 1).astype(int)
    for n_p in np.unique(n_panels):
        sel = n_panels == n_p
        d = du[sel]
        zl, sl = np.broadcast_to(z_lo, shape)[sel], np.broadcast_to(S_lo, shape)[sel]
        scale = (np.broadcast_to(h, shape) / np.broadcast_to(width, shape))[sel]
        xs = ((np.arange(n_p)[:, None] + xg) / n_p).ravel()
        ww = np.tile(wg / n_p, n_p)
        phi = d[:, None] * xs
        v = scale[:, None] * (2 * zl[:, None] * np.sinh(phi / 2) ** 2 + sl[:, None] * np.sinh(phi))
        weight = d[:, None] * ww
        res = np.empty((sel.sum(), kmax + 1))
        vk = weight
        res[:, 0] = vk.sum(axis=1)
        for k in range(1, kmax + 1):
            vk = vk * v
            res[:, k] = vk.sum(axis=1)
        out[sel] = res
    return out


def _build_kink(K: int, A: float | None, beta: float, degree: int) -> np.ndarray:
    """(5.59) with a square-root kink of q at s = beta (units dx = 1): (K+1, K+1).

    Left of the kink Q is a polynomial in s as usual, ending with the piece [s_J, beta]; right
    of it Q = Q(beta) + sqrt(s - beta) U(s) with U interpolated (U_i = (Q_i - Q(beta))/sqrt(s_i
    - beta), Q(beta) from the left interpolant, U(A) = -Q(beta)/sqrt(A - beta) at the edge),
    so Q' = T(s)/sqrt(s - beta) with T a polynomial and the kernel
    1/sqrt((s - beta)(s - t)) is integrated by s = c + h cosh(u) (_moments_cosh).
    """
    s = np.arange(K + 1, dtype=float) ** 2
    near = round(float(np.sqrt(beta)))
    if abs(beta - near**2) <= 1e-9 * (2 * near + 1):
        beta = float(near**2)  # the kink is a sample: it closes the left part
    J = int(np.searchsorted(s, beta, side="right")) - 1  # last sample at or left of the kink
    on_grid = s[J] == beta
    W = np.zeros((K + 1, K + 1))
    # left: the pieces [s_0, s_1] ... [s_J, beta] on the samples 0..J
    left_edges = s[:J + 1] if on_grid else np.append(s[:J + 1], beta)
    idx_l, w_l, C_l, deg_l = _pieces(left_edges, s[:J + 1], degree)
    e_beta = np.zeros(K + 1)  # Q(beta) = e_beta @ y: the sample, or the last piece at v = 1
    if on_grid:
        e_beta[J] = 1.0
    else:
        e_beta[idx_l[-1]] = C_l[-1].sum(axis=0)
    # right: the pieces [beta, s_(J+1)], ..., [s_K, A] (or up to s_K without an edge)
    r_nodes = s[J + 1:] if A is None else np.append(s[J + 1:], A)
    r_edges = np.concatenate([[beta], r_nodes])
    n_r = len(r_nodes)
    G = np.zeros((n_r, K + 1))  # U at the right nodes = G @ y
    dist = np.sqrt(r_nodes - beta)
    for r in range(n_r):
        if J + 1 + r <= K:
            G[r, J + 1 + r] += 1 / dist[r]
        G[r] -= e_beta / dist[r]
    deg_r = min(degree, n_r - 1)
    n_rp = len(r_edges) - 1
    start = np.clip(np.arange(n_rp) - 1 - (deg_r - 1) // 2, 0, max(n_r - 1 - deg_r, 0))
    idx_r = start[:, None] + np.arange(deg_r + 1)
    w_r = r_edges[1:] - r_edges[:-1]
    C_r = _lagrange_power((r_nodes[idx_r] - r_edges[:-1, None]) / w_r[:, None])
    e_off = (r_edges[:-1] - beta) / w_r
    kk = np.arange(deg_r + 1)[None, :, None]
    C_next = np.concatenate([C_r[:, 1:, :], np.zeros_like(C_r[:, :1, :])], axis=1)
    T = C_r * (kk + 0.5) + e_off[:, None, None] * (kk + 1) * C_next
    Wr = np.zeros((K + 1, n_r))
    # left pieces for the rows left of the kink (exact w-moments of the derivative)
    if deg_l >= 1:
        D_l = C_l[:, 1:, :] * np.arange(1, deg_l + 1)[None, :, None] / w_l[:, None, None]
        for j0 in range(0, J + 1, _BLOCK):
            j1 = min(j0 + _BLOCK, J + 1)
            tau = s[j0:j1, None]
            lo, hi, wd = left_edges[None, j0:-1], left_edges[None, j0 + 1:], w_l[None, j0:]
            mu = _moments_w(tau, lo, hi, wd, deg_l - 1, deg_l)
            mu[np.broadcast_to(lo < tau, mu.shape[:2])] = 0.0
            contrib = np.einsum("bik,ikl->bil", mu, D_l[j0:])
            for ll in range(idx_l.shape[1]):
                np.add.at(W, (np.arange(j0, j1)[:, None], idx_l[None, j0:, ll]),
                          contrib[:, :, ll])
    # right pieces for every row (the row at the kink itself is log-singular: inf)
    for j0 in range(0, K + 1, _BLOCK):
        j1 = min(j0 + _BLOCK, K + 1)
        tau = s[j0:j1, None].copy()
        tau[tau[:, 0] == beta] = -1.0  # the row at the kink: any value, zeroed below
        lo, hi, wd = r_edges[None, :-1], r_edges[None, 1:], w_r[None, :]
        ok = np.broadcast_to(lo >= tau, (j1 - j0, n_rp))
        mu = np.zeros((j1 - j0, n_rp, deg_r + 1))
        if ok.any():
            rows_ok = np.flatnonzero(ok.any(axis=1))
            first = int(np.argmax(ok[rows_ok[0]]))
            mu_part = _moments_cosh(tau[rows_ok], lo[:, first:], hi[:, first:], wd[:, first:],
                                    beta, deg_r, 8)
            mu[rows_ok, first:] = mu_part
            mu[~ok] = 0.0
        contrib = np.einsum("bik,ikl->bil", mu, T)
        for ll in range(idx_r.shape[1]):
            np.add.at(Wr, (np.arange(j0, j1)[:, None], idx_r[None, :, ll]), contrib[:, :, ll])
    W = (W + Wr @ G) * (-1 / np.pi)
    j_kink = int(J) if on_grid else -1
    W[j_kink if on_grid else slice(0, 0)] = 0.0  # the log-singular row: set by _apply
    u0 = (C_r[0, 0, :] @ G[idx_r[0]]) if on_grid else None  # U(beta) = u0 @ y
    return W, j_kink, u0


def _edge_index(y: np.ndarray, x_edge: float | None) -> tuple[int, float | None]:
    """(K, A) of one row in units dx = 1: K the last sample inside the support, A = a^2.

    ``y`` is q (inverse) or p^2 (forward): a function vanishing linearly in s at the edge.
    """
    N = y.size
    if x_edge is not None:
        K = max(min(int(np.ceil(x_edge)) - 1, N - 1), 0)
        return _snap(K, x_edge**2)
    nz = np.flatnonzero(y)
    if nz.size == 0:
        return -1, None
    K = int(nz[-1])
    if K == N - 1:
        return K, None  # no edge on the grid: truncated transform
    deg = min(_EDGE_DEGREE, K)
    span = 2.0 * K + 1  # s_(K+1) - s_K; the local variable u = (s - s_K)/span
    if deg == 0:
        return K, K**2 + span
    coef = _edge_vandermonde_inv(K, deg) @ y[K - deg:K + 1]  # power coefficients in u
    u = _edge_root(coef)
    return _snap(K, K**2 + span * u)


def _snap(K: int, A: float) -> tuple[int, float]:
    """An edge within 1e-9 dx after the sample K is that sample (a/dx off a grid point by
    rounding): a last piece [s_K, A] that short would make the interpolant through the nearly
    coincident nodes s_K, A amplify the rounding of the (nearly zero) sample K by dx/(a - x_K).
    The sample K is then replaced by the edge's exact 0."""
    if K >= 1 and A - K**2 <= 1e-9 * (2 * K + 1):
        return K - 1, float(K**2)
    return K, A


def _edge_vandermonde_inv(K: int, deg: int) -> np.ndarray:
    key = (K, deg)
    V = _EDGE_CACHE.get(key)
    if V is None:
        nodes = (np.arange(K - deg, K + 1, dtype=float) ** 2 - K**2) / (2.0 * K + 1)
        V = np.linalg.inv(np.vander(nodes, deg + 1, increasing=True))
        if len(_EDGE_CACHE) > 4096:
            _EDGE_CACHE.clear()
        _EDGE_CACHE[key] = V
    return V


def _edge_root(coef: np.ndarray) -> float:
    """The smallest root in (0, 1] of the polynomial sum_k coef[k] u^k; 1 if there is none.

    Newton from the linear root (a few float operations; the data vanish nearly linearly),
    accepted when it converges inside (0, 1] with no sign change of the polynomial before it;
    otherwise the companion-matrix roots, polished by Newton.
    """
    c = [float(v) for v in coef]

    def val(u):
        acc, der = 0.0, 0.0
        for ck in reversed(c):
            der = der * u + acc
            acc = acc * u + ck
        return acc, der

    u = -c[0] / c[1] if c[1] != 0 else 0.5
    ok = False
    if 0 < u <= 1.5:
        for _ in range(8):
            f, d1 = val(u)
            if d1 == 0:
                break
            step = f / d1
            u -= step
            if abs(step) <= 1e-15 * max(abs(u), 1e-300):
                ok = True
                break
    if ok and 0 < u <= 1 + 1e-12:
        # no earlier root: the polynomial keeps the sign of c[0] on a few points of (0, u)
        mid = val(0.5 * u)[0]  # one probe: a root before u would show as a sign change
        if (mid > 0) == (c[0] > 0) and mid != 0:
            return min(u, 1.0)
    roots = np.polynomial.polynomial.polyroots(coef) if np.any(coef[1:]) else np.array([])
    real = roots.real[(np.abs(roots.imag) <= 1e-9) & (roots.real > 0)
                      & (roots.real <= 1 + 1e-12)]
    if not real.size:
        return 1.0  # no root before the next (zero) sample: the edge is that sample
    u = float(real.min())
    for _ in range(3):  # polish: the companion matrix loses digits when the top coefficients
        # are rounding noise (data linear in s, as for Hertz)
        f, d1 = val(u)
        if d1 == 0:
            break
        u -= f / d1
    return min(max(u, 0.0), 1.0)


_EDGE_CACHE: dict = {}
_EDGE_DEGREE = 3  # the edge extrapolation: cubic through the last 4 samples


def _cached(key, make):
    """Least-recently-used cache of operators, at most _CACHE_BYTES of arrays."""
    hit = _CACHE.get(key)
    if hit is not None:
        _CACHE.move_to_end(key)
        return hit
    value = make()
    _CACHE[key] = value

    def nbytes(v):
        return sum(a.nbytes for a in v if isinstance(a, np.ndarray)) if isinstance(
            v, tuple) else v.nbytes
    while len(_CACHE) > 1 and sum(nbytes(v) for v in _CACHE.values()) > _CACHE_BYTES:
        _CACHE.popitem(last=False)
    return value


def _apply(direction: str, K: int, A: float | None, degree: int, N: int, block: np.ndarray,
           beta: float | None = None):
    """The transform of the rows ``block`` (B, K+1) in units dx = 1."""
    if beta is not None and beta < (A if A is not None else K**2):
        W, j_kink, u0 = _cached(("inverse-kink", K, A, beta, degree),
                                lambda: _build_kink(K, A, beta, degree))
        out = block @ W.T
        if j_kink >= 0:  # p ~ (u0/(2 pi)) log|r^2 - b^2| with u0 = U(b): +-inf, or, without
            # the singular term (u0 = 0), the mean of the neighbours
            u = block @ u0
            lo, hi = out[:, max(j_kink - 1, 0)], out[:, min(j_kink + 1, K)]
            out[:, j_kink] = np.where(u < 0, np.inf, np.where(u > 0, -np.inf, (lo + hi) / 2))
        return out
    if direction == "inverse" and A is not None:
        # the edge-free operator of N samples, shared by every edge, and a correction of the
        # last pieces: a new edge costs O(N degree^2), not O(N^2)
        base = _cached(("inverse", N - 1, None, degree),
                       lambda: _build("inverse", N - 1, None, degree))
        c0, corr = _cached(("inverse-edge", K, A, degree, N),
                           lambda: _edge_correction(K, A, degree, N))
        return block @ base[:K + 1, :K + 1].T + block[:, c0:] @ corr.T
    W = _cached((direction, K, A, degree), lambda: _build(direction, K, A, degree))
    return block @ W.T


def _check_degree(degree) -> None:
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)) or not (
            1 <= degree <= 9):
        raise ValueError(f"degree = {degree!r} is out of range; valid: an integer 1 <= degree "
                         "<= 9")


def _edge_over_dx(a: float, h: float, N: int) -> float:
    """The edge a > 0 in units of dx = h, checked to lie on the grid of N samples."""
    if not a / h <= N - 1:
        raise ValueError(f"edge = {a!r} is out of range; valid: 0 < edge <= (N-1)*dx = "
                         f"{(N - 1) * h!r}")
    return a / h


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
        raise ValueError(f"{name}{list(i)} = {y[i]!r} is out of range; valid: finite numbers")
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
            raise ValueError(f"{name}{list(where)} = {y[where]!r} at x = {where[-1] * h!r} "
                             f"is beyond edge = {a!r}; valid: 0 at and beyond the edge")
        if tail.size and np.any(tail):
            y = y.copy()
            y[..., first_out:] = 0.0
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
    # the transform is linear in the samples 0..K: the images of the unit vectors are the
    # columns of the operator
    M[:K + 1, :K + 1] = _apply(direction, K, A, int(degree), N, np.eye(K + 1), beta).T * scale
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
