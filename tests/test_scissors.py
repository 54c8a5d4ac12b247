"""Scissors lie flat on the table and open about the pivot screw: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker
from helpers import part_points as _points

make = maker("scissors")


@pytest.mark.parametrize("design", ["office", "kitchen", "pinking", "embroidery"])
def test_lies_flat_and_opens_about_the_screw(design):
    _, bp = make(0, design=design)
    (j,) = [s for s in bp.joints if s.movable]
    assert (j.parent, j.child) == ("body", "blade")
    assert np.allclose(np.abs(j.dofs[0].axis), (0, 0, 1))  # turns in the table's plane: nothing lifts
    body, blade = _points(bp, "body"), _points(bp, "blade")
    # the lower half lies on the table; the upper half rides on the screw, its handle clear of the table
    # (a loop dragging on the table would hold the pair shut against a hand's push)
    assert abs(body[:, 2].min()) < 1e-6 and blade[:, 2].min() > 1e-3
    # closed at rest: the blades end together and their tips overlap across the pair
    end_a, end_b = body[body[:, 0] > body[:, 0].max() - 2e-3], blade[blade[:, 0] > blade[:, 0].max() - 2e-3]
    assert abs(body[:, 0].max() - blade[:, 0].max()) < 1e-3
    assert end_a[:, 1].min() <= end_b[:, 1].max() + 1e-6 and end_b[:, 1].min() <= end_a[:, 1].max() + 1e-6
    tip_b = blade[blade[:, 0].argmax()]
    opened = bp.poses({("blade", 0): j.dofs[0].upper})["blade"]
    moved = _points(bp, "blade", opened)
    # opening swings the blade's tip to +y and the finger loop away from the thumb loop (-y)
    assert moved[blade[:, 0].argmax(), 1] > tip_b[1] + 0.02
    assert moved[:, 1].min() < blade[:, 1].min() - 0.01
