"""A part library on disk: retrieved part meshes with support points, scale policy and convex pieces.

Layout (``LIB/``)::

    index.json                       {"format": "infmob-parts/1", "parts": [{"label", "id", "path"}]}
    <label>/<part_id>/part.json      what the part is (fields below)
    <label>/<part_id>/mesh.obj       the visual mesh (OBJ, GLB or PLY; ``part.json`` names it)
    <label>/<part_id>/convex.json    {"pieces": [[[x, y, z], ...], ...]}: convex collision pieces

``part.json`` fields (every one is checked when the library is loaded):

``label``      a label retrieval knows (:data:`LABELS`)
``id``         the part id (the folder name)
``source``     where the mesh came from (a PartNet-Mobility object id, a file name, ``builtin``)
``licence``    its licence (``CC-BY-NC-4.0``, ``Apache-2.0`` ...)
``units``      ``m`` | ``cm`` | ``mm``: the mesh file's unit
``up``         the mesh axis that points out of the surface the part is mounted on (``+z``, ``-y`` ...;
               a leg: from its foot to its top; a wheel: along its axle)
``front``      the mesh axis along the part's long direction (a bar's length; any axis for a knob)
``supports``   named support points in the mesh file's coordinates and units (a bar handle's
               ``mount_a`` / ``mount_b``, a knob's ``stem``, a leg's ``top`` / ``foot``, a wheel's
               ``axle_a`` / ``axle_b``): where it touches what carries it
``joint_hints`` e.g. ``{"axis": {"point": [...], "direction": [...]}}``: the axis a knob turns about
               (its stem) or a wheel (its axle); a wheel's joint is put on it
``scale``      per-axis ranges of the scale factor the part may be fitted with:
               ``{"x": [lo, hi], "y": [lo, hi], "z": [lo, hi]}`` (x along ``front``, z along ``up``)
``materials``  material slots of the mesh: ``["main"]`` (painted with the slot of the procedural part)
``mesh``       the mesh file name; ``convex``: the convex pieces file name
``watertight`` whether the repaired mesh is closed (reported by ``parts import``)

The importer (:func:`import_parts`) writes canonical files (metres, ``up`` = ``+z``, ``front`` =
``+x``, support points on z = 0); a hand-made ``part.json`` may use any of the values above. Convex
pieces are computed once at import by CoACD (at most 255 vertices each) and never at generation.
"""

from __future__ import annotations

import csv
import json
import math
import os
import shutil
import tempfile
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import InfmobError

FORMAT = "infmob-parts/1"
MAX_HULL = 255  # PhysX keeps at most 255 vertices per convex mesh
UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001}
AXES = ("+x", "-x", "+y", "-y", "+z", "-z")
MESH_SUFFIXES = (".obj", ".glb", ".gltf", ".ply", ".stl")
# A part is a handle, knob, leg or wheel: PartNet-Mobility's come at 1k-100k faces (a few MB). A mesh
# far over these bounds is refused before it is read: 10 M faces would take ~9 GB to load and days in
# CoACD. Decimate it first (e.g. Blender's Decimate modifier, MeshLab's quadric edge collapse).
MAX_MESH_BYTES = 100 << 20
MAX_FACES = 1_000_000

# label -> the support-point sets a part of that label may have (one per kind of part) and its default
# scale policy (per-axis factor ranges about the part's own size). Bar pulls come 96-320 mm long at
# 32 mm steps on one post design (Häfele "Furniture handles" catalogue), so x stretches further than
# the cross-section, which stays within a third of the drawn size.
LABELS: dict[str, dict] = {
    "handle": {"supports": ({"mount_a", "mount_b"}, {"stem"}),
               "scale": {"x": (0.5, 2.0), "y": (0.67, 1.5), "z": (0.67, 1.5)}},
    # door knobs: 50-65 mm across on a 50-60 mm projection (EN 1906 lever/knob furniture ranges)
    "knob": {"supports": ({"stem"},), "scale": {"x": (0.67, 1.5), "y": (0.67, 1.5), "z": (0.67, 1.5)}},
    # table legs are cut to length: one turned or tapered design serves coffee tables (0.3-0.45 m) and
    # dining tables (0.7-0.78 m); their thickness (30-90 mm) follows the table within a factor 2
    "leg": {"supports": ({"top", "foot"},), "scale": {"x": (0.5, 2.0), "y": (0.5, 2.0), "z": (0.4, 2.5)}},
    # caster wheels: 40-76 mm across (chair casters EN 12529: 50 mm; furniture plate casters 50-75 mm);
    # the joint turns about the mesh's own axle (its ``axis`` hint) through the ``axle`` anchor
    "wheel": {"supports": ({"axle_a", "axle_b"},), "scale": {"x": (0.6, 1.6), "y": (0.6, 1.6), "z": (0.5, 2.0)},
              "axis_anchor": "axle"},
}
"""Part frames: ``handle``/``knob``: z out of the mounted surface, supports on z = 0, x along a bar;
``leg``: z from ``foot`` (the origin) to ``top``, both on the z axis; ``wheel``: z along the axle, the
wheel centred on the origin, ``axle_a``/``axle_b`` the axle's ends on the hub faces."""
PLAUSIBLE_M: dict[str, tuple[float, float]] = {
    # cabinet knobs 20-40 mm (a round knob is also a "handle") to appliance bar handles up to ~1 m
    # (tall fridge doors); bar pulls 96-320 mm (Häfele "Furniture handles")
    "handle": (0.02, 1.0),
    # lid knobs 17-40 mm, hob knobs 35-45 mm, door knobs 50-65 mm across (EN 1906), up to 0.1 m
    "knob": (0.01, 0.1),
    # sofa and cabinet feet from 50 mm, dining legs 0.7-0.78 m, bar-table legs to ~1.1 m
    "leg": (0.05, 1.2),
    # chair casters 50 mm (EN 12529), furniture casters 40-76 mm, trolley wheels to ~0.2 m
    "wheel": (0.02, 0.3),
}
"""label -> plausible largest extent (m) of a part's mesh: how ``import_parts`` infers a source's unit
when ``--units`` is not given. Every lower bound times 100 exceeds its upper bound, so a mesh is never
plausible both in metres and in centimetres (or millimetres); only cm/mm can be ambiguous."""
SHARED = {frozenset({"stem"}): ("handle", "knob")}
"""Support kinds whose parts serve several labels: a round knob is a cabinet handle or a door knob."""


