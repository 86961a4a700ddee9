#!/usr/bin/env python3
"""tools/denoise.py on a synthetic image: a smooth clean image plus seeded Gaussian noise, with
albedo and normal layers and one more layer, is denoised to a lower relMSE against the clean
image, and keeps its size, its channels and the other layer bit for bit; an image without its
normal layer is refused with one line naming it, and an output that is the input (by name or by
a link) is refused, the input untouched. Skips (exit 0) only when pyoidn or OpenEXR is
not installed."""

import os
import shutil
import subprocess
import sys
import unittest

import optional_packages

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DENOISE = os.path.join(ROOT, "tools", "denoise.py")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "denoise_test")
WIDTH, HEIGHT = 96, 64


def relmse(image, reference):
    return float(((image - reference) ** 2 / (reference ** 2 + 0.01)).mean())


def synthetic():
    """(clean, noisy, layers): a smooth image, it with noise of sigma 0.1, and its EXR layers."""
    import numpy as np
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH].astype(np.float32)
    clean = np.stack([0.2 + 0.6 * x / WIDTH, 0.3 + 0.4 * y / HEIGHT,
                      0.5 + 0.2 * np.sin(x / 9.0)], axis=-1).astype(np.float32)
    noisy = clean + np.random.default_rng(7).normal(0.0, 0.1, clean.shape).astype(np.float32)
    layers = {"": noisy, "albedo": np.full_like(clean, 0.7),
              "normal": np.broadcast_to(np.float32([0, 0, 1]), clean.shape),
              "indirect": np.random.default_rng(8).random(clean.shape, dtype=np.float32)}
    return clean, noisy, layers


def write_exr(path, layers):
    import numpy as np
    import OpenEXR
    channels = {}
    for layer, image in layers.items():
        for index, c in enumerate("RGB"):
            channels[(layer + "." if layer else "") + c] = np.ascontiguousarray(image[..., index])
    with OpenEXR.File({"type": OpenEXR.scanlineimage}, channels) as f:
        f.write(path)


def read_exr(path):
    import numpy as np
    import OpenEXR
    with OpenEXR.File(path, separate_channels=True) as f:
        return {name: np.array(c.pixels) for name, c in f.channels().items()}


class DenoiseTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)

    def test_lowers_the_error_and_keeps_size_and_layers(self):
        import numpy as np
        clean, noisy, layers = synthetic()
        source, target = os.path.join(SCRATCH, "noisy.exr"), os.path.join(SCRATCH, "out.exr")
        write_exr(source, layers)
        result = subprocess.run([sys.executable, DENOISE, source, target], capture_output=True,
                                text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        before, after = read_exr(source), read_exr(target)
        self.assertEqual(sorted(after), sorted(before))
        for name in before:
            self.assertEqual(after[name].shape, (HEIGHT, WIDTH), name)
        for name in ("albedo.R", "normal.B", "indirect.G"):
            np.testing.assert_array_equal(after[name], before[name])
        denoised = np.stack([after[c] for c in "RGB"], axis=-1)
        self.assertLess(relmse(denoised, clean), 0.5 * relmse(noisy, clean))

    def test_a_missing_auxiliary_layer_is_one_line(self):
        _, _, layers = synthetic()
        del layers["normal"]
        source, target = os.path.join(SCRATCH, "no-normal.exr"), os.path.join(SCRATCH, "x.exr")
        write_exr(source, layers)
        result = subprocess.run([sys.executable, DENOISE, source, target], capture_output=True,
                                text=True)
        self.assertEqual(result.returncode, 1)
        lines = result.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn("no normal layer", lines[0])
        self.assertFalse(os.path.exists(target))

    def test_an_output_that_is_the_input_is_refused_untouched(self):
        _, _, layers = synthetic()
        source = os.path.join(SCRATCH, "same.exr")
        write_exr(source, layers)
        link = os.path.join(SCRATCH, "same-link.exr")
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(source, link)
        with open(source, "rb") as f:
            before = f.read()
        for target in (source, link):
            result = subprocess.run([sys.executable, DENOISE, source, target],
                                    capture_output=True, text=True)
            self.assertEqual(result.returncode, 2, result.stderr)
            self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
            self.assertIn("is the input", result.stderr)
            with open(source, "rb") as f:
                self.assertEqual(f.read(), before)


if __name__ == "__main__":
    optional_packages.main_unless_missing("denoise_test", ("numpy", "OpenEXR", "pyoidn"))
