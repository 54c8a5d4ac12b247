"""The primitives a part is built of, each returning a :class:`~infmob_usd.piece.Piece`: boxes
(plain, bevelled, between corners), panels with rectangular holes, cylinders, discs, swept tubes,
spheres, solids and thin walls of revolution; and the ``(vertices, faces)`` arrays behind them.

Every builder takes plain numbers or ``(3,)`` arrays (metres, Z up) and a material slot name, and
declares the convex collision pieces (and their hulls) it knows by construction.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

import numpy as np
import trimesh

from .booleans import subtract
from .errors import GeometryError
from .hulls import _UNIT_BOX_HULL, _box_arrays, _fan, _outward, _quads, hull_arrays
from .measures import mass_properties
from .piece import _CLOSED_FACES, Piece, _shared_faces, _turned_copies
from .profiles import collision_bands, sections_for
from .rotation import align_z
from .triangles import cross_rows, is_closed, triangle_cross


def _axis_index(axis: str | int) -> int:
    if isinstance(axis, str):
        return "xyz".index(axis.lower())
    return int(axis)


def revolve_arrays(profile: np.ndarray, sections: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed, outward-oriented triangle mesh revolving ``(p, 2)`` ``(radius, z)`` points about +Z.

    Ring ``k`` lies at angle ``2 pi k / sections`` (vertex ``(r cos, r sin, z)``); points on
    the axis (radius 0) become one pole vertex.  A profile whose last point repeats its
    first is a closed outline (a wall) and wraps around.  Consecutive repeated points are
    dropped.  Built with NumPy alone: trimesh's revolve spends most of its time merging.
    """
    prof = np.asarray(profile, float)
    keep = np.concatenate(([True], (np.abs(np.diff(prof, axis=0)) > 1e-12).any(axis=1)))
    prof = prof[keep]
    # np.allclose(prof[0], prof[-1], atol=1e-12), without its overhead
    cyclic = len(prof) > 2 and bool(((np.abs(prof[0] - prof[-1]) <= 1e-12 + 1e-5 * np.abs(prof[-1]))
                                      | (prof[0] == prof[-1])).all())
    if cyclic:
        prof = prof[:-1]
    n = int(sections)
    pole = prof[:, 0] <= 1e-12
    cos, sin = _ring_trig(n)
    ring_pts = prof[~pole]
    rings = np.stack([np.outer(cos, ring_pts[:, 0]), np.outer(sin, ring_pts[:, 0]),
                      np.broadcast_to(ring_pts[:, 1], (n, len(ring_pts)))], -1).reshape(-1, 3)
    poles = np.column_stack((np.zeros((pole.sum(), 2)), prof[pole, 1]))
    verts = np.vstack([rings, poles])
    faces = _revolve_faces(n, tuple(pole.tolist()), cyclic)
    tri = verts[faces]
    signed = np.einsum("ij,ij->i", tri[:, 0], cross_rows(tri[:, 1], tri[:, 2])).sum()
    if signed < 0:
        return verts, np.ascontiguousarray(faces[:, ::-1])
    return verts, faces.copy()


@functools.lru_cache(maxsize=64)
def _ring_trig(n: int) -> tuple[np.ndarray, np.ndarray]:
    """``cos`` and ``sin`` of :func:`revolve_arrays`' ``n`` ring angles ``2 pi k / n`` (read-only)."""
    theta = 2 * np.pi * np.arange(n) / n
    cos, sin = np.cos(theta), np.sin(theta)
    cos.flags.writeable = False
    sin.flags.writeable = False
    return cos, sin


@functools.lru_cache(maxsize=256)
def _revolve_faces(n: int, pole: tuple[bool, ...], cyclic: bool) -> np.ndarray:
    """The triangles of :func:`revolve_arrays` before orientation (read-only): they depend only on
    the section count, which profile points are on the axis and whether the outline is closed."""
    pole = np.array(pole, bool)
    p = len(pole)
    n_ring = int((~pole).sum())
    idx = np.empty((n, p), np.int64)
    ring_col = np.cumsum(~pole) - 1
    idx[:, ~pole] = np.arange(n)[:, None] * n_ring + ring_col[~pole][None, :]
    idx[:, pole] = n * n_ring + np.arange(pole.sum())[None, :]
    si = np.arange(p if cyclic else p - 1)
    sj = (si + 1) % p
    k1 = (np.arange(n) + 1) % n
    # per segment (i, j), rows k: (a, c, d) then (a, d, b), segments in order
    a, b, c, d = idx[:, si].T, idx[:, sj].T, idx[k1][:, si].T, idx[k1][:, sj].T  # (segments, n)
    faces = np.stack([np.stack([a, c, d], -1), np.stack([a, d, b], -1)], 1).reshape(-1, 3)
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])]
    faces = np.ascontiguousarray(faces)
    faces.flags.writeable = False
    return faces


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
    return Piece(v, f, material, [v], name, hulls=[(v, f)], _owned=True)


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
    v, f = _box_arrays(np.asarray(size, float), np.asarray(center, float))
    return v, f.copy()


