"""Office chair: a wheeled star base, a gas lift, a swivelling seat, a reclining back and 4D arms.

X is depth (the sitter faces +X), Y is width, Z is up. The base is a hub with 3-10 legs
(5 most often); at the tip of every leg a caster swivels about a vertical axis, carrying one
wheel or a pair of twin wheels that turn about a horizontal axle pointing along the leg
(radial). The wheels are the lowest points of the chair (they touch the floor at z = 0).

The hub is a hollow socket; the gas lift is a hollow chrome (or black) tube standing in it,
around a fixed piston rod: it slides up along +Z from its lowest (rest) position. On top of
the lift the seat (mechanism, seat pan, cushion, adjustment lever) swivels about Z.

The back hangs on a spine behind the seat: its recline hinge is at the foot of the spine,
BEHIND the backrest cushion's centre of mass, so gravity tips the back forward against its
upright stop (lower limit 0) and reclining (about -Y, top towards -X) lifts the cushion.
Each arm is a hollow post sliding up along +Z over a bar fixed under the seat (height
adjustment, rests at the bottom), a carriage on top that slides along X and turns about Z
(the "arm slide", a revolute-prismatic joint) and the arm pad that turns about Z on it.

The builders of the base (:func:`star_base`), the lift (:func:`gas_lift`) and the seat
(:func:`swivel_seat`) are shared with the bar chair (``bar_chair.py``).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.errors import ParameterError
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    office_chair=Rule(required=("base", "lift", "seat"), optional={"back": 0.92, "arms": 0.8}),
    base=Rule(required=("hub", "legs", "casters")),
    caster=Rule(required=("fork", "wheels"), one_of={"twin": 0.6, "single": 0.4}),
    back=Rule(required=("spine", "backrest"), optional={"headrest": 0.25},
              one_of={"cushion": 0.6, "mesh": 0.4}),
    arms=Rule(required=("arm_post", "arm_slider", "arm_pad")),
)
"""``caster.one_of`` is the ``caster_style`` parameter, ``back.one_of`` the ``back_style``
parameter (object-wide, same weights). The leg count is drawn from :data:`LEG_WEIGHTS`."""

LEG_WEIGHTS = {3: 0.03, 4: 0.08, 5: 0.62, 6: 0.1, 7: 0.05, 8: 0.05, 9: 0.03, 10: 0.04}
"""Leg count -> weight when ``leg_count`` is not set (five-legged bases are the most common)."""

_CASTERS = GROWTH.rules["caster"].one_of
_BACKS = GROWTH.rules["back"].one_of

SCHEMA = Schema((
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", 0.4, 0.55),
    Float("seat_width", "seat width (Y)", "m", 0.4, 0.6),
    Float("seat_depth", "seat depth (X)", "m", 0.4, 0.52),
    Float("seat_thickness", "seat cushion thickness", "m", 0.05, 0.1),
    Int("leg_count", "legs of the star base; auto = drawn, 5 most often", "", 3, 10, auto=True),
    Float("base_radius", "caster swivel axes from the centre (raised for many legs)", "m", 0.27, 0.35),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=(0.65, 0.35)),
    Choice("caster_style", "one or two wheels per caster", choices=tuple(_CASTERS),
           weights=tuple(_CASTERS.values())),
    Float("wheel_radius", "wheel radius", "m", 0.024, 0.034),
    Float("lift_radius", "gas lift tube radius", "m", 0.022, 0.028),
    Float("lift_travel", "gas lift stroke (capped where the column is short)", "m", 0.06, 0.1),
    Float("back_height", "backrest height", "m", 0.3, 0.55),
    Float("back_width", "backrest width as a fraction of the seat width", "", 0.75, 0.95),
    Float("back_thickness", "backrest thickness", "m", 0.04, 0.075),
    Float("back_gap", "backrest bottom above the seat top", "m", 0.04, 0.1),
    Choice("back_style", "backrest: upholstered cushion or mesh in a frame", choices=tuple(_BACKS),
           weights=tuple(_BACKS.values())),
    Float("recline", "back recline range", "rad", 0.25, 0.45),
    Float("arm_height", "arm pad top above the seat top", "m", 0.17, 0.25),
    Float("arm_travel", "arm height adjustment", "m", 0.04, 0.08),
    Float("pad_length", "arm pad length (X)", "m", 0.2, 0.27),
    Float("pad_width", "arm pad width (Y)", "m", 0.06, 0.09),
    Float("arm_slide", "arm pad slide along X, each way", "m", 0.02, 0.04),
    Float("arm_turn", "arm carriage turn about Z, each way", "rad", 0.1, 0.3),
    Float("pad_turn", "arm pad turn about Z, each way", "rad", 0.1, 0.3),
    Choice("base_finish", "star base material", choices=("plastic", "chrome", "brushed_metal"),
           weights=(0.55, 0.25, 0.2)),
    Choice("lift_finish", "gas lift tube material", choices=("chrome", "plastic"), weights=(0.6, 0.4)),
    Choice("seat_finish", "seat and back upholstery", choices=("fabric", "plastic"), weights=(0.75, 0.25)),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=(0.6, 0.4)),
    *GROWTH.flags(),
))

BLACK = "plastic:black|dark_grey"
GAP = 0.004  # clearance between moving parts and their neighbours
WHEEL_INSET = 0.0006  # wheel collider radius below the visual tyre radius


def _finish(f: str, black: str = BLACK) -> str:
    return black if f == "plastic" else f


def materials(p: dict) -> dict[str, str]:
    """Material slot -> family for a chair (shared with the bar chair)."""
    seat = p["seat_finish"] if p["seat_finish"] == "fabric" else "plastic:black|dark_grey|white|red|blue"
    return {
        "base": _finish(p["base_finish"]), "caster": BLACK, "wheel": _finish(p["wheel_finish"]),
        "lift": _finish(p["lift_finish"]), "mech": "painted:black|charcoal", "pan": BLACK,
        "seat": seat, "frame": BLACK, "mesh": "fabric:charcoal|grey|navy", "pad": BLACK,
        "handle": BLACK, "ring": "chrome",
    }


def leg_count(p: dict, structure: np.random.Generator) -> int:
    n = list(LEG_WEIGHTS)
    w = np.array(list(LEG_WEIGHTS.values()))
    drawn = int(n[int(structure.choice(len(n), p=w / w.sum()))])  # always drawn: no reshuffle
    return p["leg_count"] or drawn


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("office_chair", materials=materials(p))
    H, W, D = p["seat_height"], p["seat_width"], p["seat_depth"]
    r_lift = p["lift_radius"]
    n_legs = leg_count(p, structure)
    base = star_base(bp, n_legs, p["base_radius"], p["wheel_radius"], r_lift, p["leg_style"],
                     p["caster_style"], metal=p["base_finish"] != "plastic")
    hm = 0.04  # mechanism height
    # the seat must clear the hub: thin the cushion if the chair is low
    tc = min(p["seat_thickness"], H - 0.012 - hm - GAP - 0.035 - base["top"] - 0.015)
    xc = 0.02  # the seat sits a little forward of the column
    seat = swivel_seat(bp, "lift", H, W, D, tc, "square", xc, r_lift, hm)
    travel = gas_lift(bp, base["name"], base["floor"], seat["lift_top"], r_lift, p["lift_travel"])
    bp.join(J.continuous("lift", "seat", (0.0, 0.0, seat["lift_top"]), (0, 0, 1), role="swivel"))
    if travel <= 0.04:
        raise ParameterError(f"the gas lift has only {travel * 100:.1f} cm of travel under a seat at"
                             f" {H:g} m; raise seat_height or lower wheel_radius")

    back_front = None
    if p["has_back"]:
        back_front = back_rest(bp, p, seat, W, H)
    if p["has_arms"]:
        _arms(bp, p, seat, W, H, back_front)
    return bp


# ---------------------------------------------------------------------------------------------
# shared builders


def _frame(angle: float, radius: float) -> np.ndarray:
    """Rigid transform: local +X along the leg at ``angle``, origin on the caster axis at z = 0."""
    c, s = math.cos(angle), math.sin(angle)
    m = np.eye(4)
    m[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    m[:2, 3] = (radius * c, radius * s)
    return m


def _hull(points, material: str, name: str = "") -> g.Piece:
    return g.from_trimesh(g.convex_hull(np.asarray(points, float)), material, name=name)


def _ring_yz(x: float, cy: float, cz: float, r: float, n: int = 12) -> list:
    """Points of a circle in the YZ plane at ``x`` (an axle boss seen along X)."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return [(x, cy + r * math.cos(a), cz + r * math.sin(a)) for a in t]


