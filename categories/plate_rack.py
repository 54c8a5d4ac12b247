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
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import racks as R


def plates(p, rng) -> int:
    """plate_count (at most slot_count), or each slot filled with chance 0.5, at least one"""
    n = p["slot_count"]
    drawn = max(1, int((rng.random(n) < 0.5).sum()))
    return min(p["plate_count"], n) if p["plate_count"] else drawn


GRAMMAR = Grammar("plate_rack", {
    "plate_rack": Node(label="rack", repeat={"plate": plates}, optional={"feet": 0.5}),
    "plate": Node(label="plate"),
    "feet": Node(),
})
"""Plates fill ``plates`` of the slots, which ones drawn per rack. ``feet`` are rubber pads under a
wood or plastic rack; a wire rack always stands on its capped legs."""

PARAMS = (
    Int("slot_count", "slots (fences of prong pairs = slots + 1)", "", 3, 7),
    Int("plate_count", "plates; auto = each slot holds one with chance 0.5 (at least one)", "", 1, 7, auto=True),
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
             "plate_alt": "ceramic", "feet": "rubber:black|soft_black"}


def wire_has_legs(p: dict) -> dict:
    """A wire rack stands on its capped legs, never on pads."""
    return {**p, "has_feet": p["has_feet"] and p["style"] != "wire"}


LIFT = 0.1  # lift of a plate along +Z
TURN = math.pi / 2  # turn of a plate about its axis (X) either way
END = 0.03  # rack length beyond the first and last fence
PAD = 0.006  # rubber pad height under a wood or plastic rack
WIRE = 0.6  # a wire rack's wire radius as a fraction of prong_radius


class RackLayout(Layout):
    def plate_rack(self, node):
        p = self.p
        n, r = p["slot_count"], p["plate_radius"]
        rp = p["prong_radius"] * (WIRE if p["style"] == "wire" else 1.0)
        b = p["prong_spread"] * r
        plate0 = R.plate(r, p["plate_depth"] * r, p["plate_thickness"], p["foot_fraction"] * r, "plate")
        pts = np.vstack([plate0.vertices, *plate0.convex])
        x_lo, x_hi = pts[:, 0].min(), pts[:, 0].max()
        pitch = x_hi - x_lo + 2 * p["clearance"] + 2 * rp
        fences = (np.arange(n + 1) - n / 2) * pitch
        xs = (fences[0] - END, fences[-1] + END)
        z0 = PAD if node.one("feet") else 0.0  # underside of the rack body
        if p["style"] == "wood":
            pieces, zs = R.wood_rack(fences, xs, b, rp, z0, p["prong_height"], p["base_height"])
        elif p["style"] == "plastic":
            pieces, zs = R.plastic_tray(fences, xs, b, rp, z0, p["prong_height"], p["base_height"], r)
        else:
            pieces, zs = R.wire_rack(fences, xs, b, rp, p["prong_height"], p["base_height"])
        self.add("rack", "rack", pieces)
        if node.one("feet"):
            self.grow(node.one("feet"), pieces=pieces, xs=xs)
        zc = zs + R.SEAT_GAP + r  # plate centre: its lowest point SEAT_GAP above the support
        kids = node.of("plate")
        slots = sorted(int(i) for i in self.rng.choice(n, size=len(kids), replace=False))
        for kid, i in zip(kids, slots):
            x_foot = fences[i] + rp + p["clearance"] - x_lo
            self.grow(kid, i=i, piece=plate0.translated((x_foot, 0.0, zc)), pivot=(fences[i] + pitch / 2, 0.0, zc))

    def feet(self, node, pieces, xs):
        self.extend("rack", R.pads(pieces, xs))

    def plate(self, node, i, piece, pivot):
        slot = "plate_alt" if self.p["plate_set"] == "mixed" and i % 2 else "plate"
        name = self.add(f"plate_{i}", "plate", [piece.with_material(slot)])
        # in its own plane: lift along +Z, slide along Y, turn about its axis (X) through its centre
        self.join(J.limited_planar("rack", name, pivot, slide_axes=((0, 0, 1), (0, 1, 0)),
                                   slides=((0.0, LIFT), (-R.PLATE_SLIDE, R.PLATE_SLIDE)), axis=(1, 0, 0),
                                   turn=(-TURN, TURN), role="plate"))


CATEGORY = Category("plate_rack", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RackLayout, MATERIALS,
                    derive=wire_has_legs)
