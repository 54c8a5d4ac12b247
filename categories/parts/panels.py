"""Panel work: open boxes (carcasses, chests) and flat leaves (doors, lids, flaps).

A box is built on the ground plane, centred on the z axis, its front facing
+x. A leaf lies in its local xy plane, thickness along +z, its hinge edge on
local x = 0 and its free edge at x = ``depth``.
"""

from __future__ import annotations

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame


def open_box(width: float, depth: float, height: float, wall: float, material: str,
             label: str = "body") -> Assembly:
    """A box of panels open at the top: bottom, four walls.

    Anchors: ``rim_back`` (on the back wall's top edge, x pointing to the
    front, z along -y: a lid hinged there opens upward by a positive turn
    about it), ``rim_front``
    (centre of the front wall's top, z up), ``front`` (centre of the front face,
    z out of it, x up), ``floor`` (top of the bottom panel, z up). Supports:
    the four bottom corners.
    """
    x0, x1, y0, y1 = -depth / 2, depth / 2, -width / 2, width / 2
    pieces = [
        g.box_between((x0, y0, 0), (x1, y1, wall), material),
        g.box_between((x0, y0, wall), (x0 + wall, y1, height), material),
        g.box_between((x1 - wall, y0, wall), (x1, y1, height), material),
        g.box_between((x0 + wall, y0, wall), (x1 - wall, y0 + wall, height), material),
        g.box_between((x0 + wall, y1 - wall, wall), (x1 - wall, y1, height), material),
    ]
    anchors = {
        "rim_back": Frame.at((x0, 0, height), x=(1, 0, 0), z=(0, -1, 0)),
        "rim_front": Frame.at((x1 - wall / 2, 0, height)),
        "front": Frame.at((x1, 0, height / 2), z=(1, 0, 0), x=(0, 0, 1)),
        "floor": Frame.at((0, 0, wall)),
    }
    supports = {f"foot_{i}": (x, y, 0) for i, (x, y) in enumerate(((x0, y0), (x0, y1), (x1, y0), (x1, y1)))}
    return Assembly.single(label, pieces, anchors, supports)


def leaf(width: float, depth: float, thickness: float, material: str, label: str = "lid") -> Assembly:
    """A flat leaf: ``depth`` from the hinge edge (x = 0) to the free edge, ``width`` along y.

    Anchors: ``hinge`` (middle of the hinge edge on the inner face, x towards
    the free edge, z along -y: a positive turn about it swings the free edge
    out of the outer face, so attached to a ``rim_back`` the leaf opens by a
    positive angle), ``free_edge`` (centre of the free edge's face, z out of
    it, x along the leaf's outer normal), ``top`` (centre of the outer face, z
    out of it).
    """
    piece = g.box_between((0, -width / 2, 0), (depth, width / 2, thickness), material)
    anchors = {
        "hinge": Frame.at((0, 0, 0), x=(1, 0, 0), z=(0, -1, 0)),
        "free_edge": Frame.at((depth, 0, thickness / 2), z=(1, 0, 0), x=(0, 0, 1)),
        "top": Frame.at((depth / 2, 0, thickness)),
    }
    return Assembly.single(label, [piece], anchors)


def drawer_box(width: float, height: float, depth: float, front: float, wall: float, material: str,
               label: str = "drawer") -> Assembly:
    """A drawer: a front board and a box of ``wall`` boards behind it.

    Local frame: the front's outer face is the plane x = 0 (facing +x), centred on
    the origin, the box runs back to x = -depth; width along y, height along z.
    Anchors: ``slide`` (the origin, z out of the front: the pull direction) and
    ``handle`` (the front's centre, z out of it, x along the width).
    """
    w, h, t = width / 2, height / 2, wall
    top = h - 0.01  # the box walls stop below the front's top edge
    pieces = [
        g.box_between((-front, -w, -h), (0, w, h), material),
        g.box_between((-depth, -w, -h), (-front, -w + t, top), material),
        g.box_between((-depth, w - t, -h), (-front, w, top), material),
        g.box_between((-depth, -w + t, -h), (-depth + t, w - t, top), material),
        g.box_between((-depth + t, -w + t, -h), (-front, w - t, -h + 0.008), material),
    ]
    anchors = {"slide": Frame.at((0, 0, 0), z=(1, 0, 0), x=(0, 0, 1)),
               "handle": Frame.at((0, 0, 0), z=(1, 0, 0), x=(0, 1, 0))}
    return Assembly.single(label, pieces, anchors)


def carcass(width: float, depth: float, z0: float, z1: float, board: float, material: str) -> list:
    """A cabinet carcass from ``z0`` to ``z1``: two sides, bottom, top and a thin back (half a board)."""
    xb, xf, y0, y1, t = -depth / 2, depth / 2, -width / 2, width / 2, board
    return [g.box_between([xb, y0, z0], [xf, y0 + t, z1], material),
            g.box_between([xb, y1 - t, z0], [xf, y1, z1], material),
            g.box_between([xb, y0 + t, z0], [xf, y1 - t, z0 + t], material),
            g.box_between([xb, y0 + t, z1 - t], [xf, y1 - t, z1], material),
            g.box_between([xb, y0 + t, z0 + t], [xb + t * 0.5, y1 - t, z1 - t], material)]


def shelf(xs, ys, z: float, board: float, material: str):
    """A shelf board between the carcass sides, set back 1 cm from the front."""
    return g.box_between([xs[0] + board, ys[0], z - board / 2], [xs[1] - 0.01, ys[1], z + board / 2], material)


def box_drawer(front_box, box, wall: float, front: str, body: str) -> list:
    """A drawer front (``front_box``: x0, x1, y0, y1, z0, z1) and an open box behind it (``box``)."""
    fx0, fx1, fy0, fy1, fz0, fz1 = front_box
    bx0, bx1, by0, by1, bz0, bz1 = box
    wt = wall
    return [g.box_between([fx0, fy0, fz0], [fx1, fy1, fz1], front, bevel=0.002),
            g.box_between([bx0, by0, bz0], [bx1, by1, bz0 + wt], body),
            g.box_between([bx0, by0, bz0 + wt], [bx1, by0 + wt, bz1], body),
            g.box_between([bx0, by1 - wt, bz0 + wt], [bx1, by1, bz1], body),
            g.box_between([bx0, by0 + wt, bz0 + wt], [bx0 + wt, by1 - wt, bz1], body),
            g.box_between([bx1 - wt, by0 + wt, bz0 + wt], [bx1, by1 - wt, bz1], body)]
