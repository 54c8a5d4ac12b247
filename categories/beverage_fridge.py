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
from infmob_usd.materials.families import FAMILIES, split_spec
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import hardware


def rack_count(p, rng) -> int:
    """rack_count; a wine cooler has 3 more (6-8 slide-out shelves), an undercounter fridge 2 fewer above its
    crispers, a dual-zone cooler 1 fewer per zone"""
    extra = {"wine": 3, "undercounter": -2, "dual_zone": -1}.get(p["design"], 0)
    n = max(1, p["rack_count"] + extra)
    if p["design"] == "undercounter":  # shelves at least 8 cm apart above the crispers, below a freezer
        n = min(n, max(1, int(shelf_room(p) / 0.08 - 0.6)))
    return n


def cavity_height(p: dict) -> float:
    """Height of the cooled cavity (floor liner to ceiling liner)."""
    return size(p, p["design"])[2] - 2 * p["wall"] - 2 * A.LINER - p["feet_height"] - p["kick_height"]


def freezer_height(p: dict) -> float:
    """freezer_height, at most a fifth of the cavity"""
    return min(p["freezer_height"], 0.2 * cavity_height(p))


def shelf_room(p: dict) -> float:
    """Height an undercounter fridge's shelves share: above the crispers, below the freezer compartment."""
    return cavity_height(p) - CRISPER_H - 0.03 - (freezer_height(p) + 0.012 if p.get("has_freezer") else 0.0)


def right_rack_count(p, rng) -> int:
    """right_rack_count, 1 fewer (a dual-zone cooler's right zone, set apart from the left one: wine in one
    zone, cans in the other, e.g. Whynter BWB-3388FDS, Kalamera KRC-150BV)"""
    return max(1, p["right_rack_count"] - 1)


def size(p: dict, design: str) -> tuple[float, float, float]:
    """(width, depth, height): wine coolers and dual-zone coolers are undercounter height, 0.82-0.87 m
    (Liebherr UWTes 1672, Sub-Zero UW-24, Bosch/Haier dual-zone spec sheets); a dual-zone cooler with two doors
    is at least 0.6 m wide."""
    W, D, H = p["width"], p["depth"], p["height"]
    if design in ("wine", "dual_zone"):
        H = 0.82 + 0.05 * (H - 0.5) / 0.4
    if design == "dual_zone":
        W = max(W, 0.6)
    return W, D, H


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
    Int("bin_count", "door bins on an undercounter fridge's door", "", 2, 4),
    Int("crisper_count", "crisper drawers side by side at the bottom of an undercounter fridge", "", 1, 2),
    Int("right_rack_count", "racks of a dual-zone cooler's right zone (one fewer than this, as on the left)", "",
        3, 5),
    Int("key_count", "push keys on the control strip (has_control_panel)", "", 2, 5),
    Float("freezer_height", "height of an undercounter fridge's freezer compartment (has_freezer)", "m",
          0.09, 0.14),
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
    "bin": "plastic:white|light_grey", "wood": "wood", "button": "plastic:black|dark_grey|light_grey",
    "evaporator": "brushed_metal",
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
MULLION = 0.03  # between the zones of a dual-zone cooler
BIN_DEPTH = 0.075  # door bins (x), behind the closed door
BIN_LIFT = 0.04  # a door bin lifts this far off its hooks
CRISPER_H = 0.14  # crisper drawer height


