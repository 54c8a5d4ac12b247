"""Microwave: a counter-top oven with a hinged glass door, a turntable and a control panel.

X is depth (the door faces +X), Y is width, Z is up. Seen from the front, the door covers the
left part of the front and hinges at its left edge: it turns about -Z through a pivot on its
front face, so it swings outward and to the left. The control panel is a fascia on the right,
fixed to the body; its push buttons slide in along -X, its dials turn about X. The turntable (a
glass tray on a roller ring) spins about Z over a spindle in the middle of the cavity floor.
The body is a sheet casing with a front bezel and a hollow cavity liner; the door and the fascia
are a thin skin on a dark inner frame. Sizes are those of real counter-top microwaves. A combination model
has a low wire rack on its turntable or floor; an over-the-range model's two grease filters slide back.
Parts: ``categories/parts/microwaves.py`` (layout), ``appliance.py`` (pieces), ``hardware``; sizes in
``appliance_sizes.py``.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import microwaves as MW
from .parts.appliance_sizes import MICROWAVE_RANGES as R


def dials(p, rng) -> int:
    """knob_count, or 1 beside a keypad; without one 1 or 2 (drawn, :func:`~.parts.microwaves.dial_count`)"""
    return MW.dial_count(p["knob_count"], p["has_buttons"], rng)


KEYPAD_ROWS = 6
"""Counter-top keypads are grids of three columns: a 10-key number pad (four rows: 1-9, then 0 between
two function keys) under one or two rows of function keys, e.g. Panasonic NN-SN686S, GE JES1657SRSS,
Toshiba ML-EM34P owner's manuals: 3-6 rows of three. Below four rows it is a function-key panel with
the time set by a dial."""


def key_rows(p: dict) -> int:
    """button_rows; up to three always fit (the layout shrinks keys to 50 %), a fourth to sixth row only
    where the panel holds it with keys at 65 % of button_height or more (a drawer model's strip: 4 rows)"""
    rows, design = p["button_rows"], p["design"]
    if rows <= MW.ROWS_ALWAYS_FIT or design == "drawer_model":
        return min(rows, MW.STRIP_ROWS)
    W, _, H = A.size(p, design, MW.SIZES)
    release = p["door_opener"] == "release_button" and design in ("turntable", "flatbed")
    return MW.keypad_rows(rows, H, p["feet_height"], design == "over_the_range", p["panel_fraction"] * W,
                          dials(p, None) if p["has_knob"] else 0, release, p["knob_radius"], p["button_height"])


def key_count(p: dict) -> int:
    """Push keys: three a row over :func:`key_rows` rows, the bottom row three keys or two wide ones
    (``bottom_keys``: Stop/Cancel and Start as two wide keys under the number pad, as on GE JES1072 and
    Panasonic NN-ST66 keypads)"""
    return MW.key_count(key_rows(p), p["bottom_keys"])


GRAMMAR = Grammar("microwave", {
    "microwave": Node(label="body", required=("control_panel",),
                      one_of={"turntable": 0.3, "flatbed": 0.2, "over_the_range": 0.3, "drawer_model": 0.2},
                      choice="design"),
    "turntable": Node(required=("door", "plate")),
    "flatbed": Node(required=("door",), optional={"rack": 0.5}),
    "over_the_range": Node(required=("otr_door", "plate"), repeat={"filter": 2}),
    "filter": Node(label="filter"),
    "drawer_model": Node(required=("drawer",)),
    "otr_door": Node(label="door"),
    "drawer": Node(label="drawer"),
    "door": Node(label="door", one_of={"bar": 0.4, "recessed": 0.3, "release_button": 0.3}, choice="door_opener"),
    "bar": Node(), "recessed": Node(),
    "release_button": Node(label="button"),
    "plate": Node(label="plate", optional={"rack": 0.5}),
    "rack": Node(label="rack"),
    "control_panel": Node(label="control_panel", optional={"buttons": 0.8, "knob": 0.5}),
    "buttons": Node(repeat={"button": lambda p, rng: key_count(p)}),
    "button": Node(label="button"),
    "knob": Node(repeat={"dial": dials}),
    "dial": Node(label="knob"),
})
"""Designs (``design``): a counter-top ``turntable`` model; a ``flatbed`` (inverter) model with a fixed
ceramic floor instead of the turntable; an ``over_the_range`` model (30 in, a bar handle, a vent grille
over the door, grease filters and a light under it); a ``drawer_model`` (a drawer that slides out, the
control strip above it). A ``release_button`` opener is a button on the control panel that releases the
door. A ``rack``: a combination (grill / convection) model's low wire rack, standing on the turntable (it turns
with it) or on a flatbed's ceramic floor (Panasonic NN-CT55, Sharp R-861 and GE JES1657 convection owner's
manuals: a rack for grilling and two-level cooking)."""

PARAMS = (
    Float("width", "overall width (Y)", "m", *R["width"]),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", *R["depth"]),
    Float("height", "overall height incl. the feet (Z)", "m", *R["height"]),
    Float("panel_fraction", "control panel width as a fraction of the width", "", *R["panel_fraction"]),
    Float("wall", "casing sheet thickness", "m", *R["wall"]),
    Float("door_thickness", "door thickness", "m", *R["door_thickness"]),
    Float("window_margin", "door frame width around the window (hinge side, top, bottom)", "m", *R["window_margin"]),
    Float("plate_fraction", "turntable diameter as a fraction of the largest that fits", "", *R["plate_fraction"]),
    Int("button_rows", "rows of three push buttons (4-6: a number pad with function keys, where it fits)", "",
        1, KEYPAD_ROWS),
    Int("bottom_keys", "keys in the keypad's bottom row: three, or two wide ones (Stop/Cancel, Start)", "", 2, 3),
    Float("rack_height", "a combination model's wire rack: height of its grid over what it stands on", "m",
          *R["rack_height"]),
    Float("button_height", "push button height (Z); press depth is 1/8 of it", "m", *R["button_height"]),
    Choice("button_shape", "push button shape", choices=("rect", "round"), weights=(0.65, 0.35)),
    Int("knob_count", "dials; auto = 2 without push buttons, else 1", "", 1, 2, auto=True),
    Float("knob_radius", "dial radius (capped at 0.38 x panel width)", "m", *R["knob_radius"]),
    Float("handle_length", "door handle length as a fraction of the door height", "", *R["handle_length"]),
    Choice("body_finish", "casing material", choices=("painted", "brushed_metal", "plastic"),
           weights=(0.45, 0.3, 0.25)),
    Choice("door_finish", "door frame and panel: match the casing or contrast (plastic)",
           choices=("match", "contrast")),
    Choice("interior_finish", "cavity liner material", choices=("enamel", "painted")),
    Choice("handle_finish", "door handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("feet_height", "rubber feet height", "m", *R["feet_height"]),
)

MATERIALS = {
    "body": "body_finish", "door": "plastic", "interior": "interior_finish", "glass": "glass", "plate": "glass:clear",
    "roller": "plastic", "button": "plastic", "knob": "plastic", "handle": "handle_finish", "door_inner": "rubber",
    "display": "rubber", "feet": "rubber", "trim": "chrome", "filter": "brushed_metal", "rack": "chrome",
}

DOOR_OPENS = math.pi / 2


def skins(p: dict) -> tuple[str, str]:
    """The door's and fascia's skin and inner-frame slots: the casing's finish on a dark frame, or all
    ``door`` (contrasting plastic)."""
    return ("body", "door_inner") if p["door_finish"] == "match" else ("door", "door")


class MicrowaveLayout(A.PanelNodes):
    def microwave(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = A.size(p, design, MW.SIZES)
        if design == "drawer_model":
            return self._drawer_model(node, style, W, D, H)
        body = MW.countertop(W, D, H, p["wall"], p["door_thickness"], p["feet_height"], p["panel_fraction"],
                             vent=design == "over_the_range")
        self.add("body", "body", MW.casing(body, p["wall"], p["body_finish"], p["interior_finish"]))
        door = style.one("door") or style.one("otr_door")
        self.grow(style, cavity=body.cavity, door=body, box=body.outer)
        self.grow(node.one("control_panel"), body=body, release=door.one("release_button"))

    def turntable(self, node, cavity, door, box):
        self.grow(node.one("plate"), cavity=cavity)
        self.grow(node.one("door"), body=door)

    def flatbed(self, node, cavity, door, box):
        """No turntable: a fixed ceramic floor over the antenna (Panasonic inverter flatbed models)."""
        self.extend("body", [MW.ceramic_floor(cavity)])
        self.grow(node.one("door"), body=door)
        if rack := node.one("rack"):
            self.grow(rack, parent="body", seat=MW.floor_rack_seat(cavity))

    def over_the_range(self, node, cavity, door, box):
        """A turntable, a door with a bar handle, a vent grille over the door and panel, and under the
        body two grease filters and a cooktop light (decor on the casing)."""
        self.grow(node.one("plate"), cavity=cavity)
        self.grow(node.one("otr_door"), body=door)
        self.extend("body", MW.vent_grille(box))
        spec, places = MW.grease_filters(door)
        for k, (kid, at) in enumerate(zip(node.of("filter"), places, strict=True)):
            self.grow(kid, k=k, spec=spec, at=at)

    def filter(self, node, k, spec, at):
        """A grease filter in the body's bottom: it slides 25 mm back in its track before it drops out
        (GE JVM7195, Whirlpool WMH31017 owner's manuals: "slide the filter to the rear, pull down")."""
        placed = self.place(spec.build().attached("front", to=at), f"filter_{k}")
        self.slide("body", placed.root, placed.anchor("slide"), upper=spec.travel)

    def otr_door(self, node, body):
        self._door(node, body, "bar")

    def drawer_model(self, node, body):
        self.grow(node.one("drawer"), body=body)

    def _drawer_model(self, node, style, W, D, H):
        """A drawer microwave: a casing with a wide opening, a drawer (front, open tray, cavity liner) that
        slides out along +X, a control strip above it (display, buttons, dials) on the body."""
        p = self.p
        body = MW.drawer_body(W, D, H, p["wall"], p["door_thickness"], p["feet_height"])
        self.add("body", "body", MW.casing(body, p["wall"], p["body_finish"], p["interior_finish"]))
        self.grow(style, body=body)
        self.grow(node.one("control_panel"), body=body, release=None)

    def drawer(self, node, body):
        p = self.p
        MW.drawer(body, p["body_finish"], p["interior_finish"], p["handle_length"]).place(self, "drawer")

    def plate(self, node, cavity):
        turntable = MW.turntable(cavity, self.p["plate_fraction"])
        self.extend("body", [turntable.spindle])
        plate = self.place(turntable.plate, "plate")
        self.spin("body", plate.root, plate.anchor("axis"), role="turntable")
        if rack := node.one("rack"):  # on the tray's floor, inside its rim
            self.grow(rack, parent=plate.root, seat=turntable.rack)

    def rack(self, node, parent, seat):
        """A low wire rack: a square grid inscribed in the seat's radius on four legs, fixed to what it
        stands on."""
        rack = self.place(MW.stand_rack(seat, self.p["rack_height"]), "rack")
        self.fix(parent, rack.root)

    def door(self, node, body):
        self._door(node, body, node.choice)

    def _door(self, node, body, opener):
        p = self.p
        skin, inner = skins(p)
        ys, zs = body.door_ys, body.zs
        hole = MW.door_window(ys, zs, p["window_margin"], opener)
        self.add("door", "door", A.glazed_door(body.x_front, p["door_thickness"], ys, zs, hole, skin, inner,
                                               A.inner_sheet(MATERIALS[inner])))
        self.hinge("body", "door", body.hinge, upper=DOOR_OPENS)
        length = p["handle_length"] * body.door_height
        if node.kind == "otr_door":
            self.bar(node, at=body.handle_at, length=length)
        elif opener != "release_button":
            self.grow(node.one(opener), at=body.handle_at, length=length)

    def bar(self, node, at, length):
        self.extend("door", MW.door_handle("bar", length).attached("edge", to=at).pieces)

    def recessed(self, node, at, length):
        self.extend("door", MW.door_handle("recessed", length).attached("edge", to=at).pieces)

    def control_panel(self, node, body, release):
        """A column on the fascia (display, keys, dials, door release) or, on a drawer model's wide strip,
        everything side by side."""
        p = self.p
        buttons, knob = node.one("buttons"), node.one("knob")
        n_dials, n_keys = len(knob.of("dial") if knob else ()), len(buttons.of("button") if buttons else ())
        xs, ys, zs = body.fascia_xs, body.panel_ys, body.panel_zs
        if body.strip:  # a drawer microwave's control strip
            panel = MW.strip_panel(xs[1], ys, zs, n_keys, n_dials, p["knob_radius"], p["button_height"],
                                   p["button_shape"], self.rng)
        else:
            panel = MW.column_panel(xs[1], ys, zs, n_keys, n_dials, bool(release), p["knob_radius"],
                                    p["button_height"], p["button_shape"], self.rng)
        skin, inner = skins(p)
        self.add("control_panel", "control_panel",
                 MW.fascia(xs, ys, zs, panel.holes, skin, inner, A.inner_sheet(MATERIALS[inner])) + panel.decor)
        self.fix("body", "control_panel")
        if buttons:
            self.grow(buttons, made=[b for b in panel.buttons if not b.release])
        if release:
            self.grow(release, made=panel.buttons[-1])
        if knob:
            self.grow(knob, made=panel.dials)

    release_button = A.PanelNodes.button

    def knob(self, node, made):
        for kid, d in zip(node.of("dial"), made, strict=True):
            self.grow(kid, made=d)

    def dial(self, node, made):
        self.add(made.name, "knob", made.pieces)
        self.spin("control_panel", made.name, made.at, role="knob")


CATEGORY = Category("microwave", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, MicrowaveLayout, MATERIALS,
                    palette=appliance)  # finishes real microwaves are sold in
