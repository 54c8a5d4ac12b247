"""Storage rack: a steel pallet rack / shelving unit with adjustable levels and optional goods.

X is depth (the front faces +X), Y is width, Z is up. Frames of two braced uprights stand at
both ends and between bays (a rack wider than 2.2 m has two bays). Each level of each bay is a
pair of beams with a deck (wire mesh, steel panel or wooden board). The bottom level is fixed;
every other level slides up along +Z, resting just above stop brackets on the uprights (its
lower limit, where gravity holds it), by the same travel for every level, so raised together
nothing closes up and a level raised alone never reaches the level above or its goods. Goods
(cardboard boxes, plastic crates, or pallets with stacked boxes) are fixed on a level, inside
the bay, clear of the uprights. Parts: ``categories/parts/racks.py``.
"""

from __future__ import annotations

import numpy as np

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import racks as R


def bays(p, rng) -> int:
    """bay_count, or 1 up to 2.2 m of width, else 2"""
    return p["bay_count"] or (1 if p["width"] <= 2.2 else 2)


def goods(p, rng) -> int:
    """1 with chance goods_chance (when has_goods), else 0"""
    return int(p["has_goods"] and rng.random() < p["goods_chance"])


GRAMMAR = Grammar("storage_rack", {
    "storage_rack": Node(label="frame", repeat={"bay": bays}),
    "bay": Node(repeat={"level": "level_count"}),
    "level": Node(label="shelf", repeat={"goods": goods}),
    "goods": Node(one_of={"boxes": 0.4, "pallet": 0.35, "crates": 0.25}),
    "boxes": Node(label="box"),
    "crates": Node(label="box"),
    "pallet": Node(label="pallet"),
})

PARAMS = (
    Float("width", "overall width (Y)", "m", 1.5, 3.0),
    Float("depth", "overall depth (X)", "m", 0.6, 1.2),
    Float("level_height", "spacing between levels (beam top to beam top)", "m", 0.4, 1.8),
    Int("level_count", "levels of beams", "", 3, 5),
    Float("bottom_height", "top of the lowest (fixed) level above the floor", "m", 0.08, 0.3),
    Int("bay_count", "bays side by side; auto = 1 up to 2.2 m width, else 2", "", 1, 2, auto=True),
    Float("upright_size", "upright section (X and Y)", "m", 0.06, 0.1),
    Float("beam_height", "beam height", "m", 0.06, 0.14),
    Choice("deck", "shelf deck", choices=("wire", "steel", "wood"), weights=(0.45, 0.3, 0.25)),
    Flag("has_goods", "levels may hold goods", p=0.75),
    Float("goods_chance", "chance that a level holds goods", "", 0.5, 1.0),
    Float("goods_fill", "goods height as a fraction of the clear height of a level", "", 0.35, 0.7),
    Choice("frame_finish", "upright and beam finish", choices=("enamel", "brushed_metal"), weights=(0.7, 0.3)),
)

MATERIALS = {
    "upright": "enamel:cobalt|green|black|white", "beam": "enamel:red|cobalt|black|white",
    "galvanised": "brushed_metal", "holes": "rubber:deep_black", "deck_wire": "chrome",
    "deck_steel": "brushed_metal", "deck_wood": "wood:birch|maple|oak", "feet": "brushed_metal",
    "box": "painted:off_white|pastel_yellow|light_grey", "crate": "plastic:blue|red|yellow|green|dark_grey",
    "pallet": "wood:birch|maple|oak|teak", "tape": "painted:off_white|light_grey",
}

GAP = 0.005  # level <-> uprights and stop brackets
SIDE = 0.03  # goods keep this far from the uprights
ABOVE_TOP = 0.06  # uprights reach this far above the highest raised level
HEADROOM = 0.02  # between raised goods or brackets and the level above
GOODS_LIFT = 0.001  # goods stand this far above the deck


class RackLayout(Layout):
    def storage_rack(self, node):
        p = self.p
        W, D, lh, n, u, bh = (p[k] for k in ("width", "depth", "level_height", "level_count", "upright_size",
                                              "beam_height"))
        dt = R.DECK_T[p["deck"]]
        zs = [p["bottom_height"] + i * lh for i in range(n)]  # beam tops at rest
        clear = lh - bh - dt  # from a deck top to the beams above
        goods_h = p["goods_fill"] * clear
        # raised alone, a level (and its goods) stays below the level above and its stop brackets
        travel = min(lh / 3, clear - goods_h - HEADROOM, clear - GAP - R.BRACKET_H - HEADROOM)
        slot = "upright" if p["frame_finish"] == "enamel" else "galvanised"
        bay_nodes = node.of("bay")
        ys = np.linspace(-W / 2 + u / 2, W / 2 - u / 2, len(bay_nodes) + 1)
        frame = R.upright_frame(D, u, zs[-1] + travel + ABOVE_TOP, slot)
        pieces = []
        for k, yk in enumerate(ys):
            at = Frame.at((0, yk, 0))
            sides = tuple(s for s, inner in ((1, k < len(ys) - 1), (-1, k > 0)) if inner)
            pieces += [pc.transformed(at.matrix) for pc in frame]
            for z in zs[1:]:
                pieces += [pc.transformed(at.matrix) for pc in R.stop_brackets(D, u, z - bh - GAP, sides)]
        self.add("frame", "frame", pieces)
        for b, bay in enumerate(bay_nodes):
            self.grow(bay, b=b, span=(ys[b] + u / 2 + GAP, ys[b + 1] - u / 2 - GAP), zs=zs, travel=travel,
                      goods_h=goods_h)

    def bay(self, node, b, span, zs, travel, goods_h):
        for i, (lv, z) in enumerate(zip(node.of("level"), zs)):
            self.grow(lv, name=f"level_{b}_{i}", span=span, z=z, travel=travel if i else 0.0, goods_h=goods_h)

    def level(self, node, name, span, z, travel, goods_h):
        p = self.p
        beam = "beam" if p["frame_finish"] == "enamel" else "galvanised"
        self.add(name, "shelf", R.level(span, p["depth"], z, p["beam_height"], p["deck"], beam))
        if travel:
            self.slide("frame", name, Frame.at((0, sum(span) / 2, z - p["beam_height"])), upper=travel)
        else:
            self.fix("frame", name)
        for g_ in node.of("goods"):
            self.grow(g_, level=name, span=(span[0] + SIDE, span[1] - SIDE),
                      z=z + R.DECK_T[p["deck"]] + GOODS_LIFT, h=goods_h)

    def goods(self, node, **where):
        self.grow(node.one(node.choice), **where)

    def _row(self, node, level, span, z, h):
        kind = node.kind
        depth, items = R.goods_row(kind, span, self.p["depth"], self.rng)
        label = "pallet" if kind == "pallet" else "box"
        for k, (lo, hi) in enumerate(items):
            hk = h * float(self.rng.uniform(0.75, 1.0))
            name = self.add(f"{level}_{label}_{k}", label, R.GOODS[kind](-depth / 2, depth / 2, lo, hi, z, hk))
            self.fix(level, name)

    boxes = crates = pallet = _row


CATEGORY = Category("storage_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS)
