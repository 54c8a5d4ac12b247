"""Jar: a mason / storage jar (round, square or hexagonal) with a screw lid.

The body is hollow: a round jar is one thin wall of revolution (``g.shell``) through a
smooth spline (body, rounded shoulder, neck with thread rings, rolled lip) on a bottom
disc; a square or hexagonal jar is a wall of flat panels (one convex piece per face and
band, so it stays hollow), a flat shoulder plate with a round opening (convex wedges
around the hole) and a round threaded neck on top. Glass or glazed ceramic.

The lid (metal or plastic) is a skirt around the threads with clearance all round (drawn,
without collision: see :func:`.vase.sleeve` for the PhysX reason) and a top disc a small
gap above the lip, with a raised centre button; plate and button collide as one hull (see
:func:`_top_hull`). It turns freely about Z and lifts 0..5 cm along +Z, resting on its seat
at 0 (gravity holds it down).

Profile helpers are shared with ``vase`` and ``bottle`` (they live in :mod:`.vase`).
"""

from __future__ import annotations

import math

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

from .vase import SECTIONS, lid_gap, outer_radius, polygon_wall, sleeve, spline_profile, vessel_wall

GROWTH = Growth(
    jar=Rule(required=("body", "lid"), one_of={"round": 0.5, "square": 0.25, "hexagonal": 0.25}),
    lid=Rule(required=("skirt", "top")),
)
"""``jar.one_of`` is the ``sides`` parameter (same weights)."""

_SIDES = GROWTH.rules["jar"].one_of
SIDE_COUNT = {"round": 0, "square": 4, "hexagonal": 6}

SCHEMA = Schema((
    Float("height", "overall height of the body (without the lid)", "m", 0.1, 0.25),
    Float("radius", "body radius (round) or half width across the flats", "m", 0.03, 0.08),
    Choice("sides", "cross-section", choices=tuple(_SIDES), weights=tuple(_SIDES.values())),
    Choice("body_finish", "body material", choices=("glass", "ceramic"), weights=(0.7, 0.3)),
    Choice("lid_finish", "lid material", choices=("brushed_metal", "chrome", "plastic", "painted"),
           weights=(0.35, 0.2, 0.3, 0.15)),
    Float("wall", "body wall thickness", "m", 0.0025, 0.005),
    Float("neck_ratio", "neck radius / body radius", "", 0.68, 0.9),
    Float("shoulder", "shoulder height / body height (round jars)", "", 0.06, 0.2),
    Float("neck_height", "threaded neck height", "m", 0.012, 0.02),
    Float("lid_height", "lid height", "m", 0.01, 0.02),
))

LID_LIFT = 0.05
THREAD = 0.0014  # m, thread ring height above the neck


