"""Washing machine: a front loader, washer-dryer or top loader with its porthole door or lid, drawer and controls.

Designs (``design``, sizes and sources in ``categories/parts/washers.py``): a ``front_loader`` and a
``washer_dryer`` (595-600 mm wide, 850 mm tall) load through a round porthole door in the front: a ring with a
glass bowl, hinged at its left edge (revolute about -Z); the detergent drawer pulls out of the top left of the
front (prismatic); the program dial is an endless electronic selector (continuous) or a mechanical timer
between stops (revolute), beside it keys press in (prismatic, spring-returned) and on some models a
temperature or drying-time knob turns (revolute); the service flap at the bottom right drops forward
(revolute about +Y) and only then does the drain-pump filter cap behind it turn (revolute, ``requires_open``).
A ``top_loader`` (US, 27 in wide) loads through a lid hinged at the back of its top (revolute about -Y), its
dials and keys on the front of the console at the back; it washes with an agitator up the middle of its basket
(a fabric-softener cup pressed on its post lifts off) or a low impeller plate on the basket floor
(``wash_action``).

X is depth (the front faces +X), Y is width, Z is up.
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import appliance as A
from .parts import controls
from .parts import washers as WM


def _count(what: str):
    def count(p, rng) -> int:
        lo, hi = getattr(WM.DESIGNS[p["design"]], what)
        return int(rng.integers(lo, hi + 1))
    count.__doc__ = f"{what} of the design, drawn in its range (``categories/parts/washers.py``)"
    return count


PARAMS = (
    Float("size", "where the footprint lies in its design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("tall", "where the height lies in its design's range (0 lowest, 1 tallest)", "", 0.0, 1.0),
    Float("door_size", "where the porthole door's (top loader: tub opening's) diameter lies in its range", "",
          0.0, 1.0),
    Float("corner", "radius of the casing's upright corners (over its 4 mm wall)", "m", 0.005, 0.012),
    Choice("finish", "casing colour: white, as most sold, or graphite or black (Bosch, Samsung, LG ranges)",
           choices=("white", "graphite", "black"), weights=(0.7, 0.15, 0.15)),
    Choice("program_dial", "program dial: an endless electronic selector or a mechanical timer between stops",
           choices=("selector", "timer"), weights=(0.6, 0.4)),
    Choice("lid_style", "a top loader's lid: a frame round a glass window, or a solid panel",
           choices=("glass", "solid"), weights=(0.6, 0.4)),
    # US top-loader line-ups (Whirlpool, Maytag, GE, Speed Queen, approximate): agitator models still the larger
    # share, low-profile impeller models the rest
    Choice("wash_action", "a top loader's: an agitator up the middle of the basket, or a low impeller plate on its"
           " floor (no softener cup: it sits on an agitator's post)", choices=WM.WASH_ACTIONS, weights=(0.6, 0.4)),
)

GRAMMAR = Grammar("washing_machine", {
    "washing_machine": Node(label="body", required=("controls",),
                            one_of={"front_loader": 0.4, "washer_dryer": 0.3, "top_loader": 0.3}, choice="design"),
    "front_loader": Node(required=("door", "drawer"), optional={"service_flap": 0.8}),
    "washer_dryer": Node(required=("door", "drawer"), optional={"service_flap": 0.8}),
    "top_loader": Node(required=("lid",), optional={"softener_cup": 0.5}),
    "softener_cup": Node(label="cup"),
    "door": Node(label="door"),
    "drawer": Node(label="drawer"),
    "service_flap": Node(label="flap", required=("filter",), optional={"drain_hose": 0.5}),
    "drain_hose": Node(label="hose"),
    "filter": Node(label="filter"),
    "lid": Node(label="lid"),
    "controls": Node(repeat={"dial": _count("knobs"), "key": _count("buttons")}),
    "dial": Node(label="knob"),
    "key": Node(label="button"),
})
"""Knobs and keys are counted per design (``categories/parts/washers.py`` ``DESIGNS``); the first knob is the
program dial."""

FINISHES = {"white": ("painted:white", "plastic:white|light_grey"),
            "graphite": ("painted:graphite", "plastic:dark_grey|black"),
            "black": ("painted:black", "plastic:black|dark_grey")}
"""A casing finish and the door ring's plastics that go with it."""

MATERIALS = {"body": ("finish", {k: v[0] for k, v in FINISHES.items()}), "lid": Same("body"),
             "door": ("finish", {k: v[1] for k, v in FINISHES.items()}), "trim": "chrome",
             # a porthole's glass bowl is clear (Bosch, Samsung, LG doors; a faint blue on some): smoked oven glass,
             # two layers of it, reads as an opaque grey disc from inside
             "glass": "glass:clear|clear_blue",
             "drum": "brushed_metal:stainless", "gasket": "rubber", "liner": "plastic:light_grey|dark_grey|white",
             "agitator": "plastic:white|light_grey",  # agitators and impellers: white or grey moulded PP
             "drawer": "plastic:white|light_grey",
             "handle": Same("trim"), "knob": "plastic", "button": "plastic", "display": "rubber", "feet": "rubber",
             "machine": "brushed_metal", "filter": "plastic:white|light_grey|dark_grey"}
