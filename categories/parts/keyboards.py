"""Keyboard parts: real key layouts (ANSI full size, tenkeyless, laptop-style), a case with a key well, keycaps
that press into it and fold-out feet.

World frame as every category's: the keyboard's front (the space bar's side, the typist's) faces +x, y across
(the typist's left -y), z up.
The keyboard is built level in its own frame (case bottom at z = 0, its rubber pads below) and then set down:
with fold-out feet deployed it rests tilted on its front pads and the feet (:func:`stance`).

Every key is a moving part: a keycap pressed straight down its travel (role ``button``: the switch springs it
back). The caps stand in a well of the case over a solid switch plate, so the plate collides as one box and
not as a plate with a hole per key (a 104-key board stays a few hundred collision shapes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp
from infmob_usd.piece import Piece

from .laptops import Key, rounded
from .tables import _hull, slab

# -- real products ---------------------------------------------------------------------------------------
# (width, depth, height at the back, feet excluded) in metres, mass kg, key count
PRODUCTS = {
    "logitech_k120": (0.450, 0.155, 0.0235, 0.550, 104),  # Logitech K120 spec sheet (full size, membrane)
    "logitech_mx_keys": (0.4302, 0.1316, 0.0205, 0.810, 108),  # Logitech MX Keys spec sheet (full size, scissor)
    "logitech_g_pro_tkl": (0.361, 0.153, 0.034, 0.980, 87),  # Logitech G PRO keyboard spec sheet (tenkeyless)
    "logitech_k380": (0.279, 0.124, 0.016, 0.423, 79),  # Logitech K380 spec sheet (laptop-style, with batteries)
    "apple_magic_keyboard": (0.2789, 0.1149, 0.0109, 0.239, 78),  # Apple Magic Keyboard (2021) tech specs
}

# A design's key: (pitch m, cap's foot m, cap's top m, cap height m, travel m)
KEYS = {
    "mechanical": (0.01905, 0.0181, 0.0127, 0.0080, 0.0040),
    # ISO/IEC 9995 19.05 mm pitch; OEM-profile caps ~18 x 18 mm at the foot, ~12.7 mm on top, 8-9 mm tall;
    # Cherry MX / K120 membrane travel 3.5-4 mm
    "chiclet": (0.0185, 0.0155, 0.0150, 0.0025, 0.0015),
    # laptop-style scissor keys: 18-19 mm pitch, ~15.5 mm flat caps, 1-2 mm travel (Magic Keyboard ~1 mm,
    # K380 ~1.5 mm)
}
BORDER = {"full": ((0.008, 0.016), (0.012, 0.03)), "tkl": ((0.008, 0.016), (0.012, 0.03)),
          "laptop": ((0.006, 0.010), (0.008, 0.016))}
"""(side, back) borders round the keys (m): K120 ~12 mm sides and ~30 mm back (its LED strip), G PRO ~10 mm,
K380 / Magic Keyboard ~6-10 mm (measured on the spec-sheet outlines less the key count x 19 mm)."""
FRONT = 0.010  # m, the case in front of the space bar (K120 ~12 mm, Magic Keyboard ~8 mm)
HEIGHT = {"mechanical": (0.018, 0.030), "chiclet": (0.009, 0.016)}  # m at the back: K120 23.5, G PRO 34; K380 16
CAP_WALL = 0.0012  # m, a full-size keycap's wall (OEM ABS / PBT caps 1.1-1.5 mm)
WELL = 0.003  # m, the key well's margin round the caps
RISE = 0.0025  # m, the caps' feet stand this above the well's rim once pressed (the rim hides the plate)
PAD = dict(r=0.005, h=0.002, inset=0.018)  # rubber pads under the corners
FOOT = dict(width=(0.025, 0.045), length=(0.008, 0.014), thick=0.0015, inset=0.05, gap=0.0004)
"""Fold-out feet at the back corners (K120: ~35 x 10 mm, raising the back ~8 mm; G PRO two-step feet 4-8 mm)."""
KEYBOARD_DENSITY = 450.0
"""kg/m^3 a keyboard's case weighs as a solid over its volume: K120 ~0.39 kg (its 0.55 kg less 104 caps with
stems ~1.5 g each) over ~450 x 155 x 15 mm, 370; MX Keys ~0.6 kg (steel plate) over 430 x 132 x 14 mm, 750."""

# -- layouts (key widths in units of a pitch; a negative width is a gap) -----------------------------------
F_ROW = (1.0, -1.0, 1.0, 1.0, 1.0, 1.0, -0.5, 1.0, 1.0, 1.0, 1.0, -0.5, 1.0, 1.0, 1.0, 1.0)
MAIN = (
    (1.0,) * 13 + (2.0,),
    (1.5,) + (1.0,) * 12 + (1.5,),
    (1.75,) + (1.0,) * 11 + (2.25,),
    (2.25,) + (1.0,) * 10 + (2.75,),
    (1.25, 1.25, 1.25, 6.25, 1.25, 1.25, 1.25, 1.25),
)
"""ANSI: Esc and F1-F12 (13), then the number row (14), Tab (14), Caps (13), Shift (12) and the bottom row
(8): 74 keys, 15 units wide (ANSI INCITS 154 / the IBM Model M layout of every full-size board)."""
NAV = ((0, 0, 3), (1.5, 0, 3), (2.5, 0, 3), (4.5, 1, 1), (5.5, 0, 3))
"""The navigation cluster right of the main block, 0.25 units apart: (row, first column, keys) for Print
Screen / Scroll Lock / Pause, Insert / Home / Page Up, Delete / End / Page Down, up, then left / down / right
(rows in units from the function row; 13 keys: 87 with the main block, a tenkeyless board)."""
NUMPAD = ((1.5, 0, 1, 1), (1.5, 1, 1, 1), (1.5, 2, 1, 1), (1.5, 3, 1, 1), (2.5, 0, 1, 1), (2.5, 1, 1, 1),
          (2.5, 2, 1, 1), (2.5, 3, 1, 2), (3.5, 0, 1, 1), (3.5, 1, 1, 1), (3.5, 2, 1, 1), (4.5, 0, 1, 1),
          (4.5, 1, 1, 1), (4.5, 2, 1, 1), (4.5, 3, 1, 2), (5.5, 0, 2, 1), (5.5, 2, 1, 1))
"""The numeric pad: (row, column, width, height) of Num Lock / / * -, 7 8 9 +(two rows tall), 4 5 6, 1 2 3
Enter (two rows tall), 0 (two wide) and . (17 keys: 104 in all, a full-size board)."""
LAPTOP = (
    ((1.0,) * 14, 0.55),
    ((1.0,) * 13 + (2.0,), 1.0),
    ((1.5,) + (1.0,) * 12 + (1.5,), 1.0),
    ((1.75,) + (1.0,) * 11 + (2.25,), 1.0),
    ((2.25,) + (1.0,) * 10 + (2.75,), 1.0),
    ((1.0,) * 4 + (6.0,) + (1.0,) * 5, 1.0),
)
"""A laptop-style board (K380, Magic Keyboard): half-height function keys (14), the four main rows (14, 14, 13,
12) and a bottom row of 8 keys with the arrows (left, up over down, right): 78 keys."""
ROW_GAP = 0.5  # units between the function row and the number row (full size and tenkeyless)


def _row(widths, x: float, y0: float, pitch: float, foot: float, height: float = 1.0) -> list[Key]:
    out, y = [], y0
    gap = pitch - foot
    for w in widths:
        if w > 0:
            out.append(Key(x, y - w * pitch / 2, height * pitch - gap, w * pitch - gap))
        y -= abs(w) * pitch
    return out


def layout(design: str, pitch: float, foot: float) -> list[Key]:
    """Every key of a ``full`` (104), ``tkl`` (87) or ``laptop``-style (78) board, the function row at x = 0
    (its back edge) and the main block's left edge at y = 0, running to -y (:func:`board` mirrors it: seen from
    the front, the typist's left is -y)."""
    if design == "laptop":
        keys, x, gap = [], 0.0, pitch - foot
        for widths, h in LAPTOP:
            row = _row(widths, x + h * pitch / 2, 0.0, pitch, foot, h)
            if len(row) == 10:  # the up and down arrows share a column, half height each
                c = row[8]
                half = (c.dx - gap) / 2
                row[8:9] = [Key(c.x - (half + gap) / 2, c.y, half, c.dy), Key(c.x + (half + gap) / 2, c.y, half, c.dy)]
            keys += row
            x += h * pitch
        return keys
    keys = _row(F_ROW, pitch / 2, 0.0, pitch, foot)
    for r, widths in enumerate(MAIN):
        keys += _row(widths, (r + 1 + ROW_GAP + 0.5) * pitch, 0.0, pitch, foot)
    y_nav = -15.25 * pitch
    for row, col, n in NAV:
        keys += _row((1.0,) * n, (row + (ROW_GAP if row else 0.0) + 0.5) * pitch, y_nav - col * pitch, pitch, foot)
    if design == "full":
        y_pad = y_nav - 3.25 * pitch
        for row, col, w, h in NUMPAD:
            x = (row + ROW_GAP + h / 2) * pitch
            keys.append(Key(x, y_pad - (col + w / 2) * pitch, h * pitch - (pitch - foot), w * pitch - (pitch - foot)))
    return keys