def cylinder_arrays(p0: Sequence[float], p1: Sequence[float], radius: float,
                    sections: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of the closed cylinder of :func:`cylinder`."""
    v, f = _cylinder_arrays(p0, p1, radius, sections)
    return v, f.copy()


def _cylinder_arrays(p0, p1, radius: float, sections: int) -> tuple[np.ndarray, np.ndarray]:
    """:func:`cylinder_arrays` with the shared read-only faces of its section count (known closed)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    h = float(np.linalg.norm(p1 - p0))
    v, f = _unit_cylinder(int(sections))
    if id(f) not in _CLOSED_FACES:
        _CLOSED_FACES[id(f)] = _shared_faces(f)  # kept alive here, so the id stays this array's
    rot = align_z((p1 - p0) / h)  # as trimesh.creation.cylinder
    return (v * (radius, radius, h)) @ rot.T + (p0 + p1) / 2, f


@functools.lru_cache(maxsize=64)
def _unit_cylinder(sections: int) -> tuple[np.ndarray, np.ndarray]:
    """Radius 1, height 1, centred on the origin along Z (read-only arrays)."""
    v, f = revolve_arrays(np.array([[0, -0.5], [1.0, -0.5], [1.0, 0.5], [0, 0.5]]), sections)
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


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
    if not holes:
        return box_between(lo, hi, material, name=name)
    # the grid of cells cut by every hole edge; a cell is filled unless a hole covers it
    ea = sorted({lo[a], hi[a], *[h[0] for h in holes], *[h[2] for h in holes]})
    eb = sorted({lo[b], hi[b], *[h[1] for h in holes], *[h[3] for h in holes]})
    h = np.asarray(holes, float).reshape(-1, 4)
    ca, cb = np.asarray(ea, float), np.asarray(eb, float)
    ca, cb = ((ca[:-1] + ca[1:]) / 2)[:, None, None], ((cb[:-1] + cb[1:]) / 2)[None, :, None]
    filled = ~((h[:, 0] < ca) & (ca < h[:, 2]) & (h[:, 1] < cb) & (cb < h[:, 3])).any(2)  # (cells a, cells b)
    # convex decomposition: the filled cells merged along rows
    convex = []
    for j in range(len(eb) - 1):
        for i0, i1 in _runs(np.concatenate(([False], filled[:, j], [False]))):
            clo, chi = lo.copy(), hi.copy()
            clo[a], chi[a], clo[b], chi[b] = ea[i0], ea[i1], eb[j], eb[j + 1]
            convex.append(_box_arrays(chi - clo, (clo + chi) / 2)[0])
    vertices, faces = _panel_mesh(lo, hi, n, a, b, ea, eb, filled)
    return Piece(vertices, faces, material, convex, name, hulls=[(c, _UNIT_BOX_HULL[1]) for c in convex],
                 _owned=True)


def _runs(row: np.ndarray) -> list[tuple[int, int]]:
    """``(first, end)`` cell numbers of each run of filled cells in a row padded with an empty cell at
    each end (cell ``k`` of the row is ``row[k + 1]``; a run covers grid lines ``first`` to ``end``)."""
    return list(zip(np.flatnonzero(row[1:] & ~row[:-1]).tolist(), np.flatnonzero(row[:-1] & ~row[1:]).tolist()))


def _panel_mesh(lo: np.ndarray, hi: np.ndarray, n: int, a: int, b: int, ea: list, eb: list,
                filled: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The closed, outward surface of a plate ``lo``-``hi`` (thickness along ``n``) whose grid cells
    ``ea`` x ``eb`` (in-plane axes ``a``, ``b``) are solid where ``filled[i, j]``, written directly.

    Each row of filled cells is one strip of front and back faces, zipped between the points its
    two edges need (its own ends and those of the rows beside it, so no vertex lies on another
    face's edge); walls close it wherever a filled cell meets an empty one or the outside.  A
    layout whose holes touch only at a corner (not a manifold) goes through the boolean instead.
    """
    na, nb = len(ea) - 1, len(eb) - 1
    full = np.zeros((na + 2, nb + 2), bool)  # padded: cell (i, j) is full[i + 1, j + 1]
    full[1:-1, 1:-1] = filled
    # grid point (i, j) splits line b = eb[j] where the row below or above changes there
    split = (full[:-1, :-1] != full[1:, :-1]) | (full[:-1, 1:] != full[1:, 1:])  # (na + 1, nb + 1)
    lines = [np.flatnonzero(split[:, j]).tolist() for j in range(nb + 1)]
    stride = (na + 1) * (nb + 1)
    tris: list[tuple[int, int, int, int, int, int]] = []  # (i, j) corners, counter-clockwise in (a, b)
    for j in range(nb):
        for s, e in _runs(full[:, j + 1]):
            bot = [k for k in lines[j] if s <= k <= e]
            top = [k for k in lines[j + 1] if s <= k <= e]
            p = q = 0
            while p < len(bot) - 1 or q < len(top) - 1:
                if q == len(top) - 1 or (p < len(bot) - 1 and ea[bot[p + 1]] <= ea[top[q + 1]]):
                    tris.append((bot[p], j, bot[p + 1], j, top[q], j + 1))
                    p += 1
                else:
                    tris.append((bot[p], j, top[q + 1], j + 1, top[q], j + 1))
                    q += 1
    t = np.array(tris, np.int64).reshape(-1, 6)
    flat = t[:, 0::2] + (na + 1) * t[:, 1::2]  # grid point numbers (back side; + stride: front)
    if (a, b) == (0, 2):  # (a, b, n) not cyclic: counter-clockwise in (a, b) faces -n
        flat = flat[:, ::-1]
    walls, out = [], []
    for j, line in enumerate(lines):  # walls along b = eb[j], between consecutive split points
        for p, q in zip(line[:-1], line[1:]):
            below, above = full[p + 1, j], full[p + 1, j + 1]
            if below != above:
                k0, k1 = p + (na + 1) * j, q + (na + 1) * j
                walls.append((k0, k1, k1 + stride, k0 + stride))
                out.append((b, 1.0 if below else -1.0))
    jv, iv = np.nonzero((full[:-1, 1:-1] != full[1:, 1:-1]).T)  # walls along a = ea[i], row j (by row)
    k0 = iv + (na + 1) * jv
    k1 = k0 + (na + 1)
    quads = np.vstack([np.array(walls, np.int64).reshape(-1, 4),
                       np.column_stack([k0, k1, k1 + stride, k0 + stride])])
    axis = np.concatenate([np.array([o[0] for o in out], np.int64), np.full(len(iv), a)])
    sign = np.concatenate([np.array([o[1] for o in out]), np.where(full[iv, jv + 1], 1.0, -1.0)])
    faces = np.empty((2 * len(flat), 3), np.int64)
    faces[0::2], faces[1::2] = flat + stride, flat[:, ::-1]  # per triangle: front, then back
    used = np.unique(np.concatenate([faces.ravel(), quads.ravel()]))  # the grid points used, in grid order
    remap = np.empty(2 * stride, np.int64)
    remap[used] = np.arange(len(used))
    i, j, side = used % (na + 1), (used % stride) // (na + 1), used // stride
    vertices = np.empty((len(used), 3))
    vertices[:, a], vertices[:, b] = np.asarray(ea, float)[i], np.asarray(eb, float)[j]
    vertices[:, n] = np.where(side > 0, hi[n], lo[n])
    quads = remap[quads]
    normal = triangle_cross(vertices[quads[:, :3]])
    flip = normal[np.arange(len(quads)), axis] * sign < 0
    quads[flip] = quads[flip][:, ::-1]
    faces = np.vstack([remap[faces], quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    if not is_closed(faces):  # holes that touch at a corner only: let the boolean resolve it
        cutters = []
        for i, j in zip(*np.nonzero(~filled)):
            clo, chi = lo.copy(), hi.copy()
            clo[n], chi[n] = lo[n] - 0.01, hi[n] + 0.01
            clo[a], chi[a], clo[b], chi[b] = ea[i], ea[i + 1], eb[j], eb[j + 1]
            cutters.append(trimesh.creation.box(chi - clo, trimesh.transformations.translation_matrix((clo + chi) / 2)))
        mesh = subtract(trimesh.creation.box(hi - lo, trimesh.transformations.translation_matrix((lo + hi) / 2)),
                        cutters)
        return np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64)
    return vertices, faces


def cylinder(p0: Sequence[float], p1: Sequence[float], radius: float, material: str,
             sections: int | None = 24, name: str = "") -> Piece:
    """A solid cylinder from point ``p0`` to ``p1``; ``sections=None``:
    :func:`~infmob_usd.profiles.sections_for` its radius."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if radius <= 0 or np.linalg.norm(p1 - p0) <= 0:
        raise GeometryError(f"cylinder needs radius > 0 and distinct ends, got r={radius}")
    if sections is None:
        sections = sections_for(radius)
    v, f = _cylinder_arrays(p0, p1, radius, sections)
    return Piece(v, f, material, [v], name, hulls=[(v, f)], _owned=True)  # a closed convex mesh is its own hull


def tube(path: Sequence[Sequence[float]], radius: float, material: str, sections: int | None = None,
         name: str = "") -> Piece:
    """A solid round rod of ``radius`` swept along the polyline ``path`` (``(k >= 2, 3)``): a bent wire, a
    bow handle, a hairpin leg. Each ring is square to the path's mean tangent at its point (rings turned
    with the path by parallel transport, so the rod never twists); the ends are capped flat. Each segment
    between two rings is one convex collision piece (a short, possibly slanted, cylinder). ``sections``
    round the rod: by default :func:`~infmob_usd.profiles.sections_for` its radius (12 to 24)."""
    pts = np.asarray(path, float)
    if pts.ndim != 2 or pts.shape[1] != 3 or len(pts) < 2 or not np.isfinite(pts).all() or radius <= 0:
        raise GeometryError(f"tube needs a (k>=2, 3) finite path and radius > 0, got {pts.shape}, r={radius}")
    seg = np.diff(pts, axis=0)
    length = np.linalg.norm(seg, axis=1)
    if (length < 1e-9).any():
        raise GeometryError("tube path has two equal consecutive points")
    seg = seg / length[:, None]
    if sections is None:
        sections = sections_for(radius, hi=24)
    tangent = np.vstack([seg[:1], seg[:-1] + seg[1:], seg[-1:]])
    tangent /= np.maximum(np.linalg.norm(tangent, axis=1, keepdims=True), 1e-12)
    # a first normal across the first tangent, then carried along (parallel transport)
    ref = np.eye(3)[int(np.argmin(np.abs(tangent[0])))]
    n = ref - tangent[0] * float(ref @ tangent[0])
    n /= np.linalg.norm(n)
    th = 2 * np.pi * np.arange(sections) / sections
    rings = []
    for k, t in enumerate(tangent):
        if k:
            n = n - t * float(n @ t)
            n /= np.linalg.norm(n)
        b = cross_rows(t, n)
        ring = radius * (np.cos(th)[:, None] * b + np.sin(th)[:, None] * n)
        if 0 < k < len(pts) - 1:  # a bend: the ring is a mitre, stretched in the bend's plane
            turn = seg[k] - seg[k - 1]
            turn -= t * float(turn @ t)
            size = float(np.linalg.norm(turn))
            if size > 1e-9:
                u = turn / size
                cos_half = math.cos(0.5 * math.acos(float(np.clip(seg[k - 1] @ seg[k], -1.0, 1.0))))
                ring = ring + np.outer(ring @ u, u) * (1.0 / max(cos_half, 0.2) - 1.0)
        rings.append(pts[k] + ring)
    verts = np.vstack(rings + [pts[:1], pts[-1:]])
    m = sections
    faces = []
    for k in range(len(pts) - 1):
        a0, a1 = k * m, (k + 1) * m
        for i in range(m):
            j = (i + 1) % m
            faces += [(a0 + i, a0 + j, a1 + j), (a0 + i, a1 + j, a1 + i)]
    c0, c1 = len(pts) * m, len(pts) * m + 1
    last = (len(pts) - 1) * m
    for i in range(m):
        j = (i + 1) % m
        faces += [(c0, j, i), (c1, last + i, last + j)]
    faces = np.asarray(faces, np.int64)
    if mass_properties(verts, faces)[0] < 0:  # wound inward: the parallel-transported frame is left-handed
        faces = faces[:, ::-1].copy()
    convex = [np.vstack([rings[k], rings[k + 1]]) for k in range(len(pts) - 1)]
    return Piece(verts, faces, material, convex, name, _owned=True)


def sphere(center: Sequence[float], radius: float, material: str, name: str = "") -> Piece:
    """A solid sphere (icosphere, subdivided twice: once would leave 36 degrees from face to face, more
    than :data:`~infmob_usd.shading.CREASE_DEG`, and be drawn faceted)."""
    v, f = _unit_icosphere()
    v = v * float(radius) + np.asarray(center, float)
    return Piece(v, f, material, [v], name, hulls=[(v, f)], _owned=True)


@functools.cache
def _unit_icosphere() -> tuple[np.ndarray, np.ndarray]:
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=1.0)
    v, f = np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64)
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


def revolve(profile: Sequence[tuple[float, float]], material: str, center: Sequence[float] = (0, 0, 0),
            sections: int | None = None, name: str = "") -> Piece:
    """A solid of revolution about +Z through ``center``.

    ``profile`` is ``(p, 2)`` of ``(radius, z)`` points from the bottom centre
    (radius 0) up the outside to the top centre (radius 0). Each band between
    consecutive profile points is one convex frustum for collisions. ``sections`` round
    the axis: by default :func:`~infmob_usd.profiles.sections_for` the largest radius.
    """
    prof = np.asarray(profile, float)
    if prof.ndim != 2 or prof.shape[1] != 2 or len(prof) < 3 or (prof[:, 0] < 0).any():
        raise GeometryError("revolve profile must be (p>=3, 2) of (radius >= 0, z)")
    if sections is None:
        sections = sections_for(float(prof[:, 0].max()))
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
    # each band is a frustum: its hull is known
    return Piece(verts, faces, material, convex, name, hulls=[(pts, _outward(pts, _FRUSTUM_16)) for pts in convex],
                 _owned=True)


# the hull of two coaxial 16-gons (0..15 below, 16..31 above): side quads and two caps
_FRUSTUM_16 = np.array(_quads(*[(i, (i + 1) % 16, 16 + (i + 1) % 16, 16 + i) for i in range(16)])
                       + _fan(*range(16)) + _fan(*range(16, 32)))


def shell(outer: Sequence[tuple[float, float]], thickness: float, material: str,
          center: Sequence[float] = (0, 0, 0), sections: int | None = None, convex_sectors: int | None = None,
          name: str = "") -> Piece:
    """A thin wall of revolution (lamp shade, bowl, pot wall), open at both ends.

    ``outer`` is ``(p, 2)`` of ``(radius, z)`` points of the outside surface,
    bottom to top; the inside is the same profile moved ``thickness`` inward.
    ``sections`` round the axis: by default :func:`~infmob_usd.profiles.sections_for` the largest radius.
    Collisions are ``convex_sectors`` wedges per band, so the inside stays hollow; by
    default one wedge per ~3 cm of circumference (8 to 32), so small rings get no slivers.
    Consecutive bands whose profile is straight to within :data:`~infmob_usd.profiles.BAND_TOL` collide as one
    band (:func:`~infmob_usd.profiles.collision_bands`).
    """
    outer = np.asarray(outer, float)
    if outer.ndim != 2 or len(outer) < 2 or (outer[:, 0] - thickness <= 0).any():
        raise GeometryError("shell profile must be (p>=2, 2) with every radius > thickness")
    inner = outer - [thickness, 0]
    closed = np.vstack([outer, inner[::-1], outer[:1]])
    # a closed outline gives a closed (watertight) wall
    c = np.asarray(center, float)
    verts, faces = revolve_arrays(closed, sections_for(float(outer[:, 0].max())) if sections is None else sections)
    verts = verts + c
    if convex_sectors is None:
        convex_sectors = int(np.clip(np.ceil(2 * np.pi * outer[:, 0].max() / 0.03), 8, 32))
    outer = collision_bands(outer)
    inner = outer - [thickness, 0]
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
    return Piece(verts, faces, material, convex, name, bands=_turned_copies(convex, convex_sectors, angles[:-1], c),
                 _owned=True)


def disc(center: Sequence[float], radius: float, thickness: float, material: str, sections: int | None = 32,
         name: str = "") -> Piece:
    """A flat cylinder lying in the XY plane, ``center`` at its middle (``sections=None``:
    :func:`~infmob_usd.profiles.sections_for` its radius)."""
    c = np.asarray(center, float)
    return cylinder(c - [0, 0, thickness / 2], c + [0, 0, thickness / 2], radius, material, sections, name)
