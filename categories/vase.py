"""Vase: a hollow vessel of revolution with an optional lid that sits in its mouth.

The body is a thin wall of revolution (``g.shell``) whose outside follows a smooth
spline through the control points of one of six classic shapes (amphora, ginger jar,
bud vase, cylinder, bottle-neck, bowl), closed by a bottom disc, so it stays hollow for
the simulator and a lid can sit on its rim. The lid is a flange resting a small gap
above the rim, a domed top with a finial, and a solid plug that reaches into the mouth
with radial clearance from the wall; it turns freely about Z and lifts along +Z
(0..5 cm), resting on its seat at 0 (gravity holds it down).

This module also holds the profile helpers shared by ``bottle`` and ``jar``:
:func:`spline_profile` (a smooth (radius, z) curve through control points, and a
coarse subset of it for collisions), :func:`vessel_wall` (a shell whose visual mesh
follows the fine curve and whose convex pieces follow the coarse one),
:func:`polygon_wall` (the same for a wall with 4 or 6 flat sides) and
:func:`free_radius` (how wide a plug may be inside a wall between two heights).
"""

from __future__ import annotations

import math

import numpy as np
import trimesh
from scipy.interpolate import PchipInterpolator

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

GROWTH = Growth(
    vase=Rule(required=("body",), optional={"lid": 0.5},
              one_of={"amphora": 1.0, "ginger_jar": 1.0, "bud_vase": 1.0, "cylinder": 1.0,
                      "bottle_neck": 1.0, "bowl": 1.0}),
    lid=Rule(required=("flange", "plug", "finial")),
)
"""``vase.one_of`` is object-wide: the ``profile`` parameter (same weights)."""

_PROFILES = GROWTH.rules["vase"].one_of

SCHEMA = Schema((
    Float("height", "overall height of the body", "m", 0.2, 0.45),
    Float("diameter_ratio", "largest body diameter / height", "", 0.2, 0.4),
    Choice("profile", "body shape", choices=tuple(_PROFILES), weights=tuple(_PROFILES.values())),
    Choice("finish", "body and lid material", choices=("ceramic", "glass", "enamel"),
           weights=(0.55, 0.3, 0.15)),
    Float("wall", "wall thickness", "m", 0.003, 0.006),
    Float("shape_jitter", "random scale of each profile control radius (+-)", "", 0.0, 0.08),
    Float("lid_overhang", "lid flange overhang beyond the rim", "m", 0.002, 0.01),
    Float("lid_dome", "lid dome height / flange radius", "", 0.05, 0.45),
    *GROWTH.flags(),
))

LID_LIFT = 0.05  # m, lid lift range
SECTIONS = 64  # visual sections of every surface of revolution

# outside profiles as (radius / largest radius, z / height), bottom to top
SHAPES = {
    "amphora": [(0.45, 0.0), (0.5, 0.03), (0.8, 0.2), (1.0, 0.45), (0.9, 0.62), (0.55, 0.78),
                (0.42, 0.88), (0.45, 0.96), (0.55, 1.0)],
    "ginger_jar": [(0.6, 0.0), (0.66, 0.02), (0.9, 0.2), (1.0, 0.45), (0.95, 0.68), (0.72, 0.85),
                   (0.56, 0.9), (0.53, 0.94), (0.54, 1.0)],
    "bud_vase": [(0.7, 0.0), (0.8, 0.05), (1.0, 0.2), (0.85, 0.35), (0.42, 0.52), (0.32, 0.75),
                 (0.33, 0.94), (0.42, 1.0)],
    "cylinder": [(0.9, 0.0), (0.94, 0.02), (0.96, 0.5), (1.0, 0.97), (1.0, 1.0)],
    "bottle_neck": [(0.65, 0.0), (0.76, 0.03), (1.0, 0.2), (0.95, 0.4), (0.5, 0.58), (0.31, 0.7),
                    (0.29, 0.9), (0.35, 1.0)],
    "bowl": [(0.35, 0.0), (0.4, 0.04), (0.46, 0.2), (0.6, 0.5), (0.85, 0.8), (1.0, 1.0)],
}


# ---------------------------------------------------------------------------
# shared profile helpers (bottle and jar import these)


