"""The ``toggle`` joint role: a switch's bat or rocker, flipped or pressed by a fingertip, held where it is set by
its friction (no return spring), driven like a button."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from infmob_usd import effort
from infmob_usd import joints as J
from infmob_usd.interaction import action, part_class
from infmob_usd.physical import DYNAMICS, dynamics
from infmob_usd.springs import SPRINGS


def test_a_toggle_is_pressed_and_has_no_return_spring():
    spec = J.revolute("plate", "toggle_0", (0.0, 0.0, 0.05), (0.0, -1.0, 0.0), 0.0, 0.87, "toggle", None)
    bat = SimpleNamespace(type="revolute", role=spec.role, axis=spec.dofs[0].axis)  # as the model writes it
    assert action(bat) == "press"
    tip = np.array([[0.02, 0.0, 0.04], [0.0, 0.0, 0.05]])
    assert part_class(bat, "toggle", tip, spec.dofs[0].origin, False) == "hinge_knob"
    assert "toggle" not in SPRINGS  # bistable: no spring pulls it back to rest
    assert dynamics("toggle") is DYNAMICS["toggle"]
    assert effort.role("toggle") is effort.ROLES["toggle"] is not effort.ROLES["default"]
