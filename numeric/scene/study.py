"""Parameter studies: a scene that sweeps one numeric key, or two (a map).

A sweep is written on the key itself, the form the load sweep has always had::

    radius = { from = "1 mm", to = "10 mm", points = 10, spacing = "log" }

on a body's ``E``, ``nu`` or a numeric key of its shape (``radius``, ``axis``, ``length``, ...),
on ``[interface]`` ``work_of_adhesion``, ``range``, ``friction``, or on a load's numbers
(``depth``, ``force``, ``[load.impact]`` ``velocity``/``mass``/``density``, ``[load.pressure]``
``p0``/``radius``, ``[load.tangential]``, ``[load.oscillating]`` ``amplitude``). One swept key
is a study along a line; two make a grid (the first key in the file is the first axis).

Reading (:func:`read_scene`): each sweep is checked like a load sweep (``from``, ``to``,
``points``, ``spacing``); then the scene is read once at each corner of the study (and at 0 when
a sweep crosses it) with the swept keys set to those values, so that a value the key does not
take is the key's own one-line error, before anything is computed.

Running (:func:`run`): every point of the study is one scene (one load). Closed-form studies of
a circular Hertz contact (swept: a sphere's radius, E, nu, the load) are evaluated as arrays
across all points at once (:class:`_HertzArrays`); every other study runs the scene once per
point, each run computing only the requested effects and the nodes they need
(:func:`hertzmdr.numeric.scene.runner.run`). A scene whose only sweep is its load keeps the
load sweep's own behaviour (scalar effects over the load, fields and maxima at the largest load)
and gains the study's output (the swept load in the result, results.csv, plots).
"""

from __future__ import annotations

import copy
import dataclasses
import functools
import itertools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from hertzmdr.numeric.scene.effects import EFFECTS
from hertzmdr.numeric.scene.runner import Result, to_json_value
from hertzmdr.numeric.scene.schema import SceneError, SceneSpec
from hertzmdr.numeric.scene.units import DIMENSIONS

#: the points of one swept key (the load sweep's limit), and of a whole study (a grid)
MAX_AXIS_POINTS, MAX_POINTS = 100_000, 1_000_000
#: field effects (profiles, maps) are kept per point up to this many points: a closed-form
#: von Mises map is 101 x 101 numbers, over 100 points about 20 MB of JSON
MAX_FIELD_POINTS = 100
#: the SI unit of a swept plain number (nu, friction)
NUMBER = "number"
#: effects a circular Hertz contact evaluates as arrays over every point of a study (closed
#: forms whose inputs are the depth or force, R, E* and, for the stress maxima, one nu)
VECTOR_EFFECTS = frozenset({"depth", "force", "contact_radius", "max_pressure", "mean_pressure",
                            "stiffness", "elastic_energy", "effective_modulus",
                            "effective_radius", "principal_radii", "max_shear", "max_von_mises",
                            "max_orthogonal_shear"})
STRESS_MAXIMA = frozenset({"max_shear", "max_von_mises", "max_orthogonal_shear"})
#: the tables of the load whose numbers may be swept: key -> dimension
LOAD_TABLES = {"impact": {"velocity": "velocity", "mass": "mass", "density": "density"},
               "pressure": {"p0": "pressure", "radius": "length"},
               "tangential": {"force": "force", "displacement": "length"},
               "oscillating": {"amplitude": "force"}}
INTERFACE_DIMS = {"work_of_adhesion": "surface_energy", "range": "length", "friction": NUMBER}


@dataclass(frozen=True)
class Axis:
    """One swept key.

    Attributes
    ----------
    key : str
        The key as errors name it: ``body[0] (ball).radius``, ``load.force``.
    path : tuple
        Where it lives in the scene: ``("body", 0, "radius")``, ``("load", "force")``,
        ``("interface", "friction")``, ``("load", "impact", "velocity")``.
    unit : str
        Its SI unit (``"1"`` for a plain number).
    values : numpy.ndarray
        Its values [SI], ``from`` to ``to``.
    spacing : str
        ``"linear"`` or ``"log"``.
    """

    key: str
    path: tuple
    unit: str
    values: np.ndarray
    spacing: str

    @property
    def is_load(self) -> bool:
        return self.path[0] == "load" and len(self.path) == 2

    @property
    def column(self) -> str:
        """Its header in results.csv: ``key [unit]``."""
        return f"{self.key} [{self.unit}]"


