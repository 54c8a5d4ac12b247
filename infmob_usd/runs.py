"""Run ids and the temporary names they stamp: the only names a run ever removes.

A batch run (or one ``save``) writes objects under ``.NAME.infmob-PID-TOKEN-XXXX.tmp`` and moves
replaced folders to ``.NAME.infmob-PID-TOKEN-XXXX.old``; :func:`infmob_usd.batch.clean_partial` removes
only names of this shape whose run (PID) is no longer alive. Kept apart from the batch so the writers
can name their temporary folders without importing it.
"""

from __future__ import annotations

import os
import re
import secrets

TEMP_TAG = "infmob"
TEMP_NAME = re.compile(r"^\.(?P<name>[^/]+?)\.infmob-(?P<pid>\d+)-(?P<token>[0-9a-f]{8})-[A-Za-z0-9_]*\.(?:tmp|old)$")


def new_run_id() -> str:
    """``PID-TOKEN``: the id every temporary name of one run (or one ``save``) carries."""
    return f"{os.getpid()}-{secrets.token_hex(4)}"


def temp_prefix(name: str, run_id: str) -> str:
    """Prefix of a temporary folder or file of ``name`` made by run ``run_id``."""
    return f".{name}.{TEMP_TAG}-{run_id}-"
