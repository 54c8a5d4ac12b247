"""Blenders: the motor base of each design, the jug (or the personal blender's cup) with its blades, its lid
and the lid's cap.

Everything is built round the jug's axis (Z up through the middle of the base's top, the controls on the front,
+X), the base on z = 0. Each moving part is returned with the frame its joint turns or slides about (z the axis,
a positive move opens: the jug turns out of its lock and lifts off the drive, the lid lifts, the cap turns and
lifts out of the lid).

Designs (real product types; sizes below with their sources):

* ``countertop``: a high-power blender, a square tapered clear jug (Tritan copolyester) on a box base with a
  speed dial and switches (Vitamix 5200 / E310, Ninja Professional BL610);
* ``glass_jar``: a classic blender, a round glass jar screwed into its blade collar on a base with a row of
  push buttons (Oster Pro 1200, Oster 4655, Hamilton Beach 50190);
* ``personal``: a personal (bottle) blender, the cup upside down on its blade base, pushed and twisted into a
  round motor base that has no switch: pressing the cup down runs it (NutriBullet 600 / Pro 900).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import appliance as A
from . import controls
from .casing import CasingSize, Cutout
from .vessel import Profile, polygon_wall


@dataclass(frozen=True)
class Design:
    """A blender design: the base's ``width`` (Y), ``depth`` (X) and ``height`` ranges, the jug's height, its
    bottom and top half widths (m), the motor's mass (kg)."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    jug: tuple[float, float]
    bottom: float
    top: float
    motor: float


# Spec sheets and retailer listings (inches converted, approximate where a listing rounds): Vitamix 5200 with its
# 64 oz container 20.5 H x 8.75 W x 7.25 D in (52 x 22 x 18 cm), 4.8 kg, its base ~8 in (20 cm) tall, the 64 oz
# container ~12 in (30 cm) tall; Vitamix E310 with a 48 oz container 17.5 x 8 x 11 in (44 x 20 x 28 cm); Ninja
# Professional BL610 17 x 8 x 6.5 in (43 x 20 x 17 cm), 4.3 kg, its 72 oz pitcher ~10 in (26 cm) tall; Oster
# Pro 1200 with its 6-cup glass jar ~14 x 8 x 7.5 in (36 x 20 x 19 cm), ~4.5 kg; NutriBullet 600 base ~4.7 in
# (12 cm) across and 5 in (13 cm) tall, the 24 oz cup ~7.5 in (19 cm) tall. Motors (service-part listings):
# 1.4-2.2 hp jug blenders 1.5-2 kg, a 600-900 W personal blender ~0.8 kg.
DESIGNS = {
    "countertop": Design((0.17, 0.22), (0.18, 0.21), (0.15, 0.2), (0.24, 0.30), 0.055, 0.078, 1.8),
    "glass_jar": Design((0.17, 0.2), (0.17, 0.19), (0.1, 0.13), (0.19, 0.22), 0.06, 0.075, 1.2),
    "personal": Design((0.11, 0.125), (0.11, 0.125), (0.11, 0.13), (0.16, 0.2), 0.045, 0.04, 0.8),
}
MOTOR_DENSITY = 7850.0  # steel laminations and copper windings, massed as steel
CASING_SHEET, CASING_WALL, CORNER = 0.0025, 0.003, 0.012  # m, moulded ABS base: 2.5 mm, its corner radius
JUG_WALL = {"countertop": 0.003, "glass_jar": 0.005, "personal": 0.0025}  # m: Tritan 3 mm, glass 5-6 mm
JUG_SHEET = {"countertop": 0.003, "glass_jar": 0.006, "personal": 0.0025}
TRITAN = 1180.0  # kg/m^3, Eastman Tritan copolyester (data sheet 1.18 g/cm^3): a clear jug is drawn as glass
COLLAR = 0.03  # m, the jug's blade collar (drive coupling and blade bearing) under its floor
PAD = 0.012  # m, the drive pad on the base's top the collar sits on
GAP = 0.0015  # m, between what rests and what it rests on
JUG_SEAT = 0.012  # m, how far the drive pad's locating rim guides the collar (the jug's lift-off engagement)
JUG_TWIST = math.radians(30)  # a twist-lock jug turns about a twelfth of a turn out of its lock (Ninja, Oster)
CUP_TWIST = math.radians(25)
LID_T = 0.01  # m, the lid's thickness
LID_SEAL = 0.015  # m, a lid's rubber seal skirt down inside the rim (its lift-off engagement)
CAP_R, CAP_PLUG = 0.022, 0.025  # m, the lid cap's (measuring cup's) plug radius and depth through the lid
CAP_TWIST = math.radians(40)  # the Vitamix lid plug turns a quarter to an eighth of a turn out of its tabs
CLEAR = 0.002  # m, round a plug in its hole
HANDLE_R = 0.011  # m, a jug handle's grip
DIAL = controls.Dial(radius=0.024, stem=0.005, style="ridge", turns=math.radians(270))
# Speed keys (Oster, Hamilton Beach, Ninja photos): 12-14 mm wide, 20-26 mm apart in a row of up to five
BUTTON = controls.Button(half=(0.0065, 0.005), shape="rect", proud=0.004, travel=0.003)
BUTTON_PITCH = 0.026  # m, the widest pitch of a row (a narrow base packs five keys at >= 20 mm)
BUTTONS_MAX = 5


