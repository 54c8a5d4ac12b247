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

import numpy as np

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Flag, Float, Int

from .parts import rack_sizes as RS
from .parts import racks as R
from .parts.rack_sizes import STORAGE_RACK_RANGES as SZ
from .parts.rack_sizes import STORAGE_RACK_SHARES as W


def bays(p, rng) -> int:
    """bay_count, or 1 up to 2.2 m of width, else 2"""
    return p["bay_count"] or (1 if p["width"] <= RS.TWO_BAYS_OVER else 2)


def goods(p, rng) -> int:
    """1 with chance goods_chance (when has_goods), else 0"""
    return int(p["has_goods"] and rng.random() < p["goods_chance"])


def totes(p, rng) -> int:
    """totes per level of a bay, drawn per level: as many as fit at 0.28-0.45 m wide each (IKEA SAMLA 22 L is
    28 cm wide, 45 L 39 cm; Really Useful Box 35-64 L 39-44 cm), at least 2, at most 5"""
    return R.tote_count(_bay_span(p, R.SHELF_U), rng)


def bins(p, rng) -> int:
    """bins per level of a bay: as many bin_width bins as fit, at most 12 (wider bins fill a wide bay)"""
    return R.bin_count(_bay_span(p, R.SHELF_U), p["bin_width"])


def _bay_span(p, u) -> float:
    return R.bay_span(p["width"], u, bays(p, None))


def _goods_h(p) -> float:
    """goods height on a pallet-rack level: goods_fill of the clear height between a deck and the beams above"""
    return R.goods_height(p["goods_fill"], p["level_height"], p["beam_height"], p["deck"])


def upper_levels(p, rng) -> int:
    """the levels above a bay's bottom one: level_count - 1"""
    return p["level_count"] - 1


def cabinets(p, rng) -> int:
    """drawer cabinets side by side on a level, drawn per level: from as many 45 in ones as fit (at least one) to as
    many 30 in ones as fit"""
    return R.cabinet_count(_bay_span(p, p["upright_size"]), rng)


def drawers(p, rng) -> int:
    """drawers of a cabinet, drawn per cabinet: fronts 75-300 mm high (Lista / Vidmar) filling the cabinet, 1-10"""
    return R.drawer_count(_goods_h(p), rng)


GRAMMAR = Grammar("storage_rack", {
    "storage_rack": Node(label="frame", one_of=RS.STORAGE_RACK_DESIGNS,
                         choice="design"),
    "pallet_rack": Node(repeat={"bay": bays}),
    "shelving": Node(repeat={"tote_bay": bays}),
    "tote_bay": Node(repeat={"tote_level": "shelf_levels"}),
    "tote_level": Node(label="shelf", repeat={"tote": totes}),
    "tote": Node(label="box", one_of=RS.TOTE_LIDS),
    "lid": Node(label="lid"),
    "open_tote": Node(),
    "bin_rack": Node(repeat={"bin_bay": bays}),
    "bin_bay": Node(repeat={"bin_level": "bin_levels"}),
    "bin_level": Node(label="shelf", repeat={"bin": bins}),
    "bin": Node(label="bin"),
    "bay": Node(required=("floor_level",), repeat={"level": upper_levels}),
    "floor_level": Node(label="shelf", required=("drawers",)),
    "level": Node(label="shelf", repeat={"goods": goods}),
    "goods": Node(one_of=RS.GOODS_KINDS),
    "drawers": Node(repeat={"drawer_cabinet": cabinets}),
    "drawer_cabinet": Node(label="cabinet", repeat={"drawer": drawers}),
    "drawer": Node(label="drawer"),
    "boxes": Node(label="box"),
    "crates": Node(label="box"),
    "pallet": Node(label="pallet"),
})

