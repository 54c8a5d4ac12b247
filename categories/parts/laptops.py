"""Laptop parts: a rounded base with a keyboard and a trackpad, a lid carrying the display, and its hinges.

World frame as every category's: the laptop's front faces +x, y across, z up. The base stands on its
rubber feet from x = -D/2 (the hinge side) to +D/2. The keyboard is drawn key by key (caps on a key bed);
the keys a task presses (space bar, power key, arrows) are moving parts that press 1-1.5 mm into holes in
the bed, the rest are caps fixed to it (80-100 links per laptop would be most of a scene's bodies).

Sizes of real laptops, each figure beside its source (manufacturers' spec sheets):
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp
from infmob_usd.piece import Piece

from .tables import slab

# -- real products ---------------------------------------------------------------------------------------
# (width, depth, closed thickness) in metres, mass kg
PRODUCTS = {
    "macbook_air_13_m2": (0.3041, 0.215, 0.0113, 1.24),  # Apple tech specs, MacBook Air (M2, 2022)
    "dell_xps_13_9315": (0.2953, 0.199, 0.0140, 1.17),  # Dell XPS 13 9315 spec sheet
    "thinkpad_t14_g3": (0.3177, 0.2269, 0.0179, 1.21),  # Lenovo PSREF ThinkPad T14 Gen 3
    "dell_xps_15_9520": (0.3447, 0.2301, 0.0180, 1.86),  # Dell XPS 15 9520 spec sheet
    "dell_inspiron_15_3520": (0.3585, 0.2356, 0.0190, 1.65),  # Dell Inspiron 15 3520 spec sheet (numeric pad)
    "hp_17_cn": (0.3983, 0.2599, 0.0206, 2.10),  # HP Laptop 17-cn spec sheet (numeric pad)
    "hp_spectre_x360_14": (0.2985, 0.2204, 0.0169, 1.36),  # HP Spectre x360 14-ef spec sheet (360-degree hinge)
    "hp_envy_x360_15": (0.3580, 0.2300, 0.0188, 1.88),  # HP ENVY x360 15-ew spec sheet (360-degree, numeric pad)
}
WIDTH = {"compact": (0.2953, 0.3447), "numpad": (0.3585, 0.3983), "convertible": (0.2985, 0.3580)}
"""Width ranges (m): laptops without a numeric pad (XPS 13 to XPS 15), with one (Inspiron 15 to HP 17),
360-degree convertibles (Spectre x360 14 to ENVY x360 15)."""
DEPTH_RATIO = (0.65, 0.71)  # depth / width: HP 17 0.653, Inspiron 15 0.657, XPS 13 0.674, MacBook Air 0.707
THICKNESS = (0.0113, 0.0206)  # closed, feet excluded: MacBook Air 13 to HP 17
LID_SHARE = (0.3, 0.4)  # lid / closed thickness: MacBook Air 13 lid ~4 of 11.3 mm, XPS 15 ~7 of 18 mm
LAPTOP_DENSITY = 1400.0
"""kg/m^3 a laptop's base and lid weigh as solids: its shell, battery, board and panel over its volume,
1.0-1.7 t/m^3 from the products above (MacBook Air 13: ~0.83 kg base over 304 x 215 x 7.5 mm, 1.7;
Inspiron 15: ~1.1 kg over 358 x 236 x 13 mm, 1.0; XPS 15: ~1.25 kg over 345 x 230 x 12 mm, 1.3)."""
LID_AREAL = 6.5
"""kg/m^2 a lid weighs over its area (display panel, cover, back): MacBook Air 13 ~0.41 kg over 304 x 215 mm, 6.3;
HP 17 ~0.7 kg over 398 x 260 mm, 6.8 (estimated as a third of the spec-sheet masses, not weighed)."""
CLAMSHELL_OPENS = (math.radians(120), math.radians(180))
"""A clamshell lid's stop: ~120-135 degrees (MacBook, XPS) to 180 (ThinkPad: "lay-flat" hinges)."""
CONVERTIBLE_OPENS = 2 * math.pi
"""A convertible's hinges turn the lid 360 degrees, under the base into a tablet (HP x360, Lenovo Yoga); standing
on a table the ground stops it near 180 (the core's ground limit)."""

