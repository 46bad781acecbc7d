# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad input to every entry point raises ValueError or IndexError with a message that names the problem; nothing
crashes the interpreter (a crash would end this test process, and the CTest entry with it)."""

import numpy as np
import pytest

import mdcs
from conftest import grid_mesh

V, F = grid_mesh(5, 5)


@pytest.fixture(scope="module")
def mesh():
    return mdcs.Mesh(V, F)


NAN_V = V.copy()
NAN_V[7, 1] = np.nan
INF_V = V.copy()
INF_V[3, 2] = np.inf
OUT_F = F.copy()
OUT_F[4, 2] = 25
NEG_F = F.copy()
NEG_F[2, 0] = -1
REPEAT_F = F.copy()
REPEAT_F[6] = [3, 3, 8]


@pytest.mark.parametrize("vertices, faces, error, words", [
    (NAN_V, F, ValueError, ["vertices[7, 1]", "NaN"]),
    (INF_V, F, ValueError, ["vertices[3, 2]", "infinite"]),
    (V[:, :2], F, ValueError, ["vertices", "(n, 3)", "(25, 2)"]),
    (V.ravel(), F, ValueError, ["vertices", "shape"]),
    (V.astype(complex), F, ValueError, ["vertices", "complex"]),
    (V.astype(str), F, ValueError, ["vertices", "dtype"]),
    (None, F, ValueError, ["vertices", "None"]),
    ([[0, 0, 0], [1, 0]], F, ValueError, ["vertices"]),
    (V, F.astype(float), ValueError, ["faces", "integer", "astype(int)"]),
    (V, np.c_[F, F[:, :1]], ValueError, ["faces", "triangle"]),
    (V, F[:, :2], ValueError, ["faces", "(m, 3)"]),
    (V, OUT_F, IndexError, ["faces[4, 2] = 25", "out of range", "25 vertices"]),
    (V, NEG_F, IndexError, ["faces[2, 0] = -1"]),
    (V, REPEAT_F, ValueError, ["faces[6]", "repeats a vertex"]),
    (V, np.zeros((0, 3), dtype=int), ValueError, ["faces is empty"]),
    (V, F.astype(bool), ValueError, ["faces", "bool"]),
])
def test_bad_meshes(vertices, faces, error, words):
    with pytest.raises(error) as info:
        mdcs.Mesh(vertices, faces)
    for w in words:
        assert w in str(info.value)


@pytest.mark.parametrize("call, error, words", [
    (lambda m: m.distances(25), IndexError, ["sources = 25", "out of range"]),
    (lambda m: m.distances(-1), IndexError, ["sources = -1"]),
    (lambda m: m.distances([0, 99]), IndexError, ["sources[1] = 99"]),
    (lambda m: m.distances(1.5), ValueError, ["sources"]),
    (lambda m: m.distances(True), ValueError, ["sources"]),
    (lambda m: m.distances(), ValueError, ["sources"]),
    (lambda m: m.distances([]), ValueError, ["no source"]),
    (lambda m: m.distances(0, method="heat"), ValueError, ["unknown geodesic method 'heat'"]),
    (lambda m: m.distances(0, max_distance=-1), ValueError, ["max_distance", ">= 0"]),
    (lambda m: m.distances(0, max_distance=np.nan), ValueError, ["max_distance"]),
    (lambda m: m.distances(0, method="merged", merge_tolerance=-0.1), ValueError, ["tolerance"]),
    (lambda m: m.distances(0, merge_tolerance=0.1), ValueError, ["merged"]),
    (lambda m: m.distances(0, targets=[3, 30]), IndexError, ["targets[1] = 30"]),
    (lambda m: m.distances(0, stop_at_targets=True), ValueError, ["stop_at_targets needs targets"]),
    (lambda m: m.distances(source_points=([40], [[1, 0, 0]])), IndexError, ["source_faces[0] = 40"]),
    (lambda m: m.distances(source_points=([0], [[0.5, 0.6, 0.1]])), ValueError, ["source_barycentric[0]", "sum to 1"]),
    (lambda m: m.distances(source_points=([0], [[-0.5, 1.4, 0.1]])), ValueError, [">= 0"]),
    (lambda m: m.distances(source_points=([0], [[np.nan, 0.5, 0.5]])), ValueError, ["NaN"]),
    (lambda m: m.distances(source_points=([0, 1], [[1, 0, 0]])), ValueError, ["2 entries", "1 rows"]),
    (lambda m: m.distances(source_points=([0], [[1, 0]])), ValueError, ["(k, 3)"]),
    (lambda m: m.distances(source_points=5), ValueError, ["surface points"]),
    (lambda m: m.distances(0, progress="yes"), ValueError, ["progress"]),
    (lambda m: m.field(0).shortest_path(25), IndexError, ["target = 25"]),
    (lambda m: m.field(0).distance_at(([0], [[2, 0, 0]])), ValueError, ["barycentric[0]"]),
    (lambda m: m.distance_matrix([0, 1], [0, 2], symmetric=True), ValueError, ["symmetric"]),
    (lambda m: m.distance_matrix([0, 1], threads=-1), (ValueError, TypeError, OverflowError), []),
])
def test_bad_geodesic_arguments(mesh, call, error, words):
    with pytest.raises(error) as info:
        call(mesh)
    for w in words:
        assert w in str(info.value)


def test_bad_mwt_inputs():
    good = np.random.default_rng(1).random((20, 2))
    cases = [
        (good[:2], ValueError, "at least 3 points"),
        (np.r_[good, good[:1]], ValueError, "duplicate"),
        (np.c_[np.arange(5.0), np.arange(5.0)], ValueError, "collinear"),
        (np.r_[good, [[np.nan, 0]]], ValueError, "NaN"),
        (good[:, :1], ValueError, "(n, 2)"),
    ]
    for points, error, word in cases:
        with pytest.raises(error) as info:
            mdcs.mwt.minimum_weight_triangulation(points, progress=False)
        assert word in str(info.value).lower() or word in str(info.value)
    with pytest.raises(ValueError, match="unknown metric"):
        mdcs.mwt.minimum_weight_triangulation(good, metric="L3")
    with pytest.raises(ValueError, match="diamond"):
        mdcs.mwt.minimum_weight_triangulation(good, metric="L1", pruning="diamond")
    with pytest.raises(ValueError, match="unknown LP solver"):
        mdcs.mwt.minimum_weight_triangulation(good, solver="gurobi")


def test_bad_variational_inputs():
    curve = dict(interval=(0, 1), value_range=(0, 1), left=0.2, right=0.8, lines=50)
    with pytest.raises(ValueError, match="outside the range"):
        mdcs.variational.minimal_curve("arc_length", **{**curve, "left": 2})
    with pytest.raises(ValueError, match="interval"):
        mdcs.variational.minimal_curve("arc_length", **{**curve, "interval": (1, 0)})
    with pytest.raises(ValueError, match="unknown curve functional"):
        mdcs.variational.minimal_curve("elastica", **curve)
    with pytest.raises(ValueError, match=r"G\(f="):
        mdcs.variational.minimal_curve(lambda f, fp, x: f - 0.5, **curve)
    with pytest.raises(ValueError, match="vectorised"):
        mdcs.variational.minimal_curve(lambda f, fp, x: np.ones(3), **curve)
    with pytest.raises(ValueError, match="two equal points"):
        mdcs.variational.minimal_curve("arc_length", **{**curve, "lines": [[0, 0, 0, 0]]})
    with pytest.raises(ValueError, match="lines"):
        mdcs.variational.minimal_curve("arc_length", **{**curve, "lines": 0})
    surface = dict(value_range=(0, 1), boundary=0.5, planes=20)
    with pytest.raises(ValueError, match="outside the range"):
        mdcs.variational.minimal_surface("area", **{**surface, "boundary": 3.0})
    with pytest.raises(ValueError, match="self-intersecting"):
        mdcs.variational.minimal_surface("area", polygon=[[0, 0], [1, 1], [1, 0], [0, 1]], **surface)
    with pytest.raises(ValueError, match="segments"):
        mdcs.variational.minimal_surface("area", segments=0, **surface)
    with pytest.raises(ValueError, match=r"G\(f="):
        mdcs.variational.minimal_surface(lambda f, fx, fy, x, y: x - 2, **surface)
    with pytest.raises(ValueError, match="quadrature_level"):
        mdcs.variational.minimal_surface("area", quadrature_level=9, **surface)


def test_bad_min_cut_inputs():
    with pytest.raises(IndexError, match=r"edges\[1, 1\] = 5"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 5]], [1, 1], [0], [2])
    with pytest.raises(ValueError, match="itself"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 1]], [1, 1], [0], [2])
    with pytest.raises(ValueError, match="negative or NaN"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 2]], [1, -1], [0], [2])
    with pytest.raises(ValueError, match="rows for 2 edges"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 2]], [1], [0], [2])
    with pytest.raises(IndexError, match="sink_nodes"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 2]], [1, 1], [0], [3])
    with pytest.raises(ValueError, match="unknown engine"):
        mdcs.min_cut.min_cut(3, [[0, 1], [1, 2]], [1, 1], [0], [2], engine="dinic")
    with pytest.raises(ValueError, match="at least one node"):
        mdcs.min_cut.min_cut(0, None, [], [], [])


def test_bad_silhouette_inputs():
    with pytest.raises(ValueError, match="exactly one of eye"):
        mdcs.silhouettes.silhouette_edges(V, F)
    with pytest.raises(ValueError, match="direction"):
        mdcs.silhouettes.silhouette_edges(V, F, direction=[0, 0, 0])
    with pytest.raises(ValueError, match="target_faces"):
        mdcs.silhouettes.Simplifier(V, F, target_faces=2)


def test_bad_files(tmp_path):
    with pytest.raises(ValueError, match="no such file"):
        mdcs.io.read_mesh(tmp_path / "missing.off")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    with pytest.raises(ValueError, match=r"bad\.off:6.*7"):  # the file, the line, the index
        mdcs.io.read_mesh(bad)
    # a header that claims a billion vertices: refused from the file's size, nothing allocated
    lying = tmp_path / "lying.off"
    lying.write_text("OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(ValueError, match="lying"):
        mdcs.io.read_mesh(lying)
    nan = tmp_path / "nan.off"
    nan.write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(ValueError, match=r"nan\.off:4"):
        mdcs.io.read_mesh(nan)
    garbage = tmp_path / "garbage.off"
    garbage.write_bytes(b"\x00\xff" * 50)
    with pytest.raises(ValueError):
        mdcs.io.read_mesh(garbage)


def test_bad_silhouette_hierarchy_inputs():
    edges = mdcs.silhouettes.SilhouetteEdges(V, F)
    with pytest.raises(ValueError, match="exactly one of eye"):
        edges.edges()
    with pytest.raises(ValueError, match="exactly one of eye"):
        edges.edges(eye=[0, 0, 5], direction=[0, 0, 1])
    with pytest.raises(ValueError, match="direction"):
        edges.edges(direction=[0, 0, 0])
    with pytest.raises(ValueError, match="eye"):
        edges.edges(eye=[0, np.nan, 5])
    with pytest.raises(IndexError):
        mdcs.silhouettes.SilhouetteEdges(V, np.array([[0, 1, len(V)]]))
    with pytest.raises(ValueError):
        mdcs.silhouettes.SilhouetteEdges(np.array([[0, 0, 0], [1, 0, 0], [0, np.inf, 0]]), np.array([[0, 1, 2]]))
    with pytest.raises(ValueError, match="hierarchy"):
        mdcs.silhouettes.Simplifier(V, F, hierarchy="yes")
