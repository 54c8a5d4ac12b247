"""Microwave: a counter-top oven with a hinged glass door, a turntable and a control panel.

X is depth (the door faces +X), Y is width, Z is up. Seen from the front, the door covers the
left part of the front and hinges at its left edge: it turns about -Z through a pivot on its
front face, so it swings outward and to the left. The control panel is a fascia on the right,
fixed to the body; its push buttons slide in along -X, its dials turn about X. The turntable (a
glass tray on a roller ring) spins about Z over a spindle in the middle of the cavity floor.
The body is a sheet casing with a front bezel and a hollow cavity liner; the door and the fascia
are a thin skin on a dark inner frame. Sizes are those of real counter-top microwaves. A combination model
has a low wire rack on its turntable or floor; an over-the-range model's two grease filters slide back.
Parts: ``categories/parts/appliance.py``, ``hardware``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials import FAMILIES
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import hardware


def dials(p, rng) -> int:
    """knob_count, or 1 beside a keypad; without one 1 or 2 (drawn): a timer dial alone (Sharp R-21LVF) or
    timer and power dials (most manual counter-top models)"""
    if p["knob_count"]:
        return p["knob_count"]
    return 1 if p["has_buttons"] else 1 + int(rng.integers(0, 2))


def size(p: dict, design: str) -> tuple[float, float, float]:
    """(width, depth, height) of a design. Counter-top models use the parameters; an over-the-range model is
    30 in wide, 0.39-0.44 m high, 0.38-0.42 m deep (GE JVM7195, Whirlpool WMH31017 spec sheets); a drawer
    microwave 24 or 30 in wide, 0.39 m high, 0.56-0.65 m deep (Sharp SMD2470AS / SMD3070AS)."""
    W, D, H = p["width"], p["depth"], p["height"]
    if design == "over_the_range":
        return 0.759, min(max(D, 0.38), 0.42), min(max(H + 0.1, 0.39), 0.44)
    if design == "drawer_model":
        return (0.606 if W < 0.53 else 0.759), 0.56 + 0.09 * (D - 0.32) / 0.14, 0.39
    return W, D, H


KEYPAD_ROWS = 6
"""Counter-top keypads are grids of three columns: a 10-key number pad (four rows: 1-9, then 0 between
two function keys) under one or two rows of function keys, e.g. Panasonic NN-SN686S, GE JES1657SRSS,
Toshiba ML-EM34P owner's manuals: 3-6 rows of three. Below four rows it is a function-key panel with
the time set by a dial."""


def key_rows(p: dict) -> int:
    """button_rows; up to three always fit (the layout shrinks keys to 50 %), a fourth to sixth row only
    where the panel holds it with keys at 65 % of button_height or more (a drawer model's strip: 4 rows)"""
    rows = p["button_rows"]
    if rows <= 3:
        return rows
    design = p["design"]
    if design == "drawer_model":
        return min(rows, 4)
    W, _, H = size(p, design)
    ph = H - (VENT if design == "over_the_range" else 0.0) - p["feet_height"] - 2 * EDGE
    pw = p["panel_fraction"] * W
    n_dials = dials(p, None) if p["has_knob"] else 0
    release = p["door_opener"] == "release_button" and design in ("turntable", "flatbed")
    f = 0.65
    kr, bh = min(p["knob_radius"], 0.38 * pw) * f, p["button_height"] * f
    dh = min(max(0.12 * ph, 0.022), 0.04) * f
    fixed = [dh] + [2 * kr + 0.012] * n_dials + ([RELEASE_H] if release else [])
    while rows > 3 and sum(fixed) + rows * 1.7 * bh + 0.008 * (len(fixed) + rows - 1) > ph - 2 * PANEL_MARGIN:
        rows -= 1
    return rows


def key_count(p: dict) -> int:
    """Push keys: three a row over :func:`key_rows` rows, the bottom row three keys or two wide ones
    (``bottom_keys``: Stop/Cancel and Start as two wide keys under the number pad, as on GE JES1072 and
    Panasonic NN-ST66 keypads)"""
    return 3 * key_rows(p) - (3 - p["bottom_keys"])


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
    Float("width", "overall width (Y)", "m", 0.44, 0.62),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.32, 0.46),
    Float("height", "overall height incl. the feet (Z)", "m", 0.25, 0.36),
    Float("panel_fraction", "control panel width as a fraction of the width", "", 0.2, 0.4),
    Float("wall", "casing sheet thickness", "m", 0.003, 0.006),
    Float("door_thickness", "door thickness", "m", 0.03, 0.045),
    Float("window_margin", "door frame width around the window (hinge side, top, bottom)", "m", 0.025, 0.055),
    Float("plate_fraction", "turntable diameter as a fraction of the largest that fits", "", 0.8, 0.95),
    Int("button_rows", "rows of three push buttons (4-6: a number pad with function keys, where it fits)", "",
        1, KEYPAD_ROWS),
    Int("bottom_keys", "keys in the keypad's bottom row: three, or two wide ones (Stop/Cancel, Start)", "", 2, 3),
    Float("rack_height", "a combination model's wire rack: height of its grid over what it stands on", "m",
          0.03, 0.09),
    Float("button_height", "push button height (Z); press depth is 1/8 of it", "m", 0.012, 0.02),
    Choice("button_shape", "push button shape", choices=("rect", "round"), weights=(0.65, 0.35)),
    Int("knob_count", "dials; auto = 2 without push buttons, else 1", "", 1, 2, auto=True),
    Float("knob_radius", "dial radius (capped at 0.38 x panel width)", "m", 0.016, 0.028),
    Float("handle_length", "door handle length as a fraction of the door height", "", 0.45, 0.8),
    Choice("body_finish", "casing material", choices=("painted", "brushed_metal", "plastic"),
           weights=(0.45, 0.3, 0.25)),
    Choice("door_finish", "door frame and panel: match the casing or contrast (plastic)",
           choices=("match", "contrast")),
    Choice("interior_finish", "cavity liner material", choices=("enamel", "painted")),
    Choice("handle_finish", "door handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("feet_height", "rubber feet height", "m", 0.006, 0.015),
)

