"""Pot: a cooking pot, stock pot or saucepan with a lid that lifts off and turns.

X is depth (a long handle reaches toward +X, the front), Y is width, Z is up. The body
(:func:`~.parts.vessel.cookware_body`) is a real hollow vessel: a thin wall of
revolution (a rounded bottom corner and a straight, slightly flared side) on a bottom
that follows the corner, finished with a rolled rim (a round bead curling outward). The
handles are pieces of the body named ``handle``: either two loop handles on the sides
(+-Y, a bar on two posts), or one long handle (a tapered bar leaving the wall
horizontally below the rim, then rising, with a rounded tip), always below the rim so
the lid lifts clear of them.

The lid (:func:`~.parts.vessel.dome_lid`) is a shallow dome wider than the rim, with a
metal band around its edge; on top a knob or a loop handle (fixed to the lid, pieces
named ``handle``). It has no lip reaching into the opening: the joint keeps it centred,
and thin lip hulls next to the rim made PhysX report deep false contacts that spun the
lid. It rests 2.5 mm above the rim on the lower stop of its lift, so gravity holds it
there; ``continuous_prismatic``: lift 0..3 cm along +Z, then turn freely about Z (the
lid is symmetric about Z, so the turn is neutral).

Three designs (``pot_design``, :data:`.parts.closure_sizes.POT_DESIGNS`):

* ``plain``: the dome lid above, maybe on a pasta insert (``has_pasta``: a deep straining basket of
  0.6 mm sheet hung from the rim, a collar above it carrying its handles and the lid; it lifts out,
  prismatic, label ``basket``);
* ``steamer``: one or two stacking steamer tiers of 0.8 mm pressed sheet (:func:`~.parts.closures.steamer_tier`:
  a wall as wide as the pot's, a nesting skirt with clearance, a floor, two small loop
  handles), each lifting off the one below along +Z (prismatic, a chain: body -> tier ->
  tier), the dome lid on the top tier;
* ``pressure``: a pressure cooker's bayonet lid (``revolute_prismatic``: it turns
  0..35 degrees about Z to unlock and lifts 0..3 cm) with a loop handle, a pressure valve
  that turns (continuous, the selector) and a lock slider that slides outward (prismatic).

The lid's knob or loop is its own part fixed to the lid (label ``knob`` / ``handle``), and a lid may
carry a rotary steam vent (``has_vent``: a disc with a grip tab on the dome, revolute 0..90 degrees).
A long handle is its own part fixed to the body (label ``handle``), with an optional helper loop
opposite (``has_helper``); side loops stay pieces of the body.

Finishes: brushed steel, enamel (with a steel rim and lid band) or chrome; the lid is of
the body's finish or glass; handles match the body or are black plastic or wood.
"""

from __future__ import annotations

import math

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import IDENTITY
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import closures as CL
from .parts import vessel as V
from .parts.closure_sizes import HELPER, PASTA, POT_DESIGNS, PRESSURE, STEAMER, VENT
from .parts.vessel_sizes import GLASS, GLASS_LID_THICKER, HANDLE_FAMILY, POT, POT_LIFT, POT_RIM

LIFT = POT_LIFT

GRAMMAR = Grammar("pot", {
    "pot": Node(label="body", required=("design",), choice="handle_layout",
                one_of=dict(zip(("side_handles", "long_handle"), POT["layout_weights"])),
                doc="a rolled-rim vessel with its handles, and what sits on it"),
    "design": Node(one_of=POT_DESIGNS, choice="pot_design", doc="plain, steamer or pressure cooker"),
    "plain": Node(required=("lid",), optional={"pasta": PASTA["p"]},
                  doc="a dome lid on the rim, or on a pasta insert hung in the pot"),
    "pasta": Node(label="basket", doc="a deep straining insert hung from the rim (lifts out), the lid on it"),
    "steamer": Node(required=("lid",), repeat={"tier": STEAMER["tiers"]},
                    doc="stacking steamer tiers, the lid on the top one"),
    "tier": Node(label="insert", doc="a steamer tier nesting in the vessel below (lifts off)"),
    "pressure": Node(label="lid", required=("valve", "lock"), doc="a bayonet pressure lid (turns, lifts)"),
    "valve": Node(label="valve", doc="the pressure valve / selector (turns)"),
    "lock": Node(label="button", doc="the lid's lock slider (slides outward)"),
    "side_handles": Node(doc="two loop handles on the sides (welded loops: pieces of the body)"),
    "long_handle": Node(label="handle", optional={"helper": HELPER["p"]},
                        doc="one long riveted handle toward +X with a rounded tip (fixed to the body)"),
    "helper": Node(label="handle", doc="a short helper loop opposite the long handle (big saucepans)"),
    "lid": Node(label="lid", one_of=dict(zip(("knob", "loop"), POT["lid_handle_weights"])), choice="lid_handle",
                optional={"vent": VENT["p"]}, doc="a dome lid with a band, lifting and turning on the rim"),
    "knob": Node(label="knob", doc="a round knob screwed onto the lid (fixed to it)"),
    "loop": Node(label="handle", doc="a loop handle on two posts screwed onto the lid (fixed to it)"),
    "vent": Node(label="vent", doc="a rotary steam vent on the dome (turns 0..90 degrees)"),
})

