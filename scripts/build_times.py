#!/usr/bin/env python3
"""CPU-seconds of a build per source folder, from Ninja's log (docs/building.md).

Usage: scripts/build_times.py [BUILD_DIR, default build/release] [--top N]

Ninja records each step's start and end (ms) in BUILD_DIR/.ninja_log; a step rebuilt later
appears again, and the last record counts. A step's folder is the path before CMakeFiles/
(e.g. core/render, tests/cli); links and generated shaders count to their folder too.
"""
import argparse
import collections
import pathlib
import sys


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir", nargs="?", default="build/release")
    ap.add_argument("--top", type=int, default=0, help="also list the N slowest steps")
    a = ap.parse_args()
    log = pathlib.Path(a.build_dir) / ".ninja_log"
    if not log.is_file():
        print(f"build_times: {log} not found (build first)", file=sys.stderr)
        return 2
    last = {}
    for line in log.read_text().splitlines():
        if line.startswith("#"):
            continue
        start, end, _, output, _ = line.split("\t")
        last[output] = (int(end) - int(start)) / 1000.0
    per_folder = collections.defaultdict(float)
    steps = collections.Counter()
    root = pathlib.Path(a.build_dir).resolve()
    for output, seconds in last.items():
        path = pathlib.Path(output)
        if path.is_absolute() and path.is_relative_to(root):
            output = str(path.relative_to(root))  # e.g. the test lists gtest_discover_tests writes
        parts = output.split("/")
        folder = "/".join(parts[: parts.index("CMakeFiles")]) if "CMakeFiles" in parts else "/".join(parts[:-1])
        top = "/".join(folder.split("/")[:2]) or "(top)"
        per_folder[top] += seconds
        steps[top] += 1
    total = sum(per_folder.values())
    print("| folder | CPU-s | steps | share |\n| --- | ---: | ---: | ---: |")
    for folder, seconds in sorted(per_folder.items(), key=lambda kv: -kv[1]):
        print(f"| {folder} | {seconds:.0f} | {steps[folder]} | {100 * seconds / total:.0f}% |")
    print(f"| all | {total:.0f} | {sum(steps.values())} | 100% |")
    if a.top:
        print()
        for output, seconds in sorted(last.items(), key=lambda kv: -kv[1])[: a.top]:
            print(f"{seconds:7.1f} s  {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
