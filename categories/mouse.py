"""Mouse: a corded office mouse, a wireless mouse or a gaming mouse with thumb buttons, on its skates.

Designs (``design``, sizes and sources in ``categories/parts/mice.py``): a ``wired`` office mouse with its
cable and USB plug, a shorter ``wireless`` one, and a ``gaming`` mouse (corded) with a grid of 2-12 thumb
buttons, DPI buttons behind the wheel and perhaps a sniper button or a second pair of thumb buttons on the
right (ambidextrous). Every mouse has a left and a right main button, each hinged across its rear edge
(revolute about +Y: the front presses down ~1.2 mm onto its microswitch, which springs it back, role
``button``), and a scroll wheel turning on its axle (continuous, role ``knob``). Thumb, sniper and DPI
buttons press into the shell (prismatic, role ``button``). X is the mouse's front, Y across (left +Y), Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import mice as M


def thumb_grid_count(params, rng) -> int:
    """A gaming mouse's thumb-button count, drawn from ``mice.THUMB_GRIDS``."""
    counts = list(M.THUMB_GRIDS)
    w = [M.THUMB_GRIDS[c] for c in counts]
    return counts[int(rng.choice(len(counts), p=[x / sum(w) for x in w]))]


FINISHES = ("black", "dark_grey", "light_grey", "white", "red", "blue", "teal")

GRAMMAR = Grammar("mouse", {
    "mouse": Node(label="body", required=("left_button", "right_button", "wheel"),
                  one_of={"wired": 0.3, "wireless": 0.25, "gaming": 0.45}, choice="design"),
    "wired": Node(required=("cable",), optional={"thumb_buttons": 0.4, "dpi": 0.25}),
    "wireless": Node(optional={"thumb_buttons": 0.4, "dpi": 0.25, "mode": 0.4}),
    "gaming": Node(required=("cable", "thumb_grid", "dpi_row"), optional={"sniper": 0.35, "right_thumb": 0.2,
                                                                          "mode": 0.4}),
    "cable": Node(),
    "thumb_buttons": Node(repeat={"side_button": 2}),
    "thumb_grid": Node(repeat={"side_button": thumb_grid_count}),
    "right_thumb": Node(repeat={"right_side_button": 2}),
    "dpi": Node(repeat={"dpi_button": 1}),
    "dpi_row": Node(repeat={"dpi_button": (1, 2)}),
    "sniper": Node(label="sniper_button"),
    "mode": Node(label="mode_button"),
    "left_button": Node(label="left_button"),
    "right_button": Node(label="right_button"),
    "wheel": Node(label="wheel"),
    "side_button": Node(label="side_button"),
    "right_side_button": Node(label="right_side_button"),
    "dpi_button": Node(label="dpi_button"),
})
"""``thumb_grid``: 2-12 thumb buttons (``mice.THUMB_GRIDS``); ``right_thumb``: an ambidextrous mouse's pair on the
right wall; ``dpi_row``: one or two DPI buttons; ``mode``: the wheel-mode button behind the wheel (Logitech's
free-spin / ratchet shift: M720, MX Anywhere, G502)."""

PARAMS = (
    Float("size", "where the length lies in its design's range (mice.MICE)", "", 0.0, 1.0),
    Float("width", "where the width lies in its design's range", "", 0.0, 1.0),
    Float("height", "where the height lies in its design's range", "", 0.0, 1.0),
    Float("hump", "moves the hump's peak back (-) or forward (+), as a share of the length", "", -0.06, 0.06),
    Float("bend", "which way and how far the cable curves off (-1 right, +1 left)", "", -1.0, 1.0),
    Float("taper", "the plan: an even office mouse (0) to an egg narrowing to its nose (1)", "", 0.0, 1.0),
    # one colour for the shell and the buttons (an office mouse's buttons are moulded to match its shell)
    Choice("finish", "the shell's colour", choices=FINISHES, weights=(0.45, 0.12, 0.08, 0.2, 0.05, 0.05, 0.05)),
)

MATERIALS = {
    "shell": ("finish", {c: f"plastic:{c}" for c in FINISHES}),
    "buttons": Same("shell"), "keys": "plastic:black|dark_grey", "wheel": "rubber", "hub": "plastic:dark_grey",
    "feet": "plastic:white", "cable": "rubber", "plug": "plastic:black|dark_grey", "metal": "chrome",
}
SUBSTRATES = {"shell": M.MOUSE_DENSITY}


class MouseLayout(Layout):
    def mouse(self, node):
        p = self.p
        self.m = m = M.mouse(node.choice, p["size"], p["width"], p["height"], p["hump"], p["taper"])
        d = node.one(node.choice)
        grid = d.one("thumb_grid") or d.one("thumb_buttons")
        self.left = M.thumb_grid(m, len(grid.of("side_button")), 1, d.one("sniper") is not None) if grid else []
        self.right = M.thumb_grid(m, 2, -1, False) if d.one("right_thumb") else []
        dpi = d.one("dpi") or d.one("dpi_row")
        mode = 1 if d.one("mode") else 0
        self.dpis = M.dpi_keys(m, mode + (len(dpi.of("dpi_button")) if dpi else 0))[mode:]
        self.mode_key = M.dpi_keys(m, 1)[0]
        zones = M.zones_for(m, self.left + self.right + self.dpis + ([self.mode_key] if mode else []))
        self.add("body", "body", M.body(m, zones, "shell", "feet"))
        for side, kind in ((1, "left_button"), (-1, "right_button")):
            self.grow(node.one(kind), side=side)
        self.grow(node.one("wheel"))
        self.grow(d)

    def left_button(self, node, side):
        placed = self.place(M.main_button(self.m, side, "buttons", node.kind), node.kind)
        self.hinge("body", placed.root, placed.anchor("hinge"), upper=M.press_angle(self.m), role="button")

    right_button = left_button

    def wheel(self, node):
        placed = self.place(M.wheel(self.m, "wheel", "hub"), "wheel")
        self.spin("body", placed.root, placed.anchor("axle"), role="knob")

    def wired(self, node):
        for kid in node.children:
            self.grow(kid)

    gaming = wired

    def wireless(self, node):
        self.extend("body", M.underside(self.m, "hub", "keys"))
        self.wired(node)

    def cable(self, node):
        self.extend("body", M.cable(self.m, "cable", "plug", "metal", self.p["bend"]))

    def thumb_buttons(self, node):
        keys = self.left[:len(node.of("side_button"))]
        for k, (kid, key) in enumerate(zip(node.of("side_button"), keys, strict=True)):
            self.grow(kid, key=key, name=f"side_button_{k}")

    thumb_grid = thumb_buttons

    def right_thumb(self, node):
        for k, (kid, key) in enumerate(zip(node.of("right_side_button"), self.right, strict=True)):
            self.grow(kid, key=key, name=f"right_side_button_{k}")

    def dpi(self, node):
        for k, (kid, key) in enumerate(zip(node.of("dpi_button"), self.dpis, strict=True)):
            self.grow(kid, key=key, name=f"dpi_button_{k}")

    dpi_row = dpi

    def sniper(self, node):
        self.side_button(node, self.left[-1], "sniper_button", "sniper_button")

    def side_button(self, node, key, name, label=None):
        placed = self.place(M.key_part(key, "keys", label or node.kind), name)
        self.slide("body", placed.root, placed.anchor("press"), upper=key.travel, role="button")

    dpi_button = right_side_button = side_button

    def mode(self, node):
        self.side_button(node, self.mode_key, "mode_button", "mode_button")


CATEGORY = Category("mouse", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, MouseLayout, MATERIALS,
                    substrates=SUBSTRATES)
