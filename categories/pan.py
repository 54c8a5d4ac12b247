"""Pan: a frying pan or skillet with a riveted, folding or detachable handle, maybe a lid.

X is depth (the handle reaches toward +X, the front), Y is width, Z is up. The body
(:func:`~.parts.vessel.frying_pan_body`) is a shallow hollow vessel (a bottom that
follows the rounded corner, a thin flared wall of revolution, a rolled rim), so the
inside stays hollow for the simulator. A non-stick pan has a dark coating: a thin disc
on the floor, in its own material slot. Three handle designs (``handle_style``,
:data:`.parts.closure_sizes.PAN_HANDLES`):

* ``riveted``: the long handle is its own part fixed to the body; it leaves the wall
  horizontally below the rim, out past the lid's edge, then rises, ending in a rounded
  tip or a hanging hole; this pan always has a lid (so it moves) and big ones a helper
  handle opposite (its own fixed part);
* ``folding`` (camping skillets, MSR / GSI): a short lug on the wall and the handle
  hinged at its top edge just outboard of it; it folds up over the pan (revolute about
  -Y, 0..180 degrees mechanical, shortened to clearance); maybe a lid;
* ``detachable`` (Tefal Ingenio): the handle slides off the lug along +X (prismatic,
  0..6 cm) and carries a thumb release slider on its top (prismatic along the handle,
  0..8 mm); maybe a lid.

The lid is a dome (glass or the body's metal) with a band and a knob; it rests 2.5 mm
above the rim on the lower stop of a prismatic joint along +Z (0..2 cm), so gravity
holds it there, and the handle stays below the rim out past its edge.

Finishes: stainless steel, enamelled cast iron (handle cast with the body) or non-stick
(coloured enamel outside, dark coating inside, plastic, wooden or matching handle).
"""

from __future__ import annotations

import numpy as np

from infmob_usd import joints as J
from infmob_usd.assembly import Assembly
from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import closures as CL
from .parts import vessel as V
from .parts.closure_sizes import HELPER, PAN_HANDLES, SPLIT_HANDLE
from .parts.vessel_sizes import COATING, GLASS, GLASS_LID_THICKER, HANDLE_FAMILY, KNOB, PAN, PAN_FAMILY, PAN_LIFT

LIFT = PAN_LIFT

GRAMMAR = Grammar("pan", {
    "pan": Node(label="body", required=("handle",), doc="a shallow rolled-rim vessel and its handle"),
    "handle": Node(one_of=PAN_HANDLES, choice="handle_style", doc="how the long handle is held"),
    "riveted": Node(label="handle", required=("lid",), optional={"hole": 0.6, "helper": HELPER["p"]},
                    doc="a long handle fixed to the body, a lid, maybe a helper handle"),
    "folding": Node(label="handle", optional={"lid": 0.5, "hole": 0.6},
                    doc="a handle hinged on a lug that folds up over the pan"),
    "detachable": Node(label="handle", required=("release",), optional={"lid": 0.5, "hole": 0.6},
                       doc="a handle that slides off a lug, with a thumb release slider"),
    "release": Node(label="button", doc="the thumb slider on a detachable handle"),
    "helper": Node(label="handle", doc="a short loop handle opposite the long one (fixed)"),
    "hole": Node(doc="a hanging ring at the handle's end (pieces of the handle)"),
    "lid": Node(label="lid", doc="a dome lid with a knob, lifting off the rim"),
})

PARAMS = (
    Float("radius", "outer radius of the wall at the top", "m", *PAN["radius"]),
    Float("depth_ratio", "depth / radius", "", *PAN["depth_ratio"], dist="loguniform"),
    Float("flare", "wall angle from vertical (capped: the wall flares out by <= 0.25 radius)", "rad", *PAN["flare"]),
    Float("corner", "bottom corner radius as a fraction of the depth (<= 0.15 radius)", "", *PAN["corner"]),
    Float("wall", "wall thickness", "m", *PAN["wall"]),
    Float("bottom", "bottom thickness", "m", *PAN["bottom"]),
    Float("bead", "rolled rim bead radius", "m", *PAN["bead"]),
    Float("handle_length", "handle length from the wall", "m", *PAN["handle_length"]),
    Float("handle_angle", "handle rise above horizontal", "rad", *PAN["handle_angle"]),
    Float("handle_width", "handle width", "m", *PAN["handle_width"]),
    Float("handle_thickness", "handle thickness (capped by the depth)", "m", *PAN["handle_thickness"]),
    Float("dome", "lid dome height as a fraction of the radius", "", *PAN["dome"]),
    Float("lid_thickness", "lid wall thickness (glass lids are 1.6x thicker)", "m", *PAN["lid_thickness"]),
    Float("knob_radius", "lid knob radius", "m", *PAN["knob_radius"]),
    Choice("finish", "pan material", choices=tuple(PAN_FAMILY), weights=PAN["finish_weights"]),
    Choice("handle_finish", "handle material (a cast iron handle always matches)", choices=tuple(HANDLE_FAMILY),
           weights=PAN["handle_weights"]),
    Choice("lid_finish", "lid: glass or the body's material", choices=("glass", "match"), weights=PAN["lid_weights"]),
)


