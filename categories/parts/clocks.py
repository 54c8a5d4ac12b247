"""Clocks: a wall clock, a mantel clock with its pendulum, a twin-bell alarm clock; their printed dials and hands.

Every clock faces +x: its dial lies in a y-z plane, 12 o'clock up (+z) and 3 o'clock to the right as you face it
(+y). Hands turn clockwise as seen from the front: about -x. A clock is built standing on z = 0 (a wall clock on its
rim: its back is the wall plane x = 0, as a switch's).

* ``wall``: a round moulded case, its dial recessed behind the rim; hands over the dial; a quartz movement's setting
  knob at the back.
* ``mantel``: a wooden case on a plinth under a cornice; the dial behind a hinged glass bezel; a pendulum swinging
  behind a window below the dial; a setting knob at the back.
* ``alarm``: a twin-bell alarm clock: a drum on two legs, two bells and a hammer on top, an alarm-off button between
  the bells; an alarm hand besides the time hands; time and alarm setting knobs at the back.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

# Sizes (m, kg). Wall clocks: 25-40 cm across, 4-5 cm deep, 0.4-1.2 kg (IKEA TROMMA 25 cm, Seiko QXA 30-35 cm,
# Howard Miller 625- series 30-40 cm; retailer listings). Mantel clocks: 22-36 cm wide, 22-34 cm tall, 10-15 cm
# deep, 1.5-4 kg (Howard Miller 630- / Hermle 22- series listings); pendulum swing +-3-5 degrees. Twin-bell alarm
# clocks: 9-12 cm dials, 15-18 cm tall with their bells, 0.2-0.45 kg (Peakeep, Acctim, Westclox twin-bell listings).
WALL = {"diameter": (0.25, 0.40), "depth": (0.04, 0.05), "rim": (0.008, 0.02)}
MANTEL = {"width": (0.22, 0.36), "height": (0.22, 0.34), "depth": (0.10, 0.15), "board": 0.01, "plinth": 0.02,
          "swing": math.radians(5)}
ALARM = {"radius": (0.05, 0.06), "depth": (0.045, 0.055), "legs": 0.025, "bell": 0.034}
# m, a round case's wall by its finish: a moulded ABS case 2 mm, a turned or MDF case 4-6 mm, spun aluminium or
# pressed steel 0.6-0.8 mm (a twin-bell alarm clock's drum)
CASE_WALL = {"plastic": 0.002, "wood": 0.006, "painted": 0.004, "brushed_metal": 0.0006, "chrome": 0.0006}
MARK = 0.0003  # m, how far printed marks stand off the dial (ink has no thickness; enough not to z-fight)
HAND = 0.0008  # m, a hand's blade thickness (stamped brass or aluminium 0.3-0.8 mm)
LAYER = 0.002  # m, from one hand's layer to the next along the arbor (1.2 mm clear between blades)
BEZEL_OPENS = math.radians(100)
BUTTON_TRAVEL = 0.003  # m, a twin-bell clock's alarm-off plunger


@dataclass(frozen=True)
class Clock:
    """A clock's dial: its ``centre`` (on the dial face), ``radius``; ``design``; the case's outer extents."""

    design: str
    centre: tuple[float, float, float]
    radius: float
    depth: float  # case depth along x
    width: float = 0.0  # mantel: case width (y) and height (z); alarm: drum radius in width
    height: float = 0.0

    def on_dial(self, r: float, theta: float, dx: float = 0.0) -> np.ndarray:
        """The point ``r`` from the centre at clock angle ``theta`` (0 at 12, clockwise), ``dx`` off the face."""
        x, y, z = self.centre
        return np.array((x + dx, y + r * math.sin(theta), z + r * math.cos(theta)))

    def arbor(self, dx: float = 0.0) -> Frame:
        """The hands' arbor: z along -x (a positive turn is clockwise from the front), ``dx`` off the face."""
        return Frame.at(self.on_dial(0.0, 0.0, dx), z=(-1, 0, 0), x=(0, 0, 1))


