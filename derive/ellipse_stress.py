"""Stresses under the elliptical Hertz pressure p0 (1 - x^2/a^2 - y^2/b^2)^(1/2), (5.31).

a >= b are the semi-axes (a along x), z > 0 into the body, tension positive.

Starting points:

- Superposition in Love's form. The Boussinesq stresses (5.41)-(5.46) of a unit force are,
  with H = ln(R + z) and psi = dH/dz = 1/R,
  sigma_xx = (2 nu psi_z - z psi_xx - (1 - 2 nu) H_xx)/(2 pi) (and yy alike),
  sigma_zz = (psi_z - z psi_zz)/(2 pi), tau_xy = -((1 - 2 nu) H_xy + z psi_xy)/(2 pi),
  tau_xz = -z psi_xz/(2 pi), tau_yz = -z psi_yz/(2 pi) (:func:`love_stresses`;
  ``tests/test_ellipse_stress.py`` checks them against the derived (5.41)-(5.46)
  symbolically). The operators are linear, so under a pressure p they act on
  H1 = iint p ln(rho + z) dA and psi1 = iint p/rho dA.
- psi1 of the ellipsoidal pressure is the classical potential of the ellipse (Ferrers, Dyson;
  Johnson, Contact Mechanics (1985), section 3.6, the one literature input, typed in):
  psi1 = k int_lam^inf g(w) dw/Delta(w), k = pi p0 a b/2, g = 1 - x^2/(a^2 + w) -
  y^2/(b^2 + w) - z^2/w, Delta = ((a^2 + w)(b^2 + w) w)^(1/2), lam the largest root of
  g(lam) = 0 (the ellipsoidal coordinate). The tests check psi1 against the 2-D quadrature of
  p/rho at 30 digits, and every stress below against mpmath superposition of (5.41)-(5.46).
- Its derivatives are taken here under the integral sign: g(lam) = 0 removes the boundary
  term of the first derivatives, dlam/dx_j = -g_j/g_w comes from implicit differentiation,
  and the integrals left are I_x, I_y, I_z = int_lam^inf dw/((a^2 + w, b^2 + w, w) Delta):
  Carlson's 2/3 R_D (incomplete elliptic integrals of the second kind). Their sum is
  2/Delta(lam) (d(1/Delta)/dw = -(1/(a^2 + w) + 1/(b^2 + w) + 1/w)/(2 Delta), checked here),
  which eliminates I_z: it diverges at the surface, z I_z does not. sigma_zz, tau_xz and
  tau_yz come out algebraic in lam (the I's cancel).
- H1: its second derivatives in x, y are not derivatives of psi1. With H1_x -> 0 as z -> inf,
  H1_x = -int_z^inf psi1_x(x, y, t) dt; psi1_x = -2 k x int_lam(t)^inf dw/((a^2 + w) Delta)
  and exchanging the order of integration (for fixed w, t runs from z to zeta_w,
  zeta_w^2 = w (1 - x^2/(a^2 + w) - y^2/(b^2 + w)), since lam grows with t) gives
  H1_x = 2 k x int_lam^inf (zeta_w - z) dw/((a^2 + w) Delta) (the hand step; the tests check
  d(H1_x)/dz = psi1_x and H1_xx + H1_yy = -psi1_zz). Its integrand vanishes at w = lam, so
  SymPy differentiates under the integral sign without boundary term. zeta_w Delta =
  w P2(w)^(1/2) with the quadratic P2 = (a^2 + w)(b^2 + w) - x^2 (b^2 + w) - y^2 (a^2 + w)
  = (w - w1)(w - w2): with w = w1 + v^2 the integrands are smooth in v on [(lam - w1)^(1/2),
  inf) -- also at the surface outside the contact, where P2(lam) = 0 -- and decay like v^-3.
  SymPy does not integrate them in closed form (they are elementary, through logarithms
  and arcsines whose arguments cancel near the axes and the contact edge): they are printed
  as integrands (:func:`h_integrands`) and :mod:`hertzmdr.numeric.ellipse_stress`
  integrates them by double-exponential quadrature with an error estimate.
- Stable printing: z = e lam^(1/2), e = z/lam^(1/2) in [0, 1], with e^2 = P2(lam)/((a^2 +
  lam)(b^2 + lam)) = q (q + d)/((a^2 + lam)(b^2 + lam)), q = lam - w1, d = w1 - w2: finite
  at the surface (lam = z = 0 inside the contact), where the forms in z and lam are 0/0.
  w1, b^2 + w1 and d are printed cancellation-free (the discriminant of P2 is the sum of
  squares (a^2 - b^2 - x^2 + y^2)^2 + 4 x^2 y^2; the root of larger modulus first, the other
  from the product of the roots).
- The axis x = y = 0: lam = z^2, e = 1, P2 = (a^2 + w)(b^2 + w), and SymPy integrates the H
  integrands: J_xx = 2/(A^(1/2) (A^(1/2) + B^(1/2))), J_yy = 2/(B^(1/2) (A^(1/2) + B^(1/2))),
  A = a^2 + z^2, B = b^2 + z^2. sigma_zz = -p0 a b/(A B)^(1/2); sigma_xx, sigma_yy in R_D.
  At b = a they are (5.48), (5.49) (tests). Their z-derivatives (for the maxima) by the chain
  rule with dI_x/dz = -2 z/((a^2 + z^2) Delta(z^2)) (the lower limit lam = z^2).
"""

