"""Toaster: a two-slot pop-up toaster with a carriage lever, a browning dial and a crumb tray.

A newcomer's category written against the part contract: the casing, the controls and the tray are
parts with anchors (``categories/parts/casing.py``, ``controls.py``); this module holds the real sizes
and says what goes where, never a coordinate. Dropped into ``categories/`` as ``toaster.py`` it becomes
a category (discovery registers it); the tests build it from here.

The lever rests at the top of its slot and slides down (a prismatic joint, its rest the lower limit);
its return spring (role ``lever``) holds it up; on a real toaster it also drives the bread carriage inside
(a coupled joint, ``Layout.couple``, once the carriage is a part).
"""

from __future__ import annotations

import math

from infmob_usd.categories.parts import casing, controls
from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

# Two-slice pop-up toasters (Breville, KitchenAid, Dualit retail spec sheets): 0.28-0.31 m wide,
# 0.17-0.20 m deep, 0.17-0.20 m tall, 1.2-1.7 kg; bread slots 28-38 mm wide ("wide slot" models 38 mm).
PARAMS = (
    Float("width", "outer width (Y)", "m", 0.28, 0.31),
    Float("depth", "outer depth (X)", "m", 0.17, 0.20),
    Float("height", "outer height (Z)", "m", 0.17, 0.20),
    Float("slot_width", "bread slot width", "m", 0.028, 0.038),
    Float("corner", "radius of the casing's upright corners", "m", 0.01, 0.025),
    Choice("finish", "casing finish", choices=("brushed_metal", "painted", "plastic")),
)

GRAMMAR = Grammar("toaster", {
    "toaster": Node(label="body", required=("lever", "dial", "tray")),
    "lever": Node(label="lever"),
    "dial": Node(label="knob"),
    "tray": Node(label="tray"),
})

MATERIALS = {"body": "finish", "lever": "plastic:black", "knob": "plastic:black", "tray": "brushed_metal",
             "tray_front": Same("body"), "trim": "chrome"}
SUBSTRATES = {"body": ("finish", {"painted": 7850.0})}  # a painted casing is painted steel sheet

SHEET = 0.0006  # m, steel of a toaster casing: 0.5-0.7 mm stainless or painted sheet
WALL = 0.003  # m, the casing walls as the simulator sees them (massed as SHEET)
SLOT_LENGTH = 0.135  # m, a bread slot's length: a sandwich slice is 0.11-0.13 m
SLOT_GAP = 0.02  # m, wall between the two slots
# Replacement carriage levers and browning knobs (product photos): a 40 x 15 mm paddle 25 mm out on a
# 6 x 4 mm stem that travels ~80 mm down; a 15 mm knob turning ~270 degrees from light to dark.
LEVER = controls.Lever(stem=(0.006, 0.004), paddle=(0.04, 0.015, 0.012), reach=0.013, travel=0.08)
DIAL = controls.Dial(radius=0.015, stem=0.003, style="round", turns=math.radians(270))
TRAY = dict(height=0.01, lip=0.01, clearance=0.002)  # a crumb tray 10 mm deep with a 20 mm front
LEVER_AT = (0.65, 0.6)  # lever and dial on the front, as fractions of its half width and half height
DIAL_AT = (-0.65, 0.2)


class ToasterLayout(controls.ControlFace):
    def toaster(self, node):
        p = self.p
        size = casing.CasingSize(p["width"], p["depth"], p["height"], WALL, SHEET, p["corner"])
        tray = casing.LinerSize(size.clear_width - 2 * TRAY["clearance"], size.depth - 2 * WALL - TRAY["clearance"],
                                TRAY["height"], WALL, SHEET, TRAY["lip"], WALL)
        cuts = {"lever_slot": LEVER.cutout("front", size.on("front", *LEVER_AT)),
                "dial_hole": DIAL.cutout("front", size.on("front", *DIAL_AT)),
                "tray_opening": size.floor_opening("front", tray.width, tray.height + tray.lip, TRAY["clearance"]),
                **size.slots("top", SLOT_LENGTH, p["slot_width"], SLOT_GAP)}
        body = self.place(casing.sheet_casing(size, "body", cuts), "body")
        for kind in ("lever", "dial"):
            self.grow(node.one(kind), body=body)
        self.grow(node.one("tray"), body=body, size=tray)

    def lever(self, node, body):
        self.place_lever(body.root, "lever", LEVER, body.anchor("lever_slot"), "lever")

    def dial(self, node, body):
        self.place_dial(body.root, "dial", DIAL, body.anchor("dial_hole"))

    def tray(self, node, body, size):
        made = casing.liner(size, "tray", "tray_front", label="tray").attached("front", to=body.anchor("tray_opening"))
        tray = self.place(made, "tray")
        self.slide(body.root, tray.root, tray.anchor("front"), upper=0.8 * size.depth)


CATEGORY = Category("toaster", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToasterLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=appliance)
