#!/usr/bin/env python3
"""Compare a piglit results directory with a list of expected failures.

Usage: piglit_compare.py RESULTS_DIR EXPECTED_FAILURES [--counts FILE]
                         [--bless] [--elapsed SECONDS] [--title TITLE]
                         [--folders PREFIX,...] [--profile PROFILE.xml.gz]
       piglit_compare.py RESULTS_DIR --summary-only [--counts FILE] ...
       piglit_compare.py --count-profile PROFILE.xml.gz --folders PREFIX,...

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
--counts writes the status counts to FILE (for docs/CONFORMANCE.md): the
totals, then one `folder spec@NAME@ total N pass N fail N skip N crash N
timeout N` line per folder (fail includes warn and dmesg-*, timeout
includes incomplete and notrun).
--folders restricts everything to the tests whose names start with one of
the comma-separated prefixes (`spec@glsl-1.30@,spec@glsl-1.40@`), so one
run of several sets can be compared set by set; the per-folder lines list
each prefix, in that order, even when it has no test.
--profile names piglit's test list for the suite (tests/SUITE.xml.gz): the
results must hold exactly as many tests as it has in the folders (all of
it without --folders), else the run is incomplete (exit 2).
--summary-only reports counts and the tests that neither passed nor were
skipped, with no expected-failures list and no verdict (for Mesa's runs).
--count-profile prints how many tests the profile has in the folders.
"""

import argparse
import bz2
import gzip
import json
import lzma
import os
import sys
import xml.etree.ElementTree as ET

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


def folder_of(name):
    """The folder prefix of a test name: `spec@glsl-1.30@` for
    `spec@glsl-1.30@compiler@x.vert`, the first component otherwise."""
    parts = name.split("@")
    n = 2 if parts[0] == "spec" and len(parts) > 2 else 1
    return "@".join(parts[:n]) + "@"


def in_folders(name, prefixes):
    return prefixes is None or any(name.startswith(p) for p in prefixes)


def count_profile(path, prefixes):
    """How many tests piglit's profile (a tests/SUITE.xml.gz test list) has
    in the folders."""
    opener = gzip.open if path.endswith(".gz") else open
    n = 0
    with opener(path, "rb") as f:
        for _, elem in ET.iterparse(f):
            if elem.tag == "Test":
                n += in_folders(elem.get("name", ""), prefixes)
                elem.clear()
    return n


# The per-folder columns, and the statuses each one counts.
FOLDER_COLUMNS = [("pass", {"pass"}), ("fail", {"fail", "warn", "dmesg-warn", "dmesg-fail"}),
                  ("skip", {"skip"}), ("crash", {"crash"}),
                  ("timeout", {"timeout", "incomplete", "notrun"})]


def folder_counts(tests, prefixes):
    """[(folder, {column: n, "total": n})], in the order of prefixes (or of
    the folders' names when there are none)."""
    folders = list(prefixes) if prefixes else sorted({folder_of(n) for n in tests})
    table = {f: dict({c: 0 for c, _ in FOLDER_COLUMNS}, total=0) for f in folders}
    for name, t in tests.items():
        folder = next((p for p in folders if name.startswith(p)), None)
        if folder is None:
            continue
        row = table[folder]
        row["total"] += 1
        status = t.get("result", "notrun")
        for column, statuses in FOLDER_COLUMNS:
            if status in statuses:
                row[column] += 1
    return [(f, table[f]) for f in folders]


