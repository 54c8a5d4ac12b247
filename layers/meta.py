"""semantics.txt (PartNet-Mobility style) and metadata.json."""

from __future__ import annotations

import datetime
import json
import os
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


# Wikidata item of each category, verified on a stored public copy of its Wikidata page (URL beside it).
# A category missing here has no verified Q-code: its SimReady metadata leaves `qcode` out (SR.004 then fails).
WIKIDATA: dict[str, tuple[str, str]] = {
}

LICENSE = "Apache-2.0"  # the licence of infmob-usd, under which its generated assets are released


def date_generated() -> str:
    """``usd_date_generated`` (ISO ``YYYY-MM-DD``), deterministic so the same seed gives the same bytes:
    the UTC date of ``SOURCE_DATE_EPOCH`` when set (the reproducible-builds convention), else the release
    date of this version of infmob-usd."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if epoch:
        try:
            return datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc).date().isoformat()
        except (ValueError, OverflowError, OSError):
            raise ValueError(f"SOURCE_DATE_EPOCH={epoch!r} is not a Unix time in seconds; fix or unset it") from None
    from infmob_usd._version import __release_date__

    return __release_date__


def simready_metadata(obj, bounds) -> dict:
    """SimReady provenance metadata (``SimReady_Metadata`` in the USD root layer, SR.004): author, asset name,
    type, licence, category, source, date, Wikidata Q-code (when verified), rigid-body count, extents (m) and
    mass (kg). ``bounds`` is the ``(2, 3)`` world bounds of the visual meshes."""
    lo, hi = (np.asarray(b, float) for b in bounds)
    meta = {
        "author": "infmob-usd",
        "asset_name": obj.name,
        "asset_type": "prop",
        "asset_license": LICENSE,
        "category": obj.category,
        "source_file": f"infmob_usd.categories.{obj.category} (infmob-usd {obj.version}, seed {obj.seed})",
        "usd_date_generated": date_generated(),
        "rigid_body_count": len(obj.links),
        "asset_extents": [round(float(x), 6) for x in hi - lo],
        "mass": round(float(sum(link.mass for link in obj.links)), 6),
    }
    if obj.category in WIKIDATA:
        meta["qcode"] = WIKIDATA[obj.category][0]
    return meta


def metadata(obj) -> dict:
    """Everything a dataset tool needs without parsing USD: a JSON-able dict."""
    lo, hi = obj.bounds()
    return _clean({
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
    })


def write_metadata(obj, folder: Path) -> Path:
    path = folder / "metadata.json"
    path.write_text(json.dumps(metadata(obj), indent=2, sort_keys=False) + "\n")
    return path
