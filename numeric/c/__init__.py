"""The contact laws as a C99 header for DEM codes: ``hertzmdr_laws.h`` (package data).

The header is printed by ``python -m hertzmdr.derive`` from the same SymPy relations as
``hertzmdr.numeric._generated`` (see :mod:`hertzmdr.derive.c_codegen`) and installed with the
package. Find it from Python, e.g. for a build system::

    python -c "import hertzmdr.numeric.c as c; print(c.include_dir())"

and compile with ``-I$(that directory)``; ``#include "hertzmdr_laws.h"`` then gives every law as
a ``static inline`` double function named ``hertzmdr_<relation>``. Guide: docs/c_laws.md.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["header_path", "include_dir"]

_HERE = Path(__file__).resolve().parent


def header_path() -> Path:
    """Absolute path of ``hertzmdr_laws.h``, the installed C99 header of the contact laws."""
    return _HERE / "hertzmdr_laws.h"


def include_dir() -> Path:
    """The directory to pass to the C/C++ compiler as ``-I`` to include ``hertzmdr_laws.h``."""
    return _HERE