@dataclass(frozen=True)
class Board:
    """A keyboard's case: x from ``x0`` (back) to ``x1`` (front), y within +-``W``/2, the plate's top at
    ``plate``, the well's rim at ``rim``, the back's height ``H``; the keys centred about y = 0."""

    keys: tuple
    x0: float
    x1: float
    W: float
    plate: float
    rim: float
    H: float
    corner: float
    cap: tuple  # (pitch, foot, top, height, travel)

    @property
    def cap_z(self) -> float:
        """A keycap's underside at rest."""
        return self.rim + RISE + self.cap[4]


def board(design: str, side: float, back: float, height: float, corner: float) -> Board:
    """A case round the design's layout; ``side``, ``back``, ``height`` are fractions (0..1) of their ranges."""
    kind = "chiclet" if design == "laptop" else "mechanical"
    cap = KEYS[kind]
    keys = layout(design, cap[0], cap[1])
    ymid = (max(k.y + k.dy / 2 for k in keys) + min(k.y - k.dy / 2 for k in keys)) / 2
    keys = [Key(k.x, ymid - k.y, k.dx, k.dy) for k in keys]  # the typist faces -x: their left is -y
    (s0, s1), (b0, b1) = BORDER[design]
    kx0, kx1 = min(k.x - k.dx / 2 for k in keys), max(k.x + k.dx / 2 for k in keys)
    ky = max(k.y + k.dy / 2 for k in keys)
    bk, sd = b0 + back * (b1 - b0), s0 + side * (s1 - s0)
    H = HEIGHT[kind][0] + height * (HEIGHT[kind][1] - HEIGHT[kind][0])
    plate = max(0.004, H - RISE - cap[4] - 0.6 * cap[3])
    rim = plate + 0.3 * cap[3] if kind == "mechanical" else plate + 0.0008
    return Board(tuple(keys), kx0 - bk, kx1 + FRONT, 2 * (ky + sd), plate, rim, H, corner, cap)


