"""Pepper grinder: what a user relies on beyond the contract tests: a manual mill's head turns without stop to grind
and lifts off to refill; a pair's mills lift out of their tray, one holding pepper and the other salt; a battery
mill's button presses down into its cap against a return spring."""

from __future__ import annotations

import numpy as np

from tests.helpers import maker

make = maker("pepper_grinder")


def test_manual_head_turns_and_lifts_off():
    _, bp = make(0, design="manual", has_finial=True)
    j = next(j for j in bp.joints if j.child == "head")
    kinds = sorted(d.type for d in j.dofs)
    assert kinds == ["continuous", "prismatic"] and j.role == "lift_off"
    assert all(np.allclose(d.axis, (0, 0, 1)) for d in j.dofs)  # about and along the mill's axis
    finial = next(j for j in bp.joints if j.child == "finial")
    assert finial.parent == "head" and finial.kind == "revolute" and finial.dofs[0].upper > np.pi


def test_pair_mills_lift_out_with_pepper_and_salt():
    _, bp = make(0, design="pair")
    for k, contents in enumerate(("pepper", "salt")):
        j = next(j for j in bp.joints if j.child == f"body_{k}")
        assert j.parent == "base" and j.kind == "prismatic" and np.allclose(j.dofs[0].axis, (0, 0, 1))
        assert j.role == "lift_off"
        assert any(pc.material == contents for pc in bp.parts[f"body_{k}"].pieces)
        head = next(j for j in bp.joints if j.child == f"head_{k}")
        assert head.parent == f"body_{k}" and head.kind == "continuous"


def test_battery_mill_button_presses_into_its_cap():
    _, bp = make(0, design="electric", has_button=True)
    j = next(j for j in bp.joints if j.child == "button")
    assert j.parent == "cap" and j.kind == "prismatic" and j.role == "button"
    assert np.allclose(j.dofs[0].axis, (0, 0, -1)) and 0.001 <= j.dofs[0].upper <= 0.003
