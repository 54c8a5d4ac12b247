"""Stand mixers: the base, pedestal and motor head, the bowl, its beaters and the small controls of each design.

Everything is built in the mixer's frame: the front (the bowl, the head's attachment hub) toward +X, Y across,
Z up, the back of the pedestal at x = -length / 2, the base on z = 0. Each moving part is returned with the
frame its joint turns or slides about (z the axis, a positive move opens: the head tilts back, the bowl turns
out of its lock, the cradle rises, a lever swings, a button presses in).

Designs (real product types; sizes below with their sources):

* ``tilt_head``: a die-cast pedestal whose motor head tilts back on a hinge pin to free the beater
  (KitchenAid Artisan and Classic); the bowl twists into a clamp plate on the base; a speed lever on the
  head's left side, a head lock lever on the pedestal's right side.
* ``bowl_lift``: a taller pedestal with the head fixed on it; the bowl hangs on a cradle (two arms) that a
  handle on the pedestal's right side raises to the beater (KitchenAid Professional 5 Plus, Pro 600).
* ``turntable``: a plastic tilt-head mixer with two beaters off the bowl's axis and the bowl on a turntable
  that the beaters drag round (Sunbeam Mixmaster, Hamilton Beach 64650); a speed dial on top of the head and
  a beater-eject button.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from . import controls
from .appliance import CLEAR
from .vessel import Profile


@dataclass(frozen=True)
class Design:
    """A stand mixer design: overall ``length`` (X), ``width`` (Y), ``height`` (Z) ranges (m), the housing's
    die-cast or moulded ``wall`` (m), the motor's mass (kg) and how many beaters the head drives."""

    length: tuple[float, float]
    width: tuple[float, float]
    height: tuple[float, float]
    wall: float
    motor: float
    beaters: int

    def at(self, t: float) -> tuple[float, float, float]:
        return tuple(lo + t * (hi - lo) for lo, hi in (self.length, self.width, self.height))


# Manufacturer spec sheets (inches converted): KitchenAid Artisan KSM150 tilt-head 14.1 H x 8.7 W x 13.9 D in
# (35.8 x 22.1 x 35.3 cm), 10.9 kg; Artisan Mini KSM3311 12.3 x 7.2 x 12.4 in (31.2 x 18.3 x 31.5 cm), 7.4 kg;
# Professional 5 Plus KV25G0X bowl-lift 16.5 H x 10.4 W x 13.3 D in (41.9 x 26.4 x 33.8 cm), 11.8 kg; Pro 600
# KP26M1X 16.5 x 11.3 x 14.6 in (41.9 x 28.7 x 37.1 cm), 13.2 kg; Hamilton Beach 64650 turntable mixer
# ~13.5 H x 9.8 W x 13.9 D in (34 x 25 x 35 cm), ~3.6 kg; Sunbeam Mixmaster 2371 about the same (retailer
# listings). Housings: die-cast zinc 3-4 mm (KitchenAid "all-metal construction"), moulded ABS 2.5 mm;
# universal motors of 250-575 W about 1-1.6 kg (KitchenAid service parts listings); a turntable mixer's motor
# and its metal gear train about 1.2 kg.
DESIGNS = {
    "tilt_head": Design((0.315, 0.355), (0.183, 0.222), (0.31, 0.36), 0.004, 1.3, 1),
    "bowl_lift": Design((0.338, 0.371), (0.264, 0.287), (0.41, 0.42), 0.003, 1.6, 1),
    "turntable": Design((0.33, 0.36), (0.22, 0.26), (0.32, 0.35), 0.003, 1.2, 2),
}
ZINC = 6600.0  # kg/m^3, die-cast zinc alloy (ZAMAK 3, 6.6 g/cm^3: Eastern Alloys data sheet)
MOTOR_DENSITY = 7850.0  # steel laminations and copper windings, massed as steel

