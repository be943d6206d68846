"""Write docs/sphere.md: the exact sphere's relations and the bias of Hertz's paraboloid.

    python benchmarks/sphere_bias.py [--out docs/sphere.md] [--no-figure]

Every number comes from :mod:`hertzmdr.numeric.sphere` and :mod:`hertzmdr.numeric.hertz`
(float64, accurate to ~1e-15 as tests/test_sphere.py shows); nothing is timed.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from hertzmdr.numeric import hertz, sphere

BETAS = (0.01, 0.1, 0.3, 0.5, 0.9)

PROSE = """\
# The exact sphere (Sneddon's sphere)

<!-- Written by `benchmarks/sphere_bias.py`; no timings, every number from hertzmdr.numeric. -->

Hertz's theory (5.15)-(5.25) replaces a sphere of radius R by the paraboloid r^2/(2R), which
is good while the contact radius a is small against R. `hertzmdr.numeric.sphere` takes the
spherical cap itself, f(r) = R - sqrt(R^2 - r^2), through the MDR (5.52)-(5.60), which makes
it exact at any depth: the contact radius stays below R (a -> R as d -> inf).

## Relations

Derived by SymPy in `hertzmdr.derive.sphere` (printed forms and proofs in
[derivations.md](derivations.md)); b = a/R, lam = atanh(a/R).

| quantity | relation | chapter |
| --- | --- | --- |
| MDR profile | g(x) = x atanh(x/R) = (x/2) ln((R + x)/(R - x)) | (5.52) |
| depth | d = a atanh(a/R) = R lam tanh(lam) | (5.55) |
| force | F = E* ((a^2 + R^2) atanh(a/R) - a R) = E* R^2 ((1 + b^2) lam - b) | (5.57) |
| stiffness | dF/dd = 2 a E* | Problem 5 |
| pressure | p(r) = (E*/pi) [(R/c) atanh(k/c) + integral_0^k atanh(x/R)/x dw], see below | (5.59) |
| outside | u(r) = (2/pi) integral_0^a (d - g(x))/sqrt(r^2 - x^2) dx, r > a | (5.60) |

In the pressure, c^2 = R^2 - r^2, k^2 = a^2 - r^2 and x^2 = r^2 + w^2.
The contact radius at a given depth and the depth at a given force have no closed form: the
code solves for lam by bisection from a proven bracket. The second term of the pressure has
no elementary antiderivative (at the centre it is Legendre's chi_2(a/R), a dilogarithm) and
(5.60)'s closed form cancels catastrophically (far from the contact and for shallow contacts),
so both are integrated by Gauss-Legendre panels graded toward their singularities.
Float64 results are within a few ulps of 30-digit references from the cap's profile over
a/R = 1e-8 ... 1 - 1e-10 (`tests/test_sphere.py`); the pressure put through the Boussinesq
integral (5.7) gives back d - f(r) inside the contact to 25 digits.

Printed on purpose: atanh(x/R) as log1p(2x/(R - x))/2 (R - x is exact near R, log1p near 0);
the force's (1 + b^2) atanh(b) - b, which cancels as b^2, through 2F1(1, 3/2; 5/2; b^2) below
b = 1/2; everything depth-controlled in lam, since a float64 a no longer determines atanh(a/R)
near R (at a/R = 1 - 1e-12 one rounding of a moves it by 5e-5).

## The bias of the paraboloid

Relative deviations of Hertz from the exact sphere. At the same depth d (what a
force-depth fit compares):
the contact radius sqrt(R d) and the force (4/3) E* R^(1/2) d^(3/2) are too large, so a
Hertz fit of the modulus to exact-sphere force-depth data returns E* F/F_Hertz, too small.
At the same force, Hertz predicts a shallower indentation. For small a/R the deviations are
a_Hertz/a - 1 = b^2/6 + ... and F_Hertz/F - 1 = b^2/10 + ... (from a/a_H = 1 - b^2/6 - 7b^4/120
and F/F_H = 1 - b^2/10 - 29b^4/840, checked in `tests/test_sphere.py::test_hertz_limit`).

"""


def table() -> str:
    R, E = 1.0, 1.0
    b = np.array(BETAS)
    a = b * R
    d = sphere.depth(a, R)
    F = sphere.force(d, R, E)
    rows = ["| a/R | d/R | Hertz a, same d | Hertz F, same d | E* of a Hertz fit "
            "| Hertz d, same F | Hertz a, same F |",
            "| --- | --- | --- | --- | --- | --- | --- |"]
    for i, bi in enumerate(BETAS):
        aH = hertz.contact_radius(d[i], R)
        FH = hertz.force(d[i], R, E)
        dHF = hertz.depth_from_force(F[i], R, E)
        aHF = hertz.contact_radius_from_force(F[i], R, E)
        rows.append(f"| {bi:g} | {d[i] / R:.5g} | {aH / a[i] - 1:+.3g} | {FH / F[i] - 1:+.3g} "
                    f"| {F[i] / FH - 1:+.3g} "
                    f"| {dHF / d[i] - 1:+.3g} | {aHF / a[i] - 1:+.3g} |")
    return "\n".join(rows) + "\n"


def figure(path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    R, E = 1.0, 1.0
    b = np.geomspace(1e-3, 0.999, 200)
    d = sphere.depth(b * R, R)
    F = sphere.force(d, R, E)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog(b, hertz.force(d, R, E) / F - 1, label="force at the same depth")
    ax.loglog(b, hertz.contact_radius(d, R) / (b * R) - 1, label="contact radius at the same depth")
    ax.loglog(b, 1 - hertz.depth_from_force(F, R, E) / d, label="depth at the same force (deficit)")
    ax.loglog(b, b**2 / 10, "k:", lw=1, label="b^2/10")
    ax.set_xlabel("a/R of the exact sphere")
    ax.set_ylabel("relative deviation of Hertz")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("docs/sphere.md"))
    parser.add_argument("--no-figure", action="store_true", help="skip the PNG")
    args = parser.parse_args(argv)
    text = PROSE + table()
    if not args.no_figure:
        png = args.out.with_name("sphere_bias.png")
        figure(png)
        text += f"\n![Hertz against the exact sphere]({png.name})\n"
    args.out.write_text(text)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
