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
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

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
    Float("one_piece_tank", "a one-piece cistern's height as a fraction of tank_height", "", 0.55, 0.7),
    Float("unit_height", "height of a back-to-wall furniture unit", "m", 0.8, 0.86),
    Float("unit_depth", "depth of a back-to-wall unit or of a wall-hung pan's boxed frame", "m", 0.2, 0.3),
    Float("unit_width", "width of the unit or the boxed frame", "m", 0.5, 0.6),
    Float("frame_height", "height of a wall-hung pan's boxed frame (its flush plate 0.12-0.2 m below the top)",
          "m", 1.0, 1.2),
    Float("hung_seat_height", "seat height of a wall-hung pan (installed height)", "m", 0.40, 0.44),
    Choice("ceramic_colour", "ceramic colour", choices=("white", "cream", "ivory"), weights=(0.7, 0.15, 0.15)),
    Choice("seat_finish", "seat and cover material", choices=("plastic", "wood"), weights=(0.75, 0.25)),
)

MATERIALS = {"ceramic": ("ceramic_colour", {c: f"ceramic:{c}" for c in ("white", "cream", "ivory")}),
             "seat": ("seat_finish", {"plastic": "plastic:white|light_grey|black"}), "chrome": "chrome",
             "rubber": "rubber", "wall": "painted:white|off_white|light_grey",
             "unit": "painted:white|light_grey|charcoal|sage|navy", "top": "wood"}


