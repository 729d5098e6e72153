#include "sgtllc/plot/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "cairo_library.h"
#include "sgtllc/types.h"

namespace sgtllc::plot {
namespace {

constexpr double kFontSize = 15.0;
constexpr double kTitleSize = 18.0;
constexpr const char* kFont = "DejaVu Sans";

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

/// Tick step of 1, 2 or 5 × 10^k giving about @p target ticks over [lo, hi].
double niceStep(double lo, double hi, int target) {
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * mag >= raw) return m * mag;
  }
  return 10.0 * mag;
}

std::string tickText(double v, double step) {
  char buf[32];
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return buf;
}

void setColor(cairo_t* cr, const Color& c) { cairo().set_source_rgba(cr, c.r, c.g, c.b, c.a); }

double textWidth(cairo_t* cr, const std::string& s) {
  cairo_text_extents_t e;
  cairo().text_extents(cr, s.c_str(), &e);
  return e.x_advance;
}

/// Draws @p s with its anchor at (x, y): ax = 0, 0.5, 1 anchors the left, centre or right; ay = 0, 0.5, 1 the
/// top, middle or bottom of the font's box.
void drawText(cairo_t* cr, const std::string& s, double x, double y, double ax, double ay) {
  cairo_font_extents_t f;
  cairo().font_extents(cr, &f);
  cairo().move_to(cr, x - ax * textWidth(cr, s), y + f.ascent - ay * (f.ascent + f.descent));
  cairo().show_text(cr, s.c_str());
}

}  // namespace

Color seriesColor(int index) {
  static const Color palette[] = {{0.00, 0.45, 0.70}, {0.84, 0.37, 0.00}, {0.00, 0.62, 0.45}, {0.80, 0.47, 0.65},
                                  {0.34, 0.71, 0.91}, {0.90, 0.62, 0.00}, {0.35, 0.35, 0.35}, {0.94, 0.89, 0.26}};
  return palette[static_cast<size_t>(index) % (sizeof(palette) / sizeof(palette[0]))];
}

Figure::Figure(int width_px, int height_px) : width_(width_px), height_(height_px) {}

void Figure::xlim(double lo, double hi) {
  xfixed_ = true;
  x0_ = lo;
  x1_ = hi;
}

void Figure::ylim(double lo, double hi) {
  yfixed_ = true;
  y0_ = lo;
  y1_ = hi;
}

void Figure::line(const std::vector<double>& x, const std::vector<double>& y, const std::string& label, Color color,
                  double width, bool dashed) {
  items_.push_back(Item{Kind::kLine, x, y, {}, {}, label, color, width, dashed});
}

void Figure::points(const std::vector<double>& x, const std::vector<double>& y, const std::string& label, Color color,
                    double radius) {
  items_.push_back(Item{Kind::kPoints, x, y, {}, {}, label, color, radius, false});
}

void Figure::coloredPoints(const std::vector<double>& x, const std::vector<double>& y,
                           const std::vector<Color>& colors, double radius) {
  items_.push_back(Item{Kind::kColoredPoints, x, y, colors, {}, "", Color{}, radius, false});
}

void Figure::segments(const std::vector<std::array<double, 4>>& segs, const std::string& label, Color color,
                      double width) {
  items_.push_back(Item{Kind::kSegments, {}, {}, {}, segs, label, color, width, false});
}

void Figure::legendEntry(const std::string& label, Color color, bool as_line) {
  items_.push_back(Item{Kind::kSwatch, {}, {}, {}, {}, label, color, as_line ? 1.0 : 0.0, false});
}

namespace {

void setDash(cairo_t* cr, bool dashed) {
  const double dash[] = {8.0, 5.0};
  cairo().set_dash(cr, dash, dashed ? 2 : 0, 0);
}

}  // namespace

