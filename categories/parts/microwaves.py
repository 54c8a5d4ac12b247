"""Microwave parts: the counter-top / over-the-range body and where its door, fascia and cavity go,
the drawer model's body and drawer, the over-the-range vent grille and grease filters, and the
control panels (a column of display, keys and dials, or a drawer model's horizontal strip).

World-aligned like :mod:`.appliance`: X is depth (fronts face +X), Y width, Z up. Sizes come from
:mod:`.appliance_sizes` (``MICROWAVE``), where each figure names its source.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.materials import FAMILIES

from . import appliance as A
from . import hardware
from .appliance_sizes import MICROWAVE as M
from .appliance_sizes import MICROWAVE_KEYS as K

STEEL_DENSITY = 7850.0  # kg/m^3
ROWS_ALWAYS_FIT = 3  # key rows a column panel always holds (shrinking the keys)
STRIP_ROWS = 4  # key rows a drawer model's strip takes (two rows of up to six keys)


def _over_the_range(W: float, D: float, H: float) -> tuple[float, float, float]:
    otr = M["over_the_range"]
    return otr["width"], min(max(D, otr["depth"][0]), otr["depth"][1]), \
        min(max(H + otr["taller"], otr["height"][0]), otr["height"][1])


def _drawer_model(W: float, D: float, H: float) -> tuple[float, float, float]:
    dr = M["drawer_model"]
    return (dr["widths"][0] if W < dr["narrow_below"] else dr["widths"][1]), \
        dr["depth"][0] + dr["depth"][1] * (D - dr["param_depth"][0]) / dr["param_depth"][1], dr["height"]


SIZES = {"over_the_range": _over_the_range, "drawer_model": _drawer_model}
"""Designs whose size is not the parameters' (:func:`~.appliance.size`): an over-the-range and a drawer
model take the sizes of :data:`MICROWAVE`; counter-top models use the parameters."""


def steel_sheet(family: str) -> float:
    """The sheet (m) a casing piece of ``family`` is massed with so it weighs as ``MICROWAVE["sheet"]``
    of steel: a painted or plastic-clad casing is still a steel box."""
    return M["sheet"] * STEEL_DENSITY / FAMILIES[family].density


@dataclass(frozen=True)
class Body:
    """Where a microwave's parts go: ``outer`` (x back, x bezel, x door front, y left, y right, z bottom,
    z top), the ``cavity`` (as :func:`.appliance.casing`), the door's ``door_ys``, the fascia's
    ``panel_ys`` and the ``zs`` both span (for a drawer model: the drawer's and the strip's)."""

    outer: tuple
    cavity: tuple
    door_ys: tuple
    panel_ys: tuple
    zs: tuple
    panel_zs: tuple

    @property
    def x_front(self) -> float:
        """The door's (and fascia's) front face."""
        return self.outer[2]

    @property
    def fascia_xs(self) -> tuple[float, float]:
        """The fascia's back (the bezel plane) and front face."""
        return self.outer[1:3]

    @property
    def hinge(self) -> Frame:
        """The door's hinge: on its front face at the left edge, about -Z (it swings out and to the left)."""
        return Frame.at((self.x_front, self.door_ys[0], self.zs[0]), z=(0, 0, -1))

    @property
    def handle_at(self) -> Frame:
        """The door's free edge at mid height on its front face (z out of it, x up): where a handle goes."""
        zs = self.zs
        return Frame.at((self.x_front, self.door_ys[1], (zs[0] + zs[1]) / 2), z=(1, 0, 0), x=(0, 0, 1))

    @property
    def door_height(self) -> float:
        return self.zs[1] - self.zs[0]

    @property
    def strip(self) -> bool:
        """Whether the control panel is a drawer model's wide strip (else a column beside the door)."""
        ys, zs = self.panel_ys, self.panel_zs
        return ys[1] - ys[0] > 2 * (zs[1] - zs[0])


