"""Vessel designs beyond the plain one, so a category is more than one product: vase feet, stoppers and
liners; clip-top, hinged and stopper jar lids; swing-top, pump and sports bottle closures; steamer
inserts and pressure-cooker lids for pots; folding and detachable pan handles.

Like :mod:`.vessel`, every builder returns an :class:`~infmob_usd.assembly.Assembly` in its own
local frame, Z up along the vessel's axis; closures have their ``seat`` anchor at the origin (attach
it to the body's ``lid_seat``). Mechanisms that are more than one part return their joints inside
the assembly (names local to it). Dimensions come from :mod:`.closure_sizes`.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

from . import closure_sizes as C
from . import hardware
from .vessel import Profile, _at, _closure, _piece, _plug_lid, _supports, lid_gap

# ---------------------------------------------------------------------------
# vase


def stand_foot(body: Profile, slot: str) -> Assembly:
    """A flared foot ring glued under the base of wall ``body`` (``mount`` at its top centre): as wide
    as the base, flaring outward toward the table."""
    f = C.VASE_FOOT
    r_top = body.base_radius - 0.2 * body.thickness
    top = -f["gap"]
    width = min(f["width"], f["width_ratio"] * r_top)
    ring = g.shell([(r_top + f["flare"], top - f["height"]), (r_top, top)], width, slot)
    return Assembly.single("stand", [ring], {"mount": IDENTITY}, _supports(r_top + f["flare"], top - f["height"]))


def vase_stopper(mouth: Profile, slot: str, sheet: float = 0.0) -> Assembly:
    """A turned stopper for a vase's neck: a flange past the rim, a tall dome and finial, a plug."""
    s = C.VASE_STOPPER
    r_flange = mouth.top_radius + s["overhang"]
    depth = float(np.clip(s["depth"][0] * mouth.height, *s["depth"][1:]))
    knob = float(np.clip(s["knob"][0] * r_flange, *s["knob"][1:]))
    return _plug_lid(mouth, r_flange, s["flange"], depth, s["dome"], knob, slot, sheet, label="stopper")


def liner(mouth: Profile, slot: str, reach: float) -> tuple[Assembly, float]:
    """A removable glass liner hanging from a rolled flange a small gap above the rim, its tube
    ``reach`` x the vase's depth deep with clearance from the wall all the way down (it slides out
    through the narrowest part). Returns it (``seat`` at the rim) and how far it lifts to come out."""
    L = C.LINER
    H = mouth.height
    gap = lid_gap(0.02)
    z_bot = max(H * (1.0 - reach), mouth.thickness * 2 + L["floor_clear"])
    r_out = mouth.free_radius(z_bot, H) - L["room"]
    t = min(L["wall"], 0.3 * r_out)
    z_top = H + gap
    tube = Profile.through([(r_out, z_bot), (r_out, 0.5 * (z_bot + z_top)), (r_out, z_top)], t, (24, 3))
    floor = g.disc((0, 0, z_bot + t / 2), r_out - 0.2 * t, t, slot, None)
    r_fl = max(mouth.top_radius + L["flange"], r_out + L["flange"])
    flange = g.shell([(r_fl, z_top), (r_fl, z_top + L["flange_t"])], r_fl - r_out + 0.5 * t, slot)
    a = _closure("liner", [tube.wall(slot), floor, flange], H, z_top + L["flange_t"])
    return a, min(H - z_bot, L["max_lift"])


# ---------------------------------------------------------------------------
# pan handles: a lug on the wall and a handle that folds or slides off it


