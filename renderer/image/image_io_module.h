#pragma once
// OpenImageIO's part of hsb, kept in a module of its own
// (libhsb_image_io.so beside the binary) and loaded when a raster image is
// first read or written. Debian's libOpenImageIO brings 261 libraries with
// it (GDAL, OpenVDB, OpenCV, poppler): loading them takes 0.1 s and 90 MB
// before anything else, which `hsb info`, `hsb keys`, a PDF or SVG figure
// and every child process need not pay, and which a render can pay while
// it reads its data (preload_image_io).

#include <string>
#include <vector>

#include "renderer/image/image_output.h"

namespace hsb {

// A PNG or TIFF being encoded a band of rows at a time (the module's).
struct RowEncoder;

// Every function throws std::runtime_error with OIIO's message when OIIO
// fails. Encoded images go into `memory` where the format's writer can
// write there, else into the file `file`.
struct ImageIo {
  // Encodes `image`, float samples, as an EXR (`extension` ".exr").
  void (*encode)(const ImageToWrite& image, const std::string& extension, const std::string& file,
                 std::vector<unsigned char>& memory);
  // Begins a PNG or TIFF (`extension` ".png", ".tif", ".tiff") of
  // `header`'s size, channels, bit depth, resolution and metadata (its
  // pixels are not read).
  RowEncoder* (*open_rows)(const ImageToWrite& header, const std::string& extension, const std::string& file);
  // Encodes rows [first, first + count), which follow those before:
  // `samples` are bytes (8 bits) or unsigned shorts (16), the header's
  // channels a pixel.
  void (*write_rows)(RowEncoder* encoder, int first, int count, const void* samples);
  // Ends the image, into `memory` where it was encoded there, and frees
  // the encoder.
  void (*close_rows)(RowEncoder* encoder, std::vector<unsigned char>& memory);
  // Frees an encoder without ending its image (the file is abandoned).
  void (*discard_rows)(RowEncoder* encoder);
  // The hsb:scene_sha1 a raster image at `path` holds, once it is decoded
  // whole; "" when it cannot be read or holds none.
  std::string (*stored_sha1)(const std::string& path);
};

// The module's functions, loading it (and OpenImageIO) on the first call.
// Throws std::runtime_error naming the module when it cannot be loaded,
// ResourceError when the process has no room for the threads a run starts
// (base/thread_room.h).
const ImageIo& image_io();

// Starts loading the module on a thread of its own, so that a render finds
// it loaded when it writes its image. A fork waits for the load to end: a
// child must not inherit the dynamic loader's lock half taken. Throws
// nothing: without room for threads it starts none, and image_io() says why.
void preload_image_io();

// Waits for a load preload_image_io() began, if any. A process must not
// exit() while the loader runs the libraries' constructors: exit would
// destroy their static objects (registered with exit as they were made,
// so destroyed first) under the constructors still using them, as a scene
// that failed at once did now and then (a double free in libproj's).
// hsb's main() ends with _exit instead, which destroys nothing.
void finish_image_io_preload();

// What the module's load may still add to this process's resident memory:
// 0 once it is loaded (or before it is asked for); else the share of a
// whole load's memory that its libraries' files have yet to take (the
// files paged in since it began counted as its). A render counts it
// into its estimate instead of waiting for the load, which would hold
// the render back a tenth of a second; the picture is written after it.
double image_io_pending_bytes();

// Whether the module is (or will be) loaded with RTLD_DEEPBIND, which
// takes a third off the load (image_io_module.cpp): where the process
// has no second copy of the allocator, the standard streams or libc's
// single-threaded flag.
bool image_io_binds_deep();

}  // namespace hsb

// What the module exports: its functions.
extern "C" const hsb::ImageIo* hsb_image_io_functions();
