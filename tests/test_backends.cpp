// Backends: each present gives a 4.5 core context on llvmpipe (an absent one is skipped, with
// the reason); failures are named, not silent.
#include "gl_context.h"
#include "gl_test_support.h"

#include <gtest/gtest.h>

#include <regex>

namespace sl {

namespace {
// "4.5 (Core Profile) Mesa 22.3.6", "4.6 (Core Profile) Mesa 26.1.6": 4.5 or later, core.
bool isCore45OrLater(const std::string& version) {
    std::smatch m;
    if (!std::regex_search(version, m, std::regex(R"(^(\d+)\.(\d+) \(Core Profile\))"))) return false;
    return std::stoi(m[1]) * 10 + std::stoi(m[2]) >= 45;
}
}  // namespace

TEST(Backends, VersionCheckAcceptsOnlyCore45OrLater) {
    EXPECT_TRUE(isCore45OrLater("4.5 (Core Profile) Mesa 22.3.6"));
    EXPECT_TRUE(isCore45OrLater("4.6 (Core Profile) Mesa 26.1.6"));
    EXPECT_FALSE(isCore45OrLater("4.3 (Core Profile) Mesa 20.0"));
    EXPECT_FALSE(isCore45OrLater("4.5 (Compatibility Profile) Mesa 22.3.6"));
}

TEST(Backends, OSMesaGivesCoreContextOnLlvmpipe) {
    SL_SKIP_WITHOUT_OSMESA();
    auto ctx = createContext(BackendKind::OSMesa);
    EXPECT_EQ(ctx->info().backend, "osmesa");
    EXPECT_TRUE(isCore45OrLater(ctx->info().version)) << ctx->info().version;
    EXPECT_TRUE(ctx->info().isSoftware()) << ctx->info().renderer;
    EXPECT_FALSE(ctx->info().mesaVersion.empty());
}

TEST(Backends, EglSurfacelessGivesCoreContextOnLlvmpipe) {
    auto ctx = createContext(BackendKind::Egl);
    EXPECT_EQ(ctx->info().backend, "egl");
    EXPECT_TRUE(isCore45OrLater(ctx->info().version)) << ctx->info().version;
    EXPECT_TRUE(ctx->info().isSoftware()) << ctx->info().renderer;
}

TEST(Backends, AutoTakesOSMesaWhereItLoadsElseEglAndSaysWhy) {
    const auto ctx = createContext(BackendKind::Auto);
    const std::string why = whyNoOSMesa();
    EXPECT_EQ(ctx->info().backend, why.empty() ? "osmesa" : "egl");
    EXPECT_NE(ctx->info().choice.find("auto"), std::string::npos) << ctx->info().choice;
    if (!why.empty()) EXPECT_NE(ctx->info().choice.find(why), std::string::npos) << ctx->info().choice;
}

TEST(Backends, InfoNamesTheBackendAndWhy) {
    auto r = test::runCommand(test::shadowlabBinary() + " info");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("backend:  " + test::autoBackend()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("why:      auto: "), std::string::npos) << r.output;
    r = test::runCommand(test::shadowlabBinary() + " --backend egl info");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("why:      asked for (--backend egl)"), std::string::npos) << r.output;
}

TEST(Backends, BothBackendsInOneProcessReportTheSameMesa) {
    SL_SKIP_WITHOUT_OSMESA();
    // The pitfall of the brief: OSMesa and libEGL both export gl*; each resolves its own.
    auto a = createContext(BackendKind::OSMesa);
    std::string mesaA = a->info().mesaVersion;
    a.reset();
    auto b = createContext(BackendKind::Egl);
    EXPECT_EQ(mesaA, b->info().mesaVersion);
}

TEST(Backends, NoBackendSaysWhatWasTriedAndWhatToInstall) {
    // No OSMesa at the given path, and no EGL vendor for glvnd to load.
    auto r = test::runCommand(
        "SHADOWLAB_OSMESA_LIBRARY=/nonexistent/libOSMesa.so "
        "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/50_mesa.json " +
        test::shadowlabBinary() + " info");
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_NE(r.output.find("osmesa:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("egl:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("apt-get install"), std::string::npos) << r.output;
}

TEST(Backends, UnknownBackendNameIsRejected) {
    EXPECT_THROW(parseBackendKind("vulkan"), std::invalid_argument);
    EXPECT_EQ(parseBackendKind("egl"), BackendKind::Egl);
}

TEST(Backends, MissingFunctionsAreListedByName) {
    auto nothing = [](const char*, void*) -> GlProc { return nullptr; };
    std::string missing = loadGlFunctions(nothing, nullptr);
    EXPECT_NE(missing.find("glCreateShader"), std::string::npos);
    EXPECT_NE(missing.find("glDispatchCompute"), std::string::npos);
}

}  // namespace sl
