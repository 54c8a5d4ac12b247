"""Appliance parts: sheet casings with a cavity and a face frame, turntables, control panels with
push buttons and dials, glazed doors.

Local frames are world-aligned: fronts face +x, z is up. Sizes of real counter-top microwaves
(0.44-0.62 m wide, 0.32-0.46 m deep with the door, 0.25-0.36 m tall; 0.3-0.6 mm steel casings,
1.5-2.5 mm button travel; manufacturers' spec sheets: Panasonic, Samsung, Whirlpool).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame, polar
from infmob_usd.grammar import Layout
from infmob_usd.grasps import Grasp
from infmob_usd.materials import FAMILIES

STEEL = 7850.0  # kg/m^3: what a painted casing, door or drawer of sheet really is (see Category.substrates)
LINER = 0.002  # cavity liner wall
BEZEL = 0.006  # front bezel thickness
SKIN = 0.003  # outer skin of a door or fascia; a dark inner frame behind it
INNER_KG_M2 = 7.0  # kg/m2 of the inner frame behind a door's or fascia's skin: a 0.6 mm steel inner plate
# (4.7 kg/m2) under a 2 mm moulded choke cover (2.2 kg/m2); massed solid, an over-the-range door's 25 mm rubber
# frame weighed 3.9 kg and the door 7.0 kg against the 1.5-4 kg of replacement door assemblies
# (validate/mass_ranges.csv microwave,door)
CLEAR = 0.0025  # clearance of buttons and dial stems in their panel holes
BEHIND = 0.008  # buttons and stems reach this far behind the fascia's face


def size(p, design: str, rules) -> tuple[float, float, float]:
    """(width, depth, height) of an appliance of ``design``: the parameters' ``width``, ``depth`` and
    ``height``, reshaped by the family's rule for that design where it has one (``rules``: design ->
    ``f(W, D, H)``, e.g. :data:`~.microwaves.SIZES`: an over-the-range microwave is 30 in wide)."""
    W, D, H = p["width"], p["depth"], p["height"]
    rule = rules.get(design)
    return rule(W, D, H) if rule else (W, D, H)


def drop_hinge(box) -> Frame:
    """A drop-down door's hinge (an oven's, a dishwasher's): on the front face of its ``box`` (x0, x1, y0,
    y1, z0, z1) at the bottom edge, about +Y: the top falls forward (+X)."""
    _, x1, _, _, z0, _ = box
    return Frame.at((x1, 0.0, z0), z=(0, 1, 0))


def rack_slide(xs, z: float, fraction: float, y: float = 0.0) -> tuple[Frame, float]:
    """A rack's slide out of a cavity along +X from its front (``xs``: back, front) at height ``z`` (and
    ``y``), and its travel: ``fraction`` of its depth."""
    return Frame.at((xs[1], y, z), z=(1, 0, 0)), fraction * (xs[1] - xs[0])


def side_hinge(box, left: bool) -> Frame:
    """A side-hinged door's hinge: on the front face of its ``box`` (x0, x1, y0, y1, z0, z1) at the left
    (or right) bottom corner, about -Z (+Z): the free edge swings out (+X)."""
    _, x1, y0, y1, z0, _ = box
    return Frame.at((x1, y0 if left else y1, z0), z=(0, 0, -1 if left else 1))


QUARTER_TURN = math.pi / 2  # a fold-down tine row or cup shelf: upright to flat


def fold_line(y: float, z: float, sign: int = 1) -> Frame:
    """The hinge line of a fold-down row in a rack: along ``sign`` X through ``(y, z)``."""
    return Frame.at((0.0, y, z), z=(sign, 0, 0))


def inner_sheet(family: str) -> float:
    """The sheet (m) an inner frame of material ``family`` is massed with to weigh :data:`INNER_KG_M2`."""
    return INNER_KG_M2 / FAMILIES[family].density


def machine_can(x: float, z0: float, h: float, r: float, slot: str, kg: float, name: str) -> g.Piece:
    """A hidden machine (compressor, pump) as an upright steel can at ``(x, 0)`` from ``z0`` up ``h``, no
    collision, massed as a steel shell (7850 kg/m^3) whose wall makes it weigh ``kg``."""
    can = g.cylinder([x, 0.0, z0], [x, 0.0, z0 + h], r, slot, 24)
    area = 2 * math.pi * r * (r + h)
    return can.replace(convex=(), wall=kg / (7850.0 * area), name=name)


def casing(outer, cavity, wall: float, feet_r: float) -> list[g.Piece]:
    """A sheet casing (bottom, top, sides, back), a front bezel with the cavity opening, a cavity
    liner of five thin walls, four feet and louvres on the right side.

    ``outer``: (x back, x front, y left, y right, z bottom, z top); ``cavity`` likewise.
    """
    xb, xf, y0, y1, zc0, zc1 = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    t, L, xs = wall, LINER, xf - BEZEL
    pieces = [
        g.box_between([xb, y0, zc0], [xs, y1, zc0 + t], "body"),
        g.box_between([xb, y0, zc1 - t], [xs, y1, zc1], "body"),
        g.box_between([xb, y0, zc0 + t], [xs, y0 + t, zc1 - t], "body"),
        g.box_between([xb, y1 - t, zc0 + t], [xs, y1, zc1 - t], "body"),
        g.box_between([xb, y0 + t, zc0 + t], [xb + t, y1 - t, zc1 - t], "body"),
        g.panel([xs, y0, zc0], [xf, y1, zc1], "body", "x", holes=[(cy0, cz0, cy1, cz1)]),
        g.box_between([cx0 - L, cy0 - L, cz0 - L], [cx1, cy1 + L, cz0], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz1], [cx1, cy1 + L, cz1 + L], "interior"),
        g.box_between([cx0 - L, cy0 - L, cz0], [cx1, cy0, cz1], "interior"),
        g.box_between([cx0 - L, cy1, cz0], [cx1, cy1 + L, cz1], "interior"),
        g.box_between([cx0 - L, cy0, cz0], [cx0, cy1, cz1], "interior"),
    ]
    for x in (xb + 0.04, xs - 0.04):
        for y in (y0 + 0.04, y1 - 0.04):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zc0], feet_r, "feet", 16))
    n, zt = int((zc1 - zc0) * 0.4 / 0.01), zc1 - t - 0.02  # louvres towards the back and the top
    for k in range(n):
        z = zt - k * 0.01
        pieces.append(g.box_between([xb + 0.04, y1, z - 0.0015], [xb + 0.04 + 0.3 * (xf - xb), y1 + 0.001, z + 0.0015],
                                    "display"))
    return pieces


def turntable(center, floor: float, radius: float) -> list[g.Piece]:
    """A glass tray with a rim on a roller ring (three wheels, three arms, a hub), all within
    ``radius`` of the axis and at least 3 mm above the ``floor`` and the spindle (8 mm)."""
    cx, cy = center
    z_wheel = floor + 0.003 + 0.006  # wheel centres; wheel radius 6 mm
    z_tray = z_wheel + 0.006
    r_ring = 0.5 * radius
    pieces = [
        g.disc([cx, cy, z_tray + 0.003], radius - 0.004, 0.006, "plate", 48),
        g.shell([(radius - 0.002, z_tray), (radius, z_tray + 0.015)], 0.004, "plate", center=(cx, cy, 0.0),
                sections=48),
        g.shell([(r_ring + 0.004, z_wheel - 0.002), (r_ring + 0.004, z_wheel + 0.002)], 0.008, "roller",
                center=(cx, cy, 0.0), sections=32, convex_sectors=12),
        g.cylinder([cx, cy, z_tray - 0.004], [cx, cy, z_tray], 0.018, "roller", 24),  # hub
    ]
    for arm in polar(Frame.at((cx, cy, z_wheel)).turned("z", math.pi / 6), 3, 0.0):
        c, d = arm.origin, arm.x
        pieces.append(g.cylinder(c + d * (r_ring - 0.005), c + d * (r_ring + 0.005), 0.006, "roller", 16))
        pieces.append(g.cylinder(c + d * 0.012 + [0, 0, 0.0005], c + d * (r_ring - 0.003) + [0, 0, 0.0005], 0.0015,
                                 "roller", 8))
    return pieces


TRAY_TOP = 0.021  # the turntable tray's top face over the cavity floor (wheels 9 mm, tray 6 mm over them)
STAND_RACK_R = 0.0025  # wire radius of a microwave's low rack


def stand_rack(center, z0: float, half: float, height: float) -> list[g.Piece]:
    """A combination microwave's low wire rack: a square frame ``2 half`` wide ``height`` over ``z0`` with
    wires across it, on four legs that stand on ``z0`` at its corners."""
    cx, cy = center
    r, zc = STAND_RACK_R, z0 + height
    x0, x1, y0, y1 = cx - half + r, cx + half - r, cy - half + r, cy + half - r
    pieces = [g.cylinder([x, y, z0], [x, y, zc], r, "rack", 8) for x in (x0, x1) for y in (y0, y1)]
    pieces += [g.cylinder(a, b, r, "rack", 8) for a, b in (([x0, y0, zc], [x1, y0, zc]), ([x0, y1, zc], [x1, y1, zc]),
                                                            ([x0, y0, zc], [x0, y1, zc]), ([x1, y0, zc], [x1, y1, zc]))]
    n = max(3, int((y1 - y0) / 0.03))
    ys = [y0 + (y1 - y0) * k / n for k in range(1, n)]
    pieces += [g.cylinder([x0 + r, y, zc], [x1 - r, y, zc], 0.7 * r, "rack", 6) for y in ys]
    return pieces


def spindle(center, floor: float) -> g.Piece:
    """The turntable's drive spindle in the middle of the cavity floor (8 mm tall)."""
    return g.cylinder([*center, floor], [*center, floor + 0.008], 0.006, "roller", 16)


