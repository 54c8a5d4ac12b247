"""Display parts: flat screens with bezels and buttons, tilt connectors, forks, pedestal and two-leg
stands, wall plates and articulating arms.

World-aligned local frames: the screen faces +x, z is up. Sizes of real flat-panel TVs: 24-85 inch
(0.55-1.9 m wide), 20-40 mm panels, VESA 100-600 mm mounting plates, 10-20 mm tilt barrels; wall
arms reach 0.15-0.45 m (manufacturers' spec sheets: Samsung, LG, Sony; VESA MIS-D/E/F).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g

GAP = 0.004  # clearance between moving parts and their neighbours


@dataclass(frozen=True)
class Ranges:
    """Ranges of a TV's parameters (lo, hi), m, rad or a fraction. Flat-panel TVs 24-95 in (0.6-2.1 m wide),
    20-40 mm panels with 5-20 mm bezels and a 15-50 mm electronics box on 40-75 % x 35-60 % of the back;
    pedestal plates 30-55 % of the width and 18-32 cm deep, feet 50-80 % of the width apart, 3-12 cm under
    the screen; tilt brackets 7.5-22.5 degrees, height-adjustable posts 4-14 cm, swivels 15-45 degrees;
    wall arms of 0-3 links reaching 0.15-0.45 m; curved panels 3000R-4200R; 1-7 keys (manufacturers' spec
    sheets and owner's manuals: Samsung, LG, Sony; VESA MIS-D/E/F; Sanus, Vogel's arms)."""

    width: tuple[float, float] = (0.6, 2.1)
    depth: tuple[float, float] = (0.02, 0.04)
    bezel: tuple[float, float] = (0.005, 0.02)
    back_depth: tuple[float, float] = (0.015, 0.05)
    back_width: tuple[float, float] = (0.4, 0.75)
    back_height: tuple[float, float] = (0.35, 0.6)
    clearance: tuple[float, float] = (0.03, 0.12)
    base_width: tuple[float, float] = (0.3, 0.55)
    base_depth: tuple[float, float] = (0.18, 0.32)
    leg_spread: tuple[float, float] = (0.5, 0.8)
    tilt: tuple[float, float] = (math.pi / 24, math.pi / 8)
    slide: tuple[float, float] = (0.04, 0.14)
    swivel: tuple[float, float] = (math.pi / 12, math.pi / 4)
    arm_links: tuple[int, int] = (0, 3)
    curve_radius: tuple[float, float] = (3.0, 4.2)
    arm_length: tuple[float, float] = (0.15, 0.45)
    button_count: tuple[int, int] = (1, 7)



RANGES = Ranges()
CLEAR = 0.0015  # clearance of a button in its hole
BEZEL_T = 0.008  # bezel thickness (x)
RIM = 0.010  # side rim thickness (y) when side buttons go through it
PRESS = 0.002  # button travel
FORK_T = 0.008  # fork cheek and bridge thickness
LEG_W = 0.025  # two-leg stand upright width (y)
ARM = dict(radius=0.014, barrel=0.05, lug=0.008)  # wall-arm barrel radius, barrel height, lug thickness
CAMERA = dict(w=0.05, d=0.016, h=0.05, rise=0.035, gap=0.003, wall=0.003)
"""A pop-up camera behind the top edge: 50 x 16 x 50 mm, rises 35 mm (Honor Vision, Huawei Vision X65 pop-up
cameras: a module at the top centre that rises above the frame for video calls and retracts when off)."""


def bottom_band(bezel: float, bottom_buttons: bool) -> float:
    """Height of the bottom bezel band: wider when buttons sit in it."""
    return max(bezel * 1.3, 0.008 + 2 * CLEAR + 0.008) if bottom_buttons else bezel * 1.3


def button_layout(place: str, n: int, W: float, xf: float, xs: float, zs0: float, band: float) -> list:
    """(centre, half sizes) of each button; side: (x, z) on the rim, bottom: (y, z) on the bezel."""
    if place == "side":
        bx = min(0.008, (xf - BEZEL_T - xs) - 2 * CLEAR - 0.004)
        bz = 0.012
        xc = (xf - BEZEL_T + xs) / 2
        return [((xc, zs0 + 0.08 + k * (2 * bz + 0.006)), (bx / 2, bz / 2)) for k in range(n)]
    bz, by = 0.008, 0.014
    y0 = W / 2 - 0.06 - 0.2 * W / 2
    return [((y0 - k * (by + 0.008), zs0 + band / 2), (by / 2, bz / 2)) for k in range(n)]


def _hole(c, h):
    return (c[0] - h[0] - CLEAR, c[1] - h[1] - CLEAR, c[0] + h[0] + CLEAR, c[1] + h[1] + CLEAR)


def screen(W: float, xs3, zs, hump, bezel: float, band: float, buttons: list, place: str) -> list[g.Piece]:
    """A bezel around a glossy display, a back housing and an electronics box with holes for ``buttons``
    in the bezel's bottom band or the right side rim."""
    xf, xs, xhb = xs3
    zs0, zs1 = zs
    hw, zh0, zh1 = hump
    side = bool(buttons) and place == "side"
    holes = [(-W / 2 + bezel, zs0 + band, W / 2 - bezel, zs1 - bezel)]
    if buttons and place == "bottom":
        holes += [_hole(c, h) for c, h in buttons]
    xb = xf - BEZEL_T
    pieces = [g.panel([xb, -W / 2, zs0], [xf, W / 2, zs1], "bezel", "x", holes=holes).replace(sheet=0.0015),
              g.box_between([xb, -W / 2 + bezel, zs0 + band], [xf - 0.0015, W / 2 - bezel, zs1 - bezel],
                            "display").replace(sheet=0.003),
              g.box_between([xs, -W / 2, zs0], [xb, W / 2 - RIM if side else W / 2, zs1], "housing")
              .replace(sheet=0.002)]
    if side:
        pieces.append(g.panel([xs, W / 2 - RIM, zs0], [xb, W / 2, zs1], "housing", "y",
                              holes=[_hole(c, h) for c, h in buttons]).replace(sheet=0.002))
    pieces.append(g.box_between([xhb, -hw / 2, zh0], [xs + 0.001, hw / 2, zh1], "housing",
                                bevel=min(0.01, 0.3 * (xs - xhb))).replace(sheet=0.002))
    return pieces


