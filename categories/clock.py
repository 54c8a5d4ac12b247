"""Clock: a wall clock, a mantel clock with a pendulum, or a twin-bell alarm clock, its hands showing a time.

Designs (``design``, sizes and sources in ``categories/parts/clocks.py``): a ``wall`` clock (a round moulded case,
a printed dial, hour and minute hands and maybe a second hand, each continuous about the arbor, and a quartz
movement's setting knob at the back, continuous); a ``mantel`` clock (a wooden case on a plinth; its hands behind a
glass bezel hinged on its left, revolute, which must be open before the hands are turned; a pendulum swinging
behind a window below the dial, revolute about its pivot, resting where it hangs; maybe a silent/chime lever on its
side, revolute; a setting knob at the back); an ``alarm`` clock (a twin-bell drum on two legs: hour, minute, second
and alarm hands, an alarm-off plunger on top pressed down against its spring, prismatic, role ``button``, time and
alarm setting knobs at the back, continuous, and maybe two winding keys, continuous).

The dial is printed: 60 minute ticks and 12 hour batons or Roman numerals. The hands show ``time`` at rest.
X is the dial's facing direction, Y across, Z up; a wall clock's back is the wall plane (-X), and it stands on its
rim (simulators fix its base, as on a wall).
"""

from __future__ import annotations

from infmob_usd.category import Category, Same
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import clocks as K

PARAMS = (
    Float("size", "where the clock lies in its design's size range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("depth", "where the case's depth lies in its design's range", "", 0.0, 1.0),
    Float("time", "the time the hands show at rest", "h", 0.0, 12.0),
    Choice("numerals", "hour marks printed on the dial", choices=("roman", "batons")),
    Choice("finish", "case finish (a mantel case is wood or painted wood; an alarm clock's drum is metal)",
           choices=("wood", "painted", "plastic", "brushed_metal", "chrome")),
)

GRAMMAR = Grammar("clock", {
    "clock": Node(label="body", required=("hour", "minute"), one_of={"wall": 0.4, "mantel": 0.3, "alarm": 0.3},
                  choice="design"),
    "wall": Node(required=("set_knob",), optional={"second": 0.6}),
    "mantel": Node(required=("bezel", "pendulum", "set_knob"), optional={"second": 0.6, "chime_lever": 0.5}),
    "alarm": Node(required=("second", "alarm_hand", "alarm_button", "set_knob", "alarm_knob"),
                  optional={"wind_keys": 0.5}),
    "hour": Node(label="hand"),
    "minute": Node(label="hand"),
    "second": Node(label="hand"),
    "alarm_hand": Node(label="hand"),
    "bezel": Node(label="door"),
    "pendulum": Node(label="pendulum"),
    "chime_lever": Node(label="lever"),
    "alarm_button": Node(label="button"),
    "set_knob": Node(label="knob"),
    "alarm_knob": Node(label="knob"),
    "wind_keys": Node(repeat={"wind_key": 2}),
    "wind_key": Node(label="knob"),
})

MATERIALS = {"body": "finish", "dial": "painted:white|off_white|retro_cream|pastel_yellow",
             "marks": "painted:black|charcoal|navy", "hand": Same("marks"), "second": "plastic:red|black",
             "trim": "chrome", "glass": "glass:clear", "knob": "plastic:black|dark_grey", "pendulum": "chrome"}


def _derive(p: dict) -> dict:
    if p["design"] == "mantel" and p["finish"] not in ("wood", "painted"):
        return {**p, "finish": "wood"}
    if p["design"] == "alarm" and p["finish"] in ("wood", "plastic"):
        return {**p, "finish": "painted" if p["finish"] == "wood" else "chrome"}
    return p


class ClockLayout(Layout):
    def clock(self, node):
        p = self.p
        c = K.make(node.choice, p["size"], p["depth"])
        self.add("body", "body", K.case(c, "body", "trim", p["finish"]) + [K.dial(c, "dial"), K.marks(c, p["numerals"],
                                                                                                    "marks")])
        angles = K.hand_angles(p["time"])
        gate = "bezel" if node.choice == "mantel" else None
        self.grow(node.one(node.choice), c=c, angles=angles, gate=gate)  # a mantel clock's bezel before its hands
        for kind in ("hour", "minute"):
            self.grow(node.one(kind), c=c, angles=angles, gate=gate)

    def _hand(self, node, c, angles, gate):
        kind = "alarm" if node.kind == "alarm_hand" else node.kind
        slot = "second" if kind == "second" else "hand"
        pieces, arbor = K.hand(c, kind, angles[kind], slot)
        self.spin("body", self.add(f"{kind}_hand", "hand", pieces), arbor, requires_open=gate)

    hour = minute = second = alarm_hand = _hand

    def _design(self, node, c, angles, gate):
        for kid in node.children:
            self.grow(kid, c=c, angles=angles, gate=gate)

    wall = mantel = alarm = _design

    def bezel(self, node, c, angles, gate):
        pieces, hinge = K.bezel(c, "trim", "glass")
        self.hinge("body", self.add("bezel", "door", pieces), hinge, upper=K.BEZEL_OPENS)

    def pendulum(self, node, c, angles, gate):
        pieces, pivot, swing = K.pendulum(c, "pendulum")
        self.hinge("body", self.add("pendulum", "pendulum", pieces), pivot, lower=-swing, upper=swing, role="swivel")

    def chime_lever(self, node, c, angles, gate):
        pieces, pivot, turn = K.chime_lever(c, "knob")
        self.hinge("body", self.add("chime_lever", "lever", pieces), pivot, upper=turn, role="knob")

    def set_knob(self, node, c, angles, gate):
        if c.design == "alarm":  # the setting knobs low on the back, the winding keys (if any) above them
            self._knob("set_knob", c, 0.5 * c.radius, -0.5 * c.radius)
        else:
            self._knob("set_knob", c, 0.0, 0.0)

    def alarm_knob(self, node, c, angles, gate):
        self._knob("alarm_knob", c, -0.5 * c.radius, -0.5 * c.radius)

    def wind_keys(self, node, c, angles, gate):
        for k, kid in enumerate(node.of("wind_key")):
            self.grow(kid, c=c, k=k)

    def wind_key(self, node, c, k):
        self._knob(f"wind_key_{k}", c, (2 * k - 1) * 0.5 * c.radius, 0.45 * c.radius)

    def _knob(self, name, c, dy, dz):
        pieces, axis = K.back_knob(c, dy, dz, "knob")
        self.spin("body", self.add(name, "knob", pieces), axis)

    def alarm_button(self, node, c, angles, gate):
        pieces, press = K.alarm_button(c, "trim")
        self.slide("body", self.add("alarm_button", "button", pieces), press, upper=K.BUTTON_TRAVEL, role="button")


CATEGORY = Category("clock", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ClockLayout, MATERIALS,
                    derive=_derive)
