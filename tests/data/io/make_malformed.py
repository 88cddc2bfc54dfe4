#!/usr/bin/env python3
"""Writes the malformed-input corpus (tests/data/io/malformed/) and its manifest
malformed.tsv: one line per file, "<file>\t<fragment the error message must contain>".
Every file must be rejected by its reader with rstruct::InvalidInput (CLI exit code 2).
Run from anywhere; the output lands beside this script. The files are committed, so this
only needs re-running when a case is added."""
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "malformed")
cases = []


def case(name, content, fragment):
    if isinstance(content, str):
        content = content.encode("latin-1")
    cases.append((name, content, fragment))


def ply(fmt, header_lines, body=b""):
    head = "ply\nformat %s 1.0\n" % fmt + "".join(l + "\n" for l in header_lines) + "end_header\n"
    return head.encode() + (body if isinstance(body, bytes) else body.encode())


def xyz_header(n, t="double"):
    return ["element vertex %d" % n] + ["property %s %s" % (t, a) for a in "xyz"]


# --- PLY header ---
case("ply_empty.ply", "", "not a PLY file")
case("ply_no_magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY file")
case("ply_no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n",
     "no 'end_header'")
case("ply_no_format.ply", "ply\nelement vertex 1\nend_header\n", "must give 'format'")
case("ply_bad_format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown PLY format")
case("ply_bad_version.ply", "ply\nformat ascii 2.0\nend_header\n", "unsupported PLY version")
case("ply_unknown_type.ply", ply("ascii", ["element vertex 1", "property float128 x"]),
     "unknown PLY property type")
case("ply_property_before_element.ply", ply("ascii", ["property float x"]),
     "property declared before any element")
case("ply_duplicate_element.ply",
     ply("ascii", xyz_header(1) + ["element vertex 1"], "0 0 0\n"), "duplicate element")
case("ply_duplicate_property.ply",
     ply("ascii", xyz_header(1) + ["property double x"], "0 0 0 0\n"), "duplicate property")
case("ply_list_count_float.ply",
     ply("ascii", xyz_header(1) + ["element face 1", "property list float int vertex_indices"]),
     "list count type must be an integer type")
case("ply_int_coordinates.ply", ply("ascii", xyz_header(1, "int"), "0 0 0\n"),
     "must be float or double, not int")
case("ply_list_coordinate.ply",
     ply("ascii", ["element vertex 1", "property list uchar float x", "property float y",
                   "property float z"], "1 0 0 0\n"), "must be float or double, not a list")
case("ply_missing_z.ply",
     ply("ascii", ["element vertex 1", "property float x", "property float y"], "0 0\n"),
     "needs float or double properties x, y and z")
case("ply_no_vertex_element.ply",
     ply("ascii", ["element point 1", "property float x"], "0\n"), "declares no 'vertex' element")
case("ply_zero_vertices.ply", ply("ascii", xyz_header(0)), "empty input")
case("ply_face_indices_float.ply",
     ply("ascii", xyz_header(3) + ["element face 1", "property list uchar float vertex_indices"],
         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "must be a list of integers")
case("ply_face_without_indices.ply",
     ply("ascii", xyz_header(1) + ["element face 1", "property uchar flags"], "0 0 0\n1\n"),
     "has no 'vertex_indices' list property")
case("ply_unknown_keyword.ply", ply("ascii", ["elephant vertex 1"]), "unknown PLY header keyword")
case("ply_vertex_count_overflow.ply",
     ply("ascii", ["element vertex 99999999999999999999999"] + xyz_header(0)[1:]), "is outside")
case("ply_too_many_vertices.ply", ply("binary_little_endian", xyz_header(5000000000, "float")),
     "more than 2^32 - 1 vertices")
# --- PLY body: counts against file size, truncation ---
case("ply_huge_count_binary.ply",
     ply("binary_little_endian", xyz_header(4000000000), struct.pack("<3d", 1, 2, 3)),
     "bytes are left")
case("ply_huge_count_ascii.ply", ply("ascii", xyz_header(4000000000), "1 2 3\n"),
     "lines (")
case("ply_truncated_binary.ply",
     ply("binary_little_endian", xyz_header(3), struct.pack("<8d", *range(8))),
     "declares 3 instances")
case("ply_truncated_binary_faces.ply",
     ply("binary_little_endian",
         xyz_header(3, "float") + ["element face 2", "property list uchar int vertex_indices"],
         struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2) +
         struct.pack("<Bi", 3, 0)), "runs past the end of the file")
