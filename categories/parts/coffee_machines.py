"""Coffee machines: the body of each design and the frames its moving parts turn or slide about.

A coffee machine is three boxes in one shell: a *tower* at the back (the boiler or the reservoir), a *head*
that overhangs the front at the top (the shower head, the group head or the capsule chamber) and the
*floor* in front of the tower under it (a warming plate or a drip tray); a lift-out water tank stands in a
cradle behind the tower on espresso and pod machines. Everything is built on the ground plane round the
vertical axis, the front facing +X; each moving part is returned with the frame its joint turns or slides
about (z the axis, a positive move opens: a lid's front lifts, the basket swings out, the portafilter turns
to unlock, the wand swings out, a tray pulls out, the tank lifts).

Designs (real product types; sizes below with their sources):

* ``drip``: a filter coffee maker: a glass carafe on a warming plate, a filter basket that swings out from
  under the shower head, a hinged reservoir lid on the tower, keys on the plinth (Mr. Coffee 12-cup,
  Cuisinart DCC-3200 layout);
* ``espresso``: a pump espresso machine: a portafilter locked into the group head by a twist, a steam wand
  that swings out on its ball joint, a drip tray that pulls out, a water tank that lifts out of the back,
  keys on the head's front (Breville Barista Express, De'Longhi Dedica, Gaggia Classic layout);
* ``pod``: a capsule machine: the head's lid lifts to load a capsule, a drip tray pulls out, a water tank
  lifts out of the back, keys on the head's front (Nespresso Essenza / Vertuo, Keurig K-Mini / K-Classic).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import controls
from .appliance import CLEAR
from .casing import LinerSize


@dataclass(frozen=True)
class Design:
    """A coffee machine design: outer ``width`` (Y), ``depth`` (X), ``height`` (Z) ranges (m) and its layout as
    shares: the tower's depth (tank included) of the whole depth, the head's height of the whole height, the
    floor's height (a drip machine's warming-plate plinth; m), the massed ``sheet`` of the shell (m)."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    tower: float
    head: float
    floor: float
    sheet: float

    def at(self, t: float) -> tuple[float, float, float]:
        return tuple(lo + t * (hi - lo) for lo, hi in (self.width, self.depth, self.height))


# Sizes from maker and retail spec listings (inches converted), W x D x H:
# drip: Mr. Coffee 12-cup (BVMC-SJX33GT) 8.9 x 10.2 x 14.2 in, Cuisinart DCC-3200 8 x 9 x 14 in, Hamilton Beach
#   46310 7.8 x 10.2 x 13.8 in -> 0.20-0.23 x 0.23-0.26 x 0.35-0.36 m; the warming-plate plinth 5-6 cm tall.
# espresso: De'Longhi Dedica EC685 15 x 33 x 30 cm, Gaggia Classic Pro 24 x 23 x 38 cm (23 deep without its tray),
#   Breville Barista Express BES870 33 x 31 x 40 cm -> 0.15-0.33 x 0.27-0.33 x 0.30-0.40 m.
# pod: Nespresso Essenza Mini 8.4 x 33 x 20.4 cm, Keurig K-Mini 11.4 x 28.7 x 30.7 cm, Nespresso Vertuo Next
#   14.2 x 42.9 x 31.4 cm, Keurig K-Classic 24.8 x 33.8 x 33.3 cm -> 0.11-0.25 x 0.29-0.34 x 0.21-0.33 m.
DESIGNS = {
    "drip": Design((0.20, 0.23), (0.23, 0.26), (0.35, 0.36), 0.45, 0.17, 0.055, 0.0025),
    "espresso": Design((0.15, 0.33), (0.27, 0.33), (0.30, 0.40), 0.58, 0.32, 0.012, 0.0008),
    "pod": Design((0.11, 0.25), (0.29, 0.34), (0.21, 0.33), 0.55, 0.36, 0.012, 0.0025),
}
"""Shells: a drip or pod machine's 2-3 mm moulded polypropylene / ABS, an espresso machine's 0.8 mm stainless
sheet (the weight of both is mostly their works: :data:`WORKS`)."""

