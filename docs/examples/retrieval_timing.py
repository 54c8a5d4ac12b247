"""Seconds per object with and without retrieval (warm library cache), A/B interleaved.

Usage: python docs/examples/retrieval_timing.py LIB [SEEDS] [save|nosave] [CATEGORIES]
(docs/benchmarks.md, "Part libraries"; CATEGORIES comma-separated, default the seven with handles)
"""
import statistics
import sys
import tempfile
import time

from infmob_usd import generate, save
from infmob_usd.partlib import load_library

lib = load_library(sys.argv[1])
SAVE = len(sys.argv) > 3 and sys.argv[3] == "save"
cats = ["kitchen_cabinet", "microwave", "beverage_fridge", "dishwasher", "oven", "pot", "pan"]
if len(sys.argv) > 4:
    cats = sys.argv[4].split(",")
seeds = range(int(sys.argv[2]) if len(sys.argv) > 2 else 4)
for c in cats:  # warm: imports, texture cache, library
    generate(c, 99, 16)
    generate(c, 99, 16, parts=lib, parts_share=1.0)
ratios, tot = [], {"plain": 0.0, "parts": 0.0}
for c in cats:
    for s in seeds:
        t = {}
        for how in ("plain", "parts", "parts", "plain"):
            t0 = time.perf_counter()
            o = generate(c, s, 16, **({"parts": lib, "parts_share": 1.0} if how == "parts" else {}))
            if SAVE:
                with tempfile.TemporaryDirectory() as d:
                    save(o, d)
            if how == "parts":
                obj = o
            t.setdefault(how, []).append(time.perf_counter() - t0)
        a, b = min(t["plain"]), min(t["parts"])
        tot["plain"] += a
        tot["parts"] += b
        ratios.append(b / a)
        print(f"{c:16} {s} plain {a:.3f}s parts {b:.3f}s x{b / a:.3f} retrieved {len(obj.retrieved)}", flush=True)
print(f"median ratio {statistics.median(ratios):.3f}; total plain {tot['plain']:.2f}s parts {tot['parts']:.2f}s"
      f" -> +{100 * (tot['parts'] / tot['plain'] - 1):.1f} %")
