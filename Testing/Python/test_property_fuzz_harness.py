"""The property fuzz's harness (test_property_fuzz.py) catches what it promises to: a trial that
kills its worker process and a trial that hangs are each reported as a failure with the one-line
reproducer of that trial, the trials after them still run, and the run fails. The failures are
simulated (BOOSTEDSURFACES_FUZZ_SIMULATE) in a short run.

    PYTHONPATH=<build>/lib/python3.11/site-packages:Testing/Support \\
        /usr/bin/python3 Testing/Python/test_property_fuzz_harness.py -v
"""
import os
import subprocess
import sys
import unittest

FUZZ = os.path.join(os.path.dirname(os.path.abspath(__file__)), "test_property_fuzz.py")


def run_fuzz(simulate, *arguments):
    environment = dict(os.environ, BOOSTEDSURFACES_FUZZ_SIMULATE=simulate)
    return subprocess.run([sys.executable, FUZZ, "--seed", "5"] + list(arguments),
                          env=environment, capture_output=True, text=True, timeout=300)


class HarnessTest(unittest.TestCase):
    def test_a_crash_and_a_hang_are_failures_with_their_reproducers(self):
        result = run_fuzz("crash:2,hang:4", "--trials", "7", "--timeout", "5")
        self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
        lines = result.stdout.splitlines()
        crash = [line for line in lines if line.startswith("FAIL trial 2 ")]
        hang = [line for line in lines if line.startswith("FAIL trial 4 ")]
        self.assertEqual(len(crash), 1, result.stdout)
        self.assertIn("[crash] the process died (signal SIGABRT)", crash[0])
        self.assertEqual(len(hang), 1, result.stdout)
        self.assertIn("[hang] no result after 5 s", hang[0])
        reproducers = [line.strip() for line in lines if line.strip().startswith("reproduce:")]
        self.assertEqual(len(reproducers), 2, result.stdout)
        self.assertTrue(reproducers[0].endswith("test_property_fuzz.py --seed 5 --trial 2"))
        self.assertTrue(reproducers[1].endswith("test_property_fuzz.py --seed 5 --trial 4"))
        self.assertIn("2 failed trials", result.stdout)
        # The other five trials ran: each class's updates were counted.
        updates = sum(int(line.split(":")[1].split()[0]) for line in lines
                      if line.startswith("  vtk"))
        self.assertGreaterEqual(updates, 5, result.stdout)

    def test_a_clean_run_passes(self):
        result = run_fuzz("", "--trials", "10")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("0 failed trials", result.stdout)

    def test_a_replayed_trial_prints_its_calls(self):
        result = run_fuzz("", "--trial", "3")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("# seed 5 trial 3: vtk", result.stdout)
        self.assertIn("trial 3: passed", result.stdout)


if __name__ == "__main__":
    unittest.main()
