// codec_child: the image codec in a child process. OpenImageIO loads libhwy, whose load-time
// initialiser executes `rdtscp`, an instruction valgrind 3.19 cannot run on a CPU that does not
// advertise it (this VM's): the exact cost mode (callgrind, tools/cost_exact.sh) stopped at the
// study's first image. With SHADOWLAB_CODEC=child every image read, write and comparison goes
// to `shadowlab codec-server`, started once with exec: valgrind does not follow an exec (no
// --trace-children), so OpenImageIO runs natively there and never enters the counted process.
// Same files, same bytes: the child runs the same module (image_codec.h).
#pragma once

#include "image_codec.h"

namespace sl {

// True when SHADOWLAB_CODEC=child: image_io then uses childCodec() instead of the module.
bool codecInChild();

// A table that forwards each call to the child (started on the first call). Throws
// std::runtime_error with the child's message when a call fails there.
const ImageCodec& childCodec();

// The child's loop: requests on `in`, answers on `out`, with `codec` doing the work; returns
// when `in` closes (the parent exited). `shadowlab codec-server` runs it on stdin/stdout.
int serveCodec(int in, int out, const ImageCodec& codec);

}  // namespace sl