# -- the keyboard ----------------------------------------------------------------------------------------
PITCH = 0.019  # m, full-size key pitch 19.05 mm (ISO/IEC 9995); laptops 18-19 mm (MacBook 18.5, XPS 19)
CAP = 0.0155  # m, a chiclet keycap's side at a 19 mm pitch (MacBook Air: ~15.6 mm)
CAP_H = 0.0012  # m, a keycap's thickness above the key bed
KEY_TRAVEL = 0.0012  # m, laptop scissor keys 1.0-1.5 mm (MacBook Air M2 1 mm, ThinkPad T14 1.5 mm)
BED = 0.0018  # m, the key bed: the moving keys and the pad press into its holes (their travel and 0.6 mm)
CLEAR = 0.0006  # m, a moving keycap's clearance in its hole
MARGIN = 0.012  # m, the keyboard's sides from the base's edge at least
BACK = 0.022  # m, the keyboard's top row from the hinge edge (speaker strip, MacBook Air 13 ~20 mm)
# Rows from the back (function row) to the front: key widths in pitches; "space", "left", "right", "up",
# "down", "power" name the keys that may move. A half-height row (function keys, the arrows' up/down) is 0.55.
ROWS = (
    ((1.0,) * 13 + ((1.0, "power"),), 0.55),
    ((1.0,) * 13 + (2.0,), 1.0),
    ((1.5,) + (1.0,) * 12 + (1.5,), 1.0),
    ((1.75,) + (1.0,) * 11 + (2.25,), 1.0),
    ((2.25,) + (1.0,) * 10 + (2.75,), 1.0),
    ((1.0,) * 4 + ((6.0, "space"),) + (1.0, 1.0) + ((1.0, "left"), (1.0, "updown"), (1.0, "right")), 1.0),
)
NUMPAD = (((1.0,) * 4, 0.55), ((1.0,) * 4, 1.0), ((1.0,) * 4, 1.0), ((1.0,) * 4, 1.0), ((1.0,) * 4, 1.0),
          ((2.0, 1.0, 1.0), 1.0))
"""A laptop numeric pad: four columns right of the main block (Inspiron 15, HP 17)."""
NUMPAD_GAP = 0.5  # pitches between the main block and the numeric pad
MOVING = ("space", "power", "left", "right", "up", "down")
"""The keys that may move, in the order a laptop's ``moving_keys`` count takes them."""
ROW_GAP = 0.1  # pitches between rows (a key is a pitch wide less the cap gap; rows as apart)

# -- trackpad, lid, hinges -----------------------------------------------------------------------------------
TRACKPAD = dict(depth=(0.065, 0.08), aspect=1.55, front=0.012, thick=0.0012, travel=0.001, proud=0.0006)
"""A mechanical click pad: 65-80 mm deep, ~1.55 x as wide (MacBook Air 13 ~121 x 79, XPS 13 112 x 70 mm),
12 mm from the front at least, clicking ~1 mm down (a diving-board click: modelled as a press)."""
LIP = dict(width=0.04, reach=0.004, grip=0.003)
"""The lip on the closed lid's front edge that a thumb lifts it by (ThinkPad X1, Surface Laptop, HP Pavilion lids):
40 mm wide, 4 mm proud of the base; a gripper pinches 3 mm of it across its thickness."""
SEAM = 0.0008  # m, the closed lid's display clears the keycaps by this
BEZEL = (0.004, 0.008)  # m, side and top bezel (XPS 13 ~4 mm, budget 15-inch ~8 mm)
CHIN = 0.012  # m, the bezel above the hinge at least
DISPLAY_ASPECT = {"16:10": 10 / 16, "16:9": 9 / 16}
CORNER = (0.004, 0.012)  # m, the footprint's corner radius (ThinkPad ~4 mm, MacBook ~10 mm)
FOOT = dict(r=0.004, h=0.0015, inset=0.025)  # rubber feet
HINGE_KNUCKLE = dict(width=0.03, inset=0.12)  # a convertible's hinge knuckles: width, centre from each side (x W)
HINGE_COVER = 0.36  # a clamshell's hinge cover spans +- this x W


