# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.geodesics against oracles: Euclidean distances on planar meshes, CGAL's Surface_mesh_shortest_path (an
independent exact algorithm) on curved meshes, the metric's invariants, and the C++ calls themselves."""

import pickle
import threading
import time

import numpy as np
import pytest

import mdcs
from mdcs import _mdcs
from conftest import bumpy_sphere, grid_mesh, icosphere

APPROXIMATE = ("flat_exact", "fast_marching", "dijkstra")


@pytest.fixture(scope="module")
def flat():
    V, F = grid_mesh(15, 12, size=(1.4, 1.1))
    return mdcs.Mesh(V, F), V, F


@pytest.fixture(scope="module")
def bumpy():
    V, F = bumpy_sphere(3)
    return mdcs.Mesh(V, F), V, F


def test_flat_mesh_distances_are_euclidean(flat):
    mesh, V, _ = flat
    for source in (0, 37, 179):
        euclid = np.linalg.norm(V - V[source], axis=1)
        for method in ("exact", "merged", "flat_exact"):
            d = mesh.distances(source, method=method, progress=False)
            np.testing.assert_allclose(d, euclid, rtol=0, atol=1e-12, err_msg=method)


def test_approximate_methods_against_the_exact_distances(flat, bumpy):
    for mesh, _, _ in (flat, bumpy):
        exact = mesh.distances(3, progress=False)
        far = exact > 0
        # Dijkstra along the edges is never shorter than the geodesic
        dijkstra = mesh.distances(3, method="dijkstra", progress=False)
        assert np.all(dijkstra >= exact - 1e-9) and np.all(dijkstra <= 1.5 * exact + 1e-9)
        # the other two approximate it within a few percent on average (the thesis's E, eq. 4.4.1)
        for method, bound in (("fast_marching", 0.05), ("flat_exact", 0.02)):
            d = mesh.distances(3, method=method, progress=False)
            assert np.mean(np.abs(d[far] - exact[far]) / exact[far]) < bound, method


def test_merged_with_zero_tolerance_is_exact_bit_for_bit(bumpy):
    mesh, _, _ = bumpy
    exact = mesh.distances([5, 77], progress=False)
    merged = mesh.distances([5, 77], method="merged", merge_tolerance=0.0, progress=False)
    assert np.array_equal(exact, merged)
    looser = mesh.distances([5, 77], method="merged", merge_tolerance=0.05 * mesh.mean_edge_length, progress=False)
    assert np.all(looser >= exact - 1e-12)


def test_exact_agrees_with_cgal_surface_mesh_shortest_path(bumpy):
    mesh, V, F = bumpy
    for source in (0, 211):
        ours = mesh.distances(source, progress=False)
        cgal = _mdcs.reference.cgal_shortest_path_distances(V, F, source)
        np.testing.assert_allclose(ours, cgal, rtol=1e-9, atol=1e-12)


def test_exact_agrees_with_cgal_on_a_demo_mesh(elephant, cgal_mesh_dir):
    V, F = elephant
    mesh = mdcs.Mesh.from_file(f"{cgal_mesh_dir}/elephant.off")
    assert np.array_equal(mesh.vertices, V) and np.array_equal(mesh.faces, F)
    for source in (0, 1500):
        ours = mesh.distances(source, progress=False)
        cgal = _mdcs.reference.cgal_shortest_path_distances(V, F, source)
        finite = np.isfinite(cgal)
        assert np.array_equal(finite, np.isfinite(ours))
        np.testing.assert_allclose(ours[finite], cgal[finite], rtol=1e-8, atol=1e-12)


def test_sphere_distances_approach_great_circles():
    V, F = icosphere(4)
    mesh = mdcs.Mesh(V, F)
    d = mesh.distances(0, progress=False)
    great = np.arccos(np.clip(V @ V[0], -1, 1))
    # a polyhedral sphere is shorter than the round one, by a little
    assert np.all(d <= great + 1e-9)
    assert np.max(great - d) < 0.02


