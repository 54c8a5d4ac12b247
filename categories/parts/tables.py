"""Table parts: tops (square, round, oval, split halves), aprons, legs, shelves, sleeves, pedestals.

Local frames: a table stands on z = 0 centred on the z axis; a leg stands on the
origin and rises along +z. Sizes of real tables: coffee tables 0.40-0.75 m high,
0.5-1.0 m across; dining tables 0.70-0.80 m high, 0.9-1.2 m wide, 1.4-2.8 m long,
18-25 mm apron boards, 25-45 mm tops (furniture retailers' catalogues, BS EN 12521).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame, polar

BOARD = 0.018  # apron and shelf board
WALL = 0.003  # metal tube wall
CLEAR = 0.004  # radial clearance of posts and columns in their tubes
FOOT = 0.012  # rubber foot cap height


def _hull(points, material: str) -> g.Piece:
    v, f = g.hull_arrays(np.asarray(points, float))
    return g.Piece(v, f, material, [v])


# -- tops ---------------------------------------------------------------------------------------------
def outline(length: float, width: float, shape: str, n: int = 96) -> np.ndarray:
    """``(k, 2)`` outline of a top, counter-clockwise: rectangular/square, or round/oval (an ellipse)."""
    if shape in ("round", "oval"):
        th = np.linspace(0, 2 * math.pi, n, endpoint=False)
        return np.c_[length / 2 * np.cos(th), width / 2 * np.sin(th)]
    return np.array([[length / 2, width / 2], [-length / 2, width / 2], [-length / 2, -width / 2],
                     [length / 2, -width / 2]])


def slab(xy: np.ndarray, z0: float, z1: float, bevel: float, material: str) -> g.Piece:
    """A convex slab over a convex outline, its top and bottom edges bevelled toward the centre."""
    bevel = min(bevel, 0.45 * (z1 - z0))
    c = xy.mean(0)
    pts = []
    for z, shrink in ((z0, bevel), (z0 + bevel, 0.0), (z1 - bevel, 0.0), (z1, bevel)):
        d = xy - c
        scale = 1.0 - shrink / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-9)
        pts.append(np.c_[c + d * scale, np.full(len(xy), z)])
    return _hull(np.vstack(pts), material)


def top(length: float, width: float, shape: str, z0: float, z1: float, bevel: float, material: str) -> g.Piece:
    """A whole top from ``z0`` to ``z1``."""
    return slab(outline(length, width, shape, 72 if shape == "round" else 96), z0, z1, bevel, material)


def half_top(length: float, width: float, shape: str, z0: float, z1: float, split: float, side: int,
             material: str) -> g.Piece:
    """One half of a top split across x at ``+-split / 2``, on the ``side`` (+1 or -1) of x = 0."""
    xy = outline(length, width, shape, 192)
    xs = split / 2
    keep = xy[side * xy[:, 0] > xs + 1e-4]
    yc = width / 2 * math.sqrt(max(0.0, 1 - (2 * xs / length) ** 2)) if shape == "oval" else width / 2
    return slab(np.vstack([keep, [[side * xs, yc], [side * xs, -yc]]]), z0, z1, 0.15 * (z1 - z0), material)


# -- legs ------------------------------------------------------------------------------------------------
LEG_STYLES = {
    # coffee table: a turned leg with a narrow foot swelling to a square block; a slim taper
    "coffee": dict(base=0.55, rise=0.25, swell=0.22, a=1.4, b=0.0, cap=1.0, block=0.12, max_block=0.08,
                   shoulder=0.7, n=14, taper=0.6, bevel=0.002),
    # dining table: a fuller swelling under a longer block that meets the apron
    "dining": dict(base=0.5, rise=0.2, swell=0.28, a=1.6, b=-0.2, cap=0.95, block=0.2, max_block=1.0,
                   shoulder=0.0, n=20, taper=0.55, bevel=0.003),
}
"""Leg proportions per kind of table. A turned profile's radius is
``r * (base + rise t + swell sin^2(pi clip(a t + b, 0, 1)))``, capped at ``cap * r``, ``t`` from
foot (0) to the block (1); ``taper``: the foot of a tapered leg as a fraction of its top."""


def leg(style: str, radius: float, height: float, material: str, kind: str = "coffee") -> list[g.Piece]:
    """A leg standing on the origin, ``radius`` (half its side) at the top: square, tapered or turned."""
    r, k = radius, LEG_STYLES[kind]
    if style == "square":
        return [g.box_between([-r, -r, 0], [r, r, height], material, bevel=k["bevel"])]
    if style == "tapered":
        rb = k["taper"] * r
        return [_hull([[sx * rr, sy * rr, z] for rr, z in ((rb, 0.0), (r, height)) for sx in (-1, 1)
                       for sy in (-1, 1)], material)]
    block = min(k["block"] * height, k["max_block"])
    zz = np.linspace(0.0, height - block, k["n"])
    t = zz / (height - block)
    rad = r * (k["base"] + k["rise"] * t + k["swell"] * np.sin(math.pi * np.clip(k["a"] * t + k["b"], 0, 1)) ** 2)
    prof = [(0.0, 0.0), *zip(np.minimum(rad, k["cap"] * r), zz)]
    if k["shoulder"]:
        prof.append((k["shoulder"] * r, height - block))
    prof.append((0.0, height - block))
    return [g.revolve(prof, material, sections=48),
            g.box_between([-r, -r, height - block - 0.001], [r, r, height], material)]


HAIRPIN_ROD = 0.0048
"""m, radius of a hairpin leg's rod: 3/8 in (10 mm) is the standard rod, 1/2 in the heavy-duty one
(semiexact.com/products/hairpin-leg-sold-separately-2-rod-design-clear-coat; engineerfix.com: 3/8 in for
coffee and end tables, 1/2 in or three rods for dining tables); 16 in legs for coffee tables, 28 in for
dining tables (tablelegs.com/blog/hairpin-leg-table-diy-tips)."""

HAIRPIN_PLATE = 0.004
"""m, the steel mounting plate a hairpin leg is welded to and screwed under the top by."""

GLIDE = (0.012, 0.9)
"""A tube leg's glide: its height (m) and its radius as a share of the tube's (push-in nylon glides of round
furniture tubes, 25-32 mm tubes on 10-15 mm tall glides)."""


HAIRPIN_SPREAD = 0.045
"""m, at least this far out along the plate's diagonal each rod meets the plate (a 4 in plate's corners:
the rods stand 9 cm apart at the top whatever the leg's nominal radius)."""


