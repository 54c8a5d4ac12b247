"""Pepper and salt mills: a turned body holding its peppercorns (or salt), a grinding head or a battery cap on top,
a coarseness knob or ring, and a tray that holds a pair.

A mill stands on z = 0 centred on the z axis. Its body is a wall of revolution (:class:`~.vessel.Profile`) closed
by a foot and a top plate, with the grinding mechanism in its foot and its contents inside (massed: a mill is
sold and used full). Anchors: ``seat`` (the top plate's centre, z up: what sits on it lifts and turns about it),
``ring`` (the foot's centre, z up: a coarseness ring turns about it). Sizes per design are data (:data:`MILLS`),
each figure beside the products it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from .vessel import Profile, spline_profile


@dataclass(frozen=True)
class Mill:
    """One kind of mill: ``height`` and body ``radius`` ranges (m), the head's (or cap's) share of the height."""

    height: tuple[float, float]
    radius: tuple[float, float]
    head: float


# Peugeot Paris u'Select: 12, 18, 22, 30 cm tall, 5.0-6.3 cm across the foot, 0.15-0.45 kg (beech; maker's
# listings). Cole & Mason Derwent 19 cm, 6 cm across, ~0.4 kg (acrylic and stainless). Pairs on a tray: Cole & Mason
# / Peugeot gift sets, two 12-15 cm mills on a 16-20 x 7-9 cm wooden or steel tray. Battery mills: Cole & Mason
# Battersea 21 cm x 6 cm ~0.4 kg, Peugeot Elis Sense 20 cm ~0.55 kg (with 6 AAA cells).
MILLS = {"manual": Mill((0.14, 0.30), (0.024, 0.032), 0.2),
         "pair": Mill((0.12, 0.16), (0.021, 0.027), 0.2),
         "electric": Mill((0.18, 0.23), (0.026, 0.031), 0.22)}
# Body outlines, (radius share, height share) bottom to top: a Paris mill's foot, waist and shoulder; a straight
# column; a tapering column.
SHAPES = {"classic": ((1.0, 0.0), (1.0, 0.05), (0.8, 0.18), (0.74, 0.45), (0.86, 0.78), (0.9, 0.9), (0.8, 1.0)),
          "column": ((1.0, 0.0), (1.0, 0.5), (1.0, 1.0)),
          "taper": ((1.0, 0.0), (0.95, 0.4), (0.86, 1.0))}
# Walls as the simulator sees them (m): turned wood 5-8 mm; a steel or acrylic sleeve 3 mm (massed as the slot's
# family wall: 1.2 mm steel, 3.5 mm acrylic).
WALL = {"wood": 0.006, "lacquer": 0.006, "steel": 0.003, "acrylic": 0.003}
SHEET = {"steel": 0.0008}  # m, a steel sleeve's real gauge (0.6-1 mm stainless tube), what its wall is massed as
RING_SHEET = 0.0012  # m, a coarseness ring of pressed steel, massed as this sheet
# A battery mill's motor unit: 6 AAA cells (11.5 g each) and a geared motor (~60 g) (Peugeot Elis, Cole & Mason
# battery mill listings: 0.4-0.55 kg with cells, ~0.3 kg without), carried in the cap.
CELLS = dict(kg=0.13, share=0.7)
GAP = 0.0015  # m, between a head, cap or ring and the body
FOOT = 0.006  # m, the foot plate carrying the burr
BURR = 0.6  # the steel burr's radius, share of the body's
FILL = 0.75  # the contents fill this share of the body
RING = dict(height=0.014, reach=0.0015, neck=0.78, turns=math.radians(300))  # u'Select: 6 settings over ~300 deg
FINIAL = dict(radius=0.009, height=0.014, turns=math.radians(330))  # the coarseness nut atop a Paris mill
HEAD_LIFT = 0.03  # m, a head lifts off its spindle to refill (the core caps it at a hand's lift)
# Battery mills: the cap over the cells lifts off; a 10-14 mm push button on it presses 1.5-2 mm (switch travel).
BUTTON = dict(radius=0.009, height=0.007, travel=0.002)
FLIP = dict(thick=0.004, opens=math.radians(110), share=0.7)  # a pair mill's flip-top filler lid
TRAY = dict(thick=0.015, socket=0.008, margin=0.012, gap=0.012, wall=0.003)


def lerp(span: tuple[float, float], t: float) -> float:
    return span[0] + t * (span[1] - span[0])


@dataclass(frozen=True)
class Size:
    """One mill's sizes (m): total ``height``, body ``radius``, the body's height ``body``, wall, and whether a
    coarseness ring sits round its foot (the body then starts above the ring on a narrower neck)."""

    height: float
    radius: float
    body: float
    wall: float
    ring: bool
    sheet: float = 0.0

    @classmethod
    def make(cls, design: str, t: float, finish: str, ring: bool) -> Size:
        m = MILLS[design]
        h = lerp(m.height, t)
        return cls(h, lerp(m.radius, t), h * (1 - m.head), WALL[finish], ring, SHEET.get(finish, 0.0))

    @property
    def wall_from(self) -> float:
        return FOOT + RING["height"] + 2 * GAP if self.ring else 0.0


def body(s: Size, shape: str, slot: str, contents: str, metal: str) -> Assembly:
    """The body: its wall (``shape``), foot with the burr (``metal``), top plate, and contents (``contents``)."""
    z0, R = s.wall_from, s.radius
    ctrl = [(R * a, z0 + (s.body - z0) * b) for a, b in SHAPES[shape]]
    prof = Profile.through(ctrl, s.wall, (48, 8))
    r_in = prof.free_radius(z0, s.body) - 0.001
    neck = RING["neck"] * R
    pieces = [prof.wall(slot, sheet=s.sheet),
              g.disc((0, 0, FOOT / 2), R - s.wall / 2, FOOT, slot, None),
              g.disc((0, 0, FOOT + 0.002), BURR * R, 0.004, metal, None),
              g.disc((0, 0, s.body - 0.0015), min(r_in + 0.001, prof.top_radius - s.wall / 2), 0.003, slot, None)]
    if s.ring:
        pieces.append(g.cylinder((0, 0, 0), (0, 0, z0 + 0.002), neck, slot, None))
        pieces.append(g.disc((0, 0, z0 + 0.002), R - s.wall / 2, 0.004, slot, None))
    z_fill = z0 + 0.006
    pieces.append(g.cylinder((0, 0, z_fill), (0, 0, z_fill + FILL * (s.body - z_fill - 0.006)), r_in, contents, None))
    anchors = {"seat": Frame.at((0, 0, s.body)), "ring": Frame.at((0, 0, FOOT))}
    return Assembly.single("body", pieces, anchors, {f"s{k}": (R * math.cos(a), R * math.sin(a), 0.0)
                                                     for k, a in enumerate((0, 2.1, 4.2))})


def ring(s: Size, slot: str) -> Assembly:
    """The coarseness ring round the foot's neck (u'Select). Anchor ``axis`` (z up)."""
    neck, R = RING["neck"] * s.radius, s.radius + RING["reach"]
    z0 = FOOT + GAP
    band = g.shell([(R, z0), (R, z0 + RING["height"])], R - neck - GAP, slot).replace(sheet=RING_SHEET)
    return Assembly.single("knob", [band], {"axis": Frame.at((0, 0, z0))})


def head(s: Size, slot: str, flat: bool, label: str = "head") -> Assembly:
    """The grinding head on the body's top: a dome (a Paris mill's) or a flat-topped cap (``flat``: a pair mill's,
    carrying a flip lid). Anchors ``seat`` (its underside's centre, z up), ``top`` (its top's centre)."""
    z0, hh, R = s.body + GAP, s.height - s.body - GAP, s.radius * 0.95
    if flat:
        prof = [(0, z0), (R, z0), (R, z0 + 0.85 * hh), (0.92 * R, z0 + hh), (0, z0 + hh)]
    else:
        prof = [(0, z0), (0.92 * R, z0), (R, z0 + 0.3 * hh), (0.85 * R, z0 + 0.7 * hh), (0.45 * R, z0 + 0.95 * hh),
                (0, z0 + hh)]
    piece = g.revolve(_smooth(prof), slot)
    return Assembly.single(label, [piece], {"seat": Frame.at((0, 0, s.body)), "top": Frame.at((0, 0, z0 + hh))})


def finial(slot: str) -> Assembly:
    """The coarseness nut: a knurled knob on the head's top. Anchor ``axis`` (its underside's centre, z up)."""
    r, h = FINIAL["radius"], FINIAL["height"]
    prof = [(0, 0), (0.7 * r, 0), (r, 0.35 * h), (r, 0.6 * h), (0.6 * r, 0.9 * h), (0, h)]
    return Assembly.single("knob", [g.revolve(_smooth(prof), slot)], {"axis": Frame.at((0, 0, -GAP))})


def cap(s: Size, slot: str, cells: str) -> tuple[Assembly, float]:
    """A battery mill's cap: a rounded cylinder on the body's top carrying the motor and cells (``cells``, a solid
    slot). Anchors ``seat``, ``top``; returns it and the cells' volume (m^3), which the layout masses as
    :data:`CELLS`."""
    made = head(s, slot, flat=True, label="lid")
    z0, z1 = s.body + 2 * GAP, s.height - 0.004
    r = CELLS["share"] * s.radius
    return made.with_pieces(made.root, [g.cylinder((0, 0, z0), (0, 0, z1), r, cells, None)]), \
        math.pi * r * r * (z1 - z0)


def button(slot: str) -> Assembly:
    """The push button atop a battery mill's cap; anchor ``press`` (its underside, z down: pressed in)."""
    r, h = BUTTON["radius"], BUTTON["height"]
    piece = g.revolve([(0, 0), (r, 0), (r, 0.7 * h), (0.8 * r, h), (0, h)], slot)
    return Assembly.single("button", [piece], {"mount": Frame.at((0, 0, -GAP)),
                                               "press": Frame.at((0, 0, 0), z=(0, 0, -1), x=(1, 0, 0))})


