"""Seating parts: casters, star bases, disc bases, gas lifts, swivel seats, backrests, 4D arms, foot rings.

Shared by the office chair and the bar chair. Local frames: a base stands on
z = 0 centred on the z axis; a caster's swivel axis is its local z through the
origin and its leg points along local +x; a seat's swivel axis is local z and
its sitter faces +x.

Sizes are those of real task and bar chairs: BIFMA X5.1 / EN 1335 task chairs
(seat height 0.40-0.55 m, 5-star bases of 0.60-0.70 m diameter, 50-65 mm
twin-wheel casters, 50 mm gas-lift tubes with 60-100 mm stroke); bar stools
(seat 0.60-0.85 m, foot rings 0.35-0.46 m across, 380-450 mm seats).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.errors import GeometryError
from infmob_usd.frames import Frame, polar
from infmob_usd.grammar import Layout

GAP = 0.004  # clearance between moving parts and their neighbours
WHEEL_INSET = 0.0006  # wheel collider radius below the visual tyre radius (fixed-root sims drag tyres)
BLACK = "plastic:black|dark_grey"

LEG_WEIGHTS = {4: 0.04, 5: 0.9, 6: 0.06}
"""Star-base leg count -> share: five legs on nearly every task chair (BIFMA X5.1 tip-over
stability; four-leg bases are rare and banned in some markets, six on heavy-duty chairs)."""


_PLASTIC = {"plastic": BLACK}
CHAIR_MATERIALS = {
    "base": ("base_finish", _PLASTIC), "caster": BLACK, "wheel": ("wheel_finish", _PLASTIC),
    "lift": ("lift_finish", {"black": "enamel:black"}), "mech": "painted:black|charcoal", "pan": BLACK,
    "seat": ("seat_finish", {"plastic": "plastic:black|dark_grey|white|red|blue"}), "frame": BLACK,
    "mesh": "fabric:charcoal|grey|navy", "pad": BLACK, "handle": BLACK, "ring": "chrome",
}
"""Material slot -> family, parameter, or (parameter, {value: family}), shared by the chairs:
plastic chair parts are black or dark grey, plastic seats come in a few moulded colours."""


def _hull(points, material: str) -> g.Piece:
    pts = np.asarray(points, float)
    v, f = g.hull_arrays(pts)
    return g.Piece(v, f, material, [v])


def _ring_yz(x: float, cy: float, cz: float, r: float, n: int = 12) -> list:
    """Points of a circle in the YZ plane at ``x`` (an axle boss seen along X)."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return [(x, cy + r * math.cos(a), cz + r * math.sin(a)) for a in t]


# -- casters -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Caster:
    """A caster in its local frame: the fork, the wheels (axle along +x at ``axle``), the stem top."""

    fork: tuple[g.Piece, ...]
    wheels: tuple[tuple[g.Piece, ...], ...]
    spans: tuple[tuple[float, float], ...]  # x range of each wheel
    axle: tuple[float, float, float]
    stem_top: float

    @property
    def footprint(self) -> float:
        """Radius swept about the swivel axis."""
        span = max(abs(x) for xs in self.spans for x in xs) + GAP
        return math.hypot(-self.axle[1] + self.axle[2], span)


def caster(style: str, rw: float) -> Caster:
    """A twin-wheel or single-wheel caster with wheel radius ``rw``; every wheel touches z = 0."""
    trail = 0.45 * rw + 0.006
    yw = -trail
    fork: list[g.Piece] = []
    hood0 = 2 * rw + GAP  # every fork piece above the wheels or beside them
    if style == "twin":
        ww, hw = 0.45 * rw + 0.004, 0.008  # wheel width, housing half-width between the wheels
        spans = [(-hw - GAP - ww, -hw - GAP), (hw + GAP, hw + GAP + ww)]
        boss = _ring_yz(-hw, yw, rw, 0.42 * rw) + _ring_yz(hw, yw, rw, 0.42 * rw)
        top = [(x, y, hood0) for x in (-hw, hw) for y in (yw - 0.3 * rw, 0.012)]
        fork.append(_hull(boss + top, "caster"))
        half = hw + GAP + ww + 0.002
        fork.append(g.box_between([-half, yw - 0.75 * rw, hood0], [half, 0.016, hood0 + 0.01], "caster",
                                  bevel=0.003))
        z_top = hood0 + 0.01
    else:
        ww = 0.6 * rw + 0.006
        spans = [(-ww / 2, ww / 2)]
        xo = ww / 2 + GAP
        for s in (-1, 1):
            boss = _ring_yz(s * xo, yw, rw, 0.4 * rw) + _ring_yz(s * (xo + 0.004), yw, rw, 0.4 * rw)
            top = [(s * x, y, hood0 + 0.006) for x in (xo, xo + 0.004) for y in (yw - 0.4 * rw, 0.01)]
            fork.append(_hull(boss + top, "caster"))
        fork.append(g.box_between([-xo - 0.004, yw - 0.5 * rw, hood0], [xo + 0.004, 0.016, hood0 + 0.009],
                                  "caster", bevel=0.003))
        z_top = hood0 + 0.009
    wheels = []
    for x0, x1 in spans:
        tyre = g.cylinder([x0, yw, rw], [x1, yw, rw], rw, "wheel", 32)
        inner = g.cylinder([x0, yw, rw], [x1, yw, rw], rw - WHEEL_INSET, "wheel", 32)
        tyre = g.Piece(tyre.vertices, tyre.faces, "wheel", [inner.vertices])
        hub = g.cylinder([x0 + 0.001, yw, rw], [x1 - 0.001, yw, rw], 0.55 * rw, "caster", 24)
        hub = g.Piece(hub.vertices, hub.faces, "caster", [])  # inside the tyre: decoration only
        wheels.append((tyre, hub))
    stem_top = z_top + 0.012
    fork.append(g.cylinder([0, 0, z_top - 0.002], [0, 0, stem_top - 0.004], 0.0065, "caster", 16))
    fork.append(g.cylinder([0, 0, stem_top - 0.005], [0, 0, stem_top], 0.013, "caster", 24))
    return Caster(tuple(fork), tuple(wheels), tuple(spans), (0.0, yw, rw), stem_top)


