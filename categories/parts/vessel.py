"""Vessel walls and lids: hollow bodies of revolution, necks, rims, feet, closures and cookware handles.

Everything here returns an :class:`~infmob_usd.assembly.Assembly` in its own local
frame, Z up along the vessel's axis:

* bodies (:func:`vase_body`, :func:`bottle_body`, :func:`round_jar_body`,
  :func:`polygon_jar_body`, :func:`cookware_body`) have their base centre at the
  origin and anchors ``base`` (the bottom, z up), ``rim`` (the mouth's top
  centre), ``lid_seat`` (where a closure sits: the rim, or a gap above it for
  cookware) and ``neck_top`` (bottles and jars); support points ``foot_*`` round
  the bottom edge;
* closures (:func:`lift_off_lid`, :func:`stopper`, :func:`screw_cap`,
  :func:`crown_cap`, :func:`capsule`, :func:`jar_lid`, :func:`dome_lid`,
  :func:`hinged_lid`) have their ``seat`` anchor at the origin: attach it to the
  body's ``lid_seat``; :func:`seat_joint` then joins them (lift along the seat's z,
  turning about it for round closures);
* fittings: :func:`foot_ring` (``mount`` under a base), :func:`label_band`
  (``vessel``: glued on the body, pieces of it), :func:`lid_knob` / :func:`lid_loop` (``base`` on a lid's ``top``),
  :func:`side_handles` / :func:`long_handle` (``vessel``: they are built to fit
  one wall, in its frame) with :func:`handle_tip` / :func:`hanging_ring` at the
  handle's ``end``.

Walls are thin shells whose collision is exact flat-faced wedges (see
:func:`wedges`: PhysX snaps nearly coplanar hull faces and then reports deep false
contacts). Profiles are :class:`Profile`: a fine ``(radius, z)`` curve for the
visual mesh and a coarse envelope of it for the wedges. Dimensions come from
:mod:`.vessel_sizes`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.interpolate import PchipInterpolator

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

from . import hardware
from . import vessel_sizes as S
from .lids import (
    rimmed,
    seat_joint,  # noqa: F401  (the lid family's joint, used as V.seat_joint)
)


def _piece(pc: g.Piece, sheet: float | None = None, convex=None, name: str | None = None) -> g.Piece:
    """A copy of a piece with another sheet thickness, collision or name (pieces are not edited)."""
    return g.Piece(pc.vertices, pc.faces, pc.material, pc.convex if convex is None else convex,
                   pc.name if name is None else name, pc.sheet if sheet is None else sheet)


def _at(z: float) -> Frame:
    return Frame.at((0.0, 0.0, z))


def _supports(radius: float, z: float = 0.0, count: int = 4) -> dict[str, np.ndarray]:
    ang = 2 * np.pi * np.arange(count) / count
    return {f"foot_{i}": np.array([radius * math.cos(a), radius * math.sin(a), z]) for i, a in enumerate(ang)}


# ---------------------------------------------------------------------------
# profiles


def spline_profile(ctrl, n: int = 64, coarse: int = 10, min_band: float = 0.007
                   ) -> tuple[np.ndarray, np.ndarray]:
    """A smooth ``(radius, z)`` curve through control points, and a coarse envelope of it.

    The curve is a shape-preserving (PCHIP) spline of radius and height against the
    chord length of the control polygon, so it never overshoots (a flat run stays flat,
    heights stay increasing). Returns ``(fine, coarse)``: ``n`` evenly spaced samples plus
    every control point thinned to :data:`~infmob_usd.profiles.PROFILE_TOL`
    (:func:`~infmob_usd.geometry.simplify_profile`: the visual surface), and ``coarse`` bands
    evenly spaced along the curve, none shorter than ``min_band``, bands in a nearly straight
    run merged (:func:`~infmob_usd.geometry.collision_bands`), each raised just enough that its
    chord is nowhere inside the fine curve (the convex collision bands: no thin slivers, which
    upset PhysX contact generation, and small features such as threads are enveloped).
    """
    c = np.asarray(ctrl, float)
    t = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(c, axis=0), axis=1))]
    keep = np.r_[True, np.diff(t) > 1e-9]
    c, t = c[keep], t[keep]
    fr, fz = PchipInterpolator(t, c[:, 0]), PchipInterpolator(t, c[:, 1])

    def at(ts):
        ts = np.unique(np.round(ts, 12))
        return np.c_[fr(ts), fz(ts)]

    fine = g.simplify_profile(at(np.r_[np.linspace(0, t[-1], n), t]))
    k = int(max(1, min(coarse, t[-1] // min_band)))
    dense = at(np.linspace(0, t[-1], 40 * k + 1))
    dense[:, 0] = np.maximum(dense[:, 0], np.interp(dense[:, 1], fine[:, 1], fine[:, 0]))  # the thinned chords too
    col = _lifted(at(np.linspace(0, t[-1], k + 1)), dense)
    return fine, _lifted(g.collision_bands(col), dense)


def _lifted(col: np.ndarray, dense: np.ndarray) -> np.ndarray:
    """Collision band ends ``col`` with each band moved out just enough that its chord is nowhere
    inside the ``dense`` curve."""
    col = col.copy()
    for i in range(len(col) - 1):
        z0, z1 = col[i, 1], col[i + 1, 1]
        inside = dense[(dense[:, 1] >= z0) & (dense[:, 1] <= z1)]
        if z1 - z0 < 1e-9 or not len(inside):
            continue
        chord = np.interp(inside[:, 1], [z0, z1], [col[i, 0], col[i + 1, 0]])
        lift = max(0.0, float((inside[:, 0] - chord).max()))
        col[i, 0] += lift
        col[i + 1, 0] += lift
    return col


def sectors_for(radius: float, arc: float = 0.025, lo: int = 10, hi: int = 32) -> int:
    """Wedges round a wall: one per ``arc`` of circumference, ``lo`` to ``hi``."""
    return int(np.clip(np.ceil(2 * np.pi * radius / arc), lo, hi))


def wedges(outer, inner, sectors: int, phase: float = 0.0) -> list[np.ndarray]:
    """Convex collision pieces of a wall of revolution: one 8-corner wedge per band and sector.

    ``outer`` and ``inner`` are matching ``(p, 2)`` ``(radius, z)`` profiles. Only the
    corners are used, so every face of a wedge is exactly planar: hulls with extra,
    nearly coplanar arc points get their planes snapped by PhysX cooking, and its PCM
    contact generation then reports deep false contacts with hulls a few mm away.
    """
    return list(g.wedge_points(outer, inner, sectors, phase).reshape(-1, 8, 3))


@dataclass(frozen=True, eq=False)
class Profile:
    """A wall of revolution: ``fine`` (visual) and ``coarse`` (collision) outside ``(radius, z)``
    curves, bottom to top, its ``thickness`` and the wedge ``sectors`` round it."""

    fine: np.ndarray
    coarse: np.ndarray
    thickness: float
    sectors: int

    @classmethod
    def through(cls, ctrl, thickness: float, spline: tuple[int, int], r_min: float = 0.0,
                sectors: int | None = None) -> Profile:
        """The profile through control points (:func:`spline_profile`), no radius under ``r_min``."""
        fine, coarse = spline_profile(ctrl, n=spline[0], coarse=spline[1])
        fine[:, 0] = np.maximum(fine[:, 0], r_min)
        coarse[:, 0] = np.maximum(coarse[:, 0], r_min)
        return cls(fine, coarse, thickness, sectors or sectors_for(float(fine[:, 0].max())))

    @property
    def height(self) -> float:
        return float(self.fine[-1, 1])

    @property
    def top_radius(self) -> float:
        return float(self.fine[-1, 0])

    @property
    def base_radius(self) -> float:
        return float(self.fine[0, 0])

    def _zs(self, z0: float, z1: float) -> np.ndarray:
        f, c = self.fine, self.coarse
        return np.r_[np.linspace(z0, z1, 40), f[(f[:, 1] >= z0) & (f[:, 1] <= z1), 1],
                     c[(c[:, 1] >= z0) & (c[:, 1] <= z1), 1]]

    def free_radius(self, z0: float, z1: float) -> float:
        """The widest radius a plug may have inside the wall between heights z0 and z1.

        Takes the inner surface of both the visual and the collision profile (the chords of
        the coarse bands and of the convex wedges bulge inward) and returns its smallest
        radius over ``[z0, z1]``.
        """
        zs = self._zs(z0, z1)
        r = np.minimum(np.interp(zs, self.fine[:, 1], self.fine[:, 0]),
                       np.interp(zs, self.coarse[:, 1], self.coarse[:, 0]))
        return float((r.min() - self.thickness) * math.cos(math.pi / self.sectors))

    def outer_radius(self, z0: float, z1: float) -> float:
        """The largest outside radius of the wall (visual or collision) over ``[z0, z1]``."""
        zs = self._zs(z0, z1)
        return float(max(np.interp(zs, self.fine[:, 1], self.fine[:, 0]).max(),
                         np.interp(zs, self.coarse[:, 1], self.coarse[:, 0]).max()))

    def wall(self, slot: str, sheet: float = 0.0, name: str = "") -> g.Piece:
        """The thin wall: visual mesh from ``fine``, flat-faced convex wedges from ``coarse``."""
        vis = g.shell(self.fine, self.thickness, slot, convex_sectors=1, name=name)
        return _piece(vis, sheet=sheet).with_wedges(self.coarse, self.coarse - [self.thickness, 0], self.sectors)


def lid_gap(height: float) -> float:
    """Clearance of a lid or cap from its vessel: above max(1 mm, 2% of its smallest extent)."""
    return max(0.0015, 0.03 * height)


def sleeve(outer, thickness: float, material: str, r_in: float, sectors: int = 24,
           collision_thickness: float = 0.003, sections: int | None = None, name: str = "",
           collide: bool = True, sheet: float = 0.0) -> g.Piece:
    """A thin round sleeve (cap skirt, label band) around something of radius up to ``r_in``.

    The visual wall follows ``outer`` (``(radius, z)`` points, the inside ``thickness``
    further in); the collision is ``sectors`` chunky wedges per band (at least
    ``collision_thickness`` thick, growing outward) whose inner chords stay outside
    ``r_in``. ``collide=False`` leaves the sleeve without collision (decoration).

    Why caps and lids use ``collide=False`` for their skirts: in SAPIEN 3.0.3 (PhysX PCM
    contact generation, the default) a ring of skirt wedges 1.5 mm around the wedges of a
    threaded neck gets deep false contacts (-5..-10 mm reported for hulls 1.5..3 mm
    apart) that jam the turn and lift; with PCM off they vanish. The skirt is then drawn
    but the cap collides through its top plate only. (A label band, one tall band of
    wedges, is not affected and keeps its collision.)
    """
    outer = np.asarray(outer, float)
    vis = g.shell(outer, thickness, material, sections=sections, convex_sectors=1, name=name)
    ri = r_in / math.cos(math.pi / sectors)
    zs = outer[[0, -1], 1]
    ring_out = np.c_[np.full(2, ri + collision_thickness), zs]
    col = wedges(ring_out, ring_out - [collision_thickness, 0], sectors) if collide else []
    return g.Piece(vis.vertices, vis.faces, material, col, name, sheet)


def _turned_z(points: np.ndarray, angle: float) -> np.ndarray:
    return Frame.at().turned("z", angle).point(points)


def polygon_wall(profile, thickness: float, sides: int, material: str, name: str = "") -> g.Piece:
    """A thin wall with ``sides`` flat faces (faces normal to +X first), open at both ends.

    ``profile`` is ``(p, 2)`` of ``(apothem, z)``: the distance of the outside faces from
    the axis. Each face of each band is one convex piece (its eight corners), so the
    wall is hollow and flat, with no bulging arcs.
    """
    prof = np.asarray(profile, float)
    k = 1.0 / math.cos(math.pi / sides)
    outer = prof * [k, 1.0]
    inner = (prof - [thickness, 0.0]) * [k, 1.0]
    closed = np.vstack([outer, inner[::-1], outer[:1]])
    mesh = trimesh.creation.revolve(closed, sections=sides)
    if mesh.volume < 0:
        mesh.invert()
    ang = math.pi / sides + 2 * math.pi * np.arange(sides + 1) / sides  # the corners
    convex = []
    for i in range(len(prof) - 1):
        for s in range(sides):
            pts = []
            for r, z in (outer[i], outer[i + 1], inner[i], inner[i + 1]):
                for a in (ang[s], ang[s + 1]):
                    pts.append((r * math.cos(a), r * math.sin(a), z))
            convex.append(np.array(pts))
    return g.Piece(_turned_z(mesh.vertices, math.pi / sides), mesh.faces, material, convex, name)


def _polygon_plate(R: float, sides: int, r_hole: float, z0: float, z1: float, slot: str) -> g.Piece:
    """The flat shoulder of a polygonal jar: the polygon (apothem ``R``) with a round hole."""
    k = 1.0 / math.cos(math.pi / sides)
    prism = trimesh.creation.cylinder(radius=R * k, height=z1 - z0, sections=sides)
    prism.vertices = _turned_z(prism.vertices, math.pi / sides)
    prism.apply_translation((0, 0, (z0 + z1) / 2))
    hole = trimesh.creation.cylinder(radius=r_hole, height=(z1 - z0) + 0.01, sections=g.sections_for(r_hole))
    hole.apply_translation((0, 0, (z0 + z1) / 2))
    mesh = g.subtract(prism, [hole])
    convex = []
    per_side = 6
    for s in range(sides):
        face = 2 * math.pi * s / sides
        th = face + np.linspace(-math.pi / sides, math.pi / sides, per_side + 1)
        for a0, a1 in zip(th[:-1], th[1:]):
            pts = []
            for a in (a0, a1):
                d = R / math.cos(a - face)
                for z in (z0, z1):
                    pts += [(d * math.cos(a), d * math.sin(a), z), (r_hole * math.cos(a), r_hole * math.sin(a), z)]
            convex.append(np.array(pts))
    return g.Piece(mesh.vertices, mesh.faces, slot, convex)


def _polygon_floor(apothem: float, height: float, sides: int, slot: str) -> g.Piece:
    """A ``sides``-gon floor slab (faces normal to +X first), one hull."""
    floor = g.cylinder((0, 0, 0), (0, 0, height), apothem / math.cos(math.pi / sides), slot, sides)
    v = _turned_z(floor.vertices, math.pi / sides)
    return g.Piece(v, floor.faces, slot, [v])


# ---------------------------------------------------------------------------
# bodies


def _body(pieces, profile_height: float, base_radius: float, seat: float | None = None,
          neck_top: float | None = None, label: str = "body") -> Assembly:
    anchors = {"base": IDENTITY, "rim": _at(profile_height), "lid_seat": _at(profile_height if seat is None else seat)}
    if neck_top is not None:
        anchors["neck_top"] = _at(neck_top)
    return Assembly.single(label, pieces, anchors, _supports(base_radius))


def vase_body(shape, height: float, radius: float, wall: float, jitter, slot: str,
              sheet: float = 0.0, stand: float = 0.0) -> tuple[Assembly, Profile]:
    """A vase: a thin wall through ``shape`` (``(radius / radius, z / height)`` points, each radius
    scaled by ``1 + jitter[i]``) on a bottom disc. Returns the body and its wall profile. ``stand``:
    the smallest base radius as a share of the widest control radius (the bottom two control points
    are widened to it, so the vase stands on a foot at least that wide)."""
    r_min = wall + S.VASE_NECK_ROOM
    ctrl = [(max(r_min, min(radius, f * (1.0 + j) * radius)), u * height) for (f, u), j in zip(shape, jitter)]
    if stand > 0:
        widest = max(r for r, _ in ctrl)
        ctrl[:2] = [(max(r, stand * widest * (1.0 + 0.03 * i)), z) for i, (r, z) in enumerate(ctrl[:2])]
    prof = Profile.through(ctrl, wall, S.VASE_SPLINE, r_min=r_min)
    tb = S.BOTTOM_RATIO * wall
    bottom = _piece(g.disc((0, 0, tb / 2), prof.base_radius - 0.3 * wall, tb, slot, None), sheet=sheet)
    return _body([prof.wall(slot, sheet), bottom], prof.height, prof.base_radius), prof


def foot_ring(body: Profile, slot: str) -> Assembly:
    """A foot ring glued under the base of wall ``body`` (``mount`` at its top centre, the ring just below)."""
    f = S.FOOT
    radius = body.base_radius - f["inset"] * body.thickness
    top = -f["gap"]
    ring = g.shell([(radius, top - f["height"]), (radius, top)], min(f["width"], f["width_ratio"] * radius), slot)
    return Assembly.single("stand", [ring], {"mount": IDENTITY}, _supports(radius, top - f["height"]))


def bottle_profile(kind: str, finish: str, height: float, radius: float, wall: float) -> Profile:
    """A bottle's outside: ``kind``'s body outline (:data:`.vessel_sizes.BOTTLE_BODIES`) up to
    its neck, then the glass finish of closure ``finish`` (:data:`.vessel_sizes.FINISHES`)."""
    neck = max(S.BOTTLE_KINDS[kind][1] * radius, wall + S.BOTTLE_NECK_ROOM)
    fin = np.asarray(S.FINISHES[finish], float)
    z_n = height - float(fin[-1, 1])
    ctrl = [(neck if f is None else f * radius, min(u * height, z_n - S.NECK_FINISH_ROOM) if f is None else u * height)
            for f, u in S.BOTTLE_BODIES[kind]]
    ctrl[-1] = (ctrl[-1][0] * S.NECK_TAPER, ctrl[-1][1])
    ctrl += [(neck + dr, z_n + dz) for dr, dz in fin]
    return Profile.through(ctrl, wall, S.BOTTLE_SPLINE, sectors=sectors_for(radius, 0.02, 12))


def _finish_bottom(neck: Profile, finish: str) -> float:
    """Where the glass finish of closure ``finish`` begins on a bottle profile."""
    return neck.height - S.FINISHES[finish][-1][1]


def bottle_body(prof: Profile, punt: float, slot: str, finish: str) -> Assembly:
    """A bottle: the glass wall on a flat bottom, or a push-up punt ``punt`` deep (visual) on a flat
    collision disc. ``neck_top`` is where the glass finish (of closure ``finish``) begins."""
    t = prof.thickness
    rb = prof.base_radius - S.BOTTLE_BOTTOM["inset"] * t
    tb = S.BOTTLE_BOTTOM["thickness"] * t
    flat = g.disc((0, 0, tb / 2), rb, tb, slot, None)
    bottom = flat
    if punt > 0:
        hp = max(punt, 2 * tb)
        prof_pts = [*[(f * rb, u * hp) for f, u in S.PUNT], (rb, 0.0), (rb, tb),
                    *[(f * rb, tb + u * hp) for f, u in S.PUNT_TOP], (0.0, hp + tb)]
        bottom = g.revolve(prof_pts, slot).with_collision_of(flat)
    return _body([prof.wall(slot), bottom], prof.height, prof.base_radius, neck_top=_finish_bottom(prof, finish))


def threaded_neck(radius: float, z0: float, z1: float, threads: bool = True) -> list[tuple[float, float]]:
    """Outside points of a jar neck of ``radius`` from z0 to z1: two thread rings and a rolled lip
    (``threads=False``: a plain neck with a bead lip, for clip-top, hinged and stopper jars)."""
    h = z1 - z0
    if not threads:
        return [(radius, z0), (radius, z1 - 0.35 * h), (radius + 0.8 * S.THREAD, z1 - 0.2 * h),
                (radius + 0.8 * S.THREAD, z1 - 0.06 * h), (radius + 0.3 * S.THREAD, z1)]
    pts = [(radius, z0), (radius, z0 + 0.18 * h)]
    for c in (0.38, 0.66):
        pts += [(radius + S.THREAD, z0 + (c - 0.04) * h), (radius + S.THREAD, z0 + (c + 0.04) * h),
                (radius, z0 + (c + 0.15) * h)]
    pts += [(radius + 0.4 * S.THREAD, z1 - 0.08 * h), (radius + 0.2 * S.THREAD, z1)]
    return pts


def round_jar_body(height: float, radius: float, wall: float, neck_ratio: float, shoulder: float,
                   neck_height: float, slot: str, threads: bool = True) -> tuple[Assembly, Profile]:
    """A round jar: body, rounded shoulder and threaded (or plain) neck in one thin wall on a bottom disc."""
    n = max(neck_ratio * radius, wall + S.JAR_NECK_ROOM)
    z_neck = height - neck_height
    z_sh = z_neck - shoulder * height
    rise = z_neck - z_sh
    ctrl = [(f * radius, z) for f, z in S.JAR_FOOT] + [
        (radius, z_sh), (0.97 * radius, z_sh + 0.3 * rise),
        (0.5 * (radius + n) + 0.1 * (radius - n), z_sh + 0.7 * rise), (n * 1.01, z_neck - 0.0015)]
    prof = Profile.through(ctrl + threaded_neck(n, z_neck, height, threads), wall, S.JAR_SPLINE,
                           sectors=sectors_for(radius, 0.02, 12))
    tb = S.BOTTOM_RATIO * wall
    bottom = g.disc((0, 0, tb / 2), prof.base_radius - 0.3 * wall, tb, slot, None)
    return _body([prof.wall(slot), bottom], height, prof.base_radius, neck_top=z_neck), prof


def polygon_jar_body(height: float, radius: float, sides: int, wall: float, neck_ratio: float,
                     neck_height: float, slot: str, threads: bool = True) -> tuple[Assembly, Profile]:
    """A square or hexagonal jar: flat panels, a flat shoulder plate with a round hole and a round
    threaded neck on top (its profile is returned: closures fit it)."""
    n = max(neck_ratio * radius, wall + S.JAR_NECK_ROOM)
    z_neck = height - neck_height
    tp = max(wall, S.POLY_SHOULDER)
    z_sh = z_neck - S.POLY_SHOULDER
    panels = polygon_wall([(f * radius, z) for f, z in S.POLY_FOOT] + [(radius, z_sh)], wall, sides, slot)
    plate = _polygon_plate(radius, sides, n - 0.6 * wall, z_sh - tp, z_sh, slot)
    neck = Profile.through([(n, z_sh - 0.5 * tp)] + threaded_neck(n, z_neck, height, threads), wall, S.JAR_NECK_SPLINE,
                           sectors=24)
    floor = _polygon_floor(0.999 * (radius - wall), S.BOTTOM_RATIO * wall, sides, slot)
    return _body([panels, plate, floor, neck.wall(slot)], height, radius, neck_top=z_neck), neck


# ---------------------------------------------------------------------------
# closures (seat anchor at the origin)


def _closure(label: str, pieces, seat_z: float, top_z: float) -> Assembly:
    """A closure built in its vessel's frame, moved so that its seat (height ``seat_z``) is the origin."""
    a = rimmed(Assembly.single(label, pieces, {"seat": _at(seat_z), "top": _at(top_z)}))
    return a.placed(a.anchor("seat").inverse())


