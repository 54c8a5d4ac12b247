"""Dimension tables of the vessel designs beyond the plain one, so a category is more than one product:
liners, stoppers, clip-top and hinged jar lids, swing-top, pump and sports closures, steamer inserts,
pressure-cooker lids, folding and detachable pan handles. Metres (or ratios) of real products; each table
names its source."""

from __future__ import annotations

import math

# -- vase -------------------------------------------------------------------------------------
# A vase stands: its foot is at least 40 % of its widest diameter (a narrower one tips over; Kähler Omaggio, IKEA
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

# -- pan --------------------------------------------------------------------------------------
# Three handle designs: riveted (a fixed handle, always with a lid), folding (camping skillets:
# MSR Ceramic Skillet, GSI Bugaboo; the handle pivots at its top edge and folds up over the pan,
# 0..180 degrees mechanical), detachable (Tefal Ingenio: the handle slides off a lug on the
# wall, 0..6 cm, and has a thumb release slider, 0..8 mm).
PAN_HANDLES = {"riveted": 0.45, "folding": 0.25, "detachable": 0.3}
SPLIT_HANDLE = {"lug": 0.014, "gap": 0.002, "knee_room": 0.004, "fold": 3.1416,
                "pull": 0.06, "slider": (0.022, 0.5, 0.006), "slide": 0.008, "slider_gap": 0.0006,
                "slider_at": 0.22}
# a helper handle on big skillets (Lodge 12" cast iron): a short loop opposite the long handle
HELPER = {"length": 0.05, "radius": 0.005, "standoff": 0.022, "under_rim": 0.006, "p": 0.35}

# -- jar --------------------------------------------------------------------------------------
# The four closures jars are sold with: screw lid (mason jar), clip-top (Le Parfait / Bormioli Fido: a glass
# lid on an orange rubber gasket, hinged at the back on a neck wire, clamped by a wire lever at the
# front), hinged lid (a storage jar with a flat lid on a back hinge and a front knob), stopper (an
# apothecary jar's glass or wooden stopper). Wire 2..3 mm (Fido: 2.5 mm zinc-plated steel).
JAR_CLOSURES = {"screw": 0.35, "clip_top": 0.3, "hinged": 0.15, "stopper": 0.2}
CLIP_TOP = {"wire": 0.0013, "overhang": 0.003, "glass": 0.006, "gasket": (0.004, 0.0022), "ring_below": 0.004,
            "hinge_out": 0.0045, "knuckle": 0.008, "knuckle_gap": 0.0015, "lever_half": 0.7, "lever_out": 0.004,
            "bar_in": 0.006, "bar_up": 0.0025, "lid_open": 1.92, "lever_open": 2.0, "dome": 0.25}
# hinged storage lid: 8..12 mm flat lid (acrylic, bamboo), a front knob 8..10 mm
HINGED_JAR = {"thickness": 0.01, "knob": 0.009}
# apothecary stopper: flange 2.5 mm over the lip, plug 15..25 mm, tall dome with a ball finial
# (blown hollow, 4 mm walls: a solid one on an 86 mm mouth weighed 0.49 kg, jar seed 6)
JAR_STOPPER = {"overhang": 0.0025, "depth": (0.12, 0.015, 0.025), "flange": 0.006, "dome": 0.45,
               "knob": (0.35, 0.008, 0.014), "sheet": 0.004}

# -- bottle -----------------------------------------------------------------------------------
# Which closures a profile usually wears (drawn by `closure_draw` when cap=auto): beer crown or
# Grolsch-style swing-top; wine capsule or Stelvin screw cap; PET soda screw cap or push-pull
# sports cap (PCO 1881 sports closures); apothecary stopper or swing-top; a Boston-round
# dispenser bottle with a 24/410 lotion pump.
BOTTLE_CLOSURES = {
    "beer": {"crown": 0.6, "swing_top": 0.4},
    "bordeaux": {"capsule": 0.7, "screw": 0.3},
    "burgundy": {"screw": 0.5, "capsule": 0.5},
    "champagne": {"capsule": 1.0},
    "soda": {"screw": 0.55, "sports": 0.45},
    "vintage": {"stopper": 0.6, "swing_top": 0.4},
    "dispenser": {"pump": 1.0},
}
# the glass finish each new closure sits on (a swing-top stopper seals on a flared lip; pumps and
# sports caps screw onto a threaded finish)
CLOSURE_FINISH = {"swing_top": "stopper", "pump": "screw", "sports": "screw"}
# swing-top (Grolsch): a porcelain stopper 1 mm over the lip on a red rubber washer, a wire bail
# from its sides to a neck ring 12 mm under the lip; it tips back about its back edge (0..69 deg)
# and the bail swings back about the ring's clasp (0..80 deg); together (137 deg) the stopper hangs
# clear of the shoulder (bottle seed 53, vintage: 1.9 + 1.75 rad drove it into the glass)
SWING_TOP = {"overhang": 0.001, "height": 0.012, "dome": 0.006, "washer": 0.0018, "wire": 0.0012,
             "ring_below": 0.012, "tip": 1.2, "swing": 1.4, "porcelain": 0.003}
