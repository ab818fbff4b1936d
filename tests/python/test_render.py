"""epviz.render_frame against `epviz render`: the same frame, pixel for
pixel, through the same offscreen GL choice (EPVIZ_GL / gl=)."""
import os
import struct
import zlib

import numpy as np
import pytest

import epviz
from conftest import SOURCE, run_epviz

JOB = SOURCE / "render_jobs" / "kovalevskaya.json"


def read_png_rgba(path):
    """The pixels of an 8-bit RGBA PNG (what epviz writes), with zlib alone:
    an independent reader of the CLI's frame."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, chunks = 8, {}
    while at < len(data):
        (length,), kind = struct.unpack(">I", data[at:at + 4]), data[at + 4:at + 8]
        chunks.setdefault(kind, []).append(data[at + 8:at + 8 + length])
        at += 12 + length
    width, height, depth, colour = struct.unpack(">IIBB", chunks[b"IHDR"][0][:10])
    assert depth == 8 and colour == 6, "expected 8-bit RGBA"
    raw = zlib.decompress(b"".join(chunks[b"IDAT"]))
    stride = width * 4
    out = np.zeros((height, width, 4), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        f, line = raw[y * (stride + 1)], np.frombuffer(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)], dtype=np.uint8).astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - 4] if x >= 4 else 0
            b = prev[x]
            c = prev[x - 4] if x >= 4 else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 0xFF
        out[y] = cur.reshape(width, 4)
        prev = cur
    return out


@pytest.fixture(params=["egl", "osmesa"])
def gl(request):
    return request.param


def test_frame_equals_the_cli_png(tmp_path, gl):
    r = run_epviz("render", JOB, "--frames", "0", "--width", "320", "--height", "180", "--format",
                  "png", "--out", tmp_path, "--gl", gl, "--quiet", check=False)
    if r.returncode == 1 and "GL" in r.stderr:
        pytest.skip(f"{gl} cannot draw here: {r.stderr.strip()}")
    assert r.returncode == 0, r.stderr
    expected = read_png_rgba(tmp_path / "kovalevskaya_0000.png")
    image = epviz.render_frame(str(JOB), frame=0, width=320, height=180, gl=gl)
    assert image.dtype == np.uint8 and image.shape == (180, 320, 4)
    # Not blank: many colours, and not all one.
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 50
    assert np.array_equal(image, expected)


def test_a_shipped_name_and_a_later_frame():
    image = epviz.render_frame("kovalevskaya", frame=3, width=64, height=48)
    assert image.shape == (48, 64, 4) and image[..., :3].std() > 1


@pytest.mark.parametrize(
    "kwargs,key",
    [
        (dict(frame=-1), "frame"),
        (dict(frame=10**6), "frame"),
        (dict(width=8), "width"),
        (dict(height=9000), "height"),
        (dict(gl="vulkan"), "gl"),
        (dict(frame=1.5), "frame"),
    ],
)
def test_bad_input_is_a_value_error_naming_it(kwargs, key):
    with pytest.raises(ValueError) as e:
        epviz.render_frame(str(JOB), **kwargs)
    assert "\n" not in str(e.value) and key in str(e.value), str(e.value)
