"""Reading an object folder's ``annotations.json`` back, checked (schema ``infmob-annotations/1``).

:func:`load` is what a robot, a task or an exporter calls on a folder it did not make: every problem is
one :class:`AnnotationError` line naming the file, the field and the fix; nothing is repaired silently.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

from .errors import InfmobError
from .interaction import ACTIONS, FORMAT, PATH_STEPS

PART_CLASSES = ("line_fixed_handle", "round_fixed_handle", "slider_button", "hinge_door", "slider_drawer",
                "slider_lid", "hinge_lid", "hinge_knob", "hinge_handle")
"""GAPartNet's nine actionable part classes (Geng et al., CVPR 2023)."""
JOINT_TYPES = ("revolute", "prismatic", "continuous")
MAX_BYTES = 64 << 20  # a generated file is < 1 MB; anything far larger is not ours


class AnnotationError(InfmobError, ValueError):
    """An ``annotations.json`` that is missing, unreadable or does not follow its schema."""


def _fail(path, where: str, problem: str) -> AnnotationError:
    return AnnotationError(f"{path}: {where}: {problem}; regenerate the object (infmob generate) or fix the file"
                           " (schema: docs/format.md, annotations.json)")


def _read(folder) -> tuple[Path, object]:
    if not isinstance(folder, (str, os.PathLike)):
        raise AnnotationError(f"load() needs an object folder path, got {type(folder).__name__}; pass the folder"
                              " that holds annotations.json")
    path = Path(folder) / "annotations.json"
    if os.path.islink(path) or not path.is_file():
        problem = "is a symbolic link" if os.path.islink(path) else "missing"
        raise AnnotationError(f"{path}: {problem}; pass a folder made by infmob generate (infmob-usd >= the"
                              " version that writes annotations), or regenerate it")
    try:
        if path.stat().st_size > MAX_BYTES:
            raise _fail(path, "file", f"larger than {MAX_BYTES >> 20} MB")
        return path, json.loads(path.read_bytes().decode("utf-8"),
                                parse_constant=lambda c: (_ for _ in ()).throw(ValueError(f"{c} is not a number")))
    except (OSError, UnicodeDecodeError, ValueError, RecursionError) as e:
        if isinstance(e, AnnotationError):
            raise
        raise _fail(path, "file", f"not valid UTF-8 JSON ({' '.join(str(e).split())[:80]})") from None


def _number(path, where: str, x, lo: float = -math.inf, hi: float = math.inf) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or not lo <= x <= hi:
        raise _fail(path, where, f"expected a finite number in [{lo}, {hi}], got {str(x)[:40]!r}")
    return float(x)


def _vector(path, where: str, x, unit: bool = False) -> list[float]:
    if not isinstance(x, list) or len(x) != 3:
        raise _fail(path, where, f"expected 3 numbers, got {str(x)[:40]!r}")
    v = [_number(path, f"{where}[{i}]", c) for i, c in enumerate(x)]
    if unit and abs(math.sqrt(sum(c * c for c in v)) - 1.0) > 1e-3:
        raise _fail(path, where, f"expected a unit vector, got {v}")
    return v


def _text(path, where: str, x, choices=None, nullable: bool = False):
    if x is None and nullable:
        return None
    if not isinstance(x, str) or not x or (choices is not None and x not in choices):
        allowed = f"one of {', '.join(choices)}" if choices else "a non-empty string"
        raise _fail(path, where, f"expected {allowed}, got {str(x)[:40]!r}")
    return x


def _grasp(path, where: str, g) -> None:
    if not isinstance(g, dict):
        raise _fail(path, where, "expected an object")
    _vector(path, f"{where}.position", g.get("position"))
    a = _vector(path, f"{where}.approach", g.get("approach"), unit=True)
    c = _vector(path, f"{where}.closing", g.get("closing"), unit=True)
    if abs(sum(x * y for x, y in zip(a, c))) > 1e-3:
        raise _fail(path, f"{where}.closing", "must be perpendicular to approach")
    _number(path, f"{where}.width", g.get("width"), 0.0, 1.0)
    _number(path, f"{where}.depth", g.get("depth"), 0.0, 1.0)
    blocked = g.get("blocked_by", [])
    if not isinstance(blocked, list) or not all(isinstance(n, str) and n for n in blocked):
        raise _fail(path, f"{where}.blocked_by", "expected a list of link names")


