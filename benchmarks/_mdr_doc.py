"""The parts of docs/mdr.md that are not measurements: the MDR's derived relations (from the
generated RELATIONS table) and what the tests verify them against. Used by bench_mdr.py."""

from __future__ import annotations

from hertzmdr.numeric import _generated as gen

FAMILIES = ("powerlaw", "worn", "kink", "numerical_mdr")


def derivations_section() -> str:
    """One row per generated MDR relation: its chapter equation, what it returns, its form."""
    out = ["## Derivations\n\n",
           "Every relation below is derived by SymPy from the MDR steps of "
           "`hertzmdr.derive.mdr` (the transform (5.52) with r = x t, d = g(a) (5.55), the force "
           "(5.57), the pressure (5.59), the displacement (5.60), the line load (5.61)) applied "
           "to the profile, and printed into `numeric/_generated.py`; the derivation of each, "
           "with the printed form and its reason where one is given, is in "
           "[derivations.md](derivations.md). Pressures with an extra square-root branch "
           "point (the worn tip's edge, any kink of f) come out of "
           "`mdr.elliptic_abel_integral` in Legendre's F(phi|m), E(phi|m). "
           "`hertzmdr.derive.mdr.solve(f, r)` runs the same steps on a user's SymPy profile and "
           "reports those without a closed form.\n\n",
           "| function | chapter | returns | derived form |\n| --- | --- | --- | --- |\n"]
    for name, eq, fam, expr, _ in gen.RELATIONS:
        if fam not in FAMILIES:
            continue
        summary = getattr(gen, name).__doc__.strip().splitlines()[0].rstrip(".").replace("|", "\\|")
        form = expr if len(expr) <= 90 else expr[:87] + "..."
        out.append(f"| `{name}` | {eq} | {summary} | `{form}` |\n")
    return "".join(out) + "\n"


def verification_section() -> str:
    """What each check compares, by which independent route, and where it lives."""
    rows = [
        ("kappa_n, n in [0.1, 1e6]", "quadrature of (5.52) at 30 digits",
         "tests/test_powerlaw.py::test_kappa_by_quadrature"),
        ("MDR pressure through the Boussinesq integral (5.7), n = 1, 2, 3, 4, punch",
         "2-D mpmath quadrature about the field point reproduces d - f(r) inside and (5.60) "
         "outside", "tests/test_powerlaw.py::test_against_3d_elasticity"),
        ("worn parabola (Problem 8) through (5.7)",
         "the closed-form pressure, 2-D quadrature about the axis (one pressure evaluation a "
         "ring), at 30 digits: d - f(r) on the flat, at the kink, on the parabola, at the rim; "
         "the derived (5.60) outside", "tests/test_worn.py::test_against_3d_elasticity"),
        ("worn pressure, kink pressure", "(5.59) by 30-digit quadrature of the derived g'",
         "tests/test_worn.py, tests/test_kink.py"),
        ("integral of p 2 pi r dr = (5.57)", "quadrature of the pressure",
         "tests/test_powerlaw.py::test_force_by_pressure, "
         "tests/test_worn.py::test_force_by_closed_form_pressure"),
        ("(5.53)(5.52) and (5.61)(5.59) are the identity", "symbolically, for c r^n with "
         "symbolic n and for any f(0) = 0 / q(a) = 0 (order exchanged, kernel pi/2); "
         "numerically for sampled profiles", "tests/test_mdr.py::test_roundtrips_symbolic_any_n, "
         "::test_numeric_roundtrips"),
        ("power-law pressure at any n", "(5.59) by 30-digit quadrature, n = 0.2 ... 1e8",
         "tests/test_powerlaw.py::test_general_n_pressure_forms, "
         "::test_pressure_large_n_by_quadrature"),
        ("numerical MDR of samples (smooth, kinked, noisy)", "the closed forms and 30-digit "
         "quadrature of (5.59); the error estimate bounds the error", "tests/test_mdr.py"),
        ("the splines as piecewise polynomials (Taylor coefficients per knot interval, what "
         "the engine evaluates)", "scipy's B-spline evaluation (f, f', f'')",
         "tests/test_mdr_engine.py"),
        ("`mdr_force` (5.57) from the integral of g", "the pressure of (5.59), by quadrature, "
         "integrated over the disc at 30 digits",
         "tests/test_mdr.py::test_mdr_force_by_the_pressure"),
        ("every error bound of the numerical MDR of samples (force-depth curve, force, contact "
         "radius, depth under force control, pressure, displacement, g): a sphere, a sphere "
         "on a cone with and without its kink as a breakpoint, a cone, issue 12's sphere-cone "
         "tip at 10, 50, 100 nm", "30-digit quadratures of (5.52), (5.57), (5.59) (order "
         "exchanged: an incomplete elliptic kernel) and (5.60) of the profile the samples come "
         "from; fails when a bound is below the actual error", "tests/test_mdr_bounds.py"),
        ("`RTOL_RANGE[0]`, what the refinement reaches", "callables of five profiles (smooth, "
         "kinked, sphere-cone with and without its tangent point as a breakpoint) meet it at "
         "two depths", "tests/test_mdr.py::test_rtol_range_lower_end"),
        ("the vectorized force-depth curve (301 depths in any order, 0 among them) and its "
         "stiffness dF/dd = 2 E* a (5.12)", "the power law's closed forms at every depth (the "
         "bound holds), each depth's own solve (equal), central differences of the curve "
         "(the stiffness)",
         "tests/test_mdr.py::test_force_depth_curve_vectorized_bounds_every_depth"),
    ]
    out = ["## Verification\n\n| what | against | test |\n| --- | --- | --- |\n"]
    out += [f"| {a} | {b} | `{c}` |\n" for a, b, c in rows]
    return "".join(out) + "\n" + CONTRACT + AXIS_BOUND + SMOOTHING_BOUND