def case(b: Board, material: str, pads: str) -> list[Piece]:
    """The case: a rounded tub up to the switch plate, a rim round the key well and rubber pads under it."""
    D, xc = b.x1 - b.x0, (b.x0 + b.x1) / 2
    out = [slab(rounded(b.W, D, b.corner) + (xc, 0.0), 0.0, b.plate, 0.002, material).replace(wall=0.0)]
    wx0 = min(k.x - k.dx / 2 for k in b.keys) - WELL
    wx1 = max(k.x + k.dx / 2 for k in b.keys) + WELL
    wy = max(k.y + k.dy / 2 for k in b.keys) + WELL
    inset = 0.6 * b.corner
    bands = [((b.x0 + inset, -b.W / 2 + inset), (wx0, b.W / 2 - inset)),  # behind the keys
             ((wx1, -b.W / 2 + inset), (b.x1 - inset, b.W / 2 - inset)),  # in front
             ((wx0, wy), (wx1, b.W / 2 - inset)), ((wx0, -b.W / 2 + inset), (wx1, -wy))]  # the sides
    for (x0, y0), (x1, y1) in bands:
        if x1 - x0 > 1e-3 and y1 - y0 > 1e-3:
            top = b.rim if x0 > wx0 - 1e-6 or x1 > wx1 else b.rim + 0.0005
            out.append(g.box_between((x0, y0, b.plate - 0.0002), (x1, y1, top), material,
                                     bevel=min(0.0008, 0.3 * (top - b.plate))).replace(wall=0.0))
    r, h = PAD["r"], PAD["h"]
    for x in (b.x0 + PAD["inset"], b.x1 - PAD["inset"]):
        for y in (-b.W / 2 + PAD["inset"], b.W / 2 - PAD["inset"]):
            out.append(g.cylinder((x, y, -h), (x, y, 0.0003), r, pads))
    return out


