"""Luggage: clamshell suitcase shells, a wheel plinth, spinner housings, inline wheels, a two-stage telescopic
handle, folding carry handles, a front pocket and a combination lock.

A suitcase stands on z = 0 centred on the z axis, its front facing +x, its width along y. Its case is two
shells that meet at the split plane ``x = split``: the body (the back shell, with the handle, the wheels and
the carry handles) and the lid (the front shell) hinged on a vertical line at the right edge of the split
(seen from the front), so it swings open like a book with the gravity torque about its hinge nil. Every part is
built in the world frame of a :class:`CaseSize` and carries the anchors the others attach to: the category
says "the lid on the body's ``hinge``, the first stage in the body's ``telescope``" and never computes a
coordinate. Anchors follow the project's convention: a hinge or slide anchor's z is the joint axis and a
positive move opens.

Sizes are data (:data:`SIZES` and the constants below), each figure beside the product it is read from.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from .seating import WHEEL_INSET

# Outer sizes (height with the wheels, width, depth; metres) and the lid's share of the depth, by design:
# hard spinners, checked sizes: Samsonite Freeform 24" 69 x 47 x 30 cm 3.9 kg, 28" 79 x 53 x 33 cm 4.6 kg;
#   Away The Large 74 x 52 x 32 cm 5.4 kg; Rimowa Original Check-In M (aluminium) 69 x 46 x 25 cm 6.6 kg;
#   shells split 50/50.
# soft two-wheel uprights: Travelpro Platinum Elite 22" rollaboard 58 x 36 x 23 cm 3.5 kg, 25" 70 x 45 x 30 cm
#   4.5 kg; Briggs & Riley Baseline 27" 74 x 48 x 30 cm 5.2 kg; the main lid is the front ~35 % of the depth.
# carry-ons (IATA 55 x 40 x 20 cm; US 22 x 14 x 9 in = 56 x 36 x 23 cm): Samsonite Freeform carry-on
#   55 x 40 x 20 cm 2.6 kg, Away The Carry-On 55.9 x 34.5 x 22.9 cm 3.2 kg.
SIZES = {
    "hard_spinner": dict(height=(0.66, 0.80), width=(0.44, 0.54), depth=(0.26, 0.34), lid_share=0.5),
    "soft_upright": dict(height=(0.56, 0.74), width=(0.36, 0.48), depth=(0.23, 0.31), lid_share=0.36),
    "carry_on": dict(height=(0.53, 0.56), width=(0.345, 0.40), depth=(0.20, 0.235), lid_share=0.5),
}

GAP = 0.003  # m, clearance between a moving part and its neighbours
WALL = 0.004  # m, a shell wall as the simulator sees it (massed as the shell's sheet)
# Shell walls (massed as sheet, metres): polycarbonate spinner shells 1.5-2 mm (Samsonite, Away: ~1.2-1.5 kg a
# shell of ~0.7 m^2); grooved aluminium 0.9-1 mm (Rimowa Original); a soft case's ballistic nylon over
# its foam and board panels ~1.2 kg/m^2 (Travelpro spec), massed as 3 mm of a 400 kg/m^3 layup.
SHEET = {"plastic": 0.0018, "brushed_metal": 0.001, "fabric": 0.003}
SOFT_DENSITY = 400.0  # kg/m^3, the soft case's layup as massed (see SHEET)
ALUMINIUM = 2700.0  # kg/m^3, an aluminium shell's substrate
# Corner radii of the case seen from the front and the rounding of its front and back faces' edges: moulded
# shells are round (40-70 mm corners, 35-45 mm edges: Samsonite, Away), soft cases squarer (25-40 mm, 20 mm).
ROUND = {"hard": dict(corner=(0.045, 0.07), edge=0.04), "soft": dict(corner=(0.025, 0.04), edge=0.022)}
RIBS = 5  # raised ribs on a grooved hard shell's face (Rimowa, Samsonite Cosmolite: 4-8)

# Telescopic handles (Samsonite, Travelpro spare-part listings): aluminium tubes 19-27 mm across, 4 mm less
# each stage up (two stages, or three on many carry-ons), 20-28 cm apart; the grip of a 55 cm carry-on reaches
# 98-105 cm extended, of a 75 cm case ~110 cm; a moulded grip 24-30 mm thick.
TUBE_SHEET = 0.0012  # m, the tubes' aluminium walls (1-1.5 mm drawn tube)
TUBES = dict(outer=0.0135, inner=0.0095, play=0.001, collar=0.004, grip=(0.024, 0.03), overlap=0.07)
# Folding carry handles: a 13-18 cm moulded grip ~22 mm thick on two pivots 12 mm off the shell (Samsonite
# Freeform top and side handles); it lies flat and swings out about 90 degrees.
CARRY = dict(grip=0.011, arm=0.005, length=(0.13, 0.18), reach=0.035, boss=0.01)
CARRY_TURN = math.radians(90)
LID_OPENS = math.radians(180)  # a clamshell opens flat
# Expandable cases (Samsonite "EXP", Travelpro expandable): a zipped gusset lets the front section out 4-6 cm.
EXPANDER = dict(depth=0.05, overlap=0.012)
# Spinner housings and wheels: moulded housings ~55 mm across round twin or single 50-65 mm wheels
# (Samsonite, Hinomoto spare wheels); inline two-wheel uprights: 70-80 mm skate wheels 25 mm wide in
# recessed housings at the back corners (Travelpro, Briggs & Riley).
HOUSING = 0.028  # m, a spinner housing's radius
INLINE = dict(radius=(0.034, 0.04), width=0.024, inset=0.012, hub=0.55)
SKID = 0.012  # m, a two-wheeler's base above the ground: it stands on its wheels and two front feet
# A front pocket (a soft case's zipped pocket, a business carry-on's laptop pocket): a 2-3 cm deep panel over
# the lid's front, 70-85 % of its width and height, zipped on three sides, hinged at its right edge.
POCKET = dict(share=(0.78, 0.72), depth=0.022, zip=0.004)
POCKET_OPENS = math.radians(120)
# Zip-up lid dividers (Samsonite, Away): a nylon or mesh panel across the lid's opening, zipped round three sides
# and sewn along the hinge side, with a zip pull; modelled 4 mm thick, massed as 4 mm of the lining fabric
# (100 kg/m^3: 0.4 kg/m^2, a 420D nylon panel with its zip tape).
DIVIDER = dict(t=0.004, sheet=0.004, **{"in": 0.012})
DIVIDER_OPENS = math.radians(150)
# TSA combination locks (Travel Sentry locks on Samsonite, Away): three 12 mm thumbwheels in a ~60 x 25 mm
# housing on the side, by the split.
LOCK = dict(housing=(0.064, 0.028, 0.012), wheel=0.0075, thick=0.006, pitch=0.0095)


@dataclass(frozen=True)
class CaseSize:
    """A suitcase: outer ``height`` (wheels included), ``width`` (y), ``depth`` (x); the split plane's x
    ``split``; the shell's bottom above the ground ``z0``; its corner radius and edge rounding, the
    modelled wall and its sheet; ``hard`` (a moulded or aluminium shell) or soft."""

    height: float
    width: float
    depth: float
    split: float
    z0: float
    corner: float
    edge: float
    sheet: float
    hard: bool

    @property
    def top(self) -> float:
        return self.height

    @property
    def zc(self) -> float:
        """The shell's middle height."""
        return (self.z0 + self.height) / 2

    @property
    def tube_x(self) -> float:
        """The telescopic handle's tubes: just inside the back face's edge rounding."""
        return -self.depth / 2 + self.edge + TUBES["outer"] + GAP

    @property
    def tube_y(self) -> float:
        """Half the distance between the handle's tubes: 20-28 cm apart, clear of the corners."""
        return min(0.12, self.width / 2 - self.corner - TUBES["outer"] - GAP)


