"""Pot: a cooking pot, stock pot or saucepan with a lid that lifts off and turns.

X is depth (a long handle reaches toward +X, the front), Y is width, Z is up. The body is
a real hollow vessel: a thin wall of revolution (``g.shell``: a rounded bottom corner and
a straight, slightly flared side) on a bottom disc that follows the corner, finished at
the top with a rolled rim (a round bead curling outward). The handles are pieces of the
body named ``handle``: either two loop handles on the sides (+-Y, a bar on two posts), or
one long handle (a tapered bar leaving the wall horizontally below the rim, then rising),
always below the rim so the lid lifts clear of them.

The lid is a shallow dome (a solid of revolution with a thin wall) wider than the rim, with
a metal band around its edge; on top a knob or a loop handle (fixed to the lid, pieces
named ``handle``). It has no lip reaching into the opening: the joint keeps it centred, and
thin lip hulls next to the rim made PhysX report deep false contacts that spun the lid.
It rests 2.5 mm above the rim on the lower stop of its lift, so gravity holds it there;
``continuous_prismatic``: lift 0..3 cm along +Z, then turn freely about Z (the lid is
symmetric about Z, so the turn is neutral).

Finishes: brushed steel, enamel (with a steel rim and lid band) or chrome; the lid is of
the body's finish or glass; handles match the body or are black plastic or wood.

The builders below (:func:`vessel`, :func:`lid`, :func:`long_handle`) are shared with the
``pan`` category.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

GROWTH = Growth(
    pot=Rule(required=("body", "lid"), one_of={"side_handles": 0.6, "long_handle": 0.4}),
    lid=Rule(one_of={"knob": 0.7, "loop": 0.3}),
)
"""``pot.one_of`` is the object-wide ``handle_layout`` parameter and ``lid.one_of`` the
``lid_handle`` parameter (same weights)."""

_LAYOUTS = GROWTH.rules["pot"].one_of
_LID_HANDLES = GROWTH.rules["lid"].one_of

SCHEMA = Schema((
    Float("radius", "outer radius of the wall at the top", "m", 0.08, 0.18),
    Float("depth_ratio", "depth / radius", "", 0.6, 2.0, dist="loguniform"),
    Float("flare", "wall angle from vertical", "rad", 0.0, 0.1),
    Float("corner", "bottom corner radius as a fraction of the radius", "", 0.08, 0.2),
    Float("wall", "wall thickness", "m", 0.0015, 0.003),
    Float("bottom", "bottom (clad base) thickness", "m", 0.003, 0.007),
    Float("bead", "rolled rim bead radius", "m", 0.0018, 0.003),
    Float("dome", "lid dome height as a fraction of the radius", "", 0.08, 0.25),
    Float("lid_thickness", "lid wall thickness (glass lids are 1.6x thicker)", "m", 0.0012, 0.0025),
    Choice("handle_layout", "two loop handles on the sides or one long handle",
           choices=tuple(_LAYOUTS), weights=tuple(_LAYOUTS.values())),
    Float("handle_length", "long handle length from the wall", "m", 0.14, 0.24),
    Float("handle_angle", "long handle rise above horizontal", "rad", 0.05, 0.4),
    Float("handle_width", "long handle width", "m", 0.018, 0.03),
    Float("handle_thickness", "long handle thickness", "m", 0.01, 0.016),
    Float("side_handle_length", "side loop handle length", "m", 0.06, 0.12),
    Float("side_handle_radius", "side loop bar radius", "m", 0.0035, 0.0065),
    Float("side_handle_reach", "finger room between the wall and a side loop", "m", 0.018, 0.03),
    Choice("lid_handle", "knob or loop handle on the lid", choices=tuple(_LID_HANDLES),
           weights=tuple(_LID_HANDLES.values())),
    Float("knob_radius", "lid knob radius", "m", 0.012, 0.022),
    Choice("body_finish", "body material", choices=("brushed_metal", "enamel", "chrome"),
           weights=(0.5, 0.3, 0.2)),
    Choice("lid_finish", "lid: the body's material or glass", choices=("match", "glass"),
           weights=(0.55, 0.45)),
    Choice("handle_finish", "handle material", choices=("match", "plastic", "wood"),
           weights=(0.5, 0.35, 0.15)),
    *GROWTH.flags(),
))

LIFT = 0.03  # m, lid lift
LID_GAP = 0.0025  # m, the lid rests this far above the rim on its lower stop
HANDLE_FAMILY = {"plastic": "plastic:black|dark_grey", "wood": "wood"}
GLASS = "glass:clear|clear_blue"


# ---------------------------------------------------------------------------
# shared builders (pot and pan)


def wall_profile(r_top: float, depth: float, corner: float, flare: float, z_start: float,
                 n_arc: int = 10) -> np.ndarray:
    """Outer ``(radius, z)`` points of a vessel wall, bottom to top.

    A quarter-ish arc of radius ``corner`` round the bottom corner (tangent to the floor
    at z = 0), then a straight side at ``flare`` radians from vertical up to ``(r_top,
    depth)``. The points start where the arc is at height ``z_start`` (the top of the
    bottom piece), so the wall never has a flat, paper-thin band.
    """
    sb, cb = math.sin(flare), math.cos(flare)
    # arc centre (a, corner); the side leaves the arc at angle phi1 = pi/2 - flare
    a = r_top - (depth - corner * (1 - sb)) * math.tan(flare) - corner * cb
    phi0 = math.acos(1 - z_start / corner)
    phi1 = math.pi / 2 - flare
    phis = np.linspace(phi0, phi1, n_arc)
    pts = [(a + corner * math.sin(f), corner * (1 - math.cos(f))) for f in phis]
    pts.append((r_top, depth))
    return np.array(pts)


def radius_at(profile: np.ndarray, z) -> np.ndarray:
    """Outer radius of a wall profile at height(s) ``z`` (clamped to its ends)."""
    return np.interp(z, profile[:, 1], profile[:, 0])


def vessel(r_top: float, depth: float, corner: float, flare: float, wall: float, bottom: float,
           bead: float, slot: str, rim_slot: str, sections: int = 64) -> tuple[list[g.Piece], dict]:
    """A hollow vessel: a bottom following the corner, a thin wall and a rolled rim.

    Returns the pieces and a dict of the numbers later parts need: ``profile`` (outer
    wall), ``rim_top`` (z of the rim), ``rim_outer`` (outer radius of the bead),
    ``rim_inner`` (inner radius of the opening), ``floor`` (z of the inside bottom),
    ``floor_radius`` (inner radius at the floor).
    """
    corner = max(corner, 2.5 * bottom)
    z_wall_top = depth - bead  # the wall ends in the middle of the bead
    fine = wall_profile(r_top, z_wall_top, corner, flare, bottom, 12)
    coarse = wall_profile(r_top, z_wall_top, corner, flare, bottom, 5)
    # bottom: the floor and the corner up to z = bottom, solid (revolve: axis to axis)
    arc = wall_profile(r_top, z_wall_top, corner, flare, 1e-6, 40)
    arc = arc[arc[:, 1] <= bottom + 1e-9]
    r0 = float(fine[0, 0])
    a = float(arc[0, 0])
    prof = np.vstack([[0.0, 0.0], [a, 0.0], arc[1:], [r0, bottom], [r0 - wall, bottom], [0.0, bottom]])
    prof = prof[np.r_[True, np.linalg.norm(np.diff(prof, axis=0), axis=1) > 1e-7]]
    base = g.revolve(prof, slot, sections=sections)
    ang = np.linspace(0.0, 2 * np.pi, 32, endpoint=False)
    ring = np.c_[np.cos(ang), np.sin(ang)]
    puck = np.vstack([np.c_[ring * a, np.zeros(32)], np.c_[ring * r0, np.full(32, bottom)]])
    base = g.Piece(base.vertices, base.faces, slot, [puck])  # one convex puck
    shell = g.shell(fine, wall, slot, sections=sections)
    coll = g.shell(coarse, wall, slot, sections=8)
    body_wall = shell.with_collision_of(coll)
    # rolled rim: a round bead (outer half circle, revolved with thickness = its radius)
    cx, cz = r_top - wall + bead, z_wall_top
    th = np.linspace(0.0, math.pi, 13)
    outer = np.c_[cx + bead * np.sin(th), cz - bead * np.cos(th)]
    vis = g.shell(outer, bead, rim_slot, sections=sections)
    box = g.shell([(cx + bead, cz - bead), (cx + bead, cz + bead)], 2 * bead, rim_slot, sections=8)
    rim = vis.with_collision_of(box)
    info = {
        "profile": fine, "coarse": coarse, "rim_top": depth, "rim_outer": cx + bead,
        "rim_inner": r_top - wall, "rim_bottom": cz - bead, "floor": bottom, "floor_radius": r0 - wall,
        "wall": wall,
    }
    return [base, body_wall, rim], info


def lid(info: dict, dome: float, thickness: float, slot: str, band_slot: str, knob_slot: str,
        handle: str, knob_radius: float, sections: int = 64) -> tuple[list[g.Piece], float]:
    """A dome lid resting :data:`LID_GAP` above the rim, with a band round its edge and a knob or loop.

    ``dome`` is the dome height in metres. Returns the pieces and the z of the lid's
    underside at its edge (the joint origin).
    """
    z0 = info["rim_top"] + LID_GAP
    r_l = info["rim_outer"] + 0.004
    t = thickness

    def under(r):  # z of the dome's underside
        return z0 + dome * (1 - (np.asarray(r) / r_l) ** 2)

    rs = np.linspace(0.0, r_l, 24)
    inner = np.c_[rs, under(rs)]
    outer = np.c_[rs[::-1], under(rs[::-1]) + t]
    prof = np.vstack([inner, outer])
    mesh = g.revolve(prof, slot, sections=sections)
    # one convex cap from a coarse sample (PhysX keeps at most 255 hull vertices)
    ang = np.linspace(0.0, 2 * np.pi, 24, endpoint=False)
    cap = [(0.0, 0.0, float(under(0.0)) + t)]
    for rr in (r_l, 0.85 * r_l, 0.65 * r_l, 0.4 * r_l):
        zz = float(under(rr)) + (t if rr < r_l else 0.0)
        cap += [(rr * math.cos(a), rr * math.sin(a), zz) for a in ang]
    cap += [(r_l * math.cos(a), r_l * math.sin(a), z0 + t) for a in ang]
    pieces = [g.Piece(mesh.vertices, mesh.faces, slot, [np.array(cap)])]
    # band around the edge
    pieces.append(g.shell([(r_l + 0.0015, z0), (r_l + 0.0015, z0 + t + 0.003)], 0.0035, band_slot,
                          sections=sections, convex_sectors=24))
    z_top = z0 + dome + t
    if handle == "knob":
        pieces += g.knob_handle((0, 0, z_top - 0.001), (0, 0, 1), knob_slot, radius=knob_radius,
                                depth=max(0.02, 1.2 * knob_radius))
    else:  # a loop along Y on two posts
        length = min(0.7 * r_l, max(0.06, 5 * knob_radius))
        rad, high = 0.0045, 0.022
        yp = length / 2 - 0.008
        for s in (-1, 1):
            zb = float(under(yp)) + t - 0.002
            pieces.append(g.cylinder((0, s * yp, zb), (0, s * yp, z_top + high), 0.0035, knob_slot, 16,
                                     name="handle"))
        pieces.append(g.cylinder((0, -length / 2, z_top + high), (0, length / 2, z_top + high), rad,
                                 knob_slot, 20, name="handle"))
    return pieces, z0


def _section(c, v, w, half_v, half_w, chamfer=0.35):
    """Eight points of a chamfered rectangle centred at ``c`` in the plane of ``v`` and ``w``."""
    cv, cw = half_v * chamfer, half_w * chamfer
    uv = [(half_v, half_w - cw), (half_v - cv, half_w), (-half_v + cv, half_w), (-half_v, half_w - cw),
          (-half_v, -half_w + cw), (-half_v + cv, -half_w), (half_v - cv, -half_w), (half_v, -half_w + cw)]
    return np.array([c + a * v + b * w for a, b in uv])


def long_handle(info: dict, clear_radius: float, length: float, angle: float, width: float,
                thickness: float, slot: str, hole: bool = False) -> list[g.Piece]:
    """A long handle toward +X: horizontal below the rim out past ``clear_radius``, then rising.

    Its top stays 3 mm below the bead out to ``clear_radius`` + 12 mm, so a lid lifting
    over the rim never meets it. With ``hole`` it ends in a ring (a slot to hang it by)
    made of convex segments round an elliptic hole.
    """
    prof = info["profile"]
    thickness = min(thickness, 0.8 * (info["rim_bottom"] - 0.003 - info["floor"]))  # shallow pans
    zc = info["rim_bottom"] - 0.003 - thickness / 2
    zs = np.array([zc - thickness / 2, zc + thickness / 2])
    # root: points on the wall (a little inside it), at each height and side
    y = width / 2
    root = []
    for z in zs:
        r = float(radius_at(prof, z))
        x = math.sqrt(max(r * r - y * y, 1e-6)) - 0.5 * info["wall"]
        for s in (-1, 1):
            root.append((x, s * y * 0.999, z))
            root.append((x, s * y * 0.7, z))
    root = np.array(root)
    x_knee = clear_radius + 0.012
    X, Y, Z = np.eye(3)
    knee = _section(np.array([x_knee, 0.0, zc]), Y, Z, width / 2, thickness / 2)
    pieces = [g.from_trimesh(g.convex_hull(np.vstack([root, knee])), slot, name="handle")]
    d = np.array([math.cos(angle), 0.0, math.sin(angle)])
    w = np.array([-math.sin(angle), 0.0, math.cos(angle)])
    rest = max(0.03, length - (x_knee - root[:, 0].min()))
    end = np.array([x_knee, 0.0, zc]) + d * rest
    half_end = 0.6 * width  # handles widen toward the end
    if not hole:
        tip = _section(end, Y, w, half_end, 0.42 * thickness)
        pieces.append(g.from_trimesh(g.convex_hull(np.vstack([knee, tip])), slot, name="handle"))
        cap = _section(end + d * 0.004, Y, w, 0.8 * half_end, 0.32 * thickness)
        pieces.append(g.from_trimesh(g.convex_hull(np.vstack([tip, cap])), slot, name="handle"))
        return pieces
    ring_w = max(0.006, 0.25 * half_end)
    b_h = half_end - ring_w  # hole half width
    a_h = max(b_h * 1.8, 0.012)  # hole half length
    centre = end - d * (a_h + ring_w)
    start = centre - d * (a_h + 0.5 * ring_w)
    neck = _section(start, Y, w, half_end, 0.42 * thickness)
    pieces.append(g.from_trimesh(g.convex_hull(np.vstack([knee, neck])), slot, name="handle"))
    n = 14
    angles = np.linspace(0.0, 2 * math.pi, n + 1)
    ht = 0.4 * thickness
    for k in range(n):
        pts = []
        for th in np.linspace(angles[k], angles[k + 1], 3):
            for rr_a, rr_b in ((a_h, b_h), (a_h + ring_w, b_h + ring_w)):
                p = centre + d * rr_a * math.cos(th) + Y * rr_b * math.sin(th)
                pts += [p + w * ht, p - w * ht]
        pieces.append(g.from_trimesh(g.convex_hull(np.array(pts)), slot, name="handle"))
    return pieces


def side_handles(info: dict, length: float, radius: float, reach: float, slot: str) -> list[g.Piece]:
    """Two loop handles at +-Y: a bar along X on two posts that go into the wall, below the rim."""
    prof = info["profile"]
    zh = info["rim_bottom"] - 0.006 - radius
    r = float(radius_at(prof, zh))
    inset = min(0.02, 0.15 * length)
    xp = length / 2 - inset
    yin = math.sqrt(r * r - xp * xp) - 0.6 * info["wall"]
    pieces = []
    for s in (-1, 1):
        n = np.array([0.0, s, 0.0])
        anchor = np.array([0.0, s * yin, zh])
        standoff = (r - yin) + reach
        pieces += g.bar_handle(anchor, n, (1, 0, 0), length, slot, standoff=standoff, radius=radius)
    return pieces


# ---------------------------------------------------------------------------


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    body_family = p["body_finish"]
    rim_family = "brushed_metal" if body_family == "enamel" else body_family
    glass = p["lid_finish"] == "glass"
    # "match" uses the body's own slot, so the colour is the same, not another draw
    match = p["handle_finish"] == "match"
    bp = Blueprint("pot", materials={
        "body": body_family, "rim": rim_family, "glass": GLASS,
        "handle": HANDLE_FAMILY.get(p["handle_finish"], body_family),
        "knob": HANDLE_FAMILY.get(p["handle_finish"], "plastic:black|dark_grey"),
    })
    lid_slot = "glass" if glass else "body"
    band_slot = "rim" if glass or body_family == "enamel" else "body"
    handle_slot = "body" if match else "handle"
    knob_slot = "knob" if glass and match else handle_slot
    R = p["radius"]
    D = p["depth_ratio"] * R
    pieces, info = vessel(R, D, p["corner"] * R, p["flare"], p["wall"], p["bottom"], p["bead"],
                          "body", "rim")
    if p["handle_layout"] == "long_handle":
        pieces += long_handle(info, info["rim_outer"] + 0.004 + 0.002, p["handle_length"], p["handle_angle"],
                              p["handle_width"], p["handle_thickness"], handle_slot)
    else:
        pieces += side_handles(info, p["side_handle_length"], p["side_handle_radius"],
                               p["side_handle_reach"], handle_slot)
    bp.add("body", "body", pieces)

    t_lid = p["lid_thickness"] * (1.6 if glass else 1.0)
    lid_pieces, z0 = lid(info, p["dome"] * R, t_lid, lid_slot, band_slot, knob_slot, p["lid_handle"],
                         p["knob_radius"])
    bp.add("lid", "lid", lid_pieces)
    bp.join(J.continuous_prismatic("body", "lid", (0.0, 0.0, z0), (0, 0, 1), (0.0, LIFT), role="lid"))
    return bp