def fork(c: Caster) -> Assembly:
    """The caster's fork in the leg tip's frame (anchor ``swivel``: the stem top, z up)."""
    return Assembly.single("caster", c.fork, {"swivel": Frame.at((0, 0, c.stem_top))})


def wheels(c: Caster) -> list[Assembly]:
    """The caster's wheels in the leg tip's frame (anchor ``axle``: z along the axle); supports ``axle_a``
    / ``axle_b`` where the axle meets the wheel's faces, part frame ``part_frame`` at its middle."""
    axle = Frame.at(c.axle, z=(1, 0, 0))
    _, y, z = c.axle
    return [Assembly.single("wheel", pcs, {"axle": axle, "part_frame": Frame.at(((x0 + x1) / 2, y, z), z=(1, 0, 0))},
                            {"axle_a": (x0, y, z), "axle_b": (x1, y, z)})
            for pcs, (x0, x1) in zip(c.wheels, c.spans, strict=True)]


# -- bases ------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Base:
    """A base and where the lift goes: socket floor, hub top, bore; ``tips``: caster frames (if any)."""

    assembly: Assembly
    floor: float
    top: float
    bore: float
    tips: tuple[Frame, ...] = ()


def star_base(n_legs: int, radius: float, c: Caster, r_lift: float, leg_style: str, metal: bool) -> Base:
    """A hollow hub socket for a lift of radius ``r_lift`` and ``n_legs`` legs ending over casters ``c``.

    The leg radius grows where the casters would touch while they swivel.
    """
    radius = max(radius, (c.footprint + 0.02) / math.sin(math.pi / n_legs), 0.2)
    z_lb = c.stem_top + 0.003 + 0.009  # leg bottom at the tip (a socket hides the stem)
    rise = 0.02 + 0.03 * (leg_style == "tapered")
    wt, ht = 0.034, 0.026
    wh, hh = (0.05, 0.045) if leg_style == "tapered" else (wt, 0.035)
    bore = r_lift + GAP
    hub_r = bore + 0.014
    z_h1 = z_lb + rise + hh + 0.006
    z_h0 = z_lb + rise - 0.03
    floor = z_h0 + 0.01
    sheet = 0.003 if metal else 0.0
    pieces = [
        g.shell([(hub_r, z_h0), (hub_r, z_h1)], hub_r - bore, "base").replace(sheet=sheet),
        g.disc([0, 0, (z_h0 + floor) / 2], bore + 0.002, floor - z_h0, "base", 32).replace(sheet=sheet),
    ]
    x_in, x_out = hub_r - 0.006, radius + 0.022
    pts = []
    for x, w, z0, h in ((x_in, wh, z_lb + rise, hh), (x_out, wt, z_lb, ht)):
        for y in (-w / 2, w / 2):
            pts += [(x, y, z0), (x, 0.8 * y, z0 + h), (x, y, z0 + 0.75 * h)]
    pts += [(x_out + 0.012, y, z_lb + 0.2 * ht) for y in (-0.3 * wt, 0.3 * wt)]
    pts += [(x_out + 0.012, y, z_lb + 0.7 * ht) for y in (-0.25 * wt, 0.25 * wt)]
    leg = _hull(pts, "base").replace(sheet=sheet)
    socket = g.cylinder([radius, 0, c.stem_top + 0.003], [radius, 0, z_lb + 0.004], 0.012, "base", 20)
    tips = polar(Frame.at(), n_legs, radius)
    for spoke in polar(Frame.at(), n_legs, 0.0):
        pieces += [leg.transformed(spoke.matrix), socket.transformed(spoke.matrix)]
    # a plastic base is ribbed glass-filled nylon, massed solid (5-leg nylon bases weigh 2-3 kg)
    pieces = [pc.replace(wall=0.0) for pc in pieces]
    return Base(Assembly.single("base", pieces, {"socket": Frame.at((0, 0, floor))}), floor, z_h1, bore,
                tuple(tips))


def disc_base(radius: float, bore: float, metal: bool) -> Base:
    """A domed cast disc with a socket boss and a felt pad; its top is the socket floor."""
    t = 0.012 + 0.03 * (radius - 0.2)
    prof = [(0.0, 0.0), (radius - 0.012, 0.0)]
    for k in range(1, 8):
        a = -math.pi / 2 + math.pi / 2 * k / 7
        prof.append((radius - 0.012 + 0.012 * math.cos(a), 0.006 + 0.006 * math.sin(a)))
    for k in range(1, 9):
        f = k / 8
        prof.append((radius - f * (radius - bore - 0.03), 0.006 + t * (1 - (1 - f) ** 2)))
    top = 0.006 + t
    prof.append((0.0, top))
    disc = g.revolve(prof, "base")  # a cast disc: solid on purpose (a heavy, stable foot)
    boss = g.shell([(bore + 0.02, top - 0.004), (bore + 0.014, top + 0.03)], 0.014, "base")
    felt = g.disc([0, 0, 0.0015], radius - 0.03, 0.003, "pad", 48)
    felt = g.Piece(felt.vertices, felt.faces, "pad", [])
    return Base(Assembly.single("base", [disc, boss, felt], {"socket": Frame.at((0, 0, top))}), top, top + 0.03,
                bore)


def column(base_top: float, top: float, bore: float) -> list[g.Piece]:
    """A bar stool's column sleeve from the hub to ``top`` with a trim collar."""
    col_r = bore + 0.006
    return [g.shell([(col_r, base_top - 0.006), (col_r, top)], col_r - bore, "base"),
            g.shell([(col_r + 0.002, top - 0.012), (col_r + 0.002, top)], 0.008, "base")]


