"""Full-size refrigerator parts: the insulated cabinet split into a fresh-food and a freezer zone, the
doors and the freezer drawer that close them, and a water/ice dispenser set into a door.

World-aligned like :mod:`.fridges` (whose ``solid_door``, ``door_bins``, ``door_bin``, ``crisper`` and
``rack_levels`` this module reuses unchanged): X is depth (the doors face +X), Y width, Z up. A design is
a split of one insulated cabinet (:func:`.appliance.insulated_cabinet`) by an insulated mullion:

* ``top_freezer``: freezer over the fresh-food zone, a door each, hinged on the same side;
* ``bottom_freezer``: fresh-food zone over a pull-out freezer drawer;
* ``french_door``: two fresh-food doors hinged at the outer sides (no fixed mullion between them) over a
  freezer drawer;
* ``side_by_side``: a freezer zone on the left, the fresh-food zone on the right, full height, each with
  its own door hinged at its outer side.

Sizes are in :data:`FULL`, each figure beside its source.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import appliance as A
from . import controls, hardware
from . import fridges as FR
from .appliance_sizes import FRIDGE as F

FULL = {
    # full-size refrigerators: 0.6-0.91 m wide, 1.6-1.85 m tall. Whirlpool WRT318FZDW top freezer 30 in
    # (0.76 m) x 66.25 in (1.68 m), 33.4 in deep with handles; Bosch KGN36VL and Liebherr CNef 4315 bottom
    # freezers 0.6 m x 1.86 m x 0.66 m; Samsung RF28R7351SR French door 35.75 in (0.91 m) x 70 in (1.78 m),
    # 36.5 in deep; GE GSS25GSHSS side-by-side 35.75 in x 69.9 in x 0.87 m with doors (spec sheets)
    "width": (0.6, 0.91), "depth": (0.62, 0.8), "height": (1.6, 1.85),
    # polyurethane foam walls 45-70 mm (freezer walls the thick end; Liebherr and Bosch product data)
    "wall": (0.045, 0.07),
    # insulated doors with a moulded inner liner 60-80 mm thick (replacement door assemblies, e.g. Whirlpool
    # W10909978, Samsung DA91-04327A); the dispenser's recess needs at least 60 mm
    "door_thickness": (0.06, 0.08),
    "kick_height": (0.06, 0.1), "feet_height": (0.01, 0.025),  # toe grille; levelling legs
    # freezer share of the cavity height: ~30 % of the volume on top/bottom-freezer models (Whirlpool
    # WRT318FZDW 18.2 cu ft, 4.3 of it freezer; Bosch KGN36 237 + 89 l); freezer drawers 0.45-0.6 m tall
    "freezer_share": (0.27, 0.34),
    # side-by-side freezer side 38-45 % of the width (GE GSS25GSHSS 9.1 of 25.3 cu ft; Samsung RS27T5200)
    "freezer_width": (0.38, 0.45),
    "handle_length": (0.35, 0.6),  # door handle as a share of its door's height
    "shelf_travel": (0.3, 0.5),  # a slide-out shelf pulls out this share of its depth (Whirlpool SpillGuard)
    "drawer_travel": (0.6, 0.75),  # a freezer drawer opens this share of its basket's depth
    # a deli / snack drawer over the crispers 80-100 mm tall (Whirlpool WRT318FZDW, LG LRFVS3006S "Glide
    # N' Serve"); the shelves start over it
    "deli": 0.09,
    "mullion": 0.05,  # insulated mullion between fresh-food and freezer zones
    "door_opens": math.radians(120),  # a full-size fridge door stops at 120-130 deg (installation guides)
    # tubular door handles of stainless fridges: ~25 mm bar standing 50 mm off the door on 20 mm posts
    "bar": dict(standoff=0.045, bar_radius=0.012, post_radius=0.01, inset=0.03),
    "reach": 1.05,  # handles centre near this height, inside their door (Samsung, GE product photos)
    "handle_edge": 0.05,  # a handle ends at least this far inside its door's end
    "stile": 0.055,  # a handle sits on this much of a door's free edge
    "drawer_handle": 0.7,  # a freezer drawer's handle spans this share of its width ...
    "drawer_handle_below": 0.05,  # ... this far under its top
    # the freezer drawer's basket: 4 mm inside the liner, 30 mm off the back, 25 mm under the mullion
    "basket": {"side": 0.004, "back": 0.03, "under": 0.025, "floor": 0.004, "wall": 0.003},
    # a water/ice dispenser (GE GSS25, Samsung RF28 dispenser doors): a recess 190-230 mm wide and
    # 280-320 mm tall, 30 mm deep, its middle ~1.05 m up; a paddle 90 x 100 mm hung 30 mm under the recess
    # top, pushed in 8-9 deg by a glass and sprung back; a drip grille 12 mm tall on the recess floor
    "dispenser": {"width": 0.2, "height": 0.3, "depth": 0.03, "z": 1.05, "paddle": (0.045, 0.1, 0.005),
                  "pivot": (0.004, 0.03), "push": math.radians(8.5), "tray": 0.012, "tray_in": 0.002,
                  "back": 0.003, "hinge_r": 0.004, "keys_over": 0.03},
    # hermetic compressors of full-size fridges weigh 8-11 kg (Embraco EMT/VEMY, Secop NLE data sheets)
    "compressor_kg": 9.0,
}

COUNTS = {
    # 2-5 fresh-food shelves and 1-2 crispers (Whirlpool WRT318FZDW: 2 shelves + 2 crispers; Samsung RF28R7351SR:
    # 4 shelves; Bosch KGN36: 4 shelves + 1 crisper); 1-3 freezer wire shelves (top freezers 1, side-by-sides
    # 3-5 over their baskets); 2-4 door bins per door; side-by-side freezer baskets 0-2 (GE GSS25GSHSS 2,
    # Samsung RS27T5200 1, Frigidaire FFSS2615 none); dispenser selector keys 2-4 (GE GSS25: ice / water;
    # Samsung RF28R7351SR: + light and lock); stacked freezer drawers 1-2 (Whirlpool WRB322 one, LG
    # LMXS28596S four-door two)
    "shelf_count": (2, 5), "crisper_count": (1, 2), "freezer_shelf_count": (1, 3), "freezer_drawer_count": (1, 2),
    "bin_count": (2, 4), "key_count": (2, 4), "basket_count": (0, 2),
}
BAR = hardware.HandleSize(**FULL["bar"])
SIDE_BY_SIDE_WIDTH = (0.83, 0.91)
"""Side-by-side models are 33-36 in wide (GE GSS23 33 in, GE GSS25 / Samsung RS27T5200 35.75-36 in spec
sheets): a narrower freezer door would hold no bins."""


def _side_by_side(W, D, H):
    lo, hi = SIDE_BY_SIDE_WIDTH
    w0, w1 = FULL["width"]
    return lo + (hi - lo) * (W - w0) / (w1 - w0), D, H


SIZES = {"side_by_side": _side_by_side}
"""Designs whose width is not the parameter's (:func:`~.appliance.size`)."""
DOOR_OPENS = FULL["door_opens"]


