#pragma once
// The PNG encoder (stb_image_write with zlib's deflate); see stb_png_zlib.cpp.
// The two settings are process-wide, like stb's own: png_writer.cpp guards them.
#include <cstdint>

namespace epviz::io::detail {

int& png_compression_level();  // zlib level 0..9
int& png_force_filter();       // PNG row filter 0..4, or -1 to try all per row

int png_to_func(void (*write)(void* context, void* data, int size), void* context, int width,
                int height, const std::uint8_t* rgba, int stride_bytes);

}  // namespace epviz::io::detail