class PanLayout(Layout):
    def pan(self, node):
        p = self.p
        body, pan = V.frying_pan_body(p["radius"], p["depth_ratio"] * p["radius"], p["flare"], p["corner"],
                                      p["wall"], p["bottom"], p["bead"], "body",
                                      coating="coating" if p["finish"] == "nonstick" else "")
        body = self.place(body, "body")
        self.grow(node.one("handle"), body=body, pan=pan)

    def handle(self, node, body, pan):
        h = node.one(node.choice)
        self.grow(h, body=body, pan=pan)
        for kind in ("lid", "helper"):
            if h.one(kind):
                self.grow(h.one(kind), body=body, pan=pan)

    def _handle_slot(self) -> str:
        match = self.p["finish"] == "cast_iron" or self.p["handle_finish"] == "match"
        return "body" if match else "handle"

    def riveted(self, node, body, pan):
        p, slot = self.p, self._handle_slot()
        hole = node.one("hole")
        ring, room = V.hanging_ring(p["handle_width"], p["handle_thickness"], slot) if hole else (None, 0.0)
        h = V.long_handle(pan, p["handle_length"], p["handle_angle"], p["handle_width"], p["handle_thickness"], slot,
                          end_room=room)
        h = self.place(h.attached("vessel", to=body.anchor("base")), "handle")
        self.join(J.fixed(body.root, h.root))
        if hole:
            self.grow(hole, handle=h, ring=ring)
        else:
            tip = V.handle_tip(p["handle_width"], p["handle_thickness"], slot)
            self.extend(h.root, tip.attached("start", to=h.anchor("end")).pieces)

    def hole(self, node, handle, ring):
        self.extend(handle.root, ring.attached("start", to=handle.anchor("end")).pieces)

    def _split(self, node, body, pan):
        """The lug (pieces of the body) and the handle part, with its tip or ring."""
        p, slot = self.p, self._handle_slot()
        hole = node.one("hole")
        ring, room = V.hanging_ring(p["handle_width"], p["handle_thickness"], slot) if hole else (None, 0.0)
        lug, h = CL.split_handle(pan, p["handle_length"], p["handle_angle"], p["handle_width"],
                                 p["handle_thickness"], slot, end_room=room)
        base = body.anchor("base")
        self.extend(body.root, Assembly.single("lug", lug, {"vessel": IDENTITY}).attached("vessel", to=base).pieces)
        h = self.place(h.attached("vessel", to=base), "handle")
        if hole:
            self.grow(hole, handle=h, ring=ring)
        else:
            tip = V.handle_tip(p["handle_width"], p["handle_thickness"], slot)
            self.extend(h.root, tip.attached("start", to=h.anchor("end")).pieces)
        return h

    def folding(self, node, body, pan):
        h = self._split(node, body, pan)
        self.hinge(body.root, h.root, h.anchor("fold"), SPLIT_HANDLE["fold"])

    def detachable(self, node, body, pan):
        h = self._split(node, body, pan)
        # pulled off its lug: a lift-off (the core caps the pull at a hand's)
        self.slide(body.root, h.root, h.anchor("pull"), SPLIT_HANDLE["pull"], role="lift_off")
        self.grow(node.one("release"), handle=h)

    def release(self, node, handle):
        p = self.p
        rise, end = handle.anchor("rise"), handle.anchor("end")
        rest = float(np.linalg.norm(end.origin - rise.origin))
        thick = float(handle.anchor("thickness").origin[2] - handle.anchor("vessel").origin[2])
        s = CL.release_slider(Frame.at(), rest, p["handle_width"], thick, "knob")
        # built in the rise frame's own coordinates: place it there
        s = self.place(s.placed(rise), "release")
        self.slide(handle.root, s.root, s.anchor("slide"), SPLIT_HANDLE["slide"], role="button")

    def helper(self, node, body, pan):
        h = self.place(CL.helper_handle(pan, self._handle_slot()).attached("vessel", to=body.anchor("base")),
                       "helper")
        self.join(J.fixed(body.root, h.root))

    def lid(self, node, body, pan):
        p = self.p
        glass = p["lid_finish"] == "glass"
        t = p["lid_thickness"] * (GLASS_LID_THICKER if glass else 1.0)
        lid, _ = V.dome_lid(pan, p["dome"] * p["radius"], t, "glass" if glass else "body", "rim")
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LIFT, turns=False))
        self.extend(lid.root, V.lid_knob(p["knob_radius"], "knob").attached("base", to=lid.anchor("top")).pieces)


CATEGORY = Category("pan", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PanLayout, materials={
    "body": ("finish", PAN_FAMILY), "rim": "brushed_metal", "glass": GLASS, "coating": COATING,
    "handle": ("handle_finish", HANDLE_FAMILY), "knob": KNOB,
})
