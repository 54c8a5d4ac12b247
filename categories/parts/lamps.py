"""Lamp parts: weighted bases with a hidden steel weight and a push switch, telescoping poles, upright
and hanging heads with shades of revolution and screw-in bulbs, curved arcs and architect-style chain
arms whose sizes are searched so the head clears the bars, the base and the floor.

See ``categories/lamp.py`` for the mechanism. Sizes of real lamps: desk lamps 0.35-0.6 m, floor
lamps 1.0-1.5 m, 10-22 mm poles, E14/E27 bulbs 35-65 mm across, shades 0.14-0.44 m across
(manufacturers' catalogues: IKEA, Anglepoise, Artemide).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint
from infmob_usd.frames import Frame

GAP = 0.0025  # clearance between parts that move against each other
BULB_TRAVEL = 0.012  # how far a bulb slides out of its socket while unscrewing
SWITCH_TRAVEL = 0.004  # push-switch stroke (horizontal)
SWITCH_WALL = 0.0015  # wall of the switch housing
PITCH = math.pi / 6  # chain pitch joints lift by up to PITCH
SWIVEL = math.pi / 2  # chain swing arms turn +-SWIVEL
SOCKET_LEN = 0.03  # socket shell length
SOCKET_WALL = 0.003  # a hanging socket's moulded shell wall
TWIN_R = 0.0045  # radius of the twin side bars of a chain segment (9 mm rods, Anglepoise Type 75)
COLLAR_LEN = 0.022  # collar ring around a swivel pin
BASE_PER_REACH = 0.33  # an arm lamp's base radius is at least this times its head's reach
TRIPOD_HUB = 0.16  # a tripod's hub top (where the pole starts) above the floor
MIN_POLE = 0.06
"""m: the shortest pole (base top to pole top) under an upright head; a larger shade is shrunk. Without it
0.35 m desk lamps on a tripod hub under a 13 cm shade were left 29-43 mm of pole: the head's collar sat in
the lower pole's. Seeds 0-599 have at least 64 mm, so none of them changes."""
CLAMP = dict(throat=0.06, jaw=0.011, spine=0.012, back=0.035, front=0.05, screw_x=0.018, rod=0.005, pad=0.012,
             pad_t=0.004, bar=0.0045, bar_len=0.06)
"""A desk clamp (architect lamps: Anglepoise, IKEA TERTIAL with clamp): a C of cast steel whose jaws take desk tops
up to ~55-60 mm; the upper jaw carries the pole, the spine stands behind the pole at the desk edge, a spindle
with a pad and a T-bar handle comes up through the lower jaw. m: throat, jaw and spine thickness, how far the
jaws reach behind (back) and in front of (front) the pole, the spindle's x, rod radius, pad radius and
thickness, T-bar radius and length."""
DESK_TOP = 0.74  # m: a clamp lamp hangs on a desk 0.74 m high (desk heights 0.72-0.76 m, EN 527-1 / BIFMA)
TRIPOD_SPAN = 1.8  # a tripod's feet stand on a circle this many base radii wide (Hay / IKEA tripod lamps:
#                    legs spread 0.25-0.4 m from the pole)


def blueprint(p: dict, rng: np.random.Generator) -> Blueprint:
    """The whole lamp as a scratch blueprint (parts and joints at rest, the pole top set so the lamp
    is exactly ``desk_height`` / ``floor_height`` tall); the category's layout adds its parts node by node."""
    q = _plan(p, rng)
    # everything above the pole top is rigid with it: build it once with the pole top at top0, then
    # set the pole top so the lamp is exactly H tall (the base bottom is at z = 0) and move it there
    for _ in range(20):
        head = _head(p, q, q.top0)
        rise = float(head.bounds()[1, 2]) - q.top0
        if q.style != "straight" or q.H - rise - q.z_b >= MIN_POLE:
            break
        q = replace(q, rs=q.rs * 0.92)  # too big a head for so short a lamp (a 0.35 m desk lamp on a 0.16 m hub)
    bp = Blueprint("lamp")
    _stand(bp, p, q, q.H - rise)
    _move_head(bp, head, q.H - rise - q.top0)
    return bp


# ---------------------------------------------------------------------------
# the plan: every draw, once, in a fixed order


SEGMENTS = {"pitch": 0.6, "swivel": 0.4}
"""A chain arm's segments after the first (always a pitch) pitch or swing, with these shares."""


@dataclass(frozen=True)
class Draws:
    """A lamp's random draws, made once in a fixed order (:func:`_plan`)."""

    kinds: list[str]  # a chain arm's segment kinds (the first always a pitch)
    spokes: int
    lean: float  # first chain segment, from vertical
    mid_angle: float  # middle pitch segment of three
    last_angle: float  # last pitch segment, down to the head
    riser: float  # chain shoulder / H
    curve_end: float  # where an arc ends (0 = pointing straight down)
    shade_drop: float  # an upright shade's bottom below its spokes / its height
    switch_angle: float


@dataclass(frozen=True)
class Knuckle:
    """Sizes of the hinges of a chain arm, from the pole radius (:func:`_knuckle`)."""

    w_c: float  # width of a central hub
    r_h: float  # hub and cheek radius
    r_c: float  # central bar radius
    y_tw: float  # twin bar centre line
    r_pin: float
    r_x: float  # half height of the block a swivel pin hangs from


@dataclass(frozen=True)
class ChainPlan:
    """A chain arm: each segment's kind, angle from horizontal and length, the riser top, the forward limit of
    each hinge and the head's reach (:func:`_chain_plan`)."""

    kinds: tuple[str, ...]
    angles: tuple[float, ...]
    lengths: tuple[float, ...]
    top0: float
    forward: tuple[float, ...]
    reach_x: float


@dataclass(frozen=True)
class LampPlan(Knuckle):
    """Every size and angle of one lamp, from its parameters and its draws (:func:`_plan`): lamp type and arm
    style, height ``H``, base radius ``R`` and the base's top ``z_b``, shade radius ``rs``, pole radii (upper,
    lower tube, middle tube or 0), the shade's spokes and drop, the switch's angle, where an arc ends; the pole
    top ``top0`` the head was designed on, the head's reach, an arc's radius, a chain arm's plan."""

    floor: bool = False
    style: str = "straight"
    H: float = 0.0
    R: float = 0.0
    rs: float = 0.0
    z_b: float = 0.0
    r_up: float = 0.0
    r_lo: float = 0.0
    r_mid: float = 0.0
    spokes: int = 0
    shade_drop: float = 0.0
    switch_angle: float = 0.0
    curve_end: float = 0.0
    top0: float = 0.0
    reach_x: float = 0.0
    arc_radius: float = 0.0
    chain: ChainPlan | None = None


