# Pseudo-AG^1 surfaces over closed triangle meshes (AG1.md; tspline pseudo-ag1): the golden
# values of AG1.md §8 on the regular tetrahedron, certificates, measures, files, evaluation,
# PN triangles, and bad input as ValueError with the library's message.
import json
import os
import subprocess

import numpy as np
import pytest

import tspline

# AG1.md §8: a, b, c, d and the faces abc, adb, bdc, cda (counter-clockwise from outside)
A, B, C, D = (1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)
TETRA_V = np.array([A, B, C, D], dtype=float)
TETRA_F = np.array([[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]])


def net_point(surface, counts, nets=None):
    """The control point with multi-index {vertex: count} (counts summing to the degree) in
    the patch of the face holding those vertices (a third vertex is found if two are given)."""
    nets = surface.control_nets() if nets is None else nets
    faces = surface.faces
    for f, face in enumerate(faces):
        if set(counts) <= set(face.tolist()):
            ijk = [counts.get(int(v), 0) for v in face]
            return nets[f, tspline.control_point_index(*ijk)]
    raise AssertionError(f"no face holds {sorted(counts)}")


def all_faces_at(surface, counts):
    """The control point of every face holding the vertices of counts (C^0: all equal)."""
    nets = surface.control_nets()
    out = []
    for f, face in enumerate(surface.faces):
        if set(counts) <= set(face.tolist()):
            ijk = [counts.get(int(v), 0) for v in face]
            out.append(nets[f, tspline.control_point_index(*ijk)])
    return np.array(out)


@pytest.mark.parametrize("exact", [False, True])
def test_chapter5_golden_values_c16(exact):
    # C16: every control point a convex combination of the vertices
    s = tspline.PseudoAG1Surface(TETRA_V, TETRA_F, preset="chapter5", exact=exact)
    assert s.exact == exact and s.reoriented == 0
    # faces as used: rotations of the input faces
    for given, used in zip(TETRA_F, s.faces):
        assert any(np.array_equal(np.roll(given, r), used) for r in range(3))
    V = TETRA_V
    for a in range(4):
        others = [x for x in range(4) if x != a]
        z = (12 * V[a] + V[others].sum(axis=0)) / 15
        np.testing.assert_allclose(all_faces_at(s, {a: 5}), np.tile(z, (3, 1)), rtol=0, atol=1e-15)
        for b in others:
            (c, d) = [x for x in others if x != b]
            np.testing.assert_allclose(net_point(s, {a: 4, b: 1}), (4 * V[a] + V[b]) / 5,
                                       rtol=0, atol=1e-15)
            np.testing.assert_allclose(net_point(s, {a: 3, b: 2}),
                                       (2 * V[a] + V[b] + V[c] + V[d]) / 5, rtol=0, atol=1e-15)
            for p in (c, d):  # the inner point of face abp at a
                np.testing.assert_allclose(net_point(s, {a: 3, b: 1, p: 1}),
                                           (3 * V[a] + V[b] + V[p]) / 5, rtol=0, atol=1e-15)
                q = d if p == c else c  # the flip of face abp next to ab
                np.testing.assert_allclose(net_point(s, {a: 2, b: 2, p: 1}),
                                           (3 * V[a] + 3 * V[b] + 3 * V[p] + V[q]) / 10,
                                           rtol=0, atol=1e-15)
    if exact:  # exact rationals rounded once: the nearest doubles
        assert np.array_equal(s.control_nets()[0, tspline.control_point_index(5, 0, 0)],
                              np.full(3, 11 / 15))


@pytest.mark.parametrize("exact", [False, True])
def test_exact_preset_golden_values_c23(exact):
    s = tspline.PseudoAG1Surface(TETRA_V, TETRA_F, preset="exact", exact=exact)
    nets = s.control_nets()
    tol = dict(rtol=0, atol=1e-15)
    np.testing.assert_allclose(all_faces_at(s, {0: 5}), np.full((3, 3), 13 / 15), **tol)
    np.testing.assert_allclose(net_point(s, {0: 4, 1: 1}, nets), [17 / 15, 11 / 15, 11 / 15], **tol)
    np.testing.assert_allclose(net_point(s, {0: 3, 1: 2}, nets), np.full(3, 1 / 15), **tol)
    # L_abc(ab): the flip of face abc next to ab, apex c
    np.testing.assert_allclose(net_point(s, {0: 2, 1: 2, 2: 1}, nets), [1 / 15, 1 / 5, -1 / 5],
                               **tol)
    if exact:  # exact rationals rounded once: the nearest doubles
        assert np.array_equal(net_point(s, {0: 5}, nets), np.full(3, 13 / 15))
    # Fig. 6.7: without offsets every edge dips
    r = s.edge_relations()
    assert (r["dip"] > 0).all() and s.info["flags"]["dipping_edges"] == 6
    np.testing.assert_allclose(r["relation"], np.tile([-1.0, 1, 1], (6, 1)))


