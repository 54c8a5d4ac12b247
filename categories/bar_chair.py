"""Bar chair: a tall swivel stool on a gas lift, on a wheeled star base or a disc base with a foot ring.

X is depth (the sitter faces +X), Y is width, Z is up. Two bases: the office chair's star base
(5 legs, rarely 4 or 6, with swivelling casters; the wheels touch the floor) with a tall column
and an optional foot ring, or a heavy domed disc with a tall column and a foot ring. The gas lift
is a hollow tube in the column around a fixed piston rod, sliding up along +Z from its lowest
(rest) position; the seat (round or square) swivels on top of it. An optional low back stands on
a spine behind the seat, fixed or reclining (hinge behind its centre of mass, so gravity holds it
upright). Parts: ``categories/parts/seating.py`` (shared with the office chair).
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float, Int

from .parts import seating as S

GRAMMAR = Grammar("bar_chair", {
    "bar_chair": Node(required=("lift", "seat"), one_of={"wheeled": 0.45, "disc": 0.55}, choice="base_type",
                      optional={"back": 0.4}),
    "wheeled": Node(label="base", repeat={"caster": S.legs}, optional={"foot_ring": 0.6}),
    "disc": Node(label="base", required=("foot_ring",)),
    "foot_ring": Node(),
    "caster": Node(label="caster", one_of={"twin": 0.6, "single": 0.4}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "lift": Node(label="lift"),
    "seat": Node(label="seat"),
    "back": Node(label="back"),
})

PARAMS = (
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", 0.6, 0.85),
    Float("seat_width", "seat width, or diameter of a round seat", "m", 0.34, 0.46),
    Float("seat_depth", "square seat depth (X)", "m", 0.32, 0.42),
    Float("seat_thickness", "seat cushion thickness", "m", 0.035, 0.08),
    Choice("seat_shape", "seat outline", choices=("round", "square"), weights=(0.55, 0.45)),
    Int("leg_count", "legs of a wheeled base; auto = drawn, 5 on nearly every base", "", 4, 6, auto=True),
    Float("base_radius", "caster axes (wheeled) or disc radius from the centre", "m", 0.22, 0.3),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=(0.65, 0.35)),
    Float("wheel_radius", "wheel radius", "m", 0.022, 0.03),
    Float("lift_radius", "gas lift tube radius", "m", 0.022, 0.028),
    Float("lift_travel", "gas lift stroke", "m", 0.07, 0.12),
    Float("exposed_lift", "lift tube visible between the column and the seat at rest", "m", 0.05, 0.15),
    Float("ring_drop", "foot ring below the seat top", "m", 0.35, 0.5),
    Float("ring_radius", "foot ring radius", "m", 0.17, 0.23),
    Float("back_height", "backrest height", "m", 0.14, 0.3),
    Float("back_width", "backrest width as a fraction of the seat width", "", 0.6, 0.9),
    Float("back_thickness", "backrest thickness", "m", 0.03, 0.05),
    Float("back_gap", "backrest bottom above the seat top", "m", 0.06, 0.14),
    Choice("back_mount", "the back is fixed or reclines", choices=("fixed", "hinged")),
    Float("recline", "back recline range (hinged back)", "rad", 0.15, 0.3),
    Choice("base_finish", "base material", choices=("chrome", "brushed_metal", "plastic"),
           weights=(0.45, 0.25, 0.3)),
    Choice("lift_finish", "gas lift tube material", choices=("chrome", "plastic"), weights=(0.7, 0.3)),
    Choice("seat_finish", "seat upholstery", choices=("fabric", "plastic"), weights=(0.6, 0.4)),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=(0.6, 0.4)),
)

MECHANISM = 0.035  # swivel plate height under the seat pan
RING_ABOVE_HUB = 0.07  # the lowest a foot ring sits above the hub


class StoolLayout(S.ChairNodes):
    def bar_chair(self, node):
        p = self.p
        seat = self.grow(node.one("seat"))  # first: the base's column reaches up to it
        base = self.grow(node.one(node.choice), seat=seat)
        self.grow(node.one("lift"), base=base, seat=seat)
        if node.one("back"):
            self.grow(node.one("back"), seat=seat, hinged=p["back_mount"] == "hinged")

    def seat(self, node):
        p = self.p
        depth = p["seat_depth"] if p["seat_shape"] == "square" else p["seat_width"]
        return self.swivel_seat(p["seat_shape"], depth, p["seat_thickness"], 0.0, MECHANISM)

    def wheeled(self, node, seat):
        return self._column(node, self.star_base(node), seat)

    def disc(self, node, seat):
        base = S.disc_base(self.p["base_radius"], self.p["lift_radius"] + S.GAP,
                           metal=self.p["base_finish"] != "plastic")
        self.place(base.assembly, "base")
        return self._column(node, base, seat)

    def _column(self, node, base, seat):
        p = self.p
        ring = node.one("foot_ring")
        z_ring = max(p["seat_height"] - p["ring_drop"], base.top + RING_ABOVE_HUB, S.RING_MIN)
        top = seat.lift_top - S.COLUMN_BELOW_LIFT - p["exposed_lift"]
        if ring:
            top, z_ring = S.ring_column(top, z_ring, seat.lift_top)
        self.extend("base", S.column(base.top, top, base.bore))
        if ring:
            self.grow(ring, z=z_ring, bore=base.bore)
        return base

    def foot_ring(self, node, z, bore):
        self.extend("base", S.foot_ring(z, self.p["ring_radius"], bore))


CATEGORY = Category("bar_chair", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, StoolLayout,
                    S.CHAIR_MATERIALS)
