"""Lighters: a disposable flint lighter, a flip-top windproof lighter and a long utility lighter.

Local frame: X the lighter's front (where the flame comes out), Y across its thickness, Z up. A disposable and a
windproof lighter stand on their base (z = 0); a utility lighter lies on its side, its handle at the rear
(x = 0), its wand reaching forward along +X, its trigger under the handle (-Y) and its safety slider on the
handle's spine (+Y).

A flint lighter's spark wheel turns about Y on the hood's cheeks (continuous), above its gas lever (the
"fork": revolute about Y, its thumb pad pressed down, spring-returned). A windproof lighter's lid turns open
about its rear hinge (revolute about Y); its wheel stands on the chimney, under the lid. A utility lighter's
trigger is pulled back into the handle (prismatic, spring-returned) once its safety slider is pushed forward
(prismatic).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from .casing import moulded_slab
from .handtools import hull, sweep

SHEET = 0.0006  # m, pressed steel of a hood, chimney or windproof case (0.5-0.7 mm brass or steel: Zippo, BIC)
PLAY = 0.0012  # m, clearance round a moving part (a wheel between its cheeks, a trigger in its slot)
GAP_K = 0.0001  # m, half the gap between a hinge's neighbouring knuckles along its pin
KNURL = 18  # ridges round a spark wheel (BIC, Zippo wheels: 16-20 cross-cut teeth)


def plan(w: float, d: float, r: float, n: int = 4) -> np.ndarray:
    """``(4 (n + 1), 2)`` rounded rectangle in plan (x, y), ``w`` along x, ``d`` along y, centred."""
    r = min(r, 0.49 * w, 0.49 * d)
    pts = []
    for cx, cy, a0 in ((w / 2 - r, d / 2 - r, 0.0), (-w / 2 + r, d / 2 - r, 90.0), (-w / 2 + r, -d / 2 + r, 180.0),
                       (w / 2 - r, -d / 2 + r, 270.0)):
        for a in np.radians(a0 + np.linspace(0.0, 90.0, n + 1)):
            pts.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    return np.array(pts)


def prism(outline, z0: float, z1: float, material: str, name: str, at=(0.0, 0.0), inset: float = 0.0) -> g.Piece:
    """A convex prism on the plan ``outline`` from ``z0`` to ``z1`` (its foot ``inset`` smaller: a rounded
    base edge)."""
    o = np.asarray(outline, float)
    c = o.mean(0)
    foot = c + (o - c) * (1 - inset / max(float(np.ptp(o, 0).min()), 1e-9) * 2)
    pts = [(x + at[0], y + at[1], z) for pts_, zs in ((foot, (z0,)), (o, (z0 + inset, z1))) for x, y in pts_
           for z in zs]
    return hull(pts, material, name)


def knurled_wheel(center, radius: float, width: float, steel: str, name: str = "wheel") -> list[g.Piece]:
    """A spark wheel about Y: a steel drum ringed with the ridges of its knurl (drawn; the drum collides)."""
    c = np.asarray(center, float)
    y = np.array([0.0, width / 2, 0.0])
    pieces = [g.cylinder(c - y, c + y, radius, steel, sections=24, name=name)]
    for k in range(KNURL):
        a = 2 * math.pi * k / KNURL
        d = np.array([math.cos(a), 0.0, math.sin(a)])
        t = np.array([-math.sin(a), 0.0, math.cos(a)])
        pts = [c + d * r + t * s * 0.00055 + yy for r in (radius - 0.0003, radius + 0.0004) for s in (-1, 1)
               for yy in (-y, y)]
        pieces.append(hull(pts, steel, "knurl").replace(convex=()))
    return pieces


# -- disposable flint lighter -------------------------------------------------------------------------
@dataclass(frozen=True)
class Disposable:
    """Sizes of a disposable lighter (metres), from real products."""

    width: float  # along X
    thick: float  # along Y
    height: float  # the body's, to the shoulder under the hood
    wheel: float  # spark wheel radius


DISPOSABLES = {
    # BIC J26 Maxi: 80 x 25 x 14.5 mm overall, 21 g filled; J25 Mini 62 x 21 x 11.5 mm, 11 g
    "maxi": Disposable(0.0254, 0.0145, 0.064, 0.0046),
    "mini": Disposable(0.0210, 0.0118, 0.049, 0.0040),
}
"""Disposable lighters -> sizes (BIC listings)."""

TANK_WALL = 0.0016  # m, a disposable's moulded tank (1.5-2 mm acetal: a BIC J26 weighs ~16 g empty, ~21 g filled)
LEVER_PRESS = math.radians(12)  # the fork's stroke: its thumb pad goes down 2-3 mm to open the valve
TANK_CORNER = 0.42  # a disposable's tank plan corner radius / its thickness (the BIC J26's rounded ends)
HOOD = 0.016  # m, the hood's height over the body's shoulder (BIC J26: 80 mm overall on a 64 mm tank)


def disposable(size: float) -> Disposable:
    a, b = DISPOSABLES["mini"], DISPOSABLES["maxi"]
    return Disposable(*(x + size * (y - x) for x, y in zip(
        (a.width, a.thick, a.height, a.wheel), (b.width, b.thick, b.height, b.wheel), strict=True)))


def _hood_front(d: Disposable) -> float:
    """x of the hood's front (and, mirrored, its cheeks' back): where the tank's (faceted) plan meets the
    cheeks' outer faces, 0.3 mm inside its sides."""
    y = d.thick / 2 - 0.0006 + SHEET / 2
    o = plan(d.width, d.thick, TANK_CORNER * d.thick)
    xs = [a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) for a, b in zip(o, np.roll(o, -1, 0), strict=True)
          if (a[1] - y) * (b[1] - y) < 0]
    return max(xs) - 1e-5


