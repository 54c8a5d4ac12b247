"""Computer monitor parts: a flat panel with a rear housing, its tilt head, and three carriers (a fixed stand,
a height-adjustable stand with a swivel base, a desk-mounted arm).

World frame: the screen faces +x, y across, z up; the panel's front face is x = 0. The tilt barrel sits behind
the VESA plate (as :mod:`.displays` builds a TV's); its fork is :func:`.displays.fork`.

Sizes of real monitors and stands, each beside its source (manufacturers' spec sheets):
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.piece import Piece

from . import displays as S
from .laptops import rounded
from .tables import slab

GAP = S.GAP
WIDTH = (0.4953, 0.7170)
"""m, panel width without the stand: 21.5 in (Dell SE2222H 495.3 mm) to 32 in (Samsung S32A600 717 mm)."""
HEIGHT_RATIO = (0.585, 0.6)  # panel height / width, 16:9 with bezels: Dell P2422H 324 / 537.8, U2723QE 356 / 611
PANEL = (0.010, 0.018)  # m, the panel's thickness at its edge (Dell P2422H ~11 mm, budget panels ~18 mm)
HOUSING = (0.025, 0.04)  # m, the rear housing (electronics, VESA mount) behind it: total 40-60 mm deep
MONITOR_DENSITY = 650.0
"""kg/m^3 the drawn head (panel and housing, solid) weighs: its mass over its face is 13-18 kg/m^2 (Dell P2422H
panel 3.2 kg over 538 x 324 mm: 18; Dell S2721HN 2.6 kg over 612 x 364 mm: 12), over its ~25 mm of drawn
solid thickness."""
TILT = math.radians(21)  # the top tilts back 0-21 degrees (Dell P2422H, S2721HN: -5/+21; the forward 5 left out)
SWIVEL = math.radians(45)  # Dell P2422H stand: +-45 degrees
HEIGHT_TRAVEL = (0.1, 0.13)  # m, height-adjustable stands: Dell P2422H 130 mm, HP E24 G5 150 mm -> 100-130
PIVOT = math.pi / 2  # portrait pivot: 90 degrees (Dell P2422H: +-90; one way drawn)
BARREL = (0.008, 0.05)  # m, the tilt barrel's radius and length
VESA = 0.1  # m, VESA MIS-D 100 x 100 mm plate
VESA_T = 0.004
BASE = dict(width=(0.2, 0.26), depth=(0.16, 0.2), t=(0.012, 0.02))  # P2422H base 196 x 167 mm; S2721HN ~ 240
COLUMN = (0.06, 0.035)  # m, a height-adjustable column's width and depth (P2422H ~ 64 x 38 mm)
CARRIAGE = (0.07, 0.11)  # m, the carriage's width and height on the column
ARM = dict(post=(0.016, 0.34), link=(0.2, 0.3), beam=(0.045, 0.03), plate=(0.12, 0.1, 0.01), swing=(
    math.radians(90), math.radians(150)))
"""A desk-mounted arm (Ergotron LX: 340 mm pole, 2 links reaching 640 mm; 1-3 links across makers):
post radius and height, link length range, beam height and width, the desk plate (x, y, thickness), the
swing of the first link and of the elbow (+- rad)."""


@dataclass(frozen=True)
class Head:
    """A monitor's head at rest: ``W`` wide, ``H`` tall, centre height ``zc``; the panel from x = -``tp`` to 0,
    the housing back at ``xh``; the tilt pivot (``xp``, ``zp``)."""

    W: float
    H: float
    tp: float
    xh: float
    zc: float
    xp: float
    zp: float
    pivot: bool

    @property
    def z0(self) -> float:
        return self.zc - self.H / 2


def head(W: float, ratio: float, panel: float, housing: float, z0: float, pivot: bool) -> Head:
    """The head's sizes and where its pivot goes: the tilt pivot behind the VESA plate (and the portrait pivot's
    gap) at the housing's middle height."""
    H = W * ratio
    xh = -panel - housing
    r = BARREL[0]
    xp = xh - VESA_T - (GAP if pivot else 0.0) - 1.3 * r - GAP - 0.002
    zc = z0 + H / 2
    return Head(W, H, panel, xh, zc, xp, zc - 0.05 * H, pivot)