def _lerp(lo_hi, f: float) -> float:
    return lo_hi[0] + f * (lo_hi[1] - lo_hi[0])


def make(design: str, size: float, depth: float) -> Clock:
    """A clock of ``design`` at ``size`` and ``depth`` (0-1 through its ranges)."""
    if design == "wall":
        r_case = _lerp(WALL["diameter"], size) / 2
        d = _lerp(WALL["depth"], depth)
        rim = _lerp(WALL["rim"], 1 - size)
        return Clock(design, (d - 0.008, 0.0, r_case), r_case - rim, d, r_case)
    if design == "mantel":
        w, h, d = _lerp(MANTEL["width"], size), _lerp(MANTEL["height"], size), _lerp(MANTEL["depth"], depth)
        r = min(0.3 * w, 0.27 * h)
        return Clock(design, (d / 2 + 0.002, 0.0, h - MANTEL["board"] - 0.012 - r), r, d, w, h)
    rb, d = _lerp(ALARM["radius"], size), _lerp(ALARM["depth"], depth)
    return Clock(design, (d / 2 - 0.004, 0.0, ALARM["legs"] + rb), rb - 0.006, d, rb)


def _along_x(piece: g.Piece, at) -> g.Piece:
    """A piece built about +z moved so that its z axis runs along +x through ``at``."""
    return piece.transformed(Frame.at(at, z=(1, 0, 0), x=(0, 0, 1)).matrix)


# -- cases ---------------------------------------------------------------------------------------------------------
def case(c: Clock, slot: str, trim: str, finish: str) -> list[g.Piece]:
    """The clock's case in ``finish`` (a mantel clock's with its pendulum window, an alarm clock's with its legs,
    bells, hammer and the plunger's collar)."""
    if c.design == "wall":
        return _wall_case(c, slot, CASE_WALL[finish])
    if c.design == "mantel":
        return _mantel_case(c, slot)
    return _alarm_case(c, slot, trim, CASE_WALL[finish]) + [button_collar(c, trim)]


def _drum(rc: float, floor: float, front: float, r: float, slot: str, wall: float, at) -> list[g.Piece]:
    """A round case along +x from ``at``: a solid back up to the dial's ``floor`` and a rim to ``front`` whose lip
    comes in to the dial's radius ``r`` (a hollow ring: the hands turn inside it)."""
    back = g.revolve([(0.0, 0.0), (rc - 0.004, 0.0), (rc, 0.004), (rc, floor), (0.0, floor)], slot)
    rim = g.shell([(rc, floor), (rc, front - 0.004), (rc - 0.004, front)], rc - 0.004 - r, slot)
    return [_along_x(back.replace(wall=wall), at), _along_x(rim.replace(wall=wall), at)]


def _wall_case(c: Clock, slot: str, wall: float) -> list[g.Piece]:
    rc, d, r, xd = c.width, c.depth, c.radius, c.centre[0]
    return _drum(rc, xd - 0.002, d, r, slot, wall, (0.0, 0.0, rc))


def _mantel_case(c: Clock, slot: str) -> list[g.Piece]:
    w, h, d, t, p = c.width, c.height, c.depth, MANTEL["board"], MANTEL["plinth"]
    x0, x1, y0, y1 = -d / 2, d / 2, -w / 2, w / 2
    win = window(c)
    pieces = [
        g.box_between((x0 - 0.008, y0 - 0.008, 0.0), (x1 + 0.008, y1 + 0.008, p), slot, bevel=0.003),  # plinth
        g.box_between((x0 - 0.006, y0 - 0.006, h - t), (x1 + 0.006, y1 + 0.006, h), slot, bevel=0.003),  # cornice
        g.box_between((x0, y0, p), (x0 + t, y1, h - t), slot),  # back
        g.box_between((x0 + t, y0, p), (x1, y0 + t, h - t), slot),  # sides
        g.box_between((x0 + t, y1 - t, p), (x1, y1, h - t), slot),
        g.panel((x1 - t, y0 + t, p), (x1, y1 - t, h - t), slot, "x", [win]),  # front, its pendulum window
    ]
    return pieces


