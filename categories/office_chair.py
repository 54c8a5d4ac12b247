"""Office chair: a wheeled star base, a gas lift, a swivelling seat, a reclining back and 4D arms.

X is depth (the sitter faces +X), Y is width, Z is up. The base is a hub with 5 legs (rarely 4
or 6); at the tip of every leg a caster swivels about a vertical axis, carrying one wheel or a
pair of twin wheels that turn about a horizontal axle along the leg. The wheels touch the floor.

The gas lift is a hollow tube standing in the hub's socket around a fixed piston rod: it slides
up along +Z from its lowest (rest) position. On top of it the seat swivels about Z. The back
hangs on a spine whose recline hinge is behind the backrest's centre of mass, so gravity holds
it upright against its stop. Each arm is a hollow post sliding up over a bar under the seat, a
carriage on top that slides along X and turns about Z, and a pad that turns about Z on it.
Parts: ``categories/parts/seating.py`` (shared with the bar chair).
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float, Int

from .parts import seating as S

GRAMMAR = Grammar("office_chair", {
    "office_chair": Node(required=("base", "lift", "seat"), optional={"back": 0.92, "arms": 0.8}),
    "base": Node(label="base", repeat={"caster": S.legs}),
    "caster": Node(label="caster", one_of={"twin": 0.6, "single": 0.4}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "lift": Node(label="lift"),
    "seat": Node(label="seat"),
    "back": Node(label="back", one_of={"cushion": 0.6, "mesh": 0.4}, choice="back_style",
                 optional={"headrest": 0.25}),
    "cushion": Node(), "mesh": Node(), "headrest": Node(),
    "arms": Node(repeat={"arm": 2}),
    "arm": Node(label="arm", required=("arm_slider",)),
    "arm_slider": Node(label="arm", required=("arm_pad",)),
    "arm_pad": Node(label="armrest"),
})

PARAMS = (
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", 0.4, 0.55),
    Float("seat_width", "seat width (Y)", "m", 0.4, 0.6),
    Float("seat_depth", "seat depth (X)", "m", 0.4, 0.52),
    Float("seat_thickness", "seat cushion thickness", "m", 0.05, 0.1),
    Int("leg_count", "legs of the star base; auto = drawn, 5 on nearly every chair", "", 4, 6, auto=True),
    Float("base_radius", "caster swivel axes from the centre (raised for many legs)", "m", 0.27, 0.35),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=(0.65, 0.35)),
    Float("wheel_radius", "wheel radius", "m", 0.024, 0.034),
    Float("lift_radius", "gas lift tube radius", "m", 0.022, 0.028),
    Float("lift_travel", "gas lift stroke (capped where the column is short)", "m", 0.06, 0.1),
    Float("back_height", "backrest height", "m", 0.3, 0.55),
    Float("back_width", "backrest width as a fraction of the seat width", "", 0.75, 0.95),
    Float("back_thickness", "backrest thickness", "m", 0.04, 0.075),
    Float("back_gap", "backrest bottom above the seat top", "m", 0.04, 0.1),
    Float("recline", "back recline range", "rad", 0.25, 0.45),
    Float("arm_height", "arm pad top above the seat top", "m", 0.17, 0.25),
    Float("arm_travel", "arm height adjustment", "m", 0.04, 0.08),
    Float("pad_length", "arm pad length (X)", "m", 0.2, 0.27),
    Float("pad_width", "arm pad width (Y)", "m", 0.06, 0.09),
    Float("arm_slide", "arm pad slide along X, each way", "m", 0.02, 0.04),
    Float("arm_turn", "arm carriage turn about Z, each way", "rad", 0.1, 0.3),
    Float("pad_turn", "arm pad turn about Z, each way", "rad", 0.1, 0.3),
    Choice("base_finish", "star base material", choices=("plastic", "chrome", "brushed_metal"),
           weights=(0.55, 0.25, 0.2)),
    Choice("lift_finish", "gas lift tube material", choices=("chrome", "plastic"), weights=(0.6, 0.4)),
    Choice("seat_finish", "seat and back upholstery", choices=("fabric", "plastic"), weights=(0.75, 0.25)),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=(0.6, 0.4)),
)

MECHANISM = 0.04  # height of the tilt mechanism under the seat pan
SEAT_AHEAD = 0.02  # the seat sits a little forward of the column


class ChairLayout(S.ChairNodes):
    def office_chair(self, node):
        base = self.grow(node.one("base"))
        seat = self.grow(node.one("seat"), base=base)
        self.grow(node.one("lift"), base=base, seat=seat)
        front = self.grow(node.one("back"), seat=seat) if node.one("back") else None
        if node.one("arms"):
            self.grow(node.one("arms"), seat=seat, back_front=front)

    def base(self, node):
        return self.star_base(node)

    def seat(self, node, base):
        p = self.p
        thick = S.seat_thickness(p["seat_height"], p["seat_thickness"], base.top, MECHANISM)
        return self.swivel_seat("square", p["seat_depth"], thick, SEAT_AHEAD, MECHANISM)

    def arms(self, node, seat, back_front):
        p = self.p
        dims = S.ArmDims(p["pad_length"], p["pad_width"], p["arm_height"], p["arm_slide"], p["arm_turn"],
                         p["pad_turn"])
        y = S.arm_y(p["seat_width"], dims, p["back_width"] * p["seat_width"], back_front, seat)
        for arm, (side, sign) in zip(node.of("arm"), (("left", 1), ("right", -1))):
            self.grow(arm, seat=seat, y=sign * y, side=side, dims=dims)

    def arm(self, node, seat, y, side, dims):
        a = S.arm(seat, self.p["seat_height"], y, dims)
        self.extend("seat", a.bracket)
        post = self.add(f"arm_{side}", "arm", a.post)
        self.slide("seat", post, a.post_slide, upper=self.p["arm_travel"], role="telescope")
        self.grow(node.one("arm_slider"), arm=a, side=side, post=post, dims=dims)

    def arm_slider(self, node, arm, side, post, dims):
        slider = self.add(f"arm_slider_{side}", "arm", arm.slider)
        c = arm.carriage
        self.join(J.revolute_prismatic(post, slider, c.origin, c.z, (-dims.turn, dims.turn), c.x,
                                       (-dims.slide, dims.slide), role="slide"))
        self.grow(node.one("arm_pad"), arm=arm, side=side, slider=slider, dims=dims)

    def arm_pad(self, node, arm, side, slider, dims):
        pad = self.add(f"arm_pad_{side}", "armrest", arm.pad)
        self.hinge(slider, pad, arm.pad_pivot, upper=dims.pad_turn, lower=-dims.pad_turn, role="swivel")


CATEGORY = Category("office_chair", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ChairLayout,
                    S.CHAIR_MATERIALS)