def caster_pieces(style: str, rw: float, trail: float) -> tuple[list, list, float, float]:
    """One caster in its local frame (axle along +X, swivel axis on Z through the origin).

    Returns ``(fork pieces, wheels [(pieces, axle x range)], wheel width, top z)``; the wheel
    axle is at ``(0, -trail, rw)`` and every wheel touches z = 0.
    """
    yw = -trail
    fork: list[g.Piece] = []
    wheels = []
    hood0 = 2 * rw + GAP  # every fork piece above the wheels or beside them
    if style == "twin":
        ww = 0.45 * rw + 0.004
        hw = 0.008  # housing half-width between the wheels
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
    for x0, x1 in spans:
        tyre = g.cylinder([x0, yw, rw], [x1, yw, rw], rw, "wheel", 32)
        # the collider is 0.6 mm inside the tyre: the fixed-root simulators must not drag the
        # wheels over the floor when they turn them (the mesh still touches z = 0)
        tyre = tyre.replace(convex=[g.cylinder([x0, yw, rw], [x1, yw, rw], rw - WHEEL_INSET, "wheel", 32).vertices])
        hub = g.cylinder([x0 + 0.001, yw, rw], [x1 - 0.001, yw, rw], 0.55 * rw, "caster", 24)
        hub = hub.replace(convex=[])  # inside the tyre: decoration only
        wheels.append(([tyre, hub], (x0, x1)))
    # swivel stem and bearing
    stem_top = z_top + 0.012
    fork.append(g.cylinder([0, 0, z_top - 0.002], [0, 0, stem_top - 0.004], 0.0065, "caster", 16))
    fork.append(g.cylinder([0, 0, stem_top - 0.005], [0, 0, stem_top], 0.013, "caster", 24))
    return fork, wheels, ww, stem_top


