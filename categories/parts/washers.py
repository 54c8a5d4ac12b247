"""Washing machines: a sheet casing on adjustable feet around a drum, loaded through a round porthole door in
the front (a front loader, a washer-dryer) or through a lid in the top (a top loader with its control console
at the back).

World-aligned like :mod:`.appliance`: X is depth (fronts face +X), Y width, Z up; the casing is a
:func:`~.casing.sheet_casing` standing on z = 0 (its feet below), so a front's face coordinates are
``u = -y``, ``v = z - height / 2`` and a top's ``u = y``, ``v = x``. A front loader's front has named
cut-outs: ``porthole`` (the square the loading ring fills), ``drawer`` (the detergent drawer, top left),
``flap`` (the service flap over the drain-pump filter, bottom right) and one per control (``knob_<k>``,
``key_<k>``) in the control band across the top; a top loader's top has the ``tub`` cut-out and its console
anchors ``knob_<k>`` / ``key_<k>`` on its front face. Round things are built round their own axis (local z)
and put in place with the cut-out's anchor frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grasps import Grasp

from . import appliance as A
from . import controls, hardware
from .casing import CasingSize, Cutout, LinerSize, liner, sheet_casing


@dataclass(frozen=True)
class Design:
    """A washing machine type: outer ``width`` (Y), casing ``depth`` (X, door excluded) and ``height`` (Z, feet
    and console included) ranges (m); the porthole door's outer ``door`` diameter range (a top loader: its tub
    opening's); ``knobs`` and ``buttons`` (lo, hi) counts; ``machine`` kg of hidden works (drum unit, motor,
    counterweights)."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    door: tuple[float, float]
    knobs: tuple[int, int]
    buttons: tuple[int, int]
    machine: float

    def at(self, t: float, tall: float) -> tuple[float, float, float]:
        """(width, depth, height) at ``t`` of the footprint range and ``tall`` of the height range."""
        return tuple(lo + f * (hi - lo) for (lo, hi), f in zip((self.width, self.depth, self.height), (t, t, tall)))


# Spec sheets (manufacturer pages, approximate): European front loaders are 595-600 mm wide, 845-850 mm tall and
# 550-650 mm deep without the door (Bosch Serie 4 WAN28281GB 848 x 598 x 590 mm, Samsung WW90T534DAW 850 x 600 x
# 550 mm, LG F4V310WNE 850 x 600 x 565 mm, Miele WWD320 850 x 596 x 643 mm); their porthole doors are 45-53 cm
# across round a 30-34 cm loading opening (Bosch "32 cm door", Samsung 34 cm); 2-8 keys beside the program dial,
# older mechanical models a second (temperature) knob (Zanussi ZWF, Hotpoint WMAQ). Washer-dryers are the same
# front, deeper for the condenser (Bosch WNA14400GB 848 x 598 x 620 mm, Samsung WD90T534DBW 850 x 600 x 600 mm,
# LG FWV796WTSE 850 x 600 x 615 mm), some with a drying-time knob (Indesit IWDC 6125) and more keys. US top
# loaders are 27-27.5 in wide and deep and 42-44 in tall to the top of the console (Whirlpool WTW5000DW 27.5 x
# 27 x 42 in, GE GTW465ASNWW 27 x 27.75 x 42 in), a 40-45 cm tub opening under a glass or painted lid, 1-3 knobs
# and up to 6 keys on the console. Hidden works: concrete counterweights 20-25 kg, motor 5-8 kg, tub and drum
# 12-15 kg on a front loader (a washer-dryer adds heater, fan and condenser, ~4 kg); a top loader's
# transmission and motor ~15 kg, tub and basket ~15 kg, balance ring ~5 kg (service manuals' part weights,
# approximate): the casing, drum, door and controls are massed as modelled.
DESIGNS = {
    "front_loader": Design((0.595, 0.600), (0.55, 0.65), (0.845, 0.850), (0.46, 0.52), (1, 2), (2, 8), 38.0),
    "washer_dryer": Design((0.595, 0.600), (0.60, 0.65), (0.845, 0.850), (0.46, 0.52), (1, 2), (3, 8), 44.0),
    "top_loader": Design((0.686, 0.700), (0.660, 0.705), (1.03, 1.09), (0.40, 0.45), (1, 3), (0, 6), 34.0),
}

