"""Plate rack: a dish-drying rack with rows of prongs and ceramic plates standing in its slots.

X is the rack's length (the front end faces +X), Y its width, Z up. Along X stand
``slot_count + 1`` fences of prong pairs, so every slot is bounded by a prong pair on each side
of its plate. Three kinds of rack: ``wood`` (two rails on cross battens, dowel prongs, optional
rubber pads), ``plastic`` (a moulded tray with pegs) and ``wire`` (chrome rails on capped legs,
an arch at every fence). A plate stands upright in its slot, its axis along X, a few millimetres
above the support, and hangs from the rack by a ``limited_planar`` joint in its own plane: a lift
along +Z (gravity holds it down), a slide along Y and a turn about its own axis — moving in its
own plane it never leaves its slot. Parts: ``categories/parts/plate_racks.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import plate_racks as R


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
        design = node.one(node.choice)
        size, plate = R.RackSize.of(p, feet=bool(node.one("feet"))), R.PlateSize.of(p)
        piece = R.plate(plate, "plate")
        rack = self.place(R.rack_body(size, plate, piece, len(design.of("caddy")), len(design.of("cup"))), "rack")
        if node.one("feet"):
            self.grow(node.one("feet"))
        self.grow(design, rack=rack)
        self._plates(node.of("plate"), piece, rack, "plate")
        if node.one("tier"):
            self.grow(node.one("tier"), tier=R.rack_tier(size, plate, piece, rack.anchor("tier")), piece=piece)
        if node.one("drip_tray"):
            self.grow(node.one("drip_tray"), tray=R.rack_drip_tray(rack.assembly, size), at=rack.anchor("drip_tray"))
        if node.one("spout"):
            self.grow(node.one("spout"), at=rack.anchor("spout"))

    def _plates(self, kids, piece, rack, prefix):
        slots = sorted(int(i) for i in self.rng.choice(self.p["slot_count"], size=len(kids), replace=False))
        for kid, i in zip(kids, slots):
            self.grow(kid, i=i, piece=piece, slot=rack.anchor(f"slot_{i}"), pivot=rack.anchor(f"pivot_{i}"),
                      prefix=prefix)

    def tier(self, node, tier, piece):
        """The upper tier on four posts over the first (its pieces are the rack's); its plates in its own slots."""
        self.extend("rack", tier.pieces)
        self._plates(node.of("plate"), piece, tier, "upper_plate")

    def spout(self, node, at):
        """The swivel spout at the middle of the tray's front end wall, its bottom just above the floor's
        underside; at rest it lies along the wall (pointing -Y) and swings through +X to +Y."""
        spout = self.place(R.swivel_spout("spout").attached("pivot", to=at), "spout")
        self.hinge("rack", spout.root, spout.anchor("pivot"), upper=R.SPOUT_TURN, role="swivel")

    def drip_tray(self, node, tray, at):
        """A shallow tray between the legs, under the cross wires; it slides out along +X past the front legs."""
        placed = self.place(tray.attached("mount", to=at), "drip_tray")
        self.slide("rack", placed.root, placed.anchor("pull"), upper=R.tray_travel(tray))

    def feet(self, node):
        self.extend("rack", [])  # the rack's pads are its body's (built with it, before its fittings)

    def plate(self, node, i, piece, slot, pivot, prefix="plate"):
        material = "plate_alt" if self.p["plate_set"] == "mixed" and i % 2 else "plate"
        name = self.add(f"{prefix}_{i}", "plate", [piece.replace(material=material).translated(slot.origin)])
        self.join(R.plate_joint("rack", name, pivot))

    # -- the side board: a cutlery caddy, mugs on pegs ---------------------------------------------------
    def cutlery(self, node, rack):
        for k, kid in enumerate(node.of("caddy")):
            self.grow(kid, rack=rack, k=k)

    def cups(self, node, rack):
        """Two rows of pegs along the board (its length was made for them); a mug or a tumbler upside down on
        each of them (a row may have one spare peg)."""
        pegs = [R.cup_peg("frame").placed(at) for at in R.pegs(rack.assembly)]
        self.extend("rack", [pc for peg in pegs for pc in peg.pieces])
        for k, (kid, peg) in enumerate(zip(node.of("cup"), pegs)):
            self.grow(kid, k=k, at=peg.anchor("seat"))

    def station(self, node, rack):
        self.cutlery(node, rack)
        self.cups(node, rack)

    def caddy(self, node, rack, k=0):
        caddy = self.place(R.caddy("caddy", "cutlery").attached("mount", to=rack.anchor(f"caddy_{k}")), f"caddy_{k}")
        self.lift("rack", caddy.root, caddy.anchor("lift"), engagement=R.POCKET["h"])

    def cup(self, node, k, at):
        self.grow(node.one(node.choice), k=k, at=at)

    def _on_peg(self, name, part, at):
        """A mug or tumbler upside down on its peg, lifted off it (role lift_off, the peg's height engaged)."""
        placed = self.place(part.attached("rim", to=at), name)
        self.lift("rack", placed.root, placed.anchor("lift"), engagement=R.PEG["h"])

    def mug(self, node, k, at):
        self._on_peg(f"cup_{k}", R.mug("mug"), at)

    def glass(self, node, k, at):
        self._on_peg(f"glass_{k}", R.tumbler("glass"), at)


CATEGORY = Category("plate_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS,
                    derive=wire_has_legs, palette=furniture)
