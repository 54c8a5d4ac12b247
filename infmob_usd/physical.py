"""Physical plausibility passes applied once, for every category.

* :func:`rest_on_ground` moves the object so its lowest point at rest is z = 0 (or its ``elevation``).
* :func:`rest_on_stops` makes every passive hinge neutral under gravity or pressed onto its
  rest stop (picking the side of a two-sided range, or adding a counterweight heel).
* :func:`ensure_gaps` erodes moving collision hulls that come too close to their parent.
* :func:`limit_to_ground` shortens limits so nothing goes below the ground.
* :func:`limit_to_clearance` shortens limits so moving parts never meet what they may not touch.
* :data:`DYNAMICS` gives passive joint dynamics per joint role, so doors stay
  where they are left and knobs do not spin freely.

Units: damping is N*m*s/rad (rotations) or N*s/m (slides); friction is N*m
(rotations) or N (slides); effort likewise N*m or N; velocity rad/s or m/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from .blueprint import Blueprint, descendants
from .errors import ModelError
from .hulls import hull_arrays
from .joints import Dof
from .rotation import axis_angle, axis_angles
from .triangles import triangle_cross


@dataclass(frozen=True)
class Dynamics:
    damping: float
    friction: float
    effort: float
    velocity: float


DYNAMICS: dict[str, Dynamics] = {
    "hinge": Dynamics(damping=2.0, friction=0.5, effort=50.0, velocity=2.0),       # doors, lids
    "slide": Dynamics(damping=10.0, friction=1.0, effort=200.0, velocity=0.5),     # drawers, racks
    "knob": Dynamics(damping=0.02, friction=0.01, effort=2.0, velocity=6.0),       # knobs, dials
    "button": Dynamics(damping=1.0, friction=0.2, effort=20.0, velocity=0.2),      # push buttons
    "turntable": Dynamics(damping=0.1, friction=0.05, effort=5.0, velocity=3.0),   # plates that spin
    "swivel": Dynamics(damping=0.5, friction=0.5, effort=20.0, velocity=3.0),      # lamp heads, arms
    "telescope": Dynamics(damping=20.0, friction=5.0, effort=100.0, velocity=0.3),  # sliding poles
    "wheel": Dynamics(damping=0.01, friction=0.005, effort=5.0, velocity=20.0),
    "lid": Dynamics(damping=0.5, friction=0.2, effort=10.0, velocity=2.0),
    "plate": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),       # plates in a rack
    "grate": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),       # oven grates
    "default": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),
}


def dynamics(role: str) -> Dynamics:
    return DYNAMICS.get(role, DYNAMICS["default"])


def rest_on_ground(bp: Blueprint) -> Blueprint:
    """A copy of ``bp`` translated (parts and joints) so its lowest point at rest sits at z = 0, or at
    ``bp.elevation`` for a wall-mounted object."""
    dz = float(bp.elevation) - float(bp.bounds()[0, 2])
    if abs(dz) < 1e-12:
        return bp
    offset = np.array([0.0, 0.0, dz])
    parts = {name: replace(part, pieces=[p.translated(offset) for p in part.pieces])
             for name, part in bp.parts.items()}
    joints = [
        replace(j, dofs=tuple(
            Dof(d.type, tuple(np.asarray(d.origin) + offset), d.axis, d.lower, d.upper) for d in j.dofs
        ))
        for j in bp.joints
    ]
    return replace(bp, parts=parts, joints=joints)


# ---------------------------------------------------------------------------
# passes on the built model (links in link frames, simple joints)

GROUND_TOL = 5e-4
"""m; a part may dip this far below z = 0 at a joint state (validators allow 1 mm)."""


def gap_size(extent: np.ndarray) -> float:
    """The clearance a moving part keeps from its parent: 2% of its smallest extent, >= 1 mm."""
    return max(0.001, 0.02 * float(np.min(extent)))


def _inflate(points: np.ndarray, d: float) -> np.ndarray:
    """Points of the Minkowski sum with a cube of half-size ``d`` (an L-inf offset)."""
    offs = np.array([[x, y, z] for x in (-d, d) for y in (-d, d) for z in (-d, d)])
    return (points[:, None, :] + offs[None]).reshape(-1, 3)


def _face_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    tri = v[f]
    n = triangle_cross(tri)
    length = np.sqrt(np.add.reduce(n * n, axis=1, keepdims=True))  # np.linalg.norm(n, axis=1, keepdims=True)
    keep = length[:, 0] > 1e-15
    return n[keep] / length[keep]


def _separated(a: np.ndarray, a_normals: np.ndarray, d: float, b: np.ndarray, b_normals: np.ndarray) -> bool:
    """Whether a face plane of either hull separates the hull of points ``a`` grown by a cube of
    half-size ``d`` (:func:`_inflate`) from the hull of points ``b``: a sufficient test for
    "no overlap" (edge-edge separations are left to the exact test)."""
    n = np.concatenate((a_normals, b_normals))
    nt = n.T
    pa, pb = a @ nt, b @ nt
    amax, amin = np.maximum.reduce(pa, 0), np.minimum.reduce(pa, 0)
    if d != 0:  # adding a zero grow changes no comparison
        grow = d * np.add.reduce(np.abs(n), 1)
        amax, amin = amax + grow, amin - grow
    return bool(np.logical_or.reduce((amax < np.minimum.reduce(pb, 0)) | (amin > np.maximum.reduce(pb, 0))))


def _boxes_meet(lo_a: np.ndarray, hi_b: np.ndarray, lo_b: np.ndarray, hi_a: np.ndarray) -> np.ndarray:
    """``lo_a < hi_b`` and ``lo_b < hi_a`` on each of the three axes (the last one; the others
    broadcast): whether boxes ``a`` and ``b`` overlap. The same comparisons as
    ``np.all((lo_a < hi_b) & (lo_b < hi_a), axis=-1)``, axis by axis (faster on wide arrays)."""
    out = (lo_a[..., 0] < hi_b[..., 0]) & (lo_b[..., 0] < hi_a[..., 0])
    out &= lo_a[..., 1] < hi_b[..., 1]
    out &= lo_b[..., 1] < hi_a[..., 1]
    out &= lo_a[..., 2] < hi_b[..., 2]
    out &= lo_b[..., 2] < hi_a[..., 2]
    return out


def ensure_gaps(links, joints) -> list:
    """New links whose moving parts' collision pieces keep :func:`gap_size` from their parent.

    Only collision shapes change (visual meshes stay as designed). Each offending
    convex piece of the child shrinks towards its centre by the gap on each axis
    (never by more than a quarter of its own extent there). Compound chains are
    checked child against the chain's real parent. The links given are not changed;
    links with nothing eroded are returned as they are.
    """
    import manifold3d

    by_name = {link.name: link for link in links}
    into = {j.child: j for j in joints}

    def real_parent(name):
        p = into[name].parent
        while by_name[p].dummy:
            p = into[p].parent
        return p

    new_pieces: dict[str, list] = {}
    boxes: dict[str, tuple | None] = {}  # per parent link: its convex pieces and their boxes, link frame
    meshes: dict[str, tuple] = {}
    for j in joints:
        child = by_name[j.child]
        if not j.movable or child.dummy or not child.pieces:
            continue
        parent = by_name[real_parent(child.name)]
        if not parent.pieces:
            continue
        offset = parent.origin - child.origin  # parent frame -> child frame (world-aligned at rest)
        if parent.name not in boxes:
            convex = [c for p in parent.pieces for c in p.convex]
            if convex:
                stacked = np.concatenate(convex)
                starts = np.cumsum([0] + [len(c) for c in convex[:-1]])
                boxes[parent.name] = (convex, np.minimum.reduceat(stacked, starts, axis=0),
                                      np.maximum.reduceat(stacked, starts, axis=0))
            else:
                boxes[parent.name] = None
        if boxes[parent.name] is None:
            continue
        parent_convex, parent_lo, parent_hi = boxes[parent.name]
        parent_hulls: dict[int, np.ndarray] = {}  # those met, moved into the child frame

        def parent_hull(i, convex=parent_convex, offset=offset, moved=parent_hulls):
            if i not in moved:
                moved[i] = convex[i] + offset
            return moved[i]

        if parent.name not in meshes:  # shared by the parent's children
            meshes[parent.name] = ([vf for p in parent.pieces for vf in p.hulls()], {})
        # the parent's hull meshes, and the face normals of those met (link frame), as test directions
        parent_meshes, normals = meshes[parent.name]
        # the box of a translated point set is the translated box, bit for bit (rounding is monotone)
        box_lo = parent_lo + offset
        box_hi = parent_hi + offset
        child_convex = [c for p in child.pieces for c in p.convex]
        pts = np.vstack(child_convex or [np.zeros((1, 3))])
        gap = gap_size(np.ptp(pts, axis=0))
        cache: dict[int, manifold3d.Manifold] = {}
        pieces = list(child.pieces)
        if child_convex:  # every child hull's box grown by the gap against every parent hull's box at once
            starts = np.cumsum([0] + [len(c) for c in child_convex[:-1]])
            lo_all = np.minimum.reduceat(pts, starts, axis=0) - gap
            hi_all = np.maximum.reduceat(pts, starts, axis=0) + gap
            near_all = _boxes_meet(box_lo[None], hi_all[:, None], lo_all[:, None], box_hi[None])
            near_any = near_all.any(axis=1).tolist()
        g = -1  # index of the child convex piece among all of the link's
        for n, piece in enumerate(child.pieces):
            hulls = piece.hulls()
            eroded: dict[int, tuple] = {}
            for k, c in enumerate(piece.convex):
                g += 1
                if not near_any[g]:
                    continue
                near = np.flatnonzero(near_all[g])
                child_n = _face_normals(*hulls[k])
                grown = None
                hit = False
                for i in near:
                    if i not in normals:
                        normals[i] = _face_normals(*parent_meshes[i])
                    if _separated(c, child_n, gap - 1e-6, parent_hull(i), normals[i]):
                        continue  # a face plane separates them: no overlap, no exact test needed
                    if grown is None:
                        grown = manifold3d.Manifold.hull_points(_inflate(c, gap - 1e-6))
                    if i not in cache:
                        cache[i] = manifold3d.Manifold.hull_points(parent_hull(i))
                    if (grown ^ cache[i]).volume() > 1e-12:
                        hit = True
                        break
                if hit:
                    centre = (c.min(0) + c.max(0)) / 2
                    half = (c.max(0) - c.min(0)) / 2
                    shrink = np.minimum(gap, 0.25 * 2 * half)
                    scale = np.where(half > 0, (half - shrink) / np.where(half > 0, half, 1), 1.0)
                    hull_v, hull_f = hulls[k]
                    # the same axis scaling of the hull is the hull of the scaled points
                    eroded[k] = (centre + (c - centre) * scale, centre + (hull_v - centre) * scale, hull_f)
            if eroded:
                pieces[n] = piece.with_convex(eroded)
                new_pieces[child.name] = pieces
    return [replace(link, pieces=new_pieces[link.name]) if link.name in new_pieces else link for link in links]


def _extreme_points(links, only: set | None = None) -> dict[str, np.ndarray]:
    """Per link (of ``only`` if given), the vertices of the convex hull of all its collision hulls
    (in the link frame).

    The lowest point of a rigidly moved link is one of them, and there are far fewer of them
    than hull vertices.
    """
    out = {}
    for link in links:
        if only is not None and link.name not in only:
            continue
        pts = [v for p in link.pieces for v, _ in p.hulls()]
        if pts:
            pts = np.vstack(pts)
            out[link.name] = hull_arrays(pts)[0] if len(pts) > 64 else pts
    return out


def limit_to_ground(links, joints) -> list:
    """New joints whose limits keep every part above the ground at any single joint's limit.

    For each limited joint alone, the state at each limit is checked; if the moved
    subtree dips below ``-GROUND_TOL``, that limit is moved towards rest by
    bisection until it clears. A continuous joint that goes below the ground
    cannot be limited: that raises :class:`~infmob_usd.errors.ModelError` (the
    category must raise its base). The joints given are not changed; joints whose
    limits stand are returned as they are.
    """
    # only links that some joint moves are ever tested (the root's hull, often the largest, is not)
    moved_by = {j.name: descendants(joints, j.child) for j in joints if j.movable}
    extreme = _extreme_points(links, set().union(*moved_by.values()))
    origin = {link.name: np.asarray(link.origin, float) for link in links}
    out = []
    for j in joints:
        out.append(j)
        if not j.movable:
            continue
        moved = moved_by[j.name]
        # one joint moves from rest, so its subtree moves rigidly: world points at rest, about the pivot
        pts = [extreme[n] + origin[n] for n in moved if n in extreme]
        if not pts:
            continue
        rel = np.vstack(pts) - origin[j.child]
        pivot_z, axis = float(origin[j.child][2]), np.asarray(j.axis, float)

        def lowest(value: float, j=j, rel=rel, pivot_z=pivot_z, axis=axis) -> float:
            if j.type == "prismatic":
                return pivot_z + float(rel[:, 2].min()) + value * float(axis[2])
            return pivot_z + float((rel @ axis_angle(axis, value)[2]).min())

        if j.type == "continuous":
            for a in (0.5 * np.pi, np.pi, -0.5 * np.pi):
                if lowest(a) < -GROUND_TOL:
                    raise ModelError(f"continuous joint {j.name} turns {j.child!r} through the ground;"
                                     " raise it or make it a limited revolute joint")
            continue
        for end in ("upper", "lower"):
            limit = getattr(j, end)
            if limit == 0 or lowest(limit) >= -GROUND_TOL:
                continue
            good, bad = 0.0, limit
            for _ in range(30):
                mid = 0.5 * (good + bad)
                if lowest(mid) >= -GROUND_TOL:
                    good = mid
                else:
                    bad = mid
            if abs(good) < 1e-6:
                raise ModelError(f"joint {j.name} cannot move {j.child!r} at all without hitting the ground")
            out[-1] = replace(out[-1], **{end: good})
    return out


# ---------------------------------------------------------------------------
# passive joints at rest: neutral under gravity or pressed onto the rest stop

GRAVITY = np.array([0.0, 0.0, -9.81])
"""m/s^2, world."""

BALANCED = 2e-4
"""m; a revolute joint whose carried centre of mass lies this close to the vertical plane
through its axis (torque below ``BALANCED * g * mass``) is *neutral* under gravity."""

HEEL_SECTION = (0.008, 0.03)
"""m; the side of a counterweight heel's square section is 60 % of the carried link's extent
along the joint axis, within these bounds."""


def gravity_torque(links, joints, joint) -> tuple[float, float, np.ndarray]:
    """Gravity torque about ``joint``'s axis at rest (N m, positive = toward +q), the mass it
    carries (kg) and the carried centre of mass ``(3,)`` in world coordinates.

    The carried mass is every link of the joint's subtree with its real mass and centre of mass
    (:func:`~infmob_usd.mass.inertial`, as written to the files).
    """
    by_name = {link.name: link for link in links}
    mass, moment = 0.0, np.zeros(3)
    for name in descendants(joints, joint.child):
        link = by_name[name]
        mass += link.mass
        moment += link.mass * (np.asarray(link.origin, float) + link.com)
    com = moment / mass
    torque = float(np.cross(com - np.asarray(joint.origin, float), mass * GRAVITY) @ np.asarray(joint.axis, float))
    return torque, mass, com


def rest_on_stops(links, joints, densities: dict[str, float], walls: dict[str, float] | None = None):
    """Make every passive revolute joint neutral under gravity or pressed onto its rest stop.

    A *passive* joint is one with no drive: every joint of a generated object is (they only
    have damping and friction). This pass treats the joints declared ``revolute`` (single
    DoF; compound chains keep their declared limits). With ``tau`` the gravity torque at rest
    about the axis of everything the joint carries (:func:`gravity_torque`):

    * ``|tau| <= BALANCED * g * mass``: *neutral* (a swivel about Z, a head hanging under its
      pivot); unchanged.
    * gravity pushes toward negative q: if ``lower == 0`` the joint is *pressed onto its rest
      stop*; unchanged. If the range is two-sided (``lower < 0 < upper``) the core keeps the
      side that lifts the load: limits ``(0, upper)``.
    * gravity pushes toward positive q with a two-sided range: the axis is flipped and the
      limits become ``(0, -lower)`` (pressed onto the stop that was the lower side).
    * otherwise (rest is a stop and gravity pulls away from it: a lever's grip hanging off
      its axis) a *counterweight heel* is added to the child link: a bar of the child's
      heaviest material from the axis along the side opposite the carried centre of mass,
      as long as it must be to bring that centre onto the axis (moment ``rho A L^2 / 2``).

    The heel is solid (``wall=0``) whatever its family's wall; ``walls`` (slot -> m) mass the
    child's other pieces as :func:`~infmob_usd.model.build` did.

    Returns new ``(links, joints)`` lists; links and joints not changed are the same objects.
    """
    from .mass import inertial
    from .primitives import box_between

    links, joints = list(links), list(joints)
    index = {link.name: i for i, link in enumerate(links)}
    for k, j in enumerate(joints):
        if j.kind != "revolute" or j.type != "revolute":
            continue
        torque, mass, com = gravity_torque(links, joints, j)
        if abs(torque) <= BALANCED * abs(GRAVITY[2]) * mass:
            continue
        if torque < 0 and j.lower == 0:
            continue
        if torque < 0 and j.upper > 0:
            joints[k] = replace(j, lower=0.0)
            continue
        if torque > 0 and j.lower < 0:
            joints[k] = replace(j, axis=-np.asarray(j.axis, float), lower=0.0, upper=-j.lower)
            continue
        # a counterweight heel on the child: its moment about the axis cancels the carried one
        child = links[index[j.child]]
        if not child.pieces:
            continue
        axis, pivot = np.asarray(j.axis, float), np.asarray(j.origin, float)
        arm = com - pivot
        arm = arm - (arm @ axis) * axis  # the carried centre off the axis, perpendicular to it
        r = float(np.linalg.norm(arm))
        u = arm / r
        w = np.cross(axis, u)
        heaviest = max(child.pieces, key=lambda p: densities[p.material] * p.volume())
        rho = densities[heaviest.material]
        local = [v for p in child.pieces for v, _ in p.hulls()] or [p.vertices for p in child.pieces]
        along = np.vstack(local) @ axis
        side = float(np.clip(0.6 * np.ptp(along), *HEEL_SECTION))
        length = math.sqrt(2.0 * mass * r / (rho * side * side))
        # the bar in a frame (u, w, axis) at the pivot, at the carried centre's axial position
        centre = pivot + (float((com - pivot) @ axis)) * axis - 0.5 * length * u
        frame = np.eye(4)
        frame[:3, :3] = np.column_stack([u, w, axis])
        frame[:3, 3] = centre - np.asarray(child.origin, float)  # link-local
        heel = box_between([-length / 2, -side / 2, -side / 2], [length / 2, side / 2, side / 2],
                           heaviest.material, name="counterweight").transformed(frame).replace(wall=0.0)
        pieces = child.pieces + [heel]
        walls = walls or {}
        m, c, inertia = inertial((p, densities[p.material], walls.get(p.material, 0.0)) for p in pieces)
        links[index[j.child]] = replace(child, pieces=pieces, mass=m, com=c, inertia=inertia)
    return links, joints


# ---------------------------------------------------------------------------
# joint limits from clearance: swept collision hulls against everything else

CLEARANCE = 1e-3
"""m; a moving subtree stops this far from what it may not touch (where it starts farther)."""

CONTACT_VOLUME = 1e-8
"""m^3; an exact hull intersection above this is a contact (validators fail at 1e-7 per pair)."""

SWEEP_SAGITTA = 2.5e-4
"""m; a turn is sampled finely enough that its arcs bulge at most this far past the chords
between samples (the swept volume between two samples is the hull of the two poses)."""

PARENT_GROWTH = 5e-8
"""m^3; how much more a moving subtree may overlap its parent than at rest (validators: 1e-7)."""

ALL_FRACTIONS = (0.5, 1.0)
"""The combined states the validators sample: every joint at once at 50 % and 100 % of its
range (continuous joints at f pi), prerequisites fully open."""


@dataclass(frozen=True)
class _Hull:
    link: str
    points: np.ndarray  # (k, 3) hull vertices, link frame
    faces: np.ndarray  # (m, 3)

    @cached_property
    def normals(self) -> np.ndarray:
        """``(m, 3)`` distinct face normals, link frame (the triangles of one flat face share one)."""
        n = _face_normals(self.points, self.faces)
        # the first row of each distinct rounded normal (its 24 bytes), in row order: a dict built
        # from the last row to the first keeps the first row's index
        b = np.round(n, 9).tobytes()
        first = dict(zip([b[i:i + 24] for i in range(len(b) - 24, -24, -24)], range(len(n) - 1, -1, -1)))
        return n[sorted(first.values())]


def _solid_hulls(obj) -> dict[str, list[_Hull]]:
    out = {}
    for link in obj.links:
        if link.dummy or not link.pieces:
            continue
        hulls = [_Hull(link.name, v, f) for p in link.pieces for v, f in p.hulls()]
        if hulls:
            out[link.name] = hulls
    return out


def _value_at(joint, limits, fraction: float) -> float:
    if joint.type == "continuous":
        return fraction * math.pi
    lo, hi = limits[joint.name]
    return lo + fraction * (hi - lo)


_EYE4 = np.eye(4)
_EYE4.flags.writeable = False


def _motion(joint_type: str, pivot: np.ndarray, axis: np.ndarray, value: float) -> np.ndarray:
    m = _EYE4.copy()  # np.eye(4)
    if joint_type == "prismatic":
        m[:3, 3] = axis * value
    else:
        r = axis_angle(axis, value)
        m[:3, :3], m[:3, 3] = r, pivot - r @ pivot
    return m


def _motions(joint_type: str, pivot: np.ndarray, axis: np.ndarray, values: np.ndarray) -> list[np.ndarray]:
    """:func:`_motion` at each of ``values`` (the same matrices, the turns made in one call)."""
    if joint_type == "prismatic":
        return [_motion(joint_type, pivot, axis, v) for v in values]
    out = []
    for r in axis_angles(axis, values):
        m = _EYE4.copy()  # np.eye(4)
        m[:3, :3], m[:3, 3] = r, pivot - r @ pivot
        out.append(m)
    return out


_ROUNDED = object()  # key in an _Obstacles cache of the rounded key of each exact pose


class _Obstacles:
    """Posed hulls of the links a sweep may not enter, with lazily built exact solids.

    ``cache`` is shared between sweeps: per link and pose (rounded to 1e-9), the posed points and
    hull boxes; per hull and pose, the posed normals and the exact solid; per link, its hull points
    stacked in its frame; per exact pose, its rounded key."""

    def __init__(self, links: list[str], hulls: dict[str, list[_Hull]], poses: dict[str, np.ndarray],
                 cache: dict):
        self.hulls: list[_Hull] = []
        self.world: list[np.ndarray] = []
        self.keys: list[tuple] = []
        self.poses = poses
        lo, hi = [], []
        for name in links:
            pose = poses[name]
            exact = pose.tobytes()
            rounded = cache.setdefault(_ROUNDED, {}).get(exact)  # the key of each exact pose, once
            if rounded is None:
                rounded = cache[_ROUNDED][exact] = pose.round(9).tobytes()
            key = (name, rounded)
            if key not in cache:
                hs = hulls[name]
                if ("local", name) not in cache:  # the link's hull points stacked, in its frame
                    cache["local", name] = (np.vstack([h.points for h in hs]),
                                            np.cumsum([0] + [len(h.points) for h in hs]))
                local, starts = cache["local", name]
                stacked = local @ pose[:3, :3].T + pose[:3, 3]
                cache[key] = ([stacked[a:b] for a, b in zip(starts[:-1], starts[1:])],
                              np.minimum.reduceat(stacked, starts[:-1], axis=0),
                              np.maximum.reduceat(stacked, starts[:-1], axis=0),
                              [key + (k,) for k in range(len(hs))])
            world, l, h, keys = cache[key]
            self.hulls += hulls[name]
            self.world += world
            self.keys += keys
            lo.append(l)
            hi.append(h)
        if len(lo) == 1:
            self.lo, self.hi = lo[0], hi[0]
        else:
            self.lo = np.vstack(lo) if lo else np.zeros((0, 3))
            self.hi = np.vstack(hi) if hi else np.zeros((0, 3))
        self._cache = cache

    def normals(self, i: int) -> np.ndarray:
        key = ("normals",) + self.keys[i]
        if key not in self._cache:
            self._cache[key] = self.hulls[i].normals @ self.poses[self.hulls[i].link][:3, :3].T
        return self._cache[key]

    def solid(self, i: int, grown: float = 0.0):
        """The exact solid of hull ``i``, grown by a cube of half-size ``grown`` (:func:`_inflate`)."""
        import manifold3d

        key = ("solid", grown) + self.keys[i]
        if key not in self._cache:
            pts = _inflate(self.world[i], grown) if grown > 0 else self.world[i]
            self._cache[key] = manifold3d.Manifold.hull_points(pts)
        return self._cache[key]


def _hits(points: np.ndarray, normals: np.ndarray, margin: float, obstacles: _Obstacles, i: int,
          solids: dict | None = None, key=None) -> bool:
    """Whether the hull of ``points`` grown by ``margin`` overlaps obstacle hull ``i`` by more than
    :data:`CONTACT_VOLUME`: a face-plane separation test first, the exact intersection if it fails.
    ``solids`` (with ``key`` naming ``points``) keeps the exact hull of ``points`` for the next
    obstacle tested against the same points."""
    if _separated(points, normals, margin, obstacles.world[i], obstacles.normals(i)):
        return False
    import manifold3d

    if solids is None:
        solid = manifold3d.Manifold.hull_points(points)
    else:
        solid = solids.get(key)
        if solid is None:
            solid = solids[key] = manifold3d.Manifold.hull_points(points)
    # the obstacle grown by the margin (built once per obstacle) rather than every moving hull
    return (solid ^ obstacles.solid(i, margin)).volume() > CONTACT_VOLUME


class _Normals:
    """World face normals of posed hulls, computed when first asked for."""

    def __init__(self, hulls: list[_Hull], poses):
        self.hulls, self.poses, self.done = hulls, poses, {}

    def __getitem__(self, h: int) -> np.ndarray:
        if h not in self.done:
            hull = self.hulls[h]
            self.done[h] = hull.normals @ self.poses[hull.link][:3, :3].T
        return self.done[h]


def _posed(moving: list[_Hull], poses, cache: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
    """World points of the ``moving`` hulls stacked ``(n, 3)``, and the row where each starts
    (one more entry: the end). ``cache`` keeps each hull's world points per exact pose of its link
    (the hulls of a link deep in a chain are moved by each joint above it)."""
    sizes = [len(h.points) for h in moving]
    starts = np.cumsum([0] + sizes)
    out = np.empty((starts[-1], 3))
    for h, a, b in zip(moving, starts[:-1], starts[1:]):
        pose = poses[h.link]
        if cache is None:
            out[a:b] = h.points @ pose[:3, :3].T + pose[:3, 3]
            continue
        key = (id(h), pose.tobytes())
        w = cache.get(key)
        if w is None:
            w = cache[key] = h.points @ pose[:3, :3].T + pose[:3, 3]
        out[a:b] = w
    return out, starts


_CORNERS = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)


class _Moving:
    """The hulls one joint moves, posed at rest (``poses``, the joint at 0), with what the sweep
    and the parent check of both sides of its range share: world points and normals, boxes at
    rest, the rest tests against the obstacles (each computed once)."""

    def __init__(self, joint, hulls: list[_Hull], poses, cache: dict | None = None):
        self.joint, self.hulls = joint, hulls
        self.pivot = poses[joint.child][:3, 3]
        self.axis = poses[joint.parent][:3, :3] @ np.asarray(joint.axis, float)
        self.stacked, self.starts = _posed(hulls, poses, cache)
        self.normals = _Normals(hulls, poses)
        self.lo0 = np.minimum.reduceat(self.stacked, self.starts[:-1], axis=0)
        self.hi0 = np.maximum.reduceat(self.stacked, self.starts[:-1], axis=0)
        self.rest: dict[tuple, bool] = {}  # (hull, obstacle hull, margin) -> _hits at rest (sweep obstacles)
        self.touching: frozenset | None = None  # hull pairs overlapping the parent's at rest
        self.untouched: np.ndarray | None = None  # (moving hull, parent hull): not touching

    @cached_property
    def world(self) -> list[np.ndarray]:
        stacked, starts = self.stacked, self.starts
        return [stacked[a:b] for a, b in zip(starts[:-1], starts[1:])]

    @cached_property
    def radius(self) -> float:
        """Of the largest circle a turn moves a point on (m)."""
        rel = self.stacked - self.pivot
        axis = self.axis
        return float(np.sqrt(np.max(np.einsum("ij,ij->i", rel, rel) - (rel @ axis) ** 2).clip(0))) + 1e-9

    @cached_property
    def box(self) -> np.ndarray:
        """``(8 hulls, 3)``: the corners of each hull's box at rest."""
        lo0, hi0 = self.lo0, self.hi0
        return (lo0[:, None, :] + _CORNERS[None] * (hi0 - lo0)[:, None, :]).reshape(-1, 3)

    def hits_at_rest(self, h: int, margin: float, obstacles: _Obstacles, o: int) -> bool:
        key = (h, o, margin)
        if key not in self.rest:
            self.rest[key] = _hits(self.world[h], self.normals[h], margin, obstacles, o)
        return self.rest[key]