def hairpin_leg(radius: float, height: float, material: str, rod: float = HAIRPIN_ROD) -> list[g.Piece]:
    """A two-rod hairpin leg standing on the origin: one bent rod from the corners of a steel plate under the
    top (``2 radius`` square, or wider to reach :data:`HAIRPIN_SPREAD`) down to a U bend on the floor, in the
    plate's diagonal plane."""
    zt = height - HAIRPIN_PLATE
    s_top = max(math.sqrt(2) * (radius - rod), HAIRPIN_SPREAD)
    bend = min(0.018, 0.8 * s_top)
    zc = rod + bend
    arc = [(bend * math.cos(a), zc - bend * math.sin(a)) for a in np.linspace(0.0, math.pi, 9)]
    path2 = [(s_top, zt)] + arc + [(-s_top, zt)]
    path = [(s / math.sqrt(2), s / math.sqrt(2), z) for s, z in path2]
    half = max(radius, s_top / math.sqrt(2) + rod)
    bent = g.tube(path, rod, material, 10)
    bent = bent.translated((0, 0, -float(bent.vertices[:, 2].min())))  # the bend's mitred rings dip ~0.1 mm
    return [g.box_between([-half, -half, zt], [half, half, height], material), bent]


def tube_leg(radius: float, height: float, material: str, foot: str) -> list[g.Piece]:
    """A round steel tube leg (``radius``) on a push-in glide (:data:`GLIDE`) in ``foot``."""
    gh, share = GLIDE
    return [g.cylinder((0, 0, gh), (0, 0, height), radius, material, 24),
            g.cylinder((0, 0, 0), (0, 0, gh + 0.002), share * radius, foot, 24)]


def leg_part(style: str, radius: float, height: float, material: str, kind: str = "coffee",
             foot: str | None = None) -> Assembly:
    """A leg of any style (:func:`leg`'s, ``"hairpin"``: :func:`hairpin_leg`, ``"tube"``: :func:`tube_leg` on a
    glide in ``foot``) as a part a library may replace: anchor ``foot`` (the origin); supports ``foot`` on
    the floor and ``top`` under what it carries."""
    if style == "hairpin":
        pieces = hairpin_leg(radius, height, material)
    elif style == "tube":
        pieces = tube_leg(radius, height, material, foot or material)
    else:
        pieces = leg(style, radius, height, material, kind)
    return Assembly.single("leg", pieces, {"foot": IDENTITY}, {"foot": (0.0, 0.0, 0.0), "top": (0.0, 0.0, height)})


