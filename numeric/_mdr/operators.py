"""Numerical MDR, operators: the pressure (5.59) and the surface displacement (5.60).

The pressure: the kink terms exactly (``kinks.pressure``), the smooth remainder q from its
tables by Gauss-Legendre per segment, x = r + w^2 on the segment holding r (removes the Abel
kernel's 1/sqrt(x - r)) and x = b_j + t^2 on later ones, graded towards w = 0 (t = 0) down to
the scale of the nearest singularity; its error bound from a coarser representation. The
displacement: (5.60) with x = r sin(theta) on the table of g.

:mod:`hertzmdr.numeric.abel` evaluates (5.59) from samples of the line load by another
engine; why there are two is in its module docstring (and docs/mdr.md).
"""

from __future__ import annotations

import numpy as np

from hertzmdr.numeric._mdr import kinks, tables
from hertzmdr.numeric._mdr.spline import Rep
from hertzmdr.numeric._mdr.tables import GRADE
from hertzmdr.numeric._quadrature import panels

_EPS = np.finfo(float).eps


def graded(lo, hi):
    """Break points grading [lo, hi] geometrically towards lo: shape (M, 30)."""
    lo, hi = np.asarray(lo, float)[:, None], np.asarray(hi, float)[:, None]
    return lo + (hi - lo) * GRADE


