"""Vase: a hollow vessel of revolution with an optional lid that sits in its mouth.

The body is a thin wall of revolution whose outside follows a smooth spline through
the control points of one of six classic shapes (amphora, ginger jar, bud vase,
cylinder, bottle-neck, bowl), closed by a bottom disc, so it stays hollow for the
simulator and a lid can sit on its rim; a foot ring is glued under it (so a lidless
vase is still an articulation). The lid (:func:`~.parts.vessel.lift_off_lid`) is a
flange resting a small gap above the rim, a domed top with a finial, and a solid plug
that reaches into the mouth with radial clearance from the wall; it turns freely about
Z and lifts along +Z (0..5 cm), resting on its seat at 0 (gravity holds it down).
Walls, lids and their proportions live in :mod:`.parts.vessel`.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import vessel as V
from .parts.vessel_sizes import ENAMEL_SHEET, VASE, VASE_LIFT, VASE_SHAPES

LID_LIFT = VASE_LIFT
SHAPES = VASE_SHAPES

GRAMMAR = Grammar("vase", {
    "vase": Node(required=("foot",), optional={"lid": 0.5}, one_of={s: 1.0 for s in SHAPES}, choice="profile",
                 doc="a body of one classic shape on a foot ring, maybe a lid"),
    **{s: Node(label="body", doc=f"the {s} wall of revolution and its bottom") for s in SHAPES},
    "foot": Node(label="stand", doc="a foot ring glued under the bottom"),
    "lid": Node(label="lid", doc="a lift-off lid with a plug in the mouth"),
})

PARAMS = (
    Float("height", "overall height of the body", "m", *VASE["height"]),
    Float("diameter_ratio", "largest body diameter / height", "", *VASE["diameter_ratio"]),
    Choice("finish", "body and lid material", choices=("ceramic", "glass", "enamel"), weights=VASE["finish_weights"]),
    Float("wall", "wall thickness", "m", *VASE["wall"]),
    Float("shape_jitter", "random scale of each profile control radius (+-)", "", *VASE["shape_jitter"]),
    Float("lid_overhang", "lid flange overhang beyond the rim", "m", *VASE["lid_overhang"]),
    Float("lid_dome", "lid dome height / flange radius", "", *VASE["lid_dome"]),
)


class VaseLayout(Layout):
    def vase(self, node):
        body, profile = self.grow(node.one(node.choice))
        self.grow(node.one("foot"), body=body, profile=profile)
        if node.one("lid"):
            self.grow(node.one("lid"), body=body, profile=profile)

    def _body(self, node):
        p = self.p
        jitter = [p["shape_jitter"] * float(self.rng.uniform(-1, 1)) for _ in SHAPES[node.kind]]
        body, profile = V.vase_body(SHAPES[node.kind], p["height"], p["diameter_ratio"] * p["height"] / 2, p["wall"],
                                    jitter, "body", sheet=self._sheet(0.0))
        return self.place(body, "body"), profile

    amphora = ginger_jar = bud_vase = cylinder = bottle_neck = bowl = _body

    def _sheet(self, solid: float) -> float:
        """Enamelled sheet steel weighs as a sheet; ceramic and glass as modelled (``solid``)."""
        return ENAMEL_SHEET if self.p["finish"] == "enamel" else solid

    def foot(self, node, body, profile):
        foot = self.place(V.foot_ring(profile, "body").attached("mount", to=body.anchor("base")), "foot")
        self.join(J.fixed(body.root, foot.root))

    def lid(self, node, body, profile):
        p = self.p
        lid = V.lift_off_lid(profile, p["lid_overhang"], p["lid_dome"], "body", sheet=self._sheet(p["wall"]))
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LID_LIFT))


CATEGORY = Category("vase", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, VaseLayout, materials={"body": "finish"})
