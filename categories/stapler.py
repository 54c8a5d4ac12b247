"""Stapler: a desk stapler, a long-reach stapler or a plier stapler, with its arm, magazine and base.

Designs (``design``, sizes and sources in ``categories/parts/handtools.py``): a ``desk`` stapler and a
``long_reach`` one stand on their base, the head on one rear pin; a top-loading head (``loading``) lifts the
magazine off the base (revolute: the base swings clear of it, as for tacking) and opens the top arm off the
magazine to drop a strip in (revolute); a front-loading head lifts as one with the arm (revolute) and its
magazine slides out of the front (prismatic). A ``plier`` stapler lies on its slim lower handle, its arm
closed on it (the squeeze stroke is the arm's spring travel, not a joint); the arm opens up off the handle
(revolute) and its magazine slides out of the front (prismatic). X is the stapler's front, Y across, Z up.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import handtools as H

PARAMS = (
    Float("size", "where the length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Choice("finish", "arm and base: enamelled steel or moulded plastic", choices=("enamel", "plastic")),
)

GRAMMAR = Grammar("stapler", {
    "stapler": Node(label="body", one_of={"desk": 0.45, "long_reach": 0.25, "plier": 0.3}, choice="design"),
    "desk": Node(required=("loader",)),
    "long_reach": Node(required=("loader",)),
    "loader": Node(one_of={"top_loading": 0.5, "front_loading": 0.5}, choice="loading"),
    "plier": Node(required=("lifting_arm",)),
    "top_loading": Node(required=("head",)),
    "front_loading": Node(required=("lifting_arm",)),
    "head": Node(label="magazine", required=("arm",)),
    "arm": Node(label="arm"),
    "lifting_arm": Node(label="arm", required=("magazine",)),
    "magazine": Node(label="magazine"),
})
"""Top loading: the magazine turns off the base, the arm off the magazine; front loading (and a plier
stapler): the arm turns off the base and the magazine slides out of its front."""

MATERIALS = {"body": ("finish", {"enamel": "enamel:black|graphite", "plastic": "plastic:black|dark_grey|red|blue"}),
             "steel": "chrome", "pad": "rubber:black"}
HEAD_OPENS = math.radians(180)  # the base swings right round for tacking (the core stops it at the table)
ARM_OPENS = math.radians(100)  # an arm stands past upright to drop a strip in or clear a jam
PULLS = 0.6  # share of the length a magazine slides out to load


class StaplerLayout(Layout):
    def stapler(self, node):
        self.st = H.stapler(node.choice, self.p["size"])
        self.place(H.stapler_base(self.st, "body", "steel", "pad"), "body")
        self.grow(node.one(node.choice))

    def desk(self, node):
        self.grow(node.one("loader"))

    long_reach = desk

    def loader(self, node):
        self.grow(node.one(node.choice))

    def plier(self, node):
        self.grow(node.one("lifting_arm"), opens=ARM_OPENS)

    def top_loading(self, node):
        self.grow(node.one("head"))

    def front_loading(self, node):
        self.grow(node.one("lifting_arm"), opens=HEAD_OPENS)

    def head(self, node):
        mag = self.place(H.stapler_magazine(self.st, "steel", "body"), "magazine")
        self.hinge("body", "magazine", mag.anchor("pin"), upper=HEAD_OPENS, role="lid")
        self.grow(node.one("arm"))

    def arm(self, node):
        arm = self.place(H.stapler_arm(self.st, "body"), "arm")
        self.hinge("magazine", "arm", arm.anchor("pin"), upper=ARM_OPENS, role="lid")

    def lifting_arm(self, node, opens):
        arm = self.place(H.stapler_arm(self.st, "body"), "arm")
        self.hinge("body", "arm", arm.anchor("pin"), upper=opens, role="lid")
        self.grow(node.one("magazine"))

    def magazine(self, node):
        mag = self.place(H.stapler_magazine(self.st, "steel", "body"), "magazine")
        self.slide("arm", "magazine", mag.anchor("slide"), upper=PULLS * self.st.length)


CATEGORY = Category("stapler", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, StaplerLayout, MATERIALS)
