"""Stovetop: a gas, electric-coil or induction hob, built in or a counter-top cooker, with its controls.

X is depth (the front faces +X), Y is width, Z is up. A built-in hob is a top plate (stainless or enamelled
steel, or black glass-ceramic) over a shallow housing that drops into the worktop cut-out; a counter-top
cooker is a casing on rubber feet with its knobs on a front fascia. Gas hobs carry 2-6 burners in
columns, each column under a loose cast grate that lifts off its seat (a short vertical slide, role
``lift_off``) and a knob per burner (push-to-turn valves, 270 degrees from off); electric coil hobs carry
sheathed coils on chrome drip pans and a knob per coil (infinite switches, 300 degrees); induction hobs
carry zones printed on the glass and either knobs or touch keys along the glass's front edge (push
keys sprung back, role ``button``). Built-in knobs stand on a strip along the front of the top (their
axis vertical); a counter cooker's stand on its fascia (axis +X).
Parts: ``categories/parts/hobs.py`` (body, zones, fascia), ``ovens.py`` (burners, grates), ``controls.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import appliance
from infmob_usd.params import Choice, Float, Int

from .parts import controls
from .parts import hobs as HB

B = HB.HOB["built_in"]


def zone_count(p: dict) -> int:
    """zone_count; a counter cooker has at most 2 (double burners: Cuisinart CB-60, Duxtop 9600LS)"""
    return p["zone_count"] if p["mount"] == "built_in" else min(2, p["zone_count"])


def grate_count(p, rng) -> int:
    """one grate over each column of burners (:func:`~.parts.hobs.columns`)"""
    W, _, _ = HB.size(p["mount"], zone_count(p), p["width"], p["depth"], p["height"])
    return len(HB.columns(zone_count(p), W))


GRAMMAR = Grammar("stovetop", {
    # hob sales: gas and induction lead, coil the budget end (Bosch, Frigidaire, GE ranges)
    "stovetop": Node(label="body", one_of={"gas": 0.4, "coil": 0.25, "induction": 0.35}, choice="design"),
    "gas": Node(required=("knobs",), repeat={"grate": grate_count}),
    "coil": Node(required=("knobs",)),
    "induction": Node(one_of={"knobs": 0.5, "keys": 0.5}, choice="induction_controls"),
    "knobs": Node(repeat={"knob": lambda p, rng: zone_count(p)}),
    "knob": Node(label="knob"),
    "keys": Node(repeat={"key": "key_count"}),
    "key": Node(label="button"),
    "grate": Node(label="grate"),
})
"""Designs (``design``): a ``gas`` hob (burners under cast grates that lift off, a knob each), an electric
``coil`` hob (coils on drip pans, a knob each), an ``induction`` hob (zones on glass; knobs, or touch keys on
the glass's front edge). ``mount``: ``built_in`` (a top plate over a housing, knobs on a front strip) or
``counter`` (a casing on feet, knobs on its front fascia, 1-2 zones)."""

PARAMS = (
    Choice("mount", "built into a worktop or a counter-top cooker", choices=("built_in", "counter"),
           weights=(0.7, 0.3)),
    Float("width", "built-in width (Y), mapped onto the zone count's range (2 zones: a 0.3 m domino; 3: 0.45-0.6 m;"
          " 4: 0.58-0.77 m; 5-6: 0.75-0.92 m); a counter cooker maps it onto 0.5-0.6 m", "m", *HB.WIDTH),
    Float("depth", "built-in depth (X); a counter cooker maps it onto 0.3-0.36 m", "m", *B["depth"]),
    Float("height", "built-in height, top plate and housing (Z); a counter cooker maps it onto 0.06-0.11 m",
          "m", *B["housing"]),
    Int("zone_count", "burners or cooking zones (a counter cooker: at most 2)", "", 2, 6),
    Int("key_count", "touch keys along an induction hob's glass front edge (power, function, -, +, timer)", "",
        3, 5),
    Choice("top_finish", "a gas or coil hob's top: stainless or enamelled steel", choices=("stainless", "enamel")),
    Choice("knob_style", "knob shape", choices=("ridge", "round"), weights=(0.6, 0.4)),
)

MATERIALS = {
    "top": "top_family", "housing": "brushed_metal", "feet": "rubber", "burner": "brushed_metal",
    "element": "cast_iron",  # a coil's Incoloy sheath, dark grey once fired
    "cap": "enamel:black", "grate": "cast_iron", "trim": "chrome", "display": "plastic:light_grey|dark_grey",
    "knob": "plastic:black|dark_grey|light_grey", "button": "plastic:black|dark_grey",
}
TOPS = {"induction": "enamel:black", "stainless": "brushed_metal", "enamel": "enamel:white|black|graphite"}
SUBSTRATES = {"top": ("design", {"induction": 2500.0})}  # glass-ceramic (Schott Ceran 2.56 g/cm3) looks enamel


def derive(p: dict) -> dict:
    """The top's family from the design and finish."""
    return {**p, "top_family": TOPS["induction" if p.get("design") == "induction" else p["top_finish"]]}


class StovetopLayout(controls.ControlFace):
    def stovetop(self, node):
        p = self.p
        design, n = node.choice, zone_count(p)
        W, D, H = HB.size(p["mount"], n, p["width"], p["depth"], p["height"])
        style = node.one(design)
        keys = style.one("keys")
        n_keys = len(keys.of("key")) if keys else 0
        made, cols, (area_x, _) = HB.hob_body(design, p["mount"], W, D, H, n, n_keys)
        if p["mount"] == "counter":  # knobs on the fascia; keys on the glass (a plain fascia)
            knobs = style.one("knobs")
            pieces, spots = HB.fascia(W, D, H, n if knobs else 0, 0, HB.HOB["plate"][design])
            made = made.__class__.single("body", [*made.parts[made.root].pieces, *pieces], {**made.anchors, **spots})
        body = self.place(made, "body")
        self.grow(style, body=body, cols=cols, area_x=area_x, H=H)

    def gas(self, node, body, cols, area_x, H):
        self.grow(node.one("knobs"), body=body, dial=HB.KNOB)
        for k, (kid, col) in enumerate(zip(node.of("grate"), cols, strict=True)):
            self.grow(kid, k=k, col=col, area_x=area_x, H=H)

    def coil(self, node, body, cols, area_x, H):
        self.grow(node.one("knobs"), body=body, dial=HB.COIL_KNOB)

    def induction(self, node, body, cols, area_x, H):
        self.grow(node.one(node.choice), body=body, dial=HB.COIL_KNOB)

    def knobs(self, node, body, dial):
        dial = controls.Dial(dial.radius, dial.stem, self.p["knob_style"], dial.turns)
        for k, kid in enumerate(node.of("knob")):
            self.grow(kid, k=k, body=body, dial=dial)

    def knob(self, node, k, body, dial):
        self.place_dial(body.root, f"knob_{k}", dial, body.anchor(f"knob_{k}"))

    def keys(self, node, body, dial):
        for k, kid in enumerate(node.of("key")):
            self.grow(kid, k=k, body=body)

    def key(self, node, k, body):
        self.place_button(body.root, f"key_{k}", HB.HOB["key"], body.anchor(f"key_{k}"))

    def grate(self, node, k, col, area_x, H):
        """A loose cast grate over its burners: it lifts straight off its seat (role ``lift_off``)."""
        pieces, at = HB.grate(area_x, col, H)
        name = self.add(f"grate_{k}", "grate", pieces)
        self.slide("body", name, at, upper=HB.LIFT, role="lift_off")


CATEGORY = Category("stovetop", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, StovetopLayout, MATERIALS,
                    substrates=SUBSTRATES, derive=derive, palette=appliance)
