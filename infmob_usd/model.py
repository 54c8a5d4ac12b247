"""The articulated-object model: links with frames at joint pivots, simple joints.

:func:`build` turns a world-space :class:`~infmob_usd.blueprint.Blueprint` into an
:class:`ArticulatedObject`: every link frame is placed at the pivot of the joint
that moves it (the root at the world origin), world-aligned at rest, and every
compound joint becomes a chain of simple joints through dummy links carrying
:data:`~infmob_usd.mass.DUMMY_MASS`. Pieces are stored in link-local metres.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ._version import __version__
from .blueprint import Blueprint
from .errors import ModelError
from .joints import gate_chain
from .mass import DUMMY_INERTIA, DUMMY_MASS, dummy_masses, floor_chain_inertia, inertial, link_floor, wall_of
from .measures import _measure_closed
from .physical.passive import dynamics
from .piece import Piece
from .rotation import motion


@dataclass
class Link:
    """A rigid body. ``origin`` is its frame's world position at rest (axes = world axes)."""

    name: str
    label: str
    origin: np.ndarray
    pieces: list[Piece]
    mass: float
    com: np.ndarray  # (3,) link frame
    inertia: np.ndarray  # (3, 3) about com, link axes
    dummy: bool = False


@dataclass
class Joint:
    """A simple joint. ``origin`` = the child link's frame (world, at rest); ``axis`` is world = local."""

    name: str
    type: str  # fixed | revolute | continuous | prismatic
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray
    lower: float
    upper: float
    damping: float
    friction: float
    effort: float
    velocity: float
    kind: str  # the declared kind this joint belongs to (may be compound)
    role: str
    group: str  # the child part of the declared joint; a compound chain shares it
    # the part name of JointSpec.requires_open: the joints whose ``group`` is that part must be fully open
    # before this one moves (for a declared joint, its group is its child part)
    requires_open: str | None = None
    armature: float = 0.0  # kg or kg m^2 added to the joint's inertia (set by effort.assign_drives)
    stiffness: float = 0.0  # return spring, N/m or N m/rad (0: none; set by springs.assign_springs)
    spring_ref: float = 0.0  # where the spring's force is zero (m or rad), beyond the rest stop: a preload
    mimic: tuple[str, float, float] | None = None  # (leader joint, multiplier, offset): q = m q_leader + o
    # groups that must be closed (at rest) before this joint moves: a part whose sweep from the
    # all-open state would meet them while they are open (set by physical.limit_to_clearance)
    requires_closed: tuple[str, ...] = ()
    # joints of the same part that must be at rest while this one is off rest, and it while they are:
    # the alternative modes of an exclusive compound joint (JointSpec.exclusive; a tilt-and-turn sash)
    excludes: tuple[str, ...] = ()
    # a spring-returned joint's friction where its spring cannot be written (a URDF has no spring element):
    # holds the part against its weight anywhere in its range, or a reader without the spring lets it fall
    # onto its far stop (0: the joint's own friction; set by effort.assign_drives)
    hold_friction: float = 0.0

    @property
    def movable(self) -> bool:
        return self.type != "fixed"


