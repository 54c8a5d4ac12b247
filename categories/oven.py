"""Oven: a freestanding range or a built-in oven with a bottom-hinged glass door and racks.

X is depth (the door faces +X), Y is width, Z is up. From the floor up the front is a recessed
kick plinth, a storage drawer (sliding out along +X, or a fixed front), a trim strip, the oven
door, and above it either the cooktop edge (``range``: the control panel is a backguard on the
back of the cooktop) or the control panel fascia (``wall``: a built-in oven). The door hinges at
its bottom front edge and falls forward about +Y, 0..pi/2, its hinge high enough that the open
door with its handle never reaches the floor or the open drawer; its centre of mass is behind the
hinge line, so gravity holds it shut. The cavity is hollow (a sheet casing and a five-wall liner);
wire racks rest on side rails and slide out only with the door open (``requires_open``). The
control panel carries knobs (continuous or +-pi/4 about +X) and optional push buttons; a range's
cooktop has burners and optional cast grates, each on a ``limited_floating`` joint (forward, a
little sideways, lifted).
Parts: ``categories/parts/ovens.py`` (layout), ``appliance.py`` (pieces), ``hardware``; sizes in
``appliance_sizes.py``.
"""

from __future__ import annotations

import math

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import ovens as OV
from .parts.appliance_sizes import OVEN_RANGES as R


def grates(p, rng) -> int:
    """grate_count, or 2 below 0.7 m width, else 3 (:func:`~.parts.ovens.grate_count`)"""
    return p["grate_count"] or OV.grate_count(p["width"])


def knobs(p, rng) -> int:
    """knob_count, or one per burner + 1 on a range (+ 1 for a warming drawer; at most 8), 2-3 on a
    built-in oven, 4-5 on a double wall oven (a mode and a temperature knob per oven)"""
    drawn = OV.knob_count(p["style"], sum(OV.burners_per_grate(grates(p, rng))), rng)
    return p["knob_count"] or drawn


GRAMMAR = Grammar("oven", {
    "oven": Node(label="body", required=("door", "control_panel", "racks"),
                 one_of={"range": 0.35, "wall": 0.2, "double_wall": 0.2, "warming": 0.25}, choice="style"),
    "range": Node(required=("cooktop",), optional={"drawer": 0.6}),
    "warming": Node(required=("cooktop", "warming_drawer")),
    "wall": Node(),
    "double_wall": Node(required=("lower_door", "lower_racks")),
    "lower_door": Node(label="door"),
    "lower_racks": Node(repeat={"rack": "rack_count"}),
    "warming_drawer": Node(label="drawer"),
    "cooktop": Node(optional={"grates": 0.8}),
    "grates": Node(repeat={"grate": grates}),
    "grate": Node(label="grate"),
    "drawer": Node(label="drawer"),
    "door": Node(label="door"),
    "control_panel": Node(label="control_panel", required=("knobs",), optional={"buttons": 0.5}),
    "knobs": Node(repeat={"knob": knobs}),
    "knob": Node(label="knob"),
    "buttons": Node(repeat={"button": "button_count"}),
    "button": Node(label="button"),
    "racks": Node(repeat={"rack": "rack_count"}),
    "rack": Node(label="rack"),
})
"""Designs (``style``): a freestanding ``range`` (cooktop, optional storage drawer), a range with a
``warming`` drawer (a heated drawer with a bar handle and its own knob), a built-in ``wall`` oven and a
``double_wall`` oven (two ovens stacked, each with its own door and racks). A cooktop exists on the ranges
only. Real sizes: 30 in ranges 0.76 x 0.64-0.71 x 0.91-0.94 m, warming drawers 0.13-0.18 m high
(GE JB735, Frigidaire FGEF3036 spec sheets); double wall ovens 1.24-1.31 m high (GE JKD5000, Bosch
HBL8651UC installation guides)."""

