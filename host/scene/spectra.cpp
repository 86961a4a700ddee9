#include "scene/spectra.h"

#include <cmath>
#include <cstring>
#include <iterator>

namespace rc {
namespace {

struct NamedSpectrum {
    const char* name;
    float rgb[3];
    float ior_550;  // glasses: the index at 550 nm; metals: 0
};

#include "scene/spectra_table.inc"

const NamedSpectrum* find(const std::string& name) {
    for (const NamedSpectrum& s : kNamedSpectra) {
        if (name == s.name) {
            return &s;
        }
    }
    return nullptr;
}

bool valid_pairs(const std::vector<double>& pairs) {
    if (pairs.size() < 4 || pairs.size() % 2 != 0) {
        return false;
    }
    for (size_t i = 0; i < pairs.size(); ++i) {
        if (!std::isfinite(pairs[i]) || (i % 2 == 0 && i >= 2 && !(pairs[i] > pairs[i - 2]))) {
            return false;
        }
    }
    return true;
}

// The value at `wavelength` of valid pairs: linear interpolation, held beyond the ends.
double value_at(const std::vector<double>& pairs, double wavelength) {
    if (wavelength <= pairs[0]) {
        return pairs[1];
    }
    for (size_t i = 2; i < pairs.size(); i += 2) {
        if (wavelength <= pairs[i]) {
            const double t = (wavelength - pairs[i - 2]) / (pairs[i] - pairs[i - 2]);
            return (1.0 - t) * pairs[i - 1] + t * pairs[i + 1];
        }
    }
    return pairs.back();
}

}  // namespace

std::optional<glm::vec3> named_spectrum_rgb(const std::string& name) {
    const NamedSpectrum* s = find(name);
    if (s == nullptr) {
        return std::nullopt;
    }
    return glm::vec3(s->rgb[0], s->rgb[1], s->rgb[2]);
}

std::optional<float> named_glass_ior(const std::string& name) {
    const NamedSpectrum* s = find(name);
    if (s == nullptr || s->ior_550 <= 0.0f) {
        return std::nullopt;
    }
    return s->ior_550;
}

std::optional<glm::vec3> sampled_spectrum_rgb(const std::vector<double>& pairs) {
    if (!valid_pairs(pairs)) {
        return std::nullopt;
    }
    double rgb[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < std::size(kSampledWeights); ++i) {
        const double value = value_at(pairs, kSampledFirst + kSampledStep * i);
        for (int c = 0; c < 3; ++c) {
            rgb[c] += value * kSampledWeights[i][c];
        }
    }
    return glm::vec3(rgb[0], rgb[1], rgb[2]);
}

std::optional<glm::vec3> blackbody_rgb(double kelvin) {
    if (!std::isfinite(kelvin) || !(kelvin > 0.0)) {
        return std::nullopt;
    }
    // Planck's law up to its constant factor, which the luminance normalisation removes:
    // L(l) ~ l^-5 / (exp(hc / (l k T)) - 1), hc / k = 1.438777e-2 m K.
    constexpr double kSecondRadiation = 1.438777e-2;  // m K
    double rgb[3] = {0.0, 0.0, 0.0};
    double luminance = 0.0;
    for (size_t i = 0; i < std::size(kEmissionWeights); ++i) {
        const double metres = (kSampledFirst + kSampledStep * i) * 1e-9;
        const double planck =
            1.0 / (std::pow(metres * 1e6, 5.0) * std::expm1(kSecondRadiation / (metres * kelvin)));
        for (int c = 0; c < 3; ++c) {
            rgb[c] += planck * kEmissionWeights[i][c];
        }
        luminance += planck * kEmissionWeights[i][3];
    }
    if (!(luminance > 0.0) || !std::isfinite(luminance)) {
        return std::nullopt;  // so cold that no visible light is left in double precision
    }
    return glm::vec3(rgb[0] / luminance, rgb[1] / luminance, rgb[2] / luminance);
}

std::optional<double> sampled_spectrum_at(const std::vector<double>& pairs, double wavelength) {
    if (!valid_pairs(pairs)) {
        return std::nullopt;
    }
    return value_at(pairs, wavelength);
}

}  // namespace rc