def button(place: str, c, h, W: float, xf: float) -> tuple[g.Piece, tuple, tuple]:
    """A push button through the rim (pressed along -y) or the bezel (along -x): piece, origin, axis."""
    if place == "side":
        y_in, y_out = W / 2 - RIM + PRESS + 0.002, W / 2 + 0.0025
        piece = g.box_between([c[0] - h[0], y_in, c[1] - h[1]], [c[0] + h[0], y_out, c[1] + h[1]], "button",
                              bevel=0.001)
        return piece, (c[0], y_out, c[1]), (0, -1, 0)
    x_in, x_out = xf - BEZEL_T + PRESS + 0.002, xf + 0.002
    piece = g.box_between([x_in, c[0] - h[0], c[1] - h[1]], [x_out, c[0] + h[0], c[1] + h[1]], "button",
                          bevel=0.001)
    return piece, (x_out, c[0], c[1]), (-1, 0, 0)


def connector(pivot, r_k: float, xs2, L_k: float, vesa_w: float, hump) -> list[g.Piece]:
    """A barrel along y on the tilt axis, neck plates forward to a VESA plate on the back."""
    x_p, z_p = pivot
    x_bk, xhb = xs2
    hh, zh0, zh1 = hump
    vw = min(vesa_w, 0.6)
    vh = min(0.7 * hh, 0.5, 2 * min(z_p - zh0, zh1 - z_p) - 0.02)
    ny = min(0.35 * L_k, vw / 2 - 0.02)
    pieces = [g.cylinder([x_p, -L_k / 2, z_p], [x_p, L_k / 2, z_p], r_k, "connector", 24),
              g.box_between([x_bk, -vw / 2, z_p - vh / 2], [xhb, vw / 2, z_p + vh / 2], "connector")]
    pieces += [g.box_between([x_p, y - 0.01, z_p - 0.7 * r_k], [x_bk + 0.001, y + 0.01, z_p + 0.7 * r_k], "connector")
               for y in (-ny, ny)]
    return [pc.replace(sheet=0.003) for pc in pieces]


def fork(x_p: float, z_p: float, r_k: float, L_k: float, material: str, back: bool = True) -> list[g.Piece]:
    """Two cheeks beside the barrel's ends and a bridge under (and a plate behind) it."""
    t = FORK_T
    yc = L_k / 2 + GAP + t / 2
    x0, x1 = x_p - 1.3 * r_k, x_p + 1.3 * r_k
    pieces = [g.box_between([x0, s * yc - t / 2, z_p - r_k - GAP - t], [x1, s * yc + t / 2, z_p + 1.2 * r_k], material)
              for s in (-1, 1)]
    if back:
        pieces.append(g.box_between([x0 - t, -yc - t / 2, z_p - 1.2 * r_k],
                                    [x_p - r_k - GAP, yc + t / 2, z_p + 1.2 * r_k], material))
    pieces.append(g.box_between([x0, -yc - t / 2, z_p - r_k - GAP - t], [x1, yc + t / 2, z_p - r_k - GAP], material))
    return pieces