LEGEND = (0.0035, 0.0005)  # m, a printed legend's glyph height and stroke (OEM caps: ~3.5 mm letters, top-left)
GLYPHS = (((0.0, 0.0, 0.0, 1.0), (0.0, 1.0, 0.6, 1.0)),  # L
          ((0.0, 0.0, 0.7, 0.0), (0.35, 0.0, 0.35, 1.0)),  # T
          ((0.0, 0.0, 0.0, 1.0), (0.6, 0.0, 0.6, 1.0), (0.0, 0.5, 0.6, 0.5)),  # H
          ((0.0, 0.0, 0.6, 0.0), (0.0, 0.0, 0.0, 1.0), (0.0, 0.5, 0.5, 0.5), (0.0, 1.0, 0.6, 1.0)))  # E
"""Generic glyphs as strokes ((u0, v0, u1, v1) in glyph heights; u to the reader's right, v down the cap)."""


def legend(k: Key, z: float, top: tuple[float, float], index: int, material: str) -> list[Piece]:
    """A printed legend at a cap top's back-left corner (as the typist reads it: they sit at +x facing -x, so
    their right is +y and down the cap is +x); none on a bar over 2.5 times as long as wide (the space bar).
    Drawn."""
    if max(k.dx, k.dy) > 2.5 * min(k.dx, k.dy):
        return []
    size, w = min(LEGEND[0], 0.38 * min(top)), LEGEND[1]  # smaller on a laptop's half-height function keys
    x0, y0 = k.x - top[0] / 2 + 0.25 * top[0], k.y - top[1] / 2 + 0.22 * min(top)
    v, f = [], []
    for u0, v0, u1, v1 in GLYPHS[index % len(GLYPHS)]:
        a = np.array([x0 + v0 * size, y0 + u0 * size])
        c = np.array([x0 + v1 * size, y0 + u1 * size])
        d = c - a
        n = np.array([-d[1], d[0]]) / max(float(np.hypot(*d)), 1e-9) * w / 2
        ext = d / max(float(np.hypot(*d)), 1e-9) * w / 2
        quad = [a - ext - n, c + ext - n, c + ext + n, a - ext + n]
        base = len(v)
        v += [(q[0], q[1], z) for q in quad] + [(q[0], q[1], z + 6e-5) for q in quad]
        f += [[base + i for i in tri] for tri in ((4, 5, 6), (4, 6, 7), (0, 2, 1), (0, 3, 2), (0, 1, 5), (0, 5, 4),
                                                   (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7))]
    return [Piece(np.array(v, float), np.array(f, np.int64), material, [], "legend")]


def keycap(b: Board, k: Key, material: str, marks: str | None = None, index: int = 0) -> Assembly:
    """A keycap pressed straight down (anchor ``press``, z down): a tapered cap (its top ``cap[2]`` narrower than
    its foot on a full-size pitch) standing its travel and ``RISE`` above the well's rim; its printed legend
    in ``marks`` where given."""
    _, foot, top, h, _ = b.cap
    shrink = (foot - top) / 2
    z0 = b.cap_z
    lo = [(k.x + sx * k.dx / 2, k.y + sy * k.dy / 2, z0) for sx in (-1, 1) for sy in (-1, 1)]
    hi = [(k.x + sx * (k.dx / 2 - shrink), k.y + sy * (k.dy / 2 - shrink), z0 + h) for sx in (-1, 1)
          for sy in (-1, 1)]
    # a full-size cap is a moulded shell (1-1.5 mm ABS walls: ~1.5 g, a space bar ~6 g); a chiclet cap is a plate
    piece = _hull(lo + hi, material).replace(wall=CAP_WALL if h > 0.004 else 0.0)
    grasp = Grasp.make((k.x, k.y, z0 + h), (0, 0, -1), (0, 1, 0) if k.dy <= k.dx else (1, 0, 0),
                       min(k.dx, k.dy) - 2 * shrink, h / 2)
    pieces = [piece.with_grasps(grasp)]
    if marks:
        pieces += legend(k, z0 + h, (k.dx - 2 * shrink, k.dy - 2 * shrink), index, marks)
    return Assembly.single("key", pieces, {"press": Frame.at((k.x, k.y, z0 + h), z=(0, 0, -1), x=(1, 0, 0))})


