/// @file figure.h
/// @brief A small 2-D chart renderer on Cairo for the PNG plots of reports and the simulator (internal).
///
/// Enough for line charts, scatter plots and bird's-eye views: nice ticks, grid, axis labels, title and legend.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace sgtllc::plot {

struct Color {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
};

/// Distinct colours for successive series (a colour-blind-friendly palette).
Color seriesColor(int index);

class Figure {
 public:
  Figure(int width_px, int height_px);

  void title(std::string text) { title_ = std::move(text); }
  void xlabel(std::string text) { xlabel_ = std::move(text); }
  void ylabel(std::string text) { ylabel_ = std::move(text); }
  /// Fixes an axis range; otherwise ranges cover the data with a small margin.
  void xlim(double lo, double hi);
  void ylim(double lo, double hi);
  /// One metre (unit) is as long on both axes: for maps and bird's-eye views.
  void equalAspect(bool on = true) { equal_aspect_ = on; }
  /// Where the legend box goes: "upper right", "upper left", "lower right", "lower left" (inside the axes), or
  /// "outside right" (beside them, so that it never covers data).
  void legendAt(std::string where) { legend_at_ = std::move(where); }
  /// A line of text in the middle of the axes, e.g. why a plot is empty ("no positives in this sequence").
  void note(std::string text) { note_ = std::move(text); }

  /// A polyline. An empty label keeps it out of the legend, and so does an empty series (a legend lists only what
  /// the plot shows); a dashed line has a dashed legend swatch.
  void line(const std::vector<double>& x, const std::vector<double>& y, const std::string& label, Color color,
            double width = 2.0, bool dashed = false);
  /// Filled circles of one colour.
  void points(const std::vector<double>& x, const std::vector<double>& y, const std::string& label, Color color,
              double radius = 2.5);
  /// Filled circles with one colour each (no legend entry; add swatches with legendEntry).
  void coloredPoints(const std::vector<double>& x, const std::vector<double>& y, const std::vector<Color>& colors,
                     double radius = 1.0);
  /// Line segments (x0, y0, x1, y1) of one colour.
  void segments(const std::vector<std::array<double, 4>>& segs, const std::string& label, Color color,
                double width = 1.0);
  /// A legend swatch without data.
  void legendEntry(const std::string& label, Color color, bool as_line = false);

  /// Renders and writes a PNG; throws sgtllc::Error naming the file if it cannot be written.
  void savePng(const std::string& path) const;

  int width() const { return width_; }
  int height() const { return height_; }
  /// Draws the figure with its top-left corner at (@p x, @p y) of @p cr (a cairo_t*, kept opaque here).
  void render(void* cr, double x, double y) const;

 private:
  enum class Kind { kLine, kPoints, kColoredPoints, kSegments, kSwatch };
  struct Item {
    Kind kind;
    std::vector<double> x, y;
    std::vector<Color> colors;
    std::vector<std::array<double, 4>> segs;
    std::string label;
    Color color;
    double size = 1.0;
    bool dashed = false;
  };

  int width_, height_;
  std::string title_, xlabel_, ylabel_, legend_at_ = "upper right", note_;
  bool xfixed_ = false, yfixed_ = false, equal_aspect_ = false;
  double x0_ = 0, x1_ = 1, y0_ = 0, y1_ = 1;
  std::vector<Item> items_;
};

/// Writes @p panels side by side into one PNG (as tall as the tallest); throws sgtllc::Error naming the file if it
/// cannot be written.
void savePngRow(const std::string& path, const std::vector<const Figure*>& panels);

}  // namespace sgtllc::plot
