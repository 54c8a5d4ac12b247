"""TV: a flat-panel television on a pedestal stand, a two-leg stand or a wall-mount arm.

X is depth (the screen faces +X), Y is width, Z is up. The screen is a thin panel:
a bezel frame around a glossy black display, a back housing behind it, and a deeper
electronics box ("hump") on the lower middle of the back carrying a VESA plate. The
screen is fixed to the **connector**, a tilt bracket whose barrel (a cylinder along Y)
turns between the two cheeks of a fork on the stand (revolute about Y).

Tilt and gravity: the tilt pivot lies behind the back of the screen, so the centre of
mass of the connector and screen is in front of the axis. About (0, -1, 0) gravity then
pushes toward negative q: the screen rests against its lower stop (q = 0, upright) and
tilts its top back by up to ``tilt``. Every screen point below the pivot rises and moves
forward when it tilts, every point above the pivot stays above it, so nothing enters the
stand or the ground.

Stands (``stand_style``):

* ``single_post``: a base plate with a neck rising behind the screen to the fork. With
  ``has_height_adjust`` the neck is a round post sliding in a sleeve on the base
  (revolute_prismatic: swivel about Z +-``swivel``, slide up 0..``slide``; it rests on its
  bottom stop and moves up).
* ``two_legs``: two feet under the screen with uprights behind it, joined by a low
  crossbar; the connector's barrel spans between the uprights' tops.
* ``has_wall_mount`` replaces the stand: the root is a wall plate behind the TV; one or two
  arm links turn about Z (neutral under gravity) on vertical barrels between lugs, and the
  fork for the tilt is at the end of the last arm. The swing is limited so that the screen
  never comes within 1 cm of the wall plane in any combination of the arm joints.

Buttons (``has_buttons``, 1-4): on the right side rim (pressed along -Y through holes in
the rim) or on the bottom band of the bezel (pressed along -X through holes in it).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    tv=Rule(required=("screen", "stand", "connector"), optional={"buttons": 0.6, "wall_mount": 0.2}),
    stand=Rule(one_of={"single_post": 0.6, "two_legs": 0.4}, optional={"height_adjust": 0.4}),
    screen=Rule(required=("bezel", "display", "housing")),
)
"""``stand.one_of`` is object-wide: the ``stand_style`` parameter (same weights).
``has_height_adjust`` applies to a single post only; ``has_wall_mount`` replaces the stand."""

_STANDS = GROWTH.rules["stand"].one_of

SCHEMA = Schema((
    Float("width", "screen width incl. the bezel (Y)", "m", 0.6, 2.1),
    Choice("aspect", "screen aspect ratio", choices=("16:9", "4:3"), weights=(0.85, 0.15)),
    Float("depth", "thickness of the screen panel (X)", "m", 0.02, 0.04),
    Float("bezel", "bezel width on the sides and top", "m", 0.005, 0.02),
    Float("back_depth", "extra depth of the electronics box on the back", "m", 0.015, 0.05),
    Float("back_width", "electronics box width as a fraction of the screen width", "", 0.4, 0.75),
    Float("back_height", "electronics box height as a fraction of the screen height", "", 0.35, 0.6),
    Choice("stand_style", "pedestal post or two legs", choices=tuple(_STANDS),
           weights=tuple(_STANDS.values())),
    Float("clearance", "gap between the stand's base (or feet) and the screen bottom", "m", 0.03, 0.12),
    Float("base_width", "pedestal base width as a fraction of the screen width (>= 0.25 m)", "",
          0.3, 0.55),
    Float("base_depth", "pedestal base or foot depth (X)", "m", 0.18, 0.32),
    Choice("base_shape", "pedestal base plate shape", choices=("rect", "round"), weights=(0.6, 0.4)),
    Float("leg_spread", "distance between the two legs as a fraction of the screen width", "",
          0.5, 0.8),
    Float("tilt", "tilt range: the screen top tilts back 0..tilt", "rad", math.pi / 24, math.pi / 8),
    Float("slide", "travel of a height-adjustable post", "m", 0.04, 0.14),
    Float("swivel", "swivel range (+-) of a height-adjustable post", "rad", math.pi / 12, math.pi / 4),
    Int("arm_links", "links of a wall-mount arm", "", 1, 2),
    Float("arm_length", "wall-mount arm reach from the wall plate to the tilt pivot", "m", 0.15, 0.45),
    Int("button_count", "buttons on the screen", "", 1, 4),
    Choice("button_place", "where the buttons are", choices=("side", "bottom")),
    Choice("bezel_finish", "bezel material", choices=("black", "grey", "silver"), weights=(0.6, 0.2, 0.2)),
    Choice("stand_finish", "stand material", choices=("metal", "black", "chrome"), weights=(0.4, 0.4, 0.2)),
    *GROWTH.flags(),
))

_FINISH = {
    "black": "plastic:black", "grey": "plastic:dark_grey", "silver": "brushed_metal",
    "metal": "brushed_metal", "chrome": "chrome",
}

GAP = 0.004  # clearance between moving parts and their neighbours
CLEAR = 0.0015  # clearance of a button in its hole
BEZEL_T = 0.008  # bezel thickness (X)
RIM = 0.010  # side rim thickness (Y) when side buttons go through it
PRESS = 0.002  # button travel


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    stand_finish = "plastic:black|dark_grey" if p["stand_finish"] == "black" else _FINISH[p["stand_finish"]]
    bp = Blueprint("tv", materials={
        "bezel": _FINISH[p["bezel_finish"]], "display": "screen", "housing": "plastic:black|dark_grey",
        "stand": stand_finish, "connector": "brushed_metal", "button": "plastic:black|dark_grey",
        "arm": "painted:black|charcoal",
    })
    W, D = p["width"], p["depth"]
    H = W * (9 / 16 if p["aspect"] == "16:9" else 3 / 4)
    wall = p["has_wall_mount"]
    style = "wall" if wall else p["stand_style"]

    # --- vertical layout: screen bottom zs0 above the base or feet ---------------------------
    base_t = 0.0 if wall else float(np.clip(0.008 + 0.006 * W, 0.01, 0.02))  # plate / foot height
    clearance = p["clearance"]
    adjust = style == "single_post" and p["has_height_adjust"]
    sleeve_h = p["slide"] + 0.03
    if adjust:
        clearance = max(clearance, sleeve_h + 0.015)
    zs0 = base_t + clearance
    zs1 = zs0 + H
    xf = D / 2  # front face of the screen
    xs = xf - D  # back face of the thin panel
    hw, hh = p["back_width"] * W, p["back_height"] * H
    zh0 = zs0 + (0.06 if wall else 0.04) * H  # electronics box
    zh1 = zh0 + hh
    xhb = xs - p["back_depth"]  # back face of the box
    x_bk = xhb - 0.004  # back face of the VESA plate (part of the connector)

    # --- connector geometry: barrel radius and the pivot behind the back ----------------------
    r_k = float(np.clip(0.008 + 0.004 * W, 0.01, 0.016))
    tilt = p["tilt"]
    cheek_x = 1.3 * r_k  # fork cheeks reach this far from the axis in X and 1.2 r_k above it
    e = (cheek_x + 1.2 * r_k * math.sin(tilt) + GAP + 0.004) / math.cos(tilt)
    x_p = x_bk - e
    z_p = (zh0 + zh1) / 2 if not wall else zs0 + 0.5 * H
    z_p = min(max(z_p, zh0 + 0.06), zh1 - 0.06)

    _screen(bp, p, (W, H), (xf, xs, xhb), (zs0, zs1), (hw, zh0, zh1))

    if style == "two_legs":
        y_leg = p["leg_spread"] * W / 2
        L_k = 2 * (y_leg - 0.0125 - GAP)  # between the uprights (25 mm wide)
    else:
        L_k = float(np.clip(0.12 * W, 0.08, 0.16))
    conn = _connector(bp, (x_p, z_p), r_k, (x_bk, xhb), L_k, min(hw - 0.02, 0.8 * L_k + 0.1), (hh, zh0, zh1))

    if style == "wall":
        parent, tilt = _wall_mount(bp, p, (x_p, z_p), r_k, L_k, tilt, (W, xs, x_bk, hw, zs0, zs1, zh0, zh1))
    elif style == "two_legs":
        parent = _two_legs(bp, p, (x_p, z_p), r_k, L_k, (xf, x_bk, base_t))
    else:
        parent = _pedestal(bp, p, (x_p, z_p), r_k, L_k, (xf, x_bk, base_t, W, zs0), adjust, sleeve_h)

    # tilt: the top goes back, about -Y through the barrel axis (load in front: rests on q = 0)
    bp.join(J.revolute(parent, conn, (x_p, 0.0, z_p), (0, -1, 0), 0.0, tilt, role="hinge"))
    bp.join(J.fixed(conn, "screen"))

    if p["has_buttons"]:
        _buttons(bp, p, (W, xf, xs, zs0))
    return bp


# ---------------------------------------------------------------------------------------------
# the screen


def _bottom_band(p):
    """Height of the bottom bezel band: wider when buttons sit in it."""
    b = p["bezel"] * 1.3
    if p["has_buttons"] and p["button_place"] == "bottom":
        b = max(b, 0.008 + 2 * CLEAR + 0.008)
    return b


def _button_layout(p, W, xf, xs, zs0):
    """(centre, half sizes) of each button; side: (x, z) on the rim, bottom: (y, z) on the bezel."""
    n = p["button_count"]
    if p["button_place"] == "side":
        bx = min(0.008, (xf - BEZEL_T - xs) - 2 * CLEAR - 0.004)
        bz = 0.012
        xc = (xf - BEZEL_T + xs) / 2
        return [((xc, zs0 + 0.08 + k * (2 * bz + 0.006)), (bx / 2, bz / 2)) for k in range(n)]
    bz = 0.008
    by = 0.014
    zc = zs0 + _bottom_band(p) / 2
    y0 = W / 2 - 0.06 - 0.2 * W / 2
    return [((y0 - k * (by + 0.008), zc), (by / 2, bz / 2)) for k in range(n)]


def _screen(bp, p, size, xs3, zs, hump):
    W, H = size
    xf, xs, xhb = xs3
    zs0, zs1 = zs
    hw, zh0, zh1 = hump
    bz, bb = p["bezel"], _bottom_band(p)
    side = p["has_buttons"] and p["button_place"] == "side"
    bottom = p["has_buttons"] and p["button_place"] == "bottom"
    layout = _button_layout(p, W, xf, xs, zs0) if p["has_buttons"] else []

    holes = [(-W / 2 + bz, zs0 + bb, W / 2 - bz, zs1 - bz)]
    if bottom:
        holes += [(c[0] - h[0] - CLEAR, c[1] - h[1] - CLEAR, c[0] + h[0] + CLEAR, c[1] + h[1] + CLEAR)
                  for c, h in layout]
    xb = xf - BEZEL_T
    bezel = g.panel([xb, -W / 2, zs0], [xf, W / 2, zs1], "bezel", "x", holes=holes)
    bezel.sheet = 0.0015
    display = g.box_between([xb, -W / 2 + bz, zs0 + bb], [xf - 0.0015, W / 2 - bz, zs1 - bz], "display")
    display.sheet = 0.003
    y_right = W / 2 - RIM if side else W / 2
    pieces = [bezel, display, g.box_between([xs, -W / 2, zs0], [xb, y_right, zs1], "housing")]
    if side:
        rim_holes = [(c[0] - h[0] - CLEAR, c[1] - h[1] - CLEAR, c[0] + h[0] + CLEAR, c[1] + h[1] + CLEAR)
                     for c, h in layout]
        pieces.append(g.panel([xs, W / 2 - RIM, zs0], [xb, W / 2, zs1], "housing", "y", holes=rim_holes))
    bevel = min(0.01, 0.3 * (xs - xhb))
    pieces.append(g.box_between([xhb, -hw / 2, zh0], [xs + 0.001, hw / 2, zh1], "housing", bevel=bevel))
    for pc in pieces[2:]:
        pc.sheet = 0.002
    bp.add("screen", "screen", pieces)


def _buttons(bp, p, dims):
    W, xf, xs, zs0 = dims
    for k, (c, h) in enumerate(_button_layout(p, W, xf, xs, zs0)):
        name = f"button_{k}"
        if p["button_place"] == "side":
            y_in, y_out = W / 2 - RIM + PRESS + 0.002, W / 2 + 0.0025
            piece = g.box_between([c[0] - h[0], y_in, c[1] - h[1]], [c[0] + h[0], y_out, c[1] + h[1]],
                                  "button", bevel=0.001)
            bp.add(name, "button", [piece])
            bp.join(J.prismatic("screen", name, (c[0], y_out, c[1]), (0, -1, 0), 0.0, PRESS, role="button"))
        else:
            x_in, x_out = xf - BEZEL_T + PRESS + 0.002, xf + 0.002
            piece = g.box_between([x_in, c[0] - h[0], c[1] - h[1]], [x_out, c[0] + h[0], c[1] + h[1]],
                                  "button", bevel=0.001)
            bp.add(name, "button", [piece])
            bp.join(J.prismatic("screen", name, (x_out, c[0], c[1]), (-1, 0, 0), 0.0, PRESS, role="button"))


def _connector(bp, pivot, r_k, xs2, L_k, vesa_w, hump):
    """Barrel along Y on the tilt axis, neck plates forward to a VESA plate on the back."""
    x_p, z_p = pivot
    x_bk, xhb = xs2
    hh, zh0, zh1 = hump
    vw = min(vesa_w, 0.6)
    vh = min(0.7 * hh, 0.5, 2 * min(z_p - zh0, zh1 - z_p) - 0.02)
    pieces = [
        g.cylinder([x_p, -L_k / 2, z_p], [x_p, L_k / 2, z_p], r_k, "connector", 24),
        g.box_between([x_bk, -vw / 2, z_p - vh / 2], [xhb, vw / 2, z_p + vh / 2], "connector"),
    ]
    ny = min(0.35 * L_k, vw / 2 - 0.02)
    for y in (-ny, ny):
        pieces.append(g.box_between([x_p, y - 0.01, z_p - 0.7 * r_k], [x_bk + 0.001, y + 0.01, z_p + 0.7 * r_k],
                                    "connector"))
    for pc in pieces:
        pc.sheet = 0.003
    return bp.add("connector", "connector", pieces)


def _fork(x_p, z_p, r_k, L_k, material, back=True):
    """Two cheeks beside the barrel's ends and a bridge under (or behind) it."""
    t = 0.008
    yc = L_k / 2 + GAP + t / 2
    x0, x1 = x_p - 1.3 * r_k, x_p + 1.3 * r_k
    pieces = []
    for s in (-1, 1):
        pieces.append(g.box_between([x0, s * yc - t / 2, z_p - r_k - GAP - t], [x1, s * yc + t / 2, z_p + 1.2 * r_k],
                                    material))
    if back:  # a plate behind the barrel
        pieces.append(g.box_between([x0 - t, -yc - t / 2, z_p - 1.2 * r_k], [x_p - r_k - GAP, yc + t / 2,
                                                                            z_p + 1.2 * r_k], material))
    pieces.append(g.box_between([x0, -yc - t / 2, z_p - r_k - GAP - t], [x1, yc + t / 2, z_p - r_k - GAP],
                                material))
    return pieces