@dataclass(frozen=True)
class Door:
    """A door's ``box`` (x0, x1, y0, y1, z0, z1), its hinge side (``left``) and the ``opening`` (y0, z0, y1,
    z1) of the zone part it covers (where its bins go)."""

    box: tuple
    left: bool
    opening: tuple

    @property
    def hinge(self) -> Frame:
        return A.side_hinge(self.box, self.left)


@dataclass(frozen=True)
class Zone:
    """A cooled zone: its cavity (liner faces), the x span of what stands in it behind the closed doors'
    bins, and the ``margin`` of door beside its opening (what its shelves keep clear of when it is open)."""

    cav: tuple
    xs: tuple
    margin: float


@dataclass(frozen=True)
class Cabinet:
    """The body's pieces, the fresh-food and freezer zones, the doors by part name and the freezer drawer's
    front box (None: a freezer door)."""

    pieces: list
    width: float
    fridge: Zone
    freezer: Zone
    doors: dict = field(default_factory=dict)
    drawer: tuple | None = None


def _zone(cav, xb1: float, y_edge: float) -> Zone:
    xs = FR.behind_bins((cav[0] + F["rack_gap"], xb1 - F["rack_front"]))
    return Zone(cav, xs, abs(cav[2] - y_edge) if y_edge < 0 else abs(y_edge - cav[3]))


