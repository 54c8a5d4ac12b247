"""Phone: a flip, slider or bar mobile phone or a corded desk phone with its handset and keypad.

Designs (``design``, sizes and sources in ``categories/parts/phones.py``): a ``flip`` phone (clamshell) lies
closed on its back, its lid over the keypad of its base; the lid turns open about the hinge barrel at the top
(revolute) and the base's keys ``requires_open`` it; a ``slider`` phone's screen half slides up off the keypad
of its lower half (prismatic; the keypad ``requires_open`` it) and carries the navigation keys under its
screen; a ``bar`` phone (candybar) carries its screen, navigation keys and keypad on one shell; a ``desk``
phone has its handset lying in the cradle on the left of its deck, lifted off it (role
``lift_off``), a numeric pad with function keys and a two-line display. Every key presses down against its
return spring (prismatic, role ``button``: 12 numeric keys, 9-13 navigation keys: d-pad, soft, call, end,
clear); a mobile phone's battery cover slides out of its back (prismatic, ``has_battery_cover``). A mobile
phone lies with its bottom (the end a hand holds) at +X, its hinge or slide opening towards -X; a desk phone's
front (its keypad) is +X, its handset on the left (-Y). Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import phones as P
from .parts import remotes as R

PARAMS = (
    Float("size", "where the width and length lie in the design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Choice("tone", "shell and key colours", choices=("dark", "grey", "light", "silver"),
           weights=(0.35, 0.2, 0.25, 0.2)),
)

GRAMMAR = Grammar("phone", {
    "phone": Node(label="body", one_of={"flip": 0.27, "slider": 0.22, "bar": 0.23, "desk": 0.28}, choice="design"),
    "flip": Node(required=("lid", "nav_keys", "keypad"), optional={"battery_cover": 0.7}),
    "slider": Node(required=("slider_half", "keypad"), optional={"battery_cover": 0.7}),
    "bar": Node(required=("nav_keys", "keypad"), optional={"battery_cover": 0.8}),
    "desk": Node(required=("handset", "keypad", "function_keys")),
    "lid": Node(label="lid"),
    "slider_half": Node(label="slider", required=("nav_keys",)),
    "nav_keys": Node(repeat={"key": (9, 13)}),
    "keypad": Node(repeat={"key": 12}),
    "function_keys": Node(repeat={"key": (3, 10)}),
    "handset": Node(label="handset"),
    "key": Node(label="button"),
    "battery_cover": Node(label="door"),
})
"""Keys: 1-9, *, 0, # on every phone; a mobile's d-pad (OK and four arrows), two soft keys, call and end and up to
four of clear, menu, camera, music (Motorola RAZR V3, Nokia 6500 slide); a desk phone's 3-10 function keys
(hold, redial, speaker, mute, volume, memory: Panasonic KX-TS500, Cisco 7911)."""

TONES = {"dark": ("plastic:black", "plastic:dark_grey"), "grey": ("plastic:dark_grey", "plastic:black"),
         "light": ("plastic:white", "plastic:light_grey"), "silver": ("plastic:light_grey", "plastic:dark_grey")}
"""Shell and key colours sold together: black with grey keys, graphite with black (Nokia), white with grey
(office desk phones), silver with dark keys (RAZR V3's painted finish)."""

MATERIALS = {
    "body": ("tone", {t: body for t, (body, _) in TONES.items()}),
    "key": ("tone", {t: key for t, (_, key) in TONES.items()}),
    "call": "plastic:green", "power": "plastic:red", "trim": "chrome", "screen": "screen:black|blue_black",
    "lens": "screen:black", "lcd": "plastic:light_grey",
}


TURNED = Frame.at((0, 0, 0), x=(-1, 0, 0), z=(0, 0, 1))
"""A mobile phone's parts are drawn with its top at +x and turned half round, so that it lies as it is picked up:
its bottom (the mouthpiece, the end a hand holds) towards the front, the flip or slide opening away."""


class PhoneLayout(Layout):
    def phone(self, node):
        kit = node.one(node.choice)
        counts = {c.kind: len(c.of("key")) for c in kit.walk() if c.of("key")}
        size, design = self.p["size"], node.choice
        if design == "flip":
            self.plan = P.flip_plan(size, counts["nav_keys"], counts["keypad"])
            self.order = {"nav_keys": (0, 0), "keypad": (1, 0)}
            extra = P.flip_base_hinge(self.plan, "body")
        elif design == "bar":
            self.plan = P.bar_plan(size, counts["nav_keys"], counts["keypad"])
            self.order = {"nav_keys": (0, 0), "keypad": (1, 0)}
            extra = P.bar_face(self.plan, "screen", "lens")
        elif design == "slider":
            self.plan = P.slider_base_plan(size, counts["keypad"])
            self.up = P.slider_plan(self.plan, counts["nav_keys"])
            self.order = {"keypad": (0, 0)}
            extra = []
        else:
            self.plan = P.desk_plan(size, counts["keypad"], counts["function_keys"])
            self.order = {"keypad": (0, 0), "function_keys": (0, counts["keypad"])}
            extra = [*P.desk_display(self.plan, "lcd", "lens"), *P.desk_cradle(self.plan, "body")]
        self.turn = IDENTITY if design == "desk" else TURNED
        body = R.body(self.plan, "body", door=design != "desk")
        self.add("body", "body", [pc.transformed(self.turn.matrix) for pc in [body, *R.section_trim(self.plan),
                                                                              *extra]])
        self.grow(kit)

    def _kit(self, node):
        for child in node.children:  # the lid or screen half first: the keys under it wait for it
            if child.kind not in self.order:
                self.grow(child)
        gate = {"flip": "lid", "slider": "slider"}.get(node.kind)
        for child in node.children:
            if child.kind in self.order:
                self.grow(child, parent="body", gate=gate)

    flip = slider = bar = desk = _kit

    def nav_keys(self, node, parent, gate, anchors=None):
        if anchors is not None:  # on the screen half: its own anchors
            for k, key in enumerate(node.of("key")):
                spot = self.up.sections[0].spots[k]
                self.grow(key, at=anchors[f"key_{k}"], spot=spot, name=f"nav_{k}", parent=parent, gate=None)
            return
        self.keypad(node, parent, gate)

    def keypad(self, node, parent, gate):
        section, first = self.order[node.kind]
        spots = self.plan.sections[section].spots[first:]
        for k, (key, spot) in enumerate(zip(node.of("key"), spots, strict=False)):
            at = self.turn @ self.plan.key_frame(section, spot)
            self.grow(key, at=at, spot=spot, name=f"{node.kind}_{k}", parent=parent, gate=gate)

    function_keys = keypad

    def key(self, node, at, spot, name, parent, gate):
        placed = self.place(spot.key.build(spot.slot).attached("mount", to=at), name)
        self.slide(parent, placed.root, placed.anchor("press"), upper=spot.key.travel, role="button",
                   requires_open=gate)

    def lid(self, node):
        lid = self.place(P.flip_lid(self.plan, "body", "screen", "lens").placed(self.turn), "lid")
        self.hinge("body", lid.root, lid.anchor("hinge"), upper=P.FLIP_OPENS, role="lid")

    def slider_half(self, node):
        half = self.place(P.slider_half(self.up, P.slider_lift(self.plan), "body", "screen").placed(self.turn),
                          "slider")
        self.slide("body", half.root, half.anchor("slide"), upper=P.slider_travel(self.plan))
        anchors = {f"key_{k}": half.anchor(f"key_{k}") for k in range(len(self.up.sections[0].spots))}
        self.grow(node.one("nav_keys"), parent=half.root, gate=None, anchors=anchors)

    def handset(self, node):
        hs = self.place(P.handset(self.plan, "body"), "handset")
        self.lift("body", hs.root, hs.anchor("lift"), engagement=None)

    def battery_cover(self, node):
        door = self.place(R.battery_door(self.plan, "body").placed(self.turn), "battery_cover")
        self.slide("body", door.root, door.anchor("slide"), upper=R.door_travel(self.plan))


CATEGORY = Category("phone", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PhoneLayout, MATERIALS)