case("ply_truncated_ascii.ply",
     ply("ascii", xyz_header(5),
         "0.000 0.000 0.000\n1.000 0.000 0.000\n0.000 1.000 0.000\n0.000 0.000 1.000\n"),
     "unexpected end of file")
case("ply_huge_list_binary.ply",
     ply("binary_little_endian",
         xyz_header(1, "float") + ["element face 1", "property list uint int vertex_indices"],
         struct.pack("<3f", 0, 0, 0) + struct.pack("<I", 4000000000) + b"\0" * 12),
     "runs past the end of the file")
case("ply_negative_list_length.ply",
     ply("binary_little_endian",
         xyz_header(1, "float") + ["element edge 1", "property list int int vertex_indices"],
         struct.pack("<3f", 0, 0, 0) + struct.pack("<i", -5)), "negative list length")
# --- PLY values ---
case("ply_nan_binary.ply",
     ply("binary_little_endian", xyz_header(1), struct.pack("<3d", 0, float("nan"), 0)),
     "NaN or infinite")
case("ply_inf_big_endian.ply",
     ply("binary_big_endian", xyz_header(2, "float"),
         struct.pack(">6f", 0, 0, 0, 1, float("inf"), 0)), "NaN or infinite")
case("ply_nan_property_binary.ply",
     ply("binary_little_endian", xyz_header(1) + ["property double radius"],
         struct.pack("<4d", 0, 0, 0, float("nan"))), "property 'radius' is NaN or infinite")
case("ply_inf_ascii.ply", ply("ascii", xyz_header(1), "0 inf 0\n"), "NaN/Inf")
case("ply_nan_ascii.ply", ply("ascii", xyz_header(1), "nan 0 0\n"), "NaN/Inf")
case("ply_bad_number_ascii.ply", ply("ascii", xyz_header(1), "0 1.0.0 0\n"), "expected a number")
case("ply_extra_values_ascii.ply", ply("ascii", xyz_header(1), "0 0 0 0\n"), "extra values")
case("ply_too_few_values_ascii.ply", ply("ascii", xyz_header(2), "0.0 0.0\n0.0 0.0 0.0\n"),
     "too few values")
case("ply_uchar_out_of_range_ascii.ply",
     ply("ascii", xyz_header(1) + ["property uchar label"], "0 0 0 300\n"), "outside [0, 255]")
case("ply_int_not_integer_ascii.ply",
     ply("ascii", xyz_header(1) + ["property int label"], "0 0 0 1.5\n"), "expected an integer")
# --- PLY faces ---
FACE_HDR = xyz_header(3) + ["element face 1", "property list uchar int vertex_indices"]
TRI = "0 0 0\n1 0 0\n0 1 0\n"
case("ply_face_index_out_of_range.ply", ply("ascii", FACE_HDR, TRI + "3 0 1 3\n"),
     "outside [0, 3)")
case("ply_face_negative_index.ply", ply("ascii", FACE_HDR, TRI + "3 0 -1 2\n"), "outside [0, 3)")
case("ply_face_two_vertices.ply", ply("ascii", FACE_HDR, TRI + "2 0 1\n"), "at least 3 needed")
case("ply_face_index_binary.ply",
     ply("binary_little_endian", FACE_HDR,
         struct.pack("<9d", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 7, 1)),
     "face vertex index 7 is outside [0, 3)")

