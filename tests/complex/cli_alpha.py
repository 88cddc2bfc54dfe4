#!/usr/bin/env python3
"""`rstruct alpha` end to end.

1. The kept balls of `rstruct seed --balls` (a torus sample): the simplices with alpha <= 0
   are, per dimension, as many as the seed run's dual complex K (its report), which the
   pipeline classifies with another code path (triangulation_dual_complex.cpp).
2. The output is a filtration: alpha non-decreasing, vertex ids increasing within a line,
   every face of a simplex listed before it, every simplex once.
3. The same balls as .xyzr (radii printed with 17 significant digits, which read back to
   the same doubles) give the same file.
4. Bad input (three balls; a malformed line; a missing radius property) exits with 2 and
   leaves no output file."""
import itertools
import json
import os
import struct
import subprocess
import sys
import tempfile


def run(exe, *args, expect=0):
    proc = subprocess.run([exe, *args], capture_output=True, timeout=600)
    if proc.returncode != expect:
        raise SystemExit("FAIL: %s exited %d (expected %d)\n%s" % (
            " ".join(args), proc.returncode, expect, proc.stderr.decode("utf-8", "replace")))
    return proc


def read_ply_balls(path):
    """x y z radius of a binary little-endian PLY whose vertex properties are doubles."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    count = next(int(l.split()[2]) for l in header if l.startswith("element vertex"))
    props = [l.split()[2] for l in header if l.startswith("property double")]
    assert len(props) == len([l for l in header if l.startswith("property")]), header
    rows = struct.iter_unpack("<%dd" % len(props), data[end:end + 8 * len(props) * count])
    return [tuple(r[props.index(k)] for k in ("x", "y", "z", "radius")) for r in rows]


def check_filtration(path):
    seen = set()
    last = -float("inf")
    counts = [0, 0, 0, 0]
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            fields = line.split()
            alpha, dim, vs = float(fields[0]), int(fields[1]), [int(x) for x in fields[2:]]
            assert len(vs) == dim + 1, line
            assert vs == sorted(set(vs)), "vertex ids not increasing: " + line
            assert alpha >= last, "alpha decreases at: " + line
            last = alpha
            for k in range(1, dim + 1):
                for face in itertools.combinations(vs, k):
                    assert face in seen, "face %s listed after %s" % (face, line)
            assert tuple(vs) not in seen, "listed twice: " + line
            seen.add(tuple(vs))
            if alpha <= 0:
                counts[dim] += 1
    return counts


def main():
    exe = sys.argv[1]
    with tempfile.TemporaryDirectory() as d:
        p = lambda name: os.path.join(d, name)
        run(exe, "sample", "torus", "--n", "2000", "--seed", "5", "-o", p("t.ply"), "--quiet")
        run(exe, "seed", p("t.ply"), "-o", p("s.ply"), "--balls", p("kb.ply"),
            "--report", p("seed.json"), "--quiet")
        run(exe, "alpha", p("kb.ply"), "-o", p("f.txt"), "--report", p("alpha.json"), "--quiet")
        k = json.load(open(p("seed.json")))["dual_complex"]["simplices"]
        report = json.load(open(p("alpha.json")))
        counts = check_filtration(p("f.txt"))
        assert counts == k, "alpha <= 0 gives %s, the seed run's K %s" % (counts, k)
        assert report["dual_complex_simplices"] == k, report
        total = sum(report["simplices"])
        assert total == sum(1 for l in open(p("f.txt")) if not l.startswith("#")), total

        balls = read_ply_balls(p("kb.ply"))
        with open(p("kb.xyzr"), "w") as f:
            for b in balls:
                f.write(" ".join("%.17g" % x for x in b) + "\n")
        run(exe, "alpha", p("kb.xyzr"), "-o", p("g.txt"), "--quiet")
        body = lambda name: [l for l in open(p(name)) if not l.startswith("#")]
        assert body("f.txt") == body("g.txt"), "the .xyzr input gives another filtration"

        with open(p("three.xyzr"), "w") as f:
            f.write("0 0 0 1\n1 0 0 1\n0 1 0 1\n")
        with open(p("bad.xyzr"), "w") as f:
            f.write("0 0 0 1\n1 0 0\n")
        with open(p("noradius.xyz"), "w") as f:
            f.write("0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
        for name in ("three.xyzr", "bad.xyzr", "noradius.xyz"):
            out = p("out_" + name + ".txt")
            proc = run(exe, "alpha", p(name), "-o", out, expect=2)
            message = proc.stderr.decode("utf-8", "replace")
            assert "error" in message, message
            assert not os.path.exists(out), "output written for " + name
            assert not [x for x in os.listdir(d) if x.startswith("out_")], os.listdir(d)
    print("cli_alpha: seed K %s = alpha <= 0 counts; %d simplices in filtration order" %
          (k, total))


if __name__ == "__main__":
    main()
