"""Dishwasher parts: the tub body (where the door, the racks and the control band go), a double dish
drawer's cabinet and drawers, the integrated model's cabinet front, the control fascia, rack rails and
the places of tine rows, cup shelves and cutlery baskets in a rack.

World-aligned like :mod:`.appliance` (whose ``tub_cabinet``, ``dish_rack``, ``tine_row``, ``cup_shelf``
and ``open_bin`` build the pieces): X is depth (the door faces +X), Y width, Z up. Sizes come from
:data:`.appliance_sizes.DISHWASHER`, where each figure names its source.
"""

from __future__ import annotations

from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from . import appliance as A
from . import hardware
from .appliance_sizes import DISHWASHER as DW

BAR = hardware.HandleSize(**DW["bar"])
GAP = DW["gap"]
POCKET = DW["pocket"]  # a pocket pull's depth and lip
RACK_FRONT = DW["racks"]["front"]  # kept free at a rack's front
MIN_BASKET_LIFT = DW["baskets"]["min_lift"]  # a basket that cannot lift this far stays fixed in its rack


def _compact(W: float, D: float, H: float) -> tuple[float, float, float]:
    c = DW["compact"]
    return tuple(lo + span * (v - p_lo) / p_span for v, (lo, span, p_lo, p_span) in
                 zip((W, D, H), (c["width"], c["depth"], c["height"]), strict=True))


def _dish_drawer(W: float, D: float, H: float) -> tuple[float, float, float]:
    d = DW["dish_drawer"]
    w = d["width"]
    return (w if W < w else w + (W - w)), min(D, d["depth"]), min(max(H, d["height"][0]), d["height"][1])


SIZES = {"compact": _compact, "dish_drawer": _dish_drawer}
"""Designs whose size is not the parameters' (:func:`~.appliance.size`): a compact counter-top model and a
double dish drawer take the sizes of :data:`DISHWASHER` (mapped from the parameters' ranges)."""


def pump(xb0: float, xb1: float, zf: float, zh: float) -> g.Piece:
    """The wash pump with its motor and the sump in the base under the tub (hidden, no collision): a steel
    can in the ``tub`` slot (stainless, 7850 kg/m^3) whose wall makes it ``DISHWASHER["pump_kg"]``."""
    p = DW["pump"]
    return A.machine_can((xb0 + xb1) / 2 - p["behind_centre"], zf + p["clear"], zh - zf - 2 * p["clear"],
                         p["radius"], "tub", DW["pump_kg"], "pump")


@dataclass(frozen=True)
class Tub:
    """A dishwasher body's pieces, its door's box and control band, and the racks' cavity and z range."""

    pieces: list
    door: dict
    racks: dict


def tub_body(W, D, H, wall, door_thickness, feet, kick, design: str, control_height: float, ctrl: bool,
             handle: bool) -> Tub:
    """The tub cabinet (:func:`.appliance.tub_cabinet`) with the pump (and a freestanding model's worktop);
    the door hinges at the kick's top; its top band carries the control panel and the handle, and the racks
    stay below the band and the ceiling nozzle, above the flat door's inner face and the spray arm."""
    w, ft, TL = wall, door_thickness, A.TUB_LINER
    if design == "freestanding":
        H -= DW["worktop"]
    y0, y1 = -W / 2, W / 2
    xf = D / 2  # door front face
    xb1, xb0 = xf - ft - GAP, -D / 2
    zf = feet
    zh = zf + (DW["compact_kick"] if design == "compact" else kick)  # hinge and door bottom
    zt = H - DW["door_under_top"]  # door top
    cav = (xb0 + w + TL, xb1, y0 + w + TL, y1 - w - TL, zh + DW["tub_over_hinge"], H - w - TL)
    b = DW["band"]
    band = b["base"] + (control_height if ctrl else 0.0) + (b["handle_strip"] if ctrl and handle else 0.0)
    if handle and not ctrl:
        band = b["handle_only"]
    body = A.tub_cabinet((xb0, xb1, y0, y1, zf, H), cav, zh, xf) + [pump(xb0, xb1, zf, zh)]
    if design == "freestanding":  # a worktop over the cabinet, behind the door
        body.append(g.box_between([xb0, y0, H], [xb1, y1, H + DW["worktop"]], "worktop", bevel=0.004))
    r = DW["rack_room"]
    top = min(cav[5] - r["nozzle"], zt - band - r["band"])
    bottom = max(zh + ft + A.DISPENSER + r["door"], cav[4] + r["arm"])
    return Tub(body, dict(box=(xf - ft, xf, y0, y1, zh, zt), band=band), dict(cav=cav, z=(bottom, top)))


