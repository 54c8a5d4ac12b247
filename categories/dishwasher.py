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
Parts: ``categories/parts/appliance.py``, ``hardware``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import appliance as A
from .parts import hardware


def rack_count(p, rng) -> int:
    """rack_count; a compact counter-top model has room for one rack"""
    return 1 if p["design"] == "compact" else p["rack_count"]


def upper_racks(p, rng) -> int:
    """the racks between the lower rack and a cutlery tray (on top of three or more racks)"""
    n = rack_count(p, rng)
    return max(0, n - 1 - (n >= 3))


def trays(p, rng) -> int:
    """a cutlery tray on top of three or more racks"""
    return int(rack_count(p, rng) >= 3)


def size(p: dict, design: str) -> tuple[float, float, float]:
    """(width, depth, height): a compact counter-top model is 0.55 x 0.50 x 0.44 m (Midea MCDW6ASS,
    Farberware FDW05ASBWHA spec sheets); a double dish drawer 0.6 x 0.57 x 0.82 m (Fisher & Paykel
    DD60DCX9); a freestanding model carries a 20 mm worktop on its top."""
    W, D, H = p["width"], p["depth"], p["height"]
    if design == "compact":
        return 0.5 + 0.1 * (W - 0.44) / 0.22, 0.46 + 0.08 * (D - 0.52) / 0.14, 0.42 + 0.05 * (H - 0.76) / 0.16
    if design == "dish_drawer":
        return (0.6 if W < 0.6 else 0.6 + (W - 0.6)), min(D, 0.6), min(max(H, 0.8), 0.86)
    return W, D, H


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
    Float("width", "overall width (Y)", "m", 0.44, 0.66),
    Float("depth", "overall depth incl. the door, excl. the handle (X)", "m", 0.52, 0.66),
    Float("height", "overall height incl. the feet (Z)", "m", 0.76, 0.92),
    Float("wall", "tub wall thickness (insulation + liner)", "m", 0.018, 0.03),
    Float("door_thickness", "door thickness", "m", 0.045, 0.07),
    Float("kick_height", "kick plinth height under the door: the hinge height above the floor", "m", 0.08, 0.14),
    Float("feet_height", "levelling feet height", "m", 0.01, 0.025),
    Int("rack_count", "sliding racks", "", 1, 4),
    Float("rack_travel", "rack slide-out as a fraction of its own depth", "", 0.6, 0.8),
    Float("wire_pitch", "spacing of the rack wires", "m", 0.045, 0.07),
    Int("basket_count", "cutlery baskets in the lowest rack (has_baskets)", "", 1, 4),
    Int("tine_rows", "fold-down tine rows in the lower rack (and in each drawer's rack)", "", 2, 4),
    Int("upper_tine_rows", "fold-down tine rows in an upper rack", "", 0, 2),
    Int("cup_shelf_count", "flip-down cup shelves of an upper rack (has_cup_shelves): left, or both sides", "",
        1, 2),
    Float("basket_lift", "lift of a cutlery basket out of its rack (shortened to the rack above)", "m",
          0.03, 0.06),
    Float("handle_length", "handle length as a fraction of the width", "", 0.35, 0.7),
    Float("control_height", "control panel height (has_control_panel)", "m", 0.06, 0.1),
    Int("button_count", "push buttons on the control panel (has_buttons)", "", 2, 6),
    Float("button_size", "push button height (Z); press depth is 1/8 of it", "m", 0.012, 0.02),
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

GAP = 0.004  # door to cabinet and plinth
RACK_GAP = 0.004  # rack to rails, liner and neighbours
FASCIA = 0.012  # control panel thickness (in front of the door)
DOOR_OPENS = math.pi / 2
RACK_SHARES = {1: [1.0], 2: [1.25, 1.0], 3: [1.25, 1.0, 0.42], 4: [1.1, 0.85, 0.75, 0.4]}
"""Rack heights as shares of the usable height, bottom up (a cutlery tray on top of three or more)."""
BAR = hardware.HandleSize(standoff=0.028, bar_radius=0.007, post_radius=0.0056, inset=0.02)
HANDLE_STRIP = 0.03  # the lowest strip of a control panel carries the handle


FRONT = 0.019  # an integrated model's cabinet front panel (19 mm board)
WORKTOP = 0.02  # a freestanding model's worktop


PUMP_KG = 5.0
"""kg of the machinery in a dishwasher's base: circulation pump with motor 3-4 kg, drain pump ~0.5 kg,
sump and heater (service-part listings, e.g. Bosch 00651956 circulation pump ~3.5 kg)."""


