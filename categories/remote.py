"""Remote: a TV, streaming or air-conditioner remote, or a presenter, lying on its back.

Designs (``design``, sizes and sources in ``categories/parts/remotes.py``): a ``tv`` remote is a long slab whose
keys lie in the sections of a real keypad, front to back: power and input keys, streaming shortcut keys, a
numeric pad, volume and channel keys, a d-pad on a metallic disc with its menu keys, the four colour keys and
the transport keys (each section but the first three object-wide optional: ``has_numpad`` ...); an ``ac``
remote has an LCD above its main keys (on/off, temperature, mode, fan) and its timer and swing keys under a
cover hinged at its back edge (revolute; the keys it covers ``requires_open`` it); a ``streaming`` remote is a
slim bar with round ends: power and voice keys, a large round pad (select and four arrows), 3-9 round keys in
rows of three and optionally app keys, its battery door optional (a rechargeable one has none); a
``presenter`` is a pebble with back / forward keys, a laser key and 1-3 more. Every key presses down against
its return spring (prismatic, role ``button``); the battery door in the underside slides out backwards
(prismatic). X is the end that points at the set, Y across, Z up.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import remotes as R

PARAMS = (
    Float("size", "where the width and length lie in the design's range (0 smallest, 1 largest)", "", 0.0, 1.0),
    Choice("tone", "shell and key colours", choices=("dark", "grey", "light", "silver"),
           weights=(0.4, 0.2, 0.25, 0.15)),
)

TV_KEYS = {"top_row": (2, 4), "apps": (2, 4), "numpad": (10, 12), "volume": (4, 5), "navigation": (7, 9),
           "colour_keys": 4, "playback": (3, 8)}
"""Keys per TV section: power plus 1-3 of input, settings, mute; 2-4 streaming keys; 0-9 and up to two more;
VOL and CH pairs and a mute; OK, four arrows and 2-4 of menu, back, home, exit; red, green, yellow, blue;
3-8 transport keys (Samsung BN59, LG AKB, Sony RMT remotes)."""

GRAMMAR = Grammar("remote", {
    "remote": Node(label="body", one_of={"tv": 0.35, "streaming": 0.25, "ac": 0.22, "presenter": 0.18},
                   choice="design"),
    "tv": Node(required=("top_row", "volume", "navigation", "battery_door"),
               optional={"apps": 0.5, "numpad": 0.65, "colour_keys": 0.55, "playback": 0.45}),
    **{kind: Node(repeat={"key": count}) for kind, count in TV_KEYS.items() if kind != "playback"},
    "playback": Node(repeat={"key": TV_KEYS["playback"]}, optional={"playback_cover": 0.4}),
    "playback_cover": Node(label="lid"),
    "streaming": Node(required=("stream_top", "stream_pad", "stream_keys"), optional={"apps": 0.5,
                                                                                     "battery_door": 0.75}),
    "stream_top": Node(repeat={"key": (1, 2)}),
    "stream_pad": Node(repeat={"key": 5}),
    "stream_keys": Node(repeat={"key": (3, 9)}),
    "ac": Node(required=("ac_main", "cover", "battery_door")),
    "ac_main": Node(repeat={"key": (4, 6)}),
    "cover": Node(label="lid", required=("ac_covered",)),
    "ac_covered": Node(repeat={"key": (6, 12)}),
    "presenter": Node(required=("presenter_keys", "battery_door"), optional={"power_switch": 0.5}),
    "power_switch": Node(label="switch"),
    "presenter_keys": Node(repeat={"key": (4, 6)}),
    "key": Node(label="button"),
    "battery_door": Node(label="door"),
})
"""An AC remote's main keys: on/off, temperature -/+ and 1-3 of mode, fan, swing; 6-12 keys under its cover
(timer on/off, sleep, eco, swing, clock ...: Daikin ARC466, Mitsubishi KM09); a presenter's back, forward, laser
and 1-3 of blank screen, slideshow, timer (Logitech R400 / R500, Kensington K33374)."""

TONES = {"dark": ("plastic:black", "plastic:dark_grey"), "grey": ("plastic:dark_grey", "plastic:black"),
         "light": ("plastic:white", "plastic:light_grey"), "silver": ("plastic:light_grey", "plastic:dark_grey")}
"""Shell and key colours sold together: black with grey keys (Samsung, Sony), grey with black (LG), white with
grey (Daikin, Gree AC remotes, Apple-style presenters), silver with dark keys (Philips, Logitech R800)."""

MATERIALS = {
    "body": ("tone", {t: body for t, (body, _) in TONES.items()}),
    "key": ("tone", {t: key for t, (_, key) in TONES.items()}),
    "power": "plastic:red", "app": "plastic:red|blue|black", "trim": "brushed_metal", "lens": "screen:black",
    "lcd": "plastic:light_grey",  # an unlit segment LCD reads pale grey-green under its window
    "pad": "plastic:black|dark_grey|light_grey", "ring": "plastic:black|dark_grey|blue",
    **{f"key_{c}": f"plastic:{c}" for c in R.COLOURS},
}


class RemoteLayout(Layout):
    def remote(self, node):
        kit = node.one(node.choice)
        counts = {c.kind: len(c.of("key")) for c in kit.walk() if c.of("key")}
        size = self.p["size"]
        if node.choice == "tv":
            self.plan = R.tv_plan(size, counts)
        elif node.choice == "streaming":
            self.plan = R.streaming_plan(size, counts)
        elif node.choice == "ac":
            self.plan = R.ac_plan(size, counts["ac_main"], counts["ac_covered"])
        else:
            self.plan = R.presenter_plan(size, counts["presenter_keys"])
        sections = R.STREAM_SECTIONS if node.choice == "streaming" else R.TV_SECTIONS
        self.order = [k for k in (*sections, "ac_main", "ac_covered", "presenter_keys") if k in counts]
        door = kit.one("battery_door") is not None  # a rechargeable streaming remote has no battery bay
        pieces = [R.body(self.plan, "body", door=door), R.window(self.plan, "lens"), *R.section_trim(self.plan)]
        if node.choice == "ac":
            pieces += R.lcd(self.plan, "lcd", "lens")
        self.add("body", "body", pieces)
        self.grow(kit)

    def _kit(self, node):
        for child in node.children:
            self.grow(child)

    tv = ac = presenter = streaming = _kit

    def _section(self, node, gate=None):
        index = self.order.index(node.kind)
        spots = self.plan.sections[index].spots
        for k, (key, spot) in enumerate(zip(node.of("key"), spots, strict=True)):
            self.grow(key, at=self.plan.key_frame(index, spot), spot=spot, name=f"{node.kind}_{k}", gate=gate)

    top_row = apps = numpad = volume = navigation = colour_keys = ac_main = presenter_keys = _section
    stream_top = stream_pad = stream_keys = _section

    def ac_covered(self, node):
        self._section(node, gate="cover")

    def playback(self, node):
        cover = node.one("playback_cover")
        if cover is not None:
            self.grow(cover)
        self._section(node, gate=None if cover is None else "cover")

    def playback_cover(self, node):
        lid = self.place(R.cover(self.plan, "body"), "cover")
        self.extend("body", R.cover_hinge(self.plan, "body")[0])
        self.hinge("body", lid.root, lid.anchor("hinge"), upper=R.COVER_OPENS, role="lid")

    def power_switch(self, node):
        knob, slot = R.power_switch(self.plan, "key", "lens")
        self.extend("body", slot)
        placed = self.place(knob, "power_switch")
        self.slide("body", placed.root, placed.anchor("slide"), upper=R.SWITCH[3], role="toggle")

    def key(self, node, at, spot, name, gate):
        placed = self.place(spot.key.build(spot.slot).attached("mount", to=at), name)
        self.slide("body", placed.root, placed.anchor("press"), upper=spot.key.travel, role="button",
                   requires_open=gate)

    def cover(self, node):
        lid = self.place(R.cover(self.plan, "body"), "cover")
        self.extend("body", R.cover_hinge(self.plan, "body")[0])
        self.hinge("body", lid.root, lid.anchor("hinge"), upper=R.COVER_OPENS, role="lid")
        self.grow(node.one("ac_covered"))

    def battery_door(self, node):
        door = self.place(R.battery_door(self.plan, "body"), "battery_door")
        self.slide("body", door.root, door.anchor("slide"), upper=R.door_travel(self.plan))


CATEGORY = Category("remote", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, RemoteLayout, MATERIALS)