def dial_count(knob_count: int, has_buttons: bool, rng) -> int:
    """``knob_count``; auto: 1 beside a keypad, without one 1 or 2 (drawn): a timer dial alone (Sharp
    R-21LVF) or timer and power dials (most manual counter-top models)."""
    if knob_count:
        return knob_count
    return 1 if has_buttons else 1 + int(rng.integers(0, 2))


def key_count(rows: int, bottom_keys: int) -> int:
    """Push keys: three a row, the bottom row three keys or two wide ones (Stop/Cancel and Start under the
    number pad, as on GE JES1072 and Panasonic NN-ST66 keypads)."""
    return 3 * rows - (3 - bottom_keys)


@dataclass(frozen=True)
class RackSeat:
    """Where a low wire rack stands: its ``center`` (x, y) on a floor at height ``z0``, the ``radius`` it
    fits in and the free ``room`` over that floor."""

    center: tuple[float, float]
    z0: float
    radius: float
    room: float

    @property
    def at(self) -> Frame:
        """The middle of the floor it stands on."""
        return Frame.at((*self.center, self.z0))


@dataclass(frozen=True)
class Turntable:
    """A turntable on the cavity floor: the ``spindle`` (fixed to the body) and the ``plate`` (the tray on
    its roller ring, anchor ``axis``: z up its spin axis through the floor), and ``rack``, where a rack
    stands on the tray. Both are built in the body's frame: a tray built round its own axis and moved
    there welds its vertices in another order in the GLB."""

    spindle: g.Piece
    plate: Assembly
    rack: RackSeat


def turntable(cavity, fraction: float) -> Turntable:
    """The turntable of ``fraction`` of the largest tray that fits the cavity floor (:func:`plate_fit`)."""
    c, radius = plate_fit(cavity, fraction)
    cz0 = cavity[4]
    plate = Assembly.single("plate", A.turntable(c, cz0, radius), {"axis": Frame.at((*c, cz0))})
    return Turntable(A.spindle(c, cz0), plate, rack_on_plate(cavity, c, radius))


def countertop(W, D, H, wall, door_thickness, feet, panel_fraction, vent: bool) -> Body:
    """A counter-top (or over-the-range, ``vent``) body: the door on the left, the fascia on the right,
    both inside the casing's top and bottom (under the vent band); the door's free edge clears the
    fascia by what its back corner swings out (~ft^2 / (2 width)); the cavity liner inside the walls."""
    t, ft = wall, door_thickness
    y0, y1 = -W / 2, W / 2
    zc0, zc1 = feet, H
    zd = (zc0 + M["edge"], zc1 - (M["vent"] if vent else 0.0) - M["edge"])
    panel_w = panel_fraction * W
    door_w = W - panel_w
    gap, share = M["door_gap"]
    gap_dp = max(gap, share * door_w) + ft * ft / (2 * door_w) + M["swing_room"]
    yd1 = y1 - panel_w - gap_dp
    gap_door = max(gap, share * min(yd1 - y0, zd[1] - zd[0]))
    xd1 = D / 2  # door and panel front face
    xf = xd1 - ft - gap_door  # body front face (bezel)
    xb = -D / 2
    li = M["liner_in"]
    cav = (xb + t + M["back_room"], xf - A.BEZEL, y0 + t + li, yd1 - M["bezel_side"], zc0 + t + li,
           min(zc1 - t - li, zd[1] - M["cavity_under_top"]))
    return Body((xb, xf, xd1, y0, y1, zc0, zc1), cav, (y0, yd1), (y1 - panel_w, y1), zd, zd)


def drawer_body(W, D, H, wall, door_thickness, feet) -> Body:
    """A drawer model's body: the drawer under a control strip ``MICROWAVE["strip"]`` tall."""
    t, ft = wall, door_thickness
    y0, y1 = -W / 2, W / 2
    zc0, zc1 = feet, H
    xd1, xb = D / 2, -D / 2
    xf = xd1 - ft - M["drawer_gap"]
    zt = zc1 - M["strip"]  # drawer top
    li = M["liner_in"]
    cav = (xb + t + M["back_room"], xf - A.BEZEL, y0 + t + li, y1 - t - li, zc0 + t + li,
           zt - M["drawer_cavity_under"])
    e = M["edge"]
    return Body((xb, xf, xd1, y0, y1, zc0, zc1), cav, (y0, y1), (y0 + e, y1 - e),
                (zc0 + e, zt - M["strip_gap"]), (zt + M["strip_gap"], zc1 - e))