@pytest.mark.parametrize("preset", ["exact", "chapter5"])
def test_exact_certificate_tetrahedron(preset):
    s = tspline.PseudoAG1Surface(TETRA_V, TETRA_F, preset=preset, exact=True)
    c = s.certify()
    assert c["exact"] and c["verdict"] == "proof" and c["pseudo_ag1"]
    assert (c["c0_edges"], c["middle_edges"], c["ag1_edges"]) == (6, 6, 0)
    assert (c["g1_vertices"], c["coplanar_vertices"]) == (4, 4)
    assert c["number_of_edges"] == 6 and c["number_of_vertices"] == 4
    e = c["edges"]
    assert e["vertices"].shape == (6, 2) and e["diamonds"].shape == (6, 5)
    # C5: the middle diamonds hold, the end diamonds fail on every edge
    assert e["diamonds"][:, 1:4].all() and not e["diamonds"][:, [0, 4]].any()
    assert e["c0"].all() and e["middle"].all() and not e["ag1"].any()
    assert sorted(map(sorted, e["vertices"].tolist())) == sorted(
        [sorted(x) for x in [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]])


def test_icosahedron_measures():
    v, f = tspline.thesis_polyhedron("icosahedron")
    s = tspline.PseudoAG1Surface(v, f)
    assert not s.exact and s.options["preset"] == "thesis" and not s.options["rational"]
    m = s.measure()
    assert m["vertex_max_jump_deg"] < 1e-9  # G^1 at every vertex
    assert 0 < m["mean_jump_deg"] <= m["max_jump_deg"] < 90
    assert m["edges"] == 30 and m["samples_per_edge"] == 15
    assert m["edge_max_jump_deg"].shape == (30,) and m["edge_mean_jump_deg"].shape == (30,)
    assert m["max_jump_deg"] == m["edge_max_jump_deg"].max()
    assert m["tessellation_faces"] == 20 * 16 and m["self_intersecting"] is False
    assert 0.5 < m["volume_ratio"] < 1.5 and m["folded_samples"] == 0
    c = s.certify()
    assert c["verdict"] == "within_tolerance" and c["g1_vertices"] == 12
    # C24: the thesis' offsets reduce the jumps against no offsets
    plain = tspline.PseudoAG1Surface(v, f, offsets=(0, 0, 0)).measure(levels=0)
    assert m["max_jump_deg"] < plain["max_jump_deg"]
    # the comparator: PN triangles jump more
    pn = tspline.pn_triangles(v, f).measure()
    assert pn["mean_jump_deg"] > m["mean_jump_deg"]


def test_evaluate_corners_edges_and_normals():
    v, f = tspline.thesis_polyhedron("octahedron")
    s = tspline.PseudoAG1Surface(v, f)
    faces, nets = s.faces, s.control_nets()
    planes = s.corner_planes()
    k = len(faces)
    for a in range(3):
        w = np.zeros((k, 3))
        w[:, a] = 1
        p, n = s.evaluate(np.arange(k), w)
        np.testing.assert_allclose(p, nets[:, tspline.control_point_index(*w[0].astype(int) * 5)],
                                   atol=1e-14)
        # G^1 at the vertices: the patch normal is the corner plane's
        np.testing.assert_allclose(n, planes["normal"][faces[:, a]], atol=1e-12)
        np.testing.assert_allclose(p, planes["corner"][faces[:, a]], atol=1e-14)
    # C^0: a point of an edge from both faces
    r, t = s.edges[0]
    sides = [fi for fi, face in enumerate(faces) if r in face and t in face]
    pts = []
    for fi in sides:
        w = np.zeros(3)
        w[list(faces[fi]).index(r)] = 0.3
        w[list(faces[fi]).index(t)] = 0.7
        point, normal = s.evaluate(fi, w)  # a single query: (3,) arrays
        assert point.shape == (3,) and abs(np.linalg.norm(normal) - 1) < 1e-12
        pts.append(point)
    np.testing.assert_allclose(pts[0], pts[1], atol=1e-14)


