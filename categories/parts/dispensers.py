"""Dispensers: a pump bottle, a wall soap dispenser and a condiment pump, and the frames their parts move about.

Every pump is pressed down against its return spring: its head rests at the top of its stroke and slides along
-Z (the joint's rest is its top stop; role ``plunger`` holds it there against gravity and brings it back when let
go). Each builder returns its pieces in the object's frame (Z up, the nozzle or the push panel facing +X) and
the frame its joint turns or slides about (z the axis, a positive move opens or presses).

Designs (real product types; sizes below with their sources):

* ``pump_bottle``: a soap or lotion pump bottle: a Boston round with a 24/410 pump whose collar unscrews to
  refill it, whose actuator presses down and whose nozzle head turns to lock (Method, Softsoap, Aesop, glass
  Boston rounds);
* ``wall``: a wall soap dispenser: a housing with a refill lid hinged at the back of its top and a push panel
  per chamber (1-3) hinged at its top edge over its nozzle, pushed in against its spring (GOJO ADX-12, Dettol,
  Rubbermaid; Better Living multi-chamber shower dispensers);
* ``sauce_pump``: a condiment pump: a jar whose lid, carrying the pump, lifts off to refill it, and a plunger
  head with a long spout pressed down to pump (Server Products, Tablecraft, San Jamar).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import hardware
from .vessel import Profile, _sleeve_cap

# Pump bottles (maker and retail listings): 250-500 ml Boston rounds 0.13-0.18 m tall to the neck, 60-75 mm
# across (a 500 ml Boston round 0.17 x 0.075 m); PET or glass.
BOTTLE = {"height": (0.13, 0.18), "radius_ratio": 0.21, "wall": (0.0015, 0.003)}
# A 24/410 lotion pump (pump maker spec sheets): a 12 mm collar, a 22 x 14 mm actuator with a 20 mm nozzle,
# 2 cc output on a 10 mm stroke; the head turns a quarter to lock down.
PUMP = {"turret": 0.013, "bore": 0.0045, "stem": 0.0035, "visible": 0.0125, "head": (0.011, 0.014),
        "nozzle": (0.02, 0.0035), "stroke": 0.010}
PUMP_TURNS = math.radians(90)
# Wall dispensers, W x D x H: GOJO ADX-12 0.16 x 0.10 x 0.28 m, Rubbermaid Foam 0.13 x 0.10 x 0.24 m,
# Dettol / Umbra wall pumps 0.11 x 0.09 x 0.20 m; 0.3-0.6 kg empty.
WALL = {"width": (0.11, 0.16), "depth": (0.09, 0.11), "height": (0.20, 0.28)}
# Multi-chamber shower dispensers (Better Living "The Dispenser" 1-3 chambers: 3-chamber 0.32 x 0.09 x 0.21 m):
# one push panel per chamber, each chamber 0.095-0.11 m wide.
CHAMBER = (0.095, 0.11)
CHAMBERS_MAX = 3
SHELL = 0.0025  # m, an ABS housing's moulded wall (its mass)
PANEL = (0.32, 0.006, 0.032)  # push panel: share of the height, thickness (m), the recess behind it (m)
PANEL_PUSH = math.radians(14)  # a push panel's stroke: 15-25 mm at its bottom edge
LID_OPENS = math.radians(100)
LID_HINGE = (0.6, 0.004)  # the refill lid's moulded barrel hinge along its back edge: share of the width, knuckle
# radius (m) (GOJO, Tork wall dispensers' back-hinged covers, manufacturers' pictures)
LOCK = (0.008, 0.006)  # m, the key lock's barrel radius and how far it stands out of the side
LOCK_TURNS = math.radians(90)
# Condiment pumps (Server Products 83800, Tablecraft 664 listings): a 1.5-3 qt jar 0.12-0.17 m across and
# 0.15-0.22 m tall under a lid carrying the pump; a 30 mm stroke of 1 oz.
SAUCE = {"radius": (0.06, 0.085), "height": (0.15, 0.22), "wall": 0.003, "lid": 0.006, "skirt": 0.015,
         "barrel": (0.016, 0.05), "stroke": 0.03, "spout": (0.08, 0.005)}


@dataclass(frozen=True)
class Sized:
    """A design's drawn size: ``t`` of each range."""

    t: float

    def of(self, rng: tuple[float, float]) -> float:
        return rng[0] + self.t * (rng[1] - rng[0])


# -- pump bottle ----------------------------------------------------------------------------------------------


