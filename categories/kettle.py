"""Kettle: an electric jug kettle on its base, a stovetop whistling kettle or a camping kettle with a folding bail.

Designs (``design``, sizes and sources in ``categories/parts/kettles.py``): an ``electric`` jug kettle on its
power base, its lid hinged at the back of the opening (revolute: the front lifts) with a release button on
top of the handle (prismatic, spring-returned: role ``button``) and an on/off paddle on the base (revolute);
a ``whistling`` stovetop kettle whose spout is closed by a whistle flap (revolute: it swings up off the
spout's end) under a hinged lid; a ``camping`` kettle with a wire bail that folds back over the body and rises
to carry it (revolute), a spout flap and a hinged lid.

X is the spout's direction, Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import kettles as K

PARAMS = (
    Float("girth", "where the body's radius lies in its design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("tallness", "where the body's height lies in its design's range (0 lowest, 1 tallest)", "", 0.0, 1.0),
    Choice("finish", "body finish (a stovetop kettle is metal: plastic there is brushed_metal)",
           choices=("brushed_metal", "chrome", "painted", "plastic")),
)

GRAMMAR = Grammar("kettle", {
    "kettle": Node(label="body", required=("lid",), one_of={"electric": 0.45, "whistling": 0.35, "camping": 0.2},
                   choice="design"),
    "electric": Node(required=("release", "switch")),
    "whistling": Node(required=("flap",)),
    "camping": Node(required=("bail", "flap")),
    "lid": Node(label="lid"),
    "release": Node(label="button"),
    "switch": Node(label="switch"),
    "flap": Node(label="flap"),
    "bail": Node(label="handle"),
})
"""A stovetop kettle is metal (a ``plastic`` finish is drawn only on electric kettles: ``brushed_metal``
otherwise)."""

MATERIALS = {"body": ("finish", {"painted": "enamel"}), "handle": "plastic:black", "knob": "plastic:black",
             "base": "plastic:black", "button": "plastic:black", "switch": "plastic:black", "flap": "brushed_metal",
             "bail": "brushed_metal", "trim": "chrome"}


def _derive(p: dict) -> dict:
    if p["design"] != "electric" and p["finish"] == "plastic":
        return {**p, "finish": "brushed_metal"}
    return p


class KettleLayout(Layout):
    def kettle(self, node):
        p, design = self.p, node.choice
        k = K.kettle(design, p["girth"], p["tallness"])
        self.add("body", "body", K.body(k, design, "body", "handle"))
        self.grow(node.one("lid"), k=k)
        self.grow(node.one(design), k=k)

    def _fittings(self, node, k):
        for kid in node.children:
            self.grow(kid, k=k)

    electric = whistling = camping = _fittings

    def lid(self, node, k):
        pieces, hinge = K.lid(k, "body", "knob")
        self.hinge("body", self.add("lid", "lid", pieces), hinge, upper=K.LID_OPENS, role="lid")

    def release(self, node, k):
        pieces, press = K.release_button(k, "button")
        self.slide("body", self.add("release_button", "button", pieces), press, upper=K.BUTTON_TRAVEL, role="button")

    def switch(self, node, k):
        pieces, pivot = K.switch(k, "switch")
        self.hinge("body", self.add("switch", "switch", pieces), pivot, upper=K.SWITCH_TURN, role="knob")

    def flap(self, node, k):
        pieces, hinge = K.flap(k, "flap")
        self.hinge("body", self.add("spout_flap", "flap", pieces), hinge, upper=K.FLAP_OPENS)

    def bail(self, node, k):
        pieces, pivot = K.bail(k, "bail")
        self.hinge("body", self.add("bail", "handle", pieces), pivot, upper=K.BAIL_OPENS)


CATEGORY = Category("kettle", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, KettleLayout, MATERIALS,
                    derive=_derive)
