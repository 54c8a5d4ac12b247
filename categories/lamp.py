"""Lamp: desk and floor lamps with a weighted base, a telescoping pole and a shaded head.

X is depth (the head reaches out toward +X), Y is width, Z is up. Every lamp has
a base (a round or square plate, a domed foot, a tripod, or on a desk lamp a desk clamp whose
spindle turns and rises to grip the desk top: continuous-prismatic; a clamp lamp hangs with its
upper jaw on a desk top ``DESK_TOP`` up), a lower pole that is a hollow
tube standing on it and an upper pole that turns in the tube and pulls up out of
it (revolute-prismatic); a floor lamp's pole may have two stages: a middle tube
turns and slides in the lower one, the upper pole slides (prismatic) in the middle one. At rest
the upper pole is collapsed, resting on its stop (slide 0), and extends upward by a quarter of its
visible length. On top of the
upper pole, ``arm_style`` decides:

* ``straight``: the head sits on the pole top (a table or classic floor lamp):
  a collar around the pole carries the socket, the bulb stands up in it and the
  shade is held around the bulb by thin spokes; the head turns about the pole.
* ``curved``: a fixed arc of tube rises from the pole and bends forward; the
  head hangs from its end. A desk lamp's head tilts (revolute about Y); a floor
  (arc) lamp's head turns on a pin (continuous about Z).
* ``chain``: 2-3 arm segments like an architect lamp. The first segment pitches
  about Y at the top of the short riser; each later one either pitches too or is
  a horizontal swing arm that swivels on a vertical pin (+-pi/2). A pitch joint
  rests on its stop and only lifts what it carries (up to pi/6, see below). Pitch
  joints alternate a single central bar with a pair of twin side bars, so the two
  parts of a hinge sit side by side and never pass through each other. The head
  hangs from the last segment and tilts.

Hanging heads are a cap over the shade's top ring with the socket under it. An
upright head's bulb (optional) screws out of its socket (continuous-prismatic:
turns freely and slides up to 12 mm out, gravity seats it again); a hanging bulb
only turns in its socket (continuous): gravity would pull it out of a free slide.
An optional switch on the base: a push button sticking out of a small housing, pressed
horizontally toward the pole, a rotary dimmer knob turning about z on the base's top, or a rocker switch
on the base's top (its paddle tilts between two stops about the base's tangent); or, on an
upright head, the knob of a turn-knob socket sticking out of the socket's side (continuous about
its own radial axis).

Every passive joint is still at rest under gravity (PhysX joint friction holds
neither a slide along gravity nor a loaded hinge): swivels about Z are neutral;
the pole and a standing bulb rest on their lower stop with gravity pressing them
into it; the switch slides horizontally; a hanging head's tilt hinge carries its
centre of mass straight below the pivot (balanced, so it keeps +-``head_tilt``);
and every other hinge about a horizontal axis gets the axis sign that makes the
gravity torque of what it carries push toward negative q, with limits
``(0, a)``: it rests on its lower stop and can be lifted (the core's
:func:`infmob_usd.physical.rest_on_stops` picks that side from the real link masses).

Shade shapes are shells of revolution (cone, drum, dome, bell); their collision
pieces are wedges, so a shade stays hollow around its bulb. The height of the
lamp at rest (pole collapsed) is exactly ``desk_height`` or ``floor_height``.

Limits are chosen so nothing enters anything or goes below the floor at any
joint limit: an arm is long enough that its head, tilted or swung down, stays
clear of the bars behind it, and a head too big for a short lamp is shrunk.
The arm is designed for a pitch range of -pi/6 (forward; less only if the head
would still reach the ground) to +pi/6 (lifted back); the core's ``rest_on_stops`` then
keeps the side that lifts the load (in practice the lift: every arm carries its
head in front of its hinges), so the final range lies in a range known to be
clear; a desk arc's tilted head keeps a pole slide of room above the base. So that the lamp
stands: poles, arm bars and the bulb's glass are thin walls (their collision
pieces are solid), a steel weight hidden in the base (no collision) carries most
of the mass, and an arm lamp's base radius is at least ``BASE_PER_REACH`` times
the reach of its head.
"""

from __future__ import annotations