def _pivot(d: Disposable) -> tuple[float, float]:
    """x, z of the fork's pivot: under the wheel, behind the fork's centre of mass (its prongs reach forward)."""
    return -0.3 * d.width, d.height + 0.0035


def _burner(d: Disposable) -> tuple[float, float]:
    """x and radius of the burner nozzle, under the chimney's flame hole."""
    return 0.5 * (0.12 * d.width + _hood_front(d)), 0.0016


def _wheel_at(d: Disposable) -> np.ndarray:
    """The spark wheel's centre: over the body's rear half, high in the hood."""
    return np.array([-d.width / 2 + d.wheel + 0.0012, 0.0, d.height + HOOD - d.wheel - 0.0005])


def disposable_body(d: Disposable, body: str, steel: str, dark: str) -> Assembly:
    """The fuel tank (a rounded prism), the steel hood on its shoulder: two cheeks carrying the wheel's
    axle, a chimney over the burner with its flame hole; anchors ``wheel`` (its axle, +Y: a thumb rolls the
    top back) and ``lever`` (the fork's pivot, -Y: +rotation presses its thumb pad down)."""
    w, t, h = d.width, d.thick, d.height
    pieces = [prism(plan(w, t, TANK_CORNER * t), 0.0, h, body, "tank", inset=0.0015).replace(wall=TANK_WALL)]
    cheek_y = t / 2 - 0.0006
    c = _wheel_at(d)
    front = _hood_front(d)
    # the cheeks stand full height round the chimney and drop behind it to just over the wheel's axle, so the
    # wheel's top and the fork's pad stand free for the thumb; crimped 1.5 mm over the tank's shoulder, their
    # ends where the tank's rounded corners meet them (the hood never overhangs the tank)
    outline = [(front, h - 0.0015), (front, h + HOOD), (0.05 * w, h + HOOD),
               (-front, c[2] + 0.0015), (-front, h - 0.0015)]
    for s in (-1, 1):
        pieces.append(hull([(x, s * cheek_y + dy, z) for x, z in outline for dy in (-SHEET / 2, SHEET / 2)], steel,
                           "cheek"))
    chimney = (0.12 * w, front)
    pieces.append(g.box_between((chimney[0], -cheek_y, h + HOOD - SHEET), (front, cheek_y, h + HOOD), steel,
                                name="chimney_top"))
    pieces.append(g.box_between((front - SHEET, -cheek_y, h - 0.0015), (front, cheek_y, h + HOOD), steel,
                                name="chimney_front"))
    hole, burner_r = _burner(d)
    pieces.append(g.cylinder((hole, 0.0, h + HOOD - 0.0003), (hole, 0.0, h + HOOD + 0.00005), 0.0018, dark, 16,
                             "flame_hole"))
    pieces.append(g.cylinder((hole, 0.0, h), (hole, 0.0, h + 0.0045), burner_r, steel, 16, "burner"))
    # the axle's rivet heads on the cheeks (drawn: the wheel turns on it)
    pieces.append(g.cylinder(c - (0, cheek_y + SHEET, 0), c + (0, cheek_y + SHEET, 0), 0.0009, steel, 12,
                             "axle_rivet").replace(convex=()))
    x_p, z_p = _pivot(d)
    anchors = {"wheel": Frame.at(c, z=(0, 1, 0)), "lever": Frame.at((x_p, 0.0, z_p), z=(0, -1, 0))}
    return Assembly.single("body", pieces, anchors)


