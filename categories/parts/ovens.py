"""Oven parts: the stack of a range or built-in oven (plinth, drawer bay, door, control panel, where the
lower oven of a double wall oven goes), an oven section's casing and cavity, a range's cooktop top with
its vent slots and burner columns, a loose grate's play, the storage and warming drawers, the door with
its window and bar handle, rack rails and levels, and the control panel (knobs either side, a display
and push buttons in the middle).

World-aligned like :mod:`.appliance` (whose ``oven_casing``, ``oven_door``, ``oven_rack``, ``burner``,
``grate``, ``cooker_knob`` and ``panel_housing`` build the pieces): X is depth (the door faces +X), Y
width, Z up. Sizes come from :data:`.appliance_sizes.OVEN`, where each figure names its source.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import appliance as A
from . import hardware
from .appliance_sizes import OVEN as O

T = A.OVEN_PANEL
HANDLE = hardware.HandleSize(**O["handle"])
KNOB_TURN = O["knob_turn"]  # a revolute knob turns this far either way (rad)


@dataclass(frozen=True)
class Stack:
    """Where an oven's parts go: ``xs`` (back, body front, door front), ``ys``; the plinth top ``z_pl``
    and drawer-bay top ``z_dt``; the (upper) oven's ``zs`` (base, drawer top, divider, hinge), door top
    ``z_dtop`` and the gap over it ``gap_top``; the door box, the control panel's xs and zs; a double wall
    oven's ``lower`` oven (or None)."""

    H: float
    xs: tuple
    ys: tuple
    z_pl: float
    z_dt: float
    zs: tuple
    z_dtop: float
    gap_top: float
    door: tuple
    panel: tuple
    lower: dict | None

    @property
    def panel_box(self) -> dict:
        """The control panel's ``xs``, ``ys`` (the door's width) and ``zs``."""
        return dict(xs=self.panel[0], ys=self.door[2:4], zs=self.panel[1])


GRATE_AXES = ((0, 0, 1), (1, 0, 0), (0, 1, 0))
"""A loose grate's motion: it lifts off its feet (z), then has play forward (x) and sideways (y)."""
THREE_GRATES_FROM = 0.7  # m: 24 in ranges carry two grates, 30 in and wider three (GE JB735, Frigidaire FGEF3036)


def grate_count(width: float) -> int:
    return 2 if width < THREE_GRATES_FROM else 3


def burners_per_grate(n: int) -> list[int]:
    """Burners under each of ``n`` grates: two, one under the middle of three."""
    return [1 if (n == 3 and k == 1) else 2 for k in range(n)]


def knob_count(style: str, burners: int, rng) -> int:
    """One knob per burner + 1 on a range (+ 1 for a warming drawer; at most 8), 2-3 on a built-in oven,
    4-5 on a double wall oven (a mode and a temperature knob per oven)."""
    drawn = 2 + int(rng.integers(0, 2))
    if style in ("range", "warming"):
        drawn = min(8, burners + 1 + (style == "warming"))
    elif style == "double_wall":
        drawn = 4 + int(rng.integers(0, 2))
    return drawn


def free_level(rng, racks: int) -> int:
    """The rail level left free among ``racks`` + 1 (drawn)."""
    return int(rng.integers(0, racks + 1))


def stack(W, D, height, door_thickness, design: str, panel_fraction, plinth, drawer_height, warming_height,
          lower_height) -> Stack:
    """An oven's stack bottom up: plinth, a drawer bay (a warming drawer's, or a trim band under a double wall
    oven's lower door), room for the open door's handle to hang clear below it, the door (its top back edge
    rises ~ft^2/2h when opening), then the control panel: a backguard behind a range's cooktop, a fascia
    over a built-in's door. A double wall oven: two equal doors, a trim strip between them, a shallow fascia
    on top."""
    ft = door_thickness
    rng_style, double = design in ("range", "warming"), design == "double_wall"
    H = height + (lower_height if double else 0.0)  # floor to the cooktop or the top
    xb, xd1 = -D / 2, D / 2  # back of the body, front face of the door
    xf = xd1 - ft - O["door_gap"]  # body front plane
    y0, y1 = -W / 2, W / 2
    z_pl = plinth
    bay = {"warming": warming_height, "double_wall": O["lower_trim"]}.get(design, drawer_height)
    z_dt = z_pl + bay  # drawer top (double wall: a trim band under the lower door)
    reach = HANDLE.standoff + 2 * HANDLE.bar_radius + O["handle_room"]  # the open door's handle hangs clear below
    z_h = z_dt + reach  # hinge of the (lower) door
    gap_top = O["door_top_gap"] + ft * ft / (2 * O["door_rise"])  # the door's top back edge rises when opening
    lower = None
    if double:  # two equal doors, a trim strip between them, a shallow fascia on top
        panel_h = O["double_panel"] * panel_fraction
        door_h = (H - z_h - O["mid_trim"] - O["mid_gap"] - reach - gap_top - panel_h) / 2
        z_mid = z_h + door_h + O["mid_trim"]  # top of the lower oven's frame
        lower = dict(xs=(xb, xf, xd1), ys=(y0, y1), zs=(z_pl, z_dt, z_h, z_h + door_h, z_mid), H=H)
        z_h = z_mid + O["mid_gap"] + reach
        z_dtop = z_h + door_h
        base = z_mid
    else:
        panel_h = panel_fraction * (H - z_h)
        z_dtop = H - O["range_door_top"] if rng_style else H - panel_h - gap_top
        base = z_pl
    zs = (base, base if double else z_dt, (base if double else z_dt) + O["divider"], z_h)
    e = O["door_side"]
    door = (xd1 - ft, xd1, y0 + e, y1 - e, z_h, z_dtop)
    panel = ((xb, xb + O["backguard"]), (H, H + panel_h)) if rng_style else ((xf, xd1), (z_dtop + gap_top, H))
    return Stack(H, (xb, xf, xd1), (y0, y1), z_pl, z_dt, zs, z_dtop, gap_top, door, panel, lower)