def _plug_pieces(z_seat, r_flange, t_flange, r_plug, plug_depth, dome, r_knob, slot, gap, sheet):
    zb = z_seat + gap
    zt = zb + t_flange
    dome_h = dome * r_flange
    ctrl = [(r_flange, zb), (r_flange, zt), (0.85 * r_flange, zt + 0.55 * dome_h),
            (0.5 * r_flange, zt + 0.92 * dome_h), (max(r_knob * 0.7, 0.2 * r_flange), zt + dome_h)]
    z_top = zt + dome_h
    knob = [(0.7 * r_knob, z_top + 0.25 * r_knob), (r_knob, z_top + 0.9 * r_knob),
            (0.8 * r_knob, z_top + 1.5 * r_knob), (0.3 * r_knob, z_top + 1.85 * r_knob)]
    cap, cap_col = spline_profile(ctrl + knob, n=40, coarse=6)
    top = z_top + 1.9 * r_knob
    # a solid plug (PhysX contact generation is more reliable on chunky hulls than on thin wedges)
    plug = [[0.0, z_seat - plug_depth], [r_plug, z_seat - plug_depth], [r_plug, zb]]
    vis = _piece(g.revolve(np.vstack([plug, cap, [0.0, top]]), slot), sheet=sheet)
    return [vis.with_collision_of(g.revolve(np.vstack([plug, cap_col, [0.0, top]]), slot, sections=8))], top


