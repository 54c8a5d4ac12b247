"""Bar chair: a tall swivel stool: a drafting stool on casters, a disc-base gas-lift stool, or a four-leg swivel stool.

X is depth (the sitter faces +X), Y is width, Z is up. Two bases: the office chair's star base
(5 legs, rarely 4 or 6, with swivelling casters; the wheels touch the floor) with a tall column
and an optional foot ring, or a heavy domed disc with a tall column and a foot ring. The gas lift
is a hollow tube in the column around a fixed piston rod, sliding up along +Z from its lowest
(rest) position; the seat (round or square) swivels on top of it. An optional low back stands on
a spine behind the seat, fixed or reclining (hinge behind its centre of mass, so gravity holds it
upright). Three designs (``base_type``): ``wheeled`` (a drafting stool: the foot ring, where it
has one, slides up and down the column), ``disc`` (a pedestal bar stool with a fixed foot ring),
``four_leg`` (four splayed steel legs with a foot rail and a swivel bearing plate; no lift, as on
most four-leg swivel bar stools). A gas-lift stool may have its height lever as a moving part and a
seat that tilts forward (sit-stand stools). A stool with a back may have two arms: fixed, height-adjustable
(the post slides up) or flip-up (drafting chairs). A gas-lift stool's square pan may slide forward on its
mechanism (seat depth adjustment), and one whose back reclines may have a tilt-tension knob.
Parts: ``categories/parts/seating.py`` (shared with the office chair).
"""

from __future__ import annotations

from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import seating as S
from .parts.seating_sizes import BAR_CHAIR_MECHANISM as M
from .parts.seating_sizes import BAR_CHAIR_RANGES as R
from .parts.seating_sizes import BAR_CHAIR_SHARES as W

GRAMMAR = Grammar("bar_chair", {
    "bar_chair": Node(required=("seat",), one_of={"wheeled": 0.5, "disc": 0.36, "four_leg": 0.14},
                      choice="base_type", optional={"back": 0.65, "arms": 0.45}),
    "wheeled": Node(label="base", required=("lift",), repeat={"caster": S.legs}, optional={"ring_slide": 0.7}),
    "disc": Node(label="base", required=("lift", "foot_ring")),
    "four_leg": Node(label="base"),
    "foot_ring": Node(),
    "ring_slide": Node(label="foot_ring"),
    "caster": Node(label="caster", one_of={"twin": 0.6, "single": 0.4}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "lift": Node(label="lift", optional={"lever": 0.5, "seat_tilt": 0.35}),
    "lever": Node(label="lever"),
    "seat_tilt": Node(label="seat"),
    "seat": Node(label="seat", optional={"seat_slider": 0.35, "tension_knob": 0.5}),
    "seat_slider": Node(label="seat"),
    "tension_knob": Node(label="knob"),
    "back": Node(label="back"),
    "arms": Node(repeat={"arm": 2}),
    "arm": Node(label="arm", one_of={"arm_fixed": 0.4, "arm_height": 0.3, "arm_flip": 0.3}, choice="arm_style"),
    "arm_fixed": Node(), "arm_height": Node(), "arm_flip": Node(),
})

PARAMS = (
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", *R["seat_height"]),
    Float("seat_width", "seat width, or diameter of a round seat", "m", *R["seat_width"]),
    Float("seat_depth", "square seat depth (X)", "m", *R["seat_depth"]),
    Float("seat_thickness", "seat cushion thickness", "m", *R["seat_thickness"]),
    Choice("seat_shape", "seat outline", choices=("round", "square"), weights=W["seat_shape"]),
    Int("leg_count", "legs of a wheeled base; auto = drawn, 5 on nearly every base", "", *R["leg_count"], auto=True),
    Float("base_radius", "caster axes (wheeled), disc radius or leg feet (four-leg) from the centre", "m",
          *R["base_radius"]),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=W["leg_style"]),
    Float("wheel_radius", "wheel radius", "m", *R["wheel_radius"]),
    Float("lift_radius", "gas lift tube radius", "m", *R["lift_radius"]),
    Float("lift_travel", "gas lift stroke", "m", *R["lift_travel"]),
    Float("exposed_lift", "lift tube visible between the column and the seat at rest", "m", *R["exposed_lift"]),
    Float("ring_drop", "foot ring below the seat top", "m", *R["ring_drop"]),
    Float("ring_radius", "foot ring radius", "m", *R["ring_radius"]),
    Float("back_height", "backrest height", "m", *R["back_height"]),
    Float("back_width", "backrest width as a fraction of the seat width", "", *R["back_width"]),
    Float("back_thickness", "backrest thickness", "m", *R["back_thickness"]),
    Float("back_gap", "backrest bottom above the seat top", "m", *R["back_gap"]),
    Choice("back_mount", "the back is fixed or reclines", choices=("fixed", "hinged")),
    Float("recline", "back recline range (hinged back)", "rad", *R["recline"]),
    # arms of drafting chairs and bar stools with backs (Boss B1615/B16245 drafting stools: fixed or height-
    # adjustable loop arms; Flash Furniture drafting chairs: flip-up arms): pads 22-26 cm above the seat
    Float("arm_height", "arm pad top above the seat top", "m", *R["arm_height"]),
    Float("arm_travel", "height-adjustable arms: travel", "m", *R["arm_travel"]),
    Float("pad_length", "arm pad length (X)", "m", *R["pad_length"]),
    Float("pad_width", "arm pad width (Y)", "m", *R["pad_width"]),
    Choice("base_finish", "base material", choices=("chrome", "brushed_metal", "plastic"),
           weights=W["base_finish"]),
    Choice("lift_finish", "gas lift cylinder: chromed or black-coated steel", choices=("chrome", "black"),
           weights=W["lift_finish"]),
    Choice("seat_finish", "seat upholstery", choices=("fabric", "plastic"), weights=W["seat_finish"]),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=W["wheel_finish"]),
)

