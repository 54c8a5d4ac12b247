"""One joint's sweep: the largest part of its range over which the subtree it moves meets nothing
it may not touch (swept hulls against obstacles), and grows into its parent no more than at rest."""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from ..rotation import axis_angle, axis_angles
from .hulls import CLEARANCE, _boxes_meet, _hits, _Hull, _Obstacles, _separated

SWEEP_SAGITTA = 2.5e-4
"""m; a turn is sampled finely enough that its arcs bulge at most this far past the chords
between samples (the swept volume between two samples is the hull of the two poses)."""

PARENT_GROWTH = 5e-8
"""m^3; how much more a moving subtree may overlap its parent than at rest (validators: 1e-7)."""


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


def _free(moving: _Moving, values: np.ndarray, obstacles: _Obstacles, allowed: np.ndarray) -> bool:
    """Whether no allowed obstacle hull can be near the moving hulls at any of ``values``.

    Most sweeps meet nothing: a bound on the boxes of :func:`_sample_boxes` (centre and half
    extent of each hull's box moved to every sample, by BLAS) that is looser than them by far
    more than its rounding (:data:`_FREE_PAD`) shows first whether any pair can be near; if none
    can, the exact boxes would find none either, and the result is the same without them."""
    joint, pivot, axis = moving.joint, moving.pivot, moving.axis
    lo0, hi0 = moving.lo0, moving.hi0
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
    return not (_boxes_meet(free_lo[:, None], obstacles.hi[None], obstacles.lo[None], free_hi[:, None]) & allowed).any()


def _sample_boxes(moving: _Moving, mats: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """``(samples, hulls, 3)`` lower and upper corners of each moving hull's box at every sample
    (the posed corners of each hull's box at rest bound the hull)."""
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
    return np.minimum(lo[:, :, 0], lo[:, :, 1]), np.maximum(hi[:, :, 0], hi[:, :, 1])


def _pair_margins(moving: _Moving, obstacles: _Obstacles, hs: np.ndarray, os: np.ndarray,
                  near: np.ndarray) -> np.ndarray:
    """Per hull pair ``(hs[p], os[p])`` the margin it keeps: CLEARANCE if it starts that far apart,
    else 0 if it starts apart, else (it overlaps at rest: not this joint's doing) NaN, left out.

    Only pairs near in some interval (a column of ``near``) are worked out (the others are never
    tested); a pair whose boxes at rest are farther apart than the clearance (and a nanometre)
    on an axis cannot meet the obstacle grown by it, so the exact test is left out for it."""
    lo0, hi0 = moving.lo0, moving.hi0
    margin = np.full(len(hs), np.nan)
    gap = CLEARANCE + 1e-9
    apart = np.any((lo0[hs] - gap > obstacles.hi[os]) | (obstacles.lo[os] - gap > hi0[hs]), axis=1)
    for p in np.flatnonzero(near.any(axis=0)):
        h, o = hs[p], os[p]
        if apart[p] or not moving.hits_at_rest(h, CLEARANCE, obstacles, o):
            margin[p] = CLEARANCE
        elif not moving.hits_at_rest(h, 0.0, obstacles, o):
            margin[p] = 0.0
    return margin


class _Swept:
    """The swept hulls of the pairs that may meet: hull ``h`` moved by a motion (its world points
    and normals, kept per sample or bisection value), and the hull of two of its poses."""

    def __init__(self, moving: _Moving, mats: list[np.ndarray], obstacles: _Obstacles, hs, os, margin):
        self.world, self.normals, self.mats = moving.world, moving.normals, mats
        self.obstacles, self.hs, self.os, self.margin = obstacles, hs, os, margin
        self.moved: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}

    def at(self, h, m, key):
        if (h, key) not in self.moved:
            self.moved[h, key] = (self.world[h] @ m[:3, :3].T + m[:3, 3], self.normals[h] @ m[:3, :3].T)
        return self.moved[h, key]

    def hits(self, k: int, m1: np.ndarray, key1, pairs, first: bool) -> list[int]:
        """The pairs among ``pairs`` that meet while the joint moves from sample ``k`` to ``m1``
        (named ``key1``)."""
        m0, out = self.mats[k], []
        swept: dict[int, tuple[np.ndarray, np.ndarray]] = {}  # per moving hull: the swept hull's points, normals
        solids: dict = {}
        for p in pairs:
            h, o = self.hs[p], self.os[p]
            if h not in swept:
                (w0, n0), (w1, n1) = self.at(h, m0, k), self.at(h, m1, key1)
                swept[h] = (np.vstack([w0, w1]), np.vstack([n0, n1]))
            pts, nrm = swept[h]
            if _hits(pts, nrm, self.margin[p], self.obstacles, o, solids, h):
                out.append(p)
                if first:
                    break
        return out


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
    if _free(moving, values, obstacles, allowed):
        return float(limit), ""
    mats = _motions(joint.type, pivot, axis, values)
    lo, hi = _sample_boxes(moving, mats)
    # hull pairs that may meet somewhere in the range, then in which sample intervals
    lo_all, hi_all = lo.min(0) - CLEARANCE, hi.max(0) + CLEARANCE
    hs, os = np.nonzero(_boxes_meet(lo_all[:, None], obstacles.hi[None], obstacles.lo[None], hi_all[:, None]) & allowed)
    if not len(hs):
        return float(limit), ""
    ilo = np.minimum(lo[:-1], lo[1:])[:, hs] - CLEARANCE
    ihi = np.maximum(hi[:-1], hi[1:])[:, hs] + CLEARANCE
    near = _boxes_meet(ilo, obstacles.hi[os], obstacles.lo[os], ihi)  # (intervals, pairs)
    margin = _pair_margins(moving, obstacles, hs, os, near)
    near &= ~np.isnan(margin)
    swept = _Swept(moving, mats, obstacles, hs, os, margin)
    for k in np.flatnonzero(near.any(axis=1)):
        pairs = swept.hits(k, mats[k + 1], k + 1, np.flatnonzero(near[k]), False)
        if not pairs:
            continue
        # within the interval only the pairs that meet over all of it can meet over part of it
        # (up to the sagitta)
        good, bad = float(values[k]), float(values[k + 1])
        for _ in range(14):
            mid = 0.5 * (good + bad)
            hit = swept.hits(k, _motion(joint.type, pivot, axis, mid), ("mid", mid), pairs, True)
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


