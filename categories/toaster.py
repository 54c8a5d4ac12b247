"""Toaster: a pop-up toaster (2-slot, 4-slot or long-slot) with carriage levers, browning dials, keys and a crumb tray.

Designs (``design``, sizes and sources in ``categories/parts/toasters.py``): a ``two_slot`` toaster with one
control group on its front; a ``four_slot`` side-by-side toaster with a control group per pair of slots; a
``long_slot`` toaster (two extra-long slots) with one control group or one per slot. A control group is a
carriage lever that rests at the top of its slot and slides down (prismatic, held up by its return spring:
role ``lever``), a browning dial turning 270 degrees from light to dark (most models; some set the shade with
keys), and up to three push keys pressed into the front (cancel, defrost, bagel: role ``button``); a two-slot
or single-control long-slot toaster has them at one end of its long side or stands end on, its controls up
the middle of its short end (``control_face``).
The crumb tray under the slots pulls out of the front (prismatic) by a lug on its front (the front sits flush).

X is depth (the controls face +X), Y is width, Z is up. The casing is a sheet box with rounded upright
corners; every hole in it (slots, lever slots, dial and key holes, the tray's opening) is a named cut-out
whose anchor places the part that goes through it.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import casing, controls
from .parts import toasters as T

PARAMS = (
    Float("size", "where the toaster lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    # bread slots 28-38 mm wide ("wide slot" models 38 mm: Breville, KitchenAid spec sheets)
    Float("slot_width", "bread slot width", "m", 0.028, 0.038),
    Float("corner", "radius of the casing's upright corners", "m", 0.01, 0.025),
    Choice("finish", "casing finish", choices=("brushed_metal", "painted", "plastic")),
    # both layouts are common: Cuisinart CPT-122, Breville BTA720XL (long side); Dualit, Smeg, KitchenAid (end)
    Choice("control_face", "a two-slot or single-control long-slot toaster's lever, dial and keys: at one end of"
           " its long side, or on its short end (then its front: the slots run front to back)",
           choices=T.CONTROL_FACES),
)

GRAMMAR = Grammar("toaster", {
    "toaster": Node(label="body", required=("tray",), one_of={"two_slot": 0.4, "four_slot": 0.3, "long_slot": 0.3},
                    choice="design"),
    "two_slot": Node(repeat={"controls": 1}),
    "four_slot": Node(repeat={"controls": 2}),
    "long_slot": Node(repeat={"controls": (1, 2)}),
    "controls": Node(required=("lever",), optional={"dial": 0.85}, repeat={"button": (0, T.BUTTONS_MAX)}),
    "lever": Node(label="lever"),
    "dial": Node(label="knob"),
    "button": Node(label="button"),
    "tray": Node(label="tray"),
})
"""A ``four_slot`` toaster has a control group per pair of slots; a ``long_slot`` one a group, or one per slot
(dual control); a group's dial is drawn object-wide (``has_dial``: keys-only models set the shade with keys),
its keys (0-3: cancel, defrost, bagel) per group."""

# down a slot: a mica card (amber-cream sheet) wound with nichrome ribbon (dark grey once fired) behind
# chrome guard wires (toaster teardown photos)
MATERIALS = {"body": "finish", "lever": "plastic:black", "knob": "plastic:black", "button": "plastic:black",
             "tray": "brushed_metal", "trim": "chrome", "chassis": "brushed_metal", "mica": "ceramic:cream|ivory",
             "element": "cast_iron", "carriage": "plastic:black"}
SUBSTRATES = {"body": ("finish", {"painted": 7850.0})}  # a painted casing is painted steel sheet


class ToasterLayout(controls.ControlFace):
    def toaster(self, node):
        p, design = self.p, node.choice
        groups = node.one(design).of("controls")
        size = T.casing_size(design, p["size"], p["corner"], T.end_on(design, p["control_face"], len(groups)))
        cuts = T.cutouts(design, size, p["slot_width"],
                         [(g.one("dial") is not None, len(g.of("button"))) for g in groups], p["control_face"])
        body = self.place(casing.sheet_casing(size, "body", cuts), "body")
        self.extend(body.root, T.slot_walls(size, cuts, "chassis") + T.carriage_guides(size, cuts, "carriage"))
        self.grow(node.one(design), body=body)
        self.grow(node.one("tray"), body=body, size=T.crumb_tray(size))

    def _groups(self, node, body):
        for i, group in enumerate(node.of("controls")):
            self.grow(group, body=body, i=i)

    two_slot = four_slot = long_slot = _groups

    def controls(self, node, body, i):
        self.grow(node.one("lever"), body=body, at=body.anchor(f"lever_{i}"), name=f"lever_{i}")
        if node.one("dial"):
            self.grow(node.one("dial"), body=body, at=body.anchor(f"dial_{i}"), name=f"dial_{i}")
        for k, key in enumerate(node.of("button")):
            self.grow(key, body=body, at=body.anchor(f"button_{i}_{k}"), name=f"button_{i}_{k}")

    def lever(self, node, body, at, name):
        self.place_lever(body.root, name, T.LEVER, at, "lever")

    def dial(self, node, body, at, name):
        self.place_dial(body.root, name, T.DIAL, at)

    def button(self, node, body, at, name):
        self.place_button(body.root, name, T.BUTTON, at)

    def tray(self, node, body, size):
        # its front is the casing's finish
        made = casing.liner(size, "tray", "body", label="tray")
        made = made.with_pieces(made.root, [casing.pull_tab(size, *T.TRAY_TAB, "body")])
        made = made.attached("front", to=body.anchor("tray_opening"))
        tray = self.place(made, "tray")
        self.slide(body.root, tray.root, tray.anchor("front"), upper=T.TRAY_PULL * size.depth)


CATEGORY = Category("toaster", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToasterLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=appliance)