def _neck_points(n: float, z0: float, z1: float) -> list[tuple[float, float]]:
    """A neck of radius ``n`` from z0 to z1: two thread rings and a rolled lip."""
    h = z1 - z0
    pts = [(n, z0), (n, z0 + 0.18 * h)]
    for c in (0.38, 0.66):
        pts += [(n + THREAD, z0 + (c - 0.04) * h), (n + THREAD, z0 + (c + 0.04) * h), (n, z0 + (c + 0.15) * h)]
    pts += [(n + 0.4 * THREAD, z1 - 0.08 * h), (n + 0.2 * THREAD, z1)]
    return pts


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    sides = SIDE_COUNT[p["sides"]]
    lid_fin = p["lid_finish"]
    lid_mat = {"plastic": "plastic:white|black|red|blue|green|light_grey",
               "painted": "painted:white|off_white|black|navy|sage|charcoal"}.get(lid_fin, lid_fin)
    bp = Blueprint("jar", materials={"body": p["body_finish"], "lid": lid_mat})
    H, R, t = p["height"], p["radius"], p["wall"]
    n = max(p["neck_ratio"] * R, t + 0.015)
    hn = p["neck_height"]
    z_neck = H - hn
    tb = 1.6 * t
    if sides == 0:
        z_sh = z_neck - p["shoulder"] * H
        ctrl = [(0.93 * R, 0.0), (0.985 * R, 0.004), (R, 0.012), (R, z_sh), (0.97 * R, z_sh + 0.3 * (z_neck - z_sh)),
                (0.5 * (R + n) + 0.1 * (R - n), z_sh + 0.7 * (z_neck - z_sh)), (n * 1.01, z_neck - 0.0015)]
        fine, coarse = spline_profile(ctrl + _neck_points(n, z_neck, H), n=96, coarse=16)
        sectors = int(np.clip(np.ceil(2 * np.pi * R / 0.02), 12, 32))
        body = [vessel_wall(fine, coarse, t, "body", sectors),
                g.disc((0, 0, tb / 2), float(fine[0, 0]) - 0.3 * t, tb, "body", SECTIONS)]
        neck_fine, neck_coarse = fine, coarse
    else:
        tp = max(t, 0.003)
        z_sh = z_neck - 0.003
        wall = polygon_wall([(0.96 * R, 0.0), (0.99 * R, 0.003), (R, 0.008), (R, z_sh)], t, sides, "body")
        plate = _plate(R, sides, n - 0.6 * t, z_sh - tp, z_sh)
        neck_fine, neck_coarse = spline_profile([(n, z_sh - 0.5 * tp)] + _neck_points(n, z_neck, H), n=48,
                                                coarse=10)
        a_in = (R - t) / math.cos(math.pi / sides)
        floor = g.cylinder((0, 0, 0), (0, 0, tb), 0.999 * a_in, "body", sides)
        turned = floor.vertices @ trimesh.transformations.rotation_matrix(math.pi / sides, (0, 0, 1))[:3, :3].T
        floor = g.Piece(turned, floor.faces, floor.material, [turned])
        body = [wall, plate, floor, vessel_wall(neck_fine, neck_coarse, t, "body", 24)]
    bp.add("body", "body", body)

    # --- lid: a skirt around the threads, a top disc above the lip -------------------------
    h_lid = p["lid_height"]
    gap = lid_gap(h_lid)
    z_lo = max(H - h_lid + gap, z_neck + 0.1 * hn)
    r_in = outer_radius(neck_fine, neck_coarse, z_lo - 0.0005, H) + gap
    th = 0.0012 if lid_fin != "plastic" else 0.002
    r_out = r_in + th
    z_top = H + gap
    top_t = 0.003
    skirt = sleeve([(r_out, z_lo), (r_out, z_top + 0.5 * top_t)], th, "lid", r_in, sectors=32, collide=False)
    r_top = r_out + 0.003
    top = g.disc((0, 0, z_top + top_t / 2), r_top, top_t, "lid", SECTIONS)
    # a raised centre panel (the button of a mason lid), glued on the top plate
    button = g.disc((0, 0, z_top + top_t + 0.0007), 0.7 * r_in, 0.0015, "lid", SECTIONS)
    # One collision hull for plate and button, with few, exactly planar faces. A separate
    # button hull hovers ~4.5 mm over the neck's rim wedges with its edge right above their
    # inner edge (its radius falls between the wedges' inner chord and corner radius); there
    # PhysX PCM builds the manifold on the button's top face and reports a deep false contact
    # (-(gap + button height), ~-6 mm) that jams the turn (jar seed 61). The plate's flat
    # bottom covers the whole rim, a robust face contact.
    top = top.replace(convex=[_top_hull(r_top, z_top, z_top + top_t, 0.7 * r_in, z_top + top_t + 0.00145)])
    button = button.replace(convex=[])
    pieces = [skirt, top, button]
    if lid_fin != "plastic":
        pieces = [pc.replace(sheet=0.0005) for pc in pieces]
    bp.add("lid", "lid", pieces)
    bp.join(J.continuous_prismatic("body", "lid", (0.0, 0.0, H), (0, 0, 1), (0.0, LID_LIFT), role="lid"))
    return bp


def _top_hull(r_plate: float, z0: float, z1: float, r_button: float, z2: float, sides: int = 16) -> np.ndarray:
    """Points of the lid's collision hull: a ``sides``-gon plate (z0..z1) under a button top at z2."""
    a = 2 * np.pi * np.arange(sides) / sides
    cs, sn = np.cos(a), np.sin(a)
    return np.vstack([np.c_[r * cs, r * sn, np.full(sides, z)]
                      for r, z in ((r_plate, z0), (r_plate, z1), (r_button, z2))])


def _plate(R: float, sides: int, r_hole: float, z0: float, z1: float) -> g.Piece:
    """The flat shoulder of a polygonal jar: the polygon (apothem ``R``) with a round hole."""
    k = 1.0 / math.cos(math.pi / sides)
    rot = trimesh.transformations.rotation_matrix(math.pi / sides, (0, 0, 1))
    prism = trimesh.creation.cylinder(radius=R * k, height=z1 - z0, sections=sides)
    prism.apply_transform(rot)
    prism.apply_translation((0, 0, (z0 + z1) / 2))
    hole = trimesh.creation.cylinder(radius=r_hole, height=(z1 - z0) + 0.01, sections=SECTIONS)
    hole.apply_translation((0, 0, (z0 + z1) / 2))
    mesh = g.subtract(prism, [hole])
    convex = []
    per_side = 6
    for s in range(sides):
        face = 2 * math.pi * s / sides
        th = face + np.linspace(-math.pi / sides, math.pi / sides, per_side + 1)
        for a0, a1 in zip(th[:-1], th[1:]):
            pts = []
            for a in (a0, a1):
                d = R / math.cos(a - face)
                for z in (z0, z1):
                    pts += [(d * math.cos(a), d * math.sin(a), z), (r_hole * math.cos(a), r_hole * math.sin(a), z)]
            convex.append(np.array(pts))
    return g.Piece(mesh.vertices, mesh.faces, "body", convex)
