#include "cairo_library.h"

#include <dlfcn.h>

#include <string>

#include "sgtllc/types.h"

namespace sgtllc::plot {
namespace {

constexpr const char* kLibrary = "libcairo.so.2";

CairoLibrary load() {
  // Never closed: the functions serve until the process ends.
  void* handle = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw Error(std::string("cannot draw a figure: ") + kLibrary + " (cairo, Debian package libcairo2) did not load" +
                (why ? std::string(": ") + why : std::string()));
  }
  CairoLibrary lib;
#define SGTLLC_CAIRO_RESOLVE(name)                                                                     \
  lib.name = reinterpret_cast<decltype(lib.name)>(dlsym(handle, "cairo_" #name));                      \
  if (!lib.name) throw Error(std::string("cannot draw a figure: ") + kLibrary + " has no cairo_" #name);
  SGTLLC_CAIRO_FUNCTIONS(SGTLLC_CAIRO_RESOLVE)
#undef SGTLLC_CAIRO_RESOLVE
  return lib;
}

}  // namespace

const CairoLibrary& cairo() {
  static const CairoLibrary lib = load();  // a failed load throws, and the next call tries again
  return lib;
}

}  // namespace sgtllc::plot
