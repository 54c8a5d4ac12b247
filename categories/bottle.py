"""Bottle: a hollow glass bottle with a cap that unscrews and an optional label band.

The body is a thin glass wall of revolution (``g.shell``) whose outside follows a smooth
spline through many control points of one of six recognisable profiles, closed by a
bottom (a push-up punt for wine and champagne):

* ``beer``: long-neck, straight body, rounded shoulder, long neck, crown finish;
* ``bordeaux``: straight body, high abrupt shoulder;
* ``burgundy``: wider body, long sloping shoulder;
* ``champagne``: heavy, sloping shoulder, deep punt, foil capsule and mushroom cork;
* ``soda``: PET bottle with a waist, support ring and screw threads;
* ``vintage``: apothecary bottle, wide body, short neck with a flared lip and a stopper.

The cap (crown, screw cap, foil capsule or stopper, chosen by the profile unless ``cap``
says otherwise) sits on the lip with clearance all round (a sleeve cap's skirt is drawn
but collides through its top plate only: see :func:`.vase.sleeve` for the PhysX reason); it turns freely about Z and
lifts 0..1 cm along +Z (unscrewing), resting at 0 (gravity holds it on its seat). The
label is a thin band around the straight part of the body, a separate part that turns
about Z (its centre of mass is on the axis) with clearance from the glass.

Profile helpers are shared with ``vase`` and ``jar`` (they live in :mod:`.vase`).
"""

from __future__ import annotations

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

from .vase import SECTIONS, lid_gap, outer_radius, plug_lid, sleeve, spline_profile, vessel_wall
from .vase import free_radius as _free_radius

GROWTH = Growth(
    bottle=Rule(required=("body", "cap"), optional={"label": 0.8},
                one_of={"beer": 1.0, "bordeaux": 1.0, "burgundy": 0.8, "champagne": 0.8, "soda": 1.0,
                        "vintage": 0.7}),
    cap=Rule(one_of={"crown": 1.0, "screw": 1.0, "capsule": 1.0, "stopper": 1.0}),
)
"""``bottle.one_of`` is the ``profile`` parameter; ``cap.one_of`` follows the profile
(``cap=auto``) unless the ``cap`` parameter names one."""

_PROFILES = GROWTH.rules["bottle"].one_of

SCHEMA = Schema((
    Float("height", "overall height of the glass", "m", 0.15, 0.35),
    Choice("profile", "bottle type", choices=tuple(_PROFILES), weights=tuple(_PROFILES.values())),
    Float("width_ratio", "body radius / the profile's usual radius", "", 0.85, 1.15),
    Float("wall", "glass wall thickness", "m", 0.002, 0.0035),
    Choice("cap", "closure; auto = the usual one for the profile",
           choices=("auto", *GROWTH.rules["cap"].one_of), weights=(1.0, 0.0, 0.0, 0.0, 0.0)),
    Float("label_fill", "label height / the straight part of the body", "", 0.55, 0.95),
    Float("label_offset", "label position within the straight part (0 bottom, 1 top)", "", 0.2, 0.8),
    *GROWTH.flags(),
))

CAP_TRAVEL = 0.01  # m, unscrew lift

# per profile: body radius / height, neck radius / body radius, usual cap, glass colours,
# punt depth / height, label zone (z / height)
KINDS = {
    "beer": (0.135, 0.42, "crown", "glass:amber|bottle_green|clear", 0.0, (0.1, 0.52)),
    "bordeaux": (0.122, 0.40, "capsule", "glass:bottle_green|amber|clear", 0.05, (0.16, 0.6)),
    "burgundy": (0.135, 0.38, "screw", "glass:bottle_green|amber", 0.05, (0.14, 0.46)),
    "champagne": (0.15, 0.34, "capsule", "glass:bottle_green", 0.1, (0.14, 0.44)),
    "soda": (0.155, 0.40, "screw", "glass:clear|clear_blue", 0.0, (0.38, 0.56)),
    "vintage": (0.25, 0.36, "stopper", "glass:clear|clear_blue|bottle_blue|amber", 0.0, (0.18, 0.62)),
}

