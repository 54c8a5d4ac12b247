"""Physical plausibility passes applied once, for every category.

* :func:`rest_on_ground` moves the object so its lowest point at rest is z = 0.
* :data:`DYNAMICS` gives passive joint dynamics per joint role, so doors stay
  where they are left and knobs do not spin freely.

Units: damping is N*m*s/rad (rotations) or N*s/m (slides); friction is N*m
(rotations) or N (slides); effort likewise N*m or N; velocity rad/s or m/s.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .blueprint import Blueprint, descendants
from .errors import ModelError
from .geometry import hull_arrays, triangle_cross
from .joints import Dof
from .rotation import axis_angle


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
    "default": Dynamics(damping=1.0, friction=0.2, effort=50.0, velocity=2.0),
}


def dynamics(role: str) -> Dynamics:
    return DYNAMICS.get(role, DYNAMICS["default"])


def rest_on_ground(bp: Blueprint) -> Blueprint:
    """A copy of ``bp`` translated (parts and joints) so its lowest point at rest sits at z = 0."""
    dz = -float(bp.bounds()[0, 2])
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
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n[length[:, 0] > 1e-15] / length[length[:, 0] > 1e-15]


def _separated(a: np.ndarray, a_normals: np.ndarray, d: float, b: np.ndarray, b_normals: np.ndarray) -> bool:
    """Whether a face plane of either hull separates the hull of points ``a`` grown by a cube of
    half-size ``d`` (:func:`_inflate`) from the hull of points ``b``: a sufficient test for
    "no overlap" (edge-edge separations are left to the exact test)."""
    n = np.vstack([a_normals, b_normals])
    pa, pb = a @ n.T, b @ n.T
    grow = d * np.abs(n).sum(1)
    return bool(np.any((pa.max(0) + grow < pb.min(0)) | (pa.min(0) - grow > pb.max(0))))


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
    for j in joints:
        child = by_name[j.child]
        if not j.movable or child.dummy or not child.pieces:
            continue
        parent = by_name[real_parent(child.name)]
        if not parent.pieces:
            continue
        offset = parent.origin - child.origin  # parent frame -> child frame (world-aligned at rest)
        parent_hulls = [c + offset for p in parent.pieces for c in p.convex]
        if not parent_hulls:
            continue
        parent_meshes = [vf for p in parent.pieces for vf in p.hulls()]
        normals: dict[int, np.ndarray] = {}  # face normals of the parent hulls met, as test directions
        box_lo = np.array([h.min(0) for h in parent_hulls])
        box_hi = np.array([h.max(0) for h in parent_hulls])
        pts = np.vstack([c for p in child.pieces for c in p.convex] or [np.zeros((1, 3))])
        gap = gap_size(np.ptp(pts, axis=0))
        cache: dict[int, manifold3d.Manifold] = {}
        pieces = list(child.pieces)
        for n, piece in enumerate(child.pieces):
            hulls = piece.hulls()
            eroded: dict[int, tuple] = {}
            for k, c in enumerate(piece.convex):
                lo, hi = c.min(0) - gap, c.max(0) + gap
                near = np.flatnonzero(np.all(hi > box_lo, axis=1) & np.all(box_hi > lo, axis=1))
                if not len(near):
                    continue
                child_n = _face_normals(*hulls[k])
                grown = None
                hit = False
                for i in near:
                    if i not in normals:
                        normals[i] = _face_normals(*parent_meshes[i])
                    if _separated(c, child_n, gap - 1e-6, parent_hulls[i], normals[i]):
                        continue  # a face plane separates them: no overlap, no exact test needed
                    if grown is None:
                        grown = manifold3d.Manifold.hull_points(_inflate(c, gap - 1e-6))
                    if i not in cache:
                        cache[i] = manifold3d.Manifold.hull_points(parent_hulls[i])
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


def _extreme_points(links) -> dict[str, np.ndarray]:
    """Per link, the vertices of the convex hull of all its collision hulls (in the link frame).

    The lowest point of a rigidly moved link is one of them, and there are far fewer of them
    than hull vertices.
    """
    out = {}
    for link in links:
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
    extreme = _extreme_points(links)
    origin = {link.name: np.asarray(link.origin, float) for link in links}
    out = []
    for j in joints:
        out.append(j)
        if not j.movable:
            continue
        moved = descendants(joints, j.child)
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
