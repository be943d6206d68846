"""Non-periodic boundary-element solver for a rigid indenter of any shape on a half-space.

The surface is a regular grid of rectangular pixels of size dx x dy carrying uniform pressures.
The displacement at a pixel centre is the Boussinesq integral (5.7) over every pixel, taken
exactly: for a uniformly loaded rectangle the integral of 1/s has the closed form of Love
(1929, Phil. Trans. R. Soc. A 228, 377), see :func:`influence_kernel`. The influence matrix is
Toeplitz-block-Toeplitz, so the displacement of the whole grid is a linear convolution, done by
zero-padding to twice the grid and FFT (:class:`HalfSpace`, O(N log N), no periodic images; the
kernel is even, so its transform is real; the padding is skipped where it is known to be zero),
and for a pressure confined to a box (the conjugate direction, which lives on the contact) by
padding that box alone (:meth:`HalfSpace.on_support`).

The contact problem -- find p >= 0 with gap g = h - d + u >= 0 and p g = 0 -- is solved by the
constrained conjugate-gradient iteration of Polonsky & Keer (1999, Wear 231, 206), depth- or
force-controlled (:func:`solve`). Punches (flat-ended, any footprint) are height maps that are
0 on the footprint and +inf elsewhere (:func:`polygon_punch`).

Units: SI throughout (m, Pa, N, N/m).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric._validate import as_float, nonnegative, positive

__all__ = ["influence_kernel", "HalfSpace", "BEMResult", "solve", "punch_stiffness",
           "polygon_punch", "grid", "polygon_area", "read_height_map", "boundary_area"]


def _love_primitive(X, Y):
    """F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|) = X ln(Y + s) + Y ln(X + s) - X ln|X| - Y ln|Y|
    (s = sqrt(X^2 + Y^2)), whose mixed derivative is 1/s; F(0, Y) = Y asinh(0) = 0 by
    continuity (X asinh(Y/|X|) -> 0)."""
    ax, ay = np.abs(X), np.abs(Y)
    fx = np.where(ax > 0, X * np.arcsinh(Y / np.where(ax > 0, ax, 1.0)), 0.0)
    fy = np.where(ay > 0, Y * np.arcsinh(X / np.where(ay > 0, ay, 1.0)), 0.0)
    return fx + fy


def influence_kernel(x, y, dx, dy, E_star):
    """Displacement u_z [m] at (x, y) under the unit pressure (1 Pa) on the pixel
    [-dx/2, dx/2] x [-dy/2, dy/2], by (5.7) integrated exactly (Love 1929).

    .. math::
        u_z = \\frac{1}{\\pi E^*} \\sum_{\\pm\\pm} \\pm F(x \\pm dx/2, y \\pm dy/2),
        \\quad F(X, Y) = X \\operatorname{asinh}(Y/|X|) + Y \\operatorname{asinh}(X/|Y|)

    Parameters
    ----------
    x, y : float or array_like
        Field point relative to the pixel centre [m].
    dx, dy : float
        Pixel size [m], > 0.
    E_star : float
        Effective modulus [Pa], > 0.
    """
    x, y = as_float("x", x), as_float("y", y)
    dx, dy, E_star = positive("dx", dx), positive("dy", dy), positive("E_star", E_star)
    hx, hy = dx / 2, dy / 2
    total = (_love_primitive(x + hx, y + hy) - _love_primitive(x + hx, y - hy)
             - _love_primitive(x - hx, y + hy) + _love_primitive(x - hx, y - hy))
    return total * gen.boussinesq_surface_prefactor(E_star)  # (5.7)


class HalfSpace:
    """The influence operator of an (nx, ny) grid of pixels dx x dy: pressure -> u_z.

    Parameters
    ----------
    shape : (int, int)
        Grid size (nx, ny); axis 0 is x.
    dx, dy : float
        Pixel size [m].
    E_star : float
        Effective modulus [Pa].
    workers : int
        Threads of scipy.fft.
    """

    def __init__(self, shape, dx, dy, E_star, workers: int = 1):
        from scipy import fft

        self.shape = nx, ny = tuple(int(n) for n in shape)
        self.dx, self.dy, self.E_star = float(dx), float(dy), float(E_star)
        self.workers = workers
        self._fft = fft
        # the kernel at the offsets (i dx, j dy), i = 0..nx, j = 0..ny (it is even in both):
        # (5.7) over the pixel is the mixed difference of Love's primitive F at the pixel's
        # corners, which lie on the lattice ((m - 1/2) dx, (l - 1/2) dy): F once per lattice
        # point, (nx + 2)(ny + 2) of them
        X = (np.arange(nx + 2) - 0.5) * self.dx
        Y = (np.arange(ny + 2) - 0.5) * self.dy
        F = _love_primitive(X[:, None], Y[None, :])
        Kq = ((F[1:, 1:] - F[1:, :-1] - F[:-1, 1:] + F[:-1, :-1])
              * gen.boussinesq_surface_prefactor(self.E_star))  # (5.7)
        # circulant embedding of the Toeplitz kernel on a (2nx, 2ny) grid: offsets 0..nx-1,
        # then -nx..-1 (the offset nx is never used by the linear convolution); the kernel is
        # even, so the embedding is too and its transform is real
        self._Kq = Kq
        self._box_hats: dict = {}  # (mx, my) -> (Lx, Ly, transform): see ``on_support``
        self.kernel_hat = self._embedded_hat(nx, ny, 2 * nx, 2 * ny)
        self.self_influence = float(Kq[0, 0])

    def _embedded_hat(self, mx, my, Lx, Ly):
        """The real transform of the kernel's offsets |i| < mx, |j| < my embedded in an
        (Lx, Ly) circulant (Lx >= 2 mx - 1; the offset -mx at index mx when Lx = 2 mx):
        even, so its transform is real."""
        Kq = self._Kq
        K = np.zeros((Lx, Ly))
        hx, hy = mx + (Lx == 2 * mx), my + (Ly == 2 * my)
        K[:hx, :hy] = Kq[:hx, :hy]
        K[Lx - mx + 1:, :hy] = Kq[mx - 1:0:-1, :hy]
        K[:, Ly - my + 1:] = K[:, my - 1:0:-1]
        return self._fft.rfft2(K, workers=self.workers).real

    def on_support(self, p: np.ndarray, support: np.ndarray) -> np.ndarray:
        """u_z [m] under pressures p [Pa] that vanish outside ``support`` (bool, the grid's
        shape), exact on the bounding box of the support and 0 outside it.

        When the box is small (a contact away from the grid's border), the convolution of the
        box alone is zero-padded to about twice the box instead of twice the grid; its
        kernel transform is kept per box size, rounded up to a sixteenth of the grid."""
        nx, ny = self.shape
        rows, cols = np.flatnonzero(support.any(axis=1)), np.flatnonzero(support.any(axis=0))
        if not len(rows):
            return np.zeros(self.shape)
        fft, w = self._fft, self.workers
        step_x, step_y = max(nx // 16, 1), max(ny // 16, 1)
        mx = min(-(-(rows[-1] + 1 - rows[0]) // step_x) * step_x, nx)
        my = min(-(-(cols[-1] + 1 - cols[0]) // step_y) * step_y, ny)
        if mx * my > nx * ny // 2:
            return self(p)
        if (mx, my) not in self._box_hats:
            if len(self._box_hats) >= 8:  # the contact's box settles: keep the recent sizes
                self._box_hats.pop(next(iter(self._box_hats)))
            Lx, Ly = fft.next_fast_len(2 * mx - 1, real=True), fft.next_fast_len(2 * my - 1,
                                                                                 real=True)
            self._box_hats[(mx, my)] = (Lx, Ly, self._embedded_hat(mx, my, Lx, Ly))
        Lx, Ly, hat = self._box_hats[(mx, my)]
        i0, j0 = min(rows[0], nx - mx), min(cols[0], ny - my)
        box = p[i0:i0 + mx, j0:j0 + my]
        ph = fft.fft(fft.rfft(box, n=Ly, axis=1, workers=w), n=Lx, axis=0, overwrite_x=True,
                     workers=w)
        ph *= hat
        back = fft.ifft(ph, axis=0, overwrite_x=True, workers=w)[:mx]
        u = np.zeros(self.shape)
        u[i0:i0 + mx, j0:j0 + my] = fft.irfft(back, n=Ly, axis=1, workers=w)[:, :my]
        return u

    def __call__(self, p: np.ndarray) -> np.ndarray:
        """u_z [m] at the pixel centres under the pixel pressures p [Pa] (linear convolution).

        The zero-padded 2-D transform, pruned: the rows of p are transformed alone (the
        padding rows are zero) and only the first nx rows of the product are transformed
        back, so the padded rows cost one column transform each way."""
        nx, ny = self.shape
        fft, w = self._fft, self.workers
        ph = fft.fft(fft.rfft(p, n=2 * ny, axis=1, workers=w), n=2 * nx, axis=0,
                     overwrite_x=True, workers=w)
        ph *= self.kernel_hat
        back = fft.ifft(ph, axis=0, overwrite_x=True, workers=w)[:nx]
        return fft.irfft(back, n=2 * ny, axis=1, workers=w)[:, :ny]


@dataclass(frozen=True)
class BEMResult:
    """Solution of a contact problem on a grid.

    Attributes
    ----------
    pressure : ndarray, Pa
        Pixel pressures.
    displacement : ndarray, m
        Surface displacement u_z at the pixel centres.
    gap : ndarray, m
        h - d + u_z (0 in contact, >= 0 outside; +inf outside a punch's footprint).
    contact : ndarray of bool
        Pixels in contact (p > 0; under no load the pixels the indenter touches, :func:`solve`).
    area : float, m^2
        Contact area (pixel count times dx dy).
    force : float, N
    depth : float, m
    stiffness : float or None, N/m
        Differential stiffness dF/dd: the stiffness of the flat punch with the footprint of the
        contact area (Problem 5, (5.13)); None when not requested.
    iterations : int
    residual : float
        Relative residual (see :func:`solve`).
    dx, dy : float, m
    """

    pressure: np.ndarray
    displacement: np.ndarray
    gap: np.ndarray
    contact: np.ndarray
    area: float
    force: float
    depth: float
    stiffness: float | None
    iterations: int
    residual: float
    dx: float
    dy: float
    info: dict = field(default_factory=dict)


def boundary_area(contact: np.ndarray, dx: float, dy: float) -> float:
    """Area [m^2] of the pixels on either side of the edge of a pixel contact set: those in
    contact with a neighbour out of contact, and those out of contact with a neighbour in it
    (4-neighbours; the grid's border counts as out of contact).

    A contact area counted in pixels can be wrong by whatever part of this band the true edge
    cuts: the true edge runs between the centre of a pixel in contact and the centre of its
    neighbour out of contact, so ``boundary_area / area`` bounds the area's relative error from
    the pixelation of the edge (a punch's footprint: pixel centres inside the polygon).

    Parameters
    ----------
    contact : ndarray of bool, shape (nx, ny)
        Pixels in contact (``BEMResult.contact``).
    dx, dy : float
        Pixel size [m].
    """
    c = np.pad(np.asarray(contact, dtype=bool), 1)
    inner = c[1:-1, 1:-1]
    nbrs = (c[:-2, 1:-1], c[2:, 1:-1], c[1:-1, :-2], c[1:-1, 2:])
    edge_in = inner & ~np.logical_and.reduce(nbrs)
    edge_out = ~inner & np.logical_or.reduce(nbrs)
    return float(np.count_nonzero(edge_in | edge_out)) * dx * dy


def _residual(g, G, S, allowed, scale):
    """The relative residual of :func:`solve`: the gap on the contact (G = its sum of
    squares) and the overlap outside it, over ``scale``."""
    viol = np.where(allowed & ~S & (g < 0), g, 0.0)
    return float(np.sqrt(G + np.sum(viol**2)) / scale)


def solve(height, dx, E_star, *, depth=None, force=None, dy=None, tol: float = 1e-8,
          max_iter: int = 5000, stiffness: bool = True, operator: HalfSpace | None = None,
          workers: int = 1) -> BEMResult:
    """Rigid indenter of height map ``height`` pressed into an elastic half-space.

    Polonsky & Keer (1999): conjugate gradients on the set of pixels in contact, projected on
    p >= 0, with pixels re-entering where the surfaces overlap. Force control adds the rigid
    shift (the mean gap over the contact) and the load constraint sum(p) dx dy = F.

    Parameters
    ----------
    height : array_like, shape (nx, ny)
        Height h [m] of the indenter's surface at the pixel centres (axis 0 is x), measured
        from the level h = 0 from which the depth counts (the tip of a sphere or cone, the face
        of a punch); +inf marks pixels that can never touch (outside a punch's footprint).
    dx : float
        Pixel size along x [m], > 0.
    E_star : float
        Effective modulus [Pa], > 0 (5.8), (5.26).
    depth, force : float
        Give exactly one: the indentation depth d [m] (>= 0) of the level h = 0 below the
        undeformed surface, or the normal force F [N] (>= 0). No load -- F = 0, or a depth that
        does not reach below the lowest height -- gives p = 0, u_z = 0, F = 0 exactly, with
        the pixels the indenter touches (h = d; under F = 0, d = min(height)) as the contact:
        the limit of a vanishing load (a punch's footprint, a tip's lowest pixels; none when
        the depth stops short of the indenter).
    dy : float, optional
        Pixel size along y [m]; default dx.
    tol : float
        Relative residual: the 2-norm of the gap on the contact and of the overlap outside it,
        over the 2-norm of the displacement on the contact.
    max_iter : int
        Raise RuntimeError when not converged after this many iterations.
    stiffness : bool
        Also compute dF/dd as the flat-punch stiffness of the contact area (one linear solve).
    operator : HalfSpace, optional
        A prebuilt operator for this grid (saves the kernel's FFT when solving repeatedly).

    Returns
    -------
    BEMResult
    """
    h = as_float("height", height)
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValueError(f"height has shape {h.shape}; valid: a 2-D grid, at least 2 x 2")
    if np.any(h == -np.inf):
        raise ValueError("height contains -inf; valid: finite values, or +inf off a footprint")
    dx = float(positive("dx", dx))
    dy = dx if dy is None else float(positive("dy", dy))
    E_star = float(positive("E_star", E_star))
    if (depth is None) == (force is None):
        raise ValueError("give exactly one of depth= and force=")
    allowed = np.isfinite(h)
    if not allowed.any():
        raise ValueError("height is +inf everywhere: no pixel can touch")
    op = operator or HalfSpace(h.shape, dx, dy, E_star, workers=workers)
    dA = dx * dy
    hh = np.where(allowed, h, 0.0)

    if force is not None:
        W = float(nonnegative("force", force))
        if W == 0.0:
            return _unloaded(h, allowed, float(h[allowed].min()), dx, dy, E_star, tol, op,
                             stiffness)
        p = np.where(allowed, W / (dA * allowed.sum()), 0.0)
    else:
        d = float(nonnegative("depth", depth))
        # start: the pressure of a flat punch of the overlap region, scaled by the overlap
        over = allowed & (h < d)
        if not over.any():  # the indenter does not press: no load
            return _unloaded(h, allowed, d, dx, dy, E_star, tol, op, stiffness)
        p = np.where(over, (d - hh) / op.self_influence, 0.0)
    t = np.zeros_like(p)
    G_old, delta = 1.0, 0.0
    res = np.inf
    iterations = 0
    for _ in range(max_iter):
        iterations += 1
        u = op(p)
        S = p > 0
        if force is not None:
            g = u + hh
            shift = g[S].mean()  # the rigid-body approach d on the contact
            g = g - shift
        else:
            g = u + hh - d
        g = np.where(allowed, g, 0.0)
        scale = np.sqrt(np.sum(u[S] ** 2)) or 1.0
        gS = g[S]
        G = np.sum(gS**2)
        res = _residual(g, G, S, allowed, scale)
        if res < tol:
            break
        t = np.where(S, g + delta * (G / G_old) * t, 0.0)
        G_old = G
        tS = t[S]
        rS = op.on_support(t, S)[S]  # t and what is used of its image live on S
        if force is not None:
            rS = rS - rS.mean()
        tau = np.sum(gS * tS) / np.sum(rS * tS)
        p = np.where(S, p - tau * t, 0.0)
        p = np.maximum(p, 0.0)
        overlap = allowed & (p == 0) & (g < 0)
        delta = 0.0 if overlap.any() else 1.0
        p = np.where(overlap, p - tau * g, p)
        if force is not None:
            p *= W / (p.sum() * dA)
    else:
        raise RuntimeError(f"bem.solve: residual {res:.3g} > tol = {tol:g} "
                           f"after max_iter = {max_iter} iterations")
    S = p > 0
    depth_out = float(shift) if force is not None else d
    gap = np.where(allowed, hh - depth_out + u, np.inf)
    k = punch_stiffness(S, dx, E_star, dy=dy, tol=tol, operator=op) if stiffness else None
    return BEMResult(pressure=p, displacement=u, gap=gap, contact=S, area=float(S.sum() * dA),
                     force=float(p.sum() * dA), depth=depth_out, stiffness=k, iterations=iterations,
                     residual=res, dx=dx, dy=dy)


def _unloaded(h, allowed, d, dx, dy, E_star, tol, op, stiffness) -> BEMResult:
    """The exact solution under no load at depth d [m] (see :func:`solve`): no pressure, no
    displacement; the contact is the pixels at h = d, its stiffness theirs as a flat punch
    (0 with none)."""
    touch = allowed & (h == d)
    zero = np.zeros(h.shape)
    k = None
    if stiffness:
        k = punch_stiffness(touch, dx, E_star, dy=dy, tol=tol, operator=op) if touch.any() \
            else 0.0
    return BEMResult(pressure=zero, displacement=zero.copy(),
                     gap=np.where(allowed, h - d, np.inf), contact=touch,
                     area=float(touch.sum() * dx * dy), force=0.0, depth=d, stiffness=k,
                     iterations=0, residual=0.0, dx=dx, dy=dy)


def punch_stiffness(mask, dx, E_star, *, dy=None, tol: float = 1e-10, max_iter: int = 5000,
                    operator: HalfSpace | None = None) -> float:
    """Stiffness k = F/d [N/m] of a rigid flat punch with the footprint ``mask``, (5.12)-(5.13).

    Solves A p = 1 on the footprint by conjugate gradients (the pressure under a flat punch is
    positive everywhere, so no constraint is active) and returns sum(p) dx dy per unit depth.

    Parameters
    ----------
    mask : array_like of bool, shape (nx, ny)
        Pixels of the footprint.
    dx : float
        Pixel size [m].
    E_star : float
        Effective modulus [Pa].
    dy : float, optional
        Pixel size along y [m]; default dx.
    tol : float
        Relative residual ||A p - 1|| / ||1|| on the footprint.
    """
    S = np.asarray(mask, dtype=bool)
    if not S.any():
        raise ValueError("mask has no pixel; valid: at least one True pixel")
    dx = float(positive("dx", dx))
    dy = dx if dy is None else float(positive("dy", dy))
    op = operator or HalfSpace(S.shape, dx, dy, float(positive("E_star", E_star)))
    b = S.astype(float)
    p = b / op.self_influence  # Jacobi start
    r = np.where(S, b - op.on_support(p, S), 0.0)
    z = r.copy()
    rr = np.sum(r * r)
    nb = np.sqrt(S.sum())
    for _ in range(max_iter):
        if np.sqrt(rr) / nb < tol:
            break
        Az = np.where(S, op.on_support(z, S), 0.0)
        alpha = rr / np.sum(z * Az)
        p += alpha * z
        r -= alpha * Az
        rr_new = np.sum(r * r)
        z = r + (rr_new / rr) * z
        rr = rr_new
    else:
        raise RuntimeError(f"punch_stiffness: residual {np.sqrt(rr) / nb:.3g} > tol = {tol:g}")
    return float(p.sum() * dx * dy)


def grid(n, length, ny=None, width=None):
    """Pixel-centre coordinates of an (n, ny) grid covering [-length/2, length/2] x
    [-width/2, width/2] [m]; returns (x, y, dx, dy) with x, y of shape (n, 1), (1, ny)."""
    ny = n if ny is None else ny
    width = length if width is None else width
    dx, dy = length / n, width / ny
    x = (np.arange(n) - (n - 1) / 2) * dx
    y = (np.arange(ny) - (ny - 1) / 2) * dy
    return x[:, None], y[None, :], dx, dy


def _inside_polygon(x, y, vertices):
    """Even-odd rule for the points (x, y) (broadcast) and a simple polygon."""
    inside = np.zeros(np.broadcast(x, y).shape, dtype=bool)
    v = np.asarray(vertices, dtype=float)
    for (x1, y1), (x2, y2) in zip(v, np.roll(v, -1, axis=0), strict=True):
        if y1 == y2:
            continue
        crosses = (y1 > y) != (y2 > y)
        xc = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
        inside ^= crosses & (x < xc)
    return inside


def polygon_area(vertices) -> float:
    """Area [m^2] of a simple polygon (shoelace formula)."""
    v = np.asarray(vertices, dtype=float)
    x, y = v[:, 0], v[:, 1]
    return float(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def polygon_punch(vertices, n: int, *, margin: float = 0.0):
    """Height map of a flat-ended rigid punch with a polygonal footprint, on a square grid.

    Parameters
    ----------
    vertices : array_like, shape (k, 2)
        Corners of a simple polygon [m], in order.
    n : int
        Pixels along the longer side of the bounding box (plus margin).
    margin : float
        Extra border around the bounding box, as a fraction of its longer side.

    Returns
    -------
    height : ndarray
        0 on the footprint (pixel centres inside the polygon), +inf elsewhere.
    dx : float
        Pixel size [m] (square pixels).
    """
    v = as_float("vertices", vertices)
    if v.ndim != 2 or v.shape[1] != 2 or v.shape[0] < 3:
        raise ValueError(f"vertices has shape {v.shape}; valid: (k, 2) with k >= 3")
    n = int(n)
    if n < 2:
        raise ValueError(f"n = {n} is out of range; valid: n >= 2")
    margin = float(nonnegative("margin", margin))
    lo, hi = v.min(axis=0), v.max(axis=0)
    side = (hi - lo).max() * (1 + 2 * margin)
    dx = side / n
    centre = (lo + hi) / 2
    nx = max(2, int(np.ceil((hi - lo)[0] * (1 + 2 * margin) / dx)))
    ny = max(2, int(np.ceil((hi - lo)[1] * (1 + 2 * margin) / dx)))
    x = centre[0] + (np.arange(nx) - (nx - 1) / 2) * dx
    y = centre[1] + (np.arange(ny) - (ny - 1) / 2) * dx
    inside = _inside_polygon(x[:, None], y[None, :], v)
    return np.where(inside, 0.0, np.inf), dx


def _one_line(exc: Exception) -> str:
    return " ".join(str(exc).split()).rstrip(".")


def read_height_map(path):
    """Heights [m] on a regular grid from a file: ``.npy`` (a 2-D array), or text (``.csv``
    comma-separated, anything else whitespace-separated; one row of the grid per line, axis 0
    is x). ``inf`` (or ``nan``, read as +inf) marks pixels that never touch. Pass the result
    to :func:`solve` with the grid's pixel size.

    Parameters
    ----------
    path : str or pathlib.Path
        The file.

    Returns
    -------
    ndarray, shape (nx, ny)
    """
    import warnings
    from pathlib import Path

    path = Path(path)
    try:
        if path.suffix == ".npy":
            h = np.load(path, allow_pickle=False)
        else:
            with warnings.catch_warnings():  # an empty file: the shape check below says so
                warnings.filterwarnings("ignore", message="loadtxt: input contained no data")
                h = np.loadtxt(path, delimiter="," if path.suffix == ".csv" else None, ndmin=2)
        h = np.asarray(h, dtype=float)
    except (ValueError, UnicodeDecodeError, OSError) as exc:
        # NumPy's words ("could not convert string 'x' to float64 at row 1, column 2") with
        # the file they are about
        raise ValueError(f"{path}: cannot read the heights: {_one_line(exc)}") from None
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValueError(f"{path}: heights of shape {h.shape}; valid: a 2-D grid, at least 2 x 2")
    return np.where(np.isnan(h), np.inf, h)
