"""Refrigerator: a full-size fridge-freezer with hinged doors, a freezer drawer, shelves and crispers.

X is depth (the doors face +X), Y is width, Z is up. One insulated cabinet on levelling feet with a toe
grille is split by an insulated mullion into a fresh-food zone and a freezer zone: a top freezer, a bottom
freezer drawer, French doors over a freezer drawer, or side-by-side freezer and fridge. Every door is an
insulated door hinged on its outer side about a vertical axis through its front face, opening to 120
degrees, with a tubular bar handle on its free edge and door bins moulded into its liner (static). Behind
a door, glass shelves slide out on ledge rails and crisper drawers pull out, each only with its door open
(``requires_open``); a French-door fridge's shelves are fixed (they span both doors) and its two crispers
open with their own doors. A freezer drawer pulls out along +X carrying its basket. A French-door or
side-by-side model may have a water/ice dispenser recessed in a door, its paddle pushed in by a glass and
sprung back (role ``lever``).
Parts: ``categories/parts/refrigerators.py`` (layout), ``fridges.py`` and ``appliance.py`` (pieces).
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import controls
from .parts import fridges as FR
from .parts import refrigerators as RF

R = RF.FULL
C = RF.COUNTS


def crisper_count(p, rng) -> int:
    """crisper_count; a French-door fridge has one behind each door (2)"""
    return 2 if p["design"] == "french_door" else p["crisper_count"]


GRAMMAR = Grammar("refrigerator", {
    # US sales by configuration (AHAM / Consumer Reports shares): top freezer, French door and side-by-side
    # most common, bottom freezer the European norm (Bosch, Liebherr 60 cm combis)
    "refrigerator": Node(label="body", one_of={"top_freezer": 0.3, "bottom_freezer": 0.25, "french_door": 0.25,
                                               "side_by_side": 0.2}, choice="design"),
    # a deli drawer over the crispers on about half of the models with one fridge door (Whirlpool WRT318FZDW,
    # LG LRFVS3006S have one; Bosch KGN36 has none)
    "top_freezer": Node(required=("door", "freezer_door", "shelves", "crispers", "freezer_shelves"),
                        optional={"deli_drawer": 0.5}),
    "bottom_freezer": Node(required=("door", "shelves", "crispers", "freezer_drawers"), optional={"deli_drawer": 0.5}),
    # dispensers: most side-by-sides and many French-door models (GE GSS25, Samsung RF28 / RS27 ranges)
    "french_door": Node(required=("door", "right_door", "fixed_shelves", "crispers", "freezer_drawers"),
                        optional={"dispenser": 0.5}),
    "side_by_side": Node(required=("door", "freezer_door", "shelves", "crispers", "freezer_shelves"),
                         optional={"dispenser": 0.5, "deli_drawer": 0.5}, repeat={"freezer_basket": "basket_count"}),
    "freezer_basket": Node(label="basket"),
    "door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "right_door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "freezer_door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "door_bin": Node(),
    "freezer_drawers": Node(repeat={"freezer_drawer": "freezer_drawer_count"}),
    "freezer_drawer": Node(label="drawer"),
    "deli_drawer": Node(label="drawer"),
    "shelves": Node(repeat={"shelf": "shelf_count"}),
    "fixed_shelves": Node(repeat={"fixed_shelf": "shelf_count"}),
    "shelf": Node(label="shelf"), "fixed_shelf": Node(label="shelf"),
    "freezer_shelves": Node(repeat={"freezer_shelf": "freezer_shelf_count"}),
    "freezer_shelf": Node(label="rack"),
    "crispers": Node(repeat={"crisper": crisper_count}),
    "crisper": Node(label="drawer"),
    "dispenser": Node(required=("paddle",), repeat={"key": "key_count"}),
    "key": Node(label="button"),
    "paddle": Node(label="lever"),
})
"""Designs (``design``): ``top_freezer`` (a freezer door over the fridge door, both hinged on
``hinge_side``, a wire shelf or two in the freezer); ``bottom_freezer`` (a fridge door over a freezer
drawer); ``french_door`` (two fridge doors over a freezer drawer, fixed full-width shelves, a crisper behind
each door); ``side_by_side`` (freezer left, fridge right, full-height doors). A ``dispenser``: a water/ice
recess in the left fridge door (French door) or the freezer door (side-by-side) with a sprung paddle."""

PARAMS = (
    Float("width", "overall width (Y); a side-by-side maps it onto 0.83-0.91 m", "m", *R["width"]),
    Float("depth", "overall depth incl. the doors, excl. the handles (X)", "m", *R["depth"]),
    Float("height", "overall height incl. the feet (Z)", "m", *R["height"]),
    Float("wall", "insulated wall thickness", "m", *R["wall"]),
    Float("door_thickness", "insulated door thickness", "m", *R["door_thickness"]),
    Float("kick_height", "height of the toe grille under the doors", "m", *R["kick_height"]),
    Float("feet_height", "levelling feet height", "m", *R["feet_height"]),
    Float("freezer_share", "freezer's share of the cavity height (top / bottom freezer, French door)", "",
          *R["freezer_share"]),
    Float("freezer_width", "freezer's share of the width (side-by-side)", "", *R["freezer_width"]),
    Choice("hinge_side", "hinge side of a single fridge door (and a top freezer's door), seen from the front",
           choices=("left", "right")),
    Float("handle_length", "door handle length as a fraction of its door's height", "", *R["handle_length"]),
    Int("shelf_count", "glass shelves in the fresh-food zone, over the crispers", "", *C["shelf_count"]),
    Float("shelf_travel", "a slide-out shelf's travel as a fraction of its depth", "", *R["shelf_travel"]),
    Int("crisper_count", "crisper drawers side by side (a French-door fridge: one per door)", "", *C["crisper_count"]),
    Int("freezer_shelf_count", "wire shelves in a freezer zone behind a door", "", *C["freezer_shelf_count"]),
    # one pull-out freezer drawer (Whirlpool WRB322, Samsung RF28R7351SR) or two stacked (LG LMXS28596S
    # four-door, GE Profile PFE28 lower drawers)
    Int("freezer_drawer_count", "stacked freezer drawers (bottom freezer, French door)", "",
        *C["freezer_drawer_count"]),
    Int("bin_count", "door bins on each door's liner", "", *C["bin_count"]),
    # selector keys over a dispenser: ice / water (GE GSS25), + light and lock (Samsung RF28R7351SR)
    Int("key_count", "selector keys over the dispenser (has_dispenser)", "", *C["key_count"]),
    # GE GSS25GSHSS: 2 freezer baskets under the shelves; Samsung RS27T5200: 1; some none (Frigidaire FFSS2615)
    Int("basket_count", "slide-out baskets at the bottom of a side-by-side's freezer", "", *C["basket_count"]),
    Float("drawer_travel", "a freezer drawer's travel as a fraction of its basket's depth", "", *R["drawer_travel"]),
    Choice("body_finish", "cabinet and door skin", choices=("painted", "brushed_metal"), weights=(0.45, 0.55)),
    # full-size fridge handles are stainless tube (Samsung RF28, GE GSS25, LG LRFVS stainless models) or a
    # moulded plastic bar on painted ones (Whirlpool WRT318FZDW white); bright chrome is a wine-cooler finish
    Choice("handle_finish", "door handle material", choices=("brushed_metal", "plastic"), weights=(0.7, 0.3)),
)

MATERIALS = {
    "body": "body_finish", "liner": "plastic:white|light_grey", "glass": "glass:clear", "frost": "glass:smoked",
    "handle": ("handle_finish", {"plastic": "plastic:black|dark_grey"}), "trim": "plastic:white|light_grey|dark_grey",
    "wire": "chrome", "grille": "plastic:black|dark_grey", "feet": "rubber", "gasket": "rubber",
    "bin": "plastic:white|light_grey", "display": "plastic:black|dark_grey", "paddle": "plastic:black|dark_grey",
    "button": "plastic:black|dark_grey|light_grey",
}
SUBSTRATES = {"body": ("body_finish", {"painted": A.STEEL})}  # a painted cabinet is painted steel sheet


def frame_family(p: dict) -> dict:
    """The door skins are the cabinet's finish, in its slot (:func:`.parts.refrigerators.skinned`)."""
    return {**p, "frame_family": p["body_finish"]}


