// PNG encoding and decoding with libpng's simplified API (libpng >= 1.6), which reports
// errors through png_image::message instead of longjmp, so no setjmp is needed in C++.

#include "render.h"

#include <png.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace tspline::render {
namespace {

png_image rgb_image(const Image& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  return png;
}

void check_image(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != 3 * std::size_t(image.width) * std::size_t(image.height))
    throw std::invalid_argument("PNG: the image is empty or its pixel array has the wrong size");
}

} // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  check_image(image);
  png_image png = rgb_image(image);
  const png_int_32 stride = 3 * image.width;
  png_alloc_size_t size = 0;
  // First call: size only. The simplified writer stores no time stamp or other varying data.
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.pixels.data(), stride, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  std::vector<std::uint8_t> bytes(size);
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), stride,
                                 nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  bytes.resize(size);
  return bytes;
}

void write_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw std::runtime_error("cannot write '" + path + "'");
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
    throw std::runtime_error("writing '" + path + "' failed");
}

Image read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open '" + path + "'");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()))
    throw std::runtime_error("'" + path + "' is not a readable PNG: " + png.message);
  png.format = PNG_FORMAT_RGB; // converts grey, palette and alpha (composited on black)
  if (png.width == 0 || png.height == 0 || png.width > 65536 || png.height > 65536) {
    png_image_free(&png);
    throw std::runtime_error("'" + path + "': unsupported PNG size");
  }
  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 3 * image.width, nullptr))
    throw std::runtime_error("'" + path + "': PNG decoding failed: " + png.message);
  return image;
}

} // namespace tspline::render
