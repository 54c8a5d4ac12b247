"""Sizes and shares of storage racks, as data beside their sources.

``STORAGE_RACK_RANGES``: parameter name -> (low, high) in metres (counts unitless, fractions unitless);
``STORAGE_RACK_SHARES``: choice parameter -> weights of its choices, in the order the category lists them;
``STORAGE_RACK_DESIGNS``, ``TOTE_LIDS``, ``GOODS_KINDS``: the grammar's shares of its alternatives.
"""

from __future__ import annotations

STORAGE_RACK_RANGES = {
    # pallet racks: 1-2 bays, 3-5 beam levels, uprights 60-100 mm, beams 60-140 mm (the ranges this category has
    # always drawn; light-duty selective racks. Their product source is not recorded: to be sourced)
    "width": (1.5, 3.0), "depth": (0.6, 1.2), "level_height": (0.4, 1.8), "level_count": (3, 5),
    "bottom_height": (0.08, 0.3), "bay_count": (1, 2), "upright_size": (0.06, 0.1), "beam_height": (0.06, 0.14),
    "goods_chance": (0.5, 1.0), "goods_fill": (0.35, 0.7),
    # boltless shelving: 12-24 in deep, 5 shelves over 72 in (Tennsco Z-line; IKEA BROR 0.4-0.55 m)
    "shelf_depth": (0.35, 0.6), "shelf_spacing": (0.3, 0.45), "shelf_levels": (4, 6),
    # bin racks: AkroBins 30220-30240 are 4-1/8 to 5-1/2 in wide, 5 in high; shelf pitch 6-8 in; 72-84 in bin
    # shelving units carry up to 8 shelves of 5 in bins (Akro-Mils AWS / Edsal bin units)
    "bin_width": (0.105, 0.15), "bin_spacing": (0.18, 0.24), "bin_levels": (4, 8),
    # a tote or bin slides out until its middle reaches the deck's front edge at most
    "tote_travel": (0.3, 0.5),
}
STORAGE_RACK_SHARES = {"deck": (0.45, 0.3, 0.25), "frame_finish": (0.7, 0.3)}
GOODS_SHARE = 0.75  # racks whose levels may hold goods
STORAGE_RACK_DESIGNS = {"pallet_rack": 0.35, "shelving": 0.3, "bin_rack": 0.35}
TOTE_LIDS = {"lid": 0.7, "open_tote": 0.3}
GOODS_KINDS = {"boxes": 0.3, "pallet": 0.25, "crates": 0.2, "drawers": 0.25}
TWO_BAYS_OVER = 2.2  # a pallet rack wider than this has two bays (beams up to 2.2-2.7 m)