BASE_H = 0.12  # the base plate's height as a share of the overall height
HEAD_R = 0.2  # the motor head's radius as a share of the overall height (Artisan: 7 cm of 35.8 cm)
COLUMN_D = 0.28  # the pedestal's depth (X) as a share of the length
GAP = 0.003  # m, between the head and the pedestal's top, the bowl and what carries it
BOWL_SHEET = {"stainless": 0.0006, "glass": 0.005}  # m: 0.6 mm stainless spun bowl, 5 mm pressed glass
BOWL_WALL = 0.003  # m, the bowl's wall as the simulator sees it
BEATER_CLEAR = 0.015  # m, the beater's edge off the bowl at rest (the real 2-4 mm let contacts stall a turning bowl)
HEAD_TILT = math.radians(65)  # a tilt head opens to about 60-70 degrees
BOWL_TWIST = math.radians(40)  # a tilt-head bowl turns about an eighth of a turn out of its clamp plate
CRADLE_LIFT = 0.035  # m, the bowl-lift cradle raises the bowl 3-4 cm to the beater
LIFT_HANDLE_TURN = math.radians(100)
PIN = 0.01  # m, the bowl-lift bowl's brackets drop over the cradle's 10 mm locating pins
LEVER = (0.035, 0.008, 0.006)  # m, speed or lock lever paddle: length, height, thickness (product photos)
LEVER_TURN = math.radians(50)  # the speed lever's arc from off to 10; the lock lever's throw is shorter
LOCK_TURN = math.radians(35)
DIAL = controls.Dial(radius=0.022, stem=0.005, style="ridge", turns=math.radians(270))
BUTTON = controls.Button(half=(0.012, 0.008), shape="rect", proud=0.006, travel=0.004)
HUB_KNOB = 0.014  # m, the attachment hub's thumbscrew radius
OFF = 0.0015  # m, a lever's boss stands this far off the housing (its pivot pin is inside)


@dataclass(frozen=True)
class Mixer:
    """Where a mixer's parts go: length, width, height, the head's axis height ``zc`` and radius ``rh``, the
    base's top, the pedestal's front and top, the bowl's axis ``xb``, its bottom ``zb``, rim ``zr`` and top
    radius ``rb``."""

    design: str
    length: float
    width: float
    height: float
    zc: float
    rh: float
    base_top: float
    col_front: float
    col_top: float
    xb: float
    zb: float
    zr: float
    rb: float

    @property
    def back(self) -> float:
        return -self.length / 2


def mixer(design: str, t: float) -> Mixer:
    """The layout of ``design`` at ``t`` of its size range."""
    length, width, height = DESIGNS[design].at(t)
    rh = HEAD_R * height
    zc = height - rh
    base_top = BASE_H * height
    col_front = -length / 2 + COLUMN_D * length
    col_top = zc - rh - GAP
    rb = 0.46 * width if design == "tilt_head" else 0.42 * width
    xb = col_front + rb + (0.035 if design == "bowl_lift" else 0.012)
    zb = base_top + (GAP if design == "bowl_lift" else 0.01)
    zr = col_top - 0.004 - (CRADLE_LIFT if design == "bowl_lift" else 0.0)
    return Mixer(design, length, width, height, zc, rh, base_top, col_front, col_top, xb, zb, zr, rb)


def _box(lo, hi, slot: str, wall: float, bevel: float) -> g.Piece:
    return g.box_between(lo, hi, slot, bevel=bevel).replace(wall=wall)