def case_size(design: str, shares: tuple[float, float, float], z0: float, corner: float, hard: bool,
              finish: str) -> CaseSize:
    """The case of ``design`` at ``shares`` (0-1) of its height, width and depth ranges, the shell's bottom at
    ``z0``."""
    s = SIZES[design]
    h, w, d = (lo + f * (hi - lo) for (lo, hi), f in zip((s["height"], s["width"], s["depth"]), shares))
    split = d / 2 - s["lid_share"] * d
    edge = ROUND["hard" if hard else "soft"]["edge"]
    return CaseSize(h, w, d, split, z0, corner, edge, SHEET[finish], hard)


# -- shells ---------------------------------------------------------------------------------------------------
def _rounded_rect(w: float, h: float, r: float, per_corner: int = 8) -> np.ndarray:
    """(n, 2) points (y, z) of a ``w`` x ``h`` rectangle with corners of radius ``r``, counter-clockwise."""
    r = min(r, 0.49 * min(w, h))
    pts = []
    for (cy, cz), a0 in (((w / 2 - r, h / 2 - r), 0.0), ((-w / 2 + r, h / 2 - r), 0.5 * math.pi),
                         ((-w / 2 + r, -h / 2 + r), math.pi), ((w / 2 - r, -h / 2 + r), 1.5 * math.pi)):
        for a in np.linspace(a0, a0 + 0.5 * math.pi, per_corner):
            pts.append((cy + r * math.cos(a), cz + r * math.sin(a)))
    return np.array(pts)


