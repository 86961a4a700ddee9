#!/usr/bin/env python3
"""Writes host/scene/spectra_table.inc: pbrt-v4's named spectra (metal indices eta and k, glass
indices) as linear-sRGB values, and the weights that turn a sampled spectrum into linear sRGB,
for radcache's pbrt-v4 import (host/scene/spectra.h).

The tabulated spectra are read from pbrt-v4's source file src/pbrt/util/spectrum.cpp (arrays of
interleaved wavelength in nm and value; pbrt-v4 took them from refractiveindex.info and the glass
makers' catalogues), parsed here; nothing of that file is copied into radcache but the numbers
this tool computes from them.

Conversion, with colour-science's CIE 1931 2-degree observer and CIE D65 at 1 nm from 360 to
830 nm (a spectrum interpolated linearly and held at its end values beyond its range):

    XYZ(s) = sum s(l) cmf(l) D65(l) / sum ybar(l) D65(l),   RGB = M XYZ,

M colour-science's XYZ to linear sRGB matrix, then each channel divided by that of the constant
spectrum 1 (the tabulated D65 is not exactly sRGB's white point: without this a constant 1 gives
(1.0005, 0.9999, 0.9993)), so that a constant spectrum c gives (c, c, c) exactly. This is the
colour a spectral reflectance or index has under sRGB's white (an index clamped at 0), the way an RGB renderer such as
Mitsuba 3 turns its spectral tables into RGB ones. A glass's index is also given at 550 nm alone:
radcache renders RGB, without dispersion.
Emission (a blackbody's radiance) is converted without an illuminant, as pbrt-v4's film sees a
light: RGB = M sum L(l) cmf(l) / sum L(l) ybar(l), the light's luminance made 1 (pbrt-v4 divides
every light's spectrum by its photometric integral, SpectrumToPhotometric); the table holds, per
STEP nm, M cmf and ybar integrated over the sample's hat, so that the C++ side forms both sums
from a spectrum's samples.

usage: tools/spectra_to_rgb.py PBRT_V4/src/pbrt/util/spectrum.cpp [OUT]
       (OUT defaults to host/scene/spectra_table.inc)
"""

import pathlib
import re
import sys

import numpy

ROOT = pathlib.Path(__file__).resolve().parent.parent
FIRST, LAST = 360, 830  # nm, the observer's range used
STEP = 5  # nm, the C++ side's sampled-spectrum weights
GLASS_WAVELENGTH = 550.0


