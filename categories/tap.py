"""Tap: a kitchen or bathroom faucet on a deck plate, with a swivelling spout.

X is depth (the spout reaches toward +X), Y is width, Z is up. The root part ``base`` is the
deck plate with its columns. The spout is a swept hollow tube that swivels about its column's
vertical axis (continuous, or revolute +-``spout_swivel``), mounted on a collar around the main
column, or on top of its own separate riser (``gooseneck``, ``curved`` or ``straight``).
Controls: a single lever (on the main column, or with a separate riser on a short mixer column
at +Y): flip_revolute, swivel about Z (temperature) then tilt about the cap's back bottom edge
(flow), resting closed on its lower stop; or two valve handles (cross or lever) on risers at
+-``handle_spread``, revolute about Z, hot on the left, cold on the right. Whatever the spout
sweeps over stays below its outlet. Optional real extra: a bath-shower wall mixer's diverter knob
(prismatic, pulled up 8 mm). Parts: ``categories/parts/taps.py``.
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import taps as T

R = T.RANGES  # the parameters' ranges (sourced in taps.Ranges)

GRAMMAR = Grammar("tap", {
    "tap": Node(label="base", required=("spout",), one_of={"deck": 0.4, "bridge": 0.2, "pull_out": 0.25, "wall": 0.15},
                choice="design"),
    "deck": Node(optional={"separate_pipe": 0.5}, one_of={"single_lever": 0.6, "two_handles": 0.4}, choice="handles"),
    "bridge": Node(required=("two_handles",)),
    "pull_out": Node(required=("single_lever", "spray_head")),
    "wall": Node(required=("single_lever",), optional={"diverter": 0.5}),
    "separate_pipe": Node(),
    "spout": Node(label="spout"),
    "spray_head": Node(label="spray_head"),
    "diverter": Node(label="knob", doc="a bath-shower mixer's diverter knob (pulled up 8 mm)"),
    "single_lever": Node(label="lever"),
    "two_handles": Node(repeat={"valve": 2}),
    "valve": Node(label="handle"),
})
"""Designs: a deck mixer (single lever or two valves; the spout on a collar or its own pipe), a bridge
mixer (two valves on risers joined by a bridge pipe, the spout rising from its middle), a pull-out
kitchen mixer (side lever; the spray head slides out of the spout on its hose and turns), a wall mixer
(a bar on two S-unions, the lever on top, the spout swivelling under it)."""

PARAMS = (
    Float("height", "height of the tap (top of the spout or of the lever cap)", "m", *R.height),
    Float("base_width", "deck plate width (Y); at least what its columns need", "m", *R.base_width),
    Choice("base_shape", "deck plate outline", choices=("round", "rect")),
    Float("body_radius", "radius of the main column", "m", *R.body_radius),
    Choice("spout_shape", "spout form (a gooseneck needs a separate pipe: on a collar it is curved)",
           choices=("gooseneck", "curved", "straight"), weights=(0.35, 0.4, 0.25)),
    Float("spout_reach", "horizontal reach of the spout outlet from its axis", "m", *R.spout_reach),
    Float("spout_radius", "spout tube radius", "m", *R.spout_radius),
    Choice("spout_joint", "spout swivel: free (continuous) or limited (revolute)", choices=("continuous", "revolute")),
    Float("spout_swivel", "swivel range (+-) of a limited spout", "rad", *R.spout_swivel),
    Float("lever_length", "lever arm length beyond its cap", "m", *R.lever_length),
    Float("lever_tilt", "lever lift range", "rad", *R.lever_tilt),
    Float("handle_spread", "distance of each valve handle or side mixer from the middle (Y)", "m", *R.handle_spread),
    Choice("handle_kind", "valve handle form", choices=("cross", "lever")),
    Float("head_travel", "how far a pull-out spray head slides out on its hose", "m", *R.head_travel),
    Float("wall_length", "length of a wall mixer's body (Y)", "m", *R.wall_length),
    Choice("finish", "tap finish", choices=("chrome", "brushed_metal", "matte_black"), weights=(0.5, 0.3, 0.2)),
)

MATERIALS = {"metal": ("finish", {"matte_black": "enamel:black"}), "seal": "rubber",
             "aerator": "plastic:black|dark_grey", "hot": "plastic:red", "cold": "plastic:blue"}


def designs(p: dict) -> dict:
    """A wall mixer's spout swivel is limited (it would swing into the wall)."""
    if p["design"] != "wall":
        return p
    return {**p, "spout_joint": "revolute", "spout_swivel": min(p["spout_swivel"], T.WALL_SWIVEL)}


