"""Sizes and shares of office chairs and bar stools, from real products, as data beside their sources.

``*_RANGES``: parameter name -> (low, high) in metres (angles in radians, fractions unitless); ``*_SHARES``:
choice parameter -> weights of its choices, in the order the category lists them. ``*_MECHANISM``: the fixed
sizes of a chair's seat mechanism and column (frozen dataclasses, read by the category's layout).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Mechanism:
    """Fixed sizes under a swivel seat: the tilt/swivel plate's height, how far a foot ring may slide."""

    height: float  # tilt mechanism (or swivel plate) under the seat pan
    ring_travel: float  # a sliding foot ring's travel up its column at most
    ring_above_hub: float = 0.0  # the lowest a foot ring sits above the base's hub
    seat_ahead: float = 0.0  # the seat's centre ahead of the column


# -- office chair -------------------------------------------------------------------------------------
# BIFMA X5.1 / ANSI-BIFMA G1 task chairs: seat 400-550 mm high, 400-600 mm wide, 400-520 mm deep; 5-leg
# bases 540-700 mm across (Steelcase Leap / Series 1, Herman Miller Aeron / Sayl, IKEA Markus spec
# sheets); 50-65 mm twin-wheel casters; 100 mm class-4 gas lifts (stroke 60-100 mm, tube 44-56 mm);
# drafting chairs 620-780 mm seats with 400-500 mm foot rings (Boss B16xx, Lorell drafting stools);
# arms: pads 200-270 x 60-90 mm, 170-250 mm above the seat, 40-80 mm height travel, 4D pads slide
# 20-40 mm and turn 6-17 degrees each way (Steelcase Leap, Herman Miller Aeron adjustable arms).
OFFICE_CHAIR_RANGES = {
    "seat_height": (0.4, 0.55), "seat_width": (0.4, 0.6), "seat_depth": (0.4, 0.52), "seat_thickness": (0.05, 0.1),
    "leg_count": (4, 6), "base_radius": (0.27, 0.35), "wheel_radius": (0.024, 0.034),
    "lift_radius": (0.022, 0.028), "lift_travel": (0.06, 0.1), "back_height": (0.3, 0.55),
    "draft_seat_height": (0.62, 0.78), "ring_radius": (0.2, 0.25), "back_width": (0.75, 0.95),
    "back_thickness": (0.04, 0.075), "back_gap": (0.04, 0.1), "recline": (0.25, 0.45), "arm_height": (0.17, 0.25),
    "arm_travel": (0.04, 0.08), "pad_length": (0.2, 0.27), "pad_width": (0.06, 0.09), "arm_slide": (0.02, 0.04),
    "arm_turn": (0.1, 0.3), "pad_turn": (0.1, 0.3),
}
# plastic (nylon) star bases on most task chairs, polished aluminium on executive ones
OFFICE_CHAIR_SHARES = {
    "leg_style": (0.65, 0.35), "base_finish": (0.55, 0.25, 0.2), "lift_finish": (0.6, 0.4),
    "seat_finish": (0.75, 0.25), "wheel_finish": (0.6, 0.4),
}
OFFICE_CHAIR_MECHANISM = Mechanism(
    height=0.04,  # synchro-tilt mechanisms 35-45 mm under the pan
    ring_travel=0.12,  # drafting chair foot ring height adjustment (Boss, Lorell: about 0.1-0.15 m)
    seat_ahead=0.02,  # the seat sits a little forward of the column
)
EXEC_BACK = (0.62, 0.75)  # executive high backs (Herman Miller Embody / Eames executive, Steelcase)
EXEC_THICK = 0.09  # an executive back's upholstery

# -- bar chair ------------------------------------------------------------------------------------------
# Bar / counter stools: seats 600-850 mm high, 340-460 mm across, 35-80 mm thick; disc bases 440-600 mm
# across, foot rings 340-460 mm across 350-500 mm below the seat (Flash Furniture, IKEA Franklin / Glenn,
# Boss B16xx / B1615 / B16245 drafting stools); gas lifts 70-120 mm stroke; low backs 140-300 mm;
# drafting-stool arms (fixed or height-adjustable loop arms, flip-up arms): pads 22-26 cm above the seat.
BAR_CHAIR_RANGES = {
    "seat_height": (0.6, 0.85), "seat_width": (0.34, 0.46), "seat_depth": (0.32, 0.42),
    "seat_thickness": (0.035, 0.08), "leg_count": (4, 6), "base_radius": (0.22, 0.3), "wheel_radius": (0.022, 0.03),
    "lift_radius": (0.022, 0.028), "lift_travel": (0.07, 0.12), "exposed_lift": (0.05, 0.15),
    "ring_drop": (0.35, 0.5), "ring_radius": (0.17, 0.23), "back_height": (0.14, 0.3), "back_width": (0.6, 0.9),
    "back_thickness": (0.03, 0.05), "back_gap": (0.06, 0.14), "recline": (0.15, 0.3), "arm_height": (0.18, 0.25),
    "arm_travel": (0.04, 0.07), "pad_length": (0.2, 0.26), "pad_width": (0.055, 0.08),
}
# chromed pedestal bases on most gas-lift stools
BAR_CHAIR_SHARES = {
    "seat_shape": (0.55, 0.45), "leg_style": (0.65, 0.35), "base_finish": (0.45, 0.25, 0.3),
    "lift_finish": (0.7, 0.3), "seat_finish": (0.6, 0.4), "wheel_finish": (0.6, 0.4),
}
BAR_CHAIR_MECHANISM = Mechanism(
    height=0.035,  # swivel plate under the seat pan
    ring_travel=0.1,  # a drafting stool's foot ring slides this far up its column at most (Boss, Lorell)
    ring_above_hub=0.07,  # the lowest a foot ring sits above the hub
)
