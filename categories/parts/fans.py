"""Fans: pitched, curved blades on a hub, wire grilles, motor heads, and the bodies of the four designs.

Everything is built in world coordinates at rest with the fan's air thrown toward +X (a ceiling fan's axis is
+Z), the object standing on z = 0. A head (desk and pedestal fans) is built round its own axis frame: z along
the rotor axis (forward), x up; each moving part is returned with the frame its joint turns or slides about
(z the axis, a positive move opens).

Designs (real product types; sizes below with their sources):

* ``desk``: an oscillating desk fan, its motor head on a neck over a weighted base with the speed keys or a
  speed knob on the base's front (Honeywell HTF1220, Lasko 2005, Vornado-style 12 in desk fans);
* ``pedestal``: an oscillating stand fan whose upper pole slides out of the lower tube, a control pod on the
  upper pole under the head (Lasko 2521 / S16500, Honeywell HS-1655);
* ``box``: a square box fan, the rotor between flat front and back grilles, a speed knob on the top beside a
  moulded carry handle (Lasko 3733 20 in, Lasko B20200);
* ``ceiling``: a ceiling fan as it stands on its switch housing before it is hung: the rotating motor shell
  carrying its blade irons and blades, the downrod and canopy above (Hunter 52 in, Hampton Bay 44-52 in).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame

from .casing import CasingSize, Cutout


@dataclass(frozen=True)
class Design:
    """A fan design: blade (sweep) diameter range (m), blade count range, blade pitch (deg, at the root),
    the hub axis height (desk, pedestal at rest) or body size range (box: the square's side), motor mass (kg)."""

    diameter: tuple[float, float]
    blades: tuple[int, int]
    pitch: float
    height: tuple[float, float]
    motor: float


# Retail listings and spec sheets (inches converted, approximate where a listing rounds): Honeywell HTF1220
# 12 in desk fan 13.5 W x 8.5 D x 17.3 H in (34 x 22 x 44 cm), 1.5 kg; Lasko 2005 12 in, 14.3 x 9.8 x 18.8 in,
# 2.0 kg; 9-16 in blades (23-40 cm) across desk fans. Lasko S16500 16 in pedestal fan 36-48 in (0.91-1.22 m)
# tall, 3.4 kg; Honeywell HS-1655 16 in, 40-52 in; Lasko 2521 16 in, 4.5 kg. Lasko 3733 20 in box fan
# 22.8 x 4.5 x 22.4 in (58 x 11 x 57 cm), 3.4 kg; 12-20 in box fans. Hunter 52 in ceiling fan 52 in
# (1.32 m) sweep, motor shell ~8-10 in, 6-9 kg; 42-56 in (1.07-1.42 m) residential sweeps. Desk and stand fan
# blades are pitched 25-35 degrees, ceiling fan blades 12-15 (Hunter, Emerson blade pitch specifications).
# Motor masses (replacement shaded-pole and PSC motors): desk 0.6-0.8 kg, stand 1.0-1.3 kg, box 1.2 kg,
# ceiling (die-cast rotor and stator) 3-4 kg.
DESIGNS = {
    "desk": Design((0.23, 0.40), (3, 5), 30.0, (0.30, 0.42), 0.7),
    "pedestal": Design((0.36, 0.46), (3, 5), 30.0, (0.72, 0.95), 1.1),
    "box": Design((0.30, 0.50), (3, 5), 26.0, (0.36, 0.58), 1.2),
    "ceiling": Design((1.07, 1.42), (3, 5), 13.0, (0.25, 0.45), 3.5),
}
MOTOR_DENSITY = 7850.0  # steel laminations and copper windings, massed as steel
BLADE_T = {"desk": 0.002, "pedestal": 0.002, "box": 0.002, "ceiling": 0.008}  # m: moulded PP 2 mm, MDF 6-10 mm
WIRE = 0.001  # m, grille wire radius: 2 mm chromed or painted steel wire (replacement grille listings)
RIM = 0.0025  # m, the grille's rim ring radius (5 mm rolled rim wire)
TIP_CLEAR = 0.012  # m, from the blade tips to the grille (guards keep fingers off 10-15 mm)
SPOKES = {"desk": 28, "pedestal": 36}  # wires of a front grille (counts from product photos: 28-48)
RINGS = 4  # concentric wire rings of a front grille
LATCH = (0.034, 0.026, 0.008)  # m, a grille clip: length over the rim, width, thickness (~7 g of ABS)
LATCH_OPENS = math.radians(100)
TILT = math.radians(30)  # desk and stand fan heads tilt up 25-35 degrees (listings: "adjustable tilt")
OSCILLATES = math.radians(80)  # 80-90 degree oscillation (listings), from straight ahead (rest) to one side
GAP = 0.002  # m, between a moving part and what it turns in or rests on


@dataclass(frozen=True)
class Head:
    """A motor head on its axis frame ``axis`` (z forward along the rotor axis, x up): blade radius ``r``,
    grille radius ``rg``, blade count, the blades' axial half extent ``a``, motor radius and length, the
    z of the motor's front ``zm`` (axis coordinates)."""

    design: str
    axis: Frame
    r: float
    rg: float
    blades: int
    a: float
    rm: float
    lm: float
    zm: float

    @property
    def chord(self) -> float:
        """A blade's widest chord: three broad paddles, five narrower ones (product photos)."""
        return chord(self.r, self.blades)

    @property
    def badge(self) -> float:
        return 0.16 * self.rg

    @property
    def pivot(self) -> np.ndarray:
        """The tilt pivot under the motor (world): the neck's top."""
        return self.axis.point((-self.rm - 0.03, 0.0, self.zm - 0.35 * self.lm))


def chord(r: float, blades: int) -> float:
    return r * (1.6 / blades + 0.17)


def head(design: str, r: float, blades: int, hub_z: float) -> Head:
    """A desk or pedestal fan head whose rotor axis is ``hub_z`` up, blade radius ``r``."""
    pitch = math.radians(DESIGNS[design].pitch)
    a = 0.5 * chord(r, blades) * math.sin(pitch) + 0.006
    rm = 0.05 + 0.12 * r
    lm = DESIGNS[design].motor / MOTOR_DENSITY / (math.pi * (0.6 * rm) ** 2) + 0.05
    zm = -a - 0.012 - 0.28 * r
    axis = Frame.at((0.0, 0.0, hub_z), z=(1, 0, 0), x=(0, 0, 1))
    return Head(design, axis, r, r + TIP_CLEAR + WIRE, blades, a, rm, lm, zm)


# -- blades ------------------------------------------------------------------------------------------------------
def blade(r0: float, r1: float, chord: float, pitch: float, thickness: float, slot: str, angle: float = 0.0,
          camber: float = 0.08, sweep: float = 0.25, tip: str = "round") -> g.Piece:
    """One blade about +Z through the origin, from radius ``r0`` to ``r1``: a thin cambered plate whose chord
    (``chord`` wide at its widest) is pitched ``pitch`` (rad) to the plane of rotation at its root and a third
    less at its tip, its outline swept back by ``sweep`` of a chord and rounded at the tip (``tip`` "round") or
    square (a ceiling fan's board). It turns with +Z. Collision: three convex strips along its length."""
    ns, nc = 14, 9
    s = np.linspace(0.0, 1.0, ns)[:, None]
    c = np.linspace(-1.0, 1.0, nc)[None, :]
    r = r0 + s * (r1 - r0)
    if tip == "round":  # a paddle: narrow root, widest at 70 %, rounded off to the tip
        w = chord * (0.45 + 0.55 * np.sin(np.minimum(s / 0.7, 1.0) * math.pi / 2))
        w = w * np.sqrt(np.clip(1.0 - np.maximum(s - 0.7, 0.0) ** 2 / 0.3 ** 2, 0.04, 1.0))
    else:  # a board, slightly wider at its tip
        w = chord * (0.85 + 0.15 * s)
    phi = pitch * (1.0 - 0.33 * s)
    t = 0.5 * c * w + sweep * chord * s ** 2  # across the chord (along the turn), swept back
    camber_z = camber * w * (1.0 - c ** 2)
    u = t * np.cos(phi) - camber_z * np.sin(phi)
    z = t * np.sin(phi) + camber_z * np.cos(phi)
    alpha = angle + u / r
    mid = np.stack([r * np.cos(alpha), r * np.sin(alpha), z], -1).reshape(-1, 3)
    n = len(mid)
    verts = np.vstack([mid + [0, 0, thickness / 2], mid - [0, 0, thickness / 2]])
    faces = []
    idx = np.arange(n).reshape(ns, nc)
    for i in range(ns - 1):
        for j in range(nc - 1):
            a, b, cc, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            faces += [(a, b, cc), (a, cc, d), (a + n, cc + n, b + n), (a + n, d + n, cc + n)]
    loop = list(idx[:, 0]) + list(idx[-1, 1:]) + list(idx[-2::-1, -1]) + list(idx[0, -2:0:-1])
    for p, q in zip(loop, loop[1:] + loop[:1]):
        faces += [(p, p + n, q + n), (p, q + n, q)]
    faces = np.asarray(faces, np.int64)
    v3 = verts.reshape(2, ns, nc, 3)
    cuts = (0, ns // 3, 2 * ns // 3, ns - 1)
    convex = [v3[:, i0:i1 + 1].reshape(-1, 3) for i0, i1 in zip(cuts, cuts[1:])]
    piece = g.Piece(verts, faces, slot, convex)
    if _signed_volume(piece) < 0:
        piece = piece.replace(faces=faces[:, ::-1].copy())
    return piece


def _signed_volume(p: g.Piece) -> float:
    v = p.vertices[p.faces]
    return float(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6.0)


def merged(pieces: list[g.Piece], slot: str) -> g.Piece:
    """Many closed visual pieces (grille wires) as one piece of ``slot`` without collision: one mesh, not
    dozens; the grille's collision is given by its rim and face pieces."""
    verts, faces, k = [], [], 0
    for p in pieces:
        verts.append(p.vertices)
        faces.append(p.faces + k)
        k += len(p.vertices)
    return g.Piece(np.vstack(verts), np.vstack(faces), slot, [], wall=0.0)  # solid wire


def rotor(blades: int, r0: float, r1: float, chord: float, pitch: float, thickness: float, slot: str,
          tip: str = "round", camber: float = 0.08) -> list[g.Piece]:
    """``blades`` blades evenly round +Z."""
    return [blade(r0, r1, chord, pitch, thickness, slot, 2 * math.pi * k / blades, camber=camber, tip=tip)
            for k in range(blades)]


def on_axis(pieces: list[g.Piece], axis: Frame) -> list[g.Piece]:
    """Pieces built about +Z at the origin, moved onto ``axis``."""
    m = axis.matrix
    return [p.transformed(m) for p in pieces]


# -- grilles -----------------------------------------------------------------------------------------------------
def _ring(radius: float, z: float, wire: float, slot: str, n: int = 48) -> g.Piece:
    th = np.linspace(0, 2 * math.pi, n + 1)
    path = np.c_[radius * np.cos(th), radius * np.sin(th), np.full(n + 1, z)]
    path[-1] = path[0] + [0.0, 1e-4, 0.0]  # close the loop (the tube's end caps meet inside the wire)
    return g.tube(path, wire, slot)


def dome(radius: float, z0: float, depth: float, spokes: int, rings: int, hub: float, slot: str,
         power: float = 2.0) -> list[g.Piece]:
    """A wire dome about +Z: ``spokes`` wires from the ``hub`` radius out to its ``radius`` rim at ``z0``,
    bulging ``depth`` along +Z at the centre (negative: a dish behind), crossed by ``rings`` rings."""
    def zf(rr):
        return z0 + depth * (1.0 - (rr / radius) ** power)

    rs = np.linspace(hub, radius, 7)
    wires = []
    for k in range(spokes):
        th = 2 * math.pi * (k + 0.5) / spokes
        wires.append(g.tube(np.c_[rs * math.cos(th), rs * math.sin(th), zf(rs)], WIRE, slot))
    for rr in np.linspace(hub, radius, rings + 2)[1:-1]:
        wires.append(_ring(float(rr), float(zf(rr)) + math.copysign(WIRE, depth), WIRE, slot))
    return [merged(wires, slot)]


def grille(h: Head, slot: str, badge_slot: str) -> list[g.Piece]:
    """A head's guard about its axis, a wire cage: spokes from the badge over the front dome, along the band the
    blades turn in and back over the rear dish to the motor, crossed by rings, a rolled rim at the front and
    the back, a badge at the centre (world pieces). Collision: the band (hollow wedges), the front dome as one
    thin lens in front of the blades, the badge."""
    rg, a = h.rg, h.a
    zr0, zr1 = -a - 0.008, a + 0.008
    front_depth = 0.1 * h.r
    spokes = SPOKES.get(h.design, 36)

    def front(rr):
        return zr1 + front_depth * (1.0 - (rr / rg) ** 2)

    def rear(rr):
        return zr0 + (h.zm - zr0) * (1.0 - (rr / rg) ** 1.5)

    rf, rb = np.linspace(h.badge, rg, 7), np.linspace(rg, 0.8 * h.rm, 6)
    prof = np.vstack([np.c_[rf, front(rf)], [(rg, 0.5 * (zr0 + zr1))], np.c_[rb, rear(rb)]])
    wires = []
    for k in range(spokes):
        th = 2 * math.pi * (k + 0.5) / spokes
        wires.append(g.tube(np.c_[prof[:, 0] * math.cos(th), prof[:, 0] * math.sin(th), prof[:, 1]], WIRE, slot))
    for rr in np.linspace(h.badge, rg, RINGS + 2)[1:-1]:
        wires.append(_ring(float(rr), float(front(rr)) + WIRE, WIRE, slot))
    for rr in np.linspace(0.8 * h.rm, rg, RINGS + 1)[1:-1]:
        wires.append(_ring(float(rr), float(rear(rr)) - WIRE, WIRE, slot))
    wires += [_ring(rg, zr1, RIM, slot), _ring(rg, zr0, RIM, slot), _ring(rg, 0.5 * (zr0 + zr1), WIRE, slot)]
    band = g.shell([(rg + RIM, zr0), (rg + RIM, zr1)], 2 * RIM, slot)
    ring16 = np.linspace(0, 2 * math.pi, 16, endpoint=False)
    lens = np.vstack([np.c_[rr * np.cos(ring16), rr * np.sin(ring16), np.full(16, front(rr) if rr else front(0.0))]
                      for rr in (0.0, 0.5 * rg, 0.85 * rg)] + [np.c_[rg * np.cos(ring16), rg * np.sin(ring16),
                                                                    np.full(16, zr1 + 0.002)]])
    cage = merged(wires, slot).replace(convex=list(band.convex) + [lens])
    zb = front(0.0)
    rb = h.badge
    badge = g.revolve([(0, zb - 0.002), (rb, zb - 0.002), (0.95 * rb, zb + 0.006), (0.0, zb + 0.008)], badge_slot)
    return on_axis([cage, badge], h.axis)


def motor(h: Head, slot: str, core_slot: str) -> list[g.Piece]:
    """The motor housing behind the rear dish: a drum rounded at the back, and the motor inside it (massed as
    steel, no collision of its own: the housing is solid to the simulator)."""
    z0, z1, rm = h.zm - h.lm, h.zm, h.rm
    prof = [(0.0, z0 - 0.02), (0.55 * rm, z0 - 0.017), (0.9 * rm, z0 - 0.006), (rm, z0 + 0.015), (rm, z1 - 0.01),
            (0.9 * rm, z1), (0.0, z1)]
    kg = DESIGNS[h.design].motor
    rc = 0.6 * rm
    length = kg / MOTOR_DENSITY / (math.pi * rc * rc)
    core = g.cylinder((0, 0, z1 - 0.005 - length), (0, 0, z1 - 0.005), rc, core_slot, 24).replace(convex=[], wall=0.0)
    shell = g.revolve(prof, slot).replace(wall=0.0025)
    return on_axis([shell, core], h.axis)


def head_rotor(h: Head, blade_slot: str, hub_slot: str) -> tuple[list[g.Piece], Frame]:
    """The rotor: hub, spinner and shaft (back to the motor's front) and the blades; it turns about the axis."""
    pitch = math.radians(DESIGNS[h.design].pitch)
    hub_r = 0.09 * h.r + 0.012
    blades = rotor(h.blades, 0.6 * hub_r, h.r, h.chord, pitch, BLADE_T[h.design], blade_slot)
    hub = g.revolve([(0, -h.a + 0.004), (hub_r, -h.a + 0.004), (hub_r, 0.5 * h.a),
                     (0.6 * hub_r, h.a), (0, h.a + 0.002)], hub_slot)
    shaft = g.cylinder((0, 0, h.zm + GAP), (0, 0, -h.a + 0.005), 0.005, hub_slot, 12)
    return on_axis(blades + [hub, shaft], h.axis), h.axis


def neck_bracket(h: Head, slot: str) -> list[g.Piece]:
    """Under the motor: a bracket down to the tilt knuckle (a cylinder across, along world Y) at the pivot."""
    p = h.pivot
    top = h.axis.point((-0.6 * h.rm, 0.0, h.zm - 0.35 * h.lm))
    return [g.box_between((p[0] - 0.016, -0.012, p[2]), (p[0] + 0.016, 0.012, top[2]), slot, bevel=0.004),
            g.cylinder((p[0], -0.014, p[2]), (p[0], 0.014, p[2]), 0.014, slot, 24)]


def tilt_axis(h: Head) -> Frame:
    """The tilt hinge: across the fan (world Y) through the pivot; a positive turn lifts the grille."""
    return Frame.at(tuple(h.pivot), z=(0, -1, 0), x=(1, 0, 0))


def neck(h: Head, z_low: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """The oscillating neck: a collar from ``z_low`` up to a fork whose cheeks hold the tilt knuckle; it turns
    about the vertical through the pivot."""
    p = h.pivot
    zc = p[2] - 0.014 - GAP - 0.012
    pieces = [g.cylinder((p[0], 0, z_low), (p[0], 0, zc), 0.02, slot, 32),
              g.box_between((p[0] - 0.016, -0.026, zc - 0.004), (p[0] + 0.016, 0.026, zc + 0.006), slot, bevel=0.003)]
    for sgn in (-1, 1):
        y0 = sgn * (0.014 + GAP)
        y1 = sgn * (0.014 + GAP + 0.006)
        pieces.append(g.box_between((p[0] - 0.014, min(y0, y1), zc), (p[0] + 0.014, max(y0, y1), p[2] + 0.014),
                                    slot, bevel=0.002))
    return pieces, Frame.at((p[0], 0, z_low))


def latch(h: Head, angle: float, slot: str) -> tuple[list[g.Piece], Frame]:
    """A grille clip on the rim ``angle`` round the axis from the top (pi/2: the side): a tab lying over the
    front and rear rims, hinged on the rear rim's outside; it flips back to free the front grille."""
    length, width, t = LATCH
    zr0 = -h.a - 0.008
    x_out = h.rg + 2 * RIM + GAP
    tab = g.box_between((x_out, -width / 2, zr0 - 0.004), (x_out + t, width / 2, zr0 - 0.004 + length), slot,
                        bevel=0.002)
    hook = g.box_between((x_out - 0.004, -width / 2 + 0.003, zr0 - 0.004 + length - 0.005),
                         (x_out, width / 2 - 0.003, zr0 - 0.004 + length), slot)
    at = h.axis.turned("z", angle)
    hinge = at @ Frame.at((x_out + t / 2, 0.0, zr0 - 0.004), z=(0, 1, 0), x=(1, 0, 0))
    return on_axis([tab, hook], at), hinge


PIN = (0.008, 0.012, 0.022, 0.01)  # m, an oscillation knob: stem and cap radius, height, pull (product photos)


def osc_pin(h: Head, slot: str) -> tuple[list[g.Piece], Frame]:
    """The oscillation knob on top of the motor housing: pulled up it stops the oscillation (it slides up)."""
    stem, cap, height, _ = PIN
    z = h.zm - 0.45 * h.lm
    x0 = h.rm + GAP
    pieces = [g.cylinder((x0, 0, z), (x0 + height - 0.006, 0, z), stem, slot, None),
              g.revolve([(0, 0), (cap, 0), (cap, 0.004), (0.8 * cap, 0.006), (0, 0.006)], slot)
              .transformed(Frame.at((x0 + height - 0.006, 0, z), z=(1, 0, 0), x=(0, 0, 1)).matrix)]
    return on_axis(pieces, h.axis), h.axis @ Frame.at((x0, 0, z), z=(1, 0, 0), x=(0, 0, 1))


# -- bodies ------------------------------------------------------------------------------------------------------
DESK_BASE = (0.2, 0.26)  # m, width of a desk fan's base, across the listed models (depth 0.8 of it)
DESK_BASE_H = 0.055  # m
PEDESTAL_BASE = (0.2, 0.25)  # m, radius of a stand fan's round cast base (15.7-19.7 in bases)
STEM_R = 0.016  # m, a desk fan's stem; a stand fan's lower tube 19 mm (its upper pole 14.5 mm)
POLE_R = (0.019, 0.0145)
POLE_TRAVEL = 0.25  # m, 10-12 in of height adjustment (the listings' 36-48 in)
WEIGHT = {"desk": 0.6, "pedestal": 2.2}  # kg of steel or cast iron in the base (base-weight listings)
POD = (0.09, 0.07, 0.125)  # m, a stand fan's control pod on its upper pole: width, depth, height


def desk_base(x: float, width: float, slot: str, weight_slot: str) -> tuple[CasingSize, Frame, g.Piece]:
    """A desk fan's base casing (centred under the neck at ``x``) and the hidden steel weight in it."""
    size = CasingSize(width, 0.8 * width, DESK_BASE_H, 0.003, 0.0025, 0.3 * 0.4 * width)
    r = 0.3 * width
    h = WEIGHT["desk"] / MOTOR_DENSITY / (math.pi * r * r)
    weight = g.cylinder((x, 0, 0.004), (x, 0, 0.004 + h), r, weight_slot, 32).replace(convex=[], wall=0.0)
    return size, Frame.at((x, 0, 0)), weight


def round_base(x: float, radius: float, slot: str, weight_slot: str) -> list[g.Piece]:
    """A stand fan's round domed base with the cast weight inside."""
    h = 0.045
    prof = [(0.0, 0.0), (radius, 0.0), (radius, 0.008), (0.9 * radius, 0.02), (0.35 * radius, h - 0.004),
            (0.3 * radius, h), (0.0, h)]
    rw = 0.6 * radius
    hw = WEIGHT["pedestal"] / 7200.0 / (math.pi * rw * rw)
    weight = g.cylinder((x, 0, 0.003), (x, 0, 0.003 + hw), rw, weight_slot, 48).replace(convex=[], wall=0.0)
    return [g.revolve(prof, slot, center=(x, 0, 0)).replace(wall=0.003), weight]


def pole(x: float, z0: float, z1: float, radius: float, slot: str, hollow: bool) -> g.Piece:
    if hollow:
        return g.shell([(radius, z0), (radius, z1)], 0.003, slot, center=(x, 0, 0)).replace(wall=0.0012)
    return g.cylinder((x, 0, z0), (x, 0, z1), radius, slot, None).replace(wall=0.0012)


def pod_size() -> CasingSize:
    w, d, h = POD
    return CasingSize(w, d, h, 0.003, 0.0025, 0.02)


# -- box fan -----------------------------------------------------------------------------------------------------
BOX_DEPTH = 0.11  # m, a box fan's depth (Lasko 3733: 4.5 in)
BOX_WALL = 0.012  # m, the moulded frame's wall
BOX_CORNER = 0.025  # m


def square_ring(side: float, radius: float, x0: float, x1: float, hub_z: float, slot: str, n: int = 32) -> g.Piece:
    """A square plate ``side`` wide (in Y, Z about ``hub_z``) with a round hole of ``radius``, ``x0`` to ``x1``
    thick: a box fan's face. Collision: 16 convex sectors between the hole and the square."""
    th = 2 * math.pi * np.arange(n) / n
    d = np.c_[np.cos(th), np.sin(th)]
    sq = d / np.abs(d).max(axis=1, keepdims=True) * side / 2
    ci = d * radius
    rings = [np.c_[np.full(n, x), ring[:, 0], ring[:, 1] + hub_z] for x in (x0, x1) for ring in (sq, ci)]
    verts = np.vstack(rings)  # 0: outer at x0, n: inner at x0, 2n: outer at x1, 3n: inner at x1
    faces = []
    for i in range(n):
        j = (i + 1) % n
        o0, i0, o1, i1 = 0, n, 2 * n, 3 * n
        faces += [(o0 + i, o0 + j, i0 + j), (o0 + i, i0 + j, i0 + i)]  # the back face
        faces += [(o1 + i, i1 + j, o1 + j), (o1 + i, i1 + i, i1 + j)]  # the front face
        faces += [(o0 + i, o1 + j, o0 + j), (o0 + i, o1 + i, o1 + j)]  # outside
        faces += [(i0 + i, i0 + j, i1 + j), (i0 + i, i1 + j, i1 + i)]  # the hole
    faces = np.asarray(faces, np.int64)
    step = n // 16
    convex = [np.vstack([r[k * step:(k + 1) * step + 1] if (k + 1) * step < n else np.vstack([r[k * step:], r[:1]])
                         for r in rings]) for k in range(16)]
    piece = g.Piece(verts, faces, slot, convex)
    if _signed_volume(piece) < 0:
        piece = piece.replace(faces=faces[:, ::-1].copy())
    return piece


def flat_grille(radius: float, x: float, hub_z: float, slot: str, rings: int, bars: int) -> g.Piece:
    """A box fan's flat grille across its hole at ``x``: concentric wire rings crossed by straight bars
    (visual), its collision a thin disc of the hole."""
    axis = Frame.at((x, 0.0, hub_z), z=(1, 0, 0), x=(0, 0, 1))
    wires = [_ring(float(rr), 0.0, WIRE, slot) for rr in np.linspace(0.05, radius, rings + 1)]
    for k in range(bars):
        th = math.pi * k / bars
        e = radius * np.array([math.cos(th), math.sin(th), 0.0])
        wires.append(g.tube([-e, e], WIRE, slot))
    face = merged(wires, slot)
    th = np.linspace(0, 2 * math.pi, 24, endpoint=False)
    disc = np.vstack([np.c_[radius * np.cos(th), radius * np.sin(th), np.full(24, z)] for z in (-WIRE, WIRE)])
    return on_axis([face.replace(convex=[disc])], axis)[0]


def box_frame(side: float, radius: float, hub_z: float, slot: str, stems: list[tuple[float, float]],
              stem_r: float) -> list[g.Piece]:
    """A box fan's moulded frame: front and back faces with their round holes, a venturi ring between them,
    the top with a hole for each knob stem at ``stems`` (x, y), and the two feet it stands on."""
    h = BOX_DEPTH / 2
    holes = [(x - stem_r, y - stem_r, x + stem_r, y + stem_r) for x, y in stems]
    pieces = [square_ring(side, radius, -h, -h + BOX_WALL, hub_z, slot),
              square_ring(side, radius, h - BOX_WALL, h, hub_z, slot)]
    # the square's four sides between the faces
    s, t = side / 2, 0.004
    pieces += [g.panel((-h + BOX_WALL, -s, hub_z + s - t), (h - BOX_WALL, s, hub_z + s), slot, "z", holes),
               g.box_between((-h + BOX_WALL, -s, hub_z - s), (h - BOX_WALL, s, hub_z - s + t), slot),
               g.box_between((-h + BOX_WALL, -s, hub_z - s), (h - BOX_WALL, -s + t, hub_z + s), slot),
               g.box_between((-h + BOX_WALL, s - t, hub_z - s), (h - BOX_WALL, s, hub_z + s), slot)]
    pieces.append(g.shell([(radius + 0.004, -h + BOX_WALL), (radius + 0.004, h - BOX_WALL)], 0.004, slot,
                          center=(0, 0, hub_z)).transformed(_x_axis_about(hub_z)))
    foot = 0.09
    for y in (-0.35 * side, 0.35 * side):
        pieces.append(g.box_between((-foot, y - 0.02, 0.0), (foot, y + 0.02, hub_z - s + 0.002), slot, bevel=0.006))
    return [p.replace(wall=0.0025) if p.wall is None else p for p in pieces]


def _x_axis_about(hub_z: float) -> np.ndarray:
    """The transform that turns a piece built about +Z through (0, 0, hub_z) onto the X axis at hub_z."""
    return (Frame.at((0, 0, hub_z), z=(1, 0, 0), x=(0, 0, 1)) @ Frame.at((0, 0, -hub_z))).matrix


@dataclass(frozen=True)
class BoxFan:
    """A box fan's fixed pieces (frame, grilles, handle), its rotor's pieces and axis, its knobs' mounts."""

    body: list
    rotor: list
    axis: Frame
    knobs: list


def box_fan(r: float, side: float, blades: int, knobs: int, stem: float) -> BoxFan:
    """A box fan of blade radius ``r`` in a square at least ``side`` wide, ``knobs`` (1-2) knobs of ``stem``
    radius on the top near its ends."""
    side = max(side, 2 * r + 0.06)
    hub_z = side / 2 + 0.02
    hole = r + TIP_CLEAR
    stems = [(0.0, side / 2 - 0.05), (0.0, 0.05 - side / 2)][:knobs]
    frame = box_frame(side, hole, hub_z, "body", stems, stem + 0.002)
    grilles = [flat_grille(hole, x, hub_z, "grille", 5, 6) for x in (BOX_DEPTH / 2 - 0.004, 0.004 - BOX_DEPTH / 2)]
    axis = Frame.at((0, 0, hub_z), z=(1, 0, 0), x=(0, 0, 1))
    pitch = math.radians(DESIGNS["box"].pitch)
    blades_ = rotor(blades, 0.08, r, 0.6 * r, pitch, BLADE_T["box"], "blade")
    hub = g.revolve([(0, -0.02), (0.07, -0.02), (0.07, 0.01), (0.04, 0.025), (0, 0.027)], "hub")
    top = hub_z + side / 2
    return BoxFan(frame + grilles + [carry_handle(side, hub_z, "body")], on_axis(blades_ + [hub], axis), axis,
                  [knob_mount((*xy, top)) for xy in stems])


def carry_handle(side: float, hub_z: float, slot: str) -> g.Piece:
    """The moulded carry handle on the box's top: a bar across (Y) on two posts."""
    z = hub_z + side / 2
    span = 0.09
    return g.tube([(0, -span, z - 0.002), (0, -span, z + 0.03), (0, span, z + 0.03), (0, span, z - 0.002)],
                  0.009, slot)


# -- ceiling fan -------------------------------------------------------------------------------------------------
CUP = (0.085, 0.07)  # m, the switch housing's radius and height (a ceiling fan's switch cup, 6-7 in across)
SHELL_H = 0.09  # m, the motor shell's height (Hunter: 3.5-4 in)
DOWNROD_R = 0.0125  # m, a 3/4 in (19 mm) schedule downrod, 25 mm over its coupler
CANOPY = (0.075, 0.08)  # m, the canopy's radius and height


def ceiling_body(radius: float, downrod: float, slot: str, rod_slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A ceiling fan's fixed parts standing on the floor: the switch cup, the shaft, and above the motor shell
    the coupling cover, the downrod and the canopy; returns them, the rotor's axis frame and its shell's
    radius."""
    rc, hc = CUP
    rs = 0.62 * radius * 0.16 + 0.04
    z0 = hc + GAP
    z1 = z0 + SHELL_H
    cup = g.revolve([(0, 0), (0.55 * rc, 0), (0.95 * rc, 0.15 * hc), (rc, 0.6 * hc), (0.9 * rc, hc), (0, hc)],
                    slot).replace(wall=0.002)
    cover = g.revolve([(0, z1 + GAP), (0.45 * rs, z1 + GAP), (0.3 * rs, z1 + 0.05), (0, z1 + 0.05)], slot)
    rod = g.cylinder((0, 0, z1 + 0.045), (0, 0, z1 + 0.045 + downrod), DOWNROD_R, rod_slot, None).replace(wall=0.0015)
    zc = z1 + 0.045 + downrod
    r_can, h_can = CANOPY
    canopy = g.revolve([(0, zc - 0.01), (0.2 * r_can, zc - 0.01), (0.85 * r_can, zc + 0.6 * h_can),
                        (r_can, zc + h_can), (0, zc + h_can)], slot).replace(wall=0.002)
    return [cup, cover, rod, canopy], Frame.at((0, 0, z0)), rs


def ceiling_rotor(radius: float, blades: int, rs: float, at: Frame, slot: str, iron_slot: str, blade_slot: str
                  ) -> list[g.Piece]:
    """The motor shell (the rotor of a ceiling fan's outer-rotor motor) with its blade irons and blades."""
    z0 = at.origin[2]
    kg = DESIGNS["ceiling"].motor
    shell = g.revolve([(0, z0), (0.85 * rs, z0), (rs, z0 + 0.02), (rs, z0 + SHELL_H - 0.025),
                       (0.8 * rs, z0 + SHELL_H), (0, z0 + SHELL_H)], slot)
    shell = shell.replace(wall=kg / (MOTOR_DENSITY * 2 * math.pi * rs * SHELL_H * 1.6))
    r0 = rs + 0.11
    zb = z0 + 0.025
    pitch = math.radians(DESIGNS["ceiling"].pitch)
    chord = 0.12 + 0.03 * (radius - 0.53) / 0.18
    boards = rotor(blades, r0, radius, chord, pitch, BLADE_T["ceiling"], blade_slot, tip="square", camber=0.02)
    irons = []
    for k in range(blades):
        th = 2 * math.pi * k / blades
        c, s = math.cos(th), math.sin(th)
        path = [(rs * 0.8 * c, rs * 0.8 * s, z0 + 0.012), ((rs + 0.03) * c, (rs + 0.03) * s, z0 + 0.012),
                ((r0 + 0.06) * c, (r0 + 0.06) * s, zb - 0.012)]
        irons.append(g.tube(path, 0.008, iron_slot))
    return [shell] + [b.transformed(Frame.at((0, 0, zb)).matrix) for b in boards] + irons


REVERSE = (0.016, 0.012, 0.008)  # m, the reverse switch's slider: length, height, proud (Hunter switch cups)
REVERSE_TRAVEL = 0.01


def reverse_switch(slot: str) -> tuple[list[g.Piece], Frame]:
    """The forward/reverse slide switch on the side (+X) of the cup: a slider that moves along Y."""
    rc, hc = CUP
    ln, ht, proud = REVERSE
    x = rc + 0.001  # on the housing's widest band, clear of it
    z = 0.6 * hc
    piece = g.box_between((x, -ln / 2, z - ht / 2), (x + proud, ln / 2, z + ht / 2), slot, bevel=0.002)
    return [piece], Frame.at((x, 0, z), z=(0, 1, 0), x=(1, 0, 0))


def knob_mount(at: tuple[float, float, float]) -> Frame:
    """A knob's mount on an upward face (its stem along +Z, the knob's up toward the front)."""
    return Frame.at(at, z=(0, 0, 1), x=(1, 0, 0))


def box_cutout(face: str, at: tuple[float, float], half: tuple[float, float], clear: float) -> Cutout:
    return Cutout.around(face, at, (2 * half[0], 2 * half[1]), clear)
