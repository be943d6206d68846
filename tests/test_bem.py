"""The boundary-element solver of numeric/bem.py against exact solutions.

Routes: the pixel kernel against 2-D mpmath quadrature of the Boussinesq kernel (5.7); the FFT
convolution against the dense sum; the contact solver against Hertz (sphere), the flat circular
punch (5.12) and the cone (Sneddon 1965: a = 2 d/(pi tan theta), F = (pi/2) a^2 E* tan theta).
Grids are small here (<= 64 x 64, under a second each); the convergence study with larger
grids is benchmarks/bench_bem.py, its results docs/non_axisymmetric.md.
"""

import re

import mpmath as mp
import numpy as np
import pytest

from hertzmdr.numeric import _generated as gen
from hertzmdr.numeric import bem, ellipse, hertz

from named import assert_inputs_named
from oracle import assert_close


@pytest.mark.parametrize("x, y", [(0.0, 0.0), (0.3, 0.1), (0.5, 0.25), (2.0, -1.5),
                                  (-7.0, 3.0)])
def test_kernel_by_quadrature(x, y):
    """Love's closed form against the Boussinesq integral over the pixel at 30 digits.

    The four-corner sum cancels terms of size |X| log|X| down to a result of size
    dx dy/|X|: relative rounding eps (r/dx)^2, 5e-14 at r = 7.6 dx; tolerance 1e-13.
    """
    dx, dy, E = 1.0, 0.5, 3.0
    got = bem.influence_kernel(x, y, dx, dy, E)

    def corner(A, B):
        """Integral of 1/r over the rectangle [0, A] x [0, B], in polar coordinates about its
        corner (r from 0 to the far side): a 1-D quadrature in the angle."""
        if A == 0 or B == 0:
            return mp.mpf(0)
        A, B = abs(A), abs(B)
        c = mp.atan2(B, A)
        return (mp.quad(lambda f: A / mp.cos(f), [0, c])
                + mp.quad(lambda f: B / mp.sin(f), [c, mp.pi / 2]))

    def signed(X, Y):
        return mp.sign(X) * mp.sign(Y) * corner(X, Y)

    with mp.workdps(30):
        X0, X1 = -0.5 - mp.mpf(x), 0.5 - mp.mpf(x)  # the pixel relative to the field point
        Y0, Y1 = -0.25 - mp.mpf(y), 0.25 - mp.mpf(y)
        total = signed(X1, Y1) - signed(X0, Y1) - signed(X1, Y0) + signed(X0, Y0)
        ref = total / (mp.pi * E)  # (5.7) with p = 1
    assert_close(float(got), ref, 1e-13, f"kernel at ({x}, {y})")


def test_convolution_is_the_dense_sum():
    """The zero-padded FFT product equals sum_j K(x_i - x_j) p_j: no periodic images."""
    rng = np.random.default_rng(1)
    nx, ny, dx, dy, E = 7, 5, 0.3, 0.2, 2.0
    p = rng.random((nx, ny))
    op = bem.HalfSpace((nx, ny), dx, dy, E)
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    dense = np.zeros((nx, ny))
    for a in range(nx):
        for b in range(ny):
            dense[a, b] = np.sum(p * bem.influence_kernel((a - i) * dx, (b - j) * dy, dx, dy, E))
    # float64 FFT round trip of a 14 x 10 array: a few ulps times log2(140)
    assert np.max(np.abs(op(p) - dense)) <= 1e-14 * np.max(np.abs(dense))


@pytest.mark.parametrize("box", [(5, 17, 3, 12), (0, 6, 20, 30), (30, 40, 0, 4), (2, 38, 1, 29)])
def test_convolution_on_a_support_is_the_dense_sum(box):
    """HalfSpace.on_support (the convolution of the support's bounding box alone, padded to
    about twice the box) equals sum_j K(x_i - x_j) p_j on the support: boxes inside the grid,
    at its borders, and one too large for the box route (the whole-grid product)."""
    rng = np.random.default_rng(2)
    nx, ny, dx, dy, E = 40, 30, 0.3, 0.2, 2.0
    a, b, c, d = box
    S = np.zeros((nx, ny), bool)
    S[a:b, c:d] = rng.random((b - a, d - c)) > 0.3
    p = np.where(S, rng.random((nx, ny)), 0.0)
    op = bem.HalfSpace((nx, ny), dx, dy, E)
    got = op.on_support(p, S)
    i, j = np.nonzero(S)
    dense = np.array([np.sum(p[i, j] * bem.influence_kernel((a_ - i) * dx, (b_ - j) * dy,
                                                            dx, dy, E))
                      for a_, b_ in zip(i, j, strict=True)])
    # float64 FFT round trips of at most 80 x 60: a few ulps times log2(4800)
    assert np.max(np.abs(got[S] - dense)) <= 1e-14 * np.max(np.abs(dense))


