"""Dishwasher: a built-in dishwasher with a bottom-hinged door and slide-out wire racks.

X is depth (the door faces +X), Y is width, Z is up. The machine stands on four levelling feet
behind a kick plinth; the stainless tub is built from panels, so the wash cavity is a real hollow
(filter and lower spray arm on its floor, a nozzle from its ceiling). The door is hinged at its
bottom front edge and falls forward about +Y from closed (0) to flat (pi/2); its centre of mass is
behind the hinge line, so gravity presses it shut. Optional: a control panel along the top of the
door front (display and push buttons), and a handle (bar or pocket pull). 1-4 wire racks roll out
along +X on rails: a tall lower rack with plate tines, an upper rack, a cutlery tray on top when
there are three or more; the lowest may carry cutlery baskets. Every rack runs above the open
door and slides out only with the door open (``requires_open``).
Parts: ``categories/parts/dishwashers.py`` (layout), ``appliance.py`` (pieces), ``hardware``; sizes in
``appliance_sizes.py``.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import dishwashers as DW
from .parts import hardware
from .parts.appliance_sizes import DISHWASHER_RANGES as R


def rack_count(p, rng) -> int:
    """rack_count; a compact counter-top model has room for one rack"""
    return DW.rack_count(p["design"], p["rack_count"])


def upper_racks(p, rng) -> int:
    """the racks between the lower rack and a cutlery tray (on top of three or more racks)"""
    return DW.rack_kinds(rack_count(p, rng))[0]


def trays(p, rng) -> int:
    """a cutlery tray on top of three or more racks"""
    return DW.rack_kinds(rack_count(p, rng))[1]


GRAMMAR = Grammar("dishwasher", {
    "dishwasher": Node(label="body", one_of={"freestanding": 0.35, "integrated": 0.25, "compact": 0.2,
                                             "dish_drawer": 0.2}, choice="design"),
    "freestanding": Node(required=("door", "racks")),
    "integrated": Node(required=("door", "racks")),
    "compact": Node(required=("door", "racks")),
    "dish_drawer": Node(repeat={"drawer": 2}),
    "drawer": Node(label="drawer", required=("drawer_rack",)),
    "drawer_rack": Node(label="rack", repeat={"tine_row": "tine_rows"}),
    "door": Node(label="door", optional={"handle": 0.8, "control_panel": 0.5}),
    "handle": Node(one_of={"bar": 0.6, "pocket": 0.4}, choice="handle_style"),
    "bar": Node(), "pocket": Node(),
    "control_panel": Node(label="control_panel", optional={"buttons": 0.7}),
    "buttons": Node(repeat={"button": "button_count"}),
    "button": Node(label="button"),
    "racks": Node(required=("lower_rack",), repeat={"rack": upper_racks, "tray": trays}, optional={"baskets": 0.7}),
    "lower_rack": Node(label="rack", repeat={"tine_row": "tine_rows"}),
    "rack": Node(label="rack", repeat={"tine_row": "upper_tine_rows"}, optional={"cup_shelves": 0.7}),
    "tray": Node(label="rack"),
    "tine_row": Node(label="tines"),
    "cup_shelves": Node(repeat={"cup_shelf": "cup_shelf_count"}),
    "cup_shelf": Node(label="shelf"),
    "baskets": Node(repeat={"basket": "basket_count"}),
    "basket": Node(label="basket"),
})
"""Designs (``design``): a ``freestanding`` machine (finished sides, a worktop), an ``integrated`` one
behind a cabinet front panel (shaker style, the control strip above it if there is one), a ``compact``
counter-top model (one rack) and a ``dish_drawer`` (two drawers stacked, each a tub with its own rack,
pulled out by a bar handle). Cutlery ``baskets`` stand in the lowest rack (not in a cutlery tray) and lift
out of it. The lower rack (and each drawer's rack) carries 2-4 rows of fold-down plate tines instead of
fixed ones; an upper rack 0-2 rows and optional flip-down cup shelves on its sides (1: the left one, 2:
both). Real racks: Bosch 300/500 Series (two fold-down tine sections in each rack, cup shelves, a third
rack), Miele G 7000 ("FlexCare" fold-down spikes, cup racks), Whirlpool WDT750 (fold-down tines),
Fisher & Paykel DD60 DishDrawer (fold-down tines in each drawer's rack)."""

PARAMS = (
    Float("width", "overall width (Y)", "m", *R["width"]),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", *R["depth"]),
    Float("height", "overall height incl. the feet (Z)", "m", *R["height"]),
    Float("wall", "tub wall thickness (insulation + liner)", "m", *R["wall"]),
    Float("door_thickness", "door thickness", "m", *R["door_thickness"]),
    Float("kick_height", "kick plinth height under the door: the hinge height above the floor", "m", *R["kick_height"]),
    Float("feet_height", "levelling feet height", "m", *R["feet_height"]),
    Int("rack_count", "sliding racks", "", 1, 4),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", *R["rack_travel"]),
    Float("wire_pitch", "spacing of the rack wires", "m", *R["wire_pitch"]),
    Int("basket_count", "cutlery baskets in the lowest rack (has_baskets)", "", 1, 4),
    Int("tine_rows", "fold-down tine rows in the lower rack (and in each drawer's rack)", "", 2, 4),
    Int("upper_tine_rows", "fold-down tine rows in an upper rack", "", 0, 2),
    Int("cup_shelf_count", "flip-down cup shelves of an upper rack (has_cup_shelves): left, or both sides", "",
        1, 2),
    Float("basket_lift", "lift of a cutlery basket out of its rack (shortened to the rack above)", "m",
          *R["basket_lift"]),
    Float("handle_length", "handle length as a fraction of the width", "", *R["handle_length"]),
    Float("control_height", "control panel height (has_control_panel)", "m", *R["control_height"]),
    Int("button_count", "push buttons on the control panel (has_buttons)", "", 2, 6),
    Float("button_size", "push button height (Z); press depth is 1/8 of it", "m", *R["button_size"]),
    Choice("body_finish", "door front and cabinet finish", choices=("brushed_metal", "painted"), weights=(0.55, 0.45)),
    Choice("front_finish", "cabinet front panel of an integrated model", choices=("wood", "painted")),
    Choice("rack_finish", "rack wires: nylon coated or chrome", choices=("coated", "chrome"), weights=(0.7, 0.3)),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
)

MATERIALS = {
    "body": "body_finish", "tub": "brushed_metal:stainless", "door_inner": "plastic:dark_grey|black",
    "wire": ("rack_finish", {"coated": "plastic:light_grey|white|dark_grey", "chrome": "chrome"}),
    "wheel": "plastic:dark_grey|black", "basket": "plastic:light_grey|white", "arm": "plastic:light_grey|dark_grey",
    "handle": ("handle_finish", {"plastic": "plastic:black|dark_grey"}), "panel": "plastic:black|dark_grey",
    "button": "plastic:black|dark_grey|light_grey", "display": "rubber", "feet": "rubber",
    "plinth": "plastic:black|dark_grey", "front": "front_finish", "worktop": "plastic:white|light_grey|dark_grey",
}

DOOR_OPENS = math.pi / 2


class DishwasherLayout(A.PanelNodes):
    def dishwasher(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = A.size(p, design, DW.SIZES)
        if design == "dish_drawer":
            body, geo = DW.drawer_cabinet(W, D, H, p["door_thickness"], p["feet_height"], p["kick_height"])
            self.add("body", "body", body)
            return self.grow(style, **geo)
        door = style.one("door")
        tub = DW.tub_body(W, D, H, p["wall"], p["door_thickness"], p["feet_height"], p["kick_height"], design,
                          p["control_height"], bool(door.one("control_panel")), bool(door.one("handle")))
        self.add("body", "body", tub.pieces)
        self.grow(style, door=tub.door, racks=tub.racks)

    def freestanding(self, node, door, racks):
        self.grow(node.one("door"), **door)
        self.grow(node.one("racks"), **racks)

    integrated = compact = freestanding

    def dish_drawer(self, node, xs, ys, zs):
        """Two drawers (a front, an open stainless tub, a rack fixed in it), sliding out along +X."""
        for k, kid in enumerate(node.of("drawer")):
            self.grow(kid, k=k, **DW.drawer_boxes(k, xs, ys, zs))

    def drawer(self, node, k, front, tub):
        name = f"drawer_{k}"
        made = DW.drawer(front, tub, self.p["handle_length"])
        made.drawer.place(self, name)
        self.grow(node.one("drawer_rack"), drawer=name, slot=made.rack)

    def drawer_rack(self, node, drawer, slot):
        """A dish drawer's lower rack (without tines of its own: fold-down tine rows), fixed in its tub."""
        rack = A.dish_rack(slot.xs, slot.cy1, slot.za, slot.top, self.p["wire_pitch"], "lower", tines=False)
        name = self.add(f"{drawer}_rack", "rack", rack)
        self.fix(drawer, name)
        self._tines(node, name, slot.xs, DW.rack_half_width(slot.cy1), slot.za, slot.top, DW.RACK_FRONT)

    def _tines(self, node, rack, xs, ry, za, top, front, yh=None):
        """The fold-down tine rows of a rack (:func:`~.parts.dishwashers.tine_rows`)."""
        rows = node.of("tine_row")
        if not rows:
            return
        made = DW.tine_rows(len(rows), xs, ry, za, top, front, yh)
        for k, (kid, (pieces, y, z)) in enumerate(zip(rows, made, strict=True)):
            self.grow(kid, name=f"{rack}_tines_{k}", rack=rack, pieces=pieces, at=(y, z))

    def tine_row(self, node, name, rack, pieces, at):
        y, z = at
        self.add(name, "tines", pieces)
        # about +X a standing tine folds towards -Y
        self.hinge(rack, name, A.fold_line(y, z), upper=A.QUARTER_TURN)

    def door(self, node, box, band):
        _, x1, y0, y1, _, _ = box
        integrated = self.p["design"] == "integrated"
        ctrl = node.one("control_panel")
        front = DW.cabinet_front(box, band, bool(ctrl)) if integrated else []
        self.add("door", "door", A.layered_door(box) + front)
        self.hinge("body", "door", A.drop_hinge(box), upper=DOOR_OPENS)
        if ctrl:
            self.grow(ctrl, xf=x1, ys=(y0, y1), zs=DW.control_zs(box, band), handle=bool(node.one("handle")))
        if node.one("handle"):
            self.grow(node.one("handle"), at=DW.handle_frame(box, band, bool(ctrl), integrated))

    def handle(self, node, at):
        self.grow(node.one(node.choice), at=at, length=self.p["handle_length"] * self.p["width"])

    def bar(self, node, at, length):
        h = hardware.bar_handle(length, "handle", DW.BAR).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def pocket(self, node, at, length):
        h = hardware.edge_pull(length, "handle", **DW.POCKET).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def control_panel(self, node, xf, ys, zs, handle):
        """A fascia on the top of the door front: display on the left, push buttons on the right."""
        buttons = node.one("buttons")
        pieces, made = DW.control_panel(xf, ys, zs, handle, len(buttons.of("button")) if buttons else 0,
                                        self.p["button_size"])
        self.add("control_panel", "control_panel", pieces)
        self.fix("door", "control_panel")
        if buttons:
            self.grow(buttons, made=made)

    def racks(self, node, cav, z):
        kids = [*node.of("lower_rack"), *node.of("rack"), *node.of("tray")]
        kinds = [{"lower_rack": "lower", "rack": "upper", "tray": "tray"}[kid.kind] for kid in kids]
        baskets = node.one("baskets")
        for kid, level in zip(kids, DW.rack_levels(kinds, cav, z, bool(baskets)), strict=True):
            for rail in level["rails"]:
                self.extend("body", [rail])
            slot = level["slot"]
            self.grow(kid, **slot)
            if slot["k"] == 0 and baskets:
                self.grow(baskets, rack="rack_0", xs=slot["xs"], ry=DW.rack_half_width(slot["cy1"]), za=slot["za"],
                          top=slot["top"])

    def rack(self, node, k, xs, cy1, za, top, kind, front):
        p = self.p
        name = self.add(f"rack_{k}", "rack", A.dish_rack(xs, cy1, za, top, p["wire_pitch"], kind,
                                                         tines=kind != "lower"))
        at, travel = A.rack_slide(xs, za, p["rack_travel"])
        self.slide("body", name, at, upper=travel, requires_open="door")
        ry = DW.rack_half_width(cy1)
        shelves = node.one("cup_shelves") if kind == "upper" else None
        yh = None
        if shelves:
            slot = DW.cup_shelf_slot(xs, ry, za, top)
            self.grow(shelves, rack=name, **slot)
            yh = DW.tines_beside_shelves(ry, slot["w"])
        if kind != "tray":
            self._tines(node, name, xs, ry, za, top, front, yh=yh)

    lower_rack = tray = rack

    def cup_shelves(self, node, rack, xs, ry, z, w):
        for k, kid in enumerate(node.of("cup_shelf")):
            self.grow(kid, k=k, rack=rack, xs=xs, ry=ry, z=z, w=w)

    def cup_shelf(self, node, k, rack, xs, ry, z, w):
        """The first on the left side wall, the second on the right; each swings down inwards to level."""
        pieces, y, s = DW.cup_shelf(k, xs, ry, z, w)
        name = self.add(f"{rack}_cup_shelf_{k}", "shelf", pieces)
        # about -X (left) or +X (right) the top swings inwards
        self.hinge(rack, name, A.fold_line(y, z, s), upper=A.QUARTER_TURN)

    def baskets(self, node, rack, xs, ry, za, top):
        """Open cutlery baskets side by side at the front of the lowest rack, fixed to it."""
        kids = node.of("basket")
        made, lift = DW.baskets(len(kids), xs, ry, za, top, self.p["basket_lift"])
        for k, (kid, (pieces, at)) in enumerate(zip(kids, made, strict=True)):
            self.grow(kid, k=k, rack=rack, pieces=pieces, at=at, lift=lift)

    def basket(self, node, k, rack, pieces, at, lift):
        """A cutlery basket stands in its rack and lifts straight up out of it (below the rack above): a
        lift-off part, which the core stops at a hand's lift."""
        name = self.add(f"basket_{k}", "basket", pieces)
        if lift > DW.MIN_BASKET_LIFT:
            self.slide(rack, name, Frame.at(at), upper=lift, role="lift_off")
        else:
            self.fix(rack, name)


SUBSTRATES = {"body": ("body_finish", {"painted": A.STEEL})}  # a painted cabinet is painted steel sheet

CATEGORY = Category("dishwasher", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DishwasherLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=appliance)  # finishes real dishwashers are sold in
