"""Blender: a countertop jug blender, a classic glass-jar blender or a personal bottle blender on its motor base.

Designs (``design``, sizes and sources in ``categories/parts/blenders.py``): a ``countertop`` blender (Vitamix,
Ninja) whose square clear jug sits on the drive pad, turns out of its lock and lifts off (a turn and a lift-off
slide: role ``lift_off``), its lid pressed into the rim (lift-off) with a cap that turns out of the lid and
lifts out (turn and lift-off), a speed dial (revolute) and switches on the base's front (spring-returned: role
``button``); a ``glass_jar`` blender (Oster) whose round glass jar twists off its base the same way, its lid and
fill cap likewise, a row of push buttons and on some a dial; a ``personal`` blender (NutriBullet) whose cup
stands upside down on its blade base in the motor base's ring, pushed and twisted in (turn and lift-off).

X is the front (the controls), Y across (the jug's handle at +Y), Z up.
"""

from __future__ import annotations

from dataclasses import replace

from infmob_usd import joints as J
from infmob_usd import lift_off
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float

from .parts import blenders as B
from .parts import casing, controls

PARAMS = (
    Float("size", "where the base lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("jug_height", "where the jug's height lies in its design's range (0 lowest, 1 tallest)", "", 0.0, 1.0),
    Choice("finish", "base finish", choices=("plastic", "brushed_metal", "painted"), weights=(0.5, 0.3, 0.2)),
)

GRAMMAR = Grammar("blender", {
    "blender": Node(label="body", required=("jug",), one_of={"countertop": 0.45, "glass_jar": 0.3, "personal": 0.25},
                    choice="design"),
    "countertop": Node(required=("lid", "dial"), repeat={"button": (0, 3)}),
    "glass_jar": Node(required=("lid",), optional={"dial": 0.3}, repeat={"button": (3, B.BUTTONS_MAX)}),
    "personal": Node(label=None),
    "jug": Node(label="jug"),
    "lid": Node(label="lid", optional={"cap": 0.85}),
    "cap": Node(label="cap"),
    "dial": Node(label="knob"),
    "button": Node(label="button"),
})
"""A countertop blender has a speed dial and up to three switches (start, pulse, a program key); a glass-jar
blender a row of 3-5 speed keys and, on some, a dial; a personal blender no lid (its blade base closes the
cup) and no switch (pressing the cup down runs it). A lid's cap (``has_cap``) is drawn object-wide."""

MATERIALS = {"body": "finish", "jug": "glass:clear",
             "collar": "plastic:black|dark_grey", "blade": "brushed_metal", "handle": "plastic:black|dark_grey",
             "lid": "plastic:black|dark_grey", "cap": "glass:clear|smoked", "knob": "plastic:black|dark_grey",
             "button": "plastic:black|dark_grey|light_grey", "trim": "chrome", "motor": "brushed_metal",
             "marks": "plastic:black|dark_grey"}
"""A Tritan jug or cup looks like clear glass (drawn as ``glass:clear``) but weighs what the copolyester does
(:data:`SUBSTRATES`)."""
SUBSTRATES = {"jug": ("design", {"countertop": B.TRITAN, "personal": B.TRITAN}), "motor": B.MOTOR_DENSITY,
              "body": ("finish", {"painted": 1100.0, "brushed_metal": 1100.0})}  # moulded ABS, painted or metallised


class BlenderLayout(controls.ControlFace):
    def blender(self, node):
        p, design = self.p, node.choice
        b = B.blender(design, p["size"], p["jug_height"])
        controls_node = node.one(design)
        if design == "personal":
            body = self.add("body", "body", B.round_base(b, "body") + [B.motor(b, "motor")])
        else:
            dial = controls_node.one("dial") is not None
            cuts = B.cutouts(b, dial, len(controls_node.of("button")))
            placed = self.place(casing.sheet_casing(B.casing_size(b), "body", cuts), "body")
            body = placed.root
            self.extend(body, B.pad(b, "collar") + [B.motor(b, "motor")])
        jug = self.grow(node.one("jug"), b=b, body=body)
        self.grow(controls_node, b=b, body=body, jug=jug, placed=None if design == "personal" else placed)

    def jug(self, node, b, body):
        jug = self.add("jug", "jug", B.jug(b, "jug", "collar", "blade", "handle") + B.marks(b, "marks"))
        twist = B.CUP_TWIST if b.design == "personal" else B.JUG_TWIST
        self._twist_off(body, jug, B.seat(b), twist, B.JUG_SEAT)
        return jug

    def _twist_off(self, parent, child, at, turn, engagement):
        """A part that turns out of its lock and then lifts off its seat (role lift_off)."""
        spec = J.revolute_prismatic(parent, child, tuple(at.origin), tuple(at.z), (0.0, turn), tuple(at.z),
                                    (0.0, lift_off.lift(engagement)), role="lift_off")
        self.join(replace(spec, engagement=engagement))

    def _controls(self, node, b, body, jug, placed):
        if node.one("lid"):
            self.grow(node.one("lid"), b=b, jug=jug)
        if node.one("dial"):
            self.grow(node.one("dial"), body=body, at=placed.anchor("dial"))
        for k, key in enumerate(node.of("button")):
            self.grow(key, body=body, at=placed.anchor(f"button_{k}"), name=f"button_{k}")

    countertop = glass_jar = _controls

    def personal(self, node, b, body, jug, placed):
        self.extend(body, B.receptacle(b, "trim"))

    def lid(self, node, b, jug):
        pieces, seat = B.lid(b, "lid")
        lid = self.add("lid", "lid", pieces)
        self.lift(jug, lid, seat, engagement=B.LID_SEAL)
        if node.one("cap"):
            self.grow(node.one("cap"), b=b, lid=lid)

    def cap(self, node, b, lid):
        pieces, seat = B.cap(b, "cap")
        self._twist_off(lid, self.add("cap", "cap", pieces), seat, B.CAP_TWIST, B.CAP_PLUG)

    def dial(self, node, body, at):
        self.place_dial(body, "dial", B.DIAL, at)

    def button(self, node, body, at, name):
        self.place_button(body, name, B.BUTTON, at)


CATEGORY = Category("blender", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BlenderLayout, MATERIALS,
                    substrates=SUBSTRATES)