# body outlines as (radius / body radius, z / height) up to the neck (the finish is added on top)
BODIES = {
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
}

# finishes: (dr, dz) from the neck top (neck radius, H - finish height) to the lip
FINISHES = {
    "crown": [(0.0, 0.0), (0.0013, 0.003), (0.0013, 0.0045), (0.0003, 0.0065), (0.0003, 0.0085),
              (0.0019, 0.011), (0.0019, 0.0158), (0.0011, 0.018)],
    "screw": [(0.0, 0.0), (0.0, 0.002), (0.004, 0.003), (0.004, 0.0048), (0.0005, 0.0055),
              (0.0005, 0.008), (0.0016, 0.0095), (0.0005, 0.011), (0.0016, 0.0135), (0.0005, 0.015),
              (0.0016, 0.0175), (0.0005, 0.019), (0.0005, 0.021), (0.0, 0.022)],
    "capsule": [(0.0, 0.0), (0.0008, 0.004), (0.0013, 0.008), (0.0013, 0.0105), (0.0006, 0.012)],
    "stopper": [(0.0, 0.0), (0.001, 0.006), (0.0035, 0.011), (0.0042, 0.013), (0.0038, 0.015)],
}
SKIRT_FROM = {"crown": 0.0105, "screw": 0.0065}  # where a sleeve cap's skirt starts (dz)

CAP_MATERIALS = {
    "crown": "chrome",
    "screw": "plastic:white|red|blue|green|orange|black|teal",
    "capsule": "plastic:red|black|dark_grey|green|yellow|blue",
    "stopper": "wood",
}


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    kind = p["profile"]
    ratio, neck_f, cap_default, glass, punt, zone = KINDS[kind]
    cap = cap_default if p["cap"] == "auto" else p["cap"]
    bp = Blueprint("bottle", materials={"glass": glass, "cap": CAP_MATERIALS[cap],
                                        "cork": "wood", "label": "painted:white|off_white|pastel_yellow|"
                                        "pastel_blue|black|navy|sage"})
    H = p["height"]
    R = ratio * H * p["width_ratio"]
    t = p["wall"]
    n = max(neck_f * R, t + 0.006)
    fin = np.asarray(FINISHES[cap], float)
    hf = float(fin[-1, 1])
    z_n = H - hf
    ctrl = []
    for f, u in BODIES[kind]:
        r = n if f is None else f * R
        ctrl.append((r, min(u * H, z_n - 0.004) if f is None else u * H))
    ctrl[-1] = (ctrl[-1][0] * 1.02, ctrl[-1][1])  # a hint of taper up the neck
    ctrl += [(n + dr, z_n + dz) for dr, dz in fin]
    fine, coarse = spline_profile(ctrl, n=96, coarse=14)
    sectors = int(np.clip(np.ceil(2 * np.pi * R / 0.02), 12, 32))
    wall = vessel_wall(fine, coarse, t, "glass", sectors)
    body = [wall, _bottom(fine, t, punt * H)]
    bp.add("body", "body", body)

    # --- cap -------------------------------------------------------------------------
    pieces = _cap(cap, kind, fine, coarse, t, H, z_n, sectors)
    bp.add("cap", "cap", pieces)
    bp.join(J.continuous_prismatic("body", "cap", (0.0, 0.0, H), (0, 0, 1), (0.0, CAP_TRAVEL), role="lid"))

    # --- label band --------------------------------------------------------------------
    if p["has_label"]:
        z0, z1 = zone[0] * H, zone[1] * H
        h = p["label_fill"] * (z1 - z0)
        zl = z0 + p["label_offset"] * (z1 - z0 - h)
        gap = max(0.0015, 0.025 * h)
        r_in = outer_radius(fine, coarse, zl - 0.001, zl + h + 0.001) + gap
        band = sleeve([(r_in + 0.0008, zl), (r_in + 0.0008, zl + h)], 0.0008, "label", r_in,
                      sectors=32, collision_thickness=0.002)
        band = band.replace(sheet=0.0002)  # paper
        bp.add("label", "label", [band])
        bp.join(J.continuous("body", "label", (0.0, 0.0, zl + h / 2), (0, 0, 1), role="knob"))
    return bp