def print_folder_table(title, rows):
    width = max([len("folder")] + [len(f) for f, _ in rows])
    columns = ["total"] + [c for c, _ in FOLDER_COLUMNS]
    print("\n{}: per folder".format(title))
    print("  " + "folder".ljust(width) + "".join("{:>8}".format(c) for c in columns))
    for f, row in rows:
        print("  " + f.ljust(width) + "".join("{:>8}".format(row[c]) for c in columns))


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
    ap.add_argument("results", nargs="?")
    ap.add_argument("expected", nargs="?")
    ap.add_argument("--counts")
    ap.add_argument("--bless", action="store_true")
    ap.add_argument("--elapsed", type=float)
    ap.add_argument("--title", default="piglit")
    ap.add_argument("--folders", help="comma-separated test-name prefixes")
    ap.add_argument("--profile", help="piglit's tests/SUITE.xml.gz, for the expected total")
    ap.add_argument("--summary-only", action="store_true")
    ap.add_argument("--count-profile", metavar="PROFILE")
    args = ap.parse_args()
    prefixes = [p for p in args.folders.split(",") if p] if args.folders else None

    if args.count_profile:
        print(count_profile(args.count_profile, prefixes))
        return 0
    if args.results is None or (args.expected is None and not args.summary_only):
        ap.error("RESULTS_DIR and EXPECTED_FAILURES are required (EXPECTED_FAILURES "
                 "not with --summary-only)")

    try:
        tests = load_results(args.results)
    except (OSError, ValueError, KeyError) as e:
        print("piglit-compare: cannot read results: {}".format(e), file=sys.stderr)
        return 2
    tests = {n: t for n, t in tests.items() if in_folders(n, prefixes)}
    if args.summary_only:
        expected, problems = {}, []
    else:
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
    total = len(tests)
    rows = folder_counts(tests, prefixes)

    if args.summary_only:
        bad = [n for n in sorted(tests) if tests[n].get("result") not in ("pass", "skip")]
        if bad:
            print("Neither passed nor skipped ({}):".format(len(bad)))
            for name in bad:
                print("  {} [{}]".format(name, tests[name].get("result")))
    else:
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

    if len(rows) > 1:
        print_folder_table(args.title, rows)
    shown = [s for s in STATUSES if counts.get(s)]
    summary = ", ".join("{} {}".format(counts[s], s) for s in shown)
    print("\n{}: {} tests: {}".format(args.title, total, summary))
    if not args.summary_only:
        print("{}: {} expected failures, {} new failures, {} crashes/timeouts, {} unexpected passes"
              .format(args.title, len(expected_failing), len(new_failures), len(never_ok),
                      len(fixed)))
    if args.elapsed is not None:
        print("{}: run took {:.0f} s".format(args.title, args.elapsed))

    if args.counts:
        with open(args.counts, "w", encoding="utf-8") as f:
            f.write("# Written by scripts/piglit_compare.py (from piglit-run.sh or piglit-mesa.sh); quoted by docs/CONFORMANCE.md.\n")
            f.write("suite {}\n".format(args.title))
            f.write("total {}\n".format(total))
            for s in STATUSES:
                f.write("{} {}\n".format(s, counts.get(s, 0)))
            if not args.summary_only:
                f.write("expected-failures {}\n".format(len(expected_failing)))
                f.write("new-failures {}\n".format(len(new_failures)))
            for folder, row in rows:
                f.write("folder {} total {} {}\n".format(folder, row["total"], " ".join(
                    "{} {}".format(c, row[c]) for c, _ in FOLDER_COLUMNS)))

    if args.profile:
        try:
            want = count_profile(args.profile, prefixes)
        except (OSError, ET.ParseError) as e:
            print("piglit-compare: cannot read the profile: {}".format(e), file=sys.stderr)
            return 2
        if want != total:
            print("piglit-compare: the results hold {} tests, the profile {} in these folders: "
                  "the run is incomplete".format(total, want), file=sys.stderr)
            return 2

    if args.summary_only:
        return 0
    if args.bless:
        write_list(args.expected, expected_failing + new_failures, expected)
        print("blessed: {} now lists {} tests".format(args.expected,
                                                       len(expected_failing) + len(new_failures)))
        return 1 if never_ok else 0
    return 1 if (new_failures or never_ok) else 0


if __name__ == "__main__":
    sys.exit(main())
