"""Beverage-fridge parts: the insulated body (where the door, the control strip and the racks go), the
compressor, a dual-zone cooler's two doors and zones, an undercounter fridge's solid door with its bins,
crisper drawers and freezer flap, handle anchors on a door's free stile, rack levels with their ledge
rails, and the divider plate.

World-aligned like :mod:`.appliance` (whose ``insulated_cabinet``, ``glass_door``, ``glass_shelf``,
``wire_rack`` and ``open_bin`` build the pieces): X is depth (the door faces +X), Y width, Z up. Sizes
come from :data:`.appliance_sizes.FRIDGE`, where each figure names its source.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.materials.families import FAMILIES, split_spec

from . import appliance as A
from . import hardware
from .appliance_sizes import FRIDGE as F

BAR = hardware.HandleSize(**F["bar"])
GAP = F["gap"]
RACK_EXTRA = F["rack_extra"]  # racks a design adds to (or takes from) rack_count
WIRE_PITCH = F["wire_pitch"]  # a wire rack's cradle pitch is drawn in this range
BIN_LIFT = F["bin"]["lift"]  # a door bin lifts this far off its hooks


def _undercounter(H: float) -> float:
    lo, span, p_lo, p_span = F["undercounter_height"]
    return lo + span * (H - p_lo) / p_span


SIZES = {"wine": lambda W, D, H: (W, D, _undercounter(H)),
         "dual_zone": lambda W, D, H: (max(W, F["dual_zone_width"]), D, _undercounter(H))}
"""Designs whose size is not the parameters' (:func:`~.appliance.size`): wine and dual-zone coolers are
undercounter height, a dual-zone cooler with two doors has a least width (:data:`FRIDGE`)."""


def freezer_height(height: float, cavity: float) -> float:
    """A freezer compartment ``height`` tall, at most its share of the ``cavity`` height."""
    return min(height, F["freezer"]["share"] * cavity)


def shelf_room(cavity: float, freezer: float | None) -> float:
    """Height an undercounter fridge's shelves share: above the crispers, below the freezer compartment
    (``freezer``: its height, or None)."""
    return cavity - F["crisper"]["height"] - F["crisper"]["over"] - \
        (freezer + F["freezer"]["under"] if freezer is not None else 0.0)


def shelves_fit(room: float) -> int:
    """How many shelves ``room`` holds at least ``FRIDGE["shelf_pitch"]`` apart (at least one)."""
    return max(1, int(room / F["shelf_pitch"] - F["shelf_spare"]))


def compressor(xb0: float, zf: float, zk: float, kg: float) -> g.Piece:
    """The hermetic compressor in the machine compartment behind the kick grille (hidden, no collision): a
    steel can in the ``wire`` slot (chrome, 7850 kg/m^3) massed as a shell whose wall makes it ``kg``."""
    c = F["compressor"]
    r = c["radius"]
    return A.machine_can(xb0 + c["behind"] + c["clear"] + r, zf + c["floor"], zk - zf - c["room"], r, "wire", kg,
                         "compressor")


@dataclass(frozen=True)
class Body:
    """A fridge's body pieces and where its parts go: the control strip's box (or None), the cavity, the
    door's glass ``hole``, the door ``box`` and the racks' x span."""

    pieces: list
    control: tuple | None
    cav: tuple
    hole: tuple
    box: tuple
    xs: tuple

    @property
    def margin(self) -> float:
        """The door frame beside the glass: what racks keep clear of the open door's edge."""
        return self.hole[0] - self.box[2]


FLAP_OPENS = math.pi / 2  # a freezer flap swings up a quarter turn


def cavity_height(H: float, wall: float, feet: float, kick: float) -> float:
    """Height of the cooled cavity (floor liner to ceiling liner) of a cabinet ``H`` tall."""
    return H - 2 * wall - 2 * A.LINER - feet - kick


def rack_count(design: str, asked: int) -> int:
    """``asked`` racks, plus the design's :data:`RACK_EXTRA`, at least one."""
    return max(1, asked + RACK_EXTRA.get(design, 0))


def zone_racks(asked: int) -> int:
    """A dual-zone cooler's right zone: one rack fewer than asked, at least one."""
    return max(1, asked - 1)