WALL = 0.004  # m, the shell's walls as the simulator sees them
GAP = 0.002  # m, a moving part's clearance from the shell at rest
# Water tanks (replacement-part listings): Breville BES870 2 l, 0.10 x 0.21 x 0.25 m; Nespresso Essenza 0.6 l,
# Keurig K-Classic 1.4 l: 6-10 cm deep, most of the machine's width and two thirds of its height.
TANK = (0.28, 0.8, 0.72)  # depth of the whole depth, width of the whole width, height of the whole height
TANK_SHEET = 0.002  # m, a moulded SAN / Tritan tank wall
TANK_DENSITY = 1080.0  # kg/m^3, SAN (styrene-acrylonitrile), what clear tanks are moulded of
CRADLE = (0.004, 0.025)  # m, the cradle's rim: thickness, height (how far the tank's foot sits in it)
LID_T = 0.012  # m, a lid's thickness
LID_SHEET = 0.002  # m, its moulded wall
LID_OPENS = math.radians(85)  # a reservoir lid or a capsule lever stops about upright
# A 12-cup drip machine's swing-out basket (Cuisinart DCC-3200, Mr. Coffee): a #4 cone filter basket
# 11-12 cm across, 7 cm deep, on a pivot at the head's side; it swings out about 90 degrees.
BASKET = (0.055, 0.07)  # m, top radius, depth
BASKET_SWINGS = math.radians(90)
# A 12-cup glass carafe (Mr. Coffee, Cuisinart replacement listings): 12-14 cm across, 15-17 cm tall, 0.35-0.45 kg.
CARAFE_R = 0.06
CARAFE_GLASS = 0.0025  # m, borosilicate wall
# the carafe slides forward until its centre is over the plinth's front edge: a hand lifts it from there
# A 58 mm (Breville 54 mm) commercial portafilter: a 70-75 mm brass ring, a 12-14 cm handle; it turns
# 40-50 degrees from the insertion notches to locked (the lugs' ramp is its stop).
PORTAFILTER = (0.036, 0.03, 0.13, 0.012)  # m, ring radius, ring height, handle length, grip radius
PORTAFILTER_TURNS = math.radians(45)
PORTAFILTER_WALL = 0.004  # m, its cast ring and basket (a 58 mm portafilter with its basket weighs 0.45-0.6 kg)
GROUP = (0.04, 0.02)  # m, the group head's radius and how far it hangs under the head
# A steam wand (Breville, Gaggia Classic Pro): a 9-10 mm steel tube on a ball joint, 12-16 cm long,
# swinging out 60-90 degrees.
WAND = (0.0048, 0.14)  # m, tube radius, longest length
WAND_SWINGS = math.radians(60)
# A capsule machine's outlet (Nespresso Essenza Mini, Keurig K-Classic): a spout 26-30 mm across hanging 20-25 mm
# under the head, over the cup; its capsule holder: a pocket for a 37 mm Nespresso capsule (Keurig K-cup holder 50 mm
# across) ringed by a 4-5 mm rim, under the lid.
POD_OUTLET = (0.014, 0.022)  # m, radius, drop under the head
CAPSULE_BAY = (0.021, 0.005)  # m, pocket radius, rim width
TRAY_HEIGHT = 0.035  # m, a drip tray's depth (Breville, Nespresso: 3-5 cm)
TRAY_PULL = 0.8  # it pulls out this share of its depth before it leaves its guides
# Keys on a coffee machine's front (Breville BES870 1-cup / 2-cup / power / program; Keurig cup-size keys):
# 12-16 mm round or rectangular keys 3 mm proud, 2 mm travel.
BUTTON = controls.Button(half=(0.007, 0.007), shape="round", proud=0.003, travel=0.002)
BUTTONS_MAX = 4
ROCKERS_MAX = 3  # power, brew, steam rockers (Gaggia Classic Pro, Rancilio Silvia)
# A steam / hot-water dial (Breville BES870, Gaggia Classic Pro steam knob): 30-36 mm, a quarter to half a turn.
DIAL = controls.Dial(radius=0.016, stem=0.003, style="ridge", turns=math.radians(150))
BUTTON_PITCH = 0.026  # m, centre to centre
# A machine's weight is mostly its works, not its shell: an espresso machine's boiler or thermoblock, pump and
# brass group (Dedica 4.2 kg, Gaggia Classic Pro 8 kg, Barista Express 10-11 kg maker listings, the steel shell
# 1-2.5 kg of it); a capsule machine's thermoblock and pump (~1.5 kg of its 2.1-4 kg: Keurig K-Mini, Nespresso
# Essenza Mini, K-Classic listings). Drawn as a steel core in the tower of radius, from the smallest machine of the
# design to the largest (a drip machine's heater is its warming plate, no core):
WORKS = {"espresso": (0.022, 0.035), "pod": (0.02, 0.02), "drip": (0.0, 0.0)}  # m
METAL_SHEET = 0.0008  # m, a painted or stainless shell (0.6-1 mm sheet) whatever the design's moulded one