def glazed_door(x_front: float, thickness: float, ys, zs, hole, skin: str, inner: str, frame_sheet: float
                ) -> list[g.Piece]:
    """A door of a thin outer skin on a dark inner frame (massed as ``frame_sheet`` m of sheet, see
    :func:`inner_sheet`), both with a window ``hole`` (y0, z0, y1, z1), and the glass set in it."""
    x0 = x_front - thickness
    return [g.panel([x_front - SKIN, ys[0], zs[0]], [x_front, ys[1], zs[1]], skin, "x", holes=[hole]),
            g.panel([x0, ys[0], zs[0]], [x_front - SKIN, ys[1], zs[1]], inner, "x", holes=[hole]).replace(
                sheet=frame_sheet),
            g.box_between([x_front - 0.009, hole[0], hole[1]], [x_front - 0.004, hole[2], hole[3]], "glass")]


# -- control panels -------------------------------------------------------------------------------------
def push_button(x_face: float, y: float, z: float, half: tuple[float, float], shape: str, proud: float
                ) -> g.Piece:
    """A push button through a fascia hole: from ``BEHIND`` behind the face to ``proud`` in front.

    The buttons of a grid are one button moved to each place (:func:`_button`): a bevelled box's
    hull is worked out once, not per button."""
    return _button(tuple(half), shape, proud).translated((x_face, y, z))


@functools.lru_cache(maxsize=64)
def _button(half: tuple[float, float], shape: str, proud: float) -> g.Piece:
    """:func:`push_button` with its face centre at the origin (an immutable piece, shared)."""
    if shape == "rect":
        piece = g.box_between([-BEHIND, -half[0], -half[1]], [proud, half[0], half[1]], "button", bevel=0.3 * half[1])
    else:
        piece = g.cylinder([-BEHIND, 0.0, 0.0], [proud, 0.0, 0.0], half[0], "button", 24)
    return piece.with_grasps(button_grasp(half, shape, proud))


def button_grasp(half: tuple[float, float], shape: str, proud: float) -> Grasp:
    """A finger's press on a :func:`push_button`: the middle of its face, straight in (-x), closing across
    its narrow side."""
    u, v = half if shape == "rect" else (half[0], half[0])
    return Grasp.make((proud, 0, 0), (-1, 0, 0), (0, 1, 0) if u <= v else (0, 0, 1), 2 * min(u, v), proud / 2)