def body(m: Mixer, slot: str, foot_slot: str, motor_slot: str) -> list[g.Piece]:
    """The base plate, the pedestal and (on a bowl-lift mixer, where it does not move) the motor head, the
    rubber feet and a bowl-lift's motor; a tilt head carries its own motor (:func:`head`)."""
    d = DESIGNS[m.design]
    w_base, w_col = 0.78 * m.width if m.design != "tilt_head" else 0.72 * m.width, 0.5 * m.width
    front = m.xb + 0.75 * m.rb
    pieces = [_box((m.back, -w_base / 2, 0.004), (front, w_base / 2, m.base_top), slot, d.wall, 0.3 * m.base_top),
              _box((m.back, -w_col / 2, m.base_top - 0.01), (m.col_front, w_col / 2, m.col_top), slot, d.wall,
                   0.02)]
    pieces += [g.box_between((x - 0.015, y - 0.015, 0), (x + 0.015, y + 0.015, 0.005), foot_slot)
               for x in (m.back + 0.03, front - 0.04) for y in (-w_base / 2 + 0.025, w_base / 2 - 0.025)]
    if m.design == "bowl_lift":
        pieces += head_shell(m, slot, motor_slot)
    else:  # the clamp plate the bowl turns in, or the turntable's hub
        pieces.append(g.disc((m.xb, 0, m.base_top + 0.003), 0.45 * m.rb, 0.006, "trim"))
    return pieces


def _head_profile(m: Mixer) -> tuple[float, list[tuple[float, float]]]:
    """The head's back end x0 and its (radius, distance from x0) profile: a domed back, the widest over the
    pedestal, tapering to a blunt nose round the hub."""
    r, x0, x1 = m.rh, m.back + 0.004, m.length / 2 - 0.02
    span = x1 - x0
    return x0, [(0.0, 0.0), (0.62 * r, 0.1 * r), (0.9 * r, 0.38 * r), (r, 0.9 * r), (0.97 * r, 0.5 * span),
                (0.82 * r, span - 0.3 * r), (0.62 * r, span - 0.06 * r), (0.0, span)]


def head_radius(m: Mixer, x: float) -> float:
    """The head's radius at ``x`` (its housing's profile)."""
    x0, prof = _head_profile(m)
    return float(np.interp(x - x0, [s for _, s in prof], [r for r, _ in prof]))


def head_shell(m: Mixer, slot: str, motor_slot: str) -> list[g.Piece]:
    """The motor head: a rounded housing along X from the pedestal's back to the front, the attachment hub
    on its nose, the planetary's drive under its front over the bowl, the motor inside and, on a turntable
    mixer, the control plinth on its top (:func:`plinth`)."""
    d, r = DESIGNS[m.design], m.rh
    x0, prof = _head_profile(m)
    x1 = x0 + prof[-1][1]
    along = Frame.at((x0, 0, m.zc), z=(1, 0, 0), x=(0, 0, 1))
    housing = g.revolve(prof, slot).transformed(along.matrix).replace(wall=d.wall)
    hub = g.cylinder((x1 - 0.002, 0, m.zc), (x1 + 0.02, 0, m.zc), 0.045 * m.height, "trim", 32)
    xd = m.xb if d.beaters == 1 else m.xb - 0.3 * m.rb
    drive = g.cylinder((xd, 0, m.zc - 0.6 * r), (xd, 0, m.zc - r - 0.012), 0.045, "trim", 24)
    motor_r = (d.motor / MOTOR_DENSITY / (math.pi * 1.4 * r)) ** 0.5  # a motor 1.4 head radii long
    motor = g.cylinder((x0 + 0.2 * r, 0, m.zc), (x0 + 1.6 * r, 0, m.zc), motor_r, motor_slot, 24).replace(wall=0.0)
    pieces = [housing, hub, drive, motor]
    if m.design == "turntable":
        pieces.append(plinth(m, slot))
    return pieces


PLINTH = (0.2, 0.55, 0.024, 0.012)  # the plinth from 0.2 to 0.55 of the length, 24 mm wide, 12 mm proud


def plinth(m: Mixer, slot: str) -> g.Piece:
    """A turntable mixer's control plinth along the head's top: a moulded rib with the dial's and the eject
    button's holes, tall enough that neither reaches the housing below it."""
    xa, xb = (m.back + f * m.length for f in PLINTH[:2])
    top = plinth_top(m)
    low = m.zc + min(head_radius(m, xa), head_radius(m, xb)) - 0.01
    holes = []
    for at, (du, dv) in ((dial_anchor(m), (DIAL.stem, DIAL.stem)), (eject_anchor(m), BUTTON.half)):
        x = float(at.origin[0])
        holes.append((x - dv - CLEAR, -du - CLEAR, x + dv + CLEAR, du + CLEAR))
    return g.panel((xa, -PLINTH[2], low), (xb, PLINTH[2], top), slot, "z", holes)