def casing(body: Body, wall: float, body_finish: str, interior_finish: str) -> list[g.Piece]:
    """The sheet casing (:func:`.appliance.casing`) massed as steel sheet, with the high-voltage
    transformer on its floor in the bay beside the cavity (hidden) where there is one."""
    xb, xf, _, y0, y1, zc0, zc1 = body.outer
    cav, t = body.cavity, wall
    fr, fz, fb = M["foot"]
    pieces = A.casing((xb, xf, y0, y1, zc0, zc1), cav, t, min(fr, fz * zc0 + fb))
    sheets = {"body": steel_sheet(body_finish), "interior": steel_sheet(interior_finish)}
    pieces = [pc.replace(sheet=sheets[pc.material]) if pc.material in sheets else pc for pc in pieces]
    tr = M["transformer"]
    bay = (cav[3] + A.LINER + tr["clear"], y1 - t - tr["clear"])
    if bay[1] - bay[0] > tr["min_bay"]:
        side = min(tr["side"], bay[1] - bay[0])
        ym = (bay[0] + bay[1]) / 2
        x0 = xb + t + tr["from_back"]
        core = g.box_between([x0, ym - side / 2, zc0 + t],
                             [x0 + tr["core"][0], ym + side / 2, zc0 + t + tr["core"][1]],
                             "trim", name="transformer").replace(wall=0.0)
        pieces.append(core)
    return pieces


def ceramic_floor(cavity) -> g.Piece:
    """A flatbed model's fixed ceramic floor over the antenna, inside the liner."""
    cx0, cx1, cy0, cy1, cz0, _ = cavity
    i, t = M["floor_inset"], M["floor"]
    return g.box_between([cx0 + i, cy0 + i, cz0], [cx1 - i, cy1 - i, cz0 + t], "plate", bevel=0.002)


def floor_rack_seat(cavity) -> RackSeat:
    """Where a flatbed's wire rack stands: on its ceramic floor, inside the cavity's inscribed circle."""
    cx0, cx1, cy0, cy1, cz0, _ = cavity
    r = min(cx1 - cx0, cy1 - cy0) / 2 - M["rack_clear"]
    return RackSeat(((cx0 + cx1) / 2, (cy0 + cy1) / 2), cz0 + M["floor"], r, cavity[5] - cz0 - M["floor"])


def plate_fit(cavity, fraction: float) -> tuple[tuple[float, float], float]:
    """The turntable's centre and radius: ``fraction`` of the largest that fits the cavity floor."""
    cx0, cx1, cy0, cy1, _, _ = cavity
    c = ((cx0 + cx1) / 2, (cy0 + cy1) / 2)
    r_fit = min(cx1 - cx0, cy1 - cy0) / 2
    lo, share = M["plate_room"]
    return c, fraction * (r_fit - max(lo, share * r_fit))


def rack_on_plate(cavity, center, radius) -> RackSeat:
    """Where a turntable's wire rack stands: on the tray's floor, inside its rim."""
    cz0 = cavity[4]
    return RackSeat(center, cz0 + A.TRAY_TOP, radius - M["rim_room"], cavity[5] - cz0 - A.TRAY_TOP)


def stand_rack(seat: RackSeat, height: float) -> Assembly:
    """A low wire rack standing on ``seat``: a square grid inscribed in its radius on four legs, at most its
    share of the room; anchor ``floor`` under its middle (:attr:`RackSeat.at`). Built where it stands: built
    round its own origin and moved, its wires' collision pieces merge differently (last-bit rounding)."""
    h = min(height, M["rack_room"] * seat.room)
    return Assembly.single("rack", A.stand_rack(seat.center, seat.z0, seat.radius / math.sqrt(2), h),
                           {"floor": seat.at})


