"""Printer: what a user relies on beyond the contract tests: the cassette slides out of the front holding a stack
of A4 / Letter paper; doors and trays on the front fold down forward about their bottom edge; an all-in-one's
scanner lid lifts at the back and carries the document feeder, whose cover opens with it; the output tray's
extender pulls out only once the tray is down."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import maker

make = maker("printer")


def _bounds(bp, part):
    b = np.array([pc.bounds for pc in bp.parts[part].pieces])
    return b[:, 0].min(0), b[:, 1].max(0)


@pytest.mark.parametrize("design", ["inkjet", "laser", "all_in_one"])
def test_cassette_and_front_doors(design):
    _, bp = make(0, design=design)
    joints = {j.child: j for j in bp.joints}
    cassette = joints["cassette"]
    assert cassette.kind == "prismatic" and np.allclose(cassette.dofs[0].axis, (1, 0, 0))
    assert cassette.dofs[0].upper > 0.15  # pulled out far enough to load paper
    paper = [pc for pc in bp.parts["cassette"].pieces if pc.material == "paper"]
    (size,) = [np.ptp(pc.vertices, axis=0) for pc in paper]
    assert size[0] <= 0.297 + 1e-9 and size[1] <= 0.216 + 1e-9 and size[2] > 0.002
    front = _bounds(bp, "body")[1][0]  # the front face (a display stands 1 mm proud of it)
    for name in ("door", "output_tray"):
        if name not in joints:
            continue
        j = joints[name]
        lo, hi = _bounds(bp, name)
        assert j.kind == "revolute" and np.allclose(j.dofs[0].axis, (0, 1, 0))  # top falls forward (+X)
        assert j.dofs[0].origin[2] == pytest.approx(lo[2], abs=0.003) and j.dofs[0].origin[0] >= front - 0.005


def test_scanner_lid_carries_the_feeder_and_the_extender_needs_the_tray_down():
    _, bp = make(0, design="all_in_one", has_feeder=True, has_extender=True)
    joints = {j.child: j for j in bp.joints}
    lid, cover = joints["scanner_lid"], joints["adf_cover"]
    assert lid.parent == "body" and cover.parent == "scanner_lid"
    lo, hi = bp.bounds()
    assert lid.dofs[0].origin[0] == pytest.approx(lo[0], abs=0.005)  # hinged along the back edge
    assert np.allclose(lid.dofs[0].axis, (0, -1, 0))  # the front lifts
    ext = joints["extender"]
    assert ext.parent == "output_tray" and ext.requires_open == "output_tray"
