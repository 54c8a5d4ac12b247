"""Door parts: frames (jambs, head, stops, architraves), leaves (slab, stile-and-rail with panels or
glass lites), glazing beads, hinge knuckles, knobs, levers and roses.

World-aligned frames: a door frame stands in the yz plane around x = 0, its front face toward +x.
Sizes of real interior doors: leaves 0.8-1.0 x 2.0-2.1 m, 35-60 mm thick; jambs as deep as the
wall; architraves 50-90 mm; handles at 0.95-1.05 m with a 60 mm backset (BS EN 1906, DIN 18101).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

from .hardware import HandleSize


@dataclass(frozen=True)
class Ranges:
    """Ranges of a door's parameters (lo, hi), m, a count or a fraction. Leaves 0.8-1.0 x 2.0-2.1 m and
    40-60 mm thick, 100-140 mm stiles and rails, 2-6 panels; jambs 25-50 mm on walls 100-160 mm thick,
    architraves 50-90 mm; handles at 0.95-1.05 m, levers 100-140 mm, knobs 50-64 mm across, bar pulls
    250-450 mm (BS EN 1906, DIN 18101; ironmongers' catalogues); each leaf of a French pair 68-75 % of a
    single leaf (0.6-0.75 m); barn-door hanger wheels 60-90 mm across (sliding-door hardware catalogues)."""

    leaf_width: tuple[float, float] = (0.8, 1.0)
    leaf_height: tuple[float, float] = (2.0, 2.1)
    leaf_thickness: tuple[float, float] = (0.04, 0.06)
    frame_depth: tuple[float, float] = (0.1, 0.16)
    jamb_width: tuple[float, float] = (0.025, 0.05)
    casing_width: tuple[float, float] = (0.05, 0.09)
    panel_count: tuple[int, int] = (2, 6)
    stile_width: tuple[float, float] = (0.1, 0.14)
    handle_height: tuple[float, float] = (0.95, 1.05)
    lever_length: tuple[float, float] = (0.1, 0.14)
    knob_radius: tuple[float, float] = (0.025, 0.032)
    pull_length: tuple[float, float] = (0.25, 0.45)
    pair_fraction: tuple[float, float] = (0.68, 0.75)
    wheel_radius: tuple[float, float] = (0.03, 0.045)



RANGES = Ranges()

CASING_T = 0.016  # architrave thickness
STOP = (0.012, 0.014)  # door stop: protrusion into the opening, depth
REVEAL = 0.005  # architraves set back from the jamb's inner face
ROSE = (0.028, 0.008)  # handle rose radius, thickness


# -- the door's layout: clearances, heights and fittings (``categories/door.py`` reads these) ---------
OPENS = math.pi / 2
GAP = 0.003  # leaf to jambs and head
FLOOR_GAP = 0.012  # under the leaf
THRESHOLD = 0.02
BACKSET = 0.06  # handle axis from the lock edge
LEVER_TURN = math.pi / 4
PULL = HandleSize(standoff=0.04, bar_radius=0.012, post_radius=0.0096, inset=0.02)


GUIDE = dict(clear=0.003, wall=0.004, height=0.035, length=0.05)  # barn-door floor guide channel
# barn-door stay roller (m): a 40 mm roller on a 4 mm L bracket 7 cm up the architrave, its arm 8 mm past the roller
STAY = dict(radius=0.02, height=0.03, clear=0.003, width=0.034, plate=0.004, foot=0.07, arm=0.008)
# Barn-door hardware (National Hardware, Rustica kits): wheel axles 5 cm over the leaf's top, their wheels
# 48 mm in front of the architraves, the track 6 cm past the leaf's travel each way; hanger straps 12 cm in
# from the leaf's edges, from 12 cm under its top; the bar pull 8 cm from the trailing edge, a flush pull
# (half width, half height, depth) behind it; the leaf covers the architraves 15 mm past their width and
# slides 3 cm past the opening; a stay roller 15 mm plus half an architrave in from the leaf's edge.
BARN = dict(axle_above=0.05, wheel_out=0.048, track_past=0.06, strap_in=0.12, strap_below=0.12, pull_in=0.08,
            flush_pull=(0.025, 0.07, 0.002), trim_past=0.015, travel_past=0.03, stay_in=0.015)
GUIDE_IN = 0.05  # the guide sits this far inside the leaf's edge at rest
KICK_HEIGHT = 0.2  # kick plates are 150-300 mm high, 1-1.5 mm stainless (Eurospec, Zoo Hardware listings)
KICK_T = 0.0015
KICK_INSET = 0.025  # short of each edge of the leaf
LETTER_LOW = 0.72  # a letter plate's centre at least this high (BS EN 13724: opening 0.7-1.7 m above the floor)
LETTER_BELOW = 0.25  # and this far below the handle axis
LETTER_FLAP_OPENS = 1.4  # the flap swings in to about 80 degrees
VIEWER_HEIGHT = 1.5  # door viewers are fitted at 1.4-1.6 m (Yale, Brinks fitting instructions)
VIEWER_SWING = math.pi / 2  # the privacy cover swings a quarter turn aside
DUTCH_CUT = 1.07  # a Dutch door's halves meet 1.0-1.2 m above the floor, above the lockset (Simpson, JELD-WEN)
DUTCH_KNOB = 0.12  # the top half's knob this far above the cut

SLIDE_GAP = 0.01  # a sliding leaf's back face in front of the header board
HEADER = 0.02  # barn-door header board thickness (on the architraves)
RAIL_CLEAR = 0.0015  # hanger wheels ride this far above the rail (they never touch it at rest)
# a kick plate stands 0.5 mm off the leaf's face, 10 mm over its bottom edge
KICK_OFF, KICK_ABOVE = 0.0005, 0.01
DUTCH_CLEAR = (0.015, 0.06)  # a Dutch door's cut clears a bar pull's end by 15 mm, the handle's top by 6 cm
DUTCH_KNOB_DEPTH = 0.05  # the top half's fixed knobs stand 5 cm off its faces


@dataclass(frozen=True)
class Opening:
    """Where a door's frame and leaves go (the frame's depth centred on x = 0, fronts at +x): the frame's
    ``x_front`` and ``stop_x`` (the stops behind the leaf), the ``opening`` between the jambs (y0, y1), the
    ``head``; a hinged leaf's ``xs`` / ``ys`` / ``zs`` (a double door's two leaves: ``leaves``, (ys, side)
    each); a sliding leaf's box and ``travel``; the lock side's ``lock_y`` (the leaf's lock edge),
    ``lock_out`` (+-1, out of that edge), ``jamb_face`` and ``strike_x`` (the strike plate's middle)."""

    x_front: float
    stop_x: float
    opening: tuple[float, float]
    head: float
    xs: tuple[float, float]
    ys: tuple[float, float]
    zs: tuple[float, float]
    leaves: tuple = ()
    travel: float = 0.0
    lock_y: float = 0.0
    lock_out: float = 1.0
    jamb_face: float = 0.0
    strike_x: float = 0.0


def opening(design: str, width: float, height: float, thickness: float, depth: float, left: bool,
            threshold: bool, pair_fraction: float = 0.5, casing: float = 0.0) -> Opening:
    """The :class:`Opening` of a ``design`` door: ``width`` x ``height`` x ``thickness`` leaf (a double
    door: two of ``pair_fraction`` of the width), a frame ``depth`` deep, hinged on the ``left`` or right,
    over a threshold or not; a sliding (barn) leaf covers the opening and its ``casing`` architraves."""
    W, H, T, Dj = width, height, thickness, depth
    z0 = (THRESHOLD if threshold else 0.0) + FLOOR_GAP
    leaves = ()
    if design == "double":
        Wl = pair_fraction * W
        gap_mid = GAP + T * T / Wl  # both back corners swing out at the meeting stiles
        oy0, oy1 = -Wl - gap_mid / 2 - GAP, Wl + gap_mid / 2 + GAP
        leaves = (((-Wl - gap_mid / 2, -gap_mid / 2), "left"), ((gap_mid / 2, Wl + gap_mid / 2), "right"))
        shift = 0.0
    elif design == "sliding":  # the leaf covers the opening and its architraves
        trim = casing + REVEAL + BARN["trim_past"]
        oy0, oy1 = -W / 2 + trim, W / 2 - trim
        shift, H_open = 0.0, H - trim - FLOOR_GAP
    else:
        gap_lock = GAP + T * T / W  # the back corner of the leaf swings out by ~T^2 / (2 W)
        oy0 = -W / 2 - (GAP if left else gap_lock)
        oy1 = W / 2 + (gap_lock if left else GAP)
        shift = -(oy0 + oy1) / 2  # the opening centred on y = 0
    head = z0 + (H_open if design == "sliding" else H) + GAP
    common = dict(x_front=Dj / 2, stop_x=Dj / 2 - T - GAP, opening=(oy0 + shift, oy1 + shift), head=head)
    if design == "sliding":
        x0 = Dj / 2 + CASING_T + HEADER + SLIDE_GAP
        return Opening(**common, xs=(x0, x0 + T), ys=(-W / 2, W / 2), zs=(FLOOR_GAP, FLOOR_GAP + H),
                       travel=(oy1 - oy0) + BARN["travel_past"])
    y_lock, out = ((W / 2 + shift), 1.0) if left else ((-W / 2 + shift), -1.0)
    return Opening(**common, xs=(Dj / 2 - T, Dj / 2), ys=(-W / 2 + shift, W / 2 + shift), zs=(z0, z0 + H),
                   leaves=leaves, lock_y=y_lock, lock_out=out, jamb_face=(oy1 if left else oy0) + shift,
                   strike_x=Dj / 2 - T / 2)


def frame(x_front: float, depth: float, opening, head: float, jamb: float, casing: float, threshold: float,
          stop_x: float) -> list[g.Piece]:
    """Two jambs and a head around the ``opening`` (y0, y1) up to ``head``, stops behind the leaf at
    ``stop_x``, architraves on both faces, and a threshold when ``threshold`` > 0."""
    oy0, oy1 = opening
    xb, x1 = x_front - depth, x_front
    zh = head
    pieces = [g.box_between([xb, oy0 - jamb, 0.0], [x1, oy0, zh + jamb], "frame"),
              g.box_between([xb, oy1, 0.0], [x1, oy1 + jamb, zh + jamb], "frame"),
              g.box_between([xb, oy0, zh], [x1, oy1, zh + jamb], "frame")]
    if threshold:
        pieces.append(g.box_between([xb, oy0, 0.0], [x1, oy1, threshold], "frame", bevel=0.004))
    sp, sd = STOP
    pieces += [g.box_between([stop_x - sd, oy0, threshold], [stop_x, oy0 + sp, zh], "frame"),
               g.box_between([stop_x - sd, oy1 - sp, threshold], [stop_x, oy1, zh], "frame"),
               g.box_between([stop_x - sd, oy0 + sp, zh - sp], [stop_x, oy1 - sp, zh], "frame")]
    rv, cw = REVEAL, casing
    for xa0, xa1 in ((x1, x1 + CASING_T), (xb - CASING_T, xb)):
        pieces += [g.box_between([xa0, oy0 - rv - cw, 0.0], [xa1, oy0 - rv, zh + rv + cw], "frame", bevel=0.003),
                   g.box_between([xa0, oy1 + rv, 0.0], [xa1, oy1 + rv + cw, zh + rv + cw], "frame", bevel=0.003),
                   g.box_between([xa0, oy0 - rv, zh + rv], [xa1, oy1 + rv, zh + rv + cw], "frame", bevel=0.003)]
    return pieces


def glass(holes, x0: float, x1: float, bead: str = "leaf") -> list[g.Piece]:
    """A glass pane in the middle of each hole (a0, b0, a1, b1 in y, z), with beads on both faces."""
    xm = (x0 + x1) / 2
    out = []
    for a0, b0, a1, b1 in holes:
        out.append(g.box_between([xm - 0.003, a0, b0], [xm + 0.003, a1, b1], "glass"))
        for xa, xb in ((xm + 0.003, xm + 0.013), (xm - 0.013, xm - 0.003)):
            e = 0.012
            out += [g.box_between([xa, a0, b0], [xb, a0 + e, b1], bead),
                    g.box_between([xa, a1 - e, b0], [xb, a1, b1], bead),
                    g.box_between([xa, a0 + e, b0], [xb, a1 - e, b0 + e], bead),
                    g.box_between([xa, a0 + e, b1 - e], [xb, a1 - e, b1], bead)]
    return out


LEAF = dict(bottom_rail=0.22, rail=0.12, lite_width=0.32, lite_top=0.25, lite_bottom=0.15)
"""Stile-and-rail proportions: bottom rail, rails between rows (and the lock rail at the handle);
a flat leaf's lites: width as a fraction of the leaf, their top below the leaf top, bottom above the handle."""


LEAF_WALL = 0.006
"""m: the leaf is hollow-core (the common interior door, flush or moulded-panel: 3-4 mm HDF skins on a
pine stile-and-rail frame over a honeycomb core), massed as a 6 mm shell: a 0.9 x 2.1 m leaf ~13 kg
(hollow-core 30 x 80 in slabs weigh 10-13 kg: JELD-WEN, Masonite listings)."""


def leaf(xs, ys, zs, handle_z: float, style: str, glazing: str, stile: float, count: int,
         wall: float = LEAF_WALL) -> list[g.Piece]:
    """A plain slab, or a stile-and-rail frame with ``count`` recessed or raised panels or glass lites
    in its holes (glazing: ``none``, the ``top`` row, or ``full``); the wooden pieces are massed as a shell
    ``wall`` thick (default :data:`LEAF_WALL`: hollow-core), the glass solid."""
    pieces = _leaf(xs, ys, zs, handle_z, style, glazing, stile, count)
    return [p.replace(wall=wall) if p.material == "leaf" else p for p in pieces]


EXTERIOR_WALL = 0.014
"""m: an exterior leaf (a Dutch door's halves) is solid-core or solid stile-and-rail, massed as a 14 mm shell:
a 0.9 x 2.05 m leaf ~35 kg (solid-core and solid-wood 36 x 80 in exterior slabs 30-45 kg: JELD-WEN, Simpson)."""


def _leaf(xs, ys, zs, handle_z: float, style: str, glazing: str, stile: float, count: int) -> list[g.Piece]:
    (x0, x1), (y0, y1), (z0, z1) = xs, ys, zs
    T = x1 - x0
    if style == "flat":
        if glazing == "none":
            return [g.box_between([x0, y0, z0], [x1, y1, z1], "leaf", bevel=0.002)]
        yc, lw = (y0 + y1) / 2, LEAF["lite_width"] * (y1 - y0)  # one lite, or a column of four
        top, bottom = z1 - LEAF["lite_top"], handle_z + LEAF["lite_bottom"]
        n = 1 if glazing == "top" else 4
        step = (top - bottom) / n
        holes = [(yc - lw / 2, bottom + k * step + (0.04 if n > 1 else 0.0), yc + lw / 2, bottom + (k + 1) * step)
                 for k in range(n)]
        return [g.panel([x0, y0, z0], [x1, y1, z1], "leaf", "x", holes=holes)] + glass(holes, x0, x1)
    cols = 2 if count in (4, 6) else 1
    rows = count // cols
    bottom, mid = LEAF["bottom_rail"], LEAF["rail"]
    iy0, iy1 = y0 + stile, y1 - stile
    lock0, lock1 = handle_z - mid / 2, handle_z + mid / 2  # rows split above and below the lock rail
    below = rows // 3 if rows > 2 else (1 if rows == 2 else 0)
    above = rows - below
    bands = []
    if below:
        h = (lock0 - (z0 + bottom) - (below - 1) * mid) / below
        bands += [(z0 + bottom + k * (h + mid), z0 + bottom + k * (h + mid) + h) for k in range(below)]
    top0 = lock1 if below else z0 + bottom
    h = (z1 - stile - top0 - (above - 1) * mid) / above
    bands += [(top0 + k * (h + mid), top0 + k * (h + mid) + h) for k in range(above)]
    cw = (iy1 - iy0 - (cols - 1) * mid) / cols
    holes, glazed = [], []
    for r, (b0, b1) in enumerate(bands):
        for c in range(cols):
            holes.append((iy0 + c * (cw + mid), b0, iy0 + c * (cw + mid) + cw, b1))
            glazed.append(glazing == "full" or (glazing == "top" and r == len(bands) - 1))
    pieces = [g.panel([x0, y0, z0], [x1, y1, z1], "leaf", "x", holes=holes)]
    xm = (x0 + x1) / 2
    for (ha0, hb0, ha1, hb1), is_glass in zip(holes, glazed):
        if is_glass:
            pieces += glass([(ha0, hb0, ha1, hb1)], x0, x1)
            continue
        pt = 0.45 * T  # panel board, centred in the leaf
        pieces.append(g.box_between([xm - pt / 2, ha0, hb0], [xm + pt / 2, ha1, hb1], "leaf"))
        if style == "raised":  # a raised field on both faces
            m = min(0.045, 0.2 * (ha1 - ha0), 0.2 * (hb1 - hb0))
            ft = 0.78 * T
            pieces.append(g.box_between([xm - ft / 2, ha0 + m, hb0 + m], [xm + ft / 2, ha1 - m, hb1 - m], "leaf",
                                        bevel=0.1 * T))
    return pieces


def knuckles(x: float, y: float, z0: float, z1: float) -> list[g.Piece]:
    """Three hinge knuckles on the pivot line (decoration: they turn in place, no collision)."""
    out = []
    for zc in (z0 + 0.2, z1 - 0.2, (z0 + z1) / 2 + 0.1):
        kn = g.cylinder([x, y, zc - 0.05], [x, y, zc + 0.05], 0.007, "hinge", 16)
        out.append(g.Piece(kn.vertices, kn.faces, "hinge", []))
    return out


def rose(face: float, n: float, y: float, z: float) -> g.Piece:
    """The round plate a knob or lever turns in, on the face at ``face`` (outward ``n`` = +-1)."""
    return g.cylinder([face, y, z], [face + n * ROSE[1], y, z], ROSE[0], "handle", 32)


def knob(x0: float, n: float, y: float, z: float, r: float) -> list[g.Piece]:
    """A round door knob out of the face along ``n`` from ``x0``: a neck, a ball and a cap (symmetric)."""
    return [g.cylinder([x0, y, z], [x0 + n * 0.03, y, z], 0.011, "handle", 24),
            g.cylinder([x0 + n * 0.028, y, z], [x0 + n * 0.05, y, z], r, "handle", 32),
            g.cylinder([x0 + n * 0.05, y, z], [x0 + n * 0.056, y, z], 0.75 * r, "handle", 32)]


def knob_part(r: float) -> Assembly:
    """The knob of :func:`knob` in its own frame: z out of the face, anchor ``mount`` and support point
    ``stem`` at the neck's foot (a part library may replace it: ``infmob_usd.retrieval``)."""
    return Assembly.single("knob", [g.cylinder([0, 0, 0], [0, 0, 0.03], 0.011, "handle", 24),
                                    g.cylinder([0, 0, 0.028], [0, 0, 0.05], r, "handle", 32),
                                    g.cylinder([0, 0, 0.05], [0, 0, 0.056], 0.75 * r, "handle", 32)],
                           {"mount": IDENTITY}, {"stem": (0, 0, 0)})


def lever(x0: float, n: float, y: float, z: float, u: float, length: float) -> list[g.Piece]:
    """A lever turning about x through ``(x0, y, z)``: a neck along ``n`` and a hollow grip along ``u``
    (+-1 in y) parallel to the face; the core adds the counterweight heel that balances it."""
    xg = x0 + n * 0.042  # grip axis
    return [g.cylinder([x0, y, z], [x0 + n * 0.05, y, z], 0.011, "handle", 24),
            g.cylinder([xg, y, z], [xg, y + u * length, z], 0.009, "handle", 20).replace(sheet=0.0012)]


# -- latch bolt, thumb-turn, sliding (barn) door hardware --------------------------------------------------
# Sizes: tubular/mortice latches: bolt 12-14 mm throw, 16-18 mm high, 60 mm backset (EN 12209); thumb-turns
# on a 50 mm rose with a 30-35 mm grip (EN 1906 accessories); barn-door kits: flat rail 40 x 6 mm on a header,
# 2 hangers with 70-100 mm nylon or steel wheels, leaves overlapping the opening by 50 mm a side
# (e.g. Rustica, National Hardware).

BOLT = dict(throw=0.013, height=0.018, thickness=0.016, inside=0.025, slack=0.002)
"""A latch bolt: throw beyond the lock edge, height, thickness (x), length inside the leaf at rest, slack (how
far past its throw the handle draws it)."""
THUMB = dict(rose=0.025, grip=0.034, grip_w=0.009, grip_d=0.016, above=0.16, over_pull=0.02)
THUMB_TURNS = math.pi / 2  # a thumb turn throws its bolt in a quarter turn
"""Thumb-turn: rose radius, grip length and width and projection, height above the handle axis, and its rose's
clearance over a bar pull's end."""


def _boxes_around(lo, hi, clo, chi) -> list[np.ndarray]:
    """Corner sets of axis-aligned boxes filling the box ``lo..hi`` minus the box ``clo..chi``."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    clo, chi = np.maximum(np.asarray(clo, float), lo), np.minimum(np.asarray(chi, float), hi)
    if np.any(chi <= clo):
        return [np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])]
    out, a, b = [], lo.copy(), hi.copy()
    for k in range(3):  # slabs below and above the cutter along each axis, then narrow to it
        for s0, s1 in ((a[k], clo[k]), (chi[k], b[k])):
            if s1 - s0 > 1e-9:
                l, h = a.copy(), b.copy()
                l[k], h[k] = s0, s1
                out.append(np.array([[x, y, z] for x in (l[0], h[0]) for y in (l[1], h[1]) for z in (l[2], h[2])]))
        a[k], b[k] = clo[k], chi[k]
    return out


def mortise(piece: g.Piece, lo, hi) -> g.Piece:
    """``piece`` with the box ``lo..hi`` cut out of its mesh and of its collision boxes (every convex piece
    is taken as its bounding box: true of boxes and panels)."""
    import trimesh

    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    cutter = trimesh.creation.box(hi - lo, trimesh.transformations.translation_matrix((lo + hi) / 2))
    mesh = g.subtract(trimesh.Trimesh(piece.vertices, piece.faces, process=False), [cutter])
    convex = []
    for c in piece.convex:
        c = np.asarray(c, float)
        convex += _boxes_around(c.min(0), c.max(0), lo, hi)
    # the cut piece keeps how it is massed (a hollow-core leaf stays hollow) and its sheet
    return g.Piece(mesh.vertices, mesh.faces, piece.material, convex, piece.name).replace(
        wall=piece.wall, sheet=piece.sheet)


def latch_bolt(xs, y_edge: float, out: float, z: float) -> tuple[list[g.Piece], tuple, tuple]:
    """A latch bolt at the lock edge ``y_edge`` (``out`` = +-1 points out of it) at height ``z``, thrown at
    rest. Returns its pieces, the mortise box (in the leaf) and the strike box (in the jamb), each
    (lo, hi) with 1.5 mm of clearance round the bolt."""
    xm = (xs[0] + xs[1]) / 2
    t, h, throw, inside = BOLT["thickness"], BOLT["height"], BOLT["throw"], BOLT["inside"]
    ya, yb = sorted((y_edge - out * inside, y_edge + out * throw))
    bolt = [g.box_between([xm - t / 2, ya, z - h / 2], [xm + t / 2, yb, z + h / 2], "handle", bevel=0.002)]
    c = 0.0015
    m_lo, m_hi = sorted((y_edge - out * (inside + throw + 0.004), y_edge + out * 0.001))
    s_lo, s_hi = sorted((y_edge + out * 0.0, y_edge + out * (throw + 0.004)))
    box = lambda y0, y1: ((xm - t / 2 - c, y0, z - h / 2 - c), (xm + t / 2 + c, y1, z + h / 2 + c))  # noqa: E731
    return bolt, box(m_lo, m_hi), box(s_lo, s_hi)


def strike_plate(x_mid: float, y_face: float, into: float, z: float) -> g.Piece:
    """The strike plate on the jamb's face ``y_face`` (``into`` = +-1 points into the jamb), around the bolt
    opening (decoration: the jamb carries the collision)."""
    ya, yb = sorted((y_face - into * 0.0015, y_face))
    plate = g.panel([x_mid - 0.012, ya, z - 0.04], [x_mid + 0.012, yb, z + 0.04], "handle", "y",
                    holes=[(x_mid - BOLT["thickness"] / 2 - 0.0015, z - BOLT["height"] / 2 - 0.0015,
                            x_mid + BOLT["thickness"] / 2 + 0.0015, z + BOLT["height"] / 2 + 0.0015)])
    return plate.replace(convex=[])


@dataclass(frozen=True)
class Edges:
    """A hinged leaf's edges: ``hinge_y`` and ``lock_y``, ``inward`` (+-1, from the hinge edge across the
    leaf), the handle's ``handle_y`` (:data:`BACKSET` in from the lock edge) and the ``hinge`` line (on
    the front face at the bottom; z down for a leaf hinged on the left, so both open the same way)."""

    hinge_y: float
    lock_y: float
    inward: float
    handle_y: float
    hinge: Frame


def edges(xs, ys, zs, left: bool) -> Edges:
    """The :class:`Edges` of a leaf (``xs``, ``ys``, ``zs``) hinged on the ``left`` or right."""
    y_hinge, y_lock = (ys[0], ys[1]) if left else (ys[1], ys[0])
    inward = 1.0 if left else -1.0
    return Edges(y_hinge, y_lock, inward, y_lock - inward * BACKSET,
                 Frame.at((xs[1], y_hinge, zs[0]), z=(0, 0, -1 if left else 1)))


@dataclass(frozen=True)
class ThumbTurnSet:
    """A deadbolt's thumb turn (anchor ``axis``: z along its spindle, out of the back face) and the roses
    on both faces of the leaf (a key cylinder's on the front)."""

    roses: list
    turn: Assembly


def thumb_turn_set(xs, y: float, z: float) -> ThumbTurnSet:
    """The :class:`ThumbTurnSet` at (``y``, ``z``) on a leaf ``xs`` thick."""
    start = xs[0] - ROSE[1] - GAP
    roses = thumb_rose(xs[0], -1.0, y, z, key=False) + thumb_rose(xs[1], 1.0, y, z, key=True)
    return ThumbTurnSet(roses, Assembly.single("knob", thumb_turn(start, -1.0, y, z),
                                               {"axis": Frame.at((start, y, z), z=(-1, 0, 0))}))


def thumb_turn(x0: float, n: float, y: float, z: float) -> list[g.Piece]:
    """A thumb-turn grip out of the face at ``x0`` along ``n`` (a spindle and a flat oblong grip, vertical at
    rest), turning about x through ``(x0, y, z)``."""
    gl, gw, gd = THUMB["grip"], THUMB["grip_w"], THUMB["grip_d"]
    x1 = x0 + n * 0.006
    xa, xb = sorted((x1, x1 + n * gd))
    return [g.cylinder([x0, y, z], [x1, y, z], 0.008, "handle", 20),
            g.box_between([xa, y - gw / 2, z - gl / 2], [xb, y + gw / 2, z + gl / 2], "handle", bevel=0.003)]


def thumb_rose(face: float, n: float, y: float, z: float, key: bool) -> list[g.Piece]:
    """The thumb-turn's rose, or on the other face a cylinder escutcheon with a key slot ring."""
    rose = g.cylinder([face, y, z], [face + n * ROSE[1], y, z], THUMB["rose"], "handle", 32)
    if not key:
        return [rose]
    return [rose, g.cylinder([face + n * ROSE[1], y, z], [face + n * (ROSE[1] + 0.004), y, z], 0.012, "hinge", 24)]


@dataclass(frozen=True)
class Hanging:
    """How a barn door's leaf (``xs``, ``ys``, ``zs``) hangs and slides (:data:`BARN`): toward ``d`` (-1:
    -y, the left wall); wheel axles at ``z_axle`` over the rail ``x_wheel`` out from the architraves' front
    face ``x_wall``; the rail at ``z_rail`` from ``track[0]`` to ``track[1]``; hanger straps at ``straps``
    (y); the pulls at ``y_pull`` on the trailing stile; ``slide``: the joint frame (z along the travel)."""

    d: float
    z_axle: float
    z_rail: float
    x_wall: float
    x_wheel: float
    track: tuple[float, float]
    straps: tuple[float, float]
    y_pull: float
    slide: Frame


def hanging(xs, ys, zs, travel: float, wheel_radius: float, toward_left: bool) -> Hanging:
    """The :class:`Hanging` of a barn door leaf sliding ``travel`` toward the left wall or the right."""
    d = -1.0 if toward_left else 1.0
    r = wheel_radius
    z_ax = zs[1] + BARN["axle_above"] + r  # wheel axles above the leaf's top
    x_wall = xs[0] - SLIDE_GAP - HEADER  # the architraves' front face
    lo, hi = (ys[0] + d * travel, ys[1]) if d < 0 else (ys[0], ys[1] + travel)
    return Hanging(d, z_ax, z_ax - r - RAIL_CLEAR, x_wall, x_wall + BARN["wheel_out"],
                   (lo - BARN["track_past"], hi + BARN["track_past"]),
                   (ys[0] + BARN["strap_in"], ys[1] - BARN["strap_in"]),
                   (ys[1] - BARN["pull_in"]) if d < 0 else (ys[0] + BARN["pull_in"]),
                   Frame.at((xs[1], ys[1] if d > 0 else ys[0], zs[0]), z=(0, d, 0)))


def barn_track(x_face: float, y0: float, y1: float, z: float) -> list[g.Piece]:
    """A barn-door header board on the wall face ``x_face`` from ``y0`` to ``y1`` with its flat rail on
    stand-offs; the rail's top is at ``z``."""
    return [g.box_between([x_face, y0, z - 0.13], [x_face + 0.02, y1, z + 0.06], "frame", bevel=0.003),
            g.box_between([x_face + 0.045, y0 + 0.02, z - 0.04], [x_face + 0.051, y1 - 0.02, z], "handle",
                          bevel=0.001)] + \
        [g.cylinder([x_face + 0.02, y, z - 0.02], [x_face + 0.045, y, z - 0.02], 0.008, "handle", 16)
         for y in np.linspace(y0 + 0.08, y1 - 0.08, 4)]


def hanger_strap(x_leaf: float, x_wheel: float, y: float, z0: float, z1: float) -> list[g.Piece]:
    """A hanger strap from the leaf's face at ``x_leaf`` up to a wheel axle at (``x_wheel``, ``z1``)."""
    xa, xb = sorted((x_leaf, x_leaf + 0.006))
    return [g.box_between([xa, y - 0.02, z0], [xb, y + 0.02, z1 + 0.012], "handle", bevel=0.002),
            g.cylinder([xa, y, z1], [x_wheel + 0.012, y, z1], 0.006, "handle", 16)]


def wheel(x_mid: float, y: float, z: float, r: float) -> list[g.Piece]:
    """A grooved hanger wheel on an axle along x at (``x_mid``, y, z)."""
    return [g.cylinder([x_mid - 0.009, y, z], [x_mid + 0.009, y, z], r, "handle", 32),
            g.cylinder([x_mid - 0.011, y, z], [x_mid + 0.011, y, z], 0.35 * r, "hinge", 16)]


LETTER = dict(plate=(0.3, 0.076), aperture=(0.25, 0.046), flap=(0.24, 0.034), flap_t=0.003, plate_t=0.004)
"""Letter plate (m): face plate (width, height), aperture through the leaf, flap (width, height) and
thicknesses. UK letter plates are ~300 x 76 mm with a 250 x 40-50 mm opening (Eurospec, Zoo Hardware
listings); BS EN 13724 asks for an aperture of at least 230 x 30 mm."""
VIEWER = dict(barrel=0.007, eyepiece=0.016, cover=(0.024, 0.044), pin_above=0.02)
"""Door viewer (m): lens barrel radius, eyepiece ring radius, privacy cover (width, length) and how far its
pivot pin sits above the lens (Yale / Brinks 200-degree viewers: 14 mm bore, 30-35 mm eyepiece, a swing cover)."""


def letter_plate(xs, y: float, z: float) -> tuple[tuple, list[g.Piece], list[g.Piece], tuple]:
    """A letter plate centred at ``(y, z)`` on a leaf ``xs`` thick: the aperture box to cut through the leaf,
    the fixed pieces (outer plate and inner trim around the opening), the flap pieces and the flap's pivot
    ``(origin, axis)``. The flap hangs in the outer plate's opening from a pin just outside it, above its top
    edge; a positive turn pushes its bottom edge in through the leaf (about +y), and its centre of mass is
    inward of the pin so gravity holds it closed on its stop."""
    (x0, x1) = xs
    pw, ph = LETTER["plate"]
    aw, ah = LETTER["aperture"]
    fw, fh = LETTER["flap"]
    pt, ft = LETTER["plate_t"], LETTER["flap_t"]
    za0, za1 = z - ah / 2, z + ah / 2  # the flap hangs from near the opening's top, room above for its pin
    cut = ((x0 - 0.001, y - aw / 2, za0), (x1 + 0.001, y + aw / 2, za1))
    hole = (y - aw / 2, za0, y + aw / 2, za1)
    fixed = [g.panel([x1, y - pw / 2, z - ph / 2], [x1 + pt, y + pw / 2, z + ph / 2], "handle", "x", holes=[hole]),
             g.panel([x0 - pt, y - pw / 2, z - ph / 2], [x0, y + pw / 2, z + ph / 2], "handle", "x", holes=[hole])]
    z_pin = za1 - 0.008
    flap = [g.box_between([x1 + 0.001, y - fw / 2, z_pin - 0.001 - fh], [x1 + 0.001 + ft, y + fw / 2, z_pin - 0.001],
                          "handle", bevel=0.0008)]
    return cut, fixed, flap, ((x1 + 0.001 + ft + 0.0005, y, z_pin), (0.0, 1.0, 0.0))


def viewer(xs, y: float, z: float) -> tuple[list[g.Piece], list[g.Piece], tuple]:
    """A door viewer at ``(y, z)``: the lens barrel through the leaf and its eyepiece ring on the back face
    (fixed), and the privacy cover hanging over the eyepiece from a pin above it, swinging aside about the
    leaf normal (it hangs under its pin: neutral under gravity). Returns fixed pieces, cover pieces and the
    pivot ``(origin, axis)``."""
    x0, x1 = xs
    r, re = VIEWER["barrel"], VIEWER["eyepiece"]
    cw, cl = VIEWER["cover"]
    fixed = [g.cylinder([x0 - 0.006, y, z], [x1 + 0.004, y, z], r, "handle", 20),
             g.cylinder([x1, y, z], [x1 + 0.003, y, z], 0.011, "handle", 24),
             g.cylinder([x0 - 0.006, y, z], [x0, y, z], re, "handle", 32)]
    zp = z + VIEWER["pin_above"]
    fixed.append(g.cylinder([x0, y, zp], [x0 - 0.0065, y, zp], 0.004, "handle", 16))  # the cover's pin boss
    xc0, xc1 = x0 - 0.0095, x0 - 0.007
    cover = [g.box_between([xc0, y - cw / 2, zp + 0.006 - cl], [xc1, y + cw / 2, zp + 0.006], "handle",
                           bevel=0.0008),
             g.cylinder([x0 - 0.007, y, zp], [xc0, y, zp], 0.004, "handle", 16)]
    return fixed, cover, ((xc1, y, zp), (-1.0, 0.0, 0.0))


# -- door fittings ---------------------------------------------------------------------------------
def kick_plate(xs, ys, zs) -> list[g.Piece]:
    """A stainless kick plate across the bottom of a leaf's front face (``xs[1]``), ``KICK_INSET`` short of its
    edges ``ys``, ``KICK_ABOVE`` over its bottom ``zs[0]``."""
    return [g.box_between([xs[1] + KICK_OFF, ys[0] + KICK_INSET, zs[0] + KICK_ABOVE],
                          [xs[1] + KICK_OFF + KICK_T, ys[1] - KICK_INSET, zs[0] + KICK_ABOVE + KICK_HEIGHT],
                          "handle", bevel=0.0006)]


def floor_guide(xs, y: float) -> list[g.Piece]:
    """A barn door's floor guide at ``y``: a U channel screwed to the floor that the bottom edge of a leaf over
    ``xs`` runs in (its front wall clear of a kick plate)."""
    c, t, h, ln = GUIDE["clear"], GUIDE["wall"], GUIDE["height"], GUIDE["length"]
    front = xs[1] + c + KICK_T + KICK_OFF
    return [g.box_between([xs[0] - c - t, y - ln / 2, 0.0], [xs[1] + c + t, y + ln / 2, t], "handle"),
            g.box_between([xs[0] - c - t, y - ln / 2, 0.0], [xs[0] - c, y + ln / 2, h], "handle"),
            g.box_between([front, y - ln / 2, 0.0], [front + t, y + ln / 2, h], "handle")]


def stay_roller(xs, x_wall: float, y: float) -> tuple[list[g.Piece], g.Piece, tuple]:
    """A barn door's stay roller at ``y``: an L bracket (4 mm steel, 7 cm up the architrave's face at
    ``x_wall``) reaching under the leaf's bottom edge, and a roller on a vertical pin that the leaf's front face
    (``xs[1]``, a kick plate on it) runs against. Returns the bracket, the roller and its centre."""
    r, h, clear, w = STAY["radius"], STAY["height"], STAY["clear"], STAY["width"]
    xr = xs[1] + KICK_T + KICK_OFF + clear + r  # clear of a kick plate
    xp = xr + r + clear  # the bracket's upright, in front of the roller
    t = STAY["plate"]
    z0, z1 = t + clear, t + clear + h  # the roller between the floor plate and the top arm
    bracket = [
        g.box_between([x_wall, y - w / 2, 0.0], [x_wall + t, y + w / 2, STAY["foot"]], "handle", bevel=0.001),
        g.box_between([x_wall, y - w / 2, 0.0], [xp + t, y + w / 2, t], "handle", bevel=0.001),
        g.box_between([xp, y - w / 2, 0.0], [xp + t, y + w / 2, z1 + clear + t], "handle", bevel=0.001),
        g.box_between([xr - STAY["arm"], y - w / 2, z1 + clear], [xp + t, y + w / 2, z1 + clear + t],
                      "handle", bevel=0.001)]
    return bracket, g.cylinder([xr, y, z0], [xr, y, z1], r, "handle", 32), (xr, y, (z0 + z1) / 2)


def flush_pull(x_face: float, y: float, z: float) -> g.Piece:
    """A flush pull (50 x 140 mm) on a sliding leaf's back face ``x_face``."""
    w, h, d = BARN["flush_pull"]
    return g.box_between([x_face - d, y - w, z - h], [x_face, y + w, z + h], "handle", bevel=0.001)
