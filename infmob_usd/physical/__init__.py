"""Physical plausibility passes applied once, for every category.

* :func:`rest_on_ground` moves the object so its lowest point at rest is z = 0 (or its ``elevation``)
  (:mod:`.ground`).
* :func:`rest_on_stops` makes every passive hinge neutral under gravity or pressed onto its
  rest stop (picking the side of a two-sided range, or adding a counterweight heel) (:mod:`.stops`).
* :func:`ensure_gaps` erodes moving collision hulls that come too close to their parent (:mod:`.gaps`).
* :func:`clear_bores` cuts a shaft's collision hull out of the bore of a link it only turns and slides in
  through a chain of joints on one axis (a push-to-turn knob), a pair PhysX misreads (:mod:`.bores`).
* :func:`square_rims` cuts a thin hull's chamfer or flare at a face that looks onto a parallel face of another
  link's hull across a few millimetres, at rest or as a slide carries one over the other, which PhysX's contact
  manifold misreads as a deep contact (:mod:`.rims`).
* :func:`keep_meeting_gaps` erodes a hinged part's collision hulls that pass within :data:`MEETING_GAP` of an
  independently moving neighbour (the twin leaf of a double door) over its swing (:mod:`.meeting`).
* :func:`limit_to_ground` shortens limits so nothing goes below the ground (:mod:`.ground`).
* :func:`limit_to_clearance` shortens limits so moving parts never meet what they may not touch,
  from rest and from the all-open state, and orders parts that cannot pass each other open
  (``requires_closed``) (:mod:`.clearance`, on the sweeps of :mod:`.sweep` and the hull tests
  of :mod:`.hulls`).
* :data:`DYNAMICS` gives passive joint dynamics per joint role, so doors stay
  where they are left and knobs do not spin freely (:mod:`.passive`).
"""

from .bores import clear_bores
from .clearance import ALL_FRACTIONS, clearance_limits, limit_to_clearance
from .gaps import MIN_HULL_WIDTH, ensure_gaps, gap_size, thicken_hulls
from .ground import GROUND_TOL, limit_to_ground, rest_on_ground
from .hulls import CLEARANCE, CONTACT_VOLUME
from .meeting import MEETING_GAP, keep_meeting_gaps
from .passive import DYNAMICS, Dynamics, dynamics
from .rims import square_rims
from .stops import BALANCED, GRAVITY, HEEL_SECTION, gravity_torque, rest_on_stops
from .sweep import PARENT_GROWTH, SWEEP_SAGITTA

__all__ = [
    "ALL_FRACTIONS", "BALANCED", "CLEARANCE", "CONTACT_VOLUME", "DYNAMICS", "Dynamics", "GRAVITY",
    "GROUND_TOL", "HEEL_SECTION", "PARENT_GROWTH", "SWEEP_SAGITTA", "clearance_limits", "dynamics",
    "ensure_gaps", "gap_size", "gravity_torque", "limit_to_clearance", "limit_to_ground", "rest_on_ground",
    "rest_on_stops", "MIN_HULL_WIDTH", "thicken_hulls", "MEETING_GAP", "keep_meeting_gaps",
    "square_rims", "clear_bores",
]
