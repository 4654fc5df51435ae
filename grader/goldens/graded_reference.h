// graded_reference: the reference's images that a grade reads and compares with, made the same
// way for the goldens (golden.cpp) and for a live grade (the worker's reference render), at the
// goldens' precision (golden_encoding.h): so a live grade and a grade against goldens made on
// the same Mesa are equal, value for value.
#pragma once

#include "image.h"
#include "renderer.h"
#include "scene.h"

#include <filesystem>
#include <map>
#include <string>

namespace sl::grader {

// The msm stage's lighting-only render: the scene lit from the given filtered moments (sampled
// bilinearly, whatever the scene's filter) with each camera's zf taken from its
// "relative_depth" image, by camera index (RelativeDepth::Given): it compiles the library's
// msm.glsl and no moments.glsl.
RenderResult renderFromMoments(Renderer& renderer, Scene scene, const Image& filtered,
                               const std::map<int, Image>& relativeDepth);

// The relative_depth images of a reference's render beside `input` (the msm stage's input file,
// moments_filtered.raw or .exr, in the same folder and format), by camera index.
std::map<int, Image> relativeDepthBeside(const Scene& scene, const std::filesystem::path& input);

// Everything a grade compares with or reads, rounded as the goldens store it: the frame with
// the resolved SAT (moments_raw, moments_filtered, shadow, final per camera), the per-pixel
// SAT's kernel ladder, each camera's relative_depth, and the msm stage's msm_shadow images,
// lit from the rounded moments_filtered and relative_depth. The renderer holds the reference.
// `full`, if given, receives the frame unrounded (the scene's probes are checked on it).
RenderResult gradedReferenceImages(Renderer& renderer, const Scene& scene,
                                   RenderResult* full = nullptr);

}  // namespace sl::grader
