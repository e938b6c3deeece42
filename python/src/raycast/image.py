"""raycast.Image: a rendered image as a numpy array (height, width, 3) of linear RGB that
Jupyter displays inline (`_repr_png_`: clamped to [0, 1], sRGB-encoded, 8 bits)."""
import struct
import zlib

import numpy as np


def _srgb(linear):
    c = np.clip(np.nan_to_num(np.asarray(linear, np.float64)), 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def png_bytes(rgb8):
    """An 8-bit RGB array (height, width, 3) as PNG file bytes (one IDAT, filter 0 rows)."""
    height, width, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].tobytes() for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6))
            + chunk(b"IEND", b""))


class Image(np.ndarray):
    """A (height, width, 3) float32 array of linear RGB; every numpy operation works on it."""

    def __new__(cls, array):
        a = np.asarray(array, np.float32)
        if a.ndim != 3 or a.shape[2] != 3:
            raise ValueError(f"an Image is shaped (height, width, 3), got {a.shape}")
        return a.view(cls)

    def to_srgb8(self):
        """The image as uint8 sRGB (height, width, 3): what `_repr_png_` and `save` encode."""
        return np.round(_srgb(self) * 255).astype(np.uint8)

    def _repr_png_(self):
        if self.ndim != 3 or self.shape[2] != 3 or self.size == 0:
            return None  # a slice that is no longer an image: numpy's own repr
        return png_bytes(np.ascontiguousarray(self.to_srgb8()))

    def save(self, path):
        """Writes the image as an 8-bit sRGB PNG file."""
        with open(path, "wb") as f:
            f.write(self._repr_png_())
