"""Pan: a frying pan or skillet with a long handle and an optional lid.

X is depth (the handle reaches toward +X, the front), Y is width, Z is up. The body is a
shallow hollow vessel (the ``pot`` builders: a bottom that follows the rounded corner, a
thin flared wall of revolution, a rolled rim), so the inside stays hollow for the
simulator. A non-stick pan has a dark coating: a separate thin disc on the floor, in its
own material slot. The long handle is its own part ``handle`` fixed to the body (pieces
named ``handle``; a separate link also keeps a pan without a lid an articulation): it
leaves the wall horizontally below the rim, out past the lid's edge, then rises; it may
end in a hanging hole (a ring of convex segments round an elliptic hole).

The optional lid is a dome (glass or the body's metal) with a band and a knob; it rests
2.5 mm above the rim on the lower stop of a prismatic joint along +Z (0..2 cm), so gravity
holds it there, and the handle stays below the rim out past its edge.

Finishes: stainless steel, enamelled cast iron (handle cast with the body) or non-stick
(coloured enamel outside, dark coating inside, plastic, wooden or matching handle).
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.categories.pot import GLASS, HANDLE_FAMILY, lid, long_handle, vessel
from infmob_usd.params import Choice, Float, Schema

GROWTH = Growth(
    pan=Rule(required=("body", "long_handle"), optional={"lid": 0.7}),
    long_handle=Rule(optional={"hole": 0.6}),
)

SCHEMA = Schema((
    Float("radius", "outer radius of the wall at the top", "m", 0.1, 0.16),
    Float("depth_ratio", "depth / radius", "", 0.3, 0.8, dist="loguniform"),
    Float("flare", "wall angle from vertical (capped: the wall flares out by <= 0.25 radius)", "rad", 0.2, 0.6),
    Float("corner", "bottom corner radius as a fraction of the depth (<= 0.15 radius)", "", 0.25, 0.5),
    Float("wall", "wall thickness", "m", 0.002, 0.0035),
    Float("bottom", "bottom thickness", "m", 0.003, 0.006),
    Float("bead", "rolled rim bead radius", "m", 0.0018, 0.0028),
    Float("handle_length", "handle length from the wall", "m", 0.16, 0.26),
    Float("handle_angle", "handle rise above horizontal", "rad", 0.08, 0.35),
    Float("handle_width", "handle width", "m", 0.022, 0.034),
    Float("handle_thickness", "handle thickness (capped by the depth)", "m", 0.011, 0.017),
    Float("dome", "lid dome height as a fraction of the radius", "", 0.08, 0.22),
    Float("lid_thickness", "lid wall thickness (glass lids are 1.6x thicker)", "m", 0.0012, 0.0022),
    Float("knob_radius", "lid knob radius", "m", 0.012, 0.02),
    Choice("finish", "pan material", choices=("steel", "cast_iron", "nonstick"), weights=(0.3, 0.2, 0.5)),
    Choice("handle_finish", "handle material (a cast iron handle always matches)",
           choices=("match", "plastic", "wood"), weights=(0.4, 0.4, 0.2)),
    Choice("lid_finish", "lid: glass or the body's material", choices=("glass", "match"), weights=(0.7, 0.3)),
    *GROWTH.flags(),
))

LIFT = 0.02  # m, lid lift
BODY_FAMILY = {"steel": "brushed_metal", "cast_iron": "enamel:black",
               "nonstick": "enamel:black|red|cobalt|green|cream"}
COATING = "plastic:black|dark_grey"


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    finish = p["finish"]
    match = finish == "cast_iron" or p["handle_finish"] == "match"
    bp = Blueprint("pan", materials={
        "body": BODY_FAMILY[finish], "rim": "brushed_metal", "glass": GLASS, "coating": COATING,
        "handle": HANDLE_FAMILY.get(p["handle_finish"], BODY_FAMILY[finish]),
        "knob": "plastic:black|dark_grey",
    })
    handle_slot = "body" if match else "handle"
    R = p["radius"]
    D = p["depth_ratio"] * R
    # a wide flat floor: the wall flares out by at most 0.25 R and the corner is at most
    # 0.15 R (a frying pan, not a wok)
    flare = min(p["flare"], math.atan(0.25 * R / D))
    pieces, info = vessel(R, D, min(p["corner"] * D, 0.15 * R), flare, p["wall"], p["bottom"], p["bead"],
                          "body", "body")
    if finish == "nonstick":
        pieces.append(g.disc((0, 0, info["floor"] + 0.0003), info["floor_radius"] - 0.001, 0.0006, "coating", 64))
    bp.add("body", "body", pieces)
    # the handle is its own part (fixed), so a pan without a lid is still an articulation
    bp.add("handle", "handle", long_handle(info, info["rim_outer"] + 0.006, p["handle_length"],
                                           p["handle_angle"], p["handle_width"], p["handle_thickness"],
                                           handle_slot, hole=p["has_hole"]))
    bp.join(J.fixed("body", "handle"))
    if p["has_lid"]:
        glass = p["lid_finish"] == "glass"
        t_lid = p["lid_thickness"] * (1.6 if glass else 1.0)
        lid_pieces, z0 = lid(info, p["dome"] * R, t_lid, "glass" if glass else "body", "rim", "knob", "knob",
                             p["knob_radius"])
        bp.add("lid", "lid", lid_pieces)
        bp.join(J.prismatic("body", "lid", (0.0, 0.0, z0), (0, 0, 1), 0.0, LIFT, role="lid"))
    return bp