class TapLayout(Layout):
    def tap(self, node):
        p = self.p
        design = node.one(node.choice)
        if node.choice == "wall":
            return self._wall(node, design)
        if node.choice == "deck":
            lever, pipe = design.choice == "single_lever", design.one("separate_pipe")
        else:
            lever, pipe = node.choice == "pull_out", True
        bridge = node.choice == "bridge"
        rb = p["body_radius"]
        rs = min(p["spout_radius"], T.LAYOUT["spout_max"] * rb)
        lay = T.LAYOUT
        height = p["height"]
        columns, controls, extra = [], {}, []
        # what the spout sweeps over: a side mixer with its lever, or two valve handles
        if lever and pipe:
            d = max(p["handle_spread"], rs + T.RISER + T.CAP * rb + lay["mixer_room"])
            arm = min(p["lever_length"], d - rs - T.RISER - T.CAP * rb - lay["lever_clear"])
            z_cap = T.DECK_T + T.MIXER_H
            columns += [T.column((0.0, d), T.DECK_T, z_cap, rb), T.lever_cap((0.0, d), z_cap, T.CAP * rb)]
            controls["pieces"], controls["hinge"] = T.lever((0.0, d), z_cap + T.CAP_H, T.CAP * rb, arm)
            side_top = T.highest_when_tilted(controls["pieces"], controls["hinge"], p["lever_tilt"])
        elif not lever:
            d = max(p["handle_spread"], rb + 2 * T.RISER_R + lay["valve_room"])
            reach = min(lay["valve_reach"], d - max(rb, rs + T.RISER) - lay["valve_clear"])
            z_r = T.DECK_T + (T.BRIDGE_H + T.RISER_R if bridge else T.RISER_H)
            controls["valves"] = []
            for y, slot in ((d, "hot"), (-d, "cold")):
                columns.append(T.column((0.0, y), T.DECK_T, z_r, T.RISER_R))
                controls["valves"].append((T.valve_handle((0.0, y), z_r + T.GAP, reach, p["handle_kind"], slot),
                                           (0.0, y, z_r + T.GAP)))
            if bridge:
                extra = T.bridge_bar(d, T.DECK_T + T.BRIDGE_H, lay["bridge_bar"] * T.RISER_R)
            side_top = max(pc.bounds[1, 2] for pcs, _ in controls["valves"] for pc in pcs)
        else:
            d, side_top = 0.0, T.DECK_T
        # the spout: on its own riser, or on a collar around the main column (with the lever on top)
        head = None
        if pipe:
            z_low = side_top + T.SPOUT_OVER  # the outlet (aerator included) stays above the side elements
            z_rt = T.DECK_T + (T.BRIDGE_H + lay["bridge_riser"] if bridge else 0.0)
            low, share = lay["riser"]
            if node.choice == "pull_out":
                head_r, head_min, hose = lay["head"]
                height = max(height, z_low + 2 * max(head_r * rs, head_min) + hose)
                z_rt = T.DECK_T + max(low, share * (height - T.DECK_T))
                spout, hp, hf, travel = T.pullout_spout(p["spout_reach"] + lay["head_reach"], rs, z_rt + T.GAP, height,
                                                        z_low, p["head_travel"])
                head = dict(pieces=hp, at=hf, travel=travel)
            else:
                over_outlet, over_riser = lay["spout_rise"]
                height = max(height, z_low + over_outlet, z_rt + over_riser)
                z_rt = max(z_rt, T.DECK_T + max(low, share * (height - T.DECK_T)))
                spout = T.top_spout(p["spout_shape"], p["spout_reach"], rs, z_rt + T.GAP, height, z_low)
            riser = T.column((0.0, 0.0), T.DECK_T, z_rt, rs + T.RISER, flare=lay["riser_flare"])
            axis = z_rt + T.GAP
        else:
            hc = 2 * rs + T.COLLAR
            if lever:
                z_bt = height - T.CAP_H - T.lever_height(T.CAP * rb, p["lever_length"])  # the column's top
                at, under = lay["lever_collar"]
                z_cm = min(T.DECK_T + at * (z_bt - T.DECK_T), z_bt - under - hc / 2)
                columns.append(T.lever_cap((0.0, 0.0), z_bt, T.CAP * rb))
                controls["pieces"], controls["hinge"] = T.lever((0.0, 0.0), z_bt + T.CAP_H, T.CAP * rb,
                                                                p["lever_length"])
            else:
                z_cm = max(side_top + lay["collar_over"] + rs, T.DECK_T + 0.5 * (height - T.DECK_T))
                z_bt = height = max(height, z_cm + hc / 2 + lay["column_over"])
            columns.append(T.column((0.0, 0.0), T.DECK_T, z_bt, rb, dome=not lever))
            shape = "curved" if p["spout_shape"] == "gooseneck" else p["spout_shape"]
            spout = T.collar_spout(shape, p["spout_reach"], rs, rb, z_cm, hc, T.DECK_T)
            axis = z_cm - hc / 2
        width, depth = T.deck_size(p["base_width"], d, rb, rb if lever else T.RISER_R)
        self.add("base", "base", T.deck(width, depth, p["base_shape"], bridge=bool(d)) + columns + extra)
        if pipe and node.choice == "deck":
            self.grow(design.one("separate_pipe"), riser=riser)
        elif pipe:
            self.extend("base", [riser])
        self.grow(node.one("spout"), pieces=spout, axis=(0.0, 0.0, axis))
        self.grow(design, controls=controls, head=head)

    def _wall(self, node, design):
        """A wall mixer: the body bar at ``z``, a cartridge column up from it, a stub down into the spout's
        collar."""
        p = self.p
        rb = p["body_radius"]
        rs = min(p["spout_radius"], T.LAYOUT["spout_max"] * rb)
        pieces, (z, r_bar, z_top, z_cm, hc) = T.wall_mixer(p["wall_length"], rb, rs)
        self.add("base", "base", pieces)
        shape = "curved" if p["spout_shape"] == "gooseneck" else p["spout_shape"]
        spout = T.collar_spout(shape, p["spout_reach"], rs, rb, z_cm, hc, z_cm - T.WALL_SPOUT_FOOT)
        self.grow(node.one("spout"), pieces=spout, axis=(0.0, 0.0, z_cm - hc / 2))
        lever, hinge = T.lever((0.0, 0.0), z_top + T.CAP_H, T.CAP * rb, p["lever_length"])
        self.grow(design, controls=dict(pieces=lever, hinge=hinge), head=None,
                  diverter=(-(p["wall_length"] / 2 - T.DIVERTER["inset"]), z + r_bar))

    def deck(self, node, controls, head):
        self.grow(node.one(node.choice), **controls)

    def bridge(self, node, controls, head):
        self.grow(node.one("two_handles"), **controls)

    def wall(self, node, controls, head, diverter):
        self.grow(node.one("single_lever"), **controls)
        if node.one("diverter"):
            self.grow(node.one("diverter"), y=diverter[0], z_top=diverter[1])

    def diverter(self, node, y, z_top):
        pieces, at = T.diverter_knob(y, z_top)
        self.add("diverter", "knob", pieces)
        self.join(J.prismatic("base", "diverter", tuple(at.origin), tuple(at.z), 0.0, T.DIVERTER["pull"],
                              role="button"))

    def pull_out(self, node, controls, head):
        self.grow(node.one("single_lever"), **controls)
        self.grow(node.one("spray_head"), **head)

    def separate_pipe(self, node, riser):
        self.extend("base", [riser])

    def spout(self, node, pieces, axis):
        self.add("spout", "spout", pieces)
        if self.p["spout_joint"] == "continuous":
            self.join(J.continuous("base", "spout", axis, (0, 0, 1), role="swivel"))
        else:
            a = self.p["spout_swivel"]
            self.join(J.revolute("base", "spout", axis, (0, 0, 1), -a, a, role="swivel"))

    def spray_head(self, node, pieces, at, travel):
        self.add("spray_head", "spray_head", pieces)
        # pulls out along the spout's arm on its hose and turns freely about it
        self.join(J.continuous_prismatic("spout", "spray_head", at.origin, at.z, (0.0, travel), role="slide"))

    def single_lever(self, node, pieces, hinge):
        name = self.add("lever", "lever", pieces)
        # swivel about the cartridge's vertical axis (temperature), then lift about its pin (flow)
        self.join(J.flip_revolute("base", name, hinge.origin, (0, 0, 1), (-T.LEVER_SWIVEL, T.LEVER_SWIVEL),
                                  hinge.origin, hinge.z, (0.0, self.p["lever_tilt"]), role="hinge"))

    def two_handles(self, node, valves):
        for k, (valve, (pieces, at)) in enumerate(zip(node.of("valve"), valves)):
            self.grow(valve, k=k, pieces=pieces, at=at)

    def valve(self, node, k, pieces, at):
        name = self.add(f"handle_{k}", "handle", pieces)
        self.join(J.revolute("base", name, at, (0, 0, 1), -T.HANDLE_TURN, T.HANDLE_TURN, role="knob"))


CATEGORY = Category("tap", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TapLayout, MATERIALS,
                    derive=designs)
