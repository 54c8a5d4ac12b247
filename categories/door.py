"""Door: a hinged leaf in a fixed frame, with a knob, a lever or a pull on both faces.

X is depth, Y is width, Z is up. The frame (the root) stands at x = 0 in the YZ plane on the
floor: two jambs and a head (boards as deep as the wall), an optional threshold, door stops
behind the leaf and architraves (casings) around the opening on both faces. The leaf hangs in
the opening with its front face flush with the frame's front (+X) face and opens toward +X.

The leaf hinges at one jamb (``hinge_side``): about -Z at the left (min Y) jamb, +Z at the
right (max Y) one, through a pivot on its front face at the hinge edge, so it never sweeps
through the jamb; it opens 0..pi/2 (the axis is vertical: neutral under gravity). The lock-side
gap allows for the back corner of the leaf swinging out by ~T^2 / (2 W).

Leaf styles: flat, or 2-6 recessed / raised panels set in holes of the stile-and-rail frame
(the frame is a panel with through-holes, each panel is its own boxes). Glazing replaces the
top row of panels, or every panel, by glass lites in the same holes (a flat leaf gets one lite
or a column of small lites).

Handles, the same on both faces: a knob (continuous about X, symmetric: centre of mass on the
axis), a lever (revolute about X, 0..pi/4, pressing the grip down is positive; the lever has a
hollow grip; the core's ``rest_on_stops`` adds the counterweight heel opposite the grip that
puts its centre of mass on the axis, so gravity does not turn it), or a fixed bar pull (pieces
of the leaf, named ``handle``).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    door=Rule(required=("frame", "leaf", "handles"), optional={"threshold": 0.4}),
    leaf=Rule(one_of={"flat": 0.3, "recessed": 0.35, "raised": 0.35}),
    handles=Rule(one_of={"knob": 1 / 3, "lever": 1 / 3, "pull": 1 / 3}),
)
"""``leaf.one_of`` is the ``leaf_style`` parameter and ``handles.one_of`` the ``handle``
parameter (object-wide, same weights)."""

_STYLES = GROWTH.rules["leaf"].one_of
_HANDLES = GROWTH.rules["handles"].one_of

SCHEMA = Schema((
    Float("leaf_width", "leaf width (Y)", "m", 0.8, 1.0),
    Float("leaf_height", "leaf height (Z)", "m", 2.0, 2.1),
    Float("leaf_thickness", "leaf thickness (X)", "m", 0.04, 0.06),
    Float("frame_depth", "jamb depth (X), about the wall thickness", "m", 0.1, 0.16),
    Float("jamb_width", "jamb and head board thickness", "m", 0.025, 0.05),
    Float("casing_width", "architrave width", "m", 0.05, 0.09),
    Choice("hinge_side", "jamb the leaf hangs on, seen from the front (+X)",
           choices=("left", "right")),
    Choice("leaf_style", "leaf face", choices=tuple(_STYLES), weights=tuple(_STYLES.values())),
    Int("panel_count", "panels of a panelled leaf (2, 3, 5: one column; 4, 6: two)", "", 2, 6),
    Choice("glazing", "glass lites", choices=("none", "top", "full"), weights=(0.55, 0.3, 0.15)),
    Float("stile_width", "width of the leaf's stiles and top rail", "m", 0.1, 0.14),
    Choice("handle", "handle on both faces", choices=tuple(_HANDLES), weights=tuple(_HANDLES.values())),
    Float("handle_height", "handle axis above the floor", "m", 0.95, 1.05),
    Float("lever_length", "lever grip length", "m", 0.1, 0.14),
    Float("knob_radius", "knob radius", "m", 0.025, 0.032),
    Float("pull_length", "bar pull length", "m", 0.25, 0.45),
    Choice("leaf_finish", "leaf material", choices=("wood", "painted"), weights=(0.5, 0.5)),
    Choice("frame_finish", "frame material: the leaf's or painted white",
           choices=("match", "white"), weights=(0.6, 0.4)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal"), weights=(0.5, 0.5)),
    *GROWTH.flags(),
))

OPEN = math.pi / 2
GAP = 0.003  # leaf to jambs and head
FLOOR_GAP = 0.012  # under the leaf
STOP = (0.012, 0.014)  # door stop: protrusion into the opening, depth
CASING_T = 0.016
BACKSET = 0.06  # handle axis from the lock edge
LEVER_TURN = math.pi / 4


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    finish = "wood" if p["leaf_finish"] == "wood" else "painted:white|off_white|light_grey|grey|sage|navy|charcoal"
    bp = Blueprint("door", materials={
        "leaf": finish, "frame": finish if p["frame_finish"] == "match" else "painted:white|off_white",
        "glass": "glass:clear|clear_blue", "handle": p["handle_finish"], "hinge": p["handle_finish"],
    })
    W, H, T = p["leaf_width"], p["leaf_height"], p["leaf_thickness"]
    Dj, jw, cw = p["frame_depth"], p["jamb_width"], p["casing_width"]
    left = p["hinge_side"] == "left"
    gap_lock = GAP + T * T / W  # the back corner of the leaf swings out by ~T^2 / (2 W)
    x1, x0 = Dj / 2, Dj / 2 - T  # leaf front and back faces; the leaf front is flush with the frame
    th = 0.02 if p["has_threshold"] else 0.0
    z0 = th + FLOOR_GAP
    z1 = z0 + H
    # opening (between the jambs), leaf centred in Y
    oy0 = -W / 2 - (GAP if left else gap_lock)
    oy1 = W / 2 + (gap_lock if left else GAP)
    shift = -(oy0 + oy1) / 2  # centre the opening on y = 0
    oy0, oy1 = oy0 + shift, oy1 + shift
    ly0, ly1 = -W / 2 + shift, W / 2 + shift
    zh = z1 + GAP  # head underside

    # --- frame ----------------------------------------------------------------------------
    xb = -Dj / 2
    frame = [
        g.box_between([xb, oy0 - jw, 0.0], [x1, oy0, zh + jw], "frame"),
        g.box_between([xb, oy1, 0.0], [x1, oy1 + jw, zh + jw], "frame"),
        g.box_between([xb, oy0, zh], [x1, oy1, zh + jw], "frame"),
    ]
    if th:
        frame.append(g.box_between([xb, oy0, 0.0], [x1, oy1, th], "frame", bevel=0.004))
    # stops behind the leaf
    sp, sd = STOP
    xs1 = x0 - GAP
    frame += [
        g.box_between([xs1 - sd, oy0, th], [xs1, oy0 + sp, zh], "frame"),
        g.box_between([xs1 - sd, oy1 - sp, th], [xs1, oy1, zh], "frame"),
        g.box_between([xs1 - sd, oy0 + sp, zh - sp], [xs1, oy1 - sp, zh], "frame"),
    ]
    # architraves on both faces, set back 5 mm from the jamb's inner face
    rv = 0.005
    for xa0, xa1 in ((x1, x1 + CASING_T), (xb - CASING_T, xb)):
        frame += [
            g.box_between([xa0, oy0 - rv - cw, 0.0], [xa1, oy0 - rv, zh + rv + cw], "frame", bevel=0.003),
            g.box_between([xa0, oy1 + rv, 0.0], [xa1, oy1 + rv + cw, zh + rv + cw], "frame", bevel=0.003),
            g.box_between([xa0, oy0 - rv, zh + rv], [xa1, oy1 + rv, zh + rv + cw], "frame", bevel=0.003),
        ]
    bp.add("frame", "frame", frame)

    # --- leaf -----------------------------------------------------------------------------
    y_hinge = ly0 if left else ly1
    y_lock = ly1 if left else ly0
    inward = 1.0 if left else -1.0  # from the hinge edge across the leaf
    zk = p["handle_height"]
    leaf = _leaf(p, (x0, x1), (ly0, ly1), (z0, z1), zk)
    # hinge knuckles on the pivot line: decoration (no collision), they turn in place
    for zc in (z0 + 0.2, z1 - 0.2, (z0 + z1) / 2 + 0.1):
        kn = g.cylinder([x1, y_hinge, zc - 0.05], [x1, y_hinge, zc + 0.05], 0.007, "hinge", 16)
        kn.convex = []
        leaf.append(kn)
    handle = p["handle"]
    if handle == "pull":
        for n in (1, -1):
            face = x1 if n > 0 else x0
            leaf += g.bar_handle((face, y_lock - inward * BACKSET, zk), (n, 0, 0), (0, 0, 1),
                                 p["pull_length"], "handle", standoff=0.04, radius=0.012)
    bp.add("leaf", "leaf", leaf)
    bp.join(J.revolute("frame", "leaf", (x1, y_hinge, z0), (0, 0, -1 if left else 1), 0.0, OPEN,
                       role="hinge"))

    # --- knobs / levers on both faces -------------------------------------------------------
    if handle != "pull":
        yk = y_lock - inward * BACKSET
        for side, n in (("front", 1.0), ("back", -1.0)):
            face = x1 if n > 0 else x0
            rose = g.cylinder([face, yk, zk], [face + n * 0.008, yk, zk], 0.028, "handle", 32)
            bp.extend("leaf", [rose])
            start = face + n * (0.008 + GAP)
            if handle == "knob":
                r = p["knob_radius"]
                name = f"knob_{side}"
                pieces = [g.cylinder([start, yk, zk], [start + n * 0.03, yk, zk], 0.011, "handle", 24),
                          g.cylinder([start + n * 0.028, yk, zk], [start + n * 0.05, yk, zk], r, "handle", 32),
                          g.cylinder([start + n * 0.05, yk, zk], [start + n * 0.056, yk, zk], 0.75 * r,
                                     "handle", 32)]
                bp.add(name, "knob", pieces)
                bp.join(J.continuous("leaf", name, (start, yk, zk), (n, 0, 0), role="knob"))
            else:
                name = f"lever_{side}"
                grip_dir = -inward  # the grip points back toward the hinge
                bp.add(name, "lever", _lever(start, n, yk, zk, grip_dir, p["lever_length"]))
                # axis u x (-Z) turns the grip (direction u) down for a positive angle
                axis = np.cross([0.0, grip_dir, 0.0], [0.0, 0.0, -1.0])
                bp.join(J.revolute("leaf", name, (start, yk, zk), axis, 0.0, LEVER_TURN, role="knob"))
    return bp


def _leaf(p, xs, ys, zs, zk):
    """The leaf's pieces: a plain slab, or a stile-and-rail frame with panels or glass in its holes."""
    x0, x1 = xs
    y0, y1 = ys
    z0, z1 = zs
    T = x1 - x0
    style, glazing = p["leaf_style"], p["glazing"]
    sw = p["stile_width"]
    if style == "flat":
        if glazing == "none":
            return [g.box_between([x0, y0, z0], [x1, y1, z1], "leaf", bevel=0.002)]
        # one big lite, or a column of four small lites, in the upper leaf
        yc, lw = (y0 + y1) / 2, 0.32 * (y1 - y0)
        top, bottom = z1 - 0.25, zk + 0.15
        n = 1 if glazing == "top" else 4
        step = (top - bottom) / n
        holes = [(yc - lw / 2, bottom + k * step + (0.04 if n > 1 else 0.0), yc + lw / 2, bottom + (k + 1) * step)
                 for k in range(n)]
        return [g.panel([x0, y0, z0], [x1, y1, z1], "leaf", "x", holes=holes)] + _glass(holes, x0, x1)
    count = p["panel_count"]
    cols = 2 if count in (4, 6) else 1
    rows = count // cols
    bottom_rail = 0.22
    mid = 0.12  # rail between rows, and the lock rail at the handle
    inner_y0, inner_y1 = y0 + sw, y1 - sw
    # rows split into those above and below the lock rail; at least one row above
    lock0, lock1 = zk - mid / 2, zk + mid / 2
    below = rows // 3 if rows > 2 else (1 if rows == 2 else 0)
    if below == 0:
        lock0 = lock1 = z0 + bottom_rail  # no lock rail: the panels start at the bottom rail
    above = rows - below
    bands = []
    if below:
        h = (lock0 - (z0 + bottom_rail) - (below - 1) * mid) / below
        bands += [(z0 + bottom_rail + k * (h + mid), z0 + bottom_rail + k * (h + mid) + h) for k in range(below)]
    top0 = lock1 if below else z0 + bottom_rail
    h = (z1 - sw - top0 - (above - 1) * mid) / above
    bands += [(top0 + k * (h + mid), top0 + k * (h + mid) + h) for k in range(above)]
    cw = (inner_y1 - inner_y0 - (cols - 1) * mid) / cols
    holes, glass = [], []
    for r, (b0, b1) in enumerate(bands):
        for c in range(cols):
            hole = (inner_y0 + c * (cw + mid), b0, inner_y0 + c * (cw + mid) + cw, b1)
            holes.append(hole)
            glass.append(glazing == "full" or (glazing == "top" and r == len(bands) - 1))
    pieces = [g.panel([x0, y0, z0], [x1, y1, z1], "leaf", "x", holes=holes)]
    xm = (x0 + x1) / 2
    for hole, is_glass in zip(holes, glass):
        ha0, hb0, ha1, hb1 = hole
        if is_glass:
            pieces += _glass([hole], x0, x1)
            continue
        pt = 0.45 * T  # panel board, centred in the leaf
        pieces.append(g.box_between([xm - pt / 2, ha0, hb0], [xm + pt / 2, ha1, hb1], "leaf"))
        if style == "raised":  # a raised field on both faces
            m = min(0.045, 0.2 * (ha1 - ha0), 0.2 * (hb1 - hb0))
            ft = 0.78 * T
            pieces.append(g.box_between([xm - ft / 2, ha0 + m, hb0 + m], [xm + ft / 2, ha1 - m, hb1 - m], "leaf",
                                        bevel=0.1 * T))
    return pieces