MATERIALS = {
    "body": "body_finish", "door": "plastic", "interior": "interior_finish", "glass": "glass", "plate": "glass:clear",
    "roller": "plastic", "button": "plastic", "knob": "plastic", "handle": "handle_finish", "door_inner": "rubber",
    "display": "rubber", "feet": "rubber", "trim": "chrome", "filter": "brushed_metal", "rack": "chrome",
}

DOOR_OPENS = math.pi / 2
STEEL_SHEET = 0.0006  # m: casing and cavity liner are 0.5-0.7 mm steel sheet under any finish
TRANSFORMER = (0.09, 0.075)  # m, depth and height of the HV transformer's laminated core: 2.5-4 kg
# with its windings (microwave HV transformers weigh 2.5-4 kg: service-part listings, e.g. Samsung DE26-00126A)


def steel_sheet(family: str) -> float:
    """The sheet (m) a casing piece of ``family`` is massed with so it weighs as :data:`STEEL_SHEET`
    of steel: a painted or plastic-clad casing is still a steel box."""
    return STEEL_SHEET * 7850.0 / FAMILIES[family].density


def steel_casing(p: dict, casing: list, cav, box, t: float) -> list:
    """The casing massed as steel sheet, with the high-voltage transformer on its floor in the bay
    beside the cavity (hidden) where there is one."""
    xb, y1, zc0 = box
    sheets = {"body": steel_sheet(p["body_finish"]), "interior": steel_sheet(p["interior_finish"])}
    casing = [pc.replace(sheet=sheets[pc.material]) if pc.material in sheets else pc for pc in casing]
    bay = (cav[3] + A.LINER + 0.004, y1 - t - 0.004)
    if bay[1] - bay[0] > 0.03:
        side = min(0.08, bay[1] - bay[0])
        ym = (bay[0] + bay[1]) / 2
        x0 = xb + t + 0.02
        core = g.box_between([x0, ym - side / 2, zc0 + t],
                             [x0 + TRANSFORMER[0], ym + side / 2, zc0 + t + TRANSFORMER[1]],
                             "trim", name="transformer").replace(wall=0.0)
        casing.append(core)
    return casing
