"""Count joints a hand cannot move with their own effort, over seeds 0-2 of every category (or those named).

    python tools/operable_counts.py [CATEGORY ...]

Prints the movable joints whose friction is above their effort (per category, the worst ten), and the limited
joints whose effort is below what holds them somewhere in their range (friction, the most gravity pulls them back,
a return spring at its far limit: :func:`infmob_usd.effort.against_spring`), per role.
"""

from __future__ import annotations

import collections
import sys

import infmob_usd
from infmob_usd.effort import against_spring


def main(argv: list[str]) -> int:
    cats = argv or infmob_usd.list_categories()
    over, stall = collections.Counter(), collections.Counter()
    total = limited = 0
    rows = []
    for c in cats:
        for seed in range(3):
            obj = infmob_usd.generate(c, seed=seed, texture_size=16)
            for j in obj.movable_joints:
                total += 1
                if j.friction > j.effort:
                    over[c] += 1
                    rows.append((j.effort / j.friction, c, seed, j.name, j.role, j.friction, j.effort))
                if j.type != "continuous":
                    limited += 1
                    stall[j.role] += j.effort < against_spring(obj, j)
    print(f"{sum(over.values())} of {total} movable joints have friction > effort: {dict(sorted(over.items()))}")
    for _, c, seed, name, role, friction, effort in sorted(rows)[:10]:
        print(f"  {c} {seed} {name} ({role}): friction {friction:.4g}, effort {effort:.4g}")
    print(f"{sum(stall.values())} of {limited} limited joints: effort below friction + gravity back + spring;"
          f" by role {dict(sorted((r, n) for r, n in stall.items() if n))}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