def flip_lid(s: Size, slot: str) -> Assembly:
    """A pair mill's filler lid lying on the head's flat top, hinged at its back edge (anchor ``hinge``, z = -y: a
    positive turn lifts its front); anchor ``mount`` its underside's centre."""
    r, t = FLIP["share"] * s.radius, FLIP["thick"]
    plate = g.disc((0, 0, t / 2), r, t, slot, None)
    tab = g.box_between((r - 0.002, -0.004, 0), (r + 0.003, 0.004, t), slot)
    return Assembly.single("lid", [plate, tab], {"mount": Frame.at((0, 0, -0.0005)),
                                                 "hinge": Frame.at((-r, 0, 0), z=(0, -1, 0), x=(1, 0, 0))})


def tray(s: Size, slot: str) -> tuple[Assembly, list[Frame]]:
    """The tray holding a pair: a board with a socket ring per mill; returns it and the mills' frames (each a
    socket's floor centre, z up)."""
    t, R = TRAY, s.radius
    pitch = 2 * R + t["gap"]
    hx, hy = R + t["margin"], pitch / 2 + R + t["margin"]
    pieces = [g.box_between((-hx, -hy, 0), (hx, hy, t["thick"]), slot, bevel=0.004)]
    frames = []
    for k in (-1, 1):
        c = (0.0, k * pitch / 2, t["thick"])
        r_in = R + 1.5 * GAP
        pieces.append(g.shell([(r_in + t["wall"], c[2]), (r_in + t["wall"], c[2] + t["socket"])], t["wall"], slot,
                              center=(c[0], c[1], 0)))
        frames.append(Frame.at(c))
    return Assembly.single("base", pieces, {}, {f"c{i}": (x, y, 0) for i, (x, y) in
                                                enumerate(((-hx, -hy), (-hx, hy), (hx, -hy), (hx, hy)))}), frames


def _smooth(prof) -> list[tuple[float, float]]:
    """A closed revolve outline (axis to axis) with its outer run made a smooth spline through the given points."""
    fine, _ = spline_profile(prof[1:-1], n=24)
    return [tuple(prof[0]), *map(tuple, fine), tuple(prof[-1])]
