"""Pop-up toasters: the casing of each design, its bread slots and where a control group sits on the front.

A toaster is a :func:`~.casing.sheet_casing` with its bread slots cut in the top and, on the front face, one
or two control groups: a carriage lever in its slot, a browning dial and a column of push buttons (cancel,
defrost, bagel). Every hole is a named :class:`~.casing.Cutout`, so the category places the lever, the dial
and the buttons on the casing's anchors of those names (``lever_0``, ``dial_0``, ``button_0_1`` ...).

Designs (real product types, sizes below with their sources):

* ``two_slot``: two bread slots side by side across the width, the controls on the long front face at its
  right end (Breville BTA720XL, Cuisinart CPT-122 layout), or stood end on: the controls on its short end,
  which is then its front, the lever in a vertical slot up its middle and the slots running front to back
  (Dualit Classic, Smeg TSF01, KitchenAid KMT2115 layout).
* ``four_slot``: four slots running front to back in a row across the width, two control groups (one per
  pair of slots) at the left and right of the front (Cuisinart CPT-180, Hamilton Beach 24910 layout).
* ``long_slot``: two extra-long slots (two slices end to end each) across a long body, one control group or
  one per slot (Breville BTA730XL and BTA830XL 4-slice long slot, Dualit Lite long slot); with one group it
  may stand end on as a two-slot.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g

from . import appliance as A
from . import controls
from .casing import CasingSize, Cutout, LinerSize


@dataclass(frozen=True)
class Design:
    """A toaster design: outer ``width`` (Y), ``depth`` (X), ``height`` (Z) ranges (m), its bread slots
    (``slots`` of ``slot_length``, running ``along`` the top face's ``"u"`` (across the width) or ``"v"``
    (front to back))."""

    width: tuple[float, float]
    depth: tuple[float, float]
    height: tuple[float, float]
    slots: int
    slot_length: float
    along: str

    def at(self, t: float) -> tuple[float, float, float]:
        """(width, depth, height) at ``t`` of its size range (0: the smallest, 1: the largest)."""
        return tuple(lo + t * (hi - lo) for lo, hi in (self.width, self.depth, self.height))


# Sizes from retail spec listings (manufacturer product pages, inches converted): a 2-slice toaster is
# 10.5-12 in wide, 6.5-7.8 in deep, 7-8 in tall (Cuisinart CPT-122 11.5 x 7.25 x 7.5 in, Breville BTA720XL
# 11.5 x 7.5 x 8 in, KitchenAid KMT2115 11.5 x 7.5 x 7.5 in); a side-by-side 4-slice toaster 11-12.5 in wide,
# 10.5-12 in deep (Cuisinart CPT-180 11.9 x 11.4 x 7.5 in, Hamilton Beach 24910 11.2 x 11 x 7.8 in); a long-slot
# 4-slice 15-17 in wide, 6.5-7.5 in deep (Breville BTA730XL 16.5 x 7 x 8 in, Hamilton Beach 24990 long slot
# 15.7 x 6.5 x 7.5 in). A bread slot takes a sandwich slice (0.11-0.13 m): 0.135 m long; a long slot two
# slices end to end: 0.27 m.
DESIGNS = {
    "two_slot": Design((0.27, 0.31), (0.17, 0.20), (0.18, 0.20), 2, 0.135, "u"),
    "four_slot": Design((0.28, 0.32), (0.27, 0.30), (0.18, 0.20), 4, 0.135, "v"),
    "long_slot": Design((0.38, 0.43), (0.16, 0.19), (0.18, 0.20), 2, 0.27, "u"),
}

SHEET = 0.0006  # m, steel of a toaster casing: 0.5-0.7 mm stainless or painted sheet
WALL = 0.003  # m, the casing walls as the simulator sees them (massed as SHEET)
SLOT_GAP = 0.02  # m, wall between two bread slots
# Replacement carriage levers and browning knobs (product photos): a 40 x 15 mm paddle 25 mm out on a
# 6 x 4 mm stem that travels ~80 mm down; a 15 mm knob turning ~270 degrees from light to dark.
LEVER = controls.Lever(stem=(0.006, 0.004), paddle=(0.04, 0.015, 0.012), reach=0.013, travel=0.08)
DIAL = controls.Dial(radius=0.015, stem=0.003, style="round", turns=4.712)  # 270 degrees
# Cancel / defrost / bagel / reheat keys (Breville BTA720XL, Cuisinart CPT-180 photos): 16-20 x 8-10 mm
# rounded keys about 3 mm proud that press in about 2 mm.
BUTTON = controls.Button(half=(0.009, 0.0045), shape="rect", proud=0.003, travel=0.002)
BUTTONS_MAX = 3  # cancel, defrost, bagel (a reheat key takes the place of one on some models)
TRAY_HEIGHT, TRAY_LIP, TRAY_CLEARANCE = 0.01, 0.01, 0.002  # a crumb tray 10 mm deep with a 20 mm front
TRAY_PULL = 0.8  # the tray slides out this share of its depth before it leaves its rails
# The crumb tray's front sits flush in the casing with 2 mm round it: it is pulled by a lug on the front's middle,
# 10 mm proud and 5 mm across (sized for a pinch: a Panda finger pad is 20 mm wide; not measured from a product)
TRAY_TAB = (0.01, 0.005)  # m, proud, thick

# A control group on the front face, for a group on the right (+1) or left (-1), as fractions of the front's
# half width and half height: the lever near the end, the dial and the key column inside it.
LEVER_AT = (0.68, 0.55)
DIAL_AT = (0.3, 0.5)
KEYS_V = (0.05, -0.2, -0.45)
# A control group on an end face (the short side: Dualit Classic, Smeg TSF01, KitchenAid KMT2115 product
# photos): the lever in a vertical slot up the middle, the dial under one side of it, the keys in a column
# beside it, all clear of the paddle's path down the slot and of the rounded corners' hulls (fractions of the
# end face's half extents).
END_LEVER_AT = (0.0, 0.55)
END_DIAL_AT = (-0.45, -0.5)
END_KEYS_U = 0.4
CONTROL_FACES = ("front", "end")  # a toaster's controls on its long side, or on its short end (end on)


def casing_size(design: str, t: float, corner: float, end: bool = False) -> CasingSize:
    """The casing of ``design`` at ``t`` of its size range, upright edges rounded to ``corner`` (``end``: stood
    end on, its short end the front: width and depth swapped)."""
    width, depth, height = DESIGNS[design].at(t)
    if end:
        width, depth = depth, width
    return CasingSize(width, depth, height, WALL, SHEET, corner)


def crumb_tray(size: CasingSize) -> LinerSize:
    """The crumb tray that slides in over the casing's floor plate, as wide as the corner posts let it."""
    return LinerSize(size.clear_width - 2 * TRAY_CLEARANCE, size.depth - 2 * WALL - TRAY_CLEARANCE, TRAY_HEIGHT,
                     WALL, SHEET, TRAY_LIP, WALL)


