"""Dispenser: a soap or lotion pump bottle, a wall soap dispenser or a condiment (sauce) pump.

Designs (``design``, sizes and sources in ``categories/parts/dispensers.py``): a ``pump_bottle`` (a Boston round
whose pump collar unscrews to refill it: turning and lifting, role ``lift_off``; its actuator's stem presses
down against its return spring: prismatic, role ``plunger``; its nozzle head turns a quarter on the stem to
lock: revolute); a ``wall`` dispenser (a refill lid hinged at the back of its top: revolute; a push panel per
chamber (1-3) hinged at its top edge, pushed in against its spring: revolute, role ``lever``; maybe a key lock
that turns a quarter: revolute); a ``sauce_pump`` (a jar whose lid, with the pump on it, lifts off: prismatic, role
``lift_off``; a plunger head with a long spout pressed down against its spring: prismatic, role ``plunger``).

X is the nozzle's (or the push panel's) direction, Y across, Z up.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import dispensers as D
from .parts import vessel as V
from .parts.vessel_sizes import BOTTLE_CAP_TRAVEL, BOTTLE_KINDS

LABEL_FILL = 0.7  # the label covers this share of the straight part (Method, Softsoap, Dove pump bottles)

PARAMS = (
    Float("size", "where the dispenser lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("wall", "a pump bottle's wall thickness (PET 1.5 mm to glass 3 mm)", "m", *D.BOTTLE["wall"]),
    Choice("bottle", "a pump bottle's material", choices=("glass", "plastic")),
)

def _chambers(p: dict, rng) -> int:
    """1 push panel (3 in 5), or 2 or 3 on a multi-chamber shower dispenser."""
    return int(rng.choice((1, 1, 1, 2, 3)))


GRAMMAR = Grammar("dispenser", {
    "dispenser": Node(one_of={"pump_bottle": 0.45, "wall": 0.3, "sauce_pump": 0.25}, choice="design"),
    "pump_bottle": Node(label="body", required=("collar",)),
    "collar": Node(label="cap", required=("stem",)),
    "stem": Node(label="pump", optional={"turn": 0.6}),
    "turn": Node(label="head"),
    "wall": Node(label="body", required=("lid",), optional={"lock": 0.4},
                 repeat={"panel": _chambers}),
    "lid": Node(label="lid"),
    "panel": Node(label="panel"),
    "lock": Node(label="knob"),
    "sauce_pump": Node(label="body", required=("jar_lid",)),
    "jar_lid": Node(label="lid", required=("plunger",)),
    "plunger": Node(label="pump"),
})
"""A pump's nozzle head turns to lock on most lotion pumps (``has_turn``; a foaming or fixed-head pump has its
head moulded on the stem); a wall dispenser's key lock is drawn object-wide (``has_lock``); it has a push panel
per chamber: one, or two or three on a multi-chamber shower dispenser (3 in 5 have one)."""

MATERIALS = {
    "glass": ("bottle", {"glass": "glass:amber|clear|bottle_green", "plastic": "plastic:white|light_grey|black"}),
    "pump": "plastic:white|black|light_grey", "housing": "plastic:white|light_grey|black|dark_grey",
    "panel": "plastic:light_grey|dark_grey|black|white", "trim": "plastic:dark_grey|black", "lock": "chrome",
    "jar": "plastic:white|light_grey", "metal": "brushed_metal", "spout": "plastic:white|black",
    "label": "painted:pastel_yellow|pastel_blue|navy|sage|black",  # a printed label that stands off the bottle
}


class DispenserLayout(Layout):
    def dispenser(self, node):
        self.grow(node.one(node.choice))

    # -- pump bottle
    def pump_bottle(self, node):
        p = self.p
        height = D.Sized(p["size"]).of(D.BOTTLE["height"])
        prof = V.bottle_profile("dispenser", "screw", height, D.BOTTLE["radius_ratio"] * height, p["wall"])
        body = self.place(V.bottle_body(prof, 0.0, "glass", "screw"), "body")
        # a soap or lotion bottle is sold labelled: a printed label round its straight part (the bottle's
        # dispenser label zone, :data:`.parts.vessel_sizes.BOTTLE_KINDS`)
        zone = tuple(z * height for z in BOTTLE_KINDS["dispenser"][5])
        band = V.label_band(prof, zone, LABEL_FILL, 0.5, "label")
        self.extend(body.root, band.attached("vessel", to=body.anchor("base")).pieces)
        self.grow(node.one("collar"), body=body, prof=prof)

    def collar(self, node, body, prof):
        pieces, top = D.collar(prof, float(body.anchor("neck_top").origin[2]), "pump")
        seat = body.anchor("lid_seat")
        self.add("collar", "cap", pieces)
        self.join(J.continuous_prismatic(body.root, "collar", tuple(seat.origin), tuple(seat.z),
                                         (0.0, BOTTLE_CAP_TRAVEL), role="lift_off"))
        self.grow(node.one("stem"), top=top)

    def stem(self, node, top):
        pieces, press = D.stem(top, "pump")
        self.slide("collar", self.add("stem", "pump", pieces), press, upper=D.PUMP["stroke"], role="plunger")
        head, axis = D.head(top, "pump")
        if node.one("turn"):
            self.grow(node.one("turn"), pieces=head, axis=axis)
        else:
            self.extend("stem", head)  # a fixed head, moulded on the stem

    def turn(self, node, pieces, axis):
        self.hinge("stem", self.add("head", "head", pieces), axis, upper=D.PUMP_TURNS, role="knob")

    # -- wall dispenser
    def wall(self, node):
        h = D.housing(self.p["size"], len(node.of("panel")))
        self.add("body", "body", D.housing_body(h, "housing", "trim", lid=True))
        for kid in node.children:
            if kid.kind != "panel":
                self.grow(kid, h=h)
        for k, panel in enumerate(node.of("panel")):
            self.grow(panel, h=h, k=k)

    def lid(self, node, h):
        pieces, hinge = D.wall_lid(h, "housing")
        self.hinge("body", self.add("lid", "lid", pieces), hinge, upper=D.LID_OPENS, role="lid")

    def panel(self, node, h, k):
        pieces, hinge = D.push_panel(h, k, "panel")
        self.hinge("body", self.add(f"push_panel_{k}", "panel", pieces), hinge, upper=D.PANEL_PUSH, role="lever")

    def lock(self, node, h):
        pieces, axis = D.lock(h, "lock")
        self.hinge("body", self.add("lock", "knob", pieces), axis, upper=D.LOCK_TURNS, role="knob")

    # -- condiment pump
    def sauce_pump(self, node):
        j = D.jar(self.p["size"])
        self.add("body", "body", D.jar_body(j, "jar"))
        self.grow(node.one("jar_lid"), j=j)

    def jar_lid(self, node, j):
        pieces, seat, top = D.sauce_lid(j, "metal", "jar")
        self.lift("body", self.add("lid", "lid", pieces), seat, engagement=D.SAUCE["skirt"])
        self.grow(node.one("plunger"), top=top)

    def plunger(self, node, top):
        pieces, press = D.sauce_head(top, "jar", "spout")
        self.slide("lid", self.add("plunger", "pump", pieces), press, upper=D.SAUCE["stroke"], role="plunger")


CATEGORY = Category("dispenser", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DispenserLayout, MATERIALS)
