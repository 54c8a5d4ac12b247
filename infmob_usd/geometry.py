"""The geometry kernel: pieces of parts, built on trimesh and manifold3d.

A :class:`Piece` is one triangle mesh in world coordinates (metres, Z up) with the
name of the material slot it is painted with and, where construction tells them,
its exact convex collision pieces (a panel is a box, a knob a cylinder). UVs are
derived by box projection at one texel density for every piece
(:data:`UV_TILE` metres per texture repeat), so textures have the same scale on
every part of an object; normals are smooth below :data:`CREASE_DEG` and split
above, per face corner.

Every builder takes plain numbers or ``(3,)`` arrays and returns a ``Piece``.
"""

from __future__ import annotations

import copy
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import manifold3d
import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from .errors import GeometryError

UV_TILE = 0.5
"""Metres of surface covered by one repeat of a texture."""

CREASE_DEG = 35.0
"""Edges sharper than this get split normals."""


def cross_rows(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross product of ``(n, 3)`` arrays: ``np.cross`` without its per-call overhead
    (which dominates for the small arrays of hulls)."""
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


def triangle_cross(tri: np.ndarray) -> np.ndarray:
    """``(m, 3)`` cross products of the edges of ``(m, 3, 3)`` triangles (twice their area vectors)."""
    return cross_rows(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])


@dataclass
class Piece:
    """One mesh of a part.

    Attributes
    ----------
    vertices : (n, 3) float
        Positions in metres.
    faces : (m, 3) int
        Counter-clockwise triangles (outward normals).
    material : str
        Material slot name, resolved per object by the materials room.
    convex : list of (k, 3) float
        Point sets whose convex hulls are the collision shapes of this piece.
        Empty means the piece does not collide (decoration).
    name : str
        Optional role, e.g. ``"handle"``; writers keep it in visual names.
    sheet : float
        Wall thickness in metres of a part made of sheet (a steel casing, a
        thin tube) that is modelled solid: mass then counts area x sheet, not
        the solid volume. 0 (default) means solid.
    """

    vertices: np.ndarray
    faces: np.ndarray
    material: str
    convex: list[np.ndarray] = field(default_factory=list)
    name: str = ""
    sheet: float = 0.0

    def __post_init__(self) -> None:
        self.vertices = np.ascontiguousarray(self.vertices, dtype=np.float64)
        self.faces = np.ascontiguousarray(self.faces, dtype=np.int64)
        self.convex = [np.ascontiguousarray(c, dtype=np.float64) for c in self.convex]
        self.check()

    def check(self) -> None:
        """Raise :class:`GeometryError` if the mesh is corrupt."""
        v, f = self.vertices, self.faces
        what = f"piece {self.name or self.material!r}"
        if v.ndim != 2 or v.shape[1] != 3 or len(v) < 3:
            raise GeometryError(f"{what}: vertices must be (n>=3, 3), got {v.shape}")
        if f.ndim != 2 or f.shape[1] != 3 or len(f) < 1:
            raise GeometryError(f"{what}: faces must be (m>=1, 3), got {f.shape}")
        if not np.isfinite(v).all():
            raise GeometryError(f"{what}: vertices contain NaN or inf; fix the part's dimensions")
        if f.min() < 0 or f.max() >= len(v):
            raise GeometryError(f"{what}: a face indexes a missing vertex (corrupt mesh)")
        for c in self.convex:
            if c.ndim != 2 or c.shape[1] != 3 or len(c) < 4 or not np.isfinite(c).all():
                raise GeometryError(f"{what}: a convex collision piece needs >= 4 finite points")

    # -- transforms ---------------------------------------------------------
    def transformed(self, matrix: np.ndarray) -> Piece:
        """A copy moved by a ``(4, 4)`` transform (rigid, or a stretch that keeps orientation)."""
        r, t = matrix[:3, :3], matrix[:3, 3]
        moved = Piece(
            self.vertices @ r.T + t,
            self.faces.copy(),
            self.material,
            [c @ r.T + t for c in self.convex],
            self.name,
            self.sheet,
        )
        known = getattr(self, "_hull_cache", None)
        hints = getattr(self, "_hull_hints", None)
        rigid = np.allclose(r @ r.T, np.eye(3), atol=1e-9)
        if hints and np.linalg.det(r) > 0:  # hull topologies survive any orientation-keeping map
            bands: dict[int, dict] = {}
            moved._hull_hints = {}
            for k, (src, band, angle) in hints.items():
                if k < len(self.convex) and self.convex[k] is src:
                    first = band["first"]
                    same = first < len(self.convex) and self.convex[first] is band["src"]
                    new_band = bands.setdefault(id(band), {
                        "src": moved.convex[first] if same else band["src"] @ r.T + t,
                        "topology": band["topology"], "first": first,
                        # a stretch keeps the hull topology but the wedges stop being turned copies
                        "point": r @ band["point"] + t,
                        "axis": r @ band["axis"] if rigid and band["axis"] is not None else None})
                    moved._hull_hints[k] = (moved.convex[k], new_band, angle)
        if known and np.linalg.det(r) > 0:  # so does an orientation-keeping map: faces stay outward
            moved._hull_cache = [
                None if e is None or not np.array_equal(e[0], c) else (mc, (e[1][0] @ r.T + t, e[1][1]))
                for e, c, mc in zip(known, self.convex, moved.convex)
            ]
        return moved

    def with_material(self, material: str) -> Piece:
        """The same piece (hulls kept) in another material slot."""
        out = copy.copy(self)
        out.material = material
        return out

    def with_sheet(self, sheet: float) -> Piece:
        """The same piece, its mass counted as sheet of thickness ``sheet`` (0: solid)."""
        out = copy.copy(self)
        out.sheet = float(sheet)
        return out

    def translated(self, offset: Sequence[float]) -> Piece:
        m = np.eye(4)
        m[:3, 3] = offset
        return self.transformed(m)

    @property
    def bounds(self) -> np.ndarray:
        """``(2, 3)`` min and max corner."""
        return np.array([self.vertices.min(0), self.vertices.max(0)])

    # -- derived surface attributes ------------------------------------------
    def face_normals(self) -> np.ndarray:
        """``(m, 3)`` unit face normals."""
        tri = self.vertices[self.faces]
        n = triangle_cross(tri)
        length = np.linalg.norm(n, axis=1, keepdims=True)
        return n / np.where(length > 0, length, 1.0)

    def corner_normals(self) -> np.ndarray:
        """``(m, 3, 3)`` per face-corner normals (computed once per piece).

        Each corner averages (area-weighted) the normals of the faces around its
        vertex that lie within :data:`CREASE_DEG` of its own face, so a cylinder's
        side is smooth and its caps stay flat (:func:`corner_attributes`).
        """
        self._corner_attributes()
        return self._corner_normals

    def corner_uvs(self) -> np.ndarray:
        """``(m, 3, 2)`` box-projected UVs, :data:`UV_TILE` metres per repeat (computed once)."""
        self._corner_attributes()
        return self._corner_uvs

    def _corner_attributes(self) -> None:
        if getattr(self, "_corner_normals", None) is None:
            n, uv = corner_attributes(self.vertices, self.faces)
            self._corner_normals, self._corner_uvs = n.reshape(-1, 3, 3), uv.reshape(-1, 3, 2)

    def hulls(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Collision meshes: ``(vertices (k, 3), faces (f, 3))`` per convex piece, outward.

        Computed once per point set (Qhull, or known from construction: :meth:`set_hull`) and
        recomputed if a point set is replaced; point sets are made read-only once their hull
        exists, so an edit in place fails loudly instead of leaving a stale hull.  A hull is
        kept under :data:`MAX_HULL_VERTICES` (PhysX keeps at most 255) by farthest-point
        sampling of its vertices, which keeps its extremes.
        """
        memo = getattr(self, "_hulls_memo", None)
        if memo is not None and len(memo[0]) == len(self.convex) and all(
                a is b for a, b in zip(memo[0], self.convex)):
            return memo[1]  # the same point sets (frozen below, so not edited in place)
        cache = getattr(self, "_hull_cache", None) or []
        cache = cache + [None] * (len(self.convex) - len(cache))
        hints = getattr(self, "_hull_hints", None) or {}
        out = []
        for k, c in enumerate(self.convex):
            entry = cache[k]
            # a hull is reused only while its point set is unchanged (pieces are edited in place)
            if entry is None or entry[0].shape != c.shape or not np.array_equal(entry[0], c):
                hint = hints.get(k)
                if hint is not None and hint[0] is c:  # still the constructed point set
                    band = hint[1]
                    if band["topology"] is None:
                        band["topology"] = hull_indices(band["src"])
                    used, f = band["topology"]
                    entry = cache[k] = (c.copy(), (c[used], f))
                    out.append(entry[1])
                    continue
                v, f = hull_arrays(c)
                if len(v) > MAX_HULL_VERTICES:
                    v, f = hull_arrays(_farthest_points(v, MAX_HULL_VERTICES - 55))
                entry = cache[k] = (c.copy(), (v, np.asarray(f, np.int64)))
            out.append(entry[1])
        self._hull_cache = cache[:len(self.convex)]
        for c in self.convex:  # a point set with a hull is frozen: replace it, never edit it in place
            c.flags.writeable = False
        self._hulls_memo = (list(self.convex), out)
        return out

    def with_collision_of(self, other: Piece) -> Piece:
        """This piece's mesh with ``other``'s collision pieces (and their known hulls): a fine
        visual surface over a coarse collision one."""
        out = Piece(self.vertices, self.faces, self.material, other.convex, self.name, self.sheet)
        out._hull_cache = getattr(other, "_hull_cache", None)
        out._hull_hints = getattr(other, "_hull_hints", None)
        return out

    def with_wedges(self, outer, inner, sectors: int, phase: float = 0.0) -> Piece:
        """This piece's mesh with flat-faced wedge collisions of a wall of revolution about +Z.

        One convex piece of 8 corners per band and sector (:func:`wedge_points`), so every face
        is exactly planar.  The wedges of a band are turned copies of its first (writers share
        their mesh, :meth:`hull_instances`).
        """
        pts = wedge_points(outer, inner, sectors, phase)
        out = Piece(self.vertices, self.faces, self.material, list(pts.reshape(-1, 8, 3)), self.name, self.sheet)
        turns = 2 * np.pi * np.arange(sectors) / sectors
        _mark_turned_copies(out, sectors, turns, np.zeros(3))
        return out

    def hull_instances(self) -> list[tuple[int, np.ndarray, np.ndarray] | None]:
        """Per hull of :meth:`hulls`: ``(j, R, t)`` when hull ``k`` is hull ``j`` of this piece moved
        rigidly (vertices ``v_j @ R.T + t``, same faces), else ``None``.

        Shell wedges of one band are turned copies of the band's first wedge; writers can
        then store one mesh and place the copies (a URDF ``<collision><origin rpy>``).
        """
        hulls = self.hulls()
        hints = getattr(self, "_hull_hints", None) or {}
        out: list = [None] * len(hulls)
        for k, c in enumerate(self.convex):
            hint = hints.get(k)
            if hint is None or hint[0] is not c:
                continue
            band, angle = hint[1], hint[2]
            j = band["first"]
            if j == k or band["axis"] is None or self.convex[j] is not band["src"]:
                continue  # the prototype itself, a stretched band, or a replaced (eroded) prototype
            rot = axis_angle(band["axis"], angle)
            t = band["point"] - rot @ band["point"]
            scale = float(np.ptp(hulls[k][0], axis=0).max())
            if np.abs(hulls[j][0] @ rot.T + t - hulls[k][0]).max() > 1e-9 * max(scale, 1e-3):
                continue  # edited in place since construction: not a copy any more
            out[k] = (j, rot, t)
        return out

    def set_hull(self, k: int, vertices: np.ndarray, faces: np.ndarray) -> None:
        """Declare the hull of ``convex[k]`` known from construction (outward ``faces`` over
        ``vertices``, a subset of the points): :meth:`hulls` then skips Qhull for it."""
        cache = getattr(self, "_hull_cache", None) or []
        cache = cache + [None] * (len(self.convex) - len(cache))
        cache[k] = (self.convex[k].copy(), (np.asarray(vertices, float), np.asarray(faces, np.int64)))
        self._hull_cache = cache

    def volume(self) -> float:
        """Solid volume in m^3: the mesh's if it is closed, else its convex pieces' (the solids
        its mass comes from, :func:`infmob_usd.mass.solids`)."""
        from .mass import solids

        return float(sum(abs(s[0]) for s in solids(self)))


# ---------------------------------------------------------------------------
# vectorised surface attributes

_COS_CREASE = math.cos(math.radians(CREASE_DEG))
# faces all within half the crease angle of one direction are pairwise within it (a hair
# tighter, so rounding never lets a creased vertex through)
_COS_HALF = math.cos(math.radians(CREASE_DEG / 2 - 0.01))


def _norm(x: np.ndarray) -> np.ndarray:
    """Row lengths of ``(n, 3)`` ``x``, bit for bit ``np.linalg.norm(x, axis=1)``, faster."""
    return np.sqrt(x[:, 0] * x[:, 0] + x[:, 1] * x[:, 1] + x[:, 2] * x[:, 2])


def corner_attributes(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per face-corner normals ``(3m, 3)`` and UVs ``(3m, 2)`` of a mesh.

    Each corner averages (area-weighted) the normals of the faces around its vertex that
    lie within :data:`CREASE_DEG` of its own face; UVs are box-projected, :data:`UV_TILE`
    metres per repeat.  A mesh made of several pieces (which share no vertices) gives each
    piece's own values, so the writers call it once per object.  Fast on large meshes: a
    vertex whose faces all lie within ``CREASE_DEG / 2`` of their area-weighted mean keeps
    every neighbour, so its corners take that plain area-weighted sum
    (``np.bincount`` adds in corner order, as the pairwise ``np.add.at`` does), normalised
    once per vertex; only the corners of crease vertices are compared pairwise, batched
    by valence.
    """
    tri = vertices[faces]
    cross = triangle_cross(tri)
    length = _norm(cross)[:, None]
    fn = cross / np.where(length > 0, length, 1.0)  # unit face normals
    weighted = fn * (0.5 * length)  # area-weighted
    vert = faces.ravel()  # vertex of each corner; corner c belongs to face c // 3
    nv = len(vertices)
    total = np.stack([np.bincount(vert, np.repeat(weighted[:, d], 3), nv) for d in range(3)], 1)
    tlen = _norm(total)[:, None]
    vn = total / np.maximum(tlen, 1e-15)  # the normal of a corner keeping every face of its vertex
    # a vertex is a crease unless all its faces are within CREASE_DEG / 2 of vn (then they
    # are pairwise within CREASE_DEG); a vertex without area (vn ~ 0) is a crease too
    around = vn[faces]  # (m, 3, 3): per corner, the normal of its vertex
    dots = (fn[:, None, 0] * around[..., 0] + fn[:, None, 1] * around[..., 1]
            + fn[:, None, 2] * around[..., 2]).ravel()
    crease = np.zeros(nv, bool)
    crease[vert[dots < _COS_HALF]] = True
    crease[tlen[:, 0] <= 1e-15] = True  # no area around the vertex: face normals, pairwise
    normals = around.reshape(-1, 3)
    creased = np.flatnonzero(crease[vert])
    if len(creased):
        cv = vert[creased]
        order = creased[np.argsort(cv, kind="stable")]
        counts = np.bincount(cv, minlength=nv)
        start = np.cumsum(counts) - counts
        for k in np.unique(counts[counts > 0]):
            vs = np.flatnonzero(counts == k)
            c = order[start[vs][:, None] + np.arange(k)].ravel()  # corners of each vertex, ascending
            n = fn[c // 3].reshape(len(vs), k, 3)
            x, y, z = n[..., 0], n[..., 1], n[..., 2]
            keep = (x[:, :, None] * x[:, None] + y[:, :, None] * y[:, None] + z[:, :, None] * z[:, None]
                    >= _COS_CREASE)
            acc = (keep.astype(float) @ weighted[c // 3].reshape(len(vs), k, 3)).reshape(-1, 3)
            alen = _norm(acc)[:, None]
            normals[c] = np.where(alen > 1e-15, acc / np.maximum(alen, 1e-15), fn[c // 3])
    # box-projected UVs: (y, z) on X-facing faces, (x, z) on Y-facing, (x, y) on Z-facing
    axis = np.abs(fn).argmax(1)[:, None]
    uvs = np.stack([np.where(axis == 0, tri[..., 1], tri[..., 0]),
                    np.where(axis == 2, tri[..., 1], tri[..., 2])], -1) / UV_TILE
    return normals, uvs.reshape(-1, 2)


# ---------------------------------------------------------------------------
# helpers


def _quads(*quads) -> list[tuple[int, int, int]]:
    return [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def _fan(*ring) -> list[tuple[int, int, int]]:
    return [(ring[0], ring[i], ring[i + 1]) for i in range(1, len(ring) - 1)]


# Hull faces of the point layouts the primitives produce, tried before Qhull and kept only
# when every point lies inside every face plane (so a wrong guess costs a check, never a
# wrong hull).  8: the corners of a box in _box_arrays order (index bits x, y, z).
# 16: a wedge of a shell band, 4 angles x (outer bottom, outer top, inner bottom, inner top):
# the inner points between the two end angles lie inside the hull.
_HULL_TEMPLATES = {
    8: np.array(_quads((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3))),
    16: np.array(_quads((0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (8, 12, 15, 11), (0, 4, 12, 8), (3, 11, 15, 7))
                 + _fan(0, 1, 2, 3, 11, 8) + _fan(4, 5, 6, 7, 15, 12)),
}


def _template_hull(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """``(used point indices, faces over them)`` from a known layout, or None."""
    faces = _HULL_TEMPLATES.get(len(pts))
    if faces is None:
        return None
    tri = pts[faces]
    normal = triangle_cross(tri)
    length = np.linalg.norm(normal, axis=1)
    scale = float(np.ptp(pts, axis=0).max())
    if scale <= 0 or length.min() <= 1e-12 * scale * scale:
        return None
    normal /= length[:, None]
    centre = pts.mean(0)
    flip = np.einsum("ij,ij->i", normal, tri[:, 0] - centre) < 0
    normal[flip] *= -1
    height = (pts @ normal.T) - np.einsum("ij,ij->i", normal, tri[:, 0])  # (points, faces)
    if height.max() > 1e-9 * scale:
        return None
    faces = faces.copy()
    faces[flip] = faces[flip][:, ::-1]
    return _compact(len(pts), faces)


def _compact(n: int, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    used = np.unique(faces)
    remap = np.full(n, -1)
    remap[used] = np.arange(len(used))
    return used, remap[faces]


def hull_indices(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(indices of the points on the hull, outward faces indexing that subset)``.

    The layouts of boxes and shell wedges are checked against their known hull first;
    anything else goes to Qhull (scipy) directly, oriented against the centroid: ~20x
    faster than the general path through ``trimesh.convex``.
    """
    pts = np.asarray(points, float)
    known = _template_hull(pts)
    if known is not None:
        return known
    try:
        hull = ConvexHull(pts)
    except QhullError:
        hull = ConvexHull(pts, qhull_options="QJ")  # degenerate (flat) input: joggle
    used, faces = _compact(len(pts), hull.simplices)
    return used, _outward(pts[used], faces)


def hull_arrays(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of the convex hull of a point set, faces outward (:func:`hull_indices`)."""
    pts = np.asarray(points, float)
    used, faces = hull_indices(pts)
    return pts[used], faces


def convex_hull(points: np.ndarray) -> trimesh.Trimesh:
    """The convex hull of a point set as a watertight trimesh with outward faces."""
    return trimesh.Trimesh(*hull_arrays(points), process=False)


MAX_HULL_VERTICES = 255
"""PhysX builds convex meshes of at most 255 vertices."""


def _farthest_points(points: np.ndarray, n: int) -> np.ndarray:
    """``n`` of ``points`` spread out by farthest-point sampling (deterministic: starts at index 0)."""
    chosen = [0]
    d = np.linalg.norm(points - points[0], axis=1)
    for _ in range(n - 1):
        k = int(np.argmax(d))
        chosen.append(k)
        d = np.minimum(d, np.linalg.norm(points - points[k], axis=1))
    return points[chosen]


def from_trimesh(mesh: trimesh.Trimesh, material: str, convex=None, name: str = "") -> Piece:
    """Wrap a trimesh; ``convex=None`` means "the piece is convex: use its hull"."""
    if convex is None:
        convex = [np.asarray(mesh.vertices)]
    return Piece(np.asarray(mesh.vertices), np.asarray(mesh.faces), material, convex, name)


def _to_manifold(mesh: trimesh.Trimesh) -> manifold3d.Manifold:
    m = manifold3d.Manifold(
        manifold3d.Mesh(
            vert_properties=np.asarray(mesh.vertices, np.float32),
            tri_verts=np.asarray(mesh.faces, np.uint32),
        )
    )
    if m.status() != manifold3d.Error.NoError:
        raise GeometryError(f"mesh is not a closed manifold ({m.status()}); cannot do booleans")
    return m


def _from_manifold(m: manifold3d.Manifold) -> trimesh.Trimesh:
    out = m.to_mesh()
    return trimesh.Trimesh(np.asarray(out.vert_properties[:, :3], float), np.asarray(out.tri_verts), process=False)


def subtract(a: trimesh.Trimesh, cutters: Sequence[trimesh.Trimesh]) -> trimesh.Trimesh:
    """Boolean difference ``a - union(cutters)`` through manifold3d."""
    m = _to_manifold(a)
    for c in cutters:
        m = m - _to_manifold(c)
    return _from_manifold(m)


def _axis_index(axis: str | int) -> int:
    if isinstance(axis, str):
        return "xyz".index(axis.lower())
    return int(axis)


def axis_angle(axis: Sequence[float], angle: float) -> np.ndarray:
    """Rodrigues: the ``(3, 3)`` rotation by ``angle`` radians about the unit ``axis``."""
    a = np.asarray(axis, float)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def rotation_between(a: Sequence[float], b: Sequence[float]) -> np.ndarray:
    """``(3, 3)`` rotation taking unit direction ``a`` onto ``b``."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    b = np.asarray(b, float) / np.linalg.norm(b)
    v, c = np.cross(a, b), float(np.dot(a, b))
    if c < -1 + 1e-9:  # opposite: rotate pi about any perpendicular axis
        p = np.cross(a, [1.0, 0, 0]) if abs(a[0]) < 0.9 else np.cross(a, [0, 1.0, 0])
        p /= np.linalg.norm(p)
        return 2 * np.outer(p, p) - np.eye(3)
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k / (1 + c)



def _box_arrays(size: np.ndarray, center: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """An axis-aligned box: 8 corners (in trimesh.creation.box order) and 12 outward triangles."""
    corners = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
    faces = np.array([[1, 3, 0], [4, 1, 0], [0, 3, 2], [2, 4, 0], [1, 7, 3], [5, 1, 4],
                      [5, 7, 1], [3, 7, 2], [6, 4, 2], [2, 7, 6], [6, 5, 4], [7, 5, 6]])
    return corners * size + center, faces


def revolve_arrays(profile: np.ndarray, sections: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed, outward-oriented triangle mesh revolving ``(p, 2)`` ``(radius, z)`` points about +Z.

    Ring ``k`` lies at angle ``2 pi k / sections`` (vertex ``(r cos, r sin, z)``); points on
    the axis (radius 0) become one pole vertex.  A profile whose last point repeats its
    first is a closed outline (a wall) and wraps around.  Consecutive repeated points are
    dropped.  Built with NumPy alone: trimesh's revolve spends most of its time merging.
    """
    prof = np.asarray(profile, float)
    keep = np.r_[True, np.any(np.abs(np.diff(prof, axis=0)) > 1e-12, axis=1)]
    prof = prof[keep]
    cyclic = len(prof) > 2 and np.allclose(prof[0], prof[-1], atol=1e-12)
    if cyclic:
        prof = prof[:-1]
    p, n = len(prof), int(sections)
    pole = prof[:, 0] <= 1e-12
    theta = 2 * np.pi * np.arange(n) / n
    ring_pts = prof[~pole]
    rings = np.stack([np.outer(np.cos(theta), ring_pts[:, 0]), np.outer(np.sin(theta), ring_pts[:, 0]),
                      np.broadcast_to(ring_pts[:, 1], (n, len(ring_pts)))], -1).reshape(-1, 3)
    poles = np.c_[np.zeros((pole.sum(), 2)), prof[pole, 1]]
    verts = np.vstack([rings, poles])
    idx = np.empty((n, p), np.int64)
    ring_col = np.cumsum(~pole) - 1
    idx[:, ~pole] = np.arange(n)[:, None] * len(ring_pts) + ring_col[~pole][None, :]
    idx[:, pole] = len(rings) + np.arange(pole.sum())[None, :]
    segs = [(i, (i + 1) % p) for i in range(p if cyclic else p - 1)]
    k0, k1 = np.arange(n), (np.arange(n) + 1) % n
    tris = []
    for i, j in segs:
        a, b, c, d = idx[k0, i], idx[k0, j], idx[k1, i], idx[k1, j]
        tris += [np.stack([a, c, d], 1), np.stack([a, d, b], 1)]
    faces = np.vstack(tris)
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])]
    tri = verts[faces]
    signed = np.einsum("ij,ij->i", tri[:, 0], cross_rows(tri[:, 1], tri[:, 2])).sum()
    if signed < 0:
        faces = faces[:, ::-1]
    return verts, np.ascontiguousarray(faces)


# ---------------------------------------------------------------------------
# primitives


def box(size: Sequence[float], center: Sequence[float], material: str, bevel: float = 0.0,
        name: str = "") -> Piece:
    """An axis-aligned box, optionally with chamfered edges of width ``bevel``."""
    size = np.asarray(size, float)
    if (size <= 0).any():
        raise GeometryError(f"box size must be positive, got {size.tolist()}")
    center = np.asarray(center, float)
    if bevel > 0:
        b = min(bevel, 0.45 * size.min())
        pts = []
        for k in range(3):
            s = size.copy()
            s[k] -= 2 * b
            pts.append(_box_arrays(s, center)[0])
        v, f = hull_arrays(np.vstack(pts))
    else:
        v, f = _box_arrays(size, center)
    piece = Piece(v, f, material, [v.copy()], name)
    piece.set_hull(0, v, f)
    return piece


def instances(vertices: np.ndarray, faces: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One mesh made of copies of ``(vertices, faces)`` translated by each row of ``offsets``.

    For repeated decoration (perforations, wire mesh): one array operation instead of a mesh
    per copy.
    """
    v, f, off = np.asarray(vertices, float), np.asarray(faces, np.int64), np.asarray(offsets, float)
    verts = (v[None] + off[:, None]).reshape(-1, 3)
    tris = (f[None] + (np.arange(len(off)) * len(v))[:, None, None]).reshape(-1, 3)
    return verts, tris


def box_arrays(size: Sequence[float], center: Sequence[float] = (0, 0, 0)) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of an axis-aligned box: 8 corners, 12 outward triangles."""
    return _box_arrays(np.asarray(size, float), np.asarray(center, float))


def cylinder_arrays(p0: Sequence[float], p1: Sequence[float], radius: float,
                    sections: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of the closed cylinder of :func:`cylinder`."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    h = float(np.linalg.norm(p1 - p0))
    v, f = _unit_cylinder(int(sections))
    rot = _align_z((p1 - p0) / h)  # as trimesh.creation.cylinder
    return (v * (radius, radius, h)) @ rot.T + (p0 + p1) / 2, f.copy()


@functools.lru_cache(maxsize=64)
def _unit_cylinder(sections: int) -> tuple[np.ndarray, np.ndarray]:
    """Radius 1, height 1, centred on the origin along Z (read-only arrays)."""
    v, f = revolve_arrays(np.array([[0, -0.5], [1.0, -0.5], [1.0, 0.5], [0, 0.5]]), sections)
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


def _align_z(direction: np.ndarray) -> np.ndarray:
    """``trimesh.geometry.align_vectors(+Z, direction)`` rotation, cached per direction
    (most cylinders run along a few directions)."""
    return _align_z_cached(tuple(float(x) for x in direction))


@functools.lru_cache(maxsize=1024)
def _align_z_cached(direction: tuple[float, float, float]) -> np.ndarray:
    rot = np.array(trimesh.geometry.align_vectors([0, 0, 1], direction)[:3, :3])
    rot.flags.writeable = False
    return rot


def box_between(lo: Sequence[float], hi: Sequence[float], material: str, bevel: float = 0.0,
                name: str = "") -> Piece:
    """A box from its min and max corners."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return box(hi - lo, (lo + hi) / 2, material, bevel, name)


def panel(lo: Sequence[float], hi: Sequence[float], material: str, normal_axis: str,
          holes: Sequence[tuple[float, float, float, float]] = (), name: str = "") -> Piece:
    """A box panel with rectangular through-holes along ``normal_axis``.

    Parameters
    ----------
    lo, hi : (3,) float
        Corners of the full panel.
    normal_axis : "x" | "y" | "z"
        The thickness direction; holes go through it.
    holes : sequence of (a0, b0, a1, b1)
        Rectangles in the two in-plane axes (in x, y, z order, skipping the
        normal axis), in world coordinates.

    The collision pieces are the grid cells of the panel not covered by a hole,
    merged along rows, so the hollow stays hollow for the simulator.
    """
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    n = _axis_index(normal_axis)
    a, b = [k for k in range(3) if k != n]
    whole = box_between(lo, hi, material, name=name)
    if not holes:
        return whole
    cutters = []
    for a0, b0, a1, b1 in holes:
        clo, chi = lo.copy() - 0, hi.copy()
        clo[n], chi[n] = lo[n] - 0.01, hi[n] + 0.01
        clo[a], chi[a], clo[b], chi[b] = a0, a1, b0, b1
        cutters.append(trimesh.creation.box(chi - clo, trimesh.transformations.translation_matrix((clo + chi) / 2)))
    mesh = subtract(trimesh.creation.box(hi - lo, trimesh.transformations.translation_matrix((lo + hi) / 2)), cutters)
    # convex decomposition: grid of cells from all hole edges
    ea = sorted({lo[a], hi[a], *[h[0] for h in holes], *[h[2] for h in holes]})
    eb = sorted({lo[b], hi[b], *[h[1] for h in holes], *[h[3] for h in holes]})
    convex = []
    for j in range(len(eb) - 1):
        row_start = None
        for i in range(len(ea) + 0):
            filled = False
            if i < len(ea) - 1:
                ca, cb = (ea[i] + ea[i + 1]) / 2, (eb[j] + eb[j + 1]) / 2
                filled = not any(h[0] < ca < h[2] and h[1] < cb < h[3] for h in holes)
            if filled and row_start is None:
                row_start = i
            if not filled and row_start is not None:
                clo, chi = lo.copy(), hi.copy()
                clo[a], chi[a], clo[b], chi[b] = ea[row_start], ea[i], eb[j], eb[j + 1]
                convex.append(_box_arrays(chi - clo, (clo + chi) / 2)[0])
                row_start = None
    return Piece(mesh.vertices, mesh.faces, material, convex, name)


def cylinder(p0: Sequence[float], p1: Sequence[float], radius: float, material: str,
             sections: int = 24, name: str = "") -> Piece:
    """A solid cylinder from point ``p0`` to ``p1``."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if radius <= 0 or np.linalg.norm(p1 - p0) <= 0:
        raise GeometryError(f"cylinder needs radius > 0 and distinct ends, got r={radius}")
    v, f = cylinder_arrays(p0, p1, radius, sections)
    piece = Piece(v, f, material, [v.copy()], name)
    piece.set_hull(0, v, f)  # a closed convex mesh is its own hull
    return piece


def sphere(center: Sequence[float], radius: float, material: str, name: str = "") -> Piece:
    """A solid sphere (icosphere, subdivided twice)."""
    v, f = _unit_icosphere()
    v = v * float(radius) + np.asarray(center, float)
    piece = Piece(v, f.copy(), material, [v.copy()], name)
    piece.set_hull(0, v, f)
    return piece


@functools.cache
def _unit_icosphere() -> tuple[np.ndarray, np.ndarray]:
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=1.0)
    v, f = np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64)
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


def revolve(profile: Sequence[tuple[float, float]], material: str, center: Sequence[float] = (0, 0, 0),
            sections: int = 32, name: str = "") -> Piece:
    """A solid of revolution about +Z through ``center``.

    ``profile`` is ``(p, 2)`` of ``(radius, z)`` points from the bottom centre
    (radius 0) up the outside to the top centre (radius 0). Each band between
    consecutive profile points is one convex frustum for collisions.
    """
    prof = np.asarray(profile, float)
    if prof.ndim != 2 or prof.shape[1] != 2 or len(prof) < 3 or (prof[:, 0] < 0).any():
        raise GeometryError("revolve profile must be (p>=3, 2) of (radius >= 0, z)")
    verts, faces = revolve_arrays(prof, sections)
    verts = verts + np.asarray(center, float)
    th = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    ring = np.c_[np.cos(th), np.sin(th)]
    convex = []
    for (r0, z0), (r1, z1) in zip(prof[:-1], prof[1:]):
        if abs(z1 - z0) < 1e-6 or max(r0, r1) < 1e-6:
            continue
        pts = np.vstack([np.c_[max(r0, 1e-4) * ring, np.full(16, z0)],
                         np.c_[max(r1, 1e-4) * ring, np.full(16, z1)]])
        convex.append(pts + np.asarray(center, float))
    piece = Piece(verts, faces, material, convex, name)
    for k, pts in enumerate(piece.convex):  # each band is a frustum: its hull is known
        piece.set_hull(k, pts, _outward(pts, _FRUSTUM_16))
    return piece


# the hull of two coaxial 16-gons (0..15 below, 16..31 above): side quads and two caps
_FRUSTUM_16 = np.array(_quads(*[(i, (i + 1) % 16, 16 + (i + 1) % 16, 16 + i) for i in range(16)])
                       + _fan(*range(16)) + _fan(*range(16, 32)))


def _outward(pts: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """``faces`` of a convex solid over ``pts``, each flipped to face away from the centroid."""
    tri = pts[faces]
    normal = triangle_cross(tri)
    inward = np.einsum("ij,ij->i", normal, tri[:, 0] - pts.mean(0)) < 0
    out = faces.copy()
    out[inward] = out[inward][:, ::-1]
    return out


def shell(outer: Sequence[tuple[float, float]], thickness: float, material: str,
          center: Sequence[float] = (0, 0, 0), sections: int = 32, convex_sectors: int | None = None,
          name: str = "") -> Piece:
    """A thin wall of revolution (lamp shade, bowl, pot wall), open at both ends.

    ``outer`` is ``(p, 2)`` of ``(radius, z)`` points of the outside surface,
    bottom to top; the inside is the same profile moved ``thickness`` inward.
    Collisions are ``convex_sectors`` wedges per band, so the inside stays hollow; by
    default one wedge per ~3 cm of circumference (8 to 32), so small rings get no slivers.
    """
    outer = np.asarray(outer, float)
    if outer.ndim != 2 or len(outer) < 2 or (outer[:, 0] - thickness <= 0).any():
        raise GeometryError("shell profile must be (p>=2, 2) with every radius > thickness")
    inner = outer - [thickness, 0]
    closed = np.vstack([outer, inner[::-1], outer[:1]])
    # a closed outline gives a closed (watertight) wall
    c = np.asarray(center, float)
    verts, faces = revolve_arrays(closed, sections)
    verts = verts + c
    if convex_sectors is None:
        convex_sectors = int(np.clip(np.ceil(2 * np.pi * outer[:, 0].max() / 0.03), 8, 32))
    angles = np.linspace(0, 2 * np.pi, convex_sectors + 1)
    th = np.linspace(angles[:-1], angles[1:], 4, axis=1)  # (sectors, 4)
    cos, sin = np.cos(th)[:, None, :], np.sin(th)[:, None, :]
    convex = []
    for i in range(len(outer) - 1):
        band = np.array([outer[i], outer[i + 1], inner[i], inner[i + 1]])  # (4, 2): (r, z)
        r, z = band[None, :, 0, None], band[None, :, 1, None]
        # point b * 4 + t of a wedge: band corner b at its angle t
        pts = np.stack([r * cos, r * sin, np.broadcast_to(z, cos.shape[:1] + (4, 4))], -1).reshape(-1, 16, 3) + c
        convex += list(pts)
    piece = Piece(verts, faces, material, convex, name)
    _mark_turned_copies(piece, convex_sectors, angles[:-1], c)
    return piece


def wedge_points(outer, inner, sectors: int, phase: float = 0.0) -> np.ndarray:
    """``(bands, sectors, 8, 3)`` corners of flat-faced wedges of a wall of revolution about +Z.

    ``outer`` and ``inner`` are matching ``(p, 2)`` ``(radius, z)`` profiles; corner ``b * 2 + a``
    of a wedge is band corner ``b`` (outer low, outer high, inner low, inner high) at sector
    edge ``a``, the edges at ``phase + 2 pi s / sectors``.
    """
    outer, inner = np.asarray(outer, float), np.asarray(inner, float)
    ang = phase + 2 * np.pi * np.arange(sectors + 1) / sectors
    cs, sn = np.cos(ang), np.sin(ang)
    edges_c, edges_s = np.stack([cs[:-1], cs[1:]], 1)[:, None, :], np.stack([sn[:-1], sn[1:]], 1)[:, None, :]
    bands = []
    for i in range(len(outer) - 1):
        ring = np.array([outer[i], outer[i + 1], inner[i], inner[i + 1]])  # (4, 2)
        r, z = ring[None, :, 0, None], ring[None, :, 1, None]
        pts = np.stack([r * edges_c, r * edges_s, np.broadcast_to(z, (sectors, 4, 2))], -1)  # (sectors, 4, 2, 3)
        bands.append(pts.reshape(sectors, 8, 3))
    return np.array(bands).reshape(len(bands), sectors, 8, 3)


def _mark_turned_copies(piece: Piece, count: int, turns: np.ndarray, point: np.ndarray) -> None:
    """Declare ``piece.convex`` to be bands of ``count`` wedges, wedge ``s`` of a band being its
    first turned by ``turns[s]`` about +Z through ``point``: one hull topology then serves the
    whole band (found when first needed: categories often replace a shell's collision pieces),
    and writers share the band's mesh (:meth:`Piece.hull_instances`)."""
    piece._hull_hints = {}
    for first in range(0, len(piece.convex), count):
        band = {"src": piece.convex[first], "topology": None, "first": first, "point": np.array(point, float),
                "axis": np.array([0.0, 0.0, 1.0])}
        for s in range(count):
            piece._hull_hints[first + s] = (piece.convex[first + s], band, float(turns[s]))


def disc(center: Sequence[float], radius: float, thickness: float, material: str, sections: int = 32,
         name: str = "") -> Piece:
    """A flat cylinder lying in the XY plane, ``center`` at its middle."""
    c = np.asarray(center, float)
    return cylinder(c - [0, 0, thickness / 2], c + [0, 0, thickness / 2], radius, material, sections, name)


# ---------------------------------------------------------------------------
# handles: built on a face with outward normal ``normal`` (unit axis vector)


def bar_handle(anchor: Sequence[float], normal: Sequence[float], along: Sequence[float], length: float,
               material: str, standoff: float = 0.03, radius: float = 0.006) -> list[Piece]:
    """A bar pull: two posts out of the face and a bar between them.

    ``anchor`` is the centre of the handle on the face; ``along`` the bar direction.
    """
    anchor, n, d = (np.asarray(x, float) for x in (anchor, normal, along))
    half = d * length / 2
    inset = d * min(0.02, length * 0.15)
    pieces = []
    for end in (anchor - half + inset, anchor + half - inset):
        pieces.append(cylinder(end, end + n * standoff, radius * 0.8, material, 12, name="handle"))
    bar_c = anchor + n * (standoff + radius)
    pieces.append(cylinder(bar_c - half, bar_c + half, radius, material, 16, name="handle"))
    return pieces


def knob_handle(anchor: Sequence[float], normal: Sequence[float], material: str, radius: float = 0.015,
                depth: float = 0.025) -> list[Piece]:
    """A round knob: a stem and a wider cap."""
    anchor, n = np.asarray(anchor, float), np.asarray(normal, float)
    stem = cylinder(anchor, anchor + n * depth * 0.6, radius * 0.45, material, 16, name="handle")
    cap = cylinder(anchor + n * depth * 0.55, anchor + n * depth, radius, material, 24, name="handle")
    return [stem, cap]


def pull_handle(anchor: Sequence[float], normal: Sequence[float], along: Sequence[float], length: float,
                material: str, depth: float = 0.018, lip: float = 0.012) -> list[Piece]:
    """A low-profile edge pull (the "recessed" style): a flat lip standing off the face."""
    anchor, n, d = (np.asarray(x, float) for x in (anchor, normal, along))
    side = np.cross(n, d)
    corners = []
    for s in (-1, 1):
        for t in (0, 1):
            for w in (-1, 1):
                corners.append(anchor + d * s * length / 2 + n * depth * t + side * w * lip / 2)
    mesh = convex_hull(np.array(corners))
    return [from_trimesh(mesh, material, name="handle")]