@dataclass(frozen=True)
class Laptop:
    """A laptop's outer sizes (m): ``W`` wide, ``D`` deep, base ``Tb`` and lid ``Tl`` thick, footprint corner
    ``r``; ``numpad``: a numeric pad; ``convertible``: a 360-degree dual-axis hinge."""

    W: float
    D: float
    Tb: float
    Tl: float
    r: float
    numpad: bool
    convertible: bool

    @property
    def keys_top(self) -> float:
        return self.Tb + BED + CAP_H

    @property
    def lid_z(self) -> float:
        """The closed lid's underside (its bezel's face)."""
        return self.keys_top + SEAM

    @property
    def x_back(self) -> float:
        return -self.D / 2


def laptop(design: str, numpad: bool, size: float, depth_ratio: float, thickness: float, lid_share: float,
           corner: float) -> Laptop:
    """Sizes from the parameters, each a fraction (0..1) of its sourced range for the design."""
    lo, hi = WIDTH["numpad" if numpad else "convertible" if design == "convertible" else "compact"]
    W = lo + size * (hi - lo)
    T = THICKNESS[0] + thickness * (THICKNESS[1] - THICKNESS[0])
    Tl = T * lid_share
    return Laptop(W, W * depth_ratio, T - Tl - BED - CAP_H - SEAM, Tl, corner, numpad, design == "convertible")


def rounded(W: float, D: float, r: float, n: int = 6) -> np.ndarray:
    """A rounded rectangle's outline (``(k, 2)``, x, y), ``D`` along x, ``W`` along y, corners of radius ``r``."""
    pts = []
    for cx, cy, a0 in ((D / 2 - r, W / 2 - r, 0.0), (-D / 2 + r, W / 2 - r, 90.0), (-D / 2 + r, -W / 2 + r, 180.0),
                       (D / 2 - r, -W / 2 + r, 270.0)):
        for t in np.radians(np.linspace(a0, a0 + 90.0, n)):
            pts.append((cx + r * math.cos(t), cy + r * math.sin(t)))
    return np.array(pts)


def _solid(piece: Piece) -> Piece:
    return piece.replace(wall=0.0)


def base(b: Laptop, material: str, feet: str) -> list[Piece]:
    """The base: a rounded slab on four rubber feet."""
    f = FOOT
    pieces = [_solid(slab(rounded(b.W, b.D, b.r), 0.0, b.Tb, min(0.0015, 0.2 * b.Tb), material))]
    for x in (-b.D / 2 + f["inset"], b.D / 2 - f["inset"]):
        for y in (-b.W / 2 + f["inset"], b.W / 2 - f["inset"]):
            pieces.append(g.cylinder((x, y, -f["h"]), (x, y, 0.0005), f["r"], feet))
    return pieces


def ports(b: Laptop, material: str) -> list[Piece]:
    """USB-C and USB-A openings on both sides, drawn as dark inlays (decoration)."""
    out = []
    z = b.Tb / 2
    for s, sizes in ((1, (0.0084, 0.0084)), (-1, (0.0120, 0.0084))):
        x = -b.D / 2 + 0.03
        for w in sizes:
            h = min(0.0026 if w < 0.01 else 0.0045, 0.5 * b.Tb)
            y0 = s * b.W / 2
            p = g.box_between((x, y0 - 0.0003, z - h / 2), (x + w, y0 + 0.0003, z + h / 2), material)
            out.append(Piece(p.vertices, p.faces, material))
            x += w + 0.006
    return out


@dataclass(frozen=True)
class Key:
    """A key's centre (x, y), size (along x, along y) and name (``""``: a fixed cap)."""

    x: float
    y: float
    dx: float
    dy: float
    name: str = ""
    pad: bool = False  # on the numeric pad


def keyboard(b: Laptop) -> tuple[list[Key], float, tuple[float, float]]:
    """Every key, the pitch, and the keyboard's (front x, centre y of the main block)."""
    cols = 15 + ((4 + NUMPAD_GAP) if b.numpad else 0)
    pitch = min(PITCH, (b.W - 2 * MARGIN) / cols)
    gap = pitch - CAP * pitch / PITCH
    width = cols * pitch
    y_left = width / 2  # keys run from +y (left as seen from the front) to -y
    keys = _block(ROWS, y_left, b.x_back + BACK, pitch, gap)
    if b.numpad:
        keys += [replace(k, pad=True) for k in _block(NUMPAD, y_left - (15 + NUMPAD_GAP) * pitch, b.x_back + BACK,
                                                      pitch, gap)]
    front = max(k.x + k.dx / 2 for k in keys)
    return keys, pitch, (front, y_left - 7.5 * pitch)


