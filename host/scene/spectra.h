// pbrt-v4's spectra as radcache's linear-sRGB values: its named metal and glass spectra and
// spectra sampled as wavelength-value pairs (tools/spectra_to_rgb.py generates the tables, from
// pbrt-v4's tabulated data and colour-science's CIE observer and D65).
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rc {

// A named spectrum ("metal-Au-eta", "glass-BK7", ...) as linear sRGB, or nullopt for a name
// not in pbrt-v4's list.
std::optional<glm::vec3> named_spectrum_rgb(const std::string& name);

// A named glass's index of refraction at 550 nm, or nullopt.
std::optional<float> named_glass_ior(const std::string& name);

// A spectrum given as wavelength-value pairs (nm; linear between them, held beyond the ends) as
// linear sRGB; nullopt unless there are at least two pairs, their wavelengths increasing and
// every number finite.
std::optional<glm::vec3> sampled_spectrum_rgb(const std::vector<double>& pairs);

// The same spectrum's value at one wavelength.
std::optional<double> sampled_spectrum_at(const std::vector<double>& pairs, double wavelength);

}  // namespace rc