RING_MIN = 0.22  # a foot ring lower than this is a trip hazard, not a rest
COLUMN_BELOW_LIFT = 0.03  # the column ends this far below the lift tube's top at the least


def ring_column(top: float, z_ring: float, lift_top: float) -> tuple[float, float]:
    """Column top and foot-ring height once the column must reach up to carry the ring."""
    top = max(top, min(z_ring + 0.04, lift_top - 0.05))
    return top, min(z_ring, top - 0.03)


def foot_ring(z: float, radius: float, bore: float) -> list[g.Piece]:
    """A round foot ring of 40 tube segments and four spokes to the column of bore ``bore``."""
    col_r = bore + 0.006
    rr, n = 0.009, 40
    pts = [np.array([radius * math.cos(2 * math.pi * k / n), radius * math.sin(2 * math.pi * k / n), z])
           for k in range(n + 1)]
    pieces = [g.cylinder(a, b, rr, "ring", 16) for a, b in zip(pts[:-1], pts[1:])]
    for k in range(n):
        ball = g.sphere(pts[k], rr, "ring")
        pieces.append(g.Piece(ball.vertices, ball.faces, "ring", []))
    for spoke in polar(Frame.at((0, 0, z)).turned("z", math.pi / 4), 4, 0.0):
        d = spoke.x
        pieces.append(g.cylinder(d * (col_r - 0.002) + [0, 0, z], d * (radius - 0.004) + [0, 0, z], 0.006,
                                 "ring", 12))
    pieces.append(g.shell([(col_r + 0.008, z - 0.018), (col_r + 0.008, z + 0.018)], 0.008, "ring"))
    return pieces


# -- the lift -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Lift:
    rod: tuple[g.Piece, ...]  # fixed to the base
    tube: Assembly  # anchor "slide": its foot, z up
    travel: float


def legs(p: dict, rng: np.random.Generator) -> int:
    """leg_count, or drawn from LEG_WEIGHTS"""
    n, w = list(LEG_WEIGHTS), np.array(list(LEG_WEIGHTS.values()))
    drawn = n[int(rng.choice(len(n), p=w / w.sum()))]  # always drawn: forcing it reshuffles nothing
    return p["leg_count"] or drawn


MIN_TRAVEL = 0.04  # a gas lift shorter than this is no adjustment (real strokes: 60-120 mm)


def gas_lift(floor: float, top: float, r_lift: float, travel: float) -> Lift:
    """A hollow tube from just above the socket ``floor`` to ``top`` around a fixed piston rod.

    The tube slides up along +z from rest; the travel is capped so it always surrounds the rod.
    """
    wall, cap = 0.0035, 0.008
    z0 = floor + GAP
    travel = min(travel, top - cap - GAP - 0.03 - z0)
    if travel < MIN_TRAVEL:
        raise GeometryError(f"gas lift: only {travel * 1000:.0f} mm of stroke fit between the socket and the"
                            " seat; raise the seat or lower the base")
    rod_top = z0 + travel + 0.03
    # steel, chromed or black-coated: the tube is massed as the family's sheet-steel wall, the piston
    # rod solid (wall 0), so a lift weighs about what real ones do (class 3/4 cylinders 1-2 kg in all)
    tube = [g.shell([(r_lift, z0), (r_lift, top - cap + 0.001)], wall, "lift"),
            g.disc([0, 0, top - cap / 2], r_lift, cap, "lift", 48)]
    rod = g.cylinder([0, 0, floor - 0.002], [0, 0, rod_top], 0.35 * r_lift, "lift", 20).replace(wall=0.0)
    return Lift((rod,), Assembly.single("lift", tube, {"slide": Frame.at((0, 0, z0)),
                                                       "top": Frame.at((0, 0, top))}), travel)


# -- the seat -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Seat:
    assembly: Assembly  # anchors: "swivel" (lift top, z up)
    lift_top: float
    z_pan0: float
    z_mech0: float
    x0: float
    x1: float
    xc: float


def seat_thickness(top: float, wanted: float, base_top: float, hm: float) -> float:
    """The cushion thickness that leaves the seat mechanism clear of the hub on a low chair."""
    return min(wanted, top - 0.012 - hm - GAP - 0.035 - base_top - 0.015)


