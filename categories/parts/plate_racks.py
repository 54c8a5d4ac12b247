"""Dish-rack parts: a plate rack's body (wood rails, a moulded tray or chrome wire) with its side board, an upper
tier, and the things it carries: dinner plates stood on edge, mugs and tumblers upside down on pegs, cutlery
caddies, a drip tray and a swivel spout.

Local frames: the rack stands on z = 0, its length along x (fences of prong pairs across it), centred on
x = 0 and y = 0; its side board runs along +y of it. Every fitting is built about its own origin (a mug's rim
centre, a caddy's base centre, the spout's hub axis at its bottom) and placed on an anchor of the body:
``slot_<i>`` / ``pivot_<i>`` (where plate ``i`` stands and the point it turns about), ``cup_<k>`` (peg ``k``'s
foot on the board), ``caddy_<k>`` (the middle of caddy ``k``'s place on the board), ``spout`` and
``drip_tray``. Sizes of real drainers: IKEA OSTBIT, simplehuman, Kitsure two-tier chrome racks, bamboo racks
(6-12 slots, 8-15 cm prongs); plates, mugs and tumblers from catalogue sizes (named beside each).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

LIFT = 0.1  # lift of a plate along +Z
TURN = math.pi / 2  # turn of a plate about its axis (X) either way
END = 0.03  # rack length beyond the first and last fence
PAD = 0.006  # rubber pad height under a wood or plastic rack
WIRE = 0.6  # a wire rack's wire radius as a fraction of prong_radius
SIDE_GAP = 0.015  # the side board starts this far beyond a plate slid fully sideways
TIER_GAP = 0.02  # between a lower plate lifted fully and the upper tier's lowest wire
TRAY_OUT = 0.8  # the drip tray slides out by this fraction of its length
TRAY_END_WALL = 0.004  # a plastic tray's end wall (the spout hangs on it)
SPOUT_ABOVE = 0.003  # the spout's bottom just above the tray floor's underside
SPOUT_TURN = math.pi  # the spout swings from along the end wall, through +X, to the other side
BOARD_STAND = 0.002  # mugs, tumblers and caddies stand this far above the side board
CADDY_APART, CADDY_END = 0.02, 0.01  # caddies 2 cm apart, the last 1 cm from the board's end
# The side board (a drip board beside the rack): 12 mm thick, 4 mm under the rack's side, two rows of cups
# (one CUP_PITCH each, 1 cm spare) and caddies along it, 15 mm spare at its end; a wire rack's is a
# chrome-plated steel drip tray of 0.8 mm sheet
SIDE_BOARD = dict(t=0.012, under=0.004, spare_y=0.01, spare_x=0.015, sheet=0.0008)
CUP_ROWS = (0.25, 0.75)  # the two rows of cup pegs across the board
CUP_START = 0.005  # the first peg this far past half a pitch from the board's end
# A wire rack's upper tier: its cross wires (3 rail radii under the rails' axis) are its lowest members; its
# posts stand 12 mm in from the rack's ends, reaching 7 mm into the leg feet; a wood tier's dowel posts are
# at least 6 mm or 1.5 prong radii
TIER = dict(cross=3, post_in=0.012, post_into=0.007, dowel=(0.006, 1.5))
# A wire rack's drip tray: inside the legs' 5.5 mm rubber caps with 4 mm to spare, from 5 mm inside the back
# legs to 1 cm past the front ones, 1 mm over the floor
RACK_TRAY = dict(caps=0.0055, clear=0.004, back=0.005, front=0.01, floor=0.001)
SEAT_GAP = 0.004  # a plate's lowest point above the support surface at rest
PLATE_SLIDE = 0.1  # how far a plate may slide along its slot, either way (the plastic tray's walls clear it)
UP = (0.0, 0.0, 1.0)


# -- sizes ---------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PlateSize:
    """A dinner plate: 16-30 cm across, 12-20 % as high as its radius, 3.5-6 mm stoneware, a foot ring of
    40-55 % of its radius (catalogue sizes: Denby, IKEA FÄRGRIK, Corelle)."""

    radius: float
    height: float  # foot to rim
    wall: float
    foot: float  # foot ring radius

    @classmethod
    def of(cls, p: dict) -> PlateSize:
        """From a plate rack's parameters (``plate_depth`` and ``foot_fraction`` are fractions of the radius)."""
        r = p["plate_radius"]
        return cls(r, p["plate_depth"] * r, p["plate_thickness"], p["foot_fraction"] * r)