# ---------------------------------------------------------------------------------------------
# stands


def _pedestal(bp, p, pivot, r_k, L_k, dims, adjust, sleeve_h):
    x_p, z_p = pivot
    xf, x_bk, base_t, W, zs0 = dims
    bw = max(0.25, p["base_width"] * W)
    bd = p["base_depth"] * min(1.0, 0.6 + 0.3 * W)
    xc = x_p + 0.35 * bd * 0.5
    xc = min(xc, (x_p + xf) / 2 + 0.02)
    if p["base_shape"] == "round":
        r = max(bw, bd) / 2
        plate = g.revolve([(0, 0), (r, 0), (r, 0.6 * base_t), (r - base_t, base_t), (0, base_t)], "stand",
                          center=(x_p + 0.3 * r, 0, 0), sections=48)
    else:
        plate = g.box_between([xc - bd / 2, -bw / 2, 0], [xc + bd / 2, bw / 2, base_t], "stand",
                              bevel=0.4 * base_t)
    pieces = [plate]
    z_fork0 = z_p - r_k - GAP - 0.008  # bottom of the fork bridge
    depth_room = x_bk - GAP - x_p  # the neck stays behind the screen
    if not adjust:
        nx = min(0.012, depth_room - 0.002)
        ny = float(np.clip(0.05 * W, 0.03, 0.09))
        pieces.append(g.box_between([x_p - 0.03 - nx, -ny / 2, base_t - 0.001], [x_p + nx, ny / 2, z_fork0 + 0.001],
                                    "stand", bevel=0.003))
        pieces += _fork(x_p, z_p, r_k, L_k, "stand")
        return bp.add("stand", "stand", pieces)

    r_post = min(0.02, depth_room - 0.002)
    wall_t = 0.004
    r_in = r_post + GAP
    pieces.append(g.shell([(r_in + wall_t, base_t - 0.001), (r_in + wall_t, base_t + sleeve_h)], wall_t, "stand",
                          center=(x_p, 0, 0), sections=32))
    pieces.append(g.disc([x_p, 0, base_t + 0.002], r_in + wall_t, 0.004, "stand"))  # sleeve floor
    base = bp.add("stand", "stand", pieces)
    z_post0 = base_t + 0.004 + GAP
    post = [g.cylinder([x_p, 0, z_post0], [x_p, 0, z_fork0 + 0.001], r_post, "stand", 24)]
    post += _fork(x_p, z_p, r_k, L_k, "stand")
    name = bp.add("post", "stand", post)
    bp.join(J.revolute_prismatic(base, name, (x_p, 0.0, z_post0), (0, 0, 1), (-p["swivel"], p["swivel"]),
                                 (0, 0, 1), (0.0, p["slide"])))
    return name


