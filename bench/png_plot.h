// A minimal PNG line plot (log-log axes, tick labels, legend) with no
// dependency: a 5x7 bitmap font, and PNG written with stored (uncompressed)
// deflate blocks. Enough for docs/images/performance.png.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace edge_sharpener::bench {

struct Series {
  std::string name;
  std::array<std::uint8_t, 3> color;
  std::vector<std::pair<double, double>> points;  // (x, y), both > 0
  bool dashed = false;
};

class Canvas {
 public:
  Canvas(int w, int h) : w_(w), h_(h), px_(std::size_t(w) * h * 3, 255) {}

  void set(int x, int y, const std::array<std::uint8_t, 3> &c) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    for (int k = 0; k < 3; ++k) px_[(std::size_t(y) * w_ + x) * 3 + k] = c[k];
  }
  void line(double x0, double y0, double x1, double y1, const std::array<std::uint8_t, 3> &c,
            int thick = 1, bool dashed = false) {
    const int n = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
    for (int i = 0; i <= n; ++i) {
      if (dashed && (i / 6) % 2) continue;
      const double t = double(i) / n;
      const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
      for (int dx = -(thick / 2); dx <= thick / 2; ++dx)
        for (int dy = -(thick / 2); dy <= thick / 2; ++dy) set(x + dx, y + dy, c);
    }
  }
  /// Text with its top-left corner at (x, y), glyphs scaled by `scale`.
  void text(int x, int y, const std::string &s, const std::array<std::uint8_t, 3> &c,
            int scale = 2) {
    for (char ch : s) {
      const auto &g = glyph(ch);
      for (int r = 0; r < 7; ++r)
        for (int col = 0; col < 5; ++col)
          if (g[r] & (1 << (4 - col)))
            for (int a = 0; a < scale; ++a)
              for (int b = 0; b < scale; ++b) set(x + col * scale + a, y + r * scale + b, c);
      x += 6 * scale;
    }
  }
  static int textWidth(const std::string &s, int scale = 2) { return int(s.size()) * 6 * scale; }

  bool writePng(const std::string &path) const {
    std::vector<std::uint8_t> raw;
    for (int y = 0; y < h_; ++y) {
      raw.push_back(0);
      raw.insert(raw.end(), px_.begin() + std::size_t(y) * w_ * 3,
                 px_.begin() + std::size_t(y + 1) * w_ * 3);
    }
    std::vector<std::uint8_t> z = {0x78, 0x01};
    for (std::size_t i = 0; i < raw.size(); i += 65535) {
      const std::size_t n = std::min<std::size_t>(65535, raw.size() - i);
      z.push_back(i + n == raw.size() ? 1 : 0);
      z.push_back(n & 0xff), z.push_back(n >> 8), z.push_back(~n & 0xff),
          z.push_back((~n >> 8) & 0xff);
      z.insert(z.end(), raw.begin() + i, raw.begin() + i + n);
    }
    std::uint32_t a = 1, b = 0;
    for (std::uint8_t v : raw) a = (a + v) % 65521, b = (b + a) % 65521;
    put32(z, (b << 16) | a);
    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> ihdr;
    put32(ihdr, w_), put32(ihdr, h_);
    ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
    chunk(png, "IHDR", ihdr), chunk(png, "IDAT", z), chunk(png, "IEND", {});
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(png.data(), 1, png.size(), f) == png.size();
    return std::fclose(f) == 0 && ok;
  }

 private:
  static void put32(std::vector<std::uint8_t> &v, std::uint32_t x) {
    for (int s = 24; s >= 0; s -= 8) v.push_back(std::uint8_t(x >> s));
  }
  static void chunk(std::vector<std::uint8_t> &png, const char *type,
                    const std::vector<std::uint8_t> &data) {
    put32(png, std::uint32_t(data.size()));
    std::vector<std::uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    std::uint32_t crc = 0xffffffffu;
    for (std::uint8_t v : body) {
      crc ^= v;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    png.insert(png.end(), body.begin(), body.end());
    put32(png, ~crc);
  }
  static const std::array<std::uint8_t, 7> &glyph(char c) {
    static const std::map<char, std::array<std::uint8_t, 7>> font = {
        {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},
        {'2', {14, 17, 1, 2, 4, 8, 31}},     {'3', {31, 2, 4, 2, 1, 17, 14}},
        {'4', {2, 6, 10, 18, 31, 2, 2}},     {'5', {31, 16, 30, 1, 1, 17, 14}},
        {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},
        {'8', {14, 17, 17, 14, 17, 17, 14}}, {'9', {14, 17, 17, 15, 1, 2, 12}},
        {'.', {0, 0, 0, 0, 0, 12, 12}},      {'-', {0, 0, 0, 31, 0, 0, 0}},
        {'(', {2, 4, 8, 8, 8, 4, 2}},        {')', {8, 4, 2, 2, 2, 4, 8}},
        {'/', {1, 1, 2, 4, 8, 16, 16}},      {':', {0, 12, 12, 0, 12, 12, 0}},
        {'+', {0, 4, 4, 31, 4, 4, 0}},       {',', {0, 0, 0, 0, 12, 4, 8}},
        {'a', {0, 0, 14, 1, 15, 17, 15}},    {'b', {16, 16, 22, 25, 17, 17, 30}},
        {'c', {0, 0, 14, 16, 16, 17, 14}},   {'d', {1, 1, 13, 19, 17, 17, 15}},
        {'e', {0, 0, 14, 17, 31, 16, 14}},   {'f', {6, 9, 8, 28, 8, 8, 8}},
        {'g', {0, 15, 17, 17, 15, 1, 14}},   {'h', {16, 16, 22, 25, 17, 17, 17}},
        {'i', {4, 0, 12, 4, 4, 4, 14}},      {'j', {2, 0, 6, 2, 2, 18, 12}},
        {'k', {16, 16, 18, 20, 24, 20, 18}}, {'l', {12, 4, 4, 4, 4, 4, 14}},
        {'m', {0, 0, 26, 21, 21, 17, 17}},   {'n', {0, 0, 22, 25, 17, 17, 17}},
        {'o', {0, 0, 14, 17, 17, 17, 14}},   {'p', {0, 0, 30, 17, 30, 16, 16}},
        {'q', {0, 0, 13, 19, 15, 1, 1}},     {'r', {0, 0, 22, 25, 16, 16, 16}},
        {'s', {0, 0, 14, 16, 14, 1, 30}},    {'t', {8, 8, 28, 8, 8, 9, 6}},
        {'u', {0, 0, 17, 17, 17, 19, 13}},   {'v', {0, 0, 17, 17, 17, 10, 4}},
        {'w', {0, 0, 17, 17, 21, 21, 10}},   {'x', {0, 0, 17, 10, 4, 10, 17}},
        {'y', {0, 0, 17, 17, 15, 1, 14}},    {'z', {0, 0, 31, 2, 4, 8, 31}},
        {'M', {17, 27, 21, 21, 17, 17, 17}}, {'F', {31, 16, 16, 30, 16, 16, 16}},
        {'T', {31, 4, 4, 4, 4, 4, 4}}, {'E', {31, 16, 16, 30, 16, 16, 31}},
        {'S', {15, 16, 16, 14, 1, 1, 30}},       {' ', {0, 0, 0, 0, 0, 0, 0}}};
    static const std::array<std::uint8_t, 7> unknown = {31, 17, 17, 17, 17, 17, 31};
    const auto it = font.find(c);
    return it == font.end() ? unknown : it->second;
  }

  int w_, h_;
  std::vector<std::uint8_t> px_;
};