def _plug_lid(mouth: Profile, r_flange, t_flange, plug_depth, dome, r_knob, slot, sheet, label="lid") -> Assembly:
    H = mouth.height
    gap = lid_gap(plug_depth + t_flange + dome * r_flange + 1.9 * r_knob)
    r_plug = mouth.free_radius(H - plug_depth - S.LIFT_OFF_LID["plug_room"], H) - gap
    pieces, top = _plug_pieces(H, r_flange, t_flange, r_plug, plug_depth, dome, r_knob, slot, gap, sheet)
    return _closure(label, pieces, H, top)


def lift_off_lid(mouth: Profile, overhang: float, dome: float, slot: str, sheet: float = 0.0) -> Assembly:
    """A vase lid: a flange ``overhang`` past the rim, a dome (``dome`` x flange radius) with a
    finial, and a solid plug reaching into the mouth with clearance from the wall. It rests a
    small gap above the rim (the seat)."""
    L = S.LIFT_OFF_LID
    r_flange = mouth.top_radius + overhang
    a, b, lo, hi = L["flange"]
    plug = float(np.clip(L["plug_depth"][0] * mouth.height, *L["plug_depth"][1:]))
    knob = float(np.clip(L["knob"][0] * r_flange, *L["knob"][1:]))
    return _plug_lid(mouth, r_flange, float(np.clip(a * r_flange + b, lo, hi)), plug, dome, knob, slot, sheet)