def group_sides(groups: int) -> tuple[int, ...]:
    """Which end of the front each control group takes: one on the right (u = -y, so -1 is the right end as
    one faces the front), two on both ends."""
    return (-1,) if groups == 1 else (-1, 1)


def end_on(design: str, face: str, groups: int) -> bool:
    """Whether a toaster stands end on: its controls on the short end face, which is then its front (+x), the
    slots running front to back; a design with slots across its width and a single control group only."""
    return face == "end" and DESIGNS[design].along == "u" and groups == 1


def _group_cuts(i: int, side: int, dial: bool, keys: int, size: CasingSize, end: bool) -> dict[str, Cutout]:
    """Control group ``i``'s holes on the front: at its ``side`` end of a long front, or (``end``) up the
    middle of an end-on toaster's short front."""
    if end:
        at = {"lever": END_LEVER_AT, "dial": END_DIAL_AT, "keys": [(END_KEYS_U, v) for v in KEYS_V]}
    else:
        at = {"lever": (side * LEVER_AT[0], LEVER_AT[1]), "dial": (side * DIAL_AT[0], DIAL_AT[1]),
              "keys": [(side * DIAL_AT[0], v) for v in KEYS_V]}
    cuts = {f"lever_{i}": LEVER.cutout("front", size.on("front", *at["lever"]))}
    if dial:
        cuts[f"dial_{i}"] = DIAL.cutout("front", size.on("front", *at["dial"]))
    for k in range(keys):
        cuts[f"button_{i}_{k}"] = BUTTON.cutout("front", size.on("front", *at["keys"][k]))
    return cuts


