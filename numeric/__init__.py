"""hertzmdr's runtime: NumPy and SciPy only, never SymPy.

What is where (SI units throughout; each function's docstring gives its equation number and
the domain where it is guaranteed finite and accurate):

- Closed forms, validated and vectorized, printed from ``hertzmdr.derive`` into
  ``_generated.py`` (``_generated_mp.py``: the same at arbitrary precision with mpmath):
  ``hertz`` (5.15)-(5.27), ``cone`` (5.38)-(5.40), ``powerlaw`` (Problem 7), ``worn``
  (Problem 8), ``sphere`` (the exact spherical cap), ``line`` (5.34)-(5.37), ``ellipse`` (the
  exact elliptical contact), ``bodies`` (E*, R and the principal radii of two bodies),
  ``impact`` and ``motion`` (Problems 3-4), ``pressures`` and ``contact`` (prescribed pressures,
  mean pressure, stiffness).
- Stresses: ``stress`` (Boussinesq superposition, the Hertz field, its maxima), ``line_stress``
  (the line contact, plane strain).
- Numerical methods: ``mdr`` (the numerical MDR of any sampled or callable profile, with its
  error bound), ``abel`` ((5.59) and (5.61) from samples), ``bem`` (non-axisymmetric contacts
  on a grid).
- Inverse problem: ``fit`` (a force curve F(z) fitted for E*, the contact point and the
  baseline, with the derived Jacobians of ``hertzmdr.derive.fit``; ``fit_batch`` many curves
  over worker processes, a force map; ``fit_io`` their files and figures, ``hertzmdr fit``).
- ``c``: the contact laws as a C99 header for DEM codes (``c.header_path()``), printed from
  the same relations as ``_generated.py`` (docs/c_laws.md).
- ``scene``: a TOML scene in, exactly the asked effects out (``hertzmdr run``); ``cli`` the
  ``hertzmdr`` command; ``accuracy`` what each digit costs (``hertzmdr accuracy``).
"""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("hertzmdr")
except PackageNotFoundError:  # imported from a source tree that was never installed
    __version__ = "unknown"