@dataclass(frozen=True)
class Machine:
    """One machine's outer box and where its tower, head and floor meet (m, X front, Z up)."""

    design: str
    width: float
    depth: float
    height: float
    sheet: float
    works: float

    @property
    def d(self) -> Design:
        return DESIGNS[self.design]

    @property
    def has_tank(self) -> bool:
        return self.design != "drip"

    @property
    def back(self) -> float:
        return -self.depth / 2

    @property
    def front(self) -> float:
        return self.depth / 2

    @property
    def tank_front(self) -> float:
        return self.back + (TANK[0] * self.depth if self.has_tank else 0.0)

    @property
    def tower_front(self) -> float:
        return self.back + self.d.tower * self.depth

    @property
    def head_bottom(self) -> float:
        return self.height * (1 - self.d.head)

    @property
    def bay(self) -> float:
        """x of the middle of the bay under the head (the carafe, the portafilter, the cup): a carafe clears
        the tower."""
        mid = (self.tower_front + self.front) / 2
        return max(mid, self.tower_front + CARAFE_R + 0.008) if self.design == "drip" else mid


def machine(design: str, t: float, metal: bool = False) -> Machine:
    """The machine of ``design`` at ``t`` of its size range, its shell of ``metal`` sheet or moulded."""
    d = DESIGNS[design]
    lo, hi = WORKS[design]
    return Machine(design, *d.at(t), METAL_SHEET if metal else d.sheet, lo + t * (hi - lo))


def _shell(lo, hi, slot: str, sheet: float) -> g.Piece:
    return g.box_between(lo, hi, slot, bevel=0.006).replace(sheet=sheet)


def _keyed(lo, hi, holes: list[tuple[Frame, float, float]], slot: str, sheet: float) -> g.Piece:
    """A box of the shell with a hole through it (along x) for each control on its front: (its mount, half
    width, half height)."""
    rects = [(f.origin[1] - du - CLEAR, f.origin[2] - dv - CLEAR, f.origin[1] + du + CLEAR, f.origin[2] + dv + CLEAR)
             for f, du, dv in holes]
    return g.panel(lo, hi, slot, "x", rects).replace(sheet=sheet)


def body(m: Machine, slot: str, trim: str, keys: int, dial: bool = False, dark: str = "lid") -> list[g.Piece]:
    """The shell: tower, head and floor (and the tank's cradle) with the holes of ``keys`` keys and a
    ``dial``'s stem, plus the warming plate, a capsule machine's outlet and capsule bay (``dark``: the slot of
    their openings) or the group head and an espresso machine's boiler."""
    s, w, h = m.sheet, m.width / 2, m.height
    lid = LID_T + GAP if m.design == "drip" else 0.0
    head, floor = ((m.tower_front - WALL, -w, m.head_bottom), (m.front, w, h)), \
        ((m.tower_front - WALL, -w, 0), (m.front, w, m.d.floor))
    keyed = floor if m.design == "drip" else head
    holes = [(f, *BUTTON.half) for f in key_anchors(m, keys)] + ([(dial_anchor(m), DIAL.stem, DIAL.stem)] if dial
                                                                  else [])
    pieces = [_shell((m.tank_front, -w, 0), (m.tower_front, w, h - lid), slot, s),
              *(_keyed(*box, holes, slot, s) if box is keyed else _shell(*box, slot, s)
                for box in (head, floor))]
    if m.has_tank:
        t, rim = CRADLE
        pieces.append(_shell((m.back, -w, 0), (m.tank_front, w, m.d.floor), slot, s))
        pieces += [g.box_between((m.back, -w, m.d.floor), (m.back + t, w, m.d.floor + rim), slot).replace(sheet=s),
                   *(g.box_between((m.back, k * w - t * (k > 0), m.d.floor), (m.tank_front, k * w + t * (k < 0),
                                   m.d.floor + rim), slot).replace(sheet=s) for k in (-1, 1))]
    if m.design == "drip":
        pieces.append(g.disc((m.bay, 0, m.d.floor + 0.001), 0.9 * CARAFE_R, 0.002, trim))
    if m.design == "pod":
        pieces += pod_outlet(m, trim, dark) + capsule_bay(m, trim, dark)
    if m.design == "espresso":
        r, drop = GROUP
        pieces.append(g.cylinder((m.bay, 0, m.head_bottom - drop), (m.bay, 0, m.head_bottom + 0.001), r, trim))
    if m.works > 0:
        x = (m.tank_front + m.tower_front) / 2
        pieces.append(g.cylinder((x, 0, m.d.floor), (x, 0, 0.6 * h), m.works, "works").replace(wall=0.0))  # solid
    return pieces