def _plan(p: dict, rng: np.random.Generator) -> LampPlan:
    names, w = list(SEGMENTS), np.array(list(SEGMENTS.values()))
    kinds = ["pitch"] + [names[int(rng.choice(len(names), p=w / w.sum()))] for _ in range(2)]
    u = rng.uniform
    draws = Draws(
        kinds=kinds,
        spokes=int(rng.integers(3, 5)),
        lean=math.radians(u(10.0, 28.0)),  # first chain segment, from vertical
        mid_angle=math.radians(u(-5.0, 20.0)),  # middle pitch segment of three
        last_angle=math.radians(u(-20.0, -4.0)),  # last pitch segment, down to the head
        riser=u(0.55, 0.68) if p["lamp_type"] == "floor" else u(0.15, 0.25),  # chain shoulder / H
        curve_end=math.radians(u(0.0, 30.0)),  # where an arc ends (0 = pointing straight down)
        shade_drop=u(0.1, 0.3),  # an upright shade's bottom below its spokes / its height
        switch_angle=u(-0.7, 0.7),
    )
    R = p["floor_base_radius"] if p["lamp_type"] == "floor" else p["desk_base_radius"]
    q = _design(p, draws, R)
    if q.reach_x * BASE_PER_REACH > R:  # an arm lamp needs a base that balances its head
        q = _design(p, draws, q.reach_x * BASE_PER_REACH)
    return q


def _design(p: dict, d: Draws, R: float) -> LampPlan:
    """Sizes and angles of the lamp from its parameters, the draws and the base radius."""
    floor = p["lamp_type"] == "floor"
    style = p["arm_style"]
    H = p["floor_height"] if floor else p["desk_height"]
    rs = p["floor_shade_radius"] if floor else p["desk_shade_radius"]
    if style != "straight":
        rs *= 0.75
    curve_end = d.curve_end
    r_up = p["pole_radius"]
    # a two-stage pole (floor lamps) has a middle tube between the upper pole and the lower tube
    r_mid = r_up + GAP + _tube_wall(r_up) if floor and p.get("pole_stages", 1) == 2 else 0.0
    r_lo = (r_mid or r_up) + GAP + _tube_wall(r_mid or r_up)
    t = p["base_thickness"]
    z_b = {"domed": t + 0.22 * R, "tripod": TRIPOD_HUB, "clamp": CLAMP["jaw"]}.get(p["base_shape"], t)
    q = LampPlan(floor=floor, style=style, H=H, R=R, rs=rs, z_b=z_b, r_up=r_up, r_lo=r_lo, r_mid=r_mid,
                 spokes=d.spokes, shade_drop=d.shade_drop, switch_angle=d.switch_angle,
                 curve_end=curve_end, **_knuckle(r_up).__dict__)
    reach = p["arm_reach"] * H

    if style == "straight":
        q = replace(q, top0=z_b + 0.7 * (H - z_b))
    elif style == "curved":
        tilt = None if floor else p["head_tilt"]
        for _ in range(25):
            head = _pendant(p, q, tilt)
            rc = max(reach, q.rs + r_lo + 0.03) / (1.0 + math.cos(curve_end))
            if tilt is not None:  # a head tilted back must stay clear of the pole
                rc = max(rc, (_swing_back(head, tilt) + r_lo + 0.012) / (1.0 + math.cos(curve_end)))
            # the head, tilted, stays a pole slide above the base (well clear of the switch)
            top = H - rc - r_up
            hinge = top + rc * math.sin(curve_end) - (q.r_h + 0.006)
            slide = 0.25 * (top - z_b) * (1 - p["lower_pole_fraction"])
            if hinge - slide - _swing_down(head, tilt or 0.0) >= z_b + 0.01:
                break
            q = replace(q, rs=q.rs * 0.92)  # too big a head for so short a lamp
        q = replace(q, arc_radius=rc, top0=H - rc - r_up, reach_x=rc * (1.0 + math.cos(curve_end)))
    else:
        for _ in range(12):
            plan = _chain_plan(p, q, d.kinds[:p["arm_segments"]], d.lean, d.mid_angle,
                               d.last_angle, reach, z_b + max(d.riser * H, 0.4 if floor else 0.09))
            if min(plan.forward) >= PITCH:
                break
            q = replace(q, rs=q.rs * 0.92)  # too big a head for so short a lamp
        q = replace(q, chain=plan, top0=plan.top0, reach_x=plan.reach_x)
    return q


def _chain_plan(p: dict, q: LampPlan, kinds: list[str], lean: float, mid: float, last: float, reach: float,
                top0: float) -> ChainPlan:
    """Segment angles and lengths of a chain arm, and the forward limit of each hinge.

    The last segment is long enough that its head, tilted back or swung down with
    the segment, stays in front of the hinge behind it; the first takes the height
    left over. If turning the arm forward by PITCH at any hinge would put the head on
    the ground, the middle segment and then the lean of the first shrink; failing
    that the hinge turns less far forward (never less than pi/12).
    """
    n, H, tilt = len(kinds), q.H, p["head_tilt"]
    head = _pendant(p, q, tilt)
    back = _swing_back(head, tilt)
    swing = _swing_back(head, PITCH)  # the segment before the head turned down
    for attempt in range(12):
        angles = [math.pi / 2 - lean]
        for k in range(1, n):
            angles.append(0.0 if kinds[k] == "swivel" else (last if k == n - 1 else mid))
        lengths = [0.0]
        for k in range(1, n):
            share = 0.75 * reach / (n - 1) / math.cos(angles[k])
            if k == n - 1:
                clear = q.r_h + 0.015
                share = max(share, (back + clear) / math.cos(angles[k]), q.rs + 0.05,
                            (swing + clear) / math.cos(abs(angles[k]) + PITCH))
            else:
                share = max(share * 0.8 ** attempt, 0.06)
            lengths.append(share)
        lengths[0] = 1.0
        pivots, E = _chain_points(q, kinds, angles, lengths, top0)
        zmax = max(P[2] for P in pivots[1:] + [E]) - (top0 + math.sin(angles[0]))
        lengths[0] = max((H - q.r_h - top0 - zmax) / math.sin(angles[0]), 0.1)
        pivots, E = _chain_points(q, kinds, angles, lengths, top0)
        if all(_lowest(P, E, head, PITCH) >= q.z_b + 0.01
               for P, kind in zip(pivots, kinds) if kind == "pitch"):
            break
        if attempt >= 4:
            lean = max(lean * 0.8, math.radians(4))
    # the largest forward turn of each hinge that keeps the head off the ground
    forward = []
    for P, kind in zip(pivots, kinds):
        a = PITCH
        while kind == "pitch" and a > math.pi / 12 and _lowest(P, E, head, a) < q.z_b + 0.01:
            a -= math.radians(1)
        forward.append(a)
    return ChainPlan(tuple(kinds), tuple(angles), tuple(lengths), top0, tuple(forward), float(E[0]))


def _chain_points(q: LampPlan, kinds: list[str], angles: list[float], lengths: list[float],
                  top0: float) -> tuple[list[np.ndarray], np.ndarray]:
    """The pivot of every chain joint and the head's hinge, at rest (mirrors ``_chain_arm``)."""
    P = np.array([0.0, 0.0, top0])
    pivots = []
    for k, kind in enumerate(kinds):
        if kind == "pitch":
            pivots.append(P)
            P = P + lengths[k] * np.array([math.cos(angles[k]), 0.0, math.sin(angles[k])])
        else:
            s = 1.0 if angles[k - 1] > math.radians(30) else -1.0
            C = P + (0.0, 0.0, s * (q.r_x + GAP + COLLAR_LEN / 2))
            pivots.append(C)
            P = C + (lengths[k], 0.0, 0.0)
    return pivots, P