def test_several_sources_and_nearest(bumpy):
    mesh, _, _ = bumpy
    sources = [4, 300, 500]
    d, nearest = mesh.distances(sources, return_nearest=True, progress=False)
    single = np.array([mesh.distances(s, progress=False) for s in sources])
    np.testing.assert_allclose(d, single.min(axis=0), rtol=1e-12, atol=1e-14)
    chosen = single[nearest, np.arange(len(d))]
    np.testing.assert_allclose(chosen, d, rtol=1e-12, atol=1e-14)
    assert nearest.dtype == np.int64 and d.dtype == np.float64


def test_surface_point_source_on_a_flat_mesh(flat):
    mesh, V, F = flat
    face, bary = 40, np.array([0.2, 0.3, 0.5])
    point = bary @ V[F[face]]
    d = mesh.distances(source_points=([face], [bary]), progress=False)
    np.testing.assert_allclose(d, np.linalg.norm(V - point, axis=1), atol=1e-12)
    # a point at a corner is the vertex itself
    corner = mesh.distances(source_points=([face], [[0, 1, 0]]), progress=False)
    np.testing.assert_allclose(corner, mesh.distances(F[face][1], progress=False), atol=1e-12)
    # mixed sources: vertex sources are numbered first
    _, nearest = mesh.distances(0, source_points=([face], [bary]), return_nearest=True, progress=False)
    assert nearest[0] == 0 and nearest[F[face][2]] == 1


def test_max_distance_and_targets(bumpy):
    mesh, _, _ = bumpy
    full = mesh.distances(9, progress=False)
    limit = np.median(full)
    d = mesh.distances(9, max_distance=limit, progress=False)
    inside = full <= limit * (1 - 1e-9)
    np.testing.assert_allclose(d[inside], full[inside], rtol=1e-12)
    assert np.all(np.isinf(d[full > limit * (1 + 1e-9)]))
    targets = np.array([3, 100, 7, 3])
    np.testing.assert_allclose(mesh.distances(9, targets=targets, progress=False), full[targets], rtol=1e-12)
    stopped = mesh.distances(9, targets=targets, stop_at_targets=True, progress=False)
    np.testing.assert_allclose(stopped, full[targets], rtol=1e-12)
    for method in mdcs.geodesics.METHODS:
        m = mesh.distances(9, method=method, max_distance=limit, progress=False)
        assert np.all(np.isinf(m) | (m <= limit + 1e-9)), method
    # a limit beyond every possible distance (gdist's default 1e100) is dropped: the same values as no limit
    for method in mdcs.geodesics.METHODS:
        np.testing.assert_array_equal(mesh.distances(9, method=method, max_distance=1e100, progress=False),
                                      mesh.distances(9, method=method, progress=False))
    np.testing.assert_array_equal(mesh.distance_matrix([9, 40], max_distance=1e100, progress=False),
                                  mesh.distance_matrix([9, 40], progress=False))


def test_unreachable_components_and_isolated_vertices():
    V1, F1 = grid_mesh(4, 4)
    V = np.vstack([V1, V1 + [5, 0, 0], [[9, 9, 9]]])  # two squares and an isolated vertex
    F = np.vstack([F1, F1 + len(V1)])
    mesh = mdcs.Mesh(V, F)
    assert mesh.number_of_isolated_vertices == 1
    d, nearest = mesh.distances(0, return_nearest=True, progress=False)
    assert np.all(np.isfinite(d[:16])) and np.all(np.isinf(d[16:]))
    assert np.all(nearest[16:] == -1)
    field = mesh.field(0, progress=False)
    assert len(field.shortest_path(20)) == 0 and field.shortest_path(20).length == np.inf
    # a source at the isolated vertex reaches only itself
    d = mesh.distances(32, progress=False)
    assert d[32] == 0 and np.all(np.isinf(np.delete(d, 32)))
    assert len(mesh.field(32, progress=False).shortest_path(32)) == 1
    D = mesh.distance_matrix([0, 32, 20], progress=False)
    assert D[1, 32] == 0 and np.isinf(D[0, 20]) and D[2, 20] == 0