DIALS = {"ridge": 0.6, "round": 0.4}
"""Dial styles and their shares: a thin skirt with a grip bar, or a round cap on a skirt."""


def dial(x_face: float, y: float, z: float, r: float, stem: float, style: str) -> list[g.Piece]:
    """A dial 3 mm in front of the fascia face on a stem through a hole; a pointer mark in ``trim``."""
    x0 = x_face + 0.003
    pieces = [g.cylinder([x_face - BEHIND, y, z], [x0 + 0.001, y, z], stem, "knob", 16)]
    if style == "ridge":
        depth = max(0.014, 0.7 * r)
        grip = g.box_between([x0 + 0.0045, y - 0.18 * r, z - 0.85 * r], [x0 + depth, y + 0.18 * r, z + 0.85 * r],
                             "knob", bevel=0.002)  # turned by its grip bar, fingers across it
        pieces += [g.cylinder([x0, y, z], [x0 + 0.005, y, z], r, "knob", 32),
                   grip.with_grasps(Grasp.make([x0 + depth, y, z], (-1, 0, 0), (0, 1, 0), 0.36 * r,
                                               min(0.008, (depth - 0.0045) / 2))),
                   g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.45 * r], [x0 + depth + 0.001, y + 0.0015,
                                                                                   z + 0.8 * r], "trim")]
    else:
        depth = max(0.016, 0.8 * r)
        cap = g.cylinder([x0 + 0.0035, y, z], [x0 + depth, y, z], 0.8 * r, "knob", 32)  # turned across its cap
        pieces += [g.cylinder([x0, y, z], [x0 + 0.004, y, z], r, "knob", 32),
                   cap.with_grasps(Grasp.make([x0 + depth, y, z], (-1, 0, 0), (0, 1, 0), 1.6 * r,
                                              min(0.008, (depth - 0.0035) / 2))),
                   g.box_between([x0 + depth - 0.0005, y - 0.0015, z + 0.35 * r], [x0 + depth + 0.001, y + 0.0015,
                                                                                   z + 0.7 * r], "trim")]
    return pieces


@dataclass(frozen=True)
class Drawer:
    """A drawer that slides out along +X: ``part`` in its own frame (anchor ``front``: the bottom middle of
    its front face, x out of it; ``slide``: there, z along its track), ``at`` where ``front`` goes on the
    body, and the ``travel`` it slides out."""

    part: Assembly
    at: Frame
    travel: float

    def place(self, layout: Layout, name: str, parent: str = "body", requires_open: str | None = None) -> str:
        """Add it to ``layout`` as part ``name`` sliding out of ``parent`` (only with ``requires_open``
        open, if given); returns the part's name."""
        placed = layout.place(self.part.attached("front", to=self.at), name)
        layout.slide(parent, placed.root, placed.anchor("slide"), upper=self.travel, requires_open=requires_open)
        return placed.root


DRAWER_ANCHORS = {"front": Frame.at((0.0, 0.0, 0.0)), "slide": Frame.at((0.0, 0.0, 0.0), z=(1, 0, 0))}
"""A :class:`Drawer` part's anchors in its own frame."""


@dataclass(frozen=True)
class Control:
    """A moving control a panel layout made: its part ``name``, its ``pieces``, the frame it moves on
    (a button's press frame, z into the panel; a dial's axis) and a button's ``travel``; ``release``
    marks a door-release button (grown by its own grammar node)."""

    name: str
    pieces: tuple
    at: Frame
    travel: float = 0.0
    release: bool = False


@dataclass
class Panel:
    """A control panel laid out top-down: what it shows, its holes, and what moves in them."""

    holes: list = field(default_factory=list)  # (y0, z0, y1, z1)
    decor: list = field(default_factory=list)  # pieces fixed on the fascia
    buttons: list[Control] = field(default_factory=list)
    dials: list[Control] = field(default_factory=list)


def hole_around(y: float, z: float, half) -> tuple[float, float, float, float]:
    return (y - half[0] - CLEAR, z - half[1] - CLEAR, y + half[0] + CLEAR, z + half[1] + CLEAR)


# -- insulated cabinets (fridges) ------------------------------------------------------------------
FRIDGE_SHEET = 0.0008  # steel sheet of an insulated wall (its mass; the foam weighs little)
RACK_WIRE = 0.0025  # wire radius of a fridge rack
RACK_TRIM = 0.018  # depth of a rack's front trim


def insulated_cabinet(outer, cavity, kick_top: float) -> list[g.Piece]:
    """Insulated walls around a liner, a machine compartment with a kick grille, four levelling feet.

    ``outer``: (x back, x front, y left, y right, z feet top, z top); ``cavity``: the liner's inner faces.
    """
    xb0, xb1, y0, y1, zf, H = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L = LINER
    wy0, wy1, wz0, wz1, wx0 = cy0 - L, cy1 + L, cz0 - L, cz1 + L, cx0 - L  # wall inner faces

    def wall(lo, hi):
        return g.box_between(lo, hi, "body").replace(sheet=FRIDGE_SHEET)

    pieces = [
        wall([xb0, y0, zf], [xb1, wy0, H]), wall([xb0, wy1, zf], [xb1, y1, H]), wall([xb0, wy0, wz1], [xb1, wy1, H]),
        wall([xb0, wy0, kick_top], [xb1, wy1, wz0]), wall([xb0, wy0, wz0], [wx0, wy1, wz1]),
        wall([xb0, wy0, zf], [xb1 - 0.02, wy1, zf + 0.003]),  # base plate of the machine compartment
        wall([xb0, wy0, zf + 0.003], [xb0 + 0.004, wy1, kick_top]),  # rear cover of the compressor
        g.box_between([wx0, wy0, wz0], [cx1, wy1, cz0], "liner"),
        g.box_between([wx0, wy0, cz1], [cx1, wy1, wz1], "liner"),
        g.box_between([wx0, wy0, cz0], [cx1, cy0, cz1], "liner"),
        g.box_between([wx0, cy1, cz0], [cx1, wy1, cz1], "liner"),
        g.box_between([wx0, cy0, cz0], [cx0, cy1, cz1], "liner"),
        # gasket seat around the opening (a thin dark band on the front face)
        g.box_between([xb1 - 0.001, wy0 - 0.01, wz0 - 0.01], [xb1 + 0.001, wy0, wz1 + 0.01], "gasket"),
        g.box_between([xb1 - 0.001, wy1, wz0 - 0.01], [xb1 + 0.001, wy1 + 0.01, wz1 + 0.01], "gasket"),
    ]
    gx = xb1 - 0.012  # kick grille: a recessed slotted panel across the machine compartment
    pieces.append(g.box_between([gx - 0.004, wy0, zf + 0.003], [gx, wy1, kick_top], "grille"))
    n_slots = max(3, int((wy1 - wy0) / 0.02))
    for k in range(n_slots):
        ya = wy0 + 0.012 + k * (wy1 - wy0 - 0.024) / n_slots
        pieces.append(g.box_between([gx, ya, zf + 0.012], [gx + 0.002, ya + 0.006, kick_top - 0.01], "grille"))
    for x in (xb0 + 0.035, xb1 - 0.045):
        for y in (y0 + 0.035, y1 - 0.035):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zf], 0.014, "feet", 16))
    return pieces


