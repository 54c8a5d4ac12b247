"""The blender category's blade: real cutting geometry on a hub, not a flat cross."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker

make = maker("blender")


@pytest.mark.parametrize("design", ["countertop", "glass_jar"])
def test_the_blade_stands_on_a_hub_with_wings_bent_out_of_plane(design):
    """Over the jug's floor a hub stands up and at least two blade wings rise out of the horizontal plane
    (bent up or down by 10 degrees or more), all inside the jug."""
    _, bp = make(4, design=design)
    blade = [pc for pc in bp.parts["jug"].pieces if pc.material == "blade"]
    tilts, hub = [], False
    for pc in blade:
        ext = np.ptp(pc.vertices, axis=0)
        if ext[2] > max(ext[0], ext[1]):  # taller than wide: the hub on its bearing
            hub = True
            continue
        centred = pc.vertices - pc.vertices.mean(0)
        axis = np.linalg.svd(centred, full_matrices=False)[2][0]  # the wing's length
        tilts.append(np.degrees(np.arcsin(abs(axis[2]))))
    assert hub
    assert sum(t >= 10 for t in tilts) >= 2, tilts
    wall = [pc for pc in bp.parts["jug"].pieces if pc.material == "jug"]
    reach = max(np.abs(pc.vertices[:, :2]).max() for pc in blade)
    assert reach < max(np.abs(pc.vertices[:, :2]).max() for pc in wall)