def test_paths_on_a_flat_mesh_are_straight(flat):
    mesh, V, F = flat
    field = mesh.field(0, progress=False)
    for target in (100, 179, 33):
        path = field.shortest_path(target)
        assert path.kind[0] == 0 and path.vertex[0] == target
        assert path.kind[-1] == 0 and path.vertex[-1] == 0
        np.testing.assert_allclose(path.length, field.distances[target], rtol=1e-12)
        np.testing.assert_allclose(path.points[0], V[target])
        # every node lies on the segment from the target to the source
        direction = (V[0] - V[target]) / np.linalg.norm(V[0] - V[target])
        offsets = path.points - V[target]
        assert np.max(np.linalg.norm(offsets - np.outer(offsets @ direction, direction), axis=1)) < 1e-8
        crossings = path.kind == 1
        ends = V[path.edge[crossings]]
        t = path.t[crossings][:, None]
        np.testing.assert_allclose((1 - t) * ends[:, 0] + t * ends[:, 1], path.points[crossings], atol=1e-12)
    reverse = field.shortest_path(100).reversed()
    assert reverse.vertex[0] == 0 and reverse.vertex[-1] == 100


def test_paths_from_surface_points_and_to_them(flat):
    mesh, V, F = flat
    face, bary = 120, np.array([0.6, 0.3, 0.1])
    point = bary @ V[F[face]]
    field = mesh.field(source_points=([face], [bary]), progress=False)
    path = field.shortest_path(5)
    assert path.kind[-1] == 2 and path.face[-1] == face
    np.testing.assert_allclose(path.barycentric[-1], bary, atol=1e-12)
    np.testing.assert_allclose(path.points[-1], point, atol=1e-12)
    d, nearest = field.distance_at(([face, 3], [bary, [1 / 3, 1 / 3, 1 / 3]]))
    assert d[0] == pytest.approx(0, abs=1e-12) and nearest.tolist() == [0, 0]
    to_point = mesh.field(7, progress=False).shortest_path((3, [0.2, 0.2, 0.6]))
    assert to_point.kind[0] == 2 and to_point.vertex[-1] == 7


def test_paths_of_every_method_reach_their_source(bumpy):
    mesh, V, _ = bumpy
    exact = mesh.distances(12, progress=False)
    for method in mdcs.geodesics.METHODS:
        field = mesh.field(12, method=method, shorten_paths=method != "exact", progress=False)
        for target in (400, 600):
            path = field.shortest_path(target)
            assert path.vertex[-1] == 12
            np.testing.assert_allclose(path.points[0], V[target])
            assert path.length >= exact[target] * (1 - 1e-9), method


def test_distance_matrix_matches_single_runs_for_every_thread_count(bumpy):
    mesh, _, _ = bumpy
    sources = np.array([0, 17, 290, 601, 333])
    single = np.array([mesh.distances(s, progress=False) for s in sources])
    results = [mesh.distance_matrix(sources, threads=t, progress=False) for t in (1, 2, 3, 8)]
    for r in results:
        assert np.array_equal(r, results[0])
    np.testing.assert_array_equal(results[0], single)
    targets = np.array([5, 4, 3])
    np.testing.assert_array_equal(mesh.distance_matrix(sources, targets, progress=False), single[:, targets])


def test_sparse_local_matrix(bumpy):
    mesh, _, _ = bumpy
    n = mesh.number_of_vertices
    radius = 0.4
    dense = mesh.distance_matrix(max_distance=radius, progress=False)
    sparse = mesh.distance_matrix(max_distance=radius, sparse=True, progress=False)
    assert sparse.shape == (n, n) and sparse.format == "csr"
    assert sparse.nnz == np.count_nonzero(np.isfinite(dense))
    np.testing.assert_array_equal(np.where(np.isfinite(dense), dense, 0), sparse.toarray())
    assert np.all(sparse.diagonal() == 0)
    sym = mesh.distance_matrix(max_distance=radius, sparse=True, symmetric=True, progress=False)
    assert (sym != sym.T).nnz == 0
    assert np.max(np.abs(sym - sparse)) < 1e-12


