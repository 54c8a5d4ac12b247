"""Printer: an inkjet, a laser or an all-in-one with a flatbed scanner and a document feeder.

Designs (``design``): an inkjet (paper cassette, fold-down output tray with a pull-out extender, ink access door,
maybe a rear paper support that flips up and a top cover over the cartridges), a laser (cassette, a toner door
across the front, an output bin in the top maybe with a paper stop that flips up, maybe a manual-feed flap under
the door) and an all-in-one (an inkjet's front under a flatbed scanner whose lid lifts at the back, maybe carrying
a document feeder with a top cover); any may have a rear jam-clearing door. Cassettes slide out; doors, trays,
lids and covers turn about their edges; one to six panel keys press into the front (role ``button``).
Parts: ``categories/parts/printers.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float

from .parts import controls
from .parts import printers as P

GRAMMAR = Grammar("printer", {
    "printer": Node(label="body", one_of={"inkjet": 0.35, "laser": 0.3, "all_in_one": 0.35}, choice="design"),
    "inkjet": Node(required=("cassette", "output_tray", "door", "panel"),
                   optional={"rear_feed": 0.5, "top_cover": 0.5, "rear_door": 0.4}),
    "laser": Node(required=("cassette", "door", "panel"),
                  optional={"paper_stop": 0.75, "rear_door": 0.4, "manual_feed": 0.5}),
    "all_in_one": Node(required=("cassette", "output_tray", "door", "panel", "scanner_lid"),
                       optional={"rear_door": 0.4}),
    "cassette": Node(label="tray"),
    "output_tray": Node(label="flap", optional={"extender": 0.6}),
    "extender": Node(label="extender"),
    "door": Node(label="door"),
    "rear_door": Node(label="door"),
    "rear_feed": Node(label="flap"),
    "top_cover": Node(label="lid"),
    "manual_feed": Node(label="flap"),
    "paper_stop": Node(label="flap"),
    "panel": Node(repeat={"key": (1, 6)}),
    "key": Node(label="button"),
    "scanner_lid": Node(label="lid", optional={"feeder": 0.75}),
    "feeder": Node(label="lid"),
})
"""Designs: inkjet (maybe a rear paper support, a top cover), laser (maybe a paper stop, a manual-feed flap),
all-in-one (a scanner lid, maybe with a document feeder); any may have a rear door; every output tray may have a
pull-out extender; 1-6 panel keys."""

PARAMS = (
    Float("width_share", "width (Y) within the design's range (DESIGNS in parts/printers.py), 0 to 1", "", 0.0, 1.0),
    Float("depth_share", "depth (X) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("height_share", "height (Z) of the printing unit within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("corner", "radius of the casing's upright corners", "m", 0.006, 0.02),
    Float("paper_fill", "paper in the cassette, share of its depth (a 250-sheet stack is ~25 mm)", "", 0.1, 0.6),
    Float("lid_share", "scanner lid thickness and feeder size within their ranges (LID), 0 to 1", "", 0.0, 1.0),
    Choice("key_shape", "panel keys round or rectangular", choices=("round", "rect")),
)

MATERIALS = {"body": "plastic:white|light_grey|black|dark_grey", "trim": "plastic:black|dark_grey|light_grey",
             "works": "painted:charcoal|black|graphite", "paper": "painted:white",
             "glass": "glass:smoked|clear", "pad": "plastic:white", "button": "plastic:black|dark_grey|light_grey",
             "lid": "plastic:black|dark_grey|white|light_grey", "toner": "plastic:black|dark_grey",
             "ink_k": "plastic:black", "ink_c": "plastic:teal|blue", "ink_m": "plastic:red", "ink_y": "plastic:yellow",
             "display": "screen"}
SUBSTRATES = {"paper": P.PAPER}


class PrinterLayout(controls.ControlFace):
    def printer(self, node):
        p, design = self.p, node.choice
        kids = node.one(design)
        shares = (p["width_share"], p["depth_share"], p["height_share"])
        self.pr = pr = P.Printer.make(design, shares, p["corner"], kids.one("manual_feed") is not None)
        self.key_spec = P.KEYS[p["key_shape"]]
        cuts = pr.cutouts(len(kids.one("panel").of("key")), self.key_spec)
        extras = []
        if design == "laser":  # the output bin is there whether or not it has a paper stop
            cuts["bin"], extras, self.stop_at = P.output_bin(pr, "trim")
        elif design == "all_in_one":
            cuts["platen"], pane = P.platen(pr, "glass")
            extras = [pane]
        inks = ("toner",) if design == "laser" else ("ink_k", "ink_c", "ink_m", "ink_y")
        extras = [*extras, *P.behind_door(pr, cuts["door"], inks), *P.display(pr, len(kids.one("panel").of("key")),
                                                                            "display")]
        for rear in ("rear_feed", "rear_door", "top_cover"):
            if kids.one(rear):
                cuts[rear] = P.REAR[rear](pr)
        made, volume = P.body(pr, "body", "works", cuts, extras)
        # the print engine's mass over the space it fills (a solid slot: painted steel frame and mechanism)
        self.bp.densities["works"] = pr.engine_kg / volume
        self.body = self.place(made, "body")
        self.cuts = cuts
        self.grow(kids)

    def _children(self, node):
        for kid in node.children:
            self.grow(kid)

    inkjet = laser = all_in_one = _children

    def cassette(self, node):
        made = P.cassette(self.pr, "body", "trim", "paper", self.p["paper_fill"])
        tray = self.place(made.attached("front", to=self.body.anchor("cassette")), "cassette")
        self.slide(self.body.root, tray.root, tray.anchor("front"), upper=P.CASSETTE["pull"] * self.pr.tray().depth)

    def _flap(self, name, cut, slot, opens, label, requires=None):
        c = self.cuts[cut]
        size = (c.hi[0] - c.lo[0], c.hi[1] - c.lo[1])
        made = self.place(P.flap(size, slot, label).attached("mount", to=self.body.anchor(cut)), name)
        self.hinge(self.body.root, made.root, made.anchor("hinge"), upper=opens)
        return made, size

    def output_tray(self, node):
        tray, size = self._flap("output_tray", "output", "trim", P.OUTPUT_OPENS, "flap")
        if node.one("extender"):
            self.grow(node.one("extender"), tray=tray, size=size)

    def extender(self, node, tray, size):
        ext = self.place(P.extender(size, "trim").attached("mount", to=tray.anchor("mount")), "extender")
        travel = P.EXTENDER["pull"] * P.EXTENDER["share"] * size[1]
        self.slide(tray.root, ext.root, ext.anchor("slide"), upper=travel, requires_open="output_tray")

    def door(self, node):
        self._flap("door", "door", "body", P.DOOR_OPENS, "door")

    def rear_door(self, node):
        self._flap("rear_door", "rear_door", "body", P.DOOR_OPENS, "door")

    def top_cover(self, node):
        self._flap("top_cover", "top_cover", "body", P.TOP_COVER_OPENS, "lid")

    def manual_feed(self, node):
        self._flap("manual_feed", "output", "trim", P.OUTPUT_OPENS, "flap")

    def rear_feed(self, node):
        self._flap("rear_feed", "rear_feed", "trim", P.REAR_FEED_OPENS, "flap")

    def paper_stop(self, node):
        made = self.place(P.flap(P.STOP, "trim", "flap").attached("hinge", to=self.stop_at), "paper_stop")
        self.hinge(self.body.root, made.root, made.anchor("hinge"), upper=P.STOP_OPENS)

    def panel(self, node):
        for i, kid in enumerate(node.of("key")):
            self.grow(kid, i=i)

    def key(self, node, i):
        self.place_button(self.body.root, f"key_{i}", self.key_spec, self.body.anchor(f"key_{i}"))

    def scanner_lid(self, node):
        pr, share = self.pr, self.p["lid_share"]
        made = self.place(P.scanner_lid(pr, "lid", "pad", P.lerp(P.LID["thick"], share)), "scanner_lid")
        self.hinge(self.body.root, made.root, made.anchor("hinge"), upper=P.LID_OPENS)
        if node.one("feeder"):
            self.grow(node.one("feeder"), lid=made)

    def feeder(self, node, lid):
        pr, share = self.pr, self.p["lid_share"]
        width, height = P.lerp(P.LID["adf_width"], share), P.lerp(P.LID["adf_height"], share)
        pieces, hinge = P.feeder(pr, lid.anchor("deck"), "lid", "trim", width, height)
        self.extend(lid.root, pieces)
        cover = self.place(P.adf_cover(pr, width, "trim").attached("hinge", to=hinge), "adf_cover")
        self.hinge(lid.root, cover.root, cover.anchor("hinge"), upper=P.ADF_OPENS)


CATEGORY = Category("printer", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PrinterLayout, MATERIALS,
                    substrates=SUBSTRATES)