def test_tessellate_is_watertight():
    v, f = tspline.thesis_polyhedron("cube")
    s = tspline.PseudoAG1Surface(v, f, preset="chapter5")
    points, triangles, normals, gaussian = s.tessellate(levels=2)
    assert triangles.shape == (12 * 16, 3) and normals.shape == points.shape
    assert gaussian.shape == (len(points),)
    edges = {tuple(sorted(e)) for t in triangles for e in ((t[0], t[1]), (t[1], t[2]),
                                                           (t[2], t[0]))}
    assert len(points) - len(edges) + len(triangles) == 2  # a closed sphere
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1, atol=1e-12)


def test_split_normals_show_the_jumps():
    v, f = tspline.thesis_polyhedron("octahedron")
    s = tspline.PseudoAG1Surface(v, f, preset="thesis")
    shared = s.tessellate(levels=1)
    points, triangles, normals, _ = s.tessellate(levels=1, split_normals=True)
    assert len(points) == 8 * 6 and len(triangles) == len(shared[1]) == 8 * 4
    # the copies of an edge's midpoint: one place, two normals (the jump across the edge)
    key = np.round(points, 9)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    assert len(counts) == len(shared[0])
    pairs = [np.flatnonzero(inverse.ravel() == i) for i in np.flatnonzero(counts == 2)]
    angles = [np.degrees(np.arccos(np.clip(normals[a] @ normals[b], -1, 1))) for a, b in pairs]
    assert len(pairs) == 12 and min(angles) > 1


def test_reoriented_components():
    inward = TETRA_F[:, ::-1]
    two_v = np.vstack([TETRA_V, TETRA_V + [5, 0, 0]])
    two_f = np.vstack([inward, TETRA_F + 4])
    s = tspline.PseudoAG1Surface(two_v, two_f, preset="exact", exact=True)
    assert s.reoriented == 1 and s.info["components"] == 2 and s.info["genus"] == [0, 0]
    # the used faces are the outward ones: rotations of TETRA_F
    for given, used in zip(np.vstack([TETRA_F, TETRA_F + 4]), s.faces):
        assert any(np.array_equal(np.roll(given, r), used) for r in range(3))
    assert np.array_equal(net_point(s, {0: 5}), np.full(3, 13 / 15))
    assert np.array_equal(net_point(s, {4: 5}), [88 / 15, 13 / 15, 13 / 15])
    assert s.certify()["verdict"] == "proof"


def test_overrides_and_options():
    v, f = tspline.thesis_polyhedron("icosahedron")
    s = tspline.PseudoAG1Surface(v, f, preset="chapter5", tau=0.25, flip="lower-index",
                                 edge_map="averaged", normal="centroid", star_scale=0.5,
                                 recentering=False, offsets=[0.0, 0.0, 0.0])
    o = s.options
    assert (o["preset"], o["tau"], o["flip"], o["edge_map"], o["normal"]) == (
        "chapter5", 0.25, "lower-index", "averaged", "centroid")
    assert o["star_scale"] == 0.5 and o["recentering"] is False and o["rational"]
    assert s.corner_planes()["star_scale"].tolist() == [0.5] * 12
    t = tspline.PseudoAG1Surface(v, f, preset="chapter5", tau=0.25, flip="lower-index",
                                 edge_map="averaged", normal="centroid", star_scale=0.5,
                                 recentering=False, exact=True)
    assert t.exact and t.certify()["verdict"] == "proof"
    # exact and double agree to round-off (not with flip="larger-face": the icosahedron's
    # faces have equal areas, and which flip is prescribed is then decided by round-off)
    np.testing.assert_allclose(t.control_nets(), s.control_nets(), atol=1e-13)


def test_flags_of_degenerate_cases():
    # AG1.md C32: Sato + default offsets folds at one vertex; v-arm + no offsets re-centres
    v, f = tspline.thesis_polyhedron("sato")
    assert tspline.PseudoAG1Surface(v, f).info["flags"]["folded_projections"] == 1
    v, f = tspline.thesis_polyhedron("v-arm")
    s = tspline.PseudoAG1Surface(v, f, offsets=(0, 0, 0))
    assert s.info["flags"]["recentred_vertices"] == 2
    assert s.corner_planes()["recentred"].sum() == 2