SHEET = 0.0007  # m, 0.6-0.8 mm steel casing sheet (massed so)
WALL = 0.004  # m, walls as the simulator sees them
FEET = (0.018, 0.015)  # m, adjustable feet: radius, height screwed in
BAND = dict(top=0.015, height=0.10)  # m, the control band across the top of a front: margin over it, height
OPENING = 0.33  # the loading opening's diameter as a share of the door's (32-34 cm in a 49-52 cm door)
RIM = 0.25  # the door ring's width as a share of its radius (a 34-38 cm window in a 49-52 cm door)
DOOR = dict(gap=0.006, ring=0.05, trim=0.004, bowl=0.06, glass=0.006)  # m: off the front, ring depth, trim
# ring, glass bowl depth into the opening and its wall (5-8 mm tempered glass)
HINGE = dict(length=0.24, radius=0.008, moving=0.55, plate=0.004, reach=0.018, arm=0.03)  # m: the porthole door's
# hinge at its left edge, a 20-25 cm block on the front with the door's arm between its two knuckles (Bosch Serie
# 4, Samsung WW90 doors, manufacturers' pictures), the arm's share of it, the block's plate on the front (in the
# door's 6 mm gap), its reach beside the pin and the door arm's reach into the ring. The body's knuckles sit where
# the round ring's edge is more than their radius from the pin, so the ring never sweeps through them.
DOOR_OPENS = math.radians(170)  # porthole doors open 165-180 degrees (Bosch Serie 4 ~171, Samsung 180, approx.)
GASKET = dict(depth=0.07, wall=0.015)  # m, the rubber boot from the opening back to the drum
DRUM = dict(radius=0.235, sheet=0.0006, lifters=3, from_back=0.1)  # 46-48 cm stainless drums, three lifters
DRAWER = dict(width=0.22, depth=0.40, height=0.075, lip=0.008, wall=0.003, sheet=0.002, pull=0.72, side=0.03)
# m: 20-24 cm wide detergent drawers pulling out ~30 cm to their stop (Bosch, Samsung, LG manuals' pictures);
# moulded PP 2-3 mm (massed so)
COMPARTMENTS = dict(split=(0.5, 0.75), wall=0.85, siphon=(0.009, 0.025), siphon_back=0.04)
# a drawer's main-wash compartment takes half its width, pre-wash and softener a quarter each, their walls 85 %
# of its height; the softener's siphon cap, 18 mm across and 25 mm tall, stands near its back (Bosch Serie 4,
# Samsung WW90 drawers in their manuals)
FLAP = dict(width=0.16, height=0.12, side=0.03, above=0.02, recess=0.045)  # m, the service flap bottom right
FLAP_OPENS = math.radians(90)  # it drops forward to flat
FILTER = controls.Dial(radius=0.03, stem=0.01, style="ridge", turns=math.pi)  # a drain-pump filter cap with a
# grip bar, unscrewed anticlockwise half a turn before it pulls out (Bosch, Samsung manuals)
PROGRAM = dict(radius=0.032, stem=0.006, timer=math.radians(330), other=math.radians(270))  # 60-70 mm dials; a
# mechanical timer and a temperature knob turn between stops, an electronic selector turns endlessly
KNOB_GAP = 0.025  # m, between a dial and its neighbours
KEY = controls.Button(half=(0.011, 0.006), shape="rect", proud=0.003, travel=0.002)
DISPLAY = dict(height=0.03, over=0.012, row=0.022)  # m, the display strip over the keys, the keys under the
# band's middle, a second row of keys under the first where one row does not hold them
KEY_PITCH = 2 * KEY.half[0] + 2 * A.CLEAR + 0.005  # m, the closest keys stand side by side
CONSOLE = dict(depth=0.12, height=0.14, hinge=0.05, lid=0.025, margin=0.025, side=0.07)  # m: a top loader's
# back console (depth, height over the top), the lid's hinge in front of it, lid thickness, front and side margins
LID_OPENS = math.radians(90)  # a top loader's lid stands up against the console
LID_WINDOW = 0.06  # m, a glass lid's frame round its window
TUB = dict(rim=0.03, bottom=0.25, agitator=0.05, post=0.08, depth=0.5)  # m: the tub under the top, its floor,
# agitator radius, its post's top under the tub ring, the basket's depth (a 3.5-4.7 cu ft basket ~0.5 m across
# and ~0.5 m deep: Whirlpool WTW4816, WTW5000DW, Speed Queen TR service manuals, approximate)
# A top loader washes with one of two real mechanisms (Whirlpool, GE, Speed Queen, LG product photos):
# an ``agitator``, a tapering post the basket's depth with a flared skirt ~0.7 of the basket across and 4-6
# vanes on it, and fins down the post; or an ``impeller`` (pulsator), a low domed plate ~0.8 of the basket across
# and 4-6 cm high with raised radial fins round a hub. Sizes as shares of the basket radius / depth.
AGITATOR = dict(skirt=0.7, skirt_h=0.22, top_r=0.035, vanes=4, vane_t=0.012, fins=3, fin_out=0.02)
IMPELLER = dict(radius=0.8, height=0.05, hub=0.18, fins=6, fin_t=0.012)
WASH_ACTIONS = ("agitator", "impeller")
HOSE = dict(radius=0.008, plug=0.011, length=0.02, cap=0.012, beside=0.055, pull=0.15)  # m: an emergency drain
# hose clipped beside the filter, its plug; it pulls ~15 cm out to drain into a bowl (Bosch, Samsung manuals)
CUP = dict(radius=0.045, height=0.05, wall=0.003, seat=0.02)  # m: a fabric-softener dispenser cup on the
# agitator's top (Whirlpool agitators), pressed 2 cm over the post; it lifts off to be cleaned