def spark_wheel(d: Disposable, steel: str) -> Assembly:
    """The knurled spark wheel between the cheeks (its own frame: centred, axis +z)."""
    width = d.thick - 2 * (0.0006 + SHEET) - 2 * PLAY
    return Assembly.single("wheel", knurled_wheel((0, 0, 0), d.wheel, width, steel),
                           {"axle": Frame.at((0, 0, 0), z=(0, 1, 0))})


def fork(d: Disposable, plastic: str) -> Assembly:
    """The gas lever: a moulded fork from a thumb pad behind the wheel, under the wheel to its pivot, and on
    as two prongs either side of the burner (its valve's collar sits in them); heavier in front of its pivot,
    so it rests on its stop (anchor ``pivot``, as the body's ``lever``)."""
    w = d.width
    half = d.thick / 2 - 0.0006 - SHEET - PLAY
    x_p, z_p = _pivot(d)
    top = _wheel_at(d)[2] - d.wheel - PLAY  # under the wheel
    z0 = z_p - 0.001
    x0, burner = -w / 2 - 0.0008, _burner(d)
    x1 = burner[0] - burner[1] - PLAY
    arm = hull([(x, y, z) for x in (x0, x1) for y in (-half, half) for z in (z0, top)], plastic, "fork")
    pad = hull([(x, y, z) for x in (x0, x0 + 0.0035) for y in (-half, half) for z in (z0, top + 0.0012)], plastic,
               "thumb_pad")
    inner = burner[1] + PLAY
    prongs = [hull([(x, s * y, z) for x in (x1 - 0.001, min(w / 2 - 0.0025, _hood_front(d) - SHEET - PLAY))
                    for y in (inner, half)
                    for z in (z0, z0 + 0.0022)], plastic, "prong") for s in (-1, 1)]
    return Assembly.single("lever", [arm, pad, *prongs], {"pivot": Frame.at((x_p, 0.0, z_p), z=(0, -1, 0))})


# -- windproof flip-top lighter -----------------------------------------------------------------------
@dataclass(frozen=True)
class Windproof:
    """Sizes of a flip-top windproof lighter (metres), from real products."""

    width: float  # along X
    thick: float  # along Y
    height: float  # closed, overall
    lid: float  # the lid's share of the height
    wheel: float  # spark wheel radius


WINDPROOFS = {
    # Zippo 200 (regular): 38 x 13 x 57 mm, ~57 g; its lid ~18 mm of the height, 8.5 mm wheel
    "regular": Windproof(0.038, 0.013, 0.057, 0.31, 0.0042),
    # Zippo 1610 (slim): 30 x 10 x 53 mm, ~42 g
    "slim": Windproof(0.030, 0.0105, 0.053, 0.31, 0.0038),
}
"""Windproof lighters -> sizes (Zippo listings)."""

CASE_WALL = 0.0012  # m, the case massed as a shell: its 0.6 mm brass or steel and the insert's 0.5 mm steel in it
LID_OPENS = math.radians(105)  # the lid swings back against its cam spring to ~100-110 degrees
CHIMNEY_HOLES = (4, 2)  # holes per side of the chimney: columns, rows (Zippo: 8 a side)
CORNER = 0.2  # plan corner radius / thickness: a Zippo case's flat back and front, ~2.5 mm corners
HINGE = (5, 0.0013, 0.78)
"""A Zippo's five-barrel hinge at the case's back: knuckles (the case's 2nd and 4th, the lid's 1st, 3rd, 5th),
barrel radius (m) and the share of the case's thickness it spans, soldered on the flat back by their leaves
(Zippo 200: 2.6 mm barrels over ~10 mm of the 13 mm back)."""


