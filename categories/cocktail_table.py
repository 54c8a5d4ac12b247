"""Cocktail (coffee) table: a round or square top on legs or on a single pedestal stand.

X is depth (the front faces +X), Y is width, Z is up. The top is a bevelled slab, round or
square, ``width`` across. On legs (3 or 4; a square top has 4) under an apron, with an optional
lower shelf, the table either has a lift-top — the legs and apron form a storage box and the top
rises off the apron rim along +Z, or tilted toward the front as a scissor lift-top does — or
telescopic legs: metal sleeves on the floor with posts sliding up in them, carrying the top and
the apron (height adjustment). On a pedestal, a column carrying the top slides up out of a tube
on a base disc and turns in it (revolute_prismatic). Every slide rests at its bottom.
Parts: ``categories/parts/tables.py``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import tables as T

GRAMMAR = Grammar("cocktail_table", {
    "cocktail_table": Node(required=("top",), one_of={"legs": 0.6, "pedestal": 0.4}, choice="support"),
    "top": Node(label=("top", "lid")),  # a lift-top is the lid of a storage box
    "legs": Node(label="body", optional={"shelf": 0.4, "lift_top": 0.55}),
    "lift_top": Node(),
    "shelf": Node(),
    "pedestal": Node(label="stand"),
})
"""``shelf`` and ``lift_top`` grow on a legged table; without a lift-top its legs are telescopic."""

PARAMS = (
    Float("width", "top diameter (round) or side (square)", "m", 0.5, 1.0),
    Float("height", "overall height at rest", "m", 0.4, 0.75),
    Choice("top_shape", "shape of the top", choices=("round", "square")),
    Float("top_thickness", "thickness of the top", "m", 0.02, 0.045),
    Float("bevel", "bevel of the top's edges, as a fraction of its thickness", "", 0.1, 0.4),
    Int("leg_count", "legs under a round top (a square top has 4); auto = drawn 3 or 4", "", 3, 4, auto=True),
    Choice("leg_style", "shape of fixed legs", choices=("turned", "tapered", "square"), weights=(0.35, 0.4, 0.25)),
    Float("leg_radius", "leg radius (half side of a square leg) at its top", "m", 0.015, 0.03),
    Float("leg_inset", "distance of the leg centres in from the top's edge", "m", 0.05, 0.12),
    Float("apron_height", "height of the apron under the top", "m", 0.05, 0.11),
    Float("shelf_height", "lower shelf height as a fraction of the height", "", 0.12, 0.3),
    Float("lift_travel", "how far a lift-top rises", "m", 0.12, 0.25),
    Flag("has_lift_forward", "a lift-top rises toward the front (scissor mechanism)", p=0.5),
    Float("lift_forward_ratio", "forward (+X) over upward motion of a forward lift-top", "", 0.3, 0.8),
    Float("stand_travel", "how far telescopic legs or a pedestal column extend", "m", 0.06, 0.18),
    Float("stand_turn", "turn limit (+-) of a pedestal top", "rad", math.pi / 2, math.pi),
    Float("base_radius", "pedestal base radius as a fraction of the width", "", 0.3, 0.42),
    Float("column_radius", "pedestal inner column radius", "m", 0.025, 0.045),
    Choice("top_finish", "material of the top", choices=("wood", "painted", "glass"), weights=(0.55, 0.25, 0.2)),
    Choice("frame_finish", "material of the legs and apron", choices=("wood", "painted", "brushed_metal"),
           weights=(0.5, 0.3, 0.2)),
    Choice("metal_finish", "sleeves, column and pedestal base", choices=("brushed_metal", "chrome", "painted")),
)

MATERIALS = {"top": "top_finish", "frame": "frame_finish", "metal": "metal_finish", "foot": "rubber"}

SEAT = 0.003  # a lift-top rests this far above the apron rim
INSET_MAX = 0.2  # leg inset as a fraction of the width at most
SLEEVE_TOP = 0.7  # telescopic sleeves end at this fraction of the apron's bottom height
TUBE_TOP = 0.55  # a pedestal tube ends at this fraction of the top's underside height
POST = 0.75  # telescopic post radius as a fraction of the leg radius
STRETCHER_Z = 0.06


class TableLayout(Layout):
    def cocktail_table(self, node):
        carried = self.grow(node.one(node.choice))
        self.grow(node.one("top"), **carried)

    def top(self, node, pieces, joint, label="top"):
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        slab = T.top(W, W, p["top_shape"], H - tt, H, p["bevel"] * tt, "top")
        self.add("top", label, [slab, *pieces])
        self.join(joint)

    def legs(self, node):
        p = self.p
        W, H, tt, shape = p["width"], p["height"], p["top_thickness"], p["top_shape"]
        n = 4 if shape == "square" else (p["leg_count"] or int(self.rng.integers(3, 5)))
        inset = min(p["leg_inset"], INSET_MAX * W)
        frames = T.leg_frames(W, shape, inset, n)
        lift = node.one("lift_top")
        rl = p["leg_radius"]
        za1 = H - tt - (SEAT if lift else 0.0)
        za0 = za1 - p["apron_height"]
        apron = T.apron(W, shape, inset, rl, za0, za1, "frame")
        if lift:
            body = apron + [pc.transformed(f.matrix) for f in frames for pc in T.leg(p["leg_style"], rl, za1, "frame")]
            self.add("body", "body", body)
            self.grow(lift, inset=inset, z=za0)
            if node.one("shelf"):
                self.grow(node.one("shelf"), inset=inset, r_leg=0.8 * rl, z=p["shelf_height"] * H)
            fwd = p["lift_forward_ratio"] if p["has_lift_forward"] else 0.0
            at = Frame.at((0, 0, H - tt), z=(fwd, 0, 1))
            return {"pieces": [], "label": "lid",
                    "joint": J.prismatic("body", "top", at.origin, at.z, 0.0, p["lift_travel"], role="slide")}
        # telescopic: sleeves stay, the top lifts with its apron and posts
        rp = POST * rl
        ro = rp + T.CLEAR + T.WALL
        zs1 = SLEEVE_TOP * za0
        travel = min(p["stand_travel"], zs1 - 0.1)
        zp0 = zs1 - travel - 0.05  # post bottom at rest
        self.add("body", "body", [pc.transformed(f.matrix) for f in frames
                                  for pc in T.round_sleeve(ro, zs1, "metal", "foot")])
        if node.one("shelf"):
            self.grow(node.one("shelf"), inset=inset, r_leg=ro, z=min(p["shelf_height"] * H, zs1 - 0.04))
        else:
            self.extend("body", T.stretchers(frames, STRETCHER_Z, ro, "metal", square=shape == "square"))
        posts = [g.cylinder(f.point((0, 0, zp0)), f.point((0, 0, za1)), rp, "metal", 32) for f in frames]
        at = Frame.at((0, 0, zs1))
        return {"pieces": apron + posts,
                "joint": J.prismatic("body", "top", at.origin, at.z, 0.0, travel, role="telescope")}

    def lift_top(self, node, inset, z):
        p = self.p
        self.extend("body", [T.apron_bottom(p["width"], p["top_shape"], inset, p["leg_radius"], z, "frame")])

    def shelf(self, node, inset, r_leg, z):
        self.extend("body", [T.shelf(self.p["width"], self.p["top_shape"], inset, r_leg, z, "top")])

    def pedestal(self, node):
        p = self.p
        W, H, tt = p["width"], p["height"], p["top_thickness"]
        rc = p["column_radius"]
        ro = rc + T.CLEAR + T.WALL
        base, zb = T.pedestal_base(p["base_radius"] * W, ro, "metal")
        zt1 = TUBE_TOP * (H - tt)
        travel = min(p["stand_travel"], zt1 - zb - 0.08)
        self.add("body", "stand", base + T.column_tube(ro, zb - 0.002, zt1, "metal"))
        zs = H - tt  # underside of the top
        column = [g.cylinder([0, 0, zt1 - travel - 0.06], [0, 0, zs - 0.012], rc, "metal", 48),
                  g.cylinder([0, 0, zs - 0.012], [0, 0, zs], min(0.35 * W, 0.2), "metal", 48)]  # mounting plate
        at = Frame.at((0, 0, zt1))
        return {"pieces": column, "joint": J.revolute_prismatic(
            "body", "top", at.origin, at.z, (-p["stand_turn"], p["stand_turn"]), at.z, (0.0, travel),
            role="telescope")}


CATEGORY = Category("cocktail_table", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TableLayout, MATERIALS)