SUBSTRATES = {"body": A.STEEL, "lid": A.STEEL}  # a painted casing and lid are painted steel sheet


def derive(p: dict) -> dict:
    """An impeller has no post for a softener cup to sit on."""
    if p.get("wash_action") == "impeller" and p.get("has_softener_cup"):
        return {**p, "has_softener_cup": False}
    return p


class WashingMachineLayout(controls.ControlFace):
    def washing_machine(self, node):
        p, design = self.p, node.choice
        style, ctl = node.one(design), node.one("controls")
        m = WM.machine(design, p["size"], p["tall"], p["door_size"], p["corner"], p["wash_action"])
        flap = style.one("service_flap")
        body = self.place(WM.body(m, len(ctl.of("dial")), len(ctl.of("key")), bool(flap)), "body")
        self.grow(style, body=body, m=m)
        self.grow(ctl, body=body)

    def _front(self, node, body, m):
        self.grow(node.one("door"), body=body, m=m)
        self.grow(node.one("drawer"), body=body)
        if flap := node.one("service_flap"):
            self.grow(flap, body=body, m=m)

    front_loader = washer_dryer = _front

    def top_loader(self, node, body, m):
        self.grow(node.one("lid"), body=body, m=m)
        if cup := node.one("softener_cup"):  # pressed on the agitator's post
            self.grow(cup, body=body)

    def softener_cup(self, node, body):
        cup = self.place(WM.softener_cup().attached("seat", to=body.anchor("cup")), "softener_cup")
        self.lift(body.root, cup.root, cup.anchor("seat"), engagement=WM.CUP["seat"])

    def door(self, node, body, m):
        door = self.place(WM.porthole_door(m).attached("mount", to=body.anchor("porthole")), "door")
        self.hinge(body.root, door.root, door.anchor("hinge"), upper=WM.DOOR_OPENS)

    def drawer(self, node, body):
        drawer = self.place(WM.detergent_drawer().attached("front", to=body.anchor("drawer")), "drawer")
        self.slide(body.root, drawer.root, drawer.anchor("front"), upper=WM.drawer_travel())

    def service_flap(self, node, body, m):
        pieces, hinge = WM.flap(m, WM.cutouts(m, 0, 0, True)["flap"])
        self.add("filter_flap", "flap", pieces)
        self.hinge(body.root, "filter_flap", hinge, upper=WM.FLAP_OPENS)
        self.grow(node.one("filter"), body=body)
        if hose := node.one("drain_hose"):
            self.grow(hose, body=body)

    def drain_hose(self, node, body):
        hose = self.place(WM.drain_hose().attached("mount", to=body.anchor("hose")), "drain_hose")
        self.slide(body.root, hose.root, hose.anchor("pull"), upper=WM.HOSE["pull"], requires_open="filter_flap")

    def filter(self, node, body):
        cap = self.place(WM.filter_cap().attached("mount", to=body.anchor("filter")), "filter")
        self.hinge(body.root, cap.root, cap.anchor("axis"), upper=WM.FILTER.turns, role="knob",
                   requires_open="filter_flap")

    def lid(self, node, body, m):
        pieces, _ = WM.lid(m, self.p["lid_style"] == "glass")
        self.add("lid", "lid", pieces)
        self.hinge(body.root, "lid", body.anchor("lid"), upper=WM.LID_OPENS, role="lid")

    def controls(self, node, body):
        for k, kid in enumerate(node.of("dial")):
            self.grow(kid, body=body, k=k)
        for k, kid in enumerate(node.of("key")):
            self.grow(kid, body=body, k=k)

    def dial(self, node, body, k):
        pr = WM.PROGRAM
        selector = k == 0 and self.p["program_dial"] == "selector"
        turns = None if selector else (pr["timer"] if k == 0 else pr["other"])
        spec = controls.Dial(pr["radius"], pr["stem"], "ridge" if k == 0 else "round", turns)
        self.place_dial(body.root, f"knob_{k}", spec, body.anchor(f"knob_{k}"))

    def key(self, node, body, k):
        self.place_button(body.root, f"key_{k}", WM.KEY, body.anchor(f"key_{k}"))


CATEGORY = Category("washing_machine", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, WashingMachineLayout,
                    MATERIALS, substrates=SUBSTRATES, palette=appliance, derive=derive)
