"""Telephones: a flip (clamshell) phone, a slider phone and a corded desk phone with its handset and keypad.

Local frame: a mobile phone lies on its back on z = 0, its long axis along X with its top (the earpiece, the
flip's hinge) at +x, Y across; a desk phone stands on its feet with its front (the keypad's near edge) at +x.
Shells and keys are the remotes' (:mod:`.remotes`): moulded rounded slabs that collide as a top shell with a
hole per key, keys that press straight down against their springs (role ``button``), battery covers that slide
out of the underside.

A flip phone's lid lies closed over its base's keypad and turns about the hinge barrel at the top (+y axis: its
free end rises and swings over to +x); a slider phone's screen half slides up (+x) off the keypad of its lower
half; a desk phone's handset lies in its cradle on the left of the base and lifts off it (role ``lift_off``).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from . import remotes as R
from .remotes import Design, Key, Plan, Section, Spot

DESIGNS = {
    # Motorola RAZR V3 (53 x 98 x 13.9 mm closed, 95 g), Nokia 2720 fold (48 x 92 x 19 mm, 90 g), Samsung SGH-E300
    # (46 x 89 x 22 mm, 80 g): the base carries the keypad, the lid the screen; keys 0.5-1 mm proud with 0.3 mm of
    # dome travel, drawn 1.6 mm proud pressing 1.2 mm (the simulators' least travel is 1 mm: clearance.MIN_TRAVEL)
    "flip": Design((0.088, 0.099), (0.046, 0.053), (0.0068, 0.0095), 1.0, 0.16, (0.35, 0.35), (0.80, 0.68),
                   0.0016, 0.0012),
    # Nokia 6500 slide (96 x 46 x 16.4 mm, 125 g), Samsung SGH-E250 (95 x 46 x 16 mm, 87 g), Sony Ericsson W580
    # (99 x 47 x 16 mm, 99 g): two 7-8 mm halves, the keypad on the lower one
    "slider": Design((0.094, 0.100), (0.045, 0.049), (0.0072, 0.0085), 1.0, 0.14, (0.35, 0.35), (0.80, 0.68),
                     0.0016, 0.0012),
    # Nokia 3310 (113 x 48 x 22 mm, 133 g), Nokia 1100 (106 x 46 x 20 mm, 86 g), Nokia 6300 (106 x 44 x 12 mm, 91 g):
    # a candybar, its screen over the navigation keys and the keypad in one shell
    "bar": Design((0.104, 0.113), (0.044, 0.048), (0.012, 0.020), 1.0, 0.20, (0.40, 0.40), (0.80, 0.68),
                  0.0016, 0.0012),
    # Panasonic KX-TS500 (corded, 205 x 165 x 85 mm with its handset, 0.6 kg), Cisco IP Phone 7911 (210 x 180 mm),
    # Avaya 1608: a 30-45 mm deck, the handset on its left; keys 2-3 mm proud, 2 mm travel (drawn 1.2 mm)
    "desk": Design((0.190, 0.215), (0.180, 0.215), (0.032, 0.045), 1.0, 0.10, (0.35, 0.20), (0.40, 0.30),
                   0.0022, 0.0012),
}
"""Designs -> sizes (maker spec sheets and retail listings named beside each)."""

LID = {"flip": 0.85, "slider": 1.0}  # the upper half's thickness as a share of the lower's
HALF_GAP = 0.0025  # m between a lower half's key tops and the upper half closed over them (at 1.5 mm a
# closing flip lid met them in SAPIEN's reach check)
FLIP_OPENS = math.radians(150)  # a clamshell opens to 150-170 degrees (RAZR V3: 165)
TAIL = 0.005  # m of a slider phone's lower half behind its keypad


def _size(d: Design, size: float) -> tuple[float, float, float]:
    return (d.length[0] + size * (d.length[1] - d.length[0]), d.width[0] + size * (d.width[1] - d.width[0]),
            d.thick[0] + (1 - size) * (d.thick[1] - d.thick[0]))


def _plan(design: str, size: float, sections: list[Section], back: float = 0.0, front: float | None = None) -> Plan:
    """A half whose sections run front to back from its top, the last one ending ``back`` from its back end (or
    the first starting ``front`` from its front end)."""
    d = DESIGNS[design]
    length, width, thick = _size(d, size)
    x = -length / 2 + back + sum(s.height + R.SECTION_GAP for s in sections) - R.SECTION_GAP
    if front is not None:
        x = length / 2 - front
    tops = []
    for s in sections:
        tops.append(x)
        x -= s.height + R.SECTION_GAP
    return Plan(design, length, width, thick, tuple(sections), tuple(tops), d)


# -- keypads ----------------------------------------------------------------------------------------------
def numpad(width: float, n: int, proud: float, travel: float, span: float = 0.64, shift: float = 0.0,
           dense: bool = False) -> Section:
    """1-9, then *, 0, # (12 keys) in four rows of three; ``shift`` moves the pad across (a desk phone's);
    ``dense``: a candybar's short keys at an 8 mm pitch (Nokia 3310, 1100)."""
    mobile = 0.0054 if dense else 0.0068
    key = Key((mobile if width < 0.1 else 0.011, 0.23 * span * width), "rect", proud, travel)
    ys = [y + shift for y in R._cols(3, span * width)]
    pitch = key.size[0] + ((0.0025 if dense else 0.0032) if width < 0.1 else 0.006)
    spots = [Spot(-0.004 - pitch * (k // 3), ys[k % 3], key) for k in range(n)]
    return Section(pitch * ((n + 2) // 3) + 0.002, tuple(spots))


def navigation(width: float, n: int, proud: float, travel: float, pad: float = 0.19) -> Section:
    """A mobile phone's navigation keys: a round d-pad (OK and four arrows; ``pad``: its radius over the width)
    between the two soft keys, the green call and red end keys below them (5 + 2 + 2), and 0-2 more (clear,
    menu) beside the end keys."""
    rd = pad * width
    ok = Key((0.7 * rd, 0.7 * rd), "round", proud, travel)
    arrow = Key((0.28 * rd, 0.62 * rd), "pill", proud, travel)
    cx, reach = -rd - 0.001, 0.62 * rd
    spots = [Spot(cx, 0.0, ok)] + [Spot(cx + reach * math.cos(a), reach * math.sin(a), arrow, "key", a)
                                   for a in (0.0, math.pi / 2, math.pi, 3 * math.pi / 2)]
    side = Key((0.0045, 0.16 * width), "pill", proud, travel)
    for s in (1, -1):  # soft keys level with the d-pad's top, call and end keys level with its bottom
        spots.append(Spot(cx + 0.5 * rd, s * 0.33 * width, side))
        spots.append(Spot(cx - 0.5 * rd, s * 0.33 * width, side, "call" if s > 0 else "power"))
    small = Key((0.004, 0.08 * width), "pill", proud, travel)
    spots += [Spot(cx - rd - 0.004, y, small) for y in R._cols(n - 9, 0.22 * (n - 10) * width)]
    disc = g.disc((cx, 0.0, 0.0002), rd, 0.0004, "trim", None).replace(convex=())  # the d-pad's ring, printed
    return Section(2 * rd + 0.002 + (0.007 if n > 9 else 0.0), tuple(spots), (disc,))


def desk_pad(width: float, pad: int, functions: int, proud: float, travel: float) -> Section:
    """A desk phone's keypad: the numeric pad (12 keys) with a column pair of function keys to its right
    (memory, hold, redial, speaker, volume ...: 3-10, two to a row); the pad's keys first."""
    keys = numpad(width, pad, proud, travel, span=0.34, shift=0.02 * width)
    key = Key((0.008, 0.07 * width), "pill", proud, travel)
    cols = (0.30 * width, 0.40 * width)
    spots = [Spot(-0.005 - 0.012 * (k // 2), cols[k % 2], key, "key") for k in range(functions)]
    return Section(max(keys.height, 0.012 * ((functions + 1) // 2) + 0.002), keys.spots + tuple(spots))


# -- a flip phone ------------------------------------------------------------------------------------------
def flip_plan(size: float, nav: int, keys: int) -> Plan:
    d = DESIGNS["flip"]
    width = _size(d, size)[1]
    secs = [navigation(width, nav, d.proud, d.travel), numpad(width, keys, d.proud, d.travel)]
    return _plan("flip", size, secs, 0.006)


def _hinge_axis(p: Plan) -> tuple[float, float, float]:
    """The flip's hinge: its x, its height and the barrel's radius (half the lid's thickness)."""
    t = LID["flip"] * p.thick
    return p.length / 2 - t / 2, p.thick + p.d.proud + HALF_GAP + t / 2, t / 2


def flip_base_hinge(p: Plan, material: str) -> list[g.Piece]:
    """The base's two outer hinge knuckles and the cheeks that carry them, at the sides of the top end."""
    x, z, r = _hinge_axis(p)
    out = []
    for s in (1, -1):
        y0, y1 = sorted((s * 0.5 * p.width * 0.62, s * (0.5 * p.width - 0.003)))
        out += [g.cylinder((x, y0, z), (x, y1, z), r, material, None),
                g.box_between((x - r, y0, p.thick - 0.001), (x + r, y1, z), material)]
    return out


def flip_lid(p: Plan, body: str, screen: str, lens: str) -> Assembly:
    """The lid closed over the base: a slab with the main screen on its inner face and a small outer display and
    camera on its back, hung on the centre knuckle of the hinge; anchor ``hinge`` (z along +y)."""
    x, z, r = _hinge_axis(p)
    t = 2 * r
    lp = Plan("flip", x - r - 0.0015 + p.length / 2, p.width, t, (), (), p.d)
    v, f = R.shell(lp)
    shift = np.array((-p.length / 2 + lp.length / 2, 0.0, z - r))
    slab = g.Piece(v + shift, f, body, [v + shift], "lid")
    knuckle = g.cylinder((x, -0.3 * p.width, z), (x, 0.3 * p.width, z), r, body, None)
    x0, x1 = -p.length / 2 + 0.006, x - r - 0.006
    inner = g.box_between((x0, -0.4 * p.width, z - r - 0.0001), (x1, 0.4 * p.width, z - r + 0.0004),
                          screen).replace(convex=())  # flush with the lid's inner face: the lid's hull collides
    outer = g.box_between((x1 - 0.42 * p.width, -0.3 * p.width, z + r - 0.0004), (x1 - 0.06 * p.width,
                                                                                  0.3 * p.width, z + r + 0.0004),
                          screen)
    cam = g.cylinder((x1 - 0.02 * p.width, 0.0, z + r - 0.0004), (x1 - 0.02 * p.width, 0.0, z + r + 0.0006),
                     0.0035, lens, None)
    # a thumb lifts its free end (pinched across the lid's end, from the bottom end of the phone)
    grip = Grasp.make((-p.length / 2, 0, z), (1, 0, 0), (0, 0, 1), t + 0.004, 0.004)
    return Assembly.single("lid", [slab.with_grasps(grip), knuckle, inner, outer, cam],
                           {"hinge": Frame.at((x, 0, z), z=(0, 1, 0), x=(1, 0, 0))})


# -- a bar phone ------------------------------------------------------------------------------------------
def bar_plan(size: float, nav: int, keys: int) -> Plan:
    """A candybar's shell: the navigation keys and the keypad run down from under its screen to 6 mm from its
    bottom end, the screen over the top 40 % (Nokia 3310: a 30 mm screen over 60 mm of keys)."""
    d = DESIGNS["bar"]
    width = _size(d, size)[1]
    secs = [navigation(width, nav, d.proud, d.travel, pad=0.16), numpad(width, keys, d.proud, d.travel, dense=True)]
    return _plan("bar", size, secs, 0.006)


def bar_face(p: Plan, screen: str, bezel: str) -> list[g.Piece]:
    """A candybar's face above its keys: the screen in a dark window and the earpiece slot over it (drawn on
    the shell, which collides)."""
    x0, x1 = p.tops[0] + 0.003, p.length / 2 - 0.011
    hw = 0.38 * p.width
    frame = g.box_between((x0 - 0.002, -hw - 0.002, p.thick - 0.0008), (x1 + 0.002, hw + 0.002, p.thick + 0.0003),
                          bezel, bevel=0.0004).replace(convex=())
    glass = g.box_between((x0, -hw, p.thick), (x1, hw, p.thick + 0.0005), screen, name="screen").replace(convex=())
    slot = g.box_between((x1 + 0.003, -0.08 * p.width, p.thick - 0.0005), (x1 + 0.0045, 0.08 * p.width,
                                                                            p.thick + 0.0002), bezel,
                         bevel=0.0005).replace(convex=())
    return [frame, glass, slot]


# -- a slider phone ----------------------------------------------------------------------------------------
def slider_base_plan(size: float, keys: int) -> Plan:
    d = DESIGNS["slider"]
    width = _size(d, size)[1]
    return _plan("slider", size, [numpad(width, keys, d.proud, d.travel)], TAIL)


def slider_travel(base: Plan) -> float:
    """How far the screen half slides up: the keypad and the tail behind it, and 2 mm."""
    return base.sections[0].height + TAIL + 0.002


def slider_plan(base: Plan, nav: int) -> Plan:
    """The screen half: the base's size, its navigation keys under the screen (from the bottom end)."""
    d = base.d
    sec = navigation(base.width, nav, d.proud, d.travel)
    tops = (-base.length / 2 + 0.004 + sec.height,)
    return Plan("slider", base.length, base.width, LID["slider"] * base.thick, (sec,), tops, d)


def slider_lift(base: Plan) -> float:
    """The screen half's underside: above the keypad's key tops."""
    return base.thick + base.d.proud + HALF_GAP


def slider_half(up: Plan, lift: float, body: str, screen: str) -> Assembly:
    """The screen half at ``lift``: its slab (a top shell with holes for its keys) and screen; anchors
    ``slide`` (z along +x) and one ``key_i`` per navigation key."""
    shift = (0.0, 0.0, lift)
    x1 = up.length / 2 - 0.012
    x0 = up.tops[0] + 0.003
    glass = g.box_between((x0, -0.42 * up.width, up.thick - 0.0002), (x1, 0.42 * up.width, up.thick + 0.0005), screen)
    # fingers push it up by its bottom end
    grip = Grasp.make((-up.length / 2, 0, up.thick / 2), (1, 0, 0), (0, 0, 1), up.thick + 0.004, 0.004)
    pieces = [R.body(up, body, door=False).with_grasps(grip), glass, *R.section_trim(up)]
    anchors = {f"key_{k}": up.key_frame(0, s) for k, s in enumerate(up.sections[0].spots)}
    anchors["slide"] = Frame.at((0, 0, 0), z=(1, 0, 0))
    return Assembly.single("slider", [p.translated(shift) for p in pieces], {k: f.shifted(shift)
                                                                            for k, f in anchors.items()})


# -- a desk phone --------------------------------------------------------------------------------------------
CRADLE = 0.30  # share of the width the handset's cradle takes on the left (-y, seen from the front)
HANDSET = {"cup": 0.050, "grip": (0.030, 0.024), "depth": 0.030}
"""A corded handset (Panasonic KX-TS500, Cisco 7911): 180-210 mm long (0.9 of its deck), 50 mm ear and mouth
cups, a 30 x 24 mm grip, 30 mm deep, 140-180 g."""
SADDLE = 0.012  # m the cradle's saddles stand above the deck
POCKET = dict(rim=0.008, wall=0.004, clear=0.002, plunger=(0.012, 0.016), under=0.003)
"""The cradle's two pockets (Panasonic KX-TS500, Cisco 7911 bases): a rim 8 mm above each saddle round the ear
and mouth cups on three sides (open towards the middle, where the grip passes), 4 mm walls with 2 mm of play
round the cups, which guide the handset over the first 8 mm of its lift; the hook switch's plunger
(12 x 16 mm) stands between them 3 mm under the grip (m)."""


def desk_plan(size: float, pad: int, functions: int) -> Plan:
    d = DESIGNS["desk"]
    _, width, _ = _size(d, size)
    return _plan("desk", size, [desk_pad(width, pad, functions, d.proud, d.travel)], front=0.02)


def desk_display(p: Plan, screen: str, bezel: str) -> list[g.Piece]:
    """A two-line LCD in a bezel at the back of the deck, right of the cradle."""
    x1 = -p.length / 2 + 0.012 + 0.03
    y0, y1 = 0.06 * p.width, 0.46 * p.width
    frame = g.box_between((x1 - 0.032, y0 - 0.003, p.thick - 0.001), (x1 + 0.003, y1 + 0.003, p.thick + 0.0015),
                          bezel, bevel=0.0006)
    glass = g.box_between((x1 - 0.029, y0, p.thick + 0.001), (x1, y1, p.thick + 0.0018), screen)
    return [frame, glass]


def desk_cradle(p: Plan, material: str) -> list[g.Piece]:
    """The cradle on the left of the deck: two saddles the handset's cups rest on (its ends), each in a pocket
    walled on three sides (:data:`POCKET`), and the hook switch's plunger between them under the grip."""
    y, half, k = CRADLE * p.width / 2 - 0.5 * p.width, handset_half(p), POCKET
    z0 = p.thick + SADDLE
    a, b = HANDSET["cup"] / 2 + k["clear"], 0.45 * HANDSET["cup"] + k["clear"]  # the pocket's inner half sizes
    t, top = k["wall"], z0 + k["rim"]
    pieces = []
    for sx in (1, -1):
        xc = sx * half
        pieces.append(g.box_between((xc - a, y - b, p.thick - 0.002), (xc + a, y + b, z0), material, bevel=0.003))
        end = (xc + sx * a, xc + sx * (a + t))
        pieces.append(g.box_between((min(end), y - b - t, p.thick - 0.002), (max(end), y + b + t, top), material,
                                    bevel=0.0015))
        for side in (-1, 1):
            ys = (y + side * b, y + side * (b + t))
            pieces.append(g.box_between((xc - a, min(ys), p.thick - 0.002), (xc + a, max(ys), top), material,
                                        bevel=0.0015))
    grip_bottom = z0 + HANDSET["depth"] - HANDSET["grip"][1]
    w, d = k["plunger"]
    pieces.append(g.box_between((-w / 2, y - d / 2, p.thick - 0.002), (w / 2, y + d / 2, grip_bottom - k["under"]),
                                "trim", bevel=0.002))
    return pieces


def _cup(x: float, y: float, z0: float, size: tuple[float, float], height: float, material: str) -> g.Piece:
    """A handset's ear or mouth cup: an oval puck with a rounded rim."""
    rim = 0.3 * height
    ring = R._ellipse(size[0] / 2, size[1] / 2, 24)
    pts = [R._lift(ring * (1 - rim / size[1] * (1 - math.sin(a))) + (x, y), z0 + height - rim * (1 - math.cos(a)))
           for a in np.radians(np.linspace(0.0, 90.0, 4))]
    v, f = g.hull_arrays(np.vstack([R._lift(ring * 0.92 + (x, y), z0), *pts]))
    return g.Piece(v, f, material, [v], "cup")


def handset(p: Plan, material: str) -> Assembly:
    """The handset lying in its cradle along x, the earpiece at the back: two cups on the saddles and the grip
    between them; anchor ``lift`` (z up)."""
    y, z0 = CRADLE * p.width / 2 - 0.5 * p.width, p.thick + SADDLE
    h = HANDSET
    half, dz = handset_half(p), h["depth"]
    cups = [_cup(sx * half, y, z0, (h["cup"], 0.9 * h["cup"]), dz, material) for sx in (1, -1)]
    gw, gh = h["grip"]
    # massed solid: a handset carries a steel weight and its capsules' magnets (140-180 g in all), not a bare shell
    grip = g.box_between((-half, y - gw / 2, z0 + dz - gh), (half, y + gw / 2, z0 + dz), material,
                         bevel=0.008).replace(wall=0.0)
    # picked up by its grip, fingers round it from above
    hold = Grasp.make((0, y, z0 + dz), (0, 0, -1), (0, 1, 0), gw + 0.01, 0.012)
    return Assembly.single("handset", [*cups, grip.with_grasps(hold)], {"lift": Frame.at((0, y, z0), z=(0, 0, 1))})


def handset_half(p: Plan) -> float:
    """From the handset's middle to the centre of a cup: it spans 0.9 of the deck's length."""
    return 0.45 * p.length - HANDSET["cup"] / 2