from __future__ import annotations

from functools import cache

import mpmath as mp
import sympy as sp

from hertzmdr.derive import boussinesq as bq
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import a, nu, p0, symbol, z

TEST = "tests/test_ellipse_stress.py"

b = symbol("b_e")
x, y = symbol("x", real=True), symbol("y", real=True)
lam = symbol("lam_e", nonnegative=True)
e_c = symbol("e_c", nonnegative=True)
q_e = symbol("q_e", nonnegative=True)
w1 = symbol("w1_e", real=True)
w1a, w1b, d_e = (symbol(n, nonnegative=True) for n in ("w1_a", "w1_b", "d_e"))
v = symbol("v_q", nonnegative=True)
Ix, Iy = symbol("I_x"), symbol("I_y")
Jxx, Jyy, Jxy = (symbol(n, real=True) for n in ("J_xx", "J_yy", "J_xy"))

_w = sp.Symbol("w_int", positive=True)
_lam = sp.Symbol("lam_pos", positive=True)
_z = sp.Symbol("z_pos", positive=True)
_e = sp.Symbol("e_pos", positive=True)
_Iz = sp.Symbol("I_z", positive=True)
_A, _B, _P = (sp.Symbol(n, positive=True) for n in ("A_w", "B_w", "P2_w"))
_v = sp.Symbol("v_pos", positive=True)


class carlson_rd(sp.Function):  # noqa: N801 - printed by its name (derive/codegen.py)
    """Carlson's R_D(x, y, z) = (3/2) int_0^inf dt/((t + z) ((t + x)(t + y)(t + z))^(1/2))."""

    nargs = 3

    def _eval_evalf(self, prec):
        if not all(arg.is_number for arg in self.args):
            return None
        dps = mp.libmp.prec_to_dps(prec)
        with mp.workdps(dps + 10):
            vals = [mp.mpf(str(sp.N(arg, dps + 10))) for arg in self.args]
            return sp.Float(str(mp.elliprd(*vals)), dps)


def love_stresses(H: sp.Expr, psi: sp.Expr, X, Y, Z) -> dict[str, sp.Expr]:
    """The stresses from Love's potentials H, psi = dH/dz in coordinates (X, Y, Z)."""
    k = 1 / (2 * sp.pi)
    return {
        "xx": k * (2 * nu * sp.diff(psi, Z) - Z * sp.diff(psi, X, 2)
                   - (1 - 2 * nu) * sp.diff(H, X, 2)),
        "yy": k * (2 * nu * sp.diff(psi, Z) - Z * sp.diff(psi, Y, 2)
                   - (1 - 2 * nu) * sp.diff(H, Y, 2)),
        "zz": k * (sp.diff(psi, Z) - Z * sp.diff(psi, Z, 2)),
        "xy": -k * ((1 - 2 * nu) * sp.diff(H, X, Y) + Z * sp.diff(psi, X, Y)),
        "xz": -k * Z * sp.diff(psi, X, Z),
        "yz": -k * Z * sp.diff(psi, Y, Z),
    }


