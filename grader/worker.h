// worker.h: what one grader child process renders (the hidden `grade-worker` subcommand).
#pragma once

#include "renderer.h"
#include "scene.h"

#include <filesystem>
#include <string>

namespace sl::grader {

struct WorkerArgs {
    std::string scene;       // scene JSON path
    std::string stage;       // reference | moments | gaussian | sat | msm | final
    std::string submission;  // staged submission folder
    std::string reference;   // reference solution folder ("" when only goldens exist)
    std::string input;       // reference moments_raw (gaussian, sat) or moments_filtered (msm)
    std::string out;         // folder for <image>.exr and worker.json
    std::string backend = "auto";
};

// Renders and writes the stage's images. Throws (ShaderError for compile/link errors: the
// command line turns it into exit code 3 and the mapped log on stderr).
void runWorker(const WorkerArgs& args);

// runWorker as a process's whole work: the exit code and stderr text of `shadowlab
// grade-worker` (0; 2 scene error; 3 "shader error:" and the mapped log; 4 no OpenGL; 1 other).
// A child forked without exec runs this (isolation.h).
int workerMain(const WorkerArgs& args);

// Lighting only, with `filtered` standing in for the first shadowing light's filtered moments
// (bilinear, whatever the scene's filter): the msm stage, for the student and the reference.
RenderResult renderFromMoments(Renderer& renderer, Scene scene, const Image& filtered);

}  // namespace sl::grader
