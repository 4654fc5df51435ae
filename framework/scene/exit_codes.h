// exit_codes: the exit codes of the shadowlab program and of the grader's workers, and the one
// place that turns the framework's errors into a code and a message on stderr. Here, below the
// command line and the grader, so that both map the same way (a worker forked without exec
// exits as `shadowlab grade-worker` would).
#pragma once

#include "gl_context.h"
#include "scene.h"
#include "shader_source.h"

#include <exception>
#include <ostream>

namespace sl {

enum ExitCode { Ok = 0, Failed = 1, BadInput = 2, ShaderFailed = 3, NoBackend = 4 };

// The code for `error` (a SceneError: BadInput, a ShaderError: ShaderFailed, a BackendError:
// NoBackend, anything else: Failed), after writing its message to `err` ("scene error: ...",
// "shader error:\n<mapped log>", "no OpenGL: ...", "error: ...").
// Inline: a source file of its own would reshuffle the core's unity batches.
inline ExitCode reportError(std::exception_ptr error, std::ostream& err) {
    try {
        std::rethrow_exception(error);
    } catch (const SceneError& e) {
        err << "scene error: " << e.what() << "\n";
        return BadInput;
    } catch (const ShaderError& e) {
        err << "shader error:\n" << e.what() << "\n";
        return ShaderFailed;
    } catch (const BackendError& e) {
        err << "no OpenGL: " << e.what() << "\n";
        return NoBackend;
    } catch (const std::exception& e) {
        err << "error: " << e.what() << "\n";
        return Failed;
    } catch (...) {
        err << "error: unknown\n";
        return Failed;
    }
}

}  // namespace sl
