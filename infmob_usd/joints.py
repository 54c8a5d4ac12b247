"""Joint kinds, their declaration in world space, and their expansion.

A category declares a :class:`JointSpec` in world coordinates at rest: the kind,
the parent and child parts, and one :class:`Dof` per degree of freedom (type,
pivot, axis, limits). Simple kinds have one DoF; compound kinds are chains that
the core expands through light dummy links (see :data:`KINDS`).

Limits are radians for rotations and metres for slides. Rest is 0 and lies in
``[lower, upper]``; a joint with a closed state has ``lower == 0`` (closed).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from .errors import ModelError

SIMPLE = ("fixed", "revolute", "continuous", "prismatic")

KINDS: dict[str, tuple[str, ...]] = {
    "fixed": (),
    "revolute": ("revolute",),
    "continuous": ("continuous",),
    "prismatic": ("prismatic",),
    "revolute_prismatic": ("prismatic", "revolute"),
    "continuous_prismatic": ("prismatic", "continuous"),
    "limited_planar": ("prismatic", "prismatic", "revolute"),
    "limited_floating": ("prismatic", "prismatic", "prismatic"),
    "flip_revolute": ("revolute", "revolute"),
}
"""Each kind and the simple DoF chain it expands to, parent side first."""

ROLES = ("fixed", "hinge", "slide", "knob", "button", "turntable", "swivel", "telescope", "wheel", "lid",
         "lift_off", "plate", "grate", "lever", "plunger", "self_closing", "pedal_lid", "holding", "toggle",
         "default")
"""Joint roles: what a joint is for, which sets its passive dynamics (``physical.DYNAMICS``) and, for
the spring-returned roles (button, lever, plunger, self-closing hinge, pedal-driven lid), its return
spring (:data:`infmob_usd.springs.SPRINGS`); a ``holding`` joint (a laptop lid's friction hinge, a monitor's
tilt) stays where it is put: its friction holds its load anywhere in its range (:func:`infmob_usd.effort.holding`).
``toggle``: a bistable switch part (a toggle's bat, a rocker) that a fingertip flips or presses, with no return
spring (its joint friction holds it where it is set)."""


@dataclass(frozen=True)
class Mimic:
    """A coupled joint: this joint's coordinate is ``ratio * leader + offset`` (a pedal lifting a lid,
    a toaster lever and its carriage). ``leader`` is the child part of the leading joint; both joints
    are single-DoF (revolute or prismatic)."""

    leader: str
    ratio: float = 1.0
    offset: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.ratio) and math.isfinite(self.offset)) or self.ratio == 0.0:
            raise ModelError(f"coupling to {self.leader!r}: ratio must be a finite non-zero number and offset"
                             f" finite, got ratio {self.ratio!r}, offset {self.offset!r}")


@dataclass(frozen=True)
class Dof:
    """One degree of freedom in world coordinates at rest."""

    type: str  # "revolute" | "continuous" | "prismatic"
    origin: tuple[float, float, float]
    axis: tuple[float, float, float]
    lower: float = 0.0
    upper: float = 0.0

    def __post_init__(self) -> None:
        if self.type not in ("revolute", "continuous", "prismatic"):
            raise ModelError(f"unknown DoF type {self.type!r}")
        o, a = np.asarray(self.origin, float), np.asarray(self.axis, float)
        if o.shape != (3,) or a.shape != (3,) or not np.isfinite(o).all() or not np.isfinite(a).all():
            raise ModelError(f"DoF origin and axis must be finite 3-vectors, got {self.origin}, {self.axis}")
        n = float(np.linalg.norm(a))
        if n < 1e-9:
            raise ModelError("DoF axis must not be zero")
        object.__setattr__(self, "axis", tuple(float(x) for x in a / n))
        object.__setattr__(self, "origin", tuple(float(x) for x in o))
        if self.type == "continuous":
            object.__setattr__(self, "lower", -math.pi)
            object.__setattr__(self, "upper", math.pi)
        elif not (self.lower <= 0.0 <= self.upper) or self.lower == self.upper:
            raise ModelError(
                f"{self.type} limits [{self.lower}, {self.upper}] must contain the rest value 0"
                " and not be empty"
            )


@dataclass(frozen=True)
class JointSpec:
    """A joint between two parts, as a category declares it."""

    kind: str
    parent: str
    child: str
    dofs: tuple[Dof, ...] = ()
    role: str = "default"
    requires_open: str | None = None
    """The name of a part, the child of another declared joint, that must be fully open before this
    joint moves (a rack behind a door names the door's part); checks and users open that part first.
    The written joints keep the part name: it is the ``group`` of every joint in the gate's chain
    (:attr:`.model.Joint.requires_open`). ``None``: moves freely."""
    mimic: Mimic | None = None
    """The joint whose coordinate drives this one (:class:`Mimic`); ``None``: moves on its own."""
    exclusive: bool = False
    """A compound joint whose DoFs are alternative modes: each moves only while the others are at rest
    (a tilt-and-turn sash's handle selects tilt or turn). Each written joint of the chain lists the
    others as its ``excludes`` (:attr:`.model.Joint.excludes`); an open state opens the first mode,
    parent side first (:func:`one_mode`)."""
    engagement: float | None = None
    """A lift-off joint (role ``lift_off``): how far its seat guides the part (m: a peg's height for a mug
    hung on it, a pocket's lip for a caddy standing in it); it is free, and its slides end, that far plus
    :data:`~infmob_usd.lift_off.FREE` up (:func:`infmob_usd.lift_off.capped_joint`). ``None``: a hand's
    lift, :data:`~infmob_usd.lift_off.LIFT_OFF`."""
    requires_closed: tuple[str, ...] = ()
    """Names of parts, each the child of another movable joint, that must be at rest before this joint moves
    and that cannot open while it is off rest (a folding reader's front folds only with its temples folded,
    and its temples cannot open while it is folded): the relation holds both ways, and the written joints of
    both sides list the other's part (:attr:`.model.Joint.requires_closed`). Open states (the clearance
    pass's, the validators', the previews') open the first of the two in joint order and hold the other at
    rest (:func:`closed_excludes`). ``()``: no such part."""

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ModelError(f"unknown joint kind {self.kind!r}; valid kinds: {', '.join(KINDS)}")
        want = KINDS[self.kind]
        got = tuple(d.type for d in self.dofs)
        if got != want:
            raise ModelError(f"{self.kind} joint {self.parent}->{self.child} needs DoFs {want}, got {got}")
        if self.role not in ROLES:
            raise ModelError(f"joint {self.parent}->{self.child}: unknown role {self.role!r};"
                             f" valid roles: {', '.join(ROLES)}")
        if self.mimic is not None and self.kind not in ("revolute", "prismatic"):
            raise ModelError(f"{self.kind} joint {self.parent}->{self.child} cannot follow another joint:"
                             " only a revolute or prismatic joint can be coupled")
        if self.engagement is not None and (self.role != "lift_off" or not 0.0 < self.engagement < math.inf):
            raise ModelError(f"joint {self.parent}->{self.child}: an engagement depth (got {self.engagement!r})"
                             " is a positive length, declared on a role lift_off joint only")
        if self.child in self.requires_closed or len(set(self.requires_closed)) != len(self.requires_closed):
            raise ModelError(f"joint {self.parent}->{self.child}: requires_closed {self.requires_closed!r} names"
                             " its own part or a part twice; name each other part once")
        if self.exclusive and len(self.dofs) < 2:
            raise ModelError(f"{self.kind} joint {self.parent}->{self.child} has one DoF: only the modes of a"
                             " compound joint can exclude each other")

    @property
    def movable(self) -> bool:
        return self.kind != "fixed"


V3 = Sequence[float]


def moved_joint(spec: JointSpec, point, vector) -> JointSpec:
    """``spec`` with every DoF's origin mapped by ``point`` and axis by ``vector`` (a rigid move)."""
    return replace(spec, dofs=tuple(
        Dof(d.type, tuple(point(d.origin)), tuple(vector(d.axis)), d.lower, d.upper) for d in spec.dofs))


def fixed(parent: str, child: str) -> JointSpec:
    return JointSpec("fixed", parent, child, (), "fixed")


def revolute(parent: str, child: str, pivot: V3, axis: V3, lower: float, upper: float,
             role: str = "hinge",
        requires_open: str | None = None) -> JointSpec:
    return JointSpec("revolute", parent, child, (Dof("revolute", pivot, axis, lower, upper),), role, requires_open)


def continuous(parent: str, child: str, pivot: V3, axis: V3, role: str = "knob",
        requires_open: str | None = None) -> JointSpec:
    return JointSpec("continuous", parent, child, (Dof("continuous", pivot, axis),), role, requires_open)


def prismatic(parent: str, child: str, origin: V3, axis: V3, lower: float, upper: float,
              role: str = "slide",
        requires_open: str | None = None, engagement: float | None = None) -> JointSpec:
    """A slide; ``engagement``: a lift-off part's seat depth (:attr:`JointSpec.engagement`)."""
    return JointSpec("prismatic", parent, child, (Dof("prismatic", origin, axis, lower, upper),), role, requires_open,
                     engagement=engagement)


def revolute_prismatic(parent: str, child: str, pivot: V3, axis: V3, turn: tuple[float, float],
                       slide_axis: V3, slide: tuple[float, float], role: str = "telescope",
        requires_open: str | None = None) -> JointSpec:
    """Slide along ``slide_axis`` then turn about ``axis`` through ``pivot`` (a lamp pole)."""
    return JointSpec("revolute_prismatic", parent, child, (
        Dof("prismatic", pivot, slide_axis, *slide), Dof("revolute", pivot, axis, *turn)), role, requires_open)


def continuous_prismatic(parent: str, child: str, pivot: V3, axis: V3, slide: tuple[float, float],
                         role: str = "lid",
        requires_open: str | None = None) -> JointSpec:
    """Turn freely about ``axis`` and slide along it (a screw cap, a lid)."""
    return JointSpec("continuous_prismatic", parent, child, (
        Dof("prismatic", pivot, axis, *slide), Dof("continuous", pivot, axis)), role, requires_open)


def limited_planar(parent: str, child: str, pivot: V3, slide_axes: tuple[V3, V3],
                   slides: tuple[tuple[float, float], tuple[float, float]], axis: V3,
                   turn: tuple[float, float], role: str = "plate",
        requires_open: str | None = None) -> JointSpec:
    """Two bounded slides and a bounded turn (a plate in a rack)."""
    return JointSpec("limited_planar", parent, child, (
        Dof("prismatic", pivot, slide_axes[0], *slides[0]),
        Dof("prismatic", pivot, slide_axes[1], *slides[1]),
        Dof("revolute", pivot, axis, *turn)), role, requires_open)


def limited_floating(parent: str, child: str, origin: V3, axes: tuple[V3, V3, V3],
                     slides: tuple[tuple[float, float], ...], role: str = "grate",
        requires_open: str | None = None) -> JointSpec:
    """Three bounded slides (an oven grate lifted out of its rack)."""
    return JointSpec("limited_floating", parent, child, tuple(
        Dof("prismatic", origin, a, *s) for a, s in zip(axes, slides)), role, requires_open)


def flip_revolute(parent: str, child: str, pivot0: V3, axis0: V3, turn0: tuple[float, float],
                  pivot1: V3, axis1: V3, turn1: tuple[float, float], role: str = "hinge",
        requires_open: str | None = None, exclusive: bool = False) -> JointSpec:
    """Two hinge lines in series (a towel ring, a folding lid); ``exclusive``: one at a time (a
    tilt-and-turn sash turns or tilts, never both: :attr:`JointSpec.exclusive`)."""
    return JointSpec("flip_revolute", parent, child, (
        Dof("revolute", pivot0, axis0, *turn0), Dof("revolute", pivot1, axis1, *turn1)), role, requires_open,
        exclusive=exclusive)


def closed_excludes(joints: Sequence[tuple[str, str, Sequence[str]]]) -> dict[str, list[str]]:
    """Joint name -> the joints held at rest while it is off rest in an open state, from ``(joint name, group,
    requires_closed groups)`` of the movable joints: where two parts each require the other closed
    (:attr:`JointSpec.requires_closed`, written both ways), they are never open together, read with
    :func:`one_mode` (the first in joint order opens). A one-way relation (the clearance pass's order, a door
    closed after its tray) leaves both open."""
    members: dict[str, list[str]] = {}
    closed: dict[str, set[str]] = {}
    for name, group, needs in joints:
        members.setdefault(group, []).append(name)
        closed.setdefault(group, set()).update(needs)
    out: dict[str, list[str]] = {}
    for name, group, needs in joints:
        held = [n for g in sorted(set(needs)) if group in closed.get(g, ()) for n in members.get(g, [])]
        if held:
            out[name] = held
    return out


def one_mode(q: dict[str, float], order: Sequence[str], excludes: dict[str, Sequence[str]],
             rest: dict[str, float] | None = None) -> dict[str, float]:
    """``q`` (joint name -> value) with the alternative modes of an exclusive joint
    (:attr:`JointSpec.exclusive`) opened one at a time: walking ``order`` (parent side first), every
    joint that an earlier joint off its rest value excludes is put back at rest (``rest``, default 0).
    An open state of a tilt-and-turn sash is turned, not tilted and turned."""
    rest = rest or {}
    out = dict(q)
    shut: set[str] = set()
    for name in order:
        if name in shut or out.get(name, rest.get(name, 0.0)) == rest.get(name, 0.0):
            continue
        for other in excludes.get(name, ()):
            if other in out:
                out[other] = rest.get(other, 0.0)
            shut.add(other)
    return out
