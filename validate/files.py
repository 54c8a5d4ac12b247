"""Reading object folders back: locate files, parse the URDF into plain data."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass
class UrdfJoint:
    name: str
    type: str
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray
    lower: float | None
    upper: float | None


@dataclass
class UrdfModel:
    name: str
    links: dict[str, dict] = field(default_factory=dict)  # name -> {"visual": [...], "collision": [...], "mass": m}
    joints: dict[str, UrdfJoint] = field(default_factory=dict)


def find_objects(paths) -> list[Path]:
    """Object folders among ``paths``: each path is an object folder or a folder of them."""
    found: list[Path] = []
    for p in map(Path, paths):
        if (p / "metadata.json").is_file():
            found.append(p)
        elif p.is_dir():
            found += sorted(d for d in p.rglob("*") if d.is_dir() and (d / "metadata.json").is_file()
                            and not d.name.startswith("."))
    return found


def object_files(folder: Path, meta: dict | None = None) -> tuple[Path, Path]:
    """``(usd, urdf)`` of an object folder, found by its files, not by the folder's name.

    The paths ``metadata.json`` names (``files.usd``, ``files.urdf``, relative to the folder)
    when they exist, else the one top-level ``NAME.usda`` that has a ``NAME.urdf`` beside it;
    a renamed or moved folder is found all the same.  When nothing matches, the paths named
    after the folder are returned (the caller reports them missing).
    """
    folder = Path(folder)
    files = (meta or {}).get("files") if isinstance(meta, dict) else None
    if isinstance(files, dict) and isinstance(files.get("usd"), str) and isinstance(files.get("urdf"), str):
        usd, urdf = folder / files["usd"], folder / files["urdf"]
        if usd.is_file() and urdf.is_file():
            return usd, urdf
    pairs = [p for p in sorted(folder.glob("*.usda")) if p.with_suffix(".urdf").is_file()]
    if len(pairs) == 1:
        return pairs[0], pairs[0].with_suffix(".urdf")
    name = (meta or {}).get("name") if isinstance(meta, dict) else None
    stem = name if isinstance(name, str) and name else folder.name
    return folder / f"{stem}.usda", folder / f"{stem}.urdf"


def load_metadata(folder: Path) -> dict:
    return json.loads((folder / "metadata.json").read_text())


def parse_urdf(path: Path) -> UrdfModel:
    root = ET.parse(path).getroot()
    model = UrdfModel(root.get("name", ""))
    for link in root.findall("link"):
        entry = {"visual": [], "collision": [], "mass": None}
        for kind in ("visual", "collision"):
            for el in link.findall(kind):
                mesh = el.find("geometry/mesh")
                entry[kind].append(mesh.get("filename") if mesh is not None else None)
        m = link.find("inertial/mass")
        entry["mass"] = float(m.get("value")) if m is not None else None
        model.links[link.get("name")] = entry
    for j in root.findall("joint"):
        o = j.find("origin")
        a = j.find("axis")
        lim = j.find("limit")
        model.joints[j.get("name")] = UrdfJoint(
            j.get("name"), j.get("type"), j.find("parent").get("link"), j.find("child").get("link"),
            np.array([float(x) for x in (o.get("xyz", "0 0 0") if o is not None else "0 0 0").split()]),
            np.array([float(x) for x in (a.get("xyz") if a is not None else "1 0 0").split()]),
            float(lim.get("lower")) if lim is not None and lim.get("lower") is not None else None,
            float(lim.get("upper")) if lim is not None and lim.get("upper") is not None else None,
        )
    return model