def stopper(mouth: Profile, slot: str) -> Assembly:
    """A bottle stopper (a cork with a domed wooden top): the :func:`lift_off_lid` shape with the
    proportions of :data:`.vessel_sizes.STOPPER`; solid wood (no sheet)."""
    s = S.STOPPER
    r_flange = mouth.top_radius + s["overhang"]
    knob = float(np.clip(s["knob"][0] * r_flange, *s["knob"][1:]))
    return _plug_lid(mouth, r_flange, s["flange"], s["depth"], s["dome"], knob, slot, 0.0, label="cap")


def _top_hull(r_plate: float, z0: float, z1: float, r_button: float, z2: float, sides: int = 16) -> np.ndarray:
    """Points of a lid's collision hull: a ``sides``-gon plate (z0..z1) under a button top at z2."""
    a = 2 * np.pi * np.arange(sides) / sides
    cs, sn = np.cos(a), np.sin(a)
    return np.vstack([np.c_[r * cs, r * sn, np.full(sides, z)]
                      for r, z in ((r_plate, z0), (r_plate, z1), (r_button, z2))])


def _sleeve_cap(neck: Profile, z_lo: float, skirt: float, top_t: float, overhang: float, slot: str,
                sheet: float, flare=None, flutes: int | None = None, button: tuple[float, float] | None = None,
                gap: float | None = None) -> tuple[list[g.Piece], float, float]:
    """A skirt around a neck from ``z_lo`` up (drawn, no collision: see :func:`sleeve`) under a top
    plate a small gap above the lip. Returns the pieces, the skirt's outer radius and the plate top."""
    H = neck.height
    gap = lid_gap(H - z_lo) if gap is None else gap
    r_in = neck.outer_radius(z_lo - 0.0005, H) + gap
    r_out = r_in + skirt
    z_top = H + gap
    prof = [(r_out, z_lo), (r_out, z_top + 0.5 * top_t)]
    if flare is not None:
        prof = [(r_out + dr, z_lo + dz) for dr, dz in flare] + prof[1:]
    pieces = [sleeve(prof, skirt, slot, r_in, sectors=32 if button else 24, sections=flutes, collide=False,
                     sheet=sheet)]
    r_top = r_out + overhang
    top = g.disc((0, 0, z_top + top_t / 2), r_top, top_t, slot, None)
    if button is None:
        pieces.append(_piece(top, sheet=sheet))
        return pieces, r_out, z_top + top_t
    # a raised centre panel (the button of a mason lid) on the top plate. One collision hull for
    # plate and button, with few, exactly planar faces: a separate button hull hovers over the
    # neck's rim wedges with its edge right above their inner edge, where PhysX PCM builds the
    # manifold on the button's top face and reports a deep false contact (-(gap + button
    # height), ~-6 mm) that jams the turn (jar seed 61). The plate's flat bottom covers the
    # whole rim, a robust face contact.
    ratio, bh = button
    zb = z_top + top_t + bh
    btn = g.disc((0, 0, z_top + top_t + bh / 2 - 0.00005), ratio * r_in, bh, slot, None)
    pieces += [_piece(top, sheet=sheet, convex=[_top_hull(r_top, z_top, z_top + top_t, ratio * r_in, zb - 0.00005)]),
               _piece(btn, sheet=sheet, convex=[])]
    return pieces, r_out, zb


