"""Named dimension tables of vessels (vase, bottle, jar, pot, pan): ranges, shapes, finishes.

Every figure is metres (or a ratio) of real products; where a table comes from a
standard or a catalogue the comment says which. Categories take their parameter
ranges from here (``Float(name, doc, unit, *VASE["height"])``) and the part
builders in :mod:`.vessel` their proportions, so neither writes a bare number.
"""

from __future__ import annotations

# -- vase -------------------------------------------------------------------------------------
# Parameter ranges: table vases 20..45 cm tall (IKEA / Kähler catalogue heights), glazed
# stoneware walls 3..6 mm; a lid's flange overhangs the rim by 2..10 mm.
VASE = {
    "height": (0.2, 0.45),
    "diameter_ratio": (0.2, 0.4),
    "wall": (0.003, 0.006),
    "shape_jitter": (0.0, 0.08),
    "lid_overhang": (0.002, 0.01),
    "lid_dome": (0.05, 0.45),
    "finish_weights": (0.55, 0.3, 0.15),  # ceramic, glass, enamel
}
VASE_LIFT = 0.05  # lid lift, m
VASE_NECK_ROOM = 0.012  # smallest inner radius of a vase mouth (a hand-thrown neck), m
VASE_SPLINE = (72, 12)  # fine samples, collision bands

# outside profiles as (radius / largest radius, z / height), bottom to top (classic forms)
VASE_SHAPES = {
    "amphora": [(0.45, 0.0), (0.5, 0.03), (0.8, 0.2), (1.0, 0.45), (0.9, 0.62), (0.55, 0.78),
                (0.42, 0.88), (0.45, 0.96), (0.55, 1.0)],
    "ginger_jar": [(0.6, 0.0), (0.66, 0.02), (0.9, 0.2), (1.0, 0.45), (0.95, 0.68), (0.72, 0.85),
                   (0.56, 0.9), (0.53, 0.94), (0.54, 1.0)],
    "bud_vase": [(0.7, 0.0), (0.8, 0.05), (1.0, 0.2), (0.85, 0.35), (0.42, 0.52), (0.32, 0.75),
                 (0.33, 0.94), (0.42, 1.0)],
    "cylinder": [(0.9, 0.0), (0.94, 0.02), (0.96, 0.5), (1.0, 0.97), (1.0, 1.0)],
    "bottle_neck": [(0.65, 0.0), (0.76, 0.03), (1.0, 0.2), (0.95, 0.4), (0.5, 0.58), (0.31, 0.7),
                    (0.29, 0.9), (0.35, 1.0)],
    "bowl": [(0.35, 0.0), (0.4, 0.04), (0.46, 0.2), (0.6, 0.5), (0.85, 0.8), (1.0, 1.0)],
}
ENAMEL_SHEET = 0.001  # enamelled sheet steel, m: a vase or lid of it weighs as a 1 mm sheet

# foot ring glued under a vase: 2.5 mm tall, 0.5 mm under the bottom, at most 6 mm wide
FOOT = {"height": 0.0025, "gap": 0.0005, "width": 0.006, "width_ratio": 0.4, "inset": 0.4}

# lift-off lid of a vase (flange, dome, finial, plug): proportions of the flange radius
LIFT_OFF_LID = {
    "flange": (0.04, 0.004, 0.005, 0.01),  # thickness = a * r + b, clipped to [lo, hi]
    "plug_depth": (0.08, 0.012, 0.03),  # fraction of the vase height, clipped to [lo, hi]
    "knob": (0.18, 0.006, 0.014),  # finial radius / flange radius, clipped
    "plug_room": 0.002,  # the plug's free radius is taken this far below its tip
}

# -- bottle -----------------------------------------------------------------------------------
# Heights 15..35 cm: a 330 ml long-neck is 23 cm, a 750 ml Bordeaux 30 cm, a champagne 30 cm;
# soda-lime glass walls 2..3.5 mm (Verallia catalogue).
BOTTLE = {
    "height": (0.15, 0.35),
    "width_ratio": (0.85, 1.15),
    "wall": (0.002, 0.0035),
    "label_fill": (0.55, 0.95),
    "label_offset": (0.2, 0.8),
}
BOTTLE_CAP_TRAVEL = 0.01  # unscrew lift, m
BOTTLE_NECK_ROOM = 0.006  # smallest inner neck radius beyond the wall (a cork's bore), m
BOTTLE_SPLINE = (96, 14)

