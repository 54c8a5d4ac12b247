"""Kitchen cabinet: a panel carcass split into columns of drawers, doors or open shelves.

X is depth (fronts face +X), Y is width, Z is up. Drawers slide out along +X; doors hinge about
a vertical axis on the front face at the column edge and swing outward; double doors when a
column is wider than 0.6 m. Every hinge opens up to ``door_angle``; the core
(``limit_to_clearance``) stops a leaf hinged beside another column before it or its handle meets
the neighbour's door or open drawers. A cabinet always has at least one column that moves.
Parts: ``categories/parts/panels.py``, ``hardware``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame, cells
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import hardware, panels


def columns(p, rng) -> int:
    """column_count, or max(1, floor(width / 0.45))"""
    return p["column_count"] or max(1, math.floor(p["width"] / COLUMN))


def rows(p, rng) -> int:
    """drawer_rows, or floor((height - 0.06) / 0.3)"""
    return p["drawer_rows"] or max(1, math.floor((p["height"] - 0.06) / ROW))


def leaves(p, rng) -> int:
    """two doors in a column wider than 0.6 m, else one"""
    return 2 if column_width(p) > DOUBLE else 1


def moves(tree) -> bool:
    """At least one column has drawers or doors."""
    return any(c.choice != "shelf" for c in tree.of("column"))


GRAMMAR = Grammar("kitchen_cabinet", {
    "kitchen_cabinet": Node(label="body", repeat={"column": columns}, optional={"plinth": 0.6, "countertop": 0.5}),
    "plinth": Node(), "countertop": Node(),
    "column": Node(one_of={"drawers": 0.4, "doors": 0.4, "shelf": 0.2}),
    "drawers": Node(repeat={"drawer": rows}),
    "drawer": Node(label="drawer"),
    "doors": Node(repeat={"door": leaves}),
    "door": Node(label="door"),
    "shelf": Node(),
}, accept=moves)

PARAMS = (
    Float("width", "overall width (Y)", "m", 1.0, 4.0),
    Float("height", "overall height incl. plinth (Z)", "m", 0.5, 1.3),
    Float("depth", "carcass depth (X)", "m", 0.3, 0.6),
    Float("board", "carcass board thickness", "m", 0.015, 0.022),
    Float("front_thickness", "door and drawer-front thickness", "m", 0.016, 0.024),
    Int("column_count", "columns; auto = max(1, floor(width / 0.45))", "", 1, 8, auto=True),
    Int("drawer_rows", "drawers per drawer column; auto = floor((height - 0.06) / 0.3)", "", 1, 5, auto=True),
    Float("plinth_height", "kick-board height when there is a plinth", "m", 0.06, 0.12),
    Flag("has_handles", "fronts have handles", p=0.9),
    Choice("handle_style", "handle shape", choices=("bar", "knob", "recessed"), weights=(0.5, 0.3, 0.2)),
    Choice("body_finish", "carcass and front material", choices=("painted", "wood")),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic")),
    Float("drawer_travel", "drawer opening as a fraction of depth", "", 0.5, 0.75),
    Float("door_angle", "hinge opening angle (a door beside another column may stop earlier)", "rad", math.pi / 2,
          0.65 * math.pi),
)

MATERIALS = {"body": "body_finish", "front": "body_finish", "handle": "handle_finish",
             "plinth": "plastic:black|dark_grey", "top": "wood"}

GAP = 0.003  # between neighbouring fronts and between moving parts and the carcass
COLUMN = 0.45  # a column per 45 cm of width
ROW = 0.3  # a drawer per 30 cm of height
DOUBLE = 0.6  # columns wider than this have double doors
TOP = 0.03  # countertop thickness
DRAWER_WALL = 0.012


def column_width(p: dict) -> float:
    n = columns(p, None)
    return (p["width"] - 2 * p["board"] - (n - 1) * p["board"]) / n


class CabinetLayout(Layout):
    def kitchen_cabinet(self, node):
        p = self.p
        W, H, D, t = p["width"], p["height"], p["depth"], p["board"]
        z0 = p["plinth_height"] if node.one("plinth") else 0.0
        z1 = H - (TOP if node.one("countertop") else 0.0)  # carcass top
        self.add("carcass", "body", panels.carcass(W, D, z0, z1, t, "body"))
        for extra in ("plinth", "countertop"):
            if node.one(extra):
                self.grow(node.one(extra), z=(z0, z1))
        cols = node.of("column")
        spans = cells(-W / 2 + t, W / 2 - t, len(cols), gap=t)
        for c, (col, (ya, yb)) in enumerate(zip(cols, spans)):
            if c < len(cols) - 1:  # divider to the right of this column
                self.extend("carcass", [g.box_between([-D / 2 + t * 0.5, yb, z0 + t], [D / 2, yb + t, z1 - t], "body")])
            # the front of a column covers the opening plus half of each bordering board
            fy = (ya - t / 2 + GAP / 2 if c > 0 else -W / 2 + GAP,
                  yb + t / 2 - GAP / 2 if c < len(cols) - 1 else W / 2 - GAP)
            self.grow(col, c=c, n=len(cols), ys=(ya, yb), fys=fy, zs=(z0 + t, z1 - t), fzs=(z0 + GAP, z1 - GAP))

    def plinth(self, node, z):
        D, W = self.p["depth"], self.p["width"]
        kick = g.box_between([-D / 2 + 0.02, -W / 2 + 0.01, 0], [D / 2 - 0.05, W / 2 - 0.01, z[0]], "plinth")
        self.extend("carcass", [kick])

    def countertop(self, node, z):
        D, W = self.p["depth"], self.p["width"]
        top = g.box_between([-D / 2, -W / 2 - 0.005, z[1]], [D / 2 + 0.03, W / 2 + 0.005, self.p["height"]], "top",
                            bevel=0.004)
        self.extend("carcass", [top])

    def column(self, node, **where):
        self.grow(node.one(node.choice), **where)

    def shelf(self, node, c, n, ys, fys, zs, fzs):
        D, t = self.p["depth"], self.p["board"]
        k = 1 + int(self.rng.integers(1, 3))
        self.extend("carcass", [panels.shelf((-D / 2, D / 2), ys, zs[0] + (zs[1] - zs[0]) * i / 3, t, "body")
                                for i in range(1, k)])

    def _handle(self, length: float):
        style = self.p["handle_style"]
        if style == "bar":
            return hardware.bar_handle(length, "handle")
        if style == "knob":
            return hardware.knob_handle(0.015, 0.025, "handle")
        return hardware.edge_pull(length, "handle")

    def drawers(self, node, c, n, ys, fys, zs, fzs):
        kids = node.of("drawer")
        for r, kid in enumerate(kids):
            self.grow(kid, c=c, r=r, rows=len(kids), ys=ys, fys=fys, zs=zs, fzs=fzs)

    def drawer(self, node, c, r, rows, ys, fys, zs, fzs):
        p = self.p
        D, t, ft = p["depth"], p["board"], p["front_thickness"]
        xf = D / 2
        row_h, inner_row = (fzs[1] - fzs[0]) / rows, (zs[1] - zs[0]) / rows
        clear = max(0.004, 0.02 * min(ys[1] - ys[0], inner_row))
        fz0 = fzs[0] + r * row_h + GAP / 2
        fz1 = fz0 + row_h - GAP
        # the box stays above the front of the drawer below, or pulling it drags that one along
        bz0 = max(zs[0] + r * inner_row + clear, fz0)
        bz1 = zs[0] + (r + 1) * inner_row - clear - 0.01
        box = (-D / 2 + t + clear, xf - 0.002, ys[0] + clear, ys[1] - clear, bz0, bz1)
        pieces = panels.box_drawer((xf + GAP, xf + GAP + ft, *fys, fz0, fz1), box, DRAWER_WALL, "front", "body")
        if p["has_handles"]:
            at = Frame.at((xf + GAP + ft, sum(fys) / 2, (fz0 + fz1) / 2 + 0.25 * (fz1 - fz0)), z=(1, 0, 0), x=(0, 1, 0))
            h = self._handle(min(0.6 * (fys[1] - fys[0]), 0.35)).attached("mount", to=at)
            pieces += list(h.parts[h.root].pieces)
        name = self.add(f"drawer_{c}_{r}", "drawer", pieces)
        self.slide("carcass", name, Frame.at((xf, sum(fys) / 2, fz0), z=(1, 0, 0)),
                   upper=p["drawer_travel"] * (box[1] - box[0]))

    def doors(self, node, c, n, ys, fys, zs, fzs):
        D, t = self.p["depth"], self.p["board"]
        self.extend("carcass", [panels.shelf((-D / 2, D / 2), ys, (zs[0] + zs[1]) / 2, t, "body")])
        kids = node.of("door")
        mid = sum(fys) / 2
        if len(kids) == 2:  # double doors, hinged at both outer edges
            spec = [(fys[0], mid - GAP / 2, "left"), (mid + GAP / 2, fys[1], "right")]
        else:  # one leaf, hinged on the side facing the nearer end of the cabinet
            spec = [(fys[0], fys[1], "left" if c < n / 2 else "right")]
        for k, (kid, leaf) in enumerate(zip(kids, spec, strict=True)):
            self.grow(kid, name=f"door_{c}_{k}", leaf=leaf, fzs=fzs)

    def door(self, node, name, leaf, fzs):
        p = self.p
        ya, yb, side = leaf
        xf, ft = p["depth"] / 2 + GAP, p["front_thickness"]
        pieces = [g.box_between([xf, ya, fzs[0]], [xf + ft, yb, fzs[1]], "front", bevel=0.002)]
        h = fzs[1] - fzs[0]
        if p["has_handles"]:
            hz = fzs[0] + (0.8 if h < 0.9 else 0.6) * h
            at = Frame.at((xf + ft, yb - 0.05 if side == "left" else ya + 0.05, hz), z=(1, 0, 0), x=(0, 0, 1))
            handle = self._handle(min(0.3 * h, 0.3)).attached("mount", to=at)
            pieces += list(handle.parts[handle.root].pieces)
        self.add(name, "door", pieces)
        # on the front face at the outer edge; the axis sign makes it swing out (+X)
        hinge = Frame.at((xf + ft, ya if side == "left" else yb, fzs[0]), z=(0, 0, -1 if side == "left" else 1))
        self.hinge("carcass", name, hinge, upper=p["door_angle"])


CATEGORY = Category("kitchen_cabinet", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, CabinetLayout, MATERIALS)
