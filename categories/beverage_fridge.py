"""Beverage fridge: an insulated cabinet with a framed glass door and slide-out racks.

X is depth (the door faces +X), Y is width, Z is up. The cabinet stands on four levelling feet;
at the bottom of the front is a ventilation kick grille, above it the glass door, and optionally a
control strip above the door. The walls are insulated panels (massed as sheet steel) lined with a
thin plastic liner, so the cooled cavity is a real hollow. The door is a frame around a double
glass pane, hinged on one side about a vertical axis through its front face: it swings outward
0..pi/2; the handle (a bar or an edge pull) is on the free edge. Inside are 3-5 racks (wire racks
or glass shelves) sliding out along +X on ledge rails, or a fixed divider plate. The door is solid
to a robot, so a rack slides out only with the door open (``requires_open``); racks keep clear of
the open door's hinge-side edge.
Parts: ``categories/parts/fridges.py`` (layout), ``appliance.py`` (pieces), ``hardware``; sizes in
``appliance_sizes.py``.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import fridges as FR
from .parts import hardware
from .parts.appliance_sizes import FRIDGE_RANGES as R


def rack_count(p, rng) -> int:
    """rack_count; a wine cooler has 3 more (6-8 slide-out shelves), an undercounter fridge 2 fewer above its
    crispers, a dual-zone cooler 1 fewer per zone"""
    n = FR.rack_count(p["design"], p["rack_count"])
    if p["design"] == "undercounter":  # shelves at least 8 cm apart above the crispers, below a freezer
        n = min(n, FR.shelves_fit(shelf_room(p)))
    return n


def cavity_height(p: dict) -> float:
    """Height of the cooled cavity (floor liner to ceiling liner)."""
    _, _, H = A.size(p, p["design"], FR.SIZES)
    return FR.cavity_height(H, p["wall"], p["feet_height"], p["kick_height"])


def freezer_height(p: dict) -> float:
    """freezer_height, at most a fifth of the cavity"""
    return FR.freezer_height(p["freezer_height"], cavity_height(p))


def shelf_room(p: dict) -> float:
    """Height an undercounter fridge's shelves share: above the crispers, below the freezer compartment."""
    return FR.shelf_room(cavity_height(p), freezer_height(p) if p.get("has_freezer") else None)


def right_rack_count(p, rng) -> int:
    """right_rack_count, 1 fewer (a dual-zone cooler's right zone, set apart from the left one: wine in one
    zone, cans in the other, e.g. Whynter BWB-3388FDS, Kalamera KRC-150BV)"""
    return FR.zone_racks(p["right_rack_count"])


GRAMMAR = Grammar("beverage_fridge", {
    # most beverage centres and wine coolers sold have an electronic control strip (Newair, Whynter, Danby,
    # Kalamera ranges); the rest a dial thermostat inside
    "beverage_fridge": Node(label="body", optional={"control_panel": 0.8},
                            one_of={"glass_cooler": 0.3, "undercounter": 0.25, "wine": 0.25, "dual_zone": 0.2},
                            choice="design"),
    "glass_cooler": Node(required=("door",), one_of={"racks": 0.8, "divider": 0.2}, choice="interior"),
    "wine": Node(required=("door", "racks")),
    "undercounter": Node(required=("solid_door", "racks", "crispers"), optional={"freezer": 0.5}),
    "freezer": Node(label="flap"),
    "dual_zone": Node(required=("door", "right_door", "racks", "right_racks")),
    "control_panel": Node(repeat={"key": "key_count"}),
    "key": Node(label="button"),
    "door": Node(label="door", required=("handle",)),
    "right_door": Node(label="door", required=("handle",)),
    "solid_door": Node(label="door", required=("handle",), repeat={"door_bin": "bin_count"}),
    "handle": Node(one_of={"bar": 0.6, "recessed": 0.4}, choice="handle_style"),
    "bar": Node(), "recessed": Node(),
    "door_bin": Node(label="bin"),
    "crispers": Node(repeat={"crisper": "crisper_count"}),
    "crisper": Node(label="drawer"),
    "racks": Node(repeat={"rack": rack_count}),
    "right_racks": Node(repeat={"rack": right_rack_count}),
    "rack": Node(label=("rack", "shelf")),
    "divider": Node(label="shelf"),
})
"""Designs (``design``): a ``glass_cooler`` (a glass door, racks or a divider plate); an ``undercounter``
fridge (a solid insulated door carrying 2-4 door bins that lift out, glass shelves, 1-2 crisper drawers at
the bottom); a ``wine`` cooler (6-8 slide-out shelves with wooden fronts); a ``dual_zone`` cooler (two glass
doors hinged at the outer sides, a mullion between two zones with their own racks, counted apart). An
undercounter fridge may have a freezer compartment across the top of its cavity, closed by a flap hinged
at its top edge that swings up (Danby DCR044A2, Midea WHS-87LB1 compact fridges). A control strip carries
2-5 push keys of the electronic thermostat (power, light, up, down, zone: Danby DBC117A1, Whynter
BR-130SB, Newair AB-1200 control panels)."""