# per profile: body radius / height, neck radius / body radius, usual closure, glass colours,
# punt depth / height, label zone (z / height). Proportions of the classic bottles (beer
# long-neck, Bordeaux, Burgundy, champagne, PET soda, apothecary).
BOTTLE_KINDS = {
    "beer": (0.135, 0.42, "crown", "glass:amber|bottle_green|clear", 0.0, (0.1, 0.52)),
    "bordeaux": (0.122, 0.40, "capsule", "glass:bottle_green|amber|clear", 0.05, (0.16, 0.6)),
    "burgundy": (0.135, 0.38, "screw", "glass:bottle_green|amber", 0.05, (0.14, 0.46)),
    "champagne": (0.15, 0.34, "capsule", "glass:bottle_green", 0.1, (0.14, 0.44)),
    "soda": (0.155, 0.40, "screw", "glass:clear|clear_blue", 0.0, (0.38, 0.56)),
    "vintage": (0.25, 0.36, "stopper", "glass:clear|clear_blue|bottle_blue|amber", 0.0, (0.18, 0.62)),
    # a Boston round (soap / lotion dispenser, 250..500 ml): amber or clear glass, short neck
    "dispenser": (0.2, 0.3, "pump", "glass:amber|clear|bottle_green", 0.0, (0.12, 0.62)),
}
BOTTLE_WEIGHTS = {"beer": 1.0, "bordeaux": 1.0, "burgundy": 0.8, "champagne": 0.8, "soda": 1.0, "vintage": 0.7,
                  "dispenser": 0.8}

# body outlines as (radius / body radius, z / height) up to the neck (the finish is added on top)
BOTTLE_BODIES = {
    "beer": [(0.93, 0.0), (0.985, 0.008), (1.0, 0.03), (1.0, 0.55), (0.95, 0.61), (0.78, 0.68),
             (0.6, 0.75), (None, 0.83)],
    "bordeaux": [(0.95, 0.0), (0.99, 0.01), (1.0, 0.03), (1.0, 0.64), (0.94, 0.69), (0.66, 0.735),
                 (0.5, 0.77), (None, 0.85)],
    "burgundy": [(0.95, 0.0), (0.99, 0.01), (1.0, 0.03), (1.0, 0.48), (0.93, 0.57), (0.72, 0.67),
                 (0.52, 0.76), (None, 0.86)],
    "champagne": [(0.94, 0.0), (0.99, 0.012), (1.0, 0.04), (1.0, 0.46), (0.92, 0.56), (0.7, 0.66),
                  (0.5, 0.75), (None, 0.84)],
    "soda": [(0.86, 0.0), (0.97, 0.02), (1.0, 0.06), (1.0, 0.3), (0.92, 0.37), (0.92, 0.57),
             (1.0, 0.63), (0.97, 0.68), (0.72, 0.77), (None, 0.86)],
    "vintage": [(0.95, 0.0), (0.99, 0.01), (1.0, 0.03), (1.0, 0.7), (0.93, 0.77), (0.6, 0.835),
                (None, 0.87)],
    "dispenser": [(0.95, 0.0), (0.99, 0.01), (1.0, 0.03), (1.0, 0.7), (0.9, 0.8), (0.55, 0.86),
                  (None, 0.9)],
}
NECK_TAPER = 1.02  # the neck widens this much toward the shoulder
NECK_FINISH_ROOM = 0.004  # the shoulder ends at least this far below the finish, m

# glass finishes (the top of the neck): (dr, dz) from the neck top (neck radius, H - finish
# height) to the lip. Crown: CETIE GME 13.01 (26 mm crown finish, 18 mm tall); screw: PCO 1881
# (28 mm PET finish with support ring and 2.5 thread turns, 22 mm tall); capsule: a wine cork
# finish; stopper: a flared apothecary lip.
FINISHES = {
    "crown": [(0.0, 0.0), (0.0013, 0.003), (0.0013, 0.0045), (0.0003, 0.0065), (0.0003, 0.0085),
              (0.0019, 0.011), (0.0019, 0.0158), (0.0011, 0.018)],
    "screw": [(0.0, 0.0), (0.0, 0.002), (0.004, 0.003), (0.004, 0.0048), (0.0005, 0.0055),
              (0.0005, 0.008), (0.0016, 0.0095), (0.0005, 0.011), (0.0016, 0.0135), (0.0005, 0.015),
              (0.0016, 0.0175), (0.0005, 0.019), (0.0005, 0.021), (0.0, 0.022)],
    "capsule": [(0.0, 0.0), (0.0008, 0.004), (0.0013, 0.008), (0.0013, 0.0105), (0.0006, 0.012)],
    "stopper": [(0.0, 0.0), (0.001, 0.006), (0.0035, 0.011), (0.0042, 0.013), (0.0038, 0.015)],
}
CAP_MATERIALS = {
    "crown": "chrome",
    "screw": "plastic:white|red|blue|green|orange|black|teal",
    "capsule": "plastic:red|black|dark_grey|green|yellow|blue",
    "stopper": "wood",
}
# sleeve closures: where the skirt starts above the finish bottom (dz), skirt and top plate
# thickness, how far the top plate overhangs the skirt (a crown's top is flush with its
# crimped skirt, 32 mm across a 26 mm finish; a PCO screw cap's top is flush with its
# knurled skirt: no cap is wider than its finish plus skirt), sheet (crown: 0.3 mm tinplate)
SLEEVE_CAPS = {
    "crown": {"skirt_from": 0.0105, "skirt": 0.0012, "top": 0.0025, "overhang": 0.0004, "sheet": 0.0003},
    "screw": {"skirt_from": 0.0065, "skirt": 0.0016, "top": 0.003, "overhang": 0.0004, "sheet": 0.0},
    "capsule": {"skirt": 0.001, "top": 0.003, "overhang": 0.0003, "sheet": 0.0},
}
CROWN_FLUTES = 21  # a crown cap has 21 crimps (ISO 12821)
CROWN_FLARE = [(0.0012, 0.0), (0.0004, 0.002), (0.0, 0.0035)]  # (dr, dz) of the crimped skirt edge
# foil capsule length for a 30 cm bottle (longer on champagne), and its deepest reach below the finish
CAPSULE = {"length": 0.045, "champagne": 0.09, "per_height": 0.3, "below_finish": 0.02}
# the mushroom cork head of champagne over the foil: (r / cap radius, dz), cap radius + 2 mm
MUSHROOM = {"grow": 0.002, "profile": [(0.0, -0.0015), (0.8, -0.0015), (1.0, 0.004), (0.95, 0.011),
                                       (0.6, 0.015), (0.0, 0.016)]}