def control_strip(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> list[g.Piece]:
    """A strip above a door, flush with its front, with a display and three touch keys printed on it."""
    W, h = y1 - y0, z1 - z0
    pieces = [g.box_between([x0, y0, z0], [x1, y1, z1], "frame"),
              g.box_between([x1, -0.12 * W, z0 + 0.25 * h], [x1 + 0.001, 0.12 * W, z1 - 0.25 * h], "display")]
    for k in range(3):
        yk = 0.17 * W + k * 0.045 * W
        pieces.append(g.box_between([x1, yk, z0 + 0.35 * h], [x1 + 0.0008, yk + 0.03 * W, z1 - 0.35 * h], "display"))
    return pieces


def control_strip_keys(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, n: int):
    """A strip above a door, flush with its front, with a display and ``n`` push keys in a row to its right
    (a cooler's electronic thermostat: power, light, up, down, zone ...). Returns the strip's pieces and
    one ``(piece, press frame, travel)`` per key; a key stands proud of the face and presses in along -X."""
    W, h = y1 - y0, z1 - z0
    zc = (z0 + z1) / 2
    ya, yb = 0.15 * W, 0.46 * W  # the keys' row
    pitch = (yb - ya) / n
    half = (min(0.011, 0.5 * pitch - CLEAR - 0.003), min(0.008, 0.3 * h))
    proud, travel = 0.003, 0.002
    keys, holes = [], []
    for k in range(n):
        y = ya + (k + 0.5) * pitch
        holes.append(hole_around(y, zc, half))
        piece = g.box_between([x1 - BEHIND, y - half[0], zc - half[1]], [x1 + proud, y + half[0], zc + half[1]],
                              "button", bevel=0.0015)
        keys.append((piece, Frame.at((x1 + proud, y, zc), z=(-1, 0, 0)), travel))
    pieces = [g.panel([x0, y0, z0], [x1, y1, z1], "frame", "x", holes=holes),
              g.box_between([x1, -0.12 * W, z0 + 0.25 * h], [x1 + 0.001, 0.12 * W, z1 - 0.25 * h], "display")]
    return pieces, keys


def glass_door(box, hole) -> list[g.Piece]:
    """A frame around a double glass pane and a gasket behind it (all collide)."""
    x0, x1, y0, y1, z0, z1 = box
    h0, v0, h1, v1 = hole
    ft = x1 - x0
    pieces = [g.panel([x0, y0, z0], [x1, y1, z1], "frame", "x", holes=[hole]).replace(sheet=FRIDGE_SHEET)]
    for xg in (x1 - 0.3 * ft, x0 + 0.2 * ft):  # two panes: the insulated glazing
        pieces.append(g.box_between([xg - 0.002, h0 - 0.004, v0 - 0.004], [xg + 0.002, h1 + 0.004, v1 + 0.004],
                                    "glass"))
    pieces.append(g.panel([x0 - 0.0015, y0 + 0.006, z0 + 0.006], [x0, y1 - 0.006, z1 - 0.006], "gasket", "x",
                          holes=[(h0 + 0.004, v0 + 0.004, h1 - 0.004, v1 - 0.004)]))
    return pieces


SHELF_FROST = 0.02
"""m, the printed border round a fridge's tempered glass shelf, inside its trims: Samsung, LG and Bosch shelves
carry a 15-25 mm grey ceramic-frit (or etched) band at the edges (product photos); it is what makes a clear pane
read as a pane and not as an empty frame."""


def glass_shelf(xs, ry: float, zb: float, hr: float) -> list[g.Piece]:
    """A glass shelf in a trim between ``xs`` in x and ``-ry..ry`` in y, from ``zb`` up: a 6 mm pane, clear in
    the middle and printed (slot ``frost``) in a :data:`SHELF_FROST` band round its edges."""
    rx0, rx1 = xs
    t, b, e = RACK_TRIM, SHELF_FROST, 0.01
    xa, xb, ya, yb, z1 = rx0 + b, rx1 - t - b, -ry + e + b, ry - e - b, zb + 0.006
    return [g.box_between([xa, ya, zb], [xb, yb, z1], "glass"),
            g.box_between([rx0, -ry, zb], [xa, ry, z1], "frost"),
            g.box_between([xb, -ry, zb], [rx1 - t, ry, z1], "frost"),
            g.box_between([xa, -ry, zb], [xb, ya, z1], "frost"),
            g.box_between([xa, yb, zb], [xb, ry, z1], "frost"),
            g.box_between([rx0, -ry, zb], [rx1 - t, -ry + 0.01, zb + 0.012], "trim"),
            g.box_between([rx0, ry - 0.01, zb], [rx1 - t, ry, zb + 0.012], "trim"),
            g.box_between([rx1 - t, -ry, zb], [rx1, ry, zb + min(0.022, hr)], "trim", bevel=0.002)]


def wire_rack(xs, ry: float, zb: float, hr: float, pitch: float) -> list[g.Piece]:
    """A wire rack with side runners, a back stop and a front trim; its wires wave into a shallow
    cradle for bottles, ``pitch`` apart."""
    rx0, rx1 = xs
    r, t = RACK_WIRE, RACK_TRIM
    zc = zb + r
    pieces = [
        g.box_between([rx0, -ry, zb], [rx1 - t, -ry + 0.008, zb + 0.01], "wire"),
        g.box_between([rx0, ry - 0.008, zb], [rx1 - t, ry, zb + 0.01], "wire"),
        g.cylinder([rx0 + r, -ry + 0.008, zc], [rx0 + r, ry - 0.008, zc], r, "wire", 8),
        g.cylinder([rx0 + r, -ry + 0.008, zb + hr], [rx0 + r, ry - 0.008, zb + hr], r, "wire", 8),
        g.box_between([rx1 - t, -ry, zb], [rx1, ry, zb + hr - 0.002], "trim", bevel=0.002),
    ]
    for y in (-ry + 0.004, ry - 0.004):  # back stop posts
        pieces.append(g.cylinder([rx0 + r, y, zb + 0.01], [rx0 + r, y, zb + hr], r, "wire", 8))
    n = max(3, int((2 * ry - 0.02) / pitch))
    for k in range(n):
        y = -ry + 0.01 + (k + 0.5) * (2 * ry - 0.02) / n
        lift = 0.006 * (1 - math.cos(2 * math.pi * (k + 0.5) / n * 2)) / 2  # waves across the rack
        pieces.append(g.cylinder([rx0 + 2 * r, y, zc + lift], [rx1 - t, y, zc + lift], r * 0.8, "wire", 8))
    return pieces


# -- dishwashers -----------------------------------------------------------------------------------------
DISHWASHER_SHEET = 0.0008
TUB_LINER = 0.0015
DISPENSER = 0.003  # a detergent dispenser stands this far proud of a door's inner skin
RACK_WHEEL = 0.011  # dish rack wheel radius


def tub_cabinet(outer, cavity, hinge_z: float, door_front: float) -> list[g.Piece]:
    """Insulated walls around a stainless liner (a real hollow), base, kick plinth under the door,
    levelling feet, filter, lower spray arm and a ceiling nozzle."""
    xb0, xb1, y0, y1, zf, H = outer
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L = TUB_LINER
    wy0, wy1, wz0, wz1, wx0 = cy0 - L, cy1 + L, cz0 - L, cz1 + L, cx0 - L

    def sheet(lo, hi, slot):
        return g.box_between(lo, hi, slot).replace(sheet=DISHWASHER_SHEET)

    pieces = [
        sheet([xb0, y0, zf], [xb1, wy0, H], "body"), sheet([xb0, wy1, zf], [xb1, y1, H], "body"),
        sheet([xb0, wy0, wz1], [xb1, wy1, H], "body"), sheet([xb0, wy0, hinge_z], [xb1, wy1, wz0], "body"),
        sheet([xb0, wy0, wz0], [wx0, wy1, wz1], "body"), sheet([xb0, wy0, zf], [xb1, wy1, zf + 0.004], "body"),
        sheet([xb0, wy0, zf + 0.004], [xb0 + 0.004, wy1, hinge_z], "body"),
        sheet([xb1 - 0.004, y0, zf + 0.004], [door_front - 0.012, y1, hinge_z - 0.004], "plinth"),
        sheet([wx0, wy0, wz0], [cx1, wy1, cz0], "tub"), sheet([wx0, wy0, cz1], [cx1, wy1, wz1], "tub"),
        sheet([wx0, wy0, cz0], [cx1, cy0, cz1], "tub"), sheet([wx0, cy1, cz0], [cx1, wy1, cz1], "tub"),
        sheet([wx0, cy0, cz0], [cx0, cy1, cz1], "tub"),
    ]
    xm = (cx0 + cx1) / 2
    arm = min(cx1 - cx0, cy1 - cy0) / 2 - 0.03
    pieces += [g.cylinder([cx0 + 0.08, 0.0, cz0], [cx0 + 0.08, 0.0, cz0 + 0.03], 0.035, "arm", 24),
               g.cylinder([xm, 0.0, cz0], [xm, 0.0, cz0 + 0.02], 0.022, "arm", 24),
               g.box_between([xm - 0.018, -arm, cz0 + 0.02], [xm + 0.018, arm, cz0 + 0.032], "arm", bevel=0.004),
               g.cylinder([xm, 0.0, cz1 - 0.025], [xm, 0.0, cz1], 0.016, "arm", 16)]
    for x in (xb0 + 0.04, xb1 - 0.05):
        for y in (y0 + 0.04, y1 - 0.04):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, zf], 0.015, "feet", 16))
    return pieces