@dataclass(frozen=True)
class Study:
    """The swept keys of a scene: one axis, or two (a grid, the first axis the slower)."""

    axes: tuple[Axis, ...]

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    @property
    def load_only(self) -> bool:
        """A load sweep alone: the scene keeps the load sweep's own run."""
        return len(self.axes) == 1 and self.axes[0].is_load

    def grid(self) -> list[np.ndarray]:
        """Each axis' value at each point, flattened in row order (the CSV's rows)."""
        mesh = np.meshgrid(*(a.values for a in self.axes), indexing="ij")
        return [m.reshape(-1) for m in mesh]

    def block(self) -> dict:
        """The ``study`` entry of the JSON document."""
        grid = self.grid()
        return {"shape": list(self.shape),
                "axes": [{"key": a.key, "unit": a.unit, "spacing": a.spacing,
                          "values": a.values.tolist()} for a in self.axes],
                "points": {a.key: g.tolist() for a, g in zip(self.axes, grid, strict=True)}}


# -- reading ------------------------------------------------------------------------------------

def _sweep_sites(data: dict) -> list[tuple[tuple, str, str]]:
    """(path, key, dimension) of every key in ``data`` whose value is a table where a number
    belongs: a sweep form, in the order of the file."""
    from hertzmdr.numeric.scene.shapes import SHAPES

    sites = []
    for top, value in data.items():
        if top == "body" and isinstance(value, list):
            for i, b in enumerate(value):
                if not isinstance(b, dict):
                    continue
                name = b.get("name", f"body {i + 1}")
                shape = SHAPES.get(b.get("shape")) if isinstance(b.get("shape"), str) else None
                dims = {"E": "pressure", "nu": NUMBER}
                if shape is not None:
                    dims |= {k.name: (NUMBER if k.kind == "number" else k.kind)
                             for k in shape.keys if k.kind in ("length", "angle", "number")}
                for k, v in b.items():
                    if isinstance(v, dict) and k in dims:
                        sites.append((("body", i, k), f"body[{i}] ({name}).{k}", dims[k]))
        elif top == "interface" and isinstance(value, dict):
            for k, v in value.items():
                if isinstance(v, dict) and k in INTERFACE_DIMS:
                    sites.append((("interface", k), f"interface.{k}", INTERFACE_DIMS[k]))
        elif top == "load" and isinstance(value, dict):
            for k, v in value.items():
                if k in ("depth", "force") and isinstance(v, dict):
                    sites.append((("load", k), f"load.{k}", "length" if k == "depth" else
                                  "force"))
                elif k in LOAD_TABLES and isinstance(v, dict):
                    for kk, vv in v.items():
                        if isinstance(vv, dict) and kk in LOAD_TABLES[k]:
                            sites.append((("load", k, kk), f"load.{k}.{kk}",
                                          LOAD_TABLES[k][kk]))
    return sites


def sweep_values(reader, value: dict, key: str, dim: str) -> tuple[np.ndarray, str]:
    """The points [SI] and spacing of one sweep form ``{from, to, points, spacing}``; a
    SceneError naming ``key`` for any problem. (The load sweep's own reader is
    :meth:`~.schema._Reader.normal_load`, which keeps its rule 0 <= from.)"""
    reader.extra_keys(value, {"from", "to", "points", "spacing"}, key)
    for k in ("from", "to", "points"):
        if k not in value:
            reader.fail(f"{key}.{k}", "missing: a sweep is {from, to, points} (and optionally "
                        "spacing = \"linear\" or \"log\")")
    ends = []
    for k in ("from", "to"):
        v = value[k]
        if dim == NUMBER:
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                reader.fail(f"{key}.{k}", f"must be a finite number, got {v!r}")
            ends.append(float(v))
        else:
            ends.append(reader.quantity(v, dim, f"{key}.{k}"))
    lo, hi = ends
    n = value["points"]
    if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= MAX_AXIS_POINTS:
        reader.fail(f"{key}.points", f"must be an integer in [2, {MAX_AXIS_POINTS}], got {n!r}")
    spacing = value.get("spacing", "linear")
    if spacing not in ("linear", "log"):
        reader.fail(f"{key}.spacing", f"must be \"linear\" or \"log\", got {spacing!r}")
    if not lo < hi:
        reader.fail(key, f"a sweep needs from < to, got {lo:g} and {hi:g}")
    return spaced(lo, hi, n, spacing, reader, key), spacing