def _tray_points(w: float, h: float, d: float, r: float, e: float, x0: float = 0.0) -> np.ndarray:
    """The outer points of a tray ``w`` x ``h`` in y, z from ``x0`` to ``d`` along x whose face at ``d`` has its
    edges rounded ``e``."""
    rings = [(x0, 0.0)] + [(d - e + e * math.sin(a), e * (1 - math.cos(a))) for a in np.linspace(0, 0.5 * math.pi, 6)]
    out = []
    for x, inset in rings:
        yz = _rounded_rect(w - 2 * inset, h - 2 * inset, max(r - inset, 0.3 * r))
        out.append(np.column_stack([np.full(len(yz), x), yz]))
    return np.vstack(out)


def _hull_mesh(points: np.ndarray) -> trimesh.Trimesh:
    v, f = g.hull_arrays(points)
    return trimesh.Trimesh(v, f, process=False)


def _tray_collision(w: float, h: float, d: float, r: float, e: float, top_to: float) -> list[np.ndarray]:
    """Convex pieces of a tray (:func:`_tray_points`): the flat face, four walls, four corners; the top wall
    only up to ``top_to`` along x (a handle's tubes pass behind it)."""
    t = WALL
    face = _rounded_rect(w - 2 * e, h - 2 * e, max(r - e, 0.3 * r))
    pieces = [np.vstack([np.column_stack([np.full(len(face), x), face]) for x in (d - t, d)])]
    x1 = d - e
    for sy in (-1, 1):
        y0, y1 = sorted((sy * (w / 2 - t), sy * w / 2))
        pieces.append(g.box_between((0, y0, -h / 2 + r), (x1, y1, h / 2 - r), "x").vertices)
    pieces.append(g.box_between((0, -w / 2 + r, -h / 2), (x1, w / 2 - r, -h / 2 + t), "x").vertices)
    pieces.append(g.box_between((0, -w / 2 + r, h / 2 - t), (min(x1, top_to), w / 2 - r, h / 2), "x").vertices)
    for cy, cz, a0 in ((w / 2 - r, h / 2 - r, 0.0), (-w / 2 + r, h / 2 - r, 0.5 * math.pi),
                       (-w / 2 + r, -h / 2 + r, math.pi), (w / 2 - r, -h / 2 + r, 1.5 * math.pi)):
        for k in range(3):  # three 30-degree segments: their hulls stay within 1.5 mm of the wall's inside
            a = np.linspace(a0 + k * math.pi / 6, a0 + (k + 1) * math.pi / 6, 3)
            arc = [(cy + rr * math.cos(b), cz + rr * math.sin(b)) for rr in (r, r - t) for b in a]
            pieces.append(np.array([(x, y, z) for x in (0.0, x1) for y, z in arc]))
    return pieces


def _tray(w: float, h: float, d: float, r: float, e: float, material: str, sheet: float, place: Frame,
          top_to: float = math.inf) -> g.Piece:
    """A hollow shell open at its local x = 0, its face at x = ``d``, placed by ``place``."""
    t = WALL
    outer = _hull_mesh(_tray_points(w, h, d, r, e))
    inner = _hull_mesh(_tray_points(w - 2 * t, h - 2 * t, d - t, r - t, max(e - t, 0.004), x0=-0.01))
    mesh = g.subtract(outer, [inner])
    m = place.matrix
    piece = g.Piece(mesh.vertices, mesh.faces, material, _tray_collision(w, h, d, r, e, top_to), sheet=sheet)
    return piece.transformed(m)


