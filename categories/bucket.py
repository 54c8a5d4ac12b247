"""Bucket: a household pail with a bail, a paint can with a press-in lid and a bail, or a mop bucket with a wringer.

Designs (``design``): a pail (moulded plastic or galvanised steel, tapered) carries a wire bail with a plastic grip
on two ears under its rim: the bail lies back against the wall and swings over the top to the front. A paint can
(straight tinplate or a slightly tapered plastic pail, with a printed label) has the same bail and a lid pressed
into its rim that lifts off (role ``lift_off``, guided by its plug ring). A commercial mop bucket has a down-press
wringer over the back of its tub whose lever is pressed forward and down and springs back (role ``lever``),
driving the wringer's press plate forward against the mop (a coupled joint, ``Layout.couple``); it
usually stands on four swivel casters. Parts: ``categories/parts/buckets.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import buckets as B
from .parts import seating

GRAMMAR = Grammar("bucket", {
    "bucket": Node(label="body", one_of={"pail": 0.4, "paint_can": 0.3, "mop_bucket": 0.3}, choice="design"),
    "pail": Node(required=("bail",)),
    "paint_can": Node(required=("lid", "bail")),
    "mop_bucket": Node(required=("lever",), optional={"casters": 0.75}),
    "bail": Node(label="handle"),
    "lid": Node(label="lid"),
    "lever": Node(label="lever", required=("press",)),
    "press": Node(label="press"),
    "casters": Node(repeat={"caster": 4}),
    "caster": Node(label="caster", required=("wheel",)),
    "wheel": Node(label="wheel"),
})
"""Designs: pail (a bail), paint can (a lift-off lid and a bail), mop bucket (a wringer lever driving a press plate,
maybe on four casters)."""

PARAMS = (
    Float("size", "size within the design's range (ROUND / MOP in parts/buckets.py): the top diameter, or a mop"
                  " bucket's length", "", 0.0, 1.0),
    Float("height_share", "height within the design's range (a round bucket's as a fraction of its diameter)", "",
          0.0, 1.0),
    Float("shape", "a round bucket's foot diameter (a fraction of the top) within its range; a mop bucket's width",
          "", 0.0, 1.0),
    Choice("finish", "a pail's or paint can's wall: moulded plastic or galvanised / tinplate steel",
           choices=("plastic", "brushed_metal"), weights=(0.6, 0.4)),
)

MATERIALS = {"body": "finish", "can": ("finish", {"plastic": "plastic:white|white|light_grey|black",
                                                  "brushed_metal": "brushed_metal"}),
             "tub": "plastic:yellow|yellow|dark_grey|blue|red|light_grey",
             "wringer": "plastic:dark_grey|black|light_grey", "wire": "brushed_metal",
             "grip": "plastic:black|dark_grey|red|blue|yellow", "lever": "plastic:dark_grey|black",
             "label": "painted:white|off_white|pastel_blue|pastel_yellow|charcoal|navy|sage",
             "caster": "plastic:black", "wheel": "rubber"}


class BucketLayout(Layout):
    def bucket(self, node):
        p, design = self.p, node.choice
        self.sheet = B.SHEET[p["finish"]]
        if design == "mop_bucket":
            casters = bool(node.one(design).one("casters"))
            self.caster_kind = seating.caster("single", B.MOP["caster"]) if casters else None
            self.mop = B.MopSize(*(B._lerp(B.MOP[k], p[s]) for k, s in (("depth", "size"), ("width", "shape"),
                                                                        ("height", "height_share"))),
                                 raised=self.caster_kind.stem_top if casters else 0.0)
            body = self.place(B.mop_tub(self.mop, "tub", "wringer"), "body")
        else:
            self.size = B.Round.of("pail" if design == "pail" else "paint", p["size"], p["height_share"], p["shape"])
            self.slot = "body" if design == "pail" else "can"
            label = "label" if design == "paint_can" else None
            body = self.place(B.round_body(self.size, self.slot, self.sheet, label), "body")
        self.grow(node.one(design), body=body)

    def pail(self, node, body):
        self.grow(node.one("bail"), body=body)

    def paint_can(self, node, body):
        self.grow(node.one("lid"), body=body)
        self.grow(node.one("bail"), body=body)

    def mop_bucket(self, node, body):
        self.grow(node.one("lever"), body=body)
        if node.one("casters"):
            self.grow(node.one("casters"), body=body)

    def bail(self, node, body):
        at = body.anchor("bail")
        self.place(B.bail(self.size, "wire", "grip").attached("pivot", to=at), "handle")
        self.hinge("body", "handle", at, upper=B.BAIL_TURNS)

    def lid(self, node, body):
        at = body.anchor("lid_seat")
        self.place(B.paint_lid(self.size, self.slot, self.sheet).attached("seat", to=at), "lid")
        self.lift("body", "lid", at, engagement=B.plug_depth())

    def lever(self, node, body):
        at = body.anchor("lever")
        self.place(B.mop_lever(self.mop, "lever", "grip").attached("pivot", to=at), "lever")
        self.hinge("body", "lever", at, upper=B.LEVER_PRESS, role="lever")
        self.grow(node.one("press"), body=body)

    def press(self, node, body):
        at = body.anchor("press")
        self.place(B.press_plate(self.mop, "wringer").attached("slide", to=at), "press")
        travel = B.press_travel(self.mop)
        self.slide("body", "press", at, upper=travel)
        self.couple("press", "lever", ratio=travel / B.LEVER_PRESS)  # the lever drives the plate

    def casters(self, node, body):
        for i, kid in enumerate(node.of("caster")):
            self.grow(kid, body=body, i=i)

    def caster(self, node, body, i):
        tip = body.anchor(f"tip_{i}")
        fork = self.place(seating.fork(self.caster_kind).placed(tip), f"caster_{i}")
        self.spin("body", fork.root, fork.anchor("swivel"), role="swivel")
        self.grow(node.one("wheel"), fork=fork, wheel=seating.wheels(self.caster_kind)[0].mounted(tip), i=i)

    def wheel(self, node, fork, wheel, i):
        made = self.place(wheel, f"wheel_{i}")
        self.spin(fork.root, made.root, made.anchor("axle"), role="wheel")


CATEGORY = Category("bucket", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BucketLayout, MATERIALS)
