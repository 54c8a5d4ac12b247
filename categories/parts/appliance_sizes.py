"""Named dimension tables of the appliances (microwave, dishwasher, beverage fridge, oven, TV).

Metres (or ratios, marked) of real products; each table names its source beside its figures. The
part builders (:mod:`.microwaves`, :mod:`.dishwashers`, :mod:`.fridges`, :mod:`.ovens`,
:mod:`.displays`) read their proportions from here, so a category module describes the object and
writes no bare number.
"""

from __future__ import annotations

import math

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

# The microwave's parameter ranges (min, max): the counter-top sizes above; casings modelled 3-6 mm (massed as
# sheet); doors 30-45 mm thick; dials 32-56 mm across, push keys 12-20 mm tall, rubber feet 6-15 mm (the
# spec sheets and owner's manuals named above and with MICROWAVE_KEYS); the rest are ratios of the body.
MICROWAVE_RANGES = {
    "width": (0.44, 0.62), "depth": (0.32, 0.46), "height": (0.25, 0.36), "panel_fraction": (0.2, 0.4),
    "wall": (0.003, 0.006), "door_thickness": (0.03, 0.045), "window_margin": (0.025, 0.055),
    "plate_fraction": (0.8, 0.95), "rack_height": (0.03, 0.09), "button_height": (0.012, 0.02),
    "knob_radius": (0.016, 0.028), "handle_length": (0.45, 0.8), "feet_height": (0.006, 0.015),
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

# -- dishwasher -------------------------------------------------------------------------------------
# Built-in dishwashers 0.45 / 0.6 m wide, 0.55-0.6 m deep, 0.82-0.87 m tall under the counter (Bosch
# 300/500 Series, Miele G 7000, Whirlpool WDT750 spec sheets).
DISHWASHER = {
    # a compact counter-top model 0.55 x 0.50 x 0.44 m (Midea MCDW6ASS, Farberware FDW05ASBWHA spec sheets):
    # (size at the parameter's low end, span, the parameter's low end, its span) per width, depth, height
    "compact": {"width": (0.5, 0.1, 0.44, 0.22), "depth": (0.46, 0.08, 0.52, 0.14),
                "height": (0.42, 0.05, 0.76, 0.16)},
    "compact_kick": 0.03,  # a compact model's door hinges 30 mm over its feet
    # a double dish drawer 0.6 x 0.57 x 0.82 m (Fisher & Paykel DD60DCX9): at least 0.6 m wide, at most 0.6
    # deep, 0.8-0.86 m tall
    "dish_drawer": {"width": 0.6, "depth": 0.6, "height": (0.8, 0.86)},
    "worktop": 0.02,  # a freestanding model's worktop
    "gap": 0.004,  # door to cabinet and plinth
    "rack_gap": 0.004,  # rack to rails, liner and neighbours
    "fascia": 0.012,  # control panel thickness (in front of the door)
    "handle_strip": 0.03,  # the lowest strip of a control panel carries the handle
    "handle_below": 0.035,  # a door handle's mounts under the band's bottom (or the door's top)
    "door_under_top": 0.002,  # the door's top under the cabinet's top
    "tub_over_hinge": 0.02,  # the tub's floor over the door's hinge line
    # the door's top band: 25 mm, plus the control panel and a 30 mm handle strip under it; 70 mm for a
    # handle alone
    "band": {"base": 0.025, "handle_strip": 0.03, "handle_only": 0.07},
    # racks stay 32 mm under the ceiling nozzle, 10 mm under the band; 12 mm over the flat door's
    # dispenser and 50 mm over the tub floor (the spray arm)
    "rack_room": {"nozzle": 0.032, "band": 0.01, "door": 0.012, "arm": 0.05},
    # machinery in the base: circulation pump with motor 3-4 kg, drain pump ~0.5 kg, sump and heater
    # (service-part listings, e.g. Bosch 00651956 circulation pump ~3.5 kg), a 60 mm can 40 mm behind the
    # base's middle, 6 mm clear of the base plate and the tub
    "pump_kg": 5.0,
    "pump": {"behind_centre": 0.04, "clear": 0.006, "radius": 0.06},
    "bar": dict(standoff=0.028, bar_radius=0.007, post_radius=0.0056, inset=0.02),  # a bar handle
    "pocket": dict(depth=0.016, lip=0.02),  # a pocket (edge) pull
    # an integrated model's shaker front: a 19 mm board, 70 mm rails 6 mm proud, 16 mm into the band
    "front": {"board": 0.019, "rail": 0.07, "rail_proud": 0.006, "under_band": 0.016},
    # the control fascia: 20 mm into the band, 4 mm under the door's top and inside its sides; a display over
    # 12-38 % of the width, 22 mm tall; keys over the right 45 %, at most 1.6 x as wide as tall, 8 mm
    # room above and below, 4 mm between; proud 30 % of their height + 2 mm; bevel 15 %
    "control": {"over_band": 0.02, "under_top": 0.004, "inset": 0.004, "display": ((0.12, 0.38), 0.011),
                "key_gap": 0.008, "key_wide": 1.6, "keys_w": 0.4, "key_space": 0.004, "keys_span": 0.45,
                "proud_share": 0.3, "proud": 0.002, "bevel": 0.15},
    # a double dish drawer: 12 mm cabinet panels, a plinth 4 mm sheet 12 mm behind the fronts; feet 15 mm
    # radius, 40 / 50 mm in from back / front, 40 mm in from the sides
    "drawer_panel": 0.012,
    "plinth": {"sheet": 0.004, "behind_door": 0.012},
    "feet": ((0.04, 0.05), 0.04, 0.015),
    # each drawer: a 1.5 mm skin on a 2 mm-sheet core, a tub 15 mm off the cabinet's back, 2 mm behind the
    # front, 6 mm inside the sides and over the bay's floor, 30 mm under the bay's top, 4 mm walls; the bar
    # handle 40 mm under its top; it slides out 85 % of the tub; its rack 10 mm inside the tub's ends, 4 mm
    # inside its sides, floor and 10 mm under its top
    "drawer": {"tub_back": 0.015, "tub_front": 0.002, "tub_side": 0.006, "tub_floor": 0.006, "tub_top": 0.03,
               "skin": 0.0015, "core": 0.002, "tub_wall": 0.004, "handle_below": 0.04, "travel": 0.85,
               "rack": {"ends": 0.01, "side": 0.004, "floor": 0.004, "top": 0.01}},
    # Rack heights as shares of the usable height, bottom up (a cutlery tray on top of three or more)
    "shares": {1: [1.0], 2: [1.25, 1.0], 3: [1.25, 1.0, 0.42], 4: [1.1, 0.85, 0.75, 0.4]},
    # racks 10 mm inside the tub's ends; a rack's top 6 mm under the next; rails 10 mm tall, 13 mm wide,
    # from 30 mm off the back to 4 mm inside the front; 30 mm kept free at the rack's front; a basket's or
    # tine row's rack is 20 mm inside the rails
    "racks": {"ends": 0.01, "under_next": 0.006, "rail": 0.01, "rail_in": 0.013, "rail_back": 0.03,
              "rail_front": 0.004, "front": 0.03, "half_in": 0.02},
    # fold-down tine rows (Bosch / Miele "flip tines", 2-4 per lower rack): at most 160 mm tall and 85 % of
    # the rack's height, 20 mm short of their strip, leaning 6 % of their height (8 mm room), 30 mm off the
    # rack's back, 10 mm inside its sides
    "tines": {"height": 0.16, "share": 0.85, "strip_room": 0.02, "lean": 0.06, "lean_room": 0.008, "back": 0.03,
              "side": 0.01},
    # flip-down cup shelves (Bosch, Whirlpool upper racks): at most 80 mm and 45 % of the rack's wall (70 % of
    # its height, at least 20 mm), 10 mm under its rim, 40 mm inside its ends, 15 mm in from its side, leaning
    # 6 mm; the tine rows keep 30 mm inside them
    "cup_shelf": {"height": 0.08, "share": 0.45, "wall_share": 0.7, "min_height": 0.02, "under_rim": 0.01,
                  "ends": 0.04, "wall_in": 0.015, "lean": 0.006, "tines_in": 0.03},
    # cutlery baskets: on the bottom grid (2.6 wire radii + 1 mm), 40-140 mm tall and 75 % of the rack, at most
    # 120 mm deep (35 % of the rack) and wide, 4 mm apart, 12 mm behind the rack's front, 20 mm of side room;
    # they lift 2 mm short of the rack above, a lift under 10 mm keeps them fixed
    "baskets": {"grid": 2.6, "over_grid": 0.001, "height": (0.04, 0.14, 0.75), "under_next": 0.002,
                "depth": 0.12, "depth_share": 0.35, "width": 0.12, "space": 0.004, "side_room": 0.02,
                "front_gap": 0.012, "min_lift": 0.01},
}

# The dishwasher's parameter ranges (min, max): built-in and compact models 0.44-0.66 m wide, 0.52-0.66 m
# deep, 0.76-0.92 m tall (the spec sheets named with DISHWASHER above); the rest are parts of the body, wire
# pitches and travels the layout checks.
DISHWASHER_RANGES = {
    "width": (0.44, 0.66), "depth": (0.52, 0.66), "height": (0.76, 0.92), "wall": (0.018, 0.03),
    "door_thickness": (0.045, 0.07), "kick_height": (0.08, 0.14), "feet_height": (0.01, 0.025),
    "rack_travel": (0.6, 0.8), "wire_pitch": (0.045, 0.07), "basket_lift": (0.03, 0.06),
    "handle_length": (0.35, 0.7), "control_height": (0.06, 0.1), "button_size": (0.012, 0.02),
}

# -- beverage fridge ------------------------------------------------------------------------------------
# Glass-door beverage coolers 0.45-0.7 m wide, 0.5-0.9 m tall (Newair, Whynter, Danby, Kalamera ranges);
# insulated walls of 0.8 mm sheet round a moulded liner (``appliance.insulated_cabinet``).
FRIDGE = {
    # wine and dual-zone coolers are undercounter height, 0.82-0.87 m (Liebherr UWTes 1672, Sub-Zero UW-24,
    # Bosch/Haier dual-zone spec sheets), over the height parameter's 0.5 + 0.4 m range:
    # (height at its low end, span, the parameter's low end, its span)
    "undercounter_height": (0.82, 0.05, 0.5, 0.4),
    "dual_zone_width": 0.6,  # a dual-zone cooler with two doors is at least 0.6 m wide
    # a wine cooler has 3 more racks (6-8 slide-out shelves), an undercounter fridge 2 fewer above its
    # crispers, a dual-zone cooler 1 fewer per zone
    "rack_extra": {"wine": 3, "undercounter": -2, "dual_zone": -1},
    "shelf_pitch": 0.08, "shelf_spare": 0.6,  # undercounter shelves at least 8 cm apart
    "gap": 0.004,  # door to cabinet, control strip and kick grille
    "rack_gap": 0.004,  # rack to rails, liner, back wall and neighbours
    "rack_front": 0.006,  # racks end this far behind the cabinet front
    "glass_grow": 0.003,  # a glass door's glass: the cavity opening grown by 3 mm
    "glass_margin": 0.02,  # door frame at least this wide above and below the glass
    "mullion": 0.03,  # between the zones of a dual-zone cooler
    "meeting_stile": 0.04,  # a dual-zone door's meeting stile past the mullion (it carries the handle)
    "meeting_gap": 0.006,  # between the two doors, past what their free edges swing
    "stile": 0.03,  # a door's free stile is at least this wide (the handle sits on it)
    # hermetic reciprocating compressors of small coolers weigh 5-8 kg (Embraco EMT/EMX, Secop TLS data
    # sheets); a 70 mm can 14 mm in front of the back, 4 mm over the base plate, 12 mm short of the grille's top
    "compressor_kg": 6.0,
    "compressor": {"radius": 0.07, "behind": 0.004, "clear": 0.01, "floor": 0.004, "room": 0.012},
    "bar": dict(standoff=0.03, bar_radius=0.007, post_radius=0.0056, inset=0.02),  # a bar handle
    "pull": (0.016, 0.02, 0.6),  # a recessed pull: depth, lip (at most this share of the stile)
    # a solid door: a steel pan over the front 60 % of its edges, a 3 mm moulded liner 1 mm inside it, a
    # gasket 1.5 mm thick 6 mm inside the edges round a 20 mm hole margin
    "solid_door": {"pan": 0.6, "liner": 0.003, "liner_in": 0.001, "gasket": 0.0015, "gasket_in": 0.006,
                   "gasket_hole": 0.02},
    # door bins (Danby DCR044A2, Midea WHS-87LB1): 75 mm deep, at most 70 mm tall, 3 mm walls, 3 mm off the
    # liner, 20 mm over the glass' bottom and 50 mm under its top, 40 mm between; 30 mm off the hinge side,
    # 20 mm past what the free side swings; they lift 40 mm off their hooks; shelves stay 12 mm behind them
    "bin": {"depth": 0.075, "height": 0.07, "wall": 0.003, "behind": 0.003, "bottom": 0.02, "top": 0.05,
            "spare": 0.04, "hinge_room": 0.03, "swing_room": 0.02, "lift": 0.04, "clear": 0.012},
    # crisper drawers: 140 mm tall, 4 mm over the floor and under their top, 30 mm under the shelves, 6 mm
    # apart and off the door's swing, a 12 mm front, 3 mm walls; they slide out 70 % of their depth
    "crisper": {"height": 0.14, "floor": 0.004, "over": 0.03, "side": 0.006, "front": 0.012, "under_top": 0.004,
                "wall": 0.003, "travel": 0.7},
    # freezer compartment (Danby DCR044A2, Midea WHS-87LB1 compact fridges): at most a fifth of the cavity, an
    # evaporator box of 3 mm sheet massed as 1.5 mm, a 6 mm flap 6 mm inside the sides and 4 mm under the top;
    # a finger lip 80 mm wide, 6 mm deep, 6-16 mm over the flap's bottom; shelves stay 12 mm under it
    "freezer": {"share": 0.2, "under": 0.012, "flap": 0.006, "flap_in": 0.006, "top": 0.004, "sheet": 0.003,
                "sheet_mass": 0.0015, "lip": ((0.006, 0.016), 0.04, 0.006)},
    # rack levels: n + 0.6 pitches over the cavity, the first at 0.8 of one; racks at most 30 mm tall and 20 mm
    # under the next, 6 mm off the open door, 18 mm inside the zone's sides, 4 mm under the glass; ledge rails
    # 8 mm tall, 8 mm under the rack's runners, 4 mm short of the cavity front, 2 mm past the rack
    "racks": {"spare": 0.6, "first": 0.8, "height": 0.03, "room": 0.02, "door": 0.006, "side": 0.018,
              "under_glass": 0.004, "rail": 0.008, "rail_in": 0.008, "rail_front": 0.004, "rail_past": 0.002},
    "wire_pitch": (0.028, 0.04),  # a wire rack's bottle cradles
    # a divider plate: 6 mm glass, a 16 mm trim from 30 mm to 10 mm behind the cavity front
    "divider": {"glass": 0.003, "trim": 0.008, "trim_x": (0.03, 0.01)},
}

# The oven's parameter ranges (min, max): ranges and built-in ovens 0.5-0.9 m wide, 0.55-0.7 m deep,
# 0.85-0.98 m to the cooktop or top (the spec sheets named with OVEN below); doors 40-60 mm; 32-52 mm knobs; the rest
# are ratios of the body or travels the layout checks.
OVEN_RANGES = {
    "width": (0.5, 0.9), "depth": (0.55, 0.7), "height": (0.85, 0.98), "panel_fraction": (0.2, 0.4),
    "door_thickness": (0.04, 0.06), "window_margin": (0.05, 0.09), "handle_length": (0.6, 0.9),
    "plinth_height": (0.03, 0.07), "drawer_height": (0.1, 0.16), "drawer_travel": (0.55, 0.75),
    "rack_travel": (0.5, 0.75), "knob_radius": (0.016, 0.026), "grate_play": (0.015, 0.04),
    "grate_lift": (0.06, 0.12), "lower_height": (0.34, 0.4), "warming_height": (0.13, 0.18),
}

# The beverage fridge's parameter ranges (min, max): glass-door coolers, undercounter fridges and wine
# coolers 0.45-0.7 m wide, 0.5-0.68 m deep, 0.5-0.9 m tall (the spec sheets named with FRIDGE above); walls
# 35-55 mm of foam; the rest are parts of the body and travels the layout checks.
FRIDGE_RANGES = {
    "width": (0.45, 0.7), "depth": (0.5, 0.68), "height": (0.5, 0.9), "wall": (0.035, 0.055),
    "door_thickness": (0.03, 0.045), "kick_height": (0.05, 0.1), "feet_height": (0.008, 0.02),
    "control_height": (0.035, 0.06), "handle_length": (0.35, 0.75), "rack_travel": (0.6, 0.85),
    "divider_height": (0.35, 0.65), "freezer_height": (0.09, 0.14),
}

# -- oven -------------------------------------------------------------------------------------------
# 30 in ranges 0.76 x 0.64-0.71 x 0.91-0.94 m, warming drawers 0.13-0.18 m high (GE JB735, Frigidaire
# FGEF3036 spec sheets); double wall ovens 1.24-1.31 m high (GE JKD5000, Bosch HBL8651UC installation
# guides); 0.8 mm steel sheet casings and doors (``appliance.oven_casing``).
OVEN = {
    "door_gap": 0.004,  # door <-> body front
    "door_side": 0.003,  # doors and drawer fronts inside the body's sides
    "handle": dict(standoff=0.04, bar_radius=0.01, post_radius=0.008, inset=0.02),  # the door's bar handle
    "handle_below": 0.045,  # the door handle's mounts under the door's top
    "handle_tube": 0.0012,  # the door handle is a tube (its wall)
    "handle_room": 0.014,  # the open door's handle hangs this far clear over the drawer bay
    "door_top_gap": 0.005,  # over the door's top, plus what its top back edge rises opening (~ft^2 / 2h)
    "door_rise": 0.3,  # h of that: the door's height
    "window": (1.2, 1.6),  # the door's frame under and over the window, x the window margin
    "range_door_top": 0.045,  # a range's door top under the cooktop
    "backguard": 0.06,  # depth of a range's control panel (backguard)
    "divider": 0.004,  # the casing's divider over the drawer bay
    # a double wall oven: a 16 mm trim band under the lower door, a 20 mm trim strip + 4 mm gap between the
    # ovens, a fascia 35 % of the panel fraction tall
    "lower_trim": 0.016, "mid_trim": 0.02, "mid_gap": 0.004, "double_panel": 0.35,
    # the cavity inside the casing panels: 40 mm room at the back, 30 mm at the sides, its floor over the
    # open door (15 mm over its thickness, at least 50 mm over the hinge), 50 mm under the door's top
    "cavity": {"back": 0.04, "side": 0.03, "over_door": 0.015, "floor": 0.05, "top": 0.05},
    "trim_line": ((0.03, 0.025), 0.3),  # a fixed drawer front's chrome line: z under its top, half width / W
    # a range's vent slot strip: 9 slots 8 mm wide, 2 mm proud, 4-10 mm in front of the backguard, 80 mm in
    # from the sides
    "vent": {"slots": 9, "ends": 0.08, "slot": ((0.004, 0.01), 0.004, 0.002)},
    # the burners' area: 12 mm (the vent strip) + 12 mm in front of the backguard, 15 mm behind the front,
    # 20 mm inside the sides
    "cooktop": {"vent": 0.012, "behind_vent": 0.012, "front": 0.015, "side": 0.02},
    # burners: at most 55 mm radius, 35 % of the cooktop's depth per burner, 22 mm inside their grate's
    # column; every other one 80 % of that
    "burners": {"radius": 0.055, "share": 0.35, "side": 0.022, "small": 0.8},
    "grate_gap": 0.02,  # between neighbouring grates
    "grate_side": 0.006,  # grate sideways play (+-), at most
    "grate_clear": 0.004,  # a grate's play stops this far short of its neighbour
    "grate_over": 0.002,  # grates stand this far over the cooktop
    # a storage drawer: its front 3 mm off the body, 2 mm over the plinth; a tray 15 mm off the back panel,
    # 4 mm inside the bay, 12 mm under its top; an edge pull over half the width, 16 mm deep with a 14 mm
    # lip, 22 mm under the top
    "drawer": {"front_gap": 0.003, "over_plinth": 0.002, "tray_back": 0.015, "in_bay": 0.004, "tray_under": 0.012,
               "pull": (0.016, 0.014, 0.5, 0.022)},
    # a warming drawer: a bar handle 10 mm over its middle, a marking strip 120 mm wide 14-20 mm over its bottom
    "warming": {"handle": dict(standoff=0.03, bar_radius=0.008, post_radius=0.0065, inset=0.02),
                "handle_over": 0.01, "mark": ((0.014, 0.02), 0.06)},
    # rail levels from 45 mm over the floor to 70 mm under the ceiling, rails 10 mm off the back and 4 mm
    # short of the front; racks 20 mm off the back, 35 mm behind the front, 4 mm inside the rails, on them
    "racks": {"bottom": 0.045, "top": 0.07, "rail_back": 0.01, "rail_front": 0.004, "back": 0.02, "front": 0.035,
              "side": 0.004, "over_rail": 0.002},
    # knobs: 30 mm margins at the panel's ends, at most 40 % of their pitch and 12 mm inside the panel's half
    # height; stems 3 mm or 20 % of the radius; a centre of at least 110 mm (28 mm a button) + 30 mm for the
    # display and the buttons
    "knobs": {"margin": 0.03, "share": 0.4, "rim": 0.012, "stem": 0.003, "stem_share": 0.2, "centre": 0.11,
              "per_button": 0.028, "centre_room": 0.03},
    # the centre: a display at most 30 mm (30 % of the panel) tall, 4 mm over the middle of a panel taller
    # than 100 mm; buttons at most 16 mm tall (22 %) and 20 mm wide, 8 mm under the display, 4 mm apart,
    # travel 3 mm or a quarter of their height, 2 mm proud when pressed
    "buttons": {"display": 0.03, "display_share": 0.3, "display_over": 0.004, "tall_panel": 0.1, "height": 0.016,
                "share": 0.22, "width": 0.02, "under_display": 0.008, "space": 0.004, "travel": 0.003,
                "proud": 0.002},
    "knob_turn": math.pi / 4,  # a revolute knob turns +-45 degrees
}