def windproof(kind: str) -> Windproof:
    return WINDPROOFS[kind]


def _seam(z: Windproof) -> float:
    return z.height * (1 - z.lid)


def _corner(z: Windproof) -> float:
    return min(0.18 * z.width, CORNER * z.thick)


def _hinge_axis(z: Windproof) -> tuple[float, float]:
    """(x, z) of the hinge pin: its barrels just behind the back (clear of the lid's and the case's walls), at
    the seam."""
    return -z.width / 2 - HINGE[1] - 0.0002, _seam(z)


def _knuckles(z: Windproof, lid: bool, material: str) -> list[g.Piece]:
    """The case's (or, ``lid``, the lid's) knuckles of the hinge, each with its leaf soldered to the back."""
    n, rb, share = HINGE
    hx, hz = _hinge_axis(z)
    span = share * z.thick
    step = span / n
    out = []
    for k in range(n):
        if (k % 2 == 0) != lid:
            continue
        y0, y1 = -span / 2 + k * step + GAP_K, -span / 2 + (k + 1) * step - GAP_K
        ring = [(hx + rb * math.cos(a), y, hz + rb * math.sin(a)) for y in (y0, y1)
                for a in np.linspace(0, 2 * math.pi, 12, endpoint=False)]
        dz = -1.0 if not lid else 1.0  # the leaf runs down the case's back, up the lid's
        leaf = [(x, y, hz + dz * d) for x in (-z.width / 2 + 0.0004, hx) for y in (y0, y1) for d in (0.0, 2.4 * rb)]
        out.append(hull(ring + leaf, material, "knuckle"))
    return out


def _wall_ring(w: float, t: float, r: float, z0: float, z1: float, material: str, name: str) -> g.Piece:
    """A thin upright wall round a rounded rectangle (a case's or lid's skirt)."""
    path = plan(w, t, r, 3)[::-1]  # clockwise: the sweep's left normal points out, the wall grows inwards
    sec = np.array([(-SHEET, z0), (0.0, z0), (0.0, z1), (-SHEET, z1)])
    return sweep(path, sec, material, closed=True, group=2, name=name)


def windproof_body(z: Windproof, case: str, steel: str, dark: str) -> Assembly:
    """The case's lower half (a rounded steel box, the insert in it), the chimney standing out of it with
    its holes, the hinge's knuckles at the rear; anchors ``lid`` (the hinge, -Y: +rotation lifts the front)
    and ``wheel`` (its axle, +Y)."""
    w, t, seam = z.width, z.thick, _seam(z)
    r = _corner(z)
    pieces = [prism(plan(w, t, r), 0.0, seam, case, "case", inset=0.001).replace(wall=CASE_WALL)]
    cw, ct = 0.62 * w, t - 0.004  # the chimney's plan, 2 mm inside the lid's walls
    cx = 0.5 * w - 0.5 * cw - 0.003
    top = z.height - 0.0025

    rr = ct / 2  # open at the rear, its front round
    arc = [(cx + cw / 2 - rr + rr * math.cos(a), rr * math.sin(a)) for a in np.radians(np.linspace(-90, 90, 9))]
    u = np.array([(cx - cw / 2, -rr), *arc, (cx - cw / 2, rr)])
    sec = np.array([(0.0, seam - 0.002), (SHEET, seam - 0.002), (SHEET, top), (0.0, top)])  # inwards
    pieces.append(sweep(u, sec, steel, group=2, name="chimney"))
    cols, rows = CHIMNEY_HOLES
    for s in (-1, 1):
        for i in range(cols):
            for j in range(rows):
                x = cx - 0.3 * cw + 0.55 * cw * i / max(cols - 1, 1)
                zz = seam + 0.35 * (top - seam) + 0.35 * (top - seam) * j
                y = s * (ct / 2 + 0.00005)
                pieces.append(g.cylinder((x, y - s * 0.0002, zz), (x, y, zz), 0.0011, dark, 12,
                                         "chimney_hole").replace(convex=()))
    hinge = _hinge_axis(z)
    pieces += _knuckles(z, False, case)
    # the wheel's knurl stands ~1.3 mm over the chimney's top (a thumb rolls it there; Zippo 200 insert), still
    # 0.6 mm under the closed lid
    wheel = np.array([cx - 0.5 * cw + z.wheel + 0.0004, 0.0, top - z.wheel + 0.0013])
    pieces.append(g.cylinder(wheel - (0, ct / 2, 0), wheel + (0, ct / 2, 0), 0.0008, steel, 12,
                             "axle_rivet").replace(convex=()))
    anchors = {"lid": Frame.at((hinge[0], 0.0, hinge[1]), z=(0, -1, 0)), "wheel": Frame.at(wheel, z=(0, 1, 0))}
    return Assembly.single("body", pieces, anchors)


