"""Tap parts: columns, lever cartridges, valve handles, swept spouts with aerators, deck plates.

Local frames: everything stands on the deck plane z = 0 (the deck plate's underside) with the
main column on the z axis and the spout reaching toward +x. Sizes of real kitchen and basin
mixers: 15-40 cm tall, 35-60 mm deck plates (up to 25 cm for a bridge or widespread set), spout
tubes 14-24 mm across, lever arms 4-12 cm (manufacturers' dimension sheets: Grohe, Hansgrohe).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame, polar


@dataclass(frozen=True)
class Ranges:
    """Ranges of a tap's parameters (lo, hi), m or rad. Kitchen and basin mixers 15-40 cm tall on 6-25 cm deck
    plates (a bridge or widespread set the widest), bodies 32-56 mm across, spout tubes 14-24 mm across
    reaching 10-24 cm and swivelling 30-135 degrees each way, lever arms 4-12 cm lifting 20-36 degrees, valve
    handles or a side mixer 5-10 cm off the middle, pull-out heads 12-20 cm on their hose, wall mixers' bodies 15-22
    cm long (manufacturers' dimension sheets: Grohe, Hansgrohe)."""

    height: tuple[float, float] = (0.15, 0.4)
    base_width: tuple[float, float] = (0.06, 0.25)
    body_radius: tuple[float, float] = (0.016, 0.028)
    spout_reach: tuple[float, float] = (0.1, 0.24)
    spout_radius: tuple[float, float] = (0.007, 0.012)
    spout_swivel: tuple[float, float] = (math.pi / 6, 3 * math.pi / 4)
    lever_length: tuple[float, float] = (0.04, 0.12)
    lever_tilt: tuple[float, float] = (math.pi / 9, math.pi / 5)
    handle_spread: tuple[float, float] = (0.05, 0.1)
    head_travel: tuple[float, float] = (0.12, 0.2)
    wall_length: tuple[float, float] = (0.15, 0.22)


RANGES = Ranges()

GAP = 0.003  # clearance around every moving part
DECK_T = 0.01  # deck plate thickness
TUBE = 0.0015  # wall of a spout tube (it is a hollow pipe)
CAP_H = 0.03  # lever cartridge cap height
HUB_R = 0.013  # valve handle hub radius
HUB_H = 0.024
RISER_R = 0.016  # valve riser radius
RISER_H = 0.018


# -- the tap's layout (``categories/tap.py`` reads these) ----------------------------------------------
LEVER_SWIVEL = math.pi / 2
HANDLE_TURN = math.pi / 4
CAP = 0.95  # a lever cap's radius as a fraction of its column's
SPOUT_OVER = 0.035  # an outlet stays this far above whatever it sweeps over
MIXER_H = 0.035  # a side mixer column's height
RISER = 0.004  # a spout riser is this much wider than the spout tube
FLARE = 1.25  # column feet flare to this fraction of their radius


WALL_SWIVEL = 5 * math.pi / 12  # a wall mixer's spout swings +-75 degrees, clear of the wall
WALL_X = -0.065  # the wall plane behind a wall mixer's axis (S-unions: 40-70 mm projection)
BRIDGE_H = 0.05  # bridge mixer risers: height of the bridge pipe's axis above the deck
COLLAR = 0.014  # a collar spout's collar is this much taller than the spout tube's diameter
# Deck tap layout (m, or ratios), after the dimension sheets of Grohe / Hansgrohe mixers
LAYOUT = dict(
    spout_max=0.6,  # a spout tube's radius: at most this share of the body column's
    mixer_room=0.045,  # a side mixer stands this far beyond the spout riser and its own cap (the lever's swing)
    lever_clear=0.015,  # the side mixer's lever stops this far short of the spout riser
    valve_room=0.02,  # valve risers stand at least this far beyond the body column and their own width
    valve_reach=0.045, valve_clear=0.012,  # a valve handle's reach: at most, and short of the body or riser
    bridge_bar=0.75,  # a bridge pipe's radius as a share of the valve risers'
    bridge_riser=0.012,  # a bridge mixer's spout riser rises this far above the bridge pipe's axis
    riser=(0.03, 0.2),  # a spout riser: at least 3 cm, or a fifth of the tap's height over the deck
    head=(1.6, 0.015, 0.06),  # a pull-out head's radius (x the tube's, at least), and its hose over the outlet
    head_reach=0.05,  # a pull-out spout reaches this much further (its head)
    spout_rise=(0.06, 0.1),  # a top spout rises at least this far above its outlet and above its riser
    riser_flare=1.5,  # a spout riser's foot flare
    lever_collar=(0.55, 0.012),  # a lever tap's spout collar: at this share of the column, this far under its cap
    collar_over=0.065,  # a two-handle tap's collar: this far (plus the tube) above its valve handles
    column_over=0.03,  # and the column this far above the collar
)
# deck plates: the columns' flared feet stand 8 mm inside the plate's edge; a single-column plate is at most
# 12 cm, every plate 40 % as deep as it is wide, at most 9 cm, and its feet 8 mm inside it front and back
DECK = dict(edge=0.008, single_max=0.12, depth=0.4, most_deep=0.09)
# a wall mixer (EN 200: 150 mm centres): its bar's axis 75 mm up (the plate's bottom edge 1 cm off the floor
# of the local frame), at least 20 mm radius; the cartridge column 6 mm over the bar; a stub 14 mm under the
# spout's collar with a 1 cm flange 1.3 times the column's radius; the spout's foot 9 cm under its collar
WALL_MIXER = dict(z=0.075, bar_min=0.02, column_over=0.006, stub=0.014, flange=(0.01, 1.3))
WALL_SPOUT_FOOT = 0.09


def _hull(points, material: str, name: str = "") -> g.Piece:
    v, f = g.hull_arrays(np.asarray(points, float))
    return g.Piece(v, f, material, [v], name)


def column(xy, z0: float, z1: float, r: float, flare: float = 1.25, dome: bool = False) -> g.Piece:
    """A column of revolution from the deck (flared foot) to ``z1`` (flat or domed top)."""
    h = z1 - z0
    prof = [(0, 0), (flare * r, 0), (flare * r, min(0.004, 0.1 * h)), (r, min(0.012, 0.3 * h))]
    prof += [(r, h - 0.5 * r), (0.7 * r, h - 0.1 * r), (0, h)] if dome else [(r, h - 0.002), (r - 0.002, h), (0, h)]
    return g.revolve(prof, "metal", center=(xy[0], xy[1], z0))


HUB = 0.55  # a lever's pivot hub radius as a fraction of its cartridge cap's (hub length 1.6x the cap radius)


def lever_cap(xy, z0: float, r_cap: float) -> g.Piece:
    """The cartridge housing on top of a column (fixed to the column): a short dome with a slot for the
    lever's hub (the ceramic cartridge of a single-lever mixer, e.g. Grohe Eurosmart: 35-46 mm)."""
    return g.revolve([(0, 0), (r_cap, 0), (r_cap, 0.7 * CAP_H), (0.8 * r_cap, CAP_H), (0, CAP_H)], "metal",
                     center=(xy[0], xy[1], z0))


def lever(xy, z0: float, r_cap: float, arm: float) -> tuple[list[g.Piece], Frame]:
    """A single lever on the cartridge pin above a cap whose top is at ``z0``: a hub round the pin (a
    cylinder along y centred on it: turning about the pin it stays in place, so the lever never
    leaves its cartridge) and an arm forward. Returns the pieces and the tilt hinge: the pin's axis,
    z along -y (a positive turn lifts the arm)."""
    x, y = xy
    rh = HUB * r_cap
    zc = z0 + GAP + rh  # the pin
    hub = g.cylinder([x, y - 0.8 * r_cap, zc], [x, y + 0.8 * r_cap, zc], rh, "metal", 32)
    w, t = min(0.016, 1.2 * r_cap), min(0.008, 1.2 * rh)
    rise = 0.25 * arm
    pts = [[x + 0.2 * rh, y + s * w / 2, zc + dz] for s in (-1, 1) for dz in (-t / 2, t / 2)]
    pts += [[x + r_cap + arm, y + s * 0.35 * w, zc + rise + dz] for s in (-1, 1) for dz in (-0.4 * t, 0.3 * t)]
    return [hub, _hull(pts, "metal", "handle")], Frame.at((x, y, zc), x=(1, 0, 0), z=(0, -1, 0))


def lever_height(r_cap: float, arm: float) -> float:
    """Height of a lever above its cap's top at rest (the arm's tip or the hub)."""
    rh = HUB * r_cap
    return GAP + rh + max(rh, 0.25 * arm + 0.3 * min(0.008, 1.2 * rh))


def highest_when_tilted(pieces, hinge: Frame, tilt: float) -> float:
    """Highest point of ``pieces`` turned about ``hinge.z`` by any angle in [0, tilt]."""
    v = np.vstack([pc.vertices for pc in pieces])
    return max(float(hinge.point(Frame.at().turned("z", th).point(hinge.local(v)))[:, 2].max())
               for th in np.linspace(0, tilt, 9))


def valve_handle(xy, z0: float, reach: float, kind: str, slot: str) -> list[g.Piece]:
    """A hub with four spokes (cross) or one arm forward (lever), and a hot/cold button."""
    x, y = xy
    pieces = [g.revolve([(0, 0), (HUB_R, 0), (HUB_R, 0.018), (0.8 * HUB_R, HUB_H), (0, HUB_H)], "metal",
                        center=(x, y, z0))]
    zs = z0 + 0.014
    if kind == "cross":
        for spoke in polar(Frame.at((x, y, zs)).turned("z", math.pi / 4), 4, 0.0):
            d = spoke.x
            pieces.append(g.cylinder(spoke.origin + 0.5 * HUB_R * d, spoke.origin + reach * d, 0.0045, "metal", 12,
                                     name="handle"))
            pieces.append(g.sphere(spoke.origin + reach * d, 0.0065, "metal", name="handle"))
    else:
        pts = [[x + 0.5 * HUB_R, y + s * 0.006, zs + dz] for s in (-1, 1) for dz in (-0.004, 0.004)]
        pts += [[x + reach, y + s * 0.004, zs + 0.006 + dz] for s in (-1, 1) for dz in (-0.003, 0.003)]
        pieces.append(_hull(pts, "metal", "handle"))
    pieces.append(g.disc([x, y, z0 + HUB_H + 0.0005], 0.6 * HUB_R, 0.002, slot))
    return pieces


# -- spouts: swept tubes ----------------------------------------------------------------------------------
def _ring(c, t, r, n=16):
    f = Frame.at(c, z=t)
    th = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return f.point(np.c_[r * np.cos(th), r * np.sin(th), np.zeros(n)])


def tube(points, r: float) -> list[g.Piece]:
    """A hollow pipe along a centre line: convex hulls between consecutive rings."""
    pts = np.asarray(points, float)
    keep = [0] + [i for i in range(1, len(pts)) if np.linalg.norm(pts[i] - pts[i - 1]) > 1e-6]
    pts = pts[keep]
    tan = np.gradient(pts, axis=0)
    return [_hull(np.vstack([_ring(pts[i], tan[i], r), _ring(pts[i + 1], tan[i + 1], r)]), "metal").replace(sheet=TUBE)
            for i in range(len(pts) - 1)]


def _line(p0, p1, n):
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    return [p0 + (p1 - p0) * k / n for k in range(n + 1)]


def _arc(centre, radius, a0, a1, n):
    """Points in the xz plane: centre + radius (cos a, 0, sin a)."""
    c = np.asarray(centre, float)
    return [c + radius * np.array([math.cos(a), 0.0, math.sin(a)]) for a in np.linspace(a0, a1, n + 1)]


def outlet(tip, r: float) -> list[g.Piece]:
    """An aerator hanging from the tube end at ``tip`` (the outlet's top centre)."""
    x, _, z = tip
    return [g.cylinder([x, 0, z - 0.02], [x, 0, z + 0.002], 1.12 * r, "metal", 24),
            g.cylinder([x, 0, z - 0.0205], [x, 0, z - 0.019], 0.8 * r, "aerator", 16)]


def top_spout(shape: str, reach: float, r: float, z0: float, height: float, z_low: float) -> list[g.Piece]:
    """A spout continuing a riser upward from ``z0``: a gooseneck (inverted U), ``curved`` (up, over
    and down) or ``straight`` (up, then forward); the outlet's bottom stays at or above ``z_low``."""
    top = height - r  # centre line of the highest point
    if shape == "gooseneck":
        R = max(min(reach / 2, 0.45 * (top - z0), top - z_low - r - 0.005), 0.02)
        z_end = max(z_low + 0.02, top - R - 0.5 * (top - R - z0))
        pts = _line([0, 0, z0], [0, 0, top - R], 6) + _arc([R, 0, top - R], R, math.pi, 0, 16)[1:]
        pts += _line([2 * R, 0, top - R], [2 * R, 0, z_end], 4)[1:]
        tip = (2 * R, 0, z_end)
    else:
        R = max(min(0.04, 0.4 * (top - z0), top - z_low - r - 0.005), 0.015)
        pts = _line([0, 0, z0], [0, 0, top - R], 6) + _arc([R, 0, top - R], R, math.pi, math.pi / 2, 8)[1:]
        if shape == "curved":
            R2 = min(0.035, 0.4 * (top - z_low - 0.02), 0.3 * reach)
            x2 = max(reach - R2, R + 0.01)
            pts += _line([R, 0, top], [x2, 0, top], 6)[1:] + _arc([x2, 0, top - R2], R2, math.pi / 2, 0, 8)[1:]
            tip = (x2 + R2, 0, top - R2)
        else:
            x2 = max(reach, R + 0.03)
            pts += _line([R, 0, top], [x2, 0, top], 8)[1:]
            tip = (x2 - r, 0, top - 0.6 * r)
    return tube(pts, r) + outlet(tip, r)


def collar_spout(shape: str, reach: float, r: float, rb: float, z_cm: float, hc: float, deck: float
                 ) -> list[g.Piece]:
    """A ring around a column of radius ``rb`` (radial gap ``GAP``) and a tube leaving it forward."""
    wall = 0.004
    r_in = rb + GAP
    collar = g.shell([(r_in + wall, z_cm - hc / 2), (r_in + wall, z_cm + hc / 2)], wall, "metal")
    x0 = r_in + 0.5 * wall
    room = z_cm - deck - 0.05  # the outlet stays 5 cm above the deck
    if shape == "curved":
        R2 = float(np.clip(0.35 * reach, 0.015, max(0.015, room - r)))
        x2 = max(reach - R2, x0 + 0.02)
        pts = _line([x0, 0, z_cm], [x2, 0, z_cm], 8) + _arc([x2, 0, z_cm - R2], R2, math.pi / 2, 0, 8)[1:]
        tip = (x2 + R2, 0, z_cm - R2)
    else:
        drop = min(math.tan(math.radians(8)) * reach, max(room - 0.02, 0.0))
        pts = _line([x0, 0, z_cm], [reach, 0, z_cm - drop], 10)
        tip = (reach - r, 0, z_cm - drop - 0.6 * r)
    return [collar] + tube(pts, r) + outlet(tip, r)


def pullout_spout(reach: float, r: float, z0: float, height: float, z_low: float, travel: float
                  ) -> tuple[list[g.Piece], list[g.Piece], Frame, float]:
    """A pull-out kitchen spout (Grohe Minta / Hansgrohe Focus: 20-26 cm reach, 0.15-0.5 m of hose): a
    riser up from ``z0``, a bend and a straight arm forward; the spray head docks on the arm's end and
    pulls out along it on its hose. Returns the spout pieces, the head pieces (head, nozzle face and
    the hose inside the arm), the head's slide frame (z along the arm) and the slide's travel."""
    rh = max(1.6 * r, 0.015)  # spray head radius
    top = height - rh  # the arm's centre line
    R = max(min(0.04, 0.4 * (top - z0)), 0.015)
    x_dock = max(reach - 0.07, R + 0.06)
    pts = _line([0, 0, z0], [0, 0, top - R], 6) + _arc([R, 0, top - R], R, math.pi, math.pi / 2, 8)[1:]
    pts += _line([R, 0, top], [x_dock, 0, top], 6)[1:]
    travel = min(travel, x_dock - R - 0.03)
    x1 = x_dock + GAP
    head = [g.revolve([(0, 0), (0.75 * rh, 0), (rh, 0.012), (rh, 0.06), (0.8 * rh, 0.07), (0, 0.07)], "metal")
            .transformed(Frame.at((x1, 0, top), z=(1, 0, 0)).matrix),
            g.cylinder([x1 + 0.066, 0, top], [x1 + 0.0705, 0, top], 0.65 * rh, "aerator", 24),
            # the hose inside the arm: seen when the head is out, no collision (the arm's hulls are solid)
            g.cylinder([x1 - travel - 0.01, 0, top], [x1, 0, top], max(r - TUBE - 0.0015, 0.002), "seal", 12
                       ).replace(convex=[])]
    return tube(pts, r), head, Frame.at((x1, 0, top), z=(1, 0, 0)), travel


def bridge_bar(d: float, z: float, r: float) -> list[g.Piece]:
    """The horizontal bridge pipe joining two valve risers at +-``d`` (a bridge mixer, e.g. Perrin &
    Rowe: 200-230 mm centres), with a boss in the middle for the spout riser."""
    return [g.cylinder([0, -d, z], [0, d, z], r, "metal", 24),
            g.sphere([0, 0, z], 1.35 * r, "metal")]


def wall_body(length: float, r: float, z: float, wall_x: float) -> list[g.Piece]:
    """A wall mixer's body: a bar along y at height ``z`` on two S-unions into escutcheons on the wall
    plane ``wall_x`` (150 mm centres, EN 200), and the plate they are fixed to."""
    ends = length / 2 - 0.02
    pieces = [g.box_between([wall_x - 0.008, -length / 2 - 0.04, z - 0.065], [wall_x, length / 2 + 0.04, z + 0.065],
                            "metal", bevel=0.004),
              g.cylinder([0, -length / 2, z], [0, length / 2, z], r, "metal", 32)]
    for y in (-ends, ends):
        pieces += [g.cylinder([wall_x, y, z], [wall_x + 0.012, y, z], 0.028, "metal", 32),
                   g.cylinder([wall_x + 0.012, y, z], [0, y, z], 0.011, "metal", 20)]
    return pieces


# -- deck plates --------------------------------------------------------------------------------------------
def deck(width: float, depth: float, shape: str, bridge: bool) -> list[g.Piece]:
    """The deck plate (round, an obround bridge, or a bevelled rectangle) and its rubber gasket."""
    if shape == "round" and not bridge:
        r = width / 2
        return [g.revolve([(0, 0), (r, 0), (r, 0.6 * DECK_T), (r - 0.004, DECK_T), (0, DECK_T)], "metal"),
                g.disc([0, 0, -0.001], width / 2 - 0.004, 0.002, "seal")]
    if shape == "round":
        th = np.linspace(0, 2 * np.pi, 32, endpoint=False)
        pts = [np.c_[r * np.cos(th), y + r * np.sin(th), np.full(32, z)]
               for y in (-(width - depth) / 2, (width - depth) / 2)
               for z, r in ((0, depth / 2), (0.6 * DECK_T, depth / 2), (DECK_T, depth / 2 - 0.004))]
        return [_hull(np.vstack(pts), "metal")]
    return [g.box_between([-depth / 2, -width / 2, 0], [depth / 2, width / 2, DECK_T], "metal", bevel=0.003),
            g.box_between([-depth / 2 + 0.004, -width / 2 + 0.004, -0.002], [depth / 2 - 0.004, width / 2 - 0.004, 0.0],
                          "seal")]


# A bath-shower wall mixer's diverter (EN 200 bath mixers with an automatic diverter, e.g. Grohe
# Eurosmart / Hansgrohe Logis bath mixers): a knob on top of the body bar at one end, pulled up
# 8 mm to send the water to the shower. Knob radius and height.
DIVERTER = {"radius": 0.009, "height": 0.014, "inset": 0.035, "pull": 0.008, "gap": 0.0008}


def diverter_knob(y: float, z_top: float) -> tuple[list[g.Piece], Frame]:
    """A wall mixer's diverter knob standing on the body bar's top ``z_top`` at ``y`` (x = 0): its
    pieces (a stem and a ribbed knob) and its pull frame (z up)."""
    k = DIVERTER
    r, h, z0 = k["radius"], k["height"], z_top + k["gap"]
    pieces = [g.cylinder([0, y, z0], [0, y, z0 + 0.4 * h], 0.45 * r, "metal", 20),
              g.cylinder([0, y, z0 + 0.4 * h], [0, y, z0 + h], r, "metal", 24)]
    return pieces, Frame.at((0.0, y, z0), z=(0, 0, 1), x=(1, 0, 0))


def deck_size(base_width: float, d: float, rb: float, r_side: float) -> tuple[float, float]:
    """The deck plate's width and depth for a body column ``rb`` and, ``d`` off the axis on either side (0:
    none), columns ``r_side``: at least ``base_width`` (a single column's: at most 12 cm), wide enough for
    the columns' flared feet."""
    e = DECK["edge"]
    need = 2 * (d + r_side * FLARE + e) if d else 2 * (FLARE * rb + e)
    width = max(base_width, need) if d else max(need, min(base_width, DECK["single_max"]))
    depth = float(np.clip(DECK["depth"] * width, 2 * FLARE * max(rb, RISER_R) + 2 * e, DECK["most_deep"]))
    return width, depth


def wall_mixer(length: float, rb: float, rs: float) -> tuple[list[g.Piece], tuple]:
    """A wall mixer's fixed body: the bar (:func:`wall_body`) on the wall ``WALL_X``, a cartridge column up
    from it (with its lever cap) and a stub down into the spout's collar. Returns the pieces and (bar axis z,
    bar radius, the column's top, the spout collar's centre z, the collar's height)."""
    w = WALL_MIXER
    r_bar = max(rb, w["bar_min"])
    hc = 2 * rs + COLLAR
    z = w["z"]  # the bar's axis: the plate's bottom edge at z = 0.01
    z_cm = z - r_bar - GAP - hc / 2
    stub0 = z_cm - hc / 2 - w["stub"]
    z_top = z + r_bar + w["column_over"]  # the cartridge column's top
    flange_h, flange_r = w["flange"]
    pieces = wall_body(length, r_bar, z, WALL_X)
    pieces += [column((0.0, 0.0), z, z_top, rb, flare=1.0), lever_cap((0.0, 0.0), z_top, CAP * rb),
               g.cylinder([0, 0, stub0], [0, 0, z], rb, "metal", 32),
               g.cylinder([0, 0, stub0], [0, 0, stub0 + flange_h], flange_r * rb, "metal", 32)]
    return pieces, (z, r_bar, z_top, z_cm, hc)