def _sphere(n, R=1.0, L=2.0):
    x, y, dx, _ = bem.grid(n, L)
    return (x**2 + y**2) / (2 * R), dx


def test_hertz_sphere_depth_and_force_control():
    """Against (5.21)-(5.23): the force converges like dx^2 (pixel collocation of a smooth
    pressure; the contact rim costs O(dx^2) in force), the area like dx (the staircase)."""
    E, R, d = 2.0, 1.0, 0.25
    errs = []
    for n in (32, 64):
        h, dx = _sphere(n)
        res = bem.solve(h, dx, E, depth=d)
        errs.append(abs(res.force / hertz.force(d, R, E) - 1))
        a = hertz.contact_radius(d, R)
        # area: the rim pixels, +-pi 2 a dx / 2 over pi a^2 -> 1.5 dx/a at most
        assert abs(res.area / (np.pi * a * a) - 1) < 1.5 * dx / a
        # dF/dd = 2 a E* (Problem 5): the punch of the contact area, O(dx) as the area
        assert abs(res.stiffness / hertz.stiffness(d, R, E) - 1) < 1.5 * dx / a
        assert res.residual < 1e-8 and np.all(res.pressure >= 0)
        assert np.all(res.gap[~res.contact] >= -1e-8 * d)  # no overlap, to the residual
        by_F = bem.solve(h, dx, E, force=res.force, stiffness=False)
        # the same discrete problem: depth back to the tolerance (1e-8 residual, x cond ~ 1e2)
        assert abs(by_F.depth / d - 1) < 1e-6
    assert errs[0] < 2e-3 and errs[1] < errs[0] / 3  # second order: ratio ~4


def test_flat_circular_punch():
    """k = 2 a E* (5.12), with a = sqrt(A/pi) of the pixelated footprint: first order in dx
    (the edge singularity of (5.9) on pixels), -0.0036 at 64 pixels per diameter."""
    E = 5.0
    for n in (32, 64):
        x, y, dx, _ = bem.grid(n, 2.0)
        mask = x**2 + y**2 < 1.0
        k = bem.punch_stiffness(mask, dx, E)
        a = np.sqrt(mask.sum() * dx * dx / np.pi)
        err = k / gen.punch_stiffness(E, a) - 1
        assert -0.5 * dx < err < 0, f"n = {n}: {err}"
        # the same through the contact solver, depth-controlled (h = 0 on, +inf off the face)
        res = bem.solve(np.where(mask, 0.0, np.inf), dx, E, depth=1e-3)
        assert abs(res.force / 1e-3 / k - 1) < 1e-7
        assert res.contact.sum() == mask.sum()


def test_cone():
    """Sneddon's cone: F = (pi/2) a^2 E* tan(theta), a = 2 d/(pi tan(theta)); the log
    singularity of the pressure at the tip is integrable: force error 5e-5 at n = 64."""
    E, theta = 1.0, 0.2
    x, y, dx, _ = bem.grid(64, 2.0)
    h = np.hypot(x, y) * np.tan(theta)
    a = 0.7
    d = np.pi * a * np.tan(theta) / 2
    res = bem.solve(h, dx, E, depth=d)
    assert abs(res.force / (np.pi / 2 * a**2 * E * np.tan(theta)) - 1) < 1e-3
    assert abs(res.stiffness / (2 * a * E) - 1) < 1.5 * dx / a


def test_polygon_punch_helper():
    """The footprint of polygon_punch covers the polygon's area to O(dx) and is convex-closed."""
    tri = [(0, 0), (1, 0), (0.5, np.sqrt(3) / 2)]
    h, dx = bem.polygon_punch(tri, 64)
    inside = np.isfinite(h)
    assert abs(inside.sum() * dx * dx / bem.polygon_area(tri) - 1) < 3 * dx * 3 / 0.433
    assert bem.polygon_area([(0, 0), (2, 0), (2, 1), (0, 1)]) == 2.0
    k = bem.solve(h, dx, 1.0, depth=1.0).stiffness
    beta = k / (2 * np.sqrt(inside.sum() * dx * dx / np.pi))  # (5.13)
    assert 1.0 < beta < 1.1


