"""Room facts every scene kind shares, with their sources."""

from __future__ import annotations

import math

import numpy as np

# residential ceilings: 8-9 ft (2.44-2.74 m; 2.4 m the UK/EU minimum of most building codes)
CEILING = (2.4, 2.7)
WALL = 0.12  # m: a 100 mm stud partition with 12.5 mm plasterboard each side
SILL = (0.85, 1.0)  # m: a window's sill above the floor in living rooms (guarding rules ask >= 0.8-0.9 m)
# ADA / NKBA clear floor space: 30 x 48 in (0.76 x 1.22 m) in front of a fixture; 36 in (0.91 m) walkways
WALKWAY = 0.91
YAWS = (0.0, math.pi / 2, math.pi, -math.pi / 2)  # furniture stands square to the walls
# NKBA Kitchen Planning Guidelines (2021), 17: 24 in (0.61 m) of table edge per seated diner
SEAT_WIDTH = 0.61
# dining chairs: the designs of a dining set (a metal folding chair is for events)
CHAIR_DESIGNS = ("wooden", "padded")


def door_in(layout, walls=("south", "east", "west", "north")):
    """A door set into the first wall (in a drawn order) where it and its swing fit: the placed door, or None."""
    door = layout.make("door")
    for wall in layout.rng.permutation(list(walls)):
        got = layout.embed(door, layout.room.wall(str(wall)), rng=layout.rng)
        if got is not None:
            return got
    return None


def window_in(layout, walls=("north", "east", "south", "west"), sill=SILL) -> None:
    window = layout.make("window", height=round(float(layout.rng.uniform(0.9, 1.3)), 3))
    z = float(layout.rng.uniform(*sill))
    for wall in layout.rng.permutation(list(walls)):
        if layout.embed(window, layout.room.wall(str(wall)), z=z, rng=layout.rng) is not None:
            return


def chairs_round(layout, table) -> None:
    """Chairs of one seed round the placed ``table``: one per SEAT_WIDTH of each edge, centred in its share,
    each facing the table and pushed in as far as its hulls clear the table's (``RoomLayout.tuck``)."""
    chair = layout.make("folding_chair", design=str(layout.rng.choice(CHAIR_DESIGNS)))
    lo, hi = table.lo[:2], table.hi[:2]
    mid = (lo + hi) / 2
    for axis, sign in ((0, 1), (0, -1), (1, 1), (1, -1)):
        along = 1 - axis
        length = float(hi[along] - lo[along])
        n = int(length // SEAT_WIDTH)
        for k in range(n):
            xy = mid.copy()
            xy[axis] = hi[axis] if sign > 0 else lo[axis]
            xy[along] = lo[along] + (k + 0.5) * length / n
            out = np.zeros(2)
            out[axis] = sign
            layout.tuck(chair, table, xy, out)