def body(W, D, H, wall, door_thickness, feet, kick, control_height: float | None, dual_zone: bool) -> Body:
    """The insulated cabinet (:func:`.appliance.insulated_cabinet`), the compressor, a dual-zone cooler's
    mullion; the door from the kick grille's top to the control strip (``control_height``, or None); its
    glass the cavity opening grown by 3 mm, inside the door's frame."""
    w, ft, L = wall, door_thickness, A.LINER
    y0, y1 = -W / 2, W / 2
    xf = D / 2  # door front face
    xb1, xb0 = xf - ft - GAP, -D / 2  # cabinet front and back
    zf = feet
    zk = zf + kick  # top of the kick grille
    zd = (zk + GAP, H - (control_height + GAP if control_height is not None else 0.0))  # door
    cav = (xb0 + w + L, xb1, y0 + w + L, y1 - w - L, zk + w + L, H - w - L)
    gr, gm = F["glass_grow"], F["glass_margin"]
    hole = (cav[2] - gr, max(cav[4] - gr, zd[0] + gm), cav[3] + gr, min(cav[5] + gr, zd[1] - gm))
    pieces = A.insulated_cabinet((xb0, xb1, y0, y1, zf, H), cav, zk) + [compressor(xb0, zf, zk, F["compressor_kg"])]
    if dual_zone:  # a mullion between the zones, the doors close on it
        m = F["mullion"]
        pieces.append(g.box_between([cav[0], -m / 2, cav[4]], [xb1, m / 2, cav[5]], "body")
                      .replace(sheet=A.FRIDGE_SHEET))
    control = ((xb1, xf), (y0, y1), (zd[1] + GAP, H)) if control_height is not None else None
    return Body(pieces, control, cav, hole, (xf - ft, xf, y0, y1, *zd), (cav[0] + F["rack_gap"],
                                                                          xb1 - F["rack_front"]))


def behind_bins(xs) -> tuple[float, float]:
    """The x span of shelves, crispers and the freezer flap behind the bins of a closed solid door."""
    return (xs[0], xs[1] - F["bin"]["depth"] - F["bin"]["clear"])


def crisper_zs(cav) -> tuple[float, float]:
    """The crisper drawers' bottom and top on the cavity floor."""
    cz0 = cav[4]
    return (cz0 + F["crisper"]["floor"], cz0 + F["crisper"]["height"])


def over_crispers(cav, ceiling: float) -> tuple:
    """The cavity the shelves share: above the crispers, below ``ceiling``."""
    return (*cav[:4], cav[4] + F["crisper"]["height"] + F["crisper"]["over"], ceiling)


@dataclass(frozen=True)
class Freezer:
    """A freezer compartment: the ``evaporator`` box's pieces (fixed to the body), the ``flap`` in its own
    frame (anchor ``hinge``: its top back edge, z along -Y), ``at`` where that hinge goes, and the
    ``ceiling`` below which the shelves stay."""

    evaporator: list
    flap: Assembly
    at: Frame
    ceiling: float


def freezer(cav, xs, fh: float) -> Freezer:
    """A freezer compartment ``fh`` tall across the top of the cavity: an aluminium evaporator box (its floor
    and sides, fixed to the body), a flap over its front with a finger lip, hinged on its top back edge (about
    -Y the bottom edge swings forward and up; the pivot is behind the flap's centre of mass)."""
    cx0, _, cy0, cy1, _, cz1 = cav
    f = F["freezer"]
    xf, t = xs[1], f["flap"]  # the flap's front face, its thickness
    s, sh = f["sheet"], f["sheet_mass"]
    z0 = cz1 - fh
    box = [g.box_between([cx0, cy0, z0 - s], [xf - t - s, cy1, z0], "evaporator").replace(sheet=sh),
           *[g.box_between([cx0, y0, z0], [xf - t - s, y0 + s, cz1], "evaporator").replace(sheet=sh)
             for y0 in (cy0, cy1 - s)]]
    (la, lb), lw, ld = f["lip"]
    fi = f["flap_in"]
    zh = cz1 - f["top"]  # the hinge line, the flap's own origin
    flap = [g.box_between([0.0, cy0 + fi, z0 + 0.002 - zh], [t, cy1 - fi, 0.0], "bin", bevel=0.002),
            g.box_between([t, -lw, z0 + la - zh], [t + ld, lw, z0 + lb - zh], "bin", bevel=0.002)]  # finger lip
    hinge = Frame.at((0.0, 0.0, 0.0), z=(0, -1, 0))
    return Freezer(box, Assembly.single("flap", flap, {"hinge": hinge}),
                   Frame.at((xf - t, 0.0, zh), z=(0, -1, 0)), z0 - f["under"])


