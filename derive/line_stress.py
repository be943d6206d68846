"""Stresses in the half-plane under the line contact (plane strain): Flamant, superposed over
the Hertz line pressure (5.36).

Starting points:

- Flamant (the 2-D Boussinesq problem): the Airy stress function phi = -(P/pi) r theta
  sin(theta) of a normal line load P [N/m] at the origin pushing into the body z > 0, theta
  measured from the z-axis, i.e. phi = -(P/pi) x atan(x/z). The stresses are its second
  derivatives, sigma_xx = phi_zz, sigma_zz = phi_xx, tau_xz = -phi_xz (equilibrium holds
  identically); ``tests/test_line_stress.py`` checks symbolically that phi is biharmonic (the
  compatibility of plane strain), that the derivatives are in equilibrium, that the surface
  z = 0 is traction-free away from the origin and that every half-circle around the origin
  carries the load.
- On the axis x = 0 the superposition over p(s) = p0 (1 - s^2/a^2)^(1/2) (a the half-width)
  with s = a sin(theta), t = tan(theta) has rational integrands on the real t-line; SymPy
  integrates their partial fractions exactly: sigma_zz = -p0 a/(a^2 + z^2)^(1/2) and
  sigma_xx = -p0 [(a^2 + 2 z^2)/(a (a^2 + z^2)^(1/2)) - 2 z/a], printed as
  -p0 a^3/(s (s + z)^2), s = (a^2 + z^2)^(1/2), which has no cancellation at depth.
- The full field by complex variables: with w = X + i z (X = x - s the field point relative to
  the source), Flamant is sigma_xx + sigma_zz = (2P/pi) Im(1/w),
  sigma_zz - sigma_xx = (2P/pi) z Re(1/w^2), tau_xz = (P/pi) z Im(1/w^2) (identities checked
  here). Superposed, everything is one analytic function, the Cauchy integral
  F(zeta) = int p(s)/(zeta - s) ds, zeta = x + i z, and its derivative. For the semi-ellipse
  F = (pi p0/a)(zeta - (zeta^2 - a^2)^(1/2)) (the branch ~ zeta at infinity; the one typed-in
  step: it is analytic in z > 0, its imaginary part on z = 0 is -pi p(x), it decays like the
  load/zeta, which fix it; ``tests/test_line_stress.py`` checks it against the quadrature
  of the Cauchy integral at 50 digits). Writing (zeta^2 - a^2)^(1/2) = n + i m gives McEwen's
  (1949) m, n (m^2 - n^2 = a^2 - x^2 + z^2, m n = x z, m >= 0, sign n = sign x), and SymPy
  turns Im F, Re F', Im F' into the forms Johnson (Contact Mechanics, 1985, ch. 4) prints,
  which the tests compare with this module's forms at 50 digits.
- Stable printing: with D = m^2 + n^2 = ((a^2 - x^2 + z^2)^2 + 4 x^2 z^2)^(1/2),
  g = m^2 - z^2 and h = g/(m + z) = m - z (all >= 0), the field is
  sigma_zz = -(p0/a) m g/D, sigma_xx = -(p0/a) h (m h + 2 n^2)/D, tau_xz = -(p0/a) n g/D:
  sums of positive terms (the textbook 2z - m(1 + ...) cancels far away, m^2 - z^2 near the
  surface outside the contact). m, n, g are computed in three regions (x >= 0; the field is
  even in x, tau_xz odd) without cancellation: q = (a - x)(a + x) + z^2 >= 0:
  m = ((D + q)/2)^(1/2), n = x z/m; q < 0: n = ((D - q)/2)^(1/2), m = x z/n; and
  g = (a - x)(a + x) + n^2 inside the circle x^2 + z^2 <= a^2, else
  g = 2 a^2 z^2/(D + e), e = (x - a)(x + a) + z^2 > 0 (from D^2 = e^2 + 4 a^2 z^2).
- Maxima: tau_1 = (sigma_xx - sigma_zz)/2 on the axis, p0 a z/(s (s + z)), peaks where
  (z/a)^4 + (z/a)^2 = 1, z = a phi^(-1/2), tau_1 = p0 phi^(-5/2) (phi the golden ratio);
  the von Mises stress on the axis with sigma_yy = nu (sigma_xx + sigma_zz) (plane strain,
  eps_yy = 0); tau_xz peaks where both partial derivatives (generated from F'' here) vanish,
  which is zeta = a e^(i pi/6): |tau_xz| = p0/4 at x = (3^(1/2)/2) a, z = a/2.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from hertzmdr.derive import stress as ds
from hertzmdr.derive.relation import Relation
from hertzmdr.derive.symbols import a, nu, p0, symbol, z

TEST = "tests/test_line_stress.py"

x = symbol("x", real=True)
F_L = symbol("F_L")
sxx, syy, szz, sxz = (symbol(n, real=True) for n in ("sigma_xx", "sigma_yy", "sigma_zz",
                                                     "tau_xz"))
_z = sp.Symbol("z_pos", positive=True)  # z > 0 inside the body while differentiating
_t = sp.Symbol("t_int", real=True)
_m = sp.Symbol("m_mcewen", nonnegative=True)
_n = sp.Symbol("n_mcewen", real=True)
_g = sp.Symbol("g_aux", nonnegative=True)  # m^2 - z^2
_h = sp.Symbol("h_aux", nonnegative=True)  # m - z = g/(m + z)
_c = symbol("c_mean", real=True)  # (sigma_xx + sigma_zz)/2
_t1 = symbol("tau_1", nonnegative=True)


def airy() -> sp.Expr:
    """Flamant's stress function for a unit line load, phi = -(1/pi) x atan(x/z)."""
    return -x * sp.atan(x / _z) / sp.pi