def swivel_seat(top: float, width: float, depth: float, thick: float, shape: str, xc: float, r_lift: float,
                hm: float) -> Seat:
    """Seat with its mechanism, pan, cushion and height lever, on a collar around the lift top.

    ``top`` is the seat top; the lift tube must end at ``lift_top``.
    """
    pan_t = 0.012
    z_pan0 = top - thick - pan_t
    z_mech0 = z_pan0 - hm
    lift_top = z_mech0 - GAP
    collar_r = r_lift + GAP + 0.006
    pieces = [g.shell([(collar_r, lift_top - 0.03), (collar_r, z_mech0 + 0.002)], 0.006, "mech")]
    if shape == "round":
        rad = width / 2
        pieces.append(g.disc([xc, 0, z_mech0 + hm / 2], min(0.12, 0.6 * rad), hm, "mech", 40))
        pieces.append(g.disc([xc, 0, z_pan0 + pan_t / 2], rad - 0.01, pan_t, "pan", 48))
        prof = [(0.0, z_pan0 + pan_t)]
        e = min(0.3 * thick, 0.025)
        for k in range(9):
            a = -math.pi / 2 + math.pi * k / 8
            prof.append((rad - e + e * math.cos(a), z_pan0 + pan_t + thick / 2 + (thick / 2) * math.sin(a)))
        prof.append((0.0, top))
        pieces.append(g.revolve(prof, "seat", center=(xc, 0, 0)))
        x0, x1 = xc - rad, xc + rad
        reach = 0.7 * width / 2
    else:
        mw, md = min(0.2, 0.5 * width), min(0.24, 0.55 * depth)
        pieces.append(g.box([md, mw, hm], [xc, 0, z_mech0 + hm / 2], "mech", bevel=0.006))
        pieces.append(g.box([depth - 0.01, width - 0.01, pan_t], [xc, 0, z_pan0 + pan_t / 2], "pan", bevel=0.004))
        x0, x1 = xc - depth / 2, xc + depth / 2
        b = min(0.03, 0.4 * thick)
        pieces.append(g.box([depth, width, thick], [xc, 0, z_pan0 + pan_t + thick / 2], "seat", bevel=b))
        # a lip at the front edge: the "waterfall"
        pieces.append(g.box([0.03, width - 2 * b, 0.6 * thick], [x1 - 0.02, 0, z_pan0 + pan_t + 0.45 * thick],
                            "seat", bevel=0.008))
        reach = width / 2 - 0.03
    zl = z_mech0 + 0.3 * hm  # height lever under the right side
    pieces.append(g.cylinder([xc + 0.03, 0.04, zl], [xc + 0.03, reach, zl], 0.0045, "handle", 12, name="handle"))
    pieces.append(g.box([0.04, 0.02, 0.012], [xc + 0.04, reach, zl], "handle", bevel=0.003, name="handle"))
    asm = Assembly.single("seat", pieces, {"swivel": Frame.at((0, 0, lift_top))})
    return Seat(asm, lift_top, z_pan0, z_mech0, x0, x1, xc)


# -- the back -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class BackDims:
    height: float
    width: float
    thickness: float
    gap: float  # above the seat top


@dataclass(frozen=True)
class Back:
    bracket: tuple[g.Piece, ...]  # fixed to the seat
    spine: tuple[g.Piece, ...]  # the back part's spine and knuckle
    hinge: Frame  # recline axis (z along -y: a positive turn tips the top backwards)
    x_spine: float  # spine front
    z0: float
    z1: float


def back_frame(seat: Seat, seat_top: float, dims: BackDims) -> Back:
    """The spine on its recline knuckle behind the seat, and the seat's bracket and cheeks.

    The hinge is at the foot of the spine, behind the backrest's centre of mass, so gravity
    tips the back forward onto its upright stop.
    """
    sw, st, rk = 0.06, 0.016, 0.011  # spine width, thickness, knuckle radius
    br_top = seat.z_mech0 + 0.022  # the seat's bracket under the mechanism
    zp = br_top + rk + GAP
    xp = seat.x0 - rk - 0.01
    cheek_y = sw / 2 + GAP
    bracket = [g.box_between([xp - 0.02, -0.03, seat.z_mech0], [seat.xc - 0.05, 0.03, br_top], "mech")]
    for s in (-1, 1):
        y0, y1 = (cheek_y, cheek_y + 0.008) if s > 0 else (-cheek_y - 0.008, -cheek_y)
        bracket.append(g.box_between([xp - 0.018, y0, seat.z_mech0], [xp + 0.018, y1, zp + 0.016], "mech"))
    z0 = seat_top + dims.gap
    z1 = z0 + dims.height
    spine = [g.cylinder([xp, -sw / 2, zp], [xp, sw / 2, zp], rk, "frame", 20),
             g.box_between([xp - st / 2, -sw / 2, zp], [xp + st / 2, sw / 2, z0 + 0.5 * dims.height], "frame",
                           bevel=0.003)]
    return Back(tuple(bracket), tuple(spine), Frame.at((xp, 0, zp), x=(1, 0, 0), z=(0, -1, 0)), xp + st / 2,
                z0, z1)


def cushion_back(b: Back, dims: BackDims) -> tuple[list[g.Piece], float]:
    """An upholstered back on a frame plate with a lumbar bulge; returns pieces and its front x."""
    xs, bw, bt, bh = b.x_spine, dims.width, dims.thickness, dims.height
    pieces = [
        g.box_between([xs, -0.45 * bw, b.z0 + 0.03], [xs + 0.012, 0.45 * bw, b.z1 - 0.03], "frame", bevel=0.004),
        g.box_between([xs + 0.01, -bw / 2, b.z0], [xs + 0.01 + bt, bw / 2, b.z1], "seat", bevel=min(0.025, 0.4 * bt)),
        g.box_between([xs + bt, -0.4 * bw, b.z0 + 0.18 * bh], [xs + bt + 0.015, 0.4 * bw, b.z0 + 0.45 * bh], "seat",
                      bevel=0.007),
    ]
    return pieces, xs + bt + 0.015


def mesh_back(b: Back, dims: BackDims) -> tuple[list[g.Piece], float]:
    """A mesh stretched in a frame; returns pieces and its front x."""
    xs, bw, fr = b.x_spine, dims.width, 0.025
    pieces = [g.panel([xs, -bw / 2, b.z0], [xs + 0.022, bw / 2, b.z1], "frame", "x",
                      holes=[(-bw / 2 + fr, b.z0 + fr, bw / 2 - fr, b.z1 - fr)]),
              g.box_between([xs + 0.008, -bw / 2 + fr - 0.002, b.z0 + fr - 0.002],
                            [xs + 0.012, bw / 2 - fr + 0.002, b.z1 - fr + 0.002], "mesh")]
    return pieces, xs + 0.022


def headrest(b: Back, dims: BackDims) -> tuple[list[g.Piece], float]:
    """A headrest on a stalk above the back; returns pieces and its front x."""
    xs, bw = b.x_spine, dims.width
    zh0 = b.z1 + 0.03
    pieces = [g.box_between([xs - 0.016, -0.02, b.z1 - 0.06], [xs, 0.02, zh0 + 0.05], "frame"),
              g.box_between([xs, -0.3 * bw, zh0], [xs + 0.05, 0.3 * bw, zh0 + 0.12], "seat", bevel=0.018)]
    return pieces, xs + 0.05