def cutouts(design: str, size: CasingSize, slot_width: float, groups: list[tuple[bool, int]],
            face: str = "front") -> dict[str, Cutout]:
    """Every hole of the casing: the bread slots on the top, the crumb tray's opening at the foot of the front
    and, per control group ``(has_dial, buttons)``, its lever slot, dial hole and key holes (``face`` "end": an
    end-on toaster, :func:`end_on`, its casing from :func:`casing_size` with ``end``)."""
    d, tray = DESIGNS[design], crumb_tray(size)
    end = end_on(design, face, len(groups))
    cuts = {"tray_opening": size.floor_opening("front", tray.width, tray.height + tray.lip, TRAY_CLEARANCE)}
    if d.along == "u" and not end:
        cuts.update(size.slots("top", d.slot_length, slot_width, SLOT_GAP, d.slots))
    else:
        pitch = slot_width + SLOT_GAP
        cuts.update({f"slot_{k}": Cutout.around("top", ((k - (d.slots - 1) / 2) * pitch, 0.0),
                                                (slot_width, d.slot_length)) for k in range(d.slots)})
    for i, (side, (dial, keys)) in enumerate(zip(group_sides(len(groups)), groups, strict=True)):
        cuts.update(_group_cuts(i, side, dial, keys, size, end))
    return cuts


ELEMENT_FLOOR = 0.03  # m, the heating elements' frames stop this far over the floor, clear of the crumb tray
REFLECTOR_GAP = 0.008  # m, the inner chassis (a steel reflector box) stands this far outside the outer slots
# The elements' guards (0.5 mm steel frames wound with nichrome on mica, one each side of a slot) and the steel
# chassis they hang in make most of a toaster's weight: a plastic-bodied 2-slice toaster still weighs ~1 kg
# (its plastic shell is a cool-touch skin over that chassis).


def slot_walls(size: CasingSize, cuts: dict[str, Cutout], material: str) -> list:
    """The heating-element guards lining each bread slot of ``cuts`` (one sheet along each long edge, from
    under the top plate down to :data:`ELEMENT_FLOOR`) inside the chassis's reflector box (:data:`REFLECTOR_GAP`
    round the slots): what one sees down a slot, and the chassis's mass."""
    z0, z1, t, walls = ELEMENT_FLOOR, size.height - size.wall, size.wall, []
    slots = [c for name, c in sorted(cuts.items()) if name.startswith("slot_")]
    # top face: v is world x, u is world y
    x0, y0 = (min(c.lo[k] for c in slots) - REFLECTOR_GAP for k in (1, 0))
    x1, y1 = (max(c.hi[k] for c in slots) + REFLECTOR_GAP for k in (1, 0))
    walls = [g.box_between((x0 - t, y0 - t, z0), (x0, y1 + t, z1), material),
             g.box_between((x1, y0 - t, z0), (x1 + t, y1 + t, z1), material),
             g.box_between((x0, y0 - t, z0), (x1, y0, z1), material),
             g.box_between((x0, y1, z0), (x1, y1 + t, z1), material)]
    elements = []
    for c in slots:
        (v0, u0), (v1, u1) = (c.lo[1], c.lo[0]), (c.hi[1], c.hi[0])
        if u1 - u0 > v1 - v0:  # runs across the width: its long edges are at x = v0 and v1
            walls += [g.box_between((v0 - t, u0, z0), (v0, u1, z1), material),
                      g.box_between((v1, u0, z0), (v1 + t, u1, z1), material)]
            edges = [((v0, u0), (v0, u1), (1.0, 0.0)), ((v1, u0), (v1, u1), (-1.0, 0.0))]
        else:
            walls += [g.box_between((v0, u0 - t, z0), (v1, u0, z1), material),
                      g.box_between((v0, u1, z0), (v1, u1 + t, z1), material)]
            edges = [((v0, u0), (v1, u0), (0.0, 1.0)), ((v0, u1), (v1, u1), (0.0, -1.0))]
        for a, b, inward in edges:
            elements += element(np.array(a), np.array(b), np.array(inward), z0, z1)
    return [w.replace(sheet=size.sheet) for w in walls] + elements