def _lowest(P: np.ndarray, E: np.ndarray, head: Pendant, turn: float) -> float:
    """Lowest point of a head hanging at ``E`` when a hinge at ``P`` turns it forward by ``turn``."""
    X, Z = E[0] - P[0], E[2] - P[2]
    return P[2] + Z * math.cos(turn) - X * math.sin(turn) - _swing_down(head, turn)


def _tube_wall(r_up: float) -> float:
    return max(0.0015, 0.2 * r_up)


def _knuckle(r_up: float) -> Knuckle:
    """Sizes of the hinges of a chain arm, from the pole radius."""
    w = 2 * (r_up + 0.003)  # width of a central hub
    return Knuckle(
        w_c=w,
        r_h=r_up + 0.004,  # hub and cheek radius
        r_c=min(0.0075, w / 2 - 0.0015),  # central bar radius (up to a 15 mm tube)
        y_tw=w / 2 + GAP + TWIN_R,  # twin bar centre line
        r_pin=0.004,
        r_x=r_up + 0.004,  # half height of the block a swivel pin hangs from
    )


ROTARY_TURN = 5.2  # a rotary dimmer knob turns about 300 degrees end to end (Lutron rotary dimmers, dimmable
#                    LED desk lamps with a base dial)
ROTARY_H = 0.014  # knob height above its boss


def _on_base_top(p: dict, q: LampPlan, half: float) -> tuple[float, float]:
    """``(radius, height)`` on the base's top where a control ``half`` wide (radially) sits: near the rim of
    a square or round base, in the middle of a dome's flat rim."""
    R, t, shape = q.R, p["base_thickness"], p["base_shape"]
    if shape == "square":
        return 0.9 * R - half - 0.006, t
    if shape == "round":
        return R - 0.4 * t - half - 0.004, t
    return 0.85 * R, 0.5 * t


def _rotary(bp: Blueprint, p: dict, q: LampPlan) -> None:
    """A rotary dimmer knob standing on the base's top (on a dome's flat rim), turning about z: a boss in the
    base, the knob 1 mm above it with a pointer rib on top. About a vertical axis it is neutral under gravity."""
    r_k = float(np.clip(0.1 * q.R, 0.008, 0.012))
    rho, z = _on_base_top(p, q, r_k)
    a = q.switch_angle
    c = np.array([rho * math.cos(a), rho * math.sin(a), 0.0])
    boss = g.cylinder(c + (0, 0, z - 0.001), c + (0, 0, z + 0.003), 0.45 * r_k, "switch", 20)
    knob = [g.cylinder(c + (0, 0, z + 0.004), c + (0, 0, z + 0.004 + ROTARY_H), r_k, "switch", 32),
            g.box_between(c + (-0.6 * r_k, -0.0012, z + 0.004 + ROTARY_H), c + (0.6 * r_k, 0.0012,
                                                                               z + 0.006 + ROTARY_H), "switch")]
    bp.extend("base", [boss])
    bp.add("switch", "switch", knob)
    bp.join(J.revolute("base", "switch", c + (0, 0, z + 0.004), (0, 0, 1), 0.0, ROTARY_TURN, role="knob"))


def _rocker(bp: Blueprint, p: dict, q: LampPlan) -> None:
    """A rocker switch (:func:`~categories.parts.hardware.rocker_switch`) on the base's top (on a dome's
    flat rim), its long side along the base radius: the bezel is the base's, the paddle tilts about the
    tangent. Balanced on its pivot, it rests on its "off" stop."""
    from .hardware import ROCKER, rocker_switch

    half = ROCKER["length"] / 2
    rho, z = _on_base_top(p, q, half)
    rho = max(rho, q.r_lo + half + 0.008)  # clear of the lower pole's tube
    a = q.switch_angle
    rocker = rocker_switch("switch").attached(
        "mount", to=Frame.at((rho * math.cos(a), rho * math.sin(a), z), x=(math.cos(a), math.sin(a), 0.0)))
    bp.extend("base", rocker.parts["bezel"].pieces)
    bp.add("switch", "switch", rocker.parts["rocker"].pieces)
    (joint,) = rocker.joints
    bp.join(replace(joint, parent="base", child="switch"))


SOCKET_KNOB_Z = 0.012  # a turn-knob socket's knob: its axis this far above the socket floor
SOCKET_KNOB = (0.0025, 0.004, 0.0065, 0.009)  # stem radius and length, knob radius and length (E27 turn-knob
#                                              sockets: a 12-14 mm knurled knob on a 4-5 mm stem)


def _socket_knob(bp: Blueprint, p: dict, q: LampPlan, r_so: float, z: float, prof: np.ndarray, th: float,
                 z0: float) -> None:
    """The knob of a turn-knob socket (the classic table lamp switch: each turn clicks it on or off), standing
    out of the socket's side between two spokes, 1 mm off the shell, turning about its own radial axis:
    balanced on that axis, gravity leaves it where it is. A shade too narrow there keeps the knob shorter."""
    r_st, l_st, r_k, l_k = SOCKET_KNOB
    a = math.pi / 2 + math.pi / q.spokes
    d = np.array([math.cos(a), math.sin(a), 0.0])
    room = float(_inner_radius(prof, th, z0, np.array([z - r_k, z, z + r_k])).min()) - r_so - 0.004
    l_k = float(np.clip(room - l_st - 0.001, 0.004, l_k))
    r0 = r_so + 0.001
    c = np.array([0.0, 0.0, z])
    knob = [g.cylinder(c + d * r0, c + d * (r0 + l_st), r_st, "switch", 16),
            g.cylinder(c + d * (r0 + l_st), c + d * (r0 + l_st + l_k), r_k, "switch", 24)]
    bp.add("switch", "switch", knob)
    bp.join(J.continuous("head", "switch", c + d * r0, d, role="knob"))


# ---------------------------------------------------------------------------
# assembly at a given pole top height


