# tspline.blend: Fang's blending surface of a polygon mesh, tessellated.
import numpy as np
import pytest

import tspline

OCTAHEDRON_V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                        dtype=float)
OCTAHEDRON_F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                         [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])


@pytest.mark.parametrize("variant", ["basic", "vertex", "open"])
def test_octahedron(variant):
    points, triangles, p = tspline.blend(OCTAHEDRON_V, OCTAHEDRON_F, order=2, variant=variant,
                                         resolution=4, return_properties=True)
    assert points.shape[1] == 3 and triangles.shape[1] == 3
    assert triangles.min() == 0 and triangles.max() == len(points) - 1
    # 8 faces, each cut into 4^2 triangles
    assert len(triangles) == 8 * 16
    # the surface interpolates the mesh's vertices
    for v in OCTAHEDRON_V:
        assert np.min(np.linalg.norm(points - v, axis=1)) < 1e-12
    # a closed convex shape: outward unit normals, positive curvature at the vertices
    n = p["normals"]
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1, atol=1e-9)
    assert (np.einsum("ij,ij->i", n, points) > 0).all()
    assert set(p["input_face"]) == set(range(8))


def test_quad_faces_as_lists():
    cube_v = [[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    cube_f = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    points, triangles = tspline.blend(cube_v, cube_f, resolution=2)
    assert len(points) > 8 and len(triangles) > 12


def test_bad_meshes():
    with pytest.raises(ValueError, match="not in \\[0, 6\\)"):
        tspline.blend(OCTAHEDRON_V, [[0, 1, 9]])
    flipped = OCTAHEDRON_F.copy()
    flipped[0] = flipped[0][::-1]
    with pytest.raises(ValueError, match="consistently oriented"):
        tspline.blend(OCTAHEDRON_V, flipped)
    with pytest.raises(ValueError, match="variant must be basic, vertex or open"):
        tspline.blend(OCTAHEDRON_V, OCTAHEDRON_F, variant="best")
    with pytest.raises(ValueError, match="blending order"):
        tspline.blend(OCTAHEDRON_V, OCTAHEDRON_F, order=-1)
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        tspline.blend(OCTAHEDRON_V[:, :2], OCTAHEDRON_F)
