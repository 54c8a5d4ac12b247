"""Camera: a DSLR, a mirrorless, a compact, an instant or an action camera, standing on its base.

Designs (``design``, sizes and sources in ``categories/parts/cameras.py``): a ``dslr`` whose zoom ring turns
about the lens axis (revolute) and drives the inner barrel out of the lens (prismatic, coupled to the ring),
a shutter button on the grip (prismatic, sprung), a mode dial (continuous), and optionally a tilting rear
screen (revolute about its top edge) and a card door on the grip side (revolute); a ``mirrorless`` camera is
the same mechanism on a slimmer body with a shallower grip and a short retracting kit zoom, its viewfinder in
a hump over the lens or in the top corner (``viewfinder``); a ``compact`` whose lens
telescopes out in one or two stages (prismatic each, the inner riding in the outer), with a shutter
button, optionally a mode dial, a tilting screen and a side door; an ``instant`` camera whose lens barrel
pops out (prismatic), its shutter button on the front, its film door on the back (revolute) and optionally
a battery door on the side; an ``action`` camera's fixed lens sits behind a square cover beside its front
screen, its shutter button on top and its battery door on the side. X is the lens's direction, Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import cameras as K

BODIES = ("black", "dark_grey", "graphite")
PASTELS = ("pastel_blue", "pastel_pink", "pastel_green", "pastel_yellow", "white")
PARAMS = (
    Float("size", "width and lens size within the design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Float("shape", "height against depth within the design's ranges (0 low and deep, 1 tall and slim)", "", 0.0,
          1.0),
    Float("roundness", "edges: crisp (0) to soft (1)", "", 0.0, 1.0),
    Float("reach", "a DSLR lens's length and zoom travel over an 18-55 kit zoom's (1.5: an 18-135 mm)", "", 1.0,
          1.5),
    Choice("finish", "body finish of a DSLR, a mirrorless camera or a compact: black plastic, dark grey or silver"
           " metal", choices=("black", "dark_grey", "silver"), weights=(0.55, 0.2, 0.25)),
    Choice("pastel", "an instant camera's moulded colour", choices=PASTELS),
    Choice("viewfinder", "a mirrorless camera's viewfinder: in a hump over the lens or in the top corner",
           choices=K.VIEWFINDERS, weights=(0.6, 0.4)),
)

GRAMMAR = Grammar("camera", {
    "camera": Node(one_of={"dslr": 0.22, "mirrorless": 0.2, "compact": 0.23, "instant": 0.2, "action": 0.15},
                   choice="design"),
    "dslr": Node(label="body", required=("zoom_ring", "shutter", "dial"), optional={"screen": 0.6, "door": 0.7}),
    # most mirrorless bodies tilt or flip their screen (a6400, Z50, R50)
    "mirrorless": Node(label="body", required=("zoom_ring", "shutter", "dial"), optional={"screen": 0.8,
                                                                                          "door": 0.7}),
    "compact": Node(label="body", required=("stage", "shutter"), optional={"dial": 0.6, "screen": 0.5,
                                                                          "door": 0.6}),
    "instant": Node(label="body", required=("stage", "shutter", "film_door"), optional={"door": 0.5}),
    "action": Node(label="body", required=("shutter", "door")),
    "zoom_ring": Node(label="zoom_ring", required=("barrel",)),
    "barrel": Node(label="barrel"),
    "stage": Node(label="barrel", optional={"inner_stage": 0.6}),
    "inner_stage": Node(label="barrel"),
    "shutter": Node(label="shutter"),
    "dial": Node(label="dial"),
    "screen": Node(label="screen"),
    "door": Node(label="door"),
    "film_door": Node(label="door"),
})
"""A DSLR's ring drives its inner barrel; a compact's lens has one or two stages (an instant camera's inner
stage is its close-up mode)."""

MATERIALS = {"body": ("finish", {"black": "plastic:black", "dark_grey": "plastic:dark_grey",
                                 "silver": "brushed_metal:stainless"}),
             "pastel": ("pastel", {c: f"painted:{c}" if c != "white" else "plastic:white" for c in PASTELS}),
             "grip": "rubber:black", "trim": "plastic:black", "lens": "plastic:black", "metal": "chrome",
             # a lens's coated front element: glossy glass over the barrel's black inside (the screen family's
             # cover glass: it mirrors the room, where a see-through glass over black reads as a grey disc)
             "glass": "glass:smoked", "element": "screen:blue_black",
             "screen": "screen:black", "flash": "glass:frosted", "mark": "plastic:white", "lamp": "plastic:orange",
             "action_shell": "plastic:black|dark_grey"}  # an action camera's matte shell (GoPro black, DJI grey)
# bodies are massed solid at the density that gives their named products' weight in their bounding box:
# EOS 250D 449 g in ~122 x 93 x 50 mm (+ grip) ~ 700 kg/m^3; RX100 III 290 g in 102 x 58 x 41 mm ~ 1200;
# Instax Mini 12 306 g in 104 x 122 x 67 mm ~ 360 (a hollow moulded shell round the film pack); a6400 403 g in
# 120 x 67 x 60 mm ~ 840; GoPro HERO12 154 g in 72 x 51 x 34 mm ~ 1250
SUBSTRATES = {"body": ("design", {"dslr": 700.0, "mirrorless": 840.0, "compact": 1200.0, "instant": 700.0,
                                  "action": 1250.0}), "pastel": 360.0, "action_shell": 1250.0}


class CameraLayout(Layout):
    def camera(self, node):
        p = self.p
        self.c = K.camera(node.choice, p["size"], p["shape"], p["roundness"], p["reach"], p["viewfinder"])
        self.grow(node.one(node.choice))

    def _stages(self, node) -> int:
        return 1 + int(node.one("stage").one("inner_stage") is not None)

    def dslr(self, node):
        body = self.place(K.mount_body(self.c, "body", "grip", "metal", "lens",
                                       None if node.one("screen") else "screen"), "body")
        self._controls(node, body)

    mirrorless = dslr

    def action(self, node):
        body = self.place(K.action_body(self.c, "action_shell", "trim", "element", "mark", "screen"), "body")
        self._controls(node, body)

    def compact(self, node):
        body = self.place(K.compact_body(self.c, "body", "metal", self._stages(node)), "body")
        self.grow(node.one("stage"), parent="body", k=0, stages=self._stages(node), body="body")
        self._controls(node, body)

    def instant(self, node):
        body = self.place(K.instant_body(self.c, "pastel", "trim", "glass", self._stages(node)), "body")
        self.grow(node.one("stage"), parent="body", k=0, stages=self._stages(node), body="pastel")
        self.grow(node.one("film_door"))
        self._controls(node, body)

    def _controls(self, node, body):
        for kind in ("zoom_ring", "shutter", "dial", "screen", "door"):
            if node.one(kind) is not None:
                self.grow(node.one(kind), body=body)

    def zoom_ring(self, node, body):
        ring = self.place(K.zoom_ring(self.c, "grip"), "zoom_ring")
        self.hinge("body", "zoom_ring", ring.anchor("axis"), upper=K.ZOOM_TURN, role="knob")
        self.grow(node.one("barrel"))

    def barrel(self, node):
        barrel = self.place(K.inner_barrel(self.c, "lens", "trim", "element", "mark"), "barrel")
        self.slide("body", "barrel", barrel.anchor("slide"), upper=self.c.travel)
        self.couple("barrel", "zoom_ring", self.c.travel / K.ZOOM_TURN)

    def stage(self, node, parent, k, stages, body):
        name = "barrel" if k == 0 else "inner_barrel"
        st = self.place(K.lens_stage(self.c, k, stages, body, "trim", "element", "mark"), name)
        self.slide(parent, st.root, st.anchor("slide"), upper=self.c.travel)
        if node.one("inner_stage") is not None:
            self.grow(node.one("inner_stage"), parent=st.root, k=k + 1, stages=stages, body=body)

    inner_stage = stage

    def shutter(self, node, body):
        at = body.anchor("shutter")
        button = self.place(K.shutter(self.c, "metal").attached("mount", to=at), "shutter")
        self.extend(body.root, [K.shutter_collar(self.c, "trim").transformed(at.matrix)])
        self.slide(body.root, "shutter", button.anchor("press"), upper=K.SHUTTER_TRAVEL, role="button")

    def dial(self, node, body):
        dial = self.place(K.mode_dial(self.c, "metal", "mark").attached("mount", to=body.anchor("dial")), "dial")
        self.spin(body.root, "dial", dial.anchor("axis"), role="knob")

    def screen(self, node, body):
        screen = self.place(K.tilt_screen(self.c, "trim", "screen"), "screen")
        self.hinge(body.root, "screen", screen.anchor("hinge"), upper=K.SCREEN_TILT, role="lid")

    def door(self, node, body):
        shell = {"instant": "pastel", "action": "action_shell"}.get(self.c.design, "body")
        door = self.place(K.side_door(self.c, shell), "door")
        self.hinge(body.root, "door", door.anchor("hinge"), upper=K.DOOR_OPENS, role="lid")

    def film_door(self, node):
        door = self.place(K.film_door(self.c, "pastel", "trim"), "film_door")
        self.hinge("body", "film_door", door.anchor("hinge"), upper=K.DOOR_OPENS, role="lid")


CATEGORY = Category("camera", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, CameraLayout, MATERIALS,
                    substrates=SUBSTRATES)
