// The llvmpipe yardstick's drawing, built as a module of its own
// (libgirtd_llvmpipe.so beside girtd) that llvmpipe_render.cpp loads when a
// study draws with it: linked into girtd, OSMesa's LLVM cost every run 43 MB
// of relocated pages and a tenth of a second.
#include "accuracy/llvmpipe_render.hpp"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "girtd/design_constants.hpp"

namespace girtd {

namespace {

constexpr double kDepthUnits = (1 << kZOutBits) - 1;  // GIRTD's 16-bit Z: GL's 0..1

LlvmpipeFrame draw(const std::vector<Triangle>& triangles, int width, int height, Rgb background, uint16_t z_clear) {
  // Single threaded, as the comparison with golden asks; read when the
  // context's screen is made.
  setenv("LP_NUM_THREADS", "0", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) throw std::runtime_error("OSMesa: no context (libosmesa6)");
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  if (!OSMesaMakeCurrent(ctx, rgba.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(ctx);
    throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(width) + " x " + std::to_string(height) + " buffer");
  }
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_CULL_FACE);
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
  glClearDepth(z_clear / kDepthUnits);
  glFinish();

  // Vertex arrays, filled before the clock starts (the triangles in memory).
  std::vector<double> xyz, colour;
  xyz.reserve(triangles.size() * 9);
  colour.reserve(triangles.size() * 9);
  for (const Triangle& t : triangles)
    for (const Vertex& v : t.v) {
      // Lattice point (x, y) -> window (x + 0.5, H - y - 0.5) -> clip space.
      xyz.insert(xyz.end(), {2.0 * (v.x + 0.5) / width - 1.0, 1.0 - 2.0 * (v.y + 0.5) / height,
                             2.0 * v.z / kDepthUnits - 1.0});
      colour.insert(colour.end(), {v.r / 255.0, v.g / 255.0, v.b / 255.0});
    }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_DOUBLE, 0, xyz.data());
  glColorPointer(3, GL_DOUBLE, 0, colour.data());

  // Once untimed, so that the time is drawing, not llvmpipe compiling its
  // shader variants for this state; the timed pass clears and draws again.
  auto clear_and_draw = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles.size()));
    glFinish();
  };
  clear_and_draw();
  const auto t0 = std::chrono::steady_clock::now();
  clear_and_draw();
  const auto t1 = std::chrono::steady_clock::now();

  std::vector<uint32_t> depth(size_t(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
  LlvmpipeFrame f;
  f.draw_s = std::chrono::duration<double>(t1 - t0).count();
  f.rgb.width = width;
  f.rgb.height = height;
  f.rgb.rgb.resize(size_t(width) * height * 3);
  f.z.resize(size_t(width) * height);
  for (int row = 0; row < height; ++row) {
    const int y = height - 1 - row;  // GL's rows run bottom up
    for (int x = 0; x < width; ++x) {
      const size_t gl = size_t(row) * width + x, out = size_t(y) * width + x;
      for (int c = 0; c < 3; ++c) f.rgb.rgb[3 * out + c] = rgba[4 * gl + c];
      f.z[out] = static_cast<uint16_t>(std::lround(depth[gl] / 4294967295.0 * kDepthUnits));
    }
  }
  OSMesaDestroyContext(ctx);
  return f;
}

}  // namespace

}  // namespace girtd

// The module's one entry (llvmpipe_render.hpp's LlvmpipeEntry): what draw()
// threw comes back as `error`, never as an exception across the boundary.
extern "C" void girtd_llvmpipe_draw(const std::vector<girtd::Triangle>& triangles, int width, int height,
                                    girtd::Rgb background, uint16_t z_clear, girtd::LlvmpipeFrame& out,
                                    std::string& error) {
  try {
    out = girtd::draw(triangles, width, height, background, z_clear);
  } catch (const std::exception& e) {
    error = e.what();
  }
}
