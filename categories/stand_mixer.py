"""Stand mixer: a tilt-head or bowl-lift planetary mixer, or a turntable mixer, with its bowl, beaters and levers.

Designs (``design``, sizes and sources in ``categories/parts/mixers.py``): a ``tilt_head`` mixer (KitchenAid
Artisan) whose motor head tilts back on a hinge pin (revolute), its bowl twisting out of the clamp plate on the
base (revolute), a speed lever on the head's side (revolute) and, on most models, a head lock lever on the
pedestal (revolute); a ``bowl_lift`` mixer (KitchenAid Professional) whose fixed head is over a bowl hanging on
a cradle that a handle on the pedestal raises (the handle revolute, the cradle a slide coupled to it), the bowl
lifting off the cradle's pins (lift-off); a ``turntable`` mixer (Sunbeam Mixmaster, Hamilton Beach) whose tilt
head drives two beaters beside the axis of a bowl that spins on a turntable (continuous), with a speed dial and
a beater-eject button (spring-returned: role ``button``) on the head. A KitchenAid head's attachment hub has a
thumbscrew (continuous) on most models.

X is the front (the bowl, the hub), Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Choice, Float

from .parts import controls
from .parts import mixers as M

PARAMS = (
    Float("size", "where the mixer lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Choice("finish", "housing finish (a turntable mixer is moulded plastic; a KitchenAid die-cast housing is"
           " enamelled or brushed)", choices=("enamel", "brushed_metal", "plastic"), weights=(0.7, 0.15, 0.15)),
    Choice("bowl_finish", "bowl: spun stainless steel or pressed glass", choices=("stainless", "glass"),
           weights=(0.75, 0.25)),
)

GRAMMAR = Grammar("stand_mixer", {
    "stand_mixer": Node(label="body", required=("bowl",), one_of={"tilt_head": 0.5, "bowl_lift": 0.3,
                                                                  "turntable": 0.2}, choice="design"),
    "tilt_head": Node(required=("head", "speed_lever"), optional={"lock_lever": 0.8, "hub_knob": 0.7}),
    "bowl_lift": Node(required=("cradle", "speed_lever"), optional={"hub_knob": 0.7}),
    "turntable": Node(required=("head", "dial"), optional={"eject": 0.7}),
    "head": Node(label="head"),
    "cradle": Node(label="cradle", required=("lift_handle",)),
    "lift_handle": Node(label="lever"),
    "speed_lever": Node(label="lever"),
    "lock_lever": Node(label="lever"),
    "hub_knob": Node(label="knob"),
    "dial": Node(label="knob"),
    "eject": Node(label="button"),
    "bowl": Node(label="bowl"),
})
"""The head's attachment hub (``hub_knob``) and the head lock (``lock_lever``) are KitchenAid fittings; a
turntable mixer's head has a dial and, on most, a beater-eject button."""

MATERIALS = {"body": "finish", "bowl": ("bowl_finish", {"stainless": "brushed_metal", "glass": "glass:clear"}),
             "handle": ("bowl_finish", {"stainless": "brushed_metal", "glass": "glass:clear"}),
             "trim": "chrome", "beater": "chrome", "lever": "chrome", "knob": "plastic:black|dark_grey",
             "button": "plastic:black|dark_grey", "foot": "rubber", "motor": "brushed_metal", "cradle": "finish"}
SUBSTRATES = {"body": ("finish", {"enamel": M.ZINC, "brushed_metal": M.ZINC}),
              "cradle": ("finish", {"enamel": M.ZINC, "brushed_metal": M.ZINC}), "motor": M.MOTOR_DENSITY}


def _derive(p: dict) -> dict:
    """A turntable mixer is moulded plastic; a KitchenAid housing is die-cast metal (enamelled if drawn plastic)."""
    if (p["design"] == "turntable") != (p["finish"] == "plastic"):
        return {**p, "finish": "plastic" if p["design"] == "turntable" else "enamel"}
    return p


