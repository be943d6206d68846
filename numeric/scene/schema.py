"""Read and validate a scene: a TOML file (or a dict of the same shape) describing two bodies,
their load and the effects wanted. Everything is checked here, before any physics runs; every
problem raises :class:`SceneError` naming the file, the key and what is wrong. Nothing from a
scene reaches eval, exec or sympify: values are numbers, strings read by :mod:`.units`, or lists.
"""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from hertzmdr.numeric.scene.accuracy import DEFAULT_RTOL
from hertzmdr.numeric.scene.materials import Interface
from hertzmdr.numeric.scene.shapes import SHAPES
from hertzmdr.numeric.scene.units import UnitError, to_si


class SceneError(ValueError):
    """A malformed scene: ``where`` is the file, ``key`` the offending key."""

    def __init__(self, where: str, key: str, message: str):
        self.where, self.key, self.message = where, key, message
        super().__init__(f"{where}: {key}: {message}" if key else f"{where}: {message}")


MATERIAL_KEYS = {"E", "nu", "rigid"}
TOP_KEYS = {"title", "effects", "body", "load", "accuracy", "model", "interface", "fit"}
#: the keys of a ``[fit]`` table (docs/fitting.md)
FIT_KEYS = {"curve", "columns", "units", "modulus", "depth_range", "contact_point", "sigma",
            "fixed_contact_point", "fixed_baseline"}


@dataclass
class Body:
    name: str
    shape: str
    params: dict
    E: float | None = None  # None when rigid
    nu: float | None = None

    @property
    def rigid(self) -> bool:
        return self.E is None


@dataclass(frozen=True)
class History:
    """An explicit (normal, tangential) load history read from a file (``[load] history``).

    Attributes
    ----------
    file : str
        The file's name, for messages.
    control : str
        What the tangential column is: "force" [N] or "displacement" [m].
    values : tuple of float
        The tangential column in SI units, one entry per state.
    lines : tuple of int
        The line of the file each state was read from (errors name it).
    """

    file: str
    control: str
    values: tuple[float, ...]
    lines: tuple[int, ...]


@dataclass(frozen=True)
class Tangential:
    """The tangential part of a load (docs/tangential.md): at constant normal load, or an
    explicit history of both."""

    kind: str  # "force", "displacement" (monotonic from 0), "oscillating" or "history"
    value: float  # F_x [N], u_x [m], the amplitude of the tangential force [N], or a
    # history's largest |tangential value| (its unit by history.control)
    cycles: int = 0  # oscillating: the number of full cycles after the first loading
    history: History | None = None  # "history": the states read from the file


@dataclass
class Load:
    kind: str  # "depth", "force", "impact" or "pressure"
    values: list[float] = field(default_factory=list)  # one value, or the points of a sweep
    sweep: bool = False
    spacing: str = "linear"  # a sweep's: "linear" or "log"
    velocity: float | None = None
    mass: float | None = None
    density: float | None = None
    distribution: str | None = None  # a prescribed pressure: "uniform", "hertzian", "punch"
    p0: float | None = None
    radius: float | None = None
    control: str | None = None  # a cycle: "depth" or "force"
    points: int | None = None  # a cycle: its number of points
    tangential: Tangential | None = None


@dataclass(frozen=True)
class FitSpec:
    """A scene's ``[fit]`` table: what ``hertzmdr fit --scene`` fits (docs/fitting.md).

    Attributes
    ----------
    curve : Path or None
        The curve file (or force map, or folder of curves), resolved against the scene's
        folder; None when the table leaves it to the command line.
    columns : tuple of str or None
        The header names of the position and force columns (default: a two-column file).
    units : tuple of float or None
        The SI size of one unit of each of those columns [m], [N], for a header without units.
    modulus : str
        "E" (the sample's Young's modulus through its nu, and E*) or "E_star" (E* alone).
    depth_range : tuple of float or None
        (lowest, highest) z - z_0 [m] of the points fitted, z_0 the fitted contact point.
    contact_point : float or None
        A guess of the contact point z_0 [m].
    sigma : float or None
        The force noise's standard deviation [N].
    fixed_contact_point : float or None
        The contact point z_0 [m] held fixed (not fitted).
    fixed_baseline : tuple of float or None
        The baseline (F_0 [N], s_0 [N/m]) held fixed (not fitted).
    """

    curve: Path | None = None
    columns: tuple[str, str] | None = None
    units: tuple[float, float] | None = None
    modulus: str = "E"
    depth_range: tuple[float, float] | None = None
    contact_point: float | None = None
    sigma: float | None = None
    fixed_contact_point: float | None = None
    fixed_baseline: tuple[float, float] | None = None


