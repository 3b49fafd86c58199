#!/usr/bin/env python3
"""Instruction counts of the kernels against the committed baseline.

Runs `cargo bench --features iai --bench instructions` (gungraun + valgrind's
callgrind, benches/instructions.rs), reads each bench's instruction count,
and compares it with references/perf/instructions.json: prints the change per
bench and exits 1 if any bench has more instructions than the baseline by
more than the threshold (default +5 %), 2 on a missing bench or a bad input.

    python3 scripts/instructions.py                  # run, compare, fail past +5 %
    python3 scripts/instructions.py --threshold 2    # a tighter limit
    python3 scripts/instructions.py --input out.txt  # compare a saved bench output, no run
    python3 scripts/instructions.py --update         # run and write the new baseline

Counts are exact and do not depend on the machine's load, but they do depend
on the compiler, the valgrind version and the gungraun version: the baseline
records all three, and the script warns when they differ from the current ones.
Run it from the repository root.
"""

import argparse
import datetime
import json
import re
import subprocess
import sys
from pathlib import Path

BASELINE = Path("references/perf/instructions.json")
BENCH = ["cargo", "bench", "--features", "iai", "--bench", "instructions"]
HEADER = re.compile(r"^instructions::\w+::(\w+)\s")
COUNT = re.compile(r"^\s+Instructions:\s+(\d+)\|")


def parse(text):
    """{bench: instructions} from gungraun's terminal output."""
    counts, name = {}, None
    for line in text.splitlines():
        m = HEADER.match(line)
        if m:
            name = m.group(1)
            continue
        m = COUNT.match(line)
        if m and name:
            counts[name] = int(m.group(1))
            name = None
    return counts


def tool_versions():
    def first_line(cmd):
        try:
            return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip().splitlines()[0]
        except (OSError, subprocess.CalledProcessError, IndexError):
            return "unknown"

    return {
        "rustc": first_line(["rustc", "--version"]),
        "valgrind": first_line(["valgrind", "--version"]),
        "gungraun-runner": first_line(["gungraun-runner", "--version"]),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--threshold", type=float, default=5.0, help="allowed increase in percent (default 5)")
    ap.add_argument("--input", type=Path, help="a saved output of the bench instead of running it")
    ap.add_argument("--update", action="store_true", help="write the measured counts as the new baseline")
    args = ap.parse_args()

    if args.input:
        text = args.input.read_text()
    else:
        run = subprocess.run(BENCH, capture_output=True, text=True)
        text = run.stdout
        if run.returncode != 0:
            sys.stderr.write(run.stdout + run.stderr)
            sys.stderr.write(f"error: {' '.join(BENCH)} exited with {run.returncode}\n")
            return 2
    now = parse(text)
    if not now:
        sys.stderr.write("error: no instruction counts in the bench output\n")
        return 2
    versions = tool_versions()

    if args.update:
        BASELINE.parent.mkdir(parents=True, exist_ok=True)
        doc = {
            "what": "Instructions (callgrind Ir) per bench of benches/instructions.rs; scripts/instructions.py",
            "measured": datetime.date.today().isoformat(),
            "tools": versions,
            "benches": now,
        }
        BASELINE.write_text(json.dumps(doc, indent=2) + "\n")
        print(f"wrote {BASELINE} ({len(now)} benches)")
        return 0

    base = json.loads(BASELINE.read_text())
    for tool, v in base.get("tools", {}).items():
        if versions.get(tool) != v:
            print(f"warning: baseline {tool} is '{v}', now '{versions.get(tool)}': counts may differ for that reason")
    failed, missing = [], []
    print(f"{'bench':<16} {'baseline':>14} {'now':>14} {'change':>9}")
    for name, b in base["benches"].items():
        if name not in now:
            missing.append(name)
            print(f"{name:<16} {b:>14} {'-':>14} {'missing':>9}")
            continue
        change = 100.0 * (now[name] - b) / b
        flag = ""
        if change > args.threshold:
            failed.append(name)
            flag = f"  REGRESSION (> +{args.threshold:g} %)"
        print(f"{name:<16} {b:>14} {now[name]:>14} {change:>+8.2f}%{flag}")
    for name in sorted(set(now) - set(base["benches"])):
        print(f"{name:<16} {'-':>14} {now[name]:>14} {'new':>9}")
    if missing:
        sys.stderr.write(f"error: benches missing from the output: {', '.join(missing)}\n")
        return 2
    if failed:
        sys.stderr.write(f"error: {len(failed)} bench(es) regressed past +{args.threshold:g} %: {', '.join(failed)}\n")
        return 1
    print(f"all {len(base['benches'])} benches within +{args.threshold:g} % of the baseline")
    return 0


if __name__ == "__main__":
    sys.exit(main())