def star_base(bp: Blueprint, n_legs: int, radius: float, rw: float, r_lift: float, leg_style: str,
              caster_style: str, metal: bool, name: str = "base") -> dict:
    """The star base with casters and wheels; a hollow hub socket for a lift of radius ``r_lift``.

    Adds the parts ``base``, ``caster_<i>`` and ``wheel_<i>[_<k>]`` with their joints.
    Returns ``{"name", "floor" (z of the socket floor), "top" (z of the hub top), "hub_r",
    "bore"}``.
    """
    trail = 0.45 * rw + 0.006
    fork, wheels, ww, z_s = caster_pieces(caster_style, rw, trail)
    # caster footprint while it swivels, so neighbours never meet
    span = max(abs(x) for _p, xs in wheels for x in xs) + 0.004
    sweep = math.hypot(trail + rw, span)
    radius = max(radius, (sweep + 0.02) / math.sin(math.pi / n_legs), 0.2)
    z_lb = z_s + 0.003 + 0.009  # leg bottom at the tip (a socket hides the stem)
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
        g.shell([(hub_r, z_h0), (hub_r, z_h1)], hub_r - bore, "base", sections=48),
        g.disc([0, 0, (z_h0 + floor) / 2], bore + 0.002, floor - z_h0, "base", 32),
    ]
    for i in range(n_legs):
        a = 2 * math.pi * i / n_legs
        m = _frame(a, 0.0)
        x_in, x_out = hub_r - 0.006, radius + 0.022
        pts = []
        for x, w, z0, h in ((x_in, wh, z_lb + rise, hh), (x_out, wt, z_lb, ht)):
            for y in (-w / 2, w / 2):
                pts += [(x, y, z0), (x, 0.8 * y, z0 + h), (x, y, z0 + 0.75 * h)]
        pts += [(x_out + 0.012, y, z_lb + 0.2 * ht) for y in (-0.3 * wt, 0.3 * wt)]
        pts += [(x_out + 0.012, y, z_lb + 0.7 * ht) for y in (-0.25 * wt, 0.25 * wt)]
        leg = _hull(pts, "base").transformed(m).replace(sheet=sheet)
        pieces.append(leg)
        tip = _frame(a, radius)
        pieces.append(g.cylinder([0, 0, z_s + 0.003], [0, 0, z_lb + 0.004], 0.012, "base", 20).transformed(tip))
    pieces[:2] = [pc.replace(sheet=sheet) for pc in pieces[:2]]
    bp.add(name, "base", pieces)

    for i in range(n_legs):
        a = 2 * math.pi * i / n_legs
        m = _frame(a, radius)
        cname = f"caster_{i}"
        bp.add(cname, "caster", [pc.transformed(m) for pc in fork])
        bp.join(J.continuous(name, cname, tuple(m[:3, 3] + [0, 0, z_s]), (0, 0, 1), role="swivel"))
        u = m[:3, 0]
        for k, (pcs, _xs) in enumerate(wheels):
            wname = f"wheel_{i}" if len(wheels) == 1 else f"wheel_{i}_{k}"
            bp.add(wname, "wheel", [pc.transformed(m) for pc in pcs])
            axle = m[:3, :3] @ np.array([0.0, -trail, rw]) + m[:3, 3]
            bp.join(J.continuous(cname, wname, tuple(axle), tuple(u), role="wheel"))
    return {"name": name, "floor": floor, "top": z_h1, "hub_r": hub_r, "bore": bore}


