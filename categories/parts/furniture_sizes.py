"""Named dimension tables of the tables (cocktail and dining): clearances, board sizes, drawer and leaf
proportions, mechanism travel. Metres (or ratios) of real products; each entry names its source.

The layouts in ``categories/cocktail_table.py`` and ``categories/dining_table.py`` read these; the part
builders they call live in :mod:`.tables` and :mod:`.table_mechanisms`.
"""

from __future__ import annotations

import math

# -- cocktail table -------------------------------------------------------------------------------
COCKTAIL = {
    "seat": 0.003,  # a lift-top rests this far above the apron rim
    "inset_max": 0.2,  # leg inset as a fraction of the width at most
    "leg_counts": (3, 4),  # a round top stands on 3 or 4 legs, a square one on 4
    "sleeve_top": 0.7,  # telescopic sleeves end at this fraction of the apron's bottom height
    "tube_top": 0.55,  # a pedestal tube ends at this fraction of the top's underside height
    # a pedestal's tube keeps 8 cm over its base for the column at full lift, starts 2 mm into the base; the
    # column reaches 6 cm under the tube's top at full lift
    "pedestal_tube": (0.08, 0.002, 0.06),
    "plate": (0.35, 0.2),  # the top's mounting plate: a fraction of the width, at most 20 cm radius
    "post": 0.75,  # telescopic post radius as a fraction of the leg radius
    "stretcher_z": 0.06,
    # a telescopic stand keeps 10 cm of sleeve under the lowest post and 5 cm of post in the sleeve at full
    # lift; a shelf sits 4 cm under the sleeves' tops (6 cm under a lift-top's well)
    "sleeve_room": 0.1, "post_in": 0.05, "shelf_under": 0.04, "shelf_under_well": 0.06,
    "shelf_leg": 0.8,  # a shelf's notch round a leg, a fraction of the leg radius
    # lift-top: the well's floor board (12 mm) and the struts: 70 % of a round top's half width, 20 %
    # of it behind the centre (Wayfair / IKEA lift-top mechanisms sit under the back of the top)
    "well_floor": 0.012, "round_struts": 0.7, "struts_back": 0.2,
    "drawer_clear": 0.003,  # drawer fronts in their openings
    "clear": 0.003,  # the same, under the name the shared drawer builder reads
    "board": 0.018,  # apron board (tables.BOARD)
    "drawer_margin": 0.015,  # apron board above and below the openings
    "drawer_stile": 0.024,  # apron between neighbouring drawer openings
    # drawers a side by the top's width: one under 0.7 m, two under 0.9 m, else up to three (every front at least
    # ~0.25 m wide, as on IKEA HEMNES / LIATORP storage tables)
    "drawers_per_side": ((0.7, 1), (0.9, 2), (math.inf, 3)),
    "drawer_wide": 0.6,  # drawers are at most ~0.6 m wide (IKEA HEMNES / LIATORP coffee-table drawers 0.4-0.6 m)
    "drawer_depth": 0.45,  # coffee-table drawers run 0.3-0.45 m deep
    "drawer_reach": (0.45, 0.85),  # a drawer's depth as a fraction of the box: back to back, or one side
    "drawer_wall": 0.01,
    # a painted top thicker than 30 mm is a lightweight board (board-on-frame / honeycomb core between thin
    # faces), not solid MDF: IKEA LACK (50 mm board-on-frame, paper honeycomb; 90 x 55 cm table ~7 kg),
    # Egger Eurolight and similar honeycomb boards 200-350 kg/m3 (vs MDF ~750); the upper figure is used
    "hollow_top_from": 0.03, "hollow_top_density": 350.0,
    "drawer_pull": 0.75,  # a drawer pulls out this fraction of its depth
    "metal_drawer_sheet": 0.001,  # m: steel drawers are 0.8-1.2 mm folded sheet (as the dining table's)
    # handles: a knob (at most 15 mm radius, 25 mm proud) on a front under 30 cm, else a bar up to 14 cm
    "knob": (0.015, 0.025), "knob_under": 0.3, "bar": 0.14,
    "square_leg": 0.01,  # a storage table's square legs are this much stouter than the rails
    "caster_plate": (0.001, 0.008, 0.004),  # a caster's top plate: over the stem, its thickness, past the leg
    "shelf_low": (0.08, 0.03),  # a storage table's shelf: under the apron, over the caster plates
    "leaf_floor": 0.05,  # a hanging drop leaf keeps this far above the floor (or the casters)
    "leaf_gap_y": 0.003,  # a drop leaf's edge off the top's edge at its hinge
    "loper_room": 0.03,  # the apron stays this far inside a leaf's hinge line: a folded loper (20 mm board) lies there
    "loper": 0.2,  # swing-out bracket length at most
    "loper_reach": (0.8, 0.6),  # at most this fraction of the half box; it ends at 60 % of the leaf
    "outline": 192,  # samples of a top's outline
    "drawers_w": 0.75,  # storage coffee tables with drawers are 0.75-1.2 m across (IKEA HEMNES 0.9 m, LIATORP
    #                     0.93 m, Wayfair / West Elm drawer coffee tables 0.8-1.2 m): a smaller one is a side table
    "lift_top_t": 0.03,  # a lift-top is an 18-30 mm board: lift-top mechanisms carry 10-25 kg (hardware listings of
    #                      lift-top coffee-table hinges); a 45 mm solid 1 m top (33 kg) was heavier than any real lid
}
# A nest of tables (IKEA VITTSJÖ 0.46-0.6 m, West Elm / Wayfair nests 0.45-0.65 m): at most 0.7 m across and
# 0.6 m high, 22 mm legs, each table 12 mm under the one above it; tops of 8 mm toughened glass, else 18 mm
# boards; a lone nested table is 80 % of the outer one deep, two are 44 % each (from 2 cm off the centre); an
# inner table is 85 % as deep, 4 % further out; each slides out 95 % of its depth.
NEST = {
    "size": (0.7, 0.6),
    "leg": 0.011,  # leg half side
    "leg_room": 0.003,  # the outer table's legs are this much stouter
    "leg_in": 0.01,  # the outer legs this far in from the top's edge
    "rail": (0.008, 0.05),  # its side rails: half thickness, height
    "gap": 0.012,
    "side_clear": 0.02,  # a nested table keeps this far from the legs either side
    "top": {"glass": 0.008}, "top_board": 0.018,
    "depth": (0.8, 0.44), "x0": 0.02, "inner": (0.85, 0.04), "travel": 0.95,
}