class RefrigeratorLayout(controls.ControlFace):
    def refrigerator(self, node):
        p = self.p
        design = node.choice
        share = p["freezer_width"] if design == "side_by_side" else p["freezer_share"]
        cab = RF.cabinet(design, *A.size(p, design, RF.SIZES), p["wall"], p["door_thickness"], p["feet_height"],
                         p["kick_height"], share)
        self.width = cab.width
        self.add("body", "body", cab.pieces)
        self.grow(node.one(design), cab=cab)

    def top_freezer(self, node, cab):
        left = self.p["hinge_side"] == "left"
        self.grow(node.one("door"), door=RF.handed(cab.doors["door"], left))
        self.grow(node.one("freezer_door"), door=RF.handed(cab.doors["freezer_door"], left))
        self._fresh(node, cab.fridge, "door")
        self.grow(node.one("freezer_shelves"), zone=cab.freezer, door="freezer_door")

    def bottom_freezer(self, node, cab):
        self.grow(node.one("door"), door=RF.handed(cab.doors["door"], self.p["hinge_side"] == "left"))
        self._fresh(node, cab.fridge, "door")
        self.grow(node.one("freezer_drawers"), front=cab.drawer, zone=cab.freezer)

    def french_door(self, node, cab):
        dispenser = node.one("dispenser")
        self.grow(node.one("door"), door=cab.doors["door"], dispenser=dispenser)
        self.grow(node.one("right_door"), door=cab.doors["right_door"])
        fit = self._levels(cab.fridge, len(node.one("fixed_shelves").of("fixed_shelf")))
        self.grow(node.one("fixed_shelves"), zone=cab.fridge, fit=fit)
        self.grow(node.one("crispers"), zone=cab.fridge, fit=fit, doors=("door", "right_door"))
        self.grow(node.one("freezer_drawers"), front=cab.drawer, zone=cab.freezer)

    def side_by_side(self, node, cab):
        self.grow(node.one("door"), door=cab.doors["door"])
        self.grow(node.one("freezer_door"), door=cab.doors["freezer_door"], dispenser=node.one("dispenser"))
        self._fresh(node, cab.fridge, "door")
        baskets = node.of("freezer_basket")
        self.grow(node.one("freezer_shelves"), zone=cab.freezer, door="freezer_door", baskets=len(baskets))
        for k, kid in enumerate(baskets):
            self.grow(kid, k=k, zone=cab.freezer)

    def freezer_basket(self, node, k, zone):
        """A slide-out freezer basket (moulded bin with a front), only with the freezer door open."""
        fit = self._levels(zone, 1, over_crispers=False)
        pieces, at, travel = _drawer(FR.crisper(zone.xs, (fit["yc"] - fit["ry"], fit["yc"] + fit["ry"]),
                                                RF.basket_zs(zone.cav, k)))
        name = self.add(f"freezer_basket_{k}", "basket",
                        [pc.replace(material="bin") if pc.material == "glass" else pc for pc in pieces])
        self.slide("body", name, at, upper=travel, requires_open="freezer_door")

    def _fresh(self, node, zone, door):
        """Slide-out shelves over the crispers (and a deli drawer) of the fresh-food zone behind ``door``."""
        deli = node.one("deli_drawer")
        fit = self._levels(zone, len(node.one("shelves").of("shelf")), deli=bool(deli))
        self.grow(node.one("shelves"), zone=zone, fit=fit, door=door)
        self.grow(node.one("crispers"), zone=zone, fit=fit, doors=(door,))
        if deli:
            self.grow(deli, zone=zone, fit=fit, door=door)

    def _levels(self, zone, n, over_crispers=True, deli=False):
        """Shelf levels with their ledge rails (:func:`.fridges.rack_levels`) over the crispers (and the deli
        drawer)."""
        cav = FR.over_crispers(zone.cav, zone.cav[5]) if over_crispers else zone.cav
        if deli:
            cav = (*cav[:4], RF.deli_zs(zone.cav)[1] + FR.F["crisper"]["over"], cav[5])
        hole = (*cav[2:5], cav[5] + FR.F["racks"]["under_glass"])
        return FR.rack_levels(n, cav, hole, zone.xs, self.width, self.p["door_thickness"], zone.margin)

    # -- doors ----------------------------------------------------------------------------------------------
    def door(self, node, door, dispenser=None):
        self._door(node, door, "door", dispenser)

    def right_door(self, node, door):
        self._door(node, door, "right_door", None)

    def freezer_door(self, node, door, dispenser=None):
        self._door(node, door, "freezer_door", dispenser)

    def _door(self, node, door, name, dispenser):
        """An insulated door hinged on its outer side, its bar handle on the free edge, its bins."""
        p = self.p
        made = RF.dispenser_door(door, p["frame_family"], len(dispenser.of("key"))) if dispenser else None
        pieces = made.pieces if made else RF.skinned(FR.solid_door(door.box, p["frame_family"]))
        self.add(name, "door", pieces)
        self.hinge("body", name, door.hinge, upper=RF.DOOR_OPENS)
        self.extend(name, RF.bar(*RF.handle_at(door.box, door.left, p["handle_length"])))
        kids = node.of("door_bin")
        for kid, pieces in zip(kids, RF.bins(door, len(kids)), strict=True):
            self.grow(kid, door=name, pieces=pieces)
        if dispenser:
            self.grow(dispenser, door=name, made=made)

    def door_bin(self, node, door, pieces):
        """A door bin moulded into the door's liner: static, part of the door."""
        self.extend(door, pieces)

    def dispenser(self, node, door, made):
        self.grow(node.one("paddle"), door=door, pieces=made.paddle, at=made.hinge, push=made.push)
        for k, (kid, at) in enumerate(zip(node.of("key"), made.keys, strict=True)):
            self.grow(kid, k=k, door=door, at=at)

    def key(self, node, k, door, at):
        self.place_button(door, f"key_{k}", RF.KEY, at)

    def paddle(self, node, door, pieces, at, push):
        self.add("paddle", "lever", pieces)
        self.hinge(door, "paddle", at, upper=push, role="lever")

    def freezer_drawers(self, node, front, zone):
        kids = node.of("freezer_drawer")
        for k, (kid, (box, part)) in enumerate(zip(kids, RF.stacked(front, zone, len(kids)), strict=True)):
            self.grow(kid, k=k, front=box, zone=part)

    def freezer_drawer(self, node, k, front, zone):
        """A freezer drawer: an insulated front with a bar handle carrying its basket, pulled out along +X."""
        pieces, at, travel = RF.freezer_drawer(front, zone, self.p["frame_family"], self.p["drawer_travel"])
        name = self.add(f"freezer_drawer_{k}", "drawer", pieces + RF.bar(*RF.drawer_handle_at(front)))
        self.slide("body", name, at, upper=travel)

    def deli_drawer(self, node, zone, fit, door):
        """A shallow deli drawer across the zone over the crispers, pulled out only with its door open."""
        pieces, at, travel = _drawer(FR.crisper(zone.xs, (fit["yc"] - fit["ry"], fit["yc"] + fit["ry"]),
                                                RF.deli_zs(zone.cav)))
        self.add("deli_drawer", "drawer", pieces)
        self.slide("body", "deli_drawer", at, upper=travel, requires_open=door)

    # -- shelves and drawers -----------------------------------------------------------------------------
    def shelves(self, node, zone, fit, door):
        for k, (kid, (rails, zb)) in enumerate(zip(node.of("shelf"), fit["levels"], strict=True)):
            self.extend("body", rails)
            self.grow(kid, k=k, xs=zone.xs, zb=zb, fit=fit, door=door)

    def shelf(self, node, k, xs, zb, fit, door):
        """A glass shelf sliding out on its ledge rails, only with its door open."""
        name = self.add(f"shelf_{k}", "shelf", self._glass(xs, zb, fit))
        at, travel = A.rack_slide(xs, zb, self.p["shelf_travel"], fit["yc"])
        self.slide("body", name, at, upper=travel, requires_open=door)

    def fixed_shelves(self, node, zone, fit):
        for k, (kid, (rails, zb)) in enumerate(zip(node.of("fixed_shelf"), fit["levels"], strict=True)):
            self.extend("body", rails)
            self.grow(kid, k=k, xs=zone.xs, zb=zb, fit=fit)

    def fixed_shelf(self, node, k, xs, zb, fit):
        name = self.add(f"shelf_{k}", "shelf", self._glass(xs, zb, fit))
        self.fix("body", name)

    def _glass(self, xs, zb, fit):
        return [pc.translated((0.0, fit["yc"], 0.0)) for pc in A.glass_shelf(xs, fit["ry"], zb, fit["hr"])]

    def freezer_shelves(self, node, zone, door, baskets=0):
        kids = node.of("freezer_shelf")
        zone = RF.Zone(RF.over_baskets(zone.cav, baskets), zone.xs, zone.margin)
        fit = self._levels(zone, len(kids), over_crispers=False)
        for k, (kid, (rails, zb)) in enumerate(zip(kids, fit["levels"], strict=True)):
            self.extend("body", rails)
            self.grow(kid, k=k, xs=zone.xs, zb=zb, fit=fit, door=door)

    def freezer_shelf(self, node, k, xs, zb, fit, door):
        """A wire shelf sliding out of the freezer zone, only with its door open."""
        pieces = A.wire_rack(xs, fit["ry"], zb, fit["hr"], float(self.rng.uniform(*FR.WIRE_PITCH)))
        name = self.add(f"freezer_shelf_{k}", "rack", [pc.translated((0.0, fit["yc"], 0.0)) for pc in pieces])
        at, travel = A.rack_slide(xs, zb, self.p["shelf_travel"], fit["yc"])
        self.slide("body", name, at, upper=travel, requires_open=door)

    def crispers(self, node, zone, fit, doors):
        kids = node.of("crisper")
        ys = RF.split_crispers(fit["yc"], fit["ry"]) if len(doors) == 2 else \
            RF.crisper_ys(len(kids), fit["yc"], fit["ry"])
        for k, (kid, y) in enumerate(zip(kids, ys, strict=True)):
            self.grow(kid, k=k, xs=zone.xs, ys=y, zs=FR.crisper_zs(zone.cav), door=doors[k % len(doors)])

    def crisper(self, node, k, xs, ys, zs, door):
        """A crisper drawer: a clear bin with a front, pulled out along +X only with its door open."""
        pieces, at, travel = _drawer(FR.crisper(xs, ys, zs))
        name = self.add(f"crisper_{k}", "drawer", pieces)
        self.slide("body", name, at, upper=travel, requires_open=door)


def _drawer(drawer):
    """A crisper-shaped drawer (:class:`.appliance.Drawer`) as its placed pieces, the frame it slides on and its
    travel: a freezer basket and a deli drawer reuse the crisper's shape under another label or material."""
    placed = drawer.part.attached("front", to=drawer.at)
    return list(placed.pieces), placed.anchor("slide"), drawer.travel


CATEGORY = Category("refrigerator", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RefrigeratorLayout,
                    MATERIALS, substrates=SUBSTRATES, derive=frame_family,
                    palette=appliance)