def carriage_guides(size: CasingSize, cuts: dict[str, Cutout], material: str) -> list[g.Piece]:
    """Behind each lever slot of ``cuts`` (on the front face), the dark carriage guide the lever's stem rides
    in: seen through the slot, it makes the slot read as a slot with the lever in it, not a pale gap
    (drawn, no collision; behind the stem's end, so the lever never meets it)."""
    x, m, hz, out = size.depth / 2 - A.BEHIND - 0.003, 0.006, size.height / 2, []
    for name, c in sorted(cuts.items()):
        if name.startswith("lever_"):  # front face: u = -y, v = z - height / 2
            (u0, v0), (u1, v1) = c.lo, c.hi
            out.append(g.box_between((x - 0.001, -u1 - m, v0 + hz - m), (x, -u0 + m, v1 + hz + m), material)
                       .replace(convex=()))
    return out


# A toaster's heating element (replacement elements and teardown photos: Dualit, Sunbeam, Breville): a mica
# card ~1 mm thick lining each long side of a slot, wound with flat nichrome ribbon in a zig-zag at a ~12 mm
# pitch, behind a guard of vertical steel wires ~1.5 mm thick, ~25 mm apart and ~5 mm off the card, that keeps
# the bread off the element. ``ELEMENT``: card thickness and standoff from the slot wall, ribbon half-thickness,
# zig-zag pitch, guard wire radius, its standoff from the card and its spacing (m).
ELEMENT = dict(card=0.001, off=0.0005, ribbon=0.0006, pitch=0.012, guard=0.0008, guard_off=0.005,
               guard_pitch=0.025)


def element(a: np.ndarray, b: np.ndarray, inward: np.ndarray, z0: float, z1: float) -> list[g.Piece]:
    """The element lining one long side of a slot, from ``a`` to ``b`` (x, y) along the slot wall, facing the
    slot along ``inward`` (x, y), between heights ``z0`` and ``z1``: the mica card, its nichrome zig-zag and the
    guard wires in front of it (drawn, no collision: the chassis walls carry the slot's collision)."""
    e = ELEMENT
    along = (b - a) / np.linalg.norm(b - a)
    length = float(np.linalg.norm(b - a))
    lo, hi = z0 + 0.006, z1 - 0.01

    def at(s: float, d: float, z: float) -> tuple[float, float, float]:
        p = a + s * along + d * inward
        return float(p[0]), float(p[1]), z

    c0, c1 = np.array(at(0.004, e["off"], lo)), np.array(at(length - 0.004, e["off"] + e["card"], hi))
    card = g.box_between(np.minimum(c0, c1), np.maximum(c0, c1), "mica")
    d = e["off"] + e["card"] + e["ribbon"]
    n = max(2, int((length - 0.012) / (e["pitch"] / 2)))
    zig = [at(0.006 + k * (length - 0.012) / n, d, lo + 0.004 if k % 2 else hi - 0.004) for k in range(n + 1)]
    pieces = [card, g.tube(zig, e["ribbon"], "element", 6)]
    wires = max(2, int(length / e["guard_pitch"]))
    for k in range(wires):
        s = (k + 0.5) * length / wires
        pieces.append(g.cylinder(at(s, e["off"] + e["card"] + e["guard_off"], z0 + 0.002),
                                 at(s, e["off"] + e["card"] + e["guard_off"], z1 - 0.002), e["guard"], "trim", 8))
    return [pc.replace(convex=()) for pc in pieces]
