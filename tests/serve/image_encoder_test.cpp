// JPEG and PNG encoding of rendered frames: a JPEG decodes back to the
// picture (within JPEG's error), bad input is refused, PNG is PNG.
#include <gtest/gtest.h>

#include <cstdlib>

#include "serve/image_encoder.hpp"
#include "serve/jpeg_encoder.hpp"
#include "serve_test_support.hpp"

namespace epviz::serve {
namespace {

render::RgbaImage two_halves(int width, int height) {
  render::RgbaImage image;
  image.width = width;
  image.height = height;
  image.pixels.resize(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = image.offset(x, y);
      const bool left = x < width / 2;
      image.pixels[i] = left ? 220 : 20;
      image.pixels[i + 1] = left ? 40 : 160;
      image.pixels[i + 2] = left ? 60 : 240;
      image.pixels[i + 3] = 255;
    }
  return image;
}

void expect_near(glm::u8vec4 got, glm::u8vec4 want, int tolerance) {
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(std::abs(int(got[c]) - int(want[c])), tolerance) << "channel " << c;
}

TEST(ServeJpeg, DecodesBackToThePicture) {
  const render::RgbaImage image = two_halves(96, 64);
  JpegEncoder encoder;
  const auto jpeg = encoder.encode(image.width, image.height, image.pixels, 90);
  ASSERT_GT(jpeg.size(), 2u);
  EXPECT_EQ(jpeg[0], 0xff);
  EXPECT_EQ(jpeg[1], 0xd8);
  const render::RgbaImage back = testing::decode_jpeg(jpeg);
  ASSERT_EQ(back.width, 96);
  ASSERT_EQ(back.height, 64);
  // Away from the edge between the halves, where 4:2:0 smears colour.
  expect_near(back.at(10, 30), image.at(10, 30), 6);
  expect_near(back.at(85, 30), image.at(85, 30), 6);
}

TEST(ServeJpeg, EncoderIsReusableAcrossSizes) {
  JpegEncoder encoder;
  for (int size : {32, 200, 16, 500}) {
    const render::RgbaImage image = two_halves(size, size / 2 + 1);
    const auto back =
        testing::decode_jpeg(encoder.encode(image.width, image.height, image.pixels, 80));
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
  }
}

TEST(ServeJpeg, RefusesBadInput) {
  JpegEncoder encoder;
  std::vector<std::uint8_t> pixels(16 * 16 * 4);
  EXPECT_THROW(encoder.encode(16, 15, pixels, 80), std::invalid_argument);
  EXPECT_THROW(encoder.encode(0, 16, pixels, 80), std::invalid_argument);
  EXPECT_THROW(encoder.encode(16, 16, pixels, 0), std::invalid_argument);
  EXPECT_THROW(encoder.encode(16, 16, pixels, 101), std::invalid_argument);
  EXPECT_NO_THROW(encoder.encode(16, 16, pixels, 100));
}

TEST(ServeImageEncoder, EncodesTheConfiguredFormat) {
  const render::RgbaImage image = two_halves(40, 20);
  ImageEncoder jpeg(ImageFormat::jpeg, 85);
  const EncodedImage j = jpeg.encode(image);
  EXPECT_STREQ(j.mime, "image/jpeg");
  EXPECT_EQ(testing::decode_jpeg(j.bytes).width, 40);

  ImageEncoder png(ImageFormat::png, 85);
  const EncodedImage p = png.encode(image);
  EXPECT_STREQ(p.mime, "image/png");
  const std::vector<std::uint8_t> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  ASSERT_GE(p.bytes.size(), signature.size());
  EXPECT_TRUE(std::equal(signature.begin(), signature.end(), p.bytes.begin()));
}

}  // namespace
}  // namespace epviz::serve
