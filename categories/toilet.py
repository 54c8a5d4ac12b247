"""Toilet: a close-coupled ceramic toilet with a seat, a cover, a cistern with a lift-off lid and a flush.

X is depth (the bowl faces +X, the cistern is at -X), Y is width, Z is up. The ceramic base is an
oval bowl (a thin wall of revolution, hollow for the simulator) with a flat rim, on a pedestal,
with a rear deck that carries the cistern. The cistern (``tank``) is a hollow box of five walls;
its lid rests on them with a locating lip and lifts straight up (0..0.2 m). Seat and cover share
one hinge line at the back: the seat turns about -Y (its front lifts), the cover is the seat's
child on the same line and only turns away from it. They declare a common mechanical maximum of
half a turn, split by ``cover_share``; the core stops the cover where it leans on the cistern.
The flush is a push button on the cistern front or a side trip lever on its left wall (balanced
by the core's counterweight heel). Parts: ``categories/parts/sanitary.py``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import sanitary as S

GRAMMAR = Grammar("toilet", {
    "toilet": Node(label="body", required=("tank", "seat")),
    "seat": Node(label="seat", required=("cover",)),
    "cover": Node(label="lid"),
    "tank": Node(label="tank", required=("tank_lid",), one_of={"button": 0.5, "lever": 0.5}, choice="flush"),
    "tank_lid": Node(label="lid"),
    "button": Node(label="button"),
    "lever": Node(label="lever"),
})

PARAMS = (
    Float("seat_height", "height of the seat top above the floor (the toilet's size)", "m", 0.40, 0.50),
    Float("bowl_width", "outer width of the rim (Y)", "m", 0.34, 0.40),
    Float("bowl_length", "outer length of the rim (X)", "m", 0.40, 0.48),
    Float("wall", "ceramic wall thickness of the bowl", "m", 0.010, 0.016),
    Float("tank_width", "cistern width (Y)", "m", 0.38, 0.50),
    Float("tank_depth", "cistern depth (X)", "m", 0.15, 0.21),
    Float("tank_height", "cistern height incl. the lid", "m", 0.30, 0.40),
    Float("tank_gap", "distance from the hinge line back to the cistern front", "m", 0.06, 0.10),
    Float("seat_thickness", "seat ring thickness", "m", 0.018, 0.03),
    Float("seat_ring", "seat ring width at the sides", "m", 0.055, 0.08),
    Float("cover_thickness", "cover thickness", "m", 0.012, 0.025),
    Float("lid_thickness", "cistern lid thickness", "m", 0.018, 0.03),
    Float("cover_share", "the cover's share of the common opening angle (the seat gets the rest)", "", 0.5, 0.65),
    Float("button_radius", "flush button radius", "m", 0.018, 0.03),
    Float("lever_length", "trip lever grip length", "m", 0.06, 0.09),
    Choice("ceramic_colour", "ceramic colour", choices=("white", "cream", "ivory"), weights=(0.7, 0.15, 0.15)),
    Choice("seat_finish", "seat and cover material", choices=("plastic", "wood"), weights=(0.75, 0.25)),
)

MATERIALS = {"ceramic": ("ceramic_colour", {c: f"ceramic:{c}" for c in ("white", "cream", "ivory")}),
             "seat": ("seat_finish", {"plastic": "plastic:white|light_grey|black"}), "chrome": "chrome",
             "rubber": "rubber"}

LID_LIFT = 0.2  # the cistern lid lifts 0..0.2 m
PRESS = 0.006  # flush button travel
LEVER_TURN = math.pi / 4
TAB = 0.035  # the seat's rear tab, from the rim's back to the hinge line
FLUSH_BELOW = 0.06  # the flush control sits this far below the cistern's top


class ToiletLayout(Layout):
    def toilet(self, node):
        p = self.p
        a, b = p["bowl_length"] / 2, p["bowl_width"] / 2
        z_r = p["seat_height"] - p["seat_thickness"] - S.GAP  # rim top
        z_h = z_r + S.GAP + p["seat_thickness"]  # hinge line: the seat's top rear edge
        TD, TW = p["tank_depth"], p["tank_width"]
        x_front = (2 * a + TAB + p["tank_gap"] + TD) / 2
        x_c = x_front - a  # bowl axis
        x_h = x_c - a - TAB  # hinge line
        x_tf = x_h - p["tank_gap"]  # cistern front face
        tab_w = 0.34 * b
        geo = dict(a=a, b=b, z_r=z_r, x_c=x_c, hinge=(x_h, z_h), tab_w=tab_w)
        deck = (x_tf - TD + 0.02, x_c - 0.75 * a, min(0.75 * TW, 1.3 * b))
        self.add("base", "body", S.ceramic_base(a, b, p["wall"], z_r, x_c, deck, tab_w, (x_h, z_h)))
        self.grow(node.one("tank"), xs=(x_tf - TD, x_tf), ys=(-TW / 2, TW / 2), z0=z_r)
        self.grow(node.one("seat"), **geo)

    def tank(self, node, xs, ys, z0):
        p = self.p
        z1 = z0 + p["tank_height"] - p["lid_thickness"] - S.GAP  # top of the walls
        zf = z1 - FLUSH_BELOW
        rb = p["button_radius"]
        holes = [(-rb - S.CLEAR, zf - rb - S.CLEAR, rb + S.CLEAR, zf + rb + S.CLEAR)] if node.choice == "button" else []
        self.add("tank", "tank", S.cistern(xs, ys, z0, z1, holes))
        self.fix("base", "tank")
        self.grow(node.one("tank_lid"), xs=xs, ys=ys, z=z1 + S.GAP)
        self.grow(node.one(node.choice), xs=xs, ys=ys, z=zf)

    def tank_lid(self, node, xs, ys, z):
        self.add("tank_lid", "lid", S.cistern_lid(xs, ys, z, self.p["lid_thickness"]))
        self.slide("tank", "tank_lid", Frame.at((xs[1], 0.0, z)), upper=LID_LIFT, role="lid")

    def button(self, node, xs, ys, z):
        rb, x_tf = self.p["button_radius"], xs[1]
        self.extend("tank", [S.flush_ring(S.on_face(x_tf, z), rb)])
        self.add("flush_button", "button", S.flush_button(x_tf, S.CISTERN_WALL + 0.004, z, rb))
        self.slide("tank", "flush_button", Frame.at((x_tf + 0.0125, 0.0, z), z=(-1, 0, 0)), upper=PRESS, role="button")

    def lever(self, node, xs, ys, z):
        # on the left (-Y) wall near the front; its grip points forward, behind the cistern front
        length = self.p["lever_length"]
        xa = xs[1] - length - 0.012
        y_in = ys[0] - 0.006 - S.GAP  # the lever's inner face, off the rose
        self.extend("tank", [g.cylinder([xa, ys[0], z], [xa, ys[0] - 0.006, z], 0.02, "chrome", 32)])
        self.add("flush_lever", "lever", S.trip_lever(xa, y_in, z, length))
        # pressing the grip (+X of the axis) down: about +Y
        self.hinge("tank", "flush_lever", Frame.at((xa, y_in, z), z=(0, 1, 0)), upper=LEVER_TURN, role="button")

    def seat(self, node, a, b, z_r, x_c, hinge, tab_w):
        p = self.p
        a_s, b_s = a + 0.002, b + 0.002
        x_h, z_h = hinge
        self.add("seat", "seat", S.seat(a_s, b_s, x_c, z_r + S.GAP, p["seat_thickness"], p["seat_ring"],
                                        (x_h, x_c - a_s + 0.03, tab_w)))
        # the two leaves turn at most half a turn together, split by cover_share; the core stops them
        # where the cover leans on the cistern
        cover_up = p["cover_share"] * math.pi
        line = Frame.at((x_h, 0.0, z_h), z=(0, -1, 0))
        self.hinge("base", "seat", line, upper=math.pi - cover_up)
        self.grow(node.one("cover"), a=a_s + 0.004, b=b_s + 0.004, x_c=x_c, line=line, upper=cover_up, tab_w=tab_w)

    def cover(self, node, a, b, x_c, line, upper, tab_w):
        x_h, z_h = line.origin[0], line.origin[2]
        tab = (x_h, x_c - a + 0.03, tab_w)
        self.add("cover", "lid", S.cover(a, b, x_c, z_h + S.GAP, self.p["cover_thickness"], tab))
        self.hinge("seat", "cover", line, upper=upper)


CATEGORY = Category("toilet", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToiletLayout, MATERIALS)