@dataclass
class ArticulatedObject:
    """One generated object, complete in memory, ready to be written."""

    category: str
    seed: int
    params: dict[str, Any]
    overrides: dict[str, Any]
    links: list[Link]
    joints: list[Joint]
    materials: dict[str, Any]  # slot -> materials.Look
    textures: dict[str, dict[str, bytes]] = field(default_factory=dict)  # slot -> map -> PNG bytes
    texture_size: int = 512
    timings: dict[str, float] = field(default_factory=dict)  # seconds per stage; never written to files
    retrieved: list[dict] = field(default_factory=list)  # library parts placed (infmob_usd.retrieval)
    retrieval: dict | None = None  # with a library: parts used and why others were not (Retriever.summary)
    # per operated joint, where and how a gripper opens it (infmob_usd.interaction.annotate)
    interaction: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # what the physics passes changed that a user should know

    @property
    def name(self) -> str:
        return f"{self.category}_{self.seed:06d}"

    @property
    def version(self) -> str:
        return __version__

    def bounds(self) -> np.ndarray:
        """``(2, 3)`` world bounds of every piece at rest."""
        b = np.array([p.bounds + link.origin for link in self.links for p in link.pieces])
        return np.array([b[:, 0].min(0), b[:, 1].max(0)])

    def link(self, name: str) -> Link:
        for link in self.links:
            if link.name == name:
                return link
        raise KeyError(name)

    @property
    def movable_joints(self) -> list[Joint]:
        return [j for j in self.joints if j.movable]

    def joint_kinds(self) -> dict[str, int]:
        """Histogram of declared kinds of movable joints (a compound chain counts once)."""
        groups = {j.group: j.kind for j in self.joints if j.movable}
        return dict(sorted(Counter(groups.values()).items()))

    def poses(self, q: dict[str, float] | None = None) -> dict[str, np.ndarray]:
        """World ``(4, 4)`` pose of every link frame with joints at ``q`` (name -> value; default 0).

        Raises :class:`~infmob_usd.errors.ParameterError` for a name that is not a movable joint
        of this object or a value that is not a finite number.
        """
        from .errors import ParameterError

        q = dict(q or {})
        movable = {j.name for j in self.joints if j.movable}
        unknown = sorted(str(k) for k in q if k not in movable)
        if unknown:
            raise ParameterError(f"poses: {', '.join(map(repr, unknown))} is not a movable joint of {self.name};"
                                 f" movable joints: {', '.join(sorted(movable)) or 'none'}")
        for k, v in q.items():
            if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)) \
                    or not math.isfinite(float(v)):
                raise ParameterError(f"poses: joint {k!r} got {v!r}, expected a finite number (m or rad)")
        origin = {link.name: link.origin for link in self.links}
        pose = {self.links[0].name: _translation(origin[self.links[0].name])}
        for j in self.joints:  # parents always come before their children
            moved = motion(j.type, j.axis, float(q.get(j.name, 0.0)))
            pose[j.child] = pose[j.parent] @ _translation(origin[j.child] - origin[j.parent]) @ moved
        return pose


_EYE4 = np.eye(4)
_EYE4.flags.writeable = False


def _translation(t) -> np.ndarray:
    m = _EYE4.copy()  # np.eye(4)
    m[:3, 3] = t
    return m


def _resolve_mimics(joints: list[Joint]) -> list[Joint]:
    """Each coupled joint's leader, a part name as declared, becomes the name of the joint that moves it
    (a single revolute or prismatic joint, not itself coupled: chains of followers are not written)."""
    by_part = {}
    for j in joints:
        by_part.setdefault(j.group, []).append(j)
    out = []
    for j in joints:
        if j.mimic is not None:
            part, ratio, offset = j.mimic
            lead = by_part.get(part, [])
            if len(lead) != 1 or lead[0].type not in ("revolute", "prismatic") or lead[0].mimic is not None:
                raise ModelError(f"{j.name} follows part {part!r}, whose joint is not one uncoupled revolute or"
                                 " prismatic joint; couple to a part moved by a simple hinge or slide")
            if lead[0] is j:
                raise ModelError(f"{j.name} cannot follow itself")
            j = replace(j, mimic=(lead[0].name, ratio, offset))
        out.append(j)
    return out


def _closed_both_ways(bp: Blueprint) -> dict[str, tuple[str, ...]]:
    """Part -> the parts that must be closed while it moves, from the declared
    :attr:`~.joints.JointSpec.requires_closed` of either side (the relation holds both ways). A part never
    requires closed a part of its ``requires_open`` chain (it could then never move): a ModelError."""
    movable = {spec.child for spec in bp.joints if spec.movable}
    out: dict[str, set[str]] = {}
    for spec in bp.joints:
        for other in spec.requires_closed:
            if other not in movable or not spec.movable:
                raise ModelError(f"joint of {spec.child!r} requires {other!r} closed, but "
                                 + ("it is fixed" if not spec.movable else "that part has no movable joint")
                                 + "; name parts that move, on a movable joint")
            out.setdefault(spec.child, set()).add(other)
            out.setdefault(other, set()).add(spec.child)
    requires = [(spec.child, spec.requires_open) for spec in bp.joints]
    for spec in bp.joints:
        held = sorted(set(gate_chain(spec.requires_open, requires)) & out.get(spec.child, set()))
        if held:
            raise ModelError(f"{spec.child!r} moves only with {held[0]!r} open but requires it closed (requires_closed"
                             " holds both ways); drop the requires_closed between a part and its gate")
    return {part: tuple(sorted(names)) for part, names in out.items()}


