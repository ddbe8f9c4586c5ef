"""Images: RGBA8 pixels with PNG output and notebook display."""

from __future__ import annotations

import os
from typing import Any, Union

import numpy as np

from . import _shaderbox


class Image:
    """An RGBA8 picture, top row first.

    ``array`` is the ``H x W x 4`` ``uint8`` numpy array (also what
    ``np.asarray(image)`` gives). Notebooks show the image (``_repr_png_``);
    :meth:`save` writes a PNG. ``has_alpha`` says whether alpha matters
    (a transparent background): the PNG is RGBA then, RGB otherwise.
    """

    def __init__(self, array: Any, has_alpha: bool = True):
        a = np.asarray(array)
        if a.dtype != np.uint8:
            raise TypeError(f"an Image needs uint8 pixels, not {a.dtype}")
        if a.ndim != 3 or a.shape[2] != 4 or a.shape[0] == 0 or a.shape[1] == 0:
            raise ValueError(f"an Image is H x W x 4 (RGBA), not shape {a.shape}")
        self.array = np.ascontiguousarray(a)
        self.has_alpha = bool(has_alpha)

    @property
    def width(self) -> int:
        return int(self.array.shape[1])

    @property
    def height(self) -> int:
        return int(self.array.shape[0])

    @property
    def shape(self):
        return self.array.shape

    def __array__(self, dtype=None, copy=None):
        if dtype is None or np.dtype(dtype) == self.array.dtype:
            return self.array.copy() if copy else self.array
        return self.array.astype(dtype)

    def to_png(self) -> bytes:
        """The PNG file's bytes."""
        return _shaderbox.encode_png(self.width, self.height, self.array.tobytes(), self.has_alpha)

    def _repr_png_(self) -> bytes:
        return self.to_png()

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the image as PNG to ``path`` (other formats: :meth:`to_pil`)."""
        if not os.fspath(path).lower().endswith(".png"):
            raise ValueError(f"{os.fspath(path)!r}: save() writes PNG only; name the file *.png, or use to_pil().save()")
        with open(path, "wb") as f:
            f.write(self.to_png())

    def to_pil(self):
        """The image as a ``PIL.Image.Image`` (needs Pillow)."""
        try:
            from PIL import Image as PILImage
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pil() needs Pillow: pip install Pillow") from e
        if self.has_alpha:
            return PILImage.fromarray(self.array, "RGBA")
        return PILImage.fromarray(np.ascontiguousarray(self.array[:, :, :3]), "RGB")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Image) and np.array_equal(self.array, other.array)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"<shaderbox.Image {self.width}x{self.height}{' RGBA' if self.has_alpha else ' RGB'}>"
