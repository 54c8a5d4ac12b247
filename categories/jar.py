"""Jar: a storage jar (round, square or hexagonal) with a screw lid, a clip-top, a hinged lid or a stopper.

The body is hollow: a round jar is one thin wall of revolution through a smooth spline
(body, rounded shoulder, neck, lip) on a bottom disc; a square or hexagonal jar is a wall
of flat panels (one convex piece per face and band, so it stays hollow), a flat shoulder
plate with a round opening (convex wedges around the hole) and a round neck on top. Glass
or glazed ceramic. Four closures (``closure``, :data:`.parts.closure_sizes.JAR_CLOSURES`):

* ``screw`` (mason jar, :func:`~.parts.vessel.jar_lid`): a threaded neck and a lid
  (metal or plastic) whose skirt is drawn round the threads with clearance (without
  collision: see :func:`.parts.vessel.sleeve` for the PhysX reason) and whose top plate
  with its raised button collides as one flat-faced hull (jar seed 61: a separate button
  hull jammed the turn in PhysX). It turns freely about Z and lifts 0..5 cm along +Z,
  resting on its seat at 0 (gravity holds it down);
* ``clip_top`` (Le Parfait, Bormioli Fido): a plain neck with a wire ring under the lip;
  a domed glass lid on an orange rubber gasket hinged at the back (revolute about -Y,
  its front lifts), with a wire yoke over it, and a wire lever at the front whose bar
  lies over the lid's edge (revolute about +Y, it swings forward and down); the lid opens
  only with the lever open (``requires_open``);
* ``hinged``: a thick flat lid (acrylic, bamboo) on the same back hinge, with a knob at
  the front;
* ``stopper`` (apothecary jar): a plain neck and a stopper with a tall dome and finial,
  its plug in the neck; it turns and lifts like the screw lid.
"""

from __future__ import annotations

from infmob_usd.assembly import Assembly
from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import closures as CL
from .parts import vessel as V
from .parts.closure_sizes import CLIP_TOP, HINGED_JAR, JAR_CLOSURES
from .parts.vessel_sizes import JAR, JAR_LID_FAMILY, JAR_LIFT

LID_LIFT = JAR_LIFT
SIDE_COUNT = {"round": 0, "square": 4, "hexagonal": 6}

GRAMMAR = Grammar("jar", {
    "jar": Node(required=("closure",), one_of=dict(zip(SIDE_COUNT, JAR["sides_weights"])), choice="sides",
                doc="a body of one cross-section and its closure"),
    "round": Node(label="body", doc="one wall of revolution with shoulder and neck"),
    "square": Node(label="body", doc="four flat panels, a shoulder plate and a round neck"),
    "hexagonal": Node(label="body", doc="six flat panels, a shoulder plate and a round neck"),
    "closure": Node(one_of=JAR_CLOSURES, choice="closure", doc="what closes the jar"),
    "screw": Node(label="lid", doc="a screw lid: skirt over the threads, top plate with a button"),
    "clip_top": Node(label="lid", required=("lever",), doc="a hinged glass lid on a gasket, wire yoke"),
    "lever": Node(label="lever", doc="the clip-top's wire lever clamping the lid"),
    "hinged": Node(label="lid", doc="a flat lid on a back hinge with a front knob"),
    "stopper": Node(label="stopper", doc="a stopper with a plug in the neck"),
})

PARAMS = (
    Float("height", "overall height of the body (without the lid)", "m", *JAR["height"]),
    Float("radius", "body radius (round) or half width across the flats", "m", *JAR["radius"]),
    Choice("body_finish", "body material", choices=("glass", "ceramic"), weights=JAR["body_weights"]),
    Choice("lid_finish", "lid material", choices=tuple(JAR_LID_FAMILY), weights=JAR["lid_weights"]),
    Float("wall", "body wall thickness", "m", *JAR["wall"]),
    Float("neck_ratio", "neck radius / body radius", "", *JAR["neck_ratio"]),
    Float("shoulder", "shoulder height / body height (round jars)", "", *JAR["shoulder"]),
    Float("neck_height", "threaded neck height", "m", *JAR["neck_height"]),
    Float("lid_height", "lid height", "m", *JAR["lid_height"]),
)


class JarLayout(Layout):
    def jar(self, node):
        body, neck = self.grow(node.one(node.choice))
        self.grow(node.one("closure"), body=body, neck=neck)

    def closure(self, node, body, neck):
        self.grow(node.one(node.choice), body=body, neck=neck)

    def round(self, node):
        p = self.p
        body, neck = V.round_jar_body(p["height"], p["radius"], p["wall"], p["neck_ratio"], p["shoulder"],
                                      p["neck_height"], "body", threads=p["closure"] == "screw")
        return self.place(body, "body"), neck

    def _polygon(self, node):
        p = self.p
        body, neck = V.polygon_jar_body(p["height"], p["radius"], SIDE_COUNT[node.kind], p["wall"], p["neck_ratio"],
                                        p["neck_height"], "body", threads=p["closure"] == "screw")
        return self.place(body, "body"), neck

    square = hexagonal = _polygon

    def _hinged(self, body, neck, knob: float, thickness: float | None, lever: bool):
        base = body.anchor("base")
        fittings, ring = CL.neck_ring_and_hinge(neck, "wire", lever)
        self.extend(body.root, Assembly.single("f", fittings, {"vessel": IDENTITY}).attached("vessel", to=base).pieces)
        glass = self.p["closure"] == "clip_top"
        lid = CL.clip_lid(neck, "lid_glass" if glass else "lid", "gasket", "wire", ring["hinge"], knob=knob,
                          thickness=thickness)
        lid = self.place(lid.attached("vessel", to=base), "lid")
        hinge = Frame.at(base.point(ring["hinge"].origin), z=base.vector(ring["hinge"].z))
        return lid, ring, hinge

    def clip_top(self, node, body, neck):
        lid, ring, hinge = self._hinged(body, neck, 0.0, None, True)
        lever = self.grow(node.one("lever"), body=body, neck=neck, ring=ring)
        self.hinge(body.root, lid.root, hinge, CLIP_TOP["lid_open"], role="lid", requires_open=lever.root)

    def lever(self, node, body, neck, ring):
        lever = self.place(CL.clip_lever(neck, ring, "wire").attached("vessel", to=body.anchor("base")), "lever")
        self.hinge(body.root, lever.root, lever.anchor("pivot"), CLIP_TOP["lever_open"])
        return lever

    def hinged(self, node, body, neck):
        lid, _, hinge = self._hinged(body, neck, HINGED_JAR["knob"], HINGED_JAR["thickness"], False)
        self.hinge(body.root, lid.root, hinge, CLIP_TOP["lid_open"], role="lid")

    def stopper(self, node, body, neck):
        st = CL.jar_stopper(neck, "lid_glass" if self.p["body_finish"] == "glass" else "stopper_wood")
        st = self.place(st.attached("seat", to=body.anchor("lid_seat")), "stopper")
        self.join(V.seat_joint(body.root, st, LID_LIFT))

    def screw(self, node, body, neck):
        lid = V.jar_lid(neck, self.p["neck_height"], self.p["lid_height"],
                        self.p["lid_finish"] == "plastic", "lid")
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LID_LIFT))


CATEGORY = Category("jar", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, JarLayout,
                    materials={"body": "body_finish", "lid": ("lid_finish", JAR_LID_FAMILY),
                               "lid_glass": "glass:clear", "gasket": "rubber", "wire": "chrome",
                               "stopper_wood": "wood"})
