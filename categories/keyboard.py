"""Keyboard: a full-size (104 keys), tenkeyless (87) or laptop-style (78) computer keyboard, every key pressing.

Designs (``design``, layouts and sizes in ``categories/parts/keyboards.py``): a ``full`` ANSI board with its
navigation cluster and numeric pad, a ``tkl`` (tenkeyless) board without the pad, both with tall tapered
keycaps of 4 mm travel, and a ``laptop``-style board (Logitech K380, Apple Magic Keyboard) of flat chiclet caps
pressing 1.5 mm. Every key is a part pressed straight down (prismatic, role ``button``: its switch springs it
back). A full-size or tenkeyless board may have two fold-out ``feet`` under its back corners: it then rests
tilted on them (deployed is their rest state) and each folds back and up under the case (revolute about +Y,
role ``hinge``: deployed, a foot stands plumb on its stop, so the case's weight passes through its hinge).
Deployed feet are the rest state because a foot unfolding downward from a flat rest would dig into the table
the board stands on. X is the keyboard's front
(the typist's side), Y across (the typist's left -Y), Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import keyboards as K


def key_count(params, rng) -> int:
    """The design's key count (its real layout: 104, 87 or 78 keys)."""
    return len(K.layout(params["design"], *K.KEYS["chiclet" if params["design"] == "laptop" else "mechanical"][:2]))


GRAMMAR = Grammar("keyboard", {
    "keyboard": Node(label="case", required=("keys",), one_of={"full": 0.4, "tkl": 0.3, "laptop": 0.3},
                     choice="design"),
    "full": Node(optional={"feet": 0.65}),
    "tkl": Node(optional={"feet": 0.65}),
    "laptop": Node(),
    "feet": Node(repeat={"foot": 2}),
    "foot": Node(label="foot"),
    "keys": Node(repeat={"key": key_count}),
    "key": Node(label="key"),
})
"""``keys``: every key of the design's layout; ``feet``: two fold-out feet under the back corners."""

PARAMS = (
    Float("side", "where the case's side border lies in its design's range (keyboards.BORDER)", "", 0.0, 1.0),
    Float("back", "where the case's border behind the keys lies in its design's range", "", 0.0, 1.0),
    Float("height", "where the case's height lies in its key kind's range (keyboards.HEIGHT)", "", 0.0, 1.0),
    Float("corner", "corner radius of the case's footprint", "m", 0.003, 0.012),
    Float("foot_width", "where a foot's width lies in 25-45 mm", "", 0.0, 1.0),
    Float("foot_length", "where a foot's length (the lift it gives) lies in 8-14 mm", "", 0.0, 1.0),
    Choice("finish", "the case's colour", choices=("black", "grey", "white", "silver"),
           weights=(0.45, 0.2, 0.2, 0.15)),
)

MATERIALS = {
    "case": ("finish", {"black": "plastic:black|dark_grey", "grey": "plastic:dark_grey|light_grey",
                        "white": "plastic:white|light_grey", "silver": "brushed_metal"}),
    "keys": ("finish", {"black": "plastic:black|dark_grey", "grey": "plastic:light_grey|dark_grey",
                        "white": "plastic:white", "silver": "plastic:white|light_grey"}),
    "pads": "rubber", "feet": "plastic:black|dark_grey",
    # pad-printed or laser-etched legends: white on dark caps, dark on white ones (Logitech K120, Apple)
    "legend": ("finish", {"black": "plastic:white", "grey": "plastic:white", "white": "plastic:dark_grey",
                          "silver": "plastic:dark_grey"}),
}
SUBSTRATES = {"case": K.KEYBOARD_DENSITY}


class KeyboardLayout(Layout):
    def keyboard(self, node):
        p = self.p
        d = node.one(node.choice)
        self.b = b = K.board(node.choice, p["side"], p["back"], p["height"], p["corner"])
        self.legs = K.feet(b, p["foot_width"], p["foot_length"]) if d.one("feet") else []
        self.set_down = K.tilt(b, self.legs)
        tub, *rim = [pc.transformed(self.set_down.matrix) for pc in K.case(b, "case", "pads")]
        self.add("case", "case", [tub])
        self.rim = rim
        self.grow(node.one("keys"))
        self.grow(d)

    def full(self, node):
        self.extend("case", self.rim)  # the design's well rim round its layout and the pads
        if node.one("feet"):
            self.grow(node.one("feet"))

    tkl = laptop = full

    def keys(self, node):
        for k, (kid, key) in enumerate(zip(node.of("key"), self.b.keys, strict=True)):
            self.grow(kid, key=key, name=f"key_{k}")

    def key(self, node, key, name):
        placed = self.place(K.keycap(self.b, key, "keys", "legend", int(name[4:])).placed(self.set_down), name)
        self.slide("case", placed.root, placed.anchor("press"), upper=self.b.cap[4], role="button")

    def feet(self, node):
        for k, (kid, foot) in enumerate(zip(node.of("foot"), self.legs, strict=True)):
            self.grow(kid, foot=foot, name=f"foot_{k}")

    def foot(self, node, foot, name):
        placed = self.place(K.foot_part(foot, K.angle(self.set_down), "feet").placed(self.set_down), name)
        self.hinge("case", placed.root, placed.anchor("hinge"), upper=K.FOLD)


CATEGORY = Category("keyboard", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, KeyboardLayout, MATERIALS,
                    substrates=SUBSTRATES)
