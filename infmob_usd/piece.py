"""The value type of the geometry kernel: :class:`Piece`, one mesh of a part in world
coordinates (metres, Z up) with its material slot and its convex collision pieces.

A piece is immutable (read-only arrays); transforms make new pieces that carry the hulls known
so far. Normals and UVs come from :mod:`infmob_usd.shading`, hulls from :mod:`infmob_usd.hulls`,
volumes from :mod:`infmob_usd.measures`; the builders are in :mod:`infmob_usd.primitives`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import trimesh

from .errors import GeometryError
from .hulls import _BOX_FACES, MAX_HULL_VERTICES, _farthest_points, hull_arrays, hull_indices
from .measures import solids
from .profiles import wedge_points
from .rotation import axis_angle
from .shading import corner_attributes, grain_frame
from .triangles import is_closed, triangle_cross

_all, _min, _max = np.logical_and.reduce, np.minimum.reduce, np.maximum.reduce  # .all(), .min(), .max()
_EYE4 = np.eye(4)
_EYE4.flags.writeable = False


class _Band:
    """Shell wedges that are turned copies of one prototype point set ``src`` (its hull topology,
    found once when first needed, serves them all); ``axis`` None: a stretched band, whose
    wedges are not turned copies any more."""

    __slots__ = ("src", "topology", "first", "point", "axis")

    def __init__(self, src, topology, first, point, axis):
        self.src, self.topology, self.first, self.point, self.axis = src, topology, first, point, axis


def _frozen(a, dtype, owned: bool = False) -> np.ndarray:
    """A read-only C-contiguous copy of ``a`` (or ``a`` itself if it already is one, or if the
    caller ``owned`` it: an array made for this piece alone, frozen in place)."""
    if isinstance(a, np.ndarray) and a.dtype == dtype and a.flags.c_contiguous:
        if not a.flags.writeable:
            return a
        if owned:
            a.flags.writeable = False
            return a
    out = np.array(a, dtype=dtype, order="C")
    out.flags.writeable = False
    return out


@dataclass(frozen=True, eq=False)
class Piece:
    """One mesh of a part: an immutable value (its arrays are read-only).

    Change a piece by making a new one (:meth:`replace`, :meth:`transformed`,
    :meth:`with_collision_of`, :meth:`with_convex`); the hull of each convex collision piece
    is declared at construction where it is known (``hulls``), else computed once (Qhull)
    when first asked for, and travels with every transformed copy.

    Attributes
    ----------
    vertices : (n, 3) float
        Positions in metres.
    faces : (m, 3) int
        Counter-clockwise triangles (outward normals).
    material : str
        Material slot name, resolved per object by the materials room.
    convex : tuple of (k, 3) float
        Point sets whose convex hulls are the collision shapes of this piece.
        Empty means the piece does not collide (decoration).
    name : str
        Optional role, e.g. ``"handle"``; writers keep it in visual names.
    sheet : float
        Wall thickness in metres of a part made of sheet (a steel casing, a
        thin tube) that is modelled solid: mass then counts area x sheet, not
        the solid volume. 0 (default) means solid.
    wall : float or None
        Wall thickness in metres of a hollow part whose closed mesh is its outer surface (a
        ceramic bowl, a steel tube, a hollow-core door): mass is surface area x wall (a thin
        shell, with the shell's centre of mass and inertia, :func:`~infmob_usd.measures.shells`), at most the solid's.
        ``None`` (default): the material family's wall (``Family.wall``, 0 for solid families);
        0: solid. A ``sheet`` > 0 takes precedence.
    grasps : tuple of :class:`~infmob_usd.grasps.Grasp`
        Where a gripper takes hold of this piece (a handle's bar, a dial's cap), in its coordinates;
        they move with every transformed copy (:mod:`infmob_usd.interaction` reads them).
    hulls_known : tuple of ((v, 3) float, (f, 3) int) or None
        Per convex piece, its hull where construction knows it (outward faces over a subset
        of the points); ``None`` entries are computed by :meth:`hulls`. Given as the
        ``hulls`` argument: a sequence, or a dict ``{index: (vertices, faces)}``.
    """

    vertices: np.ndarray
    faces: np.ndarray
    material: str
    convex: tuple[np.ndarray, ...] = ()
    name: str = ""
    sheet: float = 0.0
    wall: float | None = None
    grasps: tuple = ()
    # not init fields: dataclasses.replace(piece, convex=...) then drops hulls it would make stale
    hulls_known: tuple = field(default=(), init=False, repr=False)
    bands: tuple = field(default=(), init=False, repr=False)  # per convex piece: (_Band, turn angle) or None

    def __init__(self, vertices, faces, material: str, convex=(), name: str = "", sheet: float = 0.0,
                 hulls=None, bands=None, _owned: bool = False, wall: float | None = None,
                 _checked: Piece | None = None, grasps=()) -> None:
        # _owned (internal): every array given was made for this piece alone, freeze it in place;
        # _checked (internal): a checked piece whose faces these are (a moved copy)
        put = object.__setattr__
        put(self, "vertices", _frozen(vertices, np.float64, _owned))
        put(self, "faces", _frozen(faces, np.int64, _owned))
        put(self, "material", material)
        put(self, "convex", tuple(_frozen(c, np.float64, _owned) for c in convex))
        put(self, "name", name)
        put(self, "sheet", float(sheet))
        put(self, "wall", None if wall is None else float(wall))
        put(self, "grasps", tuple(grasps))
        n = len(self.convex)
        known = [None] * n
        if isinstance(hulls, dict):
            items = hulls.items()
        else:
            items = enumerate(hulls or ())
        for k, h in items:
            if h is not None and k < n:
                known[k] = (_frozen(h[0], np.float64, _owned), _frozen(h[1], np.int64, _owned))
        put(self, "hulls_known", tuple(known))
        b = tuple(bands or ())
        put(self, "bands", b[:n] + (None,) * (n - len(b[:n])))
        self._check(_checked)

    def check(self) -> None:
        """Raise :class:`GeometryError` if the mesh is corrupt."""
        self._check(None)

    def _check(self, like: Piece | None) -> None:
        """:meth:`check`; the face indices are not checked again against a ``like`` piece's vertex
        count when they are its faces."""
        v, f = self.vertices, self.faces
        if v.ndim != 2 or v.shape[1] != 3 or len(v) < 3:
            raise GeometryError(f"{self._what()}: vertices must be (n>=3, 3), got {v.shape}")
        if f.ndim != 2 or f.shape[1] != 3 or len(f) < 1:
            raise GeometryError(f"{self._what()}: faces must be (m>=1, 3), got {f.shape}")
        if not _all(np.isfinite(v), None):
            raise GeometryError(f"{self._what()}: vertices contain NaN or inf; fix the part's dimensions")
        if like is None or f is not like.faces or len(v) != len(like.vertices):
            shared = _CLOSED_FACES.get(id(f))
            if shared is not None and shared[0] is f:  # a shared face array: its index range is known
                missing = shared[2] >= len(v)
            else:
                missing = _min(f, None) < 0 or _max(f, None) >= len(v)
            if missing:
                raise GeometryError(f"{self._what()}: a face indexes a missing vertex (corrupt mesh)")
        convex = self.convex
        for c in convex:
            if c.ndim != 2 or c.shape[1] != 3 or len(c) < 4:
                raise GeometryError(f"{self._what()}: a convex collision piece needs >= 4 finite points")
        if len(convex) == 1 and convex[0] is v:
            return  # the vertices, checked above
        if convex and not _all(np.isfinite(convex[0] if len(convex) == 1 else np.concatenate(convex)), None):
            raise GeometryError(f"{self._what()}: a convex collision piece needs >= 4 finite points")

    def _what(self) -> str:
        return f"piece {self.name or self.material!r}"

    def replace(self, **changes) -> Piece:
        """A copy with some fields changed (``vertices``, ``faces``, ``material``, ``convex``,
        ``name``, ``sheet``, ``wall``, ``grasps``, ``hulls``). New ``convex`` point sets drop the known hulls unless
        ``hulls`` is given with them."""
        if "convex" in changes:
            hulls, bands = changes.pop("hulls", None), None
        else:
            hulls, bands = changes.pop("hulls", self._hulls_so_far()), self.bands
        args = {"vertices": self.vertices, "faces": self.faces, "material": self.material,
                "convex": self.convex, "name": self.name, "sheet": self.sheet, "wall": self.wall,
                "grasps": self.grasps}
        unknown = set(changes) - set(args)
        if unknown:
            raise TypeError(f"Piece.replace: no field {sorted(unknown)}")
        args.update(changes)
        return Piece(**args, hulls=hulls, bands=bands)

    def _hulls_so_far(self) -> list:
        """Known and already computed hulls (``None`` where not computed yet)."""
        memo = self.__dict__.get("_hulls")
        return list(memo) if memo is not None else list(self.hulls_known)

    # -- transforms ---------------------------------------------------------
    def transformed(self, matrix: np.ndarray) -> Piece:
        """A copy moved by a ``(4, 4)`` transform (rigid, or a stretch that keeps orientation)."""
        r = matrix[:3, :3]
        return self._moved(r, matrix[:3, 3], np.linalg.det(r) > 0, None)

    def _moved(self, r: np.ndarray, t: np.ndarray, keeps: bool, rigid: bool | None) -> Piece:
        """:meth:`transformed` by rotation (or stretch) ``r`` and translation ``t``; ``keeps``: ``r``
        keeps orientation; ``rigid``: ``r`` is a rotation (None: find out if needed)."""
        rt = r.T
        done: dict[int, np.ndarray] = {}

        def move(a: np.ndarray) -> np.ndarray:  # once per array: a box's vertices are its convex and hull
            m = done.get(id(a))
            if m is None:
                m = done[id(a)] = a @ rt + t
            return m

        vertices = move(self.vertices)
        convex = [move(c) for c in self.convex]
        # an orientation-keeping map keeps hull topologies, faces outward
        hulls, bands = None, None
        if keeps:
            hulls = [None if e is None else (move(e[0]), e[1]) for e in self._hulls_so_far()]
        if keeps and any(b is not None for b in self.bands):
            if rigid is None:
                rigid = np.allclose(r @ rt, np.eye(3), atol=1e-9)
            moved: dict[int, _Band] = {}
            bands = []
            for hint in self.bands:
                if hint is None:
                    bands.append(None)
                    continue
                band, angle = hint
                if id(band) not in moved:
                    first = band.first
                    intact = first < len(self.bands) and self.bands[first] is not None and \
                        self.bands[first][0] is band
                    moved[id(band)] = _Band(
                        convex[first] if intact else band.src @ rt + t, band.topology, first,
                        r @ band.point + t,
                        # a stretch keeps the hull topology but the wedges stop being turned copies
                        r @ band.axis if rigid and band.axis is not None else None)
                bands.append((moved[id(band)], angle))
        grasps = tuple(gr.moved(r, t) for gr in self.grasps) if self.grasps else ()
        return self._same_faces(Piece(vertices, self.faces, self.material, convex, self.name,
                                      self.sheet, hulls, bands, _owned=True, wall=self.wall, _checked=self,
                                      grasps=grasps))

    def with_grasps(self, *grasps) -> Piece:
        """This piece carrying ``grasps`` (:class:`~infmob_usd.grasps.Grasp`, in its coordinates) too."""
        return self._same_faces(Piece(self.vertices, self.faces, self.material, self.convex, self.name, self.sheet,
                                      self._hulls_so_far(), self.bands, wall=self.wall, _checked=self,
                                      grasps=self.grasps + tuple(grasps)))

    def translated(self, offset: Sequence[float]) -> Piece:
        t = np.empty(3)
        t[:] = offset  # as transformed() by a 4x4 identity with this translation column, bit for bit
        return self._moved(_EYE4[:3, :3], t, True, True)

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

        Each corner averages (area-weighted) the normals of the faces around its vertex that
        lie within :data:`~infmob_usd.shading.CREASE_DEG` of its own face, so a cylinder's side is smooth and its
        caps stay flat (:func:`~infmob_usd.shading.corner_attributes`).
        """
        return self._corner_attributes()[0]

    def corner_uvs(self) -> np.ndarray:
        """``(m, 3, 2)`` UVs box-projected in the piece's :func:`~infmob_usd.shading.grain_frame`,
        :data:`~infmob_usd.shading.UV_TILE` metres per repeat (computed once)."""
        return self._corner_attributes()[1]

    def _corner_attributes(self) -> tuple[np.ndarray, np.ndarray]:
        memo = self.__dict__.get("_corners")
        if memo is None:
            frames = np.broadcast_to(grain_frame(self.vertices), (len(self.faces), 3, 3))
            n, uv = corner_attributes(self.vertices, self.faces, frames)
            memo = (n.reshape(-1, 3, 3), uv.reshape(-1, 3, 2))
            object.__setattr__(self, "_corners", memo)  # a cache of a pure function of the value
        return memo

    def hulls(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Collision meshes: ``(vertices (k, 3), faces (f, 3))`` per convex piece, outward.

        Declared at construction where known (``hulls``), shared by the turned copies of a
        shell band, else computed once with Qhull (the piece is immutable, so it never goes
        stale). A hull is kept under :data:`~infmob_usd.hulls.MAX_HULL_VERTICES` (PhysX keeps at most 255) by
        farthest-point sampling of its vertices, which keeps its extremes.
        """
        memo = self.__dict__.get("_hulls")
        if memo is not None:
            return list(memo)
        out = []
        for k, c in enumerate(self.convex):
            entry = self.hulls_known[k]
            if entry is None:
                hint = self.bands[k]
                if hint is not None:  # a turned copy of its band's prototype
                    band = hint[0]
                    if band.topology is None:
                        band.topology = hull_indices(band.src)
                    used, f = band.topology
                    entry = (c[used], f)
                else:
                    v, f = hull_arrays(c)
                    if len(v) > MAX_HULL_VERTICES:
                        v, f = hull_arrays(_farthest_points(v, MAX_HULL_VERTICES - 55))
                    entry = (v, np.asarray(f, np.int64))
            out.append(entry)
        object.__setattr__(self, "_hulls", tuple(out))  # a cache of a pure function of the value
        return out

    def with_collision_of(self, other: Piece) -> Piece:
        """This piece's mesh with ``other``'s collision pieces (and their known hulls): a fine
        visual surface over a coarse collision one."""
        return Piece(self.vertices, self.faces, self.material, other.convex, self.name, self.sheet,
                     other._hulls_so_far(), other.bands, wall=self.wall, grasps=self.grasps)

    def with_convex(self, replaced: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]]) -> Piece:
        """A copy with convex pieces replaced: ``{k: (points, hull vertices, hull faces)}``.

        The others keep their hulls; a replaced piece is no turned copy any more."""
        convex = list(self.convex)
        hulls = self._hulls_so_far()
        bands = list(self.bands)
        for k, (pts, hv, hf) in replaced.items():
            convex[k], hulls[k], bands[k] = pts, (hv, hf), None
        return Piece(self.vertices, self.faces, self.material, convex, self.name, self.sheet, hulls, bands,
                     wall=self.wall, grasps=self.grasps)

    def with_wedges(self, outer, inner, sectors: int, phase: float = 0.0) -> Piece:
        """This piece's mesh with flat-faced wedge collisions of a wall of revolution about +Z.

        One convex piece of 8 corners per band and sector (:func:`~infmob_usd.profiles.wedge_points`), so every face
        is exactly planar.  The wedges of a band are turned copies of its first (writers share
        their mesh, :meth:`hull_instances`).
        """
        pts = list(wedge_points(outer, inner, sectors, phase).reshape(-1, 8, 3))
        turns = 2 * np.pi * np.arange(sectors) / sectors
        return Piece(self.vertices, self.faces, self.material, pts, self.name, self.sheet,
                     bands=_turned_copies(pts, sectors, turns, np.zeros(3)), wall=self.wall, grasps=self.grasps)

    def hull_instances(self) -> list[tuple[int, np.ndarray, np.ndarray] | None]:
        """Per hull of :meth:`hulls`: ``(j, R, t)`` when hull ``k`` is hull ``j`` of this piece moved
        rigidly (vertices ``v_j @ R.T + t``, same faces), else ``None``.

        Shell wedges of one band are turned copies of the band's first wedge; writers can
        then store one mesh and place the copies (a URDF ``<collision><origin rpy>``).
        """
        hulls = self.hulls()
        out: list = [None] * len(hulls)
        for k, hint in enumerate(self.bands):
            if hint is None:
                continue
            band, angle = hint
            j = band.first
            first = self.bands[j] if j < len(self.bands) else None
            if j == k or band.axis is None or first is None or first[0] is not band:
                continue  # the prototype itself, a stretched band, or a replaced (eroded) prototype
            rot = axis_angle(band.axis, angle)
            t = band.point - rot @ band.point
            scale = float(np.ptp(hulls[k][0], axis=0).max())
            if np.abs(hulls[j][0] @ rot.T + t - hulls[k][0]).max() > 1e-9 * max(scale, 1e-3):
                continue  # not a copy after all
            out[k] = (j, rot, t)
        return out

    def closed(self) -> bool:
        """:func:`~infmob_usd.triangles.is_closed` of the faces (computed once; copies with the same faces share it)."""
        memo = self.__dict__.get("_closed")
        if memo is None:
            memo = _CLOSED_FACES[id(self.faces)][1] if id(self.faces) in _CLOSED_FACES else is_closed(self.faces)
            object.__setattr__(self, "_closed", memo)  # a cache of a pure function of the faces
        return memo

    def _same_faces(self, other: Piece) -> Piece:
        """``other`` (a copy of this piece with the same faces) with what is known of them."""
        if "_closed" in self.__dict__ and other.faces is self.faces:
            object.__setattr__(other, "_closed", self.__dict__["_closed"])
        return other

    def volume(self) -> float:
        """Solid volume in m^3: the mesh's if it is closed, else its convex pieces' (the solids
        its mass comes from, :func:`~infmob_usd.measures.solids`)."""
        return float(sum(abs(s[0]) for s in solids(self)))


def _shared_faces(f: np.ndarray) -> tuple[np.ndarray, bool, int]:
    """An entry of :data:`_CLOSED_FACES` for a read-only face array of non-negative indices."""
    return f, is_closed(f), int(f.max())


_CLOSED_FACES: dict[int, tuple[np.ndarray, bool, int]] = {id(_BOX_FACES): _shared_faces(_BOX_FACES)}
"""``(faces, is_closed(faces), largest index)`` of shared read-only face arrays (kept alive here, so
their ids stay theirs)."""


def _turned_copies(convex: list, count: int, turns: np.ndarray, point: np.ndarray) -> list:
    """The ``bands`` of a :class:`Piece` whose ``convex`` are bands of ``count`` wedges, wedge ``s``
    of a band being its first turned by ``turns[s]`` about +Z through ``point``: one hull topology
    then serves the whole band (found when first needed: categories often replace a shell's
    collision pieces), and writers share the band's mesh (:meth:`Piece.hull_instances`)."""
    out = []
    for first in range(0, len(convex), count):
        band = _Band(_frozen(convex[first], np.float64), None, first, np.array(point, float),
                     np.array([0.0, 0.0, 1.0]))
        out += [(band, float(turns[s])) for s in range(count)]
    return out


def from_trimesh(mesh: trimesh.Trimesh, material: str, convex=None, name: str = "") -> Piece:
    """Wrap a trimesh; ``convex=None`` means "the piece is convex: use its hull"."""
    if convex is None:
        convex = [np.asarray(mesh.vertices)]
    return Piece(np.asarray(mesh.vertices), np.asarray(mesh.faces), material, convex, name)
