// golden: making, reading and checking golden images. They are kept small because they are
// committed: moment maps stay float32 (their tolerance is relative and reaches 1e-4 near 0,
// below half's precision) but with the mantissa rounded to kMomentMantissaBits bits, a
// relative error of 2^-16 (100× inside the tolerance) that lets ZIP compress the low bits
// away; shadow and colour images are half floats (error ≤ 5e-4, 20× inside their tolerance).
// Both encodings are deterministic, so `golden --check` can compare hashes with the manifest.
#include "golden.h"
#include "raw_image.h"
#include "worker.h"

#include "grader.h"
#include "gl_context.h"
#include "image_io.h"
#include "pass_plan.h"
#include "paths.h"
#include "renderer.h"
#include "scene.h"
#include "scene_list.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

namespace sl::grader {
namespace {

constexpr int kMomentMantissaBits = 15;

float roundMantissa(float v, int bits) {
    if (!std::isfinite(v)) return v;
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    const int drop = 23 - bits;
    const std::uint32_t half = 1u << (drop - 1);
    u = (u + half) & ~((1u << drop) - 1);  // round half up on the magnitude
    std::memcpy(&v, &u, 4);
    return v;
}

void writeEncoded(const Image& image, const fs::path& path, bool moments) {
    Image img = image;
    if (moments)
        for (float& v : img.pixels) v = roundMantissa(v, kMomentMantissaBits);
    // Files are top row first.
    std::vector<float> flipped(img.pixels.size());
    const size_t row = size_t(img.width) * img.channels;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(img.pixels.begin() + size_t(y) * row, row,
                    flipped.begin() + size_t(img.height - 1 - y) * row);
    OIIO::ImageSpec spec(img.width, img.height, img.channels,
                         moments ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF);
    spec.attribute("compression", "zip");
    spec.attribute("DateTime", "");
    if (img.channels == 1) spec.channelnames = {"Y"};
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->open(path.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, flipped.data()))
        throw std::runtime_error(path.string() + ": cannot write golden image");
    out->close();
}

std::string envOr(const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return v ? v : fallback;
}

}  // namespace

std::vector<std::string> makeGoldens(const GoldenOptions& o) {
    const fs::path solution = resolveSolution(o.solution);
    auto context = createContext(parseBackendKind(o.backend));
    const ContextInfo& info = context->info();
    const fs::path dir = o.check ? fs::temp_directory_path() / ("shadowlab-golden-check-" +
                                                                std::to_string(::getpid()))
                                 : o.out;
    fs::create_directories(dir);
    nlohmann::json manifest = {
        {"mesa_version", info.mesaVersion},
        {"renderer", info.renderer},
        {"gl_version", info.version},
        {"backend", info.backend},
        {"settings",
         {{"LP_NUM_THREADS", envOr("LP_NUM_THREADS", "")},
          {"GALLIUM_DRIVER", envOr("GALLIUM_DRIVER", "llvmpipe")},
          {"moment_encoding", "float32, mantissa rounded to " +
                                  std::to_string(kMomentMantissaBits) + " bits, ZIP"},
          {"image_encoding", "half, ZIP"}}},
        {"solution", o.solution},
        {"made_by", "shadowlab golden --solution " + o.solution + " --out " + o.out.string()},
        {"scenes", nlohmann::json::object()}};
    const auto scenes = gradedScenes(o.scenes);
    for (const GradedScene& gs : scenes) {
        const std::string& name = gs.name;
        const fs::path& path = gs.path;
        Scene scene = loadScene(path.string());
        Renderer renderer(ShaderLibrary::forSolution(solution, repoRoot()));
        RenderResult result = renderer.render(scene, planPasses(scene));
        fs::create_directories(dir / name);
        nlohmann::json images = nlohmann::json::object();
        for (const auto& [image, pixels] : result.images) {
            if (image.rfind("sat", 0) == 0) continue;  // graded through moments_filtered
            const fs::path file = dir / name / (image + ".exr");
            writeEncoded(pixels, file, image.rfind("moments", 0) == 0);
            images[image] = nlohmann::json{{"file", name + "/" + image + ".exr"},
                                           {"sha256", sha256File(file)}};
        }
        // The msm stage's reference: lit from the golden filtered moments as stored (rounded),
        // exactly what a student's msm.glsl gets as input.
        if (result.images.count("moments_filtered")) {
            const Image stored = readAnyImage(dir / name / "moments_filtered.exr");
            RenderResult isolated = renderFromMoments(renderer, scene, stored);
            for (const auto& [image, pixels] : isolated.images) {
                if (image.rfind("shadow", 0) != 0) continue;
                const fs::path file = dir / name / ("msm_" + image + ".exr");
                writeEncoded(pixels, file, false);
                images["msm_" + image] = nlohmann::json{{"file", name + "/msm_" + image + ".exr"},
                                                        {"sha256", sha256File(file)}};
            }
        }
        manifest["scenes"][name] = nlohmann::json{{"scene_sha256", sha256File(path)}, {"images", images}};
        std::cerr << "golden: " << name << " (" << images.size() << " images)\n";
    }
    std::vector<std::string> stale;
    if (o.check) {
        nlohmann::json committed = readManifest(o.out);
        for (const auto& [scene, entry] : manifest["scenes"].items())
            for (const auto& [image, e] : entry["images"].items()) {
                const auto* old = committed.is_null() ? nullptr
                                  : committed["scenes"].contains(scene) &&
                                          committed["scenes"][scene]["images"].contains(image)
                                      ? &committed["scenes"][scene]["images"][image]
                                      : nullptr;
                if (!old || (*old)["sha256"] != e["sha256"]) stale.push_back(scene + "/" + image);
            }
        std::error_code ec;
        fs::remove_all(dir, ec);
    } else {
        std::ofstream(dir / "manifest.json") << manifest.dump(2) << "\n";
    }
    return stale;
}

Image readGolden(const fs::path& goldens, const std::string& scene, const std::string& image) {
    const fs::path file = goldens / scene / (image + ".exr");
    if (!fs::exists(file)) return {};
    return readImage(file);
}

nlohmann::json readManifest(const fs::path& goldens) {
    std::ifstream in(goldens / "manifest.json");
    if (!in) return nullptr;
    try {
        return nlohmann::json::parse(in);
    } catch (const std::exception&) {
        return nullptr;
    }
}

std::vector<std::string> manifestWarnings(const nlohmann::json& manifest,
                                          const nlohmann::json& running) {
    std::vector<std::string> w;
    if (manifest.is_null()) return {"golden manifest missing or unreadable"};
    auto field = [](const nlohmann::json& j, const char* k) {
        return j.contains(k) && j[k].is_string() ? j[k].get<std::string>() : std::string();
    };
    for (auto [key, label] : {std::pair{"mesaVersion", "mesa_version"},
                              std::pair{"renderer", "renderer"}}) {
        const std::string now = field(running, key), then = field(manifest, label);
        if (!now.empty() && now != then)
            w.push_back(std::string("goldens were made with ") + label + " \"" + then +
                        "\", this machine has \"" + now +
                        "\": small edge differences are forgiven, larger ones may cost points");
    }
    return w;
}

}  // namespace sl::grader
