"""A flip phone's lid and a slider phone's screen half uncover the keypad they guard, a desk phone's handset lifts
out of its cradle: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np

from helpers import maker

make = maker("phone")


def _points(bp, part):
    return np.vstack([pc.vertices for pc in bp.parts[part].pieces])


def _joint(bp, child):
    return next(s for s in bp.joints if s.child == child)


def _keys(bp, prefix):
    return [s for s in bp.joints if s.movable and s.child.startswith(prefix)]


def test_a_flip_phones_lid_opens_off_its_keypad_about_the_hinge_at_the_top():
    _, bp = make(0, design="flip")
    lid = _joint(bp, "lid").dofs[0]
    base = _points(bp, "body")
    assert lid.type == "revolute" and abs(lid.axis[1]) > 0.99 and lid.upper > np.radians(140)
    assert lid.origin[0] < base[:, 0].min() + 0.01  # the hinge at the far end: it opens away from the front
    keys = _keys(bp, "keypad_") + _keys(bp, "nav_keys_")
    assert len(_keys(bp, "keypad_")) == 12 and all(s.requires_open == "lid" for s in keys)
    closed = _points(bp, "lid")
    pose = bp.poses({("lid", 0): np.radians(90)})["lid"]
    opened = closed @ pose[:3, :3].T + pose[:3, 3]
    for s in keys:  # closed it lies over every key; at 90 degrees it stands clear of them
        k = _points(bp, s.child)
        assert closed[:, 2].max() > k[:, 2].max() and closed[:, 0].min() < k[:, 0].mean() < closed[:, 0].max()
        assert opened[:, 0].max() < k[:, 0].min()


def test_a_slider_phones_screen_half_slides_off_its_keypad():
    _, bp = make(0, design="slider")
    half = _joint(bp, "slider")
    d = half.dofs[0]
    assert d.type == "prismatic" and d.axis[0] < -0.99
    pad = [_points(bp, s.child) for s in _keys(bp, "keypad_")]
    assert len(pad) == 12 and all(s.requires_open == "slider" for s in _keys(bp, "keypad_"))
    front = _points(bp, "slider")[:, 0].max()
    assert front - d.upper < min(k[:, 0].min() for k in pad)  # slid up, it uncovers the whole pad
    assert all(s.parent == "slider" for s in _keys(bp, "nav_"))  # its navigation keys ride on it


def test_a_desk_phones_handset_lifts_out_of_its_cradle():
    _, bp = make(0, design="desk")
    hs = _joint(bp, "handset")
    assert hs.role == "lift_off" and np.allclose(hs.dofs[0].axis, (0, 0, 1)) and hs.dofs[0].upper >= 0.02
    assert _points(bp, "handset")[:, 1].mean() < 0  # on the left, seen from the front
    assert len(_keys(bp, "keypad_")) == 12 and 3 <= len(_keys(bp, "function_keys_")) <= 10