# -- dining table ---------------------------------------------------------------------------------
DINING = {
    "seat": 0.003,  # top halves above the apron rim
    "split": 0.004,  # gap between the two halves at rest
    "board": 0.02,  # apron board thickness
    "clear": 0.003,  # drawer fronts in their openings, inner legs in their sleeves
    "leaf_t": 0.02,  # stored leaf thickness
    "leaf_gap_y": 0.003,  # a drop leaf's edge off the centre top at its rule joint
    "loper_room": 0.026,  # a drop-leaf table's apron keeps this far more inside the leaves (the folded lopers)
    "loper": 0.25,  # swing-out bracket length
    "loper_apron": 0.4,  # and at most this fraction of the apron's length
    "loper_reach": 0.8,  # swung out, it ends 80 % out under the leaf
    "two_lopers": 1.3,  # m of apron: a longer drop leaf rests on two lopers (long drop-leaf / harvest tables carry
    #                     each leaf on two swing brackets or gates; a Pembroke table's short leaf on one)
    "leveller": 0.015,  # levelling foot height under a leg (M8 furniture levellers: 10-20 mm)
    # a leveller's glide disc (at most 22 mm radius, 42 % of the leg, 9 mm high) on a 5 mm stem; a pedestal
    # glide is as under a 50 mm leg
    "glide": (0.022, 0.42, 0.009), "stem": 0.005, "pedestal_glide_leg": 0.05,
    "caster_plate": (0.004, 0.01),  # casters' top plates under the legs: thickness, wider than the leg
    "leaf_gap": 0.004,  # between the leaf and the halves above it (and between stacked leaves)
    "bearing": 0.01,  # a lazy susan's ball-bearing ring (10 mm high 6-12 in bearings)
    "susan_t": 0.02,  # the turntable's thickness
    "sleeve_wall": 0.004,
    "drawer_wall": 0.01,
    "oval_apron": 0.64,  # an oval top's apron spans this fraction of its length and width
    "margin": 0.012,  # apron board above and below a drawer opening
    "drawer_min": 0.06,  # the lowest drawer opening worth having
    "drawer_width": 0.5,  # the widest drawer
    # drawers in a long side: up to two, three on a table 1.9 m or longer (farmhouse and refectory tables carry
    # 2-3 apron drawers a side)
    "drawers_per_side": ((1.9, 2), (math.inf, 3)),
    "drawer_stile": (0.05, 0.1),  # apron kept between drawer openings: in an end board, in a long board
    "drawer_reach": (0.45, 0.8),  # a drawer's depth as a fraction of the apron: back to back, or one side
    "leaf_room": 0.006,  # drawers stay this far under the stored leaves
    "metal_drawer_sheet": 0.001,  # m: steel drawers are 0.8-1.2 mm folded sheet (a 50 cm drawer ~2-3 kg)
    "drawer_depth": 0.45,  # the deepest drawer
    # handles: a knob at most 16 mm radius (25 mm proud), a bar at most 16 cm
    "knob": (0.016, 0.025), "bar": 0.16,
    "sleeve_from": 0.45,  # adjustable legs: sleeves start at this fraction of the height
    "inner_at_rest": 0.12,  # an inner leg reaches this far up its sleeve at rest
    "inner_top": 0.03,  # and at full extension stays this far under the apron's top
    "pull": 0.75,  # a drawer pulls out this fraction of its depth
    "top_bevel": (0.2, 0.15),  # bevel / thickness of a whole top, of a drop-leaf table's centre
    "outline": 192,  # samples of a top's outline
    # a draw-leaf table: leaves 40-50 cm (each adds that much; IKEA BJURSTA, Ercol draw-leaf tables), at most a
    # third of the top, 5 mm in from its end and 1 cm from its sides, pulled out all but 3 cm; the top rests on
    # a bearer frame of 6 cm side rails and an 8 cm cross rail between them
    "draw_leaf": 0.5, "draw_leaf_share": 3, "draw_leaf_in": (0.005, 0.01), "draw_leaf_keep": 0.03,
    "bearer": (0.06, 0.04),
    "leaf_store": 0.01,  # stored extension leaves keep this far from the legs
}