_FREE_PAD = 1e-9
"""m; how much looser :func:`_sweep_limit`'s quick bound on the hull boxes is than the exact ones
(their rounding differences are ~1e-15 m for objects of metres)."""


def _sweep_limit(moving: _Moving, limit: float, obstacles: _Obstacles, allowed: np.ndarray) -> tuple[float, str]:
    """The largest value in ``[0, limit]`` (or ``[limit, 0]``) to which ``moving.joint`` turns or
    slides the ``moving`` hulls without a contact with the obstacle hulls where ``allowed`` (bool
    per obstacle hull) is true: ``(value, link hit)``."""
    joint, pivot, axis = moving.joint, moving.pivot, moving.axis
    if joint.type == "prismatic":
        n = 1
    else:
        step = min(0.2, math.sqrt(8.0 * SWEEP_SAGITTA / moving.radius))
        n = max(1, math.ceil(abs(limit) / step))
    values = np.linspace(0.0, limit, n + 1)
    lo0, hi0 = moving.lo0, moving.hi0
    # Most sweeps meet nothing: a bound on the boxes below (centre and half extent of each hull's
    # box moved to every sample, by BLAS) that is looser than them by far more than its rounding
    # (FREE_PAD) shows first whether any pair can be near; if none can, the exact boxes would find
    # none either, and the result is the same without them.
    centre, half = 0.5 * (lo0 + hi0), 0.5 * (hi0 - lo0)
    if joint.type == "prismatic":
        moved = centre[None] + (values[:, None] * axis)[:, None]
        reach = np.broadcast_to(half, moved.shape)
    else:
        turns = axis_angles(axis, values)
        moved = centre @ turns.transpose(0, 2, 1) + (pivot - turns @ pivot)[:, None]
        reach = half @ np.abs(turns).transpose(0, 2, 1)
    pad = CLEARANCE + _FREE_PAD
    free_lo, free_hi = (moved - reach).min(0) - pad, (moved + reach).max(0) + pad
    if not (_boxes_meet(free_lo[:, None], obstacles.hi[None], obstacles.lo[None], free_hi[:, None]) & allowed).any():
        return float(limit), ""
    mats = _motions(joint.type, pivot, axis, values)
    # per-hull boxes at every sample (the posed corners of each hull's box bound the hull)
    box = moving.box
    nh = len(moving.hulls)
    posed = np.einsum("kij,nj->kni", np.array([m[:3, :3] for m in mats]), box) + np.array(
        [m[:3, 3] for m in mats])[:, None, :]
    posed = posed.reshape(len(mats), nh, 8, 3)
    # the least and greatest of the 8 corners, halving (a min over the middle axis is slow);
    # min and max are exact, so the values are those of posed.min(2) and posed.max(2) (up to the
    # sign of a zero, which no comparison below sees)
    lo, hi = np.minimum(posed[:, :, :4], posed[:, :, 4:]), np.maximum(posed[:, :, :4], posed[:, :, 4:])
    lo, hi = np.minimum(lo[:, :, :2], lo[:, :, 2:]), np.maximum(hi[:, :, :2], hi[:, :, 2:])
    lo, hi = np.minimum(lo[:, :, 0], lo[:, :, 1]), np.maximum(hi[:, :, 0], hi[:, :, 1])
    # hull pairs that may meet somewhere in the range, then in which sample intervals
    lo_all, hi_all = lo.min(0) - CLEARANCE, hi.max(0) + CLEARANCE
    hs, os = np.nonzero(_boxes_meet(lo_all[:, None], obstacles.hi[None], obstacles.lo[None], hi_all[:, None]) & allowed)
    if not len(hs):
        return float(limit), ""
    ilo = np.minimum(lo[:-1], lo[1:])[:, hs] - CLEARANCE
    ihi = np.maximum(hi[:-1], hi[1:])[:, hs] + CLEARANCE
    near = _boxes_meet(ilo, obstacles.hi[os], obstacles.lo[os], ihi)  # (intervals, pairs)
    world, normals = moving.world, moving.normals
    # each pair that may meet keeps CLEARANCE if it starts that far apart, else 0 if it starts
    # apart, else (it overlaps at rest: not this joint's doing) it is left out
    # (only pairs near in some interval: the others are never tested); a pair whose boxes at rest
    # are farther apart than the clearance (and a nanometre) on an axis cannot meet the obstacle
    # grown by it, so the exact test is left out for it
    margin = np.full(len(hs), np.nan)
    apart = np.any((lo0[hs] - (CLEARANCE + 1e-9) > obstacles.hi[os])
                   | (obstacles.lo[os] - (CLEARANCE + 1e-9) > hi0[hs]), axis=1)
    for p in np.flatnonzero(near.any(axis=0)):
        h, o = hs[p], os[p]
        if apart[p] or not moving.hits_at_rest(h, CLEARANCE, obstacles, o):
            margin[p] = CLEARANCE
        elif not moving.hits_at_rest(h, 0.0, obstacles, o):
            margin[p] = 0.0
    near &= ~np.isnan(margin)

    # hull h moved by a motion: its world points and normals, kept per (sample or bisection value)
    moved: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}

    def at(h, m, key):
        if (h, key) not in moved:
            moved[h, key] = (world[h] @ m[:3, :3].T + m[:3, 3], normals[h] @ m[:3, :3].T)
        return moved[h, key]

    def swept_hits(k: int, m1: np.ndarray, key1, pairs, first: bool) -> list[int]:
        """The pairs among ``pairs`` that meet while the joint moves from sample ``k`` to ``m1``
        (named ``key1``)."""
        m0, out = mats[k], []
        swept: dict[int, tuple[np.ndarray, np.ndarray]] = {}  # per moving hull: the swept hull's points, normals
        solids: dict = {}
        for p in pairs:
            h, o = hs[p], os[p]
            if h not in swept:
                (w0, n0), (w1, n1) = at(h, m0, k), at(h, m1, key1)
                swept[h] = (np.vstack([w0, w1]), np.vstack([n0, n1]))
            pts, nrm = swept[h]
            if _hits(pts, nrm, margin[p], obstacles, o, solids, h):
                out.append(p)
                if first:
                    break
        return out

    for k in np.flatnonzero(near.any(axis=1)):
        pairs = swept_hits(k, mats[k + 1], k + 1, np.flatnonzero(near[k]), False)
        if not pairs:
            continue
        # within the interval only the pairs that meet over all of it can meet over part of it
        # (up to the sagitta)
        good, bad = float(values[k]), float(values[k + 1])
        for _ in range(14):
            mid = 0.5 * (good + bad)
            hit = swept_hits(k, _motion(joint.type, pivot, axis, mid), ("mid", mid), pairs, True)
            if hit:
                bad = mid
            else:
                good = mid
        return good, obstacles.hulls[os[pairs[0]]].link
    return float(limit), ""