class StoolLayout(S.ChairNodes):
    def bar_chair(self, node):
        p = self.p
        design = node.one(node.choice)
        lift = design.one("lift")
        seat = self.grow(node.one("seat"), lever=bool(lift and lift.one("lever")),
                         tilt=bool(lift and lift.one("seat_tilt")))
        self.grow(design, seat=seat)
        if node.one("back"):
            front = self.grow(node.one("back"), seat=seat, hinged=p["back_mount"] == "hinged")
            if node.one("arms"):
                self.grow(node.one("arms"), seat=seat, back_front=front)

    def arms(self, node, seat, back_front):
        """Two arms on brackets under the seat, beside the back (as the office chair's, without its 4D pads)."""
        p = self.p
        dims = S.ArmDims(p["pad_length"], p["pad_width"], p["arm_height"], 0.0, 0.0, 0.0)
        y = S.arm_y(p["seat_width"], dims, p["back_width"] * p["seat_width"], back_front, seat)
        for arm, (side, sign) in zip(node.of("arm"), S.SIDES, strict=True):
            self.grow(arm, seat=seat, y=sign * y, side=side, dims=dims)

    def arm(self, node, seat, y, side, dims):
        """Fixed; sliding up its post (a height-adjustable arm); or a flip-up arm (so the sitter can slide in
        sideways): the post stays, its cap (carriage and pad) turns up about the carriage's rear end to stand upright
        beside the back, above the seat."""
        a = S.arm(seat, self.p["seat_height"], y, dims)
        style = node.choice
        self.extend("seat", a.bracket)
        if style == "arm_flip":  # the post is the seat's; the cap on it (carriage and pad) flips up
            self.extend("seat", a.post)
        post = self.add(f"arm_{side}", "arm", a.slider if style == "arm_flip" else a.post)
        if style == "arm_height":
            self.slide("seat", post, a.post_slide, upper=self.p["arm_travel"], role="telescope")
        elif style == "arm_fixed":
            self.fix("seat", post)
        else:  # flip-up: a positive turn about -y lifts the cap's front; it stands upright beside the back
            self.hinge("seat", post, a.flip, upper=S.ARM_FLIP)
        self.grow(node.one(style), arm=a, post=post)

    def arm_fixed(self, node, arm, post):
        self.extend(post, [*arm.slider, *arm.pad])

    arm_height = arm_fixed

    def arm_flip(self, node, arm, post):
        self.extend(post, arm.pad)  # the cap: the carriage is the hinged part's already

    def seat(self, node, lever, tilt):
        p = self.p
        depth = S.square_depth(p["seat_shape"], p["seat_width"], p["seat_depth"])
        seat = S.swivel_seat(p["seat_height"], p["seat_width"], depth, p["seat_thickness"], p["seat_shape"], 0.0,
                             p["lift_radius"], M.height)
        pieces = seat.assembly.parts[seat.assembly.root].pieces
        if lever:  # the lever is its own part (grown under the lift)
            pieces = S.height_lever(seat, M.height, self._lever_reach(), self._mech_y())[0]
        slider = node.one("seat_slider")
        if tilt or slider:  # the pan and cushion are their own part (grown under the lift, or the slider)
            pieces = [pc for pc in pieces if pc.material not in ("seat", "pan")]
        self.add("seat", "seat", pieces)
        if slider:
            self.grow(slider, seat=seat)
        if node.one("tension_knob"):
            self.grow(node.one("tension_knob"), seat=seat)
        return seat

    def seat_slider(self, node, seat):
        """The pan and cushion slide forward on rails of the mechanism (seat depth adjustment of drafting chairs,
        e.g. Steelcase Leap / Herman Miller Aeron stools, Boss B16xx drafting stools' seat slider)."""
        self.add("seat_pan", "seat", S.split_seat(seat)[1])
        self.slide("seat", "seat_pan", S.seat_slide_axis(seat), upper=S.SEAT_SLIDE)

    def tension_knob(self, node, seat):
        """The tilt-tension knob at the front of the mechanism (drafting stools whose back reclines)."""
        p = self.p
        depth = S.knob_depth(p["seat_shape"], p["seat_width"], p["seat_depth"])
        pieces, axis = S.tension_knob(seat, depth, M.height)
        self.add("tension_knob", "knob", pieces)
        self.spin("seat", "tension_knob", axis, role="knob")

    def _lever_reach(self):
        """The paddle's y, under the seat's edge (as on the office chair's seat)."""
        return S.lever_reach(self.p["seat_shape"], self.p["seat_width"])

    def _mech_y(self):
        p = self.p
        return S.mech_half_y(p["seat_shape"], p["seat_width"], p["seat_depth"])

    def seat_tilt(self, node, seat):
        """The pan and cushion tilt forward about the mechanism's front edge (a saddle / sit-stand stool)."""
        p = self.p
        self.add("seat_pan", "seat", S.split_seat(seat)[1])
        depth = S.square_depth(p["seat_shape"], p["seat_width"], p["seat_depth"])
        self.hinge("seat", "seat_pan", S.tilt_pivot(seat, p["seat_shape"], p["seat_width"], depth),
                   upper=S.SEAT_TILT)

    def wheeled(self, node, seat):
        base = self.star_base(node)
        self._lift(node, base, seat)
        return self._column(node, base, seat, node.one("ring_slide"))

    def disc(self, node, seat):
        base = S.disc_base(self.p["base_radius"], self.p["lift_radius"] + S.GAP,
                           metal=self.p["base_finish"] != "plastic")
        self.place(base.assembly, "base")
        self._lift(node, base, seat)
        return self._column(node, base, seat, node.one("foot_ring"))

    def four_leg(self, node, seat):
        p = self.p
        self.add("base", "base", S.four_leg_stool(seat.lift_top, p["seat_height"], p["ring_drop"], p["base_radius"]))
        self.spin("base", "seat", seat.assembly.anchor("swivel"), role="swivel")

    def _lift(self, node, base, seat):
        self.grow(node.one("lift"), base=base, seat=seat)

    def lever(self, node, seat):
        _, pieces, pivot, upper = S.height_lever(seat, M.height, self._lever_reach(), self._mech_y())
        self.add("lever", "lever", pieces)
        self.hinge("seat", "lever", pivot, upper=upper, role="button")

    def lift(self, node, base, seat):
        super().lift(node, base, seat)
        if node.one("lever"):
            self.grow(node.one("lever"), seat=seat)
        if node.one("seat_tilt"):
            self.grow(node.one("seat_tilt"), seat=seat)

    def _column(self, node, base, seat, ring):
        p = self.p
        z_ring = max(p["seat_height"] - p["ring_drop"], base.top + M.ring_above_hub, S.RING_MIN)
        top = seat.lift_top - S.COLUMN_BELOW_LIFT - p["exposed_lift"]
        if ring:
            top, z_ring = S.ring_column(top, z_ring, seat.lift_top)
        self.extend("base", S.column(base.top, top, base.bore))
        if ring:
            self.grow(ring, z=z_ring, bore=base.bore, top=top)
        return base

    def foot_ring(self, node, z, bore, top):
        self.extend("base", S.foot_ring(z, self.p["ring_radius"], bore))

    def ring_slide(self, node, z, bore, top):
        """A drafting stool's foot ring: clamped on the column, it slides up and down it."""
        ring = S.stool_ring(z, top, self.p["ring_radius"], bore, M.ring_travel)
        self.add("foot_ring", "foot_ring", ring.ring)
        self.slide("base", "foot_ring", ring.at, upper=ring.travel, role="slide")


def arms_need_a_back(p: dict) -> dict:
    """Arms stand beside a back: a stool without one has none. A seat slider moves a square pan that does not
    tilt; a tension knob sets the recline of a hinged back (and sits where a tilting pan would dip); both are
    parts of a gas-lift stool's seat mechanism."""
    tilt, mech = p["has_seat_tilt"], p["base_type"] != "four_leg"  # a four-leg stool's seat is on a bare bearing
    return {**p, "has_arms": p["has_arms"] and p["has_back"],
            "has_seat_slider": p["has_seat_slider"] and mech and p["seat_shape"] == "square" and not tilt,
            "has_tension_knob": (p["has_tension_knob"] and mech and p["has_back"] and p["back_mount"] == "hinged"
                                 and not tilt)}


CATEGORY = Category("bar_chair", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, StoolLayout,
                    S.CHAIR_MATERIALS, derive=arms_need_a_back, palette=furniture)
