"""Door: a hinged leaf in a fixed frame, with a knob, a lever or a pull on both faces.

X is depth, Y is width, Z is up. The frame (the root) stands around x = 0 on the floor: two jambs
and a head as deep as the wall, an optional threshold, stops behind the leaf and architraves on
both faces. The leaf hangs in the opening, its front face flush with the frame's front (+X), and
hinges at one jamb through a pivot on its front face, opening 0..pi/2 toward +X (vertical axis:
neutral under gravity); the lock-side gap allows for its back corner swinging out. Leaf styles:
flat, or 2-6 recessed or raised panels in a stile-and-rail frame, glazed in the top row or
throughout. Handles on both faces: knobs (continuous about X), levers (revolute 0..pi/4; the core
balances them with a counterweight heel) or a fixed bar pull. Parts: ``categories/parts/doors.py``.
"""

from __future__ import annotations

import math

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import doors as P
from .parts import hardware

GRAMMAR = Grammar("door", {
    "door": Node(label="frame", required=("leaf",), optional={"threshold": 0.4}),
    "threshold": Node(),
    "leaf": Node(label="leaf", one_of={"knob": 1 / 3, "lever": 1 / 3, "pull": 1 / 3}, choice="handle"),
    "knob": Node(repeat={"knob_face": 2}),
    "knob_face": Node(label="knob"),
    "lever": Node(repeat={"lever_face": 2}),
    "lever_face": Node(label="lever"),
    "pull": Node(),
})
"""Knobs and levers come in pairs, one on each face; a pull is fixed to the leaf."""

