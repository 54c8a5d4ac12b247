"""Jar: a mason / storage jar (round, square or hexagonal) with a screw lid.

The body is hollow: a round jar is one thin wall of revolution through a smooth spline
(body, rounded shoulder, neck with thread rings, rolled lip) on a bottom disc; a square
or hexagonal jar is a wall of flat panels (one convex piece per face and band, so it
stays hollow), a flat shoulder plate with a round opening (convex wedges around the
hole) and a round threaded neck on top. Glass or glazed ceramic.

The lid (:func:`~.parts.vessel.jar_lid`, metal or plastic) is a skirt around the
threads with clearance all round (drawn, without collision: see
:func:`.parts.vessel.sleeve` for the PhysX reason) and a top plate a small gap above
the lip with a raised centre button; plate and button collide as one flat-faced hull
(jar seed 61: a separate button hull jammed the turn in PhysX). It turns freely about Z
and lifts 0..5 cm along +Z, resting on its seat at 0 (gravity holds it down).
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import vessel as V
from .parts.vessel_sizes import JAR, JAR_LID_FAMILY, JAR_LIFT

LID_LIFT = JAR_LIFT
SIDE_COUNT = {"round": 0, "square": 4, "hexagonal": 6}

GRAMMAR = Grammar("jar", {
    "jar": Node(required=("lid",), one_of=dict(zip(SIDE_COUNT, JAR["sides_weights"])), choice="sides",
                doc="a body of one cross-section and its screw lid"),
    "round": Node(label="body", doc="one wall of revolution with shoulder and threaded neck"),
    "square": Node(label="body", doc="four flat panels, a shoulder plate and a round threaded neck"),
    "hexagonal": Node(label="body", doc="six flat panels, a shoulder plate and a round threaded neck"),
    "lid": Node(label="lid", doc="a screw lid: skirt over the threads, top plate with a button"),
})

PARAMS = (
    Float("height", "overall height of the body (without the lid)", "m", *JAR["height"]),
    Float("radius", "body radius (round) or half width across the flats", "m", *JAR["radius"]),
    Choice("body_finish", "body material", choices=("glass", "ceramic"), weights=JAR["body_weights"]),
    Choice("lid_finish", "lid material", choices=tuple(JAR_LID_FAMILY), weights=JAR["lid_weights"]),
    Float("wall", "body wall thickness", "m", *JAR["wall"]),
    Float("neck_ratio", "neck radius / body radius", "", *JAR["neck_ratio"]),
    Float("shoulder", "shoulder height / body height (round jars)", "", *JAR["shoulder"]),
    Float("neck_height", "threaded neck height", "m", *JAR["neck_height"]),
    Float("lid_height", "lid height", "m", *JAR["lid_height"]),
)


class JarLayout(Layout):
    def jar(self, node):
        body, neck = self.grow(node.one(node.choice))
        self.grow(node.one("lid"), body=body, neck=neck)

    def round(self, node):
        p = self.p
        body, neck = V.round_jar_body(p["height"], p["radius"], p["wall"], p["neck_ratio"], p["shoulder"],
                                      p["neck_height"], "body")
        return self.place(body, "body"), neck

    def _polygon(self, node):
        p = self.p
        body, neck = V.polygon_jar_body(p["height"], p["radius"], SIDE_COUNT[node.kind], p["wall"], p["neck_ratio"],
                                        p["neck_height"], "body")
        return self.place(body, "body"), neck

    square = hexagonal = _polygon

    def lid(self, node, body, neck):
        lid = V.jar_lid(neck, self.p["neck_height"], self.p["lid_height"],
                        self.p["lid_finish"] == "plastic", "lid")
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LID_LIFT))


CATEGORY = Category("jar", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, JarLayout,
                    materials={"body": "body_finish", "lid": ("lid_finish", JAR_LID_FAMILY)})