PARAMS = (
    Float("width", "overall width (Y)", "m", *R["width"]),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", *R["depth"]),
    Float("height", "overall height incl. the feet (Z)", "m", *R["height"]),
    Float("wall", "insulated wall thickness", "m", *R["wall"]),
    Float("door_thickness", "glass door thickness (frame depth)", "m", *R["door_thickness"]),
    Float("kick_height", "height of the ventilation kick grille below the door", "m", *R["kick_height"]),
    Float("feet_height", "levelling feet height", "m", *R["feet_height"]),
    Float("control_height", "height of the control strip above the door", "m", *R["control_height"]),
    Choice("hinge_side", "side of the door hinge, seen from the front", choices=("left", "right")),
    Float("handle_length", "handle length as a fraction of the door height", "", *R["handle_length"]),
    Int("rack_count", "sliding racks (interior = racks)", "", 3, 5),
    Choice("rack_style", "wire racks or glass shelves", choices=("wire", "glass"), weights=(0.65, 0.35)),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", *R["rack_travel"]),
    Float("divider_height", "divider plate height as a fraction of the cavity height", "", *R["divider_height"]),
    Int("bin_count", "door bins on an undercounter fridge's door", "", 2, 4),
    Int("crisper_count", "crisper drawers side by side at the bottom of an undercounter fridge", "", 1, 2),
    Int("right_rack_count", "racks of a dual-zone cooler's right zone (one fewer than this, as on the left)", "",
        3, 5),
    Int("key_count", "push keys on the control strip (has_control_panel)", "", 2, 5),
    Float("freezer_height", "height of an undercounter fridge's freezer compartment (has_freezer)", "m",
          *R["freezer_height"]),
    Choice("body_finish", "cabinet material", choices=("painted", "brushed_metal"), weights=(0.6, 0.4)),
    Choice("door_finish", "door frame: match the cabinet or black plastic", choices=("match", "black")),
    Choice("trim_finish", "front trim of the racks", choices=("wood", "chrome", "plastic"), weights=(0.45, 0.35, 0.2)),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
)

MATERIALS = {
    "body": "body_finish", "liner": "plastic:black|dark_grey|white", "glass": "glass:clear|clear_blue",
    "frost": "glass:smoked",
    "handle": ("handle_finish", {"plastic": "plastic:black|dark_grey"}), "trim": "trim_finish", "wire": "chrome",
    "grille": "plastic:black|dark_grey", "feet": "rubber", "display": "rubber", "gasket": "rubber",
    "bin": "plastic:white|light_grey", "wood": "wood", "button": "plastic:black|dark_grey|light_grey",
    "evaporator": "brushed_metal",
}


def frame_finish(p: dict) -> dict:
    """The door frame matches the cabinet or is black plastic."""
    return {**p, "frame_family": p["body_finish"] if p["door_finish"] == "match" else "plastic:black"}


DOOR_OPENS = math.pi / 2