def layered_door(box) -> list[g.Piece]:
    """A front skin, an inner core and a stainless inner skin, each colliding over the whole leaf,
    and a detergent dispenser moulded into the inner skin."""
    x0, x1, y0, y1, z0, z1 = box
    s = 0.0015
    yc, zc = 0.15 * (y1 - y0), z0 + 0.62 * (z1 - z0)
    return [g.box_between([x1 - s, y0, z0], [x1, y1, z1], "body").replace(sheet=DISHWASHER_SHEET),
            g.box_between([x0 + s, y0, z0], [x1 - s, y1, z1], "door_inner").replace(sheet=0.002),
            g.box_between([x0, y0 + 0.01, z0 + 0.01], [x0 + s, y1 - 0.01, z1 - 0.01], "tub")
            .replace(sheet=DISHWASHER_SHEET),
            g.box_between([x0 - DISPENSER, yc - 0.06, zc - 0.04], [x0, yc + 0.06, zc + 0.04], "door_inner")]


def _wire(a, b, r):
    return g.cylinder(a, b, r, "wire", 8)


def dish_rack(xs, cy1: float, za: float, top: float, pitch: float, kind: str, tines: bool = True) -> list[g.Piece]:
    """A wire basket on four wheels from ``za`` (the wheels' bottom) up to ``top``: a tall ``lower``
    rack with plate tines (``tines=False``: without its fixed tines, for fold-down rows), an ``upper``
    rack, or a shallow cutlery ``tray``. Every wire is its own
    convex piece; the wheels ride over rails beside the side liners (out to ``cy1 - 6 mm``)."""
    rx0, rx1 = xs
    ry = cy1 - 0.02  # basket half width
    r = 0.0025
    zc = za + RACK_WHEEL  # wheel axles; the bottom frame runs here
    pieces = [g.cylinder([x, s * ry, zc], [x, s * (cy1 - 0.006), zc], RACK_WHEEL, "wheel", 16)
              for x in (rx0 + 0.04, rx1 - 0.04) for s in (-1, 1)]
    height = max(top - zc, 0.02)
    wall_h = min(height, {"tray": 0.05, "lower": 0.55 * height}.get(kind, 0.7 * height))
    zt = zc + wall_h - r
    for z in (zc, zt):  # bottom frame and top rim
        pieces += [_wire([rx0, -ry, z], [rx1, -ry, z], r), _wire([rx0, ry, z], [rx1, ry, z], r),
                   _wire([rx0, -ry, z], [rx0, ry, z], r), _wire([rx1, -ry, z], [rx1, ry, z], r)]
    nx = max(3, int(2 * ry / pitch))  # bottom grid: wires along x, a cross wire in the middle
    for k in range(1, nx):
        y = -ry + k * 2 * ry / nx
        pieces.append(_wire([rx0, y, zc + 1.6 * r], [rx1, y, zc + 1.6 * r], 0.8 * r))
    pieces.append(_wire([(rx0 + rx1) / 2, -ry, zc], [(rx0 + rx1) / 2, ry, zc], r))
    ny = max(2, int(2 * ry / pitch))  # side walls: vertical wires
    for k in range(1, ny):
        y = -ry + k * 2 * ry / ny
        pieces += [_wire([x, y, zc], [x, y, zt], 0.8 * r) for x in (rx0, rx1)]
    nxs = max(2, int((rx1 - rx0) / pitch))
    for k in range(1, nxs):
        x = rx0 + k * (rx1 - rx0) / nxs
        pieces += [_wire([x, y, zc], [x, y, zt], 0.8 * r) for y in (-ry, ry)]
    if kind == "lower" and tines:  # plate tines: two rows across the rack
        t_h = min(0.85 * height, 0.16)
        for xr in (rx0 + 0.3 * (rx1 - rx0), rx0 + 0.5 * (rx1 - rx0)):
            pieces.append(_wire([xr, -ry, zc + 1.6 * r], [xr, ry, zc + 1.6 * r], r))
            nt = max(3, int(2 * ry / 0.04))
            pieces += [_wire([xr, -ry + k * 2 * ry / nt, zc + 2 * r], [xr, -ry + k * 2 * ry / nt, zc + t_h], 0.7 * r)
                       for k in range(1, nt)]
    pieces.append(g.box_between([rx1 - 0.006, -0.06, zt - 0.012], [rx1 + 0.004, 0.06, zt + r], "wheel", bevel=0.002))
    return pieces