def dual_doors(box, hole) -> tuple[dict, dict]:
    """A dual-zone cooler's two glass doors meeting over the mullion (wide meeting stiles carry the
    handles), each hinged on its outer side: the left and right door's ``box`` and ``hole``. A free edge's
    back corner swings ~ft^2 / 2w towards the other door: the gap between them allows it."""
    x0, x1, y0, y1, z0, z1 = box
    m, st = F["mullion"], F["meeting_stile"]
    hl = (hole[0], hole[1], -m / 2 - st, hole[3])
    hr = (m / 2 + st, hole[1], hole[2], hole[3])
    gc = max(GAP, (x1 - x0) ** 2 / (y1 - y0)) + F["meeting_gap"]
    return dict(box=(x0, x1, y0, -gc / 2, z0, z1), hole=hl), dict(box=(x0, x1, gc / 2, y1, z0, z1), hole=hr)


def zones(cav) -> tuple[tuple, tuple]:
    """A dual-zone cooler's left and right cavities, either side of the mullion."""
    m = F["mullion"]
    return (*cav[:3], -m / 2, *cav[4:]), (cav[0], cav[1], m / 2, *cav[3:])


def solid_door(box, frame_family: str) -> list[g.Piece]:
    """An insulated door: an outer steel pan (its face and flanges over the front 60 % of the edges), a foam
    core with a moulded inner liner, a gasket. The pan is steel sheet whatever its finish: a painted or
    plastic ``frame_family`` is massed as that much steel (a 2 mm skin massed as board at 750 kg/m^3 made
    these doors 1.1-1.3 kg)."""
    x0, x1, y0, y1, z0, z1 = box
    skin_sheet = A.FRIDGE_SHEET * 7850.0 / FAMILIES[split_spec(frame_family)[0]].density
    d = F["solid_door"]
    xp = x1 - d["pan"] * (x1 - x0)
    e, gi, gh = d["liner_in"], d["gasket_in"], d["gasket_hole"]
    return [g.box_between([xp, y0, z0], [x1, y1, z1], "frame", bevel=0.0015).replace(sheet=skin_sheet),
            g.box_between([x0, y0 + e, z0 + e], [xp + 0.002, y1 - e, z1 - e], "liner").replace(sheet=d["liner"]),
            g.panel([x0 - d["gasket"], y0 + gi, z0 + gi], [x0, y1 - gi, z1 - gi], "gasket", "x",
                    holes=[(y0 + gh, z0 + gh, y1 - gh, z1 - gh)])]


def door_bins(n: int, box, hole, left: bool) -> list[dict]:
    """``n`` door bins behind a solid door, inside the opening, clear of the hinge side while the door swings:
    the free side's back corners swing out by ~(ft + depth)^2 / 2W past the cabinet wall, so they are inset."""
    x0, x1, y0, y1, _, _ = box
    b = F["bin"]
    depth = b["depth"]
    free = (x1 - x0 + depth) ** 2 / (2 * (y1 - y0)) + b["swing_room"]
    ya, yb = (hole[0] + depth + b["hinge_room"], hole[2] - free) if left else \
        (hole[0] + free, hole[2] - depth - b["hinge_room"])
    pitch = (hole[3] - b["top"] - (hole[1] + b["bottom"])) / n
    out = []
    for k in range(n):
        zb = hole[1] + b["bottom"] + k * pitch
        out.append(dict(xs=(x0 - depth, x0 - b["behind"]), ys=(ya, yb),
                        zs=(zb, zb + min(b["height"], pitch - b["spare"]))))
    return out


def door_bin(xs, ys, zs) -> tuple[list[g.Piece], Frame]:
    """A door bin: an open moulded tray hooked on the door liner; its pieces and lift frame."""
    t = F["bin"]["wall"]
    return [pc.replace(sheet=t) for pc in A.open_bin(xs, ys, zs[0], zs[1] - zs[0], "bin", t=t)], \
        Frame.at((xs[1], (ys[0] + ys[1]) / 2, zs[0]), z=(0, 0, 1))