@dataclass(frozen=True)
class RackSize:
    """A dish rack: ``slots`` slots between ``slots + 1`` fences of prong pairs (IKEA OSTBIT 8, simplehuman 10-12
    a tier), 8-15 cm prongs of 3-6 mm dowel (a wire rack's wire is 0.6 of that), the pair's prongs
    ``spread`` apart each side of the middle, ``clearance`` between a plate and a prong, rails (trays, legs)
    ``base`` high; ``feet``: on rubber pads."""

    style: str  # wood, plastic or wire
    slots: int
    prong_height: float
    prong: float  # prong (wire) radius
    spread: float  # half distance between the two prongs of a pair
    clearance: float
    base: float
    feet: bool

    @classmethod
    def of(cls, p: dict, feet: bool) -> RackSize:
        rp = p["prong_radius"] * (WIRE if p["style"] == "wire" else 1.0)
        return cls(p["style"], p["slot_count"], p["prong_height"], rp, p["prong_spread"] * p["plate_radius"],
                   p["clearance"], p["base_height"], feet)


@dataclass(frozen=True)
class _Fences:
    """Where a rack's fences stand for its plate: their x, the rack's ends, the slot pitch, the plate's foot
    (its lowest x from its origin), the underside of the body and the plates' centre height."""

    xs: np.ndarray
    ends: tuple[float, float]
    pitch: float
    foot: float
    z0: float


def _fences(size: RackSize, plate_piece: g.Piece) -> _Fences:
    pts = np.vstack([plate_piece.vertices, *plate_piece.convex])
    x_lo, x_hi = pts[:, 0].min(), pts[:, 0].max()
    n = size.slots
    pitch = x_hi - x_lo + 2 * size.clearance + 2 * size.prong
    fences = (np.arange(n + 1) - n / 2) * pitch
    return _Fences(fences, (fences[0] - END, fences[-1] + END), pitch, x_lo, PAD if size.feet else 0.0)


def _slot_anchors(size: RackSize, f: _Fences, zc: float, prefix: str = "") -> dict[str, Frame]:
    """``slot_<i>``: where plate ``i``'s origin goes (its foot ``clearance`` off the fence's prong);
    ``pivot_<i>``: the middle of its slot at its centre, the point it lifts, slides and turns about."""
    out = {}
    for i, x in enumerate(f.xs[:-1]):
        out[f"{prefix}slot_{i}"] = Frame.at((x + size.prong + size.clearance - f.foot, 0.0, zc))
        out[f"{prefix}pivot_{i}"] = Frame.at((x + f.pitch / 2, 0.0, zc))
    return out


# -- the plate ---------------------------------------------------------------------------------------------
def _smooth(u):
    u = np.clip(u, 0.0, 1.0)
    return u * u * u * (u * (6 * u - 15) + 10)


