"""Toaster oven: a counter-top oven (4-slice, 6-slice, air-fryer) with a drop-down glass door, racks, knobs, crumb tray.

Designs (``design``, sizes and sources in ``categories/parts/toaster_ovens.py``): a ``compact`` 4-slice oven
(one rack, two or three knobs), a ``six_slice`` oven (two rack levels, three knobs, keys on some) and a
taller ``air_fry`` oven (one or two racks). The glazed door hinges at its bottom edge and drops forward to
horizontal (revolute about +Y); the wire racks slide out of the front on side rails only with the door open
(prismatic, ``requires_open``); the knobs on the right-hand control column turn from their rest stops
(temperature ~270 degrees, function ~180, timer ~300); keys press into the column; the crumb tray under the
cavity floor pulls out of the front (prismatic).

X is depth (the door faces +X), Y is width, Z is up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import casing, controls
from .parts import toaster_ovens as TO


def _count(what: str):
    def count(p, rng) -> int:
        lo, hi = getattr(TO.DESIGNS[p["design"]], what)
        return int(rng.integers(lo, hi + 1))
    count.__doc__ = f"{what} of the design, drawn in its range (``categories/parts/toaster_ovens.py``)"
    return count


PARAMS = (
    Float("size", "where the oven's footprint lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("tall", "where the oven's height lies in its design's height range (0 lowest, 1 tallest)", "", 0.0, 1.0),
    Float("corner", "radius of the casing's upright corners", "m", 0.004, 0.015),
    Choice("finish", "casing finish", choices=("brushed_metal", "painted")),
    Choice("handle_finish", "door handle material", choices=("chrome", "brushed_metal", "plastic")),
)

GRAMMAR = Grammar("toaster_oven", {
    "toaster_oven": Node(label="body", required=("door", "panel", "tray"),
                         one_of={"compact": 0.35, "six_slice": 0.4, "air_fry": 0.25}, choice="design"),
    "compact": Node(repeat={"rack": _count("racks")}),
    "six_slice": Node(repeat={"rack": _count("racks")}),
    "air_fry": Node(repeat={"rack": _count("racks")}),
    "panel": Node(repeat={"knob": _count("knobs"), "key": _count("keys")}),
    "door": Node(label="door"),
    "rack": Node(label="rack"),
    "knob": Node(label="knob"),
    "key": Node(label="button"),
    "tray": Node(label="tray"),
})
"""Racks, knobs and keys are counted per design (``categories/parts/toaster_ovens.py`` ``DESIGNS``)."""

# A toaster oven's cavity is dark non-stick or enamelled steel (Breville BOV800XL, Cuisinart TOB-260,
# Black+Decker TO1313SB product photos), its quartz heating tubes milky white when cold
MATERIALS = {"body": "finish", "door": "plastic:black", "door_inner": "plastic:black",
             "interior": "enamel:black|graphite|anthracite", "glass": "glass", "handle": "handle_finish",
             "rack": "chrome", "knob": "plastic:black", "button": "plastic:black", "trim": "chrome",
             "element": "ceramic:white|ivory", "feet": "rubber", "tray": "brushed_metal"}
SUBSTRATES = {"body": ("finish", {"painted": 7850.0})}  # a painted casing is painted steel sheet


class ToasterOvenLayout(controls.ControlFace):
    def toaster_oven(self, node):
        p, design = self.p, node.choice
        o = TO.oven(design, p["size"], p["corner"], p["tall"])
        racks, panel = node.one(design).of("rack"), node.one("panel")
        cuts = TO.cutouts(o, len(panel.of("knob")), len(panel.of("key")))
        body = self.place(TO.casing(o, len(racks), cuts), "body")
        self.grow(node.one("door"), body=body, o=o)
        self.grow(node.one(design), body=body, o=o)
        self.grow(panel, body=body)
        self.grow(node.one("tray"), body=body, o=o)

    def door(self, node, body, o):
        self.add("door", "door", TO.door(o))
        self.hinge(body.root, "door", body.anchor("hinge"), upper=TO.DOOR_OPENS)

    def _racks(self, node, body, o):
        racks = node.of("rack")
        for k, kid in enumerate(racks):
            self.grow(kid, body=body, o=o, k=k, n=len(racks))

    compact = six_slice = air_fry = _racks

    def rack(self, node, body, o, k, n):
        pieces, travel = TO.rack(o, n, k)
        name = self.add(f"rack_{k}", "rack", pieces)
        self.slide(body.root, name, body.anchor(f"rack_{k}"), upper=travel, requires_open="door")

    def panel(self, node, body):
        for k, kid in enumerate(node.of("knob")):
            self.grow(kid, body=body, k=k)
        for k, kid in enumerate(node.of("key")):
            self.grow(kid, body=body, k=k)

    def knob(self, node, body, k):
        spec = controls.Dial(TO.KNOB.radius, TO.KNOB.stem, TO.KNOB.style, TO.KNOB_TURNS[k])
        self.place_dial(body.root, f"knob_{k}", spec, body.anchor(f"knob_{k}"))

    def key(self, node, body, k):
        self.place_button(body.root, f"key_{k}", TO.KEY, body.anchor(f"key_{k}"))

    def tray(self, node, body, o):
        made = casing.liner(o.tray, "tray", "body", label="tray").attached("front", to=body.anchor("tray_opening"))
        tray = self.place(made, "tray")
        self.slide(body.root, tray.root, tray.anchor("front"), upper=TO.TRAY["pull"] * o.tray.depth)


CATEGORY = Category("toaster_oven", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ToasterOvenLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=appliance)