@dataclass(frozen=True)
class Machine:
    """Where a washing machine's parts go: its casing ``size``, the control ``band`` zs (front styles) or console
    box (x front, z bottom, z top), the porthole's centre height ``zc`` and door radius ``rd`` (top loader: the
    tub's centre x and opening radius)."""

    design: str
    size: CasingSize
    band: tuple
    zc: float
    rd: float
    wash: str = "agitator"  # a top loader's wash action (:data:`WASH_ACTIONS`)

    @property
    def front(self) -> bool:
        return self.design != "top_loader"

    @property
    def x_face(self) -> float:
        return self.size.depth / 2


def machine(design: str, t: float, tall: float, door: float, corner: float, wash: str = "agitator") -> Machine:
    """The layout of a ``design`` washing machine at ``t`` of its footprint range, ``tall`` of its height range and
    ``door`` of its door (tub opening) range, upright edges rounded to ``corner`` (a top loader washing with
    ``wash``)."""
    d = DESIGNS[design]
    W, D, H = d.at(t, tall)
    rd = (d.door[0] + door * (d.door[1] - d.door[0])) / 2
    if design == "top_loader":
        hc = H - FEET[1] - CONSOLE["height"]
        xc = -D / 2 + CONSOLE["depth"]
        lid = (xc + CONSOLE["hinge"], D / 2 - CONSOLE["margin"])
        r = min(rd, (lid[1] - lid[0]) / 2 - TUB["rim"], W / 2 - CONSOLE["side"])
        return Machine(design, CasingSize(W, D, hc, WALL, SHEET, corner), (xc, hc, hc + CONSOLE["height"]),
                       (lid[0] + lid[1]) / 2, r, wash)
    hc = H - FEET[1]
    top = hc - BAND["top"]
    band = (top - BAND["height"], top)
    return Machine(design, CasingSize(W, D, hc, WALL, SHEET, corner), band, band[0] - KNOB_GAP - rd, rd)


def r_open(m: Machine) -> float:
    """The loading opening's radius."""
    return OPENING * 2 * m.rd if m.front else m.rd


def _front(m: Machine, y: float, z: float) -> tuple[float, float]:
    """Face coordinates (u, v) of world (y, z) on the front."""
    return -y, z - m.size.height / 2