def vent_grille(outer) -> list[g.Piece]:
    """An over-the-range model's vent grille band over the door and panel (slots printed on it), and the
    cooktop light under the body (decor on the casing)."""
    xb, xf, xd1, y0, y1, zc0, zc1 = outer
    v = M["grille"]
    zv0 = zc1 - M["vent"] + v["under"]
    grille = [g.box_between([xf - 0.001, y0 + v["side"], zv0], [xd1, y1 - v["side"], zc1 - 0.002], "door",
                            bevel=0.002)]
    pitch, a, b = v["pitch"], v["slot_from"], v["slot_to"]
    n = int((y1 - y0 - v["slot_margin"]) / pitch)
    grille += [g.box_between([xd1, y0 + a + k * pitch, zv0 + v["slot_in"]], [xd1 + 0.0008, y0 + b + k * pitch,
                                                                              zc1 - v["slot_top"]], "display")
               for k in range(n)]
    (l0, l1), ly = v["light"]
    grille.append(g.box_between([xf - l0, -ly, zc0 - 0.002], [xf - l1, ly, zc0], "glass"))  # cooktop light
    return grille


@dataclass(frozen=True)
class GreaseFilter:
    """An over-the-range model's grease filter in the body's bottom (``MICROWAVE["filters"]``): a mesh
    frame ``length`` (x) by ``width`` (y), a finger tab ``tab`` under its front edge; it slides ``travel``
    back in its track before it drops out."""

    length: float
    width: float
    tab: float
    travel: float

    def build(self) -> Assembly:
        """In its own frame: the origin at the middle of its front edge on the body's bottom (anchor
        ``front``, x out of the front); anchor ``slide`` 2 mm under it, z back along its track."""
        f, x0, half = M["filters"], -self.length, self.width / 2
        frame = [g.box_between([x0, -half, -0.0045], [0.0, half, -0.002], "filter").replace(sheet=f["sheet"]),
                 g.box_between([-0.012, -0.02, -self.tab], [-0.004, 0.02, -0.0044], "filter")]
        return Assembly.single("filter", frame, {"front": IDENTITY, "slide": Frame.at((0.0, 0.0, -0.002),
                                                                                      z=(-1, 0, 0))})


def grease_filters(body: Body) -> tuple[GreaseFilter, list[Frame]]:
    """The grease filter's size and where the two go (their ``front`` anchors, left and right): from
    ``from_back`` behind the bezel to ``from_front`` behind it, at +-``at`` of the width."""
    xb, xf, _, y0, y1, zc0, _ = body.outer
    f = M["filters"]
    # the finger tab stays clear of the ground
    spec = GreaseFilter(xf - f["from_front"] - xb - f["from_back"], f["width"] * (y1 - y0),
                        min(f["tab"], zc0 - 0.0015), f["travel"])
    return spec, [Frame.at((xf - f["from_front"], yc, zc0)) for yc in (-f["at"] * (y1 - y0), f["at"] * (y1 - y0))]


