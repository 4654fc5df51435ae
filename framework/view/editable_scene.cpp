// EditableScene: scene JSON + re-validation on every change (see editable_scene.h).
#include "editable_scene.h"

#include <fstream>
#include <sstream>
#include <vector>

namespace sl {

using Json = nlohmann::json;

namespace {

std::vector<std::string> keyParts(const std::string& key) {
    std::vector<std::string> parts;
    std::stringstream in(key);
    for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
    return parts;
}

// "shadow.filter.radius" -> "/shadow/filter/radius" (array elements by number: "lights.0").
// A new key may be added to an object, but the path may not run through a number or a
// string, nor index an array past its end (nlohmann would pad it with nulls).
Json::json_pointer checkedPointer(const Json& doc, const std::string& key, const std::string& file) {
    const std::vector<std::string> parts = keyParts(key);
    std::string pointer;
    const Json* at = &doc;
    for (const std::string& part : parts) {
        auto fail = [&](const std::string& expected) {
            return SceneError(file + ": " + (pointer.empty() ? "/" : pointer) + ": expected " +
                              expected + ", found \"" + part + "\"");
        };
        if (part.empty()) throw fail("a dotted key such as shadow.filter.radius, not an empty part");
        if (at && at->is_array()) {
            const bool digits = part.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || std::stoul(part) >= at->size())
                throw fail("an index below " + std::to_string(at->size()));
            at = &(*at)[std::stoul(part)];
        } else if (at && at->is_object()) {
            at = at->contains(part) ? &(*at)[part] : nullptr;
        } else if (at) {  // (no `at`: a new key, its objects are created)
            throw fail("nothing below a value that is neither an object nor an array");
        }
        pointer += "/" + part;
    }
    return Json::json_pointer(pointer);
}

}  // namespace

EditableScene::EditableScene(const std::string& path) : path_(path) {
    scene_ = loadScene(path);  // the loader's messages for a missing or broken file
    std::ifstream in(path, std::ios::binary);
    json_ = Json::parse(in);
    if (json_.contains("shadow") && json_["shadow"].contains("filter"))
        filterByType_[toString(scene_.shadow.filter)] = json_["shadow"]["filter"];
}

void EditableScene::set(const std::string& key, const Json& value) {
    Json edited = json_;
    const Json::json_pointer ptr = checkedPointer(edited, key, path_);
    const Json::json_pointer filter("/shadow/filter");
    const std::string currentType = toString(scene_.shadow.filter);
    if (key == "shadow.filter.type" && value.is_string()) {
        filterByType_[currentType] = edited.contains(filter) ? edited[filter] : Json{{"type", currentType}};
        auto known = filterByType_.find(value.get<std::string>());
        edited[filter] = known != filterByType_.end() ? known->second : Json{{"type", value}};
    } else {
        // A filter parameter on a scene that relied on the default filter: name its type.
        if (key.rfind("shadow.filter.", 0) == 0 && !edited.contains(filter / "type"))
            edited[filter / "type"] = currentType;
        if (!value.is_null()) edited[ptr] = value;
        else if (edited.contains(ptr)) edited[ptr.parent_pointer()].erase(ptr.back());
    }
    if (key == "shadow.technique" && value.is_string())
        return switchTechnique(std::move(edited), value.get<std::string>());
    Scene fresh = parseScene(edited.dump(2), path_);  // throws SceneError: nothing changes
    json_ = std::move(edited);
    scene_ = std::move(fresh);
}

// Tries, in order: the technique's own filter and parameters from before; the current filter
// without the parameters (they belong to the old technique); the technique's defaults.
void EditableScene::switchTechnique(Json edited, const std::string& to) {
    auto part = [](const Json& doc, const char* key) {
        return doc.contains("shadow") && doc["shadow"].contains(key) ? doc["shadow"][key] : Json();
    };
    auto with = [&](const Json& filter, const Json& parameters) {
        Json candidate = edited;
        Json& shadow = candidate["shadow"];
        if (filter.is_null()) shadow.erase("filter"); else shadow["filter"] = filter;
        if (parameters.is_null()) shadow.erase("parameters"); else shadow["parameters"] = parameters;
        return candidate;
    };
    std::vector<Json> candidates;
    if (auto known = shadowByTechnique_.find(to); known != shadowByTechnique_.end())
        candidates.push_back(with(known->second["filter"], known->second["parameters"]));
    candidates.push_back(with(part(json_, "filter"), Json()));
    candidates.push_back(with(Json(), Json()));
    std::string firstError;
    for (Json& candidate : candidates) {
        try {
            Scene fresh = parseScene(candidate.dump(2), path_);
            shadowByTechnique_[toString(scene_.shadow.technique)] =
                Json{{"filter", part(json_, "filter")}, {"parameters", part(json_, "parameters")}};
            json_ = std::move(candidate);
            scene_ = std::move(fresh);
            return;
        } catch (const SceneError& e) {
            if (firstError.empty()) firstError = e.what();
        }
    }
    throw SceneError(firstError);
}

void EditableScene::set(const std::string& key, const std::string& value) {
    Json parsed = Json::parse(value, nullptr, /*allow_exceptions=*/false);
    set(key, parsed.is_discarded() ? Json(value) : parsed);
}

std::pair<std::string, std::string> splitSetting(const std::string& setting) {
    const size_t eq = setting.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SceneError("--set " + setting + ": expected key=value (for example "
                         "shadow.filter.radius=8 or view.image=shadow)");
    return {setting.substr(0, eq), setting.substr(eq + 1)};
}

}  // namespace sl
