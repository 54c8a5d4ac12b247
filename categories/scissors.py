"""Scissors: office scissors, kitchen shears with a bottle opener, pinking shears or embroidery scissors.

Designs (``design``, sizes and sources in ``categories/parts/handtools.py``): ``office`` scissors with a
round thumb loop and a long finger loop in moulded plastic; ``kitchen`` shears with two large loops and a
bottle-opener hook between the handles; ``pinking`` shears whose thick blades cut a zigzag; ``embroidery``
scissors, small and all steel, with round forged rings and fine points.

The pair lies flat on the table on its lower half (``body``); the upper half (``blade``) turns about the
pivot screw (revolute about +z): its blade swings up to +y and its loop away from the other loop. X is the
blades' direction, Y across, Z up.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import handtools as H

PARAMS = (
    Float("size", "where the overall length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Float("blade_share", "the blade's share of the length moved by this much from its design's", "", -0.03, 0.03),
    Choice("handle_colour", "moulded handle colour (office, kitchen and pinking shears)",
           choices=("black", "orange", "red", "blue", "dark_grey", "teal"), weights=(0.3, 0.2, 0.15, 0.15, 0.1, 0.1)),
    Choice("steel", "blade finish", choices=("brushed_metal", "chrome")),
)

GRAMMAR = Grammar("scissors", {
    "scissors": Node(label="body", one_of={"office": 0.35, "kitchen": 0.25, "pinking": 0.15, "embroidery": 0.25},
                     choice="design"),
    "office": Node(required=("blade",)),
    "kitchen": Node(required=("blade",)),
    "pinking": Node(required=("blade",)),
    "embroidery": Node(required=("blade",)),
    "blade": Node(label="blade"),
})
"""Every pair has its fixed lower half (body) and its turning upper half (blade); the design node picks the
kind (its sizes, loops, edge and opener are in the design's data)."""

MATERIALS = {"steel": ("steel", {"brushed_metal": "brushed_metal:stainless|stainless_dark"}),
             "grip": ("handle_colour", {c: f"plastic:{c}" for c in PARAMS[2].choices}), "screw": "chrome"}


class ScissorsLayout(Layout):
    def scissors(self, node):
        p, design = self.p, node.choice
        self.s = H.scissors(design, p["size"], p["blade_share"])
        self.place(H.scissor_half(self.s, +1, "steel", "grip", "screw"), "body")
        self.grow(node.one(design))

    def office(self, node):
        self.grow(node.one("blade"))

    kitchen = pinking = embroidery = office

    def blade(self, node):
        half = self.place(H.scissor_half(self.s, -1, "steel", "grip", "screw"), "blade")
        self.hinge("body", "blade", half.anchor("pivot"), upper=math.radians(self.s.design.opens))


CATEGORY = Category("scissors", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ScissorsLayout, MATERIALS)