@cache
def flamant() -> dict[str, sp.Expr]:
    """sigma_xx, sigma_zz, tau_xz of a line load F_L [N/m] at the origin, pushing in +z."""
    phi = F_L * airy()
    out = {"xx": sp.diff(phi, _z, 2), "zz": sp.diff(phi, x, 2), "xz": -sp.diff(phi, x, _z)}
    return {k: sp.factor(sp.simplify(v)).subs(_z, z) for k, v in out.items()}


@cache
def axis_stresses() -> dict[str, sp.Expr]:
    """sigma_zz, sigma_xx on x = 0 under p0 (1 - s^2/a^2)^(1/2): Flamant superposed."""
    out = {}
    for comp in ("zz", "xx"):
        # source at s = a sin(theta) = a t/(1 + t^2)^(1/2): field minus source X = -s;
        # p ds = p0 a cos^2(theta) d(theta) = p0 a dt/(1 + t^2)^2
        k = flamant()[comp].subs({F_L: 1, z: _z}).subs(x, -a * _t / sp.sqrt(1 + _t**2))
        integrand = sp.factor(sp.simplify(k * p0 * a / (1 + _t**2) ** 2))
        tp = sp.Symbol("t_pos", positive=True)  # even in t: twice the integral over t > 0
        terms = sp.Add.make_args(sp.apart(integrand.subs(_t, tp), tp))
        val = sum(2 * sp.integrate(term, (tp, 0, sp.oo)) for term in terms)
        out[comp] = sp.simplify(val).subs(_z, z)
    return out


def axis_sigma_xx_stable() -> sp.Expr:
    s = sp.sqrt(a**2 + z**2)
    return -p0 * a**3 / (s * (s + z) ** 2)


def axis_max_shear() -> sp.Expr:
    """tau_1 = (sigma_xx - sigma_zz)/2 on the axis (tau_xz = 0 there), cancellation-free."""
    tau = (axis_sigma_xx_stable() - axis_stresses()["zz"]) / 2
    return sp.factor(sp.simplify(tau))


def plane_strain_sigma_yy() -> sp.Expr:
    """sigma_yy from eps_yy = (sigma_yy - nu (sigma_xx + sigma_zz))/E = 0."""
    E = symbol("E")
    (sol,) = sp.solve(sp.Eq((syy - nu * (sxx + szz)) / E, 0), syy)
    return sol


def axis_von_mises() -> sp.Expr:
    vm, _ = ds.von_mises()
    s = axis_stresses()
    sig_x, sig_z = axis_sigma_xx_stable(), s["zz"]
    sig_y = plane_strain_sigma_yy().subs({sxx: sig_x, szz: sig_z})
    zero = symbol("tau_xy", real=True), symbol("tau_yz", real=True), sxz
    return vm.subs({sxx: sig_x, syy: sig_y, szz: sig_z, **dict.fromkeys(zero, 0)})


