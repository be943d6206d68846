"""``python -m hertzmdr.numeric.demo``: the derived Hertz-family relations, and Problem 1.

Prints each derived relation of the Hertz chapter's families with its equation number (marking
those where the derivation disagrees with the chapter's print, see docs/errata.md), then works
Problem 1 of the chapter (the rail-wheel contact) with the chapter's numbers through the
numeric API. ``make demo`` runs it.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

WIDTH, EQ = 100, 16  # characters of an expression line, of its equation column

#: the families of the Hertz chapter shown by default (others with --family or --all)
DEFAULT_FAMILIES = ("pressures", "hertz", "bodies", "line", "cone", "impact")

parser = argparse.ArgumentParser(
    prog="python -m hertzmdr.numeric.demo",
    description="Print the derived Hertz-family relations with their equation numbers and "
    "work Problem 1 (rail-wheel contact) of the chapter.",
)
parser.add_argument("--family", action="append", metavar="NAME",
                    help="print only this family (repeatable), e.g. --family hertz")
parser.add_argument("--all", action="store_true", help="print every family")
parser.add_argument("--no-relations", action="store_true",
                    help="skip the relations, work Problem 1 only")


def print_relations(families: list[str] | None, out=sys.stdout) -> int:
    """Print the relations of ``families`` (all if None); return how many were printed.

    They come from the table the generator writes into ``_generated.py`` (``RELATIONS``), so
    this listing needs no SymPy and no derivation at run time."""
    import inspect

    from hertzmdr.numeric import _generated as gen

    relations = [r for r in gen.RELATIONS if families is None or r[2] in families]
    count = 0
    for fam in sorted({r[2] for r in relations}):
        print(f"\n== hertzmdr.derive.{fam} ==", file=out)
        for name, equation, family, formula, erratum in relations:
            if family != fam:
                continue
            flag = "!" if erratum else " "
            args = ", ".join(inspect.signature(getattr(gen, name)).parameters)
            text = f"{name}({args}) = {formula}"
            if len(text) > WIDTH:
                text = text[: WIDTH - 1] + "…"
            eq = equation.split(",")[0][:EQ]  # the leading equation number
            print(f"{flag}{eq:<{EQ}} {text}", file=out)
            count += 1
    print("\n! the derivation differs from the chapter's print (docs/errata.md); long "
          "expressions are cut (…): docs/derivations.md has them whole.", file=out)
    return count


def problem1(out=sys.stdout) -> dict[str, float]:
    """Problem 1: rail-wheel contact, two steel cylinders R = 0.5 m crossed at 90 deg, 1e5 N."""
    from hertzmdr.numeric import bodies, hertz

    E, nu, R_wheel, F = 210e9, 0.3, 0.5, 1e5
    E_star = bodies.effective_modulus(E, nu, E, nu)  # (5.26)
    R_1, R_2 = bodies.crossed_cylinder_radii(R_wheel, R_wheel, np.pi / 2)  # (5.32)
    R = bodies.gaussian_radius(R_1, R_2)  # (5.33): equal radii at 90 deg = a sphere
    p0 = hertz.max_pressure_from_force(F, R, E_star)  # (5.24)
    a = hertz.contact_radius_from_force(F, R, E_star)  # (5.24)
    d = hertz.depth_from_force(F, R, E_star)  # (5.23)
    print("\n== Problem 1: rail-wheel contact ==", file=out)
    print(f"  steel on steel, E = {E:.3g} Pa, nu = {nu}; wheel and rail R = {R_wheel} m, "
          f"crossed at 90 deg; F = {F:.3g} N", file=out)
    rows = [("E*", f"{E_star:.4g} Pa", "(5.26)", "chapter: ~1.2e11 Pa"),
            ("R", f"{R:.4g} m", "(5.33)", f"principal radii of the gap {R_1:.4g} m, {R_2:.4g} m"),
            ("p0", f"{p0 / 1e9:.4g} GPa", "(5.24)", "chapter: ~1.0 GPa"),
            ("a", f"{a * 1e3:.4g} mm", "(5.24)", "chapter: ~6.8 mm"),
            ("d", f"{d * 1e6:.4g} um", "(5.23)", "")]
    for name, value, eq, note in rows:
        print(f"  {name:<3} = {value:<14} {eq}  {note}", file=out)
    return {"E_star": float(E_star), "R": float(R), "p0": float(p0), "a": float(a),
            "d": float(d)}


def main(argv: list[str] | None = None) -> int:
    args = parser.parse_args(argv)
    if not args.no_relations:
        families = None if args.all else (args.family or list(DEFAULT_FAMILIES))
        n = print_relations(families)
        print(f"\n{n} relations; each is verified by the test its docstring names "
              "(numeric/_generated.py, docs/derivations.md).")
    problem1()
    return 0


if __name__ == "__main__":
    sys.exit(main())