def collar(neck: Profile, finish_bottom: float, slot: str) -> tuple[list[g.Piece], float]:
    """The pump's collar screwed on the neck (in the bottle's frame): a skirt and top plate, and a hollow
    turret whose bore takes the stem's stroke. Returns the pieces and the turret's top (z)."""
    pieces, r_out, top = _sleeve_cap(neck, max(finish_bottom + 0.0065, neck.height - 0.012), 0.0016, 0.003,
                                     0.0004, slot, 0.0)
    r = 0.55 * r_out
    turret = g.shell([(r, top - 0.0003), (r, top + PUMP["turret"])], r - PUMP["bore"], slot, sections=32)
    return pieces + [turret], top + PUMP["turret"]


def stem(top: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """The actuator's stem standing in the turret's bore (``top``: the turret's top), pressed down along -Z."""
    z0 = top - (PUMP["turret"] - PUMP["stroke"] - 0.001)  # at the bottom of its stroke, still over the plate
    pieces = [g.cylinder((0, 0, z0), (0, 0, top + PUMP["visible"]), PUMP["stem"], slot, 16)]
    return pieces, Frame.at((0, 0, top), z=(0, 0, -1))


def head(top: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """The actuator head on the stem with its nozzle toward +X; it turns about the stem (+Z) to lock."""
    hr, hh = PUMP["head"]
    nl, nr = PUMP["nozzle"]
    z0 = top + PUMP["visible"]
    body = g.revolve([(0.0, z0), (hr, z0), (hr, z0 + 0.7 * hh), (0.8 * hr, z0 + hh), (0.0, z0 + hh)], slot,
                     sections=32)
    nozzle = g.cylinder((0.5 * hr, 0, z0 + 0.55 * hh), (hr + nl, 0, z0 + 0.55 * hh), nr, slot, 12)
    return [body, nozzle], Frame.at((0, 0, z0))


# -- wall dispenser ---------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Housing:
    """A wall dispenser's housing: ``width`` (Y), ``depth`` (X), ``height`` (Z), standing on z = 0 with its back
    on x = -depth / 2."""

    width: float
    depth: float
    height: float
    chambers: int = 1

    @property
    def panel_top(self) -> float:
        return PANEL[0] * self.height

    @property
    def front(self) -> float:
        return self.depth / 2


    def chamber(self, k: int) -> tuple[float, float]:
        """(y centre, half width) of chamber ``k``, numbered from -Y."""
        half = self.width / (2 * self.chambers)
        return -self.width / 2 + (2 * k + 1) * half, half


def housing(t: float, chambers: int = 1) -> Housing:
    s = Sized(t)
    width = s.of(WALL["width"]) if chambers == 1 else chambers * s.of(CHAMBER)
    return Housing(width, s.of(WALL["depth"]), s.of(WALL["height"]), chambers)


def housing_body(h: Housing, slot: str, trim: str, lid: bool) -> list[g.Piece]:
    """The housing: the upper box (its top open under a refill lid), the lower box set back behind the push
    panel, the nozzle under the upper box in the recess, and a wall plate at the back."""
    w, x0, x1, zt = h.width / 2, -h.depth / 2, h.front, h.panel_top
    top = h.height - (0.01 if lid else 0.0)
    pieces = [g.box_between((x0, -w, zt), (x1, w, top), slot, bevel=0.005),
              g.box_between((x0, -w, 0), (x1 - PANEL[2], w, zt + 0.001), slot, bevel=0.004),
              g.box_between((x0 - 0.006, -0.8 * w, 0), (x0, 0.8 * w, 0.9 * h.height), trim)]
    if lid:
        pieces += lid_hinge(h, trim)[0]
    xn = x1 - PANEL[2] / 2 - 0.01
    pieces += [g.cylinder((xn, h.chamber(k)[0], zt - 0.012), (xn, h.chamber(k)[0], zt + 0.001), 0.005, trim, 12)
               for k in range(h.chambers)]
    return [pc.replace(sheet=SHELL) for pc in pieces]


def wall_lid(h: Housing, slot: str) -> tuple[list[g.Piece], Frame]:
    """The refill lid closing the housing's top, hinged at its back edge (axis -Y: the front lifts)."""
    w, x0, z0 = h.width / 2 - 0.002, -h.depth / 2 + 0.002, h.height - 0.01 + 0.0015
    pieces = [g.box_between((x0, -w, z0), (h.front - 0.002, w, h.height + 0.0015), slot, bevel=0.003)
              .replace(sheet=SHELL)]
    return pieces + lid_hinge(h, slot)[1], _lid_axis(h)


def _lid_axis(h: Housing) -> Frame:
    return Frame.at((-h.depth / 2 + 0.002, 0, h.height - 0.0045), z=(0, -1, 0))


def lid_hinge(h: Housing, slot: str) -> tuple[list[g.Piece], list[g.Piece]]:
    """The refill lid's barrel hinge on its axis at the housing's back top edge (:data:`LID_HINGE`), its two end
    knuckles on the housing with a leaf down its back, the middle one on the lid (decoration,
    :func:`~.hardware.barrel_hinge`); returns (housing pieces, lid pieces)."""
    share, r = LID_HINGE
    length = share * h.width
    fixed, moving = hardware.barrel_hinge(length, r, slot, moving_share=0.4, sections=12)
    # the pin frame: x out of the back, y down the back, z along the axis
    fixed.append(hardware.leaf((0.002, 0.0, -length / 2), (0.0032, 0.028, length / 2), slot, 0.0005))
    pin = Frame.at(_lid_axis(h).origin, x=(-1, 0, 0), z=(0, -1, 0))
    return [pc.transformed(pin.matrix) for pc in fixed], [pc.transformed(pin.matrix) for pc in moving]


def push_panel(h: Housing, k: int, slot: str) -> tuple[list[g.Piece], Frame]:
    """Chamber ``k``'s push panel hanging in front of the recess, hinged at its top edge (axis +Y: its bottom
    swings in)."""
    (y, w), t, zt = h.chamber(k), PANEL[1], h.panel_top - 0.002
    w -= 0.004
    x1 = h.front
    pieces = [g.box_between((x1 - t, y - w, 0.008), (x1, y + w, zt - 0.004), slot, bevel=0.002)
              .replace(sheet=SHELL)]
    return pieces, Frame.at((x1 - t / 2, y, zt - 0.004), z=(0, 1, 0))


def lock(h: Housing, slot: str) -> tuple[list[g.Piece], Frame]:
    """A key lock's barrel on the housing's right side (-Y), turning a quarter about its axis to release the lid."""
    r, out = LOCK
    y, z, x = -h.width / 2, h.height - 0.04, 0.0
    pieces = [g.cylinder((x, y - 0.0008, z), (x, y - out, z), r, slot, 16),
              g.box_between((x - 0.0012, y - out - 0.0015, z - 0.004), (x + 0.0012, y - out + 0.0005, z + 0.004),
                            slot)]
    return pieces, Frame.at((x, y, z), z=(0, -1, 0))


# -- condiment pump ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Jar:
    radius: float
    height: float


def jar(t: float) -> Jar:
    s = Sized(t)
    return Jar(s.of(SAUCE["radius"]), s.of(SAUCE["height"]))


def jar_body(j: Jar, slot: str) -> list[g.Piece]:
    """The open jar: a straight wall on a flat bottom."""
    t = SAUCE["wall"]
    return [g.shell([(j.radius, 0.0), (j.radius, j.height)], t, slot),
            g.disc((0, 0, t), j.radius - t, 2 * t, slot)]


def sauce_lid(j: Jar, slot: str, barrel_slot: str) -> tuple[list[g.Piece], Frame, float]:
    """The lid on the jar's rim with its skirt inside the mouth and the pump's barrel standing on it; it lifts
    straight off (engagement: the skirt). Returns the pieces, its seat and the barrel's top (z)."""
    lt, sk, gap = SAUCE["lid"], SAUCE["skirt"], 0.0015
    r_in = j.radius - SAUCE["wall"]
    z0 = j.height + gap
    br, bh = SAUCE["barrel"]
    pieces = [g.disc((0, 0, z0 + lt / 2), j.radius + 0.004, lt, slot),
              g.shell([(r_in - gap, z0 - sk), (r_in - gap, z0)], 0.002, slot),
              g.shell([(br, z0 + lt - 0.0005), (br, z0 + lt + bh)], br - 0.006, barrel_slot, sections=32)]
    return pieces, Frame.at((0, 0, z0)), z0 + lt + bh


def sauce_head(top: float, slot: str, spout_slot: str) -> tuple[list[g.Piece], Frame]:
    """The plunger: a rod in the barrel's bore, a round push cap and a spout reaching forward and down over the
    jar's edge; pressed down along -Z."""
    stroke = SAUCE["stroke"]
    length, r = SAUCE["spout"]
    cap_r = SAUCE["barrel"][0] + 0.006
    z = top + stroke + 0.004
    pieces = [g.cylinder((0, 0, top - 0.003), (0, 0, z), 0.0045, spout_slot, 16),
              g.cylinder((0, 0, z), (0, 0, z + 0.018), cap_r, slot, 32),
              g.tube([(0.5 * cap_r, 0, z + 0.006), (length, 0, z + 0.006), (length + 0.012, 0, z - 0.006)], r,
                     spout_slot)]
    return pieces, Frame.at((0, 0, top), z=(0, 0, -1))
