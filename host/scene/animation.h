// Keyframed rigid motion of shapes, emitters and the camera (docs/scene-format.md): linear
// translation and spherical-linear rotation between keyframes, held before the first and after
// the last keyframe.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

namespace rc {

// Frame numbers lie in [-kMaxFrameNumber, kMaxFrameNumber] (scene files and --frames): ints, read
// with a range check; frame loops count in 64 bits.
inline constexpr int kMaxFrameNumber = std::numeric_limits<int>::max();

struct Keyframe {
    double frame = 0.0;
    glm::vec3 translate{0.0f};
    glm::quat rotate{1.0f, 0.0f, 0.0f, 0.0f};
};

enum class TrackTarget { kCamera, kShape, kEmitter };

struct AnimationTrack {
    TrackTarget target = TrackTarget::kShape;
    std::string name;                 // the shape or emitter (empty for the camera)
    std::vector<Keyframe> keyframes;  // ordered by frame, at least one

    // translate(frame) * rotate(frame), applied after the object's own transform.
    glm::mat4 at(double frame) const;
};

struct Animation {
    double frame_start = 0.0;
    double frame_end = 0.0;
    double fps = 24.0;
    std::vector<AnimationTrack> tracks;

    bool empty() const { return tracks.empty(); }
    // The motion of a target at a frame (identity when no track names it).
    glm::mat4 motion(TrackTarget target, const std::string& name, double frame) const;
};

}  // namespace rc