# -- arms -----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ArmDims:
    pad_length: float
    pad_width: float
    height: float  # pad top above the seat top
    slide: float  # pad slide along x, each way
    turn: float  # carriage turn about z, each way
    pad_turn: float  # pad turn about z, each way


ARM_OFFSET = 0.03  # pad centre ahead of the post
ARM_POST = -0.06  # post axis behind the seat centre
ARM_BAR = (0.022, 0.016)  # the fixed bar under the post (x, y)
ARM_TUBE = 0.003  # hollow post wall
ARM_CARRIAGE = 0.05  # half the carriage's length (x), centred on the post
ARM_POST_HALF = ARM_BAR[0] / 2 + 0.003 + ARM_TUBE  # half the post's depth (x)


def pad_reach(a: ArmDims, xb: float | None) -> float:
    """How far (m) the arm pad reaches inwards of its post axis where the back could be
    (``xb``: the back's front, relative to the post; ``None``: anywhere)."""
    L, pw = a.pad_length, a.pad_width
    t = np.linspace(-1, 1, 9)
    edge = np.vstack([np.c_[t * L / 2, np.full(9, pw / 2)], np.c_[t * L / 2, np.full(9, -pw / 2)],
                      np.c_[np.full(9, L / 2), t * pw / 2], np.c_[np.full(9, -L / 2), t * pw / 2]])
    reach = pw / 2
    for turn in np.linspace(-a.turn, a.turn, 5):
        for pad in np.linspace(-a.pad_turn, a.pad_turn, 5):
            for s in (-a.slide, 0.0, a.slide):
                f = Frame.at((s, 0, 0)).turned("z", turn) @ Frame.at((ARM_OFFSET, 0, 0)).turned("z", pad)
                q = f.point(np.c_[edge, np.zeros(len(edge))])[:, :2]
                sel = q if xb is None else q[q[:, 0] < xb]
                if len(sel):
                    reach = max(reach, float(np.abs(sel[:, 1]).max()))
    return reach


@dataclass(frozen=True)
class Arm:
    bracket: tuple[g.Piece, ...]  # fixed to the seat
    post: tuple[g.Piece, ...]
    slider: tuple[g.Piece, ...]
    pad: tuple[g.Piece, ...]
    post_slide: Frame  # z up
    carriage: Frame  # z up
    pad_pivot: Frame  # z up
    flip: Frame  # a flip-up arm's cap hinge: the carriage's rear bottom edge, z along -y (the front lifts)


def arm(seat: Seat, seat_top: float, y: float, dims: ArmDims) -> Arm:
    """One 4D arm at lateral position ``y``: bracket under the seat, hollow post over a fixed bar,
    carriage and pad."""
    x_post = seat.xc + ARM_POST
    s = 1.0 if y > 0 else -1.0
    br0, br1 = seat.z_pan0 - 0.022, seat.z_pan0 - 0.004
    z_pt = seat_top + dims.height
    pt = 0.026
    z_pad0 = z_pt - pt
    zc0 = z_pad0 - GAP - 0.012  # carriage bottom
    zc1 = zc0 + 0.012
    cap1 = zc0 - GAP
    cap0 = cap1 - 0.008
    z_t0 = br1 + 0.006
    bracket = (
        g.box_between([x_post - 0.025, min(0.0, s * 0.08), br0], [x_post + 0.025, max(0.0, s * 0.08), br1], "mech"),
        g.box_between([x_post - 0.025, min(s * 0.08, y + s * 0.02), br0],
                      [x_post + 0.025, max(s * 0.08, y + s * 0.02), br1], "frame", bevel=0.003),
        g.box_between([x_post - ARM_BAR[0] / 2, y - ARM_BAR[1] / 2, br1 - 0.002],
                      [x_post + ARM_BAR[0] / 2, y + ARM_BAR[1] / 2, cap0 - 0.012], "frame"),
    )
    hx, hy = ARM_BAR[0] / 2 + 0.003 + ARM_TUBE, ARM_BAR[1] / 2 + 0.003 + ARM_TUBE
    ix, iy = hx - ARM_TUBE, hy - ARM_TUBE
    post = (
        g.box_between([x_post - hx, y - hy, z_t0], [x_post - ix, y + hy, cap0 + 0.001], "frame"),
        g.box_between([x_post + ix, y - hy, z_t0], [x_post + hx, y + hy, cap0 + 0.001], "frame"),
        g.box_between([x_post - ix, y - hy, z_t0], [x_post + ix, y - iy, cap0 + 0.001], "frame"),
        g.box_between([x_post - ix, y + iy, z_t0], [x_post + ix, y + hy, cap0 + 0.001], "frame"),
        g.box_between([x_post - hx - 0.004, y - hy - 0.004, cap0], [x_post + hx + 0.004, y + hy + 0.004, cap1],
                      "frame", bevel=0.002),
    )
    slider = (g.box_between([x_post - ARM_CARRIAGE, y - 0.022, zc0], [x_post + ARM_CARRIAGE, y + 0.022, zc1], "frame",
                            bevel=0.003),)
    pad = (g.box([dims.pad_length, dims.pad_width, pt], [x_post + ARM_OFFSET, y, z_pad0 + pt / 2], "pad",
                 bevel=min(0.012, 0.4 * pt)),)
    knuckle = x_post - ARM_CARRIAGE  # a flip-up cap's hinge: the carriage's rear end, over the post
    return Arm(bracket, post, slider, pad, Frame.at((x_post, y, z_t0)), Frame.at((x_post, y, zc0)),
               Frame.at((x_post + ARM_OFFSET, y, z_pad0)), Frame.at((knuckle, y, zc0), x=(1, 0, 0), z=(0, -1, 0)))


