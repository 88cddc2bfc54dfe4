#!/usr/bin/env python3
"""Writes the seed corpora of the reader fuzz targets, fuzz/corpus/fuzz_read_<fmt>/: small
valid files in the variants each reader accepts, plus this format's malformed corpus files
(tests/data/io/malformed/). Inputs kept from fuzzing runs (found-<sha1>, merged with
libFuzzer -merge=1) and crash inputs (regression-<name>) are kept when this script re-runs."""
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_header(fmt, xyz_type="float", extra=""):
    return ("ply\nformat %s 1.0\ncomment seed\nelement vertex 4\n" % fmt +
            "".join("property %s %s\n" % (xyz_type, a) for a in "xyz") +
            "property uchar red\nproperty double radius\n" + extra +
            "element face 4\nproperty list uchar int vertex_indices\n"
            "element edge 1\nproperty int a\nproperty list ushort uint b\nend_header\n")


def ply_binary(endian, xyz_type):
    code = "f" if xyz_type == "float" else "d"
    body = b""
    for i, p in enumerate(TETRA):
        body += struct.pack(endian + "3" + code + "Bd", *p, 200, 0.5 * i)
    for f in FACES:
        body += struct.pack(endian + "B3i", 3, *f)
    body += struct.pack(endian + "iH2I", 7, 2, 1, 2)
    name = "binary_little_endian" if endian == "<" else "binary_big_endian"
    return ply_header(name, xyz_type).encode() + body


def ply_ascii():
    body = "".join("%g %g %g 200 %g\n" % (*p, 0.5 * i) for i, p in enumerate(TETRA))
    body += "".join("3 %d %d %d\n" % f for f in FACES) + "7 2 1 2\n"
    return (ply_header("ascii", "double") + body).encode()


SEEDS = {
    "ply": {
        "tetra_le_float.ply": ply_binary("<", "float"),
        "tetra_be_double.ply": ply_binary(">", "double"),
        "tetra_ascii.ply": ply_ascii(),
        "points_only.ply": b"ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                           b"property float y\nproperty float z\nend_header\n0 0 0\n1 2 3\n",
    },
    "off": {
        "tetra.off": ("OFF\n4 4 6\n" + "".join("%g %g %g\n" % p for p in TETRA) +
                      "".join("3 %d %d %d\n" % f for f in FACES)).encode(),
        "coff_comments.off": b"# seed\nCOFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                             b"0 1 0 0 0 255 255 # c\n3 0 1 2 1 1 1\n",
        "no_keyword.off": b"2 0\n1e-300 -2.5 +3\n0 0 0\n",
    },
    "obj": {
        "tetra.obj": ("# seed\no tetra\n" + "".join("v %g %g %g\n" % p for p in TETRA) +
                      "vt 0 0\nvn 0 0 1\n" +
                      "".join("f %d/1/1 %d//1 %d\n" % tuple(i + 1 for i in f) for f in FACES) +
                      "f -1 -2 -3 -4\n").encode(),
        "quad.obj": b"v 0 0 0 1\nv 1 0 0\nv 1 1 0\nv 0 1 0 0.5 0.5 0.5\nusemtl m\ns 1\nf 1 2 3 4\n",
    },
    "xyz": {
        "points.xyz": b"# x y z\n0 0 0\n1,2,3\n4 5 6 7\n-1e-5 2e10 .5 0.25 9\n",
        "weights.xyz": b"0 0 0 1\n1 0 0 2\n0 1 0 3.5\n",
    },
}

if __name__ == "__main__":
    malformed = os.path.join(HERE, "malformed")
    for fmt, seeds in SEEDS.items():
        out = os.path.join(ROOT, "fuzz", "corpus", "fuzz_read_" + fmt)
        os.makedirs(out, exist_ok=True)
        for f in os.listdir(out):
            if not f.startswith(("regression-", "found-")):
                os.remove(os.path.join(out, f))
        for name, content in seeds.items():
            with open(os.path.join(out, name), "wb") as f:
                f.write(content)
        for name in sorted(os.listdir(malformed)):
            if name.endswith("." + fmt):
                shutil.copy(os.path.join(malformed, name), os.path.join(out, "malformed-" + name))