def _bottom(fine, t: float, punt: float) -> g.Piece:
    """The bottom: a flat disc, or a push-up punt (visual) on a flat collision disc."""
    rb = float(fine[0, 0]) - 0.3 * t
    tb = 1.8 * t
    flat = g.disc((0, 0, tb / 2), rb, tb, "glass", SECTIONS)
    if punt <= 0:
        return flat
    hp = max(punt, 2 * tb)
    prof = [(0.0, hp), (0.35 * rb, 0.8 * hp), (0.6 * rb, 0.45 * hp), (0.78 * rb, 0.12 * hp), (0.86 * rb, 0.0),
            (rb, 0.0), (rb, tb), (0.8 * rb, tb + 0.12 * hp), (0.62 * rb, tb + 0.45 * hp),
            (0.36 * rb, tb + 0.8 * hp), (0.0, hp + tb)]
    vis = g.revolve(prof, "glass", sections=SECTIONS)
    return vis.with_collision_of(flat)


def _cap(cap, kind, fine, coarse, t, H, z_n, sectors) -> list[g.Piece]:
    if cap == "stopper":
        r_flange = float(fine[-1, 0]) + 0.002
        depth = 0.012
        r_knob = float(np.clip(0.45 * r_flange, 0.006, 0.012))
        gap = lid_gap(depth + 0.006 + 0.3 * r_flange + 1.9 * r_knob)
        r_plug = _free_radius(fine, coarse, t, H - depth - 0.002, H, sectors) - gap
        pieces = plug_lid(H, r_flange, 0.005, r_plug, depth, 0.35, r_knob, "cork", gap)
        return [pc.replace(sheet=0.0) for pc in pieces]
    if cap == "capsule":
        length = (0.09 if kind == "champagne" else 0.045) * H / 0.3
        z_lo = max(H - length, z_n - 0.02)
        th = 0.001
    else:
        z_lo = z_n + SKIRT_FROM[cap]
        th = 0.0012 if cap == "crown" else 0.0016
    height = H - z_lo
    gap = lid_gap(height)
    r_in = outer_radius(fine, coarse, z_lo - 0.0005, H) + gap
    r_out = r_in + th
    z_top = H + gap
    top_t = 0.0025 if cap == "crown" else 0.003
    if cap == "crown":  # 21 crimped flutes flaring at the bottom edge
        prof = [(r_out + 0.0012, z_lo), (r_out + 0.0004, z_lo + 0.002), (r_out, z_lo + 0.0035),
                (r_out, z_top + 0.5 * top_t)]
        skirt = sleeve(prof, th, "cap", r_in, sections=21, collide=False)
        skirt = skirt.replace(sheet=0.0003)
    else:
        skirt = sleeve([(r_out, z_lo), (r_out, z_top + 0.5 * top_t)], th, "cap", r_in, collide=False)
    top = g.disc((0, 0, z_top + top_t / 2), r_out + 0.003, top_t, "cap", SECTIONS)
    if cap == "crown":
        top = top.replace(sheet=0.0003)
    pieces = [skirt, top]
    if kind == "champagne" and cap == "capsule":  # the mushroom cork head under the foil
        rc = r_out + 0.002
        zc = z_top + top_t
        prof = [(0.0, zc - 0.0015), (0.8 * rc, zc - 0.0015), (rc, zc + 0.004), (0.95 * rc, zc + 0.011),
                (0.6 * rc, zc + 0.015), (0.0, zc + 0.016)]
        head = g.revolve(prof, "cork", sections=SECTIONS)
        head = head.replace(convex=[np.vstack(head.convex)])  # one hull: the whole mushroom head
        pieces.append(head)
    return pieces