def arm_y(seat_width: float, dims: ArmDims, back_width: float | None, back_front: float | None,
          seat: Seat) -> float:
    """Lateral post position: beside the seat, and clear of the back wherever the pad can go."""
    x_post = seat.xc + ARM_POST
    half_y = ARM_BAR[1] / 2 + 0.003 + ARM_TUBE
    y = seat_width / 2 + half_y + 0.008
    if back_front is not None:
        y = max(y, back_width / 2 + 0.012 + pad_reach(dims, back_front + 0.012 - x_post))
    return y


# -- the nodes both chairs grow ----------------------------------------------------------------------
class ChairNodes(Layout):
    """Node methods shared by the chairs: star base with casters and wheels, lift, seat, back.

    Reads the parameters both chair schemas have: ``caster_style``, ``wheel_radius``,
    ``base_radius``, ``lift_radius``, ``lift_travel``, ``leg_style``, ``base_finish``,
    ``seat_height``, ``seat_width``, ``back_*`` and ``recline``.
    """

    def star_base(self, node) -> Base:
        p = self.p
        c = caster(p["caster_style"], p["wheel_radius"])
        casters = node.of("caster")
        base = star_base(len(casters), p["base_radius"], c, p["lift_radius"], p["leg_style"],
                         metal=p["base_finish"] != "plastic")
        self.place(base.assembly, "base")
        for i, (n, tip) in enumerate(zip(casters, base.tips)):
            self.grow(n, tip=tip, caster=c, i=i)
        return base

    def caster(self, node, tip, caster, i):
        f = self.place(fork(caster).placed(tip), f"caster_{i}")
        self.spin("base", f.root, f.anchor("swivel"), role="swivel")
        self.grow(node.one(node.choice), fork=f, wheels=[w.mounted(tip) for w in wheels(caster)], i=i)

    def twin(self, node, fork, wheels, i):
        for k, w in enumerate(wheels):
            wheel = self.place(w, f"wheel_{i}" if len(wheels) == 1 else f"wheel_{i}_{k}")
            self.spin(fork.root, wheel.root, wheel.anchor("axle"), role="wheel")

    single = twin

    def swivel_seat(self, shape: str, depth: float, thick: float, ahead: float, mechanism: float) -> Seat:
        p = self.p
        seat = swivel_seat(p["seat_height"], p["seat_width"], depth, thick, shape, ahead, p["lift_radius"],
                           mechanism)
        self.place(seat.assembly, "seat")
        return seat

    def lift(self, node, base, seat):
        lift = gas_lift(base.floor, seat.lift_top, self.p["lift_radius"], self.p["lift_travel"])
        self.extend("base", lift.rod)
        self.place(lift.tube, "lift")
        self.slide("base", "lift", lift.tube.anchor("slide"), upper=lift.travel, role="telescope")
        self.spin("lift", "seat", seat.assembly.anchor("swivel"), role="swivel")

    def back_dims(self) -> BackDims:
        p = self.p
        return BackDims(p["back_height"], p["back_width"] * p["seat_width"], p["back_thickness"], p["back_gap"])

    def back(self, node, seat, hinged: bool = True):
        """The back: spine on the seat, its style and headrest as children; returns its front x."""
        dims = self.back_dims()
        frame = back_frame(seat, self.p["seat_height"], dims)
        self.extend("seat", frame.bracket)
        self.add("back", "back", frame.spine)
        front = self.grow(node.one(node.choice), frame=frame, dims=dims) if node.choice else \
            self._back(cushion_back(frame, dims))
        if node.one("headrest"):
            front = max(front, self.grow(node.one("headrest"), frame=frame, dims=dims))
        if hinged:
            self.hinge("seat", "back", frame.hinge, upper=self.p["recline"])
        else:
            self.fix("seat", "back")
        return front

    def cushion(self, node, frame, dims):
        return self._back(cushion_back(frame, dims))

    def mesh(self, node, frame, dims):
        return self._back(mesh_back(frame, dims))

    def headrest(self, node, frame, dims):
        return self._back(headrest(frame, dims))

    def _back(self, made):
        pieces, front = made
        self.extend("back", pieces)
        return front


# -- adjustable headrest, lumbar pad, seat slider, flip-up arms -------------------------------------------
HEADREST_TRAVEL = 0.07  # headrest height adjustment (executive and mesh chairs: 50-80 mm, e.g. Herman Miller
#                         Aeron / Steelcase Gesture headrest kits)
LUMBAR_TRAVEL = 0.06  # lumbar pad height adjustment (Steelcase Leap, Herman Miller Aeron PostureFit: 50-75 mm)
SEAT_SLIDE = 0.05  # seat depth adjustment (BIFMA task chairs: 50-60 mm forward)
# a flip-up arm's cap (carriage and pad) turns up about its rear edge on the fixed post until it stands upright
# beside the back, above the seat (flip-up arms of desk-sharing and drafting chairs: about 90 degrees)
ARM_FLIP = 1.5


def adjustable_headrest(b: Back, dims: BackDims) -> tuple[list[g.Piece], Frame, Frame]:
    """A headrest on a stalk that slides up in a sleeve behind the back.

    Returns the headrest's pieces, the slide frame (z up) and the frame of its yoke (z along +y); the
    sleeve is part of the back (:func:`headrest_sleeve`).
    """
    xs, bw = b.x_spine, dims.width
    zh0 = b.z1 + 0.035
    stalk = g.box_between([xs - 0.014, -0.016, b.z1 - 0.09], [xs - 0.004, 0.016, zh0 + 0.04], "frame", bevel=0.002)
    pad = g.box_between([xs + 0.004, -0.3 * bw, zh0], [xs + 0.06, 0.3 * bw, zh0 + 0.13], "seat", bevel=0.02)
    yoke = g.box_between([xs - 0.014, -0.05, zh0 + 0.02], [xs + 0.006, 0.05, zh0 + 0.07], "frame", bevel=0.003)
    return [stalk, yoke, pad], Frame.at((xs, 0, b.z1 - 0.09)), Frame.at((xs - 0.004, 0, zh0 + 0.045),
                                                                         x=(1, 0, 0), z=(0, 1, 0))