def plinth_top(m: Mixer) -> float:
    x = m.back + 0.5 * (PLINTH[0] + PLINTH[1]) * m.length
    return m.zc + head_radius(m, x) + PLINTH[3]


def hub_anchor(m: Mixer) -> Frame:
    """The attachment hub's face (z out of it, +X): where its thumbscrew turns."""
    return Frame.at((m.length / 2, 0, m.zc), z=(1, 0, 0), x=(0, 0, 1))


def hub_knob(m: Mixer, slot: str) -> list[g.Piece]:
    """The hub's thumbscrew: a knurled knob on a short stem."""
    x = m.length / 2 + 0.001
    return [g.cylinder((x, 0, m.zc), (x + 0.012, 0, m.zc), HUB_KNOB, slot, 24),
            g.box_between((x + 0.012, -0.003, m.zc - 0.9 * HUB_KNOB), (x + 0.022, 0.003, m.zc + 0.9 * HUB_KNOB),
                          slot, bevel=0.001)]


def head(m: Mixer, slot: str, motor_slot: str) -> tuple[list[g.Piece], Frame]:
    """A tilting head and its hinge pin (:func:`head_pin`)."""
    return head_shell(m, slot, motor_slot), head_pin(m)


def head_pin(m: Mixer) -> Frame:
    """The tilt head's hinge pin at the pedestal's back top (axis -Y: the front lifts)."""
    return Frame.at((m.back + 0.35 * m.rh, 0, m.col_top), z=(0, -1, 0))


def bowl_profile(m: Mixer) -> Profile:
    """The bowl's wall: a round-bottomed bowl from its foot to its rolled rim."""
    h, rb, z = m.zr - m.zb, m.rb, m.zb
    ctrl = [(0.5 * rb, z), (0.72 * rb, z + 0.12 * h), (0.92 * rb, z + 0.5 * h), (rb, z + h)]
    return Profile.through(ctrl, BOWL_WALL, (48, 8))


def bowl(m: Mixer, slot: str, sheet: float, handle_slot: str) -> list[g.Piece]:
    """The bowl: its wall, its floor and a loop handle on its +Y side (a tilt-head bowl) or two
    brackets that drop over the cradle's pins (bowl-lift)."""
    prof = bowl_profile(m)
    pieces = [prof.wall(slot, sheet=sheet).translated((m.xb, 0, 0)),
              g.disc((m.xb, 0, m.zb + BOWL_WALL / 2), prof.base_radius - 0.001, BOWL_WALL, slot).replace(sheet=sheet)]
    z_top = m.zr - 0.02
    r_top = float(prof.fine[:, 0][abs(prof.fine[:, 1] - z_top).argmin()])
    if m.design == "bowl_lift":
        za = cradle_height(m) + 0.006 + 0.004
        ra = _bowl_r(prof, za)
        for s in (-1, 1):
            y0, y1 = sorted((s * (ra - 0.003), s * (ra + 0.022)))
            pieces.append(g.box_between((m.xb - 0.015, y0, za), (m.xb + 0.015, y1, za + 0.006), handle_slot))
    elif m.design == "tilt_head":  # a turntable bowl has no handle: it spins past the pedestal
        zl = m.zb + 0.45 * (m.zr - m.zb)
        rl = _bowl_r(prof, zl)
        path = [(m.xb, r_top - 0.003, z_top), (m.xb, r_top + 0.03, z_top - 0.01), (m.xb, r_top + 0.035, zl + 0.02),
                (m.xb, rl - 0.003, zl)]
        pieces.append(g.tube(path, 0.006, handle_slot))
    return pieces