def split_handle(pot, length: float, angle: float, width: float, thickness: float, slot: str,
                 end_room: float = 0.0) -> tuple[list[g.Piece], Assembly]:
    """A long handle toward +X (as :func:`.vessel.long_handle`) cut into a short lug fixed to the wall
    and the handle proper, a small gap outboard of the lug. Returns the lug's pieces (in the vessel's
    frame, for the body) and the handle (anchors ``vessel``, ``end`` for a tip or ring, ``fold``: a
    hinge along -Y at the top edge of the cut, so a positive turn lifts the handle up over the pan;
    ``pull``: +X along the horizontal run; ``rise``: the rising part's frame, x along it)."""
    from . import vessel_sizes as S
    from .vessel import _hull, _section, handle_root

    L, H = S.LONG_HANDLE, C.SPLIT_HANDLE
    thickness, zc, root = handle_root(pot, width, thickness)
    y = width / 2
    x_knee = pot.lid_radius + L["clear"] + S.HANDLE_KNEE + H["lug"]
    x_cut = min(root[:, 0].max() + H["lug"], x_knee - H["knee_room"] - H["gap"])
    cut = Frame.at((x_cut, 0.0, zc))
    start = Frame.at((x_cut + H["gap"], 0.0, zc))
    knee = Frame.at((x_knee, 0.0, zc))
    rise = knee.turned("-y", angle)
    rest = max(L["min_rest"], length - (x_knee - root[:, 0].min())) - end_room
    end = rise.moved(rest)
    lug = [_hull(np.vstack([root, _section(cut, y, thickness / 2)]), slot)]
    knee_pts = _section(knee, y, thickness / 2)
    pieces = [_hull(np.vstack([_section(start, y, thickness / 2), knee_pts]), slot),
              _hull(np.vstack([knee_pts, _section(end, L["widen"] * width, L["tip"] * thickness)]), slot)]
    fold = Frame.at((x_cut + H["gap"] / 2, 0.0, zc + thickness / 2), z=(0, -1, 0), x=(1, 0, 0))
    handle = Assembly.single("handle", pieces, {"vessel": IDENTITY, "end": end, "fold": fold,
                                                "pull": Frame.at(start.origin, z=(1, 0, 0), x=(0, 0, 1)),
                                                "rise": rise, "thickness": _at(thickness)},
                             {"grip": end.origin})
    return lug, handle


def release_slider(rise: Frame, rest: float, width: float, thickness: float, slot: str) -> Assembly:
    """The thumb release slider on a detachable handle's top (in the vessel's frame): a rounded block
    ``slider_gap`` above the handle, ``slider_at`` of the way along its rising part; ``slide``: its
    frame, z along the handle toward the tip."""
    H = C.SPLIT_HANDLE
    ln, w_share, h = H["slider"]
    w = w_share * width
    c = rise.moved(H["slider_at"] * rest + ln / 2, 0.0, thickness / 2 + H["slider_gap"] + h / 2)
    pts = []
    for dx in (-ln / 2, ln / 2):
        for dy in (-w / 2, w / 2):
            for dz, shrink in ((-h / 2, 1.0), (h / 2, 0.7)):
                pts.append(c.point((dx * shrink, dy * shrink, dz)))
    piece = g.from_trimesh(g.convex_hull(np.array(pts)), slot, name="button")
    return Assembly.single("button", [piece], {"slide": Frame.at(c.origin, z=rise.x, x=rise.z)})


def _bar(length: float, slot: str, standoff: float, radius: float, at: Frame) -> tuple:
    """The pieces of a :func:`~.hardware.bar_handle` (posts 0.8 of the bar's radius) mounted at ``at``."""
    size = hardware.HandleSize(standoff=standoff, bar_radius=radius, post_radius=0.8 * radius, inset=0.02)
    return hardware.bar_handle(length, slot, size).placed(at).pieces


def helper_handle(pot, slot: str) -> Assembly:
    """A short loop handle at -X below the rim (a big skillet's helper handle), in the vessel's frame."""
    h = C.HELPER
    zh = pot.rim_bottom - h["under_rim"] - h["radius"]
    r = float(pot.radius_at(zh)) - 0.6 * pot.wall
    pieces = _bar(h["length"], slot, h["standoff"], h["radius"], Frame.at((-r, 0.0, zh), z=(-1, 0, 0), x=(0, 1, 0)))
    return Assembly.single("handle", pieces, {"vessel": IDENTITY})


# ---------------------------------------------------------------------------
# jar: clip-top (hinged glass lid on a gasket, wire lever), hinged storage lid, stopper


