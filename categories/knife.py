"""Knife: a folding pocket knife, a multi-tool pocket knife with 2-5 tools or a utility knife, lying on its side.

Designs (``design``, sizes and sources in ``categories/parts/knives.py``): a ``pocket`` knife (Opinel, Buck
110) with one blade, or a stockman with two or three (a small blade beside it, a spey blade on the back
pivot); a ``multi_tool`` (Victorinox Spartan, Climber, Huntsman) with 2-5 tools, one per layer
between aluminium liners, blades on the front pivot and openers and reamer on the back one; a ``utility``
knife, retractable (Stanley 99E) or snap-off (Olfa L-1), whose blade slides out of the nose.

The handle (``body``) lies on its side, its back end at the origin and its front toward +X, the spine toward
+Y. A blade or tool (``blade``, ``saw``, ``can_opener``, ``bottle_opener``, ``reamer``) turns in its own
layer about its pivot pin (revolute about Z) from folded inside the handle out through its open side to
straight; tools on the front pivot share its pin, as do those
on the back one. A utility knife's blade and carrier (``blade``) slide out of the nose (prismatic along +X)
to the last of the slider's lock steps. PartNet-Mobility: Knife.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import knives as K

PARAMS = (
    Float("size", "where the handle length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Choice("handle", "scales of a folding knife: wood, moulded plastic (cellidor) or anodised aluminium",
           choices=("wood", "plastic", "aluminium"), weights=(0.35, 0.4, 0.25)),
    Choice("handle_colour", "colour of a utility knife's body",
           choices=("red", "black", "blue", "yellow", "dark_grey"), weights=(0.35, 0.25, 0.15, 0.15, 0.1)),
    Choice("steel", "blade finish", choices=("brushed_metal", "chrome")),
    Choice("point", "a pocket knife's blade: clip point, drop point or sheepsfoot",
           choices=("clip", "drop", "sheep")),
)

GRAMMAR = Grammar("knife", {
    "knife": Node(label="body", one_of={"pocket": 0.25, "multi_tool": 0.55, "utility": 0.2}, choice="design"),
    "pocket": Node(required=("blade_tool",), repeat={"pen_blade": (0, 2)}),
    "multi_tool": Node(repeat={"tool": (2, 5)}),
    "utility": Node(one_of={"retractable": 0.6, "snap_off": 0.4}, choice="cutter"),
    "blade_tool": Node(label="blade"),
    "pen_blade": Node(label="blade"),
    "tool": Node(one_of=K.MULTI_TOOLS),
    **{kind: Node(label=K.LABELS[kind]) for kind in K.MULTI_TOOLS},
    "retractable": Node(required=("carrier",)), "snap_off": Node(required=("carrier",)),
    "carrier": Node(label="blade"),
})
"""A multi-tool's tools are drawn one by one (its kinds may repeat: two blades of a size are not made);
a utility knife is retractable or snap-off, its blade on its carrier."""

MATERIALS = {"scale": ("handle", {"wood": "wood:walnut|cherry|oak", "plastic": "plastic:red|black|blue|dark_grey",
                                  "aluminium": "brushed_metal:stainless_dark"}),
             "alox": "brushed_metal:stainless_dark",
             "handle_colour": ("handle_colour", {c: f"plastic:{c}" for c in PARAMS[2].choices}),
             "liner": "brushed_metal:stainless", "steel": ("steel", {"brushed_metal": "brushed_metal:stainless"}),
             "pin": "chrome", "grip": "rubber:black", "edge": "chrome"}
# aluminium liners and 'alox' scales (Victorinox: aluminium alloy, 2700 kg/m^3) look brushed steel
SUBSTRATES = {"liner": 2700.0, "alox": 2700.0}
OPENS = math.radians(180)  # a folding tool opens straight (its tang's stop against the backspring)


class KnifeLayout(Layout):
    def knife(self, node):
        design = node.one(node.choice)
        if node.choice == "utility":
            self.cut = K.utility(design.choice, self.p["size"])
            self.place(K.utility_handle(self.cut, "handle_colour", "grip"), "body")
        else:
            self.fold = K.folding(node.choice, self.p["size"], len(design.of("tool")) + len(design.of("pen_blade"))
                                  + len(design.of("blade_tool")))
            scale = "alox" if self.p["handle"] == "aluminium" else "scale"
            self.place(K.folding_handle(self.fold, scale, "liner", "pin"), "body")
        self.grow(design)

    def pocket(self, node):
        self.grow(node.one("blade_tool"))
        for k, b in enumerate(node.of("pen_blade")):  # a stockman's small blade at the front, a spey at the back
            self.grow(b, k=k + 1)

    def pen_blade(self, node, k):
        self._tool("small_blade" if k == 1 else "spey_blade", k, f"tool_{k}")

    def multi_tool(self, node):
        for k, t in enumerate(node.of("tool")):
            self.grow(t, k=k)

    def blade_tool(self, node):
        self._tool("large_blade", 0, "tool", self.p["point"])

    def tool(self, node, k):
        self.grow(node.one(node.choice or node.children[0].kind), k=k)

    def _tool(self, kind, k, name, point="clip"):
        t = self.place(K.tool(self.fold, kind, k, "steel", point, "edge"), name)
        self.hinge("body", name, t.anchor("pivot"), upper=OPENS)

    def large_blade(self, node, k):
        self._tool(node.kind, k, f"tool_{k}")

    small_blade = saw = can_opener = bottle_opener = reamer = large_blade

    def utility(self, node):
        self.grow(node.one(node.choice))

    def retractable(self, node):
        self.grow(node.one("carrier"))

    snap_off = retractable

    def carrier(self, node):
        c = self.place(K.blade_carrier(self.cut, "steel", "handle_colour", "edge"), "blade")
        self.slide("body", "blade", c.anchor("slide"), upper=self.cut.design.travel)


CATEGORY = Category("knife", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, KnifeLayout, MATERIALS,
                    substrates=SUBSTRATES)
