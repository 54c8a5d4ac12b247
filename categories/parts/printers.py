"""Printers: a plastic casing with its front cut into bands (paper cassette, output tray, access door), the
print engine inside it, fold-down flaps and doors, a flatbed scanner's lid and an automatic document feeder.

Everything is built in the casing's frame (:mod:`.casing`: centred on the z axis, on z = 0, front +x). A
:class:`Printer` holds one product's sizes and does the arithmetic of where each band of the front lies; its
:meth:`Printer.cutouts` are the casing's holes, each an anchor a part is attached to. A flap or door
(:func:`flap`) fills its cut-out flush with the face and turns about its outer bottom edge (anchor ``hinge``, z the
axis a positive turn opens it about): its centre of mass lies behind that edge when closed, so it rests on its
stop under gravity. The scanner lid (:func:`scanner_lid`) turns about the top's back edge and may carry a
document feeder whose cover (:func:`adf_cover`) turns up about the feeder's outer edge.

Sizes per design are data (:data:`DESIGNS`), each figure beside the products it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grasps import Grasp

from .casing import CasingSize, Cutout, LinerSize, liner, sheet_casing
from .controls import Button


@dataclass(frozen=True)
class Design:
    """One kind of printer: outer ``width`` (y), ``depth`` (x), ``height`` (z) ranges of the printing unit (m;
    an all-in-one's scanner lid and feeder stand on top of it), the print engine's mass range (kg: frame,
    motors, carriage or toner and fuser, scanner module; massed in the space it fills), the paper cassette's
    height (m) and whether its front carries a fold-down output tray below the access door."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    engine: tuple[float, float]
    cassette: float
    output_flap: bool


# Retail spec sheets (outer W x D x H, mass), figures as listed by the makers:
# inkjet: Epson EcoTank ET-1810 375 x 347 x 179 mm, 3.5 kg; Canon PIXMA iX6850 584 x 310 x 159 mm, 8.1 kg (A3+);
#   HP OfficeJet Pro 8210 494 x 460 x 198 mm, 8.1 kg. Engines: product mass less ~1.5-2.5 kg of casing and trays.
# laser: Brother HL-L2350DW 356 x 360 x 183 mm, 7.2 kg; HP LaserJet Pro M404dn 381 x 357 x 216 mm, 8.6 kg;
#   HP LaserJet Enterprise M507 418 x 376 x 298 mm, 13.6 kg (a toner cartridge 0.7-1.5 kg, a fuser ~1 kg).
# all-in-one (printing unit under the scanner): HP OfficeJet Pro 9015e 440 x 343 x 279 mm overall, 9.3 kg;
#   Brother MFC-L2710DW 409 x 399 x 319 mm, 11.4 kg; Epson WorkForce WF-2850 375 x 347 x 231 mm, 5.4 kg.
DESIGNS = {
    "inkjet": Design((0.37, 0.50), (0.30, 0.42), (0.16, 0.21), (1.5, 5.0), 0.045, True),
    "laser": Design((0.35, 0.42), (0.34, 0.40), (0.18, 0.27), (4.5, 10.0), 0.055, False),
    "all_in_one": Design((0.38, 0.45), (0.33, 0.40), (0.16, 0.22), (3.0, 7.5), 0.05, True),
}

SHEET = 0.0025  # m, ABS / PC-ABS of printer casings and doors (2-3 mm mouldings)
WALL = 0.003  # m, the casing's walls as the simulator sees them (massed as SHEET)
CLEAR = 0.002  # m, clearance of a door, flap or cassette in its opening
FLAP = 0.004  # m, a door's or flap's moulding as the simulator sees it (massed as SHEET)
RECESS = 0.035  # m, the engine stands this far behind the front: the cavity a door opens onto
MARGIN = 0.008  # m, casing left between the front's bands and above the top band
PAPER = 800.0  # kg/m^3, office paper: 80 g/m2 at ~0.1 mm
SHEET_SIZE = (0.216, 0.297)  # m, the paper: Letter's width (216 mm) and A4's length (297 mm)
# A4 / Letter cassettes take 150-250 sheets (15-25 mm of paper) in a tray 45-60 mm deep (Brother, HP manuals);
# trays pull out to the paper's length and come out entirely (their stop is the paper length, ~0.3 m).
CASSETTE = dict(share=0.82, lip=0.012, front=0.006, wall=0.0025, sheet=0.0015, pull=0.75)
# Front bands above the cassette: the output tray's share and the door's share of what is left.
OUTPUT_SHARE, DOOR_SHARE = 0.45, 0.9
OUTPUT_OPENS = math.radians(90)  # an output tray folds down level
DOOR_OPENS = math.radians(85)  # access doors drop to just short of level (stay straps)
REAR_FEED_OPENS = math.radians(105)  # a rear paper support leans back past upright
STOP_OPENS = math.radians(90)  # a paper stop flips up square
TOP_COVER_OPENS = math.radians(80)  # a top cover lifts to a stop short of upright
LID_OPENS = math.radians(75)  # flatbed lids stand open at 70-80 degrees (HP, Epson user guides)
ADF_OPENS = math.radians(70)  # a document feeder's top cover opens to clear a jam
# Panel keys: 8-12 mm round or 12 x 8 mm rectangular, 1.5-2 mm travel (service-part photos of HP, Brother keys).
KEYS = {"round": Button(half=(0.0045, 0.0045), shape="round", proud=0.0025, travel=0.0018),
        "rect": Button(half=(0.006, 0.004), shape="rect", proud=0.0025, travel=0.0018)}
KEY_PITCH = 0.019
DISPLAY = (0.045, 0.022)  # m, a 1.5-2 in monochrome LCD beside the keys (Brother HL-L2350DW, HP M404 panels)
# Behind an inkjet's access door: four ink cartridges in their carriage (HP 305 / Canon PG-545 cartridges are
# 12-18 mm wide, 35-60 mm tall); behind a laser's: the toner cartridge's front with its grip.
CARTRIDGE = dict(width=0.016, gap=0.006, depth=0.03, count=4)
# Flatbed covers 20-30 mm thick; feeders 40-60 mm tall, 90-120 mm wide at one end (HP 9015e, Brother MFC-L2710DW).
LID = dict(thick=(0.02, 0.03), pad=0.002, adf_height=(0.04, 0.06), adf_width=(0.09, 0.12), cover=0.012,
           tray_rise=0.012, tab=0.025)  # tab: how far the lid's front lip reaches past the body's front
LIP = (0.010, 0.012)  # m, a pull lip's thickness and how far it stands out: a finger's (and a gripper's) hold
STOP = (0.12, 0.05)  # the paper stop's width and length (m)
BIN = dict(depth=0.022, front=0.06, back=0.05, side=0.06)  # a laser's top output bin, inset from the top's edges
EXTENDER = dict(share=0.8, thick=0.003, pull=0.85)  # the output tray's pull-out extender behind it


def lerp(span: tuple[float, float], t: float) -> float:
    return span[0] + t * (span[1] - span[0])


@dataclass(frozen=True)
class Printer:
    """One printer's sizes (m) and the bands of its front, computed from a :class:`Design` and shares 0-1."""

    design: str
    width: float
    depth: float
    height: float
    corner: float
    engine_kg: float
    lower_flap: bool

    @classmethod
    def make(cls, design: str, shares: tuple[float, float, float], corner: float, manual_feed: bool = False
             ) -> Printer:
        """``manual_feed``: a laser's front has a manual-feed flap below its door (as an inkjet's output tray)."""
        d = DESIGNS[design]
        w, dp, h = (lerp(r, t) for r, t in zip((d.width, d.depth, d.height), shares))
        return cls(design, w, dp, h, corner, lerp(d.engine, sum(shares) / 3), d.output_flap or manual_feed)

    @property
    def spec(self) -> Design:
        return DESIGNS[self.design]

    @property
    def size(self) -> CasingSize:
        return CasingSize(self.width, self.depth, self.height, WALL, SHEET, self.corner)

    def tray(self) -> LinerSize:
        c, s = CASSETTE, self.size
        return LinerSize(s.clear_width - 2 * CLEAR, c["share"] * (self.depth - 2 * WALL), self.spec.cassette,
                         c["wall"], c["sheet"], c["lip"], c["front"])

    def bands(self) -> dict[str, tuple[float, float]]:
        """The front's bands as (bottom, top) in face coordinates v (from the face's centre)."""
        t = self.tray()
        lo = -self.height / 2 + WALL + t.height + t.lip + 2 * CLEAR + MARGIN
        hi = self.height / 2 - MARGIN
        free = hi - lo - (MARGIN if self.lower_flap else 0.0)
        out = OUTPUT_SHARE * free if self.lower_flap else 0.0
        door_lo = lo + out + (MARGIN if out else 0.0)
        share = DOOR_SHARE if self.spec.output_flap else 1.0  # an inkjet's door leaves room for the keys above
        return {"output": (lo, lo + out), "door": (door_lo, door_lo + share * (hi - door_lo))}

    def door_span(self) -> tuple[float, float]:
        """The door's extent across the face (u): a laser's spans most of it, an inkjet's the middle."""
        hu = self.width / 2 - 2 * self.corner
        return (-0.85 * hu, 0.45 * hu) if self.design == "laser" else (-0.6 * hu, 0.35 * hu)

    def cutouts(self, keys: int, key: Button) -> dict[str, Cutout]:
        """The casing's holes: ``cassette``, ``door``, ``output`` (with a fold-down tray), ``key_0`` ..."""
        t, b, (u0, u1) = self.tray(), self.bands(), self.door_span()
        cuts = {"cassette": self.size.floor_opening("front", t.width, t.height + t.lip, CLEAR),
                "door": Cutout("front", (u0, b["door"][0]), (u1, b["door"][1]))}
        if self.lower_flap:
            cuts["output"] = Cutout("front", (u0, b["output"][0]), (u1, b["output"][1]))
        v = (b["door"][0] + b["door"][1]) / 2
        room = self.width / 2 - 2 * self.corner - u1 - 2 * MARGIN
        if self.has_display(keys):
            u1, room = u1 + DISPLAY[0] + MARGIN, room - DISPLAY[0] - MARGIN
        cols = max(1, min(keys, int(room / KEY_PITCH)))
        rows = -(-keys // cols)  # keys that do not fit in one row take a second below it
        for k in range(keys):
            r, c = divmod(k, cols)
            at = (u1 + MARGIN + (c + 0.5) * KEY_PITCH, v + ((rows - 1) / 2 - r) * KEY_PITCH)
            cuts[f"key_{k}"] = key.cutout("front", at)
        return cuts

    def has_display(self, keys: int) -> bool:
        """A laser's or an all-in-one's panel has a display beside its keys where the front has room for both."""
        room = self.width / 2 - 2 * self.corner - self.door_span()[1] - 2 * MARGIN
        return self.design != "inkjet" and room >= DISPLAY[0] + MARGIN + min(keys, 3) * KEY_PITCH

    def face_point(self, u: float, v: float, inset: float) -> tuple[float, float, float]:
        """A point ``inset`` behind the front face at face coordinates (u, v)."""
        return (self.depth / 2 - inset, -u, self.height / 2 + v)

    def engine_box(self, top: float) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """The print engine's box: behind the front's recess, above the cassette, up to ``top``."""
        t = self.tray()
        z0 = WALL + t.height + t.lip + 3 * CLEAR
        hx, hy = self.depth / 2 - WALL - CLEAR, self.width / 2 - WALL - CLEAR
        return (-hx, -hy, z0), (self.depth / 2 - RECESS, hy, top)


def body(pr: Printer, slot: str, works: str, cuts: dict[str, Cutout], extras=()) -> tuple[Assembly, float]:
    """The casing with its cut-outs and the print engine inside (``works``), plus ``extras`` pieces; returns the
    assembly and the engine's volume (m^3), which the layout masses as the engine's weight."""
    made = sheet_casing(pr.size, slot, cuts)
    top = pr.height - WALL - CLEAR
    if pr.design == "laser":
        top -= BIN["depth"] + WALL
    elif pr.design == "all_in_one":
        top -= 2 * WALL
    lo, hi = pr.engine_box(top)
    engine = g.box_between(lo, hi, works)
    vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
    return made.with_pieces(made.root, [engine, *extras]), vol


def output_bin(pr: Printer, slot: str) -> tuple[Cutout, list[g.Piece], Frame]:
    """A laser's output bin: the top's cut-out, the bin's floor and rim pieces under it, and the paper stop's
    anchor (its hinge on the bin floor near the front, z the axis that lifts it)."""
    x0, x1 = -pr.depth / 2 + BIN["back"], pr.depth / 2 - BIN["front"]
    hy = pr.width / 2 - BIN["side"]
    cut = Cutout("top", (-hy, x0), (hy, x1))
    zf = pr.height - BIN["depth"]
    floor = g.box_between((x0, -hy, zf - WALL), (x1, hy, zf), slot)
    walls = [g.box_between((x0, y0, zf), (x1, y1, pr.height - WALL), slot)
             for y0, y1 in ((-hy - WALL, -hy), (hy, hy + WALL))]
    walls += [g.box_between((x, -hy, zf), (x + WALL, hy, pr.height - WALL), slot) for x in (x0 - WALL, x1)]
    at = Frame.at((x1 - STOP[1] - 0.01, 0.0, zf + FLAP), z=(0, -1, 0), x=(1, 0, 0))
    return cut, [floor, *walls], at


def flap(size: tuple[float, float], slot: str, label: str, grip: bool = True) -> Assembly:
    """A door or flap ``size`` (u across, v up) filling a cut-out flush with its face: in the cut-out anchor's
    frame it spans x (v) and y (u) and reaches ``FLAP`` into the face (z from -FLAP to 0). Anchors ``mount``
    (the cut-out's anchor) and ``hinge`` (the outer bottom edge, z = -y: a positive turn lifts the top out);
    with ``grip`` a finger recess's lip along the top edge."""
    u, v = size[0] / 2 - CLEAR, size[1] / 2 - CLEAR
    pieces = [g.box_between((-v, -u, -FLAP), (v, u, 0.0), slot, bevel=0.0015)]
    if grip:
        w, (t, proud) = min(0.04, 0.8 * u), LIP
        pieces.append(lip((v - t, -w, 0.0), (v, w, proud), slot, (0, 0, -1), (1, 0, 0)))
    sheet = [pc.replace(sheet=SHEET) for pc in pieces]
    anchors = {"mount": Frame.at((0, 0, 0)), "hinge": Frame.at((-v, 0, 0), z=(0, -1, 0), x=(1, 0, 0))}
    return Assembly.single(label, sheet, anchors)


def lip(lo, hi, slot: str, approach, closing) -> g.Piece:
    """A moulded pull lip (a box ``lo``-``hi``) that a hand takes: fingers come along ``approach`` onto its outer face
    and close across it along ``closing`` (both unit axes of the box)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    a, c = np.asarray(approach, float), np.asarray(closing, float)
    centre, size = (lo + hi) / 2, hi - lo
    face = centre - a * (np.abs(a) @ size) / 2
    grasp = Grasp.make(face, a, c, float(np.abs(c) @ size), min(0.5 * float(np.abs(a) @ size), 0.008),
                       "line_fixed_handle", (centre, size, IDENTITY.rotation))
    return g.box_between(lo, hi, slot, bevel=0.001).with_grasps(grasp)


def extender(size: tuple[float, float], slot: str) -> Assembly:
    """The output tray's pull-out extender: a plate behind the tray (in the tray's ``mount`` frame), sliding
    along +x (the tray's length: up while it is closed, out once it is folded down). Anchor ``slide``."""
    u, v = EXTENDER["share"] * size[0] / 2, EXTENDER["share"] * size[1] / 2
    z0 = -FLAP - CLEAR - EXTENDER["thick"]
    plate = g.box_between((-v, -u, z0), (v, u, z0 + EXTENDER["thick"]), slot).replace(sheet=SHEET)
    # its pull is its thickened end, within the plate's thickness: anything standing off it would swing through
    # the casing above the slot as the tray folds down
    tab = lip((v - 0.004, -0.4 * u, z0), (v, 0.4 * u, -FLAP - CLEAR), slot, (0, 0, 1), (1, 0, 0))
    return Assembly.single("extender", [plate, tab], {"mount": Frame.at((0, 0, 0)),
                                                  "slide": Frame.at((0, 0, 0), z=(1, 0, 0), x=(0, 0, 1))})


def cassette(pr: Printer, body_slot: str, slot: str, paper_slot: str, fill: float) -> Assembly:
    """The paper cassette: a lift-out liner whose front is moulded as the casing (``body_slot``) with a stack
    of paper ``fill`` of its depth. Anchors ``front`` (the liner's) and its pull ``slide``."""
    t = pr.tray()
    made = liner(t, slot, body_slot, label="tray")
    x1 = -t.front - CLEAR
    x0 = max(-t.depth + t.wall + CLEAR, x1 - SHEET_SIZE[1])
    hy = min(t.width / 2 - t.wall - CLEAR, SHEET_SIZE[0] / 2)
    stack = g.box_between((x0, -hy, t.wall), (x1, hy, t.wall + fill * (t.height - t.wall)), paper_slot)
    zc = (t.height + t.lip) / 2
    grip = lip((0.0, -0.04, zc - LIP[0] / 2), (LIP[1], 0.04, zc + LIP[0] / 2), body_slot, (-1, 0, 0), (0, 0, 1))
    return made.with_pieces(made.root, [stack, grip])


def scanner_lid(pr: Printer, slot: str, pad_slot: str, thick: float) -> Assembly:
    """The flatbed's lid covering the top, its white pad underneath. Anchors ``hinge`` (the top's back edge,
    z = -y: a positive turn lifts the front) and ``deck`` (its top's centre, z up)."""
    hx, hy, z = pr.depth / 2, pr.width / 2, pr.height
    r = min(0.008, thick / 3)
    pieces = [g.box_between((-hx, -hy, z + CLEAR), (hx, hy, z + CLEAR + thick), slot, bevel=r).replace(sheet=SHEET),
              g.box_between((-hx + 0.02, -hy + 0.02, z + CLEAR - LID["pad"] / 2), (hx - 0.02, hy - 0.02, z + CLEAR),
                            pad_slot)]
    top = z + CLEAR + thick
    pieces.append(lip((hx, -0.05, top - LIP[0]), (hx + LID["tab"], 0.05, top), slot, (-1, 0, 0), (0, 0, 1)))
    anchors = {"hinge": Frame.at((-hx, 0, z + CLEAR), z=(0, -1, 0), x=(1, 0, 0)), "deck": Frame.at((0, 0, top))}
    return Assembly.single("lid", pieces, anchors)


def feeder(pr: Printer, deck: Frame, slot: str, tray_slot: str, width: float, height: float
           ) -> tuple[list[g.Piece], Frame]:
    """A document feeder on the lid's ``deck``: its housing at the +y end and the input tray beside it (pieces
    of the lid) and the cover's hinge (the housing's back top edge, z = -y: a positive turn lifts its front)."""
    hx, hy = pr.depth / 2 - 0.015, pr.width / 2 - 0.01
    z0 = deck.origin[2]
    y0 = hy - width
    house = g.box_between((-hx, y0, z0), (hx, hy, z0 + height - LID["cover"]), slot, bevel=0.004)
    rise = LID["tray_rise"]
    tray = g.box_between((-hx + 0.02, -hy + 0.03, z0), (hx - 0.04, y0, z0 + rise), tray_slot, bevel=0.003)
    guides = [g.box_between((-hx + 0.03, y, z0 + rise), (hx - 0.06, y + 0.004, z0 + rise + 0.008), tray_slot)
              for y in (-hy + 0.05, y0 - 0.03)]
    hinge = Frame.at((-hx, y0 + width / 2, z0 + height - LID["cover"]), z=(0, -1, 0), x=(1, 0, 0))
    return [pc.replace(sheet=SHEET) for pc in (house, tray, *guides)], hinge


def adf_cover(pr: Printer, width: float, slot: str) -> Assembly:
    """The feeder's top cover, built about its hinge (:func:`feeder`: the housing's back top edge, z = -y: a
    positive turn lifts its front), ``width`` across the housing, a pull lip past its front. Anchor ``hinge``."""
    length, t = pr.depth - 0.03, LID["cover"]
    piece = g.box_between((0.0, -width / 2, 0.0), (length, width / 2, t), slot, bevel=0.004).replace(sheet=SHEET)
    tab = lip((length, -0.03, t - LIP[0] / 2), (length + LID["tab"] / 2, 0.03, t), slot, (-1, 0, 0), (0, 0, 1))
    return Assembly.single("lid", [piece, tab], {"hinge": Frame.at((0, 0, 0), z=(0, -1, 0), x=(1, 0, 0))})


def platen(pr: Printer, glass: str) -> tuple[Cutout, g.Piece]:
    """The scanner's glass in the top: an A4 / Letter window (216 x 297 mm plus its frame) toward the back-left
    (the scan origin corner), and the glass filling it just under the top's face."""
    w, d = min(0.23, pr.width - 0.1), min(0.31, pr.depth - 0.05)
    x0, y1 = -pr.depth / 2 + 0.025, pr.width / 2 - 0.03
    cut = Cutout("top", (y1 - w, x0), (y1, x0 + d))  # the top's u runs along +y, v along +x
    z = pr.height
    pane = g.box_between((x0, y1 - w, z - WALL), (x0 + d, y1, z - 0.001), glass)
    return cut, pane


def rear_feed(pr: Printer) -> Cutout:
    """An inkjet's rear paper support: a flap across the top's back third (Canon PIXMA, Epson EcoTank)."""
    x0 = -pr.depth / 2 + 0.03
    return Cutout("top", (-0.3 * pr.width, x0), (0.3 * pr.width, x0 + 0.35 * pr.depth))


def rear_door(pr: Printer) -> Cutout:
    """A laser's rear jam-clearing door (the duplex path's cover): the back's middle, above the cassette."""
    return Cutout("back", (-0.3 * pr.width, -0.1 * pr.height), (0.3 * pr.width, 0.3 * pr.height))


def top_cover(pr: Printer) -> Cutout:
    """An inkjet's top cover over the cartridge carriage (Canon PIXMA iP / iX): the top's front part, in front of
    a rear paper support's place."""
    x1 = pr.depth / 2 - 0.03
    return Cutout("top", (-0.35 * pr.width, x1 - 0.45 * pr.depth), (0.35 * pr.width, x1))


REAR = {"rear_feed": rear_feed, "rear_door": rear_door, "top_cover": top_cover}


def behind_door(pr: Printer, door: Cutout, slots: tuple[str, ...]) -> list[g.Piece]:
    """What an open access door shows, on the engine's front in the door's recess: a laser's toner cartridge
    (``slots[0]``) with its grip, or an inkjet's row of cartridges (one per slot: black, cyan, magenta, yellow)."""
    (u0, v0), (u1, v1) = door.lo, door.hi
    x1 = pr.depth / 2 - RECESS
    if pr.design == "laser":
        um, vm = 0.1 * (u1 - u0), 0.15 * (v1 - v0)
        body = _box(pr.face_point(u1 - um, v0 + vm, RECESS), pr.face_point(u0 + um, v1 - vm, RECESS - 0.012),
                    slots[0], 0.004)
        grip = _box(pr.face_point(0.7 * u0 + 0.3 * u1, v1 - 2 * vm, RECESS - 0.012),
                    pr.face_point(0.3 * u0 + 0.7 * u1, v1 - 1.5 * vm, RECESS - 0.022), slots[0], 0.002)
        return [body, grip]
    c = CARTRIDGE
    pitch = c["width"] + c["gap"]
    um = (u0 + u1) / 2
    h = min(0.05, 0.8 * (v1 - v0))
    pieces = []
    for k, slot in enumerate(slots):
        u = um + (k - (len(slots) - 1) / 2) * pitch
        lo = (x1 - c["depth"] + 0.012, -u - c["width"] / 2, pr.height / 2 + v0 + 0.004)
        pieces.append(g.box_between(lo, (x1 + 0.012, -u + c["width"] / 2, lo[2] + h), slot, bevel=0.002))
    return pieces


def display(pr: Printer, keys: int, slot: str) -> list[g.Piece]:
    """The panel's display, slightly proud of the front beside the door (where :meth:`Printer.has_display`)."""
    if not pr.has_display(keys):
        return []
    u0 = pr.door_span()[1] + MARGIN
    b = pr.bands()["door"]
    v = (b[0] + b[1]) / 2
    return [_box(pr.face_point(u0, v - DISPLAY[1] / 2, 0.001), pr.face_point(u0 + DISPLAY[0], v + DISPLAY[1] / 2,
                                                                             -0.001), slot)]


def _box(a, b, slot: str, bevel: float = 0.0) -> g.Piece:
    """A box between two opposite corners given in any order."""
    return g.box_between(np.minimum(a, b), np.maximum(a, b), slot, bevel=bevel)