import math

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import BULB_GLASS, furniture
from infmob_usd.params import Choice, Float, Int

from .parts import lamps as L

GRAMMAR = Grammar("lamp", {
    "lamp": Node(label="base", required=("pole", "arm"), optional={"bulb": 0.6, "switch": 0.8, "screw": 0.15}),
    "pole": Node(label="pole"),
    "screw": Node(label="screw"),
    "arm": Node(one_of={"straight": 0.35, "curved": 0.2, "chain": 0.45}, choice="arm_style"),
    "straight": Node(required=("head",)),
    "curved": Node(label="arm", required=("head",)),
    "chain": Node(label="arm", required=("head",)),
    "head": Node(label="head", required=("shade",)),
    "shade": Node(label="shade"),
    "bulb": Node(label="bulb"),
    "switch": Node(one_of={"push_switch": 0.3, "rotary_switch": 0.25, "rocker_switch": 0.15, "socket_switch": 0.3},
                   choice="switch_kind"),
    "push_switch": Node(label="switch"),
    "rocker_switch": Node(label="switch"),
    "rotary_switch": Node(label="switch"),
    "socket_switch": Node(label="switch"),
})
"""A ``straight`` arm is a head on the pole top; ``curved`` an arc the head hangs from; ``chain`` 2-3
segments like an architect lamp (the segments after the first pitch or swing, drawn per segment).
Every head carries its shade. A switch is a push button or a rotary dimmer on the base, or the turn knob of the
socket of an upright head (a table lamp's keyed socket). A desk clamp's spindle (``screw``) grows with a clamp base
only (the derive rule sets ``has_screw``)."""

PARAMS = (
    Choice("lamp_type", "desk lamp or floor lamp", choices=("desk", "floor"), weights=(0.55, 0.45)),
    Float("desk_height", "height of a desk lamp at rest (pole collapsed)", "m", 0.35, 0.6),
    Float("floor_height", "height of a floor lamp at rest (pole collapsed)", "m", 1.0, 1.5),
    Int("arm_segments", "segments of a chain arm", "", 2, 3),
    Float("arm_reach", "horizontal reach of a curved or chain arm, as a fraction of the height",
          "", 0.25, 0.45),
    Choice("base_shape", "base plate shape, a tripod of three splayed legs, or a desk clamp (desk lamps)",
           choices=("round", "square", "domed", "tripod", "clamp"), weights=(0.35, 0.2, 0.15, 0.15, 0.15)),
    Float("desk_base_radius", "base radius (half side of a square base) of a desk lamp", "m",
          0.065, 0.11),
    Float("floor_base_radius", "base radius (half side of a square base) of a floor lamp", "m",
          0.13, 0.2),
    Float("base_thickness", "base plate thickness", "m", 0.015, 0.035),
    # 15-25 mm poles and arm tubes (IKEA Hektar / Ranarp, Anglepoise Type 75: 16-25 mm tube, 9 mm arm rods)
    Float("pole_radius", "upper pole radius (the lower pole is a tube around it)", "m", 0.0075, 0.0125),
    # telescoping floor lamps: a one-stage pole, or a two-stage one (a middle tube: IKEA-style telescopic reading
    # lamps, photographers' tripod floor lamps with 2-3 section columns); a desk lamp's pole has one stage
    Int("pole_stages", "telescoping stages of a floor lamp's pole (a desk lamp's has 1)", "", 1, 2),
    Float("lower_pole_fraction", "share of the pole length taken by the lower tube", "", 0.35, 0.55),
    Choice("shade_shape", "shade profile", choices=("cone", "drum", "dome", "bell"),
           weights=(0.35, 0.25, 0.25, 0.15)),
    Float("desk_shade_radius", "shade opening radius of a desk lamp (x0.75 on an arm)", "m",
          0.07, 0.13),
    Float("floor_shade_radius", "shade opening radius of a floor lamp (x0.75 on an arm)", "m",
          0.12, 0.22),
    Float("shade_height_ratio", "shade height / opening radius", "", 0.7, 1.3),
    Float("shade_top_ratio", "top / opening radius of cone and bell shades", "", 0.35, 0.75),
    Float("head_tilt", "tilt limit (+-) of a head hanging from a chain arm or a desk arc", "rad",
          math.pi / 6, math.pi / 4),
    Choice("base_finish", "base material (a steel weight is hidden inside)",
           choices=("brushed_metal", "chrome", "enamel", "wood", "ceramic")),
    Choice("pole_finish", "pole and arm material", choices=("chrome", "brushed_metal", "painted")),
    Choice("shade_finish", "shade material", choices=("fabric", "painted"), weights=(0.5, 0.5)),
)

