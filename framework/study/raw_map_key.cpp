// raw_map_key: the key of a shareable raw shadow map (see raw_map_key.h).
#include "raw_map_key.h"

#include "glsl_scan.h"
#include "image_io.h"
#include "technique.h"


#include <cctype>
#include <cstdio>

namespace sl {
namespace {

// The lines of an assembled program the preprocessor may compile under `defines`, with the
// directives that decide it; without the framework's prologue (#version and the defines'
// own lines: a define is in the key by name, where the text mentions it).
std::string compiledText(const AssembledShader& a, const std::vector<std::string>& defines) {
    glsl::LineScanner scanner;
    glsl::Conditionals conditionals(defines);
    std::string out;
    const auto lines = glsl::splitLines(a.text);
    for (size_t i = 0; i < lines.size(); ++i) {
        const auto directive = scanner.scan(lines[i]);
        const auto before = conditionals.active();
        if (directive) conditionals.apply(*directive);
        const auto after = conditionals.active();
        if (i < a.lines.size() && a.lines[i].file < 0) continue;  // the prologue
        // A line compiled, maybe compiled, or a directive entering or leaving such a region.
        if (before == glsl::Conditionals::No && after == glsl::Conditionals::No) continue;
        out.append(lines[i]);
        out += '\n';
    }
    return out;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `text` has `name` as a whole identifier.
bool mentions(const std::string& text, const std::string& name) {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        const bool startOk = at == 0 || !isIdentifierChar(text[at - 1]);
        const size_t end = at + name.size();
        if (startOk && (end == text.size() || !isIdentifierChar(text[end]))) return true;
    }
    return false;
}

std::string exact(double v) {  // hex float: equal keys mean equal values, bit for bit
    char b[48];
    std::snprintf(b, sizeof b, "%a", v);
    return b;
}

std::string uniformName(const std::string& parameter) {
    std::string u = "u";  // (appended: `"u" + std::string(...)` trips GCC 12's -Wrestrict)
    u += char(std::toupper(static_cast<unsigned char>(parameter[0])));
    u += parameter.substr(1);
    return u;
}

}  // namespace

RawMapKey rawMapKey(const Scene& /*scene*/, const PassPlan& plan, int light,
                    const ShaderLibrary& library, const std::string& sceneDigest) {
    const ShadowEffect& fx = plan.effect;  // the filter it runs decides the map's format
    const TechniqueRow& row = techniqueRow(fx.technique);
    const MapLayout layout = mapLayout(fx);
    RawMapKey key;
    const std::string what = row.store == StoreKind::File ? row.name : toString(row.store);
    key.label = what + " " + layout.formatName + (layout.layers > 1 ? "×" + std::to_string(layout.layers) : "") +
                " " + std::to_string(fx.mapSize) + "² L" + std::to_string(light);
    if (row.secondDepth) {
        key.label += " (not shared: two shadow passes)";
        return key;
    }
    // The shadow pass's program, as render/pass_programs.cpp builds it.
    const std::string fragment = "techniques/store.frag";
    const std::string program = compiledText(library.assemble("scene.vert", plan.defines), plan.defines) +
                                "\n--- " + fragment + "\n" +
                                compiledText(library.assemble(fragment, plan.defines), plan.defines);
    std::string t = "raw-map-1\nscene " + sceneDigest + "\nlight " + std::to_string(light) +
                    "\nsize " + std::to_string(fx.mapSize) + "\nformat " + layout.formatName +
                    " layers " + std::to_string(layout.layers) + "\nclear";
    for (const auto& c : shadowClearValues(fx))
        t += " (" + exact(c.x) + " " + exact(c.y) + " " + exact(c.z) + " " + exact(c.w) + ")";
    for (const std::string& d : plan.defines) {
        const size_t eq = d.find('=');
        if (mentions(program, d.substr(0, eq))) t += "\ndefine " + d;
    }
    for (const auto& [name, value] : resolvedParameters(fx))
        if (mentions(program, uniformName(name))) t += "\nuniform " + uniformName(name) + " " + exact(value);
    if (mentions(program, "uMomentBias")) t += "\nuniform uMomentBias " + exact(fx.momentBias);
    t += "\nprogram " + sha256Hex(program);
    key.text = t;
    key.digest = sha256Hex(t);
    key.label += ' ';
    key.label += key.digest.substr(0, 12);
    return key;
}

}  // namespace sl
