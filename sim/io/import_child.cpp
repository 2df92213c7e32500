#include "io/import_child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <filesystem>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <new>
#include <stdexcept>

#include "common/input_error.hpp"
#include "io/progress_line.hpp"

// ASan reserves terabytes of address space: no limit on it there.
#if defined(__SANITIZE_ADDRESS__)
#define GIRTD_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GIRTD_ASAN 1
#endif
#endif

namespace girtd {

namespace {

// The answer's bytes: a tag, then fixed-width numbers and length-prefixed
// strings (both ends are this executable: no byte order to agree on).
class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_arithmetic_v<T>, "numbers only: they are sent as their bytes");
    out_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put_text(const std::string& s) {
    put(uint64_t(s.size()));
    out_ += s;
  }
  // A count, then the items' bytes in one piece (the mesh's arrays).
  template <class T>
  void put_array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>, "sent as their bytes");
    put(uint64_t(v.size()));
    if (!v.empty()) out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void reserve(size_t bytes) { out_.reserve(bytes); }
  const std::string& bytes() const { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  template <class T>
  T get() {
    static_assert(std::is_arithmetic_v<T>, "numbers only: they are sent as their bytes");
    T v;
    need(sizeof v);
    std::memcpy(&v, in_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  // A count of items of at least `item_bytes` each: no more than the bytes left hold.
  uint64_t get_count(uint64_t item_bytes) {
    const uint64_t n = get<uint64_t>();
    if (n > (in_.size() - at_) / item_bytes) throw std::runtime_error("the importer's answer is cut short");
    return n;
  }
  bool at_end() const { return at_ == in_.size(); }
  template <class T>
  void get_array(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>, "sent as their bytes");
    v.resize(get_count(sizeof(T)));
    if (v.empty()) return;  // no data() to copy to
    std::memcpy(v.data(), in_.data() + at_, v.size() * sizeof(T));
    at_ += v.size() * sizeof(T);
  }
  std::string get_text() {
    const uint64_t n = get<uint64_t>();
    need(n);
    std::string s = in_.substr(at_, n);
    at_ += n;
    return s;
  }

 private:
  void need(uint64_t n) const {
    if (n > in_.size() - at_) throw std::runtime_error("the importer's answer is cut short");
  }
  const std::string& in_;
  size_t at_ = 0;
};

constexpr char kModelTag = 'M', kErrorTag = 'E';

// The import's progress in thousandths, in a page the parent and the child
// share (set in the child only).
using SharedProgress = std::atomic<uint32_t>;
static_assert(SharedProgress::is_always_lock_free, "shared between processes");
SharedProgress* child_progress = nullptr;

// offset: a byte in a binary file, or -1.
std::string error_answer(int64_t line, int64_t offset, const std::string& what) {
  Writer w;
  w.put(kErrorTag);
  w.put(line);
  w.put(offset);
  w.put_text(what);
  return w.bytes();
}

void put_vec(Writer& w, const Vec3& v) {
  w.put(v.x);
  w.put(v.y);
  w.put(v.z);
}
Vec3 get_vec(Reader& r) {
  Vec3 v;
  v.x = r.get<double>();
  v.y = r.get<double>();
  v.z = r.get<double>();
  return v;
}

void put_model(Writer& w, const ImportedModel& model) {
  const Mesh& mesh = model.mesh;
  w.reserve(mesh.positions.size() * sizeof(Vec3) + mesh.corners.size() * (sizeof(int) + sizeof(CornerColour)) +
            mesh.first.size() * sizeof(uint64_t) + mesh.material.size() * sizeof(int) + (1 << 16));
  w.put(uint64_t(mesh.positions.size()));  // GLM's vector is not trivially copyable: point by point
  for (const Vec3& p : mesh.positions) put_vec(w, p);
  w.put_array(mesh.corners);
  w.put_array(mesh.first);
  w.put_array(mesh.material);
  w.put_array(mesh.corner_colour);
  w.put(uint64_t(model.materials.size()));
  for (const std::optional<Surface>& s : model.materials) {
    w.put(char(s.has_value()));
    if (!s) continue;
    for (double v : {s->r, s->g, s->b, s->n, s->t_min, s->t_max}) w.put(v);
    for (double c : s->cre) w.put(c);
  }
  w.put(uint64_t(model.cameras.size()));
  for (const ModelCamera& c : model.cameras) {
    w.put_text(c.name);
    for (const Vec3& v : {c.eye, c.forward, c.up}) put_vec(w, v);
    w.put(c.fov_deg);
    w.put(c.near);
    w.put(char(c.orthographic));
  }
  w.put(uint64_t(model.lights.size()));
  for (const ModelLight& l : model.lights) {
    w.put_text(l.name);
    w.put(int(l.kind));
    put_vec(w, l.position);
    put_vec(w, l.direction);
    w.put(l.strength);
    w.put(char(l.coloured));
  }
}

ImportedModel get_model(Reader& r) {
  ImportedModel model;
  Mesh& mesh = model.mesh;
  mesh.positions.resize(r.get_count(3 * sizeof(double)));
  for (Vec3& p : mesh.positions) p = get_vec(r);
  r.get_array(mesh.corners);
  r.get_array(mesh.first);
  r.get_array(mesh.material);
  r.get_array(mesh.corner_colour);
  model.materials.resize(r.get_count(sizeof(char)));
  for (std::optional<Surface>& s : model.materials) {
    if (!r.get<char>()) continue;
    s.emplace();
    for (double* v : {&s->r, &s->g, &s->b, &s->n, &s->t_min, &s->t_max}) *v = r.get<double>();
    for (double& c : s->cre) c = r.get<double>();
  }
  // At least a name's length, 11 numbers and a flag each.
  model.cameras.resize(r.get_count(sizeof(uint64_t) + 11 * sizeof(double) + 1));
  for (ModelCamera& c : model.cameras) {
    c.name = r.get_text();
    for (Vec3* v : {&c.eye, &c.forward, &c.up}) *v = get_vec(r);
    c.fov_deg = r.get<double>();
    c.near = r.get<double>();
    c.orthographic = r.get<char>();
  }
  // At least a name's length, the kind, 7 numbers and a flag each.
  model.lights.resize(r.get_count(sizeof(uint64_t) + sizeof(int) + 7 * sizeof(double) + 1));
  for (ModelLight& l : model.lights) {
    l.name = r.get_text();
    const int kind = r.get<int>();
    if (kind < 0 || kind > int(ModelLightKind::kOther)) throw std::runtime_error("the importer's answer is garbled");
    l.kind = ModelLightKind(kind);
    l.position = get_vec(r);
    l.direction = get_vec(r);
    l.strength = r.get<double>();
    l.coloured = r.get<char>();
  }
  // What the scene reader indexes with must index within the answer.
  const auto garbled = [] { throw std::runtime_error("the importer's answer is garbled"); };
  if (mesh.first.empty() || mesh.first.front() != 0 || mesh.first.back() != mesh.corners.size()) garbled();
  for (size_t i = 0; i + 1 < mesh.first.size(); ++i)
    if (mesh.first[i + 1] < mesh.first[i] || mesh.first[i + 1] - mesh.first[i] < 3) garbled();  // out of order, or under 3 corners
  for (int i : mesh.corners)
    if (i < 0 || size_t(i) >= mesh.positions.size()) garbled();
  for (int m : mesh.material)
    if (m < 0 || size_t(m) >= model.materials.size()) garbled();
  if (!mesh.material.empty() && mesh.material.size() != mesh.polygon_count()) garbled();
  if (!mesh.corner_colour.empty() && mesh.corner_colour.size() != mesh.corners.size()) garbled();
  return model;
}

std::string answer(const ImportLimits& limits, const std::function<ImportedModel(std::vector<std::string>&)>& import) {
  Writer w;
  try {
    std::vector<std::string> warnings;
    const ImportedModel model = import(warnings);
    w.put(kModelTag);
    put_model(w, model);
    w.put(uint64_t(warnings.size()));
    for (const std::string& s : warnings) w.put_text(s);
    return w.bytes();
  } catch (const InputError& e) {
    return error_answer(e.line(), e.offset() ? int64_t(*e.offset()) : -1, e.what());
  } catch (const std::bad_alloc&) {
    return error_answer(0, -1, out_of_memory_message(limits));
  } catch (const std::exception& e) {
    return error_answer(0, -1, std::string("cannot read the model: the importer failed: ") + e.what());
  }
}

bool write_all(int fd, const std::string& s) {
  for (size_t at = 0; at < s.size();) {
    const ssize_t n = ::write(fd, s.data() + at, s.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += size_t(n);
  }
  return true;
}

// The address space this process holds now (the parent's, inherited).
uint64_t address_space_bytes() {
  uint64_t pages = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * uint64_t(sysconf(_SC_PAGESIZE));
}

[[noreturn]] void run_child(int fd, pid_t parent, const ImportLimits& limits,
                            const std::function<ImportedModel(std::vector<std::string>&)>& import) {
  // Never outlive the parent, nor the limit (a file that names a FIFO blocks
  // in the importer: the parent's deadline cannot reach a child it left).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(1);
  alarm(unsigned(limits.seconds) + 5);
  // Only the answer's pipe stays open: another thread's import must see its
  // own pipe close when its child ends, not wait for this one.
  if (fd != 3) {
    dup2(fd, 3);
    fd = 3;
  }
  close_range(4, ~0U, 0);
#if !defined(GIRTD_ASAN)
  // The limit is on what the import adds to what the child inherited.
  const uint64_t want = address_space_bytes() + limits.memory_bytes;
  rlimit as{};
  getrlimit(RLIMIT_AS, &as);
  as.rlim_cur = as.rlim_max == RLIM_INFINITY ? want : std::min<uint64_t>(want, as.rlim_max);
  setrlimit(RLIMIT_AS, &as);
#endif
  signal(SIGINT, SIG_DFL);  // a stop of the render stops the import too
  signal(SIGPIPE, SIG_DFL);  // a parent gone: end here
  // Some importers print (OpenGEX's parser on stdout): the answer is the pipe's.
  if (const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC); null >= 0) {
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  const bool sent = write_all(fd, answer(limits, import));
  ::close(fd);
  _exit(sent ? 0 : 1);
}

[[noreturn]] void refuse(const std::string& path, const std::string& what) {
  throw InputError(path, 0, "cannot read the model: the importer " + what);
}

}  // namespace

void report_import_progress(double share) {
  if (child_progress) child_progress->store(uint32_t(std::clamp(share, 0.0, 1.0) * 1000), std::memory_order_relaxed);
}

std::string out_of_memory_message(const ImportLimits& limits) {
  return "cannot read the model: the importer ran out of memory (its limit: " +
         std::to_string(limits.memory_bytes >> 20) + " MiB more than the process held)";
}

ImportedModel import_in_child(const std::string& path, const ImportLimits& limits,
                              const std::function<ImportedModel(std::vector<std::string>& warnings)>& import,
                              std::vector<std::string>& warnings) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) refuse(path, std::string("could not start: no pipe (") + strerror(errno) + ")");
  void* page = mmap(nullptr, sizeof(SharedProgress), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  SharedProgress* progress = page == MAP_FAILED ? nullptr : new (page) SharedProgress(0);
  struct Unmap {
    void* page;
    ~Unmap() {
      if (page != MAP_FAILED) munmap(page, sizeof(SharedProgress));
    }
  } unmap{page};
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    refuse(path, std::string("could not start: no process (") + strerror(err) + ")");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_progress = progress;
    run_child(fds[1], parent, limits, import);
  }
  const std::string step = "reading " + std::filesystem::path(path).filename().string();
  ::close(fds[1]);
  // Read until the child closes its end, or until the time is up.
  std::string bytes;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  bool timed_out = false;
  std::vector<char> chunk(1 << 20);
  char* buf = chunk.data();
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    if (progress) ProgressLine::get().step(step, progress->load(std::memory_order_relaxed), 1000, "");
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, int(std::min<int64_t>(left.count(), 200)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buf, chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child closed its end
    bytes.append(buf, size_t(n));
  }
  ::close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  pid_t waited;
  while ((waited = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  // Not seen (SIGCHLD ignored by the host: the child reaped itself): only a
  // whole answer, parsed below, counts.
  if (waited != pid) status = 0;
  if (timed_out)
    refuse(path, "took longer than its limit of " + std::to_string(int(limits.seconds)) + " s (stopped)");
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const bool stopped = sig == SIGINT || sig == SIGTERM || sig == SIGHUP;
    refuse(path, std::string(stopped ? "was stopped (signal " : "crashed (signal ") + std::to_string(sig) + ", " +
                     strsignal(sig) + ")");
  }
  // Exit 0 once the whole answer is written: anything else is cut short.
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
    refuse(path, "ended without a whole answer (exit " + std::to_string(WEXITSTATUS(status)) + ")");
  ImportedModel model;
  std::vector<std::string> said;
  try {
    Reader r(bytes);
    const char tag = r.get<char>();
    if (tag == kErrorTag) {
      const int64_t line = r.get<int64_t>(), offset = r.get<int64_t>();
      const std::string what = r.get_text();
      if (offset >= 0) throw InputError::at_byte(path, uint64_t(offset), what);
      throw InputError(path, int(line), what);
    }
    if (tag != kModelTag) throw std::runtime_error("the importer's answer is garbled");
    model = get_model(r);
    const uint64_t count = r.get_count(sizeof(uint64_t));
    for (uint64_t i = 0; i < count; ++i) said.push_back(r.get_text());
    if (!r.at_end()) throw std::runtime_error("the importer's answer is garbled");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    refuse(path, "ended without a whole answer");
  }
  warnings.insert(warnings.end(), said.begin(), said.end());
  return model;
}

}  // namespace girtd
