"""Switch: a wall plate of 1-4 gangs with toggles, rockers, push buttons or rotary dimmers.

Designs (``design``, sizes and sources in ``categories/parts/switches.py``): ``toggles`` (a NEMA plate of toggle
switches: each bat rests down and is flipped up, revolute, role ``toggle``: no return spring; a gang may
be a rotary dimmer instead), ``rockers`` (Decora paddles on a NEMA plate or 55 mm rockers in a European frame,
each rocking about its middle, revolute, role ``toggle``; a gang may be a dimmer), ``buttons`` (push buttons
sliding in against their springs, prismatic, role ``button``: vintage two-button switches on a NEMA plate, or one
or two push keys side by side in a European frame), ``dimmers`` (a rotary dimmer knob turning ~300 degrees from
off, revolute; the other gangs rockers or dimmers). The first gang
is always the design's own device.

A switch mounts on a wall: the plate's back is the wall plane and faces -X, its face +X; the device bodies reach
back into the wall box. The object stands on the plate's lower edge (simulators fix its base, as on a wall).
X is out of the wall, Y along it, Z up.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float, Int

from .parts import controls
from .parts import switches as S


def _more(p: dict, rng) -> int:
    """The gangs after the first."""
    return p["gangs"] - 1


PARAMS = (
    Int("gangs", "devices side by side on the plate", low=1, high=4),
    Choice("standard", "plate standard: nema (North American) or iec (European 55 mm system; toggles are nema only)",
           choices=("nema", "iec")),
    Float("knob_size", "a dimmer knob's diameter within its range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Choice("finish", "plate finish", choices=("plastic", "brushed_metal", "chrome")),
)

GRAMMAR = Grammar("switch", {
    "switch": Node(label="plate", one_of={"toggles": 0.3, "rockers": 0.3, "buttons": 0.2, "dimmers": 0.2},
                   choice="design"),
    "toggles": Node(required=("toggle",), repeat={"toggle_gang": _more}),
    "rockers": Node(required=("rocker",), repeat={"rocker_gang": _more}),
    "buttons": Node(required=("push",), repeat={"push_gang": _more}),
    "dimmers": Node(required=("dimmer",), repeat={"dimmer_gang": _more}),
    "toggle_gang": Node(one_of={"toggle": 0.85, "dimmer": 0.15}),
    "rocker_gang": Node(one_of={"rocker": 0.6, "slide_dimmer": 0.2, "dimmer": 0.2}),
    "push_gang": Node(required=("push",)),
    "dimmer_gang": Node(one_of={"dimmer": 0.6, "rocker": 0.4}),
    "push": Node(repeat={"button": (1, 2)}),
    "toggle": Node(label="toggle"),
    "rocker": Node(repeat={"paddle": (1, 2)}),
    "slide_dimmer": Node(required=("paddle", "slider")),
    "dimmer": Node(one_of={"rotary": 0.5, "push_rotary": 0.5}),
    "paddle": Node(label="rocker"),
    "slider": Node(label="slider"),
    "rotary": Node(label="knob"),
    "push_rotary": Node(label="knob"),
    "button": Node(label="button"),
})

MATERIALS = {"plate": ("finish", {"plastic": "plastic:white|light_grey|black"}),
             "device": "plastic:white|light_grey|black|dark_grey", "toggle": Same("device"),
             "button": Same("device"), "knob": "plastic:white|black|dark_grey", "trim": "plastic:dark_grey"}
SUBSTRATES = {"plate": ("finish", {"brushed_metal": 7850.0, "chrome": 7850.0})}  # a metal plate is steel sheet


def _derive(p: dict) -> dict:
    if p["design"] == "toggles" and p["standard"] != "nema":
        return {**p, "standard": "nema"}
    return p


def _gangs(design_node) -> list:
    """The device node of every gang, left to right (a gang node's one child, else the node itself)."""
    return [c.children[0] if c.kind.endswith("_gang") else c for c in design_node.children]


class SwitchLayout(controls.ControlFace):
    def switch(self, node):
        design = node.one(node.choice)
        devices = _gangs(design)
        plate = S.Plate(self.p["standard"], tuple(d.kind for d in devices))
        holes = [S.opening(plate, d.kind, len(d.of("button"))) for d in devices]
        self.add("plate", "plate", S.plate_pieces(plate, holes, "plate", "device", S.SHEET[self.p["finish"]]))
        self.grow(design, plate=plate)

    def _gangs(self, node, plate):
        for k, kid in enumerate(node.children):
            self.grow(kid, plate=plate, k=k)

    toggles = rockers = buttons = dimmers = _gangs

    def _gang(self, node, plate, k):
        self.grow(node.children[0], plate=plate, k=k)

    toggle_gang = rocker_gang = push_gang = dimmer_gang = _gang

    def toggle(self, node, plate, k):
        pieces, pivot, throw = S.toggle(plate, k, "toggle")
        self.hinge("plate", self.add(f"toggle_{k}", "toggle", pieces), pivot, upper=throw, role="toggle")

    def rocker(self, node, plate, k):
        paddles = node.of("paddle")
        for j, (kid, cell) in enumerate(zip(paddles, S.rocker_cells(plate, len(paddles)))):
            self.grow(kid, plate=plate, k=k, cell=cell, j=j)

    def slide_dimmer(self, node, plate, k):
        cell, channel = S.slide_cells(plate)
        self.grow(node.one("paddle"), plate=plate, k=k, cell=cell, j=0)
        self.grow(node.one("slider"), plate=plate, k=k, channel=channel)

    def paddle(self, node, plate, k, cell, j):
        pieces, pivot, rock = S.rocker(plate, k, cell, "device")
        self.hinge("plate", self.add(f"rocker_{k}_{j}", "rocker", pieces), pivot, upper=rock, role="toggle")

    def slider(self, node, plate, k, channel):
        pieces, along, travel = S.slider(plate, k, channel, "device")
        self.slide("plate", self.add(f"slider_{k}", "slider", pieces), along, upper=travel)

    def dimmer(self, node, plate, k):
        self.grow(node.children[0], plate=plate, k=k)

    def rotary(self, node, plate, k):
        self.place_dial("plate", f"dimmer_{k}", S.knob(self.p["knob_size"]), plate.face(k))

    def push_rotary(self, node, plate, k):
        """A push-on/off rotary dimmer: its knob presses in to switch and turns to dim."""
        placed = self.place(S.knob(self.p["knob_size"]).build().attached("mount", to=plate.face(k)), f"dimmer_{k}")
        axis = placed.anchor("axis")
        self.join(J.revolute_prismatic("plate", placed.root, tuple(axis.origin), tuple(axis.z), (0.0, S.KNOB["turns"]),
                                       tuple(-axis.z), (0.0, S.KNOB["press"]), role="knob"))

    def push(self, node, plate, k):
        n = len(node.of("button"))
        for j, kid in enumerate(node.of("button")):
            self.grow(kid, plate=plate, k=k, j=j, n=n)

    def button(self, node, plate, k, j, n):
        if plate.standard == "iec":
            pieces, press, stroke = S.iec_key(plate, k, j, n, "button")
            self.slide("plate", self.add(f"button_{k}_{j}", "button", pieces), press, upper=stroke, role="button")
        else:
            dz = S.push_offsets(n)[j]
            self.place_button("plate", f"button_{k}_{j}", S.PUSH["nema"], plate.face(k, dz), "button")


CATEGORY = Category("switch", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, SwitchLayout, MATERIALS,
                    substrates=SUBSTRATES, derive=_derive)
