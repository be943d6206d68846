"""beta of (5.13)-(5.14) for flat punches of polygonal footprint, extrapolated in the mesh size.

k = 2 E* beta sqrt(A/pi) (5.13). For each shape the flat-punch stiffness is computed by
:func:`hertzmdr.numeric.bem.punch_stiffness` on grids with n pixels along the longer side, and
beta_n = k_n / (2 E* sqrt(A_n/pi)) with A_n the area of the pixelated footprint (so the
staircase of the boundary, which changes the area by O(dx), is not counted as an error of k).
Richardson extrapolation with the observed order p = log2((b1 - b2)/(b2 - b3)) on each triple of
successive grids (n, 2n, 4n); the uncertainty is the difference between the extrapolations of
the last two triples (or, when they agree better, the last step's correction divided by
2^p - 1 times 0.1, a floor against lucky agreement).

Run: ``python benchmarks/beta.py [--nmax 512] [--quick] [--out DIR]`` (``make benchmark`` runs
it; ``--quick``: n = 16, 32, 64); writes benchmarks/results/beta.json, which
``make_nonaxi_doc.py`` turns into docs/non_axisymmetric.md.
"""

from __future__ import annotations

import json

import _common
import numpy as np

from hertzmdr.numeric import _timing, bem

SHAPES = {
    "circle (check: 1)": [(np.cos(t), np.sin(t)) for t in np.linspace(0, 2 * np.pi, 721)[:-1]],
    "equilateral triangle": [(0, 0), (1, 0), (0.5, np.sqrt(3) / 2)],
    "square": [(0, 0), (1, 0), (1, 1), (0, 1)],
    "rectangle 2:1": [(0, 0), (2, 0), (2, 1), (0, 1)],
    "rectangle 3:1": [(0, 0), (3, 0), (3, 1), (0, 1)],
    "rectangle 4:1": [(0, 0), (4, 0), (4, 1), (0, 1)],
    "rectangle 10:1": [(0, 0), (10, 0), (10, 1), (0, 1)],
}

#: (5.14): round 1.000, triangular 1.061, "rectangular" 1.021 with no aspect ratio given (our
#: square matches it; no value is listed for the elongated rectangles)
CHAPTER = {"circle (check: 1)": 1.000, "equilateral triangle": 1.061, "square": 1.021}


#: n along the long side is multiplied by this, so that the short side of a rectangle gets a
#: whole number of pixels on every grid (else its staircase changes irregularly with n) and the
#: 10:1 rectangle gets 32 to 256 pixels across
FINER = {"rectangle 3:1": 0.75, "rectangle 10:1": 5}


def beta_at(vertices, n):
    h, dx = bem.polygon_punch(vertices, n)
    mask = np.isfinite(h)
    k = bem.punch_stiffness(mask, dx, 1.0, tol=1e-10)
    area = mask.sum() * dx * dx
    return k / (2 * np.sqrt(area / np.pi))  # (5.13) with E* = 1


def richardson(ns, betas):
    """Extrapolations (value, order) of every triple of successive grids."""
    out = []
    for i in range(len(betas) - 2):
        b1, b2, b3 = betas[i:i + 3]
        ratio = (b1 - b2) / (b2 - b3)
        p = np.log2(ratio) if ratio > 0 else float("nan")
        out.append((b3 + (b3 - b2) / (2**p - 1), p))
    return out


def main(argv=None):
    ap = _common.parser(__doc__)
    ap.add_argument("--nmin", type=int, help="coarsest grid (default 64; --quick: 16)")
    ap.add_argument("--nmax", type=int, help="finest grid (default 512; --quick: 64)")
    args = ap.parse_args(argv)
    run = _common.run_from(args)
    nmin = args.nmin or (16 if args.quick else 64)
    nmax = args.nmax or (64 if args.quick else 512)
    ns = []
    n = nmin
    while n <= nmax:
        ns.append(n)
        n *= 2
    results = {}
    for name, verts in SHAPES.items():
        scale = FINER.get(name, 1)
        betas, seconds = _timing.timed(
            lambda verts=verts, scale=scale: [beta_at(verts, round(scale * n)) for n in ns])
        ext = richardson(ns, betas)
        value, order = ext[-1]
        if len(ext) >= 2 and np.isfinite(ext[-2][0]):
            unc = abs(ext[-1][0] - ext[-2][0])
        else:
            unc = abs(value - betas[-1])
        unc = max(unc, 0.1 * abs(value - betas[-1]))
        results[name] = {"n": [round(FINER.get(name, 1) * n) for n in ns], "beta_n": betas,
                         "extrapolated": value, "order": order, "uncertainty": unc,
                         "chapter": CHAPTER.get(name),
                         "seconds": seconds}
        print(f"{name:22s} " + " ".join(f"{b:.5f}" for b in betas)
              + f" -> {value:.4f} +- {unc:.4f} (order {order:.2f}); chapter {CHAPTER.get(name)}")
    out = run.results / "beta.json"
    out.write_text(json.dumps(results, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