PARAMS = (
    Float("radius", "outer radius of the wall at the top", "m", *POT["radius"]),
    Float("depth_ratio", "depth / radius", "", *POT["depth_ratio"], dist="loguniform"),
    Float("flare", "wall angle from vertical", "rad", *POT["flare"]),
    Float("corner", "bottom corner radius as a fraction of the radius", "", *POT["corner"]),
    Float("wall", "wall thickness", "m", *POT["wall"]),
    Float("bottom", "bottom (clad base) thickness", "m", *POT["bottom"]),
    Float("bead", "rolled rim bead radius", "m", *POT["bead"]),
    Float("dome", "lid dome height as a fraction of the radius", "", *POT["dome"]),
    Float("lid_thickness", "lid wall thickness (glass lids are 1.6x thicker)", "m", *POT["lid_thickness"]),
    Float("handle_length", "long handle length from the wall", "m", *POT["handle_length"]),
    Float("handle_angle", "long handle rise above horizontal", "rad", *POT["handle_angle"]),
    Float("handle_width", "long handle width", "m", *POT["handle_width"]),
    Float("handle_thickness", "long handle thickness", "m", *POT["handle_thickness"]),
    Float("side_handle_length", "side loop handle length", "m", *POT["side_handle_length"]),
    Float("side_handle_radius", "side loop bar radius", "m", *POT["side_handle_radius"]),
    Float("side_handle_reach", "finger room between the wall and a side loop", "m", *POT["side_handle_reach"]),
    Float("knob_radius", "lid knob radius", "m", *POT["knob_radius"]),
    Float("tier_height", "steamer tier height / radius", "", *STEAMER["height"]),
    Float("pasta_collar", "pasta insert collar above the rim / radius", "", *PASTA["collar"]),
    Float("pasta_reach", "pasta insert depth / the pot's inside depth", "", *PASTA["reach"]),
    Choice("body_finish", "body material", choices=tuple(POT_RIM), weights=POT["body_weights"]),
    Choice("lid_finish", "lid: the body's material or glass", choices=("match", "glass"), weights=POT["lid_weights"]),
    Choice("handle_finish", "handle material", choices=tuple(HANDLE_FAMILY), weights=POT["handle_weights"]),
)