class FridgeLayout(Layout):
    def beverage_fridge(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = A.size(p, design, FR.SIZES)
        ctrl = node.one("control_panel")
        body = FR.body(W, D, H, p["wall"], p["door_thickness"], p["feet_height"], p["kick_height"],
                       p["control_height"] if ctrl else None, design == "dual_zone")
        self.add("body", "body", body.pieces)
        if ctrl:
            xs, ys, zs = body.control
            self.grow(ctrl, xs=xs, ys=ys, zs=zs)
        self.grow(style, cav=body.cav, hole=body.hole, box=body.box, xs=body.xs, margin=body.margin)

    def glass_cooler(self, node, cav, hole, box, xs, margin):
        self.grow(node.one("door"), box=box, hole=hole)
        self.grow(node.one(node.choice), cav=cav, hole=hole, xs=xs, margin=margin)

    def wine(self, node, cav, hole, box, xs, margin):
        self.grow(node.one("door"), box=box, hole=hole)
        self.grow(node.one("racks"), cav=cav, hole=hole, xs=xs, margin=margin, wine=True)

    def undercounter(self, node, cav, hole, box, xs, margin):
        """A solid door with bins, 1-2 crisper drawers on the cavity floor, glass shelves above them, a freezer
        compartment at the top (optional); shelves, crispers and the freezer flap stop short of the bins on the
        closed door."""
        self.grow(node.one("solid_door"), box=box, hole=hole)
        xs = FR.behind_bins(xs)
        _, _, _, _, _, ceiling = cav
        if node.one("freezer"):
            ceiling = self.grow(node.one("freezer"), cav=cav, xs=xs)
        self.grow(node.one("crispers"), cav=cav, xs=xs, zs=FR.crisper_zs(cav), margin=margin)
        self.grow(node.one("racks"), cav=FR.over_crispers(cav, ceiling), hole=hole, xs=xs, margin=margin)

    def freezer(self, node, cav, xs):
        """A freezer compartment across the top of the cavity: an aluminium evaporator box (its floor and sides,
        fixed) and a flap over its front, hinged on its top back edge, that swings up out of the way (only with
        the door open). Returns the height below which the shelves stay."""
        freezer = FR.freezer(cav, xs, freezer_height(self.p))
        self.extend("body", freezer.evaporator)
        flap = self.place(freezer.flap.attached("hinge", to=freezer.at), "freezer_flap")
        self.hinge("body", flap.root, flap.anchor("hinge"), upper=FR.FLAP_OPENS, requires_open="door")
        return freezer.ceiling

    def dual_zone(self, node, cav, hole, box, xs, margin):
        """Two glass doors meeting over the mullion, each hinged on its outer side; racks in each zone."""
        left, right = FR.dual_doors(box, hole)
        self.grow(node.one("door"), **left, side="left")
        self.grow(node.one("right_door"), **right, side="right")
        left_cav, right_cav = FR.zones(cav)
        self.grow(node.one("racks"), cav=left_cav, hole=hole, xs=xs, margin=margin)
        self.grow(node.one("right_racks"), cav=right_cav, hole=hole, xs=xs, margin=margin, door="right_door",
                  prefix="right_")

    def right_door(self, node, box, hole, side):
        self.door(node, box, hole, side=side, name="right_door")

    def right_racks(self, node, **kw):
        self.racks(node, **kw)

    def solid_door(self, node, box, hole):
        """An insulated door: an outer skin, a foam core, a moulded inner liner with a gasket, and bins."""
        left = self._door(node, box, hole, FR.solid_door(box, self.p["frame_family"]), "door", None)
        kids = node.of("door_bin")
        for k, (kid, slot) in enumerate(zip(kids, FR.door_bins(len(kids), box, hole, left), strict=True)):
            self.grow(kid, k=k, **slot)

    def door_bin(self, node, k, xs, ys, zs):
        """A door bin: an open moulded tray hooked on the door liner; it lifts straight up off its hooks (a
        lift-off part, which the core stops at a hand's lift)."""
        pieces, at = FR.door_bin(xs, ys, zs)
        name = self.add(f"door_bin_{k}", "bin", pieces)
        self.slide("door", name, at, upper=FR.BIN_LIFT, role="lift_off")

    def crispers(self, node, cav, xs, zs, margin):
        p = self.p
        kids = node.of("crisper")
        for k, (kid, ys) in enumerate(zip(kids, FR.crisper_ys(len(kids), cav, p["width"], p["door_thickness"],
                                                               margin), strict=True)):
            self.grow(kid, k=k, xs=xs, ys=ys, zs=zs)

    def crisper(self, node, k, xs, ys, zs):
        """A crisper drawer: a clear open bin with a front and a finger pull, sliding out along +X."""
        FR.crisper(xs, ys, zs).place(self, f"crisper_{k}", requires_open="door")

    def control_panel(self, node, xs, ys, zs):
        """The control strip over the door (part of the body) and its push keys, pressing in along -X."""
        keys = node.of("key")
        pieces, made = A.control_strip_keys(*xs, *ys, *zs, len(keys))
        self.extend("body", pieces)
        for k, (kid, m) in enumerate(zip(keys, made, strict=True)):
            self.grow(kid, k=k, made=m)

    def key(self, node, k, made):
        piece, at, travel = made
        self.add(f"key_{k}", "button", [piece])
        self.slide("body", f"key_{k}", at, upper=travel, role="button")

    def door(self, node, box, hole, side=None, name="door"):
        self._door(node, box, hole, A.glass_door(box, hole), name, side)

    def _door(self, node, box, hole, pieces, name, side):
        """Add a door hinged on ``side`` (default: the hinge_side parameter) and its handle; returns whether
        it hinges on the left."""
        p = self.p
        *_, z0, z1 = box
        self.add(name, "door", pieces)
        left = (side or p["hinge_side"]) == "left"
        self.hinge("body", name, A.side_hinge(box, left), upper=DOOR_OPENS)
        at, stile = FR.handle_anchor(box, hole, left)
        self.grow(node.one("handle"), at=at, length=p["handle_length"] * (z1 - z0), stile=stile, door=name)
        return left

    def handle(self, node, at, length, stile, door):
        self.grow(node.one(node.choice), at=at, length=length, stile=stile, door=door)

    def bar(self, node, at, length, stile, door="door"):
        h = hardware.bar_handle(length, "handle", FR.BAR).attached("mount", to=at)
        self.extend(door, h.parts[h.root].pieces)

    def recessed(self, node, at, length, stile, door="door"):
        h = FR.recessed_pull(length, stile).attached("mount", to=at)
        self.extend(door, h.parts[h.root].pieces)

    def racks(self, node, cav, hole, xs, margin, wine=False, door="door", prefix=""):
        p = self.p
        kids = node.of("rack")
        # the racks keep clear of the open door's hinge-side edge
        W, _, _ = A.size(p, p["design"], FR.SIZES)
        fit = FR.rack_levels(len(kids), cav, hole, xs, W, p["door_thickness"], margin)
        for k, (kid, (rails, zb)) in enumerate(zip(kids, fit["levels"], strict=True)):
            for rail in rails:
                self.extend("body", [rail])
            self.grow(kid, k=k, xs=xs, ry=fit["ry"], zb=zb, hr=fit["hr"], yc=fit["yc"], wine=wine, door=door,
                      prefix=prefix)

    def rack(self, node, k, xs, ry, zb, hr, yc=0.0, wine=False, door="door", prefix=""):
        p = self.p
        if p["rack_style"] == "glass" and not wine:
            label, pieces = "shelf", A.glass_shelf(xs, ry, zb, hr)
        else:  # a wine cooler's shelves: wire cradles with a wooden front
            pieces = A.wire_rack(xs, ry, zb, hr, float(self.rng.uniform(*FR.WIRE_PITCH)))
            label, pieces = "rack", [pc.replace(material="wood") if wine and pc.material == "trim" else pc
                                     for pc in pieces]
        name = self.add(f"{prefix}rack_{k}", label, [pc.translated((0.0, yc, 0.0)) for pc in pieces])
        at, travel = A.rack_slide(xs, zb, p["rack_travel"], yc)
        self.slide("body", name, at, upper=travel, requires_open=door)

    def divider(self, node, cav, hole, xs, margin):
        self.add("divider", "shelf", FR.divider(cav, self.p["divider_height"]))
        self.fix("body", "divider")


CATEGORY = Category("beverage_fridge", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, FridgeLayout,
                    {**MATERIALS, "frame": "frame_family"}, derive=frame_finish, palette=appliance)