def pod_outlet(m: Machine, trim: str, dark: str) -> list[g.Piece]:
    """A capsule machine's coffee outlet over the cup: a nozzle housing hanging under the head's front (a round
    spout 26-30 mm across, 20-25 mm under the head: Nespresso Essenza Mini, Keurig K-Classic exit needle
    housing) with its dark orifice underneath."""
    r, drop = POD_OUTLET
    x, z = m.bay, m.head_bottom
    return [g.cylinder((x, 0, z - drop), (x, 0, z + 0.001), r, trim, 32),
            g.disc((x, 0, z - drop - 0.0005), 0.55 * r, 0.001, dark).replace(convex=())]


def capsule_bay(m: Machine, trim: str, dark: str) -> list[g.Piece]:
    """The capsule holder the lid closes over, on the head's top (decoration, flush: the lid clears it): a
    bright rim round the dark pocket a capsule drops into (:data:`CAPSULE_BAY`)."""
    r, rim = CAPSULE_BAY
    x0, z = m.tower_front + LID_T, m.height
    x = max(m.bay, x0 + r + rim + 0.006)
    return [g.disc((x, 0, z + 0.0002), r + rim, 0.0008, trim, 48).replace(convex=()),
            g.disc((x, 0, z + 0.0006), r, 0.0008, dark, 48).replace(convex=())]


def tank_size(m: Machine) -> tuple[float, float, float]:
    """(depth, width, height) of the tank standing in its cradle."""
    t = CRADLE[0]
    return m.tank_front - m.back - 2 * t - GAP, m.width - 2 * t - 2 * GAP, TANK[2] * m.height


def tank(m: Machine, slot: str, grip: str) -> tuple[list[g.Piece], Frame]:
    """The water tank standing in its cradle behind the tower, a grip on its back; it lifts straight up
    (engagement: the cradle's rim, :data:`CRADLE`)."""
    dx, dy, dz = tank_size(m)
    x0, z0 = m.back + CRADLE[0], m.d.floor + GAP / 2
    pieces = [g.box_between((x0, -dy / 2, z0), (x0 + dx, dy / 2, z0 + dz), slot, bevel=0.004).replace(
                  sheet=TANK_SHEET),
              g.box_between((x0 - 0.004, -0.03, z0 + dz - 0.03), (x0 + 0.001, 0.03, z0 + dz - 0.008), grip)]
    return pieces, Frame.at((x0 + dx / 2, 0, z0))


def tank_lid(m: Machine, slot: str) -> tuple[list[g.Piece], Frame]:
    """A fill flap on the tank's top, hinged at its back edge (axis -Y: the front lifts)."""
    dx, dy, dz = tank_size(m)
    x0, z0 = m.back + CRADLE[0] + 0.01, m.d.floor + GAP / 2 + dz + GAP
    x1 = x0 + dx - 0.02
    pieces = [g.box_between((x0, -0.4 * dy, z0), (x1, 0.4 * dy, z0 + 0.006), slot, bevel=0.002)]
    return pieces, Frame.at((x0, 0, z0 + 0.003), z=(0, -1, 0))


