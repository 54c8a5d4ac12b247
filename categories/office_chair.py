"""Office chair: task, executive, mesh or drafting chair on a wheeled star base with a gas lift and swivel.

X is depth (the sitter faces +X), Y is width, Z is up. The base is a hub with 5 legs (rarely 4
or 6); at the tip of every leg a caster swivels about a vertical axis, carrying one wheel or a
pair of twin wheels that turn about a horizontal axle along the leg. The wheels touch the floor.

The gas lift is a hollow tube standing in the hub's socket around a fixed piston rod: it slides
up along +Z from its lowest (rest) position. On top of it the seat swivels about Z. The back
hangs on a spine whose recline hinge is behind the backrest's centre of mass, so gravity holds
it upright against its stop. Each arm is a hollow post sliding up over a bar under the seat, a
carriage on top that slides along X and turns about Z, and a pad that turns about Z on it.

Four designs (``design``), each with its own structure:
- task: a cushion (or mesh) back, optionally a lumbar pad sliding up and down and an adjustable headrest;
- executive: a tall, thick upholstered back with a headrest that slides up on a stalk;
- mesh: a framed mesh back with a sliding lumbar pad, optionally the adjustable headrest;
- drafting: a tall chair (seat 0.62-0.78 m) with a foot ring that slides up and down the column,
  an optional low back.
Any design may have a tilt-tension knob (turning, under the seat's front), a seat slider (pan and cushion slide
forward on the mechanism) and arms of one style: 4D (height, slide, turn, pad turn), height-only, fixed, or
flip-up (the cap on the post turns up about a hinge at its carriage's rear end, to stand upright beside the
back, above the seat).
Parts: ``categories/parts/seating.py`` (shared with the bar chair).
"""

from __future__ import annotations

from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import seating as S
from .parts.seating_sizes import EXEC_BACK, EXEC_THICK
from .parts.seating_sizes import OFFICE_CHAIR_MECHANISM as M
from .parts.seating_sizes import OFFICE_CHAIR_RANGES as R
from .parts.seating_sizes import OFFICE_CHAIR_SHARES as W

GRAMMAR = Grammar("office_chair", {
    "office_chair": Node(required=("base", "lift", "seat"), optional={"arms": 0.75},
                         one_of={"task": 0.4, "executive": 0.2, "mesh_chair": 0.25, "drafting": 0.15},
                         choice="design"),
    "base": Node(label="base", repeat={"caster": S.legs}),
    "caster": Node(label="caster", one_of={"twin": 0.6, "single": 0.4}, choice="caster_style"),
    "twin": Node(label="wheel"),
    "single": Node(label="wheel"),
    "lift": Node(label="lift"),
    "seat": Node(label="seat", optional={"seat_slider": 0.5, "tension_knob": 0.5}),
    "tension_knob": Node(label="knob"),
    "seat_slider": Node(label="seat"),
    "task": Node(required=("back",)),
    "executive": Node(required=("high_back",)),
    "mesh_chair": Node(required=("mesh_back",)),
    "drafting": Node(required=("foot_ring",), optional={"back": 0.6}),
    "back": Node(label="back", one_of={"cushion": 0.7, "mesh": 0.3}, choice="back_style",
                 optional={"headrest": 0.3, "lumbar": 0.45}),
    "high_back": Node(label="back", required=("headrest",)),
    "mesh_back": Node(label="back", required=("lumbar",), optional={"headrest": 0.3}),
    "cushion": Node(), "mesh": Node(),
    "headrest": Node(label="headrest"),
    "lumbar": Node(label="lumbar"),
    "foot_ring": Node(label="foot_ring"),
    "arms": Node(repeat={"arm": 2}),
    "arm": Node(label="arm", one_of={"arm_4d": 0.45, "arm_height": 0.2, "arm_fixed": 0.15, "arm_flip": 0.2},
                choice="arm_style"),
    "arm_4d": Node(required=("arm_slider",)),
    "arm_height": Node(), "arm_fixed": Node(), "arm_flip": Node(),
    "arm_slider": Node(label="arm", required=("arm_pad",)),
    "arm_pad": Node(label="armrest"),
})
"""Design shares: task chairs are most of the market, then mesh and executive chairs, drafting chairs
a niche; arm styles: 4D arms on most mid-range task chairs, flip-up arms on desk-sharing chairs."""

