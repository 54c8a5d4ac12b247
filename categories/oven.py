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
little sideways, lifted). Parts: ``categories/parts/appliance.py``, ``hardware``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import hardware


def grates(p, rng) -> int:
    """grate_count, or 2 below 0.7 m width, else 3"""
    return p["grate_count"] or (2 if p["width"] < 0.7 else 3)


def burners_per_grate(n: int) -> list[int]:
    """Burners under each of ``n`` grates: two, one under the middle of three."""
    return [1 if (n == 3 and k == 1) else 2 for k in range(n)]


def knobs(p, rng) -> int:
    """knob_count, or one per burner + 1 on a range (+ 1 for a warming drawer; at most 8), 2-3 on a
    built-in oven, 4-5 on a double wall oven (a mode and a temperature knob per oven)"""
    drawn = 2 + int(rng.integers(0, 2))
    if p["style"] in ("range", "warming"):
        drawn = min(8, sum(burners_per_grate(grates(p, rng))) + 1 + (p["style"] == "warming"))
    elif p["style"] == "double_wall":
        drawn = 4 + int(rng.integers(0, 2))
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
    Float("width", "overall width (Y)", "m", 0.5, 0.9),
    Float("depth", "body depth incl. the door, excl. the handle (X)", "m", 0.55, 0.7),
    Float("height", "floor to cooktop (range) or to the top (built-in)", "m", 0.85, 0.98),
    Float("panel_fraction", "control panel height as a fraction of the oven height above the hinge", "", 0.2, 0.4),
    Float("door_thickness", "door thickness", "m", 0.04, 0.06),
    Float("window_margin", "door frame width around the window", "m", 0.05, 0.09),
    Float("handle_length", "door handle length as a fraction of the door width", "", 0.6, 0.9),
    Float("plinth_height", "recessed kick plinth height", "m", 0.03, 0.07),
    Float("drawer_height", "storage drawer front height", "m", 0.1, 0.16),
    Float("drawer_travel", "drawer opening as a fraction of its depth", "", 0.55, 0.75),
    Int("rack_count", "wire racks", "", 2, 4),
    Float("rack_travel", "rack pull-out as a fraction of its depth (the door must be open)", "", 0.5, 0.75),
    Int("knob_count", "knobs; auto = burners + 1 (range) or 2-3 (built-in)", "", 2, 8, auto=True),
    Float("knob_radius", "knob radius (shrunk to fit the panel)", "m", 0.016, 0.026),
    Choice("knob_motion", "knobs turn freely or +-pi/4", choices=("continuous", "revolute")),
    Choice("knob_style", "knob shape", choices=("ridge", "round"), weights=(0.6, 0.4)),
    Int("button_count", "push buttons under the display", "", 2, 6),
    Int("grate_count", "cooktop grates side by side; auto = 2 below 0.7 m width, else 3", "", 2, 3, auto=True),
    Float("grate_play", "grate play forward and sideways once lifted", "m", 0.015, 0.04),
    Float("grate_lift", "grate lift off the cooktop: clear of the burner caps (20 mm) and a hand under it", "m",
          0.06, 0.12),
    Float("lower_height", "extra height of a double wall oven's lower oven (added to height)", "m", 0.34, 0.4),
    Float("warming_height", "warming drawer front height (a range with a warming drawer)", "m", 0.13, 0.18),
    Choice("body_finish", "casing and door material", choices=("brushed_metal", "enamel", "painted"),
           weights=(0.5, 0.3, 0.2)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
)

MATERIALS = {
    "body": "body_finish", "door": "body_finish", "door_inner": "painted:black|charcoal",
    "interior": "enamel:black|cobalt", "glass": "glass", "rack": "chrome", "handle": "handle_finish",
    "knob": "plastic:black|dark_grey|light_grey", "button": "plastic:black|dark_grey",
    "display": "rubber:deep_black", "cooktop": "enamel:black", "grate": "enamel:black",
    "burner": "brushed_metal", "cap": "enamel:black", "trim": "chrome", "feet": "rubber",
    "plinth": "painted:black|charcoal",
}

DOOR_OPENS = math.pi / 2
T = A.OVEN_PANEL
GAP_DOOR = 0.004  # door <-> body front
HANDLE = hardware.HandleSize(standoff=0.04, bar_radius=0.01, post_radius=0.008, inset=0.02)
HANDLE_TUBE = 0.0012  # the door handle is a tube
GRATE_GAP = 0.02  # between neighbouring grates
GRATE_SIDE = 0.006  # grate sideways play (+-), at most
BACKGUARD = 0.06  # depth of a range's control panel (backguard)
KNOB_MARGIN = 0.03  # control panel ends beside the outer knobs