def plate(size: PlateSize, material: str) -> g.Piece:
    """A dinner plate stood on edge: axis along +x, foot at x = 0, centre on the x axis.

    A solid of revolution with a foot ring, a flat well, a smooth cavetto and a rolled rim;
    its collision is two thick frustums around it (foot ring to mid-cavetto, on to the rim).
    """
    R, H, t, rf = size.radius, size.height, size.wall, size.foot
    wf = max(0.006, 0.08 * rf)  # foot ring width
    hf = max(0.003, 0.18 * H)  # foot ring height
    Rc = R - t / 2  # centre of the rolled rim
    rw = rf + 0.3 * wf + 0.004  # the well is flat out to here, then the cavetto rises
    c0, c1 = hf + t / 2, H - t / 2  # mid-surface height in the well and at the rim

    def mid(r):
        return c0 + (c1 - c0) * _smooth((np.asarray(r) - rw) / (Rc - rw))

    foot = [(0.0, hf), (rf - wf, hf), (rf - 0.75 * wf, 0.0), (rf - 0.1 * wf, 0.0)]
    under = [(r, mid(r) - t / 2) for r in np.linspace(rf + 0.3 * wf, Rc, 24)]
    rim = [(Rc + t / 2 * np.cos(x), c1 + t / 2 * np.sin(x)) for x in np.linspace(-np.pi / 2, np.pi / 2, 9)[1:-1]]
    top = [(r, mid(r) + t / 2) for r in np.linspace(Rc, 0.0, 28)]
    fine = g.revolve(g.simplify_profile(foot + under + rim + top), material)  # sections and points from tolerances
    rh = rw + 0.5 * (Rc - rw)
    # two thick frustums (foot ring to mid-cavetto, on to the rim): the six 2-3 mm bands of the profile made
    # PhysX report a plate sliding along its slot 16-18 mm deep in a prong cap 5 mm away (plate_rack seed 32)
    coarse = g.revolve([(0.0, 0.0), (rf - 0.1 * wf, 0.0), (rh, float(mid(rh)) - t / 2), (R, H), (0.0, H)],
                       material)
    on_edge = Frame.at(z=(1, 0, 0), x=(0, 0, -1))
    return fine.with_collision_of(coarse).transformed(on_edge.matrix)


def plate_joint(parent: str, child: str, pivot: Frame) -> J.JointSpec:
    """A plate held in its slot, moving in its own plane: a lift along the pivot's z (gravity holds it down), a
    slide along its y and a turn about its x (the plate's axis) through its centre."""
    return J.limited_planar(parent, child, pivot.origin, slide_axes=(pivot.z, pivot.y),
                            slides=((0.0, LIFT), (-PLATE_SLIDE, PLATE_SLIDE)), axis=pivot.x, turn=(-TURN, TURN),
                            role="plate")


# -- rack bodies -------------------------------------------------------------------------------------------
def dowel(x: float, y: float, z_lo: float, z_hi: float, r: float, material: str) -> list[g.Piece]:
    """A prong: a cylinder with a domed top."""
    return [g.cylinder([x, y, z_lo], [x, y, z_hi - r], r, material, None),
            g.sphere([x, y, z_hi - r], r, material)]


BATTEN_W = 0.024  # a wooden rack's cross battens


def wood_rack(fences, xs, b, rp, z0, hp, base_h) -> tuple[list[g.Piece], float]:
    """Two rails on two cross battens, dowels in the rails. Returns pieces and the support height."""
    xa, xb = xs
    hb = 0.4 * base_h + 0.006  # battens
    wr = max(0.018, 3.2 * rp)
    bw = BATTEN_W
    pieces = [g.box_between([x, -b - wr, z0], [x + bw, b + wr, z0 + hb], "frame", bevel=0.002) for x in (xa, xb - bw)]
    zr = z0 + hb
    zs = zr + base_h
    for y in (-b, b):
        pieces.append(g.box_between([xa, y - wr / 2, zr], [xb, y + wr / 2, zs], "frame", bevel=0.002))
        for x in fences:
            pieces += dowel(x, y, zs - 0.004, zs + hp, rp, "prong")
    return pieces, zs


def plastic_tray(fences, xs, b, rp, z0, hp, base_h, plate_r) -> tuple[list[g.Piece], float]:
    """A moulded tray with round pegs; its side walls stand where a plate slid PLATE_SLIDE still clears them."""
    xa, xb = xs
    tf, wt = 0.004, 0.004  # floor and wall thickness
    need = 0.002  # clearance kept from the wall's top edge
    yw = PLATE_SLIDE + np.sqrt(max(0.0, (plate_r + need) ** 2 - (plate_r + SEAT_GAP - base_h) ** 2))
    yw = max(yw, b + rp + 0.015)
    zs = z0 + tf
    pieces = [
        g.box_between([xa - wt, -yw - wt, z0], [xb + wt, yw + wt, zs], "frame"),  # floor
        g.box_between([xa - wt, -yw - wt, zs], [xb + wt, -yw, zs + base_h], "frame"),  # side walls
        g.box_between([xa - wt, yw, zs], [xb + wt, yw + wt, zs + base_h], "frame"),
        g.box_between([xa - wt, -yw, zs], [xa, yw, zs + base_h], "frame"),  # end walls
        g.box_between([xb, -yw, zs], [xb + wt, yw, zs + base_h], "frame"),
    ]
    for y in (-b, b):
        for x in fences:
            pieces.append(g.cylinder([x, y, zs - 0.001], [x, y, zs + 0.006], rp * 1.6, "prong", 16))  # boss
            pieces += dowel(x, y, zs, zs + hp, rp, "prong")
    return pieces, zs


