"""Office: a desk with an office chair, shelving along a wall, a desk lamp, a monitor, a door and a window.

The desk is a dining_table (a four-legged table 0.7-0.8 m high: office desks are 0.72-0.76 m, BIFMA X5.5);
the shelving is a storage_rack of the shelving design; the monitor stands on the desk on its stand, facing the
chair, and a mouse may lie beside it.
"""

from __future__ import annotations

import math

from infmob_usd.grammar import Grammar, Node
from infmob_usd.params import Float
from infmob_usd.scenes.kind import SceneKind
from infmob_usd.scenes.layout import RoomLayout

from ._common import CEILING, WALL, YAWS, door_in, window_in

PARAMS = (
    Float("width", "room width (Y)", "m", 3.0, 4.5),
    Float("depth", "room depth (X)", "m", 3.0, 4.5),
    Float("ceiling", "floor to ceiling", "m", *CEILING),
)

GRAMMAR = Grammar("office", {
    "office": Node(required=("desk", "chair", "door"), optional={"shelving": 0.8, "desk_lamp": 0.7, "screen": 0.6,
                                                                "window": 0.9, "floor_lamp": 0.3},
                   repeat={"desk_item": (0, 3), "shelf_item": (0, 4)}),
    **{k: Node() for k in ("desk", "chair", "door", "shelving", "desk_lamp", "screen", "window", "floor_lamp",
                           "desk_item", "shelf_item")},
})


class OfficeLayout(RoomLayout):
    def office(self, node):
        p = self.p
        self.room_of(p["width"], p["depth"], p["ceiling"], WALL)
        self.desk_at = self.shelves_at = None
        for kind in ("desk", "chair", "shelving", "door", "window", "screen", "desk_lamp", "floor_lamp"):
            if node.one(kind) is not None:
                self.grow(node.one(kind))
        for kind in ("desk_item", "shelf_item"):
            for child in node.of(kind):
                self.grow(child)

    def desk(self, node):
        # a writing desk: a fixed top, drawers in one long side (+Y), which faces into the room
        desk = self.make("dining_table", height=round(float(self.rng.uniform(0.72, 0.76)), 3), top_style="fixed",
                         top_shape="rectangular", drawer_sides="one", has_casters=False,
                         length=round(float(self.rng.uniform(1.4, 1.8)), 3),
                         clearance=None)  # a desk: its chair stands at its front, not a diner's walkway
        turn = -math.pi / 2  # its -Y long side to the wall, its drawers (+Y) facing the room
        self.desk_at = self.on_wall(desk, self.rng.permutation(["north", "east", "west"]), self.rng, turn=turn)

    def chair(self, node):
        chair = self.make("office_chair")
        if self.desk_at is None:
            self.on_floor(chair, self.rng, YAWS)
            return
        # in front of the desk, facing it: 0.3 m out from its front edge (a seated user's reach)
        d = self.desk_at
        wall = self.room.wall(d.wall) if d.wall else None
        front = wall.inward if wall is not None else d.pose[:3, :3] @ [1.0, 0.0, 0.0]
        centre = (d.lo + d.hi) / 2
        half = abs(front[0]) * (d.hi - d.lo)[0] / 2 + abs(front[1]) * (d.hi - d.lo)[1] / 2
        yaw = math.atan2(-front[1], -front[0])
        for extra in (0.1, 0.2, 0.35, 0.5, 0.7, 0.9):  # as close as its arms and recline let it
            xy = centre[:2] + front[:2] * (half + chair.size[0] / 2 + extra)
            if self.at(chair, xy, yaw) is not None:
                return

    def shelving(self, node):
        # home shelving: 4-5 levels 0.3-0.4 m apart stay under a 2.4 m ceiling
        rack = self.make("storage_rack", design="shelving", width=round(float(self.rng.uniform(1.5, 2.0)), 3),
                         shelf_levels=int(self.rng.integers(4, 6)), has_goods=False,
                         shelf_spacing=round(float(self.rng.uniform(0.3, 0.4)), 3))
        self.shelves_at = self.on_wall(rack, self.rng.permutation(["north", "east", "south", "west"]), self.rng)

    def screen(self, node):
        if self.desk_at is not None:
            # a desk monitor on its stand (an arm clamps under the desk top, which a set-down item cannot)
            screen = self.make("monitor", stand_style=str(self.rng.choice(["fixed_stand", "adjustable_stand"])))
            self.set_on(screen, self.desk_at, self.rng,
                        prefer=lambda g: -g.area, yaw=self._facing())  # the screen faces the one sitting there

    def desk_lamp(self, node):
        if self.desk_at is not None:
            lamp = self.make("lamp", lamp_type="desk", base_shape=str(self.rng.choice(["round", "square", "domed"])))
            self.set_on(lamp, self.desk_at, self.rng, prefer=lambda g: -g.area, yaw=self._facing())

    def floor_lamp(self, node):
        self.on_floor(self.make("lamp", lamp_type="floor"), self.rng, YAWS, margin=0.25)

    def door(self, node):
        door_in(self)

    def window(self, node):
        window_in(self)

    def _facing(self) -> float | None:
        """The yaw that turns an item on the desk to face the room (the desk's wall's inward normal)."""
        return self.room.wall(self.desk_at.wall).yaw if self.desk_at is not None and self.desk_at.wall else None

    def desk_item(self, node):
        if self.desk_at is not None:
            self.set_on(self.make(str(self.rng.choice(["mouse", "bottle", "jar", "vase"]))), self.desk_at, self.rng)

    def shelf_item(self, node):
        if self.shelves_at is not None:
            self.set_on(self.make(str(self.rng.choice(["bottle", "jar", "vase", "pot"]))), self.shelves_at, self.rng)


KIND = SceneKind("office", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, OfficeLayout)
