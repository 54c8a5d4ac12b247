"""Storage rack: a pallet rack of pinned levels, boltless shelving of lidded totes, or a bin rack.

Three designs (``design``). ``pallet_rack`` is described below. ``shelving``: boltless steel shelving
(0.35-0.6 m deep, 4-6 fixed levels 0.3-0.45 m apart: Tennsco / IKEA BROR) holding a row of 2-5 plastic storage
totes (0.28-0.45 m wide, their number drawn per level) on each level; each tote slides out along +X and a
lidded tote's lid hinges up about its back edge once the tote is out (``requires_open``). ``bin_rack``: a
small-parts bin rack (0.35-0.6 m deep, 4-8 levels 0.18-0.24 m apart) whose every level holds a row of up to 12
open-fronted louvred bins (Akro-Mils AkroBins 105-150 mm wide), each sliding out along +X: racks of bins are
the large assemblies of the category.

Pallet rack: X is depth (the front faces +X), Y is width, Z is up. Frames of two braced uprights stand at
both ends and between bays (a rack wider than 2.2 m has two bays). Each level of each bay is a
pair of beams with a deck (wire mesh, steel panel or wooden board), fixed where it is pinned: a
level above the bottom one rests on its beam connectors' brackets on the uprights (a level is
adjusted by unloading it and re-pinning it in other holes of the uprights, not by a joint). Goods
(cardboard boxes, plastic crates, pallets with stacked boxes, or modular drawer cabinets: Lista /
Stanley Vidmar pallet-rack drawer systems) are fixed on a level, inside the bay, clear of the
uprights; a level's goods kind is drawn per level, but the bottom level of every bay holds drawer cabinets
(pallet-rack drawer systems stand at the floor: Lista drawers carry 75-200 kg each). A drawer cabinet's
drawers (1-10, fronts 75-300 mm) slide out along +X on full-extension slides. Parts:
``categories/parts/racks.py``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import racks as R


def bays(p, rng) -> int:
    """bay_count, or 1 up to 2.2 m of width, else 2"""
    return p["bay_count"] or (1 if p["width"] <= 2.2 else 2)


def goods(p, rng) -> int:
    """1 with chance goods_chance (when has_goods), else 0"""
    return int(p["has_goods"] and rng.random() < p["goods_chance"])


def totes(p, rng) -> int:
    """totes per level of a bay, drawn per level: as many as fit at 0.28-0.45 m wide each (IKEA SAMLA 22 L is
    28 cm wide, 45 L 39 cm; Really Useful Box 35-64 L 39-44 cm), at least 2, at most 5"""
    span = _bay_span(p, R.SHELF_U)
    lo = max(2, int(span // R.TOTE_W[1]))
    return int(rng.integers(lo, max(lo, min(R.MAX_TOTES, int(span // R.TOTE_W[0]))) + 1))


def bins(p, rng) -> int:
    """bins per level of a bay: as many bin_width bins as fit, at most 6 (wider bins fill a wide bay)"""
    return max(2, min(R.MAX_BINS, int(_bay_span(p, R.SHELF_U) // (p["bin_width"] + R.BIN_GAP))))


def _bay_span(p, u) -> float:
    return (p["width"] - u) / bays(p, None) - u - 2 * R.GAP


def _goods_h(p) -> float:
    """goods height on a pallet-rack level: goods_fill of the clear height between a deck and the beams above"""
    return p["goods_fill"] * (p["level_height"] - p["beam_height"] - R.DECK_T[p["deck"]])


def upper_levels(p, rng) -> int:
    """the levels above a bay's bottom one: level_count - 1"""
    return p["level_count"] - 1


