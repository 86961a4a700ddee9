#include "bvh/embree_device.h"

#include "util/error.h"

namespace rc {

EmbreeDevice::EmbreeDevice() {
    device_ = rtcNewDevice("verbose=0");
    if (device_ == nullptr) {
        throw Error("rtcNewDevice failed: Embree error " +
                    std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))));
    }
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::on_error, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

void EmbreeDevice::on_error(void* user, RTCError code, const char* message) {
    auto* self = static_cast<EmbreeDevice*>(user);
    self->last_message_ =
        "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

void EmbreeDevice::check(const std::string& what) const {
    const RTCError code = rtcGetDeviceError(device_);
    if (code != RTC_ERROR_NONE) {
        std::string message = last_message_.empty()
                                  ? "Embree error " + std::to_string(static_cast<int>(code))
                                  : last_message_;
        last_message_.clear();
        throw Error(what + ": " + message);
    }
}

}  // namespace rc