def crisper_ys(n: int, cav, width: float, door_thickness: float, margin: float) -> list[tuple[float, float]]:
    """``n`` crisper drawers side by side, clear of the open door's hinge-side edge."""
    c = F["crisper"]
    ry = min(width / 2 - math.hypot(margin, door_thickness) - c["side"], cav[3] - c["side"])
    w = (2 * ry - c["side"] * (n - 1)) / n
    return [(-ry + k * (w + c["side"]), -ry + k * (w + c["side"]) + w) for k in range(n)]


def crisper(xs, ys, zs) -> A.Drawer:
    """A crisper drawer: a clear open bin with a front and a finger pull, built in its own frame (the
    origin at the bottom middle of its front face)."""
    x0, x1 = xs
    c = F["crisper"]
    f, top = c["front"], c["under_top"]
    yc, h = (ys[0] + ys[1]) / 2, zs[1] - zs[0] - top
    ya, yb = ys[0] - yc, ys[1] - yc
    pieces = A.open_bin((x0 - x1, -f), (ya, yb), 0.0, h, "glass", t=c["wall"])
    pieces.append(g.box_between([-f, ya, 0.0], [0.0, yb, h], "trim", bevel=0.002))
    return A.Drawer(Assembly.single("drawer", pieces, A.DRAWER_ANCHORS), Frame.at((x1, yc, zs[0])),
                    c["travel"] * (x1 - x0))


def handle_anchor(box, hole, left: bool) -> tuple[Frame, float]:
    """A door's handle anchor: mid-height on its free stile (the frame beside the glass, at least
    ``FRIDGE["stile"]`` wide); returns the frame and the stile's width."""
    x0, x1, y0, y1, z0, z1 = box
    stile = max(F["stile"], (y1 - hole[2]) if left else (hole[0] - y0))
    free = y1 - stile / 2 if left else y0 + stile / 2
    return Frame.at((x1, free, (z0 + z1) / 2), z=(1, 0, 0), x=(0, 0, 1)), stile


def recessed_pull(length: float, stile: float):
    """A recessed edge pull that fits its stile."""
    d, lip, share = F["pull"]
    return hardware.edge_pull(length, "handle", depth=d, lip=min(lip, share * stile))


def rack_levels(n: int, cav, hole, xs, width: float, door_thickness: float, margin: float) -> dict:
    """``n`` rack levels in a cavity (a dual-zone cooler's zone is off the middle), the racks clear of the
    open door's hinge-side edge and behind the glass: their half width ``ry``, centre ``yc``, height ``hr``,
    and per level the rack's bottom ``zb`` and its ledge rails moulded into the side liner."""
    cx0, cx1, cy0, cy1, cz0, cz1 = cav
    r = F["racks"]
    yc = (cy0 + cy1) / 2
    ry = min(width / 2 - abs(yc) - math.hypot(margin, door_thickness) - r["door"], (cy1 - cy0) / 2 - r["side"])
    z_top = min(cz1, hole[3] - r["under_glass"])  # racks stay behind the glass, clear of the top rail
    pitch = (z_top - cz0) / (n + r["spare"])
    hr = min(r["height"], pitch - r["room"])  # rack height
    levels = []
    for k in range(n):
        z_rail = cz0 + pitch * (k + r["first"])  # top of the ledge rails of this level
        rails = []
        for s in (-1, 1):  # ledge rails under the rack's runners, short of the bins on a closed solid door
            ya, yb = sorted((yc + s * (ry - r["rail_in"]), yc + s * ((cy1 - cy0) / 2 + A.LINER)))
            rails.append(g.box_between([cx0, ya, z_rail - r["rail"]],
                                       [min(cx1 - r["rail_front"], xs[1] + r["rail_past"]), yb, z_rail], "liner"))
        levels.append((rails, z_rail + F["rack_gap"]))
    return dict(ry=ry, yc=yc, hr=hr, levels=levels)


def divider(cav, fraction: float) -> list[g.Piece]:
    """A glass divider plate at ``fraction`` of the cavity's height, with a trim at its front."""
    cx0, cx1, cy0, cy1, cz0, cz1 = cav
    d = F["divider"]
    zp = cz0 + fraction * (cz1 - cz0)
    h, th, (t0, t1) = d["glass"], d["trim"], d["trim_x"]
    return [g.box_between([cx0, cy0, zp - h], [cx1 - t1, cy1, zp + h], "glass"),
            g.box_between([cx1 - t0, cy0, zp - th], [cx1 - t1, cy1, zp + th], "trim")]
