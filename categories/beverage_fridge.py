"""Beverage fridge: an insulated cabinet with a framed glass door and slide-out racks.

X is depth (the door faces +X), Y is width, Z is up. The cabinet stands on four levelling feet;
at the bottom of the front is a ventilation kick grille, above it the glass door, and optionally a
control strip above the door. The walls are insulated panels (massed as sheet steel) lined with a
thin plastic liner, so the cooled cavity is a real hollow. The door is a frame around a double
glass pane, hinged on one side about a vertical axis through its front face: it swings outward
0..pi/2; the handle (a bar or an edge pull) is on the free edge. Inside are 3-5 racks (wire racks
or glass shelves) sliding out along +X on ledge rails, or a fixed divider plate. The door is solid
to a robot, so a rack slides out only with the door open (``requires_open``); racks keep clear of
the open door's hinge-side edge. Parts: ``categories/parts/appliance.py``, ``hardware``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import hardware

GRAMMAR = Grammar("beverage_fridge", {
    "beverage_fridge": Node(label="body", required=("door",), optional={"control_panel": 0.6},
                            one_of={"racks": 0.8, "divider": 0.2}, choice="interior"),
    "control_panel": Node(),
    "door": Node(label="door", one_of={"bar": 0.6, "recessed": 0.4}, choice="handle_style"),
    "bar": Node(), "recessed": Node(),
    "racks": Node(repeat={"rack": "rack_count"}),
    "rack": Node(label=("rack", "shelf")),
    "divider": Node(label="shelf"),
})

PARAMS = (
    Float("width", "overall width (Y)", "m", 0.45, 0.7),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.5, 0.68),
    Float("height", "overall height incl. the feet (Z)", "m", 0.5, 0.9),
    Float("wall", "insulated wall thickness", "m", 0.035, 0.055),
    Float("door_thickness", "glass door thickness (frame depth)", "m", 0.03, 0.045),
    Float("kick_height", "height of the ventilation kick grille below the door", "m", 0.05, 0.1),
    Float("feet_height", "levelling feet height", "m", 0.008, 0.02),
    Float("control_height", "height of the control strip above the door", "m", 0.035, 0.06),
    Choice("hinge_side", "side of the door hinge, seen from the front", choices=("left", "right")),
    Float("handle_length", "handle length as a fraction of the door height", "", 0.35, 0.75),
    Int("rack_count", "sliding racks (interior = racks)", "", 3, 5),
    Choice("rack_style", "wire racks or glass shelves", choices=("wire", "glass"), weights=(0.65, 0.35)),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", 0.6, 0.85),
    Float("divider_height", "divider plate height as a fraction of the cavity height", "", 0.35, 0.65),
    Choice("body_finish", "cabinet material", choices=("painted", "brushed_metal"), weights=(0.6, 0.4)),
    Choice("door_finish", "door frame: match the cabinet or black plastic", choices=("match", "black")),
    Choice("trim_finish", "front trim of the racks", choices=("wood", "chrome", "plastic"), weights=(0.45, 0.35, 0.2)),
    Choice("handle_finish", "handle material", choices=("brushed_metal", "chrome", "plastic"),
           weights=(0.45, 0.35, 0.2)),
)

MATERIALS = {
    "body": "body_finish", "liner": "plastic:black|dark_grey|white", "glass": "glass:clear|clear_blue",
    "handle": ("handle_finish", {"plastic": "plastic:black|dark_grey"}), "trim": "trim_finish", "wire": "chrome",
    "grille": "plastic:black|dark_grey", "feet": "rubber", "display": "rubber", "gasket": "rubber",
}


def frame_finish(p: dict) -> dict:
    """The door frame matches the cabinet or is black plastic."""
    return {**p, "frame_family": p["body_finish"] if p["door_finish"] == "match" else "plastic:black"}


GAP = 0.004  # door to cabinet, control strip and kick grille
COMPRESSOR_KG = 6.0  # hermetic reciprocating compressors of small coolers weigh 5-8 kg (Embraco EMT/EMX,
# Secop TLS data sheets); the modelled machine compartment is only the kick grille's height
RACK_GAP = 0.004  # rack to rails, liner, back wall and neighbours
DOOR_OPENS = math.pi / 2
GLASS_MARGIN = 0.02  # door frame at least this wide above and below the glass
BAR = hardware.HandleSize(standoff=0.03, bar_radius=0.007, post_radius=0.0056, inset=0.02)


class FridgeLayout(Layout):
    def compressor(self, xb0: float, zf: float, zk: float) -> list[g.Piece]:
        """The hermetic compressor in the machine compartment behind the kick grille (hidden, no
        collision): a steel can in the ``wire`` slot (chrome, 7850 kg/m^3) massed as a shell whose wall
        makes it :data:`COMPRESSOR_KG` with the motor inside."""
        h = zk - zf - 0.012
        r = 0.07
        x = xb0 + 0.004 + 0.01 + r
        can = g.cylinder([x, 0.0, zf + 0.004], [x, 0.0, zf + 0.004 + h], r, "wire", 24)
        area = 2 * math.pi * r * (r + h)
        return [can.replace(convex=(), wall=COMPRESSOR_KG / (7850.0 * area), name="compressor")]

    def beverage_fridge(self, node):
        p = self.p
        W, D, H, w, ft = p["width"], p["depth"], p["height"], p["wall"], p["door_thickness"]
        y0, y1 = -W / 2, W / 2
        xf = D / 2  # door front face
        xb1, xb0 = xf - ft - GAP, -D / 2  # cabinet front and back
        zf = p["feet_height"]
        zk = zf + p["kick_height"]  # top of the kick grille
        ctrl = node.one("control_panel")
        zd = (zk + GAP, H - (p["control_height"] + GAP if ctrl else 0.0))  # door
        cav = (xb0 + w + A.LINER, xb1, y0 + w + A.LINER, y1 - w - A.LINER, zk + w + A.LINER, H - w - A.LINER)
        # the door's glass: the cavity opening grown by 3 mm, inside the door's frame
        hole = (cav[2] - 0.003, max(cav[4] - 0.003, zd[0] + GLASS_MARGIN), cav[3] + 0.003,
                min(cav[5] + 0.003, zd[1] - GLASS_MARGIN))
        self.add("body", "body", A.insulated_cabinet((xb0, xb1, y0, y1, zf, H), cav, zk) + self.compressor(xb0, zf, zk))
        if ctrl:
            self.grow(ctrl, xs=(xb1, xf), ys=(y0, y1), zs=(zd[1] + GAP, H))
        self.grow(node.one("door"), box=(xf - ft, xf, y0, y1, *zd), hole=hole)
        self.grow(node.one(node.choice), cav=cav, hole=hole, xs=(cav[0] + RACK_GAP, xb1 - 0.006), margin=hole[0] - y0)

    def control_panel(self, node, xs, ys, zs):
        self.extend("body", A.control_strip(*xs, *ys, *zs))

    def door(self, node, box, hole):
        p = self.p
        x0, x1, y0, y1, z0, z1 = box
        self.add("door", "door", A.glass_door(box, hole))
        left = p["hinge_side"] == "left"
        self.hinge("body", "door", Frame.at((x1, y0 if left else y1, z0), z=(0, 0, -1 if left else 1)),
                   upper=DOOR_OPENS)
        free = (y1 - (y1 - hole[2]) / 2) if left else (y0 + (hole[0] - y0) / 2)
        at = Frame.at((x1, free, (z0 + z1) / 2), z=(1, 0, 0), x=(0, 0, 1))
        self.grow(node.one(node.choice), at=at, length=p["handle_length"] * (z1 - z0), stile=y1 - hole[2])

    def bar(self, node, at, length, stile):
        h = hardware.bar_handle(length, "handle", BAR).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def recessed(self, node, at, length, stile):
        h = hardware.edge_pull(length, "handle", depth=0.016, lip=min(0.02, 0.6 * stile)).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def racks(self, node, cav, hole, xs, margin):
        p = self.p
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        # the racks keep clear of the open door's hinge-side edge
        ry = min(p["width"] / 2 - math.hypot(margin, p["door_thickness"]) - 0.006, cy1 - 0.018)  # half width
        kids = node.of("rack")
        z_top = min(cz1, hole[3] - 0.004)  # racks stay behind the glass, clear of the top rail
        pitch = (z_top - cz0) / (len(kids) + 0.6)
        hr = min(0.03, pitch - 0.02)  # rack height
        for k, kid in enumerate(kids):
            z_rail = cz0 + pitch * (k + 0.8)  # top of the ledge rails of this level
            for s in (-1, 1):  # ledge rails moulded into the side liner, under the rack's runners
                ya, yb = sorted((s * (ry - 0.008), s * (cy1 + A.LINER)))
                self.extend("body", [g.box_between([cx0, ya, z_rail - 0.008], [cx1 - 0.004, yb, z_rail], "liner")])
            self.grow(kid, k=k, xs=xs, ry=ry, zb=z_rail + RACK_GAP, hr=hr)

    def rack(self, node, k, xs, ry, zb, hr):
        p = self.p
        if p["rack_style"] == "glass":
            name = self.add(f"rack_{k}", "shelf", A.glass_shelf(xs, ry, zb, hr))
        else:
            name = self.add(f"rack_{k}", "rack", A.wire_rack(xs, ry, zb, hr, float(self.rng.uniform(0.028, 0.04))))
        self.slide("body", name, Frame.at((xs[1], 0.0, zb), z=(1, 0, 0)), upper=p["rack_travel"] * (xs[1] - xs[0]),
                   requires_open="door")

    def divider(self, node, cav, hole, xs, margin):
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        zp = cz0 + self.p["divider_height"] * (cz1 - cz0)
        self.add("divider", "shelf", [g.box_between([cx0, cy0, zp - 0.003], [cx1 - 0.01, cy1, zp + 0.003], "glass"),
                                      g.box_between([cx1 - 0.03, cy0, zp - 0.008], [cx1 - 0.01, cy1, zp + 0.008],
                                                    "trim")])
        self.fix("body", "divider")


CATEGORY = Category("beverage_fridge", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, FridgeLayout,
                    {**MATERIALS, "frame": "frame_family"}, derive=frame_finish, palette=appliance)
