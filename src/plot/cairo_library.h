// Cairo, loaded when the first figure is drawn rather than when the program starts. Linking it would map cairo and
// the seventeen libraries it needs (X11, fontconfig, freetype, pixman, ...) at the start of every sgtllc command, plots
// or not: about 7 ms of CPU a start on this project's VM, where `sgtllc pair` takes about 80 ms as a whole process
// (BENCHMARKS.md, "Whole process"). The header cairo.h still gives the types and the function signatures, so each
// pointer below has cairo's own type.
#pragma once

#include <cairo.h>

namespace sgtllc::plot {

#define SGTLLC_CAIRO_FUNCTIONS(X)                                                                                    \
  X(arc) X(clip) X(create) X(destroy) X(fill) X(fill_preserve) X(font_extents) X(image_surface_create) X(line_to)     \
  X(move_to) X(paint) X(rectangle) X(restore) X(rotate) X(save) X(select_font_face) X(set_dash) X(set_font_size)     \
  X(set_line_join) X(set_line_width) X(set_source_rgb) X(set_source_rgba) X(show_text) X(stroke) X(surface_destroy) \
  X(surface_flush) X(surface_write_to_png) X(text_extents) X(translate)

/// The cairo functions the plots call, each under its name without the `cairo_` prefix.
struct CairoLibrary {
#define SGTLLC_CAIRO_POINTER(name) decltype(&::cairo_##name) name = nullptr;
  SGTLLC_CAIRO_FUNCTIONS(SGTLLC_CAIRO_POINTER)
#undef SGTLLC_CAIRO_POINTER
};

/// Cairo, loaded (libcairo.so.2) on the first call; later calls, from any thread, return the same functions. Throws
/// sgtllc::Error naming the library and the loader's reason if it cannot be loaded or lacks a function.
const CairoLibrary& cairo();

}  // namespace sgtllc::plot
