"""Test-only annotations (schema ``infmob-annotations/1``, /work/ANNOTATIONS.md) computed from a written object
folder, so that the robot check can be exercised before the build writes ``annotations.json`` itself.

Covers the simple case only: a door or drawer whose joint hangs off the root link and whose handle is a
visual mesh ``meshes/<link>__handle_handle.obj`` (the handle's vertices are in the link frame). The grasp is
the middle of the handle's front face, approached along -X (fronts face +X), fingers closing across the
handle's thinner side; the path is the grasp point moved by the joint (other joints at rest).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

FRACTIONS = [i / 10 for i in range(11)]


def _obj_vertices(path: Path) -> np.ndarray:
    return np.array([[float(x) for x in line.split()[1:4]] for line in path.read_text().splitlines()
                     if line.startswith("v ")])


def _rotate(p: np.ndarray, origin: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """``p`` turned by ``angle`` about the line through ``origin`` along unit ``axis`` (Rodrigues)."""
    v = p - origin
    c, s = math.cos(angle), math.sin(angle)
    return origin + v * c + np.cross(axis, v) * s + axis * float(axis @ v) * (1 - c)


def _target(folder: Path, joint: dict, groups: dict[str, str]) -> dict | None:
    link = joint["child"]
    mesh = folder / "meshes" / f"{link}__handle_handle.obj"
    if joint["type"] not in ("revolute", "prismatic") or not mesh.is_file():
        return None
    v = _obj_vertices(mesh)
    lo, hi = v.min(0), v.max(0)
    size, center = hi - lo, (hi + lo) / 2
    position = np.array([hi[0], center[1], center[2]])  # the front face's middle (link frame)
    closing = [0.0, 1.0, 0.0] if size[1] <= size[2] else [0.0, 0.0, 1.0]
    width = float(min(size[1], size[2]))
    origin, axis = np.array(joint["origin"], float), np.array(joint["axis"], float)
    at_rest = origin + position  # the link frame is the joint frame, unrotated at rest (root parent)
    opened = float(joint["upper"])
    if joint["type"] == "revolute":
        path = [_rotate(at_rest, origin, axis, f * opened) for f in FRACTIONS]
        part, action = "hinge_door", "pull"
    else:
        path = [at_rest + axis * f * opened for f in FRACTIONS]
        part, action = "slider_drawer", "pull"
    needs = joint.get("requires_open")
    return {
        "joint": joint["name"], "joint_type": joint["type"], "link": link, "part_class": part,
        "handle_class": "line_fixed_handle",
        "box": {"center": center.tolist(), "size": size.tolist(), "quat_wxyz": [1.0, 0.0, 0.0, 0.0]},
        "grasps": [{"position": position.tolist(), "approach": [-1.0, 0.0, 0.0], "closing": closing,
                    "width": width}],
        "action": action, "rest": float(joint["lower"]), "open": opened,
        "open_threshold": 0.9, "closed_threshold": 0.05,
        "path": [p.tolist() for p in path],
        "requires_open": [groups[g] for g in ([needs] if isinstance(needs, str) else needs or []) if g in groups],
    }


def write_annotations(folder: str | Path) -> list[dict]:
    """Write ``annotations.json`` into ``folder`` for every handled door and drawer hung off the root link;
    returns the targets."""
    folder = Path(folder)
    meta = json.loads((folder / "metadata.json").read_text())
    root = meta["links"][0]["name"]
    groups = {j["child"]: j["name"] for j in meta["joints"]}
    targets = [t for j in meta["joints"] if j["parent"] == root
               for t in [_target(folder, j, groups)] if t is not None]
    doc = {"format": "infmob-annotations/1",
           "units": "metres, radians for revolute/continuous joints, metres for prismatic; Z up, fronts face +X",
           "targets": targets}
    (folder / "annotations.json").write_text(json.dumps(doc, indent=1) + "\n")
    return targets
