"""A disk cache of the derived relations, keyed by what the derivation reads.

Deriving every family takes about a minute of CPU. The test suite needs the relations in every
pytest-xdist worker (at collection) and ``python -m hertzmdr.derive --check`` needs them again;
without a cache each of them repeated the same SymPy work. The key is a SHA-256 over the
bytes of every ``.py`` file of ``hertzmdr.derive`` (the families, the MDR, the printers), the
versions of SymPy and mpmath, and the Python version: change any of them and the relations are
derived afresh. A derivation is deterministic (tests/test_generated.py checks the printed output
of a fresh process, with another hash seed and the cache off, against the committed files), so a
cached result is the result a derivation would give.

``HERTZMDR_DERIVE_CACHE`` chooses: ``1`` (default) reads and writes, ``refresh`` derives and
writes, ``0`` neither. ``HERTZMDR_CACHE_DIR`` moves the cache (default:
``$XDG_CACHE_HOME/hertzmdr``, else ``~/.cache/hertzmdr``). Processes that start together (the
xdist workers) take a file lock, so that one derives and the others read its result.
"""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

MODES = ("1", "0", "refresh")
#: cache files not read for this many days are removed when a new one is written
KEEP_DAYS = 14


def mode() -> str:
    """The cache mode from HERTZMDR_DERIVE_CACHE; one clear error for any other value."""
    value = os.environ.get("HERTZMDR_DERIVE_CACHE", "1").strip().lower()
    if value not in MODES:
        raise ValueError(f"HERTZMDR_DERIVE_CACHE={value!r}: use 1 (read and write the cache of "
                         "derived relations), refresh (derive, then write) or 0 (no cache)")
    return value


def directory() -> Path:
    if os.environ.get("HERTZMDR_CACHE_DIR"):
        return Path(os.environ["HERTZMDR_CACHE_DIR"]).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "hertzmdr"


def key() -> str:
    """SHA-256 of the derive package's sources and the versions that shape its output (and
    the arithmetic under SymPy and mpmath: gmpy2's integers when installed, Python's if not;
    a pickle of one need not load under the other)."""
    import mpmath
    import sympy
    from mpmath.libmp import BACKEND
    from sympy.external.gmpy import GROUND_TYPES

    h = hashlib.sha256()
    for path in sorted(Path(__file__).parent.rglob("*.py")):
        h.update(path.relative_to(Path(__file__).parent).as_posix().encode() + b"\0")
        h.update(path.read_bytes() + b"\0")
    h.update(f"sympy {sympy.__version__} mpmath {mpmath.__version__} "
             f"python {sys.version_info[:2]} ground {GROUND_TYPES} backend {BACKEND}".encode())
    return h.hexdigest()[:20]


@contextmanager
def _locked(path: Path) -> Iterator[None]:
    try:
        import fcntl
    except ImportError:  # no POSIX locks (Windows): concurrent processes may both derive
        yield
        return
    with open(path, "a") as fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def _prune(folder: Path, keep: Path, name: str = "relations") -> None:
    cutoff = time.time() - KEEP_DAYS * 86400
    for old in folder.glob(f"{name}-*"):
        try:
            if old.stem != keep.stem and old.stat().st_atime < cutoff:
                old.unlink()
        except OSError:
            pass


def cached(derive: Callable[[], object], name: str = "relations") -> tuple[object, str]:
    """``derive()``'s result and where it came from ("cache", "derived" or "derived, cache
    off"). A cache that cannot be read or written (a read-only home, a truncated file) is
    passed over: the relations are then derived, never half-read. ``name`` tells the cached
    results apart (file ``<name>-<key>.pickle``): the relations, and derivations outside them
    that several processes repeat (derive/stress.py's axis stresses)."""
    how = mode()
    if how == "0":
        return derive(), "derived, cache off"
    folder = directory()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        return derive(), f"derived, cache directory {folder} not writable"
    path = folder / f"{name}-{key()}.pickle"
    with _locked(path.with_suffix(".lock")):
        if how == "1" and path.exists():
            try:
                with open(path, "rb") as fh:
                    return pickle.load(fh), "cache"
            except Exception:  # noqa: BLE001 - any unreadable cache is derived afresh
                pass
        value = derive()
        tmp = path.with_suffix(f".tmp{os.getpid()}")
        try:
            with open(tmp, "wb") as fh:
                pickle.dump(value, fh, protocol=pickle.HIGHEST_PROTOCOL)
            os.replace(tmp, path)  # readers see the whole file or none
            _prune(folder, path, name)
        except OSError:
            tmp.unlink(missing_ok=True)
        return value, "derived"


def timings_path() -> Path:
    return directory() / "family-cpu-seconds.json"


def read_timings() -> dict[str, float]:
    """CPU seconds each family took when last derived here (for scheduling), or {}."""
    try:
        data = json.loads(timings_path().read_text())
        return {str(k): float(v) for k, v in data.items()}
    except (OSError, ValueError, AttributeError, TypeError):
        return {}


def write_timings(seconds: dict[str, float]) -> None:
    if mode() == "0":
        return
    try:
        timings_path().parent.mkdir(parents=True, exist_ok=True)
        tmp = timings_path().with_suffix(f".tmp{os.getpid()}")
        tmp.write_text(json.dumps(seconds, indent=1, sort_keys=True))
        os.replace(tmp, timings_path())
    except OSError:
        pass
