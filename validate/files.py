"""Reading object folders back: locate files; the one URDF reader of validate/.

:func:`read_urdf` parses URDF text into small dataclasses (:class:`UrdfModel`,
:class:`UrdfLink`, :class:`UrdfJoint`, :class:`UrdfMesh`) and :func:`write_urdf` writes them
back (the pair is checked by a round-trip test). :meth:`UrdfJoint.local` and
:func:`forward_kinematics` are the one forward kinematics every check and the preview use.
"""

from __future__ import annotations

import functools
import json
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from infmob_usd.joints import closed_excludes
from infmob_usd.rotation import motion, transform


@dataclass(frozen=True)
class UrdfMesh:
    """A ``<visual>`` or ``<collision>`` mesh: its file (as written, relative to the URDF), scale
    and ``<origin xyz rpy>`` in the link frame."""

    filename: str
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)
    name: str | None = None

    @functools.cached_property
    def origin(self) -> np.ndarray:
        """``(4, 4)`` pose of the mesh in its link frame."""
        return transform(self.xyz, self.rpy)


@dataclass
class UrdfLink:
    name: str
    visuals: list[UrdfMesh] = field(default_factory=list)
    collisions: list[UrdfMesh] = field(default_factory=list)
    mass: float | None = None
    com: tuple[float, float, float] = (0.0, 0.0, 0.0)
    inertia: tuple[float, ...] | None = None  # ixx ixy ixz iyy iyz izz


@dataclass(frozen=True)
class UrdfJoint:
    """A URDF joint as written; ``lower``/``upper``, ``effort``/``velocity`` and
    ``damping``/``friction`` are ``None`` where the file leaves them out."""

    name: str
    type: str
    parent: str
    child: str
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    axis: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    lower: float | None = None
    upper: float | None = None
    effort: float | None = None
    velocity: float | None = None
    damping: float | None = None
    friction: float | None = None

    @property
    def movable(self) -> bool:
        return self.type in MOVABLE

    @functools.cached_property
    def origin(self) -> np.ndarray:
        """``(4, 4)`` frame of the child link in the parent link frame at ``q = 0``."""
        return transform(self.xyz, self.rpy)

    @functools.cached_property
    def unit_axis(self) -> np.ndarray:
        n = float(np.linalg.norm(self.axis))
        return self.axis / n if n > 1e-12 else np.asarray(self.axis, float)

    def local(self, q: float = 0.0) -> np.ndarray:
        """``(4, 4)`` child frame in the parent frame with the joint at ``q``: the one
        forward-kinematics step of validate/ (``origin @ motion(q)``)."""
        if not q or not self.movable:
            return self.origin
        return self.origin @ motion(self.type, self.unit_axis, q)


MOVABLE = ("revolute", "continuous", "prismatic")
JOINT_TYPES = (*MOVABLE, "fixed")


@dataclass
class UrdfModel:
    """One URDF as plain data: links and joints in file order (:func:`read_urdf`, :func:`write_urdf`)."""

    name: str
    links: dict[str, UrdfLink] = field(default_factory=dict)
    joints: dict[str, UrdfJoint] = field(default_factory=dict)

    @property
    def root(self) -> str:
        """The one link that is no joint's child."""
        children = {j.child for j in self.joints.values()}
        roots = [n for n in self.links if n not in children]
        if len(roots) != 1:
            raise ValueError(f"URDF has {len(roots)} root links {roots[:5]} (want one tree)")
        return roots[0]

    def ordered(self) -> list[UrdfJoint]:
        """The joints, each after the joint that carries its parent link (depth first from the root).

        Raises ValueError if they do not form one tree hanging from the root link."""
        children: dict[str, list[UrdfJoint]] = {}
        for j in self.joints.values():
            children.setdefault(j.parent, []).append(j)
        order, stack = [], [self.root]
        while stack:
            link = stack.pop()
            for j in children.get(link, []):
                order.append(j)
                stack.append(j.child)
        if len(order) != len(self.joints):
            raise ValueError("URDF joints do not form a tree from the root link")
        return order

    def poses(self, q: dict[str, float] | None = None, rest=None) -> dict[str, np.ndarray]:
        """World ``(4, 4)`` pose of every link, the root at identity: forward kinematics.

        ``q``: joint name -> value; a joint not in it takes ``rest(joint)`` (default 0)."""
        return forward_kinematics(self.root, self.ordered(), q, rest)