DISH_WIRE = 0.0025  # wire radius of a dish rack


def dish_rack_floor(za: float) -> float:
    """Height of the axis of a fold-down row over a dish rack whose wheels stand on ``za``: clear of the
    bottom grid's wires, so a folded row lies over them."""
    return za + RACK_WHEEL + 4 * DISH_WIRE


def tine_row(xs, y: float, z: float, h: float, lean: float, pitch: float = 0.04) -> list[g.Piece]:
    """A fold-down row of plate tines: a bar along X at ``(y, z)`` (the hinge line) carrying tines ``h``
    tall every ``pitch``, their tops leaning ``lean`` along Y so gravity holds the row on its upright
    stop (Bosch / Miele "flip tines": rows that fold flat for pots, 2-4 per lower rack)."""
    xa, xb = xs
    r = DISH_WIRE
    n = max(2, int((xb - xa) / pitch))
    return [_wire([xa, y, z], [xb, y, z], r)] + [
        _wire([xa + (k + 0.5) * (xb - xa) / n, y, z], [xa + (k + 0.5) * (xb - xa) / n, y + lean, z + h], 0.7 * r)
        for k in range(n)]


def cup_shelf(xs, y: float, z: float, w: float, lean: float) -> list[g.Piece]:
    """A flip-down cup shelf of an upper dish rack: a wire frame ``w`` tall standing at ``y`` on its hinge
    line at height ``z`` along X, its top leaning ``lean`` along Y onto the rack's side wall (it rests
    folded up there and swings down to a level shelf; Bosch, Whirlpool upper racks)."""
    xa, xb = xs
    r = 0.8 * DISH_WIRE
    top = (y + lean, z + w)
    pieces = [_wire([xa, y, z], [xb, y, z], DISH_WIRE), _wire([xa, top[0], top[1]], [xb, top[0], top[1]], r)]
    n = max(2, int((xb - xa) / 0.03))
    pieces += [_wire([xa + k * (xb - xa) / n, y, z], [xa + k * (xb - xa) / n, *top], r) for k in range(n + 1)]
    return pieces


def open_bin(xs, ys, z0: float, h: float, material: str, t: float = 0.003) -> list[g.Piece]:
    """An open box (a cutlery basket): a bottom and four walls, hollow for the simulator."""
    (xa, xb), (ya, yb) = xs, ys
    return [g.box_between([xa, ya, z0], [xb, yb, z0 + t], material),
            g.box_between([xa, ya, z0 + t], [xa + t, yb, z0 + h], material),
            g.box_between([xb - t, ya, z0 + t], [xb, yb, z0 + h], material),
            g.box_between([xa + t, ya, z0 + t], [xb - t, ya + t, z0 + h], material),
            g.box_between([xa + t, yb - t, z0 + t], [xb - t, yb, z0 + h], material)]


