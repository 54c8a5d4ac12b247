"""Coffee machine: a drip filter machine with its carafe, a pump espresso machine or a capsule (pod) machine.

Designs (``design``, sizes and sources in ``categories/parts/coffee_machines.py``): a ``drip`` machine whose
reservoir lid lifts at the front (revolute), whose cone filter basket swings out from under the shower head on
a side pivot (revolute) and whose glass carafe slides off the warming plate (prismatic), with keys on its
plinth; an ``espresso`` machine whose portafilter turns out of the group head's lugs to its stop (revolute,
45 degrees), whose steam wand swings out on its ball joint (revolute), whose drip tray pulls out (prismatic)
and whose water tank lifts out of its cradle at the back (prismatic, role ``lift_off``: free once clear of the
cradle), keys (or rocker switches: revolute) and maybe a steam dial (revolute) on its head; a ``pod`` machine
whose head lid lifts to load a capsule (revolute), with a drip tray, a lift-out tank and keys. A tank may carry
a hinged fill flap (revolute). Keys press in against their return springs (role ``button``).

X is depth (the front faces +X), Y is width, Z is up.
"""

from __future__ import annotations

from dataclasses import replace

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import casing, controls, hardware
from .parts import coffee_machines as C

PARAMS = (
    Float("size", "where the machine lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Choice("finish", "body finish (an espresso machine's plastic is drawn as brushed_metal: the sheet of"
                     " Breville, Gaggia and De'Longhi pump machines)", choices=("plastic", "brushed_metal", "painted")),
)

def _keys(p: dict, rng) -> int:
    """1 to as many keys as fit the machine's front (a pod machine's power and cup-size keys: at most 3)."""
    most = C.keys_fit(C.machine(p["design"], p["size"]))
    return int(rng.integers(1, (min(most, 3) if p["design"] == "pod" else most) + 1))


GRAMMAR = Grammar("coffee_machine", {
    "coffee_machine": Node(label="body", one_of={"drip": 0.35, "espresso": 0.35, "pod": 0.3}, choice="design"),
    "drip": Node(required=("lid", "basket", "carafe"), repeat={"button": _keys}),
    "espresso": Node(required=("portafilter", "tray", "tank"), optional={"wand": 0.85, "dial": 0.6},
                     one_of={"keypad": 0.65, "rockers": 0.35}, choice="controls"),
    "keypad": Node(repeat={"button": _keys}),
    "rockers": Node(repeat={"rocker": (1, C.ROCKERS_MAX)}),
    "rocker": Node(label="switch"),
    "pod": Node(required=("lid", "tray", "tank"), repeat={"button": _keys}),
    "tank": Node(label="tank", optional={"flap": 0.5}),
    "flap": Node(label="lid"),
    "lid": Node(label="lid"),
    "basket": Node(label="basket"),
    "carafe": Node(label="carafe"),
    "portafilter": Node(label="portafilter"),
    "wand": Node(label="wand"),
    "dial": Node(label="knob"),
    "tray": Node(label="tray"),
    "button": Node(label="button"),
})
"""Keys per machine: 1 to as many as fit its front (``coffee_machines.keys_fit``, at most 4; a pod machine 3: power
and cup sizes); a tank's fill flap is drawn object-wide (``has_flap``), the steam wand and the steam dial too
(``has_wand``: some single-dose machines have none; ``has_dial``: others steam from a key); an espresso machine has
keys or a row of 1-3 rocker switches (``controls``; power, brew, steam: Gaggia Classic Pro)."""

MATERIALS = {"body": "finish", "lid": "plastic:black|dark_grey", "button": "plastic:black|dark_grey|light_grey",
             "knob": "plastic:black",
             "trim": "brushed_metal", "works": "brushed_metal", "carafe": "glass:clear", "band": "plastic:black",
             "grip": "plastic:black", "tank": "glass:smoked", "metal": "chrome", "tray": "plastic:black|dark_grey",
             "grate": "brushed_metal"}
SUBSTRATES = {"body": ("finish", {"painted": 7850.0}),  # a painted shell is painted steel sheet
              "tank": C.TANK_DENSITY}  # a clear tank is SAN, drawn as clear glass


def _derive(p: dict) -> dict:
    if p["design"] == "espresso" and p["finish"] == "plastic":
        return {**p, "finish": "brushed_metal"}
    return p


def _keys_of(kit) -> list:
    """The keys a machine's fittings grew (an espresso machine's in its keypad)."""
    pad = kit.one("keypad")
    return (pad if pad is not None else kit).of("button")


class CoffeeLayout(controls.ControlFace):
    def coffee_machine(self, node):
        design = node.choice
        m = C.machine(design, self.p["size"], metal=self.p["finish"] != "plastic")
        kit = node.one(design)
        self.add("body", "body", C.body(m, "body", "trim", len(_keys_of(kit)), kit.one("dial") is not None))
        self.grow(node.one(design), m=m)

    def _fittings(self, node, m):
        keys = node.of("button")
        for kid in node.children:
            if kid.kind != "button":
                self.grow(kid, m=m)
        for k, (key, at) in enumerate(zip(keys, C.key_anchors(m, len(keys)), strict=True)):
            self.grow(key, at=at, name=f"button_{k}")

    drip = espresso = pod = keypad = _fittings

    def rockers(self, node, m):
        for k, (rocker, at) in enumerate(zip(node.of("rocker"), C.key_anchors(m, len(node.of("rocker"))),
                                             strict=True)):
            self.grow(rocker, at=at, name=f"rocker_{k}")

    def rocker(self, node, at, name):
        made = hardware.rocker_switch("button").attached("mount", to=at)
        self.extend("body", made.parts["bezel"].pieces)
        self.add(name, "switch", made.parts["rocker"].pieces)
        (joint,) = made.joints
        self.join(replace(joint, parent="body", child=name))

    def lid(self, node, m):
        pieces, hinge = (C.reservoir_lid if m.design == "drip" else C.pod_lid)(m, "lid")
        self.hinge("body", self.add("lid", "lid", pieces), hinge, upper=C.LID_OPENS, role="lid")

    def basket(self, node, m):
        pieces, pivot = C.basket(m, "lid")
        self.hinge("body", self.add("basket", "basket", pieces), pivot, upper=C.BASKET_SWINGS)

    def carafe(self, node, m):
        pieces, along = C.carafe(m, "carafe", "band", "grip")
        self.slide("body", self.add("carafe", "carafe", pieces), along, upper=C.carafe_pull(m))

    def portafilter(self, node, m):
        pieces, axis = C.portafilter(m, "metal", "grip")
        self.hinge("body", self.add("portafilter", "portafilter", pieces), axis, upper=C.PORTAFILTER_TURNS,
                   role="knob")

    def wand(self, node, m):
        pieces, pivot = C.wand(m, "metal")
        self.hinge("body", self.add("steam_wand", "wand", pieces), pivot, upper=C.WAND_SWINGS)

    def dial(self, node, m):
        self.place_dial("body", "steam_dial", C.DIAL, C.dial_anchor(m))

    def tray(self, node, m):
        made = casing.liner(C.drip_tray(m), "tray", label="tray").attached("front", to=C.tray_front(m))
        tray = self.place(made, "drip_tray")
        self.extend(tray.root, C.tray_grate(m, "grate"))
        self.slide("body", tray.root, tray.anchor("front"), upper=C.TRAY_PULL * C.drip_tray(m).depth)

    def tank(self, node, m):
        pieces, seat = C.tank(m, "tank", "grip")
        self.lift("body", self.add("tank", "tank", pieces), seat, engagement=C.CRADLE[1])
        if node.one("flap"):
            self.grow(node.one("flap"), m=m)

    def flap(self, node, m):
        pieces, hinge = C.tank_lid(m, "lid")
        self.hinge("tank", self.add("tank_lid", "lid", pieces), hinge, upper=C.LID_OPENS, role="lid")

    def button(self, node, at, name):
        self.place_button("body", name, C.BUTTON, at)


CATEGORY = Category("coffee_machine", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, CoffeeLayout, MATERIALS,
                    substrates=SUBSTRATES, derive=_derive, palette=appliance)