def parse_arrays(text):
    """Every `const Float NAME[] = { numbers };` of the file: NAME -> list of floats."""
    arrays = {}
    for match in re.finditer(r"const\s+Float\s+(\w+)\s*\[\s*\w*\s*\]\s*=\s*\{([^}]*)\}", text):
        body = re.sub(r"//[^\n]*", "", match.group(2))
        arrays[match.group(1)] = [float(v) for v in re.findall(r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?", body)]
    return arrays


def parse_named(text, arrays):
    """pbrt-v4's names of the metal and glass spectra: name -> (wavelengths, values)."""
    handles = dict(re.findall(r"Spectrum\s+(\w+)\s*=\s*PiecewiseLinearSpectrum::FromInterleaved"
                              r"\(\s*(\w+)", text))
    named = {}
    for name, handle in re.findall(r'\{\s*"((?:metal|glass)-[\w-]+)"\s*,\s*(\w+)\s*\}', text):
        values = arrays[handles[handle]]
        if len(values) % 2 != 0 or len(values) < 4:
            raise ValueError("%s: not wavelength-value pairs" % name)
        named[name] = (numpy.array(values[0::2]), numpy.array(values[1::2]))
    if not named:
        raise ValueError("no named metal or glass spectra found")
    return named


def observer():
    """(wavelengths, cmf * D65 per nm as a 3 x N array, normalisation) at 1 nm."""
    import colour
    wavelengths = numpy.arange(FIRST, LAST + 1, dtype=float)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    d65 = colour.SDS_ILLUMINANTS["D65"]
    cmf = numpy.array([cmfs[l] for l in wavelengths]).T
    illuminant = numpy.array([d65[l] for l in wavelengths])
    weighted = cmf * illuminant
    matrix = colour.RGB_COLOURSPACES["sRGB"].matrix_XYZ_to_RGB
    rgb_weights = matrix @ (weighted / weighted[1].sum())
    white = rgb_weights.sum(axis=1)
    return wavelengths, rgb_weights / white[:, None]


def emission_observer():
    """(wavelengths, M cmf per nm as a 3 x N array, ybar per nm) at 1 nm: emission's weights."""
    import colour
    wavelengths = numpy.arange(FIRST, LAST + 1, dtype=float)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    cmf = numpy.array([cmfs[l] for l in wavelengths]).T
    matrix = colour.RGB_COLOURSPACES["sRGB"].matrix_XYZ_to_RGB
    return wavelengths, matrix @ cmf, cmf[1]


def to_rgb(wavelengths, values, grid, weights):
    return weights @ numpy.interp(grid, wavelengths, values)


def sampled_weights(grid, weights):
    """Per STEP nm: the weights whose sum against a spectrum's samples gives its RGB."""
    samples = numpy.arange(FIRST, LAST + 1, STEP, dtype=float)
    per_sample = []
    for l in samples:
        # The 1 nm weights within the sample's interval, the hat function of linear interpolation.
        hat = numpy.clip(1.0 - numpy.abs(grid - l) / STEP, 0.0, None)
        per_sample.append(weights @ hat)
    return samples, numpy.array(per_sample)


def fmt(v):
    """A C++ float literal of 6 significant digits."""
    text = "%.6g" % v
    return text + ("f" if "." in text or "e" in text else ".0f")


def table(named, grid, weights, source):
    samples, per_sample = sampled_weights(grid, weights)
    lines = ["// Generated by tools/spectra_to_rgb.py from pbrt-v4's tabulated spectra",
             "// (" + source + "); do not edit. Linear sRGB under D65, white-balanced so that a",
             "// constant spectrum c is (c, c, c); see the tool for the conversion.",
             "", "// clang-format off", "const NamedSpectrum kNamedSpectra[] = {"]
    for name in sorted(named):
        # An index is never negative: the colour-matching lobes' negative parts give -1e-4 for
        # the nearly zero k of MgO and TiO2.
        rgb = numpy.maximum(to_rgb(*named[name], grid, weights), 0.0)
        lines.append('    {"%s", {%s, %s, %s}, %s},' % (
            name, fmt(rgb[0]), fmt(rgb[1]), fmt(rgb[2]),
            fmt(numpy.interp(GLASS_WAVELENGTH, *named[name])) if name.startswith("glass-")
            else "0.0f"))
    lines.append("};")
    lines.append("")
    lines.append("constexpr double kSampledFirst = %d;  // nm" % FIRST)
    lines.append("constexpr double kSampledStep = %d;   // nm" % STEP)
    lines.append("const float kSampledWeights[%d][3] = {" % len(samples))
    for w in per_sample:
        lines.append("    {%s, %s, %s}," % (fmt(w[0]), fmt(w[1]), fmt(w[2])))
    lines.append("};")
    grid_e, rgb_e, y_e = emission_observer()
    _, emission = sampled_weights(grid_e, numpy.vstack([rgb_e, y_e]))
    lines.append("// Emission: per sample, M cmf (linear sRGB) and ybar, for RGB = sum L w / sum L y.")
    lines.append("const float kEmissionWeights[%d][4] = {" % len(emission))
    for w in emission:
        lines.append("    {%s, %s, %s, %s}," % (fmt(w[0]), fmt(w[1]), fmt(w[2]), fmt(w[3])))
    lines.append("};")
    lines.append("// clang-format on")
    return "\n".join(lines) + "\n"


def main(argv):
    if not argv or len(argv) > 2:
        sys.exit(__doc__.strip().splitlines()[-2].strip())
    source = pathlib.Path(argv[0])
    out = pathlib.Path(argv[1]) if len(argv) > 1 else ROOT / "host" / "scene" / "spectra_table.inc"
    text = source.read_text()
    named = parse_named(text, parse_arrays(text))
    grid, weights = observer()
    constant = to_rgb(numpy.array([300.0, 900.0]), numpy.array([0.7, 0.7]), grid, weights)
    assert numpy.allclose(constant, 0.7, atol=1e-6), constant
    out.write_text(table(named, grid, weights, "pbrt-v4 src/pbrt/util/spectrum.cpp"))
    print("wrote %s: %d named spectra" % (out, len(named)))


if __name__ == "__main__":
    main(sys.argv[1:])