def leg_frames(width: float, shape: str, inset: float, count: int) -> list[Frame]:
    """Where legs stand under a top ``width`` across: 4 at the corners of a square, or ``count``
    evenly around a round top (a 4-legged round table has them at 45 degrees)."""
    if shape == "round":
        return polar(Frame.at(), count, width / 2 - inset, math.pi / 4 if count == 4 else 0.0)
    a = width / 2 - inset
    return [Frame.at((sx * a, sy * a, 0)) for sx in (-1, 1) for sy in (-1, 1)]


def corner_frames(length: float, width: float, inset: float) -> list[Frame]:
    """Four corners of a ``length`` x ``width`` rectangle, ``inset`` in from each side."""
    return [Frame.at((sx * (length / 2 - inset), sy * (width / 2 - inset), 0)) for sx in (1, -1) for sy in (1, -1)]


# -- aprons, shelves, bottoms --------------------------------------------------------------------------------
def apron(width: float, shape: str, inset: float, leg_r: float, z0: float, z1: float, material: str
          ) -> list[g.Piece]:
    """A frame of boards (square) or a ring (round) running through the leg tops."""
    if shape == "round":
        r = width / 2 - inset
        return [g.shell([(r + BOARD / 2, z0), (r + BOARD / 2, z1)], BOARD, material, sections=64)]
    a = width / 2 - inset + leg_r  # flush with the legs' outside
    return [g.box_between([-a, -a, z0], [a, -a + BOARD, z1], material),
            g.box_between([-a, a - BOARD, z0], [a, a, z1], material),
            g.box_between([-a, -a + BOARD, z0], [-a + BOARD, a - BOARD, z1], material),
            g.box_between([a - BOARD, -a + BOARD, z0], [a, a - BOARD, z1], material)]


def apron_rails(length: float, width: float, leg_w: float, z0: float, z1: float, board: float, material: str,
                holes: dict[int, list] | None = None) -> list[g.Piece]:
    """A rectangular apron of four boards between corner legs ``leg_w`` wide: long sides (y = +-width/2,
    each with the drawer openings ``holes[+1 | -1]``, rectangles (x0, z0, x1, z1)) and short ends."""
    holes = holes or {}
    xb = length / 2 - leg_w  # the long boards run between the legs
    ye = width / 2 - max(leg_w, board)  # the end boards run between the long ones
    out = []
    for s in (1, -1):
        y0, y1 = sorted((s * width / 2, s * (width / 2 - board)))
        out.append(g.panel([-xb, y0, z0], [xb, y1, z1], material, "y", holes=holes.get(s, [])))
        x0, x1 = sorted((s * length / 2, s * (length / 2 - board)))
        out.append(g.box_between([x0, -ye, z0], [x1, ye, z1], material))
    return out


def apron_bottom(width: float, shape: str, inset: float, leg_r: float, z0: float, material: str) -> g.Piece:
    """The floor of a lift-top's storage box, at the bottom of the apron."""
    t = 0.012
    if shape == "round":
        return g.disc([0, 0, z0 + t / 2], width / 2 - inset, t, material, 64)
    a = width / 2 - inset + leg_r - BOARD
    return g.box_between([-a, -a, z0], [a, a, z0 + t], material)


def shelf(width: float, shape: str, inset: float, leg_r: float, z: float, material: str) -> g.Piece:
    """A lower shelf between the legs, touching them from inside."""
    if shape == "round":
        return g.disc([0, 0, z], width / 2 - inset - leg_r, BOARD, material, 64)
    a = width / 2 - inset - leg_r
    return g.box_between([-a, -a, z - BOARD / 2], [a, a, z + BOARD / 2], material)


