// Unit tests for sim/io/png_io.hpp: RGB round trip, missing files, 16-bit grey.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "io/png_io.hpp"

namespace girtd {
namespace {

namespace fs = std::filesystem;

struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& name)
      : path(fs::temp_directory_path() / ("girtd_unit_" + std::to_string(::getpid()) + "_" + name)) {
    std::error_code ec;
    fs::remove(path, ec);
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
  std::string str() const { return path.string(); }
};

std::vector<uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

uint32_t be32(const std::vector<uint8_t>& b, size_t at) {
  return (uint32_t{b[at]} << 24) | (uint32_t{b[at + 1]} << 16) | (uint32_t{b[at + 2]} << 8) | b[at + 3];
}

}  // namespace

TEST_CASE("PNG RGB image round-trips byte for byte", "[png]") {
  TempFile tmp("pattern.png");
  // 7 x 5, not a multiple of anything, every channel different.
  RgbImage img;
  img.width = 7;
  img.height = 5;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      img.rgb.push_back(static_cast<uint8_t>(x * 37 + y * 11));
      img.rgb.push_back(static_cast<uint8_t>(255 - x * 30));
      img.rgb.push_back(static_cast<uint8_t>((x ^ y) * 50 + 3));
    }
  REQUIRE(img.rgb.size() == 7u * 5u * 3u);
  // Corner values as written: (0,0) = (0, 255, 3); (6,4) = (6*37+44 = 266 & 255 = 10, 75, (6^4)=2 -> 103).
  CHECK(img.rgb[0] == 0);
  CHECK(img.rgb[1] == 255);
  CHECK(img.rgb[2] == 3);
  write_png_rgb(tmp.str(), img);
  REQUIRE(fs::exists(tmp.path));
  const RgbImage back = read_png_rgb(tmp.str());
  CHECK(back.width == 7);
  CHECK(back.height == 5);
  CHECK(back.rgb == img.rgb);
  const size_t last = (4 * 7 + 6) * 3;
  CHECK(back.rgb[last] == 10);
  CHECK(back.rgb[last + 1] == 75);
  CHECK(back.rgb[last + 2] == 103);
}

TEST_CASE("PNG reading a missing file throws InputError naming the path", "[png]") {
  const std::string path = (fs::temp_directory_path() / "girtd_unit_no_such_file_4f1c.png").string();
  try {
    read_png_rgb(path);
    FAIL("reading a missing PNG did not throw");
  } catch (const InputError& e) {
    CHECK(e.file() == path);
  }
}

TEST_CASE("PNG reading a file that is not a PNG throws InputError", "[png]") {
  TempFile tmp("not_a_png.png");
  {
    std::ofstream out(tmp.str());
    out << "girtd-trace 1 triangle\n";
  }
  CHECK_THROWS_AS(read_png_rgb(tmp.str()), InputError);
}

TEST_CASE("PNG writing into a missing directory throws InputError", "[png]") {
  RgbImage img;
  img.width = 1;
  img.height = 1;
  img.rgb = {1, 2, 3};
  const std::string path = (fs::temp_directory_path() / "girtd_unit_no_such_dir_4f1c" / "x.png").string();
  CHECK_THROWS_AS(write_png_rgb(path, img), InputError);
}

TEST_CASE("PNG gray16 writes a 16-bit greyscale file", "[png]") {
  TempFile tmp("depth.png");
  const std::vector<uint16_t> z = {0, 1, 256, 65535, 1000, 2000, 3000, 4000, 65534, 12345, 54321, 7};  // 4 x 3
  write_png_gray16(tmp.str(), 4, 3, z);
  REQUIRE(fs::exists(tmp.path));
  const std::vector<uint8_t> b = file_bytes(tmp.str());
  // PNG layout: 8-byte signature, then IHDR: length(4) "IHDR"(4) width(4)
  // height(4) bit depth(1) colour type(1) ... -> width at 16, height at 20,
  // bit depth at 24 (16), colour type at 25 (0 = greyscale).
  REQUIRE(b.size() > 33);
  const std::vector<uint8_t> sig = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  CHECK(std::vector<uint8_t>(b.begin(), b.begin() + 8) == sig);
  CHECK(std::string(b.begin() + 12, b.begin() + 16) == "IHDR");
  CHECK(be32(b, 16) == 4);
  CHECK(be32(b, 20) == 3);
  CHECK(b[24] == 16);
  CHECK(b[25] == 0);
  // It reads back as a 4 x 3 picture.
  const RgbImage back = read_png_rgb(tmp.str());
  CHECK(back.width == 4);
  CHECK(back.height == 3);
  // And as 16-bit values, each as written (the accuracy command reads z.png).
  int w = 0, h = 0;
  CHECK(read_png_gray16(tmp.str(), w, h) == z);
  CHECK((w == 4 && h == 3));
}

}  // namespace girtd
