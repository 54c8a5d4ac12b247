"""Pepper grinder: a manual mill with a turning head, a salt-and-pepper pair on a tray, or a battery mill with a button.

Designs (``design``): a manual mill (a Paris-style turned body whose head turns without stop to grind and lifts
off its spindle to refill, maybe a coarseness nut atop the head); a pair of mills standing in the sockets of a
tray, each lifting out of its socket, its head turning to grind and carrying a flip-top filler lid or a
coarseness nut; a battery mill whose cap over the cells lifts off, with a push button on it (role ``button``)
unless it is a gravity mill that grinds when tipped over. Any mill may have a
coarseness ring round its foot that turns ~300 degrees between its settings. The contents (peppercorns, or salt
in a pair's second mill) are inside and massed; an acrylic body shows them. Parts:
``categories/parts/grinders.py``.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import grinders as M

GRAMMAR = Grammar("pepper_grinder", {
    "pepper_grinder": Node(one_of={"manual": 0.4, "pair": 0.3, "electric": 0.3}, choice="design"),
    "manual": Node(label="body", required=("head",), optional={"ring": 0.5}),
    "head": Node(label="head", optional={"finial": 0.6}),
    "finial": Node(label="knob"),
    "ring": Node(label="knob"),
    "pair": Node(label="base", repeat={"mill": 2}),
    "mill": Node(label="body", required=("mill_head",), optional={"ring": 0.5}),
    "mill_head": Node(label="head", one_of={"flip_lid": 0.5, "finial": 0.5}, choice="filler"),
    "flip_lid": Node(label="lid"),
    "electric": Node(label="body", required=("cap",), optional={"ring": 0.5}),
    "cap": Node(label="lid", optional={"button": 0.75}),
    "button": Node(label="button"),
})
"""A manual mill may have a coarseness nut on its head (``has_finial``); a pair's heads carry a flip-top filler lid
or a coarseness nut (``filler``, both alike); a battery mill has a push button, or none when it grinds as it is
tipped over (a gravity mill, ``has_button``); any mill a coarseness ring round its foot (``has_ring``, object-wide:
both mills of a pair alike)."""

PARAMS = (
    Float("size", "where the mill lies in its design's size range (MILLS in parts/grinders.py), 0 to 1", "", 0.0, 1.0),
    Choice("shape", "the body's outline", choices=("classic", "column", "taper")),
    Choice("finish", "the body: turned wood, lacquered wood, a steel sleeve or clear acrylic",
           choices=("wood", "lacquer", "steel", "acrylic")),
)

MATERIALS = {
    "body": ("finish", {"wood": "wood", "lacquer": "painted:black|white|red|navy|sage", "steel": "brushed_metal",
                        "acrylic": "glass:clear"}),
    "head": "plastic:black|dark_grey",
    "knob": "chrome", "ring": "brushed_metal", "metal": "brushed_metal", "pepper": "cast_iron:seasoned",
    "salt": "ceramic:white",
    "tray": "wood", "button": "plastic:black|dark_grey", "cells": "painted:black",
}
# peppercorns pour at 0.5-0.6 g/cm3, table salt at ~1.2 g/cm3 (bulk densities); acrylic (PMMA) 1190 kg/m3
SUBSTRATES = {"pepper": 550.0, "salt": 1200.0, "body": ("finish", {"acrylic": 1190.0})}


class GrinderLayout(Layout):
    def pepper_grinder(self, node):
        self.grow(node.one(node.choice), design=node.choice)

    @property
    def head_slot(self):
        """An acrylic mill's head is moulded black plastic; other heads are finished as the body."""
        return "head" if self.p["finish"] == "acrylic" else "body"

    def _size(self, node, design):
        return M.Size.make(design, self.p["size"], self.p["finish"], node.one("ring") is not None)

    def _body(self, node, s, name, contents, frame=None):
        made = M.body(s, self.p["shape"], "body", contents, "metal")
        return self.place(made if frame is None else made.mounted(frame), name)

    def _ring(self, node, body, s):
        if node.one("ring"):
            self.grow(node.one("ring"), body=body, s=s)

    def manual(self, node, design):
        s = self._size(node, design)
        body = self._body(node, s, "body", "pepper")
        self._ring(node, body, s)
        self.grow(node.one("head"), body=body, s=s)

    def head(self, node, body, s):
        head = self.place(M.head(s, self.head_slot, flat=False).attached("seat", to=body.anchor("seat")), "head")
        seat = body.anchor("seat")
        self.join(J.continuous_prismatic(body.root, head.root, tuple(seat.origin), tuple(seat.z), (0.0, M.HEAD_LIFT),
                                         role="lift_off"))
        if node.one("finial"):
            self.grow(node.one("finial"), head=head)

    def finial(self, node, head, k=None, s=None):
        name = "finial" if k is None else f"finial_{k}"
        knob = self.place(M.finial("knob").attached("axis", to=head.anchor("top")), name)
        self.hinge(head.root, knob.root, head.anchor("top"), upper=M.FINIAL["turns"], role="knob")

    def ring(self, node, body, s):
        name = body.root.replace("body", "ring") if body.root != "body" else "ring"
        made = self.place(M.ring(s, "ring").attached("axis", to=body.anchor("ring").moved(dz=M.GAP)), name)
        # a pair's mill stands in its tray's socket, which hides its ring: it is turned with the mill lifted out
        gate = body.root if body.root != "body" else None
        self.hinge(body.root, made.root, made.anchor("axis"), upper=M.RING["turns"], role="knob", requires_open=gate)

    def pair(self, node, design):
        s = self._size(node.of("mill")[0], design)
        tray, frames = M.tray(s, "tray")
        base = self.place(tray, "base")
        for k, (kid, frame) in enumerate(zip(node.of("mill"), frames)):
            self.grow(kid, base=base, frame=frame, k=k, s=s)

    def mill(self, node, base, frame, k, s):
        body = self._body(node, s, f"body_{k}", ("pepper", "salt")[k], frame.moved(dz=M.GAP))
        self.lift(base.root, body.root, frame.moved(dz=M.GAP), engagement=M.TRAY["socket"])
        self._ring(node, body, s)
        self.grow(node.one("mill_head"), body=body, k=k, s=s)

    def mill_head(self, node, body, k, s):
        head = self.place(M.head(s, self.head_slot, flat=True).attached("seat", to=body.anchor("seat")), f"head_{k}")
        self.spin(body.root, head.root, body.anchor("seat"), role="knob")
        self.grow(node.one(node.choice), head=head, k=k, s=s)

    def flip_lid(self, node, head, k, s):
        lid = self.place(M.flip_lid(s, self.head_slot).attached("mount", to=head.anchor("top")), f"lid_{k}")
        self.hinge(head.root, lid.root, lid.anchor("hinge"), upper=M.FLIP["opens"])

    def electric(self, node, design):
        s = self._size(node, design)
        body = self._body(node, s, "body", "pepper")
        self._ring(node, body, s)
        self.grow(node.one("cap"), body=body, s=s)

    def cap(self, node, body, s):
        made, volume = M.cap(s, self.head_slot, "cells")
        self.bp.densities["cells"] = M.CELLS["kg"] / volume  # the motor and cells over the space they fill
        cap = self.place(made.attached("seat", to=body.anchor("seat")), "cap")
        self.lift(body.root, cap.root, body.anchor("seat"))
        if node.one("button"):
            self.grow(node.one("button"), cap=cap)

    def button(self, node, cap):
        made = self.place(M.button("button").attached("mount", to=cap.anchor("top")), "button")
        self.slide(cap.root, made.root, made.anchor("press"), upper=M.BUTTON["travel"], role="button")


CATEGORY = Category("pepper_grinder", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, GrinderLayout, MATERIALS,
                    substrates=SUBSTRATES)
