"""Bottle: a hollow glass bottle with a cap that unscrews and an optional label band.

The body is a thin glass wall of revolution whose outside follows a smooth spline
through many control points of one of six recognisable profiles, closed by a bottom
(a push-up punt for wine and champagne):

* ``beer``: long-neck, straight body, rounded shoulder, long neck, crown finish;
* ``bordeaux``: straight body, high abrupt shoulder;
* ``burgundy``: wider body, long sloping shoulder;
* ``champagne``: heavy, sloping shoulder, deep punt, foil capsule and mushroom cork;
* ``soda``: PET bottle with a waist, support ring and screw threads;
* ``vintage``: apothecary bottle, wide body, short neck with a flared lip and a stopper;
* ``dispenser``: a Boston round (soap / lotion) with a short neck and a pump.

The closure (``cap``; ``auto``, the default, draws one the profile usually wears with
``closure_draw``, :data:`.parts.closure_sizes.BOTTLE_CLOSURES`):

* crown, screw cap, foil capsule or stopper: sits on the lip with clearance all round
  (a sleeve cap's skirt is drawn but collides through its top plate only: see
  :func:`.parts.vessel.sleeve` for the PhysX reason; its top is flush with its skirt, so
  the cap fits its neck); it turns freely about Z and lifts 0..1 cm along +Z
  (unscrewing), resting at 0 (gravity holds it on its seat);
* ``swing_top`` (Grolsch): a porcelain stopper on a rubber washer with a wire bail to a
  ring round the neck: ``flip_revolute``, the bail swings back about the ring's clasp and
  the stopper tips about its back edge;
* ``pump``: a collar that unscrews like a screw cap and an up-lock actuator head with a
  nozzle on it that turns and rises 12 mm (continuous_prismatic, child of the collar);
* ``sports``: a screw cap with a push-pull spout that rises 6 mm (prismatic, child of
  the cap). The label is a thin paper band glued around the
straight part of the body: pieces of the body (a label does not turn on a real bottle).
Walls, finishes and closures live in :mod:`.parts.vessel`.
"""

from __future__ import annotations

import numpy as np

from infmob_usd import joints as J
from infmob_usd.assembly import Assembly
from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Float

from .parts import closures as CL
from .parts import vessel as V
from .parts.closure_sizes import BOTTLE_CLOSURES, CLOSURE_FINISH, PUMP, SPORTS, SWING_TOP
from .parts.vessel_sizes import BOTTLE, BOTTLE_CAP_TRAVEL, BOTTLE_KINDS, BOTTLE_WEIGHTS, CAP_MATERIALS

CAP_TRAVEL = BOTTLE_CAP_TRAVEL
KINDS = BOTTLE_KINDS
SEATED = tuple(CAP_MATERIALS)  # crown, screw, capsule, stopper: turn and lift on the lip
CAPS = SEATED + ("swing_top", "pump", "sports")


def usual_cap(p: dict) -> str:
    """a closure the profile usually wears, drawn by ``closure_draw`` with its weights"""
    w = BOTTLE_CLOSURES[p["profile"]]
    cum = np.cumsum(list(w.values())) / sum(w.values())
    return list(w)[int(np.searchsorted(cum, p["closure_draw"], side="right").clip(0, len(w) - 1))]


def finish_of(cap: str) -> str:
    """the glass finish a closure sits on"""
    return CLOSURE_FINISH.get(cap, cap)


GRAMMAR = Grammar("bottle", {
    "bottle": Node(required=("cap",), optional={"label": 0.8}, one_of=BOTTLE_WEIGHTS, choice="profile",
                   doc="a glass body of one profile, its closure, maybe a label"),
    **{k: Node(label="body", doc=f"the {k} glass wall and bottom") for k in KINDS},
    "cap": Node(one_of={c: 1.0 for c in CAPS}, choice="cap", auto=usual_cap, doc="the closure"),
    **{c: Node(label="cap", doc=f"a {c} closure on its seat") for c in SEATED},
    "swing_top": Node(label="cap", doc="a porcelain stopper on a wire bail (flip: swing, then tip)"),
    "pump": Node(label="cap", required=("head",), doc="a pump's collar that unscrews"),
    "head": Node(label="head", doc="the pump's actuator head: turns to unlock, rises"),
    "sports": Node(label="cap", required=("spout",), doc="a screw cap with a push-pull spout"),
    "spout": Node(label="spout", doc="the push-pull spout: rises to open"),
    "label": Node(label="body", doc="a paper label glued round the body (pieces of the body)"),
})