@dataclass(frozen=True)
class Blender:
    """Where a blender's parts go: the design, base width, depth and height, the jug's foot ``z0`` (the drive
    pad's top), its floor ``zf``, rim ``zr``, bottom and top half widths."""

    design: str
    width: float
    depth: float
    height: float
    z0: float
    zf: float
    zr: float
    bottom: float
    top: float


def blender(design: str, t: float, u: float) -> Blender:
    """The base of ``design`` at ``t`` of its size range, the jug at ``u`` of its height range."""
    d = DESIGNS[design]
    w, dp, h = (lo + t * (hi - lo) for lo, hi in (d.width, d.depth, d.height))
    hj = d.jug[0] + u * (d.jug[1] - d.jug[0])
    z0 = h + (0.0 if design == "personal" else PAD)
    zf = z0 + GAP + COLLAR
    return Blender(design, w, dp, h, z0, zf, zf + hj, d.bottom, d.top)


def casing_size(b: Blender) -> CasingSize:
    return CasingSize(b.width, b.depth, b.height, CASING_WALL, CASING_SHEET, CORNER)


def cutouts(b: Blender, dial: bool, buttons: int) -> dict[str, Cutout]:
    """The front's holes: the dial over a row of buttons, or a row of buttons alone (centred)."""
    size, cuts = casing_size(b), {}
    if dial:
        cuts["dial"] = DIAL.cutout("front", size.on("front", 0.0, 0.2))
    row = size.on("front", 0.0, -0.45 if dial else -0.1)[1]
    # a row centred on the front's flat, clear of its rounded corners
    room = b.width / 2 - 2 * CORNER - BUTTON.half[0] - A.CLEAR - 0.002  # a corner post is 2 radii deep
    pitch = min(BUTTON_PITCH, 2 * room / max(buttons - 1, 1))
    for k in range(buttons):
        cuts[f"button_{k}"] = BUTTON.cutout("front", ((k - (buttons - 1) / 2) * pitch, row))
    return cuts


def motor(b: Blender, slot: str) -> g.Piece:
    """The motor inside the base, under the drive (a cylinder of its mass)."""
    r = min(0.045, 0.3 * b.width)
    length = DESIGNS[b.design].motor / MOTOR_DENSITY / (math.pi * r * r)
    return g.cylinder((0, 0, 0.012), (0, 0, 0.012 + length), r, slot, 24).replace(wall=0.0)  # solid, not a shell


def pad(b: Blender, slot: str) -> list[g.Piece]:
    """The drive pad on a box base's top: a square plinth the jug's collar sits on, and its drive socket."""
    a = b.bottom + 0.006
    return [g.box_between((-a, -a, b.height - 0.001), (a, a, b.z0), slot, bevel=0.004)]


