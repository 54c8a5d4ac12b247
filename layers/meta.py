"""semantics.txt (PartNet-Mobility style) and metadata.json."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .common import PM_JOINT_TYPE


def write_semantics(obj, folder: Path) -> Path:
    """``link_name joint_type semantic_label`` for every non-dummy link."""
    into = {j.child: j.kind for j in obj.joints}
    lines = [f"{link.name} {PM_JOINT_TYPE[into.get(link.name, 'fixed')]} {link.label}"
             for link in obj.links if not link.dummy]
    path = folder / "semantics.txt"
    path.write_text("\n".join(lines) + "\n")
    return path


def _clean(x):
    if isinstance(x, dict):
        return {str(k): _clean(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if isinstance(x, np.ndarray):
        return _clean(x.tolist())
    if isinstance(x, (np.floating, float)):
        return round(float(x), 9)
    if isinstance(x, np.integer):
        return int(x)
    return x


def metadata(obj) -> dict:
    """Everything a dataset tool needs without parsing USD: a JSON-able dict."""
    lo, hi = obj.bounds()
    return _exact_overrides(obj, _clean({
        "name": obj.name,
        "category": obj.category,
        "seed": obj.seed,
        "version": obj.version,
        "texture_size": obj.texture_size,
        "parameters": obj.params,
        "overrides": obj.overrides,
        "bounds": [lo, hi],
        "counts": {
            "links": sum(1 for link in obj.links if not link.dummy),
            "dummy_links": sum(1 for link in obj.links if link.dummy),
            "joints": len(obj.joints),
            "movable_joints": sum(1 for j in obj.joints if j.movable),
            "declared_movable_joints": sum(obj.joint_kinds().values()),
        },
        "joint_kinds": obj.joint_kinds(),
        "links": [
            {"name": link.name, "label": link.label, "dummy": link.dummy, "mass": link.mass,
             "origin": link.origin}
            for link in obj.links
        ],
        "joints": [
            {"name": j.name, "type": j.type, "kind": j.kind, "group": j.group, "role": j.role,
             "parent": j.parent, "child": j.child, "origin": j.origin, "axis": j.axis,
             "lower": j.lower, "upper": j.upper, "damping": j.damping, "friction": j.friction,
             "requires_open": j.requires_open}
            for j in obj.joints
        ],
        "materials": {slot: look.to_dict() for slot, look in obj.materials.items()},
        "files": {
            "usd": f"./{obj.name}.usda",
            "urdf": f"./{obj.name}.urdf",
            "semantics": "./semantics.txt",
        },
    }))


def _exact_overrides(obj, meta: dict) -> dict:
    """Overrides are stored unrounded, so replaying an object's own overrides gives the same object."""
    meta["overrides"] = {str(k): v.item() if isinstance(v, np.generic) else v for k, v in obj.overrides.items()}
    return meta


def write_metadata(obj, folder: Path) -> Path:
    path = folder / "metadata.json"
    path.write_text(json.dumps(metadata(obj), indent=2, sort_keys=False) + "\n")
    return path
