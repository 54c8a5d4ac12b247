"""Pen: a retractable click pen, a capped stick pen or a multi-colour slider pen, lying on the table.

Designs (``design``, sizes and sources in ``categories/parts/pens.py``): a ``click`` pen whose push button
(prismatic, role ``button``: spring-returned, pressed) drives its refill's point out of the nose (the
refill's slide, role ``plunger``, is coupled to the button's); a ``capped`` stick pen, round or hexagonal,
whose cap pulls off its front (prismatic, role ``lift_off``); a ``multi``-colour pen with 2-4 colour
sliders in slots round its upper barrel, each pushed forward to bring its colour out (prismatic, role
``button``).

The pen lies on its barrel, its clip up; X is the pen's axis (the tip in front), Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import pens as P

BARRELS = ("black", "white", "blue", "dark_grey", "red", "light_grey", "teal", "orange")
INKS = ("black", "blue", "red", "green")
PARAMS = (
    Float("size", "where the length lies in its design's range (0 shortest, 1 longest)", "", 0.0, 1.0),
    Float("girth", "where the barrel's radius lies in its design's range", "", 0.0, 1.0),
    Choice("barrel_colour", "moulded barrel colour", choices=BARRELS),
    Choice("ink", "ink colour: a capped pen's cap and end plug, a click pen's button show it", choices=INKS,
           weights=(0.4, 0.4, 0.1, 0.1)),
    Choice("shape", "a capped pen's barrel section", choices=tuple(P.SIDES)),
    Choice("trim", "clip and nose metal (a click pen's), or moulded plastic", choices=("chrome", "brushed_metal",
                                                                                       "plastic")),
    Int("colours", "colour sliders of a multi-colour pen", "", *P.PENS["multi"].sliders),
)

GRAMMAR = Grammar("pen", {
    "pen": Node(one_of={"click": 0.4, "capped": 0.35, "multi": 0.25}, choice="design"),
    "click": Node(label="body", required=("button",), optional={"grip": 0.6}),
    "button": Node(label="button", required=("refill",)),
    "refill": Node(label="refill"),
    "grip": Node(),
    "capped": Node(label="body", required=("cap",)),
    "cap": Node(label="cap"),
    "multi": Node(label="body", repeat={"slider": "colours"}),
    "slider": Node(label="slider"),
})
"""A click pen's button drives its refill; a capped pen has its cap; a multi-colour pen its sliders."""

MATERIALS = {"barrel": ("barrel_colour", {c: f"plastic:{c}" for c in BARRELS}),
             "ink": ("ink", {c: f"plastic:{c}" for c in INKS}),
             "trim": ("trim", {"chrome": "chrome", "brushed_metal": "brushed_metal:stainless",
                               "plastic": "plastic:black|dark_grey|light_grey"}),
             "grip": "rubber:black|dark_grey", "steel": "chrome", "refill": "plastic:white|light_grey",
             "lower": "plastic:white|light_grey", "slot": "plastic:black",
             **{f"ink_{c}": f"plastic:{c}" for c in INKS}}


class PenLayout(Layout):
    def pen(self, node):
        self.design = node.choice
        shape = self.p["shape"] if node.choice == "capped" else "round"
        self.pn = P.pen(node.choice, self.p["size"], self.p["girth"], shape)
        self.grow(node.one(node.choice))

    def click(self, node):
        body = P.click_body(self.pn, "barrel", "trim", "trim", grip=bool(node.one("grip")))
        self.grow(node.one("button"), body=self.place(body.mounted(P.lying(self.pn)), "body"))
        if node.one("grip"):
            self.grow(node.one("grip"))

    def grip(self, node):
        self.extend("body", [pc.transformed(P.lying(self.pn).matrix) for pc in P.click_grip(self.pn, "grip")])

    def button(self, node, body):
        at = body.anchor("button")
        self.place(P.click_button(self.pn, "ink").attached("slide", to=at), "button")
        self.slide("body", "button", at, upper=self.pn.design.travel, role="button")
        self.grow(node.one("refill"), body=body)

    def refill(self, node, body):
        at = body.anchor("refill")
        self.place(P.refill(self.pn, "refill", "steel").attached("slide", to=at), "refill")
        self.slide("body", "refill", at, upper=self.pn.design.tip_out, role="plunger")
        self.couple("refill", "button", self.pn.design.tip_out / self.pn.design.travel)

    def capped(self, node):
        body = P.capped_body(self.pn, "barrel", "ink", "steel")
        self.grow(node.one("cap"), body=self.place(body.mounted(P.lying(self.pn)), "body"))

    def cap(self, node, body):
        at = body.anchor("cap")
        self.place(P.cap(self.pn, "ink", "ink").attached("seat", to=at), "cap")
        self.lift("body", "cap", at, engagement=P.cap_engagement(self.pn))

    def multi(self, node):
        count = len(node.of("slider"))
        body = P.multi_body(self.pn, "barrel", "lower", "trim", "slot", count)
        body = self.place(body.mounted(P.lying(self.pn)), "body")
        for k, (sl, ink) in enumerate(zip(node.of("slider"), INKS, strict=False)):
            self.grow(sl, name=f"slider_{ink}", at=body.anchor(f"slider_{k}"), ink=f"ink_{ink}")

    def slider(self, node, name, at, ink):
        self.place(P.slider(self.pn, ink).attached("slide", to=at), name)
        self.slide("body", name, at, upper=self.pn.design.travel, role="button")


CATEGORY = Category("pen", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PenLayout, MATERIALS)
