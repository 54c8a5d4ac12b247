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
from .joints import Dof


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
    """Translate every part and joint so the lowest point at rest sits at z = 0."""
    dz = -float(bp.bounds()[0, 2])
    if abs(dz) < 1e-12:
        return bp
    offset = np.array([0.0, 0.0, dz])
    for part in bp.parts.values():
        part.pieces = [p.translated(offset) for p in part.pieces]
    bp.joints = [
        replace(j, dofs=tuple(
            Dof(d.type, tuple(np.asarray(d.origin) + offset), d.axis, d.lower, d.upper) for d in j.dofs
        ))
        for j in bp.joints
    ]
    return bp


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


def ensure_gaps(links, joints) -> int:
    """Erode collision pieces of moving parts that come closer than :func:`gap_size` to their parent.

    Only collision shapes change (visual meshes stay as designed). Each offending
    convex piece of the child shrinks towards its centre by the gap on each axis
    (never by more than a quarter of its own extent there). Compound chains are
    checked child against the chain's real parent. Returns the number of pieces eroded.
    """
    import manifold3d

    by_name = {link.name: link for link in links}
    into = {j.child: j for j in joints}

    def real_parent(name):
        p = into[name].parent
        while by_name[p].dummy:
            p = into[p].parent
        return p

    eroded = 0
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
        boxes = [(h.min(0), h.max(0)) for h in parent_hulls]
        pts = np.vstack([c for p in child.pieces for c in p.convex] or [np.zeros((1, 3))])
        gap = gap_size(np.ptp(pts, axis=0))
        cache: dict[int, manifold3d.Manifold] = {}
        for piece in child.pieces:
            for k, c in enumerate(piece.convex):
                lo, hi = c.min(0) - gap, c.max(0) + gap
                near = [i for i, (blo, bhi) in enumerate(boxes) if np.all(hi > blo) and np.all(bhi > lo)]
                if not near:
                    continue
                grown = manifold3d.Manifold.hull_points(_inflate(c, gap - 1e-6))
                hit = False
                for i in near:
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
                    piece.convex[k] = centre + (c - centre) * scale
                    piece._hulls = None
                    eroded += 1
    return eroded


def _lowest(obj, q: dict[str, float], names=None) -> float:
    """Lowest z of the collision pieces of ``names`` (default: every link) with joints at ``q``."""
    poses = obj.poses(q)
    z = np.inf
    for link in obj.links:
        if names is not None and link.name not in names:
            continue
        pts = [v for p in link.pieces for v, _ in p.hulls()]
        if pts:
            pose = poses[link.name]
            z = min(z, float((np.vstack(pts) @ pose[2, :3] + pose[2, 3]).min()))
    return z


def limit_to_ground(obj) -> list[str]:
    """Reduce joint limits so that no part goes below the ground at any single joint's limit.

    For each limited joint alone, the state at each limit is checked; if the moved
    subtree dips below ``-GROUND_TOL``, that limit is moved towards rest by
    bisection until it clears. A continuous joint that goes below the ground
    cannot be limited: that raises :class:`~infmob_usd.errors.ModelError` (the
    category must raise its base). Returns the names of the joints changed.
    """
    from .errors import ModelError

    changed = []
    for j in obj.joints:
        if not j.movable:
            continue
        moved = descendants(obj.joints, j.child)
        if j.type == "continuous":
            for a in (0.5 * np.pi, np.pi, -0.5 * np.pi):
                if _lowest(obj, {j.name: a}, moved) < -GROUND_TOL:
                    raise ModelError(f"continuous joint {j.name} turns {j.child!r} through the ground;"
                                     " raise it or make it a limited revolute joint")
            continue
        for end in ("upper", "lower"):
            limit = getattr(j, end)
            if limit == 0 or _lowest(obj, {j.name: limit}, moved) >= -GROUND_TOL:
                continue
            good, bad = 0.0, limit
            for _ in range(30):
                mid = 0.5 * (good + bad)
                if _lowest(obj, {j.name: mid}, moved) >= -GROUND_TOL:
                    good = mid
                else:
                    bad = mid
            if abs(good) < 1e-6:
                raise ModelError(f"joint {j.name} cannot move {j.child!r} at all without hitting the ground")
            setattr(j, end, good)
            changed.append(j.name)
    return changed
