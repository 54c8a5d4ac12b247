"""TV: a flat-panel television on a pedestal stand, a two-leg stand or a wall-mount arm.

X is depth (the screen faces +X), Y is width, Z is up. The screen is a thin panel: a bezel around
a glossy display, a back housing and an electronics box carrying a VESA plate. It is fixed to the
connector, a tilt bracket whose barrel turns between the cheeks of a fork (revolute about -Y).
The tilt pivot lies behind the screen, so the screen rests upright on its lower stop and tilts
its top back by up to ``tilt``; nothing enters the stand or the ground. Stands: a ``single_post``
(a base plate and a neck, or with ``has_height_adjust`` a post that swivels and slides up in a
sleeve; without it the neck swivels on its base, +-``swivel``), ``two_legs`` (two feet with uprights and a
crossbar), or ``wall_mount`` (a wall plate and 0-3 arm links turning about Z: 0 is a tilting mount, the fork
on a bracket as far off the wall as the full tilt needs; hung with the screen's centre 1.07 m up; the
screen kept 1 cm off the wall in every combination, ``displays.wall_mount_ranges``). A stand's connector
tilts or is ``rigid`` (feet and swivel-only pedestals); a wall mount always tilts. An optional pop-up
camera rises out of a pocket behind the top edge. The panel is ``flat`` or ``curved`` (``panel_shape``:
facets along an arc of ``curve_radius``, its push buttons then in the bottom band's flat middle).
Optional push buttons on the right side rim or the bezel's bottom band.
Parts: ``categories/parts/displays.py`` (screen, stand and wall-mount builders, the layout table ``TV``).
"""

from __future__ import annotations

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import displays as S

R = S.RANGES  # the parameters' ranges (sourced in displays.Ranges)

MOVES = {"tilt", "single_post", "arm", "button", "camera"}


def moves(tree) -> bool:
    """Something moves: a tilt, a swivel post, an arm, a key or the camera (feet without tilt and without keys
    or camera would not)."""
    return any(n.kind in MOVES for n in tree.walk())


GRAMMAR = Grammar("tv", {
    "tv": Node(label="screen", required=("connector", "panel"), optional={"buttons": 0.875, "camera": 0.45},
               one_of={"single_post": 0.45, "two_legs": 0.25, "wall_mount": 0.3}, choice="stand_style"),
    "panel": Node(one_of={"flat": 0.75, "curved": 0.25}, choice="panel_shape"),
    "flat": Node(), "curved": Node(),
    "connector": Node(label="connector"),
    "single_post": Node(label="stand", optional={"height_adjust": 0.4}, one_of={"tilt": 0.6, "rigid": 0.4}),
    "height_adjust": Node(label="stand"),
    "two_legs": Node(label="stand", one_of={"tilt": 0.6, "rigid": 0.4}),
    "wall_mount": Node(label="frame", required=("tilt",), repeat={"arm": "arm_links"}),
    "tilt": Node(), "rigid": Node(),
    "arm": Node(label="arm"),
    "buttons": Node(repeat={"button": "button_count"}),
    "button": Node(label="button"),
    "camera": Node(label="camera"),
}, accept=moves)
"""The screen on its connector: ``tilt`` (the connector turns in its fork, the top back) or ``rigid`` (fixed
to the stand: most TVs on feet, and pedestals that only swivel, e.g. Samsung and LG swivel stands), drawn per
stand; a wall mount always tilts. ``camera``: a pop-up camera behind the top edge (``displays.CAMERA``)."""