def stretchers(frames: list[Frame], z: float, end_r: float, material: str, square: bool) -> list[g.Piece]:
    """Low round rods between neighbouring legs (``square``: around the four corners), ending in them."""
    c = [f.origin[:2] for f in frames]
    pairs = list(zip(c, c[1:] + c[:1])) if not square else [(c[0], c[1]), (c[2], c[3]), (c[0], c[2]), (c[1], c[3])]
    out = []
    for c0, c1 in pairs:
        a0, a1 = np.array([*c0, z]), np.array([*c1, z])
        d = (a1 - a0) / np.linalg.norm(a1 - a0)
        out.append(g.cylinder(a0 + d * (end_r - 0.0015), a1 - d * (end_r - 0.0015), 0.008, material, 16))
    return out


# -- telescopic supports -----------------------------------------------------------------------------------
def round_sleeve(outer_r: float, top: float, material: str, foot: str) -> list[g.Piece]:
    """A round metal sleeve standing on a rubber foot cap (hollow: a post slides in it)."""
    return [g.shell([(outer_r, FOOT), (outer_r, top)], WALL, material, sections=48, convex_sectors=24),
            g.cylinder([0, 0, 0.0], [0, 0, FOOT], outer_r + 0.003, foot, 32)]


def square_sleeve(width: float, z0: float, z1: float, wall: float, material: str) -> list[g.Piece]:
    """A square tube of four walls (hollow for an inner leg) with a cap at the top."""
    r, t = width / 2, wall
    return [g.box_between([-r, -r, z0], [r, -r + t, z1], material),
            g.box_between([-r, r - t, z0], [r, r, z1], material),
            g.box_between([-r, -r + t, z0], [-r + t, r - t, z1], material),
            g.box_between([r - t, -r + t, z0], [r, r - t, z1], material),
            g.box_between([-r, -r, z1 - 0.01], [r, r, z1], material)]


def inner_leg(width: float, top: float, material: str, foot: str) -> list[g.Piece]:
    """A square inner leg on a rubber foot, standing on the origin."""
    w = width / 2
    return [g.box_between([-w, -w, FOOT], [w, w, top], material, bevel=0.002),
            g.box_between([-w - 0.002, -w - 0.002, 0.0], [w + 0.002, w + 0.002, FOOT], foot)]


def pedestal_base(radius: float, tube_r: float, material: str) -> tuple[list[g.Piece], float]:
    """A low domed base disc under a column tube; returns pieces and the base top."""
    zb = 0.03
    prof = [(0.0, 0.0), (radius, 0.0), (radius, 0.008), (0.85 * radius, 0.016), (0.45 * radius, zb - 0.004),
            (tube_r + 0.01, zb), (0.0, zb)]
    return [g.revolve(prof, material, sections=64)], zb


def column_tube(outer_r: float, z0: float, z1: float, material: str) -> list[g.Piece]:
    """A hollow column tube with a collar at its top."""
    return [g.shell([(outer_r, z0), (outer_r, z1)], WALL, material, sections=64, convex_sectors=24),
            g.shell([(outer_r + 0.006, z1 - 0.015), (outer_r + 0.006, z1)], 0.006, material, sections=64,
                    convex_sectors=24)]


def column_and_plate(radius: float, z0: float, z_under: float, plate_r: float, material: str) -> list[g.Piece]:
    """A column from ``z0`` up to a 12 mm mounting plate (``plate_r``) under a top at ``z_under``."""
    return [g.cylinder([0, 0, z0], [0, 0, z_under - 0.012], radius, material, 48),
            g.cylinder([0, 0, z_under - 0.012], [0, 0, z_under], plate_r, material, 48)]


# -- dining-table pedestals --------------------------------------------------------------------------------
TRESTLE_LENGTH = 1.9  # tables longer than this stand on two columns (trestle style)


def pedestal_glide_count(p: dict, rng) -> int:
    """levelling glides under the pedestal: three under a round foot (three points never rock), four under
    two trestle feet"""
    return 3 if p["length"] <= TRESTLE_LENGTH else 4


def pedestal_glides(table_length: float, apron_length: float, table_width: float) -> list[Frame]:
    """Where levelling glides go under :func:`pedestals`' feet (z up, at the floor): three around a round
    foot, two at the ends of each trestle foot."""
    if table_length <= TRESTLE_LENGTH:
        rf = 0.32 * table_width * 0.8
        return [Frame.at((rf * math.cos(a), rf * math.sin(a), 0.0)) for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3)]
    ye = 0.36 * table_width - 0.04
    return [Frame.at((x, y, 0.0)) for x in (-0.27 * apron_length, 0.27 * apron_length) for y in (ye, -ye)]


