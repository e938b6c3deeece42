"""raycast.Scene's optional, idempotent commit and the rendered raycast.Image."""
import io
import os
import struct
import zlib

import numpy as np
import pytest

import raycast
from raycast.progress import RenderProgress
from conftest import SOURCE_DIR


def test_load_then_commit_combine():
    scene = raycast.Scene.load(os.path.join(SOURCE_DIR, "scenes", "sphere.yaml"))
    scene.commit()
    scene.commit()
    assert scene.committed


def test_first_query_commits_a_built_scene():
    scene = raycast.Scene()
    scene.add_sphere((0, 0, 0), 1.0)
    assert scene.compute_distance(np.array([[0, 0, 3.0]]))[0] == 2.0
    assert scene.committed


def decode_png(data):
    """Width, height and rows (uint8 RGB) of a PNG written with filter 0 on every row."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, {}
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        assert struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0] == zlib.crc32(kind + body)
        chunks[kind] = chunks.get(kind, b"") + body
        pos += 12 + n
    width, height, depth, color = struct.unpack(">IIBB", chunks[b"IHDR"][:10])
    assert (depth, color) == (8, 2)
    raw = zlib.decompress(chunks[b"IDAT"])
    rows = [raw[y * (3 * width + 1):(y + 1) * (3 * width + 1)] for y in range(height)]
    assert all(r[0] == 0 for r in rows)
    return np.frombuffer(b"".join(r[1:] for r in rows), np.uint8).reshape(height, width, 3)


def test_render_returns_an_image_that_displays_as_png():
    scene = raycast.Scene()
    scene.add_sphere((0, 0, 0), 1.0)
    scene.add_point_light((0, 5, 5))
    image = scene.render(width=24, height=16, camera={"position": (0, 0, 5)})
    assert isinstance(image, raycast.Image) and isinstance(image, np.ndarray)
    assert image.shape == (16, 24, 3) and image.dtype == np.float32
    pixels = decode_png(image._repr_png_())
    np.testing.assert_array_equal(pixels, image.to_srgb8())
    assert pixels[8, 12].max() > 0 and pixels[0, 0].max() == 0  # the sphere, the background


def test_image_encodes_linear_light_as_srgb():
    image = raycast.Image(np.array([[[0.0, 0.5, 1.0], [2.0, -1.0, 0.0031308]]]))
    np.testing.assert_array_equal(image.to_srgb8(), [[[0, 188, 255], [255, 0, 10]]])
    assert image[0, 0]._repr_png_() is None  # a pixel is not an image


def test_render_with_progress_equals_the_whole_render():
    scene = raycast.Scene.load(os.path.join(SOURCE_DIR, "scenes", "demo.yaml"))
    whole = scene.render(width=64, height=50, samples=3, progress=False)
    banded = scene.render(width=64, height=50, samples=3, progress=True)  # bands of 16 rows
    np.testing.assert_array_equal(banded, whole)
    with pytest.raises(TypeError, match="progress"):
        scene.render(width=8, height=8, progress="yes")
    with pytest.raises(ValueError, match="larger than"):
        scene.render(width=10**6, height=10**6, progress=True)


def test_progress_bar_waits_for_its_delay_and_ends_the_line():
    out = io.StringIO()
    bar = RenderProgress(100, delay=3600.0, stream=out)
    bar(16)
    assert out.getvalue() == ""  # a quick render shows nothing
    bar(100)
    assert out.getvalue().startswith("\rrendering |" + "#" * 30 + "| 100/100 rows")
    assert out.getvalue().endswith("\n")
    out = io.StringIO()
    RenderProgress(64, delay=0.0, stream=out)(16)
    assert "|" + "#" * 7 + "." * 23 + "| 16/64 rows" in out.getvalue()