def screw_cap(neck: Profile, slot: str) -> Assembly:
    """A PCO screw cap on a bottle's screw finish: a plastic skirt over the threads under a flat top."""
    c = S.SLEEVE_CAPS["screw"]
    pieces, _, top = _sleeve_cap(neck, _finish_bottom(neck, "screw") + c["skirt_from"], c["skirt"], c["top"],
                                 c["overhang"], slot, c["sheet"])
    return _closure("cap", pieces, neck.height, top)


def crown_cap(neck: Profile, slot: str) -> Assembly:
    """A crown cap on a crown finish: a tinplate top with a skirt of 21 crimped flutes flaring at its edge."""
    c = S.SLEEVE_CAPS["crown"]
    pieces, _, top = _sleeve_cap(neck, _finish_bottom(neck, "crown") + c["skirt_from"], c["skirt"], c["top"],
                                 c["overhang"], slot, c["sheet"], flare=S.CROWN_FLARE, flutes=S.CROWN_FLUTES)
    return _closure("cap", pieces, neck.height, top)


def capsule(neck: Profile, champagne: bool, slot: str, cork_slot: str) -> Assembly:
    """A foil capsule over a cork finish; on champagne a long one under a mushroom cork head."""
    c, k = S.SLEEVE_CAPS["capsule"], S.CAPSULE
    H = neck.height
    length = (k["champagne"] if champagne else k["length"]) * H / k["per_height"]
    z_lo = max(H - length, _finish_bottom(neck, "capsule") - k["below_finish"])
    pieces, r_out, top = _sleeve_cap(neck, z_lo, c["skirt"], c["top"], c["overhang"], slot, c["sheet"])
    if champagne:  # the mushroom cork head under the foil: one hull
        rc = r_out + S.MUSHROOM["grow"]
        head = g.revolve([(f * rc, top + dz) for f, dz in S.MUSHROOM["profile"]], cork_slot)
        pieces.append(_piece(head, convex=[np.vstack(head.convex)]))
        top += S.MUSHROOM["profile"][-1][1]
    return _closure("cap", pieces, H, top)