def _stand(bp: Blueprint, p: dict, q: LampPlan, z_top: float) -> None:
    """The base, its switch and the poles, the upper pole's top at ``z_top``."""
    z_b = q.z_b
    _base(bp, p, q)
    if p["has_switch"] and p.get("switch_kind") != "socket_switch":
        {"rotary_switch": _rotary, "rocker_switch": _rocker}.get(p.get("switch_kind"), _switch)(bp, p, q)

    # --- lower pole: a tube on the base; upper pole slides and turns in it ----
    r_up, r_lo, r_mid = q.r_up, q.r_lo, q.r_mid
    tw = _tube_wall(r_mid or r_up)
    S = z_top - z_b
    T = p["lower_pole_fraction"] * S
    z_t = z_b + T
    L = z_top - z_t
    # two stages: a middle tube shows half the length above the lower tube, and slides as one stage does
    z_m = z_t + 0.5 * L if r_mid else z_top
    slide = 0.25 * (z_m - z_t)
    spare = T - slide - 0.004  # tube depth left below the pole end at rest (collapsed)
    z_ub = z_t - 0.5 * spare - slide  # the pole end at rest; fully extended it is still 0.5 spare deep
    lower = [
        _ring([(r_lo, z_b), (r_lo, z_t - 0.014)], tw, "pole"),
        _ring([(r_lo + 0.002, z_t - 0.014), (r_lo + 0.002, z_t)], tw + 0.002, "pole"),  # collar
        _ring([(r_lo + 0.007, z_b), (r_lo + 0.002, z_b + 0.01)], tw + 0.002, "pole"),  # foot
    ]
    bp.add("lower_pole", "pole", lower)
    bp.join(J.fixed("base", "lower_pole"))
    first = "middle_pole" if r_mid else "upper_pole"
    if r_mid:  # a tube like the lower one, with its collar; the upper pole slides (without turning) in it
        tw_m = _tube_wall(r_up)
        bp.add("middle_pole", "pole", [_ring([(r_mid, z_ub), (r_mid, z_m - 0.012)], tw_m, "pole"),
                                       _ring([(r_mid + 0.0015, z_m - 0.012), (r_mid + 0.0015, z_m)], tw_m + 0.0015,
                                             "pole")])
        slide2 = 0.25 * (z_top - z_m)
        spare2 = (z_m - z_ub) - slide2 - 0.004
        bp.add("upper_pole", "pole", [_tube((0, 0, z_m - 0.5 * spare2 - slide2), (0, 0, z_top), r_up, 24)])
        bp.join(J.prismatic("middle_pole", "upper_pole", (0, 0, z_m), (0, 0, 1), 0.0, slide2, role="telescope"))
    else:
        bp.add("upper_pole", "pole", [_tube((0, 0, z_ub), (0, 0, z_top), r_up, 24)])
    bp.join(J.revolute_prismatic("lower_pole", first, (0, 0, z_t), (0, 0, 1), (-math.pi, math.pi),
                                 (0, 0, 1), (0.0, slide), role="telescope"))


def _head(p: dict, q: LampPlan, z_top: float) -> Blueprint:
    """What the upper pole carries (head, arm, shade, bulb), its top at ``z_top``, in a blueprint whose
    ``upper_pole`` holds a stand-in block at the pole top (the first piece) and what the arm adds to it."""
    bp = Blueprint("lamp")
    r = q.r_up
    bp.add("upper_pole", "pole", [g.box_between((-r, -r, z_top - r), (r, r, z_top), "pole")])
    style = q.style
    if style == "straight":
        _upright_head(bp, p, q, z_top)
    elif style == "curved":
        _curved_arm(bp, p, q, z_top)
    else:
        _chain_arm(bp, p, q, z_top)
    return bp


def _move_head(bp: Blueprint, head: Blueprint, dz: float) -> None:
    """Add ``head`` (:func:`_head`, without its stand-in) to ``bp``, moved up by ``dz``: parts and joints."""
    d = np.array([0.0, 0.0, dz])
    for name, part in head.parts.items():
        if name == "upper_pole":
            bp.extend(name, [pc.translated(d) for pc in part.pieces[1:]])
        else:
            bp.add(name, part.label, [pc.translated(d) for pc in part.pieces])
    for j in head.joints:
        bp.join(replace(j, dofs=tuple(replace(f, origin=tuple(float(x) for x in np.add(f.origin, d)))
                                      for f in j.dofs)))


def _base(bp: Blueprint, p: dict, q: LampPlan) -> None:
    R, t, shape = q.R, p["base_thickness"], p["base_shape"]
    if shape == "tripod":
        bp.add("base", "base", _tripod(q.r_lo, R, q.z_b))
        return
    if shape == "clamp":
        _clamp(bp, q.r_lo)
        return
    if shape == "square":
        a = 0.9 * R
        piece = g.box_between((-a, -a, 0), (a, a, t), "base", bevel=min(0.004, t / 4))
    elif shape == "round":
        piece = g.revolve([(0, 0), (R, 0), (R, 0.6 * t), (R - 0.4 * t, t), (0, t)], "base")
    else:
        rim, z_rim, z_b = 0.3 * R, 0.5 * t, q.z_b
        r_top = q.r_lo + 0.009
        prof = [(0, 0), (R, 0), (R, z_rim), (R - rim, z_rim)]
        for f in np.linspace(0, math.pi / 2, 7)[1:]:
            prof.append((r_top + (R - rim - r_top) * math.cos(f), z_rim + (z_b - z_rim) * math.sin(f)))
        prof.append((0, z_b))
        piece = g.revolve(prof, "base")
    bp.add("base", "base", [piece, _weight(shape, R, t, prof if shape == "domed" else None)])


def _clamp(bp: Blueprint, r_lo: float) -> None:
    """A desk clamp under the pole (the desk top is z = 0, the desk edge the spine's inner face): the upper jaw
    carries the pole's foot, the spine runs down behind it, the lower jaw has a hole the spindle turns in. The
    spindle (rod, pad on top, T-bar below) turns freely and rises until its pad meets the upper jaw
    (continuous-prismatic, like a screw); at rest it hangs on its lower stop, the pad on the lower jaw."""
    c = CLAMP
    tj, th = c["jaw"], c["throat"]
    w = max(0.045, 2 * (r_lo + 0.012)) / 2  # the upper jaw is wider than the pole's foot ring
    x0, x1 = -c["back"], max(c["front"], r_lo + 0.012)
    xs = c["screw_x"]
    hole = c["rod"] + GAP
    z_lo = -th - tj  # the lower jaw's underside
    pieces = [
        g.box_between((x0, -w, 0.0), (x1, w, tj), "clamp", bevel=0.002),  # upper jaw (on the desk)
        g.box_between((x0, -w, z_lo), (x0 + c["spine"], w, 0.0), "clamp", bevel=0.002),  # spine
        g.panel([x0 + c["spine"], -w, z_lo], [x1, w, -th], "clamp", "z",
                holes=[(xs - hole, -hole, xs + hole, hole)]),  # lower jaw, the spindle's hole through it
    ]
    bp.add("base", "base", [pc.replace(wall=0.0) for pc in pieces])  # cast: solid
    travel = th - 2 * GAP - c["pad_t"]  # the pad rises to GAP under the upper jaw
    z_bar = z_lo - GAP - travel - c["bar"]  # the T-bar clears the lower jaw with the pad at the top
    screw = [
        g.cylinder((xs, 0, z_bar - c["bar"]), (xs, 0, -th + GAP), c["rod"], "clamp", 16),
        g.cylinder((xs, 0, -th + GAP), (xs, 0, -th + GAP + c["pad_t"]), c["pad"], "fitting", 24),
        g.cylinder((xs, -c["bar_len"] / 2, z_bar), (xs, c["bar_len"] / 2, z_bar), c["bar"], "clamp", 16),
    ]
    bp.add("screw", "screw", [pc.replace(wall=0.0) for pc in screw])
    bp.join(J.continuous_prismatic("base", "screw", (xs, 0, -th + GAP), (0, 0, 1), (0.0, travel), role="lid"))