def spaced(lo: float, hi: float, n: int, spacing: str, reader, key: str) -> np.ndarray:
    """n points from lo to hi, both exactly: evenly spaced, or evenly in log (0 < lo)."""
    if spacing == "log":
        if not lo > 0:
            reader.fail(f"{key}.spacing", f"log spacing needs 0 < from, got {lo:g}")
        v = np.exp(np.linspace(math.log(lo), math.log(hi), n))
        v[0], v[-1] = lo, hi
        return v
    return np.array([lo + (hi - lo) * i / (n - 1) for i in range(n)])  # the load sweep's rule


def _set_raw(data: dict, path: tuple, value) -> None:
    target = data
    for p in path[:-1]:
        target = target[p]
    target[path[-1]] = value


def read_scene(reader, data: dict, default_title: str) -> SceneSpec:
    """Read a scene dict with its sweeps: a :class:`SceneSpec` whose ``study`` is None (no
    sweep), the load sweep alone, or the study (its scene read at the first corner)."""
    sites = _sweep_sites(data) if isinstance(data, dict) else []
    if len(sites) > 2:
        reader.fail(sites[2][1], "a study sweeps one key, or two (a map); this scene sweeps "
                    f"{len(sites)}: " + ", ".join(key for _, key, _ in sites))
    others = [s for s in sites if not (s[0][0] == "load" and len(s[0]) == 2)]
    if not others:
        spec = reader.scene(data, default_title)
        if spec.load.sweep:
            kind = spec.load.kind
            spec.study = Study((Axis(f"load.{kind}", ("load", kind),
                                     DIMENSIONS["length" if kind == "depth" else "force"][0],
                                     np.asarray(spec.load.values, float),
                                     spec.load.spacing),))
        return spec
    parsed = {path: (key, *sweep_values(reader, _get_raw(data, path), key, dim))
              for path, key, dim in others}
    corners = [{path: v for path, v in zip(parsed, ends, strict=True)}
               for ends in itertools.product(*((float(vals[0]), float(vals[-1]))
                                               for _, vals, _ in parsed.values()))]
    for path, (_, vals, _) in parsed.items():  # a sweep across 0: the key must take 0 too
        if vals[0] < 0 < vals[-1]:
            corners.append({**corners[0], path: 0.0})
    first = None
    for corner in corners:
        raw = copy.deepcopy(data)
        for path, v in corner.items():
            _set_raw(raw, path, v)
        try:
            spec = reader.scene(raw, default_title)
        except SceneError as exc:
            units = {path: DIMENSIONS[dim][0] if dim != NUMBER else "1"
                     for path, _, dim in others}
            at = ", ".join(f"{parsed[p][0]} = {show(v, units[p])}" for p, v in corner.items())
            raise SceneError(exc.where, exc.key, f"{exc.message} (at the study point {at})") \
                from None
        first = first or spec
    axes = []
    for path, key, dim in sites:
        if path in parsed:
            _, vals, spacing = parsed[path]
            axes.append(Axis(key, path, DIMENSIONS[dim][0] if dim != NUMBER else "1", vals,
                             spacing))
        else:  # the load, swept too: its values as the load sweep reads them
            axes.append(Axis(key, path, DIMENSIONS[dim][0], np.asarray(first.load.values, float),
                             first.load.spacing))
    study = Study(tuple(axes))
    if study.size > MAX_POINTS:
        reader.fail(axes[-1].key, f"a study has at most {MAX_POINTS} points; this one has "
                    f"{' x '.join(map(str, study.shape))} = {study.size}")
    fields = [e for e in first.effects if EFFECTS[e].field]
    if fields and study.size > MAX_FIELD_POINTS:
        reader.fail("effects", f"the field effects ({', '.join(fields)}) are kept per point of a "
                    f"study up to {MAX_FIELD_POINTS} points (a von Mises map is 101 x 101 numbers "
                    f"a point); this study has {study.size}: ask for fewer points, or for scalar "
                    "effects only")
    first.study = study
    return first


def _get_raw(data: dict, path: tuple):
    target = data
    for p in path:
        target = target[p]
    return target


# -- one point ----------------------------------------------------------------------------------