def _glass(holes, x0, x1):
    """A glass pane in the middle of each hole, with glazing beads on both faces."""
    xm = (x0 + x1) / 2
    out = []
    for a0, b0, a1, b1 in holes:
        out.append(g.box_between([xm - 0.003, a0, b0], [xm + 0.003, a1, b1], "glass"))
        for xa, xb in ((xm + 0.003, xm + 0.013), (xm - 0.013, xm - 0.003)):
            e = 0.012
            out += [g.box_between([xa, a0, b0], [xb, a0 + e, b1], "leaf"),
                    g.box_between([xa, a1 - e, b0], [xb, a1, b1], "leaf"),
                    g.box_between([xa, a0 + e, b0], [xb, a1 - e, b0 + e], "leaf"),
                    g.box_between([xa, a0 + e, b1 - e], [xb, a1 - e, b1], "leaf")]
    return out


def _lever(x0: float, n: float, y: float, z: float, u: float, length: float) -> list[g.Piece]:
    """A lever turning about X through ``(x0, y, z)``, out of the face along ``n`` (+-1).

    A neck along X and a hollow round grip running along ``u`` (+-1 in Y) parallel to the face;
    the core adds the counterweight heel opposite the grip that puts the centre of mass on the
    axis (:func:`infmob_usd.physical.rest_on_stops`).
    """
    neck = g.cylinder([x0, y, z], [x0 + n * 0.05, y, z], 0.011, "handle", 24)
    xg = x0 + n * 0.042  # grip axis
    grip = g.cylinder([xg, y, z], [xg, y + u * length, z], 0.009, "handle", 20)
    grip.sheet = 0.0012  # a tube
    return [neck, grip]