def _wire(a, b, slot: str, r: float | None = None) -> g.Piece:
    return g.cylinder(a, b, C.CLIP_TOP["wire"] if r is None else r, slot, 10)


def neck_ring_and_hinge(neck: Profile, slot: str, lever: bool) -> tuple[list[g.Piece], dict]:
    """The body's fittings of a hinged jar lid (in the jar's frame): a wire ring round the neck under
    the lip, two knuckles at the back on wires from the ring (the lid's knuckle sits between them).
    Returns the pieces and the frames ``hinge`` (z along -Y: a positive turn lifts the lid's front)
    and ``lever`` (z along +Y, at the front: a positive turn swings the lever forward and down)."""
    k = C.CLIP_TOP
    H, n, w = neck.height, neck.top_radius, k["wire"]
    r_lid = n + k["overhang"]
    z_ring = H - k["ring_below"]
    r_ring = neck.outer_radius(z_ring - w, z_ring + w) + w + 0.0003
    ring = g.shell([(r_ring + w, z_ring - w), (r_ring + w, z_ring + w)], 2 * w, slot,
                   convex_sectors=16)
    gap = lid_gap(k["glass"])
    z_h = H + gap + k["glass"] / 2
    x_h = -(r_lid + k["hinge_out"])
    pieces = [ring]
    kn, kg = k["knuckle"], k["knuckle_gap"]
    for s in (-1, 1):
        y0, y1 = s * (kn / 2 + kg), s * (kn / 2 + kg + kn)
        pieces.append(g.cylinder((x_h, y0, z_h), (x_h, y1, z_h), 1.6 * w, slot, 12))
        pieces.append(_wire((-r_ring, s * (kn / 2 + kg + kn / 2), z_ring), (x_h, s * (kn / 2 + kg + kn / 2), z_h),
                            slot))
    frames = {"hinge": Frame.at((x_h, 0.0, z_h), z=(0, -1, 0), x=(1, 0, 0)), "z_ring": z_ring, "r_ring": r_ring}
    return pieces, frames


def clip_lid(neck: Profile, slot: str, gasket_slot: str, wire_slot: str, hinge: Frame, knob: float = 0.0,
             thickness: float | None = None) -> Assembly:
    """A round lid hinged at the back (built in the jar's frame): a glass (or flat) disc a small gap
    above the lip with a rubber gasket ring under its edge, a knuckle round the hinge line and (for a
    clip-top) a wire yoke from the knuckle over the top; ``knob`` > 0: a knob at the front instead."""
    k = C.CLIP_TOP
    H, n = neck.height, neck.top_radius
    t = k["glass"] if thickness is None else thickness
    r_lid = n + k["overhang"]
    gap = lid_gap(t)
    zb, zt = H + gap, H + gap + t
    dome = k["dome"] * t if knob <= 0 else 0.0
    prof = [(0.0, zb), (r_lid, zb), (r_lid, zt - 0.3 * t), (0.92 * r_lid, zt), (0.5 * r_lid, zt + 0.8 * dome),
            (0.0, zt + dome)]
    plate = g.revolve(prof, slot)
    a = np.linspace(0, 2 * np.pi, 20, endpoint=False)
    hull = np.vstack([np.c_[r_lid * np.cos(a), r_lid * np.sin(a), np.full(20, z)] for z in (zb, zt - 0.3 * t)]
                     + [np.c_[0.92 * r_lid * np.cos(a), 0.92 * r_lid * np.sin(a), np.full(20, zt)]])
    pieces = [_piece(plate, convex=[hull])]
    gw, gh = k["gasket"]
    gasket = g.shell([(n + 0.6 * gw, zb - 0.0002), (n + 0.6 * gw, zb + 0.25 * gh)], gw, gasket_slot)
    pieces.append(_piece(gasket, convex=[]))
    # the lid's knuckle on the hinge line, and the tab joining it to the lid's back edge
    o = hinge.origin
    kn = k["knuckle"] / 2
    w = k["wire"]
    pieces.append(g.cylinder((o[0], -kn, o[2]), (o[0], kn, o[2]), 1.6 * w, wire_slot, 12))
    pieces.append(g.box_between((o[0], -0.35 * kn, zb + 0.2 * t), (-(r_lid - 0.004), 0.35 * kn, zt - 0.2 * t),
                                wire_slot))
    if knob > 0:
        pieces += hardware.knob_handle(knob, 1.4 * knob, slot).placed(Frame.at((0.75 * r_lid, 0, zt - 0.0005))).pieces
    else:  # the wire yoke over the top, from the knuckle to the front where the lever's bar presses
        z_y = zt + dome + w + 0.0003
        pieces.append(_piece(_wire((o[0], 0.0, o[2]), (-0.45 * r_lid, 0.0, z_y), wire_slot), convex=[]))
        pieces.append(_piece(_wire((-0.45 * r_lid, 0.0, z_y), (0.55 * r_lid, 0.0, z_y), wire_slot), convex=[]))
    top = zt + dome + 2 * w
    return Assembly.single("lid", pieces, {"vessel": IDENTITY, "top": _at(top)})


