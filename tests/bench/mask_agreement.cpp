// The fraction of pixels where two renders agree on surface versus
// background: prints "agreement 0.99871 (159794 of 160000 pixels)". An
// image with alpha (hsb's with a transparent background) is background
// where its coverage is below one half; one without, where it is pure
// magenta (the benchmark sets it so). Coverage is the measure where a
// renderer filters: a background pixel beside a yellow tube takes 3 % of
// its neighbour's colour through hsb's pixel filter, which the sRGB curve
// makes 16 % of green, no longer magenta by the colour test, though nine
// tenths of it is background.

#include <OpenImageIO/imagebuf.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mask_agreement A.png B.png\n");
    return 2;
  }
  OIIO::ImageBuf a(argv[1]), b(argv[2]);
  if (!a.read() || !b.read() || a.spec().width != b.spec().width || a.spec().height != b.spec().height) {
    std::fprintf(stderr, "mask_agreement: cannot read both images at one size\n");
    return 2;
  }
  auto background = [](const OIIO::ImageBuf& image, int x, int y) {
    float p[4] = {0, 0, 0, 0};
    image.getpixel(x, y, p, 4);
    if (image.spec().nchannels == 4) return p[3] < 0.5f;
    return p[0] > 0.85f && p[1] < 0.15f && p[2] > 0.85f;
  };
  long agree = 0, total = 0;
  for (int y = 0; y < a.spec().height; ++y)
    for (int x = 0; x < a.spec().width; ++x, ++total) agree += background(a, x, y) == background(b, x, y);
  std::printf("agreement %.5f (%ld of %ld pixels)\n", double(agree) / double(total), agree, total);
  return 0;
}