PARAMS = (
    Float("width", "screen width incl. the bezel (Y)", "m", *R.width),
    Choice("aspect", "screen aspect ratio", choices=("16:9", "4:3"), weights=(0.85, 0.15)),
    Float("depth", "thickness of the screen panel (X)", "m", *R.depth),
    Float("bezel", "bezel width on the sides and top", "m", *R.bezel),
    Float("back_depth", "extra depth of the electronics box on the back", "m", *R.back_depth),
    Float("back_width", "electronics box width as a fraction of the screen width", "", *R.back_width),
    Float("back_height", "electronics box height as a fraction of the screen height", "", *R.back_height),
    Float("clearance", "gap between the stand's base (or feet) and the screen bottom", "m", *R.clearance),
    Float("base_width", "pedestal base width as a fraction of the screen width (>= 0.25 m)", "", *R.base_width),
    Float("base_depth", "pedestal base or foot depth (X)", "m", *R.base_depth),
    Choice("base_shape", "pedestal base plate shape", choices=("rect", "round"), weights=(0.6, 0.4)),
    Float("leg_spread", "distance between the two legs as a fraction of the screen width", "", *R.leg_spread),
    Float("tilt", "tilt range: the screen top tilts back 0..tilt", "rad", *R.tilt),
    Float("slide", "travel of a height-adjustable post", "m", *R.slide),
    Float("swivel", "swivel range (+-) of a height-adjustable post", "rad", *R.swivel),
    Int("arm_links", "links of a wall-mount arm (0: a tilting mount, 1: a swivel bracket, 2-3: an articulating"
        " arm)", "", *R.arm_links),
    Float("curve_radius", "radius of a curved screen (Samsung / LG curved TVs: 3000R-4200R)", "m", *R.curve_radius),
    Float("arm_length", "wall-mount arm reach from the wall plate to the tilt pivot", "m", *R.arm_length),
    Int("button_count", "push keys on the screen: 1 (a power key) to 7 (power, input, menu, volume +/-, channel"
        " +/-), as on LED TVs' side or bottom key rows (Samsung UN*EH / LG *LB owner's manuals)", "", *R.button_count),
    Choice("button_place", "where the buttons are", choices=("side", "bottom")),
    Choice("bezel_finish", "bezel material", choices=("black", "grey", "silver"), weights=(0.6, 0.2, 0.2)),
    Choice("stand_finish", "stand material", choices=("metal", "black", "chrome"), weights=(0.4, 0.4, 0.2)),
)

_FINISH = {"black": "plastic:black", "grey": "plastic:dark_grey", "silver": "brushed_metal", "metal": "brushed_metal"}
MATERIALS = {
    "bezel": ("bezel_finish", _FINISH), "display": "screen", "housing": "plastic:black|dark_grey",
    "stand": ("stand_finish", {**_FINISH, "black": "plastic:black|dark_grey"}), "connector": "brushed_metal",
    "button": "plastic:black|dark_grey", "arm": "painted:black|charcoal", "camera": "plastic:black|dark_grey",
}

