"""Numerical MDR, quadrature: g (5.52), its derivative and the (5.57) integral of g from the
spline of f, by Gauss-Legendre.

The spline's pieces far from u = x by Gauss-Legendre in u on fixed nodes (f' and h = (u f')'
evaluated once for every x); the rest with u = x sin(theta), which removes the endpoint
singularity of (5.52), broken at the pieces' ends. No tables: these are what the root finding
of (5.55) and the force (5.57) use, and what the tables are made of.
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric._mdr import kinks
from hertzmdr.numeric._mdr.spline import Rep
from hertzmdr.numeric._quadrature import gauss, panels

#: Rows of the far pieces' kernel matrix computed at once: 16 rows of 6000 Gauss points
#: (0.8 MB) stay in a core's cache through the passes over them (64 rows took 1.4 times as
#: long on the benchmark's N = 1000 profile).
CHUNK = 16


def ugrid(rep: Rep):
    """Gauss nodes in u on every piece of the spline (between consecutive sample radii,
    where f is one polynomial), with f'(u) and h(u) = f' + u f'' there: computed once."""
    if rep.ugrid is None:
        br = np.unique(np.concatenate([rep.knots, rep.edges]))
        t, w = gauss(rep.m_theta - 2)
        half = np.diff(br) / 2
        u = (br[:-1] + half)[:, None] + half[:, None] * t
        f1, f2 = rep.derivs(u.ravel())
        f1, f2 = f1.reshape(u.shape), f2.reshape(u.shape)
        wt = half[:, None] * w
        rep.ugrid = (br, u.ravel(), (wt * f1).ravel(), (wt * (f1 + u * f2)).ravel())
    return rep.ugrid


def direct(rep: Rep, x, with_G: bool = False):
    """g(x) (5.52), the smooth part q(x) of g' and G(x) = integral_0^x g by quadrature
    (G only ``with_G``, else zeros):

        g = x integral_0^x f'(u) du / sqrt(x^2 - u^2),  q = integral_0^x h(u) du /
        sqrt(x^2 - u^2),  G = integral_0^x f'(u) sqrt(x^2 - u^2) du.

    The spline's pieces far from u = x (at least two widths away) by Gauss-Legendre in u
    on fixed nodes (f', h evaluated once for all x); the rest, [u_near, x], with
    u = x sin(theta), which removes the 1/sqrt(x - u), by Gauss-Legendre in theta with
    panels broken at the pieces' ends."""
    x = np.atleast_1d(np.abs(np.asarray(x, float)))
    br, u, wf1, wh = ugrid(rep)
    lo, hi = br[:-1], br[1:]
    width = hi - lo
    # first piece that is not far from x: u_near is its left end
    notfar = (x[:, None] - hi[None, :] < 2 * width[None, :])
    first = np.argmax(notfar, axis=1)
    u_near = lo[first]
    g, q, G = np.zeros(len(x)), np.zeros(len(x)), np.zeros(len(x))
    # far pieces are a prefix: the first nfar nodes in u; rows by increasing nfar, in
    # chunks of CHUNK rows computed up to the chunk's largest nfar
    nfar = first * (len(u) // len(lo))
    order = np.argsort(nfar, kind="stable")
    W = np.column_stack([wf1, wh])
    for c in range(0, len(x), CHUNK):
        rows = order[c:c + CHUNK]
        ncol, nmin = int(nfar[rows[-1]]), int(nfar[rows[0]])
        if ncol == 0:
            continue
        xc, uc = x[rows, None], u[None, :ncol]
        # sqrt(x^2 - u^2) in place; the columns past a row's far pieces (a tail, the rows
        # being sorted by nfar) are zeroed for G and made infinite for the kernel
        root = xc - uc
        root *= xc + uc
        with np.errstate(invalid="ignore"):
            np.sqrt(root, out=root)
        tail = root[:, nmin:]
        past = np.arange(nmin, ncol)[None, :] >= nfar[rows, None]
        tail[past] = 0.0
        if with_G:
            G[rows] = root @ wf1[:ncol]
        tail[past] = np.inf
        np.divide(1.0, root, out=root)
        gq = root @ W[:ncol]
        g[rows] = x[rows] * gq[:, 0]
        q[rows] = gq[:, 1]
    # near part: theta from asin(u_near/x) to pi/2, broken at the pieces' ends
    jx = np.clip(np.searchsorted(br, x, side="right") - 1, 0, len(lo) - 1)
    K = int(np.max(jx - first)) + 1 if len(x) else 1
    kidx = np.minimum(first[:, None] + 1 + np.arange(K)[None, :], len(br) - 1)
    kb = br[kidx]
    with np.errstate(divide="ignore", invalid="ignore"):
        s0 = np.where(x > 0, u_near / x, 0.0)
        sk = np.where(x[:, None] > 0, kb / x[:, None], 1.0)
    th0 = np.arcsin(np.clip(s0, 0, 1))
    thk = np.arcsin(np.clip(sk, 0, 1))
    th, w = panels(th0, np.full(len(x), np.pi / 2), thk, rep.m_theta)
    live = w > 0
    uu = x[:, None] * np.sin(th)
    f1, f2 = np.zeros(th.shape), np.zeros(th.shape)
    f1[live], f2[live] = rep.derivs(uu[live])
    g += x * np.sum(w * f1, axis=1)
    q += np.sum(w * (f1 + uu * f2), axis=1)
    if with_G:
        G += x**2 * np.sum(w * f1 * np.cos(th) ** 2, axis=1)
    return g, q, G


def g(rep: Rep, x) -> np.ndarray:
    """(5.52): g(x) = x * integral_0^(pi/2) f'(x sin theta) dtheta [m]."""
    return direct(rep, x)[0]


def gprime(rep: Rep, x) -> np.ndarray:
    """g'(x) = q(x) + the kink terms sum_j b_j s_j / sqrt(x^2 - b_j^2), x > b_j [1]."""
    x = np.atleast_1d(np.abs(np.asarray(x, float)))
    return direct(rep, x)[1] + kinks.terms(rep, x, 1)


def g_and_gprime(rep: Rep, x) -> tuple[np.ndarray, np.ndarray]:
    """g(x) [m] and g'(x) [1], one quadrature for both."""
    x = np.atleast_1d(np.abs(np.asarray(x, float)))
    gg, q, _ = direct(rep, x)
    return gg, q + kinks.terms(rep, x, 1)


def G(rep: Rep, a) -> np.ndarray:
    """integral_0^a g dx = integral_0^a f'(u) sqrt(a^2 - u^2) du [m^2]."""
    return direct(rep, a, with_G=True)[2]