def _overlap(moving: tuple[np.ndarray, np.ndarray, list[np.ndarray]], obstacles: _Obstacles,
             motion: np.ndarray, skip: frozenset = frozenset()) -> float:
    """Summed exact intersection volume of the ``moving`` hulls (stacked world points, start of
    each hull's rows, world normals per hull) moved by ``motion`` with the obstacle hulls (box
    and face-plane prefilters; no margin), leaving out the hull pairs ``(moving, obstacle)`` in
    ``skip``."""
    import manifold3d

    if not len(obstacles.hulls):
        return 0.0
    stacked, starts, normals = moving
    r, t = motion[:3, :3], motion[:3, 3]
    p = stacked @ r.T + t
    lo, hi = np.minimum.reduceat(p, starts[:-1], axis=0), np.maximum.reduceat(p, starts[:-1], axis=0)
    near = _boxes_meet(lo[:, None], obstacles.hi[None], obstacles.lo[None], hi[:, None])
    total = 0.0
    solids: dict[int, object] = {}
    turned: dict[int, np.ndarray] = {}  # moving hull -> its world normals moved by ``motion``
    rt = r.T
    for h, i in zip(*np.nonzero(near)):
        if (h, i) in skip:
            continue
        w = p[starts[h]:starts[h + 1]]
        if h not in turned:
            turned[h] = normals[h] @ rt
        if _separated(w, turned[h], 0.0, obstacles.world[i], obstacles.normals(i)):
            continue
        if h not in solids:
            solids[h] = manifold3d.Manifold.hull_points(w)
        total += (solids[h] ^ obstacles.solid(i)).volume()
    return total