def drawer(body: Body, body_finish: str, interior_finish: str, handle_length: float) -> A.Drawer:
    """A drawer model's drawer: a front with a window and an edge pull, an open tray inside the cavity
    liner (``MICROWAVE["drawer"]``)."""
    _, xf, xd1, _, _, _, _ = body.outer
    cx0, _, cy0, cy1, cz0, cz1 = body.cavity
    (z0, z1), (y0, y1) = body.zs, body.door_ys
    d = M["drawer"]
    c = d["in_liner"]  # the tray inside the cavity liner
    tray = (cx0 + d["tray_back"] - xd1, cy0 + c, cy1 - c, cz0 + c - z0, cz1 - c - z0)
    pieces = A.storage_drawer((xf + d["front_gap"] - xd1, 0.0, y0, y1, 0.0, z1 - z0), tray, wall=d["wall"])
    pieces = [pieces[0].replace(material="body")] + [pc.replace(material="interior") for pc in pieces[1:]]
    # front and tray are 0.6 mm steel sheet like the casing and liner, under any finish (a painted family is
    # massed as board: painted drawers weighed 0.9 kg; 0.8 mm enamelled ones 7.9 kg)
    sheets = {"body": steel_sheet(body_finish), "interior": steel_sheet(interior_finish)}
    pieces = [pc.replace(sheet=sheets[pc.material]) for pc in pieces]
    pull = hardware.edge_pull(handle_length * (y1 - y0), "handle", **M["edge_pull"]).attached(
        "mount", to=Frame.at((0.0, 0.0, z1 - z0 - d["pull_below"]), z=(1, 0, 0), x=(0, 1, 0)))
    s, m = d["window"]
    hole = (y0 + s * (y1 - y0), m, y1 - s * (y1 - y0), z1 - z0 - m)
    window = g.box_between([0.0, hole[0], hole[1]], [0.001, hole[2], hole[3]], "glass")
    part = Assembly.single("drawer", pieces + [window] + list(pull.pieces), A.DRAWER_ANCHORS)
    return A.Drawer(part, Frame.at((xd1, 0.0, z0)), d["travel"] * (xf - (cx0 + d["tray_back"])))


def door_window(ys, zs, margin: float, opener: str) -> tuple[float, float, float, float]:
    """The door's window (y0, z0, y1, z1): ``margin`` of frame on the hinge side and top, more below and
    on the free side, where the handle goes."""
    m_free = max(M["free_margin"] * margin, M["handle_room"].get(opener, 0.0))
    return (ys[0] + margin, zs[0] + M["bottom_margin"] * margin, ys[1] - m_free, zs[1] - margin)


def door_handle(kind: str, length: float) -> Assembly:
    """A door's ``bar`` pull or ``recessed`` edge pull, along local x; besides ``mount`` its anchor
    ``edge`` is the door's free edge, ``bar_in`` / ``pull_in`` beside the mounts (:attr:`Body.handle_at`)."""
    if kind == "bar":
        handle = hardware.bar_handle(length, "handle", hardware.HandleSize(**M["pull"]))
        return handle.with_anchors(edge=Frame.at((0.0, -M["bar_in"], 0.0)))
    handle = hardware.edge_pull(length, "handle", **M["edge_pull"])
    return handle.with_anchors(edge=Frame.at((0.0, -M["pull_in"], 0.0)))


def _dial_style(rng) -> str:
    return list(A.DIALS)[int(rng.choice(len(A.DIALS), p=list(A.DIALS.values())))]


def keypad_rows(rows: int, H: float, feet: float, vent: bool, panel_w: float, n_dials: int, release: bool,
                knob_radius: float, button_height: float) -> int:
    """``rows`` of keys, fewer where the column panel of a body ``H`` tall (``vent``: under an
    over-the-range vent band) cannot hold them at the smallest key scale."""
    panel_h = H - (M["vent"] if vent else 0.0) - feet - 2 * M["edge"]
    f = K["min_scale"]
    kr, bh = min(knob_radius, K["knob_share"] * panel_w) * f, button_height * f
    lo, hi = K["display"]
    dh = min(max(K["display_share"] * panel_h, lo), hi) * f
    fixed = [dh] + [2 * kr + K["dial_room"]] * n_dials + ([K["release"]] if release else [])
    while rows > 3 and sum(fixed) + rows * K["row_pitch"] * bh + K["gap"] * (len(fixed) + rows - 1) > \
            panel_h - 2 * K["margin"]:
        rows -= 1
    return rows