def wire_rack(fences, xs, b, rw, hp, base_h) -> tuple[list[g.Piece], float]:
    """Chrome wire: rails on rubber-capped legs, a cross wire and an arch at every fence."""
    xa, xb = xs
    cap = 0.007  # rubber cap height
    zr = cap + base_h  # rail axis height
    zs = zr + rw  # support: the rail tops
    top = zs + hp - rw  # axis of the arch's top bar
    pieces = []
    for y in (-b, b):
        pieces.append(g.cylinder([xa, y, zr], [xb, y, zr], rw, "frame", None))  # wire: sections_for(rw)
        for x in (xa + 0.012, xb - 0.012):
            pieces.append(g.cylinder([x, y, cap - 0.001], [x, y, zr], rw, "frame", None))
            pieces.append(g.cylinder([x, y, 0.0], [x, y, cap], 0.0055, "feet", None))
    for x in fences:
        pieces.append(g.cylinder([x, -b - 0.01, zr - rw], [x, b + 0.01, zr - rw], rw, "frame", None))
        for y in (-b, b):
            pieces += [g.cylinder([x, y, zr], [x, y, top], rw, "prong", None), g.sphere([x, y, top], rw, "prong")]
        pieces.append(g.cylinder([x, -b, top], [x, b, top], rw, "prong", None))
    return pieces, zs


def _style(size: RackSize, f: _Fences, plate_r: float) -> tuple[list[g.Piece], float]:
    """The rack of ``size.style`` over the fences: its pieces and its support height (where plates stand)."""
    b, rp, hp, base = size.spread, size.prong, size.prong_height, size.base
    if size.style == "wood":
        return wood_rack(f.xs, f.ends, b, rp, f.z0, hp, base)
    if size.style == "plastic":
        return plastic_tray(f.xs, f.ends, b, rp, f.z0, hp, base, plate_r)
    return wire_rack(f.xs, f.ends, b, rp, hp, base)


def tier_posts(xs, b, r: float, z0: float, z1: float, slot: str = "frame") -> list[g.Piece]:
    """Four posts carrying a rack's upper tier, at ``xs`` (two) and y = +-b, from ``z0`` up to ``z1``."""
    return [g.cylinder([x, y, z0], [x, y, z1], r, slot, 12) for x in xs for y in (-b, b)]


def rack_body(size: RackSize, plate_size: PlateSize, plate_piece: g.Piece, caddies: int, cups: int) -> Assembly:
    """The rack, its side board and (``size.feet``) its pads: one part ``rack`` with the anchors of its slots,
    the board's cups and caddies, a plastic tray's spout and a wire rack's drip tray; supports at its feet."""
    f = _fences(size, plate_piece)
    pieces, zs = _style(size, f, plate_size.radius)
    board, side = side_board(pieces, f.ends, plate_size.radius, caddies, cups, size.style == "wire")
    on_board = _board_anchors(board, caddies, cups)
    pieces.append(side)
    pieces += [pc for k in range(caddies) for pc in caddy_pocket().placed(on_board[f"caddy_{k}"]).pieces]
    if size.feet:
        pieces += pads(pieces, f.ends)
    zc = zs + SEAT_GAP + plate_size.radius  # plate centre: its lowest point SEAT_GAP above the support
    anchors = {**_slot_anchors(size, f, zc), **on_board,
               "tier": Frame.at((0.0, 0.0, zc + plate_size.radius + LIFT + TIER_GAP)),
               "spout": Frame.at((f.ends[1] + TRAY_END_WALL + SPOUT_OFF, 0.0, f.z0 + SPOUT_ABOVE)),
               "drip_tray": Frame.at((f.ends[1] + RACK_TRAY["front"], 0.0, 0.0)),
               "drip_tray_back": Frame.at((f.ends[0] + RACK_TRAY["back"], 0.0, 0.0))}
    b = np.array([pc.bounds for pc in pieces])
    lo, hi = b[:, 0].min(0), b[:, 1].max(0)
    supports = {f"foot_{i}": (x, y, lo[2]) for i, (x, y) in enumerate(
        ((lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])))}
    return Assembly.single("rack", pieces, anchors, supports, name="rack")