class MixerLayout(controls.ControlFace):
    def stand_mixer(self, node):
        m = M.mixer(node.choice, self.p["size"])
        self.add("body", "body", M.body(m, "body", "foot", "motor"))
        carrier = self.grow(node.one(node.choice), m=m)
        self.grow(node.one("bowl"), m=m, carrier=carrier)

    def tilt_head(self, node, m):
        head = self.grow(node.one("head"), m=m)
        self.grow(node.one("speed_lever"), m=m, parent=head)
        for kind in ("lock_lever", "hub_knob"):
            if node.one(kind):
                self.grow(node.one(kind), m=m, parent=head)
        return "body"

    def bowl_lift(self, node, m):
        self.grow(node.one("speed_lever"), m=m, parent="body")
        if node.one("hub_knob"):
            self.grow(node.one("hub_knob"), m=m, parent="body")
        return self.grow(node.one("cradle"), m=m)

    def turntable(self, node, m):
        head = self.grow(node.one("head"), m=m)
        self.grow(node.one("dial"), m=m, head=head)
        if node.one("eject"):
            self.grow(node.one("eject"), m=m, head=head)
        return "body"

    def dial(self, node, m, head):
        self.place_dial(head, "speed_dial", M.DIAL, M.dial_anchor(m))

    def head(self, node, m):
        pieces, pin = M.head(m, "body", "motor")
        head = self.add("head", "head", pieces + M.beaters(m, "beater"))
        self.hinge("body", head, pin, upper=M.HEAD_TILT, role="lid")
        return head

    def speed_lever(self, node, m, parent):
        pieces, pivot = M.side_lever(m, M.speed_lever_at(m), 1, "lever")
        self.hinge(parent, self.add("speed_lever", "lever", pieces), pivot, upper=M.LEVER_TURN, role="knob")

    def lock_lever(self, node, m, parent):
        pieces, pivot = M.side_lever(m, M.lock_lever_at(m), -1, "lever")
        self.hinge("body", self.add("lock_lever", "lever", pieces), pivot, upper=M.LOCK_TURN, role="knob")

    def hub_knob(self, node, m, parent):
        self.spin(parent, self.add("hub_knob", "knob", M.hub_knob(m, "knob")), M.hub_anchor(m), role="knob")

    def eject(self, node, m, head):
        self.place_button(head, "eject_button", M.BUTTON, M.eject_anchor(m))

    def cradle(self, node, m):
        pieces, lift = M.cradle(m, "cradle")
        cradle = self.add("cradle", "cradle", pieces)
        self.slide("body", cradle, lift, upper=M.CRADLE_LIFT)
        handle_pieces, pivot = M.lift_handle(m, "cradle", "knob")
        self.grow(node.one("lift_handle"), pieces=handle_pieces, pivot=pivot)
        # one hand moves both: the handle's cam raises the cradle
        self.couple(cradle, "lift_handle", ratio=M.CRADLE_LIFT / M.LIFT_HANDLE_TURN)
        return cradle

    def lift_handle(self, node, pieces, pivot):
        self.hinge("body", self.add("lift_handle", "lever", pieces), pivot, upper=M.LIFT_HANDLE_TURN, role="knob")

    def bowl(self, node, m, carrier):
        sheet = M.BOWL_SHEET[self.p["bowl_finish"]]
        bowl = self.add("bowl", "bowl", M.bowl(m, "bowl", sheet, "handle"))
        axis = M.bowl_axis(m)
        if m.design == "bowl_lift":
            self.lift(carrier, bowl, axis, engagement=M.PIN)
        elif m.design == "turntable":
            self.spin("body", bowl, axis, role="turntable")
        else:
            self.hinge("body", bowl, axis, upper=M.BOWL_TWIST, role="hinge")


CATEGORY = Category("stand_mixer", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, MixerLayout, MATERIALS,
                    substrates=SUBSTRATES, derive=_derive)