def drawer_cabinet(W, D, H, door_thickness, feet, kick) -> tuple[list[g.Piece], dict]:
    """A double dish drawer's cabinet with two bays; returns its pieces and where the drawers go."""
    ft = door_thickness
    y0, y1 = -W / 2, W / 2
    xf, xb0 = D / 2, -D / 2
    xb1 = xf - ft - GAP
    zf = feet
    zk = zf + kick
    t = DW["drawer_panel"]  # cabinet panels (massed as sheet)

    def sheet(lo, hi, slot="body"):
        return g.box_between(lo, hi, slot).replace(sheet=A.DISHWASHER_SHEET)

    bay = (H - zk - t - GAP) / 2
    pl = DW["plinth"]
    body = [sheet([xb0, y0, zf], [xb1, y0 + t, H]), sheet([xb0, y1 - t, zf], [xb1, y1, H]),
            sheet([xb0, y0 + t, H - t], [xb1, y1 - t, H]), sheet([xb0, y0 + t, zf], [xb0 + t, y1 - t, H - t]),
            sheet([xb0 + t, y0 + t, zk - t], [xb1, y1 - t, zk]),
            sheet([xb0 + t, y0 + t, zk + bay], [xb1, y1 - t, zk + bay + t]),
            sheet([xb1 - pl["sheet"], y0, zf + pl["sheet"]], [xf - pl["behind_door"], y1, zk - pl["sheet"]],
                  "plinth")]
    (fx0, fx1), fy, fr = DW["feet"]
    body += [g.cylinder([x, y, 0.0], [x, y, zf], fr, "feet", 16) for x in (xb0 + fx0, xb1 - fx1)
             for y in (y0 + fy, y1 - fy)]
    return body, dict(xs=(xb0 + t, xb1, xf), ys=(y0, y1, t), zs=(zk, bay, t))


def drawer_boxes(k: int, xs, ys, zs) -> dict:
    """Drawer ``k``'s front and tub boxes in a drawer cabinet's bay (bottom up)."""
    (xb0t, xb1, xf), (y0, y1, t), (zk, bay, t) = xs, ys, zs
    d = DW["drawer"]
    za = zk + k * (bay + t) + GAP
    return dict(front=(xb1 + GAP, xf, y0 + GAP, y1 - GAP, za, za + bay - GAP),
                tub=(xb0t + d["tub_back"], xb1 - d["tub_front"], y0 + t + d["tub_side"], y1 - t - d["tub_side"],
                     za + d["tub_floor"], za + bay - d["tub_top"]))


@dataclass(frozen=True)
class RackSlot:
    """Where a dish drawer's rack goes (in the body at rest): its ``xs``, the tub's inner side ``cy1``,
    its floor ``za`` and the ``top`` it stays under."""

    xs: tuple[float, float]
    cy1: float
    za: float
    top: float


@dataclass(frozen=True)
class DishDrawer:
    """A dish drawer (:class:`~.appliance.Drawer`) and where its rack goes."""

    drawer: A.Drawer
    rack: RackSlot


def drawer(front, tub, handle_length: float) -> DishDrawer:
    """A dish drawer: a front skin on a core, an open stainless tub, a bar handle. Built where it stands
    in the body (its anchors there): built in its own frame and moved, the bar handle's normals round
    differently and its mesh files change."""
    x0, x1, y0, y1, z0, z1 = front
    tx0, tx1, ty0, ty1, tz0, tz1 = tub
    d = DW["drawer"]
    s = d["skin"]
    pieces = [g.box_between([x1 - s, y0, z0], [x1, y1, z1], "body").replace(sheet=A.DISHWASHER_SHEET),
              g.box_between([x0, y0, z0], [x1 - s, y1, z1], "door_inner").replace(sheet=d["core"]),
              *[pc.replace(sheet=A.DISHWASHER_SHEET) for pc in A.open_bin((tx0, tx1), (ty0, ty1), tz0, tz1 - tz0,
                                                                            "tub", t=d["tub_wall"])]]
    bar = hardware.bar_handle(handle_length * (y1 - y0), "handle", BAR).attached(
        "mount", to=Frame.at((x1, 0.0, z1 - d["handle_below"]), z=(1, 0, 0), x=(0, 1, 0)))
    r = d["rack"]
    front_at = Frame.at((x1, 0.0, z0))
    part = Assembly.single("drawer", pieces + list(bar.pieces), {k: front_at @ a for k, a in A.DRAWER_ANCHORS.items()})
    return DishDrawer(A.Drawer(part, front_at, d["travel"] * (tx1 - tx0)),
                      RackSlot((tx0 + r["ends"], tx1 - r["ends"]), ty1 - r["side"], tz0 + r["floor"], tz1 - r["top"]))