def section(xs, zs, z_dtop, ztop, frame_top, door_thickness, keep_base: bool = True
            ) -> tuple[list[g.Piece], tuple]:
    """One oven's casing (:func:`.appliance.oven_casing`: sides, back, floor, front frame, liner) from
    ``zs[0]`` up; returns its pieces and its cavity. ``keep_base``: with the plinth and the feet (the
    lowest section)."""
    xb, xf, xd1, y0, y1 = xs
    ft = door_thickness
    z_h = zs[3]
    c = O["cavity"]
    cav = (xb + T + c["back"], xf - T, y0 + T + c["side"], y1 - T - c["side"],
           z_h + max(ft + c["over_door"], c["floor"]), z_dtop - c["top"])
    pieces = A.oven_casing((xb, xf, xd1, y0, y1, ztop), zs, cav, O["door_gap"], frame_top)
    if not keep_base:
        pieces = [pc for pc in pieces if pc.material not in ("plinth", "feet")]
    # the trim strip and the kick plinth are folded sheet too, not solid blocks (a solid 76 cm trim strip
    # weighed ~20 kg: ranges came out at 150-185 kg against 60-75 kg real)
    pieces = [pc.replace(sheet=A.OVEN_SHEET) if pc.material in ("body", "plinth") and not pc.sheet else pc
              for pc in pieces]
    return pieces, cav


def lower_section(lower: dict, door_thickness) -> tuple[list[g.Piece], tuple, tuple]:
    """A double wall oven's lower oven (the upper one is the usual section): its casing pieces, cavity and
    door box."""
    xb, xf, xd1 = lower["xs"]
    y0, y1 = lower["ys"]
    z_pl, z_dt, z_h, z_top, z_mid = lower["zs"]
    pieces, cav = section((xb, xf, xd1, y0, y1), (z_pl, z_pl, z_dt, z_h), z_top, z_mid, z_mid, door_thickness)
    e = O["door_side"]
    return pieces, cav, (xd1 - door_thickness, xd1, y0 + e, y1 - e, z_h, z_top)


def fixed_drawer_front(st: Stack) -> list[g.Piece]:
    """A built-in oven's fixed drawer front under the door, with a trim line."""
    (_, xf, xd1), (y0, y1) = st.xs, st.ys
    W = y1 - y0
    (t0, t1), tw = O["trim_line"]
    return [g.box_between([xf - T, y0, st.z_pl], [xd1, y1, st.z_dt], "body", bevel=0.002).replace(sheet=A.OVEN_SHEET),
            g.box_between([xd1, -tw * W, st.z_dt - t0], [xd1 + 0.002, tw * W, st.z_dt - t1], "trim")]


def top_cover(xs, ys, H) -> list[g.Piece]:
    """A built-in oven's top panel over the casing."""
    return [g.box_between([xs[0], ys[0], H - T], [xs[1] - T, ys[1], H], "body").replace(sheet=A.OVEN_SHEET)]


def range_top(xs, ys, z_dtop, front, H) -> tuple[list[g.Piece], list[g.Piece], dict]:
    """A range's top: the cooktop plate and the trim strip over the door, a vent slot strip along the back
    of the cooktop (the oven vent of a real range) in front of the backguard's knobs at ``front``; returns
    both and where the cooktop's burners go."""
    xb, xf, xd1 = xs
    plate = [g.box_between([xb, ys[0], H - T], [xd1, ys[1], H], "cooktop").replace(sheet=A.OVEN_SHEET),
             g.box_between([xf, ys[0], z_dtop], [xd1, ys[1], H - T], "body").replace(sheet=A.OVEN_SHEET)]  # trim
    v = O["vent"]
    (s0, s1), sw, sh = v["slot"]
    vent = [g.box_between([front + s0, y - sw, H], [front + s1, y + sw, H + sh], "trim")
            for y in np.linspace(ys[0] + v["ends"], ys[1] - v["ends"], v["slots"])]
    c = O["cooktop"]
    return plate, vent, dict(xs=(front + c["vent"] + c["behind_vent"], xd1 - c["front"]),
                             ys=(ys[0] + c["side"], ys[1] - c["side"]))