def base_plate(shape: str, bw: float, bd: float, base_t: float, x_p: float, xc: float) -> g.Piece:
    """A pedestal base plate: round (centred a little in front of the post) or a bevelled rectangle."""
    if shape == "round":
        r = max(bw, bd) / 2
        return g.revolve([(0, 0), (r, 0), (r, 0.6 * base_t), (r - base_t, base_t), (0, base_t)], "stand",
                         center=(x_p + 0.3 * r, 0, 0), sections=48)
    return g.box_between([xc - bd / 2, -bw / 2, 0], [xc + bd / 2, bw / 2, base_t], "stand", bevel=0.4 * base_t)


def sleeve(x_p: float, r_in: float, base_t: float, height: float, wall: float = 0.004) -> list[g.Piece]:
    """A round sleeve on the base for a height-adjustable post, and its floor."""
    return [g.shell([(r_in + wall, base_t - 0.001), (r_in + wall, base_t + height)], wall, "stand", center=(x_p, 0, 0),
                    sections=32),
            g.disc([x_p, 0, base_t + 0.002], r_in + wall, 0.004, "stand")]


TIP_ANGLE = math.radians(10)
"""A TV on its stand must not overturn tilted 10 degrees from upright in any direction (IEC 62368-1 clause
8.6.2.2, as IEC 60065 clause 19.1 before it): its centre of mass stays inside the floor contact by its
height x tan(10 degrees)."""


def stable_span(centre, pivot, tilt: float, rise: float = 0.0) -> tuple[float, float]:
    """The x span (back, front) a stand's floor contact must cover (:data:`TIP_ANGLE`): the centre of mass
    taken at the screen's ``centre`` (x, z; the panel outweighs its stand), upright and tilted back by
    ``tilt`` about ``pivot`` (x, z), raised by ``rise`` (a height-adjustable post's travel)."""
    (x_c, z_c), (x_p, z_p) = centre, pivot
    c, s = math.cos(tilt), math.sin(tilt)  # about -y: the top goes back
    x_t, z_t = x_p + (x_c - x_p) * c - (z_c - z_p) * s, z_p + (x_c - x_p) * s + (z_c - z_p) * c
    k = math.tan(TIP_ANGLE)
    return min(x_c - k * (z_c + rise), x_t - k * (z_t + rise)), max(x_c + k * (z_c + rise), x_t + k * (z_t + rise))


def two_legs(x_p: float, z_p: float, r_k: float, L_k: float, xf: float, x_bk: float, base_t: float, depth: float,
             span: tuple[float, float]) -> list[g.Piece]:
    """Two feet under the screen with uprights behind it, a low crossbar, rests under the barrel; the feet
    reach at least ``depth`` and over the ``span`` that keeps the set standing (:func:`stable_span`)."""
    y_leg = L_k / 2 + GAP + LEG_W / 2
    ux = min(1.3 * r_k, x_bk - GAP - x_p - 0.002)
    x0, x1 = min(x_p - 0.04, xf - depth, span[0]), max(xf + 0.03, span[1])
    pieces = []
    for s in (-1, 1):
        y = s * y_leg
        pieces.append(g.box_between([x0, y - 0.02, 0], [x1, y + 0.02, base_t], "stand", bevel=0.4 * base_t))
        pieces.append(g.box_between([x_p - ux, y - LEG_W / 2, base_t - 0.001],
                                    [x_p + ux, y + LEG_W / 2, z_p + 1.2 * r_k], "stand", bevel=0.002))
    zc = base_t + 0.3 * (z_p - base_t)
    pieces.append(g.box_between([x_p - ux, -y_leg, zc - 0.012], [x_p + ux, y_leg, zc + 0.012], "stand"))
    for s in (-1, 1):
        y = s * (y_leg - LEG_W / 2 - 0.004)
        pieces.append(g.box_between([x_p - ux, y - 0.004, z_p - r_k - GAP - 0.006],
                                    [x_p + ux, y + 0.004, z_p - r_k - GAP], "stand"))
    return pieces


def lugs(x_back: float, x_pin: float, z: float, material: str) -> list[g.Piece]:
    """A block at ``x_back`` with two lugs above and below a vertical barrel at ``x_pin``."""
    r_a, h_b, t_l = ARM["radius"], ARM["barrel"], ARM["lug"]
    half = h_b / 2 + GAP
    pieces = []
    for s in (-1, 1):
        z0, z1 = (z + half, z + half + t_l) if s > 0 else (z - half - t_l, z - half)
        pieces.append(g.box_between([x_back, -1.3 * r_a, z0], [x_pin + 1.3 * r_a, 1.3 * r_a, z1], material))
    pieces.append(g.box_between([x_back - 0.001, -1.3 * r_a, z - half - t_l], [x_pin - r_a - GAP, 1.3 * r_a,
                                                                               z + half + t_l], material))
    return pieces