def headrest_sleeve(b: Back) -> list[g.Piece]:
    """The open sleeve behind the back's top that holds a headrest stalk: two cheeks and a back plate."""
    xs, z0, z1 = b.x_spine, b.z1 - 0.12, b.z1 + 0.008
    return [g.box_between([xs - 0.022, -0.026, z0], [xs - 0.018, 0.026, z1], "frame"),
            g.box_between([xs - 0.018, 0.02, z0], [xs, 0.026, z1], "frame"),
            g.box_between([xs - 0.018, -0.026, z0], [xs, -0.02, z1], "frame")]


def lumbar_pad(b: Back, dims: BackDims, front: float) -> tuple[list[g.Piece], Frame]:
    """A lumbar pad in front of the back at its lower third, sliding up along z; returns pieces and the
    slide frame."""
    bw, bh = dims.width, dims.height
    z0 = b.z0 + 0.15 * bh
    pad = g.box_between([front + GAP, -0.38 * bw, z0], [front + GAP + 0.018, 0.38 * bw, z0 + 0.09], "pad",
                        bevel=0.008)
    return [pad], Frame.at((front, 0, z0))


def split_seat(seat: Seat) -> tuple[list[g.Piece], list[g.Piece]]:
    """The swivel seat's pieces split into what stays on the mechanism and what a seat slider moves
    (the pan and the cushion)."""
    pcs = seat.assembly.parts[seat.assembly.root].pieces
    moving = [pc for pc in pcs if pc.material in ("seat", "pan")]
    return [pc for pc in pcs if pc.material not in ("seat", "pan")], moving


def tension_knob(seat: Seat, depth: float, hm: float) -> tuple[list[g.Piece], Frame]:
    """The tilt-tension knob at the front of the mechanism under the seat (turned to stiffen the
    recline); returns its pieces and its axis frame (z along +x)."""
    md = min(0.24, 0.55 * depth)
    x0 = seat.xc + md / 2
    zc = seat.z_mech0 + hm / 2 - 0.003
    r = min(0.015, hm / 2 - 0.008)
    pieces = [g.cylinder([x0 + GAP, 0, zc], [x0 + 0.03, 0, zc], r, "handle", 20),
              g.cylinder([x0 + 0.012, 0, zc], [x0 + 0.026, 0, zc], r + 0.002, "handle", 10)]
    return pieces, Frame.at((x0, 0, zc), x=(0, 0, 1), z=(1, 0, 0))


# -- bar stools: four-leg swivel frame, height lever --------------------------------------------------------
FOUR_LEG_TUBE = 0.0125  # 25 mm steel tube legs (four-leg swivel bar stools, e.g. IKEA Franklin, Flash Furniture)
BEARING_R = 0.1  # the swivel bearing plate under the seat (a 200 mm lazy-susan plate)