def _mullion(lo, hi, axis: int) -> list[g.Piece]:
    """An insulated mullion between ``lo`` and ``hi``: a steel-fronted foam core whose two faces towards the
    zones (across ``axis``: 1 a side-by-side's, 2 a stacked one's) are the liner's moulded plastic, as in
    every real cabinet (the liner is one white or light grey shell around each zone, the mullion included)."""
    L = A.LINER
    lo_in, hi_in = list(lo), list(hi)
    lo_in[axis] += L
    hi_in[axis] -= L
    a_hi, b_lo = list(hi), list(lo)
    a_hi[axis] = lo[axis] + L
    b_lo[axis] = hi[axis] - L
    return [g.box_between(lo_in, hi_in, "body").replace(sheet=A.FRIDGE_SHEET),
            g.box_between(lo, a_hi, "liner"), g.box_between(b_lo, hi, "liner")]


def cabinet(design: str, W, D, H, wall, ft, feet, kick, share: float) -> Cabinet:
    """The insulated cabinet of ``design`` (see the module), split at ``share`` of its cavity height (of its
    width for a side-by-side) into its zones, and its doors' boxes."""
    m = FULL["mullion"]
    gap, L = F["gap"], A.LINER
    y0, y1, xf = -W / 2, W / 2, D / 2
    xb1 = xf - ft - gap
    zk = feet + kick
    cav = (-D / 2 + wall + L, xb1, y0 + wall + L, y1 - wall - L, zk + wall + L, H - wall - L)
    pieces = A.insulated_cabinet((-D / 2, xb1, y0, y1, feet, H), cav, zk) + \
        [FR.compressor(-D / 2, feet, zk, FULL["compressor_kg"])]
    x0 = xf - ft
    if design == "side_by_side":
        ys = y0 + share * W
        pieces += _mullion([cav[0], ys - m / 2, cav[4]], [xb1, ys + m / 2, cav[5]], 1)
        gc = _meeting_gap(ft, ys - y0)
        fz, fr = (*cav[:3], ys - m / 2, *cav[4:]), (*cav[:2], ys + m / 2, *cav[3:])
        doors = {"freezer_door": Door((x0, xf, y0, ys - gc / 2, zk + gap, H), True, (fz[2], fz[4], fz[3], fz[5])),
                 "door": Door((x0, xf, ys + gc / 2, y1, zk + gap, H), False, (fr[2], fr[4], fr[3], fr[5]))}
        return Cabinet(pieces, W, _zone(fr, xb1, y1), _zone(fz, xb1, y0), doors)
    top = design == "top_freezer"
    zs = cav[5] - share * (cav[5] - cav[4]) if top else cav[4] + share * (cav[5] - cav[4])
    pieces += _mullion([cav[0], cav[2], zs - m / 2], [xb1, cav[3], zs + m / 2], 2)
    low, high = (*cav[:5], zs - m / 2), (*cav[:4], zs + m / 2, cav[5])
    fr, fz = (low, high) if top else (high, low)
    lower, upper = (x0, xf, y0, y1, zk + gap, zs - gap / 2), (x0, xf, y0, y1, zs + gap / 2, H)
    fdoor, zdoor = (lower, upper) if top else (upper, lower)
    opening = (fr[2], fr[4], fr[3], fr[5])
    if design == "french_door":
        gc = _meeting_gap(ft, W / 2)
        doors = {"door": Door((*fdoor[:3], -gc / 2, *fdoor[4:]), True, (*opening[:2], -gc / 2, opening[3])),
                 "right_door": Door((*fdoor[:2], gc / 2, *fdoor[3:]), False, (gc / 2, *opening[1:]))}
    else:
        doors = {"door": Door(fdoor, True, opening)}
    if top:
        doors["freezer_door"] = Door(zdoor, True, (fz[2], fz[4], fz[3], fz[5]))
    return Cabinet(pieces, W, _zone(fr, xb1, y0), _zone(fz, xb1, y0), doors, None if top else zdoor)


def _meeting_gap(ft: float, width: float) -> float:
    """Gap between two doors meeting in the middle: a free edge's back corner swings ~ft^2 / 2w towards
    the other door (:func:`.fridges.dual_doors`)."""
    return max(F["gap"], ft ** 2 / width) + F["meeting_gap"]


