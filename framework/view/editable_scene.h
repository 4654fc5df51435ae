// EditableScene: a scene file plus the changes made to it since it was loaded, by the viewer's
// panels or by `shadowlab view --set key=value`. A change is written into the scene's JSON and
// the whole scene is validated again by the loader, so a value is accepted exactly when the
// same value written in the file would be, and rejected with the loader's own message
// ("<file>: <json pointer>: expected <what>, found <what>").
#pragma once

#include "scene.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace sl {

class EditableScene {
public:
    explicit EditableScene(const std::string& path);  // throws SceneError

    const Scene& scene() const { return scene_; }
    const nlohmann::json& document() const { return json_; }

    // `key`: a dotted path into the scene JSON ("shadow.filter.radius", "lights.0.size").
    // Changing "shadow.filter.type" swaps the whole filter object: back to the one last used
    // with that type, or {"type": ...} (the loader's defaults) if it was never used.
    // Changing "shadow.technique" likewise brings back that technique's filter and
    // parameters as last used; a technique met for the first time keeps the filter if the
    // loader accepts it there, else takes the technique's defaults for both.
    // A null `value` removes the key (the loader's default applies again).
    // Throws SceneError naming the key and keeps the scene as it was.
    void set(const std::string& key, const nlohmann::json& value);
    // The same with `value` as JSON text (8, 3e-5, true, [1, 2, 3]) or else a plain string (sat).
    void set(const std::string& key, const std::string& value);

private:
    void switchTechnique(nlohmann::json edited, const std::string& to);

    std::string path_;
    nlohmann::json json_;
    Scene scene_;
    std::map<std::string, nlohmann::json> filterByType_;  // filter objects met so far
    std::map<std::string, nlohmann::json> shadowByTechnique_;  // {filter, parameters} met so far
};

// "key=value" -> {key, value}; throws SceneError when there is no '=' or no key.
std::pair<std::string, std::string> splitSetting(const std::string& setting);

}  // namespace sl
