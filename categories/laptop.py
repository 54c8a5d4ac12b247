"""Laptop: a clamshell or a 360-degree convertible, with or without a numeric pad.

X is the front (the trackpad's side), Y across, Z up; the laptop stands closed on its rubber feet. The lid
turns about the hinge line along the base's back edge (revolute about -Y: its front edge rises) from closed
to its stop: a ``clamshell``'s hinge stops at 120-180 degrees, a ``convertible``'s two knuckles turn it
360 degrees, under the base (standing on a table the ground stops it near 180; real convertibles' hinges are
dual-axis, geared 1:1, which only matters once the lid passes 180). Like a real friction hinge the lid stays
where it is put (role ``holding``: the core sizes its friction to hold the lid at any angle). The trackpad
clicks down (a press, role ``button``); the keys are drawn one by one, and with ``has_keys`` the space bar,
the power key and the arrows (``moving_keys`` of them, in that order) press down on return springs (role
``button``), the others caps fixed to the key bed. A ``numpad`` adds a numeric pad right of the keys on a
wider laptop. Parts: ``categories/parts/laptops.py`` (sizes from named products, keyboard layout, lid, hinges).
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import laptops as L

GRAMMAR = Grammar("laptop", {
    "laptop": Node(label="base", required=("keyboard", "trackpad"), optional={"keys": 0.7, "numpad": 0.35},
                   one_of={"clamshell": 0.6, "convertible": 0.4}, choice="design"),
    "clamshell": Node(label=None, required=("lid",)),
    "convertible": Node(label=None, required=("lid",)),
    "lid": Node(label="lid"),
    "keyboard": Node(label=None),
    "numpad": Node(label=None),
    "trackpad": Node(label="trackpad"),
    "keys": Node(repeat={"key": "moving_keys"}),
    "key": Node(label="key"),
})
"""``keys``: the keys that move (space bar first); without it every key is a cap fixed to the bed.
``numpad``: a numeric pad (the laptop then takes the 15-17 inch widths of laptops that have one)."""

PARAMS = (
    Float("size", "where the width lies in its design's range (0 smallest, 1 largest; laptops.WIDTH)", "", 0.0, 1.0),
    Float("depth_ratio", "depth / width (laptops.DEPTH_RATIO)", "", *L.DEPTH_RATIO),
    Float("thickness", "where the closed thickness lies in 11.3-20.6 mm (0 thinnest)", "", 0.0, 1.0),
    Float("lid_share", "the lid's share of the closed thickness", "", *L.LID_SHARE),
    Float("corner", "corner radius of the footprint", "m", *L.CORNER),
    Float("bezel", "the display's side and top bezel", "m", *L.BEZEL),
    Float("opens", "a clamshell lid's stop (a convertible's: 360 degrees)", "rad", *L.CLAMSHELL_OPENS),
    Int("moving_keys", "how many keys move: space, power, left, right, up, down in that order", "", 1,
        len(L.MOVING)),
    Choice("aspect", "display aspect ratio", choices=tuple(L.DISPLAY_ASPECT), weights=(0.55, 0.45)),
    Choice("finish", "the shell's finish", choices=("silver", "space_grey", "black", "white", "blue"),
           weights=(0.35, 0.2, 0.25, 0.1, 0.1)),
)

MATERIALS = {
    "body": ("finish", {"silver": "brushed_metal", "space_grey": "painted:charcoal|graphite|grey",
                        "black": "plastic:black|dark_grey", "white": "plastic:white|light_grey",
                        "blue": "painted:navy"}),  # Surface Laptop, XPS "frost" / Spectre "nightfall" colours
    "trackpad": Same("body"),
    "keys": "plastic:black|dark_grey", "bezel": "plastic:black", "display": "screen", "feet": "rubber",
    "logo": "chrome", "ports": "plastic:black",
}
SUBSTRATES = {"body": L.LAPTOP_DENSITY, "trackpad": 2500.0}  # a glass click pad
SLOTS = {k: k for k in ("body", "bezel", "display", "logo")}


class LaptopLayout(Layout):
    def laptop(self, node):
        p = self.p
        b = L.laptop(node.choice, node.one("numpad") is not None, p["size"], p["depth_ratio"], p["thickness"],
                     p["lid_share"], p["corner"])
        keys, _, (kb_front, y_mid) = L.keyboard(b)
        keys_node = node.one("keys")
        movers = L.moving(keys, len(keys_node.of("key"))) if keys_node else []
        pad = L.trackpad(b, kb_front, y_mid)
        deck = L.bed(b, keys, pad, movers, "body")
        self.add("base", "base", L.base(b, "body", "feet") + L.ports(b, "ports") + [deck])
        self.grow(node.one("keyboard"), b=b, keys=[k for k in keys if k not in movers and not k.pad])
        if node.one("numpad"):
            self.grow(node.one("numpad"), b=b, keys=[k for k in keys if k.pad])
        self.grow(node.one(node.choice), b=b)  # the lid first: the pad and the keys need it open
        self.grow(node.one("trackpad"), pad=pad, b=b)
        if keys_node:
            self.grow(keys_node, b=b, movers=movers)

    def keyboard(self, node, b, keys):
        self.extend("base", L.fixed_caps(b, keys, "keys"))

    numpad = keyboard

    def keys(self, node, b, movers):
        for k, (kid, key) in enumerate(zip(node.of("key"), movers, strict=True)):
            self.grow(kid, key=key, b=b, name=f"key_{k}")

    def key(self, node, key, b, name):
        placed = self.place(L.key_part(key, b.Tb + L.BED, "keys"), name)
        # under the closed lid: pressed once the lid is open
        self.slide("base", placed.root, placed.anchor("press"), upper=L.KEY_TRAVEL, role="button", requires_open="lid")

    def trackpad(self, node, pad, b):
        placed = self.place(L.key_part(pad, b.Tb + L.BED - L.TRACKPAD["thick"] + L.TRACKPAD["proud"], "trackpad",
                                       L.TRACKPAD["thick"], "trackpad"), "trackpad")
        self.slide("base", placed.root, placed.anchor("press"), upper=L.TRACKPAD["travel"], role="button",
                   requires_open="lid")

    def lid(self, node, b):
        self.add("lid", "lid", L.lid(b, self.p["aspect"], self.p["bezel"], SLOTS))

    def clamshell(self, node, b):
        self.grow(node.one("lid"), b=b)
        knuckles, axis = L.hinge(b, "body", node.kind == "convertible")
        self.extend("lid", knuckles)
        self.hinge("base", "lid", axis, upper=self.p["opens"] if node.kind == "clamshell" else L.CONVERTIBLE_OPENS,
                   role="holding")

    convertible = clamshell


CATEGORY = Category("laptop", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, LaptopLayout, MATERIALS,
                    substrates=SUBSTRATES)