def handed(door: Door, left: bool) -> Door:
    """``door`` hinged on the other side where ``left`` differs (a single door's hinge side is a choice)."""
    return door if door.left == left else Door(door.box, left, door.opening)


def handle_at(box, left: bool, fraction: float) -> tuple[Frame, float]:
    """A vertical bar handle on a door's free stile near :data:`FULL` ``reach`` height, inside the door:
    its anchor and length (``fraction`` of the door's height)."""
    _, x1, y0, y1, z0, z1 = box
    e, st = FULL["handle_edge"], FULL["stile"]
    length = min(fraction * (z1 - z0), z1 - z0 - 2 * e)
    z = min(max(FULL["reach"], z0 + e + length / 2), z1 - e - length / 2)
    y = y1 - st / 2 if left else y0 + st / 2
    return Frame.at((x1, y, z), z=(1, 0, 0), x=(0, 0, 1)), length


def drawer_handle_at(box) -> tuple[Frame, float]:
    """A freezer drawer's horizontal bar handle under its top edge: its anchor and length."""
    _, x1, y0, y1, _, z1 = box
    return Frame.at((x1, (y0 + y1) / 2, z1 - FULL["drawer_handle_below"]), z=(1, 0, 0), x=(0, 1, 0)), \
        FULL["drawer_handle"] * (y1 - y0)


def bar(at: Frame, length: float) -> list[g.Piece]:
    """A tubular bar handle's pieces at ``at`` (along its x)."""
    h = hardware.bar_handle(length, "handle", BAR).attached("mount", to=at)
    return list(h.parts[h.root].pieces)


def skinned(pieces) -> list[g.Piece]:
    """A door's or drawer front's pieces with the steel skin (:func:`.fridges.solid_door`'s ``frame`` pan) in
    the cabinet's own ``body`` slot, so doors and cabinet are one finish, massed as steel sheet."""
    return [pc.replace(material="body", sheet=A.FRIDGE_SHEET) if pc.material == "frame" else pc for pc in pieces]


def bins(door: Door, n: int) -> list[list[g.Piece]]:
    """The pieces of ``n`` door bins moulded into a door's inner liner (static), clear of the opening as it
    swings (:func:`.fridges.door_bins`)."""
    return [FR.door_bin(s["xs"], s["ys"], s["zs"])[0] for s in FR.door_bins(n, door.box, door.opening, door.left)]


def stacked(front, zone: Zone, n: int) -> list[tuple[tuple, Zone]]:
    """``n`` freezer drawers stacked in the freezer zone, the top one first: each one's front box (the
    freezer front split with a gap between) and the slice of the zone its basket takes."""
    gap = F["gap"]
    x0, x1, y0, y1, z0, z1 = front
    cav = zone.cav
    fh, ch = (z1 - z0 + gap) / n, (cav[5] - cav[4]) / n
    return [((x0, x1, y0, y1, z1 - (k + 1) * fh + gap, z1 - k * fh),
             Zone((*cav[:4], cav[5] - (k + 1) * ch, cav[5] - k * ch), zone.xs, zone.margin)) for k in range(n)]


def freezer_drawer(front, zone: Zone, frame_family: str, travel: float) -> tuple[list[g.Piece], Frame, float]:
    """A freezer drawer: an insulated front (:func:`.fridges.solid_door`) carrying an open basket in its
    slice of the freezer zone; its pieces, slide frame (+X) and travel (``travel`` of the basket's depth)."""
    b = FULL["basket"]
    cx0, _, cy0, cy1, cz0, cz1 = zone.cav
    xa, xb = cx0 + b["back"], front[0] - F["gap"]
    basket = A.open_bin((xa, xb), (cy0 + b["side"], cy1 - b["side"]), cz0 + b["floor"],
                        cz1 - b["under"] - cz0 - b["floor"], "bin", t=b["wall"])
    pieces = skinned(FR.solid_door(front, frame_family)) + basket
    return pieces, Frame.at((front[1], 0.0, front[4]), z=(1, 0, 0)), travel * (xb - xa)


def crisper_ys(n: int, yc: float, ry: float) -> list[tuple[float, float]]:
    """``n`` crisper drawers side by side across ``yc +- ry``."""
    s = F["crisper"]["side"]
    w = (2 * ry - s * (n - 1)) / n
    return [(yc - ry + k * (w + s), yc - ry + k * (w + s) + w) for k in range(n)]