def clip_lever(neck: Profile, ring: dict, slot: str) -> Assembly:
    """The wire lever of a clip-top at the front (in the jar's frame): a U of wire whose arms pivot
    just off the neck ring at +X and whose bar lies over the lid's front edge; ``pivot``: z along +Y,
    so a positive turn swings the bar forward and down, freeing the lid."""
    k = C.CLIP_TOP
    H, n, w = neck.height, neck.top_radius, k["wire"]
    r_lid = n + k["overhang"]
    half = k["lever_half"] * r_lid
    x_p = ring["r_ring"] + 2 * w + k["lever_out"] * 0.5
    x_p = max(x_p, math.sqrt(max(r_lid ** 2 - half ** 2, 0.0)) + 2 * w + 0.0015)
    z_p = ring["z_ring"]
    gap = lid_gap(k["glass"])
    z_bar = H + gap + k["glass"] * (1 + k["dome"]) + k["bar_up"] + w
    x_bar = r_lid - k["bar_in"]
    pieces = []
    for s in (-1, 1):
        pieces.append(_wire((x_p, s * half, z_p), (x_p, s * half, z_bar), slot))
        pieces.append(_wire((x_p, s * half, z_bar), (x_bar, s * 0.35 * half, z_bar), slot))
    pieces.append(_wire((x_bar, -0.35 * half, z_bar), (x_bar, 0.35 * half, z_bar), slot))
    # the finger tab at the front
    pieces.append(g.box_between((x_p - w, -0.4 * half, z_p + 0.3 * (z_bar - z_p)),
                                (x_p + 1.5 * w, 0.4 * half, z_p + 0.55 * (z_bar - z_p)), slot))
    return Assembly.single("lever", pieces, {"pivot": Frame.at((x_p, 0.0, z_p), z=(0, 1, 0), x=(1, 0, 0)),
                                             "vessel": IDENTITY})


def jar_stopper(neck: Profile, slot: str) -> Assembly:
    """An apothecary jar's stopper: flange over the lip, tall dome, ball finial, plug in the neck."""
    s = C.JAR_STOPPER
    r_flange = neck.top_radius + s["overhang"]
    depth = float(np.clip(s["depth"][0] * neck.height, *s["depth"][1:]))
    knob = float(np.clip(s["knob"][0] * r_flange, *s["knob"][1:]))
    return _plug_lid(neck, r_flange, s["flange"], depth, s["dome"], knob, slot, s["sheet"], label="stopper")


# ---------------------------------------------------------------------------
# bottle: swing-top stopper on a wire bail, lotion pump, push-pull sports cap


def _round_hull(prof, sides: int = 16) -> np.ndarray:
    """Points of a convex hull of revolution through ``(radius, z)`` points (few, exactly placed)."""
    a = 2 * np.pi * np.arange(sides) / sides
    return np.vstack([np.c_[r * np.cos(a), r * np.sin(a), np.full(sides, z)] if r > 0 else [[0.0, 0.0, z]]
                      for r, z in prof])