class ToiletLayout(Layout):
    def toilet(self, node):
        p = self.p
        design = node.choice
        a, b = p["bowl_length"] / 2, p["bowl_width"] / 2
        seat_h = p["hung_seat_height"] if design == "wall_hung" else p["seat_height"]
        z_r = seat_h - p["seat_thickness"] - S.GAP  # rim top
        z_h = z_r + S.GAP + p["seat_thickness"]  # hinge line: the seat's top rear edge
        TD, TW = p["tank_depth"], p["tank_width"]
        rear = TD if design in ("close_coupled", "one_piece") else p["unit_depth"]
        x_front = (2 * a + S.TAB + p["tank_gap"] + rear) / 2  # the object centred on x = 0
        x_c = x_front - a  # bowl axis
        x_h = x_c - a - S.TAB  # hinge line
        x_tf = x_h - p["tank_gap"]  # cistern front face (or the unit's, the frame's)
        shape = S.TOILET
        tab_w = shape["tab"] * b
        geo = dict(a=a, b=b, z_r=z_r, x_c=x_c, hinge=(x_h, z_h), tab_w=tab_w)
        hinge = (x_h, z_h)
        if design == "close_coupled":
            back, front, tank_share, bowl_share = shape["deck"]
            deck = (x_tf - TD + back, x_c - front * a, min(tank_share * TW, bowl_share * b))
            base = S.ceramic_base(a, b, p["wall"], z_r, x_c, deck, tab_w, hinge)
        elif design == "one_piece":
            tank_share, bowl_share = shape["one_piece"]
            base = S.skirted_base(a, b, p["wall"], z_r, x_c, x_tf - TD, tab_w, hinge,
                                  min(tank_share * TW, bowl_share * b))
        elif design == "back_to_wall":
            base = S.skirted_base(a, b, p["wall"], z_r, x_c, x_tf + S.GAP, tab_w, hinge, shape["back_to_wall"] * b)
        else:
            base = S.hung_base(a, b, p["wall"], z_r, x_c, x_tf + S.GAP, tab_w, hinge)
        self.add("base", "body", base)
        self.grow(node.one(design), xs=(x_tf - TD, x_tf), ys=(-TW / 2, TW / 2), z0=z_r)
        self.grow(node.one("seat"), **geo)

    def close_coupled(self, node, **where):
        self.grow(node.one("tank"), **where)

    def one_piece(self, node, xs, ys, z0):
        # the low cistern stands on the skirt's back block, as wide as it
        self.grow(node.one("tank"), xs=xs, ys=ys, z0=z0, low=True)

    def back_to_wall(self, node, xs, ys, z0):
        p = self.p
        self.grow(node.one("unit"), x_face=xs[1], size=(p["unit_depth"], p["unit_width"], p["unit_height"]))

    def wall_hung(self, node, xs, ys, z0):
        p = self.p
        self.grow(node.one("prewall"), x_face=xs[1], size=(p["unit_depth"], p["unit_width"], p["frame_height"]))

    def unit(self, node, x_face, size):
        D, W, H = size
        self.add("unit", "cabinet", [pc.replace(sheet=S.SHEET) for pc in S.vanity_unit(x_face, D, W, H)])
        self.fix("base", "unit")
        top, plate = S.TOILET["unit_plate"]
        self.grow(node.one("flush_plate"), part="unit", x_face=x_face, z=H - top - plate)

    def prewall(self, node, x_face, size):
        D, W, H = size
        self.add("prewall", "frame", [pc.replace(sheet=S.SHEET) for pc in S.prewall(x_face, D, W, H)])
        self.fix("base", "prewall")
        self.grow(node.one("flush_plate"), part="prewall", x_face=x_face, z=H - S.TOILET["frame_plate"])

    def flush_plate(self, node, part, x_face, z):
        plate, keys = S.flush_plate(x_face, z)
        self.extend(part, plate)
        for kid, (side, pieces) in zip(node.of("flush_key"), keys, strict=True):
            self.grow(kid, part=part, side=side, pieces=pieces, z=z)

    def flush_key(self, node, part, side, pieces, z):
        # a flush-plate key is chrome-plated plastic like the round buttons (S.BUTTON_WALL)
        name = self.add(f"flush_{side}", "button", [pc.replace(wall=S.BUTTON_WALL) for pc in pieces])
        x = max(pc.bounds[1, 0] for pc in pieces)
        self.slide(part, name, Frame.at((x, 0.0, z), z=(-1, 0, 0)), upper=S.PRESS, role="button")

    def tank(self, node, xs, ys, z0, low=False):
        p = self.p
        tall = p["tank_height"] * (p["one_piece_tank"] if low else 1.0)
        z1 = z0 + tall - p["lid_thickness"] - S.GAP  # top of the walls
        zf = z1 - S.FLUSH_BELOW
        rb = p["button_radius"]
        ys_b = {"button": (0.0,), "dual": S.DUAL_Y(rb)}.get(node.choice, ())
        holes = [(y - rb - S.CLEAR, zf - rb - S.CLEAR, y + rb + S.CLEAR, zf + rb + S.CLEAR) for y in ys_b]
        self.add("tank", "tank", S.cistern(xs, ys, z0, z1, holes))
        self.fix("base", "tank")
        self.grow(node.one("tank_lid"), xs=xs, ys=ys, z=z1 + S.GAP)
        self.grow(node.one(node.choice), xs=xs, ys=ys, z=zf)

    def tank_lid(self, node, xs, ys, z):
        self.add("tank_lid", "lid", S.cistern_lid(xs, ys, z, self.p["lid_thickness"]))
        self.slide("tank", "tank_lid", Frame.at((xs[1], 0.0, z)), upper=S.LID_LIFT, role="lid")

    def dual(self, node, xs, ys, z):
        rb, x_tf = self.p["button_radius"], xs[1]
        for kid, side, y in zip(node.of("flush_key"), ("small", "large"), S.DUAL_Y(rb), strict=True):
            self.extend("tank", [S.flush_ring(S.on_face(x_tf, z).shifted((0, y, 0)), rb)])
            pieces = [pc.transformed(Frame.at((0, y, 0)).matrix)
                      for pc in S.flush_button(x_tf, S.CISTERN_WALL + S.BUTTON_BEHIND, z, rb)]
            self.grow(kid, part="tank", side=side, pieces=pieces, z=z)

    def button(self, node, xs, ys, z):
        rb, x_tf = self.p["button_radius"], xs[1]
        self.extend("tank", [S.flush_ring(S.on_face(x_tf, z), rb)])
        self.add("flush_button", "button", S.flush_button(x_tf, S.CISTERN_WALL + S.BUTTON_BEHIND, z, rb))
        self.slide("tank", "flush_button", Frame.at((x_tf + S.BUTTON_PROUD, 0.0, z), z=(-1, 0, 0)), upper=S.PRESS,
                   role="button")

    def lever(self, node, xs, ys, z):
        # on the left (-Y) wall near the front; its grip points forward, behind the cistern front
        length = self.p["lever_length"]
        xa = xs[1] - length - S.LEVER_ROSE["behind"]
        rose, y_in = S.lever_rose(xa, ys[0], z)
        self.extend("tank", [rose])
        self.add("flush_lever", "lever", S.trip_lever(xa, y_in, z, length))
        # pressing the grip (+X of the axis) down: about +Y
        self.hinge("tank", "flush_lever", Frame.at((xa, y_in, z), z=(0, 1, 0)), upper=S.LEVER_TURN, role="button")

    def seat(self, node, a, b, z_r, x_c, hinge, tab_w):
        p = self.p
        past, lid_past, tab = S.TOILET["seat"]
        a_s, b_s = a + past, b + past
        x_h, z_h = hinge
        self.add("seat", "seat", S.seat(a_s, b_s, x_c, z_r + S.GAP, p["seat_thickness"], p["seat_ring"],
                                        (x_h, x_c - a_s + tab, tab_w)))
        # the two leaves turn at most half a turn together, split by cover_share; the core stops them
        # where the cover leans on the cistern
        cover_up = p["cover_share"] * math.pi
        line = Frame.at((x_h, 0.0, z_h), z=(0, -1, 0))
        self.hinge("base", "seat", line, upper=math.pi - cover_up)
        self.grow(node.one("cover"), a=a_s + lid_past, b=b_s + lid_past, x_c=x_c, line=line, upper=cover_up,
                  tab_w=tab_w)

    def cover(self, node, a, b, x_c, line, upper, tab_w):
        x_h, z_h = line.origin[0], line.origin[2]
        tab = (x_h, x_c - a + S.TOILET["seat"][2], tab_w)
        self.add("cover", "lid", S.cover(a, b, x_c, z_h + S.GAP, self.p["cover_thickness"], tab))
        self.hinge("seat", "cover", line, upper=upper)


CATEGORY = Category("toilet", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToiletLayout, MATERIALS)