def jar_lid(neck: Profile, neck_height: float, height: float, plastic: bool, slot: str) -> Assembly:
    """A mason jar screw lid ``height`` tall on a threaded neck ``neck_height`` tall: a skirt round the
    threads and a top plate with a raised button, plate and button colliding as one flat-faced hull."""
    L = S.JAR_LID
    H = neck.height
    gap = lid_gap(height)
    z_lo = max(H - height + gap, H - (1 - L["reach"]) * neck_height)
    pieces, _, top = _sleeve_cap(neck, z_lo, L["skirt_plastic" if plastic else "skirt_metal"], L["top"],
                                 L["overhang"], slot, 0.0 if plastic else L["sheet"],
                                 button=(L["button"], L["button_height"]), gap=gap)
    return _closure("lid", pieces, H, top)


def hinged_lid(radius: float, thickness: float, hinge_offset: float, slot: str, knob: float = 0.0) -> Assembly:
    """A flat round lid hinged at its back edge (a swing-top or kettle lid): ``main`` is the hinge
    knuckle's carrier, ``lid`` turns 0..~110 degrees about the ``hinge`` anchor (y axis along the
    hinge line, at -X) and rests closed on its seat at the origin."""
    plate = g.disc((0, 0, thickness / 2), radius, thickness, slot, None)
    pieces = [plate]
    if knob > 0:
        pieces += hardware.knob_handle(knob, 1.6 * knob, slot).placed(Frame.at((radius * 0.75, 0, thickness))).pieces
    hinge = Frame.at((-radius - hinge_offset, 0.0, thickness / 2), z=(0, -1, 0), x=(1, 0, 0))
    knuckle = g.cylinder(hinge.point((0, 0, -radius / 3)), hinge.point((0, 0, radius / 3)),
                         thickness / 2, slot, 16)
    carrier = Assembly.single("hinge", [knuckle], name="main")
    lid = Assembly.single("lid", pieces, name="lid")
    both = carrier.merged(lid)
    return rimmed(Assembly(both.parts, (J.revolute("main", "lid", tuple(hinge.origin), tuple(hinge.z), 0.0,
                                                   math.radians(110), role="lid"),),
                           {"seat": IDENTITY, "hinge": hinge, "top": _at(thickness)}, {}), "lid")


def label_band(prof: Profile, zone: tuple[float, float], fill: float, offset: float, slot: str) -> Assembly:
    """A paper label round a bottle's straight part: ``fill`` of the ``zone`` (z0, z1) tall, at
    ``offset`` (0 bottom, 1 top) within it, glued on the glass (a glue film off its widest radius there):
    pieces of the body, not a part that turns. Built in the bottle's frame (anchor ``vessel``); ``axis``
    at its centre."""
    L = S.LABEL
    z0, z1 = zone
    h = fill * (z1 - z0)
    zl = z0 + offset * (z1 - z0 - h)
    r_in = prof.outer_radius(zl - 0.001, zl + h + 0.001) + L["glue"]
    t = L["thickness"]
    band = sleeve([(r_in + t, zl), (r_in + t, zl + h)], t, slot, r_in, sectors=L["sectors"],
                  collision_thickness=L["collision"], sheet=L["paper"])
    return Assembly.single("label", [band], {"vessel": IDENTITY, "axis": _at(zl + h / 2)})


# ---------------------------------------------------------------------------
# cookware (pot, pan): rolled-rim vessel, dome lid, handles


def wall_profile(r_top: float, depth: float, corner: float, flare: float, z_start: float,
                 n_arc: int = 10) -> np.ndarray:
    """Outer ``(radius, z)`` points of a cookware wall, bottom to top.

    A quarter-ish arc of radius ``corner`` round the bottom corner (tangent to the floor
    at z = 0), then a straight side at ``flare`` radians from vertical up to ``(r_top,
    depth)``. The points start where the arc is at height ``z_start`` (the top of the
    bottom piece), so the wall never has a flat, paper-thin band.
    """
    sb, cb = math.sin(flare), math.cos(flare)
    a = r_top - (depth - corner * (1 - sb)) * math.tan(flare) - corner * cb
    phi0 = math.acos(1 - z_start / corner)
    phis = np.linspace(phi0, math.pi / 2 - flare, n_arc)
    pts = [(a + corner * math.sin(f), corner * (1 - math.cos(f))) for f in phis]
    pts.append((r_top, depth))
    return np.array(pts)


@dataclass(frozen=True, eq=False)
class Cookware:
    """What lids and handles need to know of a cookware body (its local frame)."""

    profile: np.ndarray  # outer wall (radius, z)
    rim_top: float
    rim_outer: float
    rim_inner: float
    rim_bottom: float
    floor: float
    floor_radius: float
    wall: float

    def radius_at(self, z):
        """Outer wall radius at height(s) ``z`` (clamped to its ends)."""
        return np.interp(z, self.profile[:, 1], self.profile[:, 0])

    @property
    def lid_radius(self) -> float:
        return self.rim_outer + S.LID_RIM_REACH


