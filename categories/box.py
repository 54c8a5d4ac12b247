"""Box: a board chest with a hasp, a corrugated carton with 2 or 4 flaps, a jewellery box or a shoe box.

Designs (``design``): a chest's lid turns on two hinges at its back and may carry a hasp that hangs over a staple
on the front: the hasp must be swung up before the lid opens (``requires_open``); a chest may have a drop handle
on each end that hangs flat and swings up to carry it. A carton (a regular slotted
shipping box) closes with two flaps meeting in the middle or with four; each flap turns
about its crease and folds right back against its wall. The four flaps of a four-flap carton close edge to
edge in one layer (the end flaps half the depth deep, the front and back flaps between them): each opens on its
own, where a regular slotted container's end flaps lie under both long flaps. A jewellery box has a lid with a
mirror under it, one or two drawers below the well and a tray that lifts out of the well once the lid is open (role
``lift_off``). A shoe box's lid lifts off its base (role ``lift_off``, guided by its skirt), or, on a one-piece
box, is creased to the base's back wall and turns up. Parts:
``categories/parts/boxes.py``.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd import lift_off
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float

from .parts import boxes as B

GRAMMAR = Grammar("box", {
    "box": Node(label="body", one_of={"chest": 0.3, "carton": 0.3, "jewellery": 0.2, "shoe_box": 0.2},
                choice="design"),
    "chest": Node(required=("lid",), optional={"handles": 0.5}),
    "handles": Node(repeat={"handle": 2}),
    "handle": Node(label="handle"),
    "carton": Node(one_of={"two_flaps": 0.4, "four_flaps": 0.6}, choice="flaps"),
    "two_flaps": Node(repeat={"flap": 2}),
    "four_flaps": Node(repeat={"flap": 4}),
    "jewellery": Node(required=("lid", "tray"), repeat={"drawer": (1, 2)}),
    "shoe_box": Node(one_of={"shoe_lid": 0.6, "box_lid": 0.4}, choice="shoe_closure"),
    "lid": Node(label="lid", optional={"latch": 0.7}),
    "latch": Node(label="latch"),
    "flap": Node(label="flap"),
    "drawer": Node(label="drawer"),
    "tray": Node(label="tray"),
    "shoe_lid": Node(label="lid"),
    "box_lid": Node(label="lid"),
})
"""Designs: chest (a hinged lid, maybe a hasp, maybe two drop handles on its ends), carton (2 flaps, or 4
meeting edge to edge), jewellery box (a hinged lid with a mirror, maybe a clasp; 1-2 drawers; a lift-out tray), shoe
box (a lift-off lid, or a one-piece box's lid hinged at the back)."""

PARAMS = (
    Float("width_share", "width (Y, the long side) within the design's range (SIZES in parts/boxes.py), 0 to 1",
          "", 0.0, 1.0),
    Float("depth_share", "depth (X) as a fraction of the width, within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("height_share", "wall height (Z) as a fraction of the width, within the design's range, 0 to 1", "",
          0.0, 1.0),
    Choice("finish", "a chest's or jewellery box's boards: wood or painted", choices=("wood", "painted"),
           weights=(0.7, 0.3)),
    Choice("hardware", "hinges, hasp and knob metal", choices=("brushed_metal", "chrome", "cast_iron")),
)

MATERIALS = {"body": "finish", "metal": "hardware", "lining": "fabric:burgundy|navy|cream|charcoal|teal|olive",
             "mirror": "chrome", "carton": "cardboard:kraft|kraft_light",
             "shoebox": "cardboard:white_top|black|orange|blue|kraft"}
# A shoe box is folding boxboard or E-flute, not C-flute: a men's box (~0.3 m^2 of 1.8 mm board) weighs
# 0.25-0.3 kg, ~500 kg/m^3 (greyboard 700-800, E-flute ~300).
SUBSTRATES = {"shoebox": 500.0}
SLOT = {"chest": "body", "jewellery": "body", "carton": "carton", "shoe_box": "shoebox"}
FLAPS = ("front", "back", "left", "right")


class BoxLayout(Layout):
    def box(self, node):
        p, design = self.p, node.choice
        self.size = B.BoxSize.of(design, p["width_share"], p["depth_share"], p["height_share"])
        self.slot = SLOT[design]
        self.drawers = len(node.one(design).of("drawer")) if design == "jewellery" else 0
        made = {"chest": B.chest, "jewellery": lambda s, m, k: B.jewellery_box(s, m, k, "lining", self.drawers),
                "carton": lambda s, m, k: B.carton(s, m), "shoe_box": lambda s, m, k: B.shoe_box(s, m)}
        body = self.place(made[design](self.size, self.slot, "metal"), "body")
        self.grow(node.one(design), body=body)

    def chest(self, node, body):
        self.grow(node.one("lid"), body=body, mirror=False)
        if node.one("handles"):
            self.grow(node.one("handles"), body=body)

    def handles(self, node, body):
        for kid, side in zip(node.of("handle"), ("left", "right")):
            self.grow(kid, body=body, side=side)

    def handle(self, node, body, side):
        made = B.drop_handle(B.hasp_scale(self.size), "metal").attached("mount", to=body.anchor(f"handle_{side}"))
        self.place(made, f"handle_{side}")
        self.hinge("body", f"handle_{side}", made.anchor("pivot"), upper=B.DROP_TURNS)

    def carton(self, node, body):
        self.grow(node.one(node.choice), body=body)

    def two_flaps(self, node, body):
        four = len(node.of("flap")) == len(FLAPS)
        for i, kid in enumerate(node.of("flap")):
            self.grow(kid, body=body, side=FLAPS[i], four=four)

    four_flaps = two_flaps

    def flap(self, node, body, side, four):
        at = body.anchor(f"flap_{side}")
        length, reach = B.flap_size(self.size, side, four)
        self.place(B.flap(length, reach, self.size.board, self.slot).attached("crease", to=at), f"flap_{side}")
        self.hinge("body", f"flap_{side}", at, upper=B.FLAP_OPENS)

    def lid(self, node, body, mirror=True):
        s = self.size
        at = body.anchor("hinge")
        latch = bool(node.one("latch"))
        made = B.board_lid(s, self.slot, "metal", latch, "mirror" if mirror else None, "lining" if mirror else None)
        lid = self.place(made.attached("hinge", to=at), "lid")
        if latch:  # declared first: the lid's joint names it as the part to open before the lid
            self.grow(node.one("latch"), lid=lid)
        self.hinge("body", "lid", at, upper=B.LID_OPENS, role="lid", requires_open="latch" if latch else None)

    def latch(self, node, lid):
        at = lid.anchor("hasp")
        self.place(B.hasp_plate(self.size, "metal").attached("pivot", to=at), "latch")
        self.hinge("lid", "latch", at, upper=B.HASP_TURNS)

    def jewellery(self, node, body):
        self.grow(node.one("lid"), body=body)
        for k, kid in enumerate(node.of("drawer")):
            self.grow(kid, body=body, k=k)
        self.grow(node.one("tray"), body=body)

    def drawer(self, node, body, k):
        at, n = body.anchor(f"drawer_{k}"), self.drawers
        made = B.jewellery_drawer(self.size, self.slot, "metal", "lining", n).attached("slide", to=at)
        self.place(made, f"drawer_{k}")
        depth = self.size.depth - 2 * self.size.board
        self.slide("body", f"drawer_{k}", at, upper=B.JEWEL["pull"] * depth)

    def tray(self, node, body):
        at = body.anchor("tray_seat")
        self.place(B.jewellery_tray(self.size, self.slot, "lining", self.drawers).attached("seat", to=at), "tray")
        seat = B.tray_height(self.size, self.drawers)  # it lifts free once clear of the well
        self.join(J.prismatic("body", "tray", tuple(at.origin), tuple(at.z), 0.0, lift_off.lift(seat),
                              "lift_off", requires_open="lid", engagement=seat))

    def shoe_box(self, node, body):
        self.grow(node.one(node.choice), body=body)

    def box_lid(self, node, body):
        at = body.anchor("hinge")
        self.place(B.shoe_lid(self.size, self.slot, hinged=True).attached("hinge", to=at), "lid")
        self.hinge("body", "lid", at, upper=B.LID_OPENS, role="lid")

    def shoe_lid(self, node, body):
        at = body.anchor("lid_seat")
        self.place(B.shoe_lid(self.size, self.slot).attached("seat", to=at), "lid")
        self.lift("body", "lid", at, engagement=B.skirt(self.size))


CATEGORY = Category("box", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BoxLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=furniture)
