"""The ``infmob`` command line: list, params, generate, validate."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .errors import InfmobError

DESCRIPTION = "Procedural, simulation-ready articulated objects as OpenUSD + URDF."


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="infmob", description=DESCRIPTION)
    sub = ap.add_subparsers(dest="command", required=True, metavar="COMMAND")

    sub.add_parser("list", help="print every category id, one per line")

    p = sub.add_parser("params", help="print a category's parameter schema and growth rules")
    p.add_argument("category")

    g = sub.add_parser("generate", help="generate objects: DIR/CATEGORY/CATEGORY_SSSSSS/ per seed")
    g.add_argument("category")
    g.add_argument("--count", type=int, default=1, help="number of objects (seeds S..S+N-1); default 1")
    g.add_argument("--seed", type=int, default=0, help="first seed S; default 0")
    g.add_argument("--out", default="infmob_out", help="output folder DIR; default ./infmob_out")
    g.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a parameter (repeatable); see `infmob params CATEGORY`")
    g.add_argument("--texture-size", type=int, default=512, metavar="PX",
                   help="texture edge in pixels, a power of two 16..4096; default 512")

    v = sub.add_parser("validate", help="check object folders: USD, URDF agreement and SAPIEN")
    v.add_argument("paths", nargs="+", metavar="PATH", help="an object folder or a folder of them")
    v.add_argument("--no-sim", action="store_true", help="skip the SAPIEN checks (USD and URDF only)")
    v.add_argument("--verbose", "-v", action="store_true", help="print every check, not only failures")
    return ap


def _fail(message: str) -> int:
    print(f"infmob: error: {message}", file=sys.stderr)
    return 2


def cmd_list(args) -> int:
    from .api import list_categories

    print("\n".join(list_categories()))
    return 0


def cmd_params(args) -> int:
    from .api import get_category

    module = get_category(args.category)
    print(f"{args.category}: {module.__doc__.strip().splitlines()[0]}\n")
    print(module.SCHEMA.table())
    print("\ngrowth rules:")
    print(module.GROWTH.table())
    return 0


def cmd_generate(args) -> int:
    from .api import check_texture_size, generate, get_category
    from .layers import check_output_dir
    from .params import parse_assignment

    module = get_category(args.category)
    overrides = dict(parse_assignment(s) for s in args.set)
    module.SCHEMA.validate(overrides)  # fail before anything is written
    check_texture_size(args.texture_size)
    if args.count < 1:
        return _fail(f"--count must be at least 1, got {args.count}")
    if args.seed < 0:
        return _fail(f"--seed must be non-negative, got {args.seed}")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        return _fail(f"output path {str(out)!r} is a file; give a folder (--out DIR)")
    target = check_output_dir(out / args.category)
    for seed in range(args.seed, args.seed + args.count):
        obj = generate(args.category, seed=seed, texture_size=args.texture_size, **overrides)
        print(obj.save(target), flush=True)
    return 0


def cmd_validate(args) -> int:
    from .validate import find_objects, validate_object  # noqa: I001

    folders = find_objects(args.paths)
    if not folders:
        return _fail(f"no object folders (with metadata.json) under {' '.join(args.paths)}")
    n_ok = 0
    tally: dict[str, int] = {}
    for folder in folders:
        report = validate_object(folder, sim=not args.no_sim)
        n_ok += report.ok
        status = "ok  " if report.ok else "FAIL"
        fails = "; ".join(f"{c.name}: {c.detail}" for c in report.failed)
        print(f"{status} {folder}" + (f"  [{fails}]" if fails else ""), flush=True)
        for c in report.checks:
            tally[c.name] = tally.get(c.name, 0) + c.ok
            if args.verbose:
                print(f"      {'ok  ' if c.ok else 'FAIL'} {c.name}: {c.detail}")
    print(f"\n{n_ok}/{len(folders)} objects passed")
    print("  " + "  ".join(f"{k} {v}/{len(folders)}" for k, v in tally.items()))
    return 0 if n_ok == len(folders) else 1


COMMANDS = {"list": cmd_list, "params": cmd_params, "generate": cmd_generate, "validate": cmd_validate}


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except InfmobError as e:
        return _fail(str(e))
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
