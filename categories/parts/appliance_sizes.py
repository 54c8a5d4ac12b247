"""Named dimension tables of the appliances (microwave, dishwasher, beverage fridge, oven, TV).

Metres (or ratios, marked) of real products; each table names its source beside its figures. The
part builders (:mod:`.microwaves`, :mod:`.dishwashers`, :mod:`.fridges`, :mod:`.ovens`,
:mod:`.displays`) read their proportions from here, so a category module describes the object and
writes no bare number.
"""

from __future__ import annotations

# -- microwave --------------------------------------------------------------------------------------
# Counter-top models 0.44-0.62 m wide, 0.32-0.46 m deep with the door, 0.25-0.36 m tall (Panasonic,
# Samsung, Whirlpool spec sheets); casing and cavity liner 0.5-0.7 mm steel sheet under any finish.
MICROWAVE = {
    "sheet": 0.0006,  # casing and liner steel sheet
    # over-the-range: 30 in wide, 0.39-0.44 m high, 0.38-0.42 m deep (GE JVM7195, Whirlpool WMH31017 spec
    # sheets); 0.1 m taller than the counter-top model the parameters describe
    "over_the_range": {"width": 0.759, "depth": (0.38, 0.42), "height": (0.39, 0.44), "taller": 0.1},
    # drawer microwave: 24 or 30 in wide (the 24 in one below a 0.53 m width parameter), 0.39 m high,
    # 0.56-0.65 m deep over the parameters' 0.32 + 0.14 m depth range (Sharp SMD2470AS / SMD3070AS)
    "drawer_model": {"widths": (0.606, 0.759), "narrow_below": 0.53, "height": 0.39, "depth": (0.56, 0.09),
                     "param_depth": (0.32, 0.14)},
    # the HV transformer's laminated core (depth, height) on the casing floor in the bay beside the cavity:
    # 2.5-4 kg with its windings (service-part listings, e.g. Samsung DE26-00126A); it needs a 30 mm bay,
    # 4 mm clear of the liner and the side wall, 20 mm in from the back, at most 80 mm wide
    "transformer": {"core": (0.09, 0.075), "clear": 0.004, "min_bay": 0.03, "side": 0.08, "from_back": 0.02},
    "edge": 0.002,  # door and fascia stop this far inside the casing's top and bottom
    "liner_in": 0.012,  # the cavity liner sits this far inside the casing walls
    "back_room": 0.02,  # behind the cavity
    "bezel_side": 0.03,  # bezel beside the cavity, on the door's free side
    "cavity_under_top": 0.03,  # the cavity's ceiling under the door's top
    "door_gap": (0.003, 0.02),  # door to bezel and fascia: at least 3 mm, 2 % of the door's size
    "swing_room": 0.001,  # past the free edge's back corner swinging out
    "foot": (0.014, 0.6, 0.006),  # rubber foot radius: min(a, b * feet height + c)
    "vent": 0.045,  # over-the-range: the vent grille band over the door and the panel
    # the vent grille: 4 mm inside the band's bottom and the casing sides; slots 6 mm wide every 12 mm
    # from 50 mm in, 10 mm over the band's bottom to 12 mm under the top; the cooktop light under the body
    # 40-90 mm behind the bezel, 80 mm wide
    "grille": {"under": 0.004, "side": 0.004, "pitch": 0.012, "slot_from": 0.05, "slot_to": 0.056,
               "slot_margin": 0.1, "slot_in": 0.01, "slot_top": 0.012, "light": ((0.09, 0.04), 0.04)},
    # grease filters (GE JVM7195, Whirlpool WMH31017 owner's manuals: "slide the filter to the rear, pull
    # down"): 28 % of the width each, centred at +-25 %, 80 mm from the back to 40 mm behind the bezel,
    # a 9 mm finger tab, 0.4 mm mesh sheet, 25 mm back in the track before they drop
    "filters": {"width": 0.28, "at": 0.25, "from_back": 0.08, "from_front": 0.04, "tab": 0.009, "sheet": 0.0004,
                "travel": 0.025},
    "strip": 0.075,  # drawer microwave: the control strip above the drawer
    "strip_gap": 0.003,  # drawer front and strip to the line between them
    "drawer_gap": 0.004,  # drawer front to the bezel
    "drawer_cavity_under": 0.02,  # the cavity's ceiling under the drawer top
    # the drawer: its tray 4 mm inside the cavity liner, 20 mm off its back, 4 mm walls, the front 3 mm off
    # the bezel; the pull 20 mm under the top, a window with 12 % side frames, 50 mm top and bottom; it
    # slides out 85 % of the tray's depth
    "drawer": {"in_liner": 0.004, "tray_back": 0.02, "wall": 0.004, "front_gap": 0.003, "pull_below": 0.02,
               "window": (0.12, 0.05), "travel": 0.85},
    "floor": 0.005,  # a flatbed's ceramic floor (a rack stands on it)
    "floor_inset": 0.01,  # the ceramic floor inside the liner walls
    "rack_clear": 0.02,  # a flatbed's rack inside the cavity's inscribed circle
    "plate_room": (0.004, 0.04),  # the turntable clears the liner by max(a, b * the largest radius)
    "rim_room": 0.012,  # a turntable's rack inside the tray's rim
    "rack_room": 0.45,  # a rack takes at most this share of the free height
    "free_margin": 1.5,  # door frame on the free side: x the window margin, at least the handle's room
    "bottom_margin": 1.15,  # door frame under the window: x the window margin
    "handle_room": {"bar": 0.06, "recessed": 0.045},  # door frame on the free side, where the handle goes
    "pull": dict(standoff=0.025, bar_radius=0.0065, post_radius=0.0052, inset=0.02),  # a bar pull on the door
    "bar_in": 0.03,  # the bar's mounts this far in from the door's free edge
    "edge_pull": dict(depth=0.014, lip=0.016),  # a recessed edge pull on the door, or on a drawer's top
    "pull_in": 0.014,  # a recessed pull's mounts in from the free edge
    # a drawer model's control strip: a display 40-200 mm from the left, 60 % of the strip's height;
    # keys from 230 mm; dials 30 mm from the right end, 20 mm apart, at most 40 % of the height less 4 mm;
    # a membrane keypad 120 mm wide; rect keys 1.8 x their height
    "strip_panel": {"display": (0.04, 0.2), "display_h": 0.3, "keys_from": 0.23, "end": 0.03, "dial_gap": 0.02,
                    "keys_gap": 0.01, "keys_margin": 0.02, "knob_share": 0.4, "membrane": 0.12, "rect_half": 0.9},
}

