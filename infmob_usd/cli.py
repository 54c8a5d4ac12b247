"""The ``infmob`` command line: list, params, generate, scene, parts, fuzz, validate, preview, stats, gallery, textures,
bench, export (docs/cli.md)."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from .errors import InfmobError, OutputError

DESCRIPTION = "Procedural, simulation-ready articulated objects as OpenUSD + URDF."


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="infmob", description=DESCRIPTION)
    sub = ap.add_subparsers(dest="command", required=True, metavar="COMMAND")

    sub.add_parser("list", help="print every category id, one per line")

    p = sub.add_parser("params", help="print a category's parameter schema and growth rules")
    p.add_argument("category", help="a category id (infmob list)")
    # in this order: `infmob --help` lists the commands so
    for add in (_generate_command, _scene_command, _parts_command, _fuzz_command, _validate_command, _preview_command,
                _stats_command, _gallery_command, _textures_command, _bench_command, _export_command):
        add(sub)
    return ap


def _generate_command(sub) -> None:
    """Add the ``infmob generate`` subcommand and its options to ``sub``."""
    g = sub.add_parser("generate", help="generate objects: DIR/CATEGORY/CATEGORY_SSSSSS/ per seed")
    g.add_argument("category", help="a category id, a comma list of them, or `all`")
    g.add_argument("--count", type=int, default=1, help="objects per category (seeds S..S+N-1); default 1")
    g.add_argument("--seed", type=int, default=0, help="first seed S; default 0")
    g.add_argument("--out", default="infmob_out", help="output folder DIR; default ./infmob_out")
    g.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a parameter (repeatable); see `infmob params CATEGORY`")
    g.add_argument("--texture-size", type=int, default=512, metavar="PX",
                   help="texture edge in pixels, a power of two 16..4096; default 512")
    g.add_argument("--workers", type=int, default=None,
                   help="parallel worker processes; default: all cores")
    g.add_argument("--backend", choices=("process", "ray"), default="process",
                   help="process pool (default) or a Ray cluster (pip install -e '.[ray]')")
    g.add_argument("--address", default=None, help="Ray cluster address (with --backend ray)")
    g.add_argument("--overwrite", action="store_true",
                   help="regenerate objects that already exist (default: skip them, resuming a run)")
    g.add_argument("--formats", default="usd,urdf,mjcf", metavar="LIST",
                   help="comma list of usd, urdf, mjcf, glb (binary glTF with PBR materials, for web viewers),"
                   " isaac (the USD in Isaac Sim's layout, instead of usd); default usd,urdf,mjcf")
    g.add_argument("--usd-layout", choices=("payload", "isaac"), default="payload",
                   help="payload (default: payload/ with one physics layer) or isaac (Isaac Sim's asset structure:"
                   " payloads/base, geometries, instances, materials, physics and a PhysX / Newton / MuJoCo variant"
                   " set each); isaac is the same as listing isaac instead of usd in --formats")
    g.add_argument("--preview", action="store_true",
                   help="also render each object's thumbnail (preview.png + sweep.gif in its folder)")
    g.add_argument("--wait", action="store_true",
                   help="if another run is writing to DIR, wait for it to finish (default: fail at once)")

    g.add_argument("--parts", default=None, metavar="LIB",
                   help="a part library (infmob parts import / export-builtin): retrievable parts may be its meshes")
    g.add_argument("--parts-share", type=float, default=None, metavar="P",
                   help="with --parts: probability in [0, 1] that a retrievable part is retrieved; default 0.5")


def _export_command(sub) -> None:
    """Add the ``infmob export`` subcommand and its options to ``sub``."""
    from .export import FIRST_ID, FORMATS

    ex = sub.add_parser("export", help="a folder of generated objects as a dataset: PartNet-Mobility, GAPartNet or"
                        " CAGE layout, splits and DATASET.md",
                        description="Export the objects under SRC (folders written by `infmob generate`) in the layout"
                        " learning code reads (docs/export.md). Streams through a process pool; an interrupted run"
                        " resumes; DIR/DATASET.md records counts, joint statistics, the command and the licence.")
    ex.add_argument("format", choices=FORMATS, metavar="FORMAT", help=f"one of {', '.join(FORMATS)}")
    ex.add_argument("src", metavar="SRC", help="a folder of generated objects (infmob generate --out SRC)")
    ex.add_argument("--out", required=True, metavar="DIR", help="the dataset folder (not inside SRC)")
    ex.add_argument("--split", default=None, metavar="NAME=FRAC,...",
                    help="split per category, e.g. train=0.8,val=0.1,test=0.1 (DIR/splits.json)")
    ex.add_argument("--seed", type=int, default=0, help="seed of the split; default 0")
    ex.add_argument("--workers", type=int, default=None, help="worker processes; default: all cores")
    ex.add_argument("--first-id", type=int, default=FIRST_ID,
                    help=f"first numeric object id (ids are kept across runs); default {FIRST_ID}")
    ex.add_argument("--overwrite", action="store_true", help="re-export objects already exported (default: resume)")
    ex.add_argument("--wait", action="store_true",
                    help="if another run is writing to DIR, wait for it to finish (default: fail at once)")


def cmd_export(args) -> int:
    from .export import export

    if not 0 <= args.first_id <= 10**12:
        return _fail(f"--first-id must be 0..10^12, got {args.first_id}")
    command = " ".join(["infmob", *(sys.argv[1:] if sys.argv and sys.argv[0].endswith("infmob") else
                                    ["export", args.format, args.src, "--out", args.out])])
    res = export(args.format, args.src, args.out, split=args.split, seed=args.seed, workers=_workers(args.workers),
                 overwrite=args.overwrite, first_id=args.first_id, command=command, wait_lock=args.wait)
    splits = ", ".join(f"{k} {v}" for k, v in res["splits"].items())
    print(f"{res['objects']} objects in {args.out} ({res['exported']} exported now"
          f"{'; ' + splits if splits else ''}); see {os.path.join(args.out, 'DATASET.md')}")
    return 0


def _scene_command(sub) -> None:
    """Add the ``infmob scene`` subcommand and its options to ``sub``."""
    from .scenes import kinds

    sc = sub.add_parser("scene", help="compose rooms of generated objects: DIR/KIND_SSSSSS/scene.usda per seed",
                        description="Compose a room (kitchen, ...) of generated articulated objects as one USD stage"
                        " (scene.usda referencing each object's folder), scene.json and a MuJoCo scene.xml.")
    sc.add_argument("kind", help=f"a scene kind: {', '.join(kinds())}")
    sc.add_argument("--seed", type=int, default=0, help="first seed S; default 0")
    sc.add_argument("--count", type=int, default=1, help="scenes (seeds S..S+N-1); default 1")
    sc.add_argument("--out", default="infmob_out", help="output folder DIR; default ./infmob_out")
    sc.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="override a scene parameter (repeatable); see --params")
    sc.add_argument("--texture-size", type=int, default=256, metavar="PX",
                    help="texture edge of every object, a power of two 16..4096; default 256")
    sc.add_argument("--workers", type=int, default=None,
                    help="processes; default: all cores. With at least as many scenes as workers, scenes are made"
                    " in parallel; else one at a time, each one's objects in parallel")
    sc.add_argument("--params", action="store_true", help="print the kind's parameters and growth rules, and exit")
    sc.add_argument("--preview", action="store_true",
                    help="also render preview.png (at rest) and preview_open.png (every joint open) in each scene")


def _parts_command(sub) -> None:
    """Add the ``infmob parts`` subcommand and its options to ``sub``."""
    pa = sub.add_parser("parts", help="part libraries: import meshes, export the built-in parts, check placement",
                        description="A part library holds part meshes with support points, scale policy and"
                        " convex pieces (format: docs/parts.md). Generate with it:"
                        " infmob generate CAT --parts LIB --parts-share P.")
    psub = pa.add_subparsers(dest="parts_command", required=True)
    pi = psub.add_parser("import", help="import PartNet-Mobility objects or a folder of meshes with labels.csv")
    pi.add_argument("src", metavar="SRC", help="a PartNet-Mobility object folder, a folder of them, or a folder of"
                    " OBJ/GLB/PLY files with labels.csv (columns file,label[,units,up,front,source,licence])")
    pi.add_argument("--out", required=True, metavar="LIB", help="the new library folder (must not exist or be empty)")
    pi.add_argument("--units", default=None, choices=("m", "cm", "mm"),
                    help="unit of the meshes; default: inferred from plausible sizes of their labels' parts"
                    " (refused when ambiguous)")
    pi.add_argument("--up", default="y", help="the meshes' up axis (PartNet-Mobility: y, the default)")
    pi.add_argument("--licence", default="", help="licence to record (default: the source's terms)")
    pi.add_argument("--labels", default=None, metavar="CSV", help="labels CSV (default SRC/labels.csv)")
    pe = psub.add_parser("export-builtin", help="write the project's procedural parts as a library")
    pe.add_argument("out", metavar="LIB", help="the new library folder (must not exist or be empty)")
    pc = psub.add_parser("check", help="gap and penetration at the support points: bounding-box vs support placement")
    pc.add_argument("lib", metavar="LIB", help="a part library folder")
    pc.add_argument("--placements", type=int, default=100, help="placements on drawn procedural parts; default 100")
    pc.add_argument("--seed", type=int, default=0, help="seed of the drawn procedural parts; default 0")
    pc.add_argument("--json", action="store_true", help="print JSON instead of a table")
    pc.add_argument("--as-drawn", action="store_true",
                    help="only pairs generation would draw (the procedural box within the part's scale policy)")


def _fuzz_command(sub) -> None:
    """Add the ``infmob fuzz`` subcommand and its options to ``sub``."""
    fz = sub.add_parser("fuzz", help="generate N random (category, seed, overrides) objects and validate each",
                        description="Property test for long runs: N draws of a category, a seed and random valid"
                        " overrides (schema extremes included). Each draw must either be rejected up front with a"
                        " ParameterError or give an object that passes the USD checks and SAPIEN `reach`. Prints"
                        " every crash and invalid object with the command that reproduces it; exit 1 if any.")
    fz.add_argument("n", type=int, metavar="N", help="number of draws")
    fz.add_argument("--seed", type=int, default=0, help="seed of the draws (same seed, same draws); default 0")
    fz.add_argument("--workers", type=int, default=None, help="worker processes; default: all cores")
    fz.add_argument("--categories", default="all", help="comma list or `all` (default)")
    fz.add_argument("--texture-size", type=int, default=16, metavar="PX", help="texture edge; default 16")
    fz.add_argument("--usd-only", action="store_true", help="skip the SAPIEN checks (faster)")
    fz.add_argument("--out", default=None, help="keep the objects that fail in this folder (default: keep none)")


def _validate_command(sub) -> None:
    """Add the ``infmob validate`` subcommand and its options to ``sub``."""
    v = sub.add_parser("validate", help="check object folders: USD, URDF agreement, SAPIEN (and --sim physics)",
                       description="Validate object folders. Default: USD checks + SAPIEN (the URDF loads, every "
                       "movable joint reaches both limits, from rest and from the all-open state). --sim adds "
                       "rest under gravity, ground, "
                       "self-collision, parent/child intersection, ManiSkill loading and the MJCF in MuJoCo "
                       "(rest, each joint pushed with its effort, contacts at rest). Checks of a format the "
                       "folder lacks are reported as skipped.")
    v.add_argument("paths", nargs="+", metavar="PATH",
                   help="an object folder or a folder of them (with --sweep: category ids, or `all`)")
    v.add_argument("--sim", action="store_true", help="add the physical-plausibility checks")
    v.add_argument("--robot", action="store_true",
                   help="add the robot check: a floating Panda gripper in SAPIEN grasps every target of the"
                   " folder's annotations.json and opens it along its path (one result per joint; why it failed)")
    v.add_argument("--usd-only", action="store_true", help="skip every simulator check")
    v.add_argument("--no-mass", action="store_true",
                   help="skip the mass check (on by default: total and moving-part masses within the ranges of"
                   " real products, validate/mass_ranges.csv)")
    v.add_argument("--mass", action="store_true", help=argparse.SUPPRESS)  # the default since the check passes
    v.add_argument("--simready", action="store_true",
                   help="add NVIDIA's validators: SimReady Robotics-Prop 4.0.0, Robot-Body 3.0.0 FET_024/FET_022,"
                   " omniverse-asset-validator defaults (pip install -e '.[simready]')")
    v.add_argument("--report", metavar="FILE", help="write a JSON report of every check to FILE")
    v.add_argument("--sweep", type=int, metavar="N",
                   help="generate seeds 0..N-1 of each category given as PATH into a temporary folder"
                   " (or --out) and validate them; prints pass rates")
    v.add_argument("--out", help="with --sweep: keep the generated objects in this folder")
    v.add_argument("--texture-size", type=int, default=64, metavar="PX",
                   help="with --sweep: texture size of the generated objects; default 64")
    v.add_argument("--workers", type=int, default=None,
                   help="parallel worker processes (generation with --sweep, and validation); default: all cores")
    v.add_argument("--verbose", "-v", action="store_true", help="print every check, not only failures")


def _preview_command(sub) -> None:
    """Add the ``infmob preview`` subcommand and its options to ``sub``."""
    pv = sub.add_parser("preview", help="render thumbnails, joint-sweep GIFs or a contact sheet (CPU, no display)",
                        description="Render each object folder at rest beside itself with its joints ~70% open"
                        " (preview.png) and a GIF sweeping each movable joint (sweep.gif); or with --sheet DIR one"
                        " contact sheet of every object under DIR. Needs a Vulkan device: on a CPU machine Mesa >= 25"
                        " lavapipe (see docs/cli.md, 'preview').")
    from .validate.preview import add_arguments as _preview_arguments

    _preview_arguments(pv)


def _stats_command(sub) -> None:
    """Add the ``infmob stats`` subcommand and its options to ``sub``."""
    st = sub.add_parser("stats", help="dataset statistics: joint counts, kinds, tree depth, tree edit distance")
    st.add_argument("folder", metavar="DIR", nargs="?", help="a folder of generated objects")
    st.add_argument("--grammar", metavar="CATEGORIES", default=None,
                    help="instead of DIR: the same figures for seeds --seed.. of --count objects per category, from "
                         "the grown blueprints without generating files (seconds instead of an hour for 22 x 100)")
    st.add_argument("--count", type=int, default=100, help="with --grammar: objects per category; default 100")
    st.add_argument("--seed", type=int, default=0, help="with --grammar: first seed; default 0")
    st.add_argument("--json", action="store_true", help="print JSON instead of a table")
    st.add_argument("--max-pairs", type=int, default=2000,
                    help="at most this many (seeded, sampled) object pairs per group for mean TED; default 2000")


def _gallery_command(sub) -> None:
    """Add the ``infmob gallery`` subcommand and its options to ``sub``."""
    ga = sub.add_parser("gallery", help="a static HTML gallery of DIR: cards, filters, 3D viewer, joint sliders, stats",
                        description="Write a self-contained site (no internet, opens from file://) showing every"
                        " object under DIR as a card, a three.js viewer with one slider per movable joint, and"
                        " the statistics of `infmob stats` as charts. Missing thumbnails are rendered (Vulkan) or"
                        " shown as placeholders.")
    from .validate.gallery import add_arguments as _gallery_arguments

    _gallery_arguments(ga)


def _textures_command(sub) -> None:
    """Add the ``infmob textures`` subcommand and its options to ``sub``."""
    tx = sub.add_parser("textures", help="build the texture library cache ahead of a large run",
                        description="Every look an object can wear is one of a finite library (16 per palette"
                        " variant of each material family); its PNG maps are made once and cached on disk in"
                        " $INFMOB_USD_CACHE (default ~/.cache/infmob-usd; `off` disables it). Generation fills the"
                        " cache as it goes; this command fills it up front, in parallel, e.g. on a shared folder"
                        " before a cluster run.")
    tx.add_argument("--texture-size", type=int, default=512, metavar="PX",
                    help="texture edge in pixels, a power of two 16..4096; default 512")
    tx.add_argument("--family", default=None, metavar="SPEC",
                    help="only this family (e.g. wood or plastic:black|white); default: all")
    tx.add_argument("--workers", type=int, default=None, help="worker processes; default: all cores")


def _bench_command(sub) -> None:
    """Add the ``infmob bench`` subcommand and its options to ``sub``."""
    b = sub.add_parser("bench", help="benchmark: seconds per object by stage, memory, parallel efficiency")
    b.add_argument("--categories", default="all", help="comma list or `all` (default)")
    b.add_argument("--count", type=int, default=10, help="objects per category; default 10")
    b.add_argument("--workers", type=int, default=None,
                   help="workers for the parallel run (1..1024); default: all cores")
    b.add_argument("--texture-size", type=int, default=512, metavar="PX", help="texture edge in pixels; default 512")
    b.add_argument("--cold", action="store_true",
                   help="every timed object starts from an empty texture cache (no library, no throughput runs)")
    b.add_argument("--json", action="store_true", help="print JSON instead of a table")


def _fail(message: str) -> int:
    print(f"infmob: error: {message}", file=sys.stderr)
    return 2


def cmd_list(args) -> int:
    from .api import list_categories

    print("\n".join(list_categories()))
    return 0


def cmd_params(args) -> int:
    from .api import get_category

    cat = get_category(args.category)
    print(f"{args.category}: {cat.doc}\n")
    print(cat.schema.table())
    print("\ngrowth rules:")
    print(cat.rules())
    return 0


MAX_COUNT = 1_000_000
"""Most objects per category in one command (one folder of a million objects is already ~10 TB)."""

MAX_WORKERS = 1024
"""Most worker processes (one per core of the largest machines; more only thrash, and each is forked up front)."""


def _workers(value: int | None, jobs: int | None = None, what: str = "objects") -> int:
    """``--workers`` checked (1..MAX_WORKERS; default: all cores) and capped at the number of ``jobs``,
    saying so when the user asked for more: a worker without a job is a forked process for nothing."""
    n = value if value is not None else (os.cpu_count() or 1)
    if not 1 <= n <= MAX_WORKERS:
        raise InfmobError(f"--workers must be 1..{MAX_WORKERS}, got {n}")
    if jobs is not None and n > max(jobs, 1):
        if value is not None:
            print(f"infmob: --workers {n} capped at {max(jobs, 1)}, the number of {what}", file=sys.stderr)
        n = max(jobs, 1)
    return n


def _categories(spec: str) -> list[str]:
    from .api import get_category, list_categories

    if spec.strip() == "all":
        return list_categories()
    names = list(dict.fromkeys(c.strip() for c in spec.split(",") if c.strip()))
    if not names:
        raise InfmobError(f"no category in {spec!r}; give a category id, a comma list of them, or `all`"
                          " (see `infmob list`)")
    for name in names:
        get_category(name)
    return names


def _out_dir(path: str) -> Path:
    """The ``--out`` folder, created (after every other argument was checked) and writable."""
    from .layers import check_output_dir

    if not path.strip() or any(ord(c) < 32 or ord(c) == 127 for c in path):
        raise OutputError(f"--out {path!r} is empty or has control characters (a newline?); give a plain folder name")
    return check_output_dir(Path(path))


def _overrides(categories: list[str], assignments: list[str]) -> dict:
    """Parsed ``--set`` values, checked against every category's schema (naming the one that rejects them)."""
    from .api import get_category
    from .errors import ParameterError
    from .params import parse_assignment

    overrides = dict(parse_assignment(s) for s in assignments)
    for category in categories:
        try:
            get_category(category).schema.validate(overrides)
        except ParameterError as e:
            lacking = [c for c in categories
                       if any(name not in get_category(c).schema.names for name in overrides)]
            if len(categories) > 1 and lacking:
                names = ", ".join(sorted({n for c in lacking for n in overrides
                                          if n not in get_category(c).schema.names}))
                raise ParameterError(f"--set {names}: not a parameter of {', '.join(lacking)}; generate only"
                                     f" categories that have it (see `infmob params CATEGORY`)") from None
            raise ParameterError(f"{category}: {e}") from None
    return overrides