def wall_plate(x_w: float, x_pin: float, z_p: float) -> list[g.Piece]:
    """A wall plate with its face at ``x_w`` and the lugs of the first arm joint."""
    pw, ph = 0.2, max(0.2, ARM["barrel"] + 2 * (GAP + ARM["lug"]) + 0.08)
    return [g.box_between([x_w - 0.006, -pw / 2, z_p - ph / 2], [x_w, pw / 2, z_p + ph / 2], "arm", bevel=0.002),
            *lugs(x_w, x_pin, z_p, "arm")]


def arm_link(x0: float, x1: float, z_p: float, end: float, last_fork: list | None) -> list[g.Piece]:
    """One arm link: a barrel at ``x0``, a beam to ``end``, then the next joint's lugs (or the tilt fork)."""
    r_a, h_b = ARM["radius"], ARM["barrel"]
    pieces = [g.cylinder([x0, 0, z_p - h_b / 2], [x0, 0, z_p + h_b / 2], r_a, "arm", 24),
              g.box_between([x0, -0.8 * r_a, z_p - 0.4 * h_b], [end + 0.001, 0.8 * r_a, z_p + 0.4 * h_b], "arm")]
    return pieces + (last_fork if last_fork is not None else lugs(x1 - r_a - GAP - 0.012, x1, z_p, "arm"))


def wall_mount_ranges(corners: np.ndarray, pivot, pivots: list[float], x_wall: float, tilt: float, n: int
                      ) -> tuple[float, float]:
    """The largest tilt (<= ``tilt``) and arm swing per joint that keep the screen ``corners`` 1 cm off
    the wall plane in every combination of the arm joints (bisection over sampled combinations)."""
    x_p, z_p = pivot
    x_p, z_p = float(x_p), float(z_p)
    points = np.asarray(corners, float).tolist()
    # plain float arithmetic, term for term the array arithmetic it replaces (same bits, no per-call
    # numpy overhead: this runs thousands of times per object)

    def clear(theta, phi):
        c, s = math.cos(theta), math.sin(theta)  # tilt about -y through the pivot: the top goes back
        tilted = [((x - x_p) * c - (z - z_p) * s + x_p, (y - 0.0) + 0.0) for x, y, z in points]
        for signs in ([1] * n, [-1] * n, [(-1) ** i for i in range(n)], [-(-1) ** i for i in range(n)]):
            for frac in (0.5, 1.0):
                pts = tilted
                for i in reversed(range(n)):  # turn the outermost joint first
                    a = signs[i] * frac * phi / n
                    c, s = math.cos(a), math.sin(a)
                    pv = float(pivots[i])
                    pts = [((u - pv) * c - (v - 0.0) * s + pv, (u - pv) * s + (v - 0.0) * c + 0.0) for u, v in pts]
                if min(u for u, _ in pts) < x_wall + 0.01:
                    return False
        return True

    def largest(ok, hi):
        lo = 0.0
        for _ in range(30):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if ok(mid) else (lo, mid)
        return lo

    tilt = max(largest(lambda t: clear(t, 0.0), tilt), 0.02)
    if n == 0:  # a tilting mount: no arm joints
        return tilt, 0.0
    return tilt, max(largest(lambda f: clear(tilt, f), math.pi / 3) / n, 0.02)