def spline_profile(ctrl, n: int = 64, coarse: int = 10, min_band: float = 0.007
                   ) -> tuple[np.ndarray, np.ndarray]:
    """A smooth ``(radius, z)`` curve through control points, and a coarse envelope of it.

    The curve is a shape-preserving (PCHIP) spline of radius and height against the
    chord length of the control polygon, so it never overshoots (a flat run stays flat,
    heights stay increasing). Returns ``(fine, coarse)``: ``n`` evenly spaced samples plus
    every control point (the visual surface), and ``coarse`` bands evenly spaced along the
    curve, none shorter than ``min_band``, each raised just enough that its chord is
    nowhere inside the fine curve (the convex collision bands: no thin slivers, which
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

    fine = at(np.r_[np.linspace(0, t[-1], n), t])
    k = int(max(1, min(coarse, t[-1] // min_band)))
    col = at(np.linspace(0, t[-1], k + 1))
    dense = at(np.linspace(0, t[-1], 40 * k + 1))
    for i in range(k):
        z0, z1 = col[i, 1], col[i + 1, 1]
        inside = dense[(dense[:, 1] >= z0) & (dense[:, 1] <= z1)]
        if z1 - z0 < 1e-9 or not len(inside):
            continue
        chord = np.interp(inside[:, 1], [z0, z1], [col[i, 0], col[i + 1, 0]])
        lift = max(0.0, float((inside[:, 0] - chord).max()))
        col[i, 0] += lift
        col[i + 1, 0] += lift
    return fine, col


def _sectors(radius: float) -> int:
    return int(np.clip(np.ceil(2 * np.pi * radius / 0.025), 10, 32))


def wedges(outer, inner, sectors: int, phase: float = 0.0) -> list[np.ndarray]:
    """Convex collision pieces of a wall of revolution: one 8-corner wedge per band and sector.

    ``outer`` and ``inner`` are matching ``(p, 2)`` ``(radius, z)`` profiles. Only the
    corners are used, so every face of a wedge is exactly planar: hulls with extra,
    nearly coplanar arc points get their planes snapped by PhysX cooking, and its PCM
    contact generation then reports deep false contacts with hulls a few mm away.
    """
    return list(g.wedge_points(outer, inner, sectors, phase).reshape(-1, 8, 3))


def vessel_wall(fine, coarse, thickness: float, material: str, sectors: int | None = None,
                name: str = "") -> g.Piece:
    """A thin wall of revolution: visual mesh from ``fine``, convex wedges from ``coarse``."""
    fine, coarse = np.asarray(fine, float), np.asarray(coarse, float)
    sectors = sectors or _sectors(float(fine[:, 0].max()))
    vis = g.shell(fine, thickness, material, sections=SECTIONS, convex_sectors=1, name=name)
    return vis.with_wedges(coarse, coarse - [thickness, 0], sectors)


def free_radius(fine, coarse, thickness: float, z0: float, z1: float, sectors: int | None = None) -> float:
    """The widest radius a plug may have inside a :func:`vessel_wall` between heights z0 and z1.

    Takes the inner surface of both the visual and the collision profile (the chords of
    the coarse bands and of the convex wedges bulge inward) and returns its smallest
    radius over ``[z0, z1]``.
    """
    fine, coarse = np.asarray(fine, float), np.asarray(coarse, float)
    sectors = sectors or _sectors(float(fine[:, 0].max()))
    zs = np.r_[np.linspace(z0, z1, 40), fine[(fine[:, 1] >= z0) & (fine[:, 1] <= z1), 1],
               coarse[(coarse[:, 1] >= z0) & (coarse[:, 1] <= z1), 1]]
    r = np.minimum(np.interp(zs, fine[:, 1], fine[:, 0]), np.interp(zs, coarse[:, 1], coarse[:, 0]))
    return float((r.min() - thickness) * math.cos(math.pi / sectors))


def outer_radius(fine, coarse, z0: float, z1: float) -> float:
    """The largest outside radius of a wall (visual or collision) over ``[z0, z1]``."""
    fine, coarse = np.asarray(fine, float), np.asarray(coarse, float)
    zs = np.r_[np.linspace(z0, z1, 40), fine[(fine[:, 1] >= z0) & (fine[:, 1] <= z1), 1],
               coarse[(coarse[:, 1] >= z0) & (coarse[:, 1] <= z1), 1]]
    return float(max(np.interp(zs, fine[:, 1], fine[:, 0]).max(), np.interp(zs, coarse[:, 1], coarse[:, 0]).max()))


def sleeve(outer, thickness: float, material: str, r_in: float, sectors: int = 24,
           collision_thickness: float = 0.003, sections: int = SECTIONS, name: str = "",
           collide: bool = True) -> g.Piece:
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
    return g.Piece(vis.vertices, vis.faces, material, col, name)


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
    rot = trimesh.transformations.rotation_matrix(math.pi / sides, (0, 0, 1))
    mesh.apply_transform(rot)
    ang = math.pi / sides + 2 * math.pi * np.arange(sides + 1) / sides  # the corners
    convex = []
    for i in range(len(prof) - 1):
        for s in range(sides):
            pts = []
            for r, z in (outer[i], outer[i + 1], inner[i], inner[i + 1]):
                for a in (ang[s], ang[s + 1]):
                    pts.append((r * math.cos(a), r * math.sin(a), z))
            convex.append(np.array(pts))
    return g.Piece(mesh.vertices, mesh.faces, material, convex, name)


def plug_lid(z_seat: float, r_flange: float, t_flange: float, r_plug: float, plug_depth: float,
             dome: float, r_knob: float, material: str, gap: float) -> list[g.Piece]:
    """A lid resting ``gap`` above a rim at ``z_seat``: plug, flange, dome and finial, one solid.

    The plug (outer radius ``r_plug``) reaches ``plug_depth`` below the seat.
    """
    zb = z_seat + gap
    zt = zb + t_flange
    dome_h = dome * r_flange
    # the dome: a smooth cap from the flange edge to the finial stem
    ctrl = [(r_flange, zb), (r_flange, zt), (0.85 * r_flange, zt + 0.55 * dome_h),
            (0.5 * r_flange, zt + 0.92 * dome_h), (max(r_knob * 0.7, 0.2 * r_flange), zt + dome_h)]
    z_top = zt + dome_h
    knob = [(0.7 * r_knob, z_top + 0.25 * r_knob), (r_knob, z_top + 0.9 * r_knob),
            (0.8 * r_knob, z_top + 1.5 * r_knob), (0.3 * r_knob, z_top + 1.85 * r_knob)]
    cap, cap_col = spline_profile(ctrl + knob, n=40, coarse=6)
    top = z_top + 1.9 * r_knob
    # a solid plug (PhysX contact generation is more reliable on chunky hulls than on thin wedges)
    plug = [[0.0, z_seat - plug_depth], [r_plug, z_seat - plug_depth], [r_plug, zb]]
    prof = np.vstack([plug, cap, [0.0, top]])
    col = np.vstack([plug, cap_col, [0.0, top]])
    vis = g.revolve(prof, material, sections=SECTIONS)
    return [vis.with_collision_of(g.revolve(col, material, sections=8))]


def lid_gap(height: float) -> float:
    """Clearance of a lid or cap from its vessel: above max(1 mm, 2% of its smallest extent)."""
    return max(0.0015, 0.03 * height)


# ---------------------------------------------------------------------------


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    finish = p["finish"]
    bp = Blueprint("vase", materials={"body": finish})
    H = p["height"]
    R = p["diameter_ratio"] * H / 2
    t = p["wall"]
    r_min = t + 0.012
    ctrl = []
    for f, u in SHAPES[p["profile"]]:
        jit = 1.0 + p["shape_jitter"] * float(geometry.uniform(-1, 1))
        ctrl.append((max(r_min, min(R, f * jit * R)), u * H))
    fine, coarse = spline_profile(ctrl, n=72, coarse=12)
    fine[:, 0] = np.maximum(fine[:, 0], r_min)
    coarse[:, 0] = np.maximum(coarse[:, 0], r_min)
    sectors = _sectors(float(fine[:, 0].max()))
    wall = vessel_wall(fine, coarse, t, "body", sectors)
    if finish == "enamel":  # enamelled sheet steel: mass of a 1 mm sheet, not of the thick wall
        wall = wall.replace(sheet=0.001)
    tb = 1.6 * t
    bottom = g.disc((0, 0, tb / 2), float(fine[0, 0]) - 0.3 * t, tb, "body", SECTIONS)
    if finish == "enamel":
        bottom = bottom.replace(sheet=0.001)
    bp.add("body", "body", [wall, bottom])
    # a foot ring under the bottom, glued on (so a lidless vase is still an articulation)
    r_foot = float(fine[0, 0]) - 0.4 * t
    foot = g.shell([(r_foot, -0.003), (r_foot, -0.0005)], min(0.006, 0.4 * r_foot), "body",
                   sections=SECTIONS)
    bp.add("foot", "stand", [foot])
    bp.join(J.fixed("body", "foot"))

    if not p["has_lid"]:
        return bp
    r_top = float(fine[-1, 0])
    r_flange = r_top + p["lid_overhang"]
    t_flange = float(np.clip(0.04 * r_flange + 0.004, 0.005, 0.01))
    plug_depth = float(np.clip(0.08 * H, 0.012, 0.03))
    r_knob = float(np.clip(0.18 * r_flange, 0.006, 0.014))
    lid_h = plug_depth + t_flange + p["lid_dome"] * r_flange + 1.9 * r_knob
    gap = lid_gap(lid_h)
    r_free = free_radius(fine, coarse, t, H - plug_depth - 0.002, H, sectors)
    r_plug = r_free - gap
    pieces = plug_lid(H, r_flange, t_flange, r_plug, plug_depth, p["lid_dome"],
                      r_knob, "body", gap)
    # a thin-walled lid modelled solid: mass of its wall, not of the solid
    pieces = [pc.replace(sheet=0.001 if finish == "enamel" else t) for pc in pieces]
    bp.add("lid", "lid", pieces)
    bp.join(J.continuous_prismatic("body", "lid", (0.0, 0.0, H), (0, 0, 1), (0.0, LID_LIFT), role="lid"))
    return bp