@dataclass(frozen=True)
class Foot:
    """A fold-out foot: hinged about y at (``x``, ``y``) under the case, ``length`` long, ``width`` wide."""

    x: float
    y: float
    length: float
    width: float


def feet(b: Board, width: float, length: float) -> list[Foot]:
    """Two feet at the back corners, their hinge ahead of the back edge by their length (folded back they lie
    under the case)."""
    w = FOOT["width"][0] + width * (FOOT["width"][1] - FOOT["width"][0])
    L = FOOT["length"][0] + length * (FOOT["length"][1] - FOOT["length"][0])
    x = b.x0 + PAD["inset"] + PAD["r"] + L + 0.004
    yc = b.W / 2 - FOOT["inset"] - w / 2
    return [Foot(x, s * yc, L, w) for s in (1, -1)]


def tilt(b: Board, fs: list[Foot]) -> Frame:
    """Where the level keyboard is set down: flat on its pads, or tilted (about y) onto its front pads and its
    deployed feet, each foot then standing plumb."""
    if not fs:
        return Frame.at((0.0, 0.0, PAD["h"]))
    f = fs[0]
    xp = b.x1 - PAD["inset"]
    a = math.atan2(f.length - PAD["h"], xp - f.x)
    x_ax, z_ax = (math.cos(a), 0.0, -math.sin(a)), (math.sin(a), 0.0, math.cos(a))
    rot = Frame.at((0.0, 0.0, 0.0), z=z_ax, x=x_ax)
    low = min(rot.point((xp, 0.0, -PAD["h"]))[2], rot.point((f.x, 0.0, -f.length))[2])
    return Frame.at((0.0, 0.0, -low), z=z_ax, x=x_ax)


def angle(frame: Frame) -> float:
    """The tilt of a :func:`tilt` frame (rad)."""
    return math.atan2(frame.z[0], frame.z[2])


def foot_part(f: Foot, tilt_angle: float, material: str) -> Assembly:
    """A deployed foot: a plate hanging from its hinge under the case, plumb once the case is tilted by
    ``tilt_angle`` (so the case's weight passes through its hinge), folding back (anchor ``hinge``, about +y:
    its tip swings back and up) to lie under the case."""
    t, gap = FOOT["thick"], FOOT["gap"]
    hz = -gap - t / 2
    d = np.array([math.sin(tilt_angle), 0.0, -math.cos(tilt_angle)])  # plumb, in the level frame
    n = np.array([math.cos(tilt_angle), 0.0, math.sin(tilt_angle)])
    c = np.array([f.x, f.y, hz])
    # a chisel tip: its edge on the table under the hinge, so folding lifts it at once (a square tip's front corner
    # would dig into the table as the foot starts to turn)
    pts = [c + s * f.length * d + u * (t / 2) * n + (0, v * f.width / 2, 0) for s in (0.0, 1.0 - t / f.length)
           for u in (-1, 1) for v in (-1, 1)] + [c + f.length * d + (0, v * f.width / 2, 0) for v in (-1, 1)]
    tip = c + f.length * d + (t / 2) * n
    piece = _hull(pts, material).replace(wall=0.0)
    # a gripper reaching in under the back edge pinches the foot across its thickness near the tip and pulls it back
    piece = piece.with_grasps(Grasp.make(tuple(tip - (t / 2) * n - 0.3 * f.length * d), (1, 0, 0), (0, 0, 1), t,
                                         0.5 * f.width))
    return Assembly.single("foot", [piece], {"hinge": Frame.at(tuple(c), z=(0, 1, 0), x=(1, 0, 0))})


FOLD = math.radians(95.0)
"""A foot folds back past square to the case (the core shortens it where it meets the case's underside)."""