def curved_screen(W: float, xs3, zs, hump, bezel: float, band: float, buttons: list, radius: float,
                  flat: float) -> list[g.Piece]:
    """A curved panel (concave towards the viewer, +x): a flat middle ``-flat..flat`` carrying the bottom
    band's button holes, then facets along an arc of ``radius`` on each side (about 2 degrees each), the
    edges brought forward by ``radius (1 - cos phi)``; a flat electronics box on the back of the middle."""
    xf, xs, xhb = xs3
    zs0, zs1 = zs
    hw, zh0, zh1 = hump
    xb = xf - BEZEL_T
    half = W / 2

    def slab(y0, y1, side=0):
        """Bezel strips, display and housing of one stretch ``y0..y1``; ``side`` +-1: the outermost stretch,
        with the side bezel at its +y (or -y) end."""
        lo, hi = y0 + (bezel if side < 0 else 0.0), y1 - (bezel if side > 0 else 0.0)
        pcs = [g.box_between([xb, y0, zs1 - bezel], [xf, y1, zs1], "bezel").replace(sheet=0.0015),
               g.box_between([xs, y0, zs0], [xb, y1, zs1], "housing").replace(sheet=0.002),
               g.box_between([xb, y0, zs0], [xf, y1, zs0 + band], "bezel").replace(sheet=0.0015),
               g.box_between([xb, lo, zs0 + band], [xf - 0.0015, hi, zs1 - bezel], "display").replace(sheet=0.003)]
        if side:
            ya, yb = (hi, y1) if side > 0 else (y0, lo)
            pcs.append(g.box_between([xb, ya, zs0 + band], [xf, yb, zs1 - bezel], "bezel").replace(sheet=0.0015))
        return pcs

    pieces = [g.panel([xb, -flat, zs0], [xf, flat, zs0 + band], "bezel", "x",
                      holes=[_hole(c, h) for c, h in buttons]).replace(sheet=0.0015),
              g.box_between([xb, -flat, zs1 - bezel], [xf, flat, zs1], "bezel").replace(sheet=0.0015),
              g.box_between([xb, -flat, zs0 + band], [xf - 0.0015, flat, zs1 - bezel], "display").replace(sheet=0.003),
              g.box_between([xs, -flat, zs0], [xb, flat, zs1], "housing").replace(sheet=0.002),
              g.box_between([xhb, -hw / 2, zh0], [xs + 0.001, hw / 2, zh1], "housing",
                            bevel=min(0.01, 0.3 * (xs - xhb))).replace(sheet=0.002)]
    pieces.append(pieces.pop(4))  # the electronics box last, as in :func:`screen`
    arc = half - flat
    n = max(2, int(math.ceil(arc / radius / math.radians(2.0))))
    step = arc / n  # arc length of a facet
    for s in (-1, 1):
        for i in range(n):
            phi = i * step / radius
            local = slab(0.0, step, s if i == n - 1 else 0) if s > 0 else slab(-step, 0.0, s if i == n - 1 else 0)
            c, sn = math.cos(-s * phi), math.sin(-s * phi)
            m = np.array([[c, -sn, 0, radius * (1 - math.cos(phi))], [sn, c, 0, s * (flat + radius * math.sin(phi))],
                          [0, 0, 1, 0], [0, 0, 0, 1]], float)  # the facet turned about z, moved to its start on the arc
            pieces += [pc.transformed(m) for pc in local]
    return pieces


def camera_pocket(xs: float, zs1: float) -> list[g.Piece]:
    """The pocket on the back of the housing that the pop-up camera sits in: a floor, two sides and a back
    wall, open at the top; ``xs`` is the housing's back face, ``zs1`` the screen's top."""
    c = CAMERA
    gp, t = c["gap"], c["wall"]
    xc1 = xs - 0.004  # the camera's front face
    xc0 = xc1 - c["d"]
    yo, zb = c["w"] / 2 + gp, zs1 - c["h"] - gp
    return [g.box_between([xc0 - gp - t, -yo - t, zb], [xc0 - gp, yo + t, zs1], "housing"),
            g.box_between([xc0 - gp - t, -yo - t, zb - t], [xs + 0.001, yo + t, zb], "housing"),
            *[g.box_between([xc0 - gp, ya, zb], [xs + 0.001, yb, zs1], "housing") for ya, yb in ((yo, yo + t),
                                                                                                 (-yo - t, -yo))]]


def camera(xs: float, zs1: float) -> list[g.Piece]:
    """The camera module at rest, its top 1 mm under the screen's top, its lens on the front face near the top."""
    c = CAMERA
    xc1 = xs - 0.004
    z1 = zs1 - 0.001
    return [g.box_between([xc1 - c["d"], -c["w"] / 2, z1 - c["h"]], [xc1, c["w"] / 2, z1], "camera", bevel=0.003),
            g.cylinder([xc1 - 0.001, 0, z1 - 0.013], [xc1 + 0.0008, 0, z1 - 0.013], 0.0065, "display", 24)]


def camera_corners(xs: float, zs1: float) -> list[list[float]]:
    """Back corners of the pocket and of the raised camera (for the wall-clearance search)."""
    c = CAMERA
    x = xs - 0.004 - c["d"] - c["gap"] - c["wall"]
    y = c["w"] / 2 + c["gap"] + c["wall"]
    return [[x, s * y, z] for s in (-1, 1) for z in (zs1, zs1 + c["rise"])]