def test_dense_symmetric_matrix(bumpy):
    mesh, _, _ = bumpy
    v = np.arange(0, 600, 37)
    D = mesh.distance_matrix(v, v, symmetric=True, progress=False)
    assert np.array_equal(D, D.T)
    assert np.all(np.diag(D) == 0)
    # the triangle inequality of the metric
    assert np.all(D[:, :, None] <= D[:, None, :] + D.T[None, :, :] + 1e-9)


def test_non_manifold_and_inconsistently_oriented_soups():
    # two tetrahedra sharing one vertex (a pinched, non-manifold vertex)
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]])
    mesh = mdcs.Mesh(V, F)
    assert mesh.was_oriented and mesh.number_of_split_vertices == 1
    d = mesh.distances(1, progress=False)
    assert d[0] == pytest.approx(1.0)
    assert np.all(np.isfinite(d[:4])) and np.all(np.isinf(d[4:]))  # the sheets meet at the pinch only
    # a flat grid with every other face flipped gives the same distances as the oriented grid
    Vg, Fg = grid_mesh(6, 5)
    flipped = Fg.copy()
    flipped[::2] = flipped[::2, ::-1]
    soup = mdcs.Mesh(Vg, flipped)
    assert soup.was_oriented
    np.testing.assert_allclose(soup.distances(3, progress=False), mdcs.Mesh(Vg, Fg).distances(3, progress=False),
                               atol=1e-12)
    # barycentric coordinates keep referring to the caller's corner order on flipped faces
    bary = [0.7, 0.2, 0.1]
    point = np.asarray(bary) @ Vg[flipped[4]]
    np.testing.assert_allclose(soup.distances(source_points=([4], [bary]), progress=False),
                               np.linalg.norm(Vg - point, axis=1), atol=1e-12)


def test_inputs_of_other_dtypes_and_layouts_give_the_same_result(flat):
    mesh, V, F = flat
    reference = mesh.distances(3, progress=False)
    variants = [(V.astype(np.float32).astype(np.float64), F.astype(np.int32)), (np.asfortranarray(V), F.T.copy().T),
                (V.tolist(), F.tolist()), (V, F.astype(np.uint16))]
    for v, f in variants:
        np.testing.assert_allclose(mdcs.Mesh(v, f).distances(np.int16(3), progress=False), reference, atol=1e-12)


def test_mesh_pickles_and_reports_itself(flat):
    mesh, V, F = flat
    copy = pickle.loads(pickle.dumps(mesh))
    assert np.array_equal(copy.distances(8, progress=False), mesh.distances(8, progress=False))
    assert "180 vertices" in repr(mesh)
    assert mesh.vertices.flags.writeable is False


def test_concurrent_calls_on_one_mesh_from_threads(bumpy):
    mesh, _, _ = bumpy
    expected = {s: mesh.distances(s, progress=False) for s in range(6)}
    errors = []

    def work(s):
        try:
            for _ in range(3):
                assert np.array_equal(mesh.distances(s, progress=False), expected[s])
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(s,)) for s in range(6)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors


def test_the_gil_is_released_during_a_computation():
    V, F = grid_mesh(120, 120, z=lambda x, y: 0.2 * np.sin(6 * x) * np.cos(5 * y))
    mesh = mdcs.Mesh(V, F)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=count)
    start = time.perf_counter()
    t.start()
    # 144 rows: about 0.3 s in Release on an idle machine (24 rows took 0.08 s, too short to tell)
    mesh.distance_matrix(np.arange(0, 14400, 100), method="fast_marching", threads=1, progress=False)
    end = time.perf_counter()
    stop.set()
    t.join()
    during = [x for x in ticks if start < x < end]
    # with the GIL held by the computation the other thread could not tick at all
    assert end - start > 0.1, "the computation was too short to tell"
    assert len(during) >= 10