# -- ovens ---------------------------------------------------------------------------------------------------
OVEN_SHEET = 0.0008  # steel sheet of the casing, door and liner
OVEN_PANEL = 0.01  # casing panels (modelled solid, massed as sheet)
OVEN_LINER = 0.003
OVEN_RACK_R = 0.0028  # rack wire radius
RAIL = (0.012, 0.006)  # side rail width, height
FACE = 0.004  # control panel face plate


def oven_casing(outer, zs, cavity, door_gap: float, frame_top: float) -> list[g.Piece]:
    """Sides, back, bottom, a divider over the drawer bay, a front frame with the cavity opening, a
    trim strip under the door, a five-wall enamel liner, a recessed kick plinth and four feet.

    ``outer``: (x back, x body front, x door front, y left, y right, z top of the casing);
    ``zs``: (plinth top, drawer top, divider, hinge); the front frame reaches up to ``frame_top``.
    """
    xb, xf, xd1, y0, y1, ztop = outer
    z_pl, z_dt, z_div, z_h = zs
    cx0, cx1, cy0, cy1, cz0, cz1 = cavity
    L, T = OVEN_LINER, OVEN_PANEL

    def sheet(piece):
        return piece.replace(sheet=OVEN_SHEET)

    pieces = [
        sheet(g.box_between([xb, y0, z_pl], [xf - T, y0 + T, ztop], "body")),
        sheet(g.box_between([xb, y1 - T, z_pl], [xf - T, y1, ztop], "body")),
        sheet(g.box_between([xb, y0 + T, z_pl], [xb + T, y1 - T, ztop], "body")),
        sheet(g.box_between([xb + T, y0 + T, z_pl], [xf - T, y1 - T, z_pl + T], "body")),
        sheet(g.box_between([xb + T, y0 + T, z_div], [xf - T, y1 - T, z_div + T], "body")),
        sheet(g.panel([xf - T, y0, z_div], [xf, y1, frame_top], "body", "x", holes=[(cy0, cz0, cy1, cz1)])),
        g.box_between([xf, y0, z_div], [xd1, y1, z_h - door_gap], "body"),  # trim strip under the door
        sheet(g.box_between([cx0 - L, cy0 - L, cz0 - L], [cx1, cy1 + L, cz0], "interior")),
        sheet(g.box_between([cx0 - L, cy0 - L, cz1], [cx1, cy1 + L, cz1 + L], "interior")),
        sheet(g.box_between([cx0 - L, cy0 - L, cz0], [cx1, cy0, cz1], "interior")),
        sheet(g.box_between([cx0 - L, cy1, cz0], [cx1, cy1 + L, cz1], "interior")),
        sheet(g.box_between([cx0 - L, cy0, cz0], [cx0, cy1, cz1], "interior")),
        g.box_between([xb + 0.03, y0 + 0.01, 0.0], [xf - 0.04, y1 - 0.01, z_pl], "plinth"),
    ]
    for x in (xb + 0.05, xf - 0.06):
        for y in (y0 + 0.05, y1 - 0.05):
            pieces.append(g.cylinder([x, y, 0.0], [x, y, z_pl], 0.015, "feet", 16))
    return pieces


def oven_door(box, hole) -> list[g.Piece]:
    """An outer skin, an inner frame and an enamel inner skin around a window, and two glass panes."""
    x0, x1, y0, y1, z0, z1 = box
    return [g.panel([x1 - 0.003, y0, z0], [x1, y1, z1], "door", "x", holes=[hole]).replace(sheet=OVEN_SHEET),
            g.panel([x0 + 0.003, y0, z0], [x1 - 0.003, y1, z1], "door_inner", "x", holes=[hole])
            .replace(sheet=OVEN_SHEET),
            g.panel([x0, y0 + 0.02, z0 + 0.02], [x0 + 0.003, y1 - 0.02, z1 - 0.02], "interior", "x", holes=[hole])
            .replace(sheet=OVEN_SHEET),
            g.box_between([x1 - 0.008, hole[0], hole[1]], [x1 - 0.003, hole[2], hole[3]], "glass"),
            g.box_between([x0 + 0.003, hole[0], hole[1]], [x0 + 0.007, hole[2], hole[3]], "glass")]


def oven_rack(xs, ys, zc: float) -> list[g.Piece]:
    """A chrome wire rack: a rectangular frame, wires along x, two cross wires."""
    (x0, x1), r = xs, OVEN_RACK_R
    ya, yb = ys[0] + r, ys[1] - r
    pieces = [g.cylinder(a, b, r, "rack", 8) for a, b in (([x0, ya, zc], [x1, ya, zc]), ([x0, yb, zc], [x1, yb, zc]),
                                                          ([x0, ya, zc], [x0, yb, zc]), ([x1, ya, zc], [x1, yb, zc]))]
    n = max(3, int((yb - ya) / 0.045))
    ys_w = [ya + (yb - ya) * k / n for k in range(1, n)]
    pieces += [g.cylinder([x0 + r, y, zc], [x1 - r, y, zc], 0.7 * r, "rack", 6) for y in ys_w]
    pieces += [g.cylinder([x0 + (x1 - x0) * f, ya, zc], [x0 + (x1 - x0) * f, yb, zc], 0.8 * r, "rack", 6)
               for f in (1 / 3, 2 / 3)]
    return pieces


def storage_drawer(front_box, tray_box, wall: float = 0.008) -> list[g.Piece]:
    """A drawer front and an open tray behind it (bottom, two sides, back), massed as sheet."""
    fx0, x1, y0, y1, z0, z1 = front_box
    tx0, ty0, ty1, tz0, tz1 = tray_box
    wt = wall
    return [p.replace(sheet=OVEN_SHEET) for p in (
        g.box_between([fx0, y0, z0], [x1, y1, z1], "body", bevel=0.002),
        g.box_between([tx0, ty0, tz0], [fx0, ty1, tz0 + wt], "body"),
        g.box_between([tx0, ty0, tz0 + wt], [fx0, ty0 + wt, tz1], "body"),
        g.box_between([tx0, ty1 - wt, tz0 + wt], [fx0, ty1, tz1], "body"),
        g.box_between([tx0, ty0 + wt, tz0 + wt], [tx0 + wt, ty1 - wt, tz1], "body"))]