class FridgeLayout(Layout):
    def compressor(self, xb0: float, zf: float, zk: float) -> list[g.Piece]:
        """The hermetic compressor in the machine compartment behind the kick grille (hidden, no
        collision): a steel can in the ``wire`` slot (chrome, 7850 kg/m^3) massed as a shell whose wall
        makes it :data:`COMPRESSOR_KG` with the motor inside."""
        r = 0.07
        return [A.machine_can(xb0 + 0.004 + 0.01 + r, zf + 0.004, zk - zf - 0.012, r, "wire", COMPRESSOR_KG,
                              "compressor")]

    def beverage_fridge(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = size(p, design)
        w, ft = p["wall"], p["door_thickness"]
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
        body = A.insulated_cabinet((xb0, xb1, y0, y1, zf, H), cav, zk) + self.compressor(xb0, zf, zk)
        if design == "dual_zone":  # a mullion between the zones, the doors close on it
            body.append(g.box_between([cav[0], -MULLION / 2, cav[4]], [xb1, MULLION / 2, cav[5]], "body")
                        .replace(sheet=A.FRIDGE_SHEET))
        self.add("body", "body", body)
        if ctrl:
            self.grow(ctrl, xs=(xb1, xf), ys=(y0, y1), zs=(zd[1] + GAP, H))
        self.grow(style, cav=cav, hole=hole, box=(xf - ft, xf, y0, y1, *zd), xs=(cav[0] + RACK_GAP, xb1 - 0.006))

    def glass_cooler(self, node, cav, hole, box, xs):
        self.grow(node.one("door"), box=box, hole=hole)
        self.grow(node.one(node.choice), cav=cav, hole=hole, xs=xs, margin=hole[0] - box[2])

    def wine(self, node, cav, hole, box, xs):
        self.grow(node.one("door"), box=box, hole=hole)
        self.grow(node.one("racks"), cav=cav, hole=hole, xs=xs, margin=hole[0] - box[2], wine=True)

    def undercounter(self, node, cav, hole, box, xs):
        """A solid door with bins, 1-2 crisper drawers on the cavity floor, glass shelves above them, a freezer
        compartment at the top (optional); shelves, crispers and the freezer flap stop short of the bins on the
        closed door."""
        self.grow(node.one("solid_door"), box=box, hole=hole)
        xs = (xs[0], xs[1] - BIN_DEPTH - 0.012)
        cz0 = cav[4]
        top = cz0 + CRISPER_H
        ceiling = cav[5]
        if node.one("freezer"):
            ceiling = self.grow(node.one("freezer"), cav=cav, xs=xs)
        self.grow(node.one("crispers"), cav=cav, xs=xs, zs=(cz0 + 0.004, top), margin=hole[0] - box[2])
        self.grow(node.one("racks"), cav=(*cav[:4], top + 0.03, ceiling), hole=hole, xs=xs, margin=hole[0] - box[2])

    def freezer(self, node, cav, xs):
        """A freezer compartment across the top of the cavity: an aluminium evaporator box (its floor and sides,
        fixed) and a flap over its front, hinged on its top back edge, that swings up out of the way (only with
        the door open). Returns the height below which the shelves stay."""
        cx0, _, cy0, cy1, _, cz1 = cav
        fh = freezer_height(self.p)
        xf, t = xs[1], 0.006  # the flap's front face, its thickness
        z0 = cz1 - fh
        self.extend("body", [g.box_between([cx0, cy0, z0 - 0.003], [xf - t - 0.003, cy1, z0], "evaporator")
                             .replace(sheet=0.0015),
                             *[g.box_between([cx0, y0, z0], [xf - t - 0.003, y0 + 0.003, cz1], "evaporator")
                               .replace(sheet=0.0015) for y0 in (cy0, cy1 - 0.003)]])
        self.add("freezer_flap", "flap", [
            g.box_between([xf - t, cy0 + 0.006, z0 + 0.002], [xf, cy1 - 0.006, cz1 - 0.004], "bin", bevel=0.002),
            g.box_between([xf, -0.04, z0 + 0.006], [xf + 0.006, 0.04, z0 + 0.016], "bin", bevel=0.002)])  # finger lip
        # about -Y the bottom edge swings forward and up; the pivot is behind the flap's centre of mass
        self.hinge("body", "freezer_flap", Frame.at((xf - t, 0.0, cz1 - 0.004), z=(0, -1, 0)), upper=math.pi / 2,
                   requires_open="door")
        return z0 - 0.012

    def dual_zone(self, node, cav, hole, box, xs):
        """Two glass doors meeting over the mullion, each hinged on its outer side; racks in each zone."""
        x0, x1, y0, y1, z0, z1 = box
        hl = (hole[0], hole[1], -MULLION / 2 - 0.04, hole[3])  # wide meeting stiles carry the handles
        hr = (MULLION / 2 + 0.04, hole[1], hole[2], hole[3])
        # a free edge's back corner swings ~ft^2 / 2w towards the other door: the gap between them allows it
        gc = max(GAP, (x1 - x0) ** 2 / (y1 - y0)) + 0.006
        self.grow(node.one("door"), box=(x0, x1, y0, -gc / 2, z0, z1), hole=hl, side="left")
        self.grow(node.one("right_door"), box=(x0, x1, gc / 2, y1, z0, z1), hole=hr, side="right")
        margin = hole[0] - y0
        self.grow(node.one("racks"), cav=(*cav[:3], -MULLION / 2, *cav[4:]), hole=hole, xs=xs, margin=margin)
        self.grow(node.one("right_racks"), cav=(cav[0], cav[1], MULLION / 2, *cav[3:]), hole=hole, xs=xs,
                  margin=margin, door="right_door", prefix="right_")

    def right_door(self, node, box, hole, side):
        self.door(node, box, hole, side=side, name="right_door")

    def right_racks(self, node, **kw):
        self.racks(node, **kw)

    def solid_door(self, node, box, hole):
        """An insulated door: an outer skin, a foam core, a moulded inner liner with a gasket, and bins."""
        x0, x1, y0, y1, z0, z1 = box
        # the outer skin is a steel pan (its face and flanges over the front 60 % of the edges) whatever its
        # finish: a painted or plastic family is massed as that much steel (a 2 mm skin massed as board at
        # 750 kg/m^3 made these doors 1.1-1.3 kg)
        skin = A.FRIDGE_SHEET * 7850.0 / FAMILIES[split_spec(self.p["frame_family"])[0]].density
        xp = x1 - 0.6 * (x1 - x0)
        pieces = [g.box_between([xp, y0, z0], [x1, y1, z1], "frame", bevel=0.0015).replace(sheet=skin),
                  g.box_between([x0, y0 + 0.001, z0 + 0.001], [xp + 0.002, y1 - 0.001, z1 - 0.001], "liner")
                  .replace(sheet=0.003),
                  g.panel([x0 - 0.0015, y0 + 0.006, z0 + 0.006], [x0, y1 - 0.006, z1 - 0.006], "gasket", "x",
                          holes=[(y0 + 0.02, z0 + 0.02, y1 - 0.02, z1 - 0.02)])]
        left = self._door(node, box, hole, pieces, "door", None)
        # bins behind the door, inside the opening, clear of the hinge side while the door swings
        # the free side's back corners swing out by ~(ft + depth)^2 / 2W past the cabinet wall: inset them
        free = (x1 - x0 + BIN_DEPTH) ** 2 / (2 * (y1 - y0)) + 0.02
        ya, yb = (hole[0] + BIN_DEPTH + 0.03, hole[2] - free) if left else (hole[0] + free, hole[2] - BIN_DEPTH - 0.03)
        kids = node.of("door_bin")
        pitch = (hole[3] - 0.05 - (hole[1] + 0.02)) / len(kids)
        for k, kid in enumerate(kids):
            zb = hole[1] + 0.02 + k * pitch
            self.grow(kid, k=k, xs=(x0 - BIN_DEPTH, x0 - 0.003), ys=(ya, yb), zs=(zb, zb + min(0.07, pitch - 0.04)))

    def door_bin(self, node, k, xs, ys, zs):
        """A door bin: an open moulded tray hooked on the door liner; it lifts straight up off its hooks."""
        name = self.add(f"door_bin_{k}", "bin", [pc.replace(sheet=0.003) for pc in
                                                 A.open_bin(xs, ys, zs[0], zs[1] - zs[0], "bin", t=0.003)])
        self.slide("door", name, Frame.at((xs[1], (ys[0] + ys[1]) / 2, zs[0]), z=(0, 0, 1)), upper=BIN_LIFT)

    def crispers(self, node, cav, xs, zs, margin):
        p = self.p
        kids = node.of("crisper")
        ry = min(p["width"] / 2 - math.hypot(margin, p["door_thickness"]) - 0.006, cav[3] - 0.006)
        w = (2 * ry - 0.006 * (len(kids) - 1)) / len(kids)
        for k, kid in enumerate(kids):
            ya = -ry + k * (w + 0.006)
            self.grow(kid, k=k, xs=xs, ys=(ya, ya + w), zs=zs)

    def crisper(self, node, k, xs, ys, zs):
        """A crisper drawer: a clear open bin with a front and a finger pull, sliding out along +X."""
        x0, x1 = xs
        pieces = A.open_bin((x0, x1 - 0.012), ys, zs[0], zs[1] - zs[0] - 0.004, "glass", t=0.003)
        pieces.append(g.box_between([x1 - 0.012, ys[0], zs[0]], [x1, ys[1], zs[1] - 0.004], "trim", bevel=0.002))
        name = self.add(f"crisper_{k}", "drawer", pieces)
        self.slide("body", name, Frame.at((x1, (ys[0] + ys[1]) / 2, zs[0]), z=(1, 0, 0)),
                   upper=0.7 * (x1 - x0), requires_open="door")

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
        x0, x1, y0, y1, z0, z1 = box
        self.add(name, "door", pieces)
        left = (side or p["hinge_side"]) == "left"
        self.hinge("body", name, Frame.at((x1, y0 if left else y1, z0), z=(0, 0, -1 if left else 1)),
                   upper=DOOR_OPENS)
        stile = max(0.03, (y1 - hole[2]) if left else (hole[0] - y0))
        free = y1 - stile / 2 if left else y0 + stile / 2
        at = Frame.at((x1, free, (z0 + z1) / 2), z=(1, 0, 0), x=(0, 0, 1))
        self.grow(node.one("handle"), at=at, length=p["handle_length"] * (z1 - z0), stile=stile, door=name)
        return left

    def handle(self, node, at, length, stile, door):
        self.grow(node.one(node.choice), at=at, length=length, stile=stile, door=door)

    def bar(self, node, at, length, stile, door="door"):
        h = hardware.bar_handle(length, "handle", BAR).attached("mount", to=at)
        self.extend(door, h.parts[h.root].pieces)

    def recessed(self, node, at, length, stile, door="door"):
        h = hardware.edge_pull(length, "handle", depth=0.016, lip=min(0.02, 0.6 * stile)).attached("mount", to=at)
        self.extend(door, h.parts[h.root].pieces)

    def racks(self, node, cav, hole, xs, margin, wine=False, door="door", prefix=""):
        p = self.p
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        yc = (cy0 + cy1) / 2  # a dual-zone cooler's zones are off the middle
        # the racks keep clear of the open door's hinge-side edge
        W = size(p, p["design"])[0]
        ry = min(W / 2 - abs(yc) - math.hypot(margin, p["door_thickness"]) - 0.006, (cy1 - cy0) / 2 - 0.018)
        kids = node.of("rack")
        z_top = min(cz1, hole[3] - 0.004)  # racks stay behind the glass, clear of the top rail
        pitch = (z_top - cz0) / (len(kids) + 0.6)
        hr = min(0.03, pitch - 0.02)  # rack height
        for k, kid in enumerate(kids):
            z_rail = cz0 + pitch * (k + 0.8)  # top of the ledge rails of this level
            for s in (-1, 1):  # ledge rails moulded into the side liner, under the rack's runners
                ya, yb = sorted((yc + s * (ry - 0.008), yc + s * ((cy1 - cy0) / 2 + A.LINER)))
                self.extend("body", [g.box_between([cx0, ya, z_rail - 0.008], [min(cx1 - 0.004, xs[1] + 0.002), yb, z_rail],
                                                   "liner")])  # short of the bins on a closed solid door
            self.grow(kid, k=k, xs=xs, ry=ry, zb=z_rail + RACK_GAP, hr=hr, yc=yc, wine=wine, door=door, prefix=prefix)

    def rack(self, node, k, xs, ry, zb, hr, yc=0.0, wine=False, door="door", prefix=""):
        p = self.p
        if p["rack_style"] == "glass" and not wine:
            label, pieces = "shelf", A.glass_shelf(xs, ry, zb, hr)
        else:  # a wine cooler's shelves: wire cradles with a wooden front
            pieces = A.wire_rack(xs, ry, zb, hr, float(self.rng.uniform(0.028, 0.04)))
            label, pieces = "rack", [pc.replace(material="wood") if wine and pc.material == "trim" else pc
                                     for pc in pieces]
        name = self.add(f"{prefix}rack_{k}", label, [pc.translated((0.0, yc, 0.0)) for pc in pieces])
        self.slide("body", name, Frame.at((xs[1], yc, zb), z=(1, 0, 0)), upper=p["rack_travel"] * (xs[1] - xs[0]),
                   requires_open=door)

    def divider(self, node, cav, hole, xs, margin):
        cx0, cx1, cy0, cy1, cz0, cz1 = cav
        zp = cz0 + self.p["divider_height"] * (cz1 - cz0)
        self.add("divider", "shelf", [g.box_between([cx0, cy0, zp - 0.003], [cx1 - 0.01, cy1, zp + 0.003], "glass"),
                                      g.box_between([cx1 - 0.03, cy0, zp - 0.008], [cx1 - 0.01, cy1, zp + 0.008],
                                                    "trim")])
        self.fix("body", "divider")


CATEGORY = Category("beverage_fridge", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, FridgeLayout,
                    {**MATERIALS, "frame": "frame_family"}, derive=frame_finish, palette=appliance)