@pytest.mark.parametrize("exact", [False, True])
def test_save_load_round_trip(tmp_path, exact):
    v, f = tspline.thesis_polyhedron("pentakis" if not exact else "octahedron")
    s = tspline.PseudoAG1Surface(v, f, preset="exact" if exact else "thesis", exact=exact)
    path = tmp_path / "s.surface"
    s.save(path)
    t = tspline.load_surface(path, exact=exact)
    assert t.degree == 5 and t.exact == exact
    assert np.array_equal(t.vertices, s.vertices)
    # the same patches: align each face's corner order, then compare the nets (%.17g: equal)
    q = np.random.default_rng(3).dirichlet([1, 1, 1], size=len(f))
    shift = [next(r for r in range(3) if np.array_equal(np.roll(a, r), b))
             for a, b in zip(s.faces, t.faces)]
    q_t = np.array([np.roll(w, r) for w, r in zip(q, shift)])
    ps, ns = s.evaluate(np.arange(len(f)), q)
    pt, nt = t.evaluate(np.arange(len(f)), q_t)
    assert np.array_equal(ps, pt) and np.array_equal(ns, nt)
    c = t.certify()
    assert c["verdict"] == ("proof" if exact else "within_tolerance")
    assert c["edges"]["relation_determined"].all()
    if not exact:
        # a double file read exactly: its round-off fails, a tolerance accepts it
        u = tspline.load_surface(path, exact=True)
        assert u.certify()["verdict"] == "failed"
        assert u.certify(tolerance=1e-9)["verdict"] == "within_tolerance"
    m_s, m_t = s.measure(levels=1), t.measure(levels=1)
    assert m_s["max_jump_deg"] == m_t["max_jump_deg"]


def test_pn_triangles():
    v, f = tspline.thesis_polyhedron("octahedron")
    pn = tspline.pn_triangles(v, f)
    assert pn.degree == 3 and not pn.exact
    nets = pn.control_nets()
    assert nets.shape == (8, 10, 3)
    np.testing.assert_array_equal(nets[:, tspline.control_point_index(3, 0, 0)],
                                  v[pn.faces[:, 0]])
    m = pn.measure(levels=1)
    assert m["vertex_max_jump_deg"] < 1e-9  # one normal per vertex
    assert m["max_jump_deg"] > 1  # G^0 only along the edges
    with pytest.raises(ValueError, match="the patches have degree 3, not 5"):
        pn.certify()
    with pytest.raises(ValueError, match="PN triangles: the mesh is not closed"):
        tspline.pn_triangles(v, f[1:])


def test_thesis_polyhedra():
    names = tspline.thesis_polyhedron_names()
    assert {"tetrahedron", "icosahedron", "torus", "torus9", "sato"} <= set(names)
    v, f = tspline.thesis_polyhedron("tetrahedron")
    assert np.array_equal(v, TETRA_V) and f.dtype == np.int64
    v, f = tspline.thesis_polyhedron("torus")
    assert f.shape == (144, 3)
    s = tspline.PseudoAG1Surface(v, f)
    assert s.info["genus"] == [1] and s.info["euler"] == 0
    with pytest.raises(ValueError, match="unknown"):
        tspline.thesis_polyhedron("dodecahedron")


# ---- bad input ---------------------------------------------------------------------------

def test_open_mesh():
    with pytest.raises(ValueError, match="^pseudo-AG1: the mesh is not closed: edge .* has a "
                                         "single face"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F[:3])


def test_nan_vertex():
    v = TETRA_V.copy()
    v[2, 1] = np.nan
    with pytest.raises(ValueError, match="^pseudo-AG1: vertex 2 has a non-finite coordinate$"):
        tspline.PseudoAG1Surface(v, TETRA_F)
    with pytest.raises(ValueError, match="vertex 2 has a non-finite coordinate"):
        tspline.PseudoAG1Surface(v, TETRA_F, preset="exact", exact=True)


@pytest.mark.parametrize("vertices, faces, message", [
    (TETRA_V[:, :2], TETRA_F, r"vertices: expected an array of shape \(n, 3\), got shape \(4, 2\)"),
    (TETRA_V.ravel(), TETRA_F, r"vertices: expected an array of shape \(n, 3\)"),
    (TETRA_V, TETRA_F[:, :2], r"faces: expected an array of shape \(m, 3\), got shape \(4, 2\)"),
    (TETRA_V, TETRA_F.astype(float) + 0.5, "faces: expected integer vertex indices"),
    (TETRA_V, TETRA_F + 1, r"pseudo-AG1: face 1 refers to vertex 4, not in \[0, 4\)"),
    (TETRA_V, [[0, 1, 1]] + TETRA_F.tolist(), "pseudo-AG1: face 0 repeats a vertex"),
    (TETRA_V, np.vstack([TETRA_F, TETRA_F[:1]]), "not a manifold, consistently oriented"),
    (TETRA_V, np.vstack([TETRA_F[:1, ::-1], TETRA_F[1:]]), "not a manifold, consistently"),
    (np.zeros((4, 3)), TETRA_F, "pseudo-AG1: face 0 has zero area"),
    (np.zeros((0, 3)), np.zeros((0, 3), dtype=int), "pseudo-AG1: the mesh has no face"),
])
def test_wrong_input(vertices, faces, message):
    with pytest.raises(ValueError, match=message):
        tspline.PseudoAG1Surface(vertices, faces)


