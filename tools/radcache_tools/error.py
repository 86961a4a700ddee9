"""An image's error against a reference, as `radcache compare` measures it (docs/tools.md,
"radcache compare"): relMSE = the mean over pixels and channels of (v - r)^2 / (r^2 + 0.01), and,
where the reference has a stddev layer and a known sample count (the `spp` of the .stats.json or
.json record beside it), relMSE net of its noise: relMSE minus the mean of
(stddev^2 / spp) / (r^2 + 0.01).

The one relMSE the tools report, relmse(), is the net figure where compare reports it, else the
plain one: compare knows the reference's noise for the beauty layer only, so an indirect or
masked-layer figure is the plain relMSE. The images are compared by radcache itself; the array
functions (numpy) are for figures of images a tool holds in memory and for the sums compare does
not make (the noise of a peer's own images), with compare's definitions.
"""

import json
import os
import tempfile

from radcache_tools import radcache

# The denominator's offset: (v - r)^2 / (r^2 + OFFSET), as in host/image/image_error.cpp.
OFFSET = 0.01


def compare(image, reference, json_path=None, aov="beauty", options=(), tool=None, echo=False):
    """`radcache compare IMAGE REFERENCE --aov AOV --json JSON_PATH OPTIONS` (--mask,
    --error-image, --reference-spp, --allow-nan...): its JSON, the figures. Without JSON_PATH the
    JSON goes to a temporary file. Exits naming the command when compare fails."""
    if json_path is None:
        with tempfile.TemporaryDirectory(prefix="radcache-compare-") as folder:
            return compare(image, reference, os.path.join(folder, "compare.json"), aov, options,
                           tool, echo)
    radcache.run(["compare", image, reference, "--aov", aov, "--json", json_path] +
                 list(options), tool, echo)
    with open(json_path) as f:
        return json.load(f)


def relmse_of(figures):
    """The relMSE of compare's figures (its JSON): net of the reference's noise where compare
    reports that (relmse_net), else the plain relmse."""
    net = figures.get("relmse_net")
    return figures["relmse"] if net is None else net


def relmse(image, reference, json_path=None, aov="beauty", options=(), tool=None, echo=False):
    """IMAGE's relMSE against REFERENCE over layer AOV: relmse_of(compare(...))."""
    return relmse_of(compare(image, reference, json_path, aov, options, tool, echo))


def has_layer(image, layer):
    """Whether `radcache compare` finds layer LAYER in IMAGE (compared with itself)."""
    return radcache.attempt(["compare", image, image, "--aov", layer]).returncode == 0


def relative_squared_errors(test, reference):
    """(v - r)^2 / (r^2 + 0.01) of every value of two arrays of one shape (numpy)."""
    import numpy
    test = numpy.asarray(test, dtype=numpy.float64)
    reference = numpy.asarray(reference, dtype=numpy.float64)
    return (test - reference) ** 2 / (reference ** 2 + OFFSET)


def noise_of_arrays(reference, stddev, spp):
    """The relMSE share of a noisy reference: the mean over its values of
    (stddev^2 / spp) / (r^2 + 0.01), stddev the standard deviation of one sample (numpy)."""
    import numpy
    reference = numpy.asarray(reference, dtype=numpy.float64)
    stddev = numpy.asarray(stddev, dtype=numpy.float64)
    if not spp > 0:
        raise ValueError("the reference's sample count must be positive, got %r" % spp)
    return float(numpy.mean(stddev ** 2 / spp / (reference ** 2 + OFFSET)))


def relmse_of_arrays(test, reference, stddev=None, spp=None):
    """relmse() of two arrays: the mean of relative_squared_errors, net of the reference's noise
    (noise_of_arrays) when its per-sample STDDEV and SPP are given."""
    import numpy
    plain = float(numpy.mean(relative_squared_errors(test, reference)))
    if stddev is None:
        return plain
    return plain - noise_of_arrays(reference, stddev, spp)
