"""The scene-directory format of the differential suite (see
../python/harness.py and ../python/compare.py), for client programs that
hand back their own images: NAME.rgba (width and height as little-endian
u32, then RGBA8 pixels, bottom row first) and NAME.fail on an exception.
"""
import os
import struct
import sys
import traceback


def save(outdir, name, pixels, top_first=True):
    """Writes an (h, w, 3 or 4) uint8 array as NAME.rgba."""
    import numpy as np
    a = np.asarray(pixels, dtype=np.uint8)
    if a.ndim != 3 or a.shape[2] not in (3, 4):
        raise ValueError(f"{name}: expected an (h, w, 3|4) image, got {a.shape}")
    if a.shape[2] == 3:
        a = np.concatenate([a, np.full(a.shape[:2] + (1,), 255, np.uint8)], axis=2)
    if top_first:
        a = a[::-1]
    h, w = a.shape[:2]
    with open(os.path.join(outdir, name + ".rgba"), "wb") as f:
        f.write(struct.pack("<II", w, h) + np.ascontiguousarray(a).tobytes())


def run(scenes):
    """`python3 SCRIPT OUTDIR [NAME...]`: runs every scene function
    f(outdir, name) of `scenes` (a list of (name, f)), or the named ones; an
    exception becomes NAME.fail, so one broken scene does not hide the
    others."""
    outdir = sys.argv[1]
    only = set(sys.argv[2:])
    os.makedirs(outdir, exist_ok=True)
    for name, f in scenes:
        if only and name not in only:
            continue
        try:
            f(outdir, name)
        except Exception:
            with open(os.path.join(outdir, name + ".fail"), "w") as o:
                o.write(traceback.format_exc())
