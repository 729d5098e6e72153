// Writing figures as PNG files: one figure, or several side by side (figure.h).
#include <algorithm>
#include <memory>

#include "cairo_library.h"
#include "sgtllc/plot/figure.h"
#include "sgtllc/types.h"

namespace sgtllc::plot {
namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

void writePng(cairo_surface_t* surface, const std::string& path) {
  cairo().surface_flush(surface);
  if (cairo().surface_write_to_png(surface, path.c_str()) != CAIRO_STATUS_SUCCESS) {
    throw Error("cannot write " + path + " (PNG)");
  }
}

/// A white canvas of @p w × @p h pixels drawn by @p draw and written to @p path.
template <typename Draw>
void drawPng(const std::string& path, int w, int h, Draw&& draw) {
  Surface surface(cairo().image_surface_create(CAIRO_FORMAT_RGB24, w, h), cairo().surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> ctx(cairo().create(surface.get()), cairo().destroy);
  cairo().set_source_rgb(ctx.get(), 1, 1, 1);
  cairo().paint(ctx.get());
  draw(ctx.get());
  writePng(surface.get(), path);
}

}  // namespace

void Figure::savePng(const std::string& path) const {
  drawPng(path, width_, height_, [this](cairo_t* cr) { render(cr, 0.0, 0.0); });
}

void savePngRow(const std::string& path, const std::vector<const Figure*>& panels) {
  int w = 0, h = 0;
  for (const Figure* f : panels) {
    w += f->width();
    h = std::max(h, f->height());
  }
  drawPng(path, std::max(w, 1), std::max(h, 1), [&panels](cairo_t* cr) {
    double x = 0.0;
    for (const Figure* f : panels) {
      f->render(cr, x, 0.0);
      x += f->width();
    }
  });
}

}  // namespace sgtllc::plot