class Terminated(SystemExit):
    """SIGTERM in the command line: unwinds like Ctrl-C (every ``finally`` removes our temporary files and
    stops our workers), then :func:`main` prints one line and exits 143."""


def _on_sigterm(signum, frame):
    raise Terminated(128 + signum)


def _unraisable(hook):
    """A ``sys.unraisablehook`` that does not let SIGTERM be lost: a signal landing in code whose exceptions
    Python only reports (an ``os.fork`` callback such as logging's lock release, a ``__del__``) is sent again
    a moment later from a thread, so it is raised where it can unwind; anything else goes to ``hook``."""
    import threading

    def on_unraisable(unraisable):
        if isinstance(unraisable.exc_value, Terminated):
            threading.Timer(0.05, os.kill, (os.getpid(), unraisable.exc_value.code - 128)).start()
        else:
            hook(unraisable)
    return on_unraisable


def cmd_generate(args) -> int:
    from .api import check_texture_size
    from .batch import Job, run_batch
    from .layers import parse_formats
    from .seeding import MAX_SEED

    formats = parse_formats(args.formats)
    if args.usd_layout == "isaac" and "usd" in formats:
        formats = parse_formats(["isaac" if f == "usd" else f for f in formats])
    if args.preview and "urdf" not in formats:
        return _fail("--preview renders the URDF; add urdf to --formats")
    categories = _categories(args.category)
    overrides = _overrides(categories, args.set)  # fail before anything is written
    check_texture_size(args.texture_size)
    if args.count < 1 or args.count > MAX_COUNT:
        return _fail(f"--count must be 1..{MAX_COUNT} (objects per category in one run), got {args.count}")
    if args.seed < 0 or args.seed + args.count - 1 > MAX_SEED:
        got = str(args.seed) if len(str(args.seed)) <= 24 else f"a {len(str(args.seed))}-digit number"
        return _fail(f"--seed must be 0..{MAX_SEED} (and --seed + --count - 1 too), got {got}")
    workers = _workers(args.workers, len(categories) * args.count)
    if args.address and args.backend != "ray":
        return _fail("--address is only used with --backend ray; add --backend ray or drop --address")
    if args.backend == "ray":
        from .batch import check_ray_address

        check_ray_address(args.address)  # seconds, not the 20 s ray.init retries for
    parts, share = None, 0.5
    if args.parts_share is not None and args.parts is None:
        return _fail("--parts-share needs --parts LIB")
    if args.parts is not None:
        from .api import check_share
        from .partlib import load_library

        share = check_share(args.parts_share if args.parts_share is not None else 0.5)
        parts = str(Path(load_library(args.parts).root).resolve())  # a bad library fails before anything is written
    if args.backend == "ray":
        from .batch import connect_ray

        connect_ray(args.address, quiet=True)  # before anything is written
    out = _out_dir(args.out)
    items = tuple(sorted(overrides.items()))
    jobs = (Job(c, seed, items, args.texture_size, formats, parts, share)
            for c in categories for seed in range(args.seed, args.seed + args.count))

    def show(row: dict) -> None:
        if "error" in row:
            tb = f" (traceback: {out / row['traceback']})" if row.get("traceback") else ""
            print(f"infmob: {row['category']} seed {row['seed']} failed: {row['error']}{tb}",
                  file=sys.stderr, flush=True)
        else:
            print(out / row["folder"], flush=True)
            for note in row.get("notes", []):
                print(f"infmob: {row['category']} seed {row['seed']}: {note}", file=sys.stderr, flush=True)
            if args.preview:
                from .validate.preview import preview

                preview(out / row["folder"])

    def log(message: str) -> None:
        print(f"infmob: {message}", file=sys.stderr, flush=True)

    total = len(categories) * args.count
    rows = run_batch(jobs, out, workers=workers, overwrite=args.overwrite, backend=args.backend,
                     address=args.address, on_row=show, total=total, wait_lock=args.wait, log=log)
    skipped = total - len(rows)
    if skipped:
        print(f"infmob: {skipped} object(s) already complete in {out}, skipped (--overwrite to redo)",
              file=sys.stderr)
    if parts is not None:
        said = retrieval_line(rows) if share > 0 else "no library part drawn (--parts-share 0)"
        print(f"infmob: {said}", file=sys.stderr)
    failed = sum(1 for r in rows if "error" in r)
    return 1 if failed else 0