def deli_zs(cav) -> tuple[float, float]:
    """A deli drawer's bottom and top: a shallow drawer over the crispers (:data:`FULL` ``deli``)."""
    z = FR.crisper_zs(cav)[1] + F["crisper"]["over"]
    return z, z + FULL["deli"]


def basket_zs(cav, k: int) -> tuple[float, float]:
    """The ``k``-th freezer basket from the floor of a side-by-side's freezer zone: crisper-sized
    (:data:`.appliance_sizes.FRIDGE` ``crisper``), stacked."""
    z0, z1 = FR.crisper_zs(cav)
    up = k * (F["crisper"]["height"] + F["crisper"]["over"])
    return z0 + up, z1 + up


def over_baskets(cav, n: int) -> tuple:
    """The freezer zone the shelves share over ``n`` baskets."""
    return (*cav[:4], cav[4] + n * (F["crisper"]["height"] + F["crisper"]["over"]), cav[5])


def split_crispers(yc: float, ry: float) -> list[tuple[float, float]]:
    """A French-door fridge's two crispers, one behind each door (each opens with its own door)."""
    s = F["crisper"]["side"]
    return [(yc - ry, -s / 2), (s / 2, yc + ry)]


KEY = controls.Button(half=(0.012, 0.008), shape="rect", proud=0.003, travel=0.002)
"""A dispenser's selector key (ice / water / light / lock: Samsung RF28R7351SR, GE GSS25 dispensers): a
24 x 16 mm key pressing in 2 mm."""


@dataclass(frozen=True)
class Dispenser:
    """A dispenser door's pieces, its paddle's pieces, hinge and push angle, and the anchors of its keys."""

    pieces: list
    paddle: list
    hinge: Frame
    push: float
    keys: list


def dispenser_door(door: Door, frame_family: str, keys: int) -> Dispenser:
    """A door with a water/ice dispenser: its pan cut by a recess (:data:`FULL` ``dispenser``) with a dark back
    and a drip grille, centred across the door clear of its handle stile, a row of ``keys`` selector keys over
    it (each in its own hole); the paddle hung under the recess top, its hinge (about +Y: the paddle's foot
    swings in, -X) and push angle."""
    d = FULL["dispenser"]
    x0, x1, y0, y1, z0, z1 = door.box
    st = FULL["stile"]
    yc = (y0 + y1) / 2 + (-st / 2 if door.left else st / 2)
    ya, yb = yc - d["width"] / 2, yc + d["width"] / 2
    za, zb = d["z"] - d["height"] / 2, d["z"] + d["height"] / 2
    pieces = FR.solid_door(door.box, frame_family)
    pan = pieces[0]
    xp = x1 - FR.F["solid_door"]["pan"] * (x1 - x0)
    xr = x1 - d["depth"]
    zk = zb + d["keys_over"]
    ks = [(ya + (k + 0.5) * d["width"] / keys, zk) for k in range(keys)]
    cuts = [KEY.cutout("front", at) for at in ks]
    holes = [(ya, za, yb, zb)] + [(c.lo[0], c.lo[1], c.hi[0], c.hi[1]) for c in cuts]
    pieces[0] = g.panel([xp, y0, z0], [x1, y1, z1], "frame", "x", holes=holes).replace(sheet=pan.sheet)
    pieces = skinned(pieces)
    pieces += [g.box_between([xr - d["back"], ya, za], [xr, yb, zb], "display"),
               g.box_between([xr, ya, za], [x1 - d["tray_in"], yb, za + d["tray"]], "grille")]
    (hw, ph, pt), (fx, down) = d["paddle"], d["pivot"]
    xa, zp = x1 - fx, zb - down
    paddle = [g.box_between([xa - pt, yc - hw, zp - ph], [xa, yc + hw, zp], "paddle", bevel=0.0015),
              g.cylinder([xa - pt / 2, yc - hw, zp], [xa - pt / 2, yc + hw, zp], d["hinge_r"], "paddle", 12)]
    return Dispenser(pieces, paddle, Frame.at((xa - pt / 2, yc, zp), z=(0, 1, 0)), d["push"],
                     [Frame.at((x1, y, z), z=(1, 0, 0), x=(0, 0, 1)) for y, z in ks])
