#pragma once
// Reading a PNG back in tests (any suite): the width and height from the file's IHDR chunk, parsed by hand
// (independent of VTK, which wrote it), and the pixels through VTK's PNG reader, to count colours.
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>

namespace png_test {

struct PngImage {
  bool valid = false;      // PNG signature and an IHDR chunk first
  int width = 0, height = 0;
  std::map<std::array<int, 3>, std::int64_t> colours;  // RGB -> pixel count (from VTK's reader)
};

inline PngImage read_png(const std::string& path) {
  PngImage img;
  std::ifstream in(path, std::ios::binary);
  unsigned char head[24] = {};
  in.read(reinterpret_cast<char*>(head), 24);
  if (!in) return img;
  const unsigned char sig[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  for (int i = 0; i < 8; ++i)
    if (head[i] != sig[i]) return img;
  if (std::string(reinterpret_cast<char*>(head + 12), 4) != "IHDR") return img;
  auto be32 = [&](int at) {
    return (std::uint32_t(head[at]) << 24) | (std::uint32_t(head[at + 1]) << 16) | (std::uint32_t(head[at + 2]) << 8) |
           std::uint32_t(head[at + 3]);
  };
  img.width = static_cast<int>(be32(16));
  img.height = static_cast<int>(be32(20));
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  if (dims[0] != img.width || dims[1] != img.height) return img;
  const int comps = data->GetNumberOfScalarComponents();
  if (comps < 3) return img;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const auto* p = static_cast<unsigned char*>(data->GetScalarPointer(x, y, 0));
      ++img.colours[{p[0], p[1], p[2]}];
    }
  img.valid = true;
  return img;
}

// Pixels whose colour is within `tol` per channel of `rgb` scaled by any brightness in [lo, 1] (shading
// darkens a flat colour; the hue stays).
inline std::int64_t pixels_like(const PngImage& img, std::array<int, 3> rgb, double lo = 0.3, int tol = 12) {
  std::int64_t n = 0;
  for (const auto& [c, count] : img.colours) {
    // The best brightness factor for c against rgb, then the distance at that factor.
    const double dot = double(c[0]) * rgb[0] + double(c[1]) * rgb[1] + double(c[2]) * rgb[2];
    const double nn = double(rgb[0]) * rgb[0] + double(rgb[1]) * rgb[1] + double(rgb[2]) * rgb[2];
    const double f = nn > 0 ? dot / nn : 0;
    if (f < lo || f > 1.05) continue;
    bool close = true;
    for (int k = 0; k < 3; ++k)
      if (std::abs(c[k] - f * rgb[k]) > tol) close = false;
    if (close) n += count;
  }
  return n;
}

}  // namespace png_test