CONTRACT = """### The accuracy contract of the numerical MDR

`rtol` has one meaning in `hertzmdr.numeric.mdr`: the target of the relative error bound
`Solution.rel_error` (force, contact radius and depth), default `mdr.DEFAULT_RTOL` = 1e-8,
accepted in `mdr.RTOL_RANGE` = (1e-11, 1e-2); outside it `Profile.solve` and
`Profile.force_depth_curve` raise a ValueError naming rtol and the range. The lower end is
measured: the bound that the grid refinement of a callable reaches (up to 8192 intervals a
segment) for smooth, kinked and sphere-cone profiles is 2.5e-13 to 1.0e-11. The upper end is
where the bound, a linearization of the difference between two resolutions, stops being tested.
A callable's grid is doubled until the bound meets rtol; a sampled profile cannot be refined
past its samples, so its quadrature is refined while that lowers the bound. The solution says
whether the target was met (`met`) and, if not, why (`why_not_met`, e.g. "a sampled profile
cannot be refined past its 51 samples; its estimate is ... with 8 Gauss points a panel").

The bound is the larger of the coarse-vs-fine differences (every other sample, or half the grid)
and the envelope of the differences of g and of its integral on radii within two coarse sample
spacings of a, put through the linearized (5.55) and (5.57) (the differences at a alone can
vanish by accident), plus a rounding floor (64 + 4 N) eps. `python tests/test_mdr_bounds.py`
prints every bound next to its actual error against 30-digit references. At given depths
(`solve(depth=...)`, `force_depth_curve`) g, g' and the integral of g come from the tables
(quintic splines of the quadrature's values, computed as far as the contact radius needs), so
their interpolation error is part of both representations' values and of the bound; a depth
whose bound misses rtol by at most `mdr.NEAR` (30) is solved again by quadrature, without
tables (the finest callable grids, whose bound near `RTOL_RANGE[0]` the tables would limit).

### Two (5.59) engines, on purpose

`numeric/abel.py` (from samples of the line load) and the numerical MDR's pressure
(`numeric/_mdr/operators.py`) both evaluate (5.59). The first must be a linear operator on
samples of q on a uniform grid, cached as a matrix and reused for every row and call: it
integrates the derivative of a piecewise polynomial in s = x^2 exactly against the kernel and
loses about log10(N) digits to differentiating samples. The second has g' itself: its smooth
remainder tabulated in x or sqrt(x - b), graded towards the axis and the kinks, and the kinks'
branch-point terms in closed form (the generated `mdr_kink_pressure`), with a contact radius
anywhere and an error bound from a second representation. Routing it through the Abel operator
would resample q on a grid ending at a and differentiate it again, losing the closed-form kink
terms and the grading. They share the Gauss-Legendre rule (`numeric/_quadrature.py`) and the
substitution that removes the kernel's singularity.

"""


