// The C interface of libradcl_oiio (src/image/plugin/), which radcl_image opens with dlopen
// the first time a TIFF or PNG is written or read. Each returns 1, or 0 with a message in err.
#pragma once

#include <cstddef>

extern "C" {

// Writes width x height RGB pixels, top row first: float when as_float, else 8-bit codes.
int radcl_oiio_write(const char* path, int width, int height, int as_float, const void* pixels,
                     char* err, std::size_t errlen);
// Reads an image as float RGB (a grey image's one channel repeated) into *rgb, which the
// caller frees with free().
int radcl_oiio_read(const char* path, int* width, int* height, float** rgb, char* err,
                    std::size_t errlen);
}

// The module's file name, found next to the programs (../lib/) or where it was installed.
#define RADCL_OIIO_PLUGIN_NAME "libradcl_oiio.so"