def _block(rows, y0: float, x0: float, pitch: float, gap: float) -> list[Key]:
    keys, x = [], x0
    for widths, height in rows:
        dx = height * pitch - gap
        xc = x + dx / 2
        y = y0
        for w in widths:
            w, name = (w, "") if isinstance(w, float) else w
            dy = w * pitch - gap
            yc = y - w * pitch / 2
            if name == "updown":  # up and down arrows: two half-height keys in one column
                h = (dx - gap) / 2
                keys += [Key(xc - dx / 2 + h / 2, yc, h, dy, "up"), Key(xc + dx / 2 - h / 2, yc, h, dy, "down")]
            else:
                keys.append(Key(xc, yc, dx, dy, name))
            y -= w * pitch
        x += height * pitch + ROW_GAP * pitch
    return keys


def moving(keys: list[Key], count: int) -> list[Key]:
    """The first ``count`` keys of :data:`MOVING` (the space bar first)."""
    named = {k.name: k for k in keys if k.name}
    return [named[n] for n in MOVING[:count]]


def trackpad(b: Laptop, kb_front: float, y_mid: float) -> Key:
    """The click pad, centred under the space bar in the palm rest."""
    t = TRACKPAD
    room = b.D / 2 - t["front"] - (kb_front + 0.012)
    dx = float(np.clip(room, *t["depth"]))
    dx = min(dx, room)
    return Key(b.D / 2 - t["front"] - dx / 2, y_mid, dx, min(t["aspect"] * dx, b.W - 2 * MARGIN))


def bed(b: Laptop, keys: list[Key], pad: Key, holes: list[Key], material: str) -> Piece:
    """The key bed over the keyboard and round the trackpad: a plate ``BED`` thick on the base's top with a
    hole for every moving key and for the pad."""
    m = 0.004
    x0 = min(k.x - k.dx / 2 for k in keys) - m
    x1 = pad.x + pad.dx / 2 + m
    y0 = min(k.y - k.dy / 2 for k in keys) - m
    y1 = max(k.y + k.dy / 2 for k in keys) + m
    y0, y1 = min(y0, pad.y - pad.dy / 2 - m), max(y1, pad.y + pad.dy / 2 + m)
    cut = [(k.x - k.dx / 2 - CLEAR, k.y - k.dy / 2 - CLEAR, k.x + k.dx / 2 + CLEAR, k.y + k.dy / 2 + CLEAR)
           for k in [*holes, pad]]
    # edges closer than 0.01 mm would leave collision cells too thin to have a hull: one edge
    cut = [tuple(round(c, 5) for c in h) for h in cut]
    return _solid(g.panel((round(x0, 5), round(y0, 5), b.Tb - 0.0002), (round(x1, 5), round(y1, 5), b.Tb + BED),
                          material, "z", cut))


def fixed_caps(b: Laptop, keys: list[Key], material: str) -> list[Piece]:
    """The caps that do not move, on the bed, one mesh per cap size (decoration: the bed collides)."""
    by_size: dict[tuple[float, float], list] = {}
    for k in keys:
        by_size.setdefault((round(k.dx, 6), round(k.dy, 6)), []).append((k.x, k.y, b.Tb + BED + CAP_H / 2))
    out = []
    for (dx, dy), centres in sorted(by_size.items()):
        proto = g.box((dx, dy, CAP_H), (0, 0, 0), material, bevel=0.35 * CAP_H)
        v, f = g.instances(proto.vertices, proto.faces, np.array(centres))
        out.append(Piece(v, f, material))
    return out


def key_part(k: Key, z: float, material: str, thick: float = CAP_H, label: str = "key") -> Assembly:
    """A moving key (or the trackpad): a cap standing ``thick`` on its hole at height ``z``, pressed down
    (anchor ``press``, z down), with a finger's press on its face."""
    piece = g.box_between((k.x - k.dx / 2, k.y - k.dy / 2, z), (k.x + k.dx / 2, k.y + k.dy / 2, z + thick), material,
                          bevel=min(0.35 * thick, 0.2 * min(k.dx, k.dy)))
    # a finger presses the middle of the face straight down, closing across its narrow side
    grasp = Grasp.make((k.x, k.y, z + thick), (0, 0, -1), (0, 1, 0) if k.dy <= k.dx else (1, 0, 0), min(k.dx, k.dy),
                       thick / 2)
    return Assembly.single(label, [_solid(piece).with_grasps(grasp)],
                           {"press": Frame.at((k.x, k.y, z + thick), z=(0, 0, -1), x=(1, 0, 0))})


