"""An object folder read as the pictures need it, and the joint configurations they show.

Reads the URDF (links' visual meshes and origins, joints with limits: a revolute joint without
any is +-pi) and ``metadata.json`` (which joints ``requires_open`` another part, which modes
``excludes`` each other), and turns a joint fraction (0 = rest, 1 = fully open) into joint values,
doors held open for what they gate, one mode of a tilt-and-turn sash open.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from infmob_usd.joints import one_mode

from .files import UrdfJoint, forward_kinematics, gate_joints, mode_excludes, parse_urdf

OPEN_FRACTION = 0.7  # "opened" preview: each joint at 70 % of its range
CONTINUOUS_OPEN = math.pi / 2  # continuous joints: a quarter turn in the opened preview


@dataclass
class _Visual:
    mesh: Path
    origin: np.ndarray  # 4x4 in the link frame
    scale: tuple


@dataclass(frozen=True)
class _Joint(UrdfJoint):
    """A URDF joint with the states the pictures show (limits always set: a revolute joint
    without any is +-pi)."""

    lower: float = 0.0
    upper: float = 0.0

    def rest(self) -> float:
        return float(np.clip(0.0, self.lower, self.upper)) if self.type != "continuous" else 0.0

    def at_fraction(self, f: float) -> float:
        """Joint value at fraction ``f`` of the way from rest to the far limit.

        For the usual joint with ``lower = 0`` this is ``lower + f * (upper - lower)``; a joint whose
        rest lies inside its range opens towards the farther limit; a continuous joint turns
        ``f / 0.7`` quarter turns (a quarter turn in the 70 % "opened" picture).
        """
        if self.type == "continuous":
            return f * CONTINUOUS_OPEN / OPEN_FRACTION
        q0 = self.rest()
        far = self.upper if abs(self.upper - q0) >= abs(self.lower - q0) else self.lower
        return q0 + f * (far - q0)

    def sweep(self, n: int) -> np.ndarray:
        if self.type == "continuous":
            return np.linspace(0.0, 2 * math.pi, n)
        return np.linspace(self.lower, self.upper, n)


@dataclass
class _ObjectFiles:
    folder: Path
    name: str
    metadata: dict
    links: dict[str, list[_Visual]]
    joints: list[_Joint]
    root: str

    @property
    def movable(self) -> list[_Joint]:
        return [j for j in self.joints if j.movable]


def _read_object(folder: Path) -> _ObjectFiles:
    folder = Path(folder)
    meta_path = folder / "metadata.json"
    metadata = json.loads(meta_path.read_text()) if meta_path.is_file() else {}
    urdfs = sorted(folder.glob("*.urdf"))
    if not urdfs:
        raise FileNotFoundError(f"no .urdf file in {folder} (is it an object folder written by infmob?)")
    urdf = folder / f"{metadata.get('name', folder.name)}.urdf"
    urdf = urdf if urdf.is_file() else urdfs[0]
    model = parse_urdf(urdf)
    links: dict[str, list[_Visual]] = {}
    for name, link in model.links.items():
        visuals = []
        for vis in link.visuals:
            fname = vis.filename
            if fname.startswith("package://"):
                fname = fname[len("package://"):]
            path = (urdf.parent / fname).resolve()
            if not path.is_file():
                raise FileNotFoundError(f"visual mesh {fname!r} of link {name!r} is missing ({path})")
            visuals.append(_Visual(path, vis.origin, tuple(vis.scale)))
        links[name] = visuals
    joints = []
    for j in model.joints.values():
        lower = 0.0 if j.lower is None else j.lower
        upper = 0.0 if j.upper is None else j.upper
        if j.type == "revolute" and lower == upper == 0.0:
            lower, upper = -math.pi, math.pi
        values = {f.name: getattr(j, f.name) for f in fields(UrdfJoint)}
        joints.append(_Joint(**values | {"lower": min(lower, upper), "upper": max(lower, upper)}))
    children = {j.child for j in joints}
    roots = [n for n in links if n not in children]
    if not roots:
        raise ValueError(f"{urdf}: no root link (the joints form a cycle)")
    # order joints parent-before-child so forward kinematics is one pass
    ordered, known, pending = [], {roots[0]}, list(joints)
    while pending:
        ready = [j for j in pending if j.parent in known]
        if not ready:
            raise ValueError(f"{urdf}: joints {[j.name for j in pending]} do not hang from the root link")
        for j in ready:
            ordered.append(j)
            known.add(j.child)
            pending.remove(j)
    name = metadata.get("name") or urdf.stem
    return _ObjectFiles(folder, name, metadata, links, ordered, roots[0])


def _forward_kinematics(obj: _ObjectFiles, qpos: dict[str, float]) -> dict[str, np.ndarray]:
    poses = forward_kinematics(obj.root, obj.joints, qpos, lambda j: j.rest() if j.movable else 0.0)
    for name in obj.links:
        poses.setdefault(name, np.eye(4))  # a link no joint reaches stays at the origin
    return poses


def _gates(obj: _ObjectFiles) -> dict[str, list[str]]:
    """{joint name: the movable joints that must be open before it moves} from ``metadata.json`` (a rack
    behind a door: the door's joints; tines on that rack: the rack's, then the door's), as
    ``validate/sim.py`` reads them (:func:`.files.gate_joints`)."""
    movable = {j.name for j in obj.movable}
    return {name: [n for n in gates if n in movable]
            for name, gates in gate_joints(obj.metadata).items() if name in movable}


def _open_gates(obj: _ObjectFiles, qpos: dict[str, float]) -> dict[str, float]:
    """``qpos`` with every door whose dependent joint is off rest held fully open: a picture never drives a
    rack through a half-open door (the order a robot, and ``validate --sim``, opens them in)."""
    out = dict(qpos)
    by_name = {j.name: j for j in obj.movable}
    for name, gates in _gates(obj).items():
        j = by_name[name]
        if abs(out.get(name, j.rest()) - j.rest()) > 1e-9:
            for gate in gates:
                out[gate] = by_name[gate].at_fraction(1.0)
    return out


def _one_mode(obj: _ObjectFiles, qpos: dict[str, float]) -> dict[str, float]:
    """``qpos`` with the modes a joint ``excludes`` (``metadata.json``) at rest while it is off rest, the
    first mode in joint order winning (:func:`infmob_usd.joints.one_mode`): an opened tilt-and-turn sash is
    turned, never tilted and turned at once."""
    excludes = mode_excludes(obj.metadata)
    if not excludes:
        return qpos
    return one_mode(qpos, [j.name for j in obj.movable], excludes, {j.name: j.rest() for j in obj.movable})


def _qpos_for(obj: _ObjectFiles, joint_fraction) -> dict[str, float]:
    """``joint_fraction``: one number for every movable joint, or ``{joint name: fraction}``. Of the modes
    that exclude each other, only the first opens (:func:`_one_mode`); a joint that ``requires_open`` a part
    moves only with that part fully open (:func:`_open_gates`)."""
    if isinstance(joint_fraction, dict):
        unknown = set(joint_fraction) - {j.name for j in obj.movable}
        if unknown:
            raise KeyError(f"no movable joint named {sorted(unknown)} in {obj.name}")
        q = {j.name: j.at_fraction(float(joint_fraction.get(j.name, 0.0))) for j in obj.movable}
    else:
        q = {j.name: j.at_fraction(float(joint_fraction)) for j in obj.movable}
    return _open_gates(obj, _one_mode(obj, q))
