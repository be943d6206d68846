"""hertzmdr: normal contact of elastic bodies (Boussinesq, Hertz, the Method of Dimensionality
Reduction), derived with SymPy, generated to NumPy, verified with mpmath.

What is where (SI units throughout):

- ``hertzmdr.derive``: the chapter's relations (5.1)-(5.61) derived with SymPy, one module per
  family, each relation a ``Relation`` record with its equation number and the test that
  verifies it; ``python -m hertzmdr.derive`` prints them into the generated code and
  docs/derivations.md. Needs SymPy; never imported by the runtime.
- ``hertzmdr.numeric``: the runtime (NumPy and SciPy): the generated closed forms, validated
  and vectorized (``hertz``, ``cone``, ``powerlaw``, ``worn``, ``sphere``, ``line``,
  ``ellipse``, ...), the stresses, the numerical methods (``mdr``, ``abel``, ``bem``), scenes
  (``hertzmdr.numeric.scene``: a TOML scene in, exactly the asked effects out), the fit of
  measured force curves (``fit``) and the command line (``hertzmdr.numeric.cli``). Its own
  docstring lists every module.
- ``python -m hertzmdr`` is the ``hertzmdr`` command (``run``, ``effects``, ``fit``, ``accuracy``).

>>> import hertzmdr
>>> hertzmdr.__version__            # doctest: +SKIP
'0.1.0'
"""

from hertzmdr.numeric import __version__

__all__ = ["__version__"]
