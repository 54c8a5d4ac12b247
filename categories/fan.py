"""Fan: a desk fan, a pedestal (stand) fan, a box fan or a ceiling fan, its bladed rotor spinning freely.

Designs (``design``, sizes and sources in ``categories/parts/fans.py``): a ``desk`` fan whose motor head tilts
(revolute about the horizontal across it) on a neck that oscillates (revolute about the vertical, or fixed on a
fan that does not), its rotor spinning on the motor's shaft (continuous), 0-3 grille clips that flip back to free
the front grille (revolute), maybe an oscillation knob on the motor pulled up to stop it (prismatic), on the
base's front a row of 2-5 speed keys (spring-returned: role ``button``) or a speed knob (revolute), maybe a timer
knob on its side; a ``pedestal`` fan the same on an upper pole that slides up out of the lower tube (prismatic,
role ``telescope``) carrying the control pod under the head; a ``box`` fan whose rotor spins in a square frame
between flat grilles, a speed knob and maybe a timer knob on the top; a ``ceiling`` fan standing on its switch
housing as it is unboxed, its motor shell with the blade irons and blades spinning about the downrod's axis
(continuous) and maybe a forward/reverse slide switch on the housing (prismatic).

X is the front (where the air goes: a ceiling fan's axis is Z), Y across, Z up.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category, Same
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import casing, controls
from .parts import fans as F

PARAMS = (
    Float("size", "where the blade diameter lies in its design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("height", "where the height (hub of a desk or stand fan, square of a box fan, downrod of a ceiling"
          " fan) lies in its design's range", "", 0.0, 1.0),
    Int("blades", "blades on the rotor", "", 3, 5),
    Choice("finish", "body finish", choices=("plastic", "painted", "brushed_metal"), weights=(0.55, 0.3, 0.15)),
    Choice("grille_finish", "grille wire finish", choices=("chrome", "painted", "plastic"), weights=(0.3, 0.3, 0.4)),
    Choice("blade_finish", "blades: opaque moulded plastic or clear (drawn as glass, massed as polypropylene)",
           choices=("plastic", "glass"), weights=(0.6, 0.4)),
    Choice("board_finish", "a ceiling fan's blade boards", choices=("wood", "painted"), weights=(0.6, 0.4)),
)

GRAMMAR = Grammar("fan", {
    "fan": Node(one_of={"desk": 0.35, "pedestal": 0.35, "box": 0.15, "ceiling": 0.15}, choice="design"),
    "desk": Node(label="body", required=("neck", "controls")),
    "pedestal": Node(label=("body", "pole"), required=("neck", "controls")),
    "box": Node(label="body", required=("rotor", "speed_knob"), optional={"timer": 0.4}),
    "ceiling": Node(label="body", required=("rotor",), optional={"reverse": 0.6}),
    "neck": Node(one_of={"oscillating": 0.8, "fixed": 0.2}, choice="oscillation"),
    "oscillating": Node(label="neck", required=("head",), optional={"osc_knob": 0.5}),
    "osc_knob": Node(label="knob"),
    "fixed": Node(label="neck", required=("head",)),
    "head": Node(label="head", required=("rotor",), repeat={"latch": (0, 3)}),
    "rotor": Node(label="rotor"),
    "latch": Node(label="latch"),
    "controls": Node(one_of={"keys": 0.6, "speed_knob": 0.4}, choice="control", optional={"timer": 0.35}),
    "keys": Node(repeat={"key": (2, 5)}),
    "key": Node(label="button"),
    "speed_knob": Node(label="knob"),
    "timer": Node(label="knob"),
    "reverse": Node(label="switch"),
})
"""A desk or stand fan's neck oscillates unless ``oscillation`` is ``fixed``; its head has 0-3
grille clips and, on an oscillating fan, maybe a knob on the motor that is pulled up to stop the oscillation;
its speed control is a row of keys (off and 1-4 speeds) or a knob, maybe with a timer knob on the side. A box fan
has a speed knob and maybe a timer knob; a ceiling fan maybe a forward/reverse switch."""

MATERIALS = {"body": "finish", "grille": "grille_finish", "blade": "blade_finish", "hub": "plastic:black|white",
             "badge": "chrome", "motor": "brushed_metal", "weight": "brushed_metal",
             "button": "plastic:black|dark_grey|light_grey|white", "knob": "plastic:black|dark_grey|white",
             "trim": "chrome", "latch": Same("body"), "board": "board_finish", "iron": "brushed_metal",
             "rod": Same("body")}
SUBSTRATES = {"body": ("finish", {"painted": 1100.0, "brushed_metal": 1100.0}),  # moulded ABS, painted or plated
              "blade": ("blade_finish", {"glass": 905.0}),  # clear blades are polypropylene (0.905 g/cm^3)
              "board": ("board_finish", {"painted": 750.0}),  # painted MDF boards
              "badge": 1100.0}  # a chrome-plated ABS badge

KEY = controls.Button(half=(0.009, 0.007), shape="rect", proud=0.008, travel=0.005)  # piano keys, 18 mm wide
KNOB = controls.Dial(radius=0.018, stem=0.004, style="ridge", turns=1.57)  # off and three speeds: a quarter turn
KEY_PITCH = 0.024
KEY_ROW = 0.875  # a column of keys down a pod's front is packed to 21 mm


class FanLayout(controls.ControlFace):
    def fan(self, node):
        self.grow(node.one(node.choice))

    def _scale(self, design):
        d, p = F.DESIGNS[design], self.p
        def lerp(r, t):
            return r[0] + t * (r[1] - r[0])
        return lerp(d.diameter, p["size"]) / 2, lerp(d.height, p["height"]), p["blades"]

    def desk(self, node):
        r, hub_z, blades = self._scale("desk")
        h = F.head("desk", r, blades, hub_z)
        width = F.DESK_BASE[0] + self.p["size"] * (F.DESK_BASE[1] - F.DESK_BASE[0])
        size, at, weight = F.desk_base(h.pivot[0], width, "body", "weight")
        cuts = self._control_cuts(node.one("controls"), size)
        body = self.place(casing.sheet_casing(size, "body", cuts).placed(at), "body")
        self.extend(body.root, [weight, F.pole(h.pivot[0], size.height - 0.002, self._neck_low(h), F.STEM_R, "body",
                                               False)])
        self.grow(node.one("neck"), parent=body.root, h=h)
        self.grow(node.one("controls"), parent=body.root, placed=body)

    def pedestal(self, node):
        r, hub_z, blades = self._scale("pedestal")
        h = F.head("pedestal", r, blades, hub_z)
        x, p = h.pivot[0], self.p
        radius = F.PEDESTAL_BASE[0] + p["size"] * (F.PEDESTAL_BASE[1] - F.PEDESTAL_BASE[0])
        pod = F.pod_size()
        z_pod = self._neck_low(h) - pod.height
        z_tube = z_pod - 0.05  # a hand's width of the upper pole shows at its lowest
        body = self.add("body", "body", F.round_base(x, radius, "body", "weight")
                        + [F.pole(x, 0.046, z_tube, F.POLE_R[0], "rod", True)])
        cuts = self._control_cuts(node.one("controls"), pod, column=True)
        placed = self.place(casing.sheet_casing(pod, "body", cuts, label="pole").placed(Frame.at((x, 0, z_pod))),
                            "pole")
        inserted = min(F.POLE_TRAVEL + 0.03, z_tube - 0.06)  # in the tube at full height, above the base
        self.extend(placed.root, [F.pole(x, z_tube - inserted, z_pod + 0.002, F.POLE_R[1], "rod", False)])
        self.slide(body, placed.root, Frame.at((x, 0, z_tube)), upper=F.POLE_TRAVEL, role="telescope")
        self.grow(node.one("neck"), parent=placed.root, h=h)
        self.grow(node.one("controls"), parent=placed.root, placed=placed)

    @staticmethod
    def _neck_low(h):
        return h.pivot[2] - 0.08

    @staticmethod
    def _control_cuts(controls_node, size, column=False):
        """The speed knob, or the keys: in a row across a base's front, in a column down a pod's front; a timer
        knob on the left side."""
        timer = {"timer": KNOB.cutout("left", (0.0, 0.0))} if controls_node.one("timer") else {}
        if controls_node.choice == "speed_knob":
            return {"knob": KNOB.cutout("front", size.on("front", 0.0, 0.0)), **timer}
        n = len(controls_node.one("keys").of("key"))
        at = [((k - (n - 1) / 2) * KEY_PITCH, 0.0) for k in range(n)]
        return {**{f"key_{k}": KEY.cutout("front", (0.0, -v * KEY_ROW) if column else (v, 0.0))
                   for k, (v, _) in enumerate(at)}, **timer}

    def controls(self, node, parent, placed):
        self.grow(node.one(node.choice), parent=parent, at=placed.anchor("knob") if node.choice == "speed_knob"
                  else placed)
        if node.one("timer"):
            self.grow(node.one("timer"), parent=parent, at=placed.anchor("timer"))

    def keys(self, node, parent, at):
        for k, key in enumerate(node.of("key")):
            self.grow(key, parent=parent, at=at.anchor(f"key_{k}"), name=f"button_{k}")

    def key(self, node, parent, at, name):
        self.place_button(parent, name, KEY, at)

    def speed_knob(self, node, parent, at, name="knob"):
        self.place_dial(parent, name, KNOB, at)

    def neck(self, node, parent, h):
        self.grow(node.one(node.choice), parent=parent, h=h)

    def oscillating(self, node, parent, h):
        pieces, axis = F.neck(h, self._neck_low(h), "body")
        neck = self.add("neck", "neck", pieces)
        if node.kind == "oscillating":
            self.hinge(parent, neck, axis, upper=F.OSCILLATES, role="swivel")
        else:
            self.fix(parent, neck)
        head = self.grow(node.one("head"), neck=neck, h=h)
        if node.kind == "oscillating" and node.one("osc_knob"):
            self.grow(node.one("osc_knob"), head=head, h=h)

    fixed = oscillating

    def osc_knob(self, node, head, h):
        pieces, axis = F.osc_pin(h, "knob")
        self.slide(head, self.add("osc_knob", "knob", pieces), axis, upper=F.PIN[3])

    def head(self, node, neck, h):
        pieces = F.grille(h, "grille", "badge") + F.motor(h, "body", "motor") + F.neck_bracket(h, "body")
        head = self.add("head", "head", pieces)
        self.hinge(neck, head, F.tilt_axis(h), upper=F.TILT)
        pieces, axis = F.head_rotor(h, "blade", "hub")
        self.grow(node.one("rotor"), parent=head, pieces=pieces, axis=axis)
        for k, clip in enumerate(node.of("latch")):
            self.grow(clip, head=head, h=h, angle=(0.0, math.pi / 2, -math.pi / 2)[k], name=f"latch_{k}")  # top, sides
        return head

    def rotor(self, node, parent, pieces, axis):
        self.spin(parent, self.add("rotor", "rotor", pieces), axis, role="wheel")

    def latch(self, node, head, h, angle, name):
        pieces, hinge = F.latch(h, angle, "latch")
        self.hinge(head, self.add(name, "latch", pieces), hinge, upper=F.LATCH_OPENS)

    def box(self, node):
        r, side, blades = self._scale("box")
        b = F.box_fan(r, side, blades, 1 + (node.one("timer") is not None), KNOB.stem)
        body = self.add("body", "body", b.body)
        self.grow(node.one("rotor"), parent=body, pieces=b.rotor, axis=b.axis)
        self.grow(node.one("speed_knob"), parent=body, at=b.knobs[0])
        if node.one("timer"):
            self.grow(node.one("timer"), parent=body, at=b.knobs[1])

    def timer(self, node, parent, at):
        self.place_dial(parent, "timer", KNOB, at)

    def ceiling(self, node):
        r, downrod, blades = self._scale("ceiling")
        pieces, at, rs = F.ceiling_body(r, downrod, "body", "rod")
        body = self.add("body", "body", pieces)
        rotor = F.ceiling_rotor(r, blades, rs, at, "body", "iron", "board")
        self.grow(node.one("rotor"), parent=body, pieces=rotor, axis=at)
        if node.one("reverse"):
            self.grow(node.one("reverse"), body=body)

    def reverse(self, node, body):
        pieces, axis = F.reverse_switch("knob")
        self.slide(body, self.add("switch", "switch", pieces), axis, upper=F.REVERSE_TRAVEL)


CATEGORY = Category("fan", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, FanLayout, MATERIALS,
                    substrates=SUBSTRATES, palette=appliance)