def tine_rows(n: int, xs, ry, za, top, front, yh=None) -> list[tuple[list[g.Piece], float, float]]:
    """``n`` fold-down tine rows of a rack, side by side across it (each in its own strip), along X from
    behind ``front`` (metres kept free at the rack's front) to its back: ``(pieces, y, z)`` of each hinge
    line; each folds flat about its bar towards -Y, into its strip, and stands leaning against the fold."""
    t = DW["tines"]
    yh = ry - t["side"] if yh is None else yh
    z = A.dish_rack_floor(za)
    strip = 2 * yh / n
    h = min(t["height"], t["share"] * (top - z), strip - t["strip_room"])
    out = []
    for k in range(n):
        y = -yh + k * strip + h + t["lean_room"]
        out.append((A.tine_row((xs[0] + t["back"], xs[1] - front), y, z, h, t["lean"] * h), y, z))
    return out


def cabinet_front(box, band: float, ctrl: bool) -> list[g.Piece]:
    """An integrated model's shaker cabinet front on the door, below the control strip (semi-integrated):
    a board and a frame of four rails."""
    x0, x1, y0, y1, z0, z1 = box
    f = DW["front"]
    zt = z1 - band + f["under_band"] if ctrl else z1
    x2, r, s = x1 + f["board"], f["rail"], f["rail_proud"]  # front face, frame rail width
    return [g.box_between([x1, y0, z0], [x2 - s, y1, zt], "front"),
            g.box_between([x2 - s, y0, z0], [x2, y0 + r, zt], "front", bevel=0.002),
            g.box_between([x2 - s, y1 - r, z0], [x2, y1, zt], "front", bevel=0.002),
            g.box_between([x2 - s, y0 + r, z0], [x2, y1 - r, z0 + r], "front", bevel=0.002),
            g.box_between([x2 - s, y0 + r, zt - r], [x2, y1 - r, zt], "front", bevel=0.002)]


def control_zs(box, band: float) -> tuple[float, float]:
    """The control fascia's bottom and top on a door's top band."""
    z1 = box[5]
    c = DW["control"]
    return (z1 - band + c["over_band"], z1 - c["under_top"])


def handle_frame(box, band: float, ctrl: bool, integrated: bool) -> Frame:
    """Where the door's handle mounts: in the top band under the control fascia (or the door's top), on
    the cabinet front's top rail of an integrated model, in front of the fascia or the door."""
    x1, z1 = box[1], box[5]
    f = DW["front"]
    below = DW["handle_below"]
    z = z1 - band + below if ctrl else z1 - below
    if integrated:  # a cabinet handle on the front panel's top rail
        z = (z1 - band + f["under_band"] if ctrl else z1) - below
    return Frame.at((x1 + (f["board"] if integrated else DW["fascia"] if ctrl else 0.0), 0.0, z), z=(1, 0, 0),
                    x=(0, 1, 0))


def control_panel(xf, ys, zs, handle: bool, n: int, button_size: float) -> tuple[list[g.Piece], list]:
    """A fascia on the top of the door front: a display on the left, ``n`` push buttons on the right
    (above the handle strip); returns the fascia with its display and the buttons
    (:class:`~.appliance.Control`)."""
    c = DW["control"]
    (y0, y1), (za, zb) = ys, zs
    xp, W = xf + DW["fascia"], y1 - y0
    zl = za + (DW["handle_strip"] if handle else 0.0)
    zc = (zl + zb) / 2
    panel = A.Panel()
    (d0, d1), dh = c["display"]
    panel.decor.append(g.box_between([xp - 0.001, y0 + d0 * W, zc - dh], [xp + 0.0015, y0 + d1 * W, zc + dh],
                                     "display"))
    if n:
        bh = min(button_size, zb - zl - 2 * A.CLEAR - c["key_gap"])
        half = (min(c["key_wide"] * bh, c["keys_w"] * W / n - 2 * A.CLEAR - c["key_space"]) / 2, bh / 2)
        proud = c["proud_share"] * bh + c["proud"]
        for k in range(n):
            y = y0 + 0.5 * W + (k + 0.5) * c["keys_span"] * W / n
            panel.holes.append(A.hole_around(y, zc, half))
            piece = g.box_between([xp - A.BEHIND, y - half[0], zc - half[1]],
                                  [xp + proud, y + half[0], zc + half[1]], "button",
                                  bevel=c["bevel"] * min(bh, 2 * half[0]))
            at = Frame.at((xp + proud, y, zc), z=(-1, 0, 0))
            panel.buttons.append(A.Control(f"button_{k}", (piece,), at, bh / 8))
    fascia = g.panel([xf, y0 + c["inset"], za], [xp, y1 - c["inset"], zb], "panel", "x", holes=panel.holes)
    return [fascia, *panel.decor], panel.buttons


