"""The example force map examples/fit_force_map.csv: its recipe, from the package's forward model.

A 10 x 10 map (1 um pitch, x and y from 0.5 to 9.5 um) taken with a colloidal probe, a rigid
sphere of R = 25 um as its paraboloid (5.23), on a soft sample of nu = 0.5 with the true
modulus field

    E(x, y) = 1 MPa, and 3 MPa inside the disc |(x, y) - (5 um, 5 um)| < 3 um

(E* = E/(1 - nu^2), (5.8)), on a tilted surface: the contact point is z_0 = 150 nm + 5 nm/um x
+ 3 nm/um y. Each curve: 120 positions z from 0 to 300 nm, F = hertz.force(max(0, z - z_0))
+ a baseline of 0.2 nN + 1e-3 N/m z, and Gaussian noise of 0.5 nN (seed 17 for the map). One
pixel, (x, y) = (9.5 um, 0.5 um), is a hole in the sample: its curve has no contact (the
baseline and the noise only), to show a curve that fails alone. The deepest indentation is
about 120 nm (at the inclusion's far side), a/R <= 0.07.

Run: ``.venv/bin/python benchmarks/make_force_map.py`` (writes the file; tests/test_fit_batch.py
checks that the shipped file is what this recipe makes).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hertzmdr.numeric import hertz

R = 25e-6  # m
NU = 0.5
E_OUT, E_IN = 1e6, 3e6  # Pa
CENTRE, RADIUS = (5e-6, 5e-6), 3e-6  # m
PITCH, NX = 1e-6, 10
N_POINTS = 120
NOISE = 0.5e-9  # N
HOLE = (9, 0)  # (column, row) of the pixel without contact: x = 9.5 um, y = 0.5 um
PATH = Path(__file__).resolve().parents[1] / "examples" / "fit_force_map.csv"


def true_modulus(x, y):
    """The sample's Young's modulus E [Pa] at (x, y) [m]."""
    inside = np.hypot(x - CENTRE[0], y - CENTRE[1]) < RADIUS
    return np.where(inside, E_IN, E_OUT)


def contact_point(x, y):
    """The contact point z_0 [m] at (x, y) [m]: a tilted surface."""
    return 150e-9 + 5e-3 * x + 3e-3 * y


def force_map_text() -> str:
    rng = np.random.default_rng(17)
    z = np.linspace(0.0, 300e-9, N_POINTS)
    lines = ["# synthetic force map (benchmarks/make_force_map.py): a rigid paraboloid R = 25 um",
             "# on nu = 0.5 with E = 1 MPa, and 3 MPa inside the disc of radius 3 um around",
             "# (5 um, 5 um); contact point 150 nm + 5 nm/um x + 3 nm/um y; baseline 0.2 nN +",
             "# 1e-3 N/m z; noise 0.5 nN (seed 17); the pixel (9.5 um, 0.5 um) has no contact",
             "x [um], y [um], z [nm], F [nN]"]
    for j in range(NX):
        for i in range(NX):
            x, y = (i + 0.5) * PITCH, (j + 0.5) * PITCH
            F = 0.2e-9 + 1e-3 * z
            if (i, j) != HOLE:
                E_star = float(true_modulus(x, y)) / (1 - NU**2)  # (5.8)
                F = F + hertz.force(np.maximum(z - contact_point(x, y), 0.0), R, E_star)
            F = F + rng.normal(0.0, NOISE, z.size)
            lines += [f"{x * 1e6:.1f}, {y * 1e6:.1f}, {zi * 1e9:.3f}, {Fi * 1e9:.4f}"
                      for zi, Fi in zip(z, F, strict=True)]
    return "\n".join(lines) + "\n"


def main():
    PATH.write_text(force_map_text())
    print(f"wrote {PATH}")


if __name__ == "__main__":
    main()
