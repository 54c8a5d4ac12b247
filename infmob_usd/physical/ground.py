"""The ground: the object rests on z = 0 (or its elevation), and no joint takes a part below it."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..blueprint import Blueprint, descendants
from ..errors import ModelError
from ..hulls import hull_arrays
from ..joints import Dof
from ..rotation import axis_angle
from .gates import carrying_gates, open_motion


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



GROUND_TOL = 5e-4
"""m; a part may dip this far below z = 0 at a joint state (validators allow 1 mm)."""


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


HALF_TURN = math.pi
"""rad: a turn of up to half a revolution from rest dips lowest at one of its ends or not at all in between
for a part hanging from it in practice; a longer one (a convertible laptop's 360-degree lid) passes states
below the ground that its limit's own does not show, so it is swept."""
SWEEP_STEP = math.radians(5.0)
"""rad: the step of that sweep (the bisection then finds the limit within it)."""


def _first_below(lowest, limit: float, kind: str) -> tuple[float, float] | None:
    """A clear value and the next one from rest towards ``limit`` whose state dips below the ground: rest and
    the limit itself, or for a turn longer than :data:`HALF_TURN` the first of its :data:`SWEEP_STEP` samples
    that does and the one before; None if none does."""
    if kind == "revolute" and abs(limit) > HALF_TURN:
        n = int(math.ceil(abs(limit) / SWEEP_STEP))
        for k in range(1, n + 1):
            if lowest(limit * k / n) < -GROUND_TOL:
                return limit * (k - 1) / n, limit * k / n
        return None
    return (0.0, limit) if lowest(limit) < -GROUND_TOL else None


def limit_to_ground(links, joints) -> list:
    """New joints whose limits keep every part above the ground at any single joint's limit.

    For each limited joint alone, the state at each limit is checked; if the moved
    subtree dips below ``-GROUND_TOL``, that limit is moved towards rest by
    bisection until it clears. A continuous joint that goes below the ground
    cannot be limited: that raises :class:`~infmob_usd.errors.ModelError` (the
    category must raise its base). A joint that ``requires_open`` parts carrying it (a flap
    on an oven door) is checked with them fully open, as the validators move it
    (:mod:`.gates`), and with them at rest, where nothing holds it in a simulator. The
    joints given are not changed; joints whose limits stand are returned as they are.
    """
    # only links that some joint moves are ever tested (the root's hull, often the largest, is not)
    moved_by = {j.name: descendants(joints, j.child) for j in joints if j.movable}
    extreme = _extreme_points(links, set().union(*moved_by.values()))
    origin = {link.name: np.asarray(link.origin, float) for link in links}
    followers: dict[str, list] = {}
    for f in joints:
        if f.movable and getattr(f, "mimic", None):
            followers.setdefault(f.mimic[0], []).append(f)
    carried, current = carrying_gates(joints), {}
    out = []
    for j in joints:
        out.append(j)
        current[j.name] = j
        if not j.movable:
            continue
        moved = moved_by[j.name]
        # one joint moves from rest, so its subtree moves rigidly: world points at rest, about the pivot
        pts = [extreme[n] + origin[n] for n in moved if n in extreme]
        if not pts:
            continue
        # a joint that requires open a part carrying it (a flap on an oven door) moves with that part open
        gates = carried.get(j.name)
        view = open_motion([current[g.name] for g in gates]) if gates else None
        lowest = _lowest(j, np.vstack(pts) - origin[j.child], origin[j.child], view)
        if j.type != "continuous" and j.name in followers:
            lowest = _coupled_lowest(j, followers[j.name], moved_by, extreme, origin, view)

        if j.type == "continuous":
            for a in (0.5 * np.pi, np.pi, -0.5 * np.pi):
                if lowest(a) < -GROUND_TOL:
                    raise ModelError(f"continuous joint {j.name} turns {j.child!r} through the ground;"
                                     " raise it or make it a limited revolute joint")
            continue
        for end in ("upper", "lower"):
            limit = getattr(j, end)
            if limit == 0:
                continue
            found = _first_below(lowest, limit, j.type)
            if found is None:
                continue
            good, bad = found
            for _ in range(30):
                mid = 0.5 * (good + bad)
                if lowest(mid) >= -GROUND_TOL:
                    good = mid
                else:
                    bad = mid
            if abs(good) < 1e-6:
                raise ModelError(f"joint {j.name} cannot move {j.child!r} at all without hitting the ground")
            out[-1] = current[j.name] = replace(out[-1], **{end: good})
    return out


def _lowest(j, rel: np.ndarray, pivot: np.ndarray, view=None):
    """The lowest world z of points ``rel`` (about ``j``'s child origin ``pivot``, at rest) with ``j`` at a
    value; ``view``: ``(R, t)``, the motion of the open gates that carry ``j`` (:func:`.gates.open_motion`),
    whose state is judged too (the lower of the two)."""
    pivot_z, axis = float(pivot[2]), np.asarray(j.axis, float)

    def lowest(value: float) -> float:
        if j.type == "prismatic":
            return pivot_z + float(rel[:, 2].min()) + value * float(axis[2])
        return pivot_z + float((rel @ axis_angle(axis, value)[2]).min())
    if view is None:
        return lowest
    rot, shift = view

    def lowest_either(value: float) -> float:
        # nothing in a simulator holds it while its gates are shut: clear of the ground with them shut too
        if j.type == "prismatic":
            p = rel + pivot + value * axis / np.linalg.norm(axis)
        else:
            p = rel @ axis_angle(axis, value).T + pivot
        return min(lowest(value), float((p @ rot[2]).min()) + float(shift[2]))
    return lowest_either


def _moved(j, value: float, pts: np.ndarray, origin: dict) -> np.ndarray:
    """World points ``pts`` moved by joint ``j`` to ``value`` from rest."""
    axis = np.asarray(j.axis, float)
    if j.type == "prismatic":
        return pts + value * axis / np.linalg.norm(axis)
    pivot = origin[j.child]
    return (pts - pivot) @ axis_angle(axis, value).T + pivot


def _coupled_lowest(j, followers: list, moved_by: dict, extreme: dict, origin: dict, view=None):
    """The lowest point as leader ``j`` moves to a value with its coupled ``followers`` (``q = ratio * value +
    offset``) moving with it, a follower below ``j`` carried along (a dual-axis hinge's second axis): the
    states a coupled pair takes together, not each joint's alone. ``view``: as :func:`_lowest`'s."""
    carried = set().union(*(moved_by[f.name] for f in followers if f.child in moved_by[j.name]))
    own = [extreme[n] + origin[n] for n in moved_by[j.name] if n in extreme and n not in carried]
    own = np.vstack(own) if own else np.zeros((0, 3))
    theirs = [(f, np.vstack([extreme[n] + origin[n] for n in moved_by[f.name] if n in extreme]
                            or [np.zeros((0, 3))])) for f in followers]

    def lowest(value: float) -> float:
        placed = [_moved(j, value, own, origin)]
        for f, pts in theirs:
            p = _moved(f, f.mimic[1] * value + f.mimic[2], pts, origin)
            placed.append(_moved(j, value, p, origin) if f.child in moved_by[j.name] else p)
        z = np.concatenate([p[:, 2] for p in placed])
        if view is not None:  # and the same points with the gates that carry them open
            z = np.concatenate([z, *(p @ view[0][2] + view[1][2] for p in placed)])
        return float(z.min()) if len(z) else np.inf

    return lowest
