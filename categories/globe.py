"""Globe: a desk globe on a semi-meridian or a floor globe in a full meridian, turning about its tilted axis.

Designs (``design``, sizes and sources in ``categories/parts/globes.py``): a ``desk`` globe (a round foot and a
turned stem; its semi-meridian carries the globe and, on a swivel stand, turns on the stem, revolute about the
vertical, role ``swivel``; else it is fixed to the stem); a ``floor`` globe (four legs and a horizon ring; the full
meridian turns in the ring's notches about the front-to-back axis, revolute, role ``swivel``, setting the tilt).
The globe turns freely about its polar axis, 23.4 degrees from vertical, in its meridian (continuous, role
``turntable``).

The map is printed: the Earth's continents (Natural Earth 1:110m land) in a land colour over an ocean colour, the
equator and the tropics. X is the stand's front, Y across (the axis tilts towards +Y), Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import globes as G

PARAMS = (
    Float("size", "where the globe's diameter lies in its design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("height", "where the stand's height lies in its design's range", "", 0.0, 1.0),
    Choice("stand", "the stand's finish (a floor stand is wood)", choices=("wood", "brushed_metal", "chrome",
                                                                           "painted")),
)

GRAMMAR = Grammar("globe", {
    "globe": Node(label="stand", one_of={"desk": 0.65, "floor": 0.35}, choice="design"),
    "desk": Node(required=("meridian",), optional={"swivel": 0.6}),
    "swivel": Node(),
    "floor": Node(required=("meridian",)),
    "meridian": Node(label="meridian", required=("sphere",)),
    "sphere": Node(label="globe"),
})

MATERIALS = {"stand": "stand", "meridian": ("stand", {"wood": "brushed_metal", "painted": "chrome"}),
             "ocean": "painted:pastel_blue|navy|charcoal|sage", "land": "painted:pastel_green|pastel_yellow|"
             "retro_cream|off_white", "lines": Same("meridian")}


def _derive(p: dict) -> dict:
    if p["design"] == "floor" and p["stand"] != "wood":
        return {**p, "stand": "wood"}
    return p


class GlobeLayout(Layout):
    def globe(self, node):
        gl = G.make(node.choice, self.p["size"], self.p["height"])
        stand = G.desk_stand(gl, "stand") if gl.design == "desk" else G.floor_stand(gl, "stand")
        self.add("stand", "stand", stand)
        self.grow(node.one(node.choice), gl=gl)

    def _design(self, node, gl):
        turns = gl.design == "floor" or node.one("swivel") is not None
        if node.one("swivel"):
            self.grow(node.one("swivel"), gl=gl)
        self.grow(node.one("meridian"), gl=gl, turns=turns)

    def swivel(self, node, gl):
        self.extend("stand", G.swivel_collar(gl, "stand"))

    desk = floor = _design

    def meridian(self, node, gl, turns):
        if gl.design == "desk":
            pieces, pivot, swing = G.semi_meridian(gl, "meridian")
        else:
            pieces, pivot, swing = G.full_meridian(gl, "meridian")
        self.add("meridian", "meridian", pieces)
        if turns:
            self.hinge("stand", "meridian", pivot, lower=-swing, upper=swing, role="swivel")
        else:  # a desk globe whose semi-meridian is fixed to its stem
            self.fix("stand", "meridian")
        self.grow(node.one("sphere"), gl=gl)

    def sphere(self, node, gl):
        pieces = G.sphere(gl, "ocean", "land", "lines", self.rng)
        self.spin("meridian", self.add("sphere", "globe", pieces), G.spin_axis(gl), role="turntable")


CATEGORY = Category("globe", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, GlobeLayout, MATERIALS,
                    derive=_derive)