def at_point(spec: SceneSpec, axes: tuple[Axis, ...], values) -> SceneSpec:
    """The scene ``spec`` with each axis' key set to its value in ``values`` (floats, or arrays
    over the points for :class:`_HertzArrays`); the load becomes one value (not a sweep)."""
    out = copy.copy(spec)
    out.bodies = [copy.copy(b) for b in spec.bodies]
    for b in out.bodies:
        b.params = dict(b.params)
    out.load = copy.copy(spec.load)
    out.study = None
    for axis, v in zip(axes, values, strict=True):
        p = axis.path
        if p[0] == "body":
            body = out.bodies[p[1]]
            if p[2] in ("E", "nu"):
                setattr(body, p[2], v)
            else:
                body.params[p[2]] = v
        elif p[0] == "interface":
            out.interface = dataclasses.replace(out.interface, **{p[1]: v})
        elif len(p) == 2:  # the load
            out.load.values, out.load.sweep = (v if np.ndim(v) else [v]), False
        elif p[1] in ("tangential", "oscillating"):
            out.load.tangential = dataclasses.replace(out.load.tangential, value=v)
        else:  # [load.impact] velocity/mass/density, [load.pressure] p0/radius
            setattr(out.load, p[2], v)
    return out


def at_the_point(exc: SceneError, axes, values) -> SceneError:
    """``exc`` with the study point it happened at appended to its message."""
    at = ", ".join(f"{a.key} = {show(float(v), a.unit)}" for a, v in zip(axes, values,
                                                                         strict=True))
    return SceneError(exc.where, exc.key, f"{exc.message} (at the study point {at})")


# -- running ------------------------------------------------------------------------------------

@dataclass
class StudyRun:
    """What :func:`run` returns: the results (each value one entry per point, in the order of
    :meth:`Study.grid`), the model of each point, and how the study was evaluated."""

    study: Study
    results: dict[str, Result]
    models: list  # the contact of each point (or the one array contact): their info()
    warnings: list[dict]
    route: str  # "arrays" or "per point"
    evaluated: list[str]  # the effects and nodes evaluated, in order (of every point)
    seconds: float


def run(spec: SceneSpec, progress: Callable[[int, int], None] | None = None) -> StudyRun:
    """Run the study of ``spec`` (``spec.study``, not a load sweep alone): as arrays where the
    contact and every requested effect allow it, else point by point (``progress(done, total)``
    is called after each point)."""
    t0 = time.perf_counter()
    out = _HertzArrays.attempt(spec)
    if out is None:
        out = _per_point(spec, progress)
    out.seconds = time.perf_counter() - t0
    return out


def _per_point(spec: SceneSpec, progress) -> StudyRun:
    from hertzmdr.numeric.scene.runner import run as run_scene

    study = spec.study
    grid = study.grid()
    values: dict[str, list] = {e: [] for e in spec.effects}
    meta: dict[str, list[Result]] = {e: [] for e in spec.effects}
    models, warnings, evaluated = [], [], []
    for k in range(study.size):
        point = tuple(float(g[k]) for g in grid)
        try:
            record, results = run_scene(at_point(spec, study.axes, point))
        except SceneError as exc:
            raise at_the_point(exc, study.axes, point) from None
        evaluated += record.evaluated
        models.append(record.contact)
        warnings += [dict(w, point=k) for w in record.warnings]
        for name, res in results.items():
            values[name].append(_squeeze(to_json_value(res.value)))
            meta[name].append(res)
        if progress is not None:
            progress(k + 1, study.size)
    results = {name: _merge(name, values[name], meta[name]) for name in spec.effects}
    return StudyRun(study, results, models, _worst(warnings, study), "per point", evaluated, 0.0)


def _squeeze(v):
    """A one-load value as a number (a run of one load gives arrays of one)."""
    if isinstance(v, list) and v and all(isinstance(x, list) and len(x) == 1 for x in v):
        return [x[0] for x in v]
    if isinstance(v, list) and len(v) == 1 and not isinstance(v[0], (list, dict)):
        return v[0]
    if isinstance(v, dict):
        return {k: _squeeze(x) for k, x in v.items()}
    return v


def _merge(name: str, values: list, results: list[Result]) -> Result:
    """One effect over the study: a list per point (fields), or arrays over the points
    (numbers, lists of numbers, tables of numbers)."""
    first = values[0]
    if EFFECTS[name].field:
        value = values
    elif isinstance(first, dict):
        value = {k: np.asarray([v[k] for v in values], float) for k in first}
    else:
        value = np.asarray(values, float)
    methods = list(dict.fromkeys(r.method for r in results))
    err = max(r.rel_error for r in results)
    return Result(name, value, results[0].unit, "; ".join(methods), err,
                  all(r.met_rtol for r in results), sum(r.seconds for r in results))


