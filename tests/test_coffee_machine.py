"""The coffee machine category's looks that a buyer checks first: where the coffee comes out and where a
capsule goes."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker

make = maker("coffee_machine")


def _box(pieces):
    pts = np.vstack([pc.vertices for pc in pieces])
    return pts.min(0), pts.max(0)


@pytest.mark.parametrize("seed", [0, 3, 7])
def test_a_pod_machine_has_an_outlet_over_its_drip_tray(seed):
    """A capsule machine's spout hangs under the head, over the drip tray, and shows a dark orifice."""
    _, bp = make(seed, design="pod")
    lo, hi = _box(bp.parts["drip_tray"].pieces)
    under = [pc for pc in bp.parts["body"].pieces
             if pc.vertices[:, 2].min() > hi[2] + 0.04 and np.all(pc.vertices[:, :2].min(0) > lo[:2])
             and np.all(pc.vertices[:, :2].max(0) < hi[:2])]
    heads = [pc for pc in bp.parts["body"].pieces if pc.material == "body"]
    head_bottom = min(pc.vertices[:, 2].min() for pc in heads if pc.vertices[:, 2].min() > hi[2])
    spout = [pc for pc in under if pc.vertices[:, 2].min() < head_bottom - 0.015]
    assert spout, "no spout hangs 15 mm or more under the head over the tray"
    assert any(pc.material != "body" for pc in spout)


@pytest.mark.parametrize("seed", [0, 3])
def test_a_pod_machine_shows_a_capsule_bay_under_its_lid(seed):
    """Opening the lid shows a round capsule pocket (a rim and a dark middle) on the head's top, under the lid."""
    _, bp = make(seed, design="pod")
    lo, hi = _box(bp.parts["lid"].pieces)
    top = max(pc.vertices[:, 2].max() for pc in bp.parts["body"].pieces if pc.material == "body")
    bay = [pc for pc in bp.parts["body"].pieces if pc.vertices[:, 2].min() >= top - 0.001
           and np.all(pc.vertices[:, :2].min(0) >= lo[:2]) and np.all(pc.vertices[:, :2].max(0) <= hi[:2])]
    assert {pc.material for pc in bay} >= {"trim", "lid"}
    plate = max(pc.vertices[:, 2].min() for pc in bp.parts["lid"].pieces)  # the lid's plate, over its lip
    assert all(pc.vertices[:, 2].max() < plate for pc in bay)  # the closed lid clears it
    assert max(np.ptp(pc.vertices[:, 1]) for pc in bay) >= 0.04  # a 37 mm capsule fits