@dataclass
class SceneSpec:
    title: str
    effects: list[str]
    bodies: list[Body]
    load: Load
    rtol: float  # [accuracy] rtol, DEFAULT_RTOL when not given (numeric/scene/accuracy.py)
    elliptic: str
    interface: Interface
    source: str
    base_dir: Path | None
    #: the swept keys (numeric/scene/study.py): None, a load sweep alone, or a study
    study: object = None
    #: the document as given (TOML tables as dicts) and how the reader took each value
    #: (key as in errors -> (how, dimension or unit)): what result.json echoes (echo.py)
    raw: dict = field(default_factory=dict)
    read_as: dict[str, tuple[str, str]] = field(default_factory=dict)
    #: the ``[fit]`` table, None without one (it changes nothing `hertzmdr run` computes)
    fit: FitSpec | None = None


def read(path_or_dict, *, known_effects) -> SceneSpec:
    """Parse and validate a scene file path or dict; raise SceneError on any problem. A
    result.json (a ``.json`` path) or the document of a run (a dict with
    ``hertzmdr_version``) is read as the scene it echoes (:mod:`.echo`)."""
    if isinstance(path_or_dict, dict):
        if "hertzmdr_version" in path_or_dict:
            from hertzmdr.numeric.scene.echo import scene_of

            return _read(_Reader("<result>", None, known_effects),
                         scene_of(path_or_dict, "<result>"), "scene")
        return _read(_Reader("<scene>", None, known_effects), path_or_dict, "scene")
    path = Path(path_or_dict)
    where = str(path)
    try:
        text = path.read_text(encoding="utf-8-sig")  # a byte-order mark is no content
    except FileNotFoundError:
        raise SceneError(where, "", "no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError(where, "", f"cannot read the file ({exc})") from None
    if path.suffix.lower() == ".json":
        from hertzmdr.numeric.scene.echo import read_result

        return _read(_Reader(where, path.parent, known_effects), read_result(text, where),
                     path.stem)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(where, "", f"TOML syntax error: {exc}") from None
    return _read(_Reader(where, path.parent, known_effects), data, path.stem)


def _read(reader: _Reader, data: dict, default_title: str) -> SceneSpec:
    """The scene with its sweeps, if any (numeric/scene/study.py)."""
    from hertzmdr.numeric.scene.study import read_scene

    spec = read_scene(reader, data, default_title)
    spec.raw = data  # a study reads its scene at a corner: the echo is of the document itself
    return spec


#: the most states a history file may hold
HISTORY_MAX_ROWS = 100_000


def read_history(path: Path, fail) -> list[tuple[int, tuple[float, float]]]:
    """The rows (line number, (normal, tangential)) of a history file: two numbers a line,
    separated by a comma and/or spaces; ``#`` starts a comment; one header line may come before
    the first state.
    ``fail(message)`` is called on the first problem, naming the file and the line."""
    from hertzmdr.numeric.scene.columns import read_pairs

    rows = read_pairs(path, fail, "history", "(normal, tangential)")
    if len(rows) > HISTORY_MAX_ROWS:
        fail(f"{path.name} has {len(rows)} states; at most {HISTORY_MAX_ROWS}")
    if len(rows) < 2:
        fail(f"{path.name} has {len(rows)} state(s); a history needs at least two")
    return rows


def suggest(name: str, choices) -> str:
    close = difflib.get_close_matches(name, sorted(choices), n=1, cutoff=0.5)
    return f"; did you mean {close[0]!r}?" if close else ""


class _Reader:
    def __init__(self, where: str, base_dir: Path | None, known_effects):
        self.where, self.base_dir, self.known_effects = where, base_dir, known_effects
        self.read_as: dict[str, tuple[str, str]] = {}  # see SceneSpec.read_as

    def fail(self, key: str, message: str):
        raise SceneError(self.where, key, message)

    def table(self, value, key: str) -> dict:
        if not isinstance(value, dict):
            self.fail(key, f"must be a table, got {type(value).__name__}")
        return value

    def extra_keys(self, table: dict, allowed, key: str) -> None:
        for k in table:
            if k not in allowed:
                names = ", ".join(sorted(allowed)) or "none yet"
                k = k if k.isprintable() else repr(k)  # a message is one line
                self.fail(f"{key}.{k}" if key else k,
                          f"unknown key{suggest(k, allowed)} (allowed: {names})")

    def quantity(self, value, dimension: str, key: str) -> float:
        self.read_as[key] = ("quantity", dimension)
        try:
            out = to_si(value, dimension)
        except UnitError as exc:
            self.fail(key, str(exc))
        if not math.isfinite(out):
            self.fail(key, f"must be finite, got {value!r}")
        return out

    def positive(self, value, dimension: str, key: str) -> float:
        out = self.quantity(value, dimension, key)
        if not out > 0:
            self.fail(key, f"must be > 0, got {value!r}")
        return out

    def cycle(self, cy: dict) -> Load:
        """``cycle = {to = ..., control = "depth" | "force", points = N}``: approach, push to
        ``to`` (a depth or a force, by ``control``; default "depth"), retract to separation."""
        self.extra_keys(cy, {"to", "control", "points"}, "load.cycle")
        if "to" not in cy:
            self.fail("load.cycle.to", "missing: the largest depth (or force) of the cycle")
        control = cy.get("control", "depth")
        if control not in ("depth", "force"):
            self.fail("load.cycle.control", f"must be \"depth\" or \"force\", got {control!r}")
        n = cy.get("points", 1000)
        if isinstance(n, bool) or not isinstance(n, int) or not 20 <= n <= 100_000:
            self.fail("load.cycle.points", f"must be an integer in [20, 100000], got {n!r}")
        dim = "length" if control == "depth" else "force"
        to = self.positive(cy["to"], dim, "load.cycle.to")
        return Load("cycle", [to], control=control, points=n)

    def scene(self, data: dict, default_title: str = "scene") -> SceneSpec:
        self.extra_keys(data, TOP_KEYS, "")
        title = data.get("title", default_title)
        if not isinstance(title, str):
            self.fail("title", "must be a string")
        effects = data.get("effects")
        if not (isinstance(effects, list) and effects and all(isinstance(e, str) for e in effects)):
            self.fail("effects", "must be a non-empty list of effect names "
                      "(`hertzmdr effects` lists them)")
        for e in effects:
            if e not in self.known_effects:
                self.fail("effects", f"unknown effect {e!r}{suggest(e, self.known_effects)}")
        if len(set(effects)) != len(effects):
            self.fail("effects", "lists an effect twice")
        bodies = data.get("body")
        if not isinstance(bodies, list) or len(bodies) != 2:
            n = len(bodies) if isinstance(bodies, list) else 0
            self.fail("body", f"a scene has exactly two [[body]] tables, this one has {n}")
        parsed = [self.body(self.table(b, f"body[{i}]"), i) for i, b in enumerate(bodies)]
        if parsed[0].rigid and parsed[1].rigid:
            self.fail("body", "both bodies are rigid: at least one must have E and nu")
        if "load" not in data:
            self.fail("load", "missing: give exactly one of depth, force, [load.impact] or "
                      "[load.pressure]")
        load = self.load(self.table(data["load"], "load"))
        rtol = DEFAULT_RTOL
        if "accuracy" in data:
            acc = self.table(data["accuracy"], "accuracy")
            self.extra_keys(acc, {"rtol"}, "accuracy")
            if "rtol" in acc:
                rtol = acc["rtol"]
                if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) \
                        or not (0 < rtol < 1):
                    self.fail("accuracy.rtol", f"must be a number in (0, 1), got {rtol!r} (each "
                              "method's own range is checked when the model is built)")
                rtol = float(rtol)
        interface = Interface()
        if "interface" in data:
            table = self.table(data["interface"], "interface")
            self.extra_keys(table, Interface.KEYS, "interface")
            values = {k: self.quantity(table[k], dim, f"interface.{k}")
                      for k, dim in Interface.KEYS.items() if k in table and dim != "number"}
            if "friction" in table:
                mu = table["friction"]
                if isinstance(mu, bool) or not isinstance(mu, (int, float)) \
                        or not (math.isfinite(mu) and mu >= 0):
                    self.fail("interface.friction", f"must be a number >= 0 (the coefficient "
                              f"of friction), got {mu!r}")
                values["friction"] = float(mu)
            try:
                interface = Interface(**values)
            except ValueError as exc:
                key = str(exc).split(" ")[0]
                self.fail(f"interface.{key}", str(exc))
        elliptic = "exact"
        if "model" in data:
            model = self.table(data["model"], "model")
            self.extra_keys(model, {"elliptic"}, "model")
            elliptic = model.get("elliptic", "exact")
            if elliptic not in ("exact", "gaussian"):
                self.fail("model.elliptic", f"must be \"exact\" or \"gaussian\", got {elliptic!r}")
        fit = self.fit(self.table(data["fit"], "fit")) if "fit" in data else None
        return SceneSpec(title, list(effects), parsed, load, rtol, elliptic, interface,
                         self.where, self.base_dir, raw=data, read_as=dict(self.read_as),
                         fit=fit)

    def fit(self, ft: dict) -> FitSpec:
        """``[fit]``: the curve to fit and how (docs/fitting.md); every value checked here,
        the curve file's content when it is fitted (numeric/fit_io.py)."""
        self.extra_keys(ft, FIT_KEYS, "fit")
        out = {}
        if "curve" in ft:
            name = ft["curve"]
            if not isinstance(name, str) or not name.strip() or not name.isprintable():
                self.fail("fit.curve", f"must be a file name (a string), got {name!r}")
            path = (self.base_dir or Path.cwd()) / name
            try:
                is_file, is_dir = path.is_file(), path.is_dir()
            except (OSError, ValueError) as exc:  # a name too long, a NUL byte
                self.fail("fit.curve", f"{name!r} cannot be a file name ({exc})")
            if not (is_file or is_dir):
                self.fail("fit.curve", f"{name!r}: no such file or folder (a name relative to "
                          "the scene's folder)")
            if is_file:  # echoed resolved, with its SHA-256
                self.read_as["fit.curve"] = ("path", "")
            out["curve"] = path
        if "columns" in ft:
            cols = ft["columns"]
            if not (isinstance(cols, list) and len(cols) == 2 and all(
                    isinstance(c, str) and c.strip() and c.isprintable() for c in cols)
                    and cols[0].strip() != cols[1].strip()):
                self.fail("fit.columns", "must be the header names of two different columns, "
                          f"position then force, e.g. [\"z\", \"F\"]; got {cols!r}")
            out["columns"] = (cols[0].strip(), cols[1].strip())
        if "units" in ft:
            units = ft["units"]
            if not (isinstance(units, list) and len(units) == 2
                    and all(isinstance(u, str) and u.strip() for u in units)):
                self.fail("fit.units", "must be a list of two unit strings [position, force], "
                          f"e.g. [\"nm\", \"nN\"]; got {units!r}")
            out["units"] = tuple(self.positive(f"1 {u.strip()}", dim, f"fit.units[{j}]")
                                 for j, (u, dim) in enumerate(zip(units, ("length", "force"),
                                                                  strict=True)))
            for j in range(2):  # a unit, not a quantity: result.json echoes it as given
                self.read_as.pop(f"fit.units[{j}]", None)
        if "modulus" in ft:
            if ft["modulus"] not in ("E", "E_star"):
                self.fail("fit.modulus", "must be \"E\" (the sample's Young's modulus, through "
                          "its nu) or \"E_star\" (the effective modulus alone); got "
                          f"{ft['modulus']!r}")
            out["modulus"] = ft["modulus"]
        if "depth_range" in ft:
            rng = ft["depth_range"]
            if not isinstance(rng, list) or len(rng) != 2:
                self.fail("fit.depth_range", "must be a list of two depths [lowest, highest] "
                          f"of z - z_0, e.g. [\"-1 um\", \"200 nm\"]; got {rng!r}")
            lo, hi = (self.quantity(v, "length", f"fit.depth_range[{j}]")
                      for j, v in enumerate(rng))
            if not (lo < hi and hi > 0):
                self.fail("fit.depth_range", f"needs lowest < highest and highest > 0 (some "
                          f"indentation), got {lo:g} m and {hi:g} m")
            out["depth_range"] = (lo, hi)
        if "contact_point" in ft:
            out["contact_point"] = self.quantity(ft["contact_point"], "length",
                                                 "fit.contact_point")
        if "sigma" in ft:
            out["sigma"] = self.positive(ft["sigma"], "force", "fit.sigma")
        if "fixed_contact_point" in ft:
            if "contact_point" in ft:
                self.fail("fit.fixed_contact_point", "and fit.contact_point (a guess) exclude "
                          "each other: give one")
            out["fixed_contact_point"] = self.quantity(ft["fixed_contact_point"], "length",
                                                       "fit.fixed_contact_point")
        if "fixed_baseline" in ft:
            fb = ft["fixed_baseline"]
            if not isinstance(fb, list) or len(fb) != 2:
                self.fail("fit.fixed_baseline", "must be a list of the baseline's force at "
                          "z = 0 and its slope [F_0, s_0], e.g. [\"2 nN\", \"0.1 mN/m\"]; got "
                          f"{fb!r}")
            out["fixed_baseline"] = (
                self.quantity(fb[0], "force", "fit.fixed_baseline[0]"),
                self.quantity(fb[1], "force_per_length", "fit.fixed_baseline[1]"))
        return FitSpec(**out)

    def body(self, b: dict, i: int) -> Body:
        key = f"body[{i}]"
        name = b.get("name", f"body {i + 1}")
        if not isinstance(name, str):
            self.fail(f"{key}.name", "must be a string")
        key = f"body[{i}] ({name})"
        shape = b.get("shape")
        if shape is None:
            self.fail(f"{key}.shape", f"missing (one of: {', '.join(SHAPES)})")
        if not isinstance(shape, str) or shape not in SHAPES:
            self.fail(f"{key}.shape", f"unknown shape {shape!r}{suggest(str(shape), SHAPES)}")
        spec = SHAPES[shape]
        self.extra_keys(b, {"name", "shape"} | MATERIAL_KEYS | {k.name for k in spec.keys}, key)
        params = {}
        for k in spec.keys:
            if k.name not in b:
                if k.required:
                    self.fail(f"{key}.{k.name}", f"missing: a {shape} needs {k.name}")
                continue
            params[k.name] = self.shape_value(b[k.name], k.kind, f"{key}.{k.name}")
            if k.kind in ("path", "length_unit", "number"):  # a file, a unit, a plain number
                self.read_as[f"{key}.{k.name}"] = (k.kind, k.unit)

        def fail(sub: str, message: str):
            self.fail(f"{key}.{sub}" if sub else key, message)

        spec.check(params, fail, self.base_dir or Path.cwd())
        if b.get("rigid", False) is True:
            if "E" in b or "nu" in b:
                self.fail(key, "a rigid body has no E or nu")
            return Body(name, shape, params)
        if "rigid" in b and b["rigid"] is not False:
            self.fail(f"{key}.rigid", f"must be true or false, got {b['rigid']!r}")
        for k in ("E", "nu"):
            if k not in b:
                self.fail(f"{key}.{k}", "missing: give E and nu, or rigid = true")
        E = self.positive(b["E"], "pressure", f"{key}.E")
        nu = b["nu"]
        if isinstance(nu, bool) or not isinstance(nu, (int, float)) or not (-1 < nu <= 0.5):
            self.fail(f"{key}.nu", f"must be a number with -1 < nu <= 0.5, got {nu!r}")
        return Body(name, shape, params, E, float(nu))

    def shape_value(self, value, kind: str, key: str):
        if kind in ("length", "angle"):
            return self.quantity(value, kind, key)
        if kind == "number":
            if isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not math.isfinite(value):
                self.fail(key, f"must be a finite number (SI units), got {value!r}")
            return float(value)
        if kind == "length_pair":
            if not isinstance(value, list) or len(value) != 2:
                self.fail(key, "must be a list of two radii [R1, R2]")
            return [self.quantity(v, "length", f"{key}[{j}]") for j, v in enumerate(value)]
        if kind == "length_list":
            if not isinstance(value, list) or len(value) < 2:
                self.fail(key, "must be a list of at least two values")
            return [self.quantity(v, "length", f"{key}[{j}]") for j, v in enumerate(value)]
        if kind == "lengths":  # a list of any length, e.g. a profile's breakpoints
            if not isinstance(value, list):
                self.fail(key, f"must be a list of lengths [...], got {value!r}")
            return [self.quantity(v, "length", f"{key}[{j}]") for j, v in enumerate(value)]
        if kind == "path":
            if not isinstance(value, str):
                self.fail(key, "must be a file name (a string)")
            return value
        if kind == "points":
            if not isinstance(value, list) or len(value) < 3 or not all(
                    isinstance(v, list) and len(v) == 2 for v in value):
                self.fail(key, "must be a list of at least three [x, y] corners")
            return [[self.quantity(c, "length", f"{key}[{j}]") for c in v]
                    for j, v in enumerate(value)]
        if kind == "length_unit":  # "nm": the factor [m] that one such unit is
            if not isinstance(value, str) or not value.strip():
                self.fail(key, f"must be a length unit such as \"nm\" or \"um\", got {value!r}")
            return self.quantity(f"1 {value.strip()}", "length", key)
        if kind == "integer":  # its range is the shape's check
            if isinstance(value, dict):
                self.fail(key, "is a count, not swept: give one integer")
            if isinstance(value, bool) or not isinstance(value, int):
                self.fail(key, f"must be an integer, got {value!r}")
            return value
        if kind == "name":  # one of the shape's names, checked by the shape
            if not isinstance(value, str) or not value.isprintable():
                self.fail(key, f"must be a name (a string), got {value!r}")
            return value
        if kind == "count":
            if isinstance(value, bool) or not isinstance(value, int) or not 8 <= value <= 2048:
                self.fail(key, f"must be an integer in [8, 2048], got {value!r}")
            return value
        raise AssertionError(kind)

    def load(self, ld: dict) -> Load:
        kinds = ("depth", "force", "impact", "pressure", "cycle")
        self.extra_keys(ld, set(kinds) | {"tangential", "oscillating", "history"}, "load")
        if "history" in ld:
            others = sorted(k for k in ld if k != "history")
            if others:
                self.fail("load", "a history gives both the normal and the tangential load: "
                          f"give history alone, not with {' and '.join(others)}")
            return self.history(self.table(ld["history"], "load.history"))
        tangential = self.tangential(ld)
        load = self.normal_load({k: v for k, v in ld.items()
                                 if k not in ("tangential", "oscillating")})
        if tangential is not None:
            if load.kind not in ("depth", "force") or load.sweep:
                self.fail("load", "a tangential load needs a constant normal load: one depth "
                          "or force, not a sweep, an impact or a prescribed pressure")
            load.tangential = tangential
        return load

    def history(self, h: dict) -> Load:
        """``history = {file = "h.csv", normal = "depth" | "force", tangential =
        "displacement" | "force", units = ["nm", "nm"]}``: two columns (normal, tangential)
        of a text file, one state a row (docs/scenes.md)."""
        key = "load.history"
        self.extra_keys(h, {"file", "normal", "tangential", "units"}, key)
        for k in ("file", "normal", "tangential"):
            if k not in h:
                self.fail(f"{key}.{k}", "missing: a history is {file = \"h.csv\", normal = "
                          "\"depth\" or \"force\", tangential = \"displacement\" or "
                          "\"force\"} (units = [..., ...] optional)")
        normal, tang = h["normal"], h["tangential"]
        if normal not in ("depth", "force"):
            self.fail(f"{key}.normal", f"must be \"depth\" or \"force\", got {normal!r}")
        if tang not in ("displacement", "force"):
            self.fail(f"{key}.tangential", f"must be \"displacement\" or \"force\", got "
                      f"{tang!r}")
        dims = ("length" if normal == "depth" else "force",
                "length" if tang == "displacement" else "force")
        scale = [1.0, 1.0]
        if "units" in h:
            units = h["units"]
            if not (isinstance(units, list) and len(units) == 2
                    and all(isinstance(u, str) and u.strip() for u in units)):
                self.fail(f"{key}.units", "must be a list of two unit strings [normal, "
                          f"tangential], e.g. [\"nm\", \"nm\"] or [\"N\", \"mN\"]; got "
                          f"{units!r}")
            scale = [self.positive(f"1 {u.strip()}", dim, f"{key}.units[{j}]")
                     for j, (u, dim) in enumerate(zip(units, dims, strict=True))]
            for j in range(2):  # a unit, not a quantity: result.json echoes it as given
                self.read_as.pop(f"{key}.units[{j}]", None)
        name = h["file"]
        if not isinstance(name, str) or not name.strip():
            self.fail(f"{key}.file", f"must be a file name (a string), got {name!r}")
        path = (self.base_dir or Path.cwd()) / name
        rows = read_history(path, lambda msg: self.fail(f"{key}.file", msg))
        self.read_as[f"{key}.file"] = ("path", "")  # echoed resolved, with its SHA-256
        nv, tv, lines = [], [], []
        for line, (a, b) in rows:
            a, b = a * scale[0], b * scale[1]
            if not (math.isfinite(a) and math.isfinite(b)):
                self.fail(f"{key}.file", f"{path.name} line {line}: the values must be "
                          "finite after the unit is applied")
            if a < 0:
                self.fail(f"{key}.file", f"{path.name} line {line}: the normal {normal} "
                          f"{a!r} is below 0; valid: >= 0 (a state out of contact is 0)")
            nv.append(a)
            tv.append(b)
            lines.append(line)
        hist = History(path.name, tang, tuple(tv), tuple(lines))
        return Load(normal, nv, sweep=True, tangential=Tangential(
            "history", max(abs(v) for v in tv), history=hist))

    def tangential(self, ld: dict) -> Tangential | None:
        if "tangential" in ld and "oscillating" in ld:
            self.fail("load", "give tangential or oscillating, not both")
        if "tangential" in ld:
            tl = self.table(ld["tangential"], "load.tangential")
            self.extra_keys(tl, {"force", "displacement"}, "load.tangential")
            if len(tl) != 1:
                self.fail("load.tangential", "give exactly one of force or displacement")
            ((k, v),) = tl.items()
            dim = "force" if k == "force" else "length"
            return Tangential(k, self.positive(v, dim, f"load.tangential.{k}"))
        if "oscillating" in ld:
            osc = self.table(ld["oscillating"], "load.oscillating")
            self.extra_keys(osc, {"amplitude", "cycles"}, "load.oscillating")
            if "amplitude" not in osc:
                self.fail("load.oscillating.amplitude", "missing: the amplitude of the "
                          "tangential force")
            n = osc.get("cycles", 1)
            if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= 1000:
                self.fail("load.oscillating.cycles", f"must be an integer in [1, 1000], got "
                          f"{n!r}")
            return Tangential("oscillating", self.positive(osc["amplitude"], "force",
                                                           "load.oscillating.amplitude"), n)
        return None

    def normal_load(self, ld: dict) -> Load:
        kinds = ("depth", "force", "impact", "pressure", "cycle")
        given = [k for k in kinds if k in ld]
        if len(given) != 1:
            self.fail("load", "give exactly one of depth, force, cycle, [load.impact] or "
                      "[load.pressure]" + (f", not {' and '.join(given)}" if given else ""))
        kind = given[0]
        if kind == "cycle":
            return self.cycle(self.table(ld["cycle"], "load.cycle"))
        if kind == "pressure":
            pr = self.table(ld["pressure"], "load.pressure")
            self.extra_keys(pr, {"distribution", "p0", "radius"}, "load.pressure")
            for k in ("distribution", "p0", "radius"):
                if k not in pr:
                    self.fail(f"load.pressure.{k}", "missing")
            from hertzmdr.numeric.pressures import DISTRIBUTIONS

            if not isinstance(pr["distribution"], str) \
                    or pr["distribution"] not in DISTRIBUTIONS:
                self.fail("load.pressure.distribution",
                          f"unknown distribution {pr['distribution']!r}"
                          f"{suggest(str(pr['distribution']), DISTRIBUTIONS)} (one of: "
                          + ", ".join(f"{k} (n = {n:g}, {eq})" for k, (n, eq)
                                      in DISTRIBUTIONS.items()) + ")")
            return Load("pressure", distribution=pr["distribution"],
                        p0=self.positive(pr["p0"], "pressure", "load.pressure.p0"),
                        radius=self.positive(pr["radius"], "length", "load.pressure.radius"))
        if kind == "impact":
            imp = self.table(ld["impact"], "load.impact")
            self.extra_keys(imp, {"velocity", "mass", "density"}, "load.impact")
            if "velocity" not in imp:
                self.fail("load.impact.velocity", "missing")
            if ("mass" in imp) == ("density" in imp):
                self.fail("load.impact", "give exactly one of mass or density")
            v = self.positive(imp["velocity"], "velocity", "load.impact.velocity")
            m = self.positive(imp["mass"], "mass", "load.impact.mass") if "mass" in imp else None
            rho = (self.positive(imp["density"], "density", "load.impact.density")
                   if "density" in imp else None)
            return Load("impact", velocity=v, mass=m, density=rho)
        dim = "length" if kind == "depth" else "force"
        value = ld[kind]
        if isinstance(value, dict):
            self.extra_keys(value, {"from", "to", "points", "spacing"}, f"load.{kind}")
            for k in ("from", "to", "points"):
                if k not in value:
                    self.fail(f"load.{kind}.{k}", "missing: a sweep is {from, to, points}")
            lo = self.quantity(value["from"], dim, f"load.{kind}.from")
            hi = self.quantity(value["to"], dim, f"load.{kind}.to")
            n = value["points"]
            if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= 100_000:
                self.fail(f"load.{kind}.points", f"must be an integer in [2, 100000], got {n!r}")
            if not 0 <= lo < hi:
                self.fail(f"load.{kind}", f"a sweep needs 0 <= from < to, got {lo} and {hi}")
            spacing = value.get("spacing", "linear")
            if spacing not in ("linear", "log"):
                self.fail(f"load.{kind}.spacing", f"must be \"linear\" or \"log\", got "
                          f"{spacing!r}")
            from hertzmdr.numeric.scene.study import spaced

            return Load(kind, spaced(lo, hi, n, spacing, self, f"load.{kind}").tolist(),
                        sweep=True, spacing=spacing)
        v = self.positive(value, dim, f"load.{kind}")
        return Load(kind, [v])