#: the smoothed profiles' bound (the defect it fixed, 2026-11-27)
SMOOTHING_BOUND = (
    "\n**The bound of a profile smoothed from noisy samples.** Until 2026-11-27 "
    "(`smoothing=\"gcv\"`) it could be below its error: for r^2/2 on 401 samples with noise "
    "of 5e-7 the force was 5.1e-4 off Hertz and `rel_error` 2.9e-4 (found by the mutation run "
    "of `_mdr`). Two causes. The smoothing spline is natural (s'' = 0 at its ends), which at "
    "the axis bent the profile: s(0) was 8.5e-5 below f(0) and s'(0) = 0.013. And the bound "
    "compared two representations both smoothed, which shared that bias. Now the segment from "
    "the axis is smoothed with its mirror image f(-r) = f(r) (the force errors of the "
    "noisy-samples table below fell 3 to 50,000 times: at N = 400 and noise 1e-6, from 5.1e-4 "
    "to 1.0e-6), and the bound adds "
    "the smoothing's own error: with eps the largest residual |f_i - s(r_i)| inside the "
    "contact, |dF| <= 2 E* a eps (a profile between s - eps and s + eps gives a force between "
    "those at d - eps and d + eps), |dd| <= eps at a given force, and 2 eps / (a g'(a)) for "
    "the contact radius (`numeric/_mdr/solve.py::smoothing`). The residual holds the noise "
    "too, so the bound overstates the error 6 to 73 times in that table. "
    "`tests/test_mdr.py::test_noisy_samples_bound_covers_the_error` checks force, contact "
    "radius, depth and g against Hertz on three draws of the noise.\n")

#: how the pressure's bound handles an order below 1 (the defect it fixed, 2026-11-27)
AXIS_BOUND = (
    "\n**The pressure's bound where the splines converge slowly.** For a sampled profile whose "
    "f grows as r^n with 1 < n < 2 at the axis, the splines' error in p(0) falls only as "
    "h^(n-1), below the order 1 at which the coarse-vs-fine difference bounds the fine error. "
    "Until 2026-11-27 it did not: for f = c r^1.5 on 400 samples, "
    "`Solution.pressure(0, return_error=True)` was 8.3 % off the closed form and its bound "
    "0.63 times that (found by the mutation run of that day). The bound now measures the order "
    "from a third resolution (every other knot of the coarse one, `Rep.halved`): where the "
    "two differences fall by a factor rho between 1 and 2, it is difference / (rho - 1), "
    "Richardson's estimate; at the axis that is 2.2 (n = 1.5) and 4.0 (n = 1.2) times the "
    "error, at r = a/2 unchanged. Where the differences neither shrink nor change sign and "
    "exceed 1e-6 of the mean pressure (`mdr.STALLED`; the quadratures' own noise is 1e-10 to "
    "1e-9 of it), p has not converged and its bound is +inf: f = 2 r^1.2 on 41 samples, whose "
    "p(0) is 68 % off. `tests/test_mdr.py::test_pressure_bound_on_the_axis_of_a_sampled_power_law` "
    "checks it against the closed form at a depth and at a force, and "
    "`test_pressure_bound_covers_power_laws_sampled_coarsely_and_finely` at 61 radii for "
    "n from 1.05 to 3.5 and 21 to 1001 samples (72 cases with HERTZMDR_SWEEP=full, 5 in CI): "
    "covered everywhere, at least 1.2 times.\n")