def round_base(b: Blender, slot: str) -> list[g.Piece]:
    """A personal blender's round base: a slightly tapered drum."""
    r, h = b.width / 2, b.height
    return [g.revolve([(0.0, 0.0), (0.92 * r, 0.0), (r, 0.1 * h), (0.94 * r, h), (0.0, h)], slot)]


def receptacle(b: Blender, slot: str) -> list[g.Piece]:
    """The ring on a personal blender's base the cup's blade base drops into and locks in."""
    ring_r = b.bottom + 0.006 + CLEAR
    return [g.shell([(ring_r + 0.003, b.height - 0.001), (ring_r + 0.003, b.height + JUG_SEAT)], 0.003, slot)]


def jug(b: Blender, slot: str, collar_slot: str, blade_slot: str, handle_slot: str) -> list[g.Piece]:
    """The jug: its blade collar, floor, wall, blades and handle (+Y); a personal blender's cup stands on its
    blade base, closed at the top."""
    wall, sheet = JUG_WALL[b.design], JUG_SHEET[b.design]
    zc = b.z0 + GAP
    if b.design == "countertop":
        a = b.bottom
        pieces = [g.box_between((-a - 0.004, -a - 0.004, zc), (a + 0.004, a + 0.004, b.zf), collar_slot, bevel=0.004),
                  g.box_between((-a, -a, b.zf), (a, a, b.zf + wall), slot).replace(sheet=sheet),
                  polygon_wall([(a, b.zf), (b.top, b.zr)], wall, 4, slot).replace(sheet=sheet)]
        reach = a
    else:
        prof = _round_profile(b)
        rc = b.bottom + 0.006
        pieces = [g.cylinder((0, 0, zc), (0, 0, b.zf), rc, collar_slot, 32),
                  g.disc((0, 0, b.zf + wall / 2), prof.base_radius - 0.001, wall, slot).replace(sheet=sheet),
                  prof.wall(slot, sheet=sheet)]
        reach = prof.base_radius - wall
        if b.design == "personal":
            pieces.append(g.disc((0, 0, b.zr - wall / 2), prof.top_radius - 0.001, wall, slot).replace(sheet=sheet))
    if b.design != "personal":  # the blade assembly over the floor (a cup's is down in its blade base)
        pieces += blades(b.zf + wall, 0.75 * reach, blade_slot)
    if b.design != "personal":
        pieces.append(g.tube(handle_path(b), HANDLE_R, handle_slot))
    return pieces


# A blender's blade assembly (Oster, Ninja, Vitamix replacement blade listings): a hub 14-18 mm across standing
# 12-20 mm off the jar floor on its bearing, a nut on top, and four stamped steel wings 10-14 mm wide, 1.5 mm thick:
# two bent up 25-35 degrees (they lift the mix into a vortex), two bent down ~15 degrees, each pitched ~15 degrees.
BLADE = {"hub": 0.008, "stand": 0.015, "width": 0.012, "thick": 0.0015, "up": math.radians(30),
         "down": math.radians(-15), "pitch": math.radians(15)}


