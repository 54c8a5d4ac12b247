"""Pliers: combination, needle-nose, slip-joint or locking pliers lying flat on the table.

Designs (``design``, sizes and sources in ``categories/parts/handtools.py``): ``combination`` pliers with
short wide jaws; ``needle_nose`` pliers with long jaws tapering to fine tips; ``slip_joint`` pliers whose
pivot bolt slides between the two holes of a slot (prismatic, then the jaw turns about it); ``locking``
pliers with a release lever hinged on the moving handle (revolute, spring-returned: role ``lever``).

The pliers lie flat on the lower half (``body``); the upper half (``jaw``) turns about the pivot (revolute
about +z): its jaw swings to +y, its handle away from the other. X is the jaws' direction, Y across, Z up.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import handtools as H

GRIPS = ("red", "blue", "orange", "black", "yellow")
PARAMS = (
    Float("size", "where the overall length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Choice("grip_colour", "dipped or moulded handle grips", choices=GRIPS, weights=(0.3, 0.25, 0.15, 0.2, 0.1)),
    Choice("steel", "finish of the forged steel", choices=("chrome", "brushed_metal")),
)

GRAMMAR = Grammar("pliers", {
    "pliers": Node(label="body", one_of={"combination": 0.3, "needle_nose": 0.25, "slip_joint": 0.25, "locking": 0.2},
                   choice="design"),
    "combination": Node(required=("jaw",)),
    "needle_nose": Node(required=("jaw",)),
    "slip_joint": Node(required=("pivot",)),
    "locking": Node(required=("lever_jaw",)),
    "pivot": Node(label="pivot", required=("jaw",)),
    "jaw": Node(label="jaw"),
    "lever_jaw": Node(label="jaw", required=("lever",)),
    "lever": Node(label="lever"),
})
"""A slip joint's jaw turns about its sliding pivot bolt; a locking plier's jaw carries the release lever."""

MATERIALS = {"steel": ("steel", {"brushed_metal": "brushed_metal:stainless_dark"}),
             "grip": ("grip_colour", {c: f"plastic:{c}" for c in GRIPS})}
# a dipped or moulded grip is a 1-2 mm PVC/TPE coat over the forged steel handle: ~60 % of the handle's
# cross-section is steel (7850 kg/m^3), the rest the coat (~1300): ~5200 kg/m^3 as a whole
SUBSTRATES = {"grip": 5200.0}


class PliersLayout(Layout):
    def pliers(self, node):
        self.pl = H.pliers(node.choice, self.p["size"])
        self.place(H.plier_half(self.pl, +1, "steel", "grip"), "body")
        self.grow(node.one(node.choice), parent="body")

    def combination(self, node, parent):
        self.grow(node.one("jaw"), parent=parent)

    needle_nose = combination

    def locking(self, node, parent):
        self.grow(node.one("lever_jaw"), parent=parent)

    def slip_joint(self, node, parent):
        self.grow(node.one("pivot"), parent=parent)

    def pivot(self, node, parent):
        bolt = self.place(H.rivet(self.pl, "steel"), "pivot")
        self.slide(parent, "pivot", bolt.anchor("slot"), upper=self.pl.design.slip)
        self.grow(node.one("jaw"), parent="pivot")

    def jaw(self, node, parent):
        half = self.place(H.plier_half(self.pl, -1, "steel", "grip"), "jaw")
        self.hinge(parent, "jaw", half.anchor("pivot"), upper=math.radians(self.pl.design.opens))
        return half

    def lever_jaw(self, node, parent):
        self.grow(node.one("lever"), half=self.jaw(node, parent))

    def lever(self, node, half):
        at = half.anchor("lever")
        self.place(H.release_lever(self.pl, "steel").attached("hinge", to=at), "lever")
        self.hinge("jaw", "lever", at, upper=math.radians(H.LEVER[3]), role="lever")


CATEGORY = Category("pliers", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PliersLayout, MATERIALS,
                    substrates=SUBSTRATES)
