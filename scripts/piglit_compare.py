#!/usr/bin/env python3
"""Compare a piglit results directory with a list of expected failures.

Usage: piglit_compare.py RESULTS_DIR EXPECTED_FAILURES [--counts FILE]
                         [--bless] [--elapsed SECONDS]

The list has one test name per line (as piglit names them in results,
`spec@glsl-1.20@compiler@...`), followed by ` # reason`. Blank lines and
lines starting with `#` are comments.

Verdict (exit status):
  0  every test passed, was skipped, or failed while listed;
  1  a test not in the list failed or warned, or any test crashed, timed
     out or did not finish (listing a test never excuses a crash: the
     compiler must not crash on any input);
  2  the inputs could not be read.
Listed tests that now pass are printed, asking for the list to shrink; they
do not fail the run.

--bless rewrites the list to the current failures (keeping the reasons of
entries that stay, giving new ones "# TODO: triage"); crashes and timeouts
are never blessed.
--counts writes the status counts to FILE (for docs/CONFORMANCE.md).
"""

import argparse
import bz2
import gzip
import json
import lzma
import os
import sys

# piglit's statuses, best to worst (framework/status.py).
STATUSES = ["pass", "warn", "dmesg-warn", "fail", "dmesg-fail", "timeout",
            "crash", "incomplete", "skip", "notrun"]
# Failures a list entry may excuse.
LISTABLE = {"fail", "warn", "dmesg-warn", "dmesg-fail"}
# Failures nothing excuses.
NEVER_OK = {"crash", "timeout", "incomplete", "notrun"}

OPENERS = [("results.json.bz2", bz2.open), ("results.json.gz", gzip.open),
           ("results.json.xz", lzma.open), ("results.json", open)]


def load_results(results_dir):
    """Returns {test name: result dict} from a piglit results directory."""
    for name, opener in OPENERS:
        path = os.path.join(results_dir, name)
        if os.path.exists(path):
            with opener(path, "rt", encoding="utf-8") as f:
                return json.load(f)["tests"]
    raise FileNotFoundError("no results.json[.bz2|.gz|.xz] in " + results_dir)


def load_expected(path):
    """Returns ({name: reason}, [problems]) from an expected-failures list."""
    expected, problems = {}, []
    if not os.path.exists(path):
        return expected, problems
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            name, sep, reason = line.partition(" # ")
            name, reason = name.strip(), reason.strip()
            if not sep or not reason:
                problems.append("{}:{}: `{}' has no ` # reason'".format(path, number, name))
            if name in expected:
                problems.append("{}:{}: `{}' is listed twice".format(path, number, name))
            expected[name] = reason
    return expected, problems


def excerpt(result, limit=12):
    """The first lines of a test's output, indented, for the log."""
    text = "\n".join(x for x in (result.get("out") or "", result.get("err") or "") if x)
    lines = [l for l in text.splitlines() if l.strip()]
    shown = lines[:limit]
    if len(lines) > limit:
        shown.append("... ({} more lines)".format(len(lines) - limit))
    return "".join("      | " + l + "\n" for l in shown)


def write_list(path, failing, expected):
    """Writes the expected-failures list for the current failures."""
    header = []
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    header.append(line)
                else:
                    break
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(header)
        for name in sorted(failing):
            f.write("{} # {}\n".format(name, expected.get(name) or "TODO: triage"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    ap.add_argument("expected")
    ap.add_argument("--counts")
    ap.add_argument("--bless", action="store_true")
    ap.add_argument("--elapsed", type=float)
    ap.add_argument("--title", default="piglit")
    args = ap.parse_args()

    try:
        tests = load_results(args.results)
    except (OSError, ValueError, KeyError) as e:
        print("piglit-compare: cannot read results: {}".format(e), file=sys.stderr)
        return 2
    expected, problems = load_expected(args.expected)

    counts = {s: 0 for s in STATUSES}
    new_failures, never_ok, fixed, expected_failing = [], [], [], []
    for name in sorted(tests):
        status = tests[name].get("result", "notrun")
        counts[status] = counts.get(status, 0) + 1
        listed = name in expected
        if status in NEVER_OK:
            never_ok.append(name)
        elif status in LISTABLE:
            (expected_failing if listed else new_failures).append(name)
        elif status == "pass" and listed:
            fixed.append(name)
    stale = sorted(n for n in expected if n not in tests)

    for p in problems:
        print("warning: " + p)
    if fixed:
        print("\nUnexpected passes ({}): remove them from {}:".format(len(fixed), args.expected))
        for name in fixed:
            print("  " + name)
    if stale:
        print("\nListed but not run ({}): remove them from {}:".format(len(stale), args.expected))
        for name in stale:
            print("  " + name)
    if new_failures:
        print("\nNew failures ({}): fix them, or list them with a reason in {}:".format(
            len(new_failures), args.expected))
        for name in new_failures:
            print("  {} [{}]".format(name, tests[name].get("result")))
            sys.stdout.write(excerpt(tests[name]))
    if never_ok:
        print("\nCrashes, timeouts and unfinished tests ({}): these always fail the run:".format(
            len(never_ok)))
        for name in never_ok[:50]:
            print("  {} [{}]".format(name, tests[name].get("result")))
            sys.stdout.write(excerpt(tests[name], 6))
        if len(never_ok) > 50:
            print("  ... and {} more".format(len(never_ok) - 50))

    total = len(tests)
    shown = [s for s in STATUSES if counts.get(s)]
    summary = ", ".join("{} {}".format(counts[s], s) for s in shown)
    print("\n{}: {} tests: {}".format(args.title, total, summary))
    print("{}: {} expected failures, {} new failures, {} crashes/timeouts, {} unexpected passes".format(
        args.title, len(expected_failing), len(new_failures), len(never_ok), len(fixed)))
    if args.elapsed is not None:
        print("{}: run took {:.0f} s".format(args.title, args.elapsed))

    if args.counts:
        with open(args.counts, "w", encoding="utf-8") as f:
            f.write("# Written by scripts/piglit-run.sh; quoted by docs/CONFORMANCE.md.\n")
            f.write("suite {}\n".format(args.title))
            f.write("total {}\n".format(total))
            for s in STATUSES:
                f.write("{} {}\n".format(s, counts.get(s, 0)))
            f.write("expected-failures {}\n".format(len(expected_failing)))
            f.write("new-failures {}\n".format(len(new_failures)))

    if args.bless:
        write_list(args.expected, expected_failing + new_failures, expected)
        print("blessed: {} now lists {} tests".format(args.expected,
                                                       len(expected_failing) + len(new_failures)))
        return 1 if never_ok else 0
    return 1 if (new_failures or never_ok) else 0


if __name__ == "__main__":
    sys.exit(main())