def cookware_body(r_top: float, depth: float, corner: float, flare: float, wall: float, bottom: float,
                  bead: float, slot: str, rim_slot: str, coating: str = "") -> tuple[Assembly, Cookware]:
    """A hollow pot or pan: a bottom following the corner, a thin wall and a rolled rim (a bead
    curling outward); with ``coating`` a thin non-stick disc on the floor. ``lid_seat`` is
    :data:`.vessel_sizes.LID_GAP` above the rim."""
    corner = max(corner, 2.5 * bottom)
    z_wall_top = depth - bead  # the wall ends in the middle of the bead
    fine = wall_profile(r_top, z_wall_top, corner, flare, bottom, 12)
    coarse = wall_profile(r_top, z_wall_top, corner, flare, bottom, 5)
    arc = wall_profile(r_top, z_wall_top, corner, flare, 1e-6, 40)
    arc = arc[arc[:, 1] <= bottom + 1e-9]
    r0, a = float(fine[0, 0]), float(arc[0, 0])
    prof = np.vstack([[0.0, 0.0], [a, 0.0], arc[1:], [r0, bottom], [r0 - wall, bottom], [0.0, bottom]])
    prof = prof[np.r_[True, np.linalg.norm(np.diff(prof, axis=0), axis=1) > 1e-7]]
    base = g.revolve(g.simplify_profile(prof), slot)
    ang = np.linspace(0.0, 2 * np.pi, 32, endpoint=False)
    ring = np.c_[np.cos(ang), np.sin(ang)]
    puck = np.vstack([np.c_[ring * a, np.zeros(32)], np.c_[ring * r0, np.full(32, bottom)]])
    base = _piece(base, convex=[puck])  # one convex puck
    body_wall = g.shell(fine, wall, slot).with_collision_of(g.shell(coarse, wall, slot, sections=8))
    cx, cz = r_top - wall + bead, z_wall_top
    th = np.linspace(0.0, math.pi, 13)
    outer = np.c_[cx + bead * np.sin(th), cz - bead * np.cos(th)]
    box = g.shell([(cx + bead, cz - bead), (cx + bead, cz + bead)], 2 * bead, rim_slot, sections=8)
    rim = g.shell(outer, bead, rim_slot).with_collision_of(box)
    pieces = [base, body_wall, rim]
    info = Cookware(fine, depth, cx + bead, r_top - wall, cz - bead, bottom, r0 - wall, wall)
    if coating:
        pieces.append(g.disc((0, 0, bottom + 0.0003), info.floor_radius - 0.001, 0.0006, coating, None))
    return _body(pieces, depth, a, seat=depth + S.LID_GAP), info


def frying_pan_body(r_top: float, depth: float, flare: float, corner_ratio: float, wall: float, bottom: float,
                    bead: float, slot: str, coating: str = "") -> tuple[Assembly, Cookware]:
    """A frying pan: :func:`cookware_body` with a wide flat floor (the wall flares out by at most a
    quarter of the radius, the corner radius is ``corner_ratio`` x depth up to 0.15 x radius: a
    frying pan, not a wok)."""
    f = S.PAN_FLAT
    flare = min(flare, math.atan(f["flare_reach"] * r_top / depth))
    corner = min(corner_ratio * depth, f["corner"] * r_top)
    return cookware_body(r_top, depth, corner, flare, wall, bottom, bead, slot, slot, coating)


@dataclass(frozen=True, eq=False)
class Dome:
    """A dome lid's shape in its seat frame: radius, rise and wall thickness."""

    radius: float
    rise: float
    thickness: float

    def under(self, r):
        """z of the dome's underside at radius ``r``."""
        return self.rise * (1 - (np.asarray(r) / self.radius) ** 2)


def dome_lid(pot: Cookware, rise: float, thickness: float, slot: str, band_slot: str) -> tuple[Assembly, Dome]:
    """A shallow dome wider than the rim with a metal band round its edge, seated (origin) at its
    underside edge; ``top`` is the crown of the dome. No lip reaches into the opening: the joint
    keeps it centred (thin lip hulls next to the rim made PhysX spin the lid)."""
    d = Dome(pot.lid_radius, rise, thickness)
    r_l, t = d.radius, thickness
    rs = np.linspace(0.0, r_l, 24)
    prof = np.vstack([np.c_[rs, d.under(rs)], np.c_[rs[::-1], d.under(rs[::-1]) + t]])
    mesh = g.revolve(g.simplify_profile(prof), slot)
    # one convex cap from a coarse sample (PhysX keeps at most 255 hull vertices)
    ang = np.linspace(0.0, 2 * np.pi, 24, endpoint=False)
    cap = [(0.0, 0.0, float(d.under(0.0)) + t)]
    for rr in (r_l, 0.85 * r_l, 0.65 * r_l, 0.4 * r_l):
        zz = float(d.under(rr)) + (t if rr < r_l else 0.0)
        cap += [(rr * math.cos(a), rr * math.sin(a), zz) for a in ang]
    cap += [(r_l * math.cos(a), r_l * math.sin(a), t) for a in ang]
    b = S.LID_BAND
    band = g.shell([(r_l + b["out"], 0.0), (r_l + b["out"], t + b["height"])], b["thickness"], band_slot,
                   convex_sectors=b["sectors"])
    lid = rimmed(Assembly.single("lid", [_piece(mesh, convex=[np.array(cap)]), band],
                                 {"seat": IDENTITY, "top": _at(rise + t)}))
    return lid, d


def lid_knob(radius: float, slot: str) -> Assembly:
    """A round knob (stem and cap) standing on ``base``, sunk 1 mm into what carries it."""
    knob = hardware.knob_handle(radius, max(0.02, 1.2 * radius), slot).placed(Frame.at((0, 0, -0.001)))
    return Assembly.single("handle", knob.pieces, {"base": IDENTITY}, {"stem": (0, 0, -0.001)})


def lid_loop(dome: Dome, knob_radius: float, slot: str) -> Assembly:
    """A loop along Y on two posts rising from the dome, ``base`` at the dome's crown."""
    L = S.LID_LOOP
    length = min(L["reach"] * dome.radius, max(L["min"], L["per_knob"] * knob_radius))
    top = dome.rise + dome.thickness
    yp = length / 2 - L["inset"]
    pieces = []
    for s in (-1, 1):
        zb = float(dome.under(yp)) + dome.thickness - L["sink"] - top
        pieces.append(g.cylinder((0, s * yp, zb), (0, s * yp, L["rise"]), L["post"], slot, 16, name="handle"))
    pieces.append(g.cylinder((0, -length / 2, L["rise"]), (0, length / 2, L["rise"]), L["radius"], slot, 20,
                             name="handle"))
    return Assembly.single("handle", pieces, {"base": IDENTITY})


