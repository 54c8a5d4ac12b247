"""Eyeglasses: full-rim, half-rim or rimless glasses, sunglasses or folding readers, put down folded.

Designs (``design``, sizes and sources in ``categories/parts/eyewear.py``): ``full_rim`` glasses with metal
or moulded acetate rims; ``half_rim`` (browline / Supra) glasses whose rim holds the lens's top and a nylon
thread its bottom; ``rimless`` glasses whose bridge and end pieces are screwed to the drilled lenses;
``sunglasses`` with tinted lenses (a metal aviator's double bridge or a thick acetate front); ``folding_readers``
whose front folds in half at a bridge hinge.

The glasses lie lenses down, the front (``body``) on the table with its brow toward +X, the temples folded
on its back. Each temple (``temple``) turns about its end piece's hinge (revolute about X) up to stand square
to the front; a ``spring`` hinge flexes past that. The temple folded last lies over the other, which opens
once it has. A folding reader's -Y half (``front_half``, with its temple) turns up about the bridge hinge
(revolute about X) over the +Y half. PartNet-Mobility: Eyeglasses.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import eyewear as E

PARAMS = (
    Float("size", "where the lens width lies in its design's range (0 narrowest, 1 widest)", "", 0.0, 1.0),
    Float("bridge", "where the bridge (distance between the lenses) lies in its design's range", "", 0.0, 1.0),
    Float("temple_length", "where the temple length lies in its design's range", "", 0.0, 1.0),
    Choice("lens_shape", "lens outline", choices=tuple(E.SHAPES), weights=tuple(E.SHAPE_SHARES.values())),
    Float("lens_depth", "the lens height moved by this share from its outline's (shallow or deep lenses)", "",
          -0.12, 0.12),
    Choice("frame", "front and temples: moulded acetate or metal (rimless glasses are always metal)",
           choices=("acetate", "metal"), weights=(0.5, 0.5)),
    Choice("acetate_colour", "colour of an acetate frame", choices=tuple(E.ACETATES),
           weights=tuple(E.ACETATES.values())),
    Choice("metal_finish", "metal frame finish: polished, brushed or painted (a black or coloured enamel)",
           choices=("chrome", "brushed_metal", "painted"), weights=(0.35, 0.3, 0.35)),
    Choice("hinge", "temple hinges: a plain barrel hinge or a spring (flex) hinge that opens past square",
           choices=("barrel", "spring"), weights=(0.5, 0.5)),
)

GRAMMAR = Grammar("eyeglasses", {
    "eyeglasses": Node(label="body", one_of=E.DESIGN_SHARES, choice="design"),
    "full_rim": Node(required=("temple", "over_temple")),
    "half_rim": Node(required=("temple", "over_temple")),
    "rimless": Node(required=("temple", "over_temple")),
    "sunglasses": Node(required=("temple", "over_temple")),
    "folding_readers": Node(required=("reader_temple", "front_half")),
    "front_half": Node(label="front_half", required=("reader_temple",)),
    "temple": Node(label="temple"),
    "over_temple": Node(label="temple"),
    "reader_temple": Node(label="temple"),
})
"""Every pair has two temples, one folded over the other; a folding reader's temples are telescoping ones,
collapsed, each folded on its own half (its second temple on the folding half)."""

MATERIALS = {"acetate": ("acetate_colour", {c: f"plastic:{c}" for c in E.ACETATES}),
             "metal": ("metal_finish", {"brushed_metal": "brushed_metal:stainless|stainless_dark",
                                        "painted": "enamel:black|graphite|midnight|cobalt|red"}),
             "lens": "glass:clear|clear_blue", "shade": "glass:smoked|bottle_green|amber",
             "pad": "plastic:light_grey|white", "tip": "plastic:black|dark_grey"}
# CR-39 lenses 1310 kg/m^3, polycarbonate (most sunglass lenses) 1200 (PPG, Sabic datasheets); cellulose
# acetate frames 1280-1300 (Mazzucchelli M49 datasheet): measured as their look's glass and plastic otherwise
SUBSTRATES = {"lens": 1310.0, "shade": 1200.0, "acetate": 1290.0}
SQUARE = math.radians(90)  # a temple opened square to the front
OPENS = {"barrel": math.radians(8), "spring": math.radians(25)}
"""Past square: a barrel hinge's stop lets a temple splay 5-10 degrees; a spring hinge (OBE, Comotec flex
hinges) flexes 20-30 degrees more and springs back."""
FOLDS = math.radians(100)
"""A folding front turns its -Y half up about the bridge hinge, its temples folded first and kept folded while it
is (its hinge ``requires_closed`` them). Real ones fold flat, half on half (180 degrees); folded that far here, the
front swung back at a drive's speed (``validate --sim`` reach, from the folded state) knocks the 2 g temple on
its back open (0.76 rad, seed 1), so the half stands just past upright."""


class EyeglassesLayout(Layout):
    def eyeglasses(self, node):
        p, design = self.p, node.choice
        self.gl = E.glasses(design, p["lens_shape"], p["size"], p["bridge"], p["temple_length"],
                            p["frame"] == "acetate", p["lens_depth"])
        frame = "acetate" if self.gl.acetate else "metal"
        self.slots = {"frame": frame, "metal": "metal", "lens": "shade" if design == "sunglasses" else "lens",
                      "pad": "pad", "tip": "tip"}
        sides = (1,) if self.gl.design.fold else (1, -1)
        self.body = self.place(E.front(self.gl, sides, self.slots, "body", self._bridge_from), "body")
        self.under = None if self.gl.design.fold else E.temple(self.gl, 1, self.slots["frame"], "tip")
        self.grow(node.one(design))

    @property
    def _bridge_from(self) -> float:
        return 0.0014 if self.gl.design.fold else 0.0

    def full_rim(self, node):  # the temple on top first: the one under it opens once it is open
        self.grow(node.one("over_temple"), front=self.body, parent="body")
        self.grow(node.one("temple"))

    half_rim = rimless = sunglasses = full_rim

    def folding_readers(self, node):
        self.grow(node.one("reader_temple"), front=self.body, parent="body", side=1)
        self.grow(node.one("front_half"))

    def front_half(self, node):
        half = self.place(E.front(self.gl, (-1,), self.slots, "front_half", self._bridge_from), "front_half")
        # folded only with both temples folded, which stay folded while it is (a real reader's order)
        self.hinge("body", "front_half", self.body.anchor("fold"), upper=FOLDS,
                   requires_closed=("temple", "over_temple"))
        self.grow(node.one("reader_temple"), front=half, parent="front_half", side=-1)

    def reader_temple(self, node, front, parent, side):
        name = "temple" if side > 0 else "over_temple"
        self.place(E.telescoping_temple(self.gl, side, self.slots["frame"], "tip"), name)
        self.hinge(parent, name, front.anchor("hinge+" if side > 0 else "hinge-"), upper=self._opens, role="lid")

    def temple(self, node):
        self.place(self.under, "temple")
        self.hinge("body", "temple", self.body.anchor("hinge+"), upper=self._opens, role="lid",
                   requires_open="over_temple")

    def over_temple(self, node, front, parent):
        at = front.anchor("hinge-")
        slope = E.over_slope(self.gl, self.under)
        over = E.temple(self.gl, -1, self.slots["frame"], "tip")
        self.place(over.placed(at.turned("z", slope) @ at.inverse()), "over_temple")
        self.hinge(parent, "over_temple", at.turned("z", slope), upper=self._opens - slope, role="lid")

    @property
    def _opens(self) -> float:
        return SQUARE + OPENS[self.p["hinge"]]


CATEGORY = Category("eyeglasses", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, EyeglassesLayout, MATERIALS,
                    substrates=SUBSTRATES)