def rack_levels(kinds: list[str], cav, z, baskets: bool) -> list[dict]:
    """The racks bottom up: each one's share of the usable height ``z`` (:data:`DISHWASHER` ``shares``),
    its rails on the side liners, its x span, the rack's own top (clear of the one above) and the room kept
    free at its front (the lowest rack's cutlery baskets)."""
    cx0, cx1, cy0, cy1 = cav[:4]
    r = DW["racks"]
    n = len(kinds)
    shares = DW["shares"][n]
    span = z[1] - z[0]
    xs = (cx0 + r["ends"], cx1 - r["ends"])
    za = z[0]
    out = []
    for k, (kind, share) in enumerate(zip(kinds, shares)):
        zb = za + span * share / sum(shares)
        top = zb - (0.0 if k == n - 1 else DW["rack_gap"] + r["under_next"])  # this rack's highest point
        rails = []
        for s in (-1, 1):  # rails: channels on the side liners
            ya, yb = sorted((s * (cy1 - r["rail_in"]), s * (cy1 + A.TUB_LINER)))
            rails.append(g.box_between([cx0 + r["rail_back"], ya, za - DW["rack_gap"] - r["rail"]],
                                       [cx1 - r["rail_front"], yb, za - DW["rack_gap"]], "tub"))
        b = DW["baskets"]
        front = r["front"] + (b["front_gap"] + min(b["depth"], b["depth_share"] * (xs[1] - xs[0]))
                              if k == 0 and baskets else 0.0)
        out.append(dict(rails=rails, slot=dict(k=k, xs=xs, cy1=cy1, za=za, top=top, kind=kind, front=front)))
        za = zb
    return out


def rack_half_width(cy1: float) -> float:
    """A dish rack's half width inside the rails (as :func:`.appliance.dish_rack`)."""
    return cy1 - DW["racks"]["half_in"]


def cup_shelf_slot(xs, ry, za, top) -> dict:
    """Where an upper rack's cup shelves hinge (under its top rim, inside its ends) and how tall they are."""
    c = DW["cup_shelf"]
    zc = za + A.RACK_WHEEL
    zt = zc + c["wall_share"] * max(top - zc, c["min_height"]) - A.DISH_WIRE  # the rack's top rim
    w = min(c["height"], c["share"] * (zt - zc))
    return dict(xs=(xs[0] + c["ends"], xs[1] - c["ends"]), ry=ry, z=zt - w - c["under_rim"], w=w)


def tines_beside_shelves(ry: float, w: float) -> float:
    """The half width the tine rows of an upper rack keep, inside its cup shelves ``w`` tall."""
    return ry - w - DW["cup_shelf"]["tines_in"]


def rack_count(design: str, asked: int) -> int:
    """Sliding racks: as asked; a compact counter-top model has room for one."""
    return 1 if design == "compact" else asked


TRAY_FROM = 3  # racks: from three up the top one is a cutlery tray (Bosch 500/800, Miele G 7000 third racks)


def rack_kinds(n: int) -> tuple[int, int]:
    """Of ``n`` racks (a lower rack first): how many upper racks and cutlery trays (on top of three or more)."""
    tray = int(n >= TRAY_FROM)
    return max(0, n - 1 - tray), tray


def cup_shelf(k: int, xs, ry, z, w) -> tuple[list[g.Piece], float, int]:
    """Cup shelf ``k``: the first on the left side wall, the second on the right; returns its pieces, its
    hinge line's y and the side's sign (each swings down inwards to level)."""
    c = DW["cup_shelf"]
    s = -1 if k == 0 else 1
    y = s * (ry - c["wall_in"])
    return A.cup_shelf(xs, y, z, w, s * c["lean"]), y, s


def baskets(n: int, xs, ry, za, top, lift: float) -> tuple[list[tuple], float]:
    """``n`` open cutlery baskets side by side at the front of the lowest rack, on its bottom grid:
    ``(pieces, lift origin)`` of each and the lift out of the rack (shortened to the rack above)."""
    rx0, rx1 = xs
    b = DW["baskets"]
    z0 = za + A.RACK_WHEEL + b["grid"] * A.DISH_WIRE + b["over_grid"]  # on the bottom grid
    lo, hi, share = b["height"]
    h = max(min(hi, share * (top - z0)), lo)
    lift = min(lift, top - z0 - h - b["under_next"])
    depth = min(b["depth"], b["depth_share"] * (rx1 - rx0))
    sp = b["space"]
    bw = min(b["width"], (2 * ry - b["side_room"]) / n - sp)
    out = []
    for k in range(n):
        y1 = ry - b["side_room"] / 2 - k * (bw + sp)
        out.append((A.open_bin((rx1 - b["front_gap"] - depth, rx1 - b["front_gap"]), (y1 - bw, y1), z0, h, "basket"),
                    (rx1 - b["front_gap"], y1 - bw / 2, z0)))
    return out, lift
