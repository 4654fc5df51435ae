// ViewOptions: what the viewer shows, as opposed to what the scene is (EditableScene) —
// which image of the render, and which of its channels.
// Set from the panels or as `shadowlab view --set view.<key>=<value>`.
#pragma once

#include <string>
#include <vector>

namespace sl {

struct ViewOptions {
    std::string image = "final";  // a RenderResult image name: final, shadow, moments_raw, ...
    int channel = -1;             // -1: all (colour / grey); 0-3: that channel alone, as grey
};

// The images the viewer offers, in its order (those a render has; see RenderResult).
const std::vector<std::string>& viewImageNames();

// Sets "view.image" | "view.channel" from its text value. Returns false if
// `key` is not a view key; throws std::invalid_argument naming key and expectation on a bad value.
bool setViewOption(ViewOptions& options, const std::string& key, const std::string& value);

}  // namespace sl
