"""Gaps: a moving part's collision hulls keep a small clearance from its parent's at rest."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .hulls import _boxes_meet, _face_normals, _inflate, _separated


def gap_size(extent: np.ndarray) -> float:
    """The clearance a moving part keeps from its parent: 2% of its smallest extent, >= 1 mm."""
    return max(0.001, 0.02 * float(np.min(extent)))


def _parent_boxes(parent) -> tuple | None:
    """A parent link's convex pieces and their boxes (link frame), or None if it has none."""
    convex = [c for p in parent.pieces for c in p.convex]
    if not convex:
        return None
    stacked = np.concatenate(convex)
    starts = np.cumsum([0] + [len(c) for c in convex[:-1]])
    return convex, np.minimum.reduceat(stacked, starts, axis=0), np.maximum.reduceat(stacked, starts, axis=0)


class _Parent:
    """A parent link's hulls seen from one child's frame (world-aligned at rest, so a translation):
    the convex pieces and their boxes moved there, the hull meshes and the face normals of those
    met (link frame, shared by the parent's children), and the exact solids built so far."""

    def __init__(self, boxes: tuple, meshes: tuple, offset: np.ndarray):
        self.convex, lo, hi = boxes
        self.offset = offset
        self.meshes, self.normals = meshes
        # the box of a translated point set is the translated box, bit for bit (rounding is monotone)
        self.lo, self.hi = lo + offset, hi + offset
        self.moved: dict[int, np.ndarray] = {}
        self.solids: dict = {}

    def hull(self, i: int) -> np.ndarray:
        if i not in self.moved:
            self.moved[i] = self.convex[i] + self.offset
        return self.moved[i]

    def normal(self, i: int) -> np.ndarray:
        if i not in self.normals:
            self.normals[i] = _face_normals(*self.meshes[i])
        return self.normals[i]

    def solid(self, i: int):
        import manifold3d

        if i not in self.solids:
            self.solids[i] = manifold3d.Manifold.hull_points(self.hull(i))
        return self.solids[i]


def _too_close(c: np.ndarray, child_n: np.ndarray, gap: float, parent: _Parent, near: np.ndarray) -> bool:
    """Whether convex piece ``c`` (face normals ``child_n``) grown by the gap overlaps any of the
    parent hulls ``near``."""
    import manifold3d

    grown = None
    for i in near:
        if _separated(c, child_n, gap - 1e-6, parent.hull(i), parent.normal(i)):
            continue  # a face plane separates them: no overlap, no exact test needed
        if grown is None:
            grown = manifold3d.Manifold.hull_points(_inflate(c, gap - 1e-6))
        if (grown ^ parent.solid(i)).volume() > 1e-12:
            return True
    return False


def _eroded(c: np.ndarray, hull: tuple, gap: float) -> tuple:
    """Convex piece ``c`` and its hull mesh shrunk towards their centre by the gap on each axis
    (never by more than a quarter of the extent there)."""
    centre = (c.min(0) + c.max(0)) / 2
    half = (c.max(0) - c.min(0)) / 2
    shrink = np.minimum(gap, 0.25 * 2 * half)
    scale = np.where(half > 0, (half - shrink) / np.where(half > 0, half, 1), 1.0)
    hull_v, hull_f = hull
    # the same axis scaling of the hull is the hull of the scaled points
    return centre + (c - centre) * scale, centre + (hull_v - centre) * scale, hull_f


