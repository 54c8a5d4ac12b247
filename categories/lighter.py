"""Lighter: a disposable flint lighter, a flip-top windproof lighter or a long utility lighter.

Designs (``design``, sizes and sources in ``categories/parts/lighters.py``): a ``disposable`` lighter standing
on its base, its knurled spark wheel turning on the hood (continuous) over its gas lever, the "fork" whose
thumb pad is pressed down (revolute, role ``lever``: spring-returned); a ``windproof`` flip-top lighter whose
lid swings open about its rear hinge (revolute) and uncovers the chimney and the spark wheel on it
(continuous; it turns once the lid is open); a ``utility`` lighter lying on its side, its trigger pulled back
into the handle (prismatic, role ``button``: spring-returned), mostly behind a child-safety slider pushed
forward on the spine first (prismatic). X is the lighter's front (the flame's side), Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import lighters as Li

BODIES = ("red", "blue", "yellow", "black", "white", "orange", "green", "teal")
PARAMS = (
    Float("size", "where a disposable or utility lighter lies between its small and large models", "", 0.0, 1.0),
    Choice("body_colour", "moulded body colour (disposable and utility lighters)", choices=BODIES),
    Choice("case", "a windproof lighter's case finish", choices=("brushed_metal", "chrome", "black_enamel")),
    Choice("model", "a windproof lighter's size", choices=tuple(Li.WINDPROOFS), weights=(0.7, 0.3)),
)

GRAMMAR = Grammar("lighter", {
    "lighter": Node(one_of={"disposable": 0.4, "windproof": 0.3, "utility": 0.3}, choice="design"),
    "disposable": Node(label="body", required=("spark_wheel", "fork")),
    "spark_wheel": Node(label="wheel"),
    "fork": Node(label="lever"),
    "windproof": Node(label="body", required=("lid",)),
    "lid": Node(label="lid", required=("chimney_wheel",)),
    "chimney_wheel": Node(label="wheel"),
    "utility": Node(label="body", optional={"safety": 0.75}, required=("trigger",)),
    "safety": Node(label="slider"),
    "trigger": Node(label="trigger"),
})
"""A disposable lighter's wheel and fork; a windproof lighter's lid, its wheel under it; a utility lighter's
trigger, behind its safety slider where it has one."""

MATERIALS = {"body": ("body_colour", {c: f"plastic:{c}" for c in BODIES}),
             "case": ("case", {"brushed_metal": "brushed_metal:stainless", "chrome": "chrome",
                               "black_enamel": "enamel:black"}),
             "steel": "brushed_metal:stainless_dark", "dark": "plastic:black", "fork": "plastic:black|red",
             "wand": "plastic:black|dark_grey|light_grey", "trim": "plastic:black|dark_grey"}
# a filled disposable's tank: ~2.5 mm moulded acetal walls (1400 kg/m^3) and 4-5 g of butane in it; a windproof
# case is 0.6 mm brass or steel over a steel insert with its wick and cotton
SUBSTRATES = {"body": 1400.0}


class LighterLayout(Layout):
    def lighter(self, node):
        self.grow(node.one(node.choice))

    def disposable(self, node):
        self.d = Li.disposable(self.p["size"])
        body = self.place(Li.disposable_body(self.d, "body", "steel", "dark"), "body")
        self.grow(node.one("spark_wheel"), body=body)
        self.grow(node.one("fork"), body=body)

    def spark_wheel(self, node, body):
        at = body.anchor("wheel")
        self.place(Li.spark_wheel(self.d, "steel").attached("axle", to=at), "wheel")
        self.spin("body", "wheel", at)

    def fork(self, node, body):
        at = body.anchor("lever")
        self.place(Li.fork(self.d, "fork").attached("pivot", to=at), "lever")
        self.hinge("body", "lever", at, upper=Li.LEVER_PRESS, role="lever")

    def windproof(self, node):
        self.z = Li.windproof(self.p["model"])
        body = self.place(Li.windproof_body(self.z, "case", "steel", "dark"), "body")
        self.grow(node.one("lid"), body=body)

    def lid(self, node, body):
        at = body.anchor("lid")
        self.place(Li.windproof_lid(self.z, "case").attached("hinge", to=at), "lid")
        self.hinge("body", "lid", at, upper=Li.LID_OPENS, role="lid")
        self.grow(node.one("chimney_wheel"), body=body)

    def chimney_wheel(self, node, body):
        at = body.anchor("wheel")
        self.place(Li.windproof_wheel(self.z, "steel").attached("axle", to=at), "wheel")
        self.spin("body", "wheel", at, requires_open="lid")

    def utility(self, node):
        self.u = Li.utility(self.p["size"])
        body = self.place(Li.utility_body(self.u, "body", "wand", "steel", "dark"), "body")
        if node.one("safety"):
            self.grow(node.one("safety"), body=body)
        self.grow(node.one("trigger"), body=body, gate="safety" if node.one("safety") else None)

    def safety(self, node, body):
        at = body.anchor("safety")
        self.place(Li.safety(self.u, "trim").attached("slide", to=at), "safety")
        self.slide("body", "safety", at, upper=Li.SAFETY[2])

    def trigger(self, node, body, gate):
        at = body.anchor("trigger")
        self.place(Li.trigger(self.u, "trim").attached("slide", to=at), "trigger")
        self.slide("body", "trigger", at, upper=Li.TRIGGER[2], role="button", requires_open=gate)


CATEGORY = Category("lighter", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, LighterLayout, MATERIALS,
                    substrates=SUBSTRATES)