def window(c: Clock) -> tuple[float, float, float, float]:
    """A mantel clock's pendulum window in its front: (y0, z0, y1, z1)."""
    half = 0.28 * c.width
    z1 = c.centre[2] - c.radius - 0.02
    return (-half, MANTEL["plinth"] + 0.02, half, z1)


def _alarm_case(c: Clock, slot: str, trim: str, wall: float) -> list[g.Piece]:
    rb, d = c.width, c.depth
    xc, zc = 0.0, c.centre[2]
    x0 = xc - d / 2
    pieces = _drum(rb, c.centre[0] - x0 - 0.002, d, c.radius, slot, wall, (x0, 0.0, zc))
    for s in (-1, 1):  # two splayed legs with ball feet
        top = (xc, s * 0.55 * rb, zc - 0.8 * rb)
        foot = (xc, s * 0.85 * rb, 0.006)
        pieces += [g.cylinder(top, foot, 0.003, trim, 12), g.sphere(foot, 0.006, trim)]
    rbell = ALARM["bell"]
    for s in (-1, 1):  # the bells on their posts, tilted out
        a = math.radians(38)
        base = np.array((xc, s * rb * math.sin(a), zc + rb * math.cos(a)))
        up = np.array((0.0, s * math.sin(a), math.cos(a)))
        dome = g.revolve([(0.0, 0.0), (rbell, 0.0), (0.98 * rbell, 0.35 * rbell), (0.8 * rbell, 0.7 * rbell),
                          (0.45 * rbell, 0.92 * rbell), (0.0, rbell)], trim).replace(wall=0.0008)
        at = base + 0.012 * up
        pieces += [g.cylinder(base - 0.002 * up, at, 0.0025, trim, 12),
                   dome.transformed(Frame.at(at, z=up, x=(1, 0, 0)).matrix)]
    zt = zc + rb
    pieces += [g.cylinder((xc - 0.004, 0.0, zt - 0.003), (xc - 0.004, 0.0, zt + 0.022), 0.002, trim, 12),  # hammer
               g.box_between((xc - 0.008, -0.004, zt + 0.02), (xc, 0.004, zt + 0.028), trim, bevel=0.001)]
    return pieces


# -- dial ----------------------------------------------------------------------------------------------------------
ROMAN = ("XII", "I", "II", "III", "IIII", "V", "VI", "VII", "VIII", "IX", "X", "XI")  # IIII: the clockmakers' four


def dial(c: Clock, slot: str) -> g.Piece:
    """The dial plate: a disc just behind the dial face."""
    x, y, z = c.centre
    return _along_x(g.cylinder((0, 0, -0.002), (0, 0, 0.0), c.radius, slot, None), (x, y, z))


def marks(c: Clock, style: str, slot: str) -> g.Piece:
    """The printed dial: 60 minute ticks and 12 hour marks (batons, or Roman numerals read from the centre), one
    decoration piece (no collision)."""
    r = c.radius
    pieces = []
    for m in range(60):
        theta = 2 * math.pi * m / 60
        major = m % 5 == 0
        length = (0.1 if major and style == "batons" else 0.04) * r
        width = (0.03 if major else 0.008) * r
        pieces.append(_stroke(c, theta, 0.95 * r - length / 2, (0.0, 0.0), length, width, slot))
    if style == "roman":
        height = 0.14 * r
        for hour, text in enumerate(ROMAN):
            pieces += _numeral(c, 2 * math.pi * hour / 12, 0.8 * r - height / 2, text, height, slot)
    vs, fs, n = [], [], 0
    for p in pieces:
        vs.append(p.vertices)
        fs.append(p.faces + n)
        n += len(p.vertices)
    return g.Piece(np.concatenate(vs), np.concatenate(fs), slot)