def forward_kinematics(root: str, ordered, q: dict[str, float] | None = None, rest=None) -> dict[str, np.ndarray]:
    """World ``(4, 4)`` pose of every link reached from ``root`` through ``ordered`` joints
    (parents first, each with ``.parent``, ``.child``, ``.name`` and ``.local(q)``); a joint
    missing from ``q`` takes ``rest(joint)`` (default 0). The one forward kinematics of validate/."""
    q = q or {}
    poses = {root: np.eye(4)}
    for j in ordered:
        value = q[j.name] if j.name in q else (rest(j) if rest is not None else 0.0)
        poses[j.child] = poses[j.parent] @ j.local(value)
    return poses


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


def find_scenes(paths) -> list[Path]:
    """Scene folders (with ``scene.json``) among ``paths``: each path is a scene folder or a folder of them."""
    found: set[Path] = set()
    for p in map(Path, paths):
        if (p / "scene.json").is_file():
            found.add(p)
        elif p.is_dir():
            found |= {q.parent for q in p.rglob("scene.json")
                      if not any(part.startswith(".") for part in q.relative_to(p).parts)}
    return sorted(found)


def scene_refusals(folder, rec) -> list[str]:
    """Why the scene folder must not be loaded, or ``[]``: every object folder ``scene.json`` names and every
    file ``scene.xml`` and ``scene.usda`` reach (MJCF ``file=`` attributes, USD references, sublayers and
    assets, through the files they name in turn) must lie inside ``folder`` with links resolved; a scene from
    elsewhere must not make us read the user's files."""
    folder = Path(folder)
    top = os.path.realpath(folder)
    out: list[str] = []

    def outside(path) -> bool:
        real = os.path.realpath(path)
        return not (real == top or real.startswith(top.rstrip(os.sep) + os.sep))

    objects = rec.get("objects") if isinstance(rec, dict) else None
    if not isinstance(objects, list):
        return ["scene.json has no list of objects"]
    for o in objects:
        name = o.get("folder") if isinstance(o, dict) else None
        if not isinstance(name, str) or os.path.isabs(name) or outside(folder / name):
            out.append(f"object folder {name!r} lies outside the scene folder: refused")
    seen: set[str] = set()
    todo = [folder / "scene.xml"] if (folder / "scene.xml").is_file() else []
    while todo and len(seen) < 10_000:
        xml = todo.pop()
        if str(xml) in seen:
            continue
        seen.add(str(xml))
        try:
            root = ET.parse(xml).getroot()
        except (OSError, ET.ParseError):
            continue  # MuJoCo's own load reports it
        meshdir = next((c.get("meshdir") for c in root.iter("compiler") if c.get("meshdir")), "")
        for el in root.iter():
            name = el.get("file")
            if name is None:
                continue
            base = xml.parent / (meshdir if el.tag in ("mesh", "hfield", "skin") else "")
            if os.path.isabs(name) or outside(base / name):
                out.append(f"{xml.name}: file {name!r} lies outside the scene folder: refused")
            elif name.endswith(".xml"):
                todo.append(base / name)
    out += _usd_refusals(folder / "scene.usda", outside)
    return out


