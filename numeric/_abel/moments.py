"""Abel transforms, moments: integrals of v^k against the kernels of (5.59) and (5.61).

mu_k of the local variable v of one piece against (s - t)^(-1/2) (exact: in closed form, a
polynomial in one parameter, for (5.59); by Gauss-Legendre in w = sqrt(s - t) elsewhere),
against sqrt(A - s)/sqrt(s - t) (the (5.61) weight at a contact edge, in theta), and against
1/sqrt((s - beta)(s - t)) (a square-root kink of q, in u with s = c + h cosh u); numeric/abel.py's
docstring has the error model of each.
"""

from __future__ import annotations

from math import comb, factorial

import numpy as np

from hertzmdr.numeric._quadrature import gauss

_THETA_PANEL = 0.1  # widest theta panel of the (5.61) edge quadrature [rad]


_COSH_PANEL = 0.25  # widest u panel of the kink quadrature


def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes mapped to [0, 1] and their weights (summing to 1)."""
    t, w = gauss(n)
    return (t + 1) / 2, w / 2


def _beta_table(kmax: int) -> np.ndarray:
    """c[k, j] = C(k, j) (2k - j)! j! / (2k + 1)! (j <= k, else 0): int_0^1 x^k (x + beta
    (1 - x))^k dx = sum_j c[k, j] beta^j, every coefficient positive."""
    c = np.zeros((kmax + 1, kmax + 1))
    for k in range(kmax + 1):
        for j in range(k + 1):
            c[k, j] = comb(k, j) * factorial(2 * k - j) * factorial(j) / factorial(2 * k + 1)
    return c


# the tables for degree <= 9 (kmax <= 8), times the 2^(j+1) that ``_half_powers`` leaves out
# (mu_k = 2 (w_b - w_a) sum_j c[k, j] 2^j (beta/2)^j; powers of 2: exact)
_BETA_TABLES = {k: _beta_table(k) * 2.0 ** np.arange(1, k + 2) for k in range(9)}


def _half_powers(tau, s_lo, s_hi, kmax):
    """The exact moments mu_k = int_{s_lo}^{s_hi} v^k (s - tau)^(-1/2) ds, v = (s - s_lo)/
    (s_hi - s_lo), k = 0..kmax, are ``_BETA_TABLES[kmax] @`` this (0 where s_lo > tau).

    With s = tau + w^2 (ds/sqrt(s - tau) = 2 dw) and w = w_a + (w_b - w_a) x, x in [0, 1]:
    v = x (x + beta (1 - x)) with beta = 2 w_a/(w_a + w_b) in [0, 1], so
    mu_k = 2 (w_b - w_a) sum_j c[k, j] beta^j with the positive c of ``_beta_table``: no
    cancellation for any beta (the integral _moments_w takes by Gauss-Legendre in w, here a
    polynomial in one parameter per piece and output point, without nodes). Returned:
    (w_b - w_a) (beta/2)^j, j = 0..kmax (the powers of 2 are in the table), with
    w_b - w_a = (s_hi - s_lo)/(w_a + w_b) and w = sqrt(s - tau) taken once at every piece end
    (a piece's w_b is the next one's w_a: consecutive pieces, s_hi[i] = s_lo[i + 1]).
    Shapes: s_lo/s_hi (P, 1) and tau (1, B), both increasing -> (P, kmax+1, B).
    """
    ends = np.append(s_lo[:, 0], s_hi[-1, 0])[:, None]
    w = np.sqrt(np.maximum(ends - tau, 0.0))
    den = w[:-1] + w[1:]  # w_a + w_b
    valid = np.searchsorted(tau[0], s_lo[:, 0], side="right")  # rows with tau <= s_lo
    for i in np.flatnonzero(valid < tau.shape[1]):
        den[i, valid[i]:] = 1.0  # rows right of the piece: w_a = 0, zeroed below
    inv = np.divide(1.0, den, out=den)
    powers = np.empty((den.shape[0], kmax + 1, den.shape[1]))
    np.multiply(s_hi - s_lo, inv, out=powers[:, 0])  # (s_hi - s_lo)/(w_a + w_b) = w_b - w_a
    for i in np.flatnonzero(valid < tau.shape[1]):
        powers[i, 0, valid[i]:] = 0.0
    if kmax:
        half_beta = np.multiply(w[:-1], inv, out=w[:-1])  # w_a/(w_a + w_b) = beta/2
        for j in range(1, kmax + 1):
            np.multiply(powers[:, j - 1], half_beta, out=powers[:, j])
    return powers


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
