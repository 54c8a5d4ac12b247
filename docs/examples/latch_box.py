"""Latch box: a box of boards with a lid hinged at the back and a turn latch on the front.

The worked example of docs/ADDING_A_CATEGORY.md. Dropped into ``categories/``
as ``latch_box.py`` it becomes a category (discovery registers it); the tests
build it from here.
"""

from __future__ import annotations

import math

from infmob_usd.categories.parts import hardware, panels
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

# Sizes of real wooden keepsake and tool boxes: 0.25-0.45 m wide, 0.18-0.30 m deep,
# 0.10-0.22 m tall, 9-15 mm boards (retail listings of pine and oak boxes).
PARAMS = (
    Float("width", "outer width (Y)", "m", 0.25, 0.45),
    Float("depth", "outer depth (X)", "m", 0.18, 0.30),
    Float("height", "height of the walls (Z), lid excluded", "m", 0.10, 0.22),
    Float("board", "board thickness", "m", 0.009, 0.015),
    Choice("finish", "wood or painted boards", choices=("wood", "painted")),
    Choice("hardware_finish", "latch and handle metal", choices=("brushed_metal", "chrome")),
)

GRAMMAR = Grammar("box", {
    "box": Node(label="body", required=("lid",), optional={"latch": 0.7}),
    "lid": Node(label="lid", optional={"handle": 0.5}),
    "latch": Node(label="latch"),
    "handle": Node(label="handle"),
})

MATERIALS = {"body": "finish", "metal": "hardware_finish"}  # lid and body: one look

LID_OPENS = math.radians(110)  # a lid stay stops real box lids at 100-120 degrees
LATCH_TURNS = math.pi / 2


class BoxLayout(Layout):
    def box(self, node):
        p = self.p
        body = self.place(panels.open_box(p["width"], p["depth"], p["height"], p["board"], "body"), "body")
        self.grow(node.one("lid"), body=body)
        if node.one("latch"):
            self.grow(node.one("latch"), body=body)

    def lid(self, node, body):
        p = self.p
        hinge = body.anchor("rim_back")
        lid = self.place(panels.leaf(p["width"], p["depth"], p["board"], "body").attached("hinge", to=hinge), "lid")
        self.hinge(body.root, lid.root, hinge, upper=LID_OPENS)
        if node.one("handle"):
            self.grow(node.one("handle"), lid=lid)

    def handle(self, node, lid):
        # on the lid's top, the bar across the box (along y)
        top = lid.anchor("top").turned("z", math.pi / 2)
        bar = hardware.bar_handle(0.5 * self.p["width"], "metal").attached("mount", to=top)
        self.fix(lid.root, self.place(bar, "handle").root)

    def latch(self, node, body):
        p = self.p
        # a turn button on the front face, its bar pointing up past the rim
        at = body.anchor("front").moved(dx=p["height"] / 2 - 0.02)
        button = hardware.turn_button(0.05, "metal").attached("mount", to=at)
        latch = self.place(button, "latch")
        self.hinge(body.root, latch.root, at, upper=LATCH_TURNS, role="knob")


CATEGORY = Category("latch_box", "Latch box: a board box with a hinged lid and a turn latch.",
                    PARAMS, GRAMMAR, BoxLayout, MATERIALS)