def _split_band(s: CaseSize, material: str) -> g.Piece:
    """The zip band round the body's rim at the split: 2 mm proud of the shell, decoration."""
    h = s.height - s.z0
    ring_o = _rounded_rect(s.width + 0.004, h + 0.004, s.corner + 0.002)
    ring_i = _rounded_rect(s.width - 2 * WALL, h - 2 * WALL, s.corner - WALL)
    x0, x1 = s.split - 0.009, s.split - 0.001

    def prism(ring, a, b):
        return _hull_mesh(np.vstack([np.column_stack([np.full(len(ring), x), ring[:, 0], ring[:, 1] + s.zc])
                                     for x in (a, b)]))

    band = g.subtract(prism(ring_o, x0, x1), [prism(ring_i, x0 - 0.01, x1 + 0.01)])
    return g.Piece(band.vertices, band.faces, material, [])


def _ribs(s: CaseSize, x_face: float, sign: float, material: str) -> list[g.Piece]:
    """Raised vertical ribs on a grooved hard shell's flat face at ``x_face`` (``sign``: the way it faces)."""
    h = s.height - s.z0 - 2 * s.edge - 0.03
    ys = np.linspace(-1, 1, RIBS) * (s.width / 2 - s.edge - 0.04)
    lo, hi = sorted((x_face - sign * 0.001, x_face + sign * 0.0025))
    return [g.box_between((lo, y - 0.006, s.zc - h / 2), (hi, y + 0.006, s.zc + h / 2), material, bevel=0.0012)
            for y in ys]


def expander_depth(s: CaseSize) -> float:
    """How deep an expansion gusset reaches into the body at rest: :data:`EXPANDER` ``depth``, short of the
    handle's tubes."""
    return min(EXPANDER["depth"], s.split - (s.tube_x + TUBES["outer"] + GAP))


def expander(s: CaseSize, material: str) -> Assembly:
    """An expansion gusset: a ring just inside the body's rim from ``expander_depth`` behind the split up to it,
    which slides out along +x carrying the lid (anchors ``slide``: out along +x; ``hinge``: the lid's, as
    :func:`hinge_frame`)."""
    d = expander_depth(s)
    inset = WALL + GAP
    w, h, r = s.width - 2 * inset, s.height - s.z0 - 2 * inset, s.corner - inset
    ring = _rounded_rect(w, h, r)
    inner = _rounded_rect(w - 2 * WALL, h - 2 * WALL, r - WALL)

    def prism(yz, a, b):
        return _hull_mesh(np.vstack([np.column_stack([np.full(len(yz), x), yz[:, 0], yz[:, 1] + s.zc])
                                     for x in (a, b)]))

    x0, x1 = s.split - d, s.split
    mesh = g.subtract(prism(ring, x0, x1), [prism(inner, x0 - 0.01, x1 + 0.01)])
    convex = [c for c in _tray_collision(w, h, d, r, 0.0, math.inf)[1:]]  # its walls and corners, no face
    place = Frame.at((x0, 0, s.zc))
    convex = [np.asarray([place.point(p) for p in c]) for c in convex]
    piece = g.Piece(mesh.vertices, mesh.faces, material, convex, sheet=s.sheet)
    return Assembly.single("expander", [piece], {"slide": Frame.at((x1, 0, s.zc), z=(1, 0, 0), x=(0, 0, 1)),
                                                 "hinge": hinge_frame(s)})


def hinge_frame(s: CaseSize) -> Frame:
    """The lid's hinge: the split's right edge (seen from the front), z down so a positive turn swings the lid
    out to the right."""
    return Frame.at((s.split + GAP / 2, -s.width / 2 - GAP, s.zc), x=(1, 0, 0), z=(0, 0, -1))


def body_shell(s: CaseSize, material: str, trim: str, lining: str, ribbed: bool) -> list[g.Piece]:
    """The back shell from the split to the back face, its zip band and its lining."""
    h, d = s.height - s.z0, s.split + s.depth / 2
    place = Frame.at((s.split, 0, s.zc), x=(-1, 0, 0), z=(0, 0, 1))
    top_to = s.split - s.tube_x - TUBES["outer"] - GAP  # local x runs from the split to the back
    pieces = [_tray(s.width, h, d, s.corner, s.edge, material, s.sheet, place, top_to), _split_band(s, trim)]
    back = s.tube_x + TUBES["outer"] + 0.002  # the lining panel hides the handle's tubes
    y, z = s.width / 2 - WALL - 0.004, (s.height - s.z0) / 2 - WALL - 0.004
    pieces.append(g.box_between((back, -y, s.zc - z), (back + 0.002, y, s.zc + z), lining).replace(convex=()))
    if ribbed:
        pieces += _ribs(s, -s.depth / 2, -1, material)
    return pieces


