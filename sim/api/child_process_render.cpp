// girtd::render_in_child_process: SystemC elaborates once per process, so a
// caller that renders on a timed back end more than once (the Python module)
// forks, renders in the child and reads the result back through a pipe.
// The child writes one JSON header line, then the pictures' raw bytes.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "api/girtd.hpp"

namespace girtd {
namespace {

bool write_all(int fd, const char* data, size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, data, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    data += k;
    n -= size_t(k);
  }
  return true;
}

std::string read_all(int fd) {
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const ssize_t k = ::read(fd, buf, sizeof buf);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    out.append(buf, size_t(k));
  }
  return out;
}

// Header: {"report", "width", "height", "frames", "wave_files"} or {"error": {file, line, offset, what}}.
std::string encode(const RenderResult& r) {
  nlohmann::json h = {{"report", r.report},          {"width", r.frame.width},
                      {"height", r.frame.height},    {"frames", r.per_frame.size()},
                      {"wave_files", r.wave_files}};
  std::string out = h.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  auto add = [&](const RgbImage& img) { out.append(reinterpret_cast<const char*>(img.rgb.data()), img.rgb.size()); };
  add(r.frame);
  out.append(reinterpret_cast<const char*>(r.z.data()), r.z.size() * sizeof(uint16_t));
  for (const RgbImage& f : r.per_frame) add(f);
  return out;
}

std::string encode(const InputError& e) {
  nlohmann::json err = {{"file", e.file()}, {"line", e.line()}, {"what", e.what()}};
  if (e.offset()) err["offset"] = *e.offset();
  // Replaced, not thrown on: a message may quote an input's non-UTF-8 bytes.
  return nlohmann::json{{"error", err}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

RenderResult decode(const std::string& bytes) {
  const size_t eol = bytes.find('\n');
  if (eol == std::string::npos) throw std::runtime_error("the render's child process sent no result");
  const nlohmann::json h = nlohmann::json::parse(bytes.substr(0, eol));
  if (h.contains("error")) {
    const nlohmann::json& e = h["error"];
    if (e.contains("offset")) throw InputError::at_byte(e["file"], e["offset"], e["what"]);
    throw InputError(e["file"], e["line"], e["what"]);
  }
  RenderResult r;
  r.report = h["report"];
  r.wave_files = h["wave_files"].get<std::vector<std::string>>();
  const int w = h["width"], ht = h["height"];
  const size_t pixels = size_t(w) * size_t(ht);
  size_t at = eol + 1;
  auto take = [&](size_t n) {
    if (bytes.size() - at < n) throw std::runtime_error("the render's child process sent a short result");
    const char* p = bytes.data() + at;
    at += n;
    return p;
  };
  auto image = [&] {
    RgbImage img{w, ht, std::vector<uint8_t>(pixels * 3)};
    std::memcpy(img.rgb.data(), take(pixels * 3), pixels * 3);
    return img;
  };
  r.frame = image();
  r.z.resize(pixels);
  std::memcpy(r.z.data(), take(pixels * sizeof(uint16_t)), pixels * sizeof(uint16_t));
  for (size_t i = 0; i < h["frames"].get<size_t>(); ++i) r.per_frame.push_back(image());
  return r;
}

}  // namespace

RenderResult render_in_child_process(const RenderRequest& request) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {  // the child: render, send, and leave without running the parent's exit handlers
    ::close(fds[0]);
    // Nothing may leave this block but _exit: an exception would climb back
    // into the caller (a Python interpreter) and run its script twice.
    int rc = 0;
    std::string message;
    try {
      try {
        const RenderResult r = render(request);
        message = r.problem ? encode(*r.problem) : encode(r);
      } catch (const InputError& e) {
        message = encode(e);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "girtd: %s\n", e.what());
      rc = 1;
    } catch (...) {
      rc = 1;
    }
    std::fflush(stderr);
    if (rc == 0 && !write_all(fds[1], message.data(), message.size())) rc = 1;
    ::_exit(rc);
  }
  ::close(fds[1]);
  const std::string bytes = read_all(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw std::runtime_error("the render's child process ended on signal " + std::to_string(WTERMSIG(status)) + " (" +
                             strsignal(WTERMSIG(status)) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the render's child process failed (exit " + std::to_string(WEXITSTATUS(status)) + ")");
  return decode(bytes);
}

}  // namespace girtd
