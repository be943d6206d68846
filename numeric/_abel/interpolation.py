"""Abel transforms, interpolation: the piecewise Lagrange interpolant in s = x^2.

Each piece [s_i, s_(i+1)] takes the Lagrange polynomial of the ``degree + 1`` nodes centred on
it (shifted, never straddling the end of the support), in the local variable v = (s - s_i)/width
(numeric/abel.py's docstring has the method).
"""

from __future__ import annotations

import numpy as np


def _stencils(n_pieces: int, last_node: int, degree: int) -> np.ndarray:
    """First node of the stencil of each piece [i, i+1]: centred, never past ``last_node``."""
    start = np.arange(n_pieces) - (degree - 1) // 2
    return np.clip(start, 0, max(last_node - degree, 0))


def _lagrange_power(nodes: np.ndarray) -> np.ndarray:
    """Power-basis coefficients of the Lagrange polynomials of ``nodes`` (shape (P, m+1)).

    Returns C with shape (P, m+1, m+1): l_l(v) = sum_k C[:, k, l] v^k. Built as products of
    linear factors (no Vandermonde inverse), which stays accurate for the nodes 0, 1, 4, 9 ...
    of the first pieces.
    """
    P, m1 = nodes.shape
    C = np.zeros((P, m1, m1))
    for ll in range(m1):
        poly = np.zeros((P, m1))
        poly[:, 0] = 1.0
        for rr in range(m1):
            if rr == ll:
                continue
            den = nodes[:, ll] - nodes[:, rr]
            shifted = np.zeros_like(poly)
            shifted[:, 1:] = poly[:, :-1]
            poly = (shifted - nodes[:, rr, None] * poly) / den[:, None]
        C[:, :, ll] = poly
    return C


def _pieces(edges: np.ndarray, nodes: np.ndarray, degree: int):
    """Stencils, widths and Lagrange coefficients of the pieces [edges_i, edges_(i+1)].

    Returns (idx, width, C, deg): idx (P, deg+1) the node indices of each stencil (centred,
    clipped to the nodes), C (P, deg+1, deg+1) in the local variable v = (s - edges_i)/width_i.
    """
    n_pieces = len(edges) - 1
    deg = min(degree, len(nodes) - 1)
    start = _stencils(n_pieces, len(nodes) - 1, deg)
    idx = start[:, None] + np.arange(deg + 1)
    width = edges[1:] - edges[:-1]
    local = (nodes[idx] - edges[:-1, None]) / width[:, None]
    return idx, width, _lagrange_power(local), deg
