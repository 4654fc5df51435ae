// Backends: both give a 4.5 core context on llvmpipe; failures are named, not silent.
#include "gl_context.h"
#include "gl_test_support.h"

#include <gtest/gtest.h>

namespace sl {

TEST(Backends, OSMesaGivesCoreContextOnLlvmpipe) {
    auto ctx = createContext(BackendKind::OSMesa);
    EXPECT_EQ(ctx->info().backend, "osmesa");
    EXPECT_NE(ctx->info().version.find("4.5 (Core Profile)"), std::string::npos);
    EXPECT_TRUE(ctx->info().isSoftware()) << ctx->info().renderer;
    EXPECT_FALSE(ctx->info().mesaVersion.empty());
}

TEST(Backends, EglSurfacelessGivesCoreContextOnLlvmpipe) {
    auto ctx = createContext(BackendKind::Egl);
    EXPECT_EQ(ctx->info().backend, "egl");
    EXPECT_NE(ctx->info().version.find("4.5 (Core Profile)"), std::string::npos);
    EXPECT_TRUE(ctx->info().isSoftware()) << ctx->info().renderer;
}

TEST(Backends, AutoPrefersOSMesa) {
    EXPECT_EQ(createContext(BackendKind::Auto)->info().backend, "osmesa");
}

TEST(Backends, BothBackendsInOneProcessReportTheSameMesa) {
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
