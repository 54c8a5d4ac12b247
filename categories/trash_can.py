"""Trash can: a pedal bin, a swing-top bin, an open bin with an inner bucket, or a sensor can.

Designs (``design``): a pedal bin (step can) lifts its lid by a foot pedal: the pedal is the one joint a foot
drives and the lid follows it (``Layout.couple``: URDF ``<mimic>``, MJCF ``<equality>``, USD
``PhysxMimicJointAPI``), the lid falling shut under its weight when the pedal is let go. A sensor can's lid
has its own motorised hinge (the infrared window on its front). A swing-top bin is a closed body with a flap
hung in its front that swings either way. An open bin (an office basket, a kitchen caddy) has no lid.
Pedal, sensor and open bins may hold a lift-out inner bucket (role ``lift_off``; behind a lid it needs the
lid open first) with a wire bail that turns up. Round or square bodies (``shape``). Parts:
``categories/parts/bins.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import bins as B

GRAMMAR = Grammar("trash_can", {
    "trash_can": Node(label="body", one_of={"pedal_bin": 0.35, "sensor_bin": 0.2, "swing_bin": 0.2,
                                            "open_bin": 0.25}, choice="design"),
    "pedal_bin": Node(required=("lid", "pedal"), optional={"bucket": 0.75}),
    "sensor_bin": Node(required=("lid",), optional={"bucket": 0.75}),
    "open_bin": Node(required=("bucket",)),
    "swing_bin": Node(required=("flap",)),
    "lid": Node(label="lid"),
    "pedal": Node(label="pedal"),
    "flap": Node(label="flap"),
    "bucket": Node(label="bucket", optional={"bail": 0.7}),
    "bail": Node(label="handle"),
})
"""Designs: pedal bin (a lid hinged at the back, lifted by a foot pedal), sensor can (a motorised lid),
swing-top bin (a closed body with a flap in its front), open bin (no lid). An inner bucket lifts out; its
wire bail folds down over its rim."""

PARAMS = (
    Float("width", "outer width (Y); a round bin's diameter", "m", *B.RANGES.width),
    Float("depth_ratio", "a square bin's depth (X) as a fraction of its width", "", *B.RANGES.depth_ratio),
    Float("aspect", "height of the body's walls (Z, the lid excluded) as a multiple of its width (at most"
                    " 0.72 m)", "",
          *B.RANGES.aspect),
    Float("flap_height", "height of a swing-top bin's flap", "m", *B.RANGES.flap_height),
    Choice("shape", "round or square body (a swing-top bin is square)", choices=("round", "square")),
    Choice("finish", "body finish", choices=("brushed_metal", "enamel", "plastic"), weights=(0.4, 0.25, 0.35)),
)

MATERIALS = {"body": "finish", "trim": "plastic:black|dark_grey", "bucket": "plastic:dark_grey|light_grey|white",
             "wire": "brushed_metal", "sensor": "glass:smoked"}
# Modelled walls are massed as sheet (metres): stainless and coated step cans are 0.4-0.6 mm steel (Brabantia,
# simplehuman); moulded plastic bins and buckets 2-3 mm.
SHEET = {"brushed_metal": 0.0005, "enamel": 0.0005, "plastic": 0.0025}
BUCKET_SHEET = 0.0015  # m, a moulded PP inner bucket (Brabantia, Curver spare buckets): 1.5 mm walls


class TrashCanLayout(Layout):
    def trash_can(self, node):
        p = self.p
        design = node.choice
        shape = "square" if design == "swing_bin" else p["shape"]
        size = B.BinSize(shape, p["width"], p["width"] * (1.0 if shape == "round" else p["depth_ratio"]),
                         min(p["width"] * p["aspect"], B.TALLEST))
        self.sheet = SHEET[p["finish"]]
        if design == "swing_bin":
            body = self.place(B.swing_body(size, p["flap_height"], "body", self.sheet), "body")
        else:
            body = self.place(B.body(size, "body", "trim", design != "open_bin", design == "pedal_bin",
                                     self.sheet), "body")
        self.grow(node.one(design), body=body, size=size)

    def pedal_bin(self, node, body, size):
        self.grow(node.one("lid"), body=body, size=size, sensor=None)
        self.grow(node.one("pedal"), body=body)
        # one degree of freedom for the foot: the lid turns LID_OPENS while the pedal goes down PEDAL_TURN
        self.couple("lid", "pedal", ratio=B.LID_OPENS / B.PEDAL_TURN)
        if node.one("bucket"):
            # the lid is open while the pedal is down: the pedal, the joint a foot drives, gates the bucket
            self.grow(node.one("bucket"), body=body, size=size, gate="pedal")

    def sensor_bin(self, node, body, size):
        self.grow(node.one("lid"), body=body, size=size, sensor="sensor")
        if node.one("bucket"):
            self.grow(node.one("bucket"), body=body, size=size, gate="lid")

    def open_bin(self, node, body, size):
        self.grow(node.one("bucket"), body=body, size=size, gate=None)

    def swing_bin(self, node, body, size):
        self.grow(node.one("flap"), body=body, size=size)

    def lid(self, node, body, size, sensor):
        hinge = body.anchor("hinge")
        self.place(B.lid(size, "body", "trim", self.sheet, sensor).attached("hinge", to=hinge), "lid")
        # a pedal bin's lid falls shut under its own weight when the pedal is let go, carrying the pedal back up
        # (no return spring: an angular spring's drive target beyond the rest stop fails SimReady's DJ.001)
        self.hinge("body", "lid", hinge, upper=B.LID_OPENS, role="lid")

    def pedal(self, node, body):
        at = body.anchor("pedal")
        self.place(B.pedal("trim", "wire").attached("pivot", to=at), "pedal")
        self.hinge("body", "pedal", at, upper=B.PEDAL_TURN)

    def flap(self, node, body, size):
        at = body.anchor("flap")
        self.place(B.flap(size, self.p["flap_height"], "body", self.sheet).attached("pivot", to=at), "flap")
        self.hinge("body", "flap", at, upper=B.FLAP_SWINGS, lower=-B.FLAP_SWINGS)

    def bucket(self, node, body, size, gate):
        inner = B.bucket_size(size)
        made = self.place(B.bucket(inner, "bucket", BUCKET_SHEET).attached("seat", to=body.anchor("floor")), "bucket")
        # the body's walls guide the bucket until its bottom clears the rim: it lifts right out
        guided = float(body.anchor("rim").origin[2] - body.anchor("floor").origin[2])
        self.lift("body", "bucket", made.anchor("seat"), engagement=guided, requires_open=gate)
        if node.one("bail"):
            self.grow(node.one("bail"), bucket=made, size=inner)

    def bail(self, node, bucket, size):
        at = bucket.anchor("bail")
        self.place(B.bail(size, "wire").attached("pivot", to=at), "bail")
        # under a lid the core stops the bail where it meets the closed lid (it stands up once the bucket is out)
        self.hinge("bucket", "bail", at, upper=B.BAIL_TURN)


CATEGORY = Category("trash_can", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TrashCanLayout, MATERIALS,
                    palette=appliance)