EDGE = 0.002  # door and fascia stop this far inside the casing's top and bottom
LINER_IN = 0.012  # the cavity liner sits this far inside the casing walls
BACK_ROOM = 0.02  # behind the cavity
BEZEL_SIDE = 0.03  # bezel beside the cavity, on the door's free side
HANDLE_ROOM = {"bar": 0.06, "recessed": 0.045}  # door frame on the free side, where the handle goes
PULL = dict(standoff=0.025, bar_radius=0.0065, post_radius=0.0052, inset=0.02)  # a bar pull on the door
RELEASE_H = 0.022  # door release button height
PANEL_MARGIN = 0.02  # free fascia above the first item and below the last
VENT = 0.045  # over-the-range: the vent grille band over the door and the panel
STRIP = 0.075  # drawer microwave: the control strip above the drawer


class MicrowaveLayout(A.PanelNodes):
    def microwave(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = size(p, design)
        t, ft = p["wall"], p["door_thickness"]
        if design == "drawer_model":
            return self._drawer_model(node, style, W, D, H)
        vent = VENT if design == "over_the_range" else 0.0
        y0, y1 = -W / 2, W / 2
        zc0, zc1 = p["feet_height"], H
        zd = (zc0 + EDGE, zc1 - vent - EDGE)  # door and panel
        panel_w = p["panel_fraction"] * W
        door_w = W - panel_w
        # the door's back corner on its free edge swings out by ~ft^2 / (2 width) in +Y
        gap_dp = max(0.003, 0.02 * door_w) + ft * ft / (2 * door_w) + 0.001
        yd1 = y1 - panel_w - gap_dp
        gap_door = max(0.003, 0.02 * min(yd1 - y0, zd[1] - zd[0]))
        xd1 = D / 2  # door and panel front face
        xf = xd1 - ft - gap_door  # body front face (bezel)
        xb = -D / 2
        cav = (xb + t + BACK_ROOM, xf - A.BEZEL, y0 + t + LINER_IN, yd1 - BEZEL_SIDE, zc0 + t + LINER_IN,
               min(zc1 - t - LINER_IN, zd[1] - 0.03))
        self.add("body", "body", steel_casing(p, A.casing((xb, xf, y0, y1, zc0, zc1), cav, t,
                                                          min(0.014, 0.6 * zc0 + 0.006)), cav, (xb, y1, zc0), t))
        door = style.one("door") or style.one("otr_door")
        self.grow(style, cavity=cav, door=dict(ys=(y0, yd1), zs=zd, x_front=xd1), box=(xb, xf, xd1, y0, y1, zc0, zc1))
        self.grow(node.one("control_panel"), xs=(xf, xd1), ys=(y1 - panel_w, y1), zs=zd,
                  release=door.one("release_button"))

    def turntable(self, node, cavity, door, box):
        self.grow(node.one("plate"), cavity=cavity)
        self.grow(node.one("door"), **door)

    def flatbed(self, node, cavity, door, box):
        """No turntable: a fixed ceramic floor over the antenna (Panasonic inverter flatbed models)."""
        cx0, cx1, cy0, cy1, cz0, _ = cavity
        self.extend("body", [g.box_between([cx0 + 0.01, cy0 + 0.01, cz0], [cx1 - 0.01, cy1 - 0.01, cz0 + 0.005],
                                           "plate", bevel=0.002)])
        self.grow(node.one("door"), **door)
        if rack := node.one("rack"):
            r = min(cx1 - cx0, cy1 - cy0) / 2 - 0.02
            self.grow(rack, parent="body", center=((cx0 + cx1) / 2, (cy0 + cy1) / 2), z0=cz0 + 0.005, radius=r,
                      room=cavity[5] - cz0 - 0.005)

    def over_the_range(self, node, cavity, door, box):
        """A turntable, a door with a bar handle, a vent grille over the door and panel, and under the
        body two grease filters and a cooktop light (decor on the casing)."""
        xb, xf, xd1, y0, y1, zc0, zc1 = box
        self.grow(node.one("plate"), cavity=cavity)
        self.grow(node.one("otr_door"), **door)
        zv0 = zc1 - VENT + 0.004
        grille = [g.box_between([xf - 0.001, y0 + 0.004, zv0], [xd1, y1 - 0.004, zc1 - 0.002], "door", bevel=0.002)]
        n = int((y1 - y0 - 0.1) / 0.012)
        grille += [g.box_between([xd1, y0 + 0.05 + k * 0.012, zv0 + 0.01], [xd1 + 0.0008, y0 + 0.056 + k * 0.012,
                                                                              zc1 - 0.012], "display")
                   for k in range(n)]
        grille.append(g.box_between([xf - 0.09, -0.04, zc0 - 0.002], [xf - 0.04, 0.04, zc0], "glass"))  # cooktop light
        self.extend("body", grille)
        w = 0.28 * (y1 - y0)
        for k, (kid, yc) in enumerate(zip(node.of("filter"), (-0.25 * (y1 - y0), 0.25 * (y1 - y0)), strict=True)):
            self.grow(kid, k=k, box=(xb + 0.08, xf - 0.04, yc - w / 2, yc + w / 2, zc0))

    def filter(self, node, k, box):
        """A grease filter in the body's bottom: it slides 25 mm back in its track before it drops out
        (GE JVM7195, Whirlpool WMH31017 owner's manuals: "slide the filter to the rear, pull down")."""
        x0, x1, ya, yb, zc0 = box
        tab = min(0.009, zc0 - 0.0015)  # a finger tab under its front edge, clear of the ground
        frame = [g.box_between([x0, ya, zc0 - 0.0045], [x1, yb, zc0 - 0.002], "filter").replace(sheet=0.0004),
                 g.box_between([x1 - 0.012, (ya + yb) / 2 - 0.02, zc0 - tab], [x1 - 0.004, (ya + yb) / 2 + 0.02,
                                                                              zc0 - 0.0044], "filter")]
        name = self.add(f"filter_{k}", "filter", frame)
        self.slide("body", name, Frame.at((x1, (ya + yb) / 2, zc0 - 0.002), z=(-1, 0, 0)), upper=0.025)

    def otr_door(self, node, ys, zs, x_front):
        self._door(node, ys, zs, x_front, "bar")

    def drawer_model(self, node, cav, box):
        self.grow(node.one("drawer"), cav=cav, box=box)

    def _drawer_model(self, node, style, W, D, H):
        """A drawer microwave: a casing with a wide opening, a drawer (front, open tray, cavity liner) that
        slides out along +X, a control strip above it (display, buttons, dials) on the body."""
        p = self.p
        t, ft = p["wall"], p["door_thickness"]
        y0, y1 = -W / 2, W / 2
        zc0, zc1 = p["feet_height"], H
        xd1, xb = D / 2, -D / 2
        xf = xd1 - ft - 0.004
        zt = zc1 - STRIP  # drawer top
        cav = (xb + t + BACK_ROOM, xf - A.BEZEL, y0 + t + LINER_IN, y1 - t - LINER_IN, zc0 + t + LINER_IN,
               zt - 0.02)
        self.add("body", "body", steel_casing(p, A.casing((xb, xf, y0, y1, zc0, zc1), cav, t,
                                                          min(0.014, 0.6 * zc0 + 0.006)), cav, (xb, y1, zc0), t))
        self.grow(style, cav=cav, box=(xf, xd1, y0, y1, zc0 + EDGE, zt - 0.003))
        self.grow(node.one("control_panel"), xs=(xf, xd1), ys=(y0 + EDGE, y1 - EDGE), zs=(zt + 0.003, zc1 - EDGE),
                  release=None)

    def drawer(self, node, cav, box):
        p = self.p
        xf, xd1, y0, y1, z0, z1 = box
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        c = 0.004  # the tray inside the cavity liner
        tray = (cx0 + 0.02, cy0 + c, cy1 - c, cz0 + c, cz1 - c)
        pieces = A.storage_drawer((xf + 0.003, xd1, y0, y1, z0, z1), tray, wall=0.004)
        pieces = [pieces[0].replace(material="body")] + [pc.replace(material="interior") for pc in pieces[1:]]
        # front and tray are 0.6 mm steel sheet like the casing and liner, under any finish (a painted family is
        # massed as board: painted drawers weighed 0.9 kg; 0.8 mm enamelled ones 7.9 kg)
        sheets = {"body": steel_sheet(p["body_finish"]), "interior": steel_sheet(p["interior_finish"])}
        pieces = [pc.replace(sheet=sheets[pc.material]) for pc in pieces]
        pull = hardware.edge_pull(p["handle_length"] * (y1 - y0), "handle", depth=0.014, lip=0.016).attached(
            "mount", to=Frame.at((xd1, 0.0, z1 - 0.02), z=(1, 0, 0), x=(0, 1, 0)))
        hole = (y0 + 0.12 * (y1 - y0), z0 + 0.05, y1 - 0.12 * (y1 - y0), z1 - 0.05)
        window = g.box_between([xd1, hole[0], hole[1]], [xd1 + 0.001, hole[2], hole[3]], "glass")
        self.add("drawer", "drawer", pieces + [window] + list(pull.parts[pull.root].pieces))
        self.slide("body", "drawer", Frame.at((xd1, 0.0, z0), z=(1, 0, 0)), upper=0.85 * (xf - tray[0]))

    def plate(self, node, cavity):
        cx0, cx1, cy0, cy1, cz0, _ = cavity
        c = ((cx0 + cx1) / 2, (cy0 + cy1) / 2)
        r_fit = min(cx1 - cx0, cy1 - cy0) / 2
        radius = self.p["plate_fraction"] * (r_fit - max(0.004, 0.04 * r_fit))
        self.extend("body", [A.spindle(c, cz0)])
        self.add("plate", "plate", A.turntable(c, cz0, radius))
        self.spin("body", "plate", Frame.at((*c, cz0)), role="turntable")
        if rack := node.one("rack"):  # on the tray's floor, inside its rim
            self.grow(rack, parent="plate", center=c, z0=cz0 + A.TRAY_TOP, radius=radius - 0.012,
                      room=cavity[5] - cz0 - A.TRAY_TOP)

    def rack(self, node, parent, center, z0, radius, room):
        """A low wire rack: a square grid inscribed in ``radius`` on four legs, fixed to what it stands on."""
        h = min(self.p["rack_height"], 0.45 * room)
        self.add("rack", "rack", A.stand_rack(center, z0, radius / math.sqrt(2), h))
        self.fix(parent, "rack")

    def door(self, node, ys, zs, x_front):
        self._door(node, ys, zs, x_front, node.choice)

    def _door(self, node, ys, zs, x_front, opener):
        p = self.p
        skin, inner = ("body", "door_inner") if p["door_finish"] == "match" else ("door", "door")
        m = p["window_margin"]
        m_free = max(1.5 * m, HANDLE_ROOM.get(opener, 0.0))
        hole = (ys[0] + m, zs[0] + 1.15 * m, ys[1] - m_free, zs[1] - m)
        self.add("door", "door", A.glazed_door(x_front, p["door_thickness"], ys, zs, hole, skin, inner,
                                                   A.inner_sheet(MATERIALS[inner])))
        # hinged on its front face at the left edge: about -Z it swings out (+X) and to the left
        self.hinge("body", "door", Frame.at((x_front, ys[0], zs[0]), z=(0, 0, -1)), upper=DOOR_OPENS)
        at = Frame.at((x_front, ys[1], (zs[0] + zs[1]) / 2), z=(1, 0, 0), x=(0, 0, 1))
        if node.kind == "otr_door":
            self.bar(node, at=at, length=p["handle_length"] * (zs[1] - zs[0]))
        elif opener != "release_button":
            self.grow(node.one(opener), at=at, length=p["handle_length"] * (zs[1] - zs[0]))

    def bar(self, node, at, length):
        size = hardware.HandleSize(**PULL)
        handle = hardware.bar_handle(length, "handle", size).attached("mount", to=at.moved(dy=0.03))
        self.extend("door", handle.parts[handle.root].pieces)

    def recessed(self, node, at, length):
        handle = hardware.edge_pull(length, "handle", depth=0.014, lip=0.016).attached("mount", to=at.moved(dy=0.014))
        self.extend("door", handle.parts[handle.root].pieces)

    def control_panel(self, node, xs, ys, zs, release):
        p = self.p
        xf, xp = xs  # back and front face of the fascia
        ya, yb = ys
        pw, ph = yb - ya, zs[1] - zs[0]
        yc = (ya + yb) / 2
        buttons, knob = node.one("buttons"), node.one("knob")
        n_dials = len(knob.of("dial")) if knob else 0
        n_keys = len(buttons.of("button")) if buttons else 0
        rows = -(-n_keys // 3)
        display = bool(buttons) or not n_dials
        keypad = not buttons and not n_dials  # a flat membrane keypad instead
        bh, kr = p["button_height"], min(p["knob_radius"], 0.38 * pw)
        dh = min(max(0.12 * ph, 0.022), 0.04)
        if pw > 2 * ph:  # a drawer microwave's control strip: everything side by side
            panel = self._strip(xp, ys, zs, n_keys, n_dials, keypad)
            return self._panel_part(node, xs, ys, zs, panel, buttons, release, knob)

        def heights(f):
            return ([dh * f] if display else []) + [1.7 * bh * f] * rows + ([0.3 * ph] if keypad else []) + \
                [2 * kr * f + 0.012] * n_dials + ([RELEASE_H] if release else [])

        avail = ph - 2 * PANEL_MARGIN
        f = 1.0  # shrink buttons, dials and display together on a short panel
        while f > 0.5 and sum(heights(f)) + 0.008 * (len(heights(f)) - 1) > avail:
            f *= 0.95
        gap = min(0.014, max(0.006, (avail - sum(heights(f))) / (len(heights(f)) + 1)))
        bh, kr, dh = bh * f, kr * f, dh * f
        panel = A.Panel()
        z = zs[1] - PANEL_MARGIN  # top of the next item
        if display:
            panel.decor.append(g.box_between([xp - 0.001, yc - 0.39 * pw, z - dh],
                                             [xp + 0.0015, yc + 0.39 * pw, z], "display"))
            z -= dh + gap
        if buttons:
            z = self._button_grid(panel, xp, yc, pw, z, bh, gap, n_keys)
        if keypad:
            panel.decor.append(g.box_between([xp - 0.001, ya + 0.12 * pw, z - 0.3 * ph],
                                             [xp + 0.001, yb - 0.12 * pw, z], "display"))
            z -= 0.3 * ph + gap
        z_floor = zs[0] + PANEL_MARGIN + (RELEASE_H + gap if release else 0.0)
        if release:
            rw, zr = 0.62 * pw, zs[0] + PANEL_MARGIN + RELEASE_H / 2
            half = (rw / 2, RELEASE_H / 2)
            panel.holes.append(A.hole_around(yc, zr, half))
            piece = g.box_between([xp - A.BEHIND, yc - half[0], zr - half[1]], [xp + 0.006, yc + half[0], zr + half[1]],
                                    "button", bevel=0.003)
            panel.buttons.append(("door_release", piece, Frame.at((xp + 0.006, yc, zr), z=(-1, 0, 0)), RELEASE_H / 8,
                                  release))
        if n_dials:
            span = (z - z_floor) / n_dials
            for k in range(n_dials):
                zk = z - span * (k + 0.5)
                r_k = min(kr * (1.0 if k == 0 else float(self.rng.uniform(0.8, 0.95))), 0.5 * span - 0.004)
                style = list(A.DIALS)[int(self.rng.choice(len(A.DIALS), p=list(A.DIALS.values())))]
                stem = max(0.003, 0.2 * r_k)
                panel.holes.append(A.hole_around(yc, zk, (stem, stem)))
                axis = Frame.at((xp, yc, zk), z=(1, 0, 0))
                panel.dials.append((f"knob_{k}", A.dial(xp, yc, zk, r_k, stem, style), axis))
        return self._panel_part(node, xs, ys, zs, panel, buttons, release, knob)

    def _strip(self, xp, ys, zs, n_keys, n_dials, keypad):
        """A horizontal control strip: a display on the left, the push buttons in a grid of one or two
        rows in the middle, the dials on the right (a drawer microwave's angled fascia, flattened)."""
        p = self.p
        (ya, yb), (za, zb) = ys, zs
        ph, zc = zb - za, (za + zb) / 2
        panel = A.Panel()
        panel.decor.append(g.box_between([xp - 0.001, ya + 0.04, zc - 0.3 * ph], [xp + 0.0015, ya + 0.2, zc + 0.3 * ph],
                                         "display"))
        y = ya + 0.23
        if n_keys:
            n = n_keys
            nrow = min(-(-n // 3), 2)
            ncol = -(-n // nrow)
            room = yb - 0.03 - n_dials * (2 * min(p["knob_radius"], 0.4 * ph - 0.004) + 0.02) - y - 0.01
            wide = 1.8 if p["button_shape"] == "rect" else 1.0  # key width / height
            bh = min(p["button_height"], (ph - 0.02 - (nrow - 1) * 0.008) / nrow,
                     (room / ncol - 2 * A.CLEAR - 0.008) / wide)  # the grid fits beside the dials
            half = (0.9 * bh, bh / 2) if p["button_shape"] == "rect" else (bh / 2, bh / 2)
            pitch_y, pitch_z = 2 * half[0] + 2 * A.CLEAR + 0.008, bh + 0.008
            proud = 0.3 * bh + 0.002
            for k in range(n):
                r, c = divmod(k, ncol)
                yk, zk = y + half[0] + c * pitch_y, zc + (0.5 * (nrow - 1) - r) * pitch_z
                panel.holes.append(A.hole_around(yk, zk, half))
                panel.buttons.append((f"button_{r}_{c}", A.push_button(xp, yk, zk, half, p["button_shape"], proud),
                                      Frame.at((xp + proud, yk, zk), z=(-1, 0, 0)), half[1] / 4, None))
            y += ncol * pitch_y + 0.01
        if keypad:
            panel.decor.append(g.box_between([xp - 0.001, y, zc - 0.3 * ph], [xp + 0.001, y + 0.12, zc + 0.3 * ph],
                                             "display"))
        for k in range(n_dials):
            r_k = min(p["knob_radius"], 0.4 * ph - 0.004)
            yk = yb - 0.03 - r_k - k * (2 * r_k + 0.02)
            stem = max(0.003, 0.2 * r_k)
            style = list(A.DIALS)[int(self.rng.choice(len(A.DIALS), p=list(A.DIALS.values())))]
            panel.holes.append(A.hole_around(yk, zc, (stem, stem)))
            panel.dials.append((f"knob_{k}", A.dial(xp, yk, zc, r_k, stem, style), Frame.at((xp, yk, zc), z=(1, 0, 0))))
        return panel

    def _panel_part(self, node, xs, ys, zs, panel, buttons, release, knob):
        p = self.p
        xf, xp = xs
        ya, yb = ys
        skin, inner = ("body", "door_inner") if p["door_finish"] == "match" else ("door", "door")
        self.add("control_panel", "control_panel", [
            g.panel([xp - A.SKIN, ya, zs[0]], [xp, yb, zs[1]], skin, "x", holes=panel.holes),
            g.panel([xf, ya, zs[0]], [xp - A.SKIN, yb, zs[1]], inner, "x", holes=panel.holes).replace(
                sheet=A.inner_sheet(MATERIALS[inner])), *panel.decor])
        self.fix("body", "control_panel")
        if buttons:
            self.grow(buttons, made=[b for b in panel.buttons if b[-1] is None])
        if release:
            self.grow(release, made=panel.buttons[-1])
        if knob:
            self.grow(knob, made=panel.dials)

    def _button_grid(self, panel, xp, yc, pw, z, bh, gap, n_keys):
        """Rows of three keys top-down; a bottom row of two holds two wide keys over the same span."""
        p = self.p
        proud = 0.3 * bh + 0.002  # a pressed button (1/8 of its height in) still stands proud
        rows = -(-n_keys // 3)
        for r in range(rows):
            zb = z - 0.85 * bh
            cols = min(3, n_keys - 3 * r)
            pitch = 0.82 * pw / cols
            for c in range(cols):
                y = yc + (c - (cols - 1) / 2) * pitch
                if p["button_shape"] == "rect":
                    half = (min(pitch - 2 * A.CLEAR - 0.005, (1.8 if cols == 3 else 2.8) * bh) / 2, bh / 2)
                else:
                    rad = min(0.6 * bh, (pitch - 2 * A.CLEAR - 0.005) / 2)
                    half = (rad, rad)
                panel.holes.append(A.hole_around(y, zb, half))
                piece = A.push_button(xp, y, zb, half, p["button_shape"], proud)
                panel.buttons.append((f"button_{r}_{c}", piece, Frame.at((xp + proud, y, zb), z=(-1, 0, 0)),
                                      half[1] / 4, None))
            z -= 1.7 * bh + gap
        return z

    release_button = A.PanelNodes.button

    def knob(self, node, made):
        for kid, d in zip(node.of("dial"), made, strict=True):
            self.grow(kid, made=d)

    def dial(self, node, made):
        name, pieces, at = made
        self.add(name, "knob", pieces)
        self.spin("control_panel", name, at, role="knob")


CATEGORY = Category("microwave", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, MicrowaveLayout, MATERIALS,
                    palette=appliance)  # finishes real microwaves are sold in