def side_handles(pot: Cookware, length: float, radius: float, reach: float, slot: str) -> Assembly:
    """Two loop handles at +-Y (a bar along X on two posts into the wall) below the rim, built in
    the vessel's frame (anchor ``vessel``); ``mount_left`` / ``mount_right`` on the wall."""
    h = S.SIDE_HANDLE
    zh = pot.rim_bottom - h["under_rim"] - radius
    r = float(pot.radius_at(zh))
    xp = length / 2 - min(h["inset"][0], h["inset"][1] * length)
    yin = math.sqrt(r * r - xp * xp) - h["into_wall"] * pot.wall
    pieces, anchors = [], {"vessel": IDENTITY}
    for s, side in ((1, "left"), (-1, "right")):
        mount = Frame.at((0.0, s * yin, zh), x=(0, s, 0))
        anchors[f"mount_{side}"] = mount
        size = hardware.HandleSize(standoff=(r - yin) + reach, bar_radius=radius, post_radius=0.8 * radius,
                                   inset=h["inset"][0])
        pieces += hardware.bar_handle(length, slot, size).placed(Frame.at(mount.origin, z=mount.x, x=(1, 0, 0))).pieces
    return Assembly.single("handle", pieces, anchors)


def _section(frame: Frame, half_v: float, half_w: float, chamfer: float = 0.35) -> np.ndarray:
    """Eight points of a chamfered rectangle in ``frame``'s y (half ``half_v``) / z (``half_w``) plane."""
    cv, cw = half_v * chamfer, half_w * chamfer
    uv = [(half_v, half_w - cw), (half_v - cv, half_w), (-half_v + cv, half_w), (-half_v, half_w - cw),
          (-half_v, -half_w + cw), (-half_v + cv, -half_w), (half_v - cv, -half_w), (half_v, -half_w + cw)]
    return frame.point([(0.0, a, b) for a, b in uv])


def _hull(points, slot: str) -> g.Piece:
    return g.from_trimesh(g.convex_hull(np.asarray(points, float)), slot, name="handle")


def handle_root(pot: Cookware, width: float, thickness: float) -> tuple[float, float, np.ndarray]:
    """Where a long handle meets the wall: its thickness (at most a share of the wall below the rim),
    the height of its centre and the (8, 3) points of its root, half a wall inside the outer surface."""
    L = S.LONG_HANDLE
    thickness = min(thickness, L["depth_share"] * (pot.rim_bottom - S.HANDLE_RIM_CLEAR - pot.floor))
    zc = pot.rim_bottom - S.HANDLE_RIM_CLEAR - thickness / 2
    y = width / 2
    root = []
    for z in (zc - thickness / 2, zc + thickness / 2):
        x = math.sqrt(max(float(pot.radius_at(z)) ** 2 - y * y, 1e-6)) - 0.5 * pot.wall
        for s in (-1, 1):
            root += [(x, s * y * 0.999, z), (x, s * y * L["root_in"], z)]
    return thickness, zc, np.array(root)


def long_handle(pot: Cookware, length: float, angle: float, width: float, thickness: float, slot: str,
                end_room: float = 0.0) -> Assembly:
    """A long handle toward +X, in the vessel's frame (anchor ``vessel``): horizontal below the rim
    out past the lid's edge (its top 3 mm under the bead, so a lid lifting over the rim never meets
    it), then rising at ``angle``. It stops ``end_room`` short of ``length``: its ``end`` anchor (x
    along the handle, z across its thickness) carries a :func:`handle_tip` or a :func:`hanging_ring`."""
    L = S.LONG_HANDLE
    thickness, zc, root = handle_root(pot, width, thickness)
    x_knee = pot.lid_radius + L["clear"] + S.HANDLE_KNEE
    knee = Frame.at((x_knee, 0.0, zc))
    knee_pts = _section(knee, width / 2, thickness / 2)
    rise = knee.turned("-y", angle)
    rest = max(L["min_rest"], length - (x_knee - root[:, 0].min())) - end_room
    end = rise.moved(rest)
    half_end = L["widen"] * width
    pieces = [_hull(np.vstack([root, knee_pts]), slot),
              _hull(np.vstack([knee_pts, _section(end, half_end, L["tip"] * thickness)]), slot)]
    return Assembly.single("handle", pieces, {"vessel": IDENTITY, "mount": Frame.at((root[:, 0].min(), 0.0, zc)),
                                              "end": end},
                           {"grip": end.origin})


def handle_tip(width: float, thickness: float, slot: str) -> Assembly:
    """The rounded end of a long handle (``start`` meets the handle's ``end``)."""
    L = S.LONG_HANDLE
    half = L["widen"] * width
    dx, wide, thin = L["cap"]
    tip = _section(IDENTITY, half, L["tip"] * thickness)
    cap = _section(IDENTITY.moved(dx), wide * half, thin * thickness)
    return Assembly.single("handle", [_hull(np.vstack([tip, cap]), slot)], {"start": IDENTITY})


def hanging_ring(width: float, thickness: float, slot: str) -> tuple[Assembly, float]:
    """A ring round an elliptic hole to hang a pan by (``start`` meets the handle's ``end``),
    convex segments; returns it and its length along the handle."""
    L, R = S.LONG_HANDLE, S.HANGING_RING
    half = L["widen"] * width
    ring_w = max(R["ring"][0], R["ring"][1] * half)
    b_h = half - ring_w
    a_h = max(b_h * R["hole"][0], R["hole"][1])
    start = IDENTITY
    centre = np.array([a_h + 0.5 * ring_w, 0.0, 0.0])
    ht = 0.4 * thickness
    n = R["segments"]
    angles = np.linspace(0.0, 2 * math.pi, n + 1)
    pieces = []
    for k in range(n):
        pts = []
        for th in np.linspace(angles[k], angles[k + 1], 3):
            for ra, rb in ((a_h, b_h), (a_h + ring_w, b_h + ring_w)):
                p = centre + (ra * math.cos(th), rb * math.sin(th), 0.0)
                pts += [p + (0, 0, ht), p - (0, 0, ht)]
        pieces.append(_hull(pts, slot))
    return Assembly.single("handle", pieces, {"start": start}), 2 * a_h + 1.5 * ring_w
