"""Folding chair: a steel, padded or wooden slatted folding chair whose seat folds up and rear legs scissor shut.

Designs (``design``, sizes and sources in ``categories/parts/folding_chairs.py``): a ``metal`` folding chair
(steel tube frames, a pressed-steel seat and a curved back panel), a ``padded`` one (the same with foam pads on
its seat and back) and a ``wooden`` slatted one (hardwood bars, slats across the seat and the back). The body is
the two side members, each one piece from its front foot up into the back; the seat turns up about its top rear
edge (revolute about the horizontal across the chair) until it stands in front of the back; the rear leg frame,
hung under the seat on its top rail (revolute) and crossing the front legs in an X, turns back against the seat
(``Layout.couple``: one DoF, as the real linkage) so that its feet close on the front feet and the folded chair
is flat.

X is the front (where the sitter faces), Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float

from .parts import folding_chairs as C

PARAMS = (
    Float("size", "where the seat height, width and depth lie in the design's ranges (0 smallest, 1 largest)", "",
          0.0, 1.0),
    Float("back", "where the back's top lies in the design's height range (0 lowest, 1 tallest)", "", 0.0, 1.0),
    Choice("frame_finish", "a metal chair's tube and panels", choices=("enamel", "chrome", "painted"),
           weights=(0.55, 0.15, 0.3)),
    Choice("wood", "a wooden chair's timber", choices=("wood", "painted"), weights=(0.7, 0.3)),
)

GRAMMAR = Grammar("folding_chair", {
    "folding_chair": Node(one_of={"metal": 0.4, "padded": 0.25, "wooden": 0.35}, choice="design"),
    "metal": Node(label="body", required=("seat", "legs")),
    "padded": Node(label="body", required=("seat", "legs")),
    "wooden": Node(label="body", required=("seat", "legs")),
    "seat": Node(label="seat"),
    "legs": Node(label="legs"),
})
"""All designs fold the same way: the seat up, the rear legs forward under it."""

MATERIALS = {"frame": "frame_finish", "foot": "rubber", "timber": "wood", "pad": "fabric"}
SUBSTRATES = {"frame": ("frame_finish", {"painted": 7850.0}),  # painted steel tube
              "timber": ("wood", {"painted": 700.0})}  # painted beech


class FoldingChairLayout(Layout):
    def folding_chair(self, node):
        self.grow(node.one(node.choice))

    def metal(self, node):
        c = C.chair(node.kind, self.p["size"], self.p["back"])
        frame = "frame" if c.metal else "timber"
        seat_pad, back_pad = C.pads(c, "pad") if node.kind == "padded" else ([], [])
        body = self.add("body", "body", C.back_frame(c, frame, frame, "foot") + back_pad)
        seat = self.grow(node.one("seat"), c=c, body=body, slot=frame, pad=seat_pad)
        self.grow(node.one("legs"), c=c, body=body, slot=frame, seat=seat)

    padded = wooden = metal

    def seat(self, node, c, body, slot, pad):
        seat = self.add("seat", "seat", C.seat(c, slot) + pad)
        self.hinge(body, seat, C.seat_hinge(c), upper=C.seat_folds(c))
        return seat

    def legs(self, node, c, body, slot, seat):
        legs = self.add("legs", "legs", C.rear_legs(c, slot, "foot"))
        ratio = C.legs_ratio(c)
        self.hinge(seat, legs, C.legs_hinge(c), upper=ratio * C.seat_folds(c))
        self.couple(legs, seat, ratio)  # the X shuts as the seat lifts


CATEGORY = Category("folding_chair", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, FoldingChairLayout,
                    MATERIALS, substrates=SUBSTRATES, palette=furniture)
