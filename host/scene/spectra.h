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

// A blackbody's emission at `kelvin` as linear sRGB with luminance Y = 1: pbrt-v4's normalisation
// of a light's spectrum (it divides by the spectrum's photometric integral), so that a light's
// "blackbody L" [T] and "scale" give a luminance of `scale`, as "rgb L" [1 1 1] does. Planck's law
// (pbrt-v4 §4.4.1) on 360-830 nm; nullopt unless kelvin is finite and positive.
std::optional<glm::vec3> blackbody_rgb(double kelvin);

// The same spectrum's value at one wavelength.
std::optional<double> sampled_spectrum_at(const std::vector<double>& pairs, double wavelength);

}  // namespace rc