@pytest.mark.parametrize("kw, message", [
    (dict(height=np.zeros(3), dx=1.0, E_star=1.0, depth=1.0), "height has shape"),
    (dict(height=np.zeros((4, 4)), dx=0.0, E_star=1.0, depth=1.0), "dx = 0.0 is out of range"),
    (dict(height=np.ones((4, 4)), dx=1.0, E_star=1.0, depth=-0.5), "depth = -0.5 is out of"),
    (dict(height=np.ones((4, 4)), dx=1.0, E_star=1.0, force=-1.0), "force = -1.0 is out of"),
    (dict(height=np.zeros((4, 4)), dx=1.0, E_star=1.0), "give exactly one"),
    (dict(height=np.full((4, 4), np.inf), dx=1.0, E_star=1.0, force=1.0), "no pixel can touch"),
])
def test_bad_input_is_named(kw, message):
    with pytest.raises(ValueError, match=message):
        bem.solve(**kw)


def test_ellipsoid_against_the_exact_elliptical_solution():
    """The BEM on the gap x^2/(2 R1) + y^2/(2 R2) reproduces numeric/ellipse (an independent
    check of the elliptic-integral solution) and not the Gaussian-radius estimate: at
    R1/R2 = 4 the two differ by 4 %, the BEM's force error is O(dx^2) ~ 5e-4 at 64 x 48."""
    E, R1, R2, d = 1.0, 4.0, 1.0, 0.1
    exact = ellipse.solve(R1, R2, E, depth=d)
    gauss = ellipse.solve(R1, R2, E, depth=d, model="gaussian")
    x, y, dx, dy = bem.grid(64, 2.4 * exact.a, 48, 2.4 * exact.b)
    res = bem.solve(x**2 / (2 * R1) + y**2 / (2 * R2), dx, E, depth=d, dy=dy)
    assert abs(res.force / exact.force - 1) < 2e-3
    assert abs(gauss.force / exact.force - 1) > 0.03
    assert abs(res.area / exact.area - 1) < 3 * (dx / exact.a + dy / exact.b)  # the rim
    assert abs(res.stiffness / exact.stiffness - 1) < 3 * (dx / exact.a + dy / exact.b)


def test_read_height_map(tmp_path):
    h = np.arange(12.0).reshape(3, 4)
    h[0, 0] = np.inf
    np.save(tmp_path / "h.npy", h)
    np.savetxt(tmp_path / "h.csv", h, delimiter=",")
    np.savetxt(tmp_path / "h.txt", np.where(np.isinf(h), np.nan, h))
    for name in ("h.npy", "h.csv", "h.txt"):
        assert np.array_equal(bem.read_height_map(tmp_path / name), h)
    np.savetxt(tmp_path / "bad.txt", np.arange(3.0))
    with pytest.raises(ValueError, match="valid: a 2-D grid"):
        bem.read_height_map(tmp_path / "bad.txt")


