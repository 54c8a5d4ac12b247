"""Safe: a fire-rated home safe, a hotel in-room safe or a tall gun cabinet, with a heavy hinged door.

Designs (``design``): a home safe opens by a combination dial (continuous) or a 12-key keypad; a hotel safe by a
keypad; a gun cabinet by either. Every door has a three-spoke bolt handle that turns a quarter turn and is hinged
on either side (``hand``); a home safe or a gun cabinet may hold an inner drawer under its ceiling that slides out
once the door is open (``requires_open``). Keys are pressed into the door's front (along -x) and spring back
(role ``button``). Parts: ``categories/parts/safes.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float

from .parts import controls
from .parts import safes as S

LOCKS = {"dial": 0.5, "keypad": 0.5}

GRAMMAR = Grammar("safe", {
    "safe": Node(label="body", one_of={"home_safe": 0.45, "hotel_safe": 0.25, "gun_cabinet": 0.3}, choice="design"),
    "home_safe": Node(required=("door",), optional={"drawer": 0.6}),
    "hotel_safe": Node(required=("hotel_door",)),
    "gun_cabinet": Node(required=("door",), optional={"drawer": 0.6}),
    "door": Node(label="door", required=("handle",), one_of=LOCKS, choice="lock"),
    "hotel_door": Node(label="door", required=("handle", "keypad")),
    "dial": Node(label="knob"),
    "keypad": Node(repeat={"key": S.KEY_GRID[0] * S.KEY_GRID[1]}),
    "key": Node(label="button"),
    "handle": Node(label="handle"),
    "drawer": Node(label="drawer"),
})
"""Designs: home safe (dial or keypad, maybe an inner drawer), hotel safe (keypad), gun cabinet (dial or keypad,
maybe a top drawer). The lock is a combination dial or a 12-key keypad (``lock``)."""

PARAMS = (
    Float("width_share", "width (Y) within the design's range (SIZES in parts/safes.py), 0 to 1", "", 0.0, 1.0),
    Float("depth_share", "depth (X) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("height_share", "height (Z) within the design's range, 0 to 1", "", 0.0, 1.0),
    Choice("hand", "the side the door is hinged on, seen from the front", choices=("left", "right")),
)

# home safes, hotel safes and gun cabinets come black or graphite (SentrySafe, Honeywell, Elsafe, Stack-On ranges);
# inside, grey felt
MATERIALS = {"body": "enamel:black|graphite|anthracite", "knob": "chrome", "lining": "fabric:grey",
             "trim": "plastic:black", "button": "plastic:black|dark_grey", "handle": "chrome", "drawer": "enamel:black",
             "hinge": Same("handle")}

# where the lock and the handle sit on the door's front, as fractions of its half width and half height
# (from the hinge side: u > 0 is away from the hinge); a tall cabinet's lock at hand height
DIAL_AT, KEYPAD_AT, HANDLE_AT = (0.0, 0.3), (0.0, 0.2), (0.45, -0.25)
CABINET_AT = 0.15  # a gun cabinet's lock and handle sit around this fraction of its half height above centre


class SafeLayout(controls.ControlFace):
    def safe(self, node):
        p, design = self.p, node.choice
        (w0, w1), (d0, d1), (h0, h1) = S.SIZES[design]
        w, d, h = (lo + p[k] * (hi - lo) for (lo, hi), k in zip(((w0, w1), (d0, d1), (h0, h1)),
                                                                  ("width_share", "depth_share", "height_share")))
        self.build, self.size = S.BUILD[design], (w, d, h)
        body = self.place(S.body(w, d, h, self.build, "body"), "body")
        self.side = "hinge_neg" if p["hand"] == "left" else "hinge_pos"
        self.sign = -1.0 if p["hand"] == "left" else 1.0  # face u (along -y) away from the hinge
        self.lift = CABINET_AT if design == "gun_cabinet" else 0.0
        self.grow(node.one(design), body=body)

    def home_safe(self, node, body):
        self.grow(node.one("door"), body=body)
        if node.one("drawer"):
            self.grow(node.one("drawer"), body=body)

    def gun_cabinet(self, node, body):
        w, d, h = self.size
        self.extend(body.root, S.barrel_comb(w, d, h, self.build.wall))
        self.home_safe(node, body)

    def hotel_safe(self, node, body):
        self.grow(node.one("hotel_door"), body=body)

    def _at(self, frac):
        w, _, h = self.size
        return (self.sign * frac[0] * w / 2, (frac[1] + self.lift) * h / 2)

    def _door(self, node, body, lock):
        w, _, h = self.size
        cuts = {"handle": S.handle_cutout(self._at(HANDLE_AT))}
        if lock == "dial":
            cuts["dial"] = S.DIAL.cutout("front", self._at(DIAL_AT))
        else:
            cuts.update(S.keypad_cutouts(self._at(KEYPAD_AT)))
        # the door is painted as the body
        made = S.door(w, h, self.build, "body", cuts).attached(self.side, to=body.anchor(self.side))
        door = self.place(made, "door")
        on_body, on_door = S.hinges(self.size[1], w, h, self.build, -1 if self.side == "hinge_neg" else 1, "hinge")
        self.extend(body.root, on_body)
        self.extend(door.root, on_door)
        self.hinge(body.root, door.root, body.anchor(self.side), upper=self.build.opens)
        self.grow(node.one("handle"), door=door)
        self.grow(node.one(lock), door=door)

    def door(self, node, body):
        self._door(node, body, node.choice)

    def hotel_door(self, node, body):
        self._door(node, body, "keypad")

    def dial(self, node, door):
        self.place_dial(door.root, "dial", S.DIAL, door.anchor("dial"))

    def keypad(self, node, door):
        for i, kid in enumerate(node.of("key")):
            self.grow(kid, door=door, i=i)

    def key(self, node, door, i):
        self.place_button(door.root, f"key_{i}", S.KEY, door.anchor(f"key_{i}"))

    def handle(self, node, door):
        at = door.anchor("handle")
        made = self.place(S.spoke_handle("handle").attached("mount", to=at), "handle")
        self.hinge(door.root, made.root, made.anchor("axis"), upper=S.HANDLE_TURN, role="knob")

    def drawer(self, node, body):
        w, d, _ = self.size
        t = self.build.wall
        made = S.drawer(w - 2 * t, d - t, "drawer").attached("front", to=body.anchor("drawer"))
        box = self.place(made, "drawer")
        self.slide(body.root, box.root, box.anchor("front"), upper=S.DRAWER["pull"] * S.DRAWER["share"] * (d - t),
                   requires_open="door")


CATEGORY = Category("safe", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, SafeLayout, MATERIALS,
                    palette=appliance)
