// An Embree device with its errors turned into rc::Error.
#pragma once

#include <embree3/rtcore.h>

#include <string>

namespace rc {

class EmbreeDevice {
   public:
    EmbreeDevice();
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice handle() const { return device_; }
    // Throws Error("<what>: Embree error <code>: <message>") if Embree reported an error.
    void check(const std::string& what) const;

   private:
    static void on_error(void* user, RTCError code, const char* message);

    RTCDevice device_ = nullptr;
    mutable std::string last_message_;
};

}  // namespace rc
