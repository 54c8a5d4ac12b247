"""Tap: a kitchen or bathroom faucet on a deck plate, with a swivelling spout.

X is depth (the spout reaches toward +X), Y is width, Z is up. The root part ``base`` is the
deck plate with its columns. The spout is a swept hollow tube that swivels about its column's
vertical axis (continuous, or revolute +-``spout_swivel``), mounted on a collar around the main
column, or on top of its own separate riser (``gooseneck``, ``curved`` or ``straight``).
Controls: a single lever (on the main column, or with a separate riser on a short mixer column
at +Y): flip_revolute, swivel about Z (temperature) then tilt about the cap's back bottom edge
(flow), resting closed on its lower stop; or two valve handles (cross or lever) on risers at
+-``handle_spread``, revolute about Z, hot on the left, cold on the right. Whatever the spout
sweeps over stays below its outlet. Parts: ``categories/parts/taps.py``.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import taps as T

GRAMMAR = Grammar("tap", {
    "tap": Node(label="base", required=("spout",), optional={"separate_pipe": 0.5},
                one_of={"single_lever": 0.6, "two_handles": 0.4}, choice="handles"),
    "separate_pipe": Node(),
    "spout": Node(label="spout"),
    "single_lever": Node(label="lever"),
    "two_handles": Node(repeat={"valve": 2}),
    "valve": Node(label="handle"),
})

PARAMS = (
    Float("height", "height of the tap (top of the spout or of the lever cap)", "m", 0.15, 0.4),
    Float("base_width", "deck plate width (Y); at least what its columns need", "m", 0.06, 0.25),
    Choice("base_shape", "deck plate outline", choices=("round", "rect")),
    Float("body_radius", "radius of the main column", "m", 0.016, 0.028),
    Choice("spout_shape", "spout form (a gooseneck needs a separate pipe: on a collar it is curved)",
           choices=("gooseneck", "curved", "straight"), weights=(0.35, 0.4, 0.25)),
    Float("spout_reach", "horizontal reach of the spout outlet from its axis", "m", 0.1, 0.24),
    Float("spout_radius", "spout tube radius", "m", 0.007, 0.012),
    Choice("spout_joint", "spout swivel: free (continuous) or limited (revolute)", choices=("continuous", "revolute")),
    Float("spout_swivel", "swivel range (+-) of a limited spout", "rad", math.pi / 6, 3 * math.pi / 4),
    Float("lever_length", "lever arm length beyond its cap", "m", 0.04, 0.12),
    Float("lever_tilt", "lever lift range", "rad", math.pi / 9, math.pi / 5),
    Float("handle_spread", "distance of each valve handle or side mixer from the middle (Y)", "m", 0.05, 0.1),
    Choice("handle_kind", "valve handle form", choices=("cross", "lever")),
    Choice("finish", "tap finish", choices=("chrome", "brushed_metal", "matte_black"), weights=(0.5, 0.3, 0.2)),
)

MATERIALS = {"metal": ("finish", {"matte_black": "enamel:black"}), "seal": "rubber",
             "aerator": "plastic:black|dark_grey", "hot": "plastic:red", "cold": "plastic:blue"}

LEVER_SWIVEL = math.pi / 2
HANDLE_TURN = math.pi / 4
CAP = 0.95  # a lever cap's radius as a fraction of its column's
SPOUT_OVER = 0.035  # an outlet stays this far above whatever it sweeps over
MIXER_H = 0.035  # a side mixer column's height
RISER = 0.004  # a spout riser is this much wider than the spout tube
FLARE = 1.25  # column feet flare to this fraction of their radius


class TapLayout(Layout):
    def tap(self, node):
        p = self.p
        lever = p["handles"] == "single_lever"
        pipe = node.one("separate_pipe")
        rb = p["body_radius"]
        rs = min(p["spout_radius"], 0.6 * rb)
        height = p["height"]
        columns, controls = [], {}
        # what the spout sweeps over: a side mixer with its lever, or two valve handles
        if lever and pipe:
            d = max(p["handle_spread"], rs + RISER + CAP * rb + 0.045)
            arm = min(p["lever_length"], d - rs - RISER - CAP * rb - 0.015)
            columns.append(T.column((0.0, d), T.DECK_T, T.DECK_T + MIXER_H, rb))
            controls["pieces"], controls["hinge"] = T.lever((0.0, d), T.DECK_T + MIXER_H + T.GAP, CAP * rb, arm)
            side_top = T.highest_when_tilted(controls["pieces"], controls["hinge"], p["lever_tilt"])
        elif not lever:
            d = max(p["handle_spread"], rb + 2 * T.RISER_R + 0.02)
            reach = min(0.045, d - max(rb, rs + RISER) - 0.012)
            z_r = T.DECK_T + T.RISER_H
            controls["valves"] = []
            for y, slot in ((d, "hot"), (-d, "cold")):
                columns.append(T.column((0.0, y), T.DECK_T, z_r, T.RISER_R))
                controls["valves"].append((T.valve_handle((0.0, y), z_r + T.GAP, reach, p["handle_kind"], slot),
                                           (0.0, y, z_r + T.GAP)))
            side_top = max(pc.bounds[1, 2] for pcs, _ in controls["valves"] for pc in pcs)
        else:
            d, side_top = 0.0, T.DECK_T
        # the spout: on its own riser, or on a collar around the main column (with the lever on top)
        if pipe:
            z_low = side_top + SPOUT_OVER  # the outlet (aerator included) stays above the side elements
            height = max(height, z_low + 0.06)
            z_rt = T.DECK_T + max(0.03, 0.2 * (height - T.DECK_T))
            riser = T.column((0.0, 0.0), T.DECK_T, z_rt, rs + RISER, flare=1.5)
            spout = T.top_spout(p["spout_shape"], p["spout_reach"], rs, z_rt + T.GAP, height, z_low)
            axis = z_rt + T.GAP
        else:
            hc = 2 * rs + 0.014
            if lever:
                z_bt = height - T.CAP_H - T.GAP  # top of the column under the cap
                z_cm = min(T.DECK_T + 0.55 * (z_bt - T.DECK_T), z_bt - 0.012 - hc / 2)
                controls["pieces"], controls["hinge"] = T.lever((0.0, 0.0), z_bt + T.GAP, CAP * rb,
                                                                p["lever_length"])
            else:
                z_cm = max(side_top + 0.065 + rs, T.DECK_T + 0.5 * (height - T.DECK_T))
                z_bt = height = max(height, z_cm + hc / 2 + 0.03)
            columns.append(T.column((0.0, 0.0), T.DECK_T, z_bt, rb, dome=not lever))
            shape = "curved" if p["spout_shape"] == "gooseneck" else p["spout_shape"]
            spout = T.collar_spout(shape, p["spout_reach"], rs, rb, z_cm, hc, T.DECK_T)
            axis = z_cm - hc / 2
        need = 2 * (d + (rb if lever else T.RISER_R) * FLARE + 0.008) if d else 2 * (FLARE * rb + 0.008)
        width = max(p["base_width"], need) if d else max(need, min(p["base_width"], 0.12))
        depth = float(np.clip(0.4 * width, 2 * FLARE * max(rb, T.RISER_R) + 0.016, 0.09))
        self.add("base", "base", T.deck(width, depth, p["base_shape"], bridge=bool(d)) + columns)
        if pipe:
            self.grow(pipe, riser=riser)
        self.grow(node.one("spout"), pieces=spout, axis=axis)
        self.grow(node.one(node.choice), **controls)

    def separate_pipe(self, node, riser):
        self.extend("base", [riser])

    def spout(self, node, pieces, axis):
        self.add("spout", "spout", pieces)
        at = (0.0, 0.0, axis)
        if self.p["spout_joint"] == "continuous":
            self.join(J.continuous("base", "spout", at, (0, 0, 1), role="swivel"))
        else:
            a = self.p["spout_swivel"]
            self.join(J.revolute("base", "spout", at, (0, 0, 1), -a, a, role="swivel"))

    def single_lever(self, node, pieces, hinge):
        name = self.add("lever", "lever", pieces)
        # swivel about the column's axis, then tilt about the cap's back bottom edge
        column = (hinge.origin[0] + CAP * self.p["body_radius"], hinge.origin[1], hinge.origin[2])
        self.join(J.flip_revolute("base", name, column, (0, 0, 1), (-LEVER_SWIVEL, LEVER_SWIVEL), hinge.origin,
                                  hinge.z, (0.0, self.p["lever_tilt"]), role="hinge"))

    def two_handles(self, node, valves):
        for k, (valve, (pieces, at)) in enumerate(zip(node.of("valve"), valves)):
            self.grow(valve, k=k, pieces=pieces, at=at)

    def valve(self, node, k, pieces, at):
        name = self.add(f"handle_{k}", "handle", pieces)
        self.join(J.revolute("base", name, at, (0, 0, 1), -HANDLE_TURN, HANDLE_TURN, role="knob"))


CATEGORY = Category("tap", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TapLayout, MATERIALS)