def _usd_refusals(usda: Path, outside) -> list[str]:
    """Layers and assets reachable from ``usda`` that lie outside (``outside(path)``)."""
    if not usda.is_file():
        return []
    from pxr import Sdf

    out, seen, todo = [], set(), [usda]
    while todo and len(seen) < 10_000:
        path = todo.pop()
        if str(path) in seen:
            continue
        seen.add(str(path))
        layer = Sdf.Layer.FindOrOpen(str(path))
        if layer is None:
            continue
        for dep in layer.GetCompositionAssetDependencies() + list(layer.GetExternalAssetDependencies()):
            target = Path(layer.ComputeAbsolutePath(dep)) if dep else None
            if target is None or outside(target):
                out.append(f"{path.name}: {dep!r} lies outside the scene folder: refused")
            elif target.suffix in (".usda", ".usd", ".usdc"):
                todo.append(target)
    return out


def outside_scenes(objects: list[Path], scenes: list[Path]) -> list[Path]:
    """``objects`` that are not inside one of ``scenes`` (a scene's own objects are shown as the scene)."""
    return [o for o in objects if not any(s in o.parents for s in scenes)]


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


def mode_excludes(meta: dict) -> dict[str, list[str]]:
    """Joint name -> the joints it ``excludes`` (``metadata.json``): the other modes of one fitting, at rest
    while it is off rest (a tilt-and-turn sash tilts or turns), and the joints of parts that it and they each
    ``requires_closed`` (never open together: :func:`infmob_usd.joints.closed_excludes`); read with
    :func:`infmob_usd.joints.one_mode`."""
    movable = [j for j in meta.get("joints", []) if j.get("type") not in (None, "fixed")]
    out = {j["name"]: list(j["excludes"]) for j in movable if j.get("excludes")}
    pairs = closed_excludes([(j["name"], j.get("group"), j.get("requires_closed") or []) for j in movable])
    for name, held in pairs.items():
        out[name] = out.get(name, []) + [n for n in held if n not in out.get(name, [])]
    return out


def load_metadata(folder: Path) -> dict:
    return json.loads((folder / "metadata.json").read_text())


def _floats(text: str | None, default: tuple) -> tuple:
    return tuple(float(x) for x in text.split()) if text else tuple(default)


def _origin(el) -> tuple[tuple, tuple]:
    o = el.find("origin")
    if o is None:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    return _floats(o.get("xyz"), (0, 0, 0)), _floats(o.get("rpy"), (0, 0, 0))


def _opt(el, key: str) -> float | None:
    return float(el.get(key)) if el is not None and el.get(key) is not None else None


def _read_mesh(el, link: str) -> UrdfMesh | None:
    mesh = el.find("geometry/mesh")
    if mesh is None or not mesh.get("filename"):
        return None  # a primitive: our writers only emit meshes
    xyz, rpy = _origin(el)
    return UrdfMesh(mesh.get("filename"), xyz, rpy, _floats(mesh.get("scale"), (1, 1, 1)), el.get("name"))


