"""The scene engine: a scene kind's grown tree is built by its layout, which makes objects and places them.

A :class:`SceneLayout` subclass (one per scene kind, in ``categories/rooms/``) has one method per node kind
of its grammar, as an object's layout does. It makes objects with :meth:`SceneLayout.make` (each a real
generated object, measured once: its bounds at rest, the box each of its joints sweeps open, its support
regions) and places them with :meth:`~SceneLayout.against` (back to a wall, front into the room),
:meth:`~SceneLayout.at` (anywhere on the floor), :meth:`~SceneLayout.hang` (on a wall, above the floor) and
:meth:`~SceneLayout.set_on` (on a support region of a placed object). Every placement is checked against
what is already placed (rest boxes do not overlap; each joint's open box stays inside the room and clear of
the others' rest boxes), so a layout tries alternatives and keeps what fits: what does not fit is dropped,
never forced.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..grammar import Grown
from ..supports import Region, hull_boxes, support_regions
from .room import Opening, Room, Wall, boxes_overlap, moved_box, pose_matrix

WALL_GAP = 0.005  # m between an object's back and the wall (out of plumb walls: installers leave 3-10 mm)
RUN_GAP = 0.003  # m between neighbours in a run (cabinet fitters' 2-3 mm joint)
SWEEP_STEP = math.radians(15)  # rad between the poses a turning part's swept box is taken at
SET_DOWN = 0.0001  # m: an item is set this far above its support (a drop from higher makes its loose parts rattle)


@dataclass(frozen=True)
class Clearance:
    """Floor space an object keeps free of other furniture, beyond its rest box in its own frame (front +X):
    ``front``, ``back`` and ``sides`` (each side) in metres, each side at least ``from_centre`` from its
    centreline, up to ``height`` above the floor (what hangs higher, a wall unit, does not block it).
    ``source``: where the figures come from."""

    front: float = 0.0
    back: float = 0.0
    sides: float = 0.0
    from_centre: float = 0.0
    height: float = 1.2
    source: str = ""

    def box(self, lo, hi) -> tuple[np.ndarray, np.ndarray]:
        """The clear box around the rest box ``lo``..``hi`` (object frame), floor to ``height``."""
        mid = (lo[1] + hi[1]) / 2
        y0 = min(lo[1] - self.sides, mid - self.from_centre)
        y1 = max(hi[1] + self.sides, mid + self.from_centre)
        return (np.array([lo[0] - self.back, y0, lo[2]]),
                np.array([hi[0] + self.front, y1, lo[2] + self.height]))


# What users and fitters keep clear, as data. A kind passes one of these (or its own) when it places the object.
CLEARANCES = {
    # NKBA Kitchen Planning Guidelines (2021), 19: 36 in (0.91 m) from a table's edge to any wall or obstruction
    # behind a seated diner where no one walks behind
    "dining_table": Clearance(front=0.91, back=0.91, sides=0.91,
                              source="NKBA kitchen guideline 19: 36 in behind a seated diner"),
    # NKBA Bath Planning Guidelines (2021), 12-13: 15 in (0.38 m) from a toilet's centreline to a side obstruction,
    # 30 in (0.76 m) clear floor space in front of it
    "toilet": Clearance(front=0.76, from_centre=0.38,
                        source="NKBA bath guidelines 12-13: 15 in to the side, 30 in in front"),
}


# what :func:`made_in_worker` computes: read off a pending Made when first used
_MEASURED = ("obj", "lo", "hi", "swept", "regions", "hulls", "moving")


@dataclass
class Made:
    """One distinct generated object and what placement needs of it (object frame at rest).

    Made in a process pool (:meth:`pending`), its object and measures arrive when first read: a layout
    that makes several objects before it looks at them (a kitchen's run of units) has them made at once."""

    key: str  # folder under objects/: unique per (category, seed, overrides)
    category: str
    seed: int
    overrides: dict[str, Any]
    obj: Any  # ArticulatedObject
    lo: np.ndarray
    hi: np.ndarray
    swept: list[tuple[str, np.ndarray, np.ndarray]]  # (joint group, lo, hi): the whole object, that group open
    regions: list[Region]
    hulls: tuple[np.ndarray, np.ndarray]  # each collision hull's box, (n, 3) lo and hi: what set-down items clear
    clearance: Clearance | None = None  # the floor space it keeps free of other furniture
    moving: list[tuple[str, np.ndarray, np.ndarray]] = field(default_factory=list)  # (group, lo, hi): only the
    # parts that group moves, over their whole travel (what a fixture beside the object must keep clear of)

    @property
    def size(self) -> np.ndarray:
        return self.hi - self.lo

    def hull_sweep(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """:func:`_hull_sweep` of the object (worked out once, when first asked for)."""
        if "_sweep" not in self.__dict__:
            self.__dict__["_sweep"] = _hull_sweep(self.obj)
        return self.__dict__["_sweep"]

    @classmethod
    def pending(cls, key: str, category: str, seed: int, overrides: dict, clearance: Clearance | None,
                future) -> Made:
        """A Made whose object and measures ``future`` (of :func:`made_in_worker`) delivers when first read."""
        made = cls.__new__(cls)
        made.key, made.category, made.seed, made.overrides, made.clearance = key, category, seed, overrides, clearance
        made._future = future
        return made

    def __getattr__(self, name: str):
        # only reached for an attribute not set yet: the measured ones of a pending Made
        future = self.__dict__.get("_future")
        if name not in _MEASURED or future is None:
            raise AttributeError(name)
        self.__dict__.update(zip(_MEASURED, future.result()))
        del self.__dict__["_future"]
        return self.__dict__[name]


def measured(obj) -> tuple:
    """``obj`` and what placement needs of it, in :data:`_MEASURED`'s order."""
    lo, hi, swept, moving = _measure(obj)
    return obj, lo, hi, swept, support_regions(obj), hull_boxes(obj), moving


def made_in_worker(generate, category: str, seed: int, texture_size: int, overrides: dict) -> tuple:
    """Generate (with ``generate``, the layout's: the core does not import the API) and measure one object
    (a pool worker's job): :func:`measured` of it."""
    return measured(generate(category, seed, texture_size=texture_size, **overrides))


@dataclass
class Placed:
    id: str
    made: Made
    pose: np.ndarray  # (4, 4) object frame in the room frame
    fixed: bool  # the root is fixed (furniture, hung units) or free (items set down)
    on: str  # "floor", "wall:<name>", "<placed id>:<link>"
    lo: np.ndarray = field(default=None)  # room-frame AABB at rest
    hi: np.ndarray = field(default=None)
    wall: str | None = None  # the wall its back is to (placed by ``against``)

    def __post_init__(self) -> None:
        self.lo, self.hi = moved_box(self.made.lo, self.made.hi, self.pose)

    def clear_box(self) -> tuple[np.ndarray, np.ndarray] | None:
        """Room-frame box of the floor space it keeps clear (its :class:`Clearance`), ``None`` if none."""
        c = self.made.clearance
        return None if c is None else moved_box(*c.box(self.made.lo, self.made.hi), self.pose)

    def swept_boxes(self) -> list[tuple[str, np.ndarray, np.ndarray]]:
        return [(g, *moved_box(lo, hi, self.pose)) for g, lo, hi in self.made.swept]

    def moving_boxes(self) -> list[tuple[str, np.ndarray, np.ndarray]]:
        """Room-frame boxes each joint group's moving parts sweep (not the rest of the object)."""
        return [(g, *moved_box(lo, hi, self.pose)) for g, lo, hi in self.made.moving]

    def region_in_room(self, region: Region) -> tuple[np.ndarray, np.ndarray]:
        lo, hi = moved_box((*region.lo, region.z), (*region.hi, region.z), self.pose)
        return lo, hi


def _moved_links(obj, joints) -> set[str]:
    """The links ``joints`` move: their children and everything hung below them."""
    out, todo = set(), [j.child for j in joints]
    while todo:
        name = todo.pop()
        if name not in out:
            out.add(name)
            todo += [j.child for j in obj.joints if j.parent == name]
    return out


def _measure(obj) -> tuple[np.ndarray, np.ndarray, list, list]:
    lo, hi = obj.bounds()
    local = {link.name: (np.array([p.bounds[0] for p in link.pieces]).min(0),
                         np.array([p.bounds[1] for p in link.pieces]).max(0)) for link in obj.links if link.pieces}
    groups: dict[str, list] = {}
    for j in obj.movable_joints:
        # a continuous joint (a stool's swivel seat) sweeps its whole turn: the scene's reach check turns it
        # a quarter each way, and a user turns it all round
        if math.isfinite(j.upper):
            groups.setdefault(j.group, []).append(j)
    swept, parts = [], []
    for group, joints in sorted(groups.items()):
        # a turning part reaches furthest part-way (a flap door swinging up passes over its hinge): sample the
        # range every SWEEP_STEP; a slide is furthest at its end
        turns = any(j.type in ("revolute", "continuous") for j in joints)
        n = max(2, int(math.ceil(max(j.upper - j.lower for j in joints) / SWEEP_STEP)) + 1) if turns else 2
        pts, moving = [], []
        moved = _moved_links(obj, joints)
        for f in np.linspace(0.0, 1.0, n):  # the moving parts from rest (a door flush with a wall at rest sticks)
            poses = obj.poses({j.name: j.lower + f * (j.upper - j.lower) for j in joints})
            for name, (a, b) in local.items():
                box = moved_box(a, b, poses[name])[0:2]
                if f > 0:
                    pts.append(box)
                if name in moved:
                    moving.append(box)
        pts = np.vstack(pts)
        swept.append((group, pts.min(0), pts.max(0)))
        if moving:
            moving = np.vstack(moving)
            parts.append((group, moving.min(0), moving.max(0)))
    return lo, hi, swept, parts


def _hull_sweep(obj) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(rest_lo, rest_hi, moving_lo, moving_hi)``, each ``(n, 3)`` in the object frame: the box of every
    collision hull at rest, and of every hull a joint group moves at each pose over its travel (sampled as
    :func:`_measure` samples it). Finer than the object's boxes: what lets a chair's seat slide under a
    table's top while its back stays clear of the table's edge."""
    hulls: dict[str, list[np.ndarray]] = {}
    for link in obj.links:
        for p in link.pieces:
            hulls.setdefault(link.name, []).extend(np.asarray(c, float) for c in p.convex if len(c) >= 4)
    rest = [h + link.origin for link in obj.links for h in hulls.get(link.name, [])]
    groups: dict[str, list] = {}
    for j in obj.movable_joints:
        if math.isfinite(j.upper):
            groups.setdefault(j.group, []).append(j)
    moving = []
    for _, joints in sorted(groups.items()):
        turns = any(j.type in ("revolute", "continuous") for j in joints)
        n = max(2, int(math.ceil(max(j.upper - j.lower for j in joints) / SWEEP_STEP)) + 1) if turns else 2
        moved = _moved_links(obj, joints)
        for f in np.linspace(0.0, 1.0, n)[1:]:
            poses = obj.poses({j.name: j.lower + f * (j.upper - j.lower) for j in joints})
            moving += [h @ poses[name][:3, :3].T + poses[name][:3, 3] for name in sorted(moved)
                       for h in hulls.get(name, [])]

    def boxes(points):
        return (np.array([h.min(0) for h in points]).reshape(-1, 3),
                np.array([h.max(0) for h in points]).reshape(-1, 3))

    return (*boxes(rest), *boxes(moving))


def _moved_boxes(lo: np.ndarray, hi: np.ndarray, pose: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Room-frame AABBs of the boxes ``lo``..``hi`` (``(n, 3)`` each, in a frame at ``pose``)."""
    pick = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    both = np.stack([lo, hi], axis=1)  # (n, 2, 3)
    corners = both[:, pick, np.arange(3)] @ pose[:3, :3].T + pose[:3, 3]  # (n, 8, 3)
    return corners.min(1), corners.max(1)


def _any_overlap(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray], gap: float) -> bool:
    """Whether any box of ``a`` comes within ``gap`` of any box of ``b`` (``(lo, hi)`` arrays, ``(n, 3)``)."""
    if not len(a[0]) or not len(b[0]):
        return False
    lo = np.maximum(a[0][:, None], b[0][None])
    hi = np.minimum(a[1][:, None], b[1][None])
    return bool(np.any(np.all(hi - lo > -gap, axis=2)))


def _steady_links(obj) -> set[str]:
    """Links something may be set down on: those no joint moves (the body, a fixed sink). Not a drawer, a door
    or a turntable, which move under a load, nor a lift-off part (a range's grate): loaded, it no longer
    lifts off or rests as the object's checks found it (a pan on a grate pushes it 2 mm along its play)."""
    moving = {j.child for j in obj.joints if j.movable}
    return {link.name for link in obj.links if link.name not in moving}


def _clear_of_host(host: Made, lo: np.ndarray, hi: np.ndarray) -> bool:
    """Whether an item's box ``lo``..``hi`` (host frame, set down on a region) is clear of every collision hull
    of the host but the ones it stands on. A region is kept where a few hulls stand on it or rise through it
    (a sink's rim 2 mm proud of the worktop, a tap's base); an item set down over one starts inside it: PhysX
    pushes it out at once, which throws its loose parts (a bottle's cap) off their seats and leaves it tilted
    on the step, where a pump head's weight turns it (measured: 2-5 degrees in 2 s)."""
    h_lo, h_hi = host.hulls
    overlap = np.all((np.minimum(hi, h_hi) - np.maximum(lo, h_lo)) > 1e-6, axis=1)
    return not overlap.any()


class SceneLayout:
    """Base of a scene kind's layout: object making and placing; the kind adds one method per node kind."""

    def __init__(self, kind: str, params: dict, rng: np.random.Generator, objects_rng: np.random.Generator,
                 texture_size: int, generate, categories: tuple[str, ...] = (), pool=None) -> None:
        """``generate``: ``(category, seed, texture_size=..., **overrides) -> ArticulatedObject`` (the API's);
        ``categories``: the category ids that exist; ``pool``: an executor that makes the objects (with
        the API's ``generate``) while the layout goes on, or ``None``: each made here when asked for."""
        self.kind, self.p, self.rng, self.objects_rng = kind, params, rng, objects_rng
        self.texture_size, self._generate, self._categories = texture_size, generate, tuple(categories)
        self.pool = pool
        self.room: Room | None = None
        self.placed: list[Placed] = []
        self._made: dict[tuple, Made] = {}
        self._keys: set[str] = set()
        self._built: list[str] = []

    # -- the tree ---------------------------------------------------------------------------------------------
    def run(self, tree: Grown) -> None:
        self.grow(tree)

    def grow(self, node: Grown, **slot: Any) -> Any:
        self._built.append(node.path)
        return getattr(self, node.kind)(node, **slot)

    # -- objects ----------------------------------------------------------------------------------------------
    def categories(self) -> tuple[str, ...]:
        """The category ids that exist (a kind uses a category only once it does)."""
        return self._categories

    def seed(self) -> int:
        """A fresh object seed from the scene's objects stream (what :meth:`make` uses by default)."""
        return int(self.objects_rng.integers(0, 10**9))

    def make(self, category: str, seed: int | None = None, clearance: Clearance | None | str = "category",
             **overrides: Any) -> Made:
        """Generate (once) the object ``category`` / ``seed`` / ``overrides`` and measure it. Objects that
        must match (the cabinets of one kitchen) share a seed: the seed draws materials, so their
        fronts and worktops are the same; their overrides make them different units. ``clearance``: the
        floor space it keeps clear (default: its category's in :data:`CLEARANCES`; ``None``: none, as a
        dining table used as a desk, whose chair stands at its front)."""
        seed = self.seed() if seed is None else int(seed)
        key = (category, seed, tuple(sorted(overrides.items())))
        if key not in self._made:
            base = f"{category}_{seed:06d}"  # the object's name (ArticulatedObject.name), known before it is made
            name, n = base, 1
            while name in self._keys:
                n += 1
                name = f"{base}_v{n}"
            self._keys.add(name)
            clear = CLEARANCES.get(category) if clearance == "category" else clearance
            if self.pool is not None:
                future = self.pool.submit(made_in_worker, self._generate, category, seed, self.texture_size,
                                          dict(overrides))
                self._made[key] = Made.pending(name, category, seed, dict(overrides), clear, future)
            else:
                obj, lo, hi, swept, regions, hulls, moving = measured(
                    self._generate(category, seed, texture_size=self.texture_size, **overrides))
                self._made[key] = Made(name, category, seed, dict(overrides), obj, lo, hi, swept, regions, hulls,
                                       clear, moving)
        return self._made[key]

    # -- placing ----------------------------------------------------------------------------------------------
    def _id(self, made: Made) -> str:
        n = sum(1 for p in self.placed if p.made.category == made.category)
        return f"{made.category}_{n}"

    def fits(self, cand: Placed, ignore: tuple[str, ...] = ()) -> bool:
        """Whether ``cand`` can stand where it is: inside the room, its rest box clear of every placed
        object's (but the ones it stands on), every joint's open box inside the room and clear of the
        others' rest boxes, and theirs clear of its rest box."""
        r, tol = self.room, 1e-3
        if r is not None and (np.any(cand.lo[:2] < -tol) or cand.hi[0] > r.depth + tol or cand.hi[1] > r.width + tol
                              or cand.hi[2] > r.height + tol):
            return False
        for other in self.placed:
            if other.id in ignore:
                continue
            if boxes_overlap(cand.lo, cand.hi, other.lo, other.hi):
                return False
        return self._clearances_kept(cand, ignore) and self._swing_clear(cand, ignore)

    def _clearances_kept(self, cand: Placed, ignore: tuple[str, ...] = ()) -> bool:
        """Whether ``cand`` stands outside every placed object's clear floor space and nothing placed stands
        in its own (an item set down on an object is in neither: it is the object's)."""
        mine = cand.clear_box()
        for other in self.placed:
            if other.id in ignore or cand.on.startswith(other.id + ":") or other.on.startswith(cand.id + ":"):
                continue
            theirs = other.clear_box()
            if theirs is not None and boxes_overlap(cand.lo, cand.hi, *theirs):
                return False
            if mine is not None and boxes_overlap(*mine, other.lo, other.hi):
                return False
        return True

    def _swing_clear(self, cand: Placed, ignore: tuple[str, ...], room: bool = True) -> bool:
        r = self.room if room else None
        for _, lo, hi in cand.swept_boxes():
            if r is not None and (np.any(lo[:2] < -1e-3) or hi[0] > r.depth + 1e-3 or hi[1] > r.width + 1e-3
                                  or hi[2] > r.height + 1e-3):
                return False
            if any(boxes_overlap(lo, hi, o.lo, o.hi) for o in self.placed if o.id not in ignore):
                return False
        # a moving part, at rest and over its travel, keeps the fitter's gap off a wall: a dishwasher's or a wine
        # cooler's door flush with a side wall drags on it and stops 0-25 % open in the simulators (a unit at the
        # end of a run gets its filler strip)
        gap = WALL_GAP - 1e-3
        for _, lo, hi in cand.moving_boxes() if r is not None else ():
            if np.any(lo[:2] < gap) or hi[0] > r.depth - gap or hi[1] > r.width - gap:
                return False
        for other in self.placed:
            if other.id in ignore or other.on.startswith(cand.id + ":"):
                continue
            for _, lo, hi in other.swept_boxes():
                if boxes_overlap(lo, hi, cand.lo, cand.hi):
                    return False
        return True

    @staticmethod
    def _opens_clear_of_host(made: Made, host: Made, local: np.ndarray) -> bool:
        """Whether every joint of ``made``, set down at ``local`` (its pose in the host's frame), opens clear of
        the host's collision hulls at rest: a rack's drip tray set on a shelf inside a cabinet would slide into
        the cabinet's closed door (the placement checks leave out the host, whose top the item stands on)."""
        return all(_clear_of_host(host, *moved_box(lo, hi, local)) for _, lo, hi in made.swept)

    @staticmethod
    def hulls_clear(a: Placed, b: Placed, gap: float = 0.01) -> bool:
        """Whether ``a`` and ``b`` stay ``gap`` apart hull by hull: each one's collision hulls at rest clear
        of the other's at rest and over the other's joints' travel (each joint opened alone)."""
        a_rest_lo, a_rest_hi, a_mov_lo, a_mov_hi = a.made.hull_sweep()
        b_rest_lo, b_rest_hi, b_mov_lo, b_mov_hi = b.made.hull_sweep()
        a_rest, a_mov = _moved_boxes(a_rest_lo, a_rest_hi, a.pose), _moved_boxes(a_mov_lo, a_mov_hi, a.pose)
        b_rest, b_mov = _moved_boxes(b_rest_lo, b_rest_hi, b.pose), _moved_boxes(b_mov_lo, b_mov_hi, b.pose)
        return not (_any_overlap(a_rest, b_rest, gap) or _any_overlap(a_rest, b_mov, gap)
                    or _any_overlap(a_mov, b_rest, gap))

    def keep(self, cand: Placed, ignore: tuple[str, ...] = ()) -> Placed | None:
        """Place ``cand`` if it :meth:`fits`; ``None`` (nothing placed) if it does not."""
        if not self.fits(cand, ignore):
            return None
        self.placed.append(cand)
        return cand

    def against(self, made: Made, wall: Wall, s: float, z: float = 0.0, fixed: bool = True,
                gap: float = WALL_GAP, check: bool = True, turn: float = 0.0) -> Placed | None:
        """``made`` with its back to ``wall`` (``gap`` off it), its own Y from ``s`` along the wall, ``z`` up.
        ``turn``: an extra yaw (a multiple of 90 degrees) before it is set against the wall (a desk or a
        table stands with its long side to the wall: ``turn`` 90 degrees puts its side there)."""
        lo, hi = moved_box(made.lo, made.hi, pose_matrix(np.zeros(3), turn))
        position = wall.origin + wall.inward * (gap - lo[0]) + wall.along * (s - lo[1])
        position = position + np.array([0.0, 0.0, z - lo[2]])
        cand = Placed(self._id(made), made, pose_matrix(position, wall.yaw + turn), fixed,
                      "floor" if z <= 0 else f"wall:{wall.name}", wall=wall.name)
        return self.keep(cand) if check else cand

    def at(self, made: Made, xy, yaw: float, fixed: bool = True) -> Placed | None:
        """``made`` standing on the floor with its frame's origin over ``xy`` (room frame), turned ``yaw``."""
        cand = Placed(self._id(made), made, pose_matrix((xy[0], xy[1], -made.lo[2]), yaw), fixed, "floor")
        return self.keep(cand)

    def set_on(self, made: Made, host: Placed, rng: np.random.Generator, tries: int = 12,
               prefer=None, fixed: bool = False, yaw: float | None = None, where=None) -> Placed | None:
        """``made`` set down (free) on a support region of ``host`` where it fits: the region big enough
        for its footprint with room above for its height, at a drawn spot; ``None`` if nowhere fits.
        ``yaw``: which way its front faces (default: as the host's); a multiple of 90 degrees from the host's.
        ``prefer``: a sort key of the regions; ``where``: a test a region must pass (a worktop, not a shelf)."""
        host_yaw = math.atan2(host.pose[1, 0], host.pose[0, 0])
        turn = 0.0 if yaw is None else yaw - host_yaw
        lo, hi = moved_box(made.lo, made.hi, pose_matrix(np.zeros(3), turn))  # its box in the host's axes
        size = hi - lo
        steady = _steady_links(host.made.obj)
        regions = [g for g in host.made.regions if g.link in steady
                   and (g.hi[0] - g.lo[0]) > size[0] and (g.hi[1] - g.lo[1]) > size[1]
                   and (g.clear is None or g.clear > size[2] + 0.01) and (where is None or where(g))]
        if prefer is not None:
            regions = sorted(regions, key=prefer)
        for region in regions[:3]:
            for _ in range(tries):
                u = rng.uniform(0, 1, 2)
                lx = region.lo[0] - lo[0] + u[0] * (region.hi[0] - region.lo[0] - size[0])
                ly = region.lo[1] - lo[1] + u[1] * (region.hi[1] - region.lo[1] - size[1])
                local = np.array([lx, ly, region.z - lo[2] + SET_DOWN])
                if not _clear_of_host(host.made, local + lo, local + hi) or not self._opens_clear_of_host(
                        made, host.made, pose_matrix(local, turn)):
                    continue
                position = host.pose[:3, :3] @ local + host.pose[:3, 3]
                cand = Placed(self._id(made), made, pose_matrix(position, host_yaw + turn), fixed,
                              f"{host.id}:{region.link}")
                if self.keep(cand, ignore=(host.id,)) is not None:
                    return cand
        return None


class RoomLayout(SceneLayout):
    """Helpers every room kind uses: runs of units along walls, openings filled by doors and windows, items
    set down on what is placed, each trying alternatives and keeping what fits."""

    FILLERS = (0.0, 0.025, 0.05, 0.075, 0.1)  # m: filler strips a fitter adds so a door clears its neighbour

    def run_along(self, modules: list[Made], wall: Wall, start: float = 0.0, end: float | None = None,
                  z: float = 0.0) -> list[tuple[Placed, float]]:
        """Place ``modules`` side by side along ``wall`` from ``start`` (each after the last, with a filler
        where a door would hit its neighbour); a module that fits nowhere before ``end`` is left out.
        Returns ``(placed, s)`` of each placed module (``s`` along the wall)."""
        end = wall.length if end is None else end
        out, s = [], start
        for made in modules:
            shifts = [*self.FILLERS, *np.arange(0.15, 0.61, 0.05)]  # a filler, else a gap up to 0.6 m
            for filler in shifts:
                if s + filler + made.size[1] > end + 1e-9:
                    break
                got = self.against(made, wall, s + filler, z=z)
                if got is not None:
                    out.append((got, s + filler))
                    s += filler + made.size[1] + RUN_GAP
                    break
        return out

    def run_back(self, modules: list[Made], wall: Wall, end: float, start: float = 0.0,
                 z: float = 0.0) -> list[tuple[Placed, float]]:
        """As :meth:`run_along`, but from ``end`` back towards ``start`` (a run that grows out of a corner:
        its first module stands at the corner)."""
        out, e = [], end
        for made in modules:
            for filler in [*self.FILLERS, *np.arange(0.15, 0.61, 0.05)]:
                s = e - filler - made.size[1]
                if s < start - 1e-9:
                    break
                got = self.against(made, wall, s, z=z)
                if got is not None:
                    out.append((got, s))
                    e = s - RUN_GAP
                    break
        return out

    @staticmethod
    def run_length(modules: list[Made]) -> float:
        return sum(m.size[1] for m in modules) + RUN_GAP * max(len(modules) - 1, 0)

    def embed(self, made: Made, wall: Wall, z: float = 0.0, rng: np.random.Generator | None = None,
              margin: float = 0.1) -> Placed | None:
        """``made`` (a door, a window) set into ``wall`` at a free spot, ``z`` above the floor (lowered if its
        top would come within 0.05 m of the ceiling); the wall gets an opening its size. ``None`` if the
        wall has no spot where its swing clears everything placed.

        A wall-set object is built round its own ``x = 0`` plane: the pieces that cross it (the frame, a
        leaf in it) give the opening, centred in the wall's thickness; a part reaching past the opening
        (a curtain rail, a barn door's leaf, a sill) stands in front of the wall, moving the object into
        the room as far as that needs."""
        boxes = [(p.bounds[0] + link.origin, p.bounds[1] + link.origin) for link in made.obj.links for p in link.pieces]
        crossing = [(lo, hi) for lo, hi in boxes if lo[0] <= 1e-3 and hi[0] >= -1e-3]
        if not crossing:
            return None
        o_lo, o_hi = np.min([b[0] for b in crossing], 0), np.max([b[1] for b in crossing], 0)
        depth = -self.room.wall_thickness / 2
        for lo, hi in boxes:
            if (np.any(lo[1:] < o_lo[1:] - 1e-3) or np.any(hi[1:] > o_hi[1:] + 1e-3)) and (lo[0] + hi[0]) > 0:
                depth = max(depth, 0.001 - float(lo[0]))
        # its head (and what it carries above the opening: a curtain rail) 0.05 m under the ceiling at most
        z = min(z, self.room.height - 0.05 - float(made.hi[2] - made.lo[2]))
        if z < 0:
            return None
        spots = np.arange(margin, wall.length - made.size[1] - margin, 0.05)
        if rng is not None:
            spots = rng.permutation(spots)
        lift = np.array([0.0, 0.0, z - made.lo[2]])
        for s in spots:
            position = wall.origin + wall.inward * depth + wall.along * (s - made.lo[1]) + lift
            cand = Placed(self._id(made), made, pose_matrix(position, wall.yaw), True, f"wall:{wall.name}",
                          wall=wall.name)
            if any(boxes_overlap(cand.lo, cand.hi, o.lo, o.hi) for o in self.placed) \
                    or not self._clearances_kept(cand) or not self._swing_clear(cand, (), room=False):
                continue
            self.placed.append(cand)
            s0, z0 = float(s - made.lo[1]), float(z - made.lo[2])
            self.room.openings.append(Opening(wall.name, s0 + float(o_lo[1]), s0 + float(o_hi[1]),
                                              z0 + float(o_lo[2]), z0 + float(o_hi[2]), cand.id))
            return cand
        return None

    def scatter(self, made: Made, hosts: list[Placed], rng: np.random.Generator, prefer=None,
                fixed: bool = False, where=None) -> Placed | None:
        """``made`` set down on the first of ``hosts`` (in a drawn order) that has room for it (``prefer``,
        ``where``: as in :meth:`set_on`)."""
        for k in rng.permutation(len(hosts)):
            got = self.set_on(made, hosts[int(k)], rng, prefer=prefer, fixed=fixed, where=where)
            if got is not None:
                return got
        return None

    def on_wall(self, made: Made, walls, rng: np.random.Generator, z: float = 0.0, step: float = 0.1,
                fixed: bool = True, turn: float = 0.0) -> Placed | None:
        """``made`` with its back to the first of ``walls`` that has a free spot for it (spots drawn);
        ``turn`` as in :meth:`against`."""
        lo, hi = moved_box(made.lo, made.hi, pose_matrix(np.zeros(3), turn))
        width = hi[1] - lo[1]
        for gap in (WALL_GAP, 0.05, 0.1):  # furniture may stand a little off the wall (a skirting, a lid's swing)
            for name in walls:
                wall = self.room.wall(name)
                for s in rng.permutation(np.arange(0.05, wall.length - width - 0.05, step)):
                    got = self.against(made, wall, float(s), z=z, fixed=fixed, turn=turn, gap=gap)
                    if got is not None:
                        return got
        return None

    def on_floor(self, made: Made, rng: np.random.Generator, yaws=(0.0,), tries: int = 40, margin: float = 0.3,
                 fixed: bool = True) -> Placed | None:
        """``made`` standing free of the walls (``margin`` off them) at a drawn spot and turn."""
        r = self.room
        for _ in range(tries):
            yaw = float(yaws[int(rng.integers(len(yaws)))])
            xy = rng.uniform([margin, margin], [r.depth - margin, r.width - margin])
            got = self.at(made, xy, yaw, fixed=fixed)
            if got is not None:
                return got
        return None

    def tuck(self, made: Made, host: Placed, xy, outward, reach: tuple[float, float] = (-0.06, 0.25),
             gap: float = 0.01) -> Placed | None:
        """``made`` on the floor facing ``host`` (a chair at a table): its front ``reach`` beyond the point
        ``xy`` of the host's edge along ``outward`` (room frame, a unit vector square to the walls), from
        under the edge outwards in 2 cm steps, at the first distance where its hulls clear the host's
        (:meth:`hulls_clear`) and it fits among everything else; ``None`` where none does."""
        out = np.array([outward[0], outward[1]], float)
        yaw = math.atan2(-out[1], -out[0])  # its front (+X) towards the host
        for d in np.arange(reach[0], reach[1] + 1e-9, 0.02):
            centre = np.asarray(xy, float) + out * (float(d) + float(made.hi[0]))
            cand = Placed(self._id(made), made, pose_matrix((centre[0], centre[1], -made.lo[2]), yaw), True, "floor")
            if self.hulls_clear(cand, host, gap) and self.fits(cand, ignore=(host.id,)):
                self.placed.append(cand)
                return cand
        return None

    def room_of(self, width: float, depth: float, height: float, wall: float) -> Room:
        self.room = Room(round(width, 4), round(depth, 4), round(height, 4), wall)
        return self.room