def point_force_potentials() -> tuple[sp.Expr, sp.Expr]:
    """H = ln(R + z), psi = 1/R of a unit force (the Boussinesq coordinates)."""
    R = bq.distance()
    return sp.log(R + bq.z), 1 / R


def potential_integrand() -> sp.Expr:
    """g(w) of psi1 = k int_lam^inf g dw/Delta (in x, y, z_pos, w_int)."""
    return 1 - x**2 / (a**2 + _w) - y**2 / (b**2 + _w) - _z**2 / _w


def delta(w=_w) -> sp.Expr:
    return sp.sqrt((a**2 + w) * (b**2 + w) * w)


K_PSI = sp.pi * p0 * a * b / 2


def _integral(expr: sp.Expr) -> sp.Expr:
    """int_lam^inf expr dw/Delta for expr = c1/(a^2 + w) + c2/(b^2 + w) + c3/w, as c.I."""
    out = 0
    for term in sp.Add.make_args(sp.expand(expr)):
        for den, sym in ((a**2 + _w, Ix), (b**2 + _w, Iy), (_w, _Iz)):
            c = sp.cancel(term * den)
            if not c.has(_w):
                out += c * sym
                break
        else:
            raise ValueError(f"term {term} is not in the basis of the I integrals")
    return out


def carlson_identity() -> sp.Expr:
    """d(1/Delta)/dw + (1/(a^2 + w) + 1/(b^2 + w) + 1/w)/(2 Delta): zero (so that
    I_x + I_y + I_z = 2/Delta(lam))."""
    return sp.simplify(sp.diff(1 / delta(), _w)
                       + (1 / (a**2 + _w) + 1 / (b**2 + _w) + 1 / _w) / (2 * delta()))


_Al, _Bl, _S, _T = (sp.Symbol(n, positive=True) for n in ("A_lam", "B_lam", "S_lam", "T_lam"))


@cache
def psi_derivatives() -> dict[tuple, sp.Expr]:
    """First and second derivatives of psi1 in x, y, z_pos, with I_x, I_y, I_z; at w = lam,
    a^2 + lam = A_lam, b^2 + lam = B_lam, g_w(lam) = S_lam."""
    g = potential_integrand()
    coords = (x, y, _z)
    at_lam = {a**2 + _lam: _Al, b**2 + _lam: _Bl}
    gw = sp.diff(g, _w).subs(_w, _lam).subs(at_lam)
    assert sp.simplify(gw - (x**2 / _Al**2 + y**2 / _Bl**2 + _z**2 / _lam**2)) == 0
    dlam = {c: -sp.diff(g, c).subs(_w, _lam).subs(at_lam) / _S for c in coords}  # g(lam) = 0
    dlt = sp.sqrt(_Al * _Bl * _lam)
    out = {}
    for i in coords:
        out[(i,)] = K_PSI * _integral(sp.diff(g, i))  # boundary term g(lam) = 0
        for j in coords:
            boundary = -sp.diff(g, i).subs(_w, _lam).subs(at_lam) / dlt * dlam[j]
            out[(i, j)] = K_PSI * (_integral(sp.diff(g, i, j)) + boundary)
    return out


@cache
def h_integrands() -> dict[str, sp.Expr]:
    """The integrands in v of J_xx, J_yy, J_xy: H1_xx = 2k (J_xx - z I_x),
    H1_yy = 2k (J_yy - z I_y), H1_xy = 2k J_xy, w = w1 + v^2."""
    zeta = sp.sqrt(_w * _P / (_A * _B))  # zeta_w, with P2 = A B - x^2 B - y^2 A
    dP = {x: -2 * x * _B, y: -2 * y * _A}
    dlt = sp.sqrt(_A * _B * _w)

    def d(expr, c):
        return sp.diff(expr, c) + sp.diff(expr, _P) * dP[c]

    hx = x * zeta / (_A * dlt)  # the zeta part of H1_x/(2k); the -z part gives -z I_x
    hy = y * zeta / (_B * dlt)
    raw = {"xx": d(hx, x), "yy": d(hy, y), "xy": d(hx, y)}
    assert sp.simplify(raw["xy"] - d(hy, x)) == 0  # H1_xy = H1_yx
    sub = {_A: w1a + _v**2, _B: w1b + _v**2, _P: _v**2 * (_v**2 + d_e), _w: w1 + _v**2}
    out = {}
    for k, e in raw.items():
        e = sp.powsimp(sp.expand(e), force=True)
        out[k] = sp.factor(e.subs(sub, simultaneous=True) * 2 * _v).subs(_v, v)
    return out


