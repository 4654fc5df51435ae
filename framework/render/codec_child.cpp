// codec_child: the image codec in a child process (see codec_child.h). The protocol is binary,
// over two pipes: a request is an opcode and its arguments, an answer a status byte (0: done,
// 1: an error message follows) and the call's result.
#include "codec_child.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>

extern char** environ;

namespace sl {
namespace {

enum Op : uint8_t { OpWrite = 1, OpRead, OpCompare, OpSheet, OpVersion };

// Whole reads and writes on a pipe; false at end of file.
bool readAll(int fd, void* p, size_t n) {
    auto* b = static_cast<char*>(p);
    while (n) {
        const ssize_t k = ::read(fd, b, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        b += k;
        n -= size_t(k);
    }
    return true;
}
void writeAll(int fd, const void* p, size_t n) {
    const auto* b = static_cast<const char*>(p);
    while (n) {
        const ssize_t k = ::write(fd, b, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) throw std::runtime_error("image codec child: the pipe closed");
        b += k;
        n -= size_t(k);
    }
}

struct Channel {
    int in, out;
    void put(const void* p, size_t n) { writeAll(out, p, n); }
    template <class T> void put(T v) { put(&v, sizeof v); }
    void putString(const std::string& s) { put<uint64_t>(s.size()); put(s.data(), s.size()); }
    void putImage(const Image& im) {
        put<int32_t>(im.width); put<int32_t>(im.height); put<int32_t>(im.channels);
        put(im.pixels.data(), im.pixels.size() * sizeof(float));
    }
    void get(void* p, size_t n) {
        if (!readAll(in, p, n)) throw std::runtime_error("image codec child: the pipe closed");
    }
    template <class T> T get() { T v; get(&v, sizeof v); return v; }
    std::string getString() {
        std::string s(get<uint64_t>(), '\0');
        get(s.data(), s.size());
        return s;
    }
    Image getImage() {
        const int w = get<int32_t>(), h = get<int32_t>(), c = get<int32_t>();
        Image im(w, h, c);
        get(im.pixels.data(), im.pixels.size() * sizeof(float));
        return im;
    }
};

size_t sampleBytes(SampleType t) { return t == SampleType::U8 ? 1 : t == SampleType::Half ? 2 : 4; }

// The parent's end: the child is started on first use and lives until the program exits.
std::mutex childMutex;
Channel* child = nullptr;

Channel& startChild() {
    if (child) return *child;
    char exe[4096];
    const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);  // valgrind: the client's
    if (n <= 0) throw std::runtime_error("image codec child: cannot find this program");
    exe[n] = '\0';
    int toChild[2], fromChild[2];
    if (::pipe2(toChild, O_CLOEXEC) || ::pipe2(fromChild, O_CLOEXEC))
        throw std::runtime_error("image codec child: pipe failed");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, toChild[0], 0);
    posix_spawn_file_actions_adddup2(&fa, fromChild[1], 1);
    char arg1[] = "codec-server";
    char* argv[] = {exe, arg1, nullptr};
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, exe, &fa, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    ::close(toChild[0]);
    ::close(fromChild[1]);
    if (rc) throw std::runtime_error(std::string("image codec child: cannot start: ") + std::strerror(rc));
    child = new Channel{fromChild[0], toChild[1]};  // lives until exit; the child sees EOF then
    return *child;
}

// Sends a request (written by `send`) and reads the status; throws the child's message.
template <class Send> Channel& call(Send send) {
    Channel& c = startChild();
    send(c);
    if (c.get<uint8_t>() != 0) throw std::runtime_error(c.getString());
    return c;
}

void childWrite(const std::string& path, int w, int h, int ch, const void* data, SampleType dt,
                SampleType ft, Compression comp, bool bottomUp) {
    std::lock_guard<std::mutex> lock(childMutex);
    call([&](Channel& c) {
        c.put(OpWrite); c.putString(path);
        c.put<int32_t>(w); c.put<int32_t>(h); c.put<int32_t>(ch);
        c.put(dt); c.put(ft); c.put(comp); c.put<uint8_t>(bottomUp);
        c.put(data, size_t(w) * h * ch * sampleBytes(dt));
    });
}
Image childRead(const std::string& path, bool bottomUp) {
    std::lock_guard<std::mutex> lock(childMutex);
    return call([&](Channel& c) { c.put(OpRead); c.putString(path); c.put<uint8_t>(bottomUp); })
        .getImage();
}
ImageFigures childCompare(const Image& a, const Image& b) {
    std::lock_guard<std::mutex> lock(childMutex);
    Channel& c = call([&](Channel& c) { c.put(OpCompare); c.putImage(a); c.putImage(b); });
    return c.get<ImageFigures>();
}
void childSheet(const std::string& path, const std::vector<std::string>& images,
                const std::vector<std::string>& labels, int columns) {
    std::lock_guard<std::mutex> lock(childMutex);
    call([&](Channel& c) {
        c.put(OpSheet); c.putString(path); c.put<int32_t>(columns);
        c.put<uint64_t>(images.size());
        for (const auto& s : images) c.putString(s);
        c.put<uint64_t>(labels.size());
        for (const auto& s : labels) c.putString(s);
    });
}
const char* childVersion() {
    static std::string v = [] {
        std::lock_guard<std::mutex> lock(childMutex);
        return call([](Channel& c) { c.put(OpVersion); }).getString();
    }();
    return v.c_str();
}

}  // namespace

