#!/usr/bin/env python3
"""Compare the outputs of two adit builds, for restructurings that must not change results
(issue 16): every file byte for byte, except summary.json, whose fields other than timings must be
equal.

    # outputs of every bundled model from the commit before and the commit after
    for m in models/*.json; do n=$(basename $m .json)
        BEFORE/adit run $m --out /tmp/cmp/base/$n; AFTER/adit run $m --out /tmp/cmp/new/$n; done
    python3 validation/compare_outputs.py /tmp/cmp/base /tmp/cmp/new

BASE and NEW hold one folder per model; exit status 1 when anything differs.
"""
import json
import os
import sys

TIMING = {"wall_seconds", "stage_seconds", "zone_cycles_per_second", "block_cycles_per_second", "seconds"}


def strip(v):
    """The value without its timing fields, at any depth."""
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in TIMING}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v


def main(base, new):
    bad = total = 0
    for model in sorted(os.listdir(base)):
        b, n = os.path.join(base, model), os.path.join(new, model)
        if not os.path.isdir(b):
            continue
        files = sorted(os.listdir(b))
        if not os.path.isdir(n) or sorted(os.listdir(n)) != files:
            print(f"{model}: file lists differ")
            bad += 1
            continue
        same = 0
        for f in files:
            total += 1
            with open(os.path.join(b, f), "rb") as x, open(os.path.join(n, f), "rb") as y:
                x, y = x.read(), y.read()
            ok = strip(json.loads(x)) == strip(json.loads(y)) if f == "summary.json" else x == y
            same += ok
            if not ok:
                print(f"{model}/{f}: differs")
                bad += 1
        print(f"{model}: {same} of {len(files)} files identical")
    print(f"{total - bad} of {total} files identical" if bad == 0 else f"{bad} differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
