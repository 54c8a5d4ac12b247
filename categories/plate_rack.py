"""Plate rack: a dish-drying rack with rows of prongs and ceramic plates standing in its slots.

X is the rack's length (the front end faces +X), Y its width, Z up. Along X stand
``slot_count + 1`` fences of prong pairs, so every slot is bounded by a prong pair on each side
of its plate. Three kinds of rack: ``wood`` (two rails on cross battens, dowel prongs, optional
rubber pads), ``plastic`` (a moulded tray with pegs) and ``wire`` (chrome rails on capped legs,
an arch at every fence). A plate stands upright in its slot, its axis along X, a few millimetres
above the support, and hangs from the rack by a ``limited_planar`` joint in its own plane: a lift
along +Z (gravity holds it down), a slide along Y and a turn about its own axis — moving in its
own plane it never leaves its slot. Parts: ``categories/parts/racks.py``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import racks as R


def plates(p, rng) -> int:
    """plate_count (at most slot_count), or each slot filled with chance ``fill``, at least one"""
    n = p["slot_count"]
    drawn = max(1, int((rng.random(n) < p["fill"]).sum()))
    return min(p["plate_count"], n) if p["plate_count"] else drawn


GRAMMAR = Grammar("plate_rack", {
    "plate_rack": Node(label="rack", repeat={"plate": plates},
                       optional={"feet": 0.5, "tier": 0.5, "drip_tray": 0.6, "spout": 0.6},
                       one_of={"cutlery": 0.35, "cups": 0.3, "station": 0.35}, choice="design"),
    "plate": Node(label="plate"),
    "feet": Node(),
    "tier": Node(repeat={"plate": plates}),
    "drip_tray": Node(label="tray"),
    "spout": Node(label="spout"),
    "cutlery": Node(repeat={"caddy": (1, 2)}),
    "cups": Node(repeat={"cup": (3, 10)}),
    "station": Node(repeat={"caddy": (1, 2), "cup": (2, 8)}),
    "caddy": Node(label="basket"),
    "cup": Node(one_of={"mug": 0.6, "glass": 0.4}),
    "mug": Node(label="cup"),
    "glass": Node(label="glass"),
})
"""Plates fill ``plates`` of the slots, which ones drawn per rack. ``feet`` are rubber pads under a
wood or plastic rack; a wire rack always stands on its capped legs. Beside the plates a side
board carries one or two cutlery caddies that lift out (``cutlery``), mugs and tumblers upside
down on pegs that lift off (``cups``), or caddies and cups (``station``): the three designs.
A wire or wood rack may have a second ``tier`` of prongs on four posts above the first, its own
plates in its slots (two-tier chrome drainers: Kitsure, simplehuman; two-tier bamboo dish racks);
a wire rack a ``drip_tray`` between its legs that slides out along +X to be emptied; a moulded
plastic tray a ``spout`` on its front end wall that swivels 180 degrees about Z (Rubbermaid, OXO
drainer trays)."""

PARAMS = (
    # drainers and wall plate racks have 6-12 plate slots (IKEA OSTBIT 8, simplehuman 2-tier 10-12 per tier)
    Int("slot_count", "slots (fences of prong pairs = slots + 1)", "", 3, 10),
    Int("plate_count", "plates; auto = each slot holds one with chance fill (at least one)", "", 1, 10, auto=True),
    Float("fill", "chance that a slot holds a plate (auto plate count)", "", 0.4, 0.95),
    Choice("style", "rack construction", choices=("wood", "plastic", "wire"), weights=(0.35, 0.3, 0.35)),
    Float("prong_height", "prong height above the support surface", "m", 0.08, 0.15),
    Float("prong_radius", "prong radius (a wire rack uses 0.6 of it)", "m", 0.003, 0.006),
    Float("prong_spread", "half distance between the two prongs of a pair, / plate radius", "", 0.45, 0.75),
    Float("plate_radius", "plate outer radius", "m", 0.08, 0.15),
    Float("plate_depth", "plate height (foot to rim), / plate radius", "", 0.12, 0.2),
    Float("plate_thickness", "plate wall thickness", "m", 0.0035, 0.006),
    Float("foot_fraction", "foot ring radius / plate radius", "", 0.4, 0.55),
    Float("clearance", "gap between a plate and the prongs on each side", "m", 0.003, 0.008),
    Float("base_height", "rail / tray wall / wire leg height", "m", 0.015, 0.03),
    Choice("plate_set", "plates all alike or two alternating colours", choices=("matching", "mixed")),
)

MATERIALS = {"frame": ("style", {"wire": "chrome"}), "prong": ("style", {"wire": "chrome"}), "plate": "ceramic",
             "plate_alt": "ceramic", "feet": "rubber:black|soft_black", "caddy": "plastic:white|light_grey|dark_grey",
             "cutlery": "brushed_metal", "mug": "ceramic", "glass": "glass:clear|clear_blue",
             "tray": "plastic:white|light_grey|dark_grey|black", "spout": "plastic:white|light_grey|dark_grey"}


def wire_has_legs(p: dict) -> dict:
    """A wire rack stands on its capped legs, never on pads; a moulded plastic tray carries no second tier; only
    a wire rack has a drip tray between its legs (the others are their own trays), only a plastic tray a spout."""
    wire, plastic = p["style"] == "wire", p["style"] == "plastic"
    return {**p, "has_feet": p["has_feet"] and not wire, "has_tier": p["has_tier"] and not plastic,
            "has_drip_tray": p["has_drip_tray"] and wire, "has_spout": p["has_spout"] and plastic}


class RackLayout(Layout):
    def plate_rack(self, node):
        p = self.p
        n, r = p["slot_count"], p["plate_radius"]
        rp = p["prong_radius"] * (R.WIRE if p["style"] == "wire" else 1.0)
        b = p["prong_spread"] * r
        plate0 = R.plate(r, p["plate_depth"] * r, p["plate_thickness"], p["foot_fraction"] * r, "plate")
        pts = np.vstack([plate0.vertices, *plate0.convex])
        x_lo, x_hi = pts[:, 0].min(), pts[:, 0].max()
        pitch = x_hi - x_lo + 2 * p["clearance"] + 2 * rp
        fences = (np.arange(n + 1) - n / 2) * pitch
        xs = (fences[0] - R.END, fences[-1] + R.END)
        z0 = R.PAD if node.one("feet") else 0.0  # underside of the rack body
        if p["style"] == "wood":
            pieces, zs = R.wood_rack(fences, xs, b, rp, z0, p["prong_height"], p["base_height"])
        elif p["style"] == "plastic":
            pieces, zs = R.plastic_tray(fences, xs, b, rp, z0, p["prong_height"], p["base_height"], r)
        else:
            pieces, zs = R.wire_rack(fences, xs, b, rp, p["prong_height"], p["base_height"])
        self.add("rack", "rack", pieces)
        # the side board: beyond the reach of a plate slid sideways, at the rack's foot
        design = node.one(node.choice)
        board, side = R.side_board(pieces, xs, r, len(design.of("caddy")), len(design.of("cup")),
                                   p["style"] == "wire")
        self.extend("rack", [side])
        if node.one("feet"):
            self.grow(node.one("feet"), pieces=self.bp.parts["rack"].pieces, xs=xs)
        self.grow(design, board=board)
        zc = zs + R.SEAT_GAP + r  # plate centre: its lowest point SEAT_GAP above the support
        self._plates(node.of("plate"), plate0, fences, pitch, x_lo, zc, "plate")
        if node.one("tier"):
            self.grow(node.one("tier"), rack=(fences, xs, b, rp, z0), top=zc + r + R.LIFT + R.TIER_GAP, plate0=plate0,
                      pitch=pitch, x_lo=x_lo, zc=zc)
        if node.one("drip_tray"):
            self.grow(node.one("drip_tray"), xs=xs, b=b, rp=rp)
        if node.one("spout"):
            self.grow(node.one("spout"), x=xs[1] + R.TRAY_END_WALL, z=z0)

    def _plates(self, kids, plate0, fences, pitch, x_lo, zc, prefix):
        p = self.p
        n = p["slot_count"]
        rp = p["prong_radius"] * (R.WIRE if p["style"] == "wire" else 1.0)
        slots = sorted(int(i) for i in self.rng.choice(n, size=len(kids), replace=False))
        for kid, i in zip(kids, slots):
            x_foot = fences[i] + rp + p["clearance"] - x_lo
            self.grow(kid, i=i, piece=plate0.translated((x_foot, 0.0, zc)), pivot=(fences[i] + pitch / 2, 0.0, zc),
                      prefix=prefix)

    def tier(self, node, rack, top, plate0, pitch, x_lo, zc):
        """The upper tier: the rack again, raised until its lowest member over the plates is at ``top`` (R.TIER_GAP
        above a lower plate lifted fully), on four posts that rise from the lower tier; its plates in its own
        slots. Wire: the legs (caps dropped) stand on posts over the lower legs, its cross wires are the lowest
        members (a rail's radius under the rail axis). Wood: the rails are, and the posts are dowels from the
        lower rails to the upper battens."""
        fences, xs, b, rp, z0 = rack
        p = self.p
        if p["style"] == "wire":
            pieces, zs = R.wire_rack(fences, xs, b, rp, p["prong_height"], p["base_height"])
            pieces, posts, dz = R.wire_tier(pieces, zs, top, xs, b, rp)
        else:
            pieces, zs = R.wood_rack(fences, xs, b, rp, z0, p["prong_height"], p["base_height"])
            dz = top - (zs - p["base_height"])
            bw = R.BATTEN_W
            least, share = R.TIER["dowel"]
            posts = R.tier_posts((xs[0] + bw / 2, xs[1] - bw / 2), b, max(least, share * rp), zs, z0 + dz)
        self.extend("rack", [pc.translated((0.0, 0.0, dz)) for pc in pieces] + posts)
        self._plates(node.of("plate"), plate0, fences, pitch, x_lo, zc + dz, "upper_plate")

    def spout(self, node, x, z):
        """The swivel spout at the middle of the tray's front end wall, its bottom just above the floor's
        underside; at rest it lies along the wall (pointing -Y) and swings through +X to +Y."""
        at = (x + R.SPOUT_OFF, 0.0, z + R.SPOUT_ABOVE)
        name = self.add("spout", "spout", R.swivel_spout(*at, "spout"))
        self.hinge("rack", name, Frame.at(at, z=(0, 0, 1)), upper=math.pi, role="swivel")

    def drip_tray(self, node, xs, b, rp):
        """A shallow tray between the legs, under the cross wires; it slides out along +X past the front legs."""
        (x0, x1), pieces = R.rack_drip_tray(xs, b)
        name = self.add("drip_tray", "tray", pieces)
        self.slide("rack", name, Frame.at((x1, 0.0, 0.0), z=(1, 0, 0)), upper=R.TRAY_OUT * (x1 - x0))

    def feet(self, node, pieces, xs):
        self.extend("rack", R.pads(pieces, xs))

    def plate(self, node, i, piece, pivot, prefix="plate"):
        slot = "plate_alt" if self.p["plate_set"] == "mixed" and i % 2 else "plate"
        name = self.add(f"{prefix}_{i}", "plate", [piece.replace(material=slot)])
        # in its own plane: lift along +Z, slide along Y, turn about its axis (X) through its centre
        self.join(J.limited_planar("rack", name, pivot, slide_axes=((0, 0, 1), (0, 1, 0)),
                                   slides=((0.0, R.LIFT), (-R.PLATE_SLIDE, R.PLATE_SLIDE)), axis=(1, 0, 0),
                                   turn=(-R.TURN, R.TURN), role="plate"))


    # -- the side board: a cutlery caddy, mugs on pegs ---------------------------------------------------
    def cutlery(self, node, board):
        for k, kid in enumerate(node.of("caddy")):
            self.grow(kid, board=board, k=k)

    def cups(self, node, board, after=0.0):
        """Two rows of pegs along the board (its length was made for them); a mug or a tumbler upside down on
        each of them (a row may have one spare peg)."""
        spots, z = R.cup_spots(board, len(node.of("cup")))
        self.extend("rack", [R.cup_peg(x, y, z, "frame") for x, y in spots])
        for k, (kid, (x, y)) in enumerate(zip(node.of("cup"), spots)):
            self.grow(kid, k=k, at=(x, y, z + R.BOARD_STAND))

    def station(self, node, board):
        self.cutlery(node, board)
        self.cups(node, board, after=len(node.of("caddy")) * (R.CADDY["x"] + R.CADDY_APART))

    def caddy(self, node, board, k=0):
        (x0, x1), (y0, y1), _, z = board
        c = R.CADDY
        yc = (y0 + y1) / 2
        xe = x1 - R.CADDY_END - k * (c["x"] + R.CADDY_APART)
        pieces = R.caddy(xe - c["x"], xe, yc - c["y"] / 2, yc + c["y"] / 2, z + R.BOARD_STAND, "caddy", "cutlery")
        name = self.add(f"caddy_{k}", "basket", pieces)
        self.slide("rack", name, Frame.at((xe - c["x"] / 2, yc, z), z=(0, 0, 1)), upper=R.CADDY_LIFT)

    def cup(self, node, k, at):
        self.grow(node.one(node.choice), k=k, at=at)

    def mug(self, node, k, at):
        name = self.add(f"cup_{k}", "cup", R.mug(*at, "mug"))
        self.slide("rack", name, Frame.at(at, z=(0, 0, 1)), upper=R.CUP_LIFT)

    def glass(self, node, k, at):
        name = self.add(f"glass_{k}", "glass", R.tumbler(*at, "glass"))
        self.slide("rack", name, Frame.at(at, z=(0, 0, 1)), upper=R.CUP_LIFT)


CATEGORY = Category("plate_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS,
                    derive=wire_has_legs, palette=furniture)