def test_exact_needs_rational_options():
    with pytest.raises(ValueError, match="^pseudo-AG1: exact=True needs rational options"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, exact=True)  # the thesis preset
    with pytest.raises(ValueError, match="exact=True needs rational options"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, preset="exact", offsets=(0.1, 0, 0),
                                 exact=True)


def test_bad_options():
    with pytest.raises(ValueError, match="unknown preset 'best'"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, preset="best")
    with pytest.raises(ValueError, match="^pseudo-AG1: the star scale must be in \\(0, 1\\]$"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, star_scale=2)
    with pytest.raises(ValueError, match="tau must be finite and >= 0"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, tau=-1)
    with pytest.raises(ValueError, match="^pseudo-AG1: flip must be one of symmetric, "
                                         "larger-face, lower-index, not 'largest'$"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, flip="largest")
    with pytest.raises(ValueError, match="offsets must be three numbers"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, offsets=(0, 0))
    with pytest.raises(ValueError, match="offsets must be finite and >= 0"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, offsets=(0, -1, 0))
    with pytest.raises(TypeError, match="unexpected keyword argument 'gain'"):
        tspline.PseudoAG1Surface(TETRA_V, TETRA_F, gain=1)


def test_bad_queries_and_files(tmp_path):
    s = tspline.PseudoAG1Surface(TETRA_V, TETRA_F)
    with pytest.raises(ValueError, match=r"evaluate: face 4 not in \[0, 4\)"):
        s.evaluate([4], [[1, 0, 0]])
    with pytest.raises(ValueError, match="weights of row 1 must be finite and sum to 1"):
        s.evaluate([0, 1], [[1, 0, 0], [0.5, 0.4, 0]])
    with pytest.raises(ValueError, match=r"bary: expected an array of shape \(k, 3\)"):
        s.evaluate([0], [[1, 0]])
    with pytest.raises(ValueError, match="evaluate: 2 faces but 1 rows"):
        s.evaluate([0, 1], [[1, 0, 0]])
    with pytest.raises(ValueError, match=r"tessellate: the level must be in \[0, 8\]"):
        s.tessellate(levels=9)
    with pytest.raises(ValueError, match="measure: need at least one sample per edge"):
        s.measure(samples=0)
    with pytest.raises(ValueError, match="tolerance must be a number > 0"):
        s.certify(tolerance=-1)
    with pytest.raises(ValueError, match="cannot open"):
        tspline.load_surface(tmp_path / "no_such.surface")
    bad = tmp_path / "bad.surface"
    bad.write_text("tspline-spline 1\n")
    with pytest.raises(ValueError, match=r"bad\.surface:1: not a tspline-surface file"):
        tspline.load_surface(bad)
    with pytest.raises(RuntimeError, match="cannot write"):
        s.save(tmp_path / "no_such_dir" / "s.surface")


# ---- the command-line tool on the same mesh -------------------------------------------------

CLI = os.environ.get("TSPLINE_CLI")


@pytest.mark.skipif(not (CLI and os.path.exists(CLI)),
                    reason="the tspline executable is not built (TSPLINE_CLI unset or missing)")
@pytest.mark.parametrize("preset", ["thesis", "exact"])
def test_measures_equal_the_cli(tmp_path, preset):
    report = tmp_path / "r.json"
    saved = tmp_path / "cli.surface"
    subprocess.run([CLI, "pseudo-ag1", "--shape", "icosahedron", "--preset", preset,
                    "--levels", "2", "--save", str(saved), "--report", str(report)],
                   check=True, capture_output=True)
    r = json.loads(report.read_text())
    v, f = tspline.thesis_polyhedron("icosahedron")
    s = tspline.PseudoAG1Surface(v, f, preset=preset, exact=preset == "exact")
    m = s.measure(samples=15, levels=2)
    assert m["max_jump_deg"] == r["max_normal_jump_deg"]
    assert m["mean_jump_deg"] == r["mean_normal_jump_deg"]
    assert m["volume_ratio"] == r["volume_ratio"]
    c = s.certify()
    assert c["ag1_edges"] == r["ag1_edges"] and c["exact"] == r["certificate"]["exact"]
    assert np.array_equal(tspline.load_surface(saved).control_nets(), s.control_nets())
