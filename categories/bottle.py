"""Bottle: a hollow glass bottle with a cap that unscrews and an optional label band.

The body is a thin glass wall of revolution whose outside follows a smooth spline
through many control points of one of six recognisable profiles, closed by a bottom
(a push-up punt for wine and champagne):

* ``beer``: long-neck, straight body, rounded shoulder, long neck, crown finish;
* ``bordeaux``: straight body, high abrupt shoulder;
* ``burgundy``: wider body, long sloping shoulder;
* ``champagne``: heavy, sloping shoulder, deep punt, foil capsule and mushroom cork;
* ``soda``: PET bottle with a waist, support ring and screw threads;
* ``vintage``: apothecary bottle, wide body, short neck with a flared lip and a stopper.

The cap (crown, screw cap, foil capsule or stopper; ``cap=auto``, the default, takes
the profile's usual one) sits on the lip with clearance all round (a sleeve cap's skirt
is drawn but collides through its top plate only: see :func:`.parts.vessel.sleeve` for
the PhysX reason); it turns freely about Z and lifts 0..1 cm along +Z (unscrewing),
resting at 0 (gravity holds it on its seat). The label is a thin band around the
straight part of the body, a separate part that turns about Z (its centre of mass is on
the axis) with clearance from the glass. Walls, finishes and closures live in
:mod:`.parts.vessel`.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Float

from .parts import vessel as V
from .parts.vessel_sizes import BOTTLE, BOTTLE_CAP_TRAVEL, BOTTLE_KINDS, BOTTLE_WEIGHTS, CAP_MATERIALS

CAP_TRAVEL = BOTTLE_CAP_TRAVEL
KINDS = BOTTLE_KINDS
CAPS = tuple(CAP_MATERIALS)


def usual_cap(p: dict) -> str:
    """the profile's usual closure"""
    return KINDS[p["profile"]][2]


GRAMMAR = Grammar("bottle", {
    "bottle": Node(required=("cap",), optional={"label": 0.8}, one_of=BOTTLE_WEIGHTS, choice="profile",
                   doc="a glass body of one profile, its closure, maybe a label"),
    **{k: Node(label="body", doc=f"the {k} glass wall and bottom") for k in KINDS},
    "cap": Node(one_of={c: 1.0 for c in CAPS}, choice="cap", auto=usual_cap, doc="the closure"),
    **{c: Node(label="cap", doc=f"a {c} closure on its seat") for c in CAPS},
    "label": Node(label="label", doc="a paper band that turns about the axis"),
})

PARAMS = (
    Float("height", "overall height of the glass", "m", *BOTTLE["height"]),
    Float("width_ratio", "body radius / the profile's usual radius", "", *BOTTLE["width_ratio"]),
    Float("wall", "glass wall thickness", "m", *BOTTLE["wall"]),
    Float("label_fill", "label height / the straight part of the body", "", *BOTTLE["label_fill"]),
    Float("label_offset", "label position within the straight part (0 bottom, 1 top)", "", *BOTTLE["label_offset"]),
)


class BottleLayout(Layout):
    def bottle(self, node):
        cap = node.one("cap")
        body, profile = self.grow(node.one(node.choice), finish=cap.choice)
        self.grow(cap, body=body, profile=profile)
        if node.one("label"):
            self.grow(node.one("label"), body=body, profile=profile)

    def _body(self, node, finish):
        p = self.p
        ratio, _, _, _, punt, _ = KINDS[node.kind]
        profile = V.bottle_profile(node.kind, finish, p["height"], ratio * p["height"] * p["width_ratio"], p["wall"])
        return self.place(V.bottle_body(profile, punt * p["height"], "glass", finish), "body"), profile

    beer = bordeaux = burgundy = champagne = soda = vintage = _body

    def cap(self, node, body, profile):
        self.grow(node.one(node.choice), body=body, profile=profile)

    def _seat(self, closure, body):
        cap = self.place(closure.attached("seat", to=body.anchor("lid_seat")), "cap")
        self.join(V.seat_joint(body.root, cap, CAP_TRAVEL))

    def crown(self, node, body, profile):
        self._seat(V.crown_cap(profile, "cap"), body)

    def screw(self, node, body, profile):
        self._seat(V.screw_cap(profile, "cap"), body)

    def capsule(self, node, body, profile):
        self._seat(V.capsule(profile, self.p["profile"] == "champagne", "cap", "cork"), body)

    def stopper(self, node, body, profile):
        self._seat(V.stopper(profile, "cork"), body)

    def label(self, node, body, profile):
        p = self.p
        zone = tuple(z * p["height"] for z in KINDS[p["profile"]][5])
        band = V.label_band(profile, zone, p["label_fill"], p["label_offset"], "label")
        band = self.place(band.attached("vessel", to=body.anchor("base")), "label")
        self.join(V.spin_joint(body.root, band))


CATEGORY = Category("bottle", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BottleLayout, materials={
    "glass": ("profile", {k: v[3] for k, v in KINDS.items()}),
    "cap": ("cap", CAP_MATERIALS),
    "cork": "wood",
    "label": "painted:white|off_white|pastel_yellow|pastel_blue|black|navy|sage",
})