def four_leg_frame(bearing_top: float, spread: float, z_ring: float) -> list[g.Piece]:
    """Four splayed tube legs under a swivel bearing plate whose top is at ``bearing_top``, their feet
    ``spread`` from the centre (on the diagonals), a square foot rail of four rungs at ``z_ring`` and
    plastic glides. Material slots: ``base`` (legs, plate), ``ring`` (rungs), ``caster`` (glides)."""
    r, t = FOUR_LEG_TUBE, 0.012
    zt = bearing_top - t
    top_a, foot_a = 0.07, spread / math.sqrt(2)  # leg tops under the plate, feet at the corners
    glide = 0.01
    corners = [(sx, sy) for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    pieces = [g.disc([0, 0, bearing_top - t / 2], BEARING_R, t, "base", 48)]
    legs = []
    for sx, sy in corners:
        a = np.array([sx * foot_a, sy * foot_a, glide])
        b = np.array([sx * top_a, sy * top_a, zt + 0.002])
        legs.append((a, b))
        pieces.append(g.cylinder(a, b, r, "base", 20))
        pieces.append(g.cylinder(a - [0, 0, glide], a + [0, 0, 0.004], r + 0.002, "caster", 20))

    def at(k, z):
        a, b = legs[k]
        return a + (b - a) * (z - a[2]) / (b[2] - a[2])

    for k in range(4):
        p0, p1 = at(k, z_ring), at((k + 1) % 4, z_ring)
        d = (p1 - p0) / np.linalg.norm(p1 - p0)
        pieces.append(g.cylinder(p0 + d * 0.004, p1 - d * 0.004, 0.009, "ring", 16))
    zs = zt - 0.09  # a lower square of stretchers stiffening the leg tops
    for k in range(4):
        p0, p1 = at(k, zs), at((k + 1) % 4, zs)
        pieces.append(g.cylinder(p0, p1, 0.007, "base", 12))
    return pieces


def height_lever(seat: Seat, hm: float, reach: float, mech_y: float) -> tuple[list[g.Piece], list[g.Piece], Frame,
                                                                               float]:
    """Split the seat's height lever (pieces named ``handle``) off the seat: returns what stays, the
    lever (rebuilt to start just outside the mechanism, whose side is at ``mech_y``), its pivot frame
    (z along +x at its inner end: a positive turn lifts the paddle) and the most it turns before the
    paddle meets the seat pan."""
    pcs = seat.assembly.parts[seat.assembly.root].pieces
    stay = [pc for pc in pcs if pc.name != "handle"]
    zl = seat.z_mech0 + 0.3 * hm
    x, y0 = seat.xc + 0.03, mech_y + GAP
    lever = [g.cylinder([x, y0, zl], [x, max(reach, y0 + 0.05), zl], 0.0045, "handle", 12, name="handle"),
             g.box([0.04, 0.02, 0.012], [x + 0.01, max(reach, y0 + 0.05), zl], "handle", bevel=0.003, name="handle")]
    arm = max(reach, y0 + 0.05) - y0 + 0.01
    room = seat.z_pan0 - GAP - (zl + 0.006)
    upper = min(0.35, math.asin(max(0.0, min(1.0, room / arm))))
    return stay, lever, Frame.at((x, y0, zl), x=(0, 1, 0), z=(1, 0, 0)), upper


def mech_half_y(shape: str, width: float, depth: float) -> float:
    """How far the seat mechanism reaches sideways (y) where the height lever leaves it."""
    if shape == "round":
        r = min(0.12, 0.6 * width / 2)
        return math.sqrt(max(r * r - 0.03 ** 2, 0.0))
    return min(0.2, 0.5 * width) / 2


SEAT_TILT = 0.2  # forward seat tilt of ergonomic / saddle stools (about 10-12 degrees: Salli, Varier, Bambach)


def tilt_pivot(seat: Seat, shape: str, width: float, depth: float) -> Frame:
    """The forward-tilt axis of a seat pan: along +y at the top front edge of its mechanism, so a
    positive turn dips the front and lifts the back clear of the mechanism."""
    reach = min(0.12, 0.6 * width / 2) if shape == "round" else min(0.24, 0.55 * depth) / 2
    return Frame.at((seat.xc + reach, 0, seat.z_pan0), x=(1, 0, 0), z=(0, 1, 0))


# -- layout helpers shared by the office chair and the bar chair -------------------------------------------
SIDES = (("left", 1), ("right", -1))  # the two arms: name and the sign of their y


def seat_slide_axis(seat: Seat) -> Frame:
    """A seat slider's axis: along +x at the mechanism's top, under the seat's centre."""
    return Frame.at((seat.xc, 0, seat.z_pan0), z=(1, 0, 0))


def square_depth(shape: str, width: float, depth: float) -> float:
    """The seat's depth: ``depth`` for a square seat, its diameter ``width`` for a round one."""
    return depth if shape == "square" else width


def lever_reach(shape: str, width: float) -> float:
    """The height lever paddle's y: under a round seat at 70 % of its radius, 30 mm in from a square one's edge."""
    return 0.7 * width / 2 if shape == "round" else width / 2 - 0.03


def knob_depth(shape: str, width: float, depth: float) -> float:
    """The depth that places a tension knob at the mechanism's front: a round seat's mechanism is a
    disc of up to 0.12 m radius (its tilt pivot), a square seat's scales with its depth."""
    r_mech = min(0.12, 0.6 * width / 2)
    return depth if shape == "square" else 2 * r_mech / 0.55


HEADREST_REACH = 0.06  # an adjustable headrest's pad front ahead of the back's spine
LUMBAR_PAD = 0.018  # a lumbar pad's thickness
LUMBAR_SHARE = 0.3  # a lumbar pad slides over at most this share of the back's height


def headrest_reach(b: Back) -> float:
    """The front x of an adjustable headrest (:func:`adjustable_headrest`)."""
    return b.x_spine + HEADREST_REACH


def lumbar_slide(dims: BackDims, front: float) -> tuple[float, float]:
    """A lumbar pad's travel up the back and its front x (:func:`lumbar_pad`)."""
    return min(LUMBAR_TRAVEL, LUMBAR_SHARE * dims.height), front + GAP + LUMBAR_PAD


def executive_back(back_height: float, lo: float, hi: float) -> float:
    """An executive high back's height: ``back_height`` (0.3-0.55 m, a task back's range) mapped onto lo-hi."""
    return lo + (hi - lo) * (back_height - 0.3) / 0.25


@dataclass(frozen=True)
class SlidingRing:
    """A foot ring clamped on the column: the column's pieces, the ring's, its slide frame and travel."""

    column: list
    ring: list
    at: Frame
    travel: float


def drafting_ring(seat: Seat, base: Base, radius: float, travel: float) -> SlidingRing:
    """A drafting chair's column sleeve, 40 mm below the lift's top, and the foot ring on it: 80 mm above the
    hub at rest (no lower than :data:`RING_MIN`), sliding up by ``travel`` at most, 30 mm short of the top."""
    top = seat.lift_top - COLUMN_BELOW_LIFT - 0.04
    z = max(base.top + 0.08, RING_MIN)
    return SlidingRing(column(base.top, top, base.bore), foot_ring(z, radius, base.bore + 0.002),
                       Frame.at((0, 0, z)), min(travel, top - 0.03 - z))


def stool_ring(z: float, top: float, radius: float, bore: float, travel: float) -> SlidingRing:
    """A drafting stool's sliding foot ring at ``z`` (at least 50 mm under the column's ``top``), sliding up by
    ``travel`` at most, 30 mm short of the top."""
    z = min(z, top - 0.05)
    return SlidingRing([], foot_ring(z, radius, bore + 0.002), Frame.at((0, 0, z)),
                       max(0.0, min(travel, top - 0.03 - z)))


def four_leg_stool(lift_top: float, seat_height: float, ring_drop: float, base_radius: float) -> list[g.Piece]:
    """A four-leg swivel stool's frame (:func:`four_leg_frame`) under a seat whose lift top is ``lift_top``: its
    bearing 30 mm below it, feet on the diagonals at 85 % of ``base_radius``, the foot rail ``ring_drop`` below
    the seat top (no lower than :data:`RING_MIN`, at least 0.14 m under the bearing)."""
    bearing = lift_top - 0.03 - GAP
    z_ring = max(seat_height - ring_drop, RING_MIN)
    z_ring = min(z_ring, bearing - 0.14)
    return four_leg_frame(bearing, 0.85 * base_radius * math.sqrt(2), z_ring)
