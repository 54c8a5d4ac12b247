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

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import fridges as FR
from .parts import refrigerators as RF

R = RF.FULL


def crisper_count(p, rng) -> int:
    """crisper_count; a French-door fridge has one behind each door (2)"""
    return 2 if p["design"] == "french_door" else p["crisper_count"]


GRAMMAR = Grammar("refrigerator", {
    # US sales by configuration (AHAM / Consumer Reports shares): top freezer, French door and side-by-side
    # most common, bottom freezer the European norm (Bosch, Liebherr 60 cm combis)
    "refrigerator": Node(label="body", one_of={"top_freezer": 0.3, "bottom_freezer": 0.25, "french_door": 0.25,
                                               "side_by_side": 0.2}, choice="design"),
    "top_freezer": Node(required=("door", "freezer_door", "shelves", "crispers", "freezer_shelves")),
    "bottom_freezer": Node(required=("door", "shelves", "crispers", "freezer_drawer")),
    # dispensers: most side-by-sides and many French-door models (GE GSS25, Samsung RF28 / RS27 ranges)
    "french_door": Node(required=("door", "right_door", "fixed_shelves", "crispers", "freezer_drawer"),
                        optional={"dispenser": 0.5}),
    "side_by_side": Node(required=("door", "freezer_door", "shelves", "crispers", "freezer_shelves"),
                         optional={"dispenser": 0.5}),
    "door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "right_door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "freezer_door": Node(label="door", repeat={"door_bin": "bin_count"}),
    "door_bin": Node(),
    "freezer_drawer": Node(label="drawer"),
    "shelves": Node(repeat={"shelf": "shelf_count"}),
    "fixed_shelves": Node(repeat={"fixed_shelf": "shelf_count"}),
    "shelf": Node(label="shelf"), "fixed_shelf": Node(label="shelf"),
    "freezer_shelves": Node(repeat={"freezer_shelf": "freezer_shelf_count"}),
    "freezer_shelf": Node(label="rack"),
    "crispers": Node(repeat={"crisper": crisper_count}),
    "crisper": Node(label="drawer"),
    "dispenser": Node(required=("paddle",)),
    "paddle": Node(label="lever"),
})
"""Designs (``design``): ``top_freezer`` (a freezer door over the fridge door, both hinged on
``hinge_side``, a wire shelf or two in the freezer); ``bottom_freezer`` (a fridge door over a freezer
drawer); ``french_door`` (two fridge doors over a freezer drawer, fixed full-width shelves, a crisper behind
each door); ``side_by_side`` (freezer left, fridge right, full-height doors). A ``dispenser``: a water/ice
recess in the left fridge door (French door) or the freezer door (side-by-side) with a sprung paddle."""

