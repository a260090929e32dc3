// PNG through libpng's simplified API (png_image_*): it reports errors through the struct's
// message instead of longjmp, so no setjmp juggling is needed around C++ objects.
#include <gsp/render/image.hpp>

#include <gsp/errors.hpp>
#include <gsp/io/atomic_file.hpp>

#include <png.h>

#include <cstring>
#include <string>

namespace gsp::render {

void write_png(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
    throw InvalidInput(path + ": cannot write an empty or inconsistent image (" + std::to_string(image.width) +
                       "x" + std::to_string(image.height) + ")");
  io::AtomicFile file(path);
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGBA;
  const int ok = png_image_write_to_stdio(&png, file.handle(), 0, image.rgba.data(), 0, nullptr);
  const std::string message = png.message;
  png_image_free(&png);
  if (!ok) throw IoError(path, "", "PNG encoding failed: " + message);
  file.commit();
}

Image read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    const std::string message = png.message;
    png_image_free(&png);
    throw IoError(path, "", "not a readable PNG: " + message);
  }
  png.format = PNG_FORMAT_RGBA;
  if (png.width == 0 || png.height == 0 || png.width > 65536 || png.height > 65536) {
    png_image_free(&png);
    throw IoError(path, "", "unsupported PNG size");
  }
  Image image(int(png.width), int(png.height));
  if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw IoError(path, "", "PNG decoding failed: " + message);
  }
  return image;
}

}  // namespace gsp::render