@cache
def field_compact() -> dict[str, sp.Expr]:
    """The six stresses with I_z eliminated and z = e lam^(1/2), in A_lam, B_lam, lam_pos,
    T_lam = lam S_lam = e^2 + lam (x^2/A_lam^2 + y^2/B_lam^2) and I_x, I_y, J's."""
    pd = psi_derivatives()
    k2 = 2 * K_PSI
    H = {"xx": k2 * (Jxx - _z * Ix), "yy": k2 * (Jyy - _z * Iy), "xy": k2 * Jxy}
    c = 1 / (2 * sp.pi)
    raw = {
        "xx": c * (2 * nu * pd[(_z,)] - _z * pd[(x, x)] - (1 - 2 * nu) * H["xx"]),
        "yy": c * (2 * nu * pd[(_z,)] - _z * pd[(y, y)] - (1 - 2 * nu) * H["yy"]),
        "zz": c * (pd[(_z,)] - _z * pd[(_z, _z)]),
        "xy": -c * ((1 - 2 * nu) * H["xy"] + _z * pd[(x, y)]),
        "xz": -c * _z * pd[(x, _z)],
        "yz": -c * _z * pd[(y, _z)],
    }
    iz = 2 / sp.sqrt(_Al * _Bl * _lam) - Ix - Iy  # I_x + I_y + I_z = 2/Delta(lam)
    out = {}
    for k, e in raw.items():
        e = sp.expand(e.subs(_Iz, iz).subs(_z, _e * sp.sqrt(_lam)).subs(_S, _T / _lam))
        e = sp.collect(sp.powsimp(e, force=True), (Ix, Iy, Jxx, Jyy, Jxy), evaluate=False)
        out[k] = sum(sp.factor(coeff) * key for key, coeff in e.items())
    return out


def _lam_values() -> dict[sp.Symbol, sp.Expr]:
    A, B = a**2 + lam, b**2 + lam
    return {_Al: A, _Bl: B, _T: e_c**2 + lam * (x**2 / A**2 + y**2 / B**2), _e: e_c,
            _lam: lam}


@cache
def field() -> dict[str, sp.Expr]:
    """The stresses printed, in (a, b, nu, p0, x, y, lam, e, I_x, I_y, J's)."""
    return {k: e.subs(_lam_values(), simultaneous=True) for k, e in field_compact().items()}


def e_squared() -> sp.Expr:
    """e^2 = z^2/lam = P2(lam)/((a^2 + lam)(b^2 + lam)) with P2(lam) = q (q + d)."""
    return q_e * (q_e + d_e) / ((a**2 + lam) * (b**2 + lam))


def e_squared_check() -> sp.Expr:  # noqa: D401
    """z^2/lam - (1 - x^2/(a^2 + lam) - y^2/(b^2 + lam)), zero by g(lam) = 0 (the origin of
    :func:`e_squared`; P2 = A B (1 - x^2/A - y^2/B))."""
    g = potential_integrand().subs(_w, _lam)
    return sp.simplify(g - (1 - x**2 / (a**2 + _lam) - y**2 / (b**2 + _lam) - _z**2 / _lam))


def surface_quadratic() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """P2's coefficients beta, gamma (P2 = w^2 + beta w + gamma) and its discriminant as the
    sum of squares."""
    P = sp.expand((a**2 + _w) * (b**2 + _w) - x**2 * (b**2 + _w) - y**2 * (a**2 + _w))
    beta, gamma = P.coeff(_w, 1), P.coeff(_w, 0)
    disc = (a**2 - b**2 - x**2 + y**2) ** 2 + 4 * x**2 * y**2
    assert sp.expand(beta**2 - 4 * gamma - disc) == 0
    return beta, gamma, disc