class PartLibraryError(InfmobError):
    """A part library (or a source to import) that cannot be used."""


def _within(real: str, top: str) -> bool:
    return real == top or real.startswith(top.rstrip(os.sep) + os.sep)


def _err(path, problem: str, fix: str) -> PartLibraryError:
    return PartLibraryError(f"{path}: {problem}; {fix}")


# -- meshes -------------------------------------------------------------------------------------------
def read_mesh(path: Path):
    """A trimesh of every triangle in ``path`` (OBJ, GLB, PLY, STL), unprocessed."""
    import trimesh

    try:
        size = os.stat(path).st_size
    except OSError as e:
        raise _err(path, f"unreadable mesh ({e.strerror})", "check the file") from None
    if size > MAX_MESH_BYTES:
        raise _err(path, f"the file is {size / 2**20:.0f} MB, over the {MAX_MESH_BYTES >> 20} MB a part mesh may"
                   f" have", f"decimate it below {MAX_FACES:,} faces first (nothing was read)")
    try:
        loaded = trimesh.load(str(path), force="mesh", process=False)
    except Exception as e:  # noqa: BLE001 - every reader failure is the same bad input
        raise _err(path, f"unreadable mesh ({type(e).__name__}: {' '.join(str(e).split())[:120]})",
                   "re-export it as OBJ, GLB or PLY") from None
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0 or len(loaded.vertices) < 3:
        raise _err(path, "the file holds no triangles", "re-export it as a triangle mesh (OBJ, GLB or PLY)")
    if len(loaded.faces) > MAX_FACES:
        raise _err(path, f"{len(loaded.faces):,} faces, over the {MAX_FACES:,} a part mesh may have",
                   "decimate it first")
    if not np.isfinite(np.asarray(loaded.vertices)).all():
        raise _err(path, "vertices contain NaN or inf", "re-export the mesh")
    return loaded


def hull_volume(vertices: np.ndarray, faces: np.ndarray) -> float:
    """Volume enclosed by outward faces (divergence theorem)."""
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def flat(points: np.ndarray) -> bool:
    """Whether a convex piece encloses no volume (all points on a plane, a line or one point): PhysX
    cooks no convex mesh from it, and a simulator given one collides with nothing there or crashes."""
    from .geometry import hull_arrays

    ext = float(np.ptp(points, axis=0).max()) if len(points) else 0.0
    if ext <= 0.0:
        return True
    try:
        v, f = hull_arrays(points)
    except Exception:  # noqa: BLE001 - Qhull gives up on fully degenerate input
        return True
    return abs(hull_volume(v, f)) <= 1e-9 * ext**3


def write_obj(path: Path, vertices: np.ndarray, faces: np.ndarray) -> None:
    """A plain OBJ (``v`` and ``f`` lines, 9 significant digits): byte-identical for the same mesh."""
    lines = [f"v {x:.9g} {y:.9g} {z:.9g}" for x, y, z in np.asarray(vertices, float)]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in np.asarray(faces, int)]
    path.write_text("\n".join(lines) + "\n")


def axis_matrix(up: str, front: str) -> np.ndarray:
    """``(3, 3)`` rotation taking mesh coordinates to the part frame: ``front`` -> +x, ``up`` -> +z."""
    def vec(a: str) -> np.ndarray:
        v = np.zeros(3)
        v["xyz".index(a[1])] = 1.0 if a[0] == "+" else -1.0
        return v

    z, x = vec(up), vec(front)
    if abs(float(x @ z)) > 0.5:
        raise ValueError(f"up {up} and front {front} are parallel")
    return np.vstack([x, np.cross(z, x), z])


@dataclass
class Repaired:
    vertices: np.ndarray
    faces: np.ndarray
    watertight: bool
    report: str


