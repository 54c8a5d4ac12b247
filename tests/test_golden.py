"""Output is byte-identical to the reviewed golden hashes (tests/golden/hashes.txt) for every category."""

import sys
from pathlib import Path

import pytest

import infmob_usd

sys.path.insert(0, str(Path(__file__).parent / "golden"))
import golden  # noqa: E402

STORED = golden.stored()


@pytest.mark.parametrize("category", infmob_usd.list_categories())
def test_files_match_the_golden_hashes(category):
    want = {k: v for k, v in STORED.items() if k[0] == category}
    assert want, f"{category} has no golden hashes: run `python tests/golden/golden.py --update` and commit them"
    diff = golden.differences(want, golden.current([category]))
    assert not diff, (f"{len(diff)} files differ from tests/golden/hashes.txt (if the change is meant, run "
                      "`python tests/golden/golden.py --update` and commit the reviewed diff):\n"
                      + "\n".join(diff[:40]))


def test_no_golden_hashes_for_unknown_categories():
    assert {k[0] for k in STORED} <= set(infmob_usd.list_categories())
