"""Counter-top toaster ovens: a sheet casing with a cavity behind a drop-down glass door, a control column on
the right, wire racks on side rails and a crumb tray under the cavity floor.

The casing is a :func:`~.casing.sheet_casing` whose front has named cut-outs: ``cavity`` (the door's
opening), ``tray_opening`` (under it) and one hole per knob (``knob_0`` ...) and key (``key_0`` ...) down the
control column; :func:`casing` adds the inner works (the wall between cavity and controls, the cavity floor,
the rack rails, the heating elements, rubber feet) and anchors ``hinge`` (the door's drop hinge: about +Y at
the door's bottom front edge) and ``rack_<k>`` (a rack's slide out of the front, z along +X). X is depth (the
door faces +X), Y width, Z up; the controls are on the right seen from the front (+Y).

Designs (real product types, sizes below with their sources): ``compact`` (4-slice, one rack), ``six_slice``
(6-slice / 12 in pizza, two rack levels), ``air_fry`` (a taller air-fryer toaster oven, one or two racks).
"""

from __future__ import annotations

from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly

from . import appliance as A
from . import controls, hardware, ovens
from .casing import CasingSize, Cutout, LinerSize, sheet_casing


@dataclass(frozen=True)
class Design:
    """A toaster oven design: outer ``width`` (Y), ``depth`` (X, door included), ``height`` (Z, feet
    included) ranges (m); ``racks`` and ``knobs`` (lo, hi) counts; ``keys`` (lo, hi) push keys."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    racks: tuple[int, int]
    knobs: tuple[int, int]
    keys: tuple[int, int]

    def at(self, t: float, tall: float | None = None) -> tuple[float, float, float]:
        """(width, depth, height) at ``t`` of its size range (0: the smallest, 1: the largest); the height at
        ``tall`` of its range where given (models of one footprint differ in height)."""
        h = t if tall is None else tall
        return tuple(lo + f * (hi - lo) for (lo, hi), f in zip((self.width, self.depth, self.height), (t, t, h)))


# Retail spec listings (manufacturer pages, inches converted, approximate): a 4-slice toaster oven is 14-16 in
# wide, 10-12 in deep, 8-9.5 in tall with one rack and 2-3 knobs (Black+Decker TO1313SB ~14.4 x 10.4 x 8.3 in,
# Hamilton Beach 31401 ~14.8 x 11 x 8.5 in); a 6-slice / 12 in pizza oven 16.5-19 in wide, 11-15 in deep,
# 9.5-11.5 in tall with two rack levels and 3 knobs (Cuisinart TOB-135 ~18.5 x 12 x 10.3 in, Breville BOV800XL
# 18.5 x 11.3 x 10.9 in: 3 knobs and keys); an air-fryer toaster oven 15.5-18 in wide, 14-16.5 in deep,
# 12-14 in tall (Cuisinart TOA-60 15.5 x 16 x 14 in: 3 knobs; Instant Vortex Plus and Breville BOV900 use keys).
DESIGNS = {
    "compact": Design((0.36, 0.40), (0.26, 0.30), (0.20, 0.24), (1, 1), (2, 3), (0, 0)),
    "six_slice": Design((0.42, 0.48), (0.29, 0.37), (0.24, 0.29), (2, 2), (3, 3), (0, 2)),
    "air_fry": Design((0.39, 0.46), (0.36, 0.42), (0.30, 0.36), (1, 2), (2, 3), (0, 2)),
}

SHEET = 0.0006  # m, 0.5-0.7 mm steel casing sheet (massed so)
WALL = 0.003  # m, walls as the simulator sees them
FEET = (0.008, 0.012)  # m, rubber feet radius and height
PANEL = 0.105  # m, the control column's width (Breville BOV800XL ~4 in, Black+Decker TO1313 ~3.5 in)
FLOOR = 0.04  # m, the cavity floor over the casing's bottom: the crumb tray slides in under it
# A toaster oven's door bar is a 12-14 mm tube standing ~22 mm off the glass (product photos: Black+Decker
# TO1313SB, Cuisinart TOB-135), far slighter than a range's 20 mm bar 40 mm out: the door drops to horizontal
# with the bar hanging clear over the counter, under the hinge at FLOOR + the feet (HANDLE_REACH < FLOOR).
HANDLE = hardware.HandleSize(standoff=0.022, bar_radius=0.0065, post_radius=0.005, inset=0.02)
HANDLE_REACH = HANDLE.standoff + 2 * HANDLE.bar_radius  # m, the open door's bar hangs this far under its hinge
TOP = 0.02  # m, the casing over the door's top
DOOR = dict(thickness=0.022, gap=0.003, margin=0.02, handle=0.7)  # a glazed door 20-25 mm thick, its bar 70 % wide
DOOR_OPENS = 1.571  # rad, a drop-down door opens to horizontal
RACK_LEVELS = {1: (0.35,), 2: (0.22, 0.6)}  # rack heights as shares of the cavity's height
RACK_FRONT, RACK_BACK, RACK_SIDE = 0.025, 0.015, 0.004  # m, a rack's wires inside the cavity
RACK_PULL = 0.55  # a rack slides out this share of its depth to its stop
ELEMENT_R = 0.005  # m, quartz / sheathed heating element tubes, two under the roof and two over the floor
# Each quartz tube ends in a metal cap held in a socket bracket on the side walls (Breville BOV800XL,
# Cuisinart TOB-260 product photos: ~14 mm caps ~12 mm long, on a ~25 x 20 mm bracket)
ELEMENT_CAP = (0.007, 0.012)  # m, the cap's radius and length
ELEMENT_BRACKET = (0.025, 0.02, 0.0015)  # m, the socket bracket's height, width (along x) and thickness
TRAY = dict(height=0.012, lip=0.008, clearance=0.002, pull=0.9)
# Knobs: temperature (~270 degrees), function (~180), timer (~300) on 32-40 mm knobs (product photos).
KNOB = controls.Dial(radius=0.017, stem=0.004, style="ridge", turns=4.712)
KNOB_TURNS = (4.712, 3.142, 5.236)
KEY = controls.Button(half=(0.011, 0.006), shape="rect", proud=0.003, travel=0.002)
KEY_ROW = 0.03  # m, the row of keys (side by side, KEY_PITCH apart) under the knobs
KEY_PITCH = 0.027
RACK_OVER = 0.002  # m, a rack's wires ride this far over its rails (play, as on a range's racks)


@dataclass(frozen=True)
class Oven:
    """Where a toaster oven's parts go: its casing ``size``, the cavity box ``cav`` (x0, x1, y0, y1, z0, z1),
    the door box, the crumb tray's size and centre ``tray_y``, and the control column's centre ``panel_y``."""

    size: CasingSize
    cav: tuple
    door: tuple
    tray: LinerSize
    tray_y: float
    panel_y: float


def oven(design: str, t: float, corner: float, tall: float | None = None) -> Oven:
    """The layout of a ``design`` toaster oven at ``t`` of its size range (its height at ``tall`` of its range,
    if given) with upright edges of ``corner``."""
    W, D, H = DESIGNS[design].at(t, tall)
    depth, height = D - DOOR["thickness"] - DOOR["gap"], H - FEET[1]
    size = CasingSize(W, depth, height, WALL, SHEET, corner)
    x0, x1, yp = -depth / 2 + WALL, depth / 2 - WALL, W / 2 - PANEL  # the control column on the right (+Y)
    post = W / 2 - max(WALL, 2 * corner)  # inside the corner posts
    cav = (x0, x1, -post, yp - WALL, FLOOR, height - TOP)
    xd = depth / 2 + DOOR["gap"]
    door = (xd, xd + DOOR["thickness"], -W / 2 + corner, yp, FLOOR, height - TOP / 2)
    c = TRAY["clearance"]
    ty0, ty1 = -post + c, cav[3] - c
    tray = LinerSize(ty1 - ty0, depth - 2 * WALL - c, TRAY["height"], WALL, SHEET, TRAY["lip"], WALL)
    return Oven(size, cav, door, tray, (ty0 + ty1) / 2, (yp + post) / 2)


def cutouts(o: Oven, knobs: int, keys: int) -> dict[str, Cutout]:
    """The front's holes: the cavity's opening, the tray's opening under it and the control column's knobs
    (evenly down it) over a row of keys; face coordinates u = -y, v = z - height / 2."""
    (_, _, y0, y1, z0, z1), hv, c = o.cav, o.size.height / 2, TRAY["clearance"]
    cuts = {"cavity": Cutout("front", (-y1, z0 - hv), (-y0, z1 - hv))}
    yc, lo, half = o.tray_y, WALL - hv, o.tray.width / 2 + c
    h = o.tray.height + o.tray.lip
    cuts["tray_opening"] = Cutout("front", (-yc - half, lo), (-yc + half, lo + h + 2 * c), (-yc, lo + c + h / 2))
    top, bottom = z1 - hv, z0 - hv + (KEY_ROW if keys else 0.0)
    pitch = (top - bottom) / max(knobs, 1)
    for k in range(knobs):
        cuts[f"knob_{k}"] = KNOB.cutout("front", (-o.panel_y, top - (k + 0.5) * pitch))
    for k in range(keys):
        u = -o.panel_y + (k - (keys - 1) / 2) * KEY_PITCH
        cuts[f"key_{k}"] = KEY.cutout("front", (u, bottom - KEY_ROW / 2))
    return cuts


def casing(o: Oven, racks: int, cuts: dict[str, Cutout]) -> Assembly:
    """The casing with its inner works; anchors ``hinge``, ``rack_<k>`` and the cut-outs'."""
    s, (x0, x1, y0, y1, z0, z1) = o.size, o.cav
    body = sheet_casing(s, "body", cuts)
    rf, fh = FEET
    pieces = [g.box_between((x0, y1, WALL), (x1, y1 + WALL, s.height - WALL), "interior"),  # wall to the controls
              g.box_between((x0, y0, z0 - WALL), (x1, y1, z0), "interior")]  # the cavity floor
    for z in (z0 + 2 * ELEMENT_R, z1 - 2 * ELEMENT_R):
        pieces += [g.cylinder((x, y0, z), (x, y1, z), ELEMENT_R, "element", 12) for x in (x0 / 2, x1 / 2)]
    pieces = [pc.replace(sheet=SHEET) for pc in pieces]
    pieces += element_sockets(o)
    xf, yf = s.depth / 2 - 2 * rf, s.width / 2 - 2 * rf
    pieces += [g.cylinder((x, y, -fh), (x, y, 0.0), rf, "feet", 12) for x in (-xf, xf) for y in (-yf, yf)]
    anchors = {"hinge": A.drop_hinge(o.door)}
    for k in range(racks):
        xs, ys, zc = rack_box(o, racks, k)
        w, h = A.RAIL
        top = zc - A.OVEN_RACK_R - RACK_OVER
        pieces += [g.box_between((xs[0], ya, top - h), (xs[1], yb, top), "interior").replace(sheet=SHEET)
                   for ya, yb in ((y0, y0 + w), (y1 - w, y1))]
        anchors[f"rack_{k}"] = A.rack_slide(xs, zc, RACK_PULL, (ys[0] + ys[1]) / 2)[0]
    return body.with_pieces(body.root, pieces).with_anchors(**anchors)