def _upright(outline_x: float, outline_y: float, r: float, x0: float, x1: float, zc: float, material: str) -> Piece:
    """A slab standing up: a rounded ``outline_y`` (y) x ``outline_x`` (z) outline, from x0 to x1, centred at zc."""
    flat = slab(rounded(outline_y, outline_x, r), 0.0, x1 - x0, min(0.002, 0.25 * (x1 - x0)), material)
    # local (u, v, w) -> world (x0 + w, v, zc - u): a proper rotation (u along z, w along x)
    m = np.array([[0, 0, 1, x0], [0, 1, 0, 0], [-1, 0, 0, zc], [0, 0, 0, 1]], float)
    return flat.transformed(m)


def panel(h: Head, bezel: float, mats: dict[str, str]) -> list[Piece]:
    """The panel (rounded, the bezel's colour), its display and the rear housing."""
    hw, hh = 0.6 * h.W, 0.62 * h.H
    body = _upright(h.H, h.W, 0.006, -h.tp, 0.0, h.zc, mats["bezel"]).replace(wall=0.0)
    housing = _upright(hh, hw, 0.03, h.xh, -h.tp + 0.001, h.zc - 0.04 * h.H, mats["body"]).replace(wall=0.0)
    disp = g.box_between((-0.0005, -h.W / 2 + bezel, h.z0 + bezel + 0.012),
                         (0.0004, h.W / 2 - bezel, h.z0 + h.H - bezel), mats["display"])
    return [body, housing, Piece(disp.vertices, disp.faces, disp.material)]


def tilt_head(h: Head, material: str) -> tuple[list[Piece], Frame]:
    """The VESA plate and the tilt barrel behind it, and the tilt axis (about -y: the top goes back)."""
    r, L = BARREL
    x1 = h.xh - (GAP if h.pivot else 0.0)
    plate = g.box_between((x1 - VESA_T, -VESA / 2, h.zp - VESA / 2), (x1 + (0.0 if h.pivot else 0.001), VESA / 2,
                                                                       h.zp + VESA / 2), material, bevel=0.001)
    web = g.box_between((h.xp, -L / 2, h.zp - 0.6 * r), (x1 - VESA_T + 0.001, L / 2, h.zp + 0.6 * r), material)
    barrel = g.cylinder((h.xp, -L / 2, h.zp), (h.xp, L / 2, h.zp), r, material)
    return [plate, web, barrel], Frame.at((h.xp, 0.0, h.zp), z=(0, -1, 0))


def pivot_axis(h: Head) -> Frame:
    """The portrait pivot: through the VESA plate's centre, about -x (seen from the front the screen turns
    clockwise: its left side, where the keys are not, goes down; the keys' side rises, so their weight keeps it
    on its landscape stop)."""
    return Frame.at((h.xh - GAP / 2, 0.0, h.zp), z=(-1, 0, 0))


def pivot_boss(h: Head, material: str) -> Piece:
    """The pivot's bearing boss on the housing's back (the screen turns on it)."""
    return g.cylinder((h.xh - 0.0005, 0, h.zp), (h.xh + 0.001, 0, h.zp), 0.045, material)


def fork(h: Head, material: str) -> list[Piece]:
    return S.fork(h.xp, h.zp, BARREL[0], BARREL[1], material)


def fork_bottom(h: Head) -> float:
    return S.fork_bottom(h.zp, BARREL[0])


def base(shape: str, h: Head, width: float, depth: float, t: float) -> Piece:
    """The stand's base plate under the screen, its centre a little in front of the column."""
    return S.base_plate(shape, width, depth, t, h.xp, h.xp + 0.3 * depth).replace(material="stand")


def neck(h: Head, t: float, material: str) -> Piece:
    """A fixed stand's neck: from the base up into the fork's bridge, behind the barrel."""
    x1 = h.xp + 0.2 * BARREL[0]
    return g.box_between((x1 - 0.03, -0.025, t - 0.001), (x1, 0.025, fork_bottom(h) + 0.001), material, bevel=0.004)