# A microwave's keypad column (Panasonic NN-SN686S, GE JES1657SRSS, Toshiba ML-EM34P owner's manuals:
# 3-6 rows of three keys; GE JES1072, Panasonic NN-ST66: two wide keys at the bottom): items top-down
# with 20 mm free above and below, 6-14 mm between them (at least 8 mm to fit), shrunk together by 5 %
# steps down to 50 % on a short panel (a 4th-6th key row only where it fits at 65 %).
MICROWAVE_KEYS = {
    "margin": 0.02, "gap": 0.008, "min_gap": 0.006, "max_gap": 0.014, "shrink": 0.95, "min_scale": 0.65,
    "min_scale_shrink": 0.5,
    "display": (0.022, 0.04), "display_share": 0.12, "display_w": 0.39,  # display height, half width / panel w
    "row_pitch": 1.7, "key_drop": 0.85, "keys_w": 0.82,  # x key height; keys span 82 % of the panel
    "key_wide": 1.8, "key_wider": 2.8, "round": 0.6, "key_gap": 0.005,  # rect key width / height (3 or 2 a row)
    "proud": 0.002, "proud_share": 0.3,  # a pressed key (1/8 of its height in) still stands proud
    "membrane": 0.3, "membrane_side": 0.12,  # a membrane keypad: share of the height, side margins / width
    "knob_share": 0.38, "dial_room": 0.012, "dial_shrink": (0.8, 0.95), "stem": 0.003, "stem_share": 0.2,
    "release": 0.022, "release_w": 0.62, "release_proud": 0.006,  # the door release button
}