def _stroke(c: Clock, theta: float, r: float, offset: tuple[float, float], length: float, width: float, slot: str,
            lean: float = 0.0) -> g.Piece:
    """A printed stroke ``length`` x ``width`` centred ``offset`` (right, up) from the point ``r`` out at clock angle
    ``theta``, its long side radial (leaned ``lean`` radians clockwise)."""
    up = np.array((0.0, math.sin(theta), math.cos(theta)))
    right = np.array((0.0, math.cos(theta), -math.sin(theta)))
    at = c.on_dial(r, theta, MARK / 2) + offset[0] * right + offset[1] * up
    axis = math.cos(lean) * up + math.sin(lean) * right
    box = g.box_between((-MARK / 2, -width / 2, -length / 2), (MARK / 2, width / 2, length / 2), slot)
    return box.transformed(Frame.at(at, x=(1, 0, 0), z=axis).matrix)


def _numeral(c: Clock, theta: float, r: float, text: str, height: float, slot: str) -> list[g.Piece]:
    """A Roman numeral of I, V and X strokes, upright as read from the dial's centre."""
    w = 0.14 * height
    widths = {"I": 0.3 * height, "V": 0.62 * height, "X": 0.62 * height}
    total = sum(widths[ch] for ch in text)
    left, out = -total / 2, []
    for ch in text:
        mid = left + widths[ch] / 2
        if ch == "I":
            out.append(_stroke(c, theta, r, (mid, 0.0), height, w, slot))
        else:
            half = widths[ch] / 2 - w / 2
            lean = math.atan2(half, height) if ch == "X" else math.atan2(half, height) / 1.0
            length = math.hypot(2 * half if ch == "X" else half, height)
            if ch == "X":
                out += [_stroke(c, theta, r, (mid, 0.0), length, w, slot, math.atan2(2 * half, height)),
                        _stroke(c, theta, r, (mid, 0.0), length, w, slot, -math.atan2(2 * half, height))]
            else:  # V: two strokes meeting at the bottom
                out += [_stroke(c, theta, r, (mid - half / 2, 0.0), length, w, slot, -lean),
                        _stroke(c, theta, r, (mid + half / 2, 0.0), length, w, slot, lean)]
        left += widths[ch]
    return out


# -- hands -----------------------------------------------------------------------------------------------------------
HANDS = {  # length, blade width at the arbor, tail as fractions of the dial's radius; layer from the dial
    "alarm": (0.45, 0.035, 0.25, 1),
    "hour": (0.55, 0.06, 0.3, 2),
    "minute": (0.8, 0.045, 0.3, 3),
    "second": (0.88, 0.012, 0.25, 4),
}
TAPER = 0.3  # a blade's width at its tip, of its width at the arbor


