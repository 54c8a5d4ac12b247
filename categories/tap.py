"""Tap: a kitchen or bathroom faucet on a deck plate, with a swivelling spout.

X is depth (the spout reaches toward +X), Y is width, Z is up. The root part ``base`` is
the deck plate with the columns standing on it (solids of revolution). The spout is a swept
tube (convex hulls between consecutive rings along its centre line) that swivels about the
vertical axis of its column (continuous or revolute +-``spout_swivel``: neutral under
gravity). It is mounted one of two ways:

* on a **collar** around the main column (a thin ring of revolution with a radial gap), the
  tube leaving the collar forward (``curved``: bends down to the outlet, ``straight``: a
  slightly falling tube with a down-turned outlet);
* on top of its own **separate pipe** (``has_separate_pipe``): a riser in the middle of the
  deck, the spout continuing it upward as a ``gooseneck`` (an inverted U), a ``curved``
  spout (up, over and down) or a ``straight`` one (up, then forward).

Controls (``handles``):

* ``single_lever``: a cap with a lever arm on top of the main column (or, with a separate
  pipe, of a short mixer column on the right, +Y). flip_revolute: swivel about Z +-pi/2
  (temperature, neutral), then tilt about the horizontal axis through the back bottom edge
  of the cap (flow). The load is in front of that axis, so about (0, -1, 0) gravity pushes
  toward negative q: the lever rests closed on its lower stop and lifts by up to
  ``lever_tilt``; every lever point stays above the pivot plane, clear of the column.
* ``two_handles``: cross or lever handles on two valve risers at +-``handle_spread`` in Y,
  revolute about Z +-pi/4 (neutral), hot (red) on the left and cold (blue) on the right.

Everything the spout can sweep over (handles, a side mixer column) is kept below the
spout's lowest point, and a collar spout stays below the lever on its column, so the spout
turns freely. Finishes: chrome, brushed steel or matte black enamel.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.blueprint import Blueprint, Growth, Rule
from infmob_usd.params import Choice, Float, Schema

GROWTH = Growth(
    tap=Rule(required=("base", "spout"), optional={"separate_pipe": 0.5},
             one_of={"single_lever": 0.6, "two_handles": 0.4}),
    spout=Rule(one_of={"gooseneck": 0.35, "curved": 0.4, "straight": 0.25}),
    handle=Rule(one_of={"cross": 0.5, "lever": 0.5}),
)
"""``tap.one_of`` is the ``handles`` parameter, ``spout.one_of`` the ``spout_shape``
parameter (a gooseneck needs a separate pipe: on a collar it becomes ``curved``) and
``handle.one_of`` the ``handle_kind`` parameter, all object-wide with the same weights."""

_HANDLES = GROWTH.rules["tap"].one_of
_SPOUTS = GROWTH.rules["spout"].one_of
_KINDS = GROWTH.rules["handle"].one_of

SCHEMA = Schema((
    Choice("handles", "one mixer lever or two valve handles", choices=tuple(_HANDLES),
           weights=tuple(_HANDLES.values())),
    Float("height", "height of the tap (top of the spout or of the lever cap)", "m", 0.15, 0.4),
    Float("base_width", "deck plate width (Y); at least what its columns need", "m", 0.06, 0.25),
    Choice("base_shape", "deck plate outline", choices=("round", "rect")),
    Float("body_radius", "radius of the main column", "m", 0.016, 0.028),
    Choice("spout_shape", "spout form", choices=tuple(_SPOUTS), weights=tuple(_SPOUTS.values())),
    Float("spout_reach", "horizontal reach of the spout outlet from its axis", "m", 0.1, 0.24),
    Float("spout_radius", "spout tube radius", "m", 0.007, 0.012),
    Choice("spout_joint", "spout swivel: free (continuous) or limited (revolute)",
           choices=("continuous", "revolute")),
    Float("spout_swivel", "swivel range (+-) of a limited spout", "rad", math.pi / 6, 3 * math.pi / 4),
    Float("lever_length", "lever arm length beyond its cap", "m", 0.04, 0.12),
    Float("lever_tilt", "lever lift range", "rad", math.pi / 9, math.pi / 5),
    Float("handle_spread", "distance of each valve handle or side mixer from the middle (Y)", "m",
          0.05, 0.1),
    Choice("handle_kind", "valve handle form", choices=tuple(_KINDS), weights=tuple(_KINDS.values())),
    Choice("finish", "tap finish", choices=("chrome", "brushed_metal", "matte_black"), weights=(0.5, 0.3, 0.2)),
    *GROWTH.flags(),
))

_FINISH = {"chrome": "chrome", "brushed_metal": "brushed_metal", "matte_black": "enamel:black"}

GAP = 0.003  # clearance around every moving part
DECK_T = 0.01  # deck plate thickness
LEVER_SWIVEL = math.pi / 2
HANDLE_TURN = math.pi / 4
TUBE = 0.0015  # wall of the spout tube (it is a hollow pipe)


def build(p: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
    bp = Blueprint("tap", materials={
        "metal": _FINISH[p["finish"]], "seal": "rubber", "aerator": "plastic:black|dark_grey",
        "hot": "plastic:red", "cold": "plastic:blue",
    })
    lever = p["handles"] == "single_lever"
    pipe = p["has_separate_pipe"]
    rb = p["body_radius"]
    rs = min(p["spout_radius"], 0.6 * rb)
    H = p["height"]
    zd = DECK_T
    base: list[g.Piece] = []
    moving: list = []  # (name, label, pieces, joint factory)

    # --- side elements: what the spout may sweep over (their highest point) ---------------------
    side_top = zd
    r_cap = 0.95 * rb
    if lever and pipe:
        rp = rs + 0.004  # spout riser radius
        d = max(p["handle_spread"], rp + r_cap + 0.03 + 0.015)
        la = min(p["lever_length"], d - rp - r_cap - 0.015)
        zc0 = zd + 0.035  # the mixer column is short
        base.append(_column((0.0, d), zd, zc0, rb))
        pieces, pivot = _lever((0.0, d), zc0 + GAP, r_cap, la, rb)
        side_top = _lever_top(pieces, pivot, p["lever_tilt"])
        moving.append(("lever", "lever", pieces, _lever_joint((0.0, d), pivot, p["lever_tilt"])))
    elif not lever:
        rv = 0.016
        d = max(p["handle_spread"], rb + 2 * rv + 0.02)
        reach_h = min(0.045, d - max(rb, rs + 0.004) - 0.012)
        z_r = zd + 0.018  # valve riser top
        for k, (y, slot) in enumerate(((d, "hot"), (-d, "cold"))):
            base.append(_column((0.0, y), zd, z_r, rv))
            pieces = _valve_handle((0.0, y), z_r + GAP, reach_h, p["handle_kind"], slot)
            side_top = max(side_top, max(pc.bounds[1, 2] for pc in pieces))
            moving.append((f"handle_{k}", "handle", pieces,
                           (lambda y=y: ((0.0, y, z_r + GAP), (0, 0, 1)))))
    else:
        d = 0.0

    # --- the spout and what carries it ------------------------------------------------------------
    shape = p["spout_shape"]
    if not pipe and shape == "gooseneck":
        shape = "curved"
    if pipe:
        rp = rs + 0.004
        z_low = side_top + 0.015 + 0.02  # the outlet (aerator included) stays above the side elements
        H = max(H, z_low + 0.06)
        z_rt = zd + max(0.03, 0.2 * (H - zd))
        base.append(_column((0.0, 0.0), zd, z_rt, rp, flare=1.5))
        spout, z_axis = _top_spout(shape, p["spout_reach"], rs, z_rt + GAP, H, z_low), z_rt + GAP
    else:
        # the main column with the collar; a lever cap sits on top of it
        hc = 2 * rs + 0.014
        if lever:
            z_bt = H - 0.03 - GAP  # top of the column (the cap is 30 mm)
            z_cm = min(zd + 0.55 * (z_bt - zd), z_bt - 0.012 - hc / 2)
        else:
            z_cm = max(side_top + 0.015 + 0.05 + rs, zd + 0.5 * (H - zd))
            H = max(H, z_cm + hc / 2 + 0.03)
            z_bt = H
        base.append(_column((0.0, 0.0), zd, z_bt, rb, dome=not lever))
        spout = _collar_spout(shape, p["spout_reach"], rs, rb, z_cm, hc, zd)
        z_axis = z_cm - hc / 2
        if lever:
            pieces, pivot = _lever((0.0, 0.0), z_bt + GAP, r_cap, p["lever_length"], rb)
            moving.append(("lever", "lever", pieces, _lever_joint((0.0, 0.0), pivot, p["lever_tilt"])))

    # --- deck plate ------------------------------------------------------------------------------
    need = 2 * (d + (rb if lever else 0.016) * 1.25 + 0.008) if d else 2 * (1.25 * rb + 0.008)
    width = max(p["base_width"], need) if d else max(need, min(p["base_width"], 0.12))
    depth = float(np.clip(0.4 * width, 2 * 1.25 * max(rb, 0.016) + 0.016, 0.09))
    if p["base_shape"] == "round" and not d:
        r = width / 2
        base.insert(0, g.revolve([(0, 0), (r, 0), (r, 0.6 * DECK_T), (r - 0.004, DECK_T), (0, DECK_T)], "metal",
                                 sections=48))
    elif p["base_shape"] == "round":
        pts = []
        for y in (-(width - depth) / 2, (width - depth) / 2):
            for z, r in ((0, depth / 2), (0.6 * DECK_T, depth / 2), (DECK_T, depth / 2 - 0.004)):
                th = np.linspace(0, 2 * np.pi, 32, endpoint=False)
                pts.append(np.c_[r * np.cos(th), y + r * np.sin(th), np.full(32, z)])
        base.insert(0, g.from_trimesh(g.convex_hull(np.vstack(pts)), "metal"))
    else:
        base.insert(0, g.box_between([-depth / 2, -width / 2, 0], [depth / 2, width / 2, DECK_T], "metal",
                                     bevel=0.003))
    if p["base_shape"] == "rect":  # a rubber gasket under the plate
        base.append(g.box_between([-depth / 2 + 0.004, -width / 2 + 0.004, -0.002],
                                  [depth / 2 - 0.004, width / 2 - 0.004, 0.0], "seal"))
    elif not d:
        base.append(g.disc([0, 0, -0.001], width / 2 - 0.004, 0.002, "seal"))
    bp.add("base", "base", base)

    bp.add("spout", "spout", spout)
    if p["spout_joint"] == "continuous":
        bp.join(J.continuous("base", "spout", (0.0, 0.0, z_axis), (0, 0, 1), role="swivel"))
    else:
        a = p["spout_swivel"]
        bp.join(J.revolute("base", "spout", (0.0, 0.0, z_axis), (0, 0, 1), -a, a, role="swivel"))

    for name, label, pieces, joint in moving:
        bp.add(name, label, pieces)
        if label == "lever":
            bp.join(joint(name))
        else:
            origin, axis = joint()
            bp.join(J.revolute("base", name, origin, axis, -HANDLE_TURN, HANDLE_TURN, role="knob"))
    return bp


# ---------------------------------------------------------------------------------------------
# columns, lever, handles


def _column(xy, z0, z1, r, flare=1.25, dome=False):
    """A column of revolution from the deck (flared foot) to ``z1`` (flat or domed top)."""
    h = z1 - z0
    prof = [(0, 0), (flare * r, 0), (flare * r, min(0.004, 0.1 * h)), (r, min(0.012, 0.3 * h))]
    if dome:
        prof += [(r, h - 0.5 * r), (0.7 * r, h - 0.1 * r), (0, h)]
    else:
        prof += [(r, h - 0.002), (r - 0.002, h), (0, h)]
    return g.revolve(prof, "metal", center=(xy[0], xy[1], z0), sections=40)


def _lever(xy, z0, r_cap, la, rb):
    """A cap on the column and an arm forward; returns the pieces and the tilt pivot."""
    x, y = xy
    h = 0.03
    cap = g.revolve([(0, 0), (r_cap, 0), (r_cap, 0.7 * h), (0.8 * r_cap, h), (0, h)], "metal",
                    center=(x, y, z0), sections=40)
    w, t = min(0.016, 1.2 * r_cap), 0.008
    rise = 0.25 * la
    zt = z0 + 0.6 * h
    pts = [[x + 0.3 * r_cap, y + s * w / 2, zt + dz] for s in (-1, 1) for dz in (0, t)]
    pts += [[x + r_cap + la, y + s * 0.35 * w, zt + rise + dz] for s in (-1, 1) for dz in (0.001, 0.7 * t)]
    arm = g.from_trimesh(g.convex_hull(np.array(pts)), "metal", name="handle")
    return [cap, arm], (x - r_cap, y, z0)


def _lever_joint(xy, pivot, tilt):
    def make(name):
        return J.flip_revolute("base", name, (xy[0], xy[1], pivot[2]), (0, 0, 1), (-LEVER_SWIVEL, LEVER_SWIVEL),
                               pivot, (0, -1, 0), (0.0, tilt), role="hinge")
    return make


def _lever_top(pieces, pivot, tilt):
    """Highest point of the lever at any tilt in [0, tilt] (about -Y through ``pivot``)."""
    v = np.vstack([pc.vertices for pc in pieces]) - pivot
    top = -np.inf
    for th in np.linspace(0, tilt, 9):
        top = max(top, float((v[:, 0] * math.sin(th) + v[:, 2] * math.cos(th)).max()))
    return pivot[2] + top


def _valve_handle(xy, z0, reach, kind, slot):
    """A hub with four spokes (cross) or one arm forward (lever), and a hot/cold button."""
    x, y = xy
    hub_r = 0.013
    pieces = [g.revolve([(0, 0), (hub_r, 0), (hub_r, 0.018), (0.8 * hub_r, 0.024), (0, 0.024)], "metal",
                        center=(x, y, z0), sections=32)]
    zs = z0 + 0.014
    if kind == "cross":
        for k in range(4):
            a = math.pi / 4 + k * math.pi / 2
            dvec = np.array([math.cos(a), math.sin(a), 0.0])
            pieces.append(g.cylinder(np.array([x, y, zs]) + 0.5 * hub_r * dvec,
                                     np.array([x, y, zs]) + reach * dvec, 0.0045, "metal", 12, name="handle"))
            pieces.append(g.sphere(np.array([x, y, zs]) + reach * dvec, 0.0065, "metal", name="handle"))
    else:
        pts = [[x + 0.5 * hub_r, y + s * 0.006, zs + dz] for s in (-1, 1) for dz in (-0.004, 0.004)]
        pts += [[x + reach, y + s * 0.004, zs + 0.006 + dz] for s in (-1, 1) for dz in (-0.003, 0.003)]
        pieces.append(g.from_trimesh(g.convex_hull(np.array(pts)), "metal", name="handle"))
    pieces.append(g.disc([x, y, z0 + 0.0245], 0.6 * hub_r, 0.002, slot))
    return pieces


# ---------------------------------------------------------------------------------------------
# spouts: swept tubes


def _ring(c, t, r, n=16):
    t = np.asarray(t, float) / np.linalg.norm(t)
    a = np.cross(t, [0, 1.0, 0]) if abs(t[1]) < 0.9 else np.cross(t, [1.0, 0, 0])
    a /= np.linalg.norm(a)
    b = np.cross(t, a)
    th = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.asarray(c, float) + r * (np.outer(np.cos(th), a) + np.outer(np.sin(th), b))


def _tube(points, r):
    """Convex hulls between consecutive rings along the centre line (tangents by differences)."""
    pts = np.asarray(points, float)
    keep = [0] + [i for i in range(1, len(pts)) if np.linalg.norm(pts[i] - pts[i - 1]) > 1e-6]
    pts = pts[keep]
    tan = np.gradient(pts, axis=0)
    out = []
    for i in range(len(pts) - 1):
        hull = g.convex_hull(np.vstack([_ring(pts[i], tan[i], r), _ring(pts[i + 1], tan[i + 1], r)]))
        out.append(g.from_trimesh(hull, "metal").replace(sheet=TUBE))
    return out


def _line(p0, p1, n):
    return [np.asarray(p0, float) + (np.asarray(p1, float) - p0) * k / n for k in range(n + 1)]


def _arc(centre, radius, a0, a1, n):
    """Points in the XZ plane: centre + radius (cos a, 0, sin a)."""
    c = np.asarray(centre, float)
    return [c + radius * np.array([math.cos(a), 0.0, math.sin(a)]) for a in np.linspace(a0, a1, n + 1)]


def _outlet(tip, r):
    """An aerator hanging from the tube end at ``tip`` (the outlet's top centre)."""
    x, _, z = tip
    return [g.cylinder([x, 0, z - 0.02], [x, 0, z + 0.002], 1.12 * r, "metal", 24),
            g.cylinder([x, 0, z - 0.0205], [x, 0, z - 0.019], 0.8 * r, "aerator", 16)]


def _top_spout(shape, reach, r, z0, H, z_low):
    """A spout continuing its riser upward; the outlet bottom stays at or above ``z_low``."""
    top = H - r  # centre line of the highest point
    pts = []
    if shape == "gooseneck":
        R = max(min(reach / 2, 0.45 * (top - z0), top - z_low - r - 0.005), 0.02)
        pts += _line([0, 0, z0], [0, 0, top - R], 6)
        pts += _arc([R, 0, top - R], R, math.pi, 0, 16)[1:]
        z_end = max(z_low + 0.02, top - R - 0.5 * (top - R - z0))
        pts += _line([2 * R, 0, top - R], [2 * R, 0, z_end], 4)[1:]
        tip = (2 * R, 0, z_end)
    else:
        R = max(min(0.04, 0.4 * (top - z0), top - z_low - r - 0.005), 0.015)
        pts += _line([0, 0, z0], [0, 0, top - R], 6)
        pts += _arc([R, 0, top - R], R, math.pi, math.pi / 2, 8)[1:]
        if shape == "curved":
            R2 = min(0.035, 0.4 * (top - z_low - 0.02), 0.3 * reach)
            x2 = max(reach - R2, R + 0.01)
            pts += _line([R, 0, top], [x2, 0, top], 6)[1:]
            pts += _arc([x2, 0, top - R2], R2, math.pi / 2, 0, 8)[1:]
            tip = (x2 + R2, 0, top - R2)
        else:
            x2 = max(reach, R + 0.03)
            pts += _line([R, 0, top], [x2, 0, top], 8)[1:]
            tip = (x2 - r, 0, top - 0.6 * r)
    return _tube(pts, r) + _outlet(tip, r)


def _collar_spout(shape, reach, r, rb, z_cm, hc, zd):
    """A ring around the column (radial gap ``GAP``) and a tube leaving it forward."""
    wall = 0.004
    r_in = rb + GAP
    collar = g.shell([(r_in + wall, z_cm - hc / 2), (r_in + wall, z_cm + hc / 2)], wall, "metal", sections=40)
    x0 = r_in + 0.5 * wall
    room = z_cm - zd - 0.05  # the outlet stays 5 cm above the deck
    if shape == "curved":
        R2 = float(np.clip(0.35 * reach, 0.015, max(0.015, room - r)))
        x2 = max(reach - R2, x0 + 0.02)
        pts = _line([x0, 0, z_cm], [x2, 0, z_cm], 8) + _arc([x2, 0, z_cm - R2], R2, math.pi / 2, 0, 8)[1:]
        tip = (x2 + R2, 0, z_cm - R2)
    else:
        drop = min(math.tan(math.radians(8)) * reach, max(room - 0.02, 0.0))
        pts = _line([x0, 0, z_cm], [reach, 0, z_cm - drop], 10)
        tip = (reach - r, 0, z_cm - drop - 0.6 * r)
    return [collar] + _tube(pts, r) + _outlet(tip, r)