def rack_tier(size: RackSize, plate_size: PlateSize, plate_piece: g.Piece, top: Frame) -> Assembly:
    """The upper tier: the rack again, raised until its lowest member over the plates is at ``top`` (the body's
    ``tier`` anchor: ``TIER_GAP`` above a lower plate lifted fully), on four posts that rise from the lower
    tier, with the anchors of its own slots (``slot_<i>``, ``pivot_<i>``). Wire: the legs (caps dropped) stand
    on posts over the lower legs, its cross wires are the lowest members (a rail's radius under the rail axis).
    Wood: the rails are, and the posts are dowels from the lower rails to the upper battens."""
    f = _fences(size, plate_piece)
    pieces, zs = _style(size, f, plate_size.radius)
    z_top = float(top.origin[2])
    b, rp = size.spread, size.prong
    if size.style == "wire":
        pieces, posts, dz = wire_tier(pieces, zs, z_top, f.ends, b, rp)
    else:
        dz = z_top - (zs - size.base)
        least, share = TIER["dowel"]
        posts = tier_posts((f.ends[0] + BATTEN_W / 2, f.ends[1] - BATTEN_W / 2), b, max(least, share * rp), zs,
                           f.z0 + dz)
    zc = zs + SEAT_GAP + plate_size.radius
    return Assembly.single("rack", [pc.translated((0.0, 0.0, dz)) for pc in pieces] + posts,
                           _slot_anchors(size, f, zc + dz), name="tier")


def wire_tier(pieces, zs: float, top: float, xs, b: float, rp: float):
    """A wire rack's upper tier: its ``pieces`` (rails at ``zs``) without their leg caps, raised so its cross
    wires are at ``top``, and the posts from the lower tier's rails to its legs. Returns the pieces, the posts
    and the rise."""
    dz = top - (zs - TIER["cross"] * rp)
    pieces = [pc for pc in pieces if pc.material != "feet"]
    posts = tier_posts((xs[0] + TIER["post_in"], xs[1] - TIER["post_in"]), b, rp, zs - rp,
                       dz + TIER["post_into"])  # rail axis to leg foot
    return pieces, posts, dz


def pads(pieces, xs) -> list[g.Piece]:
    """Four rubber pads under the corners of a rack body (it stands on them)."""
    lo = np.array([pc.bounds[0] for pc in pieces]).min(0)
    hi = np.array([pc.bounds[1] for pc in pieces]).max(0)
    return [g.cylinder([x, y, lo[2] - 0.006], [x, y, lo[2] + 0.001], 0.007, "feet", 16)
            for x in (xs[0] + 0.012, xs[1] - 0.012) for y in (lo[1] + 0.012, hi[1] - 0.012)]


# -- the side board and what stands on it --------------------------------------------------------------------
def side_board(pieces, xs, plate_r: float, caddies: int, cups: int, wire: bool):
    """The side board beside a rack of ``pieces`` over ``xs``: beyond the reach of a plate (``plate_r``) slid
    fully sideways, at the rack's foot, running past the rack's end where ``caddies`` caddies and two rows of
    ``cups`` need it. Returns its extent (x range, y range, bottom, top) and its piece."""
    lo = np.array([pc.bounds[0] for pc in pieces]).min(0)
    hi = np.array([pc.bounds[1] for pc in pieces]).max(0)
    y0 = max(hi[1], plate_r + PLATE_SLIDE + SIDE_GAP)
    sb = SIDE_BOARD
    need = caddies * (CADDY["x"] + CADDY_APART) + math.ceil(cups / 2) * CUP_PITCH + sb["spare_x"]
    board = ((xs[0], max(xs[1], xs[0] + need)), (y0, y0 + 2 * CUP_PITCH + sb["spare_y"]), lo[2], lo[2] + sb["t"])
    side = g.box_between([xs[0], hi[1] - sb["under"], lo[2]], [board[0][1], board[1][1], board[3]], "frame",
                         bevel=0.002)
    return board, side.replace(sheet=sb["sheet"]) if wire else side


