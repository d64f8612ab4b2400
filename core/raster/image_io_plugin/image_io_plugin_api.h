/* The C interface of libterrashade_image_io, the one place OpenImageIO is linked. The module is
 * dlopen'ed by float_image_io.cpp on the first EXR/HDR read or write, so the ~260 shared
 * libraries behind OIIO cost start-up time only to the commands that use them.
 * Plain C types and a version number: the loader checks the version before trusting the symbols. */
#ifndef TS_IMAGE_IO_PLUGIN_API_H
#define TS_IMAGE_IO_PLUGIN_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TS_IMAGE_IO_PLUGIN_ABI 2

/* The ABI version the module was built for (TS_IMAGE_IO_PLUGIN_ABI). */
int ts_image_io_abi_version(void);

/* Reads the first subimage of `path`, every channel, as interleaved floats, top row first
 * (integer samples scaled as OpenImageIO scales them: 0..1 for unsigned ones). On success
 * *pixels is a malloc'ed block of width*height*channels floats (release with ts_image_io_free)
 * and 0 is returned; on failure a nonzero value and a one-line message in error
 * (NUL-terminated, truncated to error_size). */
int ts_image_io_read_float(const char* path, int* width, int* height, int* channels, float** pixels, char* error,
                           size_t error_size);

void ts_image_io_free(float* pixels);

/* Writes width x height pixels of `channels` (1..4) interleaved floats, top row first, as an
 * OpenEXR file (zip compression; half floats if half_float != 0, else 32-bit). 0 on success. */
int ts_image_io_write_exr(const char* path, int width, int height, int channels, const float* data, int half_float,
                          char* error, size_t error_size);

#ifdef __cplusplus
}
#endif

#endif
