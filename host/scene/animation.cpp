#include "scene/animation.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace rc {

glm::mat4 AnimationTrack::at(double frame) const {
    const Keyframe* a = &keyframes.front();
    const Keyframe* b = a;
    if (frame >= keyframes.back().frame) {
        a = b = &keyframes.back();
    } else if (frame > keyframes.front().frame) {
        const auto after =
            std::upper_bound(keyframes.begin(), keyframes.end(), frame,
                             [](double f, const Keyframe& k) { return f < k.frame; });
        b = &*after;
        a = &*(after - 1);
    }
    glm::vec3 translate = a->translate;
    glm::quat rotate = a->rotate;
    if (a != b) {
        const float s = static_cast<float>((frame - a->frame) / (b->frame - a->frame));
        translate = a->translate + s * (b->translate - a->translate);
        rotate = glm::slerp(a->rotate, b->rotate, s);
    }
    return glm::translate(glm::mat4(1.0f), translate) * glm::mat4_cast(rotate);
}

glm::mat4 Animation::motion(TrackTarget target, const std::string& name, double frame) const {
    for (const AnimationTrack& track : tracks) {
        if (track.target == target && (target == TrackTarget::kCamera || track.name == name)) {
            return track.at(frame);
        }
    }
    return glm::mat4(1.0f);
}

}  // namespace rc
