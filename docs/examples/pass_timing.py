"""CPU seconds of each pass of generate + save, summed over a few objects, after one warm-up object per category.

Usage: python docs/examples/pass_timing.py [SEEDS] [CATEGORIES] [TEXTURE_SIZE]
(docs/benchmarks.md, "Speed"; CATEGORIES comma-separated, default the five kitchen ones; SEEDS: 0..SEEDS-1,
default 3; TEXTURE_SIZE default 512). CPU time (``time.process_time``), not wall time: on a shared machine it
moves far less with the load. Compare two checkouts by running it in each, alternately.
"""
import functools
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import infmob_usd.api as api
from infmob_usd import physical

seeds = range(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
cats = sys.argv[2].split(",") if len(sys.argv) > 2 else ["refrigerator", "oven", "dishwasher", "kitchen_cabinet",
                                                          "microwave"]
size = int(sys.argv[3]) if len(sys.argv) > 3 else 512
spent: Counter = Counter()


def _timed(module, name: str) -> None:
    f = getattr(module, name)

    @functools.wraps(f)
    def run(*args, **kwargs):
        t0 = time.process_time()
        try:
            return f(*args, **kwargs)
        finally:
            spent[name] += time.process_time() - t0

    setattr(module, name, run)


for name in ("rest_on_ground", "rest_on_stops", "ensure_gaps", "thicken_hulls", "limit_to_ground",
             "keep_meeting_gaps", "limit_to_clearance"):
    _timed(physical, name)  # api calls them through the module
for name in ("build", "assign_drives", "annotate", "write_object"):
    _timed(api, name)  # imported into api by name
with tempfile.TemporaryDirectory() as tmp:
    for c in cats:  # warm: imports, texture cache
        api.save(api.generate(c, seed=10_000, texture_size=size), Path(tmp) / "warm")
    spent.clear()
    t0, c0 = time.perf_counter(), time.process_time()
    for c in cats:
        for s in seeds:
            api.save(api.generate(c, seed=s, texture_size=size), Path(tmp) / "out")
    total = time.process_time() - c0
print(f"{len(cats) * len(seeds)} objects: CPU {total:.2f} s, wall {time.perf_counter() - t0:.2f} s")
for name, t in spent.most_common():
    print(f"  {name:20s} {t:6.2f} s  {100 * t / total:5.1f} %")
print(f"  {'(the rest)':20s} {total - sum(spent.values()):6.2f} s")