def hand(c: Clock, kind: str, theta: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """A hand of ``kind`` pointing at clock angle ``theta`` on its own layer over the dial; returns its pieces and
    the arbor it turns about.

    A quartz movement turns its hands with well under 1 mN m and holds them only through a slipping clutch, so
    hands are balanced about the arbor (hand makers' counterbalanced hands): a tapered blade, a narrow tail and a
    round counterweight at the tail's end sized to put the hand's centre of mass on the arbor."""
    length, width, tail, layer = HANDS[kind]
    r = c.radius
    dx = layer * LAYER
    frame = Frame.at(c.on_dial(0.0, 0.0, dx), x=(1, 0, 0), z=(0.0, math.sin(theta), math.cos(theta)))
    w0, ln, tl = width * r, length * r, tail * r
    pts = [(x, y, z) for x in (-HAND / 2, HAND / 2) for y, z in ((-w0 / 2, 0.0), (w0 / 2, 0.0),
                                                                   (-TAPER * w0 / 2, ln), (TAPER * w0 / 2, ln))]
    blade = g.Piece(*_hull(pts), slot, [np.array(pts)])
    stem = g.box_between((-HAND / 2, -w0 / 4, -tl), (HAND / 2, w0 / 4, 0.0), slot)
    hub = g.cylinder((-HAND / 2, 0, 0), (HAND / 2, 0, 0), max(0.8 * w0, 0.02 * r), slot, 16)
    # first moments about the arbor (per unit thickness): the trapezoid blade out, the tail back
    moment = w0 * ln ** 2 * (0.5 + (TAPER - 1) / 3) - (w0 / 2) * tl ** 2 / 2
    weight = g.cylinder((-HAND / 2, 0, -tl), (HAND / 2, 0, -tl), math.sqrt(max(moment, 1e-12) / (math.pi * tl)),
                        slot, 24)
    # turned by a fingertip on the blade (a hand is set by its minute hand, pushed round)
    grasp = Grasp.make((HAND / 2, 0.0, 0.6 * ln), (-1, 0, 0), (0, 1, 0), w0, HAND / 2)
    pieces = [p.transformed(frame.matrix) for p in (blade.with_grasps(grasp), stem, hub, weight)]
    return pieces, c.arbor(dx)


def _hull(points) -> tuple[np.ndarray, np.ndarray]:
    import trimesh

    mesh = trimesh.convex.convex_hull(np.asarray(points, float))
    mesh.fix_normals()
    return np.asarray(mesh.vertices), np.asarray(mesh.faces)


def hand_angles(time_h: float) -> dict[str, float]:
    """Clock angles of the hands showing ``time_h`` hours (0-12); the alarm hand set 7 hours on."""
    minutes = time_h * 60
    return {"hour": 2 * math.pi * time_h / 12, "minute": 2 * math.pi * (minutes % 60) / 60,
            "second": 2 * math.pi * ((minutes * 60) % 60) / 60, "alarm": 2 * math.pi * ((time_h + 7) % 12) / 12}


# -- controls --------------------------------------------------------------------------------------------------------
KNOB = {"radius": 0.009, "length": 0.010}  # a setting knob or winding key: 15-20 mm across, standing 8-12 mm out


def back_knob(c: Clock, dy: float, dz: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """A setting knob on the clock's back, ``dy``, ``dz`` from the dial's axis (turned by thumb and finger)."""
    x_back = {"wall": 0.0, "mantel": -c.depth / 2, "alarm": -c.depth / 2}[c.design]
    _, y, z = c.centre
    y, z = y + dy, z + dz
    r, ln = KNOB["radius"], KNOB["length"]
    knob = g.cylinder((x_back - 0.0015, y, z), (x_back - ln, y, z), r, slot, 24)
    grip = g.box_between((x_back - ln - 0.003, y - 0.0015, z - 0.8 * r), (x_back - ln + 0.0005, y + 0.0015,
                                                                          z + 0.8 * r), slot)
    grasp = Grasp.make((x_back - ln - 0.003, y, z), (1, 0, 0), (0, 1, 0), 0.003, 0.0025)
    return [knob, grip.with_grasps(grasp)], Frame.at((x_back - 0.0015, y, z), z=(1, 0, 0), x=(0, 0, 1))


def pendulum(c: Clock, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A mantel clock's pendulum hanging behind its window: a rod and a round bob; returns the pieces, its pivot
    (z along x: it swings in the front's plane) and its swing either side."""
    y0, z0, y1, z1 = window(c)
    x = c.depth / 2 - MANTEL["board"] - 0.012
    pivot = np.array((x, 0.0, z1 + 0.015))
    bob_r = min(0.3 * (y1 - y0), 0.35 * (z1 - z0), 0.035)
    zb = z0 + 0.01 + bob_r
    rod = g.box_between((x - 0.001, -0.003, zb), (x + 0.001, 0.003, pivot[2] + 0.004), slot)
    bob = _along_x(g.cylinder((0, 0, -0.003), (0, 0, 0.003), bob_r, slot, None), (x, 0.0, zb))
    grasp = Grasp.make((x + 0.003, 0.0, zb), (-1, 0, 0), (0, 0, 1), 2 * bob_r, 0.003)
    return [rod, bob.with_grasps(grasp)], Frame.at(pivot, z=(1, 0, 0), x=(0, 0, -1)), MANTEL["swing"]


def bezel(c: Clock, ring: str, glass: str) -> tuple[list[g.Piece], Frame]:
    """A mantel clock's hinged glass bezel over the dial: a ring and its glass, hinged on its left (as you face it);
    returns its pieces and the hinge (z up: a positive turn swings it open towards you)."""
    x, y, z = c.centre
    r, front = c.radius, x + 5 * LAYER + 0.004
    band = g.shell([(r + 0.008, 0.0), (r + 0.008, front - x - 0.001), (r + 0.002, front - x + 0.004)], 0.006, ring)
    pieces = [_along_x(band, (x + 0.0005, y, z)),
              _along_x(g.cylinder((0, 0, -0.001), (0, 0, 0.001), r + 0.003, glass, None), (front, y, z))]
    left = y - r - 0.012
    grasp = Grasp.make((front + 0.004, y + r + 0.008, z), (0, -1, 0), (1, 0, 0), 0.012, 0.004)
    pieces[0] = pieces[0].with_grasps(grasp)
    hinge = Frame.at((x + 0.003, left, z), z=(0, 0, -1), x=(1, 0, 0))
    knuckle = g.cylinder((x + 0.003, left, z - 0.012), (x + 0.003, left, z + 0.012), 0.0025, ring, 12)
    return pieces + [knuckle], hinge


BUTTON_AT = 0.012  # m, the alarm-off plunger's place on the drum's top, in front of the hammer


def button_collar(c: Clock, slot: str) -> g.Piece:
    """The collar the alarm-off plunger runs in, standing on the drum's top (part of the case)."""
    zt = c.centre[2] + c.width
    return g.shell([(0.0045, zt - 0.002), (0.0045, zt + 0.008)], 0.001, slot, (BUTTON_AT, 0.0, 0.0))


def alarm_button(c: Clock, slot: str) -> tuple[list[g.Piece], Frame]:
    """The alarm-off plunger in its collar on top of the drum; returns it and its press frame (z down)."""
    zt, x = c.centre[2] + c.width, BUTTON_AT
    stem = g.cylinder((x, 0.0, zt + 0.0045), (x, 0.0, zt + 0.012), 0.0022, slot, 12)
    cap = g.cylinder((x, 0.0, zt + 0.012), (x, 0.0, zt + 0.017), 0.006, slot, 16)
    grasp = Grasp.make((x, 0.0, zt + 0.017), (0, 0, -1), (0, 1, 0), 0.012, 0.0025)
    return [stem, cap.with_grasps(grasp)], Frame.at((x, 0.0, zt + 0.017), z=(0, 0, -1), x=(1, 0, 0))


LEVER = {"length": 0.028, "width": 0.006, "turn": math.radians(60)}  # a chime/silent selector lever on the side


def chime_lever(c: Clock, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A mantel clock's chime/silent lever on its right side (as you face it), hanging down at rest (chime);
    returns its pieces, its pivot (z along +y) and its turn."""
    ys = c.width / 2 + 0.0012
    at = np.array((0.1 * c.depth, ys, 0.62 * c.height))
    ln, w = LEVER["length"], LEVER["width"]
    boss = g.cylinder(at, at + (0.0, 0.004, 0.0), 0.005, slot, 16)
    blade = g.box_between((at[0] - w / 2, ys + 0.001, at[2] - ln), (at[0] + w / 2, ys + 0.003, at[2]), slot,
                          bevel=0.0008)
    grasp = Grasp.make((at[0], ys + 0.003, at[2] - 0.8 * ln), (0, -1, 0), (1, 0, 0), w, 0.002)
    return [boss, blade.with_grasps(grasp)], Frame.at(at, z=(0, 1, 0), x=(1, 0, 0)), LEVER["turn"]
