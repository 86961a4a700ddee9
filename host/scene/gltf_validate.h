// What glTF 2.0 requires of a document that tinygltf reads without a word (duplicate keys, where
// the last would win; arrays of the wrong length, replaced by defaults; negative offsets, read as
// 0; a node with both a matrix and TRS, whose TRS is dropped; integer positions without the
// extension that allows them), checked on the document's JSON before tinygltf converts it
// (docs/importing.md#gltf-20-import).
#pragma once

#include <string>

namespace rc {

// Error naming the file (`name`) and the JSON path of the first violation in `json_text`, the
// document's JSON (a .glb's JSON chunk): a key given twice in one object (and, as for every JSON
// radcache reads, nesting deeper than kMaxJsonDepth or a number out of range); a
// baseColorFactor or emissiveFactor, a light's color, a node's translation, rotation, scale or
// matrix of the wrong length; a negative byteOffset, byteLength, byteStride or count; a node with
// both a matrix and a translation, rotation or scale (glTF 2.0 §5.25); a POSITION accessor that
// is not float without KHR_mesh_quantization in extensionsUsed.
void validate_gltf_json(const std::string& json_text, const std::string& name);

}  // namespace rc