def retrieval_line(rows: list[dict]) -> str:
    """One line over a run's rows: library parts used of the retrievable ones, and why the others were not."""
    used = total = 0
    why: dict[str, int] = {}
    for r in rows:
        s = r.get("retrieval") or {}
        used, total = used + s.get("used", 0), total + s.get("retrievable", 0)
        for k, n in s.get("skipped", {}).items():
            why[k] = why.get(k, 0) + n
    text = f"library parts used for {used} of {total} retrievable parts"
    if why:
        text += "; skipped: " + "; ".join(f"{n} {k}" for k, n in sorted(why.items(), key=lambda kv: (-kv[1], kv[0])))
    return text


def _make_scene(job, pool=None) -> str:
    from .scenes import save_scene, scene

    kind, seed, overrides, texture_size, out, preview = job
    folder = save_scene(scene(kind, seed, texture_size=texture_size, pool=pool, **overrides), out, pool=pool)
    if preview:
        from .validate.scene_preview import scene_previews

        scene_previews(folder)
    return str(folder)


def cmd_scene(args) -> int:
    from concurrent.futures import ProcessPoolExecutor

    from .api import check_texture_size
    from .params import parse_assignment
    from .scenes import get_kind
    from .seeding import MAX_SEED

    kind = get_kind(args.kind)
    if args.params:
        print(f"{kind.name}: {kind.doc}\n\n{kind.schema.table()}\n\ngrowth rules:\n{kind.grammar.table()}")
        return 0
    overrides = kind.schema.validate(dict(parse_assignment(s) for s in args.set))
    check_texture_size(args.texture_size)
    if args.count < 1 or args.count > MAX_COUNT:
        return _fail(f"--count must be 1..{MAX_COUNT}, got {args.count}")
    if args.seed < 0 or args.seed + args.count - 1 > MAX_SEED:
        return _fail(f"--seed must be 0..{MAX_SEED} (and --seed + --count - 1 too), got {args.seed}")
    workers = _workers(args.workers)
    out = _out_dir(args.out)
    jobs = [(args.kind, s, overrides, args.texture_size, out, args.preview)
            for s in range(args.seed, args.seed + args.count)]
    if workers == 1:
        for job in jobs:
            print(_make_scene(job), flush=True)
        return 0
    from .batch import _die_with_parent

    with ProcessPoolExecutor(workers, initializer=_die_with_parent) as pool:
        if args.count >= workers:  # a scene per worker
            for folder in pool.map(_make_scene, jobs):
                print(folder, flush=True)
        else:  # fewer scenes than workers: one scene at a time, its objects made and written in parallel
            for job in jobs:
                print(_make_scene(job, pool), flush=True)
    return 0