def pedestals(table_length: float, apron_length: float, apron_width: float, table_width: float, column_r: float,
              z_top: float, material: str) -> list[g.Piece]:
    """One turned column (two on a long table) on a foot, under cross beams ending at ``z_top``."""
    La, Wa = apron_length, apron_width
    zb0 = z_top - 0.04
    xs = [0.0] if table_length <= TRESTLE_LENGTH else [-0.27 * La, 0.27 * La]
    pieces = [g.box_between([-La / 2, -0.035, zb0], [La / 2, 0.035, z_top], material)]
    for x in xs:
        pieces.append(g.box_between([x - 0.035, -Wa / 2, zb0], [x + 0.035, Wa / 2, z_top], material))
        zz = np.linspace(0.06, zb0, 16)
        t = (zz - zz[0]) / (zz[-1] - zz[0])
        rad = column_r * (1.0 - 0.25 * np.sin(math.pi * t) + 0.35 * (1 - t) ** 4)
        pieces.append(g.revolve([(0.0, 0.06), *zip(rad, zz), (0.0, zb0)], material, center=(x, 0, 0), sections=48))
        if len(xs) == 1:  # a round domed foot
            rf = 0.32 * table_width
            pieces.append(g.revolve([(0.0, 0.0), (rf, 0.0), (rf, 0.02), (0.7 * rf, 0.045), (1.3 * column_r, 0.065),
                                     (0.0, 0.065)], material, center=(x, 0, 0), sections=64))
        else:  # a trestle foot across
            pieces.append(g.box_between([x - 0.05, -0.36 * table_width, 0.0], [x + 0.05, 0.36 * table_width, 0.065],
                                        material, bevel=0.01))
    if len(xs) == 2:  # a low stretcher between the two columns
        pieces.append(g.box_between([xs[0], -0.025, 0.18], [xs[1], 0.025, 0.23], material))
    return pieces


# -- a dining table's frame ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class DiningFrame:
    """Where a dining table's apron and top stand (the table's frame, metres), from its parameters and
    :data:`~.furniture_sizes.DINING`: the apron ``La`` x ``Wa`` from ``za0`` up to ``za1`` (the top's underside,
    or the halves' / draw leaves' seat), legs ``lw`` wide (0 on a pedestal), a drop-leaf table's fixed centre
    ``wc`` wide, the stored extension leaves' stack ``leaf`` (bottom, top), ``x_in`` free between the legs
    along X (half), ``span`` free along the drawer board (half) and ``z_top`` the drawer openings' top."""

    La: float
    Wa: float
    wc: float
    lw: float
    za0: float
    za1: float
    leaf: tuple[float, float]
    x_in: float
    span: float
    z_top: float

    @classmethod
    def of(cls, p: dict, sizes: dict, stored_leaves: int | None, drop: bool, draw: bool, drawers: bool
           ) -> DiningFrame:
        """``stored_leaves``: an extending top's leaf count (None: it does not extend); ``drop``, ``draw``: a
        drop-leaf or draw-leaf top; ``drawers``: the apron has drawers (it is raised to fit them)."""
        D, ext = sizes, stored_leaves is not None
        L, W, H, tt = p["length"], p["width"], p["height"], p["top_thickness"]
        if p["top_shape"] == "oval":
            La, Wa = D["oval_apron"] * L, D["oval_apron"] * W
        else:
            La, Wa = L - 2 * p["end_overhang"], W - 2 * p["side_overhang"]
        wc = W * (1 - 2 * p["leaf_fraction"])
        if drop:  # the apron and the folded lopers stay inside the hanging leaves
            Wa = min(Wa, wc - 2 * (D["leaf_gap_y"] + D["loper_room"]))
        lw = p["leg_width"] if p["support"] == "legs" else 0.0
        za1 = H - tt - (D["seat"] if ext else 0.0) - (2 * D["leaf_gap"] + D["leaf_t"] if draw else 0.0)
        leaf = (za1 - (stored_leaves or 0) * (D["leaf_gap"] + D["leaf_t"]), za1 - D["leaf_gap"])
        need = (2 * D["margin"] + D["drawer_min"] + (za1 - leaf[0] + D["leaf_room"] if ext else 0.0) if drawers
                else D["drawer_min"])
        za0 = za1 - max(p["apron_height"], need)
        x_in = La / 2 - max(lw, D["board"])
        span = Wa / 2 - max(lw, D["board"]) if p["drawer_sides"] == "ends" else x_in
        z_top = (leaf[0] - D["leaf_room"]) if ext else za1 - D["margin"]
        return cls(La, Wa, wc, lw, za0, za1, leaf, x_in, span, z_top)

    def loper_length(self, width: float, sizes: dict) -> float:
        """A drop-leaf table's swing-out bracket: at most ``sizes["loper"]`` and ``sizes["loper_apron"]`` of the
        apron long, and swung out it ends ``sizes["loper_reach"]`` of the way out under a leaf of a top
        ``width`` wide."""
        reach = self.wc / 2 + sizes["loper_reach"] * (width - self.wc) / 2
        return min(sizes["loper"], sizes["loper_apron"] * self.La, reach - self.Wa / 2)