def roots() -> dict[str, sp.Expr]:
    """w1, a^2 + w1, b^2 + w1 and d = w1 - w2, cancellation-free."""
    beta, gamma, disc = surface_quadratic()
    sd = sp.sqrt(disc)
    w1_expr = sp.Piecewise(((-beta + sd) / 2, beta <= 0), (-2 * gamma / (beta + sd), True))
    # shifted by b^2: omega^2 + beta_b omega + gamma_b, gamma_b = -y^2 (a^2 - b^2) <= 0
    beta_b = a**2 - b**2 - x**2 - y**2
    gamma_b = -(y**2) * (a - b) * (a + b)
    wb = sp.Piecewise(((-beta_b + sd) / 2, beta_b <= 0), (-2 * gamma_b / (beta_b + sd), True))
    # shifted by a^2: omega^2 - (a^2 - b^2 + x^2 + y^2) omega + x^2 (a^2 - b^2): a sum
    wa = ((a - b) * (a + b) + x**2 + y**2 + sd) / 2
    for shift, expr in ((0, w1_expr), (b**2, wb), (a**2, wa)):
        # each is a root of P2(w - shift) (the branch condition decides which is printed)
        for piece in (expr.args if isinstance(expr, sp.Piecewise) else [(expr, True)]):
            val = piece[0] - shift
            P = (a**2 + val) * (b**2 + val) - x**2 * (b**2 + val) - y**2 * (a**2 + val)
            probe = {a: 2, b: 1, x: sp.Rational(1, 3), y: sp.Rational(1, 5)}
            assert abs(sp.N(P.subs(probe), 30)) < 1e-25
    return {"w1": w1_expr, "w1_b": wb, "w1_a": wa, "d": sd}


def cubics() -> dict[str, sp.Expr]:
    """lam P2(lam) - z^2 (a^2 + lam)(b^2 + lam), whose largest root is lam, in lam and in
    q = lam - w1 (P2 = (w - w1)(w - w1 + d))."""
    cub_lam = lam * (lam - w1) * (lam - w1 + d_e) - z**2 * (a**2 + lam) * (b**2 + lam)
    cub_q = (w1 + q_e) * q_e * (q_e + d_e) - z**2 * (w1a + q_e) * (w1b + q_e)
    return {"lam": cub_lam, "q": cub_q}


@cache
def axis() -> tuple[dict[str, sp.Expr], dict[str, sp.Expr]]:
    """sigma_xx, sigma_yy, sigma_zz on the axis in z_pos with I_x, I_y as symbols and the
    J's integrated; and the J's as SymPy integrates them."""
    A, B = a**2 + _z**2, b**2 + _z**2
    c2 = sp.Symbol("c2", positive=True)  # a^2 - b^2 (a > b while integrating)
    v0 = sp.Symbol("v0", positive=True)
    on_axis = {x: 0, y: 0, w1a: c2, w1b: 0, d_e: c2, v: _v}  # w1 = -b^2, w2 = -a^2
    vals = {}
    for key in ("xx", "yy"):
        j = sp.simplify(h_integrands()[key].subs(on_axis))
        val = sp.integrate(j, (_v, v0, sp.oo))
        # v0^2 = lam - w1 = z^2 + b^2 = B, c2 + v0^2 = A
        vals[key] = sp.simplify(val.subs(c2, A - B).subs(v0, sp.sqrt(B)))
    sqA, sqB = sp.sqrt(A), sp.sqrt(B)
    stable = {"xx": 2 / (sqA * (sqA + sqB)), "yy": 2 / (sqB * (sqA + sqB))}
    probe = {a: sp.Rational(3, 2), b: sp.Rational(1, 2), _z: sp.Rational(1, 3)}
    for key in ("xx", "yy"):
        assert abs(sp.N((vals[key] - stable[key]).subs(probe), 40)) < 1e-35
    sub = {x: 0, y: 0, _lam: _z**2, _e: 1, _T: 1, _Al: A, _Bl: B, Jxx: stable["xx"],
           Jyy: stable["yy"]}
    out = {k: field_compact()[k].subs(sub) for k in ("xx", "yy", "zz")}
    return out, vals


def rd_axis() -> dict[sp.Symbol, sp.Expr]:
    """I_x, I_y at lam = z^2 as Carlson's R_D: int_lam^inf dw/((a^2 + w) Delta) with
    w = lam + t is (2/3) R_D(b^2 + lam, lam, a^2 + lam)."""
    A, B, L = a**2 + z**2, b**2 + z**2, z**2
    return {Ix: sp.Rational(2, 3) * carlson_rd(B, L, A),
            Iy: sp.Rational(2, 3) * carlson_rd(A, L, B)}