def _tripod(r_lo: float, R: float, z_hub: float) -> list[g.Piece]:
    """A hub under the pole and three splayed legs (one under the head, +x) to rubber-tipped feet on a circle
    ``TRIPOD_SPAN * R`` wide; a steel slug in the hub (no collision) adds weight low down."""
    r_hub, r_leg = r_lo + 0.008, max(0.007, 0.8 * r_lo)
    out = [g.cylinder((0, 0, z_hub - 0.05), (0, 0, z_hub), r_hub, "base", 32)]
    for k in range(3):
        a = 2 * math.pi * k / 3
        d = np.array([math.cos(a), math.sin(a), 0.0])
        top = d * 0.6 * r_hub + (0, 0, z_hub - 0.035)
        foot = d * TRIPOD_SPAN * R + (0, 0, 0.012)
        out += [g.cylinder(top, foot, r_leg, "pole", 16),
                g.cylinder(foot - (0, 0, 0.012), foot + (0, 0, 0.004), r_leg + 0.003, "fitting", 16)]
    # the slug is solid steel (wall 0): a hollow one left small desk tripods at 0.37 kg, lighter than any real
    # tripod desk lamp (0.8-1.5 kg: IKEA / Hay listings); solid, a 25 mm hub's slug adds ~0.6 kg
    out.append(g.cylinder((0, 0, z_hub - 0.048), (0, 0, z_hub - 0.002), r_hub - 0.002, "weight", 24).replace(
        convex=[], wall=0.0))
    return out


def _weight(shape: str, R: float, t: float, prof: list | None = None) -> g.Piece:
    """The steel weight hidden inside the base (most of its volume): it adds mass, not collisions."""
    if shape == "square":
        a = 0.9 * R - 0.003
        w = g.box_between((-a, -a, 0.06 * t), (a, a, 0.94 * t), "weight")
    elif shape == "round":
        w = g.disc((0, 0, t / 2), R - 0.45 * t, 0.88 * t, "weight", 48)
    else:  # under the dome: its profile pulled inward and down
        z0 = 0.06 * t
        inner = [(0.95 * r, z0 + 0.9 * (z - z0)) for r, z in prof[3:-1]]
        w = g.revolve([(0, z0), (0.95 * prof[2][0], z0), *inner, (0, inner[-1][1])], "weight")
    return w.replace(convex=[])