class DishwasherLayout(A.PanelNodes):
    def steel(self, pieces: list[g.Piece]) -> list[g.Piece]:
        """A painted cabinet is painted steel sheet, but the painted family is massed as board (750 kg/m^3):
        its sheet pieces count 7850 / 750 times thicker (a painted compact model weighed 10 kg)."""
        if self.p["body_finish"] != "painted":
            return pieces
        return [pc.replace(sheet=pc.sheet * 7850.0 / 750.0) if pc.sheet > 0 and pc.material == "body" else pc
                for pc in pieces]

    def pump(self, xb0: float, xb1: float, zf: float, zh: float) -> list[g.Piece]:
        """The wash pump with its motor and the sump in the base under the tub (hidden, no collision):
        a steel can in the ``tub`` slot (stainless, 7850 kg/m^3) whose wall makes it :data:`PUMP_KG`."""
        return [A.machine_can((xb0 + xb1) / 2 - 0.04, zf + 0.006, zh - zf - 0.012, 0.06, "tub", PUMP_KG, "pump")]

    def dishwasher(self, node):
        p = self.p
        design = node.choice
        style = node.one(design)
        W, D, H = size(p, design)
        w, ft = p["wall"], p["door_thickness"]
        if design == "dish_drawer":
            geo = self._drawer_cabinet(W, D, H)
            return self.grow(style, **geo)
        if design == "freestanding":
            H -= WORKTOP
        y0, y1 = -W / 2, W / 2
        xf = D / 2  # door front face
        xb1, xb0 = xf - ft - GAP, -D / 2
        zf = p["feet_height"]
        zh = zf + (0.03 if design == "compact" else p["kick_height"])  # hinge and door bottom
        zt = H - 0.002  # door top
        cav = (xb0 + w + A.TUB_LINER, xb1, y0 + w + A.TUB_LINER, y1 - w - A.TUB_LINER, zh + 0.02, H - w - A.TUB_LINER)
        door = style.one("door")
        ctrl, handle = door.one("control_panel"), door.one("handle")
        # the top band of the door carries the control panel and the handle; racks stay below it
        band = 0.025 + (p["control_height"] if ctrl else 0.0) + (0.03 if ctrl and handle else 0.0)
        if handle and not ctrl:
            band = 0.07
        body = self.steel(A.tub_cabinet((xb0, xb1, y0, y1, zf, H), cav, zh, xf)) + self.pump(xb0, xb1, zf, zh)
        if design == "freestanding":  # a worktop over the cabinet, behind the door
            body.append(g.box_between([xb0, y0, H], [xb1, y1, H + WORKTOP], "worktop",
                                      bevel=0.004))
        self.add("body", "body", body)
        # racks: below the band and the ceiling nozzle; above the flat door's inner face and the spray arm
        top = min(cav[5] - 0.032, zt - band - 0.01)
        bottom = max(zh + ft + A.DISPENSER + 0.012, cav[4] + 0.05)
        self.grow(style, door=dict(box=(xf - ft, xf, y0, y1, zh, zt), band=band), racks=dict(cav=cav, z=(bottom, top)))

    def freestanding(self, node, door, racks):
        self.grow(node.one("door"), **door)
        self.grow(node.one("racks"), **racks)

    integrated = compact = freestanding

    def _drawer_cabinet(self, W, D, H):
        """A double dish drawer's cabinet with two bays (the body); returns where the drawers go."""
        p = self.p
        ft = p["door_thickness"]
        y0, y1 = -W / 2, W / 2
        xf, xb0 = D / 2, -D / 2
        xb1 = xf - ft - GAP
        zf = p["feet_height"]
        zk = zf + p["kick_height"]
        t = 0.012  # cabinet panels (massed as sheet)

        def sheet(lo, hi, slot="body"):
            return g.box_between(lo, hi, slot).replace(sheet=A.DISHWASHER_SHEET)

        bay = (H - zk - t - GAP) / 2
        body = [sheet([xb0, y0, zf], [xb1, y0 + t, H]), sheet([xb0, y1 - t, zf], [xb1, y1, H]),
                sheet([xb0, y0 + t, H - t], [xb1, y1 - t, H]), sheet([xb0, y0 + t, zf], [xb0 + t, y1 - t, H - t]),
                sheet([xb0 + t, y0 + t, zk - t], [xb1, y1 - t, zk]),
                sheet([xb0 + t, y0 + t, zk + bay], [xb1, y1 - t, zk + bay + t]),
                sheet([xb1 - 0.004, y0, zf + 0.004], [xf - 0.012, y1, zk - 0.004], "plinth")]
        body += [g.cylinder([x, y, 0.0], [x, y, zf], 0.015, "feet", 16) for x in (xb0 + 0.04, xb1 - 0.05)
                 for y in (y0 + 0.04, y1 - 0.04)]
        self.add("body", "body", self.steel(body))
        return dict(xs=(xb0 + t, xb1, xf), ys=(y0, y1, t), zs=(zk, bay, t))

    def dish_drawer(self, node, xs, ys, zs):
        """Two drawers (a front, an open stainless tub, a rack fixed in it), sliding out along +X."""
        (xb0t, xb1, xf), (y0, y1, t), (zk, bay, t) = xs, ys, zs
        for k, kid in enumerate(node.of("drawer")):
            za = zk + k * (bay + t) + GAP
            self.grow(kid, k=k, front=(xb1 + GAP, xf, y0 + GAP, y1 - GAP, za, za + bay - GAP),
                      tub=(xb0t + 0.015, xb1 - 0.002, y0 + t + 0.006, y1 - t - 0.006, za + 0.006, za + bay - 0.03))

    def drawer(self, node, k, front, tub):
        p = self.p
        x0, x1, y0, y1, z0, z1 = front
        tx0, tx1, ty0, ty1, tz0, tz1 = tub
        name = f"drawer_{k}"
        pieces = [g.box_between([x1 - 0.0015, y0, z0], [x1, y1, z1], "body").replace(sheet=A.DISHWASHER_SHEET),
                  g.box_between([x0, y0, z0], [x1 - 0.0015, y1, z1], "door_inner").replace(sheet=0.002),
                  *[pc.replace(sheet=A.DISHWASHER_SHEET) for pc in A.open_bin((tx0, tx1), (ty0, ty1), tz0, tz1 - tz0,
                                                                                "tub", t=0.004)]]
        h = hardware.bar_handle(p["handle_length"] * (y1 - y0), "handle", BAR).attached(
            "mount", to=Frame.at((x1, 0.0, z1 - 0.04), z=(1, 0, 0), x=(0, 1, 0)))
        self.add(name, "drawer", pieces + list(h.parts[h.root].pieces))
        self.slide("body", name, Frame.at((x1, 0.0, z0), z=(1, 0, 0)), upper=0.85 * (tx1 - tx0))
        self.grow(node.one("drawer_rack"), drawer=name, xs=(tx0 + 0.01, tx1 - 0.01), cy1=ty1 - 0.004, za=tz0 + 0.004,
                  top=tz1 - 0.01)

    def drawer_rack(self, node, drawer, xs, cy1, za, top):
        name = self.add(f"{drawer}_rack", "rack", A.dish_rack(xs, cy1, za, top, self.p["wire_pitch"], "lower",
                                                               tines=False))
        self.fix(drawer, name)
        self._tines(node, name, xs, cy1 - 0.02, za, top, 0.03)

    def _tines(self, node, rack, xs, ry, za, top, front, yh=None):
        """The fold-down tine rows of a rack, side by side across it (each in its own strip), along X from
        behind ``front`` (metres kept free at the rack's front) to its back; each folds flat about its bar
        towards -Y, into its strip, and stands leaning 6 % of its height against the fold."""
        rows = node.of("tine_row")
        if not rows:
            return
        yh = ry - 0.01 if yh is None else yh
        z = A.dish_rack_floor(za)
        strip = 2 * yh / len(rows)
        h = min(0.16, 0.85 * (top - z), strip - 0.02)
        for k, kid in enumerate(rows):
            y = -yh + k * strip + h + 0.008
            self.grow(kid, name=f"{rack}_tines_{k}", rack=rack, pieces=A.tine_row((xs[0] + 0.03, xs[1] - front), y, z,
                                                                                   h, 0.06 * h), at=(y, z))

    def tine_row(self, node, name, rack, pieces, at):
        y, z = at
        self.add(name, "tines", pieces)
        # about +X a standing tine folds towards -Y
        self.hinge(rack, name, Frame.at((0.0, y, z), z=(1, 0, 0)), upper=math.pi / 2)

    def door(self, node, box, band):
        x0, x1, y0, y1, z0, z1 = box
        integrated = self.p["design"] == "integrated"
        ctrl = node.one("control_panel")
        front = []
        if integrated:  # a shaker cabinet front on the door, below the control strip (semi-integrated)
            zt = z1 - band + 0.016 if ctrl else z1
            x2, r = x1 + FRONT, 0.07  # front face, frame rail width
            front = [g.box_between([x1, y0, z0], [x2 - 0.006, y1, zt], "front"),
                     g.box_between([x2 - 0.006, y0, z0], [x2, y0 + r, zt], "front", bevel=0.002),
                     g.box_between([x2 - 0.006, y1 - r, z0], [x2, y1, zt], "front", bevel=0.002),
                     g.box_between([x2 - 0.006, y0 + r, z0], [x2, y1 - r, z0 + r], "front", bevel=0.002),
                     g.box_between([x2 - 0.006, y0 + r, zt - r], [x2, y1 - r, zt], "front", bevel=0.002)]
        self.add("door", "door", A.layered_door(box) + front)
        self.hinge("body", "door", Frame.at((x1, 0.0, z0), z=(0, 1, 0)), upper=DOOR_OPENS)
        ctrl = node.one("control_panel")
        if ctrl:
            self.grow(ctrl, xf=x1, ys=(y0, y1), zs=(z1 - band + 0.02, z1 - 0.004), handle=bool(node.one("handle")))
        if node.one("handle"):
            z = z1 - band + 0.035 if ctrl else z1 - 0.035
            if integrated:  # a cabinet handle on the front panel's top rail
                z = (z1 - band + 0.016 if ctrl else z1) - 0.035
            at = Frame.at((x1 + (FRONT if integrated else FASCIA if ctrl else 0.0), 0.0, z), z=(1, 0, 0), x=(0, 1, 0))
            self.grow(node.one("handle"), at=at)

    def handle(self, node, at):
        self.grow(node.one(node.choice), at=at, length=self.p["handle_length"] * self.p["width"])

    def bar(self, node, at, length):
        h = hardware.bar_handle(length, "handle", BAR).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def pocket(self, node, at, length):
        h = hardware.edge_pull(length, "handle", depth=0.016, lip=0.02).attached("mount", to=at)
        self.extend("door", h.parts[h.root].pieces)

    def control_panel(self, node, xf, ys, zs, handle):
        """A fascia on the top of the door front: display on the left, push buttons on the right."""
        p = self.p
        (y0, y1), (za, zb) = ys, zs
        xp, W = xf + FASCIA, y1 - y0
        zl = za + (HANDLE_STRIP if handle else 0.0)
        zc = (zl + zb) / 2
        panel = A.Panel()
        panel.decor.append(g.box_between([xp - 0.001, y0 + 0.12 * W, zc - 0.011],
                                         [xp + 0.0015, y0 + 0.38 * W, zc + 0.011], "display"))
        buttons = node.one("buttons")
        if buttons:
            n = len(buttons.of("button"))
            bh = min(p["button_size"], zb - zl - 2 * A.CLEAR - 0.008)
            half = (min(1.6 * bh, 0.4 * W / n - 2 * A.CLEAR - 0.004) / 2, bh / 2)
            proud = 0.3 * bh + 0.002
            for k in range(n):
                y = y0 + 0.5 * W + (k + 0.5) * 0.45 * W / n
                panel.holes.append(A.hole_around(y, zc, half))
                piece = g.box_between([xp - A.BEHIND, y - half[0], zc - half[1]],
                                      [xp + proud, y + half[0], zc + half[1]], "button",
                                      bevel=0.15 * min(bh, 2 * half[0]))
                panel.buttons.append((f"button_{k}", piece, Frame.at((xp + proud, y, zc), z=(-1, 0, 0)), bh / 8))
        fascia = g.panel([xf, y0 + 0.004, za], [xp, y1 - 0.004, zb], "panel", "x", holes=panel.holes)
        self.add("control_panel", "control_panel", [fascia, *panel.decor])
        self.fix("door", "control_panel")
        if buttons:
            self.grow(buttons, made=panel.buttons)


    def racks(self, node, cav, z):
        cx0, cx1, cy0, cy1 = cav[:4]
        kids = [*node.of("lower_rack"), *node.of("rack"), *node.of("tray")]
        n = len(kids)
        shares = RACK_SHARES[n]
        span = z[1] - z[0]
        xs = (cx0 + 0.01, cx1 - 0.01)
        za = z[0]
        for k, (kid, share) in enumerate(zip(kids, shares)):
            zb = za + span * share / sum(shares)
            top = zb - (0.0 if k == n - 1 else RACK_GAP + 0.006)  # this rack's highest point
            kind = {"lower_rack": "lower", "rack": "upper", "tray": "tray"}[kid.kind]
            for s in (-1, 1):  # rails: channels on the side liners
                ya, yb = sorted((s * (cy1 - 0.013), s * (cy1 + A.TUB_LINER)))
                rail = g.box_between([cx0 + 0.03, ya, za - RACK_GAP - 0.01], [cx1 - 0.004, yb, za - RACK_GAP], "tub")
                self.extend("body", [rail])
            front = 0.03 + (0.012 + min(0.12, 0.35 * (xs[1] - xs[0])) if k == 0 and node.one("baskets") else 0.0)
            self.grow(kid, k=k, xs=xs, cy1=cy1, za=za, top=top, kind=kind, front=front)
            if k == 0 and node.one("baskets"):
                self.grow(node.one("baskets"), rack="rack_0", xs=xs, ry=cy1 - 0.02, za=za, top=top)
            za = zb

    def rack(self, node, k, xs, cy1, za, top, kind, front):
        p = self.p
        name = self.add(f"rack_{k}", "rack", A.dish_rack(xs, cy1, za, top, p["wire_pitch"], kind,
                                                         tines=kind != "lower"))
        self.slide("body", name, Frame.at((xs[1], 0.0, za), z=(1, 0, 0)), upper=p["rack_travel"] * (xs[1] - xs[0]),
                   requires_open="door")
        ry = cy1 - 0.02
        shelves = node.one("cup_shelves") if kind == "upper" else None
        w = 0.0
        if shelves:
            zc = za + A.RACK_WHEEL
            zt = zc + 0.7 * max(top - zc, 0.02) - A.DISH_WIRE  # the rack's top rim
            w = min(0.08, 0.45 * (zt - zc))
            self.grow(shelves, rack=name, xs=(xs[0] + 0.04, xs[1] - 0.04), ry=ry, z=zt - w - 0.01, w=w)
        if kind != "tray":
            self._tines(node, name, xs, ry, za, top, front, yh=ry - w - 0.03 if shelves else None)

    lower_rack = tray = rack

    def cup_shelves(self, node, rack, xs, ry, z, w):
        for k, kid in enumerate(node.of("cup_shelf")):
            self.grow(kid, k=k, rack=rack, xs=xs, ry=ry, z=z, w=w)

    def cup_shelf(self, node, k, rack, xs, ry, z, w):
        """The first on the left side wall, the second on the right; each swings down inwards to level."""
        s = -1 if k == 0 else 1
        y = s * (ry - 0.015)
        name = self.add(f"{rack}_cup_shelf_{k}", "shelf", A.cup_shelf(xs, y, z, w, s * 0.006))
        # about -X (left) or +X (right) the top swings inwards
        self.hinge(rack, name, Frame.at((0.0, y, z), z=(s, 0, 0)), upper=math.pi / 2)

    def baskets(self, node, rack, xs, ry, za, top):
        """Open cutlery baskets side by side at the front of the lowest rack, fixed to it."""
        rx0, rx1 = xs
        z0 = za + A.RACK_WHEEL + 2.6 * 0.0025 + 0.001  # on the bottom grid
        kids = node.of("basket")
        h = max(min(0.14, 0.75 * (top - z0)), 0.04)
        lift = min(self.p["basket_lift"], top - z0 - h - 0.002)
        depth = min(0.12, 0.35 * (rx1 - rx0))
        bw = min(0.12, (2 * ry - 0.02) / len(kids) - 0.004)
        for k, kid in enumerate(kids):
            y1 = ry - 0.01 - k * (bw + 0.004)
            self.grow(kid, k=k, rack=rack, pieces=A.open_bin((rx1 - 0.012 - depth, rx1 - 0.012), (y1 - bw, y1), z0, h,
                                                             "basket"), at=(rx1 - 0.012, y1 - bw / 2, z0), lift=lift)

    def basket(self, node, k, rack, pieces, at, lift):
        """A cutlery basket stands in its rack and lifts straight up out of it (below the rack above)."""
        name = self.add(f"basket_{k}", "basket", pieces)
        if lift > 0.01:
            self.slide(rack, name, Frame.at(at), upper=lift)
        else:
            self.fix(rack, name)


CATEGORY = Category("dishwasher", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DishwasherLayout, MATERIALS,
                    palette=appliance)  # finishes real dishwashers are sold in