def swing_top(neck: Profile, slot: str, washer_slot: str, wire_slot: str) -> tuple[list[g.Piece], Assembly, dict]:
    """A swing-top (Grolsch) closure built in the bottle's frame: the body's fittings (a wire ring
    round the neck under the lip with a clasp at the back), and the stopper (a porcelain cap a small
    gap above the lip on a rubber washer, with the wire bail from its sides round to the clasp).
    Returns the fittings, the stopper (anchor ``vessel``) and the two hinge lines: ``swing`` (the
    bail about the clasp, -Y: the stopper swings back) and ``tip`` (the stopper about its back edge)."""
    k = C.SWING_TOP
    H, w = neck.height, k["wire"]
    r_cap = neck.outer_radius(H - 0.006, H) + k["overhang"]
    gap = lid_gap(k["height"])
    zb, h, dome = H + gap, k["height"], k["dome"]
    prof = [(0.0, zb), (r_cap, zb), (r_cap, zb + 0.55 * h), (0.85 * r_cap, zb + h), (0.45 * r_cap, zb + h + 0.8 * dome),
            (0.0, zb + h + dome)]
    cap = g.revolve(prof, slot)
    # hollow-cast porcelain (Grolsch stoppers weigh ~10-15 g with wire and washer): 3 mm walls
    pieces = [_piece(cap, sheet=C.SWING_TOP["porcelain"], convex=[_round_hull(prof[1:-1] + [(0.0, zb + h + dome)])])]
    washer = g.shell([(r_cap - 0.0004, zb - 0.0004), (r_cap - 0.0004, zb + 0.001)], k["washer"], washer_slot)
    pieces.append(_piece(washer, convex=[]))
    z_r = H - k["ring_below"]
    r_ring = neck.outer_radius(z_r - 2 * w, z_r + 2 * w) + w + 0.0003
    x_c = -(r_ring + 2.5 * w)
    z_p = zb + 0.4 * h
    R = max(r_ring, r_cap) + 3 * w
    for s in (-1, 1):  # the bail: down from the stopper's side, then round the neck to the clasp
        pts = [(0.0, s * (r_cap + w), z_p), (0.0, s * R, z_r + 2 * w)]
        for ang in (115, 140, 160):
            t = math.radians(ang)
            pts.append((R * math.cos(t), s * R * math.sin(t), z_r + 2 * w))
        pts.append((x_c, s * 0.35 * r_ring, z_r))
        for a, b in zip(pts[:-1], pts[1:]):
            pieces.append(_piece(_wire(a, b, wire_slot, w), convex=[]))
        pieces.append(_piece(g.cylinder((0.0, s * r_cap * 0.97, z_p), (0.0, s * (r_cap + 1.5 * w), z_p), 1.5 * w,
                                        wire_slot, 10), convex=[]))
    fittings = [g.shell([(r_ring + w, z_r - w), (r_ring + w, z_r + w)], 2 * w, wire_slot,
                        convex_sectors=16),
                g.cylinder((x_c, -0.3 * r_ring, z_r), (x_c, 0.3 * r_ring, z_r), 1.8 * w, wire_slot, 12)]
    frames = {"swing": Frame.at((x_c, 0.0, z_r), z=(0, -1, 0), x=(1, 0, 0)),
              "tip": Frame.at((-(r_cap + 0.0008), 0.0, zb), z=(0, -1, 0), x=(1, 0, 0))}
    return fittings, Assembly.single("cap", pieces, {"vessel": IDENTITY}), frames


def pump_collar(neck: Profile, finish_bottom: float, slot: str) -> Assembly:
    """A lotion pump's collar screwed on the neck (seat at the origin): skirt, top plate and the
    lock turret the head sits on (``stem``: the top of the turret)."""
    from .vessel import _sleeve_cap

    k = C.PUMP
    pieces, r_out, top = _sleeve_cap(neck, max(finish_bottom + 0.0065, neck.height - k["collar"]), k["collar_t"],
                                     0.003, 0.0004, slot, 0.0)
    turret = g.cylinder((0, 0, top - 0.0003), (0, 0, top + k["lock_h"]), 0.55 * r_out, slot, 32)
    return _closure("cap", pieces + [turret], neck.height, top + k["lock_h"])