# -- parameter ranges ----------------------------------------------------------------------------------
# Dining tables (metres unless a ratio): 0.70-0.80 m high, 0.9-1.2 m wide, 1.4-2.8 m long (4-10 seats),
# 25-45 mm tops, 8-14 cm aprons, 5-9 cm legs (furniture retailers' catalogues, BS EN 12521 / EN 1730 test
# sizes); drop leaves of 20-34 cm (Pembroke / drop-leaf tables); extension tables open 50-80 % of the apron's
# half length per side (Bassett, Ethan Allen, Pottery Barn extension tables); 50-70 cm lazy susans on a
# ball-bearing ring; 50-75 mm plate-caster wheels (John Boos work tables, industrial rolling tables);
# adjustable legs 3-10 cm of travel (telescopic table-leg hardware listings); 10-18 cm pedestal columns.
DINING_RANGES = {
    "length": (1.4, 2.8), "width": (0.9, 1.2), "height": (0.7, 0.8), "top_thickness": (0.025, 0.045),
    "end_overhang": (0.06, 0.25), "side_overhang": (0.05, 0.12), "apron_height": (0.08, 0.14),
    "leg_width": (0.05, 0.09), "leaf_fraction": (0.2, 0.28), "lopers_per_leaf": (1, 2),
    "extension_fraction": (0.25, 0.4), "drawer_count": (1, 3), "back_drawer_count": (1, 3), "end_drawers": (1, 2),
    "leaf_count": (1, 2), "lazy_susan_radius": (0.22, 0.3), "leg_travel": (0.03, 0.1),
    "wheel_radius": (0.025, 0.038), "pedestal_radius": (0.05, 0.09),
}
# How often each choice is drawn: the generator's mix over the kinds the retailers above sell (not market data).
DINING_SHARES = {
    "top_shape": (0.7, 0.3), "leg_style": (0.4, 0.35, 0.25), "drawer_sides": (0.4, 0.35, 0.25),
    "handle_style": (0.45, 0.35, 0.2), "top_finish": (0.75, 0.25), "frame_finish": (0.6, 0.25, 0.15),
    "wheel_finish": (0.4, 0.6),
}

# Coffee (cocktail) tables: 0.40-0.75 m high, 0.5-1.0 m across, 20-45 mm tops, 15-30 mm legs 5-12 cm in from
# the edge, 5-11 cm aprons (retailers' catalogues); lift-tops rise 12-25 cm, 30-80 % as far forward on a
# scissor mechanism, over a 13-20 cm well (Wayfair / IKEA lift-top mechanisms); drop-leaf coffee tables
# 15-30 cm leaves; 50-75 mm furniture casters; telescopic legs and gas-lift pedestals 6-18 cm of travel,
# a pedestal's base 30-42 % of the top, a 25-45 mm inner column (adjustable pedestal coffee tables).
COCKTAIL_RANGES = {
    "width": (0.5, 1.0), "height": (0.4, 0.75), "top_thickness": (0.02, 0.045), "bevel": (0.1, 0.4),
    "leg_count": (3, 4), "leg_radius": (0.015, 0.03), "leg_inset": (0.05, 0.12), "apron_height": (0.05, 0.11),
    "shelf_height": (0.12, 0.3), "lift_travel": (0.12, 0.25), "lift_forward_ratio": (0.3, 0.8),
    "box_depth": (0.13, 0.2), "drawer_count": (1, 3), "back_drawer_count": (1, 3), "leaf_width": (0.15, 0.3),
    "caster_radius": (0.025, 0.0375), "stand_travel": (0.06, 0.18), "base_radius": (0.3, 0.42),
    "column_radius": (0.025, 0.045),
}
COCKTAIL_SHARES = {
    "leg_style": (0.28, 0.32, 0.2, 0.12, 0.08), "top_finish": (0.55, 0.25, 0.2), "frame_finish": (0.5, 0.3, 0.2),
}