def burner_columns(xs, ys, H, per_grate: list[int]) -> tuple[list[g.Piece], list]:
    """Burners in columns side by side across the cooktop (``per_grate`` burners in each, alternately full
    and smaller): their pieces, and each column's (y span, burner x's) for a grate over it."""
    b = O["burners"]
    n = len(per_grate)
    gw = (ys[1] - ys[0] - (n - 1) * O["grate_gap"]) / n
    depth = xs[1] - xs[0]
    pieces, columns = [], []
    for k, per in enumerate(per_grate):
        ga = ys[0] + k * (gw + O["grate_gap"])
        r_burn = min(gw / 2 - b["side"], b["share"] * depth / per, b["radius"])
        bx = [xs[0] + depth * (j + 0.5) / per for j in range(per)]
        for j, x in enumerate(bx):
            pieces += A.burner(x, ga + gw / 2, H, r_burn * (1.0 if (j + k) % 2 == 0 else b["small"]))
        columns.append(((ga, ga + gw), bx))
    return pieces, columns


def grate(xs, col, H) -> tuple[list[g.Piece], tuple, float]:
    """A loose cast grate over a burner column: its pieces, its origin on the cooktop and its sideways
    play (at most ``OVEN["grate_side"]``, half the gap to its neighbour less 4 mm)."""
    (ga, gb), bx = col
    z0 = H + O["grate_over"]
    side = min(O["grate_side"], 0.5 * O["grate_gap"] - O["grate_clear"])
    return A.grate(xs, (ga, gb), z0, bx), ((xs[0] + xs[1]) / 2, (ga + gb) / 2, z0), side


def drawer(xs, ys, zs, warming: bool, handle_length: float, travel: float) -> A.Drawer:
    """A storage drawer in the bay under the oven: a front and an open tray behind it, an edge pull. A
    warming drawer: an enamel tray, a bar handle like the door's and a marking strip. It slides out
    ``travel`` of its depth. Built in its own frame: the origin at the bottom middle of the bay's front."""
    (xb, xf, xd1), (y0, y1), (z_pl, z_dt) = xs, ys, zs
    d = O["drawer"]
    c = d["in_bay"]
    fx0, tx0 = xf + d["front_gap"] - xd1, xb + T + d["tray_back"] - xd1
    e, top = O["door_side"], z_dt - z_pl
    pieces = A.storage_drawer((fx0, 0.0, y0 + e, y1 - e, d["over_plinth"], top),
                              (tx0, y0 + T + c, y1 - T - c, T + c, top - d["tray_under"]))
    if warming:  # an enamel tray (before the painted-steel scaling: scaled, a painted oven's tray weighed 47 kg)
        pieces = [pc.replace(material="interior") if k else pc for k, pc in enumerate(pieces)]
    if warming:
        w = O["warming"]
        zc = top / 2 + w["handle_over"]
        pull = hardware.bar_handle(handle_length * (y1 - y0), "handle", hardware.HandleSize(**w["handle"])).attached(
            "mount", to=Frame.at((0.0, 0.0, zc), z=(1, 0, 0), x=(0, 1, 0)))
        (m0, m1), mw = w["mark"]
        pieces.append(g.box_between([0.0, -mw, m0], [0.0008, mw, m1], "display"))
    else:
        depth, lip, share, below = d["pull"]
        pull = hardware.edge_pull(share * (y1 - y0), "handle", depth=depth, lip=lip).attached(
            "mount", to=Frame.at((0.0, 0.0, top - below), z=(1, 0, 0), x=(0, 1, 0)))
    pieces += [pc.replace(sheet=O["handle_tube"]) if warming else pc for pc in pull.pieces]
    return A.Drawer(Assembly.single("drawer", pieces, A.DRAWER_ANCHORS), Frame.at((xd1, 0.0, z_pl)),
                    travel * (xf + d["front_gap"] - (xb + T + d["tray_back"])))