def repair(vertices, faces, where: str) -> Repaired:
    """Merge duplicate vertices, drop degenerate and duplicate faces, orient normals consistently
    outward. Raises :class:`PartLibraryError` for a mesh with non-manifold edges (an edge of more
    than two faces) or nothing left."""
    import trimesh

    m = trimesh.Trimesh(np.asarray(vertices, float), np.asarray(faces, int), process=False)
    n0v, n0f = len(m.vertices), len(m.faces)
    m.merge_vertices(digits_vertex=7)
    m.update_faces(m.nondegenerate_faces(height=1e-9))
    m.update_faces(m.unique_faces())
    m.remove_unreferenced_vertices()
    if len(m.faces) < 4:
        raise _err(where, "fewer than 4 faces left after dropping degenerate ones", "check the mesh export")
    edges = np.sort(m.edges, axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    bad = int((counts > 2).sum())
    if bad:
        raise _err(where, f"non-manifold mesh ({bad} edges shared by more than two faces)",
                   "split or remesh it in a modeller, or leave it out")
    flipped = 0
    pieces = []
    for comp in m.split(only_watertight=False):  # each connected piece outward on its own
        trimesh.repair.fix_winding(comp)
        if comp.is_watertight:
            out = comp.volume
        else:  # an open patch: its faces should point away from the mesh centre
            out = float(((comp.triangles_center - m.vertices.mean(0)) * comp.face_normals).sum())
        if out < 0:
            comp.invert()
            flipped += 1
        pieces.append(comp)
    m = trimesh.util.concatenate(pieces) if len(pieces) > 1 else pieces[0]
    report = (f"{n0v - len(m.vertices)} duplicate vertices merged, {n0f - len(m.faces)} degenerate or duplicate"
              f" faces dropped, {'watertight' if m.is_watertight else 'NOT watertight'}"
              + (f", {flipped} inside-out piece(s) turned outward" if flipped else ""))
    return Repaired(np.asarray(m.vertices, float), np.asarray(m.faces, np.int64), bool(m.is_watertight), report)


def convex_pieces(vertices: np.ndarray, faces: np.ndarray, seed: int = 0) -> list[np.ndarray]:
    """CoACD's approximate convex decomposition (at import only), each piece cut to 255 vertices."""
    try:
        import coacd
    except ImportError:
        raise PartLibraryError("importing parts needs CoACD; pip install 'infmob-usd[parts]' (or coacd)") from None

    coacd.set_log_level("error")
    parts = coacd.run_coacd(coacd.Mesh(np.asarray(vertices, float), np.asarray(faces, np.int32)), threshold=0.08,
                            max_convex_hull=8, preprocess_mode="off", resolution=600, mcts_iterations=40,
                            mcts_max_depth=2, mcts_nodes=12, seed=seed, max_ch_vertex=MAX_HULL)
    out = []
    for v, _f in parts:
        v = np.asarray(v, float)
        if len(v) > MAX_HULL:
            from .hulls import _farthest_points
            v = _farthest_points(v, MAX_HULL)
        if len(v) >= 4:
            out.append(v)
    return out


def clip_pieces(pieces: list[np.ndarray], z_max: float) -> list[np.ndarray]:
    """Convex pieces cut by the plane z = ``z_max`` (what lies above is inside the carrier); pieces wholly
    above it are dropped."""
    import trimesh

    out = []
    for v in pieces:
        if v[:, 2].max() <= z_max + 1e-9:
            out.append(v)
            continue
        if v[:, 2].min() >= z_max - 1e-6:
            continue
        hull = trimesh.convex.convex_hull(v)
        hv = np.asarray(hull.vertices, float)
        a, b = hv[hull.edges_unique[:, 0]], hv[hull.edges_unique[:, 1]]
        cross = (a[:, 2] - z_max) * (b[:, 2] - z_max) < 0  # hull edges through the plane
        t = (z_max - a[cross, 2]) / (b[cross, 2] - a[cross, 2])
        pts = np.vstack([hv[hv[:, 2] <= z_max], a[cross] + t[:, None] * (b[cross] - a[cross])])
        if len(pts) >= 4 and np.ptp(pts, axis=0).min() > 1e-6:
            out.append(np.asarray(trimesh.convex.convex_hull(pts).vertices, float))
    return out


# -- the rule per label: part frame and support points ---------------------------------------------
def canonical_frame(vertices: np.ndarray, faces: np.ndarray, label: str) -> tuple[np.ndarray, str]:
    """``(rotation (3, 3) mesh -> part frame, kind)`` by the rule of ``label``.

    A handle is a *bar* when its longest extent is at least twice the next: x along it, z (out of
    the mounted surface) along the larger of the two others, pointing from the feet to the grip
    (the side holding more surface). Otherwise it is a *stem* part (a knob): z is the axis whose two
    cross extents are the most alike, pointing from the stem to the cap.
    """
    ext = np.ptp(vertices, axis=0)
    order = np.argsort(-ext)
    tri = vertices[faces]
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    centroid = (tri.mean(1) * area[:, None]).sum(0) / max(area.sum(), 1e-30)
    mid = 0.5 * (vertices.min(0) + vertices.max(0))
    eye = np.eye(3)
    if label == "leg":
        return _leg_frame(vertices, ext), "leg"
    if label == "wheel":  # the axle: the axis across which the wheel is round
        ratios = [min(ext[[b for b in range(3) if b != a]]) / max(max(ext[[b for b in range(3) if b != a]]), 1e-12)
                  for a in range(3)]
        zi = int(np.argmax(ratios))
        xi = next(b for b in range(3) if b != zi)
        return np.vstack([eye[xi], np.cross(eye[zi], eye[xi]), eye[zi]]), "wheel"
    if label != "knob" and ext[order[0]] >= 2.0 * ext[order[1]]:
        kind = "bar"
        xi = int(order[0])
        zi = int(order[1])
    else:
        kind = "stem"
        ratios = []
        for a in range(3):
            o = [b for b in range(3) if b != a]
            ratios.append(min(ext[o]) / max(max(ext[o]), 1e-12))
        zi = int(np.argmax(ratios))
        xi = next(b for b in range(3) if b != zi)
    sign = 1.0 if centroid[zi] >= mid[zi] else -1.0
    z = eye[zi] * sign
    x = eye[xi]
    return np.vstack([x, np.cross(z, x), z]), kind


def _slab_centre(v: np.ndarray, axis: int, high: bool) -> tuple[np.ndarray, float]:
    """The centroid of the vertices within 3 % of the length of the lowest (highest) end along ``axis``,
    and the end's width (the largest extent across)."""
    span = float(np.ptp(v[:, axis]))
    tol = max(0.0005, 0.03 * span)
    end = v[:, axis].max() if high else v[:, axis].min()
    s = v[np.abs(v[:, axis] - end) <= tol]
    others = [b for b in range(3) if b != axis]
    return s.mean(0), float(np.ptp(s[:, others], axis=0).max())


def _leg_frame(v: np.ndarray, ext: np.ndarray) -> np.ndarray:
    """A leg's rotation: z along the leg from its foot to its top. The leg runs along the mesh's longest
    axis; upright in the source (along z) its top is the higher end, lying down the wider end (a leg
    tapers to its foot); a splayed leg's z goes from the centre of its foot to the centre of its top."""
    ax = int(np.argmax(ext))
    a, wa = _slab_centre(v, ax, False)
    b, wb = _slab_centre(v, ax, True)
    foot, top = (a, b) if ax == 2 or wb >= wa else (b, a)
    d = top - foot
    d = d / np.linalg.norm(d)
    from .frames import Frame

    other = np.eye(3)[next(b for b in range(3) if b != ax)]
    return Frame.at(z=d, x=other).rotation.T


def support_rule(vertices: np.ndarray, kind: str, where: str) -> dict[str, np.ndarray]:
    """Support points of a part already in its frame: the contact patches on its lowest plane.

    ``bar``: the centroids of the lowest vertices on each side of the middle (``mount_a`` at -x,
    ``mount_b`` at +x); ``stem``: the centroid of the lowest vertices (``stem``). Points lie on
    the lowest plane. ``leg``: ``foot`` on the lowest plane and ``top`` on the highest where the leg
    is at least half its full width (the shoulder under a stud), both on the line through the centres
    of the two ends; ``wheel``: ``axle_a`` / ``axle_b`` at the middle of the
    wheel's round outline on its two faces.
    """
    if kind == "leg":
        a, _ = _slab_centre(vertices, 2, False)
        b, _ = _slab_centre(vertices, 2, True)
        xy = 0.5 * (a[:2] + b[:2])
        # the top: the highest level where the leg is at least half its full width (its shoulder, under
        # a hanger bolt or dowel that goes into what it carries)
        r = np.linalg.norm(vertices[:, :2] - xy, axis=1)
        tol = max(1e-5, 1e-3 * float(np.ptp(vertices[:, 2])))
        top = float(vertices[:, 2].max())
        for z in np.unique(np.round(vertices[:, 2] / tol))[::-1] * tol:
            if r[np.abs(vertices[:, 2] - z) <= tol].max() >= 0.5 * r.max():
                top = float(vertices[np.abs(vertices[:, 2] - z) <= tol][:, 2].max())
                break
        return {"foot": np.array([*xy, vertices[:, 2].min()]), "top": np.array([*xy, top])}
    if kind == "wheel":
        c = 0.5 * (vertices.min(0) + vertices.max(0))
        return {"axle_a": np.array([c[0], c[1], vertices[:, 2].min()]),
                "axle_b": np.array([c[0], c[1], vertices[:, 2].max()])}
    z0 = float(vertices[:, 2].min())
    tol = max(0.0005, 0.03 * float(np.ptp(vertices[:, 2])))
    low = vertices[vertices[:, 2] <= z0 + tol]
    if kind == "stem":
        c = low.mean(0)
        return {"stem": np.array([c[0], c[1], z0])}
    xm = 0.5 * (vertices[:, 0].min() + vertices[:, 0].max())
    a, b = low[low[:, 0] < xm], low[low[:, 0] > xm]
    if len(a) == 0 or len(b) == 0:
        raise _err(where, "a bar handle needs a foot at each end on its mounting plane, found one",
                   "give its supports in part.json or leave it out")
    return {"mount_a": np.array([*a.mean(0)[:2], z0]), "mount_b": np.array([*b.mean(0)[:2], z0])}


# -- the library in memory --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class LibPart:
    """One loaded part, in its part frame (metres, z out of the mount, x along it)."""

    label: str
    id: str
    source: str
    licence: str
    vertices: np.ndarray
    faces: np.ndarray
    convex: tuple
    hulls: tuple
    supports: dict
    scale: dict
    joint_hints: dict = field(default_factory=dict)
    folder: str = ""
    axis: tuple | None = None
    """``(point (3,), unit direction (3,))`` in the part frame: the ``axis`` joint hint (a knob's stem,
    a wheel's axle), or None."""

    @property
    def kind(self) -> frozenset:
        return frozenset(self.supports)

    def piece(self, material: str, name: str = ""):
        from .piece import Piece

        return Piece(self.vertices, self.faces, material, self.convex, name, hulls=self.hulls)


@dataclass(frozen=True, eq=False)
class Library:
    root: str
    parts: tuple[LibPart, ...]

    def candidates(self, label: str, kind: frozenset) -> list[LibPart]:
        labels = SHARED.get(kind, (label,)) if label in SHARED.get(kind, ()) else (label,)
        return [p for p in self.parts if p.label in labels and p.kind == kind]

    @property
    def labels(self) -> list[str]:
        return sorted({p.label for p in self.parts})


_CACHE: dict[tuple, Library] = {}


def _read_json(path: Path, fix: str):
    if not path.is_file():
        raise _err(path, "missing", fix)
    try:
        return json.loads(path.read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise _err(path, f"not valid JSON ({' '.join(str(e).split())[:80]})", fix) from None


def _vec3(value, path, name) -> np.ndarray:
    try:
        a = np.asarray(value, float)
    except (TypeError, ValueError):
        a = np.zeros(0)
    if a.shape != (3,) or not np.isfinite(a).all():
        raise _err(path, f"field {name!r} must be three finite numbers, got {value!r}", "fix that field")
    return a


def _scale_of(value, pj: Path) -> dict[str, tuple[float, float]]:
    """A part.json ``scale`` field: ``{axis: (lo, hi)}`` for x, y and z, ``0 < lo <= hi``."""
    scale = {}
    if not isinstance(value, dict):
        raise _err(pj, "field 'scale' must map x, y, z to [lo, hi]", "fix that field")
    for ax in "xyz":
        r = value.get(ax)
        if not (isinstance(r, list) and len(r) == 2 and all(isinstance(v, (int, float)) for v in r)
                and 0 < r[0] <= r[1] and math.isfinite(r[1])):
            raise _err(pj, f"field 'scale.{ax}' must be [lo, hi] with 0 < lo <= hi, got {r!r}", "fix that field")
        scale[ax] = (float(r[0]), float(r[1]))
    return scale


def _hint_axis(hints: dict, pj: Path, rot: np.ndarray, k: float) -> tuple[np.ndarray, np.ndarray] | None:
    """A part.json ``joint_hints.axis`` turned by ``rot`` and scaled by ``k`` (to metres): ``(point, unit
    direction)``, or None without one."""
    if "axis" not in hints:
        return None
    ax = hints["axis"]
    if not isinstance(ax, dict) or set(ax) != {"point", "direction"}:
        raise _err(pj, "field 'joint_hints.axis' must be {\"point\": [x, y, z], \"direction\": [x, y, z]}",
                   "fix that field")
    u = rot @ _vec3(ax["direction"], pj, "joint_hints.axis.direction")
    if np.linalg.norm(u) < 1e-9:
        raise _err(pj, "field 'joint_hints.axis.direction' is zero", "give the axis direction")
    return rot @ _vec3(ax["point"], pj, "joint_hints.axis.point") * k, u / np.linalg.norm(u)


def _load_part(folder: Path, label: str, pid: str) -> LibPart:
    pj = folder / "part.json"
    d = _read_json(pj, "re-import the part (infmob parts import) or write its part.json")
    if not isinstance(d, dict):
        raise _err(pj, "must be a JSON object", "see the part.json fields in docs/parts.md")
    for key in ("label", "id", "source", "licence", "units", "up", "front", "supports", "scale", "mesh", "convex"):
        if key not in d:
            raise _err(pj, f"missing field {key!r}", "add it (see the part.json fields in docs/parts.md)")
    if d["label"] not in LABELS:
        raise _err(pj, f"unknown label {d['label']!r}", f"use one of {sorted(LABELS)}")
    if d["label"] != label or d["id"] != pid:
        raise _err(pj, f"label/id {d['label']}/{d['id']} disagree with its folder {label}/{pid}",
                   "move the folder or fix the fields")
    for key in ("source", "licence"):
        if not isinstance(d[key], str) or not d[key]:
            raise _err(pj, f"field {key!r} must be a non-empty string", "name it (e.g. \"unknown\")")
    if d["units"] not in UNITS:
        raise _err(pj, f"field 'units' must be one of {list(UNITS)}, got {d['units']!r}", "fix that field")
    for key in ("up", "front"):
        if d[key] not in AXES:
            raise _err(pj, f"field {key!r} must be one of {list(AXES)}, got {d[key]!r}", "fix that field")
    try:
        rot = axis_matrix(d["up"], d["front"])
    except ValueError as e:
        raise _err(pj, str(e), "give two perpendicular axes") from None
    k = UNITS[d["units"]]
    sup = d["supports"]
    if not isinstance(sup, dict) or not sup:
        raise _err(pj, "field 'supports' must map names to points", "e.g. {\"stem\": [0, 0, 0]}")
    kinds = LABELS[label]["supports"]
    if set(sup) not in kinds:
        raise _err(pj, f"supports {sorted(sup)} match no kind of {label!r}",
                   f"name them as one of {[sorted(s) for s in kinds]}")
    supports = {n: rot @ _vec3(v, pj, f"supports.{n}") * k for n, v in sorted(sup.items())}
    scale = _scale_of(d["scale"], pj)
    hints = d.get("joint_hints", {})
    if not isinstance(hints, dict):
        raise _err(pj, "field 'joint_hints' must be an object", "fix that field")
    axis = _hint_axis(hints, pj, rot, k)
    for name in ("mesh", "convex"):
        if not isinstance(d[name], str) or "/" in d[name] or d[name].startswith("."):
            raise _err(pj, f"field {name!r} must be a file name in the part's folder", "fix that field")
    for name in ("mesh", "convex"):
        if not _within(os.path.realpath(folder / d[name]), os.path.realpath(folder)):
            raise _err(pj, f"{name} file {d[name]!r} is a symbolic link out of the part's folder", "copy the file in")
    mesh = read_mesh(folder / d["mesh"])
    v = np.asarray(mesh.vertices, float) @ rot.T * k
    f = np.asarray(mesh.faces, np.int64)
    cj = _read_json(folder / d["convex"], "re-import the part to compute its convex pieces")
    pieces = cj.get("pieces") if isinstance(cj, dict) else None
    if not isinstance(pieces, list) or not pieces:
        raise _err(folder / d["convex"], "needs a non-empty list 'pieces'", "re-import the part")
    convex = []
    for i, pc in enumerate(pieces):
        try:
            a = np.asarray(pc, float)
        except (TypeError, ValueError):
            a = np.zeros((0, 0))
        if a.ndim != 2 or a.shape[1] != 3 or not 4 <= len(a) <= MAX_HULL or not np.isfinite(a).all():
            raise _err(folder / d["convex"], f"piece {i} must be 4..{MAX_HULL} finite points",
                       "re-import the part")
        if flat(a):
            raise _err(folder / d["convex"], f"piece {i} encloses no volume (its points lie on a plane)",
                       "re-import the part (a collision piece must be a solid)")
        convex.append(a @ rot.T * k)
    from .hulls import hull_arrays

    hulls = tuple(hull_arrays(c) for c in convex)
    return LibPart(label, pid, d["source"], d["licence"], v, f, tuple(convex), hulls, supports, scale, hints,
                   str(folder), axis)


def load_library(root) -> Library:
    """Load and check a library (cached per process while its ``index.json`` is unchanged)."""
    if isinstance(root, Library):
        return root
    root = Path(root)
    index = root / "index.json"
    if not root.is_dir():
        raise _err(root, "no such part library folder", "give a folder made by `infmob parts import` or"
                   " `infmob parts export-builtin`")
    try:
        st = index.stat()
        key = (str(root.resolve()), st.st_mtime_ns, st.st_size)
    except OSError:
        key = None
    if key is not None and key in _CACHE:
        return _CACHE[key]
    d = _read_json(index, "make the library with `infmob parts import` or `infmob parts export-builtin`")
    if not isinstance(d, dict) or d.get("format") != FORMAT or not isinstance(d.get("parts"), list):
        raise _err(index, f"not a part library index (needs format {FORMAT!r} and a list 'parts')",
                   "re-make it with `infmob parts import`")
    parts = []
    for i, e in enumerate(d["parts"]):
        if not isinstance(e, dict) or not all(isinstance(e.get(k), str) for k in ("label", "id", "path")):
            raise _err(index, f"entry {i} needs string fields label, id, path", "re-make the index")
        if e["label"] not in LABELS:
            raise _err(index, f"entry {i}: unknown label {e['label']!r}", f"use one of {sorted(LABELS)}")
        folder = root / e["path"]
        if os.path.isabs(e["path"]) or ".." in Path(e["path"]).parts or \
                not _within(os.path.realpath(folder), os.path.realpath(root)):
            raise _err(index, f"entry {i}: part folder {e['path']!r} is outside the library (an absolute path,"
                       f" .. or a symbolic link)", "give paths relative to the library, e.g. handle/h01")
        if not folder.is_dir():
            raise _err(index, f"entry {i}: part folder {e['path']!r} missing", "re-make the index or restore it")
        parts.append(_load_part(folder, e["label"], e["id"]))
    if not parts:
        raise _err(index, "the library holds no parts", "import some with `infmob parts import`")
    lib = Library(str(root), tuple(sorted(parts, key=lambda p: (p.label, p.id))))
    if key is not None:
        _CACHE[key] = lib
    return lib


# -- writing a library -------------------------------------------------------------------------------
@dataclass
class Entry:
    """One part to write: canonical mesh (metres, part frame), supports, convex pieces, provenance."""

    label: str
    id: str
    source: str
    licence: str
    vertices: np.ndarray
    faces: np.ndarray
    supports: dict
    convex: list
    watertight: bool
    report: str = ""
    scale: dict | None = None
    joint_hints: dict | None = None


def _fresh_out(out: Path) -> None:
    if os.path.islink(out):
        raise _err(out, "is a symbolic link", "give a new real folder with --out (nothing was written)")
    if out.exists() and (not out.is_dir() or any(out.iterdir())):
        raise _err(out, "exists and is not empty", "give a new folder with --out (nothing was written)")
    if not out.parent.is_dir():
        raise _err(out.parent, "no such folder", "create it first (nothing was written)")


def write_library(entries: list[Entry], out: Path) -> Path:
    """Write ``entries`` as a library into the new folder ``out`` (atomically: a temporary folder renamed)."""
    out = Path(out)
    _fresh_out(out)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", dir=out.parent))
    try:
        index = []
        for e in sorted(entries, key=lambda e: (e.label, e.id)):
            folder = tmp / e.label / e.id
            folder.mkdir(parents=True)
            write_obj(folder / "mesh.obj", e.vertices, e.faces)
            (folder / "convex.json").write_text(json.dumps(
                {"pieces": [[[round(float(x), 9) for x in p] for p in c] for c in e.convex]}) + "\n")
            hints = e.joint_hints
            if hints is None and set(e.supports) == {"stem"}:
                hints = {"axis": {"point": [round(float(x), 9) for x in e.supports["stem"]],
                                  "direction": [0.0, 0.0, 1.0]}}
            if hints is None and set(e.supports) == {"axle_a", "axle_b"}:
                a, b = np.asarray(e.supports["axle_a"], float), np.asarray(e.supports["axle_b"], float)
                hints = {"axis": {"point": [round(float(x), 9) for x in (a + b) / 2],
                                  "direction": [round(float(x), 9) for x in (b - a) / np.linalg.norm(b - a)]}}
            meta = {"label": e.label, "id": e.id, "source": e.source, "licence": e.licence, "units": "m",
                    "up": "+z", "front": "+x",
                    "supports": {k: [round(float(x), 9) for x in v] for k, v in sorted(e.supports.items())},
                    "joint_hints": hints or {},
                    "scale": {k: list(v) for k, v in (e.scale or LABELS[e.label]["scale"]).items()},
                    "materials": ["main"], "mesh": "mesh.obj", "convex": "convex.json",
                    "watertight": bool(e.watertight), "repair": e.report}
            (folder / "part.json").write_text(json.dumps(meta, indent=2) + "\n")
            index.append({"label": e.label, "id": e.id, "path": f"{e.label}/{e.id}"})
        (tmp / "index.json").write_text(json.dumps({"format": FORMAT, "parts": index}, indent=2) + "\n")
        if out.exists():
            out.rmdir()
        os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return out


def _entry(label: str, pid: str, source: str, licence: str, v: np.ndarray, f: np.ndarray, where: str,
           overrides: dict | None = None) -> Entry:
    """Repair, orient by the rule of ``label`` (or the given axes), find supports, decompose."""
    rep = repair(v, f, where)
    v, f = rep.vertices, rep.faces
    overrides = overrides or {}
    if overrides.get("up") and overrides.get("front"):
        rot, kind = axis_matrix(overrides["up"], overrides["front"]), None
    else:
        rot, kind = canonical_frame(v, f, label)
    v = v @ rot.T
    if kind is None:
        ext = np.ptp(v, axis=0)
        kind = label if label in ("leg", "wheel") else "bar" if ext[0] >= 2 * max(ext[1], 1e-12) else "stem"
    sup = support_rule(v, kind, where)
    # the part frame: supports' centre on the origin (a leg's foot), the mounting plane at z = 0
    c = sup["foot"] if kind == "leg" else np.mean(list(sup.values()), axis=0)
    v = v - c
    sup = {k: p - c for k, p in sup.items()}
    convex = convex_pieces(v, f)
    if kind == "leg":  # a bolt or dowel above the shoulder goes into the table top: no collider there
        convex = clip_pieces(convex, float(sup["top"][2]))
    convex = [c for c in convex if not flat(c)]  # a sliver CoACD leaves on a plane collides with nothing
    if not convex:
        raise _err(where, "CoACD found no convex piece", "check the mesh is a solid or leave it out")
    return Entry(label, pid, source, licence, v, f, sup, convex, rep.watertight, rep.report)


def _safe_id(text: str) -> str:
    s = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in text).strip("_")
    return s or "part"


# -- PartNet-Mobility ------------------------------------------------------------------------------------
SEMANTIC_LABELS = {"handle": "handle", "knob": "knob", "leg": "leg", "wheel": "wheel"}
"""PartNet-Mobility semantic labels imported, and the label they get."""


def _rpy(rpy) -> np.ndarray:
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def _origin(el, path) -> np.ndarray:
    m = np.eye(4)
    o = el.find("origin") if el is not None else None
    if o is not None:
        try:
            xyz = [float(x) for x in o.get("xyz", "0 0 0").split()]
            rpy = [float(x) for x in o.get("rpy", "0 0 0").split()]
        except ValueError:
            raise _err(path, "an <origin> has non-numeric xyz/rpy", "fix the URDF") from None
        if len(xyz) != 3 or len(rpy) != 3:
            raise _err(path, "an <origin> needs three xyz and three rpy values", "fix the URDF")
        m[:3, :3], m[:3, 3] = _rpy(rpy), xyz
    return m


def _mobility_parts(obj: Path, units: str, up: str) -> tuple[list, list[str]]:
    """``([(label, id, source, vertices, faces, where)], rejected lines)`` of one PartNet-Mobility object."""
    urdf, sem = obj / "mobility.urdf", obj / "semantics.txt"
    for f in (urdf, sem, obj / "result.json"):
        if not f.is_file():
            raise _err(f, "missing from a PartNet-Mobility object folder", "copy the whole object folder")
    _read_json(obj / "result.json", "copy the object's result.json again")
    try:
        root = ET.parse(urdf).getroot()
    except (ET.ParseError, OSError) as e:
        raise _err(urdf, f"unreadable URDF ({e})", "copy the object's mobility.urdf again") from None
    labels = {}
    for n, line in enumerate(sem.read_text(errors="replace").splitlines(), 1):
        w = line.split()
        if not w:
            continue
        if len(w) != 3:
            raise _err(sem, f"line {n} must be `link joint_type label`", "fix or re-copy semantics.txt")
        labels[w[0]] = w[2]
    world = {}
    joints = [(j.find("parent").get("link"), j.find("child").get("link"), _origin(j, urdf))
              for j in root.findall("joint") if j.find("parent") is not None and j.find("child") is not None]
    names = [lk.get("name") for lk in root.findall("link")]
    children = {c for _, c, _ in joints}
    for n in names:
        if n not in children:
            world[n] = np.eye(4)
    for _ in range(len(joints) + 1):
        for p, c, m in joints:
            if p in world and c not in world:
                world[c] = world[p] @ m
    to_z = axis_matrix("+" + up if up[0] not in "+-" else up, "+x" if up.lstrip("+-") != "x" else "+y")
    k = UNITS[units]
    out, rejected = [], []
    for link in root.findall("link"):
        name = link.get("name")
        label = SEMANTIC_LABELS.get(labels.get(name, ""))
        if label is None:
            continue
        vs, fs, off = [], [], 0
        for vis in link.findall("visual"):
            mesh_el = vis.find("geometry/mesh")
            if mesh_el is None or not mesh_el.get("filename"):
                continue
            path = obj / mesh_el.get("filename")
            if os.path.isabs(mesh_el.get("filename")) or not _within(os.path.realpath(path), os.path.realpath(obj)):
                raise _err(urdf, f"link {name} names {mesh_el.get('filename')!r}, outside the object folder",
                           "copy a PartNet-Mobility object as it was downloaded (nothing was read)")
            if not path.is_file():
                raise _err(path, f"named by {urdf.name} link {name} but missing", "copy textured_objs/ again")
            m = read_mesh(path)
            T = world.get(name, np.eye(4)) @ _origin(vis, urdf)
            v = np.asarray(m.vertices, float) @ T[:3, :3].T + T[:3, 3]
            vs.append(v)
            fs.append(np.asarray(m.faces) + off)
            off += len(v)
        if not vs:
            rejected.append(f"{urdf}: link {name} ({labels[name]}) has no visual mesh; skipped")
            continue
        v = np.vstack(vs) @ to_z.T * k
        out.append((label, f"{_safe_id(obj.name)}_{_safe_id(name)}", f"PartNet-Mobility {obj.name} {name}",
                    v, np.vstack(fs), f"{urdf} link {name}"))
    return out, rejected


def _labelled_meshes(src: Path, csv_path: Path, units: str | None, up: str, licence: str,
                     free: list[int] | None = None) -> list[tuple]:
    """The meshes a ``labels.csv`` lists (``(label, id, source, licence, v, f, where, overrides)``): each
    line checked (a file inside ``src``, a known label, units and axes), its mesh read and oriented.
    With ``units`` None a line without a ``units`` column is read as metres and its index appended to
    ``free`` (its unit is inferred later)."""
    found = []
    try:
        rows = list(csv.DictReader(csv_path.read_text().splitlines()))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise _err(csv_path, f"unreadable CSV ({e})", "write it as UTF-8 with a header line") from None
    if not rows or "file" not in rows[0] or "label" not in rows[0]:
        raise _err(csv_path, "needs a header with columns file,label", "add them (units,up,front optional)")
    for n, row in enumerate(rows, 2):
        path = src / (row.get("file") or "")
        if row.get("file") and (os.path.isabs(row["file"]) or
                                not _within(os.path.realpath(path), os.path.realpath(src))):
            raise _err(csv_path, f"line {n}: {row['file']!r} is outside {src}", "copy the mesh into the folder")
        if not row.get("file") or not path.is_file() or path.suffix.lower() not in MESH_SUFFIXES:
            raise _err(csv_path, f"line {n}: {row.get('file')!r} is not a mesh file in {src}",
                       f"fix the line (meshes: {', '.join(MESH_SUFFIXES)})")
        label = row["label"]
        if label not in LABELS:
            raise _err(csv_path, f"line {n}: unknown label {label!r}", f"use one of {sorted(LABELS)}")
        u = row.get("units") or units
        if u is None and free is not None:
            free.append(len(found))
            u = "m"
        if u not in UNITS:
            raise _err(csv_path, f"line {n}: units must be one of {list(UNITS)}, got {u!r}", "fix the line")
        ov = {}
        for key in ("up", "front"):
            if row.get(key):
                if row[key] not in AXES:
                    raise _err(csv_path, f"line {n}: {key} must be one of {list(AXES)}", "fix the line")
                ov[key] = row[key]
        m = read_mesh(path)
        v = np.asarray(m.vertices, float) * UNITS[u]
        if not ov:
            src_up = up if up[0] in "+-" else "+" + up
            v = v @ axis_matrix(src_up, "+x" if src_up[1] != "x" else "+y").T
        found.append((label, _safe_id(path.stem), row.get("source") or path.name,
                      row.get("licence") or licence or "unknown", v, np.asarray(m.faces), str(path), ov))
    return found


def infer_units(found: list[tuple], free: list[int], log=print) -> float:
    """The factor to metres of the meshes ``found[i]`` (read as metres) for ``i`` in ``free``: 1 when
    every one has a plausible size in metres (:data:`PLAUSIBLE_M`), else the one unit in which every one
    is plausible (said in one line through ``log``); refused when no unit or both cm and mm fit."""
    if not free:
        return 1.0
    sizes = [(found[i][0], float(np.ptp(found[i][4], axis=0).max())) for i in free]
    fits = [u for u, k in UNITS.items()
            if all(PLAUSIBLE_M[lb][0] <= size * k <= PLAUSIBLE_M[lb][1] for lb, size in sizes)]
    if "m" in fits:
        return 1.0
    shown = ", ".join(f"{lb} {size:.4g}" for lb, size in sizes[:4]) + (" ..." if len(sizes) > 4 else "")
    if len(fits) != 1:
        why = f"fit both {' and '.join(fits)}" if fits else "fit no single unit"
        raise PartLibraryError(f"cannot tell the unit of the meshes: their sizes ({shown}) {why} for part"
                               " sizes of their labels: give --units m|cm|mm (nothing was written)")
    log(f"infmob: meshes read as {fits[0]} (sizes {shown} are implausible in metres for their labels);"
        f" scaled by {UNITS[fits[0]]:g} (give --units to override)")
    return UNITS[fits[0]]


def import_parts(src, out, units: str | None = None, up: str = "y", licence: str = "", labels_csv=None,
                 log=print) -> tuple[Path, list[str]]:
    """Import a source into a new library ``out``; returns ``(out, rejected lines)``.

    ``src``: a PartNet-Mobility object folder (``mobility.urdf``, ``textured_objs/``, ``result.json``,
    ``semantics.txt``), a folder of them, or a folder of OBJ/GLB/PLY files with ``labels.csv``
    (columns ``file,label`` and optionally ``units,up,front,source,licence``). ``units``/``up``: of
    PartNet-Mobility meshes (its objects are Y-up); ``units`` None: inferred from the meshes' sizes
    (:func:`infer_units`). A mesh that cannot be used is rejected with a
    line saying why; a source that cannot be read stops the import with nothing written.
    """
    src, out = Path(src), Path(out)
    if units is not None and units not in UNITS:
        raise PartLibraryError(f"--units must be one of {list(UNITS)}, got {units!r}")
    if up.lstrip("+-") not in ("x", "y", "z"):
        raise PartLibraryError(f"--up must be x, y or z (optionally signed), got {up!r}")
    if not src.is_dir():
        raise _err(src, "no such folder", "give a PartNet-Mobility object folder or a folder with labels.csv")
    _fresh_out(out)
    found = []  # (label, id, source, licence, v, f, where, overrides)
    rejected: list[str] = []
    free: list[int] = []  # indices into found whose unit is inferred
    csv_path = Path(labels_csv) if labels_csv else src / "labels.csv"
    objects = [src] if (src / "mobility.urdf").exists() else \
        sorted(d for d in src.iterdir() if d.is_dir() and (d / "mobility.urdf").exists())
    if objects:
        for obj in objects:
            got, rej = _mobility_parts(obj, units or "m", up)
            rejected += rej
            if units is None:
                free += range(len(found), len(found) + len(got))
            found += [(lb, pid, source, licence or "PartNet-Mobility terms of use", v, f, where, {})
                      for lb, pid, source, v, f, where in got]
    elif csv_path.is_file():
        found = _labelled_meshes(src, csv_path, units, up, licence, free)
    else:
        raise _err(src, "holds neither PartNet-Mobility objects (mobility.urdf) nor labels.csv",
                   "give such a folder, or --labels CSV")
    k = infer_units(found, free, log)
    if k != 1.0:
        scaled = set(free)
        found = [(*t[:4], t[4] * k, *t[5:]) if i in scaled else t for i, t in enumerate(found)]
    entries, seen = [], set()
    for label, pid, source, lic, v, f, where, ov in found:
        while (label, pid) in seen:
            pid += "_b"
        try:
            e = _entry(label, pid, source, lic, v, f, where, ov)
        except PartLibraryError as err:
            rejected.append(f"rejected {err}")
            log(f"infmob: rejected {err}")
            continue
        seen.add((label, pid))
        entries.append(e)
        log(f"infmob: {label}/{pid}: {e.report}; {len(e.convex)} convex pieces; supports {sorted(e.supports)}")
    if not entries:
        raise _err(src, "no usable part (" + "; ".join(rejected)[:300] + ")", "fix the meshes (nothing was written)")
    write_library(entries, out)
    return out, rejected