def cabinets(p, rng) -> int:
    """drawer cabinets side by side on a level, drawn per level: from as many 45 in ones as fit (at least one) to as
    many 30 in ones as fit"""
    width = _bay_span(p, p["upright_size"]) - 2 * R.SIDE
    lo = max(1, int(width // (R.DRAWER_CAB["widths"][-1] + R.CAB_GAP)))
    return int(rng.integers(lo, max(lo, int(width // (R.DRAWER_CAB["widths"][1] + R.CAB_GAP))) + 1))


def drawers(p, rng) -> int:
    """drawers of a cabinet, drawn per cabinet: fronts 75-300 mm high (Lista / Vidmar) filling the cabinet, 1-10"""
    inner = _goods_h(p) - 2 * R.CAB_PANEL
    tallest, lowest, most = R.DRAWER_FRONTS
    lo = max(1, math.ceil(inner / tallest))
    return int(rng.integers(lo, max(lo, min(most, int(inner // lowest))) + 1))


GRAMMAR = Grammar("storage_rack", {
    "storage_rack": Node(label="frame", one_of={"pallet_rack": 0.35, "shelving": 0.3, "bin_rack": 0.35},
                         choice="design"),
    "pallet_rack": Node(repeat={"bay": bays}),
    "shelving": Node(repeat={"tote_bay": bays}),
    "tote_bay": Node(repeat={"tote_level": "shelf_levels"}),
    "tote_level": Node(label="shelf", repeat={"tote": totes}),
    "tote": Node(label="box", one_of={"lid": 0.7, "open_tote": 0.3}),
    "lid": Node(label="lid"),
    "open_tote": Node(),
    "bin_rack": Node(repeat={"bin_bay": bays}),
    "bin_bay": Node(repeat={"bin_level": "bin_levels"}),
    "bin_level": Node(label="shelf", repeat={"bin": bins}),
    "bin": Node(label="bin"),
    "bay": Node(required=("floor_level",), repeat={"level": upper_levels}),
    "floor_level": Node(label="shelf", required=("drawers",)),
    "level": Node(label="shelf", repeat={"goods": goods}),
    "goods": Node(one_of={"boxes": 0.3, "pallet": 0.25, "crates": 0.2, "drawers": 0.25}),
    "drawers": Node(repeat={"drawer_cabinet": cabinets}),
    "drawer_cabinet": Node(label="cabinet", repeat={"drawer": drawers}),
    "drawer": Node(label="drawer"),
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
    # boltless shelving: 12-24 in deep, 5 shelves over 72 in (Tennsco Z-line; IKEA BROR 0.4-0.55 m)
    Float("shelf_depth", "shelving and bin rack depth (X)", "m", 0.35, 0.6),
    Float("shelf_spacing", "shelving: spacing between levels", "m", 0.3, 0.45),
    Int("shelf_levels", "shelving: levels", "", 4, 6),
    # bin racks: AkroBins 30220-30240 are 4-1/8 to 5-1/2 in wide, 5 in high; shelf pitch 6-8 in
    Float("bin_width", "bin rack: bin width", "m", 0.105, 0.15),
    Float("bin_spacing", "bin rack: spacing between levels", "m", 0.18, 0.24),
    # 72-84 in bin shelving units carry up to 8 shelves of 5 in bins (Akro-Mils AWS / Edsal bin units)
    Int("bin_levels", "bin rack: levels", "", 4, 8),
    # a tote or bin slides on the deck until its middle reaches the deck's front edge, then it is lifted off (slid
    # further it would tip: nothing holds it up); it stands centred on the deck, so at most half its depth
    Float("tote_travel", "how far a tote or bin slides out, as a fraction of its depth (half: its middle at the "
          "deck's front edge)", "", 0.3, 0.5),
)

MATERIALS = {
    "upright": "enamel:cobalt|green|black|white", "beam": "enamel:red|cobalt|black|white",
    "galvanised": "brushed_metal", "holes": "rubber:deep_black", "deck_wire": "chrome",
    "deck_steel": "brushed_metal", "deck_wood": "wood:birch|maple|oak", "feet": "brushed_metal",
    "box": "painted:off_white|pastel_yellow|light_grey", "crate": "plastic:blue|red|yellow|green|dark_grey",
    "pallet": "wood:birch|maple|oak|teak", "tape": "painted:off_white|light_grey",
    "tote": "plastic:clear|white|light_grey|dark_grey|blue", "lid": "plastic:blue|red|yellow|green|dark_grey|white",
    "bin": "plastic:blue|red|yellow|green", "label": "painted:off_white",
    "cabinet": "enamel:graphite|cobalt|white|green", "drawer": "enamel:graphite|cobalt|white|red|green",
    "pull": "brushed_metal",
}


class RackLayout(Layout):
    def storage_rack(self, node):
        """The frame of the design (its uprights and, on a pallet rack, stop brackets), then the design."""
        p = self.p
        design = node.one(node.choice)
        n_bays = len(design.children)
        if design.kind == "pallet_rack":
            zs = self._pallet_levels()
            ys = self._frame(n_bays, p["depth"], p["upright_size"], zs[-1] + R.ABOVE_TOP, zs, brackets=True)
            self.grow(design, ys=ys, zs=zs)
            return
        spacing, count = ((p["shelf_spacing"], p["shelf_levels"]) if design.kind == "shelving"
                          else (p["bin_spacing"], p["bin_levels"]))
        zs = [p["bottom_height"] + i * spacing for i in range(count)]
        ys = self._frame(n_bays, p["shelf_depth"], R.SHELF_U, zs[-1] + R.ABOVE_TOP, zs, brackets=False)
        self.grow(design, ys=ys, zs=zs, clear=spacing - R.SHELF_BEAM - R.DECK_T[self.deck()])

    def _pallet_levels(self):
        """The levels' beam tops."""
        p = self.p
        return [p["bottom_height"] + i * p["level_height"] for i in range(p["level_count"])]

    def _frame(self, n_bays: int, D: float, u: float, top: float, zs: list, brackets: bool) -> np.ndarray:
        """Upright frames at both ends and between bays (brackets under the beams of the levels above the
        bottom one)."""
        p = self.p
        slot = "upright" if p["frame_finish"] == "enamel" else "galvanised"
        ys = np.linspace(-p["width"] / 2 + u / 2, p["width"] / 2 - u / 2, n_bays + 1)
        frame = R.upright_frame(D, u, top, slot)
        pieces = []
        for k, yk in enumerate(ys):
            at = Frame.at((0, yk, 0))
            pieces += [pc.transformed(at.matrix) for pc in frame]
            if brackets:
                sides = tuple(s for s, inner in ((1, k < len(ys) - 1), (-1, k > 0)) if inner)
                for z in zs[1:]:
                    pieces += [pc.transformed(at.matrix) for pc in R.stop_brackets(D, u, z - p["beam_height"],
                                                                                   sides)]
        self.add("frame", "frame", pieces)
        return ys

    def pallet_rack(self, node, ys, zs):
        p = self.p
        u = p["upright_size"]
        goods_h = _goods_h(p)
        for b, bay in enumerate(node.of("bay")):
            self.grow(bay, b=b, span=(ys[b] + u / 2 + R.GAP, ys[b + 1] - u / 2 - R.GAP), zs=zs, goods_h=goods_h)

    def bay(self, node, b, span, zs, goods_h):
        for i, (lv, z) in enumerate(zip(node.of("floor_level") + node.of("level"), zs, strict=True)):
            self.grow(lv, name=f"level_{b}_{i}", span=span, z=z, goods_h=goods_h)

    def level(self, node, name, span, z, goods_h):
        p = self.p
        beam = "beam" if p["frame_finish"] == "enamel" else "galvanised"
        self.add(name, "shelf", R.level(span, p["depth"], z, p["beam_height"], p["deck"], beam))
        self.fix("frame", name)
        for g_ in node.of("goods") + node.of("drawers"):
            self.grow(g_, level=name, span=(span[0] + R.SIDE, span[1] - R.SIDE),
                      z=z + R.DECK_T[p["deck"]] + R.GOODS_LIFT, h=goods_h)

    floor_level = level

    def goods(self, node, **where):
        self.grow(node.one(node.choice), **where)

    def _row(self, node, level, span, z, h):
        kind = node.kind
        depth, items = R.goods_row(kind, span, self.p["depth"], self.rng)
        label = "pallet" if kind == "pallet" else "box"
        for k, (lo, hi) in enumerate(items):
            hk = h * float(self.rng.uniform(R.GOODS_FILL_MIN, 1.0))
            name = self.add(f"{level}_{label}_{k}", label, R.GOODS[kind](-depth / 2, depth / 2, lo, hi, z, hk))
            self.fix(level, name)

    boxes = crates = pallet = _row

    def drawers(self, node, level, span, z, h):
        """Modular drawer cabinets standing on the level, side by side, fronts flush with the front beam."""
        kids = node.of("drawer_cabinet")
        width = span[1] - span[0]
        pitch = width / len(kids)
        w = next((cw for cw in reversed(R.DRAWER_CAB["widths"]) if cw + R.CAB_GAP <= pitch), pitch - R.CAB_GAP)
        x1 = self.p["depth"] / 2 - R.CAB_BACK[0]
        xs = (x1 - min(R.DRAWER_CAB["depth"], self.p["depth"] - R.CAB_BACK[1]), x1)
        for k, kid in enumerate(kids):
            yc = span[0] + (k + 0.5) * pitch
            self.grow(kid, level=level, name=f"{level}_cabinet_{k}", xs=xs, ys=(yc - w / 2, yc + w / 2), z=z, h=h)

    def drawer_cabinet(self, node, level, name, xs, ys, z, h):
        self.add(name, "cabinet", R.drawer_housing(*xs, *ys, z, h, "cabinet"))
        self.fix(level, name)
        kids = node.of("drawer")
        x0, x1 = xs[0] + R.CAB_PANEL + R.CAB_DRAWER[0], xs[1] - R.CAB_DRAWER[1]
        y0, y1 = ys[0] + R.CAB_PANEL + R.DRAWER_GAP, ys[1] - R.CAB_PANEL - R.DRAWER_GAP
        z0, z1 = z + R.CAB_PANEL + R.DRAWER_GAP, z + h - R.CAB_PANEL - R.DRAWER_GAP
        pitch = (z1 - z0) / len(kids)
        for k, kid in enumerate(kids):
            za = z0 + k * pitch
            self.grow(kid, cabinet=name, name=f"{name}_drawer_{k}", xs=(x0, x1), ys=(y0, y1),
                      zs=(za, za + pitch - R.DRAWER_GAP))

    def drawer(self, node, cabinet, name, xs, ys, zs):
        self.add(name, "drawer", R.cabinet_drawer(*xs, *ys, *zs, "drawer", "pull"))
        self.slide(cabinet, name, Frame.at((xs[1], sum(ys) / 2, zs[0]), z=(1, 0, 0)),
                   upper=R.DRAWER_OUT * (xs[1] - xs[0]))

    # -- shelving of totes, racks of bins --------------------------------------------------------------
    def shelving(self, node, ys, zs, clear):
        u = R.SHELF_U
        self.node_levels = list(zs)
        for b, bay in enumerate(node.children):
            self.grow(bay, b=b, span=(ys[b] + u / 2 + R.GAP, ys[b + 1] - u / 2 - R.GAP), zs=zs, clear=clear)

    bin_rack = shelving

    def tote_bay(self, node, b, span, zs, clear):
        for i, lv in enumerate(node.children):
            self.grow(lv, name=f"level_{b}_{i}", span=span, z=zs[i], clear=clear)

    bin_bay = tote_bay

    def deck(self) -> str:
        return "steel" if self.p["design"] == "bin_rack" else self.p["deck"]


    def _shelf(self, name, span, z):
        p = self.p
        beam = "beam" if p["frame_finish"] == "enamel" else "galvanised"
        self.add(name, "shelf", R.level(span, p["shelf_depth"], z, R.SHELF_BEAM, self.deck(), beam))
        self.fix("frame", name)
        return z + R.DECK_T[self.deck()] + R.GOODS_LIFT

    def tote_level(self, node, name, span, z, clear):
        """A row of totes, each sliding out along +X on the deck."""
        p = self.p
        top = self._shelf(name, span, z)
        kids = node.of("tote")
        xs, rows, h = R.tote_row(span, len(kids), p["shelf_depth"], clear)
        # a lid may not rise into the space of the tote above, pulled out with it (both are gates, which the
        # core never scales): its tip stays under the level above
        above = [lv for lv in self.node_levels if lv > z + 1e-9]
        lid_up = R.tote_lid_opening(min(above) - z - h if above else None, xs[1] - xs[0])
        for k, (kid, ys) in enumerate(zip(kids, rows)):
            self.grow(kid, level=name, name=f"{name}_tote_{k}", xs=xs, ys=ys, z=top, h=h, lid_up=lid_up)

    def tote(self, node, level, name, xs, ys, z, h, lid_up=R.LID_OPEN):
        self.add(name, "box", R.tote(*xs, *ys, z, h, "tote"))
        self.slide(level, name, Frame.at((xs[1], sum(ys) / 2, z), z=(1, 0, 0)),
                   upper=self.p["tote_travel"] * (xs[1] - xs[0]))
        self.grow(node.one(node.choice), tote=name, xs=xs, ys=ys, z=z + h, up=lid_up)

    def lid(self, node, tote, xs, ys, z, up=R.LID_OPEN):
        name = self.add(f"{tote}_lid", "lid", R.tote_lid(*xs, *ys, z, "lid"))
        # hinged at the back edge, axis -Y: the front edge lifts; it opens once the tote is out
        self.hinge(tote, name, Frame.at((xs[0], sum(ys) / 2, z), z=(0, -1, 0)), upper=up, role="lid",
                   requires_open=tote)

    def open_tote(self, node, tote, xs, ys, z, up=None):
        """An open tote: no lid; a label card clipped on its front wall instead."""
        self.extend(tote, [R.tote_label(xs[1], sum(ys) / 2, z)])

    def bin_level(self, node, name, span, z, clear):
        p = self.p
        top = self._shelf(name, span, z)
        kids = node.of("bin")
        xs, rows, h = R.bin_row(span, len(kids), p["shelf_depth"], clear)
        for k, (kid, ys) in enumerate(zip(kids, rows)):
            self.grow(kid, level=name, name=f"{name}_bin_{k}", xs=xs, ys=ys, z=top, h=h)

    def bin(self, node, level, name, xs, ys, z, h):
        self.add(name, "bin", R.louvred_bin(*xs, *ys, z, h, "bin", "label"))
        self.slide(level, name, Frame.at((xs[1], sum(ys) / 2, z), z=(1, 0, 0)),
                   upper=self.p["tote_travel"] * (xs[1] - xs[0]))


CATEGORY = Category("storage_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS,
                    palette=furniture)