def pump_head(slot: str) -> Assembly:
    """The actuator: a stem and a head with a nozzle toward +X (``stem`` at its bottom, the origin)."""
    k = C.PUMP
    gap = 0.0004
    hr, hh = k["head"]
    nl, nr = k["nozzle"]
    stem = g.cylinder((0, 0, gap), (0, 0, gap + k["stem"] + 0.001), 0.0035, slot, 16)
    z0 = gap + k["stem"]
    head = g.revolve([(0.0, z0), (hr, z0), (hr, z0 + 0.7 * hh), (0.8 * hr, z0 + hh), (0.0, z0 + hh)], slot,
                     sections=32)
    head = _piece(head, convex=[_round_hull([(hr, z0), (hr, z0 + 0.7 * hh), (0.8 * hr, z0 + hh)])])
    nozzle = g.cylinder((0.5 * hr, 0, z0 + 0.55 * hh), (hr + nl, 0, z0 + 0.55 * hh), nr, slot, 12)
    return Assembly.single("head", [stem, head, nozzle], {"stem": IDENTITY})


def sports_spout(cap_top: float, slot: str) -> Assembly:
    """A push-pull spout standing on a cap's top (``base`` at its bottom, the origin): a tube with a
    rounded tip and a grip ring, resting 0.3 mm above the cap."""
    k = C.SPORTS
    r, h = k["spout"], k["spout_h"]
    z0 = 0.0003
    prof = [(0.0, z0), (r, z0), (r, z0 + 0.75 * h), (0.8 * r, z0 + h), (0.35 * r, z0 + h)]
    spout = g.revolve(prof + [(0.0, z0 + h)], slot, sections=32)
    ring = g.shell([(r + k["ring"], z0 + 0.15 * h), (r + k["ring"], z0 + 0.35 * h)], k["ring"] + 0.0003, slot,
                   sections=32)
    return Assembly.single("spout", [_piece(spout, convex=[_round_hull(prof[1:] + [(0.0, z0 + h)])]),
                                      ring], {"base": IDENTITY})


# ---------------------------------------------------------------------------
# pot: stacking steamer tiers, pressure-cooker lid fittings


def steamer_tier(pot, height: float, slot: str, rim_slot: str, handle_slot: str, skirt: float | None = None,
                 label: str = "insert", sheet: float | None = None):
    """A steamer tier that nests into ``pot`` (a :class:`.vessel.Cookware`, or the tier below): a wall
    as wide as the pot's, a rolled rim, a skirt that reaches into the vessel below with clearance, a
    shoulder ring and a (perforated) floor at the skirt's bottom, two small loop handles at +-Y.
    ``seat`` (origin) is the bottom of its wall, resting a gap above the rim below; returns the tier
    and its own :class:`.vessel.Cookware` (for the next tier and the lid; ``lid_seat`` anchor).
    Wall, skirt, shoulder and floor are of ``STEAMER["sheet"]`` (a pressed insert, not a clad pot wall).
    ``skirt``: how deep it reaches into the vessel below (default ``STEAMER["skirt"]``); a pasta insert
    is this with a short collar above the rim and a skirt reaching most of the way down (``label``
    ``"basket"``, ``sheet`` its gauge)."""
    from . import vessel_sizes as S
    from .vessel import Cookware

    k = C.STEAMER
    r_top = pot.rim_inner + pot.wall
    t = k["sheet"] if sheet is None else float(sheet)  # pressed sheet, thinner than the pot's clad wall
    d = k["skirt"] if skirt is None else float(skirt)
    r_s = float(pot.radius_at(pot.rim_top - d - 0.002)) - pot.wall - k["room"]
    bead = max(0.0015, 0.8 * (pot.rim_outer - pot.rim_inner - pot.wall) / 2)
    wall = g.shell([(r_top, 0.0), (r_top, height - bead)], t, slot)
    skirt = g.shell([(r_s, -d), (r_s, t)], t, slot)
    shoulder = g.shell([(r_top, 0.0), (r_top, t)], r_top - r_s + t, slot)
    floor = g.disc((0, 0, -d + t / 2), r_s - 0.5 * t, t, slot, None)
    cx, cz = r_top - t + bead, height - bead
    th = np.linspace(0.0, math.pi, 13)
    outer = np.c_[cx + bead * np.sin(th), cz - bead * np.cos(th)]
    box = g.shell([(cx + bead, cz - bead), (cx + bead, cz + bead)], 2 * bead, rim_slot, sections=8)
    rim = g.shell(outer, bead, rim_slot).with_collision_of(box)
    hl, hr, hs = k["handle"]
    pieces = [wall, skirt, shoulder, floor, rim]
    for s in (1, -1):
        pieces += _bar(hl, handle_slot, hs, hr, Frame.at((0.0, s * (r_top - 0.5 * t), 0.55 * height), z=(0, s, 0),
                                                         x=(1, 0, 0)))
    prof = np.array([(r_top, 0.0), (r_top, height)])
    info = Cookware(prof, height, cx + bead, r_top - t, cz - bead, -d + t, r_s - t, t)
    a = Assembly.single(label, pieces, {"seat": IDENTITY, "lid_seat": _at(height + S.LID_GAP)})
    return a, info


