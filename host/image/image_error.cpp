#include "image/image_error.h"

#include <cmath>
#include <limits>

#include "util/error.h"

namespace rc {

double relative_squared_error(double value, double reference) {
    const double d = value - reference;
    return d * d / (reference * reference + 0.01);
}

ImageError image_error(const Image& test, const Image& reference, const std::string& test_name) {
    if (test.width != reference.width || test.height != reference.height) {
        throw Error(test_name + ": " + std::to_string(test.width) + "x" +
                    std::to_string(test.height) + " against a " + std::to_string(reference.width) +
                    "x" + std::to_string(reference.height) + " reference");
    }
    if (test.channels != reference.channels) {
        throw Error(test_name + ": " + std::to_string(test.channels) + " channels against " +
                    std::to_string(reference.channels) + " in the reference");
    }
    ImageError e;
    const int channels = test.channels;
    e.channels = test.channel_names;
    e.test_means.assign(channels, 0.0);
    e.reference_means.assign(channels, 0.0);
    double squared = 0.0;
    double relative = 0.0;
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            for (int c = 0; c < channels; ++c) {
                const double v = test.at(x, y, c);
                const double r = reference.at(x, y, c);
                const double d = v - r;
                squared += d * d;
                relative += relative_squared_error(v, r);
                e.test_means[c] += v;
                e.reference_means[c] += r;
                if (!(std::fabs(d) <= e.max_error)) {  // NaN counts as the largest error
                    e.max_error =
                        std::isnan(d) ? std::numeric_limits<double>::infinity() : std::fabs(d);
                    e.max_x = x;
                    e.max_y = y;
                    e.max_channel = c;
                }
            }
        }
    }
    const double values = static_cast<double>(test.width) * test.height * channels;
    if (values > 0.0) {
        e.rmse = std::sqrt(squared / values);
        e.relmse = relative / values;
        const double pixels = static_cast<double>(test.width) * test.height;
        for (int c = 0; c < channels; ++c) {
            e.test_means[c] /= pixels;
            e.reference_means[c] /= pixels;
        }
    }
    const double mse = e.rmse * e.rmse;
    e.psnr = mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
    return e;
}

}  // namespace rc