PARAMS = (
    Float("width", "overall width (Y)", "m", *SZ["width"]),
    Float("depth", "overall depth (X)", "m", *SZ["depth"]),
    Float("level_height", "spacing between levels (beam top to beam top)", "m", *SZ["level_height"]),
    Int("level_count", "levels of beams", "", *SZ["level_count"]),
    Float("bottom_height", "top of the lowest (fixed) level above the floor", "m", *SZ["bottom_height"]),
    Int("bay_count", "bays side by side; auto = 1 up to 2.2 m width, else 2", "", *SZ["bay_count"], auto=True),
    Float("upright_size", "upright section (X and Y)", "m", *SZ["upright_size"]),
    Float("beam_height", "beam height", "m", *SZ["beam_height"]),
    Choice("deck", "shelf deck", choices=("wire", "steel", "wood"), weights=W["deck"]),
    Flag("has_goods", "levels may hold goods", p=RS.GOODS_SHARE),
    Float("goods_chance", "chance that a level holds goods", "", *SZ["goods_chance"]),
    Float("goods_fill", "goods height as a fraction of the clear height of a level", "", *SZ["goods_fill"]),
    Choice("frame_finish", "upright and beam finish", choices=("enamel", "brushed_metal"), weights=W["frame_finish"]),
    # boltless shelving: 12-24 in deep, 5 shelves over 72 in (Tennsco Z-line; IKEA BROR 0.4-0.55 m)
    Float("shelf_depth", "shelving and bin rack depth (X)", "m", *SZ["shelf_depth"]),
    Float("shelf_spacing", "shelving: spacing between levels", "m", *SZ["shelf_spacing"]),
    Int("shelf_levels", "shelving: levels", "", *SZ["shelf_levels"]),
    # bin racks: AkroBins 30220-30240 are 4-1/8 to 5-1/2 in wide, 5 in high; shelf pitch 6-8 in
    Float("bin_width", "bin rack: bin width", "m", *SZ["bin_width"]),
    Float("bin_spacing", "bin rack: spacing between levels", "m", *SZ["bin_spacing"]),
    # 72-84 in bin shelving units carry up to 8 shelves of 5 in bins (Akro-Mils AWS / Edsal bin units)
    Int("bin_levels", "bin rack: levels", "", *SZ["bin_levels"]),
    # a tote or bin slides on the deck until its middle reaches the deck's front edge, then it is lifted off (slid
    # further it would tip: nothing holds it up); it stands centred on the deck, so at most half its depth
    Float("tote_travel", "how far a tote or bin slides out, as a fraction of its depth (half: its middle at the "
          "deck's front edge)", "", *SZ["tote_travel"]),
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
        ys = R.upright_ys(p["width"], u, n_bays)
        frame = R.upright_frame(D, u, top, slot)
        pieces = []
        for k, yk in enumerate(ys):
            at = Frame.at((0, yk, 0))
            pieces += [pc.transformed(at.matrix) for pc in frame]
            if brackets:
                sides = R.bracket_sides(k, len(ys))
                for z in zs[1:]:
                    pieces += [pc.transformed(at.matrix) for pc in R.stop_brackets(D, u, z - p["beam_height"],
                                                                                   sides)]
        self.add("frame", "frame", pieces)
        return ys

    def pallet_rack(self, node, ys, zs):
        p = self.p
        u = p["upright_size"]
        goods_h = _goods_h(p)
        for b, (bay, span) in enumerate(zip(node.of("bay"), R.bay_spans(ys, u), strict=True)):
            self.grow(bay, b=b, span=span, zs=zs, goods_h=goods_h)

    def bay(self, node, b, span, zs, goods_h):
        for i, (lv, z) in enumerate(zip(node.of("floor_level") + node.of("level"), zs, strict=True)):
            self.grow(lv, name=f"level_{b}_{i}", span=span, z=z, goods_h=goods_h)

    def level(self, node, name, span, z, goods_h):
        p = self.p
        beam = "beam" if p["frame_finish"] == "enamel" else "galvanised"
        self.add(name, "shelf", R.level(span, p["depth"], z, p["beam_height"], p["deck"], beam))
        self.fix("frame", name)
        for g_ in node.of("goods") + node.of("drawers"):
            self.grow(g_, level=name, span=R.goods_span(span), z=R.on_deck(z, p["deck"]), h=goods_h)

    floor_level = level

    def goods(self, node, **where):
        self.grow(node.one(node.choice), **where)

    def _row(self, node, level, span, z, h):
        kind = node.kind
        depth, items = R.goods_row(kind, span, self.p["depth"], self.rng)
        label = "pallet" if kind == "pallet" else "box"
        for k, ys in enumerate(items):
            name = self.add(f"{level}_{label}_{k}", label, R.drawn_goods(kind, depth, ys, z, h, self.rng))
            self.fix(level, name)

    boxes = crates = pallet = _row

    def drawers(self, node, level, span, z, h):
        """Modular drawer cabinets standing on the level, side by side, fronts flush with the front beam."""
        kids = node.of("drawer_cabinet")
        slots = R.cabinet_slots(span, len(kids), self.p["depth"])
        for k, (kid, ys) in enumerate(zip(kids, slots.ys, strict=True)):
            self.grow(kid, level=level, name=f"{level}_cabinet_{k}", xs=slots.xs, ys=ys, z=z, h=h)

    def drawer_cabinet(self, node, level, name, xs, ys, z, h):
        self.add(name, "cabinet", R.drawer_housing(*xs, *ys, z, h, "cabinet"))
        self.fix(level, name)
        kids = node.of("drawer")
        dxs, dys, zss = R.drawer_slots(xs, ys, z, h, len(kids))
        for k, (kid, zs) in enumerate(zip(kids, zss, strict=True)):
            self.grow(kid, cabinet=name, name=f"{name}_drawer_{k}", xs=dxs, ys=dys, zs=zs)

    def drawer(self, node, cabinet, name, xs, ys, zs):
        self.add(name, "drawer", R.cabinet_drawer(*xs, *ys, *zs, "drawer", "pull"))
        self.slide(cabinet, name, R.slide_out(xs, ys, zs[0]), upper=R.pull_out(xs, R.DRAWER_OUT))

    # -- shelving of totes, racks of bins --------------------------------------------------------------
    def shelving(self, node, ys, zs, clear):
        u = R.SHELF_U
        self.node_levels = list(zs)
        for b, (bay, span) in enumerate(zip(node.children, R.bay_spans(ys, u), strict=True)):
            self.grow(bay, b=b, span=span, zs=zs, clear=clear)

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
        return R.on_deck(z, self.deck())

    def tote_level(self, node, name, span, z, clear):
        """A row of totes, each sliding out along +X on the deck."""
        p = self.p
        top = self._shelf(name, span, z)
        kids = node.of("tote")
        xs, rows, h = R.tote_row(span, len(kids), p["shelf_depth"], clear)
        # a lid may not rise into the space of the tote above, pulled out with it (both are gates, which the
        # core never scales): its tip stays under the level above
        lid_up = R.tote_lid_opening(R.lid_room(self.node_levels, z, h), xs[1] - xs[0])
        for k, (kid, ys) in enumerate(zip(kids, rows)):
            self.grow(kid, level=name, name=f"{name}_tote_{k}", xs=xs, ys=ys, z=top, h=h, lid_up=lid_up)

    def tote(self, node, level, name, xs, ys, z, h, lid_up=R.LID_OPEN):
        self.add(name, "box", R.tote(*xs, *ys, z, h, "tote"))
        self.slide(level, name, R.slide_out(xs, ys, z), upper=R.pull_out(xs, self.p["tote_travel"]))
        self.grow(node.one(node.choice), tote=name, xs=xs, ys=ys, z=z + h, up=lid_up)

    def lid(self, node, tote, xs, ys, z, up=R.LID_OPEN):
        name = self.add(f"{tote}_lid", "lid", R.tote_lid(*xs, *ys, z, "lid"))
        # hinged at the back edge, axis -Y: the front edge lifts; it opens once the tote is out
        self.hinge(tote, name, R.lid_hinge(xs, ys, z), upper=up, role="lid",
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
        self.slide(level, name, R.slide_out(xs, ys, z), upper=R.pull_out(xs, self.p["tote_travel"]))


CATEGORY = Category("storage_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS,
                    palette=furniture)