def _worst(warnings: list[dict], study: Study, corners: bool = False) -> list[dict]:
    """One warning per ratio: the point that stretches it most, named in the message
    (``corners``: only the study's corners were checked, which the message says)."""
    from hertzmdr.numeric.scene.assumptions import ASSUMPTIONS

    grid = study.grid()
    best: dict[str, dict] = {}
    for w in warnings:
        a = ASSUMPTIONS[w["ratio"]]
        old = best.get(w["ratio"])
        worse = old is None or (w["value"] > old["value"] if a.direction == "above"
                                else w["value"] < old["value"])
        if worse:
            best[w["ratio"]] = w
    out = []
    for w in best.values():
        k = w.pop("point")
        at = ", ".join(f"{a.key} = {show(float(g[k]), a.unit)}" for a, g in
                       zip(study.axes, grid, strict=True))
        n = sum(1 for x in warnings if x["ratio"] == w["ratio"])
        where = (f"at {n} of the {2 ** len(study.axes)} corners of the study, where it is "
                 "checked" if corners else f"at {n} of {study.size} points")
        out.append({**w, "message": f"{w['message']} ({where}; the largest at {at})"})
    return out


def show(value: float, unit: str) -> str:
    """A swept value as the tables print it: engineering notation, an angle in degrees, a
    plain number as it is."""
    from hertzmdr.numeric.scene.units import engineering

    if unit == "1":
        return f"{value:.6g}"
    if unit == "rad":
        return f"{math.degrees(value):.6g} deg"
    return engineering(value, unit)


class _HertzArrays:
    """A circular Hertz contact whose R, E* and load are arrays over the study's points: one
    evaluation of each requested closed form for the whole study.

    Taken when the scene at each corner of the study is a circular Hertz contact of two
    quadratic bodies (spheres, flats) under a depth or a force, the swept keys are among a
    sphere's radius, E, nu and the load, every requested effect is a closed form of
    :data:`VECTOR_EFFECTS`, and nu of the stressed body is not swept when a stress maximum is
    asked for (its location is searched once per nu). The contact at each corner is built and
    checked as a single scene (its rtol, what applies, its warnings)."""

    @staticmethod
    def attempt(spec: SceneSpec) -> StudyRun | None:
        from hertzmdr.numeric.scene.assumptions import check as check_assumptions
        from hertzmdr.numeric.scene.kinds.hertz import HertzContact
        from hertzmdr.numeric.scene.model import build
        from hertzmdr.numeric.scene.runner import Run, check_applicable

        study = spec.study
        if not set(spec.effects) <= VECTOR_EFFECTS or spec.load.kind not in ("depth", "force") \
                or spec.interface.adhesive or spec.load.tangential is not None:
            return None
        for axis in study.axes:
            p = axis.path
            ok = axis.is_load or (p[0] == "body" and (p[2] in ("E", "nu") or (
                spec.bodies[p[1]].shape == "sphere" and p[2] == "radius")))
            if not ok:
                return None
        if any(b.shape not in ("sphere", "flat") for b in spec.bodies):
            return None
        stressed = next(i for i, b in enumerate(spec.bodies) if not b.rigid)
        if STRESS_MAXIMA & set(spec.effects) and any(
                a.path == ("body", stressed, "nu") for a in study.axes):
            return None
        corners = list(itertools.product(*((a.values[0], a.values[-1]) for a in study.axes)))
        warnings, evaluated = [], []
        for k, corner in enumerate(corners):
            one = at_point(spec, study.axes, corner)
            try:
                contact = build(one)
                if type(contact) is not HertzContact:
                    return None
                check_applicable(one, contact)
            except SceneError as exc:
                raise at_the_point(exc, study.axes, corner) from None
            r = Run(one, contact)
            for n in dict.fromkeys(n for e in spec.effects for n in EFFECTS[e].needs):
                r.node(n)
            evaluated += r.evaluated
            warnings += [dict(w, point=_corner_index(study, k)) for w in
                         check_assumptions(contact.ratios(r._nodes))]
        arrays = at_point(spec, study.axes, study.grid())
        contact = _HertzArrays.contact(arrays)
        if contact is None:
            return None
        r = Run(arrays, contact)
        results = {name: r.effect(name) for name in spec.effects}
        n = study.size
        results = {name: dataclasses.replace(res, value=_per_point_value(res.value, n))
                   for name, res in results.items()}
        return StudyRun(study, results, [contact], _worst(warnings, study, corners=True), "arrays",
                        evaluated + r.evaluated, 0.0)

    @staticmethod
    def contact(spec: SceneSpec):
        """The array contact, or None when some point is not circular (that study runs point
        by point, each point's own builder deciding)."""
        from hertzmdr.numeric import bodies
        from hertzmdr.numeric.scene.kinds.quadratic import CIRCULAR_RTOL
        from hertzmdr.numeric.scene.materials import Material, Materials
        from hertzmdr.numeric.scene.shapes import SHAPES

        elastic = [b for b in spec.bodies if not b.rigid]
        E_star = bodies.effective_modulus(*(v for b in elastic for v in (b.E, b.nu)))  # (5.26)
        mats = Materials(tuple(Material(b.name, b.E, b.nu) for b in spec.bodies), E_star)
        (a1, b1, t1), (a2, b2, t2) = (SHAPES[b.shape].principal(b.params) for b in spec.bodies)
        R1, R2 = (np.asarray(v, float) for v in bodies.principal_radii(a1, b1, a2, b2, t2 - t1))
        if not np.all(np.abs(R1 - R2) <= CIRCULAR_RTOL * np.maximum(R1, R2)):
            return None
        # quadratic.build's choice, point by point: R itself when equal, else (5.30)
        R, unequal = R1.copy(), R1 != R2
        if unequal.any():
            R[unequal] = bodies.gaussian_radius(R1[unequal], R2[unequal])  # (5.30)
        return _hertz_study_contact()(mats, spec.interface, spec.rtol, R=R,
                                      principal_radii=[R1, R2])