def control_spots(m: Machine, knobs: int, keys: int) -> tuple[list, list, tuple]:
    """Where the dials and keys go, as world (y, z): the program dial right of the detergent drawer (a front)
    or in the middle of the console (a top loader), other knobs at the right end (left end of the console),
    the keys in a row between under the display; and the display's (y0, y1, z0, z1)."""
    W, r = m.size.width, PROGRAM["radius"]
    if m.front:
        zm = (m.band[0] + m.band[1]) / 2
        y_prog = -W / 2 + DRAWER["side"] + DRAWER["width"] + KNOB_GAP + r
        more = [W / 2 - DRAWER["side"] - r - k * (2 * r + KNOB_GAP) for k in range(knobs - 1)]
        ys = (y_prog + r + KNOB_GAP, (more[-1] - r - KNOB_GAP) if more else W / 2 - DRAWER["side"])
    else:
        zm = (m.band[1] + m.band[2]) / 2
        y_prog = 0.0
        more = [-W / 2 + CONSOLE["side"] + r + k * (2 * r + KNOB_GAP) for k in range(knobs - 1)]
        ys = (r + KNOB_GAP, W / 2 - CONSOLE["side"])
    knob_at = [(y, zm) for y in [y_prog] + more]
    rows = 1 if keys * KEY_PITCH <= ys[1] - ys[0] else 2
    per_row = -(-keys // rows)
    pitch = (ys[1] - ys[0]) / max(per_row, 1)
    key_at = [(ys[0] + (k % per_row + 0.5) * pitch, zm - DISPLAY["over"] - (k // per_row) * DISPLAY["row"])
              for k in range(keys)]
    display = (ys[0], ys[1], zm, zm + DISPLAY["height"])
    return knob_at, key_at, display


def cutouts(m: Machine, knobs: int, keys: int, flap: bool) -> dict[str, Cutout]:
    """The casing's holes: a front's porthole square, drawer, service flap and controls; a top's tub square."""
    if not m.front:
        a = m.rd + TUB["rim"]
        return {"tub": Cutout.around("top", (0.0, m.zc), (2 * a, 2 * a))}
    W, c = m.size.width, A.CLEAR
    a = r_open(m) + GASKET["wall"]
    cuts = {"porthole": Cutout.around("front", (0.0, m.zc - m.size.height / 2), (2 * a, 2 * a))}
    dh = DRAWER["height"] + DRAWER["lip"]
    zd = (m.band[0] + m.band[1]) / 2
    cuts["drawer"] = Cutout.around("front", _front(m, -W / 2 + DRAWER["side"] + DRAWER["width"] / 2, zd),
                                   (DRAWER["width"], dh), c)
    if flap:
        y, z = W / 2 - FLAP["side"] - FLAP["width"] / 2, FLAP["above"] + FLAP["height"] / 2
        cuts["flap"] = Cutout.around("front", _front(m, y, z), (FLAP["width"], FLAP["height"]), c)
    knob_at, key_at, _ = control_spots(m, knobs, keys)
    for k, (y, z) in enumerate(knob_at):
        cuts[f"knob_{k}"] = controls.Dial(PROGRAM["radius"], PROGRAM["stem"]).cutout("front", _front(m, y, z))
    for k, (y, z) in enumerate(key_at):
        cuts[f"key_{k}"] = KEY.cutout("front", _front(m, y, z))
    return cuts


def holed_plate(half: float, r: float, t: float, slot: str) -> g.Piece:
    """A square plate ``2 half`` across in the local xy plane (z from -``t`` to 0) with a round hole of radius ``r``
    in its middle: the ring a loading opening is set in. Collision: one convex wedge per section of the hole,
    reaching out to the square (split at its corners)."""
    box = trimesh.creation.box((2 * half, 2 * half, t), trimesh.transformations.translation_matrix((0, 0, -t / 2)))
    n = g.sections_for(r)
    hole = trimesh.creation.cylinder(radius=r, height=2 * t, sections=n)
    mesh = g.subtract(box, [hole])
    corners = [math.pi / 4 * (2 * k + 1) for k in range(4)]
    angles = np.unique(np.round(np.r_[np.linspace(0, 2 * math.pi, n + 1), corners], 9))
    convex = []
    for a0, a1 in zip(angles[:-1], angles[1:]):
        pts = []
        for a in (a0, a1):
            c, s = math.cos(a), math.sin(a)
            d = half / max(abs(c), abs(s))
            pts += [(x, y, z) for x, y in ((r * c, r * s), (d * c, d * s)) for z in (-t, 0.0)]
        convex.append(np.array(pts))
    return g.Piece(mesh.vertices, mesh.faces, slot, convex)


def _placed(pieces, at: Frame) -> list[g.Piece]:
    return [pc.transformed(at.matrix) for pc in pieces]


def drum(m: Machine, at: Frame) -> list[g.Piece]:
    """Behind a loading opening (its anchor ``at``, z out of the casing): the ring plate, the rubber boot (a front)
    or tub ring (a top), the stainless drum with its lifters and back, seen through the door's glass."""
    ro, gw = r_open(m), GASKET["wall"]
    pieces = [holed_plate(ro + gw, ro, WALL, "body").replace(sheet=SHEET)]
    deep = m.size.depth - DRUM["from_back"] - GASKET["depth"] if m.front else TUB["depth"]
    rdrum = DRUM["radius"] if m.front else ro + TUB["rim"] - WALL
    z0 = -GASKET["depth"]
    pieces.append(g.shell([(ro, z0), (ro, 0.0)], gw, "gasket" if m.front else "liner"))
    pieces.append(g.shell([(rdrum, z0 - deep), (rdrum, z0)], DRUM["sheet"] * 5, "drum").replace(sheet=DRUM["sheet"]))
    pieces.append(g.shell([(rdrum, z0 - WALL), (rdrum, z0)], rdrum - ro + gw, "drum").replace(sheet=DRUM["sheet"]))
    back = g.cylinder((0, 0, z0 - deep - WALL), (0, 0, z0 - deep), rdrum, "drum")
    pieces.append(back.replace(sheet=DRUM["sheet"]))
    lift = 0.12 * rdrum
    for k in range(DRUM["lifters"] if m.front else 0):  # a top loader's basket has an agitator, no paddles
        turn = Frame.at((0, 0, 0)).turned("z", 2 * math.pi * k / DRUM["lifters"]).matrix
        pieces.append(g.box_between((rdrum - lift, -lift / 2, z0 - deep), (rdrum - WALL, lift / 2, z0 - WALL),
                                    "drum", bevel=0.004).transformed(turn))
    if not m.front:  # what washes the load: an agitator up the middle of the basket, or a low impeller plate
        pieces += (agitator if m.wash == "agitator" else impeller)(rdrum, z0 - deep, z0 - TUB["post"])
    return _placed(pieces, at)


def agitator(rb: float, floor: float, top: float) -> list[g.Piece]:
    """A top loader's agitator on the basket floor (radius ``rb``, floor at ``floor``, z up the basket) up to
    ``top``: a post flaring into a skirt with vanes on it, and fins down the upper post (:data:`AGITATOR`)."""
    a, ra = AGITATOR, TUB["agitator"]
    rs, hs = a["skirt"] * rb, a["skirt_h"] * (top - floor)
    post = g.revolve([(0, floor), (rs, floor), (rs, floor + 0.015), (0.45 * rs, floor + 0.4 * hs),
                      (ra, floor + hs), (a["top_r"], top - 0.01), (a["top_r"] - 0.006, top), (0, top)], "agitator")
    out = [post]
    for k in range(a["vanes"]):  # vanes standing on the skirt, from the post out to its rim
        turn = Frame.at((0, 0, 0)).turned("z", 2 * math.pi * (k + 0.5) / a["vanes"]).matrix
        vane = g.box_between((ra, -a["vane_t"] / 2, floor + 0.01), (0.95 * rs, a["vane_t"] / 2, floor + 0.045),
                             "agitator", bevel=0.004)
        rise = g.box_between((ra - 0.01, -a["vane_t"] / 2, floor + 0.04), (0.55 * rs, a["vane_t"] / 2,
                                                                           floor + 0.8 * hs), "agitator", bevel=0.004)
        out += [vane.transformed(turn), rise.transformed(turn)]
    for k in range(a["fins"]):  # fins down the upper post (the "dual action" auger's, drawn straight)
        turn = Frame.at((0, 0, 0)).turned("z", 2 * math.pi * k / a["fins"]).matrix
        fin = g.box_between((a["top_r"] - 0.004, -0.004, floor + hs + 0.02), (a["top_r"] + a["fin_out"], 0.004,
                                                                              top - 0.03), "agitator", bevel=0.002)
        out.append(fin.transformed(turn))
    return out


def impeller(rb: float, floor: float, top: float) -> list[g.Piece]:
    """A low-profile impeller on the basket floor (radius ``rb``): a shallow dome with a hub and raised radial
    fins (:data:`IMPELLER`); ``top`` is unused (it stays low: the load fills the basket over it)."""
    i = IMPELLER
    r, h = i["radius"] * rb, i["height"]
    out = [g.revolve([(0, floor), (r, floor), (r, floor + 0.01), (0.6 * r, floor + 0.45 * h),
                      (i["hub"] * rb, floor + h), (0, floor + h + 0.01)], "agitator")]
    for k in range(i["fins"]):
        turn = Frame.at((0, 0, 0)).turned("z", 2 * math.pi * k / i["fins"]).matrix
        fin = g.box_between((i["hub"] * rb, -i["fin_t"] / 2, floor + 0.005), (0.95 * r, i["fin_t"] / 2,
                                                                              floor + 0.4 * h + 0.012),
                            "agitator", bevel=0.004)
        out.append(fin.transformed(turn))
    return out


def body(m: Machine, knobs: int, keys: int, flap: bool) -> Assembly:
    """The casing with its drum, feet, hidden works and (a front) control band decor or (a top) console;
    anchors: the cut-outs', ``filter`` (a front with a flap: the filter cap's mount in its recess) and (a top)
    ``lid`` (the lid's hinge) and the console's ``knob_<k>`` / ``key_<k>``."""
    s = m.size
    cuts = cutouts(m, knobs, keys, flap)
    casing = sheet_casing(s, "body", cuts)
    hole = "porthole" if m.front else "tub"
    pieces = drum(m, casing.anchor(hole))
    if m.front:
        pieces += _placed(door_hinge(m)[0], casing.anchor(hole))
    fr, fh = FEET
    xf, yf = s.depth / 2 - 2 * fr, s.width / 2 - 2 * fr
    pieces += [g.cylinder((x, y, -fh), (x, y, 0.0), fr, "feet", 12) for x in (-xf, xf) for y in (-yf, yf)]
    under = m.zc - (DRUM["radius"] if m.front else 0.0) - 2 * WALL
    if not m.front:
        under = s.height - GASKET["depth"] - TUB["depth"] - 2 * WALL
    pieces.append(A.machine_can(0.0, WALL, under - WALL, DRUM["from_back"], "machine", DESIGNS[m.design].machine,
                                "works"))
    knob_at, key_at, display = control_spots(m, knobs, keys)
    y0, y1, z0, z1 = display
    anchors = {}
    if m.front:
        pieces.append(g.box_between((m.x_face, y0, z0), (m.x_face + 0.001, y1, z1), "display"))
        if flap:
            pieces += filter_recess(m, cuts["flap"])
            anchors["filter"] = casing.anchor("flap").moved(dz=-FLAP["recess"])
            anchors["hose"] = anchors["filter"].moved(dy=HOSE["beside"])
    else:
        pieces += console(m, knob_at, key_at, display)
        xc = m.band[0]
        for name, spots in (("knob", knob_at), ("key", key_at)):
            anchors.update({f"{name}_{k}": Frame.at((xc, y, z), z=(1, 0, 0), x=(0, 0, 1))
                            for k, (y, z) in enumerate(spots)})
        anchors["cup"] = casing.anchor("tub").moved(dz=-GASKET["depth"] - TUB["post"])
        anchors["lid"] = Frame.at((xc + CONSOLE["hinge"], 0.0, s.height + CONSOLE["lid"]), z=(0, -1, 0))
    return casing.with_pieces(casing.root, pieces).with_anchors(**anchors)


def filter_recess(m: Machine, cut: Cutout) -> list[g.Piece]:
    """The pocket behind the service flap: four walls and a back with the filter cap's hole."""
    x1 = m.x_face - WALL
    x0 = m.x_face - FLAP["recess"]
    u0, v0 = cut.lo
    u1, v1 = cut.hi
    ya, yb, za, zb = -u1, -u0, v0 + m.size.height / 2, v1 + m.size.height / 2
    yc, zc = (ya + yb) / 2, (za + zb) / 2
    st, sh = FILTER.stem + A.CLEAR, HOSE["radius"] + A.CLEAR
    yh = yc - HOSE["beside"]  # the hose's anchor is beside the filter's, on the face's +u (world -y) side
    holes = [(yc - st, zc - st, yc + st, zc + st), (yh - sh, zc - sh, yh + sh, zc + sh)]
    walls = [g.panel((x0 - WALL, ya, za), (x0, yb, zb), "liner", "x", holes=holes),
             g.box_between((x0, ya - WALL, za), (x1, ya, zb), "liner"),
             g.box_between((x0, yb, za), (x1, yb + WALL, zb), "liner"),
             g.box_between((x0, ya, za - WALL), (x1, yb, za), "liner"),
             g.box_between((x0, ya, zb), (x1, yb, zb + WALL), "liner")]
    return [w.replace(sheet=DRAWER["sheet"]) for w in walls]


def console(m: Machine, knob_at, key_at, display) -> list[g.Piece]:
    """A top loader's back console: a box across the top with its front face holed for the controls, and the
    display strip on it."""
    xc, z0, z1 = m.band
    xb, w = -m.size.depth / 2, m.size.width / 2
    holes = [(y - PROGRAM["stem"] - A.CLEAR, z - PROGRAM["stem"] - A.CLEAR, y + PROGRAM["stem"] + A.CLEAR,
              z + PROGRAM["stem"] + A.CLEAR) for y, z in knob_at]
    hu, hv = KEY.half
    holes += [(y - hu - A.CLEAR, z - hv - A.CLEAR, y + hu + A.CLEAR, z + hv + A.CLEAR) for y, z in key_at]
    pieces = [g.panel((xc - WALL, -w, z0), (xc, w, z1), "body", "x", holes=holes),
              g.box_between((xb, -w, z1 - WALL), (xc - WALL, w, z1), "body"),
              g.box_between((xb, -w, z0), (xb + WALL, w, z1 - WALL), "body"),
              g.box_between((xb + WALL, -w, z0), (xc - WALL, -w + WALL, z1 - WALL), "body"),
              g.box_between((xb + WALL, w - WALL, z0), (xc - WALL, w, z1 - WALL), "body")]
    pieces = [pc.replace(sheet=SHEET) for pc in pieces]
    y0, y1, d0, d1 = display
    pieces.append(g.box_between((xc, y0, d0), (xc + 0.001, y1, d1), "display"))
    return pieces


def door_hinge(m: Machine) -> tuple[list[g.Piece], list[g.Piece]]:
    """The porthole door's visible hinge (:data:`HINGE`) in the porthole anchor's frame (the door's rest frame):
    the casing's block with its two knuckles, from a plate on the front out to the pin, and the door's arm
    from its ring into the middle knuckle. Decoration (:func:`~.hardware.barrel_hinge`); returns (body, door)."""
    hg, zf = HINGE, DOOR["gap"] + DOOR["ring"]
    fixed, moving = hardware.barrel_hinge(hg["length"], hg["radius"], "trim", hg["moving"])
    h, mid, r = hg["length"] / 2, hg["moving"] * hg["length"] / 2, hg["radius"]
    # the pin frame: x out of the front, y out of the ring's edge, z along the pin
    fixed += [hardware.leaf((-zf, -0.006, -h), (-zf + hg["plate"], hg["reach"], h), "door", 0.001)]
    fixed += [hardware.leaf((-zf, -0.2 * r, z0), (0.0, r, z1), "door", 0.002) for z0, z1 in ((-h, -mid), (mid, h))]
    moving += [hardware.leaf((-0.7 * DOOR["ring"], -hg["arm"], -mid), (0.0, 0.0, mid), "door", 0.002)]
    pin = Frame.at((0.0, m.rd, zf), x=(0, 0, 1), z=(-1, 0, 0))
    return _placed(fixed, pin), _placed(moving, pin)


def porthole_door(m: Machine) -> Assembly:
    """A porthole door in the porthole anchor's frame (local z out of the front, x up, y to the machine's left):
    a plastic ring with a chrome trim ring, a flat cover glass and a glass bowl reaching into the opening, a grip
    on its free edge. Anchors ``mount`` (the opening's centre on the front) and ``hinge`` (on its front face at
    the left edge, about -Z world: it swings out and to the left)."""
    rd, d = m.rd, DOOR
    rg = (1 - RIM) * rd
    zb, zf = d["gap"], d["gap"] + d["ring"]
    rb = r_open(m) - GASKET["wall"] - 2 * d["gap"]
    pieces = [g.shell([(rd, zb), (rd, zf - 0.01), (rd - 0.01, zf)], rd - rg, "door"),
              g.shell([(rd - 0.012, zf - 0.002), (rd - 0.012, zf + d["trim"])], rd - rg - 0.02, "trim"),
              g.cylinder((0, 0, zf - 0.012), (0, 0, zf - 0.008), rg + 0.004, "glass"),
              g.shell([(0.7 * rb, zb - d["bowl"]), (0.9 * rb, zb - 0.3 * d["bowl"]), (rb, zb), (rb, zb + 0.02)],
                      d["glass"], "glass"),
              g.cylinder((0, 0, zb - d["bowl"] - d["glass"]), (0, 0, zb - d["bowl"]), 0.7 * rb, "glass"),
              g.box_between((-0.04, -(rd - 0.006), zf - 0.005), (0.04, -(rd - 0.03), zf + 0.014), "handle",
                            bevel=0.004)]
    # the grip is what a hand pulls the door open by: pinched across its 24 mm from the front, the inner finger
    # down to the ring's face, the outer one past the ring's edge
    y, top = -(rd - 0.018), zf + 0.014
    pieces[-1] = pieces[-1].with_grasps(Grasp.make((0, y, top), (0, 0, -1), (0, 1, 0), 0.024, 0.01, "line_fixed_handle",
                                                   ((0, y, zf + 0.0045), (0.08, 0.024, 0.019), IDENTITY.rotation)))
    hinge = Frame.at((0.0, rd, zf), z=(-1, 0, 0))
    return Assembly.single("door", pieces + door_hinge(m)[1], {"mount": IDENTITY, "hinge": hinge})


def detergent_drawer() -> Assembly:
    """The detergent drawer: an open moulded tray with a front, a grip along the front's bottom; anchors as
    :func:`~.casing.liner` (``front``: its front face's centre)."""
    d = DRAWER
    size = LinerSize(d["width"], d["depth"], d["height"], d["wall"], d["sheet"], d["lip"], d["wall"])
    tray = liner(size, "drawer", "drawer", label="drawer")
    grip = g.box_between((0.0, -0.35 * d["width"], 0.004), (0.008, 0.35 * d["width"], 0.016), "handle", bevel=0.003)
    # fingers close on the grip's top and bottom from the front (a person hooks a finger under it)
    grip = grip.with_grasps(Grasp.make((0.008, 0, 0.01), (-1, 0, 0), (0, 0, 1), 0.012, 0.006, "line_fixed_handle",
                                       ((0.004, 0, 0.01), (0.008, 0.7 * d["width"], 0.012), IDENTITY.rotation)))
    return tray.with_pieces(tray.root, [grip, *compartments(size)])


def compartments(size: LinerSize) -> list[g.Piece]:
    """The drawer's three compartments (:data:`COMPARTMENTS`): main wash, pre-wash and softener split by two
    moulded walls running front to back, the softener's siphon cap standing in its compartment."""
    c, t = COMPARTMENTS, size.wall
    x0, xf, y0, h = -size.depth + t, -size.front, -size.width / 2 + t, c["wall"] * size.height
    inner = size.width - 2 * t
    pieces = []
    for share in c["split"]:
        y = y0 + share * inner
        pieces.append(g.box_between((x0, y - t / 2, t), (xf, y + t / 2, h), "drawer").replace(sheet=size.sheet))
    ys = y0 + (c["split"][-1] + 1.0) / 2 * inner  # the softener compartment's middle
    xs = x0 + c["siphon_back"]
    r, ht = c["siphon"]
    pieces.append(g.cylinder((xs, ys, t), (xs, ys, t + ht), r, "knob", 24))
    return pieces


def filter_cap() -> Assembly:
    """The drain-pump filter cap (:data:`FILTER`, a dial with a grip bar) as part label ``filter``; anchors
    ``mount`` and ``axis`` as a :class:`~.controls.Dial`'s."""
    cap = FILTER.build()
    pieces = [pc.replace(material="filter") if pc.material == "knob" else pc for pc in cap.parts[cap.root].pieces]
    return Assembly.single("filter", pieces, cap.anchors)


def drain_hose() -> Assembly:
    """The emergency drain hose's end in its clip: a hose stub through the recess's back and its plug, in a
    control's frame (local x out of the face); anchors ``mount`` and ``pull`` (z out of the face)."""
    h = HOSE
    pieces = [g.cylinder((-A.BEHIND, 0, 0), (h["length"], 0, 0), h["radius"], "gasket"),
              g.cylinder((h["length"], 0, 0), (h["length"] + h["cap"], 0, 0), h["plug"], "filter")]
    return Assembly.single("hose", pieces, {"mount": controls.MOUNT, "pull": controls.MOUNT})


def softener_cup() -> Assembly:
    """A fabric-softener cup pressed on the agitator's post: an open cup whose skirt goes ``seat`` down over the
    post; anchor ``seat`` (the post's top, z up: it lifts off along it)."""
    c = CUP
    r, h, s = c["radius"], c["height"], c["seat"]
    cup = g.shell([(r, -s), (r, h - s)], c["wall"], "liner")
    floor = g.cylinder((0, 0, 0.0), (0, 0, c["wall"]), r - c["wall"], "liner")
    return Assembly.single("cup", [cup, floor], {"seat": IDENTITY})


def drawer_travel() -> float:
    return DRAWER["pull"] * DRAWER["depth"]


def flap(m: Machine, cut: Cutout) -> tuple[list[g.Piece], Frame]:
    """The service flap in its cut-out (its clearance all round) and its drop hinge at its bottom front edge."""
    (u0, v0), (u1, v1), c = cut.lo, cut.hi, A.CLEAR
    h = m.size.height / 2
    box = (m.x_face - WALL, m.x_face, -u1 + c, -u0 - c, v0 + h + c, v1 + h - c)
    panel = g.box_between(box[::2], box[1::2], "body", bevel=0.001).replace(sheet=SHEET * 2)
    notch = g.box_between((m.x_face, box[2] + 0.02, box[5] - 0.012), (m.x_face + 0.004, box[3] - 0.02, box[5] - 0.004),
                          "handle")
    return [panel, notch], A.drop_hinge(box)


def lid(m: Machine, glass: bool) -> tuple[list[g.Piece], tuple]:
    """A top loader's lid on the top: from its hinge in front of the console to the front margin, a frame round a
    glass window (or a solid panel), a finger lip along its front edge; and its box."""
    x0, x1 = m.band[0] + CONSOLE["hinge"], m.size.depth / 2 - CONSOLE["margin"]
    w, z0 = m.size.width / 2 - CONSOLE["margin"], m.size.height
    z1 = z0 + CONSOLE["lid"]
    lw = LID_WINDOW
    hole = (x0 + lw, -w + lw, x1 - lw, w - lw)
    pieces = [g.panel((x0, -w, z0), (x1, w, z1), "lid", "z", holes=[hole] if glass else []).replace(sheet=2 * SHEET)]
    if glass:
        pieces.append(g.box_between((hole[0], hole[1], z1 - 0.012), (hole[2], hole[3], z1 - 0.006), "glass"))
    pieces.append(g.box_between((x1, -0.3 * w, z1 - 0.01), (x1 + 0.012, 0.3 * w, z1), "handle", bevel=0.003))
    return pieces, (x0, x1, -w, w, z0, z1)