def _bowl_r(prof: Profile, z: float) -> float:
    return float(prof.fine[:, 0][abs(prof.fine[:, 1] - z).argmin()])


def bowl_axis(m: Mixer) -> Frame:
    """The bowl's axis at its foot (z up: a twist about it turns the bowl out of its lock)."""
    return Frame.at((m.xb, 0, m.zb))


def beaters(m: Mixer, slot: str) -> list[g.Piece]:
    """A flat beater on the planetary shaft (one beater) or two wire beaters off the bowl's axis, their edges
    :data:`BEATER_CLEAR` off the bowl at rest (a bowl-lift bowl is lowered: at the top of its lift)."""
    prof, lift = bowl_profile(m), CRADLE_LIFT if m.design == "bowl_lift" else 0.0
    top, z0 = m.zc - m.rh - 0.012, m.zb + lift + BEATER_CLEAR + BOWL_WALL
    if DESIGNS[m.design].beaters == 1:
        zm = z0 + 0.45 * (m.zr + lift - z0)
        for k in (1.0, 0.85, 0.7, 0.55, 0.4):  # the widest beater that swings out of the bowl as the head tilts
            half_low = k * (_bowl_r(prof, z0 + 0.02 - lift) - BEATER_CLEAR - 0.01)
            half_mid = k * (_bowl_r(prof, zm - lift) - BEATER_CLEAR - 0.01)
            loop = [(m.xb, 0, zm + 0.02), (m.xb, -half_mid, zm), (m.xb, -half_low, z0 + 0.02),
                    (m.xb, 0, z0 + 0.004), (m.xb, half_low, z0 + 0.02), (m.xb, half_mid, zm), (m.xb, 0, zm + 0.02)]
            if m.design == "bowl_lift" or _swings_clear(m, prof, loop):
                break
        return [g.cylinder((m.xb, 0, top + 0.005), (m.xb, 0, zm + 0.02), 0.006, slot, 16), g.tube(loop, 0.004, slot)]
    pieces = []
    for s in (-1, 1):
        x, y, rw = m.xb - 0.3 * m.rb, s * 0.028, 0.02
        zl = z0 + 0.05
        pieces.append(g.cylinder((x, y, top + 0.005), (x, y, zl + 0.05), 0.003, slot, 12))
        for a in (0.0, math.pi / 2):
            c, sn = rw * math.cos(a), rw * math.sin(a)
            pieces.append(g.tube([(x + c, y + sn, zl + 0.05), (x + c, y + sn, zl + 0.01), (x, y, zl - 0.01),
                                  (x - c, y - sn, zl + 0.01), (x - c, y - sn, zl + 0.05)], 0.0015, slot))
    return pieces


def _swings_clear(m: Mixer, prof: Profile, points) -> bool:
    """Whether ``points`` of the head (a beater's outline) stay :data:`BEATER_CLEAR` inside the bowl's wall,
    or over its rim, all the way through the head's tilt about its hinge pin."""
    pin = head_pin(m)
    p = np.asarray(points, float)
    inner = prof.fine - [BOWL_WALL + BEATER_CLEAR, 0.0]
    for a in np.linspace(0.0, HEAD_TILT, 14):
        q = pin.turned("z", a).point(pin.local(p)) if a else p
        below = q[:, 2] < m.zr
        r = np.hypot(q[:, 0] - m.xb, q[:, 1])
        room = np.interp(q[:, 2], inner[:, 1], inner[:, 0])
        if (below & (r > room)).any():
            return False
    return True


