"""Dimension tables of the vessel designs added for variety (issue 14): liners, stoppers, clip-top
and hinged jar lids, swing-top, pump and sports closures, steamer inserts, pressure-cooker lids,
folding and detachable pan handles. Metres (or ratios) of real products; each table names its source.
"""

from __future__ import annotations

# -- vase -------------------------------------------------------------------------------------
# A vase stands: its foot is at least 40 % of its widest diameter (issue 13; Kähler Omaggio, IKEA
# Vilja and Chinese ginger jars measure 45..70 %). Foot rings of thrown stoneware are 4..8 mm tall,
# flaring 1..2 mm outward at the table.
VASE_STAND = 0.45  # smallest foot radius / widest radius
VASE_FOOT = {"height": 0.006, "gap": 0.0005, "width": 0.007, "width_ratio": 0.3, "flare": 0.0015}
# Which closures a shape usually wears (a weighted draw with `closure_draw`): narrow necks take a
# stopper, wide mouths a lift-off lid or a removable glass liner (florists' "vase liners", e.g.
# IKEA Beräkna inner glass; Ming-style ginger jars always have lids).
VASE_CLOSURES = {
    "amphora": {"lid": 0.6, "liner": 0.4},
    "ginger_jar": {"lid": 1.0},
    "bud_vase": {"stopper": 1.0},
    "cylinder": {"liner": 0.6, "lid": 0.4},
    "bottle_neck": {"stopper": 0.8, "liner": 0.2},
    "bowl": {"liner": 0.7, "lid": 0.3},
}
# vase stopper (a turned wood or glass stopper): flange 3 mm past the rim, plug 15..30 mm deep
VASE_STOPPER = {"overhang": 0.003, "depth": (0.08, 0.015, 0.03), "flange": 0.006, "dome": 0.6,
                "knob": (0.5, 0.006, 0.014)}
# removable liner: soda-lime glass 2.5 mm, hangs from a rolled flange 2 mm above the rim, reaches
# 55..85 % of the vase's depth; lifts out (its depth below the rim, at most 25 cm)
LINER = {"wall": 0.0025, "flange": 0.004, "flange_t": 0.003, "reach": (0.55, 0.85), "room": 0.003,
         "max_lift": 0.25, "floor_clear": 0.006}