def axis_von_mises_stable() -> sp.Expr:
    """With c = (sigma_xx + sigma_zz)/2, sigma_yy = 2 nu c: sigma_vM^2 = (1 - 2 nu)^2 c^2
    + 3 tau_1^2, a sum of squares (the expanded (5.50) cancels, entirely at the surface for
    nu = 1/2)."""
    c = (axis_sigma_xx_stable() + axis_stresses()["zz"]) / 2
    return sp.sqrt((1 - 2 * nu) ** 2 * c**2 + 3 * axis_max_shear() ** 2)


def von_mises_plane_strain() -> tuple[sp.Expr, sp.Expr]:
    """(5.50) with tau_xy = tau_yz = 0 and sigma_yy = nu (sigma_xx + sigma_zz), and its form
    ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2), c = (sigma_xx + sigma_zz)/2: a sum of squares."""
    vm, _ = ds.von_mises()
    zero = symbol("tau_xy", real=True), symbol("tau_yz", real=True)
    derived = vm.subs({syy: plane_strain_sigma_yy(), **dict.fromkeys(zero, 0)})
    c = (sxx + szz) / 2
    stable = sp.sqrt((1 - 2 * nu) ** 2 * c**2 + 3 * ((sxx - szz) ** 2 / 4 + sxz**2))
    return derived, stable


def principal_in_plane() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Largest, smallest principal stress in the x-z plane and tau_1 = their half-difference."""
    ev = list(sp.Matrix([[sxx, sxz], [sxz, szz]]).eigenvals())
    probe = {sxx: 1, szz: 0, sxz: 1}
    hi, lo = sorted(ev, key=lambda e: -float(e.subs(probe)))
    tau1 = sp.sqrt(sp.factor(sp.expand((hi - lo) ** 2 / 4)))
    return hi, lo, tau1


def _radius() -> sp.Expr:
    """Mohr's circle radius ((sigma_xx - sigma_zz)^2/4 + tau_xz^2)^(1/2): a sum of squares."""
    return sp.sqrt((sxx - szz) ** 2 / 4 + sxz**2)


_WHY_RADIUS = ("the eigenvalues' expanded discriminant sigma_xx^2 - 2 sigma_xx sigma_zz + "
               "sigma_zz^2 + 4 tau_xz^2 rounds below 0 where sigma_xx = sigma_zz (the loaded "
               "surface: sqrt gives NaN); Mohr's radius ((sigma_xx - sigma_zz)^2/4 + "
               "tau_xz^2)^(1/2) is a sum of squares")


@cache
def cauchy() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """F, F', F'' of the semi-ellipse, with (zeta^2 - a^2)^(1/2) = n + i m."""
    zeta = x + sp.I * _z
    root = _n + sp.I * _m
    k = sp.pi * p0 / a
    return k * (zeta - root), k * (1 - zeta / root), k * a**2 / root**3


