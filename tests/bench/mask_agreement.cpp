// The fraction of pixels where two renders agree on surface versus
// background, the background being pure magenta (the benchmark sets it so in
// both renderers): prints "agreement 0.99871 (159794 of 160000 pixels)".

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
    image.getpixel(x, y, p, 3);
    return p[0] > 0.85f && p[1] < 0.15f && p[2] > 0.85f;
  };
  long agree = 0, total = 0;
  for (int y = 0; y < a.spec().height; ++y)
    for (int x = 0; x < a.spec().width; ++x, ++total) agree += background(a, x, y) == background(b, x, y);
  std::printf("agreement %.5f (%ld of %ld pixels)\n", double(agree) / double(total), agree, total);
  return 0;
}
