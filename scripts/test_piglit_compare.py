#!/usr/bin/env python3
"""Tests of piglit_compare.py: verdicts, list handling, --bless, --counts.

Run: python3 scripts/test_piglit_compare.py
"""

import bz2
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "piglit_compare.py")


class CompareTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.results = os.path.join(self.dir.name, "results")
        os.mkdir(self.results)
        self.expected = os.path.join(self.dir.name, "expected.txt")

    def tearDown(self):
        self.dir.cleanup()

    def write_results(self, statuses):
        tests = {name: {"result": s, "out": "output of " + name, "err": ""}
                 for name, s in statuses.items()}
        with bz2.open(os.path.join(self.results, "results.json.bz2"), "wt") as f:
            json.dump({"tests": tests}, f)

    def write_expected(self, text):
        with open(self.expected, "w") as f:
            f.write(text)

    def run_compare(self, *extra):
        p = subprocess.run([sys.executable, SCRIPT, self.results, self.expected] + list(extra),
                           capture_output=True, text=True)
        return p.returncode, p.stdout

    def test_all_pass(self):
        self.write_results({"a": "pass", "b": "skip"})
        rc, out = self.run_compare()
        self.assertEqual(rc, 0, out)
        self.assertIn("2 tests: 1 pass, 1 skip", out)

    def test_listed_failure_is_expected(self):
        self.write_results({"a": "pass", "b": "fail"})
        self.write_expected("# header\nb # needs feature X\n")
        rc, out = self.run_compare()
        self.assertEqual(rc, 0, out)
        self.assertIn("1 expected failures, 0 new failures", out)

    def test_new_failure_fails_with_its_output(self):
        self.write_results({"a": "fail"})
        rc, out = self.run_compare()
        self.assertEqual(rc, 1, out)
        self.assertIn("New failures (1)", out)
        self.assertIn("| output of a", out)

    def test_crash_fails_even_when_listed(self):
        self.write_results({"a": "crash", "b": "timeout"})
        self.write_expected("a # known\nb # known\n")
        rc, out = self.run_compare()
        self.assertEqual(rc, 1, out)
        self.assertIn("2 crashes/timeouts", out)

    def test_unexpected_pass_and_stale_entries_only_warn(self):
        self.write_results({"a": "pass"})
        self.write_expected("a # was broken\ngone # removed test\n")
        rc, out = self.run_compare()
        self.assertEqual(rc, 0, out)
        self.assertIn("Unexpected passes (1)", out)
        self.assertIn("Listed but not run (1)", out)

    def test_entry_without_reason_is_reported(self):
        self.write_results({"a": "fail"})
        self.write_expected("a\n")
        rc, out = self.run_compare()
        self.assertEqual(rc, 0, out)
        self.assertIn("has no ` # reason'", out)

    def test_bless_keeps_reasons_and_header(self):
        self.write_results({"a": "fail", "b": "fail", "c": "pass", "d": "crash"})
        self.write_expected("# header\n\nb # old reason\nc # fixed now\n")
        rc, _ = self.run_compare("--bless")
        self.assertEqual(rc, 1, "a crash is never blessed")
        with open(self.expected) as f:
            self.assertEqual(f.read(), "# header\n\na # TODO: triage\nb # old reason\n")

    def test_counts_file(self):
        self.write_results({"a": "pass", "b": "fail", "c": "skip"})
        counts = os.path.join(self.dir.name, "counts.txt")
        self.run_compare("--counts", counts, "--title", "suite")
        with open(counts) as f:
            lines = f.read().splitlines()
        for expected in ["suite suite", "total 3", "pass 1", "fail 1", "skip 1", "new-failures 1"]:
            self.assertIn(expected, lines)

    def test_missing_results_is_a_setup_error(self):
        rc, _ = self.run_compare()
        self.assertEqual(rc, 2)


if __name__ == "__main__":
    unittest.main()