class PotLayout(Layout):
    """Material slots follow the finishes: "match" uses the body's own slot (the same colour, not another draw)."""

    def _slots(self):
        p = self.p
        glass, match = p["lid_finish"] == "glass", p["handle_finish"] == "match"
        handle = "body" if match else "handle"
        return {"lid": "glass" if glass else "body",
                "band": "rim" if glass or p["body_finish"] == "enamel" else "body",
                "handle": handle, "knob": "knob" if glass and match else handle}

    def pot(self, node):
        p, R = self.p, self.p["radius"]
        body, pot = V.cookware_body(R, p["depth_ratio"] * R, p["corner"] * R, p["flare"], p["wall"], p["bottom"],
                                    p["bead"], "body", "rim")
        body = self.place(body, "body")
        self.grow(node.one(node.choice), body=body, pot=pot)
        self.grow(node.one("design"), body=body, pot=pot)

    def design(self, node, body, pot):
        self.grow(node.one(node.choice), body=body, pot=pot)

    def plain(self, node, body, pot):
        if node.one("pasta"):
            body, pot = self.grow(node.one("pasta"), body=body, pot=pot)
        self.grow(node.one("lid"), body=body, pot=pot)

    def pasta(self, node, body, pot):
        p = self.p
        collar = p["pasta_collar"] * p["radius"]
        skirt = min(p["pasta_reach"] * (pot.rim_top - pot.floor), PASTA["deepest"])
        b, info = CL.steamer_tier(pot, collar, "body", "rim", self._slots()["handle"], skirt=skirt, label="basket",
                                  sheet=PASTA["sheet"])
        b = self.place(b.attached("seat", to=body.anchor("lid_seat")), "pasta")
        s = b.anchor("seat")
        self.join(J.prismatic(body.root, b.root, tuple(s.origin), tuple(s.z), 0.0, skirt + PASTA["clear"],
                              role="lift_off"))
        return b, info

    def steamer(self, node, body, pot):
        for i, tier in enumerate(node.of("tier")):
            body, pot = self.grow(tier, below=body, pot=pot, name="tier" if i == 0 else f"tier_{i}")
        self.grow(node.one("lid"), body=body, pot=pot)

    def tier(self, node, below, pot, name):
        p = self.p
        slots = self._slots()
        t, info = CL.steamer_tier(pot, p["tier_height"] * p["radius"], "body", "rim", slots["handle"])
        t = self.place(t.attached("seat", to=below.anchor("lid_seat")), name)
        s = t.anchor("seat")
        self.join(J.prismatic(below.root, t.root, tuple(s.origin), tuple(s.z), 0.0, STEAMER["lift"], role="lift_off"))
        return t, info

    def pressure(self, node, body, pot):
        p, slots = self.p, self._slots()
        t = p["lid_thickness"]
        lid, dome = V.dome_lid(pot, p["dome"] * p["radius"], t, "body", slots["band"])
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        s = lid.anchor("seat")
        self.join(J.revolute_prismatic(body.root, lid.root, tuple(s.origin), tuple(s.z), (0.0, PRESSURE["turn"]),
                                         tuple(s.z), (0.0, LIFT), role="lift_off"))
        loop = V.lid_loop(dome, p["knob_radius"], slots["knob"])
        self.extend(lid.root, loop.attached("base", to=lid.anchor("top")).pieces)
        self.grow(node.one("valve"), lid=lid, dome=dome)
        self.grow(node.one("lock"), lid=lid, dome=dome)

    def _on_dome(self, lid, dome, x: float, half: float):
        """The frame on the dome at (x, 0) of the lid, as high as the dome is within ``half`` of it."""
        z = float(dome.under(max(abs(x) - half, 0.0))) + dome.thickness
        return lid.anchor("seat") @ IDENTITY.moved(x, 0.0, z)

    def valve(self, node, lid, dome):
        r = PRESSURE["valve"][0]
        at = self._on_dome(lid, dome, PRESSURE["valve_at"] * dome.radius, r)
        v = self.place(CL.pressure_valve(self._slots()["knob"]).attached("base", to=at), "valve")
        self.spin(lid.root, v.root, v.anchor("base"))

    def lock(self, node, lid, dome):
        half = PRESSURE["lock"][0] / 2
        at = self._on_dome(lid, dome, -PRESSURE["lock_at"] * dome.radius, half)
        lk = self.place(CL.lock_slider(self._slots()["knob"]).attached("base", to=at.turned("z", math.pi)), "lock")
        self.slide(lid.root, lk.root, lk.anchor("slide"), PRESSURE["lock_slide"], role="button")

    def side_handles(self, node, body, pot):
        p = self.p
        h = V.side_handles(pot, p["side_handle_length"], p["side_handle_radius"], p["side_handle_reach"],
                           self._slots()["handle"])
        self.extend(body.root, h.attached("vessel", to=body.anchor("base")).pieces)

    def long_handle(self, node, body, pot):
        p, slot = self.p, self._slots()["handle"]
        h = V.long_handle(pot, p["handle_length"], p["handle_angle"], p["handle_width"], p["handle_thickness"], slot)
        h = h.attached("vessel", to=body.anchor("base"))
        tip = V.handle_tip(p["handle_width"], p["handle_thickness"], slot).attached("start", to=h.anchor("end"))
        self.fix(body.root, self.add("handle", "handle", h.pieces + tip.pieces))
        if node.one("helper"):
            self.grow(node.one("helper"), body=body, pot=pot)

    def helper(self, node, body, pot):
        h = self.place(CL.helper_handle(pot, self._slots()["handle"]).attached("vessel", to=body.anchor("base")),
                       "helper")
        self.fix(body.root, h.root)

    def lid(self, node, body, pot):
        p, slots = self.p, self._slots()
        t = p["lid_thickness"] * (GLASS_LID_THICKER if p["lid_finish"] == "glass" else 1.0)
        lid, dome = V.dome_lid(pot, p["dome"] * p["radius"], t, slots["lid"], slots["band"])
        lid = self.place(lid.attached("seat", to=body.anchor("lid_seat")), "lid")
        self.join(V.seat_joint(body.root, lid, LIFT))
        self.grow(node.one(node.choice), lid=lid, dome=dome)
        if node.one("vent"):
            self.grow(node.one("vent"), lid=lid, dome=dome)

    def knob(self, node, lid, dome):
        knob = V.lid_knob(self.p["knob_radius"], self._slots()["knob"])
        self.fix(lid.root, self.add("lid_knob", "knob", knob.attached("base", to=lid.anchor("top")).pieces))

    def loop(self, node, lid, dome):
        loop = V.lid_loop(dome, self.p["knob_radius"], self._slots()["knob"])
        self.fix(lid.root, self.add("lid_handle", "handle", loop.attached("base", to=lid.anchor("top")).pieces))

    def vent(self, node, lid, dome):
        """The steam vent on the dome at -X (clear of a centred knob or a loop along Y)."""
        at = self._on_dome(lid, dome, -VENT["at"] * dome.radius, VENT["radius"])
        v = self.place(CL.steam_vent("rim").attached("base", to=at), "vent")
        self.hinge(lid.root, v.root, v.anchor("base"), upper=VENT["turn"], role="knob")


CATEGORY = Category("pot", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, PotLayout, materials={
    "body": "body_finish", "rim": ("body_finish", POT_RIM), "glass": GLASS,
    "handle": ("handle_finish", HANDLE_FAMILY), "knob": ("handle_finish", HANDLE_FAMILY),
})
