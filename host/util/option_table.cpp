#include "util/option_table.h"

namespace rc {

const char* knob_direction_name(KnobDirection direction) {
    switch (direction) {
        case KnobDirection::kIncrease:
            return "increase";
        case KnobDirection::kDecrease:
            return "decrease";
        case KnobDirection::kNone:
            break;
    }
    return "none";
}

std::string OptionInfo::help_with_default() const {
    if (!default_note.empty()) {
        return spec.help + " (default " + default_note + ")";
    }
    if (type == "flag" || default_text.empty()) {
        return spec.help;
    }
    return spec.help + " (default " + default_text + (unit.empty() ? "" : " " + unit) + ")";
}

}  // namespace rc
