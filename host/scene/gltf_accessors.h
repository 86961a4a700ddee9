// Reading glTF 2.0 accessors (the typed views of a model's buffers) with every bound checked:
// a malformed file is an Error naming the accessor, never a read outside its buffer.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace rc {

// Accessor `index` of `model` as `components` floats per element (its components converted,
// normalized integers scaled to [0, 1] or [-1, 1]); Error naming `what` and the accessor when
// the index, its type, its buffer view or its byte range are invalid, or it is sparse.
std::vector<float> read_float_accessor(const tinygltf::Model& model, int index, int components,
                                       const std::string& what);

// Accessor `index` as unsigned integer indices (SCALAR of unsigned byte, short or int).
std::vector<unsigned> read_index_accessor(const tinygltf::Model& model, int index,
                                          const std::string& what);

}  // namespace rc