def lid(s: CaseSize, material: str, lining: str, ribbed: bool) -> Assembly:
    """The front shell from the split to the front face, lined inside; anchors ``hinge`` (:func:`hinge_frame`),
    ``front`` (the flat face's centre, z out of it) and ``divider`` (:func:`divider_frame`)."""
    h, d = s.height - s.z0, s.depth / 2 - s.split - GAP
    place = Frame.at((s.split + GAP, 0, s.zc))
    pieces = [_tray(s.width, h, d, s.corner, s.edge, material, s.sheet, place)]
    x = s.depth / 2 - WALL - 0.004  # the lining over the face's inside
    y, z = s.width / 2 - s.edge, (s.height - s.z0) / 2 - s.edge
    pieces.append(g.box_between((x - 0.002, -y, s.zc - z), (x, y, s.zc + z), lining).replace(convex=()))
    if ribbed:
        pieces += _ribs(s, s.depth / 2, 1, material)
    front = Frame.at((s.depth / 2, 0, s.zc), z=(1, 0, 0), x=(0, 0, 1))
    return Assembly.single("lid", pieces, {"hinge": hinge_frame(s), "front": front, "divider": divider_frame(s)})


def divider_frame(s: CaseSize) -> Frame:
    """A lid divider's hinge: inside the lid's hinge-side wall at the opening, z up (a positive turn swings it
    out of the lid towards the body, as it opens once the lid is open)."""
    return Frame.at((s.split + GAP + DIVIDER["in"], -s.width / 2 + WALL + GAP, s.zc), x=(0, 1, 0), z=(0, 0, 1))


def divider(s: CaseSize, material: str, trim: str) -> Assembly:
    """A zip-up divider panel across the lid's opening, hinged at its hinge-side edge (anchor ``hinge``)."""
    x0 = s.split + GAP + DIVIDER["in"]
    y0, y1 = -s.width / 2 + WALL + 2 * GAP, s.width / 2 - WALL - GAP
    h = (s.height - s.z0) / 2 - WALL - GAP
    r = max(s.corner - WALL - GAP, 0.01)
    pieces = [g.box_between((x0, y0, s.zc - h + r), (x0 + DIVIDER["t"], y1, s.zc + h - r), material, bevel=0.001),
              g.box_between((x0, y0 + r, s.zc - h), (x0 + DIVIDER["t"], y1 - r, s.zc + h), material, bevel=0.001)]
    pieces = [pc.replace(sheet=DIVIDER["sheet"]) for pc in pieces]
    pieces.append(g.box_between((x0 + DIVIDER["t"], y1 - 0.03, s.zc + 0.02), (x0 + DIVIDER["t"] + 0.004, y1 - 0.012,
                                s.zc + 0.05), trim, name="handle"))
    return Assembly.single("divider", pieces, {"hinge": divider_frame(s)})


# -- what the case stands on ------------------------------------------------------------------------------
def spinner_tips(s: CaseSize, footprint: float) -> list[Frame]:
    """The four casters' swivel frames under the case's corners (x pointing out along the diagonal), inset
    so each caster's sweep (``footprint``) stays under the case and clear of its neighbours'."""
    c = max(HOUSING, footprint) + 0.004
    # two casters along a short side sweep apart: each at least its sweep off the middle
    hx, hy = (max(half - c, footprint + GAP) for half in (s.depth / 2, s.width / 2))
    return [Frame.at((sx * hx, sy * hy, 0.0), x=(sx, sy, 0.0), z=(0, 0, 1)) for sx in (1, -1) for sy in (1, -1)]


def spinner_housings(s: CaseSize, tips: list[Frame], stem_top: float, material: str) -> list[g.Piece]:
    """A moulded housing over each caster's stem, from its stem top up under the shell."""
    out = []
    for tip in tips:
        x, y, _ = tip.origin
        out.append(g.cylinder((x, y, stem_top), (x, y, s.z0 - GAP), HOUSING, material))
    return out


@dataclass(frozen=True)
class Inline:
    """A two-wheeler's inline wheels: ``radius``, ``width``, axle at x ``x`` and y = +-``y``."""

    radius: float
    width: float
    x: float
    y: float


def inline_wheels(s_width: float, depth: float, radius: float) -> Inline:
    w = INLINE["width"]
    return Inline(radius, w, -depth / 2 + 0.6 * radius, s_width / 2 - INLINE["inset"] - w / 2)