def cmd_parts(args) -> int:
    from . import partlib, parts_tools

    if args.parts_command == "import":
        out, rejected = partlib.import_parts(args.src, args.out, units=args.units, up=args.up, licence=args.licence,
                                             labels_csv=args.labels,
                                             log=lambda m: print(m, file=sys.stderr, flush=True))
        lib = partlib.load_library(out)
        print(f"{out}: {len(lib.parts)} parts ({', '.join(lib.labels)}), {len(rejected)} rejected")
        _print_check(parts_tools.summary(parts_tools.study(lib, 100, 0)), 100)
        return 0
    if args.parts_command == "export-builtin":
        out = parts_tools.export_builtin(args.out)
        print(f"{out}: {len(partlib.load_library(out).parts)} parts")
        return 0
    if args.placements < 1:
        return _fail(f"--placements must be at least 1, got {args.placements}")
    lib = partlib.load_library(args.lib)
    rows = parts_tools.study(lib, args.placements, args.seed, box=args.as_drawn)
    if args.json:
        import json

        print(json.dumps({"summary": parts_tools.summary(rows), "placements": rows}, indent=1))
        return 0
    by_part: dict = {}
    for r in rows:
        by_part.setdefault((r["label"], r["part"], r["placement"]), []).append(r)
    print(f"{'part':34} {'placement':9} {'n':>3} {'max gap mm':>10} {'max pen mm':>10} {'max lateral mm':>14}")
    for (label, pid, how), rs in sorted(by_part.items()):
        print(f"{label + '/' + pid:34} {how:9} {len(rs):3d} {max(r['gap_mm'] for r in rs):10.3f}"
              f" {max(r['penetration_mm'] for r in rs):10.3f} {max(r['lateral_mm'] for r in rs):14.3f}")
    _print_check(parts_tools.summary(rows), args.placements)
    if len(lib.labels) > 1:  # and n placements of each label on its own
        for label in lib.labels:
            print(f"{label}:")
            _print_check(parts_tools.summary(parts_tools.study(lib, args.placements, args.seed, args.as_drawn, label)),
                         args.placements)
    return 0