def door(box, margin: float, handle_length: float, handle: hardware.HandleSize = HANDLE) -> list[g.Piece]:
    """An oven door (:func:`.appliance.oven_door`) with its window ``margin`` inside the frame (more below
    and above it) and a tube bar ``handle`` (a range's by default) under its top."""
    x0, x1, y0, y1, z0, z1 = box
    m = margin
    below, above = O["window"]
    hole = (y0 + m, z0 + below * m, y1 - m, z1 - above * m)
    bar = hardware.bar_handle(handle_length * (y1 - y0), "handle", handle).attached(
        "mount", to=Frame.at((x1, 0.0, z1 - O["handle_below"]), z=(1, 0, 0), x=(0, 1, 0)))
    return A.oven_door(box, hole) + [pc.replace(sheet=O["handle_tube"]) for pc in bar.parts[bar.root].pieces]


def rack_levels(cav, n: int, empty: int) -> tuple[list[g.Piece], list[dict]]:
    """``n`` + 1 rail levels evenly up the cavity, side rails on each, one level (``empty``) left free:
    the rails' pieces and the ``n`` racks' ``xs``, ``ys`` and wire height ``zc`` (the racks' front wire sits
    ~5 cm behind the door)."""
    cx0, cx1, cy0, cy1, cz0, cz1 = cav
    r = O["racks"]
    levels = n + 1
    lo, hi = cz0 + r["bottom"], cz1 - r["top"]
    rails = [lo + k * (hi - lo) / (levels - 1) for k in range(levels)]
    w, h = A.RAIL
    pieces = [g.box_between([cx0 + r["rail_back"], ya, z - h], [cx1 - r["rail_front"], yb, z], "interior")
              for z in rails for ya, yb in ((cy0, cy0 + w), (cy1 - w, cy1))]
    used = [z for lvl, z in enumerate(rails) if lvl != empty]
    return pieces, [dict(xs=(cx0 + r["back"], cx1 - r["front"]), ys=(cy0 + r["side"], cy1 - r["side"]),
                         zc=z + r["over_rail"] + A.OVEN_RACK_R) for z in used]


def control_panel(xs, ys, zs, n_k: int, n_b: int, knob_radius: float, knob_style: str
                  ) -> tuple[list[g.Piece], A.Panel, float]:
    """A hollow housing (:func:`.appliance.panel_housing`); ``n_k`` knobs left and right, a display and
    ``n_b`` push buttons in the middle. Returns the housing with its display, the panel (holes, dials,
    buttons) and the x of the knobs' (and buttons') front, for the cooktop layout."""
    k = O["knobs"]
    xp, (ya, yb), (za, zb) = xs[1], ys, zs
    ph, zm = zb - za, (za + zb) / 2
    centre_w = (max(k["centre"], n_b * k["per_button"]) + k["centre_room"]) if n_b else 0.0
    pitch = (yb - ya - 2 * k["margin"] - centre_w) / n_k
    r = min(knob_radius, k["share"] * pitch, 0.5 * ph - k["rim"])
    left = (n_k + 1) // 2 if n_b else n_k
    panel, front = A.Panel(), xp
    for i in range(n_k):
        y = ya + k["margin"] + (centre_w if n_b and i >= left else 0.0) + (i + 0.5) * pitch
        stem = max(k["stem"], k["stem_share"] * r)
        panel.holes.append(A.hole_around(y, zm, (stem, stem)))
        pieces, reach = A.cooker_knob(xp, y, zm, r, stem, knob_style)
        front = max(front, xp + reach)
        panel.dials.append(A.Control(f"knob_{i}", tuple(pieces), Frame.at((xp, y, zm), z=(1, 0, 0))))
    if n_b:
        b = O["buttons"]
        yc = ya + k["margin"] + left * pitch + centre_w / 2
        inner = centre_w - k["centre_room"]
        dh, bh = min(b["display"], b["display_share"] * ph), min(b["height"], b["share"] * ph)
        zd = zm + b["display_over"] + dh / 2 if ph > b["tall_panel"] else zm + bh
        panel.decor.append(g.box_between([xp - 0.001, yc - inner / 2, zd - dh / 2],
                                         [xp + 0.0015, yc + inner / 2, zd + dh / 2], "display"))
        zbt = zd - dh / 2 - b["under_display"] - bh / 2
        half = (min(b["width"], inner / n_b - 2 * A.CLEAR - b["space"]) / 2, bh / 2)
        press = max(b["travel"], bh / 4)
        for j in range(n_b):
            y = yc - inner / 2 + (j + 0.5) * inner / n_b
            panel.holes.append(A.hole_around(y, zbt, half))
            piece = g.box_between([xp - A.BEHIND, y - half[0], zbt - half[1]],
                                  [xp + press + b["proud"], y + half[0], zbt + half[1]], "button", bevel=0.0015)
            at = Frame.at((xp + press + b["proud"], y, zbt), z=(-1, 0, 0))
            panel.buttons.append(A.Control(f"button_{j}", (piece,), at, press))
        front = max(front, xp + press + b["proud"])
    return A.panel_housing(xs, ys, zs, panel.holes) + panel.decor, panel, front