def _gapped_pieces(child, parent: _Parent) -> list | None:
    """The child's pieces with each convex piece too close to the parent eroded, or None if none is."""
    child_convex = [c for p in child.pieces for c in p.convex]
    pts = np.vstack(child_convex or [np.zeros((1, 3))])
    gap = gap_size(np.ptp(pts, axis=0))
    pieces = list(child.pieces)
    if child_convex:  # every child hull's box grown by the gap against every parent hull's box at once
        starts = np.cumsum([0] + [len(c) for c in child_convex[:-1]])
        lo_all = np.minimum.reduceat(pts, starts, axis=0) - gap
        hi_all = np.maximum.reduceat(pts, starts, axis=0) + gap
        near_all = _boxes_meet(parent.lo[None], hi_all[:, None], lo_all[:, None], parent.hi[None])
        near_any = near_all.any(axis=1).tolist()
    changed = False
    g = -1  # index of the child convex piece among all of the link's
    for n, piece in enumerate(child.pieces):
        hulls = piece.hulls()
        eroded: dict[int, tuple] = {}
        for k, c in enumerate(piece.convex):
            g += 1
            if near_any[g] and _too_close(c, _face_normals(*hulls[k]), gap, parent, np.flatnonzero(near_all[g])):
                eroded[k] = _eroded(c, hulls[k], gap)
        if eroded:
            pieces[n] = piece.with_convex(eroded)
            changed = True
    return pieces if changed else None


def ensure_gaps(links, joints) -> list:
    """New links whose moving parts' collision pieces keep :func:`gap_size` from their parent.

    Only collision shapes change (visual meshes stay as designed). Each offending
    convex piece of the child shrinks towards its centre by the gap on each axis
    (never by more than a quarter of its own extent there). Compound chains are
    checked child against the chain's real parent. The links given are not changed;
    links with nothing eroded are returned as they are.
    """
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
        if parent.name not in boxes:
            boxes[parent.name] = _parent_boxes(parent)
        if boxes[parent.name] is None:
            continue
        if parent.name not in meshes:  # shared by the parent's children
            meshes[parent.name] = ([vf for p in parent.pieces for vf in p.hulls()], {})
        # parent frame -> child frame (world-aligned at rest)
        pieces = _gapped_pieces(child, _Parent(boxes[parent.name], meshes[parent.name], parent.origin - child.origin))
        if pieces is not None:
            new_pieces[child.name] = pieces
    return [replace(link, pieces=new_pieces[link.name]) if link.name in new_pieces else link for link in links]


MIN_HULL_WIDTH = 1.5e-3
"""m; the thinnest a collision hull may be. PhysX merges hull faces closer than its cooking plane
tolerance (``PxCookingParams::planeTolerance``, 0.0007 m at unit scale): a thinner hull (a 0.3 mm sheet
of a pasta insert's wall) cooks into a degenerate one that reports centimetres of penetration against
a shape it does not touch, and the part is thrown off its seat at rest. Twice the tolerance, with margin."""


def _thickened(c: np.ndarray, hull: tuple) -> tuple | None:
    """Convex piece ``c`` and its hull mesh stretched about their mid-plane across their thinnest
    direction (a face normal) to :data:`MIN_HULL_WIDTH`, again while another direction is thinner (a
    curved sheet); None if already as wide."""
    hull_v, hull_f = hull
    changed = False
    for _ in range(4):
        normals = _face_normals(hull_v, hull_f)
        if not len(normals):
            break
        proj = c @ normals.T
        widths = proj.max(0) - proj.min(0)
        k = int(np.argmin(widths))
        width = float(widths[k])
        if width >= MIN_HULL_WIDTH - 1e-12 or width <= 1e-9:  # a flat piece is refused elsewhere
            break
        n = normals[k]
        mid = (proj[:, k].max() + proj[:, k].min()) / 2
        # an affine stretch keeps a hull's faces and their outward order
        c, hull_v = (p + np.outer((p @ n) - mid, n) * (MIN_HULL_WIDTH / width - 1.0) for p in (c, hull_v))
        changed = True
    return (c, hull_v, hull_f) if changed else None


def thicken_hulls(links) -> list:
    """New links whose collision hulls are each at least :data:`MIN_HULL_WIDTH` thick (visual meshes
    unchanged); links with nothing thickened are returned as they are."""
    out = []
    for link in links:
        pieces, changed = list(link.pieces), False
        for n, piece in enumerate(link.pieces):
            grown = {k: t for k, (c, h) in enumerate(zip(piece.convex, piece.hulls(), strict=True))
                     if (t := _thickened(c, h)) is not None}
            if grown:
                pieces[n] = piece.with_convex(grown)
                changed = True
        out.append(replace(link, pieces=pieces) if changed else link)
    return out