PARAMS = (
    Float("width", "overall width (Y)", "m", *R["width"]),
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
    Int("shelf_count", "glass shelves in the fresh-food zone, over the crispers", "", 2, 4),
    Float("shelf_travel", "a slide-out shelf's travel as a fraction of its depth", "", *R["shelf_travel"]),
    Int("crisper_count", "crisper drawers side by side (a French-door fridge: one per door)", "", 1, 2),
    Int("freezer_shelf_count", "wire shelves in a freezer zone behind a door", "", 1, 3),
    Int("bin_count", "door bins on each door's liner", "", 2, 4),
    Float("drawer_travel", "a freezer drawer's travel as a fraction of its basket's depth", "", *R["drawer_travel"]),
    Choice("body_finish", "cabinet and door skin", choices=("painted", "brushed_metal"), weights=(0.45, 0.55)),
    Choice("handle_finish", "door handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.5, 0.25, 0.25)),
)

MATERIALS = {
    "body": "body_finish", "liner": "plastic:white|light_grey", "glass": "glass:clear",
    "handle": ("handle_finish", {"plastic": "plastic:black|dark_grey"}), "trim": "plastic:white|light_grey|dark_grey",
    "wire": "chrome", "grille": "plastic:black|dark_grey", "feet": "rubber", "gasket": "rubber",
    "bin": "plastic:white|light_grey", "display": "plastic:black|dark_grey", "paddle": "plastic:black|dark_grey",
}
SUBSTRATES = {"body": ("body_finish", {"painted": A.STEEL})}  # a painted cabinet is painted steel sheet


def frame_family(p: dict) -> dict:
    """The door skins are the cabinet's finish (massed as steel sheet by :func:`.fridges.solid_door`)."""
    return {**p, "frame_family": p["body_finish"]}


class RefrigeratorLayout(Layout):
    def refrigerator(self, node):
        p = self.p
        design = node.choice
        share = p["freezer_width"] if design == "side_by_side" else p["freezer_share"]
        cab = RF.cabinet(design, p["width"], p["depth"], p["height"], p["wall"], p["door_thickness"],
                         p["feet_height"], p["kick_height"], share)
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
        self.grow(node.one("freezer_drawer"), front=cab.drawer, zone=cab.freezer)

    def french_door(self, node, cab):
        dispenser = node.one("dispenser")
        self.grow(node.one("door"), door=cab.doors["door"], dispenser=dispenser)
        self.grow(node.one("right_door"), door=cab.doors["right_door"])
        fit = self._levels(cab.fridge, len(node.one("fixed_shelves").of("fixed_shelf")))
        self.grow(node.one("fixed_shelves"), zone=cab.fridge, fit=fit)
        self.grow(node.one("crispers"), zone=cab.fridge, fit=fit, doors=("door", "right_door"))
        self.grow(node.one("freezer_drawer"), front=cab.drawer, zone=cab.freezer)

    def side_by_side(self, node, cab):
        self.grow(node.one("door"), door=cab.doors["door"])
        self.grow(node.one("freezer_door"), door=cab.doors["freezer_door"], dispenser=node.one("dispenser"))
        self._fresh(node, cab.fridge, "door")
        self.grow(node.one("freezer_shelves"), zone=cab.freezer, door="freezer_door")

    def _fresh(self, node, zone, door):
        """Slide-out shelves over the crispers of the fresh-food zone behind ``door``."""
        fit = self._levels(zone, len(node.one("shelves").of("shelf")))
        self.grow(node.one("shelves"), zone=zone, fit=fit, door=door)
        self.grow(node.one("crispers"), zone=zone, fit=fit, doors=(door,))

    def _levels(self, zone, n, over_crispers=True):
        """Shelf levels with their ledge rails (:func:`.fridges.rack_levels`) over the crispers."""
        cav = FR.over_crispers(zone.cav, zone.cav[5]) if over_crispers else zone.cav
        hole = (*cav[2:5], cav[5] + FR.F["racks"]["under_glass"])
        return FR.rack_levels(n, cav, hole, zone.xs, self.p["width"], self.p["door_thickness"], zone.margin)

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
        if dispenser:
            pieces, paddle, at, push = RF.dispenser_door(door, p["frame_family"])
        else:
            pieces = FR.solid_door(door.box, p["frame_family"])
        self.add(name, "door", pieces)
        self.hinge("body", name, door.hinge, upper=RF.DOOR_OPENS)
        self.extend(name, RF.bar(*RF.handle_at(door.box, door.left, p["handle_length"])))
        kids = node.of("door_bin")
        for kid, pieces in zip(kids, RF.bins(door, len(kids)), strict=True):
            self.grow(kid, door=name, pieces=pieces)
        if dispenser:
            self.grow(dispenser, door=name, paddle=paddle, at=at, push=push)

    def door_bin(self, node, door, pieces):
        """A door bin moulded into the door's liner: static, part of the door."""
        self.extend(door, pieces)

    def dispenser(self, node, door, paddle, at, push):
        self.grow(node.one("paddle"), door=door, pieces=paddle, at=at, push=push)

    def paddle(self, node, door, pieces, at, push):
        self.add("paddle", "lever", pieces)
        self.hinge(door, "paddle", at, upper=push, role="lever")

    def freezer_drawer(self, node, front, zone):
        pieces, at, travel = RF.freezer_drawer(front, zone, self.p["frame_family"], self.p["drawer_travel"])
        self.add("freezer_drawer", "drawer", pieces + RF.bar(*RF.drawer_handle_at(front)))
        self.slide("body", "freezer_drawer", at, upper=travel)

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

    def freezer_shelves(self, node, zone, door):
        kids = node.of("freezer_shelf")
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
        pieces, at, travel = FR.crisper(xs, ys, zs)
        name = self.add(f"crisper_{k}", "drawer", pieces)
        self.slide("body", name, at, upper=travel, requires_open=door)


CATEGORY = Category("refrigerator", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RefrigeratorLayout,
                    {**MATERIALS, "frame": Same("body")}, substrates=SUBSTRATES, derive=frame_family,
                    palette=appliance)
