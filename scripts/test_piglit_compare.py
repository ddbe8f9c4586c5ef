#!/usr/bin/env python3
"""Tests of piglit_compare.py: verdicts, list handling, --bless, --counts,
folder sets (--folders, per-folder counts), totals from piglit's profile,
--summary-only.

Run: python3 scripts/test_piglit_compare.py
"""

import bz2
import gzip
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

    def write_profile(self, names):
        path = os.path.join(self.dir.name, "glslparser.xml.gz")
        with gzip.open(path, "wt") as f:
            f.write("<?xml version='1.0' encoding='utf-8'?>\n<PiglitTestList count=\"{}\" "
                    "name=\"glslparser\">".format(len(names)))
            for n in names:
                f.write("<Test type=\"glsl_parser\" name=\"{}\"><option name=\"command\" "
                        "value=\"['glslparsertest']\" /></Test>".format(n))
            f.write("</PiglitTestList>")
        return path

    def read_counts(self, path):
        with open(path) as f:
            return f.read().splitlines()

    def test_counts_per_folder(self):
        self.write_results({"spec@glsl-1.30@a.vert": "pass", "spec@glsl-1.30@b.vert": "warn",
                            "spec@glsl-1.30@c.vert": "skip", "spec@glsl-1.40@d.vert": "crash",
                            "spec@glsl-1.40@e.vert": "incomplete", "spec@glsl-1.40@f.vert": "fail"})
        counts = os.path.join(self.dir.name, "counts.txt")
        rc, out = self.run_compare("--counts", counts)
        self.assertEqual(rc, 1, out)
        lines = self.read_counts(counts)
        self.assertIn("folder spec@glsl-1.30@ total 3 pass 1 fail 1 skip 1 crash 0 timeout 0", lines)
        self.assertIn("folder spec@glsl-1.40@ total 3 pass 0 fail 1 skip 0 crash 1 timeout 1", lines)
        self.assertIn("per folder", out)

    def test_folders_restrict_the_comparison(self):
        self.write_results({"spec@glsl-1.10@a.vert": "pass", "spec@glsl-1.30@b.vert": "fail",
                            "spec@glsl-1.30@c.vert": "crash"})
        self.write_expected("spec@glsl-1.10@gone.vert # removed\n")
        counts = os.path.join(self.dir.name, "counts.txt")
        rc, out = self.run_compare("--folders", "spec@glsl-1.10@,spec@glsl-3.30@",
                                   "--counts", counts, "--title", "legacy")
        self.assertEqual(rc, 0, "the glsl-1.30 failure and crash are outside the folders: " + out)
        self.assertIn("legacy: 1 tests: 1 pass", out)
        self.assertIn("Listed but not run (1)", out)
        lines = self.read_counts(counts)
        self.assertIn("total 1", lines)
        self.assertIn("folder spec@glsl-1.10@ total 1 pass 1 fail 0 skip 0 crash 0 timeout 0", lines)
        self.assertIn("folder spec@glsl-3.30@ total 0 pass 0 fail 0 skip 0 crash 0 timeout 0", lines)
        self.assertFalse(any("glsl-1.30" in l for l in lines), lines)

    def test_bless_keeps_to_the_folders(self):
        self.write_results({"spec@glsl-1.10@a.vert": "fail", "spec@glsl-1.30@b.vert": "fail"})
        rc, _ = self.run_compare("--folders", "spec@glsl-1.30@", "--bless")
        self.assertEqual(rc, 0)
        with open(self.expected) as f:
            self.assertEqual(f.read(), "spec@glsl-1.30@b.vert # TODO: triage\n")

    def test_total_is_checked_against_the_profile(self):
        profile = self.write_profile(["spec@glsl-1.30@a.vert", "spec@glsl-1.30@b.vert",
                                      "spec@glsl-1.20@c.vert"])
        self.write_results({"spec@glsl-1.30@a.vert": "pass", "spec@glsl-1.30@b.vert": "pass"})
        rc, out = self.run_compare("--folders", "spec@glsl-1.30@", "--profile", profile)
        self.assertEqual(rc, 0, out)
        self.write_results({"spec@glsl-1.30@a.vert": "pass"})
        rc, _ = self.run_compare("--folders", "spec@glsl-1.30@", "--profile", profile)
        self.assertEqual(rc, 2, "a test of the profile is missing from the results")
        p = subprocess.run([sys.executable, SCRIPT, "--count-profile", profile,
                            "--folders", "spec@glsl-1.30@,spec@glsl-1.20@"],
                           capture_output=True, text=True)
        self.assertEqual((p.returncode, p.stdout), (0, "3\n"))

    def test_summary_only_needs_no_list_and_gives_no_verdict(self):
        self.write_results({"spec@glsl-1.30@a.vert": "fail", "spec@glsl-1.30@b.vert": "crash",
                            "spec@glsl-1.30@c.vert": "pass"})
        counts = os.path.join(self.dir.name, "counts.txt")
        p = subprocess.run([sys.executable, SCRIPT, self.results, "--summary-only",
                            "--counts", counts, "--title", "mesa"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        self.assertIn("Neither passed nor skipped (2)", p.stdout)
        self.assertIn("mesa: 3 tests: 1 pass, 1 fail, 1 crash", p.stdout)
        lines = self.read_counts(counts)
        self.assertIn("folder spec@glsl-1.30@ total 3 pass 1 fail 1 skip 0 crash 1 timeout 0", lines)
        self.assertNotIn("new-failures 1", lines)

    def test_missing_results_is_a_setup_error(self):
        rc, _ = self.run_compare()
        self.assertEqual(rc, 2)


if __name__ == "__main__":
    unittest.main()