def burner(x: float, y: float, z: float, r: float) -> list[g.Piece]:
    """A gas burner (a crown) and its enamel cap on the cooktop at height ``z``."""
    return [g.cylinder([x, y, z], [x, y, z + 0.012], r, "burner", 32),
            g.cylinder([x, y, z + 0.012], [x, y, z + 0.02], 0.65 * r, "cap", 32)]


def grate(xs, ys, z0: float, burners_x, foot: float = 0.014, feet_h: float = 0.03, bar: float = 0.01
          ) -> list[g.Piece]:
    """A cast grate over a column of burners: feet at its corners (clear of the burners), a frame,
    dividers between the burners and a cross of fingers over each."""
    (gx0, gx1), (ga, gb) = xs, ys
    depth, yc, n = gx1 - gx0, (ga + gb) / 2, len(burners_x)
    zb0, zb1 = z0 + feet_h, z0 + feet_h + bar
    pieces = [g.box_between([x, y, z0], [x + foot, y + foot, zb0], "grate") for x in (gx0, gx1 - foot)
              for y in (ga, gb - foot)]
    pieces += [g.box_between([gx0, ga, zb0], [gx1, ga + bar, zb1], "grate"),
               g.box_between([gx0, gb - bar, zb0], [gx1, gb, zb1], "grate"),
               g.box_between([gx0, ga + bar, zb0], [gx0 + bar, gb - bar, zb1], "grate"),
               g.box_between([gx1 - bar, ga + bar, zb0], [gx1, gb - bar, zb1], "grate")]
    for j in range(1, n):
        x = gx0 + depth * j / n
        pieces.append(g.box_between([x - bar / 2, ga + bar, zb0], [x + bar / 2, gb - bar, zb1], "grate"))
    span = depth / n / 2 - bar / 2
    for xc in burners_x:
        pieces += [g.box_between([xc - 0.005, ga + bar, zb1 - 0.008], [xc + 0.005, gb - bar, zb1], "grate"),
                   g.box_between([xc - span, yc - 0.005, zb1 - 0.008], [xc + span, yc + 0.005, zb1], "grate")]
    return pieces


def cooker_knob(x_face: float, y: float, z: float, r: float, stem: float, style: str) -> tuple[list[g.Piece], float]:
    """A cooker knob 3 mm in front of the panel face on a stem through a hole, symmetric about its axis
    (the pointer line runs across the whole face); returns the pieces and its reach in front of the face."""
    x0 = x_face + 0.003
    pieces = [g.cylinder([x_face - BEHIND, y, z], [x0 + 0.001, y, z], stem, "knob", 16)]
    if style == "ridge":
        depth = max(0.016, 0.8 * r)
        pieces += [g.cylinder([x0, y, z], [x0 + 0.006, y, z], r, "knob", 32),
                   g.box_between([x0 + 0.0055, y - 0.2 * r, z - 0.9 * r], [x0 + depth, y + 0.2 * r, z + 0.9 * r],
                                 "knob", bevel=0.002),
                   g.box_between([x0 + depth - 0.0005, y - 0.0012, z - 0.8 * r], [x0 + depth + 0.0008, y + 0.0012,
                                                                                  z + 0.8 * r], "trim")]
    else:
        depth = max(0.018, 0.9 * r)
        pieces += [g.cylinder([x0, y, z], [x0 + 0.005, y, z], r, "knob", 32),
                   g.cylinder([x0 + 0.0045, y, z], [x0 + depth, y, z], 0.82 * r, "knob", 32),
                   g.box_between([x0 + depth - 0.0005, y - 0.0012, z - 0.7 * r], [x0 + depth + 0.0008, y + 0.0012,
                                                                                  z + 0.7 * r], "trim")]
    # turned by its grip (the bar, or the cap), fingers across it; the pointer line on its face is the surface
    width = 0.4 * r if style == "ridge" else 1.64 * r
    pieces[-1] = pieces[-1].with_grasps(Grasp.make([x0 + depth + 0.0008, y, z], (-1, 0, 0), (0, 1, 0), width,
                                                   min(0.008, depth / 2)))
    return pieces, depth + 0.0008 + 0.003


def panel_housing(xs, ys, zs, holes, wall: float = 0.004) -> list[g.Piece]:
    """A hollow control panel box: a face plate with ``holes``, back, top, bottom and sides."""
    (xa, xp), (ya, yb), (za, zb), w = xs, ys, zs, wall
    return [p.replace(sheet=OVEN_SHEET) for p in (
        g.panel([xp - FACE, ya, za], [xp, yb, zb], "body", "x", holes=holes),
        g.box_between([xa, ya, za], [xa + w, yb, zb], "body"),
        g.box_between([xa + w, ya, zb - w], [xp - FACE, yb, zb], "body"),
        g.box_between([xa + w, ya, za], [xp - FACE, yb, za + w], "body"),
        g.box_between([xa + w, ya, za + w], [xp - FACE, ya + w, zb - w], "body"),
        g.box_between([xa + w, yb - w, za + w], [xp - FACE, yb, zb - w], "body"))]


class PanelNodes(Layout):
    """The push-button nodes of a control panel, shared by the appliances: a ``buttons`` node grows each
    ``button`` child with one made :class:`Control`; the button slides along its frame's z into
    ``parent`` (default :attr:`panel_part`)."""

    panel_part = "control_panel"

    def buttons(self, node, made, parent: str | None = None):
        for kid, m in zip(node.of("button"), made, strict=True):
            self.grow(kid, made=m, parent=parent)

    def button(self, node, made: Control, parent: str | None = None):
        self.add(made.name, "button", made.pieces)
        self.slide(parent or self.panel_part, made.name, made.at, upper=made.travel, role="button")