def _axis_in_z(expr: sp.Expr) -> sp.Expr:
    return expr.subs(_z, z).subs(rd_axis())


def _axis_slope(expr: sp.Expr) -> sp.Expr:
    """d/dz of an axis expression in (z_pos, I_x, I_y): dI/dz = -2 z g(z^2)/Delta(z^2)."""
    A, B = a**2 + _z**2, b**2 + _z**2
    dlt = sp.sqrt(A * B) * _z
    dIx, dIy = -2 * _z / (A * dlt), -2 * _z / (B * dlt)
    return sp.diff(expr, _z) + sp.diff(expr, Ix) * dIx + sp.diff(expr, Iy) * dIy


@cache
def axis_shears() -> dict[str, sp.Expr]:
    """(sigma_xx - sigma_zz)/2, (sigma_yy - sigma_zz)/2 and von Mises on the axis (in z_pos,
    I_x, I_y), von Mises as (5.50) with zero shears: a sum of squares."""
    s, _ = axis()
    vm = sp.sqrt(((s["xx"] - s["yy"]) ** 2 + (s["yy"] - s["zz"]) ** 2
                  + (s["zz"] - s["xx"]) ** 2) / 2)
    return {"shear_x": (s["xx"] - s["zz"]) / 2, "shear_y": (s["yy"] - s["zz"]) / 2,
            "von_mises": vm}


