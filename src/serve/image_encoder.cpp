#include "serve/image_encoder.hpp"

#include "io/png_writer.hpp"

namespace epviz::serve {

ImageEncoder::ImageEncoder(ImageFormat format, int jpeg_quality)
    : format_(format), jpeg_quality_(jpeg_quality) {}

EncodedImage ImageEncoder::encode(const render::RgbaImage& image) {
  if (format_ == ImageFormat::png)
    // io's defaults (zlib level 1, no row filter) are its measured fastest.
    return {io::encode_png_rgba(image.width, image.height, image.pixels), "image/png"};
  if (!jpeg_) jpeg_.emplace();
  return {jpeg_->encode(image.width, image.height, image.pixels, jpeg_quality_), "image/jpeg"};
}

}  // namespace epviz::serve