def _parent_limit(moving: _Moving, limit: float, parent: _Obstacles) -> tuple[float, str]:
    """The largest value in ``[0, limit]`` at which the moving hulls apart from the parent's at rest
    overlap them by at most :data:`PARENT_GROWTH` in all, checked at quarters of the range (the
    validators' parent_child states) and bisected below the first quarter that fails. Hull pairs
    that overlap at rest (more than :data:`CONTACT_VOLUME`) are part of the design and left out."""
    if not len(parent.hulls) or limit == 0:
        return float(limit), ""
    joint, pivot, axis = moving.joint, moving.pivot, moving.axis
    stacked, starts, normals = world = (moving.stacked, moving.starts, moving.normals)
    # hull pairs that overlap at rest are part of the design (a pin in its bore, a pole in its
    # tube): what counts is pairs apart at rest coming together
    if moving.touching is None:
        lo, hi = moving.lo0, moving.hi0
        moving.touching = frozenset(
            (h, i) for h, i in zip(*np.nonzero(_boxes_meet(lo[:, None], parent.hi[None], parent.lo[None], hi[:, None])))
            if _hits(stacked[starts[h]:starts[h + 1]], normals[h], 0.0, parent, i))
        untouched = np.ones((len(moving.hulls), len(parent.hulls)), bool)
        for h, i in moving.touching:
            untouched[h, i] = False
        moving.untouched = untouched
    touching = moving.touching
    # a bound on each moving hull's box at a state (its rest box turned, :data:`_FREE_PAD` looser
    # than the hull's own box there): where no pair apart at rest can be near, _overlap would
    # find nothing to add and give 0.0
    lo0, hi0 = moving.lo0, moving.hi0
    centre, half = 0.5 * (lo0 + hi0), 0.5 * (hi0 - lo0) + _FREE_PAD

    def grows(v):
        motion = _motion(joint.type, pivot, axis, v)
        r = motion[:3, :3]
        c, e = centre @ r.T + motion[:3, 3], half @ np.abs(r).T
        if not (_boxes_meet((c - e)[:, None], parent.hi[None], parent.lo[None], (c + e)[:, None])
                & moving.untouched).any():
            return False
        return _overlap(world, parent, motion, touching) > PARENT_GROWTH

    previous = 0.0
    for f in (0.25, 0.5, 0.75, 1.0):
        if grows(f * limit):
            good, bad = previous, f * limit
            for _ in range(14):
                mid = 0.5 * (good + bad)
                good, bad = (good, mid) if grows(mid) else (mid, bad)
            return good, parent.hulls[0].link
        previous = f * limit
    return float(limit), ""