def test_statistics_and_field_attributes(bumpy):
    mesh, _, _ = bumpy
    field = mesh.field(0, progress=False)
    s = field.statistics()
    # the full field keeps per-vertex records (the default), not windows
    assert s["windows_created"] > 0 and s["stored_windows"] == 0 and s["peak_memory_bytes"] > 0
    assert field.distances.flags.writeable is False
    assert "exact" in repr(field)


def test_parallel_single_source_distances_do_not_depend_on_the_thread_count():
    V, F = bumpy_sphere(5)  # 10,242 vertices: many rounds of the parallel schedule
    mesh = mdcs.Mesh(V, F)
    sequential = mesh.distances(7, progress=False)
    parallel = [mesh.distances(7, threads=t, progress=False) for t in (2, 3, 8, 0)]
    for d in parallel[1:]:
        assert np.array_equal(d, parallel[0])  # bit for bit
    np.testing.assert_allclose(parallel[0], sequential, rtol=1e-13, atol=0)
    # the pooled solver goes back to the sequential schedule: the next default call is the sequential result
    assert np.array_equal(mesh.distances(7, progress=False), sequential)
    # with a distance limit and with several sources, the same rule
    limited = [mesh.distances([7, 5000], threads=t, max_distance=1.0, progress=False) for t in (2, 8)]
    assert np.array_equal(limited[0], limited[1])
    np.testing.assert_allclose(limited[0], mesh.distances([7, 5000], max_distance=1.0, progress=False), rtol=1e-13)
    # the other methods accept the option and run on one thread
    fmm = mesh.distances(7, method="fast_marching", progress=False)
    assert np.array_equal(mesh.distances(7, method="fast_marching", threads=4, progress=False), fmm)


@pytest.mark.parametrize("bad", [-1, 1025, 1.5, True, "2", None])
def test_thread_counts_are_checked(flat, bad):
    mesh = flat[0]
    with pytest.raises(ValueError, match="threads"):
        mesh.distances(0, threads=bad, progress=False)
    with pytest.raises(ValueError, match="threads"):
        mesh.distance_matrix([0, 1], threads=bad, progress=False)


def surface_point(V, F, faces, barycentric):
    return np.einsum("ki,kij->kj", barycentric, V[F[faces]])


def test_locate_points_on_a_flat_mesh_and_use_them_as_sources(flat):
    mesh, V, F = flat
    rng = np.random.default_rng(4)
    inside = np.c_[rng.uniform(0, 1.4, 50), rng.uniform(0, 1.1, 50), rng.uniform(-0.5, 0.5, 50)]
    located = mesh.locate(inside)
    assert located.faces.shape == (50,) and located.barycentric.shape == (50, 3)
    assert np.all(located.barycentric >= -1e-12)
    np.testing.assert_allclose(located.barycentric.sum(axis=1), 1, atol=1e-12)
    # the closest point of a plane is the orthogonal projection
    np.testing.assert_allclose(surface_point(V, F, located.faces, located.barycentric),
                               np.c_[inside[:, :2], np.zeros(50)], atol=1e-12)
    # beyond the border: the closest border point (clamped coordinates)
    outside = np.array([[-1.0, 0.5, 0.3], [2.0, 2.0, 0.0], [0.7, -3.0, -1.0]])
    o = mesh.locate(outside)
    np.testing.assert_allclose(surface_point(V, F, o.faces, o.barycentric),
                               [[0, 0.5, 0], [1.4, 1.1, 0], [0.7, 0, 0]], atol=1e-12)
    # one point as a (3,) array; located points as sources and as query points
    single = mesh.locate([0.35, 0.6, 1.0])
    assert single.faces.shape == (1,)
    d = mesh.distances(source_points=single, progress=False)
    np.testing.assert_allclose(d, np.linalg.norm(V - [0.35, 0.6, 0], axis=1), atol=1e-12)
    field = mesh.field(0, progress=False)
    at, _ = field.distance_at(located)
    np.testing.assert_allclose(at, np.linalg.norm(inside[:, :2], axis=1), atol=1e-12)