def tilt_bracket(x_w: float, x_p: float, z_p: float, r_k: float, L_k: float) -> list[g.Piece]:
    """A tilting wall mount: a wall plate with its face at ``x_w``, a bracket out to the tilt fork at ``x_p``."""
    ph = max(0.2, 2.6 * r_k + 0.08)
    x_fork = x_p - 1.3 * r_k - FORK_T  # the fork's back plate
    hz = min(0.02, 1.1 * r_k)
    return [g.box_between([x_w - 0.006, -0.1, z_p - ph / 2], [x_w, 0.1, z_p + ph / 2], "arm", bevel=0.002),
            g.box_between([x_w - 0.001, -0.35 * L_k, z_p - hz], [x_fork + 0.001, 0.35 * L_k, z_p + hz], "arm"),
            *fork(x_p, z_p, r_k, L_k, "arm")]


# -- a TV's layout: where the screen, the connector and the stand go ---------------------------------------
ASPECT = {"16:9": 9 / 16, "4:3": 3 / 4}  # screen height / width
TV = {
    # mounting height of a wall TV: the screen's centre at seated eye level, about 42 in (1.07 m) off the floor
    # (Sanus and Crutchfield TV mounting-height guides); a very tall screen keeps its bottom 30 cm up
    "wall_centre": 1.07, "wall_bottom_min": 0.3,
    # shortest link of an articulating wall arm (3-link arms reach 0.45-0.65 m: Sanus VLF628, Vogel's Wall 3345
    # spec sheets)
    "arm_link_min": 0.14,
    "base_t": (0.008, 0.006, 0.01, 0.02),  # pedestal plate / foot height: a + b * W, clipped to [lo, hi]
    "barrel": (0.008, 0.004, 0.01, 0.016),  # tilt barrel radius: a + b * W, clipped to [lo, hi]
    "sleeve_over_slide": 0.03,  # a height-adjustable post's sleeve is this much taller than its travel
    "over_sleeve": 0.015,  # the screen's bottom clears the sleeve's top by at least this
    "box_over_bottom": (0.04, 0.06),  # the electronics box's bottom over the screen's, x H (stand, wall)
    "vesa_plate": 0.004,  # the VESA plate behind the electronics box
    "pivot_in_box": 0.06,  # the tilt pivot at least this far inside the box's top and bottom
    "fork_back": (1.3, 1.2),  # the fork's reach behind the pivot: a * r + b * r * sin(tilt), + GAP + VESA plate
    "fork_w": (0.12, 0.08, 0.16),  # a single post's fork: this share of W, clipped to [lo, hi]
    "vesa": (0.02, 0.8, 0.1),  # VESA plate width: the box less a, or b * the fork's width + c
    "curved_keys": (0.024, 0.012, 0.04),  # a curved panel's keys: pitch; its flat middle >= pitch * n + c
    "camera_slide": (0.004, 0.001),  # the camera's slide origin behind the back and under the top edge
    # a pedestal: at least 25 cm wide, its depth shrinks on small screens (0.6 + 0.3 W, at most 1), its
    # centre 35 % of half its depth in front of the pivot, at most 2 cm in front of the middle of the panel
    "pedestal": {"min_width": 0.25, "depth": (0.6, 0.3), "ahead": 0.35, "ahead_max": 0.02},
    # a swivel neck (Samsung / LG swivel stands): at most 12 mm in front of the pivot (2 mm behind the screen),
    # 5 % of W wide (30-90 mm), 30 mm behind the pivot; on a 6 mm bearing disc 15 mm behind the pivot
    "neck": {"front": 0.012, "room": 0.002, "width": (0.05, 0.03, 0.09), "back": 0.03, "disc": 0.006,
             "disc_back": 0.015},
    "post": 0.02,  # a height-adjustable post's radius, at most
    "sleeve_floor": 0.004,  # the post's bottom over the base, past the sleeve's floor
    "into_fork": 0.001,  # the neck or post reaches this far into the fork's bridge
    # a tilting wall mount: the fork 1.3 barrel radii + the cheek + 2 cm off the plate, 1 cm more until the full
    # tilt clears the wall (1 mrad short of it is enough), at most 30 cm
    "tilt_mount": {"standoff": 0.02, "step": 0.01, "max": 0.3, "tol": 1e-3},
    "plate_room": 0.004,  # a wall arm's first barrel clears the wall plate by GAP and this
    "arm_end": (0.008, 0.012),  # an arm beam ends this far short of the tilt fork / the next lugs
}


def wall_elevation(H: float) -> float:
    """A wall TV's elevation: its centre at seated eye height, its bottom at least ``TV["wall_bottom_min"]`` up."""
    return max(TV["wall_bottom_min"], TV["wall_centre"] - H / 2)