def _print_check(summary: dict, n: int) -> None:
    for how, s in summary.items():
        print(f"{how} placement over {n} placements: gap mean {s['mean_gap_mm']:.3f} max {s['max_gap_mm']:.3f} mm,"
              f" penetration mean {s['mean_penetration_mm']:.3f} max {s['max_penetration_mm']:.3f} mm,"
              f" feet off their mounts up to {s['max_lateral_mm']:.3f} mm; {s['within_0.5mm']}/{n} within 0.5 mm")


def cmd_fuzz(args) -> int:
    from .fuzz import fuzz

    if args.n < 1:
        return _fail(f"N must be at least 1, got {args.n}")
    workers = _workers(args.workers, args.n, "draws")
    if args.seed < 0:
        return _fail(f"--seed must be non-negative, got {args.seed}")
    categories = _categories(args.categories)
    out = _out_dir(args.out) if args.out else None
    res = fuzz(args.n, seed=args.seed, workers=workers, categories=categories, out=out,
               sim=not args.usd_only, texture_size=args.texture_size, stream=sys.stdout)
    return 0 if not res["crashes"] and not res["invalid"] else 1


def _writable_file(path: str, option: str) -> Path:
    """Fail now, not after a long run, when ``path`` cannot be written (probe: a temporary file beside it)."""
    import tempfile

    p = Path(path)
    if p.is_dir():
        raise OutputError(f"{option} {path!r} is a folder; give a file name")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise OutputError(f"{option} {path!r}: folder {str(parent)!r} does not exist; create it or choose another")
    try:
        with tempfile.NamedTemporaryFile(dir=parent, prefix=".infmob-probe-"):
            pass
    except OSError as e:
        raise OutputError(f"{option} {path!r}: cannot write in {str(parent)!r} ({e.strerror});"
                          f" choose another file") from None
    return p