def test_locate_points_on_a_curved_mesh_against_every_vertex(bumpy):
    mesh, V, F = bumpy
    rng = np.random.default_rng(5)
    q = rng.normal(size=(40, 3)) * 1.3
    located = mesh.locate(q)
    p = surface_point(V, F, located.faces, located.barycentric)
    gap = np.linalg.norm(p - q, axis=1)
    # no vertex (a surface point too) is closer than the located point
    nearest_vertex = np.min(np.linalg.norm(q[:, None, :] - V[None, :, :], axis=2), axis=1)
    assert np.all(gap <= nearest_vertex + 1e-12)


def test_locate_rays(flat, bumpy):
    mesh, V, F = flat
    origins = np.array([[0.3, 0.4, 1.0], [0.3, 0.4, -2.0], [0.3, 0.4, 1.0], [5.0, 5.0, 1.0]])
    directions = np.array([[0, 0, -1], [0.1, 0.2, 1.0], [0, 0, 1], [0, 0, -1]], dtype=float)
    hit = mesh.locate_rays(origins, directions)
    np.testing.assert_array_equal(hit.faces[2:], [-1, -1])  # pointing away; beside the mesh
    assert np.all(np.isnan(hit.barycentric[2:]))
    np.testing.assert_allclose(surface_point(V, F, hit.faces[:2], hit.barycentric[:2]),
                               [[0.3, 0.4, 0], [0.5, 0.8, 0]], atol=1e-12)
    # on the sphere, a ray from the centre hits the surface along its direction, once
    bm, BV, BF = bumpy
    d = np.random.default_rng(6).normal(size=(30, 3))
    h = bm.locate_rays(np.zeros((30, 3)), d)
    assert np.all(h.faces >= 0)
    p = surface_point(BV, BF, h.faces, h.barycentric)
    cross = np.cross(p, d / np.linalg.norm(d, axis=1)[:, None])
    assert np.max(np.linalg.norm(cross, axis=1)) < 1e-12 and np.all(np.einsum("ij,ij->i", p, d) > 0)
    with pytest.raises(ValueError, match="zero vector"):
        mesh.locate_rays([[0, 0, 1]], [[0, 0, 0]])
    with pytest.raises(ValueError, match="same number of rows"):
        mesh.locate_rays(np.zeros((2, 3)), np.ones((3, 3)))
    with pytest.raises(ValueError):
        mesh.locate([[0, np.nan, 0]])


def test_iso_distance_curves_are_circles_on_a_flat_mesh():
    V, F = grid_mesh(61, 61, size=(1.0, 1.0))
    mesh = mdcs.Mesh(V, F)
    center = 30 * 61 + 30  # the vertex at (0.5, 0.5)
    field = mesh.field(center, progress=False)
    curves = field.iso_distance_curves([0.2, 0.3, 0.6])
    assert [c.level for c in curves[:2]] == [0.2, 0.3]
    for c in curves[:2]:  # inside the square: one closed circle each
        assert c.closed and c.points.shape[1] == 3
        r = np.linalg.norm(c.points - V[center], axis=1)
        # |x - centre| is convex: its linear interpolation on an edge (length <= sqrt(2) h, h = 1/60) is above it,
        # by at most length^2 / (8 r), so the crossing is that much closer to the centre, never farther
        assert np.all(r <= c.level + 1e-12) and np.all(r >= c.level - 2 * (1 / 60) ** 2 / (8 * 0.9 * c.level))
    # 0.6 leaves the square: four open arcs ending on the border
    arcs = [c for c in curves if c.level == 0.6]
    assert len(arcs) == 4 and not any(c.closed for c in arcs)
    for c in arcs:
        for end in (c.points[0], c.points[-1]):
            assert min(end[0], end[1], 1 - end[0], 1 - end[1]) < 1e-12
    assert mesh.iso_distance_curves(field.distances, 5.0) == []  # beyond every value
    with pytest.raises(ValueError, match="one value per vertex"):
        mesh.iso_distance_curves(field.distances[:-1], [0.2])
    bad = field.distances.copy()
    bad[3] = np.nan
    with pytest.raises(ValueError, match="distances"):
        mesh.iso_distance_curves(bad, [0.2])
