"""Vase: a hollow vessel of revolution on a foot, closed by a lid, a stopper or a removable liner.

The body is a thin wall of revolution whose outside follows a smooth spline through
the control points of one of six classic shapes (amphora, ginger jar, bud vase,
cylinder, bottle-neck, bowl), closed by a bottom disc, so it stays hollow for the
simulator; its base is widened so the vase stands (the foot is at least 45 % of the
widest diameter, :data:`.parts.closure_sizes.VASE_STAND`) and a flared foot ring is
glued under it. Every vase has one of three closures (``closure``; ``auto``, the
default, draws one the shape usually wears, :data:`.parts.closure_sizes.VASE_CLOSURES`):

* ``lid`` (:func:`~.parts.vessel.lift_off_lid`): a flange resting a small gap above
  the rim, a domed top with a finial and a solid plug reaching into the mouth; it turns
  freely about Z and lifts along +Z (0..5 cm) (a ginger jar, a lidded urn);
* ``stopper`` (:func:`~.parts.closures.vase_stopper`): a tall turned stopper in a
  narrow neck, turning and lifting the same way (a bud vase, a decanter-like bottle vase);
* ``liner`` (:func:`~.parts.closures.liner`): a removable glass liner hanging from a
  rolled flange on the rim, its tube reaching most of the way down with clearance from
  the narrowest part of the wall; it slides out along +Z (prismatic, its depth below the
  rim), as florists' vase liners do.

Walls, lids and their proportions live in :mod:`.parts.vessel` and
:mod:`.parts.closure_sizes`.
"""

from __future__ import annotations

import numpy as np

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import closures as C
from .parts import vessel as V
from .parts.closure_sizes import LINER, VASE_CLOSURES, VASE_STAND
from .parts.vessel_sizes import ENAMEL_SHEET, VASE, VASE_LIFT, VASE_SHAPES

LID_LIFT = VASE_LIFT
SHAPES = VASE_SHAPES
CLOSURES = ("lid", "stopper", "liner")


def usual_closure(p: dict) -> str:
    """the closure the shape usually wears, drawn by ``closure_draw`` with its weights"""
    w = VASE_CLOSURES[p["profile"]]
    cum = np.cumsum(list(w.values())) / sum(w.values())
    return list(w)[int(np.searchsorted(cum, p["closure_draw"], side="right").clip(0, len(w) - 1))]


GRAMMAR = Grammar("vase", {
    "vase": Node(required=("foot", "closure"), one_of={s: 1.0 for s in SHAPES}, choice="profile",
                 doc="a body of one classic shape on a foot ring, and its closure"),
    **{s: Node(label="body", doc=f"the {s} wall of revolution and its bottom") for s in SHAPES},
    "foot": Node(label="stand", doc="a flared foot ring glued under the bottom"),
    "closure": Node(one_of={c: 1.0 for c in CLOSURES}, choice="closure", auto=usual_closure,
                    doc="what closes the mouth"),
    "lid": Node(label="lid", doc="a lift-off lid with a plug in the mouth (turns and lifts)"),
    "stopper": Node(label="stopper", doc="a tall turned stopper in the neck (turns and lifts)"),
    "liner": Node(label="liner", doc="a removable glass liner hanging from its flange (slides out)"),
})

PARAMS = (
    Float("height", "overall height of the body", "m", *VASE["height"]),
    Float("diameter_ratio", "largest body diameter / height", "", *VASE["diameter_ratio"]),
    Choice("finish", "body and lid material", choices=("ceramic", "glass", "enamel"), weights=VASE["finish_weights"]),
    Float("wall", "wall thickness", "m", *VASE["wall"]),
    Float("shape_jitter", "random scale of each profile control radius (+-)", "", *VASE["shape_jitter"]),
    Float("lid_overhang", "lid flange overhang beyond the rim", "m", *VASE["lid_overhang"]),
    Float("lid_dome", "lid dome height / flange radius", "", *VASE["lid_dome"]),
    Float("closure_draw", "draw among the closures the shape usually wears (closure=auto)", "", 0.0, 1.0),
    Float("liner_reach", "liner depth / vase height", "", *LINER["reach"]),
)


class VaseLayout(Layout):
    def vase(self, node):
        body, profile = self.grow(node.one(node.choice))
        self.grow(node.one("foot"), body=body, profile=profile)
        self.grow(node.one("closure"), body=body, profile=profile)

    def closure(self, node, body, profile):
        self.grow(node.one(node.choice), body=body, profile=profile)

    def _body(self, node):
        p = self.p
        jitter = [p["shape_jitter"] * float(self.rng.uniform(-1, 1)) for _ in SHAPES[node.kind]]
        body, profile = V.vase_body(SHAPES[node.kind], p["height"], p["diameter_ratio"] * p["height"] / 2, p["wall"],
                                    jitter, "body", sheet=self._sheet(0.0), stand=VASE_STAND)
        return self.place(body, "body"), profile

    amphora = ginger_jar = bud_vase = cylinder = bottle_neck = bowl = _body

    def _sheet(self, solid: float) -> float:
        """Enamelled sheet steel weighs as a sheet; ceramic and glass as modelled (``solid``)."""
        return ENAMEL_SHEET if self.p["finish"] == "enamel" else solid

    def foot(self, node, body, profile):
        foot = self.place(C.stand_foot(profile, "body").attached("mount", to=body.anchor("base")), "foot")
        self.join(J.fixed(body.root, foot.root))

    def lid(self, node, body, profile):
        p = self.p
        lid = V.lift_off_lid(profile, p["lid_overhang"], p["lid_dome"], "body", sheet=self._sheet(p["wall"]))
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LID_LIFT))

    def stopper(self, node, body, profile):
        st = C.vase_stopper(profile, "body", sheet=self._sheet(0.0))
        st = self.place(st.attached("seat", to=body.anchor("lid_seat")), "stopper")
        self.join(V.seat_joint(body.root, st, LID_LIFT))

    def liner(self, node, body, profile):
        ln, lift = C.liner(profile, "liner", self.p["liner_reach"])
        ln = self.place(ln.attached("seat", to=body.anchor("lid_seat")), "liner")
        self.join(V.seat_joint(body.root, ln, lift, turns=False))


CATEGORY = Category("vase", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, VaseLayout, materials={"body": "finish",
                                                                                       "liner": "glass:clear"})