def _rot(axis: int, a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m = np.eye(4)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def blades(z_floor: float, reach: float, slot: str) -> list[g.Piece]:
    """A blade assembly on the jar's floor at ``z_floor``: the hub on its bearing, its nut, and four wings out to
    ``reach`` (:data:`BLADE`), alternately bent up and down: real cutting geometry, not a flat cross."""
    d = BLADE
    zb = z_floor + d["stand"]
    pieces = [g.cylinder((0, 0, z_floor), (0, 0, zb + 0.003), d["hub"], slot, 24),
              g.cylinder((0, 0, zb + 0.003), (0, 0, zb + 0.008), 0.6 * d["hub"], slot, 6)]  # the hex nut
    for k in range(4):
        bend = d["up"] if k % 2 == 0 else d["down"]
        length = (reach - 0.5 * d["hub"]) / math.cos(bend)
        wing = g.box((length, d["width"], d["thick"]), (length / 2, 0, 0), slot)
        m = _rot(2, k * math.pi / 2) @ _rot(1, -bend) @ _rot(0, d["pitch"])
        m[:3, 3] = (0.0, 0.0, zb)
        pieces.append(wing.transformed(m).translated((0.5 * d["hub"] * math.cos(k * math.pi / 2),
                                                      0.5 * d["hub"] * math.sin(k * math.pi / 2), 0.0)))
    return pieces


MARKS = 7  # printed volume marks up the jug's front, every other one long (cups / ml scales)


def marks(b: Blender, slot: str) -> list[g.Piece]:
    """The printed volume scale on the front (+X) of the jug or cup: thin ticks on the wall's outside."""
    pieces = []
    for k in range(MARKS):
        z = b.zf + (0.2 + 0.1 * k) * (b.zr - b.zf)
        x = _half_width(b, z) - 0.0004
        w = 0.008 if k % 2 else 0.016
        pieces.append(g.box_between((x, -w / 2, z - 0.0008), (x + 0.0008, w / 2, z + 0.0008), slot))
    return pieces


def _round_profile(b: Blender) -> Profile:
    h = b.zr - b.zf
    if b.design == "personal":  # the cup's mouth is down on its blade base, its closed bottom up
        ctrl = [(b.bottom, b.zf), (0.97 * b.bottom, b.zf + 0.5 * h), (b.top, b.zr)]
    else:  # a jar widening from its collar to a rim
        ctrl = [(b.bottom, b.zf), (0.88 * b.top + 0.12 * b.bottom, b.zf + 0.45 * h), (b.top, b.zr)]
    return Profile.through(ctrl, JUG_WALL[b.design], (32, 6))


def _half_width(b: Blender, z: float) -> float:
    """The jug's outer half width (apothem or radius) at height ``z``."""
    f = (z - b.zf) / (b.zr - b.zf)
    return b.bottom + f * (b.top - b.bottom)


def handle_path(b: Blender) -> list[tuple[float, float, float]]:
    """A D-shaped grip on the +Y side from under the rim down to the lower third, its ends in the wall."""
    h = b.zr - b.zf
    zt, zl = b.zr - 0.12 * h, b.zf + 0.3 * h
    yt, yl = _half_width(b, zt) - 0.002, _half_width(b, zl) - 0.002
    out = max(yt, yl) + 0.05
    return [(0, yt, zt), (0, out - 0.01, zt + 0.005), (0, out, zt - 0.02), (0, out - 0.005, zl + 0.02),
            (0, yl, zl)]


def seat(b: Blender) -> Frame:
    """The jug's seat on the drive (z up): it twists about it and lifts off along it."""
    return Frame.at((0, 0, b.z0))


def lid(b: Blender, slot: str) -> tuple[list[g.Piece], Frame]:
    """The lid on the rim with a hole for its cap: a square plate over a square jug, a ring over a round one;
    it lifts off along +Z."""
    z = b.zr + GAP
    hole = CAP_R + CLEAR
    if b.design == "countertop":
        a = b.top + 0.004
        plate = g.panel((-a, -a, z), (a, a, z + LID_T), slot, "z", [(-hole, -hole, hole, hole)])
    else:
        plate = g.shell([(b.top + 0.004, z), (b.top + 0.004, z + LID_T)], b.top + 0.004 - hole, slot)
    return [plate], Frame.at((0, 0, z))


def cap(b: Blender, slot: str) -> tuple[list[g.Piece], Frame]:
    """The lid cap: a plug down through the lid's hole under a flange that rests on the lid; it turns out of
    its tabs and lifts out (+Z)."""
    z = b.zr + GAP + LID_T + GAP
    pieces = [g.cylinder((0, 0, z - CAP_PLUG), (0, 0, z + 0.004), CAP_R, slot, 24),
              g.cylinder((0, 0, z), (0, 0, z + 0.006), CAP_R + 0.008, slot, 32),
              g.box_between((-0.012, -0.003, z + 0.006), (0.012, 0.003, z + 0.016), slot, bevel=0.002)]
    return pieces, Frame.at((0, 0, z))