# -- the lid and its hinges ----------------------------------------------------------------------------------
def display_area(b: Laptop, aspect: str, bezel: float) -> tuple[float, float, float]:
    """The display's (back x, front x, half width) on the closed lid: under the top bezel, as wide as the side
    bezels allow unless the lid is too shallow for its aspect; the rest is the chin over the hinge."""
    x1 = b.D / 2 - bezel
    half = b.W / 2 - bezel
    h = min(2 * half * DISPLAY_ASPECT[aspect], x1 - b.x_back - CHIN)
    return x1 - h, x1, h / DISPLAY_ASPECT[aspect] / 2


def lid(b: Laptop, aspect: str, bezel: float, mats: dict[str, str]) -> list[Piece]:
    """The closed lid: a rounded slab whose underside carries the bezel, the display and the webcam, a logo
    on its back."""
    z0, Tl = b.lid_z, b.Tl
    # weighed by its area (its panel and cover), not its volume: a shell that weighs LID_AREAL over its two faces
    shell = slab(rounded(b.W, b.D, b.r), z0 + 0.0004, z0 + Tl, min(0.0012, 0.2 * Tl), mats["body"]).replace(
        wall=LID_AREAL / (2 * LAPTOP_DENSITY))
    frame = _solid(slab(rounded(b.W - 0.002, b.D - 0.002, max(b.r - 0.001, 0.001)), z0 + 0.0001, z0 + 0.0006,
                        0.0001, mats["bezel"]))
    xd0, xd1, half = display_area(b, aspect, bezel)
    screen = g.box_between((xd0, -half, z0), (xd1, half, z0 + 0.0004), mats["display"])
    xc = (xd1 + b.D / 2) / 2
    cam = g.cylinder((xc, 0, z0 - 0.0001), (xc, 0, z0 + 0.0003), min(0.0015, 0.3 * (b.D / 2 - xd1)),
                     mats["display"])
    lip = (b.D / 2 - 0.003, -LIP["width"] / 2, z0 + 0.0004), (b.D / 2 + LIP["reach"], LIP["width"] / 2, z0 + Tl)
    tab = _solid(g.box_between(*lip, mats["body"], bevel=0.35 * (Tl - 0.0004)))
    # fingers pinch the lip across its thickness from the front, short of the base's front face
    tab = tab.with_grasps(Grasp.make((lip[1][0], 0.0, (lip[0][2] + lip[1][2]) / 2), (-1, 0, 0), (0, 0, 1),
                                     lip[1][2] - lip[0][2], LIP["grip"]))
    logo = g.cylinder((0.0, 0.0, z0 + Tl - 0.0002), (0.0, 0.0, z0 + Tl + 0.0002), 0.08 * b.D / 2, mats["logo"])
    return [shell, tab, frame, screen, Piece(cam.vertices, cam.faces, cam.material),
            Piece(logo.vertices, logo.faces, logo.material)]


def hinge(b: Laptop, material: str, convertible: bool) -> tuple[list[Piece], Frame]:
    """The lid's hinge: a barrel along its back edge (a clamshell's hinge cover) or two knuckles near the
    corners (a convertible's 360-degree hinges), about the hinge axis, and that axis (z along -y: the lid's
    front edge rises)."""
    z, r = b.lid_z + b.Tl / 2, b.Tl / 2 - 0.0001
    if convertible:
        yc, w = b.W / 2 - HINGE_KNUCKLE["inset"] * b.W, HINGE_KNUCKLE["width"] / 2
        spans = [(s * yc - w, s * yc + w) for s in (-1, 1)]
    else:
        spans = [(-HINGE_COVER * b.W, HINGE_COVER * b.W)]
    return ([_solid(g.cylinder((b.x_back, y0, z), (b.x_back, y1, z), r, material)) for y0, y1 in spans],
            Frame.at((b.x_back, 0.0, z), z=(0, -1, 0)))
