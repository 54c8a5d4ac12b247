"""Kitchen cabinet: a panel carcass split into columns of drawers, doors or open shelves.

X is depth (fronts face +X), Y is width, Z is up. Drawers slide out along +X;
doors hinge about a vertical axis on the front face at the column edge and swing
outward; double doors when a column is wider than 0.6 m. A door hinged on the
cabinet's outer side may open up to ``door_angle``; one hinged beside another
column stops where the leaf and its handle would leave its own column.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Int, Schema

GROWTH = Growth(
    cabinet=Rule(required=("carcass", "column"), optional={"plinth": 0.6, "countertop": 0.5}),
    column=Rule(one_of={"drawers": 0.4, "doors": 0.4, "shelf": 0.2}),
    front=Rule(optional={"handles": 0.9}),
)

SCHEMA = Schema((
    Float("width", "overall width (Y)", "m", 1.0, 4.0),
    Float("height", "overall height incl. plinth (Z)", "m", 0.5, 1.3),
    Float("depth", "carcass depth (X)", "m", 0.3, 0.6),
    Float("board", "carcass board thickness", "m", 0.015, 0.022),
    Float("front_thickness", "door and drawer-front thickness", "m", 0.016, 0.024),
    Int("column_count", "columns; auto = max(1, floor(width / 0.45))", "", 1, 8, auto=True),
    Int("drawer_rows", "drawers per drawer column; auto = floor((height - 0.06) / 0.3)", "", 1, 5,
        auto=True),
    Float("plinth_height", "kick-board height when there is a plinth", "m", 0.06, 0.12),
    Choice("handle_style", "handle shape", choices=("bar", "knob", "recessed"), weights=(0.5, 0.3, 0.2)),
    Choice("body_finish", "carcass and front material", choices=("painted", "wood")),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic")),
    Float("drawer_travel", "drawer opening as a fraction of depth", "", 0.5, 0.75),
    Float("door_angle", "opening angle of a door hinged on the cabinet's outer side", "rad", math.pi / 2,
          0.65 * math.pi),
    *GROWTH.flags(),
))

GAP = 0.003  # between neighbouring fronts and between moving parts and the carcass


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    W, H, D, t = p["width"], p["height"], p["depth"], p["board"]
    bp = Blueprint("kitchen_cabinet", materials={
        "body": p["body_finish"], "front": p["body_finish"], "handle": p["handle_finish"],
        "plinth": "plastic:black|dark_grey", "top": "wood",
    })
    z0 = p["plinth_height"] if p["has_plinth"] else 0.0
    top_t = 0.03 if p["has_countertop"] else 0.0
    z1 = H - top_t  # carcass top
    xb, xf = -D / 2, D / 2  # back and front planes of the carcass
    y0, y1 = -W / 2, W / 2

    # --- carcass: two sides, bottom, top, back, dividers (all boxes) ---------
    body = [
        g.box_between([xb, y0, z0], [xf, y0 + t, z1], "body"),
        g.box_between([xb, y1 - t, z0], [xf, y1, z1], "body"),
        g.box_between([xb, y0 + t, z0], [xf, y1 - t, z0 + t], "body"),
        g.box_between([xb, y0 + t, z1 - t], [xf, y1 - t, z1], "body"),
        g.box_between([xb, y0 + t, z0 + t], [xb + t * 0.5, y1 - t, z1 - t], "body"),
    ]
    if p["has_plinth"]:
        body.append(g.box_between([xb + 0.02, y0 + 0.01, 0], [xf - 0.05, y1 - 0.01, z0], "plinth"))
    if p["has_countertop"]:
        body.append(g.box_between([xb, y0 - 0.005, z1], [xf + 0.03, y1 + 0.005, H], "top", bevel=0.004))
    carcass = bp.add("carcass", "body", body)

    n_cols = p["column_count"] or max(1, math.floor(W / 0.45))
    inner_w = W - 2 * t
    col_w = (inner_w - (n_cols - 1) * t) / n_cols
    cz0, cz1 = z0 + t, z1 - t  # inner opening
    rows = p["drawer_rows"] or max(1, math.floor((H - 0.06) / 0.3))
    handles = p["has_handles"]
    moving = False

    for c in range(n_cols):
        ya = y0 + t + c * (col_w + t)
        yb = ya + col_w
        if c < n_cols - 1:  # divider to the right of this column
            bp.extend(carcass, [g.box_between([xb + t * 0.5, yb, cz0], [xf, yb + t, cz1], "body")])
        kind = GROWTH.choose("column", structure)
        if c == n_cols - 1 and kind == "shelf" and not moving:  # an all-shelf cabinet would not articulate
            kind = "drawers" if structure.random() < 0.5 else "doors"
        moving = moving or kind != "shelf"
        # the front of a column covers the opening plus half of each bordering board
        fy0 = ya - t / 2 + GAP / 2 if c > 0 else y0 + GAP
        fy1 = yb + t / 2 - GAP / 2 if c < n_cols - 1 else y1 - GAP
        fz0, fz1 = z0 + GAP, z1 - GAP
        if kind == "drawers":
            _drawers(bp, carcass, p, c, rows, (ya, yb), (fy0, fy1), (cz0, cz1), (fz0, fz1), handles)
        elif kind == "doors":
            _shelf(bp, carcass, (xb, xf), (ya, yb), (cz0 + cz1) / 2, t)
            _doors(bp, carcass, p, c, n_cols, (fy0, fy1), (fz0, fz1), handles)
        else:
            for k in range(1, 1 + int(structure.integers(1, 3))):
                _shelf(bp, carcass, (xb, xf), (ya, yb), cz0 + (cz1 - cz0) * k / 3, t)
    return bp


def _shelf(bp, carcass, xs, ys, z, t):
    bp.extend(carcass, [g.box_between([xs[0] + t, ys[0], z - t / 2], [xs[1] - 0.01, ys[1], z + t / 2], "body")])


def _handle(p, anchor, along, length):
    n = (1.0, 0.0, 0.0)
    if p["handle_style"] == "bar":
        return g.bar_handle(anchor, n, along, length, "handle")
    if p["handle_style"] == "knob":
        return g.knob_handle(anchor, n, "handle")
    return g.pull_handle(anchor, n, along, length, "handle")


def _drawers(bp, carcass, p, c, rows, ys, fys, zs, fzs, handles):
    D, t, ft = p["depth"], p["board"], p["front_thickness"]
    xf = D / 2
    row_h = (fzs[1] - fzs[0]) / rows
    inner_row = (zs[1] - zs[0]) / rows
    clear = max(0.004, 0.02 * min(ys[1] - ys[0], inner_row))
    wt = 0.012  # drawer box wall
    for r in range(rows):
        name = f"drawer_{c}_{r}"
        fz0 = fzs[0] + r * row_h + GAP / 2
        fz1 = fz0 + row_h - GAP
        # the box stays above the front of the drawer below (GAP clear), or it drags it along when pulled
        bz0 = max(zs[0] + r * inner_row + clear, fz0)
        bz1 = zs[0] + (r + 1) * inner_row - clear - 0.01
        by0, by1 = ys[0] + clear, ys[1] - clear
        bx0, bx1 = -D / 2 + t + clear, xf - 0.002
        front_x0 = xf + GAP
        pieces = [
            g.box_between([front_x0, fys[0], fz0], [front_x0 + ft, fys[1], fz1], "front", bevel=0.002),
            g.box_between([bx0, by0, bz0], [bx1, by1, bz0 + wt], "body"),  # bottom
            g.box_between([bx0, by0, bz0 + wt], [bx1, by0 + wt, bz1], "body"),
            g.box_between([bx0, by1 - wt, bz0 + wt], [bx1, by1, bz1], "body"),
            g.box_between([bx0, by0 + wt, bz0 + wt], [bx0 + wt, by1 - wt, bz1], "body"),
            g.box_between([bx1 - wt, by0 + wt, bz0 + wt], [bx1, by1 - wt, bz1], "body"),
        ]
        if handles:
            pieces += _handle(p, (front_x0 + ft, (fys[0] + fys[1]) / 2, (fz0 + fz1) / 2 + 0.25 * (fz1 - fz0)),
                              (0.0, 1.0, 0.0), min(0.6 * (fys[1] - fys[0]), 0.35))
        bp.add(name, "drawer", pieces)
        travel = p["drawer_travel"] * (bx1 - bx0)
        bp.join(J.prismatic(carcass, name, (xf, (fys[0] + fys[1]) / 2, fz0), (1, 0, 0), 0.0, travel,
                            role="slide"))


def _doors(bp, carcass, p, c, n_cols, fys, fzs, handles):
    ft = p["front_thickness"]
    xf = p["depth"] / 2 + GAP
    width = fys[1] - fys[0]
    mid = (fys[0] + fys[1]) / 2
    if width > 0.6:  # double doors, hinged at both outer edges
        leaves = [(fys[0], mid - GAP / 2, "left"), (mid + GAP / 2, fys[1], "right")]
    else:  # one leaf, hinged on the side facing the nearer end of the cabinet
        leaves = [(fys[0], fys[1], "left" if c < n_cols / 2 else "right")]
    for k, (ya, yb, hinge) in enumerate(leaves):
        name = f"door_{c}_{k}"
        pieces = [g.box_between([xf, ya, fzs[0]], [xf + ft, yb, fzs[1]], "front", bevel=0.002)]
        reach, standoff = yb - ya, ft  # how far the leaf reaches from its hinge, and stands proud
        if handles:
            hy = yb - 0.05 if hinge == "left" else ya + 0.05
            hz = fzs[0] + 0.8 * (fzs[1] - fzs[0]) if fzs[1] - fzs[0] < 0.9 else fzs[0] + 0.6 * (fzs[1] - fzs[0])
            handle = _handle(p, (xf + ft, hy, hz), (0.0, 0.0, 1.0), min(0.3 * (fzs[1] - fzs[0]), 0.3))
            pieces += handle
            proud = max(piece.bounds[1, 0] for piece in handle) - xf
            reach, standoff = (abs(hy - (ya if hinge == "left" else yb)), proud)
        bp.add(name, "door", pieces)
        # hinge on the front face at the outer edge; the axis sign makes it swing out (+X)
        hy, axis = (ya, (0, 0, -1)) if hinge == "left" else (yb, (0, 0, 1))
        outer = (hinge == "left" and c == 0 and k == 0) or (hinge == "right" and c == n_cols - 1)
        # beside another column the open leaf and its handle must stay within this column's
        # width (else they sweep into the neighbour's open drawers or door): tan(angle) <= reach / proud
        limit = p["door_angle"] if outer else min(p["door_angle"], math.atan2(reach, standoff) - 0.01)
        bp.join(J.revolute(carcass, name, (xf + ft, hy, fzs[0]), axis, 0.0, limit, role="hinge"))
