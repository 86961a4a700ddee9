#!/usr/bin/env python3
"""tools/spectra_to_rgb.py: its conversion of a measured reflectance (the ColorChecker's dark
skin patch) agrees with colour-science's own spectral-to-sRGB path (sd_to_XYZ under D65, then
XYZ_to_sRGB, linear) within the white balance's 0.1 %; a constant spectrum is grey; it reads
named arrays of pbrt-v4's source layout from a made-up file; and the sampled-spectrum weights
committed in host/scene/spectra_table.inc are those it computes now. Skips (exit 0) only when
colour-science is not installed."""

import os
import re
import sys
import tempfile
import unittest

import numpy

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))

FAKE_SOURCE = """
const Float Xx_eta[] = {
    300, 1.0, 600, 2.0, 900, 3.0,
};
const Float Glass_eta[] = {300, 1.6, 900, 1.4};
Spectrum xxeta = PiecewiseLinearSpectrum::FromInterleaved(Xx_eta, false, alloc);
Spectrum glass =
    PiecewiseLinearSpectrum::FromInterleaved(Glass_eta, false, alloc);
std::map<std::string, Spectrum> named = {
    {"metal-Xx-eta", xxeta},
    {"glass-Test", glass},
    {"stdillum-A", illuma},
};
"""


class SpectraToRgbTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import spectra_to_rgb
        cls.tool = spectra_to_rgb
        cls.grid, cls.weights = spectra_to_rgb.observer()

    def test_measured_reflectance_matches_colour_science(self):
        import colour
        patch = colour.SDS_COLOURCHECKERS["ISO 17321-1"]["dark skin"]
        wavelengths = numpy.array(patch.wavelengths, dtype=float)
        ours = self.tool.to_rgb(wavelengths, numpy.array(patch.values), self.grid, self.weights)
        xyz = colour.sd_to_XYZ(patch.copy().align(colour.SpectralShape(360, 830, 1)),
                               illuminant=colour.SDS_ILLUMINANTS["D65"]) / 100.0
        theirs = colour.XYZ_to_sRGB(xyz, apply_cctf_encoding=False)
        numpy.testing.assert_allclose(ours, theirs, rtol=2e-3, atol=2e-4)
        self.assertGreater(ours[0], ours[2])  # dark skin is reddish

    def test_constant_spectrum_is_grey(self):
        rgb = self.tool.to_rgb(numpy.array([200.0, 1000.0]), numpy.array([0.25, 0.25]),
                               self.grid, self.weights)
        numpy.testing.assert_allclose(rgb, [0.25, 0.25, 0.25], atol=1e-7)

    def test_reads_named_arrays_and_writes_a_table(self):
        named = self.tool.parse_named(FAKE_SOURCE, self.tool.parse_arrays(FAKE_SOURCE))
        self.assertEqual(sorted(named), ["glass-Test", "metal-Xx-eta"])
        with tempfile.TemporaryDirectory() as folder:
            source = os.path.join(folder, "spectrum.cpp")
            out = os.path.join(folder, "table.inc")
            with open(source, "w") as f:
                f.write(FAKE_SOURCE)
            self.tool.main([source, out])
            with open(out) as f:
                text = f.read()
        glass = re.search(r'\{"glass-Test", \{([^}]*)\}, ([0-9.]+)f\}', text)
        self.assertIsNotNone(glass, text)
        self.assertAlmostEqual(float(glass.group(2)), 1.6 - 0.2 * 250 / 600, places=5)
        red, green, blue = (float(v.rstrip("f")) for v in glass.group(1).split(","))
        self.assertGreater(blue, red)  # the index falls with the wavelength

    def test_committed_weights_are_current(self):
        with open(os.path.join(ROOT, "host", "scene", "spectra_table.inc")) as f:
            text = f.read()
        rows = re.findall(r"\{(-?[0-9.e+-]+)f, (-?[0-9.e+-]+)f, (-?[0-9.e+-]+)f\},",
                          text.split("kSampledWeights")[1])
        committed = numpy.array(rows, dtype=float)
        _, now = self.tool.sampled_weights(self.grid, self.weights)
        self.assertEqual(committed.shape, now.shape)
        numpy.testing.assert_allclose(committed, now, rtol=1e-5, atol=1e-12)


if __name__ == "__main__":
    try:
        import colour  # noqa: F401
    except ImportError:
        print("colour-science is not installed: skipped")
        sys.exit(0)
    unittest.main()