def _corner_index(study: Study, k: int) -> int:
    """The point (row of :meth:`Study.grid`) of corner k of the study, in the order
    :func:`itertools.product` gives the corners (the last axis fastest)."""
    n = len(study.axes)
    idx = [(len(a.values) - 1) * ((k >> (n - 1 - j)) & 1) for j, a in enumerate(study.axes)]
    return int(np.ravel_multi_index(idx, study.shape))


def _per_point_value(value, n: int):
    """An array contact's value as one entry per point: scalars broadcast, [R1, R2] as n x 2."""
    if isinstance(value, dict):
        return {k: np.broadcast_to(np.asarray(v, float), (n,)).copy() for k, v in value.items()}
    if isinstance(value, list):
        return np.stack([np.broadcast_to(np.asarray(v, float), (n,)) for v in value], axis=-1)
    return np.broadcast_to(np.asarray(value, float), (n,)).copy()


@functools.cache
def _hertz_study_contact() -> type:
    """The Hertz contact with arrays, its stresses at each point's own load (not at the
    largest load of a load sweep); made on first use, so that reading a scene does not import
    the Hertz kind."""
    from hertzmdr.numeric import hertz
    from hertzmdr.numeric.scene.kinds.hertz import HertzContact
    from hertzmdr.numeric.scene.kinds.stresses import HertzStresses

    class HertzStudyContact(HertzContact):
        def stress_solver(self, st):
            return HertzStresses(np.asarray(hertz.contact_radius(st.depth, self.R), float),
                                 np.asarray(hertz.max_pressure(st.depth, self.R, self.E_star),
                                            float),
                                 self.materials.stressed.nu)

    return HertzStudyContact


def document(spec: SceneSpec, out: StudyRun) -> dict:
    """The JSON document of a study: the load sweep's layout, each effect's value one entry
    per point (numbers: a list; tables of numbers: a table of lists; fields: a list of
    fields), and ``study`` with the axes, the shape and the swept values at every point."""
    from hertzmdr.numeric.scene.echo import inputs

    models = [{k: to_json_value(v) for k, v in c.info().items()} for c in out.models]
    model = {}
    for k in models[0]:
        vals = [m.get(k) for m in models]
        model[k] = vals[0] if all(v == vals[0] for v in vals) else vals
    return {
        "title": spec.title,
        "model": model,
        "study": {**out.study.block(), "route": out.route, "seconds": out.seconds},
        "effects": {name: {"value": to_json_value(res.value), "unit": res.unit,
                           "method": res.method, "rel_error": res.rel_error,
                           "met_rtol": res.met_rtol, "seconds": res.seconds}
                    for name, res in out.results.items()},
        "warnings": out.warnings,
        **inputs(spec),  # the scene as understood, the files it read, the version (echo.py)
    }