def gas_lift(bp: Blueprint, base: str, floor: float, top: float, r_lift: float, travel: float,
             name: str = "lift") -> float:
    """A hollow lift tube from just above the socket ``floor`` to ``top``, around a fixed piston rod.

    The rod is added to ``base``. The tube slides up along +Z from rest (its lowest position);
    returns the travel actually used (capped so the tube always surrounds the rod).
    """
    wall = 0.0035
    cap = 0.008
    z0 = floor + GAP
    travel = min(travel, top - cap - GAP - 0.03 - z0)
    rod_top = z0 + travel + 0.03
    tube = [
        g.shell([(r_lift, z0), (r_lift, top - cap + 0.001)], wall, "lift", sections=48),
        g.disc([0, 0, top - cap / 2], r_lift, cap, "lift", 48),
    ]
    bp.add(name, "lift", tube)
    bp.extend(base, [g.cylinder([0, 0, floor - 0.002], [0, 0, rod_top], 0.35 * r_lift, "lift", 20)])
    bp.join(J.prismatic(base, name, (0.0, 0.0, z0), (0, 0, 1), 0.0, travel, role="telescope"))
    return travel


def swivel_seat(bp: Blueprint, parent: str, top: float, width: float, depth: float, thick: float,
                shape: str, xc: float, r_lift: float, hm: float, name: str = "seat") -> dict:
    """Seat with its mechanism, pan, cushion and lever, on a collar around the lift top.

    ``top`` is the seat top; the lift tube must end at the returned ``lift_top``. The
    caller declares the swivel joint. Returns the heights and extents the rest needs.
    """
    pan_t = 0.012
    z_pan0 = top - thick - pan_t
    z_mech0 = z_pan0 - hm
    lift_top = z_mech0 - GAP
    collar_r = r_lift + GAP + 0.006
    pieces = [g.shell([(collar_r, lift_top - 0.03), (collar_r, z_mech0 + 0.002)], 0.006, "mech", sections=48)]
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
        pieces.append(g.revolve(prof, "seat", center=(xc, 0, 0), sections=56))
        x0, x1 = xc - rad, xc + rad
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
    # height lever under the right side
    zl = z_mech0 + 0.3 * hm
    reach = (width / 2 - 0.03) if shape != "round" else 0.7 * width / 2
    pieces.append(g.cylinder([xc + 0.03, 0.04, zl], [xc + 0.03, reach, zl], 0.0045, "handle", 12, name="handle"))
    pieces.append(g.box([0.04, 0.02, 0.012], [xc + 0.04, reach, zl], "handle", bevel=0.003, name="handle"))
    bp.add(name, "seat", pieces)
    return {"name": name, "lift_top": lift_top, "z_pan0": z_pan0, "z_mech0": z_mech0, "x0": x0, "x1": x1,
            "xc": xc, "top": top}


# ---------------------------------------------------------------------------------------------
# back and arms