# lotion pump (24/410): collar 12 mm tall, stem 4 mm, actuator head 22 x 14 mm with a 20 mm nozzle;
# the head rises 12 mm when turned to unlock (up-lock pumps); the collar unscrews 1 cm
PUMP = {"collar": 0.012, "collar_t": 0.0016, "stem": 0.004, "head": (0.011, 0.014), "nozzle": (0.02, 0.0035),
        "rise": 0.012, "lock_h": 0.006}
# push-pull sports cap: spout 11 mm across rising 6 mm from a 30 mm cap
SPORTS = {"spout": 0.0055, "spout_h": 0.012, "pull": 0.006, "ring": 0.0015}

# -- pot --------------------------------------------------------------------------------------
# Three designs: a plain pot with a dome lid; a steamer pot (1..2 stacking steamer tiers, each
# 45..70 % of the radius tall with a nesting skirt 15 mm deep: WMF / Fissler steamer sets); a
# pressure cooker (Fissler Vitavit, WMF Perfect: a bayonet lid that turns 0..35 degrees to unlock
# and lifts, a pressure valve that turns (selector), a lock slider 5 mm).
POT_DESIGNS = {"plain": 0.45, "steamer": 0.35, "pressure": 0.2}  # steamer sets sell in 1-3 tier variants
# Tiers 1..2 (steamer sets are also sold with three tiers, but a chain of three stacked slides
# sags 1.1 mm at rest in MuJoCo, past the 1 mm rest check: effort.py's armature takes the joint's
# free inertia as its load, while a middle tier's stop carries the tiers and lid above it).
# A tier is pressed from thinner sheet than the pot's clad wall: 0.6-0.8 mm 18/10 steel, a tier of 20-28 cm
# weighing 0.4-1.0 kg (WMF, Fissler, Cuisinart steamer inserts); "sheet" is that gauge (at the clad 2-3 mm
# wall a tier would weigh 2-4 kg).
STEAMER = {"tiers": (1, 2), "height": (0.45, 0.7), "skirt": 0.015, "room": 0.004, "gap": 0.0025, "lift": 0.12,
           "handle": (0.05, 0.004, 0.014), "sheet": 0.0008}
# A pasta pot's straining insert (Cuisinart 77-412, All-Clad and WMF pasta pots: a deep steel
# basket hung in the pot, lifted out to drain): it stands on the rim with a collar 15-25 % of the
# pot's radius above it (its handles on the collar, the lid on top), reaching down to 65-80 % of
# the pot's inside depth but at most 20 cm (inserts of 8-12 qt pots), of 0.6 mm perforated sheet;
# it lifts out past the rim (its skirt + 5 cm). Chance in a plain pot.
PASTA = {"collar": (0.15, 0.25), "reach": (0.65, 0.8), "deepest": 0.2, "sheet": 0.0006, "clear": 0.05, "p": 0.3}
# A rotary steam vent on a pot lid: a steel disc 24-32 mm across with a grip tab, turned 0..90
# degrees to open its steam holes (the vented glass lids of Tefal, Lagostina and WMF pots);
# radius, thickness, tab height (m); at 55 % of the lid radius; the turn (rad).
VENT = {"radius": 0.013, "thickness": 0.0025, "tab": 0.006, "at": 0.55, "turn": math.pi / 2, "gap": 0.0006,
        "p": 0.5}
PRESSURE = {"turn": 0.61, "valve": (0.012, 0.016), "valve_at": 0.42, "lock": (0.018, 0.01, 0.007), "lock_at": 0.6,
            "lock_slide": 0.005, "gap": 0.0006}