def _two_legs(bp, p, pivot, r_k, L_k, dims):
    x_p, z_p = pivot
    xf, x_bk, base_t = dims
    y_leg = L_k / 2 + GAP + 0.0125
    ux = min(1.3 * r_k, x_bk - GAP - x_p - 0.002)
    bd = p["base_depth"]
    x0, x1 = min(x_p - 0.04, xf - bd), xf + 0.03
    pieces = []
    for s in (-1, 1):
        y = s * y_leg
        pieces.append(g.box_between([x0, y - 0.02, 0], [x1, y + 0.02, base_t], "stand", bevel=0.4 * base_t))
        pieces.append(g.box_between([x_p - ux, y - 0.0125, base_t - 0.001], [x_p + ux, y + 0.0125, z_p + 1.2 * r_k],
                                    "stand", bevel=0.002))
    zc = base_t + 0.3 * (z_p - base_t)
    pieces.append(g.box_between([x_p - ux, -y_leg, zc - 0.012], [x_p + ux, y_leg, zc + 0.012], "stand"))
    # small rests under the barrel at each upright
    for s in (-1, 1):
        y = s * (y_leg - 0.0125 - 0.004)
        pieces.append(g.box_between([x_p - ux, y - 0.004, z_p - r_k - GAP - 0.006], [x_p + ux, y + 0.004,
                                                                                   z_p - r_k - GAP], "stand"))
    return bp.add("stand", "stand", pieces)