PAINTED_STEEL = 7850.0 / 750.0
"""Sheet of a painted door or drawer is painted steel (7850 kg/m^3) but the painted family is massed
as board (750 kg/m^3): its sheet counts this many times thicker (a 0.8 mm steel drawer ~2-3 kg)."""


class OvenLayout(A.PanelNodes):
    def steel(self, pieces):
        """Painted sheet pieces weigh as painted steel (:data:`PAINTED_STEEL`): the door's inner frame
        (``door_inner``, always painted) and, on a painted oven, its casing-finish pieces."""
        painted = {"door_inner", "plinth"} | ({"body", "door"} if self.p["body_finish"] == "painted" else set())
        return [pc.replace(sheet=pc.sheet * PAINTED_STEEL) if pc.sheet > 0 and pc.material in painted else pc
                for pc in pieces]

    def oven(self, node):
        p = self.p
        W, D, ft = p["width"], p["depth"], p["door_thickness"]
        design = node.choice
        rng_style, double = design in ("range", "warming"), design == "double_wall"
        style = node.one(design)
        H = p["height"] + (p["lower_height"] if double else 0.0)  # floor to the cooktop or the top
        xb, xd1 = -D / 2, D / 2  # back of the body, front face of the door
        xf = xd1 - ft - GAP_DOOR  # body front plane
        y0, y1 = -W / 2, W / 2
        z_pl = p["plinth_height"]
        bay = {"warming": p["warming_height"], "double_wall": 0.016}.get(design, p["drawer_height"])
        z_dt = z_pl + bay  # drawer top (double wall: a trim band under the lower door)
        reach = HANDLE.standoff + 2 * HANDLE.bar_radius + 0.014  # the open door's handle hangs clear below
        z_h = z_dt + reach  # hinge of the (lower) door
        gap_top = 0.005 + ft * ft / (2 * 0.3)  # the door's top back edge rises ~ft^2/2h when opening
        if double:  # two equal doors, a trim strip between them, a shallow fascia on top
            panel_h = 0.35 * p["panel_fraction"]
            door_h = (H - z_h - 0.02 - 0.004 - reach - gap_top - panel_h) / 2
            z_mid = z_h + door_h + 0.02  # top of the lower oven's frame
            lower = dict(xs=(xb, xf, xd1), ys=(y0, y1), zs=(z_pl, z_dt, z_h, z_h + door_h, z_mid), H=H)
            z_h = z_mid + 0.004 + reach
            z_dtop = z_h + door_h
            base = z_mid
        else:
            panel_h = p["panel_fraction"] * (H - z_h)
            z_dtop = H - 0.045 if rng_style else H - panel_h - gap_top
            base = z_pl
        zs = (base, base if double else z_dt, (base if double else z_dt) + 0.004, z_h)
        cav = self._section((xb, xf, xd1, y0, y1), zs, z_dtop, H - T, H - T if rng_style else H, keep_base=not double)
        if double:
            self.grow(style, **lower)
        if design == "range" and style.one("drawer"):
            self.grow(style.one("drawer"), xs=(xb, xf, xd1), ys=(y0, y1), zs=(z_pl, z_dt))
        elif design == "warming":
            self.grow(style.one("warming_drawer"), xs=(xb, xf, xd1), ys=(y0, y1), zs=(z_pl, z_dt))
        elif not double:  # a fixed drawer front with a trim line
            self.extend("body", self.steel([g.box_between([xf - T, y0, z_pl], [xd1, y1, z_dt], "body", bevel=0.002)
                                            .replace(sheet=A.OVEN_SHEET),
                                            g.box_between([xd1, -0.3 * W, z_dt - 0.03],
                                                          [xd1 + 0.002, 0.3 * W, z_dt - 0.025], "trim")]))
        self.grow(node.one("door"), box=(xd1 - ft, xd1, y0 + 0.003, y1 - 0.003, z_h, z_dtop))
        self.grow(node.one("racks"), cav=cav)
        if rng_style:
            panel = ((xb, xb + BACKGUARD), (H, H + panel_h))
        else:
            panel = ((xf, xd1), (z_dtop + gap_top, H))
        front = self.grow(node.one("control_panel"), xs=panel[0], ys=(y0 + 0.003, y1 - 0.003), zs=panel[1])
        if not double:
            self.grow(style, xs=(xb, xf, xd1), ys=(y0, y1), z_dtop=z_dtop + gap_top, front=front, H=H)
        else:
            self.extend("body", self.steel([g.box_between([xb, y0, H - T], [xf - T, y1, H], "body")
                                            .replace(sheet=A.OVEN_SHEET)]))

    def _section(self, xs, zs, z_dtop, ztop, frame_top, keep_base=True):
        """One oven's casing (sides, back, floor, front frame, liner) from ``zs[0]`` up; returns its cavity.
        ``keep_base``: with the plinth and the feet (the lowest section)."""
        xb, xf, xd1, y0, y1 = xs
        ft = self.p["door_thickness"]
        z_h = zs[3]
        cav = (xb + T + 0.04, xf - T, y0 + T + 0.03, y1 - T - 0.03, z_h + max(ft + 0.015, 0.05), z_dtop - 0.05)
        pieces = A.oven_casing((xb, xf, xd1, y0, y1, ztop), zs, cav, GAP_DOOR, frame_top)
        if not keep_base:
            pieces = [pc for pc in pieces if pc.material not in ("plinth", "feet")]
        # the trim strip and the kick plinth are folded sheet too, not solid blocks (a solid 76 cm trim strip
        # weighed ~20 kg: ranges came out at 150-185 kg against 60-75 kg real)
        pieces = [pc.replace(sheet=A.OVEN_SHEET) if pc.material in ("body", "plinth") and not pc.sheet else pc
                  for pc in pieces]
        pieces = self.steel(pieces)  # a painted casing is painted steel (a painted wall oven weighed 20 kg)
        if "body" in self.bp.parts:
            self.extend("body", pieces)
        else:
            self.add("body", "body", pieces)
        return cav

    def double_wall(self, node, xs, ys, zs, H):
        """The lower oven of a double wall oven: its casing, door and racks (the upper oven is the usual one)."""
        xb, xf, xd1 = xs
        y0, y1 = ys
        z_pl, z_dt, z_h, z_top, z_mid = zs
        cav = self._section((xb, xf, xd1, y0, y1), (z_pl, z_pl, z_dt, z_h), z_top, z_mid, z_mid)
        self.grow(node.one("lower_door"), box=(xd1 - self.p["door_thickness"], xd1, y0 + 0.003, y1 - 0.003, z_h, z_top))
        self.grow(node.one("lower_racks"), cav=cav)

    def lower_door(self, node, box):
        self.door(node, box, name="lower_door")

    def lower_racks(self, node, cav):
        self.racks(node, cav, prefix="lower_", door="lower_door")

    def range(self, node, xs, ys, z_dtop, front, H):
        xb, xf, xd1 = xs
        self.extend("body", self.steel([g.box_between([xb, ys[0], H - T], [xd1, ys[1], H], "cooktop")
                                        .replace(sheet=A.OVEN_SHEET),
                                        g.box_between([xf, ys[0], z_dtop], [xd1, ys[1], H - T], "body")
                                        .replace(sheet=A.OVEN_SHEET)]))  # trim strip
        # a vent slot strip along the back of the cooktop (the oven vent of a real range)
        self.extend("body", [g.box_between([front + 0.004, y - 0.004, H], [front + 0.01, y + 0.004, H + 0.002], "trim")
                             for y in np.linspace(ys[0] + 0.08, ys[1] - 0.08, 9)])
        self.grow(node.one("cooktop"), xs=(front + 0.012 + 0.012, xd1 - 0.015), ys=(ys[0] + 0.02, ys[1] - 0.02), H=H)

    warming = range

    def wall(self, node, xs, ys, z_dtop, front, H):
        self.extend("body", self.steel([g.box_between([xs[0], ys[0], H - T], [xs[1] - T, ys[1], H], "body")
                                        .replace(sheet=A.OVEN_SHEET)]))

    def cooktop(self, node, xs, ys, H):
        """Burners in columns; with grates, one over each column."""
        p = self.p
        n = grates(p, None)
        gw = (ys[1] - ys[0] - (n - 1) * GRATE_GAP) / n
        depth = xs[1] - xs[0]
        columns = []
        for k, per in enumerate(burners_per_grate(n)):
            ga = ys[0] + k * (gw + GRATE_GAP)
            r_burn = min(gw / 2 - 0.022, 0.35 * depth / per, 0.055)
            bx = [xs[0] + depth * (j + 0.5) / per for j in range(per)]
            for j, x in enumerate(bx):
                self.extend("body", A.burner(x, ga + gw / 2, H, r_burn * (1.0 if (j + k) % 2 == 0 else 0.8)))
            columns.append(((ga, ga + gw), bx))
        if node.one("grates"):
            self.grow(node.one("grates"), xs=xs, columns=columns, H=H)

    def grates(self, node, xs, columns, H):
        for k, (kid, col) in enumerate(zip(node.of("grate"), columns, strict=True)):
            self.grow(kid, k=k, xs=xs, col=col, H=H)

    def grate(self, node, k, xs, col, H):
        """A loose cast grate: it lifts straight off its feet (clear of the burner caps), then has a little
        play forward and sideways (a lift first, then free; not a slide across the cooktop)."""
        p = self.p
        (ga, gb), bx = col
        z0 = H + 0.002
        name = self.add(f"grate_{k}", "grate", A.grate(xs, (ga, gb), z0, bx))
        side = min(GRATE_SIDE, 0.5 * GRATE_GAP - 0.004)
        self.join(J.limited_floating("body", name, ((xs[0] + xs[1]) / 2, (ga + gb) / 2, z0),
                                     ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
                                     ((0.0, p["grate_lift"]), (0.0, p["grate_play"]), (-side, side))))

    def drawer(self, node, xs, ys, zs, warming=False):
        """A storage drawer in the bay under the oven: a front and an open tray behind it, an edge pull. A
        warming drawer: an enamel tray, a bar handle like the door's and a marking strip."""
        p = self.p
        (xb, xf, xd1), (y0, y1), (z_pl, z_dt) = xs, ys, zs
        c = 0.004
        fx0, tx0 = xf + 0.003, xb + T + 0.015
        pieces = A.storage_drawer((fx0, xd1, y0 + 0.003, y1 - 0.003, z_pl + 0.002, z_dt),
                                  (tx0, y0 + T + c, y1 - T - c, z_pl + T + c, z_dt - 0.012))
        if warming:  # an enamel tray (before the painted-steel scaling: scaled, a painted oven's tray weighed 47 kg)
            pieces = [pc.replace(material="interior") if k else pc for k, pc in enumerate(pieces)]
        pieces = self.steel(pieces)
        if warming:
            size = hardware.HandleSize(standoff=0.03, bar_radius=0.008, post_radius=0.0065, inset=0.02)
            zc = (z_pl + z_dt) / 2 + 0.01
            pull = hardware.bar_handle(p["handle_length"] * (y1 - y0), "handle", size).attached(
                "mount", to=Frame.at((xd1, 0.0, zc), z=(1, 0, 0), x=(0, 1, 0)))
            pieces.append(g.box_between([xd1, -0.06, z_pl + 0.014], [xd1 + 0.0008, 0.06, z_pl + 0.02], "display"))
        else:
            pull = hardware.edge_pull(0.5 * (y1 - y0), "handle", depth=0.016, lip=0.014).attached(
                "mount", to=Frame.at((xd1, 0.0, z_dt - 0.022), z=(1, 0, 0), x=(0, 1, 0)))
        self.add("drawer", "drawer", pieces + [pc.replace(sheet=HANDLE_TUBE) if warming else pc
                                               for pc in pull.parts[pull.root].pieces])
        self.slide("body", "drawer", Frame.at((xd1, 0.0, z_pl), z=(1, 0, 0)), upper=p["drawer_travel"] * (fx0 - tx0))

    def warming_drawer(self, node, xs, ys, zs):
        self.drawer(node, xs, ys, zs, warming=True)

    def door(self, node, box, name="door"):
        p = self.p
        x0, x1, y0, y1, z0, z1 = box
        m = p["window_margin"]
        hole = (y0 + m, z0 + 1.2 * m, y1 - m, z1 - 1.6 * m)
        bar = hardware.bar_handle(p["handle_length"] * (y1 - y0), "handle", HANDLE).attached(
            "mount", to=Frame.at((x1, 0.0, z1 - 0.045), z=(1, 0, 0), x=(0, 1, 0)))
        self.add(name, "door", self.steel(A.oven_door(box, hole)) + [pc.replace(sheet=HANDLE_TUBE)
                                                         for pc in bar.parts[bar.root].pieces])
        # hinged on the front face at the bottom edge: about +Y the top falls forward (+X)
        self.hinge("body", name, Frame.at((x1, 0.0, z0), z=(0, 1, 0)), upper=DOOR_OPENS)

    def racks(self, node, cav, prefix="", door="door"):
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        kids = node.of("rack")
        levels = len(kids) + 1
        lo, hi = cz0 + 0.045, cz1 - 0.07
        rails = [lo + k * (hi - lo) / (levels - 1) for k in range(levels)]
        empty = int(self.rng.integers(0, levels))  # one rail level stays free
        w, h = A.RAIL
        for z in rails:
            for ya, yb in ((cy0, cy0 + w), (cy1 - w, cy1)):
                self.extend("body", [g.box_between([cx0 + 0.01, ya, z - h], [cx1 - 0.004, yb, z], "interior")])
        used = [z for lvl, z in enumerate(rails) if lvl != empty]
        for k, (kid, z) in enumerate(zip(kids, used, strict=True)):
            # the racks' front wire sits ~5 cm behind the door
            self.grow(kid, k=k, xs=(cx0 + 0.02, cx1 - 0.035), ys=(cy0 + 0.004, cy1 - 0.004),
                      zc=z + 0.002 + A.OVEN_RACK_R, prefix=prefix, door=door)

    def rack(self, node, k, xs, ys, zc, prefix="", door="door"):
        name = self.add(f"{prefix}rack_{k}", "rack", A.oven_rack(xs, ys, zc))
        # behind the door: the rack slides out only once the door lies open
        self.slide("body", name, Frame.at((xs[1], 0.0, zc), z=(1, 0, 0)), upper=self.p["rack_travel"] * (xs[1] - xs[0]),
                   requires_open=door)

    def control_panel(self, node, xs, ys, zs):
        """A hollow housing; knobs left and right, display and buttons in the middle. Returns the x of
        the knobs' (and buttons') front, for the cooktop layout."""
        p = self.p
        xp, (ya, yb), (za, zb) = xs[1], ys, zs
        ph, zm = zb - za, (za + zb) / 2
        kids = node.one("knobs").of("knob")
        n_k = len(kids)
        buttons = node.one("buttons")
        n_b = len(buttons.of("button")) if buttons else 0
        centre_w = (max(0.11, n_b * 0.028) + 0.03) if n_b else 0.0
        pitch = (yb - ya - 2 * KNOB_MARGIN - centre_w) / n_k
        r = min(p["knob_radius"], 0.4 * pitch, 0.5 * ph - 0.012)
        left = (n_k + 1) // 2 if n_b else n_k
        panel, front = A.Panel(), xp
        for i in range(n_k):
            y = ya + KNOB_MARGIN + (centre_w if n_b and i >= left else 0.0) + (i + 0.5) * pitch
            stem = max(0.003, 0.2 * r)
            panel.holes.append(A.hole_around(y, zm, (stem, stem)))
            pieces, reach = A.cooker_knob(xp, y, zm, r, stem, p["knob_style"])
            front = max(front, xp + reach)
            panel.dials.append((f"knob_{i}", pieces, Frame.at((xp, y, zm), z=(1, 0, 0))))
        if n_b:
            yc = ya + KNOB_MARGIN + left * pitch + centre_w / 2
            inner = centre_w - 0.03
            dh, bh = min(0.03, 0.3 * ph), min(0.016, 0.22 * ph)
            zd = zm + 0.004 + dh / 2 if ph > 0.1 else zm + bh
            panel.decor.append(g.box_between([xp - 0.001, yc - inner / 2, zd - dh / 2],
                                             [xp + 0.0015, yc + inner / 2, zd + dh / 2], "display"))
            zbt = zd - dh / 2 - 0.008 - bh / 2
            half = (min(0.02, inner / n_b - 2 * A.CLEAR - 0.004) / 2, bh / 2)
            press = max(0.003, bh / 4)
            for j in range(n_b):
                y = yc - inner / 2 + (j + 0.5) * inner / n_b
                panel.holes.append(A.hole_around(y, zbt, half))
                piece = g.box_between([xp - A.BEHIND, y - half[0], zbt - half[1]],
                                      [xp + press + 0.002, y + half[0], zbt + half[1]], "button", bevel=0.0015)
                at = Frame.at((xp + press + 0.002, y, zbt), z=(-1, 0, 0))
                panel.buttons.append((f"button_{j}", piece, at, press))
            front = max(front, xp + press + 0.002)
        self.add("control_panel", "control_panel", A.panel_housing(xs, ys, zs, panel.holes) + panel.decor)
        self.fix("body", "control_panel")
        self.grow(node.one("knobs"), made=panel.dials)
        if buttons:
            self.grow(buttons, made=panel.buttons)
        return front

    def knobs(self, node, made):
        for kid, m in zip(node.of("knob"), made, strict=True):
            self.grow(kid, made=m)

    def knob(self, node, made):
        name, pieces, at = made
        self.add(name, "knob", pieces)
        if self.p["knob_motion"] == "continuous":
            self.spin("control_panel", name, at, role="knob")
        else:
            self.hinge("control_panel", name, at, upper=math.pi / 4, lower=-math.pi / 4, role="knob")



CATEGORY = Category("oven", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, OvenLayout, MATERIALS,
                    palette=appliance)  # finishes real ovens are sold in