def _board_anchors(board, caddies: int, cups: int) -> dict[str, Frame]:
    """``caddy_<k>``: the middle of caddy ``k``'s place on the board's top, from the board's far end;
    ``cup_<k>``: peg ``k``'s foot, in two full rows along the board, after the caddies."""
    (x0, x1), (y0, y1), _, z = board
    yc = (y0 + y1) / 2
    out = {}
    for k in range(caddies):
        xe = x1 - CADDY_END - k * (CADDY["x"] + CADDY_APART)
        out[f"caddy_{k}"] = Frame.at((xe - CADDY["x"] / 2, yc, z))
    rows = (y0 + CUP_ROWS[0] * (y1 - y0), y0 + CUP_ROWS[1] * (y1 - y0))
    start = x0 + CUP_PITCH / 2 + CUP_START
    spots = [(start + i * CUP_PITCH, y) for y in rows for i in range(math.ceil(cups / 2))]
    out.update({f"cup_{k}": Frame.at((x, y, z)) for k, (x, y) in enumerate(spots)})
    return out


def pegs(body: Assembly) -> list[Frame]:
    """The feet of a body's cup pegs, in order: two full rows (the last peg of a row may stay free)."""
    return [body.anchor(f"cup_{k}") for k in range(sum(a.startswith("cup_") for a in body.anchors))]


# an open cutlery caddy (Joseph Joseph, simplehuman drainer caddies): 11 x 13 cm, 14 cm high, 3 mm walls
CADDY = dict(x=0.11, y=0.13, h=0.14, wall=0.003)
# a 300 ml mug: 80-85 mm across, 95 mm high, 4 mm stoneware wall (catalogue sizes)
MUG = dict(r=0.041, h=0.095, wall=0.004)
PEG = dict(r=0.008, h=0.055)  # the cup pegs of a drainer's cup rail: a mug or tumbler is free once its rim
#                               clears the peg's top (its engagement, infmob_usd.lift_off)
# a drainer board's moulded caddy pocket (simplehuman, Joseph Joseph drainer trays: 10-20 mm deep): a 15 mm lip,
# 3 mm thick, 2 mm clear of the caddy's base all round; the caddy is free once its base clears the lip
POCKET = dict(h=0.015, wall=0.003, clear=0.002)
CUP_PITCH = 0.11  # centre to centre along a row of cups (a mug and its handle: 82 + 22 mm)


def _standing(label: str, pieces: list[g.Piece]) -> Assembly:
    """A part standing ``BOARD_STAND`` over a board: ``mount`` on the board under its origin, ``lift`` (z up)
    where it is lifted from."""
    stand = Frame.at((0.0, 0.0, BOARD_STAND))
    return Assembly.single(label, [pc.translated(stand.origin) for pc in pieces],
                           {"mount": Frame.at(), "lift": Frame.at(z=UP)}, {"base": (0.0, 0.0, BOARD_STAND)})


def caddy(slot: str, metal: str) -> Assembly:
    """An open cutlery caddy with two dividers and a few knives, forks and spoons standing in it; its origin at
    the middle of its base (``mount`` on the board it stands on, ``lift`` where it lifts off)."""
    w, h = CADDY["wall"], CADDY["h"]
    x0, x1, y0, y1, z = -CADDY["x"] / 2, CADDY["x"] / 2, -CADDY["y"] / 2, CADDY["y"] / 2, 0.0
    pieces = [g.box_between([x0, y0, z], [x1, y1, z + w], slot),
              g.box_between([x0, y0, z + w], [x0 + w, y1, z + h], slot, bevel=0.001),
              g.box_between([x1 - w, y0, z + w], [x1, y1, z + h], slot, bevel=0.001),
              g.box_between([x0 + w, y0, z + w], [x1 - w, y0 + w, z + h], slot, bevel=0.001),
              g.box_between([x0 + w, y1 - w, z + w], [x1 - w, y1, z + h], slot, bevel=0.001)]
    ys = np.linspace(y0, y1, 4)
    for yd in ys[1:-1]:  # dividers
        pieces.append(g.box_between([x0 + w, yd - w / 2, z + w], [x1 - w, yd + w / 2, z + 0.8 * h], slot))
    for k, (ya, yb) in enumerate(zip(ys[:-1], ys[1:])):  # a handle or two standing in each compartment
        for i, xc in enumerate(np.linspace(x0 + 0.03, x1 - 0.03, 2)):
            yc = (ya + yb) / 2
            top = z + h + 0.05 + 0.01 * ((k + i) % 2)
            pieces.append(g.box_between([xc - 0.0075, yc - 0.002, z + w], [xc + 0.0075, yc + 0.002, top], metal,
                                        bevel=0.001))
    return _standing("basket", pieces)