def side_lever(m: Mixer, at: tuple[float, float], side: int, slot: str) -> tuple[list[g.Piece], Frame]:
    """A small lever on a side face (``side`` +1 left (+Y), -1 right) at ``(x, z)``: a boss and a paddle
    pointing back, turning about the face's normal (the front of the paddle rises)."""
    x, z = at
    y = side * _side_y(m, x, z)
    ln, h, th = LEVER
    y0, y1 = sorted((y + side * 0.006, y + side * (0.006 + th)))
    pieces = [g.cylinder((x, y + side * OFF, z), (x, y + side * 0.01, z), 0.007, slot, 16),
              g.box_between((x - ln, y0, z - h / 2), (x, y1, z + h / 2), slot, bevel=0.002)]
    return pieces, Frame.at((x, y, z), z=(0, -side, 0))


def _side_y(m: Mixer, x: float, z: float) -> float:
    """The half width of the housing at ``(x, z)``: the head's round section or the pedestal's side."""
    if z > m.col_top:  # the widest of the head's section over the boss's height
        r, dz = head_radius(m, x), max(abs(z - m.zc) - 0.007, 0.0)
        return math.sqrt(max(r ** 2 - dz ** 2, 0.0))
    return 0.25 * m.width


def speed_lever_at(m: Mixer) -> tuple[float, float]:
    """On the head's left side near its back (KitchenAid's speed control)."""
    return m.back + 0.3 * m.length, m.zc - 0.15 * m.rh


def lock_lever_at(m: Mixer) -> tuple[float, float]:
    """On the pedestal's right side under the head (KitchenAid's head lock)."""
    return m.col_front - 0.01, m.col_top - 0.03


def lift_handle(m: Mixer, slot: str, knob_slot: str) -> tuple[list[g.Piece], Frame]:
    """The bowl-lift handle on the pedestal's right side: an arm pointing back and down from a pivot boss,
    a ball on its end; it turns about +Y (its end rises) and the cradle follows it."""
    x, z, y = m.col_front - 0.04, m.base_top + 0.45 * (m.col_top - m.base_top), -0.25 * m.width
    end = (x - 0.07, y - 0.02, z - 0.035)
    pieces = [g.cylinder((x, y - OFF, z), (x, y - 0.014, z), 0.012, slot, 20),
              g.tube([(x, y - 0.012, z), (x - 0.03, y - 0.018, z - 0.015), end], 0.005, slot),
              g.sphere(end, 0.012, knob_slot)]
    return pieces, Frame.at((x, y, z), z=(0, 1, 0))


def cradle_height(m: Mixer) -> float:
    """The cradle arms' height at rest (the bowl's upper third)."""
    return m.zb + 0.62 * (m.zr - m.zb)


def cradle(m: Mixer, slot: str) -> tuple[list[g.Piece], Frame]:
    """The bowl-lift cradle: a carriage on the pedestal's front and two arms round the bowl's sides, each
    with a locating pin; it slides up (+Z)."""
    za, prof = cradle_height(m), bowl_profile(m)
    ra = _bowl_r(prof, za + 0.01) + 0.012
    pieces = [g.box_between((m.col_front + GAP, -0.2 * m.width, za - 0.03), (m.col_front + 0.015, 0.2 * m.width,
                                                                                za + 0.02), slot, bevel=0.004)]
    for s in (-1, 1):
        path = [(m.col_front + 0.01, s * 0.16 * m.width, za), (m.xb - 0.6 * m.rb, s * ra, za),
                (m.xb + 0.02, s * ra, za)]
        pins = g.cylinder((m.xb, s * ra, za), (m.xb, s * ra, za + 0.008), 0.003, slot, 12)
        pieces += [g.tube(path, 0.006, slot), pins]
    return pieces, Frame.at((m.col_front, 0, za))


def dial_anchor(m: Mixer) -> Frame:
    """The speed dial's hole in the plinth near the head's back (z up)."""
    return Frame.at((m.back + 0.27 * m.length, 0, plinth_top(m)), z=(0, 0, 1), x=(-1, 0, 0))


def eject_anchor(m: Mixer) -> Frame:
    """The beater-eject button's hole in the plinth, in front of the dial (z up)."""
    return Frame.at((m.back + 0.47 * m.length, 0, plinth_top(m)), z=(0, 0, 1), x=(-1, 0, 0))
