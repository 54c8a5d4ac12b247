"""What a category hands the core: parts in world coordinates and the joints between them.

A :class:`Blueprint` is a tree of :class:`Part` s joined by
:class:`~infmob_usd.joints.JointSpec` s, all at rest in world coordinates
(metres, Z up, front faces +X), plus the material family of every material
slot its pieces name. A category's growth rules live in
:mod:`infmob_usd.grammar`, which grows the tree a blueprint is built from.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace

import numpy as np

from .assembly import Placed
from .errors import ModelError
from .joints import JointSpec
from .piece import Piece
from .rotation import motion


@dataclass
class Part:
    """A rigid part: a unique name, a semantic label and its pieces (world space)."""

    name: str
    label: str
    pieces: list[Piece] = field(default_factory=list)


@dataclass
class Blueprint:
    """Parts and joints of one object at rest, as a category builds it."""

    category: str
    materials: dict[str, str] = field(default_factory=dict)  # slot -> family
    # slot -> kg/m^3 where the slot's material is not the family's usual one (its look stays the
    # family's): a painted window frame is painted softwood, not the MDF the ``painted`` family weighs
    densities: dict[str, float] = field(default_factory=dict)
    parts: dict[str, Part] = field(default_factory=dict)
    joints: list[JointSpec] = field(default_factory=list)
    # m: where the core puts the lowest point at rest. 0 for what stands on the floor; a wall-mounted
    # object (a TV on a wall arm) hangs this high, so that nothing it moves drags on the floor
    elevation: float = 0.0

    def add(self, name: str, label: str, pieces: Iterable[Piece]) -> str:
        """Add a part and return its name."""
        if name in self.parts:
            raise ModelError(f"duplicate part name {name!r}")
        pieces = list(pieces)
        if not pieces:
            raise ModelError(f"part {name!r} has no pieces")
        self.parts[name] = Part(name, label, pieces)
        return name

    def extend(self, name: str, pieces: Iterable[Piece]) -> None:
        """Add more pieces to an existing part."""
        self.parts[name].pieces.extend(pieces)

    def place(self, assembly, name: str):
        """Add an :class:`~infmob_usd.assembly.Assembly` (already placed in world space) and its joints.

        Its root part is called ``name``, the others ``name_<local name>``.
        Returns a :class:`~infmob_usd.assembly.Placed` (global names, world anchors).
        """
        names = {local: name if local == assembly.root else f"{name}_{local}" for local in assembly.parts}
        for local, part in assembly.parts.items():
            self.add(names[local], part.label, part.pieces)
        for j in assembly.joints:
            self.join(replace(j, parent=names[j.parent], child=names[j.child],
                              requires_open=names.get(j.requires_open, j.requires_open),
                              requires_closed=tuple(names.get(n, n) for n in j.requires_closed)))
        return Placed(names, assembly)

    def join(self, spec: JointSpec) -> None:
        """Declare a joint; the child must not have a parent yet."""
        for end in (spec.parent, spec.child):
            if end not in self.parts:
                raise ModelError(f"joint {spec.parent}->{spec.child}: no part named {end!r}")
        if any(j.child == spec.child for j in self.joints):
            raise ModelError(f"part {spec.child!r} already has a parent joint")
        if spec.requires_open is not None:
            gate = next((j for j in self.joints if j.child == spec.requires_open), None)
            if gate is None or not gate.movable:
                raise ModelError(f"joint of {spec.child!r} requires {spec.requires_open!r} open, but that"
                                 " part has no movable joint declared before it")
        self.joints.append(spec)

    @property
    def root(self) -> str:
        """The one part that is nobody's child."""
        children = {j.child for j in self.joints}
        roots = [n for n in self.parts if n not in children]
        if len(roots) != 1:
            raise ModelError(f"a blueprint needs exactly one root part, found {roots}")
        return roots[0]

    def poses(self, q: dict[tuple[str, int], float] | None = None) -> dict[str, np.ndarray]:
        """World ``(4, 4)`` motion of every part from rest, DoFs at ``q``.

        ``q`` maps ``(child part, DoF index)`` to a value (radians or metres); missing
        DoFs stay at rest. A joint's DoFs apply in order, the parent side first (as its
        chain of dummy links does). A part's world pieces at that state are its rest
        pieces transformed by its matrix.

        Raises
        ------
        KeyError
            If a key of ``q`` names no DoF (a typo would otherwise silently leave
            everything at rest).
        """
        q = q or {}
        known = {(j.child, i) for j in self.joints for i in range(len(j.dofs))}
        unknown = [k for k in q if k not in known]
        if unknown:
            raise KeyError(f"q keys {unknown[:3]} name no DoF; keys are (child part, DoF index),"
                           f" e.g. {sorted(known)[:2]}")
        out = {self.root: np.eye(4)}
        by_parent: dict[str, list[JointSpec]] = {}
        for j in self.joints:
            by_parent.setdefault(j.parent, []).append(j)
        stack = [self.root]
        while stack:
            parent = stack.pop()
            for j in by_parent.get(parent, []):
                m = out[parent]
                for i, d in enumerate(j.dofs):
                    m = m @ dof_motion(d, q.get((j.child, i), 0.0))
                out[j.child] = m
                stack.append(j.child)
        return out

    def bounds(self) -> np.ndarray:
        """``(2, 3)`` bounds of every piece at rest."""
        b = np.array([p.bounds for part in self.parts.values() for p in part.pieces])
        return np.array([b[:, 0].min(0), b[:, 1].max(0)])


def descendants(joints, name: str) -> set[str]:
    """``name`` and every part (or link) hanging from it through ``joints`` (``.parent``/``.child``)."""
    names, stack = {name}, [name]
    while stack:
        n = stack.pop()
        for j in joints:
            if j.parent == n and j.child not in names:
                names.add(j.child)
                stack.append(j.child)
    return names


def dof_motion(dof, value: float) -> np.ndarray:
    """``(4, 4)`` world-space motion of one :class:`~infmob_usd.joints.Dof` moved to ``value``."""
    a, o = np.asarray(dof.axis), np.asarray(dof.origin)
    m = motion(dof.type, a, value)
    if dof.type != "prismatic":  # about the axis through the pivot
        m[:3, 3] = o - m[:3, :3] @ o
    return m