def caddy_pocket(slot: str = "frame") -> Assembly:
    """The lip of a caddy's pocket on the board, around its base (origin: the middle of the pocket's floor)."""
    c, w = POCKET["clear"], POCKET["wall"]
    x, y = CADDY["x"] / 2 + c, CADDY["y"] / 2 + c
    lips = [g.box_between([-x - w, -y - w, -0.001], [x + w, -y, POCKET["h"]], slot),
            g.box_between([-x - w, y, -0.001], [x + w, y + w, POCKET["h"]], slot),
            g.box_between([-x - w, -y, -0.001], [-x, y, POCKET["h"]], slot),
            g.box_between([x, -y, -0.001], [x + w, y, POCKET["h"]], slot)]
    return Assembly.single("rack", lips, {"mount": Frame.at()})


def cup_peg(slot: str) -> Assembly:
    """A cup peg standing on a board (its foot ``mount`` 1 mm into it); ``seat``: where a cup's rim rests."""
    pc = g.cylinder([0.0, 0.0, -0.001], [0.0, 0.0, PEG["h"]], PEG["r"], slot, 12)
    return Assembly.single("rack", [pc], {"mount": Frame.at(), "seat": Frame.at((0.0, 0.0, BOARD_STAND))})


def mug(slot: str, handle_dir: float = 1.0) -> Assembly:
    """A mug standing upside down with its rim at its origin (a hollow wall, its base on top, a handle
    on the ``handle_dir`` side along +-x); ``rim`` on the peg's seat, ``lift`` along its axis."""
    r, h, t = MUG["r"], MUG["h"], MUG["wall"]
    wall = g.shell([(r, 0.0), (r * 1.02, h - t)], t, slot, center=(0.0, 0.0, 0.0), sections=32)
    base = g.cylinder([0.0, 0.0, h - t], [0.0, 0.0, h], r * 1.02, slot, 32)
    s = handle_dir
    hx0, hx1 = sorted((s * (r - 0.002), s * (r + 0.022)))
    bar0, bar1 = sorted((s * (r + 0.016), s * (r + 0.022)))
    handle = [g.box_between([hx0, -0.005, 0.018], [hx1, 0.005, 0.026], slot, bevel=0.002),
              g.box_between([hx0, -0.005, h - 0.03], [hx1, 0.005, h - 0.022], slot, bevel=0.002),
              g.box_between([bar0, -0.005, 0.026], [bar1, 0.005, h - 0.03], slot, bevel=0.002)]
    return Assembly.single("cup", [wall, base, *handle], {"rim": Frame.at(), "lift": Frame.at(z=UP)},
                           {"rim": (0.0, 0.0, 0.0)})


# a 300 ml tumbler: 70-75 mm across, 100-110 mm high, 3 mm wall on an 8 mm base (catalogue sizes)
TUMBLER = dict(r=0.036, h=0.105, wall=0.003, base=0.008)


def tumbler(slot: str) -> Assembly:
    """A tumbler standing upside down with its rim at its origin: a thin wall narrowing to a thick base."""
    r, h, t, b = TUMBLER["r"], TUMBLER["h"], TUMBLER["wall"], TUMBLER["base"]
    wall = g.shell([(r, 0.0), (0.88 * r, h - b)], t, slot, center=(0.0, 0.0, 0.0), sections=32)
    base = g.cylinder([0.0, 0.0, h - b], [0.0, 0.0, h], 0.88 * r, slot, 32)
    return Assembly.single("glass", [wall, base], {"rim": Frame.at(), "lift": Frame.at(z=UP)},
                           {"rim": (0.0, 0.0, 0.0)})


