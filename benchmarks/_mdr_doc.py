"""The parts of docs/mdr.md that are not measurements: the MDR's derived relations (from the
generated RELATIONS table) and what the tests verify them against. Used by bench_mdr.py."""

from __future__ import annotations

from hertzmdr.numeric import _generated as gen

FAMILIES = ("powerlaw", "worn", "kink")


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
    ]
    out = ["## Verification\n\n| what | against | test |\n| --- | --- | --- |\n"]
    out += [f"| {a} | {b} | `{c}` |\n" for a, b, c in rows]
    return "".join(out) + "\n"