def _subsample(v, n):
    """At most about n of the sorted values v (every few), for panel breaks."""
    return v[:: max(1, len(v) // n)] if len(v) else v


def abel(rep: Rep, r, a: float, E_star: float, m: int, other: Rep | None = None):
    """(5.59): p(r) = (E*/pi) integral_r^a g'(x) / sqrt(x^2 - r^2) dx for 0 <= r < a: the
    kink terms exactly (incomplete elliptic integrals), the smooth part q by Gauss-Legendre
    per segment: x = r + w^2 on the segment holding r (removes the Abel kernel's
    1/sqrt(x - r)), x = b_j + t^2 on the later ones (the table's variable).

    With ``other`` (another representation of the same profile) also returns
    (E*/pi) integral_r^a |q - q_other| / sqrt(x^2 - r^2) dx on the same nodes: the
    difference of the two tables without the cancellations of the signed difference."""
    dev = np.zeros(r.shape)
    otabs = tables.tables(other, a) if other is not None else None
    out = kinks.pressure(rep, r, a, E_star)  # (5.59)
    tabs = tables.tables(rep, a)
    idx = rep.seg_index(r)
    smooth = np.zeros(r.shape)
    for i, seg in enumerate(tabs):
        if seg.lo >= a:
            break
        top = min(seg.hi, a)
        # the segment that holds r: x = r + w^2, dx / sqrt(x^2 - r^2) = 2 dw / sqrt(x + r)
        sel_all = np.flatnonzero(idx == i)
        # grade towards w = 0 down to the scale of the nearest singularity: the kernel's at
        # w^2 = -2r, and past a kink q's sqrt(x - lo) at w^2 = lo - r; lev levels a radius
        # (30 at r = 0). The radii at 30 levels apart from the others, each group with only
        # as many grading columns as its deepest radius (the rest would be empty panels)
        rr = r[sel_all]
        sig = np.sqrt(2 * rr)
        if seg.in_t:
            sig = np.minimum(sig, np.sqrt(rr - seg.lo))
        with np.errstate(divide="ignore"):
            lev_all = np.clip(np.ceil(np.log2(np.sqrt(top - rr) / np.maximum(
                sig, 1e-300 * np.sqrt(top - rr)))) + 2, 3, 30)
        for group in (lev_all < 30, lev_all >= 30):
            sel, lev = sel_all[group], lev_all[group]
            if not len(sel):
                continue
            rr = r[sel]
            W = np.sqrt(top - rr)
            xk = _subsample(seg.lo + seg.nodes**2 if seg.in_t else seg.nodes, 16)
            with np.errstate(invalid="ignore"):
                wk = np.sqrt(np.clip(xk[None, :] - rr[:, None], 0, None))
            ncol = int(lev.max())
            grade = graded(np.zeros(len(rr)), W)[:, :ncol]
            grade[np.arange(ncol)[None, :] >= lev[:, None]] = 0.0
            wn, ww = panels(np.zeros(len(rr)), W, np.concatenate([wk, grade], axis=1), m)
            live = ww > 0
            rl = np.broadcast_to(rr[:, None], wn.shape)[live]
            wl = wn[live]
            if seg.in_t:
                qv = seg.q(np.sqrt((rl - seg.lo) + wl * wl))
            else:
                qv = seg.q(rl + wl * wl)
            if i == 0 and (rr == 0).any():
                # p(0) = (E*/pi) integral q(x)/x dx: a smooth tip has f'(0) = 0, so q(0) =
                # pi f'(0)/2 = 0 (the spline's q(0) is its interpolation error, whose log
                # divergence is not the profile's); a conical tip has p(0) = inf (Solution)
                qv = qv - np.where(rl == 0, seg.q(np.zeros(1))[0], 0.0)
            vals = np.zeros(wn.shape)
            vals[live] = 2 * qv / np.sqrt(2 * rl + wl * wl)
            smooth[sel] += np.sum(ww * vals, axis=1)
            if otabs is not None:
                o = otabs[i]
                qo = o.q(np.sqrt((rl - seg.lo) + wl * wl) if seg.in_t else rl + wl * wl)
                if i == 0 and (rr == 0).any():
                    qo = qo - np.where(rl == 0, o.q(np.zeros(1))[0], 0.0)
                vals[live] = 2 * np.abs(qv - qo) / np.sqrt(2 * rl + wl * wl)
                dev[sel] += np.sum(ww * vals, axis=1)
        # the later segments [lo, top] with r < lo: x = lo + t^2, dx = 2 t dt; the nodes
        # in t are the same for every r (graded towards t = 0 for r -> lo), q once
        sel = np.flatnonzero(idx < i)
        if len(sel) and seg.in_t:
            rr = r[sel]
            T = np.array([np.sqrt(top - seg.lo)])
            br = np.concatenate([_subsample(seg.nodes, 64)[None, :], graded(np.zeros(1), T)],
                                axis=1)
            tn, tw = panels(np.zeros(1), T, br, m)
            tn, tw = tn[:, tw[0] > 0], tw[:, tw[0] > 0]
            qv = seg.q(tn[0])[None, :]
            xmr = (seg.lo - rr[:, None]) + tn * tn
            xx = seg.lo + tn * tn
            kern = tw * 2 * tn / np.sqrt(xmr * (xx + rr[:, None]))
            smooth[sel] += np.sum(kern * qv, axis=1)
            if otabs is not None:
                dev[sel] += np.sum(kern * np.abs(qv - otabs[i].q(tn[0])[None, :]), axis=1)
    if other is not None:
        return out + E_star / np.pi * smooth, E_star / np.pi * dev
    return out + E_star / np.pi * smooth


def conical_tip(fine: Rep, coarse: Rep, a: float) -> bool:
    """Whether f'(0) > 0 (then p is log-infinite at r = 0): the fine spline's slope at 0 is
    above rounding and the coarse one agrees with it to 10 % (a smooth tip's splines have
    f'(0) of the order of their interpolation error, which changes with the resolution)."""
    f0, fa = fine.fprime(np.array([0.0, a]))
    f0c = coarse.fprime(np.array([0.0]))[0]
    return bool(f0 > 1e3 * _EPS * abs(fa) and abs(f0 - f0c) <= 0.1 * f0)


def pressure(rep: Rep, r, a: float, E_star: float, m: int, conical: bool,
             other: Rep | None = None):
    """p(r) [Pa] at every r >= 0 [m] (0 outside the contact, +inf at r = 0 under a conical
    tip); with ``other`` also the Abel integral of |q - q_other| (``abel``)."""
    out, dev = np.zeros(r.shape), np.zeros(r.shape)
    ins = r < a
    if ins.any():
        if other is None:
            out[ins] = abel(rep, r[ins], a, E_star, m)
        else:
            out[ins], dev[ins] = abel(rep, r[ins], a, E_star, m, other)
    if conical:
        out[r == 0] = np.inf  # p(0) = (E*/pi) integral_0^a g'(x)/x dx, g'(0) = pi f'(0)/2
    return out if other is None else (out, dev)


def rounding(rep: Rep, r, p, a: float, E_star: float):
    """A bound of the rounding errors of p [Pa] that the coarse-vs-fine difference cannot
    see: (64 + 4 N) eps |p| (N samples: differentiating the spline loses about log10(N)
    digits), amplified by a/(a - r) near the edge (the rounding of a enters p ~
    sqrt(a - r) there), and the kink terms' (``kinks.rounding``)."""
    out = np.zeros(r.shape)
    ins = r < a
    out[ins] = (64 + 4 * len(rep.knots)) * _EPS * np.abs(p[ins]) * (1 + a / (a - r[ins]))
    return out + kinks.rounding(rep, r, a, E_star)


def displacement(rep: Rep, r, a: float, d: float, m: int = 6):
    """u_z(r) [m] at r >= 0 [m], inside and outside the contact: (5.60) with x = r sin(theta),
    u = (2/pi) integral_0^asin(min(1, a/r)) (d - g(r sin theta)) dtheta, on the table of g;
    m Gauss points a panel, panels broken at the knots' images and graded towards theta = 0
    and, from above, towards each breakpoint's asin(b/r) (g ~ sqrt(x - b) past a kink; the
    knots of a linear spline, where f' jumps too, are not graded: their jumps are of the order
    of its interpolation error)."""
    th_max = np.arcsin(np.clip(np.divide(a, r, out=np.full(r.shape, 2.0), where=r > 0), 0, 1))
    with np.errstate(divide="ignore", invalid="ignore"):
        kt = np.arcsin(np.clip(np.where(r[:, None] > 0, rep.panel_knots()[None, :]
                                        / r[:, None], 2.0), 0, 1))
        kb = [np.arcsin(np.clip(np.where(r > 0, b / r, 2.0), 0, 1)) for b in rep.edges[1:-1]]
    br = [kt, graded(np.zeros(len(r)), th_max)]
    br += [graded(np.minimum(t, th_max), th_max) for t in kb]
    th, w = panels(np.zeros(len(r)), th_max, np.concatenate(br, axis=1), m)
    gx = tables.g(rep, (r[:, None] * np.sin(th)).ravel()).reshape(th.shape)
    u = 2 / np.pi * np.sum(w * (d - gx), axis=1)  # (5.60)
    u[r == 0] = d
    return u


def envelope(values, x, knots):
    """The largest |values(y)| for y in {x - h/2, x, x + h/2} (h: the local spacing of the
    sorted ``knots``, clipped to [0, knots[-1]]): a difference of two representations that
    passes through 0 at x by accident keeps its size nearby."""
    i = np.clip(np.searchsorted(knots, x), 1, len(knots) - 1)
    h = knots[i] - knots[i - 1]
    return np.max([np.abs(values(np.clip(x + c * h, 0, knots[-1]))) for c in (-0.5, 0, 0.5)],
                  axis=0)
