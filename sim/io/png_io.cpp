#include "io/png_io.hpp"

#include <png.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "common/input_error.hpp"

namespace girtd {
namespace {

void write_image(const std::string& path, png_image& image, const void* data, int row_stride) {
  if (!png_image_write_to_file(&image, path.c_str(), 0, data, row_stride, nullptr))
    throw InputError(path, 0, std::string("cannot write PNG: ") + image.message);
}

// Opens `path` for reading as `format`; finish() decodes into `out`.
struct PngReader {
  png_image image;
  std::string path;
  PngReader(const std::string& p, uint32_t format) : path(p) {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str()))
      throw InputError(path, 0, std::string("cannot read PNG: ") + image.message);
    image.format = format;
  }
  void finish(void* out) {
    if (!png_image_finish_read(&image, nullptr, out, 0, nullptr)) {
      png_image_free(&image);
      throw InputError(path, 0, std::string("cannot decode PNG: ") + image.message);
    }
  }
};

// The PNG in memory, compressed once into a buffer of libpng's bound for
// the image (asking for the size first would compress it twice). Should a
// zlib exceed the bound, libpng says the size it needs: once more with that.
std::string write_to_memory(png_image& image, const void* pixels, const void* colormap) {
  std::string out(PNG_IMAGE_PNG_SIZE_MAX(image), '\0');
  for (int attempt = 0;; ++attempt) {
    png_alloc_size_t size = out.size();
    if (png_image_write_to_memory(&image, out.data(), &size, 0, pixels, 0, colormap)) {
      out.resize(size);
      return out;
    }
    if (attempt > 0 || size <= out.size())
      throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
    out.assign(size, '\0');
    image.warning_or_error = 0;
  }
}

png_image rgb_image(const RgbImage& img) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = img.width;
  image.height = img.height;
  image.format = PNG_FORMAT_RGB;
  return image;
}

}  // namespace

void write_png_rgb(const std::string& path, const RgbImage& img) {
  png_image image = rgb_image(img);
  write_image(path, image, img.rgb.data(), 0);
}

std::string png_rgb_bytes(const RgbImage& img, bool fast) {
  png_image image = rgb_image(img);
  if (fast) image.flags |= PNG_IMAGE_FLAG_FAST;
  return write_to_memory(image, img.rgb.data(), nullptr);
}

std::string png_indexed_bytes(int width, int height, const std::vector<uint8_t>& indices,
                              const std::array<uint8_t, 3 * 256>& palette) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = PNG_FORMAT_RGB_COLORMAP;
  image.colormap_entries = 256;
  image.flags |= PNG_IMAGE_FLAG_FAST;
  return write_to_memory(image, indices.data(), palette.data());
}

void write_png_gray16(const std::string& path, int width, int height, const std::vector<uint16_t>& values) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = PNG_FORMAT_LINEAR_Y;  // 16-bit grey
  write_image(path, image, values.data(), 0);
}

RgbImage read_png_rgb(const std::string& path) {
  PngReader r(path, PNG_FORMAT_RGB);
  RgbImage out;
  out.width = static_cast<int>(r.image.width);
  out.height = static_cast<int>(r.image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(r.image));
  r.finish(out.rgb.data());
  return out;
}

std::vector<uint16_t> read_png_gray16(const std::string& path, int& width, int& height) {
  PngReader r(path, PNG_FORMAT_LINEAR_Y);
  width = static_cast<int>(r.image.width);
  height = static_cast<int>(r.image.height);
  std::vector<uint16_t> out(size_t(width) * height);
  r.finish(out.data());
  return out;
}

}  // namespace girtd