bool codecInChild() {
    const char* v = std::getenv("SHADOWLAB_CODEC");
    return v && std::string(v) == "child";
}

const ImageCodec& childCodec() {
    static const ImageCodec table{childWrite, childRead, childCompare, childSheet, childVersion};
    return table;
}

int serveCodec(int in, int out, const ImageCodec& codec) {
    Channel c{in, out};
    uint8_t op = 0;
    while (readAll(in, &op, 1)) {
        try {
            switch (op) {
            case OpWrite: {
                const std::string path = c.getString();
                const int w = c.get<int32_t>(), h = c.get<int32_t>(), ch = c.get<int32_t>();
                const auto dt = c.get<SampleType>(), ft = c.get<SampleType>();
                const auto comp = c.get<Compression>();
                const bool bottomUp = c.get<uint8_t>();
                std::vector<char> data(size_t(w) * h * ch * sampleBytes(dt));
                c.get(data.data(), data.size());
                codec.write(path, w, h, ch, data.data(), dt, ft, comp, bottomUp);
                c.put<uint8_t>(0);
                break;
            }
            case OpRead: {
                const std::string path = c.getString();
                const bool bottomUp = c.get<uint8_t>();
                Image im = codec.read(path, bottomUp);
                c.put<uint8_t>(0);
                c.putImage(im);
                break;
            }
            case OpCompare: {
                const Image a = c.getImage(), b = c.getImage();
                const ImageFigures f = codec.compare(a, b);
                c.put<uint8_t>(0);
                c.put(f);
                break;
            }
            case OpSheet: {
                const std::string path = c.getString();
                const int columns = c.get<int32_t>();
                std::vector<std::string> images(c.get<uint64_t>());
                for (auto& s : images) s = c.getString();
                std::vector<std::string> labels(c.get<uint64_t>());
                for (auto& s : labels) s = c.getString();
                codec.contactSheet(path, images, labels, columns);
                c.put<uint8_t>(0);
                break;
            }
            case OpVersion:
                c.put<uint8_t>(0);
                c.putString(codec.version());
                break;
            default:
                return 2;  // out of step: the parent's next read fails
            }
        } catch (const std::exception& e) {
            // A request's arguments are read before the work starts, so the stream stays in step.
            c.put<uint8_t>(1);
            c.putString(e.what());
        }
    }
    return 0;
}

}  // namespace sl