def _switch(bp: Blueprint, p: dict, q: LampPlan) -> None:
    """A push button in a small housing on the base, pressed horizontally toward the pole.

    The housing (part of the base) is a box open to the outside: floor, roof, two
    side walls and a back wall around a pocket; the button slides in the pocket
    along the base radius, so gravity exerts no force along its stroke.
    """
    R, t, shape = q.R, p["base_thickness"], p["base_shape"]
    r_sw = float(np.clip(0.1 * R, 0.007, 0.012))
    hw = 0.45 * r_sw  # half width and half height of the button
    w, travel = SWITCH_WALL, SWITCH_TRAVEL
    ins, out = 0.003, travel + 0.003  # button depth in the pocket and length out of it, at rest
    x_front = w + GAP + travel + ins  # housing front face from its back
    length = x_front + out
    if shape == "square":
        edge, z, inner = 0.9 * R - 0.003, t, q.r_lo + 0.016
    elif shape == "round":
        edge, z, inner = R - 0.4 * t - 0.002, t, q.r_lo + 0.016
    else:  # on the flat rim, its back against the dome
        edge, z, inner = R - 0.002, 0.5 * t, 0.7 * R - 0.0005
    x0 = max(edge - length, inner)
    Y = hw + GAP + w  # housing half width
    zc0, zc1 = z + w, z + w + 2 * (GAP + hw)  # the pocket
    local = [
        g.box_between((x0, -Y, z - 0.001), (x0 + x_front, Y, zc0), "switch"),  # floor
        g.box_between((x0, -Y, zc1), (x0 + x_front, Y, zc1 + w), "switch"),  # roof
        g.box_between((x0, -Y, zc0), (x0 + x_front, -Y + w, zc1), "switch"),  # sides
        g.box_between((x0, Y - w, zc0), (x0 + x_front, Y, zc1), "switch"),
        g.box_between((x0, -Y + w, zc0), (x0 + w, Y - w, zc1), "switch"),  # back
    ]
    x_b = x0 + w + GAP + travel  # button inner end at rest (GAP from the back wall when pressed)
    button = g.box_between((x_b, -hw, zc0 + GAP), (x0 + length, hw, zc1 - GAP), "switch",
                           bevel=min(0.001, 0.2 * hw))
    a = q.switch_angle
    m = np.eye(4)
    m[:3, :3] = [[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]
    bp.extend("base", [pc.transformed(m) for pc in local])
    bp.add("switch", "switch", [button.transformed(m)])
    u = (math.cos(a), math.sin(a), 0.0)
    face = np.array(u) * (x0 + length) + (0, 0, (zc0 + zc1) / 2)
    bp.join(J.prismatic("base", "switch", face, (-u[0], -u[1], 0.0), 0.0, travel, role="button"))


# ---------------------------------------------------------------------------
# shades and bulbs


def _shade_profile(shape: str, rb: float, h: float, top_ratio: float, r_top_min: float) -> np.ndarray:
    """Outer ``(radius, z)`` profile from the opening (z = 0) up to the top ring."""
    if shape == "drum":
        return np.array([(rb, 0.0), (max(0.96 * rb, r_top_min), h)])
    if shape == "cone":
        return np.array([(rb, 0.0), (max(top_ratio * rb, r_top_min), h)])
    if shape == "bell":
        rt = max(top_ratio * rb, r_top_min)
        s = np.linspace(0, 1, 6)
        return np.c_[rt + (rb - rt) * (1 - s) ** 2, h * s]
    phi_max = math.acos(min(r_top_min / rb, 0.95))
    f = np.linspace(0, phi_max, 7)
    return np.c_[rb * np.cos(f), h * np.sin(f) / math.sin(phi_max)]


def _shade_height(p: dict, shape: str, rb: float) -> float:
    ratio = p["shade_height_ratio"]
    if shape == "dome":
        return rb * float(np.clip(0.75 * ratio, 0.55, 0.95))
    return rb * ratio


def _inner_radius(prof: np.ndarray, th: float, z0: float, z: np.ndarray) -> np.ndarray:
    """Inner radius of a shade whose opening is at ``z0``; inf outside its height."""
    r = np.interp(z - z0, prof[:, 1], prof[:, 0]) - th
    return np.where((z < z0) | (z > z0 + prof[-1, 1]), np.inf, r)


def _fits(prof: np.ndarray, th: float, z0: float, lo: float, hi: float, r_need: float) -> bool:
    z = np.r_[np.linspace(lo, hi, 41), prof[:, 1] + z0]
    z = z[(z >= lo) & (z <= hi)]
    return bool((_inner_radius(prof, th, z0, z) >= r_need).all())


def _bulb_profile(r_g: float, r_neck: float) -> tuple[np.ndarray, float]:
    """``(radius, s)`` of a bulb's glass, ``s`` measured from the screw end; and its length."""
    s_c = 0.8 * r_g + 0.6 * r_g
    psi = np.linspace(math.acos(0.8), math.pi, 10)[:-1]
    globe = np.c_[r_g * np.sin(psi), s_c - r_g * np.cos(psi)]
    tip = s_c + r_g
    near_tip = [0.0015, s_c + math.sqrt(r_g**2 - 0.0015**2)]
    return np.vstack([[r_neck, 0.0], globe, near_tip, [0.0, tip]]), tip


def _glass(profile: np.ndarray, center: tuple[float, float, float]) -> g.Piece:
    """A bulb's glass: a thin wall (so it weighs what glass does), colliding as one solid hull."""
    solid = g.revolve(profile, "bulb", center=center)
    wall = g.shell(profile[profile[:, 0] > 0.001], 0.0008, "bulb", center=center)
    return g.Piece(wall.vertices, wall.faces, "bulb", [np.vstack(solid.convex)])


def _ring(outer, thickness: float, slot: str, center=(0.0, 0.0, 0.0)) -> g.Piece:
    """A small tube wall (socket, collar, the lower pole): 8 wide wedges collide, not 16 slivers."""
    return g.shell(outer, thickness, slot, center=center, convex_sectors=8)


def _cap(r_cap: float, h_cap: float, slot: str, center: tuple[float, float, float]) -> list[g.Piece]:
    """A pressed-metal cap over a shade's top ring: a thin dome, colliding as a solid one."""
    r_top = max(0.55 * r_cap, 0.012)
    prof = [(r_cap, 0.0), (r_cap, 0.004), (r_top, h_cap)]
    solid = g.revolve([(0, 0), *prof, (0, h_cap)], slot, center=center)
    wall = g.shell(prof, 0.0015, slot, center=center)
    top = g.disc((center[0], center[1], center[2] + h_cap - 0.001), r_top, 0.002, slot, 40)
    return [wall.with_collision_of(solid), top]


def _shade_thickness(p: dict) -> float:
    return 0.003 if p["shade_finish"] == "fabric" else 0.0012


# ---------------------------------------------------------------------------
# heads


def _upright_head(bp: Blueprint, p: dict, q: LampPlan, z_top: float) -> None:
    """A collar around the pole top, a cup and socket, the bulb standing up, spokes, shade."""
    r_up, rb = q.r_up, q.rs
    shape = p["shade_shape"]
    th = _shade_thickness(p)
    r_so = float(np.clip(0.15 * rb, 0.011, 0.016))
    r_col = r_up + GAP + 0.002
    z_cup = z_top + GAP
    z_sock = z_cup + 0.006  # socket floor
    r_cup = max(r_so, r_col) + 0.002
    head = [
        _ring([(r_col, z_top - 0.025), (r_col, z_cup)], 0.002, "fitting"),
        g.disc((0, 0, (z_cup + z_sock) / 2), r_cup, z_sock - z_cup, "fitting"),
        _ring([(r_so, z_sock), (r_so, z_sock + 0.035)], 0.002, "fitting"),
    ]
    # the bulb: screw in the socket, glass above it
    r_sc = r_so - 0.004
    z_sb = z_sock + 0.035 + 0.004  # top of the screw cap = start of the glass
    h = _shade_height(p, shape, rb)
    r_g = float(np.clip(min(0.4 * rb, 0.25 * h), 0.014, 0.032))
    z_sp = z_sock + 0.028  # spoke height, near the socket top
    r_top_min = 0.012 if shape == "dome" else r_so + 0.01
    prof = _shade_profile(shape, rb, h, p["shade_top_ratio"], r_top_min)
    for _ in range(40):  # shrink the bulb (and grow a dome) until the bulb fits its shade
        bulb_prof, tip = _bulb_profile(r_g, r_sc + 0.001)
        lo, hi = z_sb, z_sb + tip + BULB_TRAVEL + GAP
        # the shade hangs on the spokes, raised to cover the bulb where it is tall enough
        hs = prof[-1, 1]
        z0 = min(z_sp - 0.012, max(z_sp - q.shade_drop * hs, z_sb + tip + 0.01 - hs))
        if shape == "dome" and z0 + hs < hi + 0.01:
            h *= 1.08
            prof = _shade_profile(shape, rb, h, p["shade_top_ratio"], r_top_min)
            continue
        if _fits(prof, th, z0, lo, hi, r_g + 0.005):
            break
        r_g *= 0.95
    bp.add("head", "head", head)
    bp.join(J.continuous("upper_pole", "head", (0, 0, z_top), (0, 0, 1), role="swivel"))

    shade = [g.shell(prof, th, "shade", center=(0, 0, z0))]
    if shape == "dome":  # a finial closes the top hole
        z1 = z0 + prof[-1, 1]
        shade.append(g.disc((0, 0, z1 + 0.003), prof[-1, 0] + 0.004, 0.006, "fitting"))
        shade.append(g.sphere((0, 0, z1 + 0.009), 0.007, "fitting"))
    r_wall = float(_inner_radius(prof, th, z0, np.array([z_sp]))[0]) + th / 2
    for k in range(q.spokes):
        a = 2 * math.pi * k / q.spokes + math.pi / 2
        d = np.array([math.cos(a), math.sin(a), 0.0])
        shade.append(g.cylinder(d * (r_so - 0.001) + (0, 0, z_sp), d * r_wall + (0, 0, z_sp), 0.0018,
                                "fitting", 8))
    bp.add("shade", "shade", shade)
    bp.join(J.fixed("head", "shade"))

    if p["has_switch"] and p.get("switch_kind") == "socket_switch":
        _socket_knob(bp, p, q, r_so, z_sock + SOCKET_KNOB_Z, prof, th, z0)

    if p["has_bulb"]:
        glass = np.vstack([[0.0, z_sb], np.c_[bulb_prof[:, 0], z_sb + bulb_prof[:, 1]]])
        pieces = [_tube((0, 0, z_sock + 0.003), (0, 0, z_sb + 0.0005), r_sc, 24, "bulb_cap", 0.0004),
                  _glass(glass, (0.0, 0.0, 0.0))]
        bp.add("bulb", "bulb", pieces)
        bp.join(J.continuous_prismatic("head", "bulb", (0, 0, z_sock + 0.003), (0, 0, 1),
                                       (0.0, BULB_TRAVEL), role="lid"))


@dataclass(frozen=True, eq=False)
class Pendant:
    """A hanging head's sizes (:func:`_pendant`): shade wall, profile and height, socket, cap and bulb, how far
    the cap hangs below the mount (``d_neck``) and the head's outline ``pts``."""

    th: float
    r_so: float  # socket radius
    prof: np.ndarray  # shade profile (radius, height)
    hs: float  # shade height
    r_cap: float
    h_cap: float
    r_sc: float  # bulb screw radius
    r_g: float  # bulb glass radius
    bulb_prof: np.ndarray
    tip: float
    d_neck: float
    pts: tuple[tuple[float, float], ...]  # (radius, depth below the mount), the bulb fully unscrewed included


def _pendant(p: dict, q: LampPlan, tilt: float | None) -> Pendant:
    """Sizes of a hanging head (cap, socket, shade, bulb) and how far its cap hangs below the mount.

    ``pts`` are ``(radius, depth below the mount)`` of the head's outline, bulb
    fully unscrewed included, for reasoning about the space a turning head sweeps.
    """
    rb, shape = q.rs, p["shade_shape"]
    th = _shade_thickness(p)
    r_so = float(np.clip(0.16 * rb, 0.010, 0.015))
    prof = _shade_profile(shape, rb, _shade_height(p, shape, rb), p["shade_top_ratio"], r_so + 0.004 + th)
    hs = float(prof[-1, 1])
    r_cap = float(prof[-1, 0]) + 0.003
    h_cap = 0.012 + 0.06 * r_cap
    # bulb size: it hangs below the socket and must fit the shade while it unscrews
    r_sc = r_so - 0.004
    r_g = float(np.clip(0.42 * rb, 0.018, 0.032))
    for _ in range(30):
        bulb_prof, tip = _bulb_profile(r_g, r_sc + 0.001)
        # heights relative to the cap bottom; the screw end is SOCKET_LEN + 0.004 below it
        lo, hi = -(SOCKET_LEN + 0.004 + tip + BULB_TRAVEL + GAP), -(SOCKET_LEN + 0.004)
        if r_g <= 0.012 or _fits(prof, th, -hs, lo, hi, r_g + 0.005):
            break
        r_g *= 0.95
    outline = [(0.6 * r_cap, 0.0), (r_cap, h_cap - 0.004), (0.7 * q.r_h, -0.005)]
    outline += [(float(r), h_cap + hs - float(z)) for r, z in prof]
    outline += [(r_g, h_cap + SOCKET_LEN + 0.004 + tip + BULB_TRAVEL)]
    if tilt is None:
        d_neck = q.r_x + GAP + COLLAR_LEN  # collar below the pin block
    else:  # a tilted head must stay under the parent's bars
        r_par = 1.15 * q.r_h + GAP
        sa, ca = math.sin(tilt), math.cos(tilt)
        d_neck = max(q.r_h + GAP + 0.008, max((r_par + r * sa) / ca - d for r, d in outline))
    return Pendant(th, r_so, prof, hs, r_cap, h_cap, r_sc, r_g, bulb_prof, tip, d_neck,
                   tuple((r, d + d_neck) for r, d in outline))


def _swing_back(head: Pendant, tilt: float) -> float:
    """How far behind its hinge a head reaches when tilted back by ``tilt``."""
    return max(r * math.cos(tilt) + d * math.sin(tilt) for r, d in head.pts)


def _swing_down(head: Pendant, turn: float) -> float:
    """How far below its mount a head reaches when turned by ``turn`` (about a horizontal axis)."""
    return max(d * math.cos(turn) + r * math.sin(turn) for r, d in head.pts)


def _hanging_head(bp: Blueprint, p: dict, q: LampPlan, parent: str, mount: str, E: np.ndarray,
                  tilt: float | None) -> None:
    """A head hanging below ``E``.

    ``mount``: ``"yoke"`` (side cheeks around the parent's central hub at ``E``),
    ``"hub"`` (a central hub between the parent's twin cheeks at ``E``) or
    ``"collar"`` (a ring around the parent's pin, which hangs from ``E``).
    ``tilt``: the +- limit of the head's hinge about Y, or None for a head that
    turns freely about Z.
    """
    hd = _pendant(p, q, tilt)
    prof, hs, r_cap, h_cap, r_so = hd.prof, hd.hs, hd.r_cap, hd.h_cap, hd.r_so
    cap_slot = "shade" if p["shade_finish"] == "painted" else "pole"
    x, y = E[0], E[1]
    z_c = E[2] - hd.d_neck  # cap top
    z_cb = z_c - h_cap  # cap bottom = shade top = socket top
    # the socket: a moulded shell with a 3 mm wall, closed at the cable end (an E27 pendant socket is a
    # solid bakelite or porcelain part of 30-60 g; a 2 mm open ring left a floor arc lamp's head at 9.7 g)
    head = _cap(r_cap, h_cap, cap_slot, (x, y, z_cb)) + [
        _ring([(r_so, z_cb - SOCKET_LEN), (r_so, z_cb)], SOCKET_WALL, "fitting", center=(x, y, 0)),
        g.disc((x, y, z_cb - 0.001), r_so - SOCKET_WALL, 0.002, "fitting", 24),
    ]
    w, r_h = q.w_c, q.r_h
    if mount == "yoke":
        y_in, y_out = w / 2 + GAP, w / 2 + GAP + 2 * TWIN_R
        for s in (-1, 1):
            y0, y1 = sorted((s * y_in, s * y_out))
            head.append(g.cylinder((x, y0, E[2]), (x, y1, E[2]), r_h, "pole"))
            ym = (y0 + y1) / 2  # sheet-metal yoke plates, in the middle of the cheeks
            head.append(g.box_between((x - 0.7 * r_h, ym - TWIN_R / 2, z_c - 0.002),
                                      (x + 0.7 * r_h, ym + TWIN_R / 2, E[2]), "pole"))
        head.append(g.box_between((x - 0.7 * r_h, -y_out + TWIN_R / 2, z_c - 0.002),
                                  (x + 0.7 * r_h, y_out - TWIN_R / 2, z_c + 0.003), "pole"))
    elif mount == "hub":
        head.append(g.cylinder((x, -w / 2, E[2]), (x, w / 2, E[2]), r_h, "pole"))
        head.append(g.cylinder((x, 0, E[2]), (x, 0, z_c - 0.002), q.r_c, "pole"))
    else:  # collar around the parent's pin
        r_in = q.r_pin + GAP
        head.append(_ring([(r_in + 0.002, z_c - 0.001), (r_in + 0.002, z_c + COLLAR_LEN)], 0.002, "pole",
                            center=(x, y, 0)))
    bp.add("head", "head", head)
    if tilt is None:
        bp.join(J.continuous(parent, "head", (x, y, z_c + COLLAR_LEN / 2), (0, 0, 1), role="swivel"))
    else:
        bp.join(J.revolute(parent, "head", (x, y, E[2]), (0, -1, 0), -tilt, tilt, role="swivel"))

    bp.add("shade", "shade", [g.shell(prof, hd.th, "shade", center=(x, y, z_cb - hs))])
    bp.join(J.fixed("head", "shade"))

    if p["has_bulb"]:
        bulb_prof, tip = hd.bulb_prof, hd.tip
        z_sb = z_cb - SOCKET_LEN - 0.004
        glass = np.vstack([[0.0, z_sb - tip], np.c_[bulb_prof[::-1, 0], z_sb - bulb_prof[::-1, 1]][1:],
                           [[0.0, z_sb]]])
        pieces = [_tube((x, y, z_cb - 0.003), (x, y, z_sb - 0.0005), hd.r_sc, 24, "bulb_cap", 0.0004),
                  _glass(glass, (x, y, 0.0))]
        bp.add("bulb", "bulb", pieces)
        # it only turns: gravity would pull a hanging bulb out along a free slide (the head
        # keeps room for BULB_TRAVEL below it all the same)
        bp.join(J.continuous("head", "bulb", (x, y, z_cb - 0.003), (0, 0, -1), role="lid"))


# ---------------------------------------------------------------------------
# arms


def _curved_arm(bp: Blueprint, p: dict, q: LampPlan, z_top: float) -> None:
    """A fixed arc of tube from the pole top, bending forward and down; the head hangs at its end."""
    rc, pe, r = q.arc_radius, q.curve_end, q.r_up
    phis = np.linspace(math.pi, pe, 16)
    pts = [np.array([rc + rc * math.cos(f), 0.0, z_top + rc * math.sin(f)]) for f in phis]
    pieces = []
    ext = r * math.tan(abs(phis[1] - phis[0]) / 2)  # overlap at the bends, so they stay closed
    for i, (a, b) in enumerate(zip(pts[:-1], pts[1:])):
        d = (b - a) / np.linalg.norm(b - a)
        pieces.append(_tube(a - d * (ext if i else 0.0), b + d * ext, r))
    E0 = pts[-1]
    r_x = q.r_x
    if q.floor:
        pieces.append(g.sphere(E0, r_x, "pole"))  # a pin hangs from the end; the head turns on it
        pieces.append(g.cylinder(E0, E0 - (0, 0, r_x + COLLAR_LEN), q.r_pin, "pole", 16))
        bp.add("arm", "arm", pieces)
        bp.join(J.fixed("upper_pole", "arm"))
        _hanging_head(bp, p, q, "arm", "collar", E0, None)
    else:  # a short drop to a hub; the head tilts on it
        E = E0 - (0, 0, q.r_h + 0.006)
        pieces.append(g.sphere(E0, r, "pole"))
        pieces.append(g.cylinder(E0, E, 0.8 * r, "pole", 16))
        pieces.append(g.cylinder(E - (0, q.w_c / 2, 0), E + (0, q.w_c / 2, 0), q.r_h, "pole"))
        bp.add("arm", "arm", pieces)
        bp.join(J.fixed("upper_pole", "arm"))
        _hanging_head(bp, p, q, "arm", "yoke", E, p["head_tilt"])


def _chain_arm(bp: Blueprint, p: dict, q: LampPlan, z_top: float) -> None:
    """Segments hinged end to end; see the module docstring for the two joint kinds."""
    w, r_h, r_c, y_tw = q.w_c, q.r_h, q.r_c, q.y_tw
    kinds, angles, lengths = q.chain.kinds, q.chain.angles, q.chain.lengths
    n = len(kinds)
    # the pole top is a central hub
    P = np.array([0.0, 0.0, z_top])
    bp.extend("upper_pole", [_ycyl(P, -w / 2, w / 2, r_h)])
    parent, parent_type, parent_angle = "upper_pole", "central", math.pi / 2
    for k in range(n):
        name = f"arm_{k}"
        nxt = kinds[k + 1] if k + 1 < n else "head"
        if kinds[k] == "pitch":
            kind = "twin" if parent_type == "central" else "central"
            d = np.array([math.cos(angles[k]), 0.0, math.sin(angles[k])])
            E = P + lengths[k] * d
            pieces = _segment_body(q, kind, P, E)
            # +q lifts the arm, -q turns it forward and down; the core's rest_on_stops keeps the side
            # that lifts what it carries against gravity
            lower = -q.chain.forward[k]
            joint = J.revolute(parent, name, P, (0, -1, 0), lower, PITCH, role="swivel")
        else:  # swing arm on the parent's pin, horizontal
            kind = "central"
            s = 1.0 if parent_angle > math.radians(30) else -1.0
            r_in = q.r_pin + GAP
            z0 = P[2] + s * (q.r_x + GAP)
            z1 = z0 + s * COLLAR_LEN
            zc = (z0 + z1) / 2
            r_out = r_in + 0.002
            cap_z = z1 + s * 0.003
            pieces = [
                _ring([(r_out, min(z0, z1)), (r_out, max(z0, z1))], 0.002, "pole", center=(P[0], 0, 0)),
                g.disc((P[0], 0, cap_z), r_out, 0.006, "pole"),
            ]
            C = np.array([P[0], 0.0, zc])
            E = C + (lengths[k], 0.0, 0.0)
            pieces.append(_tube(C + (r_out - 0.001, 0, 0), E, r_c))
            if nxt != "swivel":
                pieces.append(_ycyl(E, -w / 2, w / 2, r_h))
            joint = J.revolute(parent, name, C, (0, 0, 1), -SWIVEL, SWIVEL, role="swivel")
        # the far end: cheeks or hub for a hinge, or a block with a pin for a swing arm
        if nxt == "swivel":
            s = 1.0 if angles[k] > math.radians(30) else -1.0
            if kind == "twin":
                pieces.append(g.box_between(E - (r_h, y_tw + TWIN_R, q.r_x), E + (r_h, y_tw + TWIN_R, q.r_x),
                                            "pole"))
            else:
                pieces.append(g.sphere(E, q.r_x, "pole"))
            pieces.append(g.cylinder(E, E + (0, 0, s * (q.r_x + COLLAR_LEN)), q.r_pin, "pole", 16))
        bp.add(name, "arm", pieces)
        bp.join(joint)
        parent, parent_type, parent_angle, P = name, kind, angles[k], E
    mount = "yoke" if parent_type == "central" else "hub"
    _hanging_head(bp, p, q, parent, mount, P, p["head_tilt"])


def _tube(p0, p1, r: float, sections: int = 16, slot: str = "pole", wall: float = 0.0008) -> g.Piece:
    """A thin-walled tube (so it weighs what a lamp arm does), colliding as a solid rod.

    The wall is :func:`~infmob_usd.geometry.shell`'s mesh of the profile ``(r, 0)``-``(r, length)``
    (:func:`_unit_tube` stretched to the length), without the shell's wedge collisions: the rod's
    replace them."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    rod = g.cylinder_arrays(p0, p1, r, sections)  # g.cylinder's mesh, its own hull
    v, f = _unit_tube(r, min(wall, 0.3 * r), sections)
    v = v * (1.0, 1.0, float(np.linalg.norm(p1 - p0)))
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = g.rotation_between((0, 0, 1), p1 - p0), p0
    return g.Piece(v @ m[:3, :3].T + m[:3, 3], f, slot, [rod[0]], hulls=[rod])


@functools.lru_cache(maxsize=64)
def _unit_tube(r: float, t: float, sections: int) -> tuple[np.ndarray, np.ndarray]:
    """The closed wall of a tube of radius ``r``, wall ``t``, length 1 along +Z (read-only arrays): the
    revolved outline ``(r, 0), (r, 1), (r - t, 1), (r - t, 0)``, whose z are exactly 0 or 1, so scaling
    z by a length gives, bit for bit, the wall revolved at that length."""
    v, f = g.revolve_arrays(np.array([(r, 0.0), (r, 1.0), (r - t, 1.0), (r - t, 0.0), (r, 0.0)]), sections)
    v.flags.writeable = False
    f.flags.writeable = False
    return v, f


def _ycyl(c: np.ndarray, y0: float, y1: float, r: float) -> g.Piece:
    return g.cylinder((c[0], y0, c[2]), (c[0], y1, c[2]), r, "pole", 20)


def _segment_body(q: LampPlan, kind: str, P: np.ndarray, E: np.ndarray) -> list[g.Piece]:
    """Bars of a pitch segment from hinge ``P`` to ``E`` with their hinge ends."""
    w, r_h, y_tw = q.w_c, q.r_h, q.y_tw
    if kind == "central":
        return [_ycyl(P, -w / 2, w / 2, r_h), _tube(P, E, q.r_c),
                _ycyl(E, -w / 2, w / 2, r_h)]
    out = []
    for s in (-1, 1):
        y0, y1 = sorted((s * (w / 2 + GAP), s * (w / 2 + GAP + 2 * TWIN_R)))
        off = np.array([0.0, s * y_tw, 0.0])
        out += [_ycyl(P, y0, y1, r_h), _tube(P + off, E + off, TWIN_R, 12), _ycyl(E, y0, y1, r_h)]
    return out