def relations() -> list[Relation]:
    s, _ = axis()
    f = field()
    rts = roots()
    cub = cubics()
    integrands = h_integrands()
    ax = f"{TEST}::test_axis_stresses_by_superposition"
    sup = "Boussinesq (5.41)-(5.46) superposed over (5.31) in Love's form, on the axis"
    rels = []
    names = {"xx": "normal stress sigma_xx", "yy": "normal stress sigma_yy",
             "zz": "normal stress sigma_zz"}
    for k in ("xx", "yy", "zz"):
        e = _axis_in_z(s[k])
        args = (a, b, p0, z) if k == "zz" else (a, b, nu, p0, z)
        rels.append(Relation(
            f"ellipse_stress_axis_sigma_{k}", "(5.31), (5.41)-(5.46)", e, args,
            f"{names[k]} [Pa] on the axis x = y = 0 under the elliptical Hertz pressure "
            "(semi-axes a along x, b along y)", sup, ax))
    mx = f"{TEST}::test_axis_maxima_at_30_digits"
    what = {"shear_x": "principal shear (sigma_xx - sigma_zz)/2 [Pa]",
            "shear_y": "principal shear (sigma_yy - sigma_zz)/2 [Pa]",
            "von_mises": "von Mises stress (5.50) [Pa]"}
    for k, e in axis_shears().items():
        rels.append(Relation(
            f"ellipse_stress_axis_{k}", "(5.31), (5.50)", _axis_in_z(e), (a, b, nu, p0, z),
            f"{what[k]} on the axis of an elliptical Hertz contact", "the axis stresses", mx))
        rels.append(Relation(
            f"ellipse_stress_axis_{k}_slope", "(5.31), (5.50)", _axis_in_z(_axis_slope(e)),
            (a, b, nu, p0, z), f"d/dz of the {what[k].split(' [')[0]} [Pa/m] on the axis of "
            "an elliptical Hertz contact; its root is the depth of the maximum",
            "the chain rule with dI/dz from the lower limit lam = z^2", mx))
    fld = f"{TEST}::test_field_by_superposition"
    lit = ("psi1 of the ellipse (Johnson 1985, 3.6) in Love's form of Boussinesq, derivatives "
           "under the integral sign, z = e lam^(1/2)")
    comps = {"xx": ("sigma_xx", (a, b, nu, p0, x, y, lam, e_c, Ix, Iy, Jxx)),
             "yy": ("sigma_yy", (a, b, nu, p0, x, y, lam, e_c, Ix, Iy, Jyy)),
             "zz": ("sigma_zz", (a, b, p0, x, y, lam, e_c)),
             "xy": ("tau_xy", (a, b, nu, p0, x, y, lam, e_c, Jxy)),
             "xz": ("tau_xz", (a, b, p0, x, y, lam, e_c)),
             "yz": ("tau_yz", (a, b, p0, x, y, lam, e_c))}
    for k, (name, args) in comps.items():
        rels.append(Relation(
            f"ellipse_stress_{name}", "(5.31), (5.41)-(5.46)", f[k], args,
            f"stress {name} [Pa] at (x, y, z) under the elliptical Hertz pressure, from the "
            "ellipsoidal coordinate lam, e = z/lam^(1/2) and the integrals I, J", lit, fld))
    rels += [
        Relation("ellipse_stress_I_x", "(5.31)", sp.Rational(2, 3) * carlson_rd(
            b**2 + lam, lam, a**2 + lam), (a, b, lam),
            "I_x [m^-3] = int_lam^inf dw/((a^2 + w) Delta(w)) as Carlson's (2/3) R_D",
            "w = lam + t in Carlson's definition of R_D", fld),
        Relation("ellipse_stress_I_y", "(5.31)", sp.Rational(2, 3) * carlson_rd(
            a**2 + lam, lam, b**2 + lam), (a, b, lam),
            "I_y [m^-3] = int_lam^inf dw/((b^2 + w) Delta(w)) as Carlson's (2/3) R_D",
            "w = lam + t in Carlson's definition of R_D", fld),
        Relation("ellipse_stress_e_sq", "(5.31)", e_squared(), (a, b, lam, q_e, d_e),
                 "e^2 = z^2/lam [1], finite on the surface", "g(lam) = 0", fld),
        Relation("ellipse_stress_w1", "(5.31)", rts["w1"], (a, b, x, y),
                 "largest root w1 [m^2] of the surface quadratic P2 at (x, y) (< 0 inside "
                 "the contact ellipse, > 0 outside)", "P2 = w^2 + beta w + gamma", fld),
        Relation("ellipse_stress_w1_b", "(5.31)", rts["w1_b"], (a, b, x, y),
                 "b^2 + w1 [m^2] >= 0", "P2 shifted by b^2", fld),
        Relation("ellipse_stress_w1_a", "(5.31)", rts["w1_a"], (a, b, x, y),
                 "a^2 + w1 [m^2] >= 0", "P2 shifted by a^2", fld),
        Relation("ellipse_stress_d", "(5.31)", rts["d"], (a, b, x, y),
                 "w1 - w2 [m^2] >= 0, the difference of the roots of P2",
                 "the discriminant of P2 as a sum of squares", fld),
        Relation("ellipse_stress_cubic_lam", "(5.31)", cub["lam"], (a, b, z, w1, d_e, lam),
                 "lam P2(lam) - z^2 (a^2 + lam)(b^2 + lam) [m^6], zero at lam",
                 "g(lam) = 0 times lam (a^2 + lam)(b^2 + lam)", fld),
        Relation("ellipse_stress_cubic_lam_slope", "(5.31)", sp.diff(cub["lam"], lam),
                 (a, b, z, w1, d_e, lam), "d/dlam of ellipse_stress_cubic_lam [m^4]",
                 "its derivative", fld),
        Relation("ellipse_stress_cubic_q", "(5.31)", cub["q"], (z, w1, w1a, w1b, d_e, q_e),
                 "the same cubic [m^6] in q = lam - w1 (accurate where lam is close to w1 "
                 ">= 0)", "lam = w1 + q", fld),
        Relation("ellipse_stress_cubic_q_slope", "(5.31)", sp.diff(cub["q"], q_e),
                 (z, w1, w1a, w1b, d_e, q_e), "d/dq of ellipse_stress_cubic_q [m^4]",
                 "its derivative", fld),
    ]
    for k, args in (("xx", (x, w1a, w1b, d_e, v)), ("yy", (y, w1a, w1b, d_e, v)),
                    ("xy", (x, y, w1a, w1b, d_e, v))):
        rels.append(Relation(
            f"ellipse_stress_j{k}_integrand", "(5.31)", integrands[k], args,
            f"integrand [m^-3] in v of J_{k} (H1_{k} of the elliptical pressure), "
            "w = w1 + v^2, v >= (lam - w1)^(1/2)",
            "d/dx_j of H1_x = 2k x int (zeta_w - z) dw/((a^2 + w) Delta)", fld))
    return rels
