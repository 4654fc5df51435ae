// ViewOptions: parsing of the view.* settings (see view_options.h).
#include "view_options.h"
#include "image_name.h"

#include <algorithm>
#include <stdexcept>

namespace sl {

const std::vector<std::string>& viewImageNames() {
    static const std::vector<std::string> names = {"final", "shadow", "moments_raw",
                                                   "moments_filtered", "sat"};
    return names;
}

bool setViewOption(ViewOptions& options, const std::string& key, const std::string& value) {
    auto bad = [&](const std::string& expected) {
        return std::invalid_argument("--set " + key + "=" + value + ": expected " + expected +
                                     ", found \"" + value + "\"");
    };
    if (key == "view.image") {
        // A further light's maps carry a suffix: moments_raw_light1.
        const auto& names = viewImageNames();
        const auto n = ImageName::parse(value);
        const bool known = n && !n->msmIsolated && n->camera.empty() && n->cascade == 0 &&
                           n->layer == 0 &&
                           std::find(names.begin(), names.end(), toString(n->kind)) != names.end();
        if (!known)
            throw bad("one of final, shadow, moments_raw, moments_filtered, sat (a further "
                      "light's maps: moments_raw_light1, ...)");
        options.image = value;
    } else if (key == "view.channel") {
        if (value == "all") options.channel = -1;
        else if (value.size() == 1 && value[0] >= '0' && value[0] <= '3') options.channel = value[0] - '0';
        else throw bad("all, 0, 1, 2 or 3");
    } else if (key.rfind("view.", 0) == 0) {
        throw std::invalid_argument("--set " + key + ": expected view.image or view.channel, "
                                    "found \"" + key + "\"");
    } else {
        return false;
    }
    return true;
}

}  // namespace sl