PARAMS = (
    Float("seat_height", "seat top above the floor at rest (lift down)", "m", *R["seat_height"]),
    Float("seat_width", "seat width (Y)", "m", *R["seat_width"]),
    Float("seat_depth", "seat depth (X)", "m", *R["seat_depth"]),
    Float("seat_thickness", "seat cushion thickness", "m", *R["seat_thickness"]),
    Int("leg_count", "legs of the star base; auto = drawn, 5 on nearly every chair", "", *R["leg_count"], auto=True),
    Float("base_radius", "caster swivel axes from the centre (raised for many legs)", "m", *R["base_radius"]),
    Choice("leg_style", "leg shape", choices=("tapered", "straight"), weights=W["leg_style"]),
    Float("wheel_radius", "wheel radius", "m", *R["wheel_radius"]),
    Float("lift_radius", "gas lift tube radius", "m", *R["lift_radius"]),
    Float("lift_travel", "gas lift stroke (capped where the column is short)", "m", *R["lift_travel"]),
    Float("back_height", "backrest height (an executive back: 0.62-0.75 m)", "m", *R["back_height"]),
    Float("draft_seat_height", "seat top of a drafting chair at rest (BIFMA counter-height task chairs)", "m",
          *R["draft_seat_height"]),
    Float("ring_radius", "drafting chair foot ring radius (0.40-0.50 m rings)", "m", *R["ring_radius"]),
    Float("back_width", "backrest width as a fraction of the seat width", "", *R["back_width"]),
    Float("back_thickness", "backrest thickness", "m", *R["back_thickness"]),
    Float("back_gap", "backrest bottom above the seat top", "m", *R["back_gap"]),
    Float("recline", "back recline range", "rad", *R["recline"]),
    Float("arm_height", "arm pad top above the seat top", "m", *R["arm_height"]),
    Float("arm_travel", "arm height adjustment", "m", *R["arm_travel"]),
    Float("pad_length", "arm pad length (X)", "m", *R["pad_length"]),
    Float("pad_width", "arm pad width (Y)", "m", *R["pad_width"]),
    Float("arm_slide", "arm pad slide along X, each way", "m", *R["arm_slide"]),
    Float("arm_turn", "arm carriage turn about Z, each way", "rad", *R["arm_turn"]),
    Float("pad_turn", "arm pad turn about Z, each way", "rad", *R["pad_turn"]),
    Choice("base_finish", "star base material", choices=("plastic", "chrome", "brushed_metal"),
           weights=W["base_finish"]),
    Choice("lift_finish", "gas lift cylinder: chromed or black-coated steel", choices=("chrome", "black"),
           weights=W["lift_finish"]),
    Choice("seat_finish", "seat and back upholstery", choices=("fabric", "plastic"), weights=W["seat_finish"]),
    Choice("wheel_finish", "wheel tyres", choices=("plastic", "rubber"), weights=W["wheel_finish"]),
)


def drafting_height(p: dict) -> dict:
    """A drafting chair's seat is ``draft_seat_height`` high."""
    return {**p, "seat_height": p["draft_seat_height"]} if p["design"] == "drafting" else p


