"""Table mechanisms: lift-top struts, drawer aprons, nesting tables, drop leaves and gate legs.

Local frames as in :mod:`tables`: a table stands on z = 0 centred on the z axis. Sizes of real
products: lift-top coffee tables have a 13-20 cm deep storage well and rise 15-25 cm on two
spring-assisted lift mechanisms (IKEA Hemnes / Wayfair lift-top ranges); nests of tables have
slim legs (18-30 mm) and each table sits 1-2 cm under the next (IKEA Vittsjö, West Elm
nesting tables); drop-leaf tables have leaves of 20-30 cm on rule-joint hinges carried by gate
legs or swing-out brackets (Gateleg and Pembroke tables, IKEA Norden / Gamlared).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import hardware, panels
from . import tables as T

SLEEVE_R, INNER_R, ROD_R = 0.016, 0.0125, 0.0075  # lift strut stages (outer radius of each)
TUBE_WALL = 0.002
STRUT_OVERLAP = 0.022  # each stage stays this far inside the one below it at full lift


def _tube(frame: Frame, z0: float, z1: float, r: float, material: str, hollow: bool = True) -> g.Piece:
    """A round tube (or rod) along ``frame.z`` from ``z0`` to ``z1`` (local)."""
    if hollow:
        pc = g.shell([(r, z0), (r, z1)], TUBE_WALL, material, sections=24)
    else:
        pc = g.cylinder([0, 0, z0], [0, 0, z1], r, material, 16)
    return pc.transformed(frame.matrix)


def lift_struts(ys: tuple[float, ...], x: float, z_floor: float, z_under: float, axis: np.ndarray,
                travel: float, material: str) -> tuple[list, list, list, float, float]:
    """Two-stage telescopic lift struts (one per ``y``) standing on the storage floor at ``z_floor``
    and carrying a top whose underside is at ``z_under``, along ``axis`` (up, maybe tilted forward).

    Returns the sleeves (fixed to the body), the middle stage (inner tubes and a cross bar: a link of
    its own), the rods and mounting plates (fixed under the top), and the travel of each stage
    (``travel`` split in two, capped so every stage keeps ``STRUT_OVERLAP`` in the one below).
    """
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    length = (z_under - z_floor) / u[2]  # along the axis
    hs = 0.62 * length  # sleeve length
    zi0, zi1 = 0.006, length - 0.016  # inner tube along the axis
    zr0 = zi0 + 0.008  # rod bottom at rest
    t1 = min(travel / 2, hs - zi0 - STRUT_OVERLAP)
    t2 = min(travel / 2, zi1 - zr0 - STRUT_OVERLAP)
    sleeves, middle, rods = [], [], []
    frames = [Frame.at((x, y, z_floor), z=u, y=(0, 1, 0)) for y in ys]
    for f in frames:
        sleeves.append(_tube(f, -0.004, hs, SLEEVE_R, material))
        sleeves.append(g.cylinder(f.point((0, 0, -0.004)), f.point((0, 0, 0.0)), SLEEVE_R + 0.012, material, 20))
        middle.append(_tube(f, zi0, zi1, INNER_R, material))
        rods.append(_tube(f, zr0, length + 0.004, ROD_R, material, hollow=False))
        top = f.point((0, 0, length))
        rods.append(g.box_between(top + [-0.04, -0.03, -0.006], top + [0.04, 0.03, 0.0], material))
    # the cross bar joins the inner tubes above the sleeves (a lift frame, as in scissor lift-tops)
    zc = hs + 0.006
    if len(frames) == 2:
        a, b = frames[0].point((0, 0, zc + 0.008)), frames[1].point((0, 0, zc + 0.008))
        y0, y1 = sorted((a[1], b[1]))
        middle.append(g.box_between([a[0] - 0.009, y0 + INNER_R + 0.001, a[2] - 0.008],
                                    [a[0] + 0.009, y1 - INNER_R - 0.001, a[2] + 0.008], material))
    return sleeves, middle, rods, t1, t2


def drawer_apron(half: float, leg_w: float, z0: float, z1: float, board: float, material: str,
                 holes: dict[int, list]) -> list[g.Piece]:
    """A square apron of four boards between corner legs ``leg_w`` wide, ``half`` from the centre to
    the outside; the faces at x = +-half carry drawer openings ``holes[+1 | -1]`` ((y0, z0, y1, z1))."""
    yb = half - leg_w
    out = []
    for s in (1, -1):
        x0, x1 = sorted((s * half, s * (half - board)))
        out.append(g.panel([x0, -yb, z0], [x1, yb, z1], material, "x", holes=holes.get(s, [])))
        y0, y1 = sorted((s * half, s * (half - board)))
        out.append(g.box_between([-half + max(leg_w, board), y0, z0], [half - max(leg_w, board), y1, z1], material))
    return out


def nesting_table(width: float, depth: float, height: float, top_t: float, leg_r: float, x0: float,
                  top_mat: str, leg_mat: str) -> tuple[list[g.Piece], float]:
    """A small table of slim legs at its corners and a bevelled top, ``depth`` along x from ``x0``
    (toward +x), ``width`` along y, standing 2 mm above the floor on glides (so it slides out).
    Returns its pieces and the clear span between its legs along y (what a table nested in it may use)."""
    xc = x0 + depth / 2
    xy = np.array([[depth / 2, width / 2], [-depth / 2, width / 2], [-depth / 2, -width / 2],
                   [depth / 2, -width / 2]]) + [xc, 0]
    pieces = [T.slab(xy, height - top_t, height, 0.2 * top_t, top_mat)]
    ax, ay = depth / 2 - leg_r - 0.008, width / 2 - leg_r - 0.008
    for sx in (-1, 1):
        for sy in (-1, 1):
            c = (xc + sx * ax, sy * ay)
            pieces.append(g.box_between([c[0] - leg_r, c[1] - leg_r, 0.004], [c[0] + leg_r, c[1] + leg_r,
                                                                              height - top_t], leg_mat, bevel=0.002))
            pieces.append(g.box_between([c[0] - leg_r, c[1] - leg_r, 0.002], [c[0] + leg_r, c[1] + leg_r, 0.004],
                                        "foot"))
    # a stretcher under the top along each side: a real nesting table's frame (and what keeps it square)
    for sy in (-1, 1):
        pieces.append(g.box_between([xc - ax + leg_r, sy * ay - 0.006, height - top_t - 0.04],
                                    [xc + ax - leg_r, sy * ay + 0.006, height - top_t], leg_mat))
    return pieces, 2 * (ay - leg_r)


# -- drop leaves ------------------------------------------------------------------------------------------
def clip_outline(xy: np.ndarray, y0: float, y1: float) -> np.ndarray:
    """A convex outline (counter-clockwise ``(k, 2)``) cut to ``y0 <= y <= y1``."""
    out = []
    n = len(xy)
    for i in range(n):
        a, b = xy[i], xy[(i + 1) % n]
        ina = y0 <= a[1] <= y1
        if ina:
            out.append(a)
        for yc in (y0, y1):
            if (a[1] - yc) * (b[1] - yc) < 0:
                t = (yc - a[1]) / (b[1] - a[1])
                out.append(a + t * (b - a))
    pts = np.array(out)
    c = pts.mean(0)
    order = np.argsort(np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0]))
    return pts[order]


def drop_leaf(xy: np.ndarray, side: int, y_hinge: float, z0: float, z1: float, material: str
              ) -> tuple[g.Piece, Frame]:
    """The leaf of a top outline ``xy`` beyond ``|y| = y_hinge`` on ``side``, hanging down at rest
    from its hinge line (along x at the top's underside); returns the piece and the hinge frame (z along
    ``side`` * x: a positive turn raises the leaf to level)."""
    lo, hi = (y_hinge, 10.0) if side > 0 else (-10.0, -y_hinge)
    leaf = T.slab(clip_outline(xy, lo, hi), z0, z1, 0.15 * (z1 - z0), material)
    hinge = Frame.at((0, side * y_hinge, z0), z=(side, 0, 0), y=(0, 0, 1))
    down = hinge.matrix @ Frame.at().turned("z", -math.pi / 2).matrix @ hinge.inverse().matrix
    return leaf.transformed(down), hinge


def loper(x0: float, y_face: float, side: int, z0: float, z1: float, length: float, material: str
          ) -> tuple[list[g.Piece], Frame]:
    """A swing-out bracket (loper) lying along the apron's outer face at ``y_face``, hinged about z at
    ``x0``; a positive turn swings it out under the raised leaf. Returns its pieces (the board and its
    knuckle) and the hinge frame."""
    t = 0.02
    ys = sorted((y_face + side * 0.003, y_face + side * (0.003 + t)))
    piece = g.box_between([x0 + 0.004, ys[0], z0], [x0 + length, ys[1], z1], material, bevel=0.002)
    knuckle = g.cylinder([x0, (ys[0] + ys[1]) / 2, z0], [x0, (ys[0] + ys[1]) / 2, z1], t / 2, material, 16)
    return [piece, knuckle], Frame.at((x0, (ys[0] + ys[1]) / 2, z0), z=(0, 0, side))


def apron_rails_ends(length: float, width: float, leg_w: float, z0: float, z1: float, board: float,
                     material: str, holes: dict[int, list]) -> list[g.Piece]:
    """A rectangular apron like :func:`tables.apron_rails` whose end boards (x = +-length/2) carry the
    drawer openings ``holes[+1 | -1]`` ((y0, z0, y1, z1)): drawers in the ends of a table (a Pembroke
    or farmhouse table's end drawer)."""
    xb = length / 2 - leg_w
    ye = width / 2 - max(leg_w, board)
    out = []
    for s in (1, -1):
        y0, y1 = sorted((s * width / 2, s * (width / 2 - board)))
        out.append(g.box_between([-xb, y0, z0], [xb, y1, z1], material))
        x0, x1 = sorted((s * length / 2, s * (length / 2 - board)))
        out.append(g.panel([x0, -ye, z0], [x1, ye, z1], material, "x", holes=holes.get(s, [])))
    return out


def apron_loper(x0: float, y_face: float, side: int, za0: float, za1: float, length: float, material: str
                ) -> tuple[list[g.Piece], Frame]:
    """A :func:`loper` in an apron board from ``za0`` to ``za1``: 1 cm over its bottom edge, 6 mm under its top
    (the top's underside)."""
    return loper(x0, y_face, side, za0 + 0.01, za1 - 0.006, length, material)


# -- apron drawers ---------------------------------------------------------------------------------
def apron_drawer(w: float, h: float, depth: float, board: float, wall: float, face: Frame, handle: str,
                 sizes: dict, sheet: float | None = None) -> Assembly:
    """A drawer in an apron opening: a box whose front is ``w`` x ``h`` (boards ``board``, box walls ``wall``),
    attached by its ``slide`` anchor to ``face``, with a handle on the front: a ``"knob"`` (radius at most
    ``sizes["knob"][0]``, 30 % of the front's height, ``sizes["knob"][1]`` proud), else a pull of
    :data:`~categories.parts.hardware.HANDLES` (``"bar"``, ``"bow"``) at most ``sizes["bar"]`` long (half
    the front's width). ``sheet``: a steel drawer's folded-sheet thickness (None: boards)."""
    box = panels.drawer_box(w, h, depth, board, wall, "frame")
    if sheet is not None:  # a steel drawer is folded sheet, not steel boards
        part = box.parts[box.root]
        box = Assembly.single(part.label, [pc.replace(sheet=sheet) for pc in part.pieces],
                              box.anchors, box.supports, name=box.root)
    box = box.attached("slide", to=face)
    r, d = sizes["knob"]
    pull = hardware.knob_handle(min(r, 0.3 * h), d, "handle") if handle == "knob" else \
        hardware.HANDLES[handle](min(sizes["bar"], 0.5 * w), "handle")
    pull = pull.attached("mount", to=box.anchor("handle"))
    return box.with_pieces(box.root, pull.parts[pull.root].pieces)


def drawer_openings(span: float, per: int, z0: float, z1: float, margin: float, stile: float, widest: float
                    ) -> list[tuple[float, float, float, float]]:
    """``per`` drawer openings ((y0, z0, y1, z1)) in a board ``span`` long between ``z0`` and ``z1``: one bay
    per drawer, each opening at most ``widest`` wide and ``stile`` narrower than its bay, centred in it,
    ``margin`` of board above and below."""
    dw = span / per
    w = min(dw - stile, widest)
    return [(-span / 2 + (k + 0.5) * dw - w / 2, z0 + margin, -span / 2 + (k + 0.5) * dw + w / 2, z1 - margin)
            for k in range(per)]


# -- a nest of tables ------------------------------------------------------------------------------
def nest_frame(width: float, z_top: float, sizes: dict, material: str) -> tuple[list[g.Piece], float]:
    """The outer table of a nest, ``width`` square, its top's underside at ``z_top``: four square legs
    ``sizes["leg_in"]`` in from the edges and a rail under each side along x (the nested tables slide out
    along x between them). Returns its pieces and the clear span between legs and rails along y."""
    r = sizes["leg"] + sizes["leg_room"]
    a = width / 2 - r - sizes["leg_in"]
    t, h = sizes["rail"]
    legs = [g.box_between([sx * a - r, sy * a - r, 0.0], [sx * a + r, sy * a + r, z_top], material, bevel=0.002)
            for sx in (-1, 1) for sy in (-1, 1)]
    rails = [g.box_between([-a + r, sy * a - t, z_top - h], [a - r, sy * a + t, z_top], material) for sy in (-1, 1)]
    return legs + rails, 2 * (a - r) - 2 * t


# -- dining-table fittings -------------------------------------------------------------------------
def leveller(at: Frame, leg_w: float, height: float, sizes: dict) -> list[g.Piece]:
    """A levelling foot ``height`` tall under a leg ``leg_w`` wide at ``at``: a glide disc (``sizes["glide"]``:
    radius at most, fraction of the leg, height) on a threaded stem (``sizes["stem"]`` radius)."""
    r_max, share, disc = sizes["glide"]
    r = min(r_max, share * leg_w)
    return [g.cylinder(at.point((0, 0, 0)), at.point((0, 0, disc)), r, "foot", 24),
            g.cylinder(at.point((0, 0, disc)), at.point((0, 0, height)), sizes["stem"], "metal", 12)]


def lazy_susan(radius: float, z: float, bearing: float, thickness: float, ring: str, top: str
               ) -> tuple[g.Piece, g.Piece, float]:
    """A turntable of ``radius`` on a ball-bearing ring ``bearing`` high (40 % of its radius) standing on a top
    at ``z``; returns the ring, the turntable (rounded 4 mm at its rim) and the turntable's underside."""
    ring_piece = g.cylinder([0, 0, z], [0, 0, z + bearing], 0.4 * radius, ring, 48)
    z0 = z + bearing + 0.001
    r, t = radius, thickness
    table = g.revolve([(0.0, z0), (r - 0.004, z0), (r, z0 + 0.004), (r, z0 + t - 0.004), (r - 0.004, z0 + t),
                       (0.0, z0 + t)], top, sections=96)
    return ring_piece, table, z0


def bearer_frame(xb: float, yb: float, z0: float, z1: float, rails: tuple[float, float], material: str
                 ) -> list[g.Piece]:
    """A draw-leaf table's bearer frame under a fixed top: two side rails (``rails[0]`` wide) ``xb`` along x
    each side of the centre just inside ``|y| = yb``, and a cross rail (``2 * rails[1]`` wide) between them."""
    side, cross = rails
    out = [g.box_between((-xb, y0, z0), (xb, y1, z1), material) for y0, y1 in ((-yb, -yb + side), (yb - side, yb))]
    out.append(g.box_between((-cross, -yb + side, z0), (cross, yb - side, z1), material))
    return out


# -- dining-table parts placed by anchors ---------------------------------------------------------------
# These build in the table's frame (z = 0 the floor, X the long axis); the layout joins each by its named
# anchor. ``sizes`` is :data:`~.furniture_sizes.DINING`.
def opening_drawer(hole: tuple[float, float, float, float], wall_at: float, side: int, in_end: bool, depth: float,
                   handle: str | None, sizes: dict, sheet: float | None = None) -> Assembly:
    """A :func:`apron_drawer` in an apron opening ``hole`` (a0, z0, a1, z1 along its board), the board's outer
    face at ``wall_at`` on ``side`` (+1 / -1) of the table: of an end board (``in_end``, the drawer pulls out
    along X) or a long one (along Y); ``sizes["clear"]`` round its front; ``handle`` None: a knob on a front
    narrower than ``sizes["knob_under"]``, else a bar. Anchor ``slide``: the front's face."""
    a0, z0, a1, z1 = hole
    w, h = a1 - a0 - 2 * sizes["clear"], z1 - z0 - 2 * sizes["clear"]
    if handle is None:  # a knob on a narrow front, else a bar
        handle = "knob" if w < sizes["knob_under"] else "bar"
    if in_end:
        face = Frame.at((wall_at, (a0 + a1) / 2, (z0 + z1) / 2), z=(side, 0, 0), x=(0, 0, 1))
    else:
        face = Frame.at(((a0 + a1) / 2, wall_at, (z0 + z1) / 2), z=(0, side, 0), x=(0, 0, 1))
    return apron_drawer(w, h, depth, sizes["board"], sizes["drawer_wall"], face, handle, sizes, sheet)


def draw_leaf(length: float, width: float, leaf_length: float, side: int, z0: float, sizes: dict) -> Assembly:
    """A draw leaf ``leaf_length`` long stored from ``z0`` under the ``side`` (+1 / -1) end of a top ``length`` x
    ``width`` (``sizes["draw_leaf_in"]`` in from its end and sides, ``sizes["leaf_t"]`` thick). Anchor ``slide``:
    at the leaf's outer end, z pointing out along X."""
    end, edge = sizes["draw_leaf_in"]
    x0, x1 = sorted((side * (length / 2 - leaf_length), side * (length / 2 - end)))
    piece = g.box_between((x0, -width / 2 + edge, z0), (x1, width / 2 - edge, z0 + sizes["leaf_t"]), "top",
                          bevel=0.003)
    return Assembly.single("leaf", [piece], {"slide": Frame.at((side * (length / 2 - end), 0, z0), z=(side, 0, 0))})


def apron_lopers(apron_length: float, y_face: float, side: int, za0: float, za1: float, length: float, count: int,
                 material: str) -> list[Assembly]:
    """``count`` :func:`apron_loper` brackets ``length`` long in the long apron board whose face is at ``y_face``:
    one centred, or two at a quarter of the apron (``apron_length``) from each end. Anchor ``hinge``."""
    xs = [-apron_length / 4, apron_length / 4] if count == 2 else [0.0]
    out = []
    for xc in xs:
        pieces, hinge = apron_loper(xc - length / 2, y_face, side, za0, za1, length, material)
        out.append(Assembly.single("bracket", pieces, {"hinge": hinge}))
    return out


def split_half(length: float, width: float, shape: str, z0: float, z1: float, split: float, side: int,
               material: str) -> Assembly:
    """One half of an extending top (:func:`~.tables.half_top`) from ``z0`` to ``z1``. Anchor ``slide``: on the
    split's ``side`` at the underside, z pointing out along X."""
    piece = T.half_top(length, width, shape, z0, z1, split, side, material)
    return Assembly.single("top", [piece], {"slide": Frame.at((side * split / 2, 0, z0), z=(side, 0, 0))})


def stored_leaf(half: float, half_width: float, z1: float, thickness: float, material: str) -> Assembly:
    """An extension leaf stored in the apron: ``2 half`` along X, ``2 half_width`` across, its top at ``z1``."""
    return Assembly.single("leaf", [g.box_between((-half, -half_width, z1 - thickness), (half, half_width, z1),
                                                  material)])


def dining_openings(x_in: float, z0: float, z1: float, n: int, in_end: bool, sizes: dict
                    ) -> list[tuple[float, float, float, float]]:
    """``n`` drawer openings (a0, z0, a1, z1) spread evenly along an apron board with ``x_in`` free each side of
    its centre: at most ``sizes["drawer_width"]`` wide, ``sizes["drawer_stile"]`` (end board, long board) kept
    between them, ``sizes["margin"]`` of board under them, up to ``z1``."""
    dw = min(sizes["drawer_width"], 2 * x_in / n - sizes["drawer_stile"][0 if in_end else 1])
    xs = [-x_in + (k + 0.5) * 2 * x_in / n for k in range(n)]
    return [(x - dw / 2, z0 + sizes["margin"], x + dw / 2, z1) for x in xs]


def caster_plates(frames: list, leg_w: float, stem_top: float, z_leg: float, sizes: dict) -> list[g.Piece]:
    """The casters' top plates under square legs ``leg_w`` wide standing at ``frames``: from
    ``sizes["caster_plate"][0]`` over the caster's stem top ``stem_top`` up to the leg's foot ``z_leg``,
    ``sizes["caster_plate"][2]`` past the leg each side."""
    over, _, past = sizes["caster_plate"]
    return [g.box_between(f.point((-leg_w / 2 - past, -leg_w / 2 - past, stem_top + over)),
                          f.point((leg_w / 2 + past, leg_w / 2 + past, z_leg)), "metal") for f in frames]


# -- a nest of tables ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class NestedSize:
    """One table of a nest (:func:`nesting_table`'s sizes, metres): ``width`` across (y), ``depth`` along x
    from ``x0``, ``height`` to its top's upper face, tops ``top_t`` thick. ``sizes`` is
    :data:`~.furniture_sizes.NEST`."""

    width: float
    depth: float
    x0: float
    height: float
    top_t: float

    @classmethod
    def first(cls, span: float, table_width: float, z_under: float, count: int, top_t: float, sizes: dict
              ) -> NestedSize:
        """A table nested in the outer frame (``span`` between its legs, under a top ``table_width`` across
        whose underside is at ``z_under``): one of ``count`` (1: centred, 2: each from ``sizes["x0"]``)."""
        depth = sizes["depth"][0 if count == 1 else 1] * table_width
        x0 = -depth / 2 if count == 1 else sizes["x0"]
        return cls(span - sizes["side_clear"], depth, x0, z_under - sizes["gap"], top_t)

    def inner(self, span: float, sizes: dict) -> NestedSize:
        """The table nested in this one (``span`` between this one's legs)."""
        deeper, out = sizes["inner"]
        return NestedSize(span - sizes["side_clear"], deeper * self.depth, self.x0 + out * self.depth,
                          self.height - self.top_t - sizes["gap"], self.top_t)


def nested_table(size: NestedSize, side: int, sizes: dict) -> tuple[Assembly, NestedSize]:
    """A :func:`nesting_table` of ``size`` sliding out along ``side`` (+1 / -1) * x (mirrored for -1); anchor
    ``slide`` at its outer end, half way up, z pointing out. Returns it and the size of a table nested in it."""
    pieces, span = nesting_table(size.width, size.depth, size.height, size.top_t, sizes["leg"], size.x0, "top",
                                 "frame")
    if side < 0:
        pieces = [pc.transformed(Frame.at((0, 0, 0), x=(-1, 0, 0), y=(0, -1, 0)).matrix) for pc in pieces]
    slide = Frame.at((side * (size.x0 + size.depth), 0, size.height / 2), z=(side, 0, 0))
    return Assembly.single("table", pieces, {"slide": slide}), size.inner(span, sizes)


def well_struts(width: float, shape: str, inset: float, z_floor: float, z_under: float, fwd: float, travel: float,
                sizes: dict) -> tuple[tuple, Frame]:
    """A lift-top's two :func:`lift_struts` on its well's floor ``z_floor`` under a top ``width`` across (legs
    ``inset`` in) whose underside is at ``z_under``: ``sizes["round_struts"]`` of a round top's half width apart,
    ``sizes["struts_back"]`` of it behind the centre, leaning ``fwd`` forward per unit up (tilted struts lean
    forward across the centre). Returns :func:`lift_struts`' parts and the lift frame (z the lift's direction,
    at the top's underside)."""
    half = (width / 2 - inset) * (sizes["round_struts"] if shape == "round" else 1.0) - T.BOARD
    u = np.array([fwd, 0.0, 1.0])
    x = -sizes["struts_back"] * half - 0.5 * fwd * (z_under - z_floor)
    made = lift_struts((0.5 * half, -0.5 * half), x, z_floor, z_under, u, travel, "strut")
    return made, Frame.at((0, 0, z_under), z=u)


def stored_leaves(count: int, opening: float, apron_width: float, z_top: float, sizes: dict, material: str
                  ) -> list[Assembly]:
    """``count`` :func:`stored_leaf` leaves stacked in an extending table's apron (``apron_width`` across,
    ``sizes["board"]`` boards) from ``z_top`` down, ``sizes["leaf_gap"]`` apart: one ``2 opening`` long, or
    two each half that (they fill the opening side by side when laid in)."""
    half = opening / 2 if count > 1 else opening
    return [stored_leaf(half, apron_width / 2 - sizes["board"], z_top - k * (sizes["leaf_t"] + sizes["leaf_gap"]),
                        sizes["leaf_t"], material) for k in range(count)]
