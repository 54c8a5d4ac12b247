"""Monitor: a computer monitor on a fixed stand, a height-adjustable stand or a desk-mounted arm.

X is the front (the screen faces +X), Y across, Z up. The head (panel, rear housing, VESA plate) tilts on a
barrel in a fork behind it (revolute about -Y: the top goes back, 0-21 degrees), held where it is put (role
``holding``, as every positioning joint here: a friction hinge or a counterbalanced slide). Carriers: a
``fixed_stand`` (a base and a neck: tilt, on some a swivel), an ``adjustable_stand`` (a column on the base, optionally
swivelling on it, +-45 degrees; a carriage sliding up its front face 100-130 mm; optionally a portrait
``pivot`` of the head, 90 degrees, once the carriage is raised), an ``arm`` (a post on a desk plate, 1-3 links
swinging about vertical axes, optionally a portrait pivot). Optional on-screen-display keys on the panel's right
edge press into it (role ``button``). The arm's desk clamp under the desk top is not drawn: the object
stands on the desk top (z = 0) on the clamp's plate.
Parts: ``categories/parts/monitors.py`` (sizes from named products), ``displays.fork``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import monitors as M

GRAMMAR = Grammar("monitor", {
    "monitor": Node(label="screen", optional={"buttons": 0.6},
                    one_of={"fixed_stand": 0.3, "adjustable_stand": 0.45, "arm": 0.25}, choice="stand_style"),
    "fixed_stand": Node(label="stand", optional={"swivel": 0.35}),
    "adjustable_stand": Node(label="stand", required=("carriage",), optional={"swivel": 0.8, "pivot": 0.6}),
    "carriage": Node(label="carriage"),
    "swivel": Node(label="stand"),
    "arm": Node(label="stand", repeat={"arm_link": (1, 3)}, optional={"pivot": 0.6}),
    "arm_link": Node(label="arm"),
    "pivot": Node(label="head"),
    "buttons": Node(repeat={"button": "button_count"}),
    "button": Node(label="button"),
})
"""``pivot``: the head turns to portrait on the VESA plate (a separate ``head`` part); ``swivel``: the column
turns on the base."""

PARAMS = (
    Float("width", "panel width, stand excluded (monitors.WIDTH)", "m", *M.WIDTH),
    Float("height_ratio", "panel height / width", "", *M.HEIGHT_RATIO),
    Float("panel", "the panel's thickness", "m", *M.PANEL),
    Float("housing", "depth of the rear housing behind the panel", "m", *M.HOUSING),
    Float("bezel", "the display's border", "m", 0.006, 0.02),
    Float("clearance", "the screen's bottom over the base at its lowest", "m", 0.05, 0.1),
    Float("travel", "a height-adjustable stand's travel (less on a short screen: its column stays hidden)", "m",
          *M.HEIGHT_TRAVEL),
    Float("link", "an arm link's length", "m", *M.ARM["link"]),
    Float("base_width", "base plate width", "m", *M.BASE["width"]),
    Float("base_depth", "base plate depth", "m", *M.BASE["depth"]),
    Float("base_t", "base plate thickness", "m", *M.BASE["t"]),
    Choice("base_shape", "base plate shape", choices=("rect", "round")),
    Int("button_count", "on-screen-display keys on the right edge (HP E24 G4: 5)", "", 1, 5),
    Choice("finish", "housing and bezel colour", choices=("black", "white", "silver"), weights=(0.6, 0.2, 0.2)),
)

_FINISH = {"black": "plastic:black|dark_grey", "white": "plastic:white|light_grey", "silver": "plastic:light_grey"}
MATERIALS = {"body": ("finish", _FINISH), "bezel": "plastic:black|dark_grey", "display": "screen",
             "stand": "brushed_metal", "button": "plastic:black|dark_grey"}
SUBSTRATES = {"body": M.MONITOR_DENSITY, "bezel": M.MONITOR_DENSITY}
SLOTS = {k: k for k in ("body", "bezel", "display")}


class MonitorLayout(Layout):
    def monitor(self, node):
        p, style = self.p, node.choice
        stand = node.one(style)
        pivot = stand.one("pivot") is not None
        z0 = p["base_t"] + p["clearance"] if style != "arm" else M.ARM["post"][1] + M.ARM["plate"][2]
        h = M.head(p["width"], p["height_ratio"], p["panel"], p["housing"], z0, pivot)
        self.add("screen", "screen", M.panel(h, p["bezel"], SLOTS) + ([M.pivot_boss(h, "body")] if pivot else []))
        mount, axis = M.tilt_head(h, "stand")
        if not pivot:
            self.extend("screen", mount)
        parent = self.grow(stand, h=h)
        if pivot:
            self.grow(stand.one("pivot"), mount=mount)
        self.hinge(parent, "head" if pivot else "screen", axis, upper=M.TILT, role="holding")
        if pivot:  # portrait needs the corner to clear the stand: a height-adjustable head is raised first
            self.hinge("head", "screen", M.pivot_axis(h), upper=M.PIVOT, role="holding",
                       requires_open="carriage" if parent == "carriage" else None)
        if node.one("buttons"):
            self.grow(node.one("buttons"), h=h)

    def fixed_stand(self, node, h):
        p = self.p
        neck = [M.neck(h, p["base_t"], "stand")] + M.fork(h, "stand")
        plate = M.base(p["base_shape"], h, p["base_width"], p["base_depth"], p["base_t"])
        self.add("stand", "stand", [plate] + ([] if node.one("swivel") else neck))
        return self.grow(node.one("swivel"), h=h, col=neck) if node.one("swivel") else "stand"

    def adjustable_stand(self, node, h):
        p = self.p
        self.travel = M.travel(h, p["travel"])
        col, carriage, slide = M.column(h, p["base_t"], self.travel, "stand")
        plate = M.base(p["base_shape"], h, p["base_width"], p["base_depth"], p["base_t"])
        self.add("stand", "stand", [plate] + ([] if node.one("swivel") else col))
        holder = self.grow(node.one("swivel"), h=h, col=col) if node.one("swivel") else "stand"
        return self.grow(node.one("carriage"), h=h, parent=holder, pieces=carriage, slide=slide)

    def swivel(self, node, h, col):
        self.add("column", "stand", col)
        s = M.SWIVEL
        self.hinge("stand", "column", M.swivel_axis(h, self.p["base_t"]), upper=s, lower=-s, role="holding")
        return "column"

    def carriage(self, node, h, parent, pieces, slide):
        self.add("carriage", "carriage", pieces)
        self.slide(parent, "carriage", slide, upper=self.travel, role="holding")
        return "carriage"

    def arm(self, node, h):
        links = node.of("arm_link")
        xs, zs = M.arm_layout(h, len(links), self.p["link"])
        self.add("stand", "stand", M.arm_post(xs[0], zs[0] - M.ARM["beam"][0] / 2 - M.GAP, "stand"))
        parent = "stand"
        for k, kid in enumerate(links):
            parent = self.grow(kid, k=k, h=h, parent=parent, xs=xs, zs=zs, last=k == len(links) - 1)
        return parent

    def arm_link(self, node, k, h, parent, xs, zs, last):
        name = self.add(f"arm_{k}", "arm", M.arm_link(xs[k], xs[k + 1], zs[k], last, h, "stand"))
        swing = M.ARM["swing"][min(k, 1)]
        self.hinge(parent, name, M.Frame.at((xs[k], 0.0, zs[k])), upper=swing, lower=-swing, role="holding")
        return name

    def pivot(self, node, mount):
        """The VESA plate and barrel as their own part; the head turns the screen on it (joint: ``monitor``)."""
        self.add("head", "head", mount)

    def buttons(self, node, h):
        for k, kid in enumerate(node.of("button")):
            self.grow(kid, h=h, k=k)

    def button(self, node, h, k):
        key, press = M.button(h, k, "button")
        name = self.add(f"button_{k}", "button", [key])
        self.slide("screen", name, press, upper=M.BUTTON["travel"], role="button")


CATEGORY = Category("monitor", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, MonitorLayout, MATERIALS,
                    substrates=SUBSTRATES)