def test_numeric_modules_do_not_import_scipy():
    import subprocess
    import sys

    code = ("import sys, hertzmdr.numeric.bem, hertzmdr.numeric.ellipse;"
            "print(','.join(m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == ""


_H = np.array([[1e-6, 0.0, 1e-6], [0.0, 0.0, 0.0], [1e-6, 0.0, 1e-6]])  # a 3 x 3 dimple [m]
# the public functions with one valid set of inputs each (SI: m, Pa, N)
PUBLIC = [
    (bem.influence_kernel, dict(x=1e-5, y=2e-5, dx=1e-5, dy=2e-5, E_star=1e11)),
    (lambda height, dx, E_star, depth: bem.solve(height, dx, E_star, depth=depth),
     dict(height=_H, dx=1e-5, E_star=1e11, depth=2e-6)),
    (lambda height, dx, E_star, force, dy: bem.solve(height, dx, E_star, force=force, dy=dy),
     dict(height=_H, dx=1e-5, E_star=1e11, force=1e-3, dy=2e-5)),
    (lambda dx, E_star, dy: bem.punch_stiffness(_H == 0, dx, E_star, dy=dy),
     dict(dx=1e-5, E_star=1e11, dy=2e-5)),
    (lambda vertices, margin: bem.polygon_punch(vertices, 8, margin=margin),
     dict(vertices=[(0.0, 0.0), (1e-3, 0.0), (0.0, 1e-3)], margin=0.1)),
]


@pytest.mark.parametrize("func, valid", PUBLIC, ids=[
    "influence_kernel", "solve_depth", "solve_force", "punch_stiffness", "polygon_punch"])
def test_each_input_named_in_its_error(func, valid):
    assert_inputs_named(func, valid)


def _dense(shape, dx, dy, E):
    """The influence matrix of the pixel grid, entry by entry from the pixel kernel."""
    nx, ny = shape
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    i, j = i.ravel(), j.ravel()
    return bem.influence_kernel((i[:, None] - i[None, :]) * dx, (j[:, None] - j[None, :]) * dy,
                                dx, dy, E)


def _contact_by_nnls(A, b):
    """The discrete contact problem (A p = b where p > 0, A p >= b elsewhere, p >= 0) is the
    quadratic program min p.A p/2 - p.b over p >= 0; with A = L L^T it is the nonnegative
    least-squares problem min |L^T p - L^-1 b|, solved by SciPy's active-set NNLS: a route
    sharing nothing with bem.solve's projected conjugate gradients but the kernel."""
    from scipy.linalg import cholesky, solve_triangular
    from scipy.optimize import nnls

    L = cholesky(A, lower=True)
    p, _ = nnls(L.T, solve_triangular(L, b, lower=True), maxiter=50 * len(b))
    return p


@pytest.mark.parametrize("control", ["depth", "force"])
def test_solver_against_the_discrete_problem_solved_by_nnls(control):
    """An ellipsoidal dimple plus a tilt on a 12 x 10 grid of non-square pixels: bem.solve
    (tol 1e-12) against the same discrete problem solved by NNLS; the punch stiffness of the
    contact area against a dense solve of A p = 1 on it. The two routes' difference is the
    conditioning of A (~1e3 here) times the tolerance: 1e-8 relative."""
    nx, ny, dx, dy, E = 12, 10, 0.1, 0.13, 3.0
    x = (np.arange(nx) - 5.3)[:, None] * dx
    y = (np.arange(ny) - 4.1)[None, :] * dy
    h = x**2 / 6 + y**2 / 10 + 0.003 * x
    A = _dense((nx, ny), dx, dy, E)
    if control == "depth":
        res = bem.solve(h, dx, E, depth=0.03, dy=dy, tol=1e-12)
        d = 0.03
    else:
        res = bem.solve(h, dx, E, force=0.04, dy=dy, tol=1e-12)
        d = res.depth
    p = _contact_by_nnls(A, d - h.ravel()).reshape(nx, ny)
    assert np.count_nonzero(p) > 10 and np.count_nonzero(p == 0) > 10  # a partial contact
    scale = p.max()
    assert np.max(np.abs(res.pressure - p)) < 1e-8 * scale
    assert np.array_equal(res.contact, p > 1e-9 * scale)
    assert abs(res.force / (p.sum() * dx * dy) - 1) < 1e-8
    assert res.area == np.count_nonzero(res.contact) * dx * dy and res.depth == d
    u = (A @ res.pressure.ravel()).reshape(nx, ny)
    assert np.max(np.abs(res.displacement - u)) < 1e-12 * np.max(np.abs(u))
    assert np.max(np.abs(res.gap - (h - d + u))) < 1e-8 * d
    assert res.residual < 1e-12 and res.iterations > 1 and (res.dx, res.dy) == (dx, dy)
    S = res.contact.ravel()
    k = np.linalg.solve(A[np.ix_(S, S)], np.ones(S.sum())).sum() * dx * dy
    assert abs(res.stiffness / k - 1) < 1e-8


def test_polygon_area_and_footprint():
    """The shoelace area of polygons away from the origin in both orientations against their
    areas by hand; polygon_punch's footprint against the polygon: the pixel area within the
    boundary pixels (perimeter times dx), the grid over the bounding box widened by the margin
    on each side, square pixels, n pixels along the longer side; its errors."""
    L = [(1.0, 1.0), (4.0, 1.0), (4.0, 2.0), (2.0, 2.0), (2.0, 3.0), (1.0, 3.0)]  # area 3 + 1
    tri = [(1.0, 2.0), (3.0, 2.0), (1.0, 5.0)]  # area 3
    for poly, area in ((L, 4.0), (tri, 3.0)):
        assert abs(bem.polygon_area(poly) - area) < 1e-15 * area
        assert abs(bem.polygon_area(poly[::-1]) - area) < 1e-15 * area
    for margin in (0.0, 0.25):
        h, dx = bem.polygon_punch(L, 60, margin=margin)
        assert abs(dx - 3.0 * (1 + 2 * margin) / 60) < 1e-15
        nx, ny = h.shape
        # 3 x 2 box [m], widened by 2 margin of its sides, in pixels of dx
        assert (nx, ny) == (60, int(np.ceil(2.0 * (1 + 2 * margin) / dx - 1e-9)))
        inside = np.isfinite(h)
        assert np.all(h[inside] == 0.0)
        perimeter = 10.0
        assert abs(inside.sum() * dx * dx - 4.0) < perimeter * dx
        if margin == 0.0:  # pixels of 0.05 m centred on the box: no centre on an edge, and the
            assert inside.sum() == 1600  # L's 4 m^2 is exactly 1600 pixels
        # pixel centres: the footprint's centre of mass is the L's, (2.25, 1.75) [m]
        xc = 2.5 + (np.arange(nx) - (nx - 1) / 2) * dx
        yc = 2.0 + (np.arange(ny) - (ny - 1) / 2) * dx
        X, Y = np.meshgrid(xc, yc, indexing="ij")
        assert abs(X[inside].mean() - 2.25) < 2 * dx and abs(Y[inside].mean() - 1.75) < 2 * dx
        # points well inside and well outside the L, by hand
        for (px, py), want in (((1.5, 2.5), True), ((3.5, 1.5), True), ((3.0, 2.6), False),
                               ((3.5, 2.9), False)):
            i, j = int(np.argmin(abs(xc - px))), int(np.argmin(abs(yc - py)))
            assert inside[i, j] == want, (px, py, margin)
    h, dx = bem.polygon_punch(L, 2)
    assert h.shape == (2, 2) and dx == 1.5  # n = 2 is the smallest grid; no margin by default
    # the triangle (a slanted edge, unequal minima in x and y): its footprint's area and centre
    h, dx = bem.polygon_punch(tri, 90)
    inside = np.isfinite(h)
    assert abs(inside.sum() * dx * dx - 3.0) < (5.0 + np.sqrt(13.0)) * dx
    xc = 2.0 + (np.arange(h.shape[0]) - (h.shape[0] - 1) / 2) * dx
    yc = 3.5 + (np.arange(h.shape[1]) - (h.shape[1] - 1) / 2) * dx
    X, Y = np.meshgrid(xc, yc, indexing="ij")
    assert abs(X[inside].mean() - 5 / 3) < 2 * dx and abs(Y[inside].mean() - 3.0) < 2 * dx
    with pytest.raises(ValueError, match=r"^n = 1 is out of range; valid: n >= 2$"):
        bem.polygon_punch(L, 1)
    for bad in ([(0.0, 0.0), (1.0, 0.0)], [0.0, 1.0, 2.0], [(0, 0, 0), (1, 0, 0), (0, 1, 0)]):
        with pytest.raises(ValueError, match=r"^vertices has shape .*; valid: \(k, 2\) with "
                                             r"k >= 3$"):
            bem.polygon_punch(bad, 8)


def test_grid_and_height_map_files(tmp_path):
    """grid: n x ny pixel centres symmetric about 0 with pitch length/n, width/ny;
    read_height_map: the smallest grid (2 x 2) read, a single row refused with its 2-D shape,
    a pickled (object) .npy refused."""
    x, y, dx, dy = bem.grid(4, 1.0, ny=6, width=3.0)
    assert x.shape == (4, 1) and y.shape == (1, 6) and (dx, dy) == (0.25, 0.5)
    assert np.allclose(x.ravel(), [-0.375, -0.125, 0.125, 0.375], rtol=0, atol=1e-16)
    assert np.allclose(y.ravel(), [-1.25, -0.75, -0.25, 0.25, 0.75, 1.25], rtol=0, atol=1e-16)
    (tmp_path / "two.txt").write_text("0 1\n2 nan\n")
    assert np.array_equal(bem.read_height_map(tmp_path / "two.txt"), [[0.0, 1.0], [2.0, np.inf]])
    (tmp_path / "row.csv").write_text("0,1,2\n")
    with pytest.raises(ValueError, match=r"heights of shape \(1, 3\); valid: a 2-D grid"):
        bem.read_height_map(tmp_path / "row.csv")
    np.save(tmp_path / "obj.npy", np.array([[0.0, {}], [1.0, 2.0]], dtype=object),
            allow_pickle=True)
    with pytest.raises(ValueError, match="allow_pickle"):
        bem.read_height_map(tmp_path / "obj.npy")


def test_punch_stiffness_refuses_an_empty_footprint():
    with pytest.raises(ValueError, match=r"^mask has no pixel; valid: at least one True pixel$"):
        bem.punch_stiffness(np.zeros((3, 3), dtype=bool), 1e-5, 1e11)


def test_punch_stiffness_reports_its_residual_when_not_converged():
    """One conjugate-gradient step on a 6 x 6 punch leaves a relative residual of a few percent
    (measured 0.0395): reported, with the tolerance, when max_iter stops the iteration."""
    with pytest.raises(RuntimeError, match=r"^punch_stiffness: residual 0\.0[1-9]\d* > tol = "
                                           r"1e-14$"):
        bem.punch_stiffness(np.ones((6, 6), dtype=bool), 1.0, 1.0, tol=1e-14, max_iter=1)


def test_solve_messages():
    """solve's refusals in full: -inf heights, no control or both, no pixel that can touch;
    a depth that does not reach below the lowest height is no load (tests/test_zero_load.py),
    a negative one is refused."""
    h = np.array([[1e-6, 2e-6], [3e-6, 4e-6]])
    for kw, msg in (
            (dict(height=np.where(h > 3e-6, -np.inf, h), depth=1e-6),
             "height contains -inf; valid: finite values, or +inf off a footprint"),
            (dict(height=h), "give exactly one of depth= and force="),
            (dict(height=h, depth=1e-6, force=1.0), "give exactly one of depth= and force="),
            (dict(height=np.full((2, 2), np.inf), force=1.0),
             "height is +inf everywhere: no pixel can touch")):
        with pytest.raises(ValueError, match="^" + re.escape(msg) + "$"):
            bem.solve(dx=1e-5, E_star=1e11, **kw)
    with pytest.raises(ValueError, match=r"^depth = -1e-06 is out of range; valid: 0 <= depth "
                                         r"< inf$"):
        bem.solve(h, 1e-5, 1e11, depth=-1e-6)


def test_solve_result_fields_and_non_convergence():
    """Pixels off the footprint have an infinite gap; stiffness=False leaves it None; max_iter
    reached raises with the residual and the tolerance."""
    h, dx = bem.polygon_punch([(0.0, 0.0), (1e-3, 0.0), (0.0, 1e-3)], 12)
    res = bem.solve(h, dx, 1e11, depth=1e-6, stiffness=False)
    off = ~np.isfinite(h)
    assert off.any() and np.all(res.gap[off] == np.inf) and np.all(np.isfinite(res.gap[~off]))
    assert res.stiffness is None
    with pytest.raises(RuntimeError, match=r"^bem\.solve: residual \S+ > tol = 1e-14 after "
                                           r"max_iter = 1 iterations$"):
        bem.solve(_sphere(16)[0], _sphere(16)[1], 1.0, depth=0.05, tol=1e-14, max_iter=1)


@pytest.mark.parametrize("n", [8, 33, 128])
def test_boundary_area_bounds_the_pixelated_area(n):
    """A disc of radius R pixelated by pixel centres (as polygon_punch does): the exact area
    pi R^2 differs from the pixel count's by at most the band of edge pixels, at every
    resolution and off-centre placement; the band shrinks like the perimeter times dx."""
    R = 1.0
    for shift in (0.0, 0.31, 0.5):
        dx = 2.5 * R / n
        x = (np.arange(n) - n / 2 + shift) * dx
        X, Y = np.meshgrid(x, x, indexing="ij")
        mask = X**2 + Y**2 < R**2
        band = bem.boundary_area(mask, dx, dx)
        assert abs(mask.sum() * dx * dx - np.pi * R**2) <= band
        # the band is the pixels along the circle: about 2 * 2 pi R / dx of them, never more
        # than 3 times that (the staircase's diagonal runs)
        assert band <= 3 * 2 * (2 * np.pi * R / dx) * dx * dx