PARAMS = (
    Float("leaf_width", "leaf width (Y)", "m", 0.8, 1.0),
    Float("leaf_height", "leaf height (Z)", "m", 2.0, 2.1),
    Float("leaf_thickness", "leaf thickness (X)", "m", 0.04, 0.06),
    Float("frame_depth", "jamb depth (X), about the wall thickness", "m", 0.1, 0.16),
    Float("jamb_width", "jamb and head board thickness", "m", 0.025, 0.05),
    Float("casing_width", "architrave width", "m", 0.05, 0.09),
    Choice("hinge_side", "jamb the leaf hangs on, seen from the front (+X)", choices=("left", "right")),
    Choice("leaf_style", "leaf face", choices=("flat", "recessed", "raised"), weights=(0.3, 0.35, 0.35)),
    Int("panel_count", "panels of a panelled leaf (2, 3, 5: one column; 4, 6: two)", "", 2, 6),
    Choice("glazing", "glass lites", choices=("none", "top", "full"), weights=(0.55, 0.3, 0.15)),
    Float("stile_width", "width of the leaf's stiles and top rail", "m", 0.1, 0.14),
    Float("handle_height", "handle axis above the floor", "m", 0.95, 1.05),
    Float("lever_length", "lever grip length", "m", 0.1, 0.14),
    Float("knob_radius", "knob radius", "m", 0.025, 0.032),
    Float("pull_length", "bar pull length", "m", 0.25, 0.45),
    Choice("leaf_finish", "leaf material", choices=("wood", "painted")),
    Choice("frame_finish", "frame material: the leaf's or painted white", choices=("match", "white"),
           weights=(0.6, 0.4)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal")),
)

PAINTS = "painted:white|off_white|light_grey|grey|sage|navy|charcoal"
MATERIALS = {"leaf": ("leaf_finish", {"painted": PAINTS}), "frame": "frame_family",
             "glass": "glass:clear|clear_blue", "handle": "handle_finish", "hinge": "handle_finish"}


def frame_family(p: dict) -> dict:
    """A frame matching the leaf wears the leaf's family; otherwise it is painted white."""
    leaf = "wood" if p["leaf_finish"] == "wood" else PAINTS
    return {**p, "frame_family": leaf if p["frame_finish"] == "match" else "painted:white|off_white"}


OPENS = math.pi / 2
GAP = 0.003  # leaf to jambs and head
FLOOR_GAP = 0.012  # under the leaf
THRESHOLD = 0.02
BACKSET = 0.06  # handle axis from the lock edge
LEVER_TURN = math.pi / 4
PULL = hardware.HandleSize(standoff=0.04, bar_radius=0.012, post_radius=0.0096, inset=0.02)


class DoorLayout(Layout):
    def door(self, node):
        p = self.p
        W, H, T = p["leaf_width"], p["leaf_height"], p["leaf_thickness"]
        Dj = p["frame_depth"]
        left = p["hinge_side"] == "left"
        gap_lock = GAP + T * T / W  # the back corner of the leaf swings out by ~T^2 / (2 W)
        th = THRESHOLD if node.one("threshold") else 0.0
        z0 = th + FLOOR_GAP
        oy0 = -W / 2 - (GAP if left else gap_lock)
        oy1 = W / 2 + (gap_lock if left else GAP)
        shift = -(oy0 + oy1) / 2  # the opening centred on y = 0
        self.add("frame", "frame", P.frame(Dj / 2, Dj, (oy0 + shift, oy1 + shift), z0 + H + GAP, p["jamb_width"],
                                           p["casing_width"], 0.0, Dj / 2 - T - GAP))
        if th:
            self.grow(node.one("threshold"), ys=(oy0 + shift, oy1 + shift))
        self.grow(node.one("leaf"), xs=(Dj / 2 - T, Dj / 2), ys=(-W / 2 + shift, W / 2 + shift), zs=(z0, z0 + H))

    def threshold(self, node, ys):
        Dj = self.p["frame_depth"]
        self.extend("frame", [g.box_between([-Dj / 2, ys[0], 0.0], [Dj / 2, ys[1], THRESHOLD], "frame", bevel=0.004)])

    def leaf(self, node, xs, ys, zs):
        p = self.p
        left = p["hinge_side"] == "left"
        y_hinge, y_lock = (ys[0], ys[1]) if left else (ys[1], ys[0])
        inward = 1.0 if left else -1.0  # from the hinge edge across the leaf
        zk = p["handle_height"]
        pieces = P.leaf(xs, ys, zs, zk, p["leaf_style"], p["glazing"], p["stile_width"], p["panel_count"])
        self.add("leaf", "leaf", pieces + P.knuckles(xs[1], y_hinge, *zs))
        self.hinge("frame", "leaf", Frame.at((xs[1], y_hinge, zs[0]), z=(0, 0, -1 if left else 1)), upper=OPENS)
        self.grow(node.one(node.choice), xs=xs, y=y_lock - inward * BACKSET, z=zk, inward=inward)

    def pull(self, node, xs, y, z, inward):
        for n, face in ((1.0, xs[1]), (-1.0, xs[0])):
            at = Frame.at((face, y, z), z=(n, 0, 0), x=(0, 0, 1))
            bar = hardware.bar_handle(self.p["pull_length"], "handle", PULL).attached("mount", to=at)
            self.extend("leaf", bar.parts[bar.root].pieces)

    def _faces(self, node, kind, xs, y, z, inward):
        for kid, (side, n, face) in zip(node.of(kind), (("front", 1.0, xs[1]), ("back", -1.0, xs[0])), strict=True):
            self.extend("leaf", [P.rose(face, n, y, z)])
            self.grow(kid, side=side, n=n, start=face + n * (P.ROSE[1] + GAP), y=y, z=z, inward=inward)

    def knob(self, node, **where):
        self._faces(node, "knob_face", **where)

    def lever(self, node, **where):
        self._faces(node, "lever_face", **where)

    def knob_face(self, node, side, n, start, y, z, inward):
        at = Frame.at((start, y, z), z=(n, 0, 0))
        knob = self.place(P.knob_part(self.p["knob_radius"]).attached("mount", to=at), f"knob_{side}")
        self.spin("leaf", knob.root, at, role="knob")

    def lever_face(self, node, side, n, start, y, z, inward):
        grip = -inward  # the grip points back toward the hinge
        name = self.add(f"lever_{side}", "lever", P.lever(start, n, y, z, grip, self.p["lever_length"]))
        # about (grip direction) x (-Z) = (-grip, 0, 0): a positive angle turns the grip down
        self.hinge("leaf", name, Frame.at((start, y, z), z=(-grip, 0, 0)), upper=LEVER_TURN, role="knob")


CATEGORY = Category("door", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DoorLayout, MATERIALS,
                    derive=frame_family)