def back_rest(bp: Blueprint, p: dict, seat: dict, W: float, H: float, hinged: bool = True) -> float:
    """The spine with its recline hinge behind the seat; returns the back's front x at rest.

    Reads ``back_thickness``, ``back_height``, ``back_width`` (fraction of ``W``), ``back_gap``,
    ``back_style``, ``has_headrest`` and ``recline`` from ``p``; ``hinged=False`` fixes it.
    """
    bt, bh = p["back_thickness"], p["back_height"]
    bw = p["back_width"] * W
    sw, st, rk = 0.06, 0.016, 0.011  # spine width, thickness, knuckle radius
    z_mech0 = seat["z_mech0"]
    br_top = z_mech0 + 0.022  # the seat's bracket under the mechanism
    zp = br_top + rk + GAP
    xp = seat["x0"] - rk - 0.01
    # bracket and cheeks on the seat
    cheek_y = sw / 2 + GAP
    bp.extend(seat["name"], [
        g.box_between([xp - 0.02, -0.03, z_mech0], [seat["xc"] - 0.05, 0.03, br_top], "mech"),
        *[g.box_between([xp - 0.018, s * cheek_y if s > 0 else -cheek_y - 0.008, z_mech0],
                        [xp + 0.018, cheek_y + 0.008 if s > 0 else -cheek_y, zp + 0.016], "mech")
          for s in (-1, 1)],
    ])
    zb0 = H + p["back_gap"]
    zb1 = zb0 + bh
    xs1 = xp + st / 2  # spine front
    pieces = [
        g.cylinder([xp, -sw / 2, zp], [xp, sw / 2, zp], rk, "frame", 20),
        g.box_between([xp - st / 2, -sw / 2, zp], [xs1, sw / 2, zb0 + 0.5 * bh], "frame", bevel=0.003),
    ]
    # backrest, in front of the spine: its centre of mass is ahead of the hinge
    if p["back_style"] == "mesh":
        fr = 0.025
        pieces.append(g.panel([xs1, -bw / 2, zb0], [xs1 + 0.022, bw / 2, zb1], "frame", "x",
                              holes=[(-bw / 2 + fr, zb0 + fr, bw / 2 - fr, zb1 - fr)]))
        pieces.append(g.box_between([xs1 + 0.008, -bw / 2 + fr - 0.002, zb0 + fr - 0.002],
                                    [xs1 + 0.012, bw / 2 - fr + 0.002, zb1 - fr + 0.002], "mesh"))
        front = xs1 + 0.022
    else:
        pieces.append(g.box_between([xs1, -0.45 * bw, zb0 + 0.03], [xs1 + 0.012, 0.45 * bw, zb1 - 0.03], "frame",
                                    bevel=0.004))
        pieces.append(g.box_between([xs1 + 0.01, -bw / 2, zb0], [xs1 + 0.01 + bt, bw / 2, zb1], "seat",
                                    bevel=min(0.025, 0.4 * bt)))
        # lumbar bulge
        pieces.append(g.box_between([xs1 + bt, -0.4 * bw, zb0 + 0.18 * bh], [xs1 + bt + 0.015, 0.4 * bw,
                                                                             zb0 + 0.45 * bh],
                                    "seat", bevel=0.007))
        front = xs1 + bt + 0.015
    if p["has_headrest"]:
        zh0 = zb1 + 0.03
        pieces.append(g.box_between([xp - st / 2, -0.02, zb1 - 0.06], [xs1, 0.02, zh0 + 0.05], "frame"))
        pieces.append(g.box_between([xs1, -0.3 * bw, zh0], [xs1 + 0.05, 0.3 * bw, zh0 + 0.12], "seat",
                                    bevel=0.018))
        front = max(front, xs1 + 0.05)
    bp.add("back", "back", pieces)
    # about -Y: positive q tips the top towards -X (recline); gravity tips it forward onto q = 0
    if hinged:
        bp.join(J.revolute(seat["name"], "back", (xp, 0.0, zp), (0, -1, 0), 0.0, p["recline"], role="hinge"))
    else:
        bp.join(J.fixed(seat["name"], "back"))
    return front


def pad_reach(p: dict, off: float, xb: float | None) -> float:
    """How far (m) the arm pad reaches inwards of its post axis where the back could be."""
    L, pw, S, A, B = p["pad_length"], p["pad_width"], p["arm_slide"], p["arm_turn"], p["pad_turn"]
    t = np.linspace(-1, 1, 9)
    edge = np.vstack([np.c_[t * L / 2, np.full(9, pw / 2)], np.c_[t * L / 2, np.full(9, -pw / 2)],
                      np.c_[np.full(9, L / 2), t * pw / 2], np.c_[np.full(9, -L / 2), t * pw / 2]])
    reach = pw / 2
    for a in np.linspace(-A, A, 5):
        for b in np.linspace(-B, B, 5):
            for s in (-S, 0.0, S):
                ca, sa, cb, sb = math.cos(a), math.sin(a), math.cos(b), math.sin(b)
                q = edge @ np.array([[cb, sb], [-sb, cb]]) + [off, 0.0]
                q = q @ np.array([[ca, sa], [-sa, ca]]) + [s, 0.0]
                sel = q if xb is None else q[q[:, 0] < xb]
                if len(sel):
                    reach = max(reach, float(np.abs(sel[:, 1]).max()))
    return reach