def travel(h: Head, wanted: float) -> float:
    """A height-adjustable stand's travel: as wanted, but its column (the carriage's top and the travel) stays
    hidden behind the screen at rest, as real columns do."""
    return min(wanted, h.zc + h.H / 2 - (h.zp + 1.2 * BARREL[0]) - 0.005 - COLUMN_BELOW_TOP)


COLUMN_BELOW_TOP = 0.01  # m, a column's top under the screen's top at rest


def column(h: Head, t: float, travel: float, material: str) -> tuple[list[Piece], list[Piece], Frame]:
    """A height-adjustable stand: the column (on the base), the carriage that slides up its front face carrying
    the tilt fork, and the slide (+z, rest at the bottom)."""
    cw, cd = COLUMN
    plate = 0.008  # the carriage plate, between the column's face and the fork's back plate
    xf = h.xp - 1.3 * BARREL[0] - S.FORK_T - plate - GAP  # the column's front face
    zc0, zc1 = fork_bottom(h) - CARRIAGE[1] + 0.02, h.zp + 1.2 * BARREL[0]
    col = g.box_between((xf - cd, -cw / 2, t - 0.001), (xf, cw / 2, zc1 + travel + 0.005), material, bevel=0.006)
    carriage = [g.box_between((xf + GAP, -CARRIAGE[0] / 2, zc0), (xf + GAP + plate + 0.001, CARRIAGE[0] / 2, zc1),
                              material)]
    return [col], carriage + fork(h, material), Frame.at((xf, 0.0, zc0), z=(0, 0, 1))


def swivel_axis(h: Head, t: float) -> Frame:
    return Frame.at((h.xp - 0.04, 0.0, t), z=(0, 0, 1))


def arm_layout(h: Head, n: int, link: float) -> tuple[list[float], list[float]]:
    """A desk-mounted arm of ``n`` links ``link`` long, straight back from the head: the joints' x (post,
    elbows) and the links' heights, the last at the tilt pivot's, each below a beam and a gap lower."""
    x_head = h.xp - 1.3 * BARREL[0] - S.FORK_T
    xs = [x_head - link * (n - k) for k in range(n)] + [x_head]
    zs = [h.zp - (n - 1 - k) * (ARM["beam"][0] + GAP) for k in range(n)]
    return xs, zs


def arm_post(x: float, top: float, material: str) -> list[Piece]:
    px, py, pt = ARM["plate"]
    r = ARM["post"][0]
    return [g.box_between((x - px / 2, -py / 2, 0.0), (x + px / 2, py / 2, pt), material, bevel=0.003),
            g.cylinder((x, 0, pt - 0.001), (x, 0, top), r, material)]


def arm_link(x0: float, x1: float, z: float, last: bool, h: Head, material: str) -> list[Piece]:
    """One arm link: a barrel round the joint at ``x0``, a beam to ``x1`` (the next barrel, or the tilt fork)."""
    bh, bw = ARM["beam"]
    r = ARM["post"][0] + 0.006
    pieces = [g.cylinder((x0, 0, z - bh / 2), (x0, 0, z + bh / 2), r, material),
              g.box_between((x0, -bw / 2, z - bh / 2), (x1 + (0.001 if last else -r), bw / 2, z + bh / 2), material,
                            bevel=0.004)]
    if last:
        pieces += fork(h, material)
    return pieces


BUTTON = dict(size=(0.006, 0.004, 0.008), pitch=0.018, from_bottom=0.04, gap=0.0025, travel=0.0015)
"""On-screen-display keys on the panel's right edge near its bottom (HP E24 G4, ASUS ProArt: 4-5 side keys):
6 mm deep, 8 mm tall, 18 mm apart, pressed 1.5 mm into the edge (a sideways press: gravity neither returns
nor opens them)."""


def button(h: Head, k: int, material: str) -> tuple[Piece, Frame]:
    """OSD key ``k`` beside the panel's right edge (-y), and its press (+y: into the edge)."""
    b = BUTTON
    sx, sy, sz = b["size"]
    z = h.z0 + b["from_bottom"] + k * b["pitch"]
    x = -h.tp / 2
    face = -h.W / 2 - b["gap"]
    key = g.box_between((x - sx / 2, face - sy, z - sz / 2), (x + sx / 2, face, z + sz / 2), material, bevel=0.001)
    return key, Frame.at((x, face - sy, z), z=(0, 1, 0))
