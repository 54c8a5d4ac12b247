"""USB flash drive: a swivel drive, a capped drive or a retractable slider, lying flat with its plug ahead.

Designs (``design``, sizes and sources in ``categories/parts/usb.py``): a ``swivel`` drive's U-shaped steel
cover turns about the rivet through the body's back end (revolute about +z, half a turn: the bight leaves
the plug and comes to rest behind the body); a ``capped`` drive's cap pulls off its plug (prismatic along
+x, lift-off: free once past the neck and the plug it fits over); a ``slider``'s sled, pushed by a thumb
button riding in the sleeve's top slot, carries the plug out of the sleeve's mouth (prismatic along +x).
The plug is a USB-A or a USB-C (``plug``). X is the plug's direction, Y across, Z up.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import usb as U

COLOURS = ("black", "red", "blue", "dark_grey", "white", "teal", "orange", "light_grey")
PARAMS = (
    Float("size", "where the body's length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Float("shape", "width within the design's range (0 slim, 1 wide); thickest at the middle", "", 0.0, 1.0),
    Float("roundness", "edges and corners: crisp (0) to pebble-round (1)", "", 0.0, 1.0),
    Choice("plug", "USB-A (12 x 4.5 mm shell) or USB-C (8.3 x 2.4 mm)", choices=("a", "c"), weights=(0.7, 0.3)),
    Choice("body_colour", "moulded body colour", choices=COLOURS, weights=(0.3, 0.12, 0.12, 0.12, 0.1, 0.08, 0.08,
                                                                            0.08)),
    Choice("accent", "cap, sled and button colour: the body's or black", choices=("body", "black")),
    # white inserts are the cheapest USB 2.0 drives' (a white tongue in the shell reads as a plastic plug)
    Choice("insert", "the USB-A insert: blue (USB 3), black or white (USB 2)", choices=("blue", "black", "white"),
           weights=(0.45, 0.45, 0.1)),
    Choice("steel", "swivel cover finish", choices=("brushed_metal", "chrome")),
)

GRAMMAR = Grammar("usb", {
    "usb": Node(one_of={"swivel": 0.35, "capped": 0.35, "slider": 0.3}, choice="design"),
    "swivel": Node(label="body", required=("cover",)),
    "capped": Node(label="body", required=("cap",)),
    "slider": Node(label="body", required=("sled",)),
    "cover": Node(label="cover"),
    "cap": Node(label="cap"),
    "sled": Node(label="sled"),
})
"""Each design has one body and the one part that covers or carries its plug."""

MATERIALS = {"body": ("body_colour", {c: f"plastic:{c}" for c in COLOURS}),
             "accent": ("accent", {"black": "plastic:black"} | {"body": "plastic:black|dark_grey|white"}),
             "steel": ("steel", {"brushed_metal": "brushed_metal:stainless"}),
             # a plug's shell is nickel-plated steel (USB 2.0 spec 6.5.3: 'nickel plate'), a bright plating
             "shell": "chrome:chrome",
             "insert": ("insert", {c: f"plastic:{c}" for c in ("blue", "black", "white")}), "mouth": "plastic:black"}
SWIVELS = math.pi  # the cover turns half round, from over the plug to behind the body


class UsbLayout(Layout):
    def usb(self, node):
        p = self.p
        self.u = U.usb(node.choice, p["size"], p["shape"], p["plug"], p["roundness"])
        self.insert = "insert" if p["plug"] == "a" else "mouth"
        self.accent = "body" if p["accent"] == "body" else "accent"
        self.grow(node.one(node.choice))

    def swivel(self, node):
        self.place(U.swivel_body(self.u, "body", "shell", self.insert), "body")
        self.grow(node.one("cover"))

    def capped(self, node):
        self.place(U.capped_body(self.u, "body", "shell", self.insert, self.accent), "body")
        self.grow(node.one("cap"))

    def slider(self, node):
        self.place(U.sleeve(self.u, "body", "mouth"), "body")
        self.grow(node.one("sled"))

    def cover(self, node):
        cover = self.place(U.swivel_cover(self.u, "steel"), "cover")
        self.hinge("body", "cover", cover.anchor("pivot"), upper=SWIVELS, role="swivel")

    def cap(self, node):
        cap = self.place(U.cap(self.u, self.accent), "cap")
        self.lift("body", "cap", cap.anchor("pull"), engagement=U.cap_engagement(self.u))

    def sled(self, node):
        sled = self.place(U.slider_sled(self.u, "body", self.accent, "shell", self.insert), "sled")
        self.slide("body", "sled", sled.anchor("slide"), upper=U.slider_travel(self.u))


CATEGORY = Category("usb", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, UsbLayout, MATERIALS)
