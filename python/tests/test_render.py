# tspline.render: pictures through the library `tspline render` uses (src/render/scene.h).
import os
import subprocess
import zlib

import numpy as np
import pytest

import tspline

CLI = os.environ.get("TSPLINE_CLI")
needs_cli = pytest.mark.skipif(not (CLI and os.path.exists(CLI)),
                               reason="the tspline executable is not built")


def png_pixels(path):
    """The (H, W, 3) pixels of an 8-bit RGB PNG, decoded here (checks the file's structure:
    signature, chunk CRCs, IHDR, the zlib stream, the filters)."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, []
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        crc = int.from_bytes(data[pos + 8 + n:pos + 12 + n], "big")
        assert zlib.crc32(kind + body) == crc, kind
        chunks.append((kind, body))
        pos += 12 + n
    assert chunks[0][0] == b"IHDR" and chunks[-1][0] == b"IEND"
    ihdr = chunks[0][1]
    w, h = int.from_bytes(ihdr[:4], "big"), int.from_bytes(ihdr[4:8], "big")
    assert ihdr[8:10] == bytes([8, 2])  # 8 bits, RGB
    raw = zlib.decompress(b"".join(b for k, b in chunks if k == b"IDAT"))
    stride = 3 * w
    rows, previous = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = previous[i], previous[i - 3] if i >= 3 else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            else:
                assert f == 0, f"filter {f}"
        rows.append(bytes(line))
        previous = line
    return np.frombuffer(b"".join(rows), dtype=np.uint8).reshape(h, w, 3)


@pytest.fixture
def interpolator(scattered):
    p, z = scattered
    return tspline.C1Interpolator(p, z)


def test_array_shape_and_content(interpolator):
    # from above: the unit square fills the middle of the picture
    image = tspline.render(interpolator, size=(160, 120), view=(0, 90))
    assert image.shape == (120, 160, 3) and image.dtype == np.uint8
    # a shaded surface on a white background: many colours, white corners, covered centre
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 50
    assert (image[0, 0] == 255).all() and (image[-1, -1] == 255).all()
    assert (image[40:80, 50:110].astype(int).sum(axis=2) < 3 * 255).all()
    # modes and views differ; the same call gives the same pixels
    curvature = tspline.render(interpolator, size=(160, 120), view=(0, 90), mode="curvature")
    assert (curvature != image).any()
    assert (tspline.render(interpolator, size=(160, 120), view=(-30, 40)) != image).any()
    assert (tspline.render(interpolator, size=(160, 120), view=(0, 90)) == image).all()


def test_png_file_is_valid_and_equals_the_array(tmp_path, interpolator):
    path = tmp_path / "f.png"
    returned = tspline.render(interpolator, path, mode="isophotes", size=(96, 64), bands=8)
    assert returned == str(path)
    array = tspline.render(interpolator, mode="isophotes", size=(96, 64), bands=8)
    assert (png_pixels(path) == array).all()


@needs_cli
def test_same_pixels_as_the_cli(tmp_path, data_dir):
    spline = f"{data_dir}/height_field_with_hole.spline"
    cli_png = tmp_path / "cli.png"
    options = ["--mode", "net", "--size", "200x150", "--view", "10,60", "--levels", "2"]
    subprocess.run([CLI, "render", "--input", spline, "--output", str(cli_png)] + options,
                   check=True, capture_output=True)
    ours = tspline.render(spline, mode="net", size=(200, 150), view=(10, 60), levels=2)
    assert (ours == png_pixels(cli_png)).all()
    # the same spline from memory: the network read back from the file draws the same
    loaded = tspline.render(tspline.load(spline), mode="net", size=(200, 150), view=(10, 60),
                            levels=2)
    assert (loaded == ours).all()
    # a saved PNG is byte for byte the CLI's
    py_png = tmp_path / "py.png"
    tspline.render(spline, py_png, mode="net", size=(200, 150), view=(10, 60), levels=2)
    assert py_png.read_bytes() == cli_png.read_bytes()


def test_closed_surfaces_and_meshes(data_dir):
    v, f = tspline.thesis_polyhedron("icosahedron")
    s = tspline.PseudoAG1Surface(v, f)
    for mode in ("shaded", "net", "jump"):
        image = tspline.render(s, mode=mode, size=(120, 90), levels=2)
        assert image.shape == (90, 120, 3)
        assert len(np.unique(image.reshape(-1, 3), axis=0)) > 20, mode
    mesh = tspline.render(f"{data_dir}/elephant.off", size=(80, 60))
    assert mesh.shape == (60, 80, 3) and (mesh != 255).any()


def test_mann_and_exact_interpolators(dyadic):
    p, z = dyadic
    for f in (tspline.MannInterpolator(p, z), tspline.C1Interpolator(p, z, exact=True,
                                                                      fit="tangent")):
        image = tspline.render(f, size=(64, 48))
        assert image.shape == (48, 64, 3) and (image != 255).any()


def test_bad_arguments(tmp_path, interpolator, data_dir):
    with pytest.raises(ValueError, match="mode must be one of"):
        tspline.render(interpolator, mode="wire")
    with pytest.raises(ValueError, match="jump mode needs a closed surface"):
        tspline.render(interpolator, mode="jump")
    with pytest.raises(ValueError, match="size must be a pair"):
        tspline.render(interpolator, size=100)
    with pytest.raises(ValueError):  # the renderer's own range check
        tspline.render(interpolator, size=(0, 10))
    with pytest.raises(ValueError, match="levels must be between 0 and 8"):
        tspline.render(interpolator, levels=9)
    with pytest.raises(ValueError, match="range must be a finite number > 0"):
        tspline.render(interpolator, mode="curvature", range=-1)
    with pytest.raises(ValueError, match="is a plain mesh: curvature mode"):
        tspline.render(f"{data_dir}/elephant.off", mode="curvature")
    with pytest.raises(ValueError, match="unknown input format"):
        tspline.render(f"{data_dir}/franke_100.xyz")
    with pytest.raises(RuntimeError, match="cannot open"):
        tspline.render(str(tmp_path / "missing.spline"))
    with pytest.raises(RuntimeError, match="cannot"):
        tspline.render(interpolator, tmp_path / "no_such_dir" / "x.png", size=(8, 8))
    with pytest.raises(TypeError, match="expected an interpolator"):
        tspline.render(42)