def _target(path, where: str, t, names: set) -> None:
    if not isinstance(t, dict):
        raise _fail(path, where, "expected an object")
    name = _text(path, f"{where}.joint", t.get("joint"))
    if name in names:
        raise _fail(path, f"{where}.joint", f"joint {name!r} is annotated twice")
    names.add(name)
    _text(path, f"{where}.joint_type", t.get("joint_type"), JOINT_TYPES)
    _text(path, f"{where}.link", t.get("link"))
    _text(path, f"{where}.part_class", t.get("part_class"), PART_CLASSES)
    _text(path, f"{where}.handle_class", t.get("handle_class"), PART_CLASSES[:2], nullable=True)
    _text(path, f"{where}.action", t.get("action"), ACTIONS)
    box = t.get("box")
    if not isinstance(box, dict):
        raise _fail(path, f"{where}.box", "expected an object with center, size, quat_wxyz")
    _vector(path, f"{where}.box.center", box.get("center"))
    for i, s in enumerate(_vector(path, f"{where}.box.size", box.get("size"))):
        _number(path, f"{where}.box.size[{i}]", s, 0.0)
    q = box.get("quat_wxyz")
    if not isinstance(q, list) or len(q) != 4 or \
            abs(math.sqrt(sum(_number(path, f"{where}.box.quat_wxyz", c) ** 2 for c in q)) - 1) > 1e-3:
        raise _fail(path, f"{where}.box.quat_wxyz", f"expected a unit quaternion (4 numbers), got {str(q)[:40]!r}")
    grasps = t.get("grasps")
    if not isinstance(grasps, list):
        raise _fail(path, f"{where}.grasps", "expected a list")
    for i, g in enumerate(grasps):
        _grasp(path, f"{where}.grasps[{i}]", g)
    _checked_motion(path, where, t, bool(grasps))


def _checked_motion(path, where: str, t: dict, grasped: bool) -> None:
    rest, opened = (_number(path, f"{where}.{k}", t.get(k)) for k in ("rest", "open"))
    if rest == opened:
        raise _fail(path, f"{where}.open", "equals rest: a target must move")
    _number(path, f"{where}.open_threshold", t.get("open_threshold"), 0.0, 1.0)
    _number(path, f"{where}.closed_threshold", t.get("closed_threshold"), 0.0, 1.0)
    if t["closed_threshold"] >= t["open_threshold"]:
        raise _fail(path, f"{where}.closed_threshold", "must be below open_threshold")
    p = t.get("path")
    if not isinstance(p, list) or len(p) != (PATH_STEPS + 1 if grasped else 0):
        raise _fail(path, f"{where}.path", f"expected {PATH_STEPS + 1 if grasped else 0} points")
    for i, x in enumerate(p):
        _vector(path, f"{where}.path[{i}]", x)
    if grasped:
        _vector(path, f"{where}.direction", t.get("direction"), unit=True)
    for key in ("requires_open", "requires_closed"):
        names = t.get(key, [])
        if not isinstance(names, list) or not all(isinstance(n, str) and n for n in names):
            raise _fail(path, f"{where}.{key}", "expected a list of joint names")


def load(folder) -> dict:
    """The checked ``annotations.json`` of an object folder (the schema of docs/format.md).

    Raises :class:`AnnotationError` (one line: the file, the field, the fix) for a missing, unreadable,
    oversized or malformed file, a symbolic link, an unknown format, a field of the wrong type, a
    non-finite number, a non-unit direction, a path of the wrong length or a joint annotated twice.
    """
    path, doc = _read(folder)
    if not isinstance(doc, dict):
        raise _fail(path, "document", "expected a JSON object")
    if doc.get("format") != FORMAT:
        raise _fail(path, "format", f"expected {FORMAT!r}, got {str(doc.get('format'))[:40]!r}")
    targets = doc.get("targets")
    if not isinstance(targets, list):
        raise _fail(path, "targets", "expected a list")
    names: set = set()
    for i, t in enumerate(targets):
        _target(path, f"targets[{i}]", t, names)
    return doc