/// Log-log plot of `series` with decade grid lines and a legend.
inline bool plotLogLog(const std::string &path, const std::string &title, const std::string &xLabel,
                       const std::string &yLabel, const std::vector<Series> &series) {
  const int W = 900, H = 600, L = 110, R = 30, T = 60, B = 80;
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const auto &s : series)
    for (const auto &[x, y] : s.points)
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (!(x1 > 0 && y1 > 0)) return false;
  x0 = std::pow(10, std::floor(std::log10(x0))), x1 = std::pow(10, std::ceil(std::log10(x1)));
  y0 = std::pow(10, std::floor(std::log10(y0))), y1 = std::pow(10, std::ceil(std::log10(y1)));
  const auto X = [&](double x) {
    return L + (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) * (W - L - R);
  };
  const auto Y = [&](double y) {
    return H - B -
           (std::log10(y) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) * (H - T - B);
  };
  Canvas c(W, H);
  const std::array<std::uint8_t, 3> black{0, 0, 0}, grid{215, 215, 215};
  const auto label = [](double v) {
    char buf[32];
    if (v >= 1e6)
      std::snprintf(buf, sizeof buf, "%gM", v / 1e6);
    else if (v >= 1e3)
      std::snprintf(buf, sizeof buf, "%gk", v / 1e3);
    else
      std::snprintf(buf, sizeof buf, "%g", v);
    return std::string(buf);
  };
  for (double x = x0; x <= x1 * 1.001; x *= 10) {
    c.line(X(x), T, X(x), H - B, grid);
    const std::string s = label(x);
    c.text(int(X(x)) - Canvas::textWidth(s) / 2, H - B + 10, s, black);
  }
  for (double y = y0; y <= y1 * 1.001; y *= 10) {
    c.line(L, Y(y), W - R, Y(y), grid);
    const std::string s = label(y);
    c.text(L - 10 - Canvas::textWidth(s), int(Y(y)) - 7, s, black);
  }
  c.line(L, H - B, W - R, H - B, black), c.line(L, T, L, H - B, black);
  c.text((W - Canvas::textWidth(title, 3)) / 2, 15, title, black, 3);
  c.text((W - Canvas::textWidth(xLabel)) / 2, H - 35, xLabel, black);
  c.text(10, T - 25, yLabel, black);
  int ly = T + 10;
  for (const auto &s : series) {
    for (std::size_t i = 1; i < s.points.size(); ++i)
      c.line(X(s.points[i - 1].first), Y(s.points[i - 1].second), X(s.points[i].first),
             Y(s.points[i].second), s.color, 3, s.dashed);
    for (const auto &[x, y] : s.points)
      for (int d = -4; d <= 4; ++d) c.line(X(x) - 4, Y(y) + d, X(x) + 4, Y(y) + d, s.color);
    c.line(L + 20, ly + 7, L + 60, ly + 7, s.color, 3, s.dashed);
    c.text(L + 70, ly, s.name, black);
    ly += 24;
  }
  return c.writePng(path);
}

}  // namespace edge_sharpener::bench