def _wall_mount(bp, p, pivot, r_k, L_k, tilt, screen):
    """Wall plate (root), 1-2 arm links about Z, the tilt fork at the end of the last one.

    Returns the last arm and the tilt range, reduced where the screen top would reach the wall.
    """
    x_p, z_p = pivot
    W, xs, x_bk, hw, zs0, zs1, zh0, zh1 = screen
    n = p["arm_links"]
    r_a, h_b, t_l = 0.014, 0.05, 0.008
    lengths = [p["arm_length"] / n] * n
    x_w = x_p - p["arm_length"] - (r_a + GAP + 0.004)  # front face of the wall plate
    pw, ph = 0.2, max(0.2, h_b + 2 * (GAP + t_l) + 0.08)
    plate = [g.box_between([x_w - 0.006, -pw / 2, z_p - ph / 2], [x_w, pw / 2, z_p + ph / 2], "arm", bevel=0.002)]
    xa = x_w + r_a + GAP + 0.004  # first arm pivot
    plate += _lugs(x_w, xa, z_p, r_a, h_b, t_l, "arm")
    root = bp.add("wall_plate", "frame", plate)

    # tilt and swing ranges: the screen keeps 1 cm off the wall plane in every combination
    corners = np.array([[xs, s * W / 2, z] for s in (-1, 1) for z in (zs0, zs1)]
                       + [[x_bk, s * hw / 2, z] for s in (-1, 1) for z in (zh0, zh1)])
    pivots = [xa + sum(lengths[:i]) for i in range(n)]

    def clear(theta, phi):
        rel = corners - [x_p, 0, z_p]  # tilt about -Y through the pivot: the top goes back
        c, s = math.cos(theta), math.sin(theta)
        tilted = np.c_[rel[:, 0] * c - rel[:, 2] * s, rel[:, 1]] + [x_p, 0]
        for signs in ([1] * n, [-1] * n, [1, -1][:n], [-1, 1][:n]):
            for frac in (0.5, 1.0):
                pts = tilted.copy()
                for i in reversed(range(n)):  # turn the outermost joint first
                    a = signs[i] * frac * phi / n
                    c, s = math.cos(a), math.sin(a)
                    r = pts - [pivots[i], 0]
                    pts = np.c_[r[:, 0] * c - r[:, 1] * s, r[:, 0] * s + r[:, 1] * c] + [pivots[i], 0]
                if pts[:, 0].min() < x_w + 0.01:
                    return False
        return True

    def largest(ok, hi):
        lo = 0.0
        for _ in range(30):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if ok(mid) else (lo, mid)
        return lo

    tilt = max(largest(lambda t: clear(t, 0.0), tilt), 0.02)
    swing = max(largest(lambda f: clear(tilt, f), math.pi / 3) / n, 0.02)

    parent = root
    for i in range(n):
        x0 = pivots[i]
        x1 = x0 + lengths[i]
        last = i == n - 1
        pieces = [g.cylinder([x0, 0, z_p - h_b / 2], [x0, 0, z_p + h_b / 2], r_a, "arm", 24)]
        end = x_p - 1.3 * r_k - 0.008 if last else x1 - r_a - GAP - 0.012
        pieces.append(g.box_between([x0, -0.8 * r_a, z_p - 0.4 * h_b], [end + 0.001, 0.8 * r_a, z_p + 0.4 * h_b],
                                    "arm"))
        if last:
            pieces += _fork(x_p, z_p, r_k, L_k, "arm")
        else:
            pieces += _lugs(x1 - r_a - GAP - 0.012, x1, z_p, r_a, h_b, t_l, "arm")
        name = bp.add(f"arm_{i}", "arm", pieces)
        bp.join(J.revolute(parent, name, (x0, 0.0, z_p), (0, 0, 1), -swing, swing, role="swivel"))
        parent = name
    return parent, tilt


def _lugs(x_back, x_pin, z, r_a, h_b, t_l, material):
    """A block at ``x_back`` with two lugs above and below a vertical barrel at ``x_pin``."""
    half = h_b / 2 + GAP
    pieces = []
    for s in (-1, 1):
        z0, z1 = (z + half, z + half + t_l) if s > 0 else (z - half - t_l, z - half)
        pieces.append(g.box_between([x_back, -1.3 * r_a, z0], [x_pin + 1.3 * r_a, 1.3 * r_a, z1], material))
    pieces.append(g.box_between([x_back - 0.001, -1.3 * r_a, z - half - t_l], [x_pin - r_a - GAP, 1.3 * r_a,
                                                                               z + half + t_l], material))
    return pieces