def reservoir_lid(m: Machine, slot: str) -> tuple[list[g.Piece], Frame]:
    """A drip machine's reservoir lid over the tower, hinged at the back (axis -Y: the front lifts)."""
    w, z0 = m.width / 2 - 0.004, m.height - LID_T
    pieces = [g.box_between((m.back + GAP, -w, z0), (m.tower_front - WALL - GAP, w, m.height), slot, bevel=0.004)
              .replace(sheet=LID_SHEET)]
    return pieces, Frame.at((m.back + GAP, 0, z0 + LID_T / 2), z=(0, -1, 0))


def pod_lid(m: Machine, slot: str) -> tuple[list[g.Piece], Frame]:
    """A capsule machine's head lid (the brew handle): the top of the head, hinged at its back edge (axis -Y:
    the front lifts to open the capsule chamber), a lip at the front to lift it by."""
    w, z0 = m.width / 2 - 0.003, m.height + GAP
    x0 = m.tower_front + LID_T
    pieces = [g.box_between((x0, -w, z0), (m.front, w, z0 + LID_T), slot, bevel=0.004).replace(sheet=LID_SHEET),
              g.box_between((m.front + GAP, -0.6 * w, z0 - 0.012), (m.front + 0.01, 0.6 * w, z0 + LID_T), slot,
                            bevel=0.003)]
    return pieces, Frame.at((x0, 0, z0 + LID_T / 2), z=(0, -1, 0))


def basket(m: Machine, slot: str) -> tuple[list[g.Piece], Frame]:
    """A drip machine's cone filter basket hanging under the head on a side pivot (axis +Z through the pivot
    left of it: it swings out to the front), a tab at its front to pull it by."""
    r, depth = BASKET
    z1 = m.head_bottom - GAP
    cone = g.shell([(0.45 * r, z1 - depth), (r, z1)], 0.003, slot, center=(m.bay, 0, 0))
    floor = g.disc((m.bay, 0, z1 - depth + 0.002), 0.45 * r - 0.003, 0.004, slot)
    y = r + 0.006
    arm = g.box_between((m.bay - 0.005, r - 0.004, z1 - 0.012), (m.bay + 0.005, y, z1), slot)
    knuckle = g.cylinder((m.bay, y, z1 - 0.014), (m.bay, y, z1), 0.006, slot, 16)
    tab = g.box_between((m.bay + r - 0.003, -0.012, z1 - 0.012), (m.bay + r + 0.012, 0.012, z1), slot)
    return [cone, floor, arm, knuckle, tab], Frame.at((m.bay, y, z1))


def carafe(m: Machine, slot: str, band: str, handle: str) -> tuple[list[g.Piece], Frame]:
    """A glass carafe on the warming plate, its handle to the front; it slides off the plate to the front."""
    r, z0 = CARAFE_R, m.d.floor + 0.002 + GAP / 2
    top = m.head_bottom - BASKET[1] - 0.012
    hgt = top - z0
    wall = g.shell([(0.92 * r, z0), (r, z0 + 0.08 * hgt), (r, z0 + 0.45 * hgt), (0.62 * r, z0 + 0.8 * hgt),
                    (0.66 * r, top)], CARAFE_GLASS, slot, center=(m.bay, 0, 0)).replace(sheet=CARAFE_GLASS)
    bottom = g.disc((m.bay, 0, z0 + 0.002), 0.92 * r - CARAFE_GLASS, 0.004, slot).replace(sheet=CARAFE_GLASS)
    collar = g.shell([(0.66 * r + 0.003, top - 0.025), (0.66 * r + 0.003, top + 0.004)], 0.004, band,
                     center=(m.bay, 0, 0))
    x = m.bay
    grip = g.tube([(x + 0.6 * r, 0, top - 0.015), (x + r + 0.03, 0, top - 0.02), (x + r + 0.03, 0, z0 + 0.35 * hgt),
                   (x + 0.97 * r, 0, z0 + 0.3 * hgt)], 0.009, handle)
    return [wall, bottom, collar, grip], Frame.at((x, 0, z0), z=(1, 0, 0))


def carafe_pull(m: Machine) -> float:
    """How far the carafe slides out: to the plinth's front edge under its centre."""
    return m.front - m.bay


