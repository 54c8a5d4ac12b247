"""Suitcase: a hard-shell spinner, a soft two-wheel upright or a carry-on, with a telescopic handle.

Designs (``design``): a hard spinner (checked size, two moulded or aluminium shells split 50/50) and a carry-on
(cabin size, a hard or a soft case) roll on four spinner casters, each turning about its stem (swivel) and
its wheels about their axles; a soft upright rolls on two inline wheels at its back corners over a moulded
base. Every case opens as a clamshell: its front shell (the lid) turns about a vertical hinge at its right edge
and lies open beside the case (the gravity torque about a vertical hinge is nil); an expandable case's lid is
hinged on a gusset that slides out of the body's rim. The telescopic handle rises
in two stages (a prismatic chain, each stage on the one below); a folding carry handle lies on the top and
maybe one on the left side; a soft case or a carry-on may have a front pocket hinged on the lid, and a case may
have a combination lock of three thumbwheels. Parts: ``categories/parts/luggage.py``.
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float

from .parts import luggage as L
from .parts import seating as S

CASE = {"side_handle": 0.5, "lock": 0.5, "expander": 0.4}  # optional on every case

GRAMMAR = Grammar("suitcase", {
    "suitcase": Node(label="body", one_of={"hard_spinner": 0.35, "soft_upright": 0.3, "carry_on": 0.35},
                     choice="design"),
    "hard_spinner": Node(required=("lid", "telescope", "top_handle", "spinners"), optional=CASE),
    "soft_upright": Node(required=("pocket_lid", "telescope", "top_handle", "wheels"), optional=CASE),
    "carry_on": Node(required=("pocket_lid", "telescope", "top_handle"), optional=CASE,
                     one_of={"spinners": 0.6, "wheels": 0.4}),
    "lid": Node(label="lid", optional={"divider": 0.5}),
    "pocket_lid": Node(label="lid", optional={"divider": 0.5, "pocket": 0.5}),
    "divider": Node(label="divider"),
    "expander": Node(label="expander"),
    "pocket": Node(label="pocket"),
    "telescope": Node(label="handle", repeat={"mid_stage": (0, 1)}, required=("grip_stage",)),
    "mid_stage": Node(label="handle"),
    "grip_stage": Node(label="handle"),
    "top_handle": Node(label="handle"),
    "side_handle": Node(label="handle"),
    "spinners": Node(repeat={"spinner": 4}),
    "spinner": Node(label="caster", one_of={"twin": 0.5, "single": 0.5}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "wheels": Node(repeat={"inline_wheel": 2}),
    "inline_wheel": Node(label="wheel"),
    "lock": Node(repeat={"thumbwheel": 3}),
    "thumbwheel": Node(label="knob"),
})
"""Designs: hard spinner (four casters), soft upright (two inline wheels), carry-on (a hard or soft case on four
casters or two inline wheels). Every case has a lid (maybe with a zip-up divider inside; a soft upright's or a
carry-on's maybe with a front pocket; maybe on an expansion gusset), a telescopic handle of two or three stages
and a top carry handle; maybe a side carry handle and a three-wheel combination lock."""

PARAMS = (
    Float("height_share", "height (Z, wheels included) within the design's range (SIZES in parts/luggage.py),"
                          " 0 to 1", "", 0.0, 1.0),
    Float("width_share", "width (Y) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("depth_share", "depth (X) within the design's range, 0 to 1", "", 0.0, 1.0),
    Float("corner_share", "corner radius seen from the front within the shell's range (ROUND), 0 to 1", "",
          0.0, 1.0),
    Float("caster_radius", "spinner wheel radius: 50-65 mm wheels (Samsonite, Hinomoto)", "m", 0.024, 0.031),
    Float("wheel_radius", "a two-wheeler's inline wheel radius: 68-80 mm skate wheels", "m",
          *L.INLINE["radius"]),
    Float("grip_share", "the telescopic grip's thickness within 24-30 mm, 0 to 1", "", 0.0, 1.0),
    Choice("carry_on_shell", "a carry-on's case: moulded hard shell or soft fabric", choices=("hard", "soft")),
    Choice("hard_finish", "a hard shell's material: polycarbonate or grooved aluminium",
           choices=("plastic", "brushed_metal"), weights=(0.8, 0.2)),
    Choice("shell_style", "a hard shell's face: smooth or with raised ribs", choices=("smooth", "ribbed")),
)

_SHELL = "plastic:black|dark_grey|light_grey|white|red|blue|teal|green|orange|yellow"
MATERIALS = {"shell": ("hard_finish", {"plastic": _SHELL}), "fabric": "fabric:charcoal|navy|grey|burgundy|olive|denim",
             "lining": "fabric:grey|beige|cream|charcoal|teal", "trim": "plastic:black|dark_grey",
             "handle": "plastic:black|dark_grey", "tube": "brushed_metal", "caster": "plastic:black|dark_grey",
             "wheel": "rubber", "hub": "plastic:light_grey|dark_grey", "knob": "plastic:black|dark_grey"}
SUBSTRATES = {"shell": ("hard_finish", {"brushed_metal": L.ALUMINIUM}), "fabric": L.SOFT_DENSITY,
              "tube": L.ALUMINIUM}  # aluminium shells and tubes, a soft case's layup (see parts/luggage.py)


class SuitcaseLayout(Layout):
    def suitcase(self, node):
        p, design = self.p, node.choice
        hard = design == "hard_spinner" or (design == "carry_on" and p["carry_on_shell"] == "hard")
        self.shell = ("shell" if hard else "fabric")
        finish = p["hard_finish"] if hard else "fabric"
        self.ribbed = hard and (p["shell_style"] == "ribbed" or finish == "brushed_metal")
        spinners = node.one(design).one("spinners")
        if spinners:
            self.caster = S.caster(spinners.of("spinner")[0].choice, p["caster_radius"])
            z0 = self.caster.stem_top + 0.012
        else:
            z0 = L.plinth_height(p["wheel_radius"])
        lo, hi = L.ROUND["hard" if hard else "soft"]["corner"]
        shares = (p["height_share"], p["width_share"], p["depth_share"])
        s = self.size = L.case_size(design, shares, z0, lo + p["corner_share"] * (hi - lo), hard, finish)
        pieces = L.body_shell(s, self.shell, "trim", "lining", self.ribbed) + L.handle_housing(s, "trim")
        if spinners:
            self.tips = L.spinner_tips(s, self.caster.footprint)
            pieces += L.spinner_housings(s, self.tips, self.caster.stem_top, "trim")
        else:
            self.inline = L.inline_wheels(s.width, s.depth, p["wheel_radius"])
            pieces += L.plinth(s, self.inline, "trim", "trim")  # a black moulded bumper, as on soft uprights
        self.add("body", "body", pieces)
        self.grow(node.one(design))

    def _case(self, node):
        self.lid_parent = "body"
        for kind in ("expander", "lid", "pocket_lid", "telescope", "top_handle", "side_handle", "spinners", "wheels",
                     "lock"):
            if node.one(kind):
                self.grow(node.one(kind))

    hard_spinner = soft_upright = carry_on = _case

    def lid(self, node):
        made = self.place(L.lid(self.size, self.shell, "lining", self.ribbed), "lid")
        self.hinge(self.lid_parent, made.root, made.anchor("hinge"), upper=L.LID_OPENS)
        for kind in ("pocket", "divider"):
            if node.one(kind):
                self.grow(node.one(kind), lid=made)

    pocket_lid = lid

    def expander(self, node):
        made = self.place(L.expander(self.size, "trim" if self.size.hard else self.shell), "expander")
        depth = L.expander_depth(self.size)
        self.slide("body", made.root, made.anchor("slide"), upper=depth - L.EXPANDER["overlap"])
        self.lid_parent = made.root

    def divider(self, node, lid):
        made = self.place(L.divider(self.size, "lining", "trim"), "divider")
        self.hinge(lid.root, made.root, made.anchor("hinge"), upper=L.DIVIDER_OPENS, requires_open="lid")

    def pocket(self, node, lid):
        made = self.place(L.pocket(self.size, self.shell, "trim"), "pocket")
        self.hinge(lid.root, made.root, made.anchor("hinge"), upper=L.POCKET_OPENS)

    def telescope(self, node):
        mids = node.of("mid_stage")
        t = L.telescope(self.size, 2 + len(mids), self.p["grip_share"])
        below = self.place(L.stage(self.size, t, 0, "tube", "trim"), "handle_stage_0")
        self.slide("body", below.root, below.anchor("slide"), upper=t.travel, role="telescope")
        for k, n in enumerate(mids, start=1):
            below = self.grow(n, below=below, t=t, k=k)
        self.grow(node.one("grip_stage"), below=below, t=t, k=t.stages - 1)

    def mid_stage(self, node, below, t, k):
        made = self.place(L.stage(self.size, t, k, "tube", "handle" if k == t.stages - 1 else "trim"),
                          f"handle_stage_{k}")
        self.slide(below.root, made.root, below.anchor("next"), upper=t.travel, role="telescope")
        return made

    grip_stage = mid_stage

    def _carry(self, name, at):
        length = sum(L.CARRY["length"]) / 2
        self.extend("body", L.carry_mounts(at, length, "trim"))
        made = self.place(L.carry_handle(length, "handle").attached("pivot", to=at), name)
        self.hinge("body", made.root, at, upper=L.CARRY_TURN)

    def top_handle(self, node):
        self._carry("top_handle", L.top_handle_frame(self.size))

    def side_handle(self, node):
        self._carry("side_handle", L.side_handle_frame(self.size))

    def spinners(self, node):
        for i, (n, tip) in enumerate(zip(node.of("spinner"), self.tips, strict=True)):
            self.grow(n, tip=tip, i=i)

    def spinner(self, node, tip, i):
        """A swivel caster under a housing: the fork turns about its stem, its wheels about their axle."""
        f = self.place(S.fork(self.caster).placed(tip), f"caster_{i}")
        self.spin("body", f.root, f.anchor("swivel"), role="swivel")
        wheels = [w.mounted(tip) for w in S.wheels(self.caster)]
        self.grow(node.one(node.choice), fork=f, wheels=wheels, i=i)

    def twin(self, node, fork, wheels, i):
        for k, w in enumerate(wheels):
            wheel = self.place(w, f"wheel_{i}" if len(wheels) == 1 else f"wheel_{i}_{k}")
            self.spin(fork.root, wheel.root, wheel.anchor("axle"), role="wheel")

    single = twin

    def wheels(self, node):
        for i, (n, side) in enumerate(zip(node.of("inline_wheel"), (-1, 1), strict=True)):
            self.grow(n, side=side, i=i)

    def inline_wheel(self, node, side, i):
        made = self.place(L.inline_wheel(self.inline, side, "wheel", "hub"), f"wheel_{i}")
        self.spin("body", made.root, made.anchor("axle"), role="wheel")

    def lock(self, node):
        self.extend("body", L.lock_housing(self.size, "trim"))
        _, axles = L.lock_frames(self.size)
        for i, (n, at) in enumerate(zip(node.of("thumbwheel"), axles, strict=True)):
            self.grow(n, at=at, i=i)

    def thumbwheel(self, node, at, i):
        made = self.place(L.thumbwheel(at, "knob"), f"dial_{i}")
        self.spin("body", made.root, made.anchor("axle"), role="knob")


CATEGORY = Category("suitcase", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, SuitcaseLayout, MATERIALS,
                    substrates=SUBSTRATES)
