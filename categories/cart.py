"""Cart: a utility cart, a shopping trolley, a hand truck or a serving trolley, on casters or wheels.

Designs (``design``): a utility cart carries two or three moulded tray shelves on four posts; a shopping trolley a
wire basket on a chassis, maybe with a child-seat flap hung inside the basket's back that folds down into a seat;
a serving trolley a top with a drawer under it and a lower shelf, maybe with drop leaves hung at its sides. These
three roll on four casters: all four swivel, or two swivel at the handle end and two rigid ones at the front
(``caster_plan``); a swivel caster's fork turns about its stem and its wheel about its axle, a rigid caster's
wheel only. A hand truck stands on two wheels on a fixed axle and a toe plate that folds up; its loop handle may
slide up out of the frame (a telescoping handle). Parts: ``categories/parts/carts.py``,
the casters ``seating.caster``.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import carts as C
from .parts import seating as S

GRAMMAR = Grammar("cart", {
    "cart": Node(label="body", one_of={"utility_cart": 0.3, "shopping_trolley": 0.25, "hand_truck": 0.2,
                                       "serving_trolley": 0.25}, choice="design"),
    "utility_cart": Node(required=("casters",)),
    "shopping_trolley": Node(required=("casters",), optional={"child_seat": 0.8}),
    "hand_truck": Node(required=("truck_wheels", "toe_plate"), optional={"extension": 0.4}),
    "serving_trolley": Node(required=("casters", "drawer"), repeat={"leaf": (0, 2)}),
    "casters": Node(one_of={"four_swivel": 0.5, "two_swivel": 0.5}, choice="caster_plan"),
    "four_swivel": Node(repeat={"swivel_caster": 4}),
    "two_swivel": Node(repeat={"swivel_caster": 2, "rigid_caster": 2}),
    "swivel_caster": Node(label="caster", required=("caster_wheel",)),
    "caster_wheel": Node(label="wheel"),
    "rigid_caster": Node(label="wheel"),
    "child_seat": Node(label="seat"),
    "truck_wheels": Node(repeat={"truck_wheel": 2}),
    "truck_wheel": Node(label="wheel"),
    "toe_plate": Node(label="toe_plate"),
    "extension": Node(label="handle"),
    "drawer": Node(label="drawer"),
    "leaf": Node(label="leaf"),
})
"""Designs: utility cart (2-3 shelves), shopping trolley (maybe a child-seat flap), hand truck (maybe with a telescoping
handle), serving trolley (a drawer, 0-2 drop leaves). Casters: four swivel, or two swivel
at the handle end and two rigid at the front (``caster_plan``)."""

PARAMS = (
    Float("length_share", "length (X) within the design's range (SIZES in parts/carts.py), 0 to 1", "", 0.0, 1.0),
    Float("width_share", "width (Y) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("height_share", "height (Z) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("wheel_share", "caster or wheel radius within the design's range (CASTER_RADIUS, TRUCK), 0 to 1", "",
          0.0, 1.0),
    Choice("shelves", "a utility cart's shelf count", choices=("2", "3")),
    Choice("frame_finish", "a utility cart's or a hand truck's frame: painted steel or plastic",
           choices=("enamel", "plastic")),
    Choice("board_finish", "a serving trolley's boards: wood or painted", choices=("wood", "painted")),
)

MATERIALS = {"frame": ("frame_finish", {"plastic": "plastic:black|dark_grey|light_grey|blue|red"}),
             "tray": "plastic:black|dark_grey|light_grey|blue|red|yellow|white", "wire": "chrome",
             "board": "board_finish", "legs": "brushed_metal", "trim": "plastic:black|dark_grey|red|blue",
             "caster": "plastic:black|dark_grey", "wheel": "rubber", "hub": "plastic:light_grey|dark_grey|red|yellow",
             "seat": "plastic:red|blue|green|dark_grey", "handle": "brushed_metal"}

LEAF_TURN = math.radians(90)
LEAF = 0.2  # m, a drop leaf's width (tea trolleys: 18-25 cm leaves)


class CartLayout(Layout):
    def cart(self, node):
        p, design = self.p, node.choice
        shares = (p["length_share"], p["width_share"], p["height_share"])
        sub = node.one(design)
        self.design = design
        if design == "hand_truck":
            size = C.cart_size(design, shares, 0.0)
            self.truck = C.truck(size, p["wheel_share"])
            loop = not sub.one("extension")  # an extension handle replaces the fixed loop
            self.add("body", "body", C.truck_frame(size, self.truck, "frame", "trim", loop))
            self.size = size
        else:
            lo, hi = C.CASTER_RADIUS[design]
            self.caster = S.caster("single", lo + p["wheel_share"] * (hi - lo))
            z0 = self.caster.stem_top + C.PLATE["thick"]
            size = self.size = C.cart_size(design, shares, z0)
            inset = max(self.caster.footprint, 0.045)
            self.tips = C.corner_tips(size, inset)
            pieces = C.caster_plates(self.tips, self.caster.stem_top, "caster")
            if design == "utility_cart":
                pieces += C.utility_frame(size, int(p["shelves"]), self.tips, "tray", "frame")
            elif design == "shopping_trolley":
                pieces += C.trolley_frame(size, self.tips, "wire", "trim")
            else:
                pieces += C.serving_frame(size, self.tips, "board", "legs")
            self.add("body", "body", pieces)
        self.grow(sub)

    def _design(self, node):
        for child in node.children:
            self.grow(child)

    utility_cart = shopping_trolley = hand_truck = _design

    def casters(self, node):
        self.grow(node.one(node.choice))

    def four_swivel(self, node):
        # the handle end's casters swivel; on a two-swivel plan the front pair are rigid
        kids = node.of("swivel_caster")[::-1] + node.of("rigid_caster")
        for n, tip in zip(kids, self.tips[::-1], strict=True):
            self.grow(n, tip=tip)

    two_swivel = four_swivel

    def swivel_caster(self, node, tip):
        name = f"caster_{len([j for j in self.bp.joints if j.role == 'swivel'])}"
        fork = self.place(S.fork(self.caster).placed(tip), name)
        self.spin("body", fork.root, fork.anchor("swivel"), role="swivel")
        self.grow(node.one("caster_wheel"), fork=fork.root, tip=tip)

    def caster_wheel(self, node, fork, tip):
        wheel = self.place(S.wheels(self.caster)[0].mounted(tip), f"wheel_{len(self.bp.parts)}")
        self.spin(fork, wheel.root, wheel.anchor("axle"), role="wheel")

    def rigid_caster(self, node, tip):
        # a rigid caster: the fork bolted to the frame, its wheel rolling straight ahead (the axle across x)
        tip = Frame.at(tip.origin, x=(0, 1, 0), z=(0, 0, 1))
        self.extend("body", S.fork(self.caster).placed(tip).pieces)
        self.caster_wheel(node, "body", tip)

    def child_seat(self, node):
        made = self.place(C.flap(self.size, "seat"), "child_seat")
        self.hinge("body", made.root, made.anchor("hinge"), upper=C.FLAP_TURN)

    def truck_wheels(self, node):
        for n, side in zip(node.of("truck_wheel"), (-1, 1), strict=True):
            self.grow(n, side=side)

    def truck_wheel(self, node, side):
        made = self.place(C.truck_wheel(self.truck, side, "wheel", "hub"), f"wheel_{(side + 1) // 2}")
        self.spin("body", made.root, made.anchor("axle"), role="wheel")

    def toe_plate(self, node):
        made = self.place(C.toe_plate(self.size, self.truck, "frame"), "toe_plate")
        self.hinge("body", made.root, made.anchor("hinge"), upper=C.TOE_TURN)

    def extension(self, node):
        self.extend("body", C.extension_guides(self.size, self.truck, "frame"))
        made = self.place(C.extension(self.size, self.truck, "frame", "trim"), "handle")
        self.slide("body", made.root, made.anchor("slide"), upper=C.TRUCK["extends"], role="telescope")

    def drawer(self, node):
        made = self.place(C.drawer(self.size, "board", "handle"), "drawer")
        self.slide("body", made.root, made.anchor("slide"), upper=0.75 * (self.size.length - 0.12))

    def leaf(self, node, side):
        made = self.place(C.leaf(self.size, side, LEAF, "board"), f"leaf_{(side + 1) // 2}")
        self.hinge("body", made.root, made.anchor("hinge"), upper=LEAF_TURN)

    def serving_trolley(self, node):
        self.grow(node.one("casters"))
        self.grow(node.one("drawer"))
        for n, side in zip(node.of("leaf"), (1, -1)):
            self.grow(n, side=side)


CATEGORY = Category("cart", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, CartLayout, MATERIALS)