@dataclass(frozen=True)
class StorageFrame:
    """A storage coffee table's box (the table's frame, metres), from its parameters and
    :data:`~.furniture_sizes.COCKTAIL`: square legs ``lw`` wide (a little stouter than the rails) ``inset`` in
    (further in under drop leaves: the folded lopers lie inside them), the box ``2 half`` square from ``za0`` up
    to the top's underside ``za1``, ``span`` of drawer board between the legs, drawers ``depth`` deep."""

    lw: float
    inset: float
    half: float
    za0: float
    za1: float
    span: float
    depth: float

    @classmethod
    def of(cls, p: dict, sizes: dict, leaves: bool, back_to_back: bool) -> StorageFrame:
        C = sizes
        lw = 2 * p["leg_radius"] + C["square_leg"]
        inset = min(p["leg_inset"], C["inset_max"] * p["width"])
        if leaves:
            inset = max(inset, lw / 2 + C["loper_room"])
        half = p["width"] / 2 - inset + lw / 2
        za1 = p["height"] - p["top_thickness"]
        both, one = C["drawer_reach"]
        depth = min(C["drawer_depth"], (2 * half - 2 * BOARD) * (both if back_to_back else one))
        return cls(lw, inset, half, za1 - p["box_depth"], za1, 2 * (half - lw), depth)

    def corners(self) -> list[Frame]:
        """Where the four legs stand (at the box's corners)."""
        return corner_frames(2 * self.half, 2 * self.half, self.lw / 2)

    def shelf(self, p: dict, z_leg: float, sizes: dict) -> dict:
        """A low shelf between the legs (standing from ``z_leg``): its inset, leg radius and height (between
        ``sizes["shelf_low"]`` under the apron and over the caster plates), as :func:`shelf` takes them."""
        under, over = sizes["shelf_low"]
        return {"inset": self.inset - self.lw / 2 + BOARD, "r_leg": self.lw / 2,
                "z": max(min(p["shelf_height"] * p["height"], self.za0 - under), z_leg + over)}


@dataclass(frozen=True)
class LegFrame:
    """A coffee table on legs (the table's frame, metres), from its parameters and
    :data:`~.furniture_sizes.COCKTAIL`: legs ``inset`` in, the apron from ``za0`` to ``za1`` (a lift-top's well
    is ``box_depth`` deep, its top resting ``seat`` above the rim), a lower shelf at ``shelf_z``; a telescopic
    stand's posts (``post_r``) slide ``travel`` in sleeves (``sleeve_r``) up to ``sleeve_top``, a post's foot at
    ``post_bottom`` at rest."""

    inset: float
    za0: float
    za1: float
    shelf_z: float
    post_r: float
    sleeve_r: float
    sleeve_top: float
    travel: float
    post_bottom: float

    @classmethod
    def of(cls, p: dict, sizes: dict, lift: bool) -> LegFrame:
        C, H = sizes, p["height"]
        inset = min(p["leg_inset"], C["inset_max"] * p["width"])
        za1 = H - p["top_thickness"] - (C["seat"] if lift else 0.0)
        za0 = za1 - (p["box_depth"] if lift else p["apron_height"])
        rp = C["post"] * p["leg_radius"]
        ro = rp + CLEAR + WALL
        zs1 = C["sleeve_top"] * za0
        travel = min(p["stand_travel"], zs1 - C["sleeve_room"])
        shelf = min(p["shelf_height"] * H, za0 - C["shelf_under_well"] if lift else zs1 - C["shelf_under"])
        return cls(inset, za0, za1, shelf, rp, ro, zs1, travel, zs1 - travel - C["post_in"])