def screen_frame(W: float, D: float, aspect: str, wall: bool, adjust: bool, clearance: float, slide: float,
                 back: tuple[float, float, float], tilt: float) -> dict:
    """Where a TV's screen, electronics box and tilt pivot go: the screen ``W`` wide (``aspect``), ``D`` thick,
    ``clearance`` over a pedestal's base (a height-adjustable post's sleeve ``slide`` + 3 cm tall under it) or
    on a wall; the electronics box (``back``: width and height shares, depth) behind it; the tilt barrel's
    pivot behind the VESA plate, far enough back for its fork to clear the screen over the whole ``tilt``."""
    H = W * ASPECT[aspect]
    a, b, lo, hi = TV["base_t"]
    base_t = 0.0 if wall else float(np.clip(a + b * W, lo, hi))  # plate / foot height
    sleeve_h = slide + TV["sleeve_over_slide"]
    clearance = max(clearance, sleeve_h + TV["over_sleeve"]) if adjust else clearance
    zs0 = base_t + clearance
    zs1 = zs0 + H
    xf, xs = D / 2, -D / 2  # front and back face of the thin panel
    hw, hh = back[0] * W, back[1] * H
    stand_share, wall_share = TV["box_over_bottom"]
    zh0 = zs0 + (wall_share if wall else stand_share) * H  # electronics box
    zh1 = zh0 + hh
    xhb = xs - back[2]
    x_bk = xhb - TV["vesa_plate"]  # back face of the VESA plate (part of the connector)
    a, b, lo, hi = TV["barrel"]
    r_k = float(np.clip(a + b * W, lo, hi))
    fa, fb = TV["fork_back"]
    e = (fa * r_k + fb * r_k * math.sin(tilt) + GAP + TV["vesa_plate"]) / math.cos(tilt)
    x_p = x_bk - e
    m = TV["pivot_in_box"]
    z_p = min(max((zh0 + zh1) / 2 if not wall else zs0 + 0.5 * H, zh0 + m), zh1 - m)
    return dict(H=H, base_t=base_t, sleeve_h=sleeve_h, zs=(zs0, zs1), xf=xf, xs=xs, xhb=xhb, x_bk=x_bk,
                hump=(hw, hh, zh0, zh1), r_k=r_k, pivot=(x_p, z_p), centre=((xf + xs) / 2, (zs0 + zs1) / 2))


def curved_keys(layout: list, hump_w: float) -> tuple[list, float]:
    """A curved panel's keys along its flat middle (``layout`` as :func:`button_layout` on the bottom), and
    that flat middle's width (half the electronics box, at least what the keys need)."""
    pitch, per_key, spare = TV["curved_keys"]
    n = len(layout)
    return [((pitch * (k - (n - 1) / 2), c[1]), h) for k, (c, h) in enumerate(layout)], \
        max(0.5 * hump_w, per_key * n + spare)


def fork_width(two_legs: bool, W: float, leg_spread: float) -> float:
    """The tilt fork's width: between the uprights of two legs ``leg_spread`` x W apart, else a share of W."""
    if two_legs:
        return 2 * (leg_spread * W / 2 - LEG_W / 2 - GAP)  # between the uprights
    share, lo, hi = TV["fork_w"]
    return float(np.clip(share * W, lo, hi))


def vesa_width(hump_w: float, L_k: float) -> float:
    """The VESA plate's width: inside the electronics box, scaled with the fork."""
    a, b, c = TV["vesa"]
    return min(hump_w - a, b * L_k + c)


def camera_slide(xs: float, zs1: float):
    """The pop-up camera's slide origin (it rises along +Z from there)."""
    dx, dz = TV["camera_slide"]
    return (xs - dx, 0.0, zs1 - dz)


def pedestal_base(shape: str, base_width: float, base_depth: float, W: float, base_t: float, x_p: float,
                  xf: float, span: tuple[float, float]) -> g.Piece:
    """A pedestal's base plate (:func:`base_plate`): at least 25 cm wide, shallower under a small screen,
    centred a little in front of the pivot, and over the ``span`` that keeps the set standing
    (:func:`stable_span`)."""
    d = TV["pedestal"]
    bw = max(d["min_width"], base_width * W)
    bd = base_depth * min(1.0, d["depth"][0] + d["depth"][1] * W)
    xc = min(x_p + d["ahead"] * bd * 0.5, (x_p + xf) / 2 + d["ahead_max"])
    if shape == "round":  # a disc of radius max(bw, bd) / 2 centred 0.3 radii in front of the post
        r = max(max(bw, bd) / 2, (x_p - span[0]) / 0.7, (span[1] - x_p) / 1.3)
        bw, bd = max(bw, 2 * r), max(bd, 2 * r)
    elif xc - bd / 2 > span[0] or xc + bd / 2 < span[1]:
        lo, hi = min(xc - bd / 2, span[0]), max(xc + bd / 2, span[1])
        xc, bd = (lo + hi) / 2, hi - lo
    return base_plate(shape, bw, bd, base_t, x_p, xc)