# glass stopper / cork of an apothecary bottle: flange 2 mm over the lip, 12 mm plug, 5 mm flange
STOPPER = {"overhang": 0.002, "depth": 0.012, "flange": 0.005, "dome": 0.35, "knob": (0.45, 0.006, 0.012)}
BOTTLE_BOTTOM = {"thickness": 1.8, "inset": 0.3}  # x wall
# push-up punt (wine, champagne) as (r / bottom radius, z / punt height) over a flat collision disc
PUNT = [(0.0, 1.0), (0.35, 0.8), (0.6, 0.45), (0.78, 0.12), (0.86, 0.0)]  # the outside (under) face
PUNT_TOP = [(0.8, 0.12), (0.62, 0.45), (0.36, 0.8)]  # the inside face, above the bottom's thickness
# paper label band: 0.8 mm visual wall, 2 mm collision ring, 0.2 mm paper; clearance 2.5 % of its height
# a bottle label: printed paper (0.2 mm of steel-equivalent sheet) glued on the glass, 0.2 mm of glue film
LABEL = {"thickness": 0.0008, "collision": 0.002, "paper": 0.0002, "glue": 0.0002, "sectors": 16}

# -- jar --------------------------------------------------------------------------------------
# Mason / storage jars 10..25 cm tall, 3..8 cm body radius; 70 mm (regular) and 86 mm (wide)
# mouth caps (GPI 70-450 / 86-450 finishes), necks 12..20 mm tall, lids 10..20 mm.
JAR = {
    "height": (0.1, 0.25),
    "radius": (0.03, 0.08),
    "wall": (0.0025, 0.005),
    "neck_ratio": (0.68, 0.9),
    "shoulder": (0.06, 0.2),
    "neck_height": (0.012, 0.02),
    "lid_height": (0.01, 0.02),
    "sides_weights": (0.5, 0.25, 0.25),  # round, square, hexagonal
    "body_weights": (0.7, 0.3),  # glass, ceramic
    "lid_weights": (0.35, 0.2, 0.3, 0.15),  # brushed_metal, chrome, plastic, painted
}
JAR_LIFT = 0.05
JAR_NECK_ROOM = 0.015  # smallest neck radius beyond the wall, m
JAR_SPLINE = (96, 16)
JAR_NECK_SPLINE = (48, 10)
THREAD = 0.0014  # thread ring height above the neck (GPI continuous thread), m
# round jar body outline under the shoulder: (radius / R, z) near the bottom (z in metres)
JAR_FOOT = [(0.93, 0.0), (0.985, 0.004), (1.0, 0.012)]
POLY_FOOT = [(0.96, 0.0), (0.99, 0.003), (1.0, 0.008)]
POLY_SHOULDER = 0.003  # flat shoulder plate thickness (at least), m
BOTTOM_RATIO = 1.6  # bottom disc thickness / wall
JAR_LID = {"skirt_metal": 0.0012, "skirt_plastic": 0.002, "top": 0.003, "overhang": 0.0015,
           "button": 0.7, "button_height": 0.0015, "sheet": 0.0005, "reach": 0.1}
JAR_LID_FAMILY = {"brushed_metal": "brushed_metal", "chrome": "chrome",
                  "plastic": "plastic:white|black|red|blue|green|light_grey",
                  "painted": "painted:white|off_white|black|navy|sage|charcoal"}