def column_panel(xp, ys, zs, n_keys, n_dials, release: bool, knob_radius, button_height, shape, rng) -> A.Panel:
    """A fascia's column, top-down: a display (with keys, or alone), ``n_keys`` keys in rows of three, a
    flat membrane keypad (without keys or dials), the dials sharing what is left, a door release button
    at the bottom. Buttons, dials and display shrink together on a short panel."""
    ya, yb = ys
    pw, ph = yb - ya, zs[1] - zs[0]
    yc = (ya + yb) / 2
    rows = -(-n_keys // 3)
    display = bool(n_keys) or not n_dials
    keypad = not n_keys and not n_dials  # a flat membrane keypad instead
    bh, kr = button_height, min(knob_radius, K["knob_share"] * pw)
    lo, hi = K["display"]
    dh = min(max(K["display_share"] * ph, lo), hi)
    pad = K["membrane"]
    rh = K["release"]

    def heights(f):
        return ([dh * f] if display else []) + [K["row_pitch"] * bh * f] * rows + ([pad * ph] if keypad else []) + \
            [2 * kr * f + K["dial_room"]] * n_dials + ([rh] if release else [])

    avail = ph - 2 * K["margin"]
    f = 1.0  # shrink buttons, dials and display together on a short panel
    while f > K["min_scale_shrink"] and sum(heights(f)) + K["gap"] * (len(heights(f)) - 1) > avail:
        f *= K["shrink"]
    gap = min(K["max_gap"], max(K["min_gap"], (avail - sum(heights(f))) / (len(heights(f)) + 1)))
    bh, kr, dh = bh * f, kr * f, dh * f
    panel = A.Panel()
    z = zs[1] - K["margin"]  # top of the next item
    if display:
        panel.decor.append(g.box_between([xp - 0.001, yc - K["display_w"] * pw, z - dh],
                                         [xp + 0.0015, yc + K["display_w"] * pw, z], "display"))
        z -= dh + gap
    if n_keys:
        z = _button_grid(panel, xp, yc, pw, z, bh, gap, n_keys, shape)
    if keypad:
        panel.decor.append(g.box_between([xp - 0.001, ya + K["membrane_side"] * pw, z - pad * ph],
                                         [xp + 0.001, yb - K["membrane_side"] * pw, z], "display"))
        z -= pad * ph + gap
    z_floor = zs[0] + K["margin"] + (rh + gap if release else 0.0)
    if release:
        rw, zr = K["release_w"] * pw, zs[0] + K["margin"] + rh / 2
        half = (rw / 2, rh / 2)
        panel.holes.append(A.hole_around(yc, zr, half))
        proud = K["release_proud"]
        piece = g.box_between([xp - A.BEHIND, yc - half[0], zr - half[1]], [xp + proud, yc + half[0], zr + half[1]],
                              "button", bevel=0.003)
        panel.buttons.append(A.Control("door_release", (piece,), Frame.at((xp + proud, yc, zr), z=(-1, 0, 0)), rh / 8,
                                       release=True))
    if n_dials:
        span = (z - z_floor) / n_dials
        for k in range(n_dials):
            zk = z - span * (k + 0.5)
            r_k = min(kr * (1.0 if k == 0 else float(rng.uniform(*K["dial_shrink"]))), 0.5 * span - 0.004)
            style = _dial_style(rng)
            stem = max(K["stem"], K["stem_share"] * r_k)
            panel.holes.append(A.hole_around(yc, zk, (stem, stem)))
            axis = Frame.at((xp, yc, zk), z=(1, 0, 0))
            panel.dials.append(A.Control(f"knob_{k}", tuple(A.dial(xp, yc, zk, r_k, stem, style)), axis))
    return panel


def _button_grid(panel, xp, yc, pw, z, bh, gap, n_keys, shape):
    """Rows of three keys top-down; a bottom row of two holds two wide keys over the same span."""
    proud = K["proud_share"] * bh + K["proud"]  # a pressed button (1/8 of its height in) still stands proud
    rows = -(-n_keys // 3)
    for r in range(rows):
        zb = z - K["key_drop"] * bh
        cols = min(3, n_keys - 3 * r)
        pitch = K["keys_w"] * pw / cols
        for c in range(cols):
            y = yc + (c - (cols - 1) / 2) * pitch
            if shape == "rect":
                half = (min(pitch - 2 * A.CLEAR - K["key_gap"], (K["key_wide"] if cols == 3 else K["key_wider"]) * bh)
                        / 2, bh / 2)
            else:
                rad = min(K["round"] * bh, (pitch - 2 * A.CLEAR - K["key_gap"]) / 2)
                half = (rad, rad)
            panel.holes.append(A.hole_around(y, zb, half))
            piece = A.push_button(xp, y, zb, half, shape, proud)
            panel.buttons.append(A.Control(f"button_{r}_{c}", (piece,), Frame.at((xp + proud, y, zb), z=(-1, 0, 0)),
                                           half[1] / 4))
        z -= K["row_pitch"] * bh + gap
    return z


def strip_panel(xp, ys, zs, n_keys, n_dials, knob_radius, button_height, shape, rng) -> A.Panel:
    """A horizontal control strip: a display on the left, the push buttons in a grid of one or two
    rows in the middle, the dials on the right (a drawer microwave's angled fascia, flattened)."""
    S = M["strip_panel"]
    (ya, yb), (za, zb) = ys, zs
    ph, zc = zb - za, (za + zb) / 2
    keypad = not n_keys and not n_dials
    half_h = S["display_h"] * ph
    panel = A.Panel()
    panel.decor.append(g.box_between([xp - 0.001, ya + S["display"][0], zc - half_h],
                                     [xp + 0.0015, ya + S["display"][1], zc + half_h], "display"))
    y = ya + S["keys_from"]
    r_dial = min(knob_radius, S["knob_share"] * ph - 0.004)
    if n_keys:
        n = n_keys
        nrow = min(-(-n // 3), 2)
        ncol = -(-n // nrow)
        room = yb - S["end"] - n_dials * (2 * r_dial + S["dial_gap"]) - y - S["keys_gap"]
        wide = K["key_wide"] if shape == "rect" else 1.0  # key width / height
        bh = min(button_height, (ph - S["keys_margin"] - (nrow - 1) * K["gap"]) / nrow,
                 (room / ncol - 2 * A.CLEAR - K["gap"]) / wide)  # the grid fits beside the dials
        half = (S["rect_half"] * bh, bh / 2) if shape == "rect" else (bh / 2, bh / 2)
        pitch_y, pitch_z = 2 * half[0] + 2 * A.CLEAR + K["gap"], bh + K["gap"]
        proud = K["proud_share"] * bh + K["proud"]
        for k in range(n):
            r, c = divmod(k, ncol)
            yk, zk = y + half[0] + c * pitch_y, zc + (0.5 * (nrow - 1) - r) * pitch_z
            panel.holes.append(A.hole_around(yk, zk, half))
            panel.buttons.append(A.Control(f"button_{r}_{c}", (A.push_button(xp, yk, zk, half, shape, proud),),
                                           Frame.at((xp + proud, yk, zk), z=(-1, 0, 0)), half[1] / 4))
        y += ncol * pitch_y + S["keys_gap"]
    if keypad:
        panel.decor.append(g.box_between([xp - 0.001, y, zc - half_h], [xp + 0.001, y + S["membrane"], zc + half_h],
                                         "display"))
    for k in range(n_dials):
        r_k = r_dial
        yk = yb - S["end"] - r_k - k * (2 * r_k + S["dial_gap"])
        stem = max(K["stem"], K["stem_share"] * r_k)
        style = _dial_style(rng)
        panel.holes.append(A.hole_around(yk, zc, (stem, stem)))
        panel.dials.append(A.Control(f"knob_{k}", tuple(A.dial(xp, yk, zc, r_k, stem, style)),
                                     Frame.at((xp, yk, zc), z=(1, 0, 0))))
    return panel


def fascia(xs, ys, zs, holes, skin: str, inner: str, inner_sheet: float) -> list[g.Piece]:
    """The control panel's fascia: a thin skin on a dark inner frame, both with the ``holes``."""
    xf, xp = xs
    ya, yb = ys
    return [g.panel([xp - A.SKIN, ya, zs[0]], [xp, yb, zs[1]], skin, "x", holes=holes),
            g.panel([xf, ya, zs[0]], [xp - A.SKIN, yb, zs[1]], inner, "x", holes=holes).replace(sheet=inner_sheet)]
