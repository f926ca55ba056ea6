// grid_image OUT_DIR: pictures of the classroom examples [KMPSY08 §4]: the sign of
// orient2d(p', q, r) for each of the 256 x 256 neighbouring doubles p' near p, one pixel
// per grid point, for naive double, adaptive, interval and GMP rational evaluation, for
// both grids. Writes OUT_DIR/classroom_<grid>_<method>.png and prints the wrong-sign counts.
// Preconditions: OUT_DIR exists and is writable.
//
// Colours: positive (counterclockwise) blue, negative red, zero yellow. The pixel at
// column i, row j from the bottom is p' = (px + i ulps, py + j ulps), as in the paper's
// figures.
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_reference.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/predicates_classroom.hpp"
#include "arithmetic/predicates_naive.hpp"

namespace {

using Rgb = std::array<std::uint8_t, 3>;
constexpr Rgb positive_colour{33, 102, 172};
constexpr Rgb negative_colour{178, 24, 43};
constexpr Rgb zero_colour{250, 210, 40};

// ---- A minimal PNG writer: 8-bit RGB, no interlace, one IDAT chunk --------------------
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// A chunk is length, type, data, and the CRC-32 of type and data.
void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t type_at = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  const uLong crc = crc32(crc32(0L, Z_NULL, 0), out.data() + type_at, static_cast<uInt>(4 + data.size()));
  put_u32(out, static_cast<std::uint32_t>(crc));
}

// rgb holds width * height pixels, top row first.
bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height, const std::vector<Rgb>& rgb) {
  // Each scanline starts with its filter type; 0 means none.
  std::vector<std::uint8_t> raw;
  raw.reserve(height * (1 + 3 * width));
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    for (std::uint32_t x = 0; x < width; ++x) {
      const Rgb& p = rgb[y * width + x];
      raw.insert(raw.end(), p.begin(), p.end());
    }
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> packed(packed_size);
  if (compress(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size())) != Z_OK) return false;
  packed.resize(packed_size);

  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  put_u32(header, width);
  put_u32(header, height);
  header.insert(header.end(), {8, 2, 0, 0, 0});  // bit depth 8, RGB, deflate, no filter, no interlace
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", packed);
  put_chunk(png, "IEND", {});
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return static_cast<bool>(file);
}

// ---- The grids -------------------------------------------------------------------------
using Orient = std::function<int(double, double, double, double, double, double)>;

struct Method {
  const char* name;
  Orient orient2d;
};

const std::array<Method, 4> methods{{
    {"double", mk::naive::orient2d},
    {"adaptive", mk::adaptive::orient2d},
    {"interval", mk::interval_filter::orient2d},
    {"rational", mk::reference::orient2d},
}};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: grid_image OUT_DIR\n";
    return 2;
  }
  const std::string out_dir = argv[1];
  constexpr auto n = static_cast<std::uint32_t>(mk::classroom::grid_size);
  for (const auto& g : mk::classroom::grids) {
    std::vector<int> exact(n * n);
    mk::classroom::for_each_point(g, [&](int i, int j, double px, double py) {
      exact[static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i)] =
          mk::reference::orient2d(px, py, g.qx, g.qy, g.rx, g.ry);
    });
    for (const auto& m : methods) {
      std::vector<Rgb> pixels(n * n);
      mk::classroom::SignErrorCounts wrong;
      mk::classroom::for_each_point(g, [&](int i, int j, double px, double py) {
        const int s = m.orient2d(px, py, g.qx, g.qy, g.rx, g.ry);
        wrong.add(s, exact[static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i)]);
        const std::size_t row = n - 1 - static_cast<std::size_t>(j);  // j grows upward
        pixels[row * n + static_cast<std::size_t>(i)] = s > 0 ? positive_colour : s < 0 ? negative_colour : zero_colour;
      });
      const std::string path = out_dir + "/classroom_" + std::string(g.name) + "_" + m.name + ".png";
      if (!write_png(path, n, n, pixels)) {
        std::cerr << "grid_image: cannot write " << path << "\n";
        return 1;
      }
      std::cout << path << ": wrong signs " << wrong.total() << " (flipped " << wrong.sign_flipped
                << ", zero reported non-zero " << wrong.zero_reported_nonzero << ", non-zero reported zero "
                << wrong.nonzero_reported_zero << ")\n";
    }
  }
  return 0;
}