def _re_im(e: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    re, im = sp.expand_complex(e).as_real_imag()
    return sp.simplify(re), sp.simplify(im)


@cache
def field_mn() -> dict[str, sp.Expr]:
    """The field in (m, n, z) from F: Johnson's form (x = m n/z eliminated)."""
    F, Fp, _ = cauchy()
    im_F = _re_im(F)[1]
    re_Fp, im_Fp = _re_im(Fp)
    total = 2 / sp.pi * im_F  # sigma_xx + sigma_zz
    diff = -2 / sp.pi * _z * re_Fp  # sigma_zz - sigma_xx
    tau = -_z * im_Fp / sp.pi
    elim = {x: _m * _n / _z}
    out = {"zz": (total + diff) / 2, "xx": (total - diff) / 2, "xz": tau}
    return {k: sp.factor(sp.simplify(v.subs(elim))) for k, v in out.items()}


def field_stable_mn() -> dict[str, sp.Expr]:
    """The same field as sums of positive terms in m, n, g = m^2 - z^2, h = m - z."""
    D = _m**2 + _n**2
    return {"zz": -p0 / a * _m * _g / D, "xx": -p0 / a * _h * (_m * _h + 2 * _n**2) / D,
            "xz": -p0 / a * _n * _g / D}


def tau1_stable_mn() -> sp.Expr:
    """tau_1 = (((sigma_xx - sigma_zz)/2)^2 + tau_xz^2)^(1/2) of :func:`field_stable_mn`.

    With g = m^2 - z^2 and h = m - z, SymPy factors its square into
    (p0/a)^2 h^2 (n^2 + z^2)/(m^2 + n^2) (checked here), so
    tau_1 = (p0/a) h ((n^2 + z^2)/D)^(1/2), D = m^2 + n^2: a product of positive terms. The
    route through the components subtracts sigma_zz from sigma_xx, which are both ~ -p0 near
    the surface under the contact where tau_1 ~ z/b (the von Mises stress at nu = 1/2 lost
    digits in proportion).
    """
    f = field_stable_mn()
    sq = ((f["xx"] - f["zz"]) / 2) ** 2 + f["xz"] ** 2
    sq = sq.subs({_h: _m - z, _g: (_m - z) * (_m + z)})
    D = _m**2 + _n**2
    target = (p0 / a) ** 2 * (_m - z) ** 2 * (_n**2 + z**2) / D
    if sp.simplify(sp.factor(sq) - target) != 0:  # pragma: no cover - an identity
        raise AssertionError("tau_1^2 does not factor as (p0/a)^2 h^2 (n^2 + z^2)/D")
    return p0 / a * _h * sp.sqrt((_n**2 + z**2) / D)


def johnson_mn() -> dict[str, sp.Expr]:
    """Johnson (1985, ch. 4; McEwen 1949) as printed there, in this module's sign of tau_xz."""
    k = (_z**2 + _n**2) / (_m**2 + _n**2)
    return {"xx": -p0 / a * (_m * (1 + k) - 2 * _z), "zz": -p0 / a * _m * (1 - k),
            "xz": -p0 / a * _n * (_m**2 - _z**2) / (_m**2 + _n**2)}


def regions() -> dict[str, dict[sp.Symbol, sp.Expr]]:
    """m, n, g, h in (a, x, z) for x >= 0, cancellation-free in each region."""
    q = (a - x) * (a + x) + z**2
    D = sp.sqrt(q**2 + 4 * x**2 * z**2)
    e = (x - a) * (x + a) + z**2
    m_q = sp.sqrt((D + q) / 2)  # q >= 0
    n_q = sp.sqrt((D - q) / 2)  # q < 0
    g_out = 2 * a**2 * z**2 / (D + e)
    core = {_m: m_q, _n: x * z / m_q}
    core[_g] = (a - x) * (a + x) + core[_n] ** 2
    deep = {_m: m_q, _n: x * z / m_q, _g: g_out}
    side = {_m: x * z / n_q, _n: n_q, _g: g_out}
    for reg in (core, deep, side):
        reg[_h] = reg[_g] / (reg[_m] + z)
    return {"core": core, "deep": deep, "side": side}


def field(region: str) -> dict[str, sp.Expr]:
    reg = regions()[region]
    return {k: v.subs(reg, simultaneous=True) for k, v in field_stable_mn().items()}


def tau_xz_gradient() -> tuple[sp.Expr, sp.Expr]:
    """d(tau_xz)/dx = -(z/pi) Im F'', d(tau_xz)/dz = -(Im F' + z Re F'')/pi, for q >= 0."""
    _, Fp, Fpp = cauchy()
    re_pp, im_pp = _re_im(Fpp)
    im_p = _re_im(Fp)[1]
    reg = regions()["deep"]
    mn = {_m: reg[_m], _n: reg[_n]}
    gx = (-_z * im_pp / sp.pi).subs(_z, z).subs(mn, simultaneous=True)
    gz = (-(im_p + _z * re_pp) / sp.pi).subs(_z, z).subs(mn, simultaneous=True)
    return gx, gz


def relations() -> list[Relation]:
    fl = flamant()
    s = axis_stresses()
    tau = axis_max_shear()
    vm = axis_von_mises()
    vm_st = axis_von_mises_stable()
    vm_ps = von_mises_plane_strain()
    hi, lo, tau1 = principal_in_plane()
    gx, gz = tau_xz_gradient()
    origin_fl = "the Airy function phi = -(P/pi) x atan(x/z) of a line load"
    rels = []
    for comp, what in (("xx", "normal stress sigma_xx"), ("zz", "normal stress sigma_zz"),
                       ("xz", "shear stress tau_xz")):
        rels.append(Relation(
            f"flamant_{'tau' if comp == 'xz' else 'sigma'}_{comp}",
            "Flamant (2-D Boussinesq)", fl[comp], (F_L, x, z),
            f"{what} [Pa] at (x, z) of a line load F_L [N/m] at the origin pushing into the "
            "half-plane z > 0 (plane strain, tension positive)", origin_fl,
            f"{TEST}::test_flamant_is_an_elastic_field"))
    ax = f"{TEST}::test_axis_stresses_by_superposition"
    sup = "Flamant superposed over the line pressure (5.36) along the axis x = 0"
    rels += [
        Relation("line_stress_axis_sigma_zz", "(5.36), Flamant", s["zz"], (a, p0, z),
                 "normal stress sigma_zz [Pa] on the axis of a line contact of half-width a",
                 sup, ax),
        Relation("line_stress_axis_sigma_xx", "(5.36), Flamant", s["xx"], (a, p0, z),
                 "normal stress sigma_xx [Pa] on the axis of a line contact of half-width a",
                 sup, ax, stable=axis_sigma_xx_stable(),
                 stable_why="the derived form subtracts terms of size z/a to leave one of "
                 "size (a/z)^3; -p0 a^3/(s (s + z)^2), s = (a^2 + z^2)^(1/2), has none"),
        Relation("line_stress_axis_max_shear", "(5.36), Flamant", tau, (a, p0, z),
                 "principal shear stress tau_1 = (sigma_xx - sigma_zz)/2 [Pa] on the axis of "
                 "a line contact", "the axis stresses",
                 f"{TEST}::test_axis_maxima_by_superposition"),
        Relation("line_stress_axis_max_shear_slope", "(5.36), Flamant", sp.diff(tau, z),
                 (a, p0, z), "d(tau_1)/dz [Pa/m] on the axis of a line contact; its root is "
                 "the depth of the largest tau_1", "the derivative of tau_1",
                 f"{TEST}::test_axis_maxima_by_superposition"),
        Relation("line_stress_axis_von_mises", "(5.50), (5.36)", vm, (a, nu, p0, z),
                 "von Mises stress [Pa] on the axis of a line contact (plane strain)",
                 "(5.50) with the axis stresses and sigma_yy = nu (sigma_xx + sigma_zz)",
                 f"{TEST}::test_axis_maxima_by_superposition", stable=vm_st,
                 stable_why="(5.50) expanded subtracts squares of size p0^2; with c = "
                 "(sigma_xx + sigma_zz)/2 it is ((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2)"),
        Relation("line_stress_axis_von_mises_slope", "(5.50), (5.36)", sp.diff(vm_st, z),
                 (a, nu, p0, z), "d(sigma_vM)/dz [Pa/m] on the axis of a line contact; its "
                 "root is the depth of the largest von Mises stress", "the derivative",
                 f"{TEST}::test_axis_maxima_by_superposition"),
        Relation("line_stress_sigma_yy", "plane strain", plane_strain_sigma_yy(),
                 (nu, sxx, szz), "out-of-plane stress sigma_yy [Pa] in plane strain",
                 "eps_yy = (sigma_yy - nu (sigma_xx + sigma_zz))/E = 0",
                 f"{TEST}::test_plane_strain_and_principal_stresses"),
        Relation("line_stress_von_mises", "(5.50), plane strain", vm_ps[0],
                 (nu, sxx, szz, sxz), "von Mises stress [Pa] of a plane-strain state "
                 "(sigma_yy = nu (sigma_xx + sigma_zz), tau_xy = tau_yz = 0)",
                 "(5.50) with the plane-strain sigma_yy",
                 f"{TEST}::test_plane_strain_and_principal_stresses", stable=vm_ps[1],
                 stable_why="(5.50) expanded subtracts products of size p0^2 (it goes "
                 "negative at the surface for nu = 1/2, where it is 0); "
                 "((1 - 2 nu)^2 c^2 + 3 tau_1^2)^(1/2), c = (sigma_xx + sigma_zz)/2, has "
                 "only squares"),
        Relation("line_stress_principal_max", "plane stress state x-z", hi, (sxx, szz, sxz),
                 "largest principal stress [Pa] in the x-z plane",
                 "eigenvalues of the 2x2 stress tensor",
                 f"{TEST}::test_plane_strain_and_principal_stresses",
                 stable=(sxx + szz) / 2 + _radius(), stable_why=_WHY_RADIUS),
        Relation("line_stress_principal_min", "plane stress state x-z", lo, (sxx, szz, sxz),
                 "smallest principal stress [Pa] in the x-z plane",
                 "eigenvalues of the 2x2 stress tensor",
                 f"{TEST}::test_plane_strain_and_principal_stresses",
                 stable=(sxx + szz) / 2 - _radius(), stable_why=_WHY_RADIUS),
        Relation("line_stress_principal_shear", "plane stress state x-z", tau1,
                 (sxx, szz, sxz), "principal shear stress tau_1 [Pa] in the x-z plane",
                 "half the difference of the principal stresses",
                 f"{TEST}::test_plane_strain_and_principal_stresses",
                 stable=_radius(), stable_why=_WHY_RADIUS),
    ]
    where = {"core": "x^2 + z^2 <= a^2", "deep": "x^2 + z^2 > a^2 and x^2 <= a^2 + z^2",
             "side": "x^2 > a^2 + z^2"}
    lit = ("Flamant superposed over (5.36) by the Cauchy integral of the pressure (McEwen's "
           "m, n), in positive terms")
    for region in ("core", "deep", "side"):
        fld = field(region)
        for comp, what in (("xx", "normal stress sigma_xx"), ("zz", "normal stress sigma_zz"),
                           ("xz", "shear stress tau_xz")):
            name = f"line_stress_{'tau' if comp == 'xz' else 'sigma'}_{comp}_{region}"
            rels.append(Relation(
                name, "(5.36), Flamant", fld[comp], (a, p0, x, z),
                f"{what} [Pa] at (x, z) under the line pressure of half-width a, for x >= 0 "
                f"and {where[region]}", lit, f"{TEST}::test_field_by_superposition"))
        rels.append(Relation(
            f"line_stress_tau_1_{region}", "(5.36), Flamant",
            tau1_stable_mn().subs(regions()[region], simultaneous=True), (a, p0, x, z),
            f"principal shear stress tau_1 [Pa] in the x-z plane at (x, z) under the line "
            f"pressure of half-width a, for x >= 0 and {where[region]}",
            lit + "; tau_1^2 factored", f"{TEST}::test_tau_1_by_superposition"))
    rels += [
        Relation("line_stress_von_mises_c_tau", "(5.50), plane strain", vm_ps[1].subs(
            {sxx: _c + _t1, szz: _c - _t1, sxz: 0}), (nu, _c, _t1),
                 "von Mises stress [Pa] of a plane-strain state from its mean in-plane "
                 "stress c = (sigma_xx + sigma_zz)/2 and tau_1",
                 "line_stress_von_mises with sigma_xx, sigma_zz = c +- tau_1, tau_xz = 0 "
                 "(the same Mohr circle)", f"{TEST}::test_tau_1_by_superposition"),
        Relation("line_stress_tau_xz_slope_x", "(5.36), Flamant", gx, (a, p0, x, z),
                 "d(tau_xz)/dx [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2",
                 "-(z/pi) Im F'' of the Cauchy integral F of the pressure",
                 f"{TEST}::test_orthogonal_shear_maximum"),
        Relation("line_stress_tau_xz_slope_z", "(5.36), Flamant", gz, (a, p0, x, z),
                 "d(tau_xz)/dz [Pa/m] under the line pressure, x >= 0, x^2 <= a^2 + z^2",
                 "-(Im F' + z Re F'')/pi of the Cauchy integral F of the pressure",
                 f"{TEST}::test_orthogonal_shear_maximum"),
    ]
    return rels
