"""Sub-assemblies: what a part builder returns, in its own local frame.

An :class:`Assembly` is a few rigid parts (each a semantic label and its
pieces), the joints between them, named **anchors** (frames where other things
attach: a hinge line, a handle's mounts, a runner plane) and named **support
points** (where it touches what carries it), all in the assembly's local frame.
A category places an assembly by attaching one of its anchors to a frame
(:meth:`Assembly.attached`) and adds it to its blueprint
(:meth:`~infmob_usd.blueprint.Blueprint.place`); it never writes a matrix.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType

import numpy as np

from .errors import ModelError
from .frames import IDENTITY, Frame
from .joints import JointSpec, moved_joint
from .piece import Piece


@dataclass(frozen=True)
class SubPart:
    """One rigid part of an assembly: a semantic label and its pieces."""

    label: str
    pieces: tuple[Piece, ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "pieces", tuple(self.pieces))
        if not self.pieces:
            raise ModelError(f"a {self.label!r} part needs at least one piece")


def _frozen(m: Mapping | None) -> Mapping:
    return MappingProxyType(dict(m or {}))


@dataclass(frozen=True, eq=False)
class Assembly:
    """Parts, joints, anchors and support points in one local frame.

    Attributes
    ----------
    parts : mapping of local name -> :class:`SubPart`
        The first is the root (the part that attaches to what carries it).
    joints : tuple of :class:`~infmob_usd.joints.JointSpec`
        Between local part names, in local coordinates.
    anchors : mapping of name -> :class:`~infmob_usd.frames.Frame`
        Attachment frames; by convention an anchor's z axis is the hinge or
        slide axis where it has one, and its x axis points away from the part.
    supports : mapping of name -> ``(3,)`` float
        Points where the assembly touches what carries it.
    """

    parts: Mapping[str, SubPart]
    joints: tuple[JointSpec, ...] = ()
    anchors: Mapping[str, Frame] = field(default_factory=dict)
    supports: Mapping[str, np.ndarray] = field(default_factory=dict)
    retrieved: str = ""
    """The library part id that replaced the procedural part (``infmob_usd.retrieval``); ``"-"``: drawn
    and kept procedural; empty: not considered yet."""

    def __post_init__(self) -> None:
        if not self.parts:
            raise ModelError("an assembly needs at least one part")
        object.__setattr__(self, "parts", _frozen(self.parts))
        object.__setattr__(self, "joints", tuple(self.joints))
        object.__setattr__(self, "anchors", _frozen(self.anchors))
        sup = {}
        for k, v in (self.supports or {}).items():
            a = np.array(v, float).reshape(3)
            a.setflags(write=False)
            sup[k] = a
        object.__setattr__(self, "supports", _frozen(sup))
        for j in self.joints:
            for end in (j.parent, j.child):
                if end not in self.parts:
                    raise ModelError(f"assembly joint {j.parent}->{j.child}: no part named {end!r}")

    @classmethod
    def single(cls, label: str, pieces: Iterable[Piece], anchors: Mapping[str, Frame] | None = None,
               supports: Mapping | None = None, name: str = "main") -> Assembly:
        """An assembly of one rigid part."""
        return cls({name: SubPart(label, tuple(pieces))}, (), anchors or {}, supports or {})

    @property
    def root(self) -> str:
        return next(iter(self.parts))

    def anchor(self, name: str) -> Frame:
        try:
            return self.anchors[name]
        except KeyError:
            raise ModelError(f"no anchor {name!r}; this assembly has {sorted(self.anchors)}") from None

    def support(self, name: str) -> np.ndarray:
        try:
            return self.supports[name]
        except KeyError:
            raise ModelError(f"no support point {name!r}; this assembly has {sorted(self.supports)}") from None

    # -- placing -----------------------------------------------------------------------------------
    def placed(self, frame: Frame = IDENTITY) -> Assembly:
        """Everything moved from the local frame into ``frame`` (rigid)."""
        m = frame.matrix
        return Assembly(
            {k: SubPart(p.label, tuple(pc.transformed(m) for pc in p.pieces)) for k, p in self.parts.items()},
            tuple(moved_joint(j, frame.point, frame.vector) for j in self.joints),
            {k: frame @ a for k, a in self.anchors.items()},
            {k: frame.point(s) for k, s in self.supports.items()},
            self.retrieved,
        )

    def attached(self, anchor: str, to: Frame) -> Assembly:
        """Placed so that its anchor ``anchor`` coincides with ``to``.

        While an object is generated with a part library, this is where a procedural part may be
        swapped for a library mesh placed by its support points (:mod:`infmob_usd.retrieval`)."""
        from .retrieval import swap

        return swap(self).placed(to @ self.anchor(anchor).inverse())

    def mounted(self, to: Frame) -> Assembly:
        """Placed with its local frame at ``to`` (as :meth:`placed`), through the same retrieval hook as
        :meth:`attached`: for a part a layout sets down in its own frame (a table leg on its corner, a
        caster's wheel under the leg tip)."""
        from .retrieval import swap

        return swap(self).placed(to)

    def merged(self, other: Assembly, prefix: str = "") -> Assembly:
        """This assembly with ``other``'s parts (renamed ``prefix + name``), joints, anchors and supports."""
        ren = {k: prefix + k for k in other.parts}
        clash = set(ren.values()) & set(self.parts)
        if clash:
            raise ModelError(f"merging assemblies: part names {sorted(clash)} exist on both sides")
        return Assembly(
            {**self.parts, **{ren[k]: p for k, p in other.parts.items()}},
            self.joints + tuple(replace(j, parent=ren[j.parent], child=ren[j.child]) for j in other.joints),
            {**self.anchors, **{prefix + k: a for k, a in other.anchors.items()}},
            {**self.supports, **{prefix + k: s for k, s in other.supports.items()}},
        )

    def with_pieces(self, part: str, pieces: Iterable[Piece]) -> Assembly:
        """The same assembly with more pieces in one part."""
        p = self.parts[part]
        parts = dict(self.parts)
        parts[part] = SubPart(p.label, p.pieces + tuple(pieces))
        return Assembly(parts, self.joints, self.anchors, self.supports, self.retrieved)

    def with_anchors(self, **anchors: Frame) -> Assembly:
        return Assembly(self.parts, self.joints, {**self.anchors, **anchors}, self.supports, self.retrieved)

    @property
    def pieces(self) -> tuple[Piece, ...]:
        """Every piece of every part, in order (to fuse the assembly into another part)."""
        return tuple(pc for p in self.parts.values() for pc in p.pieces)

    def bounds(self) -> np.ndarray:
        """``(2, 3)`` bounds of every piece."""
        b = np.array([pc.bounds for p in self.parts.values() for pc in p.pieces])
        return np.array([b[:, 0].min(0), b[:, 1].max(0)])


@dataclass(frozen=True)
class Placed:
    """An assembly added to a blueprint: its global part names and its world anchors."""

    names: Mapping[str, str]
    assembly: Assembly

    @property
    def root(self) -> str:
        return self.names[self.assembly.root]

    def __getitem__(self, local: str) -> str:
        return self.names[local]

    def anchor(self, name: str) -> Frame:
        return self.assembly.anchor(name)

    def support(self, name: str) -> np.ndarray:
        return self.assembly.support(name)
