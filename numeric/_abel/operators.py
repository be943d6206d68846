"""Abel transforms, operators: the matrices of (5.59) and (5.61) on the samples, cached.

Built from the interpolant's pieces (``interpolation``) and the moments of their local variable
(``moments``): without an edge, with an edge (for (5.59) the edge-free operator plus a
correction of the last pieces), with a square-root kink of q; kept in a least-recently-used
cache of at most 512 MB and applied to blocks of rows.
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np

from hertzmdr.numeric._abel.interpolation import _lagrange_power, _pieces
from hertzmdr.numeric._abel.moments import (
    _BETA_TABLES,
    _half_powers,
    _moments_cosh,
    _moments_theta,
    _moments_w,
)

_CACHE: OrderedDict = OrderedDict()


_CACHE_BYTES = 512 * 2**20  # operators kept: N = 3201 takes 80 MB each


_BLOCK = 48  # rows of the operator built at once (bounds the memory of the build)


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


def _scatter_t(WT, rows, contrib, start):
    """WT[start[i] + l, rows] += contrib[i, l, :] (the transposed operator).

    The stencils are consecutive nodes from ``start``, which rises by 1 from piece to piece
    except where it is clipped at the ends of the support (a run of equal starts at either
    end): the pieces h-1 .. P-t of distinct starts go in as one slice per l, the rest of the
    two runs summed first. Any other pattern goes in piece by piece."""
    P = len(start)
    h = int(np.searchsorted(start, start[0], side="right"))  # the run of start[0]
    t = P - int(np.searchsorted(start, start[-1], side="left"))  # the run of start[-1]
    lo, hi = h - 1, P - t + 1
    c0 = int(start[0])
    if not (lo < hi and int(start[-1]) - c0 + 1 == hi - lo
            and np.all(np.diff(start[lo:hi]) == 1)):
        for i, c in enumerate(start):
            WT[c:c + contrib.shape[1], rows] += contrib[i]
        return
    n = hi - lo
    head = contrib[:lo].sum(axis=0) if lo > 0 else None
    tail = contrib[hi:].sum(axis=0) if hi < len(contrib) else None
    for ll in range(contrib.shape[1]):
        WT[c0 + ll:c0 + ll + n, rows] += contrib[lo:hi, ll]
        if head is not None:
            WT[c0 + ll, rows] += head[ll]
        if tail is not None:
            WT[c0 + n - 1 + ll, rows] += tail[ll]


def _assemble_inverse(cfg, p0, p1, n_rows):
    """(5.59): contributions of the pieces p0..p1-1 to the rows 0..n_rows-1, (n_rows,
    len(edges)) (the transpose of a C-ordered array): the exact moments of each piece
    against the kernel (``_half_powers``) times the derivative of its Lagrange basis."""
    s, edges, idx, width, D, deg = cfg
    WT = np.zeros((len(edges), n_rows))
    if deg == 0:
        return WT.T  # a single node: Q' = 0
    # the moments are _BETA_TABLES @ powers of one parameter per piece and row (_half_powers):
    # the table goes into the derivative's coefficients once per piece, E = D^T c
    E = np.ascontiguousarray(D.transpose(0, 2, 1)) @ _BETA_TABLES[deg - 1]  # (pieces, l, j)
    # blocks of pieces, each with every row it reaches (rows <= its last piece): each l adds
    # one contiguous band of rows of WT
    block = max(16, 2**18 // max(n_rows, 1))
    for i0 in range(p0, p1, block):
        i1 = min(i0 + block, p1)
        rows = min(n_rows, i1)
        powers = _half_powers(s[None, :rows], edges[i0:i1, None], edges[i0 + 1:i1 + 1, None],
                              deg - 1)  # (pieces, j, rows)
        _scatter_t(WT, slice(0, rows), E[i0:i1] @ powers, idx[i0:i1, 0])  # -> idx[i, l]
    return WT.T


def _assemble(direction, cfg, A, p0, p1, n_rows):
    """Contributions of the pieces p0..p1-1 to the rows 0..n_rows-1: (n_rows, len(edges))."""
    if direction == "inverse":
        return _assemble_inverse(cfg, p0, p1, n_rows)
    s, edges, idx, width, D, deg = cfg
    W = np.zeros((n_rows, len(edges)))
    # (5.61): with an edge, sqrt(A - s) is analytic on the pieces done in w (>= _NEAR_EDGE
    # widths from A; its branch point then lies >= 3 piece widths away in w as well): the
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
        if A is not None:
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
        W *= -1 / np.pi  # in place: W is the transpose of a C-ordered array (W.T is applied)
        return W
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


def _operator(direction: str, K: int, A: float | None, degree: int, N: int,
              beta: float | None = None) -> np.ndarray:
    """The matrix M (K+1, K+1) of ``_apply``: _apply(..., y) == y @ M.T for a kink off the
    grid (a kink on a sample has an infinite entry), the same numbers as _apply(..., identity)
    without its O(K^3) product."""
    if beta is not None and beta < (A if A is not None else K**2):
        W, j_kink, _ = _cached(("inverse-kink", K, A, beta, degree),
                               lambda: _build_kink(K, A, beta, degree))
        if j_kink >= 0:
            raise ValueError("a kink on a sample: the operator has an infinite entry")
        return W.copy()
    if direction == "inverse" and A is not None:
        base = _cached(("inverse", N - 1, None, degree),
                       lambda: _build("inverse", N - 1, None, degree))
        c0, corr = _cached(("inverse-edge", K, A, degree, N),
                           lambda: _edge_correction(K, A, degree, N))
        M = np.array(base[:K + 1, :K + 1])
        M[:, c0:] += corr
        return M
    return np.array(_cached((direction, K, A, degree), lambda: _build(direction, K, A, degree)))


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
