"""Bathroom: a toilet, a vanity unit with its basin and tap, a wall cabinet over it, a linen tower, a door and a window.

The vanity is a kitchen_cabinet sink base at vanity height (0.85-0.9 m, "comfort height"; BS 6465-2 / NKBA bath
guidelines give 0.76-0.86 m); the toilet keeps its clear floor space (``scenes.layout.CLEARANCES``: NKBA bath
guidelines, 0.76 m in front, 0.38 m from its centreline to a side obstruction). The wall cabinet hangs
0.45-0.55 m over the vanity top (a mirror cabinet's underside at about eye level less a face: retail fitting
guides give 0.45-0.6 m); the linen tower is a tall single-column cabinet
(0.4-0.5 m wide, as bathroom tall units are). Vanity, wall cabinet and tower share one seed: one set of fronts.
Toiletries (bottles, jars, a soap pump bottle) stand on the vanity top.
"""

from __future__ import annotations

import numpy as np

from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RoomLayout

from ._common import CEILING, WALL, door_in, window_in

VANITY_HEIGHT = (0.85, 0.9)
WALL_CABINET_GAP = (0.45, 0.55)  # m: vanity top to the wall cabinet's underside (mirror-cabinet fitting guides)
WALL_RUN_MIN = 1.2  # m: the narrowest wall run kitchen_cabinet makes
TOWER_WIDTH = (0.4, 0.5)  # m: bathroom tall units (IKEA GODMORGON high cabinet 40 cm; retail towers 40-50 cm)

PARAMS = (
    Float("width", "room width (Y)", "m", 2.2, 3.2),
    Float("depth", "room depth (X)", "m", 2.2, 3.2),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
)

GRAMMAR = Grammar("bathroom", {
    "bathroom": Node(required=("toilet", "vanity", "door"),
                     optional={"wall_cabinet": 0.7, "linen_tower": 0.35, "window": 0.7}, repeat={"toiletry": (1, 5)}),
    **{k: Node() for k in ("toilet", "vanity", "door", "wall_cabinet", "linen_tower", "window", "toiletry")},
})


class BathroomLayout(RoomLayout):
    def bathroom(self, node):
        p = self.p
        self.room_of(p["width"], p["depth"], p["ceiling"], WALL)
        self.hosts = []
        self.cabinet_seed = None
        for kind in ("vanity", "wall_cabinet", "toilet", "linen_tower", "door", "window"):  # the largest unit first
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for child in node.of("toiletry"):
            self.grow(child)

    def toilet(self, node):
        toilet = self.make("toilet")
        self.on_wall(toilet, self.rng.permutation(["north", "east", "west"]), self.rng)

    def vanity(self, node):
        # a vanity unit: an 80 cm basin and one 0.4-0.6 m column beside it, 1.2-1.4 m (retail vanity units
        # 1.2-1.5 m); drawn with the category's 1-5 columns, 12 seeds at a unit under 1.6 m missed in 1 of 10 rooms
        height = round(float(self.rng.uniform(*VANITY_HEIGHT)), 3)
        self.cabinet_seed = self.seed()
        vanity = self.make("kitchen_cabinet", self.cabinet_seed, design="sink_base", base_height=height,
                           sink_width=0.8, column_count=1, stand_style="plinth", door_angle=1.5708)
        got = self.on_wall(vanity, self.rng.permutation(["north", "east", "west", "south"]), self.rng)
        if got is not None:
            self.hosts.append(got)

    def wall_cabinet(self, node):
        """A wall cabinet centred over the vanity (the narrowest wall run a kitchen_cabinet makes, 1.2 m)."""
        if not self.hosts:
            return
        vanity = self.hosts[0]
        wall = self.room.wall(vanity.wall)
        lo = float(min(np.dot(vanity.lo - wall.origin, wall.along), np.dot(vanity.hi - wall.origin, wall.along)))
        z = float(vanity.hi[2]) + float(self.rng.uniform(*WALL_CABINET_GAP))
        width = round(max(WALL_RUN_MIN, float(vanity.made.size[1]) - 0.05), 3)
        for height in (0.7, 0.6):
            unit = self.make("kitchen_cabinet", self.cabinet_seed, design="wall_run", width=width, wall_height=height,
                             column_count=int(self.rng.integers(1, 3)), door_angle=1.5708)
            s = lo + (float(vanity.made.size[1]) - float(unit.size[1])) / 2
            if self.against(unit, wall, s, z=z) is not None:
                return

    def linen_tower(self, node):
        tower = self.make("kitchen_cabinet", self.cabinet_seed, design="larder", stand_style="plinth",
                          column_width=round(float(self.rng.uniform(*TOWER_WIDTH)), 3), door_angle=1.5708)
        self.on_wall(tower, self.rng.permutation(["north", "east", "south", "west"]), self.rng)

    def door(self, node):
        door_in(self)

    def window(self, node):
        window_in(self, sill=(1.2, 1.5))  # a bathroom window sits high (privacy)

    def toiletry(self, node):
        if self.hosts:
            what = str(self.rng.choice(["bottle", "jar", "dispenser"]))
            made = self.make(what, design="pump_bottle") if what == "dispenser" else self.make(what)  # a soap pump
            self.scatter(made, self.hosts, self.rng)


KIND = SceneKind("bathroom", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, BathroomLayout)