def clearance_limits(obj) -> dict[str, tuple[float, float]]:
    """Joint limits shortened so no moving part meets a link it may not touch.

    1. *Each joint alone* (in tree order, parents first): each side of the range of every
       revolute and prismatic joint (compound chains DoF by DoF) is swept from rest with the
       other joints at rest. The collision hulls of the subtree it moves, swept (hull of two
       consecutive poses; turns sampled so arcs bulge at most :data:`SWEEP_SAGITTA` past the
       chords), keep :data:`CLEARANCE` from every hull of every link but its parent, and its
       overlap with the parent grows by at most :data:`PARENT_GROWTH` over rest at quarters of
       the range (a door may not swing into its own carcass; a polygonal pin may turn in its
       polygonal bore). A hull pair that already overlaps, or is
       closer than the clearance, at rest keeps only what it has (it is not this joint's
       doing). A joint that ``requires_open`` a part sweeps with that part fully open. The limit
       becomes the last contact-free value, bisected (14 steps) within the first sample
       interval that meets something.
    2. *Joints together*: in the states :data:`ALL_FRACTIONS` (every joint at 50 % and 100 % of
       its range, as the validators sample them), two links that may touch neither by design
       (welded, or parent and child) nor at rest must keep the clearance (or, if closer at rest,
       must not overlap); where they do not, the limits of
       the movable joints between them (not those others require open; only the revolute ones
       if there are any: a door stops before a drawer gives up travel) are scaled by the same
       factor, the largest that separates them (bisection to 0.4 %), until no state changes.

    Returns ``{joint name: (lower, upper)}`` for every movable joint (continuous joints keep
    theirs: see :func:`limit_to_ground`).
    """
    from .errors import ModelError

    hulls = _solid_hulls(obj)
    movable = [j for j in obj.joints if j.movable]
    limits = {j.name: (float(j.lower), float(j.upper)) for j in movable}
    groups: dict[str, list] = {}
    for j in movable:
        groups.setdefault(j.group, []).append(j)
    gates = {j.name: [g.name for g in groups.get(j.requires_open, [])] for j in movable if j.requires_open}
    gate_of_someone = {name for names in gates.values() for name in names}
    by_name = {link.name: link for link in obj.links}
    into = {j.child: j for j in obj.joints}
    subtree = {j.name: descendants(obj.joints, j.child) for j in movable}
    by_joint = {j.name: j for j in movable}
    cache: dict = {}
    scenes: dict = {}
    posed: dict = {}

    def poses_at(q):
        """``obj.poses(q)``, computed once per state (the search revisits states; callers only read)."""
        key = tuple((k, float(v).hex()) for k, v in sorted(q.items()))
        if key not in posed:
            posed[key] = obj.poses(q)
        return posed[key]

    def real_parent(j):
        p = j.parent
        while by_name[p].dummy:
            p = into[p].parent
        return p

    def opened(q):
        for name in [n for n, v in q.items() if v != 0.0]:
            for g in gates.get(name, []):
                q[g] = limits[g][1]
        return q

    # 1. each joint alone, swept from rest
    hull_counts = [len(hs) for hs in hulls.values()]
    hull_world: dict = {}  # (hull, exact pose) -> world points
    for j in movable:
        if j.type not in ("revolute", "prismatic"):
            continue
        moving = [h for n in sorted(subtree[j.name]) for h in hulls.get(n, [])]
        if not moving:
            continue
        parent = real_parent(j)
        q = {g: limits[g][1] for g in gates.get(j.name, [])}
        key = tuple(sorted(q.items()))
        if key not in scenes:  # every link posed, shared by the joints that sweep in this state
            poses = poses_at(q)
            scenes[key] = (poses, _Obstacles(list(hulls), hulls, poses, cache))
        if limits[j.name] == (0.0, 0.0):
            continue
        poses, obstacles = scenes[key]
        # per obstacle hull (the links' hulls in ``hulls`` order): not moved by j, not its parent
        allowed = np.repeat([n not in subtree[j.name] and n != parent for n in hulls], hull_counts)
        below = _Obstacles([parent] if parent in hulls else [], hulls, poses, cache)
        moving = _Moving(j, moving, poses, hull_world)  # shared by both sides
        for side in (1, 0):
            limit = limits[j.name][side]
            if limit == 0:
                continue
            value, hit = _sweep_limit(moving, limit, obstacles, allowed)
            value, hit = min((value, hit), _parent_limit(moving, value, below), key=lambda t: abs(t[0]))
            if value != limit:
                if abs(value) < 1e-6:
                    raise ModelError(f"joint {j.name} cannot move {j.child!r} at all without meeting"
                                     f" {hit!r} (parent {real_parent(j)!r}); leave a gap between them")
                lo, hi = limits[j.name]
                limits[j.name] = (lo, value) if side == 1 else (value, hi)

    # 2. every joint at once
    solid = list(hulls)
    chain = {frozenset((real_parent(j), j.child)) for j in movable if not by_name[j.child].dummy}
    path = {}
    for i, a in enumerate(solid):
        for b in solid[i + 1:]:
            between = [j for j in movable if (a in subtree[j.name]) != (b in subtree[j.name])]
            if between and frozenset((a, b)) not in chain:
                path[tuple(sorted((a, b)))] = between
    if not path:
        return limits

    # link pair at exact poses, margin -> whether they meet: the search revisits states in which
    # most links have not moved (a result depends on the two links' posed hulls alone; an exact
    # repeat reads the same cached points, normals and solids as the first time)
    met: dict[tuple, bool] = {}

    def contacts(poses, pairs, margin=0.0) -> set:
        """Link pairs among ``pairs`` whose hulls, one grown by ``margin`` (a number, or a dict
        pair -> margin), overlap at ``poses``."""
        out = set()
        todo = []
        exact = {}  # link -> its exact pose's bytes
        for pair in sorted(tuple(sorted(p)) for p in pairs):
            d = margin if not isinstance(margin, dict) else margin[pair]
            for n in pair:
                if n not in exact:
                    exact[n] = poses[n].tobytes()
            seen = met.get((pair, exact[pair[0]], exact[pair[1]], d))
            if seen is None:
                todo.append((pair, d))
            elif seen:
                out.add(pair)
        if not todo:
            return out
        names = sorted({n for pair, _ in todo for n in pair})
        obstacles = _Obstacles(names, hulls, poses, cache)
        index = {n: k for k, n in enumerate(names)}
        starts = np.cumsum([0] + [len(hulls[n]) for n in names]).tolist()
        lo, hi = obstacles.lo, obstacles.hi
        # link boxes first: hull boxes of two links whose boxes are not near are not near
        # either (the same comparisons, monotone), so only near link pairs compare hull boxes
        link_lo = np.minimum.reduceat(lo, starts[:-1], axis=0)
        link_hi = np.maximum.reduceat(hi, starts[:-1], axis=0)
        link_near = _boxes_meet(link_lo[:, None], link_hi[None] + CLEARANCE,
                                link_lo[None], link_hi[:, None] + CLEARANCE)
        for pair, d in todo:
            ka, kb = index[pair[0]], index[pair[1]]  # ka < kb: the hulls of pair[0] come first
            hit = False
            if link_near[ka, kb]:
                a0, a1, b0, b1 = starts[ka], starts[ka + 1], starts[kb], starts[kb + 1]
                near = _boxes_meet(lo[a0:a1, None], hi[None, b0:b1] + CLEARANCE, lo[None, b0:b1],
                                  hi[a0:a1, None] + CLEARANCE)
                for u, v in zip(*np.nonzero(near)):
                    # the exact hull of pair[0]'s hull is the one obstacles.solid(a0 + u) keeps
                    if _hits(obstacles.world[a0 + u], obstacles.normals(a0 + u), d, obstacles, b0 + v,
                             cache, ("solid", 0.0) + obstacles.keys[a0 + u]):
                        hit = True
                        break
            met[pair, exact[pair[0]], exact[pair[1]], d] = hit
            if hit:
                out.add(pair)
        return out

    def state(f, scale=None):
        lim = dict(limits)
        if scale is not None:
            lim.update({name: (lo * scale[1], hi * scale[1]) for name, (lo, hi) in limits.items()
                        if name in scale[0]})
        q = {j.name: (f * math.pi if j.type == "continuous" else lim[j.name][0] + f * (lim[j.name][1]
             - lim[j.name][0])) for j in movable}
        for name in [n for n in q if q[n] != 0.0]:
            for g in gates.get(name, []):
                q[g] = lim[g][1]
        return poses_at(q)

    # pairs apart by the clearance at rest keep it; closer ones keep apart; overlapping ones are
    # left out (not a joint's doing)
    rest = poses_at({})
    touching = contacts(rest, set(path))
    checked = set(path) - touching
    near_rest = contacts(rest, checked, CLEARANCE)  # (only the pairs checked need a margin)
    margins = {pair: 0.0 if pair in near_rest else CLEARANCE for pair in checked}
    for _ in range(8):
        changed = False
        for f in ALL_FRACTIONS:
            for a, b in sorted(contacts(state(f), checked, margins)):
                names = {j.name for j in path[(a, b)] if j.type != "continuous" and j.name not in gate_of_someone}
                turns = {n for n in names if by_joint[n].type == "revolute"}
                names = turns or names  # a hinge stops before a slide gives up travel
                if not names:
                    continue
                good, bad = 0.0, 1.0
                for _ in range(8):
                    mid = 0.5 * (good + bad)
                    if (a, b) in contacts(state(f, (names, mid)), {(a, b)}, margins[(a, b)]):
                        bad = mid
                    else:
                        good = mid
                if good < 1e-6:
                    raise ModelError(f"links {a!r} and {b!r} meet whenever their joints move together")
                for name in sorted(names):
                    lo, hi = limits[name]
                    limits[name] = (lo * good, hi * good)
                changed = True
                break  # the state changed: look again
        if not changed:
            break
    return limits


def limit_to_clearance(obj):
    """A copy of ``obj`` whose joints have the limits of :func:`clearance_limits` (the object and
    its joints are not modified; unchanged joints are shared)."""
    limits = clearance_limits(obj)
    joints = [replace(j, lower=limits[j.name][0], upper=limits[j.name][1])
              if j.name in limits and limits[j.name] != (j.lower, j.upper) else j for j in obj.joints]
    return replace(obj, joints=joints)