def fork_bottom(z_p: float, r_k: float) -> float:
    """Bottom of the tilt fork's bridge under the pivot."""
    return z_p - r_k - GAP - FORK_T


def swivel_neck(x_p: float, z_p: float, r_k: float, L_k: float, W: float, x_bk: float, base_t: float
                ) -> tuple[g.Piece, list[g.Piece], tuple]:
    """A swivel pedestal's neck: a bearing disc on the base (the stand's), the neck up to the fork (the
    post's, with the fork) behind the screen; returns both and the swivel axis' origin."""
    n = TV["neck"]
    room = x_bk - GAP - x_p  # the neck stays behind the screen
    share, lo, hi = n["width"]
    nx, ny = min(n["front"], room - n["room"]), float(np.clip(share * W, lo, hi))
    xc, r_c, z_b = x_p - n["disc_back"], 0.5 * math.hypot(n["back"] + 2 * nx, ny) + n["disc"], base_t + n["disc"]
    disc = g.cylinder([xc, 0, base_t - 0.001], [xc, 0, z_b], r_c, "stand", 32)
    neck = g.box_between([x_p - n["back"] - nx, -ny / 2, z_b + GAP],
                         [x_p + nx, ny / 2, fork_bottom(z_p, r_k) + TV["into_fork"]], "stand", bevel=0.003)
    return disc, [neck] + fork(x_p, z_p, r_k, L_k, "stand"), (xc, 0.0, z_b)


def post_sleeve(x_p: float, z_p: float, r_k: float, x_bk: float, base_t: float, sleeve_h: float
                ) -> tuple[list[g.Piece], dict]:
    """A height-adjustable pedestal's sleeve on the base (:func:`sleeve`) and where its post goes
    (``r_post``, ``z0``, ``z1``: from the sleeve's floor into the fork)."""
    room = x_bk - GAP - x_p  # the post stays behind the screen
    r_post = min(TV["post"], room - TV["neck"]["room"])
    return sleeve(x_p, r_post + GAP, base_t, sleeve_h), \
        dict(r_post=r_post, z0=base_t + TV["sleeve_floor"] + GAP, z1=fork_bottom(z_p, r_k) + TV["into_fork"])


def screen_corners(xs: float, W: float, zs, x_bk: float, hump, camera: bool) -> np.ndarray:
    """The screen's back corners, the electronics box's and (``camera``) the camera's: what must clear the wall."""
    hw, zh0, zh1 = hump
    return np.array([[xs, s * W / 2, z] for s in (-1, 1) for z in zs]
                    + [[x_bk, s * hw / 2, z] for s in (-1, 1) for z in (zh0, zh1)]
                    + (camera_corners(xs, zs[1]) if camera else []))


def tilt_mount(corners: np.ndarray, pivot, r_k: float, L_k: float, tilt: float) -> tuple[list[g.Piece], float]:
    """A tilting wall mount: the fork on a bracket (:func:`tilt_bracket`), as far off the wall as the full
    ``tilt`` needs; returns its pieces and the tilt it allows."""
    x_p, z_p = pivot
    t = TV["tilt_mount"]
    stand_off = TV["fork_back"][0] * r_k + FORK_T + t["standoff"]
    while True:
        got, _ = wall_mount_ranges(corners, pivot, [], x_p - stand_off, tilt, 0)
        if got >= tilt - t["tol"] or stand_off > t["max"]:
            break
        stand_off += t["step"]
    return tilt_bracket(x_p - stand_off, x_p, z_p, r_k, L_k), got


def arm_pivots(x_p: float, arm_length: float, n: int) -> tuple[float, list[float], float]:
    """An articulating wall arm of ``n`` links reaching ``arm_length`` (3 links: each at least
    ``TV["arm_link_min"]``) to the tilt pivot ``x_p``: the wall plate's face, the link pivots, a link's length."""
    reach = max(arm_length, TV["arm_link_min"] * n) if n >= 3 else arm_length
    r_a = ARM["radius"]
    x_w = x_p - reach - (r_a + GAP + TV["plate_room"])  # front face of the wall plate
    xa = x_w + r_a + GAP + TV["plate_room"]  # first arm pivot
    length = reach / n
    return x_w, [xa + i * length for i in range(n)], length


def arm_end(x1: float, last: bool, x_p: float, r_k: float) -> float:
    """Where an arm link's beam ends: short of the tilt fork (the last link) or of the next link's lugs."""
    to_fork, to_lugs = TV["arm_end"]
    return x_p - TV["fork_back"][0] * r_k - to_fork if last else x1 - ARM["radius"] - GAP - to_lugs
