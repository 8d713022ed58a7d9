#!/usr/bin/env python3
"""Regenerates the FLIP test data of ray.judge (src/test/resources/ray/judge/flip/).

Writes small image pairs (reference and test PNGs, 8-bit RGB) and, for each, what NVIDIA's published
FLIP implementation computes for them (LDR-FLIP, sRGB inputs, the default 67.02 pixels per degree):
the mean, a few percentiles and the whole error map rounded to 5 decimals
(NAME-flip.csv, row by row; summary.csv). FlipTest compares the Java
implementation (ray.judge.Flip) with these numbers. The tests never run this script; run it by hand
after changing the pairs, and commit what it writes:

    python3 -m venv .venv-flip && .venv-flip/bin/pip install flip-evaluator==1.7 numpy pillow
    .venv-flip/bin/python tools/flip_reference.py

The "render" pairs crop real renders of this engine (reference-images/*.png); the others are drawn
here (edges, a disc with and without anti-aliasing, colour shifts, noise), all from fixed seeds.
"""
import importlib.metadata
import os
import sys

import numpy as np
from PIL import Image

import flip_evaluator as flip

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "src", "test", "resources", "ray", "judge", "flip")


def load_png(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.uint8)


def save_png(img, path):
    Image.fromarray(np.clip(img, 0, 255).astype(np.uint8), "RGB").save(path)


def disc(w, h, cx, cy, r, inside, outside, samples):
    """A disc of colour `inside` on `outside`, each pixel the mean of samples x samples grid points."""
    img = np.zeros((h, w, 3))
    offs = (np.arange(samples) + 0.5) / samples
    for y in range(h):
        for x in range(w):
            cover = 0
            for sy in offs:
                for sx in offs:
                    cover += (x + sx - cx) ** 2 + (y + sy - cy) ** 2 <= r * r
            c = cover / (samples * samples)
            img[y, x] = c * np.asarray(inside) + (1 - c) * np.asarray(outside)
    return np.floor(img + 0.5)


def pairs():
    rng = np.random.default_rng(465)
    out = {}

    # 1. a real render, cropped, against itself with +-2 steps of noise and a patch 6 steps warmer
    render = load_png(os.path.join(ROOT, "reference-images", "material-blinnphong.png"))[60:108, 40:104]
    noisy = render.astype(int) + rng.integers(-2, 3, render.shape)
    noisy[20:36, 10:30, 0] += 6
    out["render-noise"] = (render, noisy)

    # 2. another render against the same scene with the image shifted right by one pixel
    render2 = load_png(os.path.join(ROOT, "reference-images", "colored-lights.png"))
    h2, w2 = render2.shape[:2]
    y0, x0 = (h2 - 40) // 2, (w2 - 56) // 2
    crop = render2[y0:y0 + 40, x0:x0 + 56]
    shifted = render2[y0:y0 + 40, x0 - 1:x0 + 55]
    out["render-shift"] = (crop, shifted)

    # 3. a disc with 4x4 anti-aliasing against the same disc with one sample per pixel (jaggies)
    out["disc-aa"] = (disc(48, 32, 23.3, 15.7, 11.2, (230, 120, 40), (20, 30, 60), 4),
                      disc(48, 32, 23.3, 15.7, 11.2, (230, 120, 40), (20, 30, 60), 1))

    # 4. a horizontal gradient against a hue-rotated copy (colour only, no change of features)
    x = np.linspace(0, 1, 32)
    grad = np.zeros((32, 32, 3))
    grad[..., 0] = 40 + 180 * x[None, :]
    grad[..., 1] = 60 + 100 * x[:, None]
    grad[..., 2] = 150
    grad = np.floor(grad + 0.5)
    out["gradient-hue"] = (grad, grad[..., [2, 0, 1]])

    # 5. flat grey against one step brighter: the smallest difference an 8-bit image can hold
    grey = np.full((24, 40, 3), 128)
    out["grey-step"] = (grey, grey + 1)

    # 6. a checkerboard of 4-pixel squares against a blurred copy (features lost)
    yy, xx = np.mgrid[0:32, 0:32]
    checker = np.where(((xx // 4) + (yy // 4)) % 2 == 0, 220, 35)[..., None].repeat(3, axis=2)
    k = np.array([1, 2, 1]) / 4.0
    blur = checker.astype(float)
    for axis in (0, 1):
        pad = np.pad(blur, [(1, 1) if a == axis else (0, 0) for a in range(3)], mode="edge")
        sl = lambda s: tuple(slice(s, s + 32) if a == axis else slice(None) for a in range(3))
        blur = k[0] * pad[sl(0)] + k[1] * pad[sl(1)] + k[2] * pad[sl(2)]
    out["checker-blur"] = (checker, np.floor(blur + 0.5))

    # 7. saturated primaries and black/white against random colours (clamping, the extremes of the gamut)
    prim = np.zeros((16, 48, 3))
    colours = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255), (0, 0, 0), (255, 255, 0)]
    for i, c in enumerate(colours):
        prim[:, 8 * i:8 * i + 8] = c
    out["primaries-random"] = (prim, rng.integers(0, 256, prim.shape))
    return out


def main():
    os.makedirs(OUT, exist_ok=True)
    index = {"implementation": "flip-evaluator " + importlib.metadata.version("flip-evaluator"),
             "ppd": 0.7 * (3840 / 0.7) * np.pi / 180, "pairs": []}
    for name, (ref, test) in pairs().items():
        ref = np.clip(ref, 0, 255).astype(np.uint8)
        test = np.clip(test, 0, 255).astype(np.uint8)
        save_png(ref, os.path.join(OUT, name + "-reference.png"))
        save_png(test, os.path.join(OUT, name + "-test.png"))
        # evaluate what the PNGs hold, as FLIP's own loader reads them (values / 255, sRGB)
        r = load_png(os.path.join(OUT, name + "-reference.png")).astype(np.float32) / 255
        t = load_png(os.path.join(OUT, name + "-test.png")).astype(np.float32) / 255
        error, mean, params = flip.evaluate(r, t, "LDR", inputsRGB=True, applyMagma=False)
        error = np.asarray(error, dtype=np.float64).reshape(ref.shape[0], ref.shape[1])
        q = {str(p): float(np.percentile(error, p)) for p in (25, 50, 75, 90, 95, 99)}
        index["pairs"].append({"name": name, "width": int(ref.shape[1]), "height": int(ref.shape[0]),
                               "mean": float(mean), "max": float(error.max()), "percentiles": q,
                               "ppd": float(params.get("ppd", index["ppd"]))})
        with open(os.path.join(OUT, name + "-flip.csv"), "w") as f:
            for row in error:
                f.write(",".join("%.5f" % v for v in row) + "\n")
        print("%-18s %3dx%-3d mean %.6f max %.4f" % (name, ref.shape[1], ref.shape[0], mean, error.max()))
    with open(os.path.join(OUT, "summary.csv"), "w") as f:
        f.write("# %s, LDR-FLIP of sRGB PNGs at %.6f pixels per degree (tools/flip_reference.py)\n"
                % (index["implementation"], index["ppd"]))
        f.write("name,width,height,mean,max,p25,p50,p75,p90,p95,p99\n")
        for p in index["pairs"]:
            q = p["percentiles"]
            f.write("%s,%d,%d,%.8f,%.8f,%s\n" % (p["name"], p["width"], p["height"], p["mean"], p["max"],
                                                ",".join("%.8f" % q[k] for k in ("25", "50", "75", "90", "95", "99"))))


if __name__ == "__main__":
    sys.exit(main())
