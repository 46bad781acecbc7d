#!/usr/bin/env python3
"""Writes the small input files of test/cli/cases_readers.txt (test/cli/inputs/readers_*): good and bad
meshes (OFF, PLY ascii and binary in both byte orders, OBJ, STL ascii and binary), DIMACS max-flow files and
points files, one per reproducer of issue 28. Run it from anywhere; it rewrites the files next to itself."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(HERE, "readers_" + name), mode) as f:
        f.write(data)


# A closed octahedron (6 vertices, 8 outward triangles): the good mesh of every format.
V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def off(vertices, faces, header="OFF", counts=None):
    lines = [header, counts or f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(str(c) for c in v) for v in vertices]
    lines += [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def ply_ascii(vertices, faces):
    head = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property float x", "property float y",
            "property float z", f"element face {len(faces)}", "property list uchar int vertex_indices", "end_header"]
    body = [" ".join(str(c) for c in v) for v in vertices] + [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    return "\n".join(head + body) + "\n"


def ply_binary(vertices, faces, big_endian=False, index_type="i", count=None):
    e = ">" if big_endian else "<"
    type_name = {"i": "int", "I": "uint", "h": "short"}[index_type]
    head = ["ply", "format binary_%s_endian 1.0" % ("big" if big_endian else "little"), "comment MDCS reader test",
            f"element vertex {len(vertices)}", "property float x", "property float y", "property float z",
            "property uchar quality", f"element face {len(faces) if count is None else count}",
            f"property list uchar {type_name} vertex_indices", "property float weight", "end_header"]
    data = ("\n".join(head) + "\n").encode()
    for v in vertices:
        data += struct.pack(e + "fffB", *v, 7)
    for f in faces:
        data += struct.pack(e + "B" + index_type * len(f) + "f", len(f), *f, 0.5)
    return data


def obj(vertices, faces_text):
    return "".join(f"v {x} {y} {z}\n" for x, y, z in vertices) + faces_text


def stl_ascii(vertices, faces):
    out = "solid octahedron\n"
    for f in faces:
        out += "  facet normal 0 0 0\n    outer loop\n"
        for i in f:
            out += "      vertex %g %g %g\n" % vertices[i]
        out += "    endloop\n  endfacet\n"
    return out + "endsolid octahedron\n"


def stl_binary(vertices, faces, count=None):
    data = b"binary STL written by the MDCS reader tests".ljust(80, b" ")
    data += struct.pack("<I", len(faces) if count is None else count)
    for f in faces:
        data += struct.pack("<3f", 0, 0, 0)
        for i in f:
            data += struct.pack("<3f", *vertices[i])
        data += struct.pack("<H", 0)
    return data


# --- Good meshes -------------------------------------------------------------------------------------------
write("octahedron.off", off(V, F))
write("octahedron_colours.off", "COFF\n# a comment line\n6 8 12\n" +
      "".join(f"{x} {y} {z} 255 0 0 255\n" for x, y, z in V) +
      "".join(f"3 {a} {b} {c} 0.5 0.5 0.5\n" for a, b, c in F))
write("octahedron_ascii.ply", ply_ascii(V, F))
write("octahedron_le.ply", ply_binary(V, F))
write("octahedron_be.ply", ply_binary(V, F, big_endian=True, index_type="I"))
write("octahedron.obj", "# OBJ with texture and normal references, groups, and relative indices\no octa\n" +
      obj(V, "vt 0 0\nvn 0 0 1\ng all\ns off\nusemtl none\n") +
      "f 1/1/1 3/1/1 5/1/1\nf 3//1 2//1 5//1\nf 2/1 4/1 5/1\nf 4 1 5\n" +
      "".join("f %d %d %d\n" % tuple(i - 6 for i in f) for f in F[4:]))  # relative: -1 is the last vertex
write("octahedron_ascii.stl", stl_ascii(V, F))
write("octahedron_binary.stl", stl_binary(V, F))
write("octahedron.mesh", off(V, F))  # unknown extension: the content says OFF
# A cube of quads: triangulated with a note.
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_F = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
write("cube_quads.off", off(CUBE_V, CUBE_F))

# --- Bad meshes: the reproducers of issue 28 ---------------------------------------------------------------
bad_ply = ply_ascii(V, F[:-1] + [(0, 3, 600)])
write("index_out_of_range_ascii.ply", bad_ply)
write("index_negative_ascii.ply", ply_ascii(V, F[:-1] + [(0, 3, -2)]))
write("index_out_of_range_le.ply", ply_binary(V, F[:-1] + [(0, 3, 600)]))
write("index_negative_le.ply", ply_binary(V, F[:-1] + [(0, -3, 5)]))
write("index_out_of_range_be.ply", ply_binary(V, F[:-1] + [(0, 3, 1 << 30)], big_endian=True))
write("element_count_huge.ply", ply_binary(V, F, count=2000000000))
write("list_count_huge.ply", ply_ascii(V, F[:-1]).replace("element face 7", "element face 8") + "250 0 1 2\n")
write("truncated_le.ply", ply_binary(V, F)[:-7])
write("index_zero.obj", obj(V, "f 0 1 2\n"))
write("index_beyond.obj", obj(V, "f 1 2 9\n"))
write("relative_before_first.obj", obj(V, "f -1 -2 -7\n"))
write("garbage_line.obj", obj(V, "f 1 2 3\n\x01\x02garbage\n"))
write("face_count_1e9.off", off(V, F[:-1], counts="6 8 0") + "1000000000 0 1 2\n")
write("header_count_1e9.off", off(V, F, counts="6 1000000000 0"))
write("index_negative.off", off(V, F[:-1] + [(0, -1, 5)]))
write("index_out_of_range.off", off(V, F[:-1] + [(0, 6, 5)]))
write("nan.off", off(V[:-1] + [("nan", 0, -1)], F))
write("inf.off", off(V[:-1] + [(0, "inf", -1)], F))
write("overflow.off", off(V[:-1] + [(0, 0, "1e400")], F))
write("truncated.off", off(V, F)[:-12])
write("trailing.off", off(V, F) + "3 0 1 2\n")
write("two_corners.off", off(V, F[:-1] + [(0, 3)]))
write("empty.off", "")
write("garbage.off", bytes(range(256)) * 4)
write("garbage.ply", b"ply\n\xff\xfe\x00garbage")
write("truncated_binary.stl", stl_binary(V, F)[:-20])
write("count_mismatch_binary.stl", stl_binary(V, F, count=9))
write("four_vertices.stl", stl_ascii(V, F).replace("      vertex 0 0 1\n    endloop", "      vertex 0 0 1\n      vertex 0 0 2\n    endloop", 1))
write("no_faces.off", off(V, []))
write("unknown.xyz", "hello world\n")

# --- Surfaces that are not valid oriented manifold meshes -----------------------------------------------------
# Three triangles on the edge (0, 1): a non-manifold fan of three sheets (closed by nothing: open sheets).
write("three_sheets.off", off([(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -1, 0), (0.5, 0, 1)],
                                [(0, 1, 2), (1, 0, 3), (0, 1, 4)]))
# A Moebius strip: 6 quads around a twisted band, as triangles.
import math
mv = []
n = 6
for i in range(n):
    t = 2 * math.pi * i / n
    for s in (-0.3, 0.3):
        w = s * math.cos(t / 2)
        mv.append((round((1 + w) * math.cos(t), 6), round((1 + w) * math.sin(t), 6), round(s * math.sin(t / 2), 6)))
mf = []
for i in range(n):
    a, b = 2 * i, 2 * i + 1
    if i + 1 < n:
        c, d = 2 * i + 2, 2 * i + 3
    else:
        c, d = 1, 0  # the twist: the last quad joins the strip's two sides swapped
    mf += [(a, c, d), (a, d, b)]
write("moebius.off", off(mv, mf))
# Two tetrahedra that share one vertex: a pinched vertex.
TV = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1)]
TF = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3), (0, 4, 5), (0, 6, 4), (0, 5, 6), (4, 6, 5)]
write("pinched.obj", obj(TV, "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in TF)))
# The octahedron with two faces flipped: orientable, but not consistently oriented.
write("flipped.off", off(V, [(0, 4, 2), (1, 2, 4)] + F[2:]))

# --- DIMACS max-flow files -----------------------------------------------------------------------------------
GOOD = "c a small network: max flow 5\np max 4 5\nn 1 s\nn 4 t\na 1 2 3\na 1 3 2\na 2 3 1\na 2 4 2\na 3 4 3\n"
write("good.max", GOOD)
write("second_p.max", GOOD.replace("a 1 2 3\n", "a 1 2 3\np max 2 1\n"))
write("huge_nodes.max", "p max 300000000 1\nn 1 s\nn 300000000 t\na 1 300000000 7\n")
write("two_sources.max", GOOD.replace("n 4 t\n", "n 4 t\nn 2 s\n"))
write("blank_line.max", GOOD.replace("a 2 3 1\n", "a 2 3 1\n   \t \n\n"))
write("inf_capacity.max", GOOD.replace("a 2 3 1", "a 2 3 inf"))
write("nan_capacity.max", GOOD.replace("a 2 3 1", "a 2 3 nan"))
write("negative_capacity.max", GOOD.replace("a 2 3 1", "a 2 3 -1"))
write("node_out_of_range.max", GOOD.replace("a 2 3 1", "a 2 5 1"))
write("truncated.max", GOOD[:-8])
write("trailing_text.max", GOOD.replace("a 2 3 1", "a 2 3 1 x"))
write("arc_before_p.max", "a 1 2 3\n" + GOOD)
write("unknown_line.max", GOOD + "x 1 2\n")
write("source_is_sink.max", GOOD.replace("n 4 t", "n 1 t"))
write("no_sink.max", GOOD.replace("n 4 t\n", ""))
write("empty.max", "")
write("garbage.max", bytes(range(256)))

# --- Points files (mdcs mwt) -----------------------------------------------------------------------------------
write("good.xy", "# points of a convex pentagon and its centre\nx,y\n0,0\n1,0\n1.3,0.9\n0.5,1.5\n-0.3,0.9\n\n0.5 0.6\n")
write("nan.xy", "0 0\n1 0\nnan 1\n")
write("inf.xy", "0 0\n1 0\n0 inf\n")
write("overflow.xy", "0 0\n1 0\n0 1e400\n")
write("three_coordinates.xy", "0 0\n1 0 0\n0 1\n")
write("empty_field.xy", "0,0\n1,,0\n0,1\n")
write("trailing_text.xy", "0 0\n1 0\n0 1x\n")
write("no_points.xy", "# only a comment\n\n")
write("garbage.xy", bytes(range(256)))
