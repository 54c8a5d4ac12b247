"""A DSLR's zoom ring drives its inner barrel out (coupled joints, the whole throw kept) and a compact's
telescoping lens stands out by both stages: checked on the grounded blueprint with the generated limits."""

from __future__ import annotations

import numpy as np

from categories.parts import cameras as K

from helpers import maker
from zoo import object_limits

make = maker("camera")


def _limited(**overrides):
    _, bp = make(0, **overrides)
    return object_limits("camera", 0, bp, **overrides)


def test_the_zoom_ring_drives_the_inner_barrel_its_whole_throw():
    bp = _limited(design="dslr", has_screen=False, has_door=False, reach=1.0)
    ring = next(j for j in bp.joints if j.child == "zoom_ring")
    barrel = next(j for j in bp.joints if j.child == "barrel")
    assert barrel.mimic is not None and barrel.mimic.leader == "zoom_ring"
    assert np.allclose(ring.dofs[0].axis, (1, 0, 0)) and np.allclose(barrel.dofs[0].axis, (1, 0, 0))
    assert ring.dofs[0].upper > 0.95 * K.ZOOM_TURN  # nothing cut the zoom short
    out = barrel.mimic.ratio * ring.dofs[0].upper
    assert abs(out - barrel.dofs[0].upper) < 1e-6 and out > 0.018  # an 18-55 zooms ~20 mm out


def test_a_two_stage_lens_stands_out_by_both_stages():
    bp = _limited(design="compact", has_inner_stage=True)
    stages = [j for j in bp.joints if j.child in ("barrel", "inner_barrel")]
    assert [j.parent for j in stages] == ["body", "barrel"]  # the inner stage rides in the outer
    q = {(j.child, 0): j.dofs[0].upper for j in stages}
    front = lambda q: max(bp.poses(q)["inner_barrel"][0, 3] + p.vertices[:, 0].max()  # noqa: E731
                          for p in bp.parts["inner_barrel"].pieces)
    assert front(q) - front({}) > 0.02  # two stages of 11-12 mm