def element_sockets(o: Oven) -> list[g.Piece]:
    """The heating tubes' metal end caps and the brackets holding them on the cavity's side walls: what makes
    the tubes read as elements wired into the oven (drawn, no collision: the tubes collide)."""
    x0, x1, y0, y1, z0, z1 = o.cav
    (rc, lc), (bh, bw, bt), out = ELEMENT_CAP, ELEMENT_BRACKET, []
    for z in (z0 + 2 * ELEMENT_R, z1 - 2 * ELEMENT_R):
        for x in (x0 / 2, x1 / 2):
            for y, s in ((y0, 1.0), (y1, -1.0)):
                out += [g.cylinder((x, y, z), (x, y + s * lc, z), rc, "trim", 16),
                        g.box_between((x - bw / 2, min(y, y + s * bt), z - bh / 2),
                                      (x + bw / 2, max(y, y + s * bt), z + bh / 2), "trim")]
    return [pc.replace(convex=()) for pc in out]


def rack_box(o: Oven, racks: int, k: int) -> tuple:
    """Rack ``k`` of ``racks``: its ``xs``, ``ys`` and wire height."""
    x0, x1, y0, y1, z0, z1 = o.cav
    xs = (x0 + RACK_BACK, x1 - RACK_FRONT)
    return xs, (y0 + A.RAIL[0] + RACK_SIDE, y1 - A.RAIL[0] - RACK_SIDE), z0 + RACK_LEVELS[racks][k] * (z1 - z0)


def rack(o: Oven, racks: int, k: int) -> tuple[list[g.Piece], float]:
    """Rack ``k``'s wires and its travel out of the cavity."""
    xs, ys, zc = rack_box(o, racks, k)
    return A.oven_rack(xs, ys, zc), RACK_PULL * (xs[1] - xs[0])


def door(o: Oven) -> list[g.Piece]:
    """The glazed drop-down door with its bar handle (:func:`.ovens.door`)."""
    return ovens.door(o.door, DOOR["margin"], DOOR["handle"], HANDLE)
