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
        """A copy moved by a rigid ``(4, 4)`` transform."""
        r, t = matrix[:3, :3], matrix[:3, 3]
        return Piece(
            self.vertices @ r.T + t,
            self.faces.copy(),
            self.material,
            [c @ r.T + t for c in self.convex],
            self.name,
            self.sheet,
        )

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
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        length = np.linalg.norm(n, axis=1, keepdims=True)
        return n / np.where(length > 0, length, 1.0)

    def corner_normals(self) -> np.ndarray:
        """``(m, 3, 3)`` per face-corner normals.

        Each corner averages (area-weighted) the normals of the faces around its
        vertex that lie within :data:`CREASE_DEG` of its own face, so a cylinder's
        side is smooth and its caps stay flat.
        """
        fn = self.face_normals()
        tri = self.vertices[self.faces]
        area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
        vert = self.faces.ravel()  # vertex of each corner; corner c belongs to face c // 3
        order = np.argsort(vert, kind="stable")
        counts = np.bincount(vert, minlength=len(self.vertices))
        start = np.concatenate([[0], np.cumsum(counts)[:-1]])
        k = counts[vert[order]]  # group size of each sorted corner
        a = np.repeat(order, k)  # each corner paired with every corner of its vertex
        first = np.repeat(start[vert[order]], k)
        b = order[first + np.arange(len(a)) - np.repeat(np.cumsum(k) - k, k)]
        fa, fb = a // 3, b // 3
        keep = np.einsum("ij,ij->i", fn[fa], fn[fb]) >= math.cos(math.radians(CREASE_DEG))
        acc = np.zeros((len(vert), 3))
        np.add.at(acc, a[keep], fn[fb[keep]] * area[fb[keep], None])
        length = np.linalg.norm(acc, axis=1, keepdims=True)
        acc = np.where(length > 1e-15, acc / np.maximum(length, 1e-15), fn[np.arange(len(vert)) // 3])
        return acc.reshape(-1, 3, 3)

    def corner_uvs(self) -> np.ndarray:
        """``(m, 3, 2)`` box-projected UVs, :data:`UV_TILE` metres per repeat."""
        fn = self.face_normals()
        axis = np.abs(fn).argmax(1)
        # (u, v) axes per dominant axis, chosen so texture "up" follows Z on walls
        uv_axes = np.array([[1, 2], [0, 2], [0, 1]])[axis]  # (m, 2)
        tri = self.vertices[self.faces]  # (m, 3, 3)
        idx = np.broadcast_to(uv_axes[:, None, :], (len(tri), 3, 2))
        return np.take_along_axis(tri, idx, axis=2) / UV_TILE

    def hulls(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Collision meshes: ``(vertices (k, 3), faces (f, 3))`` per convex piece, outward.

        A hull is kept under :data:`MAX_HULL_VERTICES` (PhysX keeps at most 255) by
        farthest-point sampling of its vertices, which keeps its extremes.
        """
        if getattr(self, "_hulls", None) is None:
            out = []
            for c in self.convex:
                h = convex_hull(c)
                if len(h.vertices) > MAX_HULL_VERTICES:
                    h = convex_hull(_farthest_points(np.asarray(h.vertices), MAX_HULL_VERTICES - 55))
                out.append((np.asarray(h.vertices, float), np.asarray(h.faces, np.int64)))
            self._hulls = out
        return self._hulls

    def volume(self) -> float:
        """Solid volume in m^3: the mesh's if it is closed, else its convex pieces'."""
        mesh = trimesh.Trimesh(self.vertices, self.faces, process=False)
        if mesh.is_watertight:
            return abs(float(mesh.volume))
        return float(sum(convex_hull(c).volume for c in self.convex))


# ---------------------------------------------------------------------------
# helpers


def convex_hull(points: np.ndarray) -> trimesh.Trimesh:
    """The convex hull of a point set as a watertight trimesh with outward faces.

    Qhull (scipy) directly, oriented against the centroid: ~20x faster than the
    general path through ``trimesh.convex``, which matters for hundreds of pieces.
    """
    pts = np.asarray(points, float)
    try:
        hull = ConvexHull(pts)
    except QhullError:
        hull = ConvexHull(pts, qhull_options="QJ")  # degenerate (flat) input: joggle
    used = np.unique(hull.simplices)
    remap = np.full(len(pts), -1)
    remap[used] = np.arange(len(used))
    verts = pts[used]
    faces = remap[hull.simplices]
    tri = verts[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    inward = np.einsum("ij,ij->i", normal, tri[:, 0] - verts.mean(0)) < 0
    faces[inward] = faces[inward][:, ::-1]
    return trimesh.Trimesh(verts, faces, process=False)


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
            pts.append(trimesh.creation.box(s).vertices)
        mesh = convex_hull(np.vstack(pts))
    else:
        mesh = trimesh.creation.box(size)
    mesh.apply_translation(center)
    return from_trimesh(mesh, material, name=name)


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
                convex.append(trimesh.creation.box(chi - clo).vertices + (clo + chi) / 2)
                row_start = None
    return Piece(mesh.vertices, mesh.faces, material, convex, name)


def cylinder(p0: Sequence[float], p1: Sequence[float], radius: float, material: str,
             sections: int = 24, name: str = "") -> Piece:
    """A solid cylinder from point ``p0`` to ``p1``."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if radius <= 0 or np.linalg.norm(p1 - p0) <= 0:
        raise GeometryError(f"cylinder needs radius > 0 and distinct ends, got r={radius}")
    mesh = trimesh.creation.cylinder(radius=radius, segment=np.array([p0, p1]), sections=sections)
    return from_trimesh(mesh, material, name=name)


def sphere(center: Sequence[float], radius: float, material: str, name: str = "") -> Piece:
    """A solid sphere (icosphere, subdivided twice)."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=radius)
    mesh.apply_translation(center)
    return from_trimesh(mesh, material, name=name)


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
    mesh = trimesh.creation.revolve(prof, sections=sections)
    if mesh.volume < 0:
        mesh.invert()
    mesh.apply_translation(center)
    th = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    ring = np.c_[np.cos(th), np.sin(th)]
    convex = []
    for (r0, z0), (r1, z1) in zip(prof[:-1], prof[1:]):
        if abs(z1 - z0) < 1e-6 or max(r0, r1) < 1e-6:
            continue
        pts = np.vstack([np.c_[max(r0, 1e-4) * ring, np.full(16, z0)],
                         np.c_[max(r1, 1e-4) * ring, np.full(16, z1)]])
        convex.append(pts + np.asarray(center, float))
    return Piece(mesh.vertices, mesh.faces, material, convex, name)


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
    # trimesh revolves a polyline; a closed outline gives a closed (watertight) wall
    mesh = trimesh.creation.revolve(closed, sections=sections)
    if mesh.volume < 0:
        mesh.invert()
    c = np.asarray(center, float)
    mesh.apply_translation(c)
    if convex_sectors is None:
        convex_sectors = int(np.clip(np.ceil(2 * np.pi * outer[:, 0].max() / 0.03), 8, 32))
    angles = np.linspace(0, 2 * np.pi, convex_sectors + 1)
    convex = []
    for i in range(len(outer) - 1):
        band = np.array([outer[i], outer[i + 1], inner[i], inner[i + 1]])
        for s in range(convex_sectors):
            th = np.linspace(angles[s], angles[s + 1], 4)
            pts = [(r * np.cos(t), r * np.sin(t), z) for r, z in band for t in th]
            convex.append(np.array(pts) + c)
    return Piece(mesh.vertices, mesh.faces, material, convex, name)


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