MATERIALS = {
    "base": "base_finish", "pole": "pole_finish", "shade": "shade_finish", "fitting": "plastic",
    "bulb": BULB_GLASS, "bulb_cap": "brushed_metal", "switch": "plastic", "weight": "brushed_metal",
    "clamp": "brushed_metal",
}

OWNERS = {"base": "lamp", "lower_pole": "pole", "middle_pole": "pole", "upper_pole": "pole", "bulb": "bulb",
          "switch": "switch", "head": "head", "shade": "shade", "screw": "screw"}
"""Which grown node makes each part of the lamp; the others (the arm's bars and segments) are the arm's."""


class LampLayout(Layout):
    def lamp(self, node):
        made = L.blueprint(self.p, self.rng)
        kids = {"pole": node.one("pole"), "arm": node.one("arm"), "bulb": node.one("bulb"),
                "switch": node.one("switch"), "screw": node.one("screw")}
        if self.p["base_shape"] == "clamp":  # clamped on a desk edge: the upper jaw's underside is the desk top
            self.bp.elevation = L.DESK_TOP + float(made.bounds()[0, 2])
        mine = [n for n in made.parts if OWNERS.get(n, "arm") == "lamp"]
        for name in mine:
            self.add(name, made.parts[name].label, made.parts[name].pieces)
        for kind, kid in kids.items():
            if kid is not None:
                self.grow(kid, made=made, names=[n for n in made.parts if OWNERS.get(n, "arm") == kind])
        for spec in made.joints:
            self.join(spec)

    def _parts(self, node, made, names):
        for name in names:
            self.add(name, made.parts[name].label, made.parts[name].pieces)

    pole = bulb = push_switch = rotary_switch = rocker_switch = socket_switch = screw = _parts

    def switch(self, node, made, names):
        self.grow(node.one(node.choice), made=made, names=names)

    def arm(self, node, made, names):
        self.grow(node.one(node.choice), made=made, names=names)

    def _style(self, node, made, names):
        self._parts(node, made, names)
        self.grow(node.one("head"), made=made, names=["head"])

    straight = curved = chain = _style

    def head(self, node, made, names):
        self._parts(node, made, names)
        self.grow(node.one("shade"), made=made, names=["shade"])

    shade = _parts


def fit_parts(p: dict) -> dict:
    """A turn-knob socket is an upright head's (a hanging head's socket is inside its shade): another lamp draws a
    push switch instead; a tripod has no base plate to carry a base switch (its switch is the socket's, or on
    the cord). A desk lamp on a tripod has a straight pole: its 16 cm hub leaves a 0.35-0.6 m lamp no room
    for a head hanging from an arc or a chain arm (the head shrank to a 7-17 mm shade, its bulb caught in
    it), so such a lamp gets a round base. A clamp is a desk lamp's (a floor lamp drawing one
    gets a round base); it has no base plate either, and always its screw."""
    if p["lamp_type"] == "desk" and p["base_shape"] == "tripod" and p["arm_style"] != "straight":
        p = {**p, "base_shape": "round"}
    if p["lamp_type"] == "floor" and p["base_shape"] == "clamp":
        p = {**p, "base_shape": "round"}
    p = {**p, "has_screw": p["base_shape"] == "clamp"}
    if p["switch_kind"] == "socket_switch" and p["arm_style"] != "straight":
        p = {**p, "switch_kind": "push_switch"}
    base_switch = p["switch_kind"] != "socket_switch"
    if p["lamp_type"] == "desk":
        p = {**p, "pole_stages": 1}
    return {**p, "has_switch": p["has_switch"] and not (base_switch and p["base_shape"] in ("tripod", "clamp"))}


CATEGORY = Category("lamp", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, LampLayout, MATERIALS,
                    derive=fit_parts, palette=furniture)