def read_urdf(text: str) -> UrdfModel:
    """Parse URDF text into a :class:`UrdfModel` (the one URDF reader of validate/).

    Raises
    ------
    ValueError
        Malformed XML, a joint without parent or child, or an unknown joint type.
    """
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise ValueError(f"URDF is not well-formed XML: {exc}") from None
    model = UrdfModel(root.get("name", ""))
    for el in root.findall("link"):
        name = el.get("name")
        link = UrdfLink(name)
        for kind, out in (("visual", link.visuals), ("collision", link.collisions)):
            for sub in el.findall(kind):
                mesh = _read_mesh(sub, name)
                if mesh is None and kind == "collision":
                    raise ValueError(f"link {name}: a <collision> without a mesh (only meshes supported)")
                if mesh is not None:
                    out.append(mesh)
        inertial = el.find("inertial")
        if inertial is not None:
            link.mass = _opt(inertial.find("mass"), "value")
            link.com = _origin(inertial)[0]
            i = inertial.find("inertia")
            if i is not None:
                link.inertia = tuple(float(i.get(k, 0.0)) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"))
        model.links[name] = link
    for el in root.findall("joint"):
        name, kind = el.get("name"), el.get("type")
        if kind not in JOINT_TYPES:
            raise ValueError(f"joint {name}: type {kind!r} not supported (want one of {', '.join(JOINT_TYPES)})")
        parent, child = el.find("parent"), el.find("child")
        if parent is None or child is None:
            raise ValueError(f"joint {name}: needs <parent link> and <child link>")
        xyz, rpy = _origin(el)
        a, lim, dyn = el.find("axis"), el.find("limit"), el.find("dynamics")
        model.joints[name] = UrdfJoint(
            name, kind, parent.get("link"), child.get("link"), xyz, rpy,
            np.array(_floats(a.get("xyz") if a is not None else None, (1, 0, 0))),
            _opt(lim, "lower"), _opt(lim, "upper"), _opt(lim, "effort"), _opt(lim, "velocity"),
            _opt(dyn, "damping"), _opt(dyn, "friction"))
    return model


def parse_urdf(path: str | Path) -> UrdfModel:
    """Read a URDF file (:func:`read_urdf`)."""
    return read_urdf(Path(path).read_text())


def _g(x: float) -> str:
    return repr(float(x))


def _xyz(v) -> str:
    return " ".join(_g(x) for x in v)


def write_urdf(model: UrdfModel) -> str:
    """URDF text of ``model``; :func:`read_urdf` reads it back to an equal model (the pair is
    checked by a round-trip test). Floats are written exactly (``repr``)."""
    out = [f'<?xml version="1.0"?>\n<robot name={quoteattr(model.name)}>']

    def mesh(kind: str, m: UrdfMesh) -> str:
        name = f" name={quoteattr(m.name)}" if m.name is not None else ""
        scale = f' scale="{_xyz(m.scale)}"' if tuple(m.scale) != (1.0, 1.0, 1.0) else ""
        return (f'    <{kind}{name}><origin xyz="{_xyz(m.xyz)}" rpy="{_xyz(m.rpy)}"/>'
                f'<geometry><mesh filename={quoteattr(m.filename)}{scale}/></geometry></{kind}>')

    for link in model.links.values():
        out.append(f"  <link name={quoteattr(link.name)}>")
        out += [mesh("visual", m) for m in link.visuals] + [mesh("collision", m) for m in link.collisions]
        if link.mass is not None:
            inertia = ""
            if link.inertia is not None:
                inertia = "<inertia " + " ".join(
                    f'{k}="{_g(v)}"' for k, v in zip(("ixx", "ixy", "ixz", "iyy", "iyz", "izz"), link.inertia)) + "/>"
            out.append(f'    <inertial><origin xyz="{_xyz(link.com)}" rpy="0 0 0"/>'
                       f'<mass value="{_g(link.mass)}"/>{inertia}</inertial>')
        out.append("  </link>")
    for j in model.joints.values():
        out.append(f"  <joint name={quoteattr(j.name)} type={quoteattr(j.type)}>")
        out.append(f"    <parent link={quoteattr(j.parent)}/><child link={quoteattr(j.child)}/>")
        out.append(f'    <origin xyz="{_xyz(j.xyz)}" rpy="{_xyz(j.rpy)}"/>')
        out.append(f'    <axis xyz="{_xyz(j.axis)}"/>')
        lim = " ".join(f'{k}="{_g(v)}"' for k, v in (("lower", j.lower), ("upper", j.upper),
                                                    ("effort", j.effort), ("velocity", j.velocity))
                       if v is not None)
        if lim:
            out.append(f"    <limit {lim}/>")
        dyn = " ".join(f'{k}="{_g(v)}"' for k, v in (("damping", j.damping), ("friction", j.friction))
                       if v is not None)
        if dyn:
            out.append(f"    <dynamics {dyn}/>")
        out.append("  </joint>")
    out.append("</robot>\n")
    return "\n".join(out)