def build(bp: Blueprint, densities: dict[str, float], walls: dict[str, float] | None = None
          ) -> tuple[list[Link], list[Joint]]:
    """Place frames and expand compound joints. ``densities``: slot -> kg/m^3; ``walls``: slot ->
    the wall (m) of its family's hollow pieces (:func:`~infmob_usd.mass.inertial`), default solid."""
    walls = walls or {}
    root = bp.root
    by_parent: dict[str, list] = {}
    for spec in bp.joints:
        by_parent.setdefault(spec.parent, []).append(spec)
    closed_by = _closed_both_ways(bp)

    links: list[Link] = []
    joints: list[Joint] = []

    def make_link(name: str, label: str, origin: np.ndarray, world_pieces: list[Piece],
                  dummy: bool = False) -> None:
        local = [p.translated(-origin) for p in world_pieces]
        if not dummy:
            for p in local:
                if p.material not in densities:
                    raise ModelError(f"part {name!r} uses material slot {p.material!r} with no family")
        # mass, com and inertia: below, once every link's pieces are known
        links.append(Link(name, label, origin, local, DUMMY_MASS, np.zeros(3), np.eye(3) * DUMMY_INERTIA, dummy))

    root_part = bp.parts[root]
    make_link(root, root_part.label, np.zeros(3), root_part.pieces)
    queue = [root]
    while queue:
        parent = queue.pop(0)
        for spec in by_parent.get(parent, []):
            part = bp.parts[spec.child]
            dyn = dynamics(spec.role)
            if spec.kind == "fixed":
                b = np.array([p.bounds for p in part.pieces])
                origin = (b[:, 0].min(0) + b[:, 1].max(0)) / 2
                make_link(part.name, part.label, origin, part.pieces)
                joints.append(Joint(f"joint_{part.name}", "fixed", parent, part.name, origin,
                                    np.array([1.0, 0, 0]), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                    "fixed", spec.role, part.name))
            else:
                chain_parent = parent
                n = len(spec.dofs)
                names = [f"joint_{part.name}"] if n == 1 else [f"joint_{part.name}_{i}" for i in range(n)]
                for i, dof in enumerate(spec.dofs):
                    last = i == n - 1
                    child = part.name if last else f"{part.name}_dummy{i}"
                    # a joint's frame is its child's frame, so every link of the chain
                    # sits at the pivot of the DoF that moves it (axes stay world-aligned)
                    origin = np.asarray(dof.origin, float)
                    if last:
                        make_link(child, part.label, origin, part.pieces)
                    else:
                        make_link(child, "dummy", origin, [], dummy=True)
                    joints.append(Joint(names[i], dof.type, chain_parent, child, origin,
                                        np.asarray(dof.axis, float), float(dof.lower), float(dof.upper),
                                        dyn.damping, dyn.friction, dyn.effort, dyn.velocity,
                                        spec.kind, spec.role, part.name, spec.requires_open,
                                        requires_closed=closed_by.get(part.name, ()),
                                        mimic=None if spec.mimic is None else
                                        (spec.mimic.leader, spec.mimic.ratio, spec.mimic.offset),
                                        excludes=tuple(names[:i] + names[i + 1:]) if spec.exclusive else ()))
                    chain_parent = child
            queue.append(part.name)
    joints = _resolve_mimics(joints)
    reached = {link.name for link in links if not link.dummy}
    missing = set(bp.parts) - reached
    if missing:
        raise ModelError(f"parts not connected to the root {root!r}: {sorted(missing)}")
    _mass_links(links, joints, densities, walls)
    return links, joints


def _mass_links(links: list[Link], joints: list[Joint], densities: dict[str, float], walls: dict[str, float]
                ) -> None:
    """Each real link's mass, centre of mass and inertia from its pieces (the lightest floored, :func:`link_floor`),
    then each dummy's share of what it carries (:func:`~infmob_usd.mass.dummy_masses`) and the inertia floor along
    every chain."""
    # the closed meshes of every link measured as one batch (the same bits as link by link)
    _measure_closed([(p, wall_of(p, walls.get(p.material, 0.0)) > 0) for link in links if not link.dummy
                     for p in link.pieces])
    solid = [link for link in links if not link.dummy]
    raw = [inertial(((p, densities[p.material], walls.get(p.material, 0.0)) for p in link.pieces), 0.0)
           for link in solid]
    floor = link_floor(sum(r[0] for r in raw))
    for link, r in zip(solid, raw):
        link.mass, link.com, link.inertia = r if r[0] >= floor else inertial(
            ((p, densities[p.material], walls.get(p.material, 0.0)) for p in link.pieces), floor)
    children: dict[str, list[str]] = {}
    for j in joints:
        children.setdefault(j.parent, []).append(j.child)
    weights = dummy_masses({link.name: link.mass for link in links}, children, {lk.name for lk in links if lk.dummy})
    for link in links:
        link.mass = weights.get(link.name, link.mass)
    floored = floor_chain_inertia({link.name: link.inertia for link in links}, children)
    for link in links:
        link.inertia = floored[link.name]
