"""A remote's keys are a keypad on its top face that press down against their springs, its flip cover guards the
keys under it, and its battery door slides out of the underside: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np

from helpers import maker

make = maker("remote")


def _points(bp, part):
    return np.vstack([pc.vertices for pc in bp.parts[part].pieces])


def _keys(bp):
    return [s for s in bp.joints if s.movable and bp.parts[s.child].label == "button"]


def test_a_tv_remote_has_a_numeric_keypad_of_keys_pressed_down():
    _, bp = make(0, design="tv", has_numpad=True, has_colour_keys=True)
    keys = _keys(bp)
    assert 10 <= len(keys) <= 50
    top = _points(bp, "body")[:, 2].max()
    for s in keys:
        d = s.dofs[0]
        assert d.type == "prismatic" and s.role == "button"
        assert np.allclose(d.axis, (0, 0, -1)) and 0.0008 <= d.upper <= 0.002  # a rubber dome's 1-1.5 mm
        assert _points(bp, s.child)[:, 2].min() < top  # let into the face, not floating on it
    # 1-9 and 0: three columns of keys in rows along the remote
    pad = np.array([_points(bp, s.child).mean(0) for s in keys if s.child.startswith("numpad_")])
    assert len(pad) >= 10
    assert len(np.unique(np.round(pad[:9, 1], 4))) == 3 and len(np.unique(np.round(pad[:9, 0], 4))) == 3
    assert {s.child.split("_")[0] for s in keys} >= {"top", "numpad", "volume", "navigation", "colour"}


def test_the_keys_under_an_ac_remotes_cover_wait_for_it_to_open():
    _, bp = make(0, design="ac")
    cover = next(s for s in bp.joints if s.child == "cover")
    assert cover.dofs[0].type == "revolute" and cover.dofs[0].upper > np.radians(150)
    under = [s for s in _keys(bp) if s.child.startswith("ac_covered_")]
    assert 6 <= len(under) <= 12 and all(s.requires_open == "cover" for s in under)
    # closed, the cover lies over every key it guards
    lid = bp.parts["cover"].pieces[0].vertices  # its plate
    for s in under:
        k = _points(bp, s.child)
        assert lid[:, 2].min() > k[:, 2].max() and lid[:, 0].min() < k[:, 0].min() < k[:, 0].max() < lid[:, 0].max()


def test_the_battery_door_slides_out_backwards_from_the_underside():
    for design in ("tv", "ac", "presenter"):
        _, bp = make(1, design=design)
        door = next(s for s in bp.joints if s.child == "battery_door")
        d = door.dofs[0]
        assert d.type == "prismatic" and d.axis[0] < -0.99 and d.upper > 0.02
        assert _points(bp, "battery_door")[:, 2].max() < 0.005  # in the underside