def portafilter(m: Machine, slot: str, grip: str) -> tuple[list[g.Piece], Frame]:
    """The portafilter locked under the group head, its handle to the front; it turns about the group's axis
    (-Z: the handle swings to the left as one faces it, away from the wand) to the insertion notches."""
    r, ring_h, length, gr = PORTAFILTER
    z1 = m.head_bottom - GROUP[1] - GAP
    x = m.bay
    ring = g.cylinder((x, 0, z1 - ring_h), (x, 0, z1), r, slot).replace(wall=PORTAFILTER_WALL)
    spout = g.cylinder((x, 0, z1 - ring_h - 0.012), (x, 0, z1 - ring_h + 0.001), 0.008, slot, 12)
    arm = g.tube([(x + r - 0.004, 0, z1 - ring_h / 2), (x + r + 0.025, 0, z1 - ring_h / 2)], 0.008, slot)
    handle = g.tube([(x + r + 0.02, 0, z1 - ring_h / 2), (x + r + length, 0, z1 - ring_h / 2 - 0.02)], gr, grip)
    return [ring, spout, arm, handle], Frame.at((x, 0, z1), z=(0, 0, -1))


def wand(m: Machine, slot: str) -> tuple[list[g.Piece], Frame]:
    """The steam wand hanging from the head's underside at its front right (+Y) on a ball joint; it swings out to
    the right (axis +X)."""
    r, longest = WAND
    x, y, z = m.front - 0.025, m.width / 2 - 0.02, m.head_bottom - GAP
    length = min(longest, 0.7 * (z - m.d.floor - TRAY_HEIGHT))
    pieces = [g.sphere((x, y, z - 0.008), 0.008, slot),
              g.tube([(x, y, z - 0.012), (x, y, z - length), (x + 0.01, y, z - length - 0.01)], r, slot)]
    return pieces, Frame.at((x, y, z - 0.008), z=(1, 0, 0))


def drip_tray(m: Machine) -> LinerSize:
    """The drip tray in the bay under the head, standing on the floor plate."""
    return LinerSize(m.width - 2 * WALL - 2 * GAP, m.front - m.tower_front - GAP, TRAY_HEIGHT, 0.003, 0.0015,
                     0.008, 0.003)


def tray_front(m: Machine) -> Frame:
    """Where the drip tray's front goes (its anchor ``front``)."""
    size = drip_tray(m)
    return Frame.at((m.front + 0.001, 0, m.d.floor + GAP / 2 + (size.height + size.lip) / 2), z=(1, 0, 0),
                    x=(0, 0, 1))


def tray_grate(m: Machine, slot: str) -> list[g.Piece]:
    """The drip tray's cover: a perforated plate (drawn as bars) over the tray."""
    size = drip_tray(m)
    x0, x1, z = m.front - size.depth + 0.006, m.front - 0.004, m.d.floor + GAP / 2 + size.height - 0.003
    w = size.width / 2 - 0.006
    bars = int(max(3, (2 * w) // 0.012))
    ys = [-w + (k + 0.5) * 2 * w / bars for k in range(bars)]
    return [g.box_between((x0, y - 0.002, z), (x1, y + 0.002, z + 0.003), slot) for y in ys]


def key_anchors(m: Machine, count: int) -> list[Frame]:
    """Mounting frames of ``count`` keys in a row on the front (z out of it, x up): on a drip machine's
    plinth, on the head of the others, from the left end (-Y) inwards."""
    z = m.d.floor / 2 if m.design == "drip" else m.head_bottom + 0.45 * (m.height - m.head_bottom)
    y0 = -(m.width / 2 - 0.022)
    return [Frame.at((m.front, y0 + k * BUTTON_PITCH, z), z=(1, 0, 0), x=(0, 0, 1)) for k in range(count)]


def dial_anchor(m: Machine) -> Frame:
    """Where the steam dial goes: the head's front at its right end (+Y), level with the keys."""
    z = m.head_bottom + 0.45 * (m.height - m.head_bottom)
    return Frame.at((m.front, m.width / 2 - DIAL.radius - 0.012, z), z=(1, 0, 0), x=(0, 0, 1))


def keys_fit(m: Machine) -> int:
    """How many keys fit the front's width with room left for the basket, the group or the lid's lip."""
    return max(1, min(BUTTONS_MAX, int((0.45 * m.width) // BUTTON_PITCH)))
