"""Toilet: close-coupled, one-piece, back-to-wall or wall-hung, with a seat, a cover and a flush.

Designs (``design``): close-coupled and one-piece toilets carry a cistern (below); a back-to-wall pan
stands against a furniture unit and a wall-hung pan hangs off a boxed-in frame, each with a dual-flush
plate (two keys pressed in). Parts for them: ``sanitary.skirted_base``, ``hung_base``, ``flush_plate``.

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

from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import lids as L
from .parts import sanitary as S

GRAMMAR = Grammar("toilet", {
    "toilet": Node(label="body", required=("seat",), one_of={"close_coupled": 0.35, "one_piece": 0.2,
                                                             "back_to_wall": 0.25, "wall_hung": 0.2}, choice="design"),
    "close_coupled": Node(required=("tank",)),
    "one_piece": Node(required=("tank",)),
    "back_to_wall": Node(required=("unit",)),
    "wall_hung": Node(required=("prewall",)),
    "unit": Node(label="cabinet", required=("flush_plate",)),
    "prewall": Node(label="frame", required=("flush_plate",)),
    "flush_plate": Node(repeat={"flush_key": 2}),
    "flush_key": Node(label="button"),
    "seat": Node(label="seat", required=("cover",)),
    "cover": Node(label="lid"),
    "tank": Node(label="tank", required=("tank_lid",), one_of={"button": 0.4, "lever": 0.3, "dual": 0.3},
                 choice="flush"),
    "tank_lid": Node(label="lid"),
    "button": Node(label="button"),
    "lever": Node(label="lever"),
    "dual": Node(repeat={"flush_key": 2}),
})
"""Designs: close-coupled (a cistern on the pan's deck), one-piece (a low cistern on a skirted pan),
back-to-wall (a skirted pan against a furniture unit hiding the cistern; dual-flush plate on the unit),
wall-hung (the pan bolted to a boxed-in frame, off the floor; dual-flush plate on the frame). A cistern
flushes by a front button, a side trip lever or two front buttons (dual flush: small and large; pressed
horizontally, so gravity does not press them)."""

PARAMS = (
    Float("seat_height", "height of the seat top above the floor (the toilet's size)", "m", *S.RANGES.seat_height),
    Float("bowl_width", "outer width of the rim (Y)", "m", *S.RANGES.bowl_width),
    Float("bowl_length", "outer length of the rim (X)", "m", *S.RANGES.bowl_length),
    Float("wall", "ceramic wall thickness of the bowl", "m", *S.RANGES.wall),
    Float("tank_width", "cistern width (Y)", "m", *S.RANGES.tank_width),
    Float("tank_depth", "cistern depth (X)", "m", *S.RANGES.tank_depth),
    Float("tank_height", "cistern height incl. the lid", "m", *S.RANGES.tank_height),
    Float("tank_gap", "distance from the hinge line back to the cistern front", "m", *S.RANGES.tank_gap),
    Float("seat_thickness", "seat ring thickness", "m", *S.RANGES.seat_thickness),
    Float("seat_ring", "seat ring width at the sides", "m", *S.RANGES.seat_ring),
    Float("cover_thickness", "cover thickness", "m", *S.RANGES.cover_thickness),
    Float("lid_thickness", "cistern lid thickness", "m", *S.RANGES.lid_thickness),
    Float("cover_share", "the cover's share of the common opening angle (the seat gets the rest)", "",
          *S.RANGES.cover_share),
    Float("button_radius", "flush button radius", "m", *S.RANGES.button_radius),
    Float("lever_length", "trip lever grip length", "m", *S.RANGES.lever_length),
    Float("one_piece_tank", "a one-piece cistern's height as a fraction of tank_height", "", *S.RANGES.one_piece_tank),
    Float("unit_height", "height of a back-to-wall furniture unit", "m", *S.RANGES.unit_height),
    Float("unit_depth", "depth of a back-to-wall unit or of a wall-hung pan's boxed frame", "m", *S.RANGES.unit_depth),
    Float("unit_width", "width of the unit or the boxed frame", "m", *S.RANGES.unit_width),
    Float("frame_height", "height of a wall-hung pan's boxed frame (its flush plate 0.12-0.2 m below the top)",
          "m", *S.RANGES.frame_height),
    Float("hung_seat_height", "seat height of a wall-hung pan (installed height)", "m", *S.RANGES.hung_seat_height),
    Choice("ceramic_colour", "ceramic colour", choices=("white", "cream", "ivory"), weights=(0.7, 0.15, 0.15)),
    Choice("seat_finish", "seat and cover material", choices=("plastic", "wood"), weights=(0.75, 0.25)),
)

MATERIALS = {"ceramic": ("ceramic_colour", {c: f"ceramic:{c}" for c in ("white", "cream", "ivory")}),
             "seat": ("seat_finish", {"plastic": "plastic:white|light_grey|black"}), "chrome": "chrome",
             "rubber": "rubber", "wall": "painted:white|off_white|light_grey",
             "unit": "painted:white|light_grey|charcoal|sage|navy", "top": "wood"}


CISTERNS = ("close_coupled", "one_piece")


class ToiletLayout(Layout):
    def toilet(self, node):
        p = self.p
        design = node.choice
        seat_h = p["hung_seat_height"] if design == "wall_hung" else p["seat_height"]
        size = S.PanSize(p["bowl_length"], p["bowl_width"], p["wall"], seat_h, p["seat_thickness"], p["seat_ring"],
                         p["cover_thickness"], p["tank_gap"])
        tall = p["tank_height"] * (p["one_piece_tank"] if design == "one_piece" else 1.0)
        tank = S.CisternSize(p["tank_width"], p["tank_depth"], tall, p["lid_thickness"])
        rear = tank.depth if design in CISTERNS else p["unit_depth"]
        pan = self.place(S.pan(design, size, tank, rear).attached("centre", to=IDENTITY), "base")
        self.grow(node.one(design), pan=pan, tank=tank)
        self.grow(node.one("seat"), pan=pan, size=size)

    def close_coupled(self, node, **where):
        self.grow(node.one("tank"), **where)

    def one_piece(self, node, **where):  # a low cistern on the skirt's back block, as wide as it
        self.grow(node.one("tank"), **where)

    def back_to_wall(self, node, pan, tank):
        p = self.p
        self.grow(node.one("unit"), pan=pan, size=S.BoxSize(p["unit_depth"], p["unit_width"], p["unit_height"]))

    def wall_hung(self, node, pan, tank):
        p = self.p
        self.grow(node.one("prewall"), pan=pan, size=S.BoxSize(p["unit_depth"], p["unit_width"], p["frame_height"]))

    def unit(self, node, pan, size):
        unit = self.place(S.furniture_unit(size).attached("mount", to=pan.anchor("wall")), "unit")
        self.fix("base", "unit")
        self.grow(node.one("flush_plate"), part="unit", at=unit.anchor("plate"))

    def prewall(self, node, pan, size):
        frame = self.place(S.boxed_frame(size).attached("mount", to=pan.anchor("wall")), "prewall")
        self.fix("base", "prewall")
        self.grow(node.one("flush_plate"), part="prewall", at=frame.anchor("plate"))

    def flush_plate(self, node, part, at):
        plate = S.flush_plate().attached("mount", to=at)
        self.extend(part, plate.parts["plate"].pieces)
        for kid, side in zip(node.of("flush_key"), ("small", "large"), strict=True):
            self.grow(kid, part=part, side=side, pieces=plate.parts[side].pieces, at=at)

    def flush_key(self, node, part, side, pieces, at):
        # a flush-plate key is chrome-plated plastic like the round buttons (S.BUTTON_WALL)
        name = self.add(f"flush_{side}", "button", [pc.replace(wall=S.BUTTON_WALL) for pc in pieces])
        self.slide(part, name, S.key_press(pieces, at), upper=S.PRESS, role="button")

    def tank(self, node, pan, tank):
        rb = self.p["button_radius"]
        buttons = {"button": (0.0,), "dual": S.DUAL_Y(rb)}.get(node.choice, ())
        cistern = self.place(S.cistern(tank, buttons, rb).attached("mount", to=pan.anchor("back")), "tank")
        self.fix("base", "tank")
        self.grow(node.one("tank_lid"), cistern=cistern, tank=tank)
        self.grow(node.one(node.choice), cistern=cistern)

    def tank_lid(self, node, cistern, tank):
        lid = self.place(S.cistern_lid(tank).attached("seat", to=cistern.anchor("lid_seat")), "tank_lid")
        self.join(L.seat_joint("tank", lid, S.LID_LIFT, turns=False))

    def dual(self, node, cistern):
        at, rb = cistern.anchor("flush"), self.p["button_radius"]
        for kid, side, y in zip(node.of("flush_key"), ("small", "large"), S.DUAL_Y(rb), strict=True):
            self.extend("tank", [S.flush_ring(at.shifted((0, y, 0)), rb)])
            button = S.flush_button(rb).attached("mount", to=at.shifted((0, y, 0)))
            self.grow(kid, part="tank", side=side, pieces=button.pieces, at=at)

    def button(self, node, cistern):
        at, rb = cistern.anchor("flush"), self.p["button_radius"]
        self.extend("tank", [S.flush_ring(at, rb)])
        button = self.place(S.flush_button(rb).attached("mount", to=at), "flush_button")
        self.slide("tank", button.root, button.anchor("press"), upper=S.PRESS, role="button")

    def lever(self, node, cistern):
        # on the left (-Y) wall near the front; its grip points forward, behind the cistern front
        lever = S.trip_lever(self.p["lever_length"]).attached("mount", to=cistern.anchor("left"))
        self.extend("tank", lever.parts["rose"].pieces)
        self.add("flush_lever", "lever", lever.parts["lever"].pieces)
        # pressing the grip (+X of the axis) down: about +Y
        self.hinge("tank", "flush_lever", lever.anchor("pivot"), upper=S.LEVER_TURN, role="button")

    def seat(self, node, pan, size):
        # the two leaves turn at most half a turn together, split by cover_share; the core stops them
        # where the cover leans on the cistern
        line = pan.anchor("hinge")
        cover_up = self.p["cover_share"] * math.pi
        self.place(S.seat(size).attached("hinge", to=line), "seat")
        self.hinge("base", "seat", line, upper=math.pi - cover_up)
        self.grow(node.one("cover"), line=line, size=size, upper=cover_up)

    def cover(self, node, line, size, upper):
        self.place(S.cover(size).attached("hinge", to=line), "cover")
        self.hinge("seat", "cover", line, upper=upper)


CATEGORY = Category("toilet", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToiletLayout, MATERIALS)