def windproof_lid(z: Windproof, case: str) -> Assembly:
    """The lid: a rounded steel cap over the chimney, closed on the case, its knuckle on the hinge."""
    w, t, seam = z.width, z.thick, _seam(z)
    r = _corner(z)
    gap = 0.0003
    pieces = [prism(plan(w, t, r), z.height - SHEET, z.height, case, "lid_top"),
              _wall_ring(w, t, r, seam + gap, z.height - SHEET + 1e-5, case, "lid_wall")]
    hinge = _hinge_axis(z)
    pieces += _knuckles(z, True, case)
    return Assembly.single("lid", pieces, {"hinge": Frame.at((hinge[0], 0.0, hinge[1]), z=(0, -1, 0))})


def windproof_wheel(z: Windproof, steel: str) -> Assembly:
    width = z.thick - 0.004 - 2 * SHEET - 2 * PLAY
    return Assembly.single("wheel", knurled_wheel((0, 0, 0), z.wheel, width, steel),
                           {"axle": Frame.at((0, 0, 0), z=(0, 1, 0))})


# -- utility (long) lighter ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Utility:
    """Sizes of a utility lighter lying on its side (metres), from real products."""

    handle: float  # handle length (X)
    height: float  # handle height (Y, lying)
    thick: float  # handle thickness (Z, lying)
    wand: float  # wand length beyond the handle
    wand_r: float  # wand radius


UTILITIES = {
    # BIC Multi-Purpose Classic: ~26 cm long, a 11 cm handle 3 cm high, 1 cm wand; Scripto / Calico long lighters
    # 25-28 cm; BIC Flex Wand (the wand's 10-16 cm reach)
    "short": Utility(0.105, 0.030, 0.017, 0.130, 0.0048),
    "long": Utility(0.118, 0.033, 0.019, 0.160, 0.0055),
}
"""Utility lighters -> sizes (BIC, Scripto listings)."""

GRIP_EDGE = 0.3  # a utility lighter's grip: its moulded edges' radius as a share of its thickness (BIC
# Multi-Purpose, Scripto: a soft, near-oval section)
HANDLE_WALL = 0.0012  # m, a utility lighter's moulded handle shell (1-1.5 mm; the BIC Multi-Purpose weighs ~40 g)
WAND_WALL = 0.0008  # m, its wand: a thin steel gas tube in a moulded sleeve, massed as one 0.8 mm wall
TRIGGER = (0.016, 0.009, 0.007)  # trigger length, how far it stands out under the handle, its travel (m): BIC MP
SAFETY = (0.013, 0.0022, 0.005)  # safety slider length, height over the spine, travel (m): BIC MP's child guard


def utility(size: float) -> Utility:
    a, b = UTILITIES["short"], UTILITIES["long"]
    return Utility(*(x + size * (y - x) for x, y in zip(
        (a.handle, a.height, a.thick, a.wand, a.wand_r), (b.handle, b.height, b.thick, b.wand, b.wand_r), strict=True)))


def _trigger_x(u: Utility) -> float:
    return 0.56 * u.handle


