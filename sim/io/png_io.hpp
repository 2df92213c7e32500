// PNG through libpng's simplified API: 8-bit RGB, 8-bit indexed or 16-bit grey.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace girtd {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, 3 bytes per pixel
};

// Throws InputError(path, 0, ...) when the file cannot be written or read.
void write_png_rgb(const std::string& path, const RgbImage& img);
// The same PNG as bytes (for pages that inline their pictures); `fast`:
// libpng's fast compression (larger, several times quicker: heat maps).
std::string png_rgb_bytes(const RgbImage& img, bool fast = false);
// One byte per pixel through a 256-colour palette (3 bytes each), fast
// compression: a heat map of levels in a third of the RGB map's bytes.
std::string png_indexed_bytes(int width, int height, const std::vector<uint8_t>& indices,
                              const std::array<uint8_t, 3 * 256>& palette);
void write_png_gray16(const std::string& path, int width, int height, const std::vector<uint16_t>& values);
RgbImage read_png_rgb(const std::string& path);
// A file write_png_gray16 wrote (z.png), value for value.
std::vector<uint16_t> read_png_gray16(const std::string& path, int& width, int& height);

}  // namespace girtd