def _write_file(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file in the same folder (never half-written)."""
    import tempfile

    fd, tmp = tempfile.mkstemp(dir=path.parent if str(path.parent) else ".", prefix=".infmob-", suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def cmd_validate(args) -> int:
    import json
    import shutil
    import tempfile

    from .validate import find_objects
    from .validate.files import load_metadata
    from .validate.report import report_json, summary_table

    for flag in ("sim", "robot"):
        if args.usd_only and getattr(args, flag):
            return _fail(f"--usd-only and --{flag} contradict each other; choose one")
    workers = _workers(args.workers)
    if args.out and args.sweep is None:
        return _fail("--out is only used with --sweep; drop it or add --sweep N")
    report_path = _writable_file(args.report, "--report") if args.report else None
    tmp = None
    if args.sweep is not None:
        from .api import check_texture_size
        from .batch import Job, run_batch

        if args.sweep < 1:
            return _fail(f"--sweep must be at least 1, got {args.sweep}")
        if args.sweep > MAX_COUNT:
            return _fail(f"--sweep must be at most {MAX_COUNT} seeds per category, got {args.sweep}")
        check_texture_size(args.texture_size)
        categories = [c for spec in args.paths for c in _categories(spec)]
        if args.out:
            from .layers import check_output_dir

            out = check_output_dir(Path(args.out))
        else:
            out = Path(tmp := tempfile.mkdtemp(prefix="infmob-sweep-"))
        jobs = (Job(c, s, (), args.texture_size) for c in categories for s in range(args.sweep))
        try:
            rows = run_batch(jobs, out, workers=min(workers, len(categories) * args.sweep),
                             total=len(categories) * args.sweep)
        except BaseException:  # SIGTERM, Ctrl-C, a full disk: the temporary folder goes too
            if tmp:
                shutil.rmtree(tmp, ignore_errors=True)
            raise
        for r in rows:
            if "error" in r:
                print(f"FAIL {r['category']} seed {r['seed']}: generation failed: {r['error']}")
        paths = [str(out / c) for c in categories]
    else:
        paths = args.paths
    try:
        folders = find_objects(paths)
        if not folders:
            return _fail(f"no object folders (with metadata.json) under {' '.join(paths)}")
        rows = []
        n_ok = 0
        for folder, report in _validate_all(folders, not args.usd_only, args.sim, workers, args.simready,
                                            not args.no_mass, args.robot):
            n_ok += report.ok
            status = "ok  " if report.ok else "FAIL"
            fails = "; ".join(f"{c.name}: {c.detail}" for c in report.failed)
            print(f"{status} {folder}" + (f"  [{fails}]" if fails else ""), flush=True)
            if args.verbose:
                for c in report.checks:
                    print(f"      {'ok  ' if c.ok else 'FAIL'} {c.name}: {c.detail}")
            try:
                category = str(load_metadata(folder)["category"])
            except Exception:  # noqa: BLE001 - unreadable metadata is already a FAIL of that object
                category = "?"
            # the report names each object as the ok/FAIL line does (a sweep's by category/name, its
            # temporary folder being gone), so that copies of one object stay apart
            rows.append((category, report.checks, str(folder.relative_to(out)) if tmp else str(folder)))
        print(f"\n{n_ok}/{len(folders)} objects passed every check\n")
        print(summary_table(rows) + (f"\n\n{_robot_table(rows)}" if args.robot else ""))
        if report_path:
            _write_file(report_path, json.dumps(report_json(rows), indent=2) + "\n")
        scenes_ok, scenes = _validate_scenes(paths, args) if not args.usd_only else (0, 0)
        return 0 if n_ok == len(folders) and scenes_ok == scenes else 1
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)


def _robot_table(rows) -> str:
    from .validate.robot import robot_table

    return robot_table(rows)


def _validate_scenes(paths, args) -> tuple[int, int]:
    """The scene checks (:mod:`infmob_usd.validate.scene`) of every scene folder (with ``scene.json``)
    among ``paths``; with ``--sim`` also every fixed object's joints driven in the room. Returns
    ``(passed, scenes)``."""
    from .validate.files import find_scenes

    found = find_scenes(paths)
    if not found:
        return 0, 0
    from .validate.scene import check_scene

    n_ok = 0
    for folder in found:
        checks = check_scene(folder, reach=args.sim)
        ok = all(c.ok for c in checks)
        n_ok += ok
        fails = "; ".join(f"{c.name}: {c.detail}" for c in checks if not c.ok)
        print(f"{'ok  ' if ok else 'FAIL'} scene {folder}" + (f"  [{fails}]" if fails else ""), flush=True)
        if args.verbose:
            for c in checks:
                print(f"      {'ok  ' if c.ok else 'FAIL'} {c.name}: {c.detail}")
    print(f"{n_ok}/{len(found)} scenes passed every check")
    return n_ok, len(found)


def _validate_all(folders, sim: bool, physics: bool, workers: int, simready: bool = False, mass: bool = True,
                  robot: bool = False):
    """``(folder, report)`` in folder order; a process pool when ``workers > 1``.

    Checks never raise (:func:`~infmob_usd.validate.result.guarded`); a worker that dies (a
    native crash inside a reader) fails its object, and a fresh pool goes on with the rest.
    Interrupted (Ctrl-C, SIGTERM), the workers are terminated.
    """
    from concurrent.futures import ProcessPoolExecutor
    from functools import partial

    from .validate import ObjectReport, validate_object
    from .validate.result import CheckResult, one_line

    check = partial(validate_object, sim=sim, physics=physics, simready=simready, mass=mass, robot=robot)
    if workers <= 1 or len(folders) <= 1:
        for folder in folders:
            yield folder, check(folder)
        return
    from .batch import _die_with_parent, _stop_pool

    todo = list(folders)
    while todo:
        pool = ProcessPoolExecutor(max_workers=min(workers, len(todo)), initializer=_die_with_parent)
        try:
            futures = [pool.submit(check, f) for f in todo]
            for i, (folder, fut) in enumerate(zip(todo, futures)):
                try:
                    report = fut.result()
                except Exception as e:  # noqa: BLE001 - BrokenProcessPool: the worker died
                    report = ObjectReport(folder, [CheckResult("validator", False,
                                                               f"the validating process died: {one_line(e)}")])
                    yield folder, report
                    todo = todo[i + 1:]
                    break
                yield folder, report
            else:
                todo = []
        except BaseException:  # Ctrl-C, SIGTERM, or the caller stopped early: no workers left behind
            _stop_pool(pool)
            raise
        pool.shutdown(wait=True)


def cmd_stats(args) -> int:
    import json

    from .validate.stats import dataset_stats, format_stats

    if args.max_pairs < 1:
        return _fail(f"--max-pairs must be at least 1, got {args.max_pairs}")
    if args.grammar is not None:
        from .validate.stats import grammar_stats

        if args.folder is not None:
            return _fail("give either DIR or --grammar CATEGORIES, not both")
        if not 1 <= args.count <= 100_000 or not 0 <= args.seed <= 2**63 - 1 - args.count:
            return _fail(f"--count must be 1..100000 and --seed 0..2^63-1-count, got {args.count}, {args.seed}")
        stats = grammar_stats(_categories(args.grammar), args.count, args.seed, max_pairs=args.max_pairs)
        print(json.dumps(stats, indent=2) if args.json else format_stats(stats))
        return 0
    if args.folder is None:
        return _fail("give a folder of objects (DIR) or --grammar CATEGORIES")
    skipped: list = []
    stats = dataset_stats(args.folder, max_pairs=args.max_pairs, skipped=skipped)
    for folder, why in skipped:
        print(f"infmob: skipped {folder}: metadata.json unreadable ({why})", file=sys.stderr)
    if not stats["overall"]["objects"]:
        return _fail(f"no object folders (with metadata.json) under {args.folder}")
    print(json.dumps(stats, indent=2) if args.json else format_stats(stats))
    return 0


def cmd_bench(args) -> int:
    import json

    from .api import check_texture_size
    from .validate.bench import format_bench, run_bench

    categories = _categories(args.categories)
    check_texture_size(args.texture_size)
    if args.count < 1:
        return _fail("--count must be at least 1")
    workers = _workers(args.workers, len(categories) * args.count)
    res = run_bench(categories, args.count, args.texture_size, workers, cold=args.cold)
    print(json.dumps(res, indent=2) if args.json else format_bench(res))
    return 0


def cmd_textures(args) -> int:
    import time

    from tqdm import tqdm

    from .api import check_texture_size
    from .materials import FAMILIES, split_spec
    from .materials.cache import build, cache_dir

    check_texture_size(args.texture_size)
    args.workers = _workers(args.workers)
    if args.family and split_spec(args.family)[0] not in FAMILIES:
        return _fail(f"unknown material family {args.family!r}; valid families: {', '.join(FAMILIES)}")
    if args.family:
        name, only = split_spec(args.family)
        variants = [v for v, _ in FAMILIES[name].palette]
        unknown = [v for v in only if v not in variants]
        if unknown:
            return _fail(f"material family {name!r} has no variant {', '.join(map(repr, unknown))};"
                         f" its variants: {', '.join(variants)}")
    if cache_dir() is None:
        return _fail("the texture cache is disabled or not writable; set INFMOB_USD_CACHE to a writable folder")
    t0 = time.perf_counter()
    bar = tqdm(unit="look", file=sys.stderr, disable=None)  # silent unless stderr is a terminal

    def progress(done, total):
        bar.total = total
        bar.update(done - bar.n)

    try:
        res = build(args.texture_size, args.family, args.workers, progress)
    except ValueError as e:
        return _fail(str(e))
    finally:
        bar.close()
    dt = time.perf_counter() - t0
    print(f"{res['looks']} looks at {args.texture_size} px: {res['made']} made, {res['looks'] - res['made']}"
          f" already cached, in {dt:.1f} s with {args.workers} workers")
    print(f"cache {res['cache']} ({res['megabytes']:.0f} MB, every size)")
    return 0


def cmd_preview(args) -> int:
    from .validate.preview import main as preview_main

    return preview_main(args)


def cmd_gallery(args) -> int:
    from .validate.gallery import main as gallery_main

    return gallery_main(args)


COMMANDS = {"list": cmd_list, "params": cmd_params, "generate": cmd_generate, "validate": cmd_validate,
            "preview": cmd_preview, "stats": cmd_stats, "bench": cmd_bench, "textures": cmd_textures,
            "gallery": cmd_gallery, "fuzz": cmd_fuzz, "parts": cmd_parts, "scene": cmd_scene,
            "export": cmd_export}


def main(argv: list[str] | None = None) -> int:
    import signal

    if argv is None:  # the command line, not a test calling main()
        for stream in (sys.stdout, sys.stderr):  # an ASCII terminal (LC_ALL=C, PYTHONIOENCODING=ascii) or a
            try:  # folder name that is not UTF-8 prints escaped, never as a UnicodeEncodeError
                stream.reconfigure(errors="backslashreplace")
            except (AttributeError, ValueError):
                pass
    args = _parser().parse_args(argv)
    if argv is None:  # SIGTERM stops like Ctrl-C
        signal.signal(signal.SIGTERM, _on_sigterm)
        sys.unraisablehook = _unraisable(sys.unraisablehook)
    try:
        return COMMANDS[args.command](args)
    except InfmobError as e:
        return _fail(str(e))
    except Terminated as e:
        signal.signal(signal.SIGTERM, signal.SIG_IGN)  # a second SIGTERM cannot interrupt the message
        print(f"infmob: stopped by SIGTERM ({args.command}): nothing half-written was left; run it again to"
              f" {'resume' if args.command in ('generate', 'export') else 'redo it'}", file=sys.stderr)
        return e.code
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:  # `infmob params x | head`: the reader left; say nothing more
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except OSError:
            pass
        return 0


if __name__ == "__main__":
    sys.exit(main())