# -- pot --------------------------------------------------------------------------------------
# Saucepans (16 cm) to stock pots (36 cm): outer radius 8..18 cm; 18/10 steel walls 1.5..3 mm
# on 3..7 mm clad bases (WMF / Fissler catalogue figures); long handles 14..24 cm.
POT = {
    "radius": (0.08, 0.18),
    "depth_ratio": (0.6, 2.0),
    "flare": (0.0, 0.1),
    "corner": (0.08, 0.2),
    "wall": (0.0015, 0.003),
    "bottom": (0.003, 0.007),
    "bead": (0.0018, 0.003),
    "dome": (0.08, 0.25),
    "lid_thickness": (0.0012, 0.0025),
    "handle_length": (0.14, 0.24),
    "handle_angle": (0.05, 0.4),
    "handle_width": (0.018, 0.03),
    "handle_thickness": (0.01, 0.016),
    "side_handle_length": (0.06, 0.12),
    "side_handle_radius": (0.0035, 0.0065),
    "side_handle_reach": (0.018, 0.03),
    "knob_radius": (0.012, 0.022),
    "layout_weights": (0.6, 0.4),  # side handles, long handle
    "lid_handle_weights": (0.7, 0.3),  # knob, loop
    "body_weights": (0.5, 0.3, 0.2),  # brushed_metal, enamel, chrome
    "lid_weights": (0.55, 0.45),  # match, glass
    "handle_weights": (0.5, 0.35, 0.15),  # match, plastic, wood
}
POT_LIFT = 0.03
GLASS_LID_THICKER = 1.6  # tempered glass lids are thicker than steel ones
POT_RIM = {"brushed_metal": "brushed_metal", "enamel": "brushed_metal", "chrome": "chrome"}
HANDLE_FAMILY = {"match": "plastic:black|dark_grey", "plastic": "plastic:black|dark_grey", "wood": "wood"}
GLASS = "glass:clear|clear_blue"

# -- pan --------------------------------------------------------------------------------------
# Frying pans 20..32 cm across (outer radius 10..16 cm), 3..8 cm deep; handles 16..26 cm.
PAN = {
    "radius": (0.1, 0.16),
    "depth_ratio": (0.3, 0.8),
    "flare": (0.2, 0.6),
    "corner": (0.25, 0.5),
    "wall": (0.002, 0.0035),
    "bottom": (0.003, 0.006),
    "bead": (0.0018, 0.0028),
    "handle_length": (0.16, 0.26),
    "handle_angle": (0.08, 0.35),
    "handle_width": (0.022, 0.034),
    "handle_thickness": (0.011, 0.017),
    "dome": (0.08, 0.22),
    "lid_thickness": (0.0012, 0.0022),
    "knob_radius": (0.012, 0.02),
    "finish_weights": (0.3, 0.2, 0.5),  # steel, cast_iron, nonstick
    "handle_weights": (0.4, 0.4, 0.2),  # match, plastic, wood
    "lid_weights": (0.7, 0.3),  # glass, match
}
PAN_LIFT = 0.02
PAN_FLAT = {"flare_reach": 0.25, "corner": 0.15}  # a frying pan, not a wok: flare and corner / radius
PAN_FAMILY = {"steel": "brushed_metal", "cast_iron": "cast_iron", "nonstick": "enamel:black|red|cobalt|green|cream"}
COATING = "plastic:black|dark_grey"
KNOB = "plastic:black|dark_grey"

# -- cookware parts (pot and pan) ----------------------------------------------------------------
LID_GAP = 0.0025  # a cookware lid rests this far above the rim on its lower stop, m
LID_RIM_REACH = 0.004  # the dome reaches past the bead, m
LID_BAND = {"out": 0.0015, "height": 0.003, "thickness": 0.0035, "sectors": 24}
LID_LOOP = {"reach": 0.7, "min": 0.06, "per_knob": 5.0, "radius": 0.0045, "post": 0.0035, "rise": 0.022,
            "inset": 0.008, "sink": 0.002}
HANDLE_RIM_CLEAR = 0.003  # a handle's top stays this far under the bead, m
HANDLE_KNEE = 0.012  # a long handle runs horizontal this far past what it must clear, m
SIDE_HANDLE = {"under_rim": 0.006, "inset": (0.02, 0.15), "into_wall": 0.6}
LONG_HANDLE = {"clear": 0.002, "min_rest": 0.03, "widen": 0.6, "tip": 0.42,
               "cap": (0.004, 0.8, 0.32), "depth_share": 0.8, "root_in": 0.7}
HANGING_RING = {"ring": (0.006, 0.25), "hole": (1.8, 0.012), "segments": 14}