# --- OFF ---
case("off_empty.off", "", "empty input")
case("off_comments_only.off", "# nothing\n\n   # here\n", "empty input")
case("off_not_off.off", "PLY\n3 1 0\n", "not an OFF file")
case("off_4d.off", "4OFF\n1 0 0\n0 0 0 0\n", "unsupported OFF variant")
case("off_binary.off", "OFF BINARY\n", "binary OFF is not supported")
case("off_bad_counts.off", "OFF\n3\n0 0 0\n", "counts line must be")
case("off_negative_count.off", "OFF\n-3 1 0\n", "is outside")
case("off_zero_vertices.off", "OFF\n0 0 0\n", "empty input")
case("off_huge_count.off", "OFF\n4000000000 1 0\n0 0 0\n", "more than the remaining")
case("off_truncated_vertices.off",
     "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n# a long comment line that pads the file\n",
     "unexpected end of file after 3 of 4 vertices")
case("off_truncated_faces.off",
     "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# a long comment line that pads the file\n",
     "after 1 of 2 faces")
case("off_nan.off", "OFF\n3 0 0\n0 0 0\nnan 0 0\n0 1 0\n", "NaN/Inf")
case("off_overflow.off", "OFF\n3 0 0\n0 0 0\n1e400 0 0\n0 1 0\n", "out of the range of double")
case("off_vertex_two_coordinates.off", "OFF\n3 0 0\n0.0 0.0 0.0\n1.0 0.0\n0.0 1.0 0.0\n",
     "needs x y z")
case("off_bad_number.off", "OFF\n3 0 0\n0 0 0\n1 0 abc\n0 1 0\n", "expected a number")
case("off_face_index_out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
     "outside [0, 2]")
case("off_face_lists_fewer.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "lists fewer")
case("off_face_two_vertices.off", "OFF\n3 1 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n2 0 1\n",
     "at least 3 needed")
case("off_face_float_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.0\n",
     "expected an integer")

# --- OBJ ---
case("obj_empty.obj", "", "empty input")
case("obj_no_vertices.obj", "# only normals\no thing\nvn 0 0 1\n", "empty input")
case("obj_unknown_statement.obj", "v 0 0 0\nxyz 1 2 3\n", "unknown OBJ statement")
case("obj_binary_garbage.obj", b"\x7fELF\x02\x01\x01\x00\x00\x00\n\x03\x00>\x00", "unknown OBJ statement")
case("obj_nan.obj", "v 0 0 0\nv NaN 0 0\n", "NaN/Inf")
case("obj_short_vertex.obj", "v 0 0 0\nv 1 2\n", "'v' needs x y z")
case("obj_index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "index 0")
case("obj_index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
     "face vertex index 4 but the file has only 3 vertices")
case("obj_relative_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
     "relative face index -4")
case("obj_face_two_vertices.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "at least 3 needed")
case("obj_bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 x/3\n", "expected an integer")
case("obj_huge_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n", "is outside")

# --- XYZ ---
case("xyz_empty.xyz", "", "empty input")
case("xyz_comments_only.xyz", "# x y z\n\n", "empty input")
case("xyz_two_columns.xyz", "0 0 0\n1 2\n", "expected x y z")
case("xyz_nan.xyz", "0 0 0\n1 nan 2\n", "NaN/Inf")
case("xyz_minus_inf.xyz", "0 0 0\n1 2 -inf\n", "NaN/Inf")
case("xyz_overflow.xyz", "0 0 0\n1e999 2 3\n", "out of the range of double")
case("xyz_header_words.xyz", "x y z\n0 0 0\n", "expected a number")
case("xyz_binary_garbage.xyz", b"\x00\x01\x02 \xff\xfe abc\n", "expected a number")

if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    with open(os.path.join(HERE, "malformed.tsv"), "w") as manifest:
        manifest.write("# file\texpected message fragment (written by make_malformed.py)\n")
        for name, content, fragment in cases:
            with open(os.path.join(OUT, name), "wb") as f:
                f.write(content)
            manifest.write("%s\t%s\n" % (name, fragment))
    print("wrote %d files" % len(cases), file=sys.stderr)