PARAMS = (
    Float("width", "overall width (Y)", "m", *R["width"]),
    Float("depth", "body depth incl. the door, excl. the handle (X)", "m", *R["depth"]),
    Float("height", "floor to cooktop (range) or to the top (built-in)", "m", *R["height"]),
    Float("panel_fraction", "control panel height as a fraction of the oven height above the hinge", "",
          *R["panel_fraction"]),
    Float("door_thickness", "door thickness", "m", *R["door_thickness"]),
    Float("window_margin", "door frame width around the window", "m", *R["window_margin"]),
    Float("handle_length", "door handle length as a fraction of the door width", "", *R["handle_length"]),
    Float("plinth_height", "recessed kick plinth height", "m", *R["plinth_height"]),
    Float("drawer_height", "storage drawer front height", "m", *R["drawer_height"]),
    Float("drawer_travel", "drawer opening as a fraction of its depth", "", *R["drawer_travel"]),
    Int("rack_count", "wire racks", "", 2, 4),
    Float("rack_travel", "rack pull-out as a fraction of its depth (the door must be open)", "", *R["rack_travel"]),
    Int("knob_count", "knobs; auto = burners + 1 (range) or 2-3 (built-in)", "", 2, 8, auto=True),
    Float("knob_radius", "knob radius (shrunk to fit the panel)", "m", *R["knob_radius"]),
    Choice("knob_motion", "knobs turn freely or +-pi/4", choices=("continuous", "revolute")),
    Choice("knob_style", "knob shape", choices=("ridge", "round"), weights=(0.6, 0.4)),
    Int("button_count", "push buttons under the display", "", 2, 6),
    Int("grate_count", "cooktop grates side by side; auto = 2 below 0.7 m width, else 3", "", 2, 3, auto=True),
    Float("grate_play", "grate play forward and sideways once lifted", "m", *R["grate_play"]),
    Float("grate_lift", "grate lift off the cooktop as declared (the core stops a lift-off part at a hand's lift)", "m",
          *R["grate_lift"]),
    Float("lower_height", "extra height of a double wall oven's lower oven (added to height)", "m", *R["lower_height"]),
    Float("warming_height", "warming drawer front height (a range with a warming drawer)", "m", *R["warming_height"]),
    Choice("body_finish", "casing and door material", choices=("brushed_metal", "enamel", "painted"),
           weights=(0.5, 0.3, 0.2)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
)

MATERIALS = {
    "body": "body_finish", "door": "body_finish", "door_inner": "painted:black|charcoal",
    "interior": "enamel:black|midnight|anthracite", "glass": "glass", "rack": "chrome", "handle": "handle_finish",
    "knob": "plastic:black|dark_grey|light_grey", "button": "plastic:black|dark_grey",
    "display": "rubber:deep_black", "cooktop": "enamel:black", "grate": "cast_iron",
    "burner": "brushed_metal", "cap": "enamel:black", "trim": "chrome", "feet": "rubber",
    "plinth": "painted:black|charcoal",
}

DOOR_OPENS = math.pi / 2


class OvenLayout(A.PanelNodes):
    def _body(self, pieces):
        """The body part: added by the first oven section, extended after."""
        if "body" in self.bp.parts:
            self.extend("body", pieces)
        else:
            self.add("body", "body", pieces)

    def oven(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        st = OV.stack(p["width"], p["depth"], p["height"], p["door_thickness"], design, p["panel_fraction"],
                      p["plinth_height"], p["drawer_height"], p["warming_height"], p["lower_height"])
        rng_style, double = design in ("range", "warming"), st.lower is not None
        H = st.H
        pieces, cav = OV.section((*st.xs, *st.ys), st.zs, st.z_dtop, H - OV.T, H - OV.T if rng_style else H,
                                 p["door_thickness"], keep_base=not double)
        self._body(pieces)
        if double:
            self.grow(style, **st.lower)
        bay = dict(xs=st.xs, ys=st.ys, zs=(st.z_pl, st.z_dt))
        if design == "range" and style.one("drawer"):
            self.grow(style.one("drawer"), **bay)
        elif design == "warming":
            self.grow(style.one("warming_drawer"), **bay)
        elif not double:  # a fixed drawer front with a trim line
            self.extend("body", OV.fixed_drawer_front(st))
        self.grow(node.one("door"), box=st.door)
        self.grow(node.one("racks"), cav=cav)
        front = self.grow(node.one("control_panel"), **st.panel_box)
        if not double:
            self.grow(style, xs=st.xs, ys=st.ys, z_dtop=st.z_dtop + st.gap_top, front=front, H=H)
        else:
            self.extend("body", OV.top_cover(st.xs, st.ys, H))

    def double_wall(self, node, xs, ys, zs, H):
        """The lower oven of a double wall oven: its casing, door and racks (the upper oven is the usual one)."""
        pieces, cav, door = OV.lower_section(dict(xs=xs, ys=ys, zs=zs), self.p["door_thickness"])
        self._body(pieces)
        self.grow(node.one("lower_door"), box=door)
        self.grow(node.one("lower_racks"), cav=cav)

    def lower_door(self, node, box):
        self.door(node, box, name="lower_door")

    def lower_racks(self, node, cav):
        self.racks(node, cav, prefix="lower_", door="lower_door")

    def range(self, node, xs, ys, z_dtop, front, H):
        plate, vent, area = OV.range_top(xs, ys, z_dtop, front, H)
        self.extend("body", plate)
        self.extend("body", vent)
        self.grow(node.one("cooktop"), **area, H=H)

    warming = range

    def wall(self, node, xs, ys, z_dtop, front, H):
        self.extend("body", OV.top_cover(xs, ys, H))

    def cooktop(self, node, xs, ys, H):
        """Burners in columns; with grates, one over each column."""
        pieces, columns = OV.burner_columns(xs, ys, H, OV.burners_per_grate(grates(self.p, None)))
        self.extend("body", pieces)
        if node.one("grates"):
            self.grow(node.one("grates"), xs=xs, columns=columns, H=H)

    def grates(self, node, xs, columns, H):
        for k, (kid, col) in enumerate(zip(node.of("grate"), columns, strict=True)):
            self.grow(kid, k=k, xs=xs, col=col, H=H)

    def grate(self, node, k, xs, col, H):
        """A loose cast grate: it lifts straight off its feet, then has a little play forward and sideways (a
        lift first, then free; not a slide across the cooktop). Its bars stand on 30 mm feet over the 20 mm
        burner caps, so a hand's lift frees it: role ``lift_off``, the core stops it there."""
        p = self.p
        pieces, origin, side = OV.grate(xs, col, H)
        name = self.add(f"grate_{k}", "grate", pieces)
        self.join(J.limited_floating("body", name, origin, OV.GRATE_AXES,
                                     ((0.0, p["grate_lift"]), (0.0, p["grate_play"]), (-side, side)), role="lift_off"))

    def drawer(self, node, xs, ys, zs, warming=False):
        """A storage drawer in the bay under the oven: a front and an open tray behind it, an edge pull. A
        warming drawer: an enamel tray, a bar handle like the door's and a marking strip."""
        p = self.p
        OV.drawer(xs, ys, zs, warming, p["handle_length"], p["drawer_travel"]).place(self, "drawer")

    def warming_drawer(self, node, xs, ys, zs):
        self.drawer(node, xs, ys, zs, warming=True)

    def door(self, node, box, name="door"):
        p = self.p
        self.add(name, "door", OV.door(box, p["window_margin"], p["handle_length"]))
        self.hinge("body", name, A.drop_hinge(box), upper=DOOR_OPENS)

    def racks(self, node, cav, prefix="", door="door"):
        kids = node.of("rack")
        empty = OV.free_level(self.rng, len(kids))  # one rail level stays free
        rails, slots = OV.rack_levels(cav, len(kids), empty)
        for rail in rails:
            self.extend("body", [rail])
        for k, (kid, slot) in enumerate(zip(kids, slots, strict=True)):
            self.grow(kid, k=k, **slot, prefix=prefix, door=door)

    def rack(self, node, k, xs, ys, zc, prefix="", door="door"):
        name = self.add(f"{prefix}rack_{k}", "rack", A.oven_rack(xs, ys, zc))
        # behind the door: the rack slides out only once the door lies open
        at, travel = A.rack_slide(xs, zc, self.p["rack_travel"])
        self.slide("body", name, at, upper=travel, requires_open=door)

    def control_panel(self, node, xs, ys, zs):
        """A hollow housing; knobs left and right, display and buttons in the middle. Returns the x of
        the knobs' (and buttons') front, for the cooktop layout."""
        p = self.p
        buttons = node.one("buttons")
        pieces, panel, front = OV.control_panel(xs, ys, zs, len(node.one("knobs").of("knob")),
                                                len(buttons.of("button")) if buttons else 0, p["knob_radius"],
                                                p["knob_style"])
        self.add("control_panel", "control_panel", pieces)
        self.fix("body", "control_panel")
        self.grow(node.one("knobs"), made=panel.dials)
        if buttons:
            self.grow(buttons, made=panel.buttons)
        return front

    def knobs(self, node, made):
        for kid, m in zip(node.of("knob"), made, strict=True):
            self.grow(kid, made=m)

    def knob(self, node, made):
        self.add(made.name, "knob", made.pieces)
        if self.p["knob_motion"] == "continuous":
            self.spin("control_panel", made.name, made.at, role="knob")
        else:
            self.hinge("control_panel", made.name, made.at, upper=OV.KNOB_TURN, lower=-OV.KNOB_TURN, role="knob")


PAINTED_STEEL = ("body_finish", {"painted": A.STEEL})
SUBSTRATES = {"body": PAINTED_STEEL, "door": PAINTED_STEEL, "door_inner": A.STEEL, "plinth": A.STEEL}
"""A painted casing, door and drawer, the door's inner frame and the plinth are painted steel sheet (the painted
family weighs as board): a painted wall oven weighs what an enamelled one does."""

CATEGORY = Category("oven", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, OvenLayout, MATERIALS,
                    substrates=SUBSTRATES,
                    palette=appliance)  # finishes real ovens are sold in