def plinth_height(radius: float) -> float:
    """Where a two-wheeler's shell starts: over its wheels' wells."""
    return 2 * radius + GAP + 0.009


def plinth(s: CaseSize, w: Inline, material: str, trim: str) -> list[g.Piece]:
    """A two-wheeler's base under the shell: a moulded bumper (``material``, massed as its sheet) with a well
    for each wheel at the back corners, open to the side and the back so the wheels show (hoods over them), and
    two front feet in ``trim``; it stands ``SKID`` off the ground on the feet and the wheels."""
    hx, hy, top = s.depth / 2, s.width / 2 - 0.002, s.z0 - GAP
    xf = w.x + w.radius + GAP  # the wells' front
    yi = w.y - w.width / 2 - GAP
    well = 2 * w.radius + GAP
    pieces = [g.box_between((xf, -hy, SKID), (hx - 0.004, hy, top), material, bevel=0.012),
              g.box_between((-hx + 0.004, -yi, SKID), (xf + 0.01, yi, top), material, bevel=0.008)]
    for sy in (-1, 1):
        y0, y1 = sorted((sy * yi, sy * hy))
        pieces.append(g.box_between((-hx + 0.004, y0, well), (xf, y1, top), material, bevel=0.002))
    pieces = [pc.replace(sheet=s.sheet) for pc in pieces]
    for sy in (-1, 1):
        y0, y1 = sorted((sy * (hy - 0.07), sy * (hy - 0.02)))
        pieces.append(g.box_between((hx - 0.06, y0, 0.0), (hx - 0.015, y1, SKID + 0.002), trim, bevel=0.002))
    return pieces


def inline_wheel(w: Inline, side: int, tyre: str, hub: str) -> Assembly:
    """One inline wheel on its axle (anchor ``axle``: z along +y); it touches z = 0. Supports ``axle_a`` /
    ``axle_b`` where the axle meets its faces."""
    y, r = side * w.y, w.radius
    a, b = (w.x, y - w.width / 2, r), (w.x, y + w.width / 2, r)
    t = g.cylinder(a, b, r, tyre)
    inner = g.cylinder(a, b, r - WHEEL_INSET, tyre)
    pieces = [g.Piece(t.vertices, t.faces, tyre, [inner.vertices]),
              g.cylinder((w.x, y - w.width / 2 - 0.001, r), (w.x, y + w.width / 2 + 0.001, r), INLINE["hub"] * r,
                         hub).replace(convex=())]
    return Assembly.single("wheel", pieces, {"axle": Frame.at((w.x, y, r), x=(1, 0, 0), z=(0, 1, 0))},
                           {"axle_a": a, "axle_b": b})


# -- the telescopic handle ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class Telescope:
    """The stages: how many, their tube length, each stage's travel, the grip's thickness and height."""

    stages: int
    length: float
    travel: float
    grip: tuple[float, float]

    def radius(self, k: int) -> float:
        """Stage ``k``'s tube radius: the grip stage's is :data:`TUBES` ``inner``, each stage below 2 mm more."""
        return TUBES["inner"] + 0.002 * (self.stages - 1 - k)


def telescope(s: CaseSize, stages: int, grip_share: float) -> Telescope:
    """Tubes from just over the shell's floor to the top; the stages rise so the grip reaches ~1.08 m
    (:data:`TUBES`), each within the tubes' overlap."""
    length = s.top - s.z0 - WALL - 2 * GAP - 0.01 * (stages - 1)
    travel = min(max((1.08 - s.top) / stages, 0.11), 0.24, length - TUBES["overlap"])
    lo, hi = TUBES["grip"]
    return Telescope(stages, length, travel, (lo + grip_share * (hi - lo), 0.03))


def handle_housing(s: CaseSize, material: str) -> list[g.Piece]:
    """The moulded frame on the top where the handle's tubes come out (decoration over the top face)."""
    x, y = s.tube_x, s.tube_y + 0.02
    return [g.box_between((x - 0.02, -y, s.top - 0.004), (x + 0.022, y, s.top + 0.004), material,
                          bevel=0.003).replace(convex=())]


def telescope_anchor(s: CaseSize) -> Frame:
    """The first stage's slide: up from the handle housing."""
    return Frame.at((s.tube_x, 0, s.top + 0.004 + GAP), z=(0, 0, 1), x=(1, 0, 0))