def utility_body(u: Utility, body: str, wand: str, steel: str, dark: str) -> Assembly:
    """The handle lying on its side: the grip behind the trigger's slot, the nose housing over the trigger
    tapering into the wand, the wand with its metal nozzle; anchors ``trigger`` (pulled back, -X) and
    ``safety`` (pushed forward, +X, on the spine)."""
    L, H, T = u.handle, u.height, u.thick
    tl, out, travel = TRIGGER
    x_t = _trigger_x(u)
    x_g = x_t - travel - PLAY  # the grip ends where the pulled trigger stops
    y_slot = -H / 2 + 0.45 * H  # the trigger's slot runs up to here
    wy = 0.18 * H  # the wand's axis, high in the nose
    grip = plan(x_g, H, 0.3 * H, 6) + (x_g / 2, 0.0)
    pieces = [moulded_slab(grip, 0.0, T, GRIP_EDGE * T, body, "grip").replace(wall=HANDLE_WALL)]
    # the nose housing tapers from the grip's section to a collar round the wand, its edges rounded as the grip's
    sections = ((x_g - 0.004, y_slot + PLAY, H / 2 - 0.002, 0.0015, T - 0.0015), (x_g, y_slot + PLAY, H / 2, 0.0, T),
                (L, wy - u.wand_r - 0.003, wy + u.wand_r + 0.003, T / 2 - u.wand_r - 0.003, T / 2 + u.wand_r + 0.003))
    nose = [(x, y, z) for x, y0, y1, z0, z1 in sections
            for y, z in plan(y1 - y0, z1 - z0, GRIP_EDGE * min(T, z1 - z0), 4) + ((y0 + y1) / 2, (z0 + z1) / 2)]
    pieces.append(hull(nose, body, "nose").replace(wall=HANDLE_WALL))
    tip = L + u.wand
    pieces.append(g.cylinder((L - 0.004, wy, T / 2), (tip - 0.012, wy, T / 2), u.wand_r, wand, None, "wand")
                  .replace(wall=WAND_WALL))
    pieces.append(g.cylinder((tip - 0.0121, wy, T / 2), (tip, wy, T / 2), 0.92 * u.wand_r, steel, None, "nozzle")
                  .replace(wall=SHEET))
    pieces.append(g.cylinder((tip - 0.0003, wy, T / 2), (tip + 0.0001, wy, T / 2), 0.45 * u.wand_r, dark, 16,
                             "flame_hole").replace(convex=()))
    anchors = {"trigger": Frame.at((x_t, -H / 2, T / 2), z=(-1, 0, 0)),
               # on the spine's flat, clear of the grip's rounded front corner at the end of its travel
               "safety": Frame.at((x_g - 0.3 * H - SAFETY[0] - SAFETY[2], H / 2, T / 2), z=(1, 0, 0))}
    return Assembly.single("body", pieces, anchors)


def trigger(u: Utility, plastic: str) -> Assembly:
    """The trigger: a moulded block standing out under the handle, its front finger-curved (own frame:
    anchor ``slide`` at its rear face, under the handle, +z back into the handle)."""
    tl, out, _ = TRIGGER
    H, T = u.height, u.thick
    y1 = 0.45 * H - PLAY  # up into its slot
    x = [0.0, tl]
    pts = [(xx, y, z) for xx in x for y in (-out, y1) for z in (0.2 * T, 0.8 * T)]
    pts += [(tl + 0.002, -0.6 * out, z) for z in (0.25 * T, 0.75 * T)]  # the finger's hook
    piece = hull(pts, plastic, "trigger")
    return Assembly.single("trigger", [piece], {"slide": Frame.at((0.0, 0.0, T / 2), z=(-1, 0, 0))})


def safety(u: Utility, plastic: str) -> Assembly:
    """The child-safety slider on the spine: a ridged tab (own frame: anchor ``slide`` at its rear end)."""
    length, height, _ = SAFETY
    T = u.thick
    pieces = [hull([(x, y, z) for x in (0.0, length) for y in (0.0004, height) for z in (0.3 * T, 0.7 * T)],
                   plastic, "slider")]
    for k in range(4):  # grip ridges across it
        x = 0.2 * length + 0.2 * length * k
        pieces.append(g.box_between((x, height - 1e-4, 0.32 * T), (x + 0.0008, height + 0.0006, 0.68 * T), plastic,
                                    name="ridge").replace(convex=()))
    return Assembly.single("slider", pieces, {"slide": Frame.at((0.0, 0.0, T / 2), z=(1, 0, 0))})