PARAMS = (
    Float("height", "overall height of the glass", "m", *BOTTLE["height"]),
    Float("width_ratio", "body radius / the profile's usual radius", "", *BOTTLE["width_ratio"]),
    Float("wall", "glass wall thickness", "m", *BOTTLE["wall"]),
    Float("label_fill", "label height / the straight part of the body", "", *BOTTLE["label_fill"]),
    Float("label_offset", "label position within the straight part (0 bottom, 1 top)", "", *BOTTLE["label_offset"]),
    Float("closure_draw", "draw among the closures the profile usually wears (cap=auto)", "", 0.0, 1.0),
)


class BottleLayout(Layout):
    def bottle(self, node):
        cap = node.one("cap")
        body, profile = self.grow(node.one(node.choice), finish=finish_of(cap.choice))
        self.grow(cap, body=body, profile=profile)
        if node.one("label"):
            self.grow(node.one("label"), body=body, profile=profile)

    def _body(self, node, finish):
        p = self.p
        ratio, _, _, _, punt, _ = KINDS[node.kind]
        profile = V.bottle_profile(node.kind, finish, p["height"], ratio * p["height"] * p["width_ratio"], p["wall"])
        return self.place(V.bottle_body(profile, punt * p["height"], "glass", finish), "body"), profile

    beer = bordeaux = burgundy = champagne = soda = vintage = dispenser = _body

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

    def swing_top(self, node, body, profile):
        fittings, stopper, f = CL.swing_top(profile, "porcelain", "washer", "wire")
        base = body.anchor("base")
        self.extend(body.root, Assembly.single("f", fittings, {"vessel": IDENTITY}).attached("vessel", to=base).pieces)
        cap = self.place(stopper.attached("vessel", to=base), "cap")
        sw, tip = (Frame.at(base.point(f[k].origin), z=base.vector(f[k].z)) for k in ("swing", "tip"))
        self.join(J.flip_revolute(body.root, cap.root, tuple(sw.origin), tuple(sw.z), (0.0, SWING_TOP["swing"]),
                                  tuple(tip.origin), tuple(tip.z), (0.0, SWING_TOP["tip"]), role="lid"))

    def pump(self, node, body, profile):
        collar = CL.pump_collar(profile, float(body.anchor("neck_top").origin[2] - body.anchor("base").origin[2]),
                                "cap")
        collar = self.place(collar.attached("seat", to=body.anchor("lid_seat")), "cap")
        self.join(V.seat_joint(body.root, collar, CAP_TRAVEL))
        self.grow(node.one("head"), collar=collar)

    def head(self, node, collar):
        head = self.place(CL.pump_head("cap").attached("stem", to=collar.anchor("top")), "head")
        s = head.anchor("stem")
        self.join(J.continuous_prismatic(collar.root, head.root, tuple(s.origin), tuple(s.z), (0.0, PUMP["rise"]),
                                         role="button"))

    def sports(self, node, body, profile):
        cap = self.place(V.screw_cap(profile, "cap").attached("seat", to=body.anchor("lid_seat")), "cap")
        self.join(V.seat_joint(body.root, cap, CAP_TRAVEL))
        self.grow(node.one("spout"), cap=cap)

    def spout(self, node, cap):
        sp = self.place(CL.sports_spout(0.0, "spout").attached("base", to=cap.anchor("top")), "spout")
        # friction-held, not spring-returned: a push-pull spout stays where it is put
        self.slide(cap.root, sp.root, sp.anchor("base"), SPORTS["pull"], role="lid")

    def label(self, node, body, profile):
        p = self.p
        zone = tuple(z * p["height"] for z in KINDS[p["profile"]][5])
        band = V.label_band(profile, zone, p["label_fill"], p["label_offset"], "label")
        self.extend(body.root, band.attached("vessel", to=body.anchor("base")).pieces)  # glued: the body's


CATEGORY = Category("bottle", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BottleLayout, materials={
    "glass": ("profile", {k: v[3] for k, v in KINDS.items()}),
    "cap": ("cap", {**CAP_MATERIALS, "swing_top": "ceramic", "pump": "plastic:white|black|light_grey",
                    "sports": "plastic:white|blue|green|orange|black"}),
    "cork": "wood", "porcelain": "ceramic", "washer": "rubber", "wire": "chrome",
    "spout": "plastic:white|light_grey|black",
    "label": "painted:white|off_white|pastel_yellow|pastel_blue|black|navy|sage",
})
