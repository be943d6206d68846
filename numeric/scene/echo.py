"""The scene as understood, echoed in result.json, and read back from it.

:func:`inputs` adds to a run's document the hertzmdr version, ``scene``: the document as given
with every value the reader took as a quantity in SI with its unit (``{"value": 0.005,
"unit": "m"}``), every other number with its unit ("1" when it has none), file names resolved
against the scene's folder, strings and booleans as they were; and ``files``: each file the
scene read, with its SHA-256. It walks the parsed document generically, so a table or key added
to the schema is echoed without code here; a key the reader takes as a quantity (through
``_Reader.quantity``) gets its unit.

:func:`scene_of` turns such a document back into a scene (every ``{"value", "unit"}`` pair
into its SI number, which the reader takes as it took the original string), refusing a file
that changed since the run: ``hertzmdr run result.json`` then recomputes the same inputs.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from hertzmdr.numeric.scene.units import DIMENSIONS, to_si

#: the keys of an echoed quantity
PAIR = {"value", "unit"}


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _key(path: tuple, data: dict) -> str:
    """The reader's name of the value at ``path`` of the document (as in its errors):
    ``body[0] (wheel).radius``, ``load.depth.from``, ``body[1] (tip).radii[0]``."""
    out = ""
    for i, part in enumerate(path):
        if isinstance(part, int):
            out += f"[{part}]"
            if i == 1 and path[0] == "body":
                body = data["body"][part]
                name = body.get("name", f"body {part + 1}") if isinstance(body, dict) else ""
                out += f" ({name})"
        else:
            out += f".{part}" if out else part
    return out


def _how(path: tuple, spec) -> tuple[str, str] | None:
    """How the reader took the value at ``path``: its own record, or that of the list it is
    an element of (the two coordinates of a polygon's corner share one); a key of a table
    (a sweep's ``points``) has its own record or none."""
    for k in range(len(path), 0, -1):
        if not all(isinstance(part, int) for part in path[k:]):
            break
        got = spec.read_as.get(_key(path[:k], spec.raw))
        if got is not None:
            return got
    return None


def _echo(value, path: tuple, spec, files: list):
    if isinstance(value, dict):
        return {k: _echo(v, (*path, k), spec, files) for k, v in value.items()}
    if isinstance(value, list):
        return [_echo(v, (*path, j), spec, files) for j, v in enumerate(value)]
    how = _how(path, spec)
    if isinstance(value, bool):
        return value
    if how and how[0] == "path" and isinstance(value, str):
        resolved = ((spec.base_dir or Path.cwd()) / value).resolve()
        files.append({"key": _key(path, spec.raw), "given": value, "path": str(resolved),
                      "sha256": _sha256(resolved)})
        return str(resolved)
    if how and how[0] == "quantity" and how[1] in DIMENSIONS:
        return {"value": to_si(value, how[1]), "unit": DIMENSIONS[how[1]][0]}
    if isinstance(value, (int, float)):
        unit = how[1] if how and how[0] == "number" else "1"
        return {"value": value, "unit": unit}
    return value  # a name, a shape, an effect, a unit such as "nm"


def inputs(spec) -> dict:
    """The version, the scene as understood and the files it read, for the run's document."""
    from hertzmdr.numeric import __version__

    files: list[dict] = []
    scene = _echo(spec.raw, (), spec, files)
    scene["title"] = spec.title
    return {"hertzmdr_version": __version__, "scene": scene, "files": files}


def _plain(value):
    if isinstance(value, dict):
        if set(value) == PAIR:
            return value["value"]
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


def scene_of(doc: dict, where: str) -> dict:
    """The scene a run's document echoes, as a dict of SI numbers; SceneError if it has none
    or a file it read changed."""
    from hertzmdr.numeric.scene.schema import SceneError

    if not isinstance(doc, dict) or not isinstance(doc.get("scene"), dict):
        raise SceneError(where, "scene", "a result.json of `hertzmdr run` has the scene it ran "
                         "under \"scene\"; this document has none (the tour's --json prints a "
                         "list: read one scene's result.json)")
    for f in doc.get("files", []):
        path = Path(f["path"])
        if not path.is_file():
            raise SceneError(where, f["key"], f"the file {path} that the run read is gone")
        if _sha256(path) != f["sha256"]:
            raise SceneError(where, f["key"], f"the file {path} changed since the run (its "
                             "SHA-256 differs): the run cannot be reproduced from it")
    return _plain(doc["scene"])


def read_result(text: str, where: str) -> dict:
    """The scene of a result.json's text (:func:`scene_of`)."""
    from hertzmdr.numeric.scene.schema import SceneError

    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise SceneError(where, "", f"JSON syntax error: {exc}") from None
    return scene_of(doc, where)