# -- a moulded tray's spout, a wire rack's drip tray ------------------------------------------------------
# a moulded drainer tray's swivel spout (Rubbermaid, OXO, simplehuman drainer trays): a 25-30 mm wide trough
# 40-60 mm long on a round hub through the tray's end wall; it swings 180 degrees to point water at the sink
SPOUT = dict(length=0.05, width=0.026, h=0.012, hub=0.012, wall=0.002)
SPOUT_OFF = SPOUT["hub"] + 0.004  # the spout's hub axis beyond the tray's end wall


def swivel_spout(slot: str) -> Assembly:
    """A spout with its hub axis on its origin's z (``pivot``), its bottom at z = 0, pointing along -Y at rest:
    a round hub and a trough (bottom and two side walls) running from it."""
    L, w, h, t = SPOUT["length"], SPOUT["width"], SPOUT["h"], SPOUT["wall"]
    pieces = [g.cylinder([0.0, 0.0, 0.0], [0.0, 0.0, h], SPOUT["hub"], slot, 24).replace(sheet=t),
              g.box_between([-w / 2, -L, 0.0], [w / 2, 0.0, t], slot).replace(sheet=t),
              g.box_between([-w / 2, -L, t], [-w / 2 + t, 0.0, h], slot),
              g.box_between([w / 2 - t, -L, t], [w / 2, 0.0, h], slot)]
    return Assembly.single("spout", pieces, {"pivot": Frame.at()})


# a drainer's drip tray: a 1.5 mm polypropylene tray 8-12 mm deep (simplehuman, Joseph Joseph, Kitsure)
DRIP_TRAY = dict(h=0.009, wall=0.0015, tab=0.012)


def drip_tray(x0: float, x1: float, y0: float, y1: float, z: float, h: float, slot: str) -> list[g.Piece]:
    """A shallow tray: a bottom, four low walls and a finger tab on its front (+X) wall."""
    t = 0.003  # walls and bottom as 3 mm slabs for collisions, 1.5 mm sheet for mass
    s = DRIP_TRAY["wall"]
    yc = (y0 + y1) / 2
    return [g.box_between([x0, y0, z], [x1, y1, z + t], slot).replace(sheet=s),
            g.box_between([x0, y0, z + t], [x0 + t, y1, z + h], slot).replace(sheet=s),
            g.box_between([x1 - t, y0, z + t], [x1, y1, z + h], slot).replace(sheet=s),
            g.box_between([x0 + t, y0, z + t], [x1 - t, y0 + t, z + h], slot).replace(sheet=s),
            g.box_between([x0 + t, y1 - t, z + t], [x1 - t, y1, z + h], slot).replace(sheet=s),
            g.box_between([x1, yc - 0.02, z + h - t], [x1 + DRIP_TRAY["tab"], yc + 0.02, z + h], slot)]


def rack_drip_tray(body: Assembly, size: RackSize) -> Assembly:
    """A wire rack's drip tray between its legs (at +-``spread``), under the cross wires, from the body's
    ``drip_tray_back`` anchor (5 mm inside the back legs) to its ``drip_tray`` anchor (1 cm past the front
    ones): its front wall's outer face at its origin (``mount``, on the body's anchor; ``pull``: out along +x),
    its back at support ``back``."""
    t = RACK_TRAY
    y = size.spread - t["caps"] - t["clear"]  # inside the legs' 5.5 mm rubber caps
    length = float(body.anchor("drip_tray").origin[0] - body.anchor("drip_tray_back").origin[0])
    pieces = drip_tray(-length, 0.0, -y, y, t["floor"], DRIP_TRAY["h"], "tray")
    return Assembly.single("tray", pieces, {"mount": Frame.at(), "pull": Frame.at(z=(1, 0, 0))},
                           {"back": (-length, 0.0, 0.0)})


def tray_travel(tray: Assembly) -> float:
    """How far a drip tray pulls out: ``TRAY_OUT`` of its length."""
    return TRAY_OUT * -float(tray.support("back")[0])
