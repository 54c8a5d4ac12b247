"""Dining room: a dining table with chairs round it, a sideboard, a lamp, a door and windows, things on the table.

The chairs are folding chairs of one seed (a wooden or a padded set; the bar chairs are counter height), one per
0.61 m of the table's edge, each facing the table and pushed in as far as its hulls clear the table's at rest
and over every joint's travel (a drawer, an extension, a leaf); the sideboard is a kitchen_cabinet base run
against a wall (a low cabinet with drawers and doors, as a sideboard is).
"""

from __future__ import annotations

from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RoomLayout

from ._common import CEILING, WALKWAY, WALL, YAWS, chairs_round, door_in, window_in

# a sideboard: 0.8-0.9 m tall, 0.4-0.5 m deep (IKEA Hemnes / Besta, John Lewis ranges)
SIDEBOARD_HEIGHT = (0.8, 0.9)

PARAMS = (
    Float("width", "room width (Y)", "m", 3.2, 4.5),
    Float("depth", "room depth (X)", "m", 3.2, 4.5),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
)

GRAMMAR = Grammar("dining_room", {
    "dining_room": Node(required=("table", "chairs", "door"), optional={"sideboard": 0.8, "lamp": 0.6,
                                                                         "window": 0.85, "tv": 0.2},
                        repeat={"tableware": (1, 5)}),
    **{k: Node() for k in ("table", "chairs", "door", "sideboard", "lamp", "window", "tv", "tableware")},
})


class DiningRoomLayout(RoomLayout):
    def dining_room(self, node):
        p = self.p
        self.room_of(p["width"], p["depth"], p["ceiling"], WALL)
        for kind in ("table", "chairs", "sideboard", "tv", "lamp", "door", "window"):
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for child in node.of("tableware"):
            self.grow(child)

    def table(self, node):
        r = self.room
        # a table the room keeps the walkway round (the category's 1.4-2.8 x 0.9-1.2 m, as much as fits)
        spare = 2 * WALKWAY + 0.05
        long_cap, short_cap = max(r.width, r.depth) - spare, min(r.width, r.depth) - spare
        table = self.make("dining_table", length=round(float(self.rng.uniform(1.4, max(1.4, min(2.8, long_cap)))), 3),
                          width=round(float(self.rng.uniform(0.9, max(0.9, min(1.2, short_cap)))), 3))
        # its long axis (X) along the room's longer side
        longer = YAWS[1] if r.width > r.depth else 0.0
        yaw = YAWS[int(self.rng.integers(2))] if abs(r.width - r.depth) < 0.3 else longer
        # a dining table keeps a walkway round it (NKBA 36 in behind a seated diner)
        self.table_at = self.at(table, (r.depth / 2, r.width / 2), yaw) or self.on_floor(table, self.rng, YAWS,
                                                                                         margin=WALKWAY)

    def chairs(self, node):
        table = getattr(self, "table_at", None)
        if table is not None:
            chairs_round(self, table)

    def sideboard(self, node):
        unit = self.make("kitchen_cabinet", design="base_run", width=round(float(self.rng.uniform(1.2, 1.8)), 3),
                         base_height=round(float(self.rng.uniform(0.85, 0.9)), 3), stand_style="legs",
                         door_angle=1.5708)
        self.sideboard_at = self.on_wall(unit, self.rng.permutation(["north", "east", "west", "south"]), self.rng)

    def tv(self, node):
        host = getattr(self, "sideboard_at", None)
        if host is not None:
            tv = self.make("tv", stand_style=str(self.rng.choice(["single_post", "two_legs"])))  # it stands
            self.set_on(tv, host, self.rng, prefer=lambda g: -g.z)

    def lamp(self, node):
        lamp = self.make("lamp", lamp_type="floor")
        self.on_floor(lamp, self.rng, YAWS, margin=0.25)

    def door(self, node):
        door_in(self)

    def window(self, node):
        window_in(self)

    def tableware(self, node):
        hosts = [h for h in (getattr(self, "table_at", None), getattr(self, "sideboard_at", None)) if h is not None]
        made = self.make(str(self.rng.choice(["bottle", "jar", "vase", "pot"])))
        self.scatter(made, hosts[:1] if self.rng.uniform() < 0.7 else hosts, self.rng, prefer=lambda g: -g.z)


KIND = SceneKind("dining_room", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, DiningRoomLayout)