def pressure_valve(slot: str) -> Assembly:
    """A pressure cooker's valve / selector: a stem and a ribbed cap turning about its axis
    (``base`` at its bottom, resting a small gap above the lid)."""
    k = C.PRESSURE
    r, h = k["valve"]
    z0 = k["gap"]
    stem = g.cylinder((0, 0, z0), (0, 0, z0 + 0.4 * h), 0.55 * r, slot, 24)
    cap = g.revolve([(0.0, z0 + 0.35 * h), (r, z0 + 0.35 * h), (r, z0 + 0.8 * h), (0.7 * r, z0 + h), (0.0, z0 + h)],
                    slot, sections=24)
    cap = _piece(cap, convex=[_round_hull([(r, z0 + 0.35 * h), (r, z0 + 0.8 * h), (0.7 * r, z0 + h)])])
    fin = g.box_between((-0.9 * r, -0.15 * r, z0 + h - 0.0005), (0.9 * r, 0.15 * r, z0 + h + 0.004), slot)
    return Assembly.single("valve", [stem, cap, fin], {"base": IDENTITY})


def lock_slider(slot: str) -> Assembly:
    """A pressure cooker's lock slider: a rounded block on the lid (``base`` under it, a gap below),
    sliding radially outward along its ``slide`` frame's z (+X of its own frame)."""
    k = C.PRESSURE
    ln, w, h = k["lock"]
    z0 = k["gap"]
    pts = [(x * s, y, z) for x in (ln / 2,) for s in (-1, 1) for y in (-w / 2, w / 2) for z in (z0,)]
    pts += [(x * s * 0.8, y * 0.8, z0 + h) for x in (ln / 2,) for s in (-1, 1) for y in (-w / 2, w / 2)]
    piece = g.from_trimesh(g.convex_hull(np.array(pts)), slot, name="button")
    return Assembly.single("button", [piece], {"base": IDENTITY, "slide": Frame.at((0, 0, z0 + h / 2), z=(1, 0, 0),
                                                                                 x=(0, 0, 1))})


def steam_vent(slot: str) -> Assembly:
    """A pot lid's rotary steam vent: a flat disc with a grip tab across it, turning about its axis
    (``base`` at its bottom, resting a small gap above the lid; :data:`.closure_sizes.VENT`)."""
    k = C.VENT
    r, t, tab, z0 = k["radius"], k["thickness"], k["tab"], k["gap"]
    disc = g.disc((0, 0, z0 + t / 2), r, t, slot, 24)
    grip = g.box_between((-0.8 * r, -0.0015, z0 + t - 0.0005), (0.8 * r, 0.0015, z0 + t + tab), slot)
    return Assembly.single("vent", [disc, grip], {"base": IDENTITY})