class TVLayout(Layout):
    def tv(self, node):
        p = self.p
        W = p["width"]
        style = node.choice
        wall = style == "wall_mount"
        stand = node.one(style)
        adjust = stand.one("height_adjust") if style == "single_post" else None
        f = S.screen_frame(W, p["depth"], p["aspect"], wall, bool(adjust), p["clearance"], p["slide"],
                           (p["back_width"], p["back_height"], p["back_depth"]), p["tilt"])
        if wall:  # hung on the wall: the screen's centre at seated eye height, its bottom at least 30 cm up
            self.bp.elevation = S.wall_elevation(f["H"])
        xf, xs, (zs0, zs1) = f["xf"], f["xs"], f["zs"]
        hw, hh, zh0, zh1 = f["hump"]
        buttons = node.one("buttons")
        curved = node.one("panel").choice == "curved"
        place = "bottom" if curved else p["button_place"]  # a curved panel's buttons: its flat middle
        band = S.bottom_band(p["bezel"], bool(buttons) and place == "bottom")
        layout = S.button_layout(place, len(buttons.of("button")), W, xf, xs, zs0, band) if buttons else []
        if curved:
            layout, flat = S.curved_keys(layout, hw)
            pieces = S.curved_screen(W, (xf, xs, f["xhb"]), (zs0, zs1), (hw, zh0, zh1), p["bezel"], band, layout,
                                     p["curve_radius"], flat)
        else:
            pieces = S.screen(W, (xf, xs, f["xhb"]), (zs0, zs1), (hw, zh0, zh1), p["bezel"], band, layout,
                              p["button_place"])
        camera = node.one("camera")
        self.add("screen", "screen", pieces[-1:] + (S.camera_pocket(xs, zs1) if camera else []))
        # the electronics box (and a camera's pocket); the panel node adds the panel
        self.grow(node.one("panel"), pieces=pieces[:-1])
        L_k = S.fork_width(style == "two_legs", W, p["leg_spread"])
        self.grow(node.one("connector"), pivot=f["pivot"], r_k=f["r_k"], xs2=(f["x_bk"], f["xhb"]), L_k=L_k,
                  vesa=S.vesa_width(hw, L_k), hump=(hh, zh0, zh1))
        # the stand keeps the set standing upright, tilted back and raised (displays.TIP_ANGLE)
        span = S.stable_span(f["centre"], f["pivot"], p["tilt"] if stand.one("tilt") else 0.0,
                             p["slide"] if adjust else 0.0)
        geo = dict(pivot=f["pivot"], r_k=f["r_k"], L_k=L_k, W=W, xf=xf, xs=xs, x_bk=f["x_bk"], base_t=f["base_t"],
                   zs=(zs0, zs1), hump=(hw, zh0, zh1), sleeve_h=f["sleeve_h"], camera=bool(camera), span=span)
        parent, tilt = self.grow(stand, **geo)
        self.grow(stand.one("tilt") or stand.one("rigid"), parent=parent, pivot=f["pivot"], upper=tilt)
        self.fix("connector", "screen")
        if buttons:
            self.grow(buttons, layout=layout, W=W, xf=xf, place=place)
        if camera:
            self.grow(camera, xs=xs, zs1=zs1)

    def tilt(self, node, parent, pivot, upper):
        """The barrel turns in the fork: the top goes back, about -Y through its axis (load in front: rests on
        q = 0)."""
        self.extend("connector", [self.barrel])
        self.hinge(parent, "connector", Frame.at((pivot[0], 0.0, pivot[1]), z=(0, -1, 0)), upper=upper)

    def rigid(self, node, parent, pivot, upper):
        """The barrel bolted in the fork: the screen does not tilt."""
        self.extend("connector", [self.barrel])
        self.fix(parent, "connector")

    def camera(self, node, xs, zs1):
        """A pop-up camera: rises out of its pocket above the top edge (prismatic +Z, rests on its lower stop)."""
        self.add("camera", "camera", S.camera(xs, zs1))
        self.slide("screen", "camera", Frame.at(S.camera_slide(xs, zs1), z=(0, 0, 1)), upper=S.CAMERA["rise"],
                   role="telescope")

    def panel(self, node, pieces):
        self.grow(node.one(node.choice), pieces=pieces)

    def flat(self, node, pieces):
        """A flat panel (``displays.screen``): bezel, display, housing."""
        self.extend("screen", pieces)

    curved = flat  # ``displays.curved_screen``: facets along an arc

    def connector(self, node, pivot, r_k, xs2, L_k, vesa, hump):
        """The VESA plate and neck plates; the mount (``tilt`` or ``rigid``) adds the barrel in the fork (a grown
        node must make a piece of its own: the grammar's check)."""
        barrel, *rest = S.connector(pivot, r_k, xs2, L_k, vesa, hump)
        self.add("connector", "connector", rest)
        self.barrel = barrel

    def single_post(self, node, pivot, r_k, L_k, W, xf, x_bk, base_t, zs, sleeve_h, span, **_):
        p = self.p
        x_p, z_p = pivot
        pieces = [S.pedestal_base(p["base_shape"], p["base_width"], p["base_depth"], W, base_t, x_p, xf, span)]
        adj = node.one("height_adjust")
        if adj is None:  # the neck swivels on a bearing disc on the base (swivel pedestal stands)
            disc, post, axis = S.swivel_neck(x_p, z_p, r_k, L_k, W, x_bk, base_t)
            self.add("stand", "stand", pieces + [disc])
            self.add("post", "stand", post)
            self.hinge("stand", "post", Frame.at(axis), upper=p["swivel"], lower=-p["swivel"], role="swivel")
            return "post", p["tilt"]
        sleeve, slot = S.post_sleeve(x_p, z_p, r_k, x_bk, base_t, sleeve_h)
        self.add("stand", "stand", pieces + sleeve)
        return self.grow(adj, x_p=x_p, z_p=z_p, r_k=r_k, L_k=L_k, **slot)

    def height_adjust(self, node, x_p, z_p, r_k, L_k, r_post, z0, z1):
        p = self.p
        post = [g.cylinder([x_p, 0, z0], [x_p, 0, z1], r_post, "stand", 24)] + S.fork(x_p, z_p, r_k, L_k, "stand")
        self.add("post", "stand", post)
        self.join(J.revolute_prismatic("stand", "post", (x_p, 0.0, z0), (0, 0, 1), (-p["swivel"], p["swivel"]),
                                       (0, 0, 1), (0.0, p["slide"])))
        return "post", p["tilt"]

    def two_legs(self, node, pivot, r_k, L_k, xf, x_bk, base_t, span, **_):
        self.add("stand", "stand", S.two_legs(*pivot, r_k, L_k, xf, x_bk, base_t, self.p["base_depth"], span))
        return "stand", self.p["tilt"]

    def wall_mount(self, node, pivot, r_k, L_k, W, xs, x_bk, zs, hump, camera, **_):
        p = self.p
        x_p, z_p = pivot
        arms = node.of("arm")
        n = len(arms)
        corners = S.screen_corners(xs, W, zs, x_bk, hump, camera)
        if n == 0:  # a tilting mount: the fork on a bracket, as far off the wall as the full tilt needs
            pieces, tilt = S.tilt_mount(corners, pivot, r_k, L_k, p["tilt"])
            self.add("wall_plate", "frame", pieces)
            return "wall_plate", tilt
        x_w, pivots, length = S.arm_pivots(x_p, p["arm_length"], n)
        self.add("wall_plate", "frame", S.wall_plate(x_w, pivots[0], z_p))
        tilt, swing = S.wall_mount_ranges(corners, pivot, pivots, x_w, p["tilt"], n)
        parent = "wall_plate"
        for i, arm in enumerate(arms):
            parent = self.grow(arm, i=i, parent=parent, x0=pivots[i], x1=pivots[i] + length, z_p=z_p, swing=swing,
                               fork=S.fork(x_p, z_p, r_k, L_k, "arm") if i == n - 1 else None, x_p=x_p, r_k=r_k)
        return parent, tilt

    def arm(self, node, i, parent, x0, x1, z_p, swing, fork, x_p, r_k):
        end = S.arm_end(x1, fork is not None, x_p, r_k)
        name = self.add(f"arm_{i}", "arm", S.arm_link(x0, x1, z_p, end, fork))
        self.hinge(parent, name, Frame.at((x0, 0.0, z_p)), upper=swing, lower=-swing, role="swivel")
        return name

    def buttons(self, node, layout, W, xf, place):
        for k, (kid, (c, h)) in enumerate(zip(node.of("button"), layout, strict=True)):
            self.grow(kid, k=k, made=S.button(place, c, h, W, xf))

    def button(self, node, k, made):
        piece, origin, axis = made
        name = self.add(f"button_{k}", "button", [piece])
        self.join(J.prismatic("screen", name, origin, axis, 0.0, S.PRESS, role="button"))


CATEGORY = Category("tv", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, TVLayout, MATERIALS)