void Figure::render(void* context, double ox, double oy) const {
  cairo_t* cr = static_cast<cairo_t*>(context);
  // Data ranges.
  Range xr, yr;
  for (const Item& it : items_) {
    for (double v : it.x) xr.add(v);
    for (double v : it.y) yr.add(v);
    for (const auto& s : it.segs) {
      xr.add(s[0]);
      xr.add(s[2]);
      yr.add(s[1]);
      yr.add(s[3]);
    }
  }
  double x0 = xfixed_ ? x0_ : (xr.empty() ? 0.0 : xr.lo), x1 = xfixed_ ? x1_ : (xr.empty() ? 1.0 : xr.hi);
  double y0 = yfixed_ ? y0_ : (yr.empty() ? 0.0 : yr.lo), y1 = yfixed_ ? y1_ : (yr.empty() ? 1.0 : yr.hi);
  if (x1 - x0 < 1e-12) { x0 -= 0.5; x1 += 0.5; }
  if (y1 - y0 < 1e-12) { y0 -= 0.5; y1 += 0.5; }
  if (!xfixed_) { const double m = 0.03 * (x1 - x0); x0 -= m; x1 += m; }
  if (!yfixed_) { const double m = 0.03 * (y1 - y0); y0 -= m; y1 += m; }

  cairo().save(cr);
  cairo().translate(cr, ox, oy);
  cairo().select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo().set_font_size(cr, kFontSize);

  // The legend lists what the plot shows: labelled items with data, and swatches.
  std::vector<const Item*> entries;
  for (const Item& it : items_) {
    const bool has_data = it.kind == Kind::kSwatch || !it.x.empty() || !it.segs.empty();
    if (!it.label.empty() && has_data) entries.push_back(&it);
  }
  double label_w = 0;
  for (const Item* it : entries) label_w = std::max(label_w, textWidth(cr, it->label));
  const double row = kFontSize * 1.5, box_w = label_w + 50, box_h = row * entries.size() + 10;
  const bool outside = legend_at_.find("outside") != std::string::npos && !entries.empty();

  // Plot area inside margins for title, tick labels and axis labels (and an outside legend).
  const double left = 80, right = outside ? box_w + 35 : 25, top = title_.empty() ? 25 : 50, bottom = 65;
  double pw = width_ - left - right, ph = height_ - top - bottom;
  double px = left, py = top;
  if (equal_aspect_) {
    const double sx = pw / (x1 - x0), sy = ph / (y1 - y0);
    const double s = std::min(sx, sy);
    // Grow the tighter axis's range so one unit has the same length on both.
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    x0 = cx - 0.5 * pw / s;
    x1 = cx + 0.5 * pw / s;
    y0 = cy - 0.5 * ph / s;
    y1 = cy + 0.5 * ph / s;
  }
  const auto X = [&](double v) { return px + (v - x0) / (x1 - x0) * pw; };
  const auto Y = [&](double v) { return py + ph - (v - y0) / (y1 - y0) * ph; };

  // Grid and ticks.
  const double xs = niceStep(x0, x1, std::max(2, static_cast<int>(pw / 90))),
               ys = niceStep(y0, y1, std::max(2, static_cast<int>(ph / 60)));
  cairo().set_line_width(cr, 1.0);
  for (double v = std::ceil(x0 / xs) * xs; v <= x1 + 1e-9 * xs; v += xs) {
    cairo().set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo().move_to(cr, X(v), py);
    cairo().line_to(cr, X(v), py + ph);
    cairo().stroke(cr);
    cairo().set_source_rgb(cr, 0.15, 0.15, 0.15);
    drawText(cr, tickText(v, xs), X(v), py + ph + 8, 0.5, 0.0);
  }
  for (double v = std::ceil(y0 / ys) * ys; v <= y1 + 1e-9 * ys; v += ys) {
    cairo().set_source_rgb(cr, 0.9, 0.9, 0.9);
    cairo().move_to(cr, px, Y(v));
    cairo().line_to(cr, px + pw, Y(v));
    cairo().stroke(cr);
    cairo().set_source_rgb(cr, 0.15, 0.15, 0.15);
    drawText(cr, tickText(v, ys), px - 8, Y(v), 1.0, 0.5);
  }

  // Data, clipped to the plot area.
  cairo().save(cr);
  cairo().rectangle(cr, px, py, pw, ph);
  cairo().clip(cr);
  cairo().set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Item& it : items_) {
    switch (it.kind) {
      case Kind::kLine: {
        setColor(cr, it.color);
        cairo().set_line_width(cr, it.size);
        setDash(cr, it.dashed);
        for (size_t k = 0; k < it.x.size(); ++k) {
          if (k == 0) cairo().move_to(cr, X(it.x[k]), Y(it.y[k]));
          else cairo().line_to(cr, X(it.x[k]), Y(it.y[k]));
        }
        cairo().stroke(cr);
        cairo().set_dash(cr, nullptr, 0, 0);
        break;
      }
      case Kind::kPoints:
      case Kind::kColoredPoints:
        for (size_t k = 0; k < it.x.size(); ++k) {
          setColor(cr, it.kind == Kind::kPoints ? it.color : it.colors[k]);
          cairo().arc(cr, X(it.x[k]), Y(it.y[k]), it.size, 0, 2 * M_PI);
          cairo().fill(cr);
        }
        break;
      case Kind::kSegments:
        setColor(cr, it.color);
        cairo().set_line_width(cr, it.size);
        for (const auto& s : it.segs) {
          cairo().move_to(cr, X(s[0]), Y(s[1]));
          cairo().line_to(cr, X(s[2]), Y(s[3]));
        }
        cairo().stroke(cr);
        break;
      case Kind::kSwatch:
        break;
    }
  }
  cairo().restore(cr);

  // Frame, labels, title.
  cairo().set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo().set_line_width(cr, 1.2);
  cairo().rectangle(cr, px, py, pw, ph);
  cairo().stroke(cr);
  if (!xlabel_.empty()) drawText(cr, xlabel_, px + pw / 2, height_ - 22, 0.5, 0.5);
  if (!ylabel_.empty()) {
    cairo().save(cr);
    cairo().translate(cr, 20, py + ph / 2);
    cairo().rotate(cr, -M_PI / 2);
    drawText(cr, ylabel_, 0, 0, 0.5, 0.5);
    cairo().restore(cr);
  }
  if (!title_.empty()) {
    cairo().set_font_size(cr, kTitleSize);
    cairo().select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    drawText(cr, title_, px + pw / 2, 25, 0.5, 0.5);
    cairo().select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo().set_font_size(cr, kFontSize);
  }

  if (!note_.empty()) {
    cairo().set_source_rgb(cr, 0.35, 0.35, 0.35);
    drawText(cr, note_, px + pw / 2, py + ph / 2, 0.5, 0.5);
  }

  // Legend.
  if (!entries.empty()) {
    const bool at_left = legend_at_.find("left") != std::string::npos;
    const bool at_bottom = legend_at_.find("lower") != std::string::npos;
    const double bx = outside ? px + pw + 15 : at_left ? px + 10 : px + pw - box_w - 10;
    const double by = at_bottom && !outside ? py + ph - box_h - 10 : py + (outside ? 0 : 10);
    cairo().set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo().rectangle(cr, bx, by, box_w, box_h);
    cairo().fill_preserve(cr);
    cairo().set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo().set_line_width(cr, 1.0);
    cairo().stroke(cr);
    for (size_t k = 0; k < entries.size(); ++k) {
      const Item& it = *entries[k];
      const double cy = by + 5 + row * (k + 0.5);
      setColor(cr, it.color);
      const bool as_line = it.kind == Kind::kLine || it.kind == Kind::kSegments ||
                           (it.kind == Kind::kSwatch && it.size > 0.5);
      if (as_line) {
        cairo().set_line_width(cr, std::max(2.0, it.kind == Kind::kSwatch ? 2.0 : it.size));
        setDash(cr, it.dashed);
        cairo().move_to(cr, bx + 8, cy);
        cairo().line_to(cr, bx + 36, cy);
        cairo().stroke(cr);
        setDash(cr, false);
      } else {
        cairo().arc(cr, bx + 22, cy, 5, 0, 2 * M_PI);
        cairo().fill(cr);
      }
      cairo().set_source_rgb(cr, 0.1, 0.1, 0.1);
      drawText(cr, it.label, bx + 44, cy, 0.0, 0.5);
    }
  }
  cairo().restore(cr);
}

}  // namespace sgtllc::plot
