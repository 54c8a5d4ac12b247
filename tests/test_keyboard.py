"""A keyboard's keycaps carry printed legends in a colour other than the caps': checked on the grounded
blueprint."""

from __future__ import annotations

from helpers import maker

make = maker("keyboard")


def test_the_keys_carry_printed_legends_that_contrast_with_the_caps():
    for seed in range(3):
        _, bp = make(seed)
        keys = [n for n in bp.parts if n.startswith("key_")]
        marked = [n for n in keys if any(pc.name == "legend" for pc in bp.parts[n].pieces)]
        assert len(marked) >= 0.9 * len(keys) - 1  # every key but the space bar
        legend = bp.materials["legend"].split(":")[1]
        assert legend not in bp.materials["keys"].split(":")[1].split("|"), seed