def _grip(s: CaseSize, t: Telescope, x: float, z0: float, material: str) -> g.Piece:
    """The moulded grip across the top of the last stage's tubes, grasped from above."""
    thick, tall = t.grip
    half = s.tube_y + TUBES["outer"] + 0.006
    bar = g.box_between((x - thick / 2, -half, z0), (x + thick / 2, half, z0 + tall), material, bevel=0.008,
                        name="handle")
    at = Frame.at((x, 0, z0 + tall), x=(0, 1, 0), z=(0, 0, 1))
    grasp = Grasp.make((0, 0, 0), (0, 0, -1), (1, 0, 0), thick, min(0.01, tall / 2), "line_fixed_handle",
                       ((0, 0, -tall / 2), (2 * half, thick, tall), np.eye(3)))
    return bar.with_grasps(grasp.moved(at.rotation, at.origin))


def stage(s: CaseSize, t: Telescope, k: int, material: str, grip: str) -> Assembly:
    """Stage ``k`` at rest (0: the outer tubes; the last: the thinnest tubes and the grip); every stage but the
    last is hollow with a collar round its mouth. Anchors ``slide`` (this stage's slide, at the bottom of its
    collar or grip) and ``next`` (the next stage's slide on its collar's top)."""
    o = telescope_anchor(s).origin
    r, last, collar = t.radius(k), k == t.stages - 1, TUBES["collar"]
    z0 = o[2] + k * (2 * collar + GAP)  # this stage's top: its collar, or the grip's foot
    bottom, top = o[2] - t.length + k * 0.01, z0 + (0.004 if last else 2 * collar)
    pieces = []
    for y in (-s.tube_y, s.tube_y):
        if last:
            tube = g.cylinder((o[0], y, bottom), (o[0], y, top), r, material)
        else:  # hollow: the next stage slides in it
            tube = g.shell([(r, bottom), (r, top)], r - t.radius(k + 1) - TUBES["play"], material, center=(o[0], y, 0))
        pieces.append(tube.replace(sheet=TUBE_SHEET))
    if last:
        pieces.append(_grip(s, t, o[0], z0, grip))
    else:
        rc = r + 0.0035  # a moulded collar round the tube's mouth
        pieces += [g.shell([(rc, z0), (rc, z0 + 2 * collar)], rc - t.radius(k + 1) - TUBES["play"], grip,
                           center=(o[0], y, 0)) for y in (-s.tube_y, s.tube_y)]
    nxt = Frame.at((o[0], 0, z0 + 2 * collar + GAP), z=(0, 0, 1), x=(1, 0, 0))
    return Assembly.single("handle", pieces, {"slide": Frame.at((o[0], 0, z0), z=(0, 0, 1), x=(1, 0, 0)),
                                              "next": nxt})


# -- folding carry handles ------------------------------------------------------------------------------------
def top_handle_frame(s: CaseSize) -> Frame:
    """The top carry handle's pivot: along -y in front of the telescopic grip, so a positive turn lifts
    its grip, which lies flat towards the front."""
    # its mounts (20 mm long) stay on the body's top, behind the split
    x = min(s.tube_x + 0.03 + CARRY["boss"], s.split - 0.01 - GAP)
    return Frame.at((x, 0, s.top + CARRY["grip"] + GAP), x=(1, 0, 0), z=(0, -1, 0))


def side_handle_frame(s: CaseSize) -> Frame:
    """The side carry handle's pivot on the body's left side (+y), vertical, its grip lying flat behind it."""
    x = (s.split - s.depth / 2) / 2 + CARRY["reach"] / 2
    return Frame.at((x, s.width / 2 + CARRY["grip"] + GAP, s.zc), x=(-1, 0, 0), z=(0, 0, -1))


def carry_handle(length: float, material: str) -> Assembly:
    """A folding carry handle in its pivot's frame (anchor ``pivot``: z along the pivot line, x the way the grip
    lies, y out of the shell): two arms from the pivot bosses to a round grip parallel to the pivot."""
    g_r, a_r, reach = CARRY["grip"], CARRY["arm"], CARRY["reach"]
    half = length / 2
    pieces = []
    for z in (-half, half):
        pieces.append(g.cylinder((0, 0, z - 0.006), (0, 0, z + 0.006), CARRY["boss"] * 0.8, material))
        pieces.append(g.box_between((0, -a_r, z - 0.006), (reach, a_r, z + 0.006), material, bevel=0.002))
    grip = g.cylinder((reach, 0, -half + 0.006), (reach, 0, half - 0.006), g_r, material, name="handle")
    grasp = Grasp.make((reach, g_r, 0), (0, -1, 0), (1, 0, 0), 2 * g_r, g_r, "line_fixed_handle",
                       ((reach, 0, 0), (2 * g_r, 2 * g_r, length), np.eye(3)))
    pieces.append(grip.with_grasps(grasp))
    return Assembly.single("handle", pieces, {"pivot": Frame.at((0, 0, 0))})