def _arms(bp: Blueprint, p: dict, seat: dict, W: float, H: float, back_front: float | None) -> None:
    L, pw = p["pad_length"], p["pad_width"]
    xc = seat["xc"]
    x_post = xc - 0.06
    off = 0.03  # pad centre ahead of the post
    bar = (0.022, 0.016)  # fixed bar (x, y)
    tube_w = 0.003  # hollow post wall
    half = (bar[0] / 2 + 0.003 + tube_w, bar[1] / 2 + 0.003 + tube_w)
    y_arm = W / 2 + half[1] + 0.008
    if back_front is not None:
        bw = p["back_width"] * W
        y_arm = max(y_arm, bw / 2 + 0.012 + pad_reach(p, off, back_front + 0.012 - x_post))
    z_pan0 = seat["z_pan0"]
    br0, br1 = z_pan0 - 0.022, z_pan0 - 0.004
    z_pt = H + p["arm_height"]  # pad top
    pt = 0.026
    z_pad0 = z_pt - pt
    zc0 = z_pad0 - GAP - 0.012  # carriage bottom
    zc1 = zc0 + 0.012
    cap1 = zc0 - GAP
    cap0 = cap1 - 0.008
    z_t0 = br1 + 0.006
    for side, s in (("left", 1), ("right", -1)):
        y = s * y_arm
        bp.extend(seat["name"], [
            g.box_between([x_post - 0.025, min(0.0, s * 0.08), br0], [x_post + 0.025, max(0.0, s * 0.08), br1],
                          "mech"),
            g.box_between([x_post - 0.025, min(s * 0.08, y + s * 0.02), br0],
                          [x_post + 0.025, max(s * 0.08, y + s * 0.02), br1], "frame", bevel=0.003),
            g.box_between([x_post - bar[0] / 2, y - bar[1] / 2, br1 - 0.002],
                          [x_post + bar[0] / 2, y + bar[1] / 2, cap0 - 0.012], "frame"),
        ])
        hx, hy = half
        ix, iy = hx - tube_w, hy - tube_w
        post = f"arm_{side}"
        bp.add(post, "arm", [
            g.box_between([x_post - hx, y - hy, z_t0], [x_post - ix, y + hy, cap0 + 0.001], "frame"),
            g.box_between([x_post + ix, y - hy, z_t0], [x_post + hx, y + hy, cap0 + 0.001], "frame"),
            g.box_between([x_post - ix, y - hy, z_t0], [x_post + ix, y - iy, cap0 + 0.001], "frame"),
            g.box_between([x_post - ix, y + iy, z_t0], [x_post + ix, y + hy, cap0 + 0.001], "frame"),
            g.box_between([x_post - hx - 0.004, y - hy - 0.004, cap0], [x_post + hx + 0.004, y + hy + 0.004, cap1],
                          "frame", bevel=0.002),
        ])
        bp.join(J.prismatic(seat["name"], post, (x_post, y, z_t0), (0, 0, 1), 0.0, p["arm_travel"],
                            role="telescope"))
        slider = f"arm_slider_{side}"
        bp.add(slider, "arm", [g.box_between([x_post - 0.05, y - 0.022, zc0], [x_post + 0.05, y + 0.022, zc1],
                                             "frame", bevel=0.003)])
        bp.join(J.revolute_prismatic(post, slider, (x_post, y, zc0), (0, 0, 1), (-p["arm_turn"], p["arm_turn"]),
                                     (1, 0, 0), (-p["arm_slide"], p["arm_slide"]), role="slide"))
        pad = f"arm_pad_{side}"
        bp.add(pad, "armrest", [g.box([L, pw, pt], [x_post + off, y, z_pad0 + pt / 2], "pad",
                                      bevel=min(0.012, 0.4 * pt))])
        bp.join(J.revolute(slider, pad, (x_post + off, y, z_pad0), (0, 0, 1), -p["pad_turn"], p["pad_turn"],
                           role="swivel"))