class ChairLayout(S.ChairNodes):
    def office_chair(self, node):
        base = self.grow(node.one("base"))
        seat = self.grow(node.one("seat"), base=base)
        self.grow(node.one("lift"), base=base, seat=seat)
        front = self.grow(node.one(node.choice), seat=seat, base=base)
        if node.one("arms"):
            self.grow(node.one("arms"), seat=seat, back_front=front)

    def base(self, node):
        return self.star_base(node)

    def seat(self, node, base):
        p = self.p
        thick = S.seat_thickness(p["seat_height"], p["seat_thickness"], base.top, M.height)
        seat = S.swivel_seat(p["seat_height"], p["seat_width"], p["seat_depth"], thick, "square", M.seat_ahead,
                             p["lift_radius"], M.height)
        if node.one("seat_slider"):
            stay, moving = S.split_seat(seat)
            self.add("seat", "seat", stay)
            self.grow(node.one("seat_slider"), seat=seat, pieces=moving)
        else:
            self.place(seat.assembly, "seat")
        if node.one("tension_knob"):
            self.grow(node.one("tension_knob"), seat=seat)
        return seat

    def tension_knob(self, node, seat):
        pieces, axis = S.tension_knob(seat, self.p["seat_depth"], M.height)
        self.add("tension_knob", "knob", pieces)
        self.spin("seat", "tension_knob", axis, role="knob")

    def seat_slider(self, node, seat, pieces):
        """The pan and cushion slide forward on rails of the mechanism (seat depth adjustment)."""
        self.add("seat_pan", "seat", pieces)
        self.slide("seat", "seat_pan", S.seat_slide_axis(seat), upper=S.SEAT_SLIDE)

    # -- designs: each returns the back's front x (None: no back) -----------------------------------
    def task(self, node, seat, base):
        return self.grow(node.one("back"), seat=seat)

    def drafting(self, node, seat, base):
        self.grow(node.one("foot_ring"), seat=seat, base=base)
        return self.grow(node.one("back"), seat=seat) if node.one("back") else None

    def executive(self, node, seat, base):
        return self.grow(node.one("high_back"), seat=seat)

    def mesh_chair(self, node, seat, base):
        return self.grow(node.one("mesh_back"), seat=seat)

    def back(self, node, seat, hinged=True):
        return self._styled_back(node, seat, self.back_dims(), node.choice)

    def high_back(self, node, seat):
        p = self.p
        dims = S.BackDims(S.executive_back(p["back_height"], *EXEC_BACK), p["back_width"] * p["seat_width"],
                          max(p["back_thickness"], EXEC_THICK), p["back_gap"])
        return self._styled_back(node, seat, dims, "cushion")

    def mesh_back(self, node, seat):
        return self._styled_back(node, seat, self.back_dims(), "mesh")

    def _styled_back(self, node, seat, dims, style):
        frame = S.back_frame(seat, self.p["seat_height"], dims)
        self.extend("seat", frame.bracket)
        self.add("back", "back", frame.spine)
        pieces, front = S.mesh_back(frame, dims) if style == "mesh" else S.cushion_back(frame, dims)
        if style == "cushion" and node.one("lumbar"):
            pieces = pieces[:-1]  # the fixed lumbar bulge gives way to the sliding pad
            front = max(float(pc.bounds[1, 0]) for pc in pieces)
        if node.one(style):
            self.grow(node.one(style), pieces=pieces)
        else:
            self.extend("back", pieces)
        self.hinge("seat", "back", frame.hinge, upper=self.p["recline"])
        reach = front
        if node.one("lumbar"):
            reach = max(reach, self.grow(node.one("lumbar"), frame=frame, dims=dims, front=front))
        if node.one("headrest"):
            reach = max(reach, self.grow(node.one("headrest"), frame=frame, dims=dims))
        return reach

    def cushion(self, node, pieces):
        self.extend("back", pieces)

    mesh = cushion

    def headrest(self, node, frame, dims):
        pieces, slide, tilt = S.adjustable_headrest(frame, dims)
        self.extend("back", S.headrest_sleeve(frame))
        self.add("headrest", "headrest", pieces)
        self.slide("back", "headrest", slide, upper=S.HEADREST_TRAVEL)  # gravity holds it at its lowest
        return S.headrest_reach(frame)

    def lumbar(self, node, frame, dims, front):
        pieces, at = S.lumbar_pad(frame, dims, front)
        self.add("lumbar", "lumbar", pieces)
        travel, reach = S.lumbar_slide(dims, front)
        self.slide("back", "lumbar", at, upper=travel)
        return reach

    def foot_ring(self, node, seat, base):
        """A chrome foot ring clamped on a column sleeve; it slides up and down the sleeve."""
        ring = S.drafting_ring(seat, base, self.p["ring_radius"], M.ring_travel)
        self.extend("base", ring.column)
        self.add("foot_ring", "foot_ring", ring.ring)
        self.slide("base", "foot_ring", ring.at, upper=ring.travel, role="slide")

    # -- arms ---------------------------------------------------------------------------------------
    def arms(self, node, seat, back_front):
        p = self.p
        dims = S.ArmDims(p["pad_length"], p["pad_width"], p["arm_height"], p["arm_slide"], p["arm_turn"],
                         p["pad_turn"])
        y = S.arm_y(p["seat_width"], dims, p["back_width"] * p["seat_width"], back_front, seat)
        for arm, (side, sign) in zip(node.of("arm"), S.SIDES):
            self.grow(arm, seat=seat, y=sign * y, side=side, dims=dims)

    def arm(self, node, seat, y, side, dims):
        a = S.arm(seat, self.p["seat_height"], y, dims)
        style = node.choice
        self.extend("seat", a.bracket)
        if style == "arm_flip":  # the post is the seat's; the cap on it (carriage and pad) flips up
            self.extend("seat", a.post)
        post = self.add(f"arm_{side}", "arm", a.slider if style == "arm_flip" else a.post)
        if style in ("arm_4d", "arm_height"):
            self.slide("seat", post, a.post_slide, upper=self.p["arm_travel"], role="telescope")
        elif style == "arm_fixed":
            self.fix("seat", post)
        else:  # flip-up: a positive turn about -y lifts the cap's front; it stands upright beside the back
            self.hinge("seat", post, a.flip, upper=S.ARM_FLIP)
        self.grow(node.one(style), arm=a, side=side, post=post, dims=dims)

    def arm_height(self, node, arm, side, post, dims):
        self.extend(post, [*arm.slider, *arm.pad])

    arm_fixed = arm_height

    def arm_flip(self, node, arm, side, post, dims):
        self.extend(post, arm.pad)  # the cap: the carriage is the hinged part's already

    def arm_4d(self, node, arm, side, post, dims):
        self.grow(node.one("arm_slider"), arm=arm, side=side, post=post, dims=dims)

    def arm_slider(self, node, arm, side, post, dims):
        slider = self.add(f"arm_slider_{side}", "arm", arm.slider)
        c = arm.carriage
        self.join(J.revolute_prismatic(post, slider, c.origin, c.z, (-dims.turn, dims.turn), c.x,
                                       (-dims.slide, dims.slide), role="slide"))
        self.grow(node.one("arm_pad"), arm=arm, side=side, slider=slider, dims=dims)

    def arm_pad(self, node, arm, side, slider, dims):
        pad = self.add(f"arm_pad_{side}", "armrest", arm.pad)
        self.hinge(slider, pad, arm.pad_pivot, upper=dims.pad_turn, lower=-dims.pad_turn, role="swivel")


CATEGORY = Category("office_chair", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, ChairLayout,
                    S.CHAIR_MATERIALS, derive=drafting_height, palette=furniture)