def carry_mounts(at: Frame, length: float, material: str) -> list[g.Piece]:
    """The two moulded mounts a carry handle pivots in, from the shell out to its pivot line (body pieces)."""
    out = []
    for z in (-length / 2 - 0.009, length / 2 + 0.009):
        lo, hi = at.point((-0.01, -CARRY["grip"] - GAP, z - 0.003)), at.point((0.01, 0.004, z + 0.003))
        out.append(g.box_between(np.minimum(lo, hi), np.maximum(lo, hi), material, bevel=0.002))
    return out


# -- front pocket and lock ---------------------------------------------------------------------------------
def pocket_frame(s: CaseSize) -> Frame:
    """The front pocket's hinge: the right edge of the lid's face, z down (it swings out to the right)."""
    pw = POCKET["share"][0] * (s.width - 2 * s.edge)
    return Frame.at((s.depth / 2 + GAP / 2, -pw / 2 - GAP, s.zc), x=(1, 0, 0), z=(0, 0, -1))


def pocket(s: CaseSize, material: str, trim: str) -> Assembly:
    """A front pocket panel over the lid's face with a zip round three sides (anchor ``hinge``)."""
    pw = POCKET["share"][0] * (s.width - 2 * s.edge)
    ph = POCKET["share"][1] * (s.height - s.z0 - 2 * s.edge)
    x0, d, z = s.depth / 2 + GAP, POCKET["depth"], s.zc
    pieces = [g.box_between((x0, -pw / 2, z - ph / 2), (x0 + d, pw / 2, z + ph / 2), material,
                            bevel=0.009).replace(sheet=s.sheet)]
    zp = POCKET["zip"]
    pieces.append(g.box_between((x0 + d - 0.01, -pw / 2 + 0.012, z + ph / 2 - 0.002), (x0 + d - 0.004,
                                pw / 2 - 0.012, z + ph / 2 + zp - 0.002), trim).replace(convex=()))
    return Assembly.single("pocket", pieces, {"hinge": pocket_frame(s)})


def lock_frames(s: CaseSize) -> tuple[Frame, list[Frame]]:
    """The lock housing's centre on the left side (+y) by the split, near the top, and its three thumbwheels'
    axles (z along +x)."""
    hl, hw, ht = LOCK["housing"]
    c = Frame.at((s.split - hl / 2 - 0.015, s.width / 2, s.top - s.corner - 0.05), z=(0, 1, 0), x=(1, 0, 0))
    y = s.width / 2 + LOCK["wheel"] + GAP + 0.001  # proud of the shell, between the housing's cheeks
    ox, _, oz = c.origin
    wheels = [Frame.at((ox + (k - 1) * LOCK["pitch"], y, oz), z=(1, 0, 0), x=(0, 1, 0)) for k in range(3)]
    return c, wheels


def lock_housing(s: CaseSize, material: str) -> list[g.Piece]:
    """The lock's housing on the side, open round its thumbwheels (body pieces)."""
    c, _ = lock_frames(s)
    hl, hw, ht = LOCK["housing"]
    ox, oy, oz = c.origin
    gap = 3 * LOCK["pitch"] / 2 + GAP
    pieces = [g.box_between((ox - hl / 2, oy, oz - hw / 2), (ox - gap, oy + ht, oz + hw / 2), material, bevel=0.002),
              g.box_between((ox + gap, oy, oz - hw / 2), (ox + hl / 2, oy + ht, oz + hw / 2), material, bevel=0.002)]
    return pieces


def thumbwheel(at: Frame, material: str) -> Assembly:
    """One numbered thumbwheel on its axle (anchor ``axle``)."""
    r, t = LOCK["wheel"], LOCK["thick"]
    piece = g.cylinder(at.point((0, 0, -t / 2)), at.point((0, 0, t / 2)), r, material, 12)
    return Assembly.single("knob", [piece], {"axle": at})
