#!/usr/bin/env python3
"""Runs `rstruct convert FILE -o OUT.ply` on every file of the malformed corpus
(tests/data/io/malformed.tsv) and checks: exit code 2, the expected fragment and the file
name on stderr, and no output file (not even a temporary one) left behind."""
import os
import subprocess
import sys
import tempfile


def main():
    exe, data_dir = sys.argv[1], sys.argv[2]
    failures = 0
    count = 0
    with open(os.path.join(data_dir, "malformed.tsv")) as manifest, \
            tempfile.TemporaryDirectory() as out_dir:
        for line in manifest:
            if line.startswith("#") or not line.strip():
                continue
            name, fragment = line.rstrip("\n").split("\t")
            path = os.path.join(data_dir, "malformed", name)
            out = os.path.join(out_dir, "out.ply")
            proc = subprocess.run([exe, "convert", path, "-o", out], capture_output=True,
                                  timeout=60)
            stderr = proc.stderr.decode("utf-8", "replace")
            problems = []
            if proc.returncode != 2:
                problems.append("exit code %d, expected 2" % proc.returncode)
            if fragment not in stderr:
                problems.append("message lacks %r" % fragment)
            if name not in stderr:
                problems.append("message does not name the file")
            if os.listdir(out_dir):
                problems.append("left output files %s" % os.listdir(out_dir))
                for f in os.listdir(out_dir):
                    os.remove(os.path.join(out_dir, f))
            count += 1
            if problems:
                failures += 1
                print("FAIL %s: %s\n  stderr: %s" % (name, "; ".join(problems), stderr.strip()))
    # A missing input is an I/O error: exit code 2 as well.
    proc = subprocess.run([exe, "convert", os.path.join(data_dir, "no-such-file.ply"), "-o",
                           os.devnull + ".ply"], capture_output=True, timeout=60)
    if proc.returncode != 2:
        failures += 1
        print("FAIL missing input: exit code %d" % proc.returncode)
    print("%d corpus files, %d failures" % (count, failures))
    return 1 if failures or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
